//! The 3D contact routines of the C ABI, host API: a host FE code's 3D system
//! ([`HyconSolidHost`]: contact nodes with 3 equations each, contact pairs of faces given as 4
//! node ids of its numbering, symmetry planes, and its stiffness as a CSR matrix, a solve
//! callback or its condensed operator) and its analysis, the same [`HyconSolidContact`] handle
//! as the model API's, so that every `hycon_solid_contact_*` query serves both. The stiffness
//! hand-overs read their arguments as the plane host's do (`contact`); only the nodes (3
//! components) and the faces differ (`ContactAnalysis::solid_host`).
//!
//! The host's loads and displacements are over its `n` equations, as the plane host's: `load`
//! of an increment is its right-hand side (which holds the effect of its prescribed
//! displacements), `prescribed` is empty.

use super::contact::{
    HostSource, HyconCondensed, HyconContactOptions, HyconSolveFn, HyconTriangle,
    contact_equations, host_nodes, merge_host_nodes, read_condensed, read_csr, read_options,
};
use super::solid_contact::HyconSolidContact;
use super::{
    Fail, HyconStatus, boundary, free_handle, hand_out, handle, handle_mut, length, optional, put,
    read_doubles, slice,
};
use crate::contact::bodies::{HostNode, HostSystem};
use crate::contact::faces::SymmetryPlane;
use crate::contact::iteration::{ContactAnalysis, FacePair};
use crate::contact::space::Vector;
use std::ffi::c_void;

// ------------------------------------------------------------------------------------------
// Input views

/// Contact nodes of a 3D host (host API): ids, reference coordinates and equation numbers.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct HyconSolidHostNodes {
    /// `n` node ids (the host's numbering).
    pub ids: *const usize,
    /// `3 n` reference coordinates `x0 y0 z0 x1 ...` (finite).
    pub coords: *const f64,
    /// `3 n` equation numbers (`u_x`, `u_y`, `u_z` per node) in `0 .. n_equations`, or
    /// `HYCON_FIXED` for a dof the host holds at zero.
    pub equations: *const i64,
    /// Number of nodes.
    pub n: usize,
}

/// Faces of a 3D host's contact surface (host API): face `i` has the node ids
/// `nodes[4 i .. 4 i + 4]`, counter-clockwise seen from outside its body (its outward normal
/// by the right-hand rule), the corners of a 4-node face (a brick's face, say).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct HyconHostFaces {
    /// `4 n` node ids.
    pub nodes: *const usize,
    /// Number of faces.
    pub n: usize,
}

// ------------------------------------------------------------------------------------------
// The handle

/// A 3D host's contact description (host API): its contact nodes, face pairs, symmetry planes
/// and its stiffness (CSR), solve callback or condensed operator. Create with
/// `hycon_solid_host_new`, free with `hycon_solid_host_free`. Thread safety: as `HyconModel`.
pub struct HyconSolidHost {
    equations: usize,
    nodes: Vec<HostNode>,
    pairs: Vec<FacePair>,
    /// Per pair, a point inside body A (`hycon_solid_host_set_pair_inside`).
    a_inside: Vec<Option<Vector>>,
    symmetry: Vec<SymmetryPlane>,
    stiffness: Option<HostSource>,
}

/// A face view's faces (`side` names them in messages).
///
/// # Safety
/// `view` NULL or a readable view whose `nodes` holds `4 n` ids.
unsafe fn read_faces(view: *const HyconHostFaces, side: &str) -> Result<Vec<[usize; 4]>, Fail> {
    let name = side.to_lowercase();
    // SAFETY (both): the caller's contract.
    let v = unsafe { handle(view, &name)? };
    let ids = unsafe { slice(v.nodes, length(v.n, 4, 0, &name)?, &format!("{name}.nodes"))? };
    Ok((ids.chunks_exact(4))
        .map(|f| [f[0], f[1], f[2], f[3]])
        .collect())
}

// ------------------------------------------------------------------------------------------
// Describing the host

/// Create a 3D host description for a system of `n_equations` equations (the host's `K` after
/// its boundary conditions: symmetric positive definite), as `hycon_host_new`.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`out`), `HYCON_ERROR_INVALID_ARGUMENT` (`n_equations`
/// zero or beyond what memory can address).
///
/// # Safety
/// `out` must point to a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_host_new(
    out: *mut *mut HyconSolidHost,
    n_equations: usize,
) -> HyconStatus {
    boundary("hycon_solid_host_new", || {
        if n_equations == 0 || n_equations > isize::MAX as usize / 16 {
            return Err(Fail::invalid(format!(
                "n_equations = {n_equations} must be positive and addressable"
            )));
        }
        let host = HyconSolidHost {
            equations: n_equations,
            nodes: Vec::new(),
            pairs: Vec::new(),
            a_inside: Vec::new(),
            symmetry: Vec::new(),
            stiffness: None,
        };
        // SAFETY: the caller's contract on `out`.
        unsafe { hand_out(out, host) }
    })
}

