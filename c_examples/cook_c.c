/* Cook's membrane solved by a tiny host finite-element code in strict C99 that takes only the
 * element stiffness matrices from hycon.
 *
 * Geometry: the bilinear map of the unit square onto the quadrilateral with corners (0,0),
 * (48,44), (48,60), (0,44), meshed n x n. E = 1, nu = 1/3, t = 1, plane stress. Clamped at
 * x = 0; a total vertical shear of 1 uniformly distributed on the edge x = 48 (consistent nodal
 * forces). The host assembles a dense matrix of the free dofs, factors it with its own Cholesky,
 * and checks the vertical displacement at (48, 52) against the published values.
 *
 * Usage: cook_c [max_n]   (meshes 2, 4, 8, 16 up to max_n; default 16). Prints OK on success.
 */
#include "hycon.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Print the failing call with hycon's last error message and stop. */
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

/* Node (i, j) of the (n+1) x (n+1) grid; i runs along x (xi), j along the height (eta). */
static size_t node_id(size_t n, size_t i, size_t j) { return j * (n + 1) + i; }

static void node_xy(size_t n, size_t i, size_t j, double *x, double *y) {
    double xi = (double)i / (double)n, eta = (double)j / (double)n;
    *x = 48.0 * xi;
    *y = 44.0 * xi * (1.0 - eta) + 60.0 * xi * eta + 44.0 * (1.0 - xi) * eta;
}

/* In-place Cholesky A = L L^T of a dense row-major SPD matrix (lower triangle used). */
static int cholesky(double *a, size_t m) {
    size_t i, j, k;
    for (j = 0; j < m; ++j) {
        double d = a[j * m + j];
        for (k = 0; k < j; ++k) d -= a[j * m + k] * a[j * m + k];
        if (!(d > 0.0)) return -1;
        d = sqrt(d);
        a[j * m + j] = d;
        for (i = j + 1; i < m; ++i) {
            double s = a[i * m + j];
            for (k = 0; k < j; ++k) s -= a[i * m + k] * a[j * m + k];
            a[i * m + j] = s / d;
        }
    }
    return 0;
}

static void cholesky_solve(const double *l, size_t m, double *b) {
    size_t i, k;
    for (i = 0; i < m; ++i) { /* L y = b */
        double s = b[i];
        for (k = 0; k < i; ++k) s -= l[i * m + k] * b[k];
        b[i] = s / l[i * m + i];
    }
    for (i = m; i-- > 0;) { /* L^T x = y */
        double s = b[i];
        for (k = i + 1; k < m; ++k) s -= l[k * m + i] * b[k];
        b[i] = s / l[i * m + i];
    }
}

