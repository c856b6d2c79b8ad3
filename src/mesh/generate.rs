//! Mesh generators: the benchmark geometries (Cook's membrane, the Pian-Sumihara beam) and graded
//! 2:1 quadtree meshes with 5- and 6-node transition elements (a block, a half disk, or any
//! user layout of mapped quadrilateral patches), or the same grading with 4-node
//! quadrilaterals only ([`Transition::Quads`], for elements that take nothing else).
//!
//! This module owns the whole generation pipeline; every public generator is a thin wrapper over
//! [`graded_layout_with`].
//!
//! # Layout
//! A [`Layout`] is a coarse conforming mesh of quadrilateral *patches*. Each patch has four
//! corner *vertex ids* (counter-clockwise), a grid of `roots[0] x roots[1]` root cells, and is
//! carried to the plane by a user map `map(patch, [u, v])`, `[u, v]` in the unit square
//! (`u` along side 0, from corner 0 to corner 1; `v` from corner 0 to corner 3). Patch side `k`
//! runs from corner `k` to corner `k + 1`. Two patches sharing a side list its two vertices in
//! opposite orders, have the same number of root cells along it, and their maps must agree on
//! it. A side with a name in [`Patch::sides`] is a domain boundary and becomes the edge and node
//! sets of that name. Maps must be orientation preserving (counter-clockwise stays
//! counter-clockwise).
//!
//! # Algorithm
//! 1. **Grading.** Each root cell is split recursively into four children. A cell is split while,
//!    for some [`Grading`], its size (longest edge of its mapped corner quadrilateral) exceeds
//!    `min_size` and its distance to the target (point or segment, measured to the mapped
//!    corner quadrilateral) is less than `layers * size / 2`, so that about `layers` cells of
//!    each size lie between the target and the next coarser band. Cells of size at most
//!    `min_size` are never split for grading: near the target the size is the first `root size
//!    / 2^k` not above `min_size`.
//! 2. **Balance.** Repeat until stable: a leaf is split when a neighbour across one of its edges
//!    is two or more levels finer (2:1 balance), or when three or four of its edges have a finer
//!    neighbour (such an element would need 7 or 8 nodes). Neighbours are found without any
//!    tree walk: every point of the integer reference lattice has a canonical key (patch
//!    vertex, point on a patch side with its parameter measured from the lower vertex id, or
//!    patch interior point), and an edge has a finer neighbour exactly when its midpoint is a
//!    corner of some leaf, a neighbour two levels finer exactly when a quarter point is.
//! 3. **Elements.** Every leaf becomes one element: its four corners counter-clockwise from the
//!    lower-left one, with the midpoint of each edge whose neighbour is finer inserted between
//!    that edge's corners (4-, 5- or 6-node elements; no triangles, no constraints). The fine
//!    neighbours use the same node as their corner, so every boundary segment of an element is
//!    shared with exactly one other element traversed in the opposite direction, or lies on the
//!    domain boundary.
//! 4. **Straight transition edges.** Nodes are mapped, then every hanging node is moved to the
//!    midpoint of its coarse edge's two (mapped) end nodes, coarsest edges first, so transition
//!    elements have exactly straight edges through their mid-side nodes.
//!
//! Leaves are numbered patch by patch, row by row; nodes in order of first use; both are
//! deterministic. Every element gets its patch's material.

use super::Mesh;
use std::collections::{BTreeMap, BTreeSet, HashMap, HashSet};

/// Finest quadtree level (cells of `2^-MAX_LEVEL` root sizes); an integer lattice of this
/// resolution gives every node an exact key.
const MAX_LEVEL: u8 = 30;
/// Lattice points per root cell side.
const ROOT: u64 = 1 << MAX_LEVEL;

/// What a graded mesh is refined toward.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Target {
    /// A point `[x, y]`.
    Point([f64; 2]),
    /// The segment between two points.
    Line([f64; 2], [f64; 2]),
}

impl Target {
    /// Distance from the target to the convex quadrilateral `quad` (0 when they intersect).
    fn distance_to_quad(&self, quad: &[[f64; 2]; 4]) -> f64 {
        let edges = (0..4).map(|k| (quad[k], quad[(k + 1) % 4]));
        match *self {
            Target::Point(p) if inside(quad, p) => 0.0,
            Target::Point(p) => edges
                .map(|(a, b)| point_segment(p, a, b))
                .fold(f64::INFINITY, f64::min),
            Target::Line(p, _) if inside(quad, p) => 0.0,
            Target::Line(p, q) => edges
                .map(|(a, b)| segment_segment(p, q, a, b))
                .fold(f64::INFINITY, f64::min),
        }
    }
}

/// Refinement toward a target: cells near `target` get size `min_size` (or the first root size /
/// 2^k below it), and the size roughly doubles every `layers` cells away from it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grading {
    /// Where to refine.
    pub target: Target,
    /// Element size (longest edge) wanted at the target.
    pub min_size: f64,
    /// Number of cells of each size between the target and the next coarser band (at least 1).
    pub layers: usize,
}

impl Grading {
    /// Grading toward the point `p`.
    pub fn toward_point(p: [f64; 2], min_size: f64, layers: usize) -> Self {
        Grading {
            target: Target::Point(p),
            min_size,
            layers,
        }
    }

    /// Grading toward the segment from `a` to `b`.
    pub fn toward_line(a: [f64; 2], b: [f64; 2], min_size: f64, layers: usize) -> Self {
        Grading {
            target: Target::Line(a, b),
            min_size,
            layers,
        }
    }

    /// Whether a cell whose mapped corners are `quad` must be split.
    fn splits(&self, quad: &[[f64; 2]; 4]) -> bool {
        let size = longest_edge(quad);
        size > self.min_size * (1.0 + 1e-9)
            && self.target.distance_to_quad(quad) < self.layers as f64 * 0.5 * size
    }
}

