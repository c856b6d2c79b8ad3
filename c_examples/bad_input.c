/* Bad-input tests of the hycon C API, as a C host would hit them (strict C99). One
 * `bool test_x(void)` per case; main counts failures and prints OK when there are none. */
#include "expect.h"
#include "hycon.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

/* a good unit square, counter-clockwise */
static const double square[8] = {0, 0, 1, 0, 1, 1, 0, 1};
static const HyconMaterial steel = {210e3, 0.3, 1.0, HYCON_PLANE_STRAIN};

static bool test_version(void) {
    int32_t v[3] = {-1, -1, -1};
    EXPECT(hycon_version(v) == HYCON_OK);
    EXPECT(v[0] == HYCON_VERSION_MAJOR && v[1] == HYCON_VERSION_MINOR &&
           v[2] == HYCON_VERSION_PATCH);
    EXPECT(STATUS(hycon_version(NULL), HYCON_ERROR_NULL_POINTER, "out"));
    return true;
}

static bool test_good_stiffness(void) {
    double k[64];
    size_t i, j;
    EXPECT(hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 4, square, &steel, k, 64) == HYCON_OK);
    EXPECT(hycon_last_error_message(NULL, 0) == 1); /* success clears the message */
    for (i = 0; i < 8; ++i) {
        double row_x = 0.0, row_y = 0.0; /* rigid translations carry no force */
        for (j = 0; j < 8; ++j) {
            EXPECT(isfinite(k[i * 8 + j]));
            EXPECT(fabs(k[i * 8 + j] - k[j * 8 + i]) <= 1e-9 * fabs(k[0]));
            row_x += k[i * 8 + j] * (j % 2 == 0);
            row_y += k[i * 8 + j] * (j % 2 == 1);
        }
        EXPECT(k[i * 8 + i] > 0.0);
        EXPECT(fabs(row_x) <= 1e-9 * k[0] && fabs(row_y) <= 1e-9 * k[0]);
    }
    /* a longer buffer is fine; only the first 64 values are written */
    {
        double big[HYCON_MAX_DOF * HYCON_MAX_DOF];
        fill(big, HYCON_MAX_DOF * HYCON_MAX_DOF);
        EXPECT(hycon_element_stiffness(HYCON_ELEMENT_Q4, 4, square, &steel, big,
                                       HYCON_MAX_DOF * HYCON_MAX_DOF) == HYCON_OK);
        EXPECT(big[63] != EXPECT_SENTINEL &&
               untouched(big + 64, HYCON_MAX_DOF * HYCON_MAX_DOF - 64));
    }
    return true;
}

static bool test_null_pointers(void) {
    double k[64];
    fill(k, 64);
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_Q4, 4, NULL, &steel, k, 64),
                  HYCON_ERROR_NULL_POINTER, "coords"));
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_Q4, 4, square, NULL, k, 64),
                  HYCON_ERROR_NULL_POINTER, "material"));
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_Q4, 4, square, &steel, NULL, 64),
                  HYCON_ERROR_NULL_POINTER, "k_out"));
    EXPECT(STATUS(hycon_element_check(HYCON_ELEMENT_Q4, 4, NULL), HYCON_ERROR_NULL_POINTER,
                  "coords"));
    EXPECT(untouched(k, 64));
    return true;
}

static bool test_short_output(void) {
    double k[64];
    fill(k, 64);
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_Q4, 4, square, &steel, k, 63),
                  HYCON_ERROR_BUFFER_TOO_SMALL, "64 needed"));
    EXPECT(untouched(k, 64));
    /* (NULL, 0) is an empty array: too small, not a null-pointer error */
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_Q4, 4, square, &steel, NULL, 0),
                  HYCON_ERROR_BUFFER_TOO_SMALL, "k_out"));
    return true;
}

