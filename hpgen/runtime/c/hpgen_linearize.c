/* hpgen's C runtime, part 5: the linearization of the step along recorded steps
   (hpgen.runtime.linearize). Included by hpgen_runtime.c after hpgen_newton.c. */

/* For k = 0..K-1: Newton on step k from the record (g_k, p_k) = (g_rec + k NN,
   p_rec + k D): step 0 by full Newton from z (in/out: z_0 in, the last solution out), step
   k > 0 from the extrapolation of z_{k-1}, z_{k-2}, z_{k-3} (o->predictor) with o's Newton,
   whose simplified iterations use J^{-1} of the previous step's converged z; dev[k] =
   max |update(z_k) - record k+1| (the caller checks that the records are this module's
   steps). At the converged z_k: J = jacobian(z_k) inverted once (and kept as the next step's
   Newton matrix), (Fs, Yz, Ys) = step_partials(z_k), A_k = Ys - Yz J^{-1} Fs, 2D x 2D
   column-major at A + k 4 D^2. Open module: step k's step vector is hv_rec + k H, and with
   the step vector's partials (FH, YH) also B_k = YH_c - Yz J^{-1} FH_c over the step
   vector's columns c = c0 .. c0 + nc - 1 (the inputs or the runtime parameters), 2D x nc
   column-major at B + k 2 D nc. Returns the steps done (K, or the failing step with
   st->code set). */
#if HPGEN_OPEN
HPGEN_EXPORT long long hpgen_linearize(long long K, const double* g_rec, const double* p_rec,
                                       const double* hv_rec, long long c0, long long nc,
                                       double* z, const hpgen_options* o, double* A,
                                       double* B, double* dev, hpgen_status* st) {
    enum { S = 2 * HPGEN_D };
    double g1[HPGEN_NN], p1[HPGEN_D], J[HPGEN_LU_SIZE], FH[HPGEN_NZ * HPGEN_H],
        YH[S * HPGEN_H], zlast[HPGEN_NZ], zprev[HPGEN_NZ] = {0.0},
        zprev2[HPGEN_NZ] = {0.0}, res;
#else
HPGEN_EXPORT long long hpgen_linearize(long long K, const double* g_rec, const double* p_rec,
                                       double h, double* z, const hpgen_options* o,
                                       double* A, double* dev, hpgen_status* st) {
    enum { S = 2 * HPGEN_D };
    double hv[1], g1[HPGEN_NN], p1[HPGEN_D], J[HPGEN_LU_SIZE], zlast[HPGEN_NZ],
        zprev[HPGEN_NZ] = {0.0}, zprev2[HPGEN_NZ] = {0.0}, res;
#endif
    /* the step's partials on the heap: S x nz three times is megabytes for many bodies,
       beyond a thread's stack */
    double *Fs = malloc(sizeof(double) * (size_t)S * HPGEN_NZ * 2 + sizeof(double) * S * S),
           *Yz = Fs ? Fs + (size_t)S * HPGEN_NZ : NULL, *Ys = Fs ? Yz + (size_t)S * HPGEN_NZ : NULL;
    long long done;
    int piv[HPGEN_NZ];
    long long k, it, valid = 0;
    int i, j, l, code;
    hpgen_options full;
    hpgen_status_init(st);
#if HPGEN_OPEN
    if (K < 0 || c0 < 2 || nc < 0 || c0 + nc > HPGEN_H || !hpgen_options_ok(o)) {
        st->code = HPGEN_INVALID; free(Fs); return 0;
    }
#else
    if (K < 0 || !hpgen_options_ok(o)) { st->code = HPGEN_INVALID; free(Fs); return 0; }
    hv[0] = h;
#endif
    if (!Fs) { st->code = HPGEN_INVALID; return 0; }
    full = *o;
    full.simplified = 0;
    for (k = 0; k < K; ++k) {
        const double* g = g_rec + k * HPGEN_NN;
        const double* p = p_rec + k * HPGEN_D;
#if HPGEN_OPEN
        const double* hv = hv_rec + k * HPGEN_H;
        double* Bk = B + k * S * nc;
#endif
        double* Ak = A + k * S * S;
        double m = 0.0;
        /* the start: the extrapolation through z_{k-1}, z_{k-2}, z_{k-3} (quadratic, as
           hpgen_run_step's predictor before it extrapolated z - G instead) */
        memcpy(zlast, z, sizeof zlast);
        if (o->predictor && k >= 3)
            for (i = 0; i < HPGEN_NZ; ++i) z[i] = 3.0 * (z[i] - zprev[i]) + zprev2[i];
        else if (o->predictor && k == 2)
            for (i = 0; i < HPGEN_NZ; ++i) z[i] = 2.0 * z[i] - zprev[i];
        code = hpgen_step_core(g, p, hv, z, k == 0 ? &full : o, J, piv, &valid, g1, p1, &it,
                               &st->jacobians, &res, k == 0, 1);
        st->iterations = it; st->total_iterations += it; st->residual = res;
        if (code != HPGEN_OK) { st->code = code; st->step = k; done = k; goto out; }
        for (i = 0; i < HPGEN_NN; ++i) m = fmax(m, fabs(g1[i] - g[HPGEN_NN + i]));
        for (i = 0; i < HPGEN_D; ++i) m = fmax(m, fabs(p1[i] - p[HPGEN_D + i]));
        dev[k] = m;
        ++st->jacobians;
        valid = 0;
        if (hpgen_newton_j(z, g, p, hv, J)
#if HPGEN_OPEN
            || hpgen_k_step_partials(z, g, p, hv, Fs, Yz, Ys, FH, YH)
#else
            || hpgen_k_step_partials(z, g, p, hv, Fs, Yz, Ys)
#endif
            || hpgen_lu_factor_solve(J, piv, Fs, 1)) {
            st->code = HPGEN_NONFINITE; st->step = k; done = k; goto out;
        }
        valid = o->simplified ? 1 : 0;    /* J holds J^{-1} at z_k: the next Newton matrix */
        /* Fs's first column is solved, the others by J^{-1} */
        for (j = 1; j < S; ++j) hpgen_lu_apply(J, piv, Fs + j * HPGEN_NZ);
        for (j = 0; j < S; ++j)
            for (i = 0; i < S; ++i) {
                double a = Ys[i + j * S];
                for (l = 0; l < HPGEN_NZ; ++l) a -= Yz[i + l * S] * Fs[l + j * HPGEN_NZ];
                Ak[i + j * S] = a;
            }
        if (!hpgen_all_finite(Ak, S * S)) { st->code = HPGEN_NONFINITE; st->step = k; done = k; goto out; }
#if HPGEN_OPEN
        for (j = 0; j < nc; ++j) {
            double* f = FH + (c0 + j) * HPGEN_NZ;
            hpgen_lu_apply(J, piv, f);
            for (i = 0; i < S; ++i) {
                double a = YH[i + (c0 + j) * S];
                for (l = 0; l < HPGEN_NZ; ++l) a -= Yz[i + l * S] * f[l];
                Bk[i + j * S] = a;
            }
        }
        if (!hpgen_all_finite(Bk, S * nc)) { st->code = HPGEN_NONFINITE; st->step = k; done = k; goto out; }
#endif
        memcpy(zprev2, zprev, sizeof zprev);
        memcpy(zprev, zlast, sizeof zprev);
    }
    st->step = K;
    done = K;
out:
    free(Fs);
    return done;
}
