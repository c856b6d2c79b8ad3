//! Siconos and hycon side by side on the same local problems (`hycon bench siconos`,
//! docs/bench/siconos.md; feature `siconos`): each problem of [`crate::local_problems`]
//! handed in memory to Siconos' `fc3d` solvers ([`crate::siconos`]) and to hycon's, every
//! solver's reactions judged by both residuals (hycon's `natural_map_residual`, Siconos'
//! `fc3d_compute_error`) and against hycon's semi-smooth Newton solution, timed as the best of
//! a few runs. Times are measured, never asserted.

use crate::local_problems::NamedProblem;
use crate::siconos::{SiconosProblem, SiconosSolver};
use hycon::contact::local::{LocalProblem, LocalSolve};
use serde::Serialize;
use std::time::Instant;

/// The bench's settings.
#[derive(Debug, Clone, Copy)]
pub struct BenchSettings {
    /// Siconos' tolerance on its residual (`dparam[SICONOS_DPARAM_TOL]`).
    pub tolerance: f64,
    /// Runs per solver and problem; the best time counts. Runs stop early once one run has
    /// taken [`LONG_RUN`] seconds.
    pub repeats: usize,
    /// Iterations allowed to Siconos' Newton methods.
    pub newton_iterations: i32,
    /// Iterations (sweeps) allowed to Siconos' NSGS.
    pub nsgs_iterations: i32,
    /// hycon's rules run on problems of at most this many contacts (each of their up to 200
    /// iterations is a dense solve).
    pub rules_max_contacts: usize,
}

/// A run this long (seconds) is not repeated.
pub const LONG_RUN: f64 = 2.0;

/// One solver on one problem.
#[derive(Debug, Clone, Serialize)]
pub struct SolverRun {
    /// The solver's name in tables.
    pub solver: String,
    /// The best wall time of the runs, seconds.
    pub seconds: f64,
    /// The runs timed.
    pub runs: usize,
    /// Iterations: Siconos' count, hycon's Newton steps or rules' iterations (each one dense
    /// linear solve).
    pub iterations: usize,
    /// hycon's projected Gauss-Seidel sweeps (the Newton method's start; `None` for Siconos).
    pub sweeps: Option<usize>,
    /// Whether the solver met its own stopping rule (Siconos: info 0).
    pub settled: bool,
    /// hycon's residual of the reactions: `e / |q|`.
    pub residual_hycon: f64,
    /// Siconos' residual of the reactions: `e / max(|q|, |r|, |u|)`.
    pub residual_siconos: f64,
    /// The largest reaction difference from hycon's Newton solution, relative to its largest
    /// reaction.
    pub difference: f64,
}

/// Every solver on one problem.
#[derive(Debug, Clone, Serialize)]
pub struct ProblemRuns {
    /// The problem's class.
    pub class: String,
    /// The problem's name.
    pub name: String,
    /// Contacts.
    pub contacts: usize,
    /// Components per contact.
    pub dim: usize,
    /// Open, sticking and slipping contacts of hycon's Newton solution.
    pub states: [usize; 3],
    /// `|q|`.
    pub norm_q: f64,
    /// The largest diagonal entry of `W`.
    pub w_diagonal: f64,
    /// The largest reaction of hycon's Newton solution.
    pub largest_r: f64,
    /// The solvers, hycon's Newton first.
    pub runs: Vec<SolverRun>,
}

/// The largest `|a - b|` relative to the largest `|b|`.
fn difference(a: &[f64], b: &[f64]) -> f64 {
    let largest = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let diff = (a.iter().zip(b)).fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    if largest > 0.0 { diff / largest } else { diff }
}

/// Open (`r = 0`), sticking (`r` inside its cone) and slipping (on it) contacts of `r`, to
/// `1e-9` of the largest reaction.
fn states(problem: &LocalProblem, r: &[f64]) -> [usize; 3] {
    let d = problem.dim();
    let small = 1e-9 * r.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let mut count = [0; 3];
    for (i, ri) in r.chunks(d).enumerate() {
        let rt = ri[1..].iter().map(|v| v * v).sum::<f64>().sqrt();
        let k = if ri[0] <= small {
            0
        } else if rt < problem.mu()[i] * ri[0] - small {
            1
        } else {
            2
        };
        count[k] += 1;
    }
    count
}

