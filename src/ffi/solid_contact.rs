//! The 3D contact routines of the C ABI, model API: a brick model with contact pairs of brick
//! faces ([`HyconSolidModel`]) and its analysis ([`HyconSolidContact`]), a family of handles of
//! its own beside the plane's `HyconModel` and `HyconContact` (design:
//! `docs/design/3d-contact.md`, "The C ABI for 3D"). Both analyses are one
//! [`ContactAnalysis`]: the exports whose meaning does not depend on the dimension call the
//! same bodies as the plane's (`contact`), and only the views and the per-node results differ.
//!
//! The solid model's loads, prescribed values, displacements and contact forces are flat over
//! `3 n_nodes` dofs `u0 v0 w0 u1 ...`. Brick node and face order: the header's brick section
//! (`HyconBrickKind`). A pair's A nodes are reported in increasing node id order, its B nodes
//! likewise (`ContactAnalysis::solid`).

use super::contact::{
    self, HYCON_NODE_FRICTIONLESS, HYCON_NODE_OPEN, HYCON_NODE_SLIP, HYCON_NODE_STICK, HYCON_X,
    HYCON_XYZ, HYCON_Y, HYCON_Z, HyconConstraintEntry, HyconContactOptions, HyconCouplingEntry,
    HyconDirections, HyconIncrementInfo, HyconIterationRecord, HyconNodeState, HyconPlateControl,
    HyconTimings, read_options,
};
use super::solid::{HyconBrickKind, HyconSolidMaterial, brick_formulation, read_solid_material};
use super::{
    Fail, HYCON_WARNING_SHAPE, HyconStatus, Warning, boundary, boundary_warning, fill, free_handle,
    hand_out, handle, handle_mut, length, optional, put, read_doubles, slice,
};
use crate::contact::faces::SymmetryPlane;
use crate::contact::iteration::{ContactAnalysis, FacePair, NodeState};
use crate::contact::space::Vector;
use crate::error::Error;
use crate::solid::mesh::{Face, SolidMesh};
use crate::solid::model::SolidModel;
use crate::solid::{BrickFormulation, N_NODES, ShapePolicy};

// ------------------------------------------------------------------------------------------
// Input views

/// 8-node bricks (3D model API): brick `e` has the nodes `nodes[8 e .. 8 e + 8]` in the brick
/// node order (`HyconBrickKind`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct HyconBrickBlock {
    /// `8 n_elements` node ids.
    pub nodes: *const usize,
    /// Number of bricks (at least 1).
    pub n_elements: usize,
    /// `n_elements` indices into the call's materials, or NULL: every brick uses material 0.
    pub materials: *const usize,
    /// The formulation of every brick (`HYCON_BRICK_*`).
    pub kind: HyconBrickKind,
}

/// Brick faces (3D model API surfaces): `faces[2 i]` a brick index, `faces[2 i + 1]` its local
/// face (0-5, outward by the right-hand rule: the numbering of `HyconBrickKind`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct HyconBrickFaces {
    /// `2 n` values: brick, local face.
    pub faces: *const usize,
    /// Number of faces.
    pub n: usize,
}

// ------------------------------------------------------------------------------------------
// Results

/// Converged results at one A node of a 3D pair.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HyconSolidNodeResult {
    /// Node id (the caller's numbering).
    pub node: usize,
    /// `HYCON_NODE_OPEN`, `HYCON_NODE_STICK`, `HYCON_NODE_SLIP` or `HYCON_NODE_FRICTIONLESS`.
    pub state: HyconNodeState,
    /// Normal traction on A (the multiplier, force per area; `< 0` compression, pressure
    /// `p = -tn`).
    pub tn: f64,
    /// Tangential traction on A along `tangent[0]` and `tangent[1]` (force per area; 0 along a
    /// tangent dropped by a symmetry plane).
    pub ts: [f64; 2],
    /// A slip node: the unit direction of A's slip relative to B along `tangent[0]`,
    /// `tangent[1]` (the friction traction opposes it: `ts = mu tn slip_direction`); else 0 0.
    pub slip_direction: [f64; 2],
    /// Nodal normal (A's outward): of the reference configuration under small kinematics, of
    /// the converged one under finite kinematics.
    pub normal: [f64; 3],
    /// The tangents `s1`, `s2`: `(normal, s1, s2)` orthonormal and right-handed, continuous
    /// over the pair; a tangent normal to a symmetry plane the node lies on is dropped (zero).
    pub tangent: [[f64; 3]; 2],
    /// Current position (reference position plus the converged displacement).
    pub position: [f64; 3],
    /// Tributary area `integral N_k dA` (tractions are per unit of it).
    pub weight: f64,
    /// Weighted normal gap (`< 0` penetration; infinite where B does not cover the node).
    pub gap: f64,
    /// Equivalent nodal contact force on A (x, y, z).
    pub force: [f64; 3],
}

