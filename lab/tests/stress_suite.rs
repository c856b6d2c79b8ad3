//! Numerical stability stress suite (issue 5, item 5): extreme moduli, Poisson's ratios, element
//! shapes, units, loads, refinements, near-coincident nodes and bad situations. Every case either
//! gives a result correct within a stated tolerance or a clear error; never NaN, never silent
//! garbage. Each test prints a small table (`cargo test --test lab stress_suite:: -- --nocapture`).
//!
//! Two set-ups are used:
//! * the Hertz scene of `hycon_lab::scene` (half disk on a block, plane strain), pressed by
//!   the calibrated approach (target `a = R / 64`) and compared with Hertz at the same load;
//! * the contact patch test of `tests/contact_patch.rs` (two stacked blocks, non-matching flat
//!   interface, uniform pressure), whose discrete solution is the exact uniform state to
//!   round-off, generalised here to stretched, skewed and perturbed meshes and any load.
//!
//! `load_magnitudes_default_options` and `floating_body_reports_singular` guard three cases
//! that once gave a silent wrong result or a misleading error: tiny loads below an absolute gap
//! tolerance, penetration deeper than the search distance, and a force-controlled direction
//! that nothing holds.

use hycon::Error;
use hycon::contact::iteration::{
    ContactAnalysis, ContactOptions, ContactPair, Kinematics, NodeState, PlateControl,
};
use hycon::element::Formulation;
use hycon::material::{Analysis, Material};
use hycon::mesh::{Mesh, generate, quality};
use hycon::model::{Model, Solution};
use hycon_lab::scene::{DiskOnBlock, HertzComparison};
use std::time::Instant;

// ---------------------------------------------------------------------------------------------
// Hertz scene helpers

/// Hertz comparison after the calibration increment and `increments` equal steps up to the
/// calibrated approach, with the iterations of each step.
fn hertz(
    def: DiskOnBlock,
    options: ContactOptions,
    increments: usize,
) -> hycon::Result<Vec<(HertzComparison, usize)>> {
    let scene = def.build()?;
    let mut analysis = scene.analysis(options)?;
    let approach = scene.calibrated_approach(&mut analysis)?;
    let f = vec![0.0; 2 * scene.model.mesh.n_nodes()];
    let mut out = Vec::new();
    for step in 1..=increments {
        let qp = scene.prescribed(approach * step as f64 / increments as f64, 0.0);
        let info = analysis.increment(&f, &qp)?;
        out.push((scene.compare(&analysis)?, info.iterations));
    }
    Ok(out)
}

/// `(a / a_H - 1, p0 / p0_H - 1)`.
fn hertz_errors(c: &HertzComparison) -> (f64, f64) {
    (
        c.half_width / c.hertz.half_width - 1.0,
        c.peak / c.hertz.peak - 1.0,
    )
}

fn all_finite(c: &HertzComparison) -> bool {
    [
        c.load,
        c.centre,
        c.half_width,
        c.peak,
        c.l2_error,
        c.l2_error_forces,
        c.tangential_ratio,
        c.hertz.half_width,
        c.hertz.peak,
    ]
    .iter()
    .all(|v| v.is_finite())
}

fn hertz_header() -> String {
    format!(
        "{:>14} | {:>9} {:>9} {:>8} {:>8} {:>6} {:>4}\n",
        "case", "a-aH", "p0-p0H", "L2", "L2 force", "active", "it"
    )
}

fn hertz_row(label: &str, c: &HertzComparison, iterations: usize) -> String {
    let (da, dp) = hertz_errors(c);
    format!(
        "{label:>14} | {:>+8.3}% {:>+8.3}% {:>7.3}% {:>7.3}% {:>6} {:>4}\n",
        100.0 * da,
        100.0 * dp,
        100.0 * c.l2_error,
        100.0 * c.l2_error_forces,
        c.active,
        iterations
    )
}

// ---------------------------------------------------------------------------------------------
// Contact patch test helpers

/// Vertical layout of a block's element layers.
#[derive(Debug, Clone, Copy)]
enum Layers {
    /// `n` equal layers.
    Uniform(usize),
    /// `n` layers growing geometrically away from the interface, the one at the interface of
    /// thickness `cell width / aspect` (so its elements have that aspect ratio).
    Stretched(usize, f64),
}

impl Layers {
    fn count(self) -> usize {
        match self {
            Layers::Uniform(n) | Layers::Stretched(n, _) => n,
        }
    }
}

/// One patch-test case. Lower block `[0, 1] x [-0.5, 0]` (B, `E = 3`, `nu = 0.2`), upper block
/// `[0, 1] x [gap, gap + 0.5]` (A, `E = 7`, `nu = 0.4`): the same `nu (1 + nu) / E`, so both
/// widen alike under `sigma_y = -p` and the uniform state is exact in the current
/// configuration too (see `tests/contact_patch.rs`).
#[derive(Debug, Clone, Copy)]
struct Patch {
    name: &'static str,
    /// Elements along the interface: upper (A) and lower (B).
    nx_a: usize,
    nx_b: usize,
    /// Layers of the upper and lower block.
    layers_a: Layers,
    layers_b: Layers,
    /// Herringbone skew: interior vertical mesh lines shift by `+-skew * cell width`,
    /// alternating from one horizontal mesh line to the next (every interior element is a
    /// parallelogram leaning left or right).
    skew: f64,
    /// Initial gap.
    gap: f64,
    /// Applied pressure.
    pressure: f64,
    /// The interior B (interface) nodes shifted along the interface by `+-shift` (alternating).
    shift_b: f64,
    options: ContactOptions,
}

impl Default for Patch {
    fn default() -> Self {
        Patch {
            name: "",
            nx_a: 13,
            nx_b: 8,
            layers_a: Layers::Uniform(4),
            layers_b: Layers::Uniform(4),
            skew: 0.0,
            gap: 0.0,
            pressure: 1e-3,
            shift_b: 0.0,
            options: ContactOptions {
                tolerance: 1e-10,
                ..Default::default()
            },
        }
    }
}

