//! The 18-beta assumed-stress hybrid brick of Pian and Tong (1986), the 3D twin of the plane
//! Pian-Sumihara element.
//!
//! The stress is assumed in natural contravariant components `tau^ab` (Voigt order
//! `11, 22, 33, 12, 23, 31`; `xi_1, xi_2, xi_3 = xi, eta, zeta`):
//!
//! ```text
//! tau^11 = b1  + b7  eta  + b8  zeta + b13 eta zeta
//! tau^22 = b2  + b9  xi   + b10 zeta + b14 xi zeta
//! tau^33 = b3  + b11 xi   + b12 eta  + b15 xi eta
//! tau^12 = b4  + b16 zeta
//! tau^23 = b5  + b17 xi
//! tau^31 = b6  + b18 eta
//! ```
//!
//! and carried to Cartesian components with the Jacobian frozen at the centre, `J0 = dx/dxi` at
//! `xi = 0`: `sigma = J0 tau J0^T`. The six constant terms are equivalent to constant Cartesian
//! stress, so they are taken as `sigma = beta_1..6` directly (same span, and `beta_1..6` is then
//! the mean stress in Voigt order); each higher column is scaled by `1 / (|J0_a| |J0_b|)` (`J0_a`
//! the `a`-th column of `J0`), which leaves the span unchanged and gives `beta` stress units.
//!
//! Why this field: it is the least-order one (18 = 24 dofs less 6 rigid modes), it is the
//! stress field Pian and Tong derived from Wilson's incompatible modes (so the element is free of
//! shear and volumetric locking on regular and parallelepiped meshes), each normal stress carries
//! exactly the linear and bilinear terms that the bending and hourglass modes of the trilinear
//! brick excite and each shear stress the single linear term that its twisting mode needs, and
//! in the `J0` frame it is invariant: node renumberings that are symmetries of the cube permute
//! or negate the columns, and a rigid rotation of the brick rotates `J0` with it. The least-order
//! fields of Punch and Atluri (1984) reach the same count from a group-theoretic argument in
//! natural coordinates, but their stable choice is not unique; the Pian-Tong field is the one
//! library users meet in the literature and matches the plane Pian-Sumihara element hycon ships.
//!
//! `H = integral of P^T S P dV`, `G = integral of P^T B dV` (`B` the trilinear
//! strain-displacement matrix), both with 2x2x2 Gauss (exact on parallelepipeds; on distorted
//! bricks the same rule in both keeps the patch test exact, because `beta = H^-1 G q` reproduces
//! a constant stress whatever rule is used as long as it is the same one).

use super::geometry::{Trilinear, gauss_points};
use super::h8::strain_displacement;
use super::{Isotropic, N_DOF, Voigt};
use nalgebra::{Matrix3, SMatrix};

/// Number of stress parameters.
pub const N_BETA: usize = 18;

/// The 12 higher-order terms: natural component `(a, b)` and the monomial's exponents.
const HIGHER: [((usize, usize), [u8; 3]); 12] = [
    ((0, 0), [0, 1, 0]),
    ((0, 0), [0, 0, 1]),
    ((0, 0), [0, 1, 1]),
    ((1, 1), [1, 0, 0]),
    ((1, 1), [0, 0, 1]),
    ((1, 1), [1, 0, 1]),
    ((2, 2), [1, 0, 0]),
    ((2, 2), [0, 1, 0]),
    ((2, 2), [1, 1, 0]),
    ((0, 1), [0, 0, 1]),
    ((1, 2), [1, 0, 0]),
    ((2, 0), [0, 1, 0]),
];

/// The centre-Jacobian transformation of the 12 higher columns: column `k` is the Cartesian
/// Voigt vector of the unit natural component `HIGHER[k]`, scaled as the module docs say.
#[derive(Debug, Clone, Copy)]
pub struct Frame {
    columns: SMatrix<f64, 6, 12>,
}

impl Frame {
    /// The frame of a brick (its Jacobian at the centre).
    pub fn new(map: &Trilinear) -> Self {
        let j0: Matrix3<f64> = map.jacobian([0.0; 3]);
        let mut columns = SMatrix::<f64, 6, 12>::zeros();
        for (k, &((a, b), _)) in HIGHER.iter().enumerate() {
            let (ja, jb) = (j0.column(a), j0.column(b));
            let scale = 1.0 / (ja.norm() * jb.norm());
            // sigma_ij = (J_ia J_jb + J_ib J_ja) / 2, scaled
            let s = |i: usize, j: usize| 0.5 * (ja[i] * jb[j] + jb[i] * ja[j]) * scale;
            let v = [s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(2, 0)];
            for (r, value) in v.into_iter().enumerate() {
                columns[(r, k)] = value;
            }
        }
        Frame { columns }
    }

    /// The stress basis `P(xi)` (6 x 18): Cartesian stress `P beta` at natural point `xi`.
    pub fn basis(&self, xi: [f64; 3]) -> SMatrix<f64, 6, N_BETA> {
        let mut p = SMatrix::<f64, 6, N_BETA>::zeros();
        for r in 0..6 {
            p[(r, r)] = 1.0;
        }
        for (k, &(_, e)) in HIGHER.iter().enumerate() {
            let f: f64 = (0..3).map(|a| xi[a].powi(i32::from(e[a]))).product();
            for r in 0..6 {
                p[(r, 6 + k)] = self.columns[(r, k)] * f;
            }
        }
        p
    }
}

/// `H` (18 x 18) and `G` (18 x 24) of the brick.
pub fn matrices(
    map: &Trilinear,
    material: &Isotropic,
) -> (SMatrix<f64, N_BETA, N_BETA>, SMatrix<f64, N_BETA, N_DOF>) {
    let frame = Frame::new(map);
    let s = material.compliance();
    let mut h = SMatrix::<f64, N_BETA, N_BETA>::zeros();
    let mut g = SMatrix::<f64, N_BETA, N_DOF>::zeros();
    for (xi, w) in gauss_points() {
        let p = frame.basis(xi);
        let (b, det) = strain_displacement(map, xi);
        let pw = p * (w * det);
        h += pw.transpose() * (s * p);
        g += pw.transpose() * b;
    }
    (h, g)
}

/// Stress `P(xi) beta` at natural point `xi`.
pub fn stress(frame: &Frame, beta: &[f64], xi: [f64; 3]) -> Voigt {
    frame.basis(xi) * SMatrix::<f64, N_BETA, 1>::from_column_slice(&beta[..N_BETA])
}
