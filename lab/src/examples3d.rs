//! The main job's 3D examples: Hertz's sphere and Cattaneo-Mindlin on the paraboloid cap over a
//! block (`hycon::solid::contact_meshes::CapOnBlock`, 18-beta hybrid bricks, small kinematics,
//! [`crate::solid_scene`]), as [`Example`]s, the plane examples' result structs, so that they
//! print, plot and serialize as those do. `x` of a node row is the distance `r` from the axis
//! (reference position), the closed forms are [`crate::closed3d`]'s, written as a
//! [`ClosedForm`] at `centre = 0`.
//!
//! * [`hertz`]: the quarter cap of [`crate::hertz3d`] (`R / a = 16`, `E = 1`, `nu = 0.3`,
//!   symmetry planes `x = 0` and `y = 0`), pressed by Hertz's approach `a^2 / R` of the target
//!   radius `a` in one increment ([`QuarterCap::press`]), frictionless. The full model's load
//!   `P` is 4 times the quarter's; Hertz's `a` and `p0` at that load are compared with the
//!   radius from the pressure's moments (`HertzSphere::from_moments`) and the multiplier at the
//!   centre node.
//! * [`cattaneo_mindlin`]: the half cap of [`crate::mindlin3d`] on its mirror block
//!   (`R / a = 256`, the multipliers on the block's top, symmetry plane `y = 0`), Coulomb's
//!   `mu`: pressed as above, then its top moved along `x` ([`HalfCap::pull_to`], one increment
//!   at a time) until `Q / (mu P)` reaches the target. `P` and `Q` are twice the half's. The
//!   tangential traction on the block along `x` is compared with Mindlin's
//!   (`q(r) = mu p - (c/a) mu p0 sqrt(1 - r^2/c^2)` inside the stick radius
//!   `c = a (1 - Q/(mu P))^(1/3)`, `a` and `p0` Hertz's at `P`), the stick radius measured
//!   along `Q` ([`crate::mindlin3d::Ray::radius`] of the leading side) with `c`.
//!
//! Every error over the contact is relative and weighted by the nodes' tributary areas:
//! `||p - p_H|| / ||p_H||` and `||q - q_M|| / ||mu p_H||` over the A nodes of the model (the
//! symmetric parts left out weigh alike).

use crate::closed3d::HertzSphere;
use crate::examples::{
    Bodies, ClosedForm, ContactPoint, Example, Fields, HertzErrors, Increment, NodeRow, Phase,
    Progress, Run, Setup, StickZone, TimeSplit, say,
};
use crate::hertz3d::{self, QuarterCap};
use crate::mindlin3d::{HalfCap, Pull};
use hycon::contact::iteration::{ContactAnalysis, ContactOptions, NodeResult};
use hycon::solid::contact_meshes::{CapModel, CapOnBlock};
use hycon::solid::model::{SolidModel, SolidSystem};
use hycon::{Error, Result};
use std::time::Instant;

/// The 3D examples' parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CapCase {
    /// Faces per target contact radius at the centre, `a / h`.
    pub a_over_h: usize,
    /// Coulomb's `mu` of the Cattaneo-Mindlin example (> 0).
    pub friction: f64,
    /// The `Q / (mu P)` the Cattaneo-Mindlin example pulls to, in `(0, 1)`.
    pub target: f64,
    /// Displacement fields kept.
    pub fields: Fields,
}

impl Default for CapCase {
    fn default() -> Self {
        CapCase {
            a_over_h: 4,
            friction: 0.3,
            target: 0.5,
            fields: Fields::Every,
        }
    }
}

/// How close the pull comes to the target `Q / (mu P)`, and its increments at most.
const PULL_TOLERANCE: f64 = 0.005;
const PULL_STEPS: usize = 6;

fn check(case: &CapCase) -> Result<()> {
    if case.a_over_h == 0 {
        return Err(Error::InvalidInput("a/h must be at least 1".into()));
    }
    if !(case.friction.is_finite() && case.friction > 0.0) {
        return Err(Error::InvalidInput(format!(
            "Cattaneo-Mindlin needs friction > 0, got {}",
            case.friction
        )));
    }
    if !(case.target > 0.0 && case.target < 1.0) {
        return Err(Error::InvalidInput(format!(
            "target Q/(mu P) must be in (0, 1), got {}",
            case.target
        )));
    }
    Ok(())
}

