//! The 3D contact geometry of a pair of brick-face surfaces: [`FaceGeometry`], the sibling of
//! the plane and axisymmetric [`PlaneGeometry`](crate::contact::plane::PlaneGeometry) behind
//! the [`ContactGeometry`] seam (design document `docs/design/3d-contact.md`).
//!
//! Positions are flat, 3 values per node. A pair is A's faces (the multiplier side) and B's
//! faces, 4 node ids each in [`crate::solid::geometry::FACES`] order (outward); the conventions
//! are the [face kernel's](super). Per A node `k` (docs/method.md, "Contact surfaces and
//! contact elements"; the quantities of [`ContactNode`]):
//! * `frame`: the nodal frame of [`SurfaceFrames`] (normal `n_k` the direction of
//!   `integral N_k n dA`, tangents from the pair's reference direction); a tangent dropped by a
//!   symmetry plane is **zero** in the [`Frame`] ([`Frame::is_dropped`]);
//! * `weight = integral N_k dA` over the whole support, `covered_weight` over the part whose
//!   projection along its A face's auxiliary normal meets a facing B face, `coverage` the
//!   ratio of that part's projected area to the support's
//!   ([`SurfaceMortar::covered_once`]: exact polygon areas, snapped to exactly 1 within
//!   [`COVERED`](super::surface::COVERED));
//! * `gap = R_k = integral N_k (x^A - x^B) dA` (covered part), `normal_gap = -n_k . R_k /
//!   covered_weight`, `mean_distance = integral N_k g dA / covered_weight` (`g` along each A
//!   face's own auxiliary normal);
//! * the coupling row `c_kj = +D_kj` at A nodes, `-M_kj` at B nodes ([`SurfaceMortar`]).
//!   `D` is the **segment-wise** one, summed over the covered parts (Puso and Laursen), so
//!   that `sum_j c_kj = covered_weight - covered_weight = 0` to round-off for every node,
//!   whatever the faces' shapes: a rigid translation `u` of both bodies leaves `R_k`
//!   unchanged (the patch test). For a fully covered node (the only kind the active set may
//!   activate) it is the plane code's whole-support `F^A` up to the triangle rule's error
//!   (none on flat parallelograms); for a partly covered node it is the covered part only.
//!
//! A node on a symmetry plane has the normal of the mirrored model (in the plane) and the
//! tangent along the plane's normal dropped; on two planes both are dropped and the node is
//! frictionless ([`ContactGeometry::frictionless_at`]). The 3D contact analysis of the brick
//! model builds one per pair (`ContactAnalysis::solid`, `iteration/solid.rs`).

use super::clip::{AuxPlane, check_face, point, v3};
use super::mortar::inverse_bilinear;
use super::surface::{SurfaceFaces, SurfaceMortar};
use super::topology::{check_surface, edges};
use super::{CORNERS, Quad, SurfaceFrames, SymmetryPlane};
use crate::contact::geometry::{
    Adjacency, BNodeDistance, ContactGeometry, ContactNode, ContactSurface, Facing, FacingTally,
    Unresolved,
};
use crate::contact::space::{Frame, Vector};
use crate::error::{Error, Result};
use nalgebra::{Vector2, Vector3};
use std::collections::{BTreeMap, BTreeSet};

/// Parameter tolerance within which a point projects onto a face (`|s|, |t| <= 1 + INSIDE`).
const INSIDE: f64 = 1e-10;

/// The geometry of one 3D contact pair: A's and B's faces, A's and B's nodes (sorted), the
/// reference direction of A's tangent frames (fixed once, at the positions given to
/// [`FaceGeometry::new`]), the symmetry planes, and what the reference configuration fixes.
#[derive(Debug, Clone)]
pub struct FaceGeometry {
    a_faces: Vec<[usize; 4]>,
    b_faces: Vec<[usize; 4]>,
    a: Vec<usize>,
    b: Vec<usize>,
    reference: [f64; 3],
    symmetry: Vec<SymmetryPlane>,
    /// Per A node (index into A): its tangents dropped by symmetry at the reference positions.
    dropped: Vec<[bool; 2]>,
    /// A's faces around its nodes, neighbours and free edges.
    topology: Topology,
    /// A's nodes' neighbours along A's face edges, and its edge: the nodes on a free edge
    /// that does not lie in a symmetry plane (fixed at the reference positions).
    adjacency: Adjacency,
    /// Per A face: the symmetry planes (indices into `symmetry`) one of its edges lies in, at
    /// the reference positions; its auxiliary normal is turned into them ([`Self::aux_plane`]).
    face_planes: Vec<Vec<usize>>,
    /// Under small kinematics: per A face, the B nodes projecting inside it at the reference.
    interiors: Option<Vec<Vec<usize>>>,
}

