//! The C ABI: a thin checked layer over the safe Rust core.
//!
//! No mathematics lives here. Every exported function checks its inputs (pointers, lengths,
//! enums, finite values, element shape), calls the safe Rust API, and copies the result into
//! the caller's buffers. This module holds the conventions, status codes and the checked
//! boundary; `elements` exports the element routines ([`crate::element`]), `solid` the 3D brick
//! routines ([`crate::solid`]), `loads` the load and check routines of both (nodal forces of
//! edge and face loads, volume, quality, stress at natural coordinates), `contact` the contact analysis ([`crate::contact`]: model API
//! and host-assembly API) and `solid_contact` the 3D contact analysis of a brick model (the
//! `hycon_solid_*` family of handles). The header
//! `include/hycon.h` is generated from the crate by cbindgen
//! (`cbindgen --config cbindgen.toml --crate hycon --output include/hycon.h`, or
//! `HYCON_BLESS=1 cargo test --test integration header_fresh::`) and committed; `tests/header_fresh.rs` fails
//! when it is stale.
//!
//! # Conventions (repeated at the top of the header)
//! * Every symbol starts with `hycon_` / `Hycon` / `HYCON_`.
//! * Functions return a [`HyconStatus`]: `0` ([`HYCON_OK`]) on success, a negative
//!   `HYCON_ERROR_*` code on failure, and a positive value for a warning (the call succeeded,
//!   outputs were written, but something deserves attention; codes `1..=99` are reserved for
//!   warnings, [`HYCON_WARNING_SHAPE`] is the first). Every status-returning call sets this
//!   thread's message (a description when it fails or warns, empty when it succeeds);
//!   [`hycon_last_error_message`] copies it.
//! * Arrays are (pointer, length) pairs, or a pointer whose length is fixed by other arguments
//!   (stated per function). `(NULL, 0)` is an empty array.
//! * Variable-length outputs follow one size convention, `(out, len, needed)` (`fill`).
//! * One pointer rule (`pointer`): NULL required pointers are `HYCON_ERROR_NULL_POINTER`,
//!   misaligned pointers (required or optional) `HYCON_ERROR_INVALID_ARGUMENT`.
//! * Outputs are written only on success: on an error, every output buffer is left untouched
//!   (except `*needed` on `HYCON_ERROR_BUFFER_TOO_SMALL`).
//! * Inputs are read during the call only; the caller keeps ownership of all memory. The only
//!   pointers kept are a solve callback's and a monitor's user data (documented there).
//! * Thread safety: the element functions are reentrant and may be called from several threads
//!   at once; a function taking a mutable handle needs it exclusively, the const queries of a
//!   `HyconContact` may run concurrently (the analysis is `Sync`; solves are serialized inside);
//!   distinct handles are independent. The last error message is thread-local.
//! * Doubles must be finite (no NaN, no infinity); this is checked.
//! * Rust panics never cross the boundary: an internal error becomes
//!   [`HYCON_ERROR_PANIC`], and the panic message goes to the last error message, not to
//!   stderr (see `boundary` and `install_panic_hook` for the quiet panic hook; the unit test
//!   `panic_becomes_status_quietly` proves it in a child process).
//!
//! # Element node and dof order
//! An element is the counter-clockwise polygon of its boundary nodes, coordinates interleaved
//! `x0 y0 x1 y1 ...`. Q4 and Pian-Sumihara take the 4 corners; the hybrid element takes 4 to 6
//! nodes (corners plus mid-side nodes on straight edges, in boundary order). Element dofs are
//! `u0 v0 u1 v1 ...` in the same node order; element matrices are `2n x 2n`, row-major.
//!
//! # Axisymmetric analysis
//! With a `HYCON_AXISYMMETRIC` material, `x` is the radius `r >= 0` and `y` the axial
//! coordinate `z`; dofs are `u_r u_z` per node. Every integral is weighted by `2 pi r`: element
//! matrices, loads and reactions are for the full circle (a nodal force is the force summed
//! over the circumference). The thickness must be 1. Stresses have 4 components
//! `{sigma_r, sigma_z, tau_rz, sigma_theta}` (`hycon_element_stress`); edge tractions are the
//! meridian components `{t_r, t_z}`.

use crate::element::{self, Formulation};
use crate::error::{Error, ShapeError};
use crate::material::{Analysis, Material};
use std::cell::{Cell, RefCell};
use std::ffi::c_char;
use std::panic::{AssertUnwindSafe, catch_unwind};

mod contact;
mod elements;
mod loads;
mod results;
mod solid;
mod solid_contact;
mod solid_host;

pub use contact::*;
pub use elements::*;
pub use loads::*;
pub use solid::*;
pub use solid_contact::*;
pub use solid_host::*;

// ------------------------------------------------------------------------------------------
// Version

