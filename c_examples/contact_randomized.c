/* Randomized test of the contact C API (strict C99), seeded and bounded in time:
 *
 *   contact_randomized [seconds = 3] [seed = 1] [max_rounds = 0: no limit]
 *
 * Each round draws a two-block problem (a lower block [0, 2] x [0, 1] held at its bottom, an
 * upper block of random width, position, mesh and gap pressed down and slid through prescribed
 * values on its top; A = the upper block's bottom, B = the lower block's top; random moduli,
 * Poisson's ratios, friction and kinematics; in a third of the rounds axisymmetric, x = r: the
 * lower block off the axis or touching it, and on one touching it the upper block beside it
 * or on the axis too, u_r = 0 held on the axis) and checks through the model API:
 *  1. a zero increment (the last totals again) converges in at most 3 iterations to the same
 *     tractions;
 *  2. the tractions are invariant under rigid motion (a translation up to 1e3 and a rotation by
 *     any angle, the prescribed displacements rotated alike; in axisymmetry a translation
 *     along the axis only), unit scaling (lengths and moduli times powers of 10 in
 *     [1e-3, 1e3]: tractions scale with the moduli) and node renumbering (a random
 *     permutation), to 1e-8 of the peak under small kinematics and 1e-5
 *     (ten times the iteration's tolerance) under finite ones, and under rotation to at least
 *     1e4 eps |X| / approach (the coordinates' round-off across the surfaces, amplified by the
 *     contact system's condition); a failing problem fails alike, and since 0.7.0 a problem
 *     that fails at all is a violation too, except the class that has no state satisfying
 *     the discrete conditions (a B node penetrating between two open A nodes: the much
 *     stiffer body is the multiplier side), which is counted;
 *  3. random bad calls between the increments (NULL pointers, wrong lengths, non-finite
 *     values, buffers too small, unknown pairs and records, bad options, a dof prescribed
 *     twice, bad elements, a model mixing analysis kinds, axisymmetric with a thickness other
 *     than 1 or across the axis) each return an error with a message, leave their output
 *     buffers untouched and the analysis' state bit for bit as it was, and the run goes on to
 *     exactly the results of the same run without them.
 * It prints the seed, the rounds and the calls per class, and on a violation the seed, round and
 * problem, exiting 1. */
#include "hycon.h"

#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MAXX 7 /* elements per side, at most */
#define MAXN (2 * (MAXX + 1) * (MAXX + 1))
#define MAXE (2 * MAXX * MAXX)
#define MAXA (MAXX + 1)
#define SENTINEL 12345.0

/* ---------------------------------------------------------------------------------------- */
/* Random numbers: xorshift64*, seeded */

static uint64_t rng = 1;
static uint64_t next_u64(void) {
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return rng * 2685821657736338717ULL;
}
static double uniform(double lo, double hi) {
    return lo + (hi - lo) * (double)(next_u64() >> 11) / 9007199254740992.0;
}
static size_t below(size_t n) { return (size_t)(next_u64() % n); }

/* ---------------------------------------------------------------------------------------- */
/* Problems and their variants */

typedef struct {
    size_t lower[2], upper[2];
    /* `axis`: the lower block's left side (its inner radius in axisymmetry; 0 in plane
     * problems); `left`: the upper block's */
    double axis, left, width, gap, depth, slide, moduli[2], poisson[2], friction;
    HyconKinematics kinematics;
    HyconAnalysis analysis;
} Problem;

typedef struct {
    double translation[2], angle, length_scale, modulus_scale;
    bool renumber;
    size_t perm[MAXN]; /* perm[old] = new */
} Variant;

typedef struct {
    size_t nn, ne, na, nb, nbottom, ntop, naxis;
    double coords[2 * MAXN];
    size_t offsets[MAXE + 1], conn[4 * MAXE], material[MAXE];
    size_t a[MAXA], b[MAXA], bottom[MAXA], top[MAXA];
    size_t axis[2 * MAXA]; /* nodes on the axis (u_r = 0) but in the bottom and top rows */
} Mesh;

