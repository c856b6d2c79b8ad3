//! How the two polylines of a contact pair face each other, judged without the search window
//! of the contact kernels ([`super::mortar`]): the orientation check of a pair in the
//! reference configuration, and the check that no node the search lost has passed through the
//! opposite surface.
//!
//! Conventions as in [`super::mortar`]: each polyline has its body on the left, a segment
//! `p0 -> p1` has the outward normal `n = (d_y, -d_x) / |d|`, `d = p1 - p0`, and a node's
//! normal is the length-weighted mean of its adjacent segments' normals.

pub use crate::contact::geometry::Facing;
use crate::contact::geometry::FacingTally;
use crate::element::geometry::edge_normal;
use crate::error::{Error, Result};

/// Outward unit normal of node `k` of the polyline `ids` at the positions `x`: the direction of
/// `sum_e h_e n_e` over its one or two adjacent segments.
pub fn node_normal(ids: &[usize], k: usize, x: &[[f64; 2]]) -> [f64; 2] {
    let (lo, hi) = (k.saturating_sub(1), (k + 1).min(ids.len() - 1));
    // sum_e h_e n_e telescopes to the rotated chord of the neighbours
    edge_normal(x[ids[lo]], x[ids[hi]]).0
}

/// Half the length of the one or two segments adjacent to node `k` (its tributary length).
fn support(ids: &[usize], k: usize, x: &[[f64; 2]]) -> f64 {
    let len = |i: usize| {
        let (p, q) = (x[ids[i]], x[ids[i + 1]]);
        (q[0] - p[0]).hypot(q[1] - p[1])
    };
    let left = if k > 0 { len(k - 1) } else { 0.0 };
    let right = if k + 1 < ids.len() { len(k) } else { 0.0 };
    0.5 * (left + right)
}

/// The point of segment `seg` of polyline `ids` nearest to `p`: `(eta, point)` with the
/// segment parameter `eta` unclamped (`[0, 1]` on the segment) and the point clamped to it.
fn nearest_on_segment(ids: &[usize], seg: usize, p: [f64; 2], x: &[[f64; 2]]) -> (f64, [f64; 2]) {
    let (q0, q1) = (x[ids[seg]], x[ids[seg + 1]]);
    let d = [q1[0] - q0[0], q1[1] - q0[1]];
    let eta = ((p[0] - q0[0]) * d[0] + (p[1] - q0[1]) * d[1]) / (d[0] * d[0] + d[1] * d[1]);
    let s = eta.clamp(0.0, 1.0);
    (eta, [q0[0] + s * d[0], q0[1] + s * d[1]])
}

/// Classify every A node against the B segment nearest to it, if that lies within `reach`
/// (see [`Facing`]). `O(|A| |B|)`, meant for the reference configuration, once per analysis.
pub fn facing(a: &[usize], b: &[usize], x: &[[f64; 2]], reach: f64) -> Facing {
    let mut tally = FacingTally::default();
    for k in 0..a.len() {
        let p = x[a[k]];
        let nearest = (0..b.len() - 1)
            .map(|seg| {
                let (_, q) = nearest_on_segment(b, seg, p, x);
                (seg, q, (q[0] - p[0]).hypot(q[1] - p[1]))
            })
            .min_by(|u, v| u.2.total_cmp(&v.2));
        let Some((seg, q, _)) = nearest.filter(|n| n.2 <= reach) else {
            continue;
        };
        let na = node_normal(a, k, x);
        let nb = edge_normal(x[b[seg]], x[b[seg + 1]]).0;
        let cos = na[0] * nb[0] + na[1] * nb[1];
        let ahead = (q[0] - p[0]) * na[0] + (q[1] - p[1]) * na[1];
        tally.add(k, cos, ahead, support(a, k, x));
    }
    tally.finish()
}

/// On which side of the polyline `ids` the point `p` lies: the signed distance `(p - q) . n`
/// from its nearest point `q` on the polyline, `n` the outward normal there (of the segment,
/// or of the node when `q` is a node), negative on the body's side (the left). `None` when
/// `p` lies beyond an end of the polyline (its nearest point is an end node and it projects
/// outside the end segment), where the side is not defined.
pub fn side(ids: &[usize], x: &[[f64; 2]], p: [f64; 2]) -> Option<f64> {
    let last = ids.len() - 2;
    let (seg, eta, q) = (0..=last)
        .map(|seg| {
            let (eta, q) = nearest_on_segment(ids, seg, p, x);
            (seg, eta, q)
        })
        .min_by(|u, v| {
            let d = |q: [f64; 2]| (q[0] - p[0]).hypot(q[1] - p[1]);
            d(u.2).total_cmp(&d(v.2))
        })?;
    if (seg == 0 && eta < 0.0) || (seg == last && eta > 1.0) {
        return None;
    }
    let n = if eta <= 0.0 {
        node_normal(ids, seg, x)
    } else if eta >= 1.0 {
        node_normal(ids, seg + 1, x)
    } else {
        edge_normal(x[ids[seg]], x[ids[seg + 1]]).0
    };
    Some((p[0] - q[0]) * n[0] + (p[1] - q[1]) * n[1])
}