static bool test_bad_kind_and_node_count(void) {
    double k[144];
    const double hexagon[12] = {0, 0, 1, 0, 2, 0, 2, 1, 1, 1, 0, 1};
    EXPECT(STATUS(hycon_element_stiffness(0, 4, square, &steel, k, 144),
                  HYCON_ERROR_INVALID_ARGUMENT, "unknown element kind 0"));
    EXPECT(STATUS(hycon_element_stiffness(42, 4, square, &steel, k, 144),
                  HYCON_ERROR_INVALID_ARGUMENT, "unknown element kind 42"));
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_Q4, 3, square, &steel, k, 144),
                  HYCON_ERROR_BAD_ELEMENT, "3 nodes"));
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_PIAN_SUMIHARA, 6, hexagon, &steel, k,
                                             144),
                  HYCON_ERROR_BAD_ELEMENT, "6 nodes"));
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 7, hexagon, &steel, k, 144),
                  HYCON_ERROR_BAD_ELEMENT, "7 nodes"));
    /* a 6-node hybrid transition element is fine */
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 6, hexagon, &steel, k, 144),
                  HYCON_OK, NULL));
    return true;
}

static bool test_non_finite_coordinates(void) {
    double k[64], c[8];
    memcpy(c, square, sizeof c);
    c[3] = NAN;
    fill(k, 64);
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 4, c, &steel, k, 64),
                  HYCON_ERROR_INVALID_ARGUMENT, "coords[3]"));
    c[3] = INFINITY;
    EXPECT(STATUS(hycon_element_check(HYCON_ELEMENT_Q4, 4, c), HYCON_ERROR_INVALID_ARGUMENT,
                  "not finite"));
    EXPECT(untouched(k, 64));
    return true;
}

static bool test_bad_shapes(void) {
    const double clockwise[8] = {0, 0, 0, 1, 1, 1, 1, 0};
    const double flat[8] = {0, 0, 1, 0, 2, 0, 3, 0};
    const double coincident[8] = {0, 0, 1, 0, 1, 0, 0, 1};
    const double dart[8] = {0, 0, 2, 0, 0.5, 0.5, 0, 2}; /* reflex corner at node 2 */
    int kind;
    for (kind = HYCON_ELEMENT_HYBRID; kind <= HYCON_ELEMENT_Q4; ++kind) {
        double k[64];
        fill(k, 64);
        EXPECT(STATUS(hycon_element_stiffness(kind, 4, clockwise, &steel, k, 64),
                      HYCON_ERROR_BAD_ELEMENT, "inverted"));
        EXPECT(STATUS(hycon_element_check(kind, 4, flat), HYCON_ERROR_BAD_ELEMENT, NULL));
        EXPECT(STATUS(hycon_element_check(kind, 4, coincident), HYCON_ERROR_BAD_ELEMENT,
                      NULL));
        EXPECT(STATUS(hycon_element_stiffness(kind, 4, dart, &steel, k, 64),
                      HYCON_ERROR_BAD_ELEMENT, "non-convex"));
        EXPECT(STATUS(hycon_element_check(kind, 4, square), HYCON_OK, NULL));
        EXPECT(untouched(k, 64));
    }
    return true;
}

static bool test_bad_material(void) {
    double k[64];
    HyconMaterial m[6];
    size_t i;
    for (i = 0; i < 6; ++i) m[i] = steel;
    m[0].youngs = 0.0;
    m[1].poisson = 0.5;
    m[2].thickness = -1.0;
    m[3].youngs = NAN;
    m[4].analysis = 0;
    m[5].poisson = -1.0;
    fill(k, 64);
    for (i = 0; i < 6; ++i)
        EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 4, square, &m[i], k, 64),
                      HYCON_ERROR_INVALID_MATERIAL, "material"));
    EXPECT(untouched(k, 64));
    return true;
}

/* E (or t) outside 1e-100..1e100 is a material error that says so, never a "degenerate
 * element"; inside that range, elements of any size give a finite stiffness. */
