//! The 3D host path (`ContactAnalysis::solid_host`, and through the C ABI
//! `hycon_solid_host_*` with `hycon_solid_contact_new_host`) against `ContactAnalysis::solid` on
//! the same brick model: the host is the model's own `K_ff` handed over as a CSR matrix, as a
//! solve callback that factors it, or as its condensed flexibility, with the model's prescribed
//! motion in its right-hand side `-K_fp u_p`. A block turned by 30 degrees pressed on a flat and
//! dragged (friction, slip), and the quarter cap at `a/h = 4` with its two symmetry planes (a
//! component of every node on a plane held by the host). The results agree to round-off
//! (`1e-10` of each quantity's largest value: the two paths factor `K` in different orders);
//! bad input is named, each case with its own check.

use crate::common::block_on_flat_model;
use crate::common::last_error;
use faer::Mat;
use hycon::contact::bodies::{
    Condensed, CondensedKind, Csr, HostNode, HostSolve, HostStiffness, HostSystem, Triangle,
};
use hycon::contact::faces::SymmetryPlane;
use hycon::contact::iteration::{ContactAnalysis, ContactOptions, FacePair, NodeState};
use hycon::contact::space::Vector;
use hycon::ffi::*;
use hycon::solid::contact_meshes::{BlockOnFlat, CapModel, CapOnBlock, ContactMesh};
use hycon::solid::model::{SolidModel, SolidSystem};
use hycon::solid::{BrickFormulation, Isotropic};
use hycon::solver::Backend;
use std::ffi::c_void;
use std::ptr::{null, null_mut};

const FRICTION: f64 = 0.3;
const PRESS: f64 = 1e-3;
const DRAG: f64 = 2e-2;

/// A brick model with its pairs, planes and the prescribed values of its increments.
struct Scene {
    c: ContactMesh,
    model: SolidModel,
    pair: FacePair,
    planes: Vec<SymmetryPlane>,
    /// Total prescribed values per increment (over all `3 n_nodes` dofs).
    increments: Vec<Vec<f64>>,
    /// A point inside body A: A and B touch where they are near each other, so that the faces
    /// alone cannot tell facing surfaces from back-to-back ones.
    inside: Option<[f64; 3]>,
}

/// The turned block pressed on the flat, then dragged along x (friction, slip).
fn block() -> Scene {
    let c = BlockOnFlat {
        size: [1.0, 1.0, 0.5],
        cells: [2, 2, 1],
        flat: [3.0, 3.0, 1.0],
        flat_cells: [3, 3, 1],
        angle: 30.0,
    }
    .build()
    .unwrap();
    let model = block_on_flat_model(&c, &[0, 1, 2]);
    let increments = [0.0, DRAG]
        .iter()
        .map(|&drag| {
            let mut qp = vec![0.0; 3 * c.mesh.n_nodes()];
            for &n in &c.a_top {
                qp[3 * n] = drag;
                qp[3 * n + 2] = -PRESS;
            }
            qp
        })
        .collect();
    Scene {
        inside: Some(inside(&c)),
        pair: FacePair {
            a: c.a_faces.clone(),
            b: c.b_faces.clone(),
            friction: FRICTION,
        },
        c,
        model,
        planes: Vec::new(),
        increments,
    }
}

/// The centroid of the brick that owns A's first face: a point inside body A.
fn inside(c: &ContactMesh) -> [f64; 3] {
    let (e, _) = c.mesh.locate_face(c.a_faces[0]).unwrap();
    let mut p = [0.0; 3];
    for &n in &c.mesh.elements[e] {
        for (p, x) in p.iter_mut().zip(c.mesh.nodes[n]) {
            *p += x / 8.0;
        }
    }
    p
}

