/* A 3D host FE code in C99 running hycon's contact iteration through the 3D host API
 * (hycon_solid_host_*, hycon_solid_contact_new_host): its own bricks, its own equation
 * numbering, its own dense Cholesky solver.
 *
 * The problem is the contact patch test of a stack: a unit cube of 2 x 2 bricks (body A, its
 * bottom face the multiplier side) on a unit cube of 3 x 3 bricks (body B, its top face), the
 * faces non-conforming over the same footprint [-0.5, 0.5]^2 at z = 0; E = 1, nu = 0.3. A's top
 * is moved down by d (prescribed), B's bottom held along z; each body held in its plane by a
 * corner of that face (x and y) and the next corner along x (y), which the lateral expansion
 * leaves at rest. The stack is then in uniaxial stress p = E d / 2 (two unit heights), which
 * the hybrid bricks and the mortar integrals of non-conforming faces represent exactly: every
 * A node's multiplier is tn = -p, its tangential traction 0, stick (friction 0.3), and the
 * nodal forces on A sum to p times the unit area.
 *
 * The host
 *   - numbers the free dofs itself (the prescribed ones eliminated), assembles K from
 *     hycon_brick_stiffness (HYCON_BRICK_HYBRID18) and the right-hand side of its prescribed
 *     displacements, rhs = -K_fp u_p;
 *   - describes its contact nodes (ids, coordinates, 3 equations each:
 *     hycon_solid_host_add_nodes) and the pair's faces as 4 node ids each
 *     (hycon_solid_host_add_pair), with a point inside body A (the faces touch everywhere, so
 *     their order alone cannot tell facing surfaces from back-to-back ones);
 *   - runs the increment twice: with K as an upper-triangle CSR factored by hycon
 *     (hycon_solid_host_set_csr), and with a solve callback on its own dense Cholesky factor
 *     (hycon_solid_host_set_solver).
 * Checked: the closed form above to 1e-9 of p on both paths, the two paths' tractions and
 * displacements alike to 1e-10 (round-off of two factorizations), and A's bottom moved by
 * -d/2 in the displacement handed back (over the host's equations). Prints OK on success; "wrong value" and
 * exit code 1 otherwise.
 */
#include <hycon.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NA 2 /* bricks per side of A */
#define NB 3 /* bricks per side of B */
#define A_NODES ((NA + 1) * (NA + 1) * 2)
#define B_NODES ((NB + 1) * (NB + 1) * 2)
#define N_NODES (A_NODES + B_NODES)
#define N_DOFS (3 * N_NODES)
#define MAX_FACES (NB * NB)

static const double D = 1e-3;      /* the press */
static const double FRICTION = 0.3;

static int failures = 0;

static void check(int ok, const char *what, double got, double expected) {
    if (!ok) {
        printf("wrong value: %s = %.17g (expected %.17g)\n", what, got, expected);
        ++failures;
    }
}

static void must(HyconStatus s, const char *call) {
    if (s != HYCON_OK) {
        char message[512];
        hycon_last_error_message(message, sizeof message);
        printf("FAILED: %s: %s (%s)\n", call, hycon_status_name(s), message);
        exit(1);
    }
}

/* ------------------------------------------------------------------------------------------ */
/* The host's mesh: two bodies of n x n x 1 bricks over [-0.5, 0.5]^2 */

/* Node (i, j, k) of a body of n bricks per side whose ids start at `first`. */
static size_t node(size_t first, size_t n, size_t i, size_t j, size_t k) {
    return first + (k * (n + 1) + j) * (n + 1) + i;
}

static double coords[N_NODES][3];

/* The nodes of a body of n bricks per side from z0 to z0 + 1. */
static void place(size_t first, size_t n, double z0) {
    size_t i, j, k;
    for (k = 0; k < 2; ++k)
        for (j = 0; j <= n; ++j)
            for (i = 0; i <= n; ++i) {
                double *x = coords[node(first, n, i, j, k)];
                x[0] = -0.5 + (double)i / (double)n;
                x[1] = -0.5 + (double)j / (double)n;
                x[2] = z0 + (double)k;
            }
}

/* The 8 nodes of brick (i, j) of a body, in the brick node order: 0-3 counter-clockwise at
 * its bottom seen from its top, 4-7 above them. */
