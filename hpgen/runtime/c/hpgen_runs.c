/* hpgen's C runtime, part 3: a run in progress (hpgen_run) and its step: the predictor, one
   run step (hpgen_run_step) and the composed step (hpgen_run_cstep). The runs over it are in
   hpgen_advance.c. Mirrored in Python by hpgen.runtime.loop (the same order of operations).
   Included by hpgen_runtime.c after hpgen_newton.c. */

/* the step vector the kernels of a run's last step took: the run's own (open), else {h} */
#if HPGEN_OPEN
#define HPGEN_RUN_HV(run, closed_hv) run->hv
#else
#define HPGEN_RUN_HV(run, closed_hv) closed_hv
#endif

/* sizeof(hpgen_run), for callers that allocate runs as byte buffers */
HPGEN_EXPORT long long hpgen_run_size(void) { return (long long)sizeof(hpgen_run); }

/* Start a run at (g0, p0) with Newton start z0 for the first step (a family module's g0
   taken on g's block pattern: its steps never touch the structural zeros, HPGEN_G_PACKED). */
HPGEN_EXPORT void hpgen_run_init(hpgen_run* r, const double* g0, const double* p0,
                                 const double* z0) {
    memset(r, 0, sizeof *r);
#if HPGEN_G_PACKED
    {
        int i;
        for (i = 0; i < HPGEN_GNZ; ++i)
            r->g[hpgen_update_out0_pos[i]] = g0[hpgen_update_out0_pos[i]];
    }
#else
    memcpy(r->g, g0, sizeof r->g);
#endif
    memcpy(r->p, p0, sizeof r->p);
    memcpy(r->z, z0, sizeof r->z);
}

#if HPGEN_OPEN
/* An open run's inputs: start time t0, input rows U (u_rows of M doubles: 1 = the same row
   for every step, else row k for step k; the caller keeps U alive while the run steps) and
   the P runtime parameters. A run must have them before its first step. */
HPGEN_EXPORT void hpgen_run_set_inputs(hpgen_run* r, double t0, const double* U,
                                       long long u_rows, const double* params) {
    int i;
    r->t0 = t0;
    r->U = U;
    r->u_rows = u_rows;
    for (i = 0; i < HPGEN_P; ++i) r->hv[2 + HPGEN_M + i] = params[i];
}
#endif

/* The run's state (g_k, p_k), last solution z and steps done k. */
HPGEN_EXPORT long long hpgen_run_get(const hpgen_run* r, double* g, double* p, double* z) {
    memcpy(g, r->g, sizeof r->g);
    memcpy(p, r->p, sizeof r->p);
    memcpy(z, r->z, sizeof r->z);
    return r->k;
}

/* G(g, p) = guess(velocity_step(g, p, 0), g, p, h): the guess kernel at one Newton step of
   the Legendre transform from xi = 0 (the velocity itself when l is quadratic in xi), a smooth
   function of the state that carries the leading order of the solution. */
static void hpgen_predictor_base(const double* g, const double* p, const double* hv, double* G) {
    double x0[HPGEN_D], xi[HPGEN_D];
    memset(x0, 0, sizeof x0);
    hpgen_k_velocity_step(g, p, x0, HPGEN_OPEN_HV(hv) xi);
    hpgen_k_guess(xi, g, p, hv, G);
}

/* The predictor's start zs = G + sum_j hpgen_pc[m - 1][j] d_j over the m newest offsets d_0,
   d_1, ... (1 <= m <= HPGEN_PH), for the HPGEN_NZ entries at stride es (entry i of offset j
   at d[j os + i es], of G and zs at [i es]): per entry t = c_0 d_0, t += c_j d_j in the order
   of j, then G + t (hpgen.runtime.loop.predict: the same operations). */
static inline void hpgen_predict(const double* G, const double* d, int es, int os, long long m,
                                 double* zs) {
    const double* c = hpgen_pc[m - 1];
    long long j;
    int i;
    for (i = 0; i < HPGEN_NZ; ++i) {
        double t = c[0] * d[i * es];
        for (j = 1; j < m; ++j) t += c[j] * d[j * os + i * es];
        zs[i * es] = G[i * es] + t;
    }
}

