/* Thread safety of the hycon contact C API (C99 + POSIX threads).
 *
 * Two independent contact problems (different meshes, friction and loads) are solved from two
 * threads at once, each thread with its own handles, through both ways in: the model API (with
 * an iteration monitor) and the host-assembly API with a solve callback (a dense Cholesky
 * factor of the host's own assembly; user_data per thread). The results (increment summaries,
 * node results on both sides, displacements, iteration records) must equal those of the same
 * problems solved one after the other on the main thread: bit for bit, or within 1e-14 of the
 * largest value of the quantity. Callbacks must run on the thread that called into the handle,
 * and the last error message must be per thread. Then each thread queries its model analysis
 * from two more threads at once (const queries on one handle are thread-safe): both must get
 * what a sequential query gets.
 *
 * Usage: contact_threads [rounds] [shared]
 *   rounds: the threaded solves are repeated `rounds` times (default 4);
 *   shared: 1 (default) runs the concurrent queries on one handle, 0 skips them. The data-race
 *   detectors (helgrind, DRD) run with 0: they model pthread locks, not the atomics and futexes
 *   behind Rust's OnceLock and Mutex that make those queries safe, so they would report each
 *   as a race. Plain, ASan and memcheck runs use 1.
 */
#define _POSIX_C_SOURCE 200809L
#include "hycon.h"

#include <math.h>
#include <pthread.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MAX_INCREMENTS 4

/* ---------------------------------------------------------------------------------------- */
/* Problems: two stacked blocks, the lower [0, 2] x [0, 1] held at its bottom, the upper one
 * [x0, x0 + w] x [1, 2] pressed down (and slid) through its top. A = upper bottom, B = lower
 * top. */

typedef struct {
    const char *name;
    size_t nxl, nyl, nxu, nyu; /* elements per block */
    double x0, w;              /* the upper block's extent in x */
    double friction;
    size_t increments;
    double press[MAX_INCREMENTS], slide[MAX_INCREMENTS];
    size_t bad_pair; /* an unknown pair index, for the per-thread error message */
} Problem;

static const Problem problems[2] = {
    {"A", 16, 6, 8, 6, 0.6, 0.8, 0.3, 3, {0.5e-3, 1e-3, 1e-3}, {0.0, 0.0, 0.25e-3}, 7},
    {"B", 20, 5, 10, 4, 0.5, 0.9, 0.15, 4, {0.4e-3, 0.8e-3, 0.8e-3, 1.2e-3},
     {0.0, 0.1e-3, 0.3e-3, 0.3e-3}, 9},
};

static const HyconMaterial steel = {210e3, 0.3, 1.0, HYCON_PLANE_STRAIN};

typedef struct {
    size_t n_nodes, n_elements, na, nb, ntop, nbottom;
    double *coords;
    size_t *offsets, *conn, *a, *b, *top, *bottom;
} Mesh;

static void *xcalloc(size_t n, size_t size) {
    void *p = calloc(n == 0 ? 1 : n, size);
    if (p == NULL) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }
    return p;
}