/// Converged results at one B node of a 3D pair.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HyconSolidBNodeResult {
    /// Node id (the caller's numbering).
    pub node: usize,
    /// `integral M_j dA` over the projected overlap (A's measure; 0 outside it).
    pub weight: f64,
    /// Equivalent nodal contact force on B (x, y, z).
    pub force: [f64; 3],
    /// Pressure `-force . n / weight` (`n` B's outward nodal normal; 0 outside the overlap).
    pub pressure: f64,
    /// Current position.
    pub position: [f64; 3],
}

/// Contact-element quantities of one A node of a 3D pair at the converged state (the
/// reference one before the first increment), for hosts that assemble the mixed system
/// themselves.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HyconSolidContactNode {
    /// Node id (the caller's numbering).
    pub node: usize,
    /// `integral N_k dA` over the node's support.
    pub weight: f64,
    /// Fraction of the support covered by B, in [0, 1].
    pub coverage: f64,
    /// Nodal normal (A's outward).
    pub normal: [f64; 3],
    /// The tangents `s1`, `s2` (zero where a symmetry plane drops one).
    pub tangent: [[f64; 3]; 2],
    /// Weighted gap vector `R_C,k = integral N_k (x^A - x^B) dA`.
    pub gap: [f64; 3],
    /// `-n_k . R_C,k / covered weight` (`< 0` penetration; infinite when nothing is covered).
    pub normal_gap: f64,
}

// ------------------------------------------------------------------------------------------
// Handles

/// A 3D model being described (model API): brick mesh, materials, prescribed directions,
/// contact pairs of brick faces, symmetry planes, an optional rigid plate. Create with
/// `hycon_solid_model_new`, free with `hycon_solid_model_free`. Thread safety: as
/// `HyconModel`.
pub struct HyconSolidModel {
    model: SolidModel,
    pairs: Vec<FacePair>,
    symmetry: Vec<SymmetryPlane>,
    plate: Option<Vec<usize>>,
}

/// A 3D contact analysis: `K` factored once (or the host's solver), the converged state, the
/// records. Create with `hycon_solid_contact_new` (model API) or
/// `hycon_solid_contact_new_host` (host API), free with `hycon_solid_contact_free`. Thread
/// safety: as `HyconContact` (const queries may run concurrently on one handle).
pub struct HyconSolidContact {
    pub(super) analysis: ContactAnalysis,
}

// ------------------------------------------------------------------------------------------
// Reading the inputs

