//! The 3D element routines of the C ABI: shape check, stiffness, stress parameters, stress at
//! points and face tractions of one 8-node brick (see the [parent module](super) for the
//! conventions).
//!
//! # Brick node, face and dof order
//! Nodes 0-3 are one face, counter-clockwise seen from nodes 4-7; node `4 + i` lies above node
//! `i` (natural coordinates: node 0 `(-1,-1,-1)`, 1 `(+1,-1,-1)`, 2 `(+1,+1,-1)`,
//! 3 `(-1,+1,-1)`, 4-7 the same with `zeta = +1`). Coordinates are interleaved
//! `x0 y0 z0 x1 y1 z1 ...` (24 doubles); dofs `u0 v0 w0 u1 v1 w1 ...` (24). Faces, each
//! counter-clockwise seen from outside: 0 `(0 4 7 3)` `xi = -1`, 1 `(1 2 6 5)` `xi = +1`,
//! 2 `(0 1 5 4)` `eta = -1`, 3 `(3 7 6 2)` `eta = +1`, 4 `(0 3 2 1)` `zeta = -1`,
//! 5 `(4 5 6 7)` `zeta = +1`; face parameters `(s, t)` in `[-1, 1]^2` run from the face's first
//! node to its second (`s`) and to its fourth (`t`). Stresses are `{sxx, syy, szz, sxy, syz,
//! szx}`.
//!
//! # Shape policy
//! Every routine checks the brick under the default policy, `HYCON_SHAPE_INTEGRATION_POINTS`,
//! and returns `HYCON_WARNING_SHAPE` (results written) for what the strict policy rejects;
//! `hycon_brick_shape` checks under either policy and reports the measures.

use super::results::{OUTSIDE_BRICK, check_results, write_results};
use super::*;
use crate::solid::{self, BrickFormulation, Isotropic, N_DOF, N_NODES, ShapePolicy, ShapeReport};

/// Which brick formulation a 3D element routine uses (`hycon_brick_*`).
///
/// Brick node order: nodes 0-3 are one face, counter-clockwise seen from nodes 4-7; node
/// `4 + i` lies above node `i`. Natural coordinates `(xi, eta, zeta)`: node 0 `(-1,-1,-1)`,
/// 1 `(+1,-1,-1)`, 2 `(+1,+1,-1)`, 3 `(-1,+1,-1)`, 4-7 the same with `zeta = +1`:
///
/// ```text
///        7-----------6
///       /|          /|
///      4-----------5 |      zeta
///      | 3---------|-2      | eta
///      |/          |/       |/
///      0-----------1        +--- xi
/// ```
///
/// Coordinates are interleaved `x0 y0 z0 x1 y1 z1 ...` (24 doubles), dofs `u0 v0 w0 u1 ...`
/// (24), matrices 24 x 24 row-major. Faces, each counter-clockwise seen from outside (the
/// right-hand rule gives the outward normal): 0 = nodes `0 4 7 3` (`xi = -1`), 1 = `1 2 6 5`
/// (`xi = +1`), 2 = `0 1 5 4` (`eta = -1`), 3 = `3 7 6 2` (`eta = +1`), 4 = `0 3 2 1`
/// (`zeta = -1`), 5 = `4 5 6 7` (`zeta = +1`); face parameters `(s, t)` in `[-1, 1]^2` run from
/// the face's first node towards its second (`s`) and towards its fourth (`t`). Stresses are
/// `{sxx, syy, szz, sxy, syz, szx}`.
pub type HyconBrickKind = i32;
/// The 18-beta assumed-stress hybrid brick of Pian and Tong (stress in natural coordinates,
/// carried to Cartesian components with the centre Jacobian): locking-free in bending and as
/// `nu -> 0.5`.
pub const HYCON_BRICK_HYBRID18: HyconBrickKind = 1;
/// The trilinear displacement brick with 2x2x2 Gauss (the baseline; locks in bending and near
/// incompressibility).
pub const HYCON_BRICK_H8: HyconBrickKind = 2;

/// Nodes of a brick.
pub const HYCON_BRICK_NODES: usize = 8;
/// Dofs of a brick (3 per node).
pub const HYCON_BRICK_DOF: usize = 24;
/// Largest number of stress parameters of a brick (18, the hybrid brick's).
pub const HYCON_BRICK_MAX_BETA: usize = 18;

