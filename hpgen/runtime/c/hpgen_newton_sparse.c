/* hpgen's C runtime, part 2a: Newton of a module with a sparse Newton matrix (many bodies):
   its stop tests (the rate bounds, the round-off stall) and its full Newton, a chord
   iteration within the step (hpgen_newton_sparse). Mirrored in Python by
   hpgen.runtime.newton_sparse and hpgen.runtime.newton (sparse_converged, at_floor).
   Included by hpgen_runtime.c after hpgen_linalg.c, before hpgen_newton.c. */

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

/* A sparse module's simplified Newton (hpgen_newton) with HPGEN_SIMPLIFIED_REFRESH = 1:
   (a) a J evaluated in this step (at its start or at a refresh) stops, on its later iterates,
   on the chord's rate bound (hpgen_chord_converged: J - J(z) = O(|z - z_j|) in every
   direction, no slow mode behind the fast ones), where a J kept from earlier steps keeps
   the floored bound of hpgen_sparse_converged; (b) a step that converged with a J kept from
   earlier steps alone, in more than HPGEN_KEPT_J_ITERATES iterates, drops that J: the next
   step evaluates J at its first iterate. A kept J's rate grows with its age (J - J(z) =
   O(age h)), and with it the iterates a step needs from the predictor's start; a J
   refreshed only when its rate exceeds HPGEN_THETA_MAX has wasted two iterates in that step
   and the slow ones before it. 0: neither (a build may set it to compare). Mirrored in
   hpgen.runtime.newton (SIMPLIFIED_REFRESH, KEPT_J_ITERATES). */
#ifndef HPGEN_SIMPLIFIED_REFRESH
#define HPGEN_SIMPLIFIED_REFRESH 1
#endif
#ifndef HPGEN_KEPT_J_ITERATES
#define HPGEN_KEPT_J_ITERATES 3
#endif

/* ... and a kept J whose second correction is no smaller than its first does not stop on
   the stagnation test (the first correction being at the floor): that J may not contract
   at all, and the error left would be of the floor's size; the rate test refreshes it. */
#define hpgen_kept_j_diverges(it, fresh) ((it) == 2 && !(fresh))
#else
#define hpgen_at_floor(dn, zn) 0
#define hpgen_kept_j_diverges(it, fresh) 0
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

/* The stop of a chord that starts with a J factored at another substep of the same size
   (shared = 1 in hpgen_newton_sparse_pass): that J is O(h) away from this step's, not
   O(|dz|), so its rate need not be uniform over the directions (a slow mode can hide behind
   the fast ones while they dominate); the bound takes the rate as at least HPGEN_THETA_FLOOR,
   as simplified Newton's: te / (1 - te) |dz| <= tol (1 + |z|), te = max(theta,
   HPGEN_THETA_FLOOR), with |dz| <= HPGEN_ROUNDOFF_FLOOR (1 + |z|). Mirrored in
   hpgen.runtime.newton_sparse.shared_converged. */
static int hpgen_shared_converged(long long it, double dn, double dprev, double zn,
                                  double tol) {
    double th, te;
    if (it < 2) return 0;
    th = dn / dprev;
    te = th > HPGEN_THETA_FLOOR ? th : HPGEN_THETA_FLOOR;
    return te < 1.0 && dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + zn)
        && te / (1.0 - te) * dn <= tol * (1.0 + zn);
}

/* A pass wanders when a later correction is larger than its first one, above the noise
   (|dz_k| > |dz_1| and > HPGEN_STALL_MAX (1 + |z|)): from a start inside Newton's basin the
   corrections shrink from the first one on (Kantorovich: the first correction measures the
   distance to the root, and the iterates stay within about twice it); corrections that
   grow leave the start's basin, and where they end is a root of F that need not be the
   step's (on the capsule chain, Gauss 2 at h = 1e-2, a root with the energy 120 higher).
   The pass fails (HPGEN_NO_CONVERGENCE) and the next route takes the step: J at every
   iterate from the same start, then the run's plain warm start (hpgen_run_step). Mirrored
   in hpgen.runtime.newton_sparse.wanders. */
static int hpgen_wanders(double dn, double d1, double zn) {
    return dn > d1 && dn > HPGEN_STALL_MAX * (1.0 + zn);
}

/* One pass of full Newton of a module with a sparse Newton matrix. chord = 1: a chord
   iteration within the step (J and its factors at the step's first iterate; the next iterates
   one residual and one solve each, while they contract; a kept J whose rate
   theta = |dz| / |dz_prev| exceeds HPGEN_THETA_MAX, and is no stall, is evaluated again at
   the next iterate); 0: J at every iterate. A pass that wanders (hpgen_wanders) fails.
   J, piv: the factors' storage; shared = 1: they
   hold a J factored at another substep of the same size, which the chord starts with
   (hpgen_shared_converged its stop until J is evaluated here).
   Stops (inf-norms): |dz| stopped decreasing while <= HPGEN_ROUNDOFF_FLOOR (1 + |z|); after a
   fresh J |dz| <= tol (1 + |z|) and hpgen_sparse_converged (quadratic rate); after a kept J
   hpgen_chord_converged (the chord's rate bound; HPGEN_CHORD_RATE_STOP = 0:
   hpgen_sparse_converged asked of HPGEN_SIMPLIFIED_TOL tol, simplified Newton's bound); the
   round-off stall (hpgen_stalled).
   Mirrored in hpgen.runtime.newton_sparse.solve_pass. */
