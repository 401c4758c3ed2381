/* hpgen's C runtime, part 5: the linearization of the step along recorded steps
   (hpgen.runtime.linearize). Included by hpgen_runtime.c after hpgen_runs.c. A kernels.c
   that defines HPGEN_WITH_LAZY 0 (a family module's step library) leaves it out: it is
   compiled into the lazily built library with step_partials (hpgen.runtime.build). */
#if !defined(HPGEN_WITH_LAZY) || HPGEN_WITH_LAZY

/* the columns of the step vector B may differentiate (1 for a closed module: none used) */
#if HPGEN_OPEN
#define HPGEN_LIN_H HPGEN_H
#else
#define HPGEN_LIN_H 1
#endif

/* What the per-substep derivative (hpgen_lin_substep) works on during step k: the
   substep's start (g, p), the composed step's A_k (S x S) and B_k (S x nc) so far, the
   step vector's columns c0 .. c0 + nc - 1 that B differentiates, and the work arrays. */
typedef struct hpgen_lin {
    double g[HPGEN_NN], p[HPGEN_D];
    double *A, *B;
    long long c0, nc, jacobians;
    double *Fs, *Yz, *Ys, *D, *E, *T;      /* heap: S x nz (twice), S x S (three), S x H */
    double J[HPGEN_LU_SIZE];
    int piv[HPGEN_NZ];
#if HPGEN_OPEN
    double FH[HPGEN_NZ * HPGEN_H], YH[2 * HPGEN_D * HPGEN_H];
#endif
} hpgen_lin;

/* out = Ys - Yz J^{-1} X over m columns of X (nz x m, overwritten by J^{-1} X; the first
   solved with the factorization), Y's columns at Y (S rows), all column-major. */
static void hpgen_lin_implicit(const hpgen_lin* c, double* X, const double* Y, long long m,
                               double* out) {
    enum { S = 2 * HPGEN_D };
    long long i, j, l;
    for (j = 0; j < m; ++j) {
        const double* x = X + j * HPGEN_NZ;
        hpgen_lu_apply(c->J, c->piv, X + j * HPGEN_NZ);
        for (i = 0; i < S; ++i) {
            double a = Y[i + j * S];
            for (l = 0; l < HPGEN_NZ; ++l) a -= c->Yz[i + l * S] * x[l];
            out[i + j * S] = a;
        }
    }
}

/* After substep i of step k converged at r->z from (c->g, c->p) with step vector hv: its
   derivatives by the implicit function theorem, A_i = Ys - Yz J^{-1} Fs (J = dF/dz at z,
   factored here; the run's own Newton matrix is not touched) and, open, B_i = YH_c -
   Yz J^{-1} FH_c; then the chain rule A_k = A_i A_k, B_k = A_i B_k + B_i (i = 0: A_k = A_i,
   B_k = B_i), and (c->g, c->p) moved to the substep's end. HPGEN_NONFINITE when a kernel
   fails or a derivative is not finite. */
static int hpgen_lin_substep(void* ctx, const hpgen_run* r, long long i, const double* hv) {
    enum { S = 2 * HPGEN_D };
    hpgen_lin* c = (hpgen_lin*)ctx;
    double* Ai = i == 0 ? c->A : c->D;
    long long a, b, l;
    c->jacobians += 1;
    if (hpgen_newton_j(r->z, c->g, c->p, hv, c->J)
#if HPGEN_OPEN
        || hpgen_k_step_partials(r->z, c->g, c->p, hv, c->Fs, c->Yz, c->Ys, c->FH, c->YH)
#else
        || hpgen_k_step_partials(r->z, c->g, c->p, hv, c->Fs, c->Yz, c->Ys)
#endif
        || hpgen_lu_factor_solve(c->J, c->piv, c->Fs, 1))
        return HPGEN_NONFINITE;
    /* Fs's first column is solved by the factorization, the others by J^{-1} */
    {
        const double* x = c->Fs;
        for (a = 0; a < S; ++a) {
            double v = c->Ys[a];
            for (l = 0; l < HPGEN_NZ; ++l) v -= c->Yz[a + l * S] * x[l];
            Ai[a] = v;
        }
    }
    hpgen_lin_implicit(c, c->Fs + HPGEN_NZ, c->Ys + S, S - 1, Ai + S);
    if (!hpgen_all_finite(Ai, S * S)) return HPGEN_NONFINITE;
#if HPGEN_OPEN
    {
        double* Bi = i == 0 ? c->B : c->E;
        hpgen_lin_implicit(c, c->FH + c->c0 * HPGEN_NZ, c->YH + c->c0 * S, c->nc, Bi);
        if (!hpgen_all_finite(Bi, S * c->nc)) return HPGEN_NONFINITE;
    }
#endif
    if (i > 0) {
        /* A_k = A_i A_k; B_k = A_i B_k + B_i (T holds the old A_k / B_k) */
        memcpy(c->T, c->A, sizeof(double) * S * S);
        for (b = 0; b < S; ++b)
            for (a = 0; a < S; ++a) {
                double v = 0.0;
                for (l = 0; l < S; ++l) v += c->D[a + l * S] * c->T[l + b * S];
                c->A[a + b * S] = v;
            }
        if (c->nc) memcpy(c->T, c->B, sizeof(double) * S * c->nc);
        for (b = 0; b < c->nc; ++b)
            for (a = 0; a < S; ++a) {
                double v = c->E[a + b * S];
                for (l = 0; l < S; ++l) v += c->D[a + l * S] * c->T[l + b * S];
                c->B[a + b * S] = v;
            }
    }
    memcpy(c->g, r->g, sizeof c->g);
    memcpy(c->p, r->p, sizeof c->p);
    return HPGEN_OK;
}