/// The run's scene numbers.
fn setup(
    spec: &CapOnBlock,
    model: &SolidModel,
    analysis: &ContactAnalysis,
    friction: f64,
) -> Result<Setup> {
    let material = model.materials[0];
    let (a_nodes, b_nodes) = analysis.pair_size(0)?;
    let a = spec.contact_radius();
    Ok(Setup {
        radius: 1.0,
        target_half_width: a,
        elements_per_half_width: spec.a_over_h,
        element_size: a / spec.a_over_h as f64,
        modulus_ratio: 1.0,
        block_modulus: material.youngs,
        poisson: material.poisson,
        friction,
        e_star: material.youngs / (2.0 * (1.0 - material.poisson.powi(2))),
        nodes: model.mesh.n_nodes(),
        elements: model.mesh.n_elements(),
        dofs: 3 * model.mesh.n_nodes(),
        contact_nodes: [a_nodes, b_nodes],
    })
}

/// One converged increment of a cap, as the plane examples keep it.
struct State<'a> {
    number: usize,
    phase: Phase,
    /// The top's motion along `x` and down.
    slide: f64,
    approach: f64,
    iterations: usize,
    seconds: f64,
    /// The full model's `P` and `Q` (on A, along `x`), and the radius from the moments.
    load: f64,
    tangential: f64,
    radius: f64,
    /// The stick radius measured along `Q` (frictional runs).
    stick: Option<f64>,
    results: &'a [NodeResult],
    model: &'a SolidModel,
    setup: &'a Setup,
}

impl State<'_> {
    fn r(&self, n: &NodeResult) -> f64 {
        let [x, y, _] = self.model.mesh.nodes[n.node];
        x.hypot(y)
    }

    /// The increment: rows sorted by `r`, errors against Hertz and Mindlin at `P` and `Q`.
    fn increment(&self, fields: (Vec<f64>, Vec<ContactPoint>)) -> Increment {
        let mu = self.setup.friction;
        let hertz = HertzSphere::new(self.load, self.setup.radius, self.setup.e_star);
        let ratio = (mu > 0.0).then(|| self.tangential / (mu * self.load));
        let closed_form = ClosedForm {
            centre: 0.0,
            half_width: hertz.radius,
            peak: hertz.peak,
            friction: mu,
            stick_half_width: hertz.radius * (1.0 - ratio.unwrap_or(0.0).clamp(0.0, 1.0)).cbrt(),
            sign: 1.0,
        };
        let mut sorted: Vec<&NodeResult> = self.results.iter().collect();
        sorted.sort_by(|a, b| self.r(a).total_cmp(&self.r(b)));
        let rows: Vec<NodeRow> = (sorted.iter())
            .map(|n| {
                let r = self.r(n);
                NodeRow {
                    x: r,
                    p: -n.tn,
                    p_forces: -(n.frame.normal().dot(&n.force)) / n.weight,
                    q: n.frame.vector(0.0, n.ts).components()[0],
                    state: n.state,
                    p_exact: closed_form.pressure(r),
                    q_exact: closed_form.shear(r),
                }
            })
            .collect();
        let weights: Vec<f64> = sorted.iter().map(|n| n.weight).collect();
        // `||error|| / ||reference||`, weighted by the tributary areas
        let l2 = |error: &dyn Fn(&NodeRow) -> f64, reference: &dyn Fn(&NodeRow) -> f64| {
            let (mut num, mut den) = (0.0, 0.0);
            for (row, w) in rows.iter().zip(&weights) {
                num += w * error(row).powi(2);
                den += w * reference(row).powi(2);
            }
            (num / den).sqrt()
        };
        let peak = rows.iter().find(|n| n.x == 0.0).map_or(f64::NAN, |n| n.p);
        let tn: f64 = self.results.iter().map(|n| n.tn.abs()).sum();
        let hertz_errors = HertzErrors {
            half_width: hertz.radius,
            peak: hertz.peak,
            centre: 0.0,
            measured_half_width: self.radius,
            measured_peak: peak,
            half_width_error: self.radius / hertz.radius - 1.0,
            peak_error: peak / hertz.peak - 1.0,
            l2_error: l2(&|n| n.p - n.p_exact, &|n| n.p_exact),
            l2_error_forces: l2(&|n| n.p_forces - n.p_exact, &|n| n.p_exact),
            tangential_ratio: self.results.iter().map(|n| n.ts.norm()).sum::<f64>() / tn,
        };
        let count = |name: &str| rows.iter().filter(|n| n.state.name() == name).count();
        let (stick, slip) = (count("stick"), count("slip"));
        let stick_zone = (self.stick)
            .filter(|_| ratio.is_some_and(|r| r < 1.0) && stick > 0)
            .map(|measured| StickZone {
                measured,
                predicted: closed_form.stick_half_width,
                error: (measured - closed_form.stick_half_width) / hertz.radius,
                stick_nodes: stick,
            });
        let (displacement, contact) = fields;
        Increment {
            number: self.number,
            phase: self.phase,
            approach: self.approach,
            slide: self.slide,
            iterations: self.iterations,
            active: rows.len() - count("open"),
            stick,
            slip,
            load: self.load,
            tangential_load: self.tangential,
            q_over_p: self.tangential / self.load,
            q_over_mu_p: ratio,
            hertz: hertz_errors,
            closed_form,
            shear_l2_error: ratio.map(|_| l2(&|n| n.q - n.q_exact, &|n| mu * n.p_exact)),
            stick_zone,
            seconds: self.seconds,
            nodes: rows,
            displacement,
            contact,
        }
    }
}

