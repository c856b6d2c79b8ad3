//! Property tests of the Rust contact entry points (`ContactAnalysis::new`, `increment`,
//! `node_results`) on random two-block problems (proptest, fixed seed, 1024 cases): whatever the
//! outcome of a problem, its variants must give the same one.
//!
//! The problem: a lower block `[0, 2] x [0, 1]` held at its bottom, an upper block of random
//! width and position `gap` above it, pressed down by `depth` and moved sideways by `slide`
//! through prescribed values on its top; A = the upper block's bottom, B = the lower block's
//! top; random meshes, moduli, Poisson's ratios, friction and kinematics. Properties:
//! * a zero increment (the last totals again) converges in at most 3 iterations to the same
//!   tractions;
//! * rigid translation of every coordinate (up to 1e3 times the body size) leaves the
//!   tractions unchanged, and so does a rotation on top of it (to 1e4 eps |X| / approach at
//!   least: rotated, the flat surfaces carry the coordinates' round-off across them);
//! * unit scaling (lengths times `s_l`, moduli times `s_e`) scales the tractions by `s_e`;
//! * renumbering the nodes (a random permutation) leaves the tractions at each A node
//!   unchanged;
//! * all of these to 1e-8 of the peak traction under small kinematics (round-off: given the
//!   contact set the problem is linear), to 1e-5 under finite kinematics (ten times the
//!   iteration's tolerance: the nonlinear geometry's fixed point is found to that);
//! * every problem converges (0.7.0; 0.6.2 failed about 2.6% of them alike in every variant),
//!   and an error in a variant would have to be the same error in every variant (its kind),
//!   never a panic.
//!
//! The same problems in axisymmetry (`x = r`, `y = z`, 256 cases): the lower block off the
//! axis or touching it, and on one touching it the upper block beside it or on the axis too
//! (`u_r = 0` held on the axis). Their rigid motions are the translations along the axis: the
//! properties are the zero increment, an axial translation, unit scaling and renumbering, to
//! the same tolerances.
//!
//! The 3D analysis on random presses of a turned block on a flat (32 cases, module `solid`):
//! a rigid motion, unit scaling and renumbering, to round-off as the press's own condition
//! measures it.

use hycon::contact::iteration::{ContactAnalysis, ContactOptions, ContactPair, Kinematics};
use hycon::element::Formulation;
use hycon::mesh::Mesh;
use hycon::model::Model;
use hycon::{Analysis, Error, Material};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

use crate::common::{block, permutation};

/// One random problem.
#[derive(Debug, Clone)]
struct Problem {
    lower: [usize; 2],
    upper: [usize; 2],
    left: f64,
    width: f64,
    gap: f64,
    depth: f64,
    slide: f64,
    moduli: [f64; 2],
    poisson: [f64; 2],
    friction: f64,
    kinematics: Kinematics,
    /// `PlaneStrain`, or `Axisymmetric` (`x = r`, `y = z`).
    analysis: Analysis,
    /// The lower block's left side: its inner radius in axisymmetry (0 in plane problems);
    /// `left` is the upper block's.
    axis: f64,
}

/// A variant of a problem: coordinates `s_l (X + t)` after renumbering by `perm`
/// (`perm[old] = new`), moduli times `s_e`.
#[derive(Debug, Clone)]
struct Variant {
    translation: [f64; 2],
    /// Rotation about the origin after translating and scaling (radians).
    angle: f64,
    length_scale: f64,
    modulus_scale: f64,
    perm: Option<Vec<usize>>,
}

impl Variant {
    fn identity() -> Self {
        Variant {
            translation: [0.0, 0.0],
            angle: 0.0,
            length_scale: 1.0,
            modulus_scale: 1.0,
            perm: None,
        }
    }
}

/// The outcome of a run: the tractions `(tn, ts)` per A node after each increment and the
/// iterations of the zero increment, or the error's kind.
type Outcome = std::result::Result<(Vec<Vec<(f64, f64)>>, usize), String>;