static bool test_material_scale(void) {
    const double tiny_e[3] = {4.94e-324, 2.2e-308, 1e-101};
    const double huge_e[2] = {1.79e308, 1e101};
    double k[64], scaled[8];
    HyconMaterial m = steel;
    size_t i;
    fill(k, 64);
    for (i = 0; i < 3; ++i) {
        m.youngs = tiny_e[i];
        EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 4, square, &m, k, 64),
                      HYCON_ERROR_INVALID_MATERIAL, "other units"));
    }
    for (i = 0; i < 2; ++i) {
        m.youngs = huge_e[i];
        EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_Q4, 4, square, &m, k, 64),
                      HYCON_ERROR_INVALID_MATERIAL, "Young's modulus"));
    }
    m = steel;
    m.thickness = 1e-300;
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 4, square, &m, k, 64),
                  HYCON_ERROR_INVALID_MATERIAL, "thickness"));
    EXPECT(untouched(k, 64));
    /* the ends of the range on elements scaled by 1e-20 and 1e20: finite, nonzero diagonal */
    for (i = 0; i < 8; ++i) scaled[i] = 1e-20 * square[i];
    m = steel;
    m.youngs = 1e-100;
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 4, scaled, &m, k, 64),
                  HYCON_OK, NULL));
    EXPECT(isfinite(k[0]) && k[0] > 0.0);
    for (i = 0; i < 8; ++i) scaled[i] = 1e20 * square[i];
    m.youngs = 1e100;
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 4, scaled, &m, k, 64),
                  HYCON_OK, NULL));
    EXPECT(isfinite(k[0]) && k[0] > 0.0);
    return true;
}

/* A 5- or 6-node hybrid element is a quadrilateral with mid-side nodes on straight edges: a
 * convex pentagon or hexagon with every node a corner is rejected, naming the corners. */
static bool test_transition_corners(void) {
    const double pentagon[10] = {0, 0, 1, 0, 1.5, 0.8, 0.5, 1.5, -0.5, 0.8};
    const double hexagon[12] = {0, 0, 1, 0, 1.5, 0.8, 1, 1.6, 0, 1.6, -0.5, 0.8};
    /* the same outlines with straight edges: 4 corners plus mid-side nodes */
    const double five[10] = {0, 0, 1, 0, 2, 0, 2, 1, 0, 1};
    const double six[12] = {0, 0, 1, 0, 2, 0, 2, 1, 1, 1, 0, 1};
    EXPECT(STATUS(hycon_element_check(HYCON_ELEMENT_HYBRID, 5, pentagon),
                  HYCON_ERROR_BAD_ELEMENT, "5 corners"));
    EXPECT(STATUS(hycon_element_check(HYCON_ELEMENT_HYBRID, 6, hexagon),
                  HYCON_ERROR_BAD_ELEMENT, "6 corners"));
    EXPECT(STATUS(hycon_element_check(HYCON_ELEMENT_HYBRID, 5, five), HYCON_OK, NULL));
    EXPECT(STATUS(hycon_element_check(HYCON_ELEMENT_HYBRID, 6, six), HYCON_OK, NULL));
    return true;
}

static bool test_message_protocol(void) {
    char buf[8];
    size_t needed, full_len;
    char full[512];
    EXPECT(hycon_element_stiffness(0, 4, square, &steel, NULL, 0) ==
           HYCON_ERROR_INVALID_ARGUMENT);
    needed = hycon_last_error_message(NULL, 0);
    EXPECT(needed > sizeof buf); /* a real message is longer than 7 characters */
    EXPECT(hycon_last_error_message(NULL, 100) == needed); /* NULL buffer: size query */
    memset(buf, 'x', sizeof buf);
    EXPECT(hycon_last_error_message(buf, 0) == needed && buf[0] == 'x'); /* len 0: no write */
    EXPECT(hycon_last_error_message(buf, 1) == needed && buf[0] == '\0');
    EXPECT(hycon_last_error_message(buf, sizeof buf) == needed);
    EXPECT(strlen(buf) == sizeof buf - 1); /* truncated to len - 1 bytes plus NUL */
    full_len = hycon_last_error_message(full, sizeof full);
    EXPECT(full_len == needed && strlen(full) == needed - 1);
    EXPECT(strncmp(full, buf, sizeof buf - 1) == 0);
    EXPECT(strstr(full, "hycon_element_stiffness") == full); /* names the function */
    /* reading the message does not change it; a successful call clears it */
    EXPECT(hycon_last_error_message(NULL, 0) == needed);
    EXPECT(hycon_element_check(HYCON_ELEMENT_Q4, 4, square) == HYCON_OK);
    EXPECT(hycon_last_error_message(full, sizeof full) == 1 && full[0] == '\0');
    return true;
}

