/* hpgen's C runtime, part 6a: the lane-wise Newton of hpgen_lanes.c (HPGEN_L lanes, a dense
   Newton matrix): full Newton vectorised across the lanes for HPGEN_NZ <= 3
   (hpgen_lane_newton), and Newton of either kind with each lane's own kept J^{-1} for any
   HPGEN_NZ (hpgen_lane_newton_lu). Included by hpgen_lanes.c, inside its no-trapping-math
   region, for a model with lane kernels and an implicit step. */

#if HPGEN_NZ <= 3
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
#endif /* HPGEN_NZ <= 3 */

#if HPGEN_LANES_LU
/* Newton (hpgen_newton: full, or simplified with o->simplified) on L lanes from z (in/out),
   the residual and Jacobian kernels lane-wise (F and J from residual_jacobian where a lane
   needs a fresh J, F from residual where it applies its kept J^{-1}), the rest lane by lane
   with the scalar code's own functions on the lane's F and J (hpgen_norm_inf,
   hpgen_lu_factor_solve, hpgen_lu_apply) and hpgen_newton's tests in its order: a lane's z,
   iterations, Jacobians and last residual norm are bitwise hpgen_newton's. Lane l keeps its
   J^{-1} in lu[l], piv[l], valid[l] (in/out, a run's lu, piv and lu_valid; full Newton
   leaves them as they were). Lanes with act[l] = 0 are left alone. ok[l] = 1 where lane l
   converged, 0 where hpgen_newton would return a failure (z then undefined). */
static void hpgen_lane_newton_lu(const double* g, const double* p, const double* hv, double* z,
                                 const hpgen_options* o, double (*lu)[HPGEN_LU_SIZE],
                                 int (*piv)[HPGEN_NZ], long long* valid, const long long* act,
                                 long long* ok, long long* iters, long long* jacs,
                                 double* rnorm) {
    double F[HPGEN_NZ * HPGEN_L], Fr[HPGEN_NZ * HPGEN_L], J[HPGEN_NZ * HPGEN_NZ * HPGEN_L],
        dprev[HPGEN_L];
    const double tol = o->tol, stol = HPGEN_SIMPLIFIED_TOL * o->tol;
    long long active[HPGEN_L], full[HPGEN_L], fresh[HPGEN_L], it;
    int l, i;
    for (l = 0; l < HPGEN_L; ++l) {
        active[l] = act[l]; full[l] = !o->simplified; fresh[l] = 0; dprev[l] = HUGE_VAL;
        ok[l] = 0; iters[l] = 0; jacs[l] = 0; rnorm[l] = NAN;
    }
    for (it = 1; it <= o->maxit; ++it) {
        long long need_j = 0, need_r = 0, any = 0;
        for (l = 0; l < HPGEN_L; ++l) {
            const long long j = full[l] | !valid[l];
            need_j |= active[l] & j;
            need_r |= active[l] & !j;
        }
        if (need_j) hpgen_lane_residual_jacobian(z, g, p, hv, F, J);
        if (need_r) hpgen_lane_residual(z, g, p, hv, Fr);
        for (l = 0; l < HPGEN_L; ++l) {
            double f[HPGEN_NZ], zl[HPGEN_NZ], dn, zn;
            if (!active[l]) continue;
            active[l] = 0;                       /* until the iterate asks for another */
            iters[l] = it;
            if (full[l] || !valid[l]) {
                double A[HPGEN_LU_SIZE];
                valid[l] = 0;
                ++jacs[l];
                for (i = 0; i < HPGEN_NZ; ++i) f[i] = F[i * HPGEN_L + l];
                for (i = 0; i < HPGEN_NZ * HPGEN_NZ; ++i) A[i] = J[i * HPGEN_L + l];
                rnorm[l] = hpgen_norm_inf(f, HPGEN_NZ);
                if (!isfinite(rnorm[l]) || hpgen_lu_factor_solve(A, piv[l], f, o->simplified))
                    continue;
                if (o->simplified) {
                    memcpy(lu[l], A, sizeof A);
                    valid[l] = 1;
                }
                fresh[l] = 1;
            } else {
                for (i = 0; i < HPGEN_NZ; ++i) f[i] = Fr[i * HPGEN_L + l];
                rnorm[l] = hpgen_norm_inf(f, HPGEN_NZ);
                if (!isfinite(rnorm[l])) continue;
                hpgen_lu_apply(lu[l], piv[l], f);
            }
            for (i = 0; i < HPGEN_NZ; ++i) zl[i] = z[i * HPGEN_L + l] - f[i];
            for (i = 0; i < HPGEN_NZ; ++i) z[i * HPGEN_L + l] = zl[i];
            dn = hpgen_norm_inf(f, HPGEN_NZ);
            zn = hpgen_norm_inf(zl, HPGEN_NZ);
            if (!isfinite(dn) || !isfinite(zn)) continue;
            if (it > 1 && dn >= dprev[l] && dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + zn)) {
                ok[l] = 1;
                continue;
            }
            if (full[l]) {
                if (dn <= tol * (1.0 + zn)) { ok[l] = 1; continue; }
            } else {
                const double th = dn / dprev[l],
                             te = th > HPGEN_THETA_FLOOR ? th : HPGEN_THETA_FLOOR;
                if (dn <= stol * (1.0 + zn)) { ok[l] = 1; continue; }
                if (it > 1 && te < 1.0 && te / (1.0 - te) * dn <= stol * (1.0 + zn)) {
                    ok[l] = 1;
                    continue;
                }
            }
            if (!full[l] && it > 1 && dn > HPGEN_THETA_MAX * dprev[l]) {
                if (fresh[l]) full[l] = 1;
                else valid[l] = 0;
            }
            dprev[l] = dn;
            active[l] = 1;
            any = 1;
        }
        if (!any) break;
    }
}
#endif /* HPGEN_LANES_LU */