static void mesh_build(const Problem *p, Mesh *m) {
    const size_t nnl = (p->nxl + 1) * (p->nyl + 1);
    size_t i, j, e = 0;
#define LOWER(i, j) ((j) * (p->nxl + 1) + (i))
#define UPPER(i, j) (nnl + (j) * (p->nxu + 1) + (i))
    m->n_nodes = nnl + (p->nxu + 1) * (p->nyu + 1);
    m->n_elements = p->nxl * p->nyl + p->nxu * p->nyu;
    m->na = p->nxu + 1;
    m->nb = p->nxl + 1;
    m->ntop = p->nxu + 1;
    m->nbottom = p->nxl + 1;
    m->coords = (double *)xcalloc(2 * m->n_nodes, sizeof(double));
    m->offsets = (size_t *)xcalloc(m->n_elements + 1, sizeof(size_t));
    m->conn = (size_t *)xcalloc(4 * m->n_elements, sizeof(size_t));
    m->a = (size_t *)xcalloc(m->na, sizeof(size_t));
    m->b = (size_t *)xcalloc(m->nb, sizeof(size_t));
    m->top = (size_t *)xcalloc(m->ntop, sizeof(size_t));
    m->bottom = (size_t *)xcalloc(m->nbottom, sizeof(size_t));
    for (j = 0; j <= p->nyl; ++j)
        for (i = 0; i <= p->nxl; ++i) {
            m->coords[2 * LOWER(i, j)] = 2.0 * (double)i / (double)p->nxl;
            m->coords[2 * LOWER(i, j) + 1] = (double)j / (double)p->nyl;
        }
    for (j = 0; j <= p->nyu; ++j)
        for (i = 0; i <= p->nxu; ++i) {
            m->coords[2 * UPPER(i, j)] = p->x0 + p->w * (double)i / (double)p->nxu;
            m->coords[2 * UPPER(i, j) + 1] = 1.0 + (double)j / (double)p->nyu;
        }
    for (j = 0; j < p->nyl; ++j)
        for (i = 0; i < p->nxl; ++i, ++e) {
            m->conn[4 * e] = LOWER(i, j);
            m->conn[4 * e + 1] = LOWER(i + 1, j);
            m->conn[4 * e + 2] = LOWER(i + 1, j + 1);
            m->conn[4 * e + 3] = LOWER(i, j + 1);
        }
    for (j = 0; j < p->nyu; ++j)
        for (i = 0; i < p->nxu; ++i, ++e) {
            m->conn[4 * e] = UPPER(i, j);
            m->conn[4 * e + 1] = UPPER(i + 1, j);
            m->conn[4 * e + 2] = UPPER(i + 1, j + 1);
            m->conn[4 * e + 3] = UPPER(i, j + 1);
        }
    for (e = 0; e <= m->n_elements; ++e) m->offsets[e] = 4 * e;
    for (i = 0; i < m->na; ++i) m->a[i] = UPPER(i, 0);
    for (i = 0; i < m->nb; ++i) m->b[i] = LOWER(p->nxl - i, p->nyl);
    for (i = 0; i < m->ntop; ++i) m->top[i] = UPPER(i, p->nyu);
    for (i = 0; i < m->nbottom; ++i) m->bottom[i] = LOWER(i, 0);
#undef LOWER
#undef UPPER
}

static void mesh_free(Mesh *m) {
    free(m->coords);
    free(m->offsets);
    free(m->conn);
    free(m->a);
    free(m->b);
    free(m->top);
    free(m->bottom);
}

/* total prescribed values over all dofs: the top moved by (slide, -press) */
static void prescribed_values(const Mesh *m, double *qp, double press, double slide) {
    size_t i;
    memset(qp, 0, 2 * m->n_nodes * sizeof *qp);
    for (i = 0; i < m->ntop; ++i) {
        qp[2 * m->top[i]] = slide;
        qp[2 * m->top[i] + 1] = -press;
    }
}

/* ---------------------------------------------------------------------------------------- */
/* The host: its own assembly of the same mesh, prescribed dofs eliminated, dense Cholesky */

typedef struct {
    size_t ndof, n;
    int64_t *eq;     /* equation of each dof or HYCON_FIXED */
    double *k;       /* full K, ndof x ndof row-major */
    double *l;       /* Cholesky factor of K_ff, n x n row-major */
    pthread_t owner; /* the thread that may call into the handles using this host */
    size_t calls, wrong_thread;
} Host;

static bool host_build(const Mesh *m, Host *h) {
    size_t e, a, b, i, j, p, ndof = 2 * m->n_nodes;
    bool *fixed = (bool *)xcalloc(ndof, sizeof(bool));
    h->ndof = ndof;
    h->n = 0;
    h->eq = (int64_t *)xcalloc(ndof, sizeof(int64_t));
    h->k = (double *)xcalloc(ndof * ndof, sizeof(double));
    for (i = 0; i < m->nbottom; ++i) fixed[2 * m->bottom[i]] = fixed[2 * m->bottom[i] + 1] = true;
    for (i = 0; i < m->ntop; ++i) fixed[2 * m->top[i]] = fixed[2 * m->top[i] + 1] = true;
    for (i = 0; i < ndof; ++i) h->eq[i] = fixed[i] ? HYCON_FIXED : (int64_t)h->n++;
    free(fixed);
    h->l = (double *)xcalloc(h->n * h->n, sizeof(double));
    for (e = 0; e < m->n_elements; ++e) {
        double xy[8], ke[64];
        const size_t *nodes = m->conn + 4 * e;
        for (a = 0; a < 4; ++a) {
            xy[2 * a] = m->coords[2 * nodes[a]];
            xy[2 * a + 1] = m->coords[2 * nodes[a] + 1];
        }
        if (hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 4, xy, &steel, ke, 64) != HYCON_OK)
            return false;
        for (a = 0; a < 8; ++a)
            for (b = 0; b < 8; ++b)
                h->k[(2 * nodes[a / 2] + a % 2) * ndof + 2 * nodes[b / 2] + b % 2] +=
                    ke[a * 8 + b];
    }
    for (i = 0; i < ndof; ++i)
        for (j = 0; j < ndof; ++j)
            if (h->eq[i] >= 0 && h->eq[j] >= 0)
                h->l[(size_t)h->eq[i] * h->n + (size_t)h->eq[j]] = h->k[i * ndof + j];
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

