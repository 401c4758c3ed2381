/* hpgen's C runtime, part 6: lane-wise ensembles, when the model has lane kernels (HPGEN_L,
   hpgen.codegen.lanes). Included by hpgen_runtime.c last.

   HPGEN_L bodies per call in structure-of-arrays form (entry i of lane l at x[i * L + l]):
   the step's kernels printed lane-wise; Newton in hpgen_lane_newton.c (full Newton with
   HPGEN_NZ <= 3 vectorised across the lanes: per-lane convergence masks, the adjugate
   solve, the norms and the tests as fixed-count lane loops; simplified Newton, and any
   HPGEN_NZ, with each lane's own kept J^{-1} and the scalar linear algebra lane by lane).
   Every lane performs the operations of hpgen_run_cstep in the same order: its
   states are bitwise those of hpgen_advance. A composed step (hpgen_run_set_compose) runs
   its substeps in lanes, each from its own predictor offsets. A lane whose step does not
   converge cleanly (Newton failure, singular J, margin <= 0, a non-finite update in any
   substep: any case where hpgen_run_step would retry or report) redoes that step with the
   scalar hpgen_run_cstep from its state before the step, which then retries or reports
   exactly as a scalar run; a lane that fails there stops (its status set) and the other
   lanes continue. A run's first step (the crude start: a margin check, then Newton from the
   guess) is always the scalar code's. The model's lane kernels (hpgen_lane_residual_jacobian,
   hpgen_lane_residual, hpgen_lane_margin, hpgen_lane_update) come from kernels.c, as its HPGEN_L. An explicit
   step (HPGEN_EXPLICIT) has no Newton: one lane-wise update a (sub)step (hpgen_lane_update
   alone), any number of unknowns. */
#if defined(HPGEN_L)
#if HPGEN_SPARSE && !HPGEN_EXPLICIT
#error "lane code is written for a dense Newton matrix"
#endif
/* lane code with the residual kernel (hpgen.codegen.lanes defines HPGEN_LANE_RESIDUAL) runs
   simplified Newton and HPGEN_NZ > 3 in lanes; lane code without it (a module generated
   before) full Newton with HPGEN_NZ <= 3 only */
#if defined(HPGEN_LANE_RESIDUAL) && !HPGEN_EXPLICIT
#define HPGEN_LANES_LU 1
#else
#define HPGEN_LANES_LU 0
#endif
#if !HPGEN_EXPLICIT && !HPGEN_LANES_LU && HPGEN_NZ > 3
#error "lane code without a lane-wise residual is for at most 3 unknowns"
#endif
#if HPGEN_CH != HPGEN_PH
#error "the lanes shift a composed run's offsets as the plain ones (HPGEN_CH == HPGEN_PH)"
#endif

HPGEN_LANES_BEGIN
#if !HPGEN_EXPLICIT
#include "hpgen_lane_newton.c"
#endif

#include "hpgen_lane_set.c"

/* substep i's step size of the runs' (composed) step h */
#define HPGEN_LANE_SUBSTEP_H(runs, i, h) ((runs)[0].cs > 0 ? (runs)[0].cg[i] * (h) : (h))

#if HPGEN_EXPLICIT
/* L runs (runs[0..L-1], the same k, the same composition, g not stale) of an explicit step
   advanced like L calls of hpgen_advance (records of lane l at g_rec + l per_run NN, p_rec +
   l per_run D): per (sub)step z = p and one lane-wise update (hpgen_explicit_step's
   operations on every lane); a lane whose g1 or p1 sum is not finite in a substep redoes
   the step by hpgen_run_cstep, which reports it (or steps, when only the sum overflowed). */
