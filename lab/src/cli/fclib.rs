//! `hycon fclib write|solve`: FCLIB's local problem files out and in (docs/fclib.md). The
//! commands parse in every build; they run where hycon-lab was built with the feature `fclib`
//! (libfclib), and say so elsewhere.

use clap::{Subcommand, ValueEnum};
use std::path::{Path, PathBuf};

/// `hycon fclib ...`.
#[derive(Subcommand)]
#[cfg_attr(not(feature = "fclib"), allow(dead_code))]
pub enum Fclib {
    /// Write the problem sets as FCLIB local problem files, each with its solution.
    ///
    /// The problem sets are hycon_lab::local_problems' increments and random problems: one
    /// .hdf5 per problem in --out DIR (default out/fclib), each with FCLIB's solution record: the analysis' converged reactions, or for a random problem hycon's Newton
    /// solution. Prints a line per file: name, contacts, nonzeros of W, natural-map residual
    /// of the stored solution.
    Write {
        /// The problem classes (comma-separated or repeated).
        #[arg(long, value_enum, value_delimiter = ',', num_args = 1..,
              default_values_t = [Class::Hertz3d, Class::Mindlin3d, Class::Slide3d, Class::Plane, Class::Random])]
        class: Vec<Class>,
        /// hertz3d and mindlin3d: faces per contact radius of the caps.
        #[arg(long, default_value_t = 4)]
        a_over_h: usize,
        /// random: the numbers of contacts, one problem each.
        #[arg(long, value_delimiter = ',', num_args = 1.., default_values_t = [10, 40, 160])]
        contacts: Vec<usize>,
        /// random: the seed.
        #[arg(long, default_value_t = 1)]
        seed: u64,
    },
    /// Solve FCLIB local problem files with hycon's solvers.
    ///
    /// Prints per file: contacts, the
    /// range of mu, the solver, whether it settled, its iterations (and the Newton method's
    /// projected Gauss-Seidel sweeps), its time, hycon's natural-map residual (Siconos'
    /// fc3d_compute_error), libfclib's merit function (3D) and, where the file has a
    /// solution, that solution's residual and the largest difference of hycon's reactions
    /// from it relative to its max |r|. Exits with 1 if a file cannot be read (the others
    /// are solved).
    Solve {
        /// The FCLIB files (HDF5 with /fclib_local).
        #[arg(required = true)]
        files: Vec<PathBuf>,
        /// The solver.
        #[arg(long, value_enum, default_value_t = Solver::Newton)]
        solver: Solver,
    },
}

/// A problem class of `hycon fclib write` (hycon_lab::local_problems).
#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Class {
    /// The quarter cap pressed (frictionless).
    Hertz3d,
    /// The half cap pressed and pulled (mu = 0.3).
    Mindlin3d,
    /// The block dragged at 30 degrees (small and finite kinematics).
    Slide3d,
    /// The plane disk pressed and slid (dim 2).
    Plane,
    /// Random well-posed problems of growing size.
    Random,
}

/// A solver of `hycon fclib solve`.
#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Solver {
    /// The semi-smooth Newton method (the fallback's solver, docs/method.md).
    Newton,
    /// The paper's rules with the 3D direction update (docs/method.md, "The rules").
    Rules,
}

/// Runs `hycon fclib ...` with its files under `out` (`write`'s directory, default
/// out/fclib).
pub fn run(command: Fclib, out: Option<&Path>) -> Result<(), Box<dyn std::error::Error>> {
    let out = out.unwrap_or(Path::new("out/fclib"));
    #[cfg(feature = "fclib")]
    {
        match command {
            Fclib::Write {
                class,
                a_over_h,
                contacts,
                seed,
            } => with_feature::write(&class, a_over_h, &contacts, seed, out),
            Fclib::Solve { files, solver } => with_feature::solve(&files, solver),
        }
    }
    #[cfg(not(feature = "fclib"))]
    {
        let _ = (command, out);
        Err(
            "this hycon was built without FCLIB: build it with `cargo build --release -p \
             hycon-lab --features fclib` (needs libfclib-dev and libclang-dev)"
                .into(),
        )
    }
}

#[cfg(feature = "fclib")]
mod with_feature {
    use super::{Class, Solver};
    use hycon::contact::local::{LocalProblem, LocalSolve};
    use hycon_lab::fclib::{self, Metadata};
    use hycon_lab::local_problems::{self, NamedProblem};
    use std::path::{Path, PathBuf};
    use std::time::Instant;

    type AnyResult<T = ()> = Result<T, Box<dyn std::error::Error>>;

    /// The problems of `classes`, in their order.
    fn problems(
        classes: &[Class],
        a_over_h: usize,
        contacts: &[usize],
        seed: u64,
    ) -> AnyResult<Vec<NamedProblem>> {
        let mut all = Vec::new();
        for class in classes {
            all.extend(match class {
                Class::Hertz3d => local_problems::hertz3d(a_over_h)?,
                Class::Mindlin3d => local_problems::mindlin3d(a_over_h)?,
                Class::Slide3d => local_problems::slide3d()?,
                Class::Plane => local_problems::plane()?,
                Class::Random => local_problems::randoms(contacts, seed),
            });
        }
        Ok(all)
    }

