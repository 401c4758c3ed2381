/* hpgen's C runtime, part 4: the runs over a run's steps (hpgen_runs.c): hpgen_advance
   (states), hpgen_advance_sections (Poincare sections), hpgen_advance_record (record rows,
   with the record's velocity hpgen_velocity) and hpgen_observe. Mirrored in Python by
   hpgen.runtime.loop and hpgen.runtime.record_row (the same order of operations). Included
   by hpgen_runtime.c after hpgen_runs.c. */

/* The start of a run loop (hpgen.runtime.loop._loop_start): st initialised; 0 with
   HPGEN_INVALID unless steps >= 0, every >= 1 (a sections run: its cap), the options are
   valid and, for a loop that needs g (with_g), the run is not g_stale; else 1 with the
   loop's step vector hv = [h] and the full-Newton options of its first step. */
static int hpgen_loop_start(const hpgen_run* r, double h, long long steps, long long every,
                            const hpgen_options* o, int with_g, double* hv,
                            hpgen_options* full, hpgen_status* st) {
    hpgen_status_init(st);
    if (steps < 0 || every < 1 || !hpgen_options_ok(o) || (with_g && r->g_stale)) {
        st->code = HPGEN_INVALID; return 0;
    }
    hv[0] = h;
    *full = *o;
    full->simplified = 0;
    return 1;
}

/* Advance a run by `steps` steps of size h (warm-started: each Newton starts from the previous
   solution, or from the predictor of hpgen_run_step). The state after global step k is
   recorded when k % every == 0 into g_rec[j * NN], p_rec[j * D], j = 0, 1, ... (the caller
   sizes them for the records falling in this call). Stops at the first failed step (the run
   keeps the last good state). Returns the steps done in this call. */
HPGEN_EXPORT long long hpgen_advance(hpgen_run* r, double h, long long steps, long long every,
                                     const hpgen_options* o, double* g_rec, double* p_rec,
                                     hpgen_status* st) {
    double hv[1];
    long long n, rec = 0;
    hpgen_options full;
    if (!hpgen_loop_start(r, h, steps, every, o, 1, hv, &full, st)) return 0;
    for (n = 0; n < steps; ++n) {
        if (hpgen_run_cstep(r, hv, o, &full, st, 1) != HPGEN_OK) return n;
        if (r->k % every == 0) {
            memcpy(g_rec + rec * HPGEN_NN, r->g, sizeof r->g);
            memcpy(p_rec + rec * HPGEN_D, r->p, sizeof r->p);
            ++rec;
        }
    }
    st->step = r->k;
    return steps;
}

/* A composed run's group element at a section crossing theta h into step k from
   (g0, p0): one plain step S(theta h) (full Newton from the predictor base G), whose g
   carries the same O(h^2) accuracy as the crossing's linear p; the run is untouched.
   Returns the status code. */
static int hpgen_composed_section_point(const hpgen_run* r, const double* g0, const double* p0,
                                        double th, long long k, double h,
                                        const hpgen_options* full, double* g_out) {
    double z[HPGEN_NZ], p1[HPGEN_D], lu[1], res;
    long long it, jacs = 0, valid = 0;
    int piv[1];
#if HPGEN_OPEN
    double hv[HPGEN_H];
    memcpy(hv, r->hv, sizeof hv);
    hv[1] = r->t0 + (double)k * h;
#else
    double hv[1];
    (void)r; (void)k; (void)h;
#endif
    hv[0] = th;
    hpgen_predictor_base(g0, p0, hv, z);
    return hpgen_step_core(g0, p0, hv, z, full, lu, piv, &valid, g_out, p1, &it, &jacs, &res,
                           1, 1);
}

/* Advance a run by up to `steps` steps of size h, recording the upward crossings of the
   scene's Poincare section s(g, p) = 0 (kernel section): when s_k < 0 <= s_{k+1}, with
   theta = s_k / (s_k - s_{k+1}) in (0, 1], record j holds
     k_rec[j] = k,  t_rec[j] = (k + theta) h,
     p_rec[j * D] = (1 - theta) p_k + theta p_{k+1}      (linear in the step: O(h^2)),
     g_rec[j * NN] = g_k tau(theta h xi_{k+1})            (kernel chart_point: on the group;
                                                           a composed run: S(theta h) of g_k).
   s of the run's current state is kept in the run, so calls chain (a crossing between two
   calls is found). Stops after `cap` records (the crossing step included), at a failed step,
   or after `steps` steps; *n_rec: the records written. Returns the steps done in this call. */
