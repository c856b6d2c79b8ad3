/* The load and check routines from C (strict C99), as a host uses them, against closed forms:
 * consistent nodal forces of edge and face loads (hycon_element_edge_load,
 * hycon_brick_face_load), volume and scaled Jacobian (hycon_element_volume / _quality,
 * hycon_brick_volume / _quality), stress at natural coordinates (hycon_element_stress_natural,
 * hycon_brick_stress_natural), and a small host that loads Lamé's cylinder through
 * hycon_element_edge_load and solves it itself. One `bool test_x(void)` per feature; prints
 * "wrong value" and exits 1 on any mismatch. Run by ctest, under valgrind and with ASan+UBSan. */
#include "hycon.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

static const double pi = 3.14159265358979323846;

#define CHECK(call)                                                                            \
    do {                                                                                       \
        HyconStatus status_ = (call);                                                          \
        if (status_ != HYCON_OK) {                                                             \
            char message_[512];                                                                \
            hycon_last_error_message(message_, sizeof message_);                               \
            fprintf(stderr, "  %s:%d: %s: %s\n", __FILE__, __LINE__,                           \
                    hycon_status_name(status_), message_);                                     \
            return false;                                                                      \
        }                                                                                      \
    } while (0)

/* |got - want| <= tol * scale, else "wrong value" (which fails the ctest). */
static bool near(double got, double want, double tol, double scale, const char *what) {
    if (fabs(got - want) <= tol * scale) return true;
    fprintf(stderr, "  wrong value: %s = %.17g, expected %.17g (tolerance %g)\n", what, got, want,
            tol * scale);
    return false;
}

