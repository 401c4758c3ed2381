/* Hand-written Lie Stormer-Verlet for the heavy top, plain C99, written directly from the
 * paper's eqs. sv1-sv5 (Bou-Rabee & Marsden, HP integrators on Lie groups, Part I; tableau
 * [[0, 0], [1/2, 1/2]], b = (1/2, 1/2), tau = Cayley, q = 0). A peer for hpgen's generated C
 * (heavy top, tableau stormer-verlet, tau cay, rkmk truncated): benchmarks/sv_vs_hand.py times
 * both, tests/regression/test_hand_c.py checks they agree.
 *
 * Problem: G = SO(3), l(R, Omega) = 1/2 Omega.I Omega - Mg chi.(R^T e3), I = diag(1, 5, 6),
 * chi = (0, 0, 1), Mg = 1. Pairing g* x g = dot product of vectors, hat(w) y = w x y.
 *   dl/dxi (R, Omega) = I Omega,
 *   f(R) := R dl/dR (R) = Mg (R^T e3) x chi      (left-trivialized, as tests/handwritten/heavy_top.py)
 *   cay(x) = (e - x^/2)^{-1} (e + x^/2) = e + k (x^ + x^ x^ / 2),  k = 4 / (4 + |x|^2)
 *   dcay^{-1}_x y = (e - x^/2) y^ (e + x^/2) (eq. dcay), in vectors I - x^/2 + x x^T / 4,
 *   so (dcay^{-1}_x)^* m = m + 1/2 x x m + 1/4 (x.m) x.
 *
 * Paper variables and hpgen's state. The paper steps (g_k, mu_k) and eq. sv3 also needs the
 * previous increment xi_k, only through (dcay^{-1}_{-h xi_k})^* mu_k. That combination is hpgen's
 * node momentum p_k (docs/numerics.md sec. 4; tests/handwritten/heavy_top.py, class StormerVerlet):
 *     p_k = (dcay^{-1}_{-h xi_k})^* mu_k.
 * With it the paper's equations read, for a separable l (no g_{k+1} in sv2's kinetic term):
 *   sv1, sv2:  M = I Xi^1 = I Xi^2, so Xi^1 = Xi^2 =: X and xi_{k+1} = (Xi^1 + Xi^2)/2 = X;
 *   sv3:       (dcay^{-1}_{h X})^* I X = p_k + h/2 f(g_k)          (3 unknowns X, Newton);
 *   sv4:       g_{k+1} = g_k cay(h X);
 *   sv5:       mu_{k+1} = M + h/2 (dcay_{-h X})^* f(g_{k+1}), hence the next node momentum
 *              p_{k+1} = (dcay^{-1}_{-h X})^* mu_{k+1} = (dcay^{-1}_{-h X})^* M + h/2 f(g_{k+1})
 *              (the dcay_{-hX} of sv5 cancels against the dcay^{-1}_{-hX} of p: no inverse).
 * So one step is: half kick, 3-unknown Cayley solve, group update, half kick.
 *
 * Newton on F(X) = I X + a X x (I X) + a^2 (X.I X) X - rhs, a = h/2, warm-started from the
 * previous step's X (first step: X = I^{-1} p_0, the velocity, as hpgen's guess), closed-form
 * 3x3 Jacobian J = I + a (X^ I - (I X)^) + a^2 (2 X (I X)^T + (X.I X) e) and solve (Cramer),
 * stop at |dX| <= 1e-14 (1 + |X|) in the inf-norm (hpgen's default tolerance and norm), with
 * hpgen's round-off floor rule as a safety net (|dX| stopped decreasing while <= 1e-11 (1 + |X|)).
 *
 * ABI (ctypes): see the exported functions at the end. Matrices column-major (R[i + 3 j]).
 */
#include <math.h>
#include <string.h>

#define HAND_SV_ABI 1
#define HAND_OK 0
#define HAND_NO_CONVERGENCE 1
#define HAND_NONFINITE 2
#define HAND_DOMAIN 3
#define HAND_INVALID (-1)

#define TOL 1e-14
#define ROUNDOFF_FLOOR 1e-11
#define MAXIT 50

static const double I0 = 1.0, I1 = 5.0, I2 = 6.0;   /* I = diag(I0, I1, I2) */
static const double MG = 1.0;
static const double CHI0 = 0.0, CHI1 = 0.0, CHI2 = 1.0;

/* f(R) = Mg (R^T e3) x chi; R^T e3 is the third row of R: R[2], R[5], R[8] */
static void force(const double* R, double f[3]) {
    const double G0 = R[2], G1 = R[5], G2 = R[8];
    f[0] = MG * (G1 * CHI2 - G2 * CHI1);
    f[1] = MG * (G2 * CHI0 - G0 * CHI2);
    f[2] = MG * (G0 * CHI1 - G1 * CHI0);
}

