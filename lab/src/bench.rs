//! Measurements behind the performance figures of docs/performance.md: element kernel time per element
//! kind, and the cost of assembling, analysing, factoring and solving a large linear problem.
//! Timings are printed by the CLI (`hycon bench ...`), never asserted in tests.

use faer::Mat;
use hycon::assembly::{DofMap, SparsePattern, dof};
use hycon::element::{self, ElementMatrix, Formulation};
use hycon::error::{Error, Result};
use hycon::material::{Analysis, Material};
use hycon::mesh::generate::{self, Transition};
use hycon::solver::{Backend, FillOrdering, OrderingRule, SparseCholesky};
use std::time::Instant;

/// Mean time of one element stiffness evaluation.
#[derive(Debug, Clone)]
pub struct KernelTime {
    /// Element kind in words (`"hybrid 4-node"`, ...).
    pub kind: String,
    /// Nanoseconds per element.
    pub nanoseconds: f64,
}

/// Time `element::stiffness_into` for each element kind over `repeats` evaluations on a
/// slightly distorted element.
pub fn kernel_times(repeats: usize) -> Result<Vec<KernelTime>> {
    let m = Material::new(1.0, 0.3, 1.0, Analysis::PlaneStrain)?;
    let quad = [[0.0, 0.0], [1.1, 0.1], [1.0, 0.9], [-0.1, 1.0]];
    let five = [quad[0], quad[1], [1.05, 0.5], quad[2], quad[3]];
    let six = [
        quad[0],
        [0.55, 0.05],
        quad[1],
        [1.05, 0.5],
        quad[2],
        quad[3],
    ];
    let kinds: [(&str, Formulation, &[[f64; 2]]); 5] = [
        ("hybrid 4-node (7 beta)", Formulation::Hybrid, &quad),
        ("hybrid 5-node (7 beta)", Formulation::Hybrid, &five),
        ("hybrid 6-node (12 beta)", Formulation::Hybrid, &six),
        ("pian-sumihara (5 beta)", Formulation::PianSumihara, &quad),
        ("q4 (2x2 Gauss)", Formulation::Q4, &quad),
    ];
    let mut k = ElementMatrix::zeros();
    kinds
        .iter()
        .map(|&(kind, f, coords)| {
            let start = Instant::now();
            for _ in 0..repeats {
                element::stiffness_into(f, std::hint::black_box(coords), &m, &mut k)?;
                std::hint::black_box(&k);
            }
            Ok(KernelTime {
                kind: kind.to_string(),
                nanoseconds: start.elapsed().as_secs_f64() * 1e9 / repeats as f64,
            })
        })
        .collect()
}

/// Phase times (seconds) and sizes of one large linear solve.
#[derive(Debug, Clone, Default)]
pub struct ScaleRun {
    /// Free dofs.
    pub dofs: usize,
    /// Stored entries of the lower triangle of `K` and of `L`.
    pub nnz_k: usize,
    /// Stored entries of `L`.
    pub nnz_l: usize,
    /// Mesh generation.
    pub mesh: f64,
    /// Dof numbering, pattern and element stiffness assembly.
    pub assembly: f64,
    /// Symbolic analysis (ordering, elimination tree).
    pub analysis: f64,
    /// Numeric factorization.
    pub factorization: f64,
    /// One solve.
    pub solve: f64,
    /// Peak resident memory of the process so far, bytes (Linux `VmHWM`), if known.
    pub peak_memory: Option<u64>,
    /// Tip deflection of the beam relative to Euler-Bernoulli `P L^3 / (3 E I)`.
    pub tip_ratio: f64,
}

/// A cantilever `L = 4 H` of `4 n x n` square hybrid elements, clamped at `x = 0`, end shear on
/// `x = L`: mesh, assemble, analyse, factor and solve, each phase timed.
pub fn scale_run(n: usize) -> Result<ScaleRun> {
    let mut run = ScaleRun::default();
    let t = Instant::now();
    let (length, height) = (4.0, 1.0);
    let mesh = generate::beam(length, height, 4 * n, n, 0.0);
    run.mesh = t.elapsed().as_secs_f64();
    let material = Material::new(1000.0, 0.3, 1.0, Analysis::PlaneStress)?;
    let t = Instant::now();
    let clamped = &mesh.node_sets["left"];
    let dofs = DofMap::new(
        mesh.n_nodes(),
        2,
        clamped.iter().flat_map(|&n| [dof(n, 0), dof(n, 1)]),
    )?;
    let mut pattern = SparsePattern::new(&mesh, &dofs);
    pattern.assemble(&mesh, &[material], Formulation::Hybrid, &dofs)?;
    run.assembly = t.elapsed().as_secs_f64();
    run.dofs = dofs.n_free();
    run.nnz_k = pattern.nnz();
    let t = Instant::now();
    let mut cholesky = SparseCholesky::analyze(pattern.symbolic(), Backend::Faer, &[])?;
    run.analysis = t.elapsed().as_secs_f64();
    let t = Instant::now();
    cholesky.factorize(pattern.matrix())?;
    run.factorization = t.elapsed().as_secs_f64();
    run.nnz_l = cholesky.nnz_l();
    // unit end shear spread over the right-end nodes in proportion to their tributary length
    let right = &mesh.edge_sets["right"];
    let mut rhs = Mat::<f64>::zeros(dofs.n_free(), 1);
    for &[a, b] in right {
        let len = (mesh.nodes[b][1] - mesh.nodes[a][1]).abs() / height;
        for node in [a, b] {
            if let Some(i) = dofs.equation(dof(node, 1)) {
                rhs[(i, 0)] += 0.5 * len;
            }
        }
    }
    let t = Instant::now();
    cholesky.solve_in_place(rhs.as_mut())?;
    run.solve = t.elapsed().as_secs_f64();
    let tip = mesh.node_sets["right"]
        .iter()
        .copied()
        .min_by(|&a, &b| mesh.nodes[a][1].abs().total_cmp(&mesh.nodes[b][1].abs()))
        .and_then(|n| dofs.equation(dof(n, 1)))
        .map_or(f64::NAN, |i| rhs[(i, 0)]);
    let inertia = height.powi(3) / 12.0;
    run.tip_ratio = tip / (length.powi(3) / (3.0 * material.youngs * inertia));
    run.peak_memory = peak_memory();
    Ok(run)
}

/// One ordering of one brick cube in [`brick_scale_run`].
#[derive(Debug, Clone)]
pub struct BrickOrderingRun {
    /// The ordering faer's analysis used.
    pub ordering: FillOrdering,
    /// Stored entries of `L`.
    pub nnz_l: usize,
    /// Factorization flops (`sum_j c_j^2`).
    pub flops: f64,
    /// Pattern and symbolic analysis (ordering, elimination tree), seconds.
    pub analysis: f64,
    /// faer's numeric factorization (sequential), seconds; `None` when not factored.
    pub factorization: Option<f64>,
    /// One solve, seconds.
    pub solve: Option<f64>,
    /// CHOLMOD's numeric factorization with the same permutation (`CHOLMOD_GIVEN`), seconds.
    pub cholmod: Option<f64>,
    /// CHOLMOD's flop count and `nnz(L)` for that permutation.
    pub cholmod_flops: Option<(f64, usize)>,
    /// Peak resident memory of the process after this ordering's run, bytes, if known.
    pub peak_memory: Option<u64>,
}

