/* A distributed host: a PETSc program over MPI drives hycon's contact iteration (issue #14).
 *
 * The model is the Hertz scene of the other contact examples (disk_mesh.h: a half disk of
 * radius R on a block, plane strain, E = 1, nu = 0.3, both bodies meshed with 4-node quads,
 * graded toward the contact, target half-width a = R/32, n elements per half-width). Every rank
 * builds the same mesh (it is small next to the matrix); the FE work is distributed:
 *   - the global dofs are 2 node + d (u_x, u_y); PETSc splits the rows of a MATMPIAIJ over the
 *     ranks (PETSC_DECIDE); each rank assembles a contiguous share of the elements (stiffness
 *     from hycon_element_stiffness, HYCON_ELEMENT_HYBRID) with MatSetValues(ADD_VALUES), and
 *     PETSc's assembly ships the off-rank entries;
 *   - Dirichlet conditions the PETSc way: the block bottom held, the disk's flat top face moved
 *     by a prescribed displacement (approach delta down, slide s sideways); MatZeroRowsColumns
 *     with the prescribed values gives the right-hand sides of a unit approach and of a unit
 *     slide (identity rows at the held dofs, their prescribed value in the right-hand side);
 *   - the linear solver is a KSP: PREONLY + Cholesky by MUMPS (Debian's PETSc has MUMPS),
 *     factored once; KSPSetFromOptions lets -ksp_type / -pc_type change it (e.g.
 *     -ksp_type cg -pc_type gamg -ksp_rtol 1e-12: the press then matched the CSR path to 1e-10,
 *     but one right-hand side took 0.6 s and the run at n = 8 on 2 ranks had not finished in
 *     5 minutes, against 5 s with MUMPS).
 * hycon runs on rank 0 only, through the host API: the contact polylines in the global
 * numbering, a solve callback (hycon_host_set_solver). The callback broadcasts a command
 * (solve, nrhs) to the other ranks, scatters the nrhs right-hand sides into a distributed dense
 * matrix, all ranks call KSPMatSolve (one MUMPS solve phase for all columns), and the solution
 * is gathered back to rank 0. The other ranks sit in a serve loop (non-blocking broadcast
 * polled with a short sleep, so an idle rank does not spin a core) until rank 0 sends "done"
 * with the exit code.
 *
 * Checked (rank 0; a failure prints "wrong value", the program prints FAILED and all ranks
 * exit 1):
 *   - the distributed assembly: the gathered matrix times a vector, and the two unit
 *     right-hand sides, against an element-by-element product on rank 0 with the same
 *     Dirichlet treatment, to 1e-12 (dropping one element per rank gives 1e-2 and more);
 *   - the callback path against hycon's serial CSR path of the same global matrix (rank 0
 *     gathers it with MatCreateSubMatrices and gives its lower triangle to hycon_host_set_csr):
 *     A-node states identical, tn and ts to 1e-8 of max |tn|, the gathered displacement field
 *     (all dofs) to 1e-8 of max |u|, at every increment of two analyses:
 *       press: frictionless, small kinematics (or the kinematics and friction given on the
 *              command line: then the press alone), a trial approach a^2 / R, then the
 *              approach scaled to the Hertz load of the target half-width;
 *       slide: friction 0.3, finite kinematics, the same approach, then the disk's top moved
 *              sideways by 0.01 a, 0.05 a, 0.2 a, 0.4 a (partial slip, then gross sliding);
 *   - Hertz at the end of the press (multipliers): half-width (from the second moment of the
 *     pressure curve) and peak pressure within HERTZ_TOLERANCE of a = sqrt(4 P R / (pi E*)),
 *     p0 = 2 P / (pi a), E* = E / (2 (1 - nu^2)); the same comparison with a wrong
 *     E* = E / (1 - nu^2) must miss by more than the tolerance (the check can fail);
 *   - in gross sliding every active node slips and the tangential force is mu times the normal
 *     one within 2 %.
 * Printed: equations, ranks, solve callbacks and right-hand sides hycon asked for (setup,
 * increments, displacement recovery), time per increment of the callback path against the
 * CSR path.
 *
 * Usage: mpiexec -n <ranks> petsc_host [n [small|finite mu]] [PETSc options]  (n: elements
 * per contact half-width, 4..32, default 8; with the kinematics and the friction coefficient,
 * the press alone under them). Prints OK on success.
 *
 * Every hycon call of this program is in the "hycon calls" section below, one small function
 * per hycon function, so that a change of the C API touches only that section.
 */
#define _POSIX_C_SOURCE 200809L

#include "disk_mesh.h"

#include <petscksp.h>
#include <string.h>
#include <time.h>

#define HERTZ_TOLERANCE 0.05
#define MATCH_TOLERANCE 1e-8

/* ------------------------------------------------------------------------------------------ */
/* hycon calls: the only place this program calls the hycon API (see the file comment) */

/* A failed hycon call: print it with hycon's message and end all ranks. */
static void hc_fail(const char *call, HyconStatus status) {
    char message[512];
    hycon_last_error_message(message, sizeof message);
    fprintf(stderr, "%s returned %s (%d): %s\n", call, hycon_status_name(status), (int)status,
            message);
    printf("FAILED\n");
    fflush(stdout);
    MPI_Abort(MPI_COMM_WORLD, 1);
}

