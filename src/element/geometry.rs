//! Element geometry: the shape check, the centred and scaled local frame of the hybrid element,
//! the bilinear map of the 4-node quads. The quadrature rules the kernels share live in
//! [`crate::fem::quadrature`] and are re-exported here.
//!
//! Every tolerance here is relative to the element's own size, so a shape that passes in
//! millimetres passes in metres.

use crate::error::ShapeError;
use nalgebra::{Matrix2, Vector2};

pub use crate::fem::quadrature::{DUNAVANT4, GAUSS2, GAUSS2_UNIT, GAUSS3, STRANG_FIX2};

/// Sine of the angle between consecutive boundary edges below which a node counts as lying on a
/// straight edge (a mid-side node). Generated meshes put mid-side nodes at midpoints, where the
/// sine is round-off; hosts may pass coordinates printed to a few digits.
const STRAIGHT_SINE: f64 = 1e-6;

/// Relative size below which an edge or the area counts as zero.
const DEGENERATE: f64 = 1e-10;

/// What [`check_polygon`] learned about a valid element.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PolygonInfo {
    /// Area (positive: the nodes are counter-clockwise).
    pub area: f64,
    /// Area centroid.
    pub centroid: [f64; 2],
    /// Number of true corners (nodes that do not lie on a straight edge).
    pub corners: usize,
}

/// The most true corners an element has: 4 (a quadrilateral; 5- and 6-node transition
/// elements add mid-side nodes on straight edges).
pub const MAX_CORNERS: usize = 4;

/// Check that `coords` is a usable element polygon: finite coordinates, no coincident
/// consecutive nodes, positive (counter-clockwise) area, convex, every non-corner node lying
/// between its neighbours on a straight edge, and from `min_corners` to [`MAX_CORNERS`] true
/// corners.
///
/// A node is a corner when the sine of the turn between its two edges exceeds `1e-6`; a negative
/// turn beyond that is a reflex corner (non-convex); a turn of about 180 degrees that folds back
/// is degenerate.
pub fn check_polygon(coords: &[[f64; 2]], min_corners: usize) -> Result<PolygonInfo, ShapeError> {
    if coords.iter().flatten().any(|v| !v.is_finite()) {
        return Err(ShapeError::NonFinite);
    }
    let n = coords.len();
    let edge = |i: usize| -> Vector2<f64> {
        let (a, b) = (coords[i], coords[(i + 1) % n]);
        Vector2::new(b[0] - a[0], b[1] - a[1])
    };
    let size = (0..n).map(|i| edge(i).norm()).fold(0.0, f64::max);
    if size == 0.0 || (0..n).any(|i| edge(i).norm() <= DEGENERATE * size) {
        return Err(ShapeError::Degenerate);
    }
    let (area, centroid) = area_centroid(coords);
    if area.abs() <= DEGENERATE * size * size {
        return Err(ShapeError::Degenerate);
    }
    if area < 0.0 {
        return Err(ShapeError::Inverted);
    }
    let mut corners = 0;
    for i in 0..n {
        let (a, b) = (edge((i + n - 1) % n), edge(i));
        let sine = turn_sine(coords, i);
        if sine > STRAIGHT_SINE {
            corners += 1;
        } else if sine < -STRAIGHT_SINE {
            return Err(ShapeError::NonConvex { node: i });
        } else if a.dot(&b) <= 0.0 {
            return Err(ShapeError::Degenerate);
        }
    }
    if corners < min_corners {
        return Err(ShapeError::Degenerate);
    }
    if corners > MAX_CORNERS {
        return Err(ShapeError::Corners { corners });
    }
    Ok(PolygonInfo {
        area,
        centroid,
        corners,
    })
}

/// Sine of the turn of a polygon's boundary at node `i`, `(e_in x e_out) / (|e_in| |e_out|)`
/// with `e_in`, `e_out` the edges into and out of the node: the sine of the interior angle,
/// positive at a convex corner of a counter-clockwise polygon.
pub fn turn_sine(coords: &[[f64; 2]], i: usize) -> f64 {
    let n = coords.len();
    let (p, c, q) = (coords[(i + n - 1) % n], coords[i], coords[(i + 1) % n]);
    let a = Vector2::new(c[0] - p[0], c[1] - p[1]);
    let b = Vector2::new(q[0] - c[0], q[1] - c[1]);
    a.perp(&b) / (a.norm() * b.norm())
}

/// Whether node `i` of a checked polygon is a true corner (not a node on a straight edge), by
/// the rule of [`check_polygon`].
pub fn is_corner(coords: &[[f64; 2]], i: usize) -> bool {
    turn_sine(coords, i) > STRAIGHT_SINE
}

/// Check natural coordinates of a reference element (`[-1, 1]` in each direction; the plane
/// quads and the brick): finite and inside, the ends included.
pub fn check_natural(xi: &[f64]) -> crate::error::Result<()> {
    match xi.iter().find(|v| !(-1.0..=1.0).contains(*v)) {
        None => Ok(()),
        Some(v) => Err(crate::error::Error::InvalidInput(format!(
            "natural coordinates {xi:?}: {v} is {} [-1, 1]",
            if v.is_finite() {
                "outside"
            } else {
                "not finite, not in"
            }
        ))),
    }
}

