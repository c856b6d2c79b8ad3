//! The condensation of an assumed-stress hybrid element, for any number `NB` of stress
//! parameters and `ND` of dofs: the plane, axisymmetric and brick elements differ only in how
//! they integrate `H = integral of P^T S P dV` and `G = integral of P^T B dV` (or its boundary
//! form); the stiffness and the stress parameters follow from them alike (docs/method.md,
//! "Plane hybrid elements", "The hybrid brick").

use crate::error::ShapeError;
use nalgebra::{Cholesky, Const, SMatrix, SVector};

/// `H = L L^T` (Cholesky); `H` is positive definite for any valid shape, so a failure means a
/// degenerate element.
fn factor<const NB: usize>(
    h: SMatrix<f64, NB, NB>,
) -> Result<Cholesky<f64, Const<NB>>, ShapeError> {
    Cholesky::new(h).ok_or(ShapeError::Degenerate)
}

/// `K = G^T H^-1 G` into `out`, as `W^T W` with `W = L^-1 G` and `H = L L^T`: no explicit
/// inverse, symmetric by construction.
pub fn stiffness_into<const NB: usize, const ND: usize>(
    h: SMatrix<f64, NB, NB>,
    g: &SMatrix<f64, NB, ND>,
    out: &mut SMatrix<f64, ND, ND>,
) -> Result<(), ShapeError> {
    let w = factor(h)?
        .l_dirty()
        .solve_lower_triangular(g)
        .ok_or(ShapeError::Degenerate)?;
    w.tr_mul_to(&w, out);
    Ok(())
}

/// The stress parameters `beta = H^-1 G q` of the element dofs `q`.
pub fn stress_parameters<const NB: usize, const ND: usize>(
    h: SMatrix<f64, NB, NB>,
    g: &SMatrix<f64, NB, ND>,
    q: &SVector<f64, ND>,
) -> Result<SVector<f64, NB>, ShapeError> {
    Ok(factor(h)?.solve(&(g * q)))
}
