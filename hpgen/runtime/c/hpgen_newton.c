/* hpgen's C runtime, part 2: Newton on the step's residual, one step (hpgen_step_core, the
   exported hpgen_step) and the argument checks the runs share. Mirrored in Python by
   hpgen.runtime.newton (the same iteration, tests and results). Included by hpgen_runtime.c
   after hpgen_newton_sparse.c (a sparse module's stop tests and chord). */

/* Newton on residual(z, g, p, h) = 0 from z (in/out): z <- z - J^{-1} F.
   Full Newton evaluates J at every iterate. Simplified Newton (o->simplified) keeps the last
   J^{-1} in (lu, *lu_valid), across steps too, and refreshes it when the contraction
   rate theta = |dz_k| / |dz_{k-1}| exceeds HPGEN_THETA_MAX; if J was already evaluated in
   this step the rest of the step is full Newton (the fallback).
   Converged when |dz| <= tol (1 + |z|), or when |dz| stopped decreasing while
   |dz| <= HPGEN_ROUNDOFF_FLOOR (1 + |z|) (round-off floor); inf-norms; with HPGEN_SPARSE also
   by hpgen_sparse_converged, and a J evaluated in this step by hpgen_chord_converged
   (HPGEN_SIMPLIFIED_REFRESH). Returns a status code. */
static int hpgen_newton_iterates(const double* g, const double* p, const double* hv, double* z,
                                 const hpgen_options* o, double* lu, int* piv,
                                 long long* lu_valid, long long* iters, long long* jacs,
                                 double* rnorm) {
    double F[HPGEN_NZ];
    double dprev = HUGE_VAL;
    int full = !o->simplified, fresh = 0, now;
    long long it;
    int i;
    *iters = 0;
    *rnorm = NAN;
    for (it = 1; it <= o->maxit; ++it) {
        double dn, zn;
        *iters = it;
        now = 0;                           /* J evaluated at this iterate */
        if (full || !*lu_valid) {
            /* F and a fresh J in one evaluation (their common subexpressions once) */
            *lu_valid = 0;
            ++*jacs;
            if (hpgen_newton_fj(z, g, p, hv, F, lu)) return HPGEN_NONFINITE;
            *rnorm = hpgen_norm_inf(F, HPGEN_NZ);
            if (!isfinite(*rnorm) || hpgen_lu_factor_solve(lu, piv, F, o->simplified))
                return HPGEN_NONFINITE;
            *lu_valid = o->simplified ? 1 : 0;   /* lu's J^{-1} (or factors) kept or not */
            fresh = now = 1;
        } else {
            if (hpgen_k_residual(z, g, p, hv, F)) return HPGEN_NONFINITE;
            *rnorm = hpgen_norm_inf(F, HPGEN_NZ);
            if (!isfinite(*rnorm)) return HPGEN_NONFINITE;
            hpgen_lu_apply(lu, piv, F);
        }
        for (i = 0; i < HPGEN_NZ; ++i) z[i] -= F[i];
        dn = hpgen_norm_inf(F, HPGEN_NZ);
        zn = hpgen_norm_inf(z, HPGEN_NZ);
        if (!isfinite(dn) || !isfinite(zn)) return HPGEN_NONFINITE;
        if (it > 1 && dn >= dprev && dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + zn)
            && !hpgen_kept_j_diverges(it, fresh)) return HPGEN_OK;
#if HPGEN_SPARSE
        if (hpgen_sparse_converged(it, dn, dprev, zn, o->tol, full)) return HPGEN_OK;
        if (HPGEN_SIMPLIFIED_REFRESH && !full && fresh && !now
            && hpgen_chord_converged(it, dn, dprev, zn, o->tol)) return HPGEN_OK;
#endif
        if (full) {
            /* quadratic convergence: the error left after dn <= tol is about C tol^2 */
            if (dn <= o->tol * (1.0 + zn)) return HPGEN_OK;
        } else {
            /* linear convergence: the error left is about te/(1 - te) dn, te the rate but at
               least HPGEN_THETA_FLOOR; ask it to be <= HPGEN_SIMPLIFIED_TOL tol, the
               round-off level full Newton reaches */
            double th = dn / dprev, te = th > HPGEN_THETA_FLOOR ? th : HPGEN_THETA_FLOOR;
            if (dn <= HPGEN_SIMPLIFIED_TOL * o->tol * (1.0 + zn)) return HPGEN_OK;
            if (it > 1 && te < 1.0
                && te / (1.0 - te) * dn <= HPGEN_SIMPLIFIED_TOL * o->tol * (1.0 + zn))
                return HPGEN_OK;
        }
        if (!full && it > 1 && dn > HPGEN_THETA_MAX * dprev
            && !(it > 2 && hpgen_at_floor(dn, zn))) {
            if (fresh) full = 1;           /* a fresh J contracts poorly: full Newton */
            else *lu_valid = 0;            /* a stale J: refresh it at the next iterate */
        }
        dprev = dn;
    }
    return HPGEN_NO_CONVERGENCE;
}

