//! The mortar integrals of one A face against one B face over their overlap, and of one A face
//! over itself: triangulation from the centroid, Radon's 7-point triangle rule, inverse bilinear
//! maps by Newton's method.
//!
//! # Exactness
//! The triangle rule has degree 5 ([`TRIANGLE_RULE`]). On **flat parallelogram** faces the
//! maps `y -> (s, t)` are affine, so the shapes `N_a`, `M_b` are quadratic in the plane
//! coordinate `y`, the products `N_a N_b` and `N_a M_b` of degree 4, the gap `g` affine and
//! `N_a g` of degree 3, and `dA / dy` is constant: every integral is exact to round-off. On
//! flat faces of general shape (trapezoids) the inverse bilinear map is not polynomial and on
//! warped faces neither is the projection, so the rule is not exact there; the tests measure
//! its error against a fine subdivision. Whatever the shapes, `sum_b M_ab = w_a` holds to
//! round-off (the `M_b` sum to one at every point), which is what the patch test needs.

use super::clip::{AuxPlane, Overlap, check_face, overlap_on, point, tangents};
use super::{Quad, shapes};
use crate::error::{Error, Result};
use crate::fem::quadrature::GAUSS3;
use nalgebra::{Matrix2, Vector2};

const SQRT15: f64 = 3.872_983_346_207_417;

/// Radon's 7-point rule on a triangle, degree 5: barycentric coordinates and weights (summing
/// to 1, to be multiplied by the triangle's area). The centroid with weight `9/40`, and two
/// orbits `(a, a, 1 - 2a)` with `a = (6 -+ sqrt 15) / 21`, weights `(155 -+ sqrt 15) / 1200`.
pub const TRIANGLE_RULE: [([f64; 3], f64); 7] = {
    let a1 = (6.0 - SQRT15) / 21.0;
    let b1 = 1.0 - 2.0 * a1;
    let w1 = (155.0 - SQRT15) / 1200.0;
    let a2 = (6.0 + SQRT15) / 21.0;
    let b2 = 1.0 - 2.0 * a2;
    let w2 = (155.0 + SQRT15) / 1200.0;
    let c = 1.0 / 3.0;
    [
        ([c, c, c], 9.0 / 40.0),
        ([a1, a1, b1], w1),
        ([a1, b1, a1], w1),
        ([b1, a1, a1], w1),
        ([a2, a2, b2], w2),
        ([a2, b2, a2], w2),
        ([b2, a2, a2], w2),
    ]
};

/// Natural coordinates `(s, t)` of the point `y` of a projected face `q` (corners in face
/// order): Newton's method on `sum_k N_k(s, t) q_k = y` from the centre, as
/// [`crate::solid::geometry::Trilinear::inverse`] in 3D; exact in one step for a
/// parallelogram. `None` when the Jacobian is singular or the residual stays above `1e-12 h`
/// (`h` the face's size).
pub fn inverse_bilinear(q: &[Vector2<f64>; 4], y: Vector2<f64>, h: f64) -> Option<[f64; 2]> {
    let mut st = Vector2::zeros();
    for _ in 0..50 {
        let n = shapes(st[0], st[1]);
        let d = super::shape_derivatives(st[0], st[1]);
        let mut x = Vector2::zeros();
        let mut j = Matrix2::zeros();
        for k in 0..4 {
            x += q[k] * n[k];
            for i in 0..2 {
                j[(i, 0)] += q[k][i] * d[k][0];
                j[(i, 1)] += q[k][i] * d[k][1];
            }
        }
        let r = y - x;
        if r.norm() <= 1e-15 * h {
            break;
        }
        let step = j.try_inverse()? * r;
        st += step;
        if step.norm() <= 1e-15 {
            break;
        }
    }
    let n = shapes(st[0], st[1]);
    let x: Vector2<f64> = (0..4).map(|k| q[k] * n[k]).sum();
    ((y - x).norm() <= 1e-12 * h && st.iter().all(|v| v.is_finite())).then_some([st[0], st[1]])
}

