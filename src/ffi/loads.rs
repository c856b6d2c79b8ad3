//! The load and check routines of the C ABI, for every element kind: consistent nodal forces of
//! pressures and tractions on a plane or axisymmetric element's edge ([`crate::element::loads`])
//! and on a brick's face ([`crate::solid::loads`]), element volume and scaled Jacobian
//! ([`crate::element::quality`], [`crate::solid::quality`]), and stress at natural coordinates
//! (see the [parent module](super) for the conventions).

use super::elements::{ElementInput, stress_components};
use super::results::{OVERFLOW, write_results};
use super::solid::{brick_formulation, brick_stress, read_brick, shape_warning};
use super::*;
use crate::element::loads::{EdgeLoad, edge_load};
use crate::element::quality;
use crate::solid::loads::{FaceLoad, face_load};
use crate::solid::{self, N_DOF, ShapePolicy};

/// An optional input of `N` doubles: `None` when `ptr` is NULL, else the values, checked
/// finite.
///
/// # Safety
/// `ptr` must be NULL or point to `N` readable doubles.
unsafe fn optional_doubles<const N: usize>(
    ptr: *const f64,
    name: &str,
) -> Result<Option<[f64; N]>, Fail> {
    if !pointer(ptr, name, false)? {
        return Ok(None);
    }
    let mut values = [0.0; N];
    // SAFETY: forwarded contract.
    unsafe { read_doubles(ptr, &mut values, name)? };
    Ok(Some(values))
}

/// Copy a result to `out` after checking it is finite.
///
/// # Safety
/// `out` must have been checked with [`check_output`] or [`check_pointer`] and be writable for
/// `values.len()` doubles.
unsafe fn write_result(out: *mut f64, values: &[f64], what: &str) -> Result<(), Fail> {
    // SAFETY: the caller's contract.
    unsafe { write_results(out, values, what, OVERFLOW) }
}

// ------------------------------------------------------------------------------------------
// Plane and axisymmetric elements

/// Consistent nodal forces of a distributed load on boundary edge `edge` of an element: the
/// edge runs from local node `edge` to local node `edge + 1` (cyclically, so `edge < n_nodes`;
/// on the 5- and 6-node elements each segment between consecutive nodes is an edge), and
/// carries a pressure and a traction, each linear between the edge's two nodes:
///
/// * `pressure`: NULL (none) or 2 doubles, the pressure at the start and end node (force per
///   area, **positive pushing into the body**, along the inward normal);
/// * `traction`: NULL (none) or 4 doubles `{tx0, ty0, tx1, ty1}`, the traction vector at the
///   start and end node (force per area; in axisymmetry `{t_r, t_z}`).
///
/// With `n` the outward unit normal and `q = t - p n`, `out` receives
/// `f_a = integral of N_a q m ds` (`N_a` the edge's linear shape functions; `m` the thickness in
/// plane analyses, `2 pi r` in axisymmetry: full-circle forces), integrated exactly, as the
/// element force vector: `2 * n_nodes` doubles in dof order `fx0 fy0 fx1 fy1 ...`, nonzero only
/// at the edge's two nodes (`out`, `len`: at least `2 * n_nodes`; `HYCON_MAX_DOF` always
/// suffices). Add it into the global load vector as a stiffness is assembled. In plane
/// analyses a uniform pressure `p` on an edge of length `L` gives `-p n t L / 2` at each end.
///
/// Not to be confused with `hycon_element_edge_traction`, which recovers the traction
/// `sigma n` of a solved element.
///
/// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_ARGUMENT` (kind, `edge`, non-finite
/// coordinate or load value), `HYCON_ERROR_INVALID_MATERIAL`, `HYCON_ERROR_BAD_ELEMENT`
/// (checked as for `hycon_element_stiffness`: an inverted element would turn the normal),
/// `HYCON_ERROR_BUFFER_TOO_SMALL`.
///
/// # Safety
/// `coords` must be NULL or point to `2 * n_nodes` readable doubles; `material` NULL or a
/// readable struct; `pressure` NULL or 2 readable doubles; `traction` NULL or 4 readable
/// doubles; `out` NULL or writable for `len` doubles.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)] // flat C signature
pub unsafe extern "C" fn hycon_element_edge_load(
    kind: HyconElementKind,
    n_nodes: usize,
    coords: *const f64,
    material: *const HyconMaterial,
    edge: usize,
    pressure: *const f64,
    traction: *const f64,
    out: *mut f64,
    len: usize,
) -> HyconStatus {
    boundary("hycon_element_edge_load", || {
        // SAFETY: the caller's contract on `coords` (2 n_nodes doubles) and `material`.
        let (e, material) = unsafe { ElementInput::read_with(kind, n_nodes, coords, material)? };
        // SAFETY: the caller's contract on `pressure` (2 doubles) and `traction` (4).
        let (p, t) = unsafe {
            (
                optional_doubles::<2>(pressure, "pressure")?,
                optional_doubles::<4>(traction, "traction")?,
            )
        };
        let n_dof = 2 * e.n;
        check_output(out, len, n_dof, "out")?;
        let load = EdgeLoad {
            pressure: p.unwrap_or_default(),
            traction: t.map_or([[0.0; 2]; 2], |t| [[t[0], t[1]], [t[2], t[3]]]),
        };
        let f = edge_load(e.formulation, e.coords(), &material, edge, &load)?;
        // SAFETY: `out` was checked for `n_dof` values.
        unsafe { write_result(out, &f.as_slice()[..n_dof], "load") }
    })
}

