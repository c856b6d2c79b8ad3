//! The contact-set iteration of Kubomura and Pian with the stiffness factored once per analysis.
//!
//! # The equations (docs/method.md: "The mixed system with K factored once", "The contact iteration")
//! `t` is the traction acting on body A (the multiplier side), interpolated linearly between the
//! A nodes (quadratically, with zero slope at `r = 0`, next to an axisymmetric node on the axis:
//! `plane/mortar.rs`); at node `k`, `t_k = tn_k n_k + ts_k s_k` in the nodal frame (`tn < 0` compression).
//! With `Gc` the coupling (its column for a normal multiplier is `+F^A n_k` at A's dofs and
//! `-F^B n_k` at B's: the contact forces on both bodies, equal and opposite), equilibrium in the
//! total form reads
//!
//! ```text
//! K q = f - K_fp q_p + Gc t,   so   q = u0 + K^-1 Gc t,   u0 = K^-1 (f - K_fp q_p)
//! ```
//!
//! and an active node closes its weighted gap `R_C,k` (linearised about the latest iterate
//! `q_i`):
//!
//! ```text
//! normal row:   n_k . sum_j c_kj q_j = n_k . sum_j c_kj q_i,j - n_k . R_C,k(q_i)
//! stick rows:   s_ki . sum_j c_kj (q_j - q_start,j) = 0   per kept tangent s_ki of the frame
//!               (no slip since the increment began)
//! slip node:    only the normal row; its force column is n_k + sum_i c_i s_ki with
//!               c = mu d_k the law's slip coefficients for the slip direction d_k,
//!               ts_k = c tn_k
//! ```
//!
//! Columns of `Gc` live on the contact nodes' dofs only, so `K^-1` is needed only there: the
//! contact-boundary flexibility `F = E^T K^-1 E` (`E` selects the free dofs of the contact
//! nodes). Under small kinematics `K` is factored in its plain fill-reducing order and `F` is
//! built only where the iteration needs it: the responses `F v` of each A node's directions
//! `v` (normal and tangent rows) when the node first becomes active, by substitution within
//! the contact dofs' elimination-tree reach (or through a host's solve callback), kept with the
//! node flexibility `N_ab = v_a^T F v_b`. Under finite kinematics the contact dofs are
//! eliminated last and all of `F = (L22 L22^T)^-1` is read off the trailing block of `L` (no
//! solves). Every iteration is small dense algebra (`boundary.rs`):
//! `S t = rows . (b - u0)` with `S = rows^T F cols`. The load solve
//! `u0` is reused when a load is a combination of earlier ones, and the full displacement
//! field is recovered only when asked for (one solve).
//!
//! # Kinematics (docs/method.md, "Kinematics: small and finite")
//! [`Kinematics::Small`] (the default) evaluates the contact geometry of every pair once, in
//! the reference configuration: pairing, frames, weights and the coupling `c_kj` (`F^A`, `F^B`)
//! are constant, the gap is linear, `R_C,k(q) = R_C,k(X) + sum_j c_kj q_j`, and the normal row
//! above is exact, so a contact set is solved in one step and no geometry is evaluated during
//! the iteration (except that the pairing is widened, still in `X`, when the bodies move
//! farther than it looked for B: `Surfaces::widen`). [`Kinematics::Finite`] re-evaluates the
//! geometry at every iterate (the current positions `x = X + q`), a geometric iteration that
//! lets bodies slide far along each other.
//!
//! # The iteration (per increment)
//! Start from the last converged states; each iteration solves the small system, brings the
//! geometry to the new iterate and applies the paper's rules: activate an open A node whose
//! weighted gap is below `-gap_tolerance` (B nodes are checked pointwise only over A segments
//! whose two nodes are open), drop active nodes in tension, turn stick nodes that violate
//! `|ts| <= mu |tn|` into slip nodes, and slip nodes whose slip reverses back into stick. It
//! stops when no state changed and `R = |dU(i+1) - dU(i)| / |dU(i+1)|` (increment displacement
//! of the contact nodes; the denominator bounded below by round-off of the displacement, see
//! `change_ratio`) is below `tolerance` (the active set's `Convergence`, to which a 3D geometry
//! adds a residual of the contact conditions). Every decision about a node's state is the
//! increment's active set's (`active_set/`): the rules, on plain data this module gathers
//! (`checks.rs`: per node its traction, gap, slip and law), which penetrating nodes close and in
//! which closed state, the states of the fallback's solution, the plate's first support, the
//! locks and their checks at convergence, and the history: a state set seen before reappearing
//! is a cycle.
//! Two kinds are benign and resolved (at most `lock_rounds` times per increment): a node on the
//! edge of the friction cone alternating between stick and slip is locked in slip, and a node
//! on the edge of the contact zone alternating between open and closed (zero traction and zero
//! gap to round-off) is locked open, provided it then penetrates by at most `1e-4` of the
//! increment's motion. Any other cycle stops the increment with an error naming the node; so
//! does the iteration cap. A failed increment leaves the last converged state untouched.

use super::bodies::{Bodies, HostBodies, HostElements, HostSystem, ModelBodies};
use super::friction::{Coulomb, FrictionLaw};
use super::geometry::{ContactGeometry, ContactSurface};
use super::handover::{self, Section};
use super::plane::PlaneGeometry;
pub use super::plane::facing::check_a_inside;
use super::plane::mortar::SurfaceMeasure;
use super::space::{Frame, Vector};
pub use super::tangent::{SlipDirection, Tangential, Traction};
use crate::error::{ContactError, Error, Result};
use crate::model::Model;
use crate::solver::Backend;
use faer::Mat;
use nalgebra::{DMatrix, DVector};
use std::sync::PoisonError;

mod active_set;
mod boundary;
mod checks;
mod condensed;
mod driver;
mod export;
mod fallback;
mod loads;
#[cfg(feature = "oracles")]
mod oracles;
mod plate;
mod results;
mod small_system;
mod solid;
mod surfaces;
use active_set::{
    ActiveSet, BNodeHit, BNodes, EDGE_PENETRATION, LINEARIZED_CONE, Locks, NodeFacts, NodeKey,
    Rows, Tolerances, close_nearest, closed_at_rest, linearized_state, rows_of,
};
use boundary::{Boundary, Flexibility};
pub use checks::{CONDITION_LIMIT, SMALL_SLIDING_LIMIT};
pub(crate) use condensed::solve_by_rules;
use driver::{Converged, Driver};
pub(crate) use fallback::solve_conditions;
pub use loads::LOAD_LIMIT;
use plate::{Border, Plate};
pub use results::ConstraintRows;
use small_system::{Sparse, column, dot};
pub use solid::FacePair;
use surfaces::{PairNodes, Surfaces};

/// Equations per node of the bodies the plane and axisymmetric constructors
/// ([`ContactAnalysis::new`], [`ContactAnalysis::host`]) build.
const PLANE_DIM: usize = 2;

