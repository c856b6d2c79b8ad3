//! Hertz's sphere in 3D: the first 3D contact analysis end to end (issue #43). The quarter model
//! of a paraboloid cap `z = r^2 / (2 R)` (`R = 1`) on a block (`solid::contact_meshes::
//! CapOnBlock`: `R / a = 16`, faces of size `h = a / (a/h)` out to `1.5 a`, graded beyond, cap
//! `8 a` high, block `16 a` deep), both of `E = 1`, `nu = 0.3`, 18-beta hybrid bricks; the
//! block's bottom held, the nodes on the symmetry planes `x = 0` and `y = 0` held normal to
//! them, the cap's top moved down by Hertz's approach `delta = a^2 / R` of the target radius
//! `a`; frictionless, small kinematics, one increment.
//!
//! Compared with `hycon_lab::closed3d`: the contact radius and the peak pressure against Hertz
//! at the computed load `P` (as the axisymmetric sphere is, `hycon_lab::axisymmetric`), and `P`
//! against Hertz's load `hertz_load(a)` of the prescribed approach. The radius comes from the
//! moments of the contact forces, `sum f_k r_k^2 / sum f_k = 2 a^2 / 5` for Hertz's pressure;
//! the peak is the multiplier at the centre node.
//!
//! Measured (`cargo test -p hycon-lab --test lab contact_hertz3d:: -- --nocapture
//! --include-ignored`), relative to Hertz:
//!
//! | a/h | radius at `P` | `p0` at `P` | `max |p - p_H| / p0`, `r <= a/2` | `P / hertz_load(a) - 1` | active A nodes | iterations |
//! |---|---|---|---|---|---|---|
//! | 4 | +1.52% | +0.59% | 4.3% | +5.79% | 15 | 6 |
//! | 8 | +0.18% | +0.50% | 0.69% | +6.53% | 58 | 6 |
//!
//! The radius and the pressure converge; the load of the approach does not go to Hertz's: the
//! bodies are finite (the block held at depth `16 a`, the cap's top moved rigidly `8 a` above
//! the contact), which removes the half-space's displacement beyond them and stiffens the
//! contact. Boussinesq's displacement on the axis at depth `z`, `P (3 - 2 nu) / (4 pi G z)`, is
//! `0.73 a / z` of one body's Hertz approach `a^2 / (2 R)` here: some 5% of the block's and
//! 9% of the cap's, so `P`, which goes with the approach to the power 3/2, is some 10% above
//! Hertz's: the sign and the size of what is measured, and the same at both refinements.

use hycon::contact::iteration::{ContactAnalysis, ContactOptions, FacePair, NodeResult};
use hycon::contact::space::Vector;
use hycon::solid::contact_meshes::{CapModel, CapOnBlock, ContactMesh};
use hycon::solid::model::SolidModel;
use hycon::solid::{BrickFormulation, Isotropic};
use hycon_lab::closed3d::{HertzSphere, hertz_approach, hertz_load};

/// Young's modulus and Poisson's ratio of both bodies.
const YOUNGS: f64 = 1.0;
const POISSON: f64 = 0.3;

/// `E* = 1 / ((1 - nu1^2) / E1 + (1 - nu2^2) / E2)`.
fn e_star() -> f64 {
    YOUNGS / (2.0 * (1.0 - POISSON * POISSON))
}

/// One pressed cap against Hertz.
#[derive(Debug)]
struct Pressed {
    /// The total load `P` of the full model (4 times the quarter's contact force).
    load: f64,
    /// Hertz's load of the prescribed approach, `hertz_load(a)`.
    hertz_load: f64,
    /// Hertz at `load`.
    hertz: HertzSphere,
    /// The contact radius from the moments of the contact forces.
    radius: f64,
    /// The peak pressure: `-tn` at the centre node.
    peak: f64,
    /// The largest `|p_k - p(r_k)| / p0` over the A nodes within `a / 2` of the centre
    /// (`p_k = -tn_k`, `p` Hertz's at `load`).
    interior: f64,
    /// Active nodes and iterations of the increment.
    active: usize,
    iterations: usize,
}

/// The quarter cap at `a_over_h`, its analysis built (see the module docs).
fn quarter(a_over_h: usize) -> (CapOnBlock, ContactMesh, ContactAnalysis) {
    let spec = CapOnBlock::new(CapModel::Quarter, a_over_h);
    let mesh = spec.build().unwrap();
    let material = Isotropic::new(YOUNGS, POISSON).unwrap();
    let mut model = SolidModel::new(
        mesh.mesh.clone(),
        vec![material, material],
        BrickFormulation::Hybrid18,
    )
    .unwrap();
    for &n in &mesh.b_bottom {
        for d in 0..3 {
            model.fix(n, d, 0.0);
        }
    }
    for (plane, nodes) in &mesh.symmetry {
        let d = (plane.normal.iter()).position(|&v| v != 0.0).unwrap();
        for &n in nodes {
            model.fix(n, d, 0.0);
        }
    }
    // moved by the increment's prescribed values (`press`)
    for &n in &mesh.a_top {
        model.fix(n, 2, 0.0);
    }
    let pair = FacePair {
        a: mesh.a_faces.clone(),
        b: mesh.b_faces.clone(),
        friction: 0.0,
    };
    let planes: Vec<_> = mesh.symmetry.iter().map(|(p, _)| *p).collect();
    let analysis =
        ContactAnalysis::solid(model, vec![pair], &planes, ContactOptions::default()).unwrap();
    (spec, mesh, analysis)
}

