//! Contact-element kernels: the mortar integrals of one contact pair at given nodal positions
//! (docs/method.md, "Contact surfaces and contact elements"): the current ones `x = X + U` for finite kinematics, the reference
//! ones `X` (once per analysis) for small kinematics.
//!
//! # Conventions
//! * A contact pair is a **multiplier-side polyline A** and an **opposite polyline B**, each a
//!   list of node ids of one body's boundary, ordered so that the body lies on the **left** of
//!   every segment (the [`crate::mesh::Mesh`] edge convention). Node ids index the slice `x` of
//!   positions of all nodes (`x = X + U` below; `X` for small kinematics).
//! * A segment `p0 -> p1` of A with `d = p1 - p0`, `h = |d|`, unit tangent `t = d / h`, has the
//!   outward normal `n = (d_y, -d_x) / h` (`d` rotated clockwise: it points away from A, into B)
//!   and `s = (n_y, -n_x)` (so `s = -t`). B's outward normal is defined the same way from B's
//!   own orientation; a B segment **faces** an A segment when `n_B . n < 0`, i.e.
//!   `(q1 - q0) . t < 0`.
//! * The contact traction `t` is the traction acting **on A**, linear on every A segment between
//!   nodal values (`M_k` = the hat function of A node `k` along A's polyline; quadratic on a
//!   segment ending on the axis, see "Nodes on the axis" below); `tn < 0` is compression. The
//!   traction on B is `-t`.
//! * Every point `x^A(xi) = p0 + xi d`, `xi in [0, 1]`, of an A segment is projected **along
//!   that segment's constant normal `n`** onto B: the hit point `x^B` solves
//!   `(x^B - x^A(xi)) . t = 0` on a facing B segment. Its **signed distance**
//!   `g(xi) = (x^B - x^A) . n` is positive for an open gap and negative for penetration, and
//!   `x^A - x^B = -g n`. When several facing B segments are hit, the one with the smallest
//!   `|g|` is used; B segments that do not face A are ignored, and so are hits with
//!   `|g| > search_distance` (the point counts as uncovered).
//! * With a single B segment `q0 -> q1` hit, `tau_i = (q_i - p0) . t / h` is where B's node
//!   projects on the A segment, and the hit point has B parameter
//!   `eta = (xi - tau0) / (tau1 - tau0)`: affine in `xi`. The A segment is therefore split at
//!   every `tau` of a B node (and where the choice of B segment changes: `|g_i| = |g_j|`, or
//!   `|g| = search_distance`), and a 2-point Gauss rule per piece integrates every product
//!   below (degree 2 in `xi`) **exactly**.
//! * B nodes that project within `1e-10 h` of an A segment's end are taken to project onto it,
//!   so that surfaces of equal extent report full coverage despite round-off.
//!
//! # The surface measure
//! Every integral below is over A's surface with the measure `dS = m(x^A) ds` of body A (the
//! multiplier side), [`SurfaceMeasure`]: `m = t_A` (A's thickness) in plane analysis,
//! `m = 2 pi r` (`r = x^A_0` at the integration point, the full circle) in axisymmetric
//! analysis. The multipliers are then tractions per unit area (pressures) for every analysis
//! kind and thickness, and the nodal forces `F^A^T t`, `F^B^T t` are forces on the whole body
//! (per thickness `t_A`, or over the whole circle), as the element kernels' are. `r` is linear
//! along a segment, so the measure adds one polynomial degree to every integrand: the
//! closed forms below stay exact and so does the 2-point Gauss rule per piece (degree 3).
//!
//! # What is computed per A node `k` ([`ContactNode`])
//! With `ds = h dxi` on each of the one or two A segments adjacent to `k` (its *support*):
//! * `weight_k = integral M_k dS` (the tributary measure: `t (h_left + h_right) / 2` in plane,
//!   `sum_e 2 pi h_e (2 r_k + r_other) / 6` in axisymmetry with linear hats);
//! * `F^A_kj = integral M_k L^A_j dS` over the covered part of the support, as `F^B` and `R_C`
//!   are. For a fully covered node that is the whole support, in closed form (plane: `t h/3` on
//!   the diagonal, `t h/6` off it, summed over the two segments; with `m` linear on a segment
//!   from `m_k` to `m_j`: `h (3 m_k + m_j) / 12` on the diagonal and `h (m_k + m_j) / 12` off
//!   it); for a partly covered node it is integrated piece by piece with the rest. A node of
//!   which nothing is covered has no gap (it is infinite) and keeps the whole support's
//!   `F^A`, a regular row: under finite kinematics an iterate that carries B out of reach of a
//!   node the iteration still holds active must not leave it an empty row (a singular small
//!   system); the coverage check refuses such a node at convergence;
//! * `F^B_kj = integral M_k(xi) L^B_j(x^B(xi)) dS` over the covered part of the support,
//!   `L^B_j` the hat functions of B's polyline at the hit point;
//! * `R_C,k = integral M_k (x^A - x^B) dS = -integral M_k g n dS` (a 2-vector, the weighted
//!   mismatch, over the covered part);
//! * the nodal frame: `n_k = normalise(sum_e w_ke n_e)` over the adjacent segments `e`, with
//!   `w_ke = integral_e M_k dS` (in plane `w_ke = t h_e / 2`: the **length-weighted** average
//!   of the segment normals); this is the direction of `integral M_k n dS`, so a constant gap
//!   gives `R_C,k` parallel to `n_k` exactly), and `s_k = (n_k.y, -n_k.x)`;
//! * `coverage_k in [0, 1]`: the fraction of the support's length where a facing B segment was
//!   found within `search_distance` (exactly `1.0` when fully covered);
//! * `normal_gap_k = -n_k . R_C,k / integral_covered M_k dS`, a length, negative = penetration
//!   (equal to `-n_k . R_C,k / weight_k` when fully covered);
//! * the **coupling row** `c_kj`: `+F^A_kj` at A nodes, `-F^B_kj` at B nodes, so that with
//!   nodal displacement increments `du`, `sum_j c_kj du_j` is the change of `R_C,k` with the
//!   pairing (the projection) frozen. Its normal part `n_k . sum_j c_kj du_j` is the linearised
//!   normal row of the contact constraint; at zero gap it is the exact first-order change of
//!   `-n_k . R_C,k` wherever A is straight across node `k` (at a kink of A of angle `theta` it
//!   differs by a tangential term of relative size `sin(theta / 2)`). The tangential row
//!   `s_k . sum_j c_kj du_j` measures relative slip at the frozen pairing; it is *not* the
//!   derivative of `s_k . R_C,k`, which stays about zero by construction because the projection
//!   follows a tangential motion. `F^A` and `F^B` cover the same part of the support, so
//!   `sum_j c_kj = covered_weight - covered_weight = 0` for every node with any coverage (a
//!   rigid translation leaves `R_C,k` unchanged), and the gap linearised from the row,
//!   `-n_k . (R_C,k + sum_j c_kj du_j) / covered_weight` (the gap of small kinematics), is
//!   the covered mean of `g` at the moved positions with the pairing frozen, as
//!   `normal_gap` is, for a partly covered node too.
//!
//! Column sums of the B part give B's nodal weights over the projected overlap:
//! `sum_k F^B_kj = integral L^B_j dS` (the hats `M_k` sum to one), for turning B's nodal
//! forces into pressures.
//!
//! # Nodes on the axis
//! In axisymmetry an end node of A at `r = 0` (a meridian ending on the axis, within `1e-10`
//! of its segment's length) carries the pressure at the centre of a contact zone. The
//! traction of a solid of revolution is even in `r`, so `dt/dr = 0` there; on the segment
//! from the axis node to its neighbour the shapes are quadratic in the distance `s = r / h`
//! from the axis, `M_axis = 1 - s^2`, `M_next = s^2` (zero slope at `r = 0`, a partition of
//! unity, exact for `t = t0 + c r^2`). With linear hats the axis node's `F^A` column is
//! `2 pi h^2 (1/12, 1/12)` (its own and its neighbour's multiplier): its force `f_0` fixes only
//! `t_0 + t_1`, and a relative error of `f_0` (the one nodal force of an axisymmetric
//! discretisation that has no neighbour beyond the axis) reaches `t_0` amplified 2.3 times
//! (one of `f_1`, -1.9 times; uniform segments); with the quadratic shapes the column is
//! `2 pi h^2 (7/60, 3/60)` and the factors 1.6 and -0.8. The
//! axis node has a positive weight (`2 pi h^2 / 4` for a segment along `r`), a normal that is
//! its one segment's normal, and a normal row like any other node's; its radial
//! displacement is the model's business (prescribed `u_r = 0`). The quadratic integrands
//! (degree at most 4 with the measure) are integrated by a 3-point Gauss rule per piece.
//! Its radius is checked for `r >= 0` to round-off of its segments' length (a free axis node
//! drifts by round-off of its motion under finite kinematics). Where A and B both end on the
//! axis, B's end covers the part of A's axis segment between A's axis node and the projection
//! of B's (a sliver of the order of the gap times the segments' tilt under finite kinematics,
//! where the surfaces meet their mirror images across the axis): B's end values are taken
//! there, as for a B node within `END_SNAP` (1e-10 of the segment) of an A segment's end. The
//! iteration gives an A node on the axis no friction (`on_axis`): the shear traction vanishes
//! there by symmetry.
//!
//! # Candidate search
//! B's segments are binned once per call in a uniform grid (cell size: the largest of the mean
//! A segment length, the mean B segment length and `search_distance`; long segments are binned
//! piece by piece), stored as a sorted list of `(cell, segment)` pairs. Each A segment queries the
//! cells under its projection strip (`xi in [0, 1]`, `|g| <= search_distance`), again piece by
//! piece, and every candidate is tested exactly. The cost is near-linear in the number of
//! segments.

