//! Brick geometry: the trilinear map of the 8-node hexahedron, its node and face numbering, the
//! shape check, and the 2x2x2 Gauss rule.
//!
//! # Numbering
//! Natural coordinates `xi = (xi, eta, zeta)` in `[-1, 1]^3`. Nodes 0-3 are the face
//! `zeta = -1`, counter-clockwise seen from nodes 4-7; node `4 + i` lies above node `i`:
//!
//! ```text
//!        7-----------6          node  xi  eta zeta
//!       /|          /|           0    -1  -1  -1
//!      4-----------5 |           1    +1  -1  -1
//!      | |         | |           2    +1  +1  -1
//!      | 3---------|-2           3    -1  +1  -1
//!      |/          |/            4..7  as 0..3 with zeta = +1
//!      0-----------1       zeta
//!                          | eta
//!                          |/__ xi
//! ```
//!
//! Faces (each listed counter-clockwise seen from outside, so the right-hand rule gives the
//! outward normal; face parameters `(s, t)` in `[-1, 1]^2` run from its first node to its second
//! (`s`) and from its first to its fourth (`t`)):
//!
//! | face | plane | nodes |
//! |---|---|---|
//! | 0 | `xi = -1` | 0 4 7 3 |
//! | 1 | `xi = +1` | 1 2 6 5 |
//! | 2 | `eta = -1` | 0 1 5 4 |
//! | 3 | `eta = +1` | 3 7 6 2 |
//! | 4 | `zeta = -1` | 0 3 2 1 |
//! | 5 | `zeta = +1` | 4 5 6 7 |

use crate::error::ShapeError;
use nalgebra::{Matrix3, Vector3};

/// Natural coordinates of the 8 nodes.
pub const NODE_XI: [[f64; 3]; 8] = [
    [-1.0, -1.0, -1.0],
    [1.0, -1.0, -1.0],
    [1.0, 1.0, -1.0],
    [-1.0, 1.0, -1.0],
    [-1.0, -1.0, 1.0],
    [1.0, -1.0, 1.0],
    [1.0, 1.0, 1.0],
    [-1.0, 1.0, 1.0],
];

/// Local nodes of the 6 faces, counter-clockwise seen from outside (see the module docs).
pub const FACES: [[usize; 4]; 6] = [
    [0, 4, 7, 3],
    [1, 2, 6, 5],
    [0, 1, 5, 4],
    [3, 7, 6, 2],
    [0, 3, 2, 1],
    [4, 5, 6, 7],
];

/// Two-point Gauss rule on `[-1, 1]`: `(abscissa, weight)`.
pub const GAUSS2: [(f64, f64); 2] = [
    (-0.577_350_269_189_625_8, 1.0),
    (0.577_350_269_189_625_8, 1.0),
];

/// The 8 points `(xi, weight)` of the 2x2x2 Gauss rule (exact for degree 3 in each variable),
/// `x` fastest. An array rather than nested `flat_map`s: the optimised flatten adapter branches
/// on its uninitialised inner state, which valgrind reports in every kernel (the C examples run
/// under valgrind).
pub fn gauss_points() -> impl Iterator<Item = ([f64; 3], f64)> {
    let mut points = [([0.0; 3], 0.0); 8];
    for (i, point) in points.iter_mut().enumerate() {
        let ((x, wx), (y, wy), (z, wz)) = (GAUSS2[i & 1], GAUSS2[(i >> 1) & 1], GAUSS2[i >> 2]);
        *point = ([x, y, z], wx * wy * wz);
    }
    points.into_iter()
}

/// Relative size below which an edge, a volume or a Jacobian counts as zero.
const DEGENERATE: f64 = 1e-10;

/// The largest angle between the normals of a face's two triangle halves (split along either
/// diagonal) that [`check_brick`] accepts, in degrees. A trilinear brick stays valid with warped
/// faces as long as its Jacobian is positive (the MacNeal-Harder twisted beam warps every face by
/// a few degrees); beyond this a face folds on itself and the element is a mesh error.
pub const WARP_LIMIT_DEGREES: f64 = 45.0;

/// The trilinear map `x(xi) = sum N_k(xi) x_k` of an 8-node brick.
#[derive(Debug, Clone, Copy)]
pub struct Trilinear {
    /// Node coordinates.
    pub x: [[f64; 3]; 8],
}

