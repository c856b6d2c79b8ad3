//! What a host checks about one brick besides its validity: its volume and a Jacobian quality
//! (the same for both formulations, which share the trilinear geometry).
//!
//! * Volume `V = integral of det J dxi` over `[-1, 1]^3` (2 x 2 x 2 Gauss: `det J` of the
//!   trilinear map has degree at most 2 in each natural coordinate, so the rule is exact for any
//!   brick, warped faces included).
//! * Quality: the **scaled Jacobian** ([`crate::fem::quality`]), the smallest over the 8 corners
//!   of `det J / (|J_1| |J_2| |J_3|)`, `J_a = dx/dxi_a` the columns of the Jacobian; at a corner
//!   they are half the three edges leaving it, so this is the volume of the corner's edge
//!   parallelepiped over the product of the edge lengths. It is 1 for rectangular boxes, falls toward 0 as a corner flattens, does not
//!   change with size, position or rotation, and is positive for every brick the strict shape
//!   policy accepts (the default policy accepts a non-positive corner with a warning, and this
//!   measure is then at or below 0). It does not measure the aspect ratio.

use super::geometry::{NODE_XI, ShapePolicy, check_brick};
use crate::error::ShapeError;
use crate::fem::quality::scaled_jacobian as corner_quality;

/// Volume of a checked brick (see the module docs).
pub fn volume(coords: &[[f64; 3]]) -> Result<f64, ShapeError> {
    Ok(check_brick(coords, ShapePolicy::default())?.0.volume())
}

/// The scaled Jacobian of a checked brick (see the module docs), at most 1; at or below 0 where
/// the default shape policy warns of a non-positive Jacobian at a corner.
pub fn scaled_jacobian(coords: &[[f64; 3]]) -> Result<f64, ShapeError> {
    let (map, _) = check_brick(coords, ShapePolicy::default())?;
    Ok(NODE_XI
        .iter()
        .map(|xi| corner_quality(&map.jacobian(*xi)))
        .fold(f64::INFINITY, f64::min))
}