static Problem draw_problem(void) {
    Problem p;
    p.lower[0] = 2 + below(MAXX - 1);
    p.lower[1] = 1 + below(3);
    p.upper[0] = 1 + below(MAXX - 1);
    p.upper[1] = 1 + below(3);
    p.left = uniform(0.1, 0.8);
    p.width = uniform(0.4, 1.0);
    p.gap = below(2) ? 0.0 : uniform(0.0, 1e-3);
    p.depth = p.gap + pow(10.0, uniform(-4.0, -2.0));
    p.slide = below(2) ? 0.0 : uniform(-0.2, 0.2) * (p.depth - p.gap);
    p.moduli[0] = 1.0;
    p.moduli[1] = pow(10.0, uniform(-2.0, 2.0));
    p.poisson[0] = uniform(-0.2, 0.45);
    p.poisson[1] = uniform(-0.2, 0.45);
    p.friction = below(2) ? 0.0 : uniform(0.05, 0.6);
    p.kinematics = below(2) ? HYCON_KINEMATICS_SMALL : HYCON_KINEMATICS_FINITE;
    /* axisymmetric (x = r, y = z) in a third of the rounds: the lower block touching the axis
     * or off it, the upper block beside it or, on a block touching the axis, on the axis too
     * (a contact zone centred on the axis, as a sphere on a flat), pressed only: the upper
     * block's top node on the axis is prescribed, and u_r = 0 there admits no slide. (0.7.0
     * drew it frictionless and under small kinematics only: with friction the axis node's
     * stick row made the contact system singular, and under finite kinematics the active
     * axis node was found uncovered by round-off.) */
    p.analysis = below(3) == 0 ? HYCON_AXISYMMETRIC : HYCON_PLANE_STRAIN;
    p.axis = 0.0;
    if (p.analysis == HYCON_AXISYMMETRIC) {
        p.axis = below(2) ? 0.0 : uniform(0.05, 1.0);
        if (p.axis == 0.0 && below(2)) {
            p.left = 0.0;
            p.slide = 0.0;
        }
        p.left += p.axis;
    }
    return p;
}

static void print_problem(const Problem *p) {
    fprintf(stderr,
            "  problem: %s, lower %zux%zu at [%.17g, +2], upper %zux%zu at [%.17g, +%.17g], gap "
            "%.17g, depth %.17g, slide %.17g, E %.17g/%.17g, nu %.17g/%.17g, mu %.17g, "
            "kinematics %d\n",
            p->analysis == HYCON_AXISYMMETRIC ? "axisymmetric" : "plane strain", p->lower[0],
            p->lower[1], p->axis, p->upper[0], p->upper[1], p->left, p->width, p->gap, p->depth,
            p->slide, p->moduli[0], p->moduli[1], p->poisson[0], p->poisson[1], p->friction,
            (int)p->kinematics);
}

static Variant identity(void) {
    Variant v;
    memset(&v, 0, sizeof v);
    v.length_scale = v.modulus_scale = 1.0;
    return v;
}

/* A grid block of n[0] x n[1] quads into `m`; `ids` gets its node ids row by row. */
static void block(Mesh *m, double x0, double y0, double w, double h, const size_t n[2],
                  size_t mat, size_t *ids) {
    size_t i, j, k = 0;
    for (j = 0; j <= n[1]; ++j)
        for (i = 0; i <= n[0]; ++i, ++k) {
            ids[k] = m->nn++;
            m->coords[2 * ids[k]] = x0 + w * (double)i / (double)n[0];
            m->coords[2 * ids[k] + 1] = y0 + h * (double)j / (double)n[1];
        }
    for (j = 0; j < n[1]; ++j)
        for (i = 0; i < n[0]; ++i) {
            size_t *c = &m->conn[4 * m->ne];
            c[0] = ids[j * (n[0] + 1) + i];
            c[1] = ids[j * (n[0] + 1) + i + 1];
            c[2] = ids[(j + 1) * (n[0] + 1) + i + 1];
            c[3] = ids[(j + 1) * (n[0] + 1) + i];
            m->material[m->ne] = mat;
            m->ne++;
            m->offsets[m->ne] = 4 * m->ne;
        }
}

/* `out = R(angle) x` */
static void rotate(double angle, const double x[2], double out[2]) {
    double c = cos(angle), s = sin(angle);
    out[0] = c * x[0] - s * x[1];
    out[1] = s * x[0] + c * x[1];
}