/// The quarter cap at `a/h = 4` on the block, its nodes on the planes `x = 0` and `y = 0` held
/// normal to them, the block's bottom held, the cap's top pressed by `0.02` (friction 0.2).
fn quarter_cap() -> Scene {
    let c = CapOnBlock::new(CapModel::Quarter, 4).build().unwrap();
    let material = Isotropic::new(1.0, 0.3).unwrap();
    let mut model = SolidModel::new(
        c.mesh.clone(),
        vec![material; 2],
        BrickFormulation::Hybrid18,
    )
    .unwrap();
    model.prescribe(&c.b_bottom, &[0, 1, 2]).unwrap();
    for (plane, nodes) in &c.symmetry {
        let d = plane.normal.iter().position(|&v| v != 0.0).unwrap();
        for &n in nodes {
            model.fix(n, d, 0.0);
        }
    }
    for &n in &c.a_top {
        model.fix(n, 2, 0.0);
    }
    let mut qp = vec![0.0; 3 * c.mesh.n_nodes()];
    for &n in &c.a_top {
        qp[3 * n + 2] = -0.02;
    }
    Scene {
        inside: Some(inside(&c)),
        pair: FacePair {
            a: c.a_faces.clone(),
            b: c.b_faces.clone(),
            friction: 0.2,
        },
        planes: c.symmetry.iter().map(|(p, _)| *p).collect(),
        c,
        model,
        increments: vec![qp],
    }
}

/// The model as a host sees it: `K_ff` factored (the callback's solver), its equations per
/// global dof, the contact nodes (every node of the pair's faces, in increasing id order, as
/// `ContactAnalysis::solid` numbers them) and `K_ff` as an upper-triangle CSR.
struct ModelHost {
    system: SolidSystem,
    equation: Vec<Option<usize>>,
    nodes: Vec<HostNode>,
    csr: Csr,
}

impl ModelHost {
    fn new(s: &Scene) -> Self {
        let system = SolidSystem::with_trailing_on(&s.model, &[], Backend::Faer).unwrap();
        let equation: Vec<Option<usize>> = (0..3 * s.c.mesh.n_nodes())
            .map(|d| system.dofs().equation(d))
            .collect();
        let mut ids: Vec<usize> = s
            .pair
            .a
            .iter()
            .chain(&s.pair.b)
            .flatten()
            .copied()
            .collect();
        ids.sort_unstable();
        ids.dedup();
        let nodes = ids
            .iter()
            .map(|&id| HostNode {
                id,
                position: Vector::from_components(&s.c.mesh.nodes[id]),
                equations: [0, 1, 2].map(|d| equation[3 * id + d]).into(),
            })
            .collect();
        // the lower triangle by columns is the upper triangle by rows
        let k = system.matrix();
        let n = k.ncols();
        let mut csr = Csr {
            n,
            row_ptr: vec![0],
            columns: Vec::new(),
            values: Vec::new(),
            triangle: Triangle::Upper,
        };
        for j in 0..n {
            csr.columns.extend(k.row_idx_of_col(j));
            csr.values.extend_from_slice(k.val_of_col(j));
            csr.row_ptr.push(csr.columns.len());
        }
        ModelHost {
            system,
            equation,
            nodes,
            csr,
        }
    }

    /// The host's right-hand side of the prescribed values `qp`: `-K_fp u_p` at its equations.
    fn rhs(&self, model: &SolidModel, qp: &[f64]) -> Vec<f64> {
        let mut up = vec![0.0; qp.len()];
        for (d, _) in model.prescribed() {
            up[d] = qp[d];
        }
        let k_up = model.internal_forces(&up).unwrap();
        let mut rhs = vec![0.0; self.csr.n];
        for (d, e) in self.equation.iter().enumerate() {
            if let Some(e) = e {
                rhs[*e] = -k_up[d];
            }
        }
        rhs
    }

    /// `K^-1 B` for the columns of `b` (`n x nrhs`, column-major).
    fn solve(&mut self, nrhs: usize, b: &[f64]) -> Vec<f64> {
        let n = self.csr.n;
        let mut m = Mat::from_fn(n, nrhs, |i, j| b[i + n * j]);
        self.system.solve_in_place(&mut m).unwrap();
        (0..n * nrhs).map(|k| m[(k % n, k / n)]).collect()
    }

    /// The contact nodes' equations, in node order.
    fn contact_equations(&self) -> Vec<usize> {
        self.nodes
            .iter()
            .flat_map(|n| n.equations.given())
            .collect()
    }
}

