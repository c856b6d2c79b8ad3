//! The mortar integrals assembled over two surfaces of brick faces, per node.

use super::clip::{AuxPlane, SNAP, polygon_area};
use super::mortar::face_pair_on;
use super::{Quad, face_mass, pair_faces};
use crate::error::{Error, Result};
use std::collections::BTreeMap;

/// Relative shortfall (or excess) of a node's covered area below which it counts as covered
/// exactly once: a hundred times [`SNAP`], as clipping moves a polygon's vertices by up to
/// `SNAP h` (snapped to a corner, kept on an edge's line, merged, dropped), each move changing
/// its area by up to `SNAP h` times an edge.
pub const COVERED: f64 = 100.0 * SNAP;

/// The projected areas of an A node's support, each A face's on its own auxiliary plane
/// (where its overlaps with B lie): exact polygon areas, so that a face B's faces tile
/// projects to exactly its covered area, whatever its shape (unlike the weights, whose
/// covered part is integrated by the triangle rule through the inverse bilinear map).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SupportArea {
    /// The sum of its faces' projected areas.
    pub area: f64,
    /// The sum of their overlap polygons' areas with B's faces.
    pub covered: f64,
    /// The largest ratio of a face's covered area to its area over the node's faces: 1 for
    /// faces B covers once, 2 under two layers of B.
    pub layers: f64,
}

/// One side's contact surface: node positions and faces (4 node ids indexing `x`, in
/// [`crate::solid::geometry::FACES`] order, outward by the right-hand rule).
#[derive(Debug, Clone, Copy)]
pub struct SurfaceFaces<'a> {
    /// Positions of the nodes the faces use.
    pub x: &'a [[f64; 3]],
    /// The faces.
    pub faces: &'a [[usize; 4]],
}

impl SurfaceFaces<'_> {
    /// The corners of every face; an error names a face using a node id out of range.
    pub(super) fn corners(&self, side: &str) -> Result<Vec<Quad>> {
        let n = self.x.len();
        self.faces
            .iter()
            .enumerate()
            .map(|(i, f)| match f.iter().find(|&&k| k >= n) {
                Some(k) => Err(Error::InvalidInput(format!(
                    "{side} face {i} uses node {k} but there are {n} nodes"
                ))),
                None => Ok(f.map(|k| self.x[k])),
            })
            .collect()
    }
}

/// The mortar integrals of surface A (the multiplier side) against surface B, by node ids:
/// sums over the overlapping face pairs of [`face_pair`](super::face_pair) and over A's faces
/// of [`face_mass`].
///
/// `d` is summed over the **covered** parts (Puso and Laursen's segment-wise `D`), so that for
/// a fully covered A node `sum_j d[k, j] = covered[k] = sum_b m[k, b]` to round-off whatever
/// the faces' shapes: a uniform pressure `p` gives the same resultant on A (`sum_j d_kj p`) as
/// B transmits (`sum_b m_kb p`), the discrete patch-test condition. For a fully covered node
/// it equals the whole-support `F^A` of the plane code up to the triangle rule's error (none on
/// flat parallelograms).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SurfaceMortar {
    /// `D_kj` (A node, A node) over the covered parts.
    pub d: BTreeMap<(usize, usize), f64>,
    /// `M_kb` (A node, B node).
    pub m: BTreeMap<(usize, usize), f64>,
    /// `R_k = integral N_k (x^A - x^B) dA` per A node (covered parts).
    pub mismatch: BTreeMap<usize, [f64; 3]>,
    /// `g~_k = integral N_k g dA` per A node (covered parts), each face pair's gap `g` measured
    /// along its A face's auxiliary normal `n_0` ([`super::FacePair::gap`]).
    pub distance: BTreeMap<usize, f64>,
    /// `integral N_k dA` over the whole support of A node `k`.
    pub weight: BTreeMap<usize, f64>,
    /// `integral N_k dA` over the covered part of its support.
    pub covered: BTreeMap<usize, f64>,
    /// The projected areas of the node's support, whole and covered.
    pub support: BTreeMap<usize, SupportArea>,
    /// The number of overlapping face pairs.
    pub pairs: usize,
}