/// Signed area and area centroid of a polygon (shoelace formula, taken about the first node to
/// keep round-off relative to the element size).
pub fn area_centroid(coords: &[[f64; 2]]) -> (f64, [f64; 2]) {
    let o = coords[0];
    let (mut a2, mut cx, mut cy) = (0.0, 0.0, 0.0);
    for i in 1..coords.len().saturating_sub(1) {
        let (p, q) = (coords[i], coords[i + 1]);
        let (px, py, qx, qy) = (p[0] - o[0], p[1] - o[1], q[0] - o[0], q[1] - o[1]);
        let cross = px * qy - qx * py;
        a2 += cross;
        cx += cross * (px + qx);
        cy += cross * (py + qy);
    }
    let area = 0.5 * a2;
    let centroid = if a2 != 0.0 {
        [o[0] + cx / (3.0 * a2), o[1] + cy / (3.0 * a2)]
    } else {
        o
    };
    (area, centroid)
}

/// Centred, scaled local coordinates of the hybrid element: `xh = (x - xc) / s`,
/// `yh = (y - yc) / s`, with `(xc, yc)` the area centroid and `s = sqrt(area)`, so that the
/// stress basis and `H` are well conditioned for any element size or position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// Area centroid.
    pub centre: [f64; 2],
    /// Length scale `sqrt(area)`.
    pub scale: f64,
}

impl Frame {
    /// The frame of a checked polygon.
    pub fn new(info: &PolygonInfo) -> Self {
        Frame {
            centre: info.centroid,
            scale: info.area.sqrt(),
        }
    }

    /// Local coordinates `(xh, yh)` of a physical point.
    #[inline]
    pub fn local(&self, p: [f64; 2]) -> [f64; 2] {
        [
            (p[0] - self.centre[0]) / self.scale,
            (p[1] - self.centre[1]) / self.scale,
        ]
    }
}

/// Outward unit normal and length of the segment from `a` to `b` of a boundary that has its
/// body on the left (an edge of a counter-clockwise element, a segment of a contact polyline):
/// `n = (d_y, -d_x) / |d|`, `d = b - a`, the segment's direction rotated clockwise.
///
/// The one home of this convention: the element kernels, the contact kernels, the facing check,
/// the iteration's pointwise B-node check and the results all call it (a nodal normal of a
/// polyline is the normal of the chord of its neighbours, `sum_e h_e n_e` telescoped).
#[inline]
pub fn edge_normal(a: [f64; 2], b: [f64; 2]) -> ([f64; 2], f64) {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len = dx.hypot(dy);
    ([dy / len, -dx / len], len)
}

/// Natural coordinates `(xi_i, eta_i)` of the four corners of the bilinear quad.
pub const QUAD_CORNERS: [[f64; 2]; 4] = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];

/// The bilinear map `x(xi, eta) = sum N_i(xi, eta) x_i`, `N_i = (1 + xi xi_i)(1 + eta eta_i) / 4`,
/// of a 4-node quad.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bilinear {
    /// Corner coordinates, counter-clockwise.
    pub nodes: [[f64; 2]; 4],
}

impl Bilinear {
    /// The map of the first four entries of `coords`.
    pub fn new(coords: &[[f64; 2]]) -> Self {
        Bilinear {
            nodes: [coords[0], coords[1], coords[2], coords[3]],
        }
    }

    /// Shape functions `N_i` and their derivatives `dN_i/dxi`, `dN_i/deta` at `(xi, eta)`.
    pub fn shape(xi: f64, eta: f64) -> ([f64; 4], [[f64; 2]; 4]) {
        let mut n = [0.0; 4];
        let mut dn = [[0.0; 2]; 4];
        for (i, c) in QUAD_CORNERS.iter().enumerate() {
            n[i] = 0.25 * (1.0 + xi * c[0]) * (1.0 + eta * c[1]);
            dn[i] = [
                0.25 * c[0] * (1.0 + eta * c[1]),
                0.25 * c[1] * (1.0 + xi * c[0]),
            ];
        }
        (n, dn)
    }

    /// Physical point of `(xi, eta)`.
    pub fn point(&self, xi: f64, eta: f64) -> [f64; 2] {
        let (n, _) = Self::shape(xi, eta);
        let mut p = [0.0; 2];
        for (ni, x) in n.iter().zip(&self.nodes) {
            p[0] += ni * x[0];
            p[1] += ni * x[1];
        }
        p
    }

