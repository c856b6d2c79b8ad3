//! The contact routines of the C ABI: two ways in, one analysis handle.
//!
//! * **Model API**: the host describes nodes, elements, materials, prescribed directions, contact
//!   pairs and an optional rigid plate in a [`HyconModel`]; hycon assembles, factors and runs
//!   the increments.
//! * **Host-assembly API**: the host keeps its own mesh and stiffness and describes only its
//!   contact polylines (node ids, reference coordinates and equation numbers in its numbering)
//!   in a [`HyconHost`], plus either its stiffness in CSR (factored by hycon) or a solve callback
//!   ([`HyconSolveFn`]) so that it factors `K` with its own solver (CHOLMOD, PETSc, ...).
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
    Csr, HostElements, HostNode, HostSolve, HostStiffness, HostSystem, Triangle,
};
use crate::contact::iteration::{
    ContactAnalysis, ContactOptions, ContactPair, IterationRecord, Kinematics, Monitor, NodeState,
    PlateControl,
};
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

/// Directions of a prescribed displacement, a bit mask.
pub type HyconDirections = i32;
/// x only.
pub const HYCON_X: HyconDirections = 1;
/// y only.
pub const HYCON_Y: HyconDirections = 2;
/// x and y.
pub const HYCON_XY: HyconDirections = 3;

/// State of an A node, one of `HYCON_NODE_*`.
pub type HyconNodeState = i32;
/// Not in contact.
pub const HYCON_NODE_OPEN: HyconNodeState = 1;
/// In contact, no slip since the increment began.
pub const HYCON_NODE_STICK: HyconNodeState = 2;
/// In contact and sliding (`ts = mu sign tn`).
pub const HYCON_NODE_SLIP: HyconNodeState = 3;

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
    /// Active (stick + slip) A nodes in this iteration's solve.
    pub active: usize,
    /// Stick nodes among them.
    pub stick: usize,
    /// Slip nodes among them.
    pub slip: usize,
    /// State changes decided after the solve.
    pub changes: usize,
    /// Convergence measure over the contact dofs: the change of this iteration's displacement
    /// relative to the increment's motion so far (bounded below by round-off, and under finite
    /// kinematics by the largest motion of a converged increment); always finite.
    pub r: f64,
    /// Estimated 1-norm condition number of the small contact system (1 when empty).
    pub condition: f64,
}

/// Called with every iteration record; return 0 to go on, nonzero to stop the increment (it
/// then fails with `HYCON_ERROR_CALLBACK` and the last converged state is kept). Called on the
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

/// Parameters of the contact iteration. Get the defaults with `hycon_contact_options_default`,
/// then override fields. Tolerances are relative (see each field), so results do not change
/// when units are rescaled.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct HyconContactOptions {
    /// Convergence tolerance on `R` (default 1e-6; the paper used 0.01).
    pub tolerance: f64,
    /// Penetration tolerance, relative to the increment's displacement scale (default 1e-9).
    pub gap_tolerance: f64,
    /// Tension tolerance, relative to the largest `|tn|` (default 1e-9).
    pub tension_tolerance: f64,
    /// Friction-cone tolerance, relative to `mu |tn|` (default 1e-9).
    pub friction_tolerance: f64,
    /// Slip reversal tolerance, relative to the mean A segment length (default 1e-6).
    pub slip_tolerance: f64,
    /// B segments farther than this from an A segment, relative to the mean A segment length,
    /// are not paired with it (default 4).
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
    /// Optional iteration monitor (NULL: none). Kept by the `HyconContact` for its lifetime.
    pub monitor: HyconMonitorFn,
    /// Passed to `monitor`; must stay valid as long as the `HyconContact` that uses it.
    pub monitor_data: *mut c_void,
}

/// Summary of a converged increment.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HyconIncrementInfo {
    /// Increment number (1-based).
    pub increment: usize,
    /// Iterations used.
    pub iterations: usize,
    /// Active (stick + slip) A nodes at convergence.
    pub active: usize,
    /// Slip nodes at convergence.
    pub slip: usize,
}

/// Converged results at one A node (multiplier side).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HyconNodeResult {
    /// Node id (the caller's numbering).
    pub node: usize,
    /// `HYCON_NODE_OPEN`, `HYCON_NODE_STICK` or `HYCON_NODE_SLIP`.
    pub state: HyconNodeState,
    /// Slip direction along `tangent` of A relative to B (+1 or -1) for a slip node, else 0.
    pub slip_sign: i32,
    /// Normal traction on A (the multiplier; `< 0` compression, pressure `p = -tn`).
    pub tn: f64,
    /// Tangential traction on A along `tangent`.
    pub ts: f64,
    /// Nodal normal (A's outward): of the reference configuration under small kinematics, of
    /// the converged one under finite kinematics.
    pub normal: [f64; 2],
    /// Nodal tangent `(n_y, -n_x)`.
    pub tangent: [f64; 2],
    /// Current position (reference position plus the converged displacement).
    pub position: [f64; 2],
    /// Tributary length `integral M_k ds`, measured in the configuration the geometry lives in
    /// (reference under small kinematics, converged under finite): the tractions are per unit
    /// length of it, so `sum -tn * weight` is the normal load only where A is straight.
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
    /// `integral L^B_j ds` over the projected overlap (0 outside it).
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
    /// `integral M_k ds` over the node's support.
    pub weight: f64,
    /// Fraction of the support covered by B, in [0, 1].
    pub coverage: f64,
    /// Nodal normal `n_k` (A's outward).
    pub normal: [f64; 2],
    /// Nodal tangent `s_k = (n_y, -n_x)`.
    pub tangent: [f64; 2],
    /// Weighted gap vector `R_C,k = integral M_k (x^A - x^B) ds` (x, y).
    pub gap: [f64; 2],
    /// `-n_k . R_C,k / covered weight`: normal gap as a length (`< 0` penetration; infinite
    /// when nothing is covered).
    pub normal_gap: f64,
}

