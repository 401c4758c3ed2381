/* hpgen's C runtime, part 6: lane-wise ensembles, when the model has lane kernels (HPGEN_L,
   hpgen.codegen.lanes). Included by hpgen_runtime.c last. */

/* ---- lane-wise ensembles (hpgen.codegen.lanes) ----
   HPGEN_L bodies per call in structure-of-arrays form (entry i of lane l at x[i * L + l]):
   the step's kernels printed lane-wise, full Newton with per-lane convergence masks (a lane
   that converged stops updating; the loop runs while a lane is active), the adjugate solve,
   the norms and the tests as fixed-count lane loops. Every lane performs the operations of
   hpgen_run_step in the same order: its states are bitwise those of hpgen_advance. A lane
   whose step does not converge cleanly (Newton failure, singular J, margin <= 0, a
   non-finite update: any case where hpgen_run_step would retry or report) redoes that step
   with the scalar hpgen_run_step from its state before the step, which then retries or
   reports exactly as a scalar run; a lane that fails there stops (its status set) and the
   other lanes continue. The model's lane kernels (hpgen_lane_residual_jacobian,
   hpgen_lane_margin, hpgen_lane_update) come from kernels.c, as its HPGEN_L. An explicit
   step (HPGEN_EXPLICIT) has no Newton: one lane-wise update a step (hpgen_lane_update
   alone), any number of unknowns. */
#if defined(HPGEN_L)
#if HPGEN_NZ > 3 && !HPGEN_EXPLICIT
#error "lane code is written for at most 3 unknowns (the adjugate solve)"
#endif

/* the entries of a vector of HPGEN_NZ <= 3 unknowns, unrolled: X(0) X(1) ... */
#if HPGEN_NZ == 1
#define HPGEN_EACH_Z(X) X(0)
#elif HPGEN_NZ == 2
#define HPGEN_EACH_Z(X) X(0) X(1)
#else
#define HPGEN_EACH_Z(X) X(0) X(1) X(2)
#endif
/* hpgen_lane_newton's per-entry statements of one lane l (entry i) */
#define HPGEN_LANE_LOAD(i) \
            const double f##i = F[i * HPGEN_L + l], zo##i = z[i * HPGEN_L + l]; \
            double x##i, d##i, zt##i;
