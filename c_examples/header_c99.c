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

#if HYCON_VERSION < 100
#error "this program needs hycon 0.1 or newer"
#endif

int main(void) {
    int32_t v[3] = {-1, -1, -1};
    if (hycon_version(v) != HYCON_OK) {
        fprintf(stderr, "hycon_version failed\n");
        return 1;
    }
    if (v[0] != HYCON_VERSION_MAJOR || v[1] != HYCON_VERSION_MINOR || v[2] != HYCON_VERSION_PATCH) {
        fprintf(stderr, "library %d.%d.%d does not match header %d.%d.%d\n", (int)v[0], (int)v[1],
                (int)v[2], HYCON_VERSION_MAJOR, HYCON_VERSION_MINOR, HYCON_VERSION_PATCH);
        return 1;
    }
    printf("hycon %d.%d.%d (C99)\nOK\n", (int)v[0], (int)v[1], (int)v[2]);
    return 0;
}