#define HC(call)                                                                               \
    do {                                                                                       \
        HyconStatus hc_status_ = (call);                                                       \
        if (hc_status_ != HYCON_OK) hc_fail(#call, hc_status_);                                \
    } while (0)

static void hc_element_stiffness(const double xy[8], const HyconMaterial *material,
                                 double k[64]) {
    HC(hycon_element_stiffness(HYCON_ELEMENT_HYBRID, 4, xy, material, k, 64));
}

static HyconContactOptions hc_options(HyconKinematics kinematics) {
    HyconContactOptions options;
    HC(hycon_contact_options_default(&options));
    options.kinematics = kinematics;
    return options;
}

/* A host description with one contact pair; `inside` is a point inside body A (the block):
 * where the disk touches the block over the whole stretch hycon judges, the polylines alone
 * cannot tell facing surfaces from back-to-back ones. */
static HyconHost *hc_host(size_t n_equations, const HyconHostNodes *a,
                          const HyconHostNodes *b, double friction, const double inside[2]) {
    HyconHost *host = NULL;
    HC(hycon_host_new(&host, n_equations));
    HC(hycon_host_add_pair(host, a, b, friction, HYCON_PLANE_STRAIN, 1.0, NULL));
    HC(hycon_host_set_pair_inside(host, 0, inside));
    return host;
}

static void hc_host_solver(HyconHost *host, HyconSolveFn solve, void *user_data) {
    HC(hycon_host_set_solver(host, solve, user_data));
}

/* The lower triangle of the host's matrix, CSR over its equations. */
static void hc_host_csr(HyconHost *host, const size_t *row_ptr, const size_t *columns,
                        const double *values) {
    HC(hycon_host_set_csr(host, row_ptr, columns, values, HYCON_CSR_LOWER));
}

/* The host's stiffness Schur complement over its candidate equations (m x m, column-major). */
static void hc_host_condensed(HyconHost *host, const int64_t *equations, size_t m,
                              const double *schur) {
    HyconCondensed condensed;
    condensed.size = sizeof condensed;
    condensed.kind = HYCON_CONDENSED_STIFFNESS;
    condensed.m = m;
    condensed.equations = equations;
    condensed.matrix = schur;
    HC(hycon_host_set_condensed(host, &condensed));
}

/* The contact forces of the last increment over the host's equations. */
static void hc_forces(const HyconContact *contact, double *out, size_t n) {
    HC(hycon_contact_forces(contact, out, n, NULL));
}

/* Start the analysis and free the description (the analysis does not need it). */
static HyconContact *hc_start(HyconHost *host, const HyconContactOptions *options) {
    HyconContact *contact = NULL;
    HC(hycon_contact_new_host(&contact, host, options));
    hycon_host_free(host);
    return contact;
}

static HyconIncrementInfo hc_increment(HyconContact *contact, const double *rhs, size_t n) {
    HyconIncrementInfo info;
    HC(hycon_contact_increment(contact, rhs, n, NULL, 0, &info));
    return info;
}

static void hc_node_results(const HyconContact *contact, HyconNodeResult *out, size_t n_a) {
    HC(hycon_contact_node_results(contact, 0, out, n_a, NULL));
}

static void hc_displacement(const HyconContact *contact, double *u, size_t n) {
    HC(hycon_contact_displacement(contact, u, n, NULL));
}

static void hc_free(HyconContact *contact) { hycon_contact_free(contact); }

/* ------------------------------------------------------------------------------------------ */
/* The distributed solver and the serve loop */

enum { CMD_SOLVE = 1, CMD_DONE = 2 };

typedef struct Solver {
    KSP ksp;
    PetscInt n;              /* global equations */
    PetscInt m_local;        /* rows of this rank */
    PetscMPIInt rank, size;
    int *rows, *starts;      /* per rank: row count and first row */
    int *counts, *displs;    /* per rank, scaled by nrhs (scratch) */
    double *pack;            /* rank 0: the columns regrouped by rank */
    size_t pack_len;
    size_t calls, columns, max_nrhs; /* what hycon asked for */
    double seconds;          /* rank 0: wall time in the collective solves */
    double ksp_seconds;      /* rank 0: of which in KSPMatSolve (the rest: moving the columns) */
} Solver;

/* Rank 0: send a command to the serve loops. Non-blocking broadcast, because the other ranks
 * receive it with one (blocking and non-blocking collectives do not match). */
static void send_command(long command, long value) {
    long message[2];
    MPI_Request request;
    message[0] = command;
    message[1] = value;
    MPI_Ibcast(message, 2, MPI_LONG, 0, PETSC_COMM_WORLD, &request);
    MPI_Wait(&request, MPI_STATUS_IGNORE);
}

/* Other ranks: wait for a command without spinning (Open MPI's blocking wait polls a core,
 * and rank 0 runs hycon's serial work meanwhile). */
static void receive_command(long message[2]) {
    MPI_Request request;
    int done = 0;
    struct timespec pause;
    pause.tv_sec = 0;
    pause.tv_nsec = 20000; /* 20 us */
    MPI_Ibcast(message, 2, MPI_LONG, 0, PETSC_COMM_WORLD, &request);
    for (;;) {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done) break;
        nanosleep(&pause, NULL);
    }
}

/* Collective: K X = B for nrhs columns. rhs and x (n x nrhs, column-major) live on rank 0; the
 * other ranks pass NULL. */
static PetscErrorCode solve_collective(Solver *s, size_t nrhs, const double *rhs, double *x) {
    Mat b, xm;
    PetscScalar *local;
    const PetscScalar *solution;
    PetscInt lda;
    double t0;
    size_t j;
    int r;

    PetscFunctionBeginUser;
    for (r = 0; r < s->size; ++r) {
        s->counts[r] = s->rows[r] * (int)nrhs;
        s->displs[r] = s->starts[r] * (int)nrhs;
    }
    if (s->rank == 0) {
        if (s->pack_len < (size_t)s->n * nrhs) {
            free(s->pack);
            s->pack_len = (size_t)s->n * nrhs;
            s->pack = xcalloc(s->pack_len, sizeof *s->pack);
        }
        /* rank r's block: its rows of column 0, of column 1, ... (its local column-major) */
        for (r = 0; r < s->size; ++r)
            for (j = 0; j < nrhs; ++j)
                memcpy(s->pack + s->displs[r] + j * (size_t)s->rows[r],
                       rhs + j * (size_t)s->n + s->starts[r], (size_t)s->rows[r] * sizeof *rhs);
    }
    PetscCall(MatCreateDense(PETSC_COMM_WORLD, s->m_local, PETSC_DECIDE, s->n, (PetscInt)nrhs,
                             NULL, &b));
    PetscCall(MatCreateDense(PETSC_COMM_WORLD, s->m_local, PETSC_DECIDE, s->n, (PetscInt)nrhs,
                             NULL, &xm));
    PetscCall(MatDenseGetLDA(b, &lda));
    PetscCheck(lda == s->m_local, PETSC_COMM_SELF, PETSC_ERR_PLIB, "unexpected leading dimension");
    PetscCall(MatDenseGetArrayWrite(b, &local));
    PetscCallMPI(MPI_Scatterv(s->pack, s->counts, s->displs, MPI_DOUBLE, local,
                              s->counts[s->rank], MPI_DOUBLE, 0, PETSC_COMM_WORLD));
    PetscCall(MatDenseRestoreArrayWrite(b, &local));
    t0 = MPI_Wtime();
    PetscCall(KSPMatSolve(s->ksp, b, xm));
    s->ksp_seconds += MPI_Wtime() - t0;
    PetscCall(MatDenseGetLDA(xm, &lda));
    PetscCheck(lda == s->m_local, PETSC_COMM_SELF, PETSC_ERR_PLIB, "unexpected leading dimension");
    PetscCall(MatDenseGetArrayRead(xm, &solution));
    PetscCallMPI(MPI_Gatherv(solution, s->counts[s->rank], MPI_DOUBLE, s->pack, s->counts,
                             s->displs, MPI_DOUBLE, 0, PETSC_COMM_WORLD));
    PetscCall(MatDenseRestoreArrayRead(xm, &solution));
    PetscCall(MatDestroy(&b));
    PetscCall(MatDestroy(&xm));
    if (s->rank == 0)
        for (r = 0; r < s->size; ++r)
            for (j = 0; j < nrhs; ++j)
                memcpy(x + j * (size_t)s->n + s->starts[r],
                       s->pack + s->displs[r] + j * (size_t)s->rows[r],
                       (size_t)s->rows[r] * sizeof *x);
    PetscFunctionReturn(0);
}

/* hycon's HyconSolveFn on rank 0. Never unwinds; a PETSc failure becomes a nonzero return. */
static int32_t petsc_solve_cb(void *user_data, size_t n, size_t nrhs, const double *rhs,
                              double *x) {
    Solver *s = user_data;
    double start = MPI_Wtime();
    size_t k;
    if (s == NULL || n != (size_t)s->n || rhs == NULL || x == NULL) return 1;
    if (nrhs == 0) return 0;
    send_command(CMD_SOLVE, (long)nrhs);
    if (solve_collective(s, nrhs, rhs, x) != 0) return 2;
    for (k = 0; k < n * nrhs; ++k)
        if (!isfinite(x[k])) return 3;
    ++s->calls;
    s->columns += nrhs;
    if (nrhs > s->max_nrhs) s->max_nrhs = nrhs;
    s->seconds += MPI_Wtime() - start;
    return 0;
}

/* Ranks other than 0: serve solves until rank 0 says done; returns the exit code it sends. */
static int serve(Solver *s) {
    long message[2];
    for (;;) {
        receive_command(message);
        if (message[0] == CMD_DONE) return (int)message[1];
        if (solve_collective(s, (size_t)message[1], NULL, NULL) != 0) {
            fprintf(stderr, "rank %d: the collective solve failed\n", (int)s->rank);
            MPI_Abort(PETSC_COMM_WORLD, 1);
        }
    }
}

