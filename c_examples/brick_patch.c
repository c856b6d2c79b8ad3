/* MacNeal and Harder's 3D patch test (FEAD 1 (1985) 3-20) solved by a tiny host in strict C99
 * that takes the brick stiffness matrices and the stresses from hycon, at the standard (full)
 * distortion that hycon 0.8 rejected.
 *
 * Mesh: the unit cube (nodes 0-7 in hycon's brick order) around an irregular inner brick (nodes
 * 8-15 at MacNeal and Harder's coordinates, node 8 + i near corner i), joined by six bricks, one
 * per face of the cube. E = 1e6, nu = 0.25; the outer nodes follow u = 1e-3 (2x + y + z) / 2,
 * v = 1e-3 (x + 2y + z) / 2, w = 1e-3 (x + y + 2z) / 2, whose stress is sigma_x = sigma_y =
 * sigma_z = 2000, every shear 400. The host assembles the 24 free dofs of the inner nodes
 * densely, solves with its own Cholesky and checks, for both brick kinds: the inner nodes'
 * displacements to 1e-12 of the field, every brick's stress at its centroid to 1e-10 of 2000.
 *
 * The shape policy, from C: the front brick has det J < 0 at its corner node 7 (positive at every
 * integration point) and a face warped by 48 degrees, which the left brick shares. Under the
 * strict policy (hycon_brick_shape with HYCON_SHAPE_STRICT) both are HYCON_ERROR_BAD_ELEMENT, as
 * in 0.8; under the default one (HYCON_SHAPE_INTEGRATION_POINTS, the policy of every other brick
 * routine) they are HYCON_WARNING_SHAPE: the report names the corner and the face, the outputs
 * are written. The host accepts any status >= 0 and prints the warnings.
 *
 * Usage: brick_patch. Prints OK on success.
 */
#include "hycon.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures = 0;