/* hpgen_newton_iterates; with a sparse J, a step that converged with a J kept from earlier
   steps alone in more than HPGEN_KEPT_J_ITERATES iterates drops it (HPGEN_SIMPLIFIED_REFRESH,
   hpgen_newton_sparse.c) */
static int hpgen_newton(const double* g, const double* p, const double* hv, double* z,
                        const hpgen_options* o, double* lu, int* piv, long long* lu_valid,
                        long long* iters, long long* jacs, double* rnorm) {
    const long long j0 = *jacs;
    int code = hpgen_newton_iterates(g, p, hv, z, o, lu, piv, lu_valid, iters, jacs, rnorm);
#if HPGEN_SPARSE
    if (HPGEN_SIMPLIFIED_REFRESH && code == HPGEN_OK && o->simplified && *jacs == j0
        && *iters > HPGEN_KEPT_J_ITERATES)
        *lu_valid = 0;
#else
    (void)j0;
#endif
    return code;
}

/* Full Newton (o->simplified = 0): hpgen_newton's iteration, convergence tests and results
   ((z, status, *iters, *rnorm, *jacs += iterations) bitwise), in a loop of its own without
   the simplified-Newton bookkeeping: J in a local array (never kept), the counters in locals,
   and F's norm taken once, at the end. A non-finite F is caught after the solve, where it
   makes dz non-finite (dz = J^{-1} F: every F_i enters some dz_j with a nonzero factor of
   J^{-1}, or as inf * 0 = NaN): then F is tested and, if it is the culprit, z is left at the
   iterate F was evaluated at, as in hpgen_newton. A sparse module's is hpgen_newton_sparse. */
#if !HPGEN_SPARSE
static int hpgen_newton_full(const double* g, const double* p, const double* hv, double* z,
                             const hpgen_options* o, long long* iters, long long* jacs,
                             double* rnorm) {
    double F[HPGEN_NZ], Fz[HPGEN_NZ], J[HPGEN_LU_SIZE], dprev = HUGE_VAL;
    const double tol = o->tol;
    const long long maxit = o->maxit;
    long long it;
    int i, piv[HPGEN_NZ], evaluated = 0, code = HPGEN_NO_CONVERGENCE;
    for (it = 1; it <= maxit; ++it) {
        double dn, zn;
        if (hpgen_newton_fj(z, g, p, hv, F, J)) { code = HPGEN_NONFINITE; break; }
        memcpy(Fz, F, sizeof F);                  /* F(z), for *rnorm */
        evaluated = 1;
        if (hpgen_lu_factor_solve(J, piv, F, 0)) { code = HPGEN_NONFINITE; break; }
        dn = hpgen_norm_inf(F, HPGEN_NZ);
        if (!isfinite(dn) && !hpgen_all_finite(Fz, HPGEN_NZ)) { code = HPGEN_NONFINITE; break; }
        for (i = 0; i < HPGEN_NZ; ++i) z[i] -= F[i];
        zn = hpgen_norm_inf(z, HPGEN_NZ);
        if (!isfinite(dn) || !isfinite(zn)) { code = HPGEN_NONFINITE; break; }
        if (it > 1 && dn >= dprev && dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + zn)) {
            code = HPGEN_OK; break;
        }
        if (dn <= tol * (1.0 + zn)) { code = HPGEN_OK; break; }
        dprev = dn;
    }
    if (it > maxit) it = maxit;
    *iters = it;
    *jacs += it;
    *rnorm = evaluated ? hpgen_norm_inf(Fz, HPGEN_NZ) : NAN;
    return code;
}
#endif