/// The host's solve callback: its own factor of `K_ff`.
struct Factored(ModelHost);

impl HostSolve for Factored {
    fn solve(&mut self, nrhs: usize, rhs: &[f64], x: &mut [f64]) -> hycon::error::Result<()> {
        x.copy_from_slice(&self.0.solve(nrhs, rhs));
        Ok(())
    }
}

/// How the host hands its stiffness over.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Handover {
    Csr,
    Callback,
    Condensed,
}

/// The model's own analysis after every increment.
fn solid(s: &Scene) -> ContactAnalysis {
    let mut analysis = ContactAnalysis::solid(
        s.model.clone(),
        vec![s.pair.clone()],
        &s.planes,
        ContactOptions::default(),
    )
    .unwrap();
    let f = vec![0.0; 3 * s.c.mesh.n_nodes()];
    for qp in &s.increments {
        analysis.increment(&f, qp).unwrap();
    }
    analysis
}

/// The host's analysis after every increment, and its right-hand side of the last.
fn host(s: &Scene, handover: Handover) -> (ContactAnalysis, Vec<f64>) {
    let mut h = ModelHost::new(s);
    let rhs: Vec<Vec<f64>> = s.increments.iter().map(|qp| h.rhs(&s.model, qp)).collect();
    let candidates = h.contact_equations();
    // the load image of each increment (the condensed hand-over's load): u0 at the candidates
    let images: Vec<Vec<f64>> = (rhs.iter())
        .map(|b| {
            let u0 = h.solve(1, b);
            candidates.iter().map(|&e| u0[e]).collect()
        })
        .collect();
    let nodes = h.nodes.clone();
    let stiffness = match handover {
        Handover::Csr => HostStiffness::Csr(h.csr.clone()),
        Handover::Callback => HostStiffness::Solver(Box::new(Factored(h))),
        Handover::Condensed => {
            let n = h.csr.n;
            let m = candidates.len();
            let mut units = vec![0.0; n * m];
            for (j, &e) in candidates.iter().enumerate() {
                units[e + n * j] = 1.0;
            }
            let x = h.solve(m, &units);
            let matrix = (0..m * m)
                .map(|k| x[candidates[k % m] + n * (k / m)])
                .collect();
            HostStiffness::Condensed(Condensed {
                kind: CondensedKind::Flexibility,
                equations: candidates,
                matrix,
            })
        }
    };
    let system = HostSystem {
        equations: rhs[0].len(),
        nodes,
        stiffness,
        elements: None,
        a_inside: vec![s.inside.map(|p| Vector::solid(p[0], p[1], p[2]))],
        sections: Vec::new(),
    };
    let mut analysis = ContactAnalysis::solid_host(
        system,
        vec![s.pair.clone()],
        &s.planes,
        ContactOptions::default(),
    )
    .unwrap();
    let loads = if handover == Handover::Condensed {
        &images
    } else {
        &rhs
    };
    for load in loads {
        analysis.increment(load, &[]).unwrap();
    }
    let last = rhs.last().unwrap().clone();
    (analysis, last)
}

/// `got` against `expected`, each entry within `1e-10` of the largest `|expected|`.
fn close(what: &str, got: &[f64], expected: &[f64]) {
    assert_eq!(got.len(), expected.len(), "{what}");
    let scale = expected.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    assert!(scale > 0.0, "{what}: all zero");
    for (i, (g, e)) in got.iter().zip(expected).enumerate() {
        assert!(
            (g - e).abs() <= 1e-10 * scale,
            "{what}[{i}]: {g:e} against {e:e} (scale {scale:e})"
        );
    }
}