/// The displacement and the contact tractions of the last increment, if `fields` keeps them
/// for every increment.
fn fields_now(
    analysis: &ContactAnalysis,
    results: &[NodeResult],
    fields: Fields,
) -> Result<(Vec<f64>, Vec<ContactPoint>)> {
    Ok(match fields {
        Fields::Every => (analysis.displacement()?.to_vec(), ContactPoint::of(results)),
        Fields::Final | Fields::None => (Vec::new(), Vec::new()),
    })
}

/// An analysis built, and the seconds of its set-up: `ContactAnalysis::solid` does not time
/// the brick bodies' assembly and factorization apart (its timings hold zero for both), so the
/// construction's time, less the flexibility it primes (timed), stands for them.
fn timed<T>(
    build: impl FnOnce() -> Result<T>,
    analysis: impl Fn(&T) -> &ContactAnalysis,
) -> Result<(T, f64)> {
    let clock = Instant::now();
    let built = build()?;
    let seconds = clock.elapsed().as_secs_f64() - analysis(&built).timings().flexibility;
    Ok((built, seconds))
}

/// The run: the last increment's fields if `fields` keeps only those, the time split (the
/// set-up's `setup_seconds` as the factorization where the analysis has no assembly and
/// factorization times, [`timed`]) against a linear analysis of `model` (assembly,
/// factorization, one solve with the last prescribed values `qp`).
fn finish(
    (label, tag, setup): (String, String, Setup),
    mut increments: Vec<Increment>,
    (analysis, model, qp): (&ContactAnalysis, SolidModel, Vec<f64>),
    (fields, setup_seconds): (Fields, f64),
) -> Result<Run> {
    if fields == Fields::Final
        && let Some(last) = increments.last_mut()
    {
        last.displacement = analysis.displacement()?.to_vec();
        last.contact = ContactPoint::of(&analysis.node_results(0)?);
    }
    let mut phases = analysis.timings();
    if phases.assembly == 0.0 && phases.factorization == 0.0 {
        phases.factorization = setup_seconds;
    }
    let clock = Instant::now();
    let mut system = SolidSystem::with_trailing_on(&model, &[], analysis.options().backend)?;
    let linear_setup = clock.elapsed().as_secs_f64();
    let clock = Instant::now();
    system.solve_for(&model, &vec![0.0; qp.len()], &qp)?;
    let one_solve = clock.elapsed().as_secs_f64();
    let counts = (increments.len(), analysis.factorizations());
    let timings = TimeSplit::new(phases, counts, linear_setup, one_solve);
    Ok(Run {
        label,
        tag,
        setup,
        calibration: None,
        increments,
        timings,
        model: Bodies::Solid(model),
    })
}

/// Hertz's sphere in 3D: the quarter cap pressed by Hertz's approach (module docs).
///
/// # Errors
/// Bad parameters ([`Error::InvalidInput`]), those of the scene and the increment.
pub fn hertz(case: &CapCase, mut progress: Progress<'_>) -> Result<Example> {
    check(case)?;
    let spec = CapOnBlock::new(CapModel::Quarter, case.a_over_h);
    let mesh = spec.build()?;
    let label = "quarter model".to_string();
    say(&mut progress, || {
        format!(
            "{label}: {} nodes, {} bricks; factoring K",
            mesh.mesh.n_nodes(),
            mesh.mesh.n_elements()
        )
    });
    let (mut cap, setup_seconds) = timed(
        || QuarterCap::with_mesh(spec, mesh, 1.0, ContactOptions::default()),
        |cap| &cap.analysis,
    )?;
    let setup = setup(&spec, &cap.model, &cap.analysis, 0.0)?;
    let clock = Instant::now();
    let c = cap.press()?;
    let seconds = clock.elapsed().as_secs_f64();
    let results = cap.analysis.node_results(0)?;
    let approach = crate::closed3d::hertz_approach(spec.contact_radius(), 1.0);
    let state = State {
        number: 1,
        phase: Phase::Press,
        slide: 0.0,
        approach,
        iterations: c.iterations,
        seconds,
        load: c.load,
        tangential: 0.0,
        radius: c.radius,
        stick: None,
        results: &results,
        model: &cap.model,
        setup: &setup,
    };
    let increment = state.increment(fields_now(&cap.analysis, &results, case.fields)?);
    say(&mut progress, || {
        format!(
            "{label}: pressed in {} iterations, {} active, {seconds:.3} s",
            increment.iterations, increment.active
        )
    });
    let qp = cap.pressed();
    let run = finish(
        (label, String::new(), setup),
        vec![increment],
        (&cap.analysis, cap.model.clone(), qp),
        (case.fields, setup_seconds),
    )?;
    Ok(Example {
        name: "hertz3d".into(),
        title: format!(
            "Hertz sphere in 3D, quarter model of a paraboloid cap on a block, frictionless, \
             pressed by a^2/R to a = R/{}, a/h = {}, hybrid bricks, small kinematics; a from \
             the pressure's moments, p0 at the centre node",
            spec.radius_over_contact, spec.a_over_h
        ),
        kinematics: hycon::contact::iteration::Kinematics::Small.name(),
        runs: vec![run],
    })
}