/// Parse a decimal version component at compile time.
const fn parse_component(s: &str) -> i32 {
    let b = s.as_bytes();
    assert!(!b.is_empty(), "empty version component");
    let mut v = 0i32;
    let mut i = 0;
    while i < b.len() {
        assert!(b[i].is_ascii_digit(), "version component is not a number");
        v = v * 10 + (b[i] - b'0') as i32;
        i += 1;
    }
    v
}

/// Major version of the library this header belongs to (from `Cargo.toml`).
pub const HYCON_VERSION_MAJOR: i32 = 0;
/// Minor version of the library this header belongs to.
pub const HYCON_VERSION_MINOR: i32 = 13;
/// Patch version of the library this header belongs to.
pub const HYCON_VERSION_PATCH: i32 = 0;
/// The version as one number, `MAJOR * 10000 + MINOR * 100 + PATCH`, for `#if` tests.
pub const HYCON_VERSION: i32 = 1300;

// The literals above are what cbindgen can put into the header; `version_checks` (evaluated at
// compile time in `hycon_version`) compares them with the single source, `version` in
// Cargo.toml.
#[allow(clippy::assertions_on_constants)] // compile-time checks are the point
const fn version_checks() {
    assert!(HYCON_VERSION_MAJOR == parse_component(env!("CARGO_PKG_VERSION_MAJOR")));
    assert!(HYCON_VERSION_MINOR == parse_component(env!("CARGO_PKG_VERSION_MINOR")));
    assert!(HYCON_VERSION_PATCH == parse_component(env!("CARGO_PKG_VERSION_PATCH")));
    assert!(HYCON_VERSION_MINOR < 100 && HYCON_VERSION_PATCH < 100);
    assert!(
        HYCON_VERSION
            == HYCON_VERSION_MAJOR * 10000 + HYCON_VERSION_MINOR * 100 + HYCON_VERSION_PATCH
    );
}

// ------------------------------------------------------------------------------------------
// Status codes

/// Result of every status-returning function: `0` OK, `< 0` error, `> 0` warning.
pub type HyconStatus = i32;

/// Success.
pub const HYCON_OK: HyconStatus = 0;
/// A required pointer argument is NULL (or an array pointer is NULL with a nonzero length).
pub const HYCON_ERROR_NULL_POINTER: HyconStatus = -1;
/// An argument is out of range: unknown enum value, wrong length or index, a non-finite double,
/// a misaligned pointer.
pub const HYCON_ERROR_INVALID_ARGUMENT: HyconStatus = -2;
/// The material is invalid: `E <= 0`, `nu` outside `(-1, 0.5)`, `t <= 0`, non-finite values,
/// unknown analysis type, axisymmetric with `t != 1`, a model mixing analysis kinds.
pub const HYCON_ERROR_INVALID_MATERIAL: HyconStatus = -3;
/// An element has a bad shape or node count: degenerate (zero area, coincident nodes),
/// inverted (clockwise), non-convex, or a node count the formulation does not take; in
/// axisymmetry also a node at `x = r < 0` or a formulation / node count not available there.
/// The message names the element (its index when the call handles a mesh) and the defect.
pub const HYCON_ERROR_BAD_ELEMENT: HyconStatus = -4;
/// A global system is singular (a body not held against rigid motion).
pub const HYCON_ERROR_SINGULAR: HyconStatus = -5;
/// A linear solver failed for a numerical reason.
pub const HYCON_ERROR_SOLVER: HyconStatus = -6;
/// An output buffer is shorter than required; the message states the length needed.
pub const HYCON_ERROR_BUFFER_TOO_SMALL: HyconStatus = -7;
/// A contact increment failed, after the automatic cutback (no convergence, cycling contact set,
/// a surface pushed through the other or beyond what the pairing sees, at any depth and any
/// magnitude, contact reaching the end of a surface); the last converged state is kept.
pub const HYCON_ERROR_CONTACT: HyconStatus = -8;
/// A caller-supplied callback (solve or monitor) returned a nonzero status or non-finite
/// values; the last converged state is kept.
pub const HYCON_ERROR_CALLBACK: HyconStatus = -9;
/// Internal error: a Rust panic was caught at the boundary. Please report it with the message.
pub const HYCON_ERROR_PANIC: HyconStatus = -99;
/// Warning: a brick is distorted beyond the strict shape policy (a Jacobian not positive at a
/// corner, or a face warped beyond 45 degrees) but its Jacobian is positive at every
/// integration point, so the results were computed and written (see `HyconShapePolicy`). The
/// message names the corner or face and the measure. A host that tests `status != HYCON_OK`
/// rejects such bricks as 0.8 did; one that tests `status < 0` accepts them.
pub const HYCON_WARNING_SHAPE: HyconStatus = 1;

