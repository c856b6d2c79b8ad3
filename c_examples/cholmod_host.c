/* A host FE code in C99 with its own elements, its own equation numbering and CHOLMOD as its
 * linear solver, running hycon's contact iteration through the host-assembly API.
 *
 * The problem is the Hertz scene of hertz_model.c (disk_mesh.h: a half disk of radius R on a
 * block, plane strain, E = 1, nu = 0.3, target half-width a = R/32, n elements per half-width),
 * displacement-controlled: the block's bottom face is held, the disk's flat top face is moved
 * down by the approach delta (and held in x). The host
 *   - numbers the free dofs itself (the held ones eliminated) and assembles K with its own
 *     4-node bilinear element (Q4, 2x2 Gauss; compared once with hycon_element_stiffness),
 *     and the right-hand side of its prescribed displacements, rhs = -K_fp q_p;
 *   - factors K with CHOLMOD (cholmod_analyze, cholmod_factorize) and hands hycon a solve
 *     callback (hycon_host_set_solver) that solves for many right-hand sides at once;
 *   - describes its contact pair in its numbering (hycon_host_add_pair: node ids, reference
 *     coordinates, equation numbers) and runs the increments with hycon_contact_increment.
 * Two increments: a trial approach a^2 / R, then the approach scaled to the Hertz load of the
 * target half-width (the load is nearly linear in the approach).
 *
 * The same increments are run three more ways and compared:
 *   - CSR path: the same K given as CSR (hycon_host_set_csr), factored by hycon;
 *   - condensed path: the Schur complement S over the contact equations
 *     (hycon_host_set_condensed, HYCON_CONDENSED_STIFFNESS) from one CHOLMOD factorization of
 *     K with those equations eliminated last (CHOLMOD's constrained minimum degree order,
 *     CAMD, then cholmod_analyze_p with that order as given): S = L22 L22^T, L22 the factor's
 *     trailing block, no solve with unit columns. Per increment the host solves for its load
 *     with the same factor and hands over the image at those equations, and after it
 *     recovers its displacement itself from K u = rhs + hycon_contact_forces; checked against
 *     the CSR path to 1e-8 (as is the callback path);
 *   - model API: the same mesh and prescribed values through hycon_model_new with
 *     HYCON_ELEMENT_Q4 (hycon assembles and factors).
 * Checked at every increment: the A nodes' states are identical and their tractions (tn, ts) and
 * the displacements of all contact nodes agree to 1e-7 relative (to the largest |tn| and the
 * largest contact-node displacement). The three paths solve the same linear systems with
 * different orderings and factorizations, so they differ by round-off (about 1e-10 measured)
 * amplified by the contact iteration; 1e-7 leaves a wide margin over that yet is far below
 * anything a real mismatch gives (a wrong equation number, element or load: 1e-3 and more).
 * The contact iteration itself converges to R < 1e-6, but all paths take the same contact sets,
 * and within a set the converged state is the exact solution of a linear system.
 * The Hertz comparison (multipliers and B side) is printed for information (Q4, not checked).
 *
 * Finally a solve made to fail (as a CHOLMOD failure would) must fail the next increment with
 * HYCON_ERROR_CALLBACK and leave the last converged state untouched; the same increment then
 * succeeds.
 *
 * Usage: cholmod_host [n [small|finite mu]]   (elements per half-width, 4..32, default 12; the
 * press's kinematics and friction coefficient, default small 0). Prints OK on success; FAILED
 * or "wrong value" and exit code 1 otherwise.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include "disk_mesh.h"

#include <cholmod.h>
#include <string.h>
#include <time.h>

/* A monotonic wall clock in seconds (hycon's own timings are wall-clock too). */
static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double seconds_since(double start) {
    return now() - start;
}

/* ------------------------------------------------------------------------------------------ */
/* The host's element: bilinear quadrilateral, 2x2 Gauss, plane strain, thickness t */

/* Element stiffness (8 x 8, row-major, dofs u0 v0 u1 v1 ...). Returns 0, or -1 if det J <= 0. */
static int q4_stiffness(const double xy[8], double youngs, double poisson, double thickness,
                        double k[64]) {
    static const double xi_n[4] = {-1.0, 1.0, 1.0, -1.0}, eta_n[4] = {-1.0, -1.0, 1.0, 1.0};
    const double g = 1.0 / sqrt(3.0);
    const double c = youngs / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
    const double d11 = c * (1.0 - poisson), d12 = c * poisson, d33 = youngs / (2.0 * (1.0 + poisson));
    size_t p, i, j;
    memset(k, 0, 64 * sizeof *k);
    for (p = 0; p < 4; ++p) {
        double xi = g * xi_n[p], eta = g * eta_n[p];
        double dxi[4], deta[4], dx[4], dy[4], j11 = 0, j12 = 0, j21 = 0, j22 = 0, det, w;
        double b[3][8];
        for (i = 0; i < 4; ++i) {
            dxi[i] = 0.25 * xi_n[i] * (1.0 + eta_n[i] * eta);
            deta[i] = 0.25 * eta_n[i] * (1.0 + xi_n[i] * xi);
            j11 += dxi[i] * xy[2 * i];
            j12 += dxi[i] * xy[2 * i + 1];
            j21 += deta[i] * xy[2 * i];
            j22 += deta[i] * xy[2 * i + 1];
        }
        det = j11 * j22 - j12 * j21;
        if (!(det > 0.0)) return -1;
        for (i = 0; i < 4; ++i) {
            dx[i] = (j22 * dxi[i] - j12 * deta[i]) / det;
            dy[i] = (-j21 * dxi[i] + j11 * deta[i]) / det;
            b[0][2 * i] = dx[i], b[0][2 * i + 1] = 0.0;
            b[1][2 * i] = 0.0, b[1][2 * i + 1] = dy[i];
            b[2][2 * i] = dy[i], b[2][2 * i + 1] = dx[i];
        }
        w = det * thickness; /* Gauss weights 1 */
        for (i = 0; i < 8; ++i) {
            double db0 = d11 * b[0][i] + d12 * b[1][i], db1 = d12 * b[0][i] + d11 * b[1][i];
            double db2 = d33 * b[2][i];
            for (j = 0; j < 8; ++j)
                k[i * 8 + j] += w * (b[0][j] * db0 + b[1][j] * db1 + b[2][j] * db2);
        }
    }
    return 0;
}

