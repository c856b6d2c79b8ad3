//! The plane and axisymmetric contact geometry: a pair is two polylines (node chains of the
//! bodies' boundaries, each with its body on the left).
//!
//! * [`mortar`]: the contact-element kernels of one pair at given positions: nodal frames,
//!   weights, the mortar matrices `F^A` and `F^B`, the weighted gap `R_C`, coverage and the
//!   coupling rows.
//! * [`facing`]: the orientation check of a pair (do A and B face each other) and the sides
//!   of points.

pub mod facing;
pub mod mortar;

use super::geometry::{
    Adjacency, BNodeDistance, ContactGeometry, ContactSurface, Facing, Unresolved,
};
use super::space::Vector;
use crate::element::geometry::edge_normal;
use crate::error::Result;
use mortar::{SegmentInteriors, SurfaceMeasure};

/// The plane and axisymmetric geometry of one contact pair: the multiplier-side polyline A and
/// the opposite polyline B (node ids, each with its body on the left), A's surface measure,
/// and under small kinematics the B nodes inside each A segment in the reference
/// configuration.
#[derive(Debug, Clone)]
pub struct PlaneGeometry {
    a: Vec<usize>,
    b: Vec<usize>,
    measure: SurfaceMeasure,
    interiors: Option<SegmentInteriors>,
    /// A as a chain.
    adjacency: Adjacency,
}

impl PlaneGeometry {
    /// The pair of polylines `a`, `b` with A's surface measure `measure`.
    pub fn new(a: Vec<usize>, b: Vec<usize>, measure: SurfaceMeasure) -> Self {
        PlaneGeometry {
            adjacency: Adjacency::chain(a.len()),
            a,
            b,
            measure,
            interiors: None,
        }
    }

    /// A's surface measure.
    pub fn measure(&self) -> SurfaceMeasure {
        self.measure
    }
}

/// The flat positions `x` (2 per node) as points, without copying.
fn points(x: &[f64]) -> &[[f64; 2]] {
    let (points, rest) = x.as_chunks::<2>();
    debug_assert!(rest.is_empty(), "plane positions have 2 values per node");
    points
}

/// `|q - p|`.
fn distance(p: [f64; 2], q: [f64; 2]) -> f64 {
    (q[0] - p[0]).hypot(q[1] - p[1])
}

impl ContactGeometry for PlaneGeometry {
    fn dim(&self) -> usize {
        2
    }

    fn a_nodes(&self) -> &[usize] {
        &self.a
    }

    /// A's chain: `k - 1` and `k + 1`, its ends the edge.
    fn adjacency(&self) -> &Adjacency {
        &self.adjacency
    }

    fn evaluate_into(&self, x: &[f64], reach: f64, out: &mut ContactSurface) -> Result<()> {
        mortar::evaluate_into(&self.a, &self.b, points(x), reach, self.measure, out)
    }

    /// The mean A segment length.
    fn mean_size(&self, x: &[f64]) -> f64 {
        let x = points(x);
        let total: f64 = self.a.windows(2).map(|w| distance(x[w[0]], x[w[1]])).sum();
        total / (self.a.len().max(2) - 1) as f64
    }

    /// A node on the axis in axisymmetry (`|r|` within round-off of its segments' length).
    fn frictionless_at(&self, k: usize, x: &[f64]) -> bool {
        self.measure == SurfaceMeasure::Axisymmetric && mortar::on_axis(&self.a, k, points(x))
    }

    fn facing(&self, x: &[f64], reach: f64) -> Facing {
        facing::facing(&self.a, &self.b, points(x), reach)
    }

    fn check_inside(&self, x: &[f64], point: &Vector) -> Result<()> {
        let x = points(x);
        let a: Vec<[f64; 2]> = self.a.iter().map(|&n| x[n]).collect();
        facing::check_a_inside(&a, [point[0], point[1]])
    }

    /// Central difference over the covered neighbours along A, one-sided at an end.
    fn gap_slope(&self, surface: &ContactSurface, k: usize, x: &[f64]) -> f64 {
        let x = points(x);
        let nodes = &surface.nodes;
        let covered = |i: usize| nodes[i].normal_gap.is_finite();
        let lo = if k > 0 && covered(k - 1) { k - 1 } else { k };
        let hi = if k + 1 < nodes.len() && covered(k + 1) {
            k + 1
        } else {
            k
        };
        if lo == hi {
            return 0.0;
        }
        let (p, q) = (x[nodes[lo].node], x[nodes[hi].node]);
        ((nodes[hi].normal_gap - nodes[lo].normal_gap) / distance(p, q)).abs()
    }

    fn freeze_b_nodes(&mut self, x: &[f64]) {
        self.interiors = Some(SegmentInteriors::new(&self.a, &self.b, points(x)));
    }

    /// Over A segments whose two nodes are open: the B nodes projecting strictly inside the
    /// segment (more than `1e-3` of its length from either end), closing the nearer end.
    fn b_node_distances(&self, open: &[bool], x: &[f64], xg: &[f64]) -> Vec<BNodeDistance> {
        let (x, xg) = (points(x), points(xg));
        let mut out = Vec::new();
        for (k, w) in self.a.windows(2).enumerate() {
            if !(open[k] && open[k + 1]) {
                continue;
            }
            let (s0, s1) = (xg[w[0]], xg[w[1]]);
            let (n, _) = edge_normal(s0, s1);
            // current segment end points (equal to s0, s1 under finite kinematics)
            let (c0, c1) = (x[w[0]], x[w[1]]);
            // under small kinematics the B nodes inside each segment were found once, in the
            // reference configuration
            let candidates = match &self.interiors {
                Some(interiors) => interiors.segment(k),
                None => &self.b[..],
            };
            for &j in candidates {
                let (xi, inside) = mortar::interior_parameter(s0, s1, xg[j]);
                if !inside {
                    continue;
                }
                let hit = [c0[0] + xi * (c1[0] - c0[0]), c0[1] + xi * (c1[1] - c0[1])];
                let g = (x[j][0] - hit[0]) * n[0] + (x[j][1] - hit[1]) * n[1];
                out.push(BNodeDistance {
                    node: j,
                    element: vec![k, k + 1],
                    nearest: if xi < 0.5 { k } else { k + 1 },
                    distance: g,
                });
            }
        }
        out
    }