/// The host's per-node results, contact forces and (unless condensed) displacement are the
/// model's: the states alike, the values to round-off. Returns the states seen.
fn agree(
    s: &Scene,
    host: &ContactAnalysis,
    model: &ContactAnalysis,
    handover: Handover,
) -> Vec<NodeState> {
    let (h, m) = (
        host.node_results(0).unwrap(),
        model.node_results(0).unwrap(),
    );
    assert_eq!(h.len(), m.len());
    for (a, b) in h.iter().zip(&m) {
        assert_eq!(a.node, b.node);
        assert_eq!(a.state.name(), b.state.name(), "node {}", a.node);
    }
    let flat = |r: &[hycon::contact::iteration::NodeResult],
                f: &dyn Fn(&hycon::contact::iteration::NodeResult) -> Vec<f64>|
     -> Vec<f64> { r.iter().flat_map(f).collect() };
    let traction = |r: &hycon::contact::iteration::NodeResult| {
        let mut v = vec![r.tn];
        v.extend_from_slice(r.ts.components());
        v
    };
    close("traction", &flat(&h, &traction), &flat(&m, &traction));
    let frame = |r: &hycon::contact::iteration::NodeResult| {
        let mut v = r.frame.normal().components().to_vec();
        for i in 0..2 {
            v.extend_from_slice(r.frame.tangent(i).components());
        }
        v
    };
    close("frame", &flat(&h, &frame), &flat(&m, &frame));
    let force = |r: &hycon::contact::iteration::NodeResult| r.force.components().to_vec();
    close("force", &flat(&h, &force), &flat(&m, &force));
    let weight = |r: &hycon::contact::iteration::NodeResult| vec![r.weight];
    close("weight", &flat(&h, &weight), &flat(&m, &weight));
    let (hb, mb) = (
        host.b_node_results(0).unwrap(),
        model.b_node_results(0).unwrap(),
    );
    let b_force = |r: &[hycon::contact::iteration::BNodeResult]| -> Vec<f64> {
        r.iter()
            .flat_map(|b| b.force.components().to_vec())
            .collect()
    };
    assert_eq!(
        hb.iter().map(|b| b.node).collect::<Vec<_>>(),
        mb.iter().map(|b| b.node).collect::<Vec<_>>()
    );
    close("B force", &b_force(&hb), &b_force(&mb));
    // the contact forces and the displacement over the host's equations
    let eq = ModelHost::new(s).equation;
    let at_equations = |field: &[f64]| -> Vec<f64> {
        let mut out = vec![0.0; host.field_len()];
        for (d, e) in eq.iter().enumerate() {
            if let Some(e) = e {
                out[*e] = field[d];
            }
        }
        out
    };
    close(
        "contact forces",
        &host.contact_forces(),
        &at_equations(&model.contact_forces()),
    );
    if handover == Handover::Condensed {
        let e = host.displacement().unwrap_err().to_string();
        assert!(e.contains("condensed operator"), "{e}");
    } else {
        close(
            "displacement",
            host.displacement().unwrap(),
            &at_equations(model.displacement().unwrap()),
        );
    }
    m.iter().map(|r| r.state).collect()
}

#[test]
fn a_host_of_the_turned_block_gets_the_models_results() {
    let s = block();
    let model = solid(&s);
    for handover in [Handover::Csr, Handover::Callback, Handover::Condensed] {
        let (host, _) = host(&s, handover);
        let states = agree(&s, &host, &model, handover);
        // the drag makes the block slip, with friction
        assert!(
            states.iter().any(|s| matches!(s, NodeState::Slip { .. })),
            "{handover:?}: {states:?}"
        );
        assert_eq!(
            host.factorizations(),
            usize::from(handover == Handover::Csr)
        );
    }
}

#[test]
fn a_host_of_the_quarter_cap_gets_the_models_results() {
    let s = quarter_cap();
    let model = solid(&s);
    for handover in [Handover::Csr, Handover::Callback] {
        let (host, _) = host(&s, handover);
        let states = agree(&s, &host, &model, handover);
        let active = states.iter().filter(|s| **s != NodeState::Open).count();
        assert!(active > 4, "{handover:?}: {active} active");
        // a node on a symmetry plane has a dropped tangent, held by the host
        let r = host.node_results(0).unwrap();
        assert!(
            r.iter()
                .any(|r| r.frame.tangent(0).norm() == 0.0 || r.frame.tangent(1).norm() == 0.0)
        );
    }
}

// ------------------------------------------------------------------------------------------
// Through the C ABI