/// One quadrilateral patch of a [`Layout`].
#[derive(Debug, Clone, PartialEq)]
pub struct Patch {
    /// Vertex ids of the corners, counter-clockwise (any integers; shared corners share ids).
    pub corners: [usize; 4],
    /// Root cells along side 0 (and 2) and along side 1 (and 3).
    pub roots: [usize; 2],
    /// Material index of the patch's elements.
    pub material: usize,
    /// Boundary set name of each side (`None`: interior side shared with another patch, or an
    /// unnamed boundary).
    pub sides: [Option<String>; 4],
}

/// A coarse conforming layout of patches (see the module documentation).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Layout {
    /// The patches.
    pub patches: Vec<Patch>,
}

/// Exact identity of a lattice point, shared by every patch that sees it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
enum Key {
    /// A patch corner (vertex id).
    Vertex(usize),
    /// A point on a patch side: lower vertex id, higher vertex id, lattice parameter from the
    /// lower one.
    Side(usize, usize, u64),
    /// A point inside a patch: patch index and its lattice coordinates.
    Interior(usize, u64, u64),
}

/// A quadtree cell: patch, level, and integer position at that level.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
struct Cell {
    patch: usize,
    level: u8,
    i: u64,
    j: u64,
}

impl Cell {
    /// Lattice corners, counter-clockwise from the lower-left one.
    fn corners(&self) -> [[u64; 2]; 4] {
        let s = ROOT >> self.level;
        let (x, y) = (self.i * s, self.j * s);
        [[x, y], [x + s, y], [x + s, y + s], [x, y + s]]
    }

    fn children(&self) -> [Cell; 4] {
        let (i, j, level) = (2 * self.i, 2 * self.j, self.level + 1);
        let c = |i, j| Cell {
            patch: self.patch,
            level,
            i,
            j,
        };
        [c(i, j), c(i + 1, j), c(i + 1, j + 1), c(i, j + 1)]
    }

    /// Lattice point at fraction `num / den` along edge `k` (corner `k` to corner `k + 1`).
    fn edge_point(&self, k: usize, num: u64, den: u64) -> [u64; 2] {
        let c = self.corners();
        let (a, b) = (c[k], c[(k + 1) % 4]);
        let lerp = |p: u64, q: u64| {
            if q >= p {
                p + (q - p) / den * num
            } else {
                p - (p - q) / den * num
            }
        };
        [lerp(a[0], b[0]), lerp(a[1], b[1])]
    }
}

impl Layout {
    /// Panic unless every patch has root cells and distinct corners, and every shared side is
    /// used once in each direction with the same number of root cells.
    fn check(&self) {
        let mut sides: HashMap<[usize; 2], (usize, usize)> = HashMap::new();
        for (p, patch) in self.patches.iter().enumerate() {
            assert!(
                patch.roots.iter().all(|&n| n >= 1),
                "patch {p} has no root cells"
            );
            for k in 0..4 {
                let side = [patch.corners[k], patch.corners[(k + 1) % 4]];
                let n = patch.roots[k % 2];
                assert_ne!(side[0], side[1], "patch {p} has a degenerate side");
                let twin = sides.insert(side, (p, n));
                assert!(
                    twin.is_none(),
                    "side {side:?} of patch {p} is used twice in one direction"
                );
                if let Some(&(q, m)) = sides.get(&[side[1], side[0]]) {
                    assert_eq!(n, m, "patches {q} and {p} split side {side:?} differently");
                }
            }
        }
    }

    /// Lattice extent of patch `p`.
    fn extent(&self, p: usize) -> [u64; 2] {
        let r = self.patches[p].roots;
        [r[0] as u64 * ROOT, r[1] as u64 * ROOT]
    }

    /// Canonical key of lattice point `x` of patch `p`.
    fn key(&self, p: usize, x: [u64; 2]) -> Key {
        let [lx, ly] = self.extent(p);
        let corners = self.patches[p].corners;
        let (side, t, len) = match x {
            [0, 0] => return Key::Vertex(corners[0]),
            [a, 0] if a == lx => return Key::Vertex(corners[1]),
            [a, b] if a == lx && b == ly => return Key::Vertex(corners[2]),
            [0, b] if b == ly => return Key::Vertex(corners[3]),
            [a, 0] => (0, a, lx),
            [a, b] if a == lx => (1, b, ly),
            [a, b] if b == ly => (2, lx - a, lx),
            [0, b] => (3, ly - b, ly),
            [a, b] => return Key::Interior(p, a, b),
        };
        let (u, w) = (corners[side], corners[(side + 1) % 4]);
        if u < w {
            Key::Side(u, w, t)
        } else {
            Key::Side(w, u, len - t)
        }
    }

    /// Unit-square coordinates of lattice point `x` of patch `p`.
    fn local(&self, p: usize, x: [u64; 2]) -> [f64; 2] {
        let [lx, ly] = self.extent(p);
        [x[0] as f64 / lx as f64, x[1] as f64 / ly as f64]
    }

    /// Whether edge `k` of `cell` lies on patch side `k` (the only side it can lie on).
    fn on_side(&self, cell: &Cell, k: usize) -> bool {
        let [lx, ly] = self.extent(cell.patch);
        let c = cell.corners();
        match k {
            0 => c[0][1] == 0,
            1 => c[1][0] == lx,
            2 => c[2][1] == ly,
            _ => c[0][0] == 0,
        }
    }
}

