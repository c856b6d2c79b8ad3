/* Compile check: include/hycon.h is standalone, include-guarded and strict C99
 * (-std=c99 -Wall -Wextra -Werror -pedantic), and the library matches the header's version. */
#include "hycon.h"
#include "hycon.h" /* twice on purpose: the include guard must hold */

#include <stddef.h>
#include <stdio.h>

/* C99 has no _Static_assert: a negative array size fails the compilation instead. */
#define HYCON_STATIC_ASSERT(name, cond) typedef char hycon_static_assert_##name[(cond) ? 1 : -1]

HYCON_STATIC_ASSERT(material_size, sizeof(HyconMaterial) == 32);
HYCON_STATIC_ASSERT(material_youngs, offsetof(HyconMaterial, youngs) == 0);
HYCON_STATIC_ASSERT(material_poisson, offsetof(HyconMaterial, poisson) == 8);
HYCON_STATIC_ASSERT(material_thickness, offsetof(HyconMaterial, thickness) == 16);
HYCON_STATIC_ASSERT(material_analysis, offsetof(HyconMaterial, analysis) == 24);
HYCON_STATIC_ASSERT(status_size, sizeof(HyconStatus) == 4);
HYCON_STATIC_ASSERT(kind_size, sizeof(HyconElementKind) == 4);
HYCON_STATIC_ASSERT(ok_is_zero, HYCON_OK == 0);
HYCON_STATIC_ASSERT(errors_negative, HYCON_ERROR_NULL_POINTER < 0 && HYCON_ERROR_PANIC < 0);
HYCON_STATIC_ASSERT(packed_version, HYCON_VERSION == HYCON_VERSION_MAJOR * 10000 +
                                                        HYCON_VERSION_MINOR * 100 +
                                                        HYCON_VERSION_PATCH);

#if HYCON_VERSION < 400
#error "this program needs hycon 0.4 or newer (the size convention, the input views)"
#endif

/* The contact API: the fields of every struct in their documented order (a removed, renamed or
 * reordered field breaks this file; new fields may follow), every constant, and every function
 * with its exact type. Exact sizes and offsets are checked against the Rust definitions by the
 * bindgen test. */