/// A brick mesh from caller arrays, `3 n_nodes` coordinates and a brick block (connectivity
/// and material indices copied; the mesh's checks are `SolidModel::new`'s), and the block's
/// formulation.
///
/// # Safety
/// `coords` NULL or `3 n_nodes` readable doubles; `block` NULL or a readable view whose arrays
/// hold the stated counts.
unsafe fn read_mesh(
    coords: *const f64,
    n_nodes: usize,
    block: *const HyconBrickBlock,
) -> Result<(SolidMesh, BrickFormulation), Fail> {
    if n_nodes == 0 {
        return Err(Fail::invalid("a model needs nodes (n_nodes = 0)"));
    }
    // SAFETY (all reads): the caller's contract on the arrays and lengths.
    let xyz = unsafe { super::doubles(coords, length(n_nodes, 3, 0, "n_nodes")?, "coords")? };
    let b = unsafe { handle(block, "elements")? };
    let formulation = brick_formulation(b.kind)?;
    if b.n_elements == 0 {
        return Err(Fail::invalid(
            "a model needs bricks (elements.n_elements = 0)",
        ));
    }
    let ids = length(b.n_elements, N_NODES, 0, "elements.n_elements")?;
    let nodes = unsafe { slice(b.nodes, ids, "elements.nodes")? };
    let element_material = if b.materials.is_null() {
        vec![0; b.n_elements]
    } else {
        unsafe { slice(b.materials, b.n_elements, "elements.materials")? }.to_vec()
    };
    let mesh = SolidMesh {
        nodes: xyz.chunks_exact(3).map(|p| [p[0], p[1], p[2]]).collect(),
        elements: (nodes.chunks_exact(N_NODES))
            .map(|e| std::array::from_fn(|k| e[k]))
            .collect(),
        element_material,
        face_sets: Default::default(),
    };
    Ok((mesh, formulation))
}

/// A face view's faces as node ids on `mesh` (`side` names them in messages).
///
/// # Safety
/// `view` NULL or a readable view whose `faces` holds `2 n` values.
unsafe fn read_faces(
    view: *const HyconBrickFaces,
    side: &str,
    mesh: &SolidMesh,
) -> Result<Vec<Face>, Fail> {
    let name = side.to_lowercase();
    // SAFETY (both): the caller's contract.
    let v = unsafe { handle(view, &name)? };
    let values = unsafe { slice(v.faces, length(v.n, 2, 0, &name)?, &format!("{name}.faces"))? };
    (values.chunks_exact(2).enumerate())
        .map(|(i, f)| {
            mesh.brick_face(f[0], f[1]).map_err(|e| match e {
                Error::InvalidInput(m) => Fail::invalid(format!("{side} face {i}: {m}")),
                e => e.into(),
            })
        })
        .collect()
}

/// The bits of a `HyconDirections` as directions 0, 1, 2.
fn directions(d: HyconDirections) -> Result<Vec<usize>, Fail> {
    if !(1..=HYCON_XYZ).contains(&d) {
        return Err(Fail::invalid(format!(
            "directions = {d} (expected a nonzero OR of HYCON_X = 1, HYCON_Y = 2, HYCON_Z = 4)"
        )));
    }
    Ok(([HYCON_X, HYCON_Y, HYCON_Z].iter().enumerate())
        .filter(|(_, bit)| d & **bit != 0)
        .map(|(i, _)| i)
        .collect())
}

/// `HYCON_WARNING_SHAPE` naming the bricks the default shape policy warns about, if any.
fn mesh_warning(mesh: &SolidMesh) -> Result<Option<Warning>, Fail> {
    const LISTED: usize = 5;
    let warnings = mesh.check(ShapePolicy::default())?;
    if warnings.is_empty() {
        return Ok(None);
    }
    let mut words: Vec<String> = (warnings.iter().take(LISTED))
        .map(|(e, w)| format!("brick {e}: {w}"))
        .collect();
    if warnings.len() > LISTED {
        words.push(format!("and {} more", warnings.len() - LISTED));
    }
    Ok(Some(Warning {
        status: HYCON_WARNING_SHAPE,
        message: words.join("; "),
    }))
}

/// A vector's 3 components, as the C structs hold them.
fn solid(v: Vector) -> [f64; 3] {
    std::array::from_fn(|i| v[i])
}

/// The 2 components of a tangent-space quantity on a face.
fn on_face(c: &[f64]) -> [f64; 2] {
    std::array::from_fn(|i| c[i])
}

// ------------------------------------------------------------------------------------------
// Model API

