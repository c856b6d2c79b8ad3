//! The contact routines of the C ABI: two ways in, one analysis handle.
//!
//! * **Model API**: the host describes nodes, elements, materials, prescribed directions, contact
//!   pairs and an optional rigid plate in a [`HyconModel`]; hycon assembles, factors and runs
//!   the increments.
//! * **Host-assembly API**: the host keeps its own mesh and stiffness and describes only its
//!   contact polylines (node ids, reference coordinates and equation numbers in its numbering)
//!   in a [`HyconHost`], plus either its stiffness in CSR (factored by hycon), a solve callback
//!   ([`HyconSolveFn`]) so that it factors `K` with its own solver (CHOLMOD, PETSc, ...), or
//!   the condensed operator of its contact candidates ([`HyconCondensed`]) from its own solver,
//!   with no solve inside an increment.
//!
//! Both give a [`HyconContact`]: the contact iteration with `K` factored once, increments with
//! total loads, and the results (displacements, contact forces, tractions three ways, node
//! states, iteration records, contact-element matrices).
//!
//! Handle types: `hycon_X_new` creates, `hycon_X_free` destroys (`free(NULL)` is a no-op; a
//! double free or use after free is undefined behaviour, as for `free`). Thread safety is
//! stated per handle type in the header.

use super::*;
use crate::contact::bodies::{
    Condensed, CondensedKind, Csr, HostElements, HostNode, HostSolve, HostStiffness, HostSystem,
    NodeEquations, Triangle,
};
use crate::contact::handover::{self, Section};
use crate::contact::iteration::{
    ContactAnalysis, ContactOptions, ContactPair, IterationRecord, Kinematics, Monitor, NodeState,
    PlateControl,
};
use crate::contact::space::Vector;
use crate::mesh::Mesh;
use crate::model::Model;
use crate::solver::Backend;
use std::ffi::c_void;

// ------------------------------------------------------------------------------------------
// Constants

/// Sparse Cholesky library that factors `K`, one of `HYCON_BACKEND_*`.
pub type HyconBackend = i32;
/// faer (always available; the default).
pub const HYCON_BACKEND_FAER: HyconBackend = 1;
/// CHOLMOD from SuiteSparse (only when hycon was built with the `suitesparse` feature).
pub const HYCON_BACKEND_CHOLMOD: HyconBackend = 2;

/// Contact kinematics, one of `HYCON_KINEMATICS_*`.
pub type HyconKinematics = i32;
/// Small deformation (the default): the pairing, frames, weights and contact-element matrices
/// are evaluated once in the reference configuration and the gap is linear in the
/// displacements, consistent with small-strain elasticity (Hertz, Cattaneo-Mindlin); valid
/// while the surfaces slide little: an increment in which sliding with the frozen pairing would
/// move an active node's gap by more than 10% of the contact's normal approach fails with
/// `HYCON_ERROR_CONTACT` ("use finite kinematics"), keeping the last converged state.
pub const HYCON_KINEMATICS_SMALL: HyconKinematics = 1;
/// Finite kinematics: the contact geometry is evaluated at the current positions in every
/// iteration; for surfaces that slide far along each other.
pub const HYCON_KINEMATICS_FINITE: HyconKinematics = 2;

/// The largest `HyconContactOptions::threads`.
pub const HYCON_MAX_THREADS: u32 = 256;
const _: () = assert!(HYCON_MAX_THREADS as usize == crate::contact::iteration::MAX_THREADS);

/// Directions of a prescribed displacement, a bit mask.
pub type HyconDirections = i32;
/// x only.
pub const HYCON_X: HyconDirections = 1;
/// y only.
pub const HYCON_Y: HyconDirections = 2;
/// x and y.
pub const HYCON_XY: HyconDirections = 3;
/// z only (3D: `hycon_solid_model_prescribe`; the plane's `hycon_model_prescribe` rejects it).
pub const HYCON_Z: HyconDirections = 4;
/// x, y and z (3D: `hycon_solid_model_prescribe`; the plane's `hycon_model_prescribe` rejects
/// it).
pub const HYCON_XYZ: HyconDirections = 7;

/// State of an A node, one of `HYCON_NODE_*`.
pub type HyconNodeState = i32;
/// Not in contact.
pub const HYCON_NODE_OPEN: HyconNodeState = 1;
/// In contact, no slip since the increment began.
pub const HYCON_NODE_STICK: HyconNodeState = 2;
/// In contact and sliding (`ts = mu sign tn`).
pub const HYCON_NODE_SLIP: HyconNodeState = 3;
/// In contact without friction (a pair with friction 0; `ts = 0`). Before 0.7.0 such a node
/// was reported as `HYCON_NODE_SLIP` with `slip_sign` +1.
pub const HYCON_NODE_FRICTIONLESS: HyconNodeState = 4;

/// Which body a coupling entry belongs to, one of `HYCON_SIDE_*`.
pub type HyconSide = i32;
/// The multiplier side A: the entry is `F^A_kj`.
pub const HYCON_SIDE_A: HyconSide = 1;
/// The opposite side B: the entry is `F^B_kj`.
pub const HYCON_SIDE_B: HyconSide = 2;

/// Which part of a symmetric CSR matrix is given, one of `HYCON_CSR_*`.
pub type HyconTriangle = i32;
/// Every entry (checked to be symmetric to 1e-10 of the largest entry).
pub const HYCON_CSR_FULL: HyconTriangle = 1;
/// Entries with column <= row.
pub const HYCON_CSR_LOWER: HyconTriangle = 2;
/// Entries with column >= row.
pub const HYCON_CSR_UPPER: HyconTriangle = 3;

/// How a plate translation is driven in an increment, one of `HYCON_PLATE_*`.
pub type HyconPlateControl = i32;
/// The value is the plate's total displacement in that direction.
pub const HYCON_PLATE_DISPLACEMENT: HyconPlateControl = 1;
/// The value is the total force on the plate in that direction (its motion is solved for).
pub const HYCON_PLATE_FORCE: HyconPlateControl = 2;

/// Equation number of a contact dof that the host holds fixed at zero (host-assembly API).
pub const HYCON_FIXED: i64 = -1;

/// Which condensed operator a host hands over (`HyconCondensed::kind`), one of
/// `HYCON_CONDENSED_*`.
pub type HyconCondensedKind = i32;
/// The stiffness Schur complement `S = K_cc - K_ci K_ii^-1 K_ic` over the candidate equations
/// `c` (what MUMPS gives through PETSc's `MatFactorSetSchurIS` +
/// `MatFactorCreateSchurComplement`); hycon factors it once (dense Cholesky).
pub const HYCON_CONDENSED_STIFFNESS: HyconCondensedKind = 1;
/// The flexibility block `(K^-1)_cc` (one batched solve `K X = E_c`, e.g. CHOLMOD's).
pub const HYCON_CONDENSED_FLEXIBILITY: HyconCondensedKind = 2;

// ------------------------------------------------------------------------------------------
// Plain structs

/// What happened in one iteration of the contact search (also passed to the monitor).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HyconIterationRecord {
    /// Increment number (1-based).
    pub increment: usize,
    /// Iteration within the increment (1-based).
    pub iteration: usize,
    /// Active (stick + slip + frictionless) A nodes in this iteration's solve.
    pub active: usize,
    /// Stick nodes among them.
    pub stick: usize,
    /// Slip nodes among them (frictional pairs only; frictionless nodes are neither stick nor
    /// slip).
    pub slip: usize,
    /// State changes decided after the solve.
    pub changes: usize,
    /// Convergence measure over the contact dofs: the change of this iteration's displacement
    /// relative to the increment's motion so far (bounded below by round-off, and under finite
    /// kinematics by the largest motion of a converged increment); always finite.
    pub r: f64,
    /// Estimated 1-norm condition number of the small contact system (1 when empty).
    pub condition: f64,
    /// The worst violation of the discrete contact conditions by this iteration's solution
    /// (open gaps >= 0; closed nodes in compression with closed gaps; stick nodes inside the
    /// friction cone and not sliding; slip opposing the friction), relative to the problem's
    /// scale (open gaps to the increment's motion, at most the mean A segment; closed gaps and
    /// slips to the motion; tractions to the largest). At convergence at most 1e-4, else the
    /// increment fails with `HYCON_ERROR_CONTACT`.
    pub violation: f64,
    /// The sub-increment (1-based) this iteration belongs to: 1 unless the automatic cutback
    /// split the increment (see `HyconContactOptions::cutback_depth`). A sub-increment that
    /// fails is tried again, shorter, under the same index: the monitor sees both tries,
    /// `hycon_contact_records` keeps the converged one.
    pub sub_increment: usize,
}

/// Called with every iteration record, also those of the tries the automatic cutback halves
/// (`record->sub_increment` says which sub-increment a record belongs to); return 0 to go on,
/// nonzero to stop the increment (it then fails with `HYCON_ERROR_CALLBACK`, not retried, and
/// the last converged state is kept). Called on the
/// thread that called `hycon_contact_increment*`. Must not unwind (no C++ exceptions, no
/// longjmp) through hycon.
pub type HyconMonitorFn = Option<
    unsafe extern "C" fn(user_data: *mut c_void, record: *const HyconIterationRecord) -> i32,
>;

/// The host's linear solver: solve `K x_j = rhs_j` for `nrhs` right-hand sides, `rhs` and `x`
/// both `n x nrhs` column-major (`rhs` is read-only, `x` is written; they never overlap).
/// Return 0 on success, nonzero on failure (the hycon call then fails with
/// `HYCON_ERROR_CALLBACK`). hycon calls it with many columns at once: at contact setup with unit
/// right-hand sides (at most 64 columns per call) to build the boundary flexibility, and with one
/// column per new load and per displacement recovery. A load that is a combination of the
/// last few loads (proportional loading, say) is not solved again: its response is combined
/// from theirs, so such an increment makes no call at all. Called on the thread that calls into the
/// `HyconContact`. Must not unwind through hycon.
pub type HyconSolveFn = Option<
    unsafe extern "C" fn(
        user_data: *mut c_void,
        n: usize,
        nrhs: usize,
        rhs: *const f64,
        x: *mut f64,
    ) -> i32,
>;

