/* Bad-input tests of the 3D contact C API, model family (hycon_solid_model_* and
 * hycon_solid_contact_*), as a C host would hit them (strict C99), in the style of
 * contact_bad_input.c: one `bool test_x(void)` per bad-input class, each checking the status, a
 * part of the message from hycon_last_error_message, and that outputs are untouched (filled
 * with a sentinel first). main prints one line per case and FAILED on a mismatch.
 *
 * The model: two unit cubes of one brick each, B (brick 1, nodes 8-15) on [0, 1]^3 and A
 * (brick 0, nodes 0-7) on [0, 1]^2 x [1, 2], touching along z = 1 with nodes of their own.
 * B's bottom is held, A's top moved down; the pair is A's bottom (brick 0, local face 4) on B's
 * top (brick 1, local face 5). */
#include "expect.h"
#include "hycon.h"

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#define BRICKS(nodes, n, materials, kind) (&(HyconBrickBlock){(nodes), (n), (materials), (kind)})
#define FACES(faces, n) (&(HyconBrickFaces){(faces), (n)})

/* ---------------------------------------------------------------------------------------- */
/* The two-cube model */

#define NN 16
#define NDOF (3 * NN)
#define PRESS 1e-3

static double coords[3 * NN];
static const size_t bricks[16] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
static const size_t a_face[2] = {0, 4}, b_face[2] = {1, 5};
static const size_t top[4] = {4, 5, 6, 7}, bottom[4] = {8, 9, 10, 11};
static const HyconSolidMaterial steel = {210e3, 0.3};

