//! Robustness of the contact-set iteration where the plain rules of the paper alternate.
//!
//! Pressing a disk with friction at 64 elements per half-width puts a node at each contact edge
//! right on the friction cone: as stick it violates `|ts| <= mu |tn|`, as slip its slip
//! reverses, and the plain rules cycle. The iteration locks such a node in slip (on the cone,
//! with a vanishing slip) and converges; the friction law holds at every node.

use hycon::contact::iteration::{ContactOptions, NodeState};
use hycon::contact::scene::DiskOnBlock;

#[test]
fn frictional_pressing_on_a_fine_mesh_converges() {
    let mu = 0.3;
    let scene = DiskOnBlock {
        elements_per_half_width: 64,
        friction: mu,
        ..Default::default()
    }
    .build()
    .unwrap();
    let mut analysis = scene.analysis(ContactOptions::default()).unwrap();
    let approach = scene.calibrated_approach(&mut analysis).unwrap();
    let f = vec![0.0; 2 * scene.model.mesh.n_nodes()];
    let info = analysis
        .increment(&f, &scene.prescribed(approach, 0.0))
        .unwrap();
    println!("{info:?}");
    let nodes = analysis.node_results(0).unwrap();
    let tn_max = nodes.iter().map(|n| n.tn.abs()).fold(0.0, f64::max);
    for n in &nodes {
        match n.state {
            NodeState::Slip { .. } => {
                assert!(
                    (n.ts.abs() - mu * n.tn.abs()).abs() <= 1e-12 * tn_max,
                    "{n:?}"
                )
            }
            NodeState::Stick => assert!(n.ts.abs() <= mu * n.tn.abs() * (1.0 + 1e-9), "{n:?}"),
            NodeState::Open => assert_eq!((n.tn, n.ts), (0.0, 0.0)),
        }
    }
    // pressing identical bodies: almost everything sticks, and Hertz holds
    assert!(info.slip <= 4 && info.active > 120, "{info:?}");
    let c = scene.compare(&analysis).unwrap();
    assert!((c.peak / c.hertz.peak - 1.0).abs() < 0.01, "{c:?}");
}