static double max3(double a, double b, double c) {
    double m = fabs(a);
    if (fabs(b) > m) m = fabs(b);
    if (fabs(c) > m) m = fabs(c);
    return m;
}

/* eq. sv3 for X (in: start, out: solution). */
static int solve_sv3(double a, const double rhs[3], double x[3], long long* iters) {
    const double a2 = a * a, two_a2 = 2.0 * a2;
    double dprev = HUGE_VAL;
    int it;
    for (it = 1; it <= MAXIT; ++it) {
        const double x0 = x[0], x1 = x[1], x2 = x[2];
        const double m0 = I0 * x0, m1 = I1 * x1, m2 = I2 * x2;          /* M = I X (sv1) */
        const double s = x0 * m0 + x1 * m1 + x2 * m2;                    /* X.M */
        const double a2s = a2 * s;
        /* F = M + a X x M + a^2 (X.M) X - rhs */
        const double F0 = m0 + a * (x1 * m2 - x2 * m1) + a2s * x0 - rhs[0];
        const double F1 = m1 + a * (x2 * m0 - x0 * m2) + a2s * x1 - rhs[1];
        const double F2 = m2 + a * (x0 * m1 - x1 * m0) + a2s * x2 - rhs[2];
        /* J = I + a (X^ I - M^) + a^2 (2 X M^T + s e) */
        const double J00 = I0 + a2s + two_a2 * x0 * m0;
        const double J01 = a * (m2 - x2 * I1) + two_a2 * x0 * m1;
        const double J02 = a * (x1 * I2 - m1) + two_a2 * x0 * m2;
        const double J10 = a * (x2 * I0 - m2) + two_a2 * x1 * m0;
        const double J11 = I1 + a2s + two_a2 * x1 * m1;
        const double J12 = a * (m0 - x0 * I2) + two_a2 * x1 * m2;
        const double J20 = a * (m1 - x1 * I0) + two_a2 * x2 * m0;
        const double J21 = a * (x0 * I1 - m0) + two_a2 * x2 * m1;
        const double J22 = I2 + a2s + two_a2 * x2 * m2;
        /* cofactors; dX = adj(J) F / det J */
        const double C00 = J11 * J22 - J12 * J21, C01 = J12 * J20 - J10 * J22,
                     C02 = J10 * J21 - J11 * J20;
        const double det = J00 * C00 + J01 * C01 + J02 * C02;
        const double C10 = J02 * J21 - J01 * J22, C11 = J00 * J22 - J02 * J20,
                     C12 = J01 * J20 - J00 * J21;
        const double C20 = J01 * J12 - J02 * J11, C21 = J02 * J10 - J00 * J12,
                     C22 = J00 * J11 - J01 * J10;
        const double inv = 1.0 / det;
        const double d0 = (C00 * F0 + C10 * F1 + C20 * F2) * inv;
        const double d1 = (C01 * F0 + C11 * F1 + C21 * F2) * inv;
        const double d2 = (C02 * F0 + C12 * F1 + C22 * F2) * inv;
        double dn, zn;
        x[0] = x0 - d0;
        x[1] = x1 - d1;
        x[2] = x2 - d2;
        *iters = it;
        dn = max3(d0, d1, d2);
        zn = max3(x[0], x[1], x[2]);
        if (!isfinite(dn) || !isfinite(zn)) return HAND_NONFINITE;
        if (dn <= TOL * (1.0 + zn)) return HAND_OK;
        if (it > 1 && dn >= dprev && dn <= ROUNDOFF_FLOOR * (1.0 + zn)) return HAND_OK;
        dprev = dn;
    }
    return HAND_NO_CONVERGENCE;
}

/* One step (g_k, p_k) -> (g_{k+1}, p_{k+1}); x: Newton start in, X = xi_{k+1} out.
   R1, p1 must not alias R, p. */