/// One contact pair: the multiplier-side polyline A and the opposite polyline B (node ids, each
/// with its body on the left), and the Coulomb friction coefficient between them.
/// The input of the plane and axisymmetric constructors ([`ContactAnalysis::new`],
/// [`ContactAnalysis::host`]); a 3D analysis takes [`FacePair`]s.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactPair {
    /// Multiplier-side boundary nodes (body A on the left of each segment).
    pub a: Vec<usize>,
    /// Opposite boundary nodes (body B on the left of each segment).
    pub b: Vec<usize>,
    /// Coulomb friction coefficient `mu >= 0` (0: frictionless).
    pub friction: f64,
}

impl ContactPair {
    /// Check the pair on its own: friction finite and `>= 0`, each polyline a chain of at
    /// least 2 distinct nodes, no node in both. ([`ContactAnalysis`] checks this too; the C
    /// API calls it where the pair is handed over.)
    ///
    /// # Errors
    /// [`Error::InvalidInput`] saying which rule is broken.
    pub fn check(&self) -> Result<()> {
        self.check_friction()?;
        for (ids, side) in [(&self.a, "A"), (&self.b, "B")] {
            check_chain(ids, side)?;
        }
        self.check_disjoint()
    }

    /// [`check`](Self::check), and against hycon's mesh: every node exists and consecutive
    /// nodes of each polyline are the ends of an element edge in the element's
    /// counter-clockwise order (the body on the left).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the node or the segment.
    pub fn check_on(&self, mesh: &crate::mesh::Mesh) -> Result<()> {
        self.check_friction()?;
        let edges = mesh.directed_edges();
        for (ids, side) in [(&self.a, "A"), (&self.b, "B")] {
            check_chain(ids, side)?;
            if let Some(&bad) = ids.iter().find(|&&i| i >= mesh.n_nodes()) {
                return Err(Error::InvalidInput(format!(
                    "{side} polyline: unknown node {bad} (the model has {} nodes)",
                    mesh.n_nodes()
                )));
            }
            if let Some(w) = ids.windows(2).find(|w| !edges.contains_key(&(w[0], w[1]))) {
                return Err(Error::InvalidInput(format!(
                    "the {side} polyline is not a chain of element edges with the body on the \
                     left: {} -> {} is not an edge of any element in counter-clockwise order",
                    w[0], w[1]
                )));
            }
        }
        self.check_disjoint()
    }

    fn check_friction(&self) -> Result<()> {
        self.friction_law().map(drop)
    }

    /// The surface measure of the pair on `model`: its [`section_on`](Self::section_on)'s.
    /// The contact integrals are weighted by it, so that the multipliers are pressures. Call
    /// after [`check_on`](Self::check_on).
    ///
    /// # Errors
    /// As [`section_on`](Self::section_on).
    pub fn measure_on(&self, model: &Model) -> Result<SurfaceMeasure> {
        self.section_on(model)?.measure()
    }

    /// The section of the pair on `model` ([`Section::of`] the material of the elements that
    /// own A's segments). Call after [`check_on`](Self::check_on).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when A's segments lie on elements of different thicknesses or
    /// kinds (the pair's tractions would have no one measure), or A has no segment.
    pub fn section_on(&self, model: &Model) -> Result<Section> {
        let edges = model.mesh.directed_edges();
        let mut section: Option<Section> = None;
        for w in self.a.windows(2) {
            let Some(&(e, _)) = edges.get(&(w[0], w[1])) else {
                return Err(Error::InvalidInput(format!(
                    "the A polyline's segment {} -> {} is not an element edge",
                    w[0], w[1]
                )));
            };
            let material = model.mesh.element_material[e];
            let s = Section::of(model.materials.get(material).ok_or_else(|| {
                Error::InvalidInput(format!("element {e} has no material {material}"))
            })?);
            match section {
                Some(first) if first != s => {
                    return Err(Error::InvalidInput(format!(
                        "the A polyline lies on elements of different measures ({first:?} and \
                         {s:?} at segment {} -> {}): a pair's tractions are per one measure; \
                         split the pair",
                        w[0], w[1]
                    )));
                }
                _ => section = Some(s),
            }
        }
        section.ok_or_else(|| Error::InvalidInput("the A polyline has no segment".into()))
    }

    /// The friction law between the pair's surfaces: Coulomb with coefficient
    /// [`friction`](Self::friction). (A new law is a type implementing [`FrictionLaw`], chosen
    /// here.)
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a bad coefficient.
    pub fn friction_law(&self) -> Result<Box<dyn FrictionLaw>> {
        Ok(Box::new(Coulomb::new(self.friction)?))
    }

    fn check_disjoint(&self) -> Result<()> {
        match self.a.iter().find(|n| self.b.contains(n)) {
            Some(n) => Err(Error::InvalidInput(format!(
                "node {n} is in both polylines"
            ))),
            None => Ok(()),
        }
    }
}

/// A polyline is a chain of at least 2 distinct nodes.
fn check_chain(ids: &[usize], side: &str) -> Result<()> {
    if ids.len() < 2 {
        return Err(Error::InvalidInput(format!(
            "the {side} polyline has {} node(s); a chain needs at least 2",
            ids.len()
        )));
    }
    let mut seen = std::collections::HashSet::new();
    match ids.iter().find(|&&n| !seen.insert(n)) {
        Some(n) => Err(Error::InvalidInput(format!(
            "the {side} polyline is not a chain: node {n} appears twice"
        ))),
        None => Ok(()),
    }
}

/// How the contact geometry follows the deformation (docs/method.md, "Kinematics: small and finite").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Kinematics {
    /// Small deformation ("small sliding"), consistent with the small-strain elasticity of the
    /// bodies: the pairing (projection of A onto B), the nodal frames, the weights and the
    /// coupling `F^A`, `F^B` are evaluated once, in the reference configuration `X`; the
    /// weighted gap is linear in the displacements,
    /// `R_C,k(u) = R_C,k(X) + sum_j c_kj u_j`; tractions are per reference length. The
    /// contact matrices never change, so no geometry is evaluated during the iteration (only
    /// when the bodies move farther than the pairing looked for B is it evaluated again, in
    /// `X`, with a wider reach; the rows of nodes it had paired stay the same). Exact
    /// for the linearized problem that Hertz and Cattaneo-Mindlin theory solve; wrong once
    /// the surfaces slide by more than a small fraction of an element or rotate noticeably.
    #[default]
    Small,
    /// Finite kinematics ("finite sliding"): the geometry is evaluated at the current
    /// positions `x = X + u` in every iteration, tractions per current length. Needed when
    /// the bodies slide far along each other (the paper's extensive sliding); adds effects of
    /// the order of the surface strain (`a / R` in Hertz contact) to a small-strain model.
    Finite,
}

impl Kinematics {
    /// `"small"` or `"finite"`.
    pub fn name(self) -> &'static str {
        match self {
            Kinematics::Small => "small",
            Kinematics::Finite => "finite",
        }
    }
}

impl std::str::FromStr for Kinematics {
    type Err = Error;

    fn from_str(s: &str) -> Result<Self> {
        match s {
            "small" => Ok(Kinematics::Small),
            "finite" => Ok(Kinematics::Finite),
            _ => Err(Error::InvalidInput(format!(
                "unknown kinematics {s:?} (small or finite)"
            ))),
        }
    }
}