/* The guard's test on a converged step (docs/numerics.md sec. 8): the jump of its offset
   z - G from the newest one d_0, |(z - G) - d_0|, over the offsets' own variation, the larger
   of their last change |d_0 - d_1| and its change |d_0 - 2 d_1 + d_2| (which carries the scale
   where an offset turns), plus HPGEN_GUARD_FLOOR (1 + |z|) (inf-norms; entry i of offset j
   at d[j os + i es], of z and G at [i es], as in hpgen_predict; three offsets). Along a
   trajectory the offsets change smoothly and the ratio stays O(1); a root of the step
   equations other than the trajectory's jumps by O(|z|). */
static double hpgen_guard_ratio(const double* z, const double* G, const double* d, int es,
                                int os) {
    double jump = 0.0, change = 0.0, zn = 0.0;
    int i;
    for (i = 0; i < HPGEN_NZ; ++i) {
        const double d0 = d[i * es], d1 = d[os + i * es], d2 = d[2 * os + i * es];
        const double a = fabs((z[i * es] - G[i * es]) - d0);
        const double b = fabs(d0 - d1), c = fabs((d0 - d1) - (d1 - d2)), x = fabs(z[i * es]);
        if (a > jump) jump = a;
        if (b > change) change = b;
        if (c > change) change = c;
        if (x > zn) zn = x;
    }
    return jump / (change + HPGEN_GUARD_FLOOR * (1.0 + zn));
}

#if HPGEN_GUARD_LOG
/* a measurement build (-DHPGEN_GUARD_LOG=1; benchmarks/guard_ratio.py): the largest guard
   ratio of the runs' steps in this process since the last call, and the steps the guard
   solved again; both start again at 0 */
static double hpgen_guard_log_max;
static long long hpgen_guard_log_n;
HPGEN_EXPORT double hpgen_guard_log(long long* n) {
    const double q = hpgen_guard_log_max;
    *n = hpgen_guard_log_n;
    hpgen_guard_log_max = 0.0;
    hpgen_guard_log_n = 0;
    return q;
}
#endif

/* |(z - G) - d_0|, inf-norm (hpgen_guard_ratio's jump) */
static double hpgen_guard_jump(const double* z, const double* G, const double* d0) {
    double jump = 0.0;
    int i;
    for (i = 0; i < HPGEN_NZ; ++i) {
        const double a = fabs((z[i] - G[i]) - d0[i]);
        if (a > jump) jump = a;
    }
    return jump;
}

/* A step of run r whose root zs (with g1, p1, *it iterations, residual *res) failed the guard
   (hpgen_guard_ratio > HPGEN_GUARD_RATIO): solved again from G, the start a run without
   history takes, by full Newton with its own J (the run's kept J^{-1} untouched). The
   second root replaces the first when its jump from the offsets is less than half the
   first's (two solutions of one root never swap); then the run's kept J^{-1}, evaluated
   near the first root, is dropped. Both solves count in st (and st->guarded). */
static void hpgen_guard_resolve(hpgen_run* r, const double* hv, const hpgen_options* full,
                                const double* G, double* zs, double* g1, double* p1,
                                long long* it, double* res, hpgen_status* st, int with_g) {
    double zb[HPGEN_NZ], gb[HPGEN_GNZ], pb[HPGEN_D], lu[1], rb;
    long long itb = 0, valid = 0;
    int piv[1], code;
    memcpy(zb, G, sizeof zb);
    code = hpgen_step_core_packed(r->g, r->p, hv, zb, full, lu, piv, &valid, gb, pb, &itb,
                                  &st->jacobians, &rb, 1, with_g);
    st->total_iterations += itb;
    st->guarded += 1;
    *it += itb;
    if (code != HPGEN_OK
        || !(2.0 * hpgen_guard_jump(zb, G, r->dz[0]) < hpgen_guard_jump(zs, G, r->dz[0])))
        return;
    memcpy(zs, zb, sizeof zb);
    if (with_g) memcpy(g1, gb, sizeof gb);
    memcpy(p1, pb, sizeof pb);
    *res = rb;
    r->lu_valid = 0;
}