/// Isotropic material of a 3D solid: no thickness, no plane idealisation.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct HyconSolidMaterial {
    /// Young's modulus `E` (finite, in `[1e-100, 1e100]`).
    pub youngs: f64,
    /// Poisson's ratio (`-1 < nu < 0.5`).
    pub poisson: f64,
}

const _: () = {
    assert!(HYCON_BRICK_NODES == N_NODES);
    assert!(HYCON_BRICK_DOF == N_DOF);
    assert!(HYCON_BRICK_MAX_BETA == solid::MAX_BETA);
};

pub(super) fn brick_formulation(kind: HyconBrickKind) -> Result<BrickFormulation, Fail> {
    match kind {
        HYCON_BRICK_HYBRID18 => Ok(BrickFormulation::Hybrid18),
        HYCON_BRICK_H8 => Ok(BrickFormulation::H8),
        k => Err(Fail::invalid(format!(
            "unknown brick kind {k} (expected HYCON_BRICK_HYBRID18 = 1 or HYCON_BRICK_H8 = 2)"
        ))),
    }
}

/// Read 8 interleaved node coordinates.
///
/// # Safety
/// If `coords` is non-null it must point to 24 readable doubles.
pub(super) unsafe fn read_brick(coords: *const f64) -> Result<[[f64; 3]; N_NODES], Fail> {
    let mut flat = [0.0; N_DOF];
    // SAFETY: forwarded contract.
    unsafe { read_doubles(coords, &mut flat, "coords")? };
    Ok(std::array::from_fn(|k| {
        [flat[3 * k], flat[3 * k + 1], flat[3 * k + 2]]
    }))
}

/// Read and validate a solid material.
///
/// # Safety
/// If `m` is non-null it must point to a readable `HyconSolidMaterial`.
pub(super) unsafe fn read_solid_material(m: *const HyconSolidMaterial) -> Result<Isotropic, Fail> {
    check_pointer(m, "material")?;
    // SAFETY: non-null and aligned (checked); a readable struct of two doubles (contract).
    let m = unsafe { m.read() };
    Ok(Isotropic::new(m.youngs, m.poisson)?)
}

/// The inputs of the stress routines, read and checked, and the recovered field.
///
/// # Safety
/// `coords` and `q` NULL or 24 readable doubles; `material` NULL or a readable struct.
pub(super) unsafe fn brick_stress(
    kind: HyconBrickKind,
    coords: *const f64,
    material: *const HyconSolidMaterial,
    q: *const f64,
) -> Result<solid::BrickStress, Fail> {
    let formulation = brick_formulation(kind)?;
    // SAFETY: the caller's contract.
    let (x, material) = unsafe { (read_brick(coords)?, read_solid_material(material)?) };
    let mut dofs = [0.0; N_DOF];
    // SAFETY: the caller's contract on `q`.
    unsafe { read_doubles(q, &mut dofs, "q")? };
    Ok(solid::recover_stress(formulation, &x, &material, &dofs)?)
}

/// Check one brick's shape under the default policy (`HyconShapePolicy`): finite coordinates,
/// no coincident nodes, positive volume (node order as in the header's brick section),
/// `det J > 0` at every integration point; a corner where `det J <= 0` and a face warped by more
/// than 45 degrees are warnings. Both kinds accept the same shapes. Tolerances relative to the
/// longest edge. `hycon_brick_shape` chooses the policy and reports the measures.
///
/// Returns `HYCON_OK`, `HYCON_WARNING_SHAPE` with a message naming the corner or the face
/// (0.8 returned `HYCON_ERROR_BAD_ELEMENT` there), or `HYCON_ERROR_BAD_ELEMENT` with a message
/// naming the defect (degenerate, inverted, Jacobian not positive at the integration point
/// nearest local node i), `HYCON_ERROR_INVALID_ARGUMENT` (unknown kind, non-finite
/// coordinate), `HYCON_ERROR_NULL_POINTER`.
///
/// # Safety
/// `coords` must be NULL or point to 24 readable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_brick_check(
    kind: HyconBrickKind,
    coords: *const f64,
) -> HyconStatus {
    boundary_warning("hycon_brick_check", || {
        brick_formulation(kind)?;
        // SAFETY: the caller's contract on `coords`.
        let x = unsafe { read_brick(coords)? };
        Ok(shape_warning(&solid::check_shape(
            &x,
            ShapePolicy::default(),
        )?))
    })
}