/// The flat positions `x` (3 per node) as points, without copying.
fn points(x: &[f64]) -> &[[f64; 3]] {
    let (points, rest) = x.as_chunks::<3>();
    debug_assert!(rest.is_empty(), "3D positions have 3 values per node");
    points
}

/// The sorted distinct node ids of `faces`.
fn nodes_of(faces: &[[usize; 4]]) -> Vec<usize> {
    let set: BTreeSet<usize> = faces.iter().flatten().copied().collect();
    set.into_iter().collect()
}

/// `(x_2 - x_0) x (x_3 - x_1) / 2`: the vector area of a face (exact for a flat face; for a
/// warped one, the vector area of its projection on the plane of mean normal).
fn vector_area(q: &Quad) -> Vector3<f64> {
    (v3(q[2]) - v3(q[0])).cross(&(v3(q[3]) - v3(q[1]))) * 0.5
}

/// Where point `p` projects on face `q` along the face's auxiliary normal `n_0`.
struct OnFace {
    /// Natural coordinates of the projection (unclamped; outside `[-1, 1]^2` off the face).
    st: [f64; 2],
    /// The face's point at `st` clamped to `[-1, 1]^2`.
    point: Vector3<f64>,
    /// `n_0`.
    normal: Vector3<f64>,
}

impl OnFace {
    /// The projection of `p` on `q`; `None` if the inverse map fails (a face folded over it).
    fn of(q: &Quad, p: [f64; 3]) -> Option<Self> {
        let plane = AuxPlane::of(q);
        let corners = q.map(|c| plane.project(c));
        let st = inverse_bilinear(&corners, plane.project(p), super::clip::size(q))?;
        let [s, t] = st.map(|v| v.clamp(-1.0, 1.0));
        Some(OnFace {
            st,
            point: point(q, s, t),
            normal: plane.normal,
        })
    }

    /// Whether the projection lies on the face (to [`INSIDE`]).
    fn inside(&self) -> bool {
        self.st.iter().all(|v| v.abs() <= 1.0 + INSIDE)
    }

    /// The face edges (corner index pairs `(i, i + 1)`) the projection lies beyond.
    fn beyond(&self) -> impl Iterator<Item = usize> + '_ {
        let [s, t] = self.st;
        // edge i joins corners i and i + 1: t = -1, s = 1, t = 1, s = -1
        [
            t < -1.0 - INSIDE,
            s > 1.0 + INSIDE,
            t > 1.0 + INSIDE,
            s < -1.0 - INSIDE,
        ]
        .into_iter()
        .enumerate()
        .filter_map(|(i, b)| b.then_some(i))
    }
}

/// The checks of [`FaceGeometry::new`] on the faces at `x`: each side has a face, node ids in
/// range, each side one surface ([`check_surface`]), no node on both sides, every face passing
/// [`check_face`], and the sides facing each other somewhere ([`check_facing_somewhere`]).
fn check_pair(a_faces: &[[usize; 4]], b_faces: &[[usize; 4]], x: &[[f64; 3]]) -> Result<()> {
    let sides = [("A", a_faces), ("B", b_faces)];
    let mut corners = Vec::new();
    for (side, faces) in sides {
        if faces.is_empty() {
            return Err(Error::InvalidInput(format!(
                "contact side {side} has no face"
            )));
        }
        corners.push(SurfaceFaces { x, faces }.corners(side)?);
        check_surface(side, faces)?;
    }
    let b = nodes_of(b_faces);
    if let Some(&k) = a_faces
        .iter()
        .flatten()
        .find(|k| b.binary_search(k).is_ok())
    {
        let face = |faces: &[[usize; 4]]| faces.iter().position(|f| f.contains(&k));
        return Err(Error::InvalidInput(format!(
            "node {k} belongs to both sides of the pair (A face {}, B face {}): A and B must \
             be surfaces of different bodies",
            face(a_faces).unwrap_or(0),
            face(b_faces).unwrap_or(0)
        )));
    }
    for ((side, _), quads) in sides.iter().zip(&corners) {
        for (i, quad) in quads.iter().enumerate() {
            check_face(quad, &format!("{side} face {i}"))?;
        }
    }
    check_facing_somewhere(&corners[0], &corners[1])
}