/// Parameters of the contact iteration. Get the defaults with `hycon_contact_options_default`
/// (which also sets `size`), then override fields. Tolerances are relative (see each field), so
/// results do not change when units are rescaled.
///
/// Versioned by `size`: a host that fills the struct itself sets
/// `size = sizeof(HyconContactOptions)`. hycon reads only the fields that fit in `size` and
/// defaults the rest (fields are only ever added at the end), so a host built against an older
/// header keeps working; a size below the 0.7.0 layout (the first with `size`), or above the
/// layout this library knows, is rejected with `HYCON_ERROR_INVALID_ARGUMENT`.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct HyconContactOptions {
    /// `sizeof(HyconContactOptions)` as the host was compiled (set by
    /// `hycon_contact_options_default`).
    pub size: usize,
    /// Convergence tolerance on `R` (default 1e-6; the paper used 0.01).
    pub tolerance: f64,
    /// Penetration tolerance, relative to the increment's displacement scale (default 1e-9).
    pub gap_tolerance: f64,
    /// Tension tolerance, relative to the largest `|tn|` (default 1e-9).
    pub tension_tolerance: f64,
    /// Friction-cone tolerance, relative to `mu |tn|` (default 1e-9).
    pub friction_tolerance: f64,
    /// Slip tolerance (default 1e-6): a slip node returns to stick when its slip reverses by
    /// more than this, and a closing node enters in slip when it has slid more than this,
    /// relative to the increment's motion (the largest motion of a contact node in this
    /// increment or a converged one), so it scales with the load.
    pub slip_tolerance: f64,
    /// B segments farther than this from an A segment, relative to the mean A segment length,
    /// are not paired with it (default 4). The pairing reaches farther as the bodies move:
    /// at least twice an increment's largest motion under finite kinematics, and under small
    /// kinematics the reference pairing is widened to four times the largest displacement of
    /// the pair's nodes whenever twice that exceeds it, so a finer mesh never loses contact.
    pub search_distance: f64,
    /// Iteration cap per increment (default 60).
    pub max_iterations: u32,
    /// Cycle policy: how many times per increment a cycling contact set is resolved by locking
    /// the alternating nodes (in slip for stick/slip alternation at the friction cone, open for
    /// open/closed alternation at the edge of the contact zone) before a cycle fails the
    /// increment (default 3; 0 fails at the first cycle).
    pub lock_rounds: u32,
    /// Sparse Cholesky library for hycon's own factorizations (default `HYCON_BACKEND_FAER`;
    /// `HYCON_BACKEND_CHOLMOD` fails with `HYCON_ERROR_SOLVER` unless hycon was built with the
    /// `suitesparse` feature).
    pub backend: HyconBackend,
    /// Contact kinematics (default `HYCON_KINEMATICS_SMALL`; `HYCON_KINEMATICS_FINITE` for
    /// extensive sliding).
    pub kinematics: HyconKinematics,
    /// Threads the contact boundary's substitutions with hycon's own faer factor may use, 1
    /// to `HYCON_MAX_THREADS` (default 1: hycon starts no thread). More share the images of new node
    /// directions and each iteration's backward substitution among them, with every result
    /// the same to the bit. Threads are started per call and none outlives it; a host running
    /// one process per core (MPI) keeps 1.
    pub threads: u32,
    /// Optional iteration monitor (NULL: none). Kept by the `HyconContact` for its lifetime.
    pub monitor: HyconMonitorFn,
    /// Passed to `monitor`; must stay valid as long as the `HyconContact` that uses it.
    pub monitor_data: *mut c_void,
    /// Automatic cutback (default 8; 0 switches it off: a failed increment fails at once, the
    /// behaviour before 0.7.0): an increment that fails for an iteration reason (no
    /// convergence, a cycling contact set, a locked node breaking its lock, a surface pushed
    /// beyond what the pairing sees) is taken again in sub-increments from the last converged
    /// state to the target (loads, prescribed values and plate controls interpolated
    /// linearly, each converged sub-increment the start of the next), halving a failed one at
    /// most `cutback_depth` times (up to `HYCON_MAX_CUTBACK_DEPTH`). `K` is not factored
    /// again and the interpolated loads cost no solve. Beyond the limit the increment fails
    /// and the analysis is exactly as before the call.
    pub cutback_depth: u32,
    /// The shortest sub-increment the cutback tries, as a fraction of the increment, in
    /// `(0, 1]` (default 1/256).
    pub cutback_min_fraction: f64,
}

/// The largest `HyconContactOptions::cutback_depth`.
pub const HYCON_MAX_CUTBACK_DEPTH: u32 = 52;
const _: () =
    assert!(HYCON_MAX_CUTBACK_DEPTH as usize == crate::contact::iteration::MAX_CUTBACK_DEPTH);

/// The size of the 0.7.0 layout of `HyconContactOptions`, the first with a `size` field: the
/// smallest `size` accepted.
const OPTIONS_FIRST_BLOCK: usize = std::mem::size_of::<HyconContactOptions>();

/// Summary of a converged increment.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HyconIncrementInfo {
    /// Increment number (1-based).
    pub increment: usize,
    /// Iterations used (summed over the converged sub-increments: the records
    /// `hycon_contact_records` keeps of the increment).
    pub iterations: usize,
    /// Active (stick + slip + frictionless) A nodes at convergence.
    pub active: usize,
    /// Slip nodes at convergence.
    pub slip: usize,
    /// Converged sub-increments the increment was taken in: 1 unless the automatic cutback
    /// split it.
    pub sub_increments: usize,
    /// Sub-increments that failed and were tried again shorter (0 without cutback).
    pub cutbacks: usize,
}

/// Converged results at one A node (multiplier side).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HyconNodeResult {
    /// Node id (the caller's numbering).
    pub node: usize,
    /// `HYCON_NODE_OPEN`, `HYCON_NODE_STICK`, `HYCON_NODE_SLIP` or `HYCON_NODE_FRICTIONLESS`.
    pub state: HyconNodeState,
    /// Slip direction along `tangent` of A relative to B (+1 or -1) for a slip node, else 0.
    pub slip_sign: i32,
    /// Normal traction on A (the multiplier, force per area for every analysis kind and
    /// thickness; `< 0` compression, pressure `p = -tn`).
    pub tn: f64,
    /// Tangential traction on A along `tangent` (force per area).
    pub ts: f64,
    /// Nodal normal (A's outward): of the reference configuration under small kinematics, of
    /// the converged one under finite kinematics.
    pub normal: [f64; 2],
    /// Nodal tangent `(n_y, -n_x)`.
    pub tangent: [f64; 2],
    /// Current position (reference position plus the converged displacement).
    pub position: [f64; 2],
    /// Tributary measure `integral M_k dS` (`dS = t ds`, A's thickness `t`), measured in the
    /// configuration the geometry lives in (reference under small kinematics, converged under
    /// finite): the tractions are per unit of it (pressures), so `sum -tn * weight` is the
    /// normal load only where A is straight.
    pub weight: f64,
    /// Weighted normal gap per unit length (`< 0` penetration; infinite where B does not
    /// cover the node's support).
    pub gap: f64,
    /// Equivalent nodal contact force on A, `sum_k F^A_kj t_k` (x, y).
    pub force: [f64; 2],
}

/// Converged results at one B node (the opposite side).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HyconBNodeResult {
    /// Node id (the caller's numbering).
    pub node: usize,
    /// `integral L^B_j dS` over the projected overlap (0 outside it; `dS` A's measure).
    pub weight: f64,
    /// Equivalent nodal contact force on B (x, y).
    pub force: [f64; 2],
    /// Pressure `-force . n / weight` (`n` B's outward nodal normal; 0 outside the overlap).
    pub pressure: f64,
    /// Current position.
    pub position: [f64; 2],
}

/// Contact-element quantities of one A node at the converged state (the reference one before
/// the first increment; under small kinematics the pairing, frames and weights are always the
/// reference ones and the gaps linear in the displacements), for hosts that assemble the mixed
/// system themselves.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HyconContactNode {
    /// Node id (the caller's numbering).
    pub node: usize,
    /// `integral M_k dS` over the node's support (`dS = t ds`, A's surface measure).
    pub weight: f64,
    /// Fraction of the support covered by B, in [0, 1].
    pub coverage: f64,
    /// Nodal normal `n_k` (A's outward).
    pub normal: [f64; 2],
    /// Nodal tangent `s_k = (n_y, -n_x)`.
    pub tangent: [f64; 2],
    /// Weighted gap vector `R_C,k = integral M_k (x^A - x^B) dS` (x, y).
    pub gap: [f64; 2],
    /// `-n_k . R_C,k / covered weight`: normal gap as a length (`< 0` penetration; infinite
    /// when nothing is covered).
    pub normal_gap: f64,
}

/// One entry of the contact-element matrices: `F^A_kj = integral M_k L^A_j dS` or
/// `F^B_kj = integral M_k L^B_j(x^B) dS` (both >= 0; `dS` A's surface measure). The constraint row of A node `k` is
/// `sum_j F^A_kj u_j - sum_j F^B_kj u_j` (per component).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HyconCouplingEntry {
    /// Index `k` of the A node within the pair's A polyline.
    pub row: usize,
    /// Node id `j` (the caller's numbering).
    pub node: usize,
    /// `HYCON_SIDE_A` or `HYCON_SIDE_B`.
    pub side: HyconSide,
    /// The value.
    pub value: f64,
}

/// Where the time of an analysis went (wall-clock seconds, accumulated).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HyconTimings {
    /// Sparse assembly of `K` (model API).
    pub assembly: f64,
    /// Symbolic analysis and numeric factorization of `K` (once per analysis).
    pub factorization: f64,
    /// Contact-boundary flexibility (from the factor, or from host solves).
    pub flexibility: f64,
    /// Load solves.
    pub load_solves: f64,
    /// The contact iterations.
    pub iterations: f64,
    /// Displacement recovery.
    pub recovery: f64,
}

/// One constraint entry of `Kc` (see `hycon_contact_constraint_rows`).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HyconConstraintEntry {
    /// Row: `2 k` the normal and `2 k + 1` the tangential constraint of A node `k`.
    pub row: usize,
    /// Column: a field index (model dof `2 node + direction`, or host equation).
    pub column: usize,
    /// The value.
    pub value: f64,
}

// ------------------------------------------------------------------------------------------
// Input views: a few pointers and lengths that travel together, read during the call only

/// Elements of one formulation in compressed form: element `e` has the nodes
/// `nodes[offsets[e] .. offsets[e + 1]]` (4 to 6 node ids, counter-clockwise: corners plus
/// mid-side nodes of transition elements, in boundary order).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct HyconElementBlock {
    /// `n_elements + 1` offsets into `nodes`, starting at 0, nondecreasing.
    pub offsets: *const usize,
    /// `offsets[n_elements]` node ids.
    pub nodes: *const usize,
    /// Number of elements (at least 1).
    pub n_elements: usize,
    /// `n_elements` indices into the call's materials, or NULL: every element uses material 0.
    pub materials: *const usize,
    /// The formulation of every element (`HYCON_ELEMENT_*`; Pian-Sumihara and Q4 take 4-node
    /// elements only).
    pub kind: HyconElementKind,
}

/// A polyline of node ids (model API contact pairs), ordered with its body on the left.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct HyconPolyline {
    /// `n` node ids.
    pub nodes: *const usize,
    /// Number of nodes.
    pub n: usize,
}

/// A host's condensed operator over its contact candidate equations (host-assembly API,
/// `hycon_host_set_condensed`). The candidates hold every equation of the contact nodes (all
/// nodes of all pairs: under finite kinematics the polylines must cover the whole sliding
/// range) and may hold more. Versioned by `size` as `HyconContactOptions`: set
/// `size = sizeof(HyconCondensed)`.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct HyconCondensed {
    /// `sizeof(HyconCondensed)` as the host was compiled.
    pub size: usize,
    /// `HYCON_CONDENSED_STIFFNESS` or `HYCON_CONDENSED_FLEXIBILITY`.
    pub kind: HyconCondensedKind,
    /// Number of candidate equations `m`.
    pub m: usize,
    /// The `m` candidate equations (host numbering, each once): the order of the matrix's rows
    /// and columns and of every increment's load image.
    pub equations: *const i64,
    /// `m * m` doubles, column-major: `matrix[i + m * j]` couples `equations[i]` and
    /// `equations[j]`; symmetric (to 1e-6 of its largest entry; both triangles are read and
    /// averaged).
    pub matrix: *const f64,
}

/// The smallest `HyconCondensed::size` accepted: its first layout (0.8.0).
const CONDENSED_FIRST_BLOCK: usize = std::mem::size_of::<HyconCondensed>();

/// Nodes in a host's numbering (host-assembly API): ids, reference coordinates and equation
/// numbers.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct HyconHostNodes {
    /// `n` node ids.
    pub ids: *const usize,
    /// `2 n` reference coordinates `x0 y0 x1 y1 ...` (finite).
    pub coords: *const f64,
    /// `2 n` equation numbers (`u_x`, `u_y` per node) in `0 .. n_equations`, or `HYCON_FIXED`
    /// for a dof the host holds at zero.
    pub equations: *const i64,
    /// Number of nodes.
    pub n: usize,
}

// ------------------------------------------------------------------------------------------
// Handles

/// A model being described (model API): mesh, materials, prescribed directions, contact
/// pairs, optional rigid plate. Create with `hycon_model_new`, free with `hycon_model_free`.
/// Thread safety: a `HyconModel` may be used from any thread, but not from two at once;
/// distinct models are independent.
pub struct HyconModel {
    model: Model,
    pairs: Vec<ContactPair>,
    plate: Option<Vec<usize>>,
}