#if HPGEN_EXPLICIT
/* One explicit step of run r (hv the step's vector): z = p_k (the step's unknown, which the
   sections' chart curve reads), (g_{k+1}, p_{k+1}) = update(z, g_k, p_k, hv) (with_g = 0:
   update_p) once; no Newton: iterations and Jacobians 0, residual 0 (F = z - p_k = 0); the
   predictor's offsets stay unused. Returns the status code (HPGEN_NONFINITE: the update is
   not finite; the run keeps (g_k, p_k)). */
static int hpgen_explicit_step(hpgen_run* r, const double* hv, hpgen_status* st, int with_g) {
    double g1[HPGEN_NN], p1[HPGEN_D];
    int bad;
    memcpy(r->z, r->p, sizeof r->p);
    if (with_g)
        bad = hpgen_k_update(r->z, r->g, r->p, hv, g1, p1) || !hpgen_all_finite(g1, HPGEN_NN)
              || !hpgen_all_finite(p1, HPGEN_D);
    else
        bad = hpgen_k_update_p(r->z, r->g, r->p, hv, p1) || !hpgen_all_finite(p1, HPGEN_D);
    st->iterations = 0;
    st->residual = 0.0;
    if (bad) { st->code = HPGEN_NONFINITE; st->step = r->k; return HPGEN_NONFINITE; }
    if (with_g) memcpy(r->g, g1, sizeof g1);
    memcpy(r->p, p1, sizeof p1);
    r->k += 1;
    return HPGEN_OK;
}
#endif

/* One step of run r with hv = {h}: the Newton start from the predictor, the step, and on
   success the run moved to (g_{k+1}, p_{k+1}) (with_g = 0: p_{k+1} only); o for every
   step (a sparse J's first step: full); full (o with full Newton) for the first step's
   second try where simplified Newton failed there. Updates the counters of st; returns the status code.
   Predictor: z_k = G_k + dz_k with G_k = hpgen_predictor_base(g_k, p_k) (exact in p, O(1))
   and dz_k = z_k - G_k small (O(h)) and smooth in k; the start is G_k plus the polynomial
   through the last m = min(have_prev, HPGEN_PH) offsets extrapolated one step
   (hpgen_predict: quintic once six exist). The offsets from G_k, not z itself, are
   extrapolated: they are small and smooth where z is not (docs/performance.md, "Newton's
   start and stop"). Guard: a step predicted from three or more offsets whose root jumps away
   from them (hpgen_guard_ratio > HPGEN_GUARD_RATIO) is solved again from G
   (hpgen_guard_resolve). */