/// Parameters of the contact-set iteration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactOptions {
    /// Contact kinematics: small deformation (the default; linear gap, geometry evaluated once)
    /// or finite (geometry at the current positions, for extensive sliding).
    pub kinematics: Kinematics,
    /// Convergence tolerance on `R` (the paper used 0.01; 1e-6 costs about one more iteration).
    pub tolerance: f64,
    /// Iteration cap per increment.
    pub max_iterations: usize,
    /// Penetration tolerance, relative to the increment's displacement scale (the largest
    /// motion of a contact dof, bounded by the mean A segment length).
    pub gap_tolerance: f64,
    /// Tension tolerance, relative to the largest `|tn|`.
    pub tension_tolerance: f64,
    /// Friction-cone tolerance, relative to `mu |tn|`.
    pub friction_tolerance: f64,
    /// A slip node returns to stick when its slip has reversed by more than this, and a node
    /// closes in slip when it has slid more than this since the increment began, relative to
    /// the increment's motion scale (the largest motion of a contact node in this increment or
    /// any converged one): scaling every load scales the threshold with the slips.
    pub slip_tolerance: f64,
    /// Distance within which B segments are paired with an A segment, relative to the mean A
    /// segment length. The pairing reaches farther as the bodies move, so a refined mesh never
    /// loses a contact that a coarse one finds: under finite kinematics at least twice the
    /// increment's largest motion of a contact dof (see `search_reach`); under small
    /// kinematics the reference pairing is evaluated again within four times the largest
    /// displacement of the pair's nodes whenever twice that exceeds its reach (see
    /// `Surfaces::widen`).
    pub search_distance: f64,
    /// Cycle policy: how many times per increment a cycling contact set is resolved by locking
    /// the alternating nodes (in slip: a node on the edge of the friction cone alternating
    /// between stick and slip; open: a node on the edge of the contact zone alternating between
    /// open and closed) before a cycle is reported as an error. 0: report the first cycle.
    pub lock_rounds: usize,
    /// Sparse Cholesky library for hycon's factorizations of `K`.
    pub backend: Backend,
    /// Threads the contact boundary's substitutions with hycon's own faer factor may use
    /// (default 1: hycon starts no thread). With more, the images of new node directions are
    /// computed a batch per thread and each iteration's backward substitution is shared by
    /// subtrees of the elimination tree (when the contact dofs' reach holds 400k entries of
    /// `L` or more: below, a substitution takes less than half a millisecond); every number,
    /// and so every state, record and traction, is the same to the bit as with one. Threads
    /// are started per substitution and none outlives a call. A host that already runs one
    /// process or thread per core (MPI) keeps 1. Up to [`MAX_THREADS`].
    pub threads: usize,
    /// Automatic cutback: how many times an increment that fails for an iteration reason (no
    /// convergence, a cycling contact set, a locked node breaking its lock, a surface pushed
    /// beyond what the pairing sees) may be halved. The step from the last converged state to
    /// the target is then taken in sub-increments, loads and prescribed values (and a plate's
    /// controls) interpolated linearly, each converged sub-increment the start of the next
    /// (friction's path dependence); the shortest is `2^-cutback_depth` of the increment (and
    /// not below [`cutback_min_fraction`](Self::cutback_min_fraction)). `K` is not factored
    /// again, and an interpolated load costs no solve. Beyond the limit the increment fails
    /// and the analysis is exactly as before the call. 0 switches the cutback off: a failed
    /// increment fails at once (the behaviour before 0.7.0). Default 8; up to
    /// [`MAX_CUTBACK_DEPTH`].
    pub cutback_depth: usize,
    /// The shortest sub-increment the cutback tries, as a fraction of the increment, in
    /// `(0, 1]` (default `1 / 256`, as deep as the default depth).
    pub cutback_min_fraction: f64,
}

/// The largest [`ContactOptions::cutback_depth`] (a sub-increment of `2^-52` of the increment
/// is at the resolution of its own fraction).
pub const MAX_CUTBACK_DEPTH: usize = 52;

/// The largest [`ContactOptions::threads`].
pub const MAX_THREADS: usize = 256;

impl ContactOptions {
    /// Check the values: `tolerance` and `search_distance` positive and finite, the other
    /// tolerances finite and `>= 0`, at least one iteration, 1 to [`MAX_THREADS`] threads.
    /// [`ContactAnalysis`] calls it before any work.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the option.
    pub fn validate(&self) -> Result<()> {
        for (v, name) in [
            (self.tolerance, "tolerance"),
            (self.search_distance, "search_distance"),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(Error::InvalidInput(format!(
                    "options.{name} = {v} must be > 0"
                )));
            }
        }
        for (v, name) in [
            (self.gap_tolerance, "gap_tolerance"),
            (self.tension_tolerance, "tension_tolerance"),
            (self.friction_tolerance, "friction_tolerance"),
            (self.slip_tolerance, "slip_tolerance"),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(Error::InvalidInput(format!(
                    "options.{name} = {v} must be >= 0"
                )));
            }
        }
        if !(1..=MAX_THREADS).contains(&self.threads) {
            return Err(Error::InvalidInput(format!(
                "options.threads = {} must be from 1 to {MAX_THREADS}",
                self.threads
            )));
        }
        if self.max_iterations == 0 {
            return Err(Error::InvalidInput(
                "options.max_iterations must be at least 1".into(),
            ));
        }
        if self.cutback_depth > MAX_CUTBACK_DEPTH {
            return Err(Error::InvalidInput(format!(
                "options.cutback_depth = {} must be from 0 (off) to {MAX_CUTBACK_DEPTH}",
                self.cutback_depth
            )));
        }
        let f = self.cutback_min_fraction;
        if !(f > 0.0 && f <= 1.0) {
            return Err(Error::InvalidInput(format!(
                "options.cutback_min_fraction = {f} must be in (0, 1]"
            )));
        }
        Ok(())
    }
}

impl Default for ContactOptions {
    fn default() -> Self {
        ContactOptions {
            kinematics: Kinematics::Small,
            tolerance: 1e-6,
            max_iterations: 60,
            gap_tolerance: 1e-9,
            tension_tolerance: 1e-9,
            friction_tolerance: 1e-9,
            slip_tolerance: 1e-6,
            search_distance: 4.0,
            lock_rounds: 3,
            backend: Backend::Faer,
            threads: 1,
            cutback_depth: 8,
            cutback_min_fraction: 1.0 / 256.0,
        }
    }
}

/// State of an A node.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NodeState {
    /// Not in contact: no rows.
    Open,
    /// In contact, no relative tangential motion since the increment began.
    Stick,
    /// In contact, sliding; `direction` is the direction of A's slip relative to B in the
    /// node's tangent space (in the plane `+s` or `-s`), and the friction traction on A is the
    /// law's `ts = mu tn direction` (opposing it, since `tn < 0`).
    Slip {
        /// A unit vector of the tangent space (in the plane [`SlipDirection::PLUS`] or
        /// [`SlipDirection::MINUS`]; before 0.9 a sign `+1` or `-1`).
        direction: SlipDirection,
    },
    /// In contact without friction (a pair with `friction = 0`): only the normal row, no
    /// tangential traction (`ts = 0`). (Before 0.7.0 recorded as a slip along `+s`.)
    Frictionless,
}