/// Create a 3D model from its mesh and materials (nodes, elements, materials, as
/// `hycon_model_new`):
///
/// * `coords`: `3 n_nodes` doubles `x0 y0 z0 x1 ...`;
/// * `elements`: the bricks (`HyconBrickBlock`: `8 n_elements` node ids in the brick node
///   order, their material indices or NULL for all 0, the formulation);
/// * `materials`: `n_materials` materials.
///
/// The arrays are copied. Every brick is checked as by `hycon_brick_check`: a brick the default
/// shape policy only warns about gives `HYCON_WARNING_SHAPE` with the model made (the message
/// names the bricks).
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`out`, `coords`, `elements`, `materials`, or an array of
/// `elements` with a nonzero length), `HYCON_ERROR_INVALID_ARGUMENT` (no nodes or bricks, an
/// unknown node id or material index, non-finite coordinates, unknown kind, misaligned
/// pointers), `HYCON_ERROR_INVALID_MATERIAL`, `HYCON_ERROR_BAD_ELEMENT` (a degenerate or
/// inverted brick, named by index).
///
/// # Safety
/// `out` must point to a writable pointer; `coords` NULL or `3 n_nodes` readable doubles;
/// `elements` NULL or a readable view whose arrays hold the stated counts; `materials` NULL or
/// `n_materials` readable structs.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_model_new(
    out: *mut *mut HyconSolidModel,
    coords: *const f64,
    n_nodes: usize,
    elements: *const HyconBrickBlock,
    materials: *const HyconSolidMaterial,
    n_materials: usize,
) -> HyconStatus {
    boundary_warning("hycon_solid_model_new", || {
        super::check_pointer(out.cast_const(), "out")?;
        // SAFETY (all reads): the caller's contract on the arrays and lengths.
        let (mesh, formulation) = unsafe { read_mesh(coords, n_nodes, elements)? };
        if n_materials == 0 {
            return Err(Fail::invalid("a model needs materials (n_materials = 0)"));
        }
        let materials = unsafe { slice(materials, n_materials, "materials")? }
            .iter()
            .map(|m| unsafe { read_solid_material(m) })
            .collect::<Result<Vec<_>, _>>()?;
        let model = SolidModel::new(mesh, materials, formulation)?;
        let warning = mesh_warning(&model.mesh)?;
        let handed = HyconSolidModel {
            model,
            pairs: Vec::new(),
            symmetry: Vec::new(),
            plate: None,
        };
        // SAFETY: the caller's contract on `out`.
        unsafe { hand_out(out, handed)? };
        Ok(warning)
    })
}

/// Free a 3D model (NULL is a no-op). Analyses made from it keep their own copy.
///
/// # Safety
/// `model` must be NULL or a live handle from `hycon_solid_model_new`, not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_model_free(model: *mut HyconSolidModel) {
    // SAFETY: the caller's contract.
    unsafe { free_handle(model) }
}

/// Prescribe the displacement of `nodes` in `directions` (any nonzero OR of `HYCON_X`,
/// `HYCON_Y`, `HYCON_Z`; `HYCON_XYZ` all three). The values are given per increment
/// (`prescribed` of `hycon_solid_contact_increment`). Contact nodes may be prescribed too.
///
/// Errors: `HYCON_ERROR_INVALID_ARGUMENT` for an unknown node id, unknown `directions`, or a
/// displacement component prescribed twice (listed twice in `nodes`, prescribed by an earlier
/// call, or tied to the plate); on an error nothing is prescribed.
///
/// # Safety
/// `model` must be a live handle; `nodes` NULL or `n` readable ids.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_model_prescribe(
    model: *mut HyconSolidModel,
    nodes: *const usize,
    n: usize,
    directions: HyconDirections,
) -> HyconStatus {
    boundary("hycon_solid_model_prescribe", || {
        // SAFETY (both): the caller's contract.
        let m = unsafe { handle_mut(model, "model")? };
        let ids = unsafe { slice(nodes, n, "nodes")? };
        m.model.prescribe(ids, &self::directions(directions)?)?;
        Ok(())
    })
}

