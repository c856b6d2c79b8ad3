//! Command-line interface (clap): the main job (the contact examples) and one subcommand per
//! reference case.

use clap::{Args, Parser, Subcommand, ValueEnum};
use hycon::contact::iteration::Kinematics;
use hycon::element::Formulation;
use hycon::material::Analysis;
use hycon_lab::cases::{self, BeamLoad, COOK_CONVERGED, COOK_PUBLISHED};
use hycon_lab::examples::{
    self, CattaneoCase, Example, Fields, HertzCase, Run, SlideCase, SphereCase,
};
use hycon_lab::examples3d::{self, CapCase};
use hycon_lab::report;
use serde::Serialize;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

mod fclib;

#[derive(Parser)]
#[command(
    name = "hycon",
    version,
    about = "Assumed-stress hybrid elements and contact (Kubomura-Pian)",
    long_about = "Assumed-stress hybrid elements and contact (Kubomura-Pian).\n\nWithout a \
                  subcommand, runs the main job: the paper's four contact examples, the \
                  axisymmetric sphere and the 3D sphere (`hycon contact`)."
)]
struct Cli {
    /// Directory for written results [default: out for `elements`, out/contact for the contact
    /// jobs; for `run`, the scene's `[output] dir`, which this overrides].
    #[arg(long, global = true, value_name = "DIR")]
    out: Option<PathBuf>,
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// The main job (also the default): the four contact examples on the disk-on-block scene
    /// (Hertz for three modulus ratios, frictionless and frictional sliding, Cattaneo-Mindlin)
    /// the axisymmetric one (Hertz's sphere) and the two 3D ones (`hycon sphere3d`: Hertz's
    /// sphere, Cattaneo-Mindlin), tables against the closed forms, the time split, SVG plots,
    /// VTU fields and summary.json.
    Contact {
        /// Elements per contact half-width (a power of two).
        #[arg(long, default_value_t = 32)]
        n: usize,
        #[command(flatten)]
        cap: CapOptions,
        #[command(flatten)]
        output: Output,
    },
    /// Non-sliding frictionless Hertz contact, increments of the approach up to the target half-width a.
    Hertz {
        /// Elements per contact half-width (a power of two).
        #[arg(long, default_value_t = 16)]
        n: usize,
        /// E_disk / E_block, one run each (comma-separated or repeated).
        #[arg(long, value_delimiter = ',', num_args = 1.., default_values_t = [1.0, 1e-2, 1e-4])]
        modulus_ratio: Vec<f64>,
        /// Displacement increments up to the calibrated approach.
        #[arg(long, default_value_t = 3)]
        increments: usize,
        /// Contact kinematics: small (linear gap, geometry evaluated once; Hertz theory's
        /// problem) or finite (geometry at the current positions).
        #[arg(long, value_enum, default_value_t = KinematicsChoice::Small)]
        kinematics: KinematicsChoice,
        /// R / a of the scene (a power of two; 64 is the reference scene).
        #[arg(long, default_value_t = 64)]
        r_over_a: usize,
        #[command(flatten)]
        output: Output,
    },
    /// Extensive sliding: pressed to the target half-width a, then moved sideways.
    Slide {
        /// Elements per contact half-width (a power of two).
        #[arg(long, default_value_t = 8)]
        n: usize,
        /// Coulomb friction coefficient (0: frictionless).
        #[arg(long, default_value_t = 0.0)]
        friction: f64,
        /// Sliding increments.
        #[arg(long, default_value_t = 8)]
        increments: usize,
        /// Sliding distance, in contact half-widths a.
        #[arg(long, default_value_t = 2.0)]
        distance: f64,
        /// Contact kinematics: finite (the disk slides over many elements) or small (valid
        /// only for slides much shorter than an element).
        #[arg(long, value_enum, default_value_t = KinematicsChoice::Finite)]
        kinematics: KinematicsChoice,
        #[command(flatten)]
        output: Output,
    },
    /// Hertz's sphere on a half-space, axisymmetric (frictionless, small kinematics):
    /// increments of the approach up to a^2/R of the target contact radius a.
    Sphere {
        /// Elements per contact radius (a power of two).
        #[arg(long, default_value_t = 32)]
        n: usize,
        /// E_sphere / E_block, one run each (comma-separated or repeated).
        #[arg(long, value_delimiter = ',', num_args = 1.., default_values_t = [1.0])]
        modulus_ratio: Vec<f64>,
        /// Displacement increments up to a^2/R.
        #[arg(long, default_value_t = 3)]
        increments: usize,
        /// R / a of the target contact radius.
        #[arg(long, default_value_t = 32)]
        r_over_a: usize,
        #[command(flatten)]
        output: Output,
    },
    /// Hertz's sphere and Cattaneo-Mindlin in 3D (the main job's 3D examples): the quarter
    /// model of a paraboloid cap on a block pressed by Hertz's approach, then the half model
    /// on its mirror block pressed and moved along x until Q/(mu P) reaches the target; hybrid
    /// bricks, small kinematics. --json prints the two examples as a JSON array.
    Sphere3d {
        #[command(flatten)]
        cap: CapOptions,
        #[command(flatten)]
        output: Output,
    },
    /// Cattaneo-Mindlin partial slip (identical materials): pressed, then tangential
    /// displacement in small increments until Q/(mu P) passes the target.
    Cattaneo {
        /// Elements per contact half-width (a power of two).
        #[arg(long, default_value_t = 16)]
        n: usize,
        /// Coulomb friction coefficient (> 0).
        #[arg(long, default_value_t = 0.3)]
        friction: f64,
        /// Wanted increase of Q/(mu P) per increment.
        #[arg(long, default_value_t = 0.1)]
        step: f64,
        /// Stop once Q/(mu P) has passed this value.
        #[arg(long, default_value_t = 0.75)]
        target: f64,
        /// Contact kinematics: small (the theory's linearized problem) or finite.
        #[arg(long, value_enum, default_value_t = KinematicsChoice::Small)]
        kinematics: KinematicsChoice,
        #[command(flatten)]
        output: Output,
    },
    /// Cook's membrane convergence table for every element.
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
    /// Your own model: a TOML scene over a Gmsh mesh (see docs/scene-files.md).
    /// Prints a line per step (iterations, contact length, peak pressure, total force) and
    /// writes the scene's outputs.
    Run {
        /// The scene file.
        scene: PathBuf,
        /// Read and check everything without solving for contact: print the bodies, supports,
        /// loads, contact pairs (lengths, initial gaps, facing), steps and a verdict (step 1 is
        /// solved once, linearly without contact, to warn of strains beyond 0.05: units?).
        #[arg(long)]
        dry_run: bool,
        /// Fail (exit code 1) on any warning: of the scene (units, a pair out of reach) or of
        /// the run (a pair that never closed, a contact zone narrower than two elements).
        #[arg(long)]
        strict: bool,
    },
    /// Performance measurements (printed, never asserted).
    Bench {
        #[command(subcommand)]
        what: Bench,
    },
    /// FCLIB local problem files out and in (needs the build feature `fclib`, docs/fclib.md).
    Fclib {
        #[command(subcommand)]
        what: fclib::Fclib,
    },
}

/// Output options of the contact jobs.
#[derive(Args, Clone, Copy, Default)]
struct Output {
    /// Print the result as JSON on stdout instead of the tables.
    #[arg(long)]
    json: bool,
    /// Write no files (SVG, VTU, and the main job's summary.json).
    #[arg(long)]
    no_files: bool,
    /// Also write a VTU per increment, with a ParaView .pvd collection (each field costs one
    /// more solve, which then shows in the time split's recovery).
    #[arg(long)]
    every_increment: bool,
}

/// Options of the 3D examples.
#[derive(Args, Clone, Copy)]
struct CapOptions {
    /// 3D examples: faces per target contact radius at the centre (a/h).
    #[arg(long, default_value_t = 4)]
    a_over_h: usize,
    /// 3D Cattaneo-Mindlin: Coulomb friction coefficient (> 0).
    #[arg(long = "friction-3d", default_value_t = 0.3)]
    friction: f64,
    /// 3D Cattaneo-Mindlin: the Q/(mu P) the cap is pulled to.
    #[arg(long = "target-3d", default_value_t = 0.5)]
    target: f64,
}

impl Default for CapOptions {
    fn default() -> Self {
        let c = CapCase::default();
        CapOptions {
            a_over_h: c.a_over_h,
            friction: c.friction,
            target: c.target,
        }
    }
}

impl CapOptions {
    fn case(&self, output: &Output) -> CapCase {
        CapCase {
            a_over_h: self.a_over_h,
            friction: self.friction,
            target: self.target,
            fields: output.fields(),
        }
    }
}

/// The two 3D examples of `cap`.
fn examples3d(cap: &CapCase, mut progress: examples::Progress<'_>) -> hycon::Result<[Example; 2]> {
    Ok([
        examples3d::hertz(
            cap,
            progress.as_mut().map(|f| &mut **f as &mut dyn FnMut(&str)),
        )?,
        examples3d::cattaneo_mindlin(cap, progress)?,
    ])
}