/// Graded mesh of a general layout: root cells split by `gradings` (no grading: the uniform
/// root grid), 2:1 balanced, transition elements where a neighbour is finer; see the module
/// documentation. `map(patch, [u, v])` carries the unit square of each patch to the plane.
///
/// Node sets and edge sets are made for every named patch side, ordered along the boundary with
/// the body on the left.
///
/// # Panics
/// On an inconsistent layout (a patch without root cells, a side used twice in one direction,
/// or a shared side split into different numbers of root cells), a non-positive `min_size` or
/// zero `layers`.
pub fn graded_layout<F>(layout: &Layout, map: F, gradings: &[Grading]) -> Mesh
where
    F: Fn(usize, [f64; 2]) -> [f64; 2],
{
    graded_layout_with(layout, map, gradings, Transition::Elements)
}

/// How a graded mesh joins cells of different sizes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Transition {
    /// One element per leaf cell, with 5- and 6-node transition elements next to finer cells
    /// (the hybrid element's meshes; see the module documentation).
    #[default]
    Elements,
    /// 4-node quadrilaterals only (for elements that take nothing else, such as Pian-Sumihara
    /// and Q4): the balanced leaf cells are graded at twice the wanted element size, then every
    /// leaf is split into its four quadrants and each quadrant is meshed by a template, see
    /// [`graded_layout_with`]. Element sizes and band widths match those of
    /// [`Transition::Elements`] with the same gradings.
    Quads,
}

/// [`graded_layout`] with a choice of [`Transition`].
///
/// # Quad-only meshes (`Transition::Quads`)
/// Each grading is applied to the leaf cells with twice its `min_size` and half its `layers`
/// (at least 1), so the elements, half a leaf in size, come out as with
/// `Transition::Elements`. After the 2:1 balance every leaf is split into its four quadrants
/// (lower-left, lower-right, upper-right, upper-left). A leaf edge with a finer neighbour is
/// split at its quarter points (the fine neighbour's quadrant corners), any other leaf edge at
/// its midpoint. The four inner half-lines from the leaf centre to its edge midpoints are split
/// at their midpoints or not, chosen so that every quadrant has an even number of split sides
/// (always possible: the parities add up), with the fewest splits. A quadrant is then meshed by
/// one of three templates (no node inside the leaf other than lattice points at quarter
/// spacing, so every node is shared exactly through its lattice key and the mesh is
/// conforming without constraints):
/// * no split side: the quadrant itself;
/// * two opposite split sides: two quadrilaterals joined along the line between the two
///   midpoints;
/// * two adjacent split sides: three quadrilaterals around the quadrant centre (the corner
///   square between the two midpoints and two trapezoids with corner angles 45 and 135
///   degrees);
/// * four split sides: the four quarters.
///
/// No constraint equations and no hanging nodes: every element edge is shared with exactly one
/// other element or lies on the boundary. Nodes are mapped directly (no straightening is
/// needed, since no node hangs).
///
/// # Panics
/// As [`graded_layout`].
pub fn graded_layout_with<F>(
    layout: &Layout,
    map: F,
    gradings: &[Grading],
    transition: Transition,
) -> Mesh
where
    F: Fn(usize, [f64; 2]) -> [f64; 2],
{
    layout.check();
    for g in gradings {
        assert!(
            g.min_size > 0.0 && g.min_size.is_finite(),
            "min_size must be positive and finite"
        );
        assert!(g.layers >= 1, "grading needs at least one layer");
    }
    let (gradings, max_level): (Vec<Grading>, u8) = match transition {
        Transition::Elements => (gradings.to_vec(), MAX_LEVEL),
        Transition::Quads => (
            gradings
                .iter()
                .map(|g| Grading {
                    min_size: 2.0 * g.min_size,
                    layers: (g.layers / 2).max(1),
                    ..*g
                })
                .collect(),
            MAX_LEVEL - 2,
        ),
    };
    let place = |p: usize, x: [u64; 2]| map(p, layout.local(p, x));
    let quad = |c: &Cell| c.corners().map(|x| place(c.patch, x));
    let mut leaves = BTreeSet::new();
    let mut todo: Vec<Cell> = roots(layout);
    while let Some(cell) = todo.pop() {
        if cell.level < max_level && gradings.iter().any(|g| g.splits(&quad(&cell))) {
            todo.extend(cell.children());
        } else {
            leaves.insert(cell);
        }
    }
    let corner_keys = balance(layout, &mut leaves);
    match transition {
        Transition::Elements => build(layout, &leaves, &corner_keys, place),
        Transition::Quads => build_quads(layout, &leaves, &corner_keys, place),
    }
}

/// The root cells of every patch.
fn roots(layout: &Layout) -> Vec<Cell> {
    let mut cells = Vec::new();
    for (patch, p) in layout.patches.iter().enumerate() {
        for j in 0..p.roots[1] as u64 {
            for i in 0..p.roots[0] as u64 {
                cells.push(Cell {
                    patch,
                    level: 0,
                    i,
                    j,
                });
            }
        }
    }
    cells
}

/// Keys of all leaf corners.
fn corner_keys(layout: &Layout, leaves: &BTreeSet<Cell>) -> HashSet<Key> {
    leaves
        .iter()
        .flat_map(|c| c.corners().map(|x| layout.key(c.patch, x)))
        .collect()
}

/// Whether edge `k` of `cell` has a finer neighbour (its midpoint is a leaf corner).
fn hangs(layout: &Layout, corners: &HashSet<Key>, cell: &Cell, k: usize) -> bool {
    cell.level < MAX_LEVEL && corners.contains(&layout.key(cell.patch, cell.edge_point(k, 1, 2)))
}

