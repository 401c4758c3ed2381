/*
 * hpgen generated module double_body_chain_stormer_verlet_cay_truncated -- do not edit, regenerate with hpgen
 * model: double_body_chain
 * options: tableau=stormer-verlet, tau=cay, rkmk=truncated
 * hpgen version: 0.1.0
 * content hash (normalized model + options): f1db8c7f42f101f2eff1c614681288e8fab4d5bbe6b695247dbce78a05bbb544
 *
 * C backend: CasADi's generated kernels (symbols hidden) + dense LU, Newton, hpgen_step, the
 * runs (hpgen_run_*, hpgen_advance*, hpgen_record, hpgen_observe) (exported); the contract
 * with hpgen.runtime is hpgen.abi. Conventions: all arrays are double, matrices column-major
 * (g[i + j*n]), h is a scalar at the API and a 1-vector for the kernels. No static mutable
 * state: every function is thread-safe; work arrays live on the stack, sized at codegen time.
 * Status codes (hpgen.abi.STATUS):
 *   HPGEN_OK = 0: ok
 *   HPGEN_NO_CONVERGENCE = 1: Newton did not converge
 *   HPGEN_NONFINITE = 2: Newton diverged: a non-finite value (or a singular Jacobian) appeared
 *   HPGEN_DOMAIN = 3: the converged solution left the chart map tau's domain (margin(z, h) <= 0)
 *   HPGEN_RECORD = 4: a record row is not finite (or its velocity xi did not converge)
 *   HPGEN_INVALID = -1: invalid argument
 * HPGEN_DOMAIN is a start or a converged solution outside tau's domain; a Newton failure is
 * NO_CONVERGENCE or NONFINITE wherever its iterates went.
 */
/* Standard headers first: the CasADi part below is compiled under hidden visibility. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__GNUC__)
#pragma GCC visibility push(hidden)
#endif
/* ======================= CasADi-generated code (casadi.CodeGenerator) ================== */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) hpgen_double_body_chain_stormer_verlet_cay_truncated__ ## ID
#endif

#include <math.h>

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int long long int
#endif

/* Add prefix to internal symbols */
#define casadi_f0 CASADI_PREFIX(f0)
#define casadi_f1 CASADI_PREFIX(f1)
#define casadi_f10 CASADI_PREFIX(f10)
#define casadi_f11 CASADI_PREFIX(f11)
#define casadi_f12 CASADI_PREFIX(f12)
#define casadi_f13 CASADI_PREFIX(f13)
#define casadi_f14 CASADI_PREFIX(f14)
#define casadi_f15 CASADI_PREFIX(f15)
#define casadi_f16 CASADI_PREFIX(f16)
#define casadi_f2 CASADI_PREFIX(f2)
#define casadi_f3 CASADI_PREFIX(f3)
#define casadi_f4 CASADI_PREFIX(f4)
#define casadi_f5 CASADI_PREFIX(f5)
#define casadi_f6 CASADI_PREFIX(f6)
#define casadi_f7 CASADI_PREFIX(f7)
#define casadi_f8 CASADI_PREFIX(f8)
#define casadi_f9 CASADI_PREFIX(f9)
#define casadi_fabs CASADI_PREFIX(fabs)
#define casadi_fmax CASADI_PREFIX(fmax)
#define casadi_fmin CASADI_PREFIX(fmin)
#define casadi_s0 CASADI_PREFIX(s0)
#define casadi_s1 CASADI_PREFIX(s1)
#define casadi_s2 CASADI_PREFIX(s2)
#define casadi_s3 CASADI_PREFIX(s3)
#define casadi_s4 CASADI_PREFIX(s4)
#define casadi_s5 CASADI_PREFIX(s5)
#define casadi_sq CASADI_PREFIX(sq)

/* Symbol visibility in DLLs */
#ifndef CASADI_SYMBOL_EXPORT
  #if defined(_WIN32) || defined(__WIN32__) || defined(__CYGWIN__)
    #if defined(STATIC_LINKED)
      #define CASADI_SYMBOL_EXPORT
    #else
      #define CASADI_SYMBOL_EXPORT __declspec(dllexport)
    #endif
  #elif defined(__GNUC__) && defined(GCC_HASCLASSVISIBILITY)
    #define CASADI_SYMBOL_EXPORT __attribute__ ((visibility ("default")))
  #else
    #define CASADI_SYMBOL_EXPORT
  #endif
#endif

casadi_real casadi_sq(casadi_real x) { return x*x;}

casadi_real casadi_fabs(casadi_real x) {
/* Pre-c99 compatibility */
#if __STDC_VERSION__ < 199901L
  return x>0 ? x : -x;
#else
  return fabs(x);
#endif
}

casadi_real casadi_fmax(casadi_real x, casadi_real y) {
/* Pre-c99 compatibility */
#if __STDC_VERSION__ < 199901L
  return x>y ? x : y;
#else
  return (x > y || y != y) ? x : y;
#endif
}

casadi_real casadi_fmin(casadi_real x, casadi_real y) {
/* Pre-c99 compatibility */
#if __STDC_VERSION__ < 199901L
  return x<y ? x : y;
#else
  return (x < y || y != y) ? x : y;
#endif
}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void hpgen_double_body_chain_stormer_verlet_cay_truncated__casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int hpgen_double_body_chain_stormer_verlet_cay_truncated__casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int hpgen_double_body_chain_stormer_verlet_cay_truncated__casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {6, 1, 1};
static const casadi_int casadi_s1[3] = {36, 1, 1};
static const casadi_int casadi_s2[3] = {1, 1, 1};
static const casadi_int casadi_s3[3] = {49, 1, 1};
static const casadi_int casadi_s4[3] = {72, 1, 1};
static const casadi_int casadi_s5[3] = {144, 1, 1};

/* residual:(z[6],g[36],p[6],h)->(F[6]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41;
  a00=arg[2]? arg[2][0] : 0;
  a01=1.;
  a02=arg[3]? arg[3][0] : 0;
  a03=arg[0]? arg[0][0] : 0;
  a04=(a02*a03);
  a05=casadi_sq(a04);
  a06=4.;
  a05=(a05/a06);
  a05=(a01+a05);
  a07=9.0000000000000002e-01;
  a07=(a07*a03);
  a05=(a05*a07);
  a03=arg[0]? arg[0][1] : 0;
  a08=(a02*a03);
  a09=(a08*a04);
  a09=(a09/a06);
  a10=arg[0]? arg[0][2] : 0;
  a11=(a02*a10);
  a12=2.;
  a13=(a11/a12);
  a09=(a09-a13);
  a09=(a09*a03);
  a05=(a05+a09);
  a09=(a08/a12);
  a14=(a11*a04);
  a14=(a14/a06);
  a14=(a09+a14);
  a15=2.0000000000000001e-01;
  a15=(a15*a10);
  a14=(a14*a15);
  a05=(a05+a14);
  a00=(a00-a05);
  a05=arg[1]? arg[1][14] : 0;
  a14=5.0000000000000003e-02;
  a10=1.3000000000000000e+00;
  a16=arg[1]? arg[1][8] : 0;
  a17=(a14*a16);
  a10=(a10+a17);
  a17=1.0000000000000001e-01;
  a18=arg[1]? arg[1][2] : 0;
  a19=(a17*a18);
  a10=(a10+a19);
  a10=(a10-a05);
  a19=-1.0000000000000001e-01;
  a20=arg[1]? arg[1][29] : 0;
  a21=(a19*a20);
  a10=(a10+a21);
  a21=-2.9999999999999999e-01;
  a22=arg[1]? arg[1][35] : 0;
  a23=(a21*a22);
  a10=(a10+a23);
  a10=(2.*a10);
  a10=(a10*a02);
  a23=(a14*a10);
  a24=(a05*a23);
  a25=arg[1]? arg[1][7] : 0;
  a26=(a14*a25);
  a27=arg[1]? arg[1][1] : 0;
  a28=(a17*a27);
  a26=(a26+a28);
  a28=arg[1]? arg[1][13] : 0;
  a26=(a26-a28);
  a29=arg[1]? arg[1][28] : 0;
  a30=(a19*a29);
  a26=(a26+a30);
  a30=arg[1]? arg[1][34] : 0;
  a31=(a21*a30);
  a26=(a26+a31);
  a26=(2.*a26);
  a26=(a26*a02);
  a31=(a25*a26);
  a24=(a24+a31);
  a31=(a14*a26);
  a32=(a28*a31);
  a24=(a24+a32);
  a32=arg[1]? arg[1][6] : 0;
  a33=(a14*a32);
  a34=arg[1]? arg[1][0] : 0;
  a35=(a17*a34);
  a33=(a33+a35);
  a35=arg[1]? arg[1][12] : 0;
  a33=(a33-a35);
  a36=arg[1]? arg[1][27] : 0;
  a37=(a19*a36);
  a33=(a33+a37);
  a37=arg[1]? arg[1][33] : 0;
  a38=(a21*a37);
  a33=(a33+a38);
  a33=(2.*a33);
  a33=(a33*a02);
  a38=(a32*a33);
  a24=(a24+a38);
  a14=(a14*a33);
  a38=(a35*a14);
  a24=(a24+a38);
  a38=5.0000000000000000e-01;
  a39=(a38*a02);
  a39=(a10+a39);
  a40=(a16*a39);
  a24=(a24+a40);
  a00=(a00-a24);
  if (res[0]!=0) res[0][0]=a00;
  a00=arg[2]? arg[2][1] : 0;
  a24=(a04*a08);
  a24=(a24/a06);
  a13=(a13+a24);
  a13=(a13*a07);
  a24=casadi_sq(a08);
  a24=(a24/a06);
  a24=(a01+a24);
  a24=(a24*a03);
  a13=(a13+a24);
  a24=(a11*a08);
  a24=(a24/a06);
  a40=(a04/a12);
  a24=(a24-a40);
  a24=(a24*a15);
  a13=(a13+a24);
  a00=(a00-a13);
  a13=(a27*a26);
  a24=-5.0000000000000003e-02;
  a24=(a24*a02);
  a41=(a17*a10);
  a24=(a24-a41);
  a05=(a05*a24);
  a13=(a13-a05);
  a05=(a17*a26);
  a28=(a28*a05);
  a13=(a13+a28);
  a28=(a34*a33);
  a13=(a13+a28);
  a17=(a17*a33);
  a35=(a35*a17);
  a13=(a13+a35);
  a39=(a18*a39);
  a13=(a13+a39);
  a00=(a00+a13);
  if (res[0]!=0) res[0][1]=a00;
  a00=arg[2]? arg[2][2] : 0;
  a04=(a04*a11);
  a04=(a04/a06);
  a04=(a04-a09);
  a04=(a04*a07);
  a08=(a08*a11);
  a08=(a08/a06);
  a40=(a40+a08);
  a40=(a40*a03);
  a04=(a04+a40);
  a11=casadi_sq(a11);
  a11=(a11/a06);
  a11=(a01+a11);
  a11=(a11*a15);
  a04=(a04+a11);
  a00=(a00-a04);
  a16=(a16*a24);
  a18=(a18*a23);
  a16=(a16+a18);
  a25=(a25*a05);
  a16=(a16-a25);
  a27=(a27*a31);
  a16=(a16+a27);
  a32=(a32*a17);
  a16=(a16-a32);
  a34=(a34*a14);
  a16=(a16+a34);
  a00=(a00+a16);
  if (res[0]!=0) res[0][2]=a00;
  a00=arg[2]? arg[2][3] : 0;
  a16=arg[0]? arg[0][3] : 0;
  a34=(a02*a16);
  a14=casadi_sq(a34);
  a14=(a14/a06);
  a14=(a01+a14);
  a32=5.9999999999999998e-01;
  a32=(a32*a16);
  a14=(a14*a32);
  a16=arg[0]? arg[0][4] : 0;
  a17=(a02*a16);
  a27=(a17*a34);
  a27=(a27/a06);
  a31=arg[0]? arg[0][5] : 0;
  a25=(a02*a31);
  a05=(a25/a12);
  a27=(a27-a05);
  a38=(a38*a16);
  a27=(a27*a38);
  a14=(a14+a27);
  a27=(a17/a12);
  a16=(a25*a34);
  a16=(a16/a06);
  a16=(a27+a16);
  a18=1.4999999999999999e-01;
  a18=(a18*a31);
  a16=(a16*a18);
  a14=(a14+a16);
  a00=(a00-a14);
  a14=-2.9999999999999999e-02;
  a14=(a14*a02);
  a16=(a19*a10);
  a14=(a14-a16);
  a22=(a22*a14);
  a16=(a21*a26);
  a29=(a29*a16);
  a22=(a22+a29);
  a26=(a19*a26);
  a30=(a30*a26);
  a22=(a22-a30);
  a30=(a21*a33);
  a36=(a36*a30);
  a22=(a22+a36);
  a19=(a19*a33);
  a37=(a37*a19);
  a22=(a22-a37);
  a37=3.0000000000000004e-01;
  a37=(a37*a02);
  a21=(a21*a10);
  a37=(a37-a21);
  a20=(a20*a37);
  a22=(a22-a20);
  a00=(a00+a22);
  if (res[0]!=0) res[0][3]=a00;
  a00=arg[2]? arg[2][4] : 0;
  a22=(a34*a17);
  a22=(a22/a06);
  a05=(a05+a22);
  a05=(a05*a32);
  a22=casadi_sq(a17);
  a22=(a22/a06);
  a22=(a01+a22);
  a22=(a22*a38);
  a05=(a05+a22);
  a22=(a25*a17);
  a22=(a22/a06);
  a12=(a34/a12);
  a22=(a22-a12);
  a22=(a22*a18);
  a05=(a05+a22);
  a00=(a00-a05);
  a05=arg[1]? arg[1][23] : 0;
  a37=(a05*a37);
  a22=arg[1]? arg[1][22] : 0;
  a16=(a22*a16);
  a20=arg[1]? arg[1][21] : 0;
  a30=(a20*a30);
  a16=(a16+a30);
  a37=(a37-a16);
  a00=(a00+a37);
  if (res[0]!=0) res[0][4]=a00;
  a00=arg[2]? arg[2][5] : 0;
  a34=(a34*a25);
  a34=(a34/a06);
  a34=(a34-a27);
  a34=(a34*a32);
  a17=(a17*a25);
  a17=(a17/a06);
  a12=(a12+a17);
  a12=(a12*a38);
  a34=(a34+a12);
  a25=casadi_sq(a25);
  a25=(a25/a06);
  a01=(a01+a25);
  a01=(a01*a18);
  a34=(a34+a01);
  a00=(a00-a34);
  a22=(a22*a26);
  a05=(a05*a14);
  a22=(a22-a05);
  a20=(a20*a19);
  a22=(a22+a20);
  a00=(a00+a22);
  if (res[0]!=0) res[0][5]=a00;
  return 0;
}

CASADI_SYMBOL_EXPORT int residual(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int residual_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void residual_release(int mem) {
}

CASADI_SYMBOL_EXPORT void residual_incref(void) {
}

CASADI_SYMBOL_EXPORT void residual_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int residual_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int residual_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real residual_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* residual_name_in(casadi_int i) {
  switch (i) {
    case 0: return "z";
    case 1: return "g";
    case 2: return "p";
    case 3: return "h";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* residual_name_out(casadi_int i) {
  switch (i) {
    case 0: return "F";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* residual_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s0;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* residual_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int residual_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int residual_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* residual_jacobian:(z[6],g[36],p[6],h)->(F[6],J[36]) */
static int casadi_f1(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50;
  a00=arg[2]? arg[2][0] : 0;
  a01=1.;
  a02=arg[3]? arg[3][0] : 0;
  a03=arg[0]? arg[0][0] : 0;
  a04=(a02*a03);
  a05=casadi_sq(a04);
  a06=4.;
  a05=(a05/a06);
  a05=(a01+a05);
  a07=9.0000000000000002e-01;
  a03=(a07*a03);
  a08=(a05*a03);
  a09=arg[0]? arg[0][1] : 0;
  a10=(a02*a09);
  a11=(a10*a04);
  a11=(a11/a06);
  a12=arg[0]? arg[0][2] : 0;
  a13=(a02*a12);
  a14=2.;
  a15=(a13/a14);
  a11=(a11-a15);
  a16=(a11*a09);
  a08=(a08+a16);
  a16=(a10/a14);
  a17=(a13*a04);
  a17=(a17/a06);
  a17=(a16+a17);
  a18=2.0000000000000001e-01;
  a12=(a18*a12);
  a19=(a17*a12);
  a08=(a08+a19);
  a00=(a00-a08);
  a08=arg[1]? arg[1][14] : 0;
  a19=5.0000000000000003e-02;
  a20=1.3000000000000000e+00;
  a21=arg[1]? arg[1][8] : 0;
  a22=(a19*a21);
  a20=(a20+a22);
  a22=1.0000000000000001e-01;
  a23=arg[1]? arg[1][2] : 0;
  a24=(a22*a23);
  a20=(a20+a24);
  a20=(a20-a08);
  a24=-1.0000000000000001e-01;
  a25=arg[1]? arg[1][29] : 0;
  a26=(a24*a25);
  a20=(a20+a26);
  a26=-2.9999999999999999e-01;
  a27=arg[1]? arg[1][35] : 0;
  a28=(a26*a27);
  a20=(a20+a28);
  a20=(2.*a20);
  a20=(a20*a02);
  a28=(a19*a20);
  a29=(a08*a28);
  a30=arg[1]? arg[1][7] : 0;
  a31=(a19*a30);
  a32=arg[1]? arg[1][1] : 0;
  a33=(a22*a32);
  a31=(a31+a33);
  a33=arg[1]? arg[1][13] : 0;
  a31=(a31-a33);
  a34=arg[1]? arg[1][28] : 0;
  a35=(a24*a34);
  a31=(a31+a35);
  a35=arg[1]? arg[1][34] : 0;
  a36=(a26*a35);
  a31=(a31+a36);
  a31=(2.*a31);
  a31=(a31*a02);
  a36=(a30*a31);
  a29=(a29+a36);
  a36=(a19*a31);
  a37=(a33*a36);
  a29=(a29+a37);
  a37=arg[1]? arg[1][6] : 0;
  a38=(a19*a37);
  a39=arg[1]? arg[1][0] : 0;
  a40=(a22*a39);
  a38=(a38+a40);
  a40=arg[1]? arg[1][12] : 0;
  a38=(a38-a40);
  a41=arg[1]? arg[1][27] : 0;
  a42=(a24*a41);
  a38=(a38+a42);
  a42=arg[1]? arg[1][33] : 0;
  a43=(a26*a42);
  a38=(a38+a43);
  a38=(2.*a38);
  a38=(a38*a02);
  a43=(a37*a38);
  a29=(a29+a43);
  a19=(a19*a38);
  a43=(a40*a19);
  a29=(a29+a43);
  a43=5.0000000000000000e-01;
  a44=(a43*a02);
  a45=(a20+a44);
  a46=(a21*a45);
  a29=(a29+a46);
  a00=(a00-a29);
  if (res[0]!=0) res[0][0]=a00;
  a00=arg[2]? arg[2][1] : 0;
  a29=(a04*a10);
  a29=(a29/a06);
  a15=(a15+a29);
  a29=(a15*a03);
  a46=casadi_sq(a10);
  a46=(a46/a06);
  a46=(a01+a46);
  a47=(a46*a09);
  a29=(a29+a47);
  a47=(a13*a10);
  a47=(a47/a06);
  a48=(a04/a14);
  a47=(a47-a48);
  a49=(a47*a12);
  a29=(a29+a49);
  a00=(a00-a29);
  a29=(a32*a31);
  a49=-5.0000000000000003e-02;
  a49=(a49*a02);
  a50=(a22*a20);
  a49=(a49-a50);
  a08=(a08*a49);
  a29=(a29-a08);
  a08=(a22*a31);
  a33=(a33*a08);
  a29=(a29+a33);
  a33=(a39*a38);
  a29=(a29+a33);
  a22=(a22*a38);
  a40=(a40*a22);
  a29=(a29+a40);
  a45=(a23*a45);
  a29=(a29+a45);
  a00=(a00+a29);
  if (res[0]!=0) res[0][1]=a00;
  a00=arg[2]? arg[2][2] : 0;
  a29=(a04*a13);
  a29=(a29/a06);
  a29=(a29-a16);
  a16=(a29*a03);
  a45=(a10*a13);
  a45=(a45/a06);
  a48=(a48+a45);
  a45=(a48*a09);
  a16=(a16+a45);
  a45=casadi_sq(a13);
  a45=(a45/a06);
  a45=(a01+a45);
  a40=(a45*a12);
  a16=(a16+a40);
  a00=(a00-a16);
  a21=(a21*a49);
  a23=(a23*a28);
  a21=(a21+a23);
  a30=(a30*a08);
  a21=(a21-a30);
  a32=(a32*a36);
  a21=(a21+a32);
  a37=(a37*a22);
  a21=(a21-a37);
  a39=(a39*a19);
  a21=(a21+a39);
  a00=(a00+a21);
  if (res[0]!=0) res[0][2]=a00;
  a00=arg[2]? arg[2][3] : 0;
  a21=arg[0]? arg[0][3] : 0;
  a39=(a02*a21);
  a19=casadi_sq(a39);
  a19=(a19/a06);
  a19=(a01+a19);
  a37=5.9999999999999998e-01;
  a21=(a37*a21);
  a22=(a19*a21);
  a32=arg[0]? arg[0][4] : 0;
  a36=(a02*a32);
  a30=(a36*a39);
  a30=(a30/a06);
  a08=arg[0]? arg[0][5] : 0;
  a23=(a02*a08);
  a28=(a23/a14);
  a30=(a30-a28);
  a32=(a43*a32);
  a49=(a30*a32);
  a22=(a22+a49);
  a49=(a36/a14);
  a16=(a23*a39);
  a16=(a16/a06);
  a16=(a49+a16);
  a40=1.4999999999999999e-01;
  a08=(a40*a08);
  a33=(a16*a08);
  a22=(a22+a33);
  a00=(a00-a22);
  a22=-2.9999999999999999e-02;
  a22=(a22*a02);
  a33=(a24*a20);
  a22=(a22-a33);
  a27=(a27*a22);
  a33=(a26*a31);
  a34=(a34*a33);
  a27=(a27+a34);
  a31=(a24*a31);
  a35=(a35*a31);
  a27=(a27-a35);
  a35=(a26*a38);
  a41=(a41*a35);
  a27=(a27+a41);
  a24=(a24*a38);
  a42=(a42*a24);
  a27=(a27-a42);
  a42=3.0000000000000004e-01;
  a42=(a42*a02);
  a26=(a26*a20);
  a42=(a42-a26);
  a25=(a25*a42);
  a27=(a27-a25);
  a00=(a00+a27);
  if (res[0]!=0) res[0][3]=a00;
  a00=arg[2]? arg[2][4] : 0;
  a27=(a39*a36);
  a27=(a27/a06);
  a28=(a28+a27);
  a27=(a28*a21);
  a25=casadi_sq(a36);
  a25=(a25/a06);
  a25=(a01+a25);
  a26=(a25*a32);
  a27=(a27+a26);
  a26=(a23*a36);
  a26=(a26/a06);
  a14=(a39/a14);
  a26=(a26-a14);
  a20=(a26*a08);
  a27=(a27+a20);
  a00=(a00-a27);
  a27=arg[1]? arg[1][23] : 0;
  a42=(a27*a42);
  a20=arg[1]? arg[1][22] : 0;
  a33=(a20*a33);
  a38=arg[1]? arg[1][21] : 0;
  a35=(a38*a35);
  a33=(a33+a35);
  a42=(a42-a33);
  a00=(a00+a42);
  if (res[0]!=0) res[0][4]=a00;
  a00=arg[2]? arg[2][5] : 0;
  a42=(a39*a23);
  a42=(a42/a06);
  a42=(a42-a49);
  a49=(a42*a21);
  a33=(a36*a23);
  a33=(a33/a06);
  a14=(a14+a33);
  a33=(a14*a32);
  a49=(a49+a33);
  a33=casadi_sq(a23);
  a33=(a33/a06);
  a01=(a01+a33);
  a33=(a01*a08);
  a49=(a49+a33);
  a00=(a00-a49);
  a20=(a20*a31);
  a27=(a27*a22);
  a20=(a20-a27);
  a38=(a38*a24);
  a20=(a20+a38);
  a00=(a00+a20);
  if (res[0]!=0) res[0][5]=a00;
  a00=2.5000000000000000e-01;
  a20=(2.*a04);
  a20=(a20*a02);
  a20=(a00*a20);
  a20=(a03*a20);
  a05=(a07*a05);
  a20=(a20+a05);
  a05=(a10*a02);
  a05=(a00*a05);
  a38=(a09*a05);
  a20=(a20+a38);
  a24=(a13*a02);
  a24=(a00*a24);
  a27=(a12*a24);
  a20=(a20+a27);
  a20=(-a20);
  if (res[1]!=0) res[1][0]=a20;
  a20=(a03*a05);
  a15=(a07*a15);
  a20=(a20+a15);
  a15=(a12*a44);
  a20=(a20-a15);
  a20=(-a20);
  if (res[1]!=0) res[1][1]=a20;
  a20=(a03*a24);
  a07=(a07*a29);
  a20=(a20+a07);
  a07=(a09*a44);
  a20=(a20+a07);
  a20=(-a20);
  if (res[1]!=0) res[1][2]=a20;
  a20=0.;
  if (res[1]!=0) res[1][3]=a20;
  if (res[1]!=0) res[1][4]=a20;
  if (res[1]!=0) res[1][5]=a20;
  a04=(a04*a02);
  a04=(a00*a04);
  a29=(a09*a04);
  a29=(a29+a11);
  a29=(a29+a15);
  a29=(-a29);
  if (res[1]!=0) res[1][6]=a29;
  a29=(a03*a04);
  a10=(2.*a10);
  a10=(a10*a02);
  a10=(a00*a10);
  a10=(a09*a10);
  a10=(a10+a46);
  a10=(a29+a10);
  a10=(a10+a27);
  a10=(-a10);
  if (res[1]!=0) res[1][7]=a10;
  a09=(a09*a24);
  a09=(a09+a48);
  a03=(a03*a44);
  a09=(a09-a03);
  a09=(-a09);
  if (res[1]!=0) res[1][8]=a09;
  if (res[1]!=0) res[1][9]=a20;
  if (res[1]!=0) res[1][10]=a20;
  if (res[1]!=0) res[1][11]=a20;
  a04=(a12*a04);
  a17=(a18*a17);
  a04=(a04+a17);
  a04=(a04-a07);
  a04=(-a04);
  if (res[1]!=0) res[1][12]=a04;
  a05=(a12*a05);
  a47=(a18*a47);
  a05=(a05+a47);
  a03=(a03+a05);
  a03=(-a03);
  if (res[1]!=0) res[1][13]=a03;
  a29=(a29+a38);
  a13=(2.*a13);
  a13=(a13*a02);
  a13=(a00*a13);
  a12=(a12*a13);
  a18=(a18*a45);
  a12=(a12+a18);
  a29=(a29+a12);
  a29=(-a29);
  if (res[1]!=0) res[1][14]=a29;
  if (res[1]!=0) res[1][15]=a20;
  if (res[1]!=0) res[1][16]=a20;
  if (res[1]!=0) res[1][17]=a20;
  if (res[1]!=0) res[1][18]=a20;
  if (res[1]!=0) res[1][19]=a20;
  if (res[1]!=0) res[1][20]=a20;
  a29=(2.*a39);
  a29=(a29*a02);
  a29=(a00*a29);
  a29=(a21*a29);
  a19=(a37*a19);
  a29=(a29+a19);
  a19=(a36*a02);
  a19=(a00*a19);
  a12=(a32*a19);
  a29=(a29+a12);
  a18=(a23*a02);
  a18=(a00*a18);
  a45=(a08*a18);
  a29=(a29+a45);
  a29=(-a29);
  if (res[1]!=0) res[1][21]=a29;
  a29=(a21*a19);
  a28=(a37*a28);
  a29=(a29+a28);
  a28=(a08*a44);
  a29=(a29-a28);
  a29=(-a29);
  if (res[1]!=0) res[1][22]=a29;
  a29=(a21*a18);
  a37=(a37*a42);
  a29=(a29+a37);
  a37=(a32*a44);
  a29=(a29+a37);
  a29=(-a29);
  if (res[1]!=0) res[1][23]=a29;
  if (res[1]!=0) res[1][24]=a20;
  if (res[1]!=0) res[1][25]=a20;
  if (res[1]!=0) res[1][26]=a20;
  a39=(a39*a02);
  a39=(a00*a39);
  a29=(a32*a39);
  a30=(a43*a30);
  a29=(a29+a30);
  a29=(a29+a28);
  a29=(-a29);
  if (res[1]!=0) res[1][27]=a29;
  a29=(a21*a39);
  a36=(2.*a36);
  a36=(a36*a02);
  a36=(a00*a36);
  a36=(a32*a36);
  a25=(a43*a25);
  a36=(a36+a25);
  a36=(a29+a36);
  a36=(a36+a45);
  a36=(-a36);
  if (res[1]!=0) res[1][28]=a36;
  a32=(a32*a18);
  a43=(a43*a14);
  a32=(a32+a43);
  a21=(a21*a44);
  a32=(a32-a21);
  a32=(-a32);
  if (res[1]!=0) res[1][29]=a32;
  if (res[1]!=0) res[1][30]=a20;
  if (res[1]!=0) res[1][31]=a20;
  if (res[1]!=0) res[1][32]=a20;
  a39=(a08*a39);
  a16=(a40*a16);
  a39=(a39+a16);
  a39=(a39-a37);
  a39=(-a39);
  if (res[1]!=0) res[1][33]=a39;
  a19=(a08*a19);
  a26=(a40*a26);
  a19=(a19+a26);
  a21=(a21+a19);
  a21=(-a21);
  if (res[1]!=0) res[1][34]=a21;
  a29=(a29+a12);
  a23=(2.*a23);
  a23=(a23*a02);
  a00=(a00*a23);
  a08=(a08*a00);
  a40=(a40*a01);
  a08=(a08+a40);
  a29=(a29+a08);
  a29=(-a29);
  if (res[1]!=0) res[1][35]=a29;
  return 0;
}