/// Volume of an element into `*out`: area times thickness in plane analyses, and with a
/// `HYCON_AXISYMMETRIC` material `integral of 2 pi r dA = 2 pi r_c A` (`r_c` the radius of the
/// area centroid), the volume of the whole ring. Exact. (The area itself: call with a plane
/// material of thickness 1.)
///
/// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_ARGUMENT`,
/// `HYCON_ERROR_INVALID_MATERIAL`, `HYCON_ERROR_BAD_ELEMENT` (the element is checked as for
/// `hycon_element_stiffness`).
///
/// # Safety
/// `coords` must be NULL or point to `2 * n_nodes` readable doubles; `material` NULL or a
/// readable struct; `out` NULL or a writable double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_element_volume(
    kind: HyconElementKind,
    n_nodes: usize,
    coords: *const f64,
    material: *const HyconMaterial,
    out: *mut f64,
) -> HyconStatus {
    boundary("hycon_element_volume", || {
        // SAFETY: the caller's contract on `coords` (2 n_nodes doubles) and `material`.
        let (e, material) = unsafe { ElementInput::read_with(kind, n_nodes, coords, material)? };
        check_pointer(out.cast_const(), "out")?;
        let v = quality::volume(e.formulation, e.coords(), &material)?;
        // SAFETY: `out` is non-null and aligned (checked), writable (contract).
        unsafe { write_result(out, &[v], "volume") }
    })
}

/// Jacobian quality of an element into `*out`: the **scaled Jacobian**, the smallest over the
/// element's true corners of `det J / (|dx/dxi| |dx/deta|)`, which is the sine of the interior
/// angle there (mid-side nodes of the 5- and 6-node elements are not corners). 1 for a
/// rectangle, toward 0 as a corner angle nears 0 or 180 degrees; independent of size, position
/// and rotation; in `(0, 1]` for every element `hycon_element_check` accepts (so a host can flag
/// elements below its own threshold, e.g. 0.2). It does not measure the aspect ratio.
///
/// Errors: as `hycon_element_check`, and `HYCON_ERROR_NULL_POINTER` for `out`.
///
/// # Safety
/// `coords` must be NULL or point to `2 * n_nodes` readable doubles; `out` NULL or a writable
/// double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_element_quality(
    kind: HyconElementKind,
    n_nodes: usize,
    coords: *const f64,
    out: *mut f64,
) -> HyconStatus {
    boundary("hycon_element_quality", || {
        // SAFETY: the caller's contract on `coords` (2 n_nodes doubles).
        let e = unsafe { ElementInput::read(kind, n_nodes, coords)? };
        check_pointer(out.cast_const(), "out")?;
        let q = quality::scaled_jacobian(e.formulation, e.coords())?;
        // SAFETY: `out` is non-null and aligned (checked), writable (contract).
        unsafe { write_result(out, &[q], "quality") }
    })
}