/// Press the quarter cap at `a_over_h` by Hertz's approach and compare.
fn press(a_over_h: usize) -> Pressed {
    let (spec, mesh, mut analysis) = quarter(a_over_h);
    let n = 3 * mesh.mesh.n_nodes();
    let mut qp = vec![0.0; n];
    for &node in &mesh.a_top {
        qp[3 * node + 2] = -hertz_approach(spec.contact_radius(), 1.0);
    }
    let info = analysis.increment(&vec![0.0; n], &qp).unwrap();
    let nodes = analysis.node_results(0).unwrap();
    let radial = |r: &NodeResult| {
        let [x, y, _] = mesh.mesh.nodes[r.node];
        x.hypot(y)
    };
    let force = |r: &NodeResult| -r.frame.normal().dot(&r.force);
    let quarter_load: f64 = nodes.iter().map(force).sum();
    let moment: f64 = nodes.iter().map(|r| force(r) * radial(r).powi(2)).sum();
    // B takes what A takes: the B nodes' forces balance the A nodes' (the patch-test
    // condition `sum_b M_kb = sum_j D_kj` of every covered node)
    let total = |forces: &mut dyn Iterator<Item = Vector>| {
        forces.fold([0.0; 3], |s, f| {
            std::array::from_fn(|i| s[i] + f.components()[i])
        })
    };
    let on_a = total(&mut nodes.iter().map(|r| r.force));
    let on_b = total(
        &mut analysis
            .b_node_results(0)
            .unwrap()
            .into_iter()
            .map(|r| r.force),
    );
    for i in 0..3 {
        assert!(
            (on_a[i] + on_b[i]).abs() < 1e-12 * quarter_load,
            "{on_a:?} {on_b:?}"
        );
    }
    let load = 4.0 * quarter_load;
    let hertz = HertzSphere::new(load, 1.0, e_star());
    let centre = (nodes.iter()).find(|r| radial(r) == 0.0).unwrap();
    let interior = (nodes.iter())
        .filter(|r| radial(r) <= 0.5 * hertz.radius)
        .map(|r| (-r.tn - hertz.pressure(radial(r))).abs() / hertz.peak)
        .fold(0.0, f64::max);
    Pressed {
        load,
        hertz_load: hertz_load(spec.contact_radius(), 1.0, e_star()),
        hertz,
        radius: (2.5 * moment / quarter_load).sqrt(),
        peak: -centre.tn,
        interior,
        active: info.active,
        iterations: info.iterations,
    }
}

/// The relative errors of `p`: radius and peak against Hertz at its load, load against
/// Hertz's of the approach; printed.
fn errors(a_over_h: usize, p: &Pressed) -> [f64; 3] {
    let e = [
        p.radius / p.hertz.radius - 1.0,
        p.peak / p.hertz.peak - 1.0,
        p.load / p.hertz_load - 1.0,
    ];
    println!(
        "a/h = {a_over_h}: P = {:.6e} (Hertz {:.6e} at the approach, {:+.4}), a = {:.6e} \
         (Hertz {:.6e} at P, {:+.4}), p0 = {:.6e} (Hertz {:.6e}, {:+.4}), |p - p_H| / p0 \
         within a/2 {:.4}, {} active A nodes, {} iterations",
        p.load,
        p.hertz_load,
        e[2],
        p.radius,
        p.hertz.radius,
        e[0],
        p.peak,
        p.hertz.peak,
        e[1],
        p.interior,
        p.active,
        p.iterations
    );
    e
}

/// At `a/h = 4` (a few seconds): the radius within 3% and the peak within 2% of Hertz at the
/// computed load (measured +1.5% and +0.6%), the pressure within `a / 2` within 6% of `p0`
/// node by node (measured 4.3%), and the load above Hertz's for the approach by less than the
/// finite bodies' 10% (module docs; measured +5.8%). A missing symmetry factor (the quarter's
/// load taken as the whole: Hertz's radius 37% smaller), a wrong weight or normal breaks them.
#[test]
fn the_quarter_cap_matches_hertz() {
    let p = press(4);
    let [radius, peak, load] = errors(4, &p);
    assert!(radius.abs() < 0.03, "{p:?}");
    assert!(peak.abs() < 0.02, "{p:?}");
    assert!(load > 0.0 && load < 0.10, "{p:?}");
    assert!(p.interior < 0.06, "{p:?}");
    assert!(p.iterations <= 10, "{p:?}");
}

/// Refined to `a/h = 8` the radius, the peak and the pressure within `a / 2` come nearer to
/// Hertz, and the load of the approach stays within 1% of the coarse one (it is the finite
/// bodies', not the mesh's; module docs). Ignored: 10 s in the test profile; run with
/// `--include-ignored`.
#[test]
#[ignore = "10 s in the test profile"]
fn the_quarter_cap_converges_to_hertz() {
    let (coarse, fine) = (press(4), press(8));
    let [c, f] = [(4, &coarse), (8, &fine)].map(|(n, p)| errors(n, p));
    let pair = format!("a/h 4: {coarse:?}, a/h 8: {fine:?}");
    assert!(f[0].abs() < c[0].abs() && f[1].abs() < c[1].abs(), "{pair}");
    assert!(fine.interior < coarse.interior, "{pair}");
    assert!((fine.load / coarse.load - 1.0).abs() < 0.01, "{pair}");
}
