/* Bad-input tests of the hycon contact C API (model API and host-assembly API), as a C host
 * would hit them (strict C99). One `bool test_x(void)` per bad-input class; each checks the
 * status, a part of the message from hycon_last_error_message, and that outputs are untouched
 * (filled with a sentinel first). main prints one line per case and FAILED on a mismatch.
 *
 * The model: two stacked blocks of quads. The lower block (4 x 2 elements, [0, 2] x [0, 1]) is
 * held at its bottom; the upper one (2 x 2 elements, [0.6, 1.4] x [1, 2]) is pressed down
 * through prescribed displacements of its top. Contact pair: A = the upper block's bottom (left
 * to right), B = the lower block's top (right to left), each with its body on the left. The
 * host-assembly variant assembles the same mesh itself (hycon_element_stiffness), eliminates
 * the prescribed dofs and solves with a dense Cholesky factor in a solve callback. */
#include "expect.h"
#include "hycon.h"

#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The input views, built in place (C99 compound literals) so that a call reads like the
 * argument list it stands for. */
#define BLOCK(offsets, nodes, n_elements, materials, kind)                                     \
    (&(HyconElementBlock){(offsets), (nodes), (n_elements), (materials), (kind)})
#define LINE(nodes, n) (&(HyconPolyline){(nodes), (n)})
#define HOST_NODES(ids, coords, equations, n)                                                  \
    (&(HyconHostNodes){(ids), (coords), (equations), (n)})

/* ---------------------------------------------------------------------------------------- */
/* The two-block model */

#define NXL 4
#define NYL 2
#define NXU 2
#define NYU 2
#define NNL ((NXL + 1) * (NYL + 1)) /* 15 lower nodes */
#define NNU ((NXU + 1) * (NYU + 1)) /* 9 upper nodes */
#define NN (NNL + NNU)              /* 24 nodes */
#define NEL (NXL * NYL)             /* 8 lower elements */
#define NE (NEL + NXU * NYU)        /* 12 elements */
#define NDOF (2 * NN)               /* 48 dofs */
#define NA (NXU + 1)                /* 3 A nodes */
#define NB (NXL + 1)                /* 5 B nodes */
#define NTOP (NXU + 1)
#define NBOTTOM (NXL + 1)
#define PRESS 1e-3
#define FRICTION 0.3

static double coords[2 * NN];
static size_t offsets[NE + 1];
static size_t conn[4 * NE];
static size_t pair_a[NA], pair_b[NB], top[NTOP], bottom[NBOTTOM];
static const HyconMaterial steel = {210e3, 0.3, 1.0, HYCON_PLANE_STRAIN};

static size_t lower_node(size_t i, size_t j) { return j * (NXL + 1) + i; }
static size_t upper_node(size_t i, size_t j) { return NNL + j * (NXU + 1) + i; }

static void build_mesh(void) {
    size_t i, j, e = 0;
    for (j = 0; j <= NYL; ++j)
        for (i = 0; i <= NXL; ++i) {
            coords[2 * lower_node(i, j)] = 2.0 * (double)i / NXL;
            coords[2 * lower_node(i, j) + 1] = 1.0 * (double)j / NYL;
        }
    for (j = 0; j <= NYU; ++j)
        for (i = 0; i <= NXU; ++i) {
            coords[2 * upper_node(i, j)] = 0.6 + 0.8 * (double)i / NXU;
            coords[2 * upper_node(i, j) + 1] = 1.0 + 1.0 * (double)j / NYU;
        }
    for (j = 0; j < NYL; ++j)
        for (i = 0; i < NXL; ++i, ++e) {
            conn[4 * e] = lower_node(i, j);
            conn[4 * e + 1] = lower_node(i + 1, j);
            conn[4 * e + 2] = lower_node(i + 1, j + 1);
            conn[4 * e + 3] = lower_node(i, j + 1);
        }
    for (j = 0; j < NYU; ++j)
        for (i = 0; i < NXU; ++i, ++e) {
            conn[4 * e] = upper_node(i, j);
            conn[4 * e + 1] = upper_node(i + 1, j);
            conn[4 * e + 2] = upper_node(i + 1, j + 1);
            conn[4 * e + 3] = upper_node(i, j + 1);
        }
    for (e = 0; e <= NE; ++e) offsets[e] = 4 * e;
    for (i = 0; i < NA; ++i) pair_a[i] = upper_node(i, 0);
    for (i = 0; i < NB; ++i) pair_b[i] = lower_node(NXL - i, NYL);
    for (i = 0; i < NTOP; ++i) top[i] = upper_node(i, NYU);
    for (i = 0; i < NBOTTOM; ++i) bottom[i] = lower_node(i, 0);
}

/* total prescribed values: the upper top moved by (slide, -press) */
static void prescribed_values(double *qp, double press, double slide) {
    size_t i;
    memset(qp, 0, NDOF * sizeof *qp);
    for (i = 0; i < NTOP; ++i) {
        qp[2 * top[i]] = slide;
        qp[2 * top[i] + 1] = -press;
    }
}

enum { HOLD_UPPER = 1, WITH_PAIR = 2, WITH_PLATE = 4 };

/* A valid model (NULL on an unexpected failure, reported). */
static HyconModel *make_model(int what) {
    HyconModel *m = NULL;
    HyconStatus s = hycon_model_new(&m, coords, NN, BLOCK(offsets, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1);
    if (s != HYCON_OK) goto fail;
    if ((s = hycon_model_prescribe(m, bottom, NBOTTOM, HYCON_XY)) != HYCON_OK) goto fail;
    if ((what & HOLD_UPPER) && (s = hycon_model_prescribe(m, top, NTOP, HYCON_XY)) != HYCON_OK)
        goto fail;
    if ((what & WITH_PLATE) && (s = hycon_model_set_plate(m, top, NTOP)) != HYCON_OK) goto fail;
    if ((what & WITH_PAIR) &&
        (s = hycon_model_add_pair(m, LINE(pair_a, NA), LINE(pair_b, NB), FRICTION, NULL)) != HYCON_OK)
        goto fail;
    return m;
fail : {
    char message[512];
    hycon_last_error_message(message, sizeof message);
    fprintf(stderr, "  building the model failed: %s: %s\n", hycon_status_name(s), message);
    hycon_model_free(m);
    return NULL;
}
}

/* An analysis of the standard model with `options` (NULL: defaults). */
static HyconContact *make_contact(const HyconContactOptions *options) {
    HyconContact *c = NULL;
    HyconModel *m = make_model(HOLD_UPPER | WITH_PAIR);
    if (m == NULL) return NULL;
    if (hycon_contact_new(&c, m, options) != HYCON_OK) {
        char message[512];
        hycon_last_error_message(message, sizeof message);
        fprintf(stderr, "  hycon_contact_new failed: %s\n", message);
        c = NULL;
    }
    hycon_model_free(m);
    return c;
}

/* One increment of the standard model. */
static HyconStatus press(HyconContact *c, double depth, double slide, HyconIncrementInfo *info) {
    double load[NDOF], qp[NDOF];
    memset(load, 0, sizeof load);
    prescribed_values(qp, depth, slide);
    return hycon_contact_increment(c, load, NDOF, qp, NDOF, info);
}

/* ---------------------------------------------------------------------------------------- */
/* The host: the same mesh assembled by the host itself, dense Cholesky in a solve callback */

typedef struct {
    size_t n;                  /* equations */
    int64_t eq[NDOF];          /* equation of each dof, or HYCON_FIXED */
    double k[NDOF * NDOF];     /* full K over all dofs, row-major */
    double l[NDOF * NDOF];     /* Cholesky factor of K_ff, row-major n x n */
    size_t calls;              /* solve calls so far */
    int fail;                  /* nonzero: the callback returns this */
    int poison;                /* nonzero: the callback returns NaN values */
} Host;

static bool host_assemble(Host *h) {
    size_t e, a, b, i, j, p;
    bool fixed[NDOF];
    memset(h, 0, sizeof *h);
    memset(fixed, 0, sizeof fixed);
    for (i = 0; i < NBOTTOM; ++i) fixed[2 * bottom[i]] = fixed[2 * bottom[i] + 1] = true;
    for (i = 0; i < NTOP; ++i) fixed[2 * top[i]] = fixed[2 * top[i] + 1] = true;
    for (i = 0; i < NDOF; ++i) h->eq[i] = fixed[i] ? HYCON_FIXED : (int64_t)h->n++;
    for (e = 0; e < NE; ++e) {
        double xy[8], ke[64];
        for (a = 0; a < 4; ++a) {
            xy[2 * a] = coords[2 * conn[4 * e + a]];
            xy[2 * a + 1] = coords[2 * conn[4 * e + a] + 1];
        }
        if (hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 4, xy, &steel, ke, 64) != HYCON_OK)
            return false;
        for (a = 0; a < 8; ++a)
            for (b = 0; b < 8; ++b) {
                size_t r = 2 * conn[4 * e + a / 2] + a % 2, s = 2 * conn[4 * e + b / 2] + b % 2;
                h->k[r * NDOF + s] += ke[a * 8 + b];
            }
    }
    /* K_ff and its Cholesky factor */
    for (i = 0; i < NDOF; ++i)
        for (j = 0; j < NDOF; ++j)
            if (h->eq[i] >= 0 && h->eq[j] >= 0)
                h->l[(size_t)h->eq[i] * h->n + (size_t)h->eq[j]] = h->k[i * NDOF + j];
    for (j = 0; j < h->n; ++j) {
        double d = h->l[j * h->n + j];
        for (p = 0; p < j; ++p) d -= h->l[j * h->n + p] * h->l[j * h->n + p];
        if (!(d > 0.0)) return false;
        h->l[j * h->n + j] = sqrt(d);
        for (i = j + 1; i < h->n; ++i) {
            double v = h->l[i * h->n + j];
            for (p = 0; p < j; ++p) v -= h->l[i * h->n + p] * h->l[j * h->n + p];
            h->l[i * h->n + j] = v / h->l[j * h->n + j];
        }
        for (i = 0; i < j; ++i) h->l[i * h->n + j] = 0.0;
    }
    return true;
}

/* The host's right-hand side for the top moved by (slide, -press): -K_fp q_p. */
static void host_rhs(const Host *h, double *rhs, double depth, double slide) {
    double qp[NDOF];
    size_t i, j;
    prescribed_values(qp, depth, slide);
    for (i = 0; i < NDOF; ++i) {
        if (h->eq[i] < 0) continue;
        rhs[h->eq[i]] = 0.0;
        for (j = 0; j < NDOF; ++j)
            if (h->eq[j] < 0) rhs[h->eq[i]] -= h->k[i * NDOF + j] * qp[j];
    }
}

static int32_t host_solve(void *user_data, size_t n, size_t nrhs, const double *rhs, double *x) {
    Host *h = (Host *)user_data;
    size_t c, i, p;
    h->calls++;
    if (h->fail) return h->fail;
    if (n != h->n) return 1;
    for (c = 0; c < nrhs; ++c) {
        const double *b = rhs + c * n;
        double *y = x + c * n;
        for (i = 0; i < n; ++i) { /* L y = b */
            double v = b[i];
            for (p = 0; p < i; ++p) v -= h->l[i * n + p] * y[p];
            y[i] = v / h->l[i * n + i];
        }
        for (i = n; i-- > 0;) { /* L^T x = y */
            double v = y[i];
            for (p = i + 1; p < n; ++p) v -= h->l[p * n + i] * y[p];
            y[i] = v / h->l[i * n + i];
        }
        if (h->poison) y[0] = NAN;
    }
    return 0;
}

static void host_pair_arrays(const Host *h, double *a_xy, int64_t *a_eq, double *b_xy,
                             int64_t *b_eq) {
    size_t i;
    for (i = 0; i < NA; ++i) {
        a_xy[2 * i] = coords[2 * pair_a[i]];
        a_xy[2 * i + 1] = coords[2 * pair_a[i] + 1];
        a_eq[2 * i] = h->eq[2 * pair_a[i]];
        a_eq[2 * i + 1] = h->eq[2 * pair_a[i] + 1];
    }
    for (i = 0; i < NB; ++i) {
        b_xy[2 * i] = coords[2 * pair_b[i]];
        b_xy[2 * i + 1] = coords[2 * pair_b[i] + 1];
        b_eq[2 * i] = h->eq[2 * pair_b[i]];
        b_eq[2 * i + 1] = h->eq[2 * pair_b[i] + 1];
    }
}

/* A host description of the host's system with its pair (no stiffness yet). */
/* A point inside the upper block (body A), beside its bottom: the surfaces touch, so the host
 * says which side body A is on (hycon_host_set_pair_inside). */
static const double upper_inside[2] = {1.0, 1.5};

static HyconHost *make_host(const Host *h) {
    HyconHost *d = NULL;
    double a_xy[2 * NA], b_xy[2 * NB];
    int64_t a_eq[2 * NA], b_eq[2 * NB];
    host_pair_arrays(h, a_xy, a_eq, b_xy, b_eq);
    if (hycon_host_new(&d, h->n) != HYCON_OK) return NULL;
    if (hycon_host_add_pair(d, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), FRICTION,
                            HYCON_PLANE_STRAIN, 1.0, NULL) != HYCON_OK ||
        hycon_host_set_pair_inside(d, 0, upper_inside) != HYCON_OK) {
        hycon_host_free(d);
        return NULL;
    }
    return d;
}

static Host host; /* large: static storage */

static HyconContact *make_host_contact(Host *h) {
    HyconContact *c = NULL;
    HyconHost *d = make_host(h);
    if (d == NULL) return NULL;
    if (hycon_host_set_solver(d, host_solve, h) != HYCON_OK ||
        hycon_contact_new_host(&c, d, NULL) != HYCON_OK)
        c = NULL;
    hycon_host_free(d);
    return c;
}

static HyconStatus host_press(HyconContact *c, const Host *h, double depth, double slide,
                              HyconIncrementInfo *info) {
    double rhs[NDOF];
    host_rhs(h, rhs, depth, slide);
    return hycon_contact_increment(c, rhs, h->n, NULL, 0, info);
}

/* The host's stiffness as CSR (lower triangle of K_ff). */
typedef struct {
    size_t row_ptr[NDOF + 1];
    size_t columns[NDOF * NDOF];
    double values[NDOF * NDOF];
} Csr;
static Csr csr;

static void host_csr(const Host *h, Csr *m) {
    size_t i, j, nnz = 0, n = h->n;
    double kff;
    m->row_ptr[0] = 0;
    for (i = 0; i < n; ++i) {
        for (j = 0; j <= i; ++j) {
            /* K_ff[i][j] = L L^T */
            size_t p;
            kff = 0.0;
            for (p = 0; p <= j; ++p) kff += h->l[i * n + p] * h->l[j * n + p];
            if (kff != 0.0) {
                m->columns[nnz] = j;
                m->values[nnz++] = kff;
            }
        }
        m->row_ptr[i + 1] = nnz;
    }
}

/* ---------------------------------------------------------------------------------------- */
/* The converged state of a handle, to show it is kept by a failed call */

typedef struct {
    HyconNodeResult a[NA];
    HyconBNodeResult b[NB];
    double u[NDOF];
    double du[NDOF];
    double f[NDOF];
    size_t records;
} State;

static bool snapshot(HyconContact *c, State *s) {
    size_t n = 0;
    memset(s, 0, sizeof *s);
    EXPECT(hycon_contact_displacement(c, NULL, 0, &n) == HYCON_OK && n <= NDOF);
    EXPECT(hycon_contact_node_results(c, 0, s->a, NA, NULL) == HYCON_OK);
    EXPECT(hycon_contact_b_node_results(c, 0, s->b, NB, NULL) == HYCON_OK);
    EXPECT(hycon_contact_displacement(c, s->u, n, NULL) == HYCON_OK);
    EXPECT(hycon_contact_displacement_increment(c, s->du, n, NULL) == HYCON_OK); /* a new solve */
    EXPECT(hycon_contact_forces(c, s->f, n, NULL) == HYCON_OK);
    EXPECT(hycon_contact_records(c, 0, NULL, 0, &s->records) == HYCON_OK);
    return true;
}

/* bit-for-bit the same state */
static bool same_state(const State *x, const State *y) {
    size_t i;
    EXPECT(x->records == y->records);
    EXPECT(memcmp(x->u, y->u, sizeof x->u) == 0);
    EXPECT(memcmp(x->du, y->du, sizeof x->du) == 0);
    EXPECT(memcmp(x->f, y->f, sizeof x->f) == 0);
    for (i = 0; i < NA; ++i) {
        EXPECT(x->a[i].node == y->a[i].node && x->a[i].state == y->a[i].state);
        EXPECT(x->a[i].slip_sign == y->a[i].slip_sign);
        EXPECT(x->a[i].tn == y->a[i].tn && x->a[i].ts == y->a[i].ts);
        EXPECT(x->a[i].gap == y->a[i].gap && x->a[i].weight == y->a[i].weight);
        EXPECT(x->a[i].position[0] == y->a[i].position[0]);
        EXPECT(x->a[i].position[1] == y->a[i].position[1]);
        EXPECT(x->a[i].force[0] == y->a[i].force[0] && x->a[i].force[1] == y->a[i].force[1]);
    }
    for (i = 0; i < NB; ++i) {
        EXPECT(x->b[i].node == y->b[i].node && x->b[i].weight == y->b[i].weight);
        EXPECT(x->b[i].force[0] == y->b[i].force[0] && x->b[i].force[1] == y->b[i].force[1]);
    }
    return true;
}

/* equal to a relative 1e-12 of the largest value (another handle, another order of solves) */
static bool close_state(const State *x, const State *y) {
    double scale_u = 0.0, scale_t = 0.0;
    size_t i;
    for (i = 0; i < NDOF; ++i) scale_u = fmax(scale_u, fabs(x->u[i]));
    for (i = 0; i < NA; ++i) scale_t = fmax(scale_t, fabs(x->a[i].tn));
    EXPECT(scale_u > 0.0 && scale_t > 0.0);
    for (i = 0; i < NDOF; ++i) EXPECT(fabs(x->u[i] - y->u[i]) <= 1e-12 * scale_u);
    for (i = 0; i < NA; ++i) {
        EXPECT(x->a[i].state == y->a[i].state);
        EXPECT(fabs(x->a[i].tn - y->a[i].tn) <= 1e-9 * scale_t);
        EXPECT(fabs(x->a[i].ts - y->a[i].ts) <= 1e-9 * scale_t);
    }
    return true;
}