/* ------------------------------------------------------------------------------------------ */
/* CHOLMOD as the host's solver */

typedef struct CholmodState {
    cholmod_common common;
    cholmod_factor *factor;
    size_t n;
    size_t calls, columns, max_nrhs, failures;
    double seconds;    /* wall-clock time in the solves */
    int fail_next;     /* test: fail the next call as a CHOLMOD failure would */
} CholmodState;

/* K x_j = rhs_j for nrhs column-major right-hand sides with the host's factor: 0, or 2 / 3
 * for a CHOLMOD failure. */
static int32_t chol_solve(CholmodState *s, size_t nrhs, const double *rhs, double *x) {
    const size_t n = s->n;
    cholmod_dense *b, *sol;
    size_t j;
    b = cholmod_allocate_dense(n, nrhs, n, CHOLMOD_REAL, &s->common);
    if (b == NULL) return 2;
    memcpy(b->x, rhs, n * nrhs * sizeof *rhs);
    sol = cholmod_solve(CHOLMOD_A, s->factor, b, &s->common);
    cholmod_free_dense(&b, &s->common);
    if (sol == NULL || s->common.status != CHOLMOD_OK) {
        cholmod_free_dense(&sol, &s->common);
        return 3;
    }
    for (j = 0; j < nrhs; ++j)
        memcpy(x + j * n, (const double *)sol->x + j * sol->d, n * sizeof *x);
    cholmod_free_dense(&sol, &s->common);
    return 0;
}

/* hycon's HyconSolveFn: K x_j = rhs_j for nrhs column-major right-hand sides. Never unwinds:
 * every CHOLMOD failure becomes a nonzero return (hycon then reports HYCON_ERROR_CALLBACK). */
static int32_t cholmod_solve_cb(void *user_data, size_t n, size_t nrhs, const double *rhs,
                                double *x) {
    CholmodState *s = user_data;
    double start = now();
    int32_t status;
    if (s == NULL || s->factor == NULL || n != s->n || rhs == NULL || x == NULL) return 1;
    if (nrhs == 0) return 0;
    if (s->fail_next) {
        s->fail_next = 0;
        return 4;
    }
    status = chol_solve(s, nrhs, rhs, x);
    if (status != 0) {
        ++s->failures;
        return status;
    }
    ++s->calls;
    s->columns += nrhs;
    if (nrhs > s->max_nrhs) s->max_nrhs = nrhs;
    s->seconds += seconds_since(start);
    return 0;
}

/* ------------------------------------------------------------------------------------------ */
/* The condensed hand-over: the Schur complement from a factor with the candidates last */

/* The times of the hand-over's steps (wall-clock seconds). */
typedef struct SchurTimes {
    double order, factor, block;
} SchurTimes;

/* A fill-reducing order of K with the m candidate equations last: CHOLMOD's constrained
 * minimum degree (cholmod_camd: constraint set 0 for the other equations, 1 for the
 * candidates, ordered after set 0), perm[k] the equation eliminated k-th. The candidates are
 * rewritten in the order CAMD gives them (that of S's rows and columns). Measured against
 * CHOLMOD's own unconstrained order with the candidates moved to the end: 9.4e8 against
 * 1.3e9 flops at n = 32, 1.78e8 against 1.82e8 at n = 12. NULL on failure. */
static int *order_candidates_last(cholmod_sparse *k, int64_t *candidates, size_t m,
                                  cholmod_common *common) {
    const size_t n = k->nrow;
    int *set = xcalloc(n, sizeof *set), *perm = xcalloc(n, sizeof *perm);
    size_t i;
    for (i = 0; i < m; ++i) set[candidates[i]] = 1;
    if (!cholmod_camd(k, NULL, 0, set, perm, common)) {
        free(set);
        free(perm);
        return NULL;
    }
    for (i = 0; i < n; ++i)
        if (set[perm[i]] != (i >= n - m)) {
            printf("FAILED: CAMD did not order the candidates last\n");
            exit(EXIT_FAILURE);
        }
    for (i = 0; i < m; ++i) candidates[i] = perm[n - m + i];
    free(set);
    return perm;
}

/* The factor of P K P^T in the order `perm` exactly as given: one method, CHOLMOD_GIVEN, and
 * no postorder (a postorder could move the trailing equations). NULL on failure, or if it is
 * not the simplicial LL' factor that hand_over_schur asks for. */
static cholmod_factor *factor_in_order(cholmod_sparse *k, int *perm, cholmod_common *common) {
    const size_t n = k->nrow;
    cholmod_factor *factor;
    size_t i;
    common->nmethods = 1;
    common->method[0].ordering = CHOLMOD_GIVEN;
    common->postorder = 0;
    factor = cholmod_analyze_p(k, perm, NULL, 0, common);
    if (factor == NULL) return NULL;
    for (i = 0; i < n; ++i)
        if (((const int *)factor->Perm)[i] != perm[i]) {
            cholmod_free_factor(&factor, common);
            return NULL;
        }
    if (!cholmod_factorize(k, factor, common) || common->status != CHOLMOD_OK ||
        factor->minor != n || factor->is_super || !factor->is_ll)
        cholmod_free_factor(&factor, common);
    return factor;
}

/* The trailing m x m block L22 of a numeric simplicial LL' factor (dense, column-major, lower
 * triangular): column j of L holds its nz[j] rows i[p[j]..] (all >= j) and values x[p[j]..]. */