static int hpgen_run_step(hpgen_run* r, const double* hv, const hpgen_options* o,
                          const hpgen_options* full, hpgen_status* st, int with_g) {
    double g1[HPGEN_GNZ], p1[HPGEN_D], zs[HPGEN_NZ], z0[HPGEN_NZ], G[HPGEN_NZ], res;
    long long it;
    const hpgen_options* o1 = o;
    int i, code, predicted = o->predictor && r->have_prev >= 1;
#if HPGEN_OPEN
    /* the step vector of step k: [h, t0 + k h, u_k, params] */
    if (r->u_rows < 1 || (r->u_rows > 1 && r->k >= r->u_rows)) {
        st->code = HPGEN_INVALID; st->step = r->k; return HPGEN_INVALID;
    }
    r->hv[0] = hv[0];
    r->hv[1] = r->t0 + (double)r->k * hv[0];
    for (i = 0; i < HPGEN_M; ++i) r->hv[2 + i] = r->U[(r->u_rows == 1 ? 0 : r->k) * HPGEN_M + i];
    hv = r->hv;
#endif
#if HPGEN_EXPLICIT
    (void)o; (void)full; (void)G; (void)zs; (void)z0; (void)res; (void)it; (void)code;
    (void)predicted; (void)o1;
    return hpgen_explicit_step(r, hv, st, with_g);
#endif
    /* (G is kept up to date with or without o->predictor) */
    hpgen_predictor_base(r->g, r->p, hv, G);
    if (predicted && r->have_prev == HPGEN_PH)     /* the steady state: a constant m */
        hpgen_predict(G, r->dz[0], 1, HPGEN_NZ, HPGEN_PH, zs);
    else if (predicted)
        hpgen_predict(G, r->dz[0], 1, HPGEN_NZ, r->have_prev, zs);
    else
        for (i = 0; i < HPGEN_NZ; ++i) zs[i] = r->z[i];
    /* the first step (from the guess kernel: its start is checked) takes o's Newton too,
       except with a sparse J, whose simplified stop is the looser rate-based one
       (hpgen_sparse_converged): full Newton there, as the first step's error is carried
       longest; where simplified Newton fails, full Newton from the same start */
    o1 = r->k == 0 && HPGEN_SPARSE ? full : o;
    if (r->k == 0) memcpy(z0, zs, sizeof z0);
    code = hpgen_step_core_packed(r->g, r->p, hv, zs, o1, r->lu, r->piv, &r->lu_valid, g1, p1,
                                  &it, &st->jacobians, &res, r->k == 0, with_g);
    st->total_iterations += it;
    if (code != HPGEN_OK && r->k == 0 && o1->simplified) {
        memcpy(zs, z0, sizeof zs);
        code = hpgen_step_core_packed(r->g, r->p, hv, zs, full, r->lu, r->piv, &r->lu_valid,
                                      g1, p1, &it, &st->jacobians, &res, 1, with_g);
        st->total_iterations += it;
    }
    if (code != HPGEN_OK && predicted) {
        /* the extrapolated start failed (Newton diverged, or reached a root outside the
           chart): retry from the plain warm start z_k before reporting anything */
        memcpy(zs, r->z, sizeof zs);
        code = hpgen_step_core_packed(r->g, r->p, hv, zs, o, r->lu, r->piv, &r->lu_valid, g1,
                                      p1, &it, &st->jacobians, &res, 0, with_g);
        st->total_iterations += it;
    }
    st->iterations = it;
    st->residual = res;
    if (code != HPGEN_OK) { st->code = code; st->step = r->k; return code; }
    if (predicted && r->have_prev >= 3) {
        const double q = hpgen_guard_ratio(zs, G, r->dz[0], 1, HPGEN_NZ);
#if HPGEN_GUARD_LOG
        if (q > hpgen_guard_log_max) hpgen_guard_log_max = q;
        hpgen_guard_log_n += q > HPGEN_GUARD_RATIO;
#endif
        if (q > HPGEN_GUARD_RATIO) {
            hpgen_guard_resolve(r, hv, full, G, zs, g1, p1, &it, &res, st, with_g);
            st->iterations = it;
            st->residual = res;
        }
    }
    memmove(r->dz[1], r->dz[0], (HPGEN_PH - 1) * sizeof r->dz[0]);
    for (i = 0; i < HPGEN_NZ; ++i) r->dz[0][i] = zs[i] - G[i];
    if (r->have_prev < HPGEN_PH) r->have_prev += 1;
    memcpy(r->z, zs, sizeof r->z);
    if (with_g) hpgen_g_unpack(g1, r->g);
    memcpy(r->p, p1, sizeof p1);
    r->k += 1;
    return HPGEN_OK;
}

/* Make run r's steps composed steps of cs substeps with fractions gammas[0..cs-1]
   (hpgen.tableaus.composition; cs = 0: the plain step). Returns 0, or -1 for cs outside
   0..HPGEN_CS_MAX. */
HPGEN_EXPORT int hpgen_run_set_compose(hpgen_run* r, long long cs, const double* gammas) {
    long long i;
    if (cs < 0 || cs > HPGEN_CS_MAX) return -1;
    r->cs = cs;
    r->c_have = 0;
    for (i = 0; i < cs; ++i) r->cg[i] = gammas[i];
    return 0;
}

/* One step of run r: hpgen_run_step, or for a composed run (r->cs > 0) the composed step
   S(cg[cs-1] h) o ... o S(cg[0] h), substep i being hpgen_run_step with hv[0] = cg[i] h at
   the same k. Substep i's Newton starts from hpgen_run_step's predictor through substep i's
   own offsets z - G at the last min(k, HPGEN_CH) steps (G itself at the first step).
   Simplified Newton keeps J^{-1} across substeps as across steps: its contraction test
   refreshes it when the fraction changed too much (a fresh J at every change of fraction
   would cost more J evaluations than the test asks for). A sparse module's full Newton (the
   chord) built with -DHPGEN_COMPOSE_SHARE_J=1 shares the factors of the first substep's J
   with the later substeps of the same fraction (Suzuki's p, p, 1 - 4p, p, p: one J for four
   substeps), nothing across composed steps; by default a J at every substep. An open model's substep i has time
   t0 + (k + cg[0] + ... + cg[i-1]) h and input row k. st->iterations: summed over the
   substeps. On failure the run is back at its state before the step.
   after (NULL in the runs; hpgen_linearize's per-substep derivative): called after each
   substep i that converged (the plain step: i = 0) with the step vector it took; a code
   other than HPGEN_OK fails the step with that code. */