/// Split leaves until 2:1 balanced with at most two hanging edges each; returns the final leaf
/// corner keys.
fn balance(layout: &Layout, leaves: &mut BTreeSet<Cell>) -> HashSet<Key> {
    loop {
        let corners = corner_keys(layout, leaves);
        let too_coarse = |c: &Cell| {
            let quarter = |k, n| corners.contains(&layout.key(c.patch, c.edge_point(k, n, 4)));
            let unbalanced =
                c.level + 2 <= MAX_LEVEL && (0..4).any(|k| quarter(k, 1) || quarter(k, 3));
            unbalanced || (0..4).filter(|&k| hangs(layout, &corners, c, k)).count() >= 3
        };
        let split: Vec<Cell> = leaves.iter().filter(|c| too_coarse(c)).copied().collect();
        if split.is_empty() {
            return corners;
        }
        for c in split {
            leaves.remove(&c);
            leaves.extend(c.children());
        }
    }
}

/// The leaves in the order their elements are emitted: by patch, then row by row (lower-left
/// corner's `y`, then `x`), so node and element numbers grow across each patch.
fn emission_order(leaves: &BTreeSet<Cell>) -> Vec<&Cell> {
    let mut order: Vec<&Cell> = leaves.iter().collect();
    order.sort_by_key(|c| {
        let x = c.corners()[0];
        (c.patch, x[1], x[0])
    });
    order
}

/// Number the nodes, emit the elements and boundary sets, straighten the transition edges.
fn build<P>(layout: &Layout, leaves: &BTreeSet<Cell>, corners: &HashSet<Key>, place: P) -> Mesh
where
    P: Fn(usize, [u64; 2]) -> [f64; 2],
{
    let order = emission_order(leaves);
    let mut mesh = Mesh::new();
    let mut ids: HashMap<Key, usize> = HashMap::new();
    let mut node = |mesh: &mut Mesh, p: usize, x: [u64; 2]| {
        *ids.entry(layout.key(p, x))
            .or_insert_with(|| mesh.push_node(place(p, x)))
    };
    let mut hanging: Vec<(u8, usize, usize, usize)> = Vec::new();
    let mut sides: BTreeMap<String, Vec<[usize; 2]>> = BTreeMap::new();
    let mut element = Vec::with_capacity(6);
    for cell in order {
        element.clear();
        let c = cell.corners();
        let cn = c.map(|x| node(&mut mesh, cell.patch, x));
        for k in 0..4 {
            element.push(cn[k]);
            if hangs(layout, corners, cell, k) {
                let m = node(&mut mesh, cell.patch, cell.edge_point(k, 1, 2));
                hanging.push((cell.level, m, cn[k], cn[(k + 1) % 4]));
                element.push(m);
            } else if let (true, Some(name)) = (
                layout.on_side(cell, k),
                &layout.patches[cell.patch].sides[k],
            ) {
                let edge = [cn[k], cn[(k + 1) % 4]];
                sides.entry(name.clone()).or_default().push(edge);
            }
        }
        mesh.push_element(&element, layout.patches[cell.patch].material);
    }
    hanging.sort_by_key(|h| h.0);
    for (_, m, a, b) in hanging {
        let (pa, pb) = (mesh.nodes[a], mesh.nodes[b]);
        mesh.nodes[m] = [0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1])];
    }
    name_sides(&mut mesh, sides);
    mesh
}

/// Name the boundary sides: each side's edges chained along the boundary as an edge set, and
/// their nodes as a node set of the same name.
fn name_sides(mesh: &mut Mesh, sides: BTreeMap<String, Vec<[usize; 2]>>) {
    for (name, edges) in sides {
        let edges = chain(edges);
        mesh.node_sets.insert(name.clone(), chain_nodes(&edges));
        mesh.edge_sets.insert(name, edges);
    }
}

/// Quad-only elements from the balanced leaves (see [`graded_layout_with`]).
fn build_quads<P>(
    layout: &Layout,
    leaves: &BTreeSet<Cell>,
    corners: &HashSet<Key>,
    place: P,
) -> Mesh
where
    P: Fn(usize, [u64; 2]) -> [f64; 2],
{
    let order = emission_order(leaves);
    let mut mesh = Mesh::new();
    let mut ids: HashMap<Key, usize> = HashMap::new();
    let mut sides: BTreeMap<String, Vec<[usize; 2]>> = BTreeMap::new();
    for cell in order {
        let s = (ROOT >> cell.level) / 4;
        let [x0, y0] = cell.corners()[0];
        // node at quarter-lattice point (a, b) of the leaf, a, b in 0..=4
        let mut node = |mesh: &mut Mesh, [a, b]: [u64; 2]| {
            let x = [x0 + a * s, y0 + b * s];
            *ids.entry(layout.key(cell.patch, x))
                .or_insert_with(|| mesh.push_node(place(cell.patch, x)))
        };
        let fine: [bool; 4] = std::array::from_fn(|k| hangs(layout, corners, cell, k));
        for quad in leaf_template(fine) {
            let element = quad.map(|p| node(&mut mesh, p));
            mesh.push_element(&element, layout.patches[cell.patch].material);
        }
        // boundary edges (a leaf edge on a named patch side), split as the template splits it
        const CORNER: [[u64; 2]; 4] = [[0, 0], [4, 0], [4, 4], [0, 4]];
        for k in 0..4 {
            let (true, Some(name)) = (
                layout.on_side(cell, k),
                &layout.patches[cell.patch].sides[k],
            ) else {
                continue;
            };
            let (a, b) = (CORNER[k], CORNER[(k + 1) % 4]);
            let steps: u64 = if fine[k] { 4 } else { 2 };
            let point = |i: u64| {
                let t = |p: u64, q: u64| (p * (steps - i) + q * i) / steps;
                [t(a[0], b[0]), t(a[1], b[1])]
            };
            for i in 0..steps {
                let edge = [node(&mut mesh, point(i)), node(&mut mesh, point(i + 1))];
                sides.entry(name.clone()).or_default().push(edge);
            }
        }
    }
    name_sides(&mut mesh, sides);
    mesh
}

