//! The paper's examples (docs/validation.md, "The paper's examples on the reference scene") on the reference disk-on-block scene
//! ([`DiskOnBlock`]), as library functions that run an analysis and return plain result structs
//! (no printing, no files; [`crate::report`] writes them).
//!
//! * [`hertz`]: non-sliding frictionless contact, displacement control, `m` increments up to the
//!   calibrated approach (the scene's target half-width `a`), for several modulus ratios `E_disk / E_block` (the
//!   calibrated approach scales the load with `E*`, so `a/R` stays fixed and Hertz applies).
//! * [`slide`]: pressed, then the disk top moved sideways by `distance * a` in `m` increments,
//!   frictionless or with Coulomb friction.
//! * [`cattaneo_mindlin`]: identical materials, pressed, then the disk top moved tangentially in
//!   small increments (step sizes chosen from the measured tangential stiffness) until
//!   `Q / (mu P)` passes a target; the stick zone is compared with `c = a sqrt(1 - Q/(mu P))`.
//! * [`sphere`]: the axisymmetric one, Hertz's sphere on a half-space
//!   ([`crate::axisymmetric::SphereOnBlock`]), pressed in `m` increments.
//!
//! Every plane example starts with the scene's calibration: one trial increment at the approach
//! `a^2 / R`, taken on the same analysis (so its time is in the timings, and the first
//! increment listed continues from it). Each increment keeps the Hertz comparison, the nodal
//! pressure and shear along the contact with the closed forms at the same `x`, the iteration and
//! node counts, `Q/P`, and its time; each run keeps the time split of the analysis.

use crate::axisymmetric::SphereOnBlock;
use crate::scene::{DiskOnBlock, HertzComparison, Scene};
use hycon::contact::iteration::{
    ContactAnalysis, ContactOptions, Kinematics, NodeResult, NodeState, Timings,
};
use hycon::error::{Error, Result};
use hycon::model::{LinearSystem, Model};
use hycon::solid::model::SolidModel;
use serde::Serialize;
use std::time::Instant;

/// An optional progress callback: called with one line of text per increment (and per run).
pub type Progress<'a> = Option<&'a mut dyn FnMut(&str)>;

pub(crate) fn say(progress: &mut Progress<'_>, message: impl FnOnce() -> String) {
    if let Some(f) = progress.as_mut() {
        f(&message());
    }
}

/// Which displacement fields to keep (each costs one solve; the contact iteration itself needs
/// only the contact dofs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Fields {
    /// Every increment.
    #[default]
    Every,
    /// The final increment of each run.
    Final,
    /// None ([`Increment::displacement`] stays empty).
    None,
}

/// Non-sliding Hertz contact.
#[derive(Debug, Clone, PartialEq)]
pub struct HertzCase {
    /// Elements per contact half-width (a power of two).
    pub n: usize,
    /// Modulus ratios `E_disk / E_block`, one run each.
    pub modulus_ratios: Vec<f64>,
    /// Increments up to the calibrated approach.
    pub increments: usize,
    /// Contact kinematics (default small: Hertz theory is the linearized problem).
    pub kinematics: Kinematics,
    /// `R / a` of the scene (a power of two; 64 is the reference scene).
    pub r_over_a: usize,
    /// Displacement fields kept.
    pub fields: Fields,
}

impl Default for HertzCase {
    fn default() -> Self {
        HertzCase {
            n: 16,
            modulus_ratios: vec![1.0, 1e-2, 1e-4],
            increments: 3,
            kinematics: Kinematics::Small,
            r_over_a: 64,
            fields: Fields::Every,
        }
    }
}

/// Extensive sliding: pressed, then moved sideways.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlideCase {
    /// Elements per contact half-width (a power of two).
    pub n: usize,
    /// Coulomb friction coefficient (0: frictionless).
    pub friction: f64,
    /// Sliding increments.
    pub increments: usize,
    /// Sliding distance of the disk top, in target half-widths `a`.
    pub distance: f64,
    /// Contact kinematics (default finite: the disk slides over many elements).
    pub kinematics: Kinematics,
    /// Displacement fields kept.
    pub fields: Fields,
}

impl Default for SlideCase {
    fn default() -> Self {
        SlideCase {
            n: 8,
            friction: 0.0,
            increments: 8,
            distance: 2.0,
            kinematics: Kinematics::Finite,
            fields: Fields::Every,
        }
    }
}

/// Cattaneo-Mindlin partial slip.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CattaneoCase {
    /// Elements per contact half-width (a power of two).
    pub n: usize,
    /// Coulomb friction coefficient (> 0).
    pub friction: f64,
    /// Wanted increase of `Q / (mu P)` per tangential increment.
    pub step: f64,
    /// Stop once `Q / (mu P)` has passed this value (< 1).
    pub target: f64,
    /// Cap on the tangential increments.
    pub max_increments: usize,
    /// Contact kinematics (default small: the theory is the linearized problem).
    pub kinematics: Kinematics,
    /// Displacement fields kept.
    pub fields: Fields,
}