// ------------------------------------------------------------------------------------------
// Enumerations passed as integers (a C enum value outside the Rust enum would be undefined
// behaviour, so they cross as `int32_t` and are checked). Zero is never valid, so a zeroed
// struct is rejected.

/// Element formulation selector, one of the `HYCON_ELEMENT_*` values.
pub type HyconElementKind = i32;
/// Assumed-stress hybrid element (7 stress parameters; 12 for 6 nodes), 4 to 6 nodes.
pub const HYCON_ELEMENT_HYBRID: HyconElementKind = 1;
/// Pian-Sumihara 5-beta hybrid quadrilateral, 4 nodes.
pub const HYCON_ELEMENT_PIAN_SUMIHARA: HyconElementKind = 2;
/// Bilinear displacement quadrilateral with 2x2 Gauss integration, 4 nodes.
pub const HYCON_ELEMENT_Q4: HyconElementKind = 3;

/// Two-dimensional idealisation, one of `HYCON_PLANE_STRAIN`, `HYCON_PLANE_STRESS`,
/// `HYCON_AXISYMMETRIC`. One model (and one host) uses one kind.
pub type HyconAnalysis = i32;
/// Plane strain (`eps_z = 0`).
pub const HYCON_PLANE_STRAIN: HyconAnalysis = 1;
/// Plane stress (`sigma_z = 0`).
pub const HYCON_PLANE_STRESS: HyconAnalysis = 2;
/// Axisymmetric: a solid of revolution about the y axis, `x = r >= 0` (radial), `y = z`
/// (axial), no torsion. Strains `{eps_r, eps_z, gamma_rz, eps_theta = u_r / r}`, stresses
/// `{sigma_r, sigma_z, tau_rz, sigma_theta}`. **Measure: the full circle**: every volume and
/// surface integral is weighted by `2 pi r` (element matrices, loads, reactions, contact forces,
/// energies), so a nodal force is the force summed over the whole circumference. The thickness
/// must be exactly 1. Elements: the hybrid element (4 nodes, 7 stress parameters) and Q4;
/// Pian-Sumihara and the 5- and 6-node transition elements are rejected
/// (`HYCON_ERROR_BAD_ELEMENT`). Prescribe `u_r = 0` at nodes on the axis.
pub const HYCON_AXISYMMETRIC: HyconAnalysis = 3;

/// Largest node count of one element.
pub const HYCON_MAX_NODES: usize = 6;
/// Largest dof count of one element (`2 * HYCON_MAX_NODES`).
pub const HYCON_MAX_DOF: usize = 12;
/// Largest number of stress parameters of one element.
pub const HYCON_MAX_BETA: usize = 12;

#[allow(clippy::assertions_on_constants)] // compile-time checks are the point
const fn size_checks() {
    assert!(HYCON_MAX_NODES == element::MAX_NODES);
    assert!(HYCON_MAX_DOF == element::MAX_DOF);
    assert!(HYCON_MAX_BETA == element::MAX_BETA);
}

/// Isotropic linear elastic material.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HyconMaterial {
    /// Young's modulus `E > 0`, within [1e-100, 1e100] (choose units accordingly).
    pub youngs: f64,
    /// Poisson's ratio, `-1 < nu < 0.5`.
    pub poisson: f64,
    /// Thickness `t > 0`, within [1e-100, 1e100] (plane strain: the depth results are reported
    /// per, usually 1); exactly 1 in axisymmetry (the measure is `2 pi r`).
    pub thickness: f64,
    /// `HYCON_PLANE_STRAIN`, `HYCON_PLANE_STRESS` or `HYCON_AXISYMMETRIC`.
    pub analysis: HyconAnalysis,
}

// ------------------------------------------------------------------------------------------
// The boundary: errors, last error message, panics

/// A failure on its way to the C caller: a status and a message.
#[derive(Debug)]
struct Fail {
    status: HyconStatus,
    message: String,
}

impl Fail {
    fn new(status: HyconStatus, message: impl Into<String>) -> Self {
        Fail {
            status,
            message: message.into(),
        }
    }
    fn invalid(message: impl Into<String>) -> Self {
        Fail::new(HYCON_ERROR_INVALID_ARGUMENT, message)
    }
}

/// The status a core error maps to. Deliberately exhaustive: a new `Error` variant needs a
/// decision about its C status code here (and in `hycon_status_name` and the header).
fn status_of(error: &Error) -> HyconStatus {
    match error {
        Error::Element {
            kind: ShapeError::NonFinite,
            ..
        } => HYCON_ERROR_INVALID_ARGUMENT,
        Error::Element { .. } => HYCON_ERROR_BAD_ELEMENT,
        Error::Material(_) => HYCON_ERROR_INVALID_MATERIAL,
        Error::InvalidInput(_) => HYCON_ERROR_INVALID_ARGUMENT,
        Error::Singular(_) => HYCON_ERROR_SINGULAR,
        Error::Solver(_) => HYCON_ERROR_SOLVER,
        Error::Contact(_) => HYCON_ERROR_CONTACT,
        Error::Callback(_) => HYCON_ERROR_CALLBACK,
    }
}

