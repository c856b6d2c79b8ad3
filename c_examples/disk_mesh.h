/* The Hertz scene of the contact examples (hertz_model.c, cholmod_host.c): a mesh built in C, the
 * closed form and the comparison with it. Static functions only, included by both examples.
 *
 * Geometry (plane strain, lengths in units of the disk radius R):
 * - block [-W, W] x [-D, 0], its top face y = 0;
 * - the lower half of a disk of radius R centred at (0, R): lowest point at the origin, flat top
 *   face y = R (where the disk is held or pushed).
 * Both are meshed with 4-node quadrilaterals only (nodes counter-clockwise), so the same mesh
 * serves the hybrid element, Pian-Sumihara and Q4. The element size at the contact is
 * h = a / n (a the target contact half-width, n the elements per half-width), uniform over
 * |x| <= 2a and down to a depth a, then growing geometrically (ratio `growth`) away from it:
 * - the block is a tensor grid graded in x (fine nodes at (k + 1/2) h: node-to-internode
 *   against the disk, whose arc nodes sit at arc lengths k h) and in y, the x lines blended
 *   toward a uniform spacing with depth (weight (depth / D)^2), so that the columns under the
 *   contact do not stay h wide down to the bottom;
 * - the disk is a Coons patch of the half disk whose four sides are the bottom arc
 *   (225..315 degrees, graded toward its middle), the two side arcs (180..225 and 315..360
 *   degrees) and the flat top face; the arc-wise parameter is blended toward uniform with height
 *   (weight eta^2) in the same way. The patch corners at 225 and 315 degrees lie on the smooth
 *   arc, so the two corner elements there have one angle near 180 degrees (178 degrees at
 *   n = 12, convex), and the elements along the arc near them are thin (the arc is coarse there
 *   while eta is graded toward the arc: edge ratio up to about 70 at n = 12). Both are 0.7 R
 *   from the contact, where they do not matter: the pressures converge as 1 / n to an offset of
 *   0.45 % that is the known O(a / R) effect of current-configuration geometry.
 * Contact pair: A (multipliers) = the block's top nodes with |x| <= 2a, right to left (the block
 * on the left of the walk, its elements' edges in counter-clockwise order); B = the disk's arc
 * nodes with |x| <= 2.5a, left to right (the disk on the left).
 *
 * Hertz (two identical bodies, plane strain, per unit thickness): E* = E / (2 (1 - nu^2)),
 * a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a), p(x) = p0 sqrt(1 - x^2 / a^2).
 */
#ifndef HYCON_EXAMPLES_DISK_MESH_H
#define HYCON_EXAMPLES_DISK_MESH_H

#include "hycon.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DISK_PI 3.14159265358979323846

/* Print the failing call with hycon's last error message and stop. */
static void report_failure(const char *call, HyconStatus status, const char *file, int line) {
    char message[512];
    size_t needed = hycon_last_error_message(message, sizeof message);
    fprintf(stderr, "%s:%d: %s returned %s (%d): %s%s\n", file, line, call,
            hycon_status_name(status), (int)status, message,
            needed > sizeof message ? " [truncated]" : "");
    printf("FAILED\n");
    exit(EXIT_FAILURE);
}