/* in contact: every A node active and in compression */
static bool pressed(const State *s) {
    size_t i;
    for (i = 0; i < NA; ++i) {
        EXPECT(s->a[i].state == HYCON_NODE_STICK || s->a[i].state == HYCON_NODE_SLIP ||
               s->a[i].state == HYCON_NODE_FRICTIONLESS);
        EXPECT(s->a[i].tn < 0.0);
    }
    return true;
}

/* ---------------------------------------------------------------------------------------- */
/* Options */

static bool test_options_default(void) {
    HyconContactOptions o;
    EXPECT(STATUS_FN(hycon_contact_options_default, (NULL), HYCON_ERROR_NULL_POINTER, "out"));
    EXPECT(STATUS_FN(hycon_contact_options_default, (&o), HYCON_OK, NULL));
    EXPECT(o.tolerance == 1e-6 && o.max_iterations == 60 && o.lock_rounds == 3);
    EXPECT(o.search_distance == 4.0 && o.backend == HYCON_BACKEND_FAER);
    EXPECT(o.monitor == NULL && o.monitor_data == NULL && o.threads == 1);
    EXPECT(o.size == sizeof o && o.cutback_depth == 8 && o.cutback_min_fraction == 1.0 / 256);
    return true;
}

/* The options are versioned by their leading size (0.7.0): a size this library does not know
 * is rejected, and so are bad cutback limits; the analysis is not created. */
static bool test_options_size_and_cutback(void) {
    HyconContactOptions o;
    HyconContact *c = MARKER(HyconContact);
    HyconModel *m = make_model(HOLD_UPPER | WITH_PAIR);
    bool ok = true;
    EXPECT(m != NULL);
    hycon_contact_options_default(&o);
    o.size = 0;
    ok = ok && STATUS_FN(hycon_contact_new, (&c, m, &o), HYCON_ERROR_INVALID_ARGUMENT,
                         "options.size = 0");
    o.size = sizeof o - 8;
    ok = ok && STATUS_FN(hycon_contact_new, (&c, m, &o), HYCON_ERROR_INVALID_ARGUMENT,
                         "options.size");
    o.size = sizeof o + 8;
    ok = ok && STATUS_FN(hycon_contact_new, (&c, m, &o), HYCON_ERROR_INVALID_ARGUMENT,
                         "hycon_contact_options_default");
    hycon_contact_options_default(&o);
    o.cutback_depth = HYCON_MAX_CUTBACK_DEPTH + 1;
    ok = ok && STATUS_FN(hycon_contact_new, (&c, m, &o), HYCON_ERROR_INVALID_ARGUMENT,
                         "options.cutback_depth = 53");
    hycon_contact_options_default(&o);
    o.cutback_min_fraction = 0.0;
    ok = ok && STATUS_FN(hycon_contact_new, (&c, m, &o), HYCON_ERROR_INVALID_ARGUMENT,
                         "options.cutback_min_fraction = 0");
    o.cutback_min_fraction = 2.0;
    ok = ok && STATUS_FN(hycon_contact_new, (&c, m, &o), HYCON_ERROR_INVALID_ARGUMENT,
                         "options.cutback_min_fraction = 2");
    ok = ok && c == MARKER(HyconContact);
    /* cutback off is a valid setting */
    hycon_contact_options_default(&o);
    o.cutback_depth = 0;
    ok = ok && STATUS(hycon_contact_new(&c, m, &o), HYCON_OK, NULL);
    if (ok) hycon_contact_free(c);
    hycon_model_free(m);
    return ok;
}

/* ---------------------------------------------------------------------------------------- */
/* Model API: hycon_model_new */

/* NULL view structs: each is a required pointer named by its argument */
static bool test_null_views(void) {
    HyconModel *m = MARKER(HyconModel), *model = make_model(HOLD_UPPER);
    HyconHost *d = make_host(&host);
    double a_xy[2 * NA], b_xy[2 * NB];
    int64_t a_eq[2 * NA], b_eq[2 * NB];
    size_t index = 777;
    bool ok = true;
    EXPECT(model != NULL && d != NULL);
    host_pair_arrays(&host, a_xy, a_eq, b_xy, b_eq);
    ok = ok && STATUS_FN(hycon_model_new, (&m, coords, NN, NULL, &steel, 1),
                         HYCON_ERROR_NULL_POINTER, "elements is NULL");
    ok = ok && m == MARKER(HyconModel);
    ok = ok && STATUS_FN(hycon_model_add_pair, (model, NULL, LINE(pair_b, NB), 0.1, &index),
                         HYCON_ERROR_NULL_POINTER, "a is NULL");
    ok = ok && STATUS_FN(hycon_model_add_pair, (model, LINE(pair_a, NA), NULL, 0.1, &index),
                         HYCON_ERROR_NULL_POINTER, "b is NULL");
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, NULL, HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_NULL_POINTER, "a is NULL");
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(pair_a, a_xy, a_eq, NA), NULL, 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_NULL_POINTER, "b is NULL");
    /* a misaligned optional output is rejected like a required one, and nothing is added */
    ok = ok && STATUS_FN(hycon_model_add_pair,
                         (model, LINE(pair_a, NA), LINE(pair_b, NB), 0.1,
                          (size_t *)(void *)((char *)&index + 1)),
                         HYCON_ERROR_INVALID_ARGUMENT, "index is misaligned");
    ok = ok && index == 777;
    ok = ok && STATUS(hycon_model_add_pair(model, LINE(pair_a, NA), LINE(pair_b, NB), 0.1, &index),
                      HYCON_OK, NULL) &&
         index == 0; /* the failed call added no pair */
    hycon_model_free(model);
    hycon_host_free(d);
    return ok;
}

static bool test_model_new_null_pointers(void) {
    HyconModel *m = MARKER(HyconModel);
    EXPECT(STATUS_FN(hycon_model_new,
                     (NULL, coords, NN, BLOCK(offsets, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_NULL_POINTER, "out is NULL"));
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, NULL, NN, BLOCK(offsets, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_NULL_POINTER, "coords is NULL"));
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, coords, NN, BLOCK(NULL, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_NULL_POINTER, "elements.offsets is NULL"));
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, coords, NN, BLOCK(offsets, NULL, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_NULL_POINTER, "elements.nodes is NULL"));
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, coords, NN, BLOCK(offsets, conn, NE, NULL, HYCON_ELEMENT_HYBRID), NULL, 1),
                     HYCON_ERROR_NULL_POINTER, "materials is NULL"));
    EXPECT(m == MARKER(HyconModel));
    /* element_materials NULL means material 0 everywhere; a given array is read */
    {
        size_t mat[NE];
        memset(mat, 0, sizeof mat);
        EXPECT(STATUS_FN(hycon_model_new, (&m, coords, NN, BLOCK(offsets, conn, NE, mat, HYCON_ELEMENT_HYBRID), &steel, 1),
                         HYCON_OK, NULL));
        EXPECT(m != NULL && m != MARKER(HyconModel));
        hycon_model_free(m);
    }
    return true;
}

static bool test_model_new_zero_lengths(void) {
    HyconModel *m = MARKER(HyconModel);
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, coords, 0, BLOCK(offsets, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_INVALID_ARGUMENT, "needs nodes"));
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, coords, NN, BLOCK(offsets, conn, 0, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_INVALID_ARGUMENT, "elements and materials are needed"));
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, coords, NN, BLOCK(offsets, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 0),
                     HYCON_ERROR_INVALID_ARGUMENT, "elements and materials are needed"));
    /* (NULL, 0) arrays are empty, which is the same error */
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, NULL, 0, BLOCK(NULL, NULL, 0, NULL, HYCON_ELEMENT_HYBRID), NULL, 0),
                     HYCON_ERROR_INVALID_ARGUMENT, "needs nodes"));
    /* fewer nodes than the elements use: the ids beyond are unknown */
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, coords, NN - 1, BLOCK(offsets, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_INVALID_ARGUMENT, "unknown node 23"));
    EXPECT(m == MARKER(HyconModel));
    return true;
}

static bool test_model_new_inconsistent_offsets(void) {
    HyconModel *m = MARKER(HyconModel);
    size_t off[NE + 1];
    memcpy(off, offsets, sizeof off);
    off[0] = 1; /* must start at 0 */
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, coords, NN, BLOCK(off, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_INVALID_ARGUMENT, "elements.offsets must start at 0"));
    memcpy(off, offsets, sizeof off);
    off[3] = off[2] - 1; /* decreasing */
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, coords, NN, BLOCK(off, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_INVALID_ARGUMENT, "nondecreasing"));
    EXPECT(m == MARKER(HyconModel));
    return true;
}

/* An element whose offsets give it a node count no formulation takes, and a 5-node element
 * (a transition element with a mid-side node) that Q4 does not take. */
static bool test_model_new_element_node_count(void) {
    HyconModel *m = MARKER(HyconModel);
    const double xy5[10] = {0, 0, 1, 0, 2, 0, 2, 1, 0, 1};
    const size_t off5[2] = {0, 5}, nodes5[5] = {0, 1, 2, 3, 4};
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, xy5, 5, BLOCK(off5, nodes5, 1, NULL, HYCON_ELEMENT_Q4), &steel, 1),
                     HYCON_ERROR_BAD_ELEMENT, "element 0: 5 nodes"));
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, xy5, 5, BLOCK(off5, nodes5, 1, NULL, HYCON_ELEMENT_PIAN_SUMIHARA), &steel, 1),
                     HYCON_ERROR_BAD_ELEMENT, "element 0: 5 nodes"));
    EXPECT(m == MARKER(HyconModel));
    /* the hybrid element takes it */
    EXPECT(STATUS(hycon_model_new(&m, xy5, 5, BLOCK(off5, nodes5, 1, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                  HYCON_OK, NULL));
    hycon_model_free(m);
    return true;
}

/* Element 2 gets 3 nodes through the offsets (and element 3 five: still 4 * NE in all). A node
 * count no formulation takes is HYCON_ERROR_BAD_ELEMENT by the header's definition of that
 * status (and so in hycon_element_stiffness), naming the element. */
static bool test_model_new_three_node_element(void) {
    HyconModel *m = MARKER(HyconModel);
    size_t off[NE + 1];
    memcpy(off, offsets, sizeof off);
    off[3] = off[2] + 3;
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, coords, NN, BLOCK(off, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_BAD_ELEMENT, "element 2"));
    EXPECT(STATUS(hycon_model_new(&m, coords, NN, BLOCK(off, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                  HYCON_ERROR_BAD_ELEMENT, "3 nodes"));
    EXPECT(m == MARKER(HyconModel));
    return true;
}

/* The same node id twice in element 6: coincident nodes, a degenerate element
 * (HYCON_ERROR_BAD_ELEMENT by the header's definition), named by index. */
static bool test_model_new_repeated_node_in_element(void) {
    HyconModel *m = MARKER(HyconModel);
    size_t c[4 * NE];
    memcpy(c, conn, sizeof c);
    c[4 * 6 + 2] = c[4 * 6 + 1];
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, coords, NN, BLOCK(offsets, c, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_BAD_ELEMENT, "element 6"));
    EXPECT(m == MARKER(HyconModel));
    return true;
}

static bool test_model_new_non_finite_coordinates(void) {
    HyconModel *m = MARKER(HyconModel);
    double c[2 * NN];
    memcpy(c, coords, sizeof c);
    c[7] = NAN;
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, c, NN, BLOCK(offsets, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_INVALID_ARGUMENT, "coords[7]"));
    c[7] = coords[7];
    c[40] = -INFINITY;
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, c, NN, BLOCK(offsets, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_INVALID_ARGUMENT, "not finite"));
    EXPECT(m == MARKER(HyconModel));
    return true;
}

static bool test_model_new_unknown_node(void) {
    HyconModel *m = MARKER(HyconModel);
    size_t c[4 * NE];
    memcpy(c, conn, sizeof c);
    c[4 * 5 + 2] = 99;
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, coords, NN, BLOCK(offsets, c, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_INVALID_ARGUMENT, "unknown node 99"));
    EXPECT(STATUS(hycon_model_new(&m, coords, NN, BLOCK(offsets, c, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                  HYCON_ERROR_INVALID_ARGUMENT, "element 5"));
    EXPECT(m == MARKER(HyconModel));
    return true;
}

static bool test_model_new_inverted_element(void) {
    HyconModel *m = MARKER(HyconModel);
    size_t c[4 * NE];
    int kind;
    memcpy(c, conn, sizeof c);
    /* element 3 clockwise */
    c[4 * 3 + 1] = conn[4 * 3 + 3];
    c[4 * 3 + 3] = conn[4 * 3 + 1];
    for (kind = HYCON_ELEMENT_HYBRID; kind <= HYCON_ELEMENT_Q4; ++kind) {
        EXPECT(STATUS_FN(hycon_model_new,
                         (&m, coords, NN, BLOCK(offsets, c, NE, NULL, kind), &steel, 1),
                         HYCON_ERROR_BAD_ELEMENT, "element 3"));
        EXPECT(STATUS(hycon_model_new(&m, coords, NN, BLOCK(offsets, c, NE, NULL, kind), &steel, 1),
                      HYCON_ERROR_BAD_ELEMENT, "inverted"));
    }
    EXPECT(m == MARKER(HyconModel));
    return true;
}

static bool test_model_new_degenerate_element(void) {
    HyconModel *m = MARKER(HyconModel);
    double xy[2 * NN];
    /* the upper block's top right corner (only in element 11) on the node below it */
    const size_t corner = upper_node(NXU, NYU), below = upper_node(NXU, NYU - 1);
    memcpy(xy, coords, sizeof xy);
    xy[2 * corner] = coords[2 * below];
    xy[2 * corner + 1] = coords[2 * below + 1];
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, xy, NN, BLOCK(offsets, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_BAD_ELEMENT, "element 11"));
    EXPECT(STATUS(hycon_model_new(&m, xy, NN, BLOCK(offsets, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                  HYCON_ERROR_BAD_ELEMENT, "degenerate"));
    /* a non-convex element 0: its top right corner pulled inside */
    memcpy(xy, coords, sizeof xy);
    xy[2 * lower_node(1, 1)] = 0.2;
    xy[2 * lower_node(1, 1) + 1] = 0.1;
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, xy, NN, BLOCK(offsets, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_BAD_ELEMENT, "element 0"));
    EXPECT(m == MARKER(HyconModel));
    return true;
}

static bool test_model_new_unknown_kind_and_bad_material(void) {
    HyconModel *m = MARKER(HyconModel);
    HyconMaterial bad = steel;
    size_t mat[NE];
    EXPECT(STATUS_FN(hycon_model_new, (&m, coords, NN, BLOCK(offsets, conn, NE, NULL, 0), &steel, 1),
                     HYCON_ERROR_INVALID_ARGUMENT, "unknown element kind 0"));
    EXPECT(STATUS_FN(hycon_model_new, (&m, coords, NN, BLOCK(offsets, conn, NE, NULL, 4), &steel, 1),
                     HYCON_ERROR_INVALID_ARGUMENT, "unknown element kind 4"));
    bad.youngs = 0.0;
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, coords, NN, BLOCK(offsets, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &bad, 1),
                     HYCON_ERROR_INVALID_MATERIAL, "material"));
    bad = steel;
    bad.analysis = 0;
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, coords, NN, BLOCK(offsets, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &bad, 1),
                     HYCON_ERROR_INVALID_MATERIAL, "unknown analysis 0"));
    memset(mat, 0, sizeof mat);
    mat[9] = 1; /* only material 0 exists */
    EXPECT(STATUS_FN(hycon_model_new,
                     (&m, coords, NN, BLOCK(offsets, conn, NE, mat, HYCON_ELEMENT_HYBRID), &steel, 1),
                     HYCON_ERROR_INVALID_ARGUMENT, "element 9 uses material 1"));
    EXPECT(m == MARKER(HyconModel));
    return true;
}

/* free(NULL) is a no-op for every handle type (a double free of a live pointer is undefined
 * behaviour, as for free(), and is documented so; it is not tested) */
static bool test_free_null(void) {
    EXPECT(hycon_element_check(HYCON_ELEMENT_HYBRID, 0, NULL) != HYCON_OK);
    hycon_model_free(NULL);
    hycon_host_free(NULL);
    hycon_contact_free(NULL);
    /* the frees touch neither the last error nor anything else */
    EXPECT(hycon_last_error_message(NULL, 0) > 1);
    {
        HyconModel *m = make_model(HOLD_UPPER | WITH_PAIR);
        EXPECT(m != NULL);
        hycon_model_free(m);
    }
    return true;
}

/* ---------------------------------------------------------------------------------------- */
/* Model API: prescribe, pairs, plate */

static bool test_prescribe_bad_input(void) {
    HyconModel *m = make_model(0);
    const size_t unknown[2] = {3, NN};
    bool ok = true;
    EXPECT(m != NULL);
    ok = ok && STATUS_FN(hycon_model_prescribe, (NULL, top, NTOP, HYCON_XY),
                         HYCON_ERROR_NULL_POINTER, "model is NULL");
    ok = ok && STATUS_FN(hycon_model_prescribe, (m, NULL, NTOP, HYCON_XY),
                         HYCON_ERROR_NULL_POINTER, "nodes is NULL");
    ok = ok && STATUS_FN(hycon_model_prescribe, (m, unknown, 2, HYCON_X),
                         HYCON_ERROR_INVALID_ARGUMENT, "unknown node 24");
    ok = ok && STATUS_FN(hycon_model_prescribe, (m, top, NTOP, 0), HYCON_ERROR_INVALID_ARGUMENT,
                         "directions = 0");
    ok = ok && STATUS_FN(hycon_model_prescribe, (m, top, NTOP, 4), HYCON_ERROR_INVALID_ARGUMENT,
                         "directions = 4");
    ok = ok && STATUS_FN(hycon_model_prescribe, (m, top, NTOP, -1),
                         HYCON_ERROR_INVALID_ARGUMENT, "directions = -1");
    /* (NULL, 0) is an empty list */
    ok = ok && STATUS_FN(hycon_model_prescribe, (m, NULL, 0, HYCON_Y), HYCON_OK, NULL);
    hycon_model_free(m);
    return ok;
}

/* A displacement component prescribed twice is rejected by the call that does it (listed
 * twice, X then XY, prescribe then plate), and a rejected call prescribes nothing. */