/// The 3D counterpart of [`scale_run`]: a cube of `n x n x n` hybrid bricks clamped on `x = 0`
/// with a uniform load in `y`, analysed with each ordering of `rules`. The symbolic analysis
/// alone gives `nnz(L)` and the flops at any size; the numeric phases run only when `factor`
/// is set, and also through CHOLMOD with faer's permutation for the rules whose `cholmod` flag
/// is set (needs the feature `suitesparse`). Returns the free dofs, `nnz(K)` and one record
/// per ordering.
pub fn brick_scale_run(
    n: usize,
    rules: &[OrderingRule<'static>],
    factor: bool,
    cholmod: &[bool],
) -> Result<(usize, usize, Vec<BrickOrderingRun>)> {
    use hycon::solid::mesh::SolidMesh;
    use hycon::solid::model::SolidSystem;
    use hycon::solid::{BrickFormulation, Isotropic};
    let mesh = SolidMesh::uniform([1.0, 1.0, 1.0], [n, n, n]);
    let fixed: Vec<usize> = mesh
        .nodes_where(|p| p[0] == 0.0)
        .into_iter()
        .flat_map(|k| [3 * k, 3 * k + 1, 3 * k + 2])
        .collect();
    let dofs = DofMap::new(mesh.n_nodes(), 3, fixed)?;
    let material = Isotropic::new(1000.0, 0.3)?;
    let mut runs = Vec::new();
    let (mut n_free, mut nnz_k) = (0, 0);
    for (k, &rule) in rules.iter().enumerate() {
        let t = Instant::now();
        let mut system = SolidSystem::with_ordering(&mesh, dofs.clone(), Backend::Faer, rule)?;
        let analysis = t.elapsed().as_secs_f64();
        (n_free, nnz_k) = (system.dofs().n_free(), system.nnz());
        let chol = system.cholesky();
        let mut run = BrickOrderingRun {
            ordering: chol.ordering(),
            nnz_l: chol.nnz_l(),
            flops: chol.flops(),
            analysis,
            factorization: None,
            solve: None,
            cholmod: None,
            cholmod_flops: None,
            peak_memory: None,
        };
        if factor {
            system.assemble(&mesh, &[material], BrickFormulation::Hybrid18, &[])?;
            let t = Instant::now();
            system.factor()?;
            run.factorization = Some(t.elapsed().as_secs_f64());
            let mut rhs =
                Mat::<f64>::from_fn(n_free, 1, |i, _| if i % 3 == 1 { 1e-3 } else { 0.0 });
            let t = Instant::now();
            system.solve_in_place(&mut rhs)?;
            run.solve = Some(t.elapsed().as_secs_f64());
            if cholmod.get(k) == Some(&true) {
                let order = system.cholesky().order();
                let mut other = SparseCholesky::analyze_ordered(
                    system.matrix().symbolic(),
                    Backend::Cholmod,
                    &[],
                    OrderingRule::Given(&order),
                )?;
                let t = Instant::now();
                other.factorize(system.matrix())?;
                run.cholmod = Some(t.elapsed().as_secs_f64());
                run.cholmod_flops = Some((other.flops(), other.nnz_l()));
            }
        }
        run.peak_memory = peak_memory();
        runs.push(run);
    }
    Ok((n_free, nnz_k, runs))
}

/// The BLAS libraries mapped into this process (`/proc/self/maps` entries naming `blas`):
/// which one CHOLMOD ran on (Debian's `libblas.so.3` is the reference BLAS unless
/// update-alternatives points it at OpenBLAS).
pub fn blas_libraries() -> Vec<String> {
    let maps = std::fs::read_to_string("/proc/self/maps").unwrap_or_default();
    let mut libs: Vec<String> = maps
        .lines()
        .filter_map(|l| l.split_whitespace().nth(5))
        .filter(|p| p.contains("blas"))
        .map(str::to_owned)
        .collect();
    libs.sort();
    libs.dedup();
    libs
}

/// Peak resident set size of this process (Linux `/proc/self/status`, `VmHWM`), in bytes.
pub fn peak_memory() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

/// One Hertz contact analysis against the linear-solve floor on the same mesh.
#[derive(Debug, Clone)]
pub struct ContactRun {
    /// Elements per target half-width.
    pub n: usize,
    /// Coulomb friction coefficient of the pair.
    pub friction: f64,
    /// Free dofs.
    pub dofs: usize,
    /// Dofs of the contact candidates (the condensed boundary).
    pub contact_dofs: usize,
    /// The contact analysis' own time split.
    pub timings: hycon::contact::iteration::Timings,
    /// Wall time of the whole contact analysis (construction, calibration increment and 3
    /// load increments).
    pub contact_seconds: f64,
    /// Wall time of the floor: assembly, analysis and factorization of `K` plus one solve.
    pub floor_seconds: f64,
    /// L2 error of the multiplier pressure against Hertz at the last increment.
    pub l2_error: f64,
    /// Total contact iterations.
    pub iterations: usize,
}

/// A guard value beside its committed one.
#[derive(Debug, Clone, PartialEq)]
pub struct GuardVerdict {
    /// The value computed now.
    pub now: GuardValue,
    /// The committed value of the same name.
    pub committed: f64,
}

impl GuardVerdict {
    /// Worse than committed by more than 1e-6 relative (round-off across machines stays far
    /// below that): `now > committed (1 + 1e-6) + 1e-15`.
    pub fn worse(&self) -> bool {
        self.now.value > self.committed * (1.0 + 1e-6) + 1e-15
    }
}

/// Pair each of `values` with its committed value in `committed` (the text of
/// `docs/bench/guard.csv`: lines `name,value`); a name missing there is an error.
pub fn guard_verdicts(values: Vec<GuardValue>, committed: &str) -> Result<Vec<GuardVerdict>> {
    values
        .into_iter()
        .map(|now| {
            let text = committed
                .lines()
                .find_map(|l| l.strip_prefix(&format!("{},", now.name)))
                .ok_or_else(|| {
                    Error::InvalidInput(format!("guard.csv has no value for {:?}", now.name))
                })?;
            let committed = text.trim().parse().map_err(|e| {
                Error::InvalidInput(format!("guard.csv value of {:?}: {e}", now.name))
            })?;
            Ok(GuardVerdict { now, committed })
        })
        .collect()
}

/// The reference Hertz scene at `n` elements per half-width (`a = R/64`, friction
/// coefficient `friction`): time the whole contact analysis (its substitutions on `threads`
/// threads) and, on the same model, one plain factorization and solve.
pub fn contact_run(n: usize, friction: f64, threads: usize) -> Result<ContactRun> {
    use crate::scene::DiskOnBlock;
    use hycon::contact::iteration::ContactOptions;
    use hycon::model::LinearSystem;
    let scene = DiskOnBlock {
        elements_per_half_width: n,
        friction,
        ..Default::default()
    }
    .build()?;
    let f = vec![0.0; 2 * scene.model.mesh.n_nodes()];
    let clock = Instant::now();
    let mut floor = LinearSystem::new(&scene.model)?;
    floor.solve_for(&scene.model, &f, &scene.prescribed(1e-3, 0.0))?;
    let floor_seconds = clock.elapsed().as_secs_f64();
    let dofs = floor.dofs().n_free();
    drop(floor);
    let clock = Instant::now();
    let mut analysis = scene.analysis(ContactOptions {
        threads,
        ..Default::default()
    })?;
    let approach = scene.calibrated_approach(&mut analysis)?;
    for step in 1..=3 {
        analysis.increment(&f, &scene.prescribed(approach * step as f64 / 3.0, 0.0))?;
    }
    let contact_seconds = clock.elapsed().as_secs_f64();
    Ok(ContactRun {
        n,
        friction,
        dofs,
        contact_dofs: 2 * (scene.pair.a.len() + scene.pair.b.len()),
        timings: analysis.timings(),
        contact_seconds,
        floor_seconds,
        l2_error: scene.compare(&analysis)?.l2_error,
        iterations: analysis.records().len(),
    })
}

/// One accuracy figure watched by the regression guard: its name and value (an error: smaller
/// is better).
#[derive(Debug, Clone, PartialEq)]
pub struct GuardValue {
    /// What it measures.
    pub name: String,
    /// The error (relative, dimensionless).
    pub value: f64,
}

/// The reference Hertz scene at `n` elements per half-width (frictionless, default options:
/// small kinematics) after its calibration increment, with the approach that gives the target
/// half-width.
fn calibrated_reference(
    n: usize,
) -> Result<(
    crate::scene::Scene,
    hycon::contact::iteration::ContactAnalysis,
    f64,
)> {
    let scene = crate::scene::DiskOnBlock {
        elements_per_half_width: n,
        ..Default::default()
    }
    .build()?;
    let mut analysis = scene.analysis(hycon::contact::iteration::ContactOptions::default())?;
    let approach = scene.calibrated_approach(&mut analysis)?;
    Ok((scene, analysis, approach))
}

/// The accuracy figures the regression guard watches (`hycon bench guard`): the Hertz scene
/// with small kinematics at 8, 16 and 64 elements per half-width (final-increment L2 error of
/// the multiplier pressure and the absolute relative errors of half-width and peak) and the
/// 7-beta element on Cook's membrane at 8 x 8. About half a second in release.
pub fn guard_values() -> Result<Vec<GuardValue>> {
    let mut values = Vec::new();
    for n in [8, 16, 64] {
        let (scene, mut analysis, approach) = calibrated_reference(n)?;
        let f = vec![0.0; 2 * scene.model.mesh.n_nodes()];
        analysis.increment(&f, &scene.prescribed(approach, 0.0))?;
        let c = scene.compare(&analysis)?;
        let mut push = |what: &str, value: f64| {
            values.push(GuardValue {
                name: format!("hertz n={n} {what}"),
                value,
            })
        };
        push("L2 pressure error", c.l2_error);
        push(
            "half-width error",
            (c.half_width / c.hertz.half_width - 1.0).abs(),
        );
        push("peak error", (c.peak / c.hertz.peak - 1.0).abs());
    }
    let cook = crate::cases::cook_membrane(Formulation::Hybrid, 8)?;
    values.push(GuardValue {
        name: "cook 8x8 hybrid error".into(),
        value: ((cook - crate::cases::COOK_CONVERGED) / crate::cases::COOK_CONVERGED).abs(),
    });
    Ok(values)
}

// ---------------------------------------------------------------------------------------------
// Run time against error: the Hertz sweep (`hycon bench sweep`)

/// Both sparse backends, in the order tables list them (a build without the `suitesparse`
/// feature cannot run CHOLMOD: [`Backend::available`]).
pub const BACKENDS: [Backend; 2] = [Backend::Faer, Backend::Cholmod];

/// Parse a backend name given by [`Backend::name`] (`faer`, `cholmod`).
pub fn parse_backend(name: &str) -> Option<Backend> {
    BACKENDS.into_iter().find(|b| b.name() == name)
}

/// Name of a mesh variant in the sweep's tables and CSV: `"transition"` (5- and 6-node
/// transition elements, the reference scene) or `"quads"` (4-node quadrilaterals only).
pub fn mesh_name(t: Transition) -> &'static str {
    match t {
        Transition::Elements => "transition",
        Transition::Quads => "quads",
    }
}