/// Add a contact pair: the multiplier side `a` and the opposite side `b` (brick faces, each a
/// boundary face of the mesh, listed once) and the Coulomb coefficient `friction >= 0` (0:
/// frictionless; the cone is circular). The pair's index (0, 1, ...) is written to `index`
/// unless it is NULL. A pair's A nodes are numbered in increasing node id order (the order of
/// `hycon_solid_contact_node_results` and the rows of the coupling and constraint entries), B
/// nodes likewise.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`model`, `a`, `b`, or their `faces` with `n > 0`);
/// `HYCON_ERROR_INVALID_ARGUMENT` naming the side and the face for an unknown brick or local
/// face, a side without faces, a face that is not a boundary face of the mesh (shared by two
/// bricks) or is listed twice, a side that is not one connected surface (faces joined by
/// shared edges, at most two on an edge), both sides on one body (bricks joined by shared
/// nodes), a bad friction coefficient, a misaligned pointer. (Faces the kernel cannot
/// integrate, warped beyond 45 degrees, and sides that never face each other are refused by
/// `hycon_solid_contact_new`.) On an error the model is unchanged.
///
/// # Safety
/// `model` must be a live handle; `a`, `b` NULL or readable views holding `2 n` values each;
/// `index` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_model_add_pair(
    model: *mut HyconSolidModel,
    a: *const HyconBrickFaces,
    b: *const HyconBrickFaces,
    friction: f64,
    index: *mut usize,
) -> HyconStatus {
    boundary("hycon_solid_model_add_pair", || {
        // SAFETY (all): the caller's contract.
        let m = unsafe { handle_mut(model, "model")? };
        let index = optional(index, "index")?;
        let pair = FacePair {
            a: unsafe { read_faces(a, "A", &m.model.mesh)? },
            b: unsafe { read_faces(b, "B", &m.model.mesh)? },
            friction,
        };
        pair.check_on(&m.model.mesh)?;
        m.pairs.push(pair);
        unsafe { put(index, m.pairs.len() - 1) };
        Ok(())
    })
}

/// Declare a symmetry plane of the model: the plane through `point` (3 doubles) normal to
/// `normal` (3 doubles, either orientation, normalised here). An A node on it gets the
/// mirrored model's normal and no tangential traction across it. The model must hold the nodes
/// on the plane normal to it (`hycon_solid_model_prescribe`): a quarter or a half model.
///
/// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_ARGUMENT` (a non-finite value, a
/// zero normal, a misaligned pointer).
///
/// # Safety
/// `model` must be a live handle; `point` and `normal` NULL or 3 readable doubles each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_model_add_symmetry_plane(
    model: *mut HyconSolidModel,
    point: *const f64,
    normal: *const f64,
) -> HyconStatus {
    boundary("hycon_solid_model_add_symmetry_plane", || {
        // SAFETY (all): the caller's contract.
        let m = unsafe { handle_mut(model, "model")? };
        let (mut p, mut n) = ([0.0; 3], [0.0; 3]);
        unsafe {
            read_doubles(point, &mut p, "point")?;
            read_doubles(normal, &mut n, "normal")?;
        }
        m.symmetry.push(SymmetryPlane::new(p, n)?);
        Ok(())
    })
}

/// Tie `nodes` (a face of one body, none of them a contact node) to a rigid plate whose x, y
/// and z translations are driven per increment by `hycon_solid_contact_increment_with_plate`,
/// each by displacement or by force, as `hycon_model_set_plate` does in the plane. The nodes
/// are prescribed in x, y and z by this call. A body held only by the plate and by contact
/// (a pressed sphere) then takes a prescribed force. With symmetry planes the plate does not
/// move across them: a translation with a component along a plane's normal must be driven by
/// displacement 0 (a quarter model's plate moves along z only), so the plate holds its nodes
/// on a symmetry plane: prescribe the other nodes on the planes, not those.
///
/// Errors: `HYCON_ERROR_INVALID_ARGUMENT` for no nodes, an unknown node id, or a node already
/// prescribed in a direction (by `hycon_solid_model_prescribe`, twice in `nodes`, or by an
/// earlier plate: a model has one plate); on an error the model is unchanged. A plate node
/// that is a contact node is refused by `hycon_solid_contact_new`.
///
/// # Safety
/// `model` must be a live handle; `nodes` NULL or `n` readable ids.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_model_set_plate(
    model: *mut HyconSolidModel,
    nodes: *const usize,
    n: usize,
) -> HyconStatus {
    boundary("hycon_solid_model_set_plate", || {
        // SAFETY (both): the caller's contract.
        let m = unsafe { handle_mut(model, "model")? };
        let ids = unsafe { slice(nodes, n, "nodes")? };
        if ids.is_empty() {
            return Err(Fail::invalid("a plate needs at least one node"));
        }
        m.model.prescribe(ids, &[0, 1, 2])?;
        m.plate = Some(ids.to_vec());
        Ok(())
    })
}