impl Default for CattaneoCase {
    fn default() -> Self {
        CattaneoCase {
            n: 16,
            friction: 0.3,
            step: 0.1,
            target: 0.75,
            max_increments: 40,
            kinematics: Kinematics::Small,
            fields: Fields::Every,
        }
    }
}

/// One example: one or more runs (one per modulus ratio for Hertz).
#[derive(Debug, Clone, Serialize)]
pub struct Example {
    /// Short name, also the file stem of its outputs.
    pub name: String,
    /// One-line description (it names the kinematics).
    pub title: String,
    /// Contact kinematics of every run: `"small"` or `"finite"`.
    pub kinematics: &'static str,
    /// The analyses.
    pub runs: Vec<Run>,
}

/// One contact analysis along a loading path.
#[derive(Debug, Clone, Serialize)]
pub struct Run {
    /// What distinguishes this run (e.g. the modulus ratio).
    pub label: String,
    /// The same, short and safe in a file name (empty for an example's only run).
    pub tag: String,
    /// The scene, with every number.
    pub setup: Setup,
    /// The calibration trial increment (`None` for the sphere, pressed by Hertz's approach).
    pub calibration: Option<Calibration>,
    /// The increments of the loading path, in order.
    pub increments: Vec<Increment>,
    /// Where the time went (whole analysis, calibration included).
    pub timings: TimeSplit,
    /// The model (both bodies), for field output.
    #[serde(skip)]
    pub model: Bodies,
}

/// The bodies of a run, for field output.
#[derive(Debug, Clone)]
pub enum Bodies {
    /// A plane or axisymmetric model (2 dofs per node).
    Plane(Model),
    /// A brick model (3 dofs per node).
    Solid(SolidModel),
}

/// The contact tractions at one node of the multiplier side A, for field output.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactPoint {
    /// The node.
    pub node: usize,
    /// The pressure `-tn`.
    pub pressure: f64,
    /// The traction on A, global components (`z = 0` in the plane).
    pub traction: [f64; 3],
}

impl ContactPoint {
    /// The tractions of the A nodes `results`.
    pub fn of(results: &[NodeResult]) -> Vec<ContactPoint> {
        (results.iter())
            .map(|r| {
                let t = r.frame.vector(r.tn, r.ts);
                let c = t.components();
                ContactPoint {
                    node: r.node,
                    pressure: -r.tn,
                    traction: std::array::from_fn(|i| c.get(i).copied().unwrap_or(0.0)),
                }
            })
            .collect()
    }
}

/// The disk-on-block scene of a run.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Setup {
    /// Disk radius `R`.
    pub radius: f64,
    /// Target half-width `a` ([`DiskOnBlock::target_half_width`]).
    pub target_half_width: f64,
    /// Elements per target half-width.
    pub elements_per_half_width: usize,
    /// Element size at the contact `h = a / n`.
    pub element_size: f64,
    /// `E_disk / E_block`.
    pub modulus_ratio: f64,
    /// `E_block`.
    pub block_modulus: f64,
    /// Poisson's ratio of both bodies.
    pub poisson: f64,
    /// Coulomb friction coefficient.
    pub friction: f64,
    /// Effective modulus `E*` (plane strain).
    pub e_star: f64,
    /// Nodes of both bodies.
    pub nodes: usize,
    /// Elements of both bodies.
    pub elements: usize,
    /// Degrees of freedom (2 per node, prescribed included).
    pub dofs: usize,
    /// Nodes of the multiplier side A (block top) and of B (disk arc).
    pub contact_nodes: [usize; 2],
}

/// The calibration trial increment.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Calibration {
    /// Trial approach `a^2 / R`.
    pub trial_approach: f64,
    /// Calibrated approach (Hertz load for the target half-width).
    pub approach: f64,
    /// Iterations of the trial increment.
    pub iterations: usize,
}

/// Loading phase of an increment.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Phase {
    /// Normal approach.
    Press,
    /// Tangential motion of the disk top.
    Slide,
}

/// A node state as its name (`"open"`, `"stick"`, `"slip"`) in the JSON summary.
fn state_name<S: serde::Serializer>(
    state: &NodeState,
    s: S,
) -> std::result::Result<S::Ok, S::Error> {
    s.serialize_str(state.name())
}

