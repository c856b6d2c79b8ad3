//! The two sparse Cholesky backends (faer, CHOLMOD) give the same answers: Cook's membrane, the
//! condensed flexibility of trailing unknowns on a graded mesh, singular systems; plus a timing
//! comparison at about 100k unknowns (printed with `--nocapture`, never asserted). That
//! `Backend::Cholmod` is an error without the feature is a unit test in `src/solver`.
//!
//! Run: `cargo test --features suitesparse --test lab backends:: -- --nocapture`
#![cfg(feature = "suitesparse")]

use faer::Mat;
use faer::sparse::{SparseColMat, Triplet};
use hycon::assembly::dof;
use hycon::element::Formulation;
use hycon::mesh::generate::{self, Grading};
use hycon::model::{LinearSystem, Model};
use hycon::solver::{Backend, SparseCholesky};
use hycon::{Analysis, Error, Material};
use hycon_lab::cases;
use std::time::Instant;

const BACKENDS: [Backend; 2] = [Backend::Faer, Backend::Cholmod];

/// Cook's membrane (as in `cases::cook_membrane`) with `n x n` elements.
fn cook_model(formulation: Formulation, n: usize) -> (Model, usize) {
    let mesh = generate::cooks_membrane(n);
    let material = Material::new(1.0, 1.0 / 3.0, 1.0, Analysis::PlaneStress).unwrap();
    let clamped = mesh.node_sets["clamped"].clone();
    let loaded = mesh.edge_sets["loaded"].clone();
    let tip = mesh.node_sets["tip"][0];
    let mut model = Model::new(mesh, vec![material], formulation);
    model.fix(&clamped, [0.0, 0.0]).unwrap();
    model.load_edges(&loaded, [0.0, 1.0 / 16.0]);
    (model, tip)
}

/// (1) Tip displacement of Cook's membrane: both backends agree to 1e-10 and match the faer
/// path of `cases::cook_membrane` and the published values.
#[test]
fn cook_membrane_tip_agrees() {
    assert!(Backend::Cholmod.available());
    for (formulation, n) in [
        (Formulation::PianSumihara, 16),
        (Formulation::Q4, 16),
        (Formulation::Hybrid, 48),
    ] {
        let (model, tip) = cook_model(formulation, n);
        let v: Vec<f64> = BACKENDS
            .iter()
            .map(|&backend| {
                let mut system = LinearSystem::with_trailing_on(&model, &[], backend).unwrap();
                assert_eq!(system.cholesky().backend(), backend);
                assert_eq!(system.cholesky().factorizations(), 1);
                system.solve(&model).unwrap().displacement(tip)[1]
            })
            .collect();
        let reference = cases::cook_membrane(formulation, n).unwrap();
        println!(
            "Cook {formulation:?} {n}x{n}: faer {:.15} cholmod {:.15} (cases {reference:.15})",
            v[0], v[1]
        );
        assert!((v[0] - v[1]).abs() <= 1e-10 * v[0].abs(), "{v:?}");
        assert!((v[1] - reference).abs() <= 1e-10 * reference.abs());
        let published = cases::COOK_PUBLISHED.iter().find(|p| p.0 == n);
        match (formulation, published) {
            (Formulation::Q4, Some(p)) => assert!((v[1] - p.1).abs() < 6e-4, "{} vs {}", v[1], p.1),
            (Formulation::PianSumihara, Some(p)) => assert!((v[1] - p.2).abs() < 6e-4),
            _ => assert!((v[1] - cases::COOK_CONVERGED).abs() < 0.05, "{}", v[1]),
        }
    }
}

/// A graded rectangle clamped at the bottom, with the top and right sides' dofs (in a
/// scrambled order, plus some prescribed ones that must be skipped) as trailing unknowns.
fn graded_model() -> (Model, Vec<usize>) {
    let grading = Grading::toward_point([2.0, 1.0], 0.01, 3);
    let mesh = generate::graded_rectangle(0.0, 0.0, 4.0, 1.0, 48, 12, &grading);
    let material = Material::new(200.0, 0.3, 1.0, Analysis::PlaneStrain).unwrap();
    let bottom = mesh.node_sets["bottom"].clone();
    let mut trailing: Vec<usize> = mesh.node_sets["top"]
        .iter()
        .chain(&mesh.node_sets["right"])
        .flat_map(|&n| [dof(n, 1), dof(n, 0)])
        .collect();
    trailing.sort_unstable();
    trailing.dedup();
    // deterministic shuffle (an LCG), then two prescribed dofs among them
    let mut state = 12345u64;
    for i in (1..trailing.len()).rev() {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        trailing.swap(i, (state >> 33) as usize % (i + 1));
    }
    trailing.insert(3, dof(bottom[0], 0));
    trailing.push(dof(bottom[1], 1));
    let mut model = Model::new(mesh, vec![material], Formulation::Hybrid);
    model.fix(&bottom, [0.0, 0.0]).unwrap();
    (model, trailing)
}

