/*
 * hpgen's C runtime: the contract (hpgen.abi) as C, the structs of the exported API and the
 * sizes every part of the runtime is written in.
 *
 * A generated module's kernels.c is one translation unit: it defines the model (below),
 * includes this header, wraps CasADi's kernels as static functions hpgen_k_<name> (dense
 * column-major arguments, hpgen.abi.KERNELS) and exports them as hpgen_kernel_<name>, then
 * includes hpgen_runtime.c (linear algebra, Newton, the runs, the batches, the lanes), which
 * calls those kernels directly: with the sizes constant at compile time the compiler unrolls
 * the small loops and inlines the kernels into the step (hpgen.runtime.build).
 *
 * The model, defined by kernels.c before it includes this header:
 *   HPGEN_N, HPGEN_D, HPGEN_NZ      group matrix n x n, algebra dimension d, Newton unknowns
 *   HPGEN_OPEN                      0: closed; 1: open (forces, inputs, parameters or t)
 *   HPGEN_M, HPGEN_P                (open only) control inputs and runtime parameters: every
 *                                   h input of the kernels is the step vector
 *                                   hv = [h, t_k, u (M), params (P)] of HPGEN_H doubles
 *   HPGEN_W                         the scene's record row width (kernel record)
 *   HPGEN_RECORD_USES_XI            1: the record row needs the velocity xi
 *   HPGEN_LEGENDRE_QUADRATIC        1: l is quadratic in xi (one velocity Newton step is exact)
 *   HPGEN_SKIP_G                    1: neither the step nor the record row use g
 *   HPGEN_FLATTEN                   1: inline the kernels into the step (small kernels)
 *   HPGEN_SPARSE                    0: J dense (column-major, LU); 1: J as its structural
 *                                   nonzeros, factored by an LU with a static pivot order
 *                                   (HPGEN_SP_STATIC 1: HPGEN_SP_NLU entries of L + U, the
 *                                   arrays hpgen_slu_*, hpgen.codegen.static_lu) or, where a
 *                                   static pivot fails, by a sparse QR: HPGEN_SP_NJ, _NV,
 *                                   _NR, _NROW (nonzeros of J, V, R and the rows of V) and the
 *                                   arrays hpgen_sp_j, hpgen_sp_v, hpgen_sp_r, hpgen_sp_prinv,
 *                                   hpgen_sp_pc (hpgen.codegen.sparse)
 *   HPGEN_HASH                      the content hash (a string literal)
 *   HPGEN_L                         (optional) lanes of the lane-wise kernels hpgen_lane_*
 *   HPGEN_EXPLICIT                  (optional, default 0) 1: the step is explicit (a splitting
 *                                   scheme, NZ = D): update(z = p_k, g_k, p_k, h) once, no Newton
 *
 * Conventions: all arrays are double, matrices column-major (g[i + j*n]), h is a scalar at
 * the API and a 1-vector for the kernels. No static mutable state: every function is
 * thread-safe; work arrays live on the stack, sized at compile time.
 * Status codes (hpgen.abi.STATUS):
 *   HPGEN_OK = 0: ok
 *   HPGEN_NO_CONVERGENCE = 1: Newton did not converge
 *   HPGEN_NONFINITE = 2: Newton diverged: a non-finite value (or a singular Jacobian) appeared
 *   HPGEN_DOMAIN = 3: the converged solution left the chart map tau's domain (margin(z, h) <= 0)
 *   HPGEN_RECORD = 4: a record row is not finite (or its velocity xi did not converge)
 *   HPGEN_INVALID = -1: invalid argument
 * HPGEN_DOMAIN is a start or a converged solution outside tau's domain; a Newton failure is
 * NO_CONVERGENCE or NONFINITE wherever its iterates went.
 * The constants below are hpgen.abi's (tests/unit/test_abi.py reads them back bitwise).
 */
#ifndef HPGEN_RUNTIME_H
#define HPGEN_RUNTIME_H