// ------------------------------------------------------------------------------------------
// Shape policy: what is an error and what a warning, and the measures

/// How strictly a brick's shape is judged, one of `HYCON_SHAPE_INTEGRATION_POINTS` (the default
/// of every brick routine) or `HYCON_SHAPE_STRICT` (`hycon_brick_shape`).
///
/// Both policies reject (`HYCON_ERROR_BAD_ELEMENT`) coincident nodes, a volume that is not
/// positive, and a Jacobian that is not positive (`det J <= 1e-10 h^3`, `h` the longest edge) at
/// one of the 8 points of the 2x2x2 Gauss rule both bricks integrate with. The default then
/// warns (`HYCON_WARNING_SHAPE`, results written) where the strict policy rejects: a Jacobian
/// that is not positive at a corner node, a face warped by more than 45 degrees. The warp of a
/// face is the angle between the normals of its two triangle halves, for each of the two ways
/// of splitting it along a diagonal, the larger of the two (0 for a plane face).
pub type HyconShapePolicy = i32;
/// The default: errors only where the Jacobian at an integration point or the volume is not
/// positive; a corner Jacobian that is not positive and a warp beyond 45 degrees are warnings.
/// MacNeal and Harder's 3D patch test mesh passes with warnings, and both bricks are exact on it.
pub const HYCON_SHAPE_INTEGRATION_POINTS: HyconShapePolicy = 1;
/// hycon 0.8's check: the corner Jacobians and the warp limit are errors too, with 0.8's
/// messages ("Jacobian not positive at local node i", "face f is warped beyond the limit").
pub const HYCON_SHAPE_STRICT: HyconShapePolicy = 2;

/// Bit of `HyconShapeReport::warnings`: the Jacobian is not positive at corner node `corner`.
pub const HYCON_SHAPE_CORNER_JACOBIAN: i32 = 1;
/// Bit of `HyconShapeReport::warnings`: face `face` is warped by more than 45 degrees.
pub const HYCON_SHAPE_WARPED_FACE: i32 = 2;

/// The measures of a brick's shape (`hycon_brick_shape`). Jacobians are relative to `h^3`, `h`
/// the brick's longest edge, so the report does not change with the units.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HyconShapeReport {
    /// The smallest `det J / h^3` over the 8 integration points (2x2x2 Gauss).
    pub integration_jacobian: f64,
    /// The smallest `det J / h^3` over the 8 corner nodes, reached at node `corner`.
    pub corner_jacobian: f64,
    /// The largest warp over the 6 faces in degrees (measure at `HyconShapePolicy`), reached at
    /// face `face`.
    pub warp_degrees: f64,
    /// The local node (0-7) of `corner_jacobian`.
    pub corner: usize,
    /// The local face (0-5) of `warp_degrees`.
    pub face: usize,
    /// The warnings of the default policy: `HYCON_SHAPE_CORNER_JACOBIAN` and / or
    /// `HYCON_SHAPE_WARPED_FACE` (0: none).
    pub warnings: i32,
}

impl From<&ShapeReport> for HyconShapeReport {
    fn from(r: &ShapeReport) -> Self {
        let bit = |set: bool, b: i32| if set { b } else { 0 };
        HyconShapeReport {
            integration_jacobian: r.integration_jacobian,
            corner_jacobian: r.corner_jacobian,
            warp_degrees: r.warp_degrees,
            corner: r.corner,
            face: r.face,
            warnings: bit(r.corner_warning().is_some(), HYCON_SHAPE_CORNER_JACOBIAN)
                | bit(r.warp_warning().is_some(), HYCON_SHAPE_WARPED_FACE),
        }
    }
}

fn shape_policy(policy: HyconShapePolicy) -> Result<ShapePolicy, Fail> {
    match policy {
        HYCON_SHAPE_INTEGRATION_POINTS => Ok(ShapePolicy::IntegrationPoints),
        HYCON_SHAPE_STRICT => Ok(ShapePolicy::Strict),
        p => Err(Fail::invalid(format!(
            "unknown shape policy {p} (expected HYCON_SHAPE_INTEGRATION_POINTS = 1 or \
             HYCON_SHAPE_STRICT = 2)"
        ))),
    }
}

/// `HYCON_WARNING_SHAPE` with the report's warnings in words, if it has any.
pub(super) fn shape_warning(report: &ShapeReport) -> Option<Warning> {
    let words: Vec<String> = report.warnings().map(|w| w.to_string()).collect();
    (!words.is_empty()).then(|| Warning {
        status: HYCON_WARNING_SHAPE,
        message: words.join("; "),
    })
}