/// One converged increment.
#[derive(Debug, Clone, Serialize)]
pub struct Increment {
    /// 1-based number along the path (the calibration trial not counted).
    pub number: usize,
    /// Press or slide.
    pub phase: Phase,
    /// Prescribed approach of the disk top.
    pub approach: f64,
    /// Prescribed tangential displacement of the disk top.
    pub slide: f64,
    /// Contact iterations.
    pub iterations: usize,
    /// Nodes in contact (stick + slip + frictionless).
    pub active: usize,
    /// Stick nodes.
    pub stick: usize,
    /// Slip nodes.
    pub slip: usize,
    /// Normal load `P` (from the equivalent nodal forces on A).
    pub load: f64,
    /// Tangential load `Q` on A (global x).
    pub tangential_load: f64,
    /// `Q / P`.
    pub q_over_p: f64,
    /// `Q / (mu P)` (frictional runs).
    pub q_over_mu_p: Option<f64>,
    /// Pressure against Hertz at the same load.
    pub hertz: HertzErrors,
    /// The closed forms this increment is compared with.
    pub closed_form: ClosedForm,
    /// `|| q - q_exact || / || mu p_Hertz ||` (tributary weights; frictional runs).
    pub shear_l2_error: Option<f64>,
    /// Stick zone against Cattaneo-Mindlin (frictional runs with stick nodes).
    pub stick_zone: Option<StickZone>,
    /// Wall-clock seconds of the increment (contact solve and recovery).
    pub seconds: f64,
    /// Nodal values along the contact (A nodes, sorted by x).
    pub nodes: Vec<NodeRow>,
    /// Converged total displacement over all dofs, for field output.
    #[serde(skip)]
    pub displacement: Vec<f64>,
    /// The contact tractions of the A nodes, for field output (brick models; empty when
    /// [`displacement`](Self::displacement) is, and for plane models).
    #[serde(skip)]
    pub contact: Vec<ContactPoint>,
}

/// The Hertz comparison with relative errors.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct HertzErrors {
    /// Hertz half-width at the measured load.
    pub half_width: f64,
    /// Hertz peak pressure at the measured load.
    pub peak: f64,
    /// Centre of the computed pressure distribution.
    pub centre: f64,
    /// Half-width measured from the computed pressures ([`HertzComparison::half_width`]).
    pub measured_half_width: f64,
    /// Peak pressure measured from the computed pressures ([`HertzComparison::peak`]).
    pub measured_peak: f64,
    /// `measured_half_width / half_width - 1`.
    pub half_width_error: f64,
    /// `measured_peak / peak - 1`.
    pub peak_error: f64,
    /// Relative L2 error of the multiplier pressures.
    pub l2_error: f64,
    /// Relative L2 error of the pressures from equivalent nodal forces.
    pub l2_error_forces: f64,
    /// `sum |ts| / sum |tn|`.
    pub tangential_ratio: f64,
}

impl From<&HertzComparison> for HertzErrors {
    fn from(c: &HertzComparison) -> Self {
        HertzErrors {
            half_width: c.hertz.half_width,
            peak: c.hertz.peak,
            centre: c.centre,
            measured_half_width: c.half_width,
            measured_peak: c.peak,
            half_width_error: c.half_width / c.hertz.half_width - 1.0,
            peak_error: c.peak / c.hertz.peak - 1.0,
            l2_error: c.l2_error,
            l2_error_forces: c.l2_error_forces,
            tangential_ratio: c.tangential_ratio,
        }
    }
}

/// Hertz pressure and Cattaneo-Mindlin shear at the measured load, centred on the computed
/// pressure: `p = p0 sqrt(1 - r^2/a^2)`; `q = sign (mu p - (c/a) mu p0 sqrt(1 - r^2/c^2))`
/// inside the stick zone `|r| < c` and `sign mu p` outside, `c = a sqrt(1 - |Q|/(mu P))`
/// (`c = 0`, full slip, once `|Q| >= mu P`; `q = 0` frictionless), `r = x - centre`.
/// The same forms hold for Hertz's sphere and Mindlin's traction along `Q` in 3D, with `r` the
/// distance from the axis and `c = a (1 - |Q|/(mu P))^(1/3)` ([`crate::examples3d`]).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct ClosedForm {
    /// Centre of contact.
    pub centre: f64,
    /// Hertz half-width `a`.
    pub half_width: f64,
    /// Hertz peak pressure `p0`.
    pub peak: f64,
    /// Coulomb friction coefficient `mu`.
    pub friction: f64,
    /// Stick-zone half-width `c` (in 3D the stick radius).
    pub stick_half_width: f64,
    /// Sign of the tangential load (+1 or -1).
    pub sign: f64,
}

impl ClosedForm {
    /// Hertz pressure at `x`.
    pub fn pressure(&self, x: f64) -> f64 {
        ellipse(self.peak, self.half_width, x - self.centre)
    }

    /// Cattaneo-Mindlin shear at `x` (traction on the block along +x).
    pub fn shear(&self, x: f64) -> f64 {
        if self.friction == 0.0 {
            return 0.0;
        }
        let r = x - self.centre;
        let c = self.stick_half_width;
        let mut q = self.friction * self.pressure(x);
        if r.abs() < c {
            q -= (c / self.half_width) * self.friction * ellipse(self.peak, c, r);
        }
        self.sign * q
    }
}

fn ellipse(peak: f64, half_width: f64, r: f64) -> f64 {
    let s = 1.0 - (r / half_width).powi(2);
    if s > 0.0 { peak * s.sqrt() } else { 0.0 }
}