/* Vertical displacement at (48, 52) of the n x n Cook's membrane (n even), or NaN. */
static double cook_tip(HyconElementKind kind, size_t n) {
    const HyconMaterial material = {1.0, 1.0 / 3.0, 1.0, HYCON_PLANE_STRESS};
    size_t n_nodes = (n + 1) * (n + 1), n_free = 0, i, j, a, b;
    long *eq = malloc(2 * n_nodes * sizeof *eq); /* dof -> equation, -1 if clamped */
    double *k = NULL, *f = NULL, tip = NAN;
    if (eq == NULL) return NAN;
    for (j = 0; j <= n; ++j)
        for (i = 0; i <= n; ++i)
            for (a = 0; a < 2; ++a)
                eq[2 * node_id(n, i, j) + a] = i == 0 ? -1 : (long)n_free++;
    k = calloc(n_free * n_free, sizeof *k);
    f = calloc(n_free, sizeof *f);
    if (k == NULL || f == NULL) goto done;

    for (j = 0; j < n; ++j) {
        for (i = 0; i < n; ++i) {
            /* counter-clockwise: (i,j), (i+1,j), (i+1,j+1), (i,j+1) */
            const size_t nodes[4] = {node_id(n, i, j), node_id(n, i + 1, j),
                                     node_id(n, i + 1, j + 1), node_id(n, i, j + 1)};
            const size_t gi[4] = {i, i + 1, i + 1, i}, gj[4] = {j, j, j + 1, j + 1};
            double coords[8], ke[64];
            for (a = 0; a < 4; ++a) node_xy(n, gi[a], gj[a], &coords[2 * a], &coords[2 * a + 1]);
            CHECK(hycon_element_stiffness(kind, 4, coords, &material, ke, 64));
            for (a = 0; a < 8; ++a) {
                long ra = eq[2 * nodes[a / 2] + a % 2];
                if (ra < 0) continue;
                for (b = 0; b < 8; ++b) {
                    long rb = eq[2 * nodes[b / 2] + b % 2];
                    if (rb >= 0) k[(size_t)ra * n_free + (size_t)rb] += ke[a * 8 + b];
                }
            }
        }
    }
    /* total shear 1 on x = 48: each of the n edge segments carries 1/n, half to each end */
    for (j = 0; j < n; ++j) {
        f[eq[2 * node_id(n, n, j) + 1]] += 0.5 / (double)n;
        f[eq[2 * node_id(n, n, j + 1) + 1]] += 0.5 / (double)n;
    }
    if (cholesky(k, n_free) != 0) {
        fprintf(stderr, "stiffness not positive definite (n = %d)\n", (int)n);
        goto done;
    }
    cholesky_solve(k, n_free, f);
    tip = f[eq[2 * node_id(n, n, n / 2) + 1]];
done:
    free(eq);
    free(k);
    free(f);
    return tip;
}

int main(int argc, char **argv) {
    /* published v(48, 52): n, Q4, Pian-Sumihara */
    static const struct {
        size_t n;
        double q4, ps;
    } published[4] = {{2, 11.845, 21.129}, {4, 18.299, 23.022}, {8, 22.079, 23.689},
                      {16, 23.430, 23.883}};
    const double converged = 23.96, rel_tol = 5e-4;
    size_t max_n = argc > 1 ? (size_t)strtoul(argv[1], NULL, 10) : 16, r;
    int failures = 0;

    printf("%4s %10s %10s %10s\n", "n", "Q4", "P-S", "hybrid");
    for (r = 0; r < 4 && published[r].n <= max_n; ++r) {
        size_t n = published[r].n;
        double q4 = cook_tip(HYCON_ELEMENT_Q4, n);
        double ps = cook_tip(HYCON_ELEMENT_PIAN_SUMIHARA, n);
        double hy = cook_tip(HYCON_ELEMENT_HYBRID, n);
        printf("%4d %10.4f %10.4f %10.4f\n", (int)n, q4, ps, hy);
        if (!(fabs(q4 / published[r].q4 - 1.0) < rel_tol)) {
            fprintf(stderr, "Q4 %dx%d: %.5f, published %.3f\n", (int)n, (int)n, q4,
                    published[r].q4);
            ++failures;
        }
        if (!(fabs(ps / published[r].ps - 1.0) < rel_tol)) {
            fprintf(stderr, "Pian-Sumihara %dx%d: %.5f, published %.3f\n", (int)n, (int)n, ps,
                    published[r].ps);
            ++failures;
        }
        /* the 7-beta hybrid element is softer than Q4 and stiffer than Pian-Sumihara here */
        if (!(hy > q4 && hy < ps)) {
            fprintf(stderr, "hybrid %dx%d: %.5f is not between Q4 and Pian-Sumihara\n", (int)n,
                    (int)n, hy);
            ++failures;
        }
        if (n == 16 && !(fabs(hy / converged - 1.0) < 0.02)) {
            fprintf(stderr, "hybrid 16x16: %.5f is not within 2%% of %.2f\n", hy, converged);
            ++failures;
        }
    }
    if (failures != 0) {
        fprintf(stderr, "%d wrong value(s)\n", failures);
        return EXIT_FAILURE;
    }
    printf("OK\n");
    return EXIT_SUCCESS;
}
