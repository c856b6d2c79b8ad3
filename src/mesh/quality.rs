//! Element shape measures of a mesh, for reports and mesh tests.
//!
//! Every measure is taken on the element's four *true corners*: of an `n`-node element, the
//! `n - 4` nodes with the interior angle closest to 180 degrees are its mid-side nodes and are
//! skipped (in generated transition elements their angle is 180 degrees to round-off).
//! * corner angle: interior angle of the polygon at a corner, between the directions to the
//!   previous and the next boundary node;
//! * aspect ratio: longest corner-to-corner side over the shortest one (a side through a
//!   mid-side node counts once, corner to corner);
//! * the worst element is the one with the largest corner-angle deviation from 90 degrees.

use super::Mesh;
use crate::element::MAX_NODES;
use std::fmt;

/// Shape summary of a mesh (see the module documentation for the definitions).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QualityReport {
    /// Number of elements.
    pub n_elements: usize,
    /// Smallest corner angle, degrees.
    pub min_angle_deg: f64,
    /// Largest corner angle, degrees.
    pub max_angle_deg: f64,
    /// Largest aspect ratio (longest over shortest corner-to-corner side).
    pub max_aspect: f64,
    /// Element with the largest corner-angle deviation from 90 degrees.
    pub worst_element: usize,
    /// Numbers of 4-, 5- and 6-node elements.
    pub n_by_node_count: [usize; 3],
    /// Smallest element area (shoelace; negative for a clockwise element).
    pub min_area: f64,
    /// Sum of the element areas.
    pub total_area: f64,
}

/// Corner angles, aspect ratio and area of one element polygon.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElementShape {
    /// Interior angles at the four true corners, degrees, in boundary order.
    pub corner_angles_deg: [f64; 4],
    /// Longest over shortest corner-to-corner side.
    pub aspect: f64,
    /// Shoelace area (positive when counter-clockwise).
    pub area: f64,
}

/// Shape of the element polygon `coords` (4 to [`MAX_NODES`] nodes, boundary order).
pub fn element_shape(coords: &[[f64; 2]]) -> ElementShape {
    let n = coords.len();
    assert!(
        (4..=MAX_NODES).contains(&n),
        "an element has 4 to {MAX_NODES} nodes, got {n}"
    );
    let mut angles = [0.0; MAX_NODES];
    for (i, a) in angles.iter_mut().enumerate().take(n) {
        let (p, prev, next) = (coords[i], coords[(i + n - 1) % n], coords[(i + 1) % n]);
        let (u, w) = (
            [next[0] - p[0], next[1] - p[1]],
            [prev[0] - p[0], prev[1] - p[1]],
        );
        // counter-clockwise interior angle from the direction to `next` to the one to `prev`
        let ang = (u[0] * w[1] - u[1] * w[0])
            .atan2(u[0] * w[0] + u[1] * w[1])
            .to_degrees();
        *a = if ang < 0.0 { ang + 360.0 } else { ang };
    }
    let mut by_straightness: Vec<usize> = (0..n).collect();
    by_straightness.sort_by(|&i, &j| {
        (angles[i] - 180.0)
            .abs()
            .partial_cmp(&(angles[j] - 180.0).abs())
            .expect("finite angles")
    });
    let mut corners: Vec<usize> = by_straightness[n - 4..].to_vec();
    corners.sort_unstable();
    let side = |k: usize| {
        let (a, b) = (coords[corners[k]], coords[corners[(k + 1) % 4]]);
        (b[0] - a[0]).hypot(b[1] - a[1])
    };
    let sides = [side(0), side(1), side(2), side(3)];
    let longest = sides.iter().copied().fold(0.0, f64::max);
    let shortest = sides.iter().copied().fold(f64::INFINITY, f64::min);
    let area = 0.5
        * (0..n)
            .map(|i| {
                let (a, b) = (coords[i], coords[(i + 1) % n]);
                a[0] * b[1] - a[1] * b[0]
            })
            .sum::<f64>();
    ElementShape {
        corner_angles_deg: [0, 1, 2, 3].map(|k| angles[corners[k]]),
        aspect: longest / shortest,
        area,
    }
}

/// Shape report of the whole mesh.
pub fn quality(mesh: &Mesh) -> QualityReport {
    let mut report = QualityReport {
        n_elements: mesh.n_elements(),
        min_angle_deg: f64::INFINITY,
        max_angle_deg: f64::NEG_INFINITY,
        max_aspect: 0.0,
        worst_element: 0,
        n_by_node_count: [0; 3],
        min_area: f64::INFINITY,
        total_area: 0.0,
    };
    let mut worst = f64::NEG_INFINITY;
    let mut buf = [[0.0; 2]; MAX_NODES];
    for e in 0..mesh.n_elements() {
        let n = mesh.element_coords(e, &mut buf);
        let shape = element_shape(&buf[..n]);
        report.n_by_node_count[n - 4] += 1;
        for a in shape.corner_angles_deg {
            report.min_angle_deg = report.min_angle_deg.min(a);
            report.max_angle_deg = report.max_angle_deg.max(a);
            if (a - 90.0).abs() > worst {
                worst = (a - 90.0).abs();
                report.worst_element = e;
            }
        }
        report.max_aspect = report.max_aspect.max(shape.aspect);
        report.min_area = report.min_area.min(shape.area);
        report.total_area += shape.area;
    }
    report
}

impl fmt::Display for QualityReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [n4, n5, n6] = self.n_by_node_count;
        write!(
            f,
            "{} elements ({n4} 4-node, {n5} 5-node, {n6} 6-node), corner angles {:.1} to {:.1} deg, \
             max aspect {:.2}, worst element {}, area {:.6e} (min {:.3e})",
            self.n_elements,
            self.min_angle_deg,
            self.max_angle_deg,
            self.max_aspect,
            self.worst_element,
            self.total_area,
            self.min_area
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transition_square_has_right_angles() {
        let coords = [
            [0.0, 0.0],
            [1.0, 0.0],
            [2.0, 0.0],
            [2.0, 2.0],
            [1.0, 2.0],
            [0.0, 2.0],
        ];
        let s = element_shape(&coords);
        for a in s.corner_angles_deg {
            assert!((a - 90.0).abs() < 1e-12, "{a}");
        }
        assert!((s.aspect - 1.0).abs() < 1e-15);
        assert!((s.area - 4.0).abs() < 1e-15);
    }

    #[test]
    fn report_counts_and_display() {
        let mut mesh = Mesh::new();
        for p in [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]] {
            mesh.push_node(p);
        }
        mesh.push_element(&[0, 1, 2, 3, 4], 0);
        let r = quality(&mesh);
        assert_eq!(r.n_by_node_count, [0, 1, 0]);
        assert!((r.max_aspect - 2.0).abs() < 1e-15 && (r.total_area - 2.0).abs() < 1e-15);
        assert!(r.to_string().starts_with("1 elements (0 4-node, 1 5-node"));
    }
}
