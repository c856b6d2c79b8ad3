//! Axisymmetric 4-node elements: the hybrid element with 7 stress parameters and the bilinear
//! displacement quad (Q4) baseline.
//!
//! Coordinates `x = r >= 0`, `y = z`; strains `[eps_r, eps_z, gamma_rz, eps_theta]` with
//! `eps_theta = u_r / r`; stresses `[sigma_r, sigma_z, tau_rz, sigma_theta]`; every integral is
//! weighted by the measure `2 pi r` ([`Material::measure`], the full circle).
//!
//! # Why a domain form
//! The plane hybrid element needs displacements on its boundary only, because its Airy-function
//! stress field is equilibrated and `G` reduces to a boundary integral. In axisymmetry the
//! equilibrium equations carry the hoop terms, `d(sigma_r)/dr + d(tau_rz)/dz + (sigma_r -
//! sigma_theta)/r = 0` and `d(tau_rz)/dr + d(sigma_z)/dz + tau_rz/r = 0`: the Airy basis does
//! not satisfy them (its `sigma_r - sigma_theta` term is missing), and the hoop strain
//! `eps_theta = u_r / r` is a domain quantity. So `G` is the Hellinger-Reissner domain form
//! `G = integral of P^T B 2 pi r dA` with the bilinear (Q4) displacement field, whose edges are
//! linear as in the plane element; `H = integral of P^T S P 2 pi r dA`; `K = G^T H^-1 G`.
//! 3x3 Gauss integrates both exactly for parallelograms (the integrands are at most quartic in
//! each natural coordinate there).
//!
//! # The stress field (7 beta)
//! The least-order field of the zero-energy-mode construction of Jog and Annabattula (2006,
//! IJNME 68), the construction Pian and Sumihara used in the plane (the terms below were derived
//! and checked here, not copied from the paper): the Q4 displacement space has 8 modes, of which
//! only the axial translation is
//! rigid (a radial translation stretches the hoop), so 7 stress parameters are the fewest that
//! can leave no spurious mode. Four constants (`sigma_r, sigma_z, tau_rz, sigma_theta`), the two
//! Pian-Sumihara terms for the two bending (hourglass) modes, and one hoop term linear in the
//! axial coordinate for the mode `u = (-z, r)` (a plane rotation, which strains only the hoop:
//! `eps_theta = -z / r`):
//!
//! ```text
//! sigma_r     = b1 + a1^2 b5 eta' + a2^2 b6 xi'
//! sigma_z     = b2 + b1^2 b5 eta' + b2^2 b6 xi'      (Pian-Sumihara, J0 = [[a1, a2], [b1, b2]],
//! tau_rz      = b3 + a1 b1 b5 eta' + a2 b2 b6 xi'     eta' = eta / (a1^2 + b1^2), likewise xi')
//! sigma_theta = b4 + b7 zh,   zh = (z - zc) / s      (element frame: area centroid, sqrt(area))
//! ```
//!
//! The hoop term is written in the element frame's `z`, not in a natural coordinate, so that it
//! sees the rotation-like mode whatever the element's orientation (a natural coordinate running
//! radially would not). The only hydrostatic stress in the span is the constant one, so as
//! `nu -> 0.5` the element imposes one volume constraint (like the mean-dilatation Q1-P0
//! element) and does not lock. The rank (exactly one zero eigenvalue, the axial translation) is
//! checked on distorted shapes and on elements touching the axis in `tests/axisymmetric.rs`.
//! Equilibrium is not built into the field (it holds weakly); constant stress states are exact
//! (patch test). On a uniform mesh under pressure the element is nodally exact for Lamé's
//! cylinder, as Jog and Annabattula report for theirs.
//!
//! Only the 4-node element: the 5- and 6-node transition elements and the Pian-Sumihara element
//! are rejected in axisymmetric analysis (see [`super::check_element`]).

use super::geometry::{Bilinear, Frame, GAUSS2, GAUSS3};
use super::{ElementMatrix, MAX_DOF, pian_sumihara, q4};
use crate::material::Material;
use nalgebra::{SMatrix, SVector};

/// Number of stress parameters of the axisymmetric hybrid element.
pub const N_BETA: usize = 7;