/// The C solve callback: `user_data` is a `ModelHost`.
unsafe extern "C" fn solve(
    user_data: *mut c_void,
    n: usize,
    nrhs: usize,
    rhs: *const f64,
    x: *mut f64,
) -> i32 {
    // SAFETY: hycon passes the user data given and buffers of `n nrhs` doubles.
    let h = unsafe { &mut *user_data.cast::<ModelHost>() };
    let b = unsafe { std::slice::from_raw_parts(rhs, n * nrhs) };
    let out = h.solve(nrhs, b);
    unsafe { std::ptr::copy_nonoverlapping(out.as_ptr(), x, n * nrhs) };
    0
}

/// The C host's arrays: the contact nodes' view and the faces, flat.
struct CArrays {
    ids: Vec<usize>,
    coords: Vec<f64>,
    equations: Vec<i64>,
    a: Vec<usize>,
    b: Vec<usize>,
}

impl CArrays {
    fn new(s: &Scene, h: &ModelHost) -> Self {
        CArrays {
            ids: h.nodes.iter().map(|n| n.id).collect(),
            coords: h
                .nodes
                .iter()
                .flat_map(|n| n.position.components().to_vec())
                .collect(),
            equations: (h.nodes.iter())
                .flat_map(|n| {
                    n.equations
                        .as_slice()
                        .iter()
                        .map(|e| e.map_or(HYCON_FIXED, |e| e as i64))
                })
                .collect(),
            a: s.pair.a.as_flattened().to_vec(),
            b: s.pair.b.as_flattened().to_vec(),
        }
    }

    fn nodes(&self) -> HyconSolidHostNodes {
        HyconSolidHostNodes {
            ids: self.ids.as_ptr(),
            coords: self.coords.as_ptr(),
            equations: self.equations.as_ptr(),
            n: self.ids.len(),
        }
    }

    fn faces(f: &[usize]) -> HyconHostFaces {
        HyconHostFaces {
            nodes: f.as_ptr(),
            n: f.len() / 4,
        }
    }
}

/// A C host description of the scene (nodes, pair, point inside A, planes), no stiffness yet.
fn c_host(s: &Scene, h: &ModelHost, arrays: &CArrays) -> *mut HyconSolidHost {
    let mut host = null_mut();
    let mut index = usize::MAX;
    // SAFETY: live handles and arrays of the stated lengths.
    unsafe {
        assert_eq!(hycon_solid_host_new(&mut host, h.csr.n), HYCON_OK);
        let s1 = hycon_solid_host_add_nodes(host, &arrays.nodes());
        assert_eq!(s1, HYCON_OK, "{}", last_error());
        let (fa, fb) = (CArrays::faces(&arrays.a), CArrays::faces(&arrays.b));
        let s2 = hycon_solid_host_add_pair(host, &fa, &fb, s.pair.friction, &mut index);
        assert_eq!((s2, index), (HYCON_OK, 0), "{}", last_error());
        let p = s.inside.unwrap();
        assert_eq!(
            hycon_solid_host_set_pair_inside(host, 0, p.as_ptr()),
            HYCON_OK
        );
        for plane in &s.planes {
            let st = hycon_solid_host_add_symmetry_plane(
                host,
                plane.point.as_ptr(),
                plane.normal.as_ptr(),
            );
            assert_eq!(st, HYCON_OK, "{}", last_error());
        }
    }
    host
}

/// A size-convention query filled into a vector.
fn fetch<T: Default + Clone>(query: impl Fn(*mut T, usize, *mut usize) -> HyconStatus) -> Vec<T> {
    let mut n = 0;
    assert_eq!(query(null_mut(), 0, &mut n), HYCON_OK, "{}", last_error());
    let mut out = vec![T::default(); n];
    assert_eq!(
        query(out.as_mut_ptr(), n, null_mut()),
        HYCON_OK,
        "{}",
        last_error()
    );
    out
}