static bool test_prescribe_twice(void) {
    HyconModel *m = make_model(0);
    const size_t twice[2] = {7, 7}; /* a free node inside the lower block */
    bool ok = true;
    EXPECT(m != NULL);
    ok = ok && STATUS_FN(hycon_model_prescribe, (m, twice, 2, HYCON_Y),
                         HYCON_ERROR_INVALID_ARGUMENT, "node 7 direction y is prescribed twice");
    /* nothing of the rejected call was kept: node 7 can be prescribed now */
    ok = ok && STATUS_FN(hycon_model_prescribe, (m, twice, 1, HYCON_X), HYCON_OK, NULL);
    ok = ok && STATUS_FN(hycon_model_prescribe, (m, twice, 1, HYCON_XY),
                         HYCON_ERROR_INVALID_ARGUMENT, "node 7 direction x is prescribed twice");
    ok = ok && STATUS_FN(hycon_model_prescribe, (m, twice, 1, HYCON_Y), HYCON_OK, NULL);
    ok = ok && STATUS_FN(hycon_model_prescribe, (m, bottom, 1, HYCON_X),
                         HYCON_ERROR_INVALID_ARGUMENT, "prescribed twice");
    ok = ok && STATUS_FN(hycon_model_prescribe, (m, top, NTOP, HYCON_XY), HYCON_OK, NULL);
    ok = ok && STATUS_FN(hycon_model_set_plate, (m, top, NTOP), HYCON_ERROR_INVALID_ARGUMENT,
                         "prescribed twice");
    hycon_model_free(m);
    return ok;
}

static bool test_add_pair_null_pointers(void) {
    HyconModel *m = make_model(HOLD_UPPER);
    size_t index = 777;
    bool ok = true;
    EXPECT(m != NULL);
    ok = ok && STATUS_FN(hycon_model_add_pair, (NULL, LINE(pair_a, NA), LINE(pair_b, NB), 0.1, &index),
                         HYCON_ERROR_NULL_POINTER, "model is NULL");
    ok = ok && STATUS_FN(hycon_model_add_pair, (m, LINE(NULL, NA), LINE(pair_b, NB), 0.1, &index),
                         HYCON_ERROR_NULL_POINTER, "a.nodes is NULL");
    ok = ok && STATUS_FN(hycon_model_add_pair, (m, LINE(pair_a, NA), LINE(NULL, NB), 0.1, &index),
                         HYCON_ERROR_NULL_POINTER, "b.nodes is NULL");
    ok = ok && index == 777;
    /* index NULL is allowed; the next pair gets index 1 */
    ok = ok && STATUS(hycon_model_add_pair(m, LINE(pair_a, NA), LINE(pair_b, NB), 0.1, NULL), HYCON_OK, NULL);
    ok = ok && STATUS(hycon_model_add_pair(m, LINE(pair_a, NA), LINE(pair_b, NB), 0.1, &index), HYCON_OK,
                      NULL) &&
         index == 1;
    hycon_model_free(m);
    return ok;
}

