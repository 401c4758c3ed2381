/* hpgen's C runtime, part 1: linear algebra of the Newton matrix (HPGEN_NZ unknowns), dense
   (mirrored operation for operation in Python by hpgen.codegen.pylinear, printed per nz) or,
   in a module with HPGEN_SPARSE, an LU with a static pivot order and a sparse QR, both on
   patterns analysed at compile time (the Python backend agrees to round-off,
   hpgen.runtime.sparse). Included by hpgen_runtime.c; the model and the contract are
   hpgen_runtime.h's.

   What Newton, the runs and the linearization use of this file (its interface), A being
   HPGEN_LU_SIZE doubles:
     hpgen_newton_fj(z, g, p, hv, F, A)      F and J (into A's J storage) in one evaluation
     hpgen_newton_j(z, g, p, hv, A)          J alone (into A's J storage)
     hpgen_lu_factor_solve(A, piv, b, keep)  b <- J^{-1} b with J in A; keep: A keeps the
                                             factors (dense: A <- J^{-1})
     hpgen_lu_apply(A, piv, b)               b <- J^{-1} b with the kept A
     hpgen_norm_inf(x, n), hpgen_all_finite(x, n) */

/* max |x_i|; NaN if any x_i is NaN */
static double hpgen_norm_inf(const double* x, int n) {
    double m = 0.0;
    int i;
    for (i = 0; i < n; ++i) {
        double a = fabs(x[i]);
        if (a != a) return a;
        if (a > m) m = a;
    }
    return m;
}

/* every x_i finite: one test per entry. The tests are independent and their branches
   predictable, so they cost a few instructions each; a running sum of the entries (one test)
   would put n dependent additions on the step's critical path */
static int hpgen_all_finite(const double* x, int n) {
    int i;
    for (i = 0; i < n; ++i) if (!isfinite(x[i])) return 0;
    return 1;
}

#if HPGEN_SPARSE
/* A (HPGEN_LU_SIZE doubles, hpgen_runtime.h): the static LU's values | the QR's V, R, beta |
   which holds the factors (A[HPGEN_SP_FLAG]: 0 LU, 1 QR) | J's nonzeros (HPGEN_J_OFFSET).
   The LU: P J P^T = L U with the compile-time order of hpgen_slu_* (diagonal pivots; the
   multipliers' zero diagonals come after the bodies they join), 1 / u_tt stored on the
   diagonal. The QR (CasADi's casadi_qr): J P_c = Q R, V the Householder vectors; it needs no
   pivoting and takes over a J on which a static pivot fails. */
static int hpgen_newton_fj(const double* z, const double* g, const double* p, const double* hv,
                           double* F, double* A) {
    return hpgen_k_residual_jacobian_nz(z, g, p, hv, F, A + HPGEN_J_OFFSET);
}

#if !defined(HPGEN_WITH_LAZY) || HPGEN_WITH_LAZY   /* linearize only (hpgen_linearize.c) */
static int hpgen_newton_j(const double* z, const double* g, const double* p, const double* hv,
                          double* A) {
    double F[HPGEN_NZ];
    return hpgen_k_residual_jacobian_nz(z, g, p, hv, F, A + HPGEN_J_OFFSET);
}
#endif

#if HPGEN_SP_STATIC
/* L U of J's nonzeros Jnz into X (the filled pattern), left-looking: column t of P J P^T,
   minus L(:, k) U(k, t) for the k < t of its U part in ascending order, then scaled below
   the diagonal. Returns 1 when a pivot is not finite or |u_tt| <= HPGEN_STATIC_PIVOT_TOL
   times the largest |J| entry of the column (X is then partly overwritten). */