/* ------------------------------------------------------------------------------------------ */
/* Rank 0: the contact analyses and their checks */

typedef struct Snapshot {
    HyconNodeResult *nodes; /* n_a */
    double *u;              /* the whole field */
} Snapshot;

typedef struct Counts {
    size_t calls, columns;
} Counts;

static Counts counts_since(const Solver *s, Counts before) {
    Counts c;
    c.calls = s->calls - before.calls;
    c.columns = s->columns - before.columns;
    return c;
}

static Counts counts_now(const Solver *s) {
    Counts c;
    c.calls = s->calls;
    c.columns = s->columns;
    return c;
}

/* Differences of x against ref, printed; returns the number of failed checks. */
static int compare(const char *label, size_t n_a, size_t n_field, const Snapshot *x,
                   const Snapshot *ref, double *worst_t, double *worst_u) {
    double tn_max = 0.0, u_max = 0.0, dtn = 0.0, dts = 0.0, du = 0.0;
    size_t k, states = 0;
    int failures = 0;
    for (k = 0; k < n_a; ++k) {
        const HyconNodeResult *p = &x->nodes[k], *q = &ref->nodes[k];
        tn_max = fmax(tn_max, fabs(q->tn));
        dtn = fmax(dtn, fabs(p->tn - q->tn));
        dts = fmax(dts, fabs(p->ts - q->ts));
        if (p->state != q->state || p->node != q->node) ++states;
    }
    for (k = 0; k < n_field; ++k) {
        u_max = fmax(u_max, fabs(ref->u[k]));
        du = fmax(du, fabs(x->u[k] - ref->u[k]));
    }
    dtn /= tn_max, dts /= tn_max, du /= u_max;
    *worst_t = fmax(*worst_t, fmax(dtn, dts));
    *worst_u = fmax(*worst_u, du);
    printf("    %s: tn %.1e, ts %.1e (of max |tn| %.3e), displacement %.1e (of max |u| %.3e), "
           "states differing %lu\n",
           label, dtn, dts, tn_max, du, u_max, (unsigned long)states);
    if (states != 0) {
        printf("wrong value: %s: %lu A nodes in another state\n", label, (unsigned long)states);
        ++failures;
    }
    if (!(dtn <= MATCH_TOLERANCE && dts <= MATCH_TOLERANCE && du <= MATCH_TOLERANCE)) {
        printf("wrong value: %s differs by more than %.0e\n", label, MATCH_TOLERANCE);
        ++failures;
    }
    return failures;
}

/* Normal load sum -n.f over the A nodes and the pressure centre. */
static double contact_load(const HyconNodeResult *nodes, size_t n_a, double *centre) {
    double load = 0.0, w = 0.0, wx = 0.0;
    size_t k;
    for (k = 0; k < n_a; ++k) {
        const HyconNodeResult *r = &nodes[k];
        load -= r->normal[0] * r->force[0] + r->normal[1] * r->force[1];
        w -= r->tn * r->weight;
        wx -= r->tn * r->weight * r->position[0];
    }
    if (centre) *centre = w != 0.0 ? wx / w : 0.0;
    return load;
}

/* What rank 0 needs of the model. */
typedef struct Problem {
    const DiskMesh *m;
    size_t n_eq;
    HyconHostNodes a, b;
    const double *rhs_approach, *rhs_slide; /* unit approach (v = -1), unit slide (u = +1) */
    const size_t *row_ptr, *columns;        /* the gathered matrix, lower triangle */
    const double *values;
    double radius, e_star, e_star_wrong, half_width;
    struct Schur *schur; /* the condensed path's factor */
} Problem;

/* Rank 0: the condensed path's host side. The Schur complement of K over the candidate
 * equations (the contact nodes' equations) by MUMPS through MatFactorSetSchurIS +
 * MatFactorCreateSchurComplement. PETSc 3.18 refuses it for a distributed matrix ("MUMPS
 * distributed parallel Schur complements not yet supported from PETSc"), so the host factors
 * the copy of K that rank 0 gathered (the CSR path's) on PETSC_COMM_SELF, at any rank count;
 * that factor also gives the load and recovery solves (MatSolve). */
typedef struct Schur {
    Mat k, f;             /* the gathered K (SEQAIJ, both triangles) and its factor */
    Vec b, x;             /* work vectors without arrays (VecPlaceArray) */
    int64_t *equations;   /* the m candidates */
    size_t m;
    double *s;            /* m x m, column-major */
    double seconds;       /* building K, factoring it, forming S */
    double solve_seconds; /* load and recovery solves so far */
} Schur;

static PetscErrorCode schur_setup(Schur *c, const Problem *p) {
    const size_t n = p->n_eq;
    PetscInt *nnz = xcalloc(n, sizeof *nnz), *idx, i;
    IS is;
    Mat s_mat;
    MatFactorInfo info;
    const PetscScalar *values;
    PetscInt lda;
    size_t r, q, j;
    double t0 = MPI_Wtime();

    PetscFunctionBeginUser;
    c->m = 2 * (p->a.n + p->b.n);
    c->equations = xcalloc(c->m, sizeof *c->equations);
    for (q = 0; q < 2 * p->a.n; ++q) c->equations[q] = p->a.equations[q];
    for (q = 0; q < 2 * p->b.n; ++q) c->equations[2 * p->a.n + q] = p->b.equations[q];
    for (r = 0; r < n; ++r)
        for (q = p->row_ptr[r]; q < p->row_ptr[r + 1]; ++q) {
            ++nnz[r];
            if (p->columns[q] != r) ++nnz[p->columns[q]];
        }
    PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, (PetscInt)n, (PetscInt)n, 0, nnz, &c->k));
    for (r = 0; r < n; ++r)
        for (q = p->row_ptr[r]; q < p->row_ptr[r + 1]; ++q) {
            PetscInt row = (PetscInt)r, col = (PetscInt)p->columns[q];
            PetscCall(MatSetValue(c->k, row, col, p->values[q], INSERT_VALUES));
            if (col != row) PetscCall(MatSetValue(c->k, col, row, p->values[q], INSERT_VALUES));
        }
    PetscCall(MatAssemblyBegin(c->k, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(c->k, MAT_FINAL_ASSEMBLY));
    PetscCall(MatSetOption(c->k, MAT_SPD, PETSC_TRUE));
    idx = xcalloc(c->m, sizeof *idx);
    for (q = 0; q < c->m; ++q) idx[q] = (PetscInt)c->equations[q];
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)c->m, idx, PETSC_OWN_POINTER, &is));
    PetscCall(MatGetFactor(c->k, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, &c->f));
    PetscCall(MatFactorSetSchurIS(c->f, is));
    PetscCall(MatFactorInfoInitialize(&info));
    PetscCall(MatCholeskyFactorSymbolic(c->f, c->k, NULL, &info));
    PetscCall(MatCholeskyFactorNumeric(c->f, c->k, &info));
    PetscCall(MatFactorCreateSchurComplement(c->f, &s_mat, NULL));
    PetscCall(MatDenseGetLDA(s_mat, &lda));
    PetscCall(MatDenseGetArrayRead(s_mat, &values));
    c->s = xcalloc(c->m * c->m, sizeof *c->s);
    for (j = 0; j < c->m; ++j)
        for (i = 0; i < (PetscInt)c->m; ++i) c->s[(size_t)i + c->m * j] = values[i + lda * j];
    PetscCall(MatDenseRestoreArrayRead(s_mat, &values));
    PetscCall(MatDestroy(&s_mat));
    PetscCall(ISDestroy(&is));
    PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, (PetscInt)n, NULL, &c->b));
    PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, (PetscInt)n, NULL, &c->x));
    free(nnz);
    c->seconds = MPI_Wtime() - t0;
    PetscFunctionReturn(0);
}

