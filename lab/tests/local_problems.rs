//! The problem sets of `hycon_lab::local_problems`: each class's exported reactions solve
//! their problem (natural-map residual), hycon's two solvers (the semi-smooth Newton method
//! and the paper's rules) find them again, and a change of units changes nothing. The
//! paper's rules follow the slip directions from iterate to iterate, which does not settle
//! where contacts slip on faces (the Mindlin pull, the sliding block, the random problems:
//! docs/method.md, "The local problem"); where they settle they must agree.
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

/// Both solvers on `p`, printed and checked: the semi-smooth Newton method settles with a
/// residual below [`RESIDUAL`] and agrees with the exported solution (or, without one, is the
/// reference) to `agree` of the largest reaction; so do the paper's rules where they settle,
/// and they must where `rules_settle`. Returns the Newton solve.
fn check(p: &NamedProblem, agree: f64, rules_settle: bool) -> LocalSolve {
    let newton = p.problem.solve_newton();
    let rules = p.problem.solve_rules();
    let reference = p.solution.clone().unwrap_or_else(|| newton.r.clone());
    let exported = p
        .solution
        .as_ref()
        .map(|s| p.problem.natural_map_residual(s));
    println!(
        "{}/{}: {} contacts; exported residual {:.1e}; newton: {} steps, {} sweeps, \
         residual {:.1e}, {:.1e} from it; rules: settled {}, {} iterations, residual {:.1e}, \
         {:.1e} from it",
        p.class,
        p.name,
        p.problem.contacts(),
        exported.unwrap_or(f64::NAN),
        newton.iterations,
        newton.sweeps,
        newton.residual,
        difference(&newton.r, &reference),
        rules.settled,
        rules.iterations,
        rules.residual,
        difference(&rules.r, &reference),
    );
    assert!(
        !rules_settle || rules.settled,
        "{}: the rules did not settle",
        p.name
    );
    for (solver, solve) in [("newton", &newton), ("rules", &rules)] {
        if solver == "rules" && !rules.settled {
            continue;
        }
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
        // the symmetry planes' dropped tangents: decoupled rows, their reactions zero
        let w = p.problem.w();
        let decoupled: Vec<usize> = (0..w.nrows())
            .filter(|&j| (0..w.nrows()).all(|i| i == j || w[(i, j)] == 0.0))
            .collect();
        assert!(!decoupled.is_empty());
        let solution = p.solution.as_ref().unwrap();
        assert!(
            decoupled
                .iter()
                .all(|&j| p.problem.q()[j] == 0.0 && solution[j] == 0.0)
        );
        check(&p, 1e-8, true);
    }
}

#[test]
fn mindlin3d_increments_solve_their_local_problem() {
    for p in local_problems::mindlin3d(4).unwrap() {
        // the press sticks everywhere; in the pull the slip directions follow the slip
        check(&p, 1e-8, p.name.ends_with("press"));
    }
}

#[test]
fn slide3d_increments_solve_their_local_problem() {
    for p in local_problems::slide3d().unwrap() {
        let finite = p.name.contains("finite");
        check(&p, if finite { 1e-5 } else { 1e-8 }, false);
    }
}

#[test]
fn plane_increments_solve_their_local_problem() {
    for p in local_problems::plane().unwrap() {
        assert_eq!(p.problem.dim(), 2);
        check(&p, 1e-8, true);
    }
}

/// Random problems of growing size: both solvers agree, and a change of units (`W` by `a`,
/// `q` by `b`) scales the reactions by `b / a` and nothing else.
#[test]
fn random_problems_are_solved_in_any_units() {
    let (a, b) = (1e6, 1e-3);
    for p in local_problems::randoms(&[4, 16, 64], 1) {
        let newton = check(&p, 1e-8, false);
        let scaled = LocalProblem::new(
            3,
            p.problem.w() * a,
            p.problem.q().iter().map(|v| v * b).collect(),
            p.problem.mu().to_vec(),
        )
        .unwrap();
        let expected: Vec<f64> = newton.r.iter().map(|v| v * b / a).collect();
        for solve in [scaled.solve_newton(), scaled.solve_rules()] {
            if solve.sweeps == 0 && !solve.settled {
                continue; // the rules, where they do not settle
            }
            assert!(solve.settled);
            let d = difference(&solve.r, &expected);
            assert!(d < 1e-10, "{}: {d:e}", p.name);
        }
    }
}
