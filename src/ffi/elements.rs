//! The element routines of the C ABI: shape check, stiffness, stress recovery and edge
//! tractions of one element (see the [parent module](super) for the conventions).

use super::results::{OUTSIDE_ELEMENT, check_results, write_results};
use super::*;
use crate::element;

/// The inputs shared by the element functions, read and checked.
pub(super) struct ElementInput {
    pub(super) formulation: Formulation,
    pub(super) n: usize,
    coords: [[f64; 2]; element::MAX_NODES],
}

impl ElementInput {
    /// # Safety
    /// If `coords` is non-null it must point to `2 n_nodes` readable doubles.
    pub(super) unsafe fn read(
        kind: HyconElementKind,
        n_nodes: usize,
        coords: *const f64,
    ) -> Result<Self, Fail> {
        let formulation = formulation(kind)?;
        let n = node_count(formulation, n_nodes)?;
        // SAFETY: forwarded contract.
        let coords = unsafe { read_coords(coords, n)? };
        Ok(ElementInput {
            formulation,
            n,
            coords,
        })
    }

    /// [`read`](Self::read) and the material.
    ///
    /// # Safety
    /// As [`read`](Self::read); `material` NULL or a readable struct.
    pub(super) unsafe fn read_with(
        kind: HyconElementKind,
        n_nodes: usize,
        coords: *const f64,
        material: *const HyconMaterial,
    ) -> Result<(Self, Material), Fail> {
        // SAFETY: forwarded contract.
        unsafe { Ok((Self::read(kind, n_nodes, coords)?, read_material(material)?)) }
    }

    pub(super) fn coords(&self) -> &[[f64; 2]] {
        &self.coords[..self.n]
    }

    /// Recover the stress field from `2n` dofs at `q`.
    ///
    /// # Safety
    /// If `q` is non-null it must point to `2 n` readable doubles.
    pub(super) unsafe fn stress_field(
        &self,
        material: &Material,
        q: *const f64,
    ) -> Result<element::StressField, Fail> {
        let mut dofs = [0.0; element::MAX_DOF];
        // SAFETY: forwarded contract.
        unsafe { read_doubles(q, &mut dofs[..2 * self.n], "q")? };
        Ok(element::recover_stress(
            self.formulation,
            self.coords(),
            material,
            &dofs[..2 * self.n],
        )?)
    }
}

/// Stress components written by `hycon_element_stress`: 3, or 4 in axisymmetry.
pub(super) fn stress_components(material: &Material) -> usize {
    material.analysis.stress_components()
}

// ------------------------------------------------------------------------------------------
// Exported functions

/// Check one element's shape for a formulation: node count, finite coordinates, positive area,
/// counter-clockwise order, convexity (tolerances relative to the element size). It takes no
/// material, so it does not check what axisymmetry adds (4 nodes, `r >= 0`, no Pian-Sumihara):
/// `hycon_element_stiffness` does.
///
/// `coords`: `2 * n_nodes` doubles `x0 y0 x1 y1 ...`, nodes counter-clockwise.
///
/// Returns `HYCON_OK`, or `HYCON_ERROR_BAD_ELEMENT` with a message naming the defect
/// (degenerate, inverted, non-convex at local node i, node count), `HYCON_ERROR_INVALID_ARGUMENT`
/// (unknown kind, non-finite coordinate), `HYCON_ERROR_NULL_POINTER`.
///
/// # Safety
/// `coords` must be NULL or point to `2 * n_nodes` readable doubles (only read when `n_nodes`
/// suits `kind`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_element_check(
    kind: HyconElementKind,
    n_nodes: usize,
    coords: *const f64,
) -> HyconStatus {
    boundary("hycon_element_check", || {
        // SAFETY: the caller's contract on `coords`.
        let e = unsafe { ElementInput::read(kind, n_nodes, coords)? };
        Ok(element::check_shape(e.formulation, e.coords())?)
    })
}