/* x = K^-1 rhs with the Schur factor (n values each). */
static PetscErrorCode schur_solve(Schur *c, const double *rhs, double *x) {
    double t0 = MPI_Wtime();
    PetscFunctionBeginUser;
    PetscCall(VecPlaceArray(c->b, rhs));
    PetscCall(VecPlaceArray(c->x, x));
    PetscCall(MatSolve(c->f, c->b, c->x));
    PetscCall(VecResetArray(c->b));
    PetscCall(VecResetArray(c->x));
    c->solve_seconds += MPI_Wtime() - t0;
    PetscFunctionReturn(0);
}

static PetscErrorCode schur_free(Schur *c) {
    PetscFunctionBeginUser;
    PetscCall(MatDestroy(&c->f));
    PetscCall(MatDestroy(&c->k));
    PetscCall(VecDestroy(&c->b));
    PetscCall(VecDestroy(&c->x));
    free(c->equations);
    free(c->s);
    PetscFunctionReturn(0);
}

typedef struct Timing {
    double setup, increments, recovery;
    double increment_solves_seconds; /* callback path: of increments, in the collective solves */
    size_t n_increments;
    Counts setup_solves, increment_solves, recovery_solves;
} Timing;

/* One analysis (press or slide) by both paths, increment by increment. With target_load > 0,
 * the second increment's approach is the first's scaled to that load (the load is nearly
 * linear in the approach), written back to approach[1]. */
static int run_analysis(const char *name, const Problem *p, Solver *s, double friction,
                        HyconKinematics kinematics, double *approach, const double *slide,
                        size_t n_steps, double target_load, Timing *t_cb, Timing *t_csr,
                        Timing *t_cond, double *worst_t, double *worst_u, HyconNodeResult *last,
                        double *u_last) {
    const HyconContactOptions options = hc_options(kinematics);
    const size_t n_a = p->a.n, n = p->n_eq;
    Schur *schur = p->schur;
    HyconContact *c_cb, *c_csr, *c_cond;
    HyconHost *host;
    Snapshot s_cb, s_csr, s_cond;
    double *rhs = xcalloc(n, sizeof *rhs), t0;
    double *image = xcalloc(schur->m, sizeof *image), *work = xcalloc(n, sizeof *work);
    Counts c0;
    size_t step, k;
    int failures = 0;
    const double inside[2] = {0.0, -p->radius}; /* the block is [-2R, 2R] x [-2R, 0] */

    printf("%s: friction %.2f, %s kinematics\n", name, friction,
           kinematics == HYCON_KINEMATICS_FINITE ? "finite" : "small");
    memset(t_cb, 0, sizeof *t_cb);
    memset(t_csr, 0, sizeof *t_csr);
    memset(t_cond, 0, sizeof *t_cond);
    host = hc_host(n, &p->a, &p->b, friction, inside);
    hc_host_solver(host, petsc_solve_cb, s);
    c0 = counts_now(s);
    t0 = MPI_Wtime();
    c_cb = hc_start(host, &options);
    t_cb->setup = MPI_Wtime() - t0;
    t_cb->setup_solves = counts_since(s, c0);

    host = hc_host(n, &p->a, &p->b, friction, inside);
    hc_host_csr(host, p->row_ptr, p->columns, p->values);
    t0 = MPI_Wtime();
    c_csr = hc_start(host, &options);
    t_csr->setup = MPI_Wtime() - t0;

    /* the condensed path: its setup counts the host's Schur factorization (done once for both
     * analyses, counted in each) and hycon's dense factorization of S */
    host = hc_host(n, &p->a, &p->b, friction, inside);
    t0 = MPI_Wtime();
    hc_host_condensed(host, schur->equations, schur->m, schur->s);
    c_cond = hc_start(host, &options);
    t_cond->setup = schur->seconds + MPI_Wtime() - t0;
    s_cond.nodes = xcalloc(n_a, sizeof *s_cond.nodes);
    s_cond.u = xcalloc(n, sizeof *s_cond.u);

    s_cb.nodes = xcalloc(n_a, sizeof *s_cb.nodes);
    s_csr.nodes = xcalloc(n_a, sizeof *s_csr.nodes);
    s_cb.u = xcalloc(n, sizeof *s_cb.u);
    s_csr.u = xcalloc(n, sizeof *s_csr.u);
    for (step = 0; step < n_steps; ++step) {
        HyconIncrementInfo i_cb, i_csr;
        Counts c_inc, c_rec;
        double t_inc_cb, t_inc_csr, solve_seconds;
        if (step == 1 && target_load > 0.0)
            approach[1] = approach[0] * target_load / contact_load(s_cb.nodes, n_a, NULL);
        for (k = 0; k < n; ++k) rhs[k] = approach[step] * p->rhs_approach[k] +
                                         slide[step] * p->rhs_slide[k];
        c0 = counts_now(s);
        solve_seconds = s->seconds;
        t0 = MPI_Wtime();
        i_cb = hc_increment(c_cb, rhs, n);
        t_inc_cb = MPI_Wtime() - t0;
        t_cb->increment_solves_seconds += s->seconds - solve_seconds;
        c_inc = counts_since(s, c0);
        t0 = MPI_Wtime();
        i_csr = hc_increment(c_csr, rhs, n);
        t_inc_csr = MPI_Wtime() - t0;
        t_cb->increments += t_inc_cb;
        t_csr->increments += t_inc_csr;
        t_cb->increment_solves.calls += c_inc.calls;
        t_cb->increment_solves.columns += c_inc.columns;
        ++t_cb->n_increments;
        ++t_csr->n_increments;

        c0 = counts_now(s);
        t0 = MPI_Wtime();
        hc_displacement(c_cb, s_cb.u, n);
        t_cb->recovery += MPI_Wtime() - t0;
        c_rec = counts_since(s, c0);
        t_cb->recovery_solves.calls += c_rec.calls;
        t_cb->recovery_solves.columns += c_rec.columns;
        t0 = MPI_Wtime();
        hc_displacement(c_csr, s_csr.u, n);
        t_csr->recovery += MPI_Wtime() - t0;
        hc_node_results(c_cb, s_cb.nodes, n_a);
        hc_node_results(c_csr, s_csr.nodes, n_a);

        { /* condensed: the host's load solve gives the image at the candidates, hycon
           * iterates on S alone, the host recovers u from K u = rhs + forces */
            double t_inc, t_rec, solves0 = schur->solve_seconds;
            t0 = MPI_Wtime();
            if (schur_solve(schur, rhs, work) != 0) hc_fail("MatSolve (load)", HYCON_ERROR_SOLVER);
            for (k = 0; k < schur->m; ++k) image[k] = work[schur->equations[k]];
            (void)hc_increment(c_cond, image, schur->m);
            t_inc = MPI_Wtime() - t0;
            t_cond->increment_solves_seconds += schur->solve_seconds - solves0;
            t0 = MPI_Wtime();
            hc_forces(c_cond, work, n);
            for (k = 0; k < n; ++k) work[k] += rhs[k];
            if (schur_solve(schur, work, s_cond.u) != 0)
                hc_fail("MatSolve (recovery)", HYCON_ERROR_SOLVER);
            t_rec = MPI_Wtime() - t0;
            hc_node_results(c_cond, s_cond.nodes, n_a);
            t_cond->increments += t_inc;
            t_cond->recovery += t_rec;
            ++t_cond->n_increments;
        }

        printf("  increment %lu: approach %.4e, slide %.4e (%.2f a): iterations %lu / %lu, "
               "active %lu, slip %lu; %.3f / %.3f s (callback / CSR), %lu solve call(s), "
               "%lu rhs\n",
               (unsigned long)step + 1, approach[step], slide[step],
               slide[step] / p->half_width, (unsigned long)i_cb.iterations,
               (unsigned long)i_csr.iterations, (unsigned long)i_cb.active,
               (unsigned long)i_cb.slip, t_inc_cb, t_inc_csr, (unsigned long)c_inc.calls,
               (unsigned long)c_inc.columns);
        failures += compare("callback vs CSR", n_a, n, &s_cb, &s_csr, worst_t, worst_u);
        failures += compare("condensed vs CSR", n_a, n, &s_cond, &s_csr, worst_t, worst_u);
    }
    memcpy(last, s_cb.nodes, n_a * sizeof *last);
    memcpy(u_last, s_cb.u, n * sizeof *u_last);
    hc_free(c_cb);
    hc_free(c_csr);
    hc_free(c_cond);
    free(s_cond.nodes);
    free(s_cond.u);
    free(image);
    free(work);
    free(s_cb.nodes);
    free(s_csr.nodes);
    free(s_cb.u);
    free(s_csr.u);
    free(rhs);
    return failures;
}

