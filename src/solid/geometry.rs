//! Brick geometry: the trilinear map of the 8-node hexahedron, its node and face numbering, the
//! shape check with its policy and measures, and the 2x2x2 Gauss rule.
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

use crate::error::{ShapeError, ShapeWarning};
use crate::fem::boundary::FacePoint;
use crate::fem::quadrature::{GAUSS2, quad_weights};
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

/// The largest warp of a face (see [`ShapeReport::warp_degrees`] for the measure) that the strict
/// policy accepts, in degrees; beyond it the default policy warns. A trilinear brick stays valid
/// with warped faces as long as its Jacobian is positive at the integration points (the
/// MacNeal-Harder twisted beam warps every face by a few degrees, their 3D patch test one face
/// by 48 degrees).
pub const WARP_LIMIT_DEGREES: f64 = 45.0;

/// How strictly [`check_brick`] judges a distorted brick. Both policies reject what cannot be
/// computed or is not a solid: a node count other than 8, a non-finite coordinate, coincident
/// nodes, a volume that is not positive, a Jacobian that is not positive at an integration point.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum ShapePolicy {
    /// The default: errors only where the element cannot be computed (above); a Jacobian that is
    /// not positive at a corner, or a face warped beyond [`WARP_LIMIT_DEGREES`], is a warning
    /// ([`ShapeReport::warnings`]). The rule of codes that check at the integration points: the
    /// bricks only ever evaluate the Jacobian there (2x2x2 Gauss).
    #[default]
    IntegrationPoints,
    /// hycon 0.8's check: a Jacobian that is not positive at a corner
    /// ([`ShapeError::InvertedCorner`]) and a face warped beyond [`WARP_LIMIT_DEGREES`]
    /// ([`ShapeError::WarpedFace`]) are errors too, with 0.8's messages.
    Strict,
}

/// The measures of a brick's shape that the policies judge. Jacobians are relative to `h^3`,
/// `h` the longest edge, so the report is unchanged by a change of units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShapeReport {
    /// The smallest `det J / h^3` over the 8 points of the 2x2x2 Gauss rule (both bricks
    /// integrate with it); always above `1e-10` in an accepted brick.
    pub integration_jacobian: f64,
    /// The smallest `det J / h^3` over the 8 corners.
    pub corner_jacobian: f64,
    /// The local node (0-7) where [`corner_jacobian`](Self::corner_jacobian) is reached.
    pub corner: usize,
    /// The largest warp over the 6 faces, in degrees. The warp of a face is the angle between
    /// the normals of its two triangle halves, for each of the two ways of splitting it along a
    /// diagonal; the larger of the two (0 for a plane face, 180 for a face folded flat onto
    /// itself).
    pub warp_degrees: f64,
    /// The local face (0-5, numbering of the module docs) where
    /// [`warp_degrees`](Self::warp_degrees) is reached.
    pub face: usize,
}

impl ShapeReport {
    /// The corner warning: the Jacobian is not positive (`det J <= 1e-10 h^3`) at
    /// [`corner`](Self::corner).
    pub fn corner_warning(&self) -> Option<ShapeWarning> {
        (self.corner_jacobian <= DEGENERATE).then_some(ShapeWarning::CornerJacobian {
            node: self.corner,
            relative: self.corner_jacobian,
        })
    }

    /// The warp warning: [`face`](Self::face) is warped beyond [`WARP_LIMIT_DEGREES`].
    pub fn warp_warning(&self) -> Option<ShapeWarning> {
        (self.warp_degrees > WARP_LIMIT_DEGREES).then_some(ShapeWarning::WarpedFace {
            face: self.face,
            degrees: self.warp_degrees,
        })
    }

    /// The warnings of the default policy (what the strict policy rejects): the corner
    /// warning, then the warp warning, each at most once.
    pub fn warnings(&self) -> impl Iterator<Item = ShapeWarning> {
        self.corner_warning().into_iter().chain(self.warp_warning())
    }
}

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

/// The warp of face `face` (see [`ShapeReport::warp_degrees`]).
fn face_warp(map: &Trilinear, face: usize) -> f64 {
    let [a, b, c, d] = FACES[face].map(|k| map.x[k]);
    fold_angle(a, b, c, d).max(fold_angle(b, c, d, a))
}

