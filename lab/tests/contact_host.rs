//! The host-assembly path ([`ContactAnalysis::host`]) against the model path on the same
//! problem: a host that hands over its stiffness in CSR (factored by hycon) and a host that
//! solves with its own solver through [`HostSolve`] must give the model path's tractions,
//! states and displacements to round-off, increment after increment, with friction and
//! sliding.
//!
//! The "host" here is built from the reference scene's model the way an FE code would hold it:
//! `K_ff` over its free equations, the right-hand side `f_f - K_fp q_p` per increment, and the
//! contact nodes' coordinates and equation numbers in its own numbering (node ids shifted by
//! 1000 so that any mix-up of numberings shows).

use hycon::assembly::{DofMap, SparsePattern, dof};
use hycon::contact::bodies::{
    Csr, HostElements, HostNode, HostSolve, HostStiffness, HostSystem, Triangle,
};
use hycon::contact::iteration::{
    ContactAnalysis, ContactOptions, ContactPair, Kinematics, NodeResult,
};
use hycon::model::Model;
use hycon::solver::SparseCholesky;
use hycon_lab::scene::{DiskOnBlock, Scene};

mod common;
use common::OwnSolver;

const SHIFT: usize = 1000;

/// What the host holds: its numbering, its `K_ff` (lower CSC) and the contact description.
struct HostSide {
    dofs: DofMap,
    pattern: SparsePattern,
}

impl HostSide {
    fn new(model: &Model) -> Self {
        let (dofs, pattern) = model.assemble_free().unwrap();
        HostSide { dofs, pattern }
    }

    /// `K_ff` in CSR: the lower CSC arrays read as CSR are the upper triangle.
    fn csr(&self) -> Csr {
        let m = self.pattern.matrix();
        Csr {
            n: m.ncols(),
            row_ptr: m.symbolic().col_ptr().to_vec(),
            columns: m.symbolic().row_idx().to_vec(),
            values: m.val().to_vec(),
            triangle: Triangle::Upper,
        }
    }

    /// Every element of the model, in the host's numbering (ids shifted), for stress recovery.
    fn elements(&self, model: &Model) -> HostElements {
        let mesh = &model.mesh;
        HostElements {
            formulation: model.formulation,
            materials: model.materials.clone(),
            element_material: mesh.element_material.clone(),
            offsets: mesh.element_offsets.clone(),
            nodes: mesh.element_nodes.iter().map(|n| n + SHIFT).collect(),
            node_table: (0..mesh.n_nodes())
                .map(|n| HostNode {
                    id: n + SHIFT,
                    position: mesh.nodes[n],
                    equations: [self.dofs.equation(dof(n, 0)), self.dofs.equation(dof(n, 1))],
                })
                .collect(),
        }
    }

    /// `K_ff u` from the stored lower triangle.
    fn times(&self, u: &[f64]) -> Vec<f64> {
        let m = self.pattern.matrix();
        let mut out = vec![0.0; u.len()];
        for j in 0..m.ncols() {
            for (i, v) in m.row_idx_of_col(j).zip(m.val_of_col(j)) {
                out[i] += v * u[j];
                if i != j {
                    out[j] += v * u[i];
                }
            }
        }
        out
    }

    /// The right-hand side `f_f - K_fp q_p` over the free equations.
    fn rhs(&self, model: &Model, qp: &[f64]) -> Vec<f64> {
        let mut held = vec![0.0; qp.len()];
        for (d, v) in held.iter_mut().enumerate() {
            if self.dofs.equation(d).is_none() {
                *v = qp[d];
            }
        }
        let kq = model.internal_forces(&held).unwrap();
        let mut rhs = vec![0.0; self.dofs.n_free()];
        for (d, k) in kq.iter().enumerate() {
            if let Some(i) = self.dofs.equation(d) {
                rhs[i] = -k;
            }
        }
        rhs
    }

    fn system(&self, model: &Model, pair: &ContactPair, stiffness: HostStiffness) -> HostSystem {
        let mut ids: Vec<usize> = pair.a.iter().chain(&pair.b).copied().collect();
        ids.sort_unstable();
        let nodes = ids
            .iter()
            .map(|&n| HostNode {
                id: n + SHIFT,
                position: model.mesh.nodes[n],
                equations: [self.dofs.equation(dof(n, 0)), self.dofs.equation(dof(n, 1))],
            })
            .collect();
        HostSystem {
            equations: self.dofs.n_free(),
            nodes,
            stiffness,
            elements: None,
            a_inside: Vec::new(),
        }
    }
}