static bool test_add_pair_lengths(void) {
    HyconModel *m = make_model(HOLD_UPPER);
    size_t index = 777;
    bool ok = true;
    EXPECT(m != NULL);
    ok = ok && STATUS_FN(hycon_model_add_pair, (m, LINE(NULL, 0), LINE(pair_b, NB), 0.1, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "A polyline has 0 node(s)");
    ok = ok && STATUS_FN(hycon_model_add_pair, (m, LINE(pair_a, NA), LINE(pair_b, 1), 0.1, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "B polyline has 1 node(s)");
    ok = ok && index == 777;
    /* no pair was added by the failed calls */
    ok = ok && STATUS(hycon_model_add_pair(m, LINE(pair_a, NA), LINE(pair_b, NB), 0.1, &index), HYCON_OK,
                      NULL) &&
         index == 0;
    hycon_model_free(m);
    return ok;
}

static bool test_add_pair_not_a_chain(void) {
    HyconModel *m = make_model(HOLD_UPPER);
    const size_t repeated[4] = {pair_a[0], pair_a[1], pair_a[2], pair_a[1]};
    const size_t skipping[2] = {pair_a[0], pair_a[2]};
    const size_t reversed[NA] = {pair_a[2], pair_a[1], pair_a[0]};
    /* both polylines valid chains of the lower body, sharing nodes */
    const size_t lower_a[3] = {pair_b[0], pair_b[1], pair_b[2]};
    size_t index = 777;
    char part[64];
    bool ok = true;
    EXPECT(m != NULL);
    sprintf(part, "node %u appears twice", (unsigned)pair_a[1]);
    ok = ok && STATUS_FN(hycon_model_add_pair, (m, LINE(repeated, 4), LINE(pair_b, NB), 0.1, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, part);
    ok = ok && STATUS(hycon_model_add_pair(m, LINE(repeated, 4), LINE(pair_b, NB), 0.1, &index),
                      HYCON_ERROR_INVALID_ARGUMENT, "A polyline is not a chain");
    sprintf(part, "%u -> %u is not an edge", (unsigned)pair_a[0], (unsigned)pair_a[2]);
    ok = ok && STATUS_FN(hycon_model_add_pair, (m, LINE(skipping, 2), LINE(pair_b, NB), 0.1, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, part);
    /* the right edges in the wrong order: the body would be on the right */
    sprintf(part, "%u -> %u is not an edge", (unsigned)pair_a[2], (unsigned)pair_a[1]);
    ok = ok && STATUS_FN(hycon_model_add_pair, (m, LINE(reversed, NA), LINE(pair_b, NB), 0.1, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, part);
    ok = ok && STATUS(hycon_model_add_pair(m, LINE(pair_a, NA), LINE(reversed, NA), 0.1, &index),
                      HYCON_ERROR_INVALID_ARGUMENT, "B polyline is not a chain");
    sprintf(part, "node %u is in both polylines", (unsigned)pair_b[0]);
    ok = ok && STATUS_FN(hycon_model_add_pair, (m, LINE(lower_a, 3), LINE(pair_b, NB), 0.1, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, part);
    ok = ok && index == 777;
    hycon_model_free(m);
    return ok;
}

static bool test_add_pair_unknown_node(void) {
    HyconModel *m = make_model(HOLD_UPPER);
    const size_t a[NA] = {pair_a[0], pair_a[1], 99};
    size_t index = 777;
    bool ok = true;
    EXPECT(m != NULL);
    ok = ok && STATUS_FN(hycon_model_add_pair, (m, LINE(a, NA), LINE(pair_b, NB), 0.1, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "unknown node 99");
    ok = ok && STATUS_FN(hycon_model_add_pair, (m, LINE(pair_a, NA), LINE(a, NA), 0.1, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "unknown node 99");
    ok = ok && index == 777;
    hycon_model_free(m);
    return ok;
}

static bool test_add_pair_bad_friction(void) {
    HyconModel *m = make_model(HOLD_UPPER);
    const double bad[4] = {NAN, -0.1, INFINITY, -INFINITY};
    size_t i, index = 777;
    bool ok = true;
    EXPECT(m != NULL);
    for (i = 0; i < 4; ++i)
        ok = ok && STATUS_FN(hycon_model_add_pair, (m, LINE(pair_a, NA), LINE(pair_b, NB), bad[i], &index),
                             HYCON_ERROR_INVALID_ARGUMENT, "friction");
    ok = ok && index == 777;
    ok = ok && STATUS(hycon_model_add_pair(m, LINE(pair_a, NA), LINE(pair_b, NB), 0.0, &index), HYCON_OK,
                      NULL);
    hycon_model_free(m);
    return ok;
}

static bool test_set_plate_bad_input(void) {
    HyconModel *m = make_model(WITH_PAIR);
    const size_t unknown[2] = {top[0], 1000};
    bool ok = true;
    EXPECT(m != NULL);
    ok = ok && STATUS_FN(hycon_model_set_plate, (NULL, top, NTOP), HYCON_ERROR_NULL_POINTER,
                         "model is NULL");
    ok = ok && STATUS_FN(hycon_model_set_plate, (m, NULL, NTOP), HYCON_ERROR_NULL_POINTER,
                         "nodes is NULL");
    ok = ok && STATUS_FN(hycon_model_set_plate, (m, NULL, 0), HYCON_ERROR_INVALID_ARGUMENT,
                         "at least one node");
    ok = ok && STATUS_FN(hycon_model_set_plate, (m, unknown, 2), HYCON_ERROR_INVALID_ARGUMENT,
                         "unknown node 1000");
    hycon_model_free(m);
    return ok;
}

/* ---------------------------------------------------------------------------------------- */
/* Model API: hycon_contact_new */

static bool test_contact_new_null_pointers(void) {
    HyconModel *m = make_model(HOLD_UPPER | WITH_PAIR);
    HyconContact *c = MARKER(HyconContact);
    bool ok = true;
    EXPECT(m != NULL);
    ok = ok && STATUS_FN(hycon_contact_new, (NULL, m, NULL), HYCON_ERROR_NULL_POINTER,
                         "out is NULL");
    ok = ok && STATUS_FN(hycon_contact_new, (&c, NULL, NULL), HYCON_ERROR_NULL_POINTER,
                         "model is NULL");
    ok = ok && c == MARKER(HyconContact);
    hycon_model_free(m);
    return ok;
}

static bool test_contact_new_bad_options(void) {
    HyconModel *m = make_model(HOLD_UPPER | WITH_PAIR);
    HyconContact *c = MARKER(HyconContact);
    HyconContactOptions d, o;
    bool ok = true;
    EXPECT(m != NULL);
    EXPECT(hycon_contact_options_default(&d) == HYCON_OK);
#define BAD_OPTION(field, value, part)                                                         \
    o = d;                                                                                     \
    o.field = value;                                                                           \
    ok = ok && STATUS_FN(hycon_contact_new, (&c, m, &o), HYCON_ERROR_INVALID_ARGUMENT, part)
    BAD_OPTION(tolerance, NAN, "options.tolerance");
    BAD_OPTION(tolerance, 0.0, "options.tolerance = 0 must be > 0");
    BAD_OPTION(tolerance, INFINITY, "options.tolerance");
    BAD_OPTION(gap_tolerance, -1e-9, "options.gap_tolerance");
    BAD_OPTION(tension_tolerance, NAN, "options.tension_tolerance");
    BAD_OPTION(friction_tolerance, INFINITY, "options.friction_tolerance");
    BAD_OPTION(slip_tolerance, -INFINITY, "options.slip_tolerance");
    BAD_OPTION(search_distance, INFINITY, "options.search_distance");
    BAD_OPTION(search_distance, -4.0, "options.search_distance");
    BAD_OPTION(max_iterations, 0, "options.max_iterations");
    BAD_OPTION(threads, 0, "options.threads = 0 must be from 1 to 256");
    BAD_OPTION(threads, HYCON_MAX_THREADS + 1, "options.threads = 257 must be from 1 to 256");
#undef BAD_OPTION
    ok = ok && c == MARKER(HyconContact);
    hycon_model_free(m);
    return ok;
}

/* An enum option (backend or kinematics, both int32_t) set to 0 (a zero-initialised struct) or
 * to an unknown value is rejected by name; `field` points into `o`. */
static bool rejects_enum_option(HyconContactOptions *o, int32_t *field, const char *name) {
    HyconModel *m = make_model(HOLD_UPPER | WITH_PAIR);
    HyconContact *c = MARKER(HyconContact);
    const int32_t bad[3] = {0, 3, -1};
    size_t i;
    bool ok = true;
    char part[64];
    EXPECT(m != NULL);
    for (i = 0; i < 3; ++i) {
        *field = bad[i];
        sprintf(part, "options.%s = %d", name, (int)bad[i]);
        ok = ok && STATUS_FN(hycon_contact_new, (&c, m, o), HYCON_ERROR_INVALID_ARGUMENT, part);
    }
    ok = ok && c == MARKER(HyconContact);
    hycon_model_free(m);
    return ok;
}

static bool test_contact_new_unknown_kinematics(void) {
    HyconContactOptions o;
    EXPECT(hycon_contact_options_default(&o) == HYCON_OK);
    EXPECT(o.kinematics == HYCON_KINEMATICS_SMALL);
    return rejects_enum_option(&o, &o.kinematics, "kinematics");
}

static bool test_contact_new_unknown_backend(void) {
    HyconContactOptions o;
    EXPECT(hycon_contact_options_default(&o) == HYCON_OK);
    EXPECT(o.backend == HYCON_BACKEND_FAER);
    return rejects_enum_option(&o, &o.backend, "backend");
}

#ifdef HYCON_WITHOUT_CHOLMOD
/* A library built without the `suitesparse` feature (CMake: HYCON_CARGO_FEATURES without it)
 * refuses the CHOLMOD backend when the analysis is made, with an error that names the feature,
 * and writes no handle. */
static bool test_contact_new_cholmod_without_feature(void) {
    HyconContactOptions o;
    HyconModel *m = make_model(HOLD_UPPER | WITH_PAIR);
    HyconContact *c = MARKER(HyconContact);
    bool ok;
    EXPECT(m != NULL);
    EXPECT(hycon_contact_options_default(&o) == HYCON_OK);
    o.backend = HYCON_BACKEND_CHOLMOD;
    ok = STATUS_FN(hycon_contact_new, (&c, m, &o), HYCON_ERROR_SOLVER,
                   "built without the `suitesparse` feature") &&
         c == MARKER(HyconContact);
    hycon_model_free(m);
    return ok;
}
#endif

/* A model without contact pairs is allowed (its increments are linear solves); every pair
 * query then names the missing pair. */
static bool test_contact_new_no_pair(void) {
    HyconModel *m = make_model(HOLD_UPPER);
    HyconContact *c = NULL;
    HyconNodeResult a[NA];
    double u[NDOF];
    size_t n_a = 777;
    bool ok = true;
    EXPECT(m != NULL);
    ok = ok && STATUS(hycon_contact_new(&c, m, NULL), HYCON_OK, NULL);
    hycon_model_free(m);
    EXPECT(ok && c != NULL);
    fill_bytes(a, sizeof a);
    ok = ok && STATUS_FN(hycon_contact_node_results, (c, 0, NULL, 0, &n_a),
                         HYCON_ERROR_INVALID_ARGUMENT, "contact pair 0 does not exist (0 pairs)");
    ok = ok && STATUS_FN(hycon_contact_node_results, (c, 0, a, NA, NULL),
                         HYCON_ERROR_INVALID_ARGUMENT, "contact pair 0 does not exist");
    ok = ok && n_a == 777 && bytes_untouched(a, sizeof a);
    ok = ok && STATUS(press(c, PRESS, 0.0, NULL), HYCON_OK, NULL);
    ok = ok && STATUS(hycon_contact_displacement(c, u, NDOF, NULL), HYCON_OK, NULL);
    ok = ok && fabs(u[2 * top[0] + 1] + PRESS) == 0.0; /* the prescribed value */
    hycon_contact_free(c);
    return ok;
}

static bool test_contact_new_unconstrained_body(void) {
    HyconModel *m = make_model(WITH_PAIR); /* the upper block is held by nothing */
    HyconContact *c = MARKER(HyconContact);
    bool ok = true;
    EXPECT(m != NULL);
    ok = ok && STATUS_FN(hycon_contact_new, (&c, m, NULL), HYCON_ERROR_SINGULAR,
                         "is not held against rigid motion");
    ok = ok && STATUS(hycon_contact_new(&c, m, NULL), HYCON_ERROR_SINGULAR, "node 15");
    ok = ok && c == MARKER(HyconContact);
    /* held in y only: one of its three rigid modes is still free */
    ok = ok && hycon_model_prescribe(m, top, NTOP, HYCON_Y) == HYCON_OK;
    ok = ok && STATUS_FN(hycon_contact_new, (&c, m, NULL), HYCON_ERROR_SINGULAR, "2 of its 3");
    ok = ok && c == MARKER(HyconContact);
    hycon_model_free(m);
    return ok;
}

static bool test_lock_rounds_zero_accepted(void) {
    HyconContactOptions o;
    HyconContact *c;
    HyconIncrementInfo info;
    State s;
    EXPECT(hycon_contact_options_default(&o) == HYCON_OK);
    o.lock_rounds = 0;
    c = make_contact(&o);
    EXPECT(c != NULL);
    EXPECT(STATUS(press(c, PRESS, 0.0, &info), HYCON_OK, NULL));
    EXPECT(info.increment == 1 && info.active == NA);
    EXPECT(snapshot(c, &s) && pressed(&s));
    hycon_contact_free(c);
    return true;
}

/* More threads give the same converged state to the bit. */
static bool test_threads_same_state(void) {
    HyconContactOptions o;
    HyconContact *c;
    HyconIncrementInfo info;
    static State one, many;
    EXPECT(hycon_contact_options_default(&o) == HYCON_OK);
    for (o.threads = 1; o.threads <= HYCON_MAX_THREADS; o.threads += HYCON_MAX_THREADS - 1) {
        c = make_contact(&o);
        EXPECT(c != NULL);
        EXPECT(STATUS(press(c, PRESS, 0.0, &info), HYCON_OK, NULL));
        EXPECT(snapshot(c, o.threads == 1 ? &one : &many) && pressed(&one));
        hycon_contact_free(c);
    }
    EXPECT(same_state(&one, &many));
    return true;
}

/* ---------------------------------------------------------------------------------------- */
/* Increments */

static bool test_increment_null_pointers(void) {
    HyconContact *c = make_contact(NULL);
    double load[NDOF], qp[NDOF];
    HyconIncrementInfo info;
    bool ok = true;
    EXPECT(c != NULL);
    memset(load, 0, sizeof load);
    prescribed_values(qp, PRESS, 0.0);
    fill_bytes(&info, sizeof info);
    ok = ok && STATUS_FN(hycon_contact_increment, (NULL, load, NDOF, qp, NDOF, &info),
                         HYCON_ERROR_NULL_POINTER, "contact is NULL");
    ok = ok && STATUS_FN(hycon_contact_increment, (c, NULL, NDOF, qp, NDOF, &info),
                         HYCON_ERROR_NULL_POINTER, "load is NULL");
    ok = ok && STATUS_FN(hycon_contact_increment, (c, load, NDOF, NULL, NDOF, &info),
                         HYCON_ERROR_NULL_POINTER, "prescribed is NULL");
    ok = ok && bytes_untouched(&info, sizeof info);
    /* info NULL is allowed */
    ok = ok && STATUS(hycon_contact_increment(c, load, NDOF, qp, NDOF, NULL), HYCON_OK, NULL);
    hycon_contact_free(c);
    return ok;
}

static bool test_increment_wrong_lengths(void) {
    HyconContact *c = make_contact(NULL);
    double load[NDOF + 1], qp[NDOF + 1];
    HyconIncrementInfo info;
    size_t records = 99;
    bool ok = true;
    EXPECT(c != NULL);
    memset(load, 0, sizeof load);
    prescribed_values(qp, PRESS, 0.0);
    qp[NDOF] = 0.0;
    fill_bytes(&info, sizeof info);
    ok = ok && STATUS_FN(hycon_contact_increment, (c, load, NDOF - 1, qp, NDOF, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "the load vector needs 48 entries");
    ok = ok && STATUS_FN(hycon_contact_increment, (c, load, NDOF + 1, qp, NDOF, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "got 49 and 48");
    ok = ok && STATUS_FN(hycon_contact_increment, (c, NULL, 0, qp, NDOF, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "got 0 and 48");
    ok = ok && STATUS_FN(hycon_contact_increment, (c, load, NDOF, qp, 10, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "the prescribed vector 48");
    ok = ok && STATUS_FN(hycon_contact_increment, (c, load, NDOF, NULL, 0, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "got 48 and 0");
    ok = ok && bytes_untouched(&info, sizeof info);
    ok = ok && hycon_contact_records(c, 0, NULL, 0, &records) == HYCON_OK && records == 0;
    hycon_contact_free(c);
    return ok;
}

static bool test_increment_non_finite(void) {
    HyconContact *c = make_contact(NULL);
    double load[NDOF], qp[NDOF];
    HyconIncrementInfo info;
    State before, after;
    bool ok = true;
    EXPECT(c != NULL);
    EXPECT(press(c, PRESS, 0.0, NULL) == HYCON_OK);
    EXPECT(snapshot(c, &before));
    memset(load, 0, sizeof load);
    prescribed_values(qp, 2 * PRESS, 0.0);
    fill_bytes(&info, sizeof info);
    load[5] = NAN;
    ok = ok && STATUS_FN(hycon_contact_increment, (c, load, NDOF, qp, NDOF, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "load[5]");
    load[5] = INFINITY;
    ok = ok && STATUS(hycon_contact_increment(c, load, NDOF, qp, NDOF, &info),
                      HYCON_ERROR_INVALID_ARGUMENT, "not finite");
    load[5] = 0.0;
    qp[2 * top[1] + 1] = -INFINITY;
    {
        char part[32];
        sprintf(part, "prescribed[%u]", (unsigned)(2 * top[1] + 1));
        ok = ok && STATUS_FN(hycon_contact_increment, (c, load, NDOF, qp, NDOF, &info),
                             HYCON_ERROR_INVALID_ARGUMENT, part);
    }
    ok = ok && bytes_untouched(&info, sizeof info);
    ok = ok && snapshot(c, &after) && same_state(&before, &after);
    hycon_contact_free(c);
    return ok;
}

/* ---------------------------------------------------------------------------------------- */
/* Results */

/* A pointer one byte past an aligned one: misaligned for every type wider than a byte. */
static void *misaligned(void *p) { return (char *)p + 1; }

static bool test_result_functions_null_pointers(void) {
    HyconContact *c = make_contact(NULL);
    double buf[NDOF];
    HyconNodeResult a[NA];
    HyconBNodeResult b[NB];
    HyconContactNode en[NA];
    HyconIterationRecord r[4];
    HyconCouplingEntry ce[64];
    HyconConstraintEntry ke[64];
    HyconTimings t;
    size_t n = 777, words[2];
    bool ok = true;
    EXPECT(c != NULL);
    EXPECT(press(c, PRESS, 0.0, NULL) == HYCON_OK);
    fill(buf, NDOF);
    fill_bytes(a, sizeof a);
    fill_bytes(b, sizeof b);
    fill_bytes(en, sizeof en);
    fill_bytes(r, sizeof r);
    fill_bytes(ce, sizeof ce);
    fill_bytes(ke, sizeof ke);
    fill_bytes(&t, sizeof t);
#define NULL_CONTACT(fn, args)                                                                 \
    ok = ok && STATUS_FN(fn, args, HYCON_ERROR_NULL_POINTER, "contact is NULL")
    NULL_CONTACT(hycon_contact_displacement, (NULL, buf, NDOF, &n));
    NULL_CONTACT(hycon_contact_displacement, (NULL, NULL, 0, &n)); /* also the size query */
    NULL_CONTACT(hycon_contact_displacement_increment, (NULL, buf, NDOF, &n));
    NULL_CONTACT(hycon_contact_forces, (NULL, buf, NDOF, &n));
    NULL_CONTACT(hycon_contact_node_results, (NULL, 0, a, NA, &n));
    NULL_CONTACT(hycon_contact_b_node_results, (NULL, 0, b, NB, &n));
    NULL_CONTACT(hycon_contact_stress_tractions, (NULL, 0, buf, NDOF, &n));
    NULL_CONTACT(hycon_contact_records, (NULL, 0, NULL, 0, &n));
    NULL_CONTACT(hycon_contact_records, (NULL, 0, r, 1, &n));
    NULL_CONTACT(hycon_contact_timings, (NULL, &t, &n));
    NULL_CONTACT(hycon_contact_surface_nodes, (NULL, 0, en, NA, &n));
    NULL_CONTACT(hycon_contact_surface_coupling, (NULL, 0, ce, 64, &n));
    NULL_CONTACT(hycon_contact_constraint_rows, (NULL, 0, ke, 64, &n));
    NULL_CONTACT(hycon_contact_plate, (NULL, buf, buf + 2));
    NULL_CONTACT(hycon_contact_increment_with_plate, (NULL, NULL, 0, NULL, 0, NULL, NULL, NULL));
#undef NULL_CONTACT
    /* array outputs NULL with a nonzero length (NULL and 0 is the size query) */
#define NULL_OUT(fn, args)                                                                     \
    ok = ok && STATUS_FN(fn, args, HYCON_ERROR_NULL_POINTER, "out is NULL but len is")
    NULL_OUT(hycon_contact_displacement, (c, NULL, NDOF, &n));
    NULL_OUT(hycon_contact_displacement_increment, (c, NULL, NDOF, &n));
    NULL_OUT(hycon_contact_forces, (c, NULL, NDOF, &n));
    NULL_OUT(hycon_contact_node_results, (c, 0, NULL, NA, &n));
    NULL_OUT(hycon_contact_b_node_results, (c, 0, NULL, NB, &n));
    NULL_OUT(hycon_contact_stress_tractions, (c, 0, NULL, 2 * NA, &n));
    NULL_OUT(hycon_contact_records, (c, 0, NULL, 1, &n));
    NULL_OUT(hycon_contact_surface_nodes, (c, 0, NULL, NA, &n));
    NULL_OUT(hycon_contact_surface_coupling, (c, 0, NULL, 64, &n));
    NULL_OUT(hycon_contact_constraint_rows, (c, 0, NULL, 64, &n));
#undef NULL_OUT
    /* one rule for misaligned pointers: rejected by name, optional ones (needed, timings,
     * factorizations) as well as required ones, with nothing written */
#define MISALIGNED(fn, args, name)                                                            \
    ok = ok && STATUS_FN(fn, args, HYCON_ERROR_INVALID_ARGUMENT, name " is misaligned")
    MISALIGNED(hycon_contact_displacement, (c, buf, NDOF, (size_t *)misaligned(words)), "needed");
    MISALIGNED(hycon_contact_displacement, (c, NULL, 0, (size_t *)misaligned(words)), "needed");
    MISALIGNED(hycon_contact_displacement, (c, (double *)misaligned(buf), NDOF - 1, &n), "out");
    MISALIGNED(hycon_contact_node_results, (c, 0, a, NA, (size_t *)misaligned(words)), "needed");
    MISALIGNED(hycon_contact_records, (c, 0, r, 4, (size_t *)misaligned(words)), "needed");
    MISALIGNED(hycon_contact_surface_coupling,
               (c, 0, (HyconCouplingEntry *)misaligned(ce), 63, &n), "out");
    MISALIGNED(hycon_contact_constraint_rows, (c, 0, ke, 64, (size_t *)misaligned(words)),
               "needed");
    MISALIGNED(hycon_contact_timings, (c, (HyconTimings *)misaligned(&t), NULL), "timings");
    MISALIGNED(hycon_contact_timings, (c, &t, (size_t *)misaligned(words)), "factorizations");
    MISALIGNED(hycon_contact_timings, (c, NULL, (size_t *)misaligned(words)), "factorizations");
#undef MISALIGNED
    ok = ok && n == 777;
    ok = ok && untouched(buf, NDOF) && bytes_untouched(a, sizeof a) &&
         bytes_untouched(b, sizeof b) && bytes_untouched(en, sizeof en) &&
         bytes_untouched(r, sizeof r) && bytes_untouched(ce, sizeof ce) &&
         bytes_untouched(ke, sizeof ke) && bytes_untouched(&t, sizeof t);
    /* optional outputs may be NULL: needed, timings, factorizations */
    ok = ok && STATUS(hycon_contact_node_results(c, 0, a, NA, NULL), HYCON_OK, NULL);
    ok = ok && STATUS(hycon_contact_surface_coupling(c, 0, ce, 64, NULL), HYCON_OK, NULL);
    ok = ok && STATUS(hycon_contact_timings(c, NULL, NULL), HYCON_OK, NULL);
    hycon_contact_free(c);
    return ok;
}

/* The size convention, function by function: the query (NULL, 0, &needed) writes only
 * *needed; a short buffer is HYCON_ERROR_BUFFER_TOO_SMALL with the count in the message and in
 * *needed, the buffer untouched; a large one receives exactly needed elements. */
static bool test_result_buffers_too_small(void) {
    HyconContact *c = make_contact(NULL);
    double buf[NDOF + 4];
    HyconNodeResult a[NA];
    HyconBNodeResult b[NB];
    HyconContactNode en[NA];
    HyconIterationRecord r[1];
    HyconCouplingEntry ce[128];
    HyconConstraintEntry ke[128];
    size_t n = 777, count = 0, nnz = 0, i;
    char part[32];
    bool ok = true;
    EXPECT(c != NULL);
    EXPECT(press(c, PRESS, 0.0, NULL) == HYCON_OK);
    fill(buf, NDOF + 4);
    fill_bytes(a, sizeof a);
    fill_bytes(b, sizeof b);
    fill_bytes(en, sizeof en);
    fill_bytes(r, sizeof r);
    fill_bytes(ce, sizeof ce);
    fill_bytes(ke, sizeof ke);
#define SHORT(fn, args, part, count)                                                           \
    ok = ok && STATUS_FN(fn, args, HYCON_ERROR_BUFFER_TOO_SMALL, part) && n == (count);       \
    n = 777
#define QUERY(fn, args, count)                                                                 \
    ok = ok && STATUS(fn args, HYCON_OK, NULL) && n == (count);                                \
    n = 777
    SHORT(hycon_contact_displacement, (c, buf, NDOF - 1, &n), "48 needed", NDOF);
    QUERY(hycon_contact_displacement, (c, NULL, 0, &n), NDOF);
    SHORT(hycon_contact_displacement_increment, (c, buf, NDOF - 1, &n),
          "out has length 47, 48 needed", NDOF);
    QUERY(hycon_contact_displacement_increment, (c, NULL, 0, &n), NDOF);
    SHORT(hycon_contact_forces, (c, buf, 3, &n), "48 needed", NDOF);
    QUERY(hycon_contact_forces, (c, NULL, 0, &n), NDOF);
    SHORT(hycon_contact_node_results, (c, 0, a, NA - 1, &n), "3 needed", NA);
    QUERY(hycon_contact_node_results, (c, 0, NULL, 0, &n), NA);
    SHORT(hycon_contact_b_node_results, (c, 0, b, NB - 1, &n), "5 needed", NB);
    QUERY(hycon_contact_b_node_results, (c, 0, NULL, 0, &n), NB);
    SHORT(hycon_contact_stress_tractions, (c, 0, buf, 2 * NA - 1, &n), "6 needed", 2 * NA);
    QUERY(hycon_contact_stress_tractions, (c, 0, NULL, 0, &n), 2 * NA);
    /* a non-NULL buffer of length 0 is a short buffer, not the query */
    SHORT(hycon_contact_surface_nodes, (c, 0, en, 0, &n), "3 needed", NA);
    QUERY(hycon_contact_surface_nodes, (c, 0, NULL, 0, &n), NA);
    /* coupling: the count query, then a buffer one short */
    ok = ok && STATUS(hycon_contact_surface_coupling(c, 0, NULL, 0, &count), HYCON_OK, NULL);
    ok = ok && count > 1 && count <= 128;
    sprintf(part, "%u needed", (unsigned)count);
    SHORT(hycon_contact_surface_coupling, (c, 0, ce, count - 1, &n), part, count);
    /* Kc: the entry count query, then a buffer one short */
    ok = ok && STATUS(hycon_contact_constraint_rows(c, 0, NULL, 0, &nnz), HYCON_OK, NULL);
    ok = ok && nnz > 1 && nnz <= 128;
    sprintf(part, "%u needed", (unsigned)nnz);
    SHORT(hycon_contact_constraint_rows, (c, 0, ke, nnz - 1, &n), part, nnz);
#undef SHORT
#undef QUERY
    ok = ok && untouched(buf, NDOF + 4) && bytes_untouched(a, sizeof a) &&
         bytes_untouched(b, sizeof b) && bytes_untouched(en, sizeof en) &&
         bytes_untouched(r, sizeof r) && bytes_untouched(ce, sizeof ce) &&
         bytes_untouched(ke, sizeof ke);
    /* with the right sizes or more all of them work and write exactly `needed` elements */
    ok = ok && STATUS(hycon_contact_displacement(c, buf, NDOF + 4, &n), HYCON_OK, NULL) &&
         n == NDOF && untouched(buf + NDOF, 4);
    ok = ok && STATUS(hycon_contact_surface_coupling(c, 0, ce, 128, &n), HYCON_OK, NULL) &&
         n == count && bytes_untouched(ce + count, (128 - count) * sizeof *ce);
    ok = ok && STATUS(hycon_contact_constraint_rows(c, 0, ke, 128, &n), HYCON_OK, NULL) &&
         n == nnz && bytes_untouched(ke + nnz, (128 - nnz) * sizeof *ke);
    /* Kc entries: row-major, rows in 0 .. 2 NA, columns strictly ascending within a row */
    for (i = 0; ok && i < nnz; ++i) {
        ok = ke[i].row < 2 * NA && ke[i].column < NDOF;
        if (i > 0)
            ok = ok && (ke[i - 1].row < ke[i].row ||
                        (ke[i - 1].row == ke[i].row && ke[i - 1].column < ke[i].column));
    }
    hycon_contact_free(c);
    return ok;
}

static bool test_unknown_pair(void) {
    HyconContact *c = make_contact(NULL);
    double buf[NDOF];
    HyconNodeResult a[NA];
    HyconBNodeResult b[NB];
    HyconContactNode en[NA];
    HyconCouplingEntry ce[64];
    HyconConstraintEntry ke[64];
    size_t n_a = 777, n_b = 777, n = 777;
    bool ok = true;
    EXPECT(c != NULL);
    EXPECT(press(c, PRESS, 0.0, NULL) == HYCON_OK);
    fill(buf, NDOF);
    fill_bytes(a, sizeof a);
    fill_bytes(b, sizeof b);
    fill_bytes(en, sizeof en);
    fill_bytes(ce, sizeof ce);
    fill_bytes(ke, sizeof ke);
#define NO_PAIR(fn, args)                                                                      \
    ok = ok && STATUS_FN(fn, args, HYCON_ERROR_INVALID_ARGUMENT, "contact pair 1 does not exist")
    NO_PAIR(hycon_contact_node_results, (c, 1, NULL, 0, &n_a)); /* the size query too */
    NO_PAIR(hycon_contact_b_node_results, (c, 1, NULL, 0, &n_b));
    NO_PAIR(hycon_contact_node_results, (c, 1, a, NA, &n));
    NO_PAIR(hycon_contact_b_node_results, (c, 1, b, NB, &n));
    NO_PAIR(hycon_contact_stress_tractions, (c, 1, buf, NDOF, &n));
    NO_PAIR(hycon_contact_surface_nodes, (c, 1, en, NA, &n));
    NO_PAIR(hycon_contact_surface_coupling, (c, 1, ce, 64, &n));
    NO_PAIR(hycon_contact_constraint_rows, (c, 1, ke, 64, &n));
#undef NO_PAIR
    ok = ok && STATUS_FN(hycon_contact_node_results, (c, (size_t)-1, NULL, 0, &n_a),
                         HYCON_ERROR_INVALID_ARGUMENT, "does not exist (1 pairs)");
    ok = ok && n_a == 777 && n_b == 777 && n == 777;
    ok = ok && untouched(buf, NDOF) && bytes_untouched(a, sizeof a) &&
         bytes_untouched(b, sizeof b) && bytes_untouched(en, sizeof en) &&
         bytes_untouched(ce, sizeof ce) && bytes_untouched(ke, sizeof ke);
    ok = ok && STATUS(hycon_contact_node_results(c, 0, NULL, 0, &n_a), HYCON_OK, NULL) &&
         n_a == NA;
    ok = ok && STATUS(hycon_contact_b_node_results(c, 0, NULL, 0, &n_b), HYCON_OK, NULL) &&
         n_b == NB;
    hycon_contact_free(c);
    return ok;
}

static bool test_records_out_of_range(void) {
    HyconContact *c = make_contact(NULL);
    HyconIterationRecord r[64];
    size_t count = 0, n = 777;
    char part[64];
    bool ok = true;
    EXPECT(c != NULL);
    EXPECT(press(c, PRESS, 0.0, NULL) == HYCON_OK);
    EXPECT(hycon_contact_records(c, 0, NULL, 0, &count) == HYCON_OK && count > 0 && count < 64);
    fill_bytes(r, sizeof r);
    sprintf(part, "first = %u, but %u records exist", (unsigned)(count + 1), (unsigned)count);
    ok = ok && STATUS_FN(hycon_contact_records, (c, count + 1, r, 64, NULL),
                         HYCON_ERROR_INVALID_ARGUMENT, part);
    ok = ok && STATUS_FN(hycon_contact_records, (c, count + 1, NULL, 0, &n),
                         HYCON_ERROR_INVALID_ARGUMENT, part); /* the size query too */
    ok = ok && STATUS_FN(hycon_contact_records, (c, (size_t)-1, r, 2, NULL),
                         HYCON_ERROR_INVALID_ARGUMENT, "records exist");
    /* from `first` on: count - first records */
    ok = ok && STATUS(hycon_contact_records(c, 1, NULL, 0, &n), HYCON_OK, NULL) && n == count - 1;
    n = 777;
    ok = ok && STATUS(hycon_contact_records(c, count, r, 1, &n), HYCON_OK, NULL) && n == 0;
    ok = ok && bytes_untouched(r, sizeof r);
    ok = ok && STATUS(hycon_contact_records(c, 0, r, count, NULL), HYCON_OK, NULL);
    ok = ok && r[count - 1].increment == 1 && r[count - 1].changes == 0;
    /* (NULL, 0) past the end is an empty range */
    ok = ok && STATUS(hycon_contact_records(c, count, NULL, 0, NULL), HYCON_OK, NULL);
    hycon_contact_free(c);
    return ok;
}

/* Lengths whose derived lengths (n + 1, 2 n) overflow: no array can be that long, so they are
 * wrong lengths (HYCON_ERROR_INVALID_ARGUMENT), not internal errors. Nothing is read: the
 * arrays passed are short, and a correct check fails before reading them. */
static bool test_length_overflow(void) {
    HyconModel *m = MARKER(HyconModel);
    HyconHost *h = NULL;
    const size_t half = (size_t)1 << (sizeof(size_t) * 8 - 1); /* 2 * half == 0 */
    bool ok = true;
    ok = STATUS_FN(hycon_model_new,
                   (&m, coords, NN, BLOCK(offsets, conn, SIZE_MAX, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                   HYCON_ERROR_INVALID_ARGUMENT, NULL) &&
         ok;
    ok = STATUS_FN(hycon_model_new,
                   (&m, coords, half, BLOCK(offsets, conn, NE, NULL, HYCON_ELEMENT_HYBRID), &steel, 1),
                   HYCON_ERROR_INVALID_ARGUMENT, "n_nodes") &&
         ok;
    ok = m == MARKER(HyconModel) && ok;
    /* a host of SIZE_MAX equations: its row_ptr would need SIZE_MAX + 1 entries */
    if (hycon_host_new(&h, SIZE_MAX) == HYCON_OK) {
        ok = STATUS_FN(hycon_host_set_csr,
                       (h, csr.row_ptr, csr.columns, csr.values, HYCON_CSR_LOWER),
                       HYCON_ERROR_INVALID_ARGUMENT, NULL) &&
             ok;
        hycon_host_free(h);
    } else {
        /* refused at hycon_host_new: fine too, with a message naming the argument */
        char message[512];
        hycon_last_error_message(message, sizeof message);
        ok = strstr(message, "n_equations") != NULL && ok;
    }
    return ok;
}

/* ---------------------------------------------------------------------------------------- */
/* Failed increments keep the last converged state */

typedef struct {
    size_t calls;
    size_t stop_at; /* 0: never; else return nonzero at this call */
} Monitor;

static int32_t monitor(void *user_data, const HyconIterationRecord *record) {
    Monitor *m = (Monitor *)user_data;
    (void)record;
    m->calls++;
    return (m->stop_at != 0 && m->calls >= m->stop_at) ? 1 : 0;
}

/* Pressing the upper block through the lower one in one increment, by any depth: never OK
 * with the bodies passed through each other. Small kinematics pair the surfaces in the
 * reference configuration and give the linear answer (every A node in contact); finite
 * kinematics lose the pairing and must say so, keeping the last state. */
static bool test_deep_press_never_missed(void) {
    const double depths[5] = {1.5, 10.0, 1e6, 1e8, 1e10};
    const HyconKinematics kinematics[2] = {HYCON_KINEMATICS_SMALL, HYCON_KINEMATICS_FINITE};
    size_t k, i;
    for (k = 0; k < 2; ++k)
        for (i = 0; i < 5; ++i) {
            HyconContactOptions o;
            HyconContact *c;
            State before, after;
            HyconStatus s;
            EXPECT(hycon_contact_options_default(&o) == HYCON_OK);
            o.kinematics = kinematics[k];
            c = make_contact(&o);
            EXPECT(c != NULL);
            EXPECT(press(c, PRESS, 0.0, NULL) == HYCON_OK);
            EXPECT(snapshot(c, &before));
            s = press(c, depths[i], 0.0, NULL);
            if (s == HYCON_OK) {
                EXPECT(snapshot(c, &after) && pressed(&after));
            } else {
                /* "beyond what the pairing sees" once the press is beyond the search's reach
                 * (or the positions no longer resolve the surfaces), a cycling contact set
                 * within it; the automatic cutback may also take the press in sub-increments
                 * until an active node leaves the other surface ("not covered"); under finite
                 * kinematics a press ten times the block's thickness may not settle at all
                 * ("no convergence": since 0.11.0, whose consistent rows for partly covered
                 * nodes no longer let it reach "not covered") */
                char message[512];
                hycon_last_error_message(message, sizeof message);
                EXPECT(s == HYCON_ERROR_CONTACT);
                if (strstr(message, "beyond what the pairing sees") == NULL &&
                    strstr(message, "cycles") == NULL &&
                    strstr(message, "not covered by the opposite surface") == NULL &&
                    (kinematics[k] != HYCON_KINEMATICS_FINITE ||
                     strstr(message, "no convergence") == NULL)) {
                    fprintf(stderr, "  depth %g: %s\n", depths[i], message);
                    return false;
                }
                EXPECT(snapshot(c, &after) && same_state(&before, &after));
            }
            /* finite kinematics cannot resolve a press through the whole block (1 thick) in
             * one increment */
            EXPECT(kinematics[k] == HYCON_KINEMATICS_SMALL || depths[i] < 2.0 || s != HYCON_OK);
            hycon_contact_free(c);
        }
    return true;
}

/* Two faces of one body as a pair (the upper block's bottom as A, its top as B, both with the
 * body on their left): back to back, rejected when the analysis starts. */
static bool test_pair_on_one_body(void) {
    HyconModel *m = make_model(HOLD_UPPER);
    HyconContact *c = MARKER(HyconContact);
    size_t b[NTOP], i;
    bool ok = true;
    EXPECT(m != NULL);
    for (i = 0; i < NTOP; ++i) b[i] = top[NTOP - 1 - i];
    ok = ok && STATUS(hycon_model_add_pair(m, LINE(pair_a, NA), LINE(b, NTOP), 0.0, NULL), HYCON_OK, NULL);
    ok = ok && STATUS_FN(hycon_contact_new, (&c, m, NULL), HYCON_ERROR_INVALID_ARGUMENT,
                         "B lies behind A");
    ok = ok && c == MARKER(HyconContact);
    hycon_model_free(m);
    return ok;
}

/* Both polylines reversed on touching surfaces: the pair lies back to back, which the
 * geometry alone cannot tell from facing surfaces. Before 0.7.0 the host API accepted it and a
 * press returned HYCON_OK with every A node open. Now hycon_contact_new_host asks for the side
 * of body A, and the point given is checked against A's orientation. */
static bool test_host_back_to_back(void) {
    HyconHost *d = NULL;
    HyconContact *c = MARKER(HyconContact);
    double a_xy[2 * NA], b_xy[2 * NB], ra_xy[2 * NA], rb_xy[2 * NB];
    int64_t a_eq[2 * NA], b_eq[2 * NB], ra_eq[2 * NA], rb_eq[2 * NB];
    size_t ra[NA], rb[NB], i;
    const double nan_point[2] = {NAN, 1.5}, beyond[2] = {-3.0, 1.5};
    bool ok = true;
    host_pair_arrays(&host, a_xy, a_eq, b_xy, b_eq);
    for (i = 0; i < NA; ++i) {
        ra[i] = pair_a[NA - 1 - i];
        memcpy(&ra_xy[2 * i], &a_xy[2 * (NA - 1 - i)], 2 * sizeof(double));
        memcpy(&ra_eq[2 * i], &a_eq[2 * (NA - 1 - i)], 2 * sizeof(int64_t));
    }
    for (i = 0; i < NB; ++i) {
        rb[i] = pair_b[NB - 1 - i];
        memcpy(&rb_xy[2 * i], &b_xy[2 * (NB - 1 - i)], 2 * sizeof(double));
        memcpy(&rb_eq[2 * i], &b_eq[2 * (NB - 1 - i)], 2 * sizeof(int64_t));
    }
    EXPECT(hycon_host_new(&d, host.n) == HYCON_OK);
    ok = ok && STATUS(hycon_host_add_pair(d, HOST_NODES(ra, ra_xy, ra_eq, NA),
                                          HOST_NODES(rb, rb_xy, rb_eq, NB), 0.0,
                                          HYCON_PLANE_STRAIN, 1.0, NULL),
                      HYCON_OK, NULL);
    ok = ok && STATUS(hycon_host_set_solver(d, host_solve, &host), HYCON_OK, NULL);
    ok = ok && STATUS_FN(hycon_contact_new_host, (&c, d, NULL), HYCON_ERROR_INVALID_ARGUMENT,
                         "A and B touch");
    ok = ok && c == MARKER(HyconContact);
    /* the point inside the upper block shows A reversed */
    ok = ok && STATUS_FN(hycon_host_set_pair_inside, (d, 0, upper_inside),
                         HYCON_ERROR_INVALID_ARGUMENT, "A has its body on its right");
    /* bad input of hycon_host_set_pair_inside */
    ok = ok && STATUS_FN(hycon_host_set_pair_inside, (NULL, 0, upper_inside),
                         HYCON_ERROR_NULL_POINTER, "host");
    ok = ok && STATUS_FN(hycon_host_set_pair_inside, (d, 0, NULL), HYCON_ERROR_NULL_POINTER,
                         "inside");
    ok = ok && STATUS_FN(hycon_host_set_pair_inside, (d, 1, upper_inside),
                         HYCON_ERROR_INVALID_ARGUMENT, "pair 1 is unknown");
    ok = ok && STATUS_FN(hycon_host_set_pair_inside, (d, 0, nan_point),
                         HYCON_ERROR_INVALID_ARGUMENT, "inside");
    ok = ok && STATUS_FN(hycon_host_set_pair_inside, (d, 0, beyond),
                         HYCON_ERROR_INVALID_ARGUMENT, "beyond an end of the A polyline");
    ok = ok && STATUS_FN(hycon_contact_new_host, (&c, d, NULL), HYCON_ERROR_INVALID_ARGUMENT,
                         "A and B touch");
    hycon_host_free(d);
    /* the same pair facing, with its point: accepted, and a press closes it */
    d = make_host(&host);
    EXPECT(d != NULL);
    ok = ok && STATUS(hycon_host_set_solver(d, host_solve, &host), HYCON_OK, NULL);
    ok = ok && STATUS(hycon_contact_new_host(&c, d, NULL), HYCON_OK, NULL);
    if (ok) hycon_contact_free(c);
    hycon_host_free(d);
    return ok;
}

/* The host API checks a pair's orientation as the model API does: A reversed (its body on the
 * right) is rejected when the analysis starts, not run with every node open. */
static bool test_host_reversed_a(void) {
    HyconHost *d = NULL;
    HyconContact *c = MARKER(HyconContact);
    double a_xy[2 * NA], b_xy[2 * NB], r_xy[2 * NA];
    int64_t a_eq[2 * NA], b_eq[2 * NB], r_eq[2 * NA];
    size_t a[NA], i;
    bool ok = true;
    host_pair_arrays(&host, a_xy, a_eq, b_xy, b_eq);
    for (i = 0; i < NA; ++i) {
        a[i] = pair_a[NA - 1 - i];
        r_xy[2 * i] = a_xy[2 * (NA - 1 - i)];
        r_xy[2 * i + 1] = a_xy[2 * (NA - 1 - i) + 1];
        r_eq[2 * i] = a_eq[2 * (NA - 1 - i)];
        r_eq[2 * i + 1] = a_eq[2 * (NA - 1 - i) + 1];
    }
    EXPECT(hycon_host_new(&d, host.n) == HYCON_OK);
    ok = ok && STATUS(hycon_host_add_pair(d, HOST_NODES(a, r_xy, r_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.0, HYCON_PLANE_STRAIN, 1.0, NULL),
                      HYCON_OK, NULL);
    ok = ok && STATUS(hycon_host_set_solver(d, host_solve, &host), HYCON_OK, NULL);
    ok = ok && STATUS_FN(hycon_contact_new_host, (&c, d, NULL), HYCON_ERROR_INVALID_ARGUMENT,
                         "A and B run the same way");
    ok = ok && c == MARKER(HyconContact);
    hycon_host_free(d);
    return ok;
}

/* A host pair takes the A side's analysis kind and thickness: an unknown kind, a thickness
 * that is not finite and positive are rejected, and the host is left unchanged. */
static bool test_host_pair_measure(void) {
    HyconHost *d = NULL;
    double a_xy[2 * NA], b_xy[2 * NB];
    int64_t a_eq[2 * NA], b_eq[2 * NB];
    size_t index = 99;
    bool ok = true;
    host_pair_arrays(&host, a_xy, a_eq, b_xy, b_eq);
    EXPECT(hycon_host_new(&d, host.n) == HYCON_OK);
    ok = ok && STATUS(hycon_host_add_pair(d, HOST_NODES(pair_a, a_xy, a_eq, NA),
                                          HOST_NODES(pair_b, b_xy, b_eq, NB), 0.0, 7, 1.0, &index),
                      HYCON_ERROR_INVALID_ARGUMENT, "unknown analysis 7");
    ok = ok && STATUS(hycon_host_add_pair(d, HOST_NODES(pair_a, a_xy, a_eq, NA),
                                          HOST_NODES(pair_b, b_xy, b_eq, NB), 0.0,
                                          HYCON_PLANE_STRESS, 0.0, &index),
                      HYCON_ERROR_INVALID_ARGUMENT, "thickness");
    ok = ok && STATUS(hycon_host_add_pair(d, HOST_NODES(pair_a, a_xy, a_eq, NA),
                                          HOST_NODES(pair_b, b_xy, b_eq, NB), 0.0,
                                          HYCON_PLANE_STRAIN, NAN, &index),
                      HYCON_ERROR_INVALID_ARGUMENT, "thickness");
    ok = ok && index == 99;
    ok = ok && STATUS(hycon_host_add_pair(d, HOST_NODES(pair_a, a_xy, a_eq, NA),
                                          HOST_NODES(pair_b, b_xy, b_eq, NB), 0.0,
                                          HYCON_PLANE_STRESS, 2.5, &index),
                      HYCON_OK, NULL);
    ok = ok && index == 0;
    hycon_host_free(d);
    return ok;
}

typedef struct {
    size_t calls;
    size_t non_finite; /* records with R or the condition estimate not finite */
} RecordWatch;

static int32_t watch_records(void *user_data, const HyconIterationRecord *record) {
    RecordWatch *w = (RecordWatch *)user_data;
    w->calls++;
    if (!isfinite(record->r) || !isfinite(record->condition)) w->non_finite++;
    return 0;
}

/* Finite but huge loads: a result with finite values, or an error that keeps the state;
 * never a record (or a monitor call) with R = NaN. */
static bool test_huge_load(void) {
    /* up to 1e300 in magnitude taken; beyond it rejected before any work (the sums derived
     * from the load could overflow) */
    const double loads[5] = {1e300, -1e300, DBL_MAX, -DBL_MAX, 2e300};
    size_t i;
    for (i = 0; i < 5; ++i) {
        HyconContactOptions o;
        HyconContact *c;
        RecordWatch watch = {0, 0};
        double load[NDOF], qp[NDOF], t[2 * NA];
        State before, after;
        HyconStatus s;
        size_t j;
        EXPECT(hycon_contact_options_default(&o) == HYCON_OK);
        o.monitor = watch_records;
        o.monitor_data = &watch;
        c = make_contact(&o);
        EXPECT(c != NULL);
        EXPECT(press(c, PRESS, 0.0, NULL) == HYCON_OK);
        EXPECT(snapshot(c, &before));
        memset(load, 0, sizeof load);
        prescribed_values(qp, PRESS, 0.0);
        load[2 * lower_node(2, 1) + 1] = loads[i]; /* a free dof inside the lower block */
        s = hycon_contact_increment(c, load, NDOF, qp, NDOF, NULL);
        if (fabs(loads[i]) > 1e300) {
            EXPECT(STATUS(s, HYCON_ERROR_INVALID_ARGUMENT, "beyond 1e300"));
        } else if (s != HYCON_OK) {
            EXPECT(STATUS(s, HYCON_ERROR_CONTACT, "not finite"));
        }
        EXPECT(snapshot(c, &after));
        if (s != HYCON_OK) {
            EXPECT(same_state(&before, &after));
        } else {
            for (j = 0; j < NDOF; ++j) EXPECT(isfinite(after.u[j]));
            for (j = 0; j < NA; ++j) EXPECT(isfinite(after.a[j].tn));
            /* the load is not lost: pushing the lower block up presses the contact by
             * orders of magnitude more; pulling it down opens it */
            for (j = 0; j < NA; ++j)
                EXPECT(loads[i] > 0.0 ? after.a[j].tn < 1e250 * before.a[j].tn
                                      : after.a[j].state == HYCON_NODE_OPEN);
            /* every later query gives finite values or fails with a status */
            s = hycon_contact_stress_tractions(c, 0, t, 2 * NA, NULL);
            if (s == HYCON_OK) {
                for (j = 0; j < 2 * NA; ++j) EXPECT(isfinite(t[j]));
            } else {
                EXPECT(STATUS(s, HYCON_ERROR_SOLVER, "overflow"));
            }
        }
        EXPECT(watch.non_finite == 0);
        hycon_contact_free(c);
    }
    return true;
}

/* Entries of `prescribed` at free dofs are ignored, whatever they hold (NaN included). */
static bool test_ignored_prescribed_entries(void) {
    HyconContact *c = make_contact(NULL), *reference = make_contact(NULL);
    double load[NDOF], qp[NDOF];
    State x, y;
    EXPECT(c != NULL && reference != NULL);
    memset(load, 0, sizeof load);
    prescribed_values(qp, PRESS, 0.0);
    EXPECT(hycon_contact_increment(reference, load, NDOF, qp, NDOF, NULL) == HYCON_OK);
    qp[2 * lower_node(2, 1)] = NAN; /* free */
    qp[2 * lower_node(1, 2) + 1] = INFINITY; /* a free contact dof */
    EXPECT(STATUS(hycon_contact_increment(c, load, NDOF, qp, NDOF, NULL), HYCON_OK, NULL));
    EXPECT(snapshot(c, &x) && snapshot(reference, &y) && same_state(&x, &y));
    hycon_contact_free(c);
    hycon_contact_free(reference);
    return true;
}

static bool test_monitor_stops_increment(void) {
    HyconContactOptions o;
    HyconContact *c, *reference;
    Monitor mon = {0, 0};
    HyconIncrementInfo info;
    State before, after, ref;
    size_t calls;
    EXPECT(hycon_contact_options_default(&o) == HYCON_OK);
    o.monitor = monitor;
    o.monitor_data = &mon;
    c = make_contact(&o);
    reference = make_contact(NULL);
    EXPECT(c != NULL && reference != NULL);
    EXPECT(press(c, PRESS, 0.0, NULL) == HYCON_OK);
    EXPECT(mon.calls > 0);
    EXPECT(snapshot(c, &before) && pressed(&before));
    /* the monitor stops the second increment at its first iteration */
    calls = mon.calls;
    mon.stop_at = calls + 1;
    fill_bytes(&info, sizeof info);
    EXPECT(STATUS(press(c, 2 * PRESS, 0.2 * PRESS, &info), HYCON_ERROR_CALLBACK,
                  "hycon_contact_increment: callback: increment 2: the monitor stopped"));
    EXPECT(mon.calls == calls + 1);
    EXPECT(bytes_untouched(&info, sizeof info));
    EXPECT(snapshot(c, &after) && same_state(&before, &after));
    /* going on works, and gives what a handle that never failed gives */
    mon.stop_at = 0;
    EXPECT(STATUS(press(c, 2 * PRESS, 0.2 * PRESS, &info), HYCON_OK, NULL));
    EXPECT(info.increment == 2);
    EXPECT(press(reference, PRESS, 0.0, NULL) == HYCON_OK);
    EXPECT(press(reference, 2 * PRESS, 0.2 * PRESS, NULL) == HYCON_OK);
    EXPECT(snapshot(c, &after) && snapshot(reference, &ref) && close_state(&ref, &after));
    EXPECT(after.records == ref.records);
    hycon_contact_free(c);
    hycon_contact_free(reference);
    return true;
}

static bool test_contact_failure_max_iterations(void) {
    HyconContactOptions o;
    HyconContact *c;
    HyconIncrementInfo info;
    State before, after;
    EXPECT(hycon_contact_options_default(&o) == HYCON_OK);
    o.max_iterations = 1;
    c = make_contact(&o);
    EXPECT(c != NULL);
    /* nothing moves: converged at the first iteration */
    EXPECT(STATUS(press(c, 0.0, 0.0, &info), HYCON_OK, NULL));
    EXPECT(info.increment == 1 && info.iterations == 1);
    EXPECT(snapshot(c, &before));
    fill_bytes(&info, sizeof info);
    EXPECT(STATUS(press(c, PRESS, 0.0, &info), HYCON_ERROR_CONTACT,
                  "hycon_contact_increment: contact: increment 2: no convergence in 1 iterations"));
    EXPECT(bytes_untouched(&info, sizeof info));
    EXPECT(snapshot(c, &after) && same_state(&before, &after));
    /* a following increment that converges in one iteration works */
    EXPECT(STATUS(press(c, 0.0, 0.0, &info), HYCON_OK, NULL));
    EXPECT(info.increment == 2);
    hycon_contact_free(c);
    return true;
}

/* A slide that takes the A surface beyond the end of B fails the increment (the automatic
 * cutback slides it in sub-increments until an active node leaves B's end, which no shorter
 * step changes); the pressed state stays, and the next (smaller) increment works. */
static bool test_contact_failure_keeps_state(void) {
    /* finite kinematics: sliding the top block off the bottom one fails (small kinematics would
     * keep the reference pairing and succeed) */
    HyconContactOptions finite;
    HyconContact *c, *reference;
    HyconIncrementInfo info;
    State before, after, ref;
    EXPECT(hycon_contact_options_default(&finite) == HYCON_OK);
    finite.kinematics = HYCON_KINEMATICS_FINITE;
    c = make_contact(&finite);
    reference = make_contact(&finite);
    EXPECT(c != NULL && reference != NULL);
    EXPECT(press(c, PRESS, 0.0, NULL) == HYCON_OK);
    EXPECT(snapshot(c, &before) && pressed(&before));
    fill_bytes(&info, sizeof info);
    EXPECT(STATUS(press(c, PRESS, 0.9, &info), HYCON_ERROR_CONTACT,
                  "hycon_contact_increment: contact: "));
    EXPECT(bytes_untouched(&info, sizeof info));
    EXPECT(snapshot(c, &after) && same_state(&before, &after));
    EXPECT(after.records == before.records);
    EXPECT(STATUS(press(c, 1.5 * PRESS, 0.0, &info), HYCON_OK, NULL) && info.increment == 2);
    EXPECT(press(reference, PRESS, 0.0, NULL) == HYCON_OK);
    EXPECT(press(reference, 1.5 * PRESS, 0.0, NULL) == HYCON_OK);
    EXPECT(snapshot(c, &after) && snapshot(reference, &ref) && close_state(&ref, &after));
    hycon_contact_free(c);
    hycon_contact_free(reference);
    return true;
}

/* The monitor's view of the automatic cutback: the largest sub-increment index seen. */
static int32_t sub_monitor(void *user_data, const HyconIterationRecord *record) {
    size_t *largest = (size_t *)user_data;
    if (record->sub_increment > *largest) *largest = record->sub_increment;
    return 0;
}

/* The slide off B's end under finite kinematics: the whole step converges to a state with an
 * active node mostly beyond B's end, which is final ("not covered": no shorter step removes
 * it), so the cutback (the default) tries no sub-increment and the failure restores the state
 * (contact_failure_keeps_state), as with cutback_depth = 0. (Before 0.11.0 the inconsistent
 * row of a partly covered node failed the whole step otherwise, and the cutback walked
 * sub-increments up to the node's leaving.) A press converges in one sub-increment. The
 * cutback's sub-increments themselves are tested in tests/contact_cutback.rs. */
static bool test_cutback_sub_increments(void) {
    HyconContactOptions o;
    HyconContact *c;
    HyconIncrementInfo info;
    size_t largest = 0;
    int depth;
    for (depth = 0; depth < 2; ++depth) {
        EXPECT(hycon_contact_options_default(&o) == HYCON_OK);
        o.kinematics = HYCON_KINEMATICS_FINITE;
        o.cutback_depth = depth == 0 ? 0 : 8;
        o.monitor = sub_monitor;
        o.monitor_data = &largest;
        c = make_contact(&o);
        EXPECT(c != NULL);
        largest = 0;
        EXPECT(STATUS(press(c, PRESS, 0.0, &info), HYCON_OK, NULL));
        EXPECT(info.sub_increments == 1 && info.cutbacks == 0 && largest == 1);
        largest = 0;
        EXPECT(press(c, PRESS, 0.9, &info) == HYCON_ERROR_CONTACT);
        {
            char message[512];
            hycon_last_error_message(message, sizeof message);
            EXPECT(strstr(message, "not covered by the opposite surface") != NULL);
        }
        EXPECT(largest == 1);
        hycon_contact_free(c);
    }
    return true;
}

/* ---------------------------------------------------------------------------------------- */
/* The rigid plate */

static bool test_plate_bad_input(void) {
    HyconModel *m = make_model(WITH_PLATE | WITH_PAIR);
    HyconContact *c = NULL, *plain = make_contact(NULL);
    double load[NDOF], qp[NDOF], u[2], f[2];
    const HyconPlateControl disp[2] = {HYCON_PLATE_DISPLACEMENT, HYCON_PLATE_DISPLACEMENT};
    const HyconPlateControl bad0[2] = {0, HYCON_PLATE_DISPLACEMENT};
    const HyconPlateControl bad1[2] = {HYCON_PLATE_FORCE, 3};
    double value[2] = {0.0, -PRESS};
    HyconIncrementInfo info;
    bool ok = true;
    EXPECT(m != NULL && plain != NULL);
    EXPECT(hycon_contact_new(&c, m, NULL) == HYCON_OK);
    hycon_model_free(m);
    memset(load, 0, sizeof load);
    memset(qp, 0, sizeof qp);
    fill_bytes(&info, sizeof info);
    fill(u, 2);
    fill(f, 2);
    ok = ok && STATUS_FN(hycon_contact_increment, (c, load, NDOF, qp, NDOF, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "increment_with_plate");
    ok = ok && STATUS_FN(hycon_contact_increment_with_plate,
                         (c, load, NDOF, qp, NDOF, NULL, value, &info), HYCON_ERROR_NULL_POINTER,
                         "control is NULL");
    ok = ok && STATUS_FN(hycon_contact_increment_with_plate,
                         (c, load, NDOF, qp, NDOF, disp, NULL, &info), HYCON_ERROR_NULL_POINTER,
                         "value is NULL");
    ok = ok && STATUS_FN(hycon_contact_increment_with_plate,
                         (c, load, NDOF, qp, NDOF, bad0, value, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "control[0] = 0");
    ok = ok && STATUS_FN(hycon_contact_increment_with_plate,
                         (c, load, NDOF, qp, NDOF, bad1, value, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "control[1] = 3");
    value[1] = NAN;
    ok = ok && STATUS_FN(hycon_contact_increment_with_plate,
                         (c, load, NDOF, qp, NDOF, disp, value, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "value[1]");
    value[1] = -PRESS;
    ok = ok && STATUS_FN(hycon_contact_increment_with_plate,
                         (c, load, NDOF - 2, qp, NDOF, disp, value, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "the load vector needs 48 entries");
    ok = ok && bytes_untouched(&info, sizeof info);
    /* the plate outputs are both required */
    ok = ok && STATUS_FN(hycon_contact_plate, (c, NULL, f), HYCON_ERROR_NULL_POINTER,
                         "displacement is NULL");
    ok = ok && untouched(f, 2);
    /* a plate call on an analysis without a plate */
    ok = ok && STATUS_FN(hycon_contact_increment_with_plate,
                         (plain, load, NDOF, qp, NDOF, disp, value, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "with_plate");
    ok = ok && STATUS_FN(hycon_contact_plate, (plain, u, f), HYCON_ERROR_INVALID_ARGUMENT,
                         "has no plate");
    ok = ok && bytes_untouched(&info, sizeof info) && untouched(u, 2) && untouched(f, 2);
    /* the good call */
    ok = ok && STATUS(hycon_contact_increment_with_plate(c, load, NDOF, qp, NDOF, disp, value, &info),
                      HYCON_OK, NULL);
    ok = ok && info.increment == 1 && info.active == NA;
    ok = ok && STATUS(hycon_contact_plate(c, u, f), HYCON_OK, NULL) && u[1] == -PRESS &&
         f[1] < 0.0;
    hycon_contact_free(c);
    hycon_contact_free(plain);
    return ok;
}

/* A short prescribed vector (or none) in a plate increment: a wrong length, like the load. */
static bool test_plate_short_prescribed(void) {
    HyconModel *m = make_model(WITH_PLATE | WITH_PAIR);
    HyconContact *c = NULL;
    double load[NDOF], qp[NDOF];
    const HyconPlateControl disp[2] = {HYCON_PLATE_DISPLACEMENT, HYCON_PLATE_DISPLACEMENT};
    const double value[2] = {0.0, -PRESS};
    HyconIncrementInfo info;
    bool ok = true;
    EXPECT(m != NULL);
    EXPECT(hycon_contact_new(&c, m, NULL) == HYCON_OK);
    hycon_model_free(m);
    memset(load, 0, sizeof load);
    memset(qp, 0, sizeof qp);
    fill_bytes(&info, sizeof info);
    ok = ok && STATUS_FN(hycon_contact_increment_with_plate,
                         (c, load, NDOF, qp, 10, disp, value, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "prescribed vector needs 48");
    ok = ok && STATUS_FN(hycon_contact_increment_with_plate,
                         (c, load, NDOF, NULL, 0, disp, value, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "prescribed vector needs 48");
    ok = ok && bytes_untouched(&info, sizeof info);
    hycon_contact_free(c);
    return ok;
}

/* hycon_contact_plate with the force output NULL must not write the displacement output
 * ("on an error every output is left untouched"). */
static bool test_plate_outputs_untouched(void) {
    HyconModel *m = make_model(WITH_PLATE | WITH_PAIR);
    HyconContact *c = NULL;
    double u[2], f[2];
    bool ok = true;
    EXPECT(m != NULL);
    EXPECT(hycon_contact_new(&c, m, NULL) == HYCON_OK);
    hycon_model_free(m);
    fill(u, 2);
    fill(f, 2);
    ok = ok && STATUS_FN(hycon_contact_plate, (c, u, NULL), HYCON_ERROR_NULL_POINTER,
                         "force is NULL");
    if (!untouched(u, 2)) {
        fprintf(stderr, "  hycon_contact_plate wrote the displacement before failing\n");
        ok = false;
    }
    hycon_contact_free(c);
    return ok;
}

/* ---------------------------------------------------------------------------------------- */
/* Host-assembly API */

static bool test_host_new_bad_input(void) {
    HyconHost *d = MARKER(HyconHost);
    EXPECT(STATUS_FN(hycon_host_new, (NULL, 10), HYCON_ERROR_NULL_POINTER, "out is NULL"));
    EXPECT(STATUS_FN(hycon_host_new, (&d, 0), HYCON_ERROR_INVALID_ARGUMENT,
                     "n_equations = 0 must be positive"));
    EXPECT(d == MARKER(HyconHost));
    return true;
}

static bool test_host_add_pair_null_pointers(void) {
    HyconHost *d = NULL;
    double a_xy[2 * NA], b_xy[2 * NB];
    int64_t a_eq[2 * NA], b_eq[2 * NB];
    size_t index = 777;
    bool ok = true;
    host_pair_arrays(&host, a_xy, a_eq, b_xy, b_eq);
    EXPECT(hycon_host_new(&d, host.n) == HYCON_OK);
#define HOST_NULL(args, part)                                                                  \
    ok = ok && STATUS_FN(hycon_host_add_pair, args, HYCON_ERROR_NULL_POINTER, part)
    HOST_NULL((NULL, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
              "host is NULL");
    HOST_NULL((d, HOST_NODES(NULL, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index), "a.ids is NULL");
    HOST_NULL((d, HOST_NODES(pair_a, NULL, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
              "a.coords is NULL");
    HOST_NULL((d, HOST_NODES(pair_a, a_xy, NULL, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
              "a.equations is NULL");
    HOST_NULL((d, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(NULL, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index), "b.ids is NULL");
    HOST_NULL((d, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, NULL, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
              "b.coords is NULL");
    HOST_NULL((d, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, NULL, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
              "b.equations is NULL");
#undef HOST_NULL
    ok = ok && index == 777;
    /* nothing was added: the good call gets index 0 */
    ok = ok && STATUS(hycon_host_add_pair(d, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                      HYCON_OK, NULL) &&
         index == 0;
    hycon_host_free(d);
    return ok;
}

static bool test_host_add_pair_lengths(void) {
    HyconHost *d = NULL;
    double a_xy[2 * NA], b_xy[2 * NB];
    int64_t a_eq[2 * NA], b_eq[2 * NB];
    size_t index = 777;
    bool ok = true;
    host_pair_arrays(&host, a_xy, a_eq, b_xy, b_eq);
    EXPECT(hycon_host_new(&d, host.n) == HYCON_OK);
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(NULL, NULL, NULL, 0), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "A polyline has 0 node(s)");
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, 1), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "B polyline has 1 node(s)");
    ok = ok && index == 777;
    hycon_host_free(d);
    return ok;
}

static bool test_host_add_pair_non_finite(void) {
    HyconHost *d = NULL;
    double a_xy[2 * NA], b_xy[2 * NB];
    int64_t a_eq[2 * NA], b_eq[2 * NB];
    size_t index = 777;
    bool ok = true;
    host_pair_arrays(&host, a_xy, a_eq, b_xy, b_eq);
    EXPECT(hycon_host_new(&d, host.n) == HYCON_OK);
    a_xy[1] = NAN;
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "a.coords[1]");
    a_xy[1] = coords[2 * pair_a[0] + 1];
    b_xy[4] = INFINITY;
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "b.coords[4] = inf is not finite");
    ok = ok && index == 777;
    hycon_host_free(d);
    return ok;
}

static bool test_host_add_pair_not_a_chain(void) {
    HyconHost *d = NULL;
    double a_xy[2 * NA], b_xy[2 * NB];
    int64_t a_eq[2 * NA], b_eq[2 * NB];
    size_t a[NA], index = 777;
    char part[64];
    bool ok = true;
    host_pair_arrays(&host, a_xy, a_eq, b_xy, b_eq);
    EXPECT(hycon_host_new(&d, host.n) == HYCON_OK);
    /* a repeated node */
    memcpy(a, pair_a, sizeof a);
    a[2] = a[0];
    sprintf(part, "node %u appears twice", (unsigned)a[0]);
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, part);
    /* a node in both polylines */
    memcpy(a, pair_a, sizeof a);
    a[1] = pair_b[3];
    sprintf(part, "node %u is in both polylines", (unsigned)pair_b[3]);
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, part);
    /* a zero-length segment: the second B node on the third */
    b_xy[2] = b_xy[4];
    b_xy[3] = b_xy[5];
    sprintf(part, "segment %u -> %u has zero length", (unsigned)pair_b[1], (unsigned)pair_b[2]);
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, part);
    ok = ok && STATUS(hycon_host_add_pair(d, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                      HYCON_ERROR_INVALID_ARGUMENT, "B polyline is not a chain");
    ok = ok && index == 777;
    hycon_host_free(d);
    return ok;
}

/* The host's numbering: equations out of range, a node given twice differently, an equation
 * shared; a failed call adds nothing (the good pair then gets index 0). */
static bool test_host_add_pair_unknown_ids(void) {
    HyconHost *d = NULL;
    double a_xy[2 * NA], b_xy[2 * NB], moved[2 * NA];
    int64_t a_eq[2 * NA], b_eq[2 * NB], bad[2 * NA];
    size_t index = 777;
    char part[96];
    bool ok = true;
    host_pair_arrays(&host, a_xy, a_eq, b_xy, b_eq);
    EXPECT(hycon_host_new(&d, host.n) == HYCON_OK);
    memcpy(bad, a_eq, sizeof bad);
    bad[3] = (int64_t)host.n;
    sprintf(part, "equation %u is out of range", (unsigned)host.n);
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(pair_a, a_xy, bad, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, part);
    bad[3] = -2;
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(pair_a, a_xy, bad, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "equation -2 is out of range");
    memcpy(bad, a_eq, sizeof bad);
    bad[2] = b_eq[0]; /* an A dof on a B node's equation */
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(pair_a, a_xy, bad, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "shares an equation");
    ok = ok && index == 777;
    ok = ok && STATUS(hycon_host_add_pair(d, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                      HYCON_OK, NULL) &&
         index == 0;
    /* the same nodes again with other coordinates */
    memcpy(moved, a_xy, sizeof moved);
    moved[2] += 0.01;
    sprintf(part, "A node %u was given before", (unsigned)pair_a[1]);
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(pair_a, moved, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), 0.1, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, part);
    ok = ok && index == 0;
    hycon_host_free(d);
    return ok;
}

static bool test_host_add_pair_bad_friction(void) {
    HyconHost *d = NULL;
    double a_xy[2 * NA], b_xy[2 * NB];
    int64_t a_eq[2 * NA], b_eq[2 * NB];
    size_t index = 777;
    bool ok = true;
    host_pair_arrays(&host, a_xy, a_eq, b_xy, b_eq);
    EXPECT(hycon_host_new(&d, host.n) == HYCON_OK);
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), NAN, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "friction");
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB), -1.0, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "friction");
    ok = ok && index == 777;
    hycon_host_free(d);
    return ok;
}

/* The upper block's first element (it owns A's first segment) as a host hands it over. */
static HyconStatus set_a_element(HyconHost *d, const HyconMaterial *material) {
    static const size_t one[2] = {0, 4};
    const size_t *nodes = conn + 4 * NEL;
    double xy[8];
    int64_t eqs[8];
    size_t i;
    for (i = 0; i < 4; ++i) {
        xy[2 * i] = coords[2 * nodes[i]];
        xy[2 * i + 1] = coords[2 * nodes[i] + 1];
        eqs[2 * i] = host.eq[2 * nodes[i]];
        eqs[2 * i + 1] = host.eq[2 * nodes[i] + 1];
    }
    return hycon_host_set_elements(d, HOST_NODES(nodes, xy, eqs, 4),
                                   BLOCK(one, nodes, 1, NULL, HYCON_ELEMENT_Q4), material, 1);
}

/* hycon_host_set_condensed, hycon_host_contact_equations and a condensed analysis: every bad
 * hand-over refused with its own message, a good one runs, its increment takes the load image
 * only, and it has no displacement of its own. */
static bool test_host_set_condensed_bad_input(void) {
    HyconHost *d = make_host(&host);
    HyconContact *c = NULL;
    HyconCondensed good, bad;
    int64_t eq[NDOF], wrong_eq[NDOF];
    double flex[NDOF * NDOF], wrong[NDOF * NDOF], unit[NDOF], x[NDOF], rhs[NDOF];
    size_t m = 0, i, j, small = 1;
    bool ok = true;
    EXPECT(d != NULL);
    ok = ok && STATUS_FN(hycon_host_contact_equations, (NULL, NULL, 0, &m),
                         HYCON_ERROR_NULL_POINTER, "host is NULL");
    EXPECT(hycon_host_contact_equations(d, NULL, 0, &m) == HYCON_OK && m > 1 && m <= NDOF);
    ok = ok && STATUS_FN(hycon_host_contact_equations, (d, eq, 1, &small),
                         HYCON_ERROR_BUFFER_TOO_SMALL, NULL);
    ok = ok && small == m;
    EXPECT(hycon_host_contact_equations(d, eq, m, NULL) == HYCON_OK);
    /* the flexibility block (K^-1)_cc from the host's solves with unit columns */
    for (j = 0; j < m; ++j) {
        for (i = 0; i < host.n; ++i) unit[i] = (size_t)eq[j] == i ? 1.0 : 0.0;
        EXPECT(host_solve(&host, host.n, 1, unit, x) == 0);
        for (i = 0; i < m; ++i) flex[i + m * j] = x[eq[i]];
    }
    good.size = sizeof good;
    good.kind = HYCON_CONDENSED_FLEXIBILITY;
    good.m = m;
    good.equations = eq;
    good.matrix = flex;
#define BAD_CONDENSED(status, part) \
    ok = ok && STATUS_FN(hycon_host_set_condensed, (d, &bad), status, part)
    ok = ok && STATUS_FN(hycon_host_set_condensed, (NULL, &good), HYCON_ERROR_NULL_POINTER,
                         "host is NULL");
    ok = ok && STATUS_FN(hycon_host_set_condensed, (d, NULL), HYCON_ERROR_NULL_POINTER,
                         "condensed is NULL");
    bad = good, bad.size = 0;
    BAD_CONDENSED(HYCON_ERROR_INVALID_ARGUMENT, "condensed.size = 0");
    bad = good, bad.kind = 0;
    BAD_CONDENSED(HYCON_ERROR_INVALID_ARGUMENT, "condensed.kind = 0");
    bad = good, bad.m = 0;
    BAD_CONDENSED(HYCON_ERROR_INVALID_ARGUMENT, "needs m^2 > 0");
    bad = good, bad.equations = NULL;
    BAD_CONDENSED(HYCON_ERROR_NULL_POINTER, "condensed.equations is NULL");
    bad = good, bad.matrix = NULL;
    BAD_CONDENSED(HYCON_ERROR_NULL_POINTER, "condensed.matrix is NULL");
    memcpy(wrong_eq, eq, m * sizeof *eq);
    wrong_eq[1] = -2;
    bad = good, bad.equations = wrong_eq;
    BAD_CONDENSED(HYCON_ERROR_INVALID_ARGUMENT, "candidate equation -2 is out of range");
    wrong_eq[1] = (int64_t)host.n;
    BAD_CONDENSED(HYCON_ERROR_INVALID_ARGUMENT, "out of range (n = ");
    wrong_eq[1] = wrong_eq[0];
    BAD_CONDENSED(HYCON_ERROR_INVALID_ARGUMENT, "or given twice");
    memcpy(wrong, flex, m * m * sizeof *flex);
    wrong[2 + m] = NAN;
    bad = good, bad.matrix = wrong;
    BAD_CONDENSED(HYCON_ERROR_INVALID_ARGUMENT, "entry (2, 1) = NaN is not finite");
    wrong[2 + m] = 2.0 * flex[2 + m] + 1.0;
    BAD_CONDENSED(HYCON_ERROR_INVALID_ARGUMENT, "not symmetric");
#undef BAD_CONDENSED
    /* a contact equation that is no candidate: refused when the analysis starts */
    bad = good, bad.m = m - 1, bad.equations = eq + 1;
    for (j = 0; j + 1 < m; ++j)
        for (i = 0; i + 1 < m; ++i) wrong[i + (m - 1) * j] = flex[i + 1 + m * (j + 1)];
    bad.matrix = wrong;
    EXPECT(hycon_host_set_condensed(d, &bad) == HYCON_OK);
    ok = ok && STATUS_FN(hycon_contact_new_host, (&c, d, NULL), HYCON_ERROR_INVALID_ARGUMENT,
                         "is not among the condensed operator's candidates");
    ok = ok && c == NULL;
    /* a Schur complement that is not positive definite */
    for (i = 0; i < m * m; ++i) wrong[i] = -flex[i];
    bad = good, bad.kind = HYCON_CONDENSED_STIFFNESS, bad.matrix = wrong;
    EXPECT(hycon_host_set_condensed(d, &bad) == HYCON_OK);
    ok = ok && STATUS_FN(hycon_contact_new_host, (&c, d, NULL), HYCON_ERROR_SINGULAR,
                         "not positive definite");
    /* the good one: the increment takes the load image (m values), not the right-hand side */
    EXPECT(hycon_host_set_condensed(d, &good) == HYCON_OK);
    EXPECT(set_a_element(d, &(HyconMaterial){1.0, 0.3, 1.0, HYCON_PLANE_STRAIN}) == HYCON_OK);
    EXPECT(hycon_contact_new_host(&c, d, NULL) == HYCON_OK);
    host_rhs(&host, rhs, PRESS, 0.0);
    ok = ok && STATUS_FN(hycon_contact_increment, (c, rhs, host.n, NULL, 0, NULL),
                         HYCON_ERROR_INVALID_ARGUMENT, "load image");
    EXPECT(host_solve(&host, host.n, 1, rhs, x) == 0);
    for (i = 0; i < m; ++i) unit[i] = x[eq[i]];
    ok = ok && STATUS(hycon_contact_increment(c, unit, m, NULL, 0, NULL), HYCON_OK, NULL);
    ok = ok && STATUS_FN(hycon_contact_displacement, (c, x, host.n, NULL),
                         HYCON_ERROR_INVALID_ARGUMENT, "recovers the displacement");
    ok = ok && STATUS_FN(hycon_contact_displacement_increment, (c, x, host.n, NULL),
                         HYCON_ERROR_INVALID_ARGUMENT, "recovers the displacement");
    /* as documented: the displacement's size query gives n (not the load length m), the
     * stress tractions' gives 2 n_a, and the tractions themselves fail, saying why */
    ok = ok && STATUS_FN(hycon_contact_displacement, (c, NULL, 0, &small), HYCON_OK, NULL);
    ok = ok && small == host.n;
    ok = ok && STATUS_FN(hycon_contact_stress_tractions, (c, 0, NULL, 0, &small), HYCON_OK, NULL);
    ok = ok && small == 2 * NA;
    ok = ok && STATUS_FN(hycon_contact_stress_tractions, (c, 0, x, 2 * NA, NULL),
                         HYCON_ERROR_INVALID_ARGUMENT, "condensed operator recovers it itself");
    hycon_contact_free(c);
    hycon_host_free(d);
    return ok;
}

static bool test_host_set_csr_bad_input(void) {
    HyconHost *d = make_host(&host);
    size_t row_ptr[NDOF + 1], cols[4];
    double vals[4];
    const size_t n = host.n, nnz = csr.row_ptr[host.n];
    bool ok = true;
    EXPECT(d != NULL);
#define BAD_CSR(args, status, part) ok = ok && STATUS_FN(hycon_host_set_csr, args, status, part)
    BAD_CSR((NULL, csr.row_ptr, csr.columns, csr.values, HYCON_CSR_LOWER),
            HYCON_ERROR_NULL_POINTER, "host is NULL");
    BAD_CSR((d, NULL, csr.columns, csr.values, HYCON_CSR_LOWER), HYCON_ERROR_NULL_POINTER,
            "row_ptr is NULL");
    BAD_CSR((d, csr.row_ptr, NULL, csr.values, HYCON_CSR_LOWER), HYCON_ERROR_NULL_POINTER,
            "columns is NULL");
    BAD_CSR((d, csr.row_ptr, csr.columns, NULL, HYCON_CSR_LOWER), HYCON_ERROR_NULL_POINTER,
            "values is NULL");
    BAD_CSR((d, csr.row_ptr, csr.columns, csr.values, 0), HYCON_ERROR_INVALID_ARGUMENT,
            "triangle = 0");
    BAD_CSR((d, csr.row_ptr, csr.columns, csr.values, 4), HYCON_ERROR_INVALID_ARGUMENT,
            "triangle = 4");
    /* the lower triangle declared upper */
    BAD_CSR((d, csr.row_ptr, csr.columns, csr.values, HYCON_CSR_UPPER),
            HYCON_ERROR_INVALID_ARGUMENT, "outside the declared Upper triangle");
    /* the lower triangle alone declared full: not symmetric */
    BAD_CSR((d, csr.row_ptr, csr.columns, csr.values, HYCON_CSR_FULL),
            HYCON_ERROR_INVALID_ARGUMENT, "not symmetric");
    /* row_ptr not starting at 0, decreasing */
    memcpy(row_ptr, csr.row_ptr, (n + 1) * sizeof *row_ptr);
    row_ptr[0] = 1;
    BAD_CSR((d, row_ptr, csr.columns, csr.values, HYCON_CSR_LOWER), HYCON_ERROR_INVALID_ARGUMENT,
            "row_ptr");
    memcpy(row_ptr, csr.row_ptr, (n + 1) * sizeof *row_ptr);
    row_ptr[5] = row_ptr[6] + 1;
    BAD_CSR((d, row_ptr, csr.columns, csr.values, HYCON_CSR_LOWER), HYCON_ERROR_INVALID_ARGUMENT,
            "nondecreasing");
    /* a column out of range, a NaN value: a diagonal-only matrix of 4 entries in 4 rows */
    memset(row_ptr, 0, sizeof row_ptr);
    {
        size_t i;
        for (i = 1; i <= n; ++i) row_ptr[i] = i < 4 ? i : 4;
        for (i = 0; i < 4; ++i) {
            cols[i] = i;
            vals[i] = 1.0;
        }
    }
    cols[2] = n;
    BAD_CSR((d, row_ptr, cols, vals, HYCON_CSR_LOWER), HYCON_ERROR_INVALID_ARGUMENT,
            "column out of range");
    cols[2] = 2;
    vals[3] = NAN;
    BAD_CSR((d, row_ptr, cols, vals, HYCON_CSR_LOWER), HYCON_ERROR_INVALID_ARGUMENT,
            "is not finite");
#undef BAD_CSR
    (void)nnz;
    hycon_host_free(d);
    return ok;
}

static bool test_host_set_elements_bad_input(void) {
    HyconHost *d = make_host(&host);
    const HyconMaterial mat = {1.0, 0.3, 1.0, HYCON_PLANE_STRAIN};
    const size_t offsets[2] = {0, 4}, ccw[4] = {100, 101, 102, 103}, cw[4] = {100, 103, 102, 101};
    const size_t unknown[4] = {100, 101, 102, 999}, ids[4] = {100, 101, 102, 103};
    double xy[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    int64_t eqs[8] = {HYCON_FIXED, HYCON_FIXED, HYCON_FIXED, HYCON_FIXED,
                      HYCON_FIXED, HYCON_FIXED, HYCON_FIXED, HYCON_FIXED};
    bool ok = true;
    EXPECT(d != NULL);
#define BAD_EL(args, status, part) \
    ok = ok && STATUS_FN(hycon_host_set_elements, args, status, part)
    BAD_EL((NULL, HOST_NODES(ids, xy, eqs, 4), BLOCK(offsets, ccw, 1, NULL, HYCON_ELEMENT_Q4), &mat, 1),
           HYCON_ERROR_NULL_POINTER, "host is NULL");
    BAD_EL((d, HOST_NODES(ids, xy, eqs, 4), BLOCK(offsets, ccw, 1, NULL, 0), &mat, 1), HYCON_ERROR_INVALID_ARGUMENT,
           "unknown element kind");
    BAD_EL((d, HOST_NODES(ids, xy, eqs, 4), BLOCK(offsets, ccw, 1, NULL, HYCON_ELEMENT_Q4), NULL, 1),
           HYCON_ERROR_NULL_POINTER, "materials is NULL");
    BAD_EL((d, HOST_NODES(ids, xy, eqs, 4), BLOCK(offsets, unknown, 1, NULL, HYCON_ELEMENT_Q4), &mat, 1),
           HYCON_ERROR_INVALID_ARGUMENT, "not in the node table");
    BAD_EL((d, HOST_NODES(ids, xy, eqs, 4), BLOCK(offsets, cw, 1, NULL, HYCON_ELEMENT_Q4), &mat, 1),
           HYCON_ERROR_BAD_ELEMENT, "inverted");
    eqs[3] = (int64_t)host.n + 5;
    BAD_EL((d, HOST_NODES(ids, xy, eqs, 4), BLOCK(offsets, ccw, 1, NULL, HYCON_ELEMENT_Q4), &mat, 1),
           HYCON_ERROR_INVALID_ARGUMENT, "out of range");
    eqs[3] = HYCON_FIXED;
    xy[5] = NAN;
    BAD_EL((d, HOST_NODES(ids, xy, eqs, 4), BLOCK(offsets, ccw, 1, NULL, HYCON_ELEMENT_Q4), &mat, 1),
           HYCON_ERROR_INVALID_ARGUMENT, "not finite");
    xy[5] = 1.0;
    /* NULL views, and NULL arrays inside a view with a nonzero count */
    BAD_EL((d, NULL, BLOCK(offsets, ccw, 1, NULL, HYCON_ELEMENT_Q4), &mat, 1),
           HYCON_ERROR_NULL_POINTER, "nodes is NULL");
    BAD_EL((d, HOST_NODES(ids, xy, eqs, 4), NULL, &mat, 1), HYCON_ERROR_NULL_POINTER,
           "elements is NULL");
    BAD_EL((d, HOST_NODES(ids, NULL, eqs, 4), BLOCK(offsets, ccw, 1, NULL, HYCON_ELEMENT_Q4),
            &mat, 1),
           HYCON_ERROR_NULL_POINTER, "nodes.coords is NULL");
    BAD_EL((d, HOST_NODES(ids, xy, NULL, 4), BLOCK(offsets, ccw, 1, NULL, HYCON_ELEMENT_Q4),
            &mat, 1),
           HYCON_ERROR_NULL_POINTER, "nodes.equations is NULL");
    BAD_EL((d, HOST_NODES(ids, xy, eqs, 0), BLOCK(offsets, ccw, 1, NULL, HYCON_ELEMENT_Q4),
            &mat, 1),
           HYCON_ERROR_INVALID_ARGUMENT, "nodes.n = 0");
    BAD_EL((d, HOST_NODES(ids, xy, eqs, 4), BLOCK(offsets, NULL, 1, NULL, HYCON_ELEMENT_Q4),
            &mat, 1),
           HYCON_ERROR_NULL_POINTER, "elements.nodes is NULL");
    /* a misaligned array inside a view is rejected by name */
    BAD_EL((d, HOST_NODES(ids, (const double *)(const void *)((const char *)xy + 1), eqs, 4),
            BLOCK(offsets, ccw, 1, NULL, HYCON_ELEMENT_Q4), &mat, 1),
           HYCON_ERROR_INVALID_ARGUMENT, "nodes.coords is misaligned");
#undef BAD_EL
    ok = ok && STATUS(hycon_host_set_elements(d, HOST_NODES(ids, xy, eqs, 4), BLOCK(offsets, ccw, 1, NULL, HYCON_ELEMENT_Q4), &mat, 1),
                      HYCON_OK, NULL);
    hycon_host_free(d);
    return ok;
}

/* Hand-overs that do not match are refused where they are handed over, the host unchanged:
 * elements along A of another kind or thickness than their pair (given after the pair, or
 * before it: then the pair is refused), a second pair of another plane kind, an axisymmetric
 * pair with a node at r < 0. */
static bool test_host_hand_overs_match(void) {
    const HyconMaterial strain = {1.0, 0.3, 1.0, HYCON_PLANE_STRAIN};
    const HyconMaterial thick = {1.0, 0.3, 2.0, HYCON_PLANE_STRAIN};
    const HyconMaterial stress = {1.0, 0.3, 1.0, HYCON_PLANE_STRESS};
    const HyconMaterial axi = {1.0, 0.3, 1.0, HYCON_AXISYMMETRIC};
    HyconHost *d = make_host(&host), *e = NULL;
    double a_xy[2 * NA], b_xy[2 * NB];
    int64_t a_eq[2 * NA], b_eq[2 * NB];
    char part[64];
    size_t index = 99;
    bool ok = true;
    EXPECT(d != NULL);
    host_pair_arrays(&host, a_xy, a_eq, b_xy, b_eq);
    /* the pair is plane strain with t = 1 (make_host) */
    ok = ok && STATUS(set_a_element(d, &stress), HYCON_ERROR_INVALID_ARGUMENT,
                         "is plane stress, the contact pairs are plane strain");
    ok = ok && STATUS(set_a_element(d, &axi), HYCON_ERROR_INVALID_ARGUMENT,
                         "is axisymmetric, the contact pairs are plane strain");
    ok = ok && STATUS(set_a_element(d, &thick), HYCON_ERROR_INVALID_ARGUMENT,
                         "thickness 2), the pair is plane strain with thickness 1");
    ok = ok && STATUS(set_a_element(d, &strain), HYCON_OK, NULL);
    /* plane stress beside plane strain */
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB),
                          0.0, HYCON_PLANE_STRESS, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "contact pair 1: its analysis (plane stress)");
    /* the same pair again with another thickness: its element (given above) disagrees */
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (d, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB),
                          0.0, HYCON_PLANE_STRAIN, 3.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "of contact pair 1) has material 0");
    ok = ok && index == 99;
    /* elements first, then a pair they do not match */
    EXPECT(hycon_host_new(&e, host.n) == HYCON_OK);
    ok = ok && STATUS(set_a_element(e, &stress), HYCON_OK, NULL);
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (e, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB),
                          0.0, HYCON_PLANE_STRAIN, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, "is plane stress, the contact pairs are");
    ok = ok && index == 99;
    /* axisymmetric: a B node at r = x < 0 */
    b_xy[0] = -0.5;
    snprintf(part, sizeof part, "B node %lu has r = x = -0.5", (unsigned long)pair_b[0]);
    ok = ok && STATUS_FN(hycon_host_add_pair,
                         (e, HOST_NODES(pair_a, a_xy, a_eq, NA), HOST_NODES(pair_b, b_xy, b_eq, NB),
                          0.0, HYCON_AXISYMMETRIC, 1.0, &index),
                         HYCON_ERROR_INVALID_ARGUMENT, part);
    ok = ok && index == 99;
    hycon_host_free(e);
    hycon_host_free(d);
    return ok;
}

static bool test_host_set_solver_null(void) {
    HyconHost *d = make_host(&host);
    bool ok = true;
    EXPECT(d != NULL);
    ok = ok && STATUS_FN(hycon_host_set_solver, (NULL, host_solve, &host),
                         HYCON_ERROR_NULL_POINTER, "host is NULL");
    ok = ok && STATUS_FN(hycon_host_set_solver, (d, NULL, &host), HYCON_ERROR_NULL_POINTER,
                         "solve is NULL");
    /* user_data may be NULL */
    ok = ok && STATUS(hycon_host_set_solver(d, host_solve, NULL), HYCON_OK, NULL);
    hycon_host_free(d);
    return ok;
}

static bool test_contact_new_host_bad_input(void) {
    HyconHost *d = make_host(&host), *empty = NULL;
    HyconContact *c = MARKER(HyconContact);
    HyconContactOptions o;
    bool ok = true;
    EXPECT(d != NULL && hycon_host_new(&empty, host.n) == HYCON_OK);
    ok = ok && STATUS_FN(hycon_contact_new_host, (&c, NULL, NULL), HYCON_ERROR_NULL_POINTER,
                         "host is NULL");
    ok = ok && STATUS_FN(hycon_contact_new_host, (&c, d, NULL), HYCON_ERROR_INVALID_ARGUMENT,
                         "neither a stiffness");
    ok = ok && hycon_host_set_solver(empty, host_solve, &host) == HYCON_OK;
    ok = ok && STATUS_FN(hycon_contact_new_host, (&c, empty, NULL),
                         HYCON_ERROR_INVALID_ARGUMENT, "no contact pair");
    ok = ok && hycon_host_set_solver(d, host_solve, &host) == HYCON_OK;
    ok = ok && STATUS_FN(hycon_contact_new_host, (NULL, d, NULL), HYCON_ERROR_NULL_POINTER,
                         "out is NULL");
    ok = ok && hycon_contact_options_default(&o) == HYCON_OK;
    o.backend = 7;
    ok = ok && STATUS_FN(hycon_contact_new_host, (&c, d, &o), HYCON_ERROR_INVALID_ARGUMENT,
                         "options.backend = 7");
    o.backend = HYCON_BACKEND_FAER;
    o.tolerance = NAN;
    ok = ok && STATUS_FN(hycon_contact_new_host, (&c, d, &o), HYCON_ERROR_INVALID_ARGUMENT,
                         "options.tolerance");
    ok = ok && c == MARKER(HyconContact);
    hycon_host_free(d);
    hycon_host_free(empty);
    return ok;
}

/* A CSR stiffness that is not positive definite (a body not held): K_ff without the upper
 * block's top held is singular; -K_ff is negative definite. */
static bool test_contact_new_host_singular_csr(void) {
    static Csr neg;
    HyconHost *d = make_host(&host);
    HyconContact *c = MARKER(HyconContact);
    size_t i;
    bool ok = true;
    EXPECT(d != NULL);
    neg = csr;
    for (i = 0; i < csr.row_ptr[host.n]; ++i) neg.values[i] = -csr.values[i];
    ok = ok && hycon_host_set_csr(d, neg.row_ptr, neg.columns, neg.values, HYCON_CSR_LOWER) ==
                   HYCON_OK;
    ok = ok && STATUS_FN(hycon_contact_new_host, (&c, d, NULL), HYCON_ERROR_SINGULAR, NULL);
    ok = ok && c == MARKER(HyconContact);
    hycon_host_free(d);
    return ok;
}

static bool test_host_callback_fails_at_setup(void) {
    HyconHost *d = make_host(&host);
    HyconContact *c = MARKER(HyconContact);
    bool ok = true;
    EXPECT(d != NULL);
    ok = ok && hycon_host_set_solver(d, host_solve, &host) == HYCON_OK;
    host.fail = 7;
    host.calls = 0;
    ok = ok && STATUS_FN(hycon_contact_new_host, (&c, d, NULL), HYCON_ERROR_CALLBACK,
                         "the solve callback returned 7");
    ok = ok && host.calls == 1 && c == MARKER(HyconContact);
    host.fail = 0;
    host.poison = 1;
    ok = ok && STATUS_FN(hycon_contact_new_host, (&c, d, NULL), HYCON_ERROR_CALLBACK,
                         "non-finite value");
    ok = ok && c == MARKER(HyconContact);
    host.poison = 0;
    /* the same description works once the solver does */
    ok = ok && STATUS(hycon_contact_new_host(&c, d, NULL), HYCON_OK, NULL);
    if (c != MARKER(HyconContact)) hycon_contact_free(c);
    hycon_host_free(d);
    return ok;
}

/* The callback fails in a later increment: HYCON_ERROR_CALLBACK, the last converged state is
 * kept, and once the callback works again the next increment succeeds. */
static bool test_host_callback_fails_later(void) {
    HyconContact *c = make_host_contact(&host), *reference = make_host_contact(&host);
    HyconIncrementInfo info;
    State before, after, ref;
    EXPECT(c != NULL && reference != NULL);
    EXPECT(STATUS(host_press(c, &host, PRESS, 0.0, &info), HYCON_OK, NULL));
    /* the displacement recovery fails: nothing written, nothing kept */
    {
        double u[NDOF];
        fill(u, NDOF);
        host.fail = 5;
        EXPECT(STATUS_FN(hycon_contact_displacement, (c, u, host.n, NULL), HYCON_ERROR_CALLBACK,
                         "the solve callback returned 5"));
        EXPECT(STATUS_FN(hycon_contact_displacement_increment, (c, u, host.n, NULL),
                         HYCON_ERROR_CALLBACK, "the solve callback returned 5"));
        host.fail = 0;
        EXPECT(untouched(u, NDOF));
    }
    EXPECT(snapshot(c, &before) && pressed(&before));
    /* a new load direction needs a new solve, which fails */
    host.fail = -3;
    fill_bytes(&info, sizeof info);
    EXPECT(STATUS(host_press(c, &host, PRESS, 0.3 * PRESS, &info), HYCON_ERROR_CALLBACK,
                  "hycon_contact_increment: callback: the solve callback returned -3"));
    EXPECT(bytes_untouched(&info, sizeof info));
    host.fail = 0;
    EXPECT(snapshot(c, &after) && same_state(&before, &after));
    /* non-finite values from the callback: the same */
    host.poison = 1;
    EXPECT(STATUS(host_press(c, &host, PRESS, 0.3 * PRESS, &info), HYCON_ERROR_CALLBACK,
                  "hycon_contact_increment: callback: the solve callback returned a non-finite"));
    host.poison = 0;
    EXPECT(bytes_untouched(&info, sizeof info));
    EXPECT(snapshot(c, &after) && same_state(&before, &after));
    /* the callback works again */
    EXPECT(STATUS(host_press(c, &host, PRESS, 0.3 * PRESS, &info), HYCON_OK, NULL));
    EXPECT(info.increment == 2);
    EXPECT(host_press(reference, &host, PRESS, 0.0, NULL) == HYCON_OK);
    EXPECT(host_press(reference, &host, PRESS, 0.3 * PRESS, NULL) == HYCON_OK);
    EXPECT(snapshot(c, &after) && snapshot(reference, &ref) && close_state(&ref, &after));
    hycon_contact_free(c);
    hycon_contact_free(reference);
    return true;
}

static bool test_host_increment_bad_input(void) {
    HyconContact *c = make_host_contact(&host);
    double rhs[NDOF], buf[NDOF];
    HyconIncrementInfo info;
    size_t n = 0;
    char part[64];
    bool ok = true;
    EXPECT(c != NULL);
    EXPECT(hycon_contact_displacement(c, NULL, 0, &n) == HYCON_OK && n == host.n);
    host_rhs(&host, rhs, PRESS, 0.0);
    fill_bytes(&info, sizeof info);
    fill(buf, NDOF);
    sprintf(part, "the load vector needs %u entries", (unsigned)host.n);
    ok = ok && STATUS_FN(hycon_contact_increment, (c, rhs, host.n - 1, NULL, 0, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, part);
    ok = ok && STATUS_FN(hycon_contact_increment, (c, rhs, host.n, rhs, host.n, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "prescribed vector 0");
    rhs[4] = NAN;
    ok = ok && STATUS_FN(hycon_contact_increment, (c, rhs, host.n, NULL, 0, &info),
                         HYCON_ERROR_INVALID_ARGUMENT, "load[4]");
    ok = ok && bytes_untouched(&info, sizeof info);
    sprintf(part, "%u needed", (unsigned)host.n);
    ok = ok && STATUS_FN(hycon_contact_displacement, (c, buf, host.n - 1, NULL),
                         HYCON_ERROR_BUFFER_TOO_SMALL, part);
    ok = ok && untouched(buf, NDOF);
    /* tractions from element stresses need the elements of body A (none handed over) */
    ok = ok && STATUS_FN(hycon_contact_stress_tractions, (c, 0, buf, 2 * NA, NULL),
                         HYCON_ERROR_INVALID_ARGUMENT, "elements of body A");
    ok = ok && untouched(buf, NDOF);
    hycon_contact_free(c);
    return ok;
}

/* The good paths agree: model API, host CSR, host callback. */
static bool test_host_paths_agree(void) {
    HyconContact *model = make_contact(NULL), *cb = make_host_contact(&host), *fact = NULL;
    HyconHost *d = make_host(&host);
    State sm, sc, sf;
    size_t i;
    EXPECT(model != NULL && cb != NULL && d != NULL);
    EXPECT(hycon_host_set_csr(d, csr.row_ptr, csr.columns, csr.values, HYCON_CSR_LOWER) ==
           HYCON_OK);
    EXPECT(STATUS(hycon_contact_new_host(&fact, d, NULL), HYCON_OK, NULL));
    hycon_host_free(d);
    EXPECT(press(model, PRESS, 0.2 * PRESS, NULL) == HYCON_OK);
    EXPECT(host_press(cb, &host, PRESS, 0.2 * PRESS, NULL) == HYCON_OK);
    EXPECT(host_press(fact, &host, PRESS, 0.2 * PRESS, NULL) == HYCON_OK);
    EXPECT(snapshot(model, &sm) && snapshot(cb, &sc) && snapshot(fact, &sf));
    EXPECT(pressed(&sm));
    for (i = 0; i < NA; ++i) {
        double scale = fabs(sm.a[0].tn);
        EXPECT(sc.a[i].state == sm.a[i].state && sf.a[i].state == sm.a[i].state);
        EXPECT(fabs(sc.a[i].tn - sm.a[i].tn) <= 1e-8 * scale);
        EXPECT(fabs(sf.a[i].tn - sm.a[i].tn) <= 1e-8 * scale);
        EXPECT(fabs(sc.a[i].ts - sm.a[i].ts) <= 1e-8 * scale);
    }
    hycon_contact_free(model);
    hycon_contact_free(cb);
    hycon_contact_free(fact);
    return true;
}

/* ---------------------------------------------------------------------------------------- */

int main(void) {
    static const struct {
        const char *name;
        bool (*run)(void);
    } tests[] = {
        {"options_default", test_options_default},
        {"options_size_and_cutback", test_options_size_and_cutback},
        {"host_pair_measure", test_host_pair_measure},
        {"model_new_null_pointers", test_model_new_null_pointers},
        {"null_views", test_null_views},
        {"model_new_zero_lengths", test_model_new_zero_lengths},
        {"model_new_inconsistent_offsets", test_model_new_inconsistent_offsets},
        {"model_new_element_node_count", test_model_new_element_node_count},
        {"model_new_three_node_element", test_model_new_three_node_element},
        {"model_new_repeated_node_in_element", test_model_new_repeated_node_in_element},
        {"model_new_non_finite_coordinates", test_model_new_non_finite_coordinates},
        {"model_new_unknown_node", test_model_new_unknown_node},
        {"model_new_inverted_element", test_model_new_inverted_element},
        {"model_new_degenerate_element", test_model_new_degenerate_element},
        {"model_new_kind_and_material", test_model_new_unknown_kind_and_bad_material},
        {"free_null_is_a_no_op", test_free_null},
        {"prescribe_bad_input", test_prescribe_bad_input},
        {"prescribe_twice", test_prescribe_twice},
        {"add_pair_null_pointers", test_add_pair_null_pointers},
        {"add_pair_lengths", test_add_pair_lengths},
        {"add_pair_not_a_chain", test_add_pair_not_a_chain},
        {"add_pair_unknown_node", test_add_pair_unknown_node},
        {"add_pair_bad_friction", test_add_pair_bad_friction},
        {"set_plate_bad_input", test_set_plate_bad_input},
        {"contact_new_null_pointers", test_contact_new_null_pointers},
        {"contact_new_bad_options", test_contact_new_bad_options},
        {"contact_new_unknown_backend", test_contact_new_unknown_backend},
#ifdef HYCON_WITHOUT_CHOLMOD
        {"contact_new_cholmod_without_feature", test_contact_new_cholmod_without_feature},
#endif
        {"contact_new_unknown_kinematics", test_contact_new_unknown_kinematics},
        {"contact_new_no_pair", test_contact_new_no_pair},
        {"contact_new_unconstrained_body", test_contact_new_unconstrained_body},
        {"lock_rounds_zero_accepted", test_lock_rounds_zero_accepted},
        {"threads_same_state", test_threads_same_state},
        {"increment_null_pointers", test_increment_null_pointers},
        {"increment_wrong_lengths", test_increment_wrong_lengths},
        {"increment_non_finite", test_increment_non_finite},
        {"results_null_pointers", test_result_functions_null_pointers},
        {"results_buffers_too_small", test_result_buffers_too_small},
        {"results_unknown_pair", test_unknown_pair},
        {"records_out_of_range", test_records_out_of_range},
        {"length_overflow", test_length_overflow},
        {"deep_press_never_missed", test_deep_press_never_missed},
        {"pair_on_one_body", test_pair_on_one_body},
        {"huge_load", test_huge_load},
        {"ignored_prescribed_entries", test_ignored_prescribed_entries},
        {"monitor_stops_increment", test_monitor_stops_increment},
        {"contact_failure_max_iterations", test_contact_failure_max_iterations},
        {"contact_failure_keeps_state", test_contact_failure_keeps_state},
        {"cutback_sub_increments", test_cutback_sub_increments},
        {"plate_bad_input", test_plate_bad_input},
        {"plate_short_prescribed", test_plate_short_prescribed},
        {"plate_outputs_untouched", test_plate_outputs_untouched},
        {"host_new_bad_input", test_host_new_bad_input},
        {"host_add_pair_null_pointers", test_host_add_pair_null_pointers},
        {"host_add_pair_lengths", test_host_add_pair_lengths},
        {"host_add_pair_non_finite", test_host_add_pair_non_finite},
        {"host_back_to_back", test_host_back_to_back},
        {"host_reversed_a", test_host_reversed_a},
        {"host_add_pair_not_a_chain", test_host_add_pair_not_a_chain},
        {"host_add_pair_unknown_ids", test_host_add_pair_unknown_ids},
        {"host_add_pair_bad_friction", test_host_add_pair_bad_friction},
        {"host_set_csr_bad_input", test_host_set_csr_bad_input},
        {"host_set_condensed_bad_input", test_host_set_condensed_bad_input},
        {"host_set_elements_bad_input", test_host_set_elements_bad_input},
        {"host_hand_overs_match", test_host_hand_overs_match},
        {"host_set_solver_null", test_host_set_solver_null},
        {"contact_new_host_bad_input", test_contact_new_host_bad_input},
        {"contact_new_host_singular_csr", test_contact_new_host_singular_csr},
        {"host_callback_fails_at_setup", test_host_callback_fails_at_setup},
        {"host_callback_fails_later", test_host_callback_fails_later},
        {"host_increment_bad_input", test_host_increment_bad_input},
        {"host_paths_agree", test_host_paths_agree},
    };
    size_t i, n = sizeof tests / sizeof tests[0];
    int failures = 0;
    build_mesh();
    if (!host_assemble(&host)) {
        printf("host assembly FAILED\n");
        return 1;
    }
    host_csr(&host, &csr);
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
    printf("OK\n");
    return 0;
}