pub use crate::contact::geometry::{ContactNode, ContactSurface};
use crate::contact::space::{Frame, Vector};
use crate::element::geometry::{GAUSS2_UNIT, GAUSS3, edge_normal};
use crate::error::{Error, Result};

/// The measure `dS = m(x) ds` of body A's contact surface (see the [module docs](self)): the
/// contact integrals are weighted by it, so that the multipliers are pressures. It is the
/// shared measure of the analysis kinds, [`crate::fem::Measure`].
pub type SurfaceMeasure = crate::fem::Measure;

impl SurfaceMeasure {
    /// The integrals of one A node over its support (the segment `left -> x_k` ending at it
    /// and the segment `x_k -> right` starting at it, each when present): `(weight, [F^A with
    /// the left node, with itself, with the right node], normal direction)`, the direction
    /// `sum_e w_ke n_e` unnormalised, with its length and the scale it is compared with (see
    /// the [module docs](self)). In plane these are `t` times the length forms (`h/6`,
    /// `h/3`, the rotated chord), bit for bit those of unit thickness when `t = 1`.
    fn node_integrals(
        &self,
        left: Option<([f64; 2], Hats)>,
        xk: [f64; 2],
        right: Option<([f64; 2], Hats)>,
    ) -> NodeIntegrals {
        let (nl, hl) = left.map_or(([0.0; 2], 0.0), |(p, _)| edge_normal(p, xk));
        let (nr, hr) = right.map_or(([0.0; 2], 0.0), |(q, _)| edge_normal(xk, q));
        match *self {
            SurfaceMeasure::Plane { thickness: t } => {
                // sum_e h_e n_e = (x_{k+1} - x_{k-1}) rotated clockwise
                let (n, len) =
                    edge_normal(left.map_or(xk, |(p, _)| p), right.map_or(xk, |(q, _)| q));
                NodeIntegrals {
                    weight: 0.5 * (hl + hr) * t,
                    mass: [hl / 6.0 * t, (hl + hr) / 3.0 * t, hr / 6.0 * t],
                    normal: n,
                    normal_length: len,
                    normal_scale: hl + hr,
                }
            }
            SurfaceMeasure::Axisymmetric => {
                let m = |x: [f64; 2]| self.at(x);
                let mk = m(xk);
                // integral_e M_k dS and the mass entries of each segment (node k second on the
                // left one, first on the right one)
                let none = SegmentMoments::default();
                let l = left.map_or(none, |(p, hats)| hats.moments(hl, [m(p), mk]));
                let r = right.map_or(none, |(q, hats)| hats.moments(hr, [mk, m(q)]));
                let (wl, wr) = (l.weight[1], r.weight[0]);
                if wl + wr <= 0.0 {
                    // a support lying on the axis: no measure, the chord's normal
                    let none = SurfaceMeasure::Plane { thickness: 0.0 };
                    return none.node_integrals(left, xk, right);
                }
                let v = [wl * nl[0] + wr * nr[0], wl * nl[1] + wr * nr[1]];
                let len = v[0].hypot(v[1]);
                NodeIntegrals {
                    weight: wl + wr,
                    mass: [l.mass[1][0], l.mass[1][1] + r.mass[0][0], r.mass[0][1]],
                    normal: [v[0] / len, v[1] / len],
                    normal_length: len,
                    normal_scale: wl + wr,
                }
            }
        }
    }
}

