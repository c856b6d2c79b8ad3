//! The problem sets of `hycon_lab::local_problems`: each class's exported reactions solve
//! their problem (natural-map residual), hycon's two solvers (the semi-smooth Newton method
//! and the paper's rules) find them again, and a change of units changes nothing.
//!
//! Tolerances: the natural-map residual (Siconos' measure, relative to `|q|`) of an exported
//! solution and of either solver's stays below `1e-8`: a slip direction is settled to
//! `SAME_DIRECTION` (a cosine of `1 - 1e-12`, an angle of `1.4e-6`), which leaves up to
//! `3e-9` where contacts slip in turning directions (the Mindlin pull). The reactions agree
//! to `1e-8` of the largest under small kinematics (measured: `5e-14` at most) and to `1e-5`
//! under finite kinematics, where the analysis converges to its tolerance `R <= 1e-6` on the
//! geometry of the previous iterate, not to the fixed point (measured: `1.1e-6` on the block's
//! second drag).

use hycon::contact::local::{LocalProblem, LocalSolve};
use hycon_lab::local_problems::{self, NamedProblem};

/// The natural-map residual every solution must meet (module docs).
const RESIDUAL: f64 = 1e-8;

/// The largest `|a - b|` relative to the largest `|b|`.
fn difference(a: &[f64], b: &[f64]) -> f64 {
    let largest = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        / largest
}

/// Both solvers on `p`, printed and checked: each settles with a residual below [`RESIDUAL`],
/// each agrees with the exported solution (or, without one, with the other) to `agree` of the
/// largest reaction. Returns the Newton solve.
fn check(p: &NamedProblem, agree: f64) -> LocalSolve {
    let newton = p.problem.solve_newton();
    let rules = p.problem.solve_rules();
    let reference = p.solution.clone().unwrap_or_else(|| newton.r.clone());
    let exported = p
        .solution
        .as_ref()
        .map(|s| p.problem.natural_map_residual(s));
    println!(
        "{}/{}: {} contacts; exported residual {:.1e}; newton: {} steps, {} sweeps, \
         residual {:.1e}, {:.1e} from it; rules: {} iterations, residual {:.1e}, {:.1e} from it",
        p.class,
        p.name,
        p.problem.contacts(),
        exported.unwrap_or(f64::NAN),
        newton.iterations,
        newton.sweeps,
        newton.residual,
        difference(&newton.r, &reference),
        rules.iterations,
        rules.residual,
        difference(&rules.r, &reference),
    );
    for (solver, solve) in [("newton", &newton), ("rules", &rules)] {
        assert!(solve.settled, "{}: {solver} did not settle", p.name);
        assert!(
            solve.residual < RESIDUAL,
            "{}: {solver} {:e}",
            p.name,
            solve.residual
        );
        let d = difference(&solve.r, &reference);
        assert!(d < agree, "{}: {solver} {d:e} from the reference", p.name);
    }
    if let Some(e) = exported {
        assert!(e < RESIDUAL, "{}: exported {e:e}", p.name);
    }
    newton
}

#[test]
fn hertz3d_increments_solve_their_local_problem() {
    for p in local_problems::hertz3d(4).unwrap() {
        check(&p, 1e-8);
    }
}

#[test]
fn mindlin3d_increments_solve_their_local_problem() {
    for p in local_problems::mindlin3d(4).unwrap() {
        check(&p, 1e-8);
    }
}

#[test]
fn slide3d_increments_solve_their_local_problem() {
    for p in local_problems::slide3d().unwrap() {
        let finite = p.name.contains("finite");
        check(&p, if finite { 1e-5 } else { 1e-8 });
    }
}

#[test]
fn plane_increments_solve_their_local_problem() {
    for p in local_problems::plane().unwrap() {
        assert_eq!(p.problem.dim(), 2);
        check(&p, 1e-8);
    }
}

/// Random problems of growing size: both solvers agree, and a change of units (`W` by `a`,
/// `q` by `b`) scales the reactions by `b / a` and nothing else.
#[test]
fn random_problems_are_solved_in_any_units() {
    let (a, b) = (1e6, 1e-3);
    for p in local_problems::randoms(&[4, 16, 64], 1) {
        let newton = check(&p, 1e-8);
        let scaled = LocalProblem::new(
            3,
            p.problem.w() * a,
            p.problem.q().iter().map(|v| v * b).collect(),
            p.problem.mu().to_vec(),
        )
        .unwrap();
        let expected: Vec<f64> = newton.r.iter().map(|v| v * b / a).collect();
        for solve in [scaled.solve_newton(), scaled.solve_rules()] {
            assert!(solve.settled);
            let d = difference(&solve.r, &expected);
            assert!(d < 1e-10, "{}: {d:e}", p.name);
        }
    }
}