    /// The info record of a problem set's problem.
    fn metadata(named: &NamedProblem, source: &str) -> Metadata {
        Metadata {
            title: format!("hycon {} {}", named.class, named.name),
            description: format!(
                "hycon {} ({}): {} contacts of {} components, FCLIB signs (normal first, \
                 compression and opening positive); solution: {source}",
                env!("CARGO_PKG_VERSION"),
                named.class,
                named.problem.contacts(),
                named.problem.dim(),
            ),
            math_info: "W symmetric positive semi-definite (a condensed flexibility)".into(),
        }
    }

    pub fn write(
        classes: &[Class],
        a_over_h: usize,
        contacts: &[usize],
        seed: u64,
        out: &Path,
    ) -> AnyResult {
        std::fs::create_dir_all(out)?;
        println!(
            "{:<36} {:>8} {:>10} {:>12}  solution",
            "file", "contacts", "nnz(W)", "residual"
        );
        for named in problems(classes, a_over_h, contacts, seed)? {
            let (r, source) = match &named.solution {
                Some(r) => (Some(r.clone()), "the analysis' converged reactions"),
                None => match named.problem.solve_newton() {
                    solve if solve.settled => (Some(solve.r), "hycon's semi-smooth Newton method"),
                    _ => (None, "none (hycon's Newton method did not settle)"),
                },
            };
            let file = if named.name.starts_with(&named.class) {
                format!("{}.hdf5", named.name)
            } else {
                format!("{}-{}.hdf5", named.class, named.name)
            };
            let info = metadata(&named, source);
            fclib::write_local(&out.join(&file), &named.problem, r.as_deref(), &info)?;
            let nonzeros = named.problem.w().iter().filter(|v| **v != 0.0).count();
            let residual = r.map_or("-".into(), |r| {
                format!("{:.3e}", named.problem.natural_map_residual(&r))
            });
            println!(
                "{file:<36} {:>8} {nonzeros:>10} {residual:>12}  {source}",
                named.problem.contacts(),
            );
        }
        println!("written to {}", out.display());
        Ok(())
    }

    fn run_solver(problem: &LocalProblem, solver: Solver) -> LocalSolve {
        match solver {
            Solver::Newton => problem.solve_newton(),
            Solver::Rules => problem.solve_rules(),
        }
    }

    fn solver_name(solver: Solver) -> &'static str {
        match solver {
            Solver::Newton => "newton",
            Solver::Rules => "rules",
        }
    }

    /// The largest `|a - b|` over the largest `|b|`, or `b = 0` where `b` is zero.
    fn relative_difference(a: &[f64], b: &[f64]) -> String {
        let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let diff = a
            .iter()
            .zip(b)
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
        if scale > 0.0 {
            format!("{:.3e}", diff / scale)
        } else {
            "r* = 0".into()
        }
    }

    pub fn solve(files: &[PathBuf], solver: Solver) -> AnyResult {
        println!(
            "{:<40} {:>8} {:>9} {:>6} {:>7} {:>5} {:>6} {:>8} {:>10} {:>10} {:>10} {:>10}",
            "file",
            "contacts",
            "mu",
            "solver",
            "settled",
            "iter",
            "sweeps",
            "ms",
            "residual",
            "merit",
            "stored res",
            "vs stored"
        );
        let mut failed = 0;
        for path in files {
            let (problem, stored) = match fclib::read_local(path) {
                Ok(read) => read,
                Err(e) => {
                    eprintln!("hycon: {e}");
                    failed += 1;
                    continue;
                }
            };
            let start = Instant::now();
            let solve = run_solver(&problem, solver);
            let ms = start.elapsed().as_secs_f64() * 1e3;
            let (lo, hi) = problem
                .mu()
                .iter()
                .fold((f64::INFINITY, 0.0f64), |(lo, hi), &m| {
                    (lo.min(m), hi.max(m))
                });
            let mu = if lo == hi {
                format!("{lo}")
            } else {
                format!("{lo}..{hi}")
            };
            let merit = fclib::merit(&problem, &solve.r).map_or("-".into(), |m| format!("{m:.3e}"));
            let (stored, versus) = stored.map_or(("-".into(), "-".into()), |r| {
                (
                    format!("{:.3e}", problem.natural_map_residual(&r)),
                    relative_difference(&solve.r, &r),
                )
            });
            let name = path
                .file_name()
                .unwrap_or(path.as_os_str())
                .to_string_lossy();
            println!(
                "{name:<40} {:>8} {mu:>9} {:>6} {:>7} {:>5} {:>6} {ms:>8.1} {:>10.3e} {merit:>10} \
                 {stored:>10} {versus:>10}",
                problem.contacts(),
                solver_name(solver),
                if solve.settled { "yes" } else { "no" },
                solve.iterations,
                solve.sweeps,
                solve.residual,
            );
        }
        match failed {
            0 => Ok(()),
            n => Err(format!("{n} of {} files could not be read", files.len()).into()),
        }
    }
}