#if !defined(HPGEN_N) || !defined(HPGEN_D) || !defined(HPGEN_NZ) || !defined(HPGEN_OPEN) \
    || !defined(HPGEN_W) || !defined(HPGEN_RECORD_USES_XI) \
    || !defined(HPGEN_LEGENDRE_QUADRATIC) || !defined(HPGEN_SKIP_G) \
    || !defined(HPGEN_FLATTEN) || !defined(HPGEN_HASH) || !defined(HPGEN_SPARSE)
#error "define the model (HPGEN_N, HPGEN_D, HPGEN_NZ, HPGEN_OPEN, ...) before hpgen_runtime.h"
#endif
#ifndef HPGEN_EXPLICIT
#define HPGEN_EXPLICIT 0
#endif
#if HPGEN_EXPLICIT && HPGEN_NZ != HPGEN_D
#error "an explicit step's unknown is p_k: HPGEN_NZ == HPGEN_D"
#endif
#if HPGEN_OPEN && (!defined(HPGEN_M) || !defined(HPGEN_P))
#error "an open model defines HPGEN_M and HPGEN_P"
#endif

/* Standard headers first: kernels.c compiles CasADi's part under hidden visibility. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__GNUC__)
#define HPGEN_EXPORT __attribute__((visibility("default")))
#else
#define HPGEN_EXPORT
#endif

/* the version of the exported API (hpgen.abi.ABI_VERSION) */
#define HPGEN_ABI 10
#define HPGEN_NN (HPGEN_N * HPGEN_N)
/* the Newton matrix's storage (doubles): dense, J or J^{-1} column-major; sparse, the static
   LU's values (HPGEN_SP_NLU), the QR factors V | R | beta (HPGEN_NZ) from HPGEN_SP_QR, which
   of the two holds the factors at HPGEN_SP_FLAG (0: LU, 1: QR), J's nonzeros at
   HPGEN_J_OFFSET */
#if HPGEN_SPARSE
#define HPGEN_SP_QR HPGEN_SP_NLU
#define HPGEN_SP_FLAG (HPGEN_SP_QR + HPGEN_SP_NV + HPGEN_SP_NR + HPGEN_NZ)
#define HPGEN_J_OFFSET (HPGEN_SP_FLAG + 1)
#define HPGEN_LU_SIZE (HPGEN_J_OFFSET + HPGEN_SP_NJ)
#else
#define HPGEN_J_OFFSET 0
#define HPGEN_LU_SIZE (HPGEN_NZ * HPGEN_NZ)
#endif
#if HPGEN_OPEN
#define HPGEN_H (2 + HPGEN_M + HPGEN_P)
#endif

#define HPGEN_OK 0
#define HPGEN_NO_CONVERGENCE 1
#define HPGEN_NONFINITE 2
#define HPGEN_DOMAIN 3
#define HPGEN_RECORD 4
#define HPGEN_INVALID (-1)

/* Newton stalls at round-off: stop when |dz| stopped decreasing while below this * (1+|z|) */
#define HPGEN_ROUNDOFF_FLOOR 1e-11
/* a sparse module's Newton takes a stall of its contracting iterates below this * (1 + |z|)
   for the round-off noise of the solution (hpgen_stalled) */
#define HPGEN_STALL_MAX 1e-09
/* 1: a sparse module's full Newton is a chord iteration within the step (J once, again only
   on a poor rate: hpgen_newton_sparse); 0: J at every iterate (a build may set it to compare) */
#ifndef HPGEN_SPARSE_CHORD
#define HPGEN_SPARSE_CHORD 1
#endif
/* 1: the chord stops on its rate's error bound (hpgen_chord_converged); 0: on the stricter
   bound of a kept J (a build may set it to compare) */
#ifndef HPGEN_CHORD_RATE_STOP
#define HPGEN_CHORD_RATE_STOP 1
#endif
/* 1: a composed step's substeps of the first substep's size share its J (a sparse module's
   chord, hpgen_run_cstep_then; C only, a build option: it pays at small h only,
   docs/numerics.md sec. 8); 0 (default): a J at every substep */