static void brick(size_t first, size_t n, size_t i, size_t j, size_t out[8]) {
    size_t k;
    for (k = 0; k < 2; ++k) {
        out[4 * k + 0] = node(first, n, i, j, k);
        out[4 * k + 1] = node(first, n, i + 1, j, k);
        out[4 * k + 2] = node(first, n, i + 1, j + 1, k);
        out[4 * k + 3] = node(first, n, i, j + 1, k);
    }
}

/* ------------------------------------------------------------------------------------------ */
/* The host's system */

static double k_full[N_DOFS][N_DOFS];
static int prescribed[N_DOFS];
static double u_p[N_DOFS];
static long equation[N_DOFS];

/* Assemble every brick of a body into k_full. */
static void assemble(size_t first, size_t n) {
    const HyconSolidMaterial material = {1.0, 0.3};
    size_t i, j, a, b;
    for (j = 0; j < n; ++j)
        for (i = 0; i < n; ++i) {
            size_t nodes[8];
            double xyz[24], ke[576];
            brick(first, n, i, j, nodes);
            for (a = 0; a < 8; ++a) memcpy(&xyz[3 * a], coords[nodes[a]], sizeof coords[0]);
            must(hycon_brick_stiffness(HYCON_BRICK_HYBRID18, xyz, &material, ke, 576),
                 "hycon_brick_stiffness");
            for (a = 0; a < 24; ++a)
                for (b = 0; b < 24; ++b)
                    k_full[3 * nodes[a / 3] + a % 3][3 * nodes[b / 3] + b % 3] += ke[24 * a + b];
        }
}

/* Prescribe direction dir of node nd to value. */
static void hold(size_t nd, int dir, double value) {
    prescribed[3 * nd + dir] = 1;
    u_p[3 * nd + dir] = value;
}

/* The held face of a body (layer k): every node along z to `z`, a corner in x and y, the next
 * corner along x in y. */
static void hold_face(size_t first, size_t n, size_t k, double z) {
    size_t i, j;
    for (j = 0; j <= n; ++j)
        for (i = 0; i <= n; ++i) hold(node(first, n, i, j, k), 2, z);
    hold(node(first, n, 0, 0, k), 0, 0.0);
    hold(node(first, n, 0, 0, k), 1, 0.0);
    hold(node(first, n, n, 0, k), 1, 0.0);
}

/* K_ff (dense, n x n), its Cholesky factor, the right-hand side -K_fp u_p. */
typedef struct {
    size_t n;
    double *k;   /* K_ff, row-major */
    double *l;   /* its Cholesky factor, lower, row-major */
    double *rhs;
} System;

static System build(void) {
    System s;
    size_t d, e, i, j, p;
    s.n = 0;
    for (d = 0; d < N_DOFS; ++d) equation[d] = prescribed[d] ? HYCON_FIXED : (long)s.n++;
    s.k = calloc(s.n * s.n, sizeof *s.k);
    s.l = calloc(s.n * s.n, sizeof *s.l);
    s.rhs = calloc(s.n, sizeof *s.rhs);
    if (!s.k || !s.l || !s.rhs) exit(1);
    for (d = 0; d < N_DOFS; ++d) {
        if (equation[d] < 0) continue;
        for (e = 0; e < N_DOFS; ++e) {
            if (equation[e] >= 0)
                s.k[(size_t)equation[d] * s.n + (size_t)equation[e]] = k_full[d][e];
            else
                s.rhs[equation[d]] -= k_full[d][e] * u_p[e];
        }
    }
    /* Cholesky, K = L L^T */
    for (j = 0; j < s.n; ++j) {
        double diag = s.k[j * s.n + j];
        for (p = 0; p < j; ++p) diag -= s.l[j * s.n + p] * s.l[j * s.n + p];
        if (!(diag > 0.0)) {
            printf("FAILED: K is not positive definite at equation %zu\n", j);
            exit(1);
        }
        s.l[j * s.n + j] = sqrt(diag);
        for (i = j + 1; i < s.n; ++i) {
            double v = s.k[i * s.n + j];
            for (p = 0; p < j; ++p) v -= s.l[i * s.n + p] * s.l[j * s.n + p];
            s.l[i * s.n + j] = v / s.l[j * s.n + j];
        }
    }
    return s;
}

