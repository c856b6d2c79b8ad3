//! The trilinear displacement brick (H8), 2x2x2 Gauss: the baseline every FE user knows.
//!
//! `K = integral of B^T D B dV`, `B` the strain-displacement matrix of the trilinear shape
//! functions (`[exx, eyy, ezz, gxy, gyz, gzx] = B q`, engineering shear strains). It locks in
//! bending (parasitic shear) and for nearly incompressible material (volumetric locking), which
//! is what the hybrid brick is compared against.

use super::geometry::{Trilinear, gauss_points};
use super::{Isotropic, N_DOF, Voigt};
use nalgebra::SMatrix;

/// Strain-displacement matrix `B` (6 x 24) and `det J` at natural point `xi`.
pub fn strain_displacement(map: &Trilinear, xi: [f64; 3]) -> (SMatrix<f64, 6, N_DOF>, f64) {
    let (grad, det) = map.gradients(xi);
    let mut b = SMatrix::<f64, 6, N_DOF>::zeros();
    for (k, [dx, dy, dz]) in grad.into_iter().enumerate() {
        let c = 3 * k;
        b[(0, c)] = dx;
        b[(1, c + 1)] = dy;
        b[(2, c + 2)] = dz;
        b[(3, c)] = dy;
        b[(3, c + 1)] = dx;
        b[(4, c + 1)] = dz;
        b[(4, c + 2)] = dy;
        b[(5, c)] = dz;
        b[(5, c + 2)] = dx;
    }
    (b, det)
}

/// `K = sum over the 2x2x2 Gauss points of B^T D B det J w` (24 x 24).
pub fn stiffness(map: &Trilinear, material: &Isotropic) -> SMatrix<f64, N_DOF, N_DOF> {
    let d = material.elasticity();
    let mut k = SMatrix::<f64, N_DOF, N_DOF>::zeros();
    for (xi, w) in gauss_points() {
        let (b, det) = strain_displacement(map, xi);
        k += b.transpose() * (d * b) * (w * det);
    }
    k
}

/// Stress `D B q` at natural point `xi` from the 24 element dofs `q`.
pub fn stress(map: &Trilinear, material: &Isotropic, q: &[f64], xi: [f64; 3]) -> Voigt {
    let (b, _) = strain_displacement(map, xi);
    material.elasticity() * (b * SMatrix::<f64, N_DOF, 1>::from_column_slice(&q[..N_DOF]))
}