/// Start a 3D contact analysis of a model (copied: the model may be freed or changed
/// afterwards): validate, assemble, factor `K` once and set up the contact boundary's
/// flexibility. `options` NULL means the defaults (`search_distance` is relative to the mean A
/// face size, the square root of the mean A face area).
///
/// Errors: `HYCON_ERROR_SINGULAR` (a body not held against rigid motion),
/// `HYCON_ERROR_INVALID_ARGUMENT` naming the pair (bad options, A and B sharing a node, a
/// contact face the kernel cannot integrate (degenerate, warped beyond 45 degrees), sides that
/// never face each other (no A face and B face with opposed normals each in front of the
/// other, at any distance), no continuous tangent frame over a pair: split the surface into
/// pairs, a symmetry plane no model node lies on, a plate node that is a contact node),
/// `HYCON_ERROR_SOLVER`.
///
/// # Safety
/// `out` must point to a writable pointer, `model` be a live handle, `options` NULL or
/// readable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_contact_new(
    out: *mut *mut HyconSolidContact,
    model: *const HyconSolidModel,
    options: *const HyconContactOptions,
) -> HyconStatus {
    boundary("hycon_solid_contact_new", || {
        // SAFETY (all): the caller's contract.
        let m = unsafe { handle(model, "model")? };
        let (opts, monitor) = unsafe { read_options(options)? };
        let (model, pairs) = (m.model.clone(), m.pairs.clone());
        let mut analysis = match &m.plate {
            Some(plate) => {
                ContactAnalysis::solid_with_plate(model, pairs, &m.symmetry, opts, plate.clone())?
            }
            None => ContactAnalysis::solid(model, pairs, &m.symmetry, opts)?,
        };
        analysis.set_monitor(monitor);
        unsafe { hand_out(out, HyconSolidContact { analysis }) }
    })
}

/// Free a 3D analysis (NULL is a no-op).
///
/// # Safety
/// `contact` must be NULL or a live handle, not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_contact_free(contact: *mut HyconSolidContact) {
    // SAFETY: the caller's contract.
    unsafe { free_handle(contact) }
}

// ------------------------------------------------------------------------------------------
// Increments and the field: as the plane's, over `3 n_nodes` dofs

/// One increment with **total** values (from the reference state), as
/// `hycon_contact_increment`: `load` the external nodal forces over all `3 n_nodes` dofs
/// (`u0 v0 w0 u1 ...`), `prescribed` the values at the prescribed dofs over the same entries
/// (the others are ignored). The automatic cutback, `info` and the errors are the plane's.
///
/// # Safety
/// `contact` must be a live handle; arrays NULL or of the stated lengths; `info` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_contact_increment(
    contact: *mut HyconSolidContact,
    load: *const f64,
    load_len: usize,
    prescribed: *const f64,
    prescribed_len: usize,
    info: *mut HyconIncrementInfo,
) -> HyconStatus {
    boundary("hycon_solid_contact_increment", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle_mut(contact, "contact")? };
        unsafe {
            contact::increment(
                &mut c.analysis,
                load,
                load_len,
                prescribed,
                prescribed_len,
                info,
            )
        }
    })
}