/// Shape functions `N_k = (1 + xi xi_k)(1 + eta eta_k)(1 + zeta zeta_k) / 8`.
pub fn shape(xi: [f64; 3]) -> [f64; 8] {
    let mut n = [0.0; 8];
    for (k, c) in NODE_XI.iter().enumerate() {
        n[k] = 0.125 * (1.0 + xi[0] * c[0]) * (1.0 + xi[1] * c[1]) * (1.0 + xi[2] * c[2]);
    }
    n
}

/// Natural derivatives `dN_k / dxi_a` (`[k][a]`).
pub fn shape_derivatives(xi: [f64; 3]) -> [[f64; 3]; 8] {
    let mut d = [[0.0; 3]; 8];
    for (k, c) in NODE_XI.iter().enumerate() {
        let f = [1.0 + xi[0] * c[0], 1.0 + xi[1] * c[1], 1.0 + xi[2] * c[2]];
        d[k] = [
            0.125 * c[0] * f[1] * f[2],
            0.125 * c[1] * f[0] * f[2],
            0.125 * c[2] * f[0] * f[1],
        ];
    }
    d
}

impl Trilinear {
    /// The map of the brick with node coordinates `x` (exactly 8 nodes).
    pub fn new(x: &[[f64; 3]]) -> Self {
        let mut nodes = [[0.0; 3]; 8];
        nodes.copy_from_slice(&x[..8]);
        Trilinear { x: nodes }
    }

    /// Physical point `x(xi)`.
    pub fn point(&self, xi: [f64; 3]) -> [f64; 3] {
        let n = shape(xi);
        let mut p = [0.0; 3];
        for (nk, xk) in n.iter().zip(&self.x) {
            for i in 0..3 {
                p[i] += nk * xk[i];
            }
        }
        p
    }

    /// Jacobian `J_ia = dx_i / dxi_a`.
    pub fn jacobian(&self, xi: [f64; 3]) -> Matrix3<f64> {
        let d = shape_derivatives(xi);
        let mut j = Matrix3::zeros();
        for (dk, xk) in d.iter().zip(&self.x) {
            for i in 0..3 {
                for a in 0..3 {
                    j[(i, a)] += xk[i] * dk[a];
                }
            }
        }
        j
    }

    /// Physical gradients `dN_k / dx` (`[k][i]`, from `grad_xi N = J^T grad_x N`) and `det J`
    /// at `xi`. `det J` must be positive (checked shapes).
    pub fn gradients(&self, xi: [f64; 3]) -> ([[f64; 3]; 8], f64) {
        let j = self.jacobian(xi);
        let det = j.determinant();
        let jt_inv = j.transpose().try_inverse().unwrap_or_else(Matrix3::zeros);
        let d = shape_derivatives(xi);
        let mut g = [[0.0; 3]; 8];
        for (gk, dk) in g.iter_mut().zip(&d) {
            let v = jt_inv * Vector3::from(*dk);
            *gk = [v[0], v[1], v[2]];
        }
        (g, det)
    }

    /// Natural coordinates of the physical point `p` (Newton's method from the centre; exact
    /// in one step for parallelepipeds). Points outside the brick give natural coordinates
    /// outside `[-1, 1]^3` (an extrapolation); a point the map cannot reach gives non-finite
    /// values.
    pub fn inverse(&self, p: [f64; 3]) -> [f64; 3] {
        let mut xi = Vector3::zeros();
        let size = self.size();
        for _ in 0..50 {
            let x = self.point([xi[0], xi[1], xi[2]]);
            let r = Vector3::new(p[0] - x[0], p[1] - x[1], p[2] - x[2]);
            let Some(inv) = self.jacobian([xi[0], xi[1], xi[2]]).try_inverse() else {
                return [f64::NAN; 3];
            };
            let step = inv * r;
            xi += step;
            if r.norm() <= 1e-15 * size || step.norm() <= 1e-15 {
                break;
            }
        }
        [xi[0], xi[1], xi[2]]
    }

    /// The longest edge (a length scale for tolerances).
    pub fn size(&self) -> f64 {
        EDGES
            .iter()
            .map(|&(a, b)| distance(self.x[a], self.x[b]))
            .fold(0.0, f64::max)
    }

    /// Volume `integral of det J` (2x2x2 Gauss: exact for the trilinear map).
    pub fn volume(&self) -> f64 {
        gauss_points()
            .map(|(xi, w)| w * self.jacobian(xi).determinant())
            .sum()
    }
}