#ifndef HPGEN_COMPOSE_SHARE_J
#define HPGEN_COMPOSE_SHARE_J 0
#endif
/* a sparse module's simplified Newton keeps J at |dz| <= this * (1 + |z|) (hpgen_at_floor) */
#define HPGEN_KEEP_J_FLOOR 1e-12
/* simplified Newton: a contraction rate |dz_k| / |dz_{k-1}| above this refreshes the Jacobian
   (or, with a Jacobian fresh from this step, switches the step to full Newton) */
#define HPGEN_THETA_MAX 0.2
/* simplified Newton stops when its error estimate is below this * tol * (1 + |z|) */
#define HPGEN_SIMPLIFIED_TOL 0.01
/* ... its error estimate takes the contraction rate as at least this (hpgen.abi.THETA_FLOOR) */
#define HPGEN_THETA_FLOOR 0.05
/* the guard on an accepted step (hpgen_guard_ratio in hpgen_runs.c): a root whose offset
   jumps by more than this times the offsets' variation is solved again (a build may set it,
   e.g. -DHPGEN_GUARD_RATIO=1e300 turns the guard off) */
#ifndef HPGEN_GUARD_RATIO
#define HPGEN_GUARD_RATIO 15.0
#endif
/* ... the floor of that change, times (1 + |z|): round-off never reaches the ratio */
#define HPGEN_GUARD_FLOOR 1e-09
/* 1: export hpgen_guard_log, the largest guard ratio and the re-solves (a measurement build) */
#ifndef HPGEN_GUARD_LOG
#define HPGEN_GUARD_LOG 0
#endif
/* the velocity xi of a record row: Newton's tolerance and iteration cap */
#define HPGEN_VELOCITY_TOL 1e-14
#define HPGEN_VELOCITY_MAXIT 50
/* a static pivot u_kk of the sparse LU is accepted when |u_kk| > this * max_i |J_ik| (a
   build may set it, e.g. -DHPGEN_STATIC_PIVOT_TOL=1e300 sends every J to the QR) */
#ifndef HPGEN_STATIC_PIVOT_TOL
#define HPGEN_STATIC_PIVOT_TOL 1e-08
#endif
/* the predictor keeps the offsets of this many past steps; row m - 1 of hpgen_pc weighs the
   m newest in the extrapolation through m of them (hpgen.abi.PREDICTOR_COEFFICIENTS) */
/* the most substeps of a composed step (hpgen.tableaus.composition.MAX_STAGES), and the
   offsets each substep's predictor keeps (hpgen.runtime.loop.COMPOSE_HISTORY) */
#define HPGEN_CS_MAX 9
#define HPGEN_CH 6
#define HPGEN_PH 6
static const double hpgen_pc[HPGEN_PH][HPGEN_PH] = {
    { 1.0, 0.0, 0.0, 0.0, 0.0, 0.0 },
    { 2.0, -1.0, 0.0, 0.0, 0.0, 0.0 },
    { 3.0, -3.0, 1.0, 0.0, 0.0, 0.0 },
    { 4.0, -6.0, 4.0, -1.0, 0.0, 0.0 },
    { 5.0, -10.0, 10.0, -5.0, 1.0, 0.0 },
    { 6.0, -15.0, 20.0, -15.0, 6.0, -1.0 }
};

/* what only an open model passes: the step vector hv of the Lagrangian kernels
   (hpgen.abi.OPEN_EXTRA) and of the functions around them, as an argument before the
   outputs, kernel(g, p, xi, HPGEN_OPEN_HV(hv) out), as a last argument,
   f(g, p, row HPGEN_OPEN_HV_LAST(hv)), and as a last parameter HPGEN_OPEN_HV_PARAM */