/// A face's unit normal at its centre, its centre and its size (the square root of its area).
fn centre_frame(q: &Quad) -> (Vector3<f64>, Vector3<f64>, f64) {
    let plane = AuxPlane::of(q);
    (plane.normal, plane.origin, vector_area(q).norm().sqrt())
}

/// The two sides face each other somewhere, at any distance: some A face and some B face have
/// normals opposed by more than 60 degrees (`n_A . n_B < -1/2`, as
/// [`ContactGeometry::facing`] judges a node) and each lies in front of the other, or
/// within half its size behind it (touching). Otherwise the pair closes only if a body turns
/// over or passes through the other: the faces were given on the wrong sides (the back of a
/// body, faces turned the same way). `O(|A| |B|)` at worst, where it fails; it stops at the
/// first facing pair.
///
/// # Errors
/// [`Error::InvalidInput`] saying that the sides never face each other.
fn check_facing_somewhere(a: &[Quad], b: &[Quad]) -> Result<()> {
    let b_frames: Vec<_> = b.iter().map(centre_frame).collect();
    let face = |(na, ca, ha): &(Vector3<f64>, Vector3<f64>, f64)| {
        b_frames.iter().any(|(nb, cb, hb)| {
            na.dot(nb) < -0.5 && (cb - ca).dot(na) >= -0.5 * ha && (ca - cb).dot(nb) >= -0.5 * hb
        })
    };
    if a.iter().map(centre_frame).any(|f| face(&f)) {
        return Ok(());
    }
    Err(Error::InvalidInput(
        "the sides never face each other: no B face lies in front of an A face with its \
         normal against A's (every B face turns the same way as the A faces near it, or lies \
         behind them); check which faces are on side A (the multiplier side) and which on B"
            .into(),
    ))
}

/// How A's faces connect.
#[derive(Debug, Clone)]
struct Topology {
    /// Per A node (index into A): its faces (indices into A's faces).
    faces: Vec<Vec<usize>>,
    /// Per A node: the A nodes (indices into A) it shares a face edge with, sorted.
    neighbours: Vec<Vec<usize>>,
    /// A's free edges (node-id pairs, smaller first): edges of one A face only.
    free_edges: BTreeSet<(usize, usize)>,
}

impl Topology {
    /// The topology of `faces` whose sorted distinct node ids are `a`.
    fn new(a: &[usize], faces: &[[usize; 4]]) -> Self {
        let index = |k: usize| a.binary_search(&k).expect("a node of A's faces");
        let mut out = Topology {
            faces: vec![Vec::new(); a.len()],
            neighbours: vec![Vec::new(); a.len()],
            free_edges: BTreeSet::new(),
        };
        let mut count: BTreeMap<(usize, usize), usize> = BTreeMap::new();
        for (i, f) in faces.iter().enumerate() {
            for &k in f {
                out.faces[index(k)].push(i);
            }
            for (p, q) in edges(f) {
                out.neighbours[index(p)].push(index(q));
                out.neighbours[index(q)].push(index(p));
                *count.entry((p, q)).or_default() += 1;
            }
        }
        for list in &mut out.neighbours {
            list.sort_unstable();
            list.dedup();
        }
        out.free_edges = count
            .into_iter()
            .filter(|&(_, n)| n == 1)
            .map(|(e, _)| e)
            .collect();
        out
    }
}

impl Topology {
    /// The [`Adjacency`] of A's nodes `a` (sorted ids) at positions `x`: the neighbours along
    /// face edges, and on A's edge the nodes of the free edges that do not lie in one of the
    /// `symmetry` planes (both ends on it, to [`SymmetryPlane::contains`] of the edge's
    /// length).
    fn adjacency(&self, a: &[usize], x: &[[f64; 3]], symmetry: &[SymmetryPlane]) -> Adjacency {
        let index = |k: usize| a.binary_search(&k).expect("a node of A's faces");
        let mut edge = vec![false; a.len()];
        for &(p, q) in &self.free_edges {
            let h = (v3(x[q]) - v3(x[p])).norm();
            let mirrored = (symmetry.iter()).any(|s| s.contains(x[p], h) && s.contains(x[q], h));
            if !mirrored {
                edge[index(p)] = true;
                edge[index(q)] = true;
            }
        }
        Adjacency::new(self.neighbours.clone(), edge)
    }
}

