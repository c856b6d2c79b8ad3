//! The 3D contact routines of the C ABI, model family (`hycon_solid_model_*`,
//! `hycon_solid_contact_*`), called as a C host would, against `ContactAnalysis::solid` called
//! from Rust on the same model: the C results are the Rust ones copied, to the bit, with
//! friction and slip (a block turned by 30 degrees pressed on a flat, then dragged along x).

use crate::common::block_on_flat_model;
use crate::common::{last_error, turned_block_on_flat};
use hycon::contact::iteration::{ContactAnalysis, ContactOptions, FacePair, NodeState};
use hycon::ffi::*;
use hycon::solid::contact_meshes::ContactMesh;
use std::ptr::{null, null_mut};

const FRICTION: f64 = 0.3;
const PRESS: f64 = 1e-3;
const DRAG: f64 = 2e-2;

/// The total prescribed values of an increment: the block's top down by `PRESS` and along x by
/// `drag`; the flat's bottom held.
fn prescribed(c: &ContactMesh, drag: f64) -> Vec<f64> {
    let mut qp = vec![0.0; 3 * c.mesh.n_nodes()];
    for &n in &c.a_top {
        qp[3 * n] = drag;
        qp[3 * n + 2] = -PRESS;
    }
    qp
}

/// The faces as `(brick, local face)` values, flat.
fn brick_faces(c: &ContactMesh, faces: &[[usize; 4]]) -> Vec<usize> {
    (faces.iter())
        .flat_map(|&f| {
            let (e, k) = c.mesh.locate_face(f).unwrap();
            [e, k]
        })
        .collect()
}

/// The Rust analysis after the press and the drag.
fn rust_analysis(c: &ContactMesh) -> ContactAnalysis {
    let model = block_on_flat_model(c, &[0, 1, 2]);
    let pair = FacePair {
        a: c.a_faces.clone(),
        b: c.b_faces.clone(),
        friction: FRICTION,
    };
    let mut analysis =
        ContactAnalysis::solid(model, vec![pair], &[], ContactOptions::default()).unwrap();
    let load = vec![0.0; 3 * c.mesh.n_nodes()];
    for drag in [0.0, DRAG] {
        analysis.increment(&load, &prescribed(c, drag)).unwrap();
    }
    analysis
}

