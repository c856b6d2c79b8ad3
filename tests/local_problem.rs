//! The local frictional contact problem (`hycon::contact::local`): its checks, its
//! natural-map residual and the semi-smooth Newton solve, on problems with known solutions.

use crate::common::block_on_flat_model;
use crate::common::turned_block_on_flat;
use hycon::contact::iteration::{ContactAnalysis, ContactOptions, FacePair, PlateControl};
use hycon::contact::local::LocalProblem;
use hycon::solid::contact_meshes::ContactMesh;
use nalgebra::DMatrix;

/// One contact, `W = I`, pressed (`q_N = -1`) and sheared beyond the cone (`|q_T| = 0.5 >
/// mu = 0.3`): it slips, `r = (1, -0.3, 0)` (the reaction on the cone, against the slip),
/// `u = (0, 0.2, 0)`.
#[test]
fn a_slipping_contact_under_the_identity_has_its_closed_form() {
    let problem =
        LocalProblem::new(3, DMatrix::identity(3, 3), vec![-1.0, 0.5, 0.0], vec![0.3]).unwrap();
    let solve = problem.solve_newton();
    assert!(solve.settled);
    let expected = [1.0, -0.3, 0.0];
    for (a, b) in solve.r.iter().zip(expected) {
        assert!((a - b).abs() < 1e-14, "{:?}", solve.r);
    }
    let expected_u = [0.0, 0.2, 0.0];
    for (a, b) in solve.u.iter().zip(expected_u) {
        assert!((a - b).abs() < 1e-14, "{:?}", solve.u);
    }
    assert!(solve.residual < 1e-15);
    // the paper's rules: open, then stick (beyond the cone), then slip, which repeats
    let rules = problem.solve_rules();
    assert!(rules.settled);
    assert_eq!((rules.iterations, rules.sweeps), (3, 0));
    for (a, b) in rules.r.iter().zip(expected) {
        assert!((a - b).abs() < 1e-14, "{:?}", rules.r);
    }
    // a point that is not the solution has a residual: the sticking guess r = -q
    assert!(problem.natural_map_residual(&[1.0, -0.5, 0.0]) > 0.1);
}

/// Bad input is refused with a message naming what is wrong.
#[test]
fn bad_local_problems_are_refused() {
    let w = DMatrix::identity(3, 3);
    let error = |dim, w: DMatrix<f64>, q: Vec<f64>, mu: Vec<f64>| {
        LocalProblem::new(dim, w, q, mu).unwrap_err().to_string()
    };
    assert!(error(4, w.clone(), vec![0.0; 3], vec![0.3]).contains("2 or 3"));
    assert!(error(3, w.clone(), vec![0.0; 2], vec![0.3]).contains("need 3"));
    assert!(error(3, w.clone(), vec![0.0; 3], vec![-0.1]).contains("mu of contact 0"));
    assert!(error(3, w.clone(), vec![f64::NAN, 0.0, 0.0], vec![0.3]).contains("not finite"));
    let mut skew = w.clone();
    skew[(0, 1)] = 0.5;
    assert!(error(3, skew, vec![0.0; 3], vec![0.3]).contains("not symmetric"));
}

/// A frictionless contact (`mu = 0`) beside a frictional one, `W = I`, both pressed
/// (`q_N = -1`), the frictionless one with a zero tangential free term (a zero trial traction,
/// whose direction is undefined) and the other sheared beyond its cone: both solvers give
/// `r = (1, 0, 0)` and `(1, -0.3, 0)`, finite.
#[test]
fn a_frictionless_contact_has_no_tangential_reaction() {
    let q = vec![-1.0, 0.0, 0.0, -1.0, 0.5, 0.0];
    let problem = LocalProblem::new(3, DMatrix::identity(6, 6), q, vec![0.0, 0.3]).unwrap();
    let expected = [1.0, 0.0, 0.0, 1.0, -0.3, 0.0];
    for solve in [problem.solve_newton(), problem.solve_rules()] {
        assert!(solve.settled);
        for (a, b) in solve.r.iter().zip(expected) {
            assert!((a - b).abs() < 1e-14, "{:?}", solve.r);
        }
    }
}

/// The turned block on the flat (`E = 1`, `nu = 0.3`, the flat's bottom held), its top
/// prescribed in every direction (or, with a plate, tied to it).
fn block_on_flat(c: &ContactMesh, friction: f64, plate: bool) -> ContactAnalysis {
    let model = block_on_flat_model(c, &[0, 1, 2]);
    let pairs = vec![FacePair {
        a: c.a_faces.clone(),
        b: c.b_faces.clone(),
        friction,
    }];
    let options = ContactOptions::default();
    if plate {
        ContactAnalysis::solid_with_plate(model, pairs, &[], options, c.a_top.clone()).unwrap()
    } else {
        ContactAnalysis::solid(model, pairs, &[], options).unwrap()
    }
}