/// Parse a name given by [`mesh_name`].
pub fn parse_mesh(name: &str) -> Option<Transition> {
    [Transition::Elements, Transition::Quads]
        .into_iter()
        .find(|&t| mesh_name(t) == name)
}

/// Parse an element name given by [`Formulation::name`].
pub fn parse_formulation(name: &str) -> Option<Formulation> {
    Formulation::ALL.into_iter().find(|f| f.name() == name)
}

/// One run of the sweep: the reference Hertz scene (frictionless, `a = R/64`, `E_disk =
/// E_block`) with one element, mesh variant, refinement and backend; or Hertz's sphere beside
/// it ([`SweepScene::Sphere`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepCase {
    /// The scene.
    pub scene: SweepScene,
    /// Element formulation.
    pub formulation: Formulation,
    /// Mesh variant.
    pub transition: Transition,
    /// Elements per target half-width (a power of two).
    pub n: usize,
    /// Sparse backend.
    pub backend: Backend,
    /// Re-factor `K` and rebuild the flexibility every iteration (instead of once).
    pub refactor: bool,
    /// Element size cap everywhere, in radii ([`DiskOnBlock::max_element_size`]).
    ///
    /// [`DiskOnBlock::max_element_size`]: crate::scene::DiskOnBlock::max_element_size
    pub max_element_size: Option<f64>,
    /// `R / a` ([`DiskOnBlock::radius_over_half_width`]; 64 in the reference scene).
    ///
    /// [`DiskOnBlock::radius_over_half_width`]:
    ///     crate::scene::DiskOnBlock::radius_over_half_width
    pub radius_over_half_width: usize,
    /// Contact kinematics (small in the reference case).
    pub kinematics: hycon::contact::iteration::Kinematics,
}

/// The scene of a sweep case.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum SweepScene {
    /// The plane disk on a block ([`crate::scene::DiskOnBlock`]): calibration increment, final
    /// increment at the calibrated approach.
    Disk,
    /// Hertz's sphere on a half-space, axisymmetric ([`crate::axisymmetric::SphereOnBlock`],
    /// `R / a` = [`SPHERE_R_OVER_A`], quadrilaterals only, equal moduli): one increment at
    /// Hertz's approach `a^2 / R`. Its errors are over `r dr`: the half-width error is the
    /// contact radius' from the moments, the peak error the axis node's multiplier's.
    Sphere,
}

/// `R / a` of the sphere in the sweep (the CSV's `r_over_a` column for its rows).
pub const SPHERE_R_OVER_A: usize = 32;

impl SweepScene {
    /// `"disk"` or `"sphere"`.
    pub fn name(self) -> &'static str {
        match self {
            SweepScene::Disk => "disk",
            SweepScene::Sphere => "sphere",
        }
    }

    /// The scene named `name` ([`name`](Self::name)).
    pub fn parse(name: &str) -> Option<Self> {
        [SweepScene::Disk, SweepScene::Sphere]
            .into_iter()
            .find(|s| s.name() == name)
    }
}

impl SweepCase {
    /// The case on the reference scene: hybrid elements, transition mesh, faer, factor once.
    pub fn reference(n: usize) -> Self {
        SweepCase {
            scene: SweepScene::Disk,
            formulation: Formulation::Hybrid,
            transition: Transition::Elements,
            n,
            backend: Backend::Faer,
            refactor: false,
            max_element_size: None,
            radius_over_half_width: 64,
            kinematics: hycon::contact::iteration::Kinematics::Small,
        }
    }

    /// `element/mesh`, e.g. `hybrid/transition`.
    pub fn config(&self) -> String {
        format!("{}/{}", self.formulation.name(), mesh_name(self.transition))
    }

    /// The arguments of the hidden single-run subcommand that runs this case.
    pub fn cli_args(&self) -> Vec<String> {
        let mut args: Vec<String> = [
            "bench",
            "sweep-one",
            "--element",
            self.formulation.name(),
            "--mesh",
            mesh_name(self.transition),
            "--backend",
            self.backend.name(),
        ]
        .map(String::from)
        .into();
        args.extend(["--n".into(), self.n.to_string()]);
        if self.refactor {
            args.push("--refactor".into());
        }
        if let Some(c) = self.max_element_size {
            args.extend(["--max-element-size".into(), format!("{c:e}")]);
        }
        args.extend(["--r-over-a".into(), self.radius_over_half_width.to_string()]);
        args.extend(["--kinematics".into(), self.kinematics.name().into()]);
        args.extend(["--scene".into(), self.scene.name().into()]);
        args
    }
}

/// What one sweep run measured. Times in seconds (wall clock), memory in MiB.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepRun {
    /// The case.
    pub case: SweepCase,
    /// Free dofs (both bodies).
    pub dofs: usize,
    /// Elements.
    pub elements: usize,
    /// Dofs of the contact candidates (the condensed boundary).
    pub contact_dofs: usize,
    /// A nodes in contact at the end.
    pub active: usize,
    /// Contact iterations over both increments (calibration and final).
    pub iterations: usize,
    /// Numeric factorizations of `K`.
    pub factorizations: usize,
    /// Mesh generation and model set-up ([`DiskOnBlock::build`]).
    ///
    /// [`DiskOnBlock::build`]: crate::scene::DiskOnBlock::build
    pub mesh: f64,
    /// The contact analysis' own split.
    pub timings: hycon::contact::iteration::Timings,
    /// Everything from mesh generation to the recovered displacement field.
    pub total: f64,
    /// Peak resident memory of the process running the case (`VmHWM`), MiB (NaN if unknown).
    pub peak_rss: f64,
    /// Resident memory of that process before the case started (`VmRSS`), MiB.
    pub start_rss: f64,
    /// L2 error of the multiplier pressure against Hertz (relative).
    pub l2_error: f64,
    /// Same, pressures from the equivalent nodal forces.
    pub l2_error_forces: f64,
    /// `a / a_Hertz - 1` (half-width from the second moment of the pressure).
    pub half_width_error: f64,
    /// `p(0) / p0_Hertz - 1`.
    pub peak_error: f64,
}

/// Header of the sweep CSV (the order of [`SweepRun::csv_row`]).
pub const SWEEP_CSV_HEADER: &str = "element,mesh,backend,refactor,n,max_element_size,dofs,\
elements,contact_dofs,active_nodes,iterations,factorizations,mesh_s,assembly_s,\
factorization_s,flexibility_s,load_solves_s,iterations_s,recovery_s,total_s,peak_rss_mib,\
start_rss_mib,l2_error,l2_error_forces,half_width_error,peak_error,r_over_a,kinematics,scene";

impl SweepRun {
    /// Memory of the run itself: peak minus the process' memory before it started, MiB.
    pub fn memory(&self) -> f64 {
        self.peak_rss - self.start_rss
    }

    /// One CSV line (no newline), columns as [`SWEEP_CSV_HEADER`].
    pub fn csv_row(&self) -> String {
        let c = &self.case;
        let cap = c
            .max_element_size
            .map_or(String::new(), |v| format!("{v:e}"));
        let phases: String = self
            .timings
            .phases()
            .iter()
            .map(|(_, t)| format!("{t:.6},"))
            .collect();
        format!(
            "{},{},{},{},{},{cap},{},{},{},{},{},{},{:.6},{phases}\
             {:.6},{:.1},{:.1},{:.6e},{:.6e},{:.6e},{:.6e},{},{},{}",
            c.formulation.name(),
            mesh_name(c.transition),
            c.backend.name(),
            c.refactor,
            c.n,
            self.dofs,
            self.elements,
            self.contact_dofs,
            self.active,
            self.iterations,
            self.factorizations,
            self.mesh,
            self.total,
            self.peak_rss,
            self.start_rss,
            self.l2_error,
            self.l2_error_forces,
            self.half_width_error,
            self.peak_error,
            c.radius_over_half_width,
            c.kinematics.name(),
            c.scene.name(),
        )
    }