#define HYCON_ORDER(type, a, b) \
    HYCON_STATIC_ASSERT(type##_##a##_##b, offsetof(type, a) < offsetof(type, b))
HYCON_STATIC_ASSERT(HyconIterationRecord_first, offsetof(HyconIterationRecord, increment) == 0);
HYCON_ORDER(HyconIterationRecord, increment, iteration);
HYCON_ORDER(HyconIterationRecord, iteration, active);
HYCON_ORDER(HyconIterationRecord, active, stick);
HYCON_ORDER(HyconIterationRecord, stick, slip);
HYCON_ORDER(HyconIterationRecord, slip, changes);
HYCON_ORDER(HyconIterationRecord, changes, r);
HYCON_ORDER(HyconIterationRecord, r, condition);
HYCON_ORDER(HyconIterationRecord, condition, sub_increment);
HYCON_STATIC_ASSERT(HyconContactOptions_first, offsetof(HyconContactOptions, size) == 0);
HYCON_ORDER(HyconContactOptions, size, tolerance);
HYCON_ORDER(HyconContactOptions, tolerance, gap_tolerance);
HYCON_ORDER(HyconContactOptions, gap_tolerance, tension_tolerance);
HYCON_ORDER(HyconContactOptions, tension_tolerance, friction_tolerance);
HYCON_ORDER(HyconContactOptions, friction_tolerance, slip_tolerance);
HYCON_ORDER(HyconContactOptions, slip_tolerance, search_distance);
HYCON_ORDER(HyconContactOptions, search_distance, max_iterations);
HYCON_ORDER(HyconContactOptions, max_iterations, lock_rounds);
HYCON_ORDER(HyconContactOptions, lock_rounds, backend);
HYCON_ORDER(HyconContactOptions, backend, kinematics);
HYCON_ORDER(HyconContactOptions, kinematics, monitor);
HYCON_ORDER(HyconContactOptions, monitor, monitor_data);
HYCON_ORDER(HyconContactOptions, monitor_data, cutback_depth);
HYCON_ORDER(HyconContactOptions, cutback_depth, cutback_min_fraction);
HYCON_STATIC_ASSERT(HyconIncrementInfo_first, offsetof(HyconIncrementInfo, increment) == 0);
HYCON_ORDER(HyconIncrementInfo, increment, iterations);
HYCON_ORDER(HyconIncrementInfo, iterations, active);
HYCON_ORDER(HyconIncrementInfo, active, slip);
HYCON_ORDER(HyconIncrementInfo, slip, sub_increments);
HYCON_ORDER(HyconIncrementInfo, sub_increments, cutbacks);
HYCON_STATIC_ASSERT(HyconNodeResult_first, offsetof(HyconNodeResult, node) == 0);
HYCON_ORDER(HyconNodeResult, node, state);
HYCON_ORDER(HyconNodeResult, state, slip_sign);
HYCON_ORDER(HyconNodeResult, slip_sign, tn);
HYCON_ORDER(HyconNodeResult, tn, ts);
HYCON_ORDER(HyconNodeResult, ts, normal);
HYCON_ORDER(HyconNodeResult, normal, tangent);
HYCON_ORDER(HyconNodeResult, tangent, position);
HYCON_ORDER(HyconNodeResult, position, weight);
HYCON_ORDER(HyconNodeResult, weight, gap);
HYCON_ORDER(HyconNodeResult, gap, force);
HYCON_STATIC_ASSERT(HyconBNodeResult_first, offsetof(HyconBNodeResult, node) == 0);
HYCON_ORDER(HyconBNodeResult, node, weight);
HYCON_ORDER(HyconBNodeResult, weight, force);
HYCON_ORDER(HyconBNodeResult, force, pressure);
HYCON_STATIC_ASSERT(HyconTimings_first, offsetof(HyconTimings, assembly) == 0);
HYCON_ORDER(HyconTimings, assembly, factorization);
HYCON_ORDER(HyconTimings, factorization, flexibility);
HYCON_ORDER(HyconTimings, flexibility, load_solves);
HYCON_ORDER(HyconTimings, load_solves, iterations);
HYCON_ORDER(HyconTimings, iterations, recovery);
HYCON_STATIC_ASSERT(HyconContactNode_first, offsetof(HyconContactNode, node) == 0);
HYCON_ORDER(HyconContactNode, node, weight);
HYCON_ORDER(HyconContactNode, weight, coverage);
HYCON_ORDER(HyconContactNode, coverage, normal);
HYCON_ORDER(HyconContactNode, normal, tangent);
HYCON_ORDER(HyconContactNode, tangent, gap);
HYCON_ORDER(HyconContactNode, gap, normal_gap);
HYCON_STATIC_ASSERT(HyconCouplingEntry_first, offsetof(HyconCouplingEntry, row) == 0);
HYCON_ORDER(HyconCouplingEntry, row, node);
HYCON_ORDER(HyconCouplingEntry, node, side);
HYCON_ORDER(HyconCouplingEntry, side, value);
HYCON_STATIC_ASSERT(HyconConstraintEntry_first, offsetof(HyconConstraintEntry, row) == 0);
HYCON_ORDER(HyconConstraintEntry, row, column);
HYCON_ORDER(HyconConstraintEntry, column, value);
HYCON_STATIC_ASSERT(HyconElementBlock_first, offsetof(HyconElementBlock, offsets) == 0);
HYCON_ORDER(HyconElementBlock, offsets, nodes);
HYCON_ORDER(HyconElementBlock, nodes, n_elements);
HYCON_ORDER(HyconElementBlock, n_elements, materials);
HYCON_ORDER(HyconElementBlock, materials, kind);
HYCON_STATIC_ASSERT(HyconPolyline_first, offsetof(HyconPolyline, nodes) == 0);
HYCON_ORDER(HyconPolyline, nodes, n);
HYCON_STATIC_ASSERT(HyconHostNodes_first, offsetof(HyconHostNodes, ids) == 0);
HYCON_ORDER(HyconHostNodes, ids, coords);
HYCON_ORDER(HyconHostNodes, coords, equations);
HYCON_ORDER(HyconHostNodes, equations, n);
HYCON_STATIC_ASSERT(enum_sizes, sizeof(HyconBackend) == 4 && sizeof(HyconKinematics) == 4 &&
                                    sizeof(HyconDirections) == 4 &&
                                    sizeof(HyconNodeState) == 4 && sizeof(HyconSide) == 4 &&
                                    sizeof(HyconTriangle) == 4 && sizeof(HyconPlateControl) == 4);
HYCON_STATIC_ASSERT(constants, HYCON_BACKEND_FAER != HYCON_BACKEND_CHOLMOD &&
                                   HYCON_KINEMATICS_SMALL > 0 && HYCON_KINEMATICS_FINITE > 0 &&
                                   HYCON_KINEMATICS_SMALL != HYCON_KINEMATICS_FINITE &&
                                   (HYCON_X | HYCON_Y) == HYCON_XY &&
                                   HYCON_NODE_OPEN != HYCON_NODE_STICK &&
                                   HYCON_NODE_STICK != HYCON_NODE_SLIP &&
                                   HYCON_SIDE_A != HYCON_SIDE_B && HYCON_CSR_FULL > 0 &&
                                   HYCON_CSR_LOWER > 0 && HYCON_CSR_UPPER > 0 &&
                                   HYCON_PLATE_DISPLACEMENT != HYCON_PLATE_FORCE &&
                                   HYCON_FIXED < 0 && HYCON_ERROR_CONTACT < 0 &&
                                   HYCON_ERROR_CALLBACK < 0);

/* Every function of the API, through a pointer of its exact type (an incompatible pointer
 * assignment is an error under -Werror). */
static int32_t monitor_stub(void *data, const HyconIterationRecord *record) {
    (void)data;
    (void)record;
    return 0;
}
static int32_t solve_stub(void *data, size_t n, size_t nrhs, const double *rhs, double *x) {
    (void)data;
    (void)n;
    (void)nrhs;
    (void)rhs;
    (void)x;
    return 0;
}
static const HyconMonitorFn monitor_fn = monitor_stub;
static const HyconSolveFn solve_fn = solve_stub;
static HyconStatus (*const fn_version)(int32_t *) = hycon_version;
static size_t (*const fn_last_error_message)(char *, size_t) = hycon_last_error_message;
static const char *(*const fn_status_name)(HyconStatus) = hycon_status_name;
static HyconStatus (*const fn_options_default)(HyconContactOptions *) =
    hycon_contact_options_default;
static HyconStatus (*const fn_model_new)(HyconModel **, const double *, size_t,
                                         const HyconElementBlock *, const HyconMaterial *,
                                         size_t) = hycon_model_new;
static void (*const fn_model_free)(HyconModel *) = hycon_model_free;
static HyconStatus (*const fn_model_prescribe)(HyconModel *, const size_t *, size_t,
                                               HyconDirections) = hycon_model_prescribe;
static HyconStatus (*const fn_model_add_pair)(HyconModel *, const HyconPolyline *,
                                              const HyconPolyline *, double,
                                              size_t *) = hycon_model_add_pair;
static HyconStatus (*const fn_model_set_plate)(HyconModel *, const size_t *, size_t) =
    hycon_model_set_plate;
static HyconStatus (*const fn_contact_new)(HyconContact **, const HyconModel *,
                                           const HyconContactOptions *) = hycon_contact_new;
static HyconStatus (*const fn_host_new)(HyconHost **, size_t) = hycon_host_new;
static void (*const fn_host_free)(HyconHost *) = hycon_host_free;
static HyconStatus (*const fn_host_add_pair)(HyconHost *, const HyconHostNodes *,
                                             const HyconHostNodes *, double,
                                             size_t *) = hycon_host_add_pair;
static HyconStatus (*const fn_host_set_pair_inside)(HyconHost *, size_t, const double *) =
    hycon_host_set_pair_inside;
static HyconStatus (*const fn_host_set_csr)(HyconHost *, const size_t *, const size_t *,
                                            const double *, HyconTriangle) = hycon_host_set_csr;
static HyconStatus (*const fn_host_set_solver)(HyconHost *, HyconSolveFn, void *) =
    hycon_host_set_solver;
static HyconStatus (*const fn_host_set_elements)(HyconHost *, const HyconHostNodes *,
                                                 const HyconElementBlock *,
                                                 const HyconMaterial *,
                                                 size_t) = hycon_host_set_elements;
static HyconStatus (*const fn_contact_new_host)(HyconContact **, const HyconHost *,
                                                const HyconContactOptions *) =
    hycon_contact_new_host;
static void (*const fn_contact_free)(HyconContact *) = hycon_contact_free;
static HyconStatus (*const fn_increment)(HyconContact *, const double *, size_t, const double *,
                                         size_t, HyconIncrementInfo *) = hycon_contact_increment;
static HyconStatus (*const fn_increment_with_plate)(HyconContact *, const double *, size_t,
                                                    const double *, size_t,
                                                    const HyconPlateControl *, const double *,
                                                    HyconIncrementInfo *) =
    hycon_contact_increment_with_plate;
static HyconStatus (*const fn_plate)(const HyconContact *, double *, double *) =
    hycon_contact_plate;
static HyconStatus (*const fn_displacement)(const HyconContact *, double *, size_t, size_t *) =
    hycon_contact_displacement;
static HyconStatus (*const fn_displacement_increment)(const HyconContact *, double *, size_t,
                                                      size_t *) =
    hycon_contact_displacement_increment;
static HyconStatus (*const fn_forces)(const HyconContact *, double *, size_t, size_t *) =
    hycon_contact_forces;
static HyconStatus (*const fn_node_results)(const HyconContact *, size_t, HyconNodeResult *,
                                            size_t, size_t *) = hycon_contact_node_results;
static HyconStatus (*const fn_b_node_results)(const HyconContact *, size_t, HyconBNodeResult *,
                                              size_t, size_t *) = hycon_contact_b_node_results;
static HyconStatus (*const fn_stress_tractions)(const HyconContact *, size_t, double *, size_t,
                                                size_t *) = hycon_contact_stress_tractions;
static HyconStatus (*const fn_records)(const HyconContact *, size_t, HyconIterationRecord *,
                                       size_t, size_t *) = hycon_contact_records;
static HyconStatus (*const fn_timings)(const HyconContact *, HyconTimings *, size_t *) =
    hycon_contact_timings;
static HyconStatus (*const fn_surface_nodes)(const HyconContact *, size_t, HyconContactNode *,
                                             size_t, size_t *) = hycon_contact_surface_nodes;
static HyconStatus (*const fn_surface_coupling)(const HyconContact *, size_t,
                                                HyconCouplingEntry *, size_t, size_t *) =
    hycon_contact_surface_coupling;
static HyconStatus (*const fn_constraint_rows)(const HyconContact *, size_t,
                                               HyconConstraintEntry *, size_t, size_t *) =
    hycon_contact_constraint_rows;
static HyconStatus (*const fn_element_check)(HyconElementKind, size_t, const double *) =
    hycon_element_check;
static HyconStatus (*const fn_element_stiffness)(HyconElementKind, size_t, const double *,
                                                 const HyconMaterial *, double *, size_t) =
    hycon_element_stiffness;
static HyconStatus (*const fn_element_stress)(HyconElementKind, size_t, const double *,
                                              const HyconMaterial *, const double *, double,
                                              double, double *) = hycon_element_stress;
static HyconStatus (*const fn_element_stress_params)(HyconElementKind, size_t, const double *,
                                                     const HyconMaterial *, const double *,
                                                     double *, size_t, size_t *) =
    hycon_element_stress_params;
static HyconStatus (*const fn_element_edge_traction)(HyconElementKind, size_t, const double *,
                                                     const HyconMaterial *, const double *,
                                                     size_t, double, double *) =
    hycon_element_edge_traction;

typedef void (*any_function)(void);

int main(void) {
    /* Every function, so that each symbol must resolve at link time (a cast between function
     * pointer types is allowed; each one is only ever called through its own type). */
    const any_function functions[] = {
        (any_function)fn_version, (any_function)fn_last_error_message,
        (any_function)fn_status_name,
        (any_function)fn_options_default, (any_function)fn_model_new, (any_function)fn_model_free,
        (any_function)fn_model_prescribe, (any_function)fn_model_add_pair,
        (any_function)fn_model_set_plate, (any_function)fn_contact_new, (any_function)fn_host_new,
        (any_function)fn_host_free, (any_function)fn_host_add_pair,
        (any_function)fn_host_set_pair_inside, (any_function)fn_host_set_csr,
        (any_function)fn_host_set_solver, (any_function)fn_host_set_elements,
        (any_function)fn_contact_new_host,
        (any_function)fn_contact_free, (any_function)fn_increment,
        (any_function)fn_increment_with_plate, (any_function)fn_plate,
        (any_function)fn_displacement, (any_function)fn_displacement_increment,
        (any_function)fn_forces, (any_function)fn_node_results, (any_function)fn_b_node_results,
        (any_function)fn_stress_tractions, (any_function)fn_records, (any_function)fn_timings,
        (any_function)fn_surface_nodes, (any_function)fn_surface_coupling,
        (any_function)fn_constraint_rows, (any_function)fn_element_check, (any_function)fn_element_stiffness,
        (any_function)fn_element_stress, (any_function)fn_element_stress_params,
        (any_function)fn_element_edge_traction, (any_function)monitor_fn, (any_function)solve_fn};
    int32_t v[3] = {-1, -1, -1};
    HyconContactOptions options;
    size_t i, n_functions = sizeof functions / sizeof functions[0];
    for (i = 0; i < n_functions; ++i) {
        if (functions[i] == NULL) {
            fprintf(stderr, "function pointer %u is NULL\n", (unsigned)i);
            return 1;
        }
    }
    /* the plain C structs are usable from C: the defaults, with a C monitor */
    if (fn_options_default(&options) != HYCON_OK || !(options.tolerance > 0.0) ||
        options.monitor != NULL || options.size != sizeof options || options.cutback_depth == 0) {
        fprintf(stderr, "hycon_contact_options_default failed\n");
        return 1;
    }
    options.monitor = monitor_fn;
    options.monitor_data = NULL;
    (void)solve_fn;
    if (hycon_version(v) != HYCON_OK) {
        fprintf(stderr, "hycon_version failed\n");
        return 1;
    }
    if (v[0] != HYCON_VERSION_MAJOR || v[1] != HYCON_VERSION_MINOR || v[2] != HYCON_VERSION_PATCH) {
        fprintf(stderr, "library %d.%d.%d does not match header %d.%d.%d\n", (int)v[0], (int)v[1],
                (int)v[2], HYCON_VERSION_MAJOR, HYCON_VERSION_MINOR, HYCON_VERSION_PATCH);
        return 1;
    }
    printf("hycon %d.%d.%d (C99), %u API functions checked\n", (int)v[0], (int)v[1], (int)v[2],
           (unsigned)n_functions - 2);
    printf("struct sizes: record %u, options %u, increment info %u, node result %u, B node result "
           "%u, timings %u, contact node %u, coupling entry %u\nOK\n",
           (unsigned)sizeof(HyconIterationRecord), (unsigned)sizeof(HyconContactOptions),
           (unsigned)sizeof(HyconIncrementInfo), (unsigned)sizeof(HyconNodeResult),
           (unsigned)sizeof(HyconBNodeResult), (unsigned)sizeof(HyconTimings),
           (unsigned)sizeof(HyconContactNode), (unsigned)sizeof(HyconCouplingEntry));
    return 0;
}
