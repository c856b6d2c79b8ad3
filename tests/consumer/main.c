/* Smallest host of an installed hycon: version check and one element stiffness. */
#include <hycon.h>

#include <stdio.h>

int main(void) {
    const double coords[8] = {0, 0, 2, 0, 2, 1, 0, 1}; /* counter-clockwise */
    const HyconMaterial m = {1000.0, 0.25, 1.0, HYCON_PLANE_STRESS};
    double k[64];
    int32_t v[3];
    HyconStatus st = hycon_version(v);
    if (st != HYCON_OK || v[0] != HYCON_VERSION_MAJOR || v[1] != HYCON_VERSION_MINOR) {
        fprintf(stderr, "version mismatch\n");
        return 1;
    }
    st = hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 4, coords, &m, k, 64);
    if (st != HYCON_OK) {
        char msg[256];
        hycon_last_error_message(msg, sizeof msg);
        fprintf(stderr, "%s: %s\n", hycon_status_name(st), msg);
        return 1;
    }
    if (!(k[0] > 0.0 && k[0 * 8 + 1] == k[1 * 8 + 0])) {
        fprintf(stderr, "unexpected stiffness\n");
        return 1;
    }
    printf("OK hycon %d.%d.%d, K[0][0] = %g\n", (int)v[0], (int)v[1], (int)v[2], k[0]);
    return 0;
}