static void host_free(Host *h) {
    free(h->eq);
    free(h->k);
    free(h->l);
}

static void host_rhs(const Mesh *m, const Host *h, double *rhs, double press, double slide) {
    double *qp = (double *)xcalloc(h->ndof, sizeof(double));
    size_t i, j;
    prescribed_values(m, qp, press, slide);
    for (i = 0; i < h->ndof; ++i) {
        if (h->eq[i] < 0) continue;
        rhs[h->eq[i]] = 0.0;
        for (j = 0; j < h->ndof; ++j)
            if (h->eq[j] < 0) rhs[h->eq[i]] -= h->k[i * h->ndof + j] * qp[j];
    }
    free(qp);
}

static int32_t host_solve(void *user_data, size_t n, size_t nrhs, const double *rhs, double *x) {
    Host *h = (Host *)user_data;
    size_t c, i, p;
    h->calls++;
    if (!pthread_equal(pthread_self(), h->owner)) h->wrong_thread++;
    if (n != h->n) return 1;
    for (c = 0; c < nrhs; ++c) {
        const double *b = rhs + c * n;
        double *y = x + c * n;
        for (i = 0; i < n; ++i) {
            double v = b[i];
            for (p = 0; p < i; ++p) v -= h->l[i * n + p] * y[p];
            y[i] = v / h->l[i * n + i];
        }
        for (i = n; i-- > 0;) {
            double v = y[i];
            for (p = i + 1; p < n; ++p) v -= h->l[p * n + i] * y[p];
            y[i] = v / h->l[i * n + i];
        }
    }
    return 0;
}

/* ---------------------------------------------------------------------------------------- */
/* What a run produces */

typedef struct {
    pthread_t owner;
    size_t calls, wrong_thread;
} Monitor;

static int32_t monitor(void *user_data, const HyconIterationRecord *record) {
    Monitor *m = (Monitor *)user_data;
    m->calls++;
    if (!pthread_equal(pthread_self(), m->owner)) m->wrong_thread++;
    return record->iteration > 1000; /* never stops */
}

typedef struct {
    size_t increments, na, nb, nfield, nrecords;
    HyconIncrementInfo info[MAX_INCREMENTS];
    HyconNodeResult *a;          /* increments x na */
    HyconBNodeResult *b;         /* increments x nb */
    double *u;                   /* increments x nfield */
    HyconIterationRecord *records;
    size_t callback_calls, wrong_thread;
    bool ok;            /* every call succeeded */
    char failure[512];  /* else the first failure */
} Run;

static void run_free(Run *r) {
    free(r->a);
    free(r->b);
    free(r->u);
    free(r->records);
}

static bool check(Run *r, HyconStatus s, const char *what) {
    if (s == HYCON_OK) return true;
    if (r->ok) {
        char message[400];
        hycon_last_error_message(message, sizeof message);
        snprintf(r->failure, sizeof r->failure, "%s: %s: %s", what, hycon_status_name(s), message);
    }
    r->ok = false;
    return false;
}

/* The results of the increment just converged. */
static bool record_increment(Run *r, HyconContact *c, size_t k) {
    return check(r, hycon_contact_node_results(c, 0, r->a + k * r->na, r->na, NULL), "node results") &&
           check(r, hycon_contact_b_node_results(c, 0, r->b + k * r->nb, r->nb, NULL),
                 "B node results") &&
           check(r, hycon_contact_displacement(c, r->u + k * r->nfield, r->nfield, NULL),
                 "displacement");
}