static double *trailing_block(const cholmod_factor *factor, size_t m) {
    const size_t n = factor->n, first = n - m;
    const int *p = factor->p, *nz = factor->nz, *rows = factor->i;
    const double *x = factor->x;
    double *l22 = xcalloc(m * m, sizeof *l22);
    size_t j;
    for (j = first; j < n; ++j) {
        int q;
        for (q = p[j]; q < p[j] + nz[j]; ++q)
            l22[(size_t)rows[q] - first + m * (j - first)] = x[q];
    }
    return l22;
}

/* The Schur complement of the trailing equations, S = K22 - K21 K11^-1 K12 = L22 L22^T
 * (P K P^T = L L^T: K22 = L21 L21^T + L22 L22^T and L21 L21^T = K21 K11^-1 K12), m x m,
 * column-major, both triangles. */
static double *schur_from_block(const double *l22, size_t m) {
    double *s = xcalloc(m * m, sizeof *s);
    size_t i, j, k;
    for (j = 0; j < m; ++j)
        for (i = j; i < m; ++i) {
            double sum = 0.0;
            for (k = 0; k <= j; ++k) sum += l22[i + m * k] * l22[j + m * k];
            s[i + m * j] = s[j + m * i] = sum;
        }
    return s;
}

/* The condensed path's host solver: the host's contact equations
 * (hycon_host_contact_equations) as the candidates, K factored once with them eliminated last
 * (cond->factor, which then serves the load and recovery solves), and the Schur complement
 * S = L22 L22^T handed over with hycon_host_set_condensed (HYCON_CONDENSED_STIFFNESS): no
 * solve with unit columns. */
static SchurTimes hand_over_schur(HyconHost *host, cholmod_sparse *k, CholmodState *cond,
                                  int64_t **candidates, size_t *m_out) {
    SchurTimes times;
    double start = now();
    size_t m = 0;
    int *perm;
    double *l22, *schur;
    HyconCondensed condensed;
    CHECK(hycon_host_contact_equations(host, NULL, 0, &m));
    *candidates = xcalloc(m, sizeof **candidates);
    CHECK(hycon_host_contact_equations(host, *candidates, m, NULL));
    /* A simplicial LL' factor: with the reference BLAS Debian installs by default it factors
     * this matrix no slower than the supernodal method (analyze_p + factorize, 3 runs each:
     * 0.09-0.10 s against 0.14-0.16 s at n = 12, 0.50-0.62 s against 0.55-1.09 s at n = 32),
     * and its trailing block is read straight from the columns of L. */
    cond->common.supernodal = CHOLMOD_SIMPLICIAL;
    cond->common.final_ll = 1;
    perm = order_candidates_last(k, *candidates, m, &cond->common);
    times.order = seconds_since(start);
    start = now();
    cond->factor = perm == NULL ? NULL : factor_in_order(k, perm, &cond->common);
    times.factor = seconds_since(start);
    start = now();
    if (cond->factor == NULL) {
        printf("FAILED: CHOLMOD with the candidates last (status %d)\n", cond->common.status);
        exit(EXIT_FAILURE);
    }
    l22 = trailing_block(cond->factor, m);
    schur = schur_from_block(l22, m);
    condensed.size = sizeof condensed;
    condensed.kind = HYCON_CONDENSED_STIFFNESS;
    condensed.m = m;
    condensed.equations = *candidates;
    condensed.matrix = schur;
    CHECK(hycon_host_set_condensed(host, &condensed));
    times.block = seconds_since(start);
    free(perm);
    free(l22);
    free(schur);
    *m_out = m;
    return times;
}

/* One increment of the condensed path: the host's load solve gives the load image
 * u0 = K^-1 rhs at the candidates, hycon iterates on the Schur complement alone, and the host
 * recovers its displacement u (n values) from K u = rhs + forces, both solves with its factor
 * with the candidates last. Returns the wall-clock seconds of the whole. */
static double condensed_increment(HyconContact *c, CholmodState *cond, const int64_t *candidates,
                                  size_t m, const double *rhs, double *u) {
    const size_t n = cond->n;
    double start = now(), *u0 = xcalloc(n, sizeof *u0);
    double *image = xcalloc(m, sizeof *image), *forces = xcalloc(n, sizeof *forces);
    size_t k;
    if (chol_solve(cond, 1, rhs, u0) != 0) {
        printf("FAILED: CHOLMOD load solve\n");
        exit(EXIT_FAILURE);
    }
    for (k = 0; k < m; ++k) image[k] = u0[candidates[k]];
    CHECK(hycon_contact_increment(c, image, m, NULL, 0, NULL));
    CHECK(hycon_contact_forces(c, forces, n, NULL));
    for (k = 0; k < n; ++k) forces[k] += rhs[k];
    if (chol_solve(cond, 1, forces, u) != 0) {
        printf("FAILED: CHOLMOD recovery solve\n");
        exit(EXIT_FAILURE);
    }
    free(u0);
    free(image);
    free(forces);
    return seconds_since(start);
}

/* ------------------------------------------------------------------------------------------ */
/* Comparison of two analyses */

typedef struct Snapshot {
    HyconNodeResult *nodes; /* n_a */
    double *u;              /* 2 n_nodes: displacement at every node (prescribed values too) */
} Snapshot;

/* Read the A-node results and the nodal displacements of an analysis. `eq` maps the host's dofs
 * to equations (NULL: a model, whose field is the dofs); `qp` holds the prescribed values. */
static void snapshot(HyconContact *c, const DiskMesh *m, const long *eq, const double *qp,
                     double *field, size_t n_field, Snapshot *s) {
    size_t k;
    CHECK(hycon_contact_node_results(c, 0, s->nodes, m->n_a, NULL));
    CHECK(hycon_contact_displacement(c, field, n_field, NULL));
    for (k = 0; k < 2 * m->n_nodes; ++k)
        s->u[k] = eq == NULL ? field[k] : eq[k] >= 0 ? field[eq[k]] : qp[k];
}