/// The multiplier's shape functions `[M_first, M_second]` on one A segment, `xi in [0, 1]` from
/// its first node to its second (see the [module docs](self), "Nodes on the axis").
#[derive(Debug, Clone, Copy, PartialEq, Default)]
enum Hats {
    /// `[1 - xi, xi]`: the traction linear between the nodal values.
    #[default]
    Linear,
    /// The first node on the axis: `[1 - xi^2, xi^2]`, quadratic in `r`, zero slope at `r = 0`.
    AxisFirst,
    /// The second node on the axis: `[(1 - xi)^2, 1 - (1 - xi)^2]`.
    AxisSecond,
}

/// A segment's `integral M_i dS` and `F^A_ij = integral M_i L_j dS` (`i, j` = its first and
/// second node, `L` the displacement's linear hats).
#[derive(Debug, Clone, Copy, Default)]
struct SegmentMoments {
    weight: [f64; 2],
    mass: [[f64; 2]; 2],
}

/// Three-point Gauss rule on `[0, 1]`: `(abscissa, weight)`; exact for quintics.
const GAUSS3_UNIT: [(f64, f64); 3] = [
    (0.5 + 0.5 * GAUSS3[0].0, 0.5 * GAUSS3[0].1),
    (0.5 + 0.5 * GAUSS3[1].0, 0.5 * GAUSS3[1].1),
    (0.5 + 0.5 * GAUSS3[2].0, 0.5 * GAUSS3[2].1),
];

impl Hats {
    /// The shapes on an axisymmetric segment from node `first` to node `last` (`first + 1`) of
    /// a polyline of `count` nodes: quadratic when an end node of the polyline lies on the
    /// axis (`|r| <= 1e-10 h`, [`AXIS_ROUND_OFF`] of the segment's length `h`) and the other node does
    /// not, linear otherwise (and always in plane).
    fn of_segment(
        measure: SurfaceMeasure,
        r: [f64; 2],
        h: f64,
        first: usize,
        count: usize,
    ) -> Self {
        let on_axis = |r: f64| r.abs() <= AXIS_ROUND_OFF * h;
        if measure != SurfaceMeasure::Axisymmetric || on_axis(r[0]) == on_axis(r[1]) {
            Hats::Linear
        } else if first == 0 && on_axis(r[0]) {
            Hats::AxisFirst
        } else if first + 2 == count && on_axis(r[1]) {
            Hats::AxisSecond
        } else {
            Hats::Linear
        }
    }

    /// `[M_first(xi), M_second(xi)]`.
    #[inline]
    fn at(self, xi: f64) -> [f64; 2] {
        match self {
            Hats::Linear => [1.0 - xi, xi],
            Hats::AxisFirst => [1.0 - xi * xi, xi * xi],
            Hats::AxisSecond => {
                let u = 1.0 - xi;
                [u * u, 1.0 - u * u]
            }
        }
    }

    /// A Gauss rule on `[0, 1]` exact for `M_i L m g` (`L`, `m`, `g` affine in `xi`): degree 3
    /// for linear shapes, 5 for quadratic ones.
    fn rule(self) -> &'static [(f64, f64)] {
        match self {
            Hats::Linear => &GAUSS2_UNIT,
            Hats::AxisFirst | Hats::AxisSecond => &GAUSS3_UNIT,
        }
    }

    /// The segment's moments for a measure affine along it, `m` at its two nodes, length `h`
    /// (the rule is exact: `M_i L_j m` has degree at most 4).
    fn moments(self, h: f64, m: [f64; 2]) -> SegmentMoments {
        let mut out = SegmentMoments::default();
        for &(xi, gw) in self.rule() {
            let wt = gw * h * (m[0] + xi * (m[1] - m[0]));
            let lin = [1.0 - xi, xi];
            for (i, m) in self.at(xi).into_iter().enumerate() {
                out.weight[i] += wt * m;
                for (j, l) in lin.into_iter().enumerate() {
                    out.mass[i][j] += wt * m * l;
                }
            }
        }
        out
    }
}

/// What [`SurfaceMeasure::node_integrals`] returns.
struct NodeIntegrals {
    weight: f64,
    mass: [f64; 3],
    normal: [f64; 2],
    normal_length: f64,
    normal_scale: f64,
}

/// B nodes projecting within this fraction of an A segment's length of its end project onto it.
const END_SNAP: f64 = 1e-10;

/// A segment shorter than this fraction of its polyline's longest segment is rejected.
const ZERO_LENGTH: f64 = 1e-12;

/// Evaluate the contact pair `(a, b)` at the positions `x` (all nodes, indexed by node
/// id) with A's surface measure `measure`: weights, `F^A`, `F^B`, `R_C`, nodal frames, coverage
/// and coupling rows of every A node (equations in the [module docs](self)).
/// `search_distance > 0` bounds `|g|` of a valid hit.
///
/// # Errors
/// [`Error::InvalidInput`], naming the node, when a polyline has fewer than 2 nodes, a node id is
/// out of range, a coordinate is not finite, a node repeats (consecutively or anywhere: a
/// polyline must be a simple open chain), a segment has zero length, A and B share a node, A
/// folds back onto itself at a node (no nodal normal), an A node has `r < 0` in axisymmetry,
/// the measure's thickness is invalid, or `search_distance` is not positive and finite.
pub fn evaluate(
    a: &[usize],
    b: &[usize],
    x: &[[f64; 2]],
    search_distance: f64,
    measure: SurfaceMeasure,
) -> Result<ContactSurface> {
    let mut out = ContactSurface::new();
    evaluate_into(a, b, x, search_distance, measure, &mut out)?;
    Ok(out)
}

/// [`evaluate`] into an existing surface, reusing its allocations. On error `out` is left in an
/// unspecified but valid state.
///
/// # Errors
/// As [`evaluate`].
pub fn evaluate_into(
    a: &[usize],
    b: &[usize],
    x: &[[f64; 2]],
    search_distance: f64,
    measure: SurfaceMeasure,
    out: &mut ContactSurface,
) -> Result<()> {
    evaluate_impl(a, b, x, search_distance, measure, out, false)
}

/// One facing B segment that reaches into an A segment's strip.
#[derive(Debug, Clone, Copy)]
struct Candidate {
    /// B segment index (`b[seg] -> b[seg + 1]`).
    seg: usize,
    /// Projections of the B segment's nodes on the A segment (`xi` units), raw.
    tau0: f64,
    tau1: f64,
    /// Signed distances of the B segment's nodes from the A segment's line.
    g0: f64,
    g1: f64,
    /// The `xi` range the segment covers, snapped to the A segment's ends (`lo < hi`).
    lo: f64,
    hi: f64,
}

