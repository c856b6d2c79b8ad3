/* SPDX-License-Identifier: MIT */
/*
 * hycon: assumed-stress hybrid finite elements for plane elasticity, C API.
 *
 * Contents
 * - Element routines (hycon_element_*): stiffness, stress recovery, edge tractions.
 * - 3D element routines (hycon_brick_*): the 18-beta hybrid brick and the H8 brick for 3D
 *   hosts: shape check, stiffness, stress parameters, stress at points, face tractions
 *   (node and face numbering at HyconBrickKind).
 * - Load and check routines for every element kind: consistent nodal forces of a pressure or
 *   traction on an edge or face (hycon_element_edge_load, hycon_brick_face_load), volume and
 *   scaled Jacobian (hycon_element_volume / _quality, hycon_brick_volume / _quality), stress at
 *   natural coordinates (hycon_element_stress_natural, hycon_brick_stress_natural).
 * - Contact, two ways in, one analysis handle (HyconContact, hycon_contact_*):
 *   model API: describe the mesh in a HyconModel (hycon_model_*), hycon assembles and factors;
 *   host-assembly API: describe the contact polylines in a HyconHost (hycon_host_*) and give
 *   the stiffness as CSR or a solve callback (the host's own factorization; the path for
 *   distributed hosts such as PETSc over MPI).
 *
 * Conventions
 * - Prefix: every symbol starts with hycon_ (functions), Hycon (types) or HYCON_ (constants).
 * - Status codes: every function except the few that return a length or a string returns a
 *   HyconStatus: 0 (HYCON_OK) on success, < 0 (HYCON_ERROR_*) on failure, > 0 a warning (the
 *   call succeeded and wrote its outputs; 1..99 reserved, none produced yet).
 *   Every status-returning call sets this thread's error message: to a description of the
 *   failure when it fails, to the empty string when it succeeds (see
 *   hycon_last_error_message, which copies it; it, hycon_status_name and the _free functions
 *   leave it unchanged). hycon_status_name(status) gives the constant's name as a static string.
 * - Input arrays are (pointer, length) pairs, or a pointer whose length is fixed by other
 *   arguments (stated per function). (NULL, 0) is an empty array. Inputs that travel together
 *   come as small view structs (HyconElementBlock, HyconPolyline, HyconHostNodes), in one
 *   order wherever a mesh is given: nodes, elements, materials.
 * - Size convention: every function that fills a variable-length array takes
 *   (T *out, size_t len, size_t *needed), len counted in elements of T:
 *   - needed (may be NULL) receives the element count of the full result, on success and on
 *     HYCON_ERROR_BUFFER_TOO_SMALL;
 *   - out == NULL && len == 0 is the size query: HYCON_OK, only *needed is written;
 *   - out == NULL with len > 0 is HYCON_ERROR_NULL_POINTER;
 *   - len < needed (out non-NULL) is HYCON_ERROR_BUFFER_TOO_SMALL, the count in the message,
 *     out untouched;
 *   - len >= needed writes exactly needed elements (the rest of out is untouched).
 *   So: hycon_X(..., NULL, 0, &n); allocate n; hycon_X(..., buf, n, NULL).
 * - Pointers: a NULL required pointer is HYCON_ERROR_NULL_POINTER; a NULL optional one (stated
 *   per function) means "not wanted". Any non-NULL pointer, required or optional, input or
 *   output, that is not aligned for its type is HYCON_ERROR_INVALID_ARGUMENT naming it.
 * - Outputs are written only on success; on an error every output is left untouched (the one
 *   exception: *needed on HYCON_ERROR_BUFFER_TOO_SMALL).
 * - Ownership: the caller owns all memory it passes; the library never frees a caller pointer.
 * - Thread safety: the element routines are reentrant and thread-safe; the last error message
 *   is thread-local. A function taking a non-const handle (HyconModel *, HyconHost *,
 *   HyconContact *) needs it exclusively: no other call on that handle at the same time.
 *   Functions taking a const handle (every result query of a HyconContact) may run on one
 *   handle from several threads at once (solves for displacement recovery are serialized
 *   inside, so a solve callback is never entered concurrently). Handles may move between
 *   threads; distinct handles share nothing. Callbacks (solve, monitor) run on the thread that
 *   called into the handle.
 * - Handles: hycon_X_new creates, hycon_X_free destroys; hycon_X_free(NULL) is a no-op. Using a
 *   handle after freeing it, or freeing it twice, is undefined behaviour (as with free()).
 * - Caller memory: arrays passed in are copied or read during the call only. The exception is
 *   documented where it applies: a solve callback's user_data and an options' monitor_data
 *   are kept (as pointers) and must outlive the handles that use them.
 * - Doubles must be finite (no NaN, no infinity); this is checked.
 * - Elements: nodes counter-clockwise, coordinates interleaved x0 y0 x1 y1 ...; element dofs
 *   u0 v0 u1 v1 ... in node order; element matrices are row-major (and symmetric).
 * - Enumerations (element kind, analysis, backend, directions, ...) are int32_t values; 0 is
 *   never valid as an input.
 * - Rust panics never cross this API: they become HYCON_ERROR_PANIC with a message.
 */

#ifndef HYCON_H
#define HYCON_H

/* Generated by cbindgen 0.29.4 from the crate (src/ffi/). Do not edit: run `cbindgen --config cbindgen.toml --crate hycon --output include/hycon.h` or `HYCON_BLESS=1 cargo test --test integration header_fresh::`. */

#include <stdint.h>
#include <stddef.h>

// Major version of the library this header belongs to (from `Cargo.toml`).
#define HYCON_VERSION_MAJOR 0

// Minor version of the library this header belongs to.
#define HYCON_VERSION_MINOR 13

// Patch version of the library this header belongs to.
#define HYCON_VERSION_PATCH 0

// The version as one number, `MAJOR * 10000 + MINOR * 100 + PATCH`, for `#if` tests.
#define HYCON_VERSION 1300

// Largest node count of one element.
#define HYCON_MAX_NODES 6

// Largest dof count of one element (`2 * HYCON_MAX_NODES`).
#define HYCON_MAX_DOF 12

// Largest number of stress parameters of one element.
#define HYCON_MAX_BETA 12

// The largest `HyconContactOptions::threads`.
#define HYCON_MAX_THREADS 256

// Equation number of a contact dof that the host holds fixed at zero (host-assembly API).
#define HYCON_FIXED -1

// The largest `HyconContactOptions::cutback_depth`.
#define HYCON_MAX_CUTBACK_DEPTH 52

// Nodes of a brick.
#define HYCON_BRICK_NODES 8

// Dofs of a brick (3 per node).
#define HYCON_BRICK_DOF 24

// Largest number of stress parameters of a brick (18, the hybrid brick's).
#define HYCON_BRICK_MAX_BETA 18

// Bit of `HyconShapeReport::warnings`: the Jacobian is not positive at corner node `corner`.
#define HYCON_SHAPE_CORNER_JACOBIAN 1

// Bit of `HyconShapeReport::warnings`: face `face` is warped by more than 45 degrees.
#define HYCON_SHAPE_WARPED_FACE 2

// A contact analysis: `K` factored once (or the host's solver), the converged state, the
// records. Create with `hycon_contact_new` (model API) or `hycon_contact_new_host`, free with
// `hycon_contact_free`. Thread safety: the functions taking `HyconContact *` (increments,
// free) need the handle exclusively; the queries taking `const HyconContact *` may run on one
// handle from several threads at once (the displacement recovery's solves are serialized by
// a lock inside, so a solve callback is never entered concurrently, though it may be entered
// from any querying thread). Distinct handles share nothing. Callbacks run on the calling
// thread.
typedef struct HyconContact HyconContact;

// A host's contact description (host-assembly API): its contact polylines and its stiffness
// (CSR), solve callback or condensed operator. Create with `hycon_host_new`, free with `hycon_host_free`.
// Thread safety: as `HyconModel`.
typedef struct HyconHost HyconHost;

// A model being described (model API): mesh, materials, prescribed directions, contact
// pairs, optional rigid plate. Create with `hycon_model_new`, free with `hycon_model_free`.
// Thread safety: a `HyconModel` may be used from any thread, but not from two at once;
// distinct models are independent.
typedef struct HyconModel HyconModel;

// A 3D contact analysis: `K` factored once (or the host's solver), the converged state, the
// records. Create with `hycon_solid_contact_new` (model API) or
// `hycon_solid_contact_new_host` (host API), free with `hycon_solid_contact_free`. Thread
// safety: as `HyconContact` (const queries may run concurrently on one handle).
typedef struct HyconSolidContact HyconSolidContact;

// A 3D host's contact description (host API): its contact nodes, face pairs, symmetry planes
// and its stiffness (CSR), solve callback or condensed operator. Create with
// `hycon_solid_host_new`, free with `hycon_solid_host_free`. Thread safety: as `HyconModel`.
typedef struct HyconSolidHost HyconSolidHost;

// A 3D model being described (model API): brick mesh, materials, prescribed directions,
// contact pairs of brick faces, symmetry planes, an optional rigid plate. Create with
// `hycon_solid_model_new`, free with `hycon_solid_model_free`. Thread safety: as
// `HyconModel`.
typedef struct HyconSolidModel HyconSolidModel;

// Result of every status-returning function: `0` OK, `< 0` error, `> 0` warning.
typedef int32_t HyconStatus;

// Sparse Cholesky library that factors `K`, one of `HYCON_BACKEND_*`.
typedef int32_t HyconBackend;

// Contact kinematics, one of `HYCON_KINEMATICS_*`.
typedef int32_t HyconKinematics;

// What happened in one iteration of the contact search (also passed to the monitor).
typedef struct HyconIterationRecord {
    // Increment number (1-based).
    size_t increment;
    // Iteration within the increment (1-based).
    size_t iteration;
    // Active (stick + slip + frictionless) A nodes in this iteration's solve.
    size_t active;
    // Stick nodes among them.
    size_t stick;
    // Slip nodes among them (frictional pairs only; frictionless nodes are neither stick nor
    // slip).
    size_t slip;
    // State changes decided after the solve.
    size_t changes;
    // Convergence measure over the contact dofs: the change of this iteration's displacement
    // relative to the increment's motion so far (bounded below by round-off, and under finite
    // kinematics by the largest motion of a converged increment); always finite.
    double r;
    // Estimated 1-norm condition number of the small contact system (1 when empty).
    double condition;
    // The worst violation of the discrete contact conditions by this iteration's solution
    // (open gaps >= 0; closed nodes in compression with closed gaps; stick nodes inside the
    // friction cone and not sliding; slip opposing the friction), relative to the problem's
    // scale (open gaps to the increment's motion, at most the mean A segment; closed gaps and
    // slips to the motion; tractions to the largest). At convergence at most 1e-4, else the
    // increment fails with `HYCON_ERROR_CONTACT`.
    double violation;
    // The sub-increment (1-based) this iteration belongs to: 1 unless the automatic cutback
    // split the increment (see `HyconContactOptions::cutback_depth`). A sub-increment that
    // fails is tried again, shorter, under the same index: the monitor sees both tries,
    // `hycon_contact_records` keeps the converged one.
    size_t sub_increment;
} HyconIterationRecord;

// Called with every iteration record, also those of the tries the automatic cutback halves
// (`record->sub_increment` says which sub-increment a record belongs to); return 0 to go on,
// nonzero to stop the increment (it then fails with `HYCON_ERROR_CALLBACK`, not retried, and
// the last converged state is kept). Called on the
// thread that called `hycon_contact_increment*`. Must not unwind (no C++ exceptions, no
// longjmp) through hycon.
typedef int32_t (*HyconMonitorFn)(void *user_data, const struct HyconIterationRecord *record);

// Parameters of the contact iteration. Get the defaults with `hycon_contact_options_default`
// (which also sets `size`), then override fields. Tolerances are relative (see each field), so
// results do not change when units are rescaled.
//
// Versioned by `size`: a host that fills the struct itself sets
// `size = sizeof(HyconContactOptions)`. hycon reads only the fields that fit in `size` and
// defaults the rest (fields are only ever added at the end), so a host built against an older
// header keeps working; a size below the 0.7.0 layout (the first with `size`), or above the
// layout this library knows, is rejected with `HYCON_ERROR_INVALID_ARGUMENT`.
typedef struct HyconContactOptions {
    // `sizeof(HyconContactOptions)` as the host was compiled (set by
    // `hycon_contact_options_default`).
    size_t size;
    // Convergence tolerance on `R` (default 1e-6; the paper used 0.01).
    double tolerance;
    // Penetration tolerance, relative to the increment's displacement scale (default 1e-9).
    double gap_tolerance;
    // Tension tolerance, relative to the largest `|tn|` (default 1e-9).
    double tension_tolerance;
    // Friction-cone tolerance, relative to `mu |tn|` (default 1e-9).
    double friction_tolerance;
    // Slip tolerance (default 1e-6): a slip node returns to stick when its slip reverses by
    // more than this, and a closing node enters in slip when it has slid more than this,
    // relative to the increment's motion (the largest motion of a contact node in this
    // increment or a converged one), so it scales with the load.
    double slip_tolerance;
    // B segments farther than this from an A segment, relative to the mean A segment length,
    // are not paired with it (default 4). The pairing reaches farther as the bodies move:
    // at least twice an increment's largest motion under finite kinematics, and under small
    // kinematics the reference pairing is widened to four times the largest displacement of
    // the pair's nodes whenever twice that exceeds it, so a finer mesh never loses contact.
    double search_distance;
    // Iteration cap per increment (default 60).
    uint32_t max_iterations;
    // Cycle policy: how many times per increment a cycling contact set is resolved by locking
    // the alternating nodes (in slip for stick/slip alternation at the friction cone, open for
    // open/closed alternation at the edge of the contact zone) before a cycle fails the
    // increment (default 3; 0 fails at the first cycle).
    uint32_t lock_rounds;
    // Sparse Cholesky library for hycon's own factorizations (default `HYCON_BACKEND_FAER`;
    // `HYCON_BACKEND_CHOLMOD` fails with `HYCON_ERROR_SOLVER` unless hycon was built with the
    // `suitesparse` feature).
    HyconBackend backend;
    // Contact kinematics (default `HYCON_KINEMATICS_SMALL`; `HYCON_KINEMATICS_FINITE` for
    // extensive sliding).
    HyconKinematics kinematics;
    // Threads the contact boundary's substitutions with hycon's own faer factor may use, 1
    // to `HYCON_MAX_THREADS` (default 1: hycon starts no thread). More share the images of new node
    // directions and each iteration's backward substitution among them, with every result
    // the same to the bit. Threads are started per call and none outlives it; a host running
    // one process per core (MPI) keeps 1.
    uint32_t threads;
    // Optional iteration monitor (NULL: none). Kept by the `HyconContact` for its lifetime.
    HyconMonitorFn monitor;
    // Passed to `monitor`; must stay valid as long as the `HyconContact` that uses it.
    void *monitor_data;
    // Automatic cutback (default 8; 0 switches it off: a failed increment fails at once, the
    // behaviour before 0.7.0): an increment that fails for an iteration reason (no
    // convergence, a cycling contact set, a locked node breaking its lock, a surface pushed
    // beyond what the pairing sees) is taken again in sub-increments from the last converged
    // state to the target (loads, prescribed values and plate controls interpolated
    // linearly, each converged sub-increment the start of the next), halving a failed one at
    // most `cutback_depth` times (up to `HYCON_MAX_CUTBACK_DEPTH`). `K` is not factored
    // again and the interpolated loads cost no solve. Beyond the limit the increment fails
    // and the analysis is exactly as before the call.
    uint32_t cutback_depth;
    // The shortest sub-increment the cutback tries, as a fraction of the increment, in
    // `(0, 1]` (default 1/256).
    double cutback_min_fraction;
} HyconContactOptions;