/// The quadrilaterals of one leaf, in quarter-lattice coordinates of the leaf (0..=4 along each
/// axis), counter-clockwise; `fine[k]`: leaf edge `k` has a finer neighbour (split at its
/// quarter points). See [`graded_layout_with`].
fn leaf_template(fine: [bool; 4]) -> Vec<[[u64; 2]; 4]> {
    // quadrants q = 0..4 (lower-left, lower-right, upper-right, upper-left); quadrant side j
    // (bottom, right, top, left) is split when it lies on a fine leaf edge or is a split inner
    // half-line. Inner half-lines: 0 between quadrants 0 and 1 (x = 2, lower), 1 between 1
    // and 2 (y = 2, right), 2 between 2 and 3 (x = 2, upper), 3 between 3 and 0 (y = 2, left).
    let outer = |q: usize| u8::from(fine[q]) + u8::from(fine[(q + 3) % 4]);
    // quadrant q's sides on leaf edges: edges q and q + 3 (mod 4); its inner half-lines: q
    // (to the next quadrant) and q + 3 (to the previous one)
    let solve = |first: bool| {
        let mut inner = [first, false, false, false];
        for q in 1..4 {
            // quadrant q has inner half-lines q - 1 and q
            inner[q] = (outer(q) + u8::from(inner[q - 1])) % 2 == 1;
        }
        inner
    };
    let inner = [solve(false), solve(true)]
        .into_iter()
        .min_by_key(|i| i.iter().filter(|&&b| b).count())
        .expect("two candidates");
    debug_assert_eq!((outer(0) + u8::from(inner[0]) + u8::from(inner[3])) % 2, 0);
    const ORIGIN: [[u64; 2]; 4] = [[0, 0], [2, 0], [2, 2], [0, 2]];
    let mut quads = Vec::with_capacity(12);
    for (q, o) in ORIGIN.into_iter().enumerate() {
        // which of the quadrant's own sides (bottom, right, top, left) lie on leaf edges and
        // which on inner half-lines
        let split: [bool; 4] = match q {
            0 => [fine[0], inner[0], inner[3], fine[3]],
            1 => [fine[0], fine[1], inner[1], inner[0]],
            2 => [inner[1], fine[1], fine[2], inner[2]],
            _ => [inner[3], inner[2], fine[2], fine[3]],
        };
        let at = |dx: u64, dy: u64| [o[0] + dx, o[1] + dy];
        let c = [at(0, 0), at(2, 0), at(2, 2), at(0, 2)];
        let m = [at(1, 0), at(2, 1), at(1, 2), at(0, 1)];
        let p = at(1, 1);
        match split {
            [false, false, false, false] => quads.push(c),
            [true, true, true, true] => {
                for k in 0..4 {
                    quads.push([c[k], m[k], p, m[(k + 3) % 4]]);
                }
            }
            [true, false, true, false] => {
                quads.push([c[0], m[0], m[2], c[3]]);
                quads.push([m[0], c[1], c[2], m[2]]);
            }
            [false, true, false, true] => {
                quads.push([c[0], c[1], m[1], m[3]]);
                quads.push([m[3], m[1], c[2], c[3]]);
            }
            _ => {
                // two adjacent split sides j and j + 1, sharing corner j + 1
                let j = (0..4)
                    .find(|&j| split[j] && split[(j + 1) % 4])
                    .expect("an even number of split sides");
                let r = |k: usize| c[(j + k) % 4];
                let (ma, mb) = (m[j], m[(j + 1) % 4]);
                quads.push([r(0), ma, p, r(3)]);
                quads.push([ma, r(1), mb, p]);
                quads.push([p, mb, r(2), r(3)]);
            }
        }
    }
    quads
}

/// Order directed edges into chains (each edge followed by the one starting at its end);
/// chains are listed in the order of their first edge in the input.
fn chain(edges: Vec<[usize; 2]>) -> Vec<[usize; 2]> {
    let next: HashMap<usize, [usize; 2]> = edges.iter().map(|e| (e[0], *e)).collect();
    let ends: HashSet<usize> = edges.iter().map(|e| e[1]).collect();
    let mut out = Vec::with_capacity(edges.len());
    let mut used = HashSet::new();
    let starts = edges
        .iter()
        .filter(|e| !ends.contains(&e[0]))
        .chain(edges.iter());
    for start in starts {
        let mut e = *start;
        while used.insert(e[0]) {
            out.push(e);
            match next.get(&e[1]) {
                Some(&n) => e = n,
                None => break,
            }
        }
    }
    out
}

/// The nodes of chained edges in order, each once.
fn chain_nodes(edges: &[[usize; 2]]) -> Vec<usize> {
    let mut seen = HashSet::new();
    edges
        .iter()
        .flatten()
        .copied()
        .filter(|n| seen.insert(*n))
        .collect()
}

/// One patch with `nx0 x ny0` root cells carried to the plane by `map` from the unit square;
/// sides named `"bottom"` (v = 0), `"right"` (u = 1), `"top"` (v = 1), `"left"` (u = 0). This is
/// the general entry for a single mapped block; `map` must be orientation preserving.
pub fn graded_mapped<F>(nx0: usize, ny0: usize, map: F, gradings: &[Grading]) -> Mesh
where
    F: Fn([f64; 2]) -> [f64; 2],
{
    graded_mapped_with(nx0, ny0, map, gradings, Transition::Elements)
}