/// Stick-zone half-width: computed and Cattaneo-Mindlin.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct StickZone {
    /// Half the distance between the stick/non-stick boundaries (midway between the outermost
    /// stick node and its neighbour).
    pub measured: f64,
    /// `a sqrt(1 - Q/(mu P))` with the Hertz `a` at the measured load.
    pub predicted: f64,
    /// `(measured - predicted) / a`.
    pub error: f64,
    /// Stick nodes.
    pub stick_nodes: usize,
}

/// Values at one A node.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct NodeRow {
    /// Current x.
    pub x: f64,
    /// Pressure from the multipliers, `-tn`.
    pub p: f64,
    /// Pressure from the equivalent nodal forces.
    pub p_forces: f64,
    /// Shear traction on the block along its tangent `s` (+x on the flat block top; multiplier
    /// `ts`).
    pub q: f64,
    /// Contact state.
    #[serde(serialize_with = "state_name")]
    pub state: NodeState,
    /// Hertz pressure at `x`.
    pub p_exact: f64,
    /// Closed-form shear at `x`.
    pub q_exact: f64,
}

/// Where the time of an analysis went, against a linear analysis of the same model.
#[derive(Debug, Clone, Copy)]
pub struct TimeSplit {
    /// The analysis' own split (assembly, factorization, flexibility, load solves, iterations,
    /// recovery).
    pub phases: Timings,
    /// Sum of the phases.
    pub total: f64,
    /// Increments solved (calibration included).
    pub increments: usize,
    /// Numeric factorizations of `K`.
    pub factorizations: usize,
    /// One solve of the reference linear analysis.
    pub one_solve: f64,
    /// The reference linear analysis of the same model (timed separately): assembly,
    /// factorization and one solve.
    pub linear: f64,
    /// `total / linear`.
    pub ratio: f64,
}

/// In the JSON summary the phases sit beside the other fields, as one flat object.
impl Serialize for TimeSplit {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut m = s.serialize_struct("TimeSplit", 12)?;
        for (name, value) in self.phases.phases() {
            m.serialize_field(name, &value)?;
        }
        m.serialize_field("total", &self.total)?;
        m.serialize_field("increments", &self.increments)?;
        m.serialize_field("factorizations", &self.factorizations)?;
        m.serialize_field("one_solve", &self.one_solve)?;
        m.serialize_field("linear", &self.linear)?;
        m.serialize_field("ratio", &self.ratio)?;
        m.end()
    }
}

/// The analysis's time split, and a linear analysis of the same model timed for reference:
/// assembly and factorization of a fresh `K`, then one solve with the final loads.
fn time_split(
    analysis: &ContactAnalysis,
    increments: usize,
    f: &[f64],
    qp: &[f64],
) -> Result<TimeSplit> {
    let clock = Instant::now();
    let mut system = LinearSystem::new(analysis.model()?)?;
    let setup = clock.elapsed().as_secs_f64();
    let clock = Instant::now();
    system.solve_for(analysis.model()?, f, qp)?;
    let one_solve = clock.elapsed().as_secs_f64();
    Ok(TimeSplit::new(
        analysis.timings(),
        (increments, analysis.factorizations()),
        setup,
        one_solve,
    ))
}

impl TimeSplit {
    /// The split `phases` of an analysis after `increments` increments and `factorizations`
    /// numeric factorizations, against a linear analysis of the same model that took `setup`
    /// seconds (assembly and factorization) and `one_solve` (one solve).
    pub fn new(
        phases: Timings,
        (increments, factorizations): (usize, usize),
        setup: f64,
        one_solve: f64,
    ) -> Self {
        let t = phases;
        let linear = setup + one_solve;
        TimeSplit {
            phases: t,
            total: t.total(),
            increments,
            factorizations,
            one_solve,
            linear,
            ratio: t.total() / linear,
        }
    }
}

/// A scene with its analysis, calibrated, and the increments so far.
struct Path {
    label: String,
    tag: String,
    scene: Scene,
    setup: Setup,
    analysis: ContactAnalysis,
    calibration: Calibration,
    increments: Vec<Increment>,
    forces: Vec<f64>,
    solved: usize,
    fields: Fields,
}

impl Path {
    fn new(
        def: DiskOnBlock,
        (label, tag): (String, String),
        kinematics: Kinematics,
        fields: Fields,
        progress: &mut Progress<'_>,
    ) -> Result<Path> {
        let scene = def.build()?;
        let mesh = &scene.model.mesh;
        let setup = Setup {
            radius: scene.radius,
            target_half_width: scene.half_width,
            elements_per_half_width: def.elements_per_half_width,
            element_size: scene.half_width / def.elements_per_half_width as f64,
            modulus_ratio: def.modulus_ratio,
            block_modulus: def.block_modulus,
            poisson: def.poisson,
            friction: def.friction,
            e_star: scene.e_star,
            nodes: mesh.n_nodes(),
            elements: mesh.n_elements(),
            dofs: 2 * mesh.n_nodes(),
            contact_nodes: [scene.pair.a.len(), scene.pair.b.len()],
        };
        say(progress, || {
            format!(
                "{label}: {} nodes, {} elements; factoring K and building the contact flexibility",
                setup.nodes, setup.elements
            )
        });
        let mut analysis = scene.analysis(ContactOptions {
            kinematics,
            ..Default::default()
        })?;
        let approach = scene.calibrated_approach(&mut analysis)?;
        let iterations = analysis.records().last().map_or(0, |r| r.iteration);
        let forces = vec![0.0; setup.dofs];
        Ok(Path {
            label,
            tag,
            calibration: Calibration {
                trial_approach: scene.half_width * scene.half_width / scene.radius,
                approach,
                iterations,
            },
            scene,
            setup,
            analysis,
            increments: Vec::new(),
            forces,
            solved: 1,
            fields,
        })
    }