// Element formulation selector, one of the `HYCON_ELEMENT_*` values.
typedef int32_t HyconElementKind;

// Elements of one formulation in compressed form: element `e` has the nodes
// `nodes[offsets[e] .. offsets[e + 1]]` (4 to 6 node ids, counter-clockwise: corners plus
// mid-side nodes of transition elements, in boundary order).
typedef struct HyconElementBlock {
    // `n_elements + 1` offsets into `nodes`, starting at 0, nondecreasing.
    const size_t *offsets;
    // `offsets[n_elements]` node ids.
    const size_t *nodes;
    // Number of elements (at least 1).
    size_t n_elements;
    // `n_elements` indices into the call's materials, or NULL: every element uses material 0.
    const size_t *materials;
    // The formulation of every element (`HYCON_ELEMENT_*`; Pian-Sumihara and Q4 take 4-node
    // elements only).
    HyconElementKind kind;
} HyconElementBlock;

// Two-dimensional idealisation, one of `HYCON_PLANE_STRAIN`, `HYCON_PLANE_STRESS`,
// `HYCON_AXISYMMETRIC`. One model (and one host) uses one kind.
typedef int32_t HyconAnalysis;

// Isotropic linear elastic material.
typedef struct HyconMaterial {
    // Young's modulus `E > 0`, within [1e-100, 1e100] (choose units accordingly).
    double youngs;
    // Poisson's ratio, `-1 < nu < 0.5`.
    double poisson;
    // Thickness `t > 0`, within [1e-100, 1e100] (plane strain: the depth results are reported
    // per, usually 1); exactly 1 in axisymmetry (the measure is `2 pi r`).
    double thickness;
    // `HYCON_PLANE_STRAIN`, `HYCON_PLANE_STRESS` or `HYCON_AXISYMMETRIC`.
    HyconAnalysis analysis;
} HyconMaterial;

// Directions of a prescribed displacement, a bit mask.
typedef int32_t HyconDirections;

// A polyline of node ids (model API contact pairs), ordered with its body on the left.
typedef struct HyconPolyline {
    // `n` node ids.
    const size_t *nodes;
    // Number of nodes.
    size_t n;
} HyconPolyline;

// Nodes in a host's numbering (host-assembly API): ids, reference coordinates and equation
// numbers.
typedef struct HyconHostNodes {
    // `n` node ids.
    const size_t *ids;
    // `2 n` reference coordinates `x0 y0 x1 y1 ...` (finite).
    const double *coords;
    // `2 n` equation numbers (`u_x`, `u_y` per node) in `0 .. n_equations`, or `HYCON_FIXED`
    // for a dof the host holds at zero.
    const int64_t *equations;
    // Number of nodes.
    size_t n;
} HyconHostNodes;

// Which part of a symmetric CSR matrix is given, one of `HYCON_CSR_*`.
typedef int32_t HyconTriangle;

// The host's linear solver: solve `K x_j = rhs_j` for `nrhs` right-hand sides, `rhs` and `x`
// both `n x nrhs` column-major (`rhs` is read-only, `x` is written; they never overlap).
// Return 0 on success, nonzero on failure (the hycon call then fails with
// `HYCON_ERROR_CALLBACK`). hycon calls it with many columns at once: at contact setup with unit
// right-hand sides (at most 64 columns per call) to build the boundary flexibility, and with one
// column per new load and per displacement recovery. A load that is a combination of the
// last few loads (proportional loading, say) is not solved again: its response is combined
// from theirs, so such an increment makes no call at all. Called on the thread that calls into the
// `HyconContact`. Must not unwind through hycon.
typedef int32_t (*HyconSolveFn)(void *user_data, size_t n, size_t nrhs, const double *rhs, double *x);

// Which condensed operator a host hands over (`HyconCondensed::kind`), one of
// `HYCON_CONDENSED_*`.
typedef int32_t HyconCondensedKind;

// A host's condensed operator over its contact candidate equations (host-assembly API,
// `hycon_host_set_condensed`). The candidates hold every equation of the contact nodes (all
// nodes of all pairs: under finite kinematics the polylines must cover the whole sliding
// range) and may hold more. Versioned by `size` as `HyconContactOptions`: set
// `size = sizeof(HyconCondensed)`.
typedef struct HyconCondensed {
    // `sizeof(HyconCondensed)` as the host was compiled.
    size_t size;
    // `HYCON_CONDENSED_STIFFNESS` or `HYCON_CONDENSED_FLEXIBILITY`.
    HyconCondensedKind kind;
    // Number of candidate equations `m`.
    size_t m;
    // The `m` candidate equations (host numbering, each once): the order of the matrix's rows
    // and columns and of every increment's load image.
    const int64_t *equations;
    // `m * m` doubles, column-major: `matrix[i + m * j]` couples `equations[i]` and
    // `equations[j]`; symmetric (to 1e-6 of its largest entry; both triangles are read and
    // averaged).
    const double *matrix;
} HyconCondensed;

// Summary of a converged increment.
typedef struct HyconIncrementInfo {
    // Increment number (1-based).
    size_t increment;
    // Iterations used (summed over the converged sub-increments: the records
    // `hycon_contact_records` keeps of the increment).
    size_t iterations;
    // Active (stick + slip + frictionless) A nodes at convergence.
    size_t active;
    // Slip nodes at convergence.
    size_t slip;
    // Converged sub-increments the increment was taken in: 1 unless the automatic cutback
    // split it.
    size_t sub_increments;
    // Sub-increments that failed and were tried again shorter (0 without cutback).
    size_t cutbacks;
} HyconIncrementInfo;

// How a plate translation is driven in an increment, one of `HYCON_PLATE_*`.
typedef int32_t HyconPlateControl;

// State of an A node, one of `HYCON_NODE_*`.
typedef int32_t HyconNodeState;

// Converged results at one A node (multiplier side).
typedef struct HyconNodeResult {
    // Node id (the caller's numbering).
    size_t node;
    // `HYCON_NODE_OPEN`, `HYCON_NODE_STICK`, `HYCON_NODE_SLIP` or `HYCON_NODE_FRICTIONLESS`.
    HyconNodeState state;
    // Slip direction along `tangent` of A relative to B (+1 or -1) for a slip node, else 0.
    int32_t slip_sign;
    // Normal traction on A (the multiplier, force per area for every analysis kind and
    // thickness; `< 0` compression, pressure `p = -tn`).
    double tn;
    // Tangential traction on A along `tangent` (force per area).
    double ts;
    // Nodal normal (A's outward): of the reference configuration under small kinematics, of
    // the converged one under finite kinematics.
    double normal[2];
    // Nodal tangent `(n_y, -n_x)`.
    double tangent[2];
    // Current position (reference position plus the converged displacement).
    double position[2];
    // Tributary measure `integral M_k dS` (`dS = t ds`, A's thickness `t`), measured in the
    // configuration the geometry lives in (reference under small kinematics, converged under
    // finite): the tractions are per unit of it (pressures), so `sum -tn * weight` is the
    // normal load only where A is straight.
    double weight;
    // Weighted normal gap per unit length (`< 0` penetration; infinite where B does not
    // cover the node's support).
    double gap;
    // Equivalent nodal contact force on A, `sum_k F^A_kj t_k` (x, y).
    double force[2];
} HyconNodeResult;

// Converged results at one B node (the opposite side).
typedef struct HyconBNodeResult {
    // Node id (the caller's numbering).
    size_t node;
    // `integral L^B_j dS` over the projected overlap (0 outside it; `dS` A's measure).
    double weight;
    // Equivalent nodal contact force on B (x, y).
    double force[2];
    // Pressure `-force . n / weight` (`n` B's outward nodal normal; 0 outside the overlap).
    double pressure;
    // Current position.
    double position[2];
} HyconBNodeResult;

// Where the time of an analysis went (wall-clock seconds, accumulated).
typedef struct HyconTimings {
    // Sparse assembly of `K` (model API).
    double assembly;
    // Symbolic analysis and numeric factorization of `K` (once per analysis).
    double factorization;
    // Contact-boundary flexibility (from the factor, or from host solves).
    double flexibility;
    // Load solves.
    double load_solves;
    // The contact iterations.
    double iterations;
    // Displacement recovery.
    double recovery;
} HyconTimings;

// Contact-element quantities of one A node at the converged state (the reference one before
// the first increment; under small kinematics the pairing, frames and weights are always the
// reference ones and the gaps linear in the displacements), for hosts that assemble the mixed
// system themselves.
typedef struct HyconContactNode {
    // Node id (the caller's numbering).
    size_t node;
    // `integral M_k dS` over the node's support (`dS = t ds`, A's surface measure).
    double weight;
    // Fraction of the support covered by B, in [0, 1].
    double coverage;
    // Nodal normal `n_k` (A's outward).
    double normal[2];
    // Nodal tangent `s_k = (n_y, -n_x)`.
    double tangent[2];
    // Weighted gap vector `R_C,k = integral M_k (x^A - x^B) dS` (x, y).
    double gap[2];
    // `-n_k . R_C,k / covered weight`: normal gap as a length (`< 0` penetration; infinite
    // when nothing is covered).
    double normal_gap;
} HyconContactNode;

// Which body a coupling entry belongs to, one of `HYCON_SIDE_*`.
typedef int32_t HyconSide;

// One entry of the contact-element matrices: `F^A_kj = integral M_k L^A_j dS` or
// `F^B_kj = integral M_k L^B_j(x^B) dS` (both >= 0; `dS` A's surface measure). The constraint row of A node `k` is
// `sum_j F^A_kj u_j - sum_j F^B_kj u_j` (per component).
typedef struct HyconCouplingEntry {
    // Index `k` of the A node within the pair's A polyline.
    size_t row;
    // Node id `j` (the caller's numbering).
    size_t node;
    // `HYCON_SIDE_A` or `HYCON_SIDE_B`.
    HyconSide side;
    // The value.
    double value;
} HyconCouplingEntry;

// One constraint entry of `Kc` (see `hycon_contact_constraint_rows`).
typedef struct HyconConstraintEntry {
    // Row: `2 k` the normal and `2 k + 1` the tangential constraint of A node `k`.
    size_t row;
    // Column: a field index (model dof `2 node + direction`, or host equation).
    size_t column;
    // The value.
    double value;
} HyconConstraintEntry;

// Which brick formulation a 3D element routine uses (`hycon_brick_*`).
//
// Brick node order: nodes 0-3 are one face, counter-clockwise seen from nodes 4-7; node
// `4 + i` lies above node `i`. Natural coordinates `(xi, eta, zeta)`: node 0 `(-1,-1,-1)`,
// 1 `(+1,-1,-1)`, 2 `(+1,+1,-1)`, 3 `(-1,+1,-1)`, 4-7 the same with `zeta = +1`:
//
// ```text
//        7-----------6
//       /|          /|
//      4-----------5 |      zeta
//      | 3---------|-2      | eta
//      |/          |/       |/
//      0-----------1        +--- xi
// ```
//
// Coordinates are interleaved `x0 y0 z0 x1 y1 z1 ...` (24 doubles), dofs `u0 v0 w0 u1 ...`
// (24), matrices 24 x 24 row-major. Faces, each counter-clockwise seen from outside (the
// right-hand rule gives the outward normal): 0 = nodes `0 4 7 3` (`xi = -1`), 1 = `1 2 6 5`
// (`xi = +1`), 2 = `0 1 5 4` (`eta = -1`), 3 = `3 7 6 2` (`eta = +1`), 4 = `0 3 2 1`
// (`zeta = -1`), 5 = `4 5 6 7` (`zeta = +1`); face parameters `(s, t)` in `[-1, 1]^2` run from
// the face's first node towards its second (`s`) and towards its fourth (`t`). Stresses are
// `{sxx, syy, szz, sxy, syz, szx}`.
typedef int32_t HyconBrickKind;

// Isotropic material of a 3D solid: no thickness, no plane idealisation.
typedef struct HyconSolidMaterial {
    // Young's modulus `E` (finite, in `[1e-100, 1e100]`).
    double youngs;
    // Poisson's ratio (`-1 < nu < 0.5`).
    double poisson;
} HyconSolidMaterial;

// How strictly a brick's shape is judged, one of `HYCON_SHAPE_INTEGRATION_POINTS` (the default
// of every brick routine) or `HYCON_SHAPE_STRICT` (`hycon_brick_shape`).
//
// Both policies reject (`HYCON_ERROR_BAD_ELEMENT`) coincident nodes, a volume that is not
// positive, and a Jacobian that is not positive (`det J <= 1e-10 h^3`, `h` the longest edge) at
// one of the 8 points of the 2x2x2 Gauss rule both bricks integrate with. The default then
// warns (`HYCON_WARNING_SHAPE`, results written) where the strict policy rejects: a Jacobian
// that is not positive at a corner node, a face warped by more than 45 degrees. The warp of a
// face is the angle between the normals of its two triangle halves, for each of the two ways
// of splitting it along a diagonal, the larger of the two (0 for a plane face).
typedef int32_t HyconShapePolicy;