CASADI_SYMBOL_EXPORT int residual_jacobian(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f1(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int residual_jacobian_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void residual_jacobian_release(int mem) {
}

CASADI_SYMBOL_EXPORT void residual_jacobian_incref(void) {
}

CASADI_SYMBOL_EXPORT void residual_jacobian_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int residual_jacobian_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int residual_jacobian_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real residual_jacobian_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* residual_jacobian_name_in(casadi_int i) {
  switch (i) {
    case 0: return "z";
    case 1: return "g";
    case 2: return "p";
    case 3: return "h";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* residual_jacobian_name_out(casadi_int i) {
  switch (i) {
    case 0: return "F";
    case 1: return "J";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* residual_jacobian_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s0;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* residual_jacobian_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int residual_jacobian_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int residual_jacobian_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* update:(z[6],g[36],p[6],h)->(g1[36],p1[6]) */
static int casadi_f2(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69;
  a00=arg[1]? arg[1][0] : 0;
  a01=1.;
  a02=4.;
  a03=arg[3]? arg[3][0] : 0;
  a04=arg[0]? arg[0][0] : 0;
  a05=(a03*a04);
  a06=casadi_sq(a05);
  a07=arg[0]? arg[0][1] : 0;
  a08=(a03*a07);
  a09=casadi_sq(a08);
  a10=(a06+a09);
  a11=arg[0]? arg[0][2] : 0;
  a12=(a03*a11);
  a13=casadi_sq(a12);
  a10=(a10+a13);
  a10=(a02+a10);
  a10=(a02/a10);
  a14=(a13+a09);
  a15=2.;
  a14=(a14/a15);
  a14=(a10*a14);
  a14=(a01-a14);
  a16=(a00*a14);
  a17=arg[1]? arg[1][6] : 0;
  a18=(a05*a08);
  a19=(a18/a15);
  a19=(a12+a19);
  a19=(a10*a19);
  a20=(a17*a19);
  a16=(a16+a20);
  a20=arg[1]? arg[1][12] : 0;
  a21=(a05*a12);
  a22=(a21/a15);
  a22=(a22-a08);
  a22=(a10*a22);
  a23=(a20*a22);
  a16=(a16+a23);
  if (res[0]!=0) res[0][0]=a16;
  a23=arg[1]? arg[1][1] : 0;
  a24=(a23*a14);
  a25=arg[1]? arg[1][7] : 0;
  a26=(a25*a19);
  a24=(a24+a26);
  a26=arg[1]? arg[1][13] : 0;
  a27=(a26*a22);
  a24=(a24+a27);
  if (res[0]!=0) res[0][1]=a24;
  a27=arg[1]? arg[1][2] : 0;
  a28=(a27*a14);
  a29=arg[1]? arg[1][8] : 0;
  a30=(a29*a19);
  a28=(a28+a30);
  a30=arg[1]? arg[1][14] : 0;
  a31=(a30*a22);
  a28=(a28+a31);
  if (res[0]!=0) res[0][2]=a28;
  a31=arg[1]? arg[1][3] : 0;
  a32=(a31*a14);
  a33=arg[1]? arg[1][9] : 0;
  a34=(a33*a19);
  a32=(a32+a34);
  a34=arg[1]? arg[1][15] : 0;
  a35=(a34*a22);
  a32=(a32+a35);
  if (res[0]!=0) res[0][3]=a32;
  a32=arg[1]? arg[1][4] : 0;
  a35=(a32*a14);
  a36=arg[1]? arg[1][10] : 0;
  a37=(a36*a19);
  a35=(a35+a37);
  a37=arg[1]? arg[1][16] : 0;
  a38=(a37*a22);
  a35=(a35+a38);
  if (res[0]!=0) res[0][4]=a35;
  a35=arg[1]? arg[1][5] : 0;
  a14=(a35*a14);
  a38=arg[1]? arg[1][11] : 0;
  a19=(a38*a19);
  a14=(a14+a19);
  a19=arg[1]? arg[1][17] : 0;
  a22=(a19*a22);
  a14=(a14+a22);
  if (res[0]!=0) res[0][5]=a14;
  a14=(a08*a05);
  a22=(a14/a15);
  a22=(a22-a12);
  a22=(a10*a22);
  a39=(a00*a22);
  a40=(a13+a06);
  a40=(a40/a15);
  a40=(a10*a40);
  a40=(a01-a40);
  a41=(a17*a40);
  a39=(a39+a41);
  a41=(a08*a12);
  a42=(a41/a15);
  a42=(a05+a42);
  a42=(a10*a42);
  a43=(a20*a42);
  a39=(a39+a43);
  if (res[0]!=0) res[0][6]=a39;
  a43=(a23*a22);
  a44=(a25*a40);
  a43=(a43+a44);
  a44=(a26*a42);
  a43=(a43+a44);
  if (res[0]!=0) res[0][7]=a43;
  a44=(a27*a22);
  a45=(a29*a40);
  a44=(a44+a45);
  a45=(a30*a42);
  a44=(a44+a45);
  if (res[0]!=0) res[0][8]=a44;
  a45=(a31*a22);
  a46=(a33*a40);
  a45=(a45+a46);
  a46=(a34*a42);
  a45=(a45+a46);
  if (res[0]!=0) res[0][9]=a45;
  a45=(a32*a22);
  a46=(a36*a40);
  a45=(a45+a46);
  a46=(a37*a42);
  a45=(a45+a46);
  if (res[0]!=0) res[0][10]=a45;
  a22=(a35*a22);
  a40=(a38*a40);
  a22=(a22+a40);
  a42=(a19*a42);
  a22=(a22+a42);
  if (res[0]!=0) res[0][11]=a22;
  a22=(a12*a05);
  a42=(a22/a15);
  a42=(a08+a42);
  a42=(a10*a42);
  a00=(a00*a42);
  a40=(a12*a08);
  a45=(a40/a15);
  a45=(a45-a05);
  a45=(a10*a45);
  a17=(a17*a45);
  a00=(a00+a17);
  a17=(a09+a06);
  a17=(a17/a15);
  a10=(a10*a17);
  a10=(a01-a10);
  a20=(a20*a10);
  a00=(a00+a20);
  if (res[0]!=0) res[0][12]=a00;
  a23=(a23*a42);
  a25=(a25*a45);
  a23=(a23+a25);
  a26=(a26*a10);
  a23=(a23+a26);
  if (res[0]!=0) res[0][13]=a23;
  a27=(a27*a42);
  a29=(a29*a45);
  a27=(a27+a29);
  a30=(a30*a10);
  a27=(a27+a30);
  if (res[0]!=0) res[0][14]=a27;
  a31=(a31*a42);
  a33=(a33*a45);
  a31=(a31+a33);
  a34=(a34*a10);
  a31=(a31+a34);
  if (res[0]!=0) res[0][15]=a31;
  a32=(a32*a42);
  a36=(a36*a45);
  a32=(a32+a36);
  a37=(a37*a10);
  a32=(a32+a37);
  if (res[0]!=0) res[0][16]=a32;
  a35=(a35*a42);
  a38=(a38*a45);
  a35=(a35+a38);
  a19=(a19*a10);
  a35=(a35+a19);
  if (res[0]!=0) res[0][17]=a35;
  a35=arg[1]? arg[1][18] : 0;
  a19=arg[0]? arg[0][3] : 0;
  a10=(a03*a19);
  a38=casadi_sq(a10);
  a45=arg[0]? arg[0][4] : 0;
  a42=(a03*a45);
  a32=casadi_sq(a42);
  a37=(a38+a32);
  a36=arg[0]? arg[0][5] : 0;
  a31=(a03*a36);
  a34=casadi_sq(a31);
  a37=(a37+a34);
  a37=(a02+a37);
  a37=(a02/a37);
  a33=(a34+a32);
  a33=(a33/a15);
  a33=(a37*a33);
  a33=(a01-a33);
  a30=(a35*a33);
  a29=arg[1]? arg[1][24] : 0;
  a26=(a10*a42);
  a25=(a26/a15);
  a25=(a31+a25);
  a25=(a37*a25);
  a20=(a29*a25);
  a30=(a30+a20);
  a20=arg[1]? arg[1][30] : 0;
  a17=(a10*a31);
  a46=(a17/a15);
  a46=(a46-a42);
  a46=(a37*a46);
  a47=(a20*a46);
  a30=(a30+a47);
  if (res[0]!=0) res[0][18]=a30;
  a30=arg[1]? arg[1][19] : 0;
  a47=(a30*a33);
  a48=arg[1]? arg[1][25] : 0;
  a49=(a48*a25);
  a47=(a47+a49);
  a49=arg[1]? arg[1][31] : 0;
  a50=(a49*a46);
  a47=(a47+a50);
  if (res[0]!=0) res[0][19]=a47;
  a47=arg[1]? arg[1][20] : 0;
  a50=(a47*a33);
  a51=arg[1]? arg[1][26] : 0;
  a52=(a51*a25);
  a50=(a50+a52);
  a52=arg[1]? arg[1][32] : 0;
  a53=(a52*a46);
  a50=(a50+a53);
  if (res[0]!=0) res[0][20]=a50;
  a50=arg[1]? arg[1][21] : 0;
  a53=(a50*a33);
  a54=arg[1]? arg[1][27] : 0;
  a55=(a54*a25);
  a53=(a53+a55);
  a55=arg[1]? arg[1][33] : 0;
  a56=(a55*a46);
  a53=(a53+a56);
  if (res[0]!=0) res[0][21]=a53;
  a56=arg[1]? arg[1][22] : 0;
  a57=(a56*a33);
  a58=arg[1]? arg[1][28] : 0;
  a59=(a58*a25);
  a57=(a57+a59);
  a59=arg[1]? arg[1][34] : 0;
  a60=(a59*a46);
  a57=(a57+a60);
  if (res[0]!=0) res[0][22]=a57;
  a60=arg[1]? arg[1][23] : 0;
  a33=(a60*a33);
  a61=arg[1]? arg[1][29] : 0;
  a25=(a61*a25);
  a33=(a33+a25);
  a25=arg[1]? arg[1][35] : 0;
  a46=(a25*a46);
  a33=(a33+a46);
  if (res[0]!=0) res[0][23]=a33;
  a46=(a42*a10);
  a62=(a46/a15);
  a62=(a62-a31);
  a62=(a37*a62);
  a63=(a35*a62);
  a64=(a34+a38);
  a64=(a64/a15);
  a64=(a37*a64);
  a64=(a01-a64);
  a65=(a29*a64);
  a63=(a63+a65);
  a65=(a42*a31);
  a66=(a65/a15);
  a66=(a10+a66);
  a66=(a37*a66);
  a67=(a20*a66);
  a63=(a63+a67);
  if (res[0]!=0) res[0][24]=a63;
  a63=(a30*a62);
  a67=(a48*a64);
  a63=(a63+a67);
  a67=(a49*a66);
  a63=(a63+a67);
  if (res[0]!=0) res[0][25]=a63;
  a63=(a47*a62);
  a67=(a51*a64);
  a63=(a63+a67);
  a67=(a52*a66);
  a63=(a63+a67);
  if (res[0]!=0) res[0][26]=a63;
  a63=(a50*a62);
  a67=(a54*a64);
  a63=(a63+a67);
  a67=(a55*a66);
  a63=(a63+a67);
  if (res[0]!=0) res[0][27]=a63;
  a67=(a56*a62);
  a68=(a58*a64);
  a67=(a67+a68);
  a68=(a59*a66);
  a67=(a67+a68);
  if (res[0]!=0) res[0][28]=a67;
  a62=(a60*a62);
  a64=(a61*a64);
  a62=(a62+a64);
  a66=(a25*a66);
  a62=(a62+a66);
  if (res[0]!=0) res[0][29]=a62;
  a66=(a31*a10);
  a64=(a66/a15);
  a64=(a42+a64);
  a64=(a37*a64);
  a35=(a35*a64);
  a68=(a31*a42);
  a69=(a68/a15);
  a69=(a69-a10);
  a69=(a37*a69);
  a29=(a29*a69);
  a35=(a35+a29);
  a29=(a32+a38);
  a29=(a29/a15);
  a37=(a37*a29);
  a37=(a01-a37);
  a20=(a20*a37);
  a35=(a35+a20);
  if (res[0]!=0) res[0][30]=a35;
  a30=(a30*a64);
  a48=(a48*a69);
  a30=(a30+a48);
  a49=(a49*a37);
  a30=(a30+a49);
  if (res[0]!=0) res[0][31]=a30;
  a47=(a47*a64);
  a51=(a51*a69);
  a47=(a47+a51);
  a52=(a52*a37);
  a47=(a47+a52);
  if (res[0]!=0) res[0][32]=a47;
  a50=(a50*a64);
  a54=(a54*a69);
  a50=(a50+a54);
  a55=(a55*a37);
  a50=(a50+a55);
  if (res[0]!=0) res[0][33]=a50;
  a56=(a56*a64);
  a58=(a58*a69);
  a56=(a56+a58);
  a59=(a59*a37);
  a56=(a56+a59);
  if (res[0]!=0) res[0][34]=a56;
  a60=(a60*a64);
  a61=(a61*a69);
  a60=(a60+a61);
  a25=(a25*a37);
  a60=(a60+a25);
  if (res[0]!=0) res[0][35]=a60;
  a06=(a06/a02);
  a06=(a01+a06);
  a25=9.0000000000000002e-01;
  a25=(a25*a04);
  a06=(a06*a25);
  a12=(a12/a15);
  a14=(a14/a02);
  a14=(a12+a14);
  a14=(a14*a07);
  a06=(a06+a14);
  a22=(a22/a02);
  a08=(a08/a15);
  a22=(a22-a08);
  a14=2.0000000000000001e-01;
  a14=(a14*a11);
  a22=(a22*a14);
  a06=(a06+a22);
  a22=5.0000000000000003e-02;
  a11=1.3000000000000000e+00;
  a04=(a22*a44);
  a11=(a11+a04);
  a04=1.0000000000000001e-01;
  a37=(a04*a28);
  a11=(a11+a37);
  a11=(a11-a27);
  a37=-1.0000000000000001e-01;
  a61=(a37*a62);
  a11=(a11+a61);
  a61=-2.9999999999999999e-01;
  a69=(a61*a60);
  a11=(a11+a69);
  a11=(2.*a11);
  a11=(a11*a03);
  a69=(a22*a11);
  a64=(a27*a69);
  a59=(a22*a43);
  a58=(a04*a24);
  a59=(a59+a58);
  a59=(a59-a23);
  a58=(a37*a67);
  a59=(a59+a58);
  a58=(a61*a56);
  a59=(a59+a58);
  a59=(2.*a59);
  a59=(a59*a03);
  a58=(a43*a59);
  a64=(a64+a58);
  a58=(a22*a59);
  a55=(a23*a58);
  a64=(a64+a55);
  a55=(a22*a39);
  a54=(a04*a16);
  a55=(a55+a54);
  a55=(a55-a00);
  a54=(a37*a63);
  a55=(a55+a54);
  a54=(a61*a50);
  a55=(a55+a54);
  a55=(2.*a55);
  a55=(a55*a03);
  a54=(a39*a55);
  a64=(a64+a54);
  a22=(a22*a55);
  a54=(a00*a22);
  a64=(a64+a54);
  a54=5.0000000000000000e-01;
  a47=(a54*a03);
  a47=(a11+a47);
  a52=(a44*a47);
  a64=(a64+a52);
  a06=(a06-a64);
  if (res[1]!=0) res[1][0]=a06;
  a18=(a18/a02);
  a18=(a18-a12);
  a18=(a18*a25);
  a09=(a09/a02);
  a09=(a01+a09);
  a09=(a09*a07);
  a18=(a18+a09);
  a05=(a05/a15);
  a40=(a40/a02);
  a40=(a05+a40);
  a40=(a40*a14);
  a18=(a18+a40);
  a40=(a24*a59);
  a09=-5.0000000000000003e-02;
  a09=(a09*a03);
  a12=(a04*a11);
  a09=(a09-a12);
  a27=(a27*a09);
  a40=(a40-a27);
  a27=(a04*a59);
  a23=(a23*a27);
  a40=(a40+a23);
  a23=(a16*a55);
  a40=(a40+a23);
  a04=(a04*a55);
  a00=(a00*a04);
  a40=(a40+a00);
  a47=(a28*a47);
  a40=(a40+a47);
  a18=(a18+a40);
  if (res[1]!=0) res[1][1]=a18;
  a21=(a21/a02);
  a08=(a08+a21);
  a08=(a08*a25);
  a41=(a41/a02);
  a41=(a41-a05);
  a41=(a41*a07);
  a08=(a08+a41);
  a13=(a13/a02);
  a13=(a01+a13);
  a13=(a13*a14);
  a08=(a08+a13);
  a44=(a44*a09);
  a28=(a28*a69);
  a44=(a44+a28);
  a43=(a43*a27);
  a44=(a44-a43);
  a24=(a24*a58);
  a44=(a44+a24);
  a39=(a39*a04);
  a44=(a44-a39);
  a16=(a16*a22);
  a44=(a44+a16);
  a08=(a08+a44);
  if (res[1]!=0) res[1][2]=a08;
  a38=(a38/a02);
  a38=(a01+a38);
  a08=5.9999999999999998e-01;
  a08=(a08*a19);
  a38=(a38*a08);
  a31=(a31/a15);
  a46=(a46/a02);
  a46=(a31+a46);
  a54=(a54*a45);
  a46=(a46*a54);
  a38=(a38+a46);
  a66=(a66/a02);
  a42=(a42/a15);
  a66=(a66-a42);
  a46=1.4999999999999999e-01;
  a46=(a46*a36);
  a66=(a66*a46);
  a38=(a38+a66);
  a66=-2.9999999999999999e-02;
  a66=(a66*a03);
  a36=(a37*a11);
  a66=(a66-a36);
  a60=(a60*a66);
  a36=(a61*a59);
  a67=(a67*a36);
  a60=(a60+a67);
  a59=(a37*a59);
  a56=(a56*a59);
  a60=(a60-a56);
  a56=(a61*a55);
  a63=(a63*a56);
  a60=(a60+a63);
  a37=(a37*a55);
  a50=(a50*a37);
  a60=(a60-a50);
  a50=3.0000000000000004e-01;
  a50=(a50*a03);
  a61=(a61*a11);
  a50=(a50-a61);
  a62=(a62*a50);
  a60=(a60-a62);
  a38=(a38+a60);
  if (res[1]!=0) res[1][3]=a38;
  a26=(a26/a02);
  a26=(a26-a31);
  a26=(a26*a08);
  a32=(a32/a02);
  a32=(a01+a32);
  a32=(a32*a54);
  a26=(a26+a32);
  a10=(a10/a15);
  a68=(a68/a02);
  a68=(a10+a68);
  a68=(a68*a46);
  a26=(a26+a68);
  a50=(a33*a50);
  a36=(a57*a36);
  a56=(a53*a56);
  a36=(a36+a56);
  a50=(a50-a36);
  a26=(a26+a50);
  if (res[1]!=0) res[1][4]=a26;
  a17=(a17/a02);
  a42=(a42+a17);
  a42=(a42*a08);
  a65=(a65/a02);
  a65=(a65-a10);
  a65=(a65*a54);
  a42=(a42+a65);
  a34=(a34/a02);
  a01=(a01+a34);
  a01=(a01*a46);
  a42=(a42+a01);
  a57=(a57*a59);
  a33=(a33*a66);
  a57=(a57-a33);
  a53=(a53*a37);
  a57=(a57+a53);
  a42=(a42+a57);
  if (res[1]!=0) res[1][5]=a42;
  return 0;
}

CASADI_SYMBOL_EXPORT int update(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f2(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int update_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void update_release(int mem) {
}

CASADI_SYMBOL_EXPORT void update_incref(void) {
}

CASADI_SYMBOL_EXPORT void update_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int update_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int update_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real update_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* update_name_in(casadi_int i) {
  switch (i) {
    case 0: return "z";
    case 1: return "g";
    case 2: return "p";
    case 3: return "h";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* update_name_out(casadi_int i) {
  switch (i) {
    case 0: return "g1";
    case 1: return "p1";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* update_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s0;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* update_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    case 1: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int update_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int update_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* guess:(xi[6],g[36],p[6],h)->(z0[6]) */
static int casadi_f3(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0;
  a0=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a0;
  a0=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a0;
  a0=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a0;
  a0=arg[0]? arg[0][3] : 0;
  if (res[0]!=0) res[0][3]=a0;
  a0=arg[0]? arg[0][4] : 0;
  if (res[0]!=0) res[0][4]=a0;
  a0=arg[0]? arg[0][5] : 0;
  if (res[0]!=0) res[0][5]=a0;
  return 0;
}

CASADI_SYMBOL_EXPORT int guess(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f3(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int guess_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void guess_release(int mem) {
}

CASADI_SYMBOL_EXPORT void guess_incref(void) {
}

CASADI_SYMBOL_EXPORT void guess_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int guess_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int guess_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real guess_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* guess_name_in(casadi_int i) {
  switch (i) {
    case 0: return "xi";
    case 1: return "g";
    case 2: return "p";
    case 3: return "h";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* guess_name_out(casadi_int i) {
  switch (i) {
    case 0: return "z0";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* guess_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s0;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* guess_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int guess_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int guess_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* legendre:(g[36],xi[6])->(mu[6]) */
static int casadi_f4(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1;
  a0=9.0000000000000002e-01;
  a1=arg[1]? arg[1][0] : 0;
  a0=(a0*a1);
  if (res[0]!=0) res[0][0]=a0;
  a0=arg[1]? arg[1][1] : 0;
  if (res[0]!=0) res[0][1]=a0;
  a0=2.0000000000000001e-01;
  a1=arg[1]? arg[1][2] : 0;
  a0=(a0*a1);
  if (res[0]!=0) res[0][2]=a0;
  a0=5.9999999999999998e-01;
  a1=arg[1]? arg[1][3] : 0;
  a0=(a0*a1);
  if (res[0]!=0) res[0][3]=a0;
  a0=5.0000000000000000e-01;
  a1=arg[1]? arg[1][4] : 0;
  a0=(a0*a1);
  if (res[0]!=0) res[0][4]=a0;
  a0=1.4999999999999999e-01;
  a1=arg[1]? arg[1][5] : 0;
  a0=(a0*a1);
  if (res[0]!=0) res[0][5]=a0;
  return 0;
}

CASADI_SYMBOL_EXPORT int legendre(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f4(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int legendre_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void legendre_release(int mem) {
}

CASADI_SYMBOL_EXPORT void legendre_incref(void) {
}

CASADI_SYMBOL_EXPORT void legendre_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int legendre_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int legendre_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real legendre_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* legendre_name_in(casadi_int i) {
  switch (i) {
    case 0: return "g";
    case 1: return "xi";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* legendre_name_out(casadi_int i) {
  switch (i) {
    case 0: return "mu";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* legendre_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    case 1: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* legendre_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int legendre_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int legendre_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* hessian:(g[36],xi[6])->(H[36]) */
static int casadi_f5(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1;
  a0=9.0000000000000002e-01;
  if (res[0]!=0) res[0][0]=a0;
  a0=0.;
  if (res[0]!=0) res[0][1]=a0;
  if (res[0]!=0) res[0][2]=a0;
  if (res[0]!=0) res[0][3]=a0;
  if (res[0]!=0) res[0][4]=a0;
  if (res[0]!=0) res[0][5]=a0;
  if (res[0]!=0) res[0][6]=a0;
  a1=1.;
  if (res[0]!=0) res[0][7]=a1;
  if (res[0]!=0) res[0][8]=a0;
  if (res[0]!=0) res[0][9]=a0;
  if (res[0]!=0) res[0][10]=a0;
  if (res[0]!=0) res[0][11]=a0;
  if (res[0]!=0) res[0][12]=a0;
  if (res[0]!=0) res[0][13]=a0;
  a1=2.0000000000000001e-01;
  if (res[0]!=0) res[0][14]=a1;
  if (res[0]!=0) res[0][15]=a0;
  if (res[0]!=0) res[0][16]=a0;
  if (res[0]!=0) res[0][17]=a0;
  if (res[0]!=0) res[0][18]=a0;
  if (res[0]!=0) res[0][19]=a0;
  if (res[0]!=0) res[0][20]=a0;
  a1=5.9999999999999998e-01;
  if (res[0]!=0) res[0][21]=a1;
  if (res[0]!=0) res[0][22]=a0;
  if (res[0]!=0) res[0][23]=a0;
  if (res[0]!=0) res[0][24]=a0;
  if (res[0]!=0) res[0][25]=a0;
  if (res[0]!=0) res[0][26]=a0;
  if (res[0]!=0) res[0][27]=a0;
  a1=5.0000000000000000e-01;
  if (res[0]!=0) res[0][28]=a1;
  if (res[0]!=0) res[0][29]=a0;
  if (res[0]!=0) res[0][30]=a0;
  if (res[0]!=0) res[0][31]=a0;
  if (res[0]!=0) res[0][32]=a0;
  if (res[0]!=0) res[0][33]=a0;
  if (res[0]!=0) res[0][34]=a0;
  a0=1.4999999999999999e-01;
  if (res[0]!=0) res[0][35]=a0;
  return 0;
}

CASADI_SYMBOL_EXPORT int hessian(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f5(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int hessian_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void hessian_release(int mem) {
}

CASADI_SYMBOL_EXPORT void hessian_incref(void) {
}

CASADI_SYMBOL_EXPORT void hessian_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int hessian_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int hessian_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real hessian_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* hessian_name_in(casadi_int i) {
  switch (i) {
    case 0: return "g";
    case 1: return "xi";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* hessian_name_out(casadi_int i) {
  switch (i) {
    case 0: return "H";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* hessian_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    case 1: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* hessian_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int hessian_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int hessian_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* energy:(g[36],xi[6])->(E) */
static int casadi_f6(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10;
  a00=9.0000000000000002e-01;
  a01=arg[1]? arg[1][0] : 0;
  a00=(a00*a01);
  a00=(a00*a01);
  a02=arg[1]? arg[1][1] : 0;
  a02=casadi_sq(a02);
  a00=(a00+a02);
  a03=2.0000000000000001e-01;
  a04=arg[1]? arg[1][2] : 0;
  a03=(a03*a04);
  a03=(a03*a04);
  a00=(a00+a03);
  a03=5.9999999999999998e-01;
  a05=arg[1]? arg[1][3] : 0;
  a03=(a03*a05);
  a03=(a03*a05);
  a00=(a00+a03);
  a03=5.0000000000000000e-01;
  a06=arg[1]? arg[1][4] : 0;
  a07=(a03*a06);
  a07=(a07*a06);
  a00=(a00+a07);
  a07=1.4999999999999999e-01;
  a08=arg[1]? arg[1][5] : 0;
  a07=(a07*a08);
  a07=(a07*a08);
  a00=(a00+a07);
  a07=2.5000000000000000e-01;
  a06=casadi_sq(a06);
  a07=(a07*a06);
  a03=(a03*a02);
  a07=(a07+a03);
  a03=arg[0]? arg[0][14] : 0;
  a07=(a07+a03);
  a02=6.0000000000000009e-01;
  a06=arg[0]? arg[0][35] : 0;
  a02=(a02*a06);
  a07=(a07+a02);
  a02=1.0000000000000001e-01;
  a04=casadi_sq(a04);
  a04=(a02*a04);
  a07=(a07+a04);
  a04=7.4999999999999997e-02;
  a08=casadi_sq(a08);
  a04=(a04*a08);
  a07=(a07+a04);
  a04=2.9999999999999999e-01;
  a05=casadi_sq(a05);
  a04=(a04*a05);
  a07=(a07+a04);
  a04=4.5000000000000001e-01;
  a01=casadi_sq(a01);
  a04=(a04*a01);
  a07=(a07+a04);
  a04=-2.;
  a01=5.0000000000000003e-02;
  a05=arg[0]? arg[0][6] : 0;
  a05=(a01*a05);
  a08=arg[0]? arg[0][0] : 0;
  a08=(a02*a08);
  a05=(a05+a08);
  a08=arg[0]? arg[0][12] : 0;
  a05=(a05-a08);
  a08=-1.0000000000000001e-01;
  a09=arg[0]? arg[0][27] : 0;
  a09=(a08*a09);
  a05=(a05+a09);
  a09=-2.9999999999999999e-01;
  a10=arg[0]? arg[0][33] : 0;
  a10=(a09*a10);
  a05=(a05+a10);
  a05=casadi_sq(a05);
  a05=(a04*a05);
  a07=(a07+a05);
  a05=arg[0]? arg[0][7] : 0;
  a05=(a01*a05);
  a10=arg[0]? arg[0][1] : 0;
  a10=(a02*a10);
  a05=(a05+a10);
  a10=arg[0]? arg[0][13] : 0;
  a05=(a05-a10);
  a10=arg[0]? arg[0][28] : 0;
  a10=(a08*a10);
  a05=(a05+a10);
  a10=arg[0]? arg[0][34] : 0;
  a10=(a09*a10);
  a05=(a05+a10);
  a05=casadi_sq(a05);
  a05=(a04*a05);
  a07=(a07+a05);
  a05=1.3000000000000000e+00;
  a10=arg[0]? arg[0][8] : 0;
  a01=(a01*a10);
  a05=(a05+a01);
  a01=arg[0]? arg[0][2] : 0;
  a02=(a02*a01);
  a05=(a05+a02);
  a05=(a05-a03);
  a03=arg[0]? arg[0][29] : 0;
  a02=(a08*a03);
  a05=(a05+a02);
  a09=(a09*a06);
  a05=(a05+a09);
  a05=casadi_sq(a05);
  a04=(a04*a05);
  a07=(a07+a04);
  a04=-5.9999999999999998e-02;
  a04=(a04*a03);
  a07=(a07+a04);
  a08=(a08*a01);
  a07=(a07+a08);
  a00=(a00-a07);
  if (res[0]!=0) res[0][0]=a00;
  return 0;
}

CASADI_SYMBOL_EXPORT int energy(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f6(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int energy_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void energy_release(int mem) {
}

CASADI_SYMBOL_EXPORT void energy_incref(void) {
}

CASADI_SYMBOL_EXPORT void energy_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int energy_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int energy_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real energy_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* energy_name_in(casadi_int i) {
  switch (i) {
    case 0: return "g";
    case 1: return "xi";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* energy_name_out(casadi_int i) {
  switch (i) {
    case 0: return "E";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* energy_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    case 1: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* energy_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int energy_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int energy_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* momentum:(g[36],p[6])->(m[6]) */
static int casadi_f7(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13;
  a00=arg[0]? arg[0][14] : 0;
  a01=arg[0]? arg[0][7] : 0;
  a02=(a00*a01);
  a03=arg[0]? arg[0][13] : 0;
  a04=arg[0]? arg[0][8] : 0;
  a05=(a03*a04);
  a02=(a02-a05);
  a05=arg[1]? arg[1][0] : 0;
  a02=(a02*a05);
  a06=arg[0]? arg[0][2] : 0;
  a07=(a06*a03);
  a08=arg[0]? arg[0][1] : 0;
  a09=(a08*a00);
  a07=(a07-a09);
  a09=arg[1]? arg[1][1] : 0;
  a07=(a07*a09);
  a02=(a02+a07);
  a07=(a04*a08);
  a10=(a01*a06);
  a07=(a07-a10);
  a10=arg[1]? arg[1][2] : 0;
  a07=(a07*a10);
  a02=(a02+a07);
  if (res[0]!=0) res[0][0]=a02;
  a02=arg[0]? arg[0][12] : 0;
  a07=(a02*a04);
  a11=arg[0]? arg[0][6] : 0;
  a12=(a00*a11);
  a07=(a07-a12);
  a07=(a07*a05);
  a12=arg[0]? arg[0][0] : 0;
  a00=(a12*a00);
  a13=(a06*a02);
  a00=(a00-a13);
  a00=(a00*a09);
  a07=(a07+a00);
  a06=(a11*a06);
  a04=(a04*a12);
  a06=(a06-a04);
  a06=(a06*a10);
  a07=(a07+a06);
  if (res[0]!=0) res[0][1]=a07;
  a07=(a03*a11);
  a06=(a02*a01);
  a07=(a07-a06);
  a07=(a07*a05);
  a02=(a08*a02);
  a03=(a12*a03);
  a02=(a02-a03);
  a02=(a02*a09);
  a07=(a07+a02);
  a01=(a01*a12);
  a11=(a11*a08);
  a01=(a01-a11);
  a01=(a01*a10);
  a07=(a07+a01);
  if (res[0]!=0) res[0][2]=a07;
  a07=arg[0]? arg[0][35] : 0;
  a01=arg[0]? arg[0][28] : 0;
  a10=(a07*a01);
  a11=arg[0]? arg[0][34] : 0;
  a08=arg[0]? arg[0][29] : 0;
  a12=(a11*a08);
  a10=(a10-a12);
  a12=arg[1]? arg[1][3] : 0;
  a10=(a10*a12);
  a02=arg[0]? arg[0][23] : 0;
  a09=(a02*a11);
  a03=arg[0]? arg[0][22] : 0;
  a05=(a03*a07);
  a09=(a09-a05);
  a05=arg[1]? arg[1][4] : 0;
  a09=(a09*a05);
  a10=(a10+a09);
  a09=(a08*a03);
  a06=(a01*a02);
  a09=(a09-a06);
  a06=arg[1]? arg[1][5] : 0;
  a09=(a09*a06);
  a10=(a10+a09);
  if (res[0]!=0) res[0][3]=a10;
  a10=arg[0]? arg[0][33] : 0;
  a09=(a10*a08);
  a04=arg[0]? arg[0][27] : 0;
  a00=(a07*a04);
  a09=(a09-a00);
  a09=(a09*a12);
  a00=arg[0]? arg[0][21] : 0;
  a07=(a00*a07);
  a13=(a02*a10);
  a07=(a07-a13);
  a07=(a07*a05);
  a09=(a09+a07);
  a02=(a04*a02);
  a08=(a08*a00);
  a02=(a02-a08);
  a02=(a02*a06);
  a09=(a09+a02);
  if (res[0]!=0) res[0][4]=a09;
  a09=(a11*a04);
  a02=(a10*a01);
  a09=(a09-a02);
  a09=(a09*a12);
  a10=(a03*a10);
  a11=(a00*a11);
  a10=(a10-a11);
  a10=(a10*a05);
  a09=(a09+a10);
  a01=(a01*a00);
  a04=(a04*a03);
  a01=(a01-a04);
  a01=(a01*a06);
  a09=(a09+a01);
  if (res[0]!=0) res[0][5]=a09;
  return 0;
}

CASADI_SYMBOL_EXPORT int momentum(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f7(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int momentum_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void momentum_release(int mem) {
}

CASADI_SYMBOL_EXPORT void momentum_incref(void) {
}

CASADI_SYMBOL_EXPORT void momentum_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int momentum_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int momentum_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real momentum_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* momentum_name_in(casadi_int i) {
  switch (i) {
    case 0: return "g";
    case 1: return "p";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* momentum_name_out(casadi_int i) {
  switch (i) {
    case 0: return "m";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* momentum_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    case 1: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* momentum_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int momentum_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int momentum_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* defect:(g[36])->(e) */
static int casadi_f8(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13;
  a00=0.;
  a01=arg[0]? arg[0][3] : 0;
  a01=casadi_fabs(a01);
  a01=casadi_fmax(a00,a01);
  a02=arg[0]? arg[0][4] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a02=arg[0]? arg[0][5] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a01=casadi_fmax(a01,a00);
  a01=casadi_fmax(a01,a00);
  a01=casadi_fmax(a01,a00);
  a02=arg[0]? arg[0][9] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a02=arg[0]? arg[0][10] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a02=arg[0]? arg[0][11] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a01=casadi_fmax(a01,a00);
  a01=casadi_fmax(a01,a00);
  a01=casadi_fmax(a01,a00);
  a02=arg[0]? arg[0][15] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a02=arg[0]? arg[0][16] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a02=arg[0]? arg[0][17] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a02=arg[0]? arg[0][18] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a02=arg[0]? arg[0][19] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a02=arg[0]? arg[0][20] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a01=casadi_fmax(a01,a00);
  a01=casadi_fmax(a01,a00);
  a01=casadi_fmax(a01,a00);
  a02=arg[0]? arg[0][24] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a02=arg[0]? arg[0][25] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a02=arg[0]? arg[0][26] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a01=casadi_fmax(a01,a00);
  a01=casadi_fmax(a01,a00);
  a01=casadi_fmax(a01,a00);
  a02=arg[0]? arg[0][30] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a02=arg[0]? arg[0][31] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a02=arg[0]? arg[0][32] : 0;
  a02=casadi_fabs(a02);
  a01=casadi_fmax(a01,a02);
  a01=casadi_fmax(a01,a00);
  a01=casadi_fmax(a01,a00);
  a01=casadi_fmax(a01,a00);
  a00=arg[0]? arg[0][0] : 0;
  a02=casadi_sq(a00);
  a03=arg[0]? arg[0][1] : 0;
  a04=casadi_sq(a03);
  a02=(a02+a04);
  a04=arg[0]? arg[0][2] : 0;
  a05=casadi_sq(a04);
  a02=(a02+a05);
  a05=1.;
  a02=(a02-a05);
  a02=casadi_fabs(a02);
  a06=arg[0]? arg[0][6] : 0;
  a07=(a06*a00);
  a08=arg[0]? arg[0][7] : 0;
  a09=(a08*a03);
  a07=(a07+a09);
  a09=arg[0]? arg[0][8] : 0;
  a10=(a09*a04);
  a07=(a07+a10);
  a07=casadi_fabs(a07);
  a02=casadi_fmax(a02,a07);
  a07=arg[0]? arg[0][12] : 0;
  a10=(a07*a00);
  a11=arg[0]? arg[0][13] : 0;
  a12=(a11*a03);
  a10=(a10+a12);
  a12=arg[0]? arg[0][14] : 0;
  a13=(a12*a04);
  a10=(a10+a13);
  a10=casadi_fabs(a10);
  a02=casadi_fmax(a02,a10);
  a10=(a00*a06);
  a13=(a03*a08);
  a10=(a10+a13);
  a13=(a04*a09);
  a10=(a10+a13);
  a10=casadi_fabs(a10);
  a02=casadi_fmax(a02,a10);
  a10=casadi_sq(a06);
  a13=casadi_sq(a08);
  a10=(a10+a13);
  a13=casadi_sq(a09);
  a10=(a10+a13);
  a10=(a10-a05);
  a10=casadi_fabs(a10);
  a02=casadi_fmax(a02,a10);
  a10=(a07*a06);
  a13=(a11*a08);
  a10=(a10+a13);
  a13=(a12*a09);
  a10=(a10+a13);
  a10=casadi_fabs(a10);
  a02=casadi_fmax(a02,a10);
  a10=(a00*a07);
  a13=(a03*a11);
  a10=(a10+a13);
  a13=(a04*a12);
  a10=(a10+a13);
  a10=casadi_fabs(a10);
  a02=casadi_fmax(a02,a10);
  a10=(a06*a07);
  a13=(a08*a11);
  a10=(a10+a13);
  a13=(a09*a12);
  a10=(a10+a13);
  a10=casadi_fabs(a10);
  a02=casadi_fmax(a02,a10);
  a10=casadi_sq(a07);
  a13=casadi_sq(a11);
  a10=(a10+a13);
  a13=casadi_sq(a12);
  a10=(a10+a13);
  a10=(a10-a05);
  a10=casadi_fabs(a10);
  a02=casadi_fmax(a02,a10);
  a10=(a08*a12);
  a13=(a11*a09);
  a10=(a10-a13);
  a00=(a00*a10);
  a12=(a03*a12);
  a11=(a11*a04);
  a12=(a12-a11);
  a06=(a06*a12);
  a00=(a00-a06);
  a03=(a03*a09);
  a08=(a08*a04);
  a03=(a03-a08);
  a07=(a07*a03);
  a00=(a00+a07);
  a00=(a00-a05);
  a00=casadi_fabs(a00);
  a02=casadi_fmax(a02,a00);
  a01=casadi_fmax(a01,a02);
  a02=arg[0]? arg[0][21] : 0;
  a00=casadi_sq(a02);
  a07=arg[0]? arg[0][22] : 0;
  a03=casadi_sq(a07);
  a00=(a00+a03);
  a03=arg[0]? arg[0][23] : 0;
  a08=casadi_sq(a03);
  a00=(a00+a08);
  a00=(a00-a05);
  a00=casadi_fabs(a00);
  a08=arg[0]? arg[0][27] : 0;
  a04=(a08*a02);
  a09=arg[0]? arg[0][28] : 0;
  a06=(a09*a07);
  a04=(a04+a06);
  a06=arg[0]? arg[0][29] : 0;
  a12=(a06*a03);
  a04=(a04+a12);
  a04=casadi_fabs(a04);
  a00=casadi_fmax(a00,a04);
  a04=arg[0]? arg[0][33] : 0;
  a12=(a04*a02);
  a11=arg[0]? arg[0][34] : 0;
  a10=(a11*a07);
  a12=(a12+a10);
  a10=arg[0]? arg[0][35] : 0;
  a13=(a10*a03);
  a12=(a12+a13);
  a12=casadi_fabs(a12);
  a00=casadi_fmax(a00,a12);
  a12=(a02*a08);
  a13=(a07*a09);
  a12=(a12+a13);
  a13=(a03*a06);
  a12=(a12+a13);
  a12=casadi_fabs(a12);
  a00=casadi_fmax(a00,a12);
  a12=casadi_sq(a08);
  a13=casadi_sq(a09);
  a12=(a12+a13);
  a13=casadi_sq(a06);
  a12=(a12+a13);
  a12=(a12-a05);
  a12=casadi_fabs(a12);
  a00=casadi_fmax(a00,a12);
  a12=(a04*a08);
  a13=(a11*a09);
  a12=(a12+a13);
  a13=(a10*a06);
  a12=(a12+a13);
  a12=casadi_fabs(a12);
  a00=casadi_fmax(a00,a12);
  a12=(a02*a04);
  a13=(a07*a11);
  a12=(a12+a13);
  a13=(a03*a10);
  a12=(a12+a13);
  a12=casadi_fabs(a12);
  a00=casadi_fmax(a00,a12);
  a12=(a08*a04);
  a13=(a09*a11);
  a12=(a12+a13);
  a13=(a06*a10);
  a12=(a12+a13);
  a12=casadi_fabs(a12);
  a00=casadi_fmax(a00,a12);
  a12=casadi_sq(a04);
  a13=casadi_sq(a11);
  a12=(a12+a13);
  a13=casadi_sq(a10);
  a12=(a12+a13);
  a12=(a12-a05);
  a12=casadi_fabs(a12);
  a00=casadi_fmax(a00,a12);
  a12=(a09*a10);
  a13=(a11*a06);
  a12=(a12-a13);
  a02=(a02*a12);
  a10=(a07*a10);
  a11=(a11*a03);
  a10=(a10-a11);
  a08=(a08*a10);
  a02=(a02-a08);
  a07=(a07*a06);
  a09=(a09*a03);
  a07=(a07-a09);
  a04=(a04*a07);
  a02=(a02+a04);
  a02=(a02-a05);
  a02=casadi_fabs(a02);
  a00=casadi_fmax(a00,a02);
  a01=casadi_fmax(a01,a00);
  if (res[0]!=0) res[0][0]=a01;
  return 0;
}

CASADI_SYMBOL_EXPORT int defect(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f8(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int defect_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void defect_release(int mem) {
}

CASADI_SYMBOL_EXPORT void defect_incref(void) {
}

CASADI_SYMBOL_EXPORT void defect_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int defect_n_in(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_int defect_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real defect_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* defect_name_in(casadi_int i) {
  switch (i) {
    case 0: return "g";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* defect_name_out(casadi_int i) {
  switch (i) {
    case 0: return "e";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* defect_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* defect_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int defect_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 1;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int defect_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 1*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* margin:(z[6],h)->(m) */
static int casadi_f9(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4, a5;
  a0=1.;
  a1=4.;
  a2=arg[1]? arg[1][0] : 0;
  a3=arg[0]? arg[0][0] : 0;
  a3=(a2*a3);
  a3=casadi_sq(a3);
  a4=arg[0]? arg[0][1] : 0;
  a4=(a2*a4);
  a4=casadi_sq(a4);
  a3=(a3+a4);
  a4=arg[0]? arg[0][2] : 0;
  a4=(a2*a4);
  a4=casadi_sq(a4);
  a3=(a3+a4);
  a3=(a1-a3);
  a3=casadi_fmin(a0,a3);
  a4=arg[0]? arg[0][3] : 0;
  a4=(a2*a4);
  a4=casadi_sq(a4);
  a5=arg[0]? arg[0][4] : 0;
  a5=(a2*a5);
  a5=casadi_sq(a5);
  a4=(a4+a5);
  a5=arg[0]? arg[0][5] : 0;
  a2=(a2*a5);
  a2=casadi_sq(a2);
  a4=(a4+a2);
  a1=(a1-a4);
  a3=casadi_fmin(a3,a1);
  a0=casadi_fmin(a0,a3);
  a0=casadi_fmin(a0,a3);
  a0=casadi_fmin(a0,a3);
  a0=casadi_fmin(a0,a3);
  if (res[0]!=0) res[0][0]=a0;
  return 0;
}

CASADI_SYMBOL_EXPORT int margin(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f9(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int margin_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void margin_release(int mem) {
}

CASADI_SYMBOL_EXPORT void margin_incref(void) {
}

CASADI_SYMBOL_EXPORT void margin_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int margin_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int margin_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real margin_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* margin_name_in(casadi_int i) {
  switch (i) {
    case 0: return "z";
    case 1: return "h";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* margin_name_out(casadi_int i) {
  switch (i) {
    case 0: return "m";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* margin_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* margin_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int margin_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int margin_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* section:(g[36],p[6])->(s) */
static int casadi_f10(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0;
  a0=1.;
  if (res[0]!=0) res[0][0]=a0;
  return 0;
}

CASADI_SYMBOL_EXPORT int section(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f10(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int section_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void section_release(int mem) {
}

CASADI_SYMBOL_EXPORT void section_incref(void) {
}

CASADI_SYMBOL_EXPORT void section_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int section_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int section_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real section_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* section_name_in(casadi_int i) {
  switch (i) {
    case 0: return "g";
    case 1: return "p";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* section_name_out(casadi_int i) {
  switch (i) {
    case 0: return "s";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* section_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    case 1: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* section_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int section_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int section_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* chart_point:(z[6],g[36],h,theta)->(g_theta[36]) */
static int casadi_f11(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33;
  a00=arg[1]? arg[1][0] : 0;
  a01=1.;
  a02=4.;
  a03=arg[3]? arg[3][0] : 0;
  a04=arg[2]? arg[2][0] : 0;
  a05=arg[0]? arg[0][0] : 0;
  a05=(a04*a05);
  a05=(a03*a05);
  a06=casadi_sq(a05);
  a07=arg[0]? arg[0][1] : 0;
  a07=(a04*a07);
  a07=(a03*a07);
  a08=casadi_sq(a07);
  a09=(a06+a08);
  a10=arg[0]? arg[0][2] : 0;
  a10=(a04*a10);
  a10=(a03*a10);
  a11=casadi_sq(a10);
  a09=(a09+a11);
  a09=(a02+a09);
  a09=(a02/a09);
  a12=(a11+a08);
  a13=2.;
  a12=(a12/a13);
  a12=(a09*a12);
  a12=(a01-a12);
  a14=(a00*a12);
  a15=arg[1]? arg[1][6] : 0;
  a16=(a05*a07);
  a16=(a16/a13);
  a16=(a10+a16);
  a16=(a09*a16);
  a17=(a15*a16);
  a14=(a14+a17);
  a17=arg[1]? arg[1][12] : 0;
  a18=(a05*a10);
  a18=(a18/a13);
  a18=(a18-a07);
  a18=(a09*a18);
  a19=(a17*a18);
  a14=(a14+a19);
  if (res[0]!=0) res[0][0]=a14;
  a14=arg[1]? arg[1][1] : 0;
  a19=(a14*a12);
  a20=arg[1]? arg[1][7] : 0;
  a21=(a20*a16);
  a19=(a19+a21);
  a21=arg[1]? arg[1][13] : 0;
  a22=(a21*a18);
  a19=(a19+a22);
  if (res[0]!=0) res[0][1]=a19;
  a19=arg[1]? arg[1][2] : 0;
  a22=(a19*a12);
  a23=arg[1]? arg[1][8] : 0;
  a24=(a23*a16);
  a22=(a22+a24);
  a24=arg[1]? arg[1][14] : 0;
  a25=(a24*a18);
  a22=(a22+a25);
  if (res[0]!=0) res[0][2]=a22;
  a22=arg[1]? arg[1][3] : 0;
  a25=(a22*a12);
  a26=arg[1]? arg[1][9] : 0;
  a27=(a26*a16);
  a25=(a25+a27);
  a27=arg[1]? arg[1][15] : 0;
  a28=(a27*a18);
  a25=(a25+a28);
  if (res[0]!=0) res[0][3]=a25;
  a25=arg[1]? arg[1][4] : 0;
  a28=(a25*a12);
  a29=arg[1]? arg[1][10] : 0;
  a30=(a29*a16);
  a28=(a28+a30);
  a30=arg[1]? arg[1][16] : 0;
  a31=(a30*a18);
  a28=(a28+a31);
  if (res[0]!=0) res[0][4]=a28;
  a28=arg[1]? arg[1][5] : 0;
  a12=(a28*a12);
  a31=arg[1]? arg[1][11] : 0;
  a16=(a31*a16);
  a12=(a12+a16);
  a16=arg[1]? arg[1][17] : 0;
  a18=(a16*a18);
  a12=(a12+a18);
  if (res[0]!=0) res[0][5]=a12;
  a12=(a07*a05);
  a12=(a12/a13);
  a12=(a12-a10);
  a12=(a09*a12);
  a18=(a00*a12);
  a11=(a11+a06);
  a11=(a11/a13);
  a11=(a09*a11);
  a11=(a01-a11);
  a32=(a15*a11);
  a18=(a18+a32);
  a32=(a07*a10);
  a32=(a32/a13);
  a32=(a05+a32);
  a32=(a09*a32);
  a33=(a17*a32);
  a18=(a18+a33);
  if (res[0]!=0) res[0][6]=a18;
  a18=(a14*a12);
  a33=(a20*a11);
  a18=(a18+a33);
  a33=(a21*a32);
  a18=(a18+a33);
  if (res[0]!=0) res[0][7]=a18;
  a18=(a19*a12);
  a33=(a23*a11);
  a18=(a18+a33);
  a33=(a24*a32);
  a18=(a18+a33);
  if (res[0]!=0) res[0][8]=a18;
  a18=(a22*a12);
  a33=(a26*a11);
  a18=(a18+a33);
  a33=(a27*a32);
  a18=(a18+a33);
  if (res[0]!=0) res[0][9]=a18;
  a18=(a25*a12);
  a33=(a29*a11);
  a18=(a18+a33);
  a33=(a30*a32);
  a18=(a18+a33);
  if (res[0]!=0) res[0][10]=a18;
  a12=(a28*a12);
  a11=(a31*a11);
  a12=(a12+a11);
  a32=(a16*a32);
  a12=(a12+a32);
  if (res[0]!=0) res[0][11]=a12;
  a12=(a10*a05);
  a12=(a12/a13);
  a12=(a07+a12);
  a12=(a09*a12);
  a00=(a00*a12);
  a10=(a10*a07);
  a10=(a10/a13);
  a10=(a10-a05);
  a10=(a09*a10);
  a15=(a15*a10);
  a00=(a00+a15);
  a08=(a08+a06);
  a08=(a08/a13);
  a09=(a09*a08);
  a09=(a01-a09);
  a17=(a17*a09);
  a00=(a00+a17);
  if (res[0]!=0) res[0][12]=a00;
  a14=(a14*a12);
  a20=(a20*a10);
  a14=(a14+a20);
  a21=(a21*a09);
  a14=(a14+a21);
  if (res[0]!=0) res[0][13]=a14;
  a19=(a19*a12);
  a23=(a23*a10);
  a19=(a19+a23);
  a24=(a24*a09);
  a19=(a19+a24);
  if (res[0]!=0) res[0][14]=a19;
  a22=(a22*a12);
  a26=(a26*a10);
  a22=(a22+a26);
  a27=(a27*a09);
  a22=(a22+a27);
  if (res[0]!=0) res[0][15]=a22;
  a25=(a25*a12);
  a29=(a29*a10);
  a25=(a25+a29);
  a30=(a30*a09);
  a25=(a25+a30);
  if (res[0]!=0) res[0][16]=a25;
  a28=(a28*a12);
  a31=(a31*a10);
  a28=(a28+a31);
  a16=(a16*a09);
  a28=(a28+a16);
  if (res[0]!=0) res[0][17]=a28;
  a28=arg[1]? arg[1][18] : 0;
  a16=arg[0]? arg[0][3] : 0;
  a16=(a04*a16);
  a16=(a03*a16);
  a09=casadi_sq(a16);
  a31=arg[0]? arg[0][4] : 0;
  a31=(a04*a31);
  a31=(a03*a31);
  a10=casadi_sq(a31);
  a12=(a09+a10);
  a25=arg[0]? arg[0][5] : 0;
  a04=(a04*a25);
  a03=(a03*a04);
  a04=casadi_sq(a03);
  a12=(a12+a04);
  a12=(a02+a12);
  a02=(a02/a12);
  a12=(a04+a10);
  a12=(a12/a13);
  a12=(a02*a12);
  a12=(a01-a12);
  a25=(a28*a12);
  a30=arg[1]? arg[1][24] : 0;
  a29=(a16*a31);
  a29=(a29/a13);
  a29=(a03+a29);
  a29=(a02*a29);
  a22=(a30*a29);
  a25=(a25+a22);
  a22=arg[1]? arg[1][30] : 0;
  a27=(a16*a03);
  a27=(a27/a13);
  a27=(a27-a31);
  a27=(a02*a27);
  a26=(a22*a27);
  a25=(a25+a26);
  if (res[0]!=0) res[0][18]=a25;
  a25=arg[1]? arg[1][19] : 0;
  a26=(a25*a12);
  a19=arg[1]? arg[1][25] : 0;
  a24=(a19*a29);
  a26=(a26+a24);
  a24=arg[1]? arg[1][31] : 0;
  a23=(a24*a27);
  a26=(a26+a23);
  if (res[0]!=0) res[0][19]=a26;
  a26=arg[1]? arg[1][20] : 0;
  a23=(a26*a12);
  a14=arg[1]? arg[1][26] : 0;
  a21=(a14*a29);
  a23=(a23+a21);
  a21=arg[1]? arg[1][32] : 0;
  a20=(a21*a27);
  a23=(a23+a20);
  if (res[0]!=0) res[0][20]=a23;
  a23=arg[1]? arg[1][21] : 0;
  a20=(a23*a12);
  a00=arg[1]? arg[1][27] : 0;
  a17=(a00*a29);
  a20=(a20+a17);
  a17=arg[1]? arg[1][33] : 0;
  a08=(a17*a27);
  a20=(a20+a08);
  if (res[0]!=0) res[0][21]=a20;
  a20=arg[1]? arg[1][22] : 0;
  a08=(a20*a12);
  a06=arg[1]? arg[1][28] : 0;
  a15=(a06*a29);
  a08=(a08+a15);
  a15=arg[1]? arg[1][34] : 0;
  a05=(a15*a27);
  a08=(a08+a05);
  if (res[0]!=0) res[0][22]=a08;
  a08=arg[1]? arg[1][23] : 0;
  a12=(a08*a12);
  a05=arg[1]? arg[1][29] : 0;
  a29=(a05*a29);
  a12=(a12+a29);
  a29=arg[1]? arg[1][35] : 0;
  a27=(a29*a27);
  a12=(a12+a27);
  if (res[0]!=0) res[0][23]=a12;
  a12=(a31*a16);
  a12=(a12/a13);
  a12=(a12-a03);
  a12=(a02*a12);
  a27=(a28*a12);
  a04=(a04+a09);
  a04=(a04/a13);
  a04=(a02*a04);
  a04=(a01-a04);
  a07=(a30*a04);
  a27=(a27+a07);
  a07=(a31*a03);
  a07=(a07/a13);
  a07=(a16+a07);
  a07=(a02*a07);
  a32=(a22*a07);
  a27=(a27+a32);
  if (res[0]!=0) res[0][24]=a27;
  a27=(a25*a12);
  a32=(a19*a04);
  a27=(a27+a32);
  a32=(a24*a07);
  a27=(a27+a32);
  if (res[0]!=0) res[0][25]=a27;
  a27=(a26*a12);
  a32=(a14*a04);
  a27=(a27+a32);
  a32=(a21*a07);
  a27=(a27+a32);
  if (res[0]!=0) res[0][26]=a27;
  a27=(a23*a12);
  a32=(a00*a04);
  a27=(a27+a32);
  a32=(a17*a07);
  a27=(a27+a32);
  if (res[0]!=0) res[0][27]=a27;
  a27=(a20*a12);
  a32=(a06*a04);
  a27=(a27+a32);
  a32=(a15*a07);
  a27=(a27+a32);
  if (res[0]!=0) res[0][28]=a27;
  a12=(a08*a12);
  a04=(a05*a04);
  a12=(a12+a04);
  a07=(a29*a07);
  a12=(a12+a07);
  if (res[0]!=0) res[0][29]=a12;
  a12=(a03*a16);
  a12=(a12/a13);
  a12=(a31+a12);
  a12=(a02*a12);
  a28=(a28*a12);
  a03=(a03*a31);
  a03=(a03/a13);
  a03=(a03-a16);
  a03=(a02*a03);
  a30=(a30*a03);
  a28=(a28+a30);
  a10=(a10+a09);
  a10=(a10/a13);
  a02=(a02*a10);
  a01=(a01-a02);
  a22=(a22*a01);
  a28=(a28+a22);
  if (res[0]!=0) res[0][30]=a28;
  a25=(a25*a12);
  a19=(a19*a03);
  a25=(a25+a19);
  a24=(a24*a01);
  a25=(a25+a24);
  if (res[0]!=0) res[0][31]=a25;
  a26=(a26*a12);
  a14=(a14*a03);
  a26=(a26+a14);
  a21=(a21*a01);
  a26=(a26+a21);
  if (res[0]!=0) res[0][32]=a26;
  a23=(a23*a12);
  a00=(a00*a03);
  a23=(a23+a00);
  a17=(a17*a01);
  a23=(a23+a17);
  if (res[0]!=0) res[0][33]=a23;
  a20=(a20*a12);
  a06=(a06*a03);
  a20=(a20+a06);
  a15=(a15*a01);
  a20=(a20+a15);
  if (res[0]!=0) res[0][34]=a20;
  a08=(a08*a12);
  a05=(a05*a03);
  a08=(a08+a05);
  a29=(a29*a01);
  a08=(a08+a29);
  if (res[0]!=0) res[0][35]=a08;
  return 0;
}

CASADI_SYMBOL_EXPORT int chart_point(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f11(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int chart_point_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void chart_point_release(int mem) {
}

CASADI_SYMBOL_EXPORT void chart_point_incref(void) {
}

CASADI_SYMBOL_EXPORT void chart_point_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int chart_point_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int chart_point_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real chart_point_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* chart_point_name_in(casadi_int i) {
  switch (i) {
    case 0: return "z";
    case 1: return "g";
    case 2: return "h";
    case 3: return "theta";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* chart_point_name_out(casadi_int i) {
  switch (i) {
    case 0: return "g_theta";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* chart_point_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* chart_point_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int chart_point_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int chart_point_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* observe:(g[36],p[6])->(xi[6],E,m[6],e) */
static int casadi_f12(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29;
  a00=arg[1]? arg[1][0] : 0;
  a01=9.0000000000000002e-01;
  a01=(a00/a01);
  if (res[0]!=0) res[0][0]=a01;
  a02=arg[1]? arg[1][1] : 0;
  if (res[0]!=0) res[0][1]=a02;
  a03=arg[1]? arg[1][2] : 0;
  a04=2.0000000000000001e-01;
  a04=(a03/a04);
  if (res[0]!=0) res[0][2]=a04;
  a05=arg[1]? arg[1][3] : 0;
  a06=5.9999999999999998e-01;
  a06=(a05/a06);
  if (res[0]!=0) res[0][3]=a06;
  a07=arg[1]? arg[1][4] : 0;
  a08=(-a07);
  a08=(2.*a08);
  a09=(-a08);
  if (res[0]!=0) res[0][4]=a09;
  a09=arg[1]? arg[1][5] : 0;
  a10=1.4999999999999999e-01;
  a10=(a09/a10);
  if (res[0]!=0) res[0][5]=a10;
  a11=(a00*a01);
  a12=casadi_sq(a02);
  a11=(a11+a12);
  a13=(a03*a04);
  a11=(a11+a13);
  a13=(a05*a06);
  a11=(a11+a13);
  a13=(a07*a08);
  a11=(a11-a13);
  a13=(a09*a10);
  a11=(a11+a13);
  a13=2.5000000000000000e-01;
  a08=casadi_sq(a08);
  a13=(a13*a08);
  a08=5.0000000000000000e-01;
  a08=(a08*a12);
  a13=(a13+a08);
  a08=arg[0]? arg[0][14] : 0;
  a13=(a13+a08);
  a12=6.0000000000000009e-01;
  a14=arg[0]? arg[0][35] : 0;
  a12=(a12*a14);
  a13=(a13+a12);
  a12=1.0000000000000001e-01;
  a04=casadi_sq(a04);
  a04=(a12*a04);
  a13=(a13+a04);
  a04=7.4999999999999997e-02;
  a10=casadi_sq(a10);
  a04=(a04*a10);
  a13=(a13+a04);
  a04=2.9999999999999999e-01;
  a06=casadi_sq(a06);
  a04=(a04*a06);
  a13=(a13+a04);
  a04=4.5000000000000001e-01;
  a01=casadi_sq(a01);
  a04=(a04*a01);
  a13=(a13+a04);
  a04=-2.;
  a01=5.0000000000000003e-02;
  a06=arg[0]? arg[0][6] : 0;
  a10=(a01*a06);
  a15=arg[0]? arg[0][0] : 0;
  a16=(a12*a15);
  a10=(a10+a16);
  a16=arg[0]? arg[0][12] : 0;
  a10=(a10-a16);
  a17=-1.0000000000000001e-01;
  a18=arg[0]? arg[0][27] : 0;
  a19=(a17*a18);
  a10=(a10+a19);
  a19=-2.9999999999999999e-01;
  a20=arg[0]? arg[0][33] : 0;
  a21=(a19*a20);
  a10=(a10+a21);
  a10=casadi_sq(a10);
  a10=(a04*a10);
  a13=(a13+a10);
  a10=arg[0]? arg[0][7] : 0;
  a21=(a01*a10);
  a22=arg[0]? arg[0][1] : 0;
  a23=(a12*a22);
  a21=(a21+a23);
  a23=arg[0]? arg[0][13] : 0;
  a21=(a21-a23);
  a24=arg[0]? arg[0][28] : 0;
  a25=(a17*a24);
  a21=(a21+a25);
  a25=arg[0]? arg[0][34] : 0;
  a26=(a19*a25);
  a21=(a21+a26);
  a21=casadi_sq(a21);
  a21=(a04*a21);
  a13=(a13+a21);
  a21=1.3000000000000000e+00;
  a26=arg[0]? arg[0][8] : 0;
  a01=(a01*a26);
  a21=(a21+a01);
  a01=arg[0]? arg[0][2] : 0;
  a12=(a12*a01);
  a21=(a21+a12);
  a21=(a21-a08);
  a12=arg[0]? arg[0][29] : 0;
  a27=(a17*a12);
  a21=(a21+a27);
  a19=(a19*a14);
  a21=(a21+a19);
  a21=casadi_sq(a21);
  a04=(a04*a21);
  a13=(a13+a04);
  a04=-5.9999999999999998e-02;
  a04=(a04*a12);
  a13=(a13+a04);
  a17=(a17*a01);
  a13=(a13+a17);
  a11=(a11-a13);
  if (res[1]!=0) res[1][0]=a11;
  a11=(a08*a10);
  a13=(a23*a26);
  a11=(a11-a13);
  a11=(a11*a00);
  a17=(a01*a23);
  a04=(a22*a08);
  a17=(a17-a04);
  a17=(a17*a02);
  a11=(a11+a17);
  a17=(a26*a22);
  a21=(a10*a01);
  a17=(a17-a21);
  a17=(a17*a03);
  a11=(a11+a17);
  if (res[2]!=0) res[2][0]=a11;
  a11=(a16*a26);
  a17=(a08*a06);
  a11=(a11-a17);
  a11=(a11*a00);
  a17=(a15*a08);
  a19=(a01*a16);
  a17=(a17-a19);
  a17=(a17*a02);
  a11=(a11+a17);
  a17=(a06*a01);
  a19=(a26*a15);
  a17=(a17-a19);
  a17=(a17*a03);
  a11=(a11+a17);
  if (res[2]!=0) res[2][1]=a11;
  a11=(a23*a06);
  a17=(a16*a10);
  a11=(a11-a17);
  a11=(a11*a00);
  a00=(a22*a16);
  a17=(a15*a23);
  a00=(a00-a17);
  a00=(a00*a02);
  a11=(a11+a00);
  a00=(a10*a15);
  a02=(a06*a22);
  a00=(a00-a02);
  a00=(a00*a03);
  a11=(a11+a00);
  if (res[2]!=0) res[2][2]=a11;
  a11=(a14*a24);
  a00=(a25*a12);
  a11=(a11-a00);
  a11=(a11*a05);
  a03=arg[0]? arg[0][23] : 0;
  a02=(a03*a25);
  a17=arg[0]? arg[0][22] : 0;
  a19=(a17*a14);
  a02=(a02-a19);
  a02=(a02*a07);
  a11=(a11+a02);
  a02=(a12*a17);
  a27=(a24*a03);
  a02=(a02-a27);
  a02=(a02*a09);
  a11=(a11+a02);
  if (res[2]!=0) res[2][3]=a11;
  a11=(a20*a12);
  a02=(a14*a18);
  a11=(a11-a02);
  a11=(a11*a05);
  a02=arg[0]? arg[0][21] : 0;
  a28=(a02*a14);
  a29=(a03*a20);
  a28=(a28-a29);
  a28=(a28*a07);
  a11=(a11+a28);
  a28=(a18*a03);
  a29=(a12*a02);
  a28=(a28-a29);
  a28=(a28*a09);
  a11=(a11+a28);
  if (res[2]!=0) res[2][4]=a11;
  a11=(a25*a18);
  a28=(a20*a24);
  a11=(a11-a28);
  a11=(a11*a05);
  a05=(a17*a20);
  a28=(a02*a25);
  a05=(a05-a28);
  a05=(a05*a07);
  a11=(a11+a05);
  a05=(a24*a02);
  a07=(a18*a17);
  a05=(a05-a07);
  a05=(a05*a09);
  a11=(a11+a05);
  if (res[2]!=0) res[2][5]=a11;
  a11=0.;
  a05=arg[0]? arg[0][3] : 0;
  a05=casadi_fabs(a05);
  a05=casadi_fmax(a11,a05);
  a09=arg[0]? arg[0][4] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a09=arg[0]? arg[0][5] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a05=casadi_fmax(a05,a11);
  a05=casadi_fmax(a05,a11);
  a05=casadi_fmax(a05,a11);
  a09=arg[0]? arg[0][9] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a09=arg[0]? arg[0][10] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a09=arg[0]? arg[0][11] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a05=casadi_fmax(a05,a11);
  a05=casadi_fmax(a05,a11);
  a05=casadi_fmax(a05,a11);
  a09=arg[0]? arg[0][15] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a09=arg[0]? arg[0][16] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a09=arg[0]? arg[0][17] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a09=arg[0]? arg[0][18] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a09=arg[0]? arg[0][19] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a09=arg[0]? arg[0][20] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a05=casadi_fmax(a05,a11);
  a05=casadi_fmax(a05,a11);
  a05=casadi_fmax(a05,a11);
  a09=arg[0]? arg[0][24] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a09=arg[0]? arg[0][25] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a09=arg[0]? arg[0][26] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a05=casadi_fmax(a05,a11);
  a05=casadi_fmax(a05,a11);
  a05=casadi_fmax(a05,a11);
  a09=arg[0]? arg[0][30] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a09=arg[0]? arg[0][31] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a09=arg[0]? arg[0][32] : 0;
  a09=casadi_fabs(a09);
  a05=casadi_fmax(a05,a09);
  a05=casadi_fmax(a05,a11);
  a05=casadi_fmax(a05,a11);
  a05=casadi_fmax(a05,a11);
  a11=casadi_sq(a15);
  a09=casadi_sq(a22);
  a11=(a11+a09);
  a09=casadi_sq(a01);
  a11=(a11+a09);
  a09=1.;
  a11=(a11-a09);
  a11=casadi_fabs(a11);
  a07=(a06*a15);
  a28=(a10*a22);
  a07=(a07+a28);
  a28=(a26*a01);
  a07=(a07+a28);
  a07=casadi_fabs(a07);
  a11=casadi_fmax(a11,a07);
  a07=(a16*a15);
  a28=(a23*a22);
  a07=(a07+a28);
  a28=(a08*a01);
  a07=(a07+a28);
  a07=casadi_fabs(a07);
  a11=casadi_fmax(a11,a07);
  a07=(a15*a06);
  a28=(a22*a10);
  a07=(a07+a28);
  a28=(a01*a26);
  a07=(a07+a28);
  a07=casadi_fabs(a07);
  a11=casadi_fmax(a11,a07);
  a07=casadi_sq(a06);
  a28=casadi_sq(a10);
  a07=(a07+a28);
  a28=casadi_sq(a26);
  a07=(a07+a28);
  a07=(a07-a09);
  a07=casadi_fabs(a07);
  a11=casadi_fmax(a11,a07);
  a07=(a16*a06);
  a28=(a23*a10);
  a07=(a07+a28);
  a28=(a08*a26);
  a07=(a07+a28);
  a07=casadi_fabs(a07);
  a11=casadi_fmax(a11,a07);
  a07=(a15*a16);
  a28=(a22*a23);
  a07=(a07+a28);
  a28=(a01*a08);
  a07=(a07+a28);
  a07=casadi_fabs(a07);
  a11=casadi_fmax(a11,a07);
  a07=(a06*a16);
  a28=(a10*a23);
  a07=(a07+a28);
  a28=(a26*a08);
  a07=(a07+a28);
  a07=casadi_fabs(a07);
  a11=casadi_fmax(a11,a07);
  a07=casadi_sq(a16);
  a28=casadi_sq(a23);
  a07=(a07+a28);
  a28=casadi_sq(a08);
  a07=(a07+a28);
  a07=(a07-a09);
  a07=casadi_fabs(a07);
  a11=casadi_fmax(a11,a07);
  a10=(a10*a08);
  a10=(a10-a13);
  a15=(a15*a10);
  a23=(a23*a01);
  a04=(a04-a23);
  a06=(a06*a04);
  a15=(a15-a06);
  a22=(a22*a26);
  a22=(a22-a21);
  a16=(a16*a22);
  a15=(a15+a16);
  a15=(a15-a09);
  a15=casadi_fabs(a15);
  a11=casadi_fmax(a11,a15);
  a05=casadi_fmax(a05,a11);
  a11=casadi_sq(a02);
  a15=casadi_sq(a17);
  a11=(a11+a15);
  a15=casadi_sq(a03);
  a11=(a11+a15);
  a11=(a11-a09);
  a11=casadi_fabs(a11);
  a15=(a18*a02);
  a16=(a24*a17);
  a15=(a15+a16);
  a16=(a12*a03);
  a15=(a15+a16);
  a15=casadi_fabs(a15);
  a11=casadi_fmax(a11,a15);
  a15=(a20*a02);
  a16=(a25*a17);
  a15=(a15+a16);
  a16=(a14*a03);
  a15=(a15+a16);
  a15=casadi_fabs(a15);
  a11=casadi_fmax(a11,a15);
  a15=(a02*a18);
  a16=(a17*a24);
  a15=(a15+a16);
  a16=(a03*a12);
  a15=(a15+a16);
  a15=casadi_fabs(a15);
  a11=casadi_fmax(a11,a15);
  a15=casadi_sq(a18);
  a16=casadi_sq(a24);
  a15=(a15+a16);
  a16=casadi_sq(a12);
  a15=(a15+a16);
  a15=(a15-a09);
  a15=casadi_fabs(a15);
  a11=casadi_fmax(a11,a15);
  a15=(a20*a18);
  a16=(a25*a24);
  a15=(a15+a16);
  a16=(a14*a12);
  a15=(a15+a16);
  a15=casadi_fabs(a15);
  a11=casadi_fmax(a11,a15);
  a15=(a02*a20);
  a16=(a17*a25);
  a15=(a15+a16);
  a16=(a03*a14);
  a15=(a15+a16);
  a15=casadi_fabs(a15);
  a11=casadi_fmax(a11,a15);
  a15=(a18*a20);
  a16=(a24*a25);
  a15=(a15+a16);
  a16=(a12*a14);
  a15=(a15+a16);
  a15=casadi_fabs(a15);
  a11=casadi_fmax(a11,a15);
  a15=casadi_sq(a20);
  a16=casadi_sq(a25);
  a15=(a15+a16);
  a16=casadi_sq(a14);
  a15=(a15+a16);
  a15=(a15-a09);
  a15=casadi_fabs(a15);
  a11=casadi_fmax(a11,a15);
  a24=(a24*a14);
  a24=(a24-a00);
  a02=(a02*a24);
  a25=(a25*a03);
  a19=(a19-a25);
  a18=(a18*a19);
  a02=(a02-a18);
  a17=(a17*a12);
  a17=(a17-a27);
  a20=(a20*a17);
  a02=(a02+a20);
  a02=(a02-a09);
  a02=casadi_fabs(a02);
  a11=casadi_fmax(a11,a02);
  a05=casadi_fmax(a05,a11);
  if (res[3]!=0) res[3][0]=a05;
  return 0;
}

CASADI_SYMBOL_EXPORT int observe(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f12(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int observe_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void observe_release(int mem) {
}

CASADI_SYMBOL_EXPORT void observe_incref(void) {
}

CASADI_SYMBOL_EXPORT void observe_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int observe_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int observe_n_out(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_real observe_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* observe_name_in(casadi_int i) {
  switch (i) {
    case 0: return "g";
    case 1: return "p";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* observe_name_out(casadi_int i) {
  switch (i) {
    case 0: return "xi";
    case 1: return "E";
    case 2: return "m";
    case 3: return "e";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* observe_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    case 1: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* observe_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s2;
    case 2: return casadi_s0;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int observe_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 4;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int observe_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 4*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* update_p:(z[6],g[36],p[6],h)->(p1[6]) */
static int casadi_f13(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72;
  a00=1.;
  a01=arg[3]? arg[3][0] : 0;
  a02=arg[0]? arg[0][0] : 0;
  a03=(a01*a02);
  a04=casadi_sq(a03);
  a05=4.;
  a06=(a04/a05);
  a06=(a00+a06);
  a07=9.0000000000000002e-01;
  a07=(a07*a02);
  a06=(a06*a07);
  a02=arg[0]? arg[0][2] : 0;
  a08=(a01*a02);
  a09=2.;
  a10=(a08/a09);
  a11=arg[0]? arg[0][1] : 0;
  a12=(a01*a11);
  a13=(a12*a03);
  a14=(a13/a05);
  a14=(a10+a14);
  a14=(a14*a11);
  a06=(a06+a14);
  a14=(a08*a03);
  a15=(a14/a05);
  a16=(a12/a09);
  a15=(a15-a16);
  a17=2.0000000000000001e-01;
  a17=(a17*a02);
  a15=(a15*a17);
  a06=(a06+a15);
  a15=arg[1]? arg[1][2] : 0;
  a02=casadi_sq(a12);
  a18=(a04+a02);
  a19=casadi_sq(a08);
  a18=(a18+a19);
  a18=(a05+a18);
  a18=(a05/a18);
  a14=(a14/a09);
  a14=(a12+a14);
  a14=(a18*a14);
  a20=(a15*a14);
  a21=arg[1]? arg[1][8] : 0;
  a22=(a08*a12);
  a23=(a22/a09);
  a23=(a23-a03);
  a23=(a18*a23);
  a24=(a21*a23);
  a20=(a20+a24);
  a24=arg[1]? arg[1][14] : 0;
  a25=(a02+a04);
  a25=(a25/a09);
  a25=(a18*a25);
  a25=(a00-a25);
  a26=(a24*a25);
  a20=(a20+a26);
  a26=5.0000000000000003e-02;
  a27=1.3000000000000000e+00;
  a13=(a13/a09);
  a13=(a13-a08);
  a13=(a18*a13);
  a28=(a15*a13);
  a04=(a19+a04);
  a04=(a04/a09);
  a04=(a18*a04);
  a04=(a00-a04);
  a29=(a21*a04);
  a28=(a28+a29);
  a29=(a12*a08);
  a30=(a29/a09);
  a30=(a03+a30);
  a30=(a18*a30);
  a31=(a24*a30);
  a28=(a28+a31);
  a31=(a26*a28);
  a27=(a27+a31);
  a31=1.0000000000000001e-01;
  a32=(a19+a02);
  a32=(a32/a09);
  a32=(a18*a32);
  a32=(a00-a32);
  a15=(a15*a32);
  a33=(a03*a12);
  a34=(a33/a09);
  a34=(a08+a34);
  a34=(a18*a34);
  a21=(a21*a34);
  a15=(a15+a21);
  a08=(a03*a08);
  a21=(a08/a09);
  a21=(a21-a12);
  a18=(a18*a21);
  a24=(a24*a18);
  a15=(a15+a24);
  a24=(a31*a15);
  a27=(a27+a24);
  a27=(a27-a20);
  a24=-1.0000000000000001e-01;
  a21=arg[1]? arg[1][23] : 0;
  a12=arg[0]? arg[0][3] : 0;
  a35=(a01*a12);
  a36=casadi_sq(a35);
  a37=arg[0]? arg[0][4] : 0;
  a38=(a01*a37);
  a39=casadi_sq(a38);
  a40=(a36+a39);
  a41=arg[0]? arg[0][5] : 0;
  a42=(a01*a41);
  a43=casadi_sq(a42);
  a40=(a40+a43);
  a40=(a05+a40);
  a40=(a05/a40);
  a44=(a38*a35);
  a45=(a44/a09);
  a45=(a45-a42);
  a45=(a40*a45);
  a46=(a21*a45);
  a47=arg[1]? arg[1][29] : 0;
  a48=(a43+a36);
  a48=(a48/a09);
  a48=(a40*a48);
  a48=(a00-a48);
  a49=(a47*a48);
  a46=(a46+a49);
  a49=arg[1]? arg[1][35] : 0;
  a50=(a38*a42);
  a51=(a50/a09);
  a51=(a35+a51);
  a51=(a40*a51);
  a52=(a49*a51);
  a46=(a46+a52);
  a52=(a24*a46);
  a27=(a27+a52);
  a52=-2.9999999999999999e-01;
  a53=(a42*a35);
  a54=(a53/a09);
  a54=(a38+a54);
  a54=(a40*a54);
  a55=(a21*a54);
  a56=(a42*a38);
  a57=(a56/a09);
  a57=(a57-a35);
  a57=(a40*a57);
  a58=(a47*a57);
  a55=(a55+a58);
  a58=(a39+a36);
  a58=(a58/a09);
  a58=(a40*a58);
  a58=(a00-a58);
  a59=(a49*a58);
  a55=(a55+a59);
  a59=(a52*a55);
  a27=(a27+a59);
  a27=(2.*a27);
  a27=(a27*a01);
  a59=(a26*a27);
  a60=(a20*a59);
  a61=arg[1]? arg[1][1] : 0;
  a62=(a61*a13);
  a63=arg[1]? arg[1][7] : 0;
  a64=(a63*a04);
  a62=(a62+a64);
  a64=arg[1]? arg[1][13] : 0;
  a65=(a64*a30);
  a62=(a62+a65);
  a65=(a26*a62);
  a66=(a61*a32);
  a67=(a63*a34);
  a66=(a66+a67);
  a67=(a64*a18);
  a66=(a66+a67);
  a67=(a31*a66);
  a65=(a65+a67);
  a61=(a61*a14);
  a63=(a63*a23);
  a61=(a61+a63);
  a64=(a64*a25);
  a61=(a61+a64);
  a65=(a65-a61);
  a64=arg[1]? arg[1][22] : 0;
  a63=(a64*a45);
  a67=arg[1]? arg[1][28] : 0;
  a68=(a67*a48);
  a63=(a63+a68);
  a68=arg[1]? arg[1][34] : 0;
  a69=(a68*a51);
  a63=(a63+a69);
  a69=(a24*a63);
  a65=(a65+a69);
  a69=(a64*a54);
  a70=(a67*a57);
  a69=(a69+a70);
  a70=(a68*a58);
  a69=(a69+a70);
  a70=(a52*a69);
  a65=(a65+a70);
  a65=(2.*a65);
  a65=(a65*a01);
  a70=(a62*a65);
  a60=(a60+a70);
  a70=(a26*a65);
  a71=(a61*a70);
  a60=(a60+a71);
  a71=arg[1]? arg[1][0] : 0;
  a13=(a71*a13);
  a72=arg[1]? arg[1][6] : 0;
  a04=(a72*a04);
  a13=(a13+a04);
  a04=arg[1]? arg[1][12] : 0;
  a30=(a04*a30);
  a13=(a13+a30);
  a30=(a26*a13);
  a32=(a71*a32);
  a34=(a72*a34);
  a32=(a32+a34);
  a18=(a04*a18);
  a32=(a32+a18);
  a18=(a31*a32);
  a30=(a30+a18);
  a71=(a71*a14);
  a72=(a72*a23);
  a71=(a71+a72);
  a04=(a04*a25);
  a71=(a71+a04);
  a30=(a30-a71);
  a04=arg[1]? arg[1][21] : 0;
  a45=(a04*a45);
  a25=arg[1]? arg[1][27] : 0;
  a48=(a25*a48);
  a45=(a45+a48);
  a48=arg[1]? arg[1][33] : 0;
  a51=(a48*a51);
  a45=(a45+a51);
  a51=(a24*a45);
  a30=(a30+a51);
  a54=(a04*a54);
  a57=(a25*a57);
  a54=(a54+a57);
  a58=(a48*a58);
  a54=(a54+a58);
  a58=(a52*a54);
  a30=(a30+a58);
  a30=(2.*a30);
  a30=(a30*a01);
  a58=(a13*a30);
  a60=(a60+a58);
  a26=(a26*a30);
  a58=(a71*a26);
  a60=(a60+a58);
  a58=5.0000000000000000e-01;
  a57=(a58*a01);
  a57=(a27+a57);
  a51=(a28*a57);
  a60=(a60+a51);
  a06=(a06-a60);
  if (res[0]!=0) res[0][0]=a06;
  a33=(a33/a05);
  a33=(a33-a10);
  a33=(a33*a07);
  a02=(a02/a05);
  a02=(a00+a02);
  a02=(a02*a11);
  a33=(a33+a02);
  a03=(a03/a09);
  a22=(a22/a05);
  a22=(a03+a22);
  a22=(a22*a17);
  a33=(a33+a22);
  a22=(a66*a65);
  a02=-5.0000000000000003e-02;
  a02=(a02*a01);
  a10=(a31*a27);
  a02=(a02-a10);
  a20=(a20*a02);
  a22=(a22-a20);
  a20=(a31*a65);
  a61=(a61*a20);
  a22=(a22+a61);
  a61=(a32*a30);
  a22=(a22+a61);
  a31=(a31*a30);
  a71=(a71*a31);
  a22=(a22+a71);
  a57=(a15*a57);
  a22=(a22+a57);
  a33=(a33+a22);
  if (res[0]!=0) res[0][1]=a33;
  a08=(a08/a05);
  a16=(a16+a08);
  a16=(a16*a07);
  a29=(a29/a05);
  a29=(a29-a03);
  a29=(a29*a11);
  a16=(a16+a29);
  a19=(a19/a05);
  a19=(a00+a19);
  a19=(a19*a17);
  a16=(a16+a19);
  a28=(a28*a02);
  a15=(a15*a59);
  a28=(a28+a15);
  a62=(a62*a20);
  a28=(a28-a62);
  a66=(a66*a70);
  a28=(a28+a66);
  a13=(a13*a31);
  a28=(a28-a13);
  a32=(a32*a26);
  a28=(a28+a32);
  a16=(a16+a28);
  if (res[0]!=0) res[0][2]=a16;
  a36=(a36/a05);
  a36=(a00+a36);
  a16=5.9999999999999998e-01;
  a16=(a16*a12);
  a36=(a36*a16);
  a12=(a42/a09);
  a44=(a44/a05);
  a44=(a12+a44);
  a58=(a58*a37);
  a44=(a44*a58);
  a36=(a36+a44);
  a53=(a53/a05);
  a44=(a38/a09);
  a53=(a53-a44);
  a37=1.4999999999999999e-01;
  a37=(a37*a41);
  a53=(a53*a37);
  a36=(a36+a53);
  a53=-2.9999999999999999e-02;
  a53=(a53*a01);
  a41=(a24*a27);
  a53=(a53-a41);
  a55=(a55*a53);
  a41=(a52*a65);
  a63=(a63*a41);
  a55=(a55+a63);
  a65=(a24*a65);
  a69=(a69*a65);
  a55=(a55-a69);
  a69=(a52*a30);
  a45=(a45*a69);
  a55=(a55+a45);
  a24=(a24*a30);
  a54=(a54*a24);
  a55=(a55-a54);
  a54=3.0000000000000004e-01;
  a54=(a54*a01);
  a52=(a52*a27);
  a54=(a54-a52);
  a46=(a46*a54);
  a55=(a55-a46);
  a36=(a36+a55);
  if (res[0]!=0) res[0][3]=a36;
  a36=(a35*a38);
  a55=(a36/a05);
  a55=(a55-a12);
  a55=(a55*a16);
  a12=(a39/a05);
  a12=(a00+a12);
  a12=(a12*a58);
  a55=(a55+a12);
  a12=(a35/a09);
  a56=(a56/a05);
  a56=(a12+a56);
  a56=(a56*a37);
  a55=(a55+a56);
  a39=(a43+a39);
  a39=(a39/a09);
  a39=(a40*a39);
  a39=(a00-a39);
  a21=(a21*a39);
  a36=(a36/a09);
  a36=(a42+a36);
  a36=(a40*a36);
  a47=(a47*a36);
  a21=(a21+a47);
  a35=(a35*a42);
  a09=(a35/a09);
  a09=(a09-a38);
  a40=(a40*a09);
  a49=(a49*a40);
  a21=(a21+a49);
  a54=(a21*a54);
  a64=(a64*a39);
  a67=(a67*a36);
  a64=(a64+a67);
  a68=(a68*a40);
  a64=(a64+a68);
  a41=(a64*a41);
  a04=(a04*a39);
  a25=(a25*a36);
  a04=(a04+a25);
  a48=(a48*a40);
  a04=(a04+a48);
  a69=(a04*a69);
  a41=(a41+a69);
  a54=(a54-a41);
  a55=(a55+a54);
  if (res[0]!=0) res[0][4]=a55;
  a35=(a35/a05);
  a44=(a44+a35);
  a44=(a44*a16);
  a50=(a50/a05);
  a50=(a50-a12);
  a50=(a50*a58);
  a44=(a44+a50);
  a43=(a43/a05);
  a00=(a00+a43);
  a00=(a00*a37);
  a44=(a44+a00);
  a64=(a64*a65);
  a21=(a21*a53);
  a64=(a64-a21);
  a04=(a04*a24);
  a64=(a64+a04);
  a44=(a44+a64);
  if (res[0]!=0) res[0][5]=a44;
  return 0;
}

CASADI_SYMBOL_EXPORT int update_p(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f13(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int update_p_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void update_p_release(int mem) {
}

CASADI_SYMBOL_EXPORT void update_p_incref(void) {
}

CASADI_SYMBOL_EXPORT void update_p_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int update_p_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int update_p_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real update_p_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* update_p_name_in(casadi_int i) {
  switch (i) {
    case 0: return "z";
    case 1: return "g";
    case 2: return "p";
    case 3: return "h";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* update_p_name_out(casadi_int i) {
  switch (i) {
    case 0: return "p1";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* update_p_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s0;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* update_p_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int update_p_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int update_p_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* velocity_step:(g[36],p[6],xi[6])->(xi1[6]) */
static int casadi_f14(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3;
  a0=arg[2]? arg[2][0] : 0;
  a1=9.0000000000000002e-01;
  a2=(a1*a0);
  a3=arg[1]? arg[1][0] : 0;
  a2=(a2-a3);
  a2=(a2/a1);
  a0=(a0-a2);
  if (res[0]!=0) res[0][0]=a0;
  a0=arg[2]? arg[2][1] : 0;
  a2=arg[1]? arg[1][1] : 0;
  a2=(a0-a2);
  a0=(a0-a2);
  if (res[0]!=0) res[0][1]=a0;
  a0=arg[2]? arg[2][2] : 0;
  a2=2.0000000000000001e-01;
  a1=(a2*a0);
  a3=arg[1]? arg[1][2] : 0;
  a1=(a1-a3);
  a1=(a1/a2);
  a0=(a0-a1);
  if (res[0]!=0) res[0][2]=a0;
  a0=arg[2]? arg[2][3] : 0;
  a1=5.9999999999999998e-01;
  a2=(a1*a0);
  a3=arg[1]? arg[1][3] : 0;
  a2=(a2-a3);
  a2=(a2/a1);
  a0=(a0-a2);
  if (res[0]!=0) res[0][3]=a0;
  a0=arg[2]? arg[2][4] : 0;
  a2=5.0000000000000000e-01;
  a2=(a2*a0);
  a1=arg[1]? arg[1][4] : 0;
  a2=(a2-a1);
  a2=(2.*a2);
  a0=(a0-a2);
  if (res[0]!=0) res[0][4]=a0;
  a0=arg[2]? arg[2][5] : 0;
  a2=1.4999999999999999e-01;
  a1=(a2*a0);
  a3=arg[1]? arg[1][5] : 0;
  a1=(a1-a3);
  a1=(a1/a2);
  a0=(a0-a1);
  if (res[0]!=0) res[0][5]=a0;
  return 0;
}

CASADI_SYMBOL_EXPORT int velocity_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f14(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int velocity_step_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void velocity_step_release(int mem) {
}

CASADI_SYMBOL_EXPORT void velocity_step_incref(void) {
}

CASADI_SYMBOL_EXPORT void velocity_step_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int velocity_step_n_in(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_int velocity_step_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real velocity_step_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* velocity_step_name_in(casadi_int i) {
  switch (i) {
    case 0: return "g";
    case 1: return "p";
    case 2: return "xi";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* velocity_step_name_out(casadi_int i) {
  switch (i) {
    case 0: return "xi1";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* velocity_step_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    case 1: return casadi_s0;
    case 2: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* velocity_step_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int velocity_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int velocity_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* record:(g[36],p[6],xi[6])->(row[49]) */
static int casadi_f15(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32;
  a00=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a02;
  a03=arg[0]? arg[0][3] : 0;
  if (res[0]!=0) res[0][3]=a03;
  a03=arg[0]? arg[0][4] : 0;
  if (res[0]!=0) res[0][4]=a03;
  a03=arg[0]? arg[0][5] : 0;
  if (res[0]!=0) res[0][5]=a03;
  a03=arg[0]? arg[0][6] : 0;
  if (res[0]!=0) res[0][6]=a03;
  a04=arg[0]? arg[0][7] : 0;
  if (res[0]!=0) res[0][7]=a04;
  a05=arg[0]? arg[0][8] : 0;
  if (res[0]!=0) res[0][8]=a05;
  a06=arg[0]? arg[0][9] : 0;
  if (res[0]!=0) res[0][9]=a06;
  a06=arg[0]? arg[0][10] : 0;
  if (res[0]!=0) res[0][10]=a06;
  a06=arg[0]? arg[0][11] : 0;
  if (res[0]!=0) res[0][11]=a06;
  a06=arg[0]? arg[0][12] : 0;
  if (res[0]!=0) res[0][12]=a06;
  a07=arg[0]? arg[0][13] : 0;
  if (res[0]!=0) res[0][13]=a07;
  a08=arg[0]? arg[0][14] : 0;
  if (res[0]!=0) res[0][14]=a08;
  a09=arg[0]? arg[0][15] : 0;
  if (res[0]!=0) res[0][15]=a09;
  a09=arg[0]? arg[0][16] : 0;
  if (res[0]!=0) res[0][16]=a09;
  a09=arg[0]? arg[0][17] : 0;
  if (res[0]!=0) res[0][17]=a09;
  a09=arg[0]? arg[0][18] : 0;
  if (res[0]!=0) res[0][18]=a09;
  a09=arg[0]? arg[0][19] : 0;
  if (res[0]!=0) res[0][19]=a09;
  a09=arg[0]? arg[0][20] : 0;
  if (res[0]!=0) res[0][20]=a09;
  a09=arg[0]? arg[0][21] : 0;
  if (res[0]!=0) res[0][21]=a09;
  a10=arg[0]? arg[0][22] : 0;
  if (res[0]!=0) res[0][22]=a10;
  a11=arg[0]? arg[0][23] : 0;
  if (res[0]!=0) res[0][23]=a11;
  a12=arg[0]? arg[0][24] : 0;
  if (res[0]!=0) res[0][24]=a12;
  a12=arg[0]? arg[0][25] : 0;
  if (res[0]!=0) res[0][25]=a12;
  a12=arg[0]? arg[0][26] : 0;
  if (res[0]!=0) res[0][26]=a12;
  a12=arg[0]? arg[0][27] : 0;
  if (res[0]!=0) res[0][27]=a12;
  a13=arg[0]? arg[0][28] : 0;
  if (res[0]!=0) res[0][28]=a13;
  a14=arg[0]? arg[0][29] : 0;
  if (res[0]!=0) res[0][29]=a14;
  a15=arg[0]? arg[0][30] : 0;
  if (res[0]!=0) res[0][30]=a15;
  a15=arg[0]? arg[0][31] : 0;
  if (res[0]!=0) res[0][31]=a15;
  a15=arg[0]? arg[0][32] : 0;
  if (res[0]!=0) res[0][32]=a15;
  a15=arg[0]? arg[0][33] : 0;
  if (res[0]!=0) res[0][33]=a15;
  a16=arg[0]? arg[0][34] : 0;
  if (res[0]!=0) res[0][34]=a16;
  a17=arg[0]? arg[0][35] : 0;
  if (res[0]!=0) res[0][35]=a17;
  a18=arg[1]? arg[1][0] : 0;
  if (res[0]!=0) res[0][36]=a18;
  a19=arg[1]? arg[1][1] : 0;
  if (res[0]!=0) res[0][37]=a19;
  a20=arg[1]? arg[1][2] : 0;
  if (res[0]!=0) res[0][38]=a20;
  a21=arg[1]? arg[1][3] : 0;
  if (res[0]!=0) res[0][39]=a21;
  a22=arg[1]? arg[1][4] : 0;
  if (res[0]!=0) res[0][40]=a22;
  a23=arg[1]? arg[1][5] : 0;
  if (res[0]!=0) res[0][41]=a23;
  a24=9.0000000000000002e-01;
  a25=arg[2]? arg[2][0] : 0;
  a24=(a24*a25);
  a24=(a24*a25);
  a26=arg[2]? arg[2][1] : 0;
  a26=casadi_sq(a26);
  a24=(a24+a26);
  a27=2.0000000000000001e-01;
  a28=arg[2]? arg[2][2] : 0;
  a27=(a27*a28);
  a27=(a27*a28);
  a24=(a24+a27);
  a27=5.9999999999999998e-01;
  a29=arg[2]? arg[2][3] : 0;
  a27=(a27*a29);
  a27=(a27*a29);
  a24=(a24+a27);
  a27=5.0000000000000000e-01;
  a30=arg[2]? arg[2][4] : 0;
  a31=(a27*a30);
  a31=(a31*a30);
  a24=(a24+a31);
  a31=1.4999999999999999e-01;
  a32=arg[2]? arg[2][5] : 0;
  a31=(a31*a32);
  a31=(a31*a32);
  a24=(a24+a31);
  a31=2.5000000000000000e-01;
  a30=casadi_sq(a30);
  a31=(a31*a30);
  a27=(a27*a26);
  a31=(a31+a27);
  a31=(a31+a08);
  a27=6.0000000000000009e-01;
  a27=(a27*a17);
  a31=(a31+a27);
  a27=1.0000000000000001e-01;
  a28=casadi_sq(a28);
  a28=(a27*a28);
  a31=(a31+a28);
  a28=7.4999999999999997e-02;
  a32=casadi_sq(a32);
  a28=(a28*a32);
  a31=(a31+a28);
  a28=2.9999999999999999e-01;
  a29=casadi_sq(a29);
  a28=(a28*a29);
  a31=(a31+a28);
  a28=4.5000000000000001e-01;
  a25=casadi_sq(a25);
  a28=(a28*a25);
  a31=(a31+a28);
  a28=-2.;
  a25=5.0000000000000003e-02;
  a29=(a25*a03);
  a32=(a27*a00);
  a29=(a29+a32);
  a29=(a29-a06);
  a32=-1.0000000000000001e-01;
  a26=(a32*a12);
  a29=(a29+a26);
  a26=-2.9999999999999999e-01;
  a30=(a26*a15);
  a29=(a29+a30);
  a29=casadi_sq(a29);
  a29=(a28*a29);
  a31=(a31+a29);
  a29=(a25*a04);
  a30=(a27*a01);
  a29=(a29+a30);
  a29=(a29-a07);
  a30=(a32*a13);
  a29=(a29+a30);
  a30=(a26*a16);
  a29=(a29+a30);
  a29=casadi_sq(a29);
  a29=(a28*a29);
  a31=(a31+a29);
  a29=1.3000000000000000e+00;
  a25=(a25*a05);
  a29=(a29+a25);
  a27=(a27*a02);
  a29=(a29+a27);
  a29=(a29-a08);
  a27=(a32*a14);
  a29=(a29+a27);
  a26=(a26*a17);
  a29=(a29+a26);
  a29=casadi_sq(a29);
  a28=(a28*a29);
  a31=(a31+a28);
  a28=-5.9999999999999998e-02;
  a28=(a28*a14);
  a31=(a31+a28);
  a32=(a32*a02);
  a31=(a31+a32);
  a24=(a24-a31);
  if (res[0]!=0) res[0][42]=a24;
  a24=(a08*a04);
  a31=(a07*a05);
  a24=(a24-a31);
  a24=(a24*a18);
  a31=(a02*a07);
  a32=(a01*a08);
  a31=(a31-a32);
  a31=(a31*a19);
  a24=(a24+a31);
  a31=(a05*a01);
  a32=(a04*a02);
  a31=(a31-a32);
  a31=(a31*a20);
  a24=(a24+a31);
  if (res[0]!=0) res[0][43]=a24;
  a24=(a06*a05);
  a31=(a08*a03);
  a24=(a24-a31);
  a24=(a24*a18);
  a08=(a00*a08);
  a31=(a02*a06);
  a08=(a08-a31);
  a08=(a08*a19);
  a24=(a24+a08);
  a02=(a03*a02);
  a05=(a05*a00);
  a02=(a02-a05);
  a02=(a02*a20);
  a24=(a24+a02);
  if (res[0]!=0) res[0][44]=a24;
  a24=(a07*a03);
  a02=(a06*a04);
  a24=(a24-a02);
  a24=(a24*a18);
  a06=(a01*a06);
  a07=(a00*a07);
  a06=(a06-a07);
  a06=(a06*a19);
  a24=(a24+a06);
  a04=(a04*a00);
  a03=(a03*a01);
  a04=(a04-a03);
  a04=(a04*a20);
  a24=(a24+a04);
  if (res[0]!=0) res[0][45]=a24;
  a24=(a17*a13);
  a04=(a16*a14);
  a24=(a24-a04);
  a24=(a24*a21);
  a04=(a11*a16);
  a20=(a10*a17);
  a04=(a04-a20);
  a04=(a04*a22);
  a24=(a24+a04);
  a04=(a14*a10);
  a20=(a13*a11);
  a04=(a04-a20);
  a04=(a04*a23);
  a24=(a24+a04);
  if (res[0]!=0) res[0][46]=a24;
  a24=(a15*a14);
  a04=(a17*a12);
  a24=(a24-a04);
  a24=(a24*a21);
  a17=(a09*a17);
  a04=(a11*a15);
  a17=(a17-a04);
  a17=(a17*a22);
  a24=(a24+a17);
  a11=(a12*a11);
  a14=(a14*a09);
  a11=(a11-a14);
  a11=(a11*a23);
  a24=(a24+a11);
  if (res[0]!=0) res[0][47]=a24;
  a24=(a16*a12);
  a11=(a15*a13);
  a24=(a24-a11);
  a24=(a24*a21);
  a15=(a10*a15);
  a16=(a09*a16);
  a15=(a15-a16);
  a15=(a15*a22);
  a24=(a24+a15);
  a13=(a13*a09);
  a12=(a12*a10);
  a13=(a13-a12);
  a13=(a13*a23);
  a24=(a24+a13);
  if (res[0]!=0) res[0][48]=a24;
  return 0;
}

CASADI_SYMBOL_EXPORT int record(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f15(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int record_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void record_release(int mem) {
}

CASADI_SYMBOL_EXPORT void record_incref(void) {
}

CASADI_SYMBOL_EXPORT void record_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int record_n_in(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_int record_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real record_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* record_name_in(casadi_int i) {
  switch (i) {
    case 0: return "g";
    case 1: return "p";
    case 2: return "xi";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* record_name_out(casadi_int i) {
  switch (i) {
    case 0: return "row";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* record_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    case 1: return casadi_s0;
    case 2: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* record_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int record_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int record_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* step_partials:(z[6],g[36],p[6],h)->(Fs[72],Yz[72],Ys[144]) */
static int casadi_f16(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a014, a015, a016, a017, a018, a019, a020, a021, a022, a023;
  casadi_real a024, a025, a026, a027, a028, a029, a030, a031, a032, a033, a034, a035;
  casadi_real a036, a037, a038, a039, a040, a041, a042, a043, a044, a045, a046, a047;
  casadi_real a048, a049, a050, a051, a052, a053, a054, a055, a056, a057, a058, a059;
  casadi_real a060, a061, a062, a063, a064, a065, a066, a067, a068, a069, a070, a071;
  casadi_real a072, a073, a074, a075, a076, a077, a078, a079, a080, a081, a082, a083;
  casadi_real a084, a085, a086, a087, a088, a089, a090, a091, a092, a093, a094, a095;
  casadi_real a096, a097, a098, a099, a100, a101, a102, a103, a104, a105, a106, a107;
  casadi_real a108, a109, a110, a111, a112, a113, a114, a115, a116, a117, a118, a119;
  casadi_real a120, a121, a122, a123, a124, a125, a126, a127, a128, a129, a130, a131;
  casadi_real a132, a133, a134, a135, a136, a137, a138, a139, a140, a141, a142, a143;
  casadi_real a144, a145, a146, a147, a148, a149, a150, a151, a152, a153, a154, a155;
  a000=arg[1]? arg[1][14] : 0;
  a001=5.0000000000000003e-02;
  a002=arg[3]? arg[3][0] : 0;
  a003=(a001*a000);
  a004=arg[1]? arg[1][8] : 0;
  a003=(a003+a004);
  a003=(2.*a003);
  a003=(a002*a003);
  a005=(a001*a003);
  a006=(a000*a005);
  a007=1.3000000000000000e+00;
  a008=(a001*a004);
  a008=(a007+a008);
  a009=1.0000000000000001e-01;
  a010=arg[1]? arg[1][2] : 0;
  a011=(a009*a010);
  a008=(a008+a011);
  a008=(a008-a000);
  a011=-1.0000000000000001e-01;
  a012=arg[1]? arg[1][29] : 0;
  a013=(a011*a012);
  a008=(a008+a013);
  a013=-2.9999999999999999e-01;
  a014=arg[1]? arg[1][35] : 0;
  a015=(a013*a014);
  a008=(a008+a015);
  a008=(2.*a008);
  a008=(a008*a002);
  a015=(a001*a008);
  a016=(a015*a004);
  a006=(a006-a016);
  a017=arg[1]? arg[1][7] : 0;
  a018=(a001*a017);
  a019=arg[1]? arg[1][1] : 0;
  a020=(a009*a019);
  a018=(a018+a020);
  a020=arg[1]? arg[1][13] : 0;
  a018=(a018-a020);
  a021=arg[1]? arg[1][28] : 0;
  a022=(a011*a021);
  a018=(a018+a022);
  a022=arg[1]? arg[1][34] : 0;
  a023=(a013*a022);
  a018=(a018+a023);
  a018=(2.*a018);
  a018=(a018*a002);
  a023=(a018*a020);
  a024=(a001*a020);
  a024=(a024+a017);
  a024=(2.*a024);
  a024=(a002*a024);
  a025=(a017*a024);
  a025=(a023+a025);
  a006=(a006+a025);
  a025=(a001*a024);
  a026=(a020*a025);
  a027=(a001*a018);
  a028=(a027*a017);
  a026=(a026-a028);
  a006=(a006+a026);
  a026=arg[1]? arg[1][6] : 0;
  a029=(a001*a026);
  a030=arg[1]? arg[1][0] : 0;
  a031=(a009*a030);
  a029=(a029+a031);
  a031=arg[1]? arg[1][12] : 0;
  a029=(a029-a031);
  a032=arg[1]? arg[1][27] : 0;
  a033=(a011*a032);
  a029=(a029+a033);
  a033=arg[1]? arg[1][33] : 0;
  a034=(a013*a033);
  a029=(a029+a034);
  a029=(2.*a029);
  a029=(a029*a002);
  a034=(a029*a031);
  a035=(a001*a031);
  a035=(a035+a026);
  a035=(2.*a035);
  a035=(a002*a035);
  a036=(a026*a035);
  a036=(a034+a036);
  a006=(a006+a036);
  a036=(a001*a035);
  a037=(a031*a036);
  a038=(a001*a029);
  a039=(a038*a026);
  a037=(a037-a039);
  a006=(a006+a037);
  a037=5.0000000000000000e-01;
  a040=(a037*a002);
  a041=(a008+a040);
  a042=(a041*a000);
  a043=(a004*a003);
  a043=(a042+a043);
  a006=(a006+a043);
  a006=(-a006);
  if (res[0]!=0) res[0][0]=a006;
  a006=(a019*a024);
  a043=-5.0000000000000003e-02;
  a043=(a043*a002);
  a044=(a009*a008);
  a044=(a043-a044);
  a045=(a044*a004);
  a046=(a009*a003);
  a047=(a000*a046);
  a045=(a045+a047);
  a006=(a006+a045);
  a045=(a009*a024);
  a047=(a020*a045);
  a048=(a009*a018);
  a049=(a048*a017);
  a047=(a047-a049);
  a006=(a006+a047);
  a047=(a030*a035);
  a006=(a006+a047);
  a047=(a009*a035);
  a049=(a031*a047);
  a050=(a009*a029);
  a051=(a050*a026);
  a049=(a049-a051);
  a006=(a006+a049);
  a049=(a010*a003);
  a006=(a006+a049);
  if (res[0]!=0) res[0][1]=a006;
  a006=(a044*a000);
  a046=(a004*a046);
  a006=(a006-a046);
  a005=(a010*a005);
  a006=(a006+a005);
  a005=(a048*a020);
  a045=(a017*a045);
  a005=(a005+a045);
  a006=(a006-a005);
  a025=(a019*a025);
  a006=(a006+a025);
  a025=(a050*a031);
  a047=(a026*a047);
  a025=(a025+a047);
  a006=(a006-a025);
  a036=(a030*a036);
  a006=(a006+a036);
  if (res[0]!=0) res[0][2]=a006;
  a006=(a013*a024);
  a036=(a021*a006);
  a025=(a011*a003);
  a047=(a014*a025);
  a036=(a036-a047);
  a024=(a011*a024);
  a047=(a022*a024);
  a036=(a036-a047);
  a047=(a013*a035);
  a005=(a032*a047);
  a036=(a036+a005);
  a035=(a011*a035);
  a005=(a033*a035);
  a036=(a036-a005);
  a003=(a013*a003);
  a005=(a012*a003);
  a036=(a036+a005);
  if (res[0]!=0) res[0][3]=a036;
  a036=arg[1]? arg[1][23] : 0;
  a003=(a036*a003);
  a005=arg[1]? arg[1][22] : 0;
  a006=(a005*a006);
  a045=arg[1]? arg[1][21] : 0;
  a047=(a045*a047);
  a006=(a006+a047);
  a003=(a003+a006);
  a003=(-a003);
  if (res[0]!=0) res[0][4]=a003;
  a024=(a005*a024);
  a025=(a036*a025);
  a024=(a024+a025);
  a035=(a045*a035);
  a024=(a024+a035);
  if (res[0]!=0) res[0][5]=a024;
  a024=(a015*a010);
  a035=(a009*a000);
  a035=(a035+a010);
  a035=(-a035);
  a035=(2.*a035);
  a035=(a002*a035);
  a025=(a001*a035);
  a003=(a000*a025);
  a024=(a024+a003);
  a003=(a009*a020);
  a003=(a003+a019);
  a003=(-a003);
  a003=(2.*a003);
  a003=(a002*a003);
  a006=(a017*a003);
  a024=(a024+a006);
  a006=(a027*a019);
  a047=(a001*a003);
  a046=(a020*a047);
  a006=(a006+a046);
  a024=(a024+a006);
  a006=(a009*a031);
  a006=(a006+a030);
  a006=(-a006);
  a006=(2.*a006);
  a006=(a002*a006);
  a046=(a026*a006);
  a024=(a024+a046);
  a046=(a038*a030);
  a049=(a001*a006);
  a051=(a031*a049);
  a046=(a046+a051);
  a024=(a024+a046);
  a046=(a004*a035);
  a024=(a024+a046);
  a024=(-a024);
  if (res[0]!=0) res[0][6]=a024;
  a024=(a019*a003);
  a024=(a024-a023);
  a044=(a044*a010);
  a023=(a009*a035);
  a046=(a000*a023);
  a046=(a044-a046);
  a024=(a024-a046);
  a048=(a048*a019);
  a046=(a009*a003);
  a051=(a020*a046);
  a051=(a048+a051);
  a024=(a024+a051);
  a051=(a030*a006);
  a051=(a051-a034);
  a024=(a024+a051);
  a050=(a050*a030);
  a051=(a009*a006);
  a034=(a031*a051);
  a034=(a050+a034);
  a024=(a024+a034);
  a034=(a010*a035);
  a034=(a034-a042);
  a024=(a024+a034);
  if (res[0]!=0) res[0][7]=a024;
  a025=(a010*a025);
  a015=(a015*a000);
  a025=(a025-a015);
  a023=(a004*a023);
  a025=(a025-a023);
  a046=(a017*a046);
  a025=(a025-a046);
  a047=(a019*a047);
  a027=(a027*a020);
  a047=(a047-a027);
  a025=(a025+a047);
  a051=(a026*a051);
  a025=(a025-a051);
  a049=(a030*a049);
  a038=(a038*a031);
  a049=(a049-a038);
  a025=(a025+a049);
  if (res[0]!=0) res[0][8]=a025;
  a025=(a013*a003);
  a049=(a021*a025);
  a038=(a011*a035);
  a051=(a014*a038);
  a049=(a049-a051);
  a003=(a011*a003);
  a051=(a022*a003);
  a049=(a049-a051);
  a051=(a013*a006);
  a047=(a032*a051);
  a049=(a049+a047);
  a006=(a011*a006);
  a047=(a033*a006);
  a049=(a049-a047);
  a035=(a013*a035);
  a047=(a012*a035);
  a049=(a049+a047);
  if (res[0]!=0) res[0][9]=a049;
  a035=(a036*a035);
  a025=(a005*a025);
  a051=(a045*a051);
  a025=(a025+a051);
  a035=(a035+a025);
  a035=(-a035);
  if (res[0]!=0) res[0][10]=a035;
  a003=(a005*a003);
  a038=(a036*a038);
  a003=(a003+a038);
  a006=(a045*a006);
  a003=(a003+a006);
  if (res[0]!=0) res[0][11]=a003;
  a003=(a009*a004);
  a006=(a001*a010);
  a003=(a003-a006);
  a003=(2.*a003);
  a003=(a002*a003);
  a006=(a001*a003);
  a038=(a000*a006);
  a035=(a009*a017);
  a025=(a001*a019);
  a035=(a035-a025);
  a035=(2.*a035);
  a035=(a002*a035);
  a025=(a017*a035);
  a051=(a018*a019);
  a025=(a025-a051);
  a038=(a038+a025);
  a025=(a001*a035);
  a051=(a020*a025);
  a038=(a038+a051);
  a051=(a009*a026);
  a049=(a001*a030);
  a051=(a051-a049);
  a051=(2.*a051);
  a051=(a002*a051);
  a049=(a026*a051);
  a047=(a029*a030);
  a049=(a049-a047);
  a038=(a038+a049);
  a049=(a001*a051);
  a047=(a031*a049);
  a038=(a038+a047);
  a047=(a004*a003);
  a027=(a041*a010);
  a047=(a047-a027);
  a038=(a038+a047);
  a038=(-a038);
  if (res[0]!=0) res[0][12]=a038;
  a038=(a018*a017);
  a047=(a019*a035);
  a038=(a038+a047);
  a047=(a009*a003);
  a027=(a000*a047);
  a038=(a038+a027);
  a027=(a009*a035);
  a046=(a020*a027);
  a038=(a038+a046);
  a046=(a029*a026);
  a023=(a030*a051);
  a046=(a046+a023);
  a038=(a038+a046);
  a046=(a009*a051);
  a023=(a031*a046);
  a038=(a038+a023);
  a041=(a041*a004);
  a023=(a010*a003);
  a041=(a041+a023);
  a038=(a038+a041);
  if (res[0]!=0) res[0][13]=a038;
  a006=(a010*a006);
  a016=(a016+a006);
  a047=(a004*a047);
  a044=(a044+a047);
  a016=(a016-a044);
  a027=(a017*a027);
  a027=(a027-a048);
  a016=(a016-a027);
  a025=(a019*a025);
  a028=(a028+a025);
  a016=(a016+a028);
  a046=(a026*a046);
  a046=(a046-a050);
  a016=(a016-a046);
  a049=(a030*a049);
  a039=(a039+a049);
  a016=(a016+a039);
  if (res[0]!=0) res[0][14]=a016;
  a016=(a013*a035);
  a039=(a021*a016);
  a049=(a011*a003);
  a046=(a014*a049);
  a039=(a039-a046);
  a035=(a011*a035);
  a046=(a022*a035);
  a039=(a039-a046);
  a046=(a013*a051);
  a050=(a032*a046);
  a039=(a039+a050);
  a051=(a011*a051);
  a050=(a033*a051);
  a039=(a039-a050);
  a003=(a013*a003);
  a050=(a012*a003);
  a039=(a039+a050);
  if (res[0]!=0) res[0][15]=a039;
  a003=(a036*a003);
  a016=(a005*a016);
  a046=(a045*a046);
  a016=(a016+a046);
  a003=(a003+a016);
  a003=(-a003);
  if (res[0]!=0) res[0][16]=a003;
  a035=(a005*a035);
  a049=(a036*a049);
  a035=(a035+a049);
  a051=(a045*a051);
  a035=(a035+a051);
  if (res[0]!=0) res[0][17]=a035;
  a035=(a011*a014);
  a051=(a013*a012);
  a035=(a035-a051);
  a035=(2.*a035);
  a035=(a002*a035);
  a051=(a001*a035);
  a049=(a000*a051);
  a003=(a011*a022);
  a016=(a013*a021);
  a003=(a003-a016);
  a003=(2.*a003);
  a003=(a002*a003);
  a016=(a017*a003);
  a049=(a049+a016);
  a016=(a001*a003);
  a046=(a020*a016);
  a049=(a049+a046);
  a046=(a011*a033);
  a039=(a013*a032);
  a046=(a046-a039);
  a046=(2.*a046);
  a046=(a002*a046);
  a039=(a026*a046);
  a049=(a049+a039);
  a039=(a001*a046);
  a050=(a031*a039);
  a049=(a049+a050);
  a050=(a004*a035);
  a049=(a049+a050);
  a049=(-a049);
  if (res[0]!=0) res[0][18]=a049;
  a049=(a019*a003);
  a050=(a009*a035);
  a028=(a000*a050);
  a049=(a049+a028);
  a028=(a009*a003);
  a025=(a020*a028);
  a049=(a049+a025);
  a025=(a030*a046);
  a049=(a049+a025);
  a025=(a009*a046);
  a027=(a031*a025);
  a049=(a049+a027);
  a027=(a010*a035);
  a049=(a049+a027);
  if (res[0]!=0) res[0][19]=a049;
  a051=(a010*a051);
  a050=(a004*a050);
  a051=(a051-a050);
  a028=(a017*a028);
  a051=(a051-a028);
  a016=(a019*a016);
  a051=(a051+a016);
  a025=(a026*a025);
  a051=(a051-a025);
  a039=(a030*a039);
  a051=(a051+a039);
  if (res[0]!=0) res[0][20]=a051;
  a051=(a013*a018);
  a039=(a051*a022);
  a025=(a013*a003);
  a016=(a021*a025);
  a016=(a039+a016);
  a028=-2.9999999999999999e-02;
  a028=(a028*a002);
  a050=(a011*a008);
  a050=(a028-a050);
  a049=(a050*a012);
  a027=(a011*a035);
  a048=(a014*a027);
  a048=(a049+a048);
  a016=(a016-a048);
  a003=(a011*a003);
  a048=(a022*a003);
  a018=(a011*a018);
  a044=(a018*a021);
  a048=(a048-a044);
  a016=(a016-a048);
  a048=(a013*a029);
  a047=(a048*a033);
  a006=(a013*a046);
  a038=(a032*a006);
  a038=(a047+a038);
  a016=(a016+a038);
  a046=(a011*a046);
  a038=(a033*a046);
  a029=(a011*a029);
  a041=(a029*a032);
  a038=(a038-a041);
  a016=(a016-a038);
  a038=3.0000000000000004e-01;
  a038=(a038*a002);
  a008=(a013*a008);
  a008=(a038-a008);
  a023=(a008*a014);
  a035=(a013*a035);
  a015=(a012*a035);
  a015=(a023-a015);
  a016=(a016-a015);
  if (res[0]!=0) res[0][21]=a016;
  a035=(a036*a035);
  a025=(a005*a025);
  a006=(a045*a006);
  a025=(a025+a006);
  a035=(a035+a025);
  a035=(-a035);
  if (res[0]!=0) res[0][22]=a035;
  a003=(a005*a003);
  a027=(a036*a027);
  a003=(a003+a027);
  a046=(a045*a046);
  a003=(a003+a046);
  if (res[0]!=0) res[0][23]=a003;
  a003=-5.9999999999999998e-01;
  a046=(a003*a036);
  a046=(a002*a046);
  a027=(a001*a046);
  a035=(a000*a027);
  a025=(a003*a005);
  a025=(a002*a025);
  a006=(a017*a025);
  a035=(a035+a006);
  a006=(a001*a025);
  a016=(a020*a006);
  a035=(a035+a016);
  a003=(a003*a045);
  a003=(a002*a003);
  a016=(a026*a003);
  a035=(a035+a016);
  a016=(a001*a003);
  a015=(a031*a016);
  a035=(a035+a015);
  a015=(a004*a046);
  a035=(a035+a015);
  a035=(-a035);
  if (res[0]!=0) res[0][24]=a035;
  a035=(a019*a025);
  a015=(a009*a046);
  a024=(a000*a015);
  a035=(a035+a024);
  a024=(a009*a025);
  a034=(a020*a024);
  a035=(a035+a034);
  a034=(a030*a003);
  a035=(a035+a034);
  a034=(a009*a003);
  a042=(a031*a034);
  a035=(a035+a042);
  a042=(a010*a046);
  a035=(a035+a042);
  if (res[0]!=0) res[0][25]=a035;
  a027=(a010*a027);
  a015=(a004*a015);
  a027=(a027-a015);
  a024=(a017*a024);
  a027=(a027-a024);
  a006=(a019*a006);
  a027=(a027+a006);
  a034=(a026*a034);
  a027=(a027-a034);
  a016=(a030*a016);
  a027=(a027+a016);
  if (res[0]!=0) res[0][26]=a027;
  a027=(a050*a036);
  a016=(a011*a046);
  a034=(a014*a016);
  a027=(a027-a034);
  a034=(a013*a025);
  a006=(a021*a034);
  a027=(a027+a006);
  a006=(a018*a005);
  a025=(a011*a025);
  a024=(a022*a025);
  a006=(a006+a024);
  a027=(a027-a006);
  a006=(a013*a003);
  a024=(a032*a006);
  a027=(a027+a024);
  a024=(a029*a045);
  a003=(a011*a003);
  a015=(a033*a003);
  a024=(a024+a015);
  a027=(a027-a024);
  a046=(a013*a046);
  a024=(a012*a046);
  a027=(a027+a024);
  if (res[0]!=0) res[0][27]=a027;
  a046=(a036*a046);
  a023=(a023+a046);
  a034=(a005*a034);
  a034=(a034-a039);
  a006=(a045*a006);
  a006=(a006-a047);
  a034=(a034+a006);
  a023=(a023+a034);
  a023=(-a023);
  if (res[0]!=0) res[0][28]=a023;
  a025=(a005*a025);
  a018=(a018*a022);
  a025=(a025-a018);
  a050=(a050*a014);
  a016=(a036*a016);
  a050=(a050+a016);
  a025=(a025+a050);
  a003=(a045*a003);
  a029=(a029*a033);
  a003=(a003-a029);
  a025=(a025+a003);
  if (res[0]!=0) res[0][29]=a025;
  a025=(a011*a036);
  a025=(-a025);
  a025=(2.*a025);
  a025=(a002*a025);
  a003=(a001*a025);
  a029=(a000*a003);
  a050=(a011*a005);
  a050=(-a050);
  a050=(2.*a050);
  a050=(a002*a050);
  a016=(a017*a050);
  a029=(a029+a016);
  a016=(a001*a050);
  a018=(a020*a016);
  a029=(a029+a018);
  a018=(a011*a045);
  a018=(-a018);
  a018=(2.*a018);
  a018=(a002*a018);
  a023=(a026*a018);
  a029=(a029+a023);
  a023=(a001*a018);
  a034=(a031*a023);
  a029=(a029+a034);
  a034=(a004*a025);
  a029=(a029+a034);
  a029=(-a029);
  if (res[0]!=0) res[0][30]=a029;
  a029=(a019*a050);
  a034=(a009*a025);
  a006=(a000*a034);
  a029=(a029+a006);
  a006=(a009*a050);
  a047=(a020*a006);
  a029=(a029+a047);
  a047=(a030*a018);
  a029=(a029+a047);
  a047=(a009*a018);
  a039=(a031*a047);
  a029=(a029+a039);
  a039=(a010*a025);
  a029=(a029+a039);
  if (res[0]!=0) res[0][31]=a029;
  a003=(a010*a003);
  a034=(a004*a034);
  a003=(a003-a034);
  a006=(a017*a006);
  a003=(a003-a006);
  a016=(a019*a016);
  a003=(a003+a016);
  a047=(a026*a047);
  a003=(a003-a047);
  a023=(a030*a023);
  a003=(a003+a023);
  if (res[0]!=0) res[0][32]=a003;
  a003=(a013*a050);
  a023=(a021*a003);
  a047=(a051*a005);
  a023=(a023-a047);
  a047=(a011*a025);
  a016=(a014*a047);
  a023=(a023-a016);
  a050=(a011*a050);
  a016=(a022*a050);
  a023=(a023-a016);
  a016=(a013*a018);
  a006=(a032*a016);
  a034=(a048*a045);
  a006=(a006-a034);
  a023=(a023+a006);
  a018=(a011*a018);
  a006=(a033*a018);
  a023=(a023-a006);
  a006=(a008*a036);
  a025=(a013*a025);
  a034=(a012*a025);
  a006=(a006+a034);
  a023=(a023+a006);
  if (res[0]!=0) res[0][33]=a023;
  a008=(a008*a012);
  a025=(a036*a025);
  a008=(a008-a025);
  a051=(a051*a021);
  a003=(a005*a003);
  a051=(a051+a003);
  a048=(a048*a032);
  a016=(a045*a016);
  a048=(a048+a016);
  a051=(a051+a048);
  a008=(a008-a051);
  if (res[0]!=0) res[0][34]=a008;
  a050=(a005*a050);
  a044=(a044+a050);
  a047=(a036*a047);
  a049=(a049-a047);
  a044=(a044-a049);
  a018=(a045*a018);
  a041=(a041+a018);
  a044=(a044+a041);
  if (res[0]!=0) res[0][35]=a044;
  a044=1.;
  if (res[0]!=0) res[0][36]=a044;
  a041=0.;
  if (res[0]!=0) res[0][37]=a041;
  if (res[0]!=0) res[0][38]=a041;
  if (res[0]!=0) res[0][39]=a041;
  if (res[0]!=0) res[0][40]=a041;
  if (res[0]!=0) res[0][41]=a041;
  if (res[0]!=0) res[0][42]=a041;
  if (res[0]!=0) res[0][43]=a044;
  if (res[0]!=0) res[0][44]=a041;
  if (res[0]!=0) res[0][45]=a041;
  if (res[0]!=0) res[0][46]=a041;
  if (res[0]!=0) res[0][47]=a041;
  if (res[0]!=0) res[0][48]=a041;
  if (res[0]!=0) res[0][49]=a041;
  if (res[0]!=0) res[0][50]=a044;
  if (res[0]!=0) res[0][51]=a041;
  if (res[0]!=0) res[0][52]=a041;
  if (res[0]!=0) res[0][53]=a041;
  if (res[0]!=0) res[0][54]=a041;
  if (res[0]!=0) res[0][55]=a041;
  if (res[0]!=0) res[0][56]=a041;
  if (res[0]!=0) res[0][57]=a044;
  if (res[0]!=0) res[0][58]=a041;
  if (res[0]!=0) res[0][59]=a041;
  if (res[0]!=0) res[0][60]=a041;
  if (res[0]!=0) res[0][61]=a041;
  if (res[0]!=0) res[0][62]=a041;
  if (res[0]!=0) res[0][63]=a041;
  if (res[0]!=0) res[0][64]=a044;
  if (res[0]!=0) res[0][65]=a041;
  if (res[0]!=0) res[0][66]=a041;
  if (res[0]!=0) res[0][67]=a041;
  if (res[0]!=0) res[0][68]=a041;
  if (res[0]!=0) res[0][69]=a041;
  if (res[0]!=0) res[0][70]=a041;
  if (res[0]!=0) res[0][71]=a044;
  a018=4.;
  a049=arg[0]? arg[0][0] : 0;
  a047=(a002*a049);
  a050=casadi_sq(a047);
  a008=arg[0]? arg[0][1] : 0;
  a051=(a002*a008);
  a048=casadi_sq(a051);
  a016=(a050+a048);
  a003=arg[0]? arg[0][2] : 0;
  a025=(a002*a003);
  a023=casadi_sq(a025);
  a016=(a016+a023);
  a016=(a018+a016);
  a006=(a018/a016);
  a034=(a025*a047);
  a029=2.;
  a039=(a034/a029);
  a039=(a051+a039);
  a046=(a006*a039);
  a027=(a030*a046);
  a024=(a025*a051);
  a015=(a024/a029);
  a015=(a015-a047);
  a035=(a006*a015);
  a042=(a026*a035);
  a027=(a027+a042);
  a042=(a048+a050);
  a042=(a042/a029);
  a052=(a006*a042);
  a052=(a044-a052);
  a053=(a031*a052);
  a027=(a027+a053);
  a053=(a051*a002);
  a054=(a037*a053);
  a054=(a006*a054);
  a055=(a051*a047);
  a056=(a055/a029);
  a056=(a056-a025);
  a016=(a006/a016);
  a057=(2.*a047);
  a057=(a057*a002);
  a058=(a016*a057);
  a059=(a056*a058);
  a059=(a054-a059);
  a060=(a030*a059);
  a061=(a037*a057);
  a061=(a006*a061);
  a062=(a023+a050);
  a062=(a062/a029);
  a063=(a062*a058);
  a063=(a061-a063);
  a064=(a026*a063);
  a060=(a060-a064);
  a064=(a006*a002);
  a065=(a051*a025);
  a066=(a065/a029);
  a066=(a047+a066);
  a067=(a066*a058);
  a067=(a064-a067);
  a068=(a031*a067);
  a060=(a060+a068);
  a068=(a027*a060);
  a069=(a019*a046);
  a070=(a017*a035);
  a069=(a069+a070);
  a070=(a020*a052);
  a069=(a069+a070);
  a070=(a019*a059);
  a071=(a017*a063);
  a070=(a070-a071);
  a071=(a020*a067);
  a070=(a070+a071);
  a071=(a069*a070);
  a068=(a068+a071);
  a071=(a010*a046);
  a072=(a004*a035);
  a071=(a071+a072);
  a072=(a000*a052);
  a071=(a071+a072);
  a059=(a010*a059);
  a063=(a004*a063);
  a059=(a059-a063);
  a067=(a000*a067);
  a059=(a059+a067);
  a067=(a071*a059);
  a068=(a068+a067);
  if (res[1]!=0) res[1][0]=a068;
  a068=(a023+a048);
  a068=(a068/a029);
  a067=(a006*a068);
  a067=(a044-a067);
  a063=(a030*a067);
  a072=(a047*a051);
  a073=(a072/a029);
  a073=(a025+a073);
  a074=(a006*a073);
  a075=(a026*a074);
  a063=(a063+a075);
  a075=(a047*a025);
  a076=(a075/a029);
  a076=(a076-a051);
  a077=(a006*a076);
  a078=(a031*a077);
  a063=(a063+a078);
  a078=(a025*a002);
  a079=(a037*a078);
  a079=(a006*a079);
  a080=(a039*a058);
  a080=(a079-a080);
  a081=(a030*a080);
  a082=(a015*a058);
  a082=(a082+a064);
  a083=(a026*a082);
  a081=(a081-a083);
  a083=(a042*a058);
  a061=(a061-a083);
  a083=(a031*a061);
  a081=(a081-a083);
  a083=(a063*a081);
  a084=(a019*a067);
  a085=(a017*a074);
  a084=(a084+a085);
  a085=(a020*a077);
  a084=(a084+a085);
  a085=(a019*a080);
  a086=(a017*a082);
  a085=(a085-a086);
  a086=(a020*a061);
  a085=(a085-a086);
  a086=(a084*a085);
  a083=(a083+a086);
  a086=(a010*a067);
  a087=(a004*a074);
  a086=(a086+a087);
  a087=(a000*a077);
  a086=(a086+a087);
  a080=(a010*a080);
  a082=(a004*a082);
  a080=(a080-a082);
  a061=(a000*a061);
  a080=(a080-a061);
  a061=(a086*a080);
  a083=(a083+a061);
  if (res[1]!=0) res[1][1]=a083;
  a083=(a006*a056);
  a061=(a030*a083);
  a082=(a006*a062);
  a082=(a044-a082);
  a087=(a026*a082);
  a061=(a061+a087);
  a087=(a006*a066);
  a088=(a031*a087);
  a061=(a061+a088);
  a088=(a068*a058);
  a089=(a030*a088);
  a090=(a073*a058);
  a090=(a054-a090);
  a091=(a026*a090);
  a089=(a089+a091);
  a058=(a076*a058);
  a058=(a079-a058);
  a091=(a031*a058);
  a089=(a089+a091);
  a091=(a061*a089);
  a092=(a019*a083);
  a093=(a017*a082);
  a092=(a092+a093);
  a093=(a020*a087);
  a092=(a092+a093);
  a093=(a019*a088);
  a094=(a017*a090);
  a093=(a093+a094);
  a094=(a020*a058);
  a093=(a093+a094);
  a094=(a092*a093);
  a091=(a091+a094);
  a094=(a010*a083);
  a095=(a004*a082);
  a094=(a094+a095);
  a095=(a000*a087);
  a094=(a094+a095);
  a088=(a010*a088);
  a090=(a004*a090);
  a088=(a088+a090);
  a058=(a000*a058);
  a088=(a088+a058);
  a058=(a094*a088);
  a091=(a091+a058);
  if (res[1]!=0) res[1][2]=a091;
  if (res[1]!=0) res[1][3]=a041;
  if (res[1]!=0) res[1][4]=a041;
  if (res[1]!=0) res[1][5]=a041;
  a091=9.0000000000000002e-01;
  a049=(a091*a049);
  a058=2.5000000000000000e-01;
  a057=(a058*a057);
  a057=(a049*a057);
  a050=(a050/a018);
  a050=(a044+a050);
  a050=(a091*a050);
  a057=(a057+a050);
  a053=(a058*a053);
  a050=(a008*a053);
  a057=(a057+a050);
  a090=2.0000000000000001e-01;
  a003=(a090*a003);
  a078=(a058*a078);
  a095=(a003*a078);
  a057=(a057+a095);
  a096=(a001*a094);
  a007=(a007+a096);
  a096=(a009*a086);
  a007=(a007+a096);
  a007=(a007-a071);
  a096=arg[0]? arg[0][3] : 0;
  a097=(a002*a096);
  a098=casadi_sq(a097);
  a099=arg[0]? arg[0][4] : 0;
  a100=(a002*a099);
  a101=casadi_sq(a100);
  a102=(a098+a101);
  a103=arg[0]? arg[0][5] : 0;
  a104=(a002*a103);
  a105=casadi_sq(a104);
  a102=(a102+a105);
  a102=(a018+a102);
  a106=(a018/a102);
  a107=(a100*a097);
  a108=(a107/a029);
  a108=(a108-a104);
  a109=(a106*a108);
  a110=(a036*a109);
  a111=(a105+a098);
  a111=(a111/a029);
  a112=(a106*a111);
  a112=(a044-a112);
  a113=(a012*a112);
  a110=(a110+a113);
  a113=(a100*a104);
  a114=(a113/a029);
  a114=(a097+a114);
  a115=(a106*a114);
  a116=(a014*a115);
  a110=(a110+a116);
  a116=(a011*a110);
  a007=(a007+a116);
  a116=(a104*a097);
  a117=(a116/a029);
  a117=(a100+a117);
  a118=(a106*a117);
  a119=(a036*a118);
  a120=(a104*a100);
  a121=(a120/a029);
  a121=(a121-a097);
  a122=(a106*a121);
  a123=(a012*a122);
  a119=(a119+a123);
  a123=(a101+a098);
  a123=(a123/a029);
  a124=(a106*a123);
  a124=(a044-a124);
  a125=(a014*a124);
  a119=(a119+a125);
  a125=(a013*a119);
  a007=(a007+a125);
  a007=(2.*a007);
  a007=(a007*a002);
  a125=(a001*a007);
  a126=(a125*a080);
  a127=(a001*a059);
  a128=(a009*a088);
  a127=(a127+a128);
  a127=(a127-a080);
  a127=(2.*a127);
  a127=(a002*a127);
  a128=(a001*a127);
  a129=(a071*a128);
  a126=(a126+a129);
  a129=(a001*a092);
  a130=(a009*a084);
  a129=(a129+a130);
  a129=(a129-a069);
  a130=(a005*a109);
  a131=(a021*a112);
  a130=(a130+a131);
  a131=(a022*a115);
  a130=(a130+a131);
  a131=(a011*a130);
  a129=(a129+a131);
  a131=(a005*a118);
  a132=(a021*a122);
  a131=(a131+a132);
  a132=(a022*a124);
  a131=(a131+a132);
  a132=(a013*a131);
  a129=(a129+a132);
  a129=(2.*a129);
  a129=(a129*a002);
  a132=(a129*a070);
  a133=(a001*a070);
  a134=(a009*a093);
  a133=(a133+a134);
  a133=(a133-a085);
  a133=(2.*a133);
  a133=(a002*a133);
  a134=(a092*a133);
  a132=(a132+a134);
  a126=(a126+a132);
  a132=(a001*a129);
  a134=(a132*a085);
  a135=(a001*a133);
  a136=(a069*a135);
  a134=(a134+a136);
  a126=(a126+a134);
  a134=(a001*a061);
  a136=(a009*a063);
  a134=(a134+a136);
  a134=(a134-a027);
  a136=(a045*a109);
  a137=(a032*a112);
  a136=(a136+a137);
  a137=(a033*a115);
  a136=(a136+a137);
  a137=(a011*a136);
  a134=(a134+a137);
  a137=(a045*a118);
  a138=(a032*a122);
  a137=(a137+a138);
  a138=(a033*a124);
  a137=(a137+a138);
  a138=(a013*a137);
  a134=(a134+a138);
  a134=(2.*a134);
  a134=(a134*a002);
  a138=(a134*a060);
  a139=(a001*a060);
  a140=(a009*a089);
  a139=(a139+a140);
  a139=(a139-a081);
  a139=(2.*a139);
  a139=(a002*a139);
  a140=(a061*a139);
  a138=(a138+a140);
  a126=(a126+a138);
  a138=(a001*a134);
  a140=(a138*a081);
  a141=(a001*a139);
  a142=(a027*a141);
  a140=(a140+a142);
  a126=(a126+a140);
  a140=(a007+a040);
  a142=(a140*a059);
  a143=(a094*a127);
  a142=(a142+a143);
  a126=(a126+a142);
  a057=(a057-a126);
  if (res[1]!=0) res[1][6]=a057;
  a057=(a049*a053);
  a072=(a072/a018);
  a126=(a025/a029);
  a072=(a072-a126);
  a072=(a091*a072);
  a057=(a057+a072);
  a072=(a003*a040);
  a057=(a057+a072);
  a142=(a129*a093);
  a143=(a084*a133);
  a142=(a142+a143);
  a143=(a009*a007);
  a043=(a043-a143);
  a080=(a043*a080);
  a143=(a009*a127);
  a144=(a071*a143);
  a080=(a080-a144);
  a142=(a142-a080);
  a080=(a009*a129);
  a085=(a080*a085);
  a144=(a009*a133);
  a145=(a069*a144);
  a085=(a085+a145);
  a142=(a142+a085);
  a085=(a134*a089);
  a145=(a063*a139);
  a085=(a085+a145);
  a142=(a142+a085);
  a085=(a009*a134);
  a081=(a085*a081);
  a145=(a009*a139);
  a146=(a027*a145);
  a081=(a081+a146);
  a142=(a142+a081);
  a081=(a140*a088);
  a146=(a086*a127);
  a081=(a081+a146);
  a142=(a142+a081);
  a057=(a057+a142);
  if (res[1]!=0) res[1][7]=a057;
  a057=(a049*a078);
  a142=(a051/a029);
  a075=(a075/a018);
  a075=(a142+a075);
  a091=(a091*a075);
  a057=(a057+a091);
  a091=(a008*a040);
  a057=(a057-a091);
  a059=(a043*a059);
  a143=(a094*a143);
  a059=(a059-a143);
  a088=(a125*a088);
  a128=(a086*a128);
  a088=(a088+a128);
  a059=(a059+a088);
  a070=(a080*a070);
  a144=(a092*a144);
  a070=(a070+a144);
  a059=(a059-a070);
  a093=(a132*a093);
  a135=(a084*a135);
  a093=(a093+a135);
  a059=(a059+a093);
  a060=(a085*a060);
  a145=(a061*a145);
  a060=(a060+a145);
  a059=(a059-a060);
  a089=(a138*a089);
  a141=(a063*a141);
  a089=(a089+a141);
  a059=(a059+a089);
  a057=(a057+a059);
  if (res[1]!=0) res[1][8]=a057;
  a057=(a013*a133);
  a059=(a130*a057);
  a089=(a011*a127);
  a141=(a119*a089);
  a059=(a059-a141);
  a133=(a011*a133);
  a141=(a131*a133);
  a059=(a059-a141);
  a141=(a013*a139);
  a060=(a136*a141);
  a059=(a059+a060);
  a139=(a011*a139);
  a060=(a137*a139);
  a059=(a059-a060);
  a127=(a013*a127);
  a060=(a110*a127);
  a059=(a059+a060);
  if (res[1]!=0) res[1][9]=a059;
  a059=(a105+a101);
  a059=(a059/a029);
  a060=(a106*a059);
  a060=(a044-a060);
  a145=(a036*a060);
  a093=(a097*a100);
  a135=(a093/a029);
  a135=(a104+a135);
  a070=(a106*a135);
  a144=(a012*a070);
  a145=(a145+a144);
  a144=(a097*a104);
  a088=(a144/a029);
  a088=(a088-a100);
  a128=(a106*a088);
  a143=(a014*a128);
  a145=(a145+a143);
  a127=(a145*a127);
  a143=(a005*a060);
  a075=(a021*a070);
  a143=(a143+a075);
  a075=(a022*a128);
  a143=(a143+a075);
  a057=(a143*a057);
  a075=(a045*a060);
  a081=(a032*a070);
  a075=(a075+a081);
  a081=(a033*a128);
  a075=(a075+a081);
  a141=(a075*a141);
  a057=(a057+a141);
  a127=(a127+a057);
  a127=(-a127);
  if (res[1]!=0) res[1][10]=a127;
  a133=(a143*a133);
  a089=(a145*a089);
  a133=(a133+a089);
  a139=(a075*a139);
  a133=(a133+a139);
  if (res[1]!=0) res[1][11]=a133;
  a133=(a047*a002);
  a139=(a037*a133);
  a139=(a006*a139);
  a051=(2.*a051);
  a051=(a051*a002);
  a089=(a016*a051);
  a127=(a056*a089);
  a127=(a139-a127);
  a057=(a030*a127);
  a141=(a062*a089);
  a081=(a026*a141);
  a057=(a057+a081);
  a081=(a066*a089);
  a081=(a079-a081);
  a146=(a031*a081);
  a057=(a057+a146);
  a146=(a027*a057);
  a147=(a019*a127);
  a148=(a017*a141);
  a147=(a147+a148);
  a148=(a020*a081);
  a147=(a147+a148);
  a148=(a069*a147);
  a146=(a146+a148);
  a127=(a010*a127);
  a141=(a004*a141);
  a127=(a127+a141);
  a081=(a000*a081);
  a127=(a127+a081);
  a081=(a071*a127);
  a146=(a146+a081);
  if (res[1]!=0) res[1][12]=a146;
  a146=(a039*a089);
  a146=(a064-a146);
  a081=(a030*a146);
  a141=(a015*a089);
  a079=(a079-a141);
  a141=(a026*a079);
  a081=(a081+a141);
  a141=(a037*a051);
  a141=(a006*a141);
  a148=(a042*a089);
  a148=(a141-a148);
  a149=(a031*a148);
  a081=(a081-a149);
  a149=(a063*a081);
  a150=(a019*a146);
  a151=(a017*a079);
  a150=(a150+a151);
  a151=(a020*a148);
  a150=(a150-a151);
  a151=(a084*a150);
  a149=(a149+a151);
  a146=(a010*a146);
  a079=(a004*a079);
  a146=(a146+a079);
  a148=(a000*a148);
  a146=(a146-a148);
  a148=(a086*a146);
  a149=(a149+a148);
  if (res[1]!=0) res[1][13]=a149;
  a149=(a073*a089);
  a149=(a139-a149);
  a148=(a026*a149);
  a079=(a068*a089);
  a141=(a141-a079);
  a079=(a030*a141);
  a148=(a148-a079);
  a089=(a076*a089);
  a089=(a089+a064);
  a079=(a031*a089);
  a148=(a148-a079);
  a079=(a061*a148);
  a151=(a017*a149);
  a152=(a019*a141);
  a151=(a151-a152);
  a152=(a020*a089);
  a151=(a151-a152);
  a152=(a092*a151);
  a079=(a079+a152);
  a149=(a004*a149);
  a141=(a010*a141);
  a149=(a149-a141);
  a089=(a000*a089);
  a149=(a149-a089);
  a089=(a094*a149);
  a079=(a079+a089);
  if (res[1]!=0) res[1][14]=a079;
  if (res[1]!=0) res[1][15]=a041;
  if (res[1]!=0) res[1][16]=a041;
  if (res[1]!=0) res[1][17]=a041;
  a133=(a058*a133);
  a079=(a008*a133);
  a055=(a055/a018);
  a126=(a126+a055);
  a079=(a079+a126);
  a079=(a079-a072);
  a072=(a125*a146);
  a126=(a001*a127);
  a055=(a009*a149);
  a126=(a126+a055);
  a126=(a126-a146);
  a126=(2.*a126);
  a126=(a002*a126);
  a055=(a001*a126);
  a089=(a071*a055);
  a072=(a072+a089);
  a089=(a129*a147);
  a141=(a001*a147);
  a152=(a009*a151);
  a141=(a141+a152);
  a141=(a141-a150);
  a141=(2.*a141);
  a141=(a002*a141);
  a152=(a092*a141);
  a089=(a089+a152);
  a072=(a072+a089);
  a089=(a132*a150);
  a152=(a001*a141);
  a153=(a069*a152);
  a089=(a089+a153);
  a072=(a072+a089);
  a089=(a134*a057);
  a153=(a001*a057);
  a154=(a009*a148);
  a153=(a153+a154);
  a153=(a153-a081);
  a153=(2.*a153);
  a153=(a002*a153);
  a154=(a061*a153);
  a089=(a089+a154);
  a072=(a072+a089);
  a089=(a138*a081);
  a154=(a001*a153);
  a155=(a027*a154);
  a089=(a089+a155);
  a072=(a072+a089);
  a089=(a140*a127);
  a155=(a094*a126);
  a089=(a089+a155);
  a072=(a072+a089);
  a079=(a079-a072);
  if (res[1]!=0) res[1][18]=a079;
  a079=(a049*a133);
  a051=(a058*a051);
  a051=(a008*a051);
  a048=(a048/a018);
  a048=(a044+a048);
  a051=(a051+a048);
  a051=(a079+a051);
  a051=(a051+a095);
  a095=(a129*a151);
  a048=(a084*a141);
  a095=(a095+a048);
  a146=(a043*a146);
  a048=(a009*a126);
  a072=(a071*a048);
  a146=(a146-a072);
  a095=(a095-a146);
  a150=(a080*a150);
  a146=(a009*a141);
  a072=(a069*a146);
  a150=(a150+a072);
  a095=(a095+a150);
  a150=(a134*a148);
  a072=(a063*a153);
  a150=(a150+a072);
  a095=(a095+a150);
  a081=(a085*a081);
  a150=(a009*a153);
  a072=(a027*a150);
  a081=(a081+a072);
  a095=(a095+a081);
  a081=(a140*a149);
  a072=(a086*a126);
  a081=(a081+a072);
  a095=(a095+a081);
  a051=(a051+a095);
  if (res[1]!=0) res[1][19]=a051;
  a049=(a049*a040);
  a008=(a008*a078);
  a065=(a065/a018);
  a047=(a047/a029);
  a065=(a065-a047);
  a008=(a008+a065);
  a008=(a049+a008);
  a127=(a043*a127);
  a048=(a094*a048);
  a127=(a127-a048);
  a149=(a125*a149);
  a055=(a086*a055);
  a149=(a149+a055);
  a127=(a127+a149);
  a147=(a080*a147);
  a146=(a092*a146);
  a147=(a147+a146);
  a127=(a127-a147);
  a151=(a132*a151);
  a152=(a084*a152);
  a151=(a151+a152);
  a127=(a127+a151);
  a057=(a085*a057);
  a150=(a061*a150);
  a057=(a057+a150);
  a127=(a127-a057);
  a148=(a138*a148);
  a154=(a063*a154);
  a148=(a148+a154);
  a127=(a127+a148);
  a008=(a008+a127);
  if (res[1]!=0) res[1][20]=a008;
  a008=(a013*a141);
  a127=(a130*a008);
  a148=(a011*a126);
  a154=(a119*a148);
  a127=(a127-a154);
  a141=(a011*a141);
  a154=(a131*a141);
  a127=(a127-a154);
  a154=(a013*a153);
  a057=(a136*a154);
  a127=(a127+a057);
  a153=(a011*a153);
  a057=(a137*a153);
  a127=(a127-a057);
  a126=(a013*a126);
  a057=(a110*a126);
  a127=(a127+a057);
  if (res[1]!=0) res[1][21]=a127;
  a126=(a145*a126);
  a008=(a143*a008);
  a154=(a075*a154);
  a008=(a008+a154);
  a126=(a126+a008);
  a126=(-a126);
  if (res[1]!=0) res[1][22]=a126;
  a141=(a143*a141);
  a148=(a145*a148);
  a141=(a141+a148);
  a153=(a075*a153);
  a141=(a141+a153);
  if (res[1]!=0) res[1][23]=a141;
  a025=(2.*a025);
  a025=(a025*a002);
  a016=(a016*a025);
  a066=(a066*a016);
  a066=(a054-a066);
  a141=(a031*a066);
  a056=(a056*a016);
  a056=(a056+a064);
  a153=(a030*a056);
  a148=(a037*a025);
  a006=(a006*a148);
  a062=(a062*a016);
  a062=(a006-a062);
  a148=(a026*a062);
  a153=(a153+a148);
  a141=(a141-a153);
  a153=(a027*a141);
  a148=(a020*a066);
  a126=(a019*a056);
  a008=(a017*a062);
  a126=(a126+a008);
  a148=(a148-a126);
  a126=(a069*a148);
  a153=(a153+a126);
  a066=(a000*a066);
  a056=(a010*a056);
  a062=(a004*a062);
  a056=(a056+a062);
  a066=(a066-a056);
  a056=(a071*a066);
  a153=(a153+a056);
  if (res[1]!=0) res[1][24]=a153;
  a039=(a039*a016);
  a039=(a139-a039);
  a153=(a030*a039);
  a015=(a015*a016);
  a054=(a054-a015);
  a015=(a026*a054);
  a153=(a153+a015);
  a042=(a042*a016);
  a015=(a031*a042);
  a153=(a153+a015);
  a015=(a063*a153);
  a056=(a019*a039);
  a062=(a017*a054);
  a056=(a056+a062);
  a062=(a020*a042);
  a056=(a056+a062);
  a062=(a084*a056);
  a015=(a015+a062);
  a039=(a010*a039);
  a054=(a004*a054);
  a039=(a039+a054);
  a042=(a000*a042);
  a039=(a039+a042);
  a042=(a086*a039);
  a015=(a015+a042);
  if (res[1]!=0) res[1][25]=a015;
  a073=(a073*a016);
  a064=(a064-a073);
  a073=(a026*a064);
  a068=(a068*a016);
  a006=(a006-a068);
  a068=(a030*a006);
  a073=(a073-a068);
  a076=(a076*a016);
  a139=(a139-a076);
  a076=(a031*a139);
  a073=(a073+a076);
  a076=(a061*a073);
  a016=(a017*a064);
  a068=(a019*a006);
  a016=(a016-a068);
  a068=(a020*a139);
  a016=(a016+a068);
  a068=(a092*a016);
  a076=(a076+a068);
  a064=(a004*a064);
  a006=(a010*a006);
  a064=(a064-a006);
  a139=(a000*a139);
  a064=(a064+a139);
  a139=(a094*a064);
  a076=(a076+a139);
  if (res[1]!=0) res[1][26]=a076;
  if (res[1]!=0) res[1][27]=a041;
  if (res[1]!=0) res[1][28]=a041;
  if (res[1]!=0) res[1][29]=a041;
  a133=(a003*a133);
  a034=(a034/a018);
  a034=(a034-a142);
  a034=(a090*a034);
  a133=(a133+a034);
  a091=(a091+a133);
  a133=(a125*a039);
  a034=(a001*a066);
  a142=(a009*a064);
  a034=(a034+a142);
  a034=(a034-a039);
  a034=(2.*a034);
  a034=(a002*a034);
  a142=(a001*a034);
  a076=(a071*a142);
  a133=(a133+a076);
  a076=(a129*a148);
  a139=(a001*a148);
  a006=(a009*a016);
  a139=(a139+a006);
  a139=(a139-a056);
  a139=(2.*a139);
  a139=(a002*a139);
  a006=(a092*a139);
  a076=(a076+a006);
  a133=(a133+a076);
  a076=(a132*a056);
  a006=(a001*a139);
  a068=(a069*a006);
  a076=(a076+a068);
  a133=(a133+a076);
  a076=(a134*a141);
  a068=(a001*a141);
  a015=(a009*a073);
  a068=(a068+a015);
  a068=(a068-a153);
  a068=(2.*a068);
  a068=(a002*a068);
  a015=(a061*a068);
  a076=(a076+a015);
  a133=(a133+a076);
  a076=(a138*a153);
  a015=(a001*a068);
  a042=(a027*a015);
  a076=(a076+a042);
  a133=(a133+a076);
  a076=(a140*a066);
  a042=(a094*a034);
  a076=(a076+a042);
  a133=(a133+a076);
  a091=(a091-a133);
  if (res[1]!=0) res[1][30]=a091;
  a053=(a003*a053);
  a024=(a024/a018);
  a047=(a047+a024);
  a047=(a090*a047);
  a053=(a053+a047);
  a053=(a053-a049);
  a049=(a129*a016);
  a047=(a084*a139);
  a049=(a049+a047);
  a039=(a043*a039);
  a047=(a009*a034);
  a024=(a071*a047);
  a039=(a039-a024);
  a049=(a049-a039);
  a056=(a080*a056);
  a039=(a009*a139);
  a024=(a069*a039);
  a056=(a056+a024);
  a049=(a049+a056);
  a056=(a134*a073);
  a024=(a063*a068);
  a056=(a056+a024);
  a049=(a049+a056);
  a153=(a085*a153);
  a056=(a009*a068);
  a024=(a027*a056);
  a153=(a153+a024);
  a049=(a049+a153);
  a153=(a140*a064);
  a024=(a086*a034);
  a153=(a153+a024);
  a049=(a049+a153);
  a053=(a053+a049);
  if (res[1]!=0) res[1][31]=a053;
  a079=(a079+a050);
  a025=(a058*a025);
  a003=(a003*a025);
  a023=(a023/a018);
  a023=(a044+a023);
  a090=(a090*a023);
  a003=(a003+a090);
  a079=(a079+a003);
  a066=(a043*a066);
  a047=(a094*a047);
  a066=(a066-a047);
  a064=(a125*a064);
  a142=(a086*a142);
  a064=(a064+a142);
  a066=(a066+a064);
  a148=(a080*a148);
  a039=(a092*a039);
  a148=(a148+a039);
  a066=(a066-a148);
  a016=(a132*a016);
  a006=(a084*a006);
  a016=(a016+a006);
  a066=(a066+a016);
  a141=(a085*a141);
  a056=(a061*a056);
  a141=(a141+a056);
  a066=(a066-a141);
  a073=(a138*a073);
  a015=(a063*a015);
  a073=(a073+a015);
  a066=(a066+a073);
  a079=(a079+a066);
  if (res[1]!=0) res[1][32]=a079;
  a079=(a013*a139);
  a066=(a130*a079);
  a073=(a011*a034);
  a015=(a119*a073);
  a066=(a066-a015);
  a139=(a011*a139);
  a015=(a131*a139);
  a066=(a066-a015);
  a015=(a013*a068);
  a141=(a136*a015);
  a066=(a066+a141);
  a068=(a011*a068);
  a141=(a137*a068);
  a066=(a066-a141);
  a034=(a013*a034);
  a141=(a110*a034);
  a066=(a066+a141);
  if (res[1]!=0) res[1][33]=a066;
  a034=(a145*a034);
  a079=(a143*a079);
  a015=(a075*a015);
  a079=(a079+a015);
  a034=(a034+a079);
  a034=(-a034);
  if (res[1]!=0) res[1][34]=a034;
  a139=(a143*a139);
  a073=(a145*a073);
  a139=(a139+a073);
  a068=(a075*a068);
  a139=(a139+a068);
  if (res[1]!=0) res[1][35]=a139;
  if (res[1]!=0) res[1][36]=a041;
  if (res[1]!=0) res[1][37]=a041;
  if (res[1]!=0) res[1][38]=a041;
  a139=(a100*a002);
  a068=(a037*a139);
  a068=(a106*a068);
  a102=(a106/a102);
  a073=(2.*a097);
  a073=(a073*a002);
  a034=(a102*a073);
  a079=(a108*a034);
  a079=(a068-a079);
  a015=(a045*a079);
  a066=(a037*a073);
  a066=(a106*a066);
  a141=(a111*a034);
  a141=(a066-a141);
  a056=(a032*a141);
  a015=(a015-a056);
  a056=(a106*a002);
  a016=(a114*a034);
  a016=(a056-a016);
  a006=(a033*a016);
  a015=(a015+a006);
  a006=(a137*a015);
  a148=(a005*a079);
  a039=(a021*a141);
  a148=(a148-a039);
  a039=(a022*a016);
  a148=(a148+a039);
  a039=(a131*a148);
  a006=(a006+a039);
  a079=(a036*a079);
  a141=(a012*a141);
  a079=(a079-a141);
  a016=(a014*a016);
  a079=(a079+a016);
  a016=(a119*a079);
  a006=(a006+a016);
  if (res[1]!=0) res[1][39]=a006;
  a006=(a104*a002);
  a016=(a037*a006);
  a016=(a106*a016);
  a141=(a117*a034);
  a141=(a016-a141);
  a039=(a045*a141);
  a064=(a121*a034);
  a064=(a064+a056);
  a142=(a032*a064);
  a039=(a039-a142);
  a142=(a123*a034);
  a066=(a066-a142);
  a142=(a033*a066);
  a039=(a039-a142);
  a142=(a075*a039);
  a047=(a005*a141);
  a003=(a021*a064);
  a047=(a047-a003);
  a003=(a022*a066);
  a047=(a047-a003);
  a003=(a143*a047);
  a142=(a142+a003);
  a141=(a036*a141);
  a064=(a012*a064);
  a141=(a141-a064);
  a066=(a014*a066);
  a141=(a141-a066);
  a066=(a145*a141);
  a142=(a142+a066);
  if (res[1]!=0) res[1][40]=a142;
  a142=(a059*a034);
  a066=(a045*a142);
  a064=(a135*a034);
  a064=(a068-a064);
  a003=(a032*a064);
  a066=(a066+a003);
  a034=(a088*a034);
  a034=(a016-a034);
  a003=(a033*a034);
  a066=(a066+a003);
  a003=(a136*a066);
  a090=(a005*a142);
  a023=(a021*a064);
  a090=(a090+a023);
  a023=(a022*a034);
  a090=(a090+a023);
  a023=(a130*a090);
  a003=(a003+a023);
  a142=(a036*a142);
  a064=(a012*a064);
  a142=(a142+a064);
  a034=(a014*a034);
  a142=(a142+a034);
  a034=(a110*a142);
  a003=(a003+a034);
  if (res[1]!=0) res[1][41]=a003;
  a003=(a011*a079);
  a034=(a013*a141);
  a003=(a003+a034);
  a003=(2.*a003);
  a003=(a002*a003);
  a034=(a001*a003);
  a064=(a071*a034);
  a023=(a011*a148);
  a025=(a013*a047);
  a023=(a023+a025);
  a023=(2.*a023);
  a023=(a002*a023);
  a025=(a092*a023);
  a064=(a064+a025);
  a025=(a001*a023);
  a050=(a069*a025);
  a064=(a064+a050);
  a050=(a011*a015);
  a053=(a013*a039);
  a050=(a050+a053);
  a050=(2.*a050);
  a050=(a002*a050);
  a053=(a061*a050);
  a064=(a064+a053);
  a053=(a001*a050);
  a049=(a027*a053);
  a064=(a064+a049);
  a049=(a094*a003);
  a064=(a064+a049);
  a064=(-a064);
  if (res[1]!=0) res[1][42]=a064;
  a064=(a084*a023);
  a049=(a009*a003);
  a153=(a071*a049);
  a064=(a064+a153);
  a153=(a009*a023);
  a024=(a069*a153);
  a064=(a064+a024);
  a024=(a063*a050);
  a064=(a064+a024);
  a024=(a009*a050);
  a091=(a027*a024);
  a064=(a064+a091);
  a091=(a086*a003);
  a064=(a064+a091);
  if (res[1]!=0) res[1][43]=a064;
  a034=(a086*a034);
  a049=(a094*a049);
  a034=(a034-a049);
  a153=(a092*a153);
  a034=(a034-a153);
  a025=(a084*a025);
  a034=(a034+a025);
  a024=(a061*a024);
  a034=(a034-a024);
  a053=(a063*a053);
  a034=(a034+a053);
  if (res[1]!=0) res[1][44]=a034;
  a034=5.9999999999999998e-01;
  a096=(a034*a096);
  a073=(a058*a073);
  a073=(a096*a073);
  a098=(a098/a018);
  a098=(a044+a098);
  a098=(a034*a098);
  a073=(a073+a098);
  a099=(a037*a099);
  a139=(a058*a139);
  a098=(a099*a139);
  a073=(a073+a098);
  a053=1.4999999999999999e-01;
  a103=(a053*a103);
  a006=(a058*a006);
  a024=(a103*a006);
  a073=(a073+a024);
  a025=(a011*a007);
  a028=(a028-a025);
  a141=(a028*a141);
  a025=(a011*a003);
  a153=(a119*a025);
  a141=(a141-a153);
  a153=(a013*a129);
  a148=(a153*a148);
  a049=(a013*a023);
  a064=(a130*a049);
  a148=(a148+a064);
  a141=(a141+a148);
  a148=(a011*a129);
  a047=(a148*a047);
  a023=(a011*a023);
  a064=(a131*a023);
  a047=(a047+a064);
  a141=(a141-a047);
  a047=(a013*a134);
  a015=(a047*a015);
  a064=(a013*a050);
  a091=(a136*a064);
  a015=(a015+a091);
  a141=(a141+a015);
  a015=(a011*a134);
  a039=(a015*a039);
  a050=(a011*a050);
  a091=(a137*a050);
  a039=(a039+a091);
  a141=(a141-a039);
  a007=(a013*a007);
  a038=(a038-a007);
  a079=(a038*a079);
  a003=(a013*a003);
  a007=(a110*a003);
  a079=(a079-a007);
  a141=(a141-a079);
  a073=(a073+a141);
  if (res[1]!=0) res[1][45]=a073;
  a073=(a096*a139);
  a093=(a093/a018);
  a141=(a104/a029);
  a093=(a093-a141);
  a093=(a034*a093);
  a073=(a073+a093);
  a093=(a103*a040);
  a073=(a073+a093);
  a079=(a038*a142);
  a003=(a145*a003);
  a079=(a079-a003);
  a003=(a153*a090);
  a049=(a143*a049);
  a003=(a003+a049);
  a049=(a047*a066);
  a064=(a075*a064);
  a049=(a049+a064);
  a003=(a003+a049);
  a079=(a079-a003);
  a073=(a073+a079);
  if (res[1]!=0) res[1][46]=a073;
  a073=(a096*a006);
  a079=(a100/a029);
  a144=(a144/a018);
  a144=(a079+a144);
  a034=(a034*a144);
  a073=(a073+a034);
  a034=(a099*a040);
  a073=(a073-a034);
  a090=(a148*a090);
  a023=(a143*a023);
  a090=(a090+a023);
  a142=(a028*a142);
  a025=(a145*a025);
  a142=(a142-a025);
  a090=(a090-a142);
  a066=(a015*a066);
  a050=(a075*a050);
  a066=(a066+a050);
  a090=(a090+a066);
  a073=(a073+a090);
  if (res[1]!=0) res[1][47]=a073;
  if (res[1]!=0) res[1][48]=a041;
  if (res[1]!=0) res[1][49]=a041;
  if (res[1]!=0) res[1][50]=a041;
  a073=(a097*a002);
  a090=(a037*a073);
  a090=(a106*a090);
  a100=(2.*a100);
  a100=(a100*a002);
  a066=(a102*a100);
  a050=(a108*a066);
  a050=(a090-a050);
  a142=(a045*a050);
  a025=(a111*a066);
  a023=(a032*a025);
  a142=(a142+a023);
  a023=(a114*a066);
  a023=(a016-a023);
  a144=(a033*a023);
  a142=(a142+a144);
  a144=(a137*a142);
  a003=(a005*a050);
  a049=(a021*a025);
  a003=(a003+a049);
  a049=(a022*a023);
  a003=(a003+a049);
  a049=(a131*a003);
  a144=(a144+a049);
  a050=(a036*a050);
  a025=(a012*a025);
  a050=(a050+a025);
  a023=(a014*a023);
  a050=(a050+a023);
  a023=(a119*a050);
  a144=(a144+a023);
  if (res[1]!=0) res[1][51]=a144;
  a144=(a117*a066);
  a144=(a056-a144);
  a023=(a045*a144);
  a025=(a121*a066);
  a016=(a016-a025);
  a025=(a032*a016);
  a023=(a023+a025);
  a025=(a037*a100);
  a025=(a106*a025);
  a049=(a123*a066);
  a049=(a025-a049);
  a064=(a033*a049);
  a023=(a023-a064);
  a064=(a075*a023);
  a007=(a005*a144);
  a039=(a021*a016);
  a007=(a007+a039);
  a039=(a022*a049);
  a007=(a007-a039);
  a039=(a143*a007);
  a064=(a064+a039);
  a144=(a036*a144);
  a016=(a012*a016);
  a144=(a144+a016);
  a049=(a014*a049);
  a144=(a144-a049);
  a049=(a145*a144);
  a064=(a064+a049);
  if (res[1]!=0) res[1][52]=a064;
  a064=(a135*a066);
  a064=(a090-a064);
  a049=(a032*a064);
  a016=(a059*a066);
  a025=(a025-a016);
  a016=(a045*a025);
  a049=(a049-a016);
  a066=(a088*a066);
  a066=(a066+a056);
  a016=(a033*a066);
  a049=(a049-a016);
  a016=(a136*a049);
  a039=(a021*a064);
  a091=(a005*a025);
  a039=(a039-a091);
  a091=(a022*a066);
  a039=(a039-a091);
  a091=(a130*a039);
  a016=(a016+a091);
  a064=(a012*a064);
  a025=(a036*a025);
  a064=(a064-a025);
  a066=(a014*a066);
  a064=(a064-a066);
  a066=(a110*a064);
  a016=(a016+a066);
  if (res[1]!=0) res[1][53]=a016;
  a016=(a011*a050);
  a066=(a013*a144);
  a016=(a016+a066);
  a016=(2.*a016);
  a016=(a002*a016);
  a066=(a001*a016);
  a025=(a071*a066);
  a091=(a011*a003);
  a133=(a013*a007);
  a091=(a091+a133);
  a091=(2.*a091);
  a091=(a002*a091);
  a133=(a092*a091);
  a025=(a025+a133);
  a133=(a001*a091);
  a076=(a069*a133);
  a025=(a025+a076);
  a076=(a011*a142);
  a042=(a013*a023);
  a076=(a076+a042);
  a076=(2.*a076);
  a076=(a002*a076);
  a042=(a061*a076);
  a025=(a025+a042);
  a042=(a001*a076);
  a054=(a027*a042);
  a025=(a025+a054);
  a054=(a094*a016);
  a025=(a025+a054);
  a025=(-a025);
  if (res[1]!=0) res[1][54]=a025;
  a025=(a084*a091);
  a054=(a009*a016);
  a062=(a071*a054);
  a025=(a025+a062);
  a062=(a009*a091);
  a126=(a069*a062);
  a025=(a025+a126);
  a126=(a063*a076);
  a025=(a025+a126);
  a126=(a009*a076);
  a008=(a027*a126);
  a025=(a025+a008);
  a008=(a086*a016);
  a025=(a025+a008);
  if (res[1]!=0) res[1][55]=a025;
  a066=(a086*a066);
  a054=(a094*a054);
  a066=(a066-a054);
  a062=(a092*a062);
  a066=(a066-a062);
  a133=(a084*a133);
  a066=(a066+a133);
  a126=(a061*a126);
  a066=(a066-a126);
  a042=(a063*a042);
  a066=(a066+a042);
  if (res[1]!=0) res[1][56]=a066;
  a073=(a058*a073);
  a066=(a099*a073);
  a107=(a107/a018);
  a141=(a141+a107);
  a141=(a037*a141);
  a066=(a066+a141);
  a066=(a066-a093);
  a144=(a028*a144);
  a093=(a011*a016);
  a141=(a119*a093);
  a144=(a144-a141);
  a003=(a153*a003);
  a141=(a013*a091);
  a107=(a130*a141);
  a003=(a003+a107);
  a144=(a144+a003);
  a007=(a148*a007);
  a091=(a011*a091);
  a003=(a131*a091);
  a007=(a007+a003);
  a144=(a144-a007);
  a142=(a047*a142);
  a007=(a013*a076);
  a003=(a136*a007);
  a142=(a142+a003);
  a144=(a144+a142);
  a023=(a015*a023);
  a076=(a011*a076);
  a142=(a137*a076);
  a023=(a023+a142);
  a144=(a144-a023);
  a050=(a038*a050);
  a016=(a013*a016);
  a023=(a110*a016);
  a050=(a050-a023);
  a144=(a144-a050);
  a066=(a066+a144);
  if (res[1]!=0) res[1][57]=a066;
  a066=(a096*a073);
  a100=(a058*a100);
  a100=(a099*a100);
  a101=(a101/a018);
  a101=(a044+a101);
  a101=(a037*a101);
  a100=(a100+a101);
  a100=(a066+a100);
  a100=(a100+a024);
  a024=(a038*a064);
  a016=(a145*a016);
  a024=(a024-a016);
  a016=(a153*a039);
  a141=(a143*a141);
  a016=(a016+a141);
  a141=(a047*a049);
  a007=(a075*a007);
  a141=(a141+a007);
  a016=(a016+a141);
  a024=(a024-a016);
  a100=(a100+a024);
  if (res[1]!=0) res[1][58]=a100;
  a096=(a096*a040);
  a099=(a099*a006);
  a113=(a113/a018);
  a097=(a097/a029);
  a113=(a113-a097);
  a113=(a037*a113);
  a099=(a099+a113);
  a099=(a096+a099);
  a039=(a148*a039);
  a091=(a143*a091);
  a039=(a039+a091);
  a064=(a028*a064);
  a093=(a145*a093);
  a064=(a064-a093);
  a039=(a039-a064);
  a049=(a015*a049);
  a076=(a075*a076);
  a049=(a049+a076);
  a039=(a039+a049);
  a099=(a099+a039);
  if (res[1]!=0) res[1][59]=a099;
  if (res[1]!=0) res[1][60]=a041;
  if (res[1]!=0) res[1][61]=a041;
  if (res[1]!=0) res[1][62]=a041;
  a104=(2.*a104);
  a104=(a104*a002);
  a102=(a102*a104);
  a114=(a114*a102);
  a114=(a068-a114);
  a099=(a033*a114);
  a108=(a108*a102);
  a108=(a108+a056);
  a039=(a045*a108);
  a037=(a037*a104);
  a106=(a106*a037);
  a111=(a111*a102);
  a111=(a106-a111);
  a037=(a032*a111);
  a039=(a039+a037);
  a099=(a099-a039);
  a039=(a137*a099);
  a037=(a022*a114);
  a049=(a005*a108);
  a076=(a021*a111);
  a049=(a049+a076);
  a037=(a037-a049);
  a049=(a131*a037);
  a039=(a039+a049);
  a114=(a014*a114);
  a108=(a036*a108);
  a111=(a012*a111);
  a108=(a108+a111);
  a114=(a114-a108);
  a108=(a119*a114);
  a039=(a039+a108);
  if (res[1]!=0) res[1][63]=a039;
  a117=(a117*a102);
  a117=(a090-a117);
  a039=(a045*a117);
  a121=(a121*a102);
  a068=(a068-a121);
  a121=(a032*a068);
  a039=(a039+a121);
  a123=(a123*a102);
  a121=(a033*a123);
  a039=(a039+a121);
  a121=(a075*a039);
  a108=(a005*a117);
  a111=(a021*a068);
  a108=(a108+a111);
  a111=(a022*a123);
  a108=(a108+a111);
  a111=(a143*a108);
  a121=(a121+a111);
  a117=(a036*a117);
  a068=(a012*a068);
  a117=(a117+a068);
  a123=(a014*a123);
  a117=(a117+a123);
  a123=(a145*a117);
  a121=(a121+a123);
  if (res[1]!=0) res[1][64]=a121;
  a135=(a135*a102);
  a056=(a056-a135);
  a135=(a032*a056);
  a059=(a059*a102);
  a106=(a106-a059);
  a059=(a045*a106);
  a135=(a135-a059);
  a088=(a088*a102);
  a090=(a090-a088);
  a088=(a033*a090);
  a135=(a135+a088);
  a088=(a136*a135);
  a102=(a021*a056);
  a059=(a005*a106);
  a102=(a102-a059);
  a059=(a022*a090);
  a102=(a102+a059);
  a059=(a130*a102);
  a088=(a088+a059);
  a056=(a012*a056);
  a106=(a036*a106);
  a056=(a056-a106);
  a090=(a014*a090);
  a056=(a056+a090);
  a090=(a110*a056);
  a088=(a088+a090);
  if (res[1]!=0) res[1][65]=a088;
  a088=(a011*a114);
  a090=(a013*a117);
  a088=(a088+a090);
  a088=(2.*a088);
  a088=(a002*a088);
  a090=(a001*a088);
  a106=(a071*a090);
  a059=(a011*a037);
  a121=(a013*a108);
  a059=(a059+a121);
  a059=(2.*a059);
  a059=(a002*a059);
  a121=(a092*a059);
  a106=(a106+a121);
  a121=(a001*a059);
  a123=(a069*a121);
  a106=(a106+a123);
  a123=(a011*a099);
  a068=(a013*a039);
  a123=(a123+a068);
  a123=(2.*a123);
  a123=(a002*a123);
  a068=(a061*a123);
  a106=(a106+a068);
  a068=(a001*a123);
  a111=(a027*a068);
  a106=(a106+a111);
  a111=(a094*a088);
  a106=(a106+a111);
  a106=(-a106);
  if (res[1]!=0) res[1][66]=a106;
  a106=(a084*a059);
  a111=(a009*a088);
  a049=(a071*a111);
  a106=(a106+a049);
  a049=(a009*a059);
  a076=(a069*a049);
  a106=(a106+a076);
  a076=(a063*a123);
  a106=(a106+a076);
  a076=(a009*a123);
  a064=(a027*a076);
  a106=(a106+a064);
  a064=(a086*a088);
  a106=(a106+a064);
  if (res[1]!=0) res[1][67]=a106;
  a090=(a086*a090);
  a111=(a094*a111);
  a090=(a090-a111);
  a049=(a092*a049);
  a090=(a090-a049);
  a121=(a084*a121);
  a090=(a090+a121);
  a076=(a061*a076);
  a090=(a090-a076);
  a068=(a063*a068);
  a090=(a090+a068);
  if (res[1]!=0) res[1][68]=a090;
  a073=(a103*a073);
  a116=(a116/a018);
  a116=(a116-a079);
  a116=(a053*a116);
  a073=(a073+a116);
  a034=(a034+a073);
  a117=(a028*a117);
  a073=(a011*a088);
  a116=(a119*a073);
  a117=(a117-a116);
  a037=(a153*a037);
  a116=(a013*a059);
  a079=(a130*a116);
  a037=(a037+a079);
  a117=(a117+a037);
  a108=(a148*a108);
  a059=(a011*a059);
  a037=(a131*a059);
  a108=(a108+a037);
  a117=(a117-a108);
  a099=(a047*a099);
  a108=(a013*a123);
  a037=(a136*a108);
  a099=(a099+a037);
  a117=(a117+a099);
  a039=(a015*a039);
  a123=(a011*a123);
  a099=(a137*a123);
  a039=(a039+a099);
  a117=(a117-a039);
  a114=(a038*a114);
  a088=(a013*a088);
  a039=(a110*a088);
  a114=(a114-a039);
  a117=(a117-a114);
  a034=(a034+a117);
  if (res[1]!=0) res[1][69]=a034;
  a139=(a103*a139);
  a120=(a120/a018);
  a097=(a097+a120);
  a097=(a053*a097);
  a139=(a139+a097);
  a139=(a139-a096);
  a096=(a038*a056);
  a088=(a145*a088);
  a096=(a096-a088);
  a088=(a153*a102);
  a116=(a143*a116);
  a088=(a088+a116);
  a116=(a047*a135);
  a108=(a075*a108);
  a116=(a116+a108);
  a088=(a088+a116);
  a096=(a096-a088);
  a139=(a139+a096);
  if (res[1]!=0) res[1][70]=a139;
  a066=(a066+a098);
  a058=(a058*a104);
  a103=(a103*a058);
  a105=(a105/a018);
  a044=(a044+a105);
  a053=(a053*a044);
  a103=(a103+a053);
  a066=(a066+a103);
  a102=(a148*a102);
  a059=(a143*a059);
  a102=(a102+a059);
  a056=(a028*a056);
  a073=(a145*a073);
  a056=(a056-a073);
  a102=(a102-a056);
  a135=(a015*a135);
  a123=(a075*a123);
  a135=(a135+a123);
  a102=(a102+a135);
  a066=(a066+a102);
  if (res[1]!=0) res[1][71]=a066;
  a066=(a082*a031);
  a102=(a087*a026);
  a066=(a066-a102);
  a102=(a027*a066);
  a135=(a082*a020);
  a123=(a087*a017);
  a135=(a135-a123);
  a123=(a069*a135);
  a102=(a102+a123);
  a123=(a082*a000);
  a056=(a087*a004);
  a123=(a123-a056);
  a056=(a071*a123);
  a102=(a102+a056);
  if (res[2]!=0) res[2][0]=a102;
  a102=(a035*a031);
  a056=(a052*a026);
  a102=(a102-a056);
  a056=(a063*a102);
  a073=(a035*a020);
  a059=(a052*a017);
  a073=(a073-a059);
  a059=(a084*a073);
  a056=(a056+a059);
  a059=(a035*a000);
  a103=(a052*a004);
  a059=(a059-a103);
  a103=(a086*a059);
  a056=(a056+a103);
  if (res[2]!=0) res[2][1]=a056;
  a056=(a074*a031);
  a103=(a077*a026);
  a056=(a056-a103);
  a103=(a061*a056);
  a053=(a074*a020);
  a044=(a077*a017);
  a053=(a053-a044);
  a044=(a092*a053);
  a103=(a103+a044);
  a044=(a074*a000);
  a105=(a077*a004);
  a044=(a044-a105);
  a105=(a094*a044);
  a103=(a103+a105);
  if (res[2]!=0) res[2][2]=a103;
  if (res[2]!=0) res[2][3]=a041;
  if (res[2]!=0) res[2][4]=a041;
  if (res[2]!=0) res[2][5]=a041;
  a103=(a125*a059);
  a105=(a001*a123);
  a018=(a009*a044);
  a105=(a105+a018);
  a105=(a105-a059);
  a105=(2.*a105);
  a105=(a002*a105);
  a018=(a001*a105);
  a058=(a071*a018);
  a103=(a103+a058);
  a058=(a129*a135);
  a104=(a001*a135);
  a098=(a009*a053);
  a104=(a104+a098);
  a104=(a104-a073);
  a104=(2.*a104);
  a104=(a002*a104);
  a098=(a092*a104);
  a058=(a058+a098);
  a103=(a103+a058);
  a058=(a132*a073);
  a098=(a001*a104);
  a139=(a069*a098);
  a058=(a058+a139);
  a103=(a103+a058);
  a058=(a134*a066);
  a139=(a001*a066);
  a096=(a009*a056);
  a139=(a139+a096);
  a139=(a139-a102);
  a139=(2.*a139);
  a139=(a002*a139);
  a096=(a061*a139);
  a058=(a058+a096);
  a103=(a103+a058);
  a058=(a138*a102);
  a096=(a001*a139);
  a088=(a027*a096);
  a058=(a058+a088);
  a103=(a103+a058);
  a058=(a140*a123);
  a088=(a094*a105);
  a058=(a058+a088);
  a103=(a103+a058);
  a103=(-a103);
  if (res[2]!=0) res[2][6]=a103;
  a103=(a129*a053);
  a058=(a084*a104);
  a103=(a103+a058);
  a059=(a043*a059);
  a058=(a009*a105);
  a088=(a071*a058);
  a059=(a059-a088);
  a103=(a103-a059);
  a073=(a080*a073);
  a059=(a009*a104);
  a088=(a069*a059);
  a073=(a073+a088);
  a103=(a103+a073);
  a073=(a134*a056);
  a088=(a063*a139);
  a073=(a073+a088);
  a103=(a103+a073);
  a102=(a085*a102);
  a073=(a009*a139);
  a088=(a027*a073);
  a102=(a102+a088);
  a103=(a103+a102);
  a102=(a140*a044);
  a088=(a086*a105);
  a102=(a102+a088);
  a103=(a103+a102);
  if (res[2]!=0) res[2][7]=a103;
  a123=(a043*a123);
  a058=(a094*a058);
  a123=(a123-a058);
  a044=(a125*a044);
  a018=(a086*a018);
  a044=(a044+a018);
  a123=(a123+a044);
  a135=(a080*a135);
  a059=(a092*a059);
  a135=(a135+a059);
  a123=(a123-a135);
  a053=(a132*a053);
  a098=(a084*a098);
  a053=(a053+a098);
  a123=(a123+a053);
  a066=(a085*a066);
  a073=(a061*a073);
  a066=(a066+a073);
  a123=(a123-a066);
  a056=(a138*a056);
  a096=(a063*a096);
  a056=(a056+a096);
  a123=(a123+a056);
  if (res[2]!=0) res[2][8]=a123;
  a123=(a013*a104);
  a056=(a130*a123);
  a096=(a011*a105);
  a066=(a119*a096);
  a056=(a056-a066);
  a104=(a011*a104);
  a066=(a131*a104);
  a056=(a056-a066);
  a066=(a013*a139);
  a073=(a136*a066);
  a056=(a056+a073);
  a139=(a011*a139);
  a073=(a137*a139);
  a056=(a056-a073);
  a105=(a013*a105);
  a073=(a110*a105);
  a056=(a056+a073);
  if (res[2]!=0) res[2][9]=a056;
  a105=(a145*a105);
  a123=(a143*a123);
  a066=(a075*a066);
  a123=(a123+a066);
  a105=(a105+a123);
  a105=(-a105);
  if (res[2]!=0) res[2][10]=a105;
  a104=(a143*a104);
  a096=(a145*a096);
  a104=(a104+a096);
  a139=(a075*a139);
  a104=(a104+a139);
  if (res[2]!=0) res[2][11]=a104;
  a104=(a087*a030);
  a139=(a083*a031);
  a104=(a104-a139);
  a139=(a027*a104);
  a096=(a087*a019);
  a105=(a083*a020);
  a096=(a096-a105);
  a105=(a069*a096);
  a139=(a139+a105);
  a087=(a087*a010);
  a105=(a083*a000);
  a087=(a087-a105);
  a105=(a071*a087);
  a139=(a139+a105);
  if (res[2]!=0) res[2][12]=a139;
  a139=(a052*a030);
  a105=(a046*a031);
  a139=(a139-a105);
  a105=(a063*a139);
  a123=(a052*a019);
  a066=(a046*a020);
  a123=(a123-a066);
  a066=(a084*a123);
  a105=(a105+a066);
  a052=(a052*a010);
  a066=(a046*a000);
  a052=(a052-a066);
  a066=(a086*a052);
  a105=(a105+a066);
  if (res[2]!=0) res[2][13]=a105;
  a105=(a077*a030);
  a031=(a067*a031);
  a105=(a105-a031);
  a031=(a061*a105);
  a066=(a077*a019);
  a020=(a067*a020);
  a066=(a066-a020);
  a020=(a092*a066);
  a031=(a031+a020);
  a077=(a077*a010);
  a000=(a067*a000);
  a077=(a077-a000);
  a000=(a094*a077);
  a031=(a031+a000);
  if (res[2]!=0) res[2][14]=a031;
  if (res[2]!=0) res[2][15]=a041;
  if (res[2]!=0) res[2][16]=a041;
  if (res[2]!=0) res[2][17]=a041;
  a031=(a125*a052);
  a000=(a001*a087);
  a020=(a009*a077);
  a000=(a000+a020);
  a000=(a000-a052);
  a000=(2.*a000);
  a000=(a002*a000);
  a020=(a001*a000);
  a056=(a071*a020);
  a031=(a031+a056);
  a056=(a129*a096);
  a073=(a001*a096);
  a053=(a009*a066);
  a073=(a073+a053);
  a073=(a073-a123);
  a073=(2.*a073);
  a073=(a002*a073);
  a053=(a092*a073);
  a056=(a056+a053);
  a031=(a031+a056);
  a056=(a132*a123);
  a053=(a001*a073);
  a098=(a069*a053);
  a056=(a056+a098);
  a031=(a031+a056);
  a056=(a134*a104);
  a098=(a001*a104);
  a135=(a009*a105);
  a098=(a098+a135);
  a098=(a098-a139);
  a098=(2.*a098);
  a098=(a002*a098);
  a135=(a061*a098);
  a056=(a056+a135);
  a031=(a031+a056);
  a056=(a138*a139);
  a135=(a001*a098);
  a059=(a027*a135);
  a056=(a056+a059);
  a031=(a031+a056);
  a056=(a140*a087);
  a059=(a094*a000);
  a056=(a056+a059);
  a031=(a031+a056);
  a031=(-a031);
  if (res[2]!=0) res[2][18]=a031;
  a031=(a129*a066);
  a056=(a084*a073);
  a031=(a031+a056);
  a052=(a043*a052);
  a056=(a009*a000);
  a059=(a071*a056);
  a052=(a052-a059);
  a031=(a031-a052);
  a123=(a080*a123);
  a052=(a009*a073);
  a059=(a069*a052);
  a123=(a123+a059);
  a031=(a031+a123);
  a123=(a134*a105);
  a059=(a063*a098);
  a123=(a123+a059);
  a031=(a031+a123);
  a139=(a085*a139);
  a123=(a009*a098);
  a059=(a027*a123);
  a139=(a139+a059);
  a031=(a031+a139);
  a139=(a140*a077);
  a059=(a086*a000);
  a139=(a139+a059);
  a031=(a031+a139);
  if (res[2]!=0) res[2][19]=a031;
  a087=(a043*a087);
  a056=(a094*a056);
  a087=(a087-a056);
  a077=(a125*a077);
  a020=(a086*a020);
  a077=(a077+a020);
  a087=(a087+a077);
  a096=(a080*a096);
  a052=(a092*a052);
  a096=(a096+a052);
  a087=(a087-a096);
  a066=(a132*a066);
  a053=(a084*a053);
  a066=(a066+a053);
  a087=(a087+a066);
  a104=(a085*a104);
  a123=(a061*a123);
  a104=(a104+a123);
  a087=(a087-a104);
  a105=(a138*a105);
  a135=(a063*a135);
  a105=(a105+a135);
  a087=(a087+a105);
  if (res[2]!=0) res[2][20]=a087;
  a087=(a013*a073);
  a105=(a130*a087);
  a135=(a011*a000);
  a104=(a119*a135);
  a105=(a105-a104);
  a073=(a011*a073);
  a104=(a131*a073);
  a105=(a105-a104);
  a104=(a013*a098);
  a123=(a136*a104);
  a105=(a105+a123);
  a098=(a011*a098);
  a123=(a137*a098);
  a105=(a105-a123);
  a000=(a013*a000);
  a123=(a110*a000);
  a105=(a105+a123);
  if (res[2]!=0) res[2][21]=a105;
  a000=(a145*a000);
  a087=(a143*a087);
  a104=(a075*a104);
  a087=(a087+a104);
  a000=(a000+a087);
  a000=(-a000);
  if (res[2]!=0) res[2][22]=a000;
  a073=(a143*a073);
  a135=(a145*a135);
  a073=(a073+a135);
  a098=(a075*a098);
  a073=(a073+a098);
  if (res[2]!=0) res[2][23]=a073;
  a073=(a083*a026);
  a098=(a082*a030);
  a073=(a073-a098);
  a098=(a027*a073);
  a135=(a083*a017);
  a000=(a082*a019);
  a135=(a135-a000);
  a000=(a069*a135);
  a098=(a098+a000);
  a083=(a083*a004);
  a082=(a082*a010);
  a083=(a083-a082);
  a082=(a071*a083);
  a098=(a098+a082);
  if (res[2]!=0) res[2][24]=a098;
  a098=(a046*a026);
  a082=(a035*a030);
  a098=(a098-a082);
  a082=(a063*a098);
  a000=(a046*a017);
  a087=(a035*a019);
  a000=(a000-a087);
  a087=(a084*a000);
  a082=(a082+a087);
  a046=(a046*a004);
  a035=(a035*a010);
  a046=(a046-a035);
  a035=(a086*a046);
  a082=(a082+a035);
  if (res[2]!=0) res[2][25]=a082;
  a026=(a067*a026);
  a030=(a074*a030);
  a026=(a026-a030);
  a030=(a061*a026);
  a017=(a067*a017);
  a019=(a074*a019);
  a017=(a017-a019);
  a019=(a092*a017);
  a030=(a030+a019);
  a067=(a067*a004);
  a074=(a074*a010);
  a067=(a067-a074);
  a074=(a094*a067);
  a030=(a030+a074);
  if (res[2]!=0) res[2][26]=a030;
  if (res[2]!=0) res[2][27]=a041;
  if (res[2]!=0) res[2][28]=a041;
  if (res[2]!=0) res[2][29]=a041;
  a030=(a125*a046);
  a074=(a001*a083);
  a010=(a009*a067);
  a074=(a074+a010);
  a074=(a074-a046);
  a074=(2.*a074);
  a074=(a002*a074);
  a010=(a001*a074);
  a004=(a071*a010);
  a030=(a030+a004);
  a004=(a129*a135);
  a019=(a001*a135);
  a082=(a009*a017);
  a019=(a019+a082);
  a019=(a019-a000);
  a019=(2.*a019);
  a019=(a002*a019);
  a082=(a092*a019);
  a004=(a004+a082);
  a030=(a030+a004);
  a004=(a132*a000);
  a082=(a001*a019);
  a035=(a069*a082);
  a004=(a004+a035);
  a030=(a030+a004);
  a004=(a134*a073);
  a035=(a001*a073);
  a087=(a009*a026);
  a035=(a035+a087);
  a035=(a035-a098);
  a035=(2.*a035);
  a035=(a002*a035);
  a087=(a061*a035);
  a004=(a004+a087);
  a030=(a030+a004);
  a004=(a138*a098);
  a087=(a001*a035);
  a104=(a027*a087);
  a004=(a004+a104);
  a030=(a030+a004);
  a004=(a140*a083);
  a104=(a094*a074);
  a004=(a004+a104);
  a030=(a030+a004);
  a030=(-a030);
  if (res[2]!=0) res[2][30]=a030;
  a129=(a129*a017);
  a030=(a084*a019);
  a129=(a129+a030);
  a046=(a043*a046);
  a030=(a009*a074);
  a004=(a071*a030);
  a046=(a046-a004);
  a129=(a129-a046);
  a000=(a080*a000);
  a046=(a009*a019);
  a004=(a069*a046);
  a000=(a000+a004);
  a129=(a129+a000);
  a134=(a134*a026);
  a000=(a063*a035);
  a134=(a134+a000);
  a129=(a129+a134);
  a098=(a085*a098);
  a134=(a009*a035);
  a000=(a027*a134);
  a098=(a098+a000);
  a129=(a129+a098);
  a140=(a140*a067);
  a098=(a086*a074);
  a140=(a140+a098);
  a129=(a129+a140);
  if (res[2]!=0) res[2][31]=a129;
  a043=(a043*a083);
  a030=(a094*a030);
  a043=(a043-a030);
  a125=(a125*a067);
  a010=(a086*a010);
  a125=(a125+a010);
  a043=(a043+a125);
  a080=(a080*a135);
  a046=(a092*a046);
  a080=(a080+a046);
  a043=(a043-a080);
  a132=(a132*a017);
  a082=(a084*a082);
  a132=(a132+a082);
  a043=(a043+a132);
  a085=(a085*a073);
  a134=(a061*a134);
  a085=(a085+a134);
  a043=(a043-a085);
  a138=(a138*a026);
  a087=(a063*a087);
  a138=(a138+a087);
  a043=(a043+a138);
  if (res[2]!=0) res[2][32]=a043;
  a043=(a013*a019);
  a138=(a130*a043);
  a087=(a011*a074);
  a026=(a119*a087);
  a138=(a138-a026);
  a019=(a011*a019);
  a026=(a131*a019);
  a138=(a138-a026);
  a026=(a013*a035);
  a085=(a136*a026);
  a138=(a138+a085);
  a035=(a011*a035);
  a085=(a137*a035);
  a138=(a138-a085);
  a074=(a013*a074);
  a085=(a110*a074);
  a138=(a138+a085);
  if (res[2]!=0) res[2][33]=a138;
  a074=(a145*a074);
  a043=(a143*a043);
  a026=(a075*a026);
  a043=(a043+a026);
  a074=(a074+a043);
  a074=(-a074);
  if (res[2]!=0) res[2][34]=a074;
  a019=(a143*a019);
  a087=(a145*a087);
  a019=(a019+a087);
  a035=(a075*a035);
  a019=(a019+a035);
  if (res[2]!=0) res[2][35]=a019;
  if (res[2]!=0) res[2][36]=a041;
  if (res[2]!=0) res[2][37]=a041;
  if (res[2]!=0) res[2][38]=a041;
  a019=(a112*a033);
  a035=(a115*a032);
  a019=(a019-a035);
  a035=(a137*a019);
  a087=(a112*a022);
  a074=(a115*a021);
  a087=(a087-a074);
  a074=(a131*a087);
  a035=(a035+a074);
  a074=(a112*a014);
  a043=(a115*a012);
  a074=(a074-a043);
  a043=(a119*a074);
  a035=(a035+a043);
  if (res[2]!=0) res[2][39]=a035;
  a035=(a122*a033);
  a043=(a124*a032);
  a035=(a035-a043);
  a043=(a075*a035);
  a026=(a122*a022);
  a138=(a124*a021);
  a026=(a026-a138);
  a138=(a143*a026);
  a043=(a043+a138);
  a138=(a122*a014);
  a085=(a124*a012);
  a138=(a138-a085);
  a085=(a145*a138);
  a043=(a043+a085);
  if (res[2]!=0) res[2][40]=a043;
  a043=(a070*a033);
  a085=(a128*a032);
  a043=(a043-a085);
  a085=(a136*a043);
  a134=(a070*a022);
  a073=(a128*a021);
  a134=(a134-a073);
  a073=(a130*a134);
  a085=(a085+a073);
  a073=(a070*a014);
  a132=(a128*a012);
  a073=(a073-a132);
  a132=(a110*a073);
  a085=(a085+a132);
  if (res[2]!=0) res[2][41]=a085;
  a085=(a011*a074);
  a132=(a013*a138);
  a085=(a085+a132);
  a085=(2.*a085);
  a085=(a002*a085);
  a132=(a001*a085);
  a082=(a071*a132);
  a017=(a011*a087);
  a080=(a013*a026);
  a017=(a017+a080);
  a017=(2.*a017);
  a017=(a002*a017);
  a080=(a092*a017);
  a082=(a082+a080);
  a080=(a001*a017);
  a046=(a069*a080);
  a082=(a082+a046);
  a046=(a011*a019);
  a135=(a013*a035);
  a046=(a046+a135);
  a046=(2.*a046);
  a046=(a002*a046);
  a135=(a061*a046);
  a082=(a082+a135);
  a135=(a001*a046);
  a125=(a027*a135);
  a082=(a082+a125);
  a125=(a094*a085);
  a082=(a082+a125);
  a082=(-a082);
  if (res[2]!=0) res[2][42]=a082;
  a082=(a084*a017);
  a125=(a009*a085);
  a010=(a071*a125);
  a082=(a082+a010);
  a010=(a009*a017);
  a067=(a069*a010);
  a082=(a082+a067);
  a067=(a063*a046);
  a082=(a082+a067);
  a067=(a009*a046);
  a030=(a027*a067);
  a082=(a082+a030);
  a030=(a086*a085);
  a082=(a082+a030);
  if (res[2]!=0) res[2][43]=a082;
  a132=(a086*a132);
  a125=(a094*a125);
  a132=(a132-a125);
  a010=(a092*a010);
  a132=(a132-a010);
  a080=(a084*a080);
  a132=(a132+a080);
  a067=(a061*a067);
  a132=(a132-a067);
  a135=(a063*a135);
  a132=(a132+a135);
  if (res[2]!=0) res[2][44]=a132;
  a138=(a028*a138);
  a132=(a011*a085);
  a135=(a119*a132);
  a138=(a138-a135);
  a087=(a153*a087);
  a135=(a013*a017);
  a067=(a130*a135);
  a087=(a087+a067);
  a138=(a138+a087);
  a026=(a148*a026);
  a017=(a011*a017);
  a087=(a131*a017);
  a026=(a026+a087);
  a138=(a138-a026);
  a019=(a047*a019);
  a026=(a013*a046);
  a087=(a136*a026);
  a019=(a019+a087);
  a138=(a138+a019);
  a035=(a015*a035);
  a046=(a011*a046);
  a019=(a137*a046);
  a035=(a035+a019);
  a138=(a138-a035);
  a074=(a038*a074);
  a085=(a013*a085);
  a035=(a110*a085);
  a074=(a074-a035);
  a138=(a138-a074);
  if (res[2]!=0) res[2][45]=a138;
  a138=(a038*a073);
  a085=(a145*a085);
  a138=(a138-a085);
  a085=(a153*a134);
  a135=(a143*a135);
  a085=(a085+a135);
  a135=(a047*a043);
  a026=(a075*a026);
  a135=(a135+a026);
  a085=(a085+a135);
  a138=(a138-a085);
  if (res[2]!=0) res[2][46]=a138;
  a134=(a148*a134);
  a017=(a143*a017);
  a134=(a134+a017);
  a073=(a028*a073);
  a132=(a145*a132);
  a073=(a073-a132);
  a134=(a134-a073);
  a043=(a015*a043);
  a046=(a075*a046);
  a043=(a043+a046);
  a134=(a134+a043);
  if (res[2]!=0) res[2][47]=a134;
  if (res[2]!=0) res[2][48]=a041;
  if (res[2]!=0) res[2][49]=a041;
  if (res[2]!=0) res[2][50]=a041;
  a134=(a115*a045);
  a043=(a109*a033);
  a134=(a134-a043);
  a043=(a137*a134);
  a046=(a115*a005);
  a073=(a109*a022);
  a046=(a046-a073);
  a073=(a131*a046);
  a043=(a043+a073);
  a115=(a115*a036);
  a073=(a109*a014);
  a115=(a115-a073);
  a073=(a119*a115);
  a043=(a043+a073);
  if (res[2]!=0) res[2][51]=a043;
  a043=(a124*a045);
  a073=(a118*a033);
  a043=(a043-a073);
  a073=(a075*a043);
  a132=(a124*a005);
  a017=(a118*a022);
  a132=(a132-a017);
  a017=(a143*a132);
  a073=(a073+a017);
  a124=(a124*a036);
  a017=(a118*a014);
  a124=(a124-a017);
  a017=(a145*a124);
  a073=(a073+a017);
  if (res[2]!=0) res[2][52]=a073;
  a073=(a128*a045);
  a033=(a060*a033);
  a073=(a073-a033);
  a033=(a136*a073);
  a017=(a128*a005);
  a022=(a060*a022);
  a017=(a017-a022);
  a022=(a130*a017);
  a033=(a033+a022);
  a128=(a128*a036);
  a014=(a060*a014);
  a128=(a128-a014);
  a014=(a110*a128);
  a033=(a033+a014);
  if (res[2]!=0) res[2][53]=a033;
  a033=(a011*a115);
  a014=(a013*a124);
  a033=(a033+a014);
  a033=(2.*a033);
  a033=(a002*a033);
  a014=(a001*a033);
  a022=(a071*a014);
  a138=(a011*a046);
  a085=(a013*a132);
  a138=(a138+a085);
  a138=(2.*a138);
  a138=(a002*a138);
  a085=(a092*a138);
  a022=(a022+a085);
  a085=(a001*a138);
  a135=(a069*a085);
  a022=(a022+a135);
  a135=(a011*a134);
  a026=(a013*a043);
  a135=(a135+a026);
  a135=(2.*a135);
  a135=(a002*a135);
  a026=(a061*a135);
  a022=(a022+a026);
  a026=(a001*a135);
  a074=(a027*a026);
  a022=(a022+a074);
  a074=(a094*a033);
  a022=(a022+a074);
  a022=(-a022);
  if (res[2]!=0) res[2][54]=a022;
  a022=(a084*a138);
  a074=(a009*a033);
  a035=(a071*a074);
  a022=(a022+a035);
  a035=(a009*a138);
  a019=(a069*a035);
  a022=(a022+a019);
  a019=(a063*a135);
  a022=(a022+a019);
  a019=(a009*a135);
  a087=(a027*a019);
  a022=(a022+a087);
  a087=(a086*a033);
  a022=(a022+a087);
  if (res[2]!=0) res[2][55]=a022;
  a014=(a086*a014);
  a074=(a094*a074);
  a014=(a014-a074);
  a035=(a092*a035);
  a014=(a014-a035);
  a085=(a084*a085);
  a014=(a014+a085);
  a019=(a061*a019);
  a014=(a014-a019);
  a026=(a063*a026);
  a014=(a014+a026);
  if (res[2]!=0) res[2][56]=a014;
  a124=(a028*a124);
  a014=(a011*a033);
  a026=(a119*a014);
  a124=(a124-a026);
  a046=(a153*a046);
  a026=(a013*a138);
  a019=(a130*a026);
  a046=(a046+a019);
  a124=(a124+a046);
  a132=(a148*a132);
  a138=(a011*a138);
  a046=(a131*a138);
  a132=(a132+a046);
  a124=(a124-a132);
  a134=(a047*a134);
  a132=(a013*a135);
  a046=(a136*a132);
  a134=(a134+a046);
  a124=(a124+a134);
  a043=(a015*a043);
  a135=(a011*a135);
  a134=(a137*a135);
  a043=(a043+a134);
  a124=(a124-a043);
  a115=(a038*a115);
  a033=(a013*a033);
  a043=(a110*a033);
  a115=(a115-a043);
  a124=(a124-a115);
  if (res[2]!=0) res[2][57]=a124;
  a124=(a038*a128);
  a033=(a145*a033);
  a124=(a124-a033);
  a033=(a153*a017);
  a026=(a143*a026);
  a033=(a033+a026);
  a026=(a047*a073);
  a132=(a075*a132);
  a026=(a026+a132);
  a033=(a033+a026);
  a124=(a124-a033);
  if (res[2]!=0) res[2][58]=a124;
  a017=(a148*a017);
  a138=(a143*a138);
  a017=(a017+a138);
  a128=(a028*a128);
  a014=(a145*a014);
  a128=(a128-a014);
  a017=(a017-a128);
  a073=(a015*a073);
  a135=(a075*a135);
  a073=(a073+a135);
  a017=(a017+a073);
  if (res[2]!=0) res[2][59]=a017;
  if (res[2]!=0) res[2][60]=a041;
  if (res[2]!=0) res[2][61]=a041;
  if (res[2]!=0) res[2][62]=a041;
  a017=(a109*a032);
  a073=(a112*a045);
  a017=(a017-a073);
  a073=(a137*a017);
  a135=(a109*a021);
  a128=(a112*a005);
  a135=(a135-a128);
  a128=(a131*a135);
  a073=(a073+a128);
  a109=(a109*a012);
  a112=(a112*a036);
  a109=(a109-a112);
  a112=(a119*a109);
  a073=(a073+a112);
  if (res[2]!=0) res[2][63]=a073;
  a073=(a118*a032);
  a112=(a122*a045);
  a073=(a073-a112);
  a112=(a075*a073);
  a128=(a118*a021);
  a014=(a122*a005);
  a128=(a128-a014);
  a014=(a143*a128);
  a112=(a112+a014);
  a118=(a118*a012);
  a122=(a122*a036);
  a118=(a118-a122);
  a122=(a145*a118);
  a112=(a112+a122);
  if (res[2]!=0) res[2][64]=a112;
  a032=(a060*a032);
  a045=(a070*a045);
  a032=(a032-a045);
  a045=(a136*a032);
  a021=(a060*a021);
  a005=(a070*a005);
  a021=(a021-a005);
  a005=(a130*a021);
  a045=(a045+a005);
  a060=(a060*a012);
  a070=(a070*a036);
  a060=(a060-a070);
  a070=(a110*a060);
  a045=(a045+a070);
  if (res[2]!=0) res[2][65]=a045;
  a045=(a011*a109);
  a070=(a013*a118);
  a045=(a045+a070);
  a045=(2.*a045);
  a045=(a002*a045);
  a070=(a001*a045);
  a036=(a071*a070);
  a012=(a011*a135);
  a005=(a013*a128);
  a012=(a012+a005);
  a012=(2.*a012);
  a012=(a002*a012);
  a005=(a092*a012);
  a036=(a036+a005);
  a005=(a001*a012);
  a112=(a069*a005);
  a036=(a036+a112);
  a112=(a011*a017);
  a122=(a013*a073);
  a112=(a112+a122);
  a112=(2.*a112);
  a002=(a002*a112);
  a112=(a061*a002);
  a036=(a036+a112);
  a001=(a001*a002);
  a112=(a027*a001);
  a036=(a036+a112);
  a112=(a094*a045);
  a036=(a036+a112);
  a036=(-a036);
  if (res[2]!=0) res[2][66]=a036;
  a036=(a084*a012);
  a112=(a009*a045);
  a071=(a071*a112);
  a036=(a036+a071);
  a071=(a009*a012);
  a069=(a069*a071);
  a036=(a036+a069);
  a069=(a063*a002);
  a036=(a036+a069);
  a009=(a009*a002);
  a027=(a027*a009);
  a036=(a036+a027);
  a027=(a086*a045);
  a036=(a036+a027);
  if (res[2]!=0) res[2][67]=a036;
  a086=(a086*a070);
  a094=(a094*a112);
  a086=(a086-a094);
  a092=(a092*a071);
  a086=(a086-a092);
  a084=(a084*a005);
  a086=(a086+a084);
  a061=(a061*a009);
  a086=(a086-a061);
  a063=(a063*a001);
  a086=(a086+a063);
  if (res[2]!=0) res[2][68]=a086;
  a118=(a028*a118);
  a086=(a011*a045);
  a119=(a119*a086);
  a118=(a118-a119);
  a135=(a153*a135);
  a119=(a013*a012);
  a130=(a130*a119);
  a135=(a135+a130);
  a118=(a118+a135);
  a128=(a148*a128);
  a012=(a011*a012);
  a131=(a131*a012);
  a128=(a128+a131);
  a118=(a118-a128);
  a017=(a047*a017);
  a128=(a013*a002);
  a136=(a136*a128);
  a017=(a017+a136);
  a118=(a118+a017);
  a073=(a015*a073);
  a011=(a011*a002);
  a137=(a137*a011);
  a073=(a073+a137);
  a118=(a118-a073);
  a109=(a038*a109);
  a013=(a013*a045);
  a110=(a110*a013);
  a109=(a109-a110);
  a118=(a118-a109);
  if (res[2]!=0) res[2][69]=a118;
  a038=(a038*a060);
  a013=(a145*a013);
  a038=(a038-a013);
  a153=(a153*a021);
  a119=(a143*a119);
  a153=(a153+a119);
  a047=(a047*a032);
  a128=(a075*a128);
  a047=(a047+a128);
  a153=(a153+a047);
  a038=(a038-a153);
  if (res[2]!=0) res[2][70]=a038;
  a148=(a148*a021);
  a143=(a143*a012);
  a148=(a148+a143);
  a028=(a028*a060);
  a145=(a145*a086);
  a028=(a028-a145);
  a148=(a148-a028);
  a015=(a015*a032);
  a075=(a075*a011);
  a015=(a015+a075);
  a148=(a148+a015);
  if (res[2]!=0) res[2][71]=a148;
  if (res[2]!=0) res[2][72]=a041;
  if (res[2]!=0) res[2][73]=a041;
  if (res[2]!=0) res[2][74]=a041;
  if (res[2]!=0) res[2][75]=a041;
  if (res[2]!=0) res[2][76]=a041;
  if (res[2]!=0) res[2][77]=a041;
  if (res[2]!=0) res[2][78]=a041;
  if (res[2]!=0) res[2][79]=a041;
  if (res[2]!=0) res[2][80]=a041;
  if (res[2]!=0) res[2][81]=a041;
  if (res[2]!=0) res[2][82]=a041;
  if (res[2]!=0) res[2][83]=a041;
  if (res[2]!=0) res[2][84]=a041;
  if (res[2]!=0) res[2][85]=a041;
  if (res[2]!=0) res[2][86]=a041;
  if (res[2]!=0) res[2][87]=a041;
  if (res[2]!=0) res[2][88]=a041;
  if (res[2]!=0) res[2][89]=a041;
  if (res[2]!=0) res[2][90]=a041;
  if (res[2]!=0) res[2][91]=a041;
  if (res[2]!=0) res[2][92]=a041;
  if (res[2]!=0) res[2][93]=a041;
  if (res[2]!=0) res[2][94]=a041;
  if (res[2]!=0) res[2][95]=a041;
  if (res[2]!=0) res[2][96]=a041;
  if (res[2]!=0) res[2][97]=a041;
  if (res[2]!=0) res[2][98]=a041;
  if (res[2]!=0) res[2][99]=a041;
  if (res[2]!=0) res[2][100]=a041;
  if (res[2]!=0) res[2][101]=a041;
  if (res[2]!=0) res[2][102]=a041;
  if (res[2]!=0) res[2][103]=a041;
  if (res[2]!=0) res[2][104]=a041;
  if (res[2]!=0) res[2][105]=a041;
  if (res[2]!=0) res[2][106]=a041;
  if (res[2]!=0) res[2][107]=a041;
  if (res[2]!=0) res[2][108]=a041;
  if (res[2]!=0) res[2][109]=a041;
  if (res[2]!=0) res[2][110]=a041;
  if (res[2]!=0) res[2][111]=a041;
  if (res[2]!=0) res[2][112]=a041;
  if (res[2]!=0) res[2][113]=a041;
  if (res[2]!=0) res[2][114]=a041;
  if (res[2]!=0) res[2][115]=a041;
  if (res[2]!=0) res[2][116]=a041;
  if (res[2]!=0) res[2][117]=a041;
  if (res[2]!=0) res[2][118]=a041;
  if (res[2]!=0) res[2][119]=a041;
  if (res[2]!=0) res[2][120]=a041;
  if (res[2]!=0) res[2][121]=a041;
  if (res[2]!=0) res[2][122]=a041;
  if (res[2]!=0) res[2][123]=a041;
  if (res[2]!=0) res[2][124]=a041;
  if (res[2]!=0) res[2][125]=a041;
  if (res[2]!=0) res[2][126]=a041;
  if (res[2]!=0) res[2][127]=a041;
  if (res[2]!=0) res[2][128]=a041;
  if (res[2]!=0) res[2][129]=a041;
  if (res[2]!=0) res[2][130]=a041;
  if (res[2]!=0) res[2][131]=a041;
  if (res[2]!=0) res[2][132]=a041;
  if (res[2]!=0) res[2][133]=a041;
  if (res[2]!=0) res[2][134]=a041;
  if (res[2]!=0) res[2][135]=a041;
  if (res[2]!=0) res[2][136]=a041;
  if (res[2]!=0) res[2][137]=a041;
  if (res[2]!=0) res[2][138]=a041;
  if (res[2]!=0) res[2][139]=a041;
  if (res[2]!=0) res[2][140]=a041;
  if (res[2]!=0) res[2][141]=a041;
  if (res[2]!=0) res[2][142]=a041;
  if (res[2]!=0) res[2][143]=a041;
  return 0;
}

CASADI_SYMBOL_EXPORT int step_partials(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f16(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int step_partials_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void step_partials_release(int mem) {
}

CASADI_SYMBOL_EXPORT void step_partials_incref(void) {
}

CASADI_SYMBOL_EXPORT void step_partials_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int step_partials_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int step_partials_n_out(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_real step_partials_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* step_partials_name_in(casadi_int i) {
  switch (i) {
    case 0: return "z";
    case 1: return "g";
    case 2: return "p";
    case 3: return "h";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* step_partials_name_out(casadi_int i) {
  switch (i) {
    case 0: return "Fs";
    case 1: return "Yz";
    case 2: return "Ys";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* step_partials_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s0;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* step_partials_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    case 1: return casadi_s4;
    case 2: return casadi_s5;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int step_partials_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 3;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int step_partials_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 3*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}



/* ======================= end of CasADi-generated code =================================== */
#if defined(__GNUC__)
#pragma GCC visibility pop
#define HPGEN_EXPORT __attribute__((visibility("default")))
#else
#define HPGEN_EXPORT
#endif

#define HPGEN_ABI 6
#define HPGEN_N 6
#define HPGEN_NN (HPGEN_N * HPGEN_N)
#define HPGEN_D 6
#define HPGEN_NZ 6
#define HPGEN_OK 0
#define HPGEN_NO_CONVERGENCE 1
#define HPGEN_NONFINITE 2
#define HPGEN_DOMAIN 3
#define HPGEN_RECORD 4
/* the scene's record row (kernel record): its width and what it needs */
#define HPGEN_W 49
#define HPGEN_RECORD_USES_XI 1
#define HPGEN_LEGENDRE_QUADRATIC 1
/* neither the step (residual, p_{k+1}) nor the record row use g: hpgen_advance_record does
   not reconstruct the group at all */
#define HPGEN_SKIP_G 0
#define HPGEN_INVALID (-1)
/* Newton stalls at round-off: stop when |dz| stopped decreasing while below this * (1+|z|) */
#define HPGEN_ROUNDOFF_FLOOR 1e-11
/* simplified Newton: a contraction rate |dz_k| / |dz_{k-1}| above this refreshes the Jacobian
   (or, with a Jacobian fresh from this step, switches the step to full Newton) */
#define HPGEN_THETA_MAX 0.2
/* simplified Newton stops when its error estimate is below this * tol * (1 + |z|) */
#define HPGEN_SIMPLIFIED_TOL 0.01
/* ... its error estimate takes the contraction rate as at least this (hpgen.abi.THETA_FLOOR) */
#define HPGEN_THETA_FLOOR 0.05
/* the predictor keeps the offsets of this many past steps; row m - 1 of hpgen_pc weighs the
   m newest in the extrapolation through m of them (hpgen.abi.PREDICTOR_COEFFICIENTS) */
#define HPGEN_PH 6
static const double hpgen_pc[HPGEN_PH][HPGEN_PH] = {
    { 1.0, 0.0, 0.0, 0.0, 0.0, 0.0 },
    { 2.0, -1.0, 0.0, 0.0, 0.0, 0.0 },
    { 3.0, -3.0, 1.0, 0.0, 0.0, 0.0 },
    { 4.0, -6.0, 4.0, -1.0, 0.0, 0.0 },
    { 5.0, -10.0, 10.0, -5.0, 1.0, 0.0 },
    { 6.0, -15.0, 20.0, -15.0, 6.0, -1.0 }
};

typedef struct hpgen_status {
    long long code;              /* HPGEN_OK, ... */
    long long step;              /* failing step index, or steps done on success */
    long long iterations;        /* Newton iterations of the last step attempted */
    long long total_iterations;  /* Newton iterations over all steps */
    double residual;             /* inf-norm of the last residual evaluated */
    long long jacobians;         /* Jacobian evaluations (and LU factorizations), all steps */
} hpgen_status;

/* Runtime Newton settings (no recompilation needed to change them). */
typedef struct hpgen_options {
    double tol;                  /* converged when |dz| <= tol (1 + |z|), inf-norms */
    long long maxit;             /* Newton iterations per step, >= 1 */
    long long simplified;        /* 1: keep the Jacobian's LU across iterations and steps */
    long long predictor;         /* 1: start step k+1 from the predictor of hpgen_run_step (else z_k) */
} hpgen_options;

/* A run in progress: the state, the Newton start and the Newton memory. Advancing a run by
   n1 steps and then by n2 steps gives bitwise the same result as by n1 + n2 steps. */
typedef struct hpgen_run {
    double g[HPGEN_NN], p[HPGEN_D];  /* (g_k, p_k) */
    double z[HPGEN_NZ];              /* solution of the last step (or the initial guess) */
    double dz[HPGEN_PH][HPGEN_NZ];   /* predictor: z_j - G_j of the last steps j = k-1, k-2, ...
                                        (G_j the guess at step j's start, see hpgen_run_step) */
    double lu[HPGEN_NZ * HPGEN_NZ];  /* J^{-1} of the last Jacobian (simplified Newton) */
    int piv[HPGEN_NZ];
    long long k;                     /* steps done */
    long long have_prev;             /* how many of dz[0], dz[1], ... are valid (0..HPGEN_PH) */
    long long lu_valid;              /* lu holds J^{-1} */
    double s;                        /* section(g_k, p_k), when s_valid */
    long long s_valid;
    long long g_stale;               /* g is g_0, not g_k (hpgen_advance_record, HPGEN_SKIP_G) */
} hpgen_run;

HPGEN_EXPORT const char* hpgen_hash(void) { return "f1db8c7f42f101f2eff1c614681288e8fab4d5bbe6b695247dbce78a05bbb544"; }

/* out[0..3] = ABI version, n, d, nz */
HPGEN_EXPORT void hpgen_dims(long long* out) {
    out[0] = HPGEN_ABI; out[1] = HPGEN_N; out[2] = HPGEN_D; out[3] = HPGEN_NZ;
}

/* ---- kernel wrappers: dense column-major arguments, CasADi work arrays on the stack ---- */
static int hpgen_k_residual(const double* in0, const double* in1, const double* in2, const double* in3, double* out0);
static int hpgen_k_residual_jacobian(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1);
static int hpgen_k_update(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1);
static int hpgen_k_guess(const double* in0, const double* in1, const double* in2, const double* in3, double* out0);
static int hpgen_k_legendre(const double* in0, const double* in1, double* out0);
static int hpgen_k_hessian(const double* in0, const double* in1, double* out0);
static int hpgen_k_energy(const double* in0, const double* in1, double* out0);
static int hpgen_k_momentum(const double* in0, const double* in1, double* out0);
static int hpgen_k_defect(const double* in0, double* out0);
static int hpgen_k_margin(const double* in0, const double* in1, double* out0);
static int hpgen_k_section(const double* in0, const double* in1, double* out0);
static int hpgen_k_chart_point(const double* in0, const double* in1, const double* in2, const double* in3, double* out0);
static int hpgen_k_observe(const double* in0, const double* in1, double* out0, double* out1, double* out2, double* out3);
static int hpgen_k_update_p(const double* in0, const double* in1, const double* in2, const double* in3, double* out0);
static int hpgen_k_velocity_step(const double* in0, const double* in1, const double* in2, double* out0);
static int hpgen_k_record(const double* in0, const double* in1, const double* in2, double* out0);
static int hpgen_k_step_partials(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1, double* out2);

/* residual(z[6], g[36], p[6], h[1]) -> (F[6]) */
#define HPGEN_RESIDUAL_SZ_ARG 4
#define HPGEN_RESIDUAL_SZ_RES 1
#define HPGEN_RESIDUAL_SZ_IW 0
#define HPGEN_RESIDUAL_SZ_W 42
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_residual exports it */
static int hpgen_k_residual(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    const casadi_real* arg[HPGEN_RESIDUAL_SZ_ARG + 1];
    casadi_real* res[HPGEN_RESIDUAL_SZ_RES + 1];
    casadi_int iw[HPGEN_RESIDUAL_SZ_IW + 1];
    casadi_real w[HPGEN_RESIDUAL_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    arg[3] = in3;
    res[0] = out0;
    flag = residual(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_residual(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    return hpgen_k_residual(in0, in1, in2, in3, out0);
}

/* jacobian(z[6], g[36], p[6], h[1]) -> (J[36]) */
/* = output 1 of residual_jacobian (the same CasADi algorithm; its other outputs are
   computed into scratch and dropped) */
HPGEN_EXPORT int hpgen_kernel_jacobian(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    double scratch[HPGEN_NZ];
    return hpgen_k_residual_jacobian(in0, in1, in2, in3, scratch, out0);
}

/* residual_jacobian(z[6], g[36], p[6], h[1]) -> (F[6], J[36]) */
#define HPGEN_RESIDUAL_JACOBIAN_SZ_ARG 4
#define HPGEN_RESIDUAL_JACOBIAN_SZ_RES 2
#define HPGEN_RESIDUAL_JACOBIAN_SZ_IW 0
#define HPGEN_RESIDUAL_JACOBIAN_SZ_W 51
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_residual_jacobian exports it */
static int hpgen_k_residual_jacobian(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1) {
    const casadi_real* arg[HPGEN_RESIDUAL_JACOBIAN_SZ_ARG + 1];
    casadi_real* res[HPGEN_RESIDUAL_JACOBIAN_SZ_RES + 1];
    casadi_int iw[HPGEN_RESIDUAL_JACOBIAN_SZ_IW + 1];
    casadi_real w[HPGEN_RESIDUAL_JACOBIAN_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    arg[3] = in3;
    res[0] = out0;
    res[1] = out1;
    flag = residual_jacobian(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_residual_jacobian(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1) {
    return hpgen_k_residual_jacobian(in0, in1, in2, in3, out0, out1);
}

/* update(z[6], g[36], p[6], h[1]) -> (g1[36], p1[6]) */
#define HPGEN_UPDATE_SZ_ARG 4
#define HPGEN_UPDATE_SZ_RES 2
#define HPGEN_UPDATE_SZ_IW 0
#define HPGEN_UPDATE_SZ_W 70
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_update exports it */
static int hpgen_k_update(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1) {
    const casadi_real* arg[HPGEN_UPDATE_SZ_ARG + 1];
    casadi_real* res[HPGEN_UPDATE_SZ_RES + 1];
    casadi_int iw[HPGEN_UPDATE_SZ_IW + 1];
    casadi_real w[HPGEN_UPDATE_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    arg[3] = in3;
    res[0] = out0;
    res[1] = out1;
    flag = update(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_update(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1) {
    return hpgen_k_update(in0, in1, in2, in3, out0, out1);
}

/* guess(xi[6], g[36], p[6], h[1]) -> (z0[6]) */
#define HPGEN_GUESS_SZ_ARG 4
#define HPGEN_GUESS_SZ_RES 1
#define HPGEN_GUESS_SZ_IW 0
#define HPGEN_GUESS_SZ_W 1
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_guess exports it */
static int hpgen_k_guess(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    const casadi_real* arg[HPGEN_GUESS_SZ_ARG + 1];
    casadi_real* res[HPGEN_GUESS_SZ_RES + 1];
    casadi_int iw[HPGEN_GUESS_SZ_IW + 1];
    casadi_real w[HPGEN_GUESS_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    arg[3] = in3;
    res[0] = out0;
    flag = guess(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_guess(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    return hpgen_k_guess(in0, in1, in2, in3, out0);
}

/* legendre(g[36], xi[6]) -> (mu[6]) */
#define HPGEN_LEGENDRE_SZ_ARG 2
#define HPGEN_LEGENDRE_SZ_RES 1
#define HPGEN_LEGENDRE_SZ_IW 0
#define HPGEN_LEGENDRE_SZ_W 2
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_legendre exports it */
static int hpgen_k_legendre(const double* in0, const double* in1, double* out0) {
    const casadi_real* arg[HPGEN_LEGENDRE_SZ_ARG + 1];
    casadi_real* res[HPGEN_LEGENDRE_SZ_RES + 1];
    casadi_int iw[HPGEN_LEGENDRE_SZ_IW + 1];
    casadi_real w[HPGEN_LEGENDRE_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    res[0] = out0;
    flag = legendre(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_legendre(const double* in0, const double* in1, double* out0) {
    return hpgen_k_legendre(in0, in1, out0);
}

/* hessian(g[36], xi[6]) -> (H[36]) */
#define HPGEN_HESSIAN_SZ_ARG 2
#define HPGEN_HESSIAN_SZ_RES 1
#define HPGEN_HESSIAN_SZ_IW 0
#define HPGEN_HESSIAN_SZ_W 2
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_hessian exports it */
static int hpgen_k_hessian(const double* in0, const double* in1, double* out0) {
    const casadi_real* arg[HPGEN_HESSIAN_SZ_ARG + 1];
    casadi_real* res[HPGEN_HESSIAN_SZ_RES + 1];
    casadi_int iw[HPGEN_HESSIAN_SZ_IW + 1];
    casadi_real w[HPGEN_HESSIAN_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    res[0] = out0;
    flag = hessian(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_hessian(const double* in0, const double* in1, double* out0) {
    return hpgen_k_hessian(in0, in1, out0);
}

/* energy(g[36], xi[6]) -> (E[1]) */
#define HPGEN_ENERGY_SZ_ARG 2
#define HPGEN_ENERGY_SZ_RES 1
#define HPGEN_ENERGY_SZ_IW 0
#define HPGEN_ENERGY_SZ_W 11
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_energy exports it */
static int hpgen_k_energy(const double* in0, const double* in1, double* out0) {
    const casadi_real* arg[HPGEN_ENERGY_SZ_ARG + 1];
    casadi_real* res[HPGEN_ENERGY_SZ_RES + 1];
    casadi_int iw[HPGEN_ENERGY_SZ_IW + 1];
    casadi_real w[HPGEN_ENERGY_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    res[0] = out0;
    flag = energy(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_energy(const double* in0, const double* in1, double* out0) {
    return hpgen_k_energy(in0, in1, out0);
}

/* momentum(g[36], p[6]) -> (m[6]) */
#define HPGEN_MOMENTUM_SZ_ARG 2
#define HPGEN_MOMENTUM_SZ_RES 1
#define HPGEN_MOMENTUM_SZ_IW 0
#define HPGEN_MOMENTUM_SZ_W 14
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_momentum exports it */
static int hpgen_k_momentum(const double* in0, const double* in1, double* out0) {
    const casadi_real* arg[HPGEN_MOMENTUM_SZ_ARG + 1];
    casadi_real* res[HPGEN_MOMENTUM_SZ_RES + 1];
    casadi_int iw[HPGEN_MOMENTUM_SZ_IW + 1];
    casadi_real w[HPGEN_MOMENTUM_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    res[0] = out0;
    flag = momentum(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_momentum(const double* in0, const double* in1, double* out0) {
    return hpgen_k_momentum(in0, in1, out0);
}

/* defect(g[36]) -> (e[1]) */
#define HPGEN_DEFECT_SZ_ARG 1
#define HPGEN_DEFECT_SZ_RES 1
#define HPGEN_DEFECT_SZ_IW 0
#define HPGEN_DEFECT_SZ_W 14
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_defect exports it */
static int hpgen_k_defect(const double* in0, double* out0) {
    const casadi_real* arg[HPGEN_DEFECT_SZ_ARG + 1];
    casadi_real* res[HPGEN_DEFECT_SZ_RES + 1];
    casadi_int iw[HPGEN_DEFECT_SZ_IW + 1];
    casadi_real w[HPGEN_DEFECT_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    res[0] = out0;
    flag = defect(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_defect(const double* in0, double* out0) {
    return hpgen_k_defect(in0, out0);
}

/* margin(z[6], h[1]) -> (m[1]) */
#define HPGEN_MARGIN_SZ_ARG 2
#define HPGEN_MARGIN_SZ_RES 1
#define HPGEN_MARGIN_SZ_IW 0
#define HPGEN_MARGIN_SZ_W 6
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_margin exports it */
static int hpgen_k_margin(const double* in0, const double* in1, double* out0) {
    const casadi_real* arg[HPGEN_MARGIN_SZ_ARG + 1];
    casadi_real* res[HPGEN_MARGIN_SZ_RES + 1];
    casadi_int iw[HPGEN_MARGIN_SZ_IW + 1];
    casadi_real w[HPGEN_MARGIN_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    res[0] = out0;
    flag = margin(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_margin(const double* in0, const double* in1, double* out0) {
    return hpgen_k_margin(in0, in1, out0);
}

/* section(g[36], p[6]) -> (s[1]) */
#define HPGEN_SECTION_SZ_ARG 2
#define HPGEN_SECTION_SZ_RES 1
#define HPGEN_SECTION_SZ_IW 0
#define HPGEN_SECTION_SZ_W 1
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_section exports it */
static int hpgen_k_section(const double* in0, const double* in1, double* out0) {
    const casadi_real* arg[HPGEN_SECTION_SZ_ARG + 1];
    casadi_real* res[HPGEN_SECTION_SZ_RES + 1];
    casadi_int iw[HPGEN_SECTION_SZ_IW + 1];
    casadi_real w[HPGEN_SECTION_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    res[0] = out0;
    flag = section(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_section(const double* in0, const double* in1, double* out0) {
    return hpgen_k_section(in0, in1, out0);
}

/* chart_point(z[6], g[36], h[1], theta[1]) -> (g_theta[36]) */
#define HPGEN_CHART_POINT_SZ_ARG 4
#define HPGEN_CHART_POINT_SZ_RES 1
#define HPGEN_CHART_POINT_SZ_IW 0
#define HPGEN_CHART_POINT_SZ_W 34
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_chart_point exports it */
static int hpgen_k_chart_point(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    const casadi_real* arg[HPGEN_CHART_POINT_SZ_ARG + 1];
    casadi_real* res[HPGEN_CHART_POINT_SZ_RES + 1];
    casadi_int iw[HPGEN_CHART_POINT_SZ_IW + 1];
    casadi_real w[HPGEN_CHART_POINT_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    arg[3] = in3;
    res[0] = out0;
    flag = chart_point(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_chart_point(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    return hpgen_k_chart_point(in0, in1, in2, in3, out0);
}

/* observe(g[36], p[6]) -> (xi[6], E[1], m[6], e[1]) */
#define HPGEN_OBSERVE_SZ_ARG 2
#define HPGEN_OBSERVE_SZ_RES 4
#define HPGEN_OBSERVE_SZ_IW 0
#define HPGEN_OBSERVE_SZ_W 30
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_observe exports it */
static int hpgen_k_observe(const double* in0, const double* in1, double* out0, double* out1, double* out2, double* out3) {
    const casadi_real* arg[HPGEN_OBSERVE_SZ_ARG + 1];
    casadi_real* res[HPGEN_OBSERVE_SZ_RES + 1];
    casadi_int iw[HPGEN_OBSERVE_SZ_IW + 1];
    casadi_real w[HPGEN_OBSERVE_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    res[0] = out0;
    res[1] = out1;
    res[2] = out2;
    res[3] = out3;
    flag = observe(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_observe(const double* in0, const double* in1, double* out0, double* out1, double* out2, double* out3) {
    return hpgen_k_observe(in0, in1, out0, out1, out2, out3);
}

/* update_p(z[6], g[36], p[6], h[1]) -> (p1[6]) */
#define HPGEN_UPDATE_P_SZ_ARG 4
#define HPGEN_UPDATE_P_SZ_RES 1
#define HPGEN_UPDATE_P_SZ_IW 0
#define HPGEN_UPDATE_P_SZ_W 73
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_update_p exports it */
static int hpgen_k_update_p(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    const casadi_real* arg[HPGEN_UPDATE_P_SZ_ARG + 1];
    casadi_real* res[HPGEN_UPDATE_P_SZ_RES + 1];
    casadi_int iw[HPGEN_UPDATE_P_SZ_IW + 1];
    casadi_real w[HPGEN_UPDATE_P_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    arg[3] = in3;
    res[0] = out0;
    flag = update_p(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_update_p(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    return hpgen_k_update_p(in0, in1, in2, in3, out0);
}

/* velocity_step(g[36], p[6], xi[6]) -> (xi1[6]) */
#define HPGEN_VELOCITY_STEP_SZ_ARG 3
#define HPGEN_VELOCITY_STEP_SZ_RES 1
#define HPGEN_VELOCITY_STEP_SZ_IW 0
#define HPGEN_VELOCITY_STEP_SZ_W 4
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_velocity_step exports it */
static int hpgen_k_velocity_step(const double* in0, const double* in1, const double* in2, double* out0) {
    const casadi_real* arg[HPGEN_VELOCITY_STEP_SZ_ARG + 1];
    casadi_real* res[HPGEN_VELOCITY_STEP_SZ_RES + 1];
    casadi_int iw[HPGEN_VELOCITY_STEP_SZ_IW + 1];
    casadi_real w[HPGEN_VELOCITY_STEP_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    res[0] = out0;
    flag = velocity_step(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_velocity_step(const double* in0, const double* in1, const double* in2, double* out0) {
    return hpgen_k_velocity_step(in0, in1, in2, out0);
}

/* record(g[36], p[6], xi[6]) -> (row[49]) */
#define HPGEN_RECORD_SZ_ARG 3
#define HPGEN_RECORD_SZ_RES 1
#define HPGEN_RECORD_SZ_IW 0
#define HPGEN_RECORD_SZ_W 33
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_record exports it */
static int hpgen_k_record(const double* in0, const double* in1, const double* in2, double* out0) {
    const casadi_real* arg[HPGEN_RECORD_SZ_ARG + 1];
    casadi_real* res[HPGEN_RECORD_SZ_RES + 1];
    casadi_int iw[HPGEN_RECORD_SZ_IW + 1];
    casadi_real w[HPGEN_RECORD_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    res[0] = out0;
    flag = record(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_record(const double* in0, const double* in1, const double* in2, double* out0) {
    return hpgen_k_record(in0, in1, in2, out0);
}

/* step_partials(z[6], g[36], p[6], h[1]) -> (Fs[72], Yz[72], Ys[144]) */
#define HPGEN_STEP_PARTIALS_SZ_ARG 4
#define HPGEN_STEP_PARTIALS_SZ_RES 3
#define HPGEN_STEP_PARTIALS_SZ_IW 0
#define HPGEN_STEP_PARTIALS_SZ_W 156
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_step_partials exports it */
static int hpgen_k_step_partials(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1, double* out2) {
    const casadi_real* arg[HPGEN_STEP_PARTIALS_SZ_ARG + 1];
    casadi_real* res[HPGEN_STEP_PARTIALS_SZ_RES + 1];
    casadi_int iw[HPGEN_STEP_PARTIALS_SZ_IW + 1];
    casadi_real w[HPGEN_STEP_PARTIALS_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    arg[3] = in3;
    res[0] = out0;
    res[1] = out1;
    res[2] = out2;
    flag = step_partials(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_step_partials(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1, double* out2) {
    return hpgen_k_step_partials(in0, in1, in2, in3, out0, out1, out2);
}

/* ---- dense linear algebra and Newton ---- */

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
   was slower: its n dependent additions delay the step (docs/performance.md, "Against
   hand-written C") */
static int hpgen_all_finite(const double* x, int n) {
    int i;
    for (i = 0; i < n; ++i) if (!isfinite(x[i])) return 0;
    return 1;
}

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

/* Newton on residual(z, g, p, h) = 0 from z (in/out): z <- z - J^{-1} F.
   Full Newton evaluates J at every iterate. Simplified Newton (o->simplified) keeps the last J^{-1}
   in (lu, *lu_valid), across steps too, and refreshes it when the contraction
   rate theta = |dz_k| / |dz_{k-1}| exceeds HPGEN_THETA_MAX; if J was already evaluated in
   this step the rest of the step is full Newton (the fallback).
   Converged when |dz| <= tol (1 + |z|), or when |dz| stopped decreasing while
   |dz| <= 1e-11 (1 + |z|) (round-off floor); inf-norms. Returns a status code. */
static int hpgen_newton(const double* g, const double* p, const double* hv, double* z,
                        const hpgen_options* o, double* lu, int* piv, long long* lu_valid,
                        long long* iters, long long* jacs, double* rnorm) {
    double F[HPGEN_NZ];
    double dprev = HUGE_VAL;
    int full = !o->simplified, fresh = 0;
    long long it;
    int i;
    *iters = 0;
    *rnorm = NAN;
    for (it = 1; it <= o->maxit; ++it) {
        double dn, zn;
        *iters = it;
        if (full || !*lu_valid) {
            /* F and a fresh J in one evaluation (their common subexpressions once) */
            *lu_valid = 0;
            ++*jacs;
            if (hpgen_k_residual_jacobian(z, g, p, hv, F, lu)) return HPGEN_NONFINITE;
            *rnorm = hpgen_norm_inf(F, HPGEN_NZ);
            if (!isfinite(*rnorm) || hpgen_lu_factor_solve(lu, piv, F, o->simplified))
                return HPGEN_NONFINITE;
            *lu_valid = o->simplified ? 1 : 0;   /* lu holds J^{-1} only when it is kept */
            fresh = 1;
        } else {
            if (hpgen_k_residual(z, g, p, hv, F)) return HPGEN_NONFINITE;
            *rnorm = hpgen_norm_inf(F, HPGEN_NZ);
            if (!isfinite(*rnorm)) return HPGEN_NONFINITE;
            hpgen_lu_apply(lu, piv, F);
        }
        for (i = 0; i < HPGEN_NZ; ++i) z[i] -= F[i];
        dn = hpgen_norm_inf(F, HPGEN_NZ);
        zn = hpgen_norm_inf(z, HPGEN_NZ);
        if (!isfinite(dn) || !isfinite(zn)) return HPGEN_NONFINITE;
        if (it > 1 && dn >= dprev && dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + zn)) return HPGEN_OK;
        if (full) {
            /* quadratic convergence: the error left after dn <= tol is about C tol^2 */
            if (dn <= o->tol * (1.0 + zn)) return HPGEN_OK;
        } else {
            /* linear convergence: the error left is about te/(1 - te) dn, te the rate but at
               least HPGEN_THETA_FLOOR; ask it to be <= HPGEN_SIMPLIFIED_TOL tol, the
               round-off level full Newton reaches */
            double th = dn / dprev, te = th > HPGEN_THETA_FLOOR ? th : HPGEN_THETA_FLOOR;
            if (dn <= HPGEN_SIMPLIFIED_TOL * o->tol * (1.0 + zn)) return HPGEN_OK;
            if (it > 1 && te < 1.0 && te / (1.0 - te) * dn <= HPGEN_SIMPLIFIED_TOL * o->tol * (1.0 + zn))
                return HPGEN_OK;
        }
        if (!full && it > 1 && dn > HPGEN_THETA_MAX * dprev) {
            if (fresh) full = 1;           /* a fresh J contracts poorly: full Newton */
            else *lu_valid = 0;            /* a stale J: refresh it at the next iterate */
        }
        dprev = dn;
    }
    return HPGEN_NO_CONVERGENCE;
}

/* Full Newton (o->simplified = 0): hpgen_newton's iteration, convergence tests and results
   ((z, status, *iters, *rnorm, *jacs += iterations) bitwise), in a loop of its own without
   the simplified-Newton bookkeeping: J in a local array (never kept), the counters in locals,
   and F's norm taken once, at the end. A non-finite F is caught after the solve, where it
   makes dz non-finite (dz = J^{-1} F: every F_i enters some dz_j with a nonzero factor of
   J^{-1}, or as inf * 0 = NaN): then F is tested and, if it is the culprit, z is left at the
   iterate F was evaluated at, as in hpgen_newton. */
static int hpgen_newton_full(const double* g, const double* p, const double* hv, double* z,
                             const hpgen_options* o, long long* iters, long long* jacs,
                             double* rnorm) {
    double F[HPGEN_NZ], Fz[HPGEN_NZ], J[HPGEN_NZ * HPGEN_NZ], dprev = HUGE_VAL;
    const double tol = o->tol;
    const long long maxit = o->maxit;
    long long it;
    int i, piv[HPGEN_NZ], evaluated = 0, code = HPGEN_NO_CONVERGENCE;
    for (it = 1; it <= maxit; ++it) {
        double dn, zn;
        if (hpgen_k_residual_jacobian(z, g, p, hv, F, J)) { code = HPGEN_NONFINITE; break; }
        memcpy(Fz, F, sizeof F);                  /* F(z), for *rnorm */
        evaluated = 1;
        if (hpgen_lu_factor_solve(J, piv, F, 0)) { code = HPGEN_NONFINITE; break; }
        dn = hpgen_norm_inf(F, HPGEN_NZ);
        if (!isfinite(dn) && !hpgen_all_finite(Fz, HPGEN_NZ)) { code = HPGEN_NONFINITE; break; }
        for (i = 0; i < HPGEN_NZ; ++i) z[i] -= F[i];
        zn = hpgen_norm_inf(z, HPGEN_NZ);
        if (!isfinite(dn) || !isfinite(zn)) { code = HPGEN_NONFINITE; break; }
        if (it > 1 && dn >= dprev && dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + zn)) {
            code = HPGEN_OK; break;
        }
        if (dn <= tol * (1.0 + zn)) { code = HPGEN_OK; break; }
        dprev = dn;
    }
    if (it > maxit) it = maxit;
    *iters = it;
    *jacs += it;
    *rnorm = evaluated ? hpgen_norm_inf(Fz, HPGEN_NZ) : NAN;
    return code;
}

/* One step of a run: margin(z, h) > 0 at the start (check_start), Newton from z (in/out),
   margin(z, h) > 0 at the solution, then update -> (g1, p1); with_g = 0: update_p -> p1
   only (g1 untouched). */
/* small kernels: inline them and the Newton loop into one body (GCC/Clang), so the compiler
   schedules the kernels' arithmetic together with the solve */
#if defined(__GNUC__)
__attribute__((flatten))
#endif
static int hpgen_step_core(const double* g, const double* p, const double* hv, double* z,
                           const hpgen_options* o, double* lu, int* piv, long long* lu_valid,
                           double* g1, double* p1, long long* iters, long long* jacs,
                           double* rnorm, int check_start, int with_g) {
    double m[1];
    int code;
    /* a start outside tau's domain means h is too large for the chart: do not let Newton
       wander to a spurious root from there. Only needed for a start that is not built from
       the previous steps' solutions (whose margins, same h, were checked). */
    if (check_start && !hpgen_k_margin(z, hv, m) && m[0] <= 0.0) {
        *iters = 0; *rnorm = NAN;
        return HPGEN_DOMAIN;
    }
    if (o->simplified) {
        code = hpgen_newton(g, p, hv, z, o, lu, piv, lu_valid, iters, jacs, rnorm);
    } else {
        *lu_valid = 0;                     /* full Newton keeps no J^{-1} */
        code = hpgen_newton_full(g, p, hv, z, o, iters, jacs, rnorm);
    }
    /* a Newton failure is reported as such (wherever its last iterate went): DOMAIN is a
       converged solution outside tau's domain only */
    if (code != HPGEN_OK) { *lu_valid = 0; return code; }
    if (hpgen_k_margin(z, hv, m)) return HPGEN_NONFINITE;
    if (!(m[0] > 0.0)) { *lu_valid = 0; return HPGEN_DOMAIN; }
    if (!with_g) {
        if (hpgen_k_update_p(z, g, p, hv, p1) || !hpgen_all_finite(p1, HPGEN_D))
            return HPGEN_NONFINITE;
        return HPGEN_OK;
    }
    if (hpgen_k_update(z, g, p, hv, g1, p1)) return HPGEN_NONFINITE;
    if (!hpgen_all_finite(g1, HPGEN_NN) || !hpgen_all_finite(p1, HPGEN_D))
        return HPGEN_NONFINITE;
    return HPGEN_OK;
}

static void hpgen_status_init(hpgen_status* st) {
    st->code = HPGEN_OK; st->step = 0; st->iterations = 0; st->total_iterations = 0;
    st->residual = 0.0; st->jacobians = 0;
}

static int hpgen_options_ok(const hpgen_options* o) {
    return o->maxit >= 1 && o->tol > 0.0 && isfinite(o->tol);
}

/* One step from (g, p) with step size h; z: Newton start in, solution out (no memory from
   earlier steps; callers normally ask for full Newton here: a cold start). Returns the code. */
HPGEN_EXPORT int hpgen_step(const double* g, const double* p, double h, double* z,
                            const hpgen_options* o, double* g1, double* p1, hpgen_status* st) {
    double hv[1], lu[HPGEN_NZ * HPGEN_NZ];
    int piv[HPGEN_NZ];
    long long it, valid = 0;
    double r;
    int code;
    hpgen_status_init(st);
    if (!hpgen_options_ok(o)) { st->code = HPGEN_INVALID; return HPGEN_INVALID; }
    hv[0] = h;
    code = hpgen_step_core(g, p, hv, z, o, lu, piv, &valid, g1, p1, &it, &st->jacobians, &r, 1,
                           1);
    st->code = code; st->iterations = it; st->total_iterations = it; st->residual = r;
    return code;
}

/* sizeof(hpgen_run), for callers that allocate runs as byte buffers */
HPGEN_EXPORT long long hpgen_run_size(void) { return (long long)sizeof(hpgen_run); }

/* Start a run at (g0, p0) with Newton start z0 for the first step. */
HPGEN_EXPORT void hpgen_run_init(hpgen_run* r, const double* g0, const double* p0,
                                 const double* z0) {
    memset(r, 0, sizeof *r);
    memcpy(r->g, g0, sizeof r->g);
    memcpy(r->p, p0, sizeof r->p);
    memcpy(r->z, z0, sizeof r->z);
}

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
    hpgen_k_velocity_step(g, p, x0, xi);
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

/* One step of run r with hv = {h}: the Newton start from the predictor, the step, and on
   success the run moved to (g_{k+1}, p_{k+1}) (with_g = 0: p_{k+1} only); o for the steps
   after the first, full (o with full Newton) for the first. Updates the counters of st;
   returns the status code.
   Predictor: z_k = G_k + dz_k with G_k = hpgen_predictor_base(g_k, p_k) (exact in p, O(1))
   and dz_k = z_k - G_k small (O(h)) and smooth in k; the start is G_k plus the polynomial
   through the last m = min(have_prev, HPGEN_PH) offsets extrapolated one step
   (hpgen_predict: quintic once six exist). Extrapolating z itself (an older predictor) left
   errors 5-7x larger on the heavy top, the quadratic 0.5-2 more iterations per step
   (docs/performance.md). */
static int hpgen_run_step(hpgen_run* r, const double* hv, const hpgen_options* o,
                          const hpgen_options* full, hpgen_status* st, int with_g) {
    double g1[HPGEN_NN], p1[HPGEN_D], zs[HPGEN_NZ], G[HPGEN_NZ], res;
    long long it;
    int i, code, predicted = o->predictor && r->have_prev >= 1;
    hpgen_predictor_base(r->g, r->p, hv, G);    /* (kept up to date with or without o->predictor) */
    if (predicted && r->have_prev == HPGEN_PH)     /* the steady state: a constant m */
        hpgen_predict(G, r->dz[0], 1, HPGEN_NZ, HPGEN_PH, zs);
    else if (predicted)
        hpgen_predict(G, r->dz[0], 1, HPGEN_NZ, r->have_prev, zs);
    else
        for (i = 0; i < HPGEN_NZ; ++i) zs[i] = r->z[i];
    /* the first step starts from the crude guess kernel: full Newton */
    code = hpgen_step_core(r->g, r->p, hv, zs, r->k == 0 ? full : o, r->lu, r->piv,
                           &r->lu_valid, g1, p1, &it, &st->jacobians, &res, r->k == 0, with_g);
    st->total_iterations += it;
    if (code != HPGEN_OK && predicted) {
        /* the extrapolated start failed (Newton diverged, or reached a root outside the
           chart): retry from the plain warm start z_k before reporting anything */
        memcpy(zs, r->z, sizeof zs);
        code = hpgen_step_core(r->g, r->p, hv, zs, o, r->lu, r->piv, &r->lu_valid, g1, p1,
                               &it, &st->jacobians, &res, 0, with_g);
        st->total_iterations += it;
    }
    st->iterations = it;
    st->residual = res;
    if (code != HPGEN_OK) { st->code = code; st->step = r->k; return code; }
    memmove(r->dz[1], r->dz[0], (HPGEN_PH - 1) * sizeof r->dz[0]);
    for (i = 0; i < HPGEN_NZ; ++i) r->dz[0][i] = zs[i] - G[i];
    if (r->have_prev < HPGEN_PH) r->have_prev += 1;
    memcpy(r->z, zs, sizeof r->z);
    if (with_g) memcpy(r->g, g1, sizeof g1);
    memcpy(r->p, p1, sizeof p1);
    r->k += 1;
    return HPGEN_OK;
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
    hpgen_status_init(st);
    if (steps < 0 || every < 1 || !hpgen_options_ok(o) || r->g_stale) {
        st->code = HPGEN_INVALID; return 0;
    }
    hv[0] = h;
    full = *o;
    full.simplified = 0;
    for (n = 0; n < steps; ++n) {
        if (hpgen_run_step(r, hv, o, &full, st, 1) != HPGEN_OK) return n;
        if (r->k % every == 0) {
            memcpy(g_rec + rec * HPGEN_NN, r->g, sizeof r->g);
            memcpy(p_rec + rec * HPGEN_D, r->p, sizeof r->p);
            ++rec;
        }
    }
    st->step = r->k;
    return steps;
}

/* Advance a run by up to `steps` steps of size h, recording the upward crossings of the
   scene's Poincare section s(g, p) = 0 (kernel section): when s_k < 0 <= s_{k+1}, with
   theta = s_k / (s_k - s_{k+1}) in (0, 1], record j holds
     k_rec[j] = k,  t_rec[j] = (k + theta) h,
     p_rec[j * D] = (1 - theta) p_k + theta p_{k+1}      (linear in the step: O(h^2)),
     g_rec[j * NN] = g_k tau(theta h xi_{k+1})            (kernel chart_point: on the group).
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
    int i;
    hpgen_options full;
    hpgen_status_init(st);
    *n_rec = 0;
    if (steps < 0 || cap < 1 || !hpgen_options_ok(o) || r->g_stale) {
        st->code = HPGEN_INVALID; return 0;
    }
    hv[0] = h;
    full = *o;
    full.simplified = 0;
    if (!r->s_valid) {
        if (hpgen_k_section(r->g, r->p, s1)) { st->code = HPGEN_NONFINITE; return 0; }
        r->s = s1[0];
        r->s_valid = 1;
    }
    for (n = 0; n < steps && *n_rec < cap; ++n) {
        const double s0 = r->s;
        const long long k = r->k;
        memcpy(g0, r->g, sizeof g0);
        memcpy(p0, r->p, sizeof p0);
        if (hpgen_run_step(r, hv, o, &full, st, 1) != HPGEN_OK) return n;
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
            if (hpgen_k_chart_point(r->z, g0, hv, th, g_rec + j * HPGEN_NN)) {
                st->code = HPGEN_NONFINITE; st->step = r->k; return n + 1;
            }
            *n_rec = j + 1;
        }
    }
    st->step = r->k;
    return n;
}

/* xi with legendre(g, xi) = p: Newton (kernel velocity_step) from xi = 0; one step when l is
   quadratic in xi (then exact), else until |dxi| <= 1e-14 (1 + |xi|) or the round-off floor,
   at most 50 iterations (the runtime's Integrator.velocity uses the same test). */
#if HPGEN_RECORD_USES_XI
static int hpgen_velocity(const double* g, const double* p, double* xi) {
    double x1[HPGEN_D], dprev = HUGE_VAL;
    int i, it;
    for (i = 0; i < HPGEN_D; ++i) xi[i] = 0.0;
    for (it = 1; it <= 50; ++it) {
        double dn = 0.0, xn;
        if (hpgen_k_velocity_step(g, p, xi, x1) || !hpgen_all_finite(x1, HPGEN_D))
            return HPGEN_RECORD;
        for (i = 0; i < HPGEN_D; ++i) {
            const double dx = fabs(x1[i] - xi[i]);
            if (dx > dn) dn = dx;
            xi[i] = x1[i];
        }
        if (HPGEN_LEGENDRE_QUADRATIC) return HPGEN_OK;
        xn = hpgen_norm_inf(xi, HPGEN_D);
        if (dn <= 1e-14 * (1.0 + xn)) return HPGEN_OK;
        if (it > 1 && dn >= dprev && dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + xn)) return HPGEN_OK;
        dprev = dn;
    }
    return HPGEN_RECORD;
}
#endif

/* The scene's record row at (g, p) (kernel record; xi by hpgen_velocity when the row uses
   it): HPGEN_OK, or HPGEN_RECORD when the row is not finite or xi did not converge (then the
   row is all NaN). */
static int hpgen_record_row(const double* g, const double* p, double* row) {
    double xi[HPGEN_D];
#if HPGEN_RECORD_USES_XI
    if (hpgen_velocity(g, p, xi) != HPGEN_OK) {
        int i;
        for (i = 0; i < HPGEN_W; ++i) row[i] = NAN;
        return HPGEN_RECORD;
    }
#else
    memset(xi, 0, sizeof xi);
#endif
    if (hpgen_k_record(g, p, xi, row) || !hpgen_all_finite(row, HPGEN_W)) return HPGEN_RECORD;
    return HPGEN_OK;
}

/* The record row at (g, p) (the start of a run: record 0). Returns the status code. */
HPGEN_EXPORT int hpgen_record(const double* g, const double* p, double* row) {
    return hpgen_record_row(g, p, row);
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
    hpgen_status_init(st);
    *n_rec = 0;
    if (steps < 0 || every < 1 || !hpgen_options_ok(o)) { st->code = HPGEN_INVALID; return 0; }
    hv[0] = h;
    full = *o;
    full.simplified = 0;
    if (HPGEN_SKIP_G) r->g_stale = 1;
    for (n = 0; n < steps; ++n) {
        if (hpgen_run_step(r, hv, o, &full, st, !HPGEN_SKIP_G) != HPGEN_OK) return n;
        if (r->k % every == 0) {
            double* row = rows + *n_rec * HPGEN_W;
            *n_rec += 1;
            if (hpgen_record_row(r->g, r->p, row) != HPGEN_OK) {
                st->code = HPGEN_RECORD; st->step = r->k; return n + 1;
            }
        }
    }
    st->step = r->k;
    return steps;
}

/* Advance B independent runs like B calls of hpgen_advance_record: rows of run b start at
   rows + b * per_run * W, its row count in n_rec[b], its status in st[b]. Returns the number
   of failed runs. Callers split a batch across threads. */
HPGEN_EXPORT long long hpgen_advance_record_batch(hpgen_run* runs, long long B, double h,
                                                  long long steps, long long every,
                                                  const hpgen_options* o, long long per_run,
                                                  double* rows, long long* n_rec,
                                                  hpgen_status* st) {
    long long b, failed = 0;
    for (b = 0; b < B; ++b) {
        hpgen_advance_record(runs + b, h, steps, every, o, rows + b * per_run * HPGEN_W,
                             n_rec + b, st + b);
        if (st[b].code != HPGEN_OK) ++failed;
    }
    return failed;
}

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

/* Advance B independent runs (runs[0..B-1]) by `steps` steps each, one after the other,
   exactly as B calls of hpgen_advance: records of run b start at g_rec + b * per_run * NN
   (p_rec + b * per_run * D), statuses in st[b]. Callers split a batch across threads. */
HPGEN_EXPORT long long hpgen_advance_batch(hpgen_run* runs, long long B, double h,
                                           long long steps, long long every,
                                           const hpgen_options* o, long long per_run,
                                           double* g_rec, double* p_rec, hpgen_status* st) {
    long long b, failed = 0;
    for (b = 0; b < B; ++b) {
        hpgen_advance(runs + b, h, steps, every, o, g_rec + b * per_run * HPGEN_NN,
                      p_rec + b * per_run * HPGEN_D, st + b);
        if (st[b].code != HPGEN_OK) ++failed;
    }
    return failed;
}

/* ---- linearization along recorded steps (issue 12; hpgen.runtime.linearize) ---- */

/* For k = 0..K-1: Newton on step k from the record (g_k, p_k) = (g_rec + k NN,
   p_rec + k D): step 0 by full Newton from z (in/out: z_0 in, the last solution out), step
   k > 0 from the extrapolation of z_{k-1}, z_{k-2}, z_{k-3} (o->predictor) with o's Newton, whose simplified
   iterations use J^{-1} of the previous step's converged z; dev[k] = max |update(z_k) -
   record k+1| (the caller checks that the records are this module's steps). At the
   converged z_k: J = jacobian(z_k) inverted once (and kept as the next step's Newton
   matrix), (Fs, Yz, Ys) = step_partials(z_k), A_k = Ys - Yz J^{-1} Fs, 2D x 2D column-major
   at A + k 4 D^2. Returns the steps done (K, or the failing step with st->code set). */
HPGEN_EXPORT long long hpgen_linearize(long long K, const double* g_rec, const double* p_rec,
                                       double h, double* z, const hpgen_options* o,
                                       double* A, double* dev, hpgen_status* st) {
    enum { S = 2 * HPGEN_D };
    double hv[1], g1[HPGEN_NN], p1[HPGEN_D], J[HPGEN_NZ * HPGEN_NZ], Fs[HPGEN_NZ * S],
        Yz[S * HPGEN_NZ], Ys[S * S], zlast[HPGEN_NZ], zprev[HPGEN_NZ] = {0.0},
        zprev2[HPGEN_NZ] = {0.0}, res;
    int piv[HPGEN_NZ];
    long long k, it, valid = 0;
    int i, j, l, code;
    hpgen_options full;
    hpgen_status_init(st);
    if (K < 0 || !hpgen_options_ok(o)) { st->code = HPGEN_INVALID; return 0; }
    hv[0] = h;
    full = *o;
    full.simplified = 0;
    for (k = 0; k < K; ++k) {
        const double* g = g_rec + k * HPGEN_NN;
        const double* p = p_rec + k * HPGEN_D;
        double* Ak = A + k * S * S;
        double m = 0.0;
        /* the start: the extrapolation through z_{k-1}, z_{k-2}, z_{k-3} (quadratic, as
           hpgen_run_step's predictor before it extrapolated z - G instead) */
        memcpy(zlast, z, sizeof zlast);
        if (o->predictor && k >= 3)
            for (i = 0; i < HPGEN_NZ; ++i) z[i] = 3.0 * (z[i] - zprev[i]) + zprev2[i];
        else if (o->predictor && k == 2)
            for (i = 0; i < HPGEN_NZ; ++i) z[i] = 2.0 * z[i] - zprev[i];
        code = hpgen_step_core(g, p, hv, z, k == 0 ? &full : o, J, piv, &valid, g1, p1, &it,
                               &st->jacobians, &res, k == 0, 1);
        st->iterations = it; st->total_iterations += it; st->residual = res;
        if (code != HPGEN_OK) { st->code = code; st->step = k; return k; }
        for (i = 0; i < HPGEN_NN; ++i) m = fmax(m, fabs(g1[i] - g[HPGEN_NN + i]));
        for (i = 0; i < HPGEN_D; ++i) m = fmax(m, fabs(p1[i] - p[HPGEN_D + i]));
        dev[k] = m;
        ++st->jacobians;
        valid = 0;
        if (hpgen_kernel_jacobian(z, g, p, hv, J) || hpgen_k_step_partials(z, g, p, hv, Fs, Yz, Ys)
            || hpgen_lu_factor_solve(J, piv, Fs, 1)) {
            st->code = HPGEN_NONFINITE; st->step = k; return k;
        }
        valid = o->simplified ? 1 : 0;    /* J holds J^{-1} at z_k: the next Newton matrix */
        /* Fs's first column is solved, the others by J^{-1} */
        for (j = 1; j < S; ++j) hpgen_lu_apply(J, piv, Fs + j * HPGEN_NZ);
        for (j = 0; j < S; ++j)
            for (i = 0; i < S; ++i) {
                double a = Ys[i + j * S];
                for (l = 0; l < HPGEN_NZ; ++l) a -= Yz[i + l * S] * Fs[l + j * HPGEN_NZ];
                Ak[i + j * S] = a;
            }
        if (!hpgen_all_finite(Ak, S * S)) { st->code = HPGEN_NONFINITE; st->step = k; return k; }
        memcpy(zprev2, zprev, sizeof zprev);
        memcpy(zprev, zlast, sizeof zprev);
    }
    st->step = K;
    return K;
}