/// Free a 3D host description (NULL is a no-op). Analyses made from it are independent of it.
///
/// # Safety
/// `host` must be NULL or a live handle from `hycon_solid_host_new`, not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_host_free(host: *mut HyconSolidHost) {
    // SAFETY: the caller's contract.
    unsafe { free_handle(host) }
}

/// Add contact nodes: ids of the host's numbering, reference coordinates (3 per node) and the
/// equation of each displacement component (`HYCON_FIXED` for one the host holds at zero).
/// Every node of a face of `hycon_solid_host_add_pair` must have been added; a node added
/// again must come with the same coordinates and equations. The nodes' order is the order of
/// the per-node results (A nodes, B nodes) and of `hycon_solid_host_contact_equations`. The
/// arrays are copied; on an error the host is unchanged.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `nodes`, an array with `n > 0`),
/// `HYCON_ERROR_INVALID_ARGUMENT` (non-finite coordinates, an equation out of range or shared
/// by two nodes, a node given before differently, a misaligned pointer).
///
/// # Safety
/// `host` must be a live handle; `nodes` NULL or a readable view whose arrays hold the stated
/// counts.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_host_add_nodes(
    host: *mut HyconSolidHost,
    nodes: *const HyconSolidHostNodes,
) -> HyconStatus {
    boundary("hycon_solid_host_add_nodes", || {
        // SAFETY (all reads): the caller's contract.
        let h = unsafe { handle_mut(host, "host")? };
        let v = unsafe { handle(nodes, "nodes")? };
        let given = unsafe {
            host_nodes(
                v.ids,
                v.coords,
                v.equations,
                v.n,
                3,
                "nodes",
                "contact",
                h.equations,
            )?
        };
        // all-or-nothing: merge into a copy
        let mut merged = h.nodes.clone();
        merge_host_nodes(&mut merged, &given, "contact")?;
        h.nodes = merged;
        Ok(())
    })
}

/// Add a contact pair: the multiplier side `a` and the opposite side `b` as faces of 4 node ids
/// each (`HyconHostFaces`, counter-clockwise seen from outside their body), every node one
/// added by `hycon_solid_host_add_nodes`, and the Coulomb coefficient `friction >= 0` (0:
/// frictionless; the cone is circular). The pair's index (0, 1, ...) is written to `index`
/// unless it is NULL. Checked here: the friction, each side at least one face, 4 distinct
/// nodes per face, no face listed twice, no node on both sides, every node known. Checked at
/// `hycon_solid_contact_new_host`: the faces' shapes (a flat, warped or inverted face the
/// kernel cannot integrate is refused by name), a continuous frame over A, and that A and B
/// face each other. The arrays are copied; on an error the host is unchanged.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `a`, `b`, their `nodes` with `n > 0`),
/// `HYCON_ERROR_INVALID_ARGUMENT` naming the side and the face (the checks above, a
/// misaligned pointer).
///
/// # Safety
/// `host` must be a live handle; `a`, `b` NULL or readable views holding `4 n` ids each;
/// `index` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_host_add_pair(
    host: *mut HyconSolidHost,
    a: *const HyconHostFaces,
    b: *const HyconHostFaces,
    friction: f64,
    index: *mut usize,
) -> HyconStatus {
    boundary("hycon_solid_host_add_pair", || {
        // SAFETY (all): the caller's contract.
        let h = unsafe { handle_mut(host, "host")? };
        let index = optional(index, "index")?;
        let pair = FacePair {
            a: unsafe { read_faces(a, "A")? },
            b: unsafe { read_faces(b, "B")? },
            friction,
        };
        pair.check()?;
        for (side, faces) in [("A", &pair.a), ("B", &pair.b)] {
            for (i, face) in faces.iter().enumerate() {
                if let Some(k) = face.iter().find(|&&k| h.nodes.iter().all(|n| n.id != k)) {
                    return Err(Fail::invalid(format!(
                        "{side} face {i} {face:?}: node {k} is not a contact node \
                         (hycon_solid_host_add_nodes)"
                    )));
                }
            }
        }
        h.pairs.push(pair);
        h.a_inside.push(None);
        unsafe { put(index, h.pairs.len() - 1) };
        Ok(())
    })
}