#define NEAR(got, want, tol, scale)                                                            \
    do {                                                                                       \
        if (!near((got), (want), (tol), (scale), #got)) return false;                          \
    } while (0)

/* A uniform pressure on a straight edge splits 1/2-1/2 along the inward normal (plane strain,
 * thickness 2); a linear one (2 -> 5) as t L (2 p0 + p1) / 6, t L (p0 + 2 p1) / 6; a traction
 * vector adds to it. */
static bool test_edge_load_plane(void) {
    const double square[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    const HyconMaterial m = {1000.0, 0.3, 2.0, HYCON_PLANE_STRAIN};
    const double uniform[2] = {3.0, 3.0}, linear[2] = {2.0, 5.0};
    const double traction[4] = {0.0, 1.0, 0.0, 1.0};
    double f[HYCON_MAX_DOF];
    int kind;
    for (kind = HYCON_ELEMENT_HYBRID; kind <= HYCON_ELEMENT_Q4; ++kind) {
        /* edge 1: x = 1, from node 1 to node 2, outward normal +x */
        CHECK(hycon_element_edge_load(kind, 4, square, &m, 1, uniform, NULL, f, HYCON_MAX_DOF));
        NEAR(f[2], -3.0, 1e-15, 3.0);
        NEAR(f[4], -3.0, 1e-15, 3.0);
        NEAR(f[3] + f[5] + f[0] + f[1] + f[6] + f[7], 0.0, 1e-15, 3.0);
        CHECK(hycon_element_edge_load(kind, 4, square, &m, 1, linear, traction, f, 8));
        NEAR(f[2], -2.0 * (2.0 * 2.0 + 5.0) / 6.0, 1e-15, 5.0);
        NEAR(f[4], -2.0 * (2.0 + 2.0 * 5.0) / 6.0, 1e-15, 5.0);
        NEAR(f[3], 1.0, 1e-15, 5.0);
        NEAR(f[5], 1.0, 1e-15, 5.0);
    }
    return true;
}

/* Axisymmetry: a pressure p on the top of a ring r in [r1, r2] pushes down with
 * p pi (r2^2 - r1^2) in all (full-circle forces). */
static bool test_edge_load_axisymmetric(void) {
    const double r1 = 0.5, r2 = 2.0, h = 0.75, p = 3.0;
    const double ring[8] = {r1, 0, r2, 0, r2, h, r1, h};
    const HyconMaterial axi = {1000.0, 0.3, 1.0, HYCON_AXISYMMETRIC};
    const double pressure[2] = {p, p};
    double f[8];
    CHECK(hycon_element_edge_load(HYCON_ELEMENT_HYBRID, 4, ring, &axi, 2, pressure, NULL, f, 8));
    NEAR(f[5] + f[7], -p * pi * (r2 * r2 - r1 * r1), 1e-14, p * pi * r2 * r2);
    NEAR(f[5], -2.0 * pi * p * (r2 - r1) * (2.0 * r2 + r1) / 6.0, 1e-14, p * pi * r2 * r2);
    return true;
}

/* Volume A t, the ring's 2 pi r_c A, and the scaled Jacobian (1 for a rectangle, sin(theta)
 * for a rhombus; a 179.8 degree corner is flagged). */
static bool test_element_volume_and_quality(void) {
    const double rect[8] = {1, 0, 3, 0, 3, 0.5, 1, 0.5};
    const HyconMaterial plane = {1000.0, 0.3, 0.2, HYCON_PLANE_STRESS};
    const HyconMaterial axi = {1000.0, 0.3, 1.0, HYCON_AXISYMMETRIC};
    const double theta = 0.6;
    const double rhombus[8] = {0, 0, 1, 0, 1 + cos(theta), sin(theta), cos(theta), sin(theta)};
    const double e = tan(0.1 * pi / 180.0);
    const double kite[8] = {0, 0, 1, -e, 2, 0, 1, 1};
    double v = 0.0, q = 0.0;
    CHECK(hycon_element_volume(HYCON_ELEMENT_Q4, 4, rect, &plane, &v));
    NEAR(v, 2.0 * 0.5 * 0.2, 1e-15, 1.0);
    CHECK(hycon_element_volume(HYCON_ELEMENT_HYBRID, 4, rect, &axi, &v));
    NEAR(v, pi * (9.0 - 1.0) * 0.5, 1e-14, 10.0);
    CHECK(hycon_element_quality(HYCON_ELEMENT_Q4, 4, rect, &q));
    NEAR(q, 1.0, 1e-15, 1.0);
    CHECK(hycon_element_quality(HYCON_ELEMENT_PIAN_SUMIHARA, 4, rhombus, &q));
    NEAR(q, sin(theta), 1e-15, 1.0);
    CHECK(hycon_element_quality(HYCON_ELEMENT_HYBRID, 4, kite, &q));
    if (!(q > 0.0 && q < 0.01)) {
        fprintf(stderr, "  wrong value: quality of a 179.8 degree corner %g\n", q);
        return false;
    }
    return true;
}

/* The stress at natural coordinates equals hycon_element_stress at the mapped point. */
static bool test_element_stress_natural(void) {
    const double quad[8] = {0, 0, 2, 0.2, 2.3, 1.9, 0.1, 1.5};
    const double q[8] = {0, 0, 1e-3, 2e-4, 1.2e-3, -3e-4, 1e-4, 5e-4};
    const HyconMaterial m = {1000.0, 0.3, 1.0, HYCON_PLANE_STRAIN};
    const HyconMaterial axi = {1000.0, 0.3, 1.0, HYCON_AXISYMMETRIC};
    const double xi = 0.4, eta = -0.7;
    const double n[4] = {(1 - xi) * (1 - eta) / 4, (1 + xi) * (1 - eta) / 4,
                         (1 + xi) * (1 + eta) / 4, (1 - xi) * (1 + eta) / 4};
    double px = 0.0, py = 0.0, a[4], b[4];
    int k, kind, c;
    for (k = 0; k < 4; ++k) {
        px += n[k] * quad[2 * k];
        py += n[k] * quad[2 * k + 1];
    }
    for (kind = HYCON_ELEMENT_HYBRID; kind <= HYCON_ELEMENT_Q4; ++kind) {
        CHECK(hycon_element_stress_natural(kind, 4, quad, &m, q, xi, eta, a));
        CHECK(hycon_element_stress(kind, 4, quad, &m, q, px, py, b));
        for (c = 0; c < 3; ++c) NEAR(a[c], b[c], 1e-10, 1.0);
        if (kind != HYCON_ELEMENT_PIAN_SUMIHARA) {
            CHECK(hycon_element_stress_natural(kind, 4, quad, &axi, q, xi, eta, a));
            CHECK(hycon_element_stress(kind, 4, quad, &axi, q, px, py, b));
            for (c = 0; c < 4; ++c) NEAR(a[c], b[c], 1e-10, 1.0);
        }
    }
    return true;
}

/* A quarter of a cylinder's bore (radius a, height H) as 3 bricks round: a uniform pressure p
 * on their bore faces (face 0) sums to p a H in x and in y, 0 in z (the projected areas). */
static bool test_brick_face_load(void) {
    const double a = 3.0, b = 4.0, height = 2.0, p = 2.5;
    const double pressure[4] = {p, p, p, p};
    double total[3] = {0, 0, 0}, f[HYCON_BRICK_DOF];
    int e, k, i;
    for (e = 0; e < 3; ++e) {
        /* node (r, theta, z) in brick order: r = xi, theta = eta, z = zeta */
        double x[24];
        for (k = 0; k < 8; ++k) {
            const double r = (k == 1 || k == 2 || k == 5 || k == 6) ? b : a;
            const double t = (pi / 6.0) * (e + ((k % 4 == 2 || k % 4 == 3) ? 1 : 0));
            x[3 * k] = r * cos(t);
            x[3 * k + 1] = r * sin(t);
            x[3 * k + 2] = k < 4 ? 0.0 : height;
        }
        CHECK(hycon_brick_face_load(HYCON_BRICK_HYBRID18, x, 0, pressure, NULL, f,
                                    HYCON_BRICK_DOF));
        for (k = 0; k < 8; ++k)
            for (i = 0; i < 3; ++i) total[i] += f[3 * k + i];
    }
    NEAR(total[0], p * a * height, 1e-14, p * a * height);
    NEAR(total[1], p * a * height, 1e-14, p * a * height);
    NEAR(total[2], 0.0, 1e-14, p * a * height);
    return true;
}

/* The brick routines on a square frustum (bottom side 2, top 0.8, height 1.3): volume
 * h (A1 + sqrt(A1 A2) + A2) / 3; the cube's scaled Jacobian 1; stress at natural coordinates
 * equal to hycon_brick_stress at the mapped point. */
static bool test_brick_volume_quality_stress(void) {
    const double s0 = 2.0, s1 = 0.8, h = 1.3;
    const double corner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                 {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const HyconSolidMaterial m = {1000.0, 0.3};
    const double xi[3] = {0.3, -0.6, 0.8};
    double frustum[24], cube[24], q[24], v = 0.0, quality = 0.0, p[3] = {0, 0, 0}, a[6], b[6];
    int k, i, kind;
    for (k = 0; k < 8; ++k) {
        const double s = corner[k][2] < 0 ? s0 : s1;
        double n = 1.0;
        frustum[3 * k] = s * corner[k][0] / 2.0;
        frustum[3 * k + 1] = s * corner[k][1] / 2.0;
        frustum[3 * k + 2] = h * (corner[k][2] + 1.0) / 2.0;
        for (i = 0; i < 3; ++i) {
            cube[3 * k + i] = corner[k][i];
            q[3 * k + i] = 1e-3 * sin(1.0 + 3 * k + i);
            n *= (1.0 + xi[i] * corner[k][i]) / 2.0;
        }
        for (i = 0; i < 3; ++i) p[i] += n * frustum[3 * k + i];
    }
    CHECK(hycon_brick_volume(HYCON_BRICK_H8, frustum, &v));
    NEAR(v, h * (s0 * s0 + s0 * s1 + s1 * s1) / 3.0, 1e-14, 1.0);
    CHECK(hycon_brick_quality(HYCON_BRICK_HYBRID18, cube, &quality));
    NEAR(quality, 1.0, 1e-15, 1.0);
    for (kind = HYCON_BRICK_HYBRID18; kind <= HYCON_BRICK_H8; ++kind) {
        CHECK(hycon_brick_stress_natural(kind, frustum, &m, q, xi[0], xi[1], xi[2], a));
        CHECK(hycon_brick_stress(kind, frustum, &m, q, p[0], p[1], p[2], b));
        for (i = 0; i < 6; ++i) NEAR(a[i], b[i], 1e-10, 1.0);
    }
    return true;
}

/* Solve A x = b (dense, n <= 12) by Gaussian elimination with partial pivoting. */
static bool solve_dense(int n, double *a, double *b) {
    int i, j, k;
    for (k = 0; k < n; ++k) {
        int piv = k;
        for (i = k + 1; i < n; ++i)
            if (fabs(a[i * n + k]) > fabs(a[piv * n + k])) piv = i;
        if (a[piv * n + k] == 0.0) return false;
        for (j = 0; j < n; ++j) {
            double t = a[k * n + j];
            a[k * n + j] = a[piv * n + j];
            a[piv * n + j] = t;
        }
        {
            double t = b[k];
            b[k] = b[piv];
            b[piv] = t;
        }
        for (i = k + 1; i < n; ++i) {
            const double l = a[i * n + k] / a[k * n + k];
            for (j = k; j < n; ++j) a[i * n + j] -= l * a[k * n + j];
            b[i] -= l * b[k];
        }
    }
    for (k = n - 1; k >= 0; --k) {
        for (j = k + 1; j < n; ++j) b[k] -= a[k * n + j] * b[j];
        b[k] /= a[k * n + k];
    }
    return true;
}

/* A host's Lamé cylinder (a = 3, b = 9, E = 1000, nu = 0.3, unit bore pressure), axisymmetric,
 * 5 hybrid elements through the wall, u_z = 0 everywhere: the host assembles the radial dofs
 * of hycon_element_stiffness, loads the bore with hycon_element_edge_load and solves. On this
 * mesh the element is nodally exact (tests/axisymmetric.rs), so u_r(a) matches Lamé to 1e-6. */
static bool test_lame_host(void) {
    enum { N = 5, NODES = 2 * (N + 1), FREE = N + 1 };
    const double a = 3.0, b = 9.0, nu = 0.3, e = 1000.0, hgt = (b - a) / N;
    const HyconMaterial axi = {e, nu, 1.0, HYCON_AXISYMMETRIC};
    const double pressure[2] = {1.0, 1.0};
    double kg[FREE * FREE], f[FREE], x[2 * NODES];
    double bb, aa, exact;
    int el, i, j;
    memset(kg, 0, sizeof kg);
    memset(f, 0, sizeof f);
    for (i = 0; i <= N; ++i) { /* node 2i at (r, 0), node 2i + 1 at (r, h) */
        x[4 * i] = a + (b - a) * i / N;
        x[4 * i + 1] = 0.0;
        x[4 * i + 2] = x[4 * i];
        x[4 * i + 3] = hgt;
    }
    for (el = 0; el < N; ++el) {
        const int nodes[4] = {2 * el, 2 * el + 2, 2 * el + 3, 2 * el + 1};
        double coords[8], k[64];
        for (i = 0; i < 4; ++i) {
            coords[2 * i] = x[2 * nodes[i]];
            coords[2 * i + 1] = x[2 * nodes[i] + 1];
        }
        CHECK(hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 4, coords, &axi, k, 64));
        /* the radial dofs only (u_z = 0); a node pair (2i, 2i + 1) shares equation i by
         * symmetry of the load: u_r does not depend on z in this problem, so tie them */
        for (i = 0; i < 4; ++i)
            for (j = 0; j < 4; ++j) kg[(nodes[i] / 2) * FREE + nodes[j] / 2] += k[2 * i * 8 + 2 * j];
        if (el == 0) {
            double fe[8];
            CHECK(hycon_element_edge_load(HYCON_ELEMENT_HYBRID, 4, coords, &axi, 3, pressure,
                                          NULL, fe, 8));
            f[0] += fe[0] + fe[6];
        }
    }
    if (!solve_dense(FREE, kg, f)) {
        fprintf(stderr, "  wrong value: singular host matrix\n");
        return false;
    }
    bb = a * a * b * b / (b * b - a * a);
    aa = bb / (b * b);
    exact = a * (1 + nu) / e * ((1 - nu) * (aa + bb / (a * a)) - nu * (aa - bb / (a * a)));
    NEAR(f[0], exact, 1e-6, exact);
    return true;
}

int main(void) {
    static const struct {
        const char *name;
        bool (*run)(void);
    } tests[] = {
        {"edge_load_plane", test_edge_load_plane},
        {"edge_load_axisymmetric", test_edge_load_axisymmetric},
        {"element_volume_and_quality", test_element_volume_and_quality},
        {"element_stress_natural", test_element_stress_natural},
        {"brick_face_load", test_brick_face_load},
        {"brick_volume_quality_stress", test_brick_volume_quality_stress},
        {"lame_host", test_lame_host},
    };
    size_t i, n = sizeof tests / sizeof tests[0];
    int failures = 0;
    for (i = 0; i < n; ++i) {
        bool ok = tests[i].run();
        printf("%-28s %s\n", tests[i].name, ok ? "ok" : "FAILED");
        failures += !ok;
    }
    if (failures != 0) {
        printf("%d of %d test(s) failed\n", failures, (int)n);
        return 1;
    }
    printf("OK\n");
    return 0;
}