/* Run r (hpgen_run_init at record 0 with the run's first Newton start, its inputs and its
   composition set as for simulate) is stepped along the K + 1 records (g_rec + k NN,
   p_rec + k D): step k starts at record k and is taken exactly as the run takes it
   (hpgen_run_cstep: the predictor through the run's previous solutions, o's Newton, full
   Newton at step 0; a composed step's substeps with their own predictors), so that records
   of the run with the same options are reproduced bit for bit; dev[k] = max |state after
   step k - record k+1| (the caller checks that the records are this module's steps). At
   each substep's solution the derivative (hpgen_lin_substep) and the chain rule over the
   substeps give A_k (2D x 2D, column-major at A + k 4 D^2) and, open, B_k = d/d(step vector
   columns c0 .. c0 + nc - 1) (the inputs or the runtime parameters; 2D x nc column-major
   at B + k 2 D nc; a closed module takes nc = 0). st: the run's counters (iterations,
   Jacobians including one per substep for the derivative). Returns the steps done (K, or
   the failing step with st->code set). */
HPGEN_EXPORT long long hpgen_linearize(hpgen_run* r, long long K, const double* g_rec,
                                       const double* p_rec, double h, long long c0,
                                       long long nc, const hpgen_options* o, double* A,
                                       double* B, double* dev, hpgen_status* st) {
    enum { S = 2 * HPGEN_D };
    double hv[1];
    hpgen_options full;
    hpgen_lin c;
    long long k, done;
    int i;
    hpgen_status_init(st);
#if HPGEN_OPEN
    if (c0 < 2 || nc < 0 || c0 + nc > HPGEN_H) { st->code = HPGEN_INVALID; return 0; }
#else
    if (nc != 0) { st->code = HPGEN_INVALID; return 0; }
#endif
    if (K < 0 || !hpgen_options_ok(o) || r->g_stale) { st->code = HPGEN_INVALID; return 0; }
    /* the partials on the heap: S x nz is megabytes for many bodies, beyond a thread's stack */
    c.Fs = malloc(sizeof(double) * ((size_t)S * HPGEN_NZ * 2 + (size_t)S * S * 3
                                    + (size_t)S * HPGEN_LIN_H * 2));
    if (!c.Fs) { st->code = HPGEN_INVALID; return 0; }
    c.Yz = c.Fs + (size_t)S * HPGEN_NZ;
    c.Ys = c.Yz + (size_t)S * HPGEN_NZ;
    c.D = c.Ys + (size_t)S * S;
    c.T = c.D + (size_t)S * S;
    c.E = c.T + (size_t)S * (S > HPGEN_LIN_H ? S : HPGEN_LIN_H);
    c.c0 = c0;
    c.nc = nc;
    c.jacobians = 0;
    hv[0] = h;
    full = *o;
    full.simplified = 0;
    for (k = 0; k < K; ++k) {
        double m = 0.0;
        memcpy(r->g, g_rec + k * HPGEN_NN, sizeof r->g);
        memcpy(r->p, p_rec + k * HPGEN_D, sizeof r->p);
        memcpy(c.g, r->g, sizeof c.g);
        memcpy(c.p, r->p, sizeof c.p);
        c.A = A + k * S * S;
        c.B = B + k * S * nc;
        if (hpgen_run_cstep_then(r, hv, o, &full, st, 1, hpgen_lin_substep, &c) != HPGEN_OK) {
            done = k;
            goto out;
        }
        for (i = 0; i < HPGEN_NN; ++i) m = fmax(m, fabs(r->g[i] - g_rec[(k + 1) * HPGEN_NN + i]));
        for (i = 0; i < HPGEN_D; ++i) m = fmax(m, fabs(r->p[i] - p_rec[(k + 1) * HPGEN_D + i]));
        dev[k] = m;
    }
    st->step = K;
    done = K;
out:
    st->jacobians += c.jacobians;
    free(c.Fs);
    return done;
}
#endif /* HPGEN_WITH_LAZY */
