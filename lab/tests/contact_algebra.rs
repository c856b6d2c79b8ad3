//! The contact boundary's linear algebra (issue 12) against the dense reference of hycon 0.3
//! ([`ContactAnalysis::set_reference_algebra`]), in the same test run: on the Hertz press, the
//! frictionless and frictional slides and Cattaneo-Mindlin partial slip, and through a host's
//! solve callback, the lazy boundary (the plain fill-reducing factor with `F` built by
//! substitutions within the contact dofs' reach, node flexibilities cached, blocked LU) must
//! give the reference's contact states in every iteration (same record: active, stick, slip,
//! changes), the same converged states and the same tractions to `1e-10` of the peak traction,
//! and condition estimates equal to round-off.

use hycon::assembly::dof;
use hycon::contact::bodies::{HostNode, HostStiffness, HostSystem};
use hycon::contact::iteration::{
    ContactAnalysis, ContactOptions, ContactPair, Kinematics, NodeResult,
};
use hycon::solver::{Backend, SparseCholesky};
use hycon_lab::scene::{DiskOnBlock, Scene};

use crate::common::OwnSolver;

/// Tractions to this fraction of the peak `|tn|`.
const TRACTIONS: f64 = 1e-10;

fn scene(n: usize, friction: f64) -> Scene {
    DiskOnBlock {
        elements_per_half_width: n,
        friction,
        travel: 2.5,
        ..Default::default()
    }
    .build()
    .unwrap()
}

/// States equal, tractions to `TRACTIONS` of the peak.
fn assert_same(reference: &[NodeResult], other: &[NodeResult], what: &str) -> f64 {
    assert_eq!(reference.len(), other.len());
    let peak = reference.iter().fold(0.0f64, |m, r| m.max(r.tn.abs()));
    assert!(peak > 0.0, "{what}: no contact");
    let mut worst = 0.0f64;
    for (r, o) in reference.iter().zip(other) {
        assert_eq!(r.state, o.state, "{what}: state of node {}", r.node);
        let d = (r.tn - o.tn).abs().max((r.ts - o.ts).norm()) / peak;
        worst = worst.max(d);
        assert!(
            d <= TRACTIONS,
            "{what}: node {}: ({}, {:?}) vs ({}, {:?})",
            r.node,
            r.tn,
            r.ts,
            o.tn,
            o.ts
        );
    }
    worst
}

/// Same records (contact sets of every iteration), condition estimates to round-off.
fn assert_same_records(reference: &ContactAnalysis, other: &ContactAnalysis, what: &str) {
    let (r, o) = (reference.records(), other.records());
    assert_eq!(r.len(), o.len(), "{what}: iterations");
    for (a, b) in r.iter().zip(o) {
        assert_eq!(
            (
                a.increment,
                a.iteration,
                a.active,
                a.stick,
                a.slip,
                a.changes
            ),
            (
                b.increment,
                b.iteration,
                b.active,
                b.stick,
                b.slip,
                b.changes
            ),
            "{what}: record"
        );
        assert!(
            (a.condition - b.condition).abs() <= 1e-6 * a.condition,
            "{what}: condition {} vs {}",
            a.condition,
            b.condition
        );
    }
}

/// Run the same increments (`(approach, slide)` totals) on the reference and the lazy
/// algebra, comparing after every increment.
fn compare(scene: &Scene, options: ContactOptions, steps: &[(f64, f64)], what: &str) {
    let mut reference = scene.analysis(options).unwrap();
    reference.set_reference_algebra(true).unwrap();
    let mut lazy = scene.analysis(options).unwrap();
    let f = vec![0.0; 2 * scene.model.mesh.n_nodes()];
    let mut worst = 0.0f64;
    for (i, &(approach, slide)) in steps.iter().enumerate() {
        let qp = scene.prescribed(approach, slide);
        reference.increment(&f, &qp).unwrap();
        lazy.increment(&f, &qp).unwrap();
        worst = worst.max(assert_same(
            &reference.node_results(0).unwrap(),
            &lazy.node_results(0).unwrap(),
            &format!("{what}, increment {}", i + 1),
        ));
    }
    assert_same_records(&reference, &lazy, what);
    println!(
        "{what}: {} increments, {} iterations, largest traction difference {worst:.1e} of the \
         peak",
        steps.len(),
        lazy.records().len()
    );
}

/// The calibrated approach of the scene (the trial increment on a throwaway analysis).
fn approach(scene: &Scene, options: ContactOptions) -> f64 {
    let mut a = scene.analysis(options).unwrap();
    scene.calibrated_approach(&mut a).unwrap()
}

#[test]
fn hertz_press_matches_the_reference() {
    let scene = scene(16, 0.0);
    let options = ContactOptions::default();
    let trial = scene.half_width.powi(2) / scene.radius;
    let c = approach(&scene, options);
    let steps = [(trial, 0.0), (c / 3.0, 0.0), (2.0 * c / 3.0, 0.0), (c, 0.0)];
    compare(&scene, options, &steps, "hertz, frictionless, small");
}

#[test]
fn sliding_matches_the_reference() {
    for friction in [0.0, 0.3] {
        let scene = scene(8, friction);
        let options = ContactOptions {
            kinematics: Kinematics::Finite,
            ..ContactOptions::default()
        };
        let c = approach(&scene, options);
        let steps: Vec<(f64, f64)> = (0..=4)
            .map(|k| (c, 2.0 * scene.half_width * k as f64 / 4.0))
            .collect();
        compare(
            &scene,
            options,
            &steps,
            &format!("sliding, mu = {friction}, finite"),
        );
    }
}

