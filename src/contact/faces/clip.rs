//! The auxiliary plane of an A face, the projection of both faces onto it, and the clipping of
//! the two projected quadrilaterals (Sutherland-Hodgman on convex polygons) with tolerances
//! relative to the face size.

use super::{Quad, shape_derivatives, shapes};
use crate::error::{Error, Result};
use crate::solid::WARP_LIMIT_DEGREES;
use nalgebra::{Vector2, Vector3};

/// Relative size (of the longest edge `h`) below which two points coincide: clipped vertices
/// this close to a corner of either face are snapped to it, consecutive vertices this close are
/// merged, and a vertex this close to the line through its neighbours is dropped.
pub const SNAP: f64 = 1e-10;

/// Relative area (of the A face's projected area) below which an overlap is a sliver and
/// dropped.
pub const SLIVER: f64 = 1e-12;

/// Relative area (of `h^2`) below which a face counts as degenerate.
const DEGENERATE: f64 = 1e-10;

pub(super) fn v3(p: [f64; 3]) -> Vector3<f64> {
    Vector3::new(p[0], p[1], p[2])
}

/// Point `x(s, t)` of a face's bilinear map.
pub fn point(x: &Quad, s: f64, t: f64) -> Vector3<f64> {
    shapes(s, t).iter().zip(x).map(|(n, p)| v3(*p) * *n).sum()
}

/// Tangents `(x_s, x_t)` of a face's bilinear map at `(s, t)`.
pub fn tangents(x: &Quad, s: f64, t: f64) -> (Vector3<f64>, Vector3<f64>) {
    let d = shape_derivatives(s, t);
    let mut xs = Vector3::zeros();
    let mut xt = Vector3::zeros();
    for (dk, p) in d.iter().zip(x) {
        xs += v3(*p) * dk[0];
        xt += v3(*p) * dk[1];
    }
    (xs, xt)
}

/// The longest edge of a face.
pub fn size(x: &Quad) -> f64 {
    (0..4)
        .map(|k| (v3(x[(k + 1) % 4]) - v3(x[k])).norm())
        .fold(0.0, f64::max)
}

/// Angle in degrees between the normals of triangles `(a, b, c)` and `(a, c, d)`.
fn fold_angle(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> f64 {
    let n1 = (v3(b) - v3(a)).cross(&(v3(c) - v3(a)));
    let n2 = (v3(c) - v3(a)).cross(&(v3(d) - v3(a)));
    (n1.dot(&n2) / (n1.norm() * n2.norm()))
        .clamp(-1.0, 1.0)
        .acos()
        .to_degrees()
}

/// Check one face (`which` names it in the message) and return its longest edge `h`: finite
/// coordinates, no two corners within `1e-10 h`, each triangle half (split along either
/// diagonal) of area above `1e-10 h^2`, and the two halves' normals within
/// [`WARP_LIMIT_DEGREES`] of each other (the brick's own limit).
///
/// # Errors
/// [`Error::InvalidInput`] saying which check failed.
pub fn check_face(x: &Quad, which: &str) -> Result<f64> {
    if x.iter().flatten().any(|v| !v.is_finite()) {
        return Err(Error::InvalidInput(format!(
            "{which}: non-finite corner coordinate"
        )));
    }
    let h = size(x);
    if h == 0.0 || !h.is_finite() {
        return Err(Error::InvalidInput(format!("{which}: zero size")));
    }
    for a in 0..4 {
        for b in a + 1..4 {
            if (v3(x[a]) - v3(x[b])).norm() <= DEGENERATE * h {
                return Err(Error::InvalidInput(format!(
                    "{which}: corners {a} and {b} coincide"
                )));
            }
        }
    }
    let [a, b, c, d] = *x;
    for (p, q, r) in [(a, b, c), (a, c, d), (b, c, d), (b, d, a)] {
        let area = 0.5 * (v3(q) - v3(p)).cross(&(v3(r) - v3(p))).norm();
        if area <= DEGENERATE * h * h {
            return Err(Error::InvalidInput(format!(
                "{which}: zero area (collapsed corner)"
            )));
        }
    }
    let warp = fold_angle(a, b, c, d).max(fold_angle(b, c, d, a));
    if warp > WARP_LIMIT_DEGREES {
        return Err(Error::InvalidInput(format!(
            "{which}: warped by {warp:.1} degrees, beyond the limit of {WARP_LIMIT_DEGREES}"
        )));
    }
    Ok(h)
}

/// The auxiliary plane of an A face: origin `x_0 = x(0, 0)`, unit normal
/// `n_0 = x_s x x_t / |x_s x x_t|` at the centre, and the in-plane orthonormal basis
/// `e_1 = x_s / |x_s|`, `e_2 = n_0 x e_1` (right-handed, so counter-clockwise in `(e_1, e_2)`
/// is counter-clockwise about `n_0`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AuxPlane {
    /// The origin `x_0`.
    pub origin: Vector3<f64>,
    /// The unit normal `n_0` (A's outward normal at its centre).
    pub normal: Vector3<f64>,
    /// In-plane basis `e_1`, `e_2`.
    pub basis: [Vector3<f64>; 2],
}