/// `det J / h^3` at local node `node`.
fn corner_jacobian(map: &Trilinear, node: usize, h3: f64) -> f64 {
    map.jacobian(NODE_XI[node]).determinant() / h3
}

/// The local node nearest Gauss point `point` of [`gauss_points`] (`x` fastest).
fn nearest_corner(point: usize) -> usize {
    [0, 1, 3, 2][point & 3] + 4 * (point >> 2)
}

/// Check an 8-node brick (see the module docs for the node order) under `policy` and measure
/// it. Both policies: finite coordinates, no coincident nodes, positive volume, `det J > 0` at
/// the 8 integration points; [`ShapePolicy::Strict`] also `det J > 0` at every corner and no
/// face warped beyond [`WARP_LIMIT_DEGREES`] (checked before the integration points, in 0.8's
/// order). "Positive" means above `1e-10` of `h^3`, `h` the longest edge (coincident: closer
/// than `1e-10 h`).
///
/// Errors: [`ShapeError::NodeCount`], [`ShapeError::NonFinite`], [`ShapeError::Degenerate`]
/// (coincident nodes, zero volume), [`ShapeError::Inverted`] (negative volume: the bottom and
/// top faces swapped or mirrored), [`ShapeError::InvertedIntegrationPoint`]; strict also
/// [`ShapeError::InvertedCorner`], [`ShapeError::WarpedFace`]. On success the report holds the
/// measures; under the default policy its [`warnings`](ShapeReport::warnings) are what the
/// strict policy would have rejected.
pub fn check_brick(
    coords: &[[f64; 3]],
    policy: ShapePolicy,
) -> Result<(Trilinear, ShapeReport), ShapeError> {
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
    let h3 = h * h * h;
    let mut gauss = [0.0; 8];
    for (g, (xi, _)) in gauss.iter_mut().zip(gauss_points()) {
        *g = map.jacobian(xi).determinant() / h3;
    }
    // every Gauss weight is 1: the volume over h^3 is the sum
    let volume: f64 = gauss.iter().sum();
    if volume.abs() <= 8.0 * DEGENERATE {
        return Err(ShapeError::Degenerate);
    }
    if volume < 0.0 {
        return Err(ShapeError::Inverted);
    }
    if policy == ShapePolicy::Strict {
        // 0.8's errors: the first corner, the first face beyond the limits
        if let Some(node) = (0..8).find(|&n| corner_jacobian(&map, n, h3) <= DEGENERATE) {
            return Err(ShapeError::InvertedCorner { node });
        }
        if let Some(face) = (0..6).find(|&f| face_warp(&map, f) > WARP_LIMIT_DEGREES) {
            return Err(ShapeError::WarpedFace { face });
        }
    }
    if let Some(point) = gauss.iter().position(|&g| g <= DEGENERATE) {
        return Err(ShapeError::InvertedIntegrationPoint {
            node: nearest_corner(point),
        });
    }
    let report = measure(&map, &gauss, h3);
    Ok((map, report))
}

/// The [`ShapeReport`] of a brick with relative Gauss-point Jacobians `gauss`.
fn measure(map: &Trilinear, gauss: &[f64; 8], h3: f64) -> ShapeReport {
    let mut report = ShapeReport {
        integration_jacobian: gauss.iter().copied().fold(f64::INFINITY, f64::min),
        corner_jacobian: f64::INFINITY,
        corner: 0,
        warp_degrees: 0.0,
        face: 0,
    };
    for node in 0..8 {
        let det = corner_jacobian(map, node, h3);
        if det < report.corner_jacobian {
            (report.corner_jacobian, report.corner) = (det, node);
        }
    }
    for face in 0..6 {
        let w = face_warp(map, face);
        if w > report.warp_degrees {
            (report.warp_degrees, report.face) = (w, face);
        }
    }
    report
}

/// Natural coordinates of the point `(s, t)` of face `face` (see the module docs).
pub fn face_natural(face: usize, s: f64, t: f64) -> [f64; 3] {
    let w = quad_weights(s, t);
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
    FacePoint::new(FACES[face].map(|k| map.x[k]), s, t).normal
}
