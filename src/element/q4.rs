//! The bilinear displacement quad (Q4), 2x2 Gauss: the baseline every FE user knows.
//!
//! `K = integral of B^T D B t dA`, `B` the strain-displacement matrix of the bilinear shape
//! functions (`[ex, ey, gxy] = B q`). It locks in bending and for nearly incompressible
//! material, which is what the hybrid elements are compared against.

use super::ElementMatrix;
use super::geometry::{Bilinear, GAUSS2};
use crate::material::Material;
use nalgebra::SMatrix;

/// Strain-displacement matrix `B` (3 x 8) and `det J` at `(xi, eta)`.
pub fn strain_displacement(map: &Bilinear, xi: f64, eta: f64) -> (SMatrix<f64, 3, 8>, f64) {
    let (grad, det) = map.gradients(xi, eta);
    let mut b = SMatrix::<f64, 3, 8>::zeros();
    for (i, [dx, dy]) in grad.into_iter().enumerate() {
        b[(0, 2 * i)] = dx;
        b[(1, 2 * i + 1)] = dy;
        b[(2, 2 * i)] = dy;
        b[(2, 2 * i + 1)] = dx;
    }
    (b, det)
}

/// Stiffness into the leading 8 x 8 block of `out` (the rest zeroed).
pub fn stiffness_into(map: &Bilinear, material: &Material, out: &mut ElementMatrix) {
    let d = material.elasticity();
    let mut k = SMatrix::<f64, 8, 8>::zeros();
    for (xi, wx) in GAUSS2 {
        for (eta, wy) in GAUSS2 {
            let (b, det) = strain_displacement(map, xi, eta);
            k += b.transpose() * d * b * (wx * wy * det * material.thickness);
        }
    }
    out.fill(0.0);
    out.fixed_view_mut::<8, 8>(0, 0).copy_from(&k);
}

/// Stress `D B q` at `(xi, eta)` from the 8 element dofs `q`.
pub fn stress(map: &Bilinear, material: &Material, q: &[f64], xi: f64, eta: f64) -> [f64; 3] {
    let (b, _) = strain_displacement(map, xi, eta);
    let strain = b * nalgebra::SVector::<f64, 8>::from_column_slice(&q[..8]);
    let s = material.elasticity() * strain;
    [s[0], s[1], s[2]]
}