/// A host's contact description (host-assembly API): its contact polylines and its stiffness
/// (CSR), solve callback or condensed operator. Create with `hycon_host_new`, free with `hycon_host_free`.
/// Thread safety: as `HyconModel`.
pub struct HyconHost {
    equations: usize,
    nodes: Vec<HostNode>,
    pairs: Vec<ContactPair>,
    /// Per pair, a point inside body A (`hycon_host_set_pair_inside`).
    a_inside: Vec<Option<Vector>>,
    /// The section (analysis kind, thickness) of each pair's A side.
    sections: Vec<Section>,
    stiffness: Option<HostSource>,
    elements: Option<HostElements>,
}

/// How a host description (plane or 3D) holds the stiffness it was given.
pub(super) enum HostSource {
    Csr(Csr),
    Callback(CallbackSolve),
    Condensed(Condensed),
}

impl HostSource {
    /// The host's solve callback with its user data.
    pub(super) fn callback(solve: HyconSolveFn, user_data: *mut c_void) -> Result<Self, Fail> {
        match solve {
            Some(solve) => Ok(HostSource::Callback(CallbackSolve { solve, user_data })),
            None => Err(Fail::new(HYCON_ERROR_NULL_POINTER, "solve is NULL")),
        }
    }

    /// The stiffness an analysis takes from a description's `source` (copied; a callback's
    /// pointers shared); an error naming the setters (`prefix`: `hycon_host` or
    /// `hycon_solid_host`) when none was given.
    pub(super) fn stiffness(source: Option<&Self>, prefix: &str) -> Result<HostStiffness, Fail> {
        match source {
            Some(HostSource::Csr(csr)) => Ok(HostStiffness::Csr(csr.clone())),
            Some(HostSource::Callback(c)) => Ok(HostStiffness::Solver(Box::new(CallbackSolve {
                solve: c.solve,
                user_data: c.user_data,
            }))),
            Some(HostSource::Condensed(c)) => Ok(HostStiffness::Condensed(c.clone())),
            None => Err(Fail::invalid(format!(
                "the host gave neither a stiffness ({prefix}_set_csr), a solver \
                 ({prefix}_set_solver) nor its condensed operator ({prefix}_set_condensed)"
            ))),
        }
    }
}

/// A contact analysis: `K` factored once (or the host's solver), the converged state, the
/// records. Create with `hycon_contact_new` (model API) or `hycon_contact_new_host`, free with
/// `hycon_contact_free`. Thread safety: the functions taking `HyconContact *` (increments,
/// free) need the handle exclusively; the queries taking `const HyconContact *` may run on one
/// handle from several threads at once (the displacement recovery's solves are serialized by
/// a lock inside, so a solve callback is never entered concurrently, though it may be entered
/// from any querying thread). Distinct handles share nothing. Callbacks run on the calling
/// thread.
pub struct HyconContact {
    analysis: ContactAnalysis,
}

/// The host's solve callback with its user data.
pub(super) struct CallbackSolve {
    solve: unsafe extern "C" fn(*mut c_void, usize, usize, *const f64, *mut f64) -> i32,
    user_data: *mut c_void,
}

// SAFETY: the callback and its user data are only ever invoked on the thread that is calling
// into the owning handle (never concurrently: the handle is not shared between threads, as
// documented); moving the handle moves the obligation with it.
unsafe impl Send for CallbackSolve {}

impl HostSolve for CallbackSolve {
    fn solve(&mut self, nrhs: usize, rhs: &[f64], x: &mut [f64]) -> crate::Result<()> {
        let n = rhs.len() / nrhs.max(1);
        // SAFETY: `rhs` and `x` are live buffers of `n * nrhs` doubles owned by hycon; the host
        // promised the callback reads `rhs` and writes `x` within those bounds.
        let code = unsafe { (self.solve)(self.user_data, n, nrhs, rhs.as_ptr(), x.as_mut_ptr()) };
        if code == 0 {
            Ok(())
        } else {
            Err(Error::Callback(format!(
                "the solve callback returned {code} (n = {n}, nrhs = {nrhs})"
            )))
        }
    }
}

/// The monitor callback with its user data.
struct MonitorCall {
    monitor: unsafe extern "C" fn(*mut c_void, *const HyconIterationRecord) -> i32,
    user_data: *mut c_void,
}

// SAFETY: as for `CallbackSolve`: only invoked on the thread calling into the owning handle.
unsafe impl Send for MonitorCall {}

impl MonitorCall {
    /// Whether the host's monitor lets the iteration go on after record `r`.
    fn call(&self, r: &IterationRecord) -> bool {
        let record = record_to_c(r);
        // SAFETY: `record` is a live local; the host's function and data are as it gave them in
        // the options.
        unsafe { (self.monitor)(self.user_data, &record) == 0 }
    }

    fn into_monitor(self) -> Monitor {
        Box::new(move |r: &IterationRecord| self.call(r))
    }
}

fn record_to_c(r: &IterationRecord) -> HyconIterationRecord {
    HyconIterationRecord {
        increment: r.increment,
        iteration: r.iteration,
        active: r.active,
        stick: r.stick,
        slip: r.slip,
        changes: r.changes,
        r: r.r,
        condition: r.condition,
        violation: r.violation,
        sub_increment: r.sub_increment,
    }
}

// ------------------------------------------------------------------------------------------
// Reading the inputs

fn options_from_c(o: &HyconContactOptions) -> Result<(ContactOptions, Option<Monitor>), Fail> {
    let backend = match o.backend {
        HYCON_BACKEND_FAER => Backend::Faer,
        HYCON_BACKEND_CHOLMOD => Backend::Cholmod,
        b => {
            return Err(Fail::invalid(format!(
                "options.backend = {b} is unknown (HYCON_BACKEND_FAER = 1, \
                 HYCON_BACKEND_CHOLMOD = 2)"
            )));
        }
    };
    let kinematics = match o.kinematics {
        HYCON_KINEMATICS_SMALL => Kinematics::Small,
        HYCON_KINEMATICS_FINITE => Kinematics::Finite,
        k => {
            return Err(Fail::invalid(format!(
                "options.kinematics = {k} is unknown (HYCON_KINEMATICS_SMALL = 1, \
                 HYCON_KINEMATICS_FINITE = 2)"
            )));
        }
    };
    let max_iterations = usize::try_from(o.max_iterations)
        .map_err(|_| Fail::invalid("options.max_iterations does not fit in size_t"))?;
    let options = ContactOptions {
        kinematics,
        tolerance: o.tolerance,
        max_iterations,
        gap_tolerance: o.gap_tolerance,
        tension_tolerance: o.tension_tolerance,
        friction_tolerance: o.friction_tolerance,
        slip_tolerance: o.slip_tolerance,
        search_distance: o.search_distance,
        lock_rounds: o.lock_rounds as usize,
        backend,
        threads: usize::try_from(o.threads)
            .map_err(|_| Fail::invalid("options.threads does not fit in size_t"))?,
        cutback_depth: usize::try_from(o.cutback_depth)
            .map_err(|_| Fail::invalid("options.cutback_depth does not fit in size_t"))?,
        cutback_min_fraction: o.cutback_min_fraction,
    };
    options.validate()?;
    let monitor = o.monitor.map(|monitor| {
        MonitorCall {
            monitor,
            user_data: o.monitor_data,
        }
        .into_monitor()
    });
    Ok((options, monitor))
}

/// Elements in compressed form with their materials, read from caller arrays and checked
/// (offsets start at 0 and do not decrease, material indices in range).
struct ElementArrays {
    formulation: Formulation,
    offsets: Vec<usize>,
    nodes: Vec<usize>,
    element_material: Vec<usize>,
    materials: Vec<Material>,
}

/// Read and check an element block view (`name`: the argument) and its `n_materials`
/// materials.
///
/// # Safety
/// `block` must be NULL or point to a readable view whose arrays hold the stated number of
/// values; `materials` NULL or `n_materials` readable structs.
unsafe fn read_block(
    block: *const HyconElementBlock,
    name: &str,
    materials: *const HyconMaterial,
    n_materials: usize,
) -> Result<ElementArrays, Fail> {
    // SAFETY (all reads): forwarded contract.
    let b = unsafe { handle(block, name)? };
    let formulation = formulation(b.kind)?;
    let n_elements = b.n_elements;
    if n_elements == 0 || n_materials == 0 {
        return Err(Fail::invalid(format!(
            "elements and materials are needed (got {n_elements} and {n_materials})"
        )));
    }
    let n_offsets = length(n_elements, 1, 1, &format!("{name}.n_elements"))?;
    let offsets = unsafe { slice(b.offsets, n_offsets, &format!("{name}.offsets"))? };
    if offsets[0] != 0 || offsets.windows(2).any(|w| w[1] < w[0]) {
        return Err(Fail::invalid(format!(
            "{name}.offsets must start at 0 and be nondecreasing"
        )));
    }
    let nodes = unsafe { slice(b.nodes, offsets[n_elements], &format!("{name}.nodes"))? };
    let element_material = if b.materials.is_null() {
        vec![0; n_elements]
    } else {
        unsafe { slice(b.materials, n_elements, &format!("{name}.materials"))? }.to_vec()
    };
    let materials = unsafe { slice(materials, n_materials, "materials")? }
        .iter()
        .map(|m| unsafe { read_material(m) })
        .collect::<Result<Vec<_>, _>>()?;
    if let Some((e, &m)) = element_material
        .iter()
        .enumerate()
        .find(|(_, m)| **m >= n_materials)
    {
        return Err(Fail::invalid(format!(
            "element {e} uses material {m}, but there are {n_materials}"
        )));
    }
    Ok(ElementArrays {
        formulation,
        offsets: offsets.to_vec(),
        nodes: nodes.to_vec(),
        element_material,
        materials,
    })
}

/// Read and check a polyline view (`name`: the argument).
///
/// # Safety
/// `polyline` must be NULL or point to a readable view whose `nodes` holds `n` ids.
unsafe fn read_polyline<'a>(
    polyline: *const HyconPolyline,
    name: &str,
) -> Result<&'a [usize], Fail> {
    // SAFETY (both): forwarded contract.
    let p = unsafe { handle(polyline, name)? };
    unsafe { slice(p.nodes, p.n, &format!("{name}.nodes")) }
}

/// Read and check a host node view (`name`: the argument; `side`: how messages name its
/// nodes) for a system of `n_equations` equations ([`host_nodes`]).
///
/// # Safety
/// `view` must be NULL or point to a readable view whose arrays hold the stated number of
/// values.
unsafe fn read_host_nodes(
    view: *const HyconHostNodes,
    name: &str,
    side: &str,
    n_equations: usize,
) -> Result<Vec<HostNode>, Fail> {
    // SAFETY (all reads): forwarded contract.
    let v = unsafe { handle(view, name)? };
    unsafe {
        host_nodes(
            v.ids,
            v.coords,
            v.equations,
            v.n,
            2,
            name,
            side,
            n_equations,
        )
    }
}

/// Read and check `n` host nodes of `dim` components (`name`: the view; `side`: how messages
/// name its nodes) for a system of `n_equations` equations: `n` ids, `dim n` finite
/// coordinates, `dim n` equations in range or `HYCON_FIXED` (the one place `HYCON_FIXED` is
/// decoded).
///
/// # Safety
/// `ids` NULL or `n` readable ids, `coords` and `equations` NULL or `dim n` readable values.
#[allow(clippy::too_many_arguments)] // the fields of a view, named for the messages
pub(super) unsafe fn host_nodes(
    ids: *const usize,
    coords: *const f64,
    equations: *const i64,
    n: usize,
    dim: usize,
    name: &str,
    side: &str,
    n_equations: usize,
) -> Result<Vec<HostNode>, Fail> {
    let per_node = length(n, dim, 0, &format!("{name}.n"))?;
    // SAFETY (all reads): forwarded contract.
    let ids = unsafe { slice(ids, n, &format!("{name}.ids"))? };
    let xyz = unsafe { doubles(coords, per_node, &format!("{name}.coords"))? };
    let eqs = unsafe { slice(equations, per_node, &format!("{name}.equations"))? };
    ids.iter()
        .enumerate()
        .map(|(i, &id)| {
            let equations = (eqs[dim * i..dim * (i + 1)].iter())
                .map(|&e| match e {
                    HYCON_FIXED => Ok(None),
                    r if r >= 0 && (r as u64) < n_equations as u64 => Ok(Some(r as usize)),
                    r => Err(Fail::invalid(format!(
                        "{side} node {id}: equation {r} is out of range (0..{n_equations} or \
                         HYCON_FIXED)"
                    ))),
                })
                .collect::<Result<Vec<_>, _>>()?;
            Ok(HostNode {
                id,
                position: Vector::from_components(&xyz[dim * i..dim * (i + 1)]),
                equations: NodeEquations::new(&equations),
            })
        })
        .collect()
}