impl SurfaceMortar {
    /// Assemble over the face pairs [`pair_faces`] finds within `search`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a node id out of range, or a failing face or face pair
    /// (the message names the faces by their index in `a.faces`, `b.faces`).
    pub fn new(a: SurfaceFaces, b: SurfaceFaces, search: f64) -> Result<Self> {
        Self::on_planes(a, b, search, |_, q| AuxPlane::of(q))
    }

    /// [`new`](Self::new) with A face `i` (corners `q`) projected on `plane(i, q)` instead of
    /// its own auxiliary plane.
    ///
    /// # Errors
    /// As [`new`](Self::new).
    pub fn on_planes(
        a: SurfaceFaces,
        b: SurfaceFaces,
        search: f64,
        plane: impl Fn(usize, &Quad) -> AuxPlane,
    ) -> Result<Self> {
        let (qa, qb) = (a.corners("A")?, b.corners("B")?);
        let mut out = SurfaceMortar::default();
        let at = |i: usize, e: Error, b: &str| match e {
            Error::InvalidInput(msg) => Error::InvalidInput(format!("A face {i}{b}: {msg}")),
            other => other,
        };
        let planes: Vec<AuxPlane> = qa.iter().enumerate().map(|(i, q)| plane(i, q)).collect();
        let mut area = Vec::with_capacity(qa.len());
        for (i, (quad, ids)) in qa.iter().zip(a.faces).enumerate() {
            let mass = face_mass(quad).map_err(|e| at(i, e, ""))?;
            for (k, &node) in ids.iter().enumerate() {
                *out.weight.entry(node).or_default() += mass.weight[k];
                out.covered.entry(node).or_default();
            }
            area.push(polygon_area(&quad.map(|p| planes[i].project(p))));
        }
        let mut covered = vec![0.0; qa.len()];
        for (i, j) in pair_faces(&qa, &qb, search)? {
            let pair = face_pair_on(&qa[i], &qb[j], planes[i])
                .map_err(|e| at(i, e, &format!(", B face {j}")))?;
            let Some(pair) = pair else { continue };
            out.pairs += 1;
            covered[i] += pair.overlap.area;
            let (ia, ib) = (a.faces[i], b.faces[j]);
            for (k, &row) in ia.iter().enumerate() {
                *out.covered.entry(row).or_default() += pair.weight[k];
                *out.distance.entry(row).or_default() += pair.gap[k];
                let r = out.mismatch.entry(row).or_default();
                for (rc, pc) in r.iter_mut().zip(pair.mismatch[k]) {
                    *rc += pc;
                }
                for l in 0..4 {
                    *out.d.entry((row, ia[l])).or_default() += pair.d[k][l];
                    *out.m.entry((row, ib[l])).or_default() += pair.m[k][l];
                }
            }
        }
        for ((ids, &area), &covered) in a.faces.iter().zip(&area).zip(&covered) {
            for &node in ids {
                let s = out.support.entry(node).or_default();
                s.area += area;
                s.covered += covered;
                s.layers = s.layers.max(covered / area);
            }
        }
        Ok(out)
    }

    /// Coverage of A node `k`: the covered projected area of its support over its projected
    /// area ([`SupportArea`]), in `[0, 1]` to round-off for a node covered at most once (0 for
    /// a node of no A face); the 3D twin of the plane code's covered length over the
    /// support's.
    pub fn coverage(&self, k: usize) -> f64 {
        match self.support.get(&k) {
            Some(s) if s.area > 0.0 => s.covered / s.area,
            _ => 0.0,
        }
    }

    /// The coverage of A node `k` snapped to exactly 1 within [`COVERED`].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] if a face of the node is covered more than `1 + COVERED` times
    /// ([`SupportArea::layers`]): B's faces overlap each other over it, seen along A's
    /// normal, and its `R_k` would count B twice.
    pub fn covered_once(&self, k: usize) -> Result<f64> {
        let layers = self.support.get(&k).map_or(0.0, |s| s.layers);
        if layers > 1.0 + COVERED {
            return Err(Error::InvalidInput(format!(
                "A node {k} is covered {layers:.6} times over: B's faces overlap each other \
                 over its support"
            )));
        }
        let c = self.coverage(k);
        Ok(if c >= 1.0 - COVERED { 1.0 } else { c })
    }