static void build(const Problem *p, const Variant *v, Mesh *m) {
    size_t lower[MAXN], upper[MAXN], i, k;
    double coords[2 * MAXN];
    memset(m, 0, sizeof *m);
    block(m, p->axis, 0.0, 2.0, 1.0, p->lower, 0, lower);
    block(m, p->left, 1.0 + p->gap, p->width, 1.0, p->upper, 1, upper);
    m->na = m->ntop = p->upper[0] + 1;
    m->nb = m->nbottom = p->lower[0] + 1;
    for (i = 0; i < m->na; ++i) {
        m->a[i] = upper[i];
        m->top[i] = upper[p->upper[1] * (p->upper[0] + 1) + i];
    }
    for (i = 0; i < m->nb; ++i) {
        m->b[i] = lower[p->lower[1] * (p->lower[0] + 1) + p->lower[0] - i];
        m->bottom[i] = lower[i];
    }
    if (p->analysis == HYCON_AXISYMMETRIC && p->axis == 0.0)
        for (i = 1; i <= p->lower[1]; ++i) m->axis[m->naxis++] = lower[i * (p->lower[0] + 1)];
    if (p->analysis == HYCON_AXISYMMETRIC && p->left == 0.0)
        for (i = 0; i < p->upper[1]; ++i) m->axis[m->naxis++] = upper[i * (p->upper[0] + 1)];
    for (i = 0; i < m->nn; ++i) {
        double x[2];
        for (k = 0; k < 2; ++k) x[k] = v->length_scale * (m->coords[2 * i + k] + v->translation[k]);
        rotate(v->angle, x, &m->coords[2 * i]);
    }
    if (!v->renumber) return;
    memcpy(coords, m->coords, sizeof coords);
    for (i = 0; i < m->nn; ++i) {
        m->coords[2 * v->perm[i]] = coords[2 * i];
        m->coords[2 * v->perm[i] + 1] = coords[2 * i + 1];
    }
    for (i = 0; i < 4 * m->ne; ++i) m->conn[i] = v->perm[m->conn[i]];
    for (i = 0; i < m->na; ++i) m->a[i] = v->perm[m->a[i]], m->top[i] = v->perm[m->top[i]];
    for (i = 0; i < m->naxis; ++i) m->axis[i] = v->perm[m->axis[i]];
    for (i = 0; i < m->nb; ++i) m->b[i] = v->perm[m->b[i]], m->bottom[i] = v->perm[m->bottom[i]];
}

static void materials_of(const Problem *p, const Variant *v, HyconMaterial materials[2]) {
    size_t i;
    for (i = 0; i < 2; ++i) {
        materials[i].youngs = p->moduli[i] * v->modulus_scale;
        materials[i].poisson = p->poisson[i];
        materials[i].thickness = 1.0;
        materials[i].analysis = p->analysis;
    }
}

/* The model of the problem with `materials` (those of materials_of, or edited ones). */
static HyconStatus model_with(const Problem *p, const Mesh *m, const HyconMaterial materials[2],
                              HyconModel **out) {
    HyconStatus s;
    *out = NULL;
    HyconElementBlock elements;
    HyconPolyline a, b;
    elements.offsets = m->offsets;
    elements.nodes = m->conn;
    elements.n_elements = m->ne;
    elements.materials = m->material;
    elements.kind = HYCON_ELEMENT_HYBRID;
    a.nodes = m->a;
    a.n = m->na;
    b.nodes = m->b;
    b.n = m->nb;
    s = hycon_model_new(out, m->coords, m->nn, &elements, materials, 2);
    if (s == HYCON_OK) s = hycon_model_prescribe(*out, m->bottom, m->nbottom, HYCON_XY);
    if (s == HYCON_OK) s = hycon_model_prescribe(*out, m->top, m->ntop, HYCON_XY);
    if (s == HYCON_OK && m->naxis > 0) s = hycon_model_prescribe(*out, m->axis, m->naxis, HYCON_X);
    if (s == HYCON_OK) s = hycon_model_add_pair(*out, &a, &b, p->friction, NULL);
    return s;
}

static HyconStatus make_model(const Problem *p, const Variant *v, const Mesh *m,
                              HyconModel **out) {
    HyconMaterial materials[2];
    materials_of(p, v, materials);
    return model_with(p, m, materials, out);
}