    /// Parse a line written by [`SweepRun::csv_row`] (also without the last column, `scene`,
    /// which is then the disk, nor the one before it, `kinematics`, which is then finite, as in
    /// the files written before they existed, nor the one before that, `r_over_a`, which is
    /// then 64).
    pub fn from_csv_row(line: &str) -> Result<SweepRun> {
        let bad = |what: &str| Error::InvalidInput(format!("sweep CSV row {line:?}: {what}"));
        let f: Vec<&str> = line.trim().split(',').collect();
        let columns = SWEEP_CSV_HEADER.split(',').count();
        if !(columns - 3..=columns).contains(&f.len()) {
            return Err(bad("wrong number of columns"));
        }
        let num = |i: usize| -> Result<f64> { f[i].parse().map_err(|_| bad(f[i])) };
        let int = |i: usize| -> Result<usize> { f[i].parse().map_err(|_| bad(f[i])) };
        let case = SweepCase {
            scene: match f.get(28) {
                Some(s) => SweepScene::parse(s).ok_or_else(|| bad(s))?,
                None => SweepScene::Disk,
            },
            formulation: parse_formulation(f[0]).ok_or_else(|| bad(f[0]))?,
            transition: parse_mesh(f[1]).ok_or_else(|| bad(f[1]))?,
            backend: parse_backend(f[2]).ok_or_else(|| bad(f[2]))?,
            refactor: f[3].parse().map_err(|_| bad(f[3]))?,
            n: int(4)?,
            max_element_size: if f[5].is_empty() { None } else { Some(num(5)?) },
            radius_over_half_width: if f.len() > 26 { int(26)? } else { 64 },
            kinematics: match f.get(27) {
                Some(k) => k.parse()?,
                None => hycon::contact::iteration::Kinematics::Finite,
            },
        };
        Ok(SweepRun {
            case,
            dofs: int(6)?,
            elements: int(7)?,
            contact_dofs: int(8)?,
            active: int(9)?,
            iterations: int(10)?,
            factorizations: int(11)?,
            mesh: num(12)?,
            timings: hycon::contact::iteration::Timings {
                assembly: num(13)?,
                factorization: num(14)?,
                flexibility: num(15)?,
                load_solves: num(16)?,
                iterations: num(17)?,
                recovery: num(18)?,
            },
            total: num(19)?,
            peak_rss: num(20)?,
            start_rss: num(21)?,
            l2_error: num(22)?,
            l2_error_forces: num(23)?,
            half_width_error: num(24)?,
            peak_error: num(25)?,
        })
    }
}

/// Resident memory of this process now (Linux `VmRSS`), in bytes.
pub fn current_memory() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmRSS:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

/// Run one sweep case in this process: build the scene (timed as `mesh`), factor and condense
/// (`ContactAnalysis::new`), one calibration increment at a trial approach, the final
/// increment at the calibrated approach (the Hertz load of `a = R/64`), and the full
/// displacement field (one recovery solve); errors from the final increment. Peak memory is
/// the process' `VmHWM`: run each case in a fresh process (`hycon bench sweep` does) for it to
/// be the case's own.
pub fn sweep_run(case: &SweepCase) -> Result<SweepRun> {
    use crate::scene::DiskOnBlock;
    use hycon::contact::iteration::ContactOptions;
    if !case.backend.available() {
        return Err(Error::InvalidInput(format!(
            "backend {} is not available in this build",
            case.backend.name()
        )));
    }
    if case.scene == SweepScene::Sphere {
        return sphere_sweep_run(case);
    }
    let mib = |b: Option<u64>| b.map_or(f64::NAN, |b| b as f64 / 1048576.0);
    let start_rss = mib(current_memory());
    let clock = Instant::now();
    let scene = DiskOnBlock {
        elements_per_half_width: case.n,
        formulation: case.formulation,
        transition: case.transition,
        max_element_size: case.max_element_size,
        radius_over_half_width: case.radius_over_half_width,
        ..Default::default()
    }
    .build()?;
    let mesh = clock.elapsed().as_secs_f64();
    let model = &scene.model;
    let options = ContactOptions {
        backend: case.backend,
        kinematics: case.kinematics,
        ..Default::default()
    };
    let mut analysis = scene.analysis(options)?;
    analysis.set_refactor_each_iteration(case.refactor);
    let approach = scene.calibrated_approach(&mut analysis)?;
    let f = vec![0.0; 2 * model.mesh.n_nodes()];
    analysis.increment(&f, &scene.prescribed(approach, 0.0))?;
    analysis.displacement()?;
    let total = clock.elapsed().as_secs_f64();
    let c = scene.compare(&analysis)?;
    let errors = [
        c.l2_error,
        c.l2_error_forces,
        c.half_width / c.hertz.half_width - 1.0,
        c.peak / c.hertz.peak - 1.0,
    ];
    let run = RunClock {
        mesh,
        total,
        start_rss,
    };
    Ok(sweep_record(
        *case,
        (model, &scene.pair),
        &analysis,
        c.active,
        run,
        errors,
    ))
}

/// [`sweep_run`] of the sphere ([`SweepScene::Sphere`]): build the scene (timed as `mesh`),
/// factor and condense, one increment at Hertz's approach `a^2 / R` (no calibration: the
/// contact radius there is within 0.5% of the target), the full displacement field.
fn sphere_sweep_run(case: &SweepCase) -> Result<SweepRun> {
    use crate::axisymmetric::SphereOnBlock;
    use hycon::contact::iteration::ContactOptions;
    if case.transition != Transition::Quads
        || case.formulation == Formulation::PianSumihara
        || case.max_element_size.is_some()
    {
        return Err(Error::InvalidInput(format!(
            "the sphere runs on quadrilaterals with the hybrid or Q4 element, no size cap (got \
             {})",
            case.config()
        )));
    }
    let mib = |b: Option<u64>| b.map_or(f64::NAN, |b| b as f64 / 1048576.0);
    let start_rss = mib(current_memory());
    let clock = Instant::now();
    let mut scene = SphereOnBlock {
        elements_per_radius: case.n,
        radius_over_contact: SPHERE_R_OVER_A as f64,
        modulus_ratio: 1.0,
    }
    .build()?;
    scene.model.formulation = case.formulation;
    let mesh = clock.elapsed().as_secs_f64();
    let model = &scene.model;
    let mut analysis = scene.analysis(ContactOptions {
        backend: case.backend,
        kinematics: case.kinematics,
        ..Default::default()
    })?;
    analysis.set_refactor_each_iteration(case.refactor);
    let f = vec![0.0; 2 * model.mesh.n_nodes()];
    analysis.increment(&f, &scene.prescribed(scene.hertz_approach()))?;
    analysis.displacement()?;
    let total = clock.elapsed().as_secs_f64();
    let c = scene.compare(&analysis)?;
    let case = SweepCase {
        radius_over_half_width: SPHERE_R_OVER_A,
        ..*case
    };
    let errors = [
        c.l2_error,
        c.l2_error_forces,
        c.radius / c.hertz.radius - 1.0,
        c.peak / c.hertz.peak - 1.0,
    ];
    let run = RunClock {
        mesh,
        total,
        start_rss,
    };
    Ok(sweep_record(
        case,
        (model, &scene.pair),
        &analysis,
        c.active,
        run,
        errors,
    ))
}

/// A sweep run's clock and memory: the scene's build, the whole run (seconds) and the
/// resident memory before it (MiB).
struct RunClock {
    mesh: f64,
    total: f64,
    start_rss: f64,
}

