/* Hertz contact of a disk on a block through hycon's model API, from C99.
 *
 * The program builds its own mesh (disk_mesh.h: plane strain, quadrilaterals graded toward the
 * contact, a / R = 1/32, n elements per contact half-width a), gives it to hycon with the hybrid
 * element, ties the disk's flat top face to a rigid plate and presses it onto the block by force
 * control (HYCON_PLATE_FORCE in y, zero displacement in x) in 3 increments up to the Hertz load
 * of the target half-width, P = pi a^2 E* / (4 R). At each increment it compares the contact
 * pressure with Hertz at the measured load (sum of the A nodes' contact forces) three ways:
 *   multipliers  p = -tn at the A nodes (hycon_contact_node_results),
 *   B side       the pressures at the disk's arc nodes (hycon_contact_b_node_results),
 *   stresses     p = -tn from the block's element stresses (hycon_contact_stress_tractions),
 * printing the half-width (second moment of the pressure), the peak and the L2 error of each,
 * and checks them at the last increment (where a = n h; the earlier ones, with fewer elements
 * per half-width, are printed only) against the tolerances below. It also checks that the
 * plate carries the applied force and the contact balances it, that K was factored exactly once,
 * that the records (hycon_contact_records) match what the monitor saw, and that a wrong E*
 * (the factor 1 - nu^2 forgotten) fails the check (a negative control).
 *
 * The measured load is P = sum over the A nodes of -n . f (normal nodal contact forces); the
 * pressure centre is the multipliers' load centroid, used for all three curves.
 *
 * Usage: hertz_model [n [wrong-estar | cholmod]]   n = elements per half-width, 8..32 (default
 * 12; the tolerances scale with 1 / n). With `wrong-estar` the checks use the wrong E* and must
 * fail. With `cholmod` hycon factors K with CHOLMOD (HYCON_BACKEND_CHOLMOD: a library built with
 * the `suitesparse` feature) instead of faer; the checks are the same.
 * Prints OK on success; FAILED or "wrong value" and exit code 1 otherwise.
 */
#include "disk_mesh.h"

#include <string.h>

/* What the monitor saw: the records, to compare with hycon_contact_records afterwards. */
typedef struct MonitorLog {
    HyconIterationRecord records[256];
    size_t count;   /* records seen (the first 256 kept) */
    size_t printed; /* records printed */
} MonitorLog;

static int32_t monitor(void *user_data, const HyconIterationRecord *r) {
    MonitorLog *log = user_data;
    if (log->count < sizeof log->records / sizeof log->records[0]) log->records[log->count] = *r;
    ++log->count;
    printf("    increment %lu iteration %2lu: active %3lu (stick %lu, slip %3lu), changes %3lu, "
           "R = %.3e, cond = %.3e\n",
           (unsigned long)r->increment, (unsigned long)r->iteration, (unsigned long)r->active,
           (unsigned long)r->stick, (unsigned long)r->slip, (unsigned long)r->changes, r->r,
           r->condition);
    ++log->printed;
    return 0;
}

/* Tolerances on |a_h / a - 1|, |p0_h / p0 - 1| and the relative L2 error. */
typedef struct Tolerance {
    double half_width, peak, l2;
} Tolerance;

/* Check one comparison; prints the failures unless quiet. Returns the number of failures. */
static int check_fit(const char *label, const HertzFit *f, const Tolerance *tol, int quiet) {
    int failures = 0;
    double ea = fabs(f->half_width / f->a - 1.0), ep = fabs(f->peak / f->p0 - 1.0);
    if (!(ea <= tol->half_width)) {
        if (!quiet)
            printf("wrong value: %s half-width %.6e vs Hertz %.6e (%.2f%%, tolerance %.1f%%)\n",
                   label, f->half_width, f->a, 100.0 * ea, 100.0 * tol->half_width);
        ++failures;
    }
    if (!(ep <= tol->peak)) {
        if (!quiet)
            printf("wrong value: %s peak %.6e vs Hertz %.6e (%.2f%%, tolerance %.1f%%)\n", label,
                   f->peak, f->p0, 100.0 * ep, 100.0 * tol->peak);
        ++failures;
    }
    if (!(f->l2 <= tol->l2)) {
        if (!quiet)
            printf("wrong value: %s L2 error %.2f%% (tolerance %.1f%%)\n", label, 100.0 * f->l2,
                   100.0 * tol->l2);
        ++failures;
    }
    return failures;
}

