//! The rigid plate on a solid model (issue #43, force control in 3D), from Rust
//! (`ContactAnalysis::solid_with_plate`) and through the C ABI (`hycon_solid_model_set_plate`,
//! `hycon_solid_contact_increment_with_plate`, `hycon_solid_contact_plate`) as a C host calls
//! it: a block turned by 30 degrees on a flat, frictionless and with friction (its press then
//! slips: the force-controlled increment settles through the linearized conditions bordered
//! by the plate's force-controlled translation), its top tied to the plate, pressed by
//! displacement and then by the force that press took. The C results are the Rust ones to the
//! bit; bad input gets its error. (Hertz and Mindlin at a given load:
//! `lab/tests/contact_plate3d.rs`.)

use crate::common::block_on_flat_model;
use crate::common::{last_error, turned_block_on_flat};
use hycon::contact::faces::SymmetryPlane;
use hycon::contact::iteration::{ContactAnalysis, ContactOptions, FacePair, PlateControl};
use hycon::error::Error;
use hycon::ffi::*;
use hycon::solid::contact_meshes::ContactMesh;
use hycon::solid::model::SolidModel;
use hycon::solid::{BrickFormulation, Isotropic};
use std::ptr::{null, null_mut};

const FRICTION: f64 = 0.0;
/// The friction coefficient of the press that slips.
const SLIPPING: f64 = 0.3;
const PRESS: f64 = 1e-3;

fn pair(c: &ContactMesh, friction: f64) -> FacePair {
    FacePair {
        a: c.a_faces.clone(),
        b: c.b_faces.clone(),
        friction,
    }
}

/// The Rust analysis with the block's top tied to the plate.
fn rust_analysis(c: &ContactMesh, friction: f64) -> ContactAnalysis {
    let (options, top) = (ContactOptions::default(), c.a_top.clone());
    let pairs = vec![pair(c, friction)];
    ContactAnalysis::solid_with_plate(block_on_flat_model(c, &[0, 1, 2]), pairs, &[], options, top)
        .unwrap()
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

/// The C model: mesh, materials, the flat's bottom held, the pair with `friction`, the plate
/// on `plate` (checked to succeed).
fn c_model(c: &ContactMesh, plate: &[usize], friction: f64) -> *mut HyconSolidModel {
    let coords = c.mesh.nodes.as_flattened();
    let bricks = c.mesh.elements.as_flattened();
    let material = [HyconSolidMaterial {
        youngs: 1.0,
        poisson: 0.3,
    }; 2];
    let block = HyconBrickBlock {
        nodes: bricks.as_ptr(),
        n_elements: c.mesh.n_elements(),
        materials: c.mesh.element_material.as_ptr(),
        kind: HYCON_BRICK_HYBRID18,
    };
    let (a, b) = (brick_faces(c, &c.a_faces), brick_faces(c, &c.b_faces));
    let view = |v: &Vec<usize>| HyconBrickFaces {
        faces: v.as_ptr(),
        n: v.len() / 2,
    };
    let mut model = null_mut();
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
        let bottom = &c.b_bottom;
        let s = hycon_solid_model_prescribe(model, bottom.as_ptr(), bottom.len(), HYCON_XYZ);
        assert_eq!(s, HYCON_OK, "{}", last_error());
        let s = hycon_solid_model_add_pair(model, &view(&a), &view(&b), friction, null_mut());
        assert_eq!(s, HYCON_OK, "{}", last_error());
        let s = hycon_solid_model_set_plate(model, plate.as_ptr(), plate.len());
        assert_eq!(s, HYCON_OK, "{}", last_error());
    }
    model
}

/// A C analysis of `c_model(c, plate, friction)` (checked to succeed).
fn c_analysis(c: &ContactMesh, plate: &[usize], friction: f64) -> *mut HyconSolidContact {
    let model = c_model(c, plate, friction);
    let mut contact = null_mut();
    // SAFETY: live handles.
    unsafe {
        let s = hycon_solid_contact_new(&mut contact, model, null());
        hycon_solid_model_free(model);
        assert_eq!(s, HYCON_OK, "{}", last_error());
    }
    contact
}