typedef int (*hpgen_substep_hook)(void* ctx, const hpgen_run* r, long long i,
                                  const double* hv);
static int hpgen_run_cstep_then(hpgen_run* r, const double* hv, const hpgen_options* o,
                                const hpgen_options* full, hpgen_status* st, int with_g,
                                hpgen_substep_hook after, void* ctx) {
    double hs[1], g0[HPGEN_GNZ], p0[HPGEN_D], z0[HPGEN_NZ], c = 0.0;
    const long long k = r->k;
    long long it = 0, i, shared = 0;
    int code;
#if HPGEN_OPEN
    const double t0 = r->t0;
#endif
    (void)shared;
    if (r->cs == 0) {
        code = hpgen_run_step(r, hv, o, full, st, with_g);
        if (code == HPGEN_OK && after && (code = after(ctx, r, 0, HPGEN_RUN_HV(r, hv))) != HPGEN_OK) {
            st->code = code; st->step = k;
        }
        return code;
    }
    hpgen_g_pack(r->g, g0);
    memcpy(p0, r->p, sizeof p0);
    memcpy(z0, r->z, sizeof z0);
    for (i = 0; i < r->cs; ++i) {
        hs[0] = r->cg[i] * hv[0];
        r->k = k;
#if HPGEN_SPARSE
        /* full Newton: the substeps of the first substep's size share its J's factors
           (hpgen_newton_sparse's lu_state); a substep of another size keeps them aside */
        if (!o->simplified && HPGEN_COMPOSE_SHARE_J) {
            if (i == 0) shared = HPGEN_LU_STORE;
            r->lu_valid = r->cg[i] == r->cg[0] ? shared : 0;
        }
#endif
        if (r->c_have > 0) {
            r->have_prev = r->c_have;
            memcpy(r->dz[0], r->cdz[i][0], r->c_have * sizeof r->dz[0]);
        } else {
            r->have_prev = 1;
            memset(r->dz[0], 0, sizeof r->dz[0]);
        }
#if HPGEN_OPEN
        r->t0 = t0 + ((double)k + c) * hv[0] - (double)k * hs[0];
#endif
        code = hpgen_run_step(r, hs, o, full, st, with_g);
#if HPGEN_OPEN
        r->t0 = t0;
#endif
        it += st->iterations;
        if (code == HPGEN_OK && after && (code = after(ctx, r, i, HPGEN_RUN_HV(r, hs))) != HPGEN_OK) {
            st->code = code; st->step = k;
        }
        if (code != HPGEN_OK) {
            hpgen_g_unpack(g0, r->g);
            memcpy(r->p, p0, sizeof p0);
            memcpy(r->z, z0, sizeof z0);
            r->k = k;
#if HPGEN_SPARSE
            if (!o->simplified) r->lu_valid = 0;
#endif
            return code;
        }
        memcpy(r->cdz[i][0], r->dz[0], HPGEN_CH * sizeof r->dz[0]);
        c += r->cg[i];
#if HPGEN_SPARSE
        if (!o->simplified && HPGEN_COMPOSE_SHARE_J && r->cg[i] == r->cg[0])
            shared = r->lu_valid;
#endif
    }
#if HPGEN_SPARSE
    if (!o->simplified) r->lu_valid = 0;
#endif
    if (r->c_have < HPGEN_CH) r->c_have += 1;
    st->iterations = it;
    return HPGEN_OK;
}

static int hpgen_run_cstep(hpgen_run* r, const double* hv, const hpgen_options* o,
                           const hpgen_options* full, hpgen_status* st, int with_g) {
    return hpgen_run_cstep_then(r, hv, o, full, st, with_g, NULL, NULL);
}