/// Results of one patch case (errors relative to the exact values).
#[derive(Debug, Clone)]
struct PatchOutcome {
    iterations: usize,
    active: usize,
    a_nodes: usize,
    /// Multiplier pressures `-tn` at the A nodes.
    tn: Vec<f64>,
    /// Largest `|p_h / p_exact - 1|`: multipliers, equivalent nodal forces on A.
    multipliers: f64,
    forces: f64,
    /// Largest `|sigma - (0, -p, 0)| / p` over the element centres of both blocks.
    stress: f64,
    /// Largest reaction at the held dofs that carry none in the exact state, over `p`.
    reaction: f64,
    /// Widening `eps_x`.
    widening: f64,
    /// Worst element shape of the mesh: largest aspect ratio, smallest corner angle.
    max_aspect: f64,
    min_angle: f64,
}

/// A block `[0, 1] x [y0, y0 + height]` of `nx x layers` elements, the interface on top
/// (`interface_top`) or at the bottom.
fn patch_block(
    nx: usize,
    layers: Layers,
    skew: f64,
    y0: f64,
    height: f64,
    interface_top: bool,
) -> Mesh {
    let ny = layers.count();
    let hx = 1.0 / nx as f64;
    // distance from the interface of mesh line `t` (0 at the interface, `ny` at the far face)
    let depth = |t: f64| -> f64 {
        match layers {
            Layers::Uniform(_) => height * t / ny as f64,
            Layers::Stretched(_, aspect) => {
                // first layer hx / aspect, growth ratio g with sum of the layers = height
                let first = hx / aspect;
                let total = |g: f64| first * (g.powi(ny as i32) - 1.0) / (g - 1.0);
                let (mut lo, mut hi) = (1.0 + 1e-12, 1e3);
                for _ in 0..200 {
                    let mid = 0.5 * (lo + hi);
                    if total(mid) > height {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                let g = 0.5 * (lo + hi);
                if t >= ny as f64 {
                    height
                } else {
                    first * (g.powf(t) - 1.0) / (g - 1.0)
                }
            }
        }
    };
    let map = |[u, v]: [f64; 2]| {
        let t = if interface_top { 1.0 - v } else { v } * ny as f64;
        let d = depth(t);
        let y = if interface_top {
            y0 + height - d
        } else {
            y0 + d
        };
        // +-1 alternating over the mesh lines (a triangle wave through the integers)
        let zigzag = 1.0 - 2.0 * ((t.rem_euclid(2.0)) - 1.0).abs();
        let s = u * nx as f64;
        let interior = s.min(nx as f64 - s).clamp(0.0, 1.0);
        [u + skew * hx * zigzag * interior, y]
    };
    generate::graded_mapped(nx, ny, map, &[])
}

/// Nodes of an edge chain (body on the left), in order.
fn chain(edges: &[[usize; 2]]) -> Vec<usize> {
    let mut nodes = vec![edges[0][0]];
    for e in edges {
        assert_eq!(*nodes.last().unwrap(), e[0], "edges must form one chain");
        nodes.push(e[1]);
    }
    nodes
}

/// Run a patch case. Supports as in `tests/contact_patch.rs`: the lower block's bottom held
/// vertically, its bottom-left node horizontally; the upper block's top corners held vertically
/// at the exact displacement; the four interface end nodes held horizontally at the exact
/// widening. Every held dof except the bottom carries no reaction in the exact state, so the
/// load goes through the contact.
fn patch(case: Patch) -> hycon::Result<PatchOutcome> {
    let p = case.pressure;
    let lower_mat = Material::new(3.0, 0.2, 1.0, Analysis::PlaneStrain)?;
    let upper_mat = Material::new(7.0, 0.4, 1.0, Analysis::PlaneStrain)?;
    let mut mesh = Mesh::new();
    let lower = patch_block(case.nx_b, case.layers_b, case.skew, -0.5, 0.5, true);
    let upper = patch_block(case.nx_a, case.layers_a, case.skew, case.gap, 0.5, false);
    mesh.append(&lower, 0, "lower.");
    let first_upper = mesh.append(&upper, 1, "upper.");
    let find = |mesh: &Mesh, x: f64, y: f64, upper: bool| -> usize {
        let mut range = if upper {
            first_upper..mesh.n_nodes()
        } else {
            0..first_upper
        };
        range
            .find(|&i| (mesh.nodes[i][0] - x).abs() < 1e-12 && (mesh.nodes[i][1] - y).abs() < 1e-12)
            .expect("corner node")
    };
    let lower_top = chain(&mesh.edge_sets["lower.top"]);
    let upper_bottom = chain(&mesh.edge_sets["upper.bottom"]);
    let lower_bottom = chain(&mesh.edge_sets["lower.bottom"]);
    let upper_top_edges = mesh.edge_sets["upper.top"].clone();
    // B's interior interface nodes shifted along the interface, alternating
    for (k, &i) in lower_top[1..lower_top.len() - 1].iter().enumerate() {
        mesh.nodes[i][0] += if k % 2 == 0 {
            case.shift_b
        } else {
            -case.shift_b
        };
    }
    let report = quality::quality(&mesh);
    let corner = find(&mesh, 0.0, -0.5, false);
    let ends = [
        (find(&mesh, 0.0, 0.0, false), 0.0),
        (find(&mesh, 1.0, 0.0, false), 1.0),
        (find(&mesh, 0.0, case.gap, true), 0.0),
        (find(&mesh, 1.0, case.gap, true), 1.0),
    ];
    let top = 0.5 + case.gap;
    let (top_left, top_right) = (find(&mesh, 0.0, top, true), find(&mesh, 1.0, top, true));
    // exact uniform state: eps_y = -(1 - nu^2) p / E, eps_x = nu (1 + nu) p / E
    let eps = |m: &Material| -(1.0 - m.poisson * m.poisson) * p / m.youngs;
    let v_top = 0.5 * eps(&lower_mat) - case.gap + 0.5 * eps(&upper_mat);
    let widening = lower_mat.poisson * (1.0 + lower_mat.poisson) * p / lower_mat.youngs;
    let mut model = Model::new(mesh, vec![lower_mat, upper_mat], Formulation::Hybrid);
    model.fix_dir(&lower_bottom, 1, 0.0).unwrap();
    model.fix_dir(&[corner], 0, 0.0).unwrap();
    for &(node, x) in &ends {
        model.fix_dir(&[node], 0, x * widening).unwrap();
    }
    model.fix_dir(&[top_left, top_right], 1, v_top).unwrap();
    model.load_edges(&upper_top_edges, [0.0, -p]);
    let pair = ContactPair {
        a: upper_bottom.clone(),
        b: lower_top.clone(),
        friction: 0.0,
    };
    let mut analysis = ContactAnalysis::new(model.clone(), vec![pair], case.options)?;
    let info = analysis.increment(&model.external_forces(), &model.prescribed_values())?;
    // one converged increment and nothing else: every record belongs to it, the last one
    // with no state change and R below the tolerance
    let records = analysis.records();
    assert!(
        records.iter().all(|r| r.increment == 1)
            && records.len() == info.iterations
            && records
                .last()
                .is_some_and(|r| r.changes == 0 && r.r <= case.options.tolerance),
        "{}: records {records:?}",
        case.name
    );
    let nodes = analysis.node_results(0)?;
    let q = analysis.displacement()?.to_vec();
    let kq = model.internal_forces(&q)?;
    let f = model.external_forces();
    // per unit reference length (small kinematics) or current length (finite: the interface
    // has widened by eps_x)
    let exact = match case.options.kinematics {
        Kinematics::Small => p,
        Kinematics::Finite => p / (1.0 + widening),
    };
    let rel = |v: f64| (v / exact - 1.0).abs();
    // NaN-propagating maximum (f64::max would drop a NaN)
    let worst = |it: &mut dyn Iterator<Item = f64>| {
        it.fold(0.0, |m: f64, v| {
            if v.is_nan() || m.is_nan() {
                f64::NAN
            } else {
                m.max(v)
            }
        })
    };
    let multipliers = worst(&mut nodes.iter().map(|n| rel(-n.tn)));
    let forces = worst(
        &mut nodes
            .iter()
            .map(|n| rel(-(n.frame.normal().dot(&n.force)) / n.weight)),
    );
    let solution = Solution { q: q.clone() };
    let mut stress = 0.0f64;
    for e in 0..model.mesh.n_elements() {
        let s = solution.stress_field(&model, e)?.at_centre();
        let err = s[0].abs().max((s[1] + p).abs()).max(s[2].abs()) / p;
        stress = if err.is_nan() {
            f64::NAN
        } else {
            stress.max(err)
        };
    }
    let mut held = vec![2 * top_left + 1, 2 * top_right + 1];
    held.extend(ends.iter().map(|&(n, _)| 2 * n));
    let reaction = worst(&mut held.iter().map(|&d| (kq[d] - f[d]).abs() / p));
    Ok(PatchOutcome {
        iterations: info.iterations,
        active: info.active,
        a_nodes: upper_bottom.len(),
        tn: nodes.iter().map(|n| -n.tn).collect(),
        multipliers,
        forces,
        stress,
        reaction,
        widening,
        max_aspect: report.max_aspect,
        min_angle: report.min_angle_deg,
    })
}

fn patch_header() -> String {
    format!(
        "{:>24} {:>7} {:>6} {:>9} {:>3} {:>6} | {:>8} {:>8} {:>8} {:>8}\n",
        "case",
        "nx A/B",
        "aspect",
        "min angle",
        "it",
        "active",
        "tn",
        "force A",
        "stress",
        "reaction"
    )
}

fn patch_row(case: &Patch, o: &PatchOutcome) -> String {
    format!(
        "{:>24} {:>3}/{:<3} {:>6.0} {:>8.2}d {:>3} {:>3}/{:<2} | {:>8.1e} {:>8.1e} {:>8.1e} {:>8.1e}\n",
        case.name,
        case.nx_a,
        case.nx_b,
        o.max_aspect,
        o.min_angle,
        o.iterations,
        o.active,
        o.a_nodes,
        o.multipliers,
        o.forces,
        o.stress,
        o.reaction
    )
}

/// The patch-test assertions: every A node in contact, pressures (multipliers and forces),
/// element stresses and the reactions at the held dofs exact to `tol` (relative to `p`).
fn check_patch(case: &Patch, o: &PatchOutcome, tol: f64) {
    let what = case.name;
    assert_eq!(o.active, o.a_nodes, "{what}: every A node in contact");
    for (label, v) in [
        ("multiplier pressure", o.multipliers),
        ("force pressure", o.forces),
        ("element stress", o.stress),
        ("reaction", o.reaction),
    ] {
        assert!(v < tol, "{what}: {label} error {v:.2e} above {tol:.0e}");
    }
}

// ---------------------------------------------------------------------------------------------
// 1. Modulus ratio

/// `E_disk / E_block` from 1e-8 to 1e8 on the Hertz scene at 8 elements per half-width.
///
/// Tolerance: half-width and peak within 1% of Hertz. At n = 8 and ratio 1 the errors are
/// -0.31% / +0.35% (docs/validation.md: set-up offset of order a/R plus discretisation); across the ratios
/// they stay below 0.6% (the Dundurs mismatch of dissimilar bodies shifts the pressure slightly,
/// an earlier overview of the main job: 0.49-0.55% at 1e-2 and 1e-4; measured here 0.33-0.51% and 0.46-0.61%),
/// so 1% separates them from a failure. Beyond a ratio of 1e4 the soft body's flexibility
/// dominates the contact system (`F_soft + F_stiff`) by more than 1e4, so the results must
/// approach a limit: the ratios 1e-8 and 1e8 must agree with 1e-4 and 1e4 in `a` and
/// `p0 / p0_H` to 1e-5 relative (measured 2e-7 .. 5e-7, the stiff body's remaining share and
/// the iteration tolerance 1e-6; a loss of accuracy in the soft body's flexibility to the
/// 1e8 spread of the moduli would show far above 1e-5).
#[test]
fn modulus_ratio_extremes() {
    let clock = Instant::now();
    let mut out = String::from("1. modulus ratio E_disk / E_block, Hertz scene, n = 8\n");
    out += &hertz_header();
    let mut rows = Vec::new();
    for ratio in [1e-8, 1e-4, 1.0, 1e4, 1e8] {
        let def = DiskOnBlock {
            elements_per_half_width: 8,
            modulus_ratio: ratio,
            ..Default::default()
        };
        let results = hertz(def, ContactOptions::default(), 1)
            .unwrap_or_else(|e| panic!("ratio {ratio:e}: {e}"));
        let (c, it) = &results[0];
        out += &hertz_row(&format!("{ratio:e}"), c, *it);
        rows.push((ratio, c.clone()));
    }
    let limit = |extreme: usize, near: usize| {
        let (a, b) = (&rows[extreme].1, &rows[near].1);
        [
            a.half_width / b.half_width - 1.0,
            (a.peak / a.hertz.peak) / (b.peak / b.hertz.peak) - 1.0,
        ]
    };
    let limits = [limit(0, 1), limit(4, 3)];
    println!(
        "{out}1e-8 against 1e-4: a {:+.1e}, p0/p0H {:+.1e}; 1e8 against 1e4: a {:+.1e}, p0/p0H \
         {:+.1e}\ntime {:.2} s",
        limits[0][0],
        limits[0][1],
        limits[1][0],
        limits[1][1],
        clock.elapsed().as_secs_f64()
    );
    for (ratio, c) in &rows {
        assert!(all_finite(c), "ratio {ratio:e}: non-finite result {c:?}");
        let (da, dp) = hertz_errors(c);
        assert!(
            da.abs() < 0.01,
            "ratio {ratio:e}: half-width {:+.3}%",
            100.0 * da
        );
        assert!(dp.abs() < 0.01, "ratio {ratio:e}: peak {:+.3}%", 100.0 * dp);
    }
    for (k, pair) in ["1e-8 vs 1e-4", "1e8 vs 1e4"].iter().enumerate() {
        for d in limits[k] {
            assert!(
                d.abs() < 1e-5,
                "{pair}: a and p0 / p0H differ by {:?}",
                limits[k]
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------
// 2. Nearly incompressible

/// Poisson's ratio 0.3 to 0.49999 in plane strain, Hertz scene, n = 8, ratio 1.
///
/// Tolerances: half-width and peak within 1% of Hertz (`E*` from both materials, which carries
/// the `1 - nu^2`), as in test 1 (measured -0.33% / +0.46% at nu = 0.3, -0.08% / +0.26% at
/// 0.49999); the L2 error below 6% (4.5% at 0.3, 4.1% at 0.49999). The locking check: from
/// nu = 0.49 to 0.49999 the bulk modulus grows a thousandfold, so a locking element would
/// drift with it; the hybrid element's a and p0 errors must stay within 0.1 percentage
/// point of their values at 0.49 (measured drift 0.013 points).
#[test]
fn nearly_incompressible() {
    let clock = Instant::now();
    let mut out = String::from("2. Poisson's ratio, plane strain, Hertz scene, n = 8\n");
    out += &hertz_header();
    let mut rows = Vec::new();
    for nu in [0.3, 0.49, 0.4999, 0.49999] {
        let def = DiskOnBlock {
            elements_per_half_width: 8,
            poisson: nu,
            ..Default::default()
        };
        let results =
            hertz(def, ContactOptions::default(), 1).unwrap_or_else(|e| panic!("nu {nu}: {e}"));
        let (c, it) = &results[0];
        out += &hertz_row(&format!("nu = {nu}"), c, *it);
        rows.push((nu, c.clone()));
    }
    println!("{out}time {:.2} s", clock.elapsed().as_secs_f64());
    let reference = hertz_errors(&rows[1].1);
    for (nu, c) in &rows {
        assert!(all_finite(c), "nu {nu}: non-finite result {c:?}");
        let (da, dp) = hertz_errors(c);
        assert!(da.abs() < 0.01, "nu {nu}: half-width {:+.3}%", 100.0 * da);
        assert!(dp.abs() < 0.01, "nu {nu}: peak {:+.3}%", 100.0 * dp);
        assert!(c.l2_error < 0.06, "nu {nu}: L2 {:.3}%", 100.0 * c.l2_error);
        if *nu >= 0.49 {
            assert!(
                (da - reference.0).abs() < 1e-3 && (dp - reference.1).abs() < 1e-3,
                "nu {nu}: a {:+.3}%, p0 {:+.3}% drift from nu = 0.49 ({:+.3}%, {:+.3}%)",
                100.0 * da,
                100.0 * dp,
                100.0 * reference.0,
                100.0 * reference.1
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------
// 3. Stretched and skewed elements

/// Contact patch tests with elements of aspect ratio 1e3 next to the interface (both blocks,
/// 6 layers growing geometrically away from it, the first `h / 1000` thick) and with strongly
/// skewed elements (32 layers of herringbone parallelograms, smallest corner angle 7.3
/// degrees), non-matching interface (13 A / 8 B elements), with zero gap and with a gap of
/// 1e-3 closed by the load. The test also checks that the meshes have that aspect and angle.
///
/// Tolerance 1e-8 relative to `p`: the exact solution lies in the discrete spaces, so the
/// error is round-off times the conditioning. The flat mesh is exact to 1e-13; layers of
/// thickness `h / 1000` raise the condition number of the stiffness by up to the aspect
/// squared, so up to ~1e-13 x 1e6 is round-off here (measured 1.6e-11, and 2.1e-10 with the
/// gap, whose closing displacement 1e-3 is ten times the elastic one; skewed 5.6e-12 and
/// 5.5e-11). 1e-8 leaves a factor 50 and still catches any consistency error (those are of
/// order `eps_x = 8e-5` or larger).
#[test]
fn stretched_and_skewed_elements() {
    let clock = Instant::now();
    let mut out = String::from("3. stretched and skewed elements, contact patch test, p = 1e-3\n");
    let stretched = Patch {
        layers_a: Layers::Stretched(6, 1e3),
        layers_b: Layers::Stretched(6, 1e3),
        ..Default::default()
    };
    let skewed = Patch {
        layers_a: Layers::Uniform(32),
        layers_b: Layers::Uniform(32),
        skew: 0.49,
        ..Default::default()
    };
    let cases = [
        Patch {
            name: "flat (reference)",
            ..Default::default()
        },
        Patch {
            name: "aspect 1e3",
            ..stretched
        },
        Patch {
            name: "aspect 1e3, gap 1e-3",
            gap: 1e-3,
            ..stretched
        },
        Patch {
            name: "skewed",
            ..skewed
        },
        Patch {
            name: "skewed, gap 1e-3",
            gap: 1e-3,
            ..skewed
        },
    ];
    out += &patch_header();
    let mut results = Vec::new();
    for case in cases {
        let o = patch(case).unwrap_or_else(|e| panic!("{}: {e}", case.name));
        out += &patch_row(&case, &o);
        results.push((case, o));
    }
    println!("{out}time {:.2} s", clock.elapsed().as_secs_f64());
    for (case, o) in &results {
        check_patch(case, o, 1e-8);
    }
    // the meshes do what the test is about
    assert!(results[1].1.max_aspect > 999.0 && results[2].1.max_aspect > 999.0);
    assert!(results[3].1.min_angle < 10.0 && results[4].1.min_angle < 10.0);
}

// ---------------------------------------------------------------------------------------------
// 4. Units

/// The Hertz scene (n = 4, calibration + 3 increments) with lengths scaled by 1e-6, 1, 1e6 and
/// moduli (forces) by 1e-6, 1, 1e6 in all combinations: the dimensionless results a / R,
/// p0 / E, P / (E R) and the L2 error agree with the unscaled run to relative 1e-9 at every
/// increment. Every tolerance of the method is relative (gap and search distance to the segment
/// length, tension to the largest traction, convergence to the increment displacement) and the
/// scene builds its meshes for R = 1 before scaling, so the runs differ only by round-off; the
/// iteration tolerance is 1e-12 so that they stop at round-off, not at a tolerance two runs may
/// cross at different iterations (see `hertz_unit_invariance` in `tests/contact_hertz.rs`).
#[test]
fn unit_scaling() {
    let clock = Instant::now();
    let options = ContactOptions {
        tolerance: 1e-12,
        ..Default::default()
    };
    let dimensionless = |length: f64, modulus: f64| -> Vec<f64> {
        let def = DiskOnBlock {
            elements_per_half_width: 4,
            radius: length,
            block_modulus: modulus,
            ..Default::default()
        };
        hertz(def, options, 3)
            .unwrap_or_else(|e| panic!("length {length:e}, modulus {modulus:e}: {e}"))
            .iter()
            .flat_map(|(c, _)| {
                [
                    c.half_width / length,
                    c.peak / modulus,
                    c.load / (modulus * length),
                    c.l2_error,
                ]
            })
            .collect()
    };
    let base = dimensionless(1.0, 1.0);
    let mut out = String::from("4. unit scaling, Hertz scene n = 4, 3 increments\n");
    out += &format!(
        "{:>8} {:>8} | {:>12} {:>12} {:>12} | largest relative difference\n",
        "length", "modulus", "a/R", "p0/E", "L2"
    );
    let mut worst = Vec::new();
    for length in [1e-6, 1.0, 1e6] {
        for modulus in [1e-6, 1.0, 1e6] {
            let d = dimensionless(length, modulus);
            let diff =
                d.iter()
                    .zip(&base)
                    .map(|(x, y)| ((x - y) / y).abs())
                    .fold(
                        0.0,
                        |m: f64, v| if v.is_nan() { f64::NAN } else { m.max(v) },
                    );
            let n = d.len();
            out += &format!(
                "{length:>8.0e} {modulus:>8.0e} | {:>12.9} {:>12.9e} {:>12.9} | {diff:.1e}\n",
                d[n - 4],
                d[n - 3],
                d[n - 1]
            );
            worst.push((length, modulus, diff));
        }
    }
    println!("{out}time {:.2} s", clock.elapsed().as_secs_f64());
    for (length, modulus, diff) in worst {
        assert!(
            diff < 1e-9,
            "length x {length:e}, modulus x {modulus:e}: dimensionless results differ by {diff:.2e}"
        );
    }
}

// ---------------------------------------------------------------------------------------------
// 5. Load magnitude

/// Iteration options for the load sweep (see [`load_magnitudes`]).
fn load_options(kinematics: Kinematics) -> ContactOptions {
    ContactOptions {
        kinematics,
        tolerance: 1e-12,
        max_iterations: 100,
        gap_tolerance: 1e-15,
        search_distance: 8.0,
        ..Default::default()
    }
}

/// The frictionless contact patch test (zero initial gap, non-matching meshes 13 / 8) at load
/// factors 1e-9, 1e-3, 1, 1e3 times p = 1e-3 (strains up to 0.3 at 1e3: a numerical stress
/// case, not a physical one), with both kinematics.
///
/// Small kinematics: the problem is linear, so `tn / (f p) = 1` at every factor.
///
/// Finite kinematics: the contact set is the whole interface at every load, the interface is
/// flat and both blocks widen alike, so the only nonlinearity is the current-configuration
/// geometry, and its one effect is exact and known: the tractions are per unit current length
/// of an interface widened by `eps_x = nu (1 + nu) p / E` (proportional to the load), so
/// `tn / (f p) = 1 / (1 + eps_x)` = 1 - 8e-14, 1 - 8e-8, 1 - 8e-5, 1 - 0.074 (measured to
/// round-off).
///
/// Asserted, node by node, with `e = 0` (small) or `e = eps_x` (finite): `tn (1 + e) / (f p)`
/// equal to 1 and to the value at factor 1 within 1e-10 (round-off: measured 1e-13; 2e-12 at
/// factor 1e3 under finite kinematics, where the geometry moves by 8% and the iteration stops
/// at `R <= 1e-12` after ~57 iterations), and the raw `tn / (f p)` deviating from 1 by
/// `e / (1 + e)` within 1e-10.
///
/// Options (not the defaults, see [`load_magnitudes_default_options`]): the gap tolerance is
/// relative to the segment length (default 1e-9 h), so at factor 1e-9, where the first
/// iterate's penetration is ~1e-13 = 1e-12 h, the default never activates a node; the search
/// distance (default 4 A segments) must exceed the first iterate's penetration, about 5
/// segments at factor 1e3 (the upper block, all nodes open, is carried by its two top
/// corners and sags), for finite kinematics to pair the sagged surfaces.
#[test]
fn load_magnitudes() {
    let clock = Instant::now();
    let factors = [1e-9, 1e-3, 1.0, 1e3];
    let mut out = String::from("5. load magnitude, contact patch test, p = factor x 1e-3\n");
    out += &format!(
        "{:>7} {:>8} {:>3} {:>6} | {:>16} {:>16} {:>10} {:>9}\n",
        "kin.", "factor", "it", "active", "tn / (f p)", "x (1 + e)", "e", "max error"
    );
    let mut rows = Vec::new();
    for kinematics in [Kinematics::Small, Kinematics::Finite] {
        let mut group = Vec::new();
        for factor in factors {
            let case = Patch {
                name: "load",
                pressure: 1e-3 * factor,
                options: load_options(kinematics),
                ..Default::default()
            };
            let o = patch(case).unwrap_or_else(|e| panic!("factor {factor:e}: {e}"));
            let scaled: Vec<f64> = o.tn.iter().map(|t| t / case.pressure).collect();
            let e = match kinematics {
                Kinematics::Small => 0.0,
                Kinematics::Finite => o.widening,
            };
            out += &format!(
                "{:>7} {factor:>8.0e} {:>3} {:>3}/{:<2} | {:>16.13} {:>16.13} {:>10.3e} {:>9.1e}\n",
                kinematics.name(),
                o.iterations,
                o.active,
                o.a_nodes,
                scaled[0],
                scaled[0] * (1.0 + e),
                e,
                o.multipliers
            );
            group.push((factor, o, scaled, e));
        }
        rows.push((kinematics, group));
    }
    println!("{out}time {:.2} s", clock.elapsed().as_secs_f64());
    for (kinematics, group) in &rows {
        let reference: Vec<f64> = {
            let (_, _, scaled, e) = &group[2];
            scaled.iter().map(|t| t * (1.0 + e)).collect()
        };
        let kin = kinematics.name();
        for (factor, o, scaled, e) in group {
            assert_eq!(
                o.active, o.a_nodes,
                "{kin}, factor {factor:e}: every A node in contact"
            );
            for (k, (t, r)) in scaled.iter().zip(&reference).enumerate() {
                let corrected = t * (1.0 + e);
                assert!(
                    (corrected - 1.0).abs() < 1e-10 && (corrected - r).abs() < 1e-10,
                    "{kin}, factor {factor:e}, A node {k}: tn (1 + e) / (f p) = \
                     {corrected:.15} (factor 1: {r:.15})"
                );
                let deviation = 1.0 - t;
                let predicted = e / (1.0 + e);
                assert!(
                    (deviation - predicted).abs() < 1e-10,
                    "{kin}, factor {factor:e}, A node {k}: 1 - tn / (f p) = {deviation:.3e}, \
                     e / (1 + e) = {predicted:.3e}"
                );
            }
        }
    }
}

/// The load sweep's extremes with the default iteration options (and finite kinematics): each
/// must give the exact pressure or an error, never `Ok` with the bodies interpenetrating. At
/// factor 1e-9 the first iterate's penetration (~1e-13) is tiny in absolute terms, but the gap
/// tolerance is relative to the increment's own motion. At factor 1e3 the first iterate
/// penetrates (~0.4) beyond the search distance `4 h`: small kinematics pair the surfaces once
/// in the reference configuration, where they touch, and give the exact pressure; finite
/// kinematics pair the sagged surfaces because the search reaches twice the increment's motion
/// too. Their geometry is nonlinear, so the fixed-point iteration stops within its tolerance
/// `R <= tol` of the exact state: the pressure is exact to a few `tol` (1.8e-6 at the default
/// 1e-6, and it follows `tol` down: the run with `tol = 1e-10` must be exact to 1e-9).
#[test]
fn load_magnitudes_default_options() {
    let mut failures = Vec::new();
    for (kinematics, tolerance) in [
        (Kinematics::Small, 1e-6),
        (Kinematics::Finite, 1e-6),
        (Kinematics::Finite, 1e-10),
    ] {
        for factor in [1e-9, 1e3] {
            let case = Patch {
                name: "load, default options",
                pressure: 1e-3 * factor,
                options: ContactOptions {
                    kinematics,
                    tolerance,
                    ..Default::default()
                },
                ..Default::default()
            };
            let kin = kinematics.name();
            match patch(case) {
                Ok(o) => {
                    let line = format!(
                        "{kin}, tol {tolerance:e}, factor {factor:e}: Ok with {} of {} A nodes \
                         in contact, pressure error {:.2e}",
                        o.active, o.a_nodes, o.multipliers
                    );
                    println!("{line}");
                    // exact to round-off, or to the iteration's tolerance for the nonlinear
                    // finite-kinematics geometry
                    let exact = match kinematics {
                        Kinematics::Small => 1e-8,
                        Kinematics::Finite => 1e-8_f64.max(10.0 * tolerance),
                    };
                    if o.multipliers.is_nan() || o.multipliers >= exact {
                        failures.push(line);
                    }
                }
                Err(e) => {
                    println!("{kin}, factor {factor:e}: error {e}");
                    if kinematics == Kinematics::Small {
                        failures.push(format!("{kin}, factor {factor:e}: {e}"));
                    }
                }
            }
        }
    }
    assert!(failures.is_empty(), "wrong results: {failures:#?}");
}

// ---------------------------------------------------------------------------------------------
// 6. Refinement

/// The Hertz scene at 2, 4, ..., 128 elements per half-width (calibration + 3 increments;
/// n = 128 takes about 2 s of the suite's time in the dev profile, so it stays in).
///
/// Asserted: every increment converges (any error fails the test) in at most 20 iterations;
/// every result is finite; the final-increment L2 error of the multiplier pressure decreases
/// strictly from n = 2 to n = 32 (measured 23.7%, 10.8%, 4.5%, 1.08%, 0.81%) and stays below 1%
/// for n >= 32 (0.81%, 0.91%, 0.68%: it no longer decreases monotonically once it reaches the
/// floor set by the a/R offset of the set-up, -0.3% in a and +0.35% in p0, and by where the
/// contact edge falls between nodes); half-width and peak within 1% of Hertz from n = 16 (the
/// tolerance of `tests/contact_hertz.rs`).
#[test]
fn refinement_range() {
    let clock = Instant::now();
    let mut out =
        String::from("6. refinement, Hertz scene, calibration + 3 increments (final shown)\n");
    out += &format!(
        "{:>5} {:>7} | {:>9} {:>9} {:>8} {:>8} {:>6} {:>12}\n",
        "n", "time", "a-aH", "p0-p0H", "L2", "L2 force", "active", "iterations"
    );
    let mut rows = Vec::new();
    for n in [2, 4, 8, 16, 32, 64, 128] {
        let t = Instant::now();
        let def = DiskOnBlock {
            elements_per_half_width: n,
            ..Default::default()
        };
        let results =
            hertz(def, ContactOptions::default(), 3).unwrap_or_else(|e| panic!("n = {n}: {e}"));
        let (c, _) = results.last().unwrap().clone();
        let (da, dp) = hertz_errors(&c);
        let iterations: Vec<usize> = results.iter().map(|r| r.1).collect();
        out += &format!(
            "{n:>5} {:>6.2}s | {:>+8.3}% {:>+8.3}% {:>7.3}% {:>7.3}% {:>6} {:>12}\n",
            t.elapsed().as_secs_f64(),
            100.0 * da,
            100.0 * dp,
            100.0 * c.l2_error,
            100.0 * c.l2_error_forces,
            c.active,
            format!("{iterations:?}")
        );
        rows.push((n, results));
    }
    println!("{out}time {:.2} s", clock.elapsed().as_secs_f64());
    let mut finals = Vec::new();
    for (n, results) in &rows {
        for (step, (c, it)) in results.iter().enumerate() {
            assert!(all_finite(c), "n = {n}, increment {}: {c:?}", step + 1);
            assert!(
                *it <= 20,
                "n = {n}, increment {}: {it} iterations",
                step + 1
            );
        }
        let c = &results.last().unwrap().0;
        if *n >= 16 {
            let (da, dp) = hertz_errors(c);
            assert!(
                da.abs() < 0.01 && dp.abs() < 0.01,
                "n = {n}: a {da:+.4}, p0 {dp:+.4}"
            );
        }
        if *n >= 32 {
            assert!(c.l2_error < 0.01, "n = {n}: L2 {:.3}%", 100.0 * c.l2_error);
        }
        finals.push((*n, c.l2_error));
    }
    for w in finals.windows(2).filter(|w| w[1].0 <= 32) {
        assert!(
            w[1].1 < w[0].1,
            "L2 error must decrease up to n = 32: {finals:?}"
        );
    }
}

// ---------------------------------------------------------------------------------------------
// 7. Near-coincident nodes, conforming contact

/// Contact patch tests with zero initial gap over the whole interface (conforming contact),
/// node-to-node and non-matching, and with B's interior interface nodes moved along the
/// interface by +-1e-12 (relative to the width 1) off the A nodes they coincide with, so the
/// mortar projection meets overlaps of length 1e-12 (and, with a gap of 1e-3 closed by the
/// load, the near-coincidence is reached in the current configuration).
///
/// Asserted: `Ok` (no error; the API has no warnings, so one converged increment with the
/// iteration's records all belonging to it is "no warning"), every A node active, pressures,
/// stresses and reactions exact to 1e-11 relative to `p`, the tolerance of
/// `tests/contact_patch.rs` (measured 1e-14 .. 1e-13; the exact solution is in the discrete
/// spaces for any node positions along a flat interface).
#[test]
fn near_coincident_and_conforming() {
    let clock = Instant::now();
    let equal = Patch {
        nx_a: 8,
        nx_b: 8,
        ..Default::default()
    };
    let cases = [
        Patch {
            name: "node-to-node, gap 0",
            ..equal
        },
        Patch {
            name: "non-matching, gap 0",
            ..Default::default()
        },
        Patch {
            name: "B +-1e-12 off A, gap 0",
            shift_b: 1e-12,
            ..equal
        },
        Patch {
            name: "B +-1e-12 off A, gap",
            shift_b: 1e-12,
            gap: 1e-3,
            ..equal
        },
        Patch {
            name: "B +-1e-9 off A, gap 0",
            shift_b: 1e-9,
            ..equal
        },
    ];
    let mut out = String::from("7. near-coincident nodes and conforming contact, p = 1e-3\n");
    out += &patch_header();
    let mut results = Vec::new();
    for case in cases {
        let o = patch(case).unwrap_or_else(|e| panic!("{}: {e}", case.name));
        out += &patch_row(&case, &o);
        results.push((case, o));
    }
    println!("{out}time {:.2} s", clock.elapsed().as_secs_f64());
    for (case, o) in &results {
        assert!(
            o.iterations <= 10,
            "{}: {} iterations",
            case.name,
            o.iterations
        );
        check_patch(case, o, 1e-11);
    }
}

// ---------------------------------------------------------------------------------------------
// 8. Bad situations

/// A disk pulled off the block: from the start (negative approach) and after pressing. Both
/// increments converge with every node open and tractions exactly zero (not merely small: an
/// open node has no unknown), the field finite, and the Hertz comparison refuses with a clear
/// `Error::InvalidInput` ("no compressive contact load") instead of dividing by a zero load.
#[test]
fn pulled_off() {
    let clock = Instant::now();
    let scene = DiskOnBlock {
        elements_per_half_width: 8,
        ..Default::default()
    }
    .build()
    .unwrap();
    let f = vec![0.0; 2 * scene.model.mesh.n_nodes()];
    let a = scene.half_width;
    let lift = -a * a / scene.radius;
    let mut out = String::from("8a. disk pulled off the block, n = 8\n");
    let mut check = |analysis: &mut ContactAnalysis, label: &str| {
        let nodes = analysis.node_results(0).unwrap();
        let open = nodes.iter().filter(|n| n.state == NodeState::Open).count();
        let largest = nodes
            .iter()
            .map(|n| {
                n.tn.abs()
                    .max(n.ts.norm())
                    .max(n.force[0].abs())
                    .max(n.force[1].abs())
            })
            .fold(0.0, f64::max);
        let field_finite = analysis
            .displacement()
            .unwrap()
            .iter()
            .all(|v| v.is_finite());
        let comparison = scene.compare(analysis);
        out += &format!(
            "{label:>22}: {open}/{} open, max |traction or force| {largest:e}, field finite \
             {field_finite}, compare: {:?}\n",
            nodes.len(),
            comparison.as_ref().map(|c| c.load)
        );
        assert_eq!(open, nodes.len(), "{label}: every node open");
        assert_eq!(largest, 0.0, "{label}: zero tractions");
        assert!(field_finite, "{label}: finite displacement");
        match comparison {
            Err(Error::InvalidInput(m)) => {
                assert!(m.contains("no compressive contact load"), "{m}")
            }
            other => panic!("{label}: compare must refuse: {other:?}"),
        }
    };
    let mut analysis = scene.analysis(ContactOptions::default()).unwrap();
    analysis
        .increment(&f, &scene.prescribed(lift, 0.0))
        .unwrap();
    check(&mut analysis, "pulled from the start");
    let approach = scene.calibrated_approach(&mut analysis).unwrap();
    analysis
        .increment(&f, &scene.prescribed(approach, 0.0))
        .unwrap();
    let pressed = scene.compare(&analysis).unwrap();
    assert!(pressed.active > 0 && pressed.load > 0.0);
    analysis
        .increment(&f, &scene.prescribed(lift, 0.0))
        .unwrap();
    check(&mut analysis, "pressed, then pulled");
    println!("{out}time {:.2} s", clock.elapsed().as_secs_f64());
}

/// A disk held only by a rigid plate under force control, frictionless: pressed by the Hertz
/// load (x displacement-controlled), then a tangential force on the plate, which frictionless
/// contact cannot resist (the disk's rigid x motion is then undetermined: the bordered contact
/// system is singular up to round-off). The increment must fail with `Error::Singular` or
/// `Error::Contact` and a message without NaN / inf, and the analysis must keep its last
/// converged state: the same records, displacement field, plate state and contact results.
/// Also from a fresh analysis (nothing converged yet). Tangential forces 1e-2 P, 1e-8 P and 0
/// (with zero force the x motion is just as undetermined).
#[test]
fn floating_body_frictionless() {
    let clock = Instant::now();
    let scene = DiskOnBlock {
        elements_per_half_width: 8,
        ..Default::default()
    }
    .build()
    .unwrap();
    let p = scene.hertz_load();
    let f = vec![0.0; 2 * scene.model.mesh.n_nodes()];
    let press = [PlateControl::Displacement(0.0), PlateControl::Force(-p)];
    let mut out =
        String::from("8b. floating disk, frictionless, plate force-controlled in x and y\n");
    for pressed in [false, true] {
        for q in [1e-2, 1e-8, 0.0] {
            let mut analysis = scene.plate_analysis(ContactOptions::default()).unwrap();
            if pressed {
                analysis.increment_with_plate(&f, &f, &press).unwrap();
            }
            let records = analysis.records().to_vec();
            let field = analysis.displacement().unwrap().to_vec();
            let plate = analysis.plate();
            let nodes = analysis.node_results(0).unwrap();
            let push = [PlateControl::Force(q * p), PlateControl::Force(-p)];
            let result = analysis.increment_with_plate(&f, &f, &push);
            let label = format!("{}, Q = {q:e} P", if pressed { "pressed" } else { "fresh" });
            out += &format!("{label:>22}: {result:?}\n");
            let message = match &result {
                Err(e @ (Error::Singular(_) | Error::Contact(_))) => e.to_string(),
                other => panic!("{label}: must fail with Singular or Contact, got {other:?}"),
            };
            let lower = message.to_lowercase();
            assert!(
                !lower.contains("nan") && !lower.contains("inf") && message.len() > 20,
                "{label}: unreadable message {message:?}"
            );
            assert_eq!(analysis.records(), &records[..], "{label}: records changed");
            assert_eq!(analysis.plate(), plate, "{label}: plate state changed");
            assert_eq!(
                analysis.node_results(0).unwrap(),
                nodes,
                "{label}: contact state changed"
            );
            assert_eq!(
                analysis.displacement().unwrap(),
                &field[..],
                "{label}: field changed"
            );
        }
    }
    println!("{out}time {:.2} s", clock.elapsed().as_secs_f64());
}

/// The floating-body case is reported as what it is: `Error::Singular` ("frictionless contact
/// cannot resist tangential motion"). The small dense LU alone meets a pivot of round-off
/// size, not an exact zero; the solver checks that every force-controlled plate direction is
/// held by an active constraint or by the plate's own stiffness.
#[test]
fn floating_body_reports_singular() {
    let scene = DiskOnBlock {
        elements_per_half_width: 8,
        ..Default::default()
    }
    .build()
    .unwrap();
    let p = scene.hertz_load();
    let f = vec![0.0; 2 * scene.model.mesh.n_nodes()];
    let mut analysis = scene.plate_analysis(ContactOptions::default()).unwrap();
    let push = [PlateControl::Force(1e-2 * p), PlateControl::Force(-p)];
    match analysis.increment_with_plate(&f, &f, &push) {
        Err(Error::Singular(m)) => assert!(m.contains("frictionless"), "{m}"),
        other => panic!("expected Error::Singular, got {other:?}"),
    }
}
