/* A 3D cantilever solved by a tiny host finite-element code in strict C99 that takes only the
 * brick stiffness matrices (and the stress recovery) from hycon.
 *
 * Geometry: the beam [0, 10] x [0, 1] x [0, 1], n x 2 x 2 bricks, E = 1000, nu = 0.3. Clamped at
 * x = 0; a total shear force of 1 along y, uniform over the tip face x = 10 (consistent nodal
 * forces: a quarter of each tip brick face's force at each of its nodes). The host assembles the
 * free dofs into a CSR matrix (both triangles), solves it with its own Jacobi-preconditioned
 * conjugate gradients and checks the mean tip deflection against Timoshenko's beam,
 * P L^3 / (3 E I) + P L / (k G A) = 4.031 (the clamped root of a 3D solid is a little stiffer).
 * It does so for the hybrid brick and the displacement brick: the H8 locks in bending.
 * The tip face tractions recovered by hycon_brick_face_traction must carry the load.
 *
 * Built with HYCON_EXAMPLE_CHOLMOD defined (the target brick_cantilever_cholmod, where SuiteSparse
 * is present), the host factors the same CSR matrix with CHOLMOD instead (a symmetric
 * cholmod_sparse over the CSR arrays, cholmod_analyze, cholmod_factorize, cholmod_solve) and checks
 * the direct solution against its conjugate gradients to 1e-8.
 *
 * Usage: brick_cantilever [n]   (bricks along the beam; default 10: within 3% of Timoshenko;
 * coarser meshes within 10%). Prints OK on success.
 */
#include "hycon.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef HYCON_EXAMPLE_CHOLMOD
#include <cholmod.h>
#endif

static void report_failure(const char *call, HyconStatus status, const char *file, int line) {
    char message[512];
    size_t needed = hycon_last_error_message(message, sizeof message);
    fprintf(stderr, "%s:%d: %s returned %s (%d): %s%s\n", file, line, call,
            hycon_status_name(status), (int)status, message,
            needed > sizeof message ? " [truncated]" : "");
    exit(EXIT_FAILURE);
}