/// Say which side body A of pair `pair` (an index from `hycon_solid_host_add_pair`) is on:
/// `inside` is a point inside body A (3 doubles), above A's faces rather than beyond their
/// free edges: the centroid of an element that owns an A face, say. It must lie on A's body
/// side of its nearest A face (checked at `hycon_solid_contact_new_host`), which confirms A's
/// orientation; B's follows from facing A. Needed where A and B touch (lie within half a face
/// of each other) wherever they are near each other: facing surfaces and back-to-back ones
/// then look the same. Replaces an earlier point of the pair.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `inside`), `HYCON_ERROR_INVALID_ARGUMENT` (an
/// unknown pair, a non-finite point). On an error the host is unchanged.
///
/// # Safety
/// `host` must be a live handle; `inside` NULL or 3 readable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_host_set_pair_inside(
    host: *mut HyconSolidHost,
    pair: usize,
    inside: *const f64,
) -> HyconStatus {
    boundary("hycon_solid_host_set_pair_inside", || {
        // SAFETY (both): the caller's contract.
        let h = unsafe { handle_mut(host, "host")? };
        let mut p = [0.0; 3];
        unsafe { read_doubles(inside, &mut p, "inside")? };
        if pair >= h.pairs.len() {
            return Err(Fail::invalid(format!(
                "pair {pair} is unknown (the host has {} pairs)",
                h.pairs.len()
            )));
        }
        h.a_inside[pair] = Some(Vector::solid(p[0], p[1], p[2]));
        Ok(())
    })
}

/// Declare a symmetry plane of the host's model: the plane through `point` normal to `normal`
/// (3 doubles each), as `hycon_solid_model_add_symmetry_plane`. The host holds the nodes on it
/// normal to it (their equation of that component `HYCON_FIXED`, or an identity row).
///
/// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_ARGUMENT` (a non-finite value, a
/// zero normal, a misaligned pointer).
///
/// # Safety
/// `host` must be a live handle; `point` and `normal` NULL or 3 readable doubles each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_host_add_symmetry_plane(
    host: *mut HyconSolidHost,
    point: *const f64,
    normal: *const f64,
) -> HyconStatus {
    boundary("hycon_solid_host_add_symmetry_plane", || {
        // SAFETY (all): the caller's contract.
        let h = unsafe { handle_mut(host, "host")? };
        let (mut p, mut n) = ([0.0; 3], [0.0; 3]);
        unsafe {
            read_doubles(point, &mut p, "point")?;
            read_doubles(normal, &mut n, "normal")?;
        }
        h.symmetry.push(SymmetryPlane::new(p, n)?);
        Ok(())
    })
}

/// Give the host's stiffness as a CSR matrix over its `n_equations` equations (copied), as
/// `hycon_host_set_csr` (the same arrays, triangles, checks and errors). Replaces an earlier
/// matrix, solver or condensed operator.
///
/// # Safety
/// `host` must be a live handle; the arrays NULL or of the stated lengths.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_host_set_csr(
    host: *mut HyconSolidHost,
    row_ptr: *const usize,
    columns: *const usize,
    values: *const f64,
    triangle: HyconTriangle,
) -> HyconStatus {
    boundary("hycon_solid_host_set_csr", || {
        // SAFETY (all reads): the caller's contract.
        let h = unsafe { handle_mut(host, "host")? };
        let csr = unsafe { read_csr(h.equations, row_ptr, columns, values, triangle)? };
        h.stiffness = Some(HostSource::Csr(csr));
        Ok(())
    })
}

/// Let the host solve with its own factorization, as `hycon_host_set_solver`
/// (`HyconSolveFn`; `user_data` must outlive every analysis made from this description; called
/// on the thread that calls into the `HyconSolidContact`). Replaces an earlier matrix, solver
/// or condensed operator.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `solve`).
///
/// # Safety
/// `host` must be a live handle; `solve` a valid function as documented.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_host_set_solver(
    host: *mut HyconSolidHost,
    solve: HyconSolveFn,
    user_data: *mut c_void,
) -> HyconStatus {
    boundary("hycon_solid_host_set_solver", || {
        // SAFETY: the caller's contract.
        let h = unsafe { handle_mut(host, "host")? };
        h.stiffness = Some(HostSource::callback(solve, user_data)?);
        Ok(())
    })
}