static int hpgen_slu_factor(const double* Jnz, double* X) {
    double x[HPGEN_NZ];
    int t, q, s;
#if defined(HPGEN_SLU_GENERATED) && !defined(HPGEN_SLU_LOOP)   /* the same arithmetic,
    generated (hpgen.codegen.lu_code); -DHPGEN_SLU_LOOP keeps this loop (A/B, tests) */
    if (1) return hpgen_slu_generated(Jnz, X);
#endif
    memset(x, 0, sizeof x);
    memset(X, 0, HPGEN_SP_NLU * sizeof(double));
    for (q = 0; q < HPGEN_SP_NJ; ++q) X[hpgen_slu_jmap[q]] = Jnz[q];
    for (t = 0; t < HPGEN_NZ; ++t) {
        const int c0 = hpgen_slu_colptr[t], c1 = hpgen_slu_colptr[t + 1], dt = hpgen_slu_diag[t];
        double cmax = 0.0, d, r;
        for (q = c0; q < c1; ++q) {
            const double a = X[q];
            x[hpgen_slu_row[q]] = a;
            if (fabs(a) > cmax) cmax = fabs(a);
        }
        for (q = c0; q < dt; ++q) {
            const int k = hpgen_slu_row[q];
            const double xk = x[k];
            X[q] = xk;
            x[k] = 0.0;
            if (xk != 0.0)
                for (s = hpgen_slu_diag[k] + 1; s < hpgen_slu_colptr[k + 1]; ++s)
                    x[hpgen_slu_row[s]] -= X[s] * xk;
        }
        d = x[t];
        x[t] = 0.0;
        if (!(fabs(d) > HPGEN_STATIC_PIVOT_TOL * cmax) || !isfinite(d)) return 1;
        r = 1.0 / d;
        X[dt] = r;
        for (q = dt + 1; q < c1; ++q) {
            X[q] = x[hpgen_slu_row[q]] * r;
            x[hpgen_slu_row[q]] = 0.0;
        }
    }
    return 0;
}

/* b <- J^{-1} b with the LU in X: y = P b, L y' = y, U x' = y', b = P^T x' */
static void hpgen_slu_solve(const double* X, double* b) {
    double y[HPGEN_NZ];
    int t, s;
    for (t = 0; t < HPGEN_NZ; ++t) y[t] = b[hpgen_slu_perm[t]];
    for (t = 0; t < HPGEN_NZ; ++t) {
        const double yt = y[t];
        if (yt != 0.0)
            for (s = hpgen_slu_diag[t] + 1; s < hpgen_slu_colptr[t + 1]; ++s)
                y[hpgen_slu_row[s]] -= X[s] * yt;
    }
    for (t = HPGEN_NZ - 1; t >= 0; --t) {
        const double yt = y[t] * X[hpgen_slu_diag[t]];
        y[t] = yt;
        for (s = hpgen_slu_colptr[t]; s < hpgen_slu_diag[t]; ++s) y[hpgen_slu_row[s]] -= X[s] * yt;
    }
    for (t = 0; t < HPGEN_NZ; ++t) b[hpgen_slu_perm[t]] = y[t];
}
#endif

/* b <- J^{-1} b with the kept factors (the LU's, or the QR's: x = P_c R^{-1} Q^T P_r b) */
static void hpgen_lu_apply(const double* A, const int* piv, double* b) {
    double w[HPGEN_SP_NROW];
    (void)piv;
#if HPGEN_SP_STATIC
    if (A[HPGEN_SP_FLAG] == 0.0) { hpgen_slu_solve(A, b); return; }
#endif
    casadi_qr_solve(b, 1, 0, hpgen_sp_v, A + HPGEN_SP_QR, hpgen_sp_r,
                    A + HPGEN_SP_QR + HPGEN_SP_NV, A + HPGEN_SP_QR + HPGEN_SP_NV + HPGEN_SP_NR,
                    hpgen_sp_prinv, hpgen_sp_pc, w);
}

/* Factor J (nonzeros at A + HPGEN_J_OFFSET) and b <- J^{-1} b; the factors are always kept
   (keep is the dense interface's). The static LU first; where one of its pivots fails, the
   QR. Returns 1 if J has a non-finite entry or is singular: a diagonal entry of R not finite,
   or at most HPGEN_NZ DBL_EPSILON times the largest (numerically rank deficient; exactly
   zero where J is structurally singular). */
static int hpgen_lu_factor_solve(double* A, int* piv, double* b, int keep) {
    double w[HPGEN_SP_NROW], rmax = 0.0, rmin = HUGE_VAL;
    double *V = A + HPGEN_SP_QR, *R = V + HPGEN_SP_NV, *beta = R + HPGEN_SP_NR;
    const casadi_int* rcol = hpgen_sp_r + 2;
    int c;
    (void)keep;
    if (!hpgen_all_finite(A + HPGEN_J_OFFSET, HPGEN_SP_NJ)) return 1;
#if HPGEN_SP_STATIC
    if (!hpgen_slu_factor(A + HPGEN_J_OFFSET, A)) {
        A[HPGEN_SP_FLAG] = 0.0;
        hpgen_slu_solve(A, b);
        return 0;
    }
#endif
    A[HPGEN_SP_FLAG] = 1.0;
    casadi_qr(hpgen_sp_j, A + HPGEN_J_OFFSET, w, hpgen_sp_v, V, hpgen_sp_r, R, beta,
              hpgen_sp_prinv, hpgen_sp_pc);
    for (c = 0; c < HPGEN_NZ; ++c) {      /* R's diagonal: the last entry of each column */
        double r = fabs(R[rcol[c + 1] - 1]);
        if (!isfinite(r)) return 1;
        if (r > rmax) rmax = r;
        if (r < rmin) rmin = r;
    }
    if (!(rmin > HPGEN_NZ * DBL_EPSILON * rmax)) return 1;
    hpgen_lu_apply(A, piv, b);
    return 0;
}
#else
static int hpgen_newton_fj(const double* z, const double* g, const double* p, const double* hv,
                           double* F, double* A) {
    return hpgen_k_residual_jacobian(z, g, p, hv, F, A);
}