/// One entry of the contact-element matrices: `F^A_kj = integral M_k L^A_j ds` or
/// `F^B_kj = integral M_k L^B_j(x^B) ds` (both >= 0). The constraint row of A node `k` is
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
/// (CSR) or solve callback. Create with `hycon_host_new`, free with `hycon_host_free`.
/// Thread safety: as `HyconModel`.
pub struct HyconHost {
    equations: usize,
    nodes: Vec<HostNode>,
    pairs: Vec<ContactPair>,
    stiffness: Option<HostSource>,
    elements: Option<HostElements>,
}

enum HostSource {
    Csr(Csr),
    Callback(CallbackSolve),
}

/// A contact analysis: `K` factored once (or the host's solver), the converged state, the
/// records. Create with `hycon_contact_new` (model API) or `hycon_contact_new_host`, free with
/// `hycon_contact_free`. Thread safety: a `HyconContact` may be moved between threads but must
/// not be used from two threads at once (no internal locking); distinct handles share nothing
/// and may run concurrently. Callbacks run on the calling thread.
pub struct HyconContact {
    analysis: ContactAnalysis,
}

/// The host's solve callback with its user data.
struct CallbackSolve {
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
    }
}

// ------------------------------------------------------------------------------------------
// Checked access to caller memory

/// A caller array `(ptr, len)` as a slice for the duration of the call. `(NULL, 0)` is empty.
///
/// # Safety
/// If `ptr` is non-null it must point to `len` readable, initialised values that stay
/// unchanged during the call.
unsafe fn slice<'a, T>(ptr: *const T, len: usize, name: &str) -> Result<&'a [T], Fail> {
    if len == 0 {
        return Ok(&[]);
    }
    if len > isize::MAX as usize / std::mem::size_of::<T>().max(1) {
        return Err(Fail::invalid(format!("{name}: length {len} is too large")));
    }
    check_pointer(ptr, name)?;
    // SAFETY: non-null and aligned (checked); `len` readable values (caller contract).
    Ok(unsafe { std::slice::from_raw_parts(ptr, len) })
}

/// `count * per + extra`, the length of an array sized by another argument, or an error naming
/// `name` when it overflows.
fn length(count: usize, per: usize, extra: usize, name: &str) -> Result<usize, Fail> {
    count
        .checked_mul(per)
        .and_then(|n| n.checked_add(extra))
        .ok_or_else(|| Fail::invalid(format!("{name} = {count} is too large")))
}

/// [`slice`] of doubles, checked finite.
///
/// # Safety
/// As [`slice`].
unsafe fn doubles<'a>(ptr: *const f64, len: usize, name: &str) -> Result<&'a [f64], Fail> {
    // SAFETY: forwarded contract.
    let values = unsafe { slice(ptr, len, name)? };
    check_finite(values, name)?;
    Ok(values)
}

/// A handle argument as a shared reference.
///
/// # Safety
/// `ptr` must be NULL or a live handle from the matching `_new` function.
unsafe fn handle<'a, T>(ptr: *const T, name: &str) -> Result<&'a T, Fail> {
    check_pointer(ptr, name)?;
    // SAFETY: non-null, aligned, and a live handle (caller contract).
    Ok(unsafe { &*ptr })
}

/// A handle argument as an exclusive reference.
///
/// # Safety
/// As [`handle`], and not used by anyone else during the call.
unsafe fn handle_mut<'a, T>(ptr: *mut T, name: &str) -> Result<&'a mut T, Fail> {
    check_pointer(ptr.cast_const(), name)?;
    // SAFETY: non-null, aligned, live and exclusively ours during the call (caller contract).
    Ok(unsafe { &mut *ptr })
}

/// Write one value to a caller pointer.
///
/// # Safety
/// `ptr` must be NULL or point to a writable `T`.
unsafe fn write<T>(ptr: *mut T, value: T, name: &str) -> Result<(), Fail> {
    check_pointer(ptr.cast_const(), name)?;
    // SAFETY: non-null, aligned (checked) and writable (contract).
    unsafe { ptr.write(value) };
    Ok(())
}

/// Write an optional output (NULL: not wanted).
///
/// # Safety
/// `ptr` must be NULL or point to a writable `T`.
unsafe fn write_optional<T>(ptr: *mut T, value: T) {
    if !ptr.is_null() && ptr.is_aligned() {
        // SAFETY: non-null, aligned and writable (contract).
        unsafe { ptr.write(value) };
    }
}