impl FaceGeometry {
    /// The pair of A faces `a_faces` and B faces `b_faces` (node ids into the flat positions
    /// `x`, 3 per node, in [`crate::solid::geometry::FACES`] order, outward), checked at `x`
    /// (the reference configuration), with A's tangent frames from `reference` or, for `None`,
    /// the coordinate axis [`SurfaceFrames::new`] chooses at `x` (kept from then on), and the
    /// model's symmetry planes.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for `x` not 3 values per node, no A or no B face, a node id out
    /// of range (naming the face and the node), a side that is not one connected surface
    /// ([`check_surface`]), a node of both A and B (naming it and a face of each), a failing
    /// face (degenerate, warped; naming it), sides that never face each other (at any
    /// distance: no A face and B face with opposed normals each in front of the other), and
    /// the errors of [`SurfaceFrames::new`] for A's frames at `x` (naming the node).
    pub fn new(
        a_faces: Vec<[usize; 4]>,
        b_faces: Vec<[usize; 4]>,
        x: &[f64],
        reference: Option<[f64; 3]>,
        symmetry: &[SymmetryPlane],
    ) -> Result<Self> {
        if !x.len().is_multiple_of(3) {
            return Err(Error::InvalidInput(format!(
                "3D positions have 3 values per node, got {} values",
                x.len()
            )));
        }
        let pts = points(x);
        check_pair(&a_faces, &b_faces, pts)?;
        let (a, b) = (nodes_of(&a_faces), nodes_of(&b_faces));
        let frames = SurfaceFrames::new(
            SurfaceFaces {
                x: pts,
                faces: &a_faces,
            },
            reference,
            symmetry,
        )?;
        let dropped = a.iter().map(|k| frames.frames[k].dropped).collect();
        let topology = Topology::new(&a, &a_faces);
        let symmetry: Vec<SymmetryPlane> = symmetry
            .iter()
            .map(|p| SymmetryPlane::new(p.point, p.normal))
            .collect::<Result<_>>()?;
        let adjacency = topology.adjacency(&a, pts, &symmetry);
        let face_planes = a_faces
            .iter()
            .map(|f| {
                let on = |p: &SymmetryPlane| {
                    edges(f).any(|(u, v)| {
                        let h = (v3(pts[v]) - v3(pts[u])).norm();
                        p.contains(pts[u], h) && p.contains(pts[v], h)
                    })
                };
                (0..symmetry.len()).filter(|&i| on(&symmetry[i])).collect()
            })
            .collect();
        Ok(FaceGeometry {
            a_faces,
            b_faces,
            a,
            b,
            reference: frames.reference,
            symmetry,
            dropped,
            topology,
            adjacency,
            face_planes,
            interiors: None,
        })
    }

    /// The reference direction of A's tangent frames (unit).
    pub fn reference(&self) -> [f64; 3] {
        self.reference
    }

    /// A's faces.
    pub fn a_faces(&self) -> &[[usize; 4]] {
        &self.a_faces
    }

    /// B's faces.
    pub fn b_faces(&self) -> &[[usize; 4]] {
        &self.b_faces
    }

    /// B's nodes, sorted (the index `i` of [`ContactGeometry::b_node_normal`] is into these).
    pub fn b_nodes(&self) -> &[usize] {
        &self.b
    }

    fn surface<'a>(faces: &'a [[usize; 4]], x: &'a [[f64; 3]]) -> SurfaceFaces<'a> {
        SurfaceFaces { x, faces }
    }

