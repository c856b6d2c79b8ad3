//! The Pian-Sumihara 5-beta hybrid quad, for comparison.
//!
//! Stress in natural coordinates, `tau_xixi = b4 eta`, `tau_etaeta = b5 xi`, carried to
//! physical components with the Jacobian frozen at the centre, `J0 = [[a1, a2], [b1, b2]]`
//! (`x = a0 + a1 xi + a2 eta + a3 xi eta`, likewise `y`):
//!
//! ```text
//! sx  = b1 + a1^2 b4 eta + a2^2 b5 xi
//! sy  = b2 + b1^2 b4 eta + b2^2 b5 xi
//! txy = b3 + a1 b1 b4 eta + a2 b2 b5 xi
//! ```
//!
//! (the last two columns are divided by `a1^2 + b1^2` and `a2^2 + b2^2`, which leaves the span
//! unchanged and makes `beta` carry stress units). `H = integral of P^T S P t dA`,
//! `G = integral of P^T B t dA`, `B` the bilinear strain-displacement matrix; 2x2 Gauss is exact
//! for both.

use super::MAX_DOF;
use super::geometry::{Bilinear, GAUSS2};
use super::q4::strain_displacement;
use crate::material::Material;
use nalgebra::SMatrix;

/// Number of stress parameters.
pub const N_BETA: usize = 5;

/// The stress basis `P(xi, eta)` (3 x 5).
pub fn stress_basis(map: &Bilinear, xi: f64, eta: f64) -> SMatrix<f64, 3, N_BETA> {
    let j0 = map.jacobian(0.0, 0.0);
    let (a1, b1, a2, b2) = (j0[(0, 0)], j0[(1, 0)], j0[(0, 1)], j0[(1, 1)]);
    let (c1, c2) = (a1 * a1 + b1 * b1, a2 * a2 + b2 * b2);
    let (e, x) = (eta / c1, xi / c2);
    SMatrix::<f64, 3, N_BETA>::new(
        1.0,
        0.0,
        0.0,
        a1 * a1 * e,
        a2 * a2 * x, //
        0.0,
        1.0,
        0.0,
        b1 * b1 * e,
        b2 * b2 * x, //
        0.0,
        0.0,
        1.0,
        a1 * b1 * e,
        a2 * b2 * x,
    )
}

/// `H` (5 x 5) and `G` (5 x 8, zero-padded to `MAX_DOF` columns).
pub fn matrices(
    map: &Bilinear,
    material: &Material,
) -> (SMatrix<f64, N_BETA, N_BETA>, SMatrix<f64, N_BETA, MAX_DOF>) {
    let s = material.compliance();
    let t = material.thickness;
    let mut h = SMatrix::<f64, N_BETA, N_BETA>::zeros();
    let mut g = SMatrix::<f64, N_BETA, MAX_DOF>::zeros();
    for (xi, wx) in GAUSS2 {
        for (eta, wy) in GAUSS2 {
            let p = stress_basis(map, xi, eta);
            let (b, det) = strain_displacement(map, xi, eta);
            let w = wx * wy * det * t;
            h += p.transpose() * (s * p) * w;
            let mut gv = g.fixed_view_mut::<N_BETA, 8>(0, 0);
            gv += p.transpose() * b * w;
        }
    }
    (h, g)
}

/// Stress at natural coordinates `(xi, eta)` from `beta`.
pub fn stress(map: &Bilinear, beta: &[f64], xi: f64, eta: f64) -> [f64; 3] {
    let p = stress_basis(map, xi, eta);
    let mut out = [0.0; 3];
    for (r, o) in out.iter_mut().enumerate() {
        *o = (0..N_BETA).map(|k| p[(r, k)] * beta[k]).sum();
    }
    out
}
