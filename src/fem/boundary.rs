//! Distributed loads on a boundary edge (plane, axisymmetric) or face (3D), and the geometry of a
//! bilinear face.
//!
//! A load is a pressure `p` (force per area, **positive pushing into the body**) and a traction
//! vector `t` (force per area), each given at the `N` nodes of the edge or face and interpolated
//! as the element's displacement is there. With `n` the outward unit normal the surface force is
//! `q = t - p n`, and the consistent nodal forces are `f_a = integral of N_a q dS`
//! (docs/elements.md, "Loads and element checks"); [`crate::element::loads`] and
//! [`crate::solid::loads`] integrate it on an edge and on a face.

use super::quadrature::quad_weights;
use crate::error::{Error, Result};

/// A distributed load on a boundary piece with `N` nodes in `D` dimensions: the values at its
/// nodes (in the piece's node order), interpolated between them. The surface force is `t - p n`
/// (`n` the outward unit normal).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundaryLoad<const D: usize, const N: usize> {
    /// Pressure at the nodes (force per area, positive pushing into the body).
    pub pressure: [f64; N],
    /// Traction vector at the nodes (force per area; in axisymmetry `[t_r, t_z]`).
    pub traction: [[f64; D]; N],
}

impl<const D: usize, const N: usize> Default for BoundaryLoad<D, N> {
    /// No load.
    fn default() -> Self {
        BoundaryLoad {
            pressure: [0.0; N],
            traction: [[0.0; D]; N],
        }
    }
}

impl<const D: usize, const N: usize> BoundaryLoad<D, N> {
    /// A uniform pressure `p` (positive pushing into the body).
    pub fn pressure(p: f64) -> Self {
        BoundaryLoad {
            pressure: [p; N],
            ..Default::default()
        }
    }

    /// A uniform traction vector `t`.
    pub fn traction(t: [f64; D]) -> Self {
        BoundaryLoad {
            traction: [t; N],
            ..Default::default()
        }
    }

    /// Check that every value is finite.
    pub fn validate(&self) -> Result<()> {
        let mut values = self.pressure.iter().chain(self.traction.iter().flatten());
        if values.all(|v| v.is_finite()) {
            Ok(())
        } else {
            let piece = if D == 2 { "edge" } else { "face" };
            Err(Error::InvalidInput(format!(
                "{piece} load {self:?} is not finite"
            )))
        }
    }

    /// The surface force `t_k - p_k n` at node `k` for the outward unit normal `n`.
    #[inline]
    pub fn surface_force(&self, k: usize, n: [f64; D]) -> [f64; D] {
        let (t, p) = (self.traction[k], self.pressure[k]);
        std::array::from_fn(|i| t[i] - p * n[i])
    }
}

/// A point of a bilinear face `x(s, t) = sum_k M_k(s, t) x_k`, `(s, t)` in `[-1, 1]^2`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FacePoint {
    /// The physical point.
    pub x: [f64; 3],
    /// The unit normal `dx/ds x dx/dt / |dx/ds x dx/dt|` (outward when the corners are
    /// counter-clockwise seen from outside).
    pub normal: [f64; 3],
    /// The area density `|dx/ds x dx/dt|` (`dA = area ds dt`).
    pub area: f64,
    /// The bilinear weights `M_k(s, t)` of the face's 4 nodes.
    pub weights: [f64; 4],
}

impl FacePoint {
    /// The point `(s, t)` of the bilinear face with corners `[a, b, c, d]` (`a` at `(-1, -1)`,
    /// `b` at `(1, -1)`, `c` at `(1, 1)`, `d` at `(-1, 1)`).
    pub fn new([a, b, c, d]: [[f64; 3]; 4], s: f64, t: f64) -> Self {
        let weights = quad_weights(s, t);
        let (mut x, mut ds, mut dt) = ([0.0; 3], [0.0; 3], [0.0; 3]);
        for i in 0..3 {
            x[i] = weights[0] * a[i] + weights[1] * b[i] + weights[2] * c[i] + weights[3] * d[i];
            ds[i] = 0.25 * ((b[i] - a[i]) * (1.0 - t) + (c[i] - d[i]) * (1.0 + t));
            dt[i] = 0.25 * ((d[i] - a[i]) * (1.0 - s) + (c[i] - b[i]) * (1.0 + s));
        }
        let cross = [
            ds[1] * dt[2] - ds[2] * dt[1],
            ds[2] * dt[0] - ds[0] * dt[2],
            ds[0] * dt[1] - ds[1] * dt[0],
        ];
        let area = (cross[0].powi(2) + cross[1].powi(2) + cross[2].powi(2)).sqrt();
        FacePoint {
            x,
            normal: cross.map(|v| v / area),
            area,
            weights,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn loads_and_face_points() {
        let load = BoundaryLoad::<3, 4>::pressure(2.0);
        assert_eq!(load.surface_force(3, [0.0, 0.0, 1.0]), [0.0, 0.0, -2.0]);
        let bad = BoundaryLoad::<2, 2>::traction([f64::NAN, 0.0]);
        let msg = bad.validate().unwrap_err().to_string();
        assert!(
            msg.contains("edge load") && msg.contains("not finite"),
            "{msg}"
        );
        // the square [0, 2]^2 at z = 1, counter-clockwise seen from +z
        let square = [
            [0.0, 0.0, 1.0],
            [2.0, 0.0, 1.0],
            [2.0, 2.0, 1.0],
            [0.0, 2.0, 1.0],
        ];
        let p = FacePoint::new(square, 0.5, -0.5);
        assert_eq!(p.x, [1.5, 0.5, 1.0]);
        assert_eq!(p.normal, [0.0, 0.0, 1.0]);
        assert_eq!(p.area, 1.0);
    }
}