// The measures of a brick's shape (`hycon_brick_shape`). Jacobians are relative to `h^3`, `h`
// the brick's longest edge, so the report does not change with the units.
typedef struct HyconShapeReport {
    // The smallest `det J / h^3` over the 8 integration points (2x2x2 Gauss).
    double integration_jacobian;
    // The smallest `det J / h^3` over the 8 corner nodes, reached at node `corner`.
    double corner_jacobian;
    // The largest warp over the 6 faces in degrees (measure at `HyconShapePolicy`), reached at
    // face `face`.
    double warp_degrees;
    // The local node (0-7) of `corner_jacobian`.
    size_t corner;
    // The local face (0-5) of `warp_degrees`.
    size_t face;
    // The warnings of the default policy: `HYCON_SHAPE_CORNER_JACOBIAN` and / or
    // `HYCON_SHAPE_WARPED_FACE` (0: none).
    int32_t warnings;
} HyconShapeReport;

// 8-node bricks (3D model API): brick `e` has the nodes `nodes[8 e .. 8 e + 8]` in the brick
// node order (`HyconBrickKind`).
typedef struct HyconBrickBlock {
    // `8 n_elements` node ids.
    const size_t *nodes;
    // Number of bricks (at least 1).
    size_t n_elements;
    // `n_elements` indices into the call's materials, or NULL: every brick uses material 0.
    const size_t *materials;
    // The formulation of every brick (`HYCON_BRICK_*`).
    HyconBrickKind kind;
} HyconBrickBlock;

// Brick faces (3D model API surfaces): `faces[2 i]` a brick index, `faces[2 i + 1]` its local
// face (0-5, outward by the right-hand rule: the numbering of `HyconBrickKind`).
typedef struct HyconBrickFaces {
    // `2 n` values: brick, local face.
    const size_t *faces;
    // Number of faces.
    size_t n;
} HyconBrickFaces;

// Converged results at one A node of a 3D pair.
typedef struct HyconSolidNodeResult {
    // Node id (the caller's numbering).
    size_t node;
    // `HYCON_NODE_OPEN`, `HYCON_NODE_STICK`, `HYCON_NODE_SLIP` or `HYCON_NODE_FRICTIONLESS`.
    HyconNodeState state;
    // Normal traction on A (the multiplier, force per area; `< 0` compression, pressure
    // `p = -tn`).
    double tn;
    // Tangential traction on A along `tangent[0]` and `tangent[1]` (force per area; 0 along a
    // tangent dropped by a symmetry plane).
    double ts[2];
    // A slip node: the unit direction of A's slip relative to B along `tangent[0]`,
    // `tangent[1]` (the friction traction opposes it: `ts = mu tn slip_direction`); else 0 0.
    double slip_direction[2];
    // Nodal normal (A's outward): of the reference configuration under small kinematics, of
    // the converged one under finite kinematics.
    double normal[3];
    // The tangents `s1`, `s2`: `(normal, s1, s2)` orthonormal and right-handed, continuous
    // over the pair; a tangent normal to a symmetry plane the node lies on is dropped (zero).
    double tangent[2][3];
    // Current position (reference position plus the converged displacement).
    double position[3];
    // Tributary area `integral N_k dA` (tractions are per unit of it).
    double weight;
    // Weighted normal gap (`< 0` penetration; infinite where B does not cover the node).
    double gap;
    // Equivalent nodal contact force on A (x, y, z).
    double force[3];
} HyconSolidNodeResult;

// Converged results at one B node of a 3D pair.
typedef struct HyconSolidBNodeResult {
    // Node id (the caller's numbering).
    size_t node;
    // `integral M_j dA` over the projected overlap (A's measure; 0 outside it).
    double weight;
    // Equivalent nodal contact force on B (x, y, z).
    double force[3];
    // Pressure `-force . n / weight` (`n` B's outward nodal normal; 0 outside the overlap).
    double pressure;
    // Current position.
    double position[3];
} HyconSolidBNodeResult;

// Contact-element quantities of one A node of a 3D pair at the converged state (the
// reference one before the first increment), for hosts that assemble the mixed system
// themselves.
typedef struct HyconSolidContactNode {
    // Node id (the caller's numbering).
    size_t node;
    // `integral N_k dA` over the node's support.
    double weight;
    // Fraction of the support covered by B, in [0, 1].
    double coverage;
    // Nodal normal (A's outward).
    double normal[3];
    // The tangents `s1`, `s2` (zero where a symmetry plane drops one).
    double tangent[2][3];
    // Weighted gap vector `R_C,k = integral N_k (x^A - x^B) dA`.
    double gap[3];
    // `-n_k . R_C,k / covered weight` (`< 0` penetration; infinite when nothing is covered).
    double normal_gap;
} HyconSolidContactNode;

// Contact nodes of a 3D host (host API): ids, reference coordinates and equation numbers.
typedef struct HyconSolidHostNodes {
    // `n` node ids (the host's numbering).
    const size_t *ids;
    // `3 n` reference coordinates `x0 y0 z0 x1 ...` (finite).
    const double *coords;
    // `3 n` equation numbers (`u_x`, `u_y`, `u_z` per node) in `0 .. n_equations`, or
    // `HYCON_FIXED` for a dof the host holds at zero.
    const int64_t *equations;
    // Number of nodes.
    size_t n;
} HyconSolidHostNodes;

// Faces of a 3D host's contact surface (host API): face `i` has the node ids
// `nodes[4 i .. 4 i + 4]`, counter-clockwise seen from outside its body (its outward normal
// by the right-hand rule), the corners of a 4-node face (a brick's face, say).
typedef struct HyconHostFaces {
    // `4 n` node ids.
    const size_t *nodes;
    // Number of faces.
    size_t n;
} HyconHostFaces;



// Success.
#define HYCON_OK 0

// A required pointer argument is NULL (or an array pointer is NULL with a nonzero length).
#define HYCON_ERROR_NULL_POINTER -1

// An argument is out of range: unknown enum value, wrong length or index, a non-finite double,
// a misaligned pointer.
#define HYCON_ERROR_INVALID_ARGUMENT -2

// The material is invalid: `E <= 0`, `nu` outside `(-1, 0.5)`, `t <= 0`, non-finite values,
// unknown analysis type, axisymmetric with `t != 1`, a model mixing analysis kinds.
#define HYCON_ERROR_INVALID_MATERIAL -3

// An element has a bad shape or node count: degenerate (zero area, coincident nodes),
// inverted (clockwise), non-convex, or a node count the formulation does not take; in
// axisymmetry also a node at `x = r < 0` or a formulation / node count not available there.
// The message names the element (its index when the call handles a mesh) and the defect.
#define HYCON_ERROR_BAD_ELEMENT -4

// A global system is singular (a body not held against rigid motion).
#define HYCON_ERROR_SINGULAR -5

// A linear solver failed for a numerical reason.
#define HYCON_ERROR_SOLVER -6

// An output buffer is shorter than required; the message states the length needed.
#define HYCON_ERROR_BUFFER_TOO_SMALL -7

// A contact increment failed, after the automatic cutback (no convergence, cycling contact set,
// a surface pushed through the other or beyond what the pairing sees, at any depth and any
// magnitude, contact reaching the end of a surface); the last converged state is kept.
#define HYCON_ERROR_CONTACT -8

// A caller-supplied callback (solve or monitor) returned a nonzero status or non-finite
// values; the last converged state is kept.
#define HYCON_ERROR_CALLBACK -9

// Internal error: a Rust panic was caught at the boundary. Please report it with the message.
#define HYCON_ERROR_PANIC -99

// Warning: a brick is distorted beyond the strict shape policy (a Jacobian not positive at a
// corner, or a face warped beyond 45 degrees) but its Jacobian is positive at every
// integration point, so the results were computed and written (see `HyconShapePolicy`). The
// message names the corner or face and the measure. A host that tests `status != HYCON_OK`
// rejects such bricks as 0.8 did; one that tests `status < 0` accepts them.
#define HYCON_WARNING_SHAPE 1

// Assumed-stress hybrid element (7 stress parameters; 12 for 6 nodes), 4 to 6 nodes.
#define HYCON_ELEMENT_HYBRID 1

// Pian-Sumihara 5-beta hybrid quadrilateral, 4 nodes.
#define HYCON_ELEMENT_PIAN_SUMIHARA 2

// Bilinear displacement quadrilateral with 2x2 Gauss integration, 4 nodes.
#define HYCON_ELEMENT_Q4 3

// Plane strain (`eps_z = 0`).
#define HYCON_PLANE_STRAIN 1

// Plane stress (`sigma_z = 0`).
#define HYCON_PLANE_STRESS 2

// Axisymmetric: a solid of revolution about the y axis, `x = r >= 0` (radial), `y = z`
// (axial), no torsion. Strains `{eps_r, eps_z, gamma_rz, eps_theta = u_r / r}`, stresses
// `{sigma_r, sigma_z, tau_rz, sigma_theta}`. **Measure: the full circle**: every volume and
// surface integral is weighted by `2 pi r` (element matrices, loads, reactions, contact forces,
// energies), so a nodal force is the force summed over the whole circumference. The thickness
// must be exactly 1. Elements: the hybrid element (4 nodes, 7 stress parameters) and Q4;
// Pian-Sumihara and the 5- and 6-node transition elements are rejected
// (`HYCON_ERROR_BAD_ELEMENT`). Prescribe `u_r = 0` at nodes on the axis.
#define HYCON_AXISYMMETRIC 3

// faer (always available; the default).
#define HYCON_BACKEND_FAER 1

// CHOLMOD from SuiteSparse (only when hycon was built with the `suitesparse` feature).
#define HYCON_BACKEND_CHOLMOD 2

// Small deformation (the default): the pairing, frames, weights and contact-element matrices
// are evaluated once in the reference configuration and the gap is linear in the
// displacements, consistent with small-strain elasticity (Hertz, Cattaneo-Mindlin); valid
// while the surfaces slide little: an increment in which sliding with the frozen pairing would
// move an active node's gap by more than 10% of the contact's normal approach fails with
// `HYCON_ERROR_CONTACT` ("use finite kinematics"), keeping the last converged state.
#define HYCON_KINEMATICS_SMALL 1

// Finite kinematics: the contact geometry is evaluated at the current positions in every
// iteration; for surfaces that slide far along each other.
#define HYCON_KINEMATICS_FINITE 2

// x only.
#define HYCON_X 1

// y only.
#define HYCON_Y 2

// x and y.
#define HYCON_XY 3

// z only (3D: `hycon_solid_model_prescribe`; the plane's `hycon_model_prescribe` rejects it).
#define HYCON_Z 4

// x, y and z (3D: `hycon_solid_model_prescribe`; the plane's `hycon_model_prescribe` rejects
// it).
#define HYCON_XYZ 7

// Not in contact.
#define HYCON_NODE_OPEN 1

// In contact, no slip since the increment began.
#define HYCON_NODE_STICK 2

// In contact and sliding (`ts = mu sign tn`).
#define HYCON_NODE_SLIP 3

// In contact without friction (a pair with friction 0; `ts = 0`). Before 0.7.0 such a node
// was reported as `HYCON_NODE_SLIP` with `slip_sign` +1.
#define HYCON_NODE_FRICTIONLESS 4

// The multiplier side A: the entry is `F^A_kj`.
#define HYCON_SIDE_A 1

// The opposite side B: the entry is `F^B_kj`.
#define HYCON_SIDE_B 2

// Every entry (checked to be symmetric to 1e-10 of the largest entry).
#define HYCON_CSR_FULL 1

// Entries with column <= row.
#define HYCON_CSR_LOWER 2

// Entries with column >= row.
#define HYCON_CSR_UPPER 3

// The value is the plate's total displacement in that direction.
#define HYCON_PLATE_DISPLACEMENT 1

// The value is the total force on the plate in that direction (its motion is solved for).
#define HYCON_PLATE_FORCE 2

// The stiffness Schur complement `S = K_cc - K_ci K_ii^-1 K_ic` over the candidate equations
// `c` (what MUMPS gives through PETSc's `MatFactorSetSchurIS` +
// `MatFactorCreateSchurComplement`); hycon factors it once (dense Cholesky).
#define HYCON_CONDENSED_STIFFNESS 1

// The flexibility block `(K^-1)_cc` (one batched solve `K X = E_c`, e.g. CHOLMOD's).
#define HYCON_CONDENSED_FLEXIBILITY 2

// The 18-beta assumed-stress hybrid brick of Pian and Tong (stress in natural coordinates,
// carried to Cartesian components with the centre Jacobian): locking-free in bending and as
// `nu -> 0.5`.
#define HYCON_BRICK_HYBRID18 1

// The trilinear displacement brick with 2x2x2 Gauss (the baseline; locks in bending and near
// incompressibility).
#define HYCON_BRICK_H8 2

// The default: errors only where the Jacobian at an integration point or the volume is not
// positive; a corner Jacobian that is not positive and a warp beyond 45 degrees are warnings.
// MacNeal and Harder's 3D patch test mesh passes with warnings, and both bricks are exact on it.
#define HYCON_SHAPE_INTEGRATION_POINTS 1

// hycon 0.8's check: the corner Jacobians and the warp limit are errors too, with 0.8's
// messages ("Jacobian not positive at local node i", "face f is warped beyond the limit").
#define HYCON_SHAPE_STRICT 2