impl AuxPlane {
    /// The plane of A face `a` (a face that passed [`check_face`]).
    pub fn of(a: &Quad) -> Self {
        let (xs, xt) = tangents(a, 0.0, 0.0);
        let normal = xs.cross(&xt).normalize();
        let e1 = xs.normalize();
        AuxPlane {
            origin: point(a, 0.0, 0.0),
            normal,
            basis: [e1, normal.cross(&e1)],
        }
    }

    /// The plane of A face `a` through its centre `x_0` normal to the unit vector `normal`
    /// (not parallel to the face), `e_1` along `x_s` made normal to it: a face with an edge on
    /// a symmetry plane is projected along its centre normal turned into the plane, so that
    /// its edge there and B's project onto the plane's one trace (see
    /// [`FaceGeometry`](super::FaceGeometry)).
    pub fn along(a: &Quad, normal: Vector3<f64>) -> Self {
        let (xs, _) = tangents(a, 0.0, 0.0);
        let e1 = (xs - normal * xs.dot(&normal)).normalize();
        AuxPlane {
            origin: point(a, 0.0, 0.0),
            normal,
            basis: [e1, normal.cross(&e1)],
        }
    }

    /// In-plane coordinates `y = ((p - x_0) . e_1, (p - x_0) . e_2)` of the projection of `p`
    /// along `n_0`.
    pub fn project(&self, p: [f64; 3]) -> Vector2<f64> {
        let r = v3(p) - self.origin;
        Vector2::new(r.dot(&self.basis[0]), r.dot(&self.basis[1]))
    }

    /// The point of the plane with in-plane coordinates `y`.
    pub fn lift(&self, y: Vector2<f64>) -> Vector3<f64> {
        self.origin + self.basis[0] * y[0] + self.basis[1] * y[1]
    }
}

/// The overlap of an A face and a B face on A's auxiliary plane.
#[derive(Debug, Clone, PartialEq)]
pub struct Overlap {
    /// A's auxiliary plane.
    pub plane: AuxPlane,
    /// A's corners projected, in A's order (counter-clockwise).
    pub a: [Vector2<f64>; 4],
    /// B's corners projected, in B's order (clockwise about `n_0` for a facing B face).
    pub b: [Vector2<f64>; 4],
    /// The overlap polygon, counter-clockwise about `n_0`, 3 to 8 vertices.
    pub polygon: Vec<Vector2<f64>>,
    /// Its area on the plane (shoelace formula).
    pub area: f64,
    /// A's longest edge (the length scale of the tolerances).
    pub h: f64,
}