static bool record_history(Run *r, HyconContact *c) {
    if (!check(r, hycon_contact_records(c, 0, NULL, 0, &r->nrecords), "record count")) return false;
    r->records = (HyconIterationRecord *)xcalloc(r->nrecords, sizeof(HyconIterationRecord));
    return check(r, hycon_contact_records(c, 0, r->records, r->nrecords, NULL), "records");
}

static void run_init(Run *r, const Problem *p, const Mesh *m, size_t nfield) {
    memset(r, 0, sizeof *r);
    r->ok = true;
    r->increments = p->increments;
    r->na = m->na;
    r->nb = m->nb;
    r->nfield = nfield;
    r->a = (HyconNodeResult *)xcalloc(p->increments * m->na, sizeof(HyconNodeResult));
    r->b = (HyconBNodeResult *)xcalloc(p->increments * m->nb, sizeof(HyconBNodeResult));
    r->u = (double *)xcalloc(p->increments * nfield, sizeof(double));
}

/* One problem through both APIs, the two analyses alive side by side, on the calling thread. */
typedef struct {
    const Problem *p;
    pthread_barrier_t *start; /* NULL: no waiting */
    Run model, host;
    bool own_error;    /* the last error message stayed this thread's */
    bool concurrent;   /* concurrent const queries on one handle agreed with a sequential one */
    double start_time, end_time; /* seconds (CLOCK_MONOTONIC) */
} Job;

/* Const queries on one handle from two threads at once (displacement recovery racing to fill
 * the handle's cache, then displacement increments, each a solve under the handle's lock). */
typedef struct {
    const HyconContact *c;
    size_t n;
    double *u, *du;
    HyconStatus status;
} Query;

static void *query_const(void *arg) {
    Query *q = (Query *)arg;
    q->status = hycon_contact_displacement(q->c, q->u, q->n, NULL);
    if (q->status == HYCON_OK)
        q->status = hycon_contact_displacement_increment(q->c, q->du, q->n, NULL);
    return NULL;
}

/* After a repeated increment (the cache is empty again), two threads query `c` at once; their
 * results must equal each other and a later sequential query, bit for bit. */
static bool concurrent_queries(HyconContact *c, const double *load, const double *qp, size_t n) {
    Query q[2];
    pthread_t t[2];
    double *u = (double *)xcalloc(n, sizeof(double));
    bool ok = hycon_contact_increment(c, load, n, qp, n, NULL) == HYCON_OK;
    int i;
    for (i = 0; i < 2; ++i) {
        q[i].c = c;
        q[i].n = n;
        q[i].u = (double *)xcalloc(n, sizeof(double));
        q[i].du = (double *)xcalloc(n, sizeof(double));
        q[i].status = HYCON_ERROR_PANIC;
    }
    for (i = 0; ok && i < 2; ++i) ok = pthread_create(&t[i], NULL, query_const, &q[i]) == 0;
    if (ok) {
        pthread_join(t[0], NULL);
        pthread_join(t[1], NULL);
        ok = q[0].status == HYCON_OK && q[1].status == HYCON_OK &&
             hycon_contact_displacement(c, u, n, NULL) == HYCON_OK &&
             memcmp(q[0].u, q[1].u, n * sizeof(double)) == 0 &&
             memcmp(q[0].u, u, n * sizeof(double)) == 0 &&
             memcmp(q[0].du, q[1].du, n * sizeof(double)) == 0;
    }
    for (i = 0; i < 2; ++i) {
        free(q[i].u);
        free(q[i].du);
    }
    free(u);
    return ok;
}