/// Element stiffness matrix `K` (`2n x 2n`, `n = n_nodes`) into `k_out`, row-major:
/// `k_out[i * 2n + j] = K_ij`, rows and columns in element dof order `u0 v0 u1 v1 ...` (the
/// node order of `coords`). `K` is symmetric, so column-major readers get the same matrix.
///
/// * `coords`: `2 * n_nodes` doubles `x0 y0 x1 y1 ...`, nodes counter-clockwise. Q4 and
///   Pian-Sumihara take 4 nodes, the hybrid element 4 to 6 (corners plus mid-side nodes on
///   straight edges, in boundary order).
/// * `material`: finite, `E > 0`, `-1 < nu < 0.5`, `t > 0`, known analysis; `t` multiplies `K`
///   in plane analyses; `HYCON_AXISYMMETRIC` (`t = 1`, `x = r >= 0`) integrates with `2 pi r`
///   (the whole ring's stiffness) and takes 4 nodes, hybrid (7 beta) or Q4.
/// * `k_out`, `k_len`: output array of at least `(2n)^2` doubles (`HYCON_MAX_DOF^2 = 144` always
///   suffices); only the first `(2n)^2` are written, and only on success.
///
/// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_ARGUMENT` (kind, non-finite
/// coordinate), `HYCON_ERROR_INVALID_MATERIAL`, `HYCON_ERROR_BAD_ELEMENT`,
/// `HYCON_ERROR_BUFFER_TOO_SMALL`.
///
/// # Safety
/// `coords` must be NULL or point to `2 * n_nodes` readable doubles; `material` NULL or a
/// readable struct; `k_out` NULL or writable for `k_len` doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_element_stiffness(
    kind: HyconElementKind,
    n_nodes: usize,
    coords: *const f64,
    material: *const HyconMaterial,
    k_out: *mut f64,
    k_len: usize,
) -> HyconStatus {
    boundary("hycon_element_stiffness", || {
        // SAFETY: the caller's contract on `coords` (2 n_nodes doubles) and `material`.
        let (e, material) = unsafe { ElementInput::read_with(kind, n_nodes, coords, material)? };
        let n_dof = 2 * e.n;
        check_output(k_out, k_len, n_dof * n_dof, "k_out")?;
        let mut k = element::ElementMatrix::zeros();
        let got = element::stiffness_into(e.formulation, e.coords(), &material, &mut k)?;
        debug_assert_eq!(got, n_dof);
        let mut row_major = [0.0; element::MAX_DOF * element::MAX_DOF];
        for i in 0..n_dof {
            for j in 0..n_dof {
                row_major[i * n_dof + j] = k[(i, j)];
            }
        }
        let k = &row_major[..n_dof * n_dof];
        // SAFETY: `k_out` was checked for `n_dof^2` values.
        unsafe { write_results(k_out, k, "stiffness", OUTSIDE_ELEMENT) }
    })
}

/// Stress at the physical point `(px, py)` of an element, recovered from its nodal
/// displacements `q` (`2 * n_nodes` doubles, dof order `u0 v0 u1 v1 ...`): `out` receives
/// `{sx, sy, txy}` (3 doubles) in plane strain and plane stress, and
/// `{sigma_r, sigma_z, tau_rz, sigma_theta}` (**4 doubles**) with a `HYCON_AXISYMMETRIC`
/// material. `hycon_element_stress_components(material)` tells the count; a buffer of 4 always
/// suffices.
///
/// Hybrid elements evaluate their assumed stress field `P beta` with `beta = H^-1 G q`; Q4
/// evaluates `D B q` (on the axis `r = 0` in axisymmetry with `eps_theta = du_r / dr`, the limit
/// when `u_r = 0` there, as it must be prescribed). The point should lie in the
/// element; outside it the value is an extrapolation (a non-finite result is reported as
/// `HYCON_ERROR_INVALID_ARGUMENT`).
///
/// # Safety
/// `coords` and `q` must be NULL or point to `2 * n_nodes` readable doubles; `material` NULL or
/// a readable struct; `out` NULL or writable for 3 doubles (4 in axisymmetry).
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)] // flat C signature
pub unsafe extern "C" fn hycon_element_stress(
    kind: HyconElementKind,
    n_nodes: usize,
    coords: *const f64,
    material: *const HyconMaterial,
    q: *const f64,
    px: f64,
    py: f64,
    out: *mut f64,
) -> HyconStatus {
    boundary("hycon_element_stress", || {
        // SAFETY: the caller's contract on `coords` (2 n_nodes doubles) and `material`.
        let (e, material) = unsafe { ElementInput::read_with(kind, n_nodes, coords, material)? };
        check_finite_scalar(px, "px")?;
        check_finite_scalar(py, "py")?;
        check_pointer(out.cast_const(), "out")?;
        // SAFETY: the caller's contract on `q` (2 n_nodes doubles).
        let field = unsafe { e.stress_field(&material, q)? };
        let s = field.at_full([px, py]);
        let s = &s[..stress_components(&material)];
        // SAFETY: `out` is non-null and aligned (checked) and holds 3 doubles, 4 in
        // axisymmetry (contract).
        unsafe { write_results(out, s, "stress", OUTSIDE_ELEMENT) }
    })
}