/// The integrals of one A face against one B face over their overlap (see the
/// [module docs](super) for the definitions). Indices `a` run over A's corners and `b` over
/// B's, in face order.
#[derive(Debug, Clone, PartialEq)]
pub struct FacePair {
    /// `D_ab = integral N_a N_b dA` over the covered part.
    pub d: [[f64; 4]; 4],
    /// `M_ab = integral N_a M_b dA`.
    pub m: [[f64; 4]; 4],
    /// `R_a = integral N_a (x^A - x^B) dA`.
    pub mismatch: [[f64; 3]; 4],
    /// `g~_a = integral N_a g dA = -n_0 . R_a` (positive open).
    pub gap: [f64; 4],
    /// `w_a = integral N_a dA` over the covered part.
    pub weight: [f64; 4],
    /// The covered area of A, `integral dA`.
    pub area: f64,
    /// The overlap on the auxiliary plane.
    pub overlap: Overlap,
}

/// The mortar integrals of A face `a` against B face `b`, `None` where they do not overlap (or
/// B does not face A; see [`overlap`](super::clip::overlap)). The overlap polygon is split
/// into triangles from its vertex centroid (inside, the polygon being convex) and each
/// triangle integrated with
/// [`TRIANGLE_RULE`]; a point `y` maps to `(s, t)` on each face by [`inverse_bilinear`] of the
/// projected corners, to `x^A = x_A(s, t)` and `x^B = x_B(s', t')`, and
/// `dA = |x_s x x_t| / |(x_s x x_t) . n_0| dy` (A's tangents).
///
/// # Errors
/// Those of [`overlap`](super::clip::overlap); [`Error::InvalidInput`] if an inverse map
/// fails (a face folded over the overlap).
pub fn face_pair(a: &Quad, b: &Quad) -> Result<Option<FacePair>> {
    face_pair_on(a, b, AuxPlane::of(a))
}

/// [`face_pair`] on the auxiliary plane `plane` of `a` ([`overlap_on`]).
///
/// # Errors
/// Those of [`face_pair`].
pub fn face_pair_on(a: &Quad, b: &Quad, plane: AuxPlane) -> Result<Option<FacePair>> {
    let Some(overlap) = overlap_on(a, b, plane)? else {
        return Ok(None);
    };
    let hb = super::clip::size(b);
    let n0 = overlap.plane.normal;
    let poly = &overlap.polygon;
    let centre = poly.iter().sum::<Vector2<f64>>() / poly.len() as f64;
    let mut out = FacePair {
        d: [[0.0; 4]; 4],
        m: [[0.0; 4]; 4],
        mismatch: [[0.0; 3]; 4],
        gap: [0.0; 4],
        weight: [0.0; 4],
        area: 0.0,
        overlap: overlap.clone(),
    };
    for i in 0..poly.len() {
        let (p, q) = (poly[i], poly[(i + 1) % poly.len()]);
        let tri_area = 0.5 * ((p - centre).perp(&(q - centre)));
        for (l, w) in TRIANGLE_RULE {
            let y = centre * l[0] + p * l[1] + q * l[2];
            let (Some([s, t]), Some([sb, tb])) = (
                inverse_bilinear(&overlap.a, y, overlap.h),
                inverse_bilinear(&overlap.b, y, hb),
            ) else {
                return Err(Error::InvalidInput(
                    "inverse bilinear map failed on the overlap of an A and a B face".into(),
                ));
            };
            let (xs, xt) = tangents(a, s, t);
            let normal = xs.cross(&xt);
            let da = w * tri_area * normal.norm() / normal.dot(&n0).abs();
            let (na, mb) = (shapes(s, t), shapes(sb, tb));
            let diff = point(a, s, t) - point(b, sb, tb);
            out.area += da;
            for (ka, &nk) in na.iter().enumerate() {
                for kb in 0..4 {
                    out.d[ka][kb] += nk * na[kb] * da;
                    out.m[ka][kb] += nk * mb[kb] * da;
                }
                for c in 0..3 {
                    out.mismatch[ka][c] += nk * diff[c] * da;
                }
                out.gap[ka] -= nk * diff.dot(&n0) * da;
                out.weight[ka] += nk * da;
            }
        }
    }
    Ok(Some(out))
}

