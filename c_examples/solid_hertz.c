/* Hertz's sphere in 3D through the C API's solid family (issue #43): a quarter model of a
 * paraboloid cap z = r^2 / (2 R) pressed on a block, both of 18-beta hybrid bricks, built here
 * in C (strict C99) the way hycon_lab::hertz3d builds it in Rust: R / a = 16, faces of size
 * h = a / (a/h) out to 1.5 a, graded by 1.3 beyond, the cap 8 a wide and high, the block 16 a
 * wide and deep. The block's bottom is held, the nodes on the symmetry planes x = 0 and y = 0
 * are held normal to them (and the planes declared), the cap's top is moved down by Hertz's
 * approach delta = a^2 / R of the target radius a; frictionless, one increment.
 *
 * Printed: the total load P (4 times the quarter's), the contact radius from the moments of the
 * contact forces (sum f r^2 / sum f = 2 a^2 / 5 for Hertz's pressure) and the peak pressure
 * (-tn at the centre node) against Hertz at P, and P against Hertz's load of the approach. At
 * a/h = 4 the Rust scene measured radius +1.52%, p0 +0.59%, P +5.79% (the finite bodies'
 * stiffening, not the mesh's: lab/tests/contact_hertz3d.rs); the checks are the Rust test's
 * (radius within 3%, p0 within 2%, P above Hertz by less than 10%), and B's forces must balance
 * A's. The valgrind run takes a/h = 2 (some 7400 dofs; 1 min 56 s at a/h = 4) with the coarse
 * mesh's tolerances (a/h < 4: radius within 12%, p0 within 10%, P above Hertz by less than
 * 10%; measured at a/h = 2: radius +9.87%, p0 -2.26%, P +4.33%; at a/h = 3: +2.33%, +7.99%,
 * +4.50%). The ASan+UBSan run takes a/h = 4: there the automatic ordering's nested-dissection
 * trial finds the sanitizer runtime and keeps AMD instead of loading METIS (whose dlopen with
 * RTLD_DEEPBIND the runtime refuses: src/solver/ordering.rs). Usage: solid_hertz [a/h]
 * (2..16, default 4). */
#include "hycon.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define PI 3.14159265358979323846
static const double youngs = 1.0, poisson = 0.3, radius = 1.0;

/* Coordinate lines from 0: `uniform` cells of h, then cells growing by `growth` up to
 * `length` (the last one stretched to reach it), as hycon's contact_meshes::lines. Returns the
 * number of lines written to `out` (room for `cap`). */
static size_t lines(double h, size_t uniform, double length, double growth, double *out,
                    size_t cap) {
    size_t n = 0, i;
    double cell = h;
    for (i = 0; i <= uniform && n < cap; ++i) out[n++] = (double)i * h;
    while (n < cap) {
        const double last = out[n - 1];
        cell *= growth;
        if (last + 1.5 * cell >= length) {
            out[n++] = length;
            break;
        }
        out[n++] = last + cell;
    }
    return n;
}

/* A structured block of bricks over the lines xs (n each way in x and y) and zs (nz): node
 * (i, j, k) is first + i + n (j + n k), brick nodes in hycon's brick order. Appends the bricks'
 * 8 node ids to `bricks` from brick `*n_bricks` on. */
static void block_bricks(size_t first, size_t n, size_t nz, size_t *bricks, size_t *n_bricks) {
    size_t i, j, k, c;
    for (k = 0; k + 1 < nz; ++k)
        for (j = 0; j + 1 < n; ++j)
            for (i = 0; i + 1 < n; ++i) {
                const size_t n0 = first + i + n * (j + n * k), up = n * n;
                const size_t ids[8] = {n0,      n0 + 1,      n0 + 1 + n,      n0 + n,
                                       n0 + up, n0 + 1 + up, n0 + 1 + n + up, n0 + n + up};
                for (c = 0; c < 8; ++c) bricks[8 * *n_bricks + c] = ids[c];
                ++*n_bricks;
            }
}

static double height(double x, double y) { return (x * x + y * y) / (2.0 * radius); }

static int check(int ok, const char *what) {
    if (!ok) printf("wrong value: %s\n", what);
    return ok;
}