/// (2) `condensed_inverse` (read off the factor's trailing block) agrees entrywise between the
/// backends and with columns of `K^-1` from solves, to 1e-10 of the largest entry. The
/// trailing order is scrambled and the flexibility is compared unsymmetrised, so a wrong
/// permutation or a transposed block would show.
#[test]
fn condensed_inverse_agrees() {
    let (model, trailing) = graded_model();
    let mut flex = Vec::new();
    for backend in BACKENDS {
        let mut system = LinearSystem::with_trailing_on(&model, &trailing, backend).unwrap();
        let f = system.condensed_flexibility().unwrap();
        let free: Vec<usize> = trailing
            .iter()
            .filter_map(|&d| system.dofs().equation(d))
            .collect();
        // the two inserted bottom dofs (and the bottom-right corner's) are prescribed
        assert!(free.len() + 2 <= trailing.len() && free.len() > 20);
        assert_eq!(f.nrows(), free.len());
        // reference: K^-1 e_j restricted to the trailing equations, by solves
        let n = system.dofs().n_free();
        let mut e = Mat::<f64>::zeros(n, free.len());
        for (j, &i) in free.iter().enumerate() {
            e[(i, j)] = 1.0;
        }
        system.cholesky().solve_in_place(e.as_mut()).unwrap();
        let scale = f.norm_max();
        for (i, &r) in free.iter().enumerate() {
            for j in 0..free.len() {
                assert!(
                    (f[(i, j)] - e[(r, j)]).abs() <= 1e-10 * scale,
                    "{backend}: ({i}, {j}) {} vs solve {}",
                    f[(i, j)],
                    e[(r, j)]
                );
            }
        }
        assert_eq!(system.cholesky().factorizations(), 1);
        println!(
            "{backend}: {} unknowns, {} trailing, nnz(L) {}, max flexibility {scale:.6e}",
            n,
            free.len(),
            system.nnz().1
        );
        flex.push(f);
    }
    let scale = flex[0].norm_max();
    let diff = (&flex[0] - &flex[1]).norm_max();
    println!(
        "condensed flexibility: max |faer - cholmod| / max |entry| = {:.3e}",
        diff / scale
    );
    assert!(diff <= 1e-10 * scale);
    // not symmetric by construction of the check above, but it must be symmetric to round-off
    assert!((&flex[1] - flex[1].transpose()).norm_max() <= 1e-10 * scale);
}

/// (3) Singular systems are errors with a message on both backends, never panics: an
/// unconstrained body, and a stiffness with one dof's row and column zeroed.
#[test]
fn singular_systems_are_errors() {
    let (model, tip) = cook_model(Formulation::Hybrid, 8);
    let free_model = {
        let mut m = model.clone();
        m.prescribed.clear();
        m
    };
    for backend in BACKENDS {
        let err = LinearSystem::with_trailing_on(&free_model, &[], backend).unwrap_err();
        println!("{backend}, unconstrained body: {err}");
        assert!(
            matches!(err, Error::Singular(ref m) if !m.is_empty()),
            "{err}"
        );
    }

    // zero the row and column of the tip's vertical dof (lower triangle)
    let (dofs, pattern) = model.assemble_free().unwrap();
    let zero = dofs.equation(dof(tip, 1)).unwrap();
    let k = pattern.matrix();
    let mut triplets = Vec::new();
    for j in 0..k.ncols() {
        for (&i, &v) in k
            .symbolic()
            .row_idx_of_col_raw(j)
            .iter()
            .zip(k.val_of_col(j))
        {
            let v = if i == zero || j == zero { 0.0 } else { v };
            triplets.push(Triplet::new(i, j, v));
        }
    }
    let singular = SparseColMat::try_new_from_triplets(k.nrows(), k.ncols(), &triplets).unwrap();
    for backend in BACKENDS {
        let mut chol = SparseCholesky::analyze(singular.symbolic(), backend, &[]).unwrap();
        let err = chol.factorize(singular.as_ref()).unwrap_err();
        println!("{backend}, zero column {zero}: {err}");
        assert!(
            matches!(err, Error::Singular(ref m) if m.contains("not positive definite")),
            "{err}"
        );
        if backend == Backend::Cholmod {
            // CHOLMOD reports the exact failing column, mapped back to the caller's numbering.
            assert!(
                err.to_string().contains(&format!("equation {zero}")),
                "{err}"
            );
        }
        assert_eq!(chol.factorizations(), 0);
        assert!(chol.condensed_inverse().is_err());
        // the same object still factors the regular matrix afterwards
        chol.factorize(k).unwrap();
        assert_eq!(chol.factorizations(), 1);
    }
}