    /// The auxiliary plane of A face `i` (corners `q`): its own ([`AuxPlane::of`]), or for a
    /// face with an edge in a symmetry plane, along its centre normal turned into the plane
    /// (both planes: along their common line). Its edge there and B's, both in the plane,
    /// then project onto the plane's one trace, as they would in the mirrored model, where
    /// the face's mirror image cancels the normal's component across the plane; along the
    /// face's own normal B's edge would be shifted by the gap times that component, leaving
    /// a sliver of the face uncovered (or B's edge overhanging it) once the surfaces deform.
    fn aux_plane(&self, i: usize, q: &Quad) -> AuxPlane {
        let own = AuxPlane::of(q);
        if self.face_planes[i].is_empty() {
            return own;
        }
        let m = |p: usize| v3(self.symmetry[self.face_planes[i][p]].normal);
        let n = match self.face_planes[i].len() {
            1 => own.normal - m(0) * own.normal.dot(&m(0)),
            _ => {
                let line = m(0).cross(&m(1));
                line * line.dot(&own.normal)
            }
        };
        AuxPlane::along(q, n.normalize())
    }

    /// The corners of face `f` at positions `x`.
    fn quad(f: &[usize; 4], x: &[[f64; 3]]) -> Quad {
        f.map(|k| x[k])
    }

    /// A node `k` (index into A): the unit normal along the sum of its faces' vector areas
    /// ([`vector_area`]) and its tributary size, the square root of its faces' mean area.
    fn node_normal(&self, k: usize, x: &[[f64; 3]]) -> (Vector3<f64>, f64) {
        let faces = &self.topology.faces[k];
        let (n, area) = faces.iter().fold((Vector3::zeros(), 0.0), |(n, area), &i| {
            let v = vector_area(&Self::quad(&self.a_faces[i], x));
            (n + v, area + v.norm())
        });
        (n.normalize(), (area / faces.len() as f64).sqrt())
    }

    /// The B faces facing the unit normal `n` (an A normal: `n_B . n < 0` at B's centre) at
    /// `x`, with their corners.
    fn facing_b(&self, x: &[[f64; 3]], n: &Vector3<f64>) -> impl Iterator<Item = (usize, Quad)> {
        let n = *n;
        self.b_faces.iter().enumerate().filter_map(move |(i, f)| {
            let q = Self::quad(f, x);
            (AuxPlane::of(&q).normal.dot(&n) < 0.0).then_some((i, q))
        })
    }
}

/// The nearest face of `faces` to `p` (by the distance to the clamped projection [`OnFace`]),
/// with its index.
fn nearest_face(
    faces: impl Iterator<Item = (usize, Quad)>,
    p: [f64; 3],
) -> Option<(usize, OnFace)> {
    faces
        .filter_map(|(i, q)| OnFace::of(&q, p).map(|o| (i, o)))
        .min_by(|u, v| {
            let d = |o: &OnFace| (o.point - v3(p)).norm();
            d(&u.1).total_cmp(&d(&v.1))
        })
}

impl ContactGeometry for FaceGeometry {
    fn dim(&self) -> usize {
        3
    }

    fn a_nodes(&self) -> &[usize] {
        &self.a
    }

    /// The nodes sharing a face edge; the edge: free edges of A outside the symmetry planes.
    fn adjacency(&self) -> &Adjacency {
        &self.adjacency
    }