/* cube `c` (0: A on z in [1, 2], 1: B on [0, 1]) in the brick node order */
static void build_mesh(void) {
    static const double unit[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                      {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    size_t c, k, d;
    for (c = 0; c < 2; ++c)
        for (k = 0; k < 8; ++k)
            for (d = 0; d < 3; ++d)
                coords[3 * (8 * c + k) + d] = unit[k][d] + (d == 2 && c == 0 ? 1.0 : 0.0);
}

/* A valid model, with the supports and (if `with_pair`) the pair; NULL on a failure. */
static HyconSolidModel *make_model(bool with_pair) {
    HyconSolidModel *m = NULL;
    HyconStatus s = hycon_solid_model_new(&m, coords, NN,
                                          BRICKS(bricks, 2, NULL, HYCON_BRICK_HYBRID18), &steel, 1);
    if (s == HYCON_OK) s = hycon_solid_model_prescribe(m, bottom, 4, HYCON_XYZ);
    if (s == HYCON_OK) s = hycon_solid_model_prescribe(m, top, 4, HYCON_XYZ);
    if (s == HYCON_OK && with_pair)
        s = hycon_solid_model_add_pair(m, FACES(a_face, 1), FACES(b_face, 1), 0.0, NULL);
    if (s != HYCON_OK) {
        char message[512];
        hycon_last_error_message(message, sizeof message);
        fprintf(stderr, "  building the model failed: %s: %s\n", hycon_status_name(s), message);
        hycon_solid_model_free(m);
        return NULL;
    }
    return m;
}

static HyconSolidContact *make_contact(void) {
    HyconSolidContact *c = NULL;
    HyconSolidModel *m = make_model(true);
    HyconStatus s;
    if (m == NULL) return NULL;
    s = hycon_solid_contact_new(&c, m, NULL);
    hycon_solid_model_free(m);
    return s == HYCON_OK ? c : NULL;
}

static void press_values(double *qp) {
    size_t i;
    memset(qp, 0, NDOF * sizeof *qp);
    for (i = 0; i < 4; ++i) qp[3 * top[i] + 2] = -PRESS;
}

/* ---------------------------------------------------------------------------------------- */
/* Tests */

static bool test_model_new_null_pointers(void) {
    HyconSolidModel *m = MARKER(HyconSolidModel);
    bool ok = true;
    ok = ok && STATUS_FN(hycon_solid_model_new,
                         (NULL, coords, NN, BRICKS(bricks, 2, NULL, 1), &steel, 1),
                         HYCON_ERROR_NULL_POINTER, "out is NULL");
    ok = ok && STATUS_FN(hycon_solid_model_new, (&m, NULL, NN, BRICKS(bricks, 2, NULL, 1), &steel, 1),
                         HYCON_ERROR_NULL_POINTER, "coords is NULL");
    ok = ok && STATUS_FN(hycon_solid_model_new, (&m, coords, NN, NULL, &steel, 1),
                         HYCON_ERROR_NULL_POINTER, "elements is NULL");
    ok = ok && STATUS_FN(hycon_solid_model_new, (&m, coords, NN, BRICKS(NULL, 2, NULL, 1), &steel, 1),
                         HYCON_ERROR_NULL_POINTER, "elements.nodes is NULL");
    ok = ok && STATUS_FN(hycon_solid_model_new, (&m, coords, NN, BRICKS(bricks, 2, NULL, 1), NULL, 1),
                         HYCON_ERROR_NULL_POINTER, "materials is NULL");
    return ok && m == MARKER(HyconSolidModel);
}

static bool test_model_new_bad_lengths_and_values(void) {
    HyconSolidModel *m = MARKER(HyconSolidModel);
    double bad[3 * NN];
    size_t unknown[16], materials[2] = {0, 1};
    const HyconSolidMaterial soft = {-1.0, 0.3};
    bool ok = true;
    memcpy(bad, coords, sizeof bad);
    bad[7] = NAN;
    memcpy(unknown, bricks, sizeof unknown);
    unknown[3] = NN;
    ok = ok && STATUS_FN(hycon_solid_model_new, (&m, coords, 0, BRICKS(bricks, 2, NULL, 1), &steel, 1),
                         HYCON_ERROR_INVALID_ARGUMENT, "n_nodes = 0");
    ok = ok && STATUS_FN(hycon_solid_model_new, (&m, coords, NN, BRICKS(bricks, 0, NULL, 1), &steel, 1),
                         HYCON_ERROR_INVALID_ARGUMENT, "n_elements = 0");
    ok = ok && STATUS_FN(hycon_solid_model_new, (&m, coords, NN, BRICKS(bricks, 2, NULL, 1), &steel, 0),
                         HYCON_ERROR_INVALID_ARGUMENT, "n_materials = 0");
    ok = ok && STATUS_FN(hycon_solid_model_new,
                         (&m, coords, SIZE_MAX / 2, BRICKS(bricks, 2, NULL, 1), &steel, 1),
                         HYCON_ERROR_INVALID_ARGUMENT, "too large");
    ok = ok && STATUS_FN(hycon_solid_model_new, (&m, bad, NN, BRICKS(bricks, 2, NULL, 1), &steel, 1),
                         HYCON_ERROR_INVALID_ARGUMENT, "coords[7] = NaN is not finite");
    ok = ok && STATUS_FN(hycon_solid_model_new, (&m, coords, NN, BRICKS(unknown, 2, NULL, 1), &steel, 1),
                         HYCON_ERROR_INVALID_ARGUMENT, "brick 0 uses node 16");
    ok = ok && STATUS_FN(hycon_solid_model_new, (&m, coords, NN, BRICKS(bricks, 2, NULL, 9), &steel, 1),
                         HYCON_ERROR_INVALID_ARGUMENT, "unknown brick kind 9");
    ok = ok && STATUS_FN(hycon_solid_model_new, (&m, coords, NN, BRICKS(bricks, 2, NULL, 1), &soft, 1),
                         HYCON_ERROR_INVALID_MATERIAL, "Young's modulus");
    ok = ok && STATUS_FN(hycon_solid_model_new,
                         (&m, coords, NN, BRICKS(bricks, 2, materials, 1), &steel, 1),
                         HYCON_ERROR_INVALID_ARGUMENT, "brick 1 uses material 1");
    return ok && m == MARKER(HyconSolidModel);
}

static bool test_model_new_inverted_brick(void) {
    HyconSolidModel *m = MARKER(HyconSolidModel);
    size_t inverted[16];
    bool ok = true;
    memcpy(inverted, bricks, sizeof inverted);
    /* brick 1 upside down: its top nodes first */
    memcpy(inverted + 8, bricks + 12, 4 * sizeof *inverted);
    memcpy(inverted + 12, bricks + 8, 4 * sizeof *inverted);
    ok = ok && STATUS_FN(hycon_solid_model_new, (&m, coords, NN, BRICKS(inverted, 2, NULL, 1), &steel, 1),
                         HYCON_ERROR_BAD_ELEMENT, "element 1");
    return ok && m == MARKER(HyconSolidModel);
}

static bool test_free_null(void) {
    char message[64];
    hycon_solid_model_free(NULL);
    hycon_solid_contact_free(NULL);
    return hycon_last_error_message(message, sizeof message) >= 1;
}

static bool test_prescribe_bad_input(void) {
    HyconSolidModel *m = make_model(false);
    const size_t unknown[1] = {NN}, one[1] = {2}, twice[2] = {3, 3};
    bool ok = true;
    EXPECT(m != NULL);
    ok = ok && STATUS_FN(hycon_solid_model_prescribe, (NULL, one, 1, HYCON_X),
                         HYCON_ERROR_NULL_POINTER, "model is NULL");
    ok = ok && STATUS_FN(hycon_solid_model_prescribe, (m, NULL, 1, HYCON_X),
                         HYCON_ERROR_NULL_POINTER, "nodes is NULL");
    ok = ok && STATUS_FN(hycon_solid_model_prescribe, (m, unknown, 1, HYCON_X),
                         HYCON_ERROR_INVALID_ARGUMENT, "unknown node 16");
    ok = ok && STATUS_FN(hycon_solid_model_prescribe, (m, one, 1, 0), HYCON_ERROR_INVALID_ARGUMENT,
                         "directions = 0");
    ok = ok && STATUS_FN(hycon_solid_model_prescribe, (m, one, 1, 8), HYCON_ERROR_INVALID_ARGUMENT,
                         "directions = 8");
    ok = ok && STATUS_FN(hycon_solid_model_prescribe, (m, twice, 2, HYCON_Z),
                         HYCON_ERROR_INVALID_ARGUMENT, "node 3 direction z is prescribed twice");
    ok = ok && STATUS_FN(hycon_solid_model_prescribe, (m, top, 1, HYCON_Y),
                         HYCON_ERROR_INVALID_ARGUMENT, "node 4 direction y is prescribed twice");
    /* nothing was prescribed by the failed calls: node 3 takes z now */
    ok = ok && STATUS_FN(hycon_solid_model_prescribe, (m, twice, 1, HYCON_Z), HYCON_OK, NULL);
    hycon_solid_model_free(m);
    return ok;
}

static bool test_add_pair_null_pointers(void) {
    HyconSolidModel *m = make_model(false);
    size_t index = 77;
    bool ok = true;
    EXPECT(m != NULL);
    ok = ok && STATUS_FN(hycon_solid_model_add_pair, (NULL, FACES(a_face, 1), FACES(b_face, 1), 0.0, &index),
                         HYCON_ERROR_NULL_POINTER, "model is NULL");
    ok = ok && STATUS_FN(hycon_solid_model_add_pair, (m, NULL, FACES(b_face, 1), 0.0, &index),
                         HYCON_ERROR_NULL_POINTER, "a is NULL");
    ok = ok && STATUS_FN(hycon_solid_model_add_pair, (m, FACES(a_face, 1), NULL, 0.0, &index),
                         HYCON_ERROR_NULL_POINTER, "b is NULL");
    ok = ok && STATUS_FN(hycon_solid_model_add_pair, (m, FACES(NULL, 1), FACES(b_face, 1), 0.0, &index),
                         HYCON_ERROR_NULL_POINTER, "a.faces is NULL");
    ok = ok && index == 77;
    hycon_solid_model_free(m);
    return ok;
}

static bool test_add_pair_bad_faces(void) {
    HyconSolidModel *m = make_model(false);
    const size_t no_brick[2] = {2, 4}, no_face[2] = {0, 6}, twice[4] = {0, 4, 0, 4};
    size_t index = 77;
    bool ok = true;
    EXPECT(m != NULL);
    ok = ok && STATUS_FN(hycon_solid_model_add_pair, (m, FACES(no_brick, 1), FACES(b_face, 1), 0.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "A face 0: brick 2 does not exist (2 bricks)");
    ok = ok && STATUS_FN(hycon_solid_model_add_pair, (m, FACES(a_face, 1), FACES(no_face, 1), 0.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "B face 0: local face 6 of brick 0");
    ok = ok && STATUS_FN(hycon_solid_model_add_pair, (m, FACES(twice, 2), FACES(b_face, 1), 0.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "listed twice");
    ok = ok && STATUS_FN(hycon_solid_model_add_pair, (m, FACES(NULL, 0), FACES(b_face, 1), 0.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "contact side A has no face");
    ok = ok && STATUS_FN(hycon_solid_model_add_pair, (m, FACES(a_face, 1), FACES(b_face, 1), -0.1, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, NULL);
    ok = ok && STATUS_FN(hycon_solid_model_add_pair, (m, FACES(a_face, 1), FACES(b_face, 1), NAN, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, NULL);
    ok = ok && index == 77;
    ok = ok && STATUS_FN(hycon_solid_model_add_pair, (m, FACES(a_face, 1), FACES(b_face, 1), 0.2, &index),
                         HYCON_OK, NULL);
    ok = ok && index == 0;
    hycon_solid_model_free(m);
    return ok;
}

static bool test_symmetry_plane_bad_input(void) {
    HyconSolidModel *m = make_model(false);
    const double point[3] = {0, 0, 0}, zero[3] = {0, 0, 0}, x[3] = {1, 0, 0};
    const double bad[3] = {0, INFINITY, 0};
    bool ok = true;
    EXPECT(m != NULL);
    ok = ok && STATUS_FN(hycon_solid_model_add_symmetry_plane, (NULL, point, x),
                         HYCON_ERROR_NULL_POINTER, "model is NULL");
    ok = ok && STATUS_FN(hycon_solid_model_add_symmetry_plane, (m, NULL, x),
                         HYCON_ERROR_NULL_POINTER, "point is NULL");
    ok = ok && STATUS_FN(hycon_solid_model_add_symmetry_plane, (m, point, NULL),
                         HYCON_ERROR_NULL_POINTER, "normal is NULL");
    ok = ok && STATUS_FN(hycon_solid_model_add_symmetry_plane, (m, bad, x),
                         HYCON_ERROR_INVALID_ARGUMENT, "point[1] = inf is not finite");
    ok = ok && STATUS_FN(hycon_solid_model_add_symmetry_plane, (m, point, zero),
                         HYCON_ERROR_INVALID_ARGUMENT, "a non-zero normal");
    hycon_solid_model_free(m);
    return ok;
}

static bool test_contact_new_bad_input(void) {
    HyconSolidModel *m = make_model(true), *loose = NULL;
    HyconSolidContact *c = MARKER(HyconSolidContact);
    HyconContactOptions options;
    bool ok = true;
    EXPECT(m != NULL);
    ok = ok && STATUS_FN(hycon_solid_contact_new, (&c, NULL, NULL), HYCON_ERROR_NULL_POINTER,
                         "model is NULL");
    ok = ok && STATUS_FN(hycon_solid_contact_new, (NULL, m, NULL), HYCON_ERROR_NULL_POINTER,
                         "out is NULL");
    EXPECT(hycon_contact_options_default(&options) == HYCON_OK);
    options.size = 8;
    ok = ok && STATUS_FN(hycon_solid_contact_new, (&c, m, &options), HYCON_ERROR_INVALID_ARGUMENT,
                         "options.size = 8");
    EXPECT(hycon_contact_options_default(&options) == HYCON_OK);
    options.tolerance = -1.0;
    ok = ok && STATUS_FN(hycon_solid_contact_new, (&c, m, &options), HYCON_ERROR_INVALID_ARGUMENT,
                         "tolerance");
    /* A held by nothing (its top free): singular */
    EXPECT(hycon_solid_model_new(&loose, coords, NN, BRICKS(bricks, 2, NULL, 1), &steel, 1) ==
           HYCON_OK);
    EXPECT(hycon_solid_model_prescribe(loose, bottom, 4, HYCON_XYZ) == HYCON_OK);
    ok = ok && STATUS_FN(hycon_solid_contact_new, (&c, loose, NULL), HYCON_ERROR_SINGULAR, NULL);
    ok = ok && c == MARKER(HyconSolidContact);
    hycon_solid_model_free(loose);
    hycon_solid_model_free(m);
    return ok;
}

static bool test_increment_bad_input(void) {
    HyconSolidContact *c = make_contact();
    double load[NDOF], qp[NDOF];
    HyconIncrementInfo info;
    size_t records = 99;
    bool ok = true;
    EXPECT(c != NULL);
    memset(load, 0, sizeof load);
    press_values(qp);
    fill_bytes(&info, sizeof info);
    ok = ok && STATUS_FN(hycon_solid_contact_increment, (NULL, load, NDOF, qp, NDOF, &info),
                         HYCON_ERROR_NULL_POINTER, "contact is NULL");
    ok = ok && STATUS_FN(hycon_solid_contact_increment, (c, NULL, NDOF, qp, NDOF, &info),
                         HYCON_ERROR_NULL_POINTER, "load is NULL");
    ok = ok && STATUS_FN(hycon_solid_contact_increment, (c, load, NDOF - 1, qp, NDOF, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "48");
    ok = ok && STATUS_FN(hycon_solid_contact_increment, (c, load, NDOF, qp, 3, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "48");
    load[5] = NAN;
    ok = ok && STATUS_FN(hycon_solid_contact_increment, (c, load, NDOF, qp, NDOF, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "not finite");
    load[5] = 0.0;
    qp[3 * top[0] + 2] = INFINITY;
    ok = ok && STATUS_FN(hycon_solid_contact_increment, (c, load, NDOF, qp, NDOF, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "not finite");
    ok = ok && bytes_untouched(&info, sizeof info);
    ok = ok && hycon_solid_contact_records(c, 0, NULL, 0, &records) == HYCON_OK && records == 0;
    hycon_solid_contact_free(c);
    return ok;
}

/* A good press, then the queries' size convention and bad arguments. */
static bool test_results(void) {
    HyconSolidContact *c = make_contact();
    double load[NDOF], qp[NDOF], u[NDOF], forces[NDOF];
    HyconIncrementInfo info;
    HyconSolidNodeResult nodes[4];
    HyconSolidBNodeResult b_nodes[4];
    HyconSolidContactNode surface[4];
    HyconConstraintEntry rows[256];
    size_t needed = 0, i;
    double total = 0.0;
    bool ok = true;
    EXPECT(c != NULL);
    memset(load, 0, sizeof load);
    press_values(qp);
    ok = ok && STATUS_FN(hycon_solid_contact_increment, (c, load, NDOF, qp, NDOF, &info), HYCON_OK,
                         NULL);
    ok = ok && info.increment == 1 && info.active == 4;
    /* sizes */
    ok = ok && STATUS_FN(hycon_solid_contact_displacement, (c, NULL, 0, &needed), HYCON_OK, NULL) &&
         needed == NDOF;
    ok = ok && STATUS_FN(hycon_solid_contact_node_results, (c, 0, NULL, 0, &needed), HYCON_OK,
                         NULL) &&
         needed == 4;
    /* too small, NULL with a length, unknown pair: outputs untouched */
    fill_bytes(nodes, sizeof nodes);
    needed = 0;
    ok = ok && STATUS_FN(hycon_solid_contact_node_results, (c, 0, nodes, 3, &needed),
                         HYCON_ERROR_BUFFER_TOO_SMALL, "4 needed") &&
         needed == 4;
    ok = ok && STATUS_FN(hycon_solid_contact_node_results, (c, 0, NULL, 4, NULL),
                         HYCON_ERROR_NULL_POINTER, "out is NULL but len is 4");
    ok = ok && STATUS_FN(hycon_solid_contact_node_results, (c, 1, nodes, 4, NULL),
                         HYCON_ERROR_INVALID_ARGUMENT, "contact pair 1 does not exist (1 pairs)");
    ok = ok && STATUS_FN(hycon_solid_contact_node_results, (NULL, 0, nodes, 4, NULL),
                         HYCON_ERROR_NULL_POINTER, "contact is NULL");
    ok = ok && bytes_untouched(nodes, sizeof nodes);
    ok = ok && STATUS_FN(hycon_solid_contact_records, (c, 99, NULL, 0, &needed),
                         HYCON_ERROR_INVALID_ARGUMENT, "first = 99");
    /* the good calls: a uniform press of A's bottom on B's top, balanced */
    ok = ok && STATUS_FN(hycon_solid_contact_displacement, (c, u, NDOF, NULL), HYCON_OK, NULL);
    ok = ok && STATUS_FN(hycon_solid_contact_forces, (c, forces, NDOF, NULL), HYCON_OK, NULL);
    ok = ok && STATUS_FN(hycon_solid_contact_node_results, (c, 0, nodes, 4, NULL), HYCON_OK, NULL);
    ok = ok && STATUS_FN(hycon_solid_contact_b_node_results, (c, 0, b_nodes, 4, NULL), HYCON_OK,
                         NULL);
    ok = ok && STATUS_FN(hycon_solid_contact_surface_nodes, (c, 0, surface, 4, NULL), HYCON_OK,
                         NULL);
    ok = ok && STATUS_FN(hycon_solid_contact_constraint_rows, (c, 0, rows, 256, &needed), HYCON_OK,
                         NULL);
    EXPECT(ok);
    EXPECT(u[3 * top[0] + 2] == -PRESS);
    for (i = 0; i < 4; ++i) {
        EXPECT(nodes[i].node == i); /* A nodes in increasing id order: 0 1 2 3 */
        EXPECT(nodes[i].state == HYCON_NODE_FRICTIONLESS);
        EXPECT(nodes[i].tn < 0.0);
        EXPECT(nodes[i].normal[2] == -1.0 && surface[i].normal[2] == -1.0);
        EXPECT(fabs(nodes[i].weight - 0.25) < 1e-12 && fabs(surface[i].coverage - 1.0) < 1e-12);
        EXPECT(b_nodes[i].node == 12 + i && b_nodes[i].pressure > 0.0);
        EXPECT(fabs(nodes[i].force[2] + b_nodes[i].force[2]) < 1e-12 * fabs(nodes[i].force[2]));
        total += nodes[i].force[2];
    }
    /* the contact forces over the field are A's and B's nodal forces */
    EXPECT(fabs(forces[2] - nodes[0].force[2]) < 1e-12 * fabs(total));
    /* 3 rows per A node, each row within 0 .. 11 */
    for (i = 0; i < needed; ++i) EXPECT(rows[i].row < 12 && rows[i].column < NDOF);
    EXPECT(rows[needed - 1].row == 11);
    hycon_solid_contact_free(c);
    return ok;
}

int main(void) {
    static const struct {
        const char *name;
        bool (*run)(void);
    } tests[] = {
        {"model_new_null_pointers", test_model_new_null_pointers},
        {"model_new_bad_lengths_and_values", test_model_new_bad_lengths_and_values},
        {"model_new_inverted_brick", test_model_new_inverted_brick},
        {"free_null_is_a_no_op", test_free_null},
        {"prescribe_bad_input", test_prescribe_bad_input},
        {"add_pair_null_pointers", test_add_pair_null_pointers},
        {"add_pair_bad_faces", test_add_pair_bad_faces},
        {"symmetry_plane_bad_input", test_symmetry_plane_bad_input},
        {"contact_new_bad_input", test_contact_new_bad_input},
        {"increment_bad_input", test_increment_bad_input},
        {"results", test_results},
    };
    size_t i, n = sizeof tests / sizeof tests[0];
    int failures = 0;
    build_mesh();
    for (i = 0; i < n; ++i) {
        bool ok = tests[i].run();
        printf("%-36s %s\n", tests[i].name, ok ? "ok" : "FAILED");
        fflush(stdout);
        failures += !ok;
    }
    if (failures != 0) {
        printf("%d of %d test(s) FAILED\n", failures, (int)n);
        return 1;
    }
    return 0;
}