fn shifted(pair: &ContactPair) -> ContactPair {
    ContactPair {
        a: pair.a.iter().map(|n| n + SHIFT).collect(),
        b: pair.b.iter().map(|n| n + SHIFT).collect(),
        friction: pair.friction,
    }
}

fn scene() -> Scene {
    DiskOnBlock {
        elements_per_half_width: 8,
        friction: 0.3,
        travel: 1.5,
        ..DiskOnBlock::default()
    }
    .build()
    .unwrap()
}

/// Tractions, states and positions agree (relative to the peak traction and to `a`).
fn assert_same(reference: &[NodeResult], other: &[NodeResult], scale: f64, what: &str) {
    assert_eq!(reference.len(), other.len());
    let peak = reference.iter().fold(0.0f64, |m, r| m.max(r.tn.abs()));
    assert!(peak > 0.0, "{what}: no contact");
    for (r, o) in reference.iter().zip(other) {
        assert_eq!(r.node + SHIFT, o.node, "{what}: node ids");
        assert_eq!(r.state, o.state, "{what}: state of node {}", r.node);
        assert!(
            (r.tn - o.tn).abs() <= 1e-9 * peak && (r.ts - o.ts).abs() <= 1e-9 * peak,
            "{what}: node {}: ({}, {}) vs ({}, {})",
            r.node,
            r.tn,
            r.ts,
            o.tn,
            o.ts
        );
        for d in 0..2 {
            assert!((r.position[d] - o.position[d]).abs() <= 1e-9 * scale);
        }
    }
}

#[test]
fn host_csr_and_host_solver_match_the_model_path() {
    let scene = scene();
    let model = &scene.model;
    // the disk slides by 0.6 half-widths: finite kinematics
    let options = ContactOptions {
        tolerance: 1e-10,
        kinematics: Kinematics::Finite,
        ..ContactOptions::default()
    };
    let host = HostSide::new(model);
    let mut reference = scene.analysis(options).unwrap();
    let mut csr = ContactAnalysis::host(
        host.system(model, &scene.pair, HostStiffness::Csr(host.csr())),
        vec![shifted(&scene.pair)],
        options,
    )
    .unwrap();
    let mut factor =
        SparseCholesky::analyze(host.pattern.symbolic(), hycon::solver::Backend::Faer, &[])
            .unwrap();
    factor.factorize(host.pattern.matrix()).unwrap();
    let own = OwnSolver {
        factor,
        columns: Default::default(),
    };
    let mut callback = ContactAnalysis::host(
        host.system(model, &scene.pair, HostStiffness::Solver(Box::new(own))),
        vec![shifted(&scene.pair)],
        options,
    )
    .unwrap();
    assert_eq!(csr.factorizations(), 1);
    assert_eq!(callback.factorizations(), 0);

    let approach = scene.half_width.powi(2) / scene.radius;
    let f = vec![0.0; 2 * model.mesh.n_nodes()];
    // press, then slide by a few elements (stick, then slip)
    let steps = [
        (approach, 0.0),
        (approach, 0.3 * scene.half_width),
        (approach, 0.6 * scene.half_width),
    ];
    let mut rhs = Vec::new();
    for (i, &(approach, slide)) in steps.iter().enumerate() {
        let qp = scene.prescribed(approach, slide);
        rhs = host.rhs(model, &qp);
        let a = reference.increment(&f, &qp).unwrap();
        let b = csr.increment(&rhs, &[]).unwrap();
        let c = callback.increment(&rhs, &[]).unwrap();
        assert_eq!(
            (a.iterations, a.active, a.slip),
            (b.iterations, b.active, b.slip)
        );
        assert_eq!(
            (a.iterations, a.active, a.slip),
            (c.iterations, c.active, c.slip)
        );
        let r = reference.node_results(0).unwrap();
        assert_same(&r, &csr.node_results(0).unwrap(), scene.half_width, "csr");
        assert_same(
            &r,
            &callback.node_results(0).unwrap(),
            scene.half_width,
            "callback",
        );
        if i == steps.len() - 1 {
            assert!(a.slip > 0, "the last step slides");
        }
    }
    // displacements: the host's equations against the model's free dofs
    let q = reference.displacement().unwrap().to_vec();
    let scale = q.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for analysis in [&mut csr, &mut callback] {
        let u = analysis.displacement().unwrap().to_vec();
        for (d, qd) in q.iter().enumerate() {
            if let Some(i) = host.dofs.equation(d) {
                assert!(
                    (qd - u[i]).abs() <= 1e-9 * scale,
                    "dof {d}: {qd} vs {}",
                    u[i]
                );
            }
        }
        // and the contact forces reproduce them through K: K u = rhs + forces
        let forces = analysis.contact_forces();
        let ku = host.times(&u);
        let f_scale = forces.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(f_scale > 0.0);
        for i in 0..u.len() {
            let residual = ku[i] - rhs[i] - forces[i];
            assert!(
                residual.abs() <= 1e-8 * f_scale,
                "equation {i}: {residual:e}"
            );
        }
    }
}