/// Copy `values` into a caller array `(out, len)` after checking its length.
///
/// # Safety
/// `out` must be NULL or point to `len` writable `T`.
unsafe fn write_all<T: Copy>(
    out: *mut T,
    len: usize,
    values: &[T],
    name: &str,
) -> Result<(), Fail> {
    check_output(out, len, values.len(), name)?;
    if !values.is_empty() {
        // SAFETY: checked non-null, aligned and long enough; `values` is our own memory.
        unsafe { std::ptr::copy_nonoverlapping(values.as_ptr(), out, values.len()) };
    }
    Ok(())
}

/// Box a new handle and hand it to the caller.
///
/// # Safety
/// `out` must be NULL or point to a writable pointer.
unsafe fn hand_out<T>(out: *mut *mut T, value: T) -> Result<(), Fail> {
    check_pointer(out.cast_const(), "out")?;
    // SAFETY: checked non-null and aligned; writable (contract). Ownership passes to the caller,
    // who returns it through the matching `_free`.
    unsafe { out.write(Box::into_raw(Box::new(value))) };
    Ok(())
}

/// Free a handle made by [`hand_out`]; NULL is a no-op.
///
/// # Safety
/// `ptr` must be NULL or a live handle of type `T`, not used afterwards.
unsafe fn free_handle<T>(ptr: *mut T) {
    if !ptr.is_null() {
        // SAFETY: made by `Box::into_raw` in `hand_out` and not freed before (contract).
        drop(unsafe { Box::from_raw(ptr) });
    }
}

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
    offsets: Vec<usize>,
    nodes: Vec<usize>,
    element_material: Vec<usize>,
    materials: Vec<Material>,
}

/// Read `n_elements` elements in compressed form (`element_offsets`: `n_elements + 1` entries;
/// `element_nodes`: `element_offsets[n_elements]` ids; `element_materials`: `n_elements`
/// indices or NULL for all 0) and `n_materials` materials.
///
/// # Safety
/// Each array must be NULL or hold the stated number of readable values.
unsafe fn read_elements(
    element_offsets: *const usize,
    element_nodes: *const usize,
    n_elements: usize,
    element_materials: *const usize,
    materials: *const HyconMaterial,
    n_materials: usize,
) -> Result<ElementArrays, Fail> {
    if n_elements == 0 || n_materials == 0 {
        return Err(Fail::invalid(format!(
            "elements and materials are needed (got {n_elements} and {n_materials})"
        )));
    }
    let n_offsets = length(n_elements, 1, 1, "n_elements")?;
    // SAFETY (all reads): forwarded contract.
    let offsets = unsafe { slice(element_offsets, n_offsets, "element_offsets")? };
    if offsets[0] != 0 || offsets.windows(2).any(|w| w[1] < w[0]) {
        return Err(Fail::invalid(
            "element_offsets must start at 0 and be nondecreasing",
        ));
    }
    let nodes = unsafe { slice(element_nodes, offsets[n_elements], "element_nodes")? };
    let element_material = if element_materials.is_null() {
        vec![0; n_elements]
    } else {
        unsafe { slice(element_materials, n_elements, "element_materials")? }.to_vec()
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
        offsets: offsets.to_vec(),
        nodes: nodes.to_vec(),
        element_material,
        materials,
    })
}

/// Read the options argument (NULL: defaults).
///
/// # Safety
/// `options` must be NULL or point to a readable `HyconContactOptions`.
unsafe fn read_options(
    options: *const HyconContactOptions,
) -> Result<(ContactOptions, Option<Monitor>), Fail> {
    if options.is_null() {
        return Ok((ContactOptions::default(), None));
    }
    // SAFETY: forwarded contract.
    let o = unsafe { handle(options, "options")? };
    options_from_c(o)
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
        let d = ContactOptions::default();
        let o = HyconContactOptions {
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
            monitor: None,
            monitor_data: std::ptr::null_mut(),
        };
        // SAFETY: the caller's contract on `out`.
        unsafe { write(out, o, "out") }
    })
}

// ------------------------------------------------------------------------------------------
// Model API