/// The integrals of one A face over the whole face.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FaceMass {
    /// `D_ab = integral N_a N_b dA` over the face.
    pub d: [[f64; 4]; 4],
    /// `w_a = integral N_a dA` over the face.
    pub weight: [f64; 4],
    /// The face's area.
    pub area: f64,
}

/// `D`, the weights and the area of a face over the whole face, by 3x3 Gauss in `(s, t)` with
/// `dA = |x_s x x_t| ds dt`: exact on flat faces (`|x_s x x_t|` is then affine in `s` and `t`,
/// so the integrands have degree 3 in each), an approximation on warped faces.
///
/// # Errors
/// Those of [`check_face`].
pub fn face_mass(a: &Quad) -> Result<FaceMass> {
    check_face(a, "A face")?;
    let mut out = FaceMass {
        d: [[0.0; 4]; 4],
        weight: [0.0; 4],
        area: 0.0,
    };
    for (s, ws) in GAUSS3 {
        for (t, wt) in GAUSS3 {
            let (xs, xt) = tangents(a, s, t);
            let da = ws * wt * xs.cross(&xt).norm();
            let n = shapes(s, t);
            out.area += da;
            for i in 0..4 {
                out.weight[i] += n[i] * da;
                for j in 0..4 {
                    out.d[i][j] += n[i] * n[j] * da;
                }
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Rotation3, Vector3};

    /// A rectangle `[x0, x1] x [y0, y1]` at height `z`, rotated by `deg` about the vertical
    /// through `(cx, cy)`; outward `+z` (an A face) or `-z` (a facing B face).
    fn rect(x: [f64; 2], y: [f64; 2], z: f64, deg: f64, centre: [f64; 2], up: bool) -> Quad {
        let (sn, cs) = deg.to_radians().sin_cos();
        let mut q = [[x[0], y[0]], [x[1], y[0]], [x[1], y[1]], [x[0], y[1]]].map(|[u, v]| {
            let (du, dv) = (u - centre[0], v - centre[1]);
            [
                centre[0] + cs * du - sn * dv,
                centre[1] + sn * du + cs * dv,
                z,
            ]
        });
        if !up {
            q.reverse();
        }
        q
    }

    fn rel(a: f64, b: f64, scale: f64) -> f64 {
        (a - b).abs() / scale
    }

    fn factorial(n: u32) -> f64 {
        (1..=n).map(f64::from).product()
    }

    #[test]
    fn triangle_rule_has_degree_five() {
        let err = |i: i32, j: i32| {
            let exact = factorial(i as u32) * factorial(j as u32) / factorial((i + j + 2) as u32);
            let q: f64 = TRIANGLE_RULE
                .iter()
                .map(|(l, w)| 0.5 * w * l[1].powi(i) * l[2].powi(j))
                .sum();
            (q - exact).abs() / exact
        };
        for total in 0..=5 {
            for i in 0..=total {
                assert!(err(i, total - i) < 1e-14, "x^{i} y^{}", total - i);
            }
        }
        assert!(err(6, 0) > 1e-4, "degree 6 is not integrated exactly");
    }

    #[test]
    fn inverse_bilinear_recovers_natural_coordinates() {
        let q = [[0.0, 0.0], [2.0, 0.1], [1.7, 1.5], [-0.2, 1.0]].map(Vector2::from);
        for st in [[0.3, -0.7], [-1.0, 1.0], [0.9, 0.95], [1.2, -1.1]] {
            let n = shapes(st[0], st[1]);
            let y: Vector2<f64> = (0..4).map(|k| q[k] * n[k]).sum();
            let got = inverse_bilinear(&q, y, 2.0).unwrap();
            assert!((got[0] - st[0]).abs() < 1e-13 && (got[1] - st[1]).abs() < 1e-13);
        }
    }

    #[test]
    fn coincident_faces_give_m_equal_to_d() {
        // a parallelogram (where the rule is exact) and a general flat quadrilateral
        let para = [
            [0.0, 0.0, 0.0],
            [2.0, 0.5, 0.0],
            [2.6, 1.7, 0.0],
            [0.6, 1.2, 0.0],
        ];
        let general = [
            [0.0, 0.0, 0.0],
            [2.0, 0.3, 0.0],
            [1.6, 1.9, 0.0],
            [-0.3, 1.1, 0.0],
        ];
        for a in [para, general] {
            let mut b = a;
            b.reverse();
            let p = face_pair(&a, &b).unwrap().unwrap();
            let scale = p.area;
            for i in 0..4 {
                for j in 0..4 {
                    assert!(
                        rel(p.m[i][3 - j], p.d[i][j], scale) < 1e-14,
                        "M != D at {i} {j}"
                    );
                }
                assert!(p.gap[i].abs() < 1e-14 * scale * scale.sqrt());
            }
        }
        let mass = face_mass(&para).unwrap();
        let p = face_pair(&para, &{
            let mut b = para;
            b.reverse();
            b
        })
        .unwrap()
        .unwrap();
        assert!(rel(p.area, mass.area, mass.area) < 1e-14);
        for i in 0..4 {
            for j in 0..4 {
                assert!(rel(p.d[i][j], mass.d[i][j], mass.area) < 1e-14);
            }
        }
        // the parallelogram's D in closed form: area (4, 2, 1, 2) / 36 by corner distance
        let area = 2.0 * 1.2 - 0.5 * 0.6;
        for i in 0..4 {
            for j in 0..4 {
                let exact = area * [4.0, 2.0, 1.0, 2.0][(j + 4 - i) % 4] / 36.0;
                assert!(rel(mass.d[i][j], exact, area) < 1e-14);
            }
        }
    }

    /// `integral_lo^hi f` for a polynomial `f` of degree <= 5 (3-point Gauss).
    fn integral_1d(lo: f64, hi: f64, f: impl Fn(f64) -> f64) -> f64 {
        let (c, r) = (0.5 * (lo + hi), 0.5 * (hi - lo));
        GAUSS3.iter().map(|(x, w)| w * r * f(c + r * x)).sum()
    }

    #[test]
    fn offset_by_a_third_matches_the_closed_form() {
        // A = [0, 1]^2 at z = 0, B = A shifted by (1/3, 1/3), 0.1 above
        let third = 1.0 / 3.0;
        let a = rect([0.0, 1.0], [0.0, 1.0], 0.0, 0.0, [0.0; 2], true);
        let b = rect(
            [third, 1.0 + third],
            [third, 1.0 + third],
            0.1,
            0.0,
            [0.0; 2],
            false,
        );
        let p = face_pair(&a, &b).unwrap().unwrap();
        assert!(rel(p.area, 4.0 / 9.0, 1.0) < 1e-15, "area {}", p.area);
        // 1D hats: A's (1 - x, x) on [0, 1], B's (4/3 - x, x - 1/3) on [1/3, 4/3]; corner k of
        // a face is (hat i_k in x) (hat j_k in y)
        let ha = |i: usize, x: f64| if i == 0 { 1.0 - x } else { x };
        let hb = |i: usize, x: f64| if i == 0 { 1.0 + third - x } else { x - third };
        let a_ij = [(0, 0), (1, 0), (1, 1), (0, 1)];
        // B's corners are A's order reversed: b = 3 - k
        let b_ij = [(0, 1), (1, 1), (1, 0), (0, 0)];
        for (ka, &(ia, ja)) in a_ij.iter().enumerate() {
            let wa =
                integral_1d(third, 1.0, |x| ha(ia, x)) * integral_1d(third, 1.0, |y| ha(ja, y));
            assert!(rel(p.weight[ka], wa, 1.0) < 1e-15);
            assert!(rel(p.gap[ka], 0.1 * wa, 1.0) < 1e-15);
            assert!(rel(p.mismatch[ka][2], -0.1 * wa, 1.0) < 1e-15);
            for (kb, &(ib, jb)) in b_ij.iter().enumerate() {
                let mx = integral_1d(third, 1.0, |x| ha(ia, x) * hb(ib, x));
                let my = integral_1d(third, 1.0, |y| ha(ja, y) * hb(jb, y));
                assert!(rel(p.m[ka][kb], mx * my, 1.0) < 1e-15, "M[{ka}][{kb}]");
            }
            for (kd, &(id, jd)) in a_ij.iter().enumerate() {
                let dx = integral_1d(third, 1.0, |x| ha(ia, x) * ha(id, x));
                let dy = integral_1d(third, 1.0, |y| ha(ja, y) * ha(jd, y));
                assert!(rel(p.d[ka][kd], dx * dy, 1.0) < 1e-15, "D[{ka}][{kd}]");
            }
        }
    }

    /// Area of the octagon where the square `[-1, 1]^2` and its copy rotated by `deg` (0 to 90)
    /// about its centre overlap: the square less 4 corner triangles, each cut off by one edge
    /// `x cos + y sin = 1` of the rotated square.
    fn octagon_area(deg: f64) -> f64 {
        let (sn, cs) = deg.to_radians().sin_cos();
        let y1 = (1.0 - cs) / sn;
        let x1 = (1.0 - sn) / cs;
        4.0 - 4.0 * 0.5 * (1.0 - y1) * (1.0 - x1)
    }

    #[test]
    fn rotated_faces_overlap_in_octagons_of_the_exact_area() {
        let a = rect([-1.0, 1.0], [-1.0, 1.0], 0.0, 0.0, [0.0; 2], true);
        for deg in [15.0, 45.0] {
            let b = rect([-1.0, 1.0], [-1.0, 1.0], 0.2, deg, [0.0; 2], false);
            let p = face_pair(&a, &b).unwrap().unwrap();
            assert_eq!(p.overlap.polygon.len(), 8);
            let exact = octagon_area(deg);
            assert!(
                rel(p.area, exact, 4.0) < 1e-14,
                "{deg}: {} vs {exact}",
                p.area
            );
            assert!(rel(p.weight.iter().sum(), exact, 4.0) < 1e-14);
            let gap: f64 = p.gap.iter().sum();
            assert!(rel(gap, 0.2 * exact, 4.0) < 1e-14);
            // partition of unity on the overlap, and symmetry: every corner the same weight
            for k in 0..4 {
                assert!(rel(p.m[k].iter().sum(), p.weight[k], 1.0) < 1e-14);
                assert!(rel(p.weight[k], exact / 4.0, 1.0) < 1e-14);
            }
        }
    }

    /// `sum_b M_ab = sum_b D_ab` for an A face fully inside a B face: the patch-test condition.
    #[test]
    fn fully_covered_face_has_the_partition_of_unity() {
        let general = [
            [0.0, 0.0, 0.0],
            [2.0, 0.3, 0.0],
            [1.6, 1.9, 0.0],
            [-0.3, 1.1, 0.0],
        ];
        let square = rect([0.0, 1.0], [0.0, 1.0], 0.0, 0.0, [0.0; 2], true);
        for (a, exact) in [(general, false), (square, true)] {
            let mut worst: f64 = 0.0;
            for deg in [0.0, 15.0, 45.0] {
                let mut b = rect([-2.0, 3.0], [-2.0, 3.0], 0.05, deg, [0.5, 0.5], false);
                b[1][2] += 0.3; // B tilted: a gap varying over A
                let p = face_pair(&a, &b).unwrap().unwrap();
                let mass = face_mass(&a).unwrap();
                // R_a = sum_b D_ab x^A_b - sum_b M_ab x^B_b
                for (k, r) in p.mismatch.iter().enumerate() {
                    for (c, rc) in r.iter().enumerate() {
                        let dm: f64 = (0..4)
                            .map(|j| p.d[k][j] * a[j][c] - p.m[k][j] * b[j][c])
                            .sum();
                        assert!((rc - dm).abs() < 1e-13 * mass.area, "R {k} {c}");
                    }
                }
                for k in 0..4 {
                    let (sm, sd): (f64, f64) = (p.m[k].iter().sum(), p.d[k].iter().sum());
                    assert!(rel(sm, sd, mass.area) < 1e-12, "{deg}: {sm} vs {sd}");
                    // the whole face's weights (exact), to the triangle rule's error
                    worst = worst.max(rel(sd, mass.weight[k], mass.area));
                }
                assert!(
                    rel(p.area, mass.area, mass.area) < 1e-14,
                    "the rule is exact for 1"
                );
            }
            // the whole face's weights (exact) differ by the triangle rule's error, none on a
            // square
            eprintln!("covered vs whole-face weights, exact map {exact}: {worst:.2e}");
            assert!(worst < if exact { 1e-14 } else { 1e-7 });
        }
    }

    #[test]
    fn partly_covered_face_integrates_over_the_covered_part() {
        // B covers x >= 0.5 of A = [0, 1]^2
        let a = rect([0.0, 1.0], [0.0, 1.0], 0.0, 0.0, [0.0; 2], true);
        let b = rect([0.5, 2.0], [-1.0, 2.0], 0.0, 0.0, [0.0; 2], false);
        let p = face_pair(&a, &b).unwrap().unwrap();
        assert!(rel(p.area, 0.5, 1.0) < 1e-15);
        // integral over [0.5, 1] of (1 - x) = 1/8, of x = 3/8; over [0, 1] in y: 1/2
        let exact = [0.0625, 0.1875, 0.1875, 0.0625];
        for ((w, m), e) in p.weight.iter().zip(&p.m).zip(exact) {
            assert!(rel(*w, e, 1.0) < 1e-15);
            assert!(rel(m.iter().sum(), e, 1.0) < 1e-15);
        }
    }

    /// A warped A face (one corner lifted by `lift`) under a flat B face covering it: the
    /// pair's `D`, `M` and weighted gap against a fine tensor Gauss rule in A's own
    /// parameters (64 x 64 cells of 3 x 3 points), projecting along `n_0` onto B's plane in
    /// closed form. Returns the largest error relative to the face's area (times its size for
    /// the gap).
    fn warped_error(lift: f64) -> f64 {
        let mut a = rect([0.0, 1.0], [0.0, 1.0], 0.0, 0.0, [0.0; 2], true);
        a[2][2] = lift;
        let (zb, side) = (0.3, [-1.0, 2.0]);
        let b = rect(side, side, zb, 0.0, [0.0; 2], false);
        let p = face_pair(&a, &b).unwrap().unwrap();
        let n0 = p.overlap.plane.normal;
        let (mut d, mut m, mut gap) = ([[0.0; 4]; 4], [[0.0; 4]; 4], [0.0; 4]);
        let cells = 64;
        for ci in 0..cells {
            for cj in 0..cells {
                for (u, wu) in GAUSS3 {
                    for (v, wv) in GAUSS3 {
                        let h = 2.0 / cells as f64;
                        let s = -1.0 + h * (ci as f64 + 0.5 * (u + 1.0));
                        let t = -1.0 + h * (cj as f64 + 0.5 * (v + 1.0));
                        let (xs, xt) = tangents(&a, s, t);
                        let da = wu * wv * 0.25 * h * h * xs.cross(&xt).norm();
                        let xa = point(&a, s, t);
                        let g = (zb - xa[2]) / n0[2];
                        let xb: Vector3<f64> = xa + n0 * g;
                        // B reversed: corner 0 at (x0, y1), 1 (x1, y1), 2 (x1, y0), 3 (x0, y0)
                        let (sb, tb) = (
                            2.0 * (xb[0] - side[0]) / 3.0 - 1.0,
                            1.0 - 2.0 * (xb[1] - side[0]) / 3.0,
                        );
                        let (na, mb) = (shapes(s, t), shapes(sb, tb));
                        for i in 0..4 {
                            for j in 0..4 {
                                d[i][j] += na[i] * na[j] * da;
                                m[i][j] += na[i] * mb[j] * da;
                            }
                            gap[i] += na[i] * g * da;
                        }
                    }
                }
            }
        }
        let mut err: f64 = 0.0;
        for i in 0..4 {
            for j in 0..4 {
                err = err
                    .max((p.d[i][j] - d[i][j]).abs())
                    .max((p.m[i][j] - m[i][j]).abs());
            }
            err = err.max((p.gap[i] - gap[i]).abs());
        }
        err
    }

    #[test]
    fn warped_faces_report_their_integration_error() {
        let flat = warped_error(0.0);
        let slight = warped_error(0.02);
        let strong = warped_error(0.2);
        eprintln!(
            "warped pair error (of the area): flat {flat:.2e}, lift 0.02 {slight:.2e}, lift 0.2 {strong:.2e}"
        );
        assert!(flat < 1e-13, "flat square: exact");
        assert!(slight < 1e-8 && strong < 1e-6, "{slight:e} {strong:e}");
        assert!(strong > flat);
    }

    #[test]
    fn invariant_under_rigid_motion_and_scaling() {
        let a = [
            [0.0, 0.0, 0.0],
            [1.1, 0.1, 0.0],
            [1.0, 0.9, 0.05],
            [-0.1, 1.0, 0.0],
        ];
        let b = rect([0.3, 1.4], [0.2, 1.3], 0.1, 15.0, [0.8, 0.7], false);
        let base = face_pair(&a, &b).unwrap().unwrap();
        let rot = Rotation3::from_euler_angles(0.3, -1.1, 2.0);
        let shift = Vector3::new(5.0, -3.0, 7.0);
        for scale in [1.0, 1e-3, 1e3] {
            let map = |q: Quad| {
                q.map(|p| {
                    let v = rot * (Vector3::from(p) * scale) + shift * scale;
                    [v[0], v[1], v[2]]
                })
            };
            let p = face_pair(&map(a), &map(b)).unwrap().unwrap();
            let s2 = scale * scale;
            assert_eq!(p.overlap.polygon.len(), base.overlap.polygon.len());
            assert!(rel(p.area, base.area * s2, base.area * s2) < 1e-12);
            for i in 0..4 {
                for j in 0..4 {
                    assert!(rel(p.d[i][j], base.d[i][j] * s2, base.area * s2) < 1e-12);
                    assert!(rel(p.m[i][j], base.m[i][j] * s2, base.area * s2) < 1e-12);
                }
                let s3 = s2 * scale;
                assert!(rel(p.gap[i], base.gap[i] * s3, base.area * s3) < 1e-12);
                let r = rot * Vector3::from(base.mismatch[i]) * s3;
                for c in 0..3 {
                    assert!(rel(p.mismatch[i][c], r[c], base.area * s3) < 1e-12);
                }
            }
        }
    }

    #[test]
    fn degenerate_faces_are_errors_not_panics() {
        let a = rect([0.0, 1.0], [0.0, 1.0], 0.0, 0.0, [0.0; 2], true);
        let b = rect([0.0, 1.0], [0.0, 1.0], 0.1, 0.0, [0.0; 2], false);
        let zero = [[0.5, 0.5, 0.0]; 4];
        let line = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [3.0, 0.0, 0.0],
        ];
        let mut twisted = a;
        twisted[2][2] = 2.0;
        let mut nan = b;
        nan[0][0] = f64::NAN;
        let mut inf = a;
        inf[3][2] = f64::INFINITY;
        for (what, x, y) in [
            ("zero A", zero, b),
            ("zero B", a, zero),
            ("collinear", line, b),
            ("non-planar A", twisted, b),
            ("NaN B", a, nan),
            ("infinite A", inf, b),
        ] {
            assert!(face_pair(&x, &y).is_err(), "{what}");
        }
        assert!(face_mass(&zero).is_err() && face_mass(&twisted).is_err());
    }
}