impl From<Error> for Fail {
    fn from(error: Error) -> Self {
        let message = match &error {
            // a single-element call: the function name already says which element
            Error::Element {
                element: None,
                kind,
            } => kind.to_string(),
            e => e.to_string(),
        };
        Fail::new(status_of(&error), message)
    }
}

impl From<ShapeError> for Fail {
    fn from(kind: ShapeError) -> Self {
        Error::from(kind).into()
    }
}

thread_local! {
    /// Message of the last status-returning call on this thread: its failure, or empty after a
    /// success (see `hycon_last_error_message`).
    static LAST_ERROR: RefCell<String> = const { RefCell::new(String::new()) };
    /// How many [`boundary`] frames are active on this thread (panics inside are silent).
    static BOUNDARY_DEPTH: Cell<u32> = const { Cell::new(0) };
    /// Message and location of the last panic caught inside a boundary, set by the hook.
    static PANIC_MESSAGE: RefCell<String> = const { RefCell::new(String::new()) };
}

fn set_last_error(message: &str) {
    // `try_with`: during thread teardown the slot may be gone; then there is nobody to read it.
    let _ = LAST_ERROR.try_with(|m| {
        if let Ok(mut m) = m.try_borrow_mut() {
            m.clear();
            m.push_str(message);
        }
    });
}

fn payload_text(payload: &(dyn std::any::Any + Send)) -> &str {
    if let Some(s) = payload.downcast_ref::<&str>() {
        s
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s
    } else {
        "(non-string panic payload)"
    }
}

/// Install, once per process, a panic hook that is silent for panics inside [`boundary`] (it
/// records message and location for [`hycon_last_error_message`] instead of printing them to
/// the host's stderr) and hands every other panic to the previously installed hook.
///
/// In a C host the cdylib / staticlib carries its own copy of the Rust standard library, so this
/// hook only ever sees hycon's own panics. A Rust program linking the rlib shares the hook; its
/// own panics still reach its previous hook unchanged.
fn install_panic_hook() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            let inside = BOUNDARY_DEPTH.try_with(|d| d.get() > 0).unwrap_or(false);
            if !inside {
                previous(info);
                return;
            }
            let text = payload_text(info.payload());
            let message = match info.location() {
                Some(l) => format!("{text} (at {}:{})", l.file(), l.line()),
                None => text.to_string(),
            };
            let _ = PANIC_MESSAGE.try_with(|m| {
                if let Ok(mut m) = m.try_borrow_mut() {
                    *m = message;
                }
            });
        }));
    });
}

/// A warning on its way to the C caller: the call succeeded, its outputs are written; a
/// positive status and a message.
#[derive(Debug)]
struct Warning {
    status: HyconStatus,
    message: String,
}

/// Run one exported function's body: catch panics, map `Err` to its status and store the
/// message (prefixed with `function`) as this thread's last error; on success clear it.
fn boundary(function: &'static str, body: impl FnOnce() -> Result<(), Fail>) -> HyconStatus {
    boundary_warning(function, || body().map(|()| None))
}

/// [`boundary`] for a body that may succeed with a [`Warning`]: its status is returned and its
/// message (prefixed with `function` and `warning:`) becomes this thread's last error.
fn boundary_warning(
    function: &'static str,
    body: impl FnOnce() -> Result<Option<Warning>, Fail>,
) -> HyconStatus {
    install_panic_hook();
    BOUNDARY_DEPTH.with(|d| d.set(d.get() + 1));
    let result = catch_unwind(AssertUnwindSafe(body));
    BOUNDARY_DEPTH.with(|d| d.set(d.get() - 1));
    match result {
        Ok(Ok(None)) => {
            set_last_error("");
            HYCON_OK
        }
        Ok(Ok(Some(warning))) => {
            set_last_error(&format!("{function}: warning: {}", warning.message));
            warning.status
        }
        Ok(Err(fail)) => {
            set_last_error(&format!("{function}: {}", fail.message));
            fail.status
        }
        Err(payload) => {
            let recorded = PANIC_MESSAGE
                .try_with(|m| m.try_borrow_mut().map(|mut m| std::mem::take(&mut *m)))
                .ok()
                .and_then(Result::ok)
                .filter(|m| !m.is_empty());
            let text = recorded.unwrap_or_else(|| payload_text(&*payload).to_string());
            set_last_error(&format!("{function}: internal error (Rust panic): {text}"));
            HYCON_ERROR_PANIC
        }
    }
}

// ------------------------------------------------------------------------------------------
// Argument checks (safe wrappers around the raw-pointer reads and writes)