/// Check one brick's shape under `policy` and measure it (the policies and the warp measure:
/// `HyconShapePolicy`). Both kinds accept the same shapes. `report` (NULL: not wanted) receives
/// the measures on success and on a warning.
///
/// Returns `HYCON_OK`; `HYCON_WARNING_SHAPE` (default policy only) with a message naming the
/// corner and its `det J / h^3`, or the face and its warp; `HYCON_ERROR_BAD_ELEMENT` with a
/// message naming the defect; `HYCON_ERROR_INVALID_ARGUMENT` (unknown kind or policy,
/// non-finite coordinate, misaligned pointer); `HYCON_ERROR_NULL_POINTER`.
///
/// # Safety
/// `coords` must be NULL or point to 24 readable doubles; `report` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_brick_shape(
    kind: HyconBrickKind,
    coords: *const f64,
    policy: HyconShapePolicy,
    report: *mut HyconShapeReport,
) -> HyconStatus {
    boundary_warning("hycon_brick_shape", || {
        brick_formulation(kind)?;
        let policy = shape_policy(policy)?;
        let out = optional(report, "report")?;
        // SAFETY: the caller's contract on `coords`.
        let x = unsafe { read_brick(coords)? };
        let measured = solid::check_shape(&x, policy)?;
        // SAFETY: `out` was checked (aligned, writable by contract).
        unsafe { put(out, HyconShapeReport::from(&measured)) };
        Ok(shape_warning(&measured))
    })
}

/// Brick stiffness `K` (24 x 24) into `k_out`, row-major (`k_out[i * 24 + j] = K_ij`), rows and
/// columns in dof order `u0 v0 w0 u1 ...`. Symmetric, so column-major readers get the same.
/// Hybrid: `K = G^T H^-1 G`, `H = integral of P^T S P dV`, `G = integral of P^T B dV` (2x2x2
/// Gauss); H8: `K = integral of B^T D B dV`.
///
/// * `coords`: 24 doubles `x0 y0 z0 x1 ...`, node order of the header's brick section.
/// * `material`: finite, `E > 0`, `-1 < nu < 0.5`.
/// * `k_out`, `k_len`: at least 576 doubles; written only on success.
///
/// The shape is checked under the default policy: `HYCON_WARNING_SHAPE` (`k_out` written) for a
/// corner Jacobian or a warp the strict policy rejects (see `HyconShapePolicy`).
///
/// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_ARGUMENT` (kind, non-finite
/// coordinate), `HYCON_ERROR_INVALID_MATERIAL`, `HYCON_ERROR_BAD_ELEMENT`,
/// `HYCON_ERROR_BUFFER_TOO_SMALL`.
///
/// # Safety
/// `coords` NULL or 24 readable doubles; `material` NULL or a readable struct; `k_out` NULL or
/// writable for `k_len` doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_brick_stiffness(
    kind: HyconBrickKind,
    coords: *const f64,
    material: *const HyconSolidMaterial,
    k_out: *mut f64,
    k_len: usize,
) -> HyconStatus {
    boundary_warning("hycon_brick_stiffness", || {
        let formulation = brick_formulation(kind)?;
        // SAFETY: the caller's contract.
        let (x, material) = unsafe { (read_brick(coords)?, read_solid_material(material)?) };
        check_output(k_out, k_len, N_DOF * N_DOF, "k_out")?;
        let mut k = solid::BrickMatrix::zeros();
        let shape = solid::stiffness_into(formulation, &x, &material, &mut k)?;
        // row-major: the transpose's column-major storage
        let row_major = k.transpose();
        // SAFETY: `k_out` was checked for 576 values.
        unsafe { write_results(k_out, row_major.as_slice(), "stiffness", OUTSIDE_BRICK)? };
        Ok(shape_warning(&shape))
    })
}