    /// The [module docs](self)' quantities from [`SurfaceMortar`] over the face pairs within
    /// `reach` and [`SurfaceFrames`] with the pair's reference direction and symmetry planes.
    ///
    /// `reach` only selects the candidate face pairs, by bounding boxes
    /// ([`super::pair_faces`]): unlike the plane code, a covered point is not re-checked for
    /// `|g| <= reach`, so with a `reach` below the gap a pair's coverage can depend on its
    /// orientation (axis-aligned boxes of flat faces are thin, turned ones are not). The maps
    /// of [`SurfaceMortar`] are built anew on every call (`out`'s node rows are reused).
    ///
    /// # Errors
    /// Those of [`SurfaceMortar::new`] and [`SurfaceFrames::new`] at `x` (naming the face or
    /// the node), and an A node covered more than once (B's faces overlapping each other over
    /// it, seen along A's normal: its `R_k` would count B twice).
    fn evaluate_into(&self, x: &[f64], reach: f64, out: &mut ContactSurface) -> Result<()> {
        let pts = points(x);
        let (sa, sb) = (
            Self::surface(&self.a_faces, pts),
            Self::surface(&self.b_faces, pts),
        );
        let mortar = SurfaceMortar::on_planes(sa, sb, reach, |i, q| self.aux_plane(i, q))?;
        let frames = SurfaceFrames::new(sa, Some(self.reference), &self.symmetry)?;
        out.nodes.resize(self.a.len(), ContactNode::empty(3));
        for (node, &k) in out.nodes.iter_mut().zip(&self.a) {
            let f = &frames.frames[&k];
            let [s1, s2] = [0, 1].map(|i| {
                if f.dropped[i] {
                    [0.0; 3]
                } else {
                    f.tangents[i]
                }
            });
            node.node = k;
            node.frame = Frame::face(f.normal, s1, s2);
            node.weight = mortar.weight[&k];
            node.covered_weight = mortar.covered[&k];
            node.coverage = mortar.covered_once(k)?;
            node.gap = Vector::from(mortar.mismatch.get(&k).copied().unwrap_or([0.0; 3]));
            if node.covered_weight > 0.0 {
                node.normal_gap = -node.frame.normal().dot(&node.gap) / node.covered_weight;
                node.mean_distance = mortar.distance[&k] / node.covered_weight;
            } else {
                node.normal_gap = f64::INFINITY;
                node.mean_distance = f64::INFINITY;
            }
            let d = mortar
                .d
                .range((k, 0)..(k + 1, 0))
                .map(|(&(_, j), &v)| (j, v));
            let m = mortar
                .m
                .range((k, 0)..(k + 1, 0))
                .map(|(&(_, j), &v)| (j, -v));
            node.coupling.clear();
            node.coupling.extend(d.chain(m).filter(|&(_, v)| v != 0.0));
            // A's and B's nodes are distinct (checked in `new`), so no id repeats
            node.coupling.sort_unstable_by_key(|&(j, _)| j);
        }
        Ok(())
    }

    /// The mean over A's faces of the square root of the face's area (`|vector_area|`, exact
    /// for flat faces): the edge length of a square face.
    fn mean_size(&self, x: &[f64]) -> f64 {
        let x = points(x);
        let total: f64 = self
            .a_faces
            .iter()
            .map(|f| vector_area(&Self::quad(f, x)).norm().sqrt())
            .sum();
        total / self.a_faces.len() as f64
    }

    /// A node on two symmetry planes (both tangents dropped: the corner of a quarter model),
    /// as found at the positions given to [`FaceGeometry::new`] (the reference, which the core
    /// passes here too). A node on one plane keeps friction along its other tangent: its
    /// dropped tangent is zero in its [`Frame`] ([`Frame::is_dropped`]), and the core skips
    /// that component.
    fn frictionless_at(&self, k: usize, _x: &[f64]) -> bool {
        self.dropped[k] == [true, true]
    }

    /// Every A node against the B face nearest to it (its point at the node's projection along
    /// the face's auxiliary normal, clamped to the face), if within `reach`; the node's normal
    /// is the direction of its faces' summed vector areas and its tributary length the square
    /// root of their mean area. `O(|A| |B|)`, for the reference configuration.
    fn facing(&self, x: &[f64], reach: f64) -> Facing {
        let pts = points(x);
        let mut tally = FacingTally::default();
        let b_quads = || {
            self.b_faces
                .iter()
                .enumerate()
                .map(|(i, f)| (i, Self::quad(f, pts)))
        };
        for k in 0..self.a.len() {
            let (na, size) = self.node_normal(k, pts);
            let p = pts[self.a[k]];
            let Some((_, near)) =
                nearest_face(b_quads(), p).filter(|(_, o)| (o.point - v3(p)).norm() <= reach)
            else {
                continue;
            };
            let cos = na.dot(&near.normal);
            let ahead = (near.point - v3(p)).dot(&na);
            tally.add(k, cos, ahead, size);
        }
        tally.finish()
    }