/// The same through the C ABI.
fn c_analysis(c: &ContactMesh) -> *mut HyconSolidContact {
    let coords = c.mesh.nodes.as_flattened();
    let bricks = c.mesh.elements.as_flattened();
    // the block's bricks use material 0, the flat's 1
    let material = [HyconSolidMaterial {
        youngs: 1.0,
        poisson: 0.3,
    }; 2];
    let mut model = null_mut();
    let block = HyconBrickBlock {
        nodes: bricks.as_ptr(),
        n_elements: c.mesh.n_elements(),
        materials: c.mesh.element_material.as_ptr(),
        kind: HYCON_BRICK_HYBRID18,
    };
    let (a, b) = (brick_faces(c, &c.a_faces), brick_faces(c, &c.b_faces));
    let (fa, fb) = (
        HyconBrickFaces {
            faces: a.as_ptr(),
            n: a.len() / 2,
        },
        HyconBrickFaces {
            faces: b.as_ptr(),
            n: b.len() / 2,
        },
    );
    let mut index = usize::MAX;
    let mut contact = null_mut();
    // SAFETY: arrays of the stated lengths, live handles.
    unsafe {
        let s = hycon_solid_model_new(
            &mut model,
            coords.as_ptr(),
            c.mesh.n_nodes(),
            &block,
            material.as_ptr(),
            material.len(),
        );
        assert_eq!(s, HYCON_OK, "{}", last_error());
        for nodes in [&c.b_bottom, &c.a_top] {
            let s = hycon_solid_model_prescribe(model, nodes.as_ptr(), nodes.len(), HYCON_XYZ);
            assert_eq!(s, HYCON_OK, "{}", last_error());
        }
        let s = hycon_solid_model_add_pair(model, &fa, &fb, FRICTION, &mut index);
        assert_eq!((s, index), (HYCON_OK, 0), "{}", last_error());
        let s = hycon_solid_contact_new(&mut contact, model, null());
        hycon_solid_model_free(model);
        assert_eq!(s, HYCON_OK, "{}", last_error());
        let load = vec![0.0; 3 * c.mesh.n_nodes()];
        for drag in [0.0, DRAG] {
            let qp = prescribed(c, drag);
            let mut info = HyconIncrementInfo::default();
            let s = hycon_solid_contact_increment(
                contact,
                load.as_ptr(),
                load.len(),
                qp.as_ptr(),
                qp.len(),
                &mut info,
            );
            assert_eq!(s, HYCON_OK, "{}", last_error());
        }
    }
    contact
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

#[test]
fn the_c_results_are_the_rust_ones() {
    let c = turned_block_on_flat();
    let rust = rust_analysis(&c);
    let contact = c_analysis(&c);
    // SAFETY (all queries): a live handle and buffers of the stated lengths.
    let nodes = fetch(|o, l, n| unsafe { hycon_solid_contact_node_results(contact, 0, o, l, n) });
    let b_nodes =
        fetch(|o, l, n| unsafe { hycon_solid_contact_b_node_results(contact, 0, o, l, n) });
    let surface =
        fetch(|o, l, n| unsafe { hycon_solid_contact_surface_nodes(contact, 0, o, l, n) });
    let u = fetch(|o, l, n| unsafe { hycon_solid_contact_displacement(contact, o, l, n) });
    let forces = fetch(|o, l, n| unsafe { hycon_solid_contact_forces(contact, o, l, n) });
    let rows = fetch(|o, l, n| unsafe { hycon_solid_contact_constraint_rows(contact, 0, o, l, n) });
    let records = fetch(|o, l, n| unsafe { hycon_solid_contact_records(contact, 0, o, l, n) });
    unsafe { hycon_solid_contact_free(contact) };

    let expect = rust.node_results(0).unwrap();
    assert_eq!(nodes.len(), expect.len());
    let mut slipping = 0;
    for (got, r) in nodes.iter().zip(&expect) {
        assert_eq!(got.node, r.node);
        assert_eq!(got.tn, r.tn);
        assert_eq!(got.ts.as_slice(), r.ts.components());
        assert_eq!(got.normal.as_slice(), r.frame.normal().components());
        for i in 0..2 {
            assert_eq!(got.tangent[i].as_slice(), r.frame.tangent(i).components());
        }
        assert_eq!(got.position.as_slice(), r.position.components());
        assert_eq!(got.force.as_slice(), r.force.components());
        assert_eq!((got.weight, got.gap), (r.weight, r.gap));
        match r.state {
            NodeState::Slip { direction } => {
                slipping += 1;
                assert_eq!(got.state, HYCON_NODE_SLIP);
                assert_eq!(
                    got.slip_direction.as_slice(),
                    direction.vector().components()
                );
                // friction on A opposes A's slip: ts = mu tn d, tn < 0
                for i in 0..2 {
                    let ts = FRICTION * got.tn * got.slip_direction[i];
                    assert!((got.ts[i] - ts).abs() <= 1e-9 * got.tn.abs(), "{got:?}");
                }
            }
            NodeState::Stick => assert_eq!(got.state, HYCON_NODE_STICK),
            NodeState::Open => assert_eq!(got.state, HYCON_NODE_OPEN),
            NodeState::Frictionless => unreachable!("a frictional pair"),
        }
        if got.state != HYCON_NODE_SLIP {
            assert_eq!(got.slip_direction, [0.0; 2]);
        }
    }
    // dragged by 20 times the press, the block slides: every A node slips along +x (A's slip
    // relative to B), so its friction points along -x
    assert_eq!(slipping, nodes.len(), "{nodes:?}");
    let total_x: f64 = nodes.iter().map(|r| r.force[0]).sum();
    assert!(total_x < 0.0);

    let expect_b = rust.b_node_results(0).unwrap();
    assert_eq!(b_nodes.len(), expect_b.len());
    for (got, r) in b_nodes.iter().zip(&expect_b) {
        assert_eq!(
            (got.node, got.weight, got.pressure),
            (r.node, r.weight, r.pressure)
        );
        assert_eq!(got.force.as_slice(), r.force.components());
    }
    let expect_s = rust.surface(0).unwrap();
    for (got, n) in surface.iter().zip(&expect_s.nodes) {
        assert_eq!(
            (got.node, got.weight, got.coverage),
            (n.node, n.weight, n.coverage)
        );
        assert_eq!(got.gap.as_slice(), n.gap.components());
        assert_eq!(got.normal_gap, n.normal_gap);
    }
    assert_eq!(u, rust.displacement().unwrap());
    assert_eq!(forces, rust.contact_forces());
    assert_eq!(records.len(), rust.records().len());
    // 3 rows per A node, the last row is the last node's second tangent
    assert_eq!(rows.last().map(|e| e.row), Some(3 * nodes.len() - 1));
}

/// The result structs have the layouts the design measured on LP64 (192, 72 and 128 bytes).
#[test]
#[cfg(target_pointer_width = "64")]
fn result_layouts_are_the_designs() {
    assert_eq!(std::mem::size_of::<HyconSolidNodeResult>(), 192);
    assert_eq!(std::mem::size_of::<HyconSolidBNodeResult>(), 72);
    assert_eq!(std::mem::size_of::<HyconSolidContactNode>(), 128);
}