    /// Jacobian `J = [[dx/dxi, dx/deta], [dy/dxi, dy/deta]]` at `(xi, eta)`.
    pub fn jacobian(&self, xi: f64, eta: f64) -> Matrix2<f64> {
        let (_, dn) = Self::shape(xi, eta);
        let mut j = Matrix2::zeros();
        for (d, x) in dn.iter().zip(&self.nodes) {
            for r in 0..2 {
                j[(r, 0)] += d[0] * x[r];
                j[(r, 1)] += d[1] * x[r];
            }
        }
        j
    }

    /// Shape-function gradients `[dN_i/dx, dN_i/dy]` and `det J` at `(xi, eta)`.
    pub fn gradients(&self, xi: f64, eta: f64) -> ([[f64; 2]; 4], f64) {
        let (_, dn) = Self::shape(xi, eta);
        let j = self.jacobian(xi, eta);
        let det = j.determinant();
        // [dN/dx, dN/dy] = [dN/dxi, dN/deta] J^-1, with J^-1 = adj(J) / det
        let mut g = [[0.0; 2]; 4];
        for (gi, d) in g.iter_mut().zip(&dn) {
            gi[0] = (d[0] * j[(1, 1)] - d[1] * j[(1, 0)]) / det;
            gi[1] = (-d[0] * j[(0, 1)] + d[1] * j[(0, 0)]) / det;
        }
        (g, det)
    }

    /// Natural coordinates of a physical point (Newton's method from the centre; the map of a
    /// convex quad is invertible, and Newton converges in a few steps).
    pub fn inverse(&self, p: [f64; 2]) -> [f64; 2] {
        let mut x = Vector2::new(0.0, 0.0);
        let size = self.jacobian(0.0, 0.0).norm();
        for _ in 0..50 {
            let q = self.point(x[0], x[1]);
            let r = Vector2::new(p[0] - q[0], p[1] - q[1]);
            let Some(inv) = self.jacobian(x[0], x[1]).try_inverse() else {
                break;
            };
            let step = inv * r;
            x += step;
            if r.norm() <= 1e-15 * size {
                break;
            }
        }
        [x[0], x[1]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dunavant_integrates_quartics_exactly() {
        // int l1^a l2^b l3^c dA = 2 A a! b! c! / (a + b + c + 2)!; the rules are normalised to
        // A = 1
        let fact = |n: u32| (1..=n).product::<u32>() as f64;
        for (a, b, c) in [(4, 0, 0), (2, 2, 0), (1, 1, 2), (3, 1, 0), (0, 0, 0)] {
            let exact = 2.0 * fact(a) * fact(b) * fact(c) / fact(a + b + c + 2);
            let quad: f64 = DUNAVANT4
                .iter()
                .map(|(l, w)| w * l[0].powi(a as i32) * l[1].powi(b as i32) * l[2].powi(c as i32))
                .sum();
            assert!(
                (quad - exact).abs() < 1e-14,
                "({a},{b},{c}): {quad} vs {exact}"
            );
            if a + b + c <= 2 {
                let quad2: f64 = STRANG_FIX2
                    .iter()
                    .map(|(l, w)| {
                        w * l[0].powi(a as i32) * l[1].powi(b as i32) * l[2].powi(c as i32)
                    })
                    .sum();
                assert!((quad2 - exact).abs() < 1e-15, "degree-2 rule ({a},{b},{c})");
            }
        }
    }

    #[test]
    fn shape_check_classifies() {
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let info = check_polygon(&square, 4).unwrap();
        assert!((info.area - 1.0).abs() < 1e-15 && info.corners == 4);
        assert!((info.centroid[0] - 0.5).abs() < 1e-15);
        let mut cw = square;
        cw.reverse();
        assert_eq!(check_polygon(&cw, 4), Err(ShapeError::Inverted));
        let dart = [[0.0, 0.0], [1.0, 0.0], [0.2, 0.2], [0.0, 1.0]];
        assert_eq!(
            check_polygon(&dart, 4),
            Err(ShapeError::NonConvex { node: 2 })
        );
        let flat = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0]];
        assert_eq!(check_polygon(&flat, 4), Err(ShapeError::Degenerate));
        let five = [[0.0, 0.0], [0.5, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert_eq!(check_polygon(&five, 4).unwrap().corners, 4);
        assert_eq!(check_polygon(&five[..4], 4), Err(ShapeError::Degenerate));
        let nan = [[0.0, f64::NAN], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert_eq!(check_polygon(&nan, 4), Err(ShapeError::NonFinite));
        let folded = [[0.0, 0.0], [1.0, 0.0], [0.5, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert!(check_polygon(&folded, 4).is_err());
    }

    #[test]
    fn bilinear_inverse_round_trips() {
        let q = Bilinear::new(&[[0.0, 0.0], [48.0, 44.0], [48.0, 60.0], [0.0, 44.0]]);
        for &(xi, eta) in &[(0.3, -0.7), (-1.0, 1.0), (0.99, 0.2), (0.0, 0.0)] {
            let p = q.point(xi, eta);
            let back = q.inverse(p);
            assert!((back[0] - xi).abs() < 1e-12 && (back[1] - eta).abs() < 1e-12);
        }
    }
}