static void hpgen_advance_lanes(hpgen_run* runs, double h, long long steps, long long every,
                                const hpgen_options* o, long long per_run, double* g_rec,
                                double* p_rec, hpgen_status* st) {
    hpgen_lane_set s;
    double g1[HPGEN_NN * HPGEN_L], p1[HPGEN_D * HPGEN_L], gs[HPGEN_NN * HPGEN_L],
        ps[HPGEN_D * HPGEN_L], zs[HPGEN_NZ * HPGEN_L], hv[HPGEN_L], hv1[1];
    long long ok[HPGEN_L], n, i;
    const long long ns = runs[0].cs > 0 ? runs[0].cs : 1;
    int l;
    hpgen_options full = *o;
    full.simplified = 0;
    hv1[0] = h;
    hpgen_lanes_start(&s, runs, st);
    for (n = 0; n < steps && s.nalive > 0; ++n) {
        const double *g = s.g, *p = s.p;
        for (l = 0; l < HPGEN_L; ++l) ok[l] = s.alive[l];
        for (i = 0; i < ns; ++i) {
            const double hs = HPGEN_LANE_SUBSTEP_H(runs, i, h);
            for (l = 0; l < HPGEN_L; ++l) hv[l] = hs;
            memcpy(zs, p, sizeof zs);
            hpgen_lane_update(zs, g, p, hv, g1, p1);
            hpgen_lanes_finite(g1, p1, ok);
            if (i + 1 < ns) {
                memcpy(gs, g1, sizeof gs);
                memcpy(ps, p1, sizeof ps);
                g = gs;
                p = ps;
            }
        }
        hpgen_lanes_commit(&s, ok, g1, p1, zs);
        for (l = 0; l < HPGEN_L; ++l) s.k[l] += ok[l];
        hpgen_lanes_redo_record(&s, runs, ok, hv1, o, &full, st, every, per_run, g_rec, p_rec);
    }
    hpgen_lanes_finish(&s, runs, st);
}
#else
/* L runs (runs[0..L-1], the same k, the same composition, g not stale)
   advanced like L calls of hpgen_advance (records of lane l at g_rec + l per_run NN, p_rec
   + l per_run D). Substep i of a step (the plain step: i = 0 only) starts from
   hpgen_run_step's predictor through the lane's offsets (a composed run's substep i: its
   own, cdz[i]; without the predictor: the last solution), G by the scalar kernels lane by
   lane (bitwise hpgen_run_step's); the lane-wise Newton (full Newton with HPGEN_NZ <= 3:
   hpgen_lane_newton; else hpgen_lane_newton_lu, each lane's J^{-1} kept across substeps
   and steps as a run keeps it), margin and update follow. A lane
   steps when every substep converged with margin > 0 and finite g1, p1. (A composed run's
   plain offsets dz, which hpgen_run_cstep overwrites before it reads them, are left as
   they were.) */