/* The three pressure curves of the converged state (x measured from the load centre). */
typedef struct Curves {
    double load, centre;
    double *xa, *pa;  /* multipliers, n_a */
    double *xs, *ps;  /* element stresses, n_a */
    double *xb, *pb;  /* B side, n_b */
    double vertical;  /* sum of the A nodes' contact forces in y */
    size_t active;
} Curves;

static void read_curves(HyconContact *c, const DiskMesh *m, HyconNodeResult *nodes,
                        HyconBNodeResult *bnodes, double *tractions, Curves *cv) {
    size_t k;
    double wsum = 0.0, wx = 0.0;
    CHECK(hycon_contact_node_results(c, 0, nodes, m->n_a, NULL));
    CHECK(hycon_contact_b_node_results(c, 0, bnodes, m->n_b, NULL));
    CHECK(hycon_contact_stress_tractions(c, 0, tractions, 2 * m->n_a, NULL));
    cv->load = 0.0;
    cv->vertical = 0.0;
    cv->active = 0;
    for (k = 0; k < m->n_a; ++k) {
        const HyconNodeResult *r = &nodes[k];
        double p = -r->tn;
        cv->load -= r->normal[0] * r->force[0] + r->normal[1] * r->force[1];
        cv->vertical += r->force[1];
        /* small kinematics (the default): Hertz's coordinate is the reference position, not
         * `position` (reference plus displacement) */
        wsum += p * r->weight;
        wx += p * r->weight * m->coords[2 * r->node];
        if (r->state != HYCON_NODE_OPEN) ++cv->active;
    }
    cv->centre = wx / wsum;
    for (k = 0; k < m->n_a; ++k) {
        cv->xa[k] = m->coords[2 * nodes[k].node] - cv->centre;
        cv->pa[k] = -nodes[k].tn;
        cv->xs[k] = cv->xa[k];
        /* the element stresses are not zero outside the contact: tension is cut off there */
        cv->ps[k] = -tractions[2 * k] > 0.0 ? -tractions[2 * k] : 0.0;
    }
    for (k = 0; k < m->n_b; ++k) {
        size_t id = bnodes[k].node;
        cv->xb[k] = m->coords[2 * id] - cv->centre;
        cv->pb[k] = bnodes[k].pressure;
    }
}

