//! The problem sets of `hycon_lab::local_problems`: each class's exported reactions solve
//! their problem (natural-map residual), and hycon's solvers find them again.

use hycon_lab::local_problems::{self, NamedProblem};

/// The largest `|a - b|` relative to the largest `|b|`.
fn difference(a: &[f64], b: &[f64]) -> f64 {
    let largest = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        / largest
}

/// Print and check one problem: its exported solution's residual below `residual`, the Newton
/// solve settling on it to `agree` of the largest reaction.
fn check(p: &NamedProblem, residual: f64, agree: f64) {
    let newton = p.problem.solve_newton();
    let exported = p
        .solution
        .as_ref()
        .map(|s| p.problem.natural_map_residual(s));
    let against = p.solution.as_ref().map(|s| difference(&newton.r, s));
    println!(
        "{}/{}: {} contacts, exported residual {:?}, newton settled {} residual {:.2e}, \
         against the export {:?}",
        p.class,
        p.name,
        p.problem.contacts(),
        exported,
        newton.settled,
        newton.residual,
        against
    );
    assert!(newton.settled && newton.residual < 1e-12, "{}", p.name);
    if let (Some(e), Some(a)) = (exported, against) {
        assert!(e < residual, "{}: {e:e}", p.name);
        assert!(a < agree, "{}: {a:e}", p.name);
    }
}

#[test]
fn hertz3d_increments_solve_their_local_problem() {
    for p in local_problems::hertz3d(2).unwrap() {
        check(&p, 1e-10, 1e-8);
    }
}

#[test]
fn random_problems_are_solved() {
    for p in local_problems::randoms(&[4, 16, 64], 1) {
        check(&p, 1e-10, 1e-8);
    }
}