/// The record of a finished sweep run of `case` on `scene` (its model and pair): free dofs,
/// elements and the dofs of both surfaces' nodes, the analysis' counts and timings, `run`'s
/// clock, the peak memory now, and the errors against Hertz `[L2, L2 from the nodal forces,
/// contact size, peak]`.
fn sweep_record(
    case: SweepCase,
    scene: (
        &hycon::model::Model,
        &hycon::contact::iteration::ContactPair,
    ),
    analysis: &hycon::contact::iteration::ContactAnalysis,
    active: usize,
    run: RunClock,
    errors: [f64; 4],
) -> SweepRun {
    let (model, pair) = scene;
    let prescribed: std::collections::HashSet<(usize, usize)> =
        model.prescribed.iter().map(|p| (p.node, p.dir)).collect();
    let mut contact_nodes: Vec<usize> = pair.a.iter().chain(&pair.b).copied().collect();
    contact_nodes.sort_unstable();
    contact_nodes.dedup();
    let [l2_error, l2_error_forces, half_width_error, peak_error] = errors;
    SweepRun {
        case,
        dofs: 2 * model.mesh.n_nodes() - prescribed.len(),
        elements: model.mesh.n_elements(),
        contact_dofs: 2 * contact_nodes.len(),
        active,
        iterations: analysis.records().len(),
        factorizations: analysis.factorizations(),
        mesh: run.mesh,
        timings: analysis.timings(),
        total: run.total,
        peak_rss: peak_memory().map_or(f64::NAN, |b| b as f64 / 1048576.0),
        start_rss: run.start_rss,
        l2_error,
        l2_error_forces,
        half_width_error,
        peak_error,
    }
}

/// Run `case` in a fresh child process of the executable `exe` (the hidden subcommand `bench
/// sweep-one`, which prints one CSV row), so that the peak memory is the case's own.
pub fn sweep_run_in_child(exe: &std::path::Path, case: &SweepCase) -> Result<SweepRun> {
    let out = std::process::Command::new(exe)
        .args(case.cli_args())
        .output()
        .map_err(|e| Error::InvalidInput(format!("cannot run {}: {e}", exe.display())))?;
    if !out.status.success() {
        return Err(Error::InvalidInput(format!(
            "{} {}: {}",
            case.config(),
            case.n,
            String::from_utf8_lossy(&out.stderr).trim()
        )));
    }
    let text = String::from_utf8_lossy(&out.stdout);
    let row = text
        .lines()
        .rev()
        .find(|l| !l.trim().is_empty())
        .ok_or_else(|| Error::InvalidInput("sweep-one printed nothing".into()))?;
    SweepRun::from_csv_row(row)
}

/// The whole CSV text of `runs` (header first).
pub fn sweep_csv(runs: &[SweepRun]) -> String {
    let mut text = String::from(SWEEP_CSV_HEADER);
    text.push('\n');
    for r in runs {
        text.push_str(&r.csv_row());
        text.push('\n');
    }
    text
}

/// Parse a CSV written by [`sweep_csv`].
pub fn parse_sweep_csv(text: &str) -> Result<Vec<SweepRun>> {
    let mut lines = text.lines().filter(|l| !l.trim().is_empty());
    // files written before the last columns existed (scene, kinematics, then r_over_a)
    let old = SWEEP_CSV_HEADER.trim_end_matches(",scene");
    let older = old.trim_end_matches(",kinematics");
    let oldest = older.trim_end_matches(",r_over_a");
    match lines.next() {
        Some(h) if [SWEEP_CSV_HEADER, old, older, oldest].contains(&h.trim()) => {}
        _ => {
            return Err(Error::InvalidInput(
                "not a sweep CSV (header differs)".into(),
            ));
        }
    }
    lines.map(SweepRun::from_csv_row).collect()
}

/// Series key: scene, kinematics, `R / a`, element, mesh, backend, refactor (one line in the
/// plots).
fn series_key(c: &SweepCase) -> (SweepScene, &'static str, usize, usize, u8, usize, bool) {
    let f = Formulation::ALL
        .iter()
        .position(|&g| g == c.formulation)
        .unwrap_or(0);
    let m = match c.transition {
        Transition::Elements => 0,
        Transition::Quads => 1,
    };
    let b = BACKENDS.iter().position(|&g| g == c.backend).unwrap_or(0);
    (
        c.scene,
        c.kinematics.name(),
        c.radius_over_half_width,
        f,
        m,
        b,
        c.refactor,
    )
}

/// Name of a series: `element/mesh backend` (`sphere element/mesh backend` for the sphere;
/// and `, finite kinematics`, `, R/a = ...` when not 64 on the disk, `, refactor each
/// iteration`).
pub fn series_name(c: &SweepCase) -> String {
    let mut s = format!("{} {}", c.config(), c.backend.name());
    if c.scene == SweepScene::Sphere {
        s = format!("sphere {s}, R/a = {}", c.radius_over_half_width);
    }
    if c.kinematics == hycon::contact::iteration::Kinematics::Finite {
        s += ", finite kinematics";
    }
    if c.radius_over_half_width != 64 && c.scene == SweepScene::Disk {
        s += &format!(", R/a = {}", c.radius_over_half_width);
    }
    if c.refactor {
        s += ", refactor each iteration";
    }
    s
}

/// The plotted and summarised runs: without an element-size cap, one per series and `n` (the
/// fastest of repeated runs, the usual estimate on a noisy machine), grouped by series and
/// sorted by `n`.
pub fn sweep_series(runs: &[SweepRun]) -> Vec<Vec<SweepRun>> {
    let mut best: std::collections::BTreeMap<_, SweepRun> = std::collections::BTreeMap::new();
    for r in runs.iter().filter(|r| r.case.max_element_size.is_none()) {
        let key = (series_key(&r.case), r.case.n);
        match best.get(&key) {
            Some(b) if b.total <= r.total => {}
            _ => {
                best.insert(key, r.clone());
            }
        }
    }
    let mut series: Vec<Vec<SweepRun>> = Vec::new();
    for ((key, _), r) in best {
        match series.last_mut() {
            Some(s) if series_key(&s[0].case) == key => s.push(r),
            _ => series.push(vec![r]),
        }
    }
    series
}

/// Least-squares fit of `y = c x^p` on log-log axes: `(p, c, r^2)`; `None` with fewer than two
/// distinct positive points.
pub fn fit_power(points: &[(f64, f64)]) -> Option<(f64, f64, f64)> {
    let logs: Vec<(f64, f64)> = points
        .iter()
        .filter(|(x, y)| *x > 0.0 && *y > 0.0 && x.is_finite() && y.is_finite())
        .map(|(x, y)| (x.ln(), y.ln()))
        .collect();
    let n = logs.len() as f64;
    if logs.len() < 2 {
        return None;
    }
    let (mx, my) = (
        logs.iter().map(|p| p.0).sum::<f64>() / n,
        logs.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let sxx: f64 = logs.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = logs.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let syy: f64 = logs.iter().map(|p| (p.1 - my).powi(2)).sum();
    if sxx <= 0.0 {
        return None;
    }
    let p = sxy / sxx;
    let r2 = if syy > 0.0 {
        sxy * sxy / (sxx * syy)
    } else {
        1.0
    };
    Some((p, (my - p * mx).exp(), r2))
}

/// The markdown summary of a sweep: per series the fastest run reaching 1%, 0.5%, 0.25% and
/// 0.1% L2 error (with its dofs and memory), the ranking at each threshold, growth exponents of time and memory against dofs
/// fitted over the runs with `n >= fit_min_n`, and the re-factor ratios.
pub fn sweep_summary(runs: &[SweepRun], fit_min_n: usize) -> String {
    use std::fmt::Write;
    let series = sweep_series(runs);
    let plain: Vec<&Vec<SweepRun>> = series.iter().filter(|s| !s[0].case.refactor).collect();
    let mut md = String::new();
    for threshold in [0.01, 0.005, 0.0025, 0.001] {
        let _ = writeln!(
            md,
            "\n### Fastest to L2 error <= {}%\n\n| rank | configuration | n | dofs | L2 | total s | MiB |\n|---|---|---|---|---|---|---|",
            100.0 * threshold
        );
        let mut reached: Vec<&SweepRun> = plain
            .iter()
            .filter_map(|s| {
                s.iter()
                    .filter(|r| r.l2_error <= threshold)
                    .min_by(|a, b| a.total.total_cmp(&b.total))
            })
            .collect();
        reached.sort_by(|a, b| a.total.total_cmp(&b.total));
        for (k, r) in reached.iter().enumerate() {
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {:.3}% | {:.4} | {:.0} |",
                k + 1,
                series_name(&r.case),
                r.case.n,
                r.dofs,
                100.0 * r.l2_error,
                r.total,
                r.memory()
            );
        }
        for s in &plain {
            if s.iter().all(|r| r.l2_error > threshold) {
                let best = s
                    .iter()
                    .min_by(|a, b| a.l2_error.total_cmp(&b.l2_error))
                    .expect("non-empty series");
                let _ = writeln!(
                    md,
                    "| - | {} (not reached; best {:.3}% at n = {}) | | | | | |",
                    series_name(&s[0].case),
                    100.0 * best.l2_error,
                    best.case.n
                );
            }
        }
    }
    let _ = writeln!(
        md,
        "\n### Growth against dofs (least squares on log-log, runs with n >= {fit_min_n})\n\n\
         | configuration | points | dofs | time exponent (r^2) | memory exponent (r^2) |\n|---|---|---|---|---|"
    );
    for s in &plain {
        let big: Vec<&SweepRun> = s.iter().filter(|r| r.case.n >= fit_min_n).collect();
        let time: Vec<(f64, f64)> = big.iter().map(|r| (r.dofs as f64, r.total)).collect();
        let mem: Vec<(f64, f64)> = big.iter().map(|r| (r.dofs as f64, r.memory())).collect();
        let show = |f: Option<(f64, f64, f64)>| {
            f.map_or("-".into(), |(p, _, r2)| format!("{p:.2} ({r2:.3})"))
        };
        let range = match (big.first(), big.last()) {
            (Some(a), Some(b)) => format!("{} - {}", a.dofs, b.dofs),
            _ => "-".into(),
        };
        let _ = writeln!(
            md,
            "| {} | {} | {range} | {} | {} |",
            series_name(&s[0].case),
            big.len(),
            show(fit_power(&time)),
            show(fit_power(&mem))
        );
    }
    let refactor: Vec<&Vec<SweepRun>> = series.iter().filter(|s| s[0].case.refactor).collect();
    if !refactor.is_empty() {
        let _ = writeln!(
            md,
            "\n### Re-factor every iteration against factor once\n\n\
             | configuration | n | factorizations | iterations | total s (re-factor) | total s (once) | ratio |\n|---|---|---|---|---|---|---|"
        );
        for s in refactor {
            for r in s {
                let once = plain
                    .iter()
                    .find(|p| {
                        let c = &p[0].case;
                        c.scene == r.case.scene
                            && c.formulation == r.case.formulation
                            && c.transition == r.case.transition
                            && c.backend == r.case.backend
                            && c.radius_over_half_width == r.case.radius_over_half_width
                            && c.kinematics == r.case.kinematics
                    })
                    .and_then(|p| p.iter().find(|o| o.case.n == r.case.n));
                let (t1, ratio) = once.map_or(("-".into(), "-".into()), |o| {
                    (
                        format!("{:.4}", o.total),
                        format!("{:.2}", r.total / o.total),
                    )
                });
                let _ = writeln!(
                    md,
                    "| {} {} | {} | {} | {} | {:.4} | {t1} | {ratio} |",
                    r.case.config(),
                    r.case.backend.name(),
                    r.case.n,
                    r.factorizations,
                    r.iterations,
                    r.total
                );
            }
        }
    }
    md
}