int main(int argc, char **argv) {
    const double youngs = 1.0, poisson = 0.3, radius = 1.0, target = 1.0 / 32.0;
    const size_t n_increments = 3;
    const double e_star = youngs / (2.0 * (1.0 - poisson * poisson));
    /* the negative control: E* with the factor 1 - nu^2 forgotten (9% too small) */
    const double e_star_wrong = youngs / 2.0;
    size_t n = argc > 1 ? (size_t)strtoul(argv[1], NULL, 10) : 12;
    int use_wrong = argc > 2 && strcmp(argv[2], "wrong-estar") == 0;
    int use_cholmod = argc > 2 && strcmp(argv[2], "cholmod") == 0;
    DiskMeshParams params;
    DiskMesh m;
    HyconMaterial materials[2];
    HyconModel *model = NULL;
    HyconContact *c = NULL;
    HyconContactOptions options;
    MonitorLog *log;
    HyconNodeResult *nodes;
    HyconBNodeResult *bnodes;
    HyconIterationRecord *records;
    HyconTimings timings;
    Curves cv;
    double *load, *prescribed, *tractions, p_target;
    size_t n_field, step, k, n_records, factorizations;
    int failures = 0;
    Tolerance tol_multipliers, tol_b, tol_stress;

    if (n < 8 || n > 32) {
        fprintf(stderr, "usage: hertz_model [n [wrong-estar | cholmod]], 8 <= n <= 32\n");
        return EXIT_FAILURE;
    }
    /* Tolerances at the last increment, where a = n h. Measured there (n = 8, 12, 16, 24, 32;
     * small kinematics, positions taken in the reference configuration):
     *   multipliers: a -0.12 -0.08 -0.07 -0.05 -0.04 %, p0 +0.09 +0.03 +0.03 +0.03 +0.03 %,
     *     L2 4.64 3.12 2.36 1.59 1.20 % (about 38 % / n: the square-root edge resolved to one
     *     element);
     *   B side: a +0.91 +0.37 +0.19 +0.06 +0.02 % (about 7 % / n), p0 +0.01 0.00 +0.01 +0.02
     *     +0.02 %, L2 4.01 2.67 2.00 1.34 1.00 % (about 32 % / n);
     *   element stresses: a +5.01 +3.18 +2.31 +1.48 +1.09 % (about 38 % / n: the one-sided
     *     stresses smear the edge, which widens the second moment), p0 -2.21 -1.41 -1.02 -0.66
     *     -0.48 % (17 % / n), L2 5.60 3.80 2.89 1.96 1.48 % (46 % / n).
     * Hence 0.5 % on the multipliers' a and p0 (4x the worst), 12 % / n on the B side's a and
     * 0.5 % on its p0, 60 % / n on both L2 (1.6x the worst; 5 % at n = 12); 60 % / n, 30 % / n,
     * 75 % / n on the element stresses' a, p0, L2 (5, 2.5, 6.25 % at n = 12). (With 0.2's
     * finite kinematics the multipliers' a and p0 were off by -0.46 % and +0.45 % at every n.) A
     * wrong E* (1 - nu^2 forgotten: 9 % off) moves a and p0 by about 5 % and the L2 error to
     * about 9 %: the multipliers and the B side must reject it (checked below, the negative
     * control). */
    tol_multipliers.half_width = 0.005;
    tol_multipliers.peak = 0.005;
    tol_multipliers.l2 = 0.60 / (double)n;
    tol_b = tol_multipliers;
    tol_b.half_width = 0.12 / (double)n;
    tol_stress.half_width = 0.60 / (double)n;
    tol_stress.peak = 0.30 / (double)n;
    tol_stress.l2 = 0.75 / (double)n;

    params.radius = radius;
    params.half_width = target * radius;
    params.per_half_width = n;
    params.growth = 1.1;
    params.block_half_width = 2.0 * radius;
    params.block_depth = 2.0 * radius;
    m = disk_mesh_build(&params);
    printf("Hertz disk on block, model API: R = %g, target a = R/%g, h = a/%lu, %lu nodes, %lu "
           "elements (%lu block, %lu disk), %lu A nodes, %lu B nodes\n",
           radius, radius / target, (unsigned long)n, (unsigned long)m.n_nodes,
           (unsigned long)m.n_elements, (unsigned long)m.n_block_elements,
           (unsigned long)(m.n_elements - m.n_block_elements), (unsigned long)m.n_a,
           (unsigned long)m.n_b);

    for (k = 0; k < 2; ++k) {
        materials[k].youngs = youngs;
        materials[k].poisson = poisson;
        materials[k].thickness = 1.0;
        materials[k].analysis = HYCON_PLANE_STRAIN;
    }
    {
        const HyconElementBlock elements = {m.offsets, m.nodes, m.n_elements, m.materials,
                                            HYCON_ELEMENT_HYBRID};
        CHECK(hycon_model_new(&model, m.coords, m.n_nodes, &elements, materials, 2));
    }
    CHECK(hycon_model_prescribe(model, m.bottom, m.n_bottom, HYCON_XY));
    CHECK(hycon_model_set_plate(model, m.top, m.n_top));
    {
        const HyconPolyline a = {m.a, m.n_a}, b = {m.b, m.n_b};
        CHECK(hycon_model_add_pair(model, &a, &b, 0.0, NULL));
    }

    log = xcalloc(1, sizeof *log);
    CHECK(hycon_contact_options_default(&options));
    options.monitor = monitor;
    options.monitor_data = log;
    if (use_cholmod) options.backend = HYCON_BACKEND_CHOLMOD;
    printf("sparse backend: %s\n", use_cholmod ? "CHOLMOD" : "faer");
    CHECK(hycon_contact_new(&c, model, &options));
    hycon_model_free(model); /* the analysis keeps its own copy */
    model = NULL;

    CHECK(hycon_contact_displacement(c, NULL, 0, &n_field)); /* the size query */
    load = xcalloc(n_field, sizeof *load);
    prescribed = xcalloc(n_field, sizeof *prescribed);
    nodes = xcalloc(m.n_a, sizeof *nodes);
    bnodes = xcalloc(m.n_b, sizeof *bnodes);
    tractions = xcalloc(2 * m.n_a, sizeof *tractions);
    cv.xa = xcalloc(m.n_a, sizeof *cv.xa);
    cv.pa = xcalloc(m.n_a, sizeof *cv.pa);
    cv.xs = xcalloc(m.n_a, sizeof *cv.xs);
    cv.ps = xcalloc(m.n_a, sizeof *cv.ps);
    cv.xb = xcalloc(m.n_b, sizeof *cv.xb);
    cv.pb = xcalloc(m.n_b, sizeof *cv.pb);

    p_target = DISK_PI * params.half_width * params.half_width * e_star / (4.0 * radius);
    printf("E* = %.6f, Hertz load of the target half-width P = %.6e\n", e_star, p_target);
    for (step = 1; step <= n_increments; ++step) {
        const HyconPlateControl control[2] = {HYCON_PLATE_DISPLACEMENT, HYCON_PLATE_FORCE};
        double applied = p_target * (double)step / (double)n_increments;
        double value[2], plate_u[2], plate_f[2], es = use_wrong ? e_star_wrong : e_star;
        HyconIncrementInfo info;
        HertzFit fa, fb, fs;
        value[0] = 0.0;
        value[1] = -applied;
        printf("increment %lu: plate force -%.6e in y, x held\n", (unsigned long)step, applied);
        CHECK(hycon_contact_increment_with_plate(c, load, n_field, prescribed, n_field, control,
                                                 value, &info));
        CHECK(hycon_contact_plate(c, plate_u, plate_f));
        read_curves(c, &m, nodes, bnodes, tractions, &cv);
        printf("  converged in %lu iterations: %lu active nodes, plate displacement (%.3e, %.6e),"
               " plate force (%.3e, %.6e), contact load P = %.6e\n",
               (unsigned long)info.iterations, (unsigned long)info.active, plate_u[0], plate_u[1],
               plate_f[0], plate_f[1], cv.load);
        if (!(fabs(plate_f[1] + applied) <= 1e-9 * applied)) {
            printf("wrong value: plate force %.9e, applied %.9e\n", plate_f[1], -applied);
            ++failures;
        }
        /* the disk's equilibrium: the contact carries the plate force (to the iteration
         * tolerance 1e-6: the forces use the geometry re-evaluated after the last iterate) */
        if (!(fabs(cv.vertical + applied) <= 1e-6 * applied)) {
            printf("wrong value: vertical contact force %.9e, applied %.9e\n", cv.vertical,
                   -applied);
            ++failures;
        }
        fa = hertz_compare(cv.xa, cv.pa, m.n_a, cv.load, radius, es);
        fb = hertz_compare(cv.xb, cv.pb, m.n_b, cv.load, radius, es);
        fs = hertz_compare(cv.xs, cv.ps, m.n_a, cv.load, radius, es);
        printf("  Hertz at P: a = %.6e (a/h = %.2f), p0 = %.6e; pressure centre x = %.2e\n",
               fa.a, fa.a / m.h, fa.p0, cv.centre);
        hertz_print("multipliers (A nodes)", &fa);
        hertz_print("B side (disk nodes)", &fb);
        hertz_print("element stresses (A)", &fs);
        if (step == n_increments) {
            HertzFit wa, wb, ws;
            failures += check_fit("multipliers", &fa, &tol_multipliers, 0);
            failures += check_fit("B side", &fb, &tol_b, 0);
            failures += check_fit("element stresses", &fs, &tol_stress, 0);
            printf("tolerances: half-width / peak / L2 %.1f / %.1f / %.1f %% (multipliers), "
                   "%.1f / %.1f / %.1f %% (B side), %.1f / %.1f / %.1f %% (element stresses)\n",
                   100 * tol_multipliers.half_width, 100 * tol_multipliers.peak,
                   100 * tol_multipliers.l2, 100 * tol_b.half_width, 100 * tol_b.peak,
                   100 * tol_b.l2, 100 * tol_stress.half_width, 100 * tol_stress.peak,
                   100 * tol_stress.l2);
            /* negative control: the same pressures against Hertz with a wrong E* */
            if (!use_wrong) {
                int caught_a, caught_b, caught_s;
                wa = hertz_compare(cv.xa, cv.pa, m.n_a, cv.load, radius, e_star_wrong);
                wb = hertz_compare(cv.xb, cv.pb, m.n_b, cv.load, radius, e_star_wrong);
                ws = hertz_compare(cv.xs, cv.ps, m.n_a, cv.load, radius, e_star_wrong);
                printf("negative control, E* = E / 2 (1 - nu^2 forgotten):\n");
                hertz_print("multipliers (A nodes)", &wa);
                hertz_print("B side (disk nodes)", &wb);
                hertz_print("element stresses (A)", &ws);
                caught_a = check_fit("", &wa, &tol_multipliers, 1);
                caught_b = check_fit("", &wb, &tol_b, 1);
                caught_s = check_fit("", &ws, &tol_stress, 1);
                printf("  rejected by %d, %d, %d of the 3 checks (multipliers, B side, element "
                       "stresses)\n", caught_a, caught_b, caught_s);
                if (caught_a == 0 || caught_b == 0) {
                    printf("FAILED: the check does not notice a wrong E*\n");
                    ++failures;
                }
            }
        }
    }

    /* the records: as many as the monitor saw, and the same */
    CHECK(hycon_contact_records(c, 0, NULL, 0, &n_records)); /* the size query */
    records = xcalloc(n_records, sizeof *records);
    CHECK(hycon_contact_records(c, 0, records, n_records, NULL));
    if (n_records != log->count) {
        printf("wrong value: %lu records, the monitor saw %lu\n", (unsigned long)n_records,
               (unsigned long)log->count);
        ++failures;
    }
    for (k = 0; k < n_records && k < log->count && k < 256; ++k)
        if (memcmp(&records[k], &log->records[k], sizeof records[k]) != 0) {
            printf("wrong value: record %lu differs from the monitor's\n", (unsigned long)k);
            ++failures;
        }
    printf("%lu iteration records over %lu increments\n", (unsigned long)n_records,
           (unsigned long)n_increments);

    CHECK(hycon_contact_timings(c, &timings, &factorizations));
    printf("timings [s]: assembly %.3f, factorization %.3f, flexibility %.3f, load solves %.3f, "
           "iterations %.3f, recovery %.3f; %lu factorization(s)\n",
           timings.assembly, timings.factorization, timings.flexibility, timings.load_solves,
           timings.iterations, timings.recovery, (unsigned long)factorizations);
    if (factorizations != 1) {
        printf("wrong value: %lu factorizations of K, expected 1\n",
               (unsigned long)factorizations);
        ++failures;
    }

    hycon_contact_free(c);
    free(records);
    free(log);
    free(load);
    free(prescribed);
    free(nodes);
    free(bnodes);
    free(tractions);
    free(cv.xa);
    free(cv.pa);
    free(cv.xs);
    free(cv.ps);
    free(cv.xb);
    free(cv.pb);
    disk_mesh_free(&m);
    if (failures != 0) {
        printf("FAILED: %d check(s)\n", failures);
        return EXIT_FAILURE;
    }
    printf("OK\n");
    return EXIT_SUCCESS;
}