/* the totals: the upper top moved by (slide, -depth), lengths scaled */
static void totals(const Problem *p, const Variant *v, const Mesh *m, double slide, double *load,
                   double *qp) {
    size_t i;
    memset(load, 0, 2 * m->nn * sizeof *load);
    memset(qp, 0, 2 * m->nn * sizeof *qp);
    for (i = 0; i < m->ntop; ++i) {
        double u[2];
        u[0] = v->length_scale * slide;
        u[1] = -v->length_scale * p->depth;
        rotate(v->angle, u, &qp[2 * m->top[i]]);
    }
}

/* ---------------------------------------------------------------------------------------- */
/* Hostile calls: each returns whether the promises held; counts per class */

#define N_CLASSES 15
static const char *class_names[N_CLASSES] = {
    "increment: NULL handle",        "increment: NULL load",
    "increment: wrong length",       "increment: non-finite load",
    "increment: non-finite prescribed", "node results: buffer too small",
    "node results: unknown pair",    "displacement: buffer too small",
    "records: out of range",         "b-node results: NULL buffer",
    "contact_new: bad options",      "prescribe: dof twice",
    "element: bad shape",            "forces: buffer too small",
    "model: bad analysis"};
static unsigned long calls[N_CLASSES];

typedef struct {
    double tn[MAXA], ts[MAXA], u[2 * MAXN];
    size_t records;
} Snapshot;

static bool snapshot(HyconContact *c, const Mesh *m, Snapshot *s) {
    HyconNodeResult r[MAXA];
    size_t i;
    memset(s, 0, sizeof *s);
    if (hycon_contact_node_results(c, 0, r, m->na, NULL) != HYCON_OK) return false;
    for (i = 0; i < m->na; ++i) s->tn[i] = r[i].tn, s->ts[i] = r[i].ts;
    if (hycon_contact_displacement(c, s->u, 2 * m->nn, NULL) != HYCON_OK) return false;
    return hycon_contact_records(c, 0, NULL, 0, &s->records) == HYCON_OK;
}

static bool untouched(const double *a, size_t n) {
    size_t i;
    for (i = 0; i < n; ++i)
        if (a[i] != SENTINEL) return false;
    return true;
}

static bool failed_with_message(HyconStatus s) {
    char message[256];
    return s != HYCON_OK && hycon_last_error_message(message, sizeof message) > 1 &&
           strlen(message) > 0;
}