static bool shared_queries = true; /* the `shared` argument */

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void *solve_problem(void *arg) {
    Job *job = (Job *)arg;
    const Problem *p = job->p;
    Mesh mesh;
    Host host;
    Monitor mon;
    HyconContactOptions options;
    HyconModel *model = NULL;
    HyconHost *desc = NULL;
    HyconContact *cm = NULL, *ch = NULL;
    double *load, *qp, *rhs, *a_xy, *b_xy;
    int64_t *a_eq, *b_eq;
    HyconElementBlock elements;
    HyconPolyline a_line, b_line;
    HyconHostNodes a_nodes, b_nodes;
    size_t i, k;
    const double inside[2] = {p->x0 + 0.5 * p->w, 1.5}; /* the upper block's centre */

    if (job->start != NULL) pthread_barrier_wait(job->start);
    job->start_time = now();
    mesh_build(p, &mesh);
    memset(&host, 0, sizeof host);
    host.owner = pthread_self();
    mon.owner = pthread_self();
    mon.calls = mon.wrong_thread = 0;
    run_init(&job->model, p, &mesh, 2 * mesh.n_nodes);
    if (!host_build(&mesh, &host)) {
        job->model.ok = job->host.ok = false;
        snprintf(job->model.failure, sizeof job->model.failure, "host assembly failed");
        host_free(&host);
        mesh_free(&mesh);
        return NULL;
    }
    run_init(&job->host, p, &mesh, host.n);
    load = (double *)xcalloc(2 * mesh.n_nodes, sizeof(double));
    qp = (double *)xcalloc(2 * mesh.n_nodes, sizeof(double));
    rhs = (double *)xcalloc(host.n, sizeof(double));
    a_xy = (double *)xcalloc(2 * mesh.na, sizeof(double));
    b_xy = (double *)xcalloc(2 * mesh.nb, sizeof(double));
    a_eq = (int64_t *)xcalloc(2 * mesh.na, sizeof(int64_t));
    b_eq = (int64_t *)xcalloc(2 * mesh.nb, sizeof(int64_t));

    elements.offsets = mesh.offsets;
    elements.nodes = mesh.conn;
    elements.n_elements = mesh.n_elements;
    elements.materials = NULL; /* all use material 0 */
    elements.kind = HYCON_ELEMENT_HYBRID;
    a_line.nodes = mesh.a;
    a_line.n = mesh.na;
    b_line.nodes = mesh.b;
    b_line.n = mesh.nb;
    a_nodes.ids = mesh.a;
    a_nodes.coords = a_xy;
    a_nodes.equations = a_eq;
    a_nodes.n = mesh.na;
    b_nodes.ids = mesh.b;
    b_nodes.coords = b_xy;
    b_nodes.equations = b_eq;
    b_nodes.n = mesh.nb;

    /* model API, with a monitor */
    hycon_contact_options_default(&options);
    options.monitor = monitor;
    options.monitor_data = &mon;
    if (check(&job->model,
              hycon_model_new(&model, mesh.coords, mesh.n_nodes, &elements, &steel, 1),
              "hycon_model_new") &&
        check(&job->model, hycon_model_prescribe(model, mesh.bottom, mesh.nbottom, HYCON_XY),
              "prescribe bottom") &&
        check(&job->model, hycon_model_prescribe(model, mesh.top, mesh.ntop, HYCON_XY),
              "prescribe top") &&
        check(&job->model,
              hycon_model_add_pair(model, &a_line, &b_line, p->friction, NULL),
              "add pair"))
        check(&job->model, hycon_contact_new(&cm, model, &options), "hycon_contact_new");
    hycon_model_free(model);

    /* host API with the solve callback */
    for (i = 0; i < mesh.na; ++i) {
        a_xy[2 * i] = mesh.coords[2 * mesh.a[i]];
        a_xy[2 * i + 1] = mesh.coords[2 * mesh.a[i] + 1];
        a_eq[2 * i] = host.eq[2 * mesh.a[i]];
        a_eq[2 * i + 1] = host.eq[2 * mesh.a[i] + 1];
    }
    for (i = 0; i < mesh.nb; ++i) {
        b_xy[2 * i] = mesh.coords[2 * mesh.b[i]];
        b_xy[2 * i + 1] = mesh.coords[2 * mesh.b[i] + 1];
        b_eq[2 * i] = host.eq[2 * mesh.b[i]];
        b_eq[2 * i + 1] = host.eq[2 * mesh.b[i] + 1];
    }
    if (check(&job->host, hycon_host_new(&desc, host.n), "hycon_host_new") &&
        check(&job->host,
              hycon_host_add_pair(desc, &a_nodes, &b_nodes, p->friction, NULL),
              "host add pair") &&
        /* the blocks touch: say which side body A (the upper block) is on */
        check(&job->host, hycon_host_set_pair_inside(desc, 0, inside), "host pair inside") &&
        check(&job->host, hycon_host_set_solver(desc, host_solve, &host), "set solver"))
        check(&job->host, hycon_contact_new_host(&ch, desc, NULL), "hycon_contact_new_host");
    hycon_host_free(desc);

    /* the increments, alternating between the two analyses */
    for (k = 0; k < p->increments && job->model.ok && job->host.ok; ++k) {
        prescribed_values(&mesh, qp, p->press[k], p->slide[k]);
        host_rhs(&mesh, &host, rhs, p->press[k], p->slide[k]);
        if (check(&job->model,
                  hycon_contact_increment(cm, load, 2 * mesh.n_nodes, qp, 2 * mesh.n_nodes,
                                          &job->model.info[k]),
                  "model increment"))
            record_increment(&job->model, cm, k);
        if (check(&job->host, hycon_contact_increment(ch, rhs, host.n, NULL, 0, &job->host.info[k]),
                  "host increment"))
            record_increment(&job->host, ch, k);
    }
    if (job->model.ok) record_history(&job->model, cm);
    if (job->host.ok) record_history(&job->host, ch);
    /* the model handle (no callback) queried from two more threads at once */
    job->concurrent = !shared_queries || !job->model.ok || p->increments == 0;
    if (shared_queries && job->model.ok && p->increments > 0) {
        prescribed_values(&mesh, qp, p->press[p->increments - 1], p->slide[p->increments - 1]);
        job->concurrent = concurrent_queries(cm, load, qp, 2 * mesh.n_nodes);
    }

    /* the last error message is this thread's own */
    {
        char expected[64], message[256];
        HyconNodeResult dummy;
        sprintf(expected, "contact pair %u does not exist", (unsigned)p->bad_pair);
        job->own_error = hycon_contact_node_results(cm, p->bad_pair, &dummy, 1, NULL) ==
                         HYCON_ERROR_INVALID_ARGUMENT;
        hycon_contact_free(cm);
        hycon_contact_free(ch);
        hycon_last_error_message(message, sizeof message);
        job->own_error = job->own_error && strstr(message, expected) != NULL;
    }
    job->model.callback_calls = mon.calls;
    job->model.wrong_thread = mon.wrong_thread;
    job->host.callback_calls = host.calls;
    job->host.wrong_thread = host.wrong_thread;

    free(load);
    free(qp);
    free(rhs);
    free(a_xy);
    free(b_xy);
    free(a_eq);
    free(b_eq);
    host_free(&host);
    mesh_free(&mesh);
    job->end_time = now();
    return NULL;
}