/// The 12 edges of the brick as local node pairs.
pub const EDGES: [(usize, usize); 12] = [
    (0, 1),
    (1, 2),
    (2, 3),
    (3, 0),
    (4, 5),
    (5, 6),
    (6, 7),
    (7, 4),
    (0, 4),
    (1, 5),
    (2, 6),
    (3, 7),
];

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

fn sub(a: [f64; 3], b: [f64; 3]) -> Vector3<f64> {
    Vector3::new(a[0] - b[0], a[1] - b[1], a[2] - b[2])
}

/// Angle in degrees between the normals of triangles `(a, b, c)` and `(a, c, d)`.
fn fold_angle(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> f64 {
    let n1 = sub(b, a).cross(&sub(c, a));
    let n2 = sub(c, a).cross(&sub(d, a));
    let cos = n1.dot(&n2) / (n1.norm() * n2.norm());
    cos.clamp(-1.0, 1.0).acos().to_degrees()
}

/// Check an 8-node brick (see the module docs for the node order): finite coordinates, no
/// coincident nodes, positive volume, `det J > 0` at every corner (which with the positive
/// volume rules out re-entrant, collapsed and twisted shapes), no face warped beyond
/// [`WARP_LIMIT_DEGREES`]. Tolerances are relative to the longest edge `h` (`det J` against
/// `h^3`).
///
/// Errors: [`ShapeError::NodeCount`], [`ShapeError::NonFinite`], [`ShapeError::Degenerate`]
/// (coincident nodes, zero volume), [`ShapeError::Inverted`] (negative volume: the bottom and
/// top faces swapped or mirrored), [`ShapeError::InvertedCorner`],
/// [`ShapeError::WarpedFace`].
pub fn check_brick(coords: &[[f64; 3]]) -> Result<Trilinear, ShapeError> {
    if coords.len() != 8 {
        return Err(ShapeError::NodeCount {
            got: coords.len(),
            expected: "8",
        });
    }
    if coords.iter().flatten().any(|v| !v.is_finite()) {
        return Err(ShapeError::NonFinite);
    }
    let map = Trilinear::new(coords);
    let h = map.size();
    if h == 0.0 || !h.is_finite() {
        return Err(ShapeError::Degenerate);
    }
    for a in 0..8 {
        for b in a + 1..8 {
            if distance(coords[a], coords[b]) <= DEGENERATE * h {
                return Err(ShapeError::Degenerate);
            }
        }
    }
    let volume = map.volume();
    let tiny = DEGENERATE * h * h * h;
    if volume.abs() <= 8.0 * tiny {
        return Err(ShapeError::Degenerate);
    }
    if volume < 0.0 {
        return Err(ShapeError::Inverted);
    }
    for (node, xi) in NODE_XI.iter().enumerate() {
        if map.jacobian(*xi).determinant() <= tiny {
            return Err(ShapeError::InvertedCorner { node });
        }
    }
    for (face, f) in FACES.iter().enumerate() {
        let [a, b, c, d] = f.map(|k| coords[k]);
        let warp = fold_angle(a, b, c, d).max(fold_angle(b, c, d, a));
        if warp > WARP_LIMIT_DEGREES {
            return Err(ShapeError::WarpedFace { face });
        }
    }
    Ok(map)
}

/// Natural coordinates of the point `(s, t)` of face `face` (see the module docs).
pub fn face_natural(face: usize, s: f64, t: f64) -> [f64; 3] {
    let w = [
        0.25 * (1.0 - s) * (1.0 - t),
        0.25 * (1.0 + s) * (1.0 - t),
        0.25 * (1.0 + s) * (1.0 + t),
        0.25 * (1.0 - s) * (1.0 + t),
    ];
    let mut xi = [0.0; 3];
    for (wk, &k) in w.iter().zip(&FACES[face]) {
        for a in 0..3 {
            xi[a] += wk * NODE_XI[k][a];
        }
    }
    xi
}

/// Outward unit normal of face `face` at `(s, t)`: `dx/ds x dx/dt`, normalised.
pub fn face_normal(map: &Trilinear, face: usize, s: f64, t: f64) -> [f64; 3] {
    let [a, b, c, d] = FACES[face].map(|k| map.x[k]);
    let ds = (sub(b, a) * (1.0 - t) + sub(c, d) * (1.0 + t)) * 0.25;
    let dt = (sub(d, a) * (1.0 - s) + sub(c, b) * (1.0 + s)) * 0.25;
    let n = ds.cross(&dt).normalize();
    [n[0], n[1], n[2]]
}
