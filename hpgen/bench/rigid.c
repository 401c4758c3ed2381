/* hpgen bench: structure-preserving peers for a rigid body with a potential affine in
 * Gamma = R^T e3 (heavy top, free body), written by hand (hpgen.bench.rigid compiles this
 * file at bench time with hpgen.runtime.build's flags; nothing fetched).
 *
 * State y[12] = (R row-major (9), Pi (3)), Pi the body angular momentum: the bench's y.
 * H = 1/2 Pi.I^-1 Pi + m.Gamma, Gamma = R^T e3 = (R[2][0], R[2][1], R[2][2]);
 * Pi' = Pi x Omega + Gamma x m, R' = R hat(Omega), Omega = I^-1 Pi (inertia diagonal).
 *
 * hpgen_rigid_split: the explicit splitting of Dullweber, Leimkuhler & McLachlan (1997).
 *   Basic step S(h) = K(h/2) F(h) K(h/2): K(t) the potential kick Pi += t Gamma x m (R fixed),
 *   F(h) = X1(h/2) X2(h/2) X3(h) X2(h/2) X1(h/2) the free body, X_i(t) the exact flow of
 *   Pi_i^2 / (2 I_i): a rotation by theta = t Pi_i / I_i about body axis e_i,
 *   R <- R Q_i(theta), Pi <- Q_i(theta)^T Pi (spatial momentum R Pi kept to round-off,
 *   |Pi| kept by every X_i, R stays orthogonal: products of rotations). Symmetric, order 2.
 *   A step of the composed method is S(c_1 h) ... S(c_s h) with the coefficients c given
 *   (hpgen.bench.rigid: Yoshida's triple jump (order 4), Kahan & Li's s9odr6 (order 6)).
 *   Kicks are skipped when m = 0 (free body).
 * hpgen_rigid_rattle: RATTLE on the embedded R in R^{3x3} (McLachlan-Scovel), i.e. Moser-
 *   Veselov with potential kicks: Pi+ = Pi + (h/2) Gamma x m; f in SO(3) with
 *   f J - J f^T = h hat(Pi+) (J = tr(I)/2 E - I); R <- R f; Pi <- f^T Pi+ +
 *   (h/2) Gamma(R) x m. f = E + 2 q0 hat(q) + 2 hat(q)^2 (unit quaternion (q0, q), q0 > 0),
 *   the equation in q: 2 q0 I q + 2 q x (I q) = h Pi+, solved by Newton from q = (h/2)
 *   I^-1 Pi+ to round-off (stop when the update no longer shrinks or is below 1e-16 |q|).
 *
 * Both: `steps` steps of size h from y (updated in place); rec (if not NULL) receives y0
 * and the state after every `every`-th step. Return the number of steps done (< steps when
 * a non-finite value appeared or Newton failed; y is then the last good state).
 */
#include <math.h>
#include <string.h>

#define NY 12

typedef struct {
  double I[3], Iinv[3], m[3];
  int kick;
} body_t;

static void set_body(body_t *b, const double *inertia, const double *m) {
  int i;
  b->kick = 0;
  for (i = 0; i < 3; ++i) {
    b->I[i] = inertia[i];
    b->Iinv[i] = 1.0 / inertia[i];
    b->m[i] = m[i];
    if (m[i] != 0.0) b->kick = 1;
  }
}

/* Pi += t Gamma x m, Gamma = row 2 of R */
static void kick(const body_t *b, double *y, double t) {
  const double g0 = y[6], g1 = y[7], g2 = y[8];
  y[9] += t * (g1 * b->m[2] - g2 * b->m[1]);
  y[10] += t * (g2 * b->m[0] - g0 * b->m[2]);
  y[11] += t * (g0 * b->m[1] - g1 * b->m[0]);
}

/* exact flow of Pi_i^2 / (2 I_i) over time t */
static void axis_flow(const body_t *b, double *y, int i, double t) {
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  const double th = t * y[9 + i] * b->Iinv[i];
  const double c = cos(th), s = sin(th);
  double pj = y[9 + j], pk = y[9 + k];
  int r;
  for (r = 0; r < 3; ++r) {
    const double a = y[3 * r + j], bb = y[3 * r + k];
    y[3 * r + j] = c * a + s * bb;
    y[3 * r + k] = -s * a + c * bb;
  }
  y[9 + j] = c * pj + s * pk;
  y[9 + k] = -s * pj + c * pk;
}

static void basic_step(const body_t *b, double *y, double h) {
  if (b->kick) kick(b, y, 0.5 * h);
  axis_flow(b, y, 0, 0.5 * h);
  axis_flow(b, y, 1, 0.5 * h);
  axis_flow(b, y, 2, h);
  axis_flow(b, y, 1, 0.5 * h);
  axis_flow(b, y, 0, 0.5 * h);
  if (b->kick) kick(b, y, 0.5 * h);
}

static int finite_state(const double *y) {
  int i;
  for (i = 0; i < NY; ++i)
    if (!(y[i] - y[i] == 0.0)) return 0;
  return 1;
}

static void record(double *rec, long r, const double *y) {
  memcpy(rec + r * NY, y, NY * sizeof(double));
}

long hpgen_rigid_split(double *y, const double *inertia, const double *m, const double *c,
                       long nc, double h, long steps, long every, double *rec) {
  body_t b;
  double t[NY];
  long k, r = 0;
  int j;
  set_body(&b, inertia, m);
  if (rec) record(rec, r++, y);
  for (k = 0; k < steps; ++k) {
    memcpy(t, y, sizeof t);
    for (j = 0; j < nc; ++j) basic_step(&b, t, c[j] * h);
    if (!finite_state(t)) return k;
    memcpy(y, t, sizeof t);
    if (rec && (k + 1) % every == 0) record(rec, r++, y);
  }
  return steps;
}