/// The error's variant, by name (`contact SlipReversal`, `Singular`).
fn error_kind(e: &Error) -> String {
    let name = |debug: String| {
        debug
            .split(|c: char| !c.is_alphanumeric())
            .next()
            .unwrap_or_default()
            .to_string()
    };
    match e {
        Error::Contact(c) => format!("contact {}", name(format!("{c:?}"))),
        other => name(format!("{other:?}")),
    }
}

/// `x` rotated by the variant's angle.
fn rotate(v: &Variant, x: [f64; 2]) -> [f64; 2] {
    let (s, c) = v.angle.sin_cos();
    [c * x[0] - s * x[1], s * x[0] + c * x[1]]
}

/// The problem's analysis in variant `v`, with the upper block's top nodes (renumbered), or the
/// error's kind.
fn analysis(
    p: &Problem,
    v: &Variant,
) -> std::result::Result<(ContactAnalysis, Vec<usize>), String> {
    analysis_with(p, v, ContactOptions::default())
}

/// As [`analysis`], with `options` (their kinematics replaced by the problem's).
fn analysis_with(
    p: &Problem,
    v: &Variant,
    options: ContactOptions,
) -> std::result::Result<(ContactAnalysis, Vec<usize>), String> {
    let mut mesh = Mesh::new();
    let lower = block(&mut mesh, [p.axis, 0.0], [2.0, 1.0], p.lower, 0);
    let upper = block(&mut mesh, [p.left, 1.0 + p.gap], [p.width, 1.0], p.upper, 1);
    let row =
        |ids: &[usize], n: [usize; 2], j: usize| ids[j * (n[0] + 1)..(j + 1) * (n[0] + 1)].to_vec();
    let a = row(&upper, p.upper, 0);
    let mut b = row(&lower, p.lower, p.lower[1]);
    b.reverse();
    let bottom = row(&lower, p.lower, 0);
    let top = row(&upper, p.upper, p.upper[1]);
    // the nodes on the axis, u_r = 0 (but the held bottom and top rows)
    let column = |ids: &[usize], n: [usize; 2], rows: std::ops::Range<usize>| -> Vec<usize> {
        rows.map(|j| ids[j * (n[0] + 1)]).collect()
    };
    let mut on_axis = Vec::new();
    if p.analysis == Analysis::Axisymmetric && p.axis == 0.0 {
        on_axis.extend(column(&lower, p.lower, 1..p.lower[1] + 1));
    }
    if p.analysis == Analysis::Axisymmetric && p.left == 0.0 {
        on_axis.extend(column(&upper, p.upper, 0..p.upper[1]));
    }
    // the variant: transform the coordinates, renumber every id
    for x in &mut mesh.nodes {
        *x = rotate(
            v,
            [
                v.length_scale * (x[0] + v.translation[0]),
                v.length_scale * (x[1] + v.translation[1]),
            ],
        );
    }
    let n = mesh.n_nodes();
    let perm: Vec<usize> = v.perm.clone().unwrap_or_else(|| (0..n).collect());
    let map = |ids: &[usize]| -> Vec<usize> { ids.iter().map(|&i| perm[i]).collect() };
    let mut renumbered = Mesh::new();
    renumbered.nodes = vec![[0.0; 2]; n];
    for (old, &new) in perm.iter().enumerate() {
        renumbered.nodes[new] = mesh.nodes[old];
    }
    for e in 0..mesh.n_elements() {
        renumbered.push_element(&map(mesh.element(e)), mesh.element_material[e]);
    }
    let materials = (0..2)
        .map(|i| Material::new(p.moduli[i] * v.modulus_scale, p.poisson[i], 1.0, p.analysis))
        .collect::<hycon::Result<Vec<_>>>()
        .map_err(|e| error_kind(&e))?;
    let mut model = Model::new(renumbered, materials, Formulation::Hybrid);
    let (bottom, top) = (map(&bottom), map(&top));
    model.fix(&bottom, [0.0, 0.0]).map_err(|e| error_kind(&e))?;
    model.fix(&top, [0.0, 0.0]).map_err(|e| error_kind(&e))?;
    if !on_axis.is_empty() {
        model
            .fix_dir(&map(&on_axis), 0, 0.0)
            .map_err(|e| error_kind(&e))?;
    }
    let pair = ContactPair {
        a: map(&a),
        b: map(&b),
        friction: p.friction,
    };
    let options = ContactOptions {
        kinematics: p.kinematics,
        ..options
    };
    let analysis = ContactAnalysis::new(model, vec![pair], options).map_err(|e| error_kind(&e))?;
    Ok((analysis, top))
}