/// [`graded_mapped`] with a choice of [`Transition`].
pub fn graded_mapped_with<F>(
    nx0: usize,
    ny0: usize,
    map: F,
    gradings: &[Grading],
    transition: Transition,
) -> Mesh
where
    F: Fn([f64; 2]) -> [f64; 2],
{
    let names = ["bottom", "right", "top", "left"].map(|s| Some(s.to_string()));
    let layout = Layout {
        patches: vec![Patch {
            corners: [0, 1, 2, 3],
            roots: [nx0, ny0],
            material: 0,
            sides: names,
        }],
    };
    graded_layout_with(&layout, |_, uv| map(uv), gradings, transition)
}

/// The rectangle `[x0, x0 + width] x [y0, y0 + height]` with `nx0 x ny0` root cells, graded by
/// `grading`; node and edge sets `"left"`, `"right"`, `"top"`, `"bottom"`. Use square root cells
/// (`width / nx0 = height / ny0`) for square elements.
pub fn graded_rectangle(
    x0: f64,
    y0: f64,
    width: f64,
    height: f64,
    nx0: usize,
    ny0: usize,
    grading: &Grading,
) -> Mesh {
    graded_rectangle_with(
        x0,
        y0,
        [width, height],
        [nx0, ny0],
        std::slice::from_ref(grading),
        Transition::Elements,
    )
}

/// [`graded_rectangle`] with several gradings and a choice of [`Transition`]: the rectangle
/// `[x0, x0 + size[0]] x [y0, y0 + size[1]]` with `roots[0] x roots[1]` root cells.
pub fn graded_rectangle_with(
    x0: f64,
    y0: f64,
    size: [f64; 2],
    roots: [usize; 2],
    gradings: &[Grading],
    transition: Transition,
) -> Mesh {
    graded_mapped_with(
        roots[0],
        roots[1],
        |[u, v]| [x0 + u * size[0], y0 + v * size[1]],
        gradings,
        transition,
    )
}

/// Cook's membrane: corners (0, 0), (48, 44), (48, 60), (0, 44), `n x n` elements by the
/// bilinear map of the unit square, material 0. Sets: node set `"clamped"` (x = 0), edge set
/// `"loaded"` (x = 48, bottom to top), node set `"tip"` (the node at (48, 52) when `n` is even,
/// empty when odd), and `"left"`, `"right"`, `"top"`, `"bottom"` node and edge sets.
pub fn cooks_membrane(n: usize) -> Mesh {
    // (1-u)(1-v) (0,0) + u(1-v) (48,44) + uv (48,60) + (1-u)v (0,44)
    let bilinear = |[u, v]: [f64; 2]| [48.0 * u, 44.0 * u + 44.0 * v - 28.0 * u * v];
    let mut mesh = graded_mapped(n, n, bilinear, &[]);
    let tip: Vec<usize> = mesh.node_sets["right"]
        .iter()
        .copied()
        .filter(|&i| n.is_multiple_of(2) && (mesh.nodes[i][1] - 52.0).abs() < 1e-9)
        .collect();
    mesh.node_sets.insert("tip".into(), tip);
    mesh.node_sets
        .insert("clamped".into(), mesh.node_sets["left"].clone());
    mesh.edge_sets
        .insert("loaded".into(), mesh.edge_sets["right"].clone());
    mesh
}

/// The beam `[0, length] x [-height/2, height/2]` with `nx x ny` elements. Distortion rule
/// (Pian-Sumihara): node `(i, j)` sits at `x = i length / nx + distortion * (2 y / height)` for
/// interior vertical lines `0 < i < nx` (the top node moves by `+distortion`, the bottom one by
/// `-distortion`, the centre not at all) and at `x = i length / nx` on the two ends; `y = -height
/// / 2 + j height / ny`. Node sets `"left"`, `"right"` (all nodes on x = 0 / x = length) and edge
/// sets `"left"`, `"right"`, `"top"`, `"bottom"` (body on the left, so `"left"` runs downward).
pub fn beam(length: f64, height: f64, nx: usize, ny: usize, distortion: f64) -> Mesh {
    let map = |[u, v]: [f64; 2]| {
        let y = (v - 0.5) * height;
        let s = u * nx as f64;
        let interior = if nx < 2 {
            0.0
        } else {
            s.min(nx as f64 - s).min(1.0)
        };
        [u * length + distortion * (2.0 * y / height) * interior, y]
    };
    graded_mapped(nx, ny, map, &[])
}

/// Coarse layout of the lower half disk of radius 1 centred at (0, 1): an O-grid (see
/// [`half_disk`]). Returns the layout and its vertex positions.
fn half_disk_layout() -> (Layout, [[f64; 2]; 11]) {
    let s = std::f64::consts::FRAC_1_SQRT_2;
    // inner corners on the 225 and 315 degree rays, HALF_DISK_INNER from the centre
    let r = HALF_DISK_INNER * s;
    let v = [
        [-1.0, 1.0],    // 0 P0: left end of the flat face
        [-s, 1.0 - s],  // 1 A0: arc at 225 degrees
        [0.0, 0.0],     // 2 M: contact point
        [s, 1.0 - s],   // 3 A1: arc at 315 degrees
        [1.0, 1.0],     // 4 P1: right end of the flat face
        [-r, 1.0 - r],  // 5 I0
        [0.0, 1.0 - r], // 6 Mi
        [r, 1.0 - r],   // 7 I1
        [-r, 1.0],      // 8 Q0
        [0.0, 1.0],     // 9 Qm
        [r, 1.0],       // 10 Q1
    ];
    let name = |s: &str| Some(s.to_string());
    let patch = |corners, roots, sides| Patch {
        corners,
        roots,
        material: 0,
        sides,
    };
    let patches = vec![
        patch([0, 1, 5, 8], [2, 1], [name("arc"), None, None, name("top")]),
        patch([1, 2, 6, 5], [2, 1], [name("arc"), None, None, None]),
        patch([2, 3, 7, 6], [2, 1], [name("arc"), None, None, None]),
        patch(
            [3, 4, 10, 7],
            [2, 1],
            [name("arc"), name("top"), None, None],
        ),
        patch([5, 6, 9, 8], [2, 2], [None, None, name("top"), None]),
        patch([6, 7, 10, 9], [2, 2], [None, None, name("top"), None]),
    ];
    (Layout { patches }, v)
}