    /// Check that every node of `nodes` (active A nodes) is covered exactly once, to
    /// [`COVERED`] ([`covered_once`](Self::covered_once)): an active node only partly over B
    /// would transmit its pressure over part of its support (a silent hole in the contact
    /// zone), one covered more than once would transmit it twice.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the first node that is not.
    pub fn require_covered(&self, nodes: &[usize]) -> Result<()> {
        for &k in nodes {
            let c = self.covered_once(k)?;
            if c < 1.0 {
                return Err(Error::InvalidInput(format!(
                    "A node {k} is active but only {c:.6} of its support is over B"
                )));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solid::geometry::FACES;
    use crate::solid::mesh::SolidMesh;

    /// The boundary faces of `mesh` on the plane `z = z` (node ids of the mesh).
    fn faces_at(mesh: &SolidMesh, z: f64) -> Vec<[usize; 4]> {
        mesh.faces_where(|p| (p[2] - z).abs() < 1e-12)
            .into_iter()
            .map(|(e, f)| FACES[f].map(|k| mesh.elements[e][k]))
            .collect()
    }

    /// A: the top of a one-layer block over `[0, 1]^2` of `na x na` bricks (`z` from 0 to 1).
    /// B: the bottom of a one-layer block of `nb x nb` bricks over `[0, 1]^2` mapped by
    /// `place` (then raised by the gap 0.01 to z = 1.01).
    fn meshes(na: usize, nb: usize, place: impl Fn([f64; 2]) -> [f64; 2]) -> [SolidMesh; 2] {
        let a = SolidMesh::uniform([1.0, 1.0, 1.0], [na, na, 1]);
        let b = SolidMesh::uniform([1.0, 1.0, 1.0], [nb, nb, 1]).map(|p| {
            let q = place([p[0], p[1]]);
            [q[0], q[1], p[2] + 1.01]
        });
        [a, b]
    }

    fn mortar(m: &[SolidMesh; 2]) -> (SurfaceMortar, Vec<usize>) {
        let (fa, fb) = (faces_at(&m[0], 1.0), faces_at(&m[1], 1.01));
        let sa = SurfaceFaces {
            x: &m[0].nodes,
            faces: &fa,
        };
        let sb = SurfaceFaces {
            x: &m[1].nodes,
            faces: &fb,
        };
        let out = SurfaceMortar::new(sa, sb, 0.05).unwrap();
        let nodes = m[0].nodes_where(|p| p[2] == 1.0);
        (out, nodes)
    }

    /// The patch-test condition at every A node (all fully covered): `sum_b M_kb = sum_j D_kj`
    /// to 1e-10, both equal to the whole-face weight; the weighted mismatch is the gap 0.01
    /// times the weight along `-z`; A's total area is transmitted.
    fn check_patch(what: &str, m: &SurfaceMortar, nodes: &[usize]) {
        m.require_covered(nodes).unwrap();
        let mut worst: f64 = 0.0;
        for &k in nodes {
            let w = m.weight[&k];
            let sum_m: f64 = m.m.range((k, 0)..(k + 1, 0)).map(|(_, v)| v).sum();
            let sum_d: f64 = m.d.range((k, 0)..(k + 1, 0)).map(|(_, v)| v).sum();
            worst = worst.max((sum_m - sum_d).abs() / w);
            assert!((sum_m - sum_d).abs() <= 1e-10 * w, "{what}: node {k}");
            assert!((sum_d - w).abs() <= 1e-12 * w, "{what}: node {k}");
            let r = m.mismatch[&k];
            assert!((r[2] + 0.01 * w).abs() <= 1e-12 * w, "{what}: node {k} gap");
            assert!(
                r[0].abs().max(r[1].abs()) <= 1e-12 * w,
                "{what}: node {k} tangential"
            );
        }
        eprintln!(
            "{what}: {} pairs, worst |sum M - sum D| / w = {worst:.1e}",
            m.pairs
        );
        let total: f64 = m.m.values().sum();
        assert!((total - 1.0).abs() < 1e-12, "{what}: total {total}");
    }

    /// B's nodal forces from a uniform pressure on A, `sum_k M_kb p`, against the consistent
    /// forces of that pressure on B's own faces (B exactly under A).
    fn check_b_forces(what: &str, m: &SurfaceMortar, b: &SolidMesh) {
        let mut consistent: BTreeMap<usize, f64> = BTreeMap::new();
        for (e, f) in b.faces_where(|p| (p[2] - 1.01).abs() < 1e-12) {
            for (node, force) in b.face_forces(e, f, |_, n| n) {
                *consistent.entry(node).or_default() -= force[2];
            }
        }
        let mut transmitted: BTreeMap<usize, f64> = BTreeMap::new();
        for (&(_, node), v) in &m.m {
            *transmitted.entry(node).or_default() += v;
        }
        for (node, f) in &consistent {
            let t = transmitted.get(node).copied().unwrap_or(0.0);
            assert!(
                (t - f).abs() <= 1e-10 * f,
                "{what}: B node {node}: {t} vs {f}"
            );
        }
    }

    #[test]
    fn conforming_finer_and_coarser_meshes_pass_the_patch_test() {
        for (what, na, nb) in [("conforming", 3, 3), ("A finer", 4, 3), ("A coarser", 3, 5)] {
            let m = meshes(na, nb, |p| p);
            let (out, nodes) = mortar(&m);
            check_patch(what, &out, &nodes);
            check_b_forces(what, &out, &m[1]);
        }
    }

    #[test]
    fn offset_and_rotated_meshes_pass_the_patch_test() {
        // B larger than A (1.6 times), offset by a third of its face in both directions, or
        // rotated 15 and 45 degrees about the vertical through A's centre
        let offset = |p: [f64; 2]| [1.6 * p[0] - 0.3 + 0.32 / 3.0, 1.6 * p[1] - 0.3 + 0.32 / 3.0];
        let rotated = |deg: f64| {
            move |p: [f64; 2]| {
                let (sn, cs) = f64::to_radians(deg).sin_cos();
                let (u, v) = (1.6 * (p[0] - 0.5), 1.6 * (p[1] - 0.5));
                [0.5 + cs * u - sn * v, 0.5 + sn * u + cs * v]
            }
        };
        for (na, nb) in [(4, 5), (6, 3)] {
            let m = meshes(na, nb, offset);
            let (out, nodes) = mortar(&m);
            check_patch("offset", &out, &nodes);
            for deg in [15.0, 45.0] {
                let m = meshes(na, nb, rotated(deg));
                let (out, nodes) = mortar(&m);
                check_patch(&format!("rotated {deg}"), &out, &nodes);
            }
        }
    }

    #[test]
    fn partly_covered_nodes_are_reported() {
        // B covers x >= 0.5 of A (4 x 4 faces of width 0.25)
        let m = meshes(4, 2, |p| [0.5 + p[0], 2.0 * p[1] - 0.5]);
        let (out, nodes) = mortar(&m);
        for &k in &nodes {
            let x = m[0].nodes[k][0];
            let expected = if x < 0.3 {
                0.0
            } else if x < 0.6 {
                0.5
            } else {
                1.0
            };
            assert!(
                (out.coverage(k) - expected).abs() < 1e-12,
                "node at x = {x}"
            );
        }
        let covered: Vec<usize> = nodes
            .iter()
            .copied()
            .filter(|&k| m[0].nodes[k][0] > 0.6)
            .collect();
        out.require_covered(&covered).unwrap();
        let half = nodes
            .iter()
            .copied()
            .find(|&k| m[0].nodes[k][0] == 0.5)
            .unwrap();
        let err = out.require_covered(&[covered[0], half]).unwrap_err();
        assert!(
            err.to_string().contains(&format!("A node {half} ")),
            "{err}"
        );
    }

    #[test]
    fn nodes_covered_twice_are_reported() {
        // B's faces listed twice: every A node is covered twice over
        let m = meshes(3, 2, |p| [1.2 * p[0] - 0.1, 1.2 * p[1] - 0.1]);
        let fb = faces_at(&m[1], 1.01);
        let twice: Vec<[usize; 4]> = fb.iter().chain(&fb).copied().collect();
        let fa = faces_at(&m[0], 1.0);
        let sa = SurfaceFaces {
            x: &m[0].nodes,
            faces: &fa,
        };
        let once = SurfaceFaces {
            x: &m[1].nodes,
            faces: &fb,
        };
        let nodes = m[0].nodes_where(|p| p[2] == 1.0);
        SurfaceMortar::new(sa, once, 0.05)
            .unwrap()
            .require_covered(&nodes)
            .unwrap();
        let out = SurfaceMortar::new(
            sa,
            SurfaceFaces {
                x: &m[1].nodes,
                faces: &twice,
            },
            0.05,
        )
        .unwrap();
        assert!((out.coverage(nodes[0]) - 2.0).abs() < 1e-12);
        let err = out.require_covered(&nodes).unwrap_err();
        assert!(
            err.to_string()
                .contains(&format!("A node {} is covered 2.000000 times", nodes[0])),
            "{err}"
        );
    }

    /// A flat B grid 0.2 above `z = 0`, facing down, with node columns at `xs` and rows at
    /// `ys`: its nodes and faces.
    fn b_grid(xs: &[f64], ys: &[f64]) -> (Vec<[f64; 3]>, Vec<[usize; 4]>) {
        let x = ys
            .iter()
            .flat_map(|&y| xs.iter().map(move |&x| [x, y, 0.2]))
            .collect();
        let n = xs.len();
        let faces = (0..ys.len() - 1)
            .flat_map(|j| (0..n - 1).map(move |i| (i, j)))
            .map(|(i, j)| {
                let k = j * n + i;
                [k + n, k + n + 1, k + 1, k]
            })
            .collect();
        (x, faces)
    }

    #[test]
    fn a_distorted_face_tiled_by_b_is_covered_exactly_once() {
        // a trapezoid-like A face with one corner lifted (warped), under 3 x 2 B faces whose
        // edges cut it unevenly; then the same B faces twice (two layers)
        let xa = [
            [0.0, 0.0, 0.0],
            [1.1, 0.05, 0.0],
            [0.95, 0.9, 0.03],
            [-0.1, 1.0, 0.0],
        ];
        let fa = [[0, 1, 2, 3]];
        let (xb, fb) = b_grid(&[-0.5, 0.3, 0.7, 1.6], &[-0.4, 0.45, 1.5]);
        let sa = SurfaceFaces { x: &xa, faces: &fa };
        let once = SurfaceMortar::new(sa, SurfaceFaces { x: &xb, faces: &fb }, 0.5).unwrap();
        assert_eq!(once.pairs, 6);
        let mut worst: f64 = 0.0;
        for k in 0..4 {
            assert!((once.coverage(k) - 1.0).abs() < 1e-14, "node {k}");
            assert_eq!(once.covered_once(k).unwrap(), 1.0);
            worst = worst.max((once.covered[&k] / once.weight[&k] - 1.0).abs());
        }
        // the covered and whole weights differ by the triangle rule's error, more than the
        // round-off a judgement by weights would need
        eprintln!("distorted face: covered / whole weight - 1 up to {worst:.1e}");
        assert!(worst > 1e-10 && worst < 1e-6, "{worst:e}");
        once.require_covered(&[0, 1, 2, 3]).unwrap();

        let twice: Vec<[usize; 4]> = fb.iter().chain(&fb).copied().collect();
        let out = SurfaceMortar::new(
            sa,
            SurfaceFaces {
                x: &xb,
                faces: &twice,
            },
            0.5,
        )
        .unwrap();
        assert!((out.coverage(0) - 2.0).abs() < 1e-14);
        let err = out.require_covered(&[0]).unwrap_err();
        assert!(
            err.to_string()
                .contains("A node 0 is covered 2.000000 times"),
            "{err}"
        );
    }

    #[test]
    fn bad_node_ids_and_faces_are_errors() {
        let x = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        let good = [[0, 1, 2, 3]];
        let out_of_range = [[0, 1, 2, 4]];
        let collapsed = [[0, 1, 1, 3]];
        let s = |faces| SurfaceFaces { x: &x, faces };
        let flipped = [[3, 2, 1, 0]];
        assert!(SurfaceMortar::new(s(&good), s(&out_of_range), 0.1).is_err());
        let err = SurfaceMortar::new(s(&collapsed), s(&flipped), 0.1).unwrap_err();
        assert!(err.to_string().contains("A face 0"), "{err}");
        assert_eq!(
            SurfaceMortar::new(s(&good), s(&flipped), 0.1)
                .unwrap()
                .pairs,
            1
        );
    }
}