/// The prescribed values of the upper block's top pressed by `depth` and moved by `slide`.
fn totals(p: &Problem, v: &Variant, n: usize, top: &[usize], slide: f64) -> Vec<f64> {
    let mut qp = vec![0.0; 2 * n];
    for &node in top {
        let u = rotate(v, [v.length_scale * slide, -v.length_scale * p.depth]);
        qp[2 * node] = u[0];
        qp[2 * node + 1] = u[1];
    }
    qp
}

fn run(p: &Problem, v: &Variant) -> Outcome {
    let (mut analysis, top) = analysis(p, v)?;
    let n = analysis
        .model()
        .map(|m| m.mesh.n_nodes())
        .map_err(|e| error_kind(&e))?;
    let f = vec![0.0; 2 * n];
    let tractions = |a: &ContactAnalysis| -> Vec<(f64, f64)> {
        let r = a.node_results(0).unwrap();
        r.iter().map(|n| (n.tn, n.ts.components()[0])).collect()
    };
    let mut out = Vec::new();
    for slide in [0.0, p.slide] {
        analysis
            .increment(&f, &totals(p, v, n, &top, slide))
            .map_err(|e| error_kind(&e))?;
        out.push(tractions(&analysis));
    }
    let zero = analysis
        .increment(&f, &totals(p, v, n, &top, p.slide))
        .map_err(|e| format!("zero increment: {e}"))?;
    out.push(tractions(&analysis));
    Ok((out, zero.iterations))
}

/// `got` equals `want` times `factor` to `tol` of the peak `|tn|` of `want`.
fn same(want: &[Vec<(f64, f64)>], got: &[Vec<(f64, f64)>], factor: f64, tol: f64) -> bool {
    let peak = want.iter().flatten().fold(0.0f64, |m, t| m.max(t.0.abs()));
    want.len() == got.len()
        && want.iter().zip(got).all(|(w, g)| {
            w.len() == g.len()
                && w.iter().zip(g).all(|(a, b)| {
                    (a.0 * factor - b.0).abs() <= tol * peak * factor.abs()
                        && (a.1 * factor - b.1).abs() <= tol * peak * factor.abs()
                })
        })
}

fn problem() -> impl Strategy<Value = Problem> {
    (
        (1usize..=5, 1usize..=3, 1usize..=4, 1usize..=3),
        (
            0.1f64..0.8,
            0.4f64..1.0,
            0.0f64..1e-3,
            1e-4f64..1e-2,
            -0.2f64..0.2,
        ),
        (-2.0f64..2.0, -0.2f64..0.45, -0.2f64..0.45),
        (prop_oneof![Just(0.0), 0.05f64..0.6], any::<bool>()),
    )
        .prop_map(
            |(
                (nxl, nyl, nxu, nyu),
                (left, width, gap, depth, slide),
                (log_ratio, nu0, nu1),
                (friction, small),
            )| {
                Problem {
                    lower: [nxl + 1, nyl],
                    upper: [nxu, nyu],
                    left,
                    width,
                    gap,
                    depth: gap + depth,
                    slide: slide * depth,
                    moduli: [1.0, 10f64.powf(log_ratio)],
                    poisson: [nu0, nu1],
                    friction,
                    kinematics: if small {
                        Kinematics::Small
                    } else {
                        Kinematics::Finite
                    },
                    analysis: Analysis::PlaneStrain,
                    axis: 0.0,
                }
            },
        )
}