/// Create a model from its mesh and materials.
///
/// * `coords`: `2 * n_nodes` doubles `x0 y0 x1 y1 ...`;
/// * elements in compressed form: element `e` has the nodes
///   `element_nodes[element_offsets[e] .. element_offsets[e + 1]]` (4 to 6 node ids,
///   counter-clockwise: corners plus mid-side nodes of transition elements, in boundary
///   order); `element_offsets` has `n_elements + 1` entries starting at 0;
/// * `element_materials`: `n_elements` indices into `materials`, or NULL (all use material 0);
/// * `kind`: the formulation of every element (`HYCON_ELEMENT_*`; Pian-Sumihara and Q4 take
///   4-node elements only).
///
/// The arrays are copied. Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_ARGUMENT`
/// (lengths, unknown node ids, non-finite coordinates, unknown kind),
/// `HYCON_ERROR_INVALID_MATERIAL`, `HYCON_ERROR_BAD_ELEMENT` (inverted, degenerate or non-convex
/// element, named by index).
///
/// # Safety
/// `out` must point to a writable pointer; each array must be NULL or hold the stated number of
/// readable values.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn hycon_model_new(
    out: *mut *mut HyconModel,
    coords: *const f64,
    n_nodes: usize,
    element_offsets: *const usize,
    element_nodes: *const usize,
    n_elements: usize,
    element_materials: *const usize,
    materials: *const HyconMaterial,
    n_materials: usize,
    kind: HyconElementKind,
) -> HyconStatus {
    boundary("hycon_model_new", || {
        let formulation = formulation(kind)?;
        if n_nodes == 0 {
            return Err(Fail::invalid("a model needs nodes (n_nodes = 0)"));
        }
        // SAFETY (all reads below): the caller's contract on the arrays and lengths.
        let xy = unsafe { doubles(coords, length(n_nodes, 2, 0, "n_nodes")?, "coords")? };
        let elements = unsafe {
            read_elements(
                element_offsets,
                element_nodes,
                n_elements,
                element_materials,
                materials,
                n_materials,
            )?
        };
        let mut mesh = Mesh::new();
        for p in xy.chunks_exact(2) {
            mesh.push_node([p[0], p[1]]);
        }
        mesh.element_offsets = elements.offsets;
        mesh.element_nodes = elements.nodes;
        mesh.element_material = elements.element_material;
        let model = Model::new(mesh, elements.materials, formulation);
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
/// Errors: `HYCON_ERROR_INVALID_ARGUMENT` for unknown node ids, fewer than 2 nodes, repeated
/// nodes, a node in both polylines, consecutive nodes that are not an element edge with the
/// body on the left (naming the segment), a bad friction coefficient.
///
/// # Safety
/// `model` must be a live handle; `a`, `b` NULL or holding `n_a`, `n_b` ids.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_model_add_pair(
    model: *mut HyconModel,
    a: *const usize,
    n_a: usize,
    b: *const usize,
    n_b: usize,
    friction: f64,
    index: *mut usize,
) -> HyconStatus {
    boundary("hycon_model_add_pair", || {
        // SAFETY: the caller's contract.
        let m = unsafe { handle_mut(model, "model")? };
        let (a, b) = unsafe { (slice(a, n_a, "a")?, slice(b, n_b, "b")?) };
        let pair = ContactPair {
            a: a.to_vec(),
            b: b.to_vec(),
            friction,
        };
        pair.check_on(&m.model.mesh)?;
        m.pairs.push(pair);
        // SAFETY: the caller's contract on `index`.
        unsafe { write_optional(index, m.pairs.len() - 1) };
        Ok(())
    })
}

/// Tie `nodes` (a face of one body, none of them a contact node) to a rigid plate whose x and
/// y translations are driven per increment by `hycon_contact_increment_plate`, each by
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

impl HyconHost {
    /// Register the nodes of one polyline: new nodes are added, known ones must agree.
    fn merge_nodes(
        &mut self,
        ids: &[usize],
        xy: &[f64],
        eqs: &[i64],
        side: &str,
    ) -> Result<(), Fail> {
        for (i, &id) in ids.iter().enumerate() {
            let mut equations = [None; 2];
            for (d, e) in equations.iter_mut().enumerate() {
                let raw = eqs[2 * i + d];
                *e = match raw {
                    HYCON_FIXED => None,
                    r if r >= 0 && (r as u64) < self.equations as u64 => Some(r as usize),
                    r => {
                        return Err(Fail::invalid(format!(
                            "{side} node {id}: equation {r} is out of range (0..{} or \
                             HYCON_FIXED)",
                            self.equations
                        )));
                    }
                };
            }
            let node = HostNode {
                id,
                position: [xy[2 * i], xy[2 * i + 1]],
                equations,
            };
            match self.nodes.iter().find(|n| n.id == id) {
                Some(known) if *known != node => {
                    return Err(Fail::invalid(format!(
                        "{side} node {id} was given before with other coordinates or equations"
                    )));
                }
                Some(_) => {}
                None => {
                    if let Some(other) = self.nodes.iter().find(|n| {
                        n.equations
                            .iter()
                            .flatten()
                            .any(|e| equations.contains(&Some(*e)))
                    }) {
                        return Err(Fail::invalid(format!(
                            "{side} node {id} shares an equation with node {}",
                            other.id
                        )));
                    }
                    self.nodes.push(node)
                }
            }
        }
        Ok(())
    }
}

/// Add a contact pair in the host's numbering: for each polyline (A, the multiplier side, and
/// B), `n` node ids, their `2 n` reference coordinates `x0 y0 x1 y1 ...` and `2 n` equation
/// numbers (`u_x`, `u_y` per node; `HYCON_FIXED` for a dof the host holds at zero). Each
/// polyline is ordered with its body on the left. A node in several pairs must be given the
/// same coordinates and equations each time. `friction >= 0` is the Coulomb coefficient. The
/// pair's index is written to `index` unless it is NULL. The arrays are copied.
///
/// # Safety
/// `host` must be a live handle; every array NULL or holding the stated number of values.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn hycon_host_add_pair(
    host: *mut HyconHost,
    a_nodes: *const usize,
    a_coords: *const f64,
    a_equations: *const i64,
    n_a: usize,
    b_nodes: *const usize,
    b_coords: *const f64,
    b_equations: *const i64,
    n_b: usize,
    friction: f64,
    index: *mut usize,
) -> HyconStatus {
    boundary("hycon_host_add_pair", || {
        // SAFETY (all reads): the caller's contract.
        let h = unsafe { handle_mut(host, "host")? };
        let a = unsafe { slice(a_nodes, n_a, "a_nodes")? };
        let b = unsafe { slice(b_nodes, n_b, "b_nodes")? };
        let pair = ContactPair {
            a: a.to_vec(),
            b: b.to_vec(),
            friction,
        };
        pair.check()?;
        let (len_a, len_b) = (length(n_a, 2, 0, "n_a")?, length(n_b, 2, 0, "n_b")?);
        let a_xy = unsafe { doubles(a_coords, len_a, "a_coords")? };
        let b_xy = unsafe { doubles(b_coords, len_b, "b_coords")? };
        let a_eq = unsafe { slice(a_equations, len_a, "a_equations")? };
        let b_eq = unsafe { slice(b_equations, len_b, "b_equations")? };
        for (ids, xy, side) in [(a, a_xy, "A"), (b, b_xy, "B")] {
            if let Some(w) = ids
                .windows(2)
                .enumerate()
                .find(|(i, _)| xy[2 * i] == xy[2 * i + 2] && xy[2 * i + 1] == xy[2 * i + 3])
            {
                return Err(Fail::invalid(format!(
                    "the {side} polyline is not a chain: segment {} -> {} has zero length",
                    w.1[0], w.1[1]
                )));
            }
        }
        // all-or-nothing: merge into a copy
        let mut nodes = h.nodes.clone();
        std::mem::swap(&mut nodes, &mut h.nodes);
        let merged = h
            .merge_nodes(a, a_xy, a_eq, "A")
            .and_then(|_| h.merge_nodes(b, b_xy, b_eq, "B"));
        if let Err(e) = merged {
            h.nodes = nodes;
            return Err(e);
        }
        h.pairs.push(pair);
        // SAFETY: the caller's contract on `index`.
        unsafe { write_optional(index, h.pairs.len() - 1) };
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
        let n = h.equations;
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
        csr.lower()?; // check the structure now, so errors come from this call
        h.stiffness = Some(HostSource::Csr(csr));
        Ok(())
    })
}

/// Let the host solve with its own factorization: `solve(user_data, n, nrhs, rhs, x)` (see
/// `HyconSolveFn`). The function pointer and `user_data` are kept by this description and by
/// every analysis made from it, and called during `hycon_contact_new_host`, the increments and
/// displacement recovery; `user_data` (the host's factor) must outlive them. Replaces an
/// earlier matrix or solver. This is the path for distributed hosts (e.g. PETSc over MPI): hycon
/// only ever asks for solves and works on the contact dofs, which every rank can hold.
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
        let Some(solve) = solve else {
            return Err(Fail::new(HYCON_ERROR_NULL_POINTER, "solve is NULL"));
        };
        h.stiffness = Some(HostSource::Callback(CallbackSolve { solve, user_data }));
        Ok(())
    })
}