/// Cattaneo-Mindlin in 3D: the half cap pressed, then pulled along `x` (module docs).
///
/// # Errors
/// Bad parameters ([`Error::InvalidInput`]), those of the scene and the increments.
pub fn cattaneo_mindlin(case: &CapCase, mut progress: Progress<'_>) -> Result<Example> {
    check(case)?;
    let mu = case.friction;
    // (the set-up's time includes building the mesh)
    let (mut cap, setup_seconds) = timed(
        || HalfCap::new(case.a_over_h, hertz3d::POISSON, mu),
        |cap| &cap.analysis,
    )?;
    let spec = cap.spec;
    let label = format!("half model, mu = {mu}");
    say(&mut progress, || {
        format!(
            "{label}: {} nodes, {} bricks; factoring K",
            cap.scene.model.mesh.n_nodes(),
            cap.scene.model.mesh.n_elements()
        )
    });
    let setup = setup(&spec, &cap.scene.model, &cap.analysis, mu)?;
    let approach = crate::closed3d::hertz_approach(spec.contact_radius(), 1.0);
    let mut increments: Vec<Increment> = Vec::new();
    let mut last: Option<Pull> = None;
    while last.is_none_or(|p| p.ratio(mu) < case.target - PULL_TOLERANCE) {
        if increments.len() > PULL_STEPS {
            return Err(Error::InvalidInput(format!(
                "Cattaneo-Mindlin 3D: Q/(mu P) = {:.3} after {PULL_STEPS} tangential \
                 increments, target {} not reached",
                last.map_or(0.0, |p| p.ratio(mu)),
                case.target
            )));
        }
        let clock = Instant::now();
        let pull = match &last {
            None => cap.press()?,
            Some(from) => cap.pull_to(from, case.target, PULL_TOLERANCE, 1)?,
        };
        let seconds = clock.elapsed().as_secs_f64();
        let results = cap.analysis.node_results(0)?;
        let state = State {
            number: increments.len() + 1,
            phase: if last.is_none() {
                Phase::Press
            } else {
                Phase::Slide
            },
            slide: pull.displacement,
            approach,
            iterations: pull.info.iterations,
            seconds,
            load: pull.load,
            tangential: pull.tangential,
            radius: pull.radius,
            stick: Some(pull.leading.radius()),
            results: &results,
            model: &cap.scene.model,
            setup: &setup,
        };
        let increment = state.increment(fields_now(&cap.analysis, &results, case.fields)?);
        say(&mut progress, || {
            format!(
                "{label}: increment {} ({:?}) converged in {} iterations, {} active, {} slip, \
                 {seconds:.3} s",
                increment.number,
                increment.phase,
                increment.iterations,
                increment.active,
                increment.slip
            )
        });
        increments.push(increment);
        last = Some(pull);
    }
    let slide = last.map_or(0.0, |p| p.displacement);
    let qp = cap.scene.prescribed([slide, 0.0, -approach]);
    let model = cap.scene.model.clone();
    let run = finish(
        (label, String::new(), setup),
        increments,
        (&cap.analysis, model, qp),
        (case.fields, setup_seconds),
    )?;
    Ok(Example {
        name: "cattaneo-mindlin3d".into(),
        title: format!(
            "Cattaneo-Mindlin in 3D, half model of a paraboloid cap on its mirror block, mu = \
             {mu}: pressed by a^2/R to a = R/{}, then moved along x until Q/(mu P) > {}, a/h = \
             {}, hybrid bricks, small kinematics; c/a along Q",
            spec.radius_over_contact,
            case.target - PULL_TOLERANCE,
            spec.a_over_h
        ),
        kinematics: hycon::contact::iteration::Kinematics::Small.name(),
        runs: vec![run],
    })
}