/* A family module (HPGEN_G_PACKED): g is block-diagonal and the update kernel's variant
   hpgen_k_update_nz writes g_{k+1} as its HPGEN_GNZ structural nonzeros, whose positions in
   the dense n x n g (column-major) are hpgen_update_out0_pos. A run keeps g dense (the API's
   form) but its steps read and write only those positions: no step zeroes, copies or checks
   the n^2 - HPGEN_GNZ structural zeros (its kernels gather g's nonzeros themselves). Other
   modules: HPGEN_GNZ = HPGEN_NN, the positions the identity. */
#if HPGEN_SPARSE && defined(HPGEN_UPDATE_NZ_VARIANT) && defined(HPGEN_UPDATE_OUT0_NNZ) \
    && !defined(HPGEN_UPDATE_OUT1_NNZ)
#define HPGEN_G_PACKED 1
#define HPGEN_GNZ HPGEN_UPDATE_OUT0_NNZ
#else
#define HPGEN_G_PACKED 0
#define HPGEN_GNZ HPGEN_NN
#endif

/* gp <- g's HPGEN_GNZ stored entries (dense g: all of it) */
static void hpgen_g_pack(const double* g, double* gp) {
#if HPGEN_G_PACKED
    int i;
    for (i = 0; i < HPGEN_GNZ; ++i) gp[i] = g[hpgen_update_out0_pos[i]];
#else
    memcpy(gp, g, HPGEN_NN * sizeof(double));
#endif
}

/* g's stored entries <- gp (the structural zeros of a packed g untouched) */
static void hpgen_g_unpack(const double* gp, double* g) {
#if HPGEN_G_PACKED
    int i;
    for (i = 0; i < HPGEN_GNZ; ++i) g[hpgen_update_out0_pos[i]] = gp[i];
#else
    memcpy(g, gp, HPGEN_NN * sizeof(double));
#endif
}

/* g's stored entries <- those of src (dense both; a packed g's structural zeros untouched) */
static void hpgen_g_copy(const double* src, double* g) {
#if HPGEN_G_PACKED
    int i;
    for (i = 0; i < HPGEN_GNZ; ++i) g[hpgen_update_out0_pos[i]] = src[hpgen_update_out0_pos[i]];
#else
    memcpy(g, src, HPGEN_NN * sizeof(double));
#endif
}

/* The Newton solve of one step: margin(z, h) > 0 at the start (check_start), Newton from z
   (in/out), margin(z, h) > 0 at the solution. Returns the status code. */
static int hpgen_step_solve(const double* g, const double* p, const double* hv, double* z,
                            const hpgen_options* o, double* lu, int* piv, long long* lu_valid,
                            long long* iters, long long* jacs, double* rnorm, int check_start) {
    double m[1];
    int code;
    /* a start outside tau's domain means h is too large for the chart: do not let Newton
       wander to a spurious root from there. Only needed for a start that is not built from
       the previous steps' solutions (whose margins, same h, were checked). */
    if (check_start && !hpgen_k_margin(z, hv, m) && m[0] <= 0.0) {
        *iters = 0; *rnorm = NAN;
        return HPGEN_DOMAIN;
    }
    if (o->simplified) {
        code = hpgen_newton(g, p, hv, z, o, lu, piv, lu_valid, iters, jacs, rnorm);
    } else {
        /* full Newton keeps no J^{-1} (a sparse module's chord may share its factors
           between the substeps of a composed step: hpgen_newton_sparse's lu_state) */
        code = hpgen_newton_sparse(g, p, hv, z, o, lu, piv, lu_valid, iters, jacs, rnorm);
    }
    /* a Newton failure is reported as such (wherever its last iterate went): DOMAIN is a
       converged solution outside tau's domain only */
    if (code != HPGEN_OK) { *lu_valid = 0; return code; }
    if (hpgen_k_margin(z, hv, m)) return HPGEN_NONFINITE;
    if (!(m[0] > 0.0)) { *lu_valid = 0; return HPGEN_DOMAIN; }
    return HPGEN_OK;
}

/* One step: hpgen_step_solve, then update -> (g1, p1), g1 dense (n x n); with_g = 0:
   update_p -> p1 only (g1 untouched). */