/* The solve callback: K x = rhs for nrhs column-major right-hand sides with the host's factor. */
static int solve(void *user_data, size_t n, size_t nrhs, const double *rhs, double *x) {
    const System *s = user_data;
    size_t c, i, p;
    if (n != s->n) return 1;
    for (c = 0; c < nrhs; ++c) {
        const double *b = rhs + c * n;
        double *y = x + c * n;
        for (i = 0; i < n; ++i) { /* L y = b */
            double v = b[i];
            for (p = 0; p < i; ++p) v -= s->l[i * n + p] * y[p];
            y[i] = v / s->l[i * n + i];
        }
        for (i = n; i-- > 0;) { /* L^T x = y */
            double v = y[i];
            for (p = i + 1; p < n; ++p) v -= s->l[p * n + i] * y[p];
            y[i] = v / s->l[i * n + i];
        }
    }
    return 0;
}

/* ------------------------------------------------------------------------------------------ */
/* The contact description and the analysis */

static size_t contact_ids[N_NODES];
static double contact_xyz[3 * N_NODES];
static int64_t contact_eq[3 * N_NODES];
static size_t n_contact = 0;
static size_t a_faces[4 * MAX_FACES], b_faces[4 * MAX_FACES];

static void add_contact_node(size_t nd) {
    int d;
    contact_ids[n_contact] = nd;
    for (d = 0; d < 3; ++d) {
        contact_xyz[3 * n_contact + d] = coords[nd][d];
        contact_eq[3 * n_contact + d] = equation[3 * nd + d];
    }
    ++n_contact;
}

/* A's bottom (layer 0 of A) and B's top (layer 1 of B): nodes in increasing id order, faces
 * counter-clockwise seen from outside their body (A's bottom points down, B's top up). */
static void describe_contact(void) {
    size_t i, j;
    for (j = 0; j <= NA; ++j)
        for (i = 0; i <= NA; ++i) add_contact_node(node(0, NA, i, j, 0));
    for (j = 0; j <= NB; ++j)
        for (i = 0; i <= NB; ++i) add_contact_node(node(A_NODES, NB, i, j, 1));
    for (j = 0; j < NA; ++j)
        for (i = 0; i < NA; ++i) {
            size_t *f = &a_faces[4 * (j * NA + i)], b[8];
            brick(0, NA, i, j, b);
            f[0] = b[0], f[1] = b[3], f[2] = b[2], f[3] = b[1];
        }
    for (j = 0; j < NB; ++j)
        for (i = 0; i < NB; ++i) {
            size_t *f = &b_faces[4 * (j * NB + i)], b[8];
            brick(A_NODES, NB, i, j, b);
            f[0] = b[4], f[1] = b[5], f[2] = b[6], f[3] = b[7];
        }
}

/* The upper triangle of K_ff as CSR. */
typedef struct {
    size_t *row_ptr, *columns;
    double *values;
} Csr;

static Csr upper(const System *s) {
    Csr c;
    size_t i, j, nnz = 0;
    c.row_ptr = malloc((s->n + 1) * sizeof *c.row_ptr);
    c.columns = malloc(s->n * s->n * sizeof *c.columns);
    c.values = malloc(s->n * s->n * sizeof *c.values);
    if (!c.row_ptr || !c.columns || !c.values) exit(1);
    c.row_ptr[0] = 0;
    for (i = 0; i < s->n; ++i) {
        for (j = i; j < s->n; ++j)
            if (s->k[i * s->n + j] != 0.0) {
                c.columns[nnz] = j;
                c.values[nnz++] = s->k[i * s->n + j];
            }
        c.row_ptr[i + 1] = nnz;
    }
    return c;
}

/* One analysis: the host described, its stiffness as CSR (`callback` 0) or as the solve
 * callback, one increment; the A nodes' results and the displacement written out. */