#define CHECK(call)                                                                            \
    do {                                                                                       \
        HyconStatus check_status_ = (call);                                                    \
        if (check_status_ != HYCON_OK) report_failure(#call, check_status_, __FILE__, __LINE__); \
    } while (0)

#define NY 2
#define NZ 2
#define LENGTH 10.0

typedef struct {
    size_t n;          /* bricks along x */
    size_t n_nodes;
    size_t n_bricks;
    double *xyz;       /* 3 per node */
    size_t *bricks;    /* 8 per brick, hycon's brick node order */
} Mesh;

static size_t node_id(const Mesh *m, size_t i, size_t j, size_t k) {
    return i + (m->n + 1) * (j + (NY + 1) * k);
}

static Mesh make_mesh(size_t n) {
    Mesh m;
    size_t i, j, k, e = 0;
    m.n = n;
    m.n_nodes = (n + 1) * (NY + 1) * (NZ + 1);
    m.n_bricks = n * NY * NZ;
    m.xyz = malloc(3 * m.n_nodes * sizeof *m.xyz);
    m.bricks = malloc(8 * m.n_bricks * sizeof *m.bricks);
    if (!m.xyz || !m.bricks) exit(EXIT_FAILURE);
    for (k = 0; k <= NZ; ++k)
        for (j = 0; j <= NY; ++j)
            for (i = 0; i <= n; ++i) {
                size_t id = node_id(&m, i, j, k);
                m.xyz[3 * id] = LENGTH * (double)i / (double)n;
                m.xyz[3 * id + 1] = (double)j / NY;
                m.xyz[3 * id + 2] = (double)k / NZ;
            }
    for (k = 0; k < NZ; ++k)
        for (j = 0; j < NY; ++j)
            for (i = 0; i < n; ++i, ++e) {
                size_t *b = m.bricks + 8 * e, c;
                b[0] = node_id(&m, i, j, k);
                b[1] = node_id(&m, i + 1, j, k);
                b[2] = node_id(&m, i + 1, j + 1, k);
                b[3] = node_id(&m, i, j + 1, k);
                for (c = 0; c < 4; ++c) b[4 + c] = b[c] + (n + 1) * (NY + 1);
            }
    return m;
}

/* CSR matrix of the free dofs: equation[d] is the free index of global dof d, or -1. */
typedef struct {
    size_t n;
    size_t *row_ptr;
    size_t *col;
    double *val;
} Csr;

static int cmp_size(const void *a, const void *b) {
    size_t x = *(const size_t *)a, y = *(const size_t *)b;
    return (x > y) - (x < y);
}

/* The pattern: free dofs coupled when their nodes share a brick (at most 27 nodes x 3). */
static Csr csr_pattern(const Mesh *m, const long *equation, size_t n_free) {
    Csr a;
    size_t e, r, nnz = 0, max_per_row = 81;
    size_t *rows = malloc(n_free * max_per_row * sizeof *rows);
    size_t *count = calloc(n_free, sizeof *count);
    if (!rows || !count) exit(EXIT_FAILURE);
    for (e = 0; e < m->n_bricks; ++e) {
        size_t p, q, dp, dq;
        for (p = 0; p < 8; ++p)
            for (dp = 0; dp < 3; ++dp) {
                long row = equation[3 * m->bricks[8 * e + p] + dp];
                if (row < 0) continue;
                for (q = 0; q < 8; ++q)
                    for (dq = 0; dq < 3; ++dq) {
                        long col = equation[3 * m->bricks[8 * e + q] + dq];
                        size_t c, *list = rows + (size_t)row * max_per_row, seen = 0;
                        if (col < 0) continue;
                        for (c = 0; c < count[row]; ++c)
                            if (list[c] == (size_t)col) seen = 1;
                        if (!seen) list[count[row]++] = (size_t)col;
                    }
            }
    }
    a.n = n_free;
    a.row_ptr = malloc((n_free + 1) * sizeof *a.row_ptr);
    if (!a.row_ptr) exit(EXIT_FAILURE);
    a.row_ptr[0] = 0;
    for (r = 0; r < n_free; ++r) {
        qsort(rows + r * max_per_row, count[r], sizeof *rows, cmp_size);
        nnz += count[r];
        a.row_ptr[r + 1] = nnz;
    }
    a.col = malloc(nnz * sizeof *a.col);
    a.val = calloc(nnz, sizeof *a.val);
    if (!a.col || !a.val) exit(EXIT_FAILURE);
    for (r = 0; r < n_free; ++r)
        memcpy(a.col + a.row_ptr[r], rows + r * max_per_row, count[r] * sizeof *rows);
    free(rows);
    free(count);
    return a;
}

static double *csr_entry(Csr *a, size_t row, size_t col) {
    size_t lo = a->row_ptr[row], hi = a->row_ptr[row + 1];
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        if (a->col[mid] < col) lo = mid + 1;
        else hi = mid;
    }
    return a->val + lo;
}

static void brick_coords(const Mesh *m, size_t e, double out[24]) {
    size_t c;
    for (c = 0; c < 8; ++c) memcpy(out + 3 * c, m->xyz + 3 * m->bricks[8 * e + c], 3 * sizeof *out);
}

static void csr_multiply(const Csr *a, const double *x, double *y) {
    size_t r, p;
    for (r = 0; r < a->n; ++r) {
        double s = 0.0;
        for (p = a->row_ptr[r]; p < a->row_ptr[r + 1]; ++p) s += a->val[p] * x[a->col[p]];
        y[r] = s;
    }
}

/* Jacobi-preconditioned conjugate gradients, relative residual 1e-12. */
static void solve_cg(const Csr *a, const double *b, double *x) {
    size_t n = a->n, i, it;
    double *r = malloc(n * sizeof *r), *z = malloc(n * sizeof *z), *p = malloc(n * sizeof *p),
           *q = malloc(n * sizeof *q), *dinv = malloc(n * sizeof *dinv);
    double rz = 0.0, bnorm = 0.0;
    if (!r || !z || !p || !q || !dinv) exit(EXIT_FAILURE);
    for (i = 0; i < n; ++i) {
        dinv[i] = 1.0 / *csr_entry((Csr *)a, i, i);
        x[i] = 0.0;
        r[i] = b[i];
        z[i] = dinv[i] * r[i];
        p[i] = z[i];
        rz += r[i] * z[i];
        bnorm += b[i] * b[i];
    }
    for (it = 0; it < 20 * n; ++it) {
        double pq = 0.0, alpha, rz_new = 0.0, rnorm = 0.0;
        csr_multiply(a, p, q);
        for (i = 0; i < n; ++i) pq += p[i] * q[i];
        alpha = rz / pq;
        for (i = 0; i < n; ++i) {
            x[i] += alpha * p[i];
            r[i] -= alpha * q[i];
            rnorm += r[i] * r[i];
        }
        if (rnorm <= 1e-24 * bnorm) break;
        for (i = 0; i < n; ++i) {
            z[i] = dinv[i] * r[i];
            rz_new += r[i] * z[i];
        }
        for (i = 0; i < n; ++i) p[i] = z[i] + rz_new / rz * p[i];
        rz = rz_new;
    }
    free(r);
    free(z);
    free(p);
    free(q);
    free(dinv);
}