#ifdef __cplusplus
extern "C" {
#endif // __cplusplus

// Write the library's version `{major, minor, patch}` to `out` (3 values). Compare with the
// header's `HYCON_VERSION_MAJOR` etc. to detect a header / library mismatch.
//
// Errors: `HYCON_ERROR_NULL_POINTER` if `out` is NULL.
//
// # Safety
// `out` must be NULL or point to 3 writable `int32_t`.
HyconStatus hycon_version(int32_t *out);

// Copy this thread's last error message into `buf` and return the length it needs, including
// the terminating NUL.
//
// What the message is: every function that returns a `HyconStatus` sets it when it returns,
// to `"<function name>: <description>"` when it fails (a negative status), to
// `"<function name>: warning: <description>"` for a warning (a positive status) and to the
// empty string when it succeeds. So it describes the last status-returning call on this thread,
// and is empty (return value 1) unless that call failed or warned. This function, `hycon_status_name` and
// the `_free` functions do not change it. It is thread-local: a call on another thread never
// changes it.
//
// At most `len - 1` bytes plus a NUL are written (nothing if `buf` is NULL or `len` is 0), so
// `hycon_last_error_message(NULL, 0)` asks for the size and a return value greater than `len`
// means the copy was truncated (at a UTF-8 character boundary).
//
// # Safety
// `buf` must be NULL or point to `len` writable bytes.
size_t hycon_last_error_message(char *buf,
                                size_t len);

// A static, NUL-terminated name for a status code (`"HYCON_OK"`, `"HYCON_ERROR_NULL_POINTER"`,
// ..., `"HYCON_WARNING_SHAPE"`, `"HYCON_WARNING"` for any other positive value,
// `"HYCON_ERROR_UNKNOWN"` otherwise). The
// string is owned by the library and valid for the life of the process; do not free it.
const char *hycon_status_name(HyconStatus status);

// Fill `out` with the default options (the values documented per field, no monitor).
//
// # Safety
// `out` must be NULL or point to a writable `HyconContactOptions`.
HyconStatus hycon_contact_options_default(struct HyconContactOptions *out);

// Create a model from its mesh and materials (the order of every call that takes a mesh:
// nodes, elements, materials).
//
// * `coords`: `2 * n_nodes` doubles `x0 y0 x1 y1 ...`;
// * `elements`: the elements (`HyconElementBlock`: compressed node lists, their material
//   indices or NULL for all 0, the formulation);
// * `materials`: `n_materials` materials.
//
// The arrays are copied. Errors: `HYCON_ERROR_NULL_POINTER` (`out`, `coords`, `elements`,
// `materials`, or an array of `elements` with a nonzero length), `HYCON_ERROR_INVALID_ARGUMENT`
// (lengths, unknown node ids, non-finite coordinates, unknown kind, misaligned pointers),
// `HYCON_ERROR_INVALID_MATERIAL` (also materials of different analysis kinds: one model takes
// one kind), `HYCON_ERROR_BAD_ELEMENT` (inverted, degenerate or non-convex element, named by
// index; in axisymmetry also a node at `x < 0`, Pian-Sumihara or a 5- or 6-node element).
//
// # Safety
// `out` must point to a writable pointer; `coords` NULL or `2 n_nodes` readable doubles;
// `elements` NULL or a readable view whose arrays hold the stated counts; `materials` NULL or
// `n_materials` readable structs.
HyconStatus hycon_model_new(struct HyconModel **out,
                            const double *coords,
                            size_t n_nodes,
                            const struct HyconElementBlock *elements,
                            const struct HyconMaterial *materials,
                            size_t n_materials);

// Free a model (NULL is a no-op). Analyses made from it keep their own copy.
//
// # Safety
// `model` must be NULL or a live handle from `hycon_model_new`, not used afterwards.
void hycon_model_free(struct HyconModel *model);

// Prescribe the displacement of `nodes` in `directions` (`HYCON_X`, `HYCON_Y` or `HYCON_XY`).
// The values are given per increment (`prescribed` of `hycon_contact_increment`). Contact
// nodes may be prescribed too.
//
// Errors: `HYCON_ERROR_INVALID_ARGUMENT` for an unknown node id, unknown `directions`, or a
// displacement component prescribed twice (listed twice in `nodes`, prescribed by an earlier
// call, or tied to the plate); on an error nothing is prescribed.
//
// # Safety
// `model` must be a live handle; `nodes` NULL or `n` readable ids.
HyconStatus hycon_model_prescribe(struct HyconModel *model,
                                  const size_t *nodes,
                                  size_t n,
                                  HyconDirections directions);

// Add a contact pair: the multiplier-side polyline `a` and the opposite polyline `b` (node
// ids, each ordered with its body on the left: consecutive nodes must be the two ends of an
// element edge of that body, in the element's counter-clockwise order) and the Coulomb
// friction coefficient `friction >= 0` (0: frictionless). The pair's index (0, 1, ...) is
// written to `index` unless it is NULL.
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`model`, `a`, `b`, or their `nodes` with `n > 0`);
// `HYCON_ERROR_INVALID_ARGUMENT` for unknown node ids, fewer than 2 nodes, repeated nodes, a
// node in both polylines, consecutive nodes that are not an element edge with the body on the
// left (naming the segment), a bad friction coefficient, a misaligned pointer.
//
// # Safety
// `model` must be a live handle; `a`, `b` NULL or readable views holding `n` ids each;
// `index` NULL or writable.
HyconStatus hycon_model_add_pair(struct HyconModel *model,
                                 const struct HyconPolyline *a,
                                 const struct HyconPolyline *b,
                                 double friction,
                                 size_t *index);

// Tie `nodes` (a face of one body, none of them a contact node) to a rigid plate whose x and
// y translations are driven per increment by `hycon_contact_increment_with_plate`, each by
// displacement or by force. The nodes are prescribed in x and y by this call. A body held only
// by the plate and by contact (a pressed disk) then takes a prescribed force.
//
// Errors: `HYCON_ERROR_INVALID_ARGUMENT` for no nodes, an unknown node id, or a node already
// prescribed (by `hycon_model_prescribe`, twice in `nodes`, or by an earlier plate: a model
// has one plate); on an error the model is unchanged.
//
// # Safety
// `model` must be a live handle; `nodes` NULL or `n` readable ids.
HyconStatus hycon_model_set_plate(struct HyconModel *model, const size_t *nodes, size_t n);

// Start a contact analysis of a model (copied: the model may be freed or changed afterwards):
// validate, assemble, factor `K` once with the contact dofs last and read the contact-boundary
// flexibility off the factor. `options` NULL means the defaults.
//
// A model without contact pairs is allowed: its increments are plain linear solves.
//
// Errors: `HYCON_ERROR_SINGULAR` (a body not held against rigid motion: the message names it),
// `HYCON_ERROR_BAD_ELEMENT`, `HYCON_ERROR_INVALID_ARGUMENT` (bad options), `HYCON_ERROR_SOLVER`.
//
// # Safety
// `out` must point to a writable pointer, `model` be a live handle, `options` NULL or
// readable.
HyconStatus hycon_contact_new(struct HyconContact **out,
                              const struct HyconModel *model,
                              const struct HyconContactOptions *options);

// Create a host description for a system of `n_equations` equations (the host's `K` after its
// boundary conditions: symmetric positive definite).
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`out`), `HYCON_ERROR_INVALID_ARGUMENT` (`n_equations`
// zero or beyond what memory can address).
//
// # Safety
// `out` must point to a writable pointer.
HyconStatus hycon_host_new(struct HyconHost **out, size_t n_equations);

// Free a host description (NULL is a no-op). Analyses made from it are independent of it.
//
// # Safety
// `host` must be NULL or a live handle from `hycon_host_new`, not used afterwards.
void hycon_host_free(struct HyconHost *host);

// Add a contact pair in the host's numbering: the polylines `a` (the multiplier side) and `b`,
// each a `HyconHostNodes` (node ids, reference coordinates, equation numbers with
// `HYCON_FIXED` for a dof the host holds at zero), ordered with its body on the left. A node
// in several pairs must be given the same coordinates and equations each time. `friction >= 0`
// is the Coulomb coefficient. `analysis` and `thickness` are those of the A side's elements
// (`HYCON_PLANE_STRAIN` or `HYCON_PLANE_STRESS` and its thickness `t`, or
// `HYCON_AXISYMMETRIC` and 1): the contact integrals are weighted by A's surface measure,
// `t ds` or `2 pi r ds` (the full circle), so the tractions are pressures (force per area)
// and the contact forces are in the units of the host's stiffness (which carries `t`, or is
// over the full circle). All pairs of a host share one analysis kind (plane strain and plane
// stress are two kinds); their thicknesses may differ. Elements handed over
// (`hycon_host_set_elements`, before or after this call) along a pair's A segments must be of
// its kind and thickness. The pair's index is written to `index` unless it is NULL. The
// arrays are copied; on an error the host is unchanged.
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `a`, `b`, or an array of a view with `n > 0`),
// `HYCON_ERROR_INVALID_ARGUMENT` (non-finite coordinates, equations out of range or shared,
// fewer than 2 nodes, repeated nodes, a zero-length segment, a node given before differently,
// a bad friction coefficient, an unknown analysis kind or one other than the host's earlier
// pairs', a thickness that is not finite and positive (or not 1 in axisymmetry), in
// axisymmetry a node of A or B at `r = x < 0` beyond round-off (1e-10 of its segments'
// length), an element handed over on a segment of A whose material differs from `analysis`
// or `thickness` (or any element of another kind), a misaligned pointer).
//
// # Safety
// `host` must be a live handle; `a`, `b` NULL or readable views whose arrays hold the stated
// counts; `index` NULL or writable.
HyconStatus hycon_host_add_pair(struct HyconHost *host,
                                const struct HyconHostNodes *a,
                                const struct HyconHostNodes *b,
                                double friction,
                                HyconAnalysis analysis,
                                double thickness,
                                size_t *index);

// Say which side body A of pair `pair` (an index from `hycon_host_add_pair`) is on: `inside`
// is a point inside body A (2 doubles `x y`), beside its polyline rather than beyond its ends:
// the centroid of the element that owns A's first segment, say. It must lie on A's body side
// of the A polyline (its left), which confirms A's orientation; B's follows from facing A.
// Replaces an earlier point of the pair.
//
// Needed where the geometry cannot tell: when A and B touch (lie within half a segment of each
// other) wherever they are near each other, facing surfaces and back-to-back ones (both
// polylines reversed) look the same, and `hycon_contact_new_host` rejects such a pair without
// it, unless the host gave its elements (`hycon_host_set_elements`) with one on a segment of
// A (its centroid is then the point). Surfaces apart (or curved away from each
// other around a contact) need none, and a point given is checked in any case.
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `inside`), `HYCON_ERROR_INVALID_ARGUMENT` (an
// unknown pair, a non-finite point, one beyond the ends of the A polyline, one on its outward
// side: A reversed, and with B facing it the pair back to back). On an error the host is
// unchanged.
//
// # Safety
// `host` must be a live handle; `inside` NULL or 2 readable doubles.
HyconStatus hycon_host_set_pair_inside(struct HyconHost *host, size_t pair, const double *inside);

// Give the host's stiffness as a CSR matrix over its `n_equations` equations (copied):
// `row_ptr` has `n_equations + 1` entries starting at 0, `columns` and `values` have
// `row_ptr[n_equations]`; `triangle` says which part is stored (`HYCON_CSR_FULL`, checked
// symmetric; `HYCON_CSR_LOWER`; `HYCON_CSR_UPPER`). hycon factors it once (faer, or the
// options' backend) when the analysis starts. Replaces an earlier matrix or solver.
//
// The columns of a row may come in any order, and an entry given more than once is summed
// (as an assembly loop leaves it). A dof the host holds fixed is either left out of the
// equations (`HYCON_FIXED` in `hycon_host_add_pair`) or kept as an identity row and column
// (1 on the diagonal, 0 elsewhere and in the right-hand side): both work.
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, an array with entries to read),
// `HYCON_ERROR_INVALID_ARGUMENT` (an unknown `triangle`, `row_ptr` not starting at 0 or
// decreasing, a column out of range, an entry in the wrong triangle, a non-finite value, a
// full matrix that is not symmetric, a misaligned pointer). On an error the host is
// unchanged.
//
// # Safety
// `host` must be a live handle; the arrays NULL or of the stated lengths.
HyconStatus hycon_host_set_csr(struct HyconHost *host,
                               const size_t *row_ptr,
                               const size_t *columns,
                               const double *values,
                               HyconTriangle triangle);

// Let the host solve with its own factorization: `solve(user_data, n, nrhs, rhs, x)` (see
// `HyconSolveFn`). The function pointer and `user_data` are kept by this description and by
// every analysis made from it, and called during `hycon_contact_new_host`, the increments and
// displacement recovery; `user_data` (the host's factor) must outlive them. Replaces an
// earlier matrix or solver. This is the path for distributed hosts (e.g. PETSc over MPI): hycon
// only ever asks for solves and works on the contact dofs, which every rank can hold.
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `solve`).
//
// # Safety
// `host` must be a live handle; `solve` a valid function as documented.
HyconStatus hycon_host_set_solver(struct HyconHost *host, HyconSolveFn solve, void *user_data);

// Hand over the host's condensed operator over its contact candidate equations (copied):
// the stiffness Schur complement or the flexibility block (`HyconCondensed`), computed by the
// host's own solver in one factorization. hycon runs every increment on it alone, with no
// solve inside an increment: `hycon_contact_increment` then takes as `load` the **load
// image**, `u0 = K^-1 rhs` at the `m` candidate equations in their order (`load_len = m`;
// the host's solve of its total right-hand side), and after an increment the host recovers
// its displacement with one solve of its own, `K u = rhs + forces` with
// `hycon_contact_forces` (`hycon_contact_displacement`, `hycon_contact_displacement_increment`
// and `hycon_contact_stress_tractions` fail: hycon has no solver of `K`, their size queries
// answer as on the other paths).
// `hycon_host_contact_equations` lists the equations the candidates must hold. Replaces an
// earlier matrix or solver. Checked here: `size`, the kind, `m > 0`, candidates in range and
// distinct, finite values, symmetry; at `hycon_contact_new_host`: every contact equation
// among the candidates, a Schur complement positive definite (`HYCON_ERROR_SINGULAR`).
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `condensed`, its arrays),
// `HYCON_ERROR_INVALID_ARGUMENT` (the checks above, a misaligned pointer). On an error the
// host is unchanged.
//
// # Safety
// `host` must be a live handle; `condensed` NULL or a readable `HyconCondensed` whose arrays
// hold the stated counts.
HyconStatus hycon_host_set_condensed(struct HyconHost *host,
                                     const struct HyconCondensed *condensed);

// The host's contact equations: every equation of a node of its pairs (not `HYCON_FIXED`),
// in the order the nodes were first given (`u_x`, then `u_y`), each once: what the
// candidates of `hycon_host_set_condensed` must hold (as an index set for a Schur
// complement, or the columns of a batched solve).
//
// Sizes and errors follow the header's size convention (`out`, `len`, `needed`).
//
// # Safety
// `host` must be a live handle; `out` NULL or `len` writable values; `needed` NULL or
// writable.
HyconStatus hycon_host_contact_equations(const struct HyconHost *host,
                                         int64_t *out,
                                         size_t len,
                                         size_t *needed);