// ---------------------------------------------------------------------------------------------
// Plots of the sweep (plotters, SVG backend; the house style of `report::svg`)

type Plot<T> = std::result::Result<T, Box<dyn std::error::Error>>;

const FONT: &str = "sans-serif";

/// Colour of a series: one hue per element and mesh, darker for CHOLMOD.
fn series_colour(c: &SweepCase) -> plotters::style::RGBColor {
    use plotters::style::RGBColor;
    let base = match (c.formulation, c.transition) {
        _ if c.scene == SweepScene::Sphere => match c.formulation {
            Formulation::Q4 => RGBColor(230, 140, 20),
            _ => RGBColor(140, 60, 170),
        },
        (Formulation::Hybrid, Transition::Elements) => RGBColor(31, 90, 200),
        (Formulation::Hybrid, Transition::Quads) => RGBColor(0, 160, 190),
        (Formulation::PianSumihara, _) => RGBColor(40, 150, 40),
        (Formulation::Q4, _) => RGBColor(210, 50, 40),
    };
    match c.backend {
        Backend::Faer => base,
        Backend::Cholmod => RGBColor(base.0 / 2, base.1 / 2, base.2 / 2),
    }
}

/// Logarithmic axis range around positive values (a factor `pad` of margin each side).
fn log_range(values: impl Iterator<Item = f64>, pad: f64) -> std::ops::Range<f64> {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, 0.0_f64), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if lo.is_finite() && hi > 0.0 {
        lo / pad..hi * pad
    } else {
        0.1..10.0
    }
}

/// An axis label: three significant digits, no trailing zeros.
fn short_number(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let decimals = (2 - v.abs().log10().floor() as i32).max(0) as usize;
    let text = format!("{v:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

/// One log-log panel: a line with dots per series, `n` written beside each dot.
fn log_panel<DB: plotters::prelude::DrawingBackend>(
    area: &plotters::prelude::DrawingArea<DB, plotters::coord::Shift>,
    title: &str,
    (x_desc, y_desc): (&str, &str),
    series: &[Vec<SweepRun>],
    point: &dyn Fn(&SweepRun) -> (f64, f64),
    guides: &[(f64, &str)],
    legend: plotters::chart::SeriesLabelPosition,
) -> Plot<()>
where
    DB::ErrorType: 'static,
{
    use plotters::prelude::*;
    let all: Vec<(f64, f64)> = series.iter().flatten().map(point).collect();
    let xr = log_range(all.iter().map(|p| p.0), 1.3);
    let yr = log_range(
        all.iter().map(|p| p.1).chain(guides.iter().map(|g| g.0)),
        1.3,
    );
    let mut chart = ChartBuilder::on(area)
        .caption(title, (FONT, 14))
        .margin(10)
        .x_label_area_size(36)
        .y_label_area_size(60)
        .build_cartesian_2d(xr.clone().log_scale(), yr.log_scale())?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&|v| short_number(*v))
        .y_label_formatter(&|v| short_number(*v))
        .light_line_style(BLACK.mix(0.03))
        .label_style((FONT, 12))
        .draw()?;
    for &(y, name) in guides {
        chart
            .draw_series(DashedLineSeries::new(
                [(xr.start, y), (xr.end, y)],
                5,
                4,
                BLACK.mix(0.45).stroke_width(1),
            ))?
            .label(name)
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], BLACK.mix(0.45)));
    }
    for s in series {
        let c = series_colour(&s[0].case);
        let pts: Vec<(f64, f64)> = s.iter().map(point).collect();
        chart
            .draw_series(LineSeries::new(pts.clone(), c.stroke_width(2)))?
            .label(series_name(&s[0].case))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], c.stroke_width(2)));
        chart.draw_series(pts.iter().map(|&p| Circle::new(p, 3, c.filled())))?;
        chart.draw_series(s.iter().zip(&pts).map(|(r, &p)| {
            Text::new(
                format!("{}", r.case.n),
                p,
                (FONT, 10).into_font().color(&c.mix(0.9)),
            )
        }))?;
    }
    chart
        .configure_series_labels()
        .position(legend)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.4))
        .label_font((FONT, 11))
        .draw()?;
    Ok(())
}

/// The series the sweep's plots draw: every configuration except the refactor-every-iteration
/// variants.
fn plotted_series(runs: &[SweepRun]) -> Vec<Vec<SweepRun>> {
    sweep_series(runs)
        .into_iter()
        .filter(|s| !s[0].case.refactor)
        .collect()
}

/// SVG: L2 pressure error against total run time, one line per element / mesh / backend
/// (numbers beside the dots: elements per half-width), dashed lines at 1% and 0.5%.
pub fn sweep_error_time_svg(runs: &[SweepRun]) -> Plot<String> {
    use plotters::prelude::*;
    let series = plotted_series(runs);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 640)).into_drawing_area();
        root.fill(&WHITE)?;
        log_panel(
            &root,
            "Hertz scenes (disk; sphere, L2 on r dr): L2 pressure error against total run time (n = a/h)",
            (
                "total time per analysis, s",
                "L2 error of the contact pressure, %",
            ),
            &series,
            &|r| (r.total, 100.0 * r.l2_error),
            &[(1.0, "1%"), (0.5, "0.5%")],
            SeriesLabelPosition::UpperRight,
        )?;
        root.present()?;
    }
    Ok(svg)
}

/// SVG, two panels: total run time and the run's own peak memory against free dofs.
pub fn sweep_time_dofs_svg(runs: &[SweepRun]) -> Plot<String> {
    use plotters::prelude::*;
    let series = plotted_series(runs);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1300, 560)).into_drawing_area();
        root.fill(&WHITE)?;
        let panels = root.split_evenly((1, 2));
        log_panel(
            &panels[0],
            "total time against dofs",
            ("free dofs", "total time, s"),
            &series,
            &|r| (r.dofs as f64, r.total),
            &[],
            SeriesLabelPosition::UpperLeft,
        )?;
        log_panel(
            &panels[1],
            "peak memory of the run (VmHWM - VmRSS at start) against dofs",
            ("free dofs", "memory, MiB"),
            &series,
            &|r| (r.dofs as f64, r.memory()),
            &[],
            SeriesLabelPosition::UpperLeft,
        )?;
        root.present()?;
    }
    Ok(svg)
}