HPGEN_EXPORT long long hpgen_advance_sections(hpgen_run* r, double h, long long steps,
                                              const hpgen_options* o, long long cap,
                                              double* t_rec, double* g_rec, double* p_rec,
                                              long long* k_rec, long long* n_rec,
                                              hpgen_status* st) {
    double hv[1], g0[HPGEN_NN], p0[HPGEN_D], s1[1], th[1];
    long long n;
    int i, code;
    hpgen_options full;
    *n_rec = 0;
    if (!hpgen_loop_start(r, h, steps, cap, o, 1, hv, &full, st)) return 0;
    if (!r->s_valid) {
        if (hpgen_k_section(r->g, r->p, s1)) { st->code = HPGEN_NONFINITE; return 0; }
        r->s = s1[0];
        r->s_valid = 1;
    }
    memcpy(g0, r->g, sizeof g0);
    for (n = 0; n < steps && *n_rec < cap; ++n) {
        const double s0 = r->s;
        const long long k = r->k;
        hpgen_g_copy(r->g, g0);
        memcpy(p0, r->p, sizeof p0);
        if (hpgen_run_cstep(r, hv, o, &full, st, 1) != HPGEN_OK) return n;
        if (hpgen_k_section(r->g, r->p, s1) || !isfinite(s1[0])) {
            st->code = HPGEN_NONFINITE; st->step = r->k; return n + 1;
        }
        r->s = s1[0];
        if (s0 < 0.0 && s1[0] >= 0.0) {
            const long long j = *n_rec;
            const double theta = s0 / (s0 - s1[0]);
            th[0] = theta;
            k_rec[j] = k;
            t_rec[j] = ((double)k + theta) * h;
            for (i = 0; i < HPGEN_D; ++i)
                p_rec[j * HPGEN_D + i] = (1.0 - theta) * p0[i] + theta * r->p[i];
            if (r->cs > 0) {
                code = hpgen_composed_section_point(r, g0, p0, theta * h, k, h, &full,
                                                    g_rec + j * HPGEN_NN);
                if (code != HPGEN_OK) { st->code = code; st->step = r->k; return n + 1; }
            } else if (hpgen_k_chart_point(r->z, g0, HPGEN_RUN_HV(r, hv), th,
                                           g_rec + j * HPGEN_NN)) {
                st->code = HPGEN_NONFINITE; st->step = r->k; return n + 1;
            }
            *n_rec = j + 1;
        }
    }
    st->step = r->k;
    return n;
}

/* xi with legendre(g, xi) = p: Newton (kernel velocity_step) from xi = 0; one step when l is
   quadratic in xi (then exact), else until |dxi| <= HPGEN_VELOCITY_TOL (1 + |xi|) or the
   round-off floor (a sparse module: or the round-off stall), at most HPGEN_VELOCITY_MAXIT
   iterations (the runtime's Integrator.velocity uses the same test). */
#if HPGEN_RECORD_USES_XI
static int hpgen_velocity(const double* g, const double* p, double* xi HPGEN_OPEN_HV_PARAM) {
    double x1[HPGEN_D], dprev = HUGE_VAL;
    int i, it;
    for (i = 0; i < HPGEN_D; ++i) xi[i] = 0.0;
    for (it = 1; it <= HPGEN_VELOCITY_MAXIT; ++it) {
        double dn = 0.0, xn;
        if (hpgen_k_velocity_step(g, p, xi, HPGEN_OPEN_HV(hv) x1)
            || !hpgen_all_finite(x1, HPGEN_D))
            return HPGEN_RECORD;
        for (i = 0; i < HPGEN_D; ++i) {
            const double dx = fabs(x1[i] - xi[i]);
            if (dx > dn) dn = dx;
            xi[i] = x1[i];
        }
        if (HPGEN_LEGENDRE_QUADRATIC) return HPGEN_OK;
        xn = hpgen_norm_inf(xi, HPGEN_D);
        if (dn <= HPGEN_VELOCITY_TOL * (1.0 + xn)) return HPGEN_OK;
        if (it > 1 && dn >= dprev && dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + xn)) return HPGEN_OK;
#if HPGEN_SPARSE
        /* a family's Legendre map can be ill-conditioned (frames far from their bodies): the
           refinement stops at its round-off noise (hpgen_stalled, each step's J fresh) */
        if (hpgen_stalled(it, dn, dprev, xn, 1, 0)) return HPGEN_OK;
#endif
        dprev = dn;
    }
    return HPGEN_RECORD;
}
#endif