#[test]
fn host_errors_name_the_problem() {
    let scene = scene();
    let model = &scene.model;
    let host = HostSide::new(model);
    let options = ContactOptions::default();
    // an unknown node in a pair
    let mut pair = shifted(&scene.pair);
    pair.b.push(7);
    let err = ContactAnalysis::host(
        host.system(model, &scene.pair, HostStiffness::Csr(host.csr())),
        vec![pair],
        options,
    )
    .unwrap_err();
    assert!(err.to_string().contains("unknown node 7"), "{err}");
    // a full CSR that is not symmetric
    let mut csr = host.csr();
    csr.triangle = Triangle::Full;
    let err = ContactAnalysis::host(
        host.system(model, &scene.pair, HostStiffness::Csr(csr)),
        vec![shifted(&scene.pair)],
        options,
    )
    .unwrap_err();
    assert!(err.to_string().contains("not symmetric"), "{err}");
    // a failing solver: the error is a callback error
    struct Failing;
    impl HostSolve for Failing {
        fn solve(&mut self, _: usize, _: &[f64], _: &mut [f64]) -> hycon::Result<()> {
            Err(hycon::Error::Callback("out of memory in the host".into()))
        }
    }
    let err = ContactAnalysis::host(
        host.system(model, &scene.pair, HostStiffness::Solver(Box::new(Failing))),
        vec![shifted(&scene.pair)],
        options,
    )
    .unwrap_err();
    assert!(matches!(err, hycon::Error::Callback(_)), "{err}");
}

/// The displacement increment is the difference of two consecutive converged fields, on both
/// paths.
#[test]
fn displacement_increment_is_the_difference_of_totals() {
    let scene = scene();
    let model = &scene.model;
    let host = HostSide::new(model);
    let options = ContactOptions::default();
    let mut analysis = ContactAnalysis::host(
        host.system(model, &scene.pair, HostStiffness::Csr(host.csr())),
        vec![shifted(&scene.pair)],
        options,
    )
    .unwrap();
    let approach = scene.half_width.powi(2) / scene.radius;
    let mut previous = vec![0.0; host.dofs.n_free()];
    for step in [0.5, 1.0, 1.5] {
        let rhs = host.rhs(model, &scene.prescribed(step * approach, 0.0));
        analysis.increment(&rhs, &[]).unwrap();
        let total = analysis.displacement().unwrap().to_vec();
        let du = analysis.displacement_increment().unwrap();
        let scale = total.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for i in 0..total.len() {
            assert!(
                (total[i] - previous[i] - du[i]).abs() <= 1e-10 * scale,
                "equation {i}"
            );
        }
        previous = total;
    }
}

/// Tractions from element stresses (way (a)) on the host path, with the elements handed over,
/// equal the model path's; without the elements they are an error that says what is missing.
#[test]
fn host_stress_tractions_match_the_model_path() {
    let scene = scene();
    let model = &scene.model;
    let host = HostSide::new(model);
    let options = ContactOptions::default();
    let mut reference = scene.analysis(options).unwrap();
    let mut system = host.system(model, &scene.pair, HostStiffness::Csr(host.csr()));
    system.elements = Some(host.elements(model));
    let mut analysis = ContactAnalysis::host(system, vec![shifted(&scene.pair)], options).unwrap();
    let qp = scene.prescribed(scene.half_width.powi(2) / scene.radius, 0.0);
    reference
        .increment(&vec![0.0; 2 * model.mesh.n_nodes()], &qp)
        .unwrap();
    analysis.increment(&host.rhs(model, &qp), &[]).unwrap();
    let a = reference.stress_tractions(0).unwrap();
    let b = analysis.stress_tractions(0).unwrap();
    let peak = a.iter().fold(0.0f64, |m, t| m.max(t.0.abs()));
    assert!(peak > 0.0);
    for (x, y) in a.iter().zip(&b) {
        assert!((x.0 - y.0).abs() <= 1e-9 * peak && (x.1 - y.1).abs() <= 1e-9 * peak);
    }
    let mut bare = ContactAnalysis::host(
        host.system(model, &scene.pair, HostStiffness::Csr(host.csr())),
        vec![shifted(&scene.pair)],
        options,
    )
    .unwrap();
    bare.increment(&host.rhs(model, &qp), &[]).unwrap();
    let err = bare.stress_tractions(0).unwrap_err();
    assert!(err.to_string().contains("elements of body A"), "{err}");
}