static bool test_stress_routines(void) {
    /* uniform stretch u = x along x: any valid element gives a uniform stress state */
    const double q[8] = {0, 0, 1e-3, 0, 1e-3, 0, 0, 0};
    double s[3], t[2], beta[HYCON_MAX_BETA];
    size_t n_beta = 99;
    fill(s, 3);
    fill(t, 2);
    fill(beta, HYCON_MAX_BETA);
    EXPECT(STATUS(hycon_element_stress(HYCON_ELEMENT_HYBRID, 4, square, &steel, q, NAN, 0.5, s),
                  HYCON_ERROR_INVALID_ARGUMENT, "px"));
    EXPECT(STATUS(hycon_element_stress(HYCON_ELEMENT_HYBRID, 4, square, &steel, NULL, 0.5, 0.5,
                                          s),
                  HYCON_ERROR_NULL_POINTER, "q"));
    EXPECT(STATUS(hycon_element_stress(HYCON_ELEMENT_HYBRID, 4, square, &steel, q, 0.5, 0.5,
                                          NULL),
                  HYCON_ERROR_NULL_POINTER, "out"));
    EXPECT(STATUS(hycon_element_edge_traction(HYCON_ELEMENT_HYBRID, 4, square, &steel, q, 4,
                                                 0.5, t),
                  HYCON_ERROR_INVALID_ARGUMENT, "edge 4"));
    EXPECT(STATUS(hycon_element_edge_traction(HYCON_ELEMENT_HYBRID, 4, square, &steel, q, 1,
                                                 1.5, t),
                  HYCON_ERROR_INVALID_ARGUMENT, "outside [0, 1]"));
    EXPECT(STATUS(hycon_element_stress_params(HYCON_ELEMENT_HYBRID, 4, square, &steel, q,
                                                 beta, 3, &n_beta),
                  HYCON_ERROR_BUFFER_TOO_SMALL, "7 needed"));
    /* the size convention: *needed is written on HYCON_ERROR_BUFFER_TOO_SMALL, out is not */
    EXPECT(n_beta == 7 && untouched(s, 3) && untouched(t, 2) && untouched(beta, 3));
    n_beta = 99;
    EXPECT(STATUS(hycon_element_stress_params(HYCON_ELEMENT_HYBRID, 4, square, &steel, q,
                                                 NULL, 3, &n_beta),
                  HYCON_ERROR_NULL_POINTER, "out is NULL"));
    EXPECT(n_beta == 99);
    /* the size query (NULL, 0) writes only *needed */
    EXPECT(hycon_element_stress_params(HYCON_ELEMENT_HYBRID, 4, square, &steel, q, NULL, 0,
                                       &n_beta) == HYCON_OK);
    EXPECT(n_beta == 7);
    n_beta = 99;

    EXPECT(hycon_element_stress(HYCON_ELEMENT_HYBRID, 4, square, &steel, q, 0.25, 0.75, s) ==
           HYCON_OK);
    EXPECT(s[0] > 0.0 && isfinite(s[1]) && fabs(s[2]) <= 1e-9 * s[0]);
    /* edge 1 runs along x = 1 with outward normal +x: traction = (sx, txy) */
    EXPECT(hycon_element_edge_traction(HYCON_ELEMENT_HYBRID, 4, square, &steel, q, 1, 0.5, t) ==
           HYCON_OK);
    EXPECT(fabs(t[0] - s[0]) <= 1e-9 * s[0] && fabs(t[1]) <= 1e-9 * s[0]);
    EXPECT(hycon_element_stress_params(HYCON_ELEMENT_HYBRID, 4, square, &steel, q, beta,
                                       HYCON_MAX_BETA, &n_beta) == HYCON_OK);
    EXPECT(n_beta == 7 && untouched(beta + 7, HYCON_MAX_BETA - 7));
    EXPECT(hycon_element_stress_params(HYCON_ELEMENT_PIAN_SUMIHARA, 4, square, &steel, q, beta,
                                       HYCON_MAX_BETA, &n_beta) == HYCON_OK);
    EXPECT(n_beta == 5);
    /* Q4 has no stress parameters: (NULL, 0) is enough */
    EXPECT(hycon_element_stress_params(HYCON_ELEMENT_Q4, 4, square, &steel, q, NULL, 0, &n_beta) ==
           HYCON_OK);
    EXPECT(n_beta == 0);
    return true;
}