/* Differences of `x` against the reference `ref`; prints them and returns the failures. */
static int compare(const char *label, const DiskMesh *m, const Snapshot *x, const Snapshot *ref,
                   double tolerance) {
    double tn_max = 0.0, u_max = 0.0, dtn = 0.0, dts = 0.0, du = 0.0;
    size_t k, d, states = 0;
    int failures = 0;
    for (k = 0; k < m->n_a; ++k) {
        const HyconNodeResult *p = &x->nodes[k], *q = &ref->nodes[k];
        if (fabs(q->tn) > tn_max) tn_max = fabs(q->tn);
        if (fabs(p->tn - q->tn) > dtn) dtn = fabs(p->tn - q->tn);
        if (fabs(p->ts - q->ts) > dts) dts = fabs(p->ts - q->ts);
        if (p->state != q->state || p->node != q->node) ++states;
    }
    for (k = 0; k < m->n_a + m->n_b; ++k) {
        size_t id = k < m->n_a ? m->a[k] : m->b[k - m->n_a];
        for (d = 0; d < 2; ++d) {
            double v = ref->u[2 * id + d], e = fabs(x->u[2 * id + d] - v);
            if (fabs(v) > u_max) u_max = fabs(v);
            if (e > du) du = e;
        }
    }
    dtn /= tn_max, dts /= tn_max, du /= u_max;
    printf("  %-22s tn %.2e, ts %.2e (of max |tn| %.3e), contact-node displacement %.2e (of "
           "%.3e), states differing %lu\n",
           label, dtn, dts, tn_max, du, u_max, (unsigned long)states);
    if (states != 0) {
        printf("wrong value: %s: %lu A nodes in another state\n", label, (unsigned long)states);
        ++failures;
    }
    if (!(dtn <= tolerance && dts <= tolerance && du <= tolerance)) {
        printf("wrong value: %s differs by more than %.0e\n", label, tolerance);
        ++failures;
    }
    return failures;
}

static void print_timings(const char *label, HyconContact *c, size_t expected, int *failures) {
    HyconTimings t;
    size_t factorizations;
    CHECK(hycon_contact_timings(c, &t, &factorizations));
    printf("  %-12s assembly %.3f, factorization %.3f, flexibility %.3f, load solves %.3f, "
           "iterations %.3f, recovery %.3f s; %lu factorization(s) by hycon\n",
           label, t.assembly, t.factorization, t.flexibility, t.load_solves, t.iterations,
           t.recovery, (unsigned long)factorizations);
    if (factorizations != expected) {
        printf("wrong value: %s: %lu factorizations, expected %lu\n", label,
               (unsigned long)factorizations, (unsigned long)expected);
        ++*failures;
    }
}

