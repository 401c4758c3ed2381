/* hpgen's C runtime, part 2: Newton on the step's residual, one step (hpgen_step_core, the
   exported hpgen_step) and the argument checks the runs share. Mirrored in Python by
   hpgen.runtime.newton (the same iteration, tests and results). Included by hpgen_runtime.c
   after hpgen_linalg.c. */

#if HPGEN_SPARSE
/* The extra stop of a module with a sparse Newton matrix (many bodies): the error left
   after the iterate, estimated from the rate theta = |dz| / |dz_prev|, is <= tol (1 + |z|).
   After an iterate with a fresh J: theta^2 |dz| (quadratic convergence: C |dz|^2 with
   C = |dz| / |dz_prev|^2, an overestimate once |dz| is round-off), and theta |dz| (the
   error were the convergence only linear) <= HPGEN_ROUNDOFF_FLOOR (1 + |z|). With a kept J:
   |dz| <= HPGEN_ROUNDOFF_FLOOR (1 + |z|) and te/(1 - te) |dz| with te = max(theta,
   HPGEN_THETA_FLOOR) (a linear rate). The round-off in dz of a many-body step is itself about tol (1 + |z|)
   and grows with the number of bodies, so the dense modules' tests (|dz| <= tol (1 + |z|);
   a simplified bound HPGEN_SIMPLIFIED_TOL times smaller) end there only when |dz|
   stagnates, and the stagnation of a stale J looks like a poor contraction that refreshes
   J. Mirrored in hpgen.runtime.newton.sparse_converged. */
static int hpgen_sparse_converged(long long it, double dn, double dprev, double zn,
                                  double tol, int fresh_j) {
    double th, te;
    if (it < 2) return 0;
    th = dn / dprev;
    if (!(th < 1.0)) return 0;
    if (fresh_j)
        return th * dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + zn) && th * th * dn <= tol * (1.0 + zn);
    if (!(dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + zn))) return 0;
    te = th > HPGEN_THETA_FLOOR ? th : HPGEN_THETA_FLOOR;
    return te / (1.0 - te) * dn <= tol * (1.0 + zn);
}

/* The chord's stop (a J evaluated in this step at an earlier iterate, kept): from the second
   iterate on, the rate theta_k = |dz_k| / |dz_{k-1}| < 1 bounds the error left in z_k by
   theta_k / (1 - theta_k) |dz_k| (Hairer-Wanner II, IV.8); stop when that is
   <= tol (1 + |z|) with |dz_k| <= HPGEN_ROUNDOFF_FLOOR (1 + |z|), rather than pay one more
   residual and solve to see the next correction at the noise. Unlike a J kept across steps
   (hpgen_sparse_converged's HPGEN_THETA_FLOOR and HPGEN_SIMPLIFIED_TOL), the chord's J_0 was
   evaluated at the step's own start z_0: J_0 - J(z) = O(|z - z_0|) in every direction, so no
   slow mode hides behind the fast ones and the chord's rate, of the order of
   C |dz_1| (C the curvature of F), is what theta_k measures. Mirrored in
   hpgen.runtime.newton_sparse.chord_converged. */
static int hpgen_chord_converged(long long it, double dn, double dprev, double zn, double tol) {
    double th;
    if (it < 2) return 0;
    th = dn / dprev;
    return th < 1.0 && dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + zn)
        && th / (1.0 - th) * dn <= tol * (1.0 + zn);
}

/* A sparse module's simplified Newton keeps its J at the round-off noise: from a step's
   third iterate on, once |dz| <= HPGEN_KEEP_J_FLOOR (1 + |z|), a contraction rate above
   HPGEN_THETA_MAX neither refreshes J nor switches to full Newton; the iterates go on with
   the kept J until a stop test holds (the stagnation test, once |dz| stops decreasing, or
   hpgen_sparse_converged). The round-off in dz of a many-body step is about tol (1 + |z|)
   times a factor that grows with the bodies: corrections at that level are noise whose
   ratio is a random number of order 1, and a fresh J (several residuals' cost, with its
   factorization) cannot contract noise. The rate of the first two corrections, taken while
   the start's error dominates, still refreshes an aged J. HPGEN_KEEP_J_FLOOR is 10 times
   below HPGEN_ROUNDOFF_FLOOR: above it the slow rate of an aged J can pass for noise, and
   the stagnation test then stops with errors of that size, which the joints' velocity
   form shows (hpgen.abi.KEEP_J_FLOOR). Mirrored in hpgen.runtime.newton.at_floor. */
static int hpgen_at_floor(double dn, double zn) {
    return dn <= HPGEN_KEEP_J_FLOOR * (1.0 + zn);
}