#define CHECK(call)                                                                            \
    do {                                                                                       \
        HyconStatus check_status_ = (call);                                                    \
        if (check_status_ != HYCON_OK) report_failure(#call, check_status_, __FILE__, __LINE__); \
    } while (0)

/* Allocation that stops the program (with FAILED) when memory runs out. */
static void *xcalloc(size_t count, size_t size) {
    void *p = calloc(count == 0 ? 1 : count, size);
    if (p == NULL) {
        fprintf(stderr, "out of memory (%lu x %lu bytes)\n", (unsigned long)count,
                (unsigned long)size);
        printf("FAILED\n");
        exit(EXIT_FAILURE);
    }
    return p;
}

/* The optional arguments after n of the contact hosts (cholmod_host, petsc_host): the
 * kinematics ("small" or "finite") and the friction coefficient mu in [0, 1] of their press.
 * Returns 1 when it read them, 0 when they are absent (or a PETSc option, "-...", is in their
 * place: the defaults passed in stay), -1 for arguments it cannot read. */
static inline int disk_case_args(int argc, char **argv, HyconKinematics *kinematics,
                                 double *friction) {
    char *end;
    if (argc < 3 || argv[2][0] == '-') return 0;
    if (strcmp(argv[2], "small") == 0)
        *kinematics = HYCON_KINEMATICS_SMALL;
    else if (strcmp(argv[2], "finite") == 0)
        *kinematics = HYCON_KINEMATICS_FINITE;
    else
        return -1;
    if (argc < 4) return -1;
    *friction = strtod(argv[3], &end);
    return end != argv[3] && *end == '\0' && *friction >= 0.0 && *friction <= 1.0 ? 1 : -1;
}

typedef struct DiskMeshParams {
    double radius;           /* R */
    double half_width;       /* target contact half-width a */
    size_t per_half_width;   /* n: element size h = a / n at the contact */
    double growth;           /* size ratio of neighbouring elements outside the fine zone */
    double block_half_width; /* W */
    double block_depth;      /* D */
} DiskMeshParams;

typedef struct DiskMesh {
    size_t n_nodes, n_elements, n_block_elements; /* block elements first, then the disk's */
    double *coords;    /* 2 n_nodes: x0 y0 x1 y1 ... */
    size_t *offsets;   /* n_elements + 1 (element e: nodes[offsets[e] .. offsets[e + 1]]) */
    size_t *nodes;     /* 4 n_elements, counter-clockwise */
    size_t *materials; /* n_elements: 0 block, 1 disk */
    size_t *bottom;    /* block bottom face (held) */
    size_t n_bottom;
    size_t *top; /* disk top face y = R (plate or prescribed approach) */
    size_t n_top;
    size_t *a; /* contact side A: block top, |x| <= 2a, right to left */
    size_t n_a;
    size_t *b; /* contact side B: disk arc, |x| <= 2.5a, left to right */
    size_t n_b;
    double h; /* element size at the contact */
} DiskMesh;

/* One side of a graded distribution: points start, start + h, ... while <= fine (uniform), then
 * steps h g, h g^2, ... up to `length`, the graded part scaled to end exactly there. Writes the
 * points to `out` unless NULL; returns their count. */
static size_t graded_side(double start, double h, double fine, double growth, double length,
                          double *out) {
    size_t count = 0, last_fine, k;
    double p = start, step = h, end;
    if (out) out[count] = p;
    ++count;
    while (p + h <= fine * (1.0 + 1e-12)) {
        p += h;
        if (out) out[count] = p;
        ++count;
    }
    last_fine = count - 1;
    end = p;
    while (p < length) {
        step *= growth;
        /* a last step shorter than half the previous one is merged into it */
        if (length - p < 0.5 * step && p > end) break;
        p += step;
        if (out) out[count] = p;
        ++count;
    }
    if (out && count - 1 > last_fine) {
        double scale = (length - end) / (out[count - 1] - end);
        for (k = last_fine + 1; k < count; ++k) out[k] = end + (out[k] - end) * scale;
        out[count - 1] = length;
    }
    return count;
}

/* Symmetric distribution on [-length, length]: the side from graded_side mirrored (a node at 0
 * when start is 0). Returns a malloc'd array and its count in *count. */
static double *graded_symmetric(double start, double h, double fine, double growth,
                                double length, size_t *count) {
    size_t m = graded_side(start, h, fine, growth, length, NULL), n, k;
    double *side = xcalloc(m, sizeof *side), *all;
    graded_side(start, h, fine, growth, length, side);
    n = start == 0.0 ? 2 * m - 1 : 2 * m;
    all = xcalloc(n, sizeof *all);
    for (k = 0; k < m; ++k) {
        all[n - m + k] = side[k];
        all[m - 1 - k] = -side[k];
    }
    free(side);
    *count = n;
    return all;
}

/* Point of the circle of radius r centred at (0, r) at angle phi from its lowest point. */
static void circle_point(double r, double phi, double *x, double *y) {
    *x = r * sin(phi);
    *y = r - r * cos(phi);
}

/* The Coons patch of the lower half disk at (xi, eta) in [0, 1]^2 (see the file comment). */
static void half_disk_point(double r, double xi, double eta, double *x, double *y) {
    const double q = 0.25 * DISK_PI;
    double bx, by, tx, ty, lx, ly, rx, ry, c00x, c00y, c10x, c10y, c01x, c01y, c11x, c11y;
    circle_point(r, (2.0 * xi - 1.0) * q, &bx, &by); /* bottom arc */
    tx = r * (2.0 * xi - 1.0);                       /* top face */
    ty = r;
    circle_point(r, -q * (1.0 + eta), &lx, &ly); /* left arc */
    circle_point(r, q * (1.0 + eta), &rx, &ry);  /* right arc */
    circle_point(r, -q, &c00x, &c00y);
    circle_point(r, q, &c10x, &c10y);
    c01x = -r, c01y = r, c11x = r, c11y = r;
    *x = (1 - eta) * bx + eta * tx + (1 - xi) * lx + xi * rx -
         ((1 - xi) * (1 - eta) * c00x + xi * (1 - eta) * c10x + (1 - xi) * eta * c01x +
          xi * eta * c11x);
    *y = (1 - eta) * by + eta * ty + (1 - xi) * ly + xi * ry -
         ((1 - xi) * (1 - eta) * c00y + xi * (1 - eta) * c10y + (1 - xi) * eta * c01y +
          xi * eta * c11y);
}

static void disk_mesh_free(DiskMesh *m) {
    free(m->coords);
    free(m->offsets);
    free(m->nodes);
    free(m->materials);
    free(m->bottom);
    free(m->top);
    free(m->a);
    free(m->b);
}

/* Build the scene's mesh (see the file comment). */
static DiskMesh disk_mesh_build(const DiskMeshParams *p) {
    DiskMesh m;
    const double r = p->radius, a = p->half_width, h = a / (double)p->per_half_width;
    const double w = p->block_half_width, d = p->block_depth, quarter = 0.25 * DISK_PI * r;
    /* dy/deta of the disk patch at its lowest point, so that eta steps are about h there */
    const double c = r * (0.25 * DISK_PI * sin(0.25 * DISK_PI) + 1.0 - cos(0.25 * DISK_PI));
    size_t nxs, nys, nss, nes, nx, ny, ni, nj, i, j, e = 0, k, base;
    double *xs = graded_symmetric(0.5 * h, h, 2.0 * a, p->growth, w, &nxs);
    double *ss = graded_symmetric(0.0, h, 2.0 * a, p->growth, quarter, &nss);
    double *ys, *es;
    nys = graded_side(0.0, h, a, p->growth, d, NULL);
    ys = xcalloc(nys, sizeof *ys);
    graded_side(0.0, h, a, p->growth, d, ys); /* depths below the top */
    nes = graded_side(0.0, h, a, p->growth, c, NULL);
    es = xcalloc(nes, sizeof *es);
    graded_side(0.0, h, a, p->growth, c, es);

    nx = nxs - 1, ny = nys - 1; /* block elements per row and column */
    ni = nss - 1, nj = nes - 1; /* disk elements along the arc and upward */
    m.h = h;
    m.n_nodes = (nx + 1) * (ny + 1) + (ni + 1) * (nj + 1);
    m.n_block_elements = nx * ny;
    m.n_elements = nx * ny + ni * nj;
    m.coords = xcalloc(2 * m.n_nodes, sizeof *m.coords);
    m.offsets = xcalloc(m.n_elements + 1, sizeof *m.offsets);
    m.nodes = xcalloc(4 * m.n_elements, sizeof *m.nodes);
    m.materials = xcalloc(m.n_elements, sizeof *m.materials);

    /* block: node (i, j) = j (nx + 1) + i, row j = 0 at the bottom */
    for (j = 0; j <= ny; ++j) {
        double depth = ys[ny - j], wgt = (depth / d) * (depth / d);
        for (i = 0; i <= nx; ++i) {
            double uniform = -w + 2.0 * w * (double)i / (double)nx;
            size_t id = j * (nx + 1) + i;
            m.coords[2 * id] = (1.0 - wgt) * xs[i] + wgt * uniform;
            m.coords[2 * id + 1] = -depth;
        }
    }
    for (j = 0; j < ny; ++j)
        for (i = 0; i < nx; ++i, ++e) {
            size_t n0 = j * (nx + 1) + i;
            m.nodes[4 * e] = n0;
            m.nodes[4 * e + 1] = n0 + 1;
            m.nodes[4 * e + 2] = n0 + nx + 2;
            m.nodes[4 * e + 3] = n0 + nx + 1;
            m.materials[e] = 0;
        }
    /* disk: node (i, j) = base + j (ni + 1) + i, row j = 0 on the arc, i left to right */
    base = (nx + 1) * (ny + 1);
    for (j = 0; j <= nj; ++j) {
        double eta = es[j] / c, wgt = eta * eta;
        for (i = 0; i <= ni; ++i) {
            double graded = 0.5 * (ss[i] / quarter + 1.0), uniform = (double)i / (double)ni;
            double xi = (1.0 - wgt) * graded + wgt * uniform;
            size_t id = base + j * (ni + 1) + i;
            half_disk_point(r, xi, eta, &m.coords[2 * id], &m.coords[2 * id + 1]);
        }
    }
    for (j = 0; j < nj; ++j)
        for (i = 0; i < ni; ++i, ++e) {
            size_t n0 = base + j * (ni + 1) + i;
            m.nodes[4 * e] = n0;
            m.nodes[4 * e + 1] = n0 + 1;
            m.nodes[4 * e + 2] = n0 + ni + 2;
            m.nodes[4 * e + 3] = n0 + ni + 1;
            m.materials[e] = 1;
        }
    for (k = 0; k <= m.n_elements; ++k) m.offsets[k] = 4 * k;

    /* node sets */
    m.n_bottom = nx + 1;
    m.bottom = xcalloc(m.n_bottom, sizeof *m.bottom);
    for (i = 0; i <= nx; ++i) m.bottom[i] = i;
    m.n_top = ni + 1;
    m.top = xcalloc(m.n_top, sizeof *m.top);
    for (i = 0; i <= ni; ++i) m.top[i] = base + nj * (ni + 1) + i;
    m.a = xcalloc(nx + 1, sizeof *m.a);
    m.n_a = 0;
    for (i = nx + 1; i-- > 0;) /* right to left */
        if (fabs(m.coords[2 * (ny * (nx + 1) + i)]) <= 2.0 * a * (1.0 + 1e-12))
            m.a[m.n_a++] = ny * (nx + 1) + i;
    m.b = xcalloc(ni + 1, sizeof *m.b);
    m.n_b = 0;
    for (i = 0; i <= ni; ++i)
        if (fabs(m.coords[2 * (base + i)]) <= 2.5 * a) m.b[m.n_b++] = base + i;

    free(xs);
    free(ss);
    free(ys);
    free(es);
    return m;
}

/* ------------------------------------------------------------------------------------------ */
/* Hertz */

typedef struct HertzFit {
    double load;       /* P per unit thickness (the measured contact load) */
    double a, p0;      /* Hertz at that load */
    double half_width; /* 2 sqrt(M2 / M0) of the pressure curve (a for Hertz) */
    double peak;       /* the curve at the centre */
    double l2;         /* || p_h - p_Hertz ||_L2 / || p_Hertz ||_L2 */
} HertzFit;

static double hertz_pressure(double a, double p0, double x) {
    double s = 1.0 - (x / a) * (x / a);
    return s > 0.0 ? p0 * sqrt(s) : 0.0;
}

/* Sort (x, p) pairs by x (insertion sort: the curves are short and nearly sorted). */
static void sort_curve(double *x, double *p, size_t n) {
    size_t i, j;
    for (i = 1; i < n; ++i) {
        double xi = x[i], pi = p[i];
        for (j = i; j > 0 && x[j - 1] > xi; --j) {
            x[j] = x[j - 1];
            p[j] = p[j - 1];
        }
        x[j] = xi;
        p[j] = pi;
    }
}

/* Compare the piecewise-linear pressure curve (x[k], p[k]) (x measured from the pressure centre,
 * any order; sorted in place) with Hertz at `load`:
 * half-width from the second moment (integral p x^2 / integral p = a^2 / 4 for Hertz, exact
 * Simpson per piece), the curve's value at x = 0, and the continuous relative L2 error (pieces
 * split at +-a where Hertz has its square-root edge, 8-point Gauss per piece). */
static HertzFit hertz_compare(double *x, double *p, size_t n, double load, double radius,
                              double e_star) {
    static const double g8[4][2] = {{0.1834346424956498, 0.3626837833783620},
                                    {0.5255324099163290, 0.3137066458778873},
                                    {0.7966664774136267, 0.2223810344533745},
                                    {0.9602898564975363, 0.1012285362903763}};
    HertzFit f;
    double m0 = 0.0, m2 = 0.0, num = 0.0, den = 0.0;
    size_t k, g, s;
    sort_curve(x, p, n);
    f.load = load;
    f.a = sqrt(4.0 * load * radius / (DISK_PI * e_star));
    f.p0 = 2.0 * load / (DISK_PI * f.a);
    f.peak = 0.0;
    for (k = 0; k + 1 < n; ++k) {
        double xa = x[k], xb = x[k + 1], pa = p[k], pb = p[k + 1];
        double xm = 0.5 * (xa + xb), pm = 0.5 * (pa + pb), w = (xb - xa) / 6.0;
        double cuts[4];
        size_t n_cuts = 0;
        if (!(xb > xa)) continue;
        m0 += w * (pa + 4.0 * pm + pb);
        m2 += w * (pa * xa * xa + 4.0 * pm * xm * xm + pb * xb * xb);
        if (xa <= 0.0 && 0.0 <= xb) f.peak = pa + (0.0 - xa) / (xb - xa) * (pb - pa);
        cuts[n_cuts++] = xa;
        if (xa < -f.a && -f.a < xb) cuts[n_cuts++] = -f.a;
        if (xa < f.a && f.a < xb) cuts[n_cuts++] = f.a;
        cuts[n_cuts++] = xb;
        for (s = 0; s + 1 < n_cuts; ++s) {
            double mid = 0.5 * (cuts[s] + cuts[s + 1]), half = 0.5 * (cuts[s + 1] - cuts[s]);
            for (g = 0; g < 8; ++g) {
                double xg = mid + (g < 4 ? -g8[g][0] : g8[g - 4][0]) * half;
                double wg = g8[g % 4][1] * half;
                double ph = pa + (xg - xa) / (xb - xa) * (pb - pa);
                double exact = hertz_pressure(f.a, f.p0, xg);
                num += wg * (ph - exact) * (ph - exact);
                den += wg * exact * exact;
            }
        }
    }
    f.half_width = m0 > 0.0 && m2 > 0.0 ? 2.0 * sqrt(m2 / m0) : 0.0;
    f.l2 = den > 0.0 ? sqrt(num / den) : INFINITY;
    return f;
}

/* One line of a Hertz comparison: relative errors of half-width and peak, and the L2 error. */
static void hertz_print(const char *label, const HertzFit *f) {
    printf("  %-26s a = %.6e (%+6.2f%%)  p0 = %.6e (%+6.2f%%)  L2 = %5.2f%%\n", label,
           f->half_width, 100.0 * (f->half_width / f->a - 1.0), f->peak,
           100.0 * (f->peak / f->p0 - 1.0), 100.0 * f->l2);
}

#endif /* HYCON_EXAMPLES_DISK_MESH_H */