/// The C host (CSR and callback) gives the Rust host's results to the bit, and so the model's
/// to round-off.
#[test]
fn the_c_host_gives_the_rust_hosts_results() {
    let s = block();
    for handover in [Handover::Csr, Handover::Callback] {
        let (rust, _) = host(&s, handover);
        let mut h = ModelHost::new(&s);
        let arrays = CArrays::new(&s, &h);
        let rhs: Vec<Vec<f64>> = s.increments.iter().map(|qp| h.rhs(&s.model, qp)).collect();
        let c = c_host(&s, &h, &arrays);
        let mut contact = null_mut();
        // SAFETY: live handles, arrays of the stated lengths; `h` outlives the analysis.
        unsafe {
            let st = match handover {
                Handover::Csr => hycon_solid_host_set_csr(
                    c,
                    h.csr.row_ptr.as_ptr(),
                    h.csr.columns.as_ptr(),
                    h.csr.values.as_ptr(),
                    HYCON_CSR_UPPER,
                ),
                _ => hycon_solid_host_set_solver(c, Some(solve), std::ptr::from_mut(&mut h).cast()),
            };
            assert_eq!(st, HYCON_OK, "{}", last_error());
            let equations = fetch(|o, l, n| hycon_solid_host_contact_equations(c, o, l, n));
            assert_eq!(
                equations,
                h.contact_equations()
                    .iter()
                    .map(|&e| e as i64)
                    .collect::<Vec<_>>()
            );
            let st = hycon_solid_contact_new_host(&mut contact, c, null());
            hycon_solid_host_free(c);
            assert_eq!(st, HYCON_OK, "{}", last_error());
            for load in &rhs {
                let mut info = HyconIncrementInfo::default();
                let st = hycon_solid_contact_increment(
                    contact,
                    load.as_ptr(),
                    load.len(),
                    null(),
                    0,
                    &mut info,
                );
                assert_eq!(st, HYCON_OK, "{}", last_error());
            }
            let nodes = fetch(|o, l, n| hycon_solid_contact_node_results(contact, 0, o, l, n));
            let u = fetch(|o, l, n| hycon_solid_contact_displacement(contact, o, l, n));
            let forces = fetch(|o, l, n| hycon_solid_contact_forces(contact, o, l, n));
            hycon_solid_contact_free(contact);
            let expect = rust.node_results(0).unwrap();
            assert_eq!(nodes.len(), expect.len());
            for (got, r) in nodes.iter().zip(&expect) {
                assert_eq!(got.node, r.node);
                assert_eq!(got.tn, r.tn);
                assert_eq!(got.ts.as_slice(), r.ts.components());
                assert_eq!(got.normal.as_slice(), r.frame.normal().components());
                assert_eq!(got.force.as_slice(), r.force.components());
                assert_eq!(
                    got.state == HYCON_NODE_SLIP,
                    matches!(r.state, NodeState::Slip { .. })
                );
            }
            assert_eq!(u, rust.displacement().unwrap());
            assert_eq!(forces, rust.contact_forces());
        }
    }
}

// ------------------------------------------------------------------------------------------
// Bad input

/// The Rust constructor's error for the block's host with `edit` applied to its system and
/// pair.
fn refused(edit: impl FnOnce(&mut HostSystem, &mut FacePair)) -> String {
    let s = block();
    let h = ModelHost::new(&s);
    let mut system = HostSystem {
        equations: h.csr.n,
        nodes: h.nodes.clone(),
        stiffness: HostStiffness::Csr(h.csr.clone()),
        elements: None,
        a_inside: vec![s.inside.map(|p| Vector::solid(p[0], p[1], p[2]))],
        sections: Vec::new(),
    };
    let mut pair = s.pair.clone();
    edit(&mut system, &mut pair);
    ContactAnalysis::solid_host(system, vec![pair], &[], ContactOptions::default())
        .unwrap_err()
        .to_string()
}