/// The best time of up to `repeats` runs of `solve` (fewer once a run is long), the last
/// run's result and the runs done.
fn timed<T>(repeats: usize, mut solve: impl FnMut() -> T) -> (f64, T, usize) {
    let start = Instant::now();
    let mut result = solve();
    let mut best = start.elapsed().as_secs_f64();
    let mut runs = 1;
    while runs < repeats && best < LONG_RUN {
        let start = Instant::now();
        result = solve();
        best = best.min(start.elapsed().as_secs_f64());
        runs += 1;
    }
    (best, result, runs)
}

/// hycon's `solve` on `problem`, timed, against `reference` (hycon's Newton solution).
fn hycon_run(
    name: &str,
    problem: &LocalProblem,
    siconos: Option<&SiconosProblem>,
    repeats: usize,
    solve: impl Fn(&LocalProblem) -> LocalSolve,
    reference: Option<&[f64]>,
) -> (SolverRun, LocalSolve) {
    let (seconds, out, runs) = timed(repeats, || solve(problem));
    let run = SolverRun {
        solver: name.into(),
        seconds,
        runs,
        iterations: out.iterations,
        sweeps: Some(out.sweeps),
        settled: out.settled,
        residual_hycon: out.residual,
        residual_siconos: siconos.map_or(f64::NAN, |s| s.compute_error(&out.r)),
        difference: reference.map_or(0.0, |r| difference(&out.r, r)),
    };
    (run, out)
}

/// The name of hycon's rules in tables.
const RULES: &str = "hycon rules";

/// Every solver on `named`: hycon's Newton (the reference), hycon's rules (up to
/// `rules_max_contacts`), then Siconos' (three-component problems only).
pub fn compare(named: &NamedProblem, settings: &BenchSettings) -> ProblemRuns {
    let problem = &named.problem;
    let siconos = SiconosProblem::new(problem);
    let repeats = settings.repeats;
    let (newton_run, newton) = hycon_run(
        "hycon Newton",
        problem,
        siconos.as_ref(),
        repeats,
        LocalProblem::solve_newton,
        None,
    );
    let mut out = vec![newton_run];
    if problem.contacts() <= settings.rules_max_contacts {
        let (rules_run, _) = hycon_run(
            RULES,
            problem,
            siconos.as_ref(),
            repeats,
            LocalProblem::solve_rules,
            Some(&newton.r),
        );
        out.push(rules_run);
    }
    if let Some(s) = &siconos {
        for solver in SiconosSolver::ALL {
            let iterations = match solver {
                SiconosSolver::Nsgs => settings.nsgs_iterations,
                _ => settings.newton_iterations,
            };
            let (seconds, solve, runs) =
                timed(repeats, || s.solve(solver, settings.tolerance, iterations));
            out.push(SolverRun {
                solver: solver.name().into(),
                seconds,
                runs,
                iterations: usize::try_from(solve.iterations).unwrap_or(0),
                sweeps: None,
                settled: solve.info == 0,
                residual_hycon: problem.natural_map_residual(&solve.r),
                residual_siconos: s.compute_error(&solve.r),
                difference: difference(&solve.r, &newton.r),
            });
        }
    }
    let norm_q = problem.q().iter().map(|v| v * v).sum::<f64>().sqrt();
    let w = problem.w();
    ProblemRuns {
        class: named.class.clone(),
        name: named.name.clone(),
        contacts: problem.contacts(),
        dim: problem.dim(),
        states: states(problem, &newton.r),
        norm_q,
        w_diagonal: (0..w.nrows()).fold(0.0f64, |m, i| m.max(w[(i, i)])),
        largest_r: newton.r.iter().fold(0.0f64, |m, v| m.max(v.abs())),
        runs: out,
    }
}