impl Candidate {
    /// B parameter `eta` of the hit point at `xi`, clamped to `[0, 1]`.
    fn eta(&self, xi: f64) -> f64 {
        ((xi - self.tau0) / (self.tau1 - self.tau0)).clamp(0.0, 1.0)
    }

    /// Signed distance `g(xi)` (affine on the segment's range).
    fn g(&self, xi: f64) -> f64 {
        self.g0 + self.eta(xi) * (self.g1 - self.g0)
    }
}

/// Scratch buffers of one evaluation.
#[derive(Debug, Clone, Default)]
struct Workspace {
    grid: Grid,
    ids: Vec<usize>,
    candidates: Vec<Candidate>,
    breaks: Vec<f64>,
    /// Per A segment: length and unit outward normal.
    seg_len: Vec<f64>,
    seg_normal: Vec<[f64; 2]>,
    /// Per A segment: the multiplier's shape functions.
    seg_hats: Vec<Hats>,
    /// Per A node: the support's length, its uncovered length, `integral_covered M_k g dS`.
    support: Vec<f64>,
    uncovered: Vec<f64>,
    distance: Vec<f64>,
    /// Per A node: `F^A` with its left neighbour, itself and its right neighbour, over the
    /// whole support (closed form) and over the covered part (accumulated piece by piece).
    mass: Vec<[f64; 3]>,
    covered_mass: Vec<[f64; 3]>,
    sorted: Vec<(usize, u8)>,
}

/// Uniform grid of B segments as a sorted list of `(cell key, segment)` pairs.
#[derive(Debug, Clone, Default)]
struct Grid {
    origin: [f64; 2],
    top: [f64; 2],
    cell: f64,
    nx: usize,
    ny: usize,
    entries: Vec<(u64, usize)>,
}

impl Grid {
    fn index(&self, v: f64, axis: usize) -> usize {
        let n = if axis == 0 { self.nx } else { self.ny };
        ((v - self.origin[axis]) / self.cell)
            .floor()
            .clamp(0.0, (n - 1) as f64) as usize
    }

    /// Bin the segments of `b` (positions `x`) in cells of size `cell`.
    fn build(&mut self, b: &[usize], x: &[[f64; 2]], cell: f64) {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for &i in b {
            for c in 0..2 {
                lo[c] = lo[c].min(x[i][c]);
                hi[c] = hi[c].max(x[i][c]);
            }
        }
        self.origin = lo;
        self.top = hi;
        self.cell = cell;
        // the extent of a chain is at most its length <= n_segments * cell
        self.nx = ((hi[0] - lo[0]) / cell).floor().min(b.len() as f64) as usize + 1;
        self.ny = ((hi[1] - lo[1]) / cell).floor().min(b.len() as f64) as usize + 1;
        self.entries.clear();
        for (j, w) in b.windows(2).enumerate() {
            let (q0, q1) = (x[w[0]], x[w[1]]);
            let len = (q1[0] - q0[0]).hypot(q1[1] - q0[1]);
            let m = (len / cell).ceil().clamp(1.0, b.len() as f64) as usize;
            for i in 0..m {
                let (s0, s1) = (i as f64 / m as f64, (i + 1) as f64 / m as f64);
                let pa = lerp(q0, q1, s0);
                let pb = lerp(q0, q1, s1);
                let (ix0, ix1) = (
                    self.index(pa[0].min(pb[0]), 0),
                    self.index(pa[0].max(pb[0]), 0),
                );
                let (iy0, iy1) = (
                    self.index(pa[1].min(pb[1]), 1),
                    self.index(pa[1].max(pb[1]), 1),
                );
                for ix in ix0..=ix1 {
                    for iy in iy0..=iy1 {
                        self.entries.push((self.key(ix, iy), j));
                    }
                }
            }
        }
        self.entries.sort_unstable();
        self.entries.dedup();
    }

    fn key(&self, ix: usize, iy: usize) -> u64 {
        ix as u64 * self.ny as u64 + iy as u64
    }

    /// Append the segments binned in cells that meet the box `[lo, hi]` to `out`.
    fn query(&self, lo: [f64; 2], hi: [f64; 2], out: &mut Vec<usize>) {
        if hi[0] < self.origin[0]
            || hi[1] < self.origin[1]
            || lo[0] > self.top[0]
            || lo[1] > self.top[1]
        {
            return;
        }
        let (ix0, ix1) = (self.index(lo[0], 0), self.index(hi[0], 0));
        let (iy0, iy1) = (self.index(lo[1], 1), self.index(hi[1], 1));
        for ix in ix0..=ix1 {
            let (k0, k1) = (self.key(ix, iy0), self.key(ix, iy1));
            let start = self.entries.partition_point(|e| e.0 < k0);
            out.extend(
                self.entries[start..]
                    .iter()
                    .take_while(|e| e.0 <= k1)
                    .map(|e| e.1),
            );
        }
    }
}

/// A B node projecting within this fraction of an A segment's length of its ends is not inside
/// it: a node facing an A node (node-to-node) is that node's weighted gap's business.
const INTERIOR_MARGIN: f64 = 1e-3;

/// Where point `x` projects on the segment `s0 -> s1`: `xi` with `s0 + xi (s1 - s0)` the foot
/// of the perpendicular from `x`, and whether that lies strictly inside the segment (more than
/// [`INTERIOR_MARGIN`] of its length from either end).
pub(crate) fn interior_parameter(s0: [f64; 2], s1: [f64; 2], x: [f64; 2]) -> (f64, bool) {
    let d = sub(s1, s0);
    let xi = dot(sub(x, s0), d) / dot(d, d);
    (xi, (INTERIOR_MARGIN..=1.0 - INTERIOR_MARGIN).contains(&xi))
}

/// The B nodes that project strictly inside each A segment (see [`interior_parameter`]), per
/// segment in B's order, at fixed positions: under small kinematics the pointwise B-node
/// check over open A segments reads its candidates here instead of testing every B node
/// against every open segment in every iteration (`O(|A| |B|)` each time).
#[derive(Debug, Clone)]
pub(crate) struct SegmentInteriors {
    /// `nodes[start[k]..start[k + 1]]` project inside segment `k`.
    start: Vec<usize>,
    nodes: Vec<usize>,
}

impl SegmentInteriors {
    /// The B nodes of `b` inside each segment of polyline `a`, at positions `x`.
    pub(crate) fn new(a: &[usize], b: &[usize], x: &[[f64; 2]]) -> Self {
        let mut out = SegmentInteriors {
            start: vec![0],
            nodes: Vec::new(),
        };
        for w in a.windows(2) {
            let inside = b
                .iter()
                .filter(|&&j| interior_parameter(x[w[0]], x[w[1]], x[j]).1);
            out.nodes.extend(inside);
            out.start.push(out.nodes.len());
        }
        out
    }