/// Distance of the inner O-grid corners from the disk centre, in radii.
const HALF_DISK_INNER: f64 = 0.75;

/// Point at parameter `t` along the curve from vertex `a` to vertex `b` of the half-disk layout:
/// arcs between consecutive vertices 0..4 (angles 180, 225, 270, 315, 360 degrees), straight
/// otherwise.
fn half_disk_curve(v: &[[f64; 2]; 11], a: usize, b: usize, t: f64) -> [f64; 2] {
    if a.max(b) <= 4 && a.abs_diff(b) == 1 {
        let angle = |i: usize| std::f64::consts::PI * (1.0 + i as f64 / 4.0);
        let phi = angle(a) + t * (angle(b) - angle(a));
        [phi.cos(), 1.0 + phi.sin()]
    } else {
        [
            v[a][0] + t * (v[b][0] - v[a][0]),
            v[a][1] + t * (v[b][1] - v[a][1]),
        ]
    }
}

/// Coons (transfinite) map of patch `p` of the half-disk layout, radius 1.
fn half_disk_map(layout: &Layout, v: &[[f64; 2]; 11], p: usize, [x, y]: [f64; 2]) -> [f64; 2] {
    let c = layout.patches[p].corners;
    let side = |k: usize, t: f64| {
        let (a, b) = (c[k], c[(k + 1) % 4]);
        // evaluate from the lower vertex id so both patches of a side agree bit for bit
        if a < b {
            half_disk_curve(v, a, b, t)
        } else {
            half_disk_curve(v, b, a, 1.0 - t)
        }
    };
    match (x, y) {
        (_, 0.0) => return side(0, x),
        (1.0, _) => return side(1, y),
        (_, 1.0) => return side(2, 1.0 - x),
        (0.0, _) => return side(3, 1.0 - y),
        _ => {}
    }
    let (bot, right, top, left) = (side(0, x), side(1, y), side(2, 1.0 - x), side(3, 1.0 - y));
    let corner = |k: usize| v[c[k]];
    let w = [(1.0 - x) * (1.0 - y), x * (1.0 - y), x * y, (1.0 - x) * y];
    let mut out = [0.0; 2];
    for d in 0..2 {
        out[d] = (1.0 - y) * bot[d] + y * top[d] + (1.0 - x) * left[d] + x * right[d]
            - (0..4).map(|k| w[k] * corner(k)[d]).sum::<f64>();
    }
    out
}

/// The lower half of the disk of radius `radius` centred at (0, radius): its lowest point, the
/// contact point, is the origin and its flat face is y = radius. Graded by `grading` (usually
/// toward the point (0, 0) or a segment along the bottom).
///
/// Layout: an O-grid of six patches with Coons (transfinite) maps: two inner squares under the
/// flat face (their lower corners on the 225 and 315 degree rays at 0.75 radius from the centre,
/// 2 x 2 root cells each) and four ring patches under the arc, each spanning 45 degrees (2 x 1
/// root cells). Why not the single-block elliptical-grid map of the square `[-1, 1] x [-1, 0]`:
/// it sends two corners of the square to smooth points of the arc, where the corner cells get an
/// interior angle of about `180 - 45 s` degrees (`s` the cell size in radii), about 169 degrees
/// for the quarter-radius cells grading puts there, and its cells at the contact point have
/// aspect `sqrt(2)`. The O-grid's worst corner angle is 135 degrees (where three patches meet);
/// the inner-corner distance 0.75 balances the aspect at the contact point (about 1.2, cells
/// slightly taller than wide) against the ring cells at the 225 / 315 degree rays (about 1.8).
/// Arc nodes are on the circle to round-off.
///
/// Sets: edge and node sets `"arc"` (left to right along the bottom, body on the left),
/// `"top"` (the flat face, right to left), node set `"bottom"` (the lowest node).
pub fn half_disk(radius: f64, grading: &Grading) -> Mesh {
    half_disk_with(radius, std::slice::from_ref(grading), Transition::Elements)
}

/// [`half_disk`] with several gradings and a choice of [`Transition`].
pub fn half_disk_with(radius: f64, gradings: &[Grading], transition: Transition) -> Mesh {
    let (layout, v) = half_disk_layout();
    let unit: Vec<Grading> = gradings
        .iter()
        .map(|g| Grading {
            target: match g.target {
                Target::Point(p) => Target::Point(p.map(|c| c / radius)),
                Target::Line(a, b) => Target::Line(a.map(|c| c / radius), b.map(|c| c / radius)),
            },
            min_size: g.min_size / radius,
            layers: g.layers,
        })
        .collect();
    let mut mesh = graded_layout_with(
        &layout,
        |p, uv| half_disk_map(&layout, &v, p, uv),
        &unit,
        transition,
    );
    for p in &mut mesh.nodes {
        *p = p.map(|c| c * radius);
    }
    let lowest = (0..mesh.n_nodes())
        .min_by(|&a, &b| {
            let key = |i: usize| (mesh.nodes[i][1], mesh.nodes[i][0].abs());
            key(a).partial_cmp(&key(b)).expect("finite coordinates")
        })
        .expect("a mesh has nodes");
    mesh.node_sets.insert("bottom".into(), vec![lowest]);
    mesh
}