#[derive(Subcommand)]
enum Bench {
    /// Convergence of the 3D bricks on Saint-Venant's end-loaded cantilever (nu = 0, exact
    /// tractions at the free end, exact displacements held at the root): the largest nodal
    /// displacement error against free dofs for the hybrid brick and the H8 on regular and
    /// distorted (20%) meshes of 4k x k x k bricks. Prints the table and writes
    /// brick_convergence.svg to --out [default: docs/bench].
    Brick {
        /// Bricks across the section, comma separated (beyond 4 the 20% random distortion warps
        /// some faces past the brick check).
        #[arg(long, value_delimiter = ',', default_values_t = [1, 2, 3, 4])]
        k: Vec<usize>,
    },
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
    /// Size of 3D solves: a clamped cube of n x n x n hybrid bricks per n. The symbolic
    /// analysis gives nnz(L) (the factor's memory) at every size; cubes up to --factor-max
    /// free dofs are also assembled, factored and solved, and their times fitted against dofs.
    BrickScale {
        /// Bricks per side, comma separated.
        #[arg(long, value_delimiter = ',', default_values_t = [10, 20, 30, 40, 50, 60, 70])]
        n: Vec<usize>,
        /// Factor only cubes with at most this many free dofs.
        #[arg(long, default_value_t = 30_000)]
        factor_max: usize,
        /// Memory available to L plus K, GB (decimal), for the largest cube that fits.
        #[arg(long, default_value_t = 24.0)]
        memory_gb: f64,
        /// Orderings of faer's analysis, comma separated: amd, nd (METIS nested dissection),
        /// auto (the one with fewer flops).
        #[arg(long, value_delimiter = ',', default_values = ["amd", "nd"])]
        orderings: Vec<String>,
        /// Orderings (of --orderings) whose factored cubes CHOLMOD also factors with faer's
        /// permutation, comma separated (needs --features suitesparse; one thread: run with
        /// OPENBLAS_NUM_THREADS=1).
        #[arg(long, value_delimiter = ',')]
        cholmod: Vec<String>,
    },
    /// The Hertz scene (a = R/64, calibration + 3 increments; frictionless, then mu = 0.3) at
    /// each refinement: whole contact analysis against one assembly + factorization + solve of K.
    Contact {
        /// Elements per half-width, comma separated (powers of two).
        #[arg(long, value_delimiter = ',', default_values_t = [4, 8, 16, 32, 64])]
        n: Vec<usize>,
        /// Threads of the contact boundary's substitutions (`ContactOptions::threads`; the
        /// floor's factorization and solve are sequential either way).
        #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=256))]
        threads: u32,
    },
    /// Random two-block presses (pressed, slid, the last totals repeated), counted by how the
    /// contact iteration ends with hycon's rules (fallback and cutback) and with the paper's
    /// alone; each failure classified against a reference run in 50 sub-increments per phase.
    Presses {
        /// How many presses per seed.
        #[arg(long, default_value_t = 20_000)]
        count: usize,
        /// Seeds of the draws, comma separated (the full run: 1,2,3,4,5).
        #[arg(long, value_delimiter = ',', default_values_t = [1])]
        seed: Vec<u64>,
        /// `wide` (0.7.0: friction 0.05-1, modulus ratios 1e-4-1e4, meshes up to 32 a side)
        /// or `narrow` (0.6.2's, the distribution of tests/contact_properties.rs).
        #[arg(long, default_value = "wide")]
        ranges: hycon_lab::presses::Ranges,
        /// Run only these presses of each seed's draw (indices from 0, comma separated, as
        /// the report lists the ones the reference settles).
        #[arg(long, value_delimiter = ',')]
        press: Vec<usize>,
        /// Write one line per press to this file (`seed index outcome iterations paper
        /// paper-iterations`, tab separated), to compare two versions press by press.
        #[arg(long)]
        list: Option<std::path::PathBuf>,
    },
    /// The L2 error of the contact pressure against where the Hertz edge falls between two
    /// nodes (frictionless reference scene, small kinematics): the method and the best
    /// approximation on the same nodes, at evenly spaced edge positions within one element.
    Edge {
        /// Elements per half-width, comma separated (powers of two).
        #[arg(long, value_delimiter = ',', default_values_t = [16, 32, 64, 128])]
        n: Vec<usize>,
        /// Edge positions per element.
        #[arg(long, default_value_t = 8)]
        positions: usize,
    },
    /// The same for Hertz's sphere (axisymmetric, frictionless, small kinematics, equal
    /// moduli): the L2 error over r dr against where the contact edge falls, per R/a.
    SphereEdge {
        /// Elements per target contact radius, comma separated (powers of two).
        #[arg(long, value_delimiter = ',', default_values_t = [16, 32, 64])]
        n: Vec<usize>,
        /// R / a, comma separated.
        #[arg(long, value_delimiter = ',', default_values_t = [32, 64])]
        r_over_a: Vec<usize>,
        /// Edge positions per element.
        #[arg(long, default_value_t = 8)]
        positions: usize,
    },
    /// Hertz's sphere in 3D (`hycon_lab::hertz3d`): the quarter paraboloid cap on a block,
    /// frictionless, pressed by Hertz's approach of the target radius, per modulus ratio,
    /// block size and a/h: the contact radius and the peak from the pressure's moments, the
    /// centre node's pressure and the L2 error of the pressure against Hertz at the computed
    /// load; the load against Hertz's for the approach (above it by the finite bodies'
    /// stiffening) and against the finite bodies' reference; the time split against a linear
    /// analysis of the same model; with --radial the pressure along x against hycon's
    /// axisymmetric sphere at the same load.
    Hertz3d {
        /// Faces per target contact radius at the centre, comma separated.
        #[arg(long, value_delimiter = ',', default_values_t = [4, 8])]
        a_over_h: Vec<usize>,
        /// E_cap / E_block, comma separated.
        #[arg(long, value_delimiter = ',', default_values_t = [1.0, 0.01])]
        modulus_ratio: Vec<f64>,
        /// The block's half-width and depth in a, comma separated.
        #[arg(long, value_delimiter = ',', default_values_t = [16.0])]
        block: Vec<f64>,
        /// The cap's half-width and height in a, comma separated (at most 12 at R/a = 16).
        #[arg(long, value_delimiter = ',', default_values_t = [8.0])]
        cap: Vec<f64>,
        /// Also compare the pressure along x with the axisymmetric sphere's.
        #[arg(long)]
        radial: bool,
        /// Runs of the contact analysis and of the linear analysis per row; each time split
        /// the fastest (the errors are the same every run).
        #[arg(long, default_value_t = 1)]
        repeats: usize,
    },
    /// What skipping unneeded work saves, on the reference Hertz scene (frictionless, a = R/64,
    /// calibration + 3 increments): each figure the fastest of --repeats runs.
    Skip {
        /// Elements per half-width.
        #[arg(long, default_value_t = 32)]
        n: usize,
        /// Runs per figure (the fastest is kept).
        #[arg(long, default_value_t = 3)]
        repeats: usize,
    },
    /// Run time against error: the reference Hertz scene (frictionless, a = R/64, calibration
    /// increment + final increment + full-field recovery) for each element / mesh variant /
    /// backend and n = min, 2 min, ..., max elements per half-width, and Hertz's sphere beside
    /// it (axisymmetric, a = R/32, one increment at a^2/R + recovery), each run in a fresh
    /// child process (its own peak memory). Writes sweep.csv, sweep_error_time.svg,
    /// sweep_time_dofs.svg and sweep_summary.md to --out [default: docs/bench].
    Sweep {
        /// Smallest elements per half-width (a power of two).
        #[arg(long, default_value_t = 4)]
        min: usize,
        /// Largest elements per half-width (a power of two, at most 256).
        #[arg(long, default_value_t = 256)]
        max: usize,
        /// Element/mesh configurations: hybrid, pian-sumihara or q4 / transition (5- and
        /// 6-node transition elements, hybrid only) or quads (4-node quadrilaterals only).
        #[arg(
            long,
            value_delimiter = ',',
            default_values = ["hybrid/transition", "hybrid/quads", "pian-sumihara/quads", "q4/quads"]
        )]
        configs: Vec<String>,
        /// Sparse backend(s).
        #[arg(long, value_enum, default_value_t = BackendChoice::Faer)]
        backend: BackendChoice,
        /// Extra runs that re-factor K and rebuild the flexibility every iteration, at these n
        /// (comma separated; 0: none).
        #[arg(long, value_delimiter = ',', default_values_t = [8, 16, 32])]
        refactor_n: Vec<usize>,
        /// R / a of the scene (a power of two; 64 is the reference scene).
        #[arg(long, default_value_t = 64)]
        r_over_a: usize,
        /// Contact kinematics of every case.
        #[arg(long, value_enum, default_value_t = KinematicsChoice::Small)]
        kinematics: KinematicsChoice,
        /// Runs per case (the plots and the summary take the fastest).
        #[arg(long, default_value_t = 1)]
        repeats: usize,
        /// Growth exponents are fitted over the runs with at least this n.
        #[arg(long, default_value_t = 16)]
        fit_min_n: usize,
        /// Hertz's sphere (axisymmetric, R/a = 32, quadrilaterals) beside the disk: its
        /// element/mesh configurations (hybrid/quads, q4/quads; empty: none), same n and
        /// backends.
        #[arg(long, value_delimiter = ',', default_values = ["hybrid/quads"])]
        sphere_configs: Vec<String>,
        /// Do not run anything: re-read this sweep CSV and rewrite the plots and the summary.
        #[arg(long, value_name = "CSV")]
        from_csv: Option<PathBuf>,
    },
    /// One sweep case in this process; prints one CSV row (used by `bench sweep`).
    #[command(hide = true)]
    SweepOne {
        #[arg(long, value_enum, default_value_t = Element::Hybrid)]
        element: Element,
        #[arg(long, value_enum, default_value_t = MeshChoice::Transition)]
        mesh: MeshChoice,
        #[arg(long, default_value_t = 16)]
        n: usize,
        #[arg(long, default_value = "faer")]
        backend: String,
        #[arg(long)]
        refactor: bool,
        #[arg(long)]
        max_element_size: Option<f64>,
        #[arg(long, default_value_t = 64)]
        r_over_a: usize,
        #[arg(long, value_enum, default_value_t = KinematicsChoice::Small)]
        kinematics: KinematicsChoice,
        #[arg(long, default_value = "disk")]
        scene: String,
        /// Also print the CSV header.
        #[arg(long)]
        header: bool,
    },
    /// Cost against size: one configuration at fixed n with the element size capped at
    /// 2^-k radii for each k (uniformly finer far fields, up to and past 1M dofs), each in a
    /// fresh child process; fits time and memory against dofs. Writes contact_scale.csv and
    /// contact_scale.md to --out [default: docs/bench].
    ContactScale {
        /// Elements per half-width.
        #[arg(long, default_value_t = 16)]
        n: usize,
        /// Element/mesh configuration (as for `sweep`).
        #[arg(long, default_value = "hybrid/transition")]
        config: String,
        /// Exponents k of the caps 2^-k (radii); k = 7 gives about 1.1M dofs.
        #[arg(long, value_delimiter = ',', default_values_t = [3, 4, 5, 6, 7])]
        levels: Vec<i32>,
        /// Sparse backends (comma separated: faer, cholmod).
        #[arg(long, value_delimiter = ',', default_values = ["faer"])]
        backend: Vec<String>,
    },
    /// The regression guard: accuracy at fixed meshes against the committed values; fails
    /// (exit 1) when an error got worse. Timings are printed, never checked.
    Guard {
        /// The committed values (`name,value` lines).
        #[arg(long, default_value = "docs/bench/guard.csv")]
        reference: PathBuf,
        /// Write the current values to the reference file instead of checking.
        #[arg(long)]
        write: bool,
    },
    /// Siconos' fc3d solvers (NSN_AC with and without line search, NSN_AC after the
    /// extragradient warm start, NSGS) and hycon's semi-smooth Newton solve side by side on
    /// the same in-memory local problems: the 3D scenes' increments (hertz3d, mindlin3d,
    /// slide3d), the plane disk (hycon only: Siconos' fc3d is 3D) and random well-posed
    /// problems of growing size. Prints the tables, writes siconos_table.md and siconos.json
    /// to --out [default: docs/bench]. Feature `siconos` (links libsiconos_numerics).
    #[cfg(feature = "siconos")]
    Siconos {
        /// Contacts of the random problems, comma separated.
        #[arg(long, value_delimiter = ',', default_values_t = [10, 30, 100, 300])]
        sizes: Vec<usize>,
        /// Faces per contact radius of the hertz3d and mindlin3d caps, comma separated.
        #[arg(long, value_delimiter = ',', default_values_t = [4, 8])]
        a_over_h: Vec<usize>,
        /// Siconos' tolerance on its residual (fc3d_compute_error).
        #[arg(long, default_value_t = 1e-10)]
        tolerance: f64,
        /// Runs per solver and problem (the best time counts; a run over 2 s is not repeated).
        #[arg(long, default_value_t = 3)]
        repeats: usize,
        /// Iterations allowed to Siconos' Newton methods.
        #[arg(long, default_value_t = 1000)]
        newton_iterations: i32,
        /// Sweeps allowed to Siconos' NSGS.
        #[arg(long, default_value_t = 20_000)]
        nsgs_iterations: i32,
        /// Run hycon's rules only on problems of at most this many contacts (up to 200 dense
        /// solves each).
        #[arg(long, default_value_t = 150)]
        rules_max_contacts: usize,
        /// Problem classes, comma separated (hertz3d, mindlin3d, slide3d, plane, random).
        #[arg(long, value_delimiter = ',', default_values = ["hertz3d", "mindlin3d", "slide3d", "plane", "random"])]
        classes: Vec<String>,
    },
}