    /// The B nodes inside segment `k` (between A nodes `k` and `k + 1`).
    pub(crate) fn segment(&self, k: usize) -> &[usize] {
        &self.nodes[self.start[k]..self.start[k + 1]]
    }
}

fn lerp(p: [f64; 2], q: [f64; 2], s: f64) -> [f64; 2] {
    [p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])]
}

fn dot(u: [f64; 2], v: [f64; 2]) -> f64 {
    u[0] * v[0] + u[1] * v[1]
}

fn sub(u: [f64; 2], v: [f64; 2]) -> [f64; 2] {
    [u[0] - v[0], u[1] - v[1]]
}

/// Snap a projection `tau` to the A segment's end it lies within [`END_SNAP`] of.
fn snap(tau: f64) -> f64 {
    if tau.abs() <= END_SNAP {
        0.0
    } else if (tau - 1.0).abs() <= END_SNAP {
        1.0
    } else {
        tau
    }
}

/// A radius within this fraction of the adjacent segments' length of zero is round-off of the
/// axis (the element check's tolerance, relative to the element size).
const AXIS_ROUND_OFF: f64 = 1e-10;

/// How far from `r = 0` the radius of node `k` of polyline `ids` is round-off of the axis:
/// [`AXIS_ROUND_OFF`] times the longer of its segments.
fn axis_round_off(ids: &[usize], k: usize, x: &[[f64; 2]]) -> f64 {
    let length = |i: usize, j: usize| {
        let d = sub(x[ids[j]], x[ids[i]]);
        d[0].hypot(d[1])
    };
    let left = if k > 0 { length(k - 1, k) } else { 0.0 };
    let right = if k + 1 < ids.len() {
        length(k, k + 1)
    } else {
        0.0
    };
    AXIS_ROUND_OFF * left.max(right)
}

/// The first node of contact polyline `ids` at `r = x < 0` beyond round-off of its segments'
/// length ([`AXIS_ROUND_OFF`]), if any: in axisymmetry no node lies there.
pub(crate) fn below_axis(ids: &[usize], x: &[[f64; 2]]) -> Option<usize> {
    (0..ids.len()).find(|&k| x[ids[k]][0] < -axis_round_off(ids, k, x))
}

/// Whether node `k` of contact polyline `ids` lies on the axis of an axisymmetric analysis
/// (`|r|` within round-off of its segments' length, [`AXIS_ROUND_OFF`]).
pub(crate) fn on_axis(ids: &[usize], k: usize, x: &[[f64; 2]]) -> bool {
    x[ids[k]][0].abs() <= axis_round_off(ids, k, x)
}

/// Check one polyline: length, ids in range, finite coordinates, no consecutive repeat, no
/// zero-length segment.
fn check_polyline(name: &str, ids: &[usize], x: &[[f64; 2]]) -> Result<()> {
    if ids.len() < 2 {
        return Err(Error::InvalidInput(format!(
            "contact polyline {name} has {} node(s), needs at least 2",
            ids.len()
        )));
    }
    for &i in ids {
        if i >= x.len() {
            return Err(Error::InvalidInput(format!(
                "contact polyline {name}: node {i} is out of range ({} nodes)",
                x.len()
            )));
        }
        if !(x[i][0].is_finite() && x[i][1].is_finite()) {
            return Err(Error::InvalidInput(format!(
                "contact polyline {name}: node {i} has a non-finite coordinate"
            )));
        }
    }
    let mut longest: f64 = 0.0;
    for w in ids.windows(2) {
        if w[0] == w[1] {
            return Err(Error::InvalidInput(format!(
                "contact polyline {name} repeats node {} consecutively",
                w[0]
            )));
        }
        let d = sub(x[w[1]], x[w[0]]);
        longest = longest.max(d[0].hypot(d[1]));
    }
    for w in ids.windows(2) {
        let d = sub(x[w[1]], x[w[0]]);
        if d[0].hypot(d[1]) <= ZERO_LENGTH * longest {
            return Err(Error::InvalidInput(format!(
                "contact polyline {name}: nodes {} and {} coincide (zero-length segment)",
                w[0], w[1]
            )));
        }
    }
    Ok(())
}

/// Reject a node that appears twice in A, twice in B, or in both.
fn check_distinct(a: &[usize], b: &[usize], sorted: &mut Vec<(usize, u8)>) -> Result<()> {
    sorted.clear();
    sorted.extend(a.iter().map(|&i| (i, 0u8)));
    sorted.extend(b.iter().map(|&i| (i, 1u8)));
    sorted.sort_unstable();
    for w in sorted.windows(2) {
        if w[0].0 == w[1].0 {
            let node = w[0].0;
            return Err(Error::InvalidInput(if w[0].1 != w[1].1 {
                format!("node {node} is on both contact polylines A and B")
            } else {
                let name = if w[0].1 == 0 { "A" } else { "B" };
                format!(
                    "contact polyline {name} visits node {node} twice (it must be a simple \
                     open chain)"
                )
            }));
        }
    }
    Ok(())
}