    fn approach(&self) -> f64 {
        self.calibration.approach
    }

    /// One increment to `(approach, slide)`; returns the stored increment.
    fn step(
        &mut self,
        phase: Phase,
        approach: f64,
        slide: f64,
        progress: &mut Progress<'_>,
    ) -> Result<&Increment> {
        let clock = Instant::now();
        let number = self.increments.len() + 1;
        // a failure names the analysis' increment (the calibration trial is its increment 1);
        // the progress lines name the run
        let info = self
            .analysis
            .increment(&self.forces, &self.scene.prescribed(approach, slide))?;
        let seconds = clock.elapsed().as_secs_f64();
        self.solved += 1;
        let results = self.scene.node_results(&self.analysis)?;
        let comparison = self.scene.compare(&self.analysis)?;
        let displacement = match self.fields {
            Fields::Every => self.analysis.displacement()?.to_vec(),
            Fields::Final | Fields::None => Vec::new(),
        };
        let increment = evaluate(
            number,
            phase,
            approach,
            slide,
            info.iterations,
            seconds,
            &results,
            (comparison.load, (&comparison).into()),
            self.setup.friction,
            displacement,
        );
        say(progress, || {
            format!(
                "{}: increment {number} ({:?}) converged in {} iterations, {} active, {} slip, {:.3} s",
                self.label, phase, increment.iterations, increment.active, increment.slip, seconds
            )
        });
        self.increments.push(increment);
        Ok(self.increments.last().expect("just pushed"))
    }

    fn finish(mut self) -> Result<Run> {
        if self.fields == Fields::Final {
            let q = self.analysis.displacement()?.to_vec();
            if let Some(last) = self.increments.last_mut() {
                last.displacement = q;
            }
        }
        let last = self
            .increments
            .last()
            .map_or((0.0, 0.0), |i| (i.approach, i.slide));
        let qp = self.scene.prescribed(last.0, last.1);
        let timings = time_split(&self.analysis, self.solved, &self.forces, &qp)?;
        Ok(Run {
            label: self.label,
            tag: self.tag,
            setup: self.setup,
            calibration: Some(self.calibration),
            increments: self.increments,
            timings,
            model: Bodies::Plane(self.analysis.model()?.clone()),
        })
    }
}

/// Everything kept of one converged increment.
#[allow(clippy::too_many_arguments)]
fn evaluate(
    number: usize,
    phase: Phase,
    approach: f64,
    slide: f64,
    iterations: usize,
    seconds: f64,
    results: &[NodeResult],
    (load, errors): (f64, HertzErrors),
    friction: f64,
    displacement: Vec<f64>,
) -> Increment {
    let tangential_load: f64 = results.iter().map(|n| n.force[0]).sum();
    let ratio = (friction > 0.0).then(|| {
        let r = tangential_load / (friction * load);
        if r.abs() < 1e-9 { 0.0 } else { r }
    });
    let hertz = errors;
    let c = ratio.map_or(0.0, |r| hertz.half_width * (1.0 - r.abs().min(1.0)).sqrt());
    let closed_form = ClosedForm {
        centre: errors.centre,
        half_width: hertz.half_width,
        peak: hertz.peak,
        friction,
        stick_half_width: c,
        // round-off Q (no tangential loading) counts as positive
        sign: if tangential_load < -1e-9 * load.abs() {
            -1.0
        } else {
            1.0
        },
    };
    let mut sorted: Vec<&NodeResult> = results.iter().collect();
    sorted.sort_by(|a, b| a.position[0].total_cmp(&b.position[0]));
    let nodes: Vec<NodeRow> = sorted
        .iter()
        .map(|n| NodeRow {
            x: n.position[0],
            p: -n.tn,
            p_forces: -(n.frame.normal().dot(&n.force)) / n.weight,
            q: n.ts.components()[0],
            state: n.state,
            p_exact: closed_form.pressure(n.position[0]),
            q_exact: closed_form.shear(n.position[0]),
        })
        .collect();
    let count = |name: &str| nodes.iter().filter(|n| n.state.name() == name).count();
    let (stick, slip) = (count("stick"), count("slip"));
    let active = nodes.len() - count("open");
    let shear_l2_error = (friction > 0.0).then(|| {
        let (mut num, mut den) = (0.0, 0.0);
        for (row, n) in nodes.iter().zip(&sorted) {
            num += n.weight * (row.q - row.q_exact).powi(2);
            den += n.weight * (friction * row.p_exact).powi(2);
        }
        (num / den).sqrt()
    });
    // partial slip only: some node sticks (full slip has no stick zone to compare)
    let stick_zone = ratio.filter(|r| r.abs() < 1.0 && stick > 0).map(|_| {
        let stick_idx: Vec<usize> = (0..nodes.len())
            .filter(|&i| nodes[i].state == NodeState::Stick)
            .collect();
        let measured = match (stick_idx.first(), stick_idx.last()) {
            (Some(&l), Some(&r)) => {
                let left = if l > 0 {
                    0.5 * (nodes[l].x + nodes[l - 1].x)
                } else {
                    nodes[l].x
                };
                let right = if r + 1 < nodes.len() {
                    0.5 * (nodes[r].x + nodes[r + 1].x)
                } else {
                    nodes[r].x
                };
                0.5 * (right - left)
            }
            _ => 0.0,
        };
        StickZone {
            measured,
            predicted: c,
            error: (measured - c) / hertz.half_width,
            stick_nodes: stick_idx.len(),
        }
    });
    Increment {
        number,
        phase,
        approach,
        slide,
        iterations,
        active,
        stick,
        slip,
        load,
        tangential_load,
        q_over_p: tangential_load / load,
        q_over_mu_p: ratio,
        hertz: errors,
        closed_form,
        shear_l2_error,
        stick_zone,
        seconds,
        nodes,
        displacement,
        contact: Vec::new(),
    }
}