static bool test_status_names(void) {
    EXPECT(strcmp(hycon_status_name(HYCON_OK), "HYCON_OK") == 0);
    EXPECT(strcmp(hycon_status_name(HYCON_ERROR_BAD_ELEMENT), "HYCON_ERROR_BAD_ELEMENT") == 0);
    EXPECT(strcmp(hycon_status_name(HYCON_ERROR_PANIC), "HYCON_ERROR_PANIC") == 0);
    EXPECT(strcmp(hycon_status_name(7), "HYCON_WARNING") == 0);
    EXPECT(strcmp(hycon_status_name(-1000), "HYCON_ERROR_UNKNOWN") == 0);
    return true;
}

/* Axisymmetric mode (HYCON_AXISYMMETRIC): a ring element on the axis works and its stress has 4
 * components (exactly 4 written); a thickness other than 1, Pian-Sumihara, a 5-node element
 * and a node at r < 0 are rejected, outputs untouched. */
static bool test_axisymmetric(void) {
    static const HyconMaterial axi = {1000.0, 0.4999, 1.0, HYCON_AXISYMMETRIC};
    static const double ring[8] = {0, 0, 1, 0, 1, 1, 0, 1}; /* two nodes on the axis */
    static const double q[8] = {0, 0, 1e-3, 0, 1e-3, 0, 0, 0};
    static const double five[10] = {1, 0, 1.5, 0, 2, 0, 2, 1, 1, 1};
    static const double left[8] = {-1, 0, 1, 0, 1, 1, -1, 1};
    HyconMaterial thick = axi;
    double k[HYCON_MAX_DOF * HYCON_MAX_DOF], s[5];
    const size_t len = HYCON_MAX_DOF * HYCON_MAX_DOF;
    size_t count = 0;
    EXPECT(hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 4, ring, &axi, k, 64) == HYCON_OK);
    EXPECT(isfinite(k[0]) && k[0] > 0.0);
    fill(s, 5);
    EXPECT(hycon_element_stress(HYCON_ELEMENT_HYBRID, 4, ring, &axi, q, 0.5, 0.5, s) ==
           HYCON_OK);
    EXPECT(isfinite(s[0]) && isfinite(s[3]) && s[4] == EXPECT_SENTINEL);
    EXPECT(hycon_element_stress_components(&axi, &count) == HYCON_OK && count == 4);
    EXPECT(hycon_element_stress_components(&steel, &count) == HYCON_OK && count == 3);
    fill(k, len);
    thick.thickness = 2.0;
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_Q4, 4, ring, &thick, k, len),
                  HYCON_ERROR_INVALID_MATERIAL, "2 pi r"));
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_PIAN_SUMIHARA, 4, ring, &axi, k, len),
                  HYCON_ERROR_BAD_ELEMENT, "axisymmetric"));
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 5, five, &axi, k, len),
                  HYCON_ERROR_BAD_ELEMENT, "4-node elements only"));
    EXPECT(STATUS(hycon_element_stiffness(HYCON_ELEMENT_Q4, 4, left, &axi, k, len),
                  HYCON_ERROR_BAD_ELEMENT, "negative radius"));
    EXPECT(untouched(k, len));
    return true;
}

/* The load and check routines (hycon_element_edge_load, _volume, _quality, _stress_natural and
 * the hycon_brick_ twins): NULL pointers, short outputs, out-of-range edges, faces and natural
 * coordinates, NaN in loads, coordinates and natural coordinates, bad shapes; the outputs stay
 * untouched on every error. */