/// The full table: a row per problem and solver.
pub fn full_table(problems: &[ProblemRuns]) -> String {
    let mut s = String::from(
        "| class | problem | contacts (open/stick/slip) | solver | time (ms) | runs | \
         iterations (+sweeps) | settled | residual hycon | residual Siconos | difference |\n\
         |---|---|---|---|---:|---:|---:|---|---:|---:|---:|\n",
    );
    for p in problems {
        let [open, stick, slip] = p.states;
        for r in &p.runs {
            s += &format!(
                "| {} | {} | {} ({open}/{stick}/{slip}) | {} | {:.3} | {} | {} | {} | {:.1e} | \
                 {:.1e} | {:.1e} |\n",
                p.class,
                p.name,
                p.contacts,
                r.solver,
                r.seconds * 1e3,
                r.runs,
                match r.sweeps {
                    Some(sweeps) => format!("{}+{sweeps}", r.iterations),
                    None => r.iterations.to_string(),
                },
                if r.settled { "yes" } else { "no" },
                r.residual_hycon,
                r.residual_siconos,
                r.difference
            );
        }
    }
    s
}

/// A time in milliseconds with the solver's iterations and whether it settled.
fn time_cell(r: &SolverRun) -> String {
    let mark = if r.settled { "" } else { ", not settled" };
    match r.sweeps {
        Some(sweeps) => format!("{:.3} ({}+{sweeps}{mark})", r.seconds * 1e3, r.iterations),
        None => format!("{:.3} ({}{mark})", r.seconds * 1e3, r.iterations),
    }
}

/// The side-by-side table: a row per problem, hycon's Newton and rules against Siconos'
/// fastest settled solver (times with iterations, and hycon's start sweeps), the residuals by
/// `fc3d_compute_error` (on 2D problems, which Siconos' `fc3d` does not take, hycon's
/// `e / |q|`), and the largest reaction difference of the settled Siconos solvers and of the
/// rules from hycon's Newton solution.
pub fn summary_table(problems: &[ProblemRuns]) -> String {
    let mut s = String::from(
        "| class | problem | contacts | hycon Newton ms (steps+sweeps) | hycon rules ms \
         (iterations) | hycon residual | Siconos best | its ms (iterations) | its residual | \
         largest difference Siconos | rules |\n\
         |---|---|---:|---:|---:|---:|---|---:|---:|---:|---:|\n",
    );
    let cell = |d: Option<f64>| d.map_or("-".into(), |d| format!("{d:.1e}"));
    for p in problems {
        let newton = &p.runs[0];
        let rules = p.runs.iter().find(|r| r.solver == RULES);
        let settled: Vec<&SolverRun> = (p.runs.iter())
            .filter(|r| r.sweeps.is_none() && r.settled)
            .collect();
        let best = (settled.iter()).min_by(|a, b| a.seconds.total_cmp(&b.seconds));
        let largest = (settled.iter())
            .map(|r| r.difference)
            .fold(None, |m: Option<f64>, d| Some(m.map_or(d, |m| m.max(d))));
        let (name, time, residual) = match best {
            Some(b) => (
                b.solver.clone(),
                time_cell(b),
                format!("{:.1e}", b.residual_siconos),
            ),
            None if p.dim == 3 => ("none settled".into(), "-".into(), "-".into()),
            None => ("(2D: not fc3d)".into(), "-".into(), "-".into()),
        };
        let hycon_residual = match p.dim {
            3 => format!("{:.1e}", newton.residual_siconos),
            _ => format!("{:.1e} (e/\\|q\\|)", newton.residual_hycon),
        };
        s += &format!(
            "| {} | {} | {} | {} | {} | {hycon_residual} | {name} | {time} | {residual} | {} | \
             {} |\n",
            p.class,
            p.name,
            p.contacts,
            time_cell(newton),
            rules.map_or("-".into(), time_cell),
            cell(largest),
            cell(rules.filter(|r| r.settled).map(|r| r.difference)),
        );
    }
    s
}