/// `R / a` of the reference scene, for titles.
fn r_over_a() -> f64 {
    let d = DiskOnBlock::default();
    (d.radius / d.target_half_width()).round()
}

fn check_n(n: usize) -> Result<()> {
    if n == 0 || !n.is_power_of_two() {
        return Err(Error::InvalidInput(format!(
            "elements per half-width must be a power of two, got {n}"
        )));
    }
    Ok(())
}

fn check_increments(m: usize) -> Result<()> {
    if m == 0 {
        return Err(Error::InvalidInput(
            "at least one increment is needed".into(),
        ));
    }
    Ok(())
}

fn check_ratios(ratios: &[f64]) -> Result<()> {
    if ratios.is_empty() {
        return Err(Error::InvalidInput("no modulus ratio given".into()));
    }
    match ratios.iter().find(|r| !(r.is_finite() && **r > 0.0)) {
        Some(ratio) => Err(Error::InvalidInput(format!(
            "modulus ratio must be finite and > 0, got {ratio}"
        ))),
        None => Ok(()),
    }
}

fn check_friction(mu: f64) -> Result<()> {
    if !(mu.is_finite() && mu >= 0.0) {
        return Err(Error::InvalidInput(format!(
            "friction must be finite and >= 0, got {mu}"
        )));
    }
    Ok(())
}

/// Example 1: non-sliding frictionless Hertz contact, one run per modulus ratio, `increments`
/// equal steps of the approach up to the calibrated one.
pub fn hertz(case: &HertzCase, mut progress: Progress<'_>) -> Result<Example> {
    check_n(case.n)?;
    check_increments(case.increments)?;
    check_ratios(&case.modulus_ratios)?;
    let mut runs = Vec::new();
    for &ratio in &case.modulus_ratios {
        let def = DiskOnBlock {
            elements_per_half_width: case.n,
            modulus_ratio: ratio,
            radius_over_half_width: case.r_over_a,
            ..Default::default()
        };
        let mut path = Path::new(
            def,
            (
                format!("E_disk/E_block = {ratio:.0e}"),
                format!("ratio-{ratio:.0e}"),
            ),
            case.kinematics,
            case.fields,
            &mut progress,
        )?;
        let approach = path.approach();
        for k in 1..=case.increments {
            let d = approach * k as f64 / case.increments as f64;
            path.step(Phase::Press, d, 0.0, &mut progress)?;
        }
        runs.push(path.finish()?);
    }
    Ok(Example {
        name: "hertz".into(),
        title: format!(
            "non-sliding Hertz contact, frictionless, {} increments to a = R/{}, n = {}, {} \
             kinematics",
            case.increments,
            case.r_over_a,
            case.n,
            case.kinematics.name()
        ),
        kinematics: case.kinematics.name(),
        runs,
    })
}