/// Read the options argument (NULL: defaults).
///
/// # Safety
/// `options` must be NULL or point to a readable `HyconContactOptions`.
pub(super) unsafe fn read_options(
    options: *const HyconContactOptions,
) -> Result<(ContactOptions, Option<Monitor>), Fail> {
    if options.is_null() {
        return Ok((ContactOptions::default(), None));
    }
    check_pointer(options, "options")?;
    // SAFETY: non-null and aligned (checked), and the host's struct begins with its size
    let size = unsafe { options.cast::<usize>().read() };
    let known = std::mem::size_of::<HyconContactOptions>();
    if !(OPTIONS_FIRST_BLOCK..=known).contains(&size) {
        return Err(Fail::invalid(format!(
            "options.size = {size}: expected sizeof(HyconContactOptions), from \
             {OPTIONS_FIRST_BLOCK} (the 0.7.0 layout, the first with a size) to {known} (this \
             library's): fill the options with hycon_contact_options_default"
        )));
    }
    // the fields that fit in `size`; the rest keep their defaults
    let mut o = default_options();
    // SAFETY: the host's struct is `size` readable bytes (its contract), `o` has `known >=
    // size` bytes, every bit pattern copied is one the host wrote into a field of the same
    // layout, and the two do not overlap
    unsafe {
        std::ptr::copy_nonoverlapping(
            options.cast::<u8>(),
            std::ptr::from_mut(&mut o).cast::<u8>(),
            size,
        );
    }
    options_from_c(&o)
}

/// The default options in their C form (no monitor).
fn default_options() -> HyconContactOptions {
    let d = ContactOptions::default();
    HyconContactOptions {
        size: std::mem::size_of::<HyconContactOptions>(),
        tolerance: d.tolerance,
        gap_tolerance: d.gap_tolerance,
        tension_tolerance: d.tension_tolerance,
        friction_tolerance: d.friction_tolerance,
        slip_tolerance: d.slip_tolerance,
        search_distance: d.search_distance,
        max_iterations: d.max_iterations as u32,
        lock_rounds: d.lock_rounds as u32,
        backend: HYCON_BACKEND_FAER,
        kinematics: match d.kinematics {
            Kinematics::Small => HYCON_KINEMATICS_SMALL,
            Kinematics::Finite => HYCON_KINEMATICS_FINITE,
        },
        threads: d.threads as u32,
        monitor: None,
        monitor_data: std::ptr::null_mut(),
        cutback_depth: d.cutback_depth as u32,
        cutback_min_fraction: d.cutback_min_fraction,
    }
}

// ------------------------------------------------------------------------------------------
// Options

/// Fill `out` with the default options (the values documented per field, no monitor).
///
/// # Safety
/// `out` must be NULL or point to a writable `HyconContactOptions`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_options_default(
    out: *mut HyconContactOptions,
) -> HyconStatus {
    boundary("hycon_contact_options_default", || {
        let o = default_options();
        // SAFETY: the caller's contract on `out`.
        unsafe { write(out, o, "out") }
    })
}

// ------------------------------------------------------------------------------------------
// Model API

/// Create a model from its mesh and materials (the order of every call that takes a mesh:
/// nodes, elements, materials).
///
/// * `coords`: `2 * n_nodes` doubles `x0 y0 x1 y1 ...`;
/// * `elements`: the elements (`HyconElementBlock`: compressed node lists, their material
///   indices or NULL for all 0, the formulation);
/// * `materials`: `n_materials` materials.
///
/// The arrays are copied. Errors: `HYCON_ERROR_NULL_POINTER` (`out`, `coords`, `elements`,
/// `materials`, or an array of `elements` with a nonzero length), `HYCON_ERROR_INVALID_ARGUMENT`
/// (lengths, unknown node ids, non-finite coordinates, unknown kind, misaligned pointers),
/// `HYCON_ERROR_INVALID_MATERIAL` (also materials of different analysis kinds: one model takes
/// one kind), `HYCON_ERROR_BAD_ELEMENT` (inverted, degenerate or non-convex element, named by
/// index; in axisymmetry also a node at `x < 0`, Pian-Sumihara or a 5- or 6-node element).
///
/// # Safety
/// `out` must point to a writable pointer; `coords` NULL or `2 n_nodes` readable doubles;
/// `elements` NULL or a readable view whose arrays hold the stated counts; `materials` NULL or
/// `n_materials` readable structs.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_model_new(
    out: *mut *mut HyconModel,
    coords: *const f64,
    n_nodes: usize,
    elements: *const HyconElementBlock,
    materials: *const HyconMaterial,
    n_materials: usize,
) -> HyconStatus {
    boundary("hycon_model_new", || {
        check_pointer(out.cast_const(), "out")?;
        if n_nodes == 0 {
            return Err(Fail::invalid("a model needs nodes (n_nodes = 0)"));
        }
        // SAFETY (all reads below): the caller's contract on the arrays and lengths.
        let xy = unsafe { doubles(coords, length(n_nodes, 2, 0, "n_nodes")?, "coords")? };
        let elements = unsafe { read_block(elements, "elements", materials, n_materials)? };
        let mut mesh = Mesh::new();
        for p in xy.chunks_exact(2) {
            mesh.push_node([p[0], p[1]]);
        }
        mesh.element_offsets = elements.offsets;
        mesh.element_nodes = elements.nodes;
        mesh.element_material = elements.element_material;
        let model = Model::new(mesh, elements.materials, elements.formulation);
        model.validate()?;
        // SAFETY: the caller's contract on `out`.
        unsafe {
            hand_out(
                out,
                HyconModel {
                    model,
                    pairs: Vec::new(),
                    plate: None,
                },
            )
        }
    })
}

/// Free a model (NULL is a no-op). Analyses made from it keep their own copy.
///
/// # Safety
/// `model` must be NULL or a live handle from `hycon_model_new`, not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_model_free(model: *mut HyconModel) {
    // SAFETY: the caller's contract.
    unsafe { free_handle(model) }
}

/// Prescribe the displacement of `nodes` in `directions` (`HYCON_X`, `HYCON_Y` or `HYCON_XY`).
/// The values are given per increment (`prescribed` of `hycon_contact_increment`). Contact
/// nodes may be prescribed too.
///
/// Errors: `HYCON_ERROR_INVALID_ARGUMENT` for an unknown node id, unknown `directions`, or a
/// displacement component prescribed twice (listed twice in `nodes`, prescribed by an earlier
/// call, or tied to the plate); on an error nothing is prescribed.
///
/// # Safety
/// `model` must be a live handle; `nodes` NULL or `n` readable ids.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_model_prescribe(
    model: *mut HyconModel,
    nodes: *const usize,
    n: usize,
    directions: HyconDirections,
) -> HyconStatus {
    boundary("hycon_model_prescribe", || {
        // SAFETY: the caller's contract.
        let m = unsafe { handle_mut(model, "model")? };
        let ids = unsafe { slice(nodes, n, "nodes")? };
        let dirs: &[usize] = match directions {
            HYCON_X => &[0],
            HYCON_Y => &[1],
            HYCON_XY => &[0, 1],
            d => {
                return Err(Fail::invalid(format!(
                    "directions = {d} (expected HYCON_X = 1, HYCON_Y = 2 or HYCON_XY = 3)"
                )));
            }
        };
        match dirs {
            [d] => m.model.fix_dir(ids, *d, 0.0)?,
            _ => m.model.fix(ids, [0.0, 0.0])?,
        }
        Ok(())
    })
}

/// Add a contact pair: the multiplier-side polyline `a` and the opposite polyline `b` (node
/// ids, each ordered with its body on the left: consecutive nodes must be the two ends of an
/// element edge of that body, in the element's counter-clockwise order) and the Coulomb
/// friction coefficient `friction >= 0` (0: frictionless). The pair's index (0, 1, ...) is
/// written to `index` unless it is NULL.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`model`, `a`, `b`, or their `nodes` with `n > 0`);
/// `HYCON_ERROR_INVALID_ARGUMENT` for unknown node ids, fewer than 2 nodes, repeated nodes, a
/// node in both polylines, consecutive nodes that are not an element edge with the body on the
/// left (naming the segment), a bad friction coefficient, a misaligned pointer.
///
/// # Safety
/// `model` must be a live handle; `a`, `b` NULL or readable views holding `n` ids each;
/// `index` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_model_add_pair(
    model: *mut HyconModel,
    a: *const HyconPolyline,
    b: *const HyconPolyline,
    friction: f64,
    index: *mut usize,
) -> HyconStatus {
    boundary("hycon_model_add_pair", || {
        // SAFETY (all): the caller's contract.
        let m = unsafe { handle_mut(model, "model")? };
        let index = optional(index, "index")?;
        let (a, b) = unsafe { (read_polyline(a, "a")?, read_polyline(b, "b")?) };
        let pair = ContactPair {
            a: a.to_vec(),
            b: b.to_vec(),
            friction,
        };
        pair.check_on(&m.model.mesh)?;
        m.pairs.push(pair);
        unsafe { put(index, m.pairs.len() - 1) };
        Ok(())
    })
}

/// Tie `nodes` (a face of one body, none of them a contact node) to a rigid plate whose x and
/// y translations are driven per increment by `hycon_contact_increment_with_plate`, each by
/// displacement or by force. The nodes are prescribed in x and y by this call. A body held only
/// by the plate and by contact (a pressed disk) then takes a prescribed force.
///
/// Errors: `HYCON_ERROR_INVALID_ARGUMENT` for no nodes, an unknown node id, or a node already
/// prescribed (by `hycon_model_prescribe`, twice in `nodes`, or by an earlier plate: a model
/// has one plate); on an error the model is unchanged.
///
/// # Safety
/// `model` must be a live handle; `nodes` NULL or `n` readable ids.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_model_set_plate(
    model: *mut HyconModel,
    nodes: *const usize,
    n: usize,
) -> HyconStatus {
    boundary("hycon_model_set_plate", || {
        // SAFETY: the caller's contract.
        let m = unsafe { handle_mut(model, "model")? };
        let ids = unsafe { slice(nodes, n, "nodes")? };
        if ids.is_empty() {
            return Err(Fail::invalid("a plate needs at least one node"));
        }
        m.model.fix(ids, [0.0, 0.0])?;
        m.plate = Some(ids.to_vec());
        Ok(())
    })
}

/// Start a contact analysis of a model (copied: the model may be freed or changed afterwards):
/// validate, assemble, factor `K` once with the contact dofs last and read the contact-boundary
/// flexibility off the factor. `options` NULL means the defaults.
///
/// A model without contact pairs is allowed: its increments are plain linear solves.
///
/// Errors: `HYCON_ERROR_SINGULAR` (a body not held against rigid motion: the message names it),
/// `HYCON_ERROR_BAD_ELEMENT`, `HYCON_ERROR_INVALID_ARGUMENT` (bad options), `HYCON_ERROR_SOLVER`.
///
/// # Safety
/// `out` must point to a writable pointer, `model` be a live handle, `options` NULL or
/// readable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_new(
    out: *mut *mut HyconContact,
    model: *const HyconModel,
    options: *const HyconContactOptions,
) -> HyconStatus {
    boundary("hycon_contact_new", || {
        // SAFETY: the caller's contract.
        let m = unsafe { handle(model, "model")? };
        let (opts, monitor) = unsafe { read_options(options)? };
        let mut analysis = match &m.plate {
            Some(plate) => {
                ContactAnalysis::with_plate(m.model.clone(), m.pairs.clone(), opts, plate.clone())?
            }
            None => ContactAnalysis::new(m.model.clone(), m.pairs.clone(), opts)?,
        };
        analysis.set_monitor(monitor);
        // SAFETY: the caller's contract on `out`.
        unsafe { hand_out(out, HyconContact { analysis }) }
    })
}