/* ---------------------------------------------------------------------------------------- */
/* Comparison */

typedef struct {
    size_t values, identical;
    double worst; /* largest difference relative to the quantity's scale */
} Stats;

static double scale_of(const double *v, size_t n) {
    double s = 0.0;
    size_t i;
    for (i = 0; i < n; ++i) s = fmax(s, fabs(v[i]));
    return s > 0.0 ? s : 1.0;
}

static bool same(double x, double y, double scale, Stats *st) {
    double d;
    st->values++;
    if (memcmp(&x, &y, sizeof x) == 0) {
        st->identical++;
        return true;
    }
    d = fabs(x - y) / scale;
    if (!(d <= st->worst)) st->worst = d; /* NaN also counts as worst */
    return d <= 1e-14;
}

#define SAME_INT(x, y, what)                                                                   \
    do {                                                                                       \
        if ((x) != (y)) {                                                                      \
            fprintf(stderr, "  %s: %s differs (%lu vs %lu)\n", label, what, (unsigned long)(x),  \
                    (unsigned long)(y));                                                       \
            return false;                                                                      \
        }                                                                                      \
    } while (0)
#define SAME_DOUBLE(x, y, scale, what)                                                         \
    do {                                                                                       \
        if (!same((x), (y), (scale), st)) {                                                    \
            fprintf(stderr, "  %s: %s differs (%.17g vs %.17g)\n", label, what, (double)(x),     \
                    (double)(y));                                                              \
            return false;                                                                      \
        }                                                                                      \
    } while (0)