/// The problems of [`problem`] in axisymmetry: the lower block off the axis (inner radius in
/// `[0.05, 1)`) or touching it, and on one touching it the upper block beside it or on the
/// axis too. That last case is pressed only (the upper block's top node on the axis is
/// prescribed, and `u_r = 0` there admits no slide); 0.7.0 drew it frictionless and under
/// small kinematics only (as `contact_randomized.c`: with friction the axis node's stick row
/// made the contact system singular, and under finite kinematics the active axis node was
/// found uncovered by round-off).
fn axisymmetric_problem() -> impl Strategy<Value = Problem> {
    (
        problem(),
        prop_oneof![Just(None), (0.05f64..1.0).prop_map(Some)],
        any::<bool>(),
    )
        .prop_map(|(p, off_axis, both_on_axis)| {
            let analysis = Analysis::Axisymmetric;
            match off_axis {
                Some(axis) => Problem {
                    analysis,
                    axis,
                    left: axis + p.left,
                    ..p
                },
                None if both_on_axis => Problem {
                    analysis,
                    left: 0.0,
                    slide: 0.0,
                    ..p
                },
                None => Problem { analysis, ..p },
            }
        })
}

/// The tolerance of the variants: round-off under small kinematics (given the contact set the
/// problem is linear); under finite ones the iteration's tolerance (1e-6 of the increment's
/// motion): the fixed point of the nonlinear geometry is found to that, and a variant's
/// round-off may stop it one iteration earlier or later.
fn tolerance(p: &Problem) -> f64 {
    match p.kinematics {
        Kinematics::Small => 1e-8,
        Kinematics::Finite => 1e-5,
    }
}

/// The problem's node count.
fn n_nodes(p: &Problem) -> usize {
    (p.lower[0] + 1) * (p.lower[1] + 1) + (p.upper[0] + 1) * (p.upper[1] + 1)
}

