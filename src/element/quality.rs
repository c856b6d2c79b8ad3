//! What a host checks about one plane or axisymmetric element besides its validity: its volume
//! and a Jacobian quality.
//!
//! * Volume `V = integral of m dA` ([`Material::measure`]): `A t` in plane analyses, and in
//!   axisymmetry `integral of 2 pi r dA = 2 pi r_c A` (Pappus), `r_c` the radius of the area
//!   centroid: the volume of the whole ring. Exact for every element (its edges are straight).
//! * Quality: the **scaled Jacobian** ([`crate::fem::quality`]), the smallest over the element's
//!   true corners of `det J / (|dx/dxi| |dx/deta|)` there, which for the bilinear map of a 4-node
//!   quad is the sine of the interior angle at the corner (`J` at a corner has the two half edges from it as
//!   columns). The same number is defined for the hybrid element's polygons: mid-side nodes on
//!   straight edges are not corners and are skipped. It is 1 for rectangles, falls toward 0 as a
//!   corner angle approaches 0 or 180 degrees, does not change with size, position or rotation,
//!   and is positive for every element [`super::check_shape`] accepts (whose threshold is
//!   `1e-6`). It does not measure the aspect ratio. A triangle (the hybrid element takes 3 true
//!   corners) reaches at most `sin 60 = 0.866`.
//!
//! For whole meshes, [`crate::mesh::quality`] reports corner angles and aspect ratios.

use super::geometry::{area_centroid, is_corner};
use super::{Formulation, checked, checked_for};
use crate::error::ShapeError;
use crate::fem::quality::scaled_jacobian as corner_quality;
use crate::material::Material;
use nalgebra::Matrix2;

/// Volume of a checked element (see the module docs): `A t`, or `2 pi r_c A` in axisymmetry.
pub fn volume(
    formulation: Formulation,
    coords: &[[f64; 2]],
    material: &Material,
) -> Result<f64, ShapeError> {
    let (info, _) = checked_for(formulation, coords, material)?;
    let (area, centroid) = (info.area, area_centroid(coords).1);
    Ok(area * material.measure(centroid))
}

/// The scaled Jacobian of a checked element (see the module docs): the smallest sine of an
/// interior angle at a true corner, in `(0, 1]`.
pub fn scaled_jacobian(formulation: Formulation, coords: &[[f64; 2]]) -> Result<f64, ShapeError> {
    checked(formulation, coords)?;
    Ok((0..coords.len())
        .filter(|&i| is_corner(coords, i))
        .map(|i| corner_quality(&corner_jacobian(coords, i)))
        .fold(f64::INFINITY, f64::min))
}

/// The Jacobian of the bilinear map at corner `i` of a polygon, up to the factor `1/2` (which
/// the scaled Jacobian does not see): the edges to the next and from the previous node,
/// `[x_{i+1} - x_i, x_{i-1} - x_i]` as columns.
fn corner_jacobian(coords: &[[f64; 2]], i: usize) -> Matrix2<f64> {
    let n = coords.len();
    let (p, c, q) = (coords[(i + n - 1) % n], coords[i], coords[(i + 1) % n]);
    Matrix2::new(q[0] - c[0], p[0] - c[0], q[1] - c[1], p[1] - c[1])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::Analysis;

    #[test]
    fn rectangle_and_ring_volumes() {
        let rect = [[1.0, 0.0], [3.0, 0.0], [3.0, 0.5], [1.0, 0.5]];
        let plane = Material::new(1.0, 0.3, 0.2, Analysis::PlaneStress).unwrap();
        let v = volume(Formulation::Q4, &rect, &plane).unwrap();
        assert!((v - 2.0 * 0.5 * 0.2).abs() < 1e-15);
        // ring r in [1, 3], height 0.5: pi (9 - 1) 0.5
        let axi = Material::new(1.0, 0.3, 1.0, Analysis::Axisymmetric).unwrap();
        let v = volume(Formulation::Hybrid, &rect, &axi).unwrap();
        let exact = std::f64::consts::PI * 8.0 * 0.5;
        assert!((v - exact).abs() < 1e-14 * exact, "{v} vs {exact}");
        assert_eq!(scaled_jacobian(Formulation::Q4, &rect).unwrap(), 1.0);
    }

    /// The scaled Jacobian of a plane element is the sine of its sharpest corner, and every
    /// corner's value is the turn sine the shape check measures.
    #[test]
    fn scaled_jacobian_is_the_corner_sine() {
        let (c, s) = (0.5, 0.75f64.sqrt());
        let rhombus = [[0.0, 0.0], [1.0, 0.0], [1.0 + c, s], [c, s]];
        let q = scaled_jacobian(Formulation::Hybrid, &rhombus).unwrap();
        assert!((q - s).abs() < 1e-15, "{q} vs sin 60 = {s}");
        let kite = [[0.0, 0.0], [2.0, -0.3], [2.5, 1.0], [0.4, 1.7]];
        for i in 0..4 {
            let sine = crate::element::geometry::turn_sine(&kite, i);
            assert_eq!(
                corner_quality(&corner_jacobian(&kite, i)),
                sine,
                "corner {i}"
            );
        }
    }
}