static void hpgen_advance_lanes(hpgen_run* runs, double h, long long steps, long long every,
                                const hpgen_options* o, long long per_run, double* g_rec,
                                double* p_rec, hpgen_status* st) {
    hpgen_lane_set s;
    double G[HPGEN_NZ * HPGEN_L], zs[HPGEN_NZ * HPGEN_L], zc[HPGEN_NZ * HPGEN_L],
        g1[HPGEN_NN * HPGEN_L], p1[HPGEN_D * HPGEN_L], gs[HPGEN_NN * HPGEN_L],
        ps[HPGEN_D * HPGEN_L], nd[HPGEN_CS_MAX][HPGEN_NZ * HPGEN_L], hv[HPGEN_L], m[HPGEN_L],
        res[HPGEN_L], hvs[1], hv1[1];
    double wlu[HPGEN_L][HPGEN_LU_SIZE];           /* the lanes' J^{-1} during a step */
    int wpiv[HPGEN_L][HPGEN_NZ];
    long long ok[HPGEN_L], okn[HPGEN_L], it[HPGEN_L], jn[HPGEN_L], sit[HPGEN_L],
        sjac[HPGEN_L], wvalid[HPGEN_L], n, i;
    const long long cs = runs[0].cs, ns = cs > 0 ? cs : 1;
    int l, q, j;
    hpgen_options full = *o;
    full.simplified = 0;
    hv1[0] = h;
    hpgen_lanes_start(&s, runs, st);
    for (n = 0; n < steps && s.nalive > 0; ++n) {
        long long first = 1;
        for (l = 0; l < HPGEN_L; ++l) first &= !s.alive[l] | (s.k[l] == 0);
        /* a run's first step, and a composed run without offsets, are scalar code's */
        for (l = 0; l < HPGEN_L; ++l) ok[l] = (!first) & s.alive[l] & ((cs == 0) | (s.ch[l] > 0));
        if (!first) {
            const double *g = s.g, *p = s.p, *zp = s.z;
            for (l = 0; l < HPGEN_L; ++l) sit[l] = sjac[l] = 0;
            if (o->simplified) {
                memcpy(wlu, s.lu, sizeof wlu);
                memcpy(wpiv, s.piv, sizeof wpiv);
            }
            memcpy(wvalid, s.valid, sizeof wvalid);
            for (i = 0; i < ns; ++i) {
                hvs[0] = HPGEN_LANE_SUBSTEP_H(runs, i, h);
                for (l = 0; l < HPGEN_L; ++l) {
                    double gl[HPGEN_NN], pl[HPGEN_D], Gl[HPGEN_NZ];
                    const long long pm = !o->predictor ? 0 : cs == 0 ? s.hp[l] : s.ch[l];
                    hv[l] = hvs[0];
                    for (q = 0; q < HPGEN_NN; ++q) gl[q] = g[q * HPGEN_L + l];
                    for (q = 0; q < HPGEN_D; ++q) pl[q] = p[q * HPGEN_L + l];
                    hpgen_predictor_base(gl, pl, hvs, Gl);
                    for (q = 0; q < HPGEN_NZ; ++q) G[q * HPGEN_L + l] = Gl[q];
                    if (pm > 0)
                        hpgen_predict(G + l, cs == 0 ? &s.dz[0][l] : &s.cdz[i][0][l], HPGEN_L,
                                      HPGEN_NZ * HPGEN_L, pm, zs + l);
                    else
                        for (q = 0; q < HPGEN_NZ; ++q) zs[q * HPGEN_L + l] = zp[q * HPGEN_L + l];
                }
#if HPGEN_NZ <= 3
                if (!HPGEN_LANES_LU || !o->simplified) {
                    hpgen_lane_newton(g, p, hv, zs, o, okn, it, res);
                    for (l = 0; l < HPGEN_L; ++l) {
                        jn[l] = it[l];
                        wvalid[l] = 0;                 /* full Newton keeps no J^{-1} */
                    }
                } else
#endif
                {
#if HPGEN_LANES_LU
                    hpgen_lane_newton_lu(g, p, hv, zs, o, wlu, wpiv, wvalid, ok, okn, it, jn,
                                         res);
#endif
                }
                hpgen_lane_margin(zs, hv, m);
                hpgen_lane_update(zs, g, p, hv, g1, p1);
                for (l = 0; l < HPGEN_L; ++l) {
                    ok[l] &= okn[l] & (m[l] > 0.0);
                    sit[l] += it[l];
                    sjac[l] += jn[l];
                }
                hpgen_lanes_finite(g1, p1, ok);
                /* a root the guard questions: the scalar step's (hpgen_guard_resolve) */
                for (l = 0; l < HPGEN_L; ++l)
                    if (o->predictor && (cs == 0 ? s.hp[l] : s.ch[l]) >= 3
                        && hpgen_guard_ratio(zs + l, G + l, cs == 0 ? &s.dz[0][l]
                                             : &s.cdz[i][0][l], HPGEN_L, HPGEN_NZ * HPGEN_L)
                               > HPGEN_GUARD_RATIO)
                        ok[l] = 0;
                if (cs > 0)         /* (the plain step's offsets: zs - G at the commit) */
                    for (q = 0; q < HPGEN_NZ * HPGEN_L; ++q) nd[i][q] = zs[q] - G[q];
                if (i + 1 < ns) {
                    memcpy(gs, g1, sizeof gs);
                    memcpy(ps, p1, sizeof ps);
                    memcpy(zc, zs, sizeof zc);
                    g = gs;
                    p = ps;
                    zp = zc;
                }
            }
            /* commit the lanes that stepped, their offsets shifted by one step */
            if (hpgen_lanes_commit(&s, ok, g1, p1, zs) && cs == 0) {
                memmove(s.dz[1], s.dz[0], (HPGEN_PH - 1) * sizeof s.dz[0]);
                for (q = 0; q < HPGEN_NZ * HPGEN_L; ++q) s.dz[0][q] = zs[q] - G[q];
            } else {
                for (l = 0; l < HPGEN_L; ++l) {
                    if (!ok[l]) continue;
                    for (i = 0; i < ns; ++i) {
                        double(*d)[HPGEN_NZ * HPGEN_L] = cs == 0 ? s.dz : s.cdz[i];
                        for (q = 0; q < HPGEN_NZ; ++q) {
                            const int x = q * HPGEN_L + l;
                            for (j = HPGEN_PH - 1; j > 0; --j) d[j][x] = d[j - 1][x];
                            d[0][x] = cs == 0 ? zs[x] - G[x] : nd[i][x];
                        }
                    }
                }
            }
            for (l = 0; l < HPGEN_L; ++l) {
                const long long c = ok[l];
                if (c && o->simplified) {
                    memcpy(s.lu[l], wlu[l], sizeof wlu[l]);
                    memcpy(s.piv[l], wpiv[l], sizeof wpiv[l]);
                }
                s.valid[l] = c ? wvalid[l] : s.valid[l];
                if (cs == 0)
                    s.hp[l] += c & (s.hp[l] < HPGEN_PH);
                else
                    s.ch[l] += c & (s.ch[l] < HPGEN_CH);
                s.k[l] += c;
                st[l].total_iterations += c ? sit[l] : 0;
                st[l].jacobians += c ? sjac[l] : 0;
                st[l].iterations = c ? sit[l] : st[l].iterations;
                st[l].residual = c ? res[l] : st[l].residual;
            }
        }
        hpgen_lanes_redo_record(&s, runs, ok, hv1, o, &full, st, every, per_run, g_rec, p_rec);
    }
    hpgen_lanes_finish(&s, runs, st);
}
#endif /* HPGEN_EXPLICIT */

HPGEN_LANES_END

/* hpgen_advance_batch with lanes: groups of L consecutive runs at the same step with the
   same composition advance together (hpgen_advance_lanes); the other runs (the remainder
   of B / L, invalid arguments, simplified Newton without HPGEN_LANES_LU) by hpgen_advance,
   one after the other. The same records, statuses and return value as hpgen_advance_batch. */
HPGEN_EXPORT long long hpgen_advance_batch_lanes(hpgen_run* runs, long long B, double h,
                                                 long long steps, long long every,
                                                 const hpgen_options* o, long long per_run,
                                                 double* g_rec, double* p_rec,
                                                 hpgen_status* st) {
    long long b = 0, failed = 0, j;
    if (steps >= 0 && every >= 1 && hpgen_options_ok(o)
        && (HPGEN_EXPLICIT || HPGEN_LANES_LU || !o->simplified)) {
        for (; b + HPGEN_L <= B; b += HPGEN_L) {
            int same = 1, l;
            for (l = 0; l < HPGEN_L; ++l)
                same &= runs[b + l].k == runs[b].k && !runs[b + l].g_stale
                        && runs[b + l].cs == runs[b].cs
                        && !memcmp(runs[b + l].cg, runs[b].cg, sizeof runs[b].cg);
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