/// The properties of one problem: it converges, its zero increment converges at once to the
/// same tractions, and every `(name, variant, factor, tolerance)` gives the tractions times
/// `factor` to that tolerance of the peak.
fn variants_agree_with(
    p: &Problem,
    variants: Vec<(&str, Variant, f64, f64)>,
) -> std::result::Result<(), TestCaseError> {
    let base = run(p, &Variant::identity());
    // 0.7.0: every problem of this distribution settles (0.6.2 failed about 2.6% of the plane
    // ones alike in every variant: `hycon bench presses --ranges narrow`), so no problem fails
    // alike
    prop_assert!(base.is_ok(), "the problem fails: {base:?}");
    // the zero increment: at once, to the same tractions
    let at_once = 3;
    if let Ok((t, zero_iterations)) = &base {
        prop_assert!(
            *zero_iterations <= at_once,
            "zero increment took {zero_iterations} iterations"
        );
        prop_assert!(
            same(&t[1..2], &t[2..3], 1.0, tolerance(p)),
            "zero increment moved: {t:?}"
        );
    }
    for (name, variant, factor, within) in variants {
        let other = run(p, &variant);
        match (&base, &other) {
            (Ok((want, _)), Ok((got, _))) => prop_assert!(
                same(want, got, factor, within),
                "{name}: tractions differ\n{want:?}\n{got:?}"
            ),
            (Err(want), Err(got)) => prop_assert_eq!(want, got, "{}: different errors", name),
            _ => prop_assert!(false, "{name}: {base:?} against {other:?}"),
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 1024,
        rng_seed: RngSeed::Fixed(0x0068_7963_6f6e),
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    #[test]
    fn variants_agree(
        p in problem(),
        translation in (-1e3f64..1e3, -1e3f64..1e3),
        angle in -std::f64::consts::PI..std::f64::consts::PI,
        scales in (-3i32..=3, -3i32..=3),
        seed in any::<u64>(),
    ) {
        let within = tolerance(&p);
        let s_e = 10f64.powi(scales.1);
        // rotated, the flat surfaces carry the coordinates' round-off eps |X| across them:
        // relative to the approach, amplified by the contact system's condition (1e4 here)
        let rigid = within.max(
            1e4 * f64::EPSILON * (translation.0.hypot(translation.1) + 3.0) / (p.depth - p.gap),
        );
        let perm = permutation(n_nodes(&p), seed);
        variants_agree_with(&p, vec![
            ("translation", Variant { translation: [translation.0, translation.1], ..Variant::identity() }, 1.0, within),
            ("rigid motion", Variant { translation: [translation.0, translation.1], angle, ..Variant::identity() }, 1.0, rigid),
            ("unit scaling", Variant { length_scale: 10f64.powi(scales.0), modulus_scale: s_e, ..Variant::identity() }, s_e, within),
            ("renumbering", Variant { perm: Some(perm), ..Variant::identity() }, 1.0, within),
        ])?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 256,
        rng_seed: RngSeed::Fixed(0x0068_7963_6f70),
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    /// Axisymmetry: the rigid motions are the translations along the axis (a rotation or a
    /// radial translation changes the problem).
    #[test]
    fn axisymmetric_variants_agree(
        p in axisymmetric_problem(),
        dz in -1e3f64..1e3,
        scales in (-3i32..=3, -3i32..=3),
        seed in any::<u64>(),
    ) {
        let within = tolerance(&p);
        let s_e = 10f64.powi(scales.1);
        let perm = permutation(n_nodes(&p), seed);
        variants_agree_with(&p, vec![
            ("axial translation", Variant { translation: [0.0, dz], ..Variant::identity() }, 1.0, within),
            ("unit scaling", Variant { length_scale: 10f64.powi(scales.0), modulus_scale: s_e, ..Variant::identity() }, s_e, within),
            ("renumbering", Variant { perm: Some(perm), ..Variant::identity() }, 1.0, within),
        ])?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 256,
        rng_seed: RngSeed::Fixed(0x0068_7963_6f6f),
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    /// Load scaling: with touching surfaces and small kinematics the problem is positively
    /// homogeneous in the load, so pressing and sliding `s` times as far gives `s` times the
    /// tractions with the same contact states, for `s` from 1e-6 to 1e9 (every tolerance of
    /// the iteration is relative to the increment's own motion or tractions).
    #[test]
    fn load_scaling(p in problem(), k in -6i32..=9) {
        let p = Problem { gap: 0.0, kinematics: Kinematics::Small, ..p };
        let s = 10f64.powi(k);
        let scaled = Problem { depth: s * p.depth, slide: s * p.slide, ..p.clone() };
        let base = run(&p, &Variant::identity());
        let other = run(&scaled, &Variant::identity());
        match (&base, &other) {
            (Ok((want, _)), Ok((got, _))) => prop_assert!(
                same(want, got, s, 1e-8),
                "scaled by {s:e}: tractions differ\n{want:?}\n{got:?}"
            ),
            (Err(want), Err(got)) => prop_assert_eq!(want, got, "scaled by {}: different errors", s),
            _ => prop_assert!(false, "scaled by {s:e}: {base:?} against {other:?}"),
        }
    }
}

/// A press the random problems contain: a punch one element wide, with friction, whose corner
/// node alternates between stick and slip under the paper's rules (0.6.2 locked it in slip,
/// where it slid against its friction by a tenth of the press, and failed the increment). The
/// rules of 0.7.0 settle it on a state that satisfies the conditions: every node keeps the
/// friction law, the record's worst violation at convergence is within the limit.
#[test]
fn a_press_whose_corner_alternates_between_stick_and_slip_settles() {
    let p = Problem {
        lower: [3, 1],
        upper: [1, 3],
        left: 0.28927094453899016,
        width: 0.6911293449590747,
        gap: 0.00035757320991738163,
        depth: 0.0032542192812968535,
        slide: 0.0,
        moduli: [1.0, 0.0655974350362587],
        poisson: [0.3053780252713488, 0.31289662183799355],
        friction: 0.43148467224425613,
        kinematics: Kinematics::Small,
        analysis: Analysis::PlaneStrain,
        axis: 0.0,
    };
    let v = Variant::identity();
    let (mut analysis, top) = analysis(&p, &v).unwrap();
    let n = analysis.model().unwrap().mesh.n_nodes();
    analysis
        .increment(&vec![0.0; 2 * n], &totals(&p, &v, n, &top, 0.0))
        .unwrap();
    let last = analysis.records().last().unwrap();
    assert!(
        last.violation <= hycon::contact::iteration::CONDITION_LIMIT,
        "{last:?}"
    );
    let mu = p.friction;
    for node in analysis.node_results(0).unwrap() {
        match node.state {
            hycon::contact::iteration::NodeState::Stick => {
                assert!(node.ts.norm() <= mu * node.tn.abs() * (1.0 + 1e-9))
            }
            hycon::contact::iteration::NodeState::Slip { direction } => {
                assert!((node.ts.norm() - mu * node.tn.abs()).abs() <= 1e-12 * node.tn.abs());
                let ts = node.ts;
                assert!(direction.along(&ts) <= 0.0, "{node:?}");
            }
            other => panic!("{other:?}: the punch is pressed on its whole width"),
        }
    }
    let frictionless = Problem { friction: 0.0, ..p };
    assert!(run(&frictionless, &v).is_ok());
}

/// The problem of the two tests below: a contact zone centred on the axis (A and B both reach
/// it, their axis nodes' `u_r` held), pressed only (from `contact_randomized`, seed 1).
fn centred_on_the_axis(friction: f64, kinematics: Kinematics) -> Problem {
    Problem {
        lower: [2, 1],
        upper: [5, 1],
        left: 0.0,
        width: 0.746_464_875_206_702_7,
        gap: 0.0,
        depth: 0.000_162_388_535_141_600_78,
        slide: 0.0,
        moduli: [1.0, 0.207_693_558_828_456_33],
        poisson: [0.306_823_630_350_642_6, 0.229_542_983_743_742],
        friction,
        kinematics,
        analysis: Analysis::Axisymmetric,
        axis: 0.0,
    }
}

/// Friction on a contact zone centred on the axis: the shear traction vanishes on the axis
/// (`tau_rz(0) = 0`), so A's axis node closes frictionless (`ts = 0`) and the others keep the
/// friction law. 0.7.0 gave the axis node a stick row, which constrained the radial slip the
/// two `u_r = 0` already hold: the small system was singular (`Err(Singular)`; 27 of 171 such
/// rounds of `contact_randomized` at seed 1 with friction).
#[test]
fn friction_on_a_zone_centred_on_the_axis_converges() {
    let p = centred_on_the_axis(0.370_423_457_938_957_3, Kinematics::Small);
    let v = Variant::identity();
    let (mut analysis, top) = analysis(&p, &v).unwrap();
    let n = analysis.model().unwrap().mesh.n_nodes();
    analysis
        .increment(&vec![0.0; 2 * n], &totals(&p, &v, n, &top, 0.0))
        .unwrap();
    let nodes = analysis.node_results(0).unwrap();
    use hycon::contact::iteration::NodeState;
    assert_eq!(nodes[0].state, NodeState::Frictionless, "{:?}", nodes[0]);
    assert!(
        nodes[0].tn < 0.0 && nodes[0].ts.norm() == 0.0,
        "{:?}",
        nodes[0]
    );
    let stick = nodes.iter().filter(|n| n.state == NodeState::Stick).count();
    assert!(stick > 0, "{nodes:?}");
    for node in &nodes[1..] {
        assert!(
            node.ts.norm() <= p.friction * node.tn.abs() * (1.0 + 1e-9),
            "{node:?}"
        );
    }
}

/// A zone centred on the axis under finite kinematics (a one-element block pressed on a
/// three-element one, from `axisymmetric_variants_agree`): B's axis node projects onto A's
/// tilted axis segment a hair (`gap * tilt`) away from A's axis node, and B's end covers that
/// sliver, so the active axis node is fully covered. 0.7.0 failed the increment (`contact
/// Uncovered`: "contact node .. is active but .. of its support is not covered").
#[test]
fn finite_kinematics_on_a_zone_centred_on_the_axis_converges() {
    for friction in [0.0, 0.3] {
        let p = Problem {
            lower: [3, 1],
            upper: [1, 1],
            width: 0.954_609_835_728_871_7,
            depth: 0.006_575_080_249_640_766,
            moduli: [1.0, 1.0],
            poisson: [0.0, 0.0],
            ..centred_on_the_axis(friction, Kinematics::Finite)
        };
        let (t, _) = run(&p, &Variant::identity()).unwrap();
        assert!(t[0][0].0 < 0.0, "mu {friction}: {t:?}");
    }
}

/// Round 83973 of `contact_randomized 1000 1` (`mu = 0.40`, a slide 3,000 times shorter than
/// the approach): rotated by 0.6 rad its tractions changed by 1.8e-4 of their peak while the
/// slip tolerance was judged against the largest motion of one displacement component, which
/// a rotation changes; judged against the length of a node's motion, the rotated problem
/// gives the same tractions to round-off.
#[test]
fn a_rotation_changes_no_threshold() {
    let p = Problem {
        lower: [3, 2],
        upper: [3, 2],
        left: 0.7035429082441973,
        width: 0.5536196487150902,
        gap: 0.0008817288070726428,
        depth: 0.0010139359077763893,
        slide: -3.6129923317446577e-7,
        moduli: [1.0, 1.8293016733337304],
        poisson: [0.15431988254100176, 0.34986998638479655],
        friction: 0.40022083148886256,
        kinematics: Kinematics::Small,
        analysis: Analysis::PlaneStrain,
        axis: 0.0,
    };
    let base = run(&p, &Variant::identity()).unwrap();
    for angle in [-0.597264, 0.3, 1.5] {
        let rotated = Variant {
            angle,
            ..Variant::identity()
        };
        let got = run(&p, &rotated).unwrap();
        assert!(same(&base.0, &got.0, 1.0, 1e-10), "rotated by {angle} rad");
    }
}

/// The 3D analysis (`ContactAnalysis::solid`) on random presses of a turned block on a flat
/// ([`press3d`](crate::common::press3d)): random meshes of either brick, turn, block size, gap,
/// press, slide in both directions, moduli, Poisson's ratios and friction, under small
/// kinematics (32 cases). Every press converges, and a rigid motion (a random rotation and a
/// translation up to 1e2), unit scaling and renumbering (with the bricks and faces listed in
/// another order, each face from another corner) give its results, mapped back: the tractions
/// (as vectors), forces, weights, normals and every node's displacement, and with them the
/// tangents where the variant keeps the reference axis; to 1e-8 of each quantity's scale or
/// ten times the change that moving every coordinate by `4 eps |X|` makes (`|X|` the size of
/// the variant's coordinates), whichever is larger: a measure of the press's own condition.
/// Near the stick-slip boundary a slip node's direction is that of a nearly vanishing
/// 2-vector, which amplifies round-off far beyond the plane's `1e4 eps |X| / approach` (a
/// press with two such nodes changed by 7e-8 of its tractions when moved by 13, and by 3e-8
/// with its coordinates moved by `2 eps |X|` at random). A press that round-off changes by
/// more than 1e-5 fails the test (its states would flip: an ill-posed press).
mod solid {
    use crate::common::permutation;
    use crate::common::press3d::{Press, Variant, difference, run};
    use hycon::contact::iteration::ContactOptions;
    use hycon::solid::BrickFormulation;
    use hycon::solid::contact_meshes::BlockOnFlat;
    use nalgebra::Rotation3;
    use proptest::prelude::*;
    use proptest::test_runner::RngSeed;

    /// A block of `1..=3 x 1..=3` bricks, `0.4..1` wide and `0.3..1` high, turned `0..90`
    /// degrees, `0..1e-3` above a flat of `1.6 x 1.6 x 0.5` in `1..=4 x 1..=4` bricks (it covers
    /// the turned block), pressed by the gap and `1e-4..1e-2` more, then slid by up to a fifth
    /// of that along `x` and `y`.
    fn press() -> impl Strategy<Value = Press> {
        (
            (1usize..=3, 1usize..=3, 1usize..=4, 1usize..=4),
            (0.0f64..90.0, 0.4f64..1.0, 0.4f64..1.0, 0.3f64..1.0),
            (0.0f64..1e-3, 1e-4f64..1e-2, -0.2f64..0.2, -0.2f64..0.2),
            (-2.0f64..2.0, -0.2f64..0.45, -0.2f64..0.45),
            (prop_oneof![Just(0.0), 0.05f64..0.6], any::<bool>()),
        )
            .prop_map(
                |(
                    (ax, ay, bx, by),
                    (angle, lx, ly, lz),
                    (gap, depth, sx, sy),
                    (log_ratio, nu0, nu1),
                    (friction, hybrid),
                )| {
                    let press = gap + depth;
                    Press {
                        meshes: BlockOnFlat {
                            size: [lx, ly, lz],
                            cells: [ax, ay, 1],
                            flat: [1.6, 1.6, 0.5],
                            flat_cells: [bx, by, 1],
                            angle,
                        },
                        gap,
                        moduli: [1.0, 10f64.powf(log_ratio)],
                        poisson: [nu0, nu1],
                        friction,
                        formulation: if hybrid {
                            BrickFormulation::Hybrid18
                        } else {
                            BrickFormulation::H8
                        },
                        steps: vec![[0.0, 0.0, -press], [sx * depth, sy * depth, -press]],
                    }
                },
            )
    }

    proptest! {
        #![proptest_config(ProptestConfig {
            cases: 32,
            rng_seed: RngSeed::Fixed(0x0068_7963_6f33),
            failure_persistence: None,
            ..ProptestConfig::default()
        })]

        #[test]
        fn variants_agree_in_3d(
            p in press(),
            angles in (-3.1f64..3.1, -1.5f64..1.5, -3.1f64..3.1),
            translation in (-1e2f64..1e2, -1e2f64..1e2, -1e2f64..1e2),
            scales in (-3i32..=3, -3i32..=3),
            seed in any::<u64>(),
        ) {
            let options = ContactOptions::default;
            let base = run(&p, &Variant::identity(), options());
            prop_assert!(base.is_ok(), "the press fails: {base:?}");
            let base = base.unwrap();
            let t = [translation.0, translation.1, translation.2];
            // round-off: what moving every coordinate by 4 eps |X| does to this press (ten times
            // it), |X| its coordinates' size, or 1e-8 of each quantity's scale
            let round_off = |size: f64| -> std::result::Result<f64, TestCaseError> {
                let noise = Variant { noise: 4.0 * f64::EPSILON * size, ..Variant::identity() };
                let got = run(&p, &noise, options());
                prop_assert!(got.is_ok(), "coordinates moved by round-off: {got:?}");
                let d = difference(&base, &got.unwrap(), false);
                // (a press that round-off changes by more is ill-posed: its states flip)
                prop_assert!(d <= 1e-5, "coordinates moved by round-off: relative change {d:e}");
                Ok(1e-8f64.max(10.0 * d))
            };
            let within = round_off(3.0)?;
            let rigid = round_off(t.iter().map(|v| v * v).sum::<f64>().sqrt() + 3.0)?;
            let n = p.meshes.build().unwrap().mesh.n_nodes();
            let variants = [
                ("rigid motion", Variant {
                    rotation: Rotation3::from_euler_angles(angles.0, angles.1, angles.2),
                    translation: t,
                    ..Variant::identity()
                }, false, rigid),
                ("unit scaling", Variant {
                    length_scale: 10f64.powi(scales.0),
                    modulus_scale: 10f64.powi(scales.1),
                    ..Variant::identity()
                }, true, within),
                ("renumbering", Variant {
                    perm: Some(permutation(n, seed)),
                    ..Variant::identity()
                }, true, within),
            ];
            for (what, v, tangents, tolerance) in variants {
                let got = run(&p, &v, options());
                prop_assert!(got.is_ok(), "{what}: {got:?}");
                let d = difference(&base, &got.unwrap(), tangents);
                prop_assert!(d <= tolerance, "{what}: relative difference {d:e}");
            }
        }
    }
}