#ifdef HYCON_EXAMPLE_CHOLMOD
/* The same system factored by CHOLMOD: the CSR arrays (both triangles) are those of the
 * compressed columns of the symmetric matrix, and stype = 1 reads the upper triangle. */
static void solve_cholmod(const Csr *a, const double *b, double *x) {
    cholmod_common common;
    cholmod_sparse *k;
    cholmod_factor *factor;
    cholmod_dense *rhs, *sol;
    size_t i, nnz = a->row_ptr[a->n];
    int ok = 1;
    cholmod_start(&common);
    k = cholmod_allocate_sparse(a->n, a->n, nnz, 1, 1, 1, CHOLMOD_REAL, &common);
    rhs = cholmod_allocate_dense(a->n, 1, a->n, CHOLMOD_REAL, &common);
    if (!k || !rhs) {
        printf("FAILED: CHOLMOD allocation (status %d)\n", common.status);
        exit(EXIT_FAILURE);
    }
    for (i = 0; i <= a->n; ++i) ((int *)k->p)[i] = (int)a->row_ptr[i];
    for (i = 0; i < nnz; ++i) {
        ((int *)k->i)[i] = (int)a->col[i];
        ((double *)k->x)[i] = a->val[i];
    }
    memcpy(rhs->x, b, a->n * sizeof *b);
    factor = cholmod_analyze(k, &common);
    if (!factor || !cholmod_factorize(k, factor, &common) || common.status != CHOLMOD_OK)
        ok = 0;
    sol = ok ? cholmod_solve(CHOLMOD_A, factor, rhs, &common) : NULL;
    if (!sol) {
        printf("FAILED: CHOLMOD factorization or solve (status %d)\n", common.status);
        exit(EXIT_FAILURE);
    }
    memcpy(x, sol->x, a->n * sizeof *x);
    cholmod_free_dense(&sol, &common);
    cholmod_free_dense(&rhs, &common);
    cholmod_free_factor(&factor, &common);
    cholmod_free_sparse(&k, &common);
    cholmod_finish(&common);
}
#endif

/* Solve the cantilever with one brick kind; returns the mean tip deflection v and writes the
 * total tip-face traction force (y) recovered from the element stresses. */