/// Whether the point `p` with outward normal `n` (a node of the other surface) lies behind the
/// polyline `ids` (inside its body) by more than `depth_limit`: over the segments that face
/// `n` (`n . n_seg < 0`) and onto which `p` projects (`eta` in `[0, 1]`), the one nearest to
/// the line through it decides. Returns that segment and the depth `-(p - q0) . n_seg > 0`.
pub fn behind(
    ids: &[usize],
    x: &[[f64; 2]],
    p: [f64; 2],
    n: [f64; 2],
    depth_limit: f64,
) -> Option<(usize, f64)> {
    let mut nearest: Option<(usize, f64)> = None;
    for seg in 0..ids.len() - 1 {
        let (q0, q1) = (x[ids[seg]], x[ids[seg + 1]]);
        let ns = edge_normal(q0, q1).0;
        if n[0] * ns[0] + n[1] * ns[1] >= 0.0 {
            continue;
        }
        let (eta, _) = nearest_on_segment(ids, seg, p, x);
        if !(0.0..=1.0).contains(&eta) {
            continue;
        }
        let signed = (p[0] - q0[0]) * ns[0] + (p[1] - q0[1]) * ns[1];
        if nearest.is_none_or(|(_, s)| signed.abs() < s.abs()) {
            nearest = Some((seg, signed));
        }
    }
    nearest
        .filter(|&(_, signed)| -signed > depth_limit)
        .map(|(seg, signed)| (seg, -signed))
}

/// A point `inside` body A must lie on A's body side (the left) of the A polyline, whose node
/// positions are `a` in order, beside it rather than beyond its ends (see [`side`]):
/// then A has its body on its left, and with B facing it (checked when the analysis is
/// created) so has B.
///
/// # Errors
/// [`Error::InvalidInput`]: a non-finite point, one beyond the polyline's ends, or one on its
/// outward side (the A polyline reversed).
pub fn check_a_inside(a: &[[f64; 2]], inside: [f64; 2]) -> Result<()> {
    if !(inside[0].is_finite() && inside[1].is_finite()) {
        return Err(Error::InvalidInput(format!(
            "the point inside body A {inside:?} is not finite"
        )));
    }
    let ids: Vec<usize> = (0..a.len()).collect();
    match side(&ids, a, inside) {
        Some(d) if d < 0.0 => Ok(()),
        Some(_) => Err(Error::InvalidInput(format!(
            "the point {inside:?} inside body A lies on the outward side of the A polyline: \
             A has its body on its right, so it is reversed (and B with it, if they face each \
             other: the pair is back to back)"
        ))),
        None => Err(Error::InvalidInput(format!(
            "the point {inside:?} inside body A lies beyond an end of the A polyline, where \
             its side is not defined: give one beside it (the centroid of the element that \
             owns A's first segment, say)"
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A = the bottom of an upper block (left to right), B = the top of a lower block (right
    /// to left), `gap` apart; both bodies on the left of their polylines.
    fn blocks(gap: f64) -> (Vec<usize>, Vec<usize>, Vec<[f64; 2]>) {
        let mut x = Vec::new();
        for i in 0..5 {
            x.push([0.25 * i as f64, gap]);
        }
        for i in 0..5 {
            x.push([1.0 - 0.25 * i as f64 + 0.1, 0.0]);
        }
        ((0..5).collect(), (5..10).collect(), x)
    }

    #[test]
    fn facing_surfaces_are_recognised() {
        let (a, b, x) = blocks(0.1);
        let f = facing(&a, &b, &x, 1.0);
        assert_eq!((f.facing + f.touching, f.same_way, f.behind), (5, 0, 0));
        let (a, b, x) = blocks(0.0);
        assert_eq!(facing(&a, &b, &x, 1.0).touching, 5);
        let (a, b, x) = blocks(0.2);
        assert_eq!(facing(&a, &b, &x, 1.0).facing, 5);
        // touching surfaces cannot be told from back-to-back ones (both reversed)
        let (mut a, mut b, x) = blocks(0.0);
        a.reverse();
        b.reverse();
        assert_eq!(facing(&a, &b, &x, 1.0).touching, 5);
    }

    #[test]
    fn a_point_inside_the_body_lies_on_its_side() {
        let (a, _, x) = blocks(0.0);
        // A's body (the upper block) lies above it
        assert!(side(&a, &x, [0.3, 0.1]).unwrap() < 0.0);
        assert!(side(&a, &x, [0.5, 0.1]).unwrap() < 0.0);
        assert!(side(&a, &x, [0.3, -0.1]).unwrap() > 0.0);
        assert_eq!(side(&a, &x, [-0.5, 0.1]), None);
        let mut reversed = a.clone();
        reversed.reverse();
        assert!(side(&reversed, &x, [0.3, 0.1]).unwrap() > 0.0);
    }

    #[test]
    fn a_reversed_polyline_runs_the_same_way() {
        let (mut a, b, x) = blocks(0.0);
        a.reverse();
        let f = facing(&a, &b, &x, 1.0);
        assert_eq!((f.facing, f.same_way, f.example), (0, 5, Some(0)));
    }

    #[test]
    fn back_to_back_faces_lie_behind() {
        // A above B by 1: both reversed, each normal points into its own body
        let (mut a, mut b, x) = blocks(1.0);
        a.reverse();
        b.reverse();
        let f = facing(&a, &b, &x, 2.0);
        assert_eq!((f.facing, f.behind), (0, 5));
        // out of reach: not judged
        assert_eq!(facing(&a, &b, &x, 0.5), Facing::default());
    }

    #[test]
    fn a_point_through_the_surface_is_behind_it() {
        let (_, b, x) = blocks(0.0);
        let down = [0.0, -1.0];
        // A's outward normal points down; a point 1e8 below B's top is inside the lower block
        assert_eq!(behind(&b, &x, [0.5, -1e8], down, 1.0), Some((2, 1e8)));
        assert_eq!(behind(&b, &x, [0.5, -0.5], down, 1.0), None);
        // above B, or beside its ends, or with a normal that does not face B: not behind
        assert_eq!(behind(&b, &x, [0.5, 3.0], down, 1.0), None);
        assert_eq!(behind(&b, &x, [5.0, -1e8], down, 1.0), None);
        assert_eq!(behind(&b, &x, [0.5, -1e8], [0.0, 1.0], 1.0), None);
    }
}