/// Examples 2 and 3: extensive sliding. Pressed to the calibrated approach in one increment,
/// then the disk top moved by `distance * a` in `increments` equal steps.
pub fn slide(case: &SlideCase, mut progress: Progress<'_>) -> Result<Example> {
    check_n(case.n)?;
    check_increments(case.increments)?;
    check_friction(case.friction)?;
    if !(case.distance.is_finite() && case.distance >= 0.0) {
        return Err(Error::InvalidInput(format!(
            "sliding distance must be finite and >= 0, got {}",
            case.distance
        )));
    }
    let def = DiskOnBlock {
        elements_per_half_width: case.n,
        friction: case.friction,
        travel: case.distance + 0.5,
        ..Default::default()
    };
    let (name, what) = if case.friction > 0.0 {
        (
            "slide-friction",
            format!("frictional sliding, mu = {}", case.friction),
        )
    } else {
        ("slide-frictionless", "frictionless sliding".to_string())
    };
    let mut path = Path::new(
        def,
        (what.clone(), String::new()),
        case.kinematics,
        case.fields,
        &mut progress,
    )?;
    let approach = path.approach();
    path.step(Phase::Press, approach, 0.0, &mut progress)?;
    let a = path.scene.half_width;
    for k in 1..=case.increments {
        let s = case.distance * a * k as f64 / case.increments as f64;
        path.step(Phase::Slide, approach, s, &mut progress)?;
    }
    Ok(Example {
        name: name.into(),
        title: format!(
            "{what}: pressed to a = R/{}, then moved {} a sideways in {} increments, n = {}, \
             {} kinematics",
            r_over_a(),
            case.distance,
            case.increments,
            case.n,
            case.kinematics.name()
        ),
        kinematics: case.kinematics.name(),
        runs: vec![path.finish()?],
    })
}

/// Example 4: Cattaneo-Mindlin partial slip (identical materials). Pressed to the calibrated
/// approach, then the disk top moved tangentially; each step is sized from the tangential
/// stiffness of the previous one to raise `Q / (mu P)` by about `step`, until it passes
/// `target`.
pub fn cattaneo_mindlin(case: &CattaneoCase, mut progress: Progress<'_>) -> Result<Example> {
    check_n(case.n)?;
    check_friction(case.friction)?;
    if case.friction == 0.0 {
        return Err(Error::InvalidInput(
            "Cattaneo-Mindlin needs friction > 0".into(),
        ));
    }
    if !(case.target > 0.0 && case.target < 1.0) {
        return Err(Error::InvalidInput(format!(
            "target Q/(mu P) must be in (0, 1), got {}",
            case.target
        )));
    }
    if !(case.step > 0.0 && case.step < 1.0) {
        return Err(Error::InvalidInput(format!(
            "step of Q/(mu P) must be in (0, 1), got {}",
            case.step
        )));
    }
    let mu = case.friction;
    let def = DiskOnBlock {
        elements_per_half_width: case.n,
        friction: mu,
        modulus_ratio: 1.0,
        ..Default::default()
    };
    let mut path = Path::new(
        def,
        (format!("Cattaneo-Mindlin, mu = {mu}"), String::new()),
        case.kinematics,
        case.fields,
        &mut progress,
    )?;
    let approach = path.approach();
    let pressed = path.step(Phase::Press, approach, 0.0, &mut progress)?;
    let (mut q_old, load) = (pressed.tangential_load, pressed.load);
    // first step: a guess (tangential and normal stiffness are alike); then the secant
    // stiffness of the last step, which only softens as slip spreads (so steps undershoot)
    let mut delta = case.step * mu * approach;
    let mut slide = 0.0;
    let mut ratio = 0.0;
    let mut taken = 0;
    while ratio < case.target {
        if taken == case.max_increments {
            return Err(Error::InvalidInput(format!(
                "Cattaneo-Mindlin: Q/(mu P) = {ratio:.3} after {taken} tangential increments, \
                 target {} not reached: raise the step or the increment cap",
                case.target
            )));
        }
        slide += delta;
        let inc = path.step(Phase::Slide, approach, slide, &mut progress)?;
        taken += 1;
        let q = inc.tangential_load;
        ratio = q / (mu * inc.load);
        let stiffness = (q - q_old) / delta;
        if !(stiffness > 0.0 && stiffness.is_finite()) {
            return Err(Error::InvalidInput(format!(
                "Cattaneo-Mindlin: tangential load did not grow (Q = {q:.3e}) at increment {}: \
                 the set-up does not load the contact tangentially",
                inc.number
            )));
        }
        q_old = q;
        let wanted = (ratio + case.step).min(case.target + 0.5 * case.step);
        delta = ((wanted - ratio).max(0.25 * case.step) * mu * load) / stiffness;
    }
    Ok(Example {
        name: "cattaneo-mindlin".into(),
        title: format!(
            "Cattaneo-Mindlin partial slip, identical materials, mu = {mu}: tangential \
             displacement until Q/(mu P) > {}, n = {}, {} kinematics",
            case.target,
            case.n,
            case.kinematics.name()
        ),
        kinematics: case.kinematics.name(),
        runs: vec![path.finish()?],
    })
}

/// The axisymmetric example: Hertz's sphere on a half-space ([`SphereOnBlock`], frictionless,
/// small kinematics).
#[derive(Debug, Clone, PartialEq)]
pub struct SphereCase {
    /// Elements per target contact radius (a power of two).
    pub n: usize,
    /// Modulus ratios `E_sphere / E_block`, one run each.
    pub modulus_ratios: Vec<f64>,
    /// `R / a` of the target contact radius (32 in the main job).
    pub r_over_a: usize,
    /// Equal increments up to Hertz's approach `a^2 / R` of the target contact radius.
    pub increments: usize,
    /// Displacement fields kept.
    pub fields: Fields,
}