static int hpgen_newton_sparse_pass(const double* g, const double* p, const double* hv,
                                    double* z, const hpgen_options* o, int chord, double* J,
                                    int* piv, int shared, long long* iters, long long* jacs,
                                    double* rnorm) {
    double F[HPGEN_NZ], Fz[HPGEN_NZ], dprev = HUGE_VAL, d1 = HUGE_VAL;
    const double tol = o->tol;
    const long long maxit = o->maxit;
    long long it, nj = 0;
    int i, evaluated = 0, need_j = !shared, fresh = 0, contracted = 0, own = 0;
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
            fresh = own = 1;
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
        if (it == 1) d1 = dn;
        else if (hpgen_wanders(dn, d1, zn)) break;
        /* (a shared J's slow modes can read as a stagnation or a stall: not until J is
           evaluated here) */
        if (it > 1 && own && dn >= dprev && dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + zn)) {
            code = HPGEN_OK; break;
        }
        if (fresh && dn <= tol * (1.0 + zn)) { code = HPGEN_OK; break; }
        if (fresh ? hpgen_sparse_converged(it, dn, dprev, zn, tol, 1)
            : !own ? hpgen_shared_converged(it, dn, dprev, zn, tol)
            : HPGEN_CHORD_RATE_STOP ? hpgen_chord_converged(it, dn, dprev, zn, tol)
            : hpgen_sparse_converged(it, dn, dprev, zn, HPGEN_SIMPLIFIED_TOL * tol, 0)) {
            code = HPGEN_OK; break;
        }
        if (own && hpgen_stalled(it, dn, dprev, zn, fresh, contracted)) {
            code = HPGEN_OK; break;
        }
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

/* lu_state of a sparse module's full Newton (hpgen_newton_sparse; a run's lu_valid): */
#define HPGEN_LU_STORE 2    /* in: factor the step's J in the caller's lu, to be shared */
#define HPGEN_LU_SHARED 3   /* in: lu holds the factors of another substep of this size, the
                               chord starts with them; out: lu holds this step's factors */

/* The chord pass, and if it fails (a divergent or stalled chord from a poor start: the
   predictor's extrapolation on a hard step) a second pass with J at every iterate from the same
   start; iterations and J evaluations of all passes are counted. HPGEN_SPARSE_CHORD = 0: J
   at every iterate only. *lu_state (in/out, may be NULL): HPGEN_LU_STORE or HPGEN_LU_SHARED
   keep the chord's factors in (lu, piv) for the next substep of the same size (a composed
   step, hpgen_run_cstep_then); a chord that starts with shared factors and fails is repeated
   from the same start with a fresh J. On return HPGEN_LU_SHARED if (lu, piv) hold factors of
   a J evaluated at a converged chord's step (or shared with it), else 0. Mirrored in
   hpgen.runtime.newton_sparse.solve_sparse. */
static int hpgen_newton_sparse(const double* g, const double* p, const double* hv, double* z,
                               const hpgen_options* o, double* lu, int* piv,
                               long long* lu_state, long long* iters, long long* jacs,
                               double* rnorm) {
    double z0[HPGEN_NZ], Jl[HPGEN_LU_SIZE];
    const long long state = lu_state ? *lu_state : 0;
    const int keep = state == HPGEN_LU_STORE || state == HPGEN_LU_SHARED;
    double* J = keep ? lu : Jl;
    long long first = 0;
    int code, pl[HPGEN_NZ], *pv = keep ? piv : pl;
    if (lu_state) *lu_state = 0;
    if (!HPGEN_SPARSE_CHORD)
        return hpgen_newton_sparse_pass(g, p, hv, z, o, 0, Jl, pl, 0, iters, jacs, rnorm);
    memcpy(z0, z, sizeof z0);
    if (state == HPGEN_LU_SHARED) {
        code = hpgen_newton_sparse_pass(g, p, hv, z, o, 1, J, pv, 1, iters, jacs, rnorm);
        if (code == HPGEN_OK) { *lu_state = HPGEN_LU_SHARED; return code; }
        first = *iters;
        memcpy(z, z0, sizeof z0);
    }
    code = hpgen_newton_sparse_pass(g, p, hv, z, o, 1, J, pv, 0, iters, jacs, rnorm);
    *iters += first;
    if (code == HPGEN_OK) {
        if (keep) *lu_state = HPGEN_LU_SHARED;
        return code;
    }
    if (*iters - first <= 1) return code;   /* a first iterate is the same in both */
    first = *iters;
    memcpy(z, z0, sizeof z0);
    code = hpgen_newton_sparse_pass(g, p, hv, z, o, 0, Jl, pl, 0, iters, jacs, rnorm);
    *iters += first;
    return code;
}
#else
#define hpgen_newton_sparse(g, p, hv, z, o, lu, piv, lu_state, iters, jacs, rnorm) \
    (*(lu_state) = 0, hpgen_newton_full(g, p, hv, z, o, iters, jacs, rnorm))
#endif