impl NodeState {
    /// `"open"`, `"stick"`, `"slip"` or `"frictionless"`.
    pub fn name(&self) -> &'static str {
        match self {
            NodeState::Open => "open",
            NodeState::Stick => "stick",
            NodeState::Slip { .. } => "slip",
            NodeState::Frictionless => "frictionless",
        }
    }

    /// Whether `other` is the same state, slip directions compared by
    /// [`SlipDirection::same_as`] (what the active set's cycle check compares; in the plane
    /// the same as `==`).
    pub fn same_as(&self, other: &NodeState) -> bool {
        match (self, other) {
            (NodeState::Slip { direction: a }, NodeState::Slip { direction: b }) => a.same_as(b),
            _ => self == other,
        }
    }
}

/// Converged contact results at one A node.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NodeResult {
    /// Node id (A side).
    pub node: usize,
    /// Open, stick, slip or frictionless.
    pub state: NodeState,
    /// Normal traction on A (multiplier, force per area for every analysis kind and
    /// thickness; `< 0` compression, pressure `p = -tn`).
    pub tn: f64,
    /// Tangential traction on A along the frame's tangents (force per area; one component,
    /// along `s`, in the plane and in axisymmetry, two on a 3D face, 0 along a tangent
    /// dropped by symmetry).
    pub ts: Tangential,
    /// Nodal frame: A's outward normal and the tangents (in the plane `s = (n_y, -n_x)`), of
    /// the reference configuration under small kinematics, of the converged one under finite
    /// kinematics.
    pub frame: Frame,
    /// Current position (reference position plus the converged displacement).
    pub position: Vector,
    /// Tributary measure `integral of M_k dS` (`dS = t ds` in plane, `2 pi r ds` in
    /// axisymmetry: an area), measured in the configuration the geometry lives in (reference
    /// under small kinematics, converged under finite): the tractions are per unit of it, and
    /// it divides nodal forces into pressures.
    pub weight: f64,
    /// Normal weighted gap per unit length (`< 0` penetration; infinite where B does not cover
    /// the node's support).
    pub gap: f64,
    /// Equivalent nodal contact force on A at this node, `sum_k F^A_kj t_k` (global x, y).
    pub force: Vector,
}

/// Converged contact results at one B node (see [`ContactAnalysis::b_node_results`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BNodeResult {
    /// Node id (B side).
    pub node: usize,
    /// `integral of L^B_j dS` over the projected overlap (A's measure `dS`).
    pub weight: f64,
    /// Equivalent nodal contact force on B (global x, y).
    pub force: Vector,
    /// Pressure `-force . n / weight` (`n` B's outward nodal normal; 0 outside the overlap).
    pub pressure: f64,
    /// Current position of the node.
    pub position: Vector,
}

/// What happened in one iteration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IterationRecord {
    /// Increment number (1-based).
    pub increment: usize,
    /// Iteration number within the increment (1-based).
    pub iteration: usize,
    /// Active (stick + slip + frictionless) nodes used in this iteration's solve.
    pub active: usize,
    /// Stick nodes among them.
    pub stick: usize,
    /// Slip nodes among them (frictional pairs only; frictionless nodes are neither stick nor
    /// slip).
    pub slip: usize,
    /// State changes decided after the solve.
    pub changes: usize,
    /// Convergence measure `R`.
    pub r: f64,
    /// Estimated 1-norm condition number of the small contact system solved in this iteration
    /// (Hager's estimator; 1 when it is empty).
    pub condition: f64,
    /// The worst violation of the discrete contact conditions by this iteration's solution
    /// with its states (gap >= 0 at open nodes, `p >= 0` and a closed gap at closed ones,
    /// `|ts| <= mu p` and no slip at stick nodes, slip opposing `ts` at slip nodes), relative
    /// to the problem's scale: open nodes' penetration to the gap scale (the increment's motion,
    /// at most the mean A segment), closed nodes' gaps and slips to the motion, tractions to
    /// the largest `|tn|`. At
    /// convergence it is at most [`CONDITION_LIMIT`] (else the increment fails with
    /// [`ContactError::ConditionViolated`]).
    pub violation: f64,
    /// The sub-increment (1-based) of the increment this iteration belongs to: 1 unless the
    /// automatic cutback split the increment (see [`ContactOptions::cutback_depth`]). A
    /// sub-increment that fails is tried again, shorter, under the same index: the monitor
    /// sees both tries, [`ContactAnalysis::records`] keeps the converged one.
    pub sub_increment: usize,
}

/// Summary of a converged increment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IncrementInfo {
    /// Increment number (1-based).
    pub increment: usize,
    /// Iterations used (summed over the converged sub-increments: the records
    /// [`ContactAnalysis::records`] keeps of the increment).
    pub iterations: usize,
    /// Active nodes at convergence.
    pub active: usize,
    /// Slip nodes at convergence.
    pub slip: usize,
    /// Converged sub-increments the increment was taken in: 1 unless the automatic cutback
    /// split it (see [`ContactOptions::cutback_depth`]).
    pub sub_increments: usize,
    /// Sub-increments that failed and were tried again shorter (0 without cutback).
    pub cutbacks: usize,
}

/// Where the time of an analysis went (wall-clock seconds, accumulated over increments).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Timings {
    /// Sparse assembly of `K`.
    pub assembly: f64,
    /// Symbolic analysis and numeric factorization of `K` (once per analysis).
    pub factorization: f64,
    /// Contact-boundary flexibility `F`: the responses of node directions as they become active
    /// (small kinematics), or all of `F` read off the factor's trailing block once (finite).
    pub flexibility: f64,
    /// The load solves `u0 = K^-1 (f - K_fp q_p)`, one per increment.
    pub load_solves: f64,
    /// Contact iterations: geometry, small dense systems, state updates.
    pub iterations: f64,
    /// Full-field recovery, one solve per converged increment.
    pub recovery: f64,
}

impl Timings {
    /// The parts with their field names, in field order (for tables, CSV and JSON writers).
    pub fn phases(&self) -> [(&'static str, f64); 6] {
        [
            ("assembly", self.assembly),
            ("factorization", self.factorization),
            ("flexibility", self.flexibility),
            ("load_solves", self.load_solves),
            ("iterations", self.iterations),
            ("recovery", self.recovery),
        ]
    }

    /// Sum of all parts.
    pub fn total(&self) -> f64 {
        self.phases().iter().map(|(_, t)| t).sum()
    }
}

/// How one translation of a rigid plate is driven in an increment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PlateControl {
    /// The plate's displacement in this direction (total).
    Displacement(f64),
    /// The force applied to the plate in this direction (total); its displacement is an
    /// unknown of the contact system.
    Force(f64),
}

/// A caller's function that sees every iteration record; returning `false` stops the increment
/// (the last converged state is kept).
pub type Monitor = Box<dyn FnMut(&IterationRecord) -> bool + Send>;

/// Per-node state kept between increments.
#[derive(Debug, Clone, Copy, PartialEq)]
struct NodeData {
    state: NodeState,
    traction: Traction,
}