/* Hertz at the end of the press; returns the failed checks. */
static int check_hertz(const Problem *p, const HyconNodeResult *nodes, double *a_err,
                       double *p0_err) {
    const size_t n_a = p->a.n;
    double *x = xcalloc(n_a, sizeof *x), *pr = xcalloc(n_a, sizeof *pr), centre;
    double load = contact_load(nodes, n_a, &centre), wrong_a, wrong_p0;
    HertzFit fit, wrong;
    size_t k;
    int failures = 0;
    for (k = 0; k < n_a; ++k) {
        x[k] = nodes[k].position[0] - centre;
        pr[k] = -nodes[k].tn;
    }
    fit = hertz_compare(x, pr, n_a, load, p->radius, p->e_star);
    for (k = 0; k < n_a; ++k) {
        x[k] = nodes[k].position[0] - centre;
        pr[k] = -nodes[k].tn;
    }
    wrong = hertz_compare(x, pr, n_a, load, p->radius, p->e_star_wrong);
    *a_err = fit.half_width / fit.a - 1.0;
    *p0_err = fit.peak / fit.p0 - 1.0;
    wrong_a = wrong.half_width / wrong.a - 1.0;
    wrong_p0 = wrong.peak / wrong.p0 - 1.0;
    printf("Hertz at the contact load P = %.6e: a = %.6e, p0 = %.6e (E* = E / (2 (1 - nu^2)))\n",
           load, fit.a, fit.p0);
    hertz_print("multipliers (A nodes)", &fit);
    printf("  with a wrong E* = E / (1 - nu^2): a %+.2f%%, p0 %+.2f%% (must miss the %.0f%% "
           "tolerance)\n",
           100.0 * wrong_a, 100.0 * wrong_p0, 100.0 * HERTZ_TOLERANCE);
    if (!(fabs(*a_err) <= HERTZ_TOLERANCE && fabs(*p0_err) <= HERTZ_TOLERANCE)) {
        printf("wrong value: Hertz half-width or peak off by more than %.0f%%\n",
               100.0 * HERTZ_TOLERANCE);
        ++failures;
    }
    if (!(fabs(wrong_a) > HERTZ_TOLERANCE || fabs(wrong_p0) > HERTZ_TOLERANCE)) {
        printf("wrong value: the Hertz check would pass with a wrong E*\n");
        ++failures;
    }
    free(x);
    free(pr);
    return failures;
}

/* Gross sliding at the end of the slide: every active node slips, T = mu N within 2 %. */
static int check_sliding(const Problem *p, const HyconNodeResult *nodes, double friction) {
    double normal = 0.0, tangential = 0.0;
    size_t k, active = 0, slipping = 0;
    for (k = 0; k < p->a.n; ++k) {
        const HyconNodeResult *r = &nodes[k];
        if (r->state == HYCON_NODE_OPEN) continue;
        ++active;
        if (r->state == HYCON_NODE_SLIP) ++slipping;
        normal -= r->normal[0] * r->force[0] + r->normal[1] * r->force[1];
        tangential += r->tangent[0] * r->force[0] + r->tangent[1] * r->force[1];
    }
    printf("gross sliding: %lu of %lu active nodes slip, T / N = %.4f (mu = %.2f)\n",
           (unsigned long)slipping, (unsigned long)active, fabs(tangential) / normal, friction);
    if (active == 0 || slipping != active || !(fabs(fabs(tangential) / normal - friction) <=
                                               0.02 * friction)) {
        printf("wrong value: no gross sliding at the end of the slide\n");
        return 1;
    }
    return 0;
}

/* Rank 0, independently of PETSc: the gathered matrix (lower triangle) and the two unit
 * right-hand sides against an element-by-element product over all elements with the same
 * Dirichlet treatment (held rows and columns replaced by the identity, right-hand side
 * -K_fp q_p on the free rows and q_p on the held ones). Catches a lost off-rank entry or a
 * wrong row in the distributed assembly, which the callback-vs-CSR comparison cannot (both
 * paths use this matrix). Returns the failed checks. */
static int check_assembly(const DiskMesh *m, const HyconMaterial *material, size_t n,
                          const size_t *row_ptr, const size_t *columns, const double *values,
                          const double *rhs_approach, const double *rhs_slide) {
    unsigned char *held = xcalloc(n, 1);
    double *v = xcalloc(n, sizeof *v), *y_el = xcalloc(n, sizeof *y_el);
    double *y_csr = xcalloc(n, sizeof *y_csr), diff[3] = {0.0, 0.0, 0.0};
    size_t k, e, i, j, load;
    int failures = 0;
    for (k = 0; k < m->n_bottom; ++k) held[2 * m->bottom[k]] = held[2 * m->bottom[k] + 1] = 1;
    for (k = 0; k < m->n_top; ++k) held[2 * m->top[k]] = held[2 * m->top[k] + 1] = 1;
    for (load = 0; load < 3; ++load) { /* 0: a pseudo-random vector; 1, 2: the unit loads */
        const double *reference = load == 1 ? rhs_approach : rhs_slide;
        double scale = 0.0;
        for (k = 0; k < n; ++k) {
            int top_dof = held[k] && m->coords[k - k % 2 + 1] > 0.5;
            v[k] = load == 0 ? sin(1.3 * (double)k + 0.7)
                 : held[k] && top_dof && k % 2 == (load == 1 ? 1u : 0u) ? (load == 1 ? -1.0 : 1.0)
                                                                      : 0.0;
            y_el[k] = 0.0;
            y_csr[k] = 0.0;
        }
        for (e = 0; e < m->n_elements; ++e) {
            const size_t *en = &m->nodes[m->offsets[e]];
            double xy[8], ke[64];
            for (i = 0; i < 4; ++i) {
                xy[2 * i] = m->coords[2 * en[i]];
                xy[2 * i + 1] = m->coords[2 * en[i] + 1];
            }
            hc_element_stiffness(xy, material, ke);
            for (i = 0; i < 8; ++i) {
                size_t r = 2 * en[i / 2] + i % 2;
                if (held[r]) continue;
                for (j = 0; j < 8; ++j) {
                    size_t c = 2 * en[j / 2] + j % 2;
                    /* the matrix: free columns only; a load: the held columns only, negated */
                    if (load == 0 && !held[c]) y_el[r] += ke[i * 8 + j] * v[c];
                    if (load != 0 && held[c]) y_el[r] -= ke[i * 8 + j] * v[c];
                }
            }
        }
        for (k = 0; k < n; ++k)
            if (held[k]) y_el[k] = v[k];
        if (load == 0) {
            for (i = 0; i < n; ++i)
                for (k = row_ptr[i]; k < row_ptr[i + 1]; ++k) {
                    y_csr[i] += values[k] * v[columns[k]];
                    if (columns[k] != i) y_csr[columns[k]] += values[k] * v[i];
                }
        } else {
            memcpy(y_csr, reference, n * sizeof *y_csr);
        }
        for (k = 0; k < n; ++k) {
            scale = fmax(scale, fabs(y_el[k]));
            diff[load] = fmax(diff[load], fabs(y_el[k] - y_csr[k]));
        }
        diff[load] /= scale;
    }
    printf("assembly check against an element-by-element product on rank 0: K v %.1e, unit "
           "approach %.1e, unit slide %.1e (relative)\n",
           diff[0], diff[1], diff[2]);
    if (!(diff[0] <= 1e-12 && diff[1] <= 1e-12 && diff[2] <= 1e-12)) {
        printf("wrong value: the distributed assembly or its Dirichlet conditions differ\n");
        ++failures;
    }
    free(held);
    free(v);
    free(y_el);
    free(y_csr);
    return failures;
}

