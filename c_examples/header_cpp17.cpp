// Compile check: include/hycon.h is standalone, include-guarded and clean C++17
// (-std=c++17 -Wall -Wextra -Werror -pedantic), with C linkage, and the library matches the
// header's version.
#include "hycon.h"
#include "hycon.h"  // twice on purpose: the include guard must hold

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <type_traits>

static_assert(sizeof(HyconMaterial) == 32, "HyconMaterial layout");
static_assert(offsetof(HyconMaterial, youngs) == 0, "HyconMaterial layout");
static_assert(offsetof(HyconMaterial, poisson) == 8, "HyconMaterial layout");
static_assert(offsetof(HyconMaterial, thickness) == 16, "HyconMaterial layout");
static_assert(offsetof(HyconMaterial, analysis) == 24, "HyconMaterial layout");
static_assert(std::is_standard_layout_v<HyconMaterial>, "HyconMaterial is plain data");
static_assert(std::is_trivially_copyable_v<HyconMaterial>, "HyconMaterial is plain data");
static_assert(std::is_same_v<HyconStatus, std::int32_t>, "HyconStatus is int32_t");
static_assert(HYCON_VERSION == HYCON_VERSION_MAJOR * 10000 + HYCON_VERSION_MINOR * 100 +
                                   HYCON_VERSION_PATCH,
              "packed version");

// The prototypes have C linkage and the expected types.
static_assert(std::is_same_v<decltype(&hycon_element_stiffness),
                             HyconStatus (*)(HyconElementKind, std::size_t, const double *,
                                             const HyconMaterial *, double *, std::size_t)>,
              "hycon_element_stiffness signature");

// The contact API's structs are plain C data, and its function types are as documented.
template <class... T>
constexpr bool all_plain =
    ((std::is_standard_layout_v<T> && std::is_trivially_copyable_v<T>) && ...);
static_assert(all_plain<HyconIterationRecord, HyconContactOptions, HyconIncrementInfo,
                        HyconNodeResult, HyconBNodeResult, HyconTimings, HyconContactNode,
                        HyconCouplingEntry, HyconConstraintEntry, HyconElementBlock,
                        HyconPolyline, HyconHostNodes>,
              "contact structs are plain data");
static_assert(std::is_same_v<HyconMonitorFn,
                             std::int32_t (*)(void *, const HyconIterationRecord *)>,
              "HyconMonitorFn");
static_assert(std::is_same_v<HyconSolveFn, std::int32_t (*)(void *, std::size_t, std::size_t,
                                                           const double *, double *)>,
              "HyconSolveFn");
static_assert(std::is_same_v<decltype(&hycon_contact_increment_with_plate),
                             HyconStatus (*)(HyconContact *, const double *, std::size_t,
                                             const double *, std::size_t,
                                             const HyconPlateControl *, const double *,
                                             HyconIncrementInfo *)>,
              "hycon_contact_increment_with_plate signature");
static_assert(std::is_same_v<decltype(&hycon_contact_node_results),
                             HyconStatus (*)(const HyconContact *, std::size_t, HyconNodeResult *,
                                             std::size_t, std::size_t *)>,
              "hycon_contact_node_results signature");
static_assert(std::is_same_v<decltype(&hycon_contact_displacement),
                             HyconStatus (*)(const HyconContact *, double *, std::size_t,
                                             std::size_t *)>,
              "hycon_contact_displacement signature (const handle, size convention)");
static_assert(std::is_same_v<decltype(&hycon_model_new),
                             HyconStatus (*)(HyconModel **, const double *, std::size_t,
                                             const HyconElementBlock *, const HyconMaterial *,
                                             std::size_t)>,
              "hycon_model_new signature (nodes, elements, materials)");
static_assert(std::is_same_v<decltype(&hycon_host_set_solver),
                             HyconStatus (*)(HyconHost *, HyconSolveFn, void *)>,
              "hycon_host_set_solver signature");
static_assert(std::is_same_v<decltype(&hycon_contact_free), void (*)(HyconContact *)>,
              "hycon_contact_free signature");

int main() {
    std::int32_t v[3] = {-1, -1, -1};
    if (hycon_version(v) != HYCON_OK) {
        std::fprintf(stderr, "hycon_version failed\n");
        return 1;
    }
    if (v[0] != HYCON_VERSION_MAJOR || v[1] != HYCON_VERSION_MINOR || v[2] != HYCON_VERSION_PATCH) {
        std::fprintf(stderr, "library/header version mismatch\n");
        return 1;
    }
    std::printf("hycon %d.%d.%d (C++17)\nOK\n", int(v[0]), int(v[1]), int(v[2]));
    return 0;
}
