//! Consistent nodal forces of a distributed load on one face of a brick.
//!
//! Face `f` (numbering and node order in [`super::geometry`]; its 4 nodes counter-clockwise seen
//! from outside) is the bilinear surface `x(s, t) = sum_k M_k(s, t) x_k`, `(s, t)` in
//! `[-1, 1]^2`, `M_k` the bilinear weights of the face's nodes (the brick's shape functions
//! restricted to the face), with the area vector `dA n = (dx/ds x dx/dt) ds dt` pointing
//! outward. On it the load is a pressure `p` (force per area, **positive pushing into the
//! body**) and a traction vector `t` (force per area), each given at the face's 4 nodes and
//! interpolated with the `M_k`. The surface force is `q = t - p n`, and the consistent nodal
//! forces are
//!
//! ```text
//! f_k = integral over the face of M_k q dA = integral of M_k (t |dx/ds x dx/dt| - p (dx/ds x dx/dt)) ds dt.
//! ```
//!
//! Quadrature: 2 x 2 Gauss (exact to degree 3 in each of `s`, `t`). `dx/ds x dx/dt` is linear in
//! `s` and in `t` (its `s t` term is `a3 x a3 = 0` for `x = a0 + a1 s + a2 t + a3 s t`), so the
//! pressure integrand `M_k p (dx/ds x dx/dt)` has degree at most 3 in each variable and the
//! pressure part is **exact on every face, warped or not**: the sum of the nodal forces of a
//! uniform pressure is `-p` times the face's vector area, which depends only on its boundary
//! (the projected area). On a plane face `|dx/ds x dx/dt|` is linear as well and the traction
//! part is exact too; on a warped face it is the square root of a polynomial, and 2 x 2 Gauss
//! approximates it (the error vanishes with the square of the warp).

use super::N_DOF;
use super::geometry::{FACES, ShapePolicy, Trilinear, check_brick};
use crate::error::{Error, Result};
use crate::fem::boundary::BoundaryLoad;
use crate::fem::quadrature::GAUSS2;
use nalgebra::SVector;

pub use crate::fem::boundary::FacePoint;

/// The brick's element force vector (24 values, dofs `u0 v0 w0 u1 ...`).
pub type BrickVector = SVector<f64, N_DOF>;

/// A distributed load on one brick face: pressure and traction `[tx, ty, tz]` at the face's 4
/// nodes in face order ([`FACES`]), interpolated bilinearly. The surface force is `t - p n`
/// (`n` the outward unit normal).
pub type FaceLoad = BoundaryLoad<3, 4>;

/// The surface force `t - p n` of `load` at a face point: the nodal values `t_k - p_k n`
/// interpolated with the point's weights.
fn surface_force(load: &FaceLoad, point: &FacePoint) -> [f64; 3] {
    let mut q = [0.0; 3];
    for (k, m) in point.weights.iter().enumerate() {
        let qk = load.surface_force(k, point.normal);
        for (qi, qki) in q.iter_mut().zip(qk) {
            *qi += m * qki;
        }
    }
    q
}

/// Consistent nodal forces `f_k = integral of M_k q dA` of the surface force `q` (force per
/// area, evaluated at each quadrature point) on face `face` of the brick `map`: the forces on
/// the face's 4 nodes, in face order. 2 x 2 Gauss (see the module docs for when it is exact).
/// Panics if `face >= 6`.
pub fn face_forces(
    map: &Trilinear,
    face: usize,
    q: impl Fn(&FacePoint) -> [f64; 3],
) -> [[f64; 3]; 4] {
    let corners = FACES[face].map(|k| map.x[k]);
    let mut f = [[0.0; 3]; 4];
    for (s, ws) in GAUSS2 {
        for (t, wt) in GAUSS2 {
            let point = FacePoint::new(corners, s, t);
            let qp = q(&point);
            for (fk, m) in f.iter_mut().zip(point.weights) {
                for i in 0..3 {
                    fk[i] += m * qp[i] * point.area * ws * wt;
                }
            }
        }
    }
    f
}

/// Consistent nodal forces of `load` on face `face` (0 to 5) of a brick (see the module docs),
/// as the brick's force vector in dof order `u0 v0 w0 u1 ...`: only the face's 4 nodes carry
/// forces. Both formulations take these loads (the displacement on a face is the bilinear
/// interpolation of its 4 nodes in both).
///
/// Checks the brick's shape (an inverted brick would turn the normal inward), `face < 6` and a
/// finite load.
pub fn face_load(coords: &[[f64; 3]], face: usize, load: &FaceLoad) -> Result<BrickVector> {
    let (map, _) = check_brick(coords, ShapePolicy::default())?;
    if face >= FACES.len() {
        return Err(Error::InvalidInput(format!(
            "face {face} of a brick (faces are 0 to 5)"
        )));
    }
    load.validate()?;
    let f = face_forces(&map, face, |p| surface_force(load, p));
    let mut out = BrickVector::zeros();
    for (&node, fk) in FACES[face].iter().zip(f) {
        for i in 0..3 {
            out[3 * node + i] = fk[i];
        }
    }
    Ok(out)
}