// ------------------------------------------------------------------------------------------
// Host-assembly API

/// Create a host description for a system of `n_equations` equations (the host's `K` after its
/// boundary conditions: symmetric positive definite).
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`out`), `HYCON_ERROR_INVALID_ARGUMENT` (`n_equations`
/// zero or beyond what memory can address).
///
/// # Safety
/// `out` must point to a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_host_new(
    out: *mut *mut HyconHost,
    n_equations: usize,
) -> HyconStatus {
    boundary("hycon_host_new", || {
        if n_equations == 0 || n_equations > isize::MAX as usize / 16 {
            return Err(Fail::invalid(format!(
                "n_equations = {n_equations} must be positive and addressable"
            )));
        }
        // SAFETY: the caller's contract on `out`.
        unsafe {
            hand_out(
                out,
                HyconHost {
                    equations: n_equations,
                    nodes: Vec::new(),
                    pairs: Vec::new(),
                    a_inside: Vec::new(),
                    sections: Vec::new(),
                    stiffness: None,
                    elements: None,
                },
            )
        }
    })
}

/// Free a host description (NULL is a no-op). Analyses made from it are independent of it.
///
/// # Safety
/// `host` must be NULL or a live handle from `hycon_host_new`, not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_host_free(host: *mut HyconHost) {
    // SAFETY: the caller's contract.
    unsafe { free_handle(host) }
}

/// Register host nodes (`side` names them in messages) into `known`: new nodes are added,
/// known ones must agree, and no two nodes share an equation. On an error `known` may hold
/// some of the new nodes: callers merge into a copy.
pub(super) fn merge_host_nodes(
    known: &mut Vec<HostNode>,
    nodes: &[HostNode],
    side: &str,
) -> Result<(), Fail> {
    for node in nodes {
        let id = node.id;
        match known.iter().find(|n| n.id == id) {
            Some(k) if k != node => {
                return Err(Fail::invalid(format!(
                    "{side} node {id} was given before with other coordinates or equations"
                )));
            }
            Some(_) => {}
            None => {
                if let Some(other) = known.iter().find(|n| {
                    n.equations
                        .given()
                        .any(|e| node.equations.given().any(|f| f == e))
                }) {
                    return Err(Fail::invalid(format!(
                        "{side} node {id} shares an equation with node {}",
                        other.id
                    )));
                }
                known.push(*node)
            }
        }
    }
    Ok(())
}

/// Add a contact pair in the host's numbering: the polylines `a` (the multiplier side) and `b`,
/// each a `HyconHostNodes` (node ids, reference coordinates, equation numbers with
/// `HYCON_FIXED` for a dof the host holds at zero), ordered with its body on the left. A node
/// in several pairs must be given the same coordinates and equations each time. `friction >= 0`
/// is the Coulomb coefficient. `analysis` and `thickness` are those of the A side's elements
/// (`HYCON_PLANE_STRAIN` or `HYCON_PLANE_STRESS` and its thickness `t`, or
/// `HYCON_AXISYMMETRIC` and 1): the contact integrals are weighted by A's surface measure,
/// `t ds` or `2 pi r ds` (the full circle), so the tractions are pressures (force per area)
/// and the contact forces are in the units of the host's stiffness (which carries `t`, or is
/// over the full circle). All pairs of a host share one analysis kind (plane strain and plane
/// stress are two kinds); their thicknesses may differ. Elements handed over
/// (`hycon_host_set_elements`, before or after this call) along a pair's A segments must be of
/// its kind and thickness. The pair's index is written to `index` unless it is NULL. The
/// arrays are copied; on an error the host is unchanged.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `a`, `b`, or an array of a view with `n > 0`),
/// `HYCON_ERROR_INVALID_ARGUMENT` (non-finite coordinates, equations out of range or shared,
/// fewer than 2 nodes, repeated nodes, a zero-length segment, a node given before differently,
/// a bad friction coefficient, an unknown analysis kind or one other than the host's earlier
/// pairs', a thickness that is not finite and positive (or not 1 in axisymmetry), in
/// axisymmetry a node of A or B at `r = x < 0` beyond round-off (1e-10 of its segments'
/// length), an element handed over on a segment of A whose material differs from `analysis`
/// or `thickness` (or any element of another kind), a misaligned pointer).
///
/// # Safety
/// `host` must be a live handle; `a`, `b` NULL or readable views whose arrays hold the stated
/// counts; `index` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_host_add_pair(
    host: *mut HyconHost,
    a: *const HyconHostNodes,
    b: *const HyconHostNodes,
    friction: f64,
    analysis: HyconAnalysis,
    thickness: f64,
    index: *mut usize,
) -> HyconStatus {
    boundary("hycon_host_add_pair", || {
        // SAFETY (all reads): the caller's contract.
        let h = unsafe { handle_mut(host, "host")? };
        let index = optional(index, "index")?;
        let kind =
            analysis_from_c(analysis).ok_or_else(|| Fail::invalid(unknown_analysis(analysis)))?;
        let section = Section::new(kind, thickness)?;
        let mut sections = h.sections.clone();
        sections.push(section);
        handover::check_sections(&sections, sections.len())?;
        let a = unsafe { read_host_nodes(a, "a", "A", h.equations)? };
        let b = unsafe { read_host_nodes(b, "b", "B", h.equations)? };
        let ids = |nodes: &[HostNode]| nodes.iter().map(|n| n.id).collect::<Vec<_>>();
        let pair = ContactPair {
            a: ids(&a),
            b: ids(&b),
            friction,
        };
        pair.check()?;
        for (nodes, side) in [(&a, "A"), (&b, "B")] {
            if let Some(w) = nodes.windows(2).find(|w| w[0].position == w[1].position) {
                return Err(Fail::invalid(format!(
                    "the {side} polyline is not a chain: segment {} -> {} has zero length",
                    w[0].id, w[1].id
                )));
            }
            let points: Vec<f64> = nodes
                .iter()
                .flat_map(|n| n.position.components().iter().copied())
                .collect();
            handover::check_radii(&section, side, &ids(nodes), &points)?;
        }
        let mut pairs = h.pairs.clone();
        pairs.push(pair);
        if let Some(elements) = &h.elements {
            handover::check_element_sections(elements, &pairs, &sections)?;
        }
        // all-or-nothing: merge into a copy
        let mut nodes = h.nodes.clone();
        merge_host_nodes(&mut nodes, &a, "A")?;
        merge_host_nodes(&mut nodes, &b, "B")?;
        h.nodes = nodes;
        h.pairs = pairs;
        h.a_inside.push(None);
        h.sections = sections;
        // SAFETY: the caller's contract on `index`.
        unsafe { put(index, h.pairs.len() - 1) };
        Ok(())
    })
}

/// Say which side body A of pair `pair` (an index from `hycon_host_add_pair`) is on: `inside`
/// is a point inside body A (2 doubles `x y`), beside its polyline rather than beyond its ends:
/// the centroid of the element that owns A's first segment, say. It must lie on A's body side
/// of the A polyline (its left), which confirms A's orientation; B's follows from facing A.
/// Replaces an earlier point of the pair.
///
/// Needed where the geometry cannot tell: when A and B touch (lie within half a segment of each
/// other) wherever they are near each other, facing surfaces and back-to-back ones (both
/// polylines reversed) look the same, and `hycon_contact_new_host` rejects such a pair without
/// it, unless the host gave its elements (`hycon_host_set_elements`) with one on a segment of
/// A (its centroid is then the point). Surfaces apart (or curved away from each
/// other around a contact) need none, and a point given is checked in any case.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `inside`), `HYCON_ERROR_INVALID_ARGUMENT` (an
/// unknown pair, a non-finite point, one beyond the ends of the A polyline, one on its outward
/// side: A reversed, and with B facing it the pair back to back). On an error the host is
/// unchanged.
///
/// # Safety
/// `host` must be a live handle; `inside` NULL or 2 readable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_host_set_pair_inside(
    host: *mut HyconHost,
    pair: usize,
    inside: *const f64,
) -> HyconStatus {
    boundary("hycon_host_set_pair_inside", || {
        // SAFETY (both): the caller's contract.
        let h = unsafe { handle_mut(host, "host")? };
        let p = unsafe { doubles(inside, 2, "inside")? };
        let point = [p[0], p[1]];
        let Some(ids) = h.pairs.get(pair).map(|p| p.a.clone()) else {
            return Err(Fail::invalid(format!(
                "pair {pair} is unknown (the host has {} pairs)",
                h.pairs.len()
            )));
        };
        let positions: Vec<[f64; 2]> = ids
            .iter()
            .filter_map(|&id| h.nodes.iter().find(|n| n.id == id))
            .map(|n| [n.position[0], n.position[1]])
            .collect();
        crate::contact::iteration::check_a_inside(&positions, point)
            .map_err(|e| Fail::invalid(format!("pair {pair}: {e}")))?;
        h.a_inside[pair] = Some(point.into());
        Ok(())
    })
}

/// Give the host's stiffness as a CSR matrix over its `n_equations` equations (copied):
/// `row_ptr` has `n_equations + 1` entries starting at 0, `columns` and `values` have
/// `row_ptr[n_equations]`; `triangle` says which part is stored (`HYCON_CSR_FULL`, checked
/// symmetric; `HYCON_CSR_LOWER`; `HYCON_CSR_UPPER`). hycon factors it once (faer, or the
/// options' backend) when the analysis starts. Replaces an earlier matrix or solver.
///
/// The columns of a row may come in any order, and an entry given more than once is summed
/// (as an assembly loop leaves it). A dof the host holds fixed is either left out of the
/// equations (`HYCON_FIXED` in `hycon_host_add_pair`) or kept as an identity row and column
/// (1 on the diagonal, 0 elsewhere and in the right-hand side): both work.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, an array with entries to read),
/// `HYCON_ERROR_INVALID_ARGUMENT` (an unknown `triangle`, `row_ptr` not starting at 0 or
/// decreasing, a column out of range, an entry in the wrong triangle, a non-finite value, a
/// full matrix that is not symmetric, a misaligned pointer). On an error the host is
/// unchanged.
///
/// # Safety
/// `host` must be a live handle; the arrays NULL or of the stated lengths.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_host_set_csr(
    host: *mut HyconHost,
    row_ptr: *const usize,
    columns: *const usize,
    values: *const f64,
    triangle: HyconTriangle,
) -> HyconStatus {
    boundary("hycon_host_set_csr", || {
        // SAFETY (all reads): the caller's contract.
        let h = unsafe { handle_mut(host, "host")? };
        let csr = unsafe { read_csr(h.equations, row_ptr, columns, values, triangle)? };
        h.stiffness = Some(HostSource::Csr(csr));
        Ok(())
    })
}

/// A host's CSR matrix of order `n` from its arrays (copied), its structure checked
/// ([`Csr::lower`]), so that errors come from the call that gives it.
///
/// # Safety
/// The arrays NULL or of the lengths `row_ptr` states.
pub(super) unsafe fn read_csr(
    n: usize,
    row_ptr: *const usize,
    columns: *const usize,
    values: *const f64,
    triangle: HyconTriangle,
) -> Result<Csr, Fail> {
    let triangle = match triangle {
        HYCON_CSR_FULL => Triangle::Full,
        HYCON_CSR_LOWER => Triangle::Lower,
        HYCON_CSR_UPPER => Triangle::Upper,
        t => {
            return Err(Fail::invalid(format!(
                "triangle = {t} (expected HYCON_CSR_FULL = 1, HYCON_CSR_LOWER = 2 or \
                 HYCON_CSR_UPPER = 3)"
            )));
        }
    };
    // SAFETY (all reads): forwarded contract.
    let ptr = unsafe { slice(row_ptr, length(n, 1, 1, "n_equations")?, "row_ptr")? };
    let nnz = ptr[n];
    let cols = unsafe { slice(columns, nnz, "columns")? };
    let vals = unsafe { doubles(values, nnz, "values")? };
    let csr = Csr {
        n,
        row_ptr: ptr.to_vec(),
        columns: cols.to_vec(),
        values: vals.to_vec(),
        triangle,
    };
    csr.lower()?;
    Ok(csr)
}