#define EXPECT(cond)                                                          \
    do {                                                                      \
        if (!(cond)) {                                                        \
            fprintf(stderr, "%s:%d: wrong value: %s\n", __FILE__, __LINE__, #cond); \
            ++failures;                                                       \
        }                                                                     \
    } while (0)

static const double XYZ[16][3] = {
    {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.0, 1.0, 0.0}, {0.0, 1.0, 0.0},
    {0.0, 0.0, 1.0}, {1.0, 0.0, 1.0}, {1.0, 1.0, 1.0}, {0.0, 1.0, 1.0},
    {0.249, 0.342, 0.192}, {0.826, 0.288, 0.288}, {0.850, 0.649, 0.263},
    {0.273, 0.750, 0.230}, {0.320, 0.186, 0.643}, {0.677, 0.305, 0.683},
    {0.788, 0.693, 0.644}, {0.165, 0.745, 0.702},
};

/* centre, bottom, top, front (y = 0), back, left (x = 0), right */
static const size_t BRICKS[7][8] = {
    {8, 9, 10, 11, 12, 13, 14, 15}, {0, 1, 2, 3, 8, 9, 10, 11},
    {12, 13, 14, 15, 4, 5, 6, 7},   {0, 1, 9, 8, 4, 5, 13, 12},
    {11, 10, 2, 3, 15, 14, 6, 7},   {0, 8, 11, 3, 4, 12, 15, 7},
    {9, 1, 2, 10, 13, 5, 6, 14},
};

#define FRONT 3
#define LEFT 5

static void field(const double p[3], double u[3]) {
    u[0] = 1e-3 * (2.0 * p[0] + p[1] + p[2]) / 2.0;
    u[1] = 1e-3 * (p[0] + 2.0 * p[1] + p[2]) / 2.0;
    u[2] = 1e-3 * (p[0] + p[1] + 2.0 * p[2]) / 2.0;
}

static void brick_coords(size_t e, double x[24]) {
    for (size_t c = 0; c < 8; ++c)
        for (size_t i = 0; i < 3; ++i) x[3 * c + i] = XYZ[BRICKS[e][c]][i];
}

static void last_message(char *buf, size_t len) { (void)hycon_last_error_message(buf, len); }

/* Both policies on every brick: the expected errors and warnings, the report's measures. */
static void check_shapes(HyconBrickKind kind) {
    char message[512];
    for (size_t e = 0; e < 7; ++e) {
        double x[24];
        brick_coords(e, x);
        HyconShapeReport report;
        memset(&report, 0, sizeof report);
        HyconStatus strict = hycon_brick_shape(kind, x, HYCON_SHAPE_STRICT, &report);
        last_message(message, sizeof message);
        if (e == FRONT) {
            EXPECT(strict == HYCON_ERROR_BAD_ELEMENT);
            EXPECT(strstr(message, "Jacobian not positive at local node 7") != NULL);
        } else if (e == LEFT) {
            EXPECT(strict == HYCON_ERROR_BAD_ELEMENT);
            EXPECT(strstr(message, "face 2 is warped beyond the limit") != NULL);
        } else {
            EXPECT(strict == HYCON_OK && report.warnings == 0);
        }
        HyconStatus status = hycon_brick_shape(kind, x, HYCON_SHAPE_INTEGRATION_POINTS, &report);
        last_message(message, sizeof message);
        EXPECT(report.integration_jacobian > 4e-3);
        if (e == FRONT || e == LEFT) {
            printf("brick %zu: %s: %s\n", e, hycon_status_name(status), message);
            EXPECT(status == HYCON_WARNING_SHAPE);
            EXPECT(fabs(report.warp_degrees - 48.0) < 0.05);
            EXPECT(report.face == (e == FRONT ? 0u : 2u));
        } else {
            EXPECT(status == HYCON_OK && report.warnings == 0 && message[0] == '\0');
            EXPECT(report.warp_degrees < 45.0 && report.corner_jacobian > 0.0);
        }
        if (e == FRONT) {
            EXPECT(report.warnings == (HYCON_SHAPE_CORNER_JACOBIAN | HYCON_SHAPE_WARPED_FACE));
            EXPECT(report.corner == 7 && fabs(report.corner_jacobian + 0.00158) < 5e-6);
        } else if (e == LEFT) {
            EXPECT(report.warnings == HYCON_SHAPE_WARPED_FACE);
        }
    }
}

/* The patch test with one kind (failures counted in `failures`). */
static void patch(HyconBrickKind kind, const char *name) {
    const HyconSolidMaterial material = {1e6, 0.25};
    double a[24 * 24], f[24];
    memset(a, 0, sizeof a);
    memset(f, 0, sizeof f);
    double u_outer[8][3];
    for (size_t n = 0; n < 8; ++n) field(XYZ[n], u_outer[n]);
    for (size_t e = 0; e < 7; ++e) {
        double x[24], k[576];
        brick_coords(e, x);
        HyconStatus status = hycon_brick_stiffness(kind, x, &material, k, 576);
        if (status < 0) {
            char message[512];
            last_message(message, sizeof message);
            fprintf(stderr, "wrong value: hycon_brick_stiffness: %s\n", message);
            ++failures;
            return;
        }
        EXPECT(status == ((e == FRONT || e == LEFT) ? HYCON_WARNING_SHAPE : HYCON_OK));
        /* free dof of inner node n (8..15), direction d: 3 (n - 8) + d; outer nodes prescribed */
        for (size_t p = 0; p < 24; ++p) {
            const size_t np = BRICKS[e][p / 3];
            if (np < 8) continue;
            const size_t row = 3 * (np - 8) + p % 3;
            for (size_t q = 0; q < 24; ++q) {
                const size_t nq = BRICKS[e][q / 3];
                if (nq < 8)
                    f[row] -= k[p * 24 + q] * u_outer[nq][q % 3];
                else
                    a[row * 24 + 3 * (nq - 8) + q % 3] += k[p * 24 + q];
            }
        }
    }
    /* dense Cholesky a = L L^T (lower triangle), then the two triangular solves */
    for (size_t j = 0; j < 24; ++j) {
        double d = a[j * 24 + j];
        for (size_t k = 0; k < j; ++k) d -= a[j * 24 + k] * a[j * 24 + k];
        if (!(d > 0.0)) {
            fprintf(stderr, "wrong value: matrix not positive definite\n");
            ++failures;
            return;
        }
        a[j * 24 + j] = sqrt(d);
        for (size_t i = j + 1; i < 24; ++i) {
            double s = a[i * 24 + j];
            for (size_t k = 0; k < j; ++k) s -= a[i * 24 + k] * a[j * 24 + k];
            a[i * 24 + j] = s / a[j * 24 + j];
        }
    }
    for (size_t i = 0; i < 24; ++i) {
        for (size_t k = 0; k < i; ++k) f[i] -= a[i * 24 + k] * f[k];
        f[i] /= a[i * 24 + i];
    }
    for (size_t i = 24; i-- > 0;) {
        for (size_t k = i + 1; k < 24; ++k) f[i] -= a[k * 24 + i] * f[k];
        f[i] /= a[i * 24 + i];
    }
    double u_err = 0.0, s_err = 0.0;
    for (size_t n = 8; n < 16; ++n) {
        double u[3];
        field(XYZ[n], u);
        for (size_t d = 0; d < 3; ++d) u_err = fmax(u_err, fabs(f[3 * (n - 8) + d] - u[d]) / 2e-3);
    }
    const double exact[6] = {2000.0, 2000.0, 2000.0, 400.0, 400.0, 400.0};
    for (size_t e = 0; e < 7; ++e) {
        double x[24], q[24], centroid[3] = {0.0, 0.0, 0.0}, s[6];
        brick_coords(e, x);
        for (size_t c = 0; c < 8; ++c) {
            const size_t n = BRICKS[e][c];
            for (size_t d = 0; d < 3; ++d) {
                q[3 * c + d] = n < 8 ? u_outer[n][d] : f[3 * (n - 8) + d];
                centroid[d] += XYZ[n][d] / 8.0;
            }
        }
        HyconStatus status = hycon_brick_stress(kind, x, &material, q, centroid[0], centroid[1],
                                                centroid[2], s);
        EXPECT(status >= 0);
        for (size_t i = 0; i < 6; ++i) s_err = fmax(s_err, fabs(s[i] - exact[i]) / 2000.0);
    }
    printf("MacNeal-Harder 3D patch, %s: displacement error %.1e, stress error %.1e\n", name,
           u_err, s_err);
    EXPECT(u_err < 1e-12);
    EXPECT(s_err < 1e-10);
}

int main(void) {
    check_shapes(HYCON_BRICK_HYBRID18);
    check_shapes(HYCON_BRICK_H8);
    patch(HYCON_BRICK_HYBRID18, "hybrid18");
    patch(HYCON_BRICK_H8, "h8");
    if (failures > 0) {
        fprintf(stderr, "%d checks failed\n", failures);
        return EXIT_FAILURE;
    }
    printf("OK\n");
    return EXIT_SUCCESS;
}