fn cross2(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

/// Signed area of a polygon (positive counter-clockwise): `sum y_i x y_(i+1) / 2`.
pub fn polygon_area(p: &[Vector2<f64>]) -> f64 {
    (0..p.len())
        .map(|i| cross2(p[i], p[(i + 1) % p.len()]))
        .sum::<f64>()
        * 0.5
}

/// Whether a counter-clockwise quadrilateral is convex: every corner turns left, to `tol`
/// (an area).
fn convex(q: &[Vector2<f64>; 4], tol: f64) -> bool {
    (0..4).all(|k| cross2(q[(k + 1) % 4] - q[k], q[(k + 2) % 4] - q[(k + 1) % 4]) > tol)
}

/// The overlap of A face `a` and B face `b` projected on A's auxiliary plane, or `None` when
/// they do not overlap, B does not face A (`n_B . n_0 >= 0` at B's centre), or the overlap is
/// a sliver (area below [`SLIVER`] of A's).
///
/// Both projected faces must be convex: B's projection is oriented counter-clockwise and
/// clipped by each edge of A's (Sutherland-Hodgman). A vertex within `SNAP h` of an edge's
/// line counts as on it (kept, no intersection created), so that conforming faces clip to
/// themselves; then vertices are snapped to corners of either face within `SNAP h`, merged
/// with their successor within `SNAP h`, and dropped within `SNAP h` of the line through their
/// neighbours.
///
/// # Errors
/// [`Error::InvalidInput`] for a face failing [`check_face`], or projecting to a non-convex
/// quadrilateral (A re-entrant; B re-entrant, or warped and seen nearly edge-on).
pub fn overlap(a: &Quad, b: &Quad) -> Result<Option<Overlap>> {
    overlap_on(a, b, AuxPlane::of(a))
}

/// [`overlap`] on the auxiliary plane `plane` of `a` (its own, [`AuxPlane::of`], or one
/// [`AuxPlane::along`] a given normal).
///
/// # Errors
/// Those of [`overlap`].
pub fn overlap_on(a: &Quad, b: &Quad, plane: AuxPlane) -> Result<Option<Overlap>> {
    let h = check_face(a, "A face")?;
    let hb = check_face(b, "B face")?;
    let (bs, bt) = tangents(b, 0.0, 0.0);
    if bs.cross(&bt).dot(&plane.normal) >= 0.0 {
        return Ok(None);
    }
    let a2 = a.map(|p| plane.project(p));
    let b2 = b.map(|p| plane.project(p));
    let area_a = polygon_area(&a2);
    if !convex(&a2, DEGENERATE * h * h) {
        return Err(Error::InvalidInput(
            "A face projects to a non-convex quadrilateral on its own plane".into(),
        ));
    }
    let mut b_ccw = b2;
    b_ccw.reverse();
    if polygon_area(&b_ccw) <= SLIVER * area_a {
        return Ok(None);
    }
    if !convex(&b_ccw, -DEGENERATE * hb * hb) {
        return Err(Error::InvalidInput(
            "B face projects to a non-convex quadrilateral on the A face's plane".into(),
        ));
    }
    let eps = SNAP * h;
    let mut polygon = b_ccw.to_vec();
    for k in 0..4 {
        polygon = clip_by_edge(&polygon, a2[k], a2[(k + 1) % 4], eps);
        if polygon.is_empty() {
            return Ok(None);
        }
    }
    let corners: Vec<Vector2<f64>> = a2.iter().chain(&b2).copied().collect();
    let polygon = tidy(polygon, &corners, eps);
    if polygon.len() < 3 {
        return Ok(None);
    }
    let area = polygon_area(&polygon);
    if area <= SLIVER * area_a {
        return Ok(None);
    }
    Ok(Some(Overlap {
        plane,
        a: a2,
        b: b2,
        polygon,
        area,
        h,
    }))
}

/// One Sutherland-Hodgman step: the part of `poly` on the left of the line `p -> q`, a vertex
/// within `eps` of the line counting as on it.
fn clip_by_edge(
    poly: &[Vector2<f64>],
    p: Vector2<f64>,
    q: Vector2<f64>,
    eps: f64,
) -> Vec<Vector2<f64>> {
    let e = q - p;
    let len = e.norm();
    let dist = |x: Vector2<f64>| cross2(e, x - p) / len;
    let mut out = Vec::with_capacity(poly.len() + 1);
    for i in 0..poly.len() {
        let (cur, next) = (poly[i], poly[(i + 1) % poly.len()]);
        let (dc, dn) = (dist(cur), dist(next));
        if dc >= -eps {
            out.push(cur);
        }
        if (dc > eps && dn < -eps) || (dc < -eps && dn > eps) {
            out.push(cur + (next - cur) * (dc / (dc - dn)));
        }
    }
    out
}

/// Snap vertices to `corners` within `eps`, merge consecutive vertices within `eps`, drop
/// vertices within `eps` of the line through their neighbours.
fn tidy(poly: Vec<Vector2<f64>>, corners: &[Vector2<f64>], eps: f64) -> Vec<Vector2<f64>> {
    let snapped: Vec<Vector2<f64>> = poly
        .into_iter()
        .map(|v| {
            corners
                .iter()
                .copied()
                .find(|c| (c - v).norm() <= eps)
                .unwrap_or(v)
        })
        .collect();
    let mut out: Vec<Vector2<f64>> = Vec::with_capacity(snapped.len());
    for v in snapped {
        if out.last().is_none_or(|l| (l - v).norm() > eps) {
            out.push(v);
        }
    }
    while out.len() > 1 && (out[0] - out[out.len() - 1]).norm() <= eps {
        out.pop();
    }
    let mut i = 0;
    while out.len() >= 3 && i < out.len() {
        let n = out.len();
        let (prev, cur, next) = (out[(i + n - 1) % n], out[i], out[(i + 1) % n]);
        let base = next - prev;
        let off = cross2(base, cur - prev).abs() / base.norm().max(f64::MIN_POSITIVE);
        if off <= eps {
            out.remove(i);
            i = i.saturating_sub(1);
        } else {
            i += 1;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(c: [f64; 2], half: f64, angle_deg: f64, z: f64, facing: bool) -> Quad {
        let (sn, cs) = angle_deg.to_radians().sin_cos();
        let mut q = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]].map(|[u, v]: [f64; 2]| {
            let (x, y) = (half * u, half * v);
            [c[0] + cs * x - sn * y, c[1] + sn * x + cs * y, z]
        });
        if facing {
            q.reverse();
        }
        q
    }

    #[test]
    fn coincident_faces_overlap_in_the_face() {
        let a = square([0.0, 0.0], 1.0, 0.0, 0.0, false);
        let b = square([0.0, 0.0], 1.0, 0.0, 0.0, true);
        let o = overlap(&a, &b).unwrap().unwrap();
        assert_eq!(o.polygon.len(), 4);
        assert!((o.area - 4.0).abs() <= 1e-14 * 4.0, "{}", o.area);
        for v in &o.polygon {
            assert!(o.a.contains(v), "vertex {v:?} not snapped to a corner");
        }
    }

    #[test]
    fn rotated_square_clips_to_an_octagon() {
        let a = square([0.0, 0.0], 1.0, 0.0, 0.0, false);
        for deg in [15.0, 45.0] {
            let b = square([0.0, 0.0], 1.0, deg, 0.3, true);
            let o = overlap(&a, &b).unwrap().unwrap();
            assert_eq!(o.polygon.len(), 8, "{deg} degrees");
            assert!(polygon_area(&o.polygon) > 0.0);
        }
    }

    #[test]
    fn faces_that_do_not_face_or_touch_give_none() {
        let a = square([0.0, 0.0], 1.0, 0.0, 0.0, false);
        let same_way = square([0.0, 0.0], 1.0, 0.0, 0.1, false);
        assert!(overlap(&a, &same_way).unwrap().is_none());
        let apart = square([3.0, 0.0], 1.0, 0.0, 0.1, true);
        assert!(overlap(&a, &apart).unwrap().is_none());
        // sharing one edge only: a zero-area overlap
        let edge = square([2.0, 0.0], 1.0, 0.0, 0.0, true);
        assert!(overlap(&a, &edge).unwrap().is_none());
        // overlapping by 1e-13 of the width: a sliver
        let sliver = square([2.0 - 1e-13, 0.0], 1.0, 0.0, 0.0, true);
        assert!(overlap(&a, &sliver).unwrap().is_none());
    }

    #[test]
    fn bad_faces_are_errors() {
        let a = square([0.0, 0.0], 1.0, 0.0, 0.0, false);
        let b = square([0.0, 0.0], 1.0, 0.0, 0.0, true);
        let mut nan = b;
        nan[2][1] = f64::NAN;
        let mut collapsed = a;
        collapsed[2] = collapsed[1];
        let mut folded = a;
        folded[2][2] = 3.0;
        let mut zero = a;
        zero.iter_mut().for_each(|p| *p = [1.0, 2.0, 3.0]);
        let mut reentrant = a;
        reentrant[2] = [-0.5, -0.5, 0.0];
        for (what, a, b) in [
            ("NaN", a, nan),
            ("collapsed", collapsed, b),
            ("folded", folded, b),
            ("zero", zero, b),
            ("re-entrant", reentrant, b),
        ] {
            assert!(
                matches!(overlap(&a, &b), Err(Error::InvalidInput(_))),
                "{what}"
            );
        }
    }
}