#[test]
fn bad_host_input_is_named_in_the_core() {
    let check = |e: String, what: &str| assert!(e.contains(what), "{e}");
    let e = refused(|_, p| p.a[0][2] = p.a[0][0]);
    check(e.clone(), "contact pair 0: A face 0");
    check(e, "appears twice");
    check(refused(|_, p| p.b[0][0] = p.a[0][0]), "is also on side B");
    check(
        refused(|_, p| p.a.push(p.a[0])),
        "is listed twice in the pair",
    );
    check(refused(|_, p| p.friction = -1.0), "friction");
    check(refused(|_, p| p.b.clear()), "contact side B has no face");
    check(
        refused(|_, p| p.a[0][1] = 1_000_000),
        "node 1000000 is not one of the host's contact nodes",
    );
    // the A faces reversed: A and B turn the same way, so they never face each other; both
    // reversed (back to back, which touching faces cannot tell): the point inside A lies on
    // A's outward side
    check(
        refused(|_, p| p.a.iter_mut().for_each(|f| f.reverse())),
        "the sides never face each other",
    );
    check(
        refused(|_, p| {
            p.a.iter_mut().chain(&mut p.b).for_each(|f| f.reverse());
        }),
        "lies on the outward side of A face",
    );
    // touching everywhere: without a point inside A the side is not known
    check(
        refused(|s, _| s.a_inside.clear()),
        "Say which side body A is on",
    );
    check(
        refused(|s, _| s.a_inside.push(None)),
        "a_inside has 2 entries for 1 pairs",
    );
    // a face squashed flat (one corner moved onto the opposite one)
    check(
        refused(|s, p| {
            let (k, l) = (p.b[0][0], p.b[0][2]);
            let target = s.nodes.iter().find(|n| n.id == l).unwrap().position;
            s.nodes.iter_mut().find(|n| n.id == k).unwrap().position = target;
        }),
        "B face 0",
    );
    // plane nodes, plane concepts
    check(
        refused(|s, _| {
            for n in &mut s.nodes {
                let [x, y, _] = [n.position[0], n.position[1], n.position[2]];
                n.position = Vector::plane(x, y);
                n.equations = [n.equations.get(0), n.equations.get(1)].into();
            }
        }),
        "3 components per contact node; its contact nodes have 2",
    );
    check(
        refused(|s, _| {
            s.sections = vec![
                hycon::contact::handover::Section::new(hycon::material::Analysis::PlaneStrain, 1.0)
                    .unwrap(),
            ]
        }),
        "a 3D host gives no sections and no elements",
    );
}