static double cantilever(const Mesh *m, HyconBrickKind kind, double *tip_force) {
    const HyconSolidMaterial material = {1000.0, 0.3};
    long *equation = malloc(3 * m->n_nodes * sizeof *equation);
    size_t d, e, n_free = 0, tip_nodes = 0;
    double *f, *u, *full, sum_v = 0.0, k[576], x[24];
    Csr a;
    if (!equation) exit(EXIT_FAILURE);
    for (d = 0; d < 3 * m->n_nodes; ++d)
        equation[d] = m->xyz[3 * (d / 3)] == 0.0 ? -1 : (long)n_free++;
    a = csr_pattern(m, equation, n_free);
    f = calloc(n_free, sizeof *f);
    u = calloc(n_free, sizeof *u);
    full = calloc(3 * m->n_nodes, sizeof *full);
    if (!f || !u || !full) exit(EXIT_FAILURE);
    for (e = 0; e < m->n_bricks; ++e) {
        size_t p, q;
        brick_coords(m, e, x);
        CHECK(hycon_brick_check(kind, x));
        CHECK(hycon_brick_stiffness(kind, x, &material, k, 576));
        for (p = 0; p < 24; ++p) {
            long row = equation[3 * m->bricks[8 * e + p / 3] + p % 3];
            if (row < 0) continue;
            for (q = 0; q < 24; ++q) {
                long col = equation[3 * m->bricks[8 * e + q / 3] + q % 3];
                if (col >= 0) *csr_entry(&a, (size_t)row, (size_t)col) += k[p * 24 + q];
            }
        }
    }
    /* tip: brick face 1 (xi = +1: nodes 1 2 6 5) of the last brick of each row, area 1/4 */
    for (e = 0; e < m->n_bricks; ++e) {
        static const size_t face1[4] = {1, 2, 6, 5};
        size_t c;
        if (e % m->n != m->n - 1) continue;
        for (c = 0; c < 4; ++c) f[equation[3 * m->bricks[8 * e + face1[c]] + 1]] += 0.25 / 4.0;
    }
#ifdef HYCON_EXAMPLE_CHOLMOD
    {
        double *u_cg = calloc(n_free, sizeof *u_cg), diff = 0.0, size = 0.0;
        if (!u_cg) exit(EXIT_FAILURE);
        solve_cholmod(&a, f, u);
        solve_cg(&a, f, u_cg);
        for (d = 0; d < n_free; ++d) {
            diff = fmax(diff, fabs(u[d] - u_cg[d]));
            size = fmax(size, fabs(u[d]));
        }
        free(u_cg);
        if (!(diff <= 1e-8 * size)) {
            printf("wrong value: CHOLMOD and CG differ by %g (of %g)\n", diff, size);
            exit(EXIT_FAILURE);
        }
    }
#else
    solve_cg(&a, f, u);
#endif
    for (d = 0; d < 3 * m->n_nodes; ++d) full[d] = equation[d] < 0 ? 0.0 : u[equation[d]];
    for (d = 0; d < m->n_nodes; ++d)
        if (m->xyz[3 * d] == LENGTH) {
            sum_v += full[3 * d + 1];
            ++tip_nodes;
        }
    /* the load carried by the recovered tractions on the tip faces (2x2 Gauss per face) */
    *tip_force = 0.0;
    for (e = 0; e < m->n_bricks; ++e) {
        double q[24], t[3], beta[HYCON_BRICK_MAX_BETA], s[6];
        size_t c, g, needed = 0;
        if (e % m->n != m->n - 1) continue;
        brick_coords(m, e, x);
        for (c = 0; c < 8; ++c) memcpy(q + 3 * c, full + 3 * m->bricks[8 * e + c], 3 * sizeof *q);
        for (g = 0; g < 4; ++g) {
            double gs = (g & 1 ? 1.0 : -1.0) / sqrt(3.0), gt = (g & 2 ? 1.0 : -1.0) / sqrt(3.0);
            CHECK(hycon_brick_face_traction(kind, x, &material, q, 1, gs, gt, t));
            *tip_force += t[1] * 0.25 / 4.0;
        }
        CHECK(hycon_brick_stress_params(kind, x, &material, q, beta, HYCON_BRICK_MAX_BETA,
                                        &needed));
        if (needed != (kind == HYCON_BRICK_HYBRID18 ? 18u : 0u)) {
            printf("wrong value: %zu stress parameters\n", needed);
            exit(EXIT_FAILURE);
        }
        CHECK(hycon_brick_stress(kind, x, &material, q, 9.9, 0.5, 0.5, s));
    }
    free(equation);
    free(f);
    free(u);
    free(full);
    free(a.row_ptr);
    free(a.col);
    free(a.val);
    return sum_v / (double)tip_nodes;
}

int main(int argc, char **argv) {
    size_t n = argc > 1 ? (size_t)strtoul(argv[1], NULL, 10) : 10;
    const double timoshenko = 4.0 + 10.0 / (5.0 / 6.0 * 1000.0 / 2.6);
    double force_h, force_8, hybrid, h8;
    Mesh m;
    if (n < 2 || n > 200) {
        fprintf(stderr, "usage: brick_cantilever [n in 2..200]\n");
        return EXIT_FAILURE;
    }
    m = make_mesh(n);
    hybrid = cantilever(&m, HYCON_BRICK_HYBRID18, &force_h);
    h8 = cantilever(&m, HYCON_BRICK_H8, &force_8);
#ifdef HYCON_EXAMPLE_CHOLMOD
    printf("CHOLMOD: ");
#endif
    printf("%zu x %d x %d bricks: tip deflection / Timoshenko: hybrid18 %.4f, h8 %.4f; "
           "tip traction force (of 1): hybrid18 %.4f, h8 %.4f\n",
           n, NY, NZ, hybrid / timoshenko, h8 / timoshenko, force_h, force_8);
    free(m.xyz);
    free(m.bricks);
    /* 3% from 10 bricks along the beam (aspect 2), 10% on coarser meshes */
    if (fabs(hybrid / timoshenko - 1.0) > (n >= 10 ? 0.03 : 0.10)) {
        printf("wrong value: hybrid tip deflection\n");
        return EXIT_FAILURE;
    }
    if (h8 > 0.9 * hybrid) {
        printf("wrong value: the H8 should lock\n");
        return EXIT_FAILURE;
    }
    if (fabs(force_h - 1.0) > 0.05) {
        printf("wrong value: hybrid tip traction force\n");
        return EXIT_FAILURE;
    }
    printf("OK\n");
    return EXIT_SUCCESS;
}