/* The scene's record row at (g, p) (kernel record; xi by hpgen_velocity when the row uses
   it): HPGEN_OK, or HPGEN_RECORD when the row is not finite or xi did not converge (then the
   row is all NaN). */
static int hpgen_record_row(const double* g, const double* p, double* row HPGEN_OPEN_HV_PARAM) {
    double xi[HPGEN_D];
#if HPGEN_RECORD_USES_XI
    if (hpgen_velocity(g, p, xi HPGEN_OPEN_HV_LAST(hv)) != HPGEN_OK) {
        int i;
        for (i = 0; i < HPGEN_W; ++i) row[i] = NAN;
        return HPGEN_RECORD;
    }
#else
    memset(xi, 0, sizeof xi);
#endif
    if (hpgen_k_record(g, p, xi, HPGEN_OPEN_HV(hv) row) || !hpgen_all_finite(row, HPGEN_W))
        return HPGEN_RECORD;
    return HPGEN_OK;
}

/* The record row at (g, p) (the start of a run: record 0). Returns the status code. */
/* (an open model's takes hv, the step vector at the record's time, [h, t, u, params]) */
HPGEN_EXPORT int hpgen_record(const double* g, const double* p, double* row HPGEN_OPEN_HV_PARAM) {
    return hpgen_record_row(g, p, row HPGEN_OPEN_HV_LAST(hv));
}

/* Advance a run like hpgen_advance, keeping only the scene's record row (W doubles) of the
   state after global step k when k % every == 0, in rows[j * W], j = 0, 1, ... With
   HPGEN_SKIP_G (neither the step nor the row use g) g_{k+1} is never formed: the run's g
   stays g_0 and the run is marked g_stale (hpgen_advance and hpgen_advance_sections then
   refuse it). The states (p_k, z) are bitwise those of hpgen_advance. A row that is not
   finite stops the run after its step with code HPGEN_RECORD (the row is written, *n_rec
   counts it). *n_rec: rows written. Returns the steps done in this call. */
HPGEN_EXPORT long long hpgen_advance_record(hpgen_run* r, double h, long long steps,
                                            long long every, const hpgen_options* o,
                                            double* rows, long long* n_rec, hpgen_status* st) {
    double hv[1];
    long long n;
    hpgen_options full;
    *n_rec = 0;
    if (!hpgen_loop_start(r, h, steps, every, o, 0, hv, &full, st)) return 0;
    if (HPGEN_SKIP_G) r->g_stale = 1;
    for (n = 0; n < steps; ++n) {
        if (hpgen_run_cstep(r, hv, o, &full, st, !HPGEN_SKIP_G) != HPGEN_OK) return n;
        if (r->k % every == 0) {
            double* row = rows + *n_rec * HPGEN_W;
            *n_rec += 1;
#if HPGEN_OPEN
            r->hv[1] = r->t0 + (double)r->k * h;      /* the record's time */
#endif
            if (hpgen_record_row(r->g, r->p, row HPGEN_OPEN_HV_LAST(r->hv)) != HPGEN_OK) {
                st->code = HPGEN_RECORD; st->step = r->k; return n + 1;
            }
        }
    }
    st->step = r->k;
    return steps;
}

#if !HPGEN_OPEN
/* Observables of K records (g_rec[k * NN], p_rec[k * D], as hpgen_advance writes them):
   kernel observe per record -> xi_out[k * D], E_out[k], m_out[k * D], e_out[k]. Returns the
   first record whose outputs are not finite, or K. */
HPGEN_EXPORT long long hpgen_observe(long long K, const double* g_rec, const double* p_rec,
                                     double* xi_out, double* E_out, double* m_out,
                                     double* e_out) {
    long long k;
    for (k = 0; k < K; ++k) {
        double* xi = xi_out + k * HPGEN_D;
        double* m = m_out + k * HPGEN_D;
        if (hpgen_k_observe(g_rec + k * HPGEN_NN, p_rec + k * HPGEN_D, xi, E_out + k, m,
                            e_out + k)
            || !hpgen_all_finite(xi, HPGEN_D) || !isfinite(E_out[k])) return k;
    }
    return K;
}
#endif