/// Stress parameters `beta = H^-1 G q` of a brick from its nodal displacements `q` (24 doubles,
/// dof order `u0 v0 w0 u1 ...`): 18 for the hybrid brick (the first 6 are the mean stress
/// `{sxx, syy, szz, sxy, syz, szx}`), 0 for H8.
///
/// `out`, `len`, `needed`: the header's size convention (`HYCON_BRICK_MAX_BETA` always
/// suffices; `(NULL, 0, &needed)` asks for the count). `HYCON_WARNING_SHAPE` as
/// `hycon_brick_stiffness`.
///
/// # Safety
/// `coords` and `q` NULL or 24 readable doubles; `material` NULL or a readable struct; `out`
/// NULL or writable for `len` doubles; `needed` NULL or writable.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)] // flat C signature
pub unsafe extern "C" fn hycon_brick_stress_params(
    kind: HyconBrickKind,
    coords: *const f64,
    material: *const HyconSolidMaterial,
    q: *const f64,
    out: *mut f64,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary_warning("hycon_brick_stress_params", || {
        // SAFETY: the caller's contract.
        let field = unsafe { brick_stress(kind, coords, material, q)? };
        let beta = field.beta();
        check_results(beta, "beta", OUTSIDE_BRICK)?;
        // SAFETY: the caller's contract on `out` and `needed`.
        unsafe { fill(out, len, needed, "out", beta.len(), || Ok(beta.to_vec()))? };
        Ok(shape_warning(field.shape()))
    })
}

/// Stress `{sxx, syy, szz, sxy, syz, szx}` at the physical point `(px, py, pz)` of a brick from
/// its nodal displacements `q` (24 doubles). The point should lie in the brick (it is mapped to
/// natural coordinates by Newton's method); outside, the value is an extrapolation. `out`
/// receives 6 doubles on success. `HYCON_WARNING_SHAPE` as `hycon_brick_stiffness`.
///
/// # Safety
/// `coords` and `q` NULL or 24 readable doubles; `material` NULL or a readable struct; `out`
/// NULL or writable for 6 doubles.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)] // flat C signature
pub unsafe extern "C" fn hycon_brick_stress(
    kind: HyconBrickKind,
    coords: *const f64,
    material: *const HyconSolidMaterial,
    q: *const f64,
    px: f64,
    py: f64,
    pz: f64,
    out: *mut f64,
) -> HyconStatus {
    boundary_warning("hycon_brick_stress", || {
        for (v, name) in [(px, "px"), (py, "py"), (pz, "pz")] {
            check_finite_scalar(v, name)?;
        }
        check_pointer(out.cast_const(), "out")?;
        // SAFETY: the caller's contract.
        let field = unsafe { brick_stress(kind, coords, material, q)? };
        let s = field.at([px, py, pz]);
        // SAFETY: `out` is non-null and aligned (checked) and holds 6 doubles (contract).
        unsafe { write_results(out, s.as_slice(), "stress", OUTSIDE_BRICK)? };
        Ok(shape_warning(field.shape()))
    })
}

/// Traction `{tx, ty, tz} = sigma n` (outward unit normal `n`) at face parameters `(s, t)` in
/// `[-1, 1]^2` of face `face` (0 to 5, numbering in the header's brick section) of a brick,
/// from its nodal displacements `q` (24 doubles). `out` receives 3 doubles on success.
/// `HYCON_WARNING_SHAPE` as `hycon_brick_stiffness`.
///
/// # Safety
/// `coords` and `q` NULL or 24 readable doubles; `material` NULL or a readable struct; `out`
/// NULL or writable for 3 doubles.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)] // flat C signature
pub unsafe extern "C" fn hycon_brick_face_traction(
    kind: HyconBrickKind,
    coords: *const f64,
    material: *const HyconSolidMaterial,
    q: *const f64,
    face: usize,
    s: f64,
    t: f64,
    out: *mut f64,
) -> HyconStatus {
    boundary_warning("hycon_brick_face_traction", || {
        if face >= 6 {
            return Err(Fail::invalid(format!(
                "face {face} of a brick (faces are 0 to 5)"
            )));
        }
        for (v, name) in [(s, "s"), (t, "t")] {
            check_finite_scalar(v, name)?;
            if !(-1.0..=1.0).contains(&v) {
                return Err(Fail::invalid(format!("{name} = {v} is outside [-1, 1]")));
            }
        }
        check_pointer(out.cast_const(), "out")?;
        // SAFETY: the caller's contract.
        let field = unsafe { brick_stress(kind, coords, material, q)? };
        let tr = field.face_traction(face, s, t);
        // SAFETY: `out` is non-null and aligned (checked) and holds 3 doubles (contract).
        unsafe { write_results(out, &tr, "traction", OUTSIDE_BRICK)? };
        Ok(shape_warning(field.shape()))
    })
}