/// One C increment with the plate driven by `control` and `value`; the status.
fn c_increment(
    contact: *mut HyconSolidContact,
    n: usize,
    control: [HyconPlateControl; 3],
    value: [f64; 3],
) -> HyconStatus {
    let zero = vec![0.0; n];
    let mut info = HyconIncrementInfo::default();
    // SAFETY: arrays of the stated lengths, a live handle.
    unsafe {
        hycon_solid_contact_increment_with_plate(
            contact,
            zero.as_ptr(),
            n,
            zero.as_ptr(),
            n,
            control.as_ptr(),
            value.as_ptr(),
            &mut info,
        )
    }
}

/// The C plate state: displacement and force.
fn c_plate(contact: *const HyconSolidContact) -> ([f64; 3], [f64; 3]) {
    let (mut u, mut f) = ([0.0; 3], [0.0; 3]);
    // SAFETY: a live handle, 3 writable doubles each.
    let s = unsafe { hycon_solid_contact_plate(contact, u.as_mut_ptr(), f.as_mut_ptr()) };
    assert_eq!(s, HYCON_OK, "{}", last_error());
    (u, f)
}

/// Pressed by `PRESS` (x and y held), the plate takes a force `F`; pressed again from the start
/// by the force `F` in z, the plate comes down by `PRESS` (to `1e-10`) and exerts `F` (to
/// round-off), x and y held at zero. From C the same, to the bit: the plate state, every A
/// node's multipliers and state, the displacement. A factor in the bordered system (the
/// plate's response, its stiffness, the sign of the balance) breaks the first part; a C layer
/// that reads the controls in another order, the second.
#[test]
fn force_control_from_c_is_the_rust_one() {
    assert_eq!(force_control_from_c(FRICTION), 0);
}

/// The same with friction `mu = 0.3`: the press slips (measured: 8 of the 9 closed nodes),
/// and at the force the displacement-controlled press took the force-controlled one comes
/// down by the same `PRESS` (to `1e-10`: the linearized conditions bordered by the plate's
/// z translation settle it), from C to the bit.
#[test]
fn a_frictional_press_that_slips_at_a_given_force() {
    assert!(force_control_from_c(SLIPPING) > 0);
}

/// The press of `force_control_from_c_is_the_rust_one` with `friction`: the number of slip
/// nodes of the force-controlled increment.
fn force_control_from_c(friction: f64) -> usize {
    let c = turned_block_on_flat();
    let n = 3 * c.mesh.n_nodes();
    let zero = vec![0.0; n];
    let held = PlateControl::Displacement(0.0);
    let mut displaced = rust_analysis(&c, friction);
    let down = [held, held, PlateControl::Displacement(-PRESS)];
    displaced.increment_with_plate(&zero, &zero, &down).unwrap();
    let (u, force) = displaced.plate().unwrap();
    assert_eq!(u.components(), [0.0, 0.0, -PRESS]);
    let f = force.components()[2];
    assert!(f < 0.0, "{force:?}");

    let mut forced = rust_analysis(&c, friction);
    let by_force = [held, held, PlateControl::Force(f)];
    let info = (forced.increment_with_plate(&zero, &zero, &by_force)).unwrap();
    let (u, force) = forced.plate().unwrap();
    assert!((force.components()[2] / f - 1.0).abs() < 1e-12, "{force:?}");
    assert!((u.components()[2] / -PRESS - 1.0).abs() < 1e-10, "{u:?}");
    assert_eq!(&u.components()[..2], [0.0, 0.0]);

    let contact = c_analysis(&c, &c.a_top, friction);
    let control = [
        HYCON_PLATE_DISPLACEMENT,
        HYCON_PLATE_DISPLACEMENT,
        HYCON_PLATE_FORCE,
    ];
    let s = c_increment(contact, n, control, [0.0, 0.0, f]);
    assert_eq!(s, HYCON_OK, "{}", last_error());
    let (cu, cf) = c_plate(contact);
    assert_eq!(
        (cu.as_slice(), cf.as_slice()),
        (u.components(), force.components())
    );
    let mut len = 0;
    // SAFETY (both): a live handle, buffers of the stated lengths.
    let s = unsafe { hycon_solid_contact_node_results(contact, 0, null_mut(), 0, &mut len) };
    assert_eq!(s, HYCON_OK, "{}", last_error());
    let mut nodes = vec![HyconSolidNodeResult::default(); len];
    let s = unsafe {
        hycon_solid_contact_node_results(contact, 0, nodes.as_mut_ptr(), len, null_mut())
    };
    assert_eq!(s, HYCON_OK, "{}", last_error());
    let expect = forced.node_results(0).unwrap();
    assert_eq!(nodes.len(), expect.len());
    for (got, r) in nodes.iter().zip(&expect) {
        assert_eq!((got.node, got.tn), (r.node, r.tn));
        assert_eq!(got.force.as_slice(), r.force.components());
    }
    let mut q = vec![0.0; n];
    // SAFETY: a live handle, a buffer of the stated length.
    let s = unsafe { hycon_solid_contact_displacement(contact, q.as_mut_ptr(), n, null_mut()) };
    assert_eq!(s, HYCON_OK, "{}", last_error());
    assert_eq!(q, forced.displacement().unwrap());
    unsafe { hycon_solid_contact_free(contact) };
    println!("friction {friction}: {info:?}");
    info.slip
}