/// Stress parameters `beta` of a hybrid element, recovered from its nodal displacements `q`
/// (`2 * n_nodes` doubles, dof order `u0 v0 u1 v1 ...`): 7 for the hybrid element with 4 or 5
/// nodes (and the axisymmetric hybrid element), 12 with 6 nodes, 5 for Pian-Sumihara, 0 for Q4.
///
/// `out`, `len`, `needed`: the header's size convention (`HYCON_MAX_BETA` always suffices; the
/// size query `(NULL, 0, &needed)` gives the count, 0 for Q4).
///
/// Errors: as `hycon_element_stress`, and `HYCON_ERROR_BUFFER_TOO_SMALL`.
///
/// # Safety
/// `coords` and `q` must be NULL or point to `2 * n_nodes` readable doubles; `material` NULL or
/// a readable struct; `out` NULL or writable for `len` doubles; `needed` NULL or writable.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)] // flat C signature
pub unsafe extern "C" fn hycon_element_stress_params(
    kind: HyconElementKind,
    n_nodes: usize,
    coords: *const f64,
    material: *const HyconMaterial,
    q: *const f64,
    out: *mut f64,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_element_stress_params", || {
        // SAFETY: the caller's contract on `coords` (2 n_nodes doubles) and `material`.
        let (e, material) = unsafe { ElementInput::read_with(kind, n_nodes, coords, material)? };
        // SAFETY: the caller's contract on `q` (2 n_nodes doubles).
        let field = unsafe { e.stress_field(&material, q)? };
        let beta = field.beta();
        check_results(beta, "beta", OUTSIDE_ELEMENT)?;
        // SAFETY: the caller's contract on `out` and `needed`.
        unsafe { fill(out, len, needed, "out", beta.len(), || Ok(beta.to_vec())) }
    })
}

/// Number of stress components `hycon_element_stress` writes for `material`: 3 (`{sx, sy, txy}`)
/// in plane strain and plane stress, 4 (`{sigma_r, sigma_z, tau_rz, sigma_theta}`) in
/// axisymmetry, into `*out`.
///
/// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_MATERIAL`.
///
/// # Safety
/// `material` NULL or a readable struct; `out` NULL or a writable `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_element_stress_components(
    material: *const HyconMaterial,
    out: *mut usize,
) -> HyconStatus {
    boundary("hycon_element_stress_components", || {
        // SAFETY: the caller's contract on `material` and `out`.
        unsafe {
            let material = read_material(material)?;
            write(out, stress_components(&material), "out")
        }
    })
}

/// Traction `{tx, ty} = sigma n` (outward unit normal `n`) at parameter `s` in `[0, 1]` along
/// boundary edge `edge` of an element, the edge running from local node `edge` to local node
/// `edge + 1` (cyclically, so `edge < n_nodes`), from nodal displacements `q` (`2 * n_nodes`
/// doubles, dof order `u0 v0 u1 v1 ...`). `out` receives 2 doubles on success (in axisymmetry
/// the meridian traction `{t_r, t_z}`, a pressure: force per area).
///
/// # Safety
/// `coords` and `q` must be NULL or point to `2 * n_nodes` readable doubles; `material` NULL or
/// a readable struct; `out` NULL or writable for 2 doubles.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)] // flat C signature
pub unsafe extern "C" fn hycon_element_edge_traction(
    kind: HyconElementKind,
    n_nodes: usize,
    coords: *const f64,
    material: *const HyconMaterial,
    q: *const f64,
    edge: usize,
    s: f64,
    out: *mut f64,
) -> HyconStatus {
    boundary("hycon_element_edge_traction", || {
        // SAFETY: the caller's contract on `coords` (2 n_nodes doubles) and `material`.
        let (e, material) = unsafe { ElementInput::read_with(kind, n_nodes, coords, material)? };
        if edge >= e.n {
            return Err(Fail::invalid(format!(
                "edge {edge} of a {}-node element (edges are 0 to {})",
                e.n,
                e.n - 1
            )));
        }
        check_finite_scalar(s, "s")?;
        if !(0.0..=1.0).contains(&s) {
            return Err(Fail::invalid(format!("s = {s} is outside [0, 1]")));
        }
        check_pointer(out.cast_const(), "out")?;
        // SAFETY: the caller's contract on `q` (2 n_nodes doubles).
        let field = unsafe { e.stress_field(&material, q)? };
        let t = field.edge_traction(edge, s);
        // SAFETY: `out` is non-null and aligned (checked) and holds 2 doubles (contract).
        unsafe { write_results(out, &t, "traction", OUTSIDE_ELEMENT) }
    })
}