/// Optionally hand over the elements of body A along the A polylines (at least those owning an
/// A segment), so that `hycon_contact_stress_tractions` can recover the tractions from their
/// stresses (the paper's way (a)) from the host's displacements. The elements must be hycon
/// element formulations (`kind`), counter-clockwise, in compressed form as in
/// `hycon_model_new` (`element_offsets` has `n_elements + 1` entries, `element_materials`
/// `n_elements` indices into `materials` or NULL for all 0), with node ids of the host's
/// numbering; the node table gives, for each of the `n_nodes` nodes they use, its id
/// (`node_ids`), reference coordinates (`coords`, 2 per node) and equations (`equations`, 2 per
/// node, `HYCON_FIXED` for a held dof). Copied; replaces earlier elements. Note the order:
/// kind and materials first, then the elements, then the node table (`hycon_model_new` takes
/// the coordinates first and the kind last).
///
/// # Safety
/// `host` must be a live handle; every array NULL or holding the stated number of values.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn hycon_host_set_elements(
    host: *mut HyconHost,
    kind: HyconElementKind,
    materials: *const HyconMaterial,
    n_materials: usize,
    element_materials: *const usize,
    element_offsets: *const usize,
    element_nodes: *const usize,
    n_elements: usize,
    node_ids: *const usize,
    coords: *const f64,
    equations: *const i64,
    n_nodes: usize,
) -> HyconStatus {
    boundary("hycon_host_set_elements", || {
        // SAFETY (all reads): the caller's contract.
        let h = unsafe { handle_mut(host, "host")? };
        let formulation = formulation(kind)?;
        if n_nodes == 0 {
            return Err(Fail::invalid("elements need nodes (n_nodes = 0)"));
        }
        let elements = unsafe {
            read_elements(
                element_offsets,
                element_nodes,
                n_elements,
                element_materials,
                materials,
                n_materials,
            )?
        };
        let ids = unsafe { slice(node_ids, n_nodes, "node_ids")? };
        let per_node = length(n_nodes, 2, 0, "n_nodes")?;
        let xy = unsafe { doubles(coords, per_node, "coords")? };
        let eqs = unsafe { slice(equations, per_node, "equations")? };
        let node_table = ids
            .iter()
            .enumerate()
            .map(|(i, &id)| {
                let mut equations = [None; 2];
                for (d, e) in equations.iter_mut().enumerate() {
                    *e = match eqs[2 * i + d] {
                        HYCON_FIXED => None,
                        r if r >= 0 && (r as u64) < h.equations as u64 => Some(r as usize),
                        r => {
                            return Err(Fail::invalid(format!(
                                "element node {id}: equation {r} is out of range (0..{} or \
                                 HYCON_FIXED)",
                                h.equations
                            )));
                        }
                    };
                }
                Ok(HostNode {
                    id,
                    position: [xy[2 * i], xy[2 * i + 1]],
                    equations,
                })
            })
            .collect::<Result<Vec<_>, Fail>>()?;
        let elements = HostElements {
            formulation,
            materials: elements.materials,
            element_material: elements.element_material,
            offsets: elements.offsets,
            nodes: elements.nodes,
            node_table,
        };
        // check now (shapes, ids), so that errors come from this call
        crate::contact::bodies::check_elements(&elements, h.equations)?;
        h.elements = Some(elements);
        Ok(())
    })
}