/// Distinct objects on distinct threads (each owns its CHOLMOD common), and a factor moved
/// to another thread.
#[test]
fn objects_on_several_threads() {
    let (model, tip) = cook_model(Formulation::Hybrid, 16);
    let reference = {
        let mut s = LinearSystem::with_trailing_on(&model, &[], Backend::Faer).unwrap();
        s.solve(&model).unwrap().displacement(tip)[1]
    };
    let system = LinearSystem::with_trailing_on(&model, &[], Backend::Cholmod).unwrap();
    std::thread::scope(|scope| {
        let moved = scope.spawn(|| {
            let mut system = system;
            system.solve(&model).unwrap().displacement(tip)[1]
        });
        let fresh: Vec<_> = (0..2)
            .map(|_| {
                scope.spawn(|| {
                    let mut s =
                        LinearSystem::with_trailing_on(&model, &[], Backend::Cholmod).unwrap();
                    s.solve(&model).unwrap().displacement(tip)[1]
                })
            })
            .collect();
        for v in fresh
            .into_iter()
            .map(|h| h.join().unwrap())
            .chain([moved.join().unwrap()])
        {
            assert!((v - reference).abs() <= 1e-10 * reference.abs());
        }
    });
}

/// Timing of faer against CHOLMOD on Cook's membrane at about 100k unknowns (Hybrid, 224 x 224
/// elements): analysis, factorization, refactorization, a 64-column solve. Printed only. In
/// the dev profile hycon itself is built at opt-level 1, which slows faer's kernels (they are
/// monomorphised here) but not CHOLMOD's (a prebuilt C library), so release timings favour
/// faer more than these.
#[test]
fn timing_faer_vs_cholmod_100k() {
    let (model, tip) = cook_model(Formulation::Hybrid, 224);
    let (dofs, pattern) = model.assemble_free().unwrap();
    let n = dofs.n_free();
    let f = model.external_forces();
    let mut rhs = Mat::<f64>::zeros(n, 64);
    for (d, &fd) in f.iter().enumerate() {
        if let Some(i) = dofs.equation(d) {
            for j in 0..64 {
                rhs[(i, j)] = fd * (1.0 + j as f64);
            }
        }
    }
    let row = dofs.equation(dof(tip, 1)).unwrap();
    let mut tips = Vec::new();
    println!("{n} unknowns, nnz(K lower) {}", pattern.nnz());
    for backend in BACKENDS {
        let t = Instant::now();
        let mut chol = SparseCholesky::analyze(pattern.symbolic(), backend, &[]).unwrap();
        let analysis = t.elapsed().as_secs_f64();
        let t = Instant::now();
        chol.factorize(pattern.matrix()).unwrap();
        let factor = t.elapsed().as_secs_f64();
        let t = Instant::now();
        chol.factorize(pattern.matrix()).unwrap();
        let refactor = t.elapsed().as_secs_f64();
        let mut x = rhs.clone();
        let t = Instant::now();
        chol.solve_in_place(x.as_mut()).unwrap();
        let solve = t.elapsed().as_secs_f64();
        println!(
            "{backend:>7}: analysis {analysis:6.3} s, factorization {factor:6.3} s, \
             refactorization {refactor:6.3} s, 64-rhs solve {solve:6.3} s, nnz(L) {}",
            chol.nnz_l()
        );
        tips.push(x[(row, 0)]);
        assert_eq!(chol.factorizations(), 2);
    }
    println!(
        "tip displacement: faer {:.12} cholmod {:.12}",
        tips[0], tips[1]
    );
    assert!((tips[0] - tips[1]).abs() <= 1e-10 * tips[0].abs());
}

/// (6) A whole frictional contact analysis (the reference Hertz scene, pressed then slid) runs
/// the same on both backends: states, tractions and iteration counts agree.
#[test]
fn contact_analysis_agrees() {
    use hycon::contact::iteration::{ContactOptions, Kinematics};
    use hycon_lab::scene::DiskOnBlock;
    let scene = DiskOnBlock {
        elements_per_half_width: 8,
        friction: 0.3,
        travel: 1.0,
        ..DiskOnBlock::default()
    }
    .build()
    .unwrap();
    let approach = scene.half_width.powi(2) / scene.radius;
    let f = vec![0.0; 2 * scene.model.mesh.n_nodes()];
    let runs: Vec<_> = BACKENDS
        .iter()
        .map(|&backend| {
            // the disk slides by 0.4 half-widths: finite kinematics
            let options = ContactOptions {
                tolerance: 1e-10,
                backend,
                kinematics: Kinematics::Finite,
                ..ContactOptions::default()
            };
            let mut analysis = scene.analysis(options).unwrap();
            let mut out = Vec::new();
            for slide in [0.0, 0.4 * scene.half_width] {
                let info = analysis
                    .increment(&f, &scene.prescribed(approach, slide))
                    .unwrap();
                out.push((info.iterations, analysis.node_results(0).unwrap()));
            }
            assert_eq!(analysis.factorizations(), 1);
            out
        })
        .collect();
    for ((i0, r0), (i1, r1)) in runs[0].iter().zip(&runs[1]) {
        assert_eq!(i0, i1);
        let peak = r0.iter().fold(0.0f64, |m, r| m.max(r.tn.abs()));
        assert!(peak > 0.0);
        for (a, b) in r0.iter().zip(r1) {
            assert_eq!(a.state, b.state, "node {}", a.node);
            assert!((a.tn - b.tn).abs() <= 1e-9 * peak && (a.ts - b.ts).norm() <= 1e-9 * peak);
        }
    }
}