/// One row of the "skip what a scene does not need" table: the time with the skip and without
/// it (the work done anyway), on the same scene.
#[derive(Debug, Clone, PartialEq)]
pub struct SkipRow {
    /// What is skipped.
    pub what: String,
    /// Seconds with the skip (what hycon does).
    pub with_skip: f64,
    /// Seconds without it.
    pub without: f64,
    /// What the two numbers time.
    pub measured: String,
}

/// What one press of [`skip_press`] measured.
#[derive(Debug, Clone, Copy, Default)]
struct Press {
    /// Whole press, seconds.
    seconds: f64,
    timings: hycon::contact::iteration::Timings,
    /// Unknowns of the small systems summed over the iterations.
    unknowns: usize,
    /// Contact iterations.
    iterations: usize,
}

/// The reference Hertz scene at `n` elements per half-width, pressed by the calibrated
/// approach in 3 increments; `pair` replaces the scene's candidate pair when given.
/// Work a skip-table row adds back on purpose, to measure what skipping it saves.
#[derive(Debug, Clone, Copy, Default)]
struct Waste {
    /// Recover the full displacement field after every increment.
    recover_each: bool,
    /// Factor `K` again in every iteration.
    refactor_each: bool,
}

fn skip_press(
    scene: &crate::scene::Scene,
    pair: Option<hycon::contact::iteration::ContactPair>,
    options: hycon::contact::iteration::ContactOptions,
    waste: Waste,
) -> Result<Press> {
    use hycon::contact::iteration::ContactAnalysis;
    let f = vec![0.0; 2 * scene.model.mesh.n_nodes()];
    let clock = Instant::now();
    let pair = pair.unwrap_or_else(|| scene.pair.clone());
    let mut analysis = ContactAnalysis::new(scene.model.clone(), vec![pair], options)?;
    analysis.set_refactor_each_iteration(waste.refactor_each);
    let approach = scene.calibrated_approach(&mut analysis)?;
    for step in 1..=3 {
        analysis.increment(&f, &scene.prescribed(approach * step as f64 / 3.0, 0.0))?;
        if waste.recover_each {
            analysis.displacement()?;
        }
    }
    Ok(Press {
        seconds: clock.elapsed().as_secs_f64(),
        timings: analysis.timings(),
        unknowns: analysis.records().iter().map(|r| r.active + r.stick).sum(),
        iterations: analysis.records().len(),
    })
}

/// Measure what skipping unneeded work saves on the reference Hertz scene at `n` elements per
/// half-width (each figure the fastest of `repeats` runs): tangential rows at `mu = 0`, the
/// factorization kept for the whole analysis, the flexibility on the candidate dofs only, the
/// contact geometry evaluated once (small kinematics), the field recovered only on request,
/// and a scene without contact going straight to one linear solve.
pub fn skip_table(n: usize, repeats: usize) -> Result<Vec<SkipRow>> {
    use crate::scene::DiskOnBlock;
    use hycon::contact::iteration::{ContactAnalysis, ContactOptions, ContactPair, Kinematics};
    use hycon::model::LinearSystem;
    let build = |friction: f64| {
        DiskOnBlock {
            elements_per_half_width: n,
            friction,
            ..Default::default()
        }
        .build()
    };
    let scene = build(0.0)?;
    let sticky = build(0.3)?;
    let defaults = ContactOptions::default();
    let best = |run: &dyn Fn() -> Result<Press>| {
        (0..repeats.max(1)).try_fold(
            Press {
                seconds: f64::INFINITY,
                ..Default::default()
            },
            |best: Press, _| {
                let r = run()?;
                Ok::<_, hycon::Error>(if r.seconds < best.seconds { r } else { best })
            },
        )
    };
    let plain = best(&|| skip_press(&scene, None, defaults, Waste::default()))?;
    let friction = best(&|| skip_press(&sticky, None, defaults, Waste::default()))?;
    let refactor = best(&|| {
        let waste = Waste {
            refactor_each: true,
            ..Waste::default()
        };
        skip_press(&scene, None, defaults, waste)
    })?;
    let whole = ContactPair {
        a: scene.model.mesh.node_sets["block.top"].clone(),
        b: scene.model.mesh.node_sets["disk.arc"].clone(),
        friction: 0.0,
    };
    let surfaces = best(&|| skip_press(&scene, Some(whole.clone()), defaults, Waste::default()))?;
    let recovered = best(&|| {
        skip_press(
            &scene,
            None,
            defaults,
            Waste {
                recover_each: true,
                ..Waste::default()
            },
        )
    })?;
    let finite = best(&|| {
        let options = ContactOptions {
            kinematics: Kinematics::Finite,
            ..defaults
        };
        skip_press(&scene, None, options, Waste::default())
    })?;
    let f = vec![0.0; 2 * scene.model.mesh.n_nodes()];
    let qp = scene.prescribed(1e-3 * scene.half_width, 0.0);
    let timed = |run: &dyn Fn() -> Result<()>| -> Result<f64> {
        (0..repeats.max(1)).try_fold(f64::INFINITY, |best, _| {
            let clock = Instant::now();
            run()?;
            Ok(best.min(clock.elapsed().as_secs_f64()))
        })
    };
    let no_contact = timed(&|| {
        let mut analysis = ContactAnalysis::new(scene.model.clone(), Vec::new(), defaults)?;
        analysis.increment(&f, &qp)?;
        analysis.displacement()?;
        Ok(())
    })?;
    let linear = timed(&|| {
        LinearSystem::new(&scene.model)?.solve_for(&scene.model, &f, &qp)?;
        Ok(())
    })?;
    let with_contact = timed(&|| {
        let mut analysis = scene.analysis(defaults)?;
        analysis.increment(&f, &qp)?;
        analysis.displacement()?;
        Ok(())
    })?;
    Ok(vec![
        SkipRow {
            what: format!(
                "no tangential rows at mu = 0 ({} unknowns in all iterations; {} with mu = 0.3)",
                plain.unknowns, friction.unknowns
            ),
            with_skip: plain.timings.iterations,
            without: friction.timings.iterations,
            measured: "contact iterations of the press, mu = 0 vs mu = 0.3".into(),
        },
        SkipRow {
            what: "K factored once per analysis".into(),
            with_skip: plain.seconds,
            without: refactor.seconds,
            measured: "whole press; the other re-factors K and rebuilds F every iteration".into(),
        },
        SkipRow {
            what: format!(
                "F only on the candidate dofs ({} of {} surface nodes)",
                scene.pair.a.len() + scene.pair.b.len(),
                whole.a.len() + whole.b.len()
            ),
            with_skip: plain.timings.flexibility,
            without: surfaces.timings.flexibility,
            measured: "flexibility F; the other pairs the whole block top with the whole arc"
                .into(),
        },
        SkipRow {
            what: format!(
                "contact geometry evaluated once: small kinematics ({} iterations; {} with \
                 finite kinematics)",
                plain.iterations, finite.iterations
            ),
            with_skip: plain.timings.iterations,
            without: finite.timings.iterations,
            measured: "contact iterations of the press, small vs finite kinematics".into(),
        },
        SkipRow {
            what: "full field only on request".into(),
            with_skip: plain.seconds,
            without: recovered.seconds,
            measured: "whole press; the other recovers the field after every increment".into(),
        },
        SkipRow {
            what: "no contact pair: straight to the linear solve".into(),
            with_skip: no_contact,
            without: with_contact,
            measured: format!(
                "one increment and its field without pairs vs with the pair (one assembly + \
                 factorization + solve alone: {linear:.4} s)"
            ),
        },
    ])
}

/// One run of [`edge_sweep`]: the reference Hertz scene pressed so that the Hertz edge falls
/// at a chosen place between two A nodes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EdgeRun {
    /// Elements per target half-width.
    pub n: usize,
    /// Hertz half-width at the computed load, in element sizes at the contact.
    pub half_width_over_h: f64,
    /// L2 error of the multiplier pressure.
    pub l2_error: f64,
    /// L2 error of the best approximation on the same nodes
    /// ([`crate::scene::best_approximation`]).
    pub best_l2_error: f64,
    /// The same, zero at the nodes the method found open
    /// ([`crate::scene::best_approximation_on`]): the least error of a pressure with the
    /// method's contact set.
    pub best_active_l2_error: f64,
    /// Half-width error against Hertz (second moment, relative).
    pub half_width_error: f64,
    /// Peak error against Hertz (relative).
    pub peak_error: f64,
}

impl EdgeRun {
    /// Where the edge falls between the last node inside and the first outside, in `[0, 1)`.
    pub fn edge_position(&self) -> f64 {
        self.half_width_over_h - self.half_width_over_h.floor()
    }
}