#[test]
fn bad_c_host_input_is_named() {
    let s = block();
    let h = ModelHost::new(&s);
    let arrays = CArrays::new(&s, &h);
    let expect = |status: HyconStatus, code: HyconStatus, what: &str| {
        assert_eq!(status, code, "{}", last_error());
        let m = last_error();
        assert!(m.contains(what), "{m}");
    };
    // SAFETY: live handles and arrays of the stated lengths, or NULL where a test says so.
    unsafe {
        let mut host = null_mut();
        expect(
            hycon_solid_host_new(&mut host, 0),
            HYCON_ERROR_INVALID_ARGUMENT,
            "n_equations = 0",
        );
        expect(
            hycon_solid_host_new(null_mut(), 3),
            HYCON_ERROR_NULL_POINTER,
            "out",
        );
        assert_eq!(hycon_solid_host_new(&mut host, h.csr.n), HYCON_OK);
        expect(
            hycon_solid_host_add_nodes(host, null()),
            HYCON_ERROR_NULL_POINTER,
            "nodes",
        );
        // an equation out of range, a non-finite coordinate
        let mut bad = CArrays::new(&s, &h);
        bad.equations[4] = h.csr.n as i64;
        expect(
            hycon_solid_host_add_nodes(host, &bad.nodes()),
            HYCON_ERROR_INVALID_ARGUMENT,
            "is out of range",
        );
        let mut bad = CArrays::new(&s, &h);
        bad.coords[2] = f64::NAN;
        expect(
            hycon_solid_host_add_nodes(host, &bad.nodes()),
            HYCON_ERROR_INVALID_ARGUMENT,
            "nodes.coords",
        );
        // a face before its nodes
        let (fa, fb) = (CArrays::faces(&arrays.a), CArrays::faces(&arrays.b));
        expect(
            hycon_solid_host_add_pair(host, &fa, &fb, 0.3, null_mut()),
            HYCON_ERROR_INVALID_ARGUMENT,
            "is not a contact node (hycon_solid_host_add_nodes)",
        );
        assert_eq!(hycon_solid_host_add_nodes(host, &arrays.nodes()), HYCON_OK);
        // a node again, moved
        let mut moved = CArrays::new(&s, &h);
        moved.coords[0] += 1.0;
        expect(
            hycon_solid_host_add_nodes(host, &moved.nodes()),
            HYCON_ERROR_INVALID_ARGUMENT,
            "was given before with other coordinates",
        );
        expect(
            hycon_solid_host_add_pair(host, null(), &fb, 0.3, null_mut()),
            HYCON_ERROR_NULL_POINTER,
            "a",
        );
        let mut twice = arrays.a.clone();
        twice[1] = twice[0];
        expect(
            hycon_solid_host_add_pair(host, &CArrays::faces(&twice), &fb, 0.3, null_mut()),
            HYCON_ERROR_INVALID_ARGUMENT,
            "appears twice",
        );
        expect(
            hycon_solid_host_add_pair(host, &fa, &fb, f64::NAN, null_mut()),
            HYCON_ERROR_INVALID_ARGUMENT,
            "friction",
        );
        // no pair yet
        let mut contact = null_mut();
        expect(
            hycon_solid_contact_new_host(&mut contact, host, null()),
            HYCON_ERROR_INVALID_ARGUMENT,
            "no contact pair",
        );
        assert_eq!(
            hycon_solid_host_add_pair(host, &fa, &fb, 0.3, null_mut()),
            HYCON_OK
        );
        let p = [0.0, 0.0, f64::INFINITY];
        expect(
            hycon_solid_host_set_pair_inside(host, 0, p.as_ptr()),
            HYCON_ERROR_INVALID_ARGUMENT,
            "inside",
        );
        expect(
            hycon_solid_host_set_pair_inside(host, 1, s.inside.unwrap().as_ptr()),
            HYCON_ERROR_INVALID_ARGUMENT,
            "pair 1 is unknown",
        );
        let zero = [0.0; 3];
        expect(
            hycon_solid_host_add_symmetry_plane(host, zero.as_ptr(), zero.as_ptr()),
            HYCON_ERROR_INVALID_ARGUMENT,
            "normal",
        );
        // no stiffness yet; then a bad triangle, a NULL solver
        expect(
            hycon_solid_contact_new_host(&mut contact, host, null()),
            HYCON_ERROR_INVALID_ARGUMENT,
            "hycon_solid_host_set_csr",
        );
        expect(
            hycon_solid_host_set_csr(
                host,
                h.csr.row_ptr.as_ptr(),
                h.csr.columns.as_ptr(),
                h.csr.values.as_ptr(),
                7,
            ),
            HYCON_ERROR_INVALID_ARGUMENT,
            "triangle = 7",
        );
        expect(
            hycon_solid_host_set_csr(
                host,
                h.csr.row_ptr.as_ptr(),
                h.csr.columns.as_ptr(),
                h.csr.values.as_ptr(),
                HYCON_CSR_LOWER,
            ),
            HYCON_ERROR_INVALID_ARGUMENT,
            "outside the declared Lower triangle",
        );
        expect(
            hycon_solid_host_set_solver(host, None, null_mut()),
            HYCON_ERROR_NULL_POINTER,
            "solve is NULL",
        );
        let st = hycon_solid_host_set_csr(
            host,
            h.csr.row_ptr.as_ptr(),
            h.csr.columns.as_ptr(),
            h.csr.values.as_ptr(),
            HYCON_CSR_UPPER,
        );
        assert_eq!(st, HYCON_OK, "{}", last_error());
        // touching everywhere without the point inside A
        expect(
            hycon_solid_contact_new_host(&mut contact, host, null()),
            HYCON_ERROR_INVALID_ARGUMENT,
            "hycon_solid_host_set_pair_inside",
        );
        assert!(contact.is_null());
        expect(
            hycon_solid_contact_new_host(&mut contact, null(), null()),
            HYCON_ERROR_NULL_POINTER,
            "host",
        );
        hycon_solid_host_free(host);
        hycon_solid_host_free(null_mut());
    }
}