/// Hand over the host's condensed operator over its contact candidate equations, as
/// `hycon_host_set_condensed` (the same struct, checks and errors): every increment then takes
/// as `load` the load image `u0 = K^-1 rhs` at the `m` candidates, and the host recovers its
/// displacement itself from `hycon_solid_contact_forces` (`hycon_solid_contact_displacement`
/// and `hycon_solid_contact_displacement_increment` fail). `hycon_solid_host_contact_equations`
/// lists the equations the candidates must hold. Replaces an earlier matrix, solver or
/// condensed operator.
///
/// # Safety
/// `host` must be a live handle; `condensed` NULL or a readable `HyconCondensed` whose arrays
/// hold the stated counts.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_host_set_condensed(
    host: *mut HyconSolidHost,
    condensed: *const HyconCondensed,
) -> HyconStatus {
    boundary("hycon_solid_host_set_condensed", || {
        // SAFETY (all reads): the caller's contract.
        let h = unsafe { handle_mut(host, "host")? };
        let condensed = unsafe { read_condensed(condensed, h.equations)? };
        h.stiffness = Some(HostSource::Condensed(condensed));
        Ok(())
    })
}

/// The host's contact equations: every equation of its contact nodes (not `HYCON_FIXED`), in
/// the order the nodes were added (`u_x`, `u_y`, `u_z`), each once: what the candidates of
/// `hycon_solid_host_set_condensed` must hold.
///
/// Sizes and errors follow the header's size convention (`out`, `len`, `needed`).
///
/// # Safety
/// `host` must be a live handle; `out` NULL or `len` writable values; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_host_contact_equations(
    host: *const HyconSolidHost,
    out: *mut i64,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_solid_host_contact_equations", || {
        // SAFETY (all): the caller's contract.
        let h = unsafe { handle(host, "host")? };
        unsafe { contact_equations(&h.nodes, out, len, needed) }
    })
}

/// Start a 3D contact analysis of a host's system (`ContactAnalysis::solid_host`): factor its
/// CSR matrix once, or build the flexibility from batched solves through its callback, or read
/// it off its condensed operator, and check the faces. The result is a `HyconSolidContact`:
/// every `hycon_solid_contact_*` function applies, with the field over the host's `n`
/// equations (`load` of an increment its right-hand side, `prescribed` NULL with length 0;
/// the load image for a condensed operator), the per-node results in the order the nodes were
/// added, node ids of the host's numbering, and the constraint rows' columns host equations.
/// `options` NULL means the defaults.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`out`, `host`), `HYCON_ERROR_INVALID_ARGUMENT` (no
/// pair, no stiffness, solver or condensed operator, a face the kernel cannot integrate (flat,
/// warped, inverted) or no continuous frame over A, naming the pair; a pair whose surfaces run
/// the same way or lie back to back; a pair whose surfaces touch wherever they are near each
/// other without `hycon_solid_host_set_pair_inside`; a point inside A on A's outward side; a
/// contact equation that is no candidate of the condensed operator; bad options),
/// `HYCON_ERROR_SINGULAR` (the CSR matrix or the Schur complement is not positive definite: a
/// body not held), `HYCON_ERROR_SOLVER`, `HYCON_ERROR_CALLBACK` (the solver failed or returned
/// non-finite values).
///
/// # Safety
/// `out` must point to a writable pointer, `host` be a live handle, `options` NULL or
/// readable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_solid_contact_new_host(
    out: *mut *mut HyconSolidContact,
    host: *const HyconSolidHost,
    options: *const HyconContactOptions,
) -> HyconStatus {
    boundary("hycon_solid_contact_new_host", || {
        // SAFETY (all): the caller's contract.
        let h = unsafe { handle(host, "host")? };
        let (opts, monitor) = unsafe { read_options(options)? };
        if h.pairs.is_empty() {
            return Err(Fail::invalid(
                "the host has no contact pair (hycon_solid_host_add_pair)",
            ));
        }
        let system = HostSystem {
            equations: h.equations,
            nodes: h.nodes.clone(),
            stiffness: HostSource::stiffness(h.stiffness.as_ref(), "hycon_solid_host")?,
            elements: None,
            a_inside: h.a_inside.clone(),
            sections: Vec::new(),
        };
        let mut analysis = ContactAnalysis::solid_host(system, h.pairs.clone(), &h.symmetry, opts)?;
        analysis.set_monitor(monitor);
        unsafe { hand_out(out, HyconSolidContact { analysis }) }
    })
}