fn formulation(kind: HyconElementKind) -> Result<Formulation, Fail> {
    match kind {
        HYCON_ELEMENT_HYBRID => Ok(Formulation::Hybrid),
        HYCON_ELEMENT_PIAN_SUMIHARA => Ok(Formulation::PianSumihara),
        HYCON_ELEMENT_Q4 => Ok(Formulation::Q4),
        _ => Err(Fail::invalid(format!(
            "unknown element kind {kind} (expected HYCON_ELEMENT_HYBRID = 1, \
             HYCON_ELEMENT_PIAN_SUMIHARA = 2 or HYCON_ELEMENT_Q4 = 3)"
        ))),
    }
}

/// Check that `n_nodes` suits `f` before any coordinate is read.
fn node_count(f: Formulation, n_nodes: usize) -> Result<usize, Fail> {
    if f.accepts(n_nodes) {
        Ok(n_nodes)
    } else {
        let expected = match f {
            Formulation::Hybrid => "4 to 6",
            Formulation::PianSumihara | Formulation::Q4 => "4",
        };
        Err(ShapeError::NodeCount {
            got: n_nodes,
            expected,
        }
        .into())
    }
}

/// The one pointer rule, for required and optional pointers alike: NULL is
/// `HYCON_ERROR_NULL_POINTER` when `required` and "absent" (`Ok(false)`) otherwise; a non-NULL
/// pointer not aligned for `T` is `HYCON_ERROR_INVALID_ARGUMENT` naming the argument.
fn pointer<T>(ptr: *const T, name: &str, required: bool) -> Result<bool, Fail> {
    if ptr.is_null() {
        if required {
            Err(Fail::new(
                HYCON_ERROR_NULL_POINTER,
                format!("{name} is NULL"),
            ))
        } else {
            Ok(false)
        }
    } else if !ptr.is_aligned() {
        Err(Fail::invalid(format!("{name} is misaligned")))
    } else {
        Ok(true)
    }
}

/// A required pointer argument: non-NULL and aligned ([`pointer()`]).
fn check_pointer<T>(ptr: *const T, name: &str) -> Result<(), Fail> {
    pointer(ptr, name, true).map(|_| ())
}

/// An optional output (NULL: not wanted), checked by [`pointer()`] before any work is done so
/// that a bad one fails the call with nothing written; write it with [`put`].
fn optional<T>(ptr: *mut T, name: &str) -> Result<Option<*mut T>, Fail> {
    Ok(pointer(ptr.cast_const(), name, false)?.then_some(ptr))
}

/// Write an output checked by [`optional`].
///
/// # Safety
/// The pointer, if any, must be writable for one `T`.
unsafe fn put<T>(out: Option<*mut T>, value: T) {
    if let Some(ptr) = out {
        // SAFETY: non-null and aligned (checked by `optional`), writable (contract).
        unsafe { ptr.write(value) };
    }
}

/// Write one value to a required output pointer.
///
/// # Safety
/// `ptr` must be NULL or point to a writable `T`.
unsafe fn write<T>(ptr: *mut T, value: T, name: &str) -> Result<(), Fail> {
    check_pointer(ptr.cast_const(), name)?;
    // SAFETY: non-null, aligned (checked) and writable (contract).
    unsafe { ptr.write(value) };
    Ok(())
}

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

/// [`slice()`] of doubles, checked finite.
///
/// # Safety
/// As [`slice()`].
unsafe fn doubles<'a>(ptr: *const f64, len: usize, name: &str) -> Result<&'a [f64], Fail> {
    // SAFETY: forwarded contract.
    let values = unsafe { slice(ptr, len, name)? };
    check_finite(values, name)?;
    Ok(values)
}

/// `count * per + extra`, the length of an array sized by another argument, or an error naming
/// `name` when it overflows.
fn length(count: usize, per: usize, extra: usize, name: &str) -> Result<usize, Fail> {
    count
        .checked_mul(per)
        .and_then(|n| n.checked_add(extra))
        .ok_or_else(|| Fail::invalid(format!("{name} = {count} is too large")))
}