/// The L2 error against where the contact edge falls between two nodes: the reference scene
/// (frictionless, small kinematics, `R / a = 64`, equal moduli) at `n` elements per half-width,
/// pressed so that the Hertz half-width `a_H` lies at `positions` evenly spaced places of one
/// element (`a_H / h = k + (j + 1/2) / positions`, the approach scaled by `(a_H / a_0)^2` from
/// the calibrated one: `P` grows about linearly with the approach and `a_H` as `sqrt(P)`).
pub fn edge_sweep(n: usize, positions: usize) -> Result<Vec<EdgeRun>> {
    let (scene, mut analysis, approach) = calibrated_reference(n)?;
    let f = vec![0.0; 2 * scene.model.mesh.n_nodes()];
    let h = scene.half_width / n as f64;
    let mut press = |approach: f64| -> Result<EdgeRun> {
        analysis.increment(&f, &scene.prescribed(approach, 0.0))?;
        let c = scene.compare(&analysis)?;
        Ok(EdgeRun {
            n,
            half_width_over_h: c.hertz.half_width / h,
            l2_error: c.l2_error,
            best_l2_error: c.best_l2_error,
            best_active_l2_error: c.best_active_l2_error,
            half_width_error: c.half_width / c.hertz.half_width - 1.0,
            peak_error: c.peak / c.hertz.peak - 1.0,
        })
    };
    let first = press(approach)?;
    let k = first.half_width_over_h.floor();
    (0..positions)
        .map(|j| {
            let target = k + (j as f64 + 0.5) / positions as f64;
            press(approach * (target / first.half_width_over_h).powi(2))
        })
        .collect()
}

/// One point of the brick convergence study (`hycon bench brick`).
#[derive(Debug, Clone)]
pub struct BrickRun {
    /// `"hybrid18"` or `"h8"`.
    pub element: &'static str,
    /// Whether the interior nodes were moved at random (by up to 20% of their shortest edge).
    pub distorted: bool,
    /// Bricks across the section (`4k x k x k` bricks).
    pub k: usize,
    /// Free dofs.
    pub dofs: usize,
    /// Largest nodal displacement error over the largest exact displacement.
    pub error: f64,
}

/// Saint-Venant's end-loaded cantilever with `nu = 0` (the field of `tests/solid_validation.rs`):
/// `[0, 10] x [-0.5, 0.5]^2`, E = 1000, end shear 1 at `x = 0`; exact displacements and the
/// stresses `(sx, sy, sz, txy, tyz, tzx)`.
fn saint_venant(p: [f64; 3]) -> ([f64; 3], [f64; 6]) {
    let (l, c, b, e): (f64, f64, f64, f64) = (10.0, 0.5, 1.0, 1000.0);
    let g = e / 2.0;
    let i = b * (2.0 * c).powi(3) / 12.0;
    let [x, y, _] = p;
    let u = -x * x * y / (2.0 * e * i)
        + y.powi(3) / (6.0 * i * g)
        + (l * l / (2.0 * e * i) - c * c / (2.0 * i * g)) * y;
    let v = x.powi(3) / (6.0 * e * i) - l * l * x / (2.0 * e * i) + l.powi(3) / (3.0 * e * i);
    let s = [-x * y / i, 0.0, 0.0, -(c * c - y * y) / (2.0 * i), 0.0, 0.0];
    ([u, v, 0.0], s)
}

/// The error of one brick on Saint-Venant's beam meshed with `4k x k x k` bricks: exact
/// displacements held on the root `x = 10`, exact tractions on the free end `x = 0`.
pub fn brick_run(k: usize, distorted: bool, hybrid: bool) -> Result<BrickRun> {
    use hycon::solid::mesh::{SolidMesh, graded};
    use hycon::solid::model::SolidModel;
    use hycon::solid::{BrickFormulation, Isotropic};
    let mut mesh = SolidMesh::block(
        &graded(0.0, 10.0, 4 * k, 1.0),
        &graded(-0.5, 0.5, k, 1.0),
        &graded(-0.5, 0.5, k, 1.0),
    );
    if distorted {
        mesh = mesh.distort(0.2, 11, |p| {
            p[0] > 1e-9 && p[0] < 10.0 - 1e-9 && p[1].abs() < 0.5 - 1e-9 && p[2].abs() < 0.5 - 1e-9
        });
    }
    let formulation = if hybrid {
        BrickFormulation::Hybrid18
    } else {
        BrickFormulation::H8
    };
    let mut model = SolidModel::new(
        mesh.clone(),
        vec![Isotropic::new(1000.0, 0.0)?],
        formulation,
    )?;
    for n in mesh.nodes_where(|p| (p[0] - 10.0).abs() < 1e-12) {
        for (d, ud) in saint_venant(mesh.nodes[n]).0.into_iter().enumerate() {
            model.fix(n, d, ud);
        }
    }
    let free_end = mesh.faces_where(|p| p[0].abs() < 1e-12);
    model.load_faces(&free_end, |x, n| {
        let s = saint_venant(x).1;
        [
            s[0] * n[0] + s[3] * n[1] + s[5] * n[2],
            s[3] * n[0] + s[1] * n[1] + s[4] * n[2],
            s[5] * n[0] + s[4] * n[1] + s[2] * n[2],
        ]
    });
    let sol = model.solve()?;
    let (mut err, mut max): (f64, f64) = (0.0, 0.0);
    for (n, &p) in mesh.nodes.iter().enumerate() {
        for (got, want) in sol.at(n).into_iter().zip(saint_venant(p).0) {
            err = err.max((got - want).abs());
            max = max.max(want.abs());
        }
    }
    Ok(BrickRun {
        element: if hybrid { "hybrid18" } else { "h8" },
        distorted,
        k,
        dofs: sol.n_free,
        error: err / max,
    })
}

/// The convergence study: both bricks on regular and distorted meshes, `k` in `ks`.
pub fn brick_convergence(ks: &[usize]) -> Result<Vec<BrickRun>> {
    let mut runs = Vec::new();
    for hybrid in [true, false] {
        for distorted in [false, true] {
            for &k in ks {
                runs.push(brick_run(k, distorted, hybrid)?);
            }
        }
    }
    Ok(runs)
}

/// SVG: error against free dofs (log-log), a line per brick and mesh, `k` beside each dot.
pub fn brick_convergence_svg(runs: &[BrickRun]) -> Plot<String> {
    use plotters::prelude::*;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 640)).into_drawing_area();
        root.fill(&WHITE)?;
        let xr = log_range(runs.iter().map(|r| r.dofs as f64), 1.3);
        let yr = log_range(runs.iter().map(|r| r.error), 1.5);
        let mut chart = ChartBuilder::on(&root)
            .caption(
                "Saint-Venant's cantilever, nu = 0: error against dofs (dots: k, 4k x k x k bricks)",
                (FONT, 14),
            )
            .margin(10)
            .x_label_area_size(36)
            .y_label_area_size(60)
            .build_cartesian_2d(xr.log_scale(), yr.log_scale())?;
        chart
            .configure_mesh()
            .x_desc("free dofs")
            .y_desc("max nodal displacement error / max displacement")
            .x_label_formatter(&|v| short_number(*v))
            .y_label_formatter(&|v| short_number(*v))
            .light_line_style(BLACK.mix(0.03))
            .label_style((FONT, 12))
            .draw()?;
        for (element, hue) in [("hybrid18", 0.6), ("h8", 0.0)] {
            for distorted in [false, true] {
                let s: Vec<&BrickRun> = runs
                    .iter()
                    .filter(|r| r.element == element && r.distorted == distorted)
                    .collect();
                if s.is_empty() {
                    continue;
                }
                let c = HSLColor(hue, 0.8, if distorted { 0.6 } else { 0.35 });
                let pts: Vec<(f64, f64)> = s.iter().map(|r| (r.dofs as f64, r.error)).collect();
                let name = format!(
                    "{element}, {} meshes",
                    if distorted { "distorted" } else { "regular" }
                );
                let style = c.stroke_width(2);
                if distorted {
                    chart
                        .draw_series(DashedLineSeries::new(pts.clone(), 6, 4, style))?
                        .label(name)
                        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], style));
                } else {
                    chart
                        .draw_series(LineSeries::new(pts.clone(), style))?
                        .label(name)
                        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], style));
                }
                chart.draw_series(pts.iter().map(|&p| Circle::new(p, 3, c.filled())))?;
                chart.draw_series(s.iter().zip(&pts).map(|(r, &p)| {
                    Text::new(format!("{}", r.k), p, (FONT, 10).into_font().color(&c))
                }))?;
            }
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerLeft)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.4))
            .label_font((FONT, 11))
            .draw()?;
        root.present()?;
    }
    Ok(svg)
}