/// As `hycon_solid_contact_increment` for a model with a plate (`hycon_solid_model_set_plate`):
/// `control` and `value` (3 entries each, x, y, z) drive the plate's translations
/// (`HYCON_PLATE_DISPLACEMENT`: total displacement; `HYCON_PLATE_FORCE`: total force on the
/// plate, its motion solved for), as `hycon_contact_increment_with_plate` in the plane.
///
/// Errors: those of `hycon_solid_contact_increment`; `HYCON_ERROR_INVALID_ARGUMENT` without a
/// plate, for an unknown control, a non-finite value, or a translation with a component along
/// a symmetry plane's normal that is not a displacement of 0; `HYCON_ERROR_SINGULAR` for a
/// force-controlled translation that no constraint of the contact set resists (control it by
/// displacement). On an error the analysis is as before the call.
///
/// # Safety
/// As `hycon_solid_contact_increment`; `control` and `value` must hold 3 values each.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn hycon_solid_contact_increment_with_plate(
    contact: *mut HyconSolidContact,
    load: *const f64,
    load_len: usize,
    prescribed: *const f64,
    prescribed_len: usize,
    control: *const HyconPlateControl,
    value: *const f64,
    info: *mut HyconIncrementInfo,
) -> HyconStatus {
    boundary("hycon_solid_contact_increment_with_plate", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle_mut(contact, "contact")? };
        unsafe {
            contact::increment_with_plate(
                &mut c.analysis,
                (load, load_len),
                (prescribed, prescribed_len),
                (control, value, 3),
                info,
            )
        }
    })
}

/// The converged plate displacement and the force the plate exerts on the body (3 values each,
/// x, y, z), as `hycon_contact_plate`. `HYCON_ERROR_INVALID_ARGUMENT` without a plate.
///
/// # Safety
/// `contact` must be a live handle; `displacement` and `force` must hold 3 writable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_contact_plate(
    contact: *const HyconSolidContact,
    displacement: *mut f64,
    force: *mut f64,
) -> HyconStatus {
    boundary("hycon_solid_contact_plate", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { contact::plate(&c.analysis, displacement, force) }
    })
}

/// The displacement of the last converged increment over the `3 n_nodes` dofs (zero before the
/// first), as `hycon_contact_displacement`; its size query gives the field length, also the
/// `load_len` of an increment.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable doubles; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_contact_displacement(
    contact: *const HyconSolidContact,
    out: *mut f64,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_solid_contact_displacement", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { contact::displacement(&c.analysis, out, len, needed) }
    })
}

/// The displacement increment of the last converged increment, as
/// `hycon_contact_displacement_increment`.
///
/// # Safety
/// As `hycon_solid_contact_displacement`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_contact_displacement_increment(
    contact: *const HyconSolidContact,
    out: *mut f64,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_solid_contact_displacement_increment", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { contact::displacement_increment(&c.analysis, out, len, needed) }
    })
}

/// The contact forces of the last converged increment over the field (`K u = load + forces`),
/// as `hycon_contact_forces`.
///
/// # Safety
/// As `hycon_solid_contact_displacement`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_contact_forces(
    contact: *const HyconSolidContact,
    out: *mut f64,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_solid_contact_forces", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { contact::forces(&c.analysis, out, len, needed) }
    })
}

/// The iteration records from number `first` on, as `hycon_contact_records`.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_contact_records(
    contact: *const HyconSolidContact,
    first: usize,
    out: *mut HyconIterationRecord,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_solid_contact_records", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { contact::records(&c.analysis, first, out, len, needed) }
    })
}

/// Where the time went and the number of factorizations, as `hycon_contact_timings`.
///
/// # Safety
/// `contact` must be a live handle; outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_contact_timings(
    contact: *const HyconSolidContact,
    timings: *mut HyconTimings,
    factorizations: *mut usize,
) -> HyconStatus {
    boundary("hycon_solid_contact_timings", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { contact::timings_of(&c.analysis, timings, factorizations) }
    })
}

// ------------------------------------------------------------------------------------------
// Results per node and the contact-element matrices