/// A handle (or input struct) argument as a shared reference.
///
/// # Safety
/// `ptr` must be NULL or point to a live, readable `T` (a handle from the matching `_new`).
unsafe fn handle<'a, T>(ptr: *const T, name: &str) -> Result<&'a T, Fail> {
    check_pointer(ptr, name)?;
    // SAFETY: non-null, aligned, and live (caller contract).
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

/// The one size convention of every function that fills a variable-length array
/// `(out, len, needed)`:
/// * `needed` (optional, checked by [`optional`]) receives `count`, the element count of the
///   full result, on success and on `HYCON_ERROR_BUFFER_TOO_SMALL`;
/// * `out == NULL && len == 0` is the size query: `HYCON_OK`, nothing else written, and
///   `values` is not evaluated;
/// * `out == NULL` with `len > 0` is `HYCON_ERROR_NULL_POINTER`; a misaligned `out` is
///   `HYCON_ERROR_INVALID_ARGUMENT`;
/// * `len < count` is `HYCON_ERROR_BUFFER_TOO_SMALL`, the count in the message, `out` untouched;
/// * otherwise exactly `count` elements are written (the rest of `out` is untouched).
///
/// # Safety
/// `out` must be NULL or point to `len` writable `T`; `needed` NULL or a writable `size_t`.
unsafe fn fill<T: Copy>(
    out: *mut T,
    len: usize,
    needed: *mut usize,
    name: &str,
    count: usize,
    values: impl FnOnce() -> Result<Vec<T>, Fail>,
) -> Result<(), Fail> {
    let needed = optional(needed, "needed")?;
    if out.is_null() && len == 0 {
        // SAFETY: checked by `optional`; writable (contract).
        unsafe { put(needed, count) };
        return Ok(());
    }
    if out.is_null() {
        return Err(Fail::new(
            HYCON_ERROR_NULL_POINTER,
            format!("{name} is NULL but len is {len} (NULL and 0 ask for the size)"),
        ));
    }
    check_pointer(out.cast_const(), name)?;
    if len < count {
        // SAFETY: as above.
        unsafe { put(needed, count) };
        return Err(Fail::new(
            HYCON_ERROR_BUFFER_TOO_SMALL,
            format!("{name} has length {len}, {count} needed"),
        ));
    }
    let values = values()?;
    assert_eq!(
        values.len(),
        count,
        "{name}: result length differs from its count"
    );
    // SAFETY: `out` is non-null, aligned and writable for `len >= count` values (checked and
    // contract); `values` is our own memory.
    unsafe {
        std::ptr::copy_nonoverlapping(values.as_ptr(), out, count);
        put(needed, count);
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

fn check_finite(values: &[f64], name: &str) -> Result<(), Fail> {
    match values.iter().position(|v| !v.is_finite()) {
        None => Ok(()),
        Some(i) => Err(Fail::invalid(format!(
            "{name}[{i}] = {} is not finite",
            values[i]
        ))),
    }
}

fn check_finite_scalar(value: f64, name: &str) -> Result<(), Fail> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(Fail::invalid(format!("{name} = {value} is not finite")))
    }
}

/// Copy `N <= dst.len()` doubles from a caller array into `dst` and check they are finite.
///
/// # Safety
/// If `ptr` is non-null it must point to at least `dst.len()` readable doubles.
unsafe fn read_doubles(ptr: *const f64, dst: &mut [f64], name: &str) -> Result<(), Fail> {
    check_pointer(ptr, name)?;
    // SAFETY: non-null and aligned (checked); the caller guarantees `dst.len()` readable
    // doubles. `dst` is our own local buffer, so the regions cannot overlap.
    unsafe { std::ptr::copy_nonoverlapping(ptr, dst.as_mut_ptr(), dst.len()) };
    check_finite(dst, name)
}

/// Read `n` interleaved node coordinates.
///
/// # Safety
/// If `coords` is non-null it must point to `2 n` readable doubles.
unsafe fn read_coords(
    coords: *const f64,
    n: usize,
) -> Result<[[f64; 2]; element::MAX_NODES], Fail> {
    let mut flat = [0.0; element::MAX_DOF];
    // SAFETY: forwarded contract; `n <= MAX_NODES` was checked by `node_count`.
    unsafe { read_doubles(coords, &mut flat[..2 * n], "coords")? };
    let mut out = [[0.0; 2]; element::MAX_NODES];
    for (p, xy) in out.iter_mut().zip(flat.chunks_exact(2)) {
        *p = [xy[0], xy[1]];
    }
    Ok(out)
}

/// Read and validate a material.
///
/// # Safety
/// If `m` is non-null it must point to a readable `HyconMaterial`.
unsafe fn read_material(m: *const HyconMaterial) -> Result<Material, Fail> {
    check_pointer(m, "material")?;
    // SAFETY: non-null and aligned (checked); the caller guarantees a readable struct of
    // plain doubles and an int32_t (every bit pattern is valid).
    let m = unsafe { m.read() };
    let analysis = analysis_from_c(m.analysis).ok_or_else(|| {
        Fail::new(
            HYCON_ERROR_INVALID_MATERIAL,
            format!("invalid material: {}", unknown_analysis(m.analysis)),
        )
    })?;
    Ok(Material::new(m.youngs, m.poisson, m.thickness, analysis)?)
}

/// The analysis kind of a C `HyconAnalysis` value (`None`: unknown).
pub(crate) fn analysis_from_c(a: HyconAnalysis) -> Option<Analysis> {
    match a {
        HYCON_PLANE_STRAIN => Some(Analysis::PlaneStrain),
        HYCON_PLANE_STRESS => Some(Analysis::PlaneStress),
        HYCON_AXISYMMETRIC => Some(Analysis::Axisymmetric),
        _ => None,
    }
}

/// The message for an unknown `HyconAnalysis` value.
pub(crate) fn unknown_analysis(a: HyconAnalysis) -> String {
    format!(
        "unknown analysis {a} (expected HYCON_PLANE_STRAIN = 1, HYCON_PLANE_STRESS = 2 or \
         HYCON_AXISYMMETRIC = 3)"
    )
}

/// Check a fixed-size output `(ptr, len)` (its size stated by the function's other
/// arguments, `size > 0`) can take `size` values: the same pointer rule, `len < size` is
/// `HYCON_ERROR_BUFFER_TOO_SMALL` (`(NULL, 0)` is an empty array, so too small).
fn check_output<T>(ptr: *mut T, len: usize, size: usize, name: &str) -> Result<(), Fail> {
    pointer(ptr.cast_const(), name, len > 0)?;
    if len < size {
        return Err(Fail::new(
            HYCON_ERROR_BUFFER_TOO_SMALL,
            format!("{name} has length {len}, {size} needed"),
        ));
    }
    Ok(())
}

/// Copy `src` to a caller array.
///
/// # Safety
/// `dst` must have been checked with [`check_output`] or [`check_pointer`] and be writable for
/// `src.len()` values.
unsafe fn write_doubles(dst: *mut f64, src: &[f64]) {
    // SAFETY: `dst` is non-null, aligned and writable for `src.len()` doubles (caller
    // contract); `src` is our own local storage, so the regions do not overlap.
    unsafe { std::ptr::copy_nonoverlapping(src.as_ptr(), dst, src.len()) };
}

// ------------------------------------------------------------------------------------------
// Exported functions

/// Write the library's version `{major, minor, patch}` to `out` (3 values). Compare with the
/// header's `HYCON_VERSION_MAJOR` etc. to detect a header / library mismatch.
///
/// Errors: `HYCON_ERROR_NULL_POINTER` if `out` is NULL.
///
/// # Safety
/// `out` must be NULL or point to 3 writable `int32_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_version(out: *mut i32) -> HyconStatus {
    // Compile-time checks of the header constants, inside a function body where cbindgen does
    // not look: a failed check fails the build.
    const {
        version_checks();
        size_checks();
    };
    boundary("hycon_version", || {
        check_pointer(out.cast_const(), "out")?;
        let v = [
            parse_component(env!("CARGO_PKG_VERSION_MAJOR")),
            parse_component(env!("CARGO_PKG_VERSION_MINOR")),
            parse_component(env!("CARGO_PKG_VERSION_PATCH")),
        ];
        // SAFETY: `out` is non-null and aligned (checked), writable for 3 values (contract);
        // `v` is local.
        unsafe { std::ptr::copy_nonoverlapping(v.as_ptr(), out, 3) };
        Ok(())
    })
}