static bool same_run(const Run *x, const Run *y, const char *label, Stats *st) {
    size_t k, i, j;
    double su, sa_t, sa_f, sb_f, sb_w;
    if (!x->ok || !y->ok) {
        fprintf(stderr, "  %s: a run failed: %s%s\n", label, x->failure, y->failure);
        return false;
    }
    SAME_INT(x->nrecords, y->nrecords, "record count");
    SAME_INT(x->callback_calls, y->callback_calls, "callback calls");
    SAME_INT(y->wrong_thread, 0, "callbacks on another thread");
    SAME_INT(x->wrong_thread, 0, "callbacks on another thread");
    for (k = 0; k < x->increments; ++k) {
        SAME_INT(x->info[k].increment, y->info[k].increment, "info.increment");
        SAME_INT(x->info[k].iterations, y->info[k].iterations, "info.iterations");
        SAME_INT(x->info[k].active, y->info[k].active, "info.active");
        SAME_INT(x->info[k].slip, y->info[k].slip, "info.slip");
    }
    su = scale_of(x->u, x->increments * x->nfield);
    for (i = 0; i < x->increments * x->nfield; ++i) SAME_DOUBLE(x->u[i], y->u[i], su, "u");
    sa_t = sa_f = sb_f = sb_w = 0.0;
    for (i = 0; i < x->increments * x->na; ++i) {
        sa_t = fmax(sa_t, fmax(fabs(x->a[i].tn), fabs(x->a[i].ts)));
        sa_f = fmax(sa_f, fmax(fabs(x->a[i].force[0]), fabs(x->a[i].force[1])));
    }
    for (i = 0; i < x->increments * x->nb; ++i) {
        sb_f = fmax(sb_f, fmax(fabs(x->b[i].force[0]), fabs(x->b[i].force[1])));
        sb_w = fmax(sb_w, fabs(x->b[i].pressure));
    }
    sa_t = sa_t > 0.0 ? sa_t : 1.0;
    sa_f = sa_f > 0.0 ? sa_f : 1.0;
    sb_f = sb_f > 0.0 ? sb_f : 1.0;
    sb_w = sb_w > 0.0 ? sb_w : 1.0;
    for (i = 0; i < x->increments * x->na; ++i) {
        const HyconNodeResult *a = &x->a[i], *b = &y->a[i];
        SAME_INT(a->node, b->node, "A node");
        SAME_INT(a->state, b->state, "A node state");
        SAME_INT(a->slip_sign, b->slip_sign, "A slip sign");
        SAME_DOUBLE(a->tn, b->tn, sa_t, "tn");
        SAME_DOUBLE(a->ts, b->ts, sa_t, "ts");
        SAME_DOUBLE(a->weight, b->weight, 1.0, "weight");
        SAME_DOUBLE(a->gap, b->gap, 1.0, "gap");
        for (j = 0; j < 2; ++j) {
            SAME_DOUBLE(a->normal[j], b->normal[j], 1.0, "normal");
            SAME_DOUBLE(a->tangent[j], b->tangent[j], 1.0, "tangent");
            SAME_DOUBLE(a->position[j], b->position[j], 2.0, "position");
            SAME_DOUBLE(a->force[j], b->force[j], sa_f, "A force");
        }
    }
    for (i = 0; i < x->increments * x->nb; ++i) {
        const HyconBNodeResult *a = &x->b[i], *b = &y->b[i];
        SAME_INT(a->node, b->node, "B node");
        SAME_DOUBLE(a->weight, b->weight, 1.0, "B weight");
        SAME_DOUBLE(a->pressure, b->pressure, sb_w, "B pressure");
        SAME_DOUBLE(a->force[0], b->force[0], sb_f, "B force");
        SAME_DOUBLE(a->force[1], b->force[1], sb_f, "B force");
    }
    for (i = 0; i < x->nrecords; ++i) {
        const HyconIterationRecord *a = &x->records[i], *b = &y->records[i];
        SAME_INT(a->increment, b->increment, "record.increment");
        SAME_INT(a->iteration, b->iteration, "record.iteration");
        SAME_INT(a->active, b->active, "record.active");
        SAME_INT(a->stick, b->stick, "record.stick");
        SAME_INT(a->slip, b->slip, "record.slip");
        SAME_INT(a->changes, b->changes, "record.changes");
        SAME_DOUBLE(a->r, b->r, fmax(fabs(a->r), 1e-300), "record.r");
        SAME_DOUBLE(a->condition, b->condition, fmax(fabs(a->condition), 1e-300),
                    "record.condition");
    }
    return true;
}

