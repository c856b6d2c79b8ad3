//! The seam between the contact core and a contact geometry: what the iteration, the active
//! set, the checks and the results ask of a pair's surfaces, for any dimension.
//!
//! A pair's geometry ([`ContactGeometry`]) evaluates the pair at given positions into one
//! [`ContactNode`] per multiplier-side (A) node: its frame, weight, covered weight, coverage,
//! weighted gap `R_C`, normal gap, mean distance and coupling row (docs/method.md, "Contact
//! surfaces and contact elements"). It also answers the pair checks (do A and B face each
//! other, does a point lie inside A), the scales of the iteration (the mean element size), the
//! reference gap slope of the small-sliding check, the B nodes over open A elements, and what
//! "neighbours along A" means ([`Adjacency`]). Positions are a flat slice with
//! [`ContactGeometry::dim`] values per node (node `i` at `x[dim * i..dim * i + dim]`).
//!
//! The plane and axisymmetric implementation, on polylines, is
//! [`PlaneGeometry`](super::plane::PlaneGeometry); a 3D implementation on faces is a sibling
//! of it.

use super::space::{Frame, Vector};
use crate::error::Result;
use std::any::Any;

/// The contact quantities of one A node (equations in docs/method.md, "Contact surfaces and
/// contact elements", and in the plane implementation's [module docs](super::plane::mortar)).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactNode {
    /// Global node id (an entry of A).
    pub node: usize,
    /// The nodal frame: A's outward normal `n_k` (pointing into B), the direction of
    /// `integral M_k n dS` over the node's support, and its tangents (in the plane
    /// `s_k = (n_k.y, -n_k.x)`).
    pub frame: Frame,
    /// `weight_k = integral M_k dS` over the whole support (the tributary measure: length
    /// times thickness in plane, area of the full circle's band in axisymmetry).
    pub weight: f64,
    /// `integral M_k dS` over the covered part of the support only (`== weight` when
    /// `coverage == 1`).
    pub covered_weight: f64,
    /// Fraction of the support where B was found, in `[0, 1]`; exactly `1.0` when fully
    /// covered. The contact solver must not activate a node with `coverage < 1`.
    pub coverage: f64,
    /// `R_C,k = integral M_k (x^A - x^B) dS = -integral M_k g n dS` over the covered part.
    pub gap: Vector,
    /// `-n_k . R_C,k / covered_weight`: the weighted normal gap as a length, negative =
    /// penetration. `f64::INFINITY` when nothing of the support is covered.
    pub normal_gap: f64,
    /// `integral M_k g dS / covered_weight`, with each element's own normal: the weighted mean
    /// signed distance (equal to `normal_gap` where A is flat; on a curved A it reproduces a
    /// constant offset exactly, while `normal_gap` carries the factor `n_k . n_e`).
    /// `f64::INFINITY` when nothing of the support is covered.
    pub mean_distance: f64,
    /// The coupling row: `(global node id, c_kj)` with `c_kj = +F^A_kj` at A nodes and
    /// `-F^B_kj` at B nodes, one entry per node, sorted by node id, exact zeros dropped.
    pub coupling: Vec<(usize, f64)>,
}

impl ContactNode {
    /// A node of dimension `dim` with nothing evaluated yet (zero normal, weights and gap).
    pub fn empty(dim: usize) -> Self {
        ContactNode {
            node: 0,
            frame: Frame::zero(dim),
            weight: 0.0,
            covered_weight: 0.0,
            coverage: 0.0,
            gap: Vector::zero(dim),
            normal_gap: 0.0,
            mean_distance: 0.0,
            coupling: Vec::new(),
        }
    }

    /// Whether the node's whole support is covered by B (`coverage == 1`).
    pub fn is_covered(&self) -> bool {
        self.coverage >= 1.0
    }

    /// `sum_j c_kj du_j`: the first-order change of `R_C,k` (frozen pairing) under nodal
    /// displacement increments `du` (flat, `dim` values per node, indexed by global node id).
    pub fn coupling_times(&self, du: &[f64]) -> Vector {
        let dim = self.gap.dim();
        self.coupling
            .iter()
            .fold(Vector::zero(dim), |acc, &(j, c)| {
                acc.add_scaled(c, &Vector::from_components(&du[dim * j..dim * j + dim]))
            })
    }
}

/// The contact quantities of a whole pair: one [`ContactNode`] per A node, in A's order.
///
/// Keeps the geometry's scratch buffers between evaluations, so that re-evaluating the same
/// pair does not reallocate.
#[derive(Debug, Clone, Default)]
pub struct ContactSurface {
    /// One entry per A node, in A's order.
    pub nodes: Vec<ContactNode>,
    pub(crate) work: Scratch,
}

impl ContactSurface {
    /// An empty surface (fill it with [`ContactGeometry::evaluate_into`]).
    pub fn new() -> Self {
        Self::default()
    }