#[test]
fn cattaneo_mindlin_matches_the_reference() {
    let scene = scene(16, 0.3);
    let options = ContactOptions::default();
    let c = approach(&scene, options);
    let h = scene.half_width / 16.0;
    let mut steps = vec![(c, 0.0)];
    steps.extend((1..=10).map(|k| (c, 0.02 * h * k as f64)));
    compare(&scene, options, &steps, "cattaneo-mindlin, mu = 0.3, small");
}

/// Through a solve callback the lazy boundary solves once per node direction that becomes
/// active (and once per load), the reference once per contact dof; both give the same states
/// and tractions.
#[test]
fn callback_path_matches_the_reference_with_fewer_solves() {
    let scene = scene(16, 0.3);
    let model = &scene.model;
    let (dofs, pattern) = model.assemble_free().unwrap();
    let rhs = |qp: &[f64]| -> Vec<f64> {
        let mut held = vec![0.0; qp.len()];
        for (d, v) in held.iter_mut().enumerate() {
            if dofs.equation(d).is_none() {
                *v = qp[d];
            }
        }
        let kq = model.internal_forces(&held).unwrap();
        let mut out = vec![0.0; dofs.n_free()];
        for (d, k) in kq.iter().enumerate() {
            if let Some(i) = dofs.equation(d) {
                out[i] = -k;
            }
        }
        out
    };
    let pair: &ContactPair = &scene.pair;
    let analysis = |columns: std::sync::Arc<std::sync::atomic::AtomicUsize>| {
        let mut factor =
            SparseCholesky::analyze(pattern.matrix().symbolic(), Backend::Faer, &[]).unwrap();
        factor.factorize(pattern.matrix().as_ref()).unwrap();
        let mut ids: Vec<usize> = pair.a.iter().chain(&pair.b).copied().collect();
        ids.sort_unstable();
        let nodes = ids
            .iter()
            .map(|&n| HostNode {
                id: n,
                position: model.mesh.nodes[n].into(),
                equations: [dofs.equation(dof(n, 0)), dofs.equation(dof(n, 1))].into(),
            })
            .collect();
        let system = HostSystem {
            equations: dofs.n_free(),
            nodes,
            stiffness: HostStiffness::Solver(Box::new(OwnSolver { factor, columns })),
            elements: None,
            a_inside: Vec::new(),
            sections: vec![pair.section_on(model).unwrap()],
        };
        ContactAnalysis::host(system, vec![pair.clone()], ContactOptions::default()).unwrap()
    };
    let counts = [0, 1].map(|_| std::sync::Arc::new(std::sync::atomic::AtomicUsize::new(0)));
    let mut reference = analysis(counts[0].clone());
    reference.set_reference_algebra(true).unwrap();
    let mut lazy = analysis(counts[1].clone());
    let c = approach(&scene, ContactOptions::default());
    let h = scene.half_width / 16.0;
    for (i, slide) in [0.0, 0.05 * h, 0.1 * h].into_iter().enumerate() {
        let b = rhs(&scene.prescribed(c, slide));
        reference.increment(&b, &[]).unwrap();
        lazy.increment(&b, &[]).unwrap();
        assert_same(
            &reference.node_results(0).unwrap(),
            &lazy.node_results(0).unwrap(),
            &format!("callback, increment {}", i + 1),
        );
    }
    assert_same_records(&reference, &lazy, "callback");
    let [reference_solves, lazy_solves] =
        counts.map(|c| c.load(std::sync::atomic::Ordering::Relaxed));
    let contact_dofs = 2 * (pair.a.len() + pair.b.len());
    println!(
        "callback: {contact_dofs} contact dofs; solves: reference {reference_solves}, lazy \
         {lazy_solves}"
    );
    assert!(reference_solves >= contact_dofs);
    assert!(lazy_solves < reference_solves / 2, "{lazy_solves}");
}

/// Threads change nothing but time (`ContactOptions::threads`): on Cattaneo-Mindlin partial
/// slip (small kinematics, friction, image batches added as nodes enter), every record (with
/// `R` and the condition estimate) and every node's state and tractions are the same to the
/// bit with 1 and with 3 threads.
#[test]
fn threads_change_nothing_to_the_bit() {
    let scene = scene(32, 0.3);
    let c = approach(&scene, ContactOptions::default());
    let h = scene.half_width / 32.0;
    let mut steps = vec![(c / 2.0, 0.0), (c, 0.0)];
    steps.extend((1..=4).map(|k| (c, 0.05 * h * k as f64)));
    let f = vec![0.0; 2 * scene.model.mesh.n_nodes()];
    let run = |threads: usize| {
        let mut a = scene
            .analysis(ContactOptions {
                threads,
                ..ContactOptions::default()
            })
            .unwrap();
        let mut results = Vec::new();
        for &(approach, slide) in &steps {
            a.increment(&f, &scene.prescribed(approach, slide)).unwrap();
            results.extend(a.node_results(0).unwrap().into_iter().map(|r| {
                (
                    r.node,
                    r.state,
                    r.tn.to_bits(),
                    r.ts.components()[0].to_bits(),
                )
            }));
        }
        let records: Vec<_> = a
            .records()
            .iter()
            .map(|r| {
                (
                    r.active,
                    r.stick,
                    r.slip,
                    r.changes,
                    r.r.to_bits(),
                    r.condition.to_bits(),
                )
            })
            .collect();
        (records, results)
    };
    let (one, three) = (run(1), run(3));
    assert!(one.1.iter().any(|r| r.2 != 0), "the scene makes contact");
    assert_eq!(one.0, three.0, "records");
    assert_eq!(one.1, three.1, "states and tractions");
    println!(
        "threads 1 and 3: {} iterations, {} node results, all the same to the bit",
        one.0.len(),
        one.1.len()
    );
}