// Optionally hand over the elements of body A along the A polylines (at least those owning an
// A segment), so that `hycon_contact_stress_tractions` can recover the tractions from their
// stresses (the paper's way (a)) from the host's displacements. The same order as
// `hycon_model_new`: nodes, elements, materials. `nodes` is the node table of every node the
// elements use (ids, reference coordinates, equations with `HYCON_FIXED` for a held dof);
// `elements` the elements (hycon formulations, counter-clockwise, node ids of the host's
// numbering); `materials` the `n_materials` materials the elements' indices refer to. Every
// material the elements use is of the pairs' analysis kind, and an element on a segment of a
// pair's A polyline has that pair's kind and thickness (`hycon_host_add_pair`; pairs added
// later are checked against these elements there): the stresses would otherwise be of
// another analysis, silently wrong. Copied; replaces earlier elements; on an error the host
// is unchanged.
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, a view, an array of a view with a nonzero count,
// `materials`), `HYCON_ERROR_INVALID_ARGUMENT` (counts, unknown ids, equations, non-finite
// coordinates, misaligned pointers, a material of another kind than the pairs', an element
// along A of another kind or thickness than its pair), `HYCON_ERROR_INVALID_MATERIAL`,
// `HYCON_ERROR_BAD_ELEMENT`.
//
// # Safety
// `host` must be a live handle; `nodes` and `elements` NULL or readable views whose arrays
// hold the stated counts; `materials` NULL or `n_materials` readable structs.
HyconStatus hycon_host_set_elements(struct HyconHost *host,
                                    const struct HyconHostNodes *nodes,
                                    const struct HyconElementBlock *elements,
                                    const struct HyconMaterial *materials,
                                    size_t n_materials);