    /// Whether every A node is fully covered by B.
    pub fn all_covered(&self) -> bool {
        self.nodes.iter().all(ContactNode::is_covered)
    }
}

/// A geometry's scratch buffers, of its own type: not compared, not cloned (a clone starts
/// empty), not printed.
#[derive(Default)]
pub(crate) struct Scratch(Option<Box<dyn Any + Send + Sync>>);

impl Scratch {
    /// The buffers of type `T`, created empty on first use.
    pub(crate) fn get<T: Any + Send + Sync + Default>(&mut self) -> &mut T {
        if !self.0.as_ref().is_some_and(|b| b.is::<T>()) {
            self.0 = Some(Box::<T>::default());
        }
        self.0
            .as_mut()
            .and_then(|b| b.downcast_mut())
            .expect("buffers of this type were just made")
    }
}

impl Clone for Scratch {
    fn clone(&self) -> Self {
        Scratch(None)
    }
}

impl std::fmt::Debug for Scratch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Scratch")
    }
}

/// How the A nodes of a pair see B in one configuration (counts of A nodes with a B element
/// within reach, classified by that nearest element).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Facing {
    /// B faces A from in front: normals opposed (`n_A . n_B < -1/2`), B on A's outward side by
    /// more than half the node's tributary length.
    pub facing: usize,
    /// Normals opposed and B within half the node's tributary length of A, in front or behind
    /// (touching surfaces, round-off, a discretised curve): the geometry cannot tell facing
    /// surfaces from back-to-back ones (both surfaces reversed) here.
    pub touching: usize,
    /// Normals pointing the same way (`n_A . n_B > 1/2`): one surface is reversed.
    pub same_way: usize,
    /// Normals opposed but B behind A by more than half the tributary length: back to back
    /// (two faces of one body, or both surfaces reversed).
    pub behind: usize,
    /// The first A node (index into A) of the majority class other than `facing`, if any.
    pub example: Option<usize>,
}

/// [`Facing`] counted node by node: what a geometry's [`ContactGeometry::facing`] fills.
#[derive(Debug, Clone, Copy, Default)]
pub struct FacingTally {
    out: Facing,
    first_same: Option<usize>,
    first_behind: Option<usize>,
}

impl FacingTally {
    /// Count A node `k` (index into A) whose normal makes the cosine `cos` with the normal of
    /// its nearest B element, that element's point lying `ahead` along A's normal, against half
    /// the node's tributary length `size` (the classes of [`Facing`]).
    pub fn add(&mut self, k: usize, cos: f64, ahead: f64, size: f64) {
        let out = &mut self.out;
        if cos > 0.5 {
            out.same_way += 1;
            self.first_same.get_or_insert(k);
        } else if cos < -0.5 && ahead < -0.5 * size {
            out.behind += 1;
            self.first_behind.get_or_insert(k);
        } else if cos < -0.5 && ahead <= 0.5 * size {
            out.touching += 1;
        } else if cos < -0.5 {
            out.facing += 1;
        }
    }

    /// The counts, with the first node of the larger class of reversed surfaces as the example.
    pub fn finish(self) -> Facing {
        let example = if self.out.same_way >= self.out.behind {
            self.first_same
        } else {
            self.first_behind
        };
        Facing {
            example,
            ..self.out
        }
    }
}

/// A B node that lies over an A element whose nodes are all open (the pointwise B-node check):
/// its signed distance from the element along the element's normal.
#[derive(Debug, Clone, PartialEq)]
pub struct BNodeDistance {
    /// The B node (global id).
    pub node: usize,
    /// The A element's nodes (indices into A).
    pub element: Vec<usize>,
    /// The A node (index into A) nearest to where the B node projects: the node it closes.
    pub nearest: usize,
    /// `g = (x_B - x_hit) . n_e`, `< 0` when the B node penetrates.
    pub distance: f64,
}

/// An element of a pair (of A or of B) whose motion round-off of the positions can no longer
/// tell from its size (see `ContactAnalysis::resolved`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unresolved {
    /// The element's node that moved most (global id).
    pub node: usize,
    /// How far it moved.
    pub motion: f64,
    /// The element's size in the reference configuration.
    pub length: f64,
}

/// How a pair's A nodes connect along A: the neighbours of each (the nodes it shares an
/// element edge with) and whether it lies on A's edge (the end of a polyline; a node on a
/// free edge of a face surface, unless that edge lies in a symmetry plane, across which the
/// mirrored surface goes on). What "neighbours along A" means to the active set (a run of
/// penetrating nodes becomes a connected patch) and to the fallback's candidates.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Adjacency {
    neighbours: Vec<Vec<usize>>,
    edge: Vec<bool>,
}