#define HPGEN_LANE_RNORM(i) \
            rn = fabs(f##i) > rn ? fabs(f##i) : rn; \
            fin += f##i - f##i;
#define HPGEN_LANE_STEP(i) \
            d##i = x##i * r; \
            zt##i = zo##i - d##i; \
            dn = fabs(d##i) > dn ? fabs(d##i) : dn; \
            fin += (d##i - d##i) + (zt##i - zt##i);
#define HPGEN_LANE_ZNORM(i) \
            zn = fabs(zt##i) > zn ? fabs(zt##i) : zn;
#define HPGEN_LANE_BLEND(i) \
            zw[i * HPGEN_L + l] = a != 0.0 ? zt##i : zo##i;

HPGEN_LANES_BEGIN
#if !HPGEN_EXPLICIT
/* Full Newton (hpgen_newton with o->simplified = 0) on L lanes from z (in/out): ok[l] = 1
   where lane l converged (z its solution, iters[l] its iterations, rnorm[l] its last
   residual norm), 0 where hpgen_newton would return a failure (z then undefined). One lane
   loop per iteration after the kernel: the solve by the cofactors of hpgen_lu_factor_solve
   (the same operations), z - dz, the inf-norms and the tests, the entries unrolled at
   compile time (HPGEN_EACH_Z), flags as doubles 0/1 and blends for the masks (no branch on
   a lane), so that gcc vectorises it. Finiteness: the sum of x - x over the entries is 0 iff
   every entry is finite (x - x is NaN for inf and NaN). A lane stays inactive once stopped:
   its iterations are the sum of its active flags. */
static void hpgen_lane_newton(const double* g, const double* p, const double* hv, double* zio,
                              const hpgen_options* o, long long* okio, long long* itio,
                              double* rnio) {
    /* z, rnorm: blended from one buffer into the other, swapped at every iteration (a
       blend into the value's own place, x = c ? y : x, would become a conditional store) */
    double F[HPGEN_NZ * HPGEN_L], J[HPGEN_NZ * HPGEN_NZ * HPGEN_L], dprev[HPGEN_L],
        zbuf[2][HPGEN_NZ * HPGEN_L], rbuf[2][HPGEN_L], active[HPGEN_L], ok[HPGEN_L],
        iters[HPGEN_L];
    const double tol = o->tol;
    double *z = zbuf[0], *zw = zbuf[1], *rnorm = rbuf[0], *rw = rbuf[1], *t;
    long long it;
    int l;
    memcpy(z, zio, sizeof zbuf[0]);
    for (l = 0; l < HPGEN_L; ++l) {
        active[l] = 1.0; ok[l] = 0.0; iters[l] = 0.0; rnorm[l] = 0.0; dprev[l] = HUGE_VAL;
    }
    for (it = 1; it <= o->maxit; ++it) {
        const double later = it > 1 ? 1.0 : 0.0;
        double any = 0.0;
        hpgen_lane_residual_jacobian(z, g, p, hv, F, J);
        for (l = 0; l < HPGEN_L; ++l) {
            const double a = active[l];
            double rn = 0.0, dn = 0.0, zn = 0.0, fin = 0.0, det, r, good, conv, rs;
            HPGEN_EACH_Z(HPGEN_LANE_LOAD)
            HPGEN_EACH_Z(HPGEN_LANE_RNORM)
#if HPGEN_NZ == 1
            det = J[l];
            x0 = f0;
#elif HPGEN_NZ == 2
            {
                const double ja = J[l], jc = J[HPGEN_L + l], jb = J[2 * HPGEN_L + l],
                             jd = J[3 * HPGEN_L + l];
                det = ja * jd - jb * jc;
                x0 = jd * f0 - jb * f1;
                x1 = ja * f1 - jc * f0;
            }
#else
            {
                const double j00 = J[l], j10 = J[HPGEN_L + l], j20 = J[2 * HPGEN_L + l],
                             j01 = J[3 * HPGEN_L + l], j11 = J[4 * HPGEN_L + l],
                             j21 = J[5 * HPGEN_L + l], j02 = J[6 * HPGEN_L + l],
                             j12 = J[7 * HPGEN_L + l], j22 = J[8 * HPGEN_L + l];
                const double c00 = j11 * j22 - j12 * j21, c01 = j12 * j20 - j10 * j22,
                             c02 = j10 * j21 - j11 * j20, c10 = j02 * j21 - j01 * j22,
                             c11 = j00 * j22 - j02 * j20, c12 = j01 * j20 - j00 * j21,
                             c20 = j01 * j12 - j02 * j11, c21 = j02 * j10 - j00 * j12,
                             c22 = j00 * j11 - j01 * j10;
                det = j00 * c00 + j01 * c01 + j02 * c02;
                x0 = c00 * f0 + c10 * f1 + c20 * f2;
                x1 = c01 * f0 + c11 * f1 + c21 * f2;
                x2 = c02 * f0 + c12 * f1 + c22 * f2;
            }
#endif
            r = 1.0 / det;
            fin += det - det;
            HPGEN_EACH_Z(HPGEN_LANE_STEP)
            HPGEN_EACH_Z(HPGEN_LANE_ZNORM)
            good = (fin == 0.0 && det != 0.0) ? a : 0.0;
            conv = ((dn <= tol * (1.0 + zn))
                    | ((later * dn >= dprev[l]) & (dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + zn))))
                   ? good : 0.0;
            HPGEN_EACH_Z(HPGEN_LANE_BLEND)
            /* rnorm of the lane's last active iteration (rn finite there), by arithmetic: a
               blend with a load as one arm would make the load conditional */
            rs = rn <= DBL_MAX ? rn : 0.0;
            rw[l] = rs * a + rnorm[l] * (1.0 - a);
            iters[l] += a;
            ok[l] += conv;
            active[l] = good - conv;
            dprev[l] = dn;
            any += active[l];
        }
        t = z; z = zw; zw = t;
        t = rnorm; rnorm = rw; rw = t;
        if (any == 0.0) break;
    }
    memcpy(zio, z, sizeof zbuf[0]);
    for (l = 0; l < HPGEN_L; ++l) {
        okio[l] = ok[l] != 0.0;
        itio[l] = (long long)iters[l];
        rnio[l] = rnorm[l];
    }
}

#endif /* !HPGEN_EXPLICIT */

/* lane l <-> run r: the state hpgen_run_step reads and writes */
static void hpgen_lane_gather(const hpgen_run* r, int l, double* g, double* p, double* z,
                              double (*dz)[HPGEN_NZ * HPGEN_L], long long* hp,
                              long long* k) {
    int i, j;
    for (i = 0; i < HPGEN_NN; ++i) g[i * HPGEN_L + l] = r->g[i];
    for (i = 0; i < HPGEN_D; ++i) p[i * HPGEN_L + l] = r->p[i];
    for (i = 0; i < HPGEN_NZ; ++i) {
        z[i * HPGEN_L + l] = r->z[i];
        for (j = 0; j < HPGEN_PH; ++j) dz[j][i * HPGEN_L + l] = r->dz[j][i];
    }
    hp[l] = r->have_prev;
    k[l] = r->k;
}

static void hpgen_lane_scatter(hpgen_run* r, int l, const double* g, const double* p,
                               const double* z, double (*dz)[HPGEN_NZ * HPGEN_L],
                               const long long* hp, const long long* k) {
    int i, j;
    for (i = 0; i < HPGEN_NN; ++i) r->g[i] = g[i * HPGEN_L + l];
    for (i = 0; i < HPGEN_D; ++i) r->p[i] = p[i * HPGEN_L + l];
    for (i = 0; i < HPGEN_NZ; ++i) {
        r->z[i] = z[i * HPGEN_L + l];
        for (j = 0; j < HPGEN_PH; ++j) r->dz[j][i] = dz[j][i * HPGEN_L + l];
    }
    r->have_prev = hp[l];
    r->k = k[l];
}

#if HPGEN_EXPLICIT
/* L runs (runs[0..L-1], the same k, g not stale) of an explicit step advanced like L calls
   of hpgen_advance (records of lane l at g_rec + l per_run NN, p_rec + l per_run D): per step
   z = p_k and one lane-wise update (hpgen_explicit_step's operations on every lane); a lane
   whose g1 or p1 sum is not finite redoes the step by hpgen_run_step, which reports it (or
   steps, when only the sum overflowed). */
static void hpgen_advance_lanes(hpgen_run* runs, double h, long long steps, long long every,
                                const hpgen_options* o, long long per_run, double* g_rec,
                                double* p_rec, hpgen_status* st) {
    double g[HPGEN_NN * HPGEN_L], p[HPGEN_D * HPGEN_L], z[HPGEN_NZ * HPGEN_L],
        dz[HPGEN_PH][HPGEN_NZ * HPGEN_L], g1[HPGEN_NN * HPGEN_L], p1[HPGEN_D * HPGEN_L],
        hv[HPGEN_L], hv1[1];
    long long hp[HPGEN_L], k[HPGEN_L], rec[HPGEN_L], ok[HPGEN_L], alive[HPGEN_L], n,
        nalive = HPGEN_L;
    int i, l;
    hpgen_options full = *o;
    full.simplified = 0;
    hv1[0] = h;
    for (l = 0; l < HPGEN_L; ++l) {
        hpgen_status_init(st + l);
        hpgen_lane_gather(runs + l, l, g, p, z, dz, hp, k);
        hv[l] = h;
        alive[l] = 1;
        rec[l] = 0;
    }
    for (n = 0; n < steps && nalive > 0; ++n) {
        long long all = 1;
        memcpy(z, p, sizeof z);
        hpgen_lane_update(z, g, p, hv, g1, p1);
        for (l = 0; l < HPGEN_L; ++l) {
            double sg = 0.0, sp = 0.0;
            for (i = 0; i < HPGEN_NN; ++i) sg += g1[i * HPGEN_L + l];
            for (i = 0; i < HPGEN_D; ++i) sp += p1[i * HPGEN_L + l];
            ok[l] = alive[l] & (sg - sg == 0.0) & (sp - sp == 0.0);
            all &= ok[l];
        }
        if (all) {
            memcpy(g, g1, sizeof g);
            memcpy(p, p1, sizeof p);
        } else {
            for (l = 0; l < HPGEN_L; ++l) {
                if (!ok[l]) continue;
                for (i = 0; i < HPGEN_NN; ++i) g[i * HPGEN_L + l] = g1[i * HPGEN_L + l];
                for (i = 0; i < HPGEN_D; ++i) p[i * HPGEN_L + l] = p1[i * HPGEN_L + l];
            }
        }
        for (l = 0; l < HPGEN_L; ++l) k[l] += ok[l];
        for (l = 0; l < HPGEN_L; ++l) {
            if (!alive[l] || ok[l]) continue;
            hpgen_lane_scatter(runs + l, l, g, p, z, dz, hp, k);
            if (hpgen_run_step(runs + l, hv1, o, &full, st + l, 1) != HPGEN_OK) {
                alive[l] = 0;
                --nalive;
                continue;
            }
            hpgen_lane_gather(runs + l, l, g, p, z, dz, hp, k);
        }
        for (l = 0; l < HPGEN_L; ++l) {
            if (!alive[l] || k[l] % every != 0) continue;
            for (i = 0; i < HPGEN_NN; ++i)
                g_rec[(l * per_run + rec[l]) * HPGEN_NN + i] = g[i * HPGEN_L + l];
            for (i = 0; i < HPGEN_D; ++i)
                p_rec[(l * per_run + rec[l]) * HPGEN_D + i] = p[i * HPGEN_L + l];
            ++rec[l];
        }
    }
    for (l = 0; l < HPGEN_L; ++l) {
        if (!alive[l]) continue;
        hpgen_lane_scatter(runs + l, l, g, p, z, dz, hp, k);
        st[l].step = k[l];
    }
}
#else
/* L runs (runs[0..L-1], the same k, full Newton, g not stale) advanced like L calls of
   hpgen_advance (records of lane l at g_rec + l per_run NN, p_rec + l per_run D). */
static void hpgen_advance_lanes(hpgen_run* runs, double h, long long steps, long long every,
                                const hpgen_options* o, long long per_run, double* g_rec,
                                double* p_rec, hpgen_status* st) {
    double g[HPGEN_NN * HPGEN_L], p[HPGEN_D * HPGEN_L], z[HPGEN_NZ * HPGEN_L],
        dz[HPGEN_PH][HPGEN_NZ * HPGEN_L],
        G[HPGEN_NZ * HPGEN_L], zs[HPGEN_NZ * HPGEN_L],
        g1[HPGEN_NN * HPGEN_L], p1[HPGEN_D * HPGEN_L], hv[HPGEN_L], m[HPGEN_L],
        res[HPGEN_L], hv1[1];
    long long hp[HPGEN_L], k[HPGEN_L], rec[HPGEN_L], it[HPGEN_L], ok[HPGEN_L],
        alive[HPGEN_L], n, nalive = HPGEN_L;
    int i, l;
    hpgen_options full = *o;
    full.simplified = 0;
    hv1[0] = h;
    for (l = 0; l < HPGEN_L; ++l) {
        hpgen_status_init(st + l);
        hpgen_lane_gather(runs + l, l, g, p, z, dz, hp, k);
        hv[l] = h;
        alive[l] = 1;
        rec[l] = 0;
    }
    for (n = 0; n < steps && nalive > 0; ++n) {
        long long first = 1;
        for (l = 0; l < HPGEN_L; ++l) first &= !alive[l] | (k[l] == 0);
        if (first) {
            /* a run's first step (the crude start: a margin check, then full Newton) is
               scalar code's */
            for (l = 0; l < HPGEN_L; ++l) ok[l] = 0;
        } else {
            /* the start: the predictor of hpgen_run_step, per lane (G by the scalar
               kernels, lane by lane: bitwise hpgen_run_step's) */
            long long pm[HPGEN_L];
            long long all = 1;
            for (l = 0; l < HPGEN_L; ++l) {
                double gl[HPGEN_NN], pl[HPGEN_D], Gl[HPGEN_NZ];
                for (i = 0; i < HPGEN_NN; ++i) gl[i] = g[i * HPGEN_L + l];
                for (i = 0; i < HPGEN_D; ++i) pl[i] = p[i * HPGEN_L + l];
                hpgen_predictor_base(gl, pl, hv1, Gl);
                for (i = 0; i < HPGEN_NZ; ++i) G[i * HPGEN_L + l] = Gl[i];
                pm[l] = o->predictor ? hp[l] : 0;
            }
            for (l = 0; l < HPGEN_L; ++l) {
                if (pm[l] > 0)
                    hpgen_predict(G + l, &dz[0][l], HPGEN_L, HPGEN_NZ * HPGEN_L, pm[l], zs + l);
                else
                    for (i = 0; i < HPGEN_NZ; ++i) zs[i * HPGEN_L + l] = z[i * HPGEN_L + l];
            }
            hpgen_lane_newton(g, p, hv, zs, o, ok, it, res);
            hpgen_lane_margin(zs, hv, m);
            hpgen_lane_update(zs, g, p, hv, g1, p1);
            /* the lanes that stepped: margin > 0, g1 and p1 finite (the sums of
               hpgen_all_finite's common path; a lane whose sum is not finite redoes the
               step in scalar code, which tells an overflowing sum from a non-finite entry) */
            for (l = 0; l < HPGEN_L; ++l) {
                double sg = 0.0, sp = 0.0;
                for (i = 0; i < HPGEN_NN; ++i) sg += g1[i * HPGEN_L + l];
                for (i = 0; i < HPGEN_D; ++i) sp += p1[i * HPGEN_L + l];
                ok[l] = ok[l] & alive[l] & (m[l] > 0.0) & (k[l] != 0) & (sg - sg == 0.0)
                        & (sp - sp == 0.0);
                all &= ok[l];
            }
            /* commit them: whole arrays when every lane stepped (the common case), else
               lane by lane */
            if (all) {
                memmove(dz[1], dz[0], (HPGEN_PH - 1) * sizeof dz[0]);
                for (i = 0; i < HPGEN_NZ * HPGEN_L; ++i) dz[0][i] = zs[i] - G[i];
                memcpy(z, zs, sizeof z);
                memcpy(g, g1, sizeof g);
                memcpy(p, p1, sizeof p);
            } else {
                for (l = 0; l < HPGEN_L; ++l) {
                    if (!ok[l]) continue;
                    for (i = 0; i < HPGEN_NZ; ++i) {
                        const int j = i * HPGEN_L + l;
                        int q;
                        for (q = HPGEN_PH - 1; q > 0; --q) dz[q][j] = dz[q - 1][j];
                        dz[0][j] = zs[j] - G[j];
                        z[j] = zs[j];
                    }
                    for (i = 0; i < HPGEN_NN; ++i) g[i * HPGEN_L + l] = g1[i * HPGEN_L + l];
                    for (i = 0; i < HPGEN_D; ++i) p[i * HPGEN_L + l] = p1[i * HPGEN_L + l];
                }
            }
            for (l = 0; l < HPGEN_L; ++l) {
                const long long c = ok[l];
                hp[l] += c & (hp[l] < HPGEN_PH);
                k[l] += c;
                st[l].total_iterations += c ? it[l] : 0;
                st[l].jacobians += c ? it[l] : 0;
                st[l].iterations = c ? it[l] : st[l].iterations;
                st[l].residual = c ? res[l] : st[l].residual;
            }
        }
        /* the others: this step by hpgen_run_step from the lane's state */
        for (l = 0; l < HPGEN_L; ++l) {
            if (!alive[l] || ok[l]) continue;
            hpgen_lane_scatter(runs + l, l, g, p, z, dz, hp, k);
            if (hpgen_run_step(runs + l, hv1, o, &full, st + l, 1) != HPGEN_OK) {
                alive[l] = 0;
                --nalive;
                continue;
            }
            hpgen_lane_gather(runs + l, l, g, p, z, dz, hp, k);
        }
        for (l = 0; l < HPGEN_L; ++l) {
            if (!alive[l] || k[l] % every != 0) continue;
            for (i = 0; i < HPGEN_NN; ++i)
                g_rec[(l * per_run + rec[l]) * HPGEN_NN + i] = g[i * HPGEN_L + l];
            for (i = 0; i < HPGEN_D; ++i)
                p_rec[(l * per_run + rec[l]) * HPGEN_D + i] = p[i * HPGEN_L + l];
            ++rec[l];
        }
    }
    for (l = 0; l < HPGEN_L; ++l) {
        if (!alive[l]) continue;
        hpgen_lane_scatter(runs + l, l, g, p, z, dz, hp, k);
        st[l].step = k[l];
    }
}
#endif /* HPGEN_EXPLICIT */

HPGEN_LANES_END

/* hpgen_advance_batch with lanes: groups of L consecutive runs at the same step, with full
   Newton (o->simplified = 0; an explicit step: any options), advance together (hpgen_advance_lanes); the other runs (the
   remainder of B / L, simplified Newton, invalid arguments) by hpgen_advance, one after the
   other. The same records, statuses and return value as hpgen_advance_batch. */
HPGEN_EXPORT long long hpgen_advance_batch_lanes(hpgen_run* runs, long long B, double h,
                                                 long long steps, long long every,
                                                 const hpgen_options* o, long long per_run,
                                                 double* g_rec, double* p_rec,
                                                 hpgen_status* st) {
    long long b = 0, failed = 0, j;
    if (steps >= 0 && every >= 1 && hpgen_options_ok(o)
        && (HPGEN_EXPLICIT || !o->simplified)) {
        for (; b + HPGEN_L <= B; b += HPGEN_L) {
            int same = 1, l;
            for (l = 0; l < HPGEN_L; ++l)
                same &= runs[b + l].k == runs[b].k && !runs[b + l].g_stale;
            if (!same) break;
            hpgen_advance_lanes(runs + b, h, steps, every, o, per_run,
                                g_rec + b * per_run * HPGEN_NN, p_rec + b * per_run * HPGEN_D,
                                st + b);
        }
    }
    for (j = b; j < B; ++j)
        hpgen_advance(runs + j, h, steps, every, o, g_rec + j * per_run * HPGEN_NN,
                      p_rec + j * per_run * HPGEN_D, st + j);
    for (j = 0; j < B; ++j) failed += st[j].code != HPGEN_OK;
    return failed;
}

/* bodies per call of the lane-wise kernels */
HPGEN_EXPORT long long hpgen_lanes(void) { return HPGEN_L; }
#endif /* HPGEN_L */