/// Stress at natural coordinates `(xi, eta)` in `[-1, 1]^2` of an element, recovered from its
/// nodal displacements `q` (`2 * n_nodes` doubles): `out` receives what `hycon_element_stress`
/// writes (`{sx, sy, txy}`, or 4 values `{sigma_r, sigma_z, tau_rz, sigma_theta}` in
/// axisymmetry).
///
/// Natural coordinates are those of the element's bilinear map: node 0 at `(-1, -1)`, node 1 at
/// `(1, -1)`, node 2 at `(1, 1)`, node 3 at `(-1, 1)`; for the 5- and 6-node hybrid elements the
/// map of their 4 true corners in node order (the first corner at `(-1, -1)`), the mid-side nodes
/// taking no part. Q4, Pian-Sumihara and the axisymmetric elements evaluate their field there
/// (at a host's Gauss points, for instance); the plane hybrid element, whose field lives in
/// physical coordinates, gives the stress at the mapped point, the same as
/// `hycon_element_stress` there.
///
/// Errors: as `hycon_element_stress`; `HYCON_ERROR_INVALID_ARGUMENT` also for `xi` or `eta`
/// outside `[-1, 1]` and for a 5- or 6-node element with only 3 true corners.
///
/// # Safety
/// `coords` and `q` must be NULL or point to `2 * n_nodes` readable doubles; `material` NULL or
/// a readable struct; `out` NULL or writable for 3 doubles (4 in axisymmetry).
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)] // flat C signature
pub unsafe extern "C" fn hycon_element_stress_natural(
    kind: HyconElementKind,
    n_nodes: usize,
    coords: *const f64,
    material: *const HyconMaterial,
    q: *const f64,
    xi: f64,
    eta: f64,
    out: *mut f64,
) -> HyconStatus {
    boundary("hycon_element_stress_natural", || {
        // SAFETY: the caller's contract on `coords` (2 n_nodes doubles) and `material`.
        let (e, material) = unsafe { ElementInput::read_with(kind, n_nodes, coords, material)? };
        check_pointer(out.cast_const(), "out")?;
        // SAFETY: the caller's contract on `q` (2 n_nodes doubles).
        let field = unsafe { e.stress_field(&material, q)? };
        let s = field.at_natural_point(xi, eta)?;
        // SAFETY: `out` is non-null and aligned (checked) and holds 3 doubles, 4 in
        // axisymmetry (contract).
        unsafe { write_result(out, &s[..stress_components(&material)], "stress") }
    })
}

// ------------------------------------------------------------------------------------------
// Bricks

/// Consistent nodal forces of a distributed load on face `face` (0 to 5, numbering at
/// `HyconBrickKind`) of a brick, each value given at the face's 4 nodes in the face's node order
/// (face 0 is nodes `0 4 7 3`, ...) and interpolated bilinearly:
///
/// * `pressure`: NULL (none) or 4 doubles (force per area, **positive pushing into the body**);
/// * `traction`: NULL (none) or 12 doubles `{tx, ty, tz}` per face node (force per area).
///
/// With `n` the outward unit normal and `q = t - p n`, `out` receives
/// `f_k = integral over the face of N_k q dA` as the brick's force vector: 24 doubles in dof
/// order `fx0 fy0 fz0 fx1 ...`, nonzero only at the face's 4 nodes (`len >= 24`). 2 x 2 Gauss:
/// exact for the pressure on any face, warped or not (the forces of a uniform pressure sum to
/// `-p` times the face's projected area vector), and for the traction on plane faces; on a
/// warped face the traction part is approximated (error of the order of the warp squared).
///
/// Not to be confused with `hycon_brick_face_traction`, which recovers the traction `sigma n`
/// of a solved brick.
///
/// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_ARGUMENT` (kind, `face`, non-finite
/// coordinate or load value), `HYCON_ERROR_BAD_ELEMENT` (the shape check of
/// `hycon_brick_check`), `HYCON_ERROR_BUFFER_TOO_SMALL`.
///
/// # Safety
/// `coords` NULL or 24 readable doubles; `pressure` NULL or 4 readable doubles; `traction` NULL
/// or 12 readable doubles; `out` NULL or writable for `len` doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_brick_face_load(
    kind: HyconBrickKind,
    coords: *const f64,
    face: usize,
    pressure: *const f64,
    traction: *const f64,
    out: *mut f64,
    len: usize,
) -> HyconStatus {
    boundary_warning("hycon_brick_face_load", || {
        brick_formulation(kind)?;
        // SAFETY: the caller's contract on `coords`, `pressure` (4 doubles) and `traction`
        // (12).
        let (x, p, t) = unsafe {
            (
                read_brick(coords)?,
                optional_doubles::<4>(pressure, "pressure")?,
                optional_doubles::<12>(traction, "traction")?,
            )
        };
        check_output(out, len, N_DOF, "out")?;
        let load = FaceLoad {
            pressure: p.unwrap_or_default(),
            traction: t.map_or([[0.0; 3]; 4], |t| {
                std::array::from_fn(|k| [t[3 * k], t[3 * k + 1], t[3 * k + 2]])
            }),
        };
        let f = face_load(&x, face, &load)?;
        // SAFETY: `out` was checked for 24 values.
        unsafe { write_result(out, f.as_slice(), "load")? };
        brick_shape_warning(&x)
    })
}