/// A contact analysis: the model with its stiffness factored once, the contact pairs, the
/// contact-boundary flexibility, and the last converged state. It composes its parts, each
/// owning its data: the contact geometry (`Surfaces`, `surfaces.rs`), the boundary algebra
/// (`Boundary`, `boundary.rs`) and the increment driver (`Driver`, `driver.rs`); the
/// state decisions of an increment are its active set's (`active_set/`).
pub struct ContactAnalysis {
    /// The bodies: positions, solves and responses of `K` (read by every part).
    bodies: Box<dyn Bodies>,
    options: ContactOptions,
    /// The contact geometry: the pairs, their geometries and friction laws, the reference and
    /// converged surfaces and the pairing's reach.
    surfaces: Surfaces,
    /// The boundary algebra: the contact dofs, `F`, the node flexibility, the small system's
    /// storage, the converged contact displacement and the kept load solves.
    boundary: Boundary,
    /// The increment driver: counters, records, timings, the monitor, the fallback's switch,
    /// what the last increments settled and converged with.
    driver: Driver,
    /// Converged node data, per pair, per A node: the state the next increment's active set
    /// starts from and the result queries read.
    nodes: Vec<Vec<NodeData>>,
    plate: Option<Plate>,
}

impl std::fmt::Debug for ContactAnalysis {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ContactAnalysis")
            .field("bodies", &self.bodies)
            .field("pairs", &self.surfaces.pairs.len())
            .field("contact dofs", &self.boundary.dofs.len())
            .field("increment", &self.driver.increment)
            .finish()
    }
}

impl ContactAnalysis {
    /// Validate and factor `K` once: in its fill-reducing order under small kinematics (the
    /// flexibility `F` is then built as nodes become active), with the contact nodes' dofs
    /// eliminated last under finite kinematics (all of `F` read off the factor's trailing
    /// block).
    pub fn new(model: Model, pairs: Vec<ContactPair>, options: ContactOptions) -> Result<Self> {
        options.validate()?;
        let measures = pairs
            .iter()
            .enumerate()
            .map(|(i, pair)| {
                pair.check_on(&model.mesh)
                    .and_then(|_| pair.measure_on(&model))
                    .map_err(|e| in_pair(i, e))
            })
            .collect::<Result<Vec<_>>>()?;
        let (nodes, laws) = (plane_nodes(&pairs), plane_laws(&pairs)?);
        let dofs = contact_dofs(&nodes, PLANE_DIM);
        let lazy = options.kinematics == Kinematics::Small;
        let bodies = ModelBodies::new(model, &dofs, options.backend, lazy, options.threads)?;
        let geometries = plane_geometries(&pairs, measures);
        Self::setup(
            Box::new(bodies),
            nodes,
            laws,
            geometries,
            dofs,
            options,
            None,
        )
    }

    /// A contact analysis of a host's system: its contact nodes (ids of its numbering, which
    /// the pairs use), and its stiffness, as a CSR matrix that is factored here (once; as for
    /// [`new`](Self::new)) or as a solve callback (the responses `F v` then come from batched
    /// callback solves, one column per node direction that becomes active, or per contact dof
    /// an active node touches under finite kinematics). Loads are the host's right-hand sides
    /// ([`increment`](Self::increment) with empty `qp`), displacements its equations.
    pub fn host(
        mut system: HostSystem,
        pairs: Vec<ContactPair>,
        options: ContactOptions,
    ) -> Result<Self> {
        options.validate()?;
        for (i, pair) in pairs.iter().enumerate() {
            pair.check().map_err(|e| in_pair(i, e))?;
        }
        check_inside_count(&system.a_inside, pairs.len())?;
        // the host's point inside body A, or the centroid of its element on a segment of A
        let a_inside: Vec<Option<Vector>> = (0..pairs.len())
            .map(|i| {
                let given = system.a_inside.get(i).copied().flatten();
                let beside = || system.elements.as_ref()?.centroid_beside(&pairs[i].a);
                given.or_else(beside)
            })
            .collect();
        let sections = std::mem::take(&mut system.sections);
        let measures = host_measures(&sections, &pairs, system.elements.as_ref())?;
        let (bodies, seconds) = host_bodies(system, &options)?;
        check_host_dimension(&bodies, &a_inside, PLANE_DIM)?;
        let n_nodes = bodies.positions().as_chunks::<2>().0.len();
        check_host_nodes(&pairs, &bodies)?;
        let pairs: Vec<ContactPair> = pairs
            .into_iter()
            .map(|p| {
                let local = |ids: &[usize]| ids.iter().filter_map(|&n| bodies.local(n)).collect();
                ContactPair {
                    a: local(&p.a),
                    b: local(&p.b),
                    friction: p.friction,
                }
            })
            .collect();
        check_host_radii(&pairs, &sections, &bodies)?;
        let dofs = (0..PLANE_DIM * n_nodes).collect();
        let geometries = plane_geometries(&pairs, measures);
        let (pairs, laws) = (plane_nodes(&pairs), plane_laws(&pairs)?);
        let mut analysis = Self::setup(
            Box::new(bodies),
            pairs,
            laws,
            geometries,
            dofs,
            options,
            Some(a_inside),
        )?;
        analysis.driver.timings.factorization = seconds;
        Ok(analysis)
    }

    /// The common part of the constructors: slots, `F`, node data. `pairs`, `laws` and
    /// `geometries`: the nodes, the friction law and the geometry of each pair, built by each
    /// constructor from its own pair type; `geometries`
    /// its measure checked by the constructors (a model's come from its validated materials, a
    /// host's are checked before its stiffness is factored). `a_inside`: a host's points inside body A per
    /// pair (`None` for a model, whose element edges tell the sides).
    fn setup(
        mut bodies: Box<dyn Bodies>,
        pairs: Vec<PairNodes>,
        laws: Vec<Box<dyn FrictionLaw>>,
        mut geometries: Vec<Box<dyn ContactGeometry>>,
        dofs: Vec<usize>,
        options: ContactOptions,
        a_inside: Option<Vec<Option<Vector>>>,
    ) -> Result<Self> {
        let mut timings = Timings::default();
        let setup = bodies.setup_seconds();
        (timings.assembly, timings.factorization) = (setup.assembly, setup.factorization);
        let clock = std::time::Instant::now();
        let flexibility = if bodies.lazy_flexibility() {
            Flexibility::lazy(dofs.len())
        } else {
            Flexibility::full(bodies.flexibility(&dofs)?)
        };
        timings.flexibility = clock.elapsed().as_secs_f64();
        let x = bodies.positions();
        let reach: Vec<f64> = (geometries.iter())
            .map(|g| options.search_distance * g.mean_size(x))
            .collect();
        let reference = (geometries.iter().zip(&reach))
            .map(|(g, &r)| g.evaluate(x, r))
            .collect::<Result<Vec<_>>>()?;
        if options.kinematics == Kinematics::Small {
            // the candidates of the pointwise B-node check, found once in the reference
            // configuration
            for g in &mut geometries {
                g.freeze_b_nodes(x);
            }
        }
        for (i, geometry) in geometries.iter().enumerate() {
            let side = match &a_inside {
                None => Side::Edges,
                Some(points) => Side::Inside(points.get(i).copied().flatten()),
            };
            check_facing(&**geometry, bodies.as_ref(), options.search_distance, side)
                .map_err(|e| in_pair(i, e))?;
        }
        let nodes = reference
            .iter()
            .map(|surface| {
                (surface.nodes.iter())
                    .map(|node| NodeData {
                        state: NodeState::Open,
                        traction: Traction::zero(node.frame.tangents().len()),
                    })
                    .collect()
            })
            .collect();
        let mut boundary = Boundary::new(
            dofs,
            bodies.positions().len(),
            flexibility,
            pairs.iter().map(|p| p.a.len()),
        );
        (boundary.flexibility_seconds, timings.flexibility) = (timings.flexibility, 0.0);
        let mut analysis = ContactAnalysis {
            surfaces: Surfaces {
                pairs,
                geometries,
                laws,
                current: reference.clone(),
                reference,
                reach,
                kinematics: options.kinematics,
                search_distance: options.search_distance,
            },
            boundary,
            driver: Driver::new(timings),
            bodies,
            options,
            nodes,
            plate: None,
        };
        if !analysis.boundary.flexibility.is_full() {
            let clock = std::time::Instant::now();
            let before = analysis.boundary.flexibility_seconds;
            (analysis.boundary).prime(&mut *analysis.bodies, &analysis.surfaces)?;
            // (node directions time themselves; columns through ensure_columns too)
            analysis.boundary.flexibility_seconds = before + clock.elapsed().as_secs_f64();
        }
        Ok(analysis)
    }