/// Copy this thread's last error message into `buf` and return the length it needs, including
/// the terminating NUL.
///
/// What the message is: every function that returns a `HyconStatus` sets it when it returns,
/// to `"<function name>: <description>"` when it fails (a negative status), to
/// `"<function name>: warning: <description>"` for a warning (a positive status) and to the
/// empty string when it succeeds. So it describes the last status-returning call on this thread,
/// and is empty (return value 1) unless that call failed or warned. This function, `hycon_status_name` and
/// the `_free` functions do not change it. It is thread-local: a call on another thread never
/// changes it.
///
/// At most `len - 1` bytes plus a NUL are written (nothing if `buf` is NULL or `len` is 0), so
/// `hycon_last_error_message(NULL, 0)` asks for the size and a return value greater than `len`
/// means the copy was truncated (at a UTF-8 character boundary).
///
/// # Safety
/// `buf` must be NULL or point to `len` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hycon_last_error_message(buf: *mut c_char, len: usize) -> usize {
    let copy = |message: &str| -> usize {
        let needed = message.len() + 1;
        if buf.is_null() || len == 0 {
            return needed;
        }
        let mut n = message.len().min(len - 1);
        while !message.is_char_boundary(n) {
            n -= 1; // do not cut a UTF-8 sequence
        }
        // SAFETY: `buf` is non-null and writable for `len > n` bytes (caller contract); the
        // message is our own storage.
        unsafe {
            std::ptr::copy_nonoverlapping(message.as_ptr().cast::<c_char>(), buf, n);
            buf.add(n).write(0);
        }
        needed
    };
    LAST_ERROR
        .try_with(|m| match m.try_borrow() {
            Ok(m) => copy(&m),
            Err(_) => copy(""),
        })
        .unwrap_or_else(|_| copy(""))
}