/// Tractions way (b), the multipliers: converged results at the A nodes of `pair` (states,
/// `tn`, `ts`, slip directions, frames, gaps, nodal forces), one per A node in increasing node
/// id order: the size query gives the A node count.
///
/// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
/// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_contact_node_results(
    contact: *const HyconSolidContact,
    pair: usize,
    out: *mut HyconSolidNodeResult,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_solid_contact_node_results", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        let (n_a, _) = c.analysis.pair_size(pair)?;
        let results = || -> Result<Vec<HyconSolidNodeResult>, Fail> {
            Ok((c.analysis.node_results(pair)?.iter())
                .map(|r| {
                    let (state, slip_direction) = match r.state {
                        NodeState::Open => (HYCON_NODE_OPEN, [0.0; 2]),
                        NodeState::Stick => (HYCON_NODE_STICK, [0.0; 2]),
                        NodeState::Slip { direction } => {
                            (HYCON_NODE_SLIP, on_face(direction.vector().components()))
                        }
                        NodeState::Frictionless => (HYCON_NODE_FRICTIONLESS, [0.0; 2]),
                    };
                    HyconSolidNodeResult {
                        node: r.node,
                        state,
                        tn: r.tn,
                        ts: on_face(r.ts.components()),
                        slip_direction,
                        normal: solid(r.frame.normal()),
                        tangent: [solid(r.frame.tangent(0)), solid(r.frame.tangent(1))],
                        position: solid(r.position),
                        weight: r.weight,
                        gap: r.gap,
                        force: solid(r.force),
                    }
                })
                .collect())
        };
        unsafe { fill(out, len, needed, "out", n_a, results) }
    })
}

/// Tractions way (c), the B side: nodal forces, weights and pressures at the B nodes of
/// `pair`, one per B node in increasing node id order: the size query gives the B node count.
///
/// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
/// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_contact_b_node_results(
    contact: *const HyconSolidContact,
    pair: usize,
    out: *mut HyconSolidBNodeResult,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_solid_contact_b_node_results", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        let (_, n_b) = c.analysis.pair_size(pair)?;
        let results = || -> Result<Vec<HyconSolidBNodeResult>, Fail> {
            Ok((c.analysis.b_node_results(pair)?.iter())
                .map(|r| HyconSolidBNodeResult {
                    node: r.node,
                    weight: r.weight,
                    force: solid(r.force),
                    pressure: r.pressure,
                    position: solid(r.position),
                })
                .collect())
        };
        unsafe { fill(out, len, needed, "out", n_b, results) }
    })
}

/// Contact-element quantities of the A nodes of `pair` in the converged configuration (the
/// reference one before the first increment): weights, frames, weighted gaps `R_C`, coverage;
/// one per A node. Rust: `ContactAnalysis::surface(pair).nodes`.
///
/// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
/// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_contact_surface_nodes(
    contact: *const HyconSolidContact,
    pair: usize,
    out: *mut HyconSolidContactNode,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_solid_contact_surface_nodes", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        let nodes: Vec<HyconSolidContactNode> = (c.analysis.surface(pair)?.nodes.iter())
            .map(|n| HyconSolidContactNode {
                node: n.node,
                weight: n.weight,
                coverage: n.coverage,
                normal: solid(n.frame.normal()),
                tangent: [solid(n.frame.tangent(0)), solid(n.frame.tangent(1))],
                gap: solid(n.gap),
                normal_gap: n.normal_gap,
            })
            .collect();
        unsafe { fill(out, len, needed, "out", nodes.len(), || Ok(nodes)) }
    })
}

/// The contact-element matrices `F^A` (`D`) and `F^B` (`M`) of `pair` as entries (row = A
/// node index), as `hycon_contact_surface_coupling`.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_contact_surface_coupling(
    contact: *const HyconSolidContact,
    pair: usize,
    out: *mut HyconCouplingEntry,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_solid_contact_surface_coupling", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { contact::surface_coupling(&c.analysis, pair, out, len, needed) }
    })
}

/// The constraint matrix `Kc` of `pair` as row-major, CSR-ready entries, as
/// `hycon_contact_constraint_rows`, with `3 n_a` rows: `3k` the normal constraint of A node
/// `k`, `3k + 1` and `3k + 2` the tangential ones along `s1` and `s2` (empty for a tangent
/// dropped by a symmetry plane); columns are model dofs `3 node + direction`.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_contact_constraint_rows(
    contact: *const HyconSolidContact,
    pair: usize,
    out: *mut HyconConstraintEntry,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_solid_contact_constraint_rows", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { contact::constraint_rows(&c.analysis, pair, out, len, needed) }
    })
}