/// `--kinematics`.
#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum KinematicsChoice {
    /// Small deformation: pairing and contact matrices from the reference configuration,
    /// linear gap.
    Small,
    /// Finite kinematics: geometry at the current positions in every iteration.
    Finite,
}

impl From<KinematicsChoice> for Kinematics {
    fn from(k: KinematicsChoice) -> Self {
        match k {
            KinematicsChoice::Small => Kinematics::Small,
            KinematicsChoice::Finite => Kinematics::Finite,
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum BackendChoice {
    Faer,
    Cholmod,
    All,
}

#[derive(Clone, Copy, ValueEnum)]
enum MeshChoice {
    /// 5- and 6-node transition elements (the reference scene; hybrid only).
    Transition,
    /// 4-node quadrilaterals only.
    Quads,
}

impl From<MeshChoice> for hycon::mesh::generate::Transition {
    fn from(m: MeshChoice) -> Self {
        match m {
            MeshChoice::Transition => Self::Elements,
            MeshChoice::Quads => Self::Quads,
        }
    }
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
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            // usage errors exit with status 1 like every other error; --help and --version
            // print and succeed
            let _ = e.print();
            return if e.use_stderr() {
                ExitCode::FAILURE
            } else {
                ExitCode::SUCCESS
            };
        }
    };
    let out = cli.out;
    let contact_dir = || {
        out.clone()
            .unwrap_or_else(|| Path::new("out").join("contact"))
    };
    let command = cli.command.unwrap_or(Command::Contact {
        n: 32,
        cap: CapOptions::default(),
        output: Output::default(),
    });
    let result = match command {
        Command::Contact { n, cap, output } => {
            main_job(n, &cap.case(&output), output, &contact_dir())
        }
        Command::Sphere3d { cap, output } => several(output, &contact_dir(), |progress| {
            Ok(examples3d(&cap.case(&output), progress)?.into())
        }),
        Command::Hertz {
            n,
            modulus_ratio,
            increments,
            kinematics,
            r_over_a,
            output,
        } => single(output, &contact_dir(), |progress| {
            examples::hertz(
                &HertzCase {
                    n,
                    modulus_ratios: modulus_ratio,
                    increments,
                    kinematics: kinematics.into(),
                    r_over_a,
                    fields: output.fields(),
                },
                progress,
            )
        }),
        Command::Slide {
            n,
            friction,
            increments,
            distance,
            kinematics,
            output,
        } => single(output, &contact_dir(), |progress| {
            examples::slide(
                &SlideCase {
                    n,
                    friction,
                    increments,
                    distance,
                    kinematics: kinematics.into(),
                    fields: output.fields(),
                },
                progress,
            )
        }),
        Command::Cattaneo {
            n,
            friction,
            step,
            target,
            kinematics,
            output,
        } => single(output, &contact_dir(), |progress| {
            examples::cattaneo_mindlin(
                &CattaneoCase {
                    n,
                    friction,
                    step,
                    target,
                    kinematics: kinematics.into(),
                    fields: output.fields(),
                    ..Default::default()
                },
                progress,
            )
        }),
        Command::Sphere {
            n,
            modulus_ratio,
            increments,
            r_over_a,
            output,
        } => single(output, &contact_dir(), |progress| {
            examples::sphere(
                &SphereCase {
                    n,
                    modulus_ratios: modulus_ratio,
                    r_over_a,
                    increments,
                    fields: output.fields(),
                },
                progress,
            )
        }),
        Command::Elements { max_n } => {
            elements_table(max_n, out.as_deref().unwrap_or(Path::new("out")))
        }
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
        Command::Bench { what } => bench(what, out.as_deref()),
        Command::Fclib { what } => fclib::run(what, out.as_deref()),
        Command::Run {
            scene,
            dry_run,
            strict,
        } => run_scene(&scene, dry_run, strict, out.as_deref()),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("hycon: {e}");
            ExitCode::FAILURE
        }
    }
}

type AnyResult<T = ()> = Result<T, Box<dyn std::error::Error>>;

/// `hycon run [--dry-run] [--strict] SCENE`: the dry run's description, or the run's table and
/// files; a step that does not converge fails the command after the files of the converged
/// steps, and under `--strict` so does any warning. `--out DIR` (relative to the working
/// directory) replaces the scene's `[output] dir`.
fn run_scene(path: &Path, dry_run: bool, strict: bool, out: Option<&Path>) -> AnyResult {
    let mut scene = hycon_lab::scenefile::load(path)?;
    if let Some(dir) = out {
        scene.spec.output.dir = Some(std::path::absolute(dir)?);
    }
    let strict_failure = |n: usize| -> AnyResult {
        match (strict, n) {
            (true, 1) => Err("--strict: 1 warning above".into()),
            (true, n) if n > 1 => Err(format!("--strict: {n} warnings above").into()),
            _ => Ok(()),
        }
    };
    if dry_run {
        scene.check_first_solve();
        print!("{}", scene.describe());
        return strict_failure(scene.warnings.len());
    }
    for n in &scene.notes {
        println!("note: {n}");
    }
    for w in &scene.warnings {
        println!("warning: {w}");
    }
    let summary = hycon_lab::scenefile::run(&scene, &mut std::io::stdout())?;
    match summary.error {
        Some(e) => Err(e.into()),
        None => strict_failure(scene.warnings.len() + summary.warnings.len()),
    }
}

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