/// Let the host solve with its own factorization: `solve(user_data, n, nrhs, rhs, x)` (see
/// `HyconSolveFn`). The function pointer and `user_data` are kept by this description and by
/// every analysis made from it, and called during `hycon_contact_new_host`, the increments and
/// displacement recovery; `user_data` (the host's factor) must outlive them. Replaces an
/// earlier matrix or solver. This is the path for distributed hosts (e.g. PETSc over MPI): hycon
/// only ever asks for solves and works on the contact dofs, which every rank can hold.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `solve`).
///
/// # Safety
/// `host` must be a live handle; `solve` a valid function as documented.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_host_set_solver(
    host: *mut HyconHost,
    solve: HyconSolveFn,
    user_data: *mut c_void,
) -> HyconStatus {
    boundary("hycon_host_set_solver", || {
        // SAFETY: the caller's contract.
        let h = unsafe { handle_mut(host, "host")? };
        h.stiffness = Some(HostSource::callback(solve, user_data)?);
        Ok(())
    })
}

/// Hand over the host's condensed operator over its contact candidate equations (copied):
/// the stiffness Schur complement or the flexibility block (`HyconCondensed`), computed by the
/// host's own solver in one factorization. hycon runs every increment on it alone, with no
/// solve inside an increment: `hycon_contact_increment` then takes as `load` the **load
/// image**, `u0 = K^-1 rhs` at the `m` candidate equations in their order (`load_len = m`;
/// the host's solve of its total right-hand side), and after an increment the host recovers
/// its displacement with one solve of its own, `K u = rhs + forces` with
/// `hycon_contact_forces` (`hycon_contact_displacement`, `hycon_contact_displacement_increment`
/// and `hycon_contact_stress_tractions` fail: hycon has no solver of `K`, their size queries
/// answer as on the other paths).
/// `hycon_host_contact_equations` lists the equations the candidates must hold. Replaces an
/// earlier matrix or solver. Checked here: `size`, the kind, `m > 0`, candidates in range and
/// distinct, finite values, symmetry; at `hycon_contact_new_host`: every contact equation
/// among the candidates, a Schur complement positive definite (`HYCON_ERROR_SINGULAR`).
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `condensed`, its arrays),
/// `HYCON_ERROR_INVALID_ARGUMENT` (the checks above, a misaligned pointer). On an error the
/// host is unchanged.
///
/// # Safety
/// `host` must be a live handle; `condensed` NULL or a readable `HyconCondensed` whose arrays
/// hold the stated counts.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_host_set_condensed(
    host: *mut HyconHost,
    condensed: *const HyconCondensed,
) -> HyconStatus {
    boundary("hycon_host_set_condensed", || {
        // SAFETY (all reads): the caller's contract.
        let h = unsafe { handle_mut(host, "host")? };
        let condensed = unsafe { read_condensed(condensed, h.equations)? };
        h.stiffness = Some(HostSource::Condensed(condensed));
        Ok(())
    })
}

/// A host's condensed operator from its view (copied) for a system of `n_equations`
/// equations, checked ([`Condensed::check`]).
///
/// # Safety
/// `condensed` NULL or a readable `HyconCondensed` whose arrays hold the stated counts.
pub(super) unsafe fn read_condensed(
    condensed: *const HyconCondensed,
    n_equations: usize,
) -> Result<Condensed, Fail> {
    check_pointer(condensed, "condensed")?;
    // SAFETY: non-null and aligned (checked); the struct begins with its size
    let size = unsafe { condensed.cast::<usize>().read() };
    let known = std::mem::size_of::<HyconCondensed>();
    if !(CONDENSED_FIRST_BLOCK..=known).contains(&size) {
        return Err(Fail::invalid(format!(
            "condensed.size = {size}: expected sizeof(HyconCondensed) = {known}"
        )));
    }
    // SAFETY (all reads): forwarded contract.
    let c = unsafe { handle(condensed, "condensed")? };
    let kind = match c.kind {
        HYCON_CONDENSED_STIFFNESS => CondensedKind::Stiffness,
        HYCON_CONDENSED_FLEXIBILITY => CondensedKind::Flexibility,
        k => {
            return Err(Fail::invalid(format!(
                "condensed.kind = {k} is unknown (HYCON_CONDENSED_STIFFNESS = 1, \
                 HYCON_CONDENSED_FLEXIBILITY = 2)"
            )));
        }
    };
    let m = c.m;
    let values = length(m, m, 0, "condensed.m")?;
    let equations = unsafe { slice(c.equations, m, "condensed.equations")? };
    let matrix = unsafe { slice(c.matrix, values, "condensed.matrix")? };
    let equations = equations
        .iter()
        .map(|&e| {
            usize::try_from(e)
                .map_err(|_| Fail::invalid(format!("candidate equation {e} is out of range")))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let condensed = Condensed {
        kind,
        equations,
        matrix: matrix.to_vec(),
    };
    condensed.check(n_equations)?;
    Ok(condensed)
}

/// The host's contact equations: every equation of a node of its pairs (not `HYCON_FIXED`),
/// in the order the nodes were first given (`u_x`, then `u_y`), each once: what the
/// candidates of `hycon_host_set_condensed` must hold (as an index set for a Schur
/// complement, or the columns of a batched solve).
///
/// Sizes and errors follow the header's size convention (`out`, `len`, `needed`).
///
/// # Safety
/// `host` must be a live handle; `out` NULL or `len` writable values; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_host_contact_equations(
    host: *const HyconHost,
    out: *mut i64,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_host_contact_equations", || {
        // SAFETY (all): the caller's contract.
        let h = unsafe { handle(host, "host")? };
        unsafe { contact_equations(&h.nodes, out, len, needed) }
    })
}

/// Write the equations of host `nodes` (not `HYCON_FIXED`), in node order, by the size
/// convention.
///
/// # Safety
/// `out` NULL or `len` writable values; `needed` NULL or writable.
pub(super) unsafe fn contact_equations(
    nodes: &[HostNode],
    out: *mut i64,
    len: usize,
    needed: *mut usize,
) -> Result<(), Fail> {
    let equations: Vec<i64> = (nodes.iter())
        .flat_map(|n| n.equations.given())
        .map(|e| e as i64)
        .collect();
    // SAFETY: forwarded contract.
    unsafe { fill(out, len, needed, "out", equations.len(), || Ok(equations)) }
}

/// Optionally hand over the elements of body A along the A polylines (at least those owning an
/// A segment), so that `hycon_contact_stress_tractions` can recover the tractions from their
/// stresses (the paper's way (a)) from the host's displacements. The same order as
/// `hycon_model_new`: nodes, elements, materials. `nodes` is the node table of every node the
/// elements use (ids, reference coordinates, equations with `HYCON_FIXED` for a held dof);
/// `elements` the elements (hycon formulations, counter-clockwise, node ids of the host's
/// numbering); `materials` the `n_materials` materials the elements' indices refer to. Every
/// material the elements use is of the pairs' analysis kind, and an element on a segment of a
/// pair's A polyline has that pair's kind and thickness (`hycon_host_add_pair`; pairs added
/// later are checked against these elements there): the stresses would otherwise be of
/// another analysis, silently wrong. Copied; replaces earlier elements; on an error the host
/// is unchanged.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, a view, an array of a view with a nonzero count,
/// `materials`), `HYCON_ERROR_INVALID_ARGUMENT` (counts, unknown ids, equations, non-finite
/// coordinates, misaligned pointers, a material of another kind than the pairs', an element
/// along A of another kind or thickness than its pair), `HYCON_ERROR_INVALID_MATERIAL`,
/// `HYCON_ERROR_BAD_ELEMENT`.
///
/// # Safety
/// `host` must be a live handle; `nodes` and `elements` NULL or readable views whose arrays
/// hold the stated counts; `materials` NULL or `n_materials` readable structs.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_host_set_elements(
    host: *mut HyconHost,
    nodes: *const HyconHostNodes,
    elements: *const HyconElementBlock,
    materials: *const HyconMaterial,
    n_materials: usize,
) -> HyconStatus {
    boundary("hycon_host_set_elements", || {
        // SAFETY (all reads): the caller's contract.
        let h = unsafe { handle_mut(host, "host")? };
        let node_table = unsafe { read_host_nodes(nodes, "nodes", "element", h.equations)? };
        if node_table.is_empty() {
            return Err(Fail::invalid("elements need nodes (nodes.n = 0)"));
        }
        let elements = unsafe { read_block(elements, "elements", materials, n_materials)? };
        let elements = HostElements {
            formulation: elements.formulation,
            materials: elements.materials,
            element_material: elements.element_material,
            offsets: elements.offsets,
            nodes: elements.nodes,
            node_table,
        };
        // check now (shapes, ids), so that errors come from this call
        crate::contact::bodies::check_elements(&elements, h.equations)?;
        handover::check_element_sections(&elements, &h.pairs, &h.sections)?;
        h.elements = Some(elements);
        Ok(())
    })
}

/// Start a contact analysis of a host's system: factor its CSR matrix once (the contact
/// equations last) and read the flexibility off the factor, build the flexibility from
/// batched solves through its callback, or read it off its condensed operator. `options`
/// NULL means the defaults. The checks of `hycon_host_add_pair` and `hycon_host_set_elements`
/// (sections, radii, elements along A) hold already, as they were made there.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`out`, `host`), `HYCON_ERROR_INVALID_ARGUMENT` (no
/// pair, no stiffness, solver or condensed operator given, a pair whose polylines run the same
/// way or lie back to back, a pair whose surfaces touch wherever they are near each other
/// without `hycon_host_set_pair_inside`, a contact equation that is no candidate of the
/// condensed operator, bad options), `HYCON_ERROR_SINGULAR` (the CSR matrix or the condensed
/// Schur complement is not positive definite: a body not held), `HYCON_ERROR_SOLVER` (the
/// factorization failed otherwise, or the options' backend is not built in),
/// `HYCON_ERROR_CALLBACK` (the solver failed or returned non-finite values).
///
/// # Safety
/// `out` must point to a writable pointer, `host` be a live handle, `options` NULL or
/// readable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_new_host(
    out: *mut *mut HyconContact,
    host: *const HyconHost,
    options: *const HyconContactOptions,
) -> HyconStatus {
    boundary("hycon_contact_new_host", || {
        // SAFETY: the caller's contract.
        let h = unsafe { handle(host, "host")? };
        let (opts, monitor) = unsafe { read_options(options)? };
        if h.pairs.is_empty() {
            return Err(Fail::invalid(
                "the host has no contact pair (hycon_host_add_pair)",
            ));
        }
        let stiffness = HostSource::stiffness(h.stiffness.as_ref(), "hycon_host")?;
        let system = HostSystem {
            equations: h.equations,
            nodes: h.nodes.clone(),
            stiffness,
            elements: h.elements.clone(),
            a_inside: h.a_inside.clone(),
            sections: h.sections.clone(),
        };
        let mut analysis = ContactAnalysis::host(system, h.pairs.clone(), opts)?;
        analysis.set_monitor(monitor);
        // SAFETY: the caller's contract on `out`.
        unsafe { hand_out(out, HyconContact { analysis }) }
    })
}

// ------------------------------------------------------------------------------------------
// Analysis

/// Free an analysis (NULL is a no-op).
///
/// # Safety
/// `contact` must be NULL or a live handle, not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_free(contact: *mut HyconContact) {
    // SAFETY: the caller's contract.
    unsafe { free_handle(contact) }
}

/// The two components of a plane vector, as the C structs hold them.
fn plane(v: crate::contact::space::Vector) -> [f64; 2] {
    [v[0], v[1]]
}