int main(int argc, char **argv) {
    const double youngs = 1.0, poisson = 0.3, radius = 1.0, target = 1.0 / 32.0;
    const double tolerance = 1e-7;
    const double e_star = youngs / (2.0 * (1.0 - poisson * poisson));
    size_t n = argc > 1 ? (size_t)strtoul(argv[1], NULL, 10) : 12;
    HyconKinematics kinematics = HYCON_KINEMATICS_SMALL;
    double friction = 0.0;
    DiskMeshParams params;
    DiskMesh m;
    CholmodState *chol, *cond;
    cholmod_triplet *triplets;
    cholmod_sparse *kff;
    HyconMaterial materials[2];
    HyconModel *model = NULL;
    HyconHost *host_cb = NULL, *host_csr = NULL, *host_cond = NULL;
    HyconContact *c_cb = NULL, *c_csr = NULL, *c_model = NULL, *c_cond = NULL;
    int64_t *candidates = NULL;
    /* wall-clock seconds of each path: setup (hycon_contact_new_host, and for the condensed path
     * the host's Schur complement before it), then the increments */
    double cb_setup, csr_setup, cond_setup, cb_increments = 0.0, csr_increments = 0.0;
    double cond_increments = 0.0;
    size_t cb_columns[2]; /* the callback's right-hand sides: setup, the two increments */
    SchurTimes schur_times;
    size_t n_cand = 0;
    Snapshot s_cond;
    HyconContactOptions options;
    HyconElementBlock q4_elements;
    HyconHostNodes a_nodes, b_nodes;
    HyconPolyline a_line, b_line;
    Snapshot s_cb, s_csr, s_model;
    long *eq;
    int64_t *a_eq, *b_eq;
    double *a_xy, *b_xy, *rhs_unit, *rhs, *qp, *field_host, *field_model, *zero;
    size_t *row_ptr, *columns;
    double deltas[2], k_max = 0.0, k_diff = 0.0;
    size_t n_eq = 0, k, e, i, j, step, n_model_field;
    int failures = 0;
    double start;

    if (n < 4 || n > 32 || disk_case_args(argc, argv, &kinematics, &friction) < 0) {
        fprintf(stderr,
                "usage: cholmod_host [n [small|finite mu]], 4 <= n <= 32, 0 <= mu <= 1\n");
        return EXIT_FAILURE;
    }
    params.radius = radius;
    params.half_width = target * radius;
    params.per_half_width = n;
    params.growth = 1.1;
    params.block_half_width = 2.0 * radius;
    params.block_depth = 2.0 * radius;
    m = disk_mesh_build(&params);

    /* the host's equations: block bottom and disk top held (eliminated), the rest numbered */
    eq = xcalloc(2 * m.n_nodes, sizeof *eq);
    for (k = 0; k < m.n_bottom; ++k) eq[2 * m.bottom[k]] = eq[2 * m.bottom[k] + 1] = -1;
    for (k = 0; k < m.n_top; ++k) eq[2 * m.top[k]] = eq[2 * m.top[k] + 1] = -1;
    for (k = 0; k < 2 * m.n_nodes; ++k) eq[k] = eq[k] < 0 ? -1 : (long)n_eq++;
    printf("Hertz disk on block, host with CHOLMOD: h = a/%lu, %lu nodes, %lu Q4 elements, %lu "
           "equations, %lu A nodes, %lu B nodes; %s kinematics, mu %.2f\n",
           (unsigned long)n, (unsigned long)m.n_nodes, (unsigned long)m.n_elements,
           (unsigned long)n_eq, (unsigned long)m.n_a, (unsigned long)m.n_b,
           kinematics == HYCON_KINEMATICS_FINITE ? "finite" : "small", friction);

    /* prescribed values of a unit approach: top face v = -1 */
    qp = xcalloc(2 * m.n_nodes, sizeof *qp);
    for (k = 0; k < m.n_top; ++k) qp[2 * m.top[k] + 1] = -1.0;

    /* assembly: upper triangle of K_ff as triplets, rhs_unit = -K_fp q_p(unit approach) */
    chol = xcalloc(1, sizeof *chol);
    cholmod_start(&chol->common);
    chol->n = n_eq;
    triplets = cholmod_allocate_triplet(n_eq, n_eq, 36 * m.n_elements, 1, CHOLMOD_REAL,
                                        &chol->common);
    rhs_unit = xcalloc(n_eq, sizeof *rhs_unit);
    if (triplets == NULL) {
        printf("FAILED: cholmod_allocate_triplet\n");
        return EXIT_FAILURE;
    }
    for (k = 0; k < 2; ++k) {
        materials[k].youngs = youngs;
        materials[k].poisson = poisson;
        materials[k].thickness = 1.0;
        materials[k].analysis = HYCON_PLANE_STRAIN;
    }
    start = now();
    for (e = 0; e < m.n_elements; ++e) {
        const size_t *en = &m.nodes[m.offsets[e]];
        double xy[8], ke[64], kh[64];
        for (i = 0; i < 4; ++i) {
            xy[2 * i] = m.coords[2 * en[i]];
            xy[2 * i + 1] = m.coords[2 * en[i] + 1];
        }
        if (q4_stiffness(xy, youngs, poisson, 1.0, ke) != 0) {
            printf("FAILED: element %lu is inverted or degenerate\n", (unsigned long)e);
            return EXIT_FAILURE;
        }
        /* the host's element is the textbook Q4: it must equal hycon's to round-off */
        CHECK(hycon_element_stiffness(HYCON_ELEMENT_Q4, 4, xy, &materials[m.materials[e]], kh,
                                      64));
        for (i = 0; i < 64; ++i) {
            if (fabs(kh[i]) > k_max) k_max = fabs(kh[i]);
            if (fabs(kh[i] - ke[i]) > k_diff) k_diff = fabs(kh[i] - ke[i]);
        }
        for (i = 0; i < 8; ++i) {
            long r = eq[2 * en[i / 2] + i % 2];
            if (r < 0) continue;
            for (j = 0; j < 8; ++j) {
                long col = eq[2 * en[j / 2] + j % 2];
                if (col < 0) {
                    rhs_unit[r] -= ke[i * 8 + j] * qp[2 * en[j / 2] + j % 2];
                } else if (r <= col) {
                    size_t t = triplets->nnz++;
                    ((int *)triplets->i)[t] = (int)r;
                    ((int *)triplets->j)[t] = (int)col;
                    ((double *)triplets->x)[t] = ke[i * 8 + j];
                }
            }
        }
    }
    kff = cholmod_triplet_to_sparse(triplets, 0, &chol->common);
    cholmod_free_triplet(&triplets, &chol->common);
    printf("host assembly %.3f s; host Q4 vs hycon_element_stiffness(HYCON_ELEMENT_Q4): max "
           "difference %.2e of max entry %.3e\n",
           seconds_since(start), k_diff, k_max);
    if (!(k_diff <= 1e-12 * k_max)) {
        printf("wrong value: the host's Q4 differs from hycon's\n");
        ++failures;
    }
    if (kff == NULL) {
        printf("FAILED: cholmod_triplet_to_sparse (status %d)\n", chol->common.status);
        return EXIT_FAILURE;
    }
    start = now();
    chol->factor = cholmod_analyze(kff, &chol->common);
    if (chol->factor == NULL || !cholmod_factorize(kff, chol->factor, &chol->common) ||
        chol->common.status != CHOLMOD_OK || chol->factor->minor != n_eq) {
        printf("FAILED: CHOLMOD could not factor K (status %d)\n", chol->common.status);
        return EXIT_FAILURE;
    }
    printf("CHOLMOD: %lu nonzeros in the upper triangle of K, analyze + factorize %.3f s "
           "(%s, nnz(L) = %.0f, %.3g flops)\n",
           (unsigned long)((int *)kff->p)[n_eq], seconds_since(start),
           chol->factor->is_super ? "supernodal" : "simplicial", chol->common.lnz,
           chol->common.fl);

    /* the contact pair in the host's numbering */
    a_xy = xcalloc(2 * m.n_a, sizeof *a_xy);
    a_eq = xcalloc(2 * m.n_a, sizeof *a_eq);
    b_xy = xcalloc(2 * m.n_b, sizeof *b_xy);
    b_eq = xcalloc(2 * m.n_b, sizeof *b_eq);
    for (k = 0; k < 2 * m.n_a; ++k) {
        a_xy[k] = m.coords[2 * m.a[k / 2] + k % 2];
        a_eq[k] = eq[2 * m.a[k / 2] + k % 2] < 0 ? HYCON_FIXED : eq[2 * m.a[k / 2] + k % 2];
    }
    for (k = 0; k < 2 * m.n_b; ++k) {
        b_xy[k] = m.coords[2 * m.b[k / 2] + k % 2];
        b_eq[k] = eq[2 * m.b[k / 2] + k % 2] < 0 ? HYCON_FIXED : eq[2 * m.b[k / 2] + k % 2];
    }
    CHECK(hycon_contact_options_default(&options));
    options.kinematics = kinematics;

    /* the views of the mesh and of the contact pair, shared by the three paths */
    q4_elements.offsets = m.offsets;
    q4_elements.nodes = m.nodes;
    q4_elements.n_elements = m.n_elements;
    q4_elements.materials = m.materials;
    q4_elements.kind = HYCON_ELEMENT_Q4;
    a_nodes.ids = m.a;
    a_nodes.coords = a_xy;
    a_nodes.equations = a_eq;
    a_nodes.n = m.n_a;
    b_nodes.ids = m.b;
    b_nodes.coords = b_xy;
    b_nodes.equations = b_eq;
    b_nodes.n = m.n_b;
    a_line.nodes = m.a;
    a_line.n = m.n_a;
    b_line.nodes = m.b;
    b_line.n = m.n_b;

    /* path 1: the solve callback (CHOLMOD) */
    CHECK(hycon_host_new(&host_cb, n_eq));
    CHECK(hycon_host_add_pair(host_cb, &a_nodes, &b_nodes, friction, HYCON_PLANE_STRAIN, 1.0,
                              NULL));
    { /* a point inside body A (the block [-2R, 2R] x [-2R, 0]): where the disk touches the
       * block over the whole stretch hycon judges, the polylines alone cannot tell facing
       * surfaces from back-to-back ones (path 2 gives its elements, which tell it instead) */
        const double inside[2] = {0.0, -radius};
        CHECK(hycon_host_set_pair_inside(host_cb, 0, inside));
    }
    CHECK(hycon_host_set_solver(host_cb, cholmod_solve_cb, chol));
    start = now();
    CHECK(hycon_contact_new_host(&c_cb, host_cb, &options));
    cb_setup = seconds_since(start);
    cb_columns[0] = chol->columns;
    hycon_host_free(host_cb); /* the analysis is independent of the description */

    /* path 2: the same K as CSR, factored by hycon. CHOLMOD's upper triangle by columns is the
     * lower triangle by rows. */
    row_ptr = xcalloc(n_eq + 1, sizeof *row_ptr);
    columns = xcalloc((size_t)((int *)kff->p)[n_eq], sizeof *columns);
    for (k = 0; k <= n_eq; ++k) row_ptr[k] = (size_t)((int *)kff->p)[k];
    for (k = 0; k < row_ptr[n_eq]; ++k) columns[k] = (size_t)((int *)kff->i)[k];
    CHECK(hycon_host_new(&host_csr, n_eq));
    CHECK(hycon_host_add_pair(host_csr, &a_nodes, &b_nodes, friction, HYCON_PLANE_STRAIN, 1.0,
                              NULL));
    CHECK(hycon_host_set_csr(host_csr, row_ptr, columns, (const double *)kff->x,
                             HYCON_CSR_LOWER));
    { /* the host's elements (as hycon's Q4), so that hycon also gives the tractions from the
       * element stresses, way (a); here every element, with every node's equations */
        size_t *ids = xcalloc(m.n_nodes, sizeof *ids);
        int64_t *node_eq = xcalloc(2 * m.n_nodes, sizeof *node_eq);
        for (k = 0; k < m.n_nodes; ++k) ids[k] = k;
        for (k = 0; k < 2 * m.n_nodes; ++k) node_eq[k] = eq[k] < 0 ? HYCON_FIXED : eq[k];
        const HyconHostNodes table = {ids, m.coords, node_eq, m.n_nodes};
        CHECK(hycon_host_set_elements(host_csr, &table, &q4_elements, materials, 2));
        free(ids);
        free(node_eq);
    }
    start = now();
    CHECK(hycon_contact_new_host(&c_csr, host_csr, &options));
    csr_setup = seconds_since(start);
    hycon_host_free(host_csr);
    free(row_ptr);
    free(columns);

    /* path 4: the condensed hand-over: the host factors K once more with the contact equations
     * eliminated last (its own CHOLMOD, its own common) and hands over the Schur complement
     * from the factor's trailing block; increments take the load image, the host recovers its
     * displacement from the contact forces, both with that factor */
    cond = xcalloc(1, sizeof *cond);
    cholmod_start(&cond->common);
    cond->n = n_eq;
    CHECK(hycon_host_new(&host_cond, n_eq));
    CHECK(hycon_host_add_pair(host_cond, &a_nodes, &b_nodes, friction, HYCON_PLANE_STRAIN, 1.0,
                              NULL));
    {
        const double inside[2] = {0.0, -radius};
        CHECK(hycon_host_set_pair_inside(host_cond, 0, inside));
    }
    start = now();
    schur_times = hand_over_schur(host_cond, kff, cond, &candidates, &n_cand);
    CHECK(hycon_contact_new_host(&c_cond, host_cond, &options));
    cond_setup = seconds_since(start);
    hycon_host_free(host_cond);
    printf("condensed: %lu candidate equations last; CAMD order %.3f s, analyze_p + "
           "factorize %.3f s (simplicial, nnz(L) = %.0f, %.3g flops), L22 and S = L22 L22^T "
           "%.3f s\n",
           (unsigned long)n_cand, schur_times.order, schur_times.factor, cond->common.lnz,
           cond->common.fl, schur_times.block);

    /* path 3: the model API, HYCON_ELEMENT_Q4 on the same mesh */
    CHECK(hycon_model_new(&model, m.coords, m.n_nodes, &q4_elements, materials, 2));
    CHECK(hycon_model_prescribe(model, m.bottom, m.n_bottom, HYCON_XY));
    CHECK(hycon_model_prescribe(model, m.top, m.n_top, HYCON_XY));
    CHECK(hycon_model_add_pair(model, &a_line, &b_line, friction, NULL));
    CHECK(hycon_contact_new(&c_model, model, &options));
    hycon_model_free(model);
    CHECK(hycon_contact_displacement(c_model, NULL, 0, &n_model_field)); /* the size query */
    if (n_model_field != 2 * m.n_nodes) {
        printf("wrong value: model field length %lu\n", (unsigned long)n_model_field);
        ++failures;
    }

    rhs = xcalloc(n_eq, sizeof *rhs);
    field_host = xcalloc(n_eq, sizeof *field_host);
    field_model = xcalloc(2 * m.n_nodes, sizeof *field_model);
    zero = xcalloc(2 * m.n_nodes, sizeof *zero);
    s_cb.nodes = xcalloc(m.n_a, sizeof *s_cb.nodes);
    s_csr.nodes = xcalloc(m.n_a, sizeof *s_csr.nodes);
    s_model.nodes = xcalloc(m.n_a, sizeof *s_model.nodes);
    s_cb.u = xcalloc(2 * m.n_nodes, sizeof *s_cb.u);
    s_csr.u = xcalloc(2 * m.n_nodes, sizeof *s_csr.u);
    s_model.u = xcalloc(2 * m.n_nodes, sizeof *s_model.u);
    s_cond.nodes = xcalloc(m.n_a, sizeof *s_cond.nodes);
    s_cond.u = xcalloc(2 * m.n_nodes, sizeof *s_cond.u);

    deltas[0] = params.half_width * params.half_width / radius; /* trial approach */
    for (step = 0; step < 2; ++step) {
        HyconIncrementInfo info_cb, info_csr, info_model;
        double delta, load = 0.0, p_target, *qp_now = xcalloc(2 * m.n_nodes, sizeof *qp_now);
        if (step == 1) { /* scale the approach to the Hertz load of the target half-width */
            for (k = 0; k < m.n_a; ++k)
                load -= s_cb.nodes[k].normal[0] * s_cb.nodes[k].force[0] +
                        s_cb.nodes[k].normal[1] * s_cb.nodes[k].force[1];
            p_target = DISK_PI * params.half_width * params.half_width * e_star / (4.0 * radius);
            deltas[1] = deltas[0] * p_target / load;
        }
        delta = deltas[step];
        for (k = 0; k < n_eq; ++k) rhs[k] = delta * rhs_unit[k];
        for (k = 0; k < 2 * m.n_nodes; ++k) qp_now[k] = delta * qp[k];
        printf("increment %lu: approach %.6e\n", (unsigned long)step + 1, delta);
        start = now();
        CHECK(hycon_contact_increment(c_cb, rhs, n_eq, NULL, 0, &info_cb));
        cb_increments += seconds_since(start);
        start = now();
        CHECK(hycon_contact_increment(c_csr, rhs, n_eq, NULL, 0, &info_csr));
        csr_increments += seconds_since(start);
        CHECK(hycon_contact_increment(c_model, zero, 2 * m.n_nodes, qp_now, 2 * m.n_nodes,
                                      &info_model));
        printf("  iterations %lu / %lu / %lu, active nodes %lu / %lu / %lu (callback / CSR / "
               "model)\n",
               (unsigned long)info_cb.iterations, (unsigned long)info_csr.iterations,
               (unsigned long)info_model.iterations, (unsigned long)info_cb.active,
               (unsigned long)info_csr.active, (unsigned long)info_model.active);
        cond_increments += condensed_increment(c_cond, cond, candidates, n_cand, rhs, field_host);
        CHECK(hycon_contact_node_results(c_cond, 0, s_cond.nodes, m.n_a, NULL));
        for (k = 0; k < 2 * m.n_nodes; ++k)
            s_cond.u[k] = eq[k] >= 0 ? field_host[eq[k]] : qp_now[k];
        if (hycon_contact_displacement(c_cond, field_host, n_eq, NULL) !=
            HYCON_ERROR_INVALID_ARGUMENT) {
            printf("wrong value: a condensed analysis has no solver for the displacement\n");
            ++failures;
        }
        start = now(); /* the displacement of the callback and CSR paths: recovered on request */
        snapshot(c_cb, &m, eq, qp_now, field_host, n_eq, &s_cb);
        cb_increments += seconds_since(start);
        start = now();
        snapshot(c_csr, &m, eq, qp_now, field_host, n_eq, &s_csr);
        csr_increments += seconds_since(start);
        snapshot(c_model, &m, NULL, qp_now, field_model, 2 * m.n_nodes, &s_model);
        printf("  differences from the model API:\n");
        failures += compare("callback (CHOLMOD)", &m, &s_cb, &s_model, tolerance);
        failures += compare("CSR (hycon factors)", &m, &s_csr, &s_model, tolerance);
        printf("  differences from the CSR path:\n");
        failures += compare("condensed (CHOLMOD S)", &m, &s_cond, &s_csr, 1e-8);
        failures += compare("callback (CHOLMOD)", &m, &s_cb, &s_csr, 1e-8);
        { /* way (a), tractions from element stresses: the CSR host (its elements handed over)
           * against the model API */
            double *ta = xcalloc(2 * m.n_a, sizeof *ta), *tb = xcalloc(2 * m.n_a, sizeof *tb);
            double peak = 0.0, diff = 0.0;
            CHECK(hycon_contact_stress_tractions(c_csr, 0, ta, 2 * m.n_a, NULL));
            CHECK(hycon_contact_stress_tractions(c_model, 0, tb, 2 * m.n_a, NULL));
            for (k = 0; k < 2 * m.n_a; ++k) {
                peak = fmax(peak, fabs(tb[k]));
                diff = fmax(diff, fabs(ta[k] - tb[k]));
            }
            printf("    element-stress tractions (CSR host with its elements): %.1e of the peak\n",
                   peak > 0.0 ? diff / peak : 1.0);
            if (!(peak > 0.0) || diff > tolerance * peak) {
                printf("wrong value: element-stress tractions of the host differ from the "
                       "model's\n");
                ++failures;
            }
            free(ta);
            free(tb);
        }
        {
            /* Hertz, for information: Q4 on this mesh, multipliers and B side */
            HyconBNodeResult *bn = xcalloc(m.n_b, sizeof *bn);
            double *x = xcalloc(m.n_a + m.n_b, sizeof *x), *p = xcalloc(m.n_a + m.n_b, sizeof *p);
            double wsum = 0.0, wx = 0.0, centre;
            HertzFit fa, fb;
            load = 0.0;
            for (k = 0; k < m.n_a; ++k) {
                const HyconNodeResult *r = &s_cb.nodes[k];
                load -= r->normal[0] * r->force[0] + r->normal[1] * r->force[1];
                wsum -= r->tn * r->weight;
                wx -= r->tn * r->weight * r->position[0];
            }
            centre = wx / wsum;
            for (k = 0; k < m.n_a; ++k) {
                x[k] = s_cb.nodes[k].position[0] - centre;
                p[k] = -s_cb.nodes[k].tn;
            }
            fa = hertz_compare(x, p, m.n_a, load, radius, e_star);
            CHECK(hycon_contact_b_node_results(c_cb, 0, bn, m.n_b, NULL));
            for (k = 0; k < m.n_b; ++k) {
                x[k] = m.coords[2 * bn[k].node] + s_cb.u[2 * bn[k].node] - centre;
                p[k] = bn[k].pressure;
            }
            fb = hertz_compare(x, p, m.n_b, load, radius, e_star);
            printf("  Hertz at the contact load P = %.6e (information; Q4): a = %.6e (a/h = "
                   "%.2f), p0 = %.6e\n",
                   load, fa.a, fa.a / m.h, fa.p0);
            hertz_print("multipliers (A nodes)", &fa);
            hertz_print("B side (disk nodes)", &fb);
            free(bn);
            free(x);
            free(p);
        }
        free(qp_now);
    }

    cb_columns[1] = chol->columns - cb_columns[0];

    /* a failing solve: the increment fails with HYCON_ERROR_CALLBACK, the state is kept */
    {
        HyconNodeResult *before = xcalloc(m.n_a, sizeof *before);
        char message[256];
        HyconStatus status;
        CHECK(hycon_contact_node_results(c_cb, 0, before, m.n_a, NULL));
        /* a load that is not a combination of earlier ones (those hycon answers without a
         * solve): 10 % more approach and a small force at equation 0, in the block */
        for (k = 0; k < n_eq; ++k) rhs[k] = 1.1 * deltas[1] * rhs_unit[k];
        rhs[0] += 1e-6 * fabs(rhs[n_eq - 1]) + 1e-12;
        chol->fail_next = 1;
        status = hycon_contact_increment(c_cb, rhs, n_eq, NULL, 0, NULL);
        hycon_last_error_message(message, sizeof message);
        printf("a solve that fails (returns 4): %s, \"%s\"\n", hycon_status_name(status),
               message);
        CHECK(hycon_contact_node_results(c_cb, 0, s_cb.nodes, m.n_a, NULL));
        if (status != HYCON_ERROR_CALLBACK ||
            memcmp(before, s_cb.nodes, m.n_a * sizeof *before) != 0) {
            printf("wrong value: a failing solve must give HYCON_ERROR_CALLBACK and keep the "
                   "converged state\n");
            ++failures;
        }
        /* and the analysis goes on from there */
        CHECK(hycon_contact_increment(c_cb, rhs, n_eq, NULL, 0, NULL));
        free(before);
    }

    printf("solve callback: %lu calls, %lu right-hand sides (at most %lu per call), %.3f s in "
           "CHOLMOD solves\n",
           (unsigned long)chol->calls, (unsigned long)chol->columns,
           (unsigned long)chol->max_nrhs, chol->seconds);
    if (chol->max_nrhs < 2 || chol->failures != 0) {
        printf("wrong value: the callback never got several right-hand sides at once, or "
               "failed\n");
        ++failures;
    }
    printf("timings:\n");
    print_timings("callback", c_cb, 0, &failures);
    print_timings("CSR", c_csr, 1, &failures);
    print_timings("model", c_model, 1, &failures);
    print_timings("condensed", c_cond, 0, &failures);
    printf("  condensed: the host's Schur complement %.3f s (order %.3f, factor %.3f, S %.3f)\n",
           schur_times.order + schur_times.factor + schur_times.block, schur_times.order,
           schur_times.factor, schur_times.block);
    printf("wall clock: CSR path setup %.3f s (hycon's factorization) + 2 increments %.3f s "
           "(with the displacement) = %.3f s; condensed path setup %.3f s (the host's Schur "
           "complement) + 2 increments %.3f s (with the host's load and recovery solves) = "
           "%.3f s: %.2fx the CSR path; callback path setup %.3f s (after the host's "
           "factorization; %lu right-hand sides) + 2 increments %.3f s (with the displacement; "
           "%lu right-hand sides) = %.3f s\n",
           csr_setup, csr_increments, csr_setup + csr_increments, cond_setup, cond_increments,
           cond_setup + cond_increments,
           (cond_setup + cond_increments) / (csr_setup + csr_increments), cb_setup,
           (unsigned long)cb_columns[0], cb_increments, (unsigned long)cb_columns[1],
           cb_setup + cb_increments);

    hycon_contact_free(c_cb);
    hycon_contact_free(c_csr);
    hycon_contact_free(c_model);
    hycon_contact_free(c_cond);
    free(candidates);
    free(s_cond.nodes);
    free(s_cond.u);
    cholmod_free_factor(&cond->factor, &cond->common);
    cholmod_finish(&cond->common);
    free(cond);
    cholmod_free_factor(&chol->factor, &chol->common);
    cholmod_free_sparse(&kff, &chol->common);
    cholmod_finish(&chol->common);
    free(chol);
    free(eq);
    free(a_eq);
    free(b_eq);
    free(a_xy);
    free(b_xy);
    free(rhs_unit);
    free(rhs);
    free(qp);
    free(field_host);
    free(field_model);
    free(zero);
    free(s_cb.nodes);
    free(s_csr.nodes);
    free(s_model.nodes);
    free(s_cb.u);
    free(s_csr.u);
    free(s_model.u);
    disk_mesh_free(&m);
    if (failures != 0) {
        printf("FAILED: %d check(s)\n", failures);
        return EXIT_FAILURE;
    }
    printf("OK\n");
    return EXIT_SUCCESS;
}