/* solve 2 q0 I q + 2 q x (I q) = v (v = h Pi+); returns iterations, -1 on failure */
static int mv_solve(const body_t *b, const double *v, double *q) {
  int it, i;
  double prev = INFINITY;
  for (i = 0; i < 3; ++i) q[i] = 0.5 * b->Iinv[i] * v[i];
  for (it = 1; it <= 50; ++it) {
    const double qq = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    double q0, Iq[3], F[3], A[3][3], det, dq[3], dn, qn;
    if (!(qq < 1.0)) return -1;
    q0 = sqrt(1.0 - qq);
    for (i = 0; i < 3; ++i) Iq[i] = b->I[i] * q[i];
    F[0] = 2.0 * (q0 * Iq[0] + q[1] * Iq[2] - q[2] * Iq[1]) - v[0];
    F[1] = 2.0 * (q0 * Iq[1] + q[2] * Iq[0] - q[0] * Iq[2]) - v[1];
    F[2] = 2.0 * (q0 * Iq[2] + q[0] * Iq[1] - q[1] * Iq[0]) - v[2];
    /* dF = 2 [ -(I q) q^T / q0 + q0 I + hat(q) I - hat(I q) ] dq */
    {
      int r, s;
      const double hq[3][3] = {{0, -q[2], q[1]}, {q[2], 0, -q[0]}, {-q[1], q[0], 0}};
      const double hI[3][3] = {{0, -Iq[2], Iq[1]}, {Iq[2], 0, -Iq[0]}, {-Iq[1], Iq[0], 0}};
      for (r = 0; r < 3; ++r)
        for (s = 0; s < 3; ++s)
          A[r][s] = 2.0 * (-Iq[r] * q[s] / q0 + (r == s ? q0 * b->I[r] : 0.0)
                           + hq[r][s] * b->I[s] - hI[r][s]);
    }
    det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1])
        - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0])
        + A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
    if (!(det != 0.0) || !(det - det == 0.0)) return -1;
    dq[0] = (F[0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1])
             - A[0][1] * (F[1] * A[2][2] - A[1][2] * F[2])
             + A[0][2] * (F[1] * A[2][1] - A[1][1] * F[2])) / det;
    dq[1] = (A[0][0] * (F[1] * A[2][2] - A[1][2] * F[2])
             - F[0] * (A[1][0] * A[2][2] - A[1][2] * A[2][0])
             + A[0][2] * (A[1][0] * F[2] - F[1] * A[2][0])) / det;
    dq[2] = (A[0][0] * (A[1][1] * F[2] - F[1] * A[2][1])
             - A[0][1] * (A[1][0] * F[2] - F[1] * A[2][0])
             + F[0] * (A[1][0] * A[2][1] - A[1][1] * A[2][0])) / det;
    dn = fabs(dq[0]) > fabs(dq[1]) ? fabs(dq[0]) : fabs(dq[1]);
    if (fabs(dq[2]) > dn) dn = fabs(dq[2]);
    for (i = 0; i < 3; ++i) q[i] -= dq[i];
    qn = fabs(q[0]) + fabs(q[1]) + fabs(q[2]);
    if (!(dn - dn == 0.0)) return -1;
    if (dn <= 1e-16 * qn || dn >= prev) return it;
    prev = dn;
  }
  return -1;
}

long hpgen_rigid_rattle(double *y, const double *inertia, const double *m, double h,
                        long steps, long every, double *rec, long *iterations) {
  body_t b;
  double t[NY], v[3], q[3], f[3][3], P[3];
  long k, r = 0, its = 0;
  int i, j, n;
  set_body(&b, inertia, m);
  if (rec) record(rec, r++, y);
  for (k = 0; k < steps; ++k) {
    double q0, qq;
    memcpy(t, y, sizeof t);
    if (b.kick) kick(&b, t, 0.5 * h);
    for (i = 0; i < 3; ++i) v[i] = h * t[9 + i];
    n = mv_solve(&b, v, q);
    if (n < 0) break;
    its += n;
    qq = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    q0 = sqrt(1.0 - qq);
    /* f = E + 2 q0 hat(q) + 2 hat(q)^2, hat(q)^2 = q q^T - |q|^2 E */
    for (i = 0; i < 3; ++i)
      for (j = 0; j < 3; ++j) f[i][j] = 2.0 * q[i] * q[j] + (i == j ? 1.0 - 2.0 * qq : 0.0);
    f[0][1] -= 2.0 * q0 * q[2]; f[1][0] += 2.0 * q0 * q[2];
    f[0][2] += 2.0 * q0 * q[1]; f[2][0] -= 2.0 * q0 * q[1];
    f[1][2] -= 2.0 * q0 * q[0]; f[2][1] += 2.0 * q0 * q[0];
    for (i = 0; i < 3; ++i) {                  /* R <- R f (row i) */
      const double a0 = t[3 * i], a1 = t[3 * i + 1], a2 = t[3 * i + 2];
      for (j = 0; j < 3; ++j) t[3 * i + j] = a0 * f[0][j] + a1 * f[1][j] + a2 * f[2][j];
    }
    for (j = 0; j < 3; ++j) P[j] = f[0][j] * t[9] + f[1][j] * t[10] + f[2][j] * t[11];
    for (j = 0; j < 3; ++j) t[9 + j] = P[j];   /* Pi <- f^T Pi+ */
    if (b.kick) kick(&b, t, 0.5 * h);
    if (!finite_state(t)) break;
    memcpy(y, t, sizeof t);
    if (rec && (k + 1) % every == 0) record(rec, r++, y);
  }
  if (iterations) *iterations = its;
  return k;
}