/* ... and a kept J whose second correction is no smaller than its first does not stop on
   the stagnation test (the first correction being at the floor): that J may not contract
   at all, and the error left would be of the floor's size; the rate test refreshes it. */
#define hpgen_kept_j_diverges(it, fresh) ((it) == 2 && !(fresh))
#else
#define hpgen_at_floor(dn, zn) 0
#define hpgen_kept_j_diverges(it, fresh) 0
#endif

/* Newton on residual(z, g, p, h) = 0 from z (in/out): z <- z - J^{-1} F.
   Full Newton evaluates J at every iterate. Simplified Newton (o->simplified) keeps the last
   J^{-1} in (lu, *lu_valid), across steps too, and refreshes it when the contraction
   rate theta = |dz_k| / |dz_{k-1}| exceeds HPGEN_THETA_MAX; if J was already evaluated in
   this step the rest of the step is full Newton (the fallback).
   Converged when |dz| <= tol (1 + |z|), or when |dz| stopped decreasing while
   |dz| <= HPGEN_ROUNDOFF_FLOOR (1 + |z|) (round-off floor); inf-norms; with HPGEN_SPARSE also
   by hpgen_sparse_converged. Returns a status code. */
static int hpgen_newton(const double* g, const double* p, const double* hv, double* z,
                        const hpgen_options* o, double* lu, int* piv, long long* lu_valid,
                        long long* iters, long long* jacs, double* rnorm) {
    double F[HPGEN_NZ];
    double dprev = HUGE_VAL;
    int full = !o->simplified, fresh = 0;
    long long it;
    int i;
    *iters = 0;
    *rnorm = NAN;
    for (it = 1; it <= o->maxit; ++it) {
        double dn, zn;
        *iters = it;
        if (full || !*lu_valid) {
            /* F and a fresh J in one evaluation (their common subexpressions once) */
            *lu_valid = 0;
            ++*jacs;
            if (hpgen_newton_fj(z, g, p, hv, F, lu)) return HPGEN_NONFINITE;
            *rnorm = hpgen_norm_inf(F, HPGEN_NZ);
            if (!isfinite(*rnorm) || hpgen_lu_factor_solve(lu, piv, F, o->simplified))
                return HPGEN_NONFINITE;
            *lu_valid = o->simplified ? 1 : 0;   /* lu's J^{-1} (or factors) kept or not */
            fresh = 1;
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

#if HPGEN_SPARSE
/* The round-off stall of a module with a sparse Newton matrix (many bodies): the correction
   dz_k is the round-off noise of the step's solution, and z_k is as close to it as the
   arithmetic allows, when
     theta_k = |dz_k| / |dz_{k-1}| > HPGEN_THETA_MAX,  |dz_k| <= HPGEN_STALL_MAX (1 + |z_k|),
   with a J that contracts: evaluated at z_{k-1} (fresh: Newton's rate near the root is
   C |dz_{k-1}|, far below THETA_MAX at that size), or one that already contracted in this step
   (theta <= THETA_MAX once; a J factored in this step keeps its linear rate, which only falls
   as the iterates approach the root; a J kept from earlier steps does not qualify: its slow
   modes can surface once its fast ones died). The noise of dz grows with cond(J), so its
   level is read off the data (where the step's corrections stop contracting); a stall above
   HPGEN_STALL_MAX (1 + |z|) is not taken for noise. Mirrored in
   hpgen.runtime.newton_sparse.stalled. */
static int hpgen_stalled(long long it, double dn, double dprev, double zn, int fresh,
                         int contracted) {
    return it > 1 && (fresh || contracted) && dn > HPGEN_THETA_MAX * dprev
        && dn <= HPGEN_STALL_MAX * (1.0 + zn);
}

/* One pass of full Newton of a module with a sparse Newton matrix. chord = 1: a chord
   iteration within the step (J and its factors at the step's first iterate; the next iterates
   one residual and one solve each, while they contract; a kept J whose rate
   theta = |dz| / |dz_prev| exceeds HPGEN_THETA_MAX, and is no stall, is evaluated again at
   the next iterate); 0: J at every iterate. Nothing is kept across steps.
   Stops (inf-norms): |dz| stopped decreasing while <= HPGEN_ROUNDOFF_FLOOR (1 + |z|); after a
   fresh J |dz| <= tol (1 + |z|) and hpgen_sparse_converged (quadratic rate); after a kept J
   hpgen_chord_converged (the chord's rate bound; HPGEN_CHORD_RATE_STOP = 0:
   hpgen_sparse_converged asked of HPGEN_SIMPLIFIED_TOL tol, simplified Newton's bound); the
   round-off stall (hpgen_stalled).
   Mirrored in hpgen.runtime.newton_sparse.solve_pass. */
static int hpgen_newton_sparse_pass(const double* g, const double* p, const double* hv,
                                    double* z, const hpgen_options* o, int chord,
                                    long long* iters, long long* jacs, double* rnorm) {
    double F[HPGEN_NZ], Fz[HPGEN_NZ], J[HPGEN_LU_SIZE], dprev = HUGE_VAL;
    const double tol = o->tol;
    const long long maxit = o->maxit;
    long long it, nj = 0;
    int i, piv[HPGEN_NZ], evaluated = 0, need_j = 1, fresh = 0, contracted = 0;
    int code = HPGEN_NO_CONVERGENCE;
    for (it = 1; it <= maxit; ++it) {
        double dn, zn;
        if (need_j) {
            ++nj;
            if (hpgen_newton_fj(z, g, p, hv, F, J)) { code = HPGEN_NONFINITE; break; }
            memcpy(Fz, F, sizeof F);
            evaluated = 1;
            if (hpgen_lu_factor_solve(J, piv, F, chord)) {
                code = HPGEN_NONFINITE; break;
            }
            need_j = !chord;
            fresh = 1;
        } else {
            if (hpgen_k_residual(z, g, p, hv, F)) { code = HPGEN_NONFINITE; break; }
            memcpy(Fz, F, sizeof F);
            hpgen_lu_apply(J, piv, F);
            fresh = 0;
        }
        dn = hpgen_norm_inf(F, HPGEN_NZ);
        if (!isfinite(dn) && !hpgen_all_finite(Fz, HPGEN_NZ)) { code = HPGEN_NONFINITE; break; }
        for (i = 0; i < HPGEN_NZ; ++i) z[i] -= F[i];
        zn = hpgen_norm_inf(z, HPGEN_NZ);
        if (!isfinite(dn) || !isfinite(zn)) { code = HPGEN_NONFINITE; break; }
        if (it > 1 && dn >= dprev && dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + zn)) {
            code = HPGEN_OK; break;
        }
        if (fresh && dn <= tol * (1.0 + zn)) { code = HPGEN_OK; break; }
        if (fresh ? hpgen_sparse_converged(it, dn, dprev, zn, tol, 1)
            : HPGEN_CHORD_RATE_STOP ? hpgen_chord_converged(it, dn, dprev, zn, tol)
            : hpgen_sparse_converged(it, dn, dprev, zn, HPGEN_SIMPLIFIED_TOL * tol, 0)) {
            code = HPGEN_OK; break;
        }
        if (hpgen_stalled(it, dn, dprev, zn, fresh, contracted)) { code = HPGEN_OK; break; }
        if (it > 1 && dn <= HPGEN_THETA_MAX * dprev) contracted = 1;
        else if (it > 1 && !fresh) need_j = 1;
        dprev = dn;
    }
    if (it > maxit) it = maxit;
    *iters = it;
    *jacs += nj;
    *rnorm = evaluated ? hpgen_norm_inf(Fz, HPGEN_NZ) : NAN;
    return code;
}

/* The chord pass, and if it fails (a divergent or stalled chord from a poor start: the
   predictor's extrapolation on a hard step) a second pass with J at every iterate from the same
   start; iterations and J evaluations of both passes are counted. HPGEN_SPARSE_CHORD = 0: J
   at every iterate only. Mirrored in hpgen.runtime.newton_sparse.solve_sparse. */
static int hpgen_newton_sparse(const double* g, const double* p, const double* hv, double* z,
                               const hpgen_options* o, long long* iters, long long* jacs,
                               double* rnorm) {
    double z0[HPGEN_NZ];
    long long first;
    int code;
    if (!HPGEN_SPARSE_CHORD)
        return hpgen_newton_sparse_pass(g, p, hv, z, o, 0, iters, jacs, rnorm);
    memcpy(z0, z, sizeof z0);
    code = hpgen_newton_sparse_pass(g, p, hv, z, o, 1, iters, jacs, rnorm);
    if (code == HPGEN_OK || *iters <= 1) return code;   /* a first iterate is the same in both */
    first = *iters;
    memcpy(z, z0, sizeof z0);
    code = hpgen_newton_sparse_pass(g, p, hv, z, o, 0, iters, jacs, rnorm);
    *iters += first;
    return code;
}
#else
#define hpgen_newton_sparse hpgen_newton_full
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
        *lu_valid = 0;                     /* full Newton keeps no J^{-1} */
        code = hpgen_newton_sparse(g, p, hv, z, o, iters, jacs, rnorm);
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
    st->residual = 0.0; st->jacobians = 0;
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

