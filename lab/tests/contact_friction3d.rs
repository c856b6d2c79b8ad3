//! Coulomb friction in 3D: the half model of the paraboloid cap on the block
//! (`solid::contact_meshes::CapOnBlock`, `a/h = 4`, `R / a = 16`, `E = 1`, `nu = 0.3` both,
//! 18-beta hybrid bricks, `mu = 0.3`), pressed by Hertz's approach `a^2 / R` of the target
//! radius `a`, then its top moved along `x` by Mindlin's tangential displacement for
//! `Q = mu P / 2` (`closed3d::Mindlin::compliance_displacement`), the block's bottom held and
//! the nodes on the symmetry plane `y = 0` held along `y`; small kinematics.
//!
//! What is checked is the friction law on a face with two tangents, node by node, through the
//! whole iteration: both increments converge; every slip node is on the circular cone
//! (`|ts| = mu |tn|`) with its traction opposing its slip direction, every stick node inside
//! it; in the tangential increment every slip node slides along `+x` (with the cap's top) and
//! the tangential load `Q` lies between 0 and `mu P`; a node on the symmetry plane carries no
//! traction across it.
//!
//! Not yet checked against Cattaneo-Mindlin's stick radius, because this model is not
//! Mindlin's (measured with `cargo test -p hycon-lab --test lab contact_friction3d:: --
//! --nocapture`): already the normal increment slips at 4 of the 26 active A nodes (28 of 107
//! at `a/h = 8`), the bodies being finite and unlike (a cap `8 a` high on a block `16 a`
//! deep: their surfaces' radial displacements under the pressure differ, which Mindlin's
//! identical half-spaces exclude), and the tangential increment then slips more on the
//! trailing side than on the leading one (at `a/h = 8`, 25 and 17 slip nodes), where
//! Mindlin's annulus is symmetric. `Q / (mu P)` reaches 0.457 (0.447 at `a/h = 8`) for the
//! displacement that gives 0.5 on half-spaces.
//! The comparison with Mindlin is `contact_mindlin3d`'s: on mirror bodies (the block as big as
//! the cap) the press still slips at the same 4 nodes, the cap's curvature `R / a = 16` (its
//! tilted normal) moving its surface inward relative to the block's; at `R / a = 256`, with the
//! multipliers on the flat block, it slips nowhere (`hycon_lab::mindlin3d`'s docs).

use hycon::contact::iteration::{ContactAnalysis, ContactOptions, FacePair, NodeState};
use hycon::solid::contact_meshes::{CapModel, CapOnBlock};
use hycon::solid::model::SolidModel;
use hycon::solid::{BrickFormulation, Isotropic};
use hycon_lab::closed3d::{Mindlin, hertz_approach};

const MU: f64 = 0.3;

/// The friction law at every node of pair 0, and (`sliding`) every slip node's slip along
/// `+x`; returns the full model's normal and tangential (`x`) loads.
fn check_nodes(analysis: &ContactAnalysis, on_plane: &[usize], sliding: bool) -> (f64, f64) {
    let nodes = analysis.node_results(0).unwrap();
    let tn_max = nodes.iter().fold(0.0f64, |m, r| m.max(r.tn.abs()));
    for r in &nodes {
        let limit = MU * r.tn.abs();
        match r.state {
            NodeState::Slip { direction } => {
                let along = direction.vector().scaled(MU * r.tn);
                let misfit = (0..2)
                    .map(|i| (r.ts.components()[i] - along.components()[i]).abs())
                    .fold(0.0, f64::max);
                assert!(misfit <= 1e-12 * tn_max, "{r:?}");
                assert!((r.ts.norm() - limit).abs() <= 1e-12 * tn_max, "{r:?}");
                let slip = r.frame.vector(0.0, direction.vector());
                assert!(!sliding || slip.components()[0] > 0.0, "{r:?}");
            }
            NodeState::Stick => assert!(r.ts.norm() <= limit * (1.0 + 1e-9), "{r:?}"),
            NodeState::Open => assert_eq!(r.tn, 0.0),
            NodeState::Frictionless => panic!("a frictional pair: {r:?}"),
        }
        if on_plane.contains(&r.node) {
            let t = r.frame.vector(0.0, r.ts);
            assert!(t.components()[1].abs() <= 1e-12 * tn_max, "{r:?}");
        }
    }
    let total = |c: usize| 2.0 * nodes.iter().map(|r| r.force.components()[c]).sum::<f64>();
    (total(2), -total(0))
}

#[test]
fn a_cap_pressed_then_pulled_keeps_the_circular_cone() {
    let spec = CapOnBlock::new(CapModel::Half, 4);
    let mesh = spec.build().unwrap();
    let material = Isotropic::new(1.0, 0.3).unwrap();
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
    let (plane, on_plane) = &mesh.symmetry[0];
    assert_eq!(plane.normal, [0.0, 1.0, 0.0]);
    for &n in on_plane {
        model.fix(n, 1, 0.0);
    }
    // moved by the increments' prescribed values
    for &n in &mesh.a_top {
        model.fix(n, 0, 0.0);
        model.fix(n, 2, 0.0);
    }
    let pair = FacePair {
        a: mesh.a_faces.clone(),
        b: mesh.b_faces.clone(),
        friction: MU,
    };
    let mut analysis =
        ContactAnalysis::solid(model, vec![pair], &[*plane], ContactOptions::default()).unwrap();
    let n = 3 * mesh.mesh.n_nodes();
    let f = vec![0.0; n];
    let mut qp = vec![0.0; n];
    for &k in &mesh.a_top {
        qp[3 * k + 2] = -hertz_approach(spec.contact_radius(), 1.0);
    }
    let normal = analysis.increment(&f, &qp).unwrap();
    let (p, _) = check_nodes(&analysis, on_plane, false);
    let e_star = 1.0 / (2.0 * (1.0 - 0.09));
    let g = 1.0 / 2.6;
    let half = Mindlin::new(p, 1.0, e_star, MU, 0.5 * MU * p).unwrap();
    for &k in &mesh.a_top {
        qp[3 * k] = half.compliance_displacement([g, g], [0.3, 0.3]);
    }
    let pulled = analysis.increment(&f, &qp).unwrap();
    let (p, q) = check_nodes(&analysis, on_plane, true);
    let stuck = Mindlin::new(p, 1.0, e_star, MU, q).unwrap();
    println!(
        "normal: {normal:?}\npulled: {pulled:?}\nP = {p:.5e}, Q / (mu P) = {:.4}, Mindlin's \
         c/a at that Q {:.4}",
        q / (MU * p),
        stuck.stick / stuck.hertz.radius
    );
    assert!(q > 0.0 && q < MU * p, "{q} {p}");
    assert!(
        pulled.slip > normal.slip && pulled.slip < pulled.active,
        "{pulled:?}"
    );
}
