//! Measurements behind the performance figures in the README: element kernel time per element
//! kind, and the cost of assembling, analysing, factoring and solving a large linear problem.
//! Timings are printed by the CLI (`hycon bench ...`), never asserted in tests.

use crate::assembly::{DofMap, SparsePattern, dof};
use crate::element::{self, ElementMatrix, Formulation};
use crate::error::Result;
use crate::material::{Analysis, Material};
use crate::mesh::generate;
use crate::solver::SparseCholesky;
use faer::Mat;
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
        clamped.iter().flat_map(|&n| [dof(n, 0), dof(n, 1)]),
    );
    let mut pattern = SparsePattern::new(&mesh, &dofs);
    pattern.assemble(&mesh, &[material], Formulation::Hybrid, &dofs)?;
    run.assembly = t.elapsed().as_secs_f64();
    run.dofs = dofs.n_free();
    run.nnz_k = pattern.nnz();
    let t = Instant::now();
    let mut cholesky = SparseCholesky::analyze(pattern.symbolic())?;
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
    /// Free dofs.
    pub dofs: usize,
    /// Dofs of the contact candidates (the condensed boundary).
    pub contact_dofs: usize,
    /// The contact analysis' own time split.
    pub timings: crate::contact::iteration::Timings,
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

/// The reference Hertz scene at `n` elements per half-width (frictionless, `a = R/64`):
/// time the whole contact analysis and, on the same model, one plain factorization and solve.
pub fn contact_run(n: usize) -> Result<ContactRun> {
    use crate::contact::iteration::ContactOptions;
    use crate::contact::scene::DiskOnBlock;
    use crate::model::LinearSystem;
    let scene = DiskOnBlock {
        elements_per_half_width: n,
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
    let mut analysis = scene.analysis(ContactOptions::default())?;
    let approach = scene.calibrated_approach(&mut analysis)?;
    for step in 1..=3 {
        analysis.increment(&f, &scene.prescribed(approach * step as f64 / 3.0, 0.0))?;
    }
    let contact_seconds = clock.elapsed().as_secs_f64();
    Ok(ContactRun {
        n,
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

/// The accuracy figures the regression guard watches (`hycon bench guard`): the Hertz scene at
/// 8 and 16 elements per half-width (final-increment L2 error of the multiplier pressure and
/// the absolute relative errors of half-width and peak) and the 7-beta element on Cook's
/// membrane at 8 x 8. About a second in release.
pub fn guard_values() -> Result<Vec<GuardValue>> {
    use crate::contact::iteration::ContactOptions;
    use crate::contact::scene::DiskOnBlock;
    let mut values = Vec::new();
    for n in [8, 16] {
        let scene = DiskOnBlock {
            elements_per_half_width: n,
            ..Default::default()
        }
        .build()?;
        let mut analysis = scene.analysis(ContactOptions::default())?;
        let approach = scene.calibrated_approach(&mut analysis)?;
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