    /// The model (mesh, materials, boundary conditions); an error for a host's system.
    pub fn model(&self) -> Result<&Model> {
        model_of(&*self.bodies)
    }

    /// The displacement field of the last converged increment (zero before the first): over
    /// all dofs of a model, over the equations of a host. Recovered on the first call after an
    /// increment (one solve), then kept: the iteration itself needs only the contact dofs.
    /// Takes `&self`: concurrent calls are safe (the solves are serialized by a lock; two
    /// first calls may both solve, one result is kept).
    pub fn displacement(&self) -> Result<&[f64]> {
        if let Some((q, _)) = self.driver.field.get() {
            return Ok(q);
        }
        self.bodies.check_solver()?;
        let clock = std::time::Instant::now();
        let q = match &self.driver.converged {
            Some(c) => {
                let total = self.total_load(c);
                self.bodies.solve(&total, &c.prescribed)?
            }
            None => vec![0.0; self.bodies.field_len()],
        };
        let seconds = clock.elapsed().as_secs_f64();
        Ok(&self.driver.field.get_or_init(|| (q, seconds)).0)
    }

    /// Length of load and displacement vectors: `2 n_nodes` for a plane model, `3 n_nodes` for
    /// a brick model, the host's equation count for a host.
    pub fn field_len(&self) -> usize {
        self.bodies.field_len()
    }

    /// The contact forces of the last converged increment over the field (zero before the
    /// first; zero at a host's fixed dofs): what the host adds to its right-hand side to
    /// recover the displacement with its own solver.
    pub fn contact_forces(&self) -> Vec<f64> {
        let mut out = vec![0.0; self.bodies.field_len()];
        if let Some(c) = &self.driver.converged {
            self.scatter(&c.contact, &mut out);
        }
        out
    }

    /// Add forces given at the contact dofs into a field vector.
    fn scatter(&self, forces: &[f64], out: &mut [f64]) {
        for (&d, &v) in self.boundary.dofs.iter().zip(forces) {
            if let Some(i) = self.bodies.field_index(d) {
                out[i] += v;
            }
        }
    }

    /// The displacement increment of the last converged increment (its field minus the one
    /// before; the whole field at the first increment), same layout as
    /// [`displacement`](Self::displacement). One solve, with the difference of the two
    /// increments' loads (the response is linear in them).
    pub fn displacement_increment(&self) -> Result<Vec<f64>> {
        let Some(c) = &self.driver.converged else {
            return Ok(vec![0.0; self.bodies.field_len()]);
        };
        self.bodies.check_solver()?;
        let mut load = self.total_load(c);
        let mut prescribed = c.prescribed.clone();
        if let Some(p) = &self.driver.previous {
            for (l, v) in load.iter_mut().zip(self.total_load(p)) {
                *l -= v;
            }
            for (q, v) in prescribed.iter_mut().zip(&p.prescribed) {
                *q -= v;
            }
        }
        let clock = std::time::Instant::now();
        let du = self.bodies.solve(&load, &prescribed)?;
        *self
            .driver
            .recovery
            .lock()
            .unwrap_or_else(PoisonError::into_inner) += clock.elapsed().as_secs_f64();
        Ok(du)
    }

    /// External loads plus contact forces of a converged increment.
    fn total_load(&self, c: &Converged) -> Vec<f64> {
        let mut total = c.load.clone();
        self.scatter(&c.contact, &mut total);
        total
    }

    /// The options the analysis runs with.
    pub fn options(&self) -> &ContactOptions {
        &self.options
    }

    /// Where the time went so far.
    pub fn timings(&self) -> Timings {
        let mut t = self.driver.timings;
        t.flexibility = self.boundary.flexibility_seconds;
        t.load_solves = self.boundary.load_seconds;
        t.recovery += self.driver.field.get().map_or(0.0, |f| f.1)
            + *self
                .driver
                .recovery
                .lock()
                .unwrap_or_else(PoisonError::into_inner);
        t
    }

    /// Every iteration record so far, in order.
    pub fn records(&self) -> &[IterationRecord] {
        &self.driver.records
    }

    /// Number of numeric factorizations of `K` performed by hycon (1 per analysis; 0 when a
    /// host solves with its own solver).
    pub fn factorizations(&self) -> usize {
        self.bodies.factorizations()
    }

    /// The caller's id of A node `(pair, index)`.
    pub(super) fn external_a(&self, (p, k): NodeKey) -> usize {
        self.bodies.external(self.surfaces.pairs[p].a[k])
    }

    /// The friction law of A node `k` of pair `p` (see [`Surfaces::node_law`]).
    fn node_law(&self, p: usize, k: usize) -> &dyn FrictionLaw {
        self.surfaces.node_law(p, k, self.bodies.positions())
    }

    /// How far the pairing of pair `p` reaches in the iterate `uc` of an increment that
    /// started at `startc` (see [`Surfaces::search_reach`]).
    fn search_reach(&self, p: usize, xg: &[f64], uc: &[f64], startc: &[f64]) -> f64 {
        let motion = checks::largest_node_motion(uc, startc, self.dim());
        self.surfaces.search_reach(p, xg, motion)
    }

    /// Current positions `X + u` of the nodes, with `u` given at the contact dofs (see
    /// [`Boundary::positions`]).
    fn positions(&self, uc: &[f64]) -> Vec<f64> {
        self.boundary.positions(self.bodies.positions(), uc)
    }

    /// The positions the contact geometry is evaluated at, given the current ones `x` (see
    /// [`Surfaces::geometry_positions`]).
    fn geometry_positions<'a>(&'a self, x: &'a [f64]) -> &'a [f64] {
        self.surfaces.geometry_positions(self.bodies.positions(), x)
    }