/* HPGEN_FLATTEN (small kernels): inline them and the Newton loop into one body (GCC/Clang),
   so the compiler schedules the kernels' arithmetic together with the solve */
#if HPGEN_FLATTEN && defined(__GNUC__)
__attribute__((flatten))
#endif
static int hpgen_step_core(const double* g, const double* p, const double* hv, double* z,
                           const hpgen_options* o, double* lu, int* piv, long long* lu_valid,
                           double* g1, double* p1, long long* iters, long long* jacs,
                           double* rnorm, int check_start, int with_g) {
    int code = hpgen_step_solve(g, p, hv, z, o, lu, piv, lu_valid, iters, jacs, rnorm,
                                check_start);
    if (code != HPGEN_OK) return code;
    if (!with_g) {
        if (hpgen_k_update_p(z, g, p, hv, p1) || !hpgen_all_finite(p1, HPGEN_D))
            return HPGEN_NONFINITE;
        return HPGEN_OK;
    }
    if (hpgen_k_update(z, g, p, hv, g1, p1)) return HPGEN_NONFINITE;
    if (!hpgen_all_finite(g1, HPGEN_NN) || !hpgen_all_finite(p1, HPGEN_D))
        return HPGEN_NONFINITE;
    return HPGEN_OK;
}

#if HPGEN_G_PACKED
/* hpgen_step_core with g1 as g_{k+1}'s HPGEN_GNZ stored entries (a run's step) */
static int hpgen_step_core_packed(const double* g, const double* p, const double* hv, double* z,
                                  const hpgen_options* o, double* lu, int* piv,
                                  long long* lu_valid, double* g1, double* p1, long long* iters,
                                  long long* jacs, double* rnorm, int check_start, int with_g) {
    int code = hpgen_step_solve(g, p, hv, z, o, lu, piv, lu_valid, iters, jacs, rnorm,
                                check_start);
    if (code != HPGEN_OK) return code;
    if (!with_g) {
        if (hpgen_k_update_p(z, g, p, hv, p1) || !hpgen_all_finite(p1, HPGEN_D))
            return HPGEN_NONFINITE;
        return HPGEN_OK;
    }
    if (hpgen_k_update_nz(z, g, p, hv, g1, p1)) return HPGEN_NONFINITE;
    if (!hpgen_all_finite(g1, HPGEN_GNZ) || !hpgen_all_finite(p1, HPGEN_D))
        return HPGEN_NONFINITE;
    return HPGEN_OK;
}
#else
#define hpgen_step_core_packed hpgen_step_core
#endif

static void hpgen_status_init(hpgen_status* st) {
    st->code = HPGEN_OK; st->step = 0; st->iterations = 0; st->total_iterations = 0;
    st->residual = 0.0; st->jacobians = 0; st->guarded = 0;
}

static int hpgen_options_ok(const hpgen_options* o) {
    return o->maxit >= 1 && o->tol > 0.0 && isfinite(o->tol);
}

/* One step from (g, p) with step size h; z: Newton start in, solution out (no memory from
   earlier steps; callers normally ask for full Newton here: a cold start). Returns the code. */
#if HPGEN_OPEN
/* (open model: hv is the step vector [h, t, u, params] of the step) */
HPGEN_EXPORT int hpgen_step(const double* g, const double* p, const double* hv, double* z,
                            const hpgen_options* o, double* g1, double* p1, hpgen_status* st) {
    double lu[HPGEN_LU_SIZE];
#else
HPGEN_EXPORT int hpgen_step(const double* g, const double* p, double h, double* z,
                            const hpgen_options* o, double* g1, double* p1, hpgen_status* st) {
    double hv[1], lu[HPGEN_LU_SIZE];
#endif
    int piv[HPGEN_NZ];
    long long it, valid = 0;
    double r;
    int code;
    hpgen_status_init(st);
    if (!hpgen_options_ok(o)) { st->code = HPGEN_INVALID; return HPGEN_INVALID; }
#if !HPGEN_OPEN
    hv[0] = h;
#endif
    code = hpgen_step_core(g, p, hv, z, o, lu, piv, &valid, g1, p1, &it, &st->jacobians, &r, 1,
                           1);
    st->code = code; st->iterations = it; st->total_iterations = it; st->residual = r;
    return code;
}