static bool hostile_call(HyconContact *c, const Problem *p, const Variant *v, const Mesh *m) {
    static double load[2 * MAXN], qp[2 * MAXN], out[2 * MAXN + 8];
    HyconNodeResult nodes[MAXA + 1];
    HyconIterationRecord records[2];
    HyconIncrementInfo info;
    Snapshot before, after;
    HyconStatus s = HYCON_OK;
    size_t n = 2 * m->nn, i, k = below(N_CLASSES);
    bool ok = true;
    if (!snapshot(c, m, &before)) return false;
    totals(p, v, m, p->slide, load, qp);
    for (i = 0; i < 2 * MAXN + 8; ++i) out[i] = SENTINEL;
    memset(&info, 0xA5, sizeof info);
    calls[k]++;
    switch (k) {
    case 0: s = hycon_contact_increment(NULL, load, n, qp, n, &info); break;
    case 1: s = hycon_contact_increment(c, NULL, n, qp, n, &info); break;
    case 2: s = hycon_contact_increment(c, load, n - 1 - below(2), qp, n, &info); break;
    case 3:
        load[below(n)] = below(2) ? NAN : -INFINITY;
        s = hycon_contact_increment(c, load, n, qp, n, &info);
        break;
    case 4:
        qp[2 * m->top[below(m->ntop)] + below(2)] = below(2) ? NAN : INFINITY;
        s = hycon_contact_increment(c, load, n, qp, n, &info);
        break;
    case 5:
        for (i = 0; i <= MAXA; ++i) nodes[i].tn = SENTINEL;
        s = hycon_contact_node_results(c, 0, nodes, m->na - 1, NULL);
        for (i = 0; i <= MAXA; ++i) ok = ok && nodes[i].tn == SENTINEL;
        break;
    case 6: s = hycon_contact_node_results(c, 1 + below(3), nodes, MAXA, NULL); break;
    case 7: s = hycon_contact_displacement(c, out, n - 1 - below(n), NULL); break;
    case 8: {
        size_t count = 0;
        hycon_contact_records(c, 0, NULL, 0, &count);
        records[0].r = SENTINEL;
        s = hycon_contact_records(c, count + 1 + below(3), records, 2, NULL);
        ok = ok && records[0].r == SENTINEL;
        break;
    }
    case 9: s = hycon_contact_b_node_results(c, 0, NULL, m->nb, NULL); break;
    case 10: {
        HyconContactOptions o;
        HyconModel *model = NULL;
        HyconContact *marker = (HyconContact *)(void *)&marker, *fresh = marker;
        hycon_contact_options_default(&o);
        switch (below(4)) {
        case 0: o.tolerance = NAN; break;
        case 1: o.kinematics = 0; break;
        case 2: o.search_distance = -1.0; break;
        default: o.backend = 77; break;
        }
        ok = ok && make_model(p, v, m, &model) == HYCON_OK;
        s = hycon_contact_new(&fresh, model, &o);
        ok = ok && fresh == marker;
        hycon_model_free(model);
        break;
    }
    case 11: {
        HyconModel *model = NULL;
        size_t twice[2];
        twice[0] = twice[1] = m->a[below(m->na)];
        ok = ok && make_model(p, v, m, &model) == HYCON_OK;
        s = hycon_model_prescribe(model, twice, 2, HYCON_X);
        hycon_model_free(model);
        break;
    }
    case 12: {
        /* a dart (reflex corner), a clockwise square or a pentagon of 5 corners */
        static const double shapes[3][10] = {{0, 0, 2, 0, 0.5, 0.5, 0, 2, 0, 0},
                                             {0, 0, 0, 1, 1, 1, 1, 0, 0, 0},
                                             {0, 0, 1, 0, 1.5, 0.8, 0.5, 1.5, -0.5, 0.8}};
        size_t shape = below(3);
        s = hycon_element_check(HYCON_ELEMENT_HYBRID, shape == 2 ? 5 : 4, shapes[shape]);
        break;
    }
    case 13: s = hycon_contact_forces(c, out, n - 1 - below(n), NULL); break;
    default: {
        /* two analysis kinds in one model, a thickness other than 1 in axisymmetry, or (in
         * axisymmetry) the mesh moved across the axis: an error, the handle untouched */
        HyconMaterial materials[2];
        HyconElementBlock elements;
        HyconModel *marker = (HyconModel *)(void *)&marker, *fresh = marker;
        static double moved[2 * MAXN];
        const size_t what = below(p->analysis == HYCON_AXISYMMETRIC ? 3 : 1);
        materials_of(p, v, materials);
        memcpy(moved, m->coords, 2 * m->nn * sizeof *moved);
        if (what == 0)
            materials[below(2)].analysis =
                p->analysis == HYCON_AXISYMMETRIC ? HYCON_PLANE_STRESS : HYCON_AXISYMMETRIC;
        else if (what == 1)
            materials[below(2)].thickness = 2.0;
        else
            for (i = 0; i < m->nn; ++i) moved[2 * i] -= v->length_scale * (p->axis + 0.01);
        elements.offsets = m->offsets;
        elements.nodes = m->conn;
        elements.n_elements = m->ne;
        elements.materials = m->material;
        elements.kind = HYCON_ELEMENT_HYBRID;
        s = hycon_model_new(&fresh, moved, m->nn, &elements, materials, 2);
        ok = ok && fresh == marker;
        if (s == HYCON_OK) hycon_model_free(fresh);
        break;
    }
    }
    ok = ok && failed_with_message(s) && untouched(out, 2 * MAXN + 8);
    for (i = 0; i < sizeof info; ++i) ok = ok && ((unsigned char *)&info)[i] == 0xA5;
    ok = ok && snapshot(c, m, &after) && memcmp(&before, &after, sizeof before) == 0;
    if (!ok) fprintf(stderr, "  hostile call \"%s\" broke a promise (status %d)\n", class_names[k],
                     (int)s);
    return ok;
}

/* ---------------------------------------------------------------------------------------- */
/* Runs */

typedef struct {
    HyconStatus status; /* of the first failing call, or HYCON_OK */
    /* the failure is the class that has no state satisfying the conditions: a B node
     * penetrates between two open A nodes (a much stiffer multiplier side A) */
    bool no_state;
    size_t na, zero_iterations;
    double tn[3][MAXA], ts[3][MAXA];
    char message[256]; /* of the first failing call */
} Outcome;

static bool hostile_ok = true;