static void run(System *s, const Csr *csr, int callback, HyconSolidNodeResult *nodes,
                size_t *n_a, double *u) {
    HyconSolidHost *host = NULL;
    HyconSolidContact *contact = NULL;
    const HyconSolidHostNodes view = {contact_ids, contact_xyz, contact_eq, n_contact};
    const HyconHostFaces fa = {a_faces, NA * NA}, fb = {b_faces, NB * NB};
    const double inside[3] = {-0.25, -0.25, 0.5}; /* the centre of A's first brick */
    HyconIncrementInfo info;
    size_t pair = 99, needed = 0;
    must(hycon_solid_host_new(&host, s->n), "hycon_solid_host_new");
    must(hycon_solid_host_add_nodes(host, &view), "hycon_solid_host_add_nodes");
    must(hycon_solid_host_add_pair(host, &fa, &fb, FRICTION, &pair), "hycon_solid_host_add_pair");
    must(hycon_solid_host_set_pair_inside(host, pair, inside), "hycon_solid_host_set_pair_inside");
    if (callback)
        must(hycon_solid_host_set_solver(host, solve, s), "hycon_solid_host_set_solver");
    else
        must(hycon_solid_host_set_csr(host, csr->row_ptr, csr->columns, csr->values,
                                      HYCON_CSR_UPPER),
             "hycon_solid_host_set_csr");
    must(hycon_solid_contact_new_host(&contact, host, NULL), "hycon_solid_contact_new_host");
    hycon_solid_host_free(host); /* the analysis keeps its own copy */
    must(hycon_solid_contact_increment(contact, s->rhs, s->n, NULL, 0, &info),
         "hycon_solid_contact_increment");
    must(hycon_solid_contact_node_results(contact, pair, NULL, 0, &needed),
         "hycon_solid_contact_node_results");
    *n_a = needed;
    must(hycon_solid_contact_node_results(contact, pair, nodes, needed, NULL),
         "hycon_solid_contact_node_results");
    must(hycon_solid_contact_displacement(contact, u, s->n, NULL),
         "hycon_solid_contact_displacement");
    printf("%s path: %zu iterations, %zu active A nodes of %zu\n",
           callback ? "callback" : "CSR", info.iterations, info.active, needed);
    hycon_solid_contact_free(contact);
}

int main(void) {
    HyconSolidNodeResult nodes[2][N_NODES];
    size_t n_a[2], k, i, j;
    double *u[2], p = D / 2.0, total = 0.0, worst = 0.0, worst_u = 0.0, bottom = 0.0;
    System s;
    Csr csr;
    place(0, NA, 0.0);
    place(A_NODES, NB, -1.0);
    assemble(0, NA);
    assemble(A_NODES, NB);
    hold_face(0, NA, 1, -D);        /* A's top, pressed */
    hold_face(A_NODES, NB, 0, 0.0); /* B's bottom, held */
    s = build();
    csr = upper(&s);
    describe_contact();
    for (k = 0; k < 2; ++k) {
        u[k] = calloc(s.n, sizeof *u[k]);
        if (!u[k]) return 1;
        run(&s, &csr, (int)k, nodes[k], &n_a[k], u[k]);
    }
    check(n_a[0] == (NA + 1) * (NA + 1) && n_a[1] == n_a[0], "A nodes", (double)n_a[1],
          (double)((NA + 1) * (NA + 1)));
    for (i = 0; i < n_a[0]; ++i) {
        const HyconSolidNodeResult *r = &nodes[0][i];
        check(r->state == HYCON_NODE_STICK, "state (stick)", (double)r->state, HYCON_NODE_STICK);
        check(fabs(r->tn + p) < 1e-9 * p, "tn", r->tn, -p);
        check(hypot(r->ts[0], r->ts[1]) < 1e-9 * p, "|ts|", hypot(r->ts[0], r->ts[1]), 0.0);
        check(fabs(r->normal[2] + 1.0) < 1e-12, "normal z (A's bottom, outward)", r->normal[2],
              -1.0);
        total += r->force[2];
        check(r->node == nodes[1][i].node && r->state == nodes[1][i].state, "callback node",
              (double)nodes[1][i].node, (double)r->node);
        worst = fmax(worst, fabs(r->tn - nodes[1][i].tn));
    }
    check(fabs(total - p) < 1e-9 * p, "sum of A's nodal forces along z", total, p);
    check(worst < 1e-10 * p, "CSR against callback, tn", worst, 0.0);
    for (i = 0; i < s.n; ++i) worst_u = fmax(worst_u, fabs(u[0][i] - u[1][i]));
    check(worst_u < 1e-10 * D, "CSR against callback, displacement", worst_u, 0.0);
    /* A's bottom moves down by half the press (both bodies compress alike) */
    for (j = 0; j <= NA; ++j)
        for (i = 0; i <= NA; ++i) {
            long e = equation[3 * node(0, NA, i, j, 0) + 2];
            if (e >= 0) bottom = fmax(bottom, fabs(u[0][e] + D / 2.0));
        }
    check(bottom < 1e-9 * D, "A's bottom at -d/2", bottom, 0.0);
    printf("p = %.6g, tn = %.17g, sum of forces %.17g\n", p, nodes[0][0].tn, total);
    free(s.k), free(s.l), free(s.rhs), free(u[0]), free(u[1]);
    free(csr.row_ptr), free(csr.columns), free(csr.values);
    if (failures) return 1;
    printf("OK\n");
    return 0;
}