/// Whether `p` is inside or on the quadrilateral `quad` (either orientation, convex).
fn inside(quad: &[[f64; 2]; 4], p: [f64; 2]) -> bool {
    let s: Vec<f64> = (0..4)
        .map(|k| cross(quad[k], quad[(k + 1) % 4], p))
        .collect();
    s.iter().all(|&c| c >= 0.0) || s.iter().all(|&c| c <= 0.0)
}

/// `(b - a) x (p - a)`.
fn cross(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
}

/// Distance from `p` to the segment `a b`.
fn point_segment(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let d = [b[0] - a[0], b[1] - a[1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p[0] - a[0] - t * d[0]).hypot(p[1] - a[1] - t * d[1])
}

/// Distance between the segments `p q` and `a b`.
fn segment_segment(p: [f64; 2], q: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (c1, c2) = (cross(p, q, a), cross(p, q, b));
    let (c3, c4) = (cross(a, b, p), cross(a, b, q));
    if c1 * c2 <= 0.0 && c3 * c4 <= 0.0 && (c1 != 0.0 || c2 != 0.0 || c3 != 0.0 || c4 != 0.0) {
        return 0.0;
    }
    point_segment(p, a, b)
        .min(point_segment(q, a, b))
        .min(point_segment(a, p, q))
        .min(point_segment(b, p, q))
}

/// Longest edge of a quadrilateral.
fn longest_edge(quad: &[[f64; 2]; 4]) -> f64 {
    (0..4)
        .map(|k| {
            let (a, b) = (quad[k], quad[(k + 1) % 4]);
            (b[0] - a[0]).hypot(b[1] - a[1])
        })
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_agree_across_a_shared_side() {
        let (layout, _) = half_disk_layout();
        // patch 1 side 1 (M -> Mi) is patch 2 side 3 (Mi -> M): both have v = 0 at M
        let a = layout.key(1, [2 * ROOT, ROOT / 4]);
        let b = layout.key(2, [0, ROOT / 4]);
        assert_eq!(a, b);
        // patch 1 side 2 (Mi -> I0) is patch 4 side 0 (I0 -> Mi)
        assert_eq!(
            layout.key(1, [ROOT / 2, ROOT]),
            layout.key(4, [ROOT / 2, 0])
        );
        assert_eq!(layout.key(1, [2 * ROOT, 0]), Key::Vertex(2));
    }

    #[test]
    fn chain_orders_edges() {
        let edges = chain(vec![[3, 4], [1, 2], [2, 3]]);
        assert_eq!(edges, vec![[1, 2], [2, 3], [3, 4]]);
        assert_eq!(chain_nodes(&edges), vec![1, 2, 3, 4]);
    }

    #[test]
    fn leaf_templates_tile_the_leaf_conformingly() {
        // every pattern of fine edges, also 3 and 4 (which balancing avoids)
        for bits in 0..16u8 {
            let fine: [bool; 4] = std::array::from_fn(|k| bits & (1 << k) != 0);
            let quads = leaf_template(fine);
            let mut area2 = 0i64;
            let mut segments: HashMap<[[u64; 2]; 2], usize> = HashMap::new();
            for q in &quads {
                let p = q.map(|[x, y]| [x as i64, y as i64]);
                let a2: i64 = (0..4)
                    .map(|k| {
                        let (a, b) = (p[k], p[(k + 1) % 4]);
                        a[0] * b[1] - a[1] * b[0]
                    })
                    .sum();
                area2 += a2;
                for k in 0..4 {
                    // strictly convex, counter-clockwise
                    let (a, b, c) = (p[k], p[(k + 1) % 4], p[(k + 2) % 4]);
                    let cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
                    assert!(cross > 0, "pattern {fine:?}: quad {q:?} not convex");
                    *segments.entry([q[k], q[(k + 1) % 4]]).or_default() += 1;
                }
            }
            assert_eq!(
                area2,
                2 * 16,
                "pattern {fine:?}: quads do not tile the leaf"
            );
            // interior segments are matched by their reverse; boundary segments split the leaf
            // edges at quarter points where fine, at the midpoint elsewhere
            let mut boundary = [0usize; 4];
            for (&[a, b], &count) in &segments {
                assert_eq!(count, 1);
                let on_edge = |k: usize, p: [u64; 2]| match k {
                    0 => p[1] == 0,
                    1 => p[0] == 4,
                    2 => p[1] == 4,
                    _ => p[0] == 0,
                };
                match (0..4).find(|&k| on_edge(k, a) && on_edge(k, b)) {
                    Some(k) => {
                        boundary[k] += 1;
                        let len = a[0].abs_diff(b[0]) + a[1].abs_diff(b[1]);
                        assert_eq!(len, if fine[k] { 1 } else { 2 }, "pattern {fine:?}");
                    }
                    None => assert!(segments.contains_key(&[b, a]), "pattern {fine:?}"),
                }
            }
            let expected = fine.map(|f| if f { 4 } else { 2 });
            assert_eq!(boundary, expected, "pattern {fine:?}");
        }
    }

    #[test]
    fn distances() {
        let quad = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert_eq!(Target::Point([0.5, 0.5]).distance_to_quad(&quad), 0.0);
        assert!((Target::Point([2.0, 0.5]).distance_to_quad(&quad) - 1.0).abs() < 1e-15);
        assert_eq!(
            Target::Line([-1.0, 0.5], [3.0, 0.5]).distance_to_quad(&quad),
            0.0
        );
        assert!(
            (Target::Line([-1.0, 3.0], [3.0, 3.0]).distance_to_quad(&quad) - 2.0).abs() < 1e-15
        );
    }
}