/// Volume of a brick into `*out` (`integral of det J`, exact for any trilinear brick).
///
/// Errors: as `hycon_brick_check`, and `HYCON_ERROR_NULL_POINTER` for `out`.
///
/// # Safety
/// `coords` NULL or 24 readable doubles; `out` NULL or a writable double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_brick_volume(
    kind: HyconBrickKind,
    coords: *const f64,
    out: *mut f64,
) -> HyconStatus {
    // SAFETY: the caller's contract.
    unsafe {
        brick_measure(
            "hycon_brick_volume",
            kind,
            coords,
            out,
            "volume",
            solid::quality::volume,
        )
    }
}

/// Jacobian quality of a brick into `*out`: the **scaled Jacobian**, the smallest over the 8
/// corners of `det J / (|J_1| |J_2| |J_3|)` (`J_a = dx/dxi_a`; at a corner, half its three
/// edges), the volume of the corner's edge parallelepiped over the product of its edge lengths.
/// 1 for a rectangular box, toward 0 as a corner flattens; independent of size, position and
/// rotation; in `(0, 1]` for every brick the strict shape policy accepts (so a host can flag
/// bricks below its own threshold, e.g. 0.2), at or below 0 where the default policy warns of a
/// non-positive corner Jacobian. It does not measure the aspect ratio.
///
/// Errors: as `hycon_brick_check`, and `HYCON_ERROR_NULL_POINTER` for `out`.
///
/// # Safety
/// `coords` NULL or 24 readable doubles; `out` NULL or a writable double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_brick_quality(
    kind: HyconBrickKind,
    coords: *const f64,
    out: *mut f64,
) -> HyconStatus {
    // SAFETY: the caller's contract.
    unsafe {
        brick_measure(
            "hycon_brick_quality",
            kind,
            coords,
            out,
            "quality",
            solid::quality::scaled_jacobian,
        )
    }
}

/// Stress `{sxx, syy, szz, sxy, syz, szx}` at natural coordinates `(xi, eta, zeta)` in
/// `[-1, 1]^3` of a brick (node 0 at `(-1, -1, -1)`, numbering at `HyconBrickKind`), from its
/// nodal displacements `q` (24 doubles): the hybrid brick's `P beta` or the H8's `D B q` there,
/// the same as `hycon_brick_stress` at the mapped physical point. `out` receives 6 doubles.
///
/// Errors: as `hycon_brick_stress`; `HYCON_ERROR_INVALID_ARGUMENT` also for a natural
/// coordinate outside `[-1, 1]`.
///
/// # Safety
/// `coords` and `q` NULL or 24 readable doubles; `material` NULL or a readable struct; `out`
/// NULL or writable for 6 doubles.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)] // flat C signature
pub unsafe extern "C" fn hycon_brick_stress_natural(
    kind: HyconBrickKind,
    coords: *const f64,
    material: *const HyconSolidMaterial,
    q: *const f64,
    xi: f64,
    eta: f64,
    zeta: f64,
    out: *mut f64,
) -> HyconStatus {
    boundary_warning("hycon_brick_stress_natural", || {
        check_pointer(out.cast_const(), "out")?;
        // SAFETY: the caller's contract.
        let field = unsafe { brick_stress(kind, coords, material, q)? };
        let s = field.at_natural_point([xi, eta, zeta])?;
        // SAFETY: `out` is non-null and aligned (checked) and holds 6 doubles (contract).
        unsafe { write_result(out, s.as_slice(), "stress")? };
        Ok(shape_warning(field.shape()))
    })
}

/// The body of `hycon_brick_volume` and `hycon_brick_quality`, named `function`: one number
/// `what` of a brick, `measure(coords)`, into `*out`, with the shape warning.
///
/// # Safety
/// `coords` NULL or 24 readable doubles; `out` NULL or a writable double.
unsafe fn brick_measure(
    function: &'static str,
    kind: HyconBrickKind,
    coords: *const f64,
    out: *mut f64,
    what: &str,
    measure: fn(&[[f64; 3]]) -> Result<f64, ShapeError>,
) -> HyconStatus {
    boundary_warning(function, || {
        brick_formulation(kind)?;
        // SAFETY: the caller's contract on `coords`.
        let x = unsafe { read_brick(coords)? };
        check_pointer(out.cast_const(), "out")?;
        let value = measure(&x)?;
        // SAFETY: `out` is non-null and aligned (checked), writable (contract).
        unsafe { write_result(out, &[value], what)? };
        brick_shape_warning(&x)
    })
}

/// The warning every brick routine returns with its results under the default shape policy
/// (`HYCON_WARNING_SHAPE`: a non-positive corner Jacobian or a face warped beyond the limit).
fn brick_shape_warning(x: &[[f64; 3]]) -> Result<Option<Warning>, Fail> {
    Ok(shape_warning(&solid::check_shape(
        x,
        ShapePolicy::default(),
    )?))
}
