//! The local frictional contact problem (`hycon::contact::local`): its checks, its
//! natural-map residual and the semi-smooth Newton solve, on problems with known solutions.

use hycon::contact::local::LocalProblem;
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