/// Start a contact analysis of a host's system: factor its CSR matrix once (the contact
/// equations last) and read the flexibility off the factor, or build the flexibility from
/// batched solves through its callback. `options` NULL means the defaults.
///
/// Errors: `HYCON_ERROR_INVALID_ARGUMENT` (no pair, no stiffness or solver given),
/// `HYCON_ERROR_SINGULAR` (the CSR matrix is not positive definite: a body not held),
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
        let stiffness = match &h.stiffness {
            Some(HostSource::Csr(csr)) => HostStiffness::Csr(csr.clone()),
            Some(HostSource::Callback(c)) => HostStiffness::Solver(Box::new(CallbackSolve {
                solve: c.solve,
                user_data: c.user_data,
            })),
            None => {
                return Err(Fail::invalid(
                    "the host gave neither a stiffness (hycon_host_set_csr) nor a solver \
                     (hycon_host_set_solver)",
                ));
            }
        };
        let system = HostSystem {
            equations: h.equations,
            nodes: h.nodes.clone(),
            stiffness,
            elements: h.elements.clone(),
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

/// Length of the load and displacement vectors: `2 * n_nodes` (model API) or `n_equations`
/// (host API).
///
/// # Safety
/// `contact` must be a live handle, `n` writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_field_len(
    contact: *const HyconContact,
    n: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_field_len", || {
        // SAFETY: the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        let len = c.analysis.field_len();
        unsafe { write(n, len, "n") }
    })
}

fn info_to_c(i: crate::contact::iteration::IncrementInfo) -> HyconIncrementInfo {
    HyconIncrementInfo {
        increment: i.increment,
        iterations: i.iterations,
        active: i.active,
        slip: i.slip,
    }
}

/// Apply one load increment with **total** values (from the reference state):
/// * model API: `load` = external nodal forces over all `2 * n_nodes` dofs (`u0 v0 u1 v1 ...`),
///   `prescribed` = values at the prescribed dofs over the same `2 * n_nodes` entries (the
///   others are ignored, whatever they hold: NaN there is fine);
/// * host API: `load` = the host's right-hand side over its equations (including the effect of
///   its prescribed displacements), `prescribed` = (NULL, 0).
///
/// On success the converged state advances and `info` (unless NULL) gets the summary. On
/// failure the last converged state is kept and the status says why: `HYCON_ERROR_CONTACT` (no
/// convergence, cycling contact set with the node named, penetration beyond the search
/// distance, contact reaching the end of a surface), `HYCON_ERROR_SINGULAR` (a body held only
/// by frictionless contact), `HYCON_ERROR_CALLBACK` (solver or monitor),
/// `HYCON_ERROR_INVALID_ARGUMENT` (lengths, non-finite values, a plate analysis).
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
        let f = unsafe { slice(load, load_len, "load")? };
        let qp = unsafe { slice(prescribed, prescribed_len, "prescribed")? };
        let done = c.analysis.increment(f, qp)?;
        unsafe { write_optional(info, info_to_c(done)) };
        Ok(())
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
pub unsafe extern "C" fn hycon_contact_increment_plate(
    contact: *mut HyconContact,
    load: *const f64,
    load_len: usize,
    prescribed: *const f64,
    prescribed_len: usize,
    control: *const HyconPlateControl,
    value: *const f64,
    info: *mut HyconIncrementInfo,
) -> HyconStatus {
    boundary("hycon_contact_increment_plate", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle_mut(contact, "contact")? };
        let f = unsafe { slice(load, load_len, "load")? };
        let qp = unsafe { slice(prescribed, prescribed_len, "prescribed")? };
        let kinds = unsafe { slice(control, 2, "control")? };
        let values = unsafe { doubles(value, 2, "value")? };
        let mut plate = [PlateControl::Displacement(0.0); 2];
        for d in 0..2 {
            plate[d] = match kinds[d] {
                HYCON_PLATE_DISPLACEMENT => PlateControl::Displacement(values[d]),
                HYCON_PLATE_FORCE => PlateControl::Force(values[d]),
                k => {
                    return Err(Fail::invalid(format!(
                        "control[{d}] = {k} (expected HYCON_PLATE_DISPLACEMENT = 1 or \
                         HYCON_PLATE_FORCE = 2)"
                    )));
                }
            };
        }
        let done = c.analysis.increment_with_plate(f, qp, plate)?;
        unsafe { write_optional(info, info_to_c(done)) };
        Ok(())
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
        let Some((u, f)) = c.analysis.plate() else {
            return Err(Fail::invalid("this analysis has no plate"));
        };
        check_output(displacement, 2, 2, "displacement")?;
        check_output(force, 2, 2, "force")?;
        unsafe { write_all(displacement, 2, &u, "displacement")? };
        unsafe { write_all(force, 2, &f, "force") }
    })
}