    /// `point` must lie on A's body side of A's nearest face: `(p - q) . n_0 < 0`, `q` the
    /// face's point at `p`'s projection along its auxiliary normal `n_0` (clamped to the face),
    /// and not beyond a free edge of A (projecting outside its nearest face across an edge that
    /// no other A face shares), where the side is not defined.
    ///
    /// # Errors
    /// [`Error::InvalidInput`]: a non-finite point, one beyond A's free edge, or one on A's
    /// outward side (A's faces reversed).
    fn check_inside(&self, x: &[f64], point: &Vector) -> Result<()> {
        let p = [point[0], point[1], point[2]];
        if !p.iter().all(|v| v.is_finite()) {
            return Err(Error::InvalidInput(format!(
                "the point inside body A {p:?} is not finite"
            )));
        }
        let pts = points(x);
        let faces = self
            .a_faces
            .iter()
            .enumerate()
            .map(|(i, f)| (i, Self::quad(f, pts)));
        let Some((i, on)) = nearest_face(faces, p) else {
            return Err(Error::InvalidInput(format!(
                "the point {p:?} inside body A projects onto no A face"
            )));
        };
        let f = &self.a_faces[i];
        let free = on.beyond().find(|&e| {
            let (u, v) = (f[e], f[(e + 1) % 4]);
            self.topology.free_edges.contains(&(u.min(v), u.max(v)))
        });
        if let Some(e) = free {
            return Err(Error::InvalidInput(format!(
                "the point {p:?} inside body A lies beyond the free edge ({}, {}) of A face {i}, \
                 where its side is not defined: give one above A (the centroid of an element \
                 that owns an A face, say)",
                f[e],
                f[(e + 1) % 4]
            )));
        }
        if (v3(p) - on.point).dot(&on.normal) < 0.0 {
            Ok(())
        } else {
            Err(Error::InvalidInput(format!(
                "the point {p:?} inside body A lies on the outward side of A face {i}: A's \
                 faces point into their own body, so they are reversed (and B's with them, if \
                 they face each other: the pair is back to back)"
            )))
        }
    }

    /// The magnitude of the least-squares gradient of the normal gap over node `k` and its
    /// covered neighbours along A's face edges, in the tangent plane of `n_k`: exact for a
    /// gap linear along A (the 3D form of the plane code's central difference); with the
    /// neighbours all on one line, the largest `|dg0| / |dx|` along them; 0 without a covered
    /// neighbour.
    fn gap_slope(&self, surface: &ContactSurface, k: usize, x: &[f64]) -> f64 {
        let pts = points(x);
        let nodes = &surface.nodes;
        let n = v3(nodes[k].frame.normal().components().try_into().expect("3D"));
        let at = |i: usize| v3(pts[nodes[i].node]);
        let steps: Vec<(Vector3<f64>, f64)> = self.topology.neighbours[k]
            .iter()
            .filter(|&&j| nodes[j].normal_gap.is_finite())
            .map(|&j| {
                let d = at(j) - at(k);
                (d - n * d.dot(&n), nodes[j].normal_gap - nodes[k].normal_gap)
            })
            .collect();
        let Some(&(first, _)) = steps.first() else {
            return 0.0;
        };
        let e1 = first.normalize();
        let e2 = n.cross(&e1);
        let (mut a, mut b) = (nalgebra::Matrix2::<f64>::zeros(), Vector2::<f64>::zeros());
        for (d, dg) in &steps {
            let y = Vector2::new(d.dot(&e1), d.dot(&e2));
            a += y * y.transpose();
            b += y * *dg;
        }
        let line = a.determinant() <= 1e-8 * a.trace() * a.trace();
        match a.try_inverse().filter(|_| !line) {
            Some(inv) => (inv * b).norm(),
            None => steps
                .iter()
                .map(|(d, dg)| (dg / d.norm()).abs())
                .fold(0.0, f64::max),
        }
    }

    fn freeze_b_nodes(&mut self, x: &[f64]) {
        let pts = points(x);
        let interiors = self
            .a_faces
            .iter()
            .map(|f| {
                let q = Self::quad(f, pts);
                self.b
                    .iter()
                    .copied()
                    .filter(|&j| OnFace::of(&q, pts[j]).is_some_and(|o| strictly_inside(o.st)))
                    .collect()
            })
            .collect();
        self.interiors = Some(interiors);
    }