    /// The dimension of the positions: the bodies' equations per node.
    fn dim(&self) -> usize {
        self.bodies.dim()
    }
}

/// The plane and axisymmetric geometry of every pair: its polylines with the measure of its A
/// side.
fn plane_geometries(
    pairs: &[ContactPair],
    measures: Vec<SurfaceMeasure>,
) -> Vec<Box<dyn ContactGeometry>> {
    (pairs.iter().zip(measures))
        .map(|(p, m)| {
            Box::new(PlaneGeometry::new(p.a.clone(), p.b.clone(), m)) as Box<dyn ContactGeometry>
        })
        .collect()
}

/// The contact dofs of a model's pairs, sorted: `dim n + c` for every A and B node `n` and
/// direction `c < dim`.
fn contact_dofs(pairs: &[PairNodes], dim: usize) -> Vec<usize> {
    let mut dofs: Vec<usize> = (pairs.iter())
        .flat_map(|p| p.a.iter().chain(&p.b))
        .flat_map(|&n| (0..dim).map(move |c| dim * n + c))
        .collect();
    dofs.sort_unstable();
    dofs.dedup();
    dofs
}

/// The nodes of every plane or axisymmetric pair, as the iteration reads them: its polylines.
fn plane_nodes(pairs: &[ContactPair]) -> Vec<PairNodes> {
    (pairs.iter())
        .map(|p| PairNodes {
            a: p.a.clone(),
            b: p.b.clone(),
        })
        .collect()
}

/// The friction law of every plane or axisymmetric pair ([`ContactPair::friction_law`]).
///
/// # Errors
/// [`Error::InvalidInput`] for a bad friction coefficient (the constructors' checks refuse it
/// first).
fn plane_laws(pairs: &[ContactPair]) -> Result<Vec<Box<dyn FrictionLaw>>> {
    pairs.iter().map(ContactPair::friction_law).collect()
}

/// What tells the side of body A of a pair beyond the geometry of its polylines.
#[derive(Debug, Clone, Copy)]
enum Side {
    /// A model: the element edges (checked by [`ContactPair::check_on`]).
    Edges,
    /// A host: a point inside body A, if it gave one (see [`HostSystem::a_inside`]).
    Inside(Option<Vector>),
}

/// A host's points inside body A ([`HostSystem::a_inside`]): none, or one (or `None`) per pair.
fn check_inside_count(a_inside: &[Option<Vector>], pairs: usize) -> Result<()> {
    if a_inside.is_empty() || a_inside.len() == pairs {
        return Ok(());
    }
    Err(Error::InvalidInput(format!(
        "a_inside has {} entries for {pairs} pairs (give none, or one per pair)",
        a_inside.len()
    )))
}

/// A host's system as the bodies of an analysis with `options` ([`HostBodies::new`]: its
/// nodes checked and a CSR stiffness factored, lazily under small kinematics), and the seconds
/// that took (the host's factorization).
fn host_bodies(system: HostSystem, options: &ContactOptions) -> Result<(HostBodies, f64)> {
    let clock = std::time::Instant::now();
    let lazy = options.kinematics == Kinematics::Small;
    let bodies = HostBodies::new(system, options.backend, lazy, options.threads)?;
    Ok((bodies, clock.elapsed().as_secs_f64()))
}

/// A host's nodes and its points inside body A have the `dim` components of its constructor:
/// 2 for [`ContactAnalysis::host`] (plane or axisymmetric), 3 for
/// [`ContactAnalysis::solid_host`].
fn check_host_dimension(
    bodies: &HostBodies,
    a_inside: &[Option<Vector>],
    dim: usize,
) -> Result<()> {
    if bodies.dim() != dim {
        let kind = if dim == PLANE_DIM {
            "a host's contact analysis is plane or axisymmetric (2 components per contact node)"
        } else {
            "a 3D host's contact analysis (faces of 4 nodes) has 3 components per contact node"
        };
        return Err(Error::InvalidInput(format!(
            "{kind}; its contact nodes have {}",
            bodies.dim()
        )));
    }
    for (i, point) in a_inside.iter().enumerate() {
        if let Some(p) = point.filter(|p| p.dim() != dim) {
            return Err(in_pair(
                i,
                Error::InvalidInput(format!(
                    "the point inside body A has {} components, the host's nodes {dim}",
                    p.dim()
                )),
            ));
        }
    }
    Ok(())
}

/// A host's pair measures from its `sections` (one per pair, valid, of one kind), checked
/// against the `elements` along A if it gave them (see [`handover`]).
fn host_measures(
    sections: &[Section],
    pairs: &[ContactPair],
    elements: Option<&HostElements>,
) -> Result<Vec<SurfaceMeasure>> {
    handover::check_sections(sections, pairs.len())?;
    if let Some(elements) = elements {
        handover::check_element_sections(elements, pairs, sections)?;
    }
    sections.iter().map(Section::measure).collect()
}

/// In axisymmetry, no node of a host's pairs (local ids) at `r < 0` (see
/// [`handover::check_radii`]).
fn check_host_radii(
    pairs: &[ContactPair],
    sections: &[Section],
    bodies: &dyn Bodies,
) -> Result<()> {
    let x = bodies.positions().as_chunks::<2>().0;
    for (i, (pair, section)) in pairs.iter().zip(sections).enumerate() {
        for (side, ids) in [("A", &pair.a), ("B", &pair.b)] {
            let points: Vec<f64> = ids.iter().flat_map(|&n| x[n]).collect();
            let external: Vec<usize> = ids.iter().map(|&n| bodies.external(n)).collect();
            handover::check_radii(section, side, &external, &points).map_err(|e| in_pair(i, e))?;
        }
    }
    Ok(())
}

/// A pair's polylines must face each other in the reference configuration: of the A nodes
/// with a B segment within the search distance, more must see B from in front (farther than
/// half a segment) than see it running the same way (one polyline reversed) or lying behind A
/// (back to back: two faces of one body, or both polylines reversed); see
/// [`ContactGeometry::facing`]. Where the surfaces touch (within half a segment) the geometry cannot
/// tell facing surfaces from back-to-back ones: on a model the element edges tell; a host
/// whose pair touches everywhere it is judged must say which side body A is on (a point
/// inside it, checked by [`ContactGeometry::check_inside`]), and a point it gives is always checked.
fn check_facing(
    geometry: &dyn ContactGeometry,
    bodies: &dyn Bodies,
    search_distance: f64,
    side: Side,
) -> Result<()> {
    let x = bodies.positions();
    let f = geometry.facing(x, search_distance * geometry.mean_size(x));
    let judged = f.facing + f.touching + f.same_way + f.behind;
    let node = |k: Option<usize>| k.map_or(0, |k| bodies.external(geometry.a_nodes()[k]));
    if f.same_way > f.facing + f.touching {
        return Err(Error::InvalidInput(format!(
            "A and B run the same way: at {} of the {judged} A nodes near B (A node {} first) \
             the outward normals of A and B point alike; each polyline must have its body on \
             its left, so one of them is reversed",
            f.same_way,
            node(f.example)
        )));
    }
    if f.behind > f.facing {
        return Err(Error::InvalidInput(format!(
            "B lies behind A: at {} of the {judged} A nodes near B (A node {} first) A's \
             outward normal points away from B, which is more than half a segment behind it; \
             the polylines are back to back (two faces of one body, or both reversed)",
            f.behind,
            node(f.example)
        )));
    }
    match side {
        Side::Edges => Ok(()),
        Side::Inside(Some(p)) => geometry.check_inside(x, &p),
        Side::Inside(None) if f.touching > 0 && f.facing == 0 => Err(Error::InvalidInput(format!(
            "A and B touch (at {} of the {judged} A nodes near B they lie within half a \
                 segment of each other) and face each other nowhere farther apart: the \
                 geometry cannot tell facing surfaces from back-to-back ones (both polylines \
                 reversed). Say which side body A is on: a point inside it \
                 (hycon_host_set_pair_inside, hycon_solid_host_set_pair_inside; \
                 HostSystem::a_inside)",
            f.touching
        ))),
        Side::Inside(None) => Ok(()),
    }
}