/// The displacement of the last converged increment (total, from the reference state; zero
/// before the first) over the field (`hycon_contact_field_len` values): all dofs of a model,
/// the host's equations. Costs one solve on the first call after an increment.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_displacement(
    contact: *mut HyconContact,
    out: *mut f64,
    len: usize,
) -> HyconStatus {
    boundary("hycon_contact_displacement", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle_mut(contact, "contact")? };
        let needed = c.analysis.field_len();
        check_output(out, len, needed, "out")?;
        let q = c.analysis.displacement()?;
        unsafe { write_all(out, len, q, "out") }
    })
}

/// The displacement increment of the last converged increment (its total displacement minus
/// the previous increment's; the total at the first), same layout as
/// `hycon_contact_displacement`. One solve per call.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_displacement_increment(
    contact: *mut HyconContact,
    out: *mut f64,
    len: usize,
) -> HyconStatus {
    boundary("hycon_contact_displacement_increment", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle_mut(contact, "contact")? };
        check_output(out, len, c.analysis.field_len(), "out")?;
        let du = c.analysis.displacement_increment()?;
        unsafe { write_all(out, len, &du, "out") }
    })
}

/// The contact forces of the last converged increment over the field (zero at a host's fixed
/// dofs): adding them to the load gives the right-hand side whose solution is the displacement
/// (`K u = load + forces`), for hosts that recover displacements and stresses themselves.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_forces(
    contact: *const HyconContact,
    out: *mut f64,
    len: usize,
) -> HyconStatus {
    boundary("hycon_contact_forces", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { write_all(out, len, &c.analysis.contact_forces(), "out") }
    })
}

/// Sizes of pair `pair`: nodes of its A and B polylines (either output may be NULL).
///
/// # Safety
/// `contact` must be a live handle; outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_pair_size(
    contact: *const HyconContact,
    pair: usize,
    n_a: *mut usize,
    n_b: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_pair_size", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        let (a, b) = c.analysis.pair_size(pair)?;
        unsafe {
            write_optional(n_a, a);
            write_optional(n_b, b);
        }
        Ok(())
    })
}

/// Tractions way (b), the multipliers: converged results at the A nodes of `pair` (states,
/// `tn`, `ts`, frames, gaps, nodal forces); `out` needs the A node count.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_node_results(
    contact: *const HyconContact,
    pair: usize,
    out: *mut HyconNodeResult,
    len: usize,
) -> HyconStatus {
    boundary("hycon_contact_node_results", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        let results: Vec<HyconNodeResult> = c
            .analysis
            .node_results(pair)?
            .iter()
            .map(|r| {
                let (state, slip_sign) = match r.state {
                    NodeState::Open => (HYCON_NODE_OPEN, 0),
                    NodeState::Stick => (HYCON_NODE_STICK, 0),
                    NodeState::Slip { sign } => (HYCON_NODE_SLIP, i32::from(sign)),
                };
                HyconNodeResult {
                    node: r.node,
                    state,
                    slip_sign,
                    tn: r.tn,
                    ts: r.ts,
                    normal: r.normal,
                    tangent: r.tangent,
                    position: r.position,
                    weight: r.weight,
                    gap: r.gap,
                    force: r.force,
                }
            })
            .collect();
        unsafe { write_all(out, len, &results, "out") }
    })
}

/// Tractions way (c), the B side: nodal forces, weights and pressures at the B nodes of `pair`;
/// `out` needs the B node count.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_b_node_results(
    contact: *const HyconContact,
    pair: usize,
    out: *mut HyconBNodeResult,
    len: usize,
) -> HyconStatus {
    boundary("hycon_contact_b_node_results", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        let results: Vec<HyconBNodeResult> = c
            .analysis
            .b_node_results(pair)?
            .iter()
            .map(|r| HyconBNodeResult {
                node: r.node,
                weight: r.weight,
                force: r.force,
                pressure: r.pressure,
                position: r.position,
            })
            .collect();
        unsafe { write_all(out, len, &results, "out") }
    })
}

/// Tractions way (a), from the element stresses of body A: `tn ts` per A node of `pair` in its
/// nodal frame, `2 * n_a` doubles. Model API; host API when the host handed over the elements
/// along A (`hycon_host_set_elements`). Costs the displacement recovery (one solve) if not done
/// yet.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_stress_tractions(
    contact: *mut HyconContact,
    pair: usize,
    out: *mut f64,
    len: usize,
) -> HyconStatus {
    boundary("hycon_contact_stress_tractions", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle_mut(contact, "contact")? };
        let (n_a, _) = c.analysis.pair_size(pair)?;
        check_output(out, len, 2 * n_a, "out")?;
        let t: Vec<f64> = c
            .analysis
            .stress_tractions(pair)?
            .iter()
            .flat_map(|&(tn, ts)| [tn, ts])
            .collect();
        unsafe { write_all(out, len, &t, "out") }
    })
}

/// Number of iteration records so far (all increments, failed ones excluded).
///
/// # Safety
/// `contact` must be a live handle; `count` writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_record_count(
    contact: *const HyconContact,
    count: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_record_count", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        unsafe { write(count, c.analysis.records().len(), "count") }
    })
}

