//! The Jacobian quality of an element, the same definition in two and three dimensions.
//!
//! The **scaled Jacobian** at a corner of an element is `det J / prod_a |J_a|`, `J_a = dx/dxi_a`
//! the columns of the Jacobian of its map there, which at a corner are (half) the edges leaving
//! it: the signed volume of the corner's edge parallelogram or parallelepiped over the product of
//! its edge lengths (the scaled Jacobian of the Verdict library). An element's quality is the
//! smallest over its corners: 1 for a rectangle or a rectangular box, toward 0 as a corner
//! flattens, unchanged by size, position and rotation, independent of the aspect ratio.

use nalgebra::{Const, DimMin, SMatrix};

/// `det J / prod_a |J_a|` of the Jacobian `j` at a corner (see the [module docs](self)).
pub fn scaled_jacobian<const D: usize>(j: &SMatrix<f64, D, D>) -> f64
where
    Const<D>: DimMin<Const<D>, Output = Const<D>>,
{
    let lengths: f64 = j.column_iter().map(|c| c.norm()).product();
    j.determinant() / lengths
}