/// The block pressed by `1e-3` and sheared by `shear` along `x`: the prescribed values.
fn pressed(c: &ContactMesh, shear: f64) -> Vec<f64> {
    let mut qp = vec![0.0; 3 * c.mesh.n_nodes()];
    for &k in &c.a_top {
        qp[3 * k] = shear;
        qp[3 * k + 2] = -1e-3;
    }
    qp
}

/// A converged 3D increment exports its local problem: one contact per A node in or near
/// contact with three components, `mu` the pair's, the converged reactions those of the
/// node results with the normal's sign turned, solving the problem to round-off (small
/// kinematics: the conditions are linear in the reactions), and the semi-smooth Newton method
/// finds them again (and the paper's rules, without friction). Frictionless, the contacts keep their tangential rows with `mu = 0`. Before the
/// first increment, and after a failed one, the export is refused.
#[test]
fn a_converged_increment_exports_its_local_problem() {
    let c = turned_block_on_flat();
    for (friction, shear) in [(0.3, 2e-4), (0.0, 0.0)] {
        let mut analysis = block_on_flat(&c, friction, false);
        let refused = analysis.local_problem().unwrap_err().to_string();
        assert!(refused.contains("no increment has converged"), "{refused}");
        let zero = vec![0.0; 3 * c.mesh.n_nodes()];
        analysis.increment(&zero, &pressed(&c, shear)).unwrap();
        let export = analysis.local_problem().unwrap();
        let problem = &export.problem;
        assert_eq!(problem.dim(), 3);
        assert_eq!(export.contacts.len(), problem.contacts());
        assert!(problem.mu().iter().all(|&mu| mu == friction));
        let nodes = analysis.node_results(0).unwrap();
        let largest = export.solution.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(largest > 0.0);
        for (i, contact) in export.contacts.iter().enumerate() {
            let node = &nodes[contact.node];
            assert_eq!(node.node, contact.id);
            assert_eq!(export.solution[3 * i], -node.tn);
            assert_eq!(&export.solution[3 * i + 1..3 * i + 3], node.ts.components());
        }
        // every closed node is a contact
        let closed = nodes.iter().filter(|n| n.tn < 0.0).count();
        let contacts_closed = (0..problem.contacts())
            .filter(|&i| export.solution[3 * i] > 0.0)
            .count();
        assert_eq!(closed, contacts_closed);
        assert!(export.residual < 1e-12, "{:e}", export.residual);
        println!(
            "mu {friction}: {} contacts, residual {:.1e}",
            problem.contacts(),
            export.residual
        );
        // the paper's rules follow the slip directions, a fixed point that need not settle
        // where contacts slip on a face (docs/method.md, "The local problem"): here only the
        // frictionless press
        let rules = problem.solve_rules();
        println!(
            "  rules: settled {}, {} iterations, residual {:.1e}",
            rules.settled, rules.iterations, rules.residual
        );
        let solves = if friction == 0.0 {
            vec![problem.solve_newton(), rules]
        } else {
            vec![problem.solve_newton()]
        };
        for solve in solves {
            assert!(solve.settled);
            for (a, b) in solve.r.iter().zip(&export.solution) {
                assert!((a - b).abs() < 1e-9 * largest, "{a} against {b}");
            }
        }
        // a failed increment: the monitor stops it
        analysis.set_monitor(Some(Box::new(|_| false)));
        assert!(
            analysis
                .increment(&zero, &pressed(&c, 2.0 * shear))
                .is_err()
        );
        let refused = analysis.local_problem().unwrap_err().to_string();
        assert!(refused.contains("the last increment failed"), "{refused}");
    }
}

/// Under a force-controlled plate that holds the block alone (the block floats but for the
/// plate and the contact), the plate's balance is a constraint on the reactions: refused.
#[test]
fn a_floating_body_under_a_force_controlled_plate_is_refused() {
    let c = turned_block_on_flat();
    let mut analysis = block_on_flat(&c, 0.3, true);
    let zero = vec![0.0; 3 * c.mesh.n_nodes()];
    let held = PlateControl::Displacement(0.0);
    let control = [held, held, PlateControl::Force(-1e-3)];
    analysis
        .increment_with_plate(&zero, &zero, &control)
        .unwrap();
    let refused = analysis.local_problem().unwrap_err().to_string();
    assert!(refused.contains("floating body"), "{refused}");
}

/// The cone of `mu = 0` is the half-line `r_T = 0, r_N >= 0`: an open frictionless contact at
/// `r = 0` (`u = q = (1, 0, 0)`) solves its problem, `r - P_K(r - û) = -P_K((-1, 0, 0)) = 0`.
#[test]
fn an_open_frictionless_contact_has_no_residual() {
    let problem =
        LocalProblem::new(3, DMatrix::identity(3, 3), vec![1.0, 0.0, 0.0], vec![0.0]).unwrap();
    assert_eq!(problem.natural_map_residual(&[0.0; 3]), 0.0);
    // and a reaction that pulls is not a solution
    assert!(problem.natural_map_residual(&[-0.5, 0.0, 0.0]) > 0.1);
}