pub(super) fn info_to_c(i: crate::contact::iteration::IncrementInfo) -> HyconIncrementInfo {
    HyconIncrementInfo {
        increment: i.increment,
        iterations: i.iterations,
        active: i.active,
        slip: i.slip,
        sub_increments: i.sub_increments,
        cutbacks: i.cutbacks,
    }
}

/// Apply one load increment with **total** values (from the reference state):
/// * model API: `load` = external nodal forces over all `2 * n_nodes` dofs (`u0 v0 u1 v1 ...`),
///   `prescribed` = values at the prescribed dofs over the same `2 * n_nodes` entries (the
///   others are ignored, whatever they hold: NaN there is fine);
/// * host API: `load` = the host's right-hand side over its equations (including the effect of
///   its prescribed displacements), `prescribed` = (NULL, 0);
/// * host API with a condensed operator (`hycon_host_set_condensed`): `load` = the load image
///   `u0 = K^-1 rhs` at the candidate equations, in their order (`load_len = m`),
///   `prescribed` = (NULL, 0).
///
/// `load_len` is the field length, which the size query of the displacement gives:
/// `hycon_contact_displacement(contact, NULL, 0, &load_len)`; on the condensed path it is
/// instead the candidate count `m` the host handed over (`HyconCondensed::m`), and that size
/// query gives the host's equation count (the length of `hycon_contact_forces`).
///
/// An increment that fails for an iteration reason is taken again in sub-increments (the
/// automatic cutback, `HyconContactOptions::cutback_depth`); it is still one increment, and
/// `info->sub_increments` says how many it took. On success the converged state advances and
/// `info` (unless NULL) gets the summary. On failure (beyond the cutback's limit) the analysis
/// is exactly as before the call and the status says why: `HYCON_ERROR_CONTACT` (no
/// convergence, cycling contact set with the node named, a surface pushed through the other or
/// beyond what the pairing sees, at any depth, including a motion so large that double
/// precision no longer resolves the surfaces, contact reaching the end of a surface),
/// `HYCON_ERROR_SINGULAR` (a body held only by frictionless contact), `HYCON_ERROR_CALLBACK`
/// (solver or monitor),
/// `HYCON_ERROR_INVALID_ARGUMENT` (lengths, non-finite values or values beyond 1e300 in
/// magnitude, where the load plus the contact forces or the stresses may overflow: choose other
/// units; a plate analysis).
///
/// # Safety
/// `contact` must be a live handle; arrays NULL or of the stated lengths; `info` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_increment(
    contact: *mut HyconContact,
    load: *const f64,
    load_len: usize,
    prescribed: *const f64,
    prescribed_len: usize,
    info: *mut HyconIncrementInfo,
) -> HyconStatus {
    boundary("hycon_contact_increment", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle_mut(contact, "contact")? };
        unsafe {
            increment(
                &mut c.analysis,
                load,
                load_len,
                prescribed,
                prescribed_len,
                info,
            )
        }
    })
}

/// As `hycon_contact_increment` for a model with a plate (`hycon_model_set_plate`): `control`
/// and `value` (2 entries each, x then y) drive the plate's translations
/// (`HYCON_PLATE_DISPLACEMENT`: total displacement; `HYCON_PLATE_FORCE`: total force on the
/// plate, its motion solved for).
///
/// # Safety
/// As `hycon_contact_increment`; `control` and `value` must hold 2 values each.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn hycon_contact_increment_with_plate(
    contact: *mut HyconContact,
    load: *const f64,
    load_len: usize,
    prescribed: *const f64,
    prescribed_len: usize,
    control: *const HyconPlateControl,
    value: *const f64,
    info: *mut HyconIncrementInfo,
) -> HyconStatus {
    boundary("hycon_contact_increment_with_plate", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle_mut(contact, "contact")? };
        unsafe {
            increment_with_plate(
                &mut c.analysis,
                (load, load_len),
                (prescribed, prescribed_len),
                (control, value, 2),
                info,
            )
        }
    })
}

/// The converged plate displacement and the force the plate exerts on the body (2 values each,
/// x then y).
///
/// # Safety
/// `contact` must be a live handle; `displacement` and `force` must hold 2 writable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_plate(
    contact: *const HyconContact,
    displacement: *mut f64,
    force: *mut f64,
) -> HyconStatus {
    boundary("hycon_contact_plate", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { plate(&c.analysis, displacement, force) }
    })
}

/// The displacement of the last converged increment (total, from the reference state; zero
/// before the first) over the field: all `2 * n_nodes` dofs of a model (`u0 v0 u1 v1 ...`), the
/// host's `n_equations` equations. The size query `(NULL, 0, &needed)` gives that length, which
/// is also the `load_len` of `hycon_contact_increment` (except on the condensed path, whose
/// `load_len` is the candidate count `m`). The first call after an increment recovers the
/// field (one solve; a host's solve callback is called), later calls copy it.
///
/// A host that handed over its condensed operator (`hycon_host_set_condensed`) recovers its
/// displacement itself (`K u = rhs + hycon_contact_forces`): hycon has no solver of its `K`,
/// so there the size query still gives `n_equations` but a call with `out` fails with
/// `HYCON_ERROR_INVALID_ARGUMENT` (saying so), before the first increment too.
///
/// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
/// `HYCON_ERROR_INVALID_ARGUMENT` on the condensed path, `HYCON_ERROR_CALLBACK` when a host's
/// solve fails or returns non-finite values, `HYCON_ERROR_SOLVER` when hycon's solve fails.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable doubles; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_displacement(
    contact: *const HyconContact,
    out: *mut f64,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_displacement", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { displacement(&c.analysis, out, len, needed) }
    })
}

/// The displacement increment of the last converged increment (its total displacement minus
/// the previous increment's; the total at the first; zero before the first), same layout and
/// length as `hycon_contact_displacement`. One solve per call (not for the size query).
///
/// On the condensed path (`hycon_host_set_condensed`) as `hycon_contact_displacement`: the
/// size query gives `n_equations`, a call with `out` after an increment fails with
/// `HYCON_ERROR_INVALID_ARGUMENT` (hycon has no solver of `K`; the host solves
/// `K du = rhs - rhs_previous + forces - forces_previous` itself).
///
/// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
/// `HYCON_ERROR_INVALID_ARGUMENT` on the condensed path, `HYCON_ERROR_CALLBACK` when a host's
/// solve fails or returns non-finite values, `HYCON_ERROR_SOLVER` when hycon's solve fails.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable doubles; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_displacement_increment(
    contact: *const HyconContact,
    out: *mut f64,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_displacement_increment", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { displacement_increment(&c.analysis, out, len, needed) }
    })
}

/// The contact forces of the last converged increment over the field (zero at a host's fixed
/// dofs; same length as `hycon_contact_displacement`): adding them to the load gives the
/// right-hand side whose solution is the displacement (`K u = load + forces`), for hosts that
/// recover displacements and stresses themselves. Rust: `ContactAnalysis::contact_forces`.
///
/// Sizes and errors follow the header's size convention (`out`, `len`, `needed`).
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable doubles; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_forces(
    contact: *const HyconContact,
    out: *mut f64,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_forces", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { forces(&c.analysis, out, len, needed) }
    })
}

/// Tractions way (b), the multipliers: converged results at the A nodes of `pair` (states,
/// `tn`, `ts`, frames, gaps, nodal forces), one per A node in polyline order: the size query
/// gives the A node count.
///
/// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
/// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_node_results(
    contact: *const HyconContact,
    pair: usize,
    out: *mut HyconNodeResult,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_node_results", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        let (n_a, _) = c.analysis.pair_size(pair)?;
        let results = || -> Result<Vec<HyconNodeResult>, Fail> {
            Ok(c.analysis
                .node_results(pair)?
                .iter()
                .map(|r| {
                    let (state, slip_sign) = match r.state {
                        NodeState::Open => (HYCON_NODE_OPEN, 0),
                        NodeState::Stick => (HYCON_NODE_STICK, 0),
                        NodeState::Slip { direction } => {
                            (HYCON_NODE_SLIP, i32::from(direction.sign().unwrap_or(1)))
                        }
                        NodeState::Frictionless => (HYCON_NODE_FRICTIONLESS, 0),
                    };
                    HyconNodeResult {
                        node: r.node,
                        state,
                        slip_sign,
                        tn: r.tn,
                        // the plane's one tangent, as `tangent` below
                        ts: r.ts.components()[0],
                        normal: plane(r.frame.normal()),
                        tangent: plane(r.frame.tangent(0)),
                        position: plane(r.position),
                        weight: r.weight,
                        gap: r.gap,
                        force: plane(r.force),
                    }
                })
                .collect())
        };
        unsafe { fill(out, len, needed, "out", n_a, results) }
    })
}

/// Tractions way (c), the B side: nodal forces, weights and pressures at the B nodes of `pair`,
/// one per B node in polyline order: the size query gives the B node count.
///
/// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
/// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_b_node_results(
    contact: *const HyconContact,
    pair: usize,
    out: *mut HyconBNodeResult,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_b_node_results", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        let (_, n_b) = c.analysis.pair_size(pair)?;
        let results = || -> Result<Vec<HyconBNodeResult>, Fail> {
            Ok(c.analysis
                .b_node_results(pair)?
                .iter()
                .map(|r| HyconBNodeResult {
                    node: r.node,
                    weight: r.weight,
                    force: plane(r.force),
                    pressure: r.pressure,
                    position: plane(r.position),
                })
                .collect())
        };
        unsafe { fill(out, len, needed, "out", n_b, results) }
    })
}

/// Tractions way (a), from the element stresses of body A: `tn ts` per A node of `pair` in its
/// nodal frame, `2 * n_a` doubles (the size query gives `2 * n_a` on every path). Model API;
/// host API when the host handed over the elements along A (`hycon_host_set_elements`) and
/// its stiffness as a CSR matrix or a solver: the stresses come from the displacement, which
/// costs its recovery (one solve) if not done yet. A host that handed over its condensed
/// operator instead recovers the displacement itself, so hycon has none to take the stresses
/// of: there a call with `out` fails with `HYCON_ERROR_INVALID_ARGUMENT` (the message says
/// so); the multipliers (`hycon_contact_node_results`) are the tractions on that path.
///
/// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
/// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range, no elements handed over, the
/// condensed path, an A node or segment that is no node or edge of the elements handed over,
/// `HYCON_ERROR_SOLVER` when the displacement or the stresses overflow (never non-finite
/// values), `HYCON_ERROR_CALLBACK` when a host's solve fails.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable doubles; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_stress_tractions(
    contact: *const HyconContact,
    pair: usize,
    out: *mut f64,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_stress_tractions", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        let (n_a, _) = c.analysis.pair_size(pair)?;
        let tractions = || -> Result<Vec<f64>, Fail> {
            Ok(c.analysis
                .stress_tractions(pair)?
                .iter()
                .flat_map(|&(tn, ts)| [tn, ts])
                .collect())
        };
        unsafe { fill(out, len, needed, "out", 2 * n_a, tractions) }
    })
}

/// The iteration records from number `first` on (0-based; all increments in order, failed ones
/// excluded): the full result has `count - first` records, `count` the number so far, so the
/// size query with `first = 0` gives the count and a monitor-free host can fetch only the new
/// records of each increment. `first` may equal the count (nothing to copy).
///
/// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
/// `HYCON_ERROR_INVALID_ARGUMENT` when `first` exceeds the count.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_records(
    contact: *const HyconContact,
    first: usize,
    out: *mut HyconIterationRecord,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_records", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { records(&c.analysis, first, out, len, needed) }
    })
}

/// Where the time went so far, and the number of numeric factorizations of `K` done by hycon
/// (1 per analysis; 0 when a host solves itself); either output may be NULL.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` (`contact`), `HYCON_ERROR_INVALID_ARGUMENT` (a misaligned
/// output).
///
/// # Safety
/// `contact` must be a live handle; outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_timings(
    contact: *const HyconContact,
    timings: *mut HyconTimings,
    factorizations: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_timings", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { timings_of(&c.analysis, timings, factorizations) }
    })
}