/// Bad input, each refused with its status and a message saying what is wrong, and nothing
/// changed: a NULL model or node array, no nodes, an unknown node, a node prescribed twice
/// (twice in the list, or a second plate), a plate node that is a contact node (at
/// `hycon_solid_contact_new`), an unknown control, a non-finite force, NULL controls, an
/// increment or a plate query without a plate; from Rust, a plate node not prescribed in z.
#[test]
fn bad_plate_input_is_refused() {
    let c = turned_block_on_flat();
    let n = 3 * c.mesh.n_nodes();
    let top = &c.a_top;
    // SAFETY (all calls): handles live or NULL as stated, arrays of the stated lengths.
    unsafe {
        let s = hycon_solid_model_set_plate(null_mut(), top.as_ptr(), top.len());
        assert_eq!(s, HYCON_ERROR_NULL_POINTER);
        let described = c_model(&c, top, FRICTION);
        let s = hycon_solid_model_set_plate(described, null(), 2);
        assert_eq!(s, HYCON_ERROR_NULL_POINTER, "{}", last_error());
        let s = hycon_solid_model_set_plate(described, top.as_ptr(), 0);
        assert_eq!(s, HYCON_ERROR_INVALID_ARGUMENT);
        assert!(
            last_error().contains("at least one node"),
            "{}",
            last_error()
        );
        let unknown = [c.mesh.n_nodes()];
        let s = hycon_solid_model_set_plate(described, unknown.as_ptr(), 1);
        assert_eq!(s, HYCON_ERROR_INVALID_ARGUMENT);
        assert!(last_error().contains("unknown node"), "{}", last_error());
        // a second plate on the same nodes: already prescribed
        let s = hycon_solid_model_set_plate(described, top.as_ptr(), top.len());
        assert_eq!(s, HYCON_ERROR_INVALID_ARGUMENT);
        assert!(
            last_error().contains("prescribed twice"),
            "{}",
            last_error()
        );
        hycon_solid_model_free(described);
    }
    // a contact node on the plate: refused when the analysis is built
    let contact_node = c.a_faces[0][0];
    let on_contact = c_model(&c, &[&top[..], &[contact_node]].concat(), FRICTION);
    let mut contact = null_mut();
    // SAFETY: live handles.
    unsafe {
        let s = hycon_solid_contact_new(&mut contact, on_contact, null());
        hycon_solid_model_free(on_contact);
        assert_eq!(s, HYCON_ERROR_INVALID_ARGUMENT);
        assert!(contact.is_null());
    }
    assert!(
        last_error().contains(&format!("plate node {contact_node}"))
            && last_error().contains("contact node"),
        "{}",
        last_error()
    );

    let contact = c_analysis(&c, top, FRICTION);
    let disp = HYCON_PLATE_DISPLACEMENT;
    let s = c_increment(contact, n, [disp, disp, 7], [0.0; 3]);
    assert_eq!(s, HYCON_ERROR_INVALID_ARGUMENT);
    assert!(last_error().contains("control[2] = 7"), "{}", last_error());
    let s = c_increment(
        contact,
        n,
        [disp, disp, HYCON_PLATE_FORCE],
        [0.0, 0.0, f64::NAN],
    );
    assert_eq!(s, HYCON_ERROR_INVALID_ARGUMENT);
    assert!(
        last_error().contains("value[2] = NaN is not finite"),
        "{}",
        last_error()
    );
    let zero = vec![0.0; n];
    // SAFETY: a live handle, arrays of the stated lengths, NULL controls.
    let s = unsafe {
        hycon_solid_contact_increment_with_plate(
            contact,
            zero.as_ptr(),
            n,
            zero.as_ptr(),
            n,
            null(),
            zero.as_ptr(),
            null_mut(),
        )
    };
    assert_eq!(s, HYCON_ERROR_NULL_POINTER, "{}", last_error());
    // nothing converged: the plate at rest
    assert_eq!(c_plate(contact), ([0.0; 3], [0.0; 3]));
    unsafe { hycon_solid_contact_free(contact) };

    // without a plate
    let rust = ContactAnalysis::solid(
        block_on_flat_model(&c, &[0, 1, 2]),
        vec![pair(&c, FRICTION)],
        &[],
        ContactOptions::default(),
    )
    .unwrap();
    assert!(rust.plate().is_none());
    let mut plain = rust;
    let held = [PlateControl::Displacement(0.0); 3];
    match plain.increment_with_plate(&zero, &zero, &held) {
        Err(Error::InvalidInput(m)) => assert!(m.contains("with_plate"), "{m}"),
        other => panic!("{other:?}"),
    }
    // the plate's nodes must be prescribed in x, y and z: the last one only in z (the others
    // hold the block)
    let material = Isotropic::new(1.0, 0.3).unwrap();
    let mut loose = SolidModel::new(
        c.mesh.clone(),
        vec![material; 2],
        BrickFormulation::Hybrid18,
    )
    .unwrap();
    loose.prescribe(&c.b_bottom, &[0, 1, 2]).unwrap();
    let (last, rest) = top.split_last().unwrap();
    loose.prescribe(rest, &[0, 1, 2]).unwrap();
    loose.prescribe(&[*last], &[2]).unwrap();
    let options = ContactOptions::default();
    match ContactAnalysis::solid_with_plate(
        loose,
        vec![pair(&c, FRICTION)],
        &[],
        options,
        top.clone(),
    ) {
        Err(Error::InvalidInput(m)) => {
            assert!(
                m.contains(&format!("plate node {last}")) && m.contains("prescribed in x, y and z"),
                "{m}"
            )
        }
        other => panic!("{other:?}"),
    }
}