static int sv_step(const double* R, const double* p, double h, double x[3], double* R1,
                   double* p1, long long* iters) {
    const double a = 0.5 * h;
    double f[3], rhs[3], w0, w1, w2, ww, k, hk, C[9], m0, m1, m2, c0, c1, c2, s;
    int i, code;
    /* sv3, right-hand side: p_k + h/2 f(g_k) (half kick) */
    force(R, f);
    rhs[0] = p[0] + a * f[0];
    rhs[1] = p[1] + a * f[1];
    rhs[2] = p[2] + a * f[2];
    code = solve_sv3(a, rhs, x, iters);
    if (code != HAND_OK) return code;
    /* sv4: g_{k+1} = g_k cay(h X), cay(w) = e + k w^ + k/2 (w w^T - |w|^2 e) */
    w0 = h * x[0]; w1 = h * x[1]; w2 = h * x[2];
    ww = w0 * w0 + w1 * w1 + w2 * w2;
    if (!(ww < 4.0)) return HAND_DOMAIN;          /* hpgen's chart domain |h xi| < 2 */
    k = 4.0 / (4.0 + ww);
    hk = 0.5 * k;
    C[0] = 1.0 + hk * (w0 * w0 - ww);
    C[1] = k * w2 + hk * w1 * w0;
    C[2] = -k * w1 + hk * w2 * w0;
    C[3] = -k * w2 + hk * w0 * w1;
    C[4] = 1.0 + hk * (w1 * w1 - ww);
    C[5] = k * w0 + hk * w2 * w1;
    C[6] = k * w1 + hk * w0 * w2;
    C[7] = -k * w0 + hk * w1 * w2;
    C[8] = 1.0 + hk * (w2 * w2 - ww);
    for (i = 0; i < 3; ++i) {
        R1[i + 0] = R[i] * C[0] + R[i + 3] * C[1] + R[i + 6] * C[2];
        R1[i + 3] = R[i] * C[3] + R[i + 3] * C[4] + R[i + 6] * C[5];
        R1[i + 6] = R[i] * C[6] + R[i + 3] * C[7] + R[i + 6] * C[8];
    }
    /* sv5 mapped to the node momentum: p_{k+1} = (dcay^{-1}_{-hX})^* M + h/2 f(g_{k+1}),
       (dcay^{-1}_{-hX})^* M = M - a X x M + a^2 (X.M) X */
    m0 = I0 * x[0]; m1 = I1 * x[1]; m2 = I2 * x[2];
    c0 = x[1] * m2 - x[2] * m1;
    c1 = x[2] * m0 - x[0] * m2;
    c2 = x[0] * m1 - x[1] * m0;
    s = a * a * (x[0] * m0 + x[1] * m1 + x[2] * m2);
    force(R1, f);
    p1[0] = m0 - a * c0 + s * x[0] + a * f[0];
    p1[1] = m1 - a * c1 + s * x[1] + a * f[1];
    p1[2] = m2 - a * c2 + s * x[2] + a * f[2];
    for (i = 0; i < 9; ++i) if (!isfinite(R1[i])) return HAND_NONFINITE;
    if (!isfinite(p1[0]) || !isfinite(p1[1]) || !isfinite(p1[2])) return HAND_NONFINITE;
    return HAND_OK;
}

/* ---- exported ABI -------------------------------------------------------------------------- */

/* ABI version (1). */
int hand_sv_abi(void) { return HAND_SV_ABI; }

/* One step from (R[9] column-major, p[3]) with step h. x0[3]: Newton start (NULL: the
   velocity I^{-1} p); x1[3] (may be NULL): the solution X = xi_{k+1}. Returns a code (0 = OK,
   1 no convergence, 2 non-finite, 3 outside the Cayley chart |h X| < 2); *iters (may be NULL):
   Newton iterations. */
int hand_sv_step(const double* R, const double* p, double h, const double* x0, double* x1,
                 double* R1, double* p1, long long* iters) {
    double x[3];
    long long it = 0;
    int code;
    if (x0) memcpy(x, x0, sizeof x);
    else { x[0] = p[0] / I0; x[1] = p[1] / I1; x[2] = p[2] / I2; }
    code = sv_step(R, p, h, x, R1, p1, &it);
    if (x1) memcpy(x1, x, sizeof x);
    if (iters) *iters = it;
    return code;
}

/* `steps` steps of size h from (R0[9] column-major, p0[3]), warm-started; records (R, p) at
   steps 0, every, 2 every, ... into R_rec[(steps / every + 1) * 9] and p_rec[(...) * 3] (the
   layout of hpgen's simulate). total_iters (may be NULL): Newton iterations summed; code (may
   be NULL): status of the last step. Returns the steps done (stops at the first failed step),
   -1 on invalid arguments. */
long long hand_sv_simulate(const double* R0, const double* p0, double h, long long steps,
                           long long every, double* R_rec, double* p_rec,
                           long long* total_iters, int* code_out) {
    double R[2][9], p[2][3], x[3];
    long long k, it, total = 0;
    int cur = 0, code = HAND_OK;
    if (steps < 0 || every < 1) return -1;
    memcpy(R[0], R0, sizeof R[0]);
    memcpy(p[0], p0, sizeof p[0]);
    memcpy(R_rec, R0, sizeof R[0]);
    memcpy(p_rec, p0, sizeof p[0]);
    x[0] = p0[0] / I0; x[1] = p0[1] / I1; x[2] = p0[2] / I2;
    for (k = 0; k < steps; ++k) {
        const int nxt = 1 - cur;
        code = sv_step(R[cur], p[cur], h, x, R[nxt], p[nxt], &it);
        total += it;
        if (code != HAND_OK) break;
        cur = nxt;
        if ((k + 1) % every == 0) {
            const long long rec = (k + 1) / every;
            memcpy(R_rec + rec * 9, R[cur], sizeof R[0]);
            memcpy(p_rec + rec * 3, p[cur], sizeof p[0]);
        }
    }
    if (total_iters) *total_iters = total;
    if (code_out) *code_out = code;
    return k;
}