/* ------------------------------------------------------------------------------------------ */

/* Rank 0's gathered copy of K: the lower triangle as CSR (row_ptr, columns, values). */
static PetscErrorCode gather_lower(Mat k, PetscMPIInt rank, size_t **row_ptr, size_t **columns,
                                   double **values) {
    IS is;
    Mat *sub;
    PetscInt n, rows, i, j;
    const PetscInt *ia, *ja;
    const PetscScalar *va;
    PetscBool done;
    size_t nnz = 0;

    PetscFunctionBeginUser;
    PetscCall(MatGetSize(k, &n, NULL));
    PetscCall(ISCreateStride(PETSC_COMM_SELF, rank == 0 ? n : 0, 0, 1, &is));
    PetscCall(MatCreateSubMatrices(k, 1, &is, &is, MAT_INITIAL_MATRIX, &sub));
    PetscCall(ISDestroy(&is));
    if (rank == 0) {
        PetscCall(MatGetRowIJ(sub[0], 0, PETSC_FALSE, PETSC_FALSE, &rows, &ia, &ja, &done));
        PetscCheck(done && rows == n, PETSC_COMM_SELF, PETSC_ERR_PLIB, "MatGetRowIJ");
        PetscCall(MatSeqAIJGetArrayRead(sub[0], &va));
        *row_ptr = xcalloc((size_t)n + 1, sizeof **row_ptr);
        *columns = xcalloc((size_t)ia[n], sizeof **columns);
        *values = xcalloc((size_t)ia[n], sizeof **values);
        for (i = 0; i < n; ++i) {
            for (j = ia[i]; j < ia[i + 1]; ++j)
                if (ja[j] <= i) {
                    (*columns)[nnz] = (size_t)ja[j];
                    (*values)[nnz++] = va[j];
                }
            (*row_ptr)[i + 1] = nnz;
        }
        PetscCall(MatSeqAIJRestoreArrayRead(sub[0], &va));
        PetscCall(MatRestoreRowIJ(sub[0], 0, PETSC_FALSE, PETSC_FALSE, &rows, &ia, &ja, &done));
    }
    PetscCall(MatDestroySubMatrices(1, &sub));
    PetscFunctionReturn(0);
}