#if !defined(HPGEN_WITH_LAZY) || HPGEN_WITH_LAZY   /* linearize only (hpgen_linearize.c) */
static int hpgen_newton_j(const double* z, const double* g, const double* p, const double* hv,
                          double* A) {
    return hpgen_kernel_jacobian(z, g, p, hv, A);
}
#endif

/* The Newton matrix is kept as J^{-1} (explicit, column-major in A; piv is workspace): a
   simplified-Newton iteration then costs one matrix-vector product, NZ^2 independent
   multiply-adds, instead of two triangular solves whose divisions and recurrences form a
   long dependency chain. Newton's fixed point depends on F only; the accuracy of J^{-1}
   only sets the contraction rate. */

/* b <- A b, A = J^{-1} from hpgen_lu_factor_solve */
static void hpgen_lu_apply(const double* A, const int* piv, double* b) {
    double x[HPGEN_NZ];
    int i, j;
    (void)piv;
    for (i = 0; i < HPGEN_NZ; ++i) x[i] = A[i] * b[0];
    for (j = 1; j < HPGEN_NZ; ++j)
        for (i = 0; i < HPGEN_NZ; ++i) x[i] += A[i + j * HPGEN_NZ] * b[j];
    for (i = 0; i < HPGEN_NZ; ++i) b[i] = x[i];
}

#if HPGEN_NZ <= 3
/* NZ <= 3: J^{-1} by cofactors (adjugate / det); Cramer's rule is accurate to a few ulps
   times cond(J) here. b <- J^{-1} b (the adjugate applied to b alongside the division) and,
   with keep, A <- J^{-1} (else A is left as it was: full Newton does not need J^{-1}).
   Returns 1 if det J is zero or not finite (then so is some entry of J: every entry enters
   det). */
static int hpgen_lu_factor_solve(double* A, int* piv, double* b, int keep) {
#if HPGEN_NZ == 1
    double r;
    if (!(A[0] != 0.0) || !isfinite(A[0])) return 1;
    r = 1.0 / A[0];
    b[0] *= r;
    if (keep) A[0] = r;
#elif HPGEN_NZ == 2
    const double a = A[0], c = A[1], bb = A[2], d = A[3], det = a * d - bb * c;
    const double x0 = d * b[0] - bb * b[1], x1 = a * b[1] - c * b[0];
    double r;
    if (!(det != 0.0) || !isfinite(det)) return 1;
    r = 1.0 / det;
    b[0] = x0 * r; b[1] = x1 * r;
    if (keep) { A[0] = d * r; A[2] = -bb * r; A[1] = -c * r; A[3] = a * r; }
#else
    /* J[i][j] = A[i + 3 j]; (J^{-1})_ij = C_ji / det, C the cofactors */
    const double j00 = A[0], j10 = A[1], j20 = A[2], j01 = A[3], j11 = A[4], j21 = A[5],
                 j02 = A[6], j12 = A[7], j22 = A[8];
    const double c00 = j11 * j22 - j12 * j21, c01 = j12 * j20 - j10 * j22,
                 c02 = j10 * j21 - j11 * j20, c10 = j02 * j21 - j01 * j22,
                 c11 = j00 * j22 - j02 * j20, c12 = j01 * j20 - j00 * j21,
                 c20 = j01 * j12 - j02 * j11, c21 = j02 * j10 - j00 * j12,
                 c22 = j00 * j11 - j01 * j10;
    const double det = j00 * c00 + j01 * c01 + j02 * c02;
    const double x0 = c00 * b[0] + c10 * b[1] + c20 * b[2],
                 x1 = c01 * b[0] + c11 * b[1] + c21 * b[2],
                 x2 = c02 * b[0] + c12 * b[1] + c22 * b[2];
    double r;
    if (!(det != 0.0) || !isfinite(det)) return 1;
    r = 1.0 / det;
    b[0] = x0 * r; b[1] = x1 * r; b[2] = x2 * r;
    if (keep) {
        A[0] = c00 * r; A[1] = c01 * r; A[2] = c02 * r;
        A[3] = c10 * r; A[4] = c11 * r; A[5] = c12 * r;
        A[6] = c20 * r; A[7] = c21 * r; A[8] = c22 * r;
    }
#endif
    (void)piv;
    return 0;
}
#else
/* LU with partial pivoting in place (pivot: first row of largest |a_ik|, as LAPACK), row
   interchanges in piv; U's diagonal is stored inverted (1 / u_kk). A is NZ x NZ
   column-major. Returns 1 if a pivot is exactly zero. */