// Start a contact analysis of a host's system: factor its CSR matrix once (the contact
// equations last) and read the flexibility off the factor, build the flexibility from
// batched solves through its callback, or read it off its condensed operator. `options`
// NULL means the defaults. The checks of `hycon_host_add_pair` and `hycon_host_set_elements`
// (sections, radii, elements along A) hold already, as they were made there.
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`out`, `host`), `HYCON_ERROR_INVALID_ARGUMENT` (no
// pair, no stiffness, solver or condensed operator given, a pair whose polylines run the same
// way or lie back to back, a pair whose surfaces touch wherever they are near each other
// without `hycon_host_set_pair_inside`, a contact equation that is no candidate of the
// condensed operator, bad options), `HYCON_ERROR_SINGULAR` (the CSR matrix or the condensed
// Schur complement is not positive definite: a body not held), `HYCON_ERROR_SOLVER` (the
// factorization failed otherwise, or the options' backend is not built in),
// `HYCON_ERROR_CALLBACK` (the solver failed or returned non-finite values).
//
// # Safety
// `out` must point to a writable pointer, `host` be a live handle, `options` NULL or
// readable.
HyconStatus hycon_contact_new_host(struct HyconContact **out,
                                   const struct HyconHost *host,
                                   const struct HyconContactOptions *options);

// Free an analysis (NULL is a no-op).
//
// # Safety
// `contact` must be NULL or a live handle, not used afterwards.
void hycon_contact_free(struct HyconContact *contact);

// Apply one load increment with **total** values (from the reference state):
// * model API: `load` = external nodal forces over all `2 * n_nodes` dofs (`u0 v0 u1 v1 ...`),
//   `prescribed` = values at the prescribed dofs over the same `2 * n_nodes` entries (the
//   others are ignored, whatever they hold: NaN there is fine);
// * host API: `load` = the host's right-hand side over its equations (including the effect of
//   its prescribed displacements), `prescribed` = (NULL, 0);
// * host API with a condensed operator (`hycon_host_set_condensed`): `load` = the load image
//   `u0 = K^-1 rhs` at the candidate equations, in their order (`load_len = m`),
//   `prescribed` = (NULL, 0).
//
// `load_len` is the field length, which the size query of the displacement gives:
// `hycon_contact_displacement(contact, NULL, 0, &load_len)`; on the condensed path it is
// instead the candidate count `m` the host handed over (`HyconCondensed::m`), and that size
// query gives the host's equation count (the length of `hycon_contact_forces`).
//
// An increment that fails for an iteration reason is taken again in sub-increments (the
// automatic cutback, `HyconContactOptions::cutback_depth`); it is still one increment, and
// `info->sub_increments` says how many it took. On success the converged state advances and
// `info` (unless NULL) gets the summary. On failure (beyond the cutback's limit) the analysis
// is exactly as before the call and the status says why: `HYCON_ERROR_CONTACT` (no
// convergence, cycling contact set with the node named, a surface pushed through the other or
// beyond what the pairing sees, at any depth, including a motion so large that double
// precision no longer resolves the surfaces, contact reaching the end of a surface),
// `HYCON_ERROR_SINGULAR` (a body held only by frictionless contact), `HYCON_ERROR_CALLBACK`
// (solver or monitor),
// `HYCON_ERROR_INVALID_ARGUMENT` (lengths, non-finite values or values beyond 1e300 in
// magnitude, where the load plus the contact forces or the stresses may overflow: choose other
// units; a plate analysis).
//
// # Safety
// `contact` must be a live handle; arrays NULL or of the stated lengths; `info` NULL or
// writable.
HyconStatus hycon_contact_increment(struct HyconContact *contact,
                                    const double *load,
                                    size_t load_len,
                                    const double *prescribed,
                                    size_t prescribed_len,
                                    struct HyconIncrementInfo *info);

// As `hycon_contact_increment` for a model with a plate (`hycon_model_set_plate`): `control`
// and `value` (2 entries each, x then y) drive the plate's translations
// (`HYCON_PLATE_DISPLACEMENT`: total displacement; `HYCON_PLATE_FORCE`: total force on the
// plate, its motion solved for).
//
// # Safety
// As `hycon_contact_increment`; `control` and `value` must hold 2 values each.
HyconStatus hycon_contact_increment_with_plate(struct HyconContact *contact,
                                               const double *load,
                                               size_t load_len,
                                               const double *prescribed,
                                               size_t prescribed_len,
                                               const HyconPlateControl *control,
                                               const double *value,
                                               struct HyconIncrementInfo *info);

// The converged plate displacement and the force the plate exerts on the body (2 values each,
// x then y).
//
// # Safety
// `contact` must be a live handle; `displacement` and `force` must hold 2 writable doubles.
HyconStatus hycon_contact_plate(const struct HyconContact *contact,
                                double *displacement,
                                double *force);

// The displacement of the last converged increment (total, from the reference state; zero
// before the first) over the field: all `2 * n_nodes` dofs of a model (`u0 v0 u1 v1 ...`), the
// host's `n_equations` equations. The size query `(NULL, 0, &needed)` gives that length, which
// is also the `load_len` of `hycon_contact_increment` (except on the condensed path, whose
// `load_len` is the candidate count `m`). The first call after an increment recovers the
// field (one solve; a host's solve callback is called), later calls copy it.
//
// A host that handed over its condensed operator (`hycon_host_set_condensed`) recovers its
// displacement itself (`K u = rhs + hycon_contact_forces`): hycon has no solver of its `K`,
// so there the size query still gives `n_equations` but a call with `out` fails with
// `HYCON_ERROR_INVALID_ARGUMENT` (saying so), before the first increment too.
//
// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
// `HYCON_ERROR_INVALID_ARGUMENT` on the condensed path, `HYCON_ERROR_CALLBACK` when a host's
// solve fails or returns non-finite values, `HYCON_ERROR_SOLVER` when hycon's solve fails.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable doubles; `needed` NULL or
// writable.
HyconStatus hycon_contact_displacement(const struct HyconContact *contact,
                                       double *out,
                                       size_t len,
                                       size_t *needed);

// The displacement increment of the last converged increment (its total displacement minus
// the previous increment's; the total at the first; zero before the first), same layout and
// length as `hycon_contact_displacement`. One solve per call (not for the size query).
//
// On the condensed path (`hycon_host_set_condensed`) as `hycon_contact_displacement`: the
// size query gives `n_equations`, a call with `out` after an increment fails with
// `HYCON_ERROR_INVALID_ARGUMENT` (hycon has no solver of `K`; the host solves
// `K du = rhs - rhs_previous + forces - forces_previous` itself).
//
// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
// `HYCON_ERROR_INVALID_ARGUMENT` on the condensed path, `HYCON_ERROR_CALLBACK` when a host's
// solve fails or returns non-finite values, `HYCON_ERROR_SOLVER` when hycon's solve fails.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable doubles; `needed` NULL or
// writable.
HyconStatus hycon_contact_displacement_increment(const struct HyconContact *contact,
                                                 double *out,
                                                 size_t len,
                                                 size_t *needed);

// The contact forces of the last converged increment over the field (zero at a host's fixed
// dofs; same length as `hycon_contact_displacement`): adding them to the load gives the
// right-hand side whose solution is the displacement (`K u = load + forces`), for hosts that
// recover displacements and stresses themselves. Rust: `ContactAnalysis::contact_forces`.
//
// Sizes and errors follow the header's size convention (`out`, `len`, `needed`).
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable doubles; `needed` NULL or
// writable.
HyconStatus hycon_contact_forces(const struct HyconContact *contact,
                                 double *out,
                                 size_t len,
                                 size_t *needed);

// Tractions way (b), the multipliers: converged results at the A nodes of `pair` (states,
// `tn`, `ts`, frames, gaps, nodal forces), one per A node in polyline order: the size query
// gives the A node count.
//
// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
// writable.
HyconStatus hycon_contact_node_results(const struct HyconContact *contact,
                                       size_t pair,
                                       struct HyconNodeResult *out,
                                       size_t len,
                                       size_t *needed);

// Tractions way (c), the B side: nodal forces, weights and pressures at the B nodes of `pair`,
// one per B node in polyline order: the size query gives the B node count.
//
// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
// writable.
HyconStatus hycon_contact_b_node_results(const struct HyconContact *contact,
                                         size_t pair,
                                         struct HyconBNodeResult *out,
                                         size_t len,
                                         size_t *needed);

// Tractions way (a), from the element stresses of body A: `tn ts` per A node of `pair` in its
// nodal frame, `2 * n_a` doubles (the size query gives `2 * n_a` on every path). Model API;
// host API when the host handed over the elements along A (`hycon_host_set_elements`) and
// its stiffness as a CSR matrix or a solver: the stresses come from the displacement, which
// costs its recovery (one solve) if not done yet. A host that handed over its condensed
// operator instead recovers the displacement itself, so hycon has none to take the stresses
// of: there a call with `out` fails with `HYCON_ERROR_INVALID_ARGUMENT` (the message says
// so); the multipliers (`hycon_contact_node_results`) are the tractions on that path.
//
// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range, no elements handed over, the
// condensed path, an A node or segment that is no node or edge of the elements handed over,
// `HYCON_ERROR_SOLVER` when the displacement or the stresses overflow (never non-finite
// values), `HYCON_ERROR_CALLBACK` when a host's solve fails.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable doubles; `needed` NULL or
// writable.
HyconStatus hycon_contact_stress_tractions(const struct HyconContact *contact,
                                           size_t pair,
                                           double *out,
                                           size_t len,
                                           size_t *needed);

// The iteration records from number `first` on (0-based; all increments in order, failed ones
// excluded): the full result has `count - first` records, `count` the number so far, so the
// size query with `first = 0` gives the count and a monitor-free host can fetch only the new
// records of each increment. `first` may equal the count (nothing to copy).
//
// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
// `HYCON_ERROR_INVALID_ARGUMENT` when `first` exceeds the count.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
// writable.
HyconStatus hycon_contact_records(const struct HyconContact *contact,
                                  size_t first,
                                  struct HyconIterationRecord *out,
                                  size_t len,
                                  size_t *needed);

// Where the time went so far, and the number of numeric factorizations of `K` done by hycon
// (1 per analysis; 0 when a host solves itself); either output may be NULL.
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`contact`), `HYCON_ERROR_INVALID_ARGUMENT` (a misaligned
// output).
//
// # Safety
// `contact` must be a live handle; outputs NULL or writable.
HyconStatus hycon_contact_timings(const struct HyconContact *contact,
                                  struct HyconTimings *timings,
                                  size_t *factorizations);

// Contact-element quantities of the A nodes of `pair` in the converged configuration (the
// reference one before the first increment): weights, frames, weighted gaps `R_C`, coverage;
// one per A node (the size query gives the A node count). Rust:
// `ContactAnalysis::surface(pair).nodes`.
//
// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
// writable.
HyconStatus hycon_contact_surface_nodes(const struct HyconContact *contact,
                                        size_t pair,
                                        struct HyconContactNode *out,
                                        size_t len,
                                        size_t *needed);

// The contact-element matrices `F^A` and `F^B` of `pair` (converged configuration) as a list
// of entries (row `k`, node `j`, side, value), rows in A node order. Rust:
// `ContactAnalysis::surface(pair)`, the `coupling` of each node.
//
// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
// writable.
HyconStatus hycon_contact_surface_coupling(const struct HyconContact *contact,
                                           size_t pair,
                                           struct HyconCouplingEntry *out,
                                           size_t len,
                                           size_t *needed);

// The constraint matrix `Kc` of `pair` (converged configuration) as a list of entries
// (`HyconConstraintEntry`: row, column, value). It has `2 n_a` rows: row `2k` the normal
// constraint `n_k . (sum_j F^A_kj u_j - sum_j F^B_kj u_j)` and row `2k + 1` the tangential one
// with `s_k`; columns are field indices (model dofs `2 node + direction`, or host equations;
// a host's fixed dofs are left out). The entries are in row-major order, rows ascending and
// columns strictly ascending within a row, so they are CSR-ready: `columns[i] = out[i].column`,
// `values[i] = out[i].value`, and `row_ptr[r + 1]` counts the entries with `row <= r`. The
// mixed system of a host that assembles it itself reads `[K  -Kc^T; -Kc  0] [u; t] = [f; -g]`
// with the active rows. Rust: `ContactAnalysis::constraint_rows`.
//
// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
// writable.
HyconStatus hycon_contact_constraint_rows(const struct HyconContact *contact,
                                          size_t pair,
                                          struct HyconConstraintEntry *out,
                                          size_t len,
                                          size_t *needed);

// Check one element's shape for a formulation: node count, finite coordinates, positive area,
// counter-clockwise order, convexity (tolerances relative to the element size). It takes no
// material, so it does not check what axisymmetry adds (4 nodes, `r >= 0`, no Pian-Sumihara):
// `hycon_element_stiffness` does.
//
// `coords`: `2 * n_nodes` doubles `x0 y0 x1 y1 ...`, nodes counter-clockwise.
//
// Returns `HYCON_OK`, or `HYCON_ERROR_BAD_ELEMENT` with a message naming the defect
// (degenerate, inverted, non-convex at local node i, node count), `HYCON_ERROR_INVALID_ARGUMENT`
// (unknown kind, non-finite coordinate), `HYCON_ERROR_NULL_POINTER`.
//
// # Safety
// `coords` must be NULL or point to `2 * n_nodes` readable doubles (only read when `n_nodes`
// suits `kind`).
HyconStatus hycon_element_check(HyconElementKind kind, size_t n_nodes, const double *coords);

// Element stiffness matrix `K` (`2n x 2n`, `n = n_nodes`) into `k_out`, row-major:
// `k_out[i * 2n + j] = K_ij`, rows and columns in element dof order `u0 v0 u1 v1 ...` (the
// node order of `coords`). `K` is symmetric, so column-major readers get the same matrix.
//
// * `coords`: `2 * n_nodes` doubles `x0 y0 x1 y1 ...`, nodes counter-clockwise. Q4 and
//   Pian-Sumihara take 4 nodes, the hybrid element 4 to 6 (corners plus mid-side nodes on
//   straight edges, in boundary order).
// * `material`: finite, `E > 0`, `-1 < nu < 0.5`, `t > 0`, known analysis; `t` multiplies `K`
//   in plane analyses; `HYCON_AXISYMMETRIC` (`t = 1`, `x = r >= 0`) integrates with `2 pi r`
//   (the whole ring's stiffness) and takes 4 nodes, hybrid (7 beta) or Q4.
// * `k_out`, `k_len`: output array of at least `(2n)^2` doubles (`HYCON_MAX_DOF^2 = 144` always
//   suffices); only the first `(2n)^2` are written, and only on success.
//
// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_ARGUMENT` (kind, non-finite
// coordinate), `HYCON_ERROR_INVALID_MATERIAL`, `HYCON_ERROR_BAD_ELEMENT`,
// `HYCON_ERROR_BUFFER_TOO_SMALL`.
//
// # Safety
// `coords` must be NULL or point to `2 * n_nodes` readable doubles; `material` NULL or a
// readable struct; `k_out` NULL or writable for `k_len` doubles.
HyconStatus hycon_element_stiffness(HyconElementKind kind,
                                    size_t n_nodes,
                                    const double *coords,
                                    const struct HyconMaterial *material,
                                    double *k_out,
                                    size_t k_len);

// Stress at the physical point `(px, py)` of an element, recovered from its nodal
// displacements `q` (`2 * n_nodes` doubles, dof order `u0 v0 u1 v1 ...`): `out` receives
// `{sx, sy, txy}` (3 doubles) in plane strain and plane stress, and
// `{sigma_r, sigma_z, tau_rz, sigma_theta}` (**4 doubles**) with a `HYCON_AXISYMMETRIC`
// material. `hycon_element_stress_components(material)` tells the count; a buffer of 4 always
// suffices.
//
// Hybrid elements evaluate their assumed stress field `P beta` with `beta = H^-1 G q`; Q4
// evaluates `D B q` (on the axis `r = 0` in axisymmetry with `eps_theta = du_r / dr`, the limit
// when `u_r = 0` there, as it must be prescribed). The point should lie in the
// element; outside it the value is an extrapolation (a non-finite result is reported as
// `HYCON_ERROR_INVALID_ARGUMENT`).
//
// # Safety
// `coords` and `q` must be NULL or point to `2 * n_nodes` readable doubles; `material` NULL or
// a readable struct; `out` NULL or writable for 3 doubles (4 in axisymmetry).
HyconStatus hycon_element_stress(HyconElementKind kind,
                                 size_t n_nodes,
                                 const double *coords,
                                 const struct HyconMaterial *material,
                                 const double *q,
                                 double px,
                                 double py,
                                 double *out);

// Stress parameters `beta` of a hybrid element, recovered from its nodal displacements `q`
// (`2 * n_nodes` doubles, dof order `u0 v0 u1 v1 ...`): 7 for the hybrid element with 4 or 5
// nodes (and the axisymmetric hybrid element), 12 with 6 nodes, 5 for Pian-Sumihara, 0 for Q4.
//
// `out`, `len`, `needed`: the header's size convention (`HYCON_MAX_BETA` always suffices; the
// size query `(NULL, 0, &needed)` gives the count, 0 for Q4).
//
// Errors: as `hycon_element_stress`, and `HYCON_ERROR_BUFFER_TOO_SMALL`.
//
// # Safety
// `coords` and `q` must be NULL or point to `2 * n_nodes` readable doubles; `material` NULL or
// a readable struct; `out` NULL or writable for `len` doubles; `needed` NULL or writable.
HyconStatus hycon_element_stress_params(HyconElementKind kind,
                                        size_t n_nodes,
                                        const double *coords,
                                        const struct HyconMaterial *material,
                                        const double *q,
                                        double *out,
                                        size_t len,
                                        size_t *needed);

// Number of stress components `hycon_element_stress` writes for `material`: 3 (`{sx, sy, txy}`)
// in plane strain and plane stress, 4 (`{sigma_r, sigma_z, tau_rz, sigma_theta}`) in
// axisymmetry, into `*out`.
//
// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_MATERIAL`.
//
// # Safety
// `material` NULL or a readable struct; `out` NULL or a writable `size_t`.
HyconStatus hycon_element_stress_components(const struct HyconMaterial *material, size_t *out);

// Traction `{tx, ty} = sigma n` (outward unit normal `n`) at parameter `s` in `[0, 1]` along
// boundary edge `edge` of an element, the edge running from local node `edge` to local node
// `edge + 1` (cyclically, so `edge < n_nodes`), from nodal displacements `q` (`2 * n_nodes`
// doubles, dof order `u0 v0 u1 v1 ...`). `out` receives 2 doubles on success (in axisymmetry
// the meridian traction `{t_r, t_z}`, a pressure: force per area).
//
// # Safety
// `coords` and `q` must be NULL or point to `2 * n_nodes` readable doubles; `material` NULL or
// a readable struct; `out` NULL or writable for 2 doubles.
HyconStatus hycon_element_edge_traction(HyconElementKind kind,
                                        size_t n_nodes,
                                        const double *coords,
                                        const struct HyconMaterial *material,
                                        const double *q,
                                        size_t edge,
                                        double s,
                                        double *out);

// Consistent nodal forces of a distributed load on boundary edge `edge` of an element: the
// edge runs from local node `edge` to local node `edge + 1` (cyclically, so `edge < n_nodes`;
// on the 5- and 6-node elements each segment between consecutive nodes is an edge), and
// carries a pressure and a traction, each linear between the edge's two nodes:
//
// * `pressure`: NULL (none) or 2 doubles, the pressure at the start and end node (force per
//   area, **positive pushing into the body**, along the inward normal);
// * `traction`: NULL (none) or 4 doubles `{tx0, ty0, tx1, ty1}`, the traction vector at the
//   start and end node (force per area; in axisymmetry `{t_r, t_z}`).
//
// With `n` the outward unit normal and `q = t - p n`, `out` receives
// `f_a = integral of N_a q m ds` (`N_a` the edge's linear shape functions; `m` the thickness in
// plane analyses, `2 pi r` in axisymmetry: full-circle forces), integrated exactly, as the
// element force vector: `2 * n_nodes` doubles in dof order `fx0 fy0 fx1 fy1 ...`, nonzero only
// at the edge's two nodes (`out`, `len`: at least `2 * n_nodes`; `HYCON_MAX_DOF` always
// suffices). Add it into the global load vector as a stiffness is assembled. In plane
// analyses a uniform pressure `p` on an edge of length `L` gives `-p n t L / 2` at each end.
//
// Not to be confused with `hycon_element_edge_traction`, which recovers the traction
// `sigma n` of a solved element.
//
// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_ARGUMENT` (kind, `edge`, non-finite
// coordinate or load value), `HYCON_ERROR_INVALID_MATERIAL`, `HYCON_ERROR_BAD_ELEMENT`
// (checked as for `hycon_element_stiffness`: an inverted element would turn the normal),
// `HYCON_ERROR_BUFFER_TOO_SMALL`.
//
// # Safety
// `coords` must be NULL or point to `2 * n_nodes` readable doubles; `material` NULL or a
// readable struct; `pressure` NULL or 2 readable doubles; `traction` NULL or 4 readable
// doubles; `out` NULL or writable for `len` doubles.
HyconStatus hycon_element_edge_load(HyconElementKind kind,
                                    size_t n_nodes,
                                    const double *coords,
                                    const struct HyconMaterial *material,
                                    size_t edge,
                                    const double *pressure,
                                    const double *traction,
                                    double *out,
                                    size_t len);

// Volume of an element into `*out`: area times thickness in plane analyses, and with a
// `HYCON_AXISYMMETRIC` material `integral of 2 pi r dA = 2 pi r_c A` (`r_c` the radius of the
// area centroid), the volume of the whole ring. Exact. (The area itself: call with a plane
// material of thickness 1.)
//
// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_ARGUMENT`,
// `HYCON_ERROR_INVALID_MATERIAL`, `HYCON_ERROR_BAD_ELEMENT` (the element is checked as for
// `hycon_element_stiffness`).
//
// # Safety
// `coords` must be NULL or point to `2 * n_nodes` readable doubles; `material` NULL or a
// readable struct; `out` NULL or a writable double.
HyconStatus hycon_element_volume(HyconElementKind kind,
                                 size_t n_nodes,
                                 const double *coords,
                                 const struct HyconMaterial *material,
                                 double *out);

// Jacobian quality of an element into `*out`: the **scaled Jacobian**, the smallest over the
// element's true corners of `det J / (|dx/dxi| |dx/deta|)`, which is the sine of the interior
// angle there (mid-side nodes of the 5- and 6-node elements are not corners). 1 for a
// rectangle, toward 0 as a corner angle nears 0 or 180 degrees; independent of size, position
// and rotation; in `(0, 1]` for every element `hycon_element_check` accepts (so a host can flag
// elements below its own threshold, e.g. 0.2). It does not measure the aspect ratio.
//
// Errors: as `hycon_element_check`, and `HYCON_ERROR_NULL_POINTER` for `out`.
//
// # Safety
// `coords` must be NULL or point to `2 * n_nodes` readable doubles; `out` NULL or a writable
// double.
HyconStatus hycon_element_quality(HyconElementKind kind,
                                  size_t n_nodes,
                                  const double *coords,
                                  double *out);

// Stress at natural coordinates `(xi, eta)` in `[-1, 1]^2` of an element, recovered from its
// nodal displacements `q` (`2 * n_nodes` doubles): `out` receives what `hycon_element_stress`
// writes (`{sx, sy, txy}`, or 4 values `{sigma_r, sigma_z, tau_rz, sigma_theta}` in
// axisymmetry).
//
// Natural coordinates are those of the element's bilinear map: node 0 at `(-1, -1)`, node 1 at
// `(1, -1)`, node 2 at `(1, 1)`, node 3 at `(-1, 1)`; for the 5- and 6-node hybrid elements the
// map of their 4 true corners in node order (the first corner at `(-1, -1)`), the mid-side nodes
// taking no part. Q4, Pian-Sumihara and the axisymmetric elements evaluate their field there
// (at a host's Gauss points, for instance); the plane hybrid element, whose field lives in
// physical coordinates, gives the stress at the mapped point, the same as
// `hycon_element_stress` there.
//
// Errors: as `hycon_element_stress`; `HYCON_ERROR_INVALID_ARGUMENT` also for `xi` or `eta`
// outside `[-1, 1]` and for a 5- or 6-node element with only 3 true corners.
//
// # Safety
// `coords` and `q` must be NULL or point to `2 * n_nodes` readable doubles; `material` NULL or
// a readable struct; `out` NULL or writable for 3 doubles (4 in axisymmetry).
HyconStatus hycon_element_stress_natural(HyconElementKind kind,
                                         size_t n_nodes,
                                         const double *coords,
                                         const struct HyconMaterial *material,
                                         const double *q,
                                         double xi,
                                         double eta,
                                         double *out);

// Consistent nodal forces of a distributed load on face `face` (0 to 5, numbering at
// `HyconBrickKind`) of a brick, each value given at the face's 4 nodes in the face's node order
// (face 0 is nodes `0 4 7 3`, ...) and interpolated bilinearly:
//
// * `pressure`: NULL (none) or 4 doubles (force per area, **positive pushing into the body**);
// * `traction`: NULL (none) or 12 doubles `{tx, ty, tz}` per face node (force per area).
//
// With `n` the outward unit normal and `q = t - p n`, `out` receives
// `f_k = integral over the face of N_k q dA` as the brick's force vector: 24 doubles in dof
// order `fx0 fy0 fz0 fx1 ...`, nonzero only at the face's 4 nodes (`len >= 24`). 2 x 2 Gauss:
// exact for the pressure on any face, warped or not (the forces of a uniform pressure sum to
// `-p` times the face's projected area vector), and for the traction on plane faces; on a
// warped face the traction part is approximated (error of the order of the warp squared).
//
// Not to be confused with `hycon_brick_face_traction`, which recovers the traction `sigma n`
// of a solved brick.
//
// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_ARGUMENT` (kind, `face`, non-finite
// coordinate or load value), `HYCON_ERROR_BAD_ELEMENT` (the shape check of
// `hycon_brick_check`), `HYCON_ERROR_BUFFER_TOO_SMALL`.
//
// # Safety
// `coords` NULL or 24 readable doubles; `pressure` NULL or 4 readable doubles; `traction` NULL
// or 12 readable doubles; `out` NULL or writable for `len` doubles.
HyconStatus hycon_brick_face_load(HyconBrickKind kind,
                                  const double *coords,
                                  size_t face,
                                  const double *pressure,
                                  const double *traction,
                                  double *out,
                                  size_t len);

// Volume of a brick into `*out` (`integral of det J`, exact for any trilinear brick).
//
// Errors: as `hycon_brick_check`, and `HYCON_ERROR_NULL_POINTER` for `out`.
//
// # Safety
// `coords` NULL or 24 readable doubles; `out` NULL or a writable double.
HyconStatus hycon_brick_volume(HyconBrickKind kind, const double *coords, double *out);

// Jacobian quality of a brick into `*out`: the **scaled Jacobian**, the smallest over the 8
// corners of `det J / (|J_1| |J_2| |J_3|)` (`J_a = dx/dxi_a`; at a corner, half its three
// edges), the volume of the corner's edge parallelepiped over the product of its edge lengths.
// 1 for a rectangular box, toward 0 as a corner flattens; independent of size, position and
// rotation; in `(0, 1]` for every brick the strict shape policy accepts (so a host can flag
// bricks below its own threshold, e.g. 0.2), at or below 0 where the default policy warns of a
// non-positive corner Jacobian. It does not measure the aspect ratio.
//
// Errors: as `hycon_brick_check`, and `HYCON_ERROR_NULL_POINTER` for `out`.
//
// # Safety
// `coords` NULL or 24 readable doubles; `out` NULL or a writable double.
HyconStatus hycon_brick_quality(HyconBrickKind kind, const double *coords, double *out);

// Stress `{sxx, syy, szz, sxy, syz, szx}` at natural coordinates `(xi, eta, zeta)` in
// `[-1, 1]^3` of a brick (node 0 at `(-1, -1, -1)`, numbering at `HyconBrickKind`), from its
// nodal displacements `q` (24 doubles): the hybrid brick's `P beta` or the H8's `D B q` there,
// the same as `hycon_brick_stress` at the mapped physical point. `out` receives 6 doubles.
//
// Errors: as `hycon_brick_stress`; `HYCON_ERROR_INVALID_ARGUMENT` also for a natural
// coordinate outside `[-1, 1]`.
//
// # Safety
// `coords` and `q` NULL or 24 readable doubles; `material` NULL or a readable struct; `out`
// NULL or writable for 6 doubles.
HyconStatus hycon_brick_stress_natural(HyconBrickKind kind,
                                       const double *coords,
                                       const struct HyconSolidMaterial *material,
                                       const double *q,
                                       double xi,
                                       double eta,
                                       double zeta,
                                       double *out);

// Check one brick's shape under the default policy (`HyconShapePolicy`): finite coordinates,
// no coincident nodes, positive volume (node order as in the header's brick section),
// `det J > 0` at every integration point; a corner where `det J <= 0` and a face warped by more
// than 45 degrees are warnings. Both kinds accept the same shapes. Tolerances relative to the
// longest edge. `hycon_brick_shape` chooses the policy and reports the measures.
//
// Returns `HYCON_OK`, `HYCON_WARNING_SHAPE` with a message naming the corner or the face
// (0.8 returned `HYCON_ERROR_BAD_ELEMENT` there), or `HYCON_ERROR_BAD_ELEMENT` with a message
// naming the defect (degenerate, inverted, Jacobian not positive at the integration point
// nearest local node i), `HYCON_ERROR_INVALID_ARGUMENT` (unknown kind, non-finite
// coordinate), `HYCON_ERROR_NULL_POINTER`.
//
// # Safety
// `coords` must be NULL or point to 24 readable doubles.
HyconStatus hycon_brick_check(HyconBrickKind kind, const double *coords);

// Check one brick's shape under `policy` and measure it (the policies and the warp measure:
// `HyconShapePolicy`). Both kinds accept the same shapes. `report` (NULL: not wanted) receives
// the measures on success and on a warning.
//
// Returns `HYCON_OK`; `HYCON_WARNING_SHAPE` (default policy only) with a message naming the
// corner and its `det J / h^3`, or the face and its warp; `HYCON_ERROR_BAD_ELEMENT` with a
// message naming the defect; `HYCON_ERROR_INVALID_ARGUMENT` (unknown kind or policy,
// non-finite coordinate, misaligned pointer); `HYCON_ERROR_NULL_POINTER`.
//
// # Safety
// `coords` must be NULL or point to 24 readable doubles; `report` NULL or writable.
HyconStatus hycon_brick_shape(HyconBrickKind kind,
                              const double *coords,
                              HyconShapePolicy policy,
                              struct HyconShapeReport *report);

// Brick stiffness `K` (24 x 24) into `k_out`, row-major (`k_out[i * 24 + j] = K_ij`), rows and
// columns in dof order `u0 v0 w0 u1 ...`. Symmetric, so column-major readers get the same.
// Hybrid: `K = G^T H^-1 G`, `H = integral of P^T S P dV`, `G = integral of P^T B dV` (2x2x2
// Gauss); H8: `K = integral of B^T D B dV`.
//
// * `coords`: 24 doubles `x0 y0 z0 x1 ...`, node order of the header's brick section.
// * `material`: finite, `E > 0`, `-1 < nu < 0.5`.
// * `k_out`, `k_len`: at least 576 doubles; written only on success.
//
// The shape is checked under the default policy: `HYCON_WARNING_SHAPE` (`k_out` written) for a
// corner Jacobian or a warp the strict policy rejects (see `HyconShapePolicy`).
//
// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_ARGUMENT` (kind, non-finite
// coordinate), `HYCON_ERROR_INVALID_MATERIAL`, `HYCON_ERROR_BAD_ELEMENT`,
// `HYCON_ERROR_BUFFER_TOO_SMALL`.
//
// # Safety
// `coords` NULL or 24 readable doubles; `material` NULL or a readable struct; `k_out` NULL or
// writable for `k_len` doubles.
HyconStatus hycon_brick_stiffness(HyconBrickKind kind,
                                  const double *coords,
                                  const struct HyconSolidMaterial *material,
                                  double *k_out,
                                  size_t k_len);

// Stress parameters `beta = H^-1 G q` of a brick from its nodal displacements `q` (24 doubles,
// dof order `u0 v0 w0 u1 ...`): 18 for the hybrid brick (the first 6 are the mean stress
// `{sxx, syy, szz, sxy, syz, szx}`), 0 for H8.
//
// `out`, `len`, `needed`: the header's size convention (`HYCON_BRICK_MAX_BETA` always
// suffices; `(NULL, 0, &needed)` asks for the count). `HYCON_WARNING_SHAPE` as
// `hycon_brick_stiffness`.
//
// # Safety
// `coords` and `q` NULL or 24 readable doubles; `material` NULL or a readable struct; `out`
// NULL or writable for `len` doubles; `needed` NULL or writable.
HyconStatus hycon_brick_stress_params(HyconBrickKind kind,
                                      const double *coords,
                                      const struct HyconSolidMaterial *material,
                                      const double *q,
                                      double *out,
                                      size_t len,
                                      size_t *needed);

// Stress `{sxx, syy, szz, sxy, syz, szx}` at the physical point `(px, py, pz)` of a brick from
// its nodal displacements `q` (24 doubles). The point should lie in the brick (it is mapped to
// natural coordinates by Newton's method); outside, the value is an extrapolation. `out`
// receives 6 doubles on success. `HYCON_WARNING_SHAPE` as `hycon_brick_stiffness`.
//
// # Safety
// `coords` and `q` NULL or 24 readable doubles; `material` NULL or a readable struct; `out`
// NULL or writable for 6 doubles.
HyconStatus hycon_brick_stress(HyconBrickKind kind,
                               const double *coords,
                               const struct HyconSolidMaterial *material,
                               const double *q,
                               double px,
                               double py,
                               double pz,
                               double *out);

// Traction `{tx, ty, tz} = sigma n` (outward unit normal `n`) at face parameters `(s, t)` in
// `[-1, 1]^2` of face `face` (0 to 5, numbering in the header's brick section) of a brick,
// from its nodal displacements `q` (24 doubles). `out` receives 3 doubles on success.
// `HYCON_WARNING_SHAPE` as `hycon_brick_stiffness`.
//
// # Safety
// `coords` and `q` NULL or 24 readable doubles; `material` NULL or a readable struct; `out`
// NULL or writable for 3 doubles.
HyconStatus hycon_brick_face_traction(HyconBrickKind kind,
                                      const double *coords,
                                      const struct HyconSolidMaterial *material,
                                      const double *q,
                                      size_t face,
                                      double s,
                                      double t,
                                      double *out);

// Create a 3D model from its mesh and materials (nodes, elements, materials, as
// `hycon_model_new`):
//
// * `coords`: `3 n_nodes` doubles `x0 y0 z0 x1 ...`;
// * `elements`: the bricks (`HyconBrickBlock`: `8 n_elements` node ids in the brick node
//   order, their material indices or NULL for all 0, the formulation);
// * `materials`: `n_materials` materials.
//
// The arrays are copied. Every brick is checked as by `hycon_brick_check`: a brick the default
// shape policy only warns about gives `HYCON_WARNING_SHAPE` with the model made (the message
// names the bricks).
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`out`, `coords`, `elements`, `materials`, or an array of
// `elements` with a nonzero length), `HYCON_ERROR_INVALID_ARGUMENT` (no nodes or bricks, an
// unknown node id or material index, non-finite coordinates, unknown kind, misaligned
// pointers), `HYCON_ERROR_INVALID_MATERIAL`, `HYCON_ERROR_BAD_ELEMENT` (a degenerate or
// inverted brick, named by index).
//
// # Safety
// `out` must point to a writable pointer; `coords` NULL or `3 n_nodes` readable doubles;
// `elements` NULL or a readable view whose arrays hold the stated counts; `materials` NULL or
// `n_materials` readable structs.
HyconStatus hycon_solid_model_new(struct HyconSolidModel **out,
                                  const double *coords,
                                  size_t n_nodes,
                                  const struct HyconBrickBlock *elements,
                                  const struct HyconSolidMaterial *materials,
                                  size_t n_materials);

// Free a 3D model (NULL is a no-op). Analyses made from it keep their own copy.
//
// # Safety
// `model` must be NULL or a live handle from `hycon_solid_model_new`, not used afterwards.
void hycon_solid_model_free(struct HyconSolidModel *model);

// Prescribe the displacement of `nodes` in `directions` (any nonzero OR of `HYCON_X`,
// `HYCON_Y`, `HYCON_Z`; `HYCON_XYZ` all three). The values are given per increment
// (`prescribed` of `hycon_solid_contact_increment`). Contact nodes may be prescribed too.
//
// Errors: `HYCON_ERROR_INVALID_ARGUMENT` for an unknown node id, unknown `directions`, or a
// displacement component prescribed twice (listed twice in `nodes`, prescribed by an earlier
// call, or tied to the plate); on an error nothing is prescribed.
//
// # Safety
// `model` must be a live handle; `nodes` NULL or `n` readable ids.
HyconStatus hycon_solid_model_prescribe(struct HyconSolidModel *model,
                                        const size_t *nodes,
                                        size_t n,
                                        HyconDirections directions);

// Add a contact pair: the multiplier side `a` and the opposite side `b` (brick faces, each a
// boundary face of the mesh, listed once) and the Coulomb coefficient `friction >= 0` (0:
// frictionless; the cone is circular). The pair's index (0, 1, ...) is written to `index`
// unless it is NULL. A pair's A nodes are numbered in increasing node id order (the order of
// `hycon_solid_contact_node_results` and the rows of the coupling and constraint entries), B
// nodes likewise.
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`model`, `a`, `b`, or their `faces` with `n > 0`);
// `HYCON_ERROR_INVALID_ARGUMENT` naming the side and the face for an unknown brick or local
// face, a side without faces, a face that is not a boundary face of the mesh (shared by two
// bricks) or is listed twice, a side that is not one connected surface (faces joined by
// shared edges, at most two on an edge), both sides on one body (bricks joined by shared
// nodes), a bad friction coefficient, a misaligned pointer. (Faces the kernel cannot
// integrate, warped beyond 45 degrees, and sides that never face each other are refused by
// `hycon_solid_contact_new`.) On an error the model is unchanged.
//
// # Safety
// `model` must be a live handle; `a`, `b` NULL or readable views holding `2 n` values each;
// `index` NULL or writable.
HyconStatus hycon_solid_model_add_pair(struct HyconSolidModel *model,
                                       const struct HyconBrickFaces *a,
                                       const struct HyconBrickFaces *b,
                                       double friction,
                                       size_t *index);