    /// The rotated chord of B's neighbours of node `i` (of its one segment at an end).
    fn b_node_normal(&self, i: usize, x: &[f64]) -> Vector {
        let b = &self.b;
        let (prev, next) = (b[i.saturating_sub(1)], b[(i + 1).min(b.len() - 1)]);
        let x = points(x);
        edge_normal(x[prev], x[next]).0.into()
    }

    /// Against every B segment ([`facing::behind`]), the A node with its nodal normal.
    fn behind(&self, k: usize, x: &[f64], limit: f64) -> Option<(Vec<usize>, f64)> {
        let x = points(x);
        let n = facing::node_normal(&self.a, k, x);
        facing::behind(&self.b, x, x[self.a[k]], n, limit)
            .map(|(seg, depth)| (vec![self.b[seg], self.b[seg + 1]], depth))
    }

    /// The segments of A and of B, each measured by the smaller of its current and reference
    /// lengths.
    fn unresolved(&self, x: &[f64], reference: &[f64], round_off: f64) -> Option<Unresolved> {
        let (x, reference) = (points(x), points(reference));
        let moved = |n: usize| distance(reference[n], x[n]);
        for ids in [&self.a, &self.b] {
            for w in ids.windows(2) {
                let length = |x: &[[f64; 2]]| distance(x[w[0]], x[w[1]]);
                let motion = moved(w[0]).max(moved(w[1]));
                if length(x).min(length(reference)) <= round_off * motion {
                    let node = if moved(w[0]) >= moved(w[1]) {
                        w[0]
                    } else {
                        w[1]
                    };
                    return Some(Unresolved {
                        node,
                        motion,
                        length: length(reference),
                    });
                }
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A flat A on `y = 0` at `x = 2, 1, 0` (right to left: its body below, `n = +y`) and a
    /// flat B on `y = -0.1` at `x = -0.5, 0.75, 2.5` (left to right: its body above), so A
    /// penetrates B by 0.1 everywhere; positions flat, A's nodes 0..3, B's 3..6.
    fn pair() -> (PlaneGeometry, Vec<f64>) {
        let x = vec![
            2.0, 0.0, 1.0, 0.0, 0.0, 0.0, -0.5, -0.1, 0.75, -0.1, 2.5, -0.1,
        ];
        let g = PlaneGeometry::new(vec![0, 1, 2], vec![3, 4, 5], SurfaceMeasure::default());
        (g, x)
    }

    /// Through the seam, over flat positions: the evaluation is the kernel's over points, the
    /// mean size is the mean segment length, the point inside A lies below it.
    #[test]
    fn the_seam_is_the_plane_kernels() {
        let (g, x) = pair();
        let geometry: &dyn ContactGeometry = &g;
        let direct =
            mortar::evaluate(&[0, 1, 2], &[3, 4, 5], points(&x), 1.0, g.measure()).unwrap();
        assert_eq!(geometry.evaluate(&x, 1.0).unwrap().nodes, direct.nodes);
        assert_eq!(geometry.dim(), 2);
        assert_eq!(geometry.mean_size(&x), 1.0);
        assert!(!geometry.frictionless_at(2, &x));
        assert!(geometry.check_inside(&x, &Vector::plane(1.0, -0.5)).is_ok());
        assert!(geometry.check_inside(&x, &Vector::plane(1.0, 0.5)).is_err());
        assert_eq!(
            geometry.b_node_normal(1, &x),
            Vector::plane(0.0, -1.0),
            "B's outward normal points into A"
        );
    }

    /// The B node at `x = 0.75` projects inside A's second segment (`1 -> 0`, at a quarter of
    /// it), penetrates by 0.1 and closes A node 1; with node 1 closed nothing is checked.
    /// A node 1 lies 0.1 behind B's second segment; round-off of a motion of `1e20` hides
    /// A's unit segments.
    #[test]
    fn b_nodes_passing_through_and_resolution() {
        let (mut g, x) = pair();
        for frozen in [false, true] {
            if frozen {
                g.freeze_b_nodes(&x);
            }
            let found = g.b_node_distances(&[true; 3], &x, &x);
            assert_eq!(found.len(), 1);
            let d = &found[0];
            assert_eq!(
                (d.node, d.element.as_slice(), d.nearest),
                (4, &[1, 2][..], 1)
            );
            assert!((d.distance + 0.1).abs() < 1e-15, "{}", d.distance);
            assert!(g.b_node_distances(&[true, false, true], &x, &x).is_empty());
        }
        let (element, depth) = g.behind(1, &x, 0.05).unwrap();
        assert_eq!(element, vec![4, 5]);
        assert!((depth - 0.1).abs() < 1e-15, "{depth}");
        assert_eq!(g.behind(1, &x, 0.2), None);
        assert_eq!(g.unresolved(&x, &x, 1e-14), None);
        let mut moved = x.clone();
        moved[0] += 1e20;
        let u = g.unresolved(&moved, &x, 1e-14).unwrap();
        assert_eq!((u.node, u.motion, u.length), (0, 1e20, 1.0));
    }
}