/// The model of `bodies`; an error for a host's system.
fn model_of(bodies: &dyn Bodies) -> Result<&Model> {
    bodies.as_model().ok_or_else(|| {
        Error::InvalidInput(
            "this analysis runs on a host's system: hycon has no model of it".into(),
        )
    })
}

/// Name the pair in an error of its checks.
pub(crate) fn in_pair(i: usize, e: Error) -> Error {
    match e {
        Error::InvalidInput(m) => Error::InvalidInput(format!("contact pair {i}: {m}")),
        other => other,
    }
}

/// Every node of a host's pairs must be one of the contact nodes it described.
fn check_host_nodes(pairs: &[ContactPair], bodies: &dyn Bodies) -> Result<()> {
    for (i, p) in pairs.iter().enumerate() {
        if let Some(&n) = p.a.iter().chain(&p.b).find(|&&n| bodies.local(n).is_none()) {
            return Err(Error::InvalidInput(format!(
                "contact pair {i}: unknown node {n} (it is not one of the contact nodes)"
            )));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A pair's measure comes from the material of the elements that own A's segments; A on
    /// elements of two thicknesses is rejected (a host's sections: `handover.rs`).
    #[test]
    fn pair_measure_from_the_model() {
        use crate::material::{Analysis, Material};
        // two unit squares side by side (materials 0 and 1), a third on top of the first
        let mut mesh = crate::mesh::Mesh::new();
        mesh.nodes = vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [0.0, 1.0],
        ];
        mesh.push_element(&[0, 1, 4, 5], 0);
        mesh.push_element(&[1, 2, 3, 4], 1);
        let material = |t: f64| Material::new(1.0, 0.3, t, Analysis::PlaneStress).unwrap();
        let model = |t1: f64| {
            Model::new(
                mesh.clone(),
                vec![material(2.5), material(t1)],
                crate::element::Formulation::Hybrid,
            )
        };
        let top = ContactPair {
            a: vec![3, 4, 5],
            b: vec![0, 1],
            friction: 0.0,
        };
        let one = ContactPair {
            a: vec![4, 5],
            ..top.clone()
        };
        let plane = |thickness| SurfaceMeasure::Plane { thickness };
        assert_eq!(one.measure_on(&model(1.0)).unwrap(), plane(2.5));
        assert_eq!(top.measure_on(&model(2.5)).unwrap(), plane(2.5));
        let e = top.measure_on(&model(1.0)).unwrap_err().to_string();
        assert!(e.contains("different measures"), "{e}");
        // axisymmetric: the measure is 2 pi r, the thickness must be 1
        let axi = SurfaceMeasure::new(Analysis::Axisymmetric, 1.0).unwrap();
        assert_eq!(axi, SurfaceMeasure::Axisymmetric);
        let e = SurfaceMeasure::new(Analysis::Axisymmetric, 2.0)
            .unwrap_err()
            .to_string();
        assert!(e.contains("2 pi r"), "{e}");
        let m = Material::new(1.0, 0.3, 1.0, Analysis::Axisymmetric).unwrap();
        assert_eq!(m.measure_kind(), SurfaceMeasure::Axisymmetric);
    }

    /// Options and pairs are checked in the core, so a Rust caller gets the same errors as a C
    /// caller: each bad value is named.
    #[test]
    fn options_and_pairs_are_checked_in_the_core() {
        let bad = |o: ContactOptions, what: &str| {
            let e = o.validate().unwrap_err().to_string();
            assert!(e.contains(what), "{e}");
        };
        let d = ContactOptions::default();
        d.validate().unwrap();
        bad(
            ContactOptions {
                tolerance: 0.0,
                ..d
            },
            "options.tolerance = 0 must be > 0",
        );
        bad(
            ContactOptions {
                search_distance: f64::NAN,
                ..d
            },
            "options.search_distance",
        );
        bad(
            ContactOptions {
                gap_tolerance: -1.0,
                ..d
            },
            "options.gap_tolerance",
        );
        bad(
            ContactOptions {
                max_iterations: 0,
                ..d
            },
            "options.max_iterations",
        );
        for threads in [0, MAX_THREADS + 1] {
            bad(
                ContactOptions { threads, ..d },
                &format!("options.threads = {threads} must be from 1 to {MAX_THREADS}"),
            );
        }
        let pair = |a: Vec<usize>, b: Vec<usize>, friction: f64| ContactPair { a, b, friction };
        let check = |p: ContactPair, what: &str| {
            let e = p.check().unwrap_err().to_string();
            assert!(e.contains(what), "{e}");
        };
        pair(vec![0, 1], vec![2, 3], 0.3).check().unwrap();
        check(pair(vec![0, 1], vec![2, 3], -0.1), "friction");
        check(pair(vec![0], vec![2, 3], 0.0), "A polyline has 1 node(s)");
        check(pair(vec![0, 1, 0], vec![2, 3], 0.0), "node 0 appears twice");
        check(
            pair(vec![0, 1], vec![1, 3], 0.0),
            "node 1 is in both polylines",
        );
        // on a mesh: one unit square, counter-clockwise 0 1 2 3; its bottom edge is 0 -> 1
        let mut mesh = crate::mesh::Mesh::new();
        mesh.nodes = vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [0.0, 1.0],
            [0.0, 2.0],
            [1.0, 2.0],
        ];
        mesh.push_element(&[0, 1, 2, 3], 0);
        pair(vec![0, 1], vec![4, 5], 0.0)
            .check_on(&mesh)
            .unwrap_err();
        let e = pair(vec![1, 0], vec![2, 3], 0.0)
            .check_on(&mesh)
            .unwrap_err();
        assert!(e.to_string().contains("1 -> 0 is not an edge"), "{e}");
        let e = pair(vec![0, 1], vec![2, 9], 0.0)
            .check_on(&mesh)
            .unwrap_err();
        assert!(e.to_string().contains("unknown node 9"), "{e}");
        pair(vec![0, 1], vec![2, 3], 0.0).check_on(&mesh).unwrap();
    }
}