/* Press, slide, repeat the totals; `hostile` bad calls between the increments. */
static Outcome run(const Problem *p, const Variant *v, size_t hostile) {
    static double load[2 * MAXN], qp[2 * MAXN];
    Outcome o;
    Mesh m;
    HyconModel *model = NULL;
    HyconContact *c = NULL;
    HyconContactOptions options;
    size_t step, i;
    memset(&o, 0, sizeof o);
    build(p, v, &m);
    o.na = m.na;
    hycon_contact_options_default(&options);
    options.kinematics = p->kinematics;
    o.status = make_model(p, v, &m, &model);
    if (o.status == HYCON_OK) o.status = hycon_contact_new(&c, model, &options);
    if (o.status != HYCON_OK) hycon_last_error_message(o.message, sizeof o.message);
    hycon_model_free(model);
    for (step = 0; step < 3 && o.status == HYCON_OK; ++step) {
        HyconIncrementInfo info;
        HyconNodeResult r[MAXA];
        totals(p, v, &m, step == 0 ? 0.0 : p->slide, load, qp);
        o.status = hycon_contact_increment(c, load, 2 * m.nn, qp, 2 * m.nn, &info);
        if (o.status != HYCON_OK) {
            hycon_last_error_message(o.message, sizeof o.message);
            o.no_state =
                strstr(o.message, "a B node penetrates between two open A nodes") != NULL;
            break;
        }
        if (step == 2) o.zero_iterations = info.iterations;
        o.status = hycon_contact_node_results(c, 0, r, m.na, NULL);
        for (i = 0; i < m.na; ++i) o.tn[step][i] = r[i].tn, o.ts[step][i] = r[i].ts;
        for (i = 0; i < hostile; ++i) hostile_ok = hostile_call(c, p, v, &m) && hostile_ok;
    }
    hycon_contact_free(c);
    return o;
}

/* `got` equals `want` times `factor` to `tol` of the peak |tn| */
static bool same(const Outcome *want, const Outcome *got, double factor, double tol) {
    double peak = 0.0;
    size_t s, i;
    if (want->status != got->status) return false;
    if (want->status != HYCON_OK) return true;
    for (s = 0; s < 3; ++s)
        for (i = 0; i < want->na; ++i) peak = fmax(peak, fabs(want->tn[s][i]));
    for (s = 0; s < 3; ++s)
        for (i = 0; i < want->na; ++i)
            if (fabs(want->tn[s][i] * factor - got->tn[s][i]) > tol * peak * fabs(factor) ||
                fabs(want->ts[s][i] * factor - got->ts[s][i]) > tol * peak * fabs(factor))
                return false;
    return true;
}