// Declare a symmetry plane of the model: the plane through `point` (3 doubles) normal to
// `normal` (3 doubles, either orientation, normalised here). An A node on it gets the
// mirrored model's normal and no tangential traction across it. The model must hold the nodes
// on the plane normal to it (`hycon_solid_model_prescribe`): a quarter or a half model.
//
// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_ARGUMENT` (a non-finite value, a
// zero normal, a misaligned pointer).
//
// # Safety
// `model` must be a live handle; `point` and `normal` NULL or 3 readable doubles each.
HyconStatus hycon_solid_model_add_symmetry_plane(struct HyconSolidModel *model,
                                                 const double *point,
                                                 const double *normal);

// Tie `nodes` (a face of one body, none of them a contact node) to a rigid plate whose x, y
// and z translations are driven per increment by `hycon_solid_contact_increment_with_plate`,
// each by displacement or by force, as `hycon_model_set_plate` does in the plane. The nodes
// are prescribed in x, y and z by this call. A body held only by the plate and by contact
// (a pressed sphere) then takes a prescribed force. With symmetry planes the plate does not
// move across them: a translation with a component along a plane's normal must be driven by
// displacement 0 (a quarter model's plate moves along z only), so the plate holds its nodes
// on a symmetry plane: prescribe the other nodes on the planes, not those.
//
// Errors: `HYCON_ERROR_INVALID_ARGUMENT` for no nodes, an unknown node id, or a node already
// prescribed in a direction (by `hycon_solid_model_prescribe`, twice in `nodes`, or by an
// earlier plate: a model has one plate); on an error the model is unchanged. A plate node
// that is a contact node is refused by `hycon_solid_contact_new`.
//
// # Safety
// `model` must be a live handle; `nodes` NULL or `n` readable ids.
HyconStatus hycon_solid_model_set_plate(struct HyconSolidModel *model,
                                        const size_t *nodes,
                                        size_t n);

// Start a 3D contact analysis of a model (copied: the model may be freed or changed
// afterwards): validate, assemble, factor `K` once and set up the contact boundary's
// flexibility. `options` NULL means the defaults (`search_distance` is relative to the mean A
// face size, the square root of the mean A face area).
//
// Errors: `HYCON_ERROR_SINGULAR` (a body not held against rigid motion),
// `HYCON_ERROR_INVALID_ARGUMENT` naming the pair (bad options, A and B sharing a node, a
// contact face the kernel cannot integrate (degenerate, warped beyond 45 degrees), sides that
// never face each other (no A face and B face with opposed normals each in front of the
// other, at any distance), no continuous tangent frame over a pair: split the surface into
// pairs, a symmetry plane no model node lies on, a plate node that is a contact node),
// `HYCON_ERROR_SOLVER`.
//
// # Safety
// `out` must point to a writable pointer, `model` be a live handle, `options` NULL or
// readable.
HyconStatus hycon_solid_contact_new(struct HyconSolidContact **out,
                                    const struct HyconSolidModel *model,
                                    const struct HyconContactOptions *options);

// Free a 3D analysis (NULL is a no-op).
//
// # Safety
// `contact` must be NULL or a live handle, not used afterwards.
void hycon_solid_contact_free(struct HyconSolidContact *contact);

// One increment with **total** values (from the reference state), as
// `hycon_contact_increment`: `load` the external nodal forces over all `3 n_nodes` dofs
// (`u0 v0 w0 u1 ...`), `prescribed` the values at the prescribed dofs over the same entries
// (the others are ignored). The automatic cutback, `info` and the errors are the plane's.
//
// # Safety
// `contact` must be a live handle; arrays NULL or of the stated lengths; `info` NULL or
// writable.
HyconStatus hycon_solid_contact_increment(struct HyconSolidContact *contact,
                                          const double *load,
                                          size_t load_len,
                                          const double *prescribed,
                                          size_t prescribed_len,
                                          struct HyconIncrementInfo *info);