/* A distributed vector gathered to rank 0 (out: n values there, untouched elsewhere). */
static PetscErrorCode gather_vec(Vec v, PetscMPIInt rank, double *out) {
    VecScatter scatter;
    Vec all;
    const PetscScalar *a;
    PetscInt n;

    PetscFunctionBeginUser;
    PetscCall(VecScatterCreateToZero(v, &scatter, &all));
    PetscCall(VecScatterBegin(scatter, v, all, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(scatter, v, all, INSERT_VALUES, SCATTER_FORWARD));
    if (rank == 0) {
        PetscCall(VecGetSize(all, &n));
        PetscCall(VecGetArrayRead(all, &a));
        memcpy(out, a, (size_t)n * sizeof *out);
        PetscCall(VecRestoreArrayRead(all, &a));
    }
    PetscCall(VecScatterDestroy(&scatter));
    PetscCall(VecDestroy(&all));
    PetscFunctionReturn(0);
}

int main(int argc, char **argv) {
    const double youngs = 1.0, poisson = 0.3, radius = 1.0, target = 1.0 / 32.0;
    const double friction = 0.3;
    HyconKinematics press_kinematics = HYCON_KINEMATICS_SMALL;
    double press_friction = 0.0;
    int press_only = 0;
    size_t n = 8, n_analyses;
    DiskMeshParams params;
    DiskMesh m;
    HyconMaterial material;
    Solver s;
    Mat k, k_slide;
    Vec q_approach, q_slide, b_approach, b_slide;
    PetscInt n_eq, rstart, rend, e0, e1, e, i, *held, n_held = 0;
    PetscMPIInt rank, size;
    double t_assembly, t_factor, t0;
    char solver_name[128];
    int exit_code = 0;
    size_t j;

    PetscCall(PetscInitialize(&argc, &argv, NULL,
                              "petsc_host [n]: hycon's contact iteration driven by PETSc"));
    PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
    PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
    (void)report_failure; /* disk_mesh.h's CHECK: hycon calls go through hc_* here */
    if (argc > 1 && argv[1][0] != '-') n = (size_t)strtoul(argv[1], NULL, 10);
    press_only = disk_case_args(argc, argv, &press_kinematics, &press_friction);
    n_analyses = press_only == 1 ? 1 : 2;
    if (n < 4 || n > 32 || press_only < 0) {
        PetscCall(PetscPrintf(PETSC_COMM_WORLD, "usage: petsc_host [n [small|finite mu]], "
                                                "4 <= n <= 32, 0 <= mu <= 1\n"));
        PetscCall(PetscFinalize());
        return EXIT_FAILURE;
    }

    /* the model: the same mesh on every rank */
    params.radius = radius;
    params.half_width = target * radius;
    params.per_half_width = n;
    params.growth = 1.1;
    params.block_half_width = 2.0 * radius;
    params.block_depth = 2.0 * radius;
    m = disk_mesh_build(&params);
    material.youngs = youngs;
    material.poisson = poisson;
    material.thickness = 1.0;
    material.analysis = HYCON_PLANE_STRAIN;
    n_eq = (PetscInt)(2 * m.n_nodes);

    /* parallel assembly: each rank its contiguous share of the elements */
    t0 = MPI_Wtime();
    PetscCall(MatCreateAIJ(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, n_eq, n_eq, 18, NULL, 18,
                           NULL, &k));
    PetscCall(MatSetOption(k, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
    e0 = (PetscInt)(m.n_elements * (size_t)rank / (size_t)size);
    e1 = (PetscInt)(m.n_elements * ((size_t)rank + 1) / (size_t)size);
    for (e = e0; e < e1; ++e) {
        const size_t *en = &m.nodes[m.offsets[e]];
        double xy[8], ke[64];
        PetscInt dofs[8];
        for (i = 0; i < 4; ++i) {
            xy[2 * i] = m.coords[2 * en[i]];
            xy[2 * i + 1] = m.coords[2 * en[i] + 1];
            dofs[2 * i] = (PetscInt)(2 * en[i]);
            dofs[2 * i + 1] = (PetscInt)(2 * en[i] + 1);
        }
        hc_element_stiffness(xy, &material, ke);
        PetscCall(MatSetValues(k, 8, dofs, 8, dofs, ke, ADD_VALUES));
    }
    PetscCall(MatAssemblyBegin(k, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(k, MAT_FINAL_ASSEMBLY));
    PetscCall(MatGetOwnershipRange(k, &rstart, &rend));

    /* Dirichlet conditions: block bottom held, disk top prescribed. Each rank zeroes the rows
     * it owns; MatZeroRowsColumns puts the prescribed values into the right-hand side (its
     * rows: the value; the others: minus the coupling), one unit load per direction. */
    held = xcalloc(2 * (m.n_bottom + m.n_top), sizeof *held);
    PetscCall(MatCreateVecs(k, &q_approach, &b_approach));
    PetscCall(VecDuplicate(q_approach, &q_slide));
    PetscCall(VecDuplicate(b_approach, &b_slide));
    PetscCall(VecSet(b_approach, 0.0));
    PetscCall(VecSet(b_slide, 0.0));
    for (j = 0; j < m.n_bottom + m.n_top; ++j) {
        int top = j >= m.n_bottom;
        PetscInt node = (PetscInt)(top ? m.top[j - m.n_bottom] : m.bottom[j]), d;
        for (d = 0; d < 2; ++d) {
            PetscInt row = 2 * node + d;
            if (row < rstart || row >= rend) continue;
            held[n_held++] = row;
            PetscCall(VecSetValue(q_approach, row, top && d == 1 ? -1.0 : 0.0, INSERT_VALUES));
            PetscCall(VecSetValue(q_slide, row, top && d == 0 ? 1.0 : 0.0, INSERT_VALUES));
        }
    }
    PetscCall(VecAssemblyBegin(q_approach));
    PetscCall(VecAssemblyEnd(q_approach));
    PetscCall(VecAssemblyBegin(q_slide));
    PetscCall(VecAssemblyEnd(q_slide));
    PetscCall(MatDuplicate(k, MAT_COPY_VALUES, &k_slide));
    PetscCall(MatZeroRowsColumns(k, n_held, held, 1.0, q_approach, b_approach));
    PetscCall(MatZeroRowsColumns(k_slide, n_held, held, 1.0, q_slide, b_slide));
    PetscCall(MatDestroy(&k_slide));
    PetscCall(MatSetOption(k, MAT_SYMMETRIC, PETSC_TRUE));
    PetscCall(MatSetOption(k, MAT_SPD, PETSC_TRUE));
    t_assembly = MPI_Wtime() - t0;

    /* the solver: MUMPS Cholesky, factored once */
    memset(&s, 0, sizeof s);
    s.n = n_eq;
    s.m_local = rend - rstart;
    s.rank = rank;
    s.size = size;
    s.rows = xcalloc((size_t)size, sizeof *s.rows);
    s.starts = xcalloc((size_t)size, sizeof *s.starts);
    s.counts = xcalloc((size_t)size, sizeof *s.counts);
    s.displs = xcalloc((size_t)size, sizeof *s.displs);
    {
        const PetscInt *ranges;
        PC pc;
        PetscCall(MatGetOwnershipRanges(k, &ranges));
        for (i = 0; i < size; ++i) {
            s.rows[i] = (int)(ranges[i + 1] - ranges[i]);
            s.starts[i] = (int)ranges[i];
        }
        t0 = MPI_Wtime();
        PetscCall(KSPCreate(PETSC_COMM_WORLD, &s.ksp));
        PetscCall(KSPSetOperators(s.ksp, k, k));
        PetscCall(KSPSetType(s.ksp, KSPPREONLY));
        PetscCall(KSPGetPC(s.ksp, &pc));
        PetscCall(PCSetType(pc, PCCHOLESKY));
        PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
        PetscCall(KSPSetFromOptions(s.ksp));
        PetscCall(KSPSetUp(s.ksp));
        t_factor = MPI_Wtime() - t0;
        {
            KSPType ksp_type;
            PCType pc_type;
            MatSolverType factor_type = NULL;
            PetscBool is_factor;
            PetscCall(KSPGetType(s.ksp, &ksp_type));
            PetscCall(PCGetType(pc, &pc_type));
            PetscCall(PetscObjectTypeCompareAny((PetscObject)pc, &is_factor, PCCHOLESKY, PCLU, ""));
            if (is_factor) PetscCall(PCFactorGetMatSolverType(pc, &factor_type));
            snprintf(solver_name, sizeof solver_name, "KSP %s, PC %s%s%s", ksp_type, pc_type,
                     factor_type ? " by " : "", factor_type ? factor_type : "");
        }
    }

    {
        /* rank 0 gathers what hycon needs: the unit right-hand sides and (for the CSR path
         * only) the matrix */
        double *rhs_approach = rank == 0 ? xcalloc((size_t)n_eq, sizeof *rhs_approach) : NULL;
        double *rhs_slide = rank == 0 ? xcalloc((size_t)n_eq, sizeof *rhs_slide) : NULL;
        size_t *row_ptr = NULL, *columns = NULL;
        double *values = NULL;
        PetscCall(gather_vec(b_approach, rank, rhs_approach));
        PetscCall(gather_vec(b_slide, rank, rhs_slide));
        PetscCall(gather_lower(k, rank, &row_ptr, &columns, &values));

        if (rank != 0) {
            exit_code = serve(&s);
        } else {
            Problem p;
            size_t *a_ids = m.a, *b_ids = m.b, q;
            double *a_xy = xcalloc(2 * m.n_a, sizeof *a_xy);
            double *b_xy = xcalloc(2 * m.n_b, sizeof *b_xy);
            int64_t *a_eq = xcalloc(2 * m.n_a, sizeof *a_eq);
            int64_t *b_eq = xcalloc(2 * m.n_b, sizeof *b_eq);
            HyconNodeResult *last = xcalloc(m.n_a, sizeof *last);
            double *u_last = xcalloc((size_t)n_eq, sizeof *u_last);
            double approach[6], slide[6], worst_t = 0.0, worst_u = 0.0, a_err = 0.0, p0_err = 0.0;
            double p_target;
            Timing press_cb, press_csr, press_cond, slide_cb, slide_csr, slide_cond;
            Schur schur;
            int failures = 0;

            for (q = 0; q < 2 * m.n_a; ++q) {
                a_xy[q] = m.coords[2 * a_ids[q / 2] + q % 2];
                a_eq[q] = (int64_t)(2 * a_ids[q / 2] + q % 2);
            }
            for (q = 0; q < 2 * m.n_b; ++q) {
                b_xy[q] = m.coords[2 * b_ids[q / 2] + q % 2];
                b_eq[q] = (int64_t)(2 * b_ids[q / 2] + q % 2);
            }
            p.m = &m;
            p.n_eq = (size_t)n_eq;
            p.a.ids = a_ids, p.a.coords = a_xy, p.a.equations = a_eq, p.a.n = m.n_a;
            p.b.ids = b_ids, p.b.coords = b_xy, p.b.equations = b_eq, p.b.n = m.n_b;
            p.rhs_approach = rhs_approach;
            p.rhs_slide = rhs_slide;
            p.row_ptr = row_ptr;
            p.columns = columns;
            p.values = values;
            p.radius = radius;
            p.e_star = youngs / (2.0 * (1.0 - poisson * poisson));
            p.e_star_wrong = youngs / (1.0 - poisson * poisson);
            p.half_width = params.half_width;

            printf("PETSc host over %d rank(s): h = a/%lu, %lu nodes, %lu elements, %ld "
                   "equations (%lu nonzeros in the lower triangle), %lu A nodes, %lu B nodes\n",
                   (int)size, (unsigned long)n, (unsigned long)m.n_nodes,
                   (unsigned long)m.n_elements, (long)n_eq, (unsigned long)row_ptr[n_eq],
                   (unsigned long)m.n_a, (unsigned long)m.n_b);
            printf("assembly + Dirichlet %.3f s; solver %s, setup (factorization) %.3f s\n",
                   t_assembly, solver_name, t_factor);

            failures += check_assembly(&m, &material, (size_t)n_eq, row_ptr, columns, values,
                                       rhs_approach, rhs_slide);
            memset(&schur, 0, sizeof schur);
            if (schur_setup(&schur, &p) != 0) hc_fail("the MUMPS Schur complement", HYCON_ERROR_SOLVER);
            p.schur = &schur;
            printf("condensed path: MUMPS Schur complement over %lu candidate equations on rank "
                   "0 (K gathered there), %.3f s\n",
                   (unsigned long)schur.m, schur.seconds);

            /* press: a trial approach, then the approach of the target's Hertz load */
            approach[0] = params.half_width * params.half_width / radius;
            slide[0] = slide[1] = 0.0;
            p_target = DISK_PI * params.half_width * params.half_width * p.e_star / (4.0 * radius);
            failures += run_analysis("press", &p, &s, press_friction, press_kinematics, approach,
                                     slide, 2, p_target, &press_cb, &press_csr, &press_cond,
                                     &worst_t, &worst_u, last, u_last);
            failures += check_hertz(&p, last, &a_err, &p0_err);
            if (n_analyses == 2) { /* slide: press, then move the top sideways */
                for (q = 0; q < 5; ++q) approach[q] = approach[1];
                slide[0] = 0.0;
                slide[1] = 0.01 * params.half_width;
                slide[2] = 0.05 * params.half_width;
                slide[3] = 0.2 * params.half_width;
                slide[4] = 0.4 * params.half_width;
                failures += run_analysis("slide", &p, &s, friction, HYCON_KINEMATICS_FINITE,
                                         approach, slide, 5, 0.0, &slide_cb, &slide_csr,
                                         &slide_cond, &worst_t, &worst_u, last, u_last);
                failures += check_sliding(&p, last, friction);
            }

            printf("\nsummary: %d rank(s), %ld equations, %lu A nodes; %s (PETSc %d.%d.%d); "
                   "press: %s kinematics, mu %.2f\n",
                   (int)size, (long)n_eq, (unsigned long)m.n_a, solver_name, PETSC_VERSION_MAJOR,
                   PETSC_VERSION_MINOR, PETSC_VERSION_SUBMINOR,
                   press_kinematics == HYCON_KINEMATICS_FINITE ? "finite" : "small",
                   press_friction);
            printf("| analysis | path | setup s | increments | s / increment | of which solves "
                   "| solve calls (setup / increments / recovery) | right-hand sides (setup / "
                   "increments / recovery) |\n");
            {
                const char *names[2] = {"press", "slide"};
                Timing *cb[2], *csr[2], *cond[2];
                cb[0] = &press_cb, cb[1] = &slide_cb, csr[0] = &press_csr, csr[1] = &slide_csr;
                cond[0] = &press_cond, cond[1] = &slide_cond;
                for (q = 0; q < n_analyses; ++q) {
                    printf("| %s | callback | %.3f | %lu | %.4f | %.4f | %lu / %lu / %lu | %lu / "
                           "%lu / %lu |\n",
                           names[q], cb[q]->setup, (unsigned long)cb[q]->n_increments,
                           cb[q]->increments / (double)cb[q]->n_increments,
                           cb[q]->increment_solves_seconds / (double)cb[q]->n_increments,
                           (unsigned long)cb[q]->setup_solves.calls,
                           (unsigned long)cb[q]->increment_solves.calls,
                           (unsigned long)cb[q]->recovery_solves.calls,
                           (unsigned long)cb[q]->setup_solves.columns,
                           (unsigned long)cb[q]->increment_solves.columns,
                           (unsigned long)cb[q]->recovery_solves.columns);
                    printf("| %s | CSR | %.3f | %lu | %.4f | - | - | - |\n", names[q],
                           csr[q]->setup,
                           (unsigned long)csr[q]->n_increments,
                           csr[q]->increments / (double)csr[q]->n_increments);
                    printf("| %s | condensed | %.3f | %lu | %.4f | %.4f | - | - |\n", names[q],
                           cond[q]->setup, (unsigned long)cond[q]->n_increments,
                           cond[q]->increments / (double)cond[q]->n_increments,
                           cond[q]->increment_solves_seconds / (double)cond[q]->n_increments);
                }
                for (q = 0; q < n_analyses; ++q)
                    printf("%s totals (setup + increments + recovery), s: callback %.3f, CSR "
                           "%.3f, condensed %.3f\n",
                           names[q], cb[q]->setup + cb[q]->increments + cb[q]->recovery,
                           csr[q]->setup + csr[q]->increments + csr[q]->recovery,
                           cond[q]->setup + cond[q]->increments + cond[q]->recovery);
            }
            printf("solve callback: %lu calls, %lu right-hand sides (at most %lu per call), "
                   "%.3f s in the collective solves, of which %.3f s in KSPMatSolve and %.3f s "
                   "moving the columns (pack, scatter, gather)\n",
                   (unsigned long)s.calls, (unsigned long)s.columns, (unsigned long)s.max_nrhs,
                   s.seconds, s.ksp_seconds, s.seconds - s.ksp_seconds);
            printf("callback vs CSR: max relative difference tractions %.1e, displacements "
                   "%.1e (tolerance %.0e); Hertz a %+.2f%%, p0 %+.2f%% (tolerance %.0f%%)\n",
                   worst_t, worst_u, MATCH_TOLERANCE, 100.0 * a_err, 100.0 * p0_err,
                   100.0 * HERTZ_TOLERANCE);
            if (s.max_nrhs < 2) {
                printf("wrong value: the callback never got several right-hand sides at once\n");
                ++failures;
            }
            exit_code = failures == 0 ? 0 : 1;
            if (failures != 0)
                printf("FAILED: %d check(s)\n", failures);
            else
                printf("OK\n");
            fflush(stdout);
            send_command(CMD_DONE, exit_code);
            if (schur_free(&schur) != 0) exit_code = 1;
            free(a_xy);
            free(b_xy);
            free(a_eq);
            free(b_eq);
            free(last);
            free(u_last);
        }
        free(rhs_approach);
        free(rhs_slide);
        free(row_ptr);
        free(columns);
        free(values);
    }

    PetscCall(KSPDestroy(&s.ksp));
    PetscCall(MatDestroy(&k));
    PetscCall(VecDestroy(&q_approach));
    PetscCall(VecDestroy(&q_slide));
    PetscCall(VecDestroy(&b_approach));
    PetscCall(VecDestroy(&b_slide));
    free(held);
    free(s.rows);
    free(s.starts);
    free(s.counts);
    free(s.displs);
    free(s.pack);
    disk_mesh_free(&m);
    PetscCall(PetscFinalize());
    return exit_code;
}