impl Adjacency {
    /// The nodes of a chain of `n` nodes: `k - 1` and `k + 1` are the neighbours of `k`, the
    /// first and the last are its edge.
    pub fn chain(n: usize) -> Self {
        Adjacency {
            neighbours: (0..n)
                .map(|k| {
                    let before = k.checked_sub(1);
                    let after = (k + 1 < n).then_some(k + 1);
                    before.into_iter().chain(after).collect()
                })
                .collect(),
            edge: (0..n).map(|k| k == 0 || k + 1 == n).collect(),
        }
    }

    /// Per node (index into A) its neighbours (indices into A, sorted, without itself) and
    /// whether it lies on A's edge.
    pub fn new(neighbours: Vec<Vec<usize>>, edge: Vec<bool>) -> Self {
        debug_assert_eq!(neighbours.len(), edge.len());
        Adjacency { neighbours, edge }
    }

    /// The neighbours of node `k` (indices into A, sorted).
    pub fn neighbours(&self, k: usize) -> &[usize] {
        &self.neighbours[k]
    }

    /// Whether node `k` lies on A's edge.
    pub fn on_edge(&self, k: usize) -> bool {
        self.edge[k]
    }
}

/// The geometry of one contact pair, as the contact core consumes it. Positions `x` are flat,
/// [`dim`](Self::dim) values per node, indexed by global node id.
pub trait ContactGeometry: std::fmt::Debug + Send + Sync {
    /// The dimension of the positions (2 for plane and axisymmetric, 3 for solids).
    fn dim(&self) -> usize;

    /// The multiplier-side (A) nodes, in the order of the evaluated [`ContactNode`]s.
    fn a_nodes(&self) -> &[usize];

    /// Evaluate the pair at positions `x`, pairing B with A within `reach` (a length > 0),
    /// into `out` (reusing its allocations).
    ///
    /// # Errors
    /// [`Error::InvalidInput`](crate::error::Error::InvalidInput) naming the node when the
    /// surfaces are invalid at `x` (see the implementation).
    fn evaluate_into(&self, x: &[f64], reach: f64, out: &mut ContactSurface) -> Result<()>;

    /// [`evaluate_into`](Self::evaluate_into) a new surface.
    ///
    /// # Errors
    /// As [`evaluate_into`](Self::evaluate_into).
    fn evaluate(&self, x: &[f64], reach: f64) -> Result<ContactSurface> {
        let mut out = ContactSurface::new();
        self.evaluate_into(x, reach, &mut out)?;
        Ok(out)
    }

    /// How A's nodes connect along A ([`Adjacency`]).
    fn adjacency(&self) -> &Adjacency;

    /// The mean size of A's elements at `x`: the length scale of the gap tolerance and of the
    /// search distance.
    fn mean_size(&self, x: &[f64]) -> f64;

    /// Whether A node `k` (index into A) carries no tangential traction by symmetry (a node on
    /// the axis in axisymmetry), at the reference positions `x`.
    fn frictionless_at(&self, k: usize, x: &[f64]) -> bool;

    /// How A's nodes see B at `x` within `reach` (the orientation check of a pair).
    fn facing(&self, x: &[f64], reach: f64) -> Facing;

    /// Check that `point` lies inside body A, beside A's surface.
    ///
    /// # Errors
    /// [`Error::InvalidInput`](crate::error::Error::InvalidInput) saying where it lies.
    fn check_inside(&self, x: &[f64], point: &Vector) -> Result<()>;

    /// `|dg0/ds|` at A node `k` of `surface` evaluated at `x`: the slope of the normal gap
    /// along A (0 when no neighbour is covered).
    fn gap_slope(&self, surface: &ContactSurface, k: usize, x: &[f64]) -> f64;

    /// Freeze the candidates of [`b_node_distances`](Self::b_node_distances) at the
    /// reference positions `x` (small kinematics: they do not change).
    fn freeze_b_nodes(&mut self, x: &[f64]);

    /// The B nodes over the A elements whose nodes are all `open` (per A node), the element's
    /// normal and the B node's projection taken at `xg` (the geometry's configuration), the
    /// distance measured at the current positions `x`.
    fn b_node_distances(&self, open: &[bool], x: &[f64], xg: &[f64]) -> Vec<BNodeDistance>;

    /// B's outward normal at B node `i` (index into B) at positions `x`: the direction of the
    /// mean of its elements' normals.
    fn b_node_normal(&self, i: usize, x: &[f64]) -> Vector;

    /// Whether A node `k` at the current positions `x` lies behind B (inside B's body) by more
    /// than `limit`, over B's facing elements without a search window: the B element's nodes
    /// (global ids) and the depth.
    fn behind(&self, k: usize, x: &[f64], limit: f64) -> Option<(Vec<usize>, f64)>;

    /// The first element of A or B that the motion from `reference` to `x` has made
    /// unresolvable (position round-off `round_off` times the motion reaching its size).
    fn unresolved(&self, x: &[f64], reference: &[f64], round_off: f64) -> Option<Unresolved>;
}
