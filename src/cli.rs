//! Command-line interface (clap): the main job and one subcommand per reference case.

use clap::{Parser, Subcommand, ValueEnum};
use hycon::cases::{self, BeamLoad, COOK_CONVERGED, COOK_PUBLISHED};
use hycon::element::Formulation;
use hycon::material::Analysis;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

#[derive(Parser)]
#[command(
    name = "hycon",
    version,
    about = "Assumed-stress hybrid elements and contact (Kubomura-Pian)"
)]
struct Cli {
    /// Directory for written results.
    #[arg(long, global = true, default_value = "out")]
    out: PathBuf,
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// The main job: Cook's membrane convergence table for every element (also the default).
    Elements {
        /// Finest mesh (n x n), a power of two >= 2.
        #[arg(long, default_value_t = 32)]
        max_n: usize,
    },
    /// Cook's membrane with one element and mesh.
    Cook {
        #[arg(long, value_enum, default_value_t = Element::Hybrid)]
        element: Element,
        /// Elements per side (even).
        #[arg(long, default_value_t = 16)]
        n: usize,
    },
    /// The Pian-Sumihara cantilever (L = 10, h = 2, E = 1500).
    Beam {
        #[arg(long, value_enum, default_value_t = Element::Hybrid)]
        element: Element,
        #[arg(long, value_enum, default_value_t = Load::Moment)]
        load: Load,
        /// Elements along the length and through the depth (even).
        #[arg(long, default_value_t = 5)]
        nx: usize,
        #[arg(long, default_value_t = 2)]
        ny: usize,
        /// Shift of interior vertical grid lines (0 = regular mesh).
        #[arg(long, default_value_t = 0.0)]
        distortion: f64,
        /// Poisson's ratio.
        #[arg(long, default_value_t = 0.25)]
        nu: f64,
        /// Plane strain instead of plane stress.
        #[arg(long)]
        plane_strain: bool,
    },
    /// Performance measurements (printed, never asserted).
    Bench {
        #[command(subcommand)]
        what: Bench,
    },
}

#[derive(Subcommand)]
enum Bench {
    /// Element stiffness kernel time per element, for each element kind.
    Kernels {
        /// Evaluations per kind.
        #[arg(long, default_value_t = 200_000)]
        repeats: usize,
    },
    /// Assemble, analyse, factor and solve a cantilever of 4n x n hybrid elements
    /// (n = 354 gives about 1M dofs).
    Scale {
        #[arg(long, default_value_t = 354)]
        n: usize,
    },
}

#[derive(Clone, Copy, ValueEnum)]
enum Element {
    Hybrid,
    PianSumihara,
    Q4,
}

impl From<Element> for Formulation {
    fn from(e: Element) -> Self {
        match e {
            Element::Hybrid => Formulation::Hybrid,
            Element::PianSumihara => Formulation::PianSumihara,
            Element::Q4 => Formulation::Q4,
        }
    }
}

#[derive(Clone, Copy, ValueEnum)]
enum Load {
    Moment,
    Shear,
}

pub fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command.unwrap_or(Command::Elements { max_n: 32 }) {
        Command::Elements { max_n } => elements_table(max_n, &cli.out),
        Command::Cook { element, n } => cases::cook_membrane(element.into(), n)
            .map(|v| {
                println!("Cook's membrane {n}x{n}: v(48,52) = {v:.6} (converged {COOK_CONVERGED})")
            })
            .map_err(Into::into),
        Command::Beam {
            element,
            load,
            nx,
            ny,
            distortion,
            nu,
            plane_strain,
        } => beam(element.into(), load, nx, ny, distortion, nu, plane_strain),
        Command::Bench { what } => bench(what),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("hycon: {e}");
            ExitCode::FAILURE
        }
    }
}

type AnyResult = Result<(), Box<dyn std::error::Error>>;

/// Cook's membrane for every element on n x n meshes, n = 2, 4, ..., max_n; printed and written
/// to `out/cook.csv`.
fn elements_table(max_n: usize, out: &Path) -> AnyResult {
    println!(
        "Cook's membrane: v at (48, 52), plane stress E = 1, nu = 1/3, converged {COOK_CONVERGED}"
    );
    println!(
        "{:>6} | {:>18} | {:>18} | {:>18} | published Q4 / P-S",
        "mesh", "hybrid 7-beta", "Pian-Sumihara", "Q4"
    );
    std::fs::create_dir_all(out)?;
    let path = out.join("cook.csv");
    let mut csv = std::fs::File::create(&path)?;
    writeln!(csv, "element,n,v_tip,error_vs_{COOK_CONVERGED},seconds")?;
    let mut n = 2;
    while n <= max_n {
        let mut row = format!("{:>6} |", format!("{n}x{n}"));
        for f in Formulation::ALL {
            let start = Instant::now();
            let v = cases::cook_membrane(f, n)?;
            let secs = start.elapsed().as_secs_f64();
            let err = (v - COOK_CONVERGED) / COOK_CONVERGED;
            row += &format!(" {v:>9.4} ({:>+6.2}%) |", 100.0 * err);
            writeln!(csv, "{},{n},{v:.10},{err:.6e},{secs:.6}", f.name())?;
        }
        if let Some((_, q4, ps)) = COOK_PUBLISHED.iter().find(|p| p.0 == n) {
            row += &format!(" {q4:.3} / {ps:.3}");
        }
        println!("{row}");
        n *= 2;
    }
    println!("written: {}", path.display());
    Ok(())
}

fn beam(
    f: Formulation,
    load: Load,
    nx: usize,
    ny: usize,
    distortion: f64,
    nu: f64,
    plane_strain: bool,
) -> AnyResult {
    let mut material = cases::cantilever_material();
    material.poisson = nu;
    if plane_strain {
        material.analysis = Analysis::PlaneStrain;
    }
    let (load, exact) = match load {
        Load::Moment => (
            BeamLoad::Moment,
            100.0 * (1.0 - nu * nu).powi(plane_strain as i32),
        ),
        Load::Shear => (BeamLoad::Shear, 102.6),
    };
    let v = cases::cantilever(f, load, material, nx, ny, distortion)?;
    println!(
        "cantilever {nx}x{ny}, distortion {distortion}, {}: tip v = {v:.6} (reference {exact}, error {:+.3}%)",
        f.name(),
        100.0 * (v - exact) / exact
    );
    Ok(())
}

fn bench(what: Bench) -> AnyResult {
    match what {
        Bench::Kernels { repeats } => {
            println!("element stiffness kernel, {repeats} evaluations each:");
            for k in hycon::bench::kernel_times(repeats)? {
                println!("  {:<26} {:>8.0} ns/element", k.kind, k.nanoseconds);
            }
        }
        Bench::Scale { n } => {
            let r = hycon::bench::scale_run(n)?;
            let mib = |b: Option<u64>| {
                b.map_or("n/a".into(), |b| format!("{:.0} MiB", b as f64 / 1048576.0))
            };
            println!(
                "cantilever {}x{n} hybrid elements: {} free dofs, nnz(K lower) {}, nnz(L) {}",
                4 * n,
                r.dofs,
                r.nnz_k,
                r.nnz_l
            );
            println!(
                "  mesh {:.2} s, assembly {:.2} s, analysis {:.2} s, factorization {:.2} s, solve {:.2} s; peak memory {}",
                r.mesh,
                r.assembly,
                r.analysis,
                r.factorization,
                r.solve,
                mib(r.peak_memory)
            );
            println!(
                "  tip deflection / Euler-Bernoulli = {:.4} (shear adds ~ (H/L)^2 terms)",
                r.tip_ratio
            );
        }
    }
    Ok(())
}