/// A plate translation across a symmetry plane is refused unless it is a displacement of 0,
/// and the state is kept: the block's model declared symmetric about `x = x0` (the plane
/// through its top's first node, which the plate holds; the plane's own checks do not see the
/// other nodes), the plate's x driven by force 0 or by a displacement is refused, y and z free.
#[test]
fn a_plate_does_not_cross_a_symmetry_plane() {
    let c = turned_block_on_flat();
    let n = 3 * c.mesh.n_nodes();
    let zero = vec![0.0; n];
    let plane = SymmetryPlane::new(c.mesh.nodes[c.a_top[0]], [1.0, 0.0, 0.0]).unwrap();
    let options = ContactOptions::default();
    let mut analysis = ContactAnalysis::solid_with_plate(
        block_on_flat_model(&c, &[0, 1, 2]),
        vec![pair(&c, FRICTION)],
        &[plane],
        options,
        c.a_top.clone(),
    )
    .unwrap();
    let held = PlateControl::Displacement(0.0);
    let down = PlateControl::Displacement(-PRESS);
    for x in [PlateControl::Force(0.0), PlateControl::Displacement(1e-4)] {
        match analysis.increment_with_plate(&zero, &zero, &[x, held, down]) {
            Err(Error::InvalidInput(m)) => {
                assert!(
                    m.contains("x translation") && m.contains("symmetry plane"),
                    "{m}"
                )
            }
            other => panic!("{x:?}: {other:?}"),
        }
    }
    assert!(analysis.records().is_empty());
    analysis
        .increment_with_plate(&zero, &zero, &[held, held, down])
        .unwrap();
    assert_eq!(analysis.plate().unwrap().0.components(), [0.0, 0.0, -PRESS]);
}