fn evaluate_impl(
    a: &[usize],
    b: &[usize],
    x: &[[f64; 2]],
    dist: f64,
    measure: SurfaceMeasure,
    out: &mut ContactSurface,
    brute_force: bool,
) -> Result<()> {
    if !(dist > 0.0 && dist.is_finite()) {
        return Err(Error::InvalidInput(format!(
            "contact search distance must be positive and finite (got {dist})"
        )));
    }
    measure.validate()?;
    check_polyline("A", a, x)?;
    check_polyline("B", b, x)?;
    if measure == SurfaceMeasure::Axisymmetric
        && let Some(k) = below_axis(a, x)
    {
        return Err(Error::InvalidInput(format!(
            "contact polyline A: node {} has r = {} < 0 beyond round-off of its segments' \
             length (axisymmetric: x is the radius)",
            a[k], x[a[k]][0]
        )));
    }
    let w = out.work.get::<Workspace>();
    check_distinct(a, b, &mut w.sorted)?;

    let (na, nb) = (a.len(), b.len());
    // A segments: lengths and normals n = (d_y, -d_x) / h
    w.seg_len.clear();
    w.seg_normal.clear();
    w.seg_hats.clear();
    for (e, s) in a.windows(2).enumerate() {
        let (n, h) = edge_normal(x[s[0]], x[s[1]]);
        w.seg_len.push(h);
        w.seg_normal.push(n);
        let r = [x[s[0]][0], x[s[1]][0]];
        w.seg_hats.push(Hats::of_segment(measure, r, h, e, na));
    }
    // nodes: frame, weight, F^A
    out.nodes.resize_with(na, || ContactNode::empty(2));
    w.support.clear();
    w.mass.clear();
    for (k, node) in out.nodes.iter_mut().enumerate() {
        let left = (k > 0).then(|| (x[a[k - 1]], w.seg_hats[k - 1]));
        let right = (k + 1 < na).then(|| (x[a[k + 1]], w.seg_hats[k]));
        let m = measure.node_integrals(left, x[a[k]], right);
        if m.normal_length <= 1e-12 * m.normal_scale {
            return Err(Error::InvalidInput(format!(
                "contact polyline A folds back onto itself at node {} (no nodal normal)",
                a[k]
            )));
        }
        let n = m.normal;
        node.node = a[k];
        node.frame = Frame::plane(n.into());
        node.weight = m.weight;
        node.covered_weight = 0.0;
        node.gap = Vector::zero(2);
        node.coupling.clear();
        w.mass.push(m.mass);
        // the support's length (coverage is a fraction of it)
        let hl = if k > 0 { w.seg_len[k - 1] } else { 0.0 };
        let hr = if k + 1 < na { w.seg_len[k] } else { 0.0 };
        w.support.push(hl + hr);
    }
    w.uncovered.clear();
    w.uncovered.resize(na, 0.0);
    w.distance.clear();
    w.distance.resize(na, 0.0);
    w.covered_mass.clear();
    w.covered_mass.resize(na, [0.0; 3]);

    // candidate search structure over B
    let mean_a = w.seg_len.iter().sum::<f64>() / (na - 1) as f64;
    let mean_b = b
        .windows(2)
        .map(|s| {
            let d = sub(x[s[1]], x[s[0]]);
            d[0].hypot(d[1])
        })
        .sum::<f64>()
        / (nb - 1) as f64;
    let cell = mean_a.max(mean_b).max(dist);
    if !brute_force {
        w.grid.build(b, x, cell);
    }

    for e in 0..na - 1 {
        let (p0, p1) = (x[a[e]], x[a[e + 1]]);
        let h = w.seg_len[e];
        let n = w.seg_normal[e];
        let t = [-n[1], n[0]];
        // candidates: B segments binned under the strip {xi in [0, 1], |g| <= dist}
        w.ids.clear();
        if brute_force {
            w.ids.extend(0..nb - 1);
        } else {
            let m = (h / cell).ceil().clamp(1.0, na as f64) as usize;
            let scale = p0[0]
                .abs()
                .max(p0[1].abs())
                .max(p1[0].abs())
                .max(p1[1].abs());
            let pad = 1e-9 * cell + 1e-14 * scale;
            for i in 0..m {
                let c0 = lerp(p0, p1, i as f64 / m as f64);
                let c1 = lerp(p0, p1, (i + 1) as f64 / m as f64);
                let mut lo = [f64::INFINITY; 2];
                let mut hi = [f64::NEG_INFINITY; 2];
                for c in [c0, c1] {
                    for sgn in [-dist, dist] {
                        for ax in 0..2 {
                            let v = c[ax] + sgn * n[ax];
                            lo[ax] = lo[ax].min(v - pad);
                            hi[ax] = hi[ax].max(v + pad);
                        }
                    }
                }
                w.grid.query(lo, hi, &mut w.ids);
            }
            w.ids.sort_unstable();
            w.ids.dedup();
        }
        w.candidates.clear();
        for &j in &w.ids {
            let (r0, r1) = (sub(x[b[j]], p0), sub(x[b[j + 1]], p0));
            let (tau0, tau1) = (dot(r0, t) / h, dot(r1, t) / h);
            let (g0, g1) = (dot(r0, n), dot(r1, n));
            // facing: (q1 - q0) . t < 0 (also rejects segments parallel to n)
            if tau1 >= tau0 {
                continue;
            }
            let (mut lo, mut hi) = (snap(tau1), snap(tau0));
            if measure == SurfaceMeasure::Axisymmetric {
                // both surfaces end on the axis: B's end there covers A's (module docs)
                let on_axis = |p: [f64; 2]| p[0].abs() <= AXIS_ROUND_OFF * h;
                if on_axis(p0) && on_axis(x[b[j + 1]]) {
                    lo = lo.min(0.0);
                }
                if on_axis(p1) && on_axis(x[b[j]]) {
                    hi = hi.max(1.0);
                }
            }
            if hi <= 0.0 || lo >= 1.0 || lo >= hi {
                continue;
            }
            if (g0 > dist && g1 > dist) || (g0 < -dist && g1 < -dist) {
                continue;
            }
            w.candidates.push(Candidate {
                seg: j,
                tau0,
                tau1,
                g0,
                g1,
                lo,
                hi,
            });
        }
        let (k0, k1) = (e, e + 1);
        if w.candidates.is_empty() {
            w.uncovered[k0] += h;
            w.uncovered[k1] += h;
            continue;
        }
        w.candidates
            .sort_unstable_by(|u, v| u.lo.total_cmp(&v.lo).then(u.seg.cmp(&v.seg)));
        // break points: B nodes' projections, |g| = dist, and |g_i| = |g_j|
        w.breaks.clear();
        w.breaks.extend([0.0, 1.0]);
        for c in &w.candidates {
            w.breaks.extend([c.lo, c.hi]);
            for level in [dist, -dist] {
                if (c.g0 - level) * (c.g1 - level) < 0.0 {
                    let eta = (level - c.g0) / (c.g1 - c.g0);
                    w.breaks.push(c.tau0 + eta * (c.tau1 - c.tau0));
                }
            }
        }
        let cands = &w.candidates;
        for i in 0..cands.len() {
            for j in i + 1..cands.len() {
                let (ci, cj) = (&cands[i], &cands[j]);
                if cj.lo >= ci.hi {
                    break;
                }
                let (l, u) = (cj.lo, ci.hi.min(cj.hi));
                for sign in [1.0, -1.0] {
                    let (fl, fu) = (ci.g(l) - sign * cj.g(l), ci.g(u) - sign * cj.g(u));
                    if fl * fu < 0.0 {
                        w.breaks.push(l + (u - l) * fl / (fl - fu));
                    }
                }
            }
        }
        w.breaks.retain(|v| (0.0..=1.0).contains(v));
        w.breaks.sort_unstable_by(f64::total_cmp);
        w.breaks.dedup();

        for piece in w.breaks.windows(2) {
            let (xa, xb) = (piece[0], piece[1]);
            let mid = 0.5 * (xa + xb);
            // the facing hit nearest to A (smallest |g|) within the search distance
            let mut best: Option<(&Candidate, f64)> = None;
            for c in cands {
                if c.lo > mid {
                    break;
                }
                if c.hi < mid {
                    continue;
                }
                let g = c.g(mid).abs();
                if g <= dist && best.is_none_or(|(_, bg)| g < bg) {
                    best = Some((c, g));
                }
            }
            let len = (xb - xa) * h;
            let Some((c, _)) = best else {
                w.uncovered[k0] += len;
                w.uncovered[k1] += len;
                continue;
            };
            // exact Gauss on the piece: L^B, g and the measure affine in xi, M affine (or
            // quadratic on an axis segment)
            let mut fa = [[0.0; 2]; 2];
            let mut fb = [[0.0; 2]; 2];
            let mut mg = [0.0; 2];
            let mut mw = [0.0; 2];
            let hats = w.seg_hats[e];
            for &(gp, gw) in hats.rule() {
                let xi = xa + (xb - xa) * gp;
                let wt = gw * len * measure.at(lerp(p0, p1, xi));
                let mk = hats.at(xi);
                let eta = c.eta(xi);
                let lb = [1.0 - eta, eta];
                let g = c.g0 + eta * (c.g1 - c.g0);
                for r in 0..2 {
                    fa[r][0] += wt * mk[r] * (1.0 - xi);
                    fa[r][1] += wt * mk[r] * xi;
                    fb[r][0] += wt * mk[r] * lb[0];
                    fb[r][1] += wt * mk[r] * lb[1];
                    mg[r] += wt * mk[r] * g;
                    mw[r] += wt * mk[r];
                }
            }
            let (q0, q1) = (b[c.seg], b[c.seg + 1]);
            // the segment is node k0's right one and node k1's left one
            let cm = &mut w.covered_mass;
            cm[k0][1] += fa[0][0];
            cm[k0][2] += fa[0][1];
            cm[k1][0] += fa[1][0];
            cm[k1][1] += fa[1][1];
            for (r, k) in [(0, k0), (1, k1)] {
                let node = &mut out.nodes[k];
                node.gap[0] -= mg[r] * n[0];
                node.gap[1] -= mg[r] * n[1];
                node.covered_weight += mw[r];
                w.distance[k] += mg[r];
                node.coupling.push((q0, -fb[r][0]));
                node.coupling.push((q1, -fb[r][1]));
            }
        }
    }

    // finish: coverage, gaps, A's part of the coupling rows, merged rows
    for (k, node) in out.nodes.iter_mut().enumerate() {
        let support = w.support[k];
        node.coverage = if w.uncovered[k] <= 0.0 {
            1.0
        } else {
            (1.0 - w.uncovered[k] / support).clamp(0.0, 1.0)
        };
        // F^A over the covered part: the closed form when that is the whole support; over
        // the whole support when nothing is covered (module docs)
        let mass = if node.is_covered() || node.covered_weight == 0.0 {
            w.mass[k]
        } else {
            w.covered_mass[k]
        };
        let neighbours = [k.checked_sub(1), Some(k), (k + 1 < na).then_some(k + 1)];
        for (j, v) in neighbours.into_iter().zip(mass) {
            if let Some(j) = j {
                node.coupling.push((a[j], v));
            }
        }
        if node.covered_weight > 0.0 {
            node.normal_gap = -node.frame.normal().dot(&node.gap) / node.covered_weight;
            node.mean_distance = w.distance[k] / node.covered_weight;
        } else {
            node.normal_gap = f64::INFINITY;
            node.mean_distance = f64::INFINITY;
        }
        merge(&mut node.coupling);
    }
    Ok(())
}