static int hpgen_lu_factor(double* A, int* piv) {
    const int n = HPGEN_NZ;
    int i, j, k;
    for (k = 0; k < n; ++k) {
        int pk = k;
        double amax = fabs(A[k + k * n]), r;
        for (i = k + 1; i < n; ++i) {
            double a = fabs(A[i + k * n]);
            if (a > amax) { amax = a; pk = i; }
        }
        piv[k] = pk;
        if (amax == 0.0) return 1;
        if (pk != k) {
            for (j = 0; j < n; ++j) {
                double t = A[k + j * n]; A[k + j * n] = A[pk + j * n]; A[pk + j * n] = t;
            }
        }
        r = 1.0 / A[k + k * n];
        A[k + k * n] = r;
        for (i = k + 1; i < n; ++i) A[i + k * n] *= r;
        for (j = k + 1; j < n; ++j) {
            double a = A[k + j * n];
            if (a != 0.0) for (i = k + 1; i < n; ++i) A[i + j * n] -= A[i + k * n] * a;
        }
    }
    return 0;
}

/* b <- J^{-1} b with the factors of hpgen_lu_factor: all row interchanges first (the
   factorization swapped whole rows, L included), then L y = P b and U x = y. */
static void hpgen_lu_solve(const double* LU, const int* piv, double* b) {
    const int n = HPGEN_NZ;
    int i, j, k;
    for (k = 0; k < n; ++k)
        if (piv[k] != k) { double t = b[k]; b[k] = b[piv[k]]; b[piv[k]] = t; }
    for (k = 0; k < n; ++k)
        for (i = k + 1; i < n; ++i) b[i] -= LU[i + k * n] * b[k];
    for (k = n - 1; k >= 0; --k) {
        double s = b[k];
        for (j = k + 1; j < n; ++j) s -= LU[k + j * n] * b[j];
        b[k] = s * LU[k + k * n];
    }
}

/* X <- J^{-1} from the factors: the solve above for all unit vectors at once, ordered so
   that the columns' recurrences run side by side. X is NZ x NZ column-major. */
static void hpgen_lu_inverse(const double* LU, const int* piv, double* X) {
    const int n = HPGEN_NZ;
    int i, j, k;
    for (i = 0; i < n * n; ++i) X[i] = 0.0;
    for (j = 0; j < n; ++j) X[j + j * n] = 1.0;
    for (k = 0; k < n; ++k)
        if (piv[k] != k)
            for (j = 0; j < n; ++j) {
                double t = X[k + j * n]; X[k + j * n] = X[piv[k] + j * n]; X[piv[k] + j * n] = t;
            }
    for (k = 0; k < n; ++k)
        for (j = 0; j < n; ++j) {
            const double xk = X[k + j * n];
            if (xk != 0.0) for (i = k + 1; i < n; ++i) X[i + j * n] -= LU[i + k * n] * xk;
        }
    for (k = n - 1; k >= 0; --k)
        for (j = 0; j < n; ++j) {
            const double xk = X[k + j * n] * LU[k + k * n];
            X[k + j * n] = xk;
            for (i = 0; i < k; ++i) X[i + j * n] -= LU[i + k * n] * xk;
        }
}

/* b <- J^{-1} b by the LU of J (A holds J on entry); with keep, A <- J^{-1} (for simplified
   Newton), else A is left as the LU factors. Returns 1 if J has a non-finite entry or is
   singular. */
static int hpgen_lu_factor_solve(double* A, int* piv, double* b, int keep) {
    double LU[HPGEN_NZ * HPGEN_NZ];
    if (!hpgen_all_finite(A, HPGEN_NZ * HPGEN_NZ)) return 1;
    memcpy(LU, A, sizeof LU);
    if (hpgen_lu_factor(LU, piv)) return 1;
    hpgen_lu_solve(LU, piv, b);
    if (keep) {
        hpgen_lu_inverse(LU, piv, A);
        return !hpgen_all_finite(A, HPGEN_NZ * HPGEN_NZ);
    }
    return 0;
}
#endif
#endif /* HPGEN_SPARSE */