impl Default for SphereCase {
    fn default() -> Self {
        SphereCase {
            n: 32,
            modulus_ratios: vec![1.0],
            r_over_a: 32,
            increments: 3,
            fields: Fields::Every,
        }
    }
}

/// The axisymmetric example: the sphere pressed onto the half-space in `increments` equal
/// steps of the approach up to `a^2 / R` (no calibration: the contact radius at that approach
/// is within 0.5% of the target), one run per modulus ratio. Each increment is compared with
/// Hertz at its computed load (full circle): the half-width columns hold the contact radius
/// from the pressure's moments on `r dr` ([`SphereComparison::radius`]), the peak columns the
/// multiplier of the node on the axis, the L2 errors are over `r dr`.
///
/// [`SphereComparison::radius`]: crate::axisymmetric::SphereComparison::radius
pub fn sphere(case: &SphereCase, mut progress: Progress<'_>) -> Result<Example> {
    check_n(case.n)?;
    check_increments(case.increments)?;
    check_ratios(&case.modulus_ratios)?;
    if case.r_over_a < 2 {
        return Err(Error::InvalidInput(format!(
            "R / a must be at least 2, got {}",
            case.r_over_a
        )));
    }
    let mut runs = Vec::new();
    for &ratio in &case.modulus_ratios {
        let label = format!("E_sphere/E_block = {ratio:.0e}");
        let scene = SphereOnBlock {
            elements_per_radius: case.n,
            radius_over_contact: case.r_over_a as f64,
            modulus_ratio: ratio,
        }
        .build()?;
        let mesh = &scene.model.mesh;
        let setup = Setup {
            radius: 1.0,
            target_half_width: scene.target,
            elements_per_half_width: case.n,
            element_size: scene.target / case.n as f64,
            modulus_ratio: ratio,
            block_modulus: scene.model.materials[0].youngs,
            poisson: scene.model.materials[0].poisson,
            friction: 0.0,
            e_star: scene.e_star,
            nodes: mesh.n_nodes(),
            elements: mesh.n_elements(),
            dofs: 2 * mesh.n_nodes(),
            contact_nodes: [scene.pair.a.len(), scene.pair.b.len()],
        };
        say(&mut progress, || {
            format!(
                "{label}: {} nodes, {} elements; factoring K",
                setup.nodes, setup.elements
            )
        });
        let mut analysis = scene.analysis(ContactOptions::default())?;
        let f = vec![0.0; setup.dofs];
        let mut increments = Vec::new();
        for k in 1..=case.increments {
            let approach = scene.hertz_approach() * k as f64 / case.increments as f64;
            let clock = Instant::now();
            let info = analysis.increment(&f, &scene.prescribed(approach))?;
            let seconds = clock.elapsed().as_secs_f64();
            let results = analysis.node_results(0)?;
            let c = scene.compare(&analysis)?;
            let tn: f64 = results.iter().map(|n| n.tn.abs()).sum();
            let errors = HertzErrors {
                half_width: c.hertz.radius,
                peak: c.hertz.peak,
                centre: 0.0,
                measured_half_width: c.radius,
                measured_peak: c.peak,
                half_width_error: c.radius / c.hertz.radius - 1.0,
                peak_error: c.peak / c.hertz.peak - 1.0,
                l2_error: c.l2_error,
                l2_error_forces: c.l2_error_forces,
                tangential_ratio: results.iter().map(|n| n.ts.norm()).sum::<f64>() / tn,
            };
            let displacement = match case.fields {
                Fields::Every => analysis.displacement()?.to_vec(),
                Fields::Final | Fields::None => Vec::new(),
            };
            let increment = evaluate(
                k,
                Phase::Press,
                approach,
                0.0,
                info.iterations,
                seconds,
                &results,
                (c.load, errors),
                0.0,
                displacement,
            );
            say(&mut progress, || {
                format!(
                    "{label}: increment {k} converged in {} iterations, {} active, {seconds:.3} s",
                    increment.iterations, increment.active
                )
            });
            increments.push(increment);
        }
        if case.fields == Fields::Final
            && let Some(last) = increments.last_mut()
        {
            last.displacement = analysis.displacement()?.to_vec();
        }
        let qp = scene.prescribed(scene.hertz_approach());
        let timings = time_split(&analysis, case.increments, &f, &qp)?;
        runs.push(Run {
            label,
            tag: format!("ratio-{ratio:.0e}"),
            setup,
            calibration: None,
            increments,
            timings,
            model: Bodies::Plane(analysis.model()?.clone()),
        });
    }
    Ok(Example {
        name: "sphere".into(),
        title: format!(
            "Hertz sphere on a half-space, axisymmetric (x = r), frictionless, {} increments to \
             a = R/{}, n = {}, small kinematics; a from the moments of p on r dr, p0 at the \
             axis node",
            case.increments, case.r_over_a, case.n
        ),
        kinematics: Kinematics::Small.name(),
        runs,
    })
}