// As `hycon_solid_contact_increment` for a model with a plate (`hycon_solid_model_set_plate`):
// `control` and `value` (3 entries each, x, y, z) drive the plate's translations
// (`HYCON_PLATE_DISPLACEMENT`: total displacement; `HYCON_PLATE_FORCE`: total force on the
// plate, its motion solved for), as `hycon_contact_increment_with_plate` in the plane.
//
// Errors: those of `hycon_solid_contact_increment`; `HYCON_ERROR_INVALID_ARGUMENT` without a
// plate, for an unknown control, a non-finite value, or a translation with a component along
// a symmetry plane's normal that is not a displacement of 0; `HYCON_ERROR_SINGULAR` for a
// force-controlled translation that no constraint of the contact set resists (control it by
// displacement). On an error the analysis is as before the call.
//
// # Safety
// As `hycon_solid_contact_increment`; `control` and `value` must hold 3 values each.
HyconStatus hycon_solid_contact_increment_with_plate(struct HyconSolidContact *contact,
                                                     const double *load,
                                                     size_t load_len,
                                                     const double *prescribed,
                                                     size_t prescribed_len,
                                                     const HyconPlateControl *control,
                                                     const double *value,
                                                     struct HyconIncrementInfo *info);

// The converged plate displacement and the force the plate exerts on the body (3 values each,
// x, y, z), as `hycon_contact_plate`. `HYCON_ERROR_INVALID_ARGUMENT` without a plate.
//
// # Safety
// `contact` must be a live handle; `displacement` and `force` must hold 3 writable doubles.
HyconStatus hycon_solid_contact_plate(const struct HyconSolidContact *contact,
                                      double *displacement,
                                      double *force);

// The displacement of the last converged increment over the `3 n_nodes` dofs (zero before the
// first), as `hycon_contact_displacement`; its size query gives the field length, also the
// `load_len` of an increment.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable doubles; `needed` NULL or
// writable.
HyconStatus hycon_solid_contact_displacement(const struct HyconSolidContact *contact,
                                             double *out,
                                             size_t len,
                                             size_t *needed);

// The displacement increment of the last converged increment, as
// `hycon_contact_displacement_increment`.
//
// # Safety
// As `hycon_solid_contact_displacement`.
HyconStatus hycon_solid_contact_displacement_increment(const struct HyconSolidContact *contact,
                                                       double *out,
                                                       size_t len,
                                                       size_t *needed);

// The contact forces of the last converged increment over the field (`K u = load + forces`),
// as `hycon_contact_forces`.
//
// # Safety
// As `hycon_solid_contact_displacement`.
HyconStatus hycon_solid_contact_forces(const struct HyconSolidContact *contact,
                                       double *out,
                                       size_t len,
                                       size_t *needed);

// The iteration records from number `first` on, as `hycon_contact_records`.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
// writable.
HyconStatus hycon_solid_contact_records(const struct HyconSolidContact *contact,
                                        size_t first,
                                        struct HyconIterationRecord *out,
                                        size_t len,
                                        size_t *needed);

// Where the time went and the number of factorizations, as `hycon_contact_timings`.
//
// # Safety
// `contact` must be a live handle; outputs NULL or writable.
HyconStatus hycon_solid_contact_timings(const struct HyconSolidContact *contact,
                                        struct HyconTimings *timings,
                                        size_t *factorizations);

// Tractions way (b), the multipliers: converged results at the A nodes of `pair` (states,
// `tn`, `ts`, slip directions, frames, gaps, nodal forces), one per A node in increasing node
// id order: the size query gives the A node count.
//
// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
// writable.
HyconStatus hycon_solid_contact_node_results(const struct HyconSolidContact *contact,
                                             size_t pair,
                                             struct HyconSolidNodeResult *out,
                                             size_t len,
                                             size_t *needed);

// Tractions way (c), the B side: nodal forces, weights and pressures at the B nodes of
// `pair`, one per B node in increasing node id order: the size query gives the B node count.
//
// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
// writable.
HyconStatus hycon_solid_contact_b_node_results(const struct HyconSolidContact *contact,
                                               size_t pair,
                                               struct HyconSolidBNodeResult *out,
                                               size_t len,
                                               size_t *needed);

// Contact-element quantities of the A nodes of `pair` in the converged configuration (the
// reference one before the first increment): weights, frames, weighted gaps `R_C`, coverage;
// one per A node. Rust: `ContactAnalysis::surface(pair).nodes`.
//
// Sizes and errors follow the header's size convention (`out`, `len`, `needed`); also
// `HYCON_ERROR_INVALID_ARGUMENT` for a pair index out of range.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
// writable.
HyconStatus hycon_solid_contact_surface_nodes(const struct HyconSolidContact *contact,
                                              size_t pair,
                                              struct HyconSolidContactNode *out,
                                              size_t len,
                                              size_t *needed);

// The contact-element matrices `F^A` (`D`) and `F^B` (`M`) of `pair` as entries (row = A
// node index), as `hycon_contact_surface_coupling`.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
// writable.
HyconStatus hycon_solid_contact_surface_coupling(const struct HyconSolidContact *contact,
                                                 size_t pair,
                                                 struct HyconCouplingEntry *out,
                                                 size_t len,
                                                 size_t *needed);

// The constraint matrix `Kc` of `pair` as row-major, CSR-ready entries, as
// `hycon_contact_constraint_rows`, with `3 n_a` rows: `3k` the normal constraint of A node
// `k`, `3k + 1` and `3k + 2` the tangential ones along `s1` and `s2` (empty for a tangent
// dropped by a symmetry plane); columns are model dofs `3 node + direction`.
//
// # Safety
// `contact` must be a live handle; `out` NULL or `len` writable structs; `needed` NULL or
// writable.
HyconStatus hycon_solid_contact_constraint_rows(const struct HyconSolidContact *contact,
                                                size_t pair,
                                                struct HyconConstraintEntry *out,
                                                size_t len,
                                                size_t *needed);

// Create a 3D host description for a system of `n_equations` equations (the host's `K` after
// its boundary conditions: symmetric positive definite), as `hycon_host_new`.
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`out`), `HYCON_ERROR_INVALID_ARGUMENT` (`n_equations`
// zero or beyond what memory can address).
//
// # Safety
// `out` must point to a writable pointer.
HyconStatus hycon_solid_host_new(struct HyconSolidHost **out, size_t n_equations);

// Free a 3D host description (NULL is a no-op). Analyses made from it are independent of it.
//
// # Safety
// `host` must be NULL or a live handle from `hycon_solid_host_new`, not used afterwards.
void hycon_solid_host_free(struct HyconSolidHost *host);

// Add contact nodes: ids of the host's numbering, reference coordinates (3 per node) and the
// equation of each displacement component (`HYCON_FIXED` for one the host holds at zero).
// Every node of a face of `hycon_solid_host_add_pair` must have been added; a node added
// again must come with the same coordinates and equations. The nodes' order is the order of
// the per-node results (A nodes, B nodes) and of `hycon_solid_host_contact_equations`. The
// arrays are copied; on an error the host is unchanged.
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `nodes`, an array with `n > 0`),
// `HYCON_ERROR_INVALID_ARGUMENT` (non-finite coordinates, an equation out of range or shared
// by two nodes, a node given before differently, a misaligned pointer).
//
// # Safety
// `host` must be a live handle; `nodes` NULL or a readable view whose arrays hold the stated
// counts.
HyconStatus hycon_solid_host_add_nodes(struct HyconSolidHost *host,
                                       const struct HyconSolidHostNodes *nodes);

// Add a contact pair: the multiplier side `a` and the opposite side `b` as faces of 4 node ids
// each (`HyconHostFaces`, counter-clockwise seen from outside their body), every node one
// added by `hycon_solid_host_add_nodes`, and the Coulomb coefficient `friction >= 0` (0:
// frictionless; the cone is circular). The pair's index (0, 1, ...) is written to `index`
// unless it is NULL. Checked here: the friction, each side at least one face, 4 distinct
// nodes per face, no face listed twice, no node on both sides, every node known. Checked at
// `hycon_solid_contact_new_host`: the faces' shapes (a flat, warped or inverted face the
// kernel cannot integrate is refused by name), a continuous frame over A, and that A and B
// face each other. The arrays are copied; on an error the host is unchanged.
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `a`, `b`, their `nodes` with `n > 0`),
// `HYCON_ERROR_INVALID_ARGUMENT` naming the side and the face (the checks above, a
// misaligned pointer).
//
// # Safety
// `host` must be a live handle; `a`, `b` NULL or readable views holding `4 n` ids each;
// `index` NULL or writable.
HyconStatus hycon_solid_host_add_pair(struct HyconSolidHost *host,
                                      const struct HyconHostFaces *a,
                                      const struct HyconHostFaces *b,
                                      double friction,
                                      size_t *index);

// Say which side body A of pair `pair` (an index from `hycon_solid_host_add_pair`) is on:
// `inside` is a point inside body A (3 doubles), above A's faces rather than beyond their
// free edges: the centroid of an element that owns an A face, say. It must lie on A's body
// side of its nearest A face (checked at `hycon_solid_contact_new_host`), which confirms A's
// orientation; B's follows from facing A. Needed where A and B touch (lie within half a face
// of each other) wherever they are near each other: facing surfaces and back-to-back ones
// then look the same. Replaces an earlier point of the pair.
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `inside`), `HYCON_ERROR_INVALID_ARGUMENT` (an
// unknown pair, a non-finite point). On an error the host is unchanged.
//
// # Safety
// `host` must be a live handle; `inside` NULL or 3 readable doubles.
HyconStatus hycon_solid_host_set_pair_inside(struct HyconSolidHost *host,
                                             size_t pair,
                                             const double *inside);

// Declare a symmetry plane of the host's model: the plane through `point` normal to `normal`
// (3 doubles each), as `hycon_solid_model_add_symmetry_plane`. The host holds the nodes on it
// normal to it (their equation of that component `HYCON_FIXED`, or an identity row).
//
// Errors: `HYCON_ERROR_NULL_POINTER`, `HYCON_ERROR_INVALID_ARGUMENT` (a non-finite value, a
// zero normal, a misaligned pointer).
//
// # Safety
// `host` must be a live handle; `point` and `normal` NULL or 3 readable doubles each.
HyconStatus hycon_solid_host_add_symmetry_plane(struct HyconSolidHost *host,
                                                const double *point,
                                                const double *normal);

// Give the host's stiffness as a CSR matrix over its `n_equations` equations (copied), as
// `hycon_host_set_csr` (the same arrays, triangles, checks and errors). Replaces an earlier
// matrix, solver or condensed operator.
//
// # Safety
// `host` must be a live handle; the arrays NULL or of the stated lengths.
HyconStatus hycon_solid_host_set_csr(struct HyconSolidHost *host,
                                     const size_t *row_ptr,
                                     const size_t *columns,
                                     const double *values,
                                     HyconTriangle triangle);

// Let the host solve with its own factorization, as `hycon_host_set_solver`
// (`HyconSolveFn`; `user_data` must outlive every analysis made from this description; called
// on the thread that calls into the `HyconSolidContact`). Replaces an earlier matrix, solver
// or condensed operator.
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`host`, `solve`).
//
// # Safety
// `host` must be a live handle; `solve` a valid function as documented.
HyconStatus hycon_solid_host_set_solver(struct HyconSolidHost *host,
                                        HyconSolveFn solve,
                                        void *user_data);

// Hand over the host's condensed operator over its contact candidate equations, as
// `hycon_host_set_condensed` (the same struct, checks and errors): every increment then takes
// as `load` the load image `u0 = K^-1 rhs` at the `m` candidates, and the host recovers its
// displacement itself from `hycon_solid_contact_forces` (`hycon_solid_contact_displacement`
// and `hycon_solid_contact_displacement_increment` fail). `hycon_solid_host_contact_equations`
// lists the equations the candidates must hold. Replaces an earlier matrix, solver or
// condensed operator.
//
// # Safety
// `host` must be a live handle; `condensed` NULL or a readable `HyconCondensed` whose arrays
// hold the stated counts.
HyconStatus hycon_solid_host_set_condensed(struct HyconSolidHost *host,
                                           const struct HyconCondensed *condensed);

// The host's contact equations: every equation of its contact nodes (not `HYCON_FIXED`), in
// the order the nodes were added (`u_x`, `u_y`, `u_z`), each once: what the candidates of
// `hycon_solid_host_set_condensed` must hold.
//
// Sizes and errors follow the header's size convention (`out`, `len`, `needed`).
//
// # Safety
// `host` must be a live handle; `out` NULL or `len` writable values; `needed` NULL or
// writable.
HyconStatus hycon_solid_host_contact_equations(const struct HyconSolidHost *host,
                                               int64_t *out,
                                               size_t len,
                                               size_t *needed);

// Start a 3D contact analysis of a host's system (`ContactAnalysis::solid_host`): factor its
// CSR matrix once, or build the flexibility from batched solves through its callback, or read
// it off its condensed operator, and check the faces. The result is a `HyconSolidContact`:
// every `hycon_solid_contact_*` function applies, with the field over the host's `n`
// equations (`load` of an increment its right-hand side, `prescribed` NULL with length 0;
// the load image for a condensed operator), the per-node results in the order the nodes were
// added, node ids of the host's numbering, and the constraint rows' columns host equations.
// `options` NULL means the defaults.
//
// Errors: `HYCON_ERROR_NULL_POINTER` (`out`, `host`), `HYCON_ERROR_INVALID_ARGUMENT` (no
// pair, no stiffness, solver or condensed operator, a face the kernel cannot integrate (flat,
// warped, inverted) or no continuous frame over A, naming the pair; a pair whose surfaces run
// the same way or lie back to back; a pair whose surfaces touch wherever they are near each
// other without `hycon_solid_host_set_pair_inside`; a point inside A on A's outward side; a
// contact equation that is no candidate of the condensed operator; bad options),
// `HYCON_ERROR_SINGULAR` (the CSR matrix or the Schur complement is not positive definite: a
// body not held), `HYCON_ERROR_SOLVER`, `HYCON_ERROR_CALLBACK` (the solver failed or returned
// non-finite values).
//
// # Safety
// `out` must point to a writable pointer, `host` be a live handle, `options` NULL or
// readable.
HyconStatus hycon_solid_contact_new_host(struct HyconSolidContact **out,
                                         const struct HyconSolidHost *host,
                                         const struct HyconContactOptions *options);

#ifdef __cplusplus
}  // extern "C"
#endif  // __cplusplus

#endif  /* HYCON_H */