/* the problem is a contact problem: in contact at the end, some slip under the slide */
static bool meaningful(const Run *r, const char *label) {
    const HyconIncrementInfo *last = &r->info[r->increments - 1];
    if (!r->ok) {
        fprintf(stderr, "  %s failed: %s\n", label, r->failure);
        return false;
    }
    if (last->active == 0 || r->nrecords < r->increments) {
        fprintf(stderr, "  %s: no contact (active %lu, records %lu)\n", label,
                (unsigned long)last->active, (unsigned long)r->nrecords);
        return false;
    }
    return true;
}

static void job_free(Job *j) {
    run_free(&j->model);
    run_free(&j->host);
}

int main(int argc, char **argv) {
    int rounds = argc > 1 ? atoi(argv[1]) : 4;
    shared_queries = argc > 2 ? atoi(argv[2]) != 0 : true;
    int round, failures = 0;
    size_t i;
    Job reference[2];
    Stats st = {0, 0, 0.0};

    if (rounds < 1) rounds = 1;
    /* one after the other on the main thread */
    for (i = 0; i < 2; ++i) {
        memset(&reference[i], 0, sizeof reference[i]);
        reference[i].p = &problems[i];
        solve_problem(&reference[i]);
        if (!meaningful(&reference[i].model, "reference model run") ||
            !meaningful(&reference[i].host, "reference host run") || !reference[i].own_error ||
            !reference[i].concurrent) {
            printf("reference %s FAILED\n", problems[i].name);
            return 1;
        }
        printf("reference %s: %lu increments, %lu + %lu iterations, %lu active, %lu slip at the "
               "end\n",
               problems[i].name, (unsigned long)problems[i].increments,
               (unsigned long)reference[i].model.nrecords,
               (unsigned long)reference[i].host.nrecords,
               (unsigned long)reference[i].model.info[problems[i].increments - 1].active,
               (unsigned long)reference[i].model.info[problems[i].increments - 1].slip);
    }

    for (round = 1; round <= rounds; ++round) {
        pthread_t threads[2];
        pthread_barrier_t start;
        Job jobs[2];
        bool ok = true;
        pthread_barrier_init(&start, NULL, 2);
        for (i = 0; i < 2; ++i) {
            memset(&jobs[i], 0, sizeof jobs[i]);
            jobs[i].p = &problems[i];
            jobs[i].start = &start;
            if (pthread_create(&threads[i], NULL, solve_problem, &jobs[i]) != 0) {
                printf("pthread_create FAILED\n");
                return 1;
            }
        }
        for (i = 0; i < 2; ++i) pthread_join(threads[i], NULL);
        pthread_barrier_destroy(&start);
        for (i = 0; i < 2; ++i) {
            char label[64];
            sprintf(label, "round %d problem %s model API", round, problems[i].name);
            ok = same_run(&reference[i].model, &jobs[i].model, label, &st) && ok;
            sprintf(label, "round %d problem %s host API", round, problems[i].name);
            ok = same_run(&reference[i].host, &jobs[i].host, label, &st) && ok;
            if (!jobs[i].concurrent) {
                fprintf(stderr, "  round %d problem %s: concurrent const queries on one handle "
                                "FAILED\n",
                        round, problems[i].name);
                ok = false;
            }
            if (!jobs[i].own_error) {
                fprintf(stderr, "  round %d problem %s: the last error message is not the "
                                "thread's own\n",
                        round, problems[i].name);
                ok = false;
            }
            job_free(&jobs[i]);
        }
        {
            double overlap = fmin(jobs[0].end_time, jobs[1].end_time) -
                             fmax(jobs[0].start_time, jobs[1].start_time);
            printf("round %d: two threads at once (%.0f ms of %.0f + %.0f ms side by side) == "
                   "one after the other: %s\n",
                   round, 1e3 * fmax(overlap, 0.0), 1e3 * (jobs[0].end_time - jobs[0].start_time),
                   1e3 * (jobs[1].end_time - jobs[1].start_time), ok ? "ok" : "FAILED");
        }
        failures += !ok;
    }
    for (i = 0; i < 2; ++i) job_free(&reference[i]);
    printf("%lu values compared, %lu bit-identical, largest relative difference %.3g\n",
           (unsigned long)st.values, (unsigned long)st.identical, st.worst);
    if (failures != 0) {
        printf("%d of %d round(s) FAILED\n", failures, rounds);
        return 1;
    }
    printf("OK\n");
    return 0;
}