/// Sort a coupling row by node id, sum entries of the same node, drop exact zeros.
fn merge(row: &mut Vec<(usize, f64)>) {
    row.sort_by_key(|e| e.0);
    let mut write = 0;
    for read in 0..row.len() {
        if write > 0 && row[write - 1].0 == row[read].0 {
            row[write - 1].1 += row[read].1;
        } else {
            row[write] = row[read];
            write += 1;
        }
    }
    row.truncate(write);
    row.retain(|e| e.1 != 0.0);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A flat A on `y = 0` (nodes right to left: A below, n = +y) and B on `y = gap` (left to
    /// right: B above, facing).
    fn flat(xa: &[f64], xb: &[f64], gap: f64) -> (Vec<usize>, Vec<usize>, Vec<[f64; 2]>) {
        let mut x = Vec::new();
        let a: Vec<usize> = xa
            .iter()
            .rev()
            .map(|&v| {
                x.push([v, 0.0]);
                x.len() - 1
            })
            .collect();
        let b: Vec<usize> = xb
            .iter()
            .map(|&v| {
                x.push([v, gap]);
                x.len() - 1
            })
            .collect();
        (a, b, x)
    }

    /// The B nodes inside each A segment: strictly inside, not within the margin of an end
    /// (a node facing an A node belongs to that node), in B's order, whatever the B node's
    /// distance from the segment.
    #[test]
    fn segment_interiors_hold_the_b_nodes_projecting_inside() {
        let (a, mut b, mut x) = flat(&[0.0, 1.0, 2.0], &[0.5, 1.0, 1.0005, 1.5, 2.5], 0.1);
        x.push([1.25, -3.0]);
        b.push(x.len() - 1);
        let interiors = SegmentInteriors::new(&a, &b, &x);
        // A runs right to left: segment 0 is [2, 1], segment 1 is [1, 0]
        let at = |k: usize| -> Vec<f64> { interiors.segment(k).iter().map(|&j| x[j][0]).collect() };
        assert_eq!(at(0), vec![1.5, 1.25]);
        assert_eq!(at(1), vec![0.5]);
        let (xi, inside) = interior_parameter(x[a[0]], x[a[1]], [1.9995, 7.0]);
        assert!((xi - 0.0005).abs() < 1e-12 && !inside);
    }

    #[test]
    fn snap_and_merge() {
        assert_eq!(snap(1e-12), 0.0);
        assert_eq!(snap(1.0 - 1e-12), 1.0);
        assert_eq!(snap(0.5), 0.5);
        let mut row = vec![(3, 1.0), (1, 2.0), (3, -1.0), (1, 0.5)];
        merge(&mut row);
        assert_eq!(row, vec![(1, 2.5)]);
    }

    #[test]
    fn normal_points_into_b_and_tangent_convention() {
        let (a, b, x) = flat(&[0.0, 1.0, 2.0], &[0.0, 2.0], 0.1);
        let s = evaluate(&a, &b, &x, 1.0, SurfaceMeasure::default()).unwrap();
        for nd in &s.nodes {
            assert_eq!(nd.frame.normal(), Vector::plane(0.0, 1.0));
            assert_eq!(nd.frame.tangents(), &[Vector::plane(1.0, 0.0)]);
            assert!((nd.normal_gap - 0.1).abs() < 1e-15);
        }
    }

    /// The grid search finds exactly what the brute-force scan finds (bitwise identical
    /// results): wavy non-matching surfaces, A much coarser or much finer than B, B folding
    /// back over A, any orientation, search distances from a fraction of a segment to more
    /// than the whole extent.
    #[test]
    fn grid_search_matches_brute_force() {
        let mut seed = 12345u64;
        let mut rnd = move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for trial in 0..60 {
            let (na, nb) = match trial % 3 {
                0 => (5 + trial, 7 + 3 * trial),
                1 => (3, 150 + trial),
                _ => (120 + trial, 4),
            };
            let folded = trial % 4 == 3;
            let (c, s) = ((7.0 * rnd()).cos(), (7.0 * rnd()).sin());
            let norm = c.hypot(s);
            let (c, s) = (c / norm, s / norm);
            let place = |p: [f64; 2]| [c * p[0] - s * p[1] + 3.0, s * p[0] + c * p[1] - 1.0];
            let mut x = Vec::new();
            let mut a = Vec::new();
            for i in 0..na {
                let u = 1.0 - i as f64 / (na - 1) as f64 + 0.2 * (rnd() - 0.5) / na as f64;
                x.push(place([u, 0.05 * (7.0 * u).sin()]));
                a.push(x.len() - 1);
            }
            let mut b = Vec::new();
            for i in 0..nb {
                let u = -0.1 + 1.2 * i as f64 / (nb - 1) as f64;
                let mut y = 0.05 * (7.0 * u).sin() + 0.02 * (rnd() - 0.5);
                if folded && i % 2 == 1 {
                    // zig-zag: every other node far back and ahead, so B folds over A
                    y += 0.3;
                }
                let u = if folded && i % 2 == 1 { u - 0.3 } else { u };
                x.push(place([u, y]));
                b.push(x.len() - 1);
            }
            let dist = [0.01, 0.05, 0.3, 5.0][trial % 4] * (0.5 + rnd());
            let mut fast = ContactSurface::new();
            let mut slow = ContactSurface::new();
            evaluate_impl(
                &a,
                &b,
                &x,
                dist,
                SurfaceMeasure::default(),
                &mut fast,
                false,
            )
            .unwrap();
            evaluate_impl(&a, &b, &x, dist, SurfaceMeasure::default(), &mut slow, true).unwrap();
            assert_eq!(fast.nodes, slow.nodes, "trial {trial}");
            assert!(
                fast.nodes.iter().any(|n| n.covered_weight > 0.0),
                "trial {trial}"
            );
        }
    }

    /// A flat A along `r` ending on the axis (either end): the axis segment's quadratic
    /// shapes give the closed forms of the module docs (`F^A` column of the axis node
    /// `2 pi h^2 (7/60, 3/60)`, its weight `2 pi h^2 / 4`), the hats still sum to one (column
    /// sums of `F^A` = `integral L_j dS`, weights summing to the disk's area `pi R^2`), and the
    /// segments away from the axis keep the linear forms.
    #[test]
    fn axis_segment_has_zero_slope_shapes() {
        use std::f64::consts::PI;
        let (h, n) = (0.25, 4);
        for axis_first in [false, true] {
            let mut r: Vec<f64> = (0..=n).map(|i| i as f64 * h).collect();
            if !axis_first {
                r.reverse();
            }
            let (a, b, x) = flat(&r, &[-0.1, 1.1], 0.01);
            let s = evaluate(&a, &b, &x, 1.0, SurfaceMeasure::Axisymmetric).unwrap();
            let at = |k: usize| x[s.nodes[k].node][0];
            let entry = |k: usize, j: usize| -> f64 {
                let id = s.nodes[j].node;
                s.nodes[k]
                    .coupling
                    .iter()
                    .find(|e| e.0 == id)
                    .map_or(0.0, |e| e.1)
            };
            let axis = (0..=n).find(|&k| at(k) == 0.0).unwrap();
            let next = (0..=n).find(|&k| (at(k) - h).abs() < 1e-15).unwrap();
            let unit = 2.0 * PI * h * h;
            let close = |u: f64, v: f64| (u - v).abs() <= 1e-14 * unit;
            assert!(close(entry(axis, axis), unit * 7.0 / 60.0));
            assert!(close(entry(next, axis), unit * 3.0 / 60.0));
            assert!(close(entry(axis, next), unit * 8.0 / 60.0));
            assert!(close(s.nodes[axis].weight, unit / 4.0));
            // away from the axis: linear forms, h (3 m_k + m_j) / 12 and h (m_k + m_j) / 12
            let m = |r: f64| 2.0 * PI * r;
            let (k, j) = (
                next,
                (0..=n).find(|&k| (at(k) - 2.0 * h).abs() < 1e-15).unwrap(),
            );
            assert!(close(entry(j, k), h * (m(2.0 * h) + m(h)) / 12.0));
            let total: f64 = s.nodes.iter().map(|nd| nd.weight).sum();
            assert!(close(total, PI * (n as f64 * h).powi(2)));
            for j in 0..=n {
                let column: f64 = (0..=n).map(|k| entry(k, j)).sum();
                let left = if at(j) > 0.0 {
                    h * (2.0 * m(at(j)) + m(at(j) - h)) / 6.0
                } else {
                    0.0
                };
                let right = if at(j) < n as f64 * h {
                    h * (2.0 * m(at(j)) + m(at(j) + h)) / 6.0
                } else {
                    0.0
                };
                assert!(close(column, left + right), "{axis_first} {j}");
            }
        }
    }

    #[test]
    fn reuse_gives_identical_results() {
        let (a, b, x) = flat(&[0.0, 0.3, 1.0, 1.4, 2.0], &[-0.1, 0.7, 1.1, 2.2], 0.05);
        let fresh = evaluate(&a, &b, &x, 1.0, SurfaceMeasure::default()).unwrap();
        let mut reused =
            evaluate(&b[..2], &a[..3], &x, 1.0, SurfaceMeasure::default()).unwrap_or_default();
        evaluate_into(&a, &b, &x, 1.0, SurfaceMeasure::default(), &mut reused).unwrap();
        assert_eq!(fresh.nodes, reused.nodes);
    }
}