static bool test_load_routines(void) {
    static const double q[8] = {0, 0, 1e-3, 0, 1e-3, 0, 0, 0};
    static const double clockwise[8] = {0, 0, 0, 1, 1, 1, 1, 0};
    static const double cube[24] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                    0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    static const HyconSolidMaterial solid = {210e3, 0.3};
    const double p2[2] = {1.0, 1.0}, p4[4] = {1.0, 1.0, 1.0, 1.0};
    const double nan2[2] = {1.0, NAN}, nan4[4] = {0.0, 0.0, INFINITY, 0.0};
    double f[HYCON_BRICK_DOF], v = EXPECT_SENTINEL, s[6], bad_cube[24], q24[24];
    size_t i;
    for (i = 0; i < 24; ++i) q24[i] = 0.0;
    fill(f, HYCON_BRICK_DOF);
    fill(s, 6);
    /* edge loads */
    EXPECT(STATUS(hycon_element_edge_load(HYCON_ELEMENT_HYBRID, 4, NULL, &steel, 0, p2, NULL,
                                             f, 8),
                  HYCON_ERROR_NULL_POINTER, "coords"));
    EXPECT(STATUS(hycon_element_edge_load(HYCON_ELEMENT_HYBRID, 4, square, NULL, 0, p2, NULL,
                                             f, 8),
                  HYCON_ERROR_NULL_POINTER, "material"));
    EXPECT(STATUS(hycon_element_edge_load(HYCON_ELEMENT_HYBRID, 4, square, &steel, 0, p2,
                                             NULL, NULL, 8),
                  HYCON_ERROR_NULL_POINTER, "out"));
    EXPECT(STATUS(hycon_element_edge_load(HYCON_ELEMENT_HYBRID, 4, square, &steel, 0, p2,
                                             NULL, f, 7),
                  HYCON_ERROR_BUFFER_TOO_SMALL, "8 needed"));
    EXPECT(STATUS(hycon_element_edge_load(HYCON_ELEMENT_Q4, 4, square, &steel, 4, p2, NULL, f,
                                             8),
                  HYCON_ERROR_INVALID_ARGUMENT, "edge 4"));
    EXPECT(STATUS(hycon_element_edge_load(HYCON_ELEMENT_Q4, 4, square, &steel, 0, nan2, NULL,
                                             f, 8),
                  HYCON_ERROR_INVALID_ARGUMENT, "pressure[1]"));
    EXPECT(STATUS(hycon_element_edge_load(HYCON_ELEMENT_Q4, 4, square, &steel, 0, NULL, nan4,
                                             f, 8),
                  HYCON_ERROR_INVALID_ARGUMENT, "traction[2]"));
    EXPECT(STATUS(hycon_element_edge_load(HYCON_ELEMENT_Q4, 4, clockwise, &steel, 0, p2, NULL,
                                             f, 8),
                  HYCON_ERROR_BAD_ELEMENT, "inverted"));
    EXPECT(STATUS(hycon_element_edge_load(0, 4, square, &steel, 0, p2, NULL, f, 8),
                  HYCON_ERROR_INVALID_ARGUMENT, "unknown element kind"));
    /* volume and quality */
    EXPECT(STATUS(hycon_element_volume(HYCON_ELEMENT_Q4, 4, square, &steel, NULL),
                  HYCON_ERROR_NULL_POINTER, "out"));
    EXPECT(STATUS(hycon_element_volume(HYCON_ELEMENT_Q4, 3, square, &steel, &v),
                  HYCON_ERROR_BAD_ELEMENT, "3 nodes"));
    EXPECT(STATUS(hycon_element_quality(HYCON_ELEMENT_Q4, 4, clockwise, &v),
                  HYCON_ERROR_BAD_ELEMENT, "inverted"));
    EXPECT(STATUS(hycon_element_quality(HYCON_ELEMENT_Q4, 4, NULL, &v),
                  HYCON_ERROR_NULL_POINTER, "coords"));
    /* stress at natural coordinates */
    EXPECT(STATUS(hycon_element_stress_natural(HYCON_ELEMENT_HYBRID, 4, square, &steel, q,
                                                  1.5, 0.0, s),
                  HYCON_ERROR_INVALID_ARGUMENT, "outside [-1, 1]"));
    EXPECT(STATUS(hycon_element_stress_natural(HYCON_ELEMENT_HYBRID, 4, square, &steel, q,
                                                  0.0, NAN, s),
                  HYCON_ERROR_INVALID_ARGUMENT, "not finite"));
    EXPECT(STATUS(hycon_element_stress_natural(HYCON_ELEMENT_HYBRID, 4, square, &steel, NULL,
                                                  0.0, 0.0, s),
                  HYCON_ERROR_NULL_POINTER, "q"));
    EXPECT(STATUS(hycon_element_stress_natural(HYCON_ELEMENT_HYBRID, 4, square, &steel, q,
                                                  0.0, 0.0, NULL),
                  HYCON_ERROR_NULL_POINTER, "out"));
    /* bricks */
    EXPECT(STATUS(hycon_brick_face_load(HYCON_BRICK_H8, cube, 6, p4, NULL, f, 24),
                  HYCON_ERROR_INVALID_ARGUMENT, "face 6"));
    EXPECT(STATUS(hycon_brick_face_load(HYCON_BRICK_H8, cube, 0, p4, NULL, f, 23),
                  HYCON_ERROR_BUFFER_TOO_SMALL, "24 needed"));
    EXPECT(STATUS(hycon_brick_face_load(HYCON_BRICK_H8, cube, 0, nan4, NULL, f, 24),
                  HYCON_ERROR_INVALID_ARGUMENT, "pressure[2]"));
    EXPECT(STATUS(hycon_brick_face_load(HYCON_BRICK_H8, NULL, 0, p4, NULL, f, 24),
                  HYCON_ERROR_NULL_POINTER, "coords"));
    EXPECT(STATUS(hycon_brick_face_load(7, cube, 0, p4, NULL, f, 24),
                  HYCON_ERROR_INVALID_ARGUMENT, "unknown brick kind"));
    for (i = 0; i < 24; ++i) bad_cube[i] = cube[i];
    bad_cube[5] = NAN;
    EXPECT(STATUS(hycon_brick_volume(HYCON_BRICK_H8, bad_cube, &v),
                  HYCON_ERROR_INVALID_ARGUMENT, "coords[5]"));
    EXPECT(STATUS(hycon_brick_volume(HYCON_BRICK_H8, cube, NULL), HYCON_ERROR_NULL_POINTER,
                  "out"));
    bad_cube[5] = 0.0;
    bad_cube[20] = -1.0; /* node 6 below the bottom face: Jacobian not positive */
    EXPECT(STATUS(hycon_brick_quality(HYCON_BRICK_HYBRID18, bad_cube, &v),
                  HYCON_ERROR_BAD_ELEMENT, NULL));
    EXPECT(STATUS(hycon_brick_stress_natural(HYCON_BRICK_HYBRID18, cube, &solid, q24, 0.0,
                                                -1.5, 0.0, s),
                  HYCON_ERROR_INVALID_ARGUMENT, "outside [-1, 1]"));
    EXPECT(STATUS(hycon_brick_stress_natural(HYCON_BRICK_HYBRID18, cube, NULL, q24, 0.0, 0.0,
                                                0.0, s),
                  HYCON_ERROR_NULL_POINTER, "material"));
    EXPECT(untouched(f, HYCON_BRICK_DOF) && untouched(s, 6) && v == EXPECT_SENTINEL);
    /* the good calls write exactly their outputs */
    EXPECT(hycon_element_edge_load(HYCON_ELEMENT_Q4, 4, square, &steel, 0, p2, NULL, f,
                                   HYCON_BRICK_DOF) == HYCON_OK);
    EXPECT(f[7] == 0.0 && untouched(f + 8, HYCON_BRICK_DOF - 8));
    EXPECT(hycon_brick_stress_natural(HYCON_BRICK_H8, cube, &solid, q24, 1.0, -1.0, 0.0, s) ==
           HYCON_OK);
    EXPECT(s[5] == 0.0);
    return true;
}

int main(void) {
    static const struct {
        const char *name;
        bool (*run)(void);
    } tests[] = {
        {"version", test_version},
        {"good_stiffness", test_good_stiffness},
        {"null_pointers", test_null_pointers},
        {"short_output", test_short_output},
        {"bad_kind_and_node_count", test_bad_kind_and_node_count},
        {"non_finite_coordinates", test_non_finite_coordinates},
        {"bad_shapes", test_bad_shapes},
        {"bad_material", test_bad_material},
        {"material_scale", test_material_scale},
        {"transition_corners", test_transition_corners},
        {"message_protocol", test_message_protocol},
        {"stress_routines", test_stress_routines},
        {"status_names", test_status_names},
        {"axisymmetric", test_axisymmetric},
        {"load_routines", test_load_routines},
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