/// Strain-displacement matrix `B` (4 x 8, rows `eps_r, eps_z, gamma_rz, eps_theta`), `det J`
/// and the physical point at `(xi, eta)`. The hoop row is `N_i / r` (`r > 0` at interior points).
pub fn strain_displacement(
    map: &Bilinear,
    xi: f64,
    eta: f64,
) -> (SMatrix<f64, 4, 8>, f64, [f64; 2]) {
    let (plane, det) = q4::strain_displacement(map, xi, eta);
    let (n, _) = Bilinear::shape(xi, eta);
    let p = map.point(xi, eta);
    let mut b = SMatrix::<f64, 4, 8>::zeros();
    b.fixed_rows_mut::<3>(0).copy_from(&plane);
    for (i, ni) in n.iter().enumerate() {
        b[(3, 2 * i)] = ni / p[0];
    }
    (b, det, p)
}

/// Q4 stiffness `K = integral of B^T D B 2 pi r dA` (2x2 Gauss) into the leading 8 x 8 block
/// of `out` (the rest zeroed).
pub fn q4_stiffness_into(map: &Bilinear, material: &Material, out: &mut ElementMatrix) {
    let d = material.elasticity_axisymmetric();
    let mut k = SMatrix::<f64, 8, 8>::zeros();
    for (xi, wx) in GAUSS2 {
        for (eta, wy) in GAUSS2 {
            let (b, det, p) = strain_displacement(map, xi, eta);
            k += b.transpose() * d * b * (wx * wy * det * material.measure(p));
        }
    }
    out.fill(0.0);
    out.fixed_view_mut::<8, 8>(0, 0).copy_from(&k);
}

/// Q4 stress `D B q` (`[sigma_r, sigma_z, tau_rz, sigma_theta]`) at `(xi, eta)` from the 8
/// element dofs `q` (not finite on the axis, where `B`'s hoop row is).
pub fn q4_stress(map: &Bilinear, material: &Material, q: &[f64], xi: f64, eta: f64) -> [f64; 4] {
    let (b, _, _) = strain_displacement(map, xi, eta);
    let s =
        material.elasticity_axisymmetric() * (b * SVector::<f64, 8>::from_column_slice(&q[..8]));
    [s[0], s[1], s[2], s[3]]
}

/// The stress basis `P` (4 x 7) at natural coordinates `(xi, eta)`, physical point `p`.
pub fn stress_basis(
    map: &Bilinear,
    frame: &Frame,
    xi: f64,
    eta: f64,
    p: [f64; 2],
) -> SMatrix<f64, 4, N_BETA> {
    let ps = pian_sumihara::stress_basis(map, xi, eta);
    let mut out = SMatrix::<f64, 4, N_BETA>::zeros();
    // meridian constants b1..b3 and the two Pian-Sumihara terms b5, b6
    for (col, ps_col) in [(0, 0), (1, 1), (2, 2), (4, 3), (5, 4)] {
        out.fixed_view_mut::<3, 1>(0, col)
            .copy_from(&ps.fixed_view::<3, 1>(0, ps_col));
    }
    out[(3, 3)] = 1.0;
    out[(3, 6)] = frame.local(p)[1];
    out
}

/// `H` (7 x 7) and `G` (7 x 8, zero-padded to `MAX_DOF` columns) of the axisymmetric hybrid
/// element, 3x3 Gauss weighted by `2 pi r`.
pub fn matrices(
    map: &Bilinear,
    frame: &Frame,
    material: &Material,
) -> (SMatrix<f64, N_BETA, N_BETA>, SMatrix<f64, N_BETA, MAX_DOF>) {
    let s = material.compliance_axisymmetric();
    let mut h = SMatrix::<f64, N_BETA, N_BETA>::zeros();
    let mut g = SMatrix::<f64, N_BETA, MAX_DOF>::zeros();
    for (xi, wx) in GAUSS3 {
        for (eta, wy) in GAUSS3 {
            let (b, det, p) = strain_displacement(map, xi, eta);
            let pb = stress_basis(map, frame, xi, eta, p);
            let w = wx * wy * det * material.measure(p);
            h += pb.transpose() * (s * pb) * w;
            let mut gv = g.fixed_view_mut::<N_BETA, 8>(0, 0);
            gv += pb.transpose() * b * w;
        }
    }
    (h, g)
}

/// Stress `P beta` (`[sigma_r, sigma_z, tau_rz, sigma_theta]`) at natural coordinates
/// `(xi, eta)`, physical point `p`.
pub fn stress(
    map: &Bilinear,
    frame: &Frame,
    beta: &[f64],
    xi: f64,
    eta: f64,
    p: [f64; 2],
) -> [f64; 4] {
    let s = stress_basis(map, frame, xi, eta, p) * SVector::<f64, N_BETA>::from_column_slice(beta);
    [s[0], s[1], s[2], s[3]]
}