/// A static, NUL-terminated name for a status code (`"HYCON_OK"`, `"HYCON_ERROR_NULL_POINTER"`,
/// ..., `"HYCON_WARNING_SHAPE"`, `"HYCON_WARNING"` for any other positive value,
/// `"HYCON_ERROR_UNKNOWN"` otherwise). The
/// string is owned by the library and valid for the life of the process; do not free it.
#[unsafe(no_mangle)]
pub extern "C" fn hycon_status_name(status: HyconStatus) -> *const c_char {
    let name = match status {
        HYCON_OK => c"HYCON_OK",
        HYCON_ERROR_NULL_POINTER => c"HYCON_ERROR_NULL_POINTER",
        HYCON_ERROR_INVALID_ARGUMENT => c"HYCON_ERROR_INVALID_ARGUMENT",
        HYCON_ERROR_INVALID_MATERIAL => c"HYCON_ERROR_INVALID_MATERIAL",
        HYCON_ERROR_BAD_ELEMENT => c"HYCON_ERROR_BAD_ELEMENT",
        HYCON_ERROR_SINGULAR => c"HYCON_ERROR_SINGULAR",
        HYCON_ERROR_SOLVER => c"HYCON_ERROR_SOLVER",
        HYCON_ERROR_BUFFER_TOO_SMALL => c"HYCON_ERROR_BUFFER_TOO_SMALL",
        HYCON_ERROR_CONTACT => c"HYCON_ERROR_CONTACT",
        HYCON_ERROR_CALLBACK => c"HYCON_ERROR_CALLBACK",
        HYCON_ERROR_PANIC => c"HYCON_ERROR_PANIC",
        HYCON_WARNING_SHAPE => c"HYCON_WARNING_SHAPE",
        s if s > 0 => c"HYCON_WARNING",
        _ => c"HYCON_ERROR_UNKNOWN",
    };
    name.as_ptr()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An analysis may be shared between threads for the const queries (a host description
    /// holds the host's callback data and is only moved).
    #[test]
    fn handles_are_send_and_sync() {
        fn check<T: Send + Sync>() {}
        fn send<T: Send>() {}
        check::<HyconContact>();
        check::<HyconModel>();
        send::<HyconHost>();
    }

    fn last_error() -> String {
        let mut buf = vec![0 as c_char; 512];
        // SAFETY: `buf` holds 512 writable bytes.
        unsafe { hycon_last_error_message(buf.as_mut_ptr(), buf.len()) };
        let bytes: Vec<u8> = buf
            .iter()
            .take_while(|&&c| c != 0)
            .map(|&c| c as u8)
            .collect();
        String::from_utf8(bytes).unwrap()
    }

    /// Run in a child process by `panic_becomes_status_quietly` (a no-op otherwise): a panic
    /// inside the boundary becomes `HYCON_ERROR_PANIC` with its message, and the library keeps
    /// working. Prints what the parent checks.
    #[test]
    fn panic_child() {
        if std::env::var_os("HYCON_PANIC_CHILD").is_none() {
            return;
        }
        let status = boundary("hycon_test_panic", || {
            panic!("deliberate panic for testing the C boundary")
        });
        println!("status {status}");
        println!("message {}", last_error());
        let mut v = [0i32; 3];
        // SAFETY: `v` holds 3 writable values.
        println!("after {}", unsafe { hycon_version(v.as_mut_ptr()) });
    }

    /// Panics never cross the boundary and are not printed: the child's stderr stays empty
    /// (the test harness runs it with `--nocapture`, so a printing hook would show there).
    #[test]
    fn panic_becomes_status_quietly() {
        let output = std::process::Command::new(std::env::current_exe().unwrap())
            .args([
                "--exact",
                "ffi::tests::panic_child",
                "--nocapture",
                "--test-threads=1",
            ])
            .env("HYCON_PANIC_CHILD", "1")
            .env("RUST_BACKTRACE", "0")
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&output.stdout);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(output.status.success(), "{stdout}\n{stderr}");
        assert!(
            stdout.contains(&format!("status {HYCON_ERROR_PANIC}")),
            "{stdout}"
        );
        assert!(
            stdout.contains(
                "message hycon_test_panic: internal error (Rust panic): deliberate panic for \
                 testing the C boundary (at src/ffi/mod.rs:"
            ),
            "{stdout}"
        );
        assert!(stdout.contains(&format!("after {HYCON_OK}")), "{stdout}");
        assert!(!stderr.contains("panicked"), "{stderr}");
        assert!(!stderr.contains("deliberate panic"), "{stderr}");
    }

    /// A panic outside any boundary still reaches the previously installed hook.
    #[test]
    fn panics_outside_the_boundary_reach_the_previous_hook() {
        install_panic_hook();
        let outside = std::panic::catch_unwind(|| panic!("outside the boundary"));
        assert!(outside.is_err());
    }
}
