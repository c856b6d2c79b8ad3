/* Shrink fit of two thick tubes through the model API, axisymmetric (x = r, y = z, the full
 * circle): inner tube a <= r <= b + delta, outer tube b <= r <= c (docs/validation.md, "Shrink fit of two tubes": a = 0.5,
 * b = 1, c = 2, E = 1, nu = 0.3, delta = 1e-3), length 0.5, their ends held axially so that
 * Lame's plane-strain solution is exact. The interference is an overlap of the two meshes in
 * the reference configuration; one increment with no load closes it (small kinematics).
 *
 * Checked: the contact pressure (the multipliers on the outer bore, A) at every A node equals
 * Lame's for the radii modelled to 1e-9, and the textbook value
 * p = E delta (b^2 - a^2)(c^2 - b^2) / (2 b^3 (1 - nu^2)(c^2 - a^2)) within 0.1%.
 * Argument: elements through each wall (default 8). */
#include <hycon.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define CHECK(call)                                                                            \
    do {                                                                                       \
        const HyconStatus st_ = (call);                                                        \
        if (st_ != HYCON_OK) {                                                                 \
            char msg_[512];                                                                    \
            hycon_last_error_message(msg_, sizeof msg_);                                        \
            fprintf(stderr, "FAILED: %s -> %d: %s\n", #call, (int)st_, msg_);                   \
            return 1;                                                                          \
        }                                                                                      \
    } while (0)

enum { MAX_NR = 64, NZ_OUTER = 4, NZ_INNER = 3 };

static const double A = 0.5, B = 1.0, C = 2.0, DELTA = 1e-3, LENGTH = 0.5, E = 1.0, NU = 0.3;

/* Append a tube r0 <= r <= r1, 0 <= z <= LENGTH with nr x nz elements (counter-clockwise);
 * node (i, j) is first + j (nr + 1) + i. */
static size_t tube(double r0, double r1, size_t nr, size_t nz, double *coords, size_t first,
                   size_t *offsets, size_t *nodes, size_t e0) {
    size_t i, j, e = e0;
    for (j = 0; j <= nz; ++j)
        for (i = 0; i <= nr; ++i) {
            coords[2 * (first + j * (nr + 1) + i)] = r0 + (r1 - r0) * (double)i / (double)nr;
            coords[2 * (first + j * (nr + 1) + i) + 1] = LENGTH * (double)j / (double)nz;
        }
    for (j = 0; j < nz; ++j)
        for (i = 0; i < nr; ++i, ++e) {
            const size_t n0 = first + j * (nr + 1) + i;
            nodes[4 * e] = n0;
            nodes[4 * e + 1] = n0 + 1;
            nodes[4 * e + 2] = n0 + nr + 2;
            nodes[4 * e + 3] = n0 + nr + 1;
            offsets[e + 1] = 4 * (e + 1);
        }
    return e;
}

/* u_r of a tube's surface at radius r under the stresses (s_r, s_theta), plane strain. */
static double radial(double r, double s_r, double s_t) {
    return r * (1.0 + NU) / E * ((1.0 - NU) * s_t - NU * s_r);
}

int main(int argc, char **argv) {
    const size_t nr = argc > 1 ? (size_t)atoi(argv[1]) : 8;
    const size_t n_outer = (nr + 1) * (NZ_OUTER + 1), n_inner = (nr + 1) * (NZ_INNER + 1);
    const size_t n_nodes = n_outer + n_inner, n_el = nr * (NZ_OUTER + NZ_INNER);
    static double coords[2 * (MAX_NR + 1) * (NZ_OUTER + NZ_INNER + 2)];
    static size_t offsets[MAX_NR * (NZ_OUTER + NZ_INNER) + 1];
    static size_t nodes[4 * MAX_NR * (NZ_OUTER + NZ_INNER)];
    static size_t ends[4 * (MAX_NR + 1)], a[NZ_OUTER + 1], b[NZ_INNER + 1];
    static double zero[2 * (MAX_NR + 1) * (NZ_OUTER + NZ_INNER + 2)];
    static HyconNodeResult results[NZ_OUTER + 1];
    const HyconMaterial steel = {E, NU, 1.0, HYCON_AXISYMMETRIC};
    HyconModel *model = NULL;
    HyconContact *c = NULL;
    HyconIncrementInfo info;
    size_t i, j, n_ends = 0, failures = 0;
    double d, u_outer, u_inner, p_exact, p_book;
    if (nr < 1 || nr > MAX_NR) {
        fprintf(stderr, "FAILED: elements through the wall must be 1 to %d\n", MAX_NR);
        return 1;
    }
    offsets[0] = 0;
    tube(B, C, nr, NZ_OUTER, coords, 0, offsets, nodes, 0);
    tube(A, B + DELTA, nr, NZ_INNER, coords, n_outer, offsets, nodes, nr * NZ_OUTER);
    /* A: the outer bore (i = 0) from the top down; B: the inner outside (i = nr) upward */
    for (j = 0; j <= NZ_OUTER; ++j) a[j] = (NZ_OUTER - j) * (nr + 1);
    for (j = 0; j <= NZ_INNER; ++j) b[j] = n_outer + j * (nr + 1) + nr;
    for (i = 0; i <= nr; ++i) {
        ends[n_ends++] = i;
        ends[n_ends++] = NZ_OUTER * (nr + 1) + i;
        ends[n_ends++] = n_outer + i;
        ends[n_ends++] = n_outer + NZ_INNER * (nr + 1) + i;
    }
    {
        const HyconElementBlock elements = {offsets, nodes, n_el, NULL, HYCON_ELEMENT_HYBRID};
        const HyconPolyline pa = {a, NZ_OUTER + 1}, pb = {b, NZ_INNER + 1};
        CHECK(hycon_model_new(&model, coords, n_nodes, &elements, &steel, 1));
        CHECK(hycon_model_prescribe(model, ends, n_ends, HYCON_Y)); /* ends held axially */
        CHECK(hycon_model_add_pair(model, &pa, &pb, 0.0, NULL));
    }
    CHECK(hycon_contact_new(&c, model, NULL));
    hycon_model_free(model);
    /* no load, nothing moved: the overlap alone presses the tubes together */
    CHECK(hycon_contact_increment(c, zero, 2 * n_nodes, zero, 2 * n_nodes, &info));
    CHECK(hycon_contact_node_results(c, 0, results, NZ_OUTER + 1, NULL));
    /* Lame for the radii modelled: u_outer(b) - u_inner(d) = delta, p_outer b = p_inner d */
    d = B + DELTA;
    u_outer = radial(B, -1.0, (B * B + C * C) / (C * C - B * B));
    u_inner = radial(d, -1.0, -(d * d + A * A) / (d * d - A * A));
    p_exact = DELTA / (u_outer - u_inner * B / d);
    p_book = E * DELTA * (B * B - A * A) * (C * C - B * B) /
             (2.0 * B * B * B * (1.0 - NU * NU) * (C * C - A * A));
    printf("shrink fit, %u elements through each wall, %u iterations\n", (unsigned)nr,
           (unsigned)info.iterations);
    printf("Lame (radii modelled) p = %.10e, textbook p = %.10e\n", p_exact, p_book);
    for (j = 0; j <= NZ_OUTER; ++j) {
        const double p = -results[j].tn;
        const int ok = fabs(p / p_exact - 1.0) < 1e-9 && fabs(p / p_book - 1.0) < 1e-3;
        printf("  z = %.4f  p = %.10e  (%+.1e vs Lame, %+.1e vs textbook)%s\n",
               results[j].position[1], p, p / p_exact - 1.0, p / p_book - 1.0,
               ok ? "" : "  wrong value");
        failures += !ok;
    }
    hycon_contact_free(c);
    if (failures) {
        printf("FAILED: %u nodes\n", (unsigned)failures);
        return 1;
    }
    return 0;
}