#if HPGEN_OPEN
#define HPGEN_OPEN_HV(hv) hv,
#define HPGEN_OPEN_HV_LAST(hv) , hv
#define HPGEN_OPEN_HV_PARAM , const double* hv
#else
#define HPGEN_OPEN_HV(hv)
#define HPGEN_OPEN_HV_LAST(hv)
#define HPGEN_OPEN_HV_PARAM
#endif

/* the lane code (kernels.c's lane kernels, hpgen_lanes.c) assumes no floating-point traps:
   gcc then if-converts and vectorises its lane loops; IEEE results are unchanged (no
   reassociation, no contraction at -std=c99) */
#if defined(__GNUC__) && !defined(__clang__)
#define HPGEN_LANES_BEGIN _Pragma("GCC push_options") _Pragma("GCC optimize(\"no-trapping-math\")")
#define HPGEN_LANES_END _Pragma("GCC pop_options")
#else
#define HPGEN_LANES_BEGIN
#define HPGEN_LANES_END
#endif

typedef struct hpgen_status {
    long long code;              /* HPGEN_OK, ... */
    long long step;              /* failing step index, or steps done on success */
    long long iterations;        /* Newton iterations of the last step attempted */
    long long total_iterations;  /* Newton iterations over all steps */
    double residual;             /* inf-norm of the last residual evaluated */
    long long jacobians;         /* Jacobian evaluations (and LU factorizations), all steps */
    long long guarded;           /* steps solved again by the guard (hpgen_guard_resolve) */
} hpgen_status;

/* Runtime Newton settings (no recompilation needed to change them). */
typedef struct hpgen_options {
    double tol;                  /* converged when |dz| <= tol (1 + |z|), inf-norms */
    long long maxit;             /* Newton iterations per step, >= 1 */
    long long simplified;        /* 1: keep the Jacobian's LU across iterations and steps */
    long long predictor;         /* 1: start step k+1 from the predictor (else from z_k) */
} hpgen_options;

/* A run in progress: the state, the Newton start and the Newton memory. Advancing a run by
   n1 steps and then by n2 steps gives bitwise the same result as by n1 + n2 steps. Callers
   allocate it as hpgen_run_size() bytes. */
typedef struct hpgen_run {
    double g[HPGEN_NN], p[HPGEN_D];  /* (g_k, p_k) */
    double z[HPGEN_NZ];              /* solution of the last step (or the initial guess) */
    double dz[HPGEN_PH][HPGEN_NZ];   /* predictor: z_j - G_j of the last steps j = k-1, k-2, ...
                                        (G_j the guess at step j's start, see hpgen_run_step) */
    double lu[HPGEN_LU_SIZE];        /* J^{-1} (sparse: J's QR) of the last Jacobian */
    int piv[HPGEN_NZ];
    long long k;                     /* steps done */
    long long have_prev;             /* how many of dz[0], dz[1], ... are valid (0..HPGEN_PH) */
    long long lu_valid;              /* lu holds J^{-1} */
    double s;                        /* section(g_k, p_k), when s_valid */
    long long s_valid;
    long long g_stale;               /* g is g_0, not g_k (hpgen_advance_record, HPGEN_SKIP_G) */
    /* a composed step (hpgen_run_set_compose; cs = 0: the plain step): cs substeps of
       fractions cg, substep i predicted from its own offsets z - G at the previous steps,
       cdz[i][0], cdz[i][1], ... (newest first; c_have of them valid) */
    long long cs, c_have;
    double cg[HPGEN_CS_MAX];
    double cdz[HPGEN_CS_MAX][HPGEN_CH][HPGEN_NZ];
#if HPGEN_OPEN
    double hv[HPGEN_H];              /* the step vector of the current step */
    double t0;                       /* the time of step 0 */
    const double* U;                 /* the input rows (M doubles each; the caller keeps them) */
    long long u_rows;                /* 1: one row for every step; else row k for step k */
#endif
} hpgen_run;

#endif /* HPGEN_RUNTIME_H */