static int fail(const char *call, HyconStatus s) {
    char message[1024];
    hycon_last_error_message(message, sizeof message);
    printf("FAILED: %s returned %s: %s\n", call, hycon_status_name(s), message);
    return 1;
}

int main(int argc, char **argv) {
    const size_t a_over_h = argc > 1 ? (size_t)strtoul(argv[1], NULL, 10) : 4;
    const double a = radius / 16.0, h = a / (double)a_over_h, zone = 1.5 * a * (1.0 + 1e-12);
    const size_t uniform = (size_t)ceil(1.5 * (double)a_over_h);
    const int coarse = a_over_h < 4; /* the memory-checked runs' mesh: looser tolerances */
    double cl[256], bl[256];
    size_t nc, nb, n_nodes, n_bricks = 0, i, j, k, n_a = 0, n_b = 0, top_k;
    double *coords, *load, *prescribed, *u;
    size_t *bricks, *a_faces, *b_faces, *held;
    size_t n_held;
    HyconSolidModel *model = NULL;
    HyconSolidContact *contact = NULL;
    HyconSolidNodeResult *results;
    HyconSolidBNodeResult *b_results;
    HyconIncrementInfo info;
    HyconStatus s;
    int ok = 1;
    const HyconSolidMaterial material = {youngs, poisson};
    const double e_star = youngs / (2.0 * (1.0 - poisson * poisson));
    const double delta = a * a / radius, origin[3] = {0.0, 0.0, 0.0};
    const double x_normal[3] = {1.0, 0.0, 0.0}, y_normal[3] = {0.0, 1.0, 0.0};

    if (a_over_h < 2 || a_over_h > 16) {
        printf("FAILED: a/h in 2..16\n");
        return 1;
    }
    nc = lines(h, uniform, 8.0 * a, 1.3, cl, 256);   /* the cap's lines in x, y and height */
    nb = lines(h, uniform, 16.0 * a, 1.3, bl, 256);  /* the block's in x, y and depth */
    n_nodes = nc * nc * nc + nb * nb * nb;
    coords = malloc(3 * n_nodes * sizeof *coords);
    load = calloc(3 * n_nodes, sizeof *load);
    prescribed = calloc(3 * n_nodes, sizeof *prescribed);
    u = malloc(3 * n_nodes * sizeof *u);
    held = malloc(3 * n_nodes * sizeof *held);
    bricks = malloc(8 * ((nc - 1) * (nc - 1) * (nc - 1) + (nb - 1) * (nb - 1) * (nb - 1)) *
                    sizeof *bricks);
    a_faces = malloc(2 * (nc - 1) * (nc - 1) * sizeof *a_faces);
    b_faces = malloc(2 * (nb - 1) * (nb - 1) * sizeof *b_faces);
    if (!coords || !load || !prescribed || !u || !held || !bricks || !a_faces || !b_faces) {
        printf("FAILED: out of memory\n");
        return 1;
    }

    /* the cap (nodes 0 ..): its bottom on the paraboloid, its top flat at H */
    for (k = 0; k < nc; ++k)
        for (j = 0; j < nc; ++j)
            for (i = 0; i < nc; ++i) {
                double *p = coords + 3 * (i + nc * (j + nc * k));
                const double x = cl[i], y = cl[j], top = cl[nc - 1], f = height(x, y);
                p[0] = x;
                p[1] = y;
                p[2] = k == nc - 1 ? top : f + cl[k] * (top - f) / top;
            }
    /* the block (nodes nc^3 ..): its top on z = 0 */
    for (k = 0; k < nb; ++k)
        for (j = 0; j < nb; ++j)
            for (i = 0; i < nb; ++i) {
                double *p = coords + 3 * (nc * nc * nc + i + nb * (j + nb * k));
                p[0] = bl[i];
                p[1] = bl[j];
                p[2] = -bl[nb - 1 - k];
            }
    block_bricks(0, nc, nc, bricks, &n_bricks);
    block_bricks(nc * nc * nc, nb, nb, bricks, &n_bricks);

    /* A: the cap's bottom faces (local face 4) within 1.5 a of the axis; B: the block's top
     * faces (local face 5) within 3 a of it in x and y */
    for (j = 0; j + 1 < nc; ++j)
        for (i = 0; i + 1 < nc; ++i)
            if (hypot(cl[i + 1], cl[j + 1]) <= zone) {
                a_faces[2 * n_a] = i + (nc - 1) * j;  /* bricks of layer k = 0 */
                a_faces[2 * n_a + 1] = 4;
                ++n_a;
            }
    top_k = nb - 2;
    for (j = 0; j + 1 < nb; ++j)
        for (i = 0; i + 1 < nb; ++i)
            if (bl[i + 1] <= 2.0 * zone && bl[j + 1] <= 2.0 * zone) {
                b_faces[2 * n_b] = (nc - 1) * (nc - 1) * (nc - 1) + i + (nb - 1) * (j + (nb - 1) * top_k);
                b_faces[2 * n_b + 1] = 5;
                ++n_b;
            }

    s = hycon_solid_model_new(&model, coords, n_nodes,
                              &(HyconBrickBlock){bricks, n_bricks, NULL, HYCON_BRICK_HYBRID18},
                              &material, 1);
    if (s != HYCON_OK) return fail("hycon_solid_model_new", s);

    /* the block's bottom held in x, y, z */
    n_held = 0;
    for (i = 0; i < nb * nb; ++i) held[n_held++] = nc * nc * nc + i;
    s = hycon_solid_model_prescribe(model, held, n_held, HYCON_XYZ);
    if (s != HYCON_OK) return fail("hycon_solid_model_prescribe (bottom)", s);
    /* the symmetry planes: x = 0 held in x, y = 0 in y (except the bottom, held already) */
    for (k = 0; k < 2; ++k) {
        n_held = 0;
        for (i = 0; i < n_nodes; ++i) {
            const double *p = coords + 3 * i;
            const int bottom = i >= nc * nc * nc && i < nc * nc * nc + nb * nb;
            if (p[k] == 0.0 && !bottom) held[n_held++] = i;
        }
        s = hycon_solid_model_prescribe(model, held, n_held, k == 0 ? HYCON_X : HYCON_Y);
        if (s != HYCON_OK) return fail("hycon_solid_model_prescribe (symmetry)", s);
        s = hycon_solid_model_add_symmetry_plane(model, origin, k == 0 ? x_normal : y_normal);
        if (s != HYCON_OK) return fail("hycon_solid_model_add_symmetry_plane", s);
    }
    /* the cap's top moved down by delta */
    n_held = 0;
    for (i = 0; i < nc * nc; ++i) {
        held[n_held] = i + nc * nc * (nc - 1);
        prescribed[3 * held[n_held] + 2] = -delta;
        ++n_held;
    }
    s = hycon_solid_model_prescribe(model, held, n_held, HYCON_Z);
    if (s != HYCON_OK) return fail("hycon_solid_model_prescribe (top)", s);
    s = hycon_solid_model_add_pair(model, &(HyconBrickFaces){a_faces, n_a},
                                   &(HyconBrickFaces){b_faces, n_b}, 0.0, NULL);
    if (s != HYCON_OK) return fail("hycon_solid_model_add_pair", s);

    s = hycon_solid_contact_new(&contact, model, NULL);
    hycon_solid_model_free(model); /* the analysis has its own copy */
    if (s != HYCON_OK) return fail("hycon_solid_contact_new", s);
    s = hycon_solid_contact_increment(contact, load, 3 * n_nodes, prescribed, 3 * n_nodes, &info);
    if (s != HYCON_OK) return fail("hycon_solid_contact_increment", s);
    s = hycon_solid_contact_displacement(contact, u, 3 * n_nodes, NULL);
    if (s != HYCON_OK) return fail("hycon_solid_contact_displacement", s);
    ok &= check(u[3 * (nc * nc * (nc - 1)) + 2] == -delta, "the cap's top moved by -delta");

    {
        size_t na = 0, nbn = 0, centre = (size_t)-1;
        double quarter = 0.0, moment = 0.0, on_a[3] = {0, 0, 0}, on_b[3] = {0, 0, 0};
        double load_p, hertz_a, hertz_p0, a_fem, p0, hertz_load;
        s = hycon_solid_contact_node_results(contact, 0, NULL, 0, &na);
        if (s != HYCON_OK) return fail("hycon_solid_contact_node_results (size)", s);
        s = hycon_solid_contact_b_node_results(contact, 0, NULL, 0, &nbn);
        if (s != HYCON_OK) return fail("hycon_solid_contact_b_node_results (size)", s);
        results = malloc(na * sizeof *results);
        b_results = malloc(nbn * sizeof *b_results);
        if (!results || !b_results) return 1;
        s = hycon_solid_contact_node_results(contact, 0, results, na, NULL);
        if (s != HYCON_OK) return fail("hycon_solid_contact_node_results", s);
        s = hycon_solid_contact_b_node_results(contact, 0, b_results, nbn, NULL);
        if (s != HYCON_OK) return fail("hycon_solid_contact_b_node_results", s);
        for (i = 0; i < na; ++i) {
            const HyconSolidNodeResult *r = results + i;
            const double *x = coords + 3 * r->node, r2 = x[0] * x[0] + x[1] * x[1];
            const double f = -(r->normal[0] * r->force[0] + r->normal[1] * r->force[1] +
                               r->normal[2] * r->force[2]);
            quarter += f;
            moment += f * r2;
            for (k = 0; k < 3; ++k) on_a[k] += r->force[k];
            if (r2 == 0.0) centre = i;
            ok &= check(r->state == HYCON_NODE_OPEN || r->state == HYCON_NODE_FRICTIONLESS,
                        "a frictionless pair's node is open or frictionless");
        }
        for (i = 0; i < nbn; ++i)
            for (k = 0; k < 3; ++k) on_b[k] += b_results[i].force[k];
        for (k = 0; k < 3; ++k)
            ok &= check(fabs(on_a[k] + on_b[k]) < 1e-12 * quarter, "B's forces balance A's");
        if (centre == (size_t)-1) return fail("no A node at the centre", HYCON_OK);
        load_p = 4.0 * quarter;
        a_fem = sqrt(2.5 * moment / quarter);
        p0 = -results[centre].tn;
        hertz_a = cbrt(3.0 * load_p * radius / (4.0 * e_star));
        hertz_p0 = 3.0 * load_p / (2.0 * PI * hertz_a * hertz_a);
        hertz_load = 4.0 * e_star * a * a * a / (3.0 * radius);
        printf("quarter cap on a block, a/h = %zu: %zu nodes, %zu bricks, %zu A faces, %zu B "
               "faces\n",
               a_over_h, n_nodes, n_bricks, n_a, n_b);
        printf("%zu iterations, %zu active A nodes of %zu\n", info.iterations, info.active, na);
        printf("load P   %.6e  Hertz at the approach %.6e  (%+.2f%%)\n", load_p, hertz_load,
               100.0 * (load_p / hertz_load - 1.0));
        printf("radius a %.6e  Hertz at P %.6e  (%+.2f%%)\n", a_fem, hertz_a,
               100.0 * (a_fem / hertz_a - 1.0));
        printf("peak p0  %.6e  Hertz at P %.6e  (%+.2f%%)\n", p0, hertz_p0,
               100.0 * (p0 / hertz_p0 - 1.0));
        ok &= check(fabs(a_fem / hertz_a - 1.0) < (coarse ? 0.12 : 0.03),
                    "contact radius within 3% of Hertz (12% at a/h < 4)");
        ok &= check(fabs(p0 / hertz_p0 - 1.0) < (coarse ? 0.10 : 0.02),
                    "peak pressure within 2% of Hertz (10% at a/h < 4)");
        ok &= check(load_p > hertz_load && load_p < 1.10 * hertz_load,
                    "load above Hertz's by less than the finite bodies' 10%");
        free(results);
        free(b_results);
    }

    hycon_solid_contact_free(contact);
    free(coords);
    free(load);
    free(prescribed);
    free(u);
    free(held);
    free(bricks);
    free(a_faces);
    free(b_faces);
    if (!ok) return 1;
    printf("ok\n");
    return 0;
}