    /// Over A faces whose four nodes are open: the B nodes projecting strictly inside the face
    /// along its auxiliary normal `n_0` at `xg` (`|s|, |t| < 1`), the distance
    /// `(x_B - x_A(s, t)) . n_0` at `x`, closing the face's corner nearest to `(s, t)`.
    fn b_node_distances(&self, open: &[bool], x: &[f64], xg: &[f64]) -> Vec<BNodeDistance> {
        let (x, xg) = (points(x), points(xg));
        let index = |k: usize| self.a.binary_search(&k).expect("an A node");
        let mut out = Vec::new();
        for (i, f) in self.a_faces.iter().enumerate() {
            let element = f.map(index);
            if !element.iter().all(|&e| open[e]) {
                continue;
            }
            let (qg, qx) = (Self::quad(f, xg), Self::quad(f, x));
            let candidates = match &self.interiors {
                Some(interiors) => &interiors[i][..],
                None => &self.b[..],
            };
            for &j in candidates {
                let Some(on) = OnFace::of(&qg, xg[j]).filter(|o| strictly_inside(o.st)) else {
                    continue;
                };
                let [s, t] = on.st;
                let hit = point(&qx, s, t);
                let corner = (0..4)
                    .min_by(|&u, &v| {
                        let d = |c: usize| (s - CORNERS[c][0]).hypot(t - CORNERS[c][1]);
                        d(u).total_cmp(&d(v))
                    })
                    .expect("4 corners");
                out.push(BNodeDistance {
                    node: j,
                    element: element.to_vec(),
                    nearest: element[corner],
                    distance: (v3(x[j]) - hit).dot(&on.normal),
                });
            }
        }
        out
    }

    /// The direction of the sum of the vector areas of B's faces at B node `i` (index into
    /// [`b_nodes`](FaceGeometry::b_nodes)): B's outward normal there, each face weighted by its
    /// area, the 3D twin of the plane's rotated chord.
    fn b_node_normal(&self, i: usize, x: &[f64]) -> Vector {
        let pts = points(x);
        let node = self.b[i];
        let sum = (self.b_faces.iter())
            .filter(|f| f.contains(&node))
            .fold(Vector3::zeros(), |s, f| {
                s + vector_area(&Self::quad(f, pts))
            });
        let n = sum / sum.norm();
        Vector::solid(n.x, n.y, n.z)
    }

    /// Over B's faces facing A node `k`'s normal (the direction of its faces' summed vector
    /// areas) onto which the node projects (along the B face's auxiliary normal), the one
    /// nearest to it decides: depth `-(x_k - q) . n_0 > limit`.
    fn behind(&self, k: usize, x: &[f64], limit: f64) -> Option<(Vec<usize>, f64)> {
        let pts = points(x);
        let (n, _) = self.node_normal(k, pts);
        let p = pts[self.a[k]];
        let mut nearest: Option<(usize, f64)> = None;
        for (i, q) in self.facing_b(pts, &n) {
            let Some(on) = OnFace::of(&q, p).filter(OnFace::inside) else {
                continue;
            };
            let signed = (v3(p) - on.point).dot(&on.normal);
            if nearest.is_none_or(|(_, s)| signed.abs() < s.abs()) {
                nearest = Some((i, signed));
            }
        }
        nearest
            .filter(|&(_, signed)| -signed > limit)
            .map(|(i, signed)| (self.b_faces[i].to_vec(), -signed))
    }

    /// The faces of A and of B, each measured by its shortest edge (the finest length its
    /// motion must resolve), the smaller of the current and reference ones.
    fn unresolved(&self, x: &[f64], reference: &[f64], round_off: f64) -> Option<Unresolved> {
        let (x, reference) = (points(x), points(reference));
        let moved = |n: usize| (v3(x[n]) - v3(reference[n])).norm();
        let shortest = |f: &[usize; 4], x: &[[f64; 3]]| {
            (0..4)
                .map(|i| (v3(x[f[(i + 1) % 4]]) - v3(x[f[i]])).norm())
                .fold(f64::INFINITY, f64::min)
        };
        self.a_faces.iter().chain(&self.b_faces).find_map(|f| {
            let node = *f
                .iter()
                .max_by(|&&u, &&v| moved(u).total_cmp(&moved(v)))
                .expect("4 nodes");
            let motion = moved(node);
            let length = shortest(f, reference);
            (shortest(f, x).min(length) <= round_off * motion).then_some(Unresolved {
                node,
                motion,
                length,
            })
        })
    }
}

/// Whether natural coordinates lie strictly inside a face (`|s|, |t| < 1`).
fn strictly_inside(st: [f64; 2]) -> bool {
    st.iter().all(|v| v.abs() < 1.0)
}