/// Contact-element quantities of the A nodes of `pair` in the converged configuration (the
/// reference one before the first increment): weights, frames, weighted gaps `R_C`, coverage;
/// one per A node (the size query gives the A node count). Rust:
/// `ContactAnalysis::surface(pair).nodes`.
///
/// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
/// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_surface_nodes(
    contact: *const HyconContact,
    pair: usize,
    out: *mut HyconContactNode,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_surface_nodes", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        let nodes: Vec<HyconContactNode> = c
            .analysis
            .surface(pair)?
            .nodes
            .iter()
            .map(|n| HyconContactNode {
                node: n.node,
                weight: n.weight,
                coverage: n.coverage,
                normal: plane(n.frame.normal()),
                tangent: plane(n.frame.tangent(0)),
                gap: plane(n.gap),
                normal_gap: n.normal_gap,
            })
            .collect();
        unsafe { fill(out, len, needed, "out", nodes.len(), || Ok(nodes)) }
    })
}

/// The contact-element matrices `F^A` and `F^B` of `pair` (converged configuration) as a list
/// of entries (row `k`, node `j`, side, value), rows in A node order. Rust:
/// `ContactAnalysis::surface(pair)`, the `coupling` of each node.
///
/// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
/// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_surface_coupling(
    contact: *const HyconContact,
    pair: usize,
    out: *mut HyconCouplingEntry,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_surface_coupling", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { surface_coupling(&c.analysis, pair, out, len, needed) }
    })
}

/// The constraint matrix `Kc` of `pair` (converged configuration) as a list of entries
/// (`HyconConstraintEntry`: row, column, value). It has `2 n_a` rows: row `2k` the normal
/// constraint `n_k . (sum_j F^A_kj u_j - sum_j F^B_kj u_j)` and row `2k + 1` the tangential one
/// with `s_k`; columns are field indices (model dofs `2 node + direction`, or host equations;
/// a host's fixed dofs are left out). The entries are in row-major order, rows ascending and
/// columns strictly ascending within a row, so they are CSR-ready: `columns[i] = out[i].column`,
/// `values[i] = out[i].value`, and `row_ptr[r + 1]` counts the entries with `row <= r`. The
/// mixed system of a host that assembles it itself reads `[K  -Kc^T; -Kc  0] [u; t] = [f; -g]`
/// with the active rows. Rust: `ContactAnalysis::constraint_rows`.
///
/// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
/// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_constraint_rows(
    contact: *const HyconContact,
    pair: usize,
    out: *mut HyconConstraintEntry,
    len: usize,
    needed: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_constraint_rows", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { constraint_rows(&c.analysis, pair, out, len, needed) }
    })
}

// ------------------------------------------------------------------------------------------
// The bodies of the exports whose meaning does not depend on the dimension: the plane's
// `hycon_contact_*` above and the solid's `hycon_solid_contact_*` (`solid_contact`) both wrap a
// `ContactAnalysis` and call these (arguments, errors and safety as those exports state).

/// One increment with total values (`hycon_contact_increment`).
///
/// # Safety
/// `load` and `prescribed` NULL or of the stated lengths; `info` NULL or writable.
pub(super) unsafe fn increment(
    analysis: &mut ContactAnalysis,
    load: *const f64,
    load_len: usize,
    prescribed: *const f64,
    prescribed_len: usize,
    info: *mut HyconIncrementInfo,
) -> Result<(), Fail> {
    let info = optional(info, "info")?;
    // SAFETY (all): the caller's contract.
    let f = unsafe { slice(load, load_len, "load")? };
    let qp = unsafe { slice(prescribed, prescribed_len, "prescribed")? };
    let done = analysis.increment(f, qp)?;
    unsafe { put(info, info_to_c(done)) };
    Ok(())
}

/// One increment with the plate driven per direction (`hycon_contact_increment_with_plate`,
/// `hycon_solid_contact_increment_with_plate`): `control` and `value` hold one entry per
/// direction, `dim` of them (2 in the plane, 3 in 3D).
///
/// # Safety
/// Arrays NULL or of the stated lengths (`control` and `value` `dim` entries); `info` NULL or
/// writable.
pub(super) unsafe fn increment_with_plate(
    analysis: &mut ContactAnalysis,
    (load, load_len): (*const f64, usize),
    (prescribed, prescribed_len): (*const f64, usize),
    (control, value, dim): (*const HyconPlateControl, *const f64, usize),
    info: *mut HyconIncrementInfo,
) -> Result<(), Fail> {
    let info = optional(info, "info")?;
    // SAFETY (all): the caller's contract.
    let f = unsafe { slice(load, load_len, "load")? };
    let qp = unsafe { slice(prescribed, prescribed_len, "prescribed")? };
    let kinds = unsafe { slice(control, dim, "control")? };
    let values = unsafe { doubles(value, dim, "value")? };
    let plate = (kinds.iter().zip(values).enumerate())
        .map(|(d, (&kind, &v))| match kind {
            HYCON_PLATE_DISPLACEMENT => Ok(PlateControl::Displacement(v)),
            HYCON_PLATE_FORCE => Ok(PlateControl::Force(v)),
            k => Err(Fail::invalid(format!(
                "control[{d}] = {k} (expected HYCON_PLATE_DISPLACEMENT = 1 or \
                 HYCON_PLATE_FORCE = 2)"
            ))),
        })
        .collect::<Result<Vec<_>, _>>()?;
    let done = analysis.increment_with_plate(f, qp, &plate)?;
    unsafe { put(info, info_to_c(done)) };
    Ok(())
}

/// The converged plate displacement and force, one value per direction each
/// (`hycon_contact_plate`, `hycon_solid_contact_plate`).
///
/// # Safety
/// `displacement` and `force` writable for one double per direction of the analysis.
pub(super) unsafe fn plate(
    analysis: &ContactAnalysis,
    displacement: *mut f64,
    force: *mut f64,
) -> Result<(), Fail> {
    let Some((u, f)) = analysis.plate() else {
        return Err(Fail::invalid("this analysis has no plate"));
    };
    check_pointer(displacement.cast_const(), "displacement")?;
    check_pointer(force.cast_const(), "force")?;
    // SAFETY: both checked non-null and aligned, writable for one double per direction
    // (contract).
    unsafe {
        write_doubles(displacement, u.components());
        write_doubles(force, f.components());
    }
    Ok(())
}

/// The converged displacement over the field (`hycon_contact_displacement`).
///
/// # Safety
/// `out` NULL or `len` writable doubles; `needed` NULL or writable.
pub(super) unsafe fn displacement(
    analysis: &ContactAnalysis,
    out: *mut f64,
    len: usize,
    needed: *mut usize,
) -> Result<(), Fail> {
    let count = analysis.field_len();
    // SAFETY: the caller's contract.
    unsafe {
        fill(out, len, needed, "out", count, || {
            Ok(analysis.displacement()?.to_vec())
        })
    }
}

/// The last converged increment's displacement increment
/// (`hycon_contact_displacement_increment`).
///
/// # Safety
/// As [`displacement`].
pub(super) unsafe fn displacement_increment(
    analysis: &ContactAnalysis,
    out: *mut f64,
    len: usize,
    needed: *mut usize,
) -> Result<(), Fail> {
    let count = analysis.field_len();
    // SAFETY: the caller's contract.
    unsafe {
        fill(out, len, needed, "out", count, || {
            Ok(analysis.displacement_increment()?)
        })
    }
}

/// The converged contact forces over the field (`hycon_contact_forces`).
///
/// # Safety
/// As [`displacement`].
pub(super) unsafe fn forces(
    analysis: &ContactAnalysis,
    out: *mut f64,
    len: usize,
    needed: *mut usize,
) -> Result<(), Fail> {
    let count = analysis.field_len();
    // SAFETY: the caller's contract.
    unsafe {
        fill(out, len, needed, "out", count, || {
            Ok(analysis.contact_forces())
        })
    }
}

/// The iteration records from `first` on (`hycon_contact_records`).
///
/// # Safety
/// `out` NULL or `len` writable records; `needed` NULL or writable.
pub(super) unsafe fn records(
    analysis: &ContactAnalysis,
    first: usize,
    out: *mut HyconIterationRecord,
    len: usize,
    needed: *mut usize,
) -> Result<(), Fail> {
    let all = analysis.records();
    let Some(records) = all.get(first..) else {
        return Err(Fail::invalid(format!(
            "first = {first}, but {} records exist",
            all.len()
        )));
    };
    // SAFETY: the caller's contract.
    unsafe {
        fill(out, len, needed, "out", records.len(), || {
            Ok(records.iter().map(record_to_c).collect())
        })
    }
}

/// The timings and the factorization count (`hycon_contact_timings`).
///
/// # Safety
/// Outputs NULL or writable.
pub(super) unsafe fn timings_of(
    analysis: &ContactAnalysis,
    timings: *mut HyconTimings,
    factorizations: *mut usize,
) -> Result<(), Fail> {
    let timings = optional(timings, "timings")?;
    let factorizations = optional(factorizations, "factorizations")?;
    let t = analysis.timings();
    let out = HyconTimings {
        assembly: t.assembly,
        factorization: t.factorization,
        flexibility: t.flexibility,
        load_solves: t.load_solves,
        iterations: t.iterations,
        recovery: t.recovery,
    };
    // SAFETY: both checked by `optional`, writable (contract).
    unsafe {
        put(timings, out);
        put(factorizations, analysis.factorizations());
    }
    Ok(())
}

/// The entries of `F^A` and `F^B` of `pair` (`hycon_contact_surface_coupling`).
///
/// # Safety
/// `out` NULL or `len` writable entries; `needed` NULL or writable.
pub(super) unsafe fn surface_coupling(
    analysis: &ContactAnalysis,
    pair: usize,
    out: *mut HyconCouplingEntry,
    len: usize,
    needed: *mut usize,
) -> Result<(), Fail> {
    let surface = analysis.surface(pair)?;
    let a_ids: std::collections::HashSet<usize> = surface.nodes.iter().map(|n| n.node).collect();
    let entries: Vec<HyconCouplingEntry> = surface
        .nodes
        .iter()
        .enumerate()
        .flat_map(|(k, n)| {
            let a_ids = &a_ids;
            n.coupling.iter().map(move |&(j, v)| {
                let side = if a_ids.contains(&j) {
                    HYCON_SIDE_A
                } else {
                    HYCON_SIDE_B
                };
                HyconCouplingEntry {
                    row: k,
                    node: j,
                    side,
                    value: if side == HYCON_SIDE_A { v } else { -v },
                }
            })
        })
        .collect();
    // SAFETY: the caller's contract.
    unsafe { fill(out, len, needed, "out", entries.len(), || Ok(entries)) }
}

/// The constraint matrix `Kc` of `pair` as row-major entries
/// (`hycon_contact_constraint_rows`).
///
/// # Safety
/// `out` NULL or `len` writable entries; `needed` NULL or writable.
pub(super) unsafe fn constraint_rows(
    analysis: &ContactAnalysis,
    pair: usize,
    out: *mut HyconConstraintEntry,
    len: usize,
    needed: *mut usize,
) -> Result<(), Fail> {
    let rows = analysis.constraint_rows(pair)?;
    let mut entries = Vec::with_capacity(rows.columns.len());
    for (row, range) in rows.row_ptr.windows(2).enumerate() {
        let mut row_entries: Vec<(usize, f64)> = (range[0]..range[1])
            .map(|i| (rows.columns[i], rows.values[i]))
            .collect();
        row_entries.sort_by_key(|e| e.0);
        for (column, value) in row_entries {
            match entries.last_mut() {
                Some(HyconConstraintEntry {
                    row: r,
                    column: col,
                    value: v,
                }) if *r == row && *col == column => *v += value,
                _ => entries.push(HyconConstraintEntry { row, column, value }),
            }
        }
    }
    // SAFETY: the caller's contract.
    unsafe { fill(out, len, needed, "out", entries.len(), || Ok(entries)) }
}