/// `bench brick`: the table (as in docs/elements.md) and the plot.
/// `hycon bench brick-scale`: per cube and ordering, `nnz(L)`, flops, `L + K` memory, faer's
/// factorization time and rate (and CHOLMOD's with the same permutation), then the largest cube
/// whose `L + K` fits in `memory_gb` per ordering, with its factorization time from the fit
/// `t = c N^p` over the factored cubes.
fn brick_scale(
    ns: &[usize],
    factor_max: usize,
    memory_gb: f64,
    orderings: &[String],
    cholmod: &[String],
) -> AnyResult {
    use hycon::solver::OrderingRule;
    let rules = orderings
        .iter()
        .map(|o| match o.as_str() {
            "amd" => Ok(OrderingRule::Amd),
            "nd" => Ok(OrderingRule::NestedDissection),
            "auto" => Ok(OrderingRule::Auto),
            other => Err(format!("--orderings: {other} is not amd, nd or auto")),
        })
        .collect::<Result<Vec<_>, _>>()?;
    if let Some(o) = cholmod.iter().find(|o| !orderings.contains(o)) {
        return Err(format!("--cholmod: {o} is not one of --orderings").into());
    }
    if !cholmod.is_empty() && !hycon::solver::Backend::Cholmod.available() {
        return Err("--cholmod needs hycon built with --features suitesparse".into());
    }
    let with_cholmod: Vec<bool> = orderings.iter().map(|o| cholmod.contains(o)).collect();
    match hycon::solver::ordering::metis_status() {
        Ok(bits) => println!("METIS: libmetis.so.5 loaded, {bits}-bit idx_t"),
        Err(e) => println!("METIS: {e}"),
    }
    println!(
        "| n | free dofs | ordering | nnz(L) | flops | L+K GB | analysis s | faer factorization s | faer Gflop/s | CHOLMOD nnz(L) | CHOLMOD flops | CHOLMOD factorization s | CHOLMOD Gflop/s | solve s | peak RSS GB |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    let seconds = |t: Option<f64>| t.map_or("-".into(), |t| format!("{t:.2}"));
    let rate =
        |flops: f64, t: Option<f64>| t.map_or("-".into(), |t| format!("{:.2}", flops / t * 1e-9));
    // per ordering: factored (dofs, seconds) and the largest cube that fits
    let mut factored = vec![Vec::new(); rules.len()];
    let mut largest = vec![None; rules.len()];
    for &n in ns {
        let dofs = 3 * n * (n + 1) * (n + 1);
        let (n_free, nnz_k, runs) =
            hycon_lab::bench::brick_scale_run(n, &rules, dofs <= factor_max, &with_cholmod)?;
        for (k, r) in runs.iter().enumerate() {
            // L: 8-byte values; K: 8-byte values and 8-byte row indices
            let gb = (r.nnz_l * 8 + nnz_k * 16) as f64 * 1e-9;
            println!(
                "| {n} | {n_free} | {} | {:.3e} | {:.2e} | {gb:.2} | {:.2} | {} | {} | {} | {} | {} | {} | {} | {} |",
                r.ordering,
                r.nnz_l as f64,
                r.flops,
                r.analysis,
                seconds(r.factorization),
                rate(r.flops, r.factorization),
                r.cholmod_flops
                    .map_or("-".into(), |(_, nnz)| format!("{:.3e}", nnz as f64)),
                r.cholmod_flops
                    .map_or("-".into(), |(fl, _)| format!("{fl:.2e}")),
                seconds(r.cholmod),
                rate(r.cholmod_flops.map_or(r.flops, |(fl, _)| fl), r.cholmod),
                seconds(r.solve),
                r.peak_memory
                    .map_or("n/a".into(), |b| format!("{:.2}", b as f64 * 1e-9))
            );
            if let Some(t) = r.factorization {
                factored[k].push((n_free as f64, t));
            }
            if gb <= memory_gb && largest[k].is_none_or(|(m, _, _)| n > m) {
                largest[k] = Some((n, n_free, gb));
            }
        }
        if let (Some(a), Some(b)) = (runs.first(), runs.get(1)) {
            println!(
                "  n = {n}: {} / {}: nnz(L) x{:.3}, flops x{:.3}{}",
                b.ordering,
                a.ordering,
                b.nnz_l as f64 / a.nnz_l as f64,
                b.flops / a.flops,
                match (a.factorization, b.factorization) {
                    (Some(ta), Some(tb)) => format!(", factorization {:.2}x faster", ta / tb),
                    _ => String::new(),
                }
            );
        }
    }
    if !cholmod.is_empty() {
        println!(
            "CHOLMOD's BLAS: {}",
            hycon_lab::bench::blas_libraries().join(", ")
        );
    }
    for (k, fits) in largest.iter().enumerate() {
        let Some((n, dofs, gb)) = fits else { continue };
        print!(
            "{}: largest cube whose L + K fits in {memory_gb} GB: n = {n}, {dofs} free dofs, {gb:.2} GB",
            orderings[k]
        );
        match hycon_lab::bench::fit_power(&factored[k]) {
            Some((p, c, _)) => println!(
                "; factorization time fitted as {c:.3e} N^{p:.2} over the factored sizes: about {:.0} s",
                c * (*dofs as f64).powf(p)
            ),
            None => println!(),
        }
    }
    Ok(())
}

fn brick(ks: &[usize], out: &Path) -> AnyResult {
    if ks.iter().any(|&k| k == 0 || k > 16) {
        return Err("--k: bricks across the section must be 1..=16".into());
    }
    let runs = hycon_lab::bench::brick_convergence(ks)?;
    println!("| mesh | dofs | hybrid18 | h8 |");
    println!("|---|---|---|---|");
    for distorted in [false, true] {
        for &k in ks {
            let find = |e: &str| {
                runs.iter()
                    .find(|r| r.element == e && r.distorted == distorted && r.k == k)
            };
            if let (Some(h), Some(d)) = (find("hybrid18"), find("h8")) {
                println!(
                    "| {} {}x{k}x{k} | {} | {:.2e} | {:.2e} |",
                    if distorted { "distorted" } else { "regular" },
                    4 * k,
                    h.dofs,
                    h.error,
                    d.error
                );
            }
        }
    }
    std::fs::create_dir_all(out)?;
    let path = out.join("brick_convergence.svg");
    std::fs::write(&path, hycon_lab::bench::brick_convergence_svg(&runs)?)?;
    println!("written: {}", path.display());
    Ok(())
}

/// `bench edge`: a row per run and a summary per n.
fn edge(ns: &[usize], positions: usize) -> AnyResult {
    println!(
        "{:>4} {:>8} {:>5} {:>8} {:>8} {:>6} {:>8} {:>8} {:>8}",
        "n", "a_H/h", "edge", "L2 %", "best %", "ratio", "active %", "a %", "p0 %"
    );
    for &n in ns {
        let runs = hycon_lab::bench::edge_sweep(n, positions)?;
        for r in &runs {
            println!(
                "{:>4} {:>8.3} {:>5.2} {:>8.4} {:>8.4} {:>6.2} {:>8.4} {:>+8.4} {:>+8.4}",
                r.n,
                r.half_width_over_h,
                r.edge_position(),
                100.0 * r.l2_error,
                100.0 * r.best_l2_error,
                r.l2_error / r.best_l2_error,
                100.0 * r.best_active_l2_error,
                100.0 * r.half_width_error,
                100.0 * r.peak_error
            );
        }
        let stats = |f: &dyn Fn(&hycon_lab::bench::EdgeRun) -> f64| {
            let v: Vec<f64> = runs.iter().map(f).collect();
            let mean = v.iter().sum::<f64>() / v.len() as f64;
            let (lo, hi) = v
                .iter()
                .fold((f64::INFINITY, 0.0f64), |(l, h), x| (l.min(*x), h.max(*x)));
            (mean, lo, hi)
        };
        let (m, lo, hi) = stats(&|r| 100.0 * r.l2_error);
        let (bm, blo, bhi) = stats(&|r| 100.0 * r.best_l2_error);
        let (am, alo, ahi) = stats(&|r| 100.0 * r.best_active_l2_error);
        println!(
            "n = {n}: L2 mean {m:.3}% (min {lo:.3}, max {hi:.3}); best approximation mean {bm:.3}% (min {blo:.3}, max {bhi:.3}); with the contact set mean {am:.3}% (min {alo:.3}, max {ahi:.3})"
        );
    }
    Ok(())
}

/// `hycon bench siconos`: the problems of each class in turn, a line per problem as it is
/// done, then both tables; writes siconos_table.md and siconos.json to `out`.
#[cfg(feature = "siconos")]
fn siconos(
    classes: &[String],
    sizes: &[usize],
    a_over_h: &[usize],
    settings: &hycon_lab::siconos_bench::BenchSettings,
    out: &Path,
) -> AnyResult {
    use hycon_lab::local_problems;
    use hycon_lab::siconos_bench::{compare, full_table, summary_table};
    let mut runs = Vec::new();
    for class in classes {
        let problems = match class.as_str() {
            "hertz3d" | "mindlin3d" => {
                let mut all = Vec::new();
                for &a in a_over_h {
                    all.extend(match class.as_str() {
                        "hertz3d" => local_problems::hertz3d(a)?,
                        _ => local_problems::mindlin3d(a)?,
                    });
                }
                all
            }
            "slide3d" => local_problems::slide3d()?,
            "plane" => local_problems::plane()?,
            "random" => local_problems::randoms(sizes, 1),
            other => return Err(format!("unknown problem class {other:?}").into()),
        };
        for p in &problems {
            let r = compare(p, settings);
            let times: Vec<String> = (r.runs.iter())
                .map(|s| format!("{} {:.3} ms", s.solver, s.seconds * 1e3))
                .collect();
            println!(
                "{}/{} ({} contacts): {}",
                r.class,
                r.name,
                r.contacts,
                times.join(", ")
            );
            runs.push(r);
        }
    }
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    let threads = std::env::var("OPENBLAS_NUM_THREADS").unwrap_or_else(|_| "unset".into());
    let head = format!(
        "tolerance {:e}, best of {} runs; load average {}; BLAS mapped: {}; \
         OPENBLAS_NUM_THREADS {threads}\n",
        settings.tolerance,
        settings.repeats,
        load.split_whitespace()
            .take(3)
            .collect::<Vec<_>>()
            .join(" "),
        hycon_lab::bench::blas_libraries().join(", ")
    );
    let table = format!("{head}\n{}\n{}", summary_table(&runs), full_table(&runs));
    println!("\n{table}");
    std::fs::create_dir_all(out)?;
    std::fs::write(out.join("siconos_table.md"), &table)?;
    std::fs::write(
        out.join("siconos.json"),
        serde_json::to_string_pretty(&runs)?,
    )?;
    println!(
        "written: {}, {}",
        out.join("siconos_table.md").display(),
        out.join("siconos.json").display()
    );
    Ok(())
}

/// `hycon bench hertz3d`: one row per modulus ratio, cap and block size (`[caps, blocks]`)
/// and a/h, each followed by the time split, the fastest of `repeats` runs of each analysis
/// (and the radial comparison with `radial`).
fn hertz3d(
    a_over_h: &[usize],
    ratios: &[f64],
    [caps, blocks]: [&[f64]; 2],
    radial: bool,
    repeats: usize,
) -> AnyResult {
    use hycon::solid::contact_meshes::{CapModel, CapOnBlock};
    use hycon_lab::hertz3d::QuarterCap;
    let sizes = caps
        .iter()
        .flat_map(|&c| blocks.iter().map(move |&b| (c, b)));
    for &ratio in ratios {
        for (cap_extent, block) in sizes.clone() {
            println!(
                "E_cap/E_block = {ratio:e}, block {block} a wide and deep, cap {cap_extent} a"
            );
            println!(
                "{:>4} {:>7} {:>7} {:>5} {:>8} {:>8} {:>8} {:>7} {:>9} {:>8} {:>8} {:>8} {:>7}",
                "a/h",
                "dofs",
                "active",
                "iters",
                "a %",
                "p0 %",
                "p(0) %",
                "L2 %",
                "p(<a/2)%",
                "P-PH %",
                "cP/d %",
                "P-P* %",
                "seconds"
            );
            for &n in a_over_h {
                let spec = CapOnBlock {
                    block_extent: block,
                    cap_extent,
                    ..CapOnBlock::new(CapModel::Quarter, n)
                };
                // the errors are the same every run: the last run's kept, the fastest times
                let mut runs = Vec::new();
                let mut last = None;
                for _ in 0..repeats.max(1) {
                    drop(last.take()); // one model in memory at a time
                    let mut cap = QuarterCap::with(spec, ratio, Default::default())?;
                    let c = cap.press()?;
                    let linear = cap.linear(c.load)?;
                    runs.push((cap.analysis.timings(), linear));
                    last = Some((cap, c));
                }
                let (cap, c) = last.expect("one run at least");
                let phases = (runs.iter().map(|r| r.0))
                    .min_by(|a, b| a.total().total_cmp(&b.total()))
                    .expect("one run at least");
                let linear = (runs.iter().map(|r| r.1))
                    .min_by(|a, b| a.total().total_cmp(&b.total()))
                    .expect("one run at least");
                let seconds = phases.total();
                let check = cap.load_check(&c, &linear);
                let [radius, peak, load] = c.errors().map(|e| 100.0 * e);
                println!(
                    "{n:>4} {:>7} {:>7} {:>5} {radius:>+8.3} {:>+8.3} {peak:>+8.3} {:>7.3} \
                     {:>9.3} {load:>+8.3} {:>+8.3} {:>+8.3} {seconds:>7.2}",
                    3 * cap.mesh.mesh.n_nodes(),
                    c.active,
                    c.iterations,
                    100.0 * c.peak_error(),
                    100.0 * c.l2_error,
                    100.0 * c.interior,
                    100.0 * check.finite_share / check.approach,
                    100.0 * check.error(),
                );
                print_time_split(
                    &hycon_lab::hertz3d::time_split(phases, &linear),
                    &format!(
                        "; ordering {}, nnz(L) {:.3e}, fastest of {}",
                        linear.ordering,
                        linear.nnz_l as f64,
                        repeats.max(1)
                    ),
                );
                if radial {
                    print_radial(&cap.radial_comparison(&c)?, &c);
                }
            }
        }
    }
    Ok(())
}

/// The pressure along x against the axisymmetric sphere's: one line per node, the largest
/// difference.
fn print_radial(r: &hycon_lab::hertz3d::RadialComparison, c: &hycon_lab::hertz3d::CapComparison) {
    let p0 = c.hertz.peak;
    println!(
        "   along x against the axisymmetric sphere at P_axi/P - 1 = {:+.1e} (its a {:+.3}%, p0 \
         {:+.3}%, L2 {:.3}%; nodes {:.1e} h apart):",
        r.load_mismatch(),
        100.0 * (r.axisymmetric.radius / r.axisymmetric.hertz.radius - 1.0),
        100.0 * (r.axisymmetric.peak_from_moments / r.axisymmetric.hertz.peak - 1.0),
        100.0 * r.axisymmetric.l2_error,
        r.offset
    );
    println!(
        "   {:>7} {:>9} {:>9} {:>9} {:>9}",
        "x/a", "p3d/p0", "paxi/p0", "pH/p0", "diff/p0"
    );
    for [x, p3, pa, ph] in &r.rows {
        println!(
            "   {:>7.4} {:>9.5} {:>9.5} {:>9.5} {:>+9.5}",
            x / c.hertz.radius,
            p3 / p0,
            pa / p0,
            ph / p0,
            (p3 - pa) / p0
        );
    }
    println!("   largest |p3d - paxi| / p0 = {:.4}", r.max_difference(p0));
}

/// `bench sphere-edge`: a row per run, a summary per n and R/a, the rate over n per R/a.
fn sphere_edge(ns: &[usize], r_over_a: &[usize], positions: usize) -> AnyResult {
    println!(
        "{:>4} {:>4} {:>8} {:>5} {:>8} {:>8} {:>8} {:>8}",
        "R/a", "n", "a_H/h", "edge", "L2 %", "a %", "p0 %", "p(0) %"
    );
    for &ratio in r_over_a {
        let mut means = Vec::new();
        for &n in ns {
            let runs = hycon_lab::axisymmetric::SphereOnBlock {
                elements_per_radius: n,
                radius_over_contact: ratio as f64,
                modulus_ratio: 1.0,
            }
            .edge_sweep(positions)?;
            for r in &runs {
                let c = &r.comparison;
                println!(
                    "{ratio:>4} {n:>4} {:>8.3} {:>5.2} {:>8.4} {:>+8.4} {:>+8.4} {:>+8.4}",
                    r.radius_over_h,
                    r.edge_position(),
                    100.0 * c.l2_error,
                    100.0 * (c.radius / c.hertz.radius - 1.0),
                    100.0 * (c.peak_from_moments / c.hertz.peak - 1.0),
                    100.0 * (c.peak / c.hertz.peak - 1.0),
                );
            }
            let l2: Vec<f64> = runs.iter().map(|r| 100.0 * r.comparison.l2_error).collect();
            let mean = l2.iter().sum::<f64>() / l2.len() as f64;
            let (lo, hi) = l2
                .iter()
                .fold((f64::INFINITY, 0.0f64), |(l, h), x| (l.min(*x), h.max(*x)));
            println!("R/a = {ratio}, n = {n}: L2 mean {mean:.3}% (min {lo:.3}, max {hi:.3})");
            means.push((n as f64, mean));
        }
        if let Some((rate, _, _)) = hycon_lab::bench::fit_power(&means) {
            println!(
                "R/a = {ratio}: rate of the mean over n (least squares) {:.2}",
                -rate
            );
        }
    }
    Ok(())
}

fn bench(what: Bench, out: Option<&Path>) -> AnyResult {
    let out = out.unwrap_or(Path::new("docs/bench"));
    match what {
        Bench::Brick { k } => brick(&k, out)?,
        Bench::BrickScale {
            n,
            factor_max,
            memory_gb,
            orderings,
            cholmod,
        } => brick_scale(&n, factor_max, memory_gb, &orderings, &cholmod)?,
        Bench::Sweep {
            min,
            max,
            configs,
            backend,
            refactor_n,
            r_over_a,
            kinematics,
            repeats,
            fit_min_n,
            sphere_configs,
            from_csv,
        } => {
            let plan = SweepPlan {
                min,
                max,
                configs,
                sphere_configs,
                backend,
                refactor_n,
                r_over_a,
                kinematics: kinematics.into(),
                repeats,
            };
            sweep(&plan, fit_min_n, from_csv.as_deref(), out)?
        }
        Bench::SweepOne {
            element,
            mesh,
            n,
            backend,
            refactor,
            max_element_size,
            r_over_a,
            kinematics,
            scene,
            header,
        } => {
            let case = hycon_lab::bench::SweepCase {
                scene: hycon_lab::bench::SweepScene::parse(&scene)
                    .ok_or_else(|| format!("unknown scene {scene:?} (disk, sphere)"))?,
                formulation: element.into(),
                transition: mesh.into(),
                n,
                backend: hycon_lab::bench::parse_backend(&backend)
                    .ok_or_else(|| format!("unknown backend {backend:?}"))?,
                refactor,
                max_element_size,
                radius_over_half_width: r_over_a,
                kinematics: kinematics.into(),
            };
            let run = hycon_lab::bench::sweep_run(&case)?;
            if header {
                println!("{}", hycon_lab::bench::SWEEP_CSV_HEADER);
            }
            println!("{}", run.csv_row());
        }
        Bench::ContactScale {
            n,
            config,
            levels,
            backend,
        } => contact_scale(n, &config, &levels, &backend, out)?,
        Bench::Kernels { repeats } => {
            println!("element stiffness kernel, {repeats} evaluations each:");
            for k in hycon_lab::bench::kernel_times(repeats)? {
                println!("  {:<26} {:>8.0} ns/element", k.kind, k.nanoseconds);
            }
        }
        Bench::Skip { n, repeats } => {
            println!("| skipped | with the skip (s) | without (s) | saving | what is timed |");
            println!("|---|---|---|---|---|");
            for r in hycon_lab::bench::skip_table(n, repeats)? {
                println!(
                    "| {} | {:.4} | {:.4} | {:.1}x | {} |",
                    r.what,
                    r.with_skip,
                    r.without,
                    r.without / r.with_skip,
                    r.measured
                );
            }
        }
        Bench::Guard { reference, write } => guard(&reference, write)?,
        #[cfg(feature = "siconos")]
        Bench::Siconos {
            sizes,
            a_over_h,
            tolerance,
            repeats,
            newton_iterations,
            nsgs_iterations,
            rules_max_contacts,
            classes,
        } => {
            let settings = hycon_lab::siconos_bench::BenchSettings {
                tolerance,
                repeats,
                newton_iterations,
                nsgs_iterations,
                rules_max_contacts,
            };
            siconos(&classes, &sizes, &a_over_h, &settings, out)?
        }
        Bench::Edge { n, positions } => edge(&n, positions)?,
        Bench::SphereEdge {
            n,
            r_over_a,
            positions,
        } => sphere_edge(&n, &r_over_a, positions)?,
        Bench::Hertz3d {
            a_over_h,
            modulus_ratio,
            block,
            cap,
            radial,
            repeats,
        } => hertz3d(&a_over_h, &modulus_ratio, [&cap, &block], radial, repeats)?,
        Bench::Presses {
            count,
            seed,
            ranges,
            press,
            list,
        } => {
            let mut lines = String::new();
            for seed in seed {
                let presses: Vec<_> = hycon_lab::presses::Press::draw_from(ranges, count, seed)
                    .into_iter()
                    .enumerate()
                    .filter(|(i, _)| press.is_empty() || press.contains(i))
                    .collect();
                let outcomes = hycon_lab::presses::outcomes(&presses);
                presses_report(&outcomes, ranges, seed);
                for line in &outcomes.listing {
                    lines.push_str(&format!("{seed}\t{line}\n"));
                }
            }
            if let Some(path) = list {
                std::fs::write(&path, lines)?;
                println!("written: {}", path.display());
            }
        }
        Bench::Contact { n, threads } => {
            println!("threads: {threads}");
            println!(
                "{:>4} {:>4} {:>7} {:>8} {:>9} {:>9} {:>6} {:>7} {:>5} | assembly factor flexib. loads iter.",
                "n", "mu", "dofs", "contact", "contact s", "floor s", "ratio", "L2", "iters"
            );
            for friction in [0.0, 0.3] {
                for &n in &n {
                    let r = hycon_lab::bench::contact_run(n, friction, threads as usize)?;
                    let t = r.timings;
                    println!(
                        "{:>4} {:>4} {:>7} {:>8} {:>9.4} {:>9.4} {:>6.2} {:>6.2}% {:>5} | {:.4} {:.4} {:.4} {:.4} {:.4}",
                        r.n,
                        r.friction,
                        r.dofs,
                        r.contact_dofs,
                        r.contact_seconds,
                        r.floor_seconds,
                        r.contact_seconds / r.floor_seconds,
                        100.0 * r.l2_error,
                        r.iterations,
                        t.assembly,
                        t.factorization,
                        t.flexibility,
                        t.load_solves,
                        t.iterations
                    );
                }
            }
        }
        Bench::Scale { n } => {
            let r = hycon_lab::bench::scale_run(n)?;
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

/// Progress lines on stderr, with the elapsed time, once `after` seconds have passed (short runs
/// stay quiet).
fn progress_printer(start: Instant, after: f64) -> impl FnMut(&str) {
    move |message: &str| {
        let t = start.elapsed().as_secs_f64();
        if t >= after {
            eprintln!("[{t:6.1} s] {message}");
        }
    }
}

/// One contact example alone (`hycon hertz | slide | cattaneo | sphere`).
fn single(
    output: Output,
    dir: &Path,
    run: impl FnOnce(examples::Progress<'_>) -> hycon::Result<Example>,
) -> AnyResult {
    several(output, dir, |progress| Ok(vec![run(progress)?]))
}

/// Contact examples without the main job's overview (`hycon sphere3d`, and [`single`]):
/// `--json` prints one example as a JSON object, several as an array.
fn several(
    output: Output,
    dir: &Path,
    run: impl FnOnce(examples::Progress<'_>) -> hycon::Result<Vec<Example>>,
) -> AnyResult {
    let mut progress = progress_printer(Instant::now(), 1.0);
    let all = run(Some(&mut progress))?;
    let mut files = Vec::new();
    if !output.no_files {
        for example in &all {
            files.extend(write_files(dir, example, output.every_increment)?);
        }
    }
    if output.json {
        let text = match all.as_slice() {
            [one] => report::json::to_string(one)?,
            _ => report::json::to_string(&all)?,
        };
        println!("{text}");
    } else {
        for example in &all {
            print_example(example);
        }
    }
    say_written(dir, &files, output.json);
    Ok(())
}

/// What the main job writes into `summary.json`.
#[derive(Serialize)]
struct Summary<'a> {
    program: &'static str,
    version: &'static str,
    elements_per_half_width: usize,
    seconds: f64,
    examples: &'a [Example],
}

/// The main job's sliding example: pressed, then moved 2a in 8 increments.
fn main_slide(n: usize, friction: f64, output: &Output) -> SlideCase {
    SlideCase {
        n,
        friction,
        increments: 8,
        distance: 2.0,
        fields: output.fields(),
        ..Default::default()
    }
}

/// The main job: the four contact examples, the axisymmetric one and the two 3D ones
/// (`cap`), tables, time split, files.
fn main_job(n: usize, cap: &CapCase, output: Output, dir: &Path) -> AnyResult {
    let start = Instant::now();
    let mut progress = progress_printer(start, 0.0);
    let plane = [
        examples::hertz(
            &HertzCase {
                n,
                fields: output.fields(),
                ..Default::default()
            },
            Some(&mut progress),
        )?,
        examples::slide(&main_slide(n, 0.0, &output), Some(&mut progress))?,
        examples::slide(&main_slide(n, 0.3, &output), Some(&mut progress))?,
        examples::cattaneo_mindlin(
            &CattaneoCase {
                n,
                fields: output.fields(),
                ..Default::default()
            },
            Some(&mut progress),
        )?,
        examples::sphere(
            &SphereCase {
                n,
                fields: output.fields(),
                ..Default::default()
            },
            Some(&mut progress),
        )?,
    ];
    let all: Vec<Example> = plane
        .into_iter()
        .chain(examples3d(cap, Some(&mut progress))?)
        .collect();
    let seconds = start.elapsed().as_secs_f64();
    let mut files = Vec::new();
    if !output.no_files {
        for example in &all {
            progress(&format!("writing the plot and fields of {}", example.name));
            files.extend(write_files(dir, example, output.every_increment)?);
        }
    }
    let summary = Summary {
        program: "hycon",
        version: env!("CARGO_PKG_VERSION"),
        elements_per_half_width: n,
        seconds,
        examples: &all,
    };
    if !output.no_files {
        let path = dir.join("summary.json");
        report::json::write(&path, &summary)?;
        files.push(path);
    }
    if output.json {
        println!("{}", report::json::to_string(&summary)?);
    } else {
        for example in &all {
            print_example(example);
        }
        print_overview(&all, seconds);
    }
    say_written(dir, &files, output.json);
    Ok(())
}

impl Output {
    /// The displacement fields the files need (each costs one solve).
    fn fields(&self) -> Fields {
        if self.no_files {
            Fields::None
        } else if self.every_increment {
            Fields::Every
        } else {
            Fields::Final
        }
    }
}

/// The SVG plot and the VTU fields of `example` into `dir`.
fn write_files(dir: &Path, example: &Example, every_increment: bool) -> AnyResult<Vec<PathBuf>> {
    let svg = dir.join(format!("{}.svg", example.name));
    report::svg::write(&svg, example)?;
    let mut files = vec![svg];
    files.extend(report::vtu::write_example(dir, example, every_increment)?);
    Ok(files)
}

fn say_written(dir: &Path, files: &[PathBuf], to_stderr: bool) {
    if files.is_empty() {
        return;
    }
    let count = |ext: &str| {
        files
            .iter()
            .filter(|f| f.extension().is_some_and(|e| e == ext))
            .count()
    };
    let names: Vec<String> = files
        .iter()
        .filter(|f| f.extension().is_some_and(|e| e == "svg" || e == "json"))
        .filter_map(|f| f.file_name().map(|n| n.to_string_lossy().into_owned()))
        .collect();
    let line = format!(
        "written to {}: {} ({} .vtu fields{})",
        dir.display(),
        names.join(", "),
        count("vtu"),
        if count("pvd") > 0 {
            format!(", {} .pvd collections for ParaView", count("pvd"))
        } else {
            String::new()
        }
    );
    if to_stderr {
        eprintln!("{line}");
    } else {
        println!("{line}");
    }
}

fn pct(x: f64) -> String {
    format!("{:+.2}%", 100.0 * x)
}

/// The table of one example: one block per run, one row per increment, then the time split.
fn print_example(example: &Example) {
    println!();
    println!("== {}: {}", example.name, example.title);
    for run in &example.runs {
        print_run(run);
    }
}

fn print_run(run: &Run) {
    let s = &run.setup;
    let a = s.target_half_width;
    let friction = s.friction > 0.0;
    println!(
        "-- {}: {} nodes, {} elements, {} dofs, {} + {} contact nodes; R = {}, a = R/{} = {:.4e}, \
         h = a/{}, E* = {:.4}, nu = {}, mu = {}",
        run.label,
        s.nodes,
        s.elements,
        s.dofs,
        s.contact_nodes[0],
        s.contact_nodes[1],
        s.radius,
        (s.radius / a).round(),
        a,
        s.elements_per_half_width,
        s.e_star,
        s.poisson,
        s.friction
    );
    match &run.calibration {
        Some(c) => println!(
            "   calibration: trial approach {:.4e} ({} iterations) -> approach {:.4e} (Hertz load for a)",
            c.trial_approach, c.iterations, c.approach
        ),
        None => println!(
            "   approach a^2/R = {:.4e} (Hertz's for the target a; no calibration)",
            a * a / s.radius
        ),
    }
    let mut head = format!(
        "   {:>3} {:>5} {:>9} {:>7} | {:>3} {:>4} {:>4} | {:>10} {:>8} {:>8} {:>8} {:>8} | {:>7}",
        "inc",
        "phase",
        "approach",
        "slide/a",
        "it",
        "act",
        "slip",
        "P",
        "a-aH",
        "p0-p0H",
        "L2 mult",
        "L2 force",
        "Q/P"
    );
    if friction {
        head += &format!(
            " {:>7} {:>8} {:>6} {:>6} {:>7}",
            "Q/muP", "L2 shear", "c/a", "cCM/a", "dc/a"
        );
    }
    head += &format!(" | {:>9}", "time");
    println!("{head}");
    for inc in &run.increments {
        let h = &inc.hertz;
        let phase = match inc.phase {
            examples::Phase::Press => "press",
            examples::Phase::Slide => "slide",
        };
        let mut row = format!(
            "   {:>3} {:>5} {:>9.3e} {:>7.3} | {:>3} {:>4} {:>4} | {:>10.4e} {:>8} {:>8} {:>8} {:>8} | {:>+7.4}",
            inc.number,
            phase,
            inc.approach,
            inc.slide / a,
            inc.iterations,
            inc.active,
            inc.slip,
            inc.load,
            pct(h.half_width_error),
            pct(h.peak_error),
            format!("{:.2}%", 100.0 * h.l2_error),
            format!("{:.2}%", 100.0 * h.l2_error_forces),
            inc.q_over_p
        );
        if friction {
            let ratio = inc.q_over_mu_p.map_or("-".into(), |r| format!("{r:.4}"));
            let shear = inc
                .shear_l2_error
                .map_or("-".into(), |e| format!("{:.2}%", 100.0 * e));
            let (c, ccm, dc) = inc
                .stick_zone
                .map_or(("-".into(), "-".into(), "-".into()), |z| {
                    (
                        format!("{:.3}", z.measured / a),
                        format!("{:.3}", z.predicted / a),
                        format!("{:+.3}", z.error),
                    )
                });
            row += &format!(" {ratio:>7} {shear:>8} {c:>6} {ccm:>6} {dc:>7}");
        }
        row += &format!(" | {:>7.4} s", inc.seconds);
        println!("{row}");
    }
    print_time_split(&run.timings, " (calibration included)");
}

/// The time split of an analysis against a linear analysis of the same model, two lines
/// (`note` after the increment count).
fn print_time_split(t: &hycon_lab::examples::TimeSplit, note: &str) {
    let p = &t.phases;
    println!(
        "   time: assembly {:.3} s, factorization {:.3} s ({}x), flexibility {:.3} s, load solves \
         {:.3} s, iterations {:.3} s, recovery {:.3} s; total {:.3} s over {} increments{note}",
        p.assembly,
        p.factorization,
        t.factorizations,
        p.flexibility,
        p.load_solves,
        p.iterations,
        p.recovery,
        t.total,
        t.increments
    );
    println!(
        "         = {:.1} x a linear analysis of the same model (assembly + factorization + one \
         solve, timed separately: {:.3} s, of which the solve {:.4} s)",
        t.ratio, t.linear, t.one_solve
    );
}

/// One line per run: the worst errors and the cost.
fn print_overview(all: &[Example], seconds: f64) {
    println!();
    println!("== overview (worst increment of each run; ratio = analysis / linear analysis)");
    println!(
        "   {:<18} {:<28} {:>4} {:>5} {:>8} {:>8} {:>8} {:>8} {:>9} {:>8} {:>6}",
        "example",
        "run",
        "inc",
        "iters",
        "a-aH",
        "p0-p0H",
        "L2 mult",
        "L2 force",
        "max|dc|/a",
        "time",
        "ratio"
    );
    for example in all {
        for run in &example.runs {
            let worst = |f: &dyn Fn(&examples::Increment) -> f64| {
                run.increments.iter().map(f).fold(
                    0.0f64,
                    |m, v| {
                        if v.abs() > m.abs() { v } else { m }
                    },
                )
            };
            let dc = run
                .increments
                .iter()
                .filter_map(|i| i.stick_zone.map(|z| z.error.abs()))
                .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))));
            println!(
                "   {:<18} {:<28} {:>4} {:>5} {:>8} {:>8} {:>8} {:>8} {:>9} {:>7.3}s {:>6.1}",
                example.name,
                run.label,
                run.increments.len(),
                run.increments.iter().map(|i| i.iterations).sum::<usize>(),
                pct(worst(&|i| i.hertz.half_width_error)),
                pct(worst(&|i| i.hertz.peak_error)),
                format!("{:.2}%", 100.0 * worst(&|i| i.hertz.l2_error)),
                format!("{:.2}%", 100.0 * worst(&|i| i.hertz.l2_error_forces)),
                dc.map_or("-".into(), |d| format!("{d:.3}")),
                run.timings.total,
                run.timings.ratio
            );
        }
    }
    println!("   all examples: {seconds:.2} s");
}

/// Compare the guard values with the committed ones (worse by more than 1e-6 relative fails:
/// round-off across machines stays far below that) or write them.
fn guard(reference: &Path, write: bool) -> AnyResult {
    let clock = Instant::now();
    let values = hycon_lab::bench::guard_values()?;
    println!(
        "regression guard computed in {:.2} s (printed, not checked)",
        clock.elapsed().as_secs_f64()
    );
    if write {
        let text: String = values
            .iter()
            .map(|v| format!("{},{:.17e}\n", v.name, v.value))
            .collect();
        std::fs::write(reference, text)?;
        println!("written: {}", reference.display());
        return Ok(());
    }
    let committed = std::fs::read_to_string(reference)
        .map_err(|e| format!("cannot read {}: {e}", reference.display()))?;
    let mut worse = Vec::new();
    for v in hycon_lab::bench::guard_verdicts(values.clone(), &committed)? {
        let verdict = if v.worse() { "WORSE" } else { "ok" };
        println!(
            "  {:<32} committed {:.6e}  now {:.6e}  {verdict}",
            v.now.name, v.committed, v.now.value
        );
        if v.worse() {
            worse.push(v.now.name);
        }
    }
    if worse.is_empty() {
        println!("regression guard: {} values, none worse", values.len());
        Ok(())
    } else {
        Err(format!("regression guard: worse than committed: {worse:?}").into())
    }
}

/// What `hycon bench sweep` runs.
struct SweepPlan {
    min: usize,
    max: usize,
    configs: Vec<String>,
    sphere_configs: Vec<String>,
    backend: BackendChoice,
    refactor_n: Vec<usize>,
    r_over_a: usize,
    kinematics: Kinematics,
    repeats: usize,
}

/// Parse `element/mesh` into a case at `n` (faer, factor once).
fn parse_config(config: &str, n: usize) -> AnyResult<hycon_lab::bench::SweepCase> {
    let (e, m) = config
        .split_once('/')
        .ok_or_else(|| format!("configuration {config:?} is not element/mesh"))?;
    Ok(hycon_lab::bench::SweepCase {
        formulation: hycon_lab::bench::parse_formulation(e)
            .ok_or_else(|| format!("unknown element {e:?} (hybrid, pian-sumihara, q4)"))?,
        transition: hycon_lab::bench::parse_mesh(m)
            .ok_or_else(|| format!("unknown mesh {m:?} (transition, quads)"))?,
        ..hycon_lab::bench::SweepCase::reference(n)
    })
}

/// The sweep's cases, in run order (by n, then configuration, backend; re-factor runs last).
fn sweep_cases(plan: &SweepPlan) -> AnyResult<Vec<hycon_lab::bench::SweepCase>> {
    use hycon::solver::Backend;
    for n in [plan.min, plan.max] {
        if n == 0 || !n.is_power_of_two() || n > 256 {
            return Err(format!("--min/--max must be powers of two in 1..=256, got {n}").into());
        }
    }
    let backends: Vec<Backend> = match plan.backend {
        BackendChoice::Faer => vec![Backend::Faer],
        BackendChoice::Cholmod => vec![Backend::Cholmod],
        BackendChoice::All => hycon_lab::bench::BACKENDS.to_vec(),
    };
    let mut usable = Vec::new();
    for b in backends {
        if b.available() {
            usable.push(b);
        } else {
            eprintln!(
                "note: backend {} is not available in this build (CHOLMOD needs --features suitesparse); skipped",
                b.name()
            );
        }
    }
    if usable.is_empty() {
        return Err("no available backend to run".into());
    }
    let mut ns = Vec::new();
    let mut n = plan.min;
    while n <= plan.max {
        ns.push(n);
        n *= 2;
    }
    let mut cases = Vec::new();
    let sphere = hycon_lab::bench::SweepScene::Sphere;
    let scenes = [
        (
            hycon_lab::bench::SweepScene::Disk,
            &plan.configs,
            plan.r_over_a,
        ),
        (
            sphere,
            &plan.sphere_configs,
            hycon_lab::bench::SPHERE_R_OVER_A,
        ),
    ];
    for &n in &ns {
        for (scene, configs, r_over_a) in scenes {
            for config in configs.iter().filter(|c| !c.is_empty()) {
                for &backend in &usable {
                    cases.push(hycon_lab::bench::SweepCase {
                        scene,
                        backend,
                        radius_over_half_width: r_over_a,
                        kinematics: plan.kinematics,
                        ..parse_config(config, n)?
                    });
                }
            }
        }
    }
    for &n in plan.refactor_n.iter().filter(|&&n| n > 0) {
        for config in plan.configs.iter().filter(|c| !c.is_empty()) {
            for &backend in &usable {
                cases.push(hycon_lab::bench::SweepCase {
                    refactor: true,
                    backend,
                    radius_over_half_width: plan.r_over_a,
                    kinematics: plan.kinematics,
                    ..parse_config(config, n)?
                });
            }
        }
    }
    Ok(cases)
}

/// `hycon bench sweep`: run the cases in child processes (or re-read a CSV), write the CSV,
/// the plots and the summary.
fn sweep(plan: &SweepPlan, fit_min_n: usize, from_csv: Option<&Path>, out: &Path) -> AnyResult {
    let mut failed = Vec::new();
    let runs = match from_csv {
        Some(path) => hycon_lab::bench::parse_sweep_csv(&std::fs::read_to_string(path)?)?,
        None => {
            let cases = sweep_cases(plan)?;
            let exe = std::env::current_exe()?;
            let clock = Instant::now();
            println!(
                "{:<34} {:>4} {:>8} {:>6} {:>5} {:>8} {:>8} {:>8} {:>8} {:>8} {:>8} {:>8} {:>7} {:>8} {:>8}",
                "configuration",
                "n",
                "dofs",
                "cand.",
                "iters",
                "mesh",
                "assembly",
                "factor",
                "flexib.",
                "iter.",
                "recov.",
                "total s",
                "MiB",
                "L2",
                "a-aH"
            );
            let mut runs = Vec::new();
            for case in &cases {
                for _ in 0..plan.repeats.max(1) {
                    match hycon_lab::bench::sweep_run_in_child(&exe, case) {
                        Ok(r) => {
                            let t = r.timings;
                            println!(
                                "{:<34} {:>4} {:>8} {:>6} {:>5} {:>8.4} {:>8.4} {:>8.4} {:>8.4} {:>8.4} {:>8.4} {:>8.4} {:>7.1} {:>7.3}% {:>+7.3}%",
                                hycon_lab::bench::series_name(case),
                                case.n,
                                r.dofs,
                                r.contact_dofs,
                                r.iterations,
                                r.mesh,
                                t.assembly,
                                t.factorization,
                                t.flexibility,
                                t.iterations,
                                t.recovery,
                                r.total,
                                r.memory(),
                                100.0 * r.l2_error,
                                100.0 * r.half_width_error
                            );
                            runs.push(r);
                        }
                        Err(e) => {
                            eprintln!("FAILED: {e}");
                            failed.push(format!(
                                "{} n={}: {e}",
                                hycon_lab::bench::series_name(case),
                                case.n
                            ));
                        }
                    }
                }
            }
            println!(
                "{} runs in {:.1} s, {} failed",
                runs.len(),
                clock.elapsed().as_secs_f64(),
                failed.len()
            );
            for f in &failed {
                println!("  failed: {f}");
            }
            runs
        }
    };
    std::fs::create_dir_all(out)?;
    let write = |name: &str, text: &str| -> AnyResult {
        let path = out.join(name);
        std::fs::write(&path, text)?;
        println!("written: {}", path.display());
        Ok(())
    };
    if from_csv.is_none() {
        write("sweep.csv", &hycon_lab::bench::sweep_csv(&runs))?;
    }
    write(
        "sweep_error_time.svg",
        &hycon_lab::bench::sweep_error_time_svg(&runs)?,
    )?;
    write(
        "sweep_time_dofs.svg",
        &hycon_lab::bench::sweep_time_dofs_svg(&runs)?,
    )?;
    let summary = hycon_lab::bench::sweep_summary(&runs, fit_min_n);
    println!("{summary}");
    write("sweep_summary.md", &summary)?;
    if failed.is_empty() {
        Ok(())
    } else {
        Err(format!(
            "{} sweep runs failed (the files hold the others)",
            failed.len()
        )
        .into())
    }
}

/// `hycon bench contact-scale`: one configuration at fixed n, element size capped at 2^-k,
/// for each backend.
fn contact_scale(
    n: usize,
    config: &str,
    levels: &[i32],
    backends: &[String],
    out: &Path,
) -> AnyResult {
    use std::fmt::Write as _;
    let exe = std::env::current_exe()?;
    let mut runs = Vec::new();
    println!(
        "{:<28} {:>3} {:>9} {:>6} {:>8} {:>8} {:>8} {:>8} {:>8} {:>8} {:>8} {:>8} {:>8} {:>7}",
        "configuration",
        "k",
        "dofs",
        "cand.",
        "mesh",
        "assembly",
        "factor",
        "flexib.",
        "loads",
        "iter.",
        "recov.",
        "total s",
        "MiB",
        "L2"
    );
    for name in backends {
        let backend = hycon_lab::bench::parse_backend(name)
            .ok_or_else(|| format!("unknown backend {name:?}"))?;
        for &k in levels {
            let case = hycon_lab::bench::SweepCase {
                backend,
                max_element_size: Some(2f64.powi(-k)),
                ..parse_config(config, n)?
            };
            let r = hycon_lab::bench::sweep_run_in_child(&exe, &case)?;
            let phases: String = r
                .timings
                .phases()
                .iter()
                .map(|(_, t)| format!(" {t:>8.3}"))
                .collect();
            println!(
                "{:<28} {:>3} {:>9} {:>6} {:>8.3}{phases} {:>8.3} {:>8.1} {:>6.3}%",
                hycon_lab::bench::series_name(&case),
                k,
                r.dofs,
                r.contact_dofs,
                r.mesh,
                r.total,
                r.peak_rss,
                100.0 * r.l2_error
            );
            runs.push((k, r));
        }
    }
    std::fs::create_dir_all(out)?;
    let csv = out.join("contact_scale.csv");
    let plain: Vec<hycon_lab::bench::SweepRun> = runs.iter().map(|(_, r)| r.clone()).collect();
    std::fs::write(&csv, hycon_lab::bench::sweep_csv(&plain))?;
    println!("written: {}", csv.display());
    let mut md = String::new();
    let _ = writeln!(
        md,
        "### Cost against size: {config}, n = {n}, element size capped at 2^-k radii\n\n\
         | backend | k | dofs | elements | mesh s | assembly s | factorization s | flexibility s \
         | load solves s | iterations s | recovery s | total s | peak RSS MiB | L2 |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
    );
    for (k, r) in &runs {
        let phases: String = r
            .timings
            .phases()
            .iter()
            .map(|(_, t)| format!(" {t:.3} |"))
            .collect();
        let _ = writeln!(
            md,
            "| {} | {k} | {} | {} | {:.3} |{phases} {:.3} | {:.0} | {:.3}% |",
            r.case.backend.name(),
            r.dofs,
            r.elements,
            r.mesh,
            r.total,
            r.peak_rss,
            100.0 * r.l2_error
        );
    }
    let _ = writeln!(
        md,
        "\nGrowth against dofs, least squares on log-log over all runs but the smallest \
         (exponent, r^2):\n\n\
         | backend | runs | total time | factorization | load solves + recovery | assembly | mesh | peak memory (VmHWM - VmRSS at start) |\n\
         |---|---|---|---|---|---|---|---|"
    );
    for name in backends {
        let big: Vec<&hycon_lab::bench::SweepRun> = runs
            .iter()
            .map(|(_, r)| r)
            .filter(|r| r.case.backend.name() == name.as_str())
            .skip(1)
            .collect();
        let fit = |y: &dyn Fn(&hycon_lab::bench::SweepRun) -> f64| {
            let pts: Vec<(f64, f64)> = big.iter().map(|r| (r.dofs as f64, y(r))).collect();
            hycon_lab::bench::fit_power(&pts)
                .map_or("-".into(), |(p, _, r2)| format!("{p:.2} ({r2:.3})"))
        };
        let _ = writeln!(
            md,
            "| {name} | {} | {} | {} | {} | {} | {} | {} |",
            big.len(),
            fit(&|r| r.total),
            fit(&|r| r.timings.factorization),
            fit(&|r| r.timings.load_solves + r.timings.recovery),
            fit(&|r| r.timings.assembly),
            fit(&|r| r.mesh),
            fit(&|r| r.memory())
        );
    }
    println!("{md}");
    let path = out.join("contact_scale.md");
    std::fs::write(&path, md)?;
    println!("written: {}", path.display());
    Ok(())
}

/// Print the outcomes of `hycon bench presses` for one seed.
fn presses_report(o: &hycon_lab::presses::Outcomes, ranges: hycon_lab::presses::Ranges, seed: u64) {
    let ranges = format!("{ranges:?}").to_lowercase();
    println!(
        "{} random two-block presses ({ranges} ranges, seed {seed}): {} converged",
        o.count, o.converged
    );
    for (kind, n) in &o.failed {
        println!("  failed, {kind}: {n}");
    }
    let failed = o.count - o.converged;
    if failed > 0 {
        println!(
            "  failed presses: {:.2} s each on average (the cutback's tries included)",
            o.failed_seconds / failed as f64
        );
    }
    if !o.reference_settles.is_empty() {
        println!("  presses the reference settles: {:?}", o.reference_settles);
    }
    println!(
        "  converged through the fallback: {}; cut back: {}; largest condition violation at \
         convergence {:.1e} ({} over the limit)",
        o.by_fallback, o.by_cutback, o.worst_violation, o.violating
    );
    println!(
        "  the paper's rules alone (no fallback, no cutback, as 0.6.2): {} converged",
        o.paper_converged
    );
    for (kind, n) in &o.paper_failed {
        println!("    paper's rules failed, {kind}: {n}");
    }
    let per = |x: f64, n: usize| if n == 0 { 0.0 } else { x / n as f64 };
    println!(
        "  converged both ways: {} presses, iterations {} (hycon) / {} (paper's rules), {:.2} s / \
         {:.2} s",
        o.both, o.iterations[0], o.iterations[1], o.seconds[0], o.seconds[1]
    );
    println!(
        "  converged only with hycon's fallback and cutback: {} presses, {:.1} iterations and {:.2} ms \
         each",
        o.rescued.0,
        per(o.rescued.1 as f64, o.rescued.0),
        1e3 * per(o.rescued.2, o.rescued.0)
    );
}