/// Copy the iteration records `first .. first + len` into `out` (`first + len` must not exceed
/// `hycon_contact_record_count`).
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_records(
    contact: *const HyconContact,
    first: usize,
    out: *mut HyconIterationRecord,
    len: usize,
) -> HyconStatus {
    boundary("hycon_contact_records", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        let all = c.analysis.records();
        let Some(records) = first.checked_add(len).and_then(|end| all.get(first..end)) else {
            return Err(Fail::invalid(format!(
                "records {first} .. {first} + {len} requested, {} exist",
                all.len()
            )));
        };
        let records: Vec<HyconIterationRecord> = records.iter().map(record_to_c).collect();
        unsafe { write_all(out, len, &records, "out") }
    })
}

/// Where the time went so far, and the number of numeric factorizations of `K` done by hycon
/// (1 per analysis; 0 when a host solves itself); either output may be NULL.
///
/// # Safety
/// `contact` must be a live handle; outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_timings(
    contact: *mut HyconContact,
    timings: *mut HyconTimings,
    factorizations: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_timings", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle_mut(contact, "contact")? };
        let t = c.analysis.timings();
        let out = HyconTimings {
            assembly: t.assembly,
            factorization: t.factorization,
            flexibility: t.flexibility,
            load_solves: t.load_solves,
            iterations: t.iterations,
            recovery: t.recovery,
        };
        let count = c.analysis.factorizations();
        unsafe {
            write_optional(timings, out);
            write_optional(factorizations, count);
        }
        Ok(())
    })
}

/// Contact-element quantities of the A nodes of `pair` in the converged configuration (the
/// reference one before the first increment): weights, frames, weighted gaps `R_C`, coverage.
/// `out` needs the A node count.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_element_nodes(
    contact: *const HyconContact,
    pair: usize,
    out: *mut HyconContactNode,
    len: usize,
) -> HyconStatus {
    boundary("hycon_contact_element_nodes", || {
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
                normal: n.normal,
                tangent: n.tangent,
                gap: n.gap,
                normal_gap: n.normal_gap,
            })
            .collect();
        unsafe { write_all(out, len, &nodes, "out") }
    })
}

/// The contact-element matrices `F^A` and `F^B` of `pair` (converged configuration) as a list
/// of entries (row `k`, node `j`, side, value). Call with `out` NULL and `len` 0 to get the
/// entry count in `count`; then with a buffer of at least that many.
///
/// # Safety
/// `contact` must be a live handle; `out` NULL or `len` writable structs; `count` writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_contact_coupling(
    contact: *const HyconContact,
    pair: usize,
    out: *mut HyconCouplingEntry,
    len: usize,
    count: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_coupling", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        check_pointer(count.cast_const(), "count")?;
        let surface = c.analysis.surface(pair)?;
        let a_ids: std::collections::HashSet<usize> =
            surface.nodes.iter().map(|n| n.node).collect();
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
        if !(out.is_null() && len == 0) {
            unsafe { write_all(out, len, &entries, "out")? };
        }
        unsafe { write(count, entries.len(), "count") }
    })
}

/// The constraint matrix `Kc` of `pair` (converged configuration) in CSR form: `2 n_a` rows,
/// row `2k` the normal constraint `n_k . (sum_j F^A_kj u_j - sum_j F^B_kj u_j)` and row `2k + 1`
/// the tangential one with `s_k`; columns are field indices (model dofs `2 node + direction`,
/// or host equations; a host's fixed dofs are left out). The mixed system of a host that
/// assembles it itself reads `[K  -Kc^T; -Kc  0] [u; t] = [f; -g]` with the active rows.
/// Call with `row_ptr`, `columns` and `values` all NULL to get the entry count in `nnz`; then
/// with `row_ptr` of `2 n_a + 1` entries and `columns`, `values` of at least `nnz` (NULL with
/// capacity 0 when `nnz` is 0).
///
/// # Safety
/// `contact` must be a live handle; `row_ptr` NULL or `row_ptr_len` writable; `columns` and
/// `values` NULL or `capacity` writable each; `nnz` writable.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn hycon_contact_kc(
    contact: *const HyconContact,
    pair: usize,
    row_ptr: *mut usize,
    row_ptr_len: usize,
    columns: *mut usize,
    values: *mut f64,
    capacity: usize,
    nnz: *mut usize,
) -> HyconStatus {
    boundary("hycon_contact_kc", || {
        // SAFETY (all): the caller's contract.
        let c = unsafe { handle(contact, "contact")? };
        check_pointer(nnz.cast_const(), "nnz")?;
        let rows = c.analysis.constraint_rows(pair)?;
        let query = row_ptr.is_null() && columns.is_null() && values.is_null();
        if !query {
            check_output(row_ptr, row_ptr_len, rows.row_ptr.len(), "row_ptr")?;
            check_output(columns, capacity, rows.columns.len(), "columns")?;
            check_output(values, capacity, rows.values.len(), "values")?;
            unsafe {
                write_all(row_ptr, row_ptr_len, &rows.row_ptr, "row_ptr")?;
                write_all(columns, capacity, &rows.columns, "columns")?;
                write_all(values, capacity, &rows.values, "values")?;
            }
        }
        unsafe { write(nnz, rows.columns.len(), "nnz") }
    })
}