int main(int argc, char **argv) {
    double seconds = argc > 1 ? atof(argv[1]) : 3.0;
    uint64_t seed = argc > 2 ? strtoull(argv[2], NULL, 10) : 1;
    unsigned long max_rounds = argc > 3 ? strtoul(argv[3], NULL, 10) : 0;
    unsigned long rounds = 0, failures = 0, failed_problems = 0, no_state = 0, total = 0,
                  by_status[100], axisymmetric[3] = {0, 0, 0};
    clock_t start = clock();
    size_t k;
    rng = seed * 0x9E3779B97F4A7C15ULL + 1;
    memset(by_status, 0, sizeof by_status);
    while ((double)(clock() - start) < seconds * CLOCKS_PER_SEC &&
           (max_rounds == 0 || rounds < max_rounds)) {
        Problem p = draw_problem();
        Variant v = identity();
        Outcome base = run(&p, &v, 0), other;
        double tol = p.kinematics == HYCON_KINEMATICS_SMALL ? 1e-8 : 1e-5;
        bool ok = true;
        size_t i, nn = (p.lower[0] + 1) * (p.lower[1] + 1) + (p.upper[0] + 1) * (p.upper[1] + 1);
        ++rounds;
        if (p.analysis == HYCON_AXISYMMETRIC) /* off the axis, B on it, A and B on it */
            axisymmetric[p.axis > 0.0 ? 0 : p.left > 0.0 ? 1 : 2]++;
        if (base.status != HYCON_OK && base.no_state) {
            /* no state satisfies the discrete conditions (README, "Presses that settle"):
             * counted, not a violation */
            ++no_state;
        } else if (base.status != HYCON_OK) {
            /* since 0.7.0 every other problem of this distribution settles: one that fails
             * (alike in every variant or not) is a violation */
            ++failed_problems;
            by_status[(size_t)(-base.status) % 100]++;
            fprintf(stderr, "round %lu: the problem fails with %s: %s\n", rounds,
                    hycon_status_name(base.status), base.message);
            ok = false;
        }
        /* 1. the zero increment */
        if (base.status == HYCON_OK) {
            Outcome zero = base;
            memcpy(zero.tn[1], base.tn[2], sizeof zero.tn[1]);
            memcpy(zero.ts[1], base.ts[2], sizeof zero.ts[1]);
            if (base.zero_iterations > 3 || !same(&base, &zero, 1.0, tol)) {
                fprintf(stderr, "round %lu: the zero increment took %zu iterations or moved\n",
                            rounds, base.zero_iterations);
                ok = false;
            }
        }
        /* 2. rigid motion, unit scaling, renumbering */
        /* in axisymmetry the rigid motions are the translations along the axis */
        v.translation[1] = uniform(-1e3, 1e3);
        if (p.analysis != HYCON_AXISYMMETRIC) {
            v.translation[0] = uniform(-1e3, 1e3);
            v.angle = uniform(-3.14159, 3.14159);
        }
        other = run(&p, &v, 0);
        /* rotated, the flat surfaces carry round-off of the coordinates, eps |X|, in their
         * normal direction: relative to the approach, amplified by the contact system's
         * condition (up to 1e4 here) */
        if (!same(&base, &other, 1.0,
                  fmax(tol, 1e4 * DBL_EPSILON * (hypot(v.translation[0], v.translation[1]) + 3.0) /
                                (p.depth - p.gap)))) {
            fprintf(stderr, "round %lu: rigid motion by (%g, %g), %g rad changed the results\n",
                    rounds, v.translation[0], v.translation[1], v.angle);
            ok = false;
        }
        v = identity();
        v.length_scale = pow(10.0, (double)below(7) - 3.0);
        v.modulus_scale = pow(10.0, (double)below(7) - 3.0);
        other = run(&p, &v, 0);
        if (!same(&base, &other, v.modulus_scale, tol)) {
            fprintf(stderr, "round %lu: unit scaling (%g, %g) changed the results\n", rounds,
                    v.length_scale, v.modulus_scale);
            ok = false;
        }
        v = identity();
        v.renumber = true;
        for (i = 0; i < nn; ++i) v.perm[i] = i;
        for (i = nn - 1; i > 0; --i) {
            size_t j = below(i + 1), t = v.perm[i];
            v.perm[i] = v.perm[j];
            v.perm[j] = t;
        }
        other = run(&p, &v, 0);
        if (!same(&base, &other, 1.0, tol)) {
            fprintf(stderr, "round %lu: renumbering changed the results\n", rounds);
            ok = false;
        }
        /* 3. hostile calls change nothing */
        hostile_ok = true;
        v = identity();
        other = run(&p, &v, 1 + below(4));
        if (!hostile_ok || !same(&base, &other, 1.0, 0.0)) {
            fprintf(stderr, "round %lu: bad calls changed the run\n", rounds);
            ok = false;
        }
        if (!ok) {
            print_problem(&p);
            ++failures;
        }
    }
    printf("contact_randomized: seed %llu, %lu rounds (%lu problems failing, alike in every "
           "variant or not: each a violation; %lu without a state that satisfies the "
           "conditions, a B node between open A nodes), %lu violations\n",
           (unsigned long long)seed, rounds, failed_problems, no_state, failures);
    printf("  axisymmetric rounds: %lu off the axis, %lu with B on it, %lu with A and B on it\n",
           axisymmetric[0], axisymmetric[1], axisymmetric[2]);
    for (k = 1; k < 100; ++k)
        if (by_status[k] > 0)
            printf("  failing alike with %-19s %lu\n", hycon_status_name(-(HyconStatus)k),
                   by_status[k]);
    for (k = 0; k < N_CLASSES; ++k) {
        printf("  %-34s %lu\n", class_names[k], calls[k]);
        total += calls[k];
    }
    printf("  %-34s %lu\n", "bad calls in all", total);
    if (failures > 0) {
        printf("FAILED (reproduce: contact_randomized %g %llu %lu)\n", seconds,
               (unsigned long long)seed, rounds);
        return 1;
    }
    printf("OK\n");
    return 0;
}
