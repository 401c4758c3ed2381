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
 *   HPGEN_NONFINITE = 2: a non-finite value (or a singular Jacobian) appeared
 *   HPGEN_DOMAIN = 3: the chart map tau left its domain (margin(z, h) <= 0)
 *   HPGEN_RECORD = 4: a record row is not finite (or its velocity xi did not converge)
 *   HPGEN_INVALID = -1: invalid argument
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

/* step_partials:(z[6],g[36],p[6],h)->(J[36],Fs[72],Yz[72],Ys[144]) */
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
  casadi_real a156, a157, a158, a159, a160, a161, a162, a163, a164, a165, a166, a167;
  a000=9.0000000000000002e-01;
  a001=arg[0]? arg[0][0] : 0;
  a002=(a000*a001);
  a003=2.5000000000000000e-01;
  a004=arg[3]? arg[3][0] : 0;
  a001=(a004*a001);
  a005=(2.*a001);
  a005=(a005*a004);
  a006=(a003*a005);
  a006=(a002*a006);
  a007=1.;
  a008=casadi_sq(a001);
  a009=4.;
  a010=(a008/a009);
  a010=(a007+a010);
  a010=(a000*a010);
  a006=(a006+a010);
  a010=arg[0]? arg[0][1] : 0;
  a011=(a004*a010);
  a012=(a011*a004);
  a013=(a003*a012);
  a014=(a010*a013);
  a006=(a006+a014);
  a015=2.0000000000000001e-01;
  a016=arg[0]? arg[0][2] : 0;
  a017=(a015*a016);
  a016=(a004*a016);
  a018=(a016*a004);
  a019=(a003*a018);
  a020=(a017*a019);
  a006=(a006+a020);
  a021=(-a006);
  if (res[0]!=0) res[0][0]=a021;
  a021=(a002*a013);
  a022=2.;
  a023=(a016/a022);
  a024=(a001*a011);
  a025=(a024/a009);
  a026=(a023+a025);
  a026=(a000*a026);
  a026=(a021+a026);
  a027=5.0000000000000000e-01;
  a028=(a027*a004);
  a029=(a017*a028);
  a026=(a026-a029);
  a026=(-a026);
  if (res[0]!=0) res[0][1]=a026;
  a026=(a002*a019);
  a030=(a001*a016);
  a031=(a030/a009);
  a032=(a011/a022);
  a033=(a031-a032);
  a033=(a000*a033);
  a033=(a026+a033);
  a034=(a010*a028);
  a033=(a033+a034);
  a033=(-a033);
  if (res[0]!=0) res[0][2]=a033;
  a033=0.;
  if (res[0]!=0) res[0][3]=a033;
  if (res[0]!=0) res[0][4]=a033;
  if (res[0]!=0) res[0][5]=a033;
  a035=(a001*a004);
  a036=(a003*a035);
  a037=(a010*a036);
  a038=(a011*a001);
  a039=(a038/a009);
  a040=(a039-a023);
  a040=(a037+a040);
  a040=(a040+a029);
  a040=(-a040);
  if (res[0]!=0) res[0][6]=a040;
  a040=(a002*a036);
  a041=(2.*a011);
  a041=(a041*a004);
  a042=(a003*a041);
  a042=(a010*a042);
  a043=casadi_sq(a011);
  a044=(a043/a009);
  a044=(a007+a044);
  a042=(a042+a044);
  a042=(a040+a042);
  a042=(a042+a020);
  a020=(-a042);
  if (res[0]!=0) res[0][7]=a020;
  a010=(a010*a019);
  a019=(a001/a022);
  a020=(a011*a016);
  a044=(a020/a009);
  a045=(a019+a044);
  a045=(a010+a045);
  a002=(a002*a028);
  a045=(a045-a002);
  a045=(-a045);
  if (res[0]!=0) res[0][8]=a045;
  if (res[0]!=0) res[0][9]=a033;
  if (res[0]!=0) res[0][10]=a033;
  if (res[0]!=0) res[0][11]=a033;
  a036=(a017*a036);
  a045=(a016*a001);
  a046=(a045/a009);
  a047=(a032+a046);
  a047=(a015*a047);
  a047=(a036+a047);
  a047=(a047-a034);
  a047=(-a047);
  if (res[0]!=0) res[0][12]=a047;
  a013=(a017*a013);
  a047=(a016*a011);
  a048=(a047/a009);
  a049=(a048-a019);
  a049=(a015*a049);
  a049=(a013+a049);
  a049=(a002+a049);
  a049=(-a049);
  if (res[0]!=0) res[0][13]=a049;
  a040=(a040+a014);
  a014=(2.*a016);
  a014=(a014*a004);
  a049=(a003*a014);
  a017=(a017*a049);
  a049=casadi_sq(a016);
  a050=(a049/a009);
  a050=(a007+a050);
  a050=(a015*a050);
  a017=(a017+a050);
  a040=(a040+a017);
  a017=(-a040);
  if (res[0]!=0) res[0][14]=a017;
  if (res[0]!=0) res[0][15]=a033;
  if (res[0]!=0) res[0][16]=a033;
  if (res[0]!=0) res[0][17]=a033;
  if (res[0]!=0) res[0][18]=a033;
  if (res[0]!=0) res[0][19]=a033;
  if (res[0]!=0) res[0][20]=a033;
  a017=5.9999999999999998e-01;
  a050=arg[0]? arg[0][3] : 0;
  a051=(a017*a050);
  a050=(a004*a050);
  a052=(2.*a050);
  a052=(a052*a004);
  a053=(a003*a052);
  a053=(a051*a053);
  a054=casadi_sq(a050);
  a055=(a054/a009);
  a055=(a007+a055);
  a055=(a017*a055);
  a053=(a053+a055);
  a055=arg[0]? arg[0][4] : 0;
  a056=(a027*a055);
  a055=(a004*a055);
  a057=(a055*a004);
  a058=(a003*a057);
  a059=(a056*a058);
  a053=(a053+a059);
  a060=1.4999999999999999e-01;
  a061=arg[0]? arg[0][5] : 0;
  a062=(a060*a061);
  a061=(a004*a061);
  a063=(a061*a004);
  a064=(a003*a063);
  a065=(a062*a064);
  a053=(a053+a065);
  a066=(-a053);
  if (res[0]!=0) res[0][21]=a066;
  a066=(a051*a058);
  a067=(a061/a022);
  a068=(a050*a055);
  a069=(a068/a009);
  a070=(a067+a069);
  a070=(a017*a070);
  a070=(a066+a070);
  a071=(a062*a028);
  a070=(a070-a071);
  a070=(-a070);
  if (res[0]!=0) res[0][22]=a070;
  a070=(a051*a064);
  a072=(a050*a061);
  a073=(a072/a009);
  a074=(a055/a022);
  a075=(a073-a074);
  a075=(a017*a075);
  a075=(a070+a075);
  a076=(a056*a028);
  a075=(a075+a076);
  a075=(-a075);
  if (res[0]!=0) res[0][23]=a075;
  if (res[0]!=0) res[0][24]=a033;
  if (res[0]!=0) res[0][25]=a033;
  if (res[0]!=0) res[0][26]=a033;
  a075=(a050*a004);
  a077=(a003*a075);
  a078=(a056*a077);
  a079=(a055*a050);
  a080=(a079/a009);
  a081=(a080-a067);
  a081=(a027*a081);
  a081=(a078+a081);
  a081=(a081+a071);
  a081=(-a081);
  if (res[0]!=0) res[0][27]=a081;
  a081=(a051*a077);
  a082=(2.*a055);
  a082=(a082*a004);
  a083=(a003*a082);
  a083=(a056*a083);
  a084=casadi_sq(a055);
  a085=(a084/a009);
  a085=(a007+a085);
  a085=(a027*a085);
  a083=(a083+a085);
  a083=(a081+a083);
  a083=(a083+a065);
  a065=(-a083);
  if (res[0]!=0) res[0][28]=a065;
  a056=(a056*a064);
  a064=(a050/a022);
  a065=(a055*a061);
  a085=(a065/a009);
  a086=(a064+a085);
  a086=(a027*a086);
  a086=(a056+a086);
  a051=(a051*a028);
  a086=(a086-a051);
  a086=(-a086);
  if (res[0]!=0) res[0][29]=a086;
  if (res[0]!=0) res[0][30]=a033;
  if (res[0]!=0) res[0][31]=a033;
  if (res[0]!=0) res[0][32]=a033;
  a077=(a062*a077);
  a086=(a061*a050);
  a087=(a086/a009);
  a088=(a074+a087);
  a088=(a060*a088);
  a088=(a077+a088);
  a088=(a088-a076);
  a088=(-a088);
  if (res[0]!=0) res[0][33]=a088;
  a058=(a062*a058);
  a088=(a061*a055);
  a089=(a088/a009);
  a090=(a089-a064);
  a090=(a060*a090);
  a090=(a058+a090);
  a090=(a051+a090);
  a090=(-a090);
  if (res[0]!=0) res[0][34]=a090;
  a081=(a081+a059);
  a059=(2.*a061);
  a059=(a059*a004);
  a003=(a003*a059);
  a062=(a062*a003);
  a003=casadi_sq(a061);
  a090=(a003/a009);
  a090=(a007+a090);
  a090=(a060*a090);
  a062=(a062+a090);
  a081=(a081+a062);
  a062=(-a081);
  if (res[0]!=0) res[0][35]=a062;
  a062=arg[1]? arg[1][14] : 0;
  a090=5.0000000000000003e-02;
  a091=(a090*a062);
  a092=arg[1]? arg[1][8] : 0;
  a091=(a091+a092);
  a091=(2.*a091);
  a091=(a004*a091);
  a093=(a090*a091);
  a094=(a062*a093);
  a095=1.3000000000000000e+00;
  a096=(a090*a092);
  a096=(a095+a096);
  a097=1.0000000000000001e-01;
  a098=arg[1]? arg[1][2] : 0;
  a099=(a097*a098);
  a096=(a096+a099);
  a096=(a096-a062);
  a099=-1.0000000000000001e-01;
  a100=arg[1]? arg[1][29] : 0;
  a101=(a099*a100);
  a096=(a096+a101);
  a101=-2.9999999999999999e-01;
  a102=arg[1]? arg[1][35] : 0;
  a103=(a101*a102);
  a096=(a096+a103);
  a096=(2.*a096);
  a096=(a096*a004);
  a103=(a090*a096);
  a104=(a103*a092);
  a094=(a094-a104);
  a105=arg[1]? arg[1][7] : 0;
  a106=(a090*a105);
  a107=arg[1]? arg[1][1] : 0;
  a108=(a097*a107);
  a106=(a106+a108);
  a108=arg[1]? arg[1][13] : 0;
  a106=(a106-a108);
  a109=arg[1]? arg[1][28] : 0;
  a110=(a099*a109);
  a106=(a106+a110);
  a110=arg[1]? arg[1][34] : 0;
  a111=(a101*a110);
  a106=(a106+a111);
  a106=(2.*a106);
  a106=(a106*a004);
  a111=(a106*a108);
  a112=(a090*a108);
  a112=(a112+a105);
  a112=(2.*a112);
  a112=(a004*a112);
  a113=(a105*a112);
  a113=(a111+a113);
  a094=(a094+a113);
  a113=(a090*a112);
  a114=(a108*a113);
  a115=(a090*a106);
  a116=(a115*a105);
  a114=(a114-a116);
  a094=(a094+a114);
  a114=arg[1]? arg[1][6] : 0;
  a117=(a090*a114);
  a118=arg[1]? arg[1][0] : 0;
  a119=(a097*a118);
  a117=(a117+a119);
  a119=arg[1]? arg[1][12] : 0;
  a117=(a117-a119);
  a120=arg[1]? arg[1][27] : 0;
  a121=(a099*a120);
  a117=(a117+a121);
  a121=arg[1]? arg[1][33] : 0;
  a122=(a101*a121);
  a117=(a117+a122);
  a117=(2.*a117);
  a117=(a117*a004);
  a122=(a117*a119);
  a123=(a090*a119);
  a123=(a123+a114);
  a123=(2.*a123);
  a123=(a004*a123);
  a124=(a114*a123);
  a124=(a122+a124);
  a094=(a094+a124);
  a124=(a090*a123);
  a125=(a119*a124);
  a126=(a090*a117);
  a127=(a126*a114);
  a125=(a125-a127);
  a094=(a094+a125);
  a125=(a096+a028);
  a128=(a125*a062);
  a129=(a092*a091);
  a129=(a128+a129);
  a094=(a094+a129);
  a094=(-a094);
  if (res[1]!=0) res[1][0]=a094;
  a094=(a107*a112);
  a129=-5.0000000000000003e-02;
  a129=(a129*a004);
  a130=(a097*a096);
  a130=(a129-a130);
  a131=(a130*a092);
  a132=(a097*a091);
  a133=(a062*a132);
  a131=(a131+a133);
  a094=(a094+a131);
  a131=(a097*a112);
  a133=(a108*a131);
  a134=(a097*a106);
  a135=(a134*a105);
  a133=(a133-a135);
  a094=(a094+a133);
  a133=(a118*a123);
  a094=(a094+a133);
  a133=(a097*a123);
  a135=(a119*a133);
  a136=(a097*a117);
  a137=(a136*a114);
  a135=(a135-a137);
  a094=(a094+a135);
  a135=(a098*a091);
  a094=(a094+a135);
  if (res[1]!=0) res[1][1]=a094;
  a094=(a130*a062);
  a132=(a092*a132);
  a094=(a094-a132);
  a093=(a098*a093);
  a094=(a094+a093);
  a093=(a134*a108);
  a131=(a105*a131);
  a093=(a093+a131);
  a094=(a094-a093);
  a113=(a107*a113);
  a094=(a094+a113);
  a113=(a136*a119);
  a133=(a114*a133);
  a113=(a113+a133);
  a094=(a094-a113);
  a124=(a118*a124);
  a094=(a094+a124);
  if (res[1]!=0) res[1][2]=a094;
  a094=(a101*a112);
  a124=(a109*a094);
  a113=(a099*a091);
  a133=(a102*a113);
  a124=(a124-a133);
  a112=(a099*a112);
  a133=(a110*a112);
  a124=(a124-a133);
  a133=(a101*a123);
  a093=(a120*a133);
  a124=(a124+a093);
  a123=(a099*a123);
  a093=(a121*a123);
  a124=(a124-a093);
  a091=(a101*a091);
  a093=(a100*a091);
  a124=(a124+a093);
  if (res[1]!=0) res[1][3]=a124;
  a124=arg[1]? arg[1][23] : 0;
  a091=(a124*a091);
  a093=arg[1]? arg[1][22] : 0;
  a094=(a093*a094);
  a131=arg[1]? arg[1][21] : 0;
  a133=(a131*a133);
  a094=(a094+a133);
  a091=(a091+a094);
  a091=(-a091);
  if (res[1]!=0) res[1][4]=a091;
  a112=(a093*a112);
  a113=(a124*a113);
  a112=(a112+a113);
  a123=(a131*a123);
  a112=(a112+a123);
  if (res[1]!=0) res[1][5]=a112;
  a112=(a103*a098);
  a123=(a097*a062);
  a123=(a123+a098);
  a123=(-a123);
  a123=(2.*a123);
  a123=(a004*a123);
  a113=(a090*a123);
  a091=(a062*a113);
  a112=(a112+a091);
  a091=(a097*a108);
  a091=(a091+a107);
  a091=(-a091);
  a091=(2.*a091);
  a091=(a004*a091);
  a094=(a105*a091);
  a112=(a112+a094);
  a094=(a115*a107);
  a133=(a090*a091);
  a132=(a108*a133);
  a094=(a094+a132);
  a112=(a112+a094);
  a094=(a097*a119);
  a094=(a094+a118);
  a094=(-a094);
  a094=(2.*a094);
  a094=(a004*a094);
  a132=(a114*a094);
  a112=(a112+a132);
  a132=(a126*a118);
  a135=(a090*a094);
  a137=(a119*a135);
  a132=(a132+a137);
  a112=(a112+a132);
  a132=(a092*a123);
  a112=(a112+a132);
  a112=(-a112);
  if (res[1]!=0) res[1][6]=a112;
  a112=(a107*a091);
  a112=(a112-a111);
  a130=(a130*a098);
  a111=(a097*a123);
  a132=(a062*a111);
  a132=(a130-a132);
  a112=(a112-a132);
  a134=(a134*a107);
  a132=(a097*a091);
  a137=(a108*a132);
  a137=(a134+a137);
  a112=(a112+a137);
  a137=(a118*a094);
  a137=(a137-a122);
  a112=(a112+a137);
  a136=(a136*a118);
  a137=(a097*a094);
  a122=(a119*a137);
  a122=(a136+a122);
  a112=(a112+a122);
  a122=(a098*a123);
  a122=(a122-a128);
  a112=(a112+a122);
  if (res[1]!=0) res[1][7]=a112;
  a113=(a098*a113);
  a103=(a103*a062);
  a113=(a113-a103);
  a111=(a092*a111);
  a113=(a113-a111);
  a132=(a105*a132);
  a113=(a113-a132);
  a133=(a107*a133);
  a115=(a115*a108);
  a133=(a133-a115);
  a113=(a113+a133);
  a137=(a114*a137);
  a113=(a113-a137);
  a135=(a118*a135);
  a126=(a126*a119);
  a135=(a135-a126);
  a113=(a113+a135);
  if (res[1]!=0) res[1][8]=a113;
  a113=(a101*a091);
  a135=(a109*a113);
  a126=(a099*a123);
  a137=(a102*a126);
  a135=(a135-a137);
  a091=(a099*a091);
  a137=(a110*a091);
  a135=(a135-a137);
  a137=(a101*a094);
  a133=(a120*a137);
  a135=(a135+a133);
  a094=(a099*a094);
  a133=(a121*a094);
  a135=(a135-a133);
  a123=(a101*a123);
  a133=(a100*a123);
  a135=(a135+a133);
  if (res[1]!=0) res[1][9]=a135;
  a123=(a124*a123);
  a113=(a093*a113);
  a137=(a131*a137);
  a113=(a113+a137);
  a123=(a123+a113);
  a123=(-a123);
  if (res[1]!=0) res[1][10]=a123;
  a091=(a093*a091);
  a126=(a124*a126);
  a091=(a091+a126);
  a094=(a131*a094);
  a091=(a091+a094);
  if (res[1]!=0) res[1][11]=a091;
  a091=(a097*a092);
  a094=(a090*a098);
  a091=(a091-a094);
  a091=(2.*a091);
  a091=(a004*a091);
  a094=(a090*a091);
  a126=(a062*a094);
  a123=(a097*a105);
  a113=(a090*a107);
  a123=(a123-a113);
  a123=(2.*a123);
  a123=(a004*a123);
  a113=(a105*a123);
  a137=(a106*a107);
  a113=(a113-a137);
  a126=(a126+a113);
  a113=(a090*a123);
  a137=(a108*a113);
  a126=(a126+a137);
  a137=(a097*a114);
  a135=(a090*a118);
  a137=(a137-a135);
  a137=(2.*a137);
  a137=(a004*a137);
  a135=(a114*a137);
  a133=(a117*a118);
  a135=(a135-a133);
  a126=(a126+a135);
  a135=(a090*a137);
  a133=(a119*a135);
  a126=(a126+a133);
  a133=(a092*a091);
  a115=(a125*a098);
  a133=(a133-a115);
  a126=(a126+a133);
  a126=(-a126);
  if (res[1]!=0) res[1][12]=a126;
  a126=(a106*a105);
  a133=(a107*a123);
  a126=(a126+a133);
  a133=(a097*a091);
  a115=(a062*a133);
  a126=(a126+a115);
  a115=(a097*a123);
  a132=(a108*a115);
  a126=(a126+a132);
  a132=(a117*a114);
  a111=(a118*a137);
  a132=(a132+a111);
  a126=(a126+a132);
  a132=(a097*a137);
  a111=(a119*a132);
  a126=(a126+a111);
  a125=(a125*a092);
  a111=(a098*a091);
  a125=(a125+a111);
  a126=(a126+a125);
  if (res[1]!=0) res[1][13]=a126;
  a094=(a098*a094);
  a104=(a104+a094);
  a133=(a092*a133);
  a130=(a130+a133);
  a104=(a104-a130);
  a115=(a105*a115);
  a115=(a115-a134);
  a104=(a104-a115);
  a113=(a107*a113);
  a116=(a116+a113);
  a104=(a104+a116);
  a132=(a114*a132);
  a132=(a132-a136);
  a104=(a104-a132);
  a135=(a118*a135);
  a127=(a127+a135);
  a104=(a104+a127);
  if (res[1]!=0) res[1][14]=a104;
  a104=(a101*a123);
  a127=(a109*a104);
  a135=(a099*a091);
  a132=(a102*a135);
  a127=(a127-a132);
  a123=(a099*a123);
  a132=(a110*a123);
  a127=(a127-a132);
  a132=(a101*a137);
  a136=(a120*a132);
  a127=(a127+a136);
  a137=(a099*a137);
  a136=(a121*a137);
  a127=(a127-a136);
  a091=(a101*a091);
  a136=(a100*a091);
  a127=(a127+a136);
  if (res[1]!=0) res[1][15]=a127;
  a091=(a124*a091);
  a104=(a093*a104);
  a132=(a131*a132);
  a104=(a104+a132);
  a091=(a091+a104);
  a091=(-a091);
  if (res[1]!=0) res[1][16]=a091;
  a123=(a093*a123);
  a135=(a124*a135);
  a123=(a123+a135);
  a137=(a131*a137);
  a123=(a123+a137);
  if (res[1]!=0) res[1][17]=a123;
  a123=(a099*a102);
  a137=(a101*a100);
  a123=(a123-a137);
  a123=(2.*a123);
  a123=(a004*a123);
  a137=(a090*a123);
  a135=(a062*a137);
  a091=(a099*a110);
  a104=(a101*a109);
  a091=(a091-a104);
  a091=(2.*a091);
  a091=(a004*a091);
  a104=(a105*a091);
  a135=(a135+a104);
  a104=(a090*a091);
  a132=(a108*a104);
  a135=(a135+a132);
  a132=(a099*a121);
  a127=(a101*a120);
  a132=(a132-a127);
  a132=(2.*a132);
  a132=(a004*a132);
  a127=(a114*a132);
  a135=(a135+a127);
  a127=(a090*a132);
  a136=(a119*a127);
  a135=(a135+a136);
  a136=(a092*a123);
  a135=(a135+a136);
  a135=(-a135);
  if (res[1]!=0) res[1][18]=a135;
  a135=(a107*a091);
  a136=(a097*a123);
  a116=(a062*a136);
  a135=(a135+a116);
  a116=(a097*a091);
  a113=(a108*a116);
  a135=(a135+a113);
  a113=(a118*a132);
  a135=(a135+a113);
  a113=(a097*a132);
  a115=(a119*a113);
  a135=(a135+a115);
  a115=(a098*a123);
  a135=(a135+a115);
  if (res[1]!=0) res[1][19]=a135;
  a137=(a098*a137);
  a136=(a092*a136);
  a137=(a137-a136);
  a116=(a105*a116);
  a137=(a137-a116);
  a104=(a107*a104);
  a137=(a137+a104);
  a113=(a114*a113);
  a137=(a137-a113);
  a127=(a118*a127);
  a137=(a137+a127);
  if (res[1]!=0) res[1][20]=a137;
  a137=(a101*a106);
  a127=(a137*a110);
  a113=(a101*a091);
  a104=(a109*a113);
  a104=(a127+a104);
  a116=-2.9999999999999999e-02;
  a116=(a116*a004);
  a136=(a099*a096);
  a136=(a116-a136);
  a135=(a136*a100);
  a115=(a099*a123);
  a134=(a102*a115);
  a134=(a135+a134);
  a104=(a104-a134);
  a091=(a099*a091);
  a134=(a110*a091);
  a106=(a099*a106);
  a130=(a106*a109);
  a134=(a134-a130);
  a104=(a104-a134);
  a134=(a101*a117);
  a133=(a134*a121);
  a094=(a101*a132);
  a126=(a120*a094);
  a126=(a133+a126);
  a104=(a104+a126);
  a132=(a099*a132);
  a126=(a121*a132);
  a117=(a099*a117);
  a125=(a117*a120);
  a126=(a126-a125);
  a104=(a104-a126);
  a126=3.0000000000000004e-01;
  a126=(a126*a004);
  a096=(a101*a096);
  a096=(a126-a096);
  a111=(a096*a102);
  a123=(a101*a123);
  a103=(a100*a123);
  a103=(a111-a103);
  a104=(a104-a103);
  if (res[1]!=0) res[1][21]=a104;
  a123=(a124*a123);
  a113=(a093*a113);
  a094=(a131*a094);
  a113=(a113+a094);
  a123=(a123+a113);
  a123=(-a123);
  if (res[1]!=0) res[1][22]=a123;
  a091=(a093*a091);
  a115=(a124*a115);
  a091=(a091+a115);
  a132=(a131*a132);
  a091=(a091+a132);
  if (res[1]!=0) res[1][23]=a091;
  a091=-5.9999999999999998e-01;
  a132=(a091*a124);
  a132=(a004*a132);
  a115=(a090*a132);
  a123=(a062*a115);
  a113=(a091*a093);
  a113=(a004*a113);
  a094=(a105*a113);
  a123=(a123+a094);
  a094=(a090*a113);
  a104=(a108*a094);
  a123=(a123+a104);
  a091=(a091*a131);
  a091=(a004*a091);
  a104=(a114*a091);
  a123=(a123+a104);
  a104=(a090*a091);
  a103=(a119*a104);
  a123=(a123+a103);
  a103=(a092*a132);
  a123=(a123+a103);
  a123=(-a123);
  if (res[1]!=0) res[1][24]=a123;
  a123=(a107*a113);
  a103=(a097*a132);
  a112=(a062*a103);
  a123=(a123+a112);
  a112=(a097*a113);
  a122=(a108*a112);
  a123=(a123+a122);
  a122=(a118*a091);
  a123=(a123+a122);
  a122=(a097*a091);
  a128=(a119*a122);
  a123=(a123+a128);
  a128=(a098*a132);
  a123=(a123+a128);
  if (res[1]!=0) res[1][25]=a123;
  a115=(a098*a115);
  a103=(a092*a103);
  a115=(a115-a103);
  a112=(a105*a112);
  a115=(a115-a112);
  a094=(a107*a094);
  a115=(a115+a094);
  a122=(a114*a122);
  a115=(a115-a122);
  a104=(a118*a104);
  a115=(a115+a104);
  if (res[1]!=0) res[1][26]=a115;
  a115=(a136*a124);
  a104=(a099*a132);
  a122=(a102*a104);
  a115=(a115-a122);
  a122=(a101*a113);
  a094=(a109*a122);
  a115=(a115+a094);
  a094=(a106*a093);
  a113=(a099*a113);
  a112=(a110*a113);
  a094=(a094+a112);
  a115=(a115-a094);
  a094=(a101*a091);
  a112=(a120*a094);
  a115=(a115+a112);
  a112=(a117*a131);
  a091=(a099*a091);
  a103=(a121*a091);
  a112=(a112+a103);
  a115=(a115-a112);
  a132=(a101*a132);
  a112=(a100*a132);
  a115=(a115+a112);
  if (res[1]!=0) res[1][27]=a115;
  a132=(a124*a132);
  a111=(a111+a132);
  a122=(a093*a122);
  a122=(a122-a127);
  a094=(a131*a094);
  a094=(a094-a133);
  a122=(a122+a094);
  a111=(a111+a122);
  a111=(-a111);
  if (res[1]!=0) res[1][28]=a111;
  a113=(a093*a113);
  a106=(a106*a110);
  a113=(a113-a106);
  a136=(a136*a102);
  a104=(a124*a104);
  a136=(a136+a104);
  a113=(a113+a136);
  a091=(a131*a091);
  a117=(a117*a121);
  a091=(a091-a117);
  a113=(a113+a091);
  if (res[1]!=0) res[1][29]=a113;
  a113=(a099*a124);
  a113=(-a113);
  a113=(2.*a113);
  a113=(a004*a113);
  a091=(a090*a113);
  a117=(a062*a091);
  a136=(a099*a093);
  a136=(-a136);
  a136=(2.*a136);
  a136=(a004*a136);
  a104=(a105*a136);
  a117=(a117+a104);
  a104=(a090*a136);
  a106=(a108*a104);
  a117=(a117+a106);
  a106=(a099*a131);
  a106=(-a106);
  a106=(2.*a106);
  a106=(a004*a106);
  a111=(a114*a106);
  a117=(a117+a111);
  a111=(a090*a106);
  a122=(a119*a111);
  a117=(a117+a122);
  a122=(a092*a113);
  a117=(a117+a122);
  a117=(-a117);
  if (res[1]!=0) res[1][30]=a117;
  a117=(a107*a136);
  a122=(a097*a113);
  a094=(a062*a122);
  a117=(a117+a094);
  a094=(a097*a136);
  a133=(a108*a094);
  a117=(a117+a133);
  a133=(a118*a106);
  a117=(a117+a133);
  a133=(a097*a106);
  a127=(a119*a133);
  a117=(a117+a127);
  a127=(a098*a113);
  a117=(a117+a127);
  if (res[1]!=0) res[1][31]=a117;
  a091=(a098*a091);
  a122=(a092*a122);
  a091=(a091-a122);
  a094=(a105*a094);
  a091=(a091-a094);
  a104=(a107*a104);
  a091=(a091+a104);
  a133=(a114*a133);
  a091=(a091-a133);
  a111=(a118*a111);
  a091=(a091+a111);
  if (res[1]!=0) res[1][32]=a091;
  a091=(a101*a136);
  a111=(a109*a091);
  a133=(a137*a093);
  a111=(a111-a133);
  a133=(a099*a113);
  a104=(a102*a133);
  a111=(a111-a104);
  a136=(a099*a136);
  a104=(a110*a136);
  a111=(a111-a104);
  a104=(a101*a106);
  a094=(a120*a104);
  a122=(a134*a131);
  a094=(a094-a122);
  a111=(a111+a094);
  a106=(a099*a106);
  a094=(a121*a106);
  a111=(a111-a094);
  a094=(a096*a124);
  a113=(a101*a113);
  a122=(a100*a113);
  a094=(a094+a122);
  a111=(a111+a094);
  if (res[1]!=0) res[1][33]=a111;
  a096=(a096*a100);
  a113=(a124*a113);
  a096=(a096-a113);
  a137=(a137*a109);
  a091=(a093*a091);
  a137=(a137+a091);
  a134=(a134*a120);
  a104=(a131*a104);
  a134=(a134+a104);
  a137=(a137+a134);
  a096=(a096-a137);
  if (res[1]!=0) res[1][34]=a096;
  a136=(a093*a136);
  a130=(a130+a136);
  a133=(a124*a133);
  a135=(a135-a133);
  a130=(a130-a135);
  a106=(a131*a106);
  a125=(a125+a106);
  a130=(a130+a125);
  if (res[1]!=0) res[1][35]=a130;
  if (res[1]!=0) res[1][36]=a007;
  if (res[1]!=0) res[1][37]=a033;
  if (res[1]!=0) res[1][38]=a033;
  if (res[1]!=0) res[1][39]=a033;
  if (res[1]!=0) res[1][40]=a033;
  if (res[1]!=0) res[1][41]=a033;
  if (res[1]!=0) res[1][42]=a033;
  if (res[1]!=0) res[1][43]=a007;
  if (res[1]!=0) res[1][44]=a033;
  if (res[1]!=0) res[1][45]=a033;
  if (res[1]!=0) res[1][46]=a033;
  if (res[1]!=0) res[1][47]=a033;
  if (res[1]!=0) res[1][48]=a033;
  if (res[1]!=0) res[1][49]=a033;
  if (res[1]!=0) res[1][50]=a007;
  if (res[1]!=0) res[1][51]=a033;
  if (res[1]!=0) res[1][52]=a033;
  if (res[1]!=0) res[1][53]=a033;
  if (res[1]!=0) res[1][54]=a033;
  if (res[1]!=0) res[1][55]=a033;
  if (res[1]!=0) res[1][56]=a033;
  if (res[1]!=0) res[1][57]=a007;
  if (res[1]!=0) res[1][58]=a033;
  if (res[1]!=0) res[1][59]=a033;
  if (res[1]!=0) res[1][60]=a033;
  if (res[1]!=0) res[1][61]=a033;
  if (res[1]!=0) res[1][62]=a033;
  if (res[1]!=0) res[1][63]=a033;
  if (res[1]!=0) res[1][64]=a007;
  if (res[1]!=0) res[1][65]=a033;
  if (res[1]!=0) res[1][66]=a033;
  if (res[1]!=0) res[1][67]=a033;
  if (res[1]!=0) res[1][68]=a033;
  if (res[1]!=0) res[1][69]=a033;
  if (res[1]!=0) res[1][70]=a033;
  if (res[1]!=0) res[1][71]=a007;
  a130=(a008+a043);
  a130=(a130+a049);
  a130=(a009+a130);
  a125=(a009/a130);
  a045=(a045/a022);
  a045=(a011+a045);
  a106=(a125*a045);
  a135=(a118*a106);
  a047=(a047/a022);
  a047=(a047-a001);
  a133=(a125*a047);
  a136=(a114*a133);
  a135=(a135+a136);
  a136=(a043+a008);
  a136=(a136/a022);
  a096=(a125*a136);
  a096=(a007-a096);
  a137=(a119*a096);
  a135=(a135+a137);
  a012=(a027*a012);
  a012=(a125*a012);
  a038=(a038/a022);
  a038=(a038-a016);
  a130=(a125/a130);
  a137=(a130*a005);
  a134=(a038*a137);
  a134=(a012-a134);
  a104=(a118*a134);
  a005=(a027*a005);
  a005=(a125*a005);
  a008=(a049+a008);
  a008=(a008/a022);
  a091=(a008*a137);
  a091=(a005-a091);
  a113=(a114*a091);
  a104=(a104-a113);
  a113=(a125*a004);
  a020=(a020/a022);
  a001=(a001+a020);
  a020=(a001*a137);
  a020=(a113-a020);
  a111=(a119*a020);
  a104=(a104+a111);
  a111=(a135*a104);
  a094=(a107*a106);
  a122=(a105*a133);
  a094=(a094+a122);
  a122=(a108*a096);
  a094=(a094+a122);
  a122=(a107*a134);
  a117=(a105*a091);
  a122=(a122-a117);
  a117=(a108*a020);
  a122=(a122+a117);
  a117=(a094*a122);
  a111=(a111+a117);
  a117=(a098*a106);
  a127=(a092*a133);
  a117=(a117+a127);
  a127=(a062*a096);
  a117=(a117+a127);
  a134=(a098*a134);
  a091=(a092*a091);
  a134=(a134-a091);
  a020=(a062*a020);
  a134=(a134+a020);
  a020=(a117*a134);
  a111=(a111+a020);
  if (res[2]!=0) res[2][0]=a111;
  a049=(a049+a043);
  a049=(a049/a022);
  a043=(a125*a049);
  a043=(a007-a043);
  a111=(a118*a043);
  a024=(a024/a022);
  a016=(a016+a024);
  a024=(a125*a016);
  a020=(a114*a024);
  a111=(a111+a020);
  a030=(a030/a022);
  a030=(a030-a011);
  a011=(a125*a030);
  a020=(a119*a011);
  a111=(a111+a020);
  a018=(a027*a018);
  a018=(a125*a018);
  a020=(a045*a137);
  a020=(a018-a020);
  a091=(a118*a020);
  a127=(a047*a137);
  a127=(a127+a113);
  a132=(a114*a127);
  a091=(a091-a132);
  a132=(a136*a137);
  a005=(a005-a132);
  a132=(a119*a005);
  a091=(a091-a132);
  a132=(a111*a091);
  a115=(a107*a043);
  a112=(a105*a024);
  a115=(a115+a112);
  a112=(a108*a011);
  a115=(a115+a112);
  a112=(a107*a020);
  a103=(a105*a127);
  a112=(a112-a103);
  a103=(a108*a005);
  a112=(a112-a103);
  a103=(a115*a112);
  a132=(a132+a103);
  a103=(a098*a043);
  a123=(a092*a024);
  a103=(a103+a123);
  a123=(a062*a011);
  a103=(a103+a123);
  a020=(a098*a020);
  a127=(a092*a127);
  a020=(a020-a127);
  a005=(a062*a005);
  a020=(a020-a005);
  a005=(a103*a020);
  a132=(a132+a005);
  if (res[2]!=0) res[2][1]=a132;
  a132=(a125*a038);
  a005=(a118*a132);
  a127=(a125*a008);
  a127=(a007-a127);
  a123=(a114*a127);
  a005=(a005+a123);
  a123=(a125*a001);
  a128=(a119*a123);
  a005=(a005+a128);
  a128=(a049*a137);
  a138=(a118*a128);
  a139=(a016*a137);
  a139=(a012-a139);
  a140=(a114*a139);
  a138=(a138+a140);
  a137=(a030*a137);
  a137=(a018-a137);
  a140=(a119*a137);
  a138=(a138+a140);
  a140=(a005*a138);
  a141=(a107*a132);
  a142=(a105*a127);
  a141=(a141+a142);
  a142=(a108*a123);
  a141=(a141+a142);
  a142=(a107*a128);
  a143=(a105*a139);
  a142=(a142+a143);
  a143=(a108*a137);
  a142=(a142+a143);
  a143=(a141*a142);
  a140=(a140+a143);
  a143=(a098*a132);
  a144=(a092*a127);
  a143=(a143+a144);
  a144=(a062*a123);
  a143=(a143+a144);
  a128=(a098*a128);
  a139=(a092*a139);
  a128=(a128+a139);
  a137=(a062*a137);
  a128=(a128+a137);
  a137=(a143*a128);
  a140=(a140+a137);
  if (res[2]!=0) res[2][2]=a140;
  if (res[2]!=0) res[2][3]=a033;
  if (res[2]!=0) res[2][4]=a033;
  if (res[2]!=0) res[2][5]=a033;
  a140=(a090*a143);
  a095=(a095+a140);
  a140=(a097*a103);
  a095=(a095+a140);
  a095=(a095-a117);
  a140=(a054+a084);
  a140=(a140+a003);
  a140=(a009+a140);
  a009=(a009/a140);
  a079=(a079/a022);
  a079=(a079-a061);
  a137=(a009*a079);
  a139=(a124*a137);
  a144=(a003+a054);
  a144=(a144/a022);
  a145=(a009*a144);
  a145=(a007-a145);
  a146=(a100*a145);
  a139=(a139+a146);
  a065=(a065/a022);
  a065=(a050+a065);
  a146=(a009*a065);
  a147=(a102*a146);
  a139=(a139+a147);
  a147=(a099*a139);
  a095=(a095+a147);
  a086=(a086/a022);
  a086=(a055+a086);
  a147=(a009*a086);
  a148=(a124*a147);
  a088=(a088/a022);
  a088=(a088-a050);
  a050=(a009*a088);
  a149=(a100*a050);
  a148=(a148+a149);
  a054=(a084+a054);
  a054=(a054/a022);
  a149=(a009*a054);
  a149=(a007-a149);
  a150=(a102*a149);
  a148=(a148+a150);
  a150=(a101*a148);
  a095=(a095+a150);
  a095=(2.*a095);
  a095=(a095*a004);
  a150=(a090*a095);
  a151=(a150*a020);
  a152=(a090*a134);
  a153=(a097*a128);
  a152=(a152+a153);
  a152=(a152-a020);
  a152=(2.*a152);
  a152=(a004*a152);
  a153=(a090*a152);
  a154=(a117*a153);
  a151=(a151+a154);
  a154=(a090*a141);
  a155=(a097*a115);
  a154=(a154+a155);
  a154=(a154-a094);
  a155=(a093*a137);
  a156=(a109*a145);
  a155=(a155+a156);
  a156=(a110*a146);
  a155=(a155+a156);
  a156=(a099*a155);
  a154=(a154+a156);
  a156=(a093*a147);
  a157=(a109*a050);
  a156=(a156+a157);
  a157=(a110*a149);
  a156=(a156+a157);
  a157=(a101*a156);
  a154=(a154+a157);
  a154=(2.*a154);
  a154=(a154*a004);
  a157=(a154*a122);
  a158=(a090*a122);
  a159=(a097*a142);
  a158=(a158+a159);
  a158=(a158-a112);
  a158=(2.*a158);
  a158=(a004*a158);
  a159=(a141*a158);
  a157=(a157+a159);
  a151=(a151+a157);
  a157=(a090*a154);
  a159=(a157*a112);
  a160=(a090*a158);
  a161=(a094*a160);
  a159=(a159+a161);
  a151=(a151+a159);
  a159=(a090*a005);
  a161=(a097*a111);
  a159=(a159+a161);
  a159=(a159-a135);
  a161=(a131*a137);
  a162=(a120*a145);
  a161=(a161+a162);
  a162=(a121*a146);
  a161=(a161+a162);
  a162=(a099*a161);
  a159=(a159+a162);
  a162=(a131*a147);
  a163=(a120*a050);
  a162=(a162+a163);
  a163=(a121*a149);
  a162=(a162+a163);
  a163=(a101*a162);
  a159=(a159+a163);
  a159=(2.*a159);
  a159=(a159*a004);
  a163=(a159*a104);
  a164=(a090*a104);
  a165=(a097*a138);
  a164=(a164+a165);
  a164=(a164-a091);
  a164=(2.*a164);
  a164=(a004*a164);
  a165=(a005*a164);
  a163=(a163+a165);
  a151=(a151+a163);
  a163=(a090*a159);
  a165=(a163*a091);
  a166=(a090*a164);
  a167=(a135*a166);
  a165=(a165+a167);
  a151=(a151+a165);
  a028=(a095+a028);
  a165=(a028*a134);
  a167=(a143*a152);
  a165=(a165+a167);
  a151=(a151+a165);
  a006=(a006-a151);
  if (res[2]!=0) res[2][6]=a006;
  a025=(a025-a023);
  a025=(a000*a025);
  a021=(a021+a025);
  a021=(a021+a029);
  a025=(a154*a142);
  a006=(a115*a158);
  a025=(a025+a006);
  a006=(a097*a095);
  a129=(a129-a006);
  a020=(a129*a020);
  a006=(a097*a152);
  a151=(a117*a006);
  a020=(a020-a151);
  a025=(a025-a020);
  a020=(a097*a154);
  a112=(a020*a112);
  a151=(a097*a158);
  a165=(a094*a151);
  a112=(a112+a165);
  a025=(a025+a112);
  a112=(a159*a138);
  a165=(a111*a164);
  a112=(a112+a165);
  a025=(a025+a112);
  a112=(a097*a159);
  a091=(a112*a091);
  a165=(a097*a164);
  a167=(a135*a165);
  a091=(a091+a167);
  a025=(a025+a091);
  a091=(a028*a128);
  a167=(a103*a152);
  a091=(a091+a167);
  a025=(a025+a091);
  a021=(a021+a025);
  if (res[2]!=0) res[2][7]=a021;
  a031=(a032+a031);
  a000=(a000*a031);
  a026=(a026+a000);
  a026=(a026-a034);
  a134=(a129*a134);
  a006=(a143*a006);
  a134=(a134-a006);
  a128=(a150*a128);
  a153=(a103*a153);
  a128=(a128+a153);
  a134=(a134+a128);
  a122=(a020*a122);
  a151=(a141*a151);
  a122=(a122+a151);
  a134=(a134-a122);
  a142=(a157*a142);
  a160=(a115*a160);
  a142=(a142+a160);
  a134=(a134+a142);
  a104=(a112*a104);
  a165=(a005*a165);
  a104=(a104+a165);
  a134=(a134-a104);
  a138=(a163*a138);
  a166=(a111*a166);
  a138=(a138+a166);
  a134=(a134+a138);
  a026=(a026+a134);
  if (res[2]!=0) res[2][8]=a026;
  a026=(a101*a158);
  a134=(a155*a026);
  a138=(a099*a152);
  a166=(a148*a138);
  a134=(a134-a166);
  a158=(a099*a158);
  a166=(a156*a158);
  a134=(a134-a166);
  a166=(a101*a164);
  a104=(a161*a166);
  a134=(a134+a104);
  a164=(a099*a164);
  a104=(a162*a164);
  a134=(a134-a104);
  a152=(a101*a152);
  a104=(a139*a152);
  a134=(a134+a104);
  if (res[2]!=0) res[2][9]=a134;
  a003=(a003+a084);
  a003=(a003/a022);
  a084=(a009*a003);
  a007=(a007-a084);
  a084=(a124*a007);
  a068=(a068/a022);
  a061=(a061+a068);
  a068=(a009*a061);
  a134=(a100*a068);
  a084=(a084+a134);
  a072=(a072/a022);
  a072=(a072-a055);
  a055=(a009*a072);
  a022=(a102*a055);
  a084=(a084+a022);
  a152=(a084*a152);
  a022=(a093*a007);
  a134=(a109*a068);
  a022=(a022+a134);
  a134=(a110*a055);
  a022=(a022+a134);
  a026=(a022*a026);
  a134=(a131*a007);
  a104=(a120*a068);
  a134=(a134+a104);
  a104=(a121*a055);
  a134=(a134+a104);
  a166=(a134*a166);
  a026=(a026+a166);
  a152=(a152+a026);
  a152=(-a152);
  if (res[2]!=0) res[2][10]=a152;
  a158=(a022*a158);
  a138=(a084*a138);
  a158=(a158+a138);
  a164=(a134*a164);
  a158=(a158+a164);
  if (res[2]!=0) res[2][11]=a158;
  a035=(a027*a035);
  a035=(a125*a035);
  a158=(a130*a041);
  a164=(a038*a158);
  a164=(a035-a164);
  a138=(a118*a164);
  a152=(a008*a158);
  a026=(a114*a152);
  a138=(a138+a026);
  a026=(a001*a158);
  a026=(a018-a026);
  a166=(a119*a026);
  a138=(a138+a166);
  a166=(a135*a138);
  a104=(a107*a164);
  a165=(a105*a152);
  a104=(a104+a165);
  a165=(a108*a026);
  a104=(a104+a165);
  a165=(a094*a104);
  a166=(a166+a165);
  a164=(a098*a164);
  a152=(a092*a152);
  a164=(a164+a152);
  a026=(a062*a026);
  a164=(a164+a026);
  a026=(a117*a164);
  a166=(a166+a026);
  if (res[2]!=0) res[2][12]=a166;
  a166=(a045*a158);
  a166=(a113-a166);
  a026=(a118*a166);
  a152=(a047*a158);
  a018=(a018-a152);
  a152=(a114*a018);
  a026=(a026+a152);
  a041=(a027*a041);
  a041=(a125*a041);
  a152=(a136*a158);
  a152=(a041-a152);
  a165=(a119*a152);
  a026=(a026-a165);
  a165=(a111*a026);
  a142=(a107*a166);
  a160=(a105*a018);
  a142=(a142+a160);
  a160=(a108*a152);
  a142=(a142-a160);
  a160=(a115*a142);
  a165=(a165+a160);
  a166=(a098*a166);
  a018=(a092*a018);
  a166=(a166+a018);
  a152=(a062*a152);
  a166=(a166-a152);
  a152=(a103*a166);
  a165=(a165+a152);
  if (res[2]!=0) res[2][13]=a165;
  a165=(a016*a158);
  a165=(a035-a165);
  a152=(a114*a165);
  a018=(a049*a158);
  a041=(a041-a018);
  a018=(a118*a041);
  a152=(a152-a018);
  a158=(a030*a158);
  a158=(a158+a113);
  a018=(a119*a158);
  a152=(a152-a018);
  a018=(a005*a152);
  a160=(a105*a165);
  a122=(a107*a041);
  a160=(a160-a122);
  a122=(a108*a158);
  a160=(a160-a122);
  a122=(a141*a160);
  a018=(a018+a122);
  a165=(a092*a165);
  a041=(a098*a041);
  a165=(a165-a041);
  a158=(a062*a158);
  a165=(a165-a158);
  a158=(a143*a165);
  a018=(a018+a158);
  if (res[2]!=0) res[2][14]=a018;
  if (res[2]!=0) res[2][15]=a033;
  if (res[2]!=0) res[2][16]=a033;
  if (res[2]!=0) res[2][17]=a033;
  a023=(a023+a039);
  a037=(a037+a023);
  a037=(a037-a029);
  a029=(a150*a166);
  a023=(a090*a164);
  a039=(a097*a165);
  a023=(a023+a039);
  a023=(a023-a166);
  a023=(2.*a023);
  a023=(a004*a023);
  a039=(a090*a023);
  a018=(a117*a039);
  a029=(a029+a018);
  a018=(a154*a104);
  a158=(a090*a104);
  a041=(a097*a160);
  a158=(a158+a041);
  a158=(a158-a142);
  a158=(2.*a158);
  a158=(a004*a158);
  a041=(a141*a158);
  a018=(a018+a041);
  a029=(a029+a018);
  a018=(a157*a142);
  a041=(a090*a158);
  a122=(a094*a041);
  a018=(a018+a122);
  a029=(a029+a018);
  a018=(a159*a138);
  a122=(a090*a138);
  a151=(a097*a152);
  a122=(a122+a151);
  a122=(a122-a026);
  a122=(2.*a122);
  a122=(a004*a122);
  a151=(a005*a122);
  a018=(a018+a151);
  a029=(a029+a018);
  a018=(a163*a026);
  a151=(a090*a122);
  a128=(a135*a151);
  a018=(a018+a128);
  a029=(a029+a018);
  a018=(a028*a164);
  a128=(a143*a023);
  a018=(a018+a128);
  a029=(a029+a018);
  a037=(a037-a029);
  if (res[2]!=0) res[2][18]=a037;
  a037=(a154*a160);
  a029=(a115*a158);
  a037=(a037+a029);
  a166=(a129*a166);
  a029=(a097*a023);
  a018=(a117*a029);
  a166=(a166-a018);
  a037=(a037-a166);
  a142=(a020*a142);
  a166=(a097*a158);
  a018=(a094*a166);
  a142=(a142+a018);
  a037=(a037+a142);
  a142=(a159*a152);
  a018=(a111*a122);
  a142=(a142+a018);
  a037=(a037+a142);
  a026=(a112*a026);
  a142=(a097*a122);
  a018=(a135*a142);
  a026=(a026+a018);
  a037=(a037+a026);
  a026=(a028*a165);
  a018=(a103*a023);
  a026=(a026+a018);
  a037=(a037+a026);
  a042=(a042+a037);
  if (res[2]!=0) res[2][19]=a042;
  a044=(a044-a019);
  a010=(a010+a044);
  a010=(a002+a010);
  a164=(a129*a164);
  a029=(a143*a029);
  a164=(a164-a029);
  a165=(a150*a165);
  a039=(a103*a039);
  a165=(a165+a039);
  a164=(a164+a165);
  a104=(a020*a104);
  a166=(a141*a166);
  a104=(a104+a166);
  a164=(a164-a104);
  a160=(a157*a160);
  a041=(a115*a041);
  a160=(a160+a041);
  a164=(a164+a160);
  a138=(a112*a138);
  a142=(a005*a142);
  a138=(a138+a142);
  a164=(a164-a138);
  a152=(a163*a152);
  a151=(a111*a151);
  a152=(a152+a151);
  a164=(a164+a152);
  a010=(a010+a164);
  if (res[2]!=0) res[2][20]=a010;
  a010=(a101*a158);
  a164=(a155*a010);
  a152=(a099*a023);
  a151=(a148*a152);
  a164=(a164-a151);
  a158=(a099*a158);
  a151=(a156*a158);
  a164=(a164-a151);
  a151=(a101*a122);
  a138=(a161*a151);
  a164=(a164+a138);
  a122=(a099*a122);
  a138=(a162*a122);
  a164=(a164-a138);
  a023=(a101*a023);
  a138=(a139*a023);
  a164=(a164+a138);
  if (res[2]!=0) res[2][21]=a164;
  a023=(a084*a023);
  a010=(a022*a010);
  a151=(a134*a151);
  a010=(a010+a151);
  a023=(a023+a010);
  a023=(-a023);
  if (res[2]!=0) res[2][22]=a023;
  a158=(a022*a158);
  a152=(a084*a152);
  a158=(a158+a152);
  a122=(a134*a122);
  a158=(a158+a122);
  if (res[2]!=0) res[2][23]=a158;
  a130=(a130*a014);
  a001=(a001*a130);
  a001=(a012-a001);
  a158=(a119*a001);
  a038=(a038*a130);
  a038=(a038+a113);
  a122=(a118*a038);
  a014=(a027*a014);
  a125=(a125*a014);
  a008=(a008*a130);
  a008=(a125-a008);
  a014=(a114*a008);
  a122=(a122+a014);
  a158=(a158-a122);
  a122=(a135*a158);
  a014=(a108*a001);
  a152=(a107*a038);
  a023=(a105*a008);
  a152=(a152+a023);
  a014=(a014-a152);
  a152=(a094*a014);
  a122=(a122+a152);
  a001=(a062*a001);
  a038=(a098*a038);
  a008=(a092*a008);
  a038=(a038+a008);
  a001=(a001-a038);
  a038=(a117*a001);
  a122=(a122+a038);
  if (res[2]!=0) res[2][24]=a122;
  a045=(a045*a130);
  a045=(a035-a045);
  a122=(a118*a045);
  a047=(a047*a130);
  a012=(a012-a047);
  a047=(a114*a012);
  a122=(a122+a047);
  a136=(a136*a130);
  a047=(a119*a136);
  a122=(a122+a047);
  a047=(a111*a122);
  a038=(a107*a045);
  a008=(a105*a012);
  a038=(a038+a008);
  a008=(a108*a136);
  a038=(a038+a008);
  a008=(a115*a038);
  a047=(a047+a008);
  a045=(a098*a045);
  a012=(a092*a012);
  a045=(a045+a012);
  a136=(a062*a136);
  a045=(a045+a136);
  a136=(a103*a045);
  a047=(a047+a136);
  if (res[2]!=0) res[2][25]=a047;
  a016=(a016*a130);
  a113=(a113-a016);
  a016=(a114*a113);
  a049=(a049*a130);
  a125=(a125-a049);
  a049=(a118*a125);
  a016=(a016-a049);
  a030=(a030*a130);
  a035=(a035-a030);
  a030=(a119*a035);
  a016=(a016+a030);
  a030=(a005*a016);
  a130=(a105*a113);
  a049=(a107*a125);
  a130=(a130-a049);
  a049=(a108*a035);
  a130=(a130+a049);
  a049=(a141*a130);
  a030=(a030+a049);
  a113=(a092*a113);
  a125=(a098*a125);
  a113=(a113-a125);
  a035=(a062*a035);
  a113=(a113+a035);
  a035=(a143*a113);
  a030=(a030+a035);
  if (res[2]!=0) res[2][26]=a030;
  if (res[2]!=0) res[2][27]=a033;
  if (res[2]!=0) res[2][28]=a033;
  if (res[2]!=0) res[2][29]=a033;
  a046=(a046-a032);
  a046=(a015*a046);
  a036=(a036+a046);
  a034=(a034+a036);
  a036=(a150*a045);
  a046=(a090*a001);
  a032=(a097*a113);
  a046=(a046+a032);
  a046=(a046-a045);
  a046=(2.*a046);
  a046=(a004*a046);
  a032=(a090*a046);
  a030=(a117*a032);
  a036=(a036+a030);
  a030=(a154*a014);
  a035=(a090*a014);
  a125=(a097*a130);
  a035=(a035+a125);
  a035=(a035-a038);
  a035=(2.*a035);
  a035=(a004*a035);
  a125=(a141*a035);
  a030=(a030+a125);
  a036=(a036+a030);
  a030=(a157*a038);
  a125=(a090*a035);
  a049=(a094*a125);
  a030=(a030+a049);
  a036=(a036+a030);
  a030=(a159*a158);
  a049=(a090*a158);
  a047=(a097*a016);
  a049=(a049+a047);
  a049=(a049-a122);
  a049=(2.*a049);
  a049=(a004*a049);
  a047=(a005*a049);
  a030=(a030+a047);
  a036=(a036+a030);
  a030=(a163*a122);
  a047=(a090*a049);
  a136=(a135*a047);
  a030=(a030+a136);
  a036=(a036+a030);
  a030=(a028*a001);
  a136=(a143*a046);
  a030=(a030+a136);
  a036=(a036+a030);
  a034=(a034-a036);
  if (res[2]!=0) res[2][30]=a034;
  a019=(a019+a048);
  a015=(a015*a019);
  a013=(a013+a015);
  a013=(a013-a002);
  a002=(a154*a130);
  a015=(a115*a035);
  a002=(a002+a015);
  a045=(a129*a045);
  a015=(a097*a046);
  a019=(a117*a015);
  a045=(a045-a019);
  a002=(a002-a045);
  a038=(a020*a038);
  a045=(a097*a035);
  a019=(a094*a045);
  a038=(a038+a019);
  a002=(a002+a038);
  a038=(a159*a016);
  a019=(a111*a049);
  a038=(a038+a019);
  a002=(a002+a038);
  a122=(a112*a122);
  a038=(a097*a049);
  a019=(a135*a038);
  a122=(a122+a019);
  a002=(a002+a122);
  a122=(a028*a113);
  a019=(a103*a046);
  a122=(a122+a019);
  a002=(a002+a122);
  a013=(a013+a002);
  if (res[2]!=0) res[2][31]=a013;
  a001=(a129*a001);
  a015=(a143*a015);
  a001=(a001-a015);
  a113=(a150*a113);
  a032=(a103*a032);
  a113=(a113+a032);
  a001=(a001+a113);
  a014=(a020*a014);
  a045=(a141*a045);
  a014=(a014+a045);
  a001=(a001-a014);
  a130=(a157*a130);
  a125=(a115*a125);
  a130=(a130+a125);
  a001=(a001+a130);
  a158=(a112*a158);
  a038=(a005*a038);
  a158=(a158+a038);
  a001=(a001-a158);
  a016=(a163*a016);
  a047=(a111*a047);
  a016=(a016+a047);
  a001=(a001+a016);
  a040=(a040+a001);
  if (res[2]!=0) res[2][32]=a040;
  a040=(a101*a035);
  a001=(a155*a040);
  a016=(a099*a046);
  a047=(a148*a016);
  a001=(a001-a047);
  a035=(a099*a035);
  a047=(a156*a035);
  a001=(a001-a047);
  a047=(a101*a049);
  a158=(a161*a047);
  a001=(a001+a158);
  a049=(a099*a049);
  a158=(a162*a049);
  a001=(a001-a158);
  a046=(a101*a046);
  a158=(a139*a046);
  a001=(a001+a158);
  if (res[2]!=0) res[2][33]=a001;
  a046=(a084*a046);
  a040=(a022*a040);
  a047=(a134*a047);
  a040=(a040+a047);
  a046=(a046+a040);
  a046=(-a046);
  if (res[2]!=0) res[2][34]=a046;
  a035=(a022*a035);
  a016=(a084*a016);
  a035=(a035+a016);
  a049=(a134*a049);
  a035=(a035+a049);
  if (res[2]!=0) res[2][35]=a035;
  if (res[2]!=0) res[2][36]=a033;
  if (res[2]!=0) res[2][37]=a033;
  if (res[2]!=0) res[2][38]=a033;
  a057=(a027*a057);
  a057=(a009*a057);
  a140=(a009/a140);
  a035=(a140*a052);
  a049=(a079*a035);
  a049=(a057-a049);
  a016=(a131*a049);
  a052=(a027*a052);
  a052=(a009*a052);
  a046=(a144*a035);
  a046=(a052-a046);
  a040=(a120*a046);
  a016=(a016-a040);
  a040=(a009*a004);
  a047=(a065*a035);
  a047=(a040-a047);
  a001=(a121*a047);
  a016=(a016+a001);
  a001=(a162*a016);
  a158=(a093*a049);
  a038=(a109*a046);
  a158=(a158-a038);
  a038=(a110*a047);
  a158=(a158+a038);
  a038=(a156*a158);
  a001=(a001+a038);
  a049=(a124*a049);
  a046=(a100*a046);
  a049=(a049-a046);
  a047=(a102*a047);
  a049=(a049+a047);
  a047=(a148*a049);
  a001=(a001+a047);
  if (res[2]!=0) res[2][39]=a001;
  a063=(a027*a063);
  a063=(a009*a063);
  a001=(a086*a035);
  a001=(a063-a001);
  a047=(a131*a001);
  a046=(a088*a035);
  a046=(a046+a040);
  a038=(a120*a046);
  a047=(a047-a038);
  a038=(a054*a035);
  a052=(a052-a038);
  a038=(a121*a052);
  a047=(a047-a038);
  a038=(a134*a047);
  a130=(a093*a001);
  a125=(a109*a046);
  a130=(a130-a125);
  a125=(a110*a052);
  a130=(a130-a125);
  a125=(a022*a130);
  a038=(a038+a125);
  a001=(a124*a001);
  a046=(a100*a046);
  a001=(a001-a046);
  a052=(a102*a052);
  a001=(a001-a052);
  a052=(a084*a001);
  a038=(a038+a052);
  if (res[2]!=0) res[2][40]=a038;
  a038=(a003*a035);
  a052=(a131*a038);
  a046=(a061*a035);
  a046=(a057-a046);
  a125=(a120*a046);
  a052=(a052+a125);
  a035=(a072*a035);
  a035=(a063-a035);
  a125=(a121*a035);
  a052=(a052+a125);
  a125=(a161*a052);
  a014=(a093*a038);
  a045=(a109*a046);
  a014=(a014+a045);
  a045=(a110*a035);
  a014=(a014+a045);
  a045=(a155*a014);
  a125=(a125+a045);
  a038=(a124*a038);
  a046=(a100*a046);
  a038=(a038+a046);
  a035=(a102*a035);
  a038=(a038+a035);
  a035=(a139*a038);
  a125=(a125+a035);
  if (res[2]!=0) res[2][41]=a125;
  a125=(a099*a049);
  a035=(a101*a001);
  a125=(a125+a035);
  a125=(2.*a125);
  a125=(a004*a125);
  a035=(a090*a125);
  a046=(a117*a035);
  a045=(a099*a158);
  a113=(a101*a130);
  a045=(a045+a113);
  a045=(2.*a045);
  a045=(a004*a045);
  a113=(a141*a045);
  a046=(a046+a113);
  a113=(a090*a045);
  a032=(a094*a113);
  a046=(a046+a032);
  a032=(a099*a016);
  a015=(a101*a047);
  a032=(a032+a015);
  a032=(2.*a032);
  a032=(a004*a032);
  a015=(a005*a032);
  a046=(a046+a015);
  a015=(a090*a032);
  a013=(a135*a015);
  a046=(a046+a013);
  a013=(a143*a125);
  a046=(a046+a013);
  a046=(-a046);
  if (res[2]!=0) res[2][42]=a046;
  a046=(a115*a045);
  a013=(a097*a125);
  a002=(a117*a013);
  a046=(a046+a002);
  a002=(a097*a045);
  a122=(a094*a002);
  a046=(a046+a122);
  a122=(a111*a032);
  a046=(a046+a122);
  a122=(a097*a032);
  a019=(a135*a122);
  a046=(a046+a019);
  a019=(a103*a125);
  a046=(a046+a019);
  if (res[2]!=0) res[2][43]=a046;
  a035=(a103*a035);
  a013=(a143*a013);
  a035=(a035-a013);
  a002=(a141*a002);
  a035=(a035-a002);
  a113=(a115*a113);
  a035=(a035+a113);
  a122=(a005*a122);
  a035=(a035-a122);
  a015=(a111*a015);
  a035=(a035+a015);
  if (res[2]!=0) res[2][44]=a035;
  a035=(a099*a095);
  a116=(a116-a035);
  a001=(a116*a001);
  a035=(a099*a125);
  a015=(a148*a035);
  a001=(a001-a015);
  a015=(a101*a154);
  a158=(a015*a158);
  a122=(a101*a045);
  a113=(a155*a122);
  a158=(a158+a113);
  a001=(a001+a158);
  a158=(a099*a154);
  a130=(a158*a130);
  a045=(a099*a045);
  a113=(a156*a045);
  a130=(a130+a113);
  a001=(a001-a130);
  a130=(a101*a159);
  a016=(a130*a016);
  a113=(a101*a032);
  a002=(a161*a113);
  a016=(a016+a002);
  a001=(a001+a016);
  a016=(a099*a159);
  a047=(a016*a047);
  a032=(a099*a032);
  a002=(a162*a032);
  a047=(a047+a002);
  a001=(a001-a047);
  a095=(a101*a095);
  a126=(a126-a095);
  a049=(a126*a049);
  a125=(a101*a125);
  a095=(a139*a125);
  a049=(a049-a095);
  a001=(a001-a049);
  a053=(a053+a001);
  if (res[2]!=0) res[2][45]=a053;
  a069=(a069-a067);
  a069=(a017*a069);
  a066=(a066+a069);
  a066=(a066+a071);
  a069=(a126*a038);
  a125=(a084*a125);
  a069=(a069-a125);
  a125=(a015*a014);
  a122=(a022*a122);
  a125=(a125+a122);
  a122=(a130*a052);
  a113=(a134*a113);
  a122=(a122+a113);
  a125=(a125+a122);
  a069=(a069-a125);
  a066=(a066+a069);
  if (res[2]!=0) res[2][46]=a066;
  a073=(a074+a073);
  a017=(a017*a073);
  a070=(a070+a017);
  a070=(a070-a076);
  a014=(a158*a014);
  a045=(a022*a045);
  a014=(a014+a045);
  a038=(a116*a038);
  a035=(a084*a035);
  a038=(a038-a035);
  a014=(a014-a038);
  a052=(a016*a052);
  a032=(a134*a032);
  a052=(a052+a032);
  a014=(a014+a052);
  a070=(a070+a014);
  if (res[2]!=0) res[2][47]=a070;
  if (res[2]!=0) res[2][48]=a033;
  if (res[2]!=0) res[2][49]=a033;
  if (res[2]!=0) res[2][50]=a033;
  a075=(a027*a075);
  a075=(a009*a075);
  a070=(a140*a082);
  a014=(a079*a070);
  a014=(a075-a014);
  a052=(a131*a014);
  a032=(a144*a070);
  a038=(a120*a032);
  a052=(a052+a038);
  a038=(a065*a070);
  a038=(a063-a038);
  a035=(a121*a038);
  a052=(a052+a035);
  a035=(a162*a052);
  a045=(a093*a014);
  a017=(a109*a032);
  a045=(a045+a017);
  a017=(a110*a038);
  a045=(a045+a017);
  a017=(a156*a045);
  a035=(a035+a017);
  a014=(a124*a014);
  a032=(a100*a032);
  a014=(a014+a032);
  a038=(a102*a038);
  a014=(a014+a038);
  a038=(a148*a014);
  a035=(a035+a038);
  if (res[2]!=0) res[2][51]=a035;
  a035=(a086*a070);
  a035=(a040-a035);
  a038=(a131*a035);
  a032=(a088*a070);
  a063=(a063-a032);
  a032=(a120*a063);
  a038=(a038+a032);
  a082=(a027*a082);
  a082=(a009*a082);
  a032=(a054*a070);
  a032=(a082-a032);
  a017=(a121*a032);
  a038=(a038-a017);
  a017=(a134*a038);
  a073=(a093*a035);
  a066=(a109*a063);
  a073=(a073+a066);
  a066=(a110*a032);
  a073=(a073-a066);
  a066=(a022*a073);
  a017=(a017+a066);
  a035=(a124*a035);
  a063=(a100*a063);
  a035=(a035+a063);
  a032=(a102*a032);
  a035=(a035-a032);
  a032=(a084*a035);
  a017=(a017+a032);
  if (res[2]!=0) res[2][52]=a017;
  a017=(a061*a070);
  a017=(a075-a017);
  a032=(a120*a017);
  a063=(a003*a070);
  a082=(a082-a063);
  a063=(a131*a082);
  a032=(a032-a063);
  a070=(a072*a070);
  a070=(a070+a040);
  a063=(a121*a070);
  a032=(a032-a063);
  a063=(a161*a032);
  a066=(a109*a017);
  a069=(a093*a082);
  a066=(a066-a069);
  a069=(a110*a070);
  a066=(a066-a069);
  a069=(a155*a066);
  a063=(a063+a069);
  a017=(a100*a017);
  a082=(a124*a082);
  a017=(a017-a082);
  a070=(a102*a070);
  a017=(a017-a070);
  a070=(a139*a017);
  a063=(a063+a070);
  if (res[2]!=0) res[2][53]=a063;
  a063=(a099*a014);
  a070=(a101*a035);
  a063=(a063+a070);
  a063=(2.*a063);
  a063=(a004*a063);
  a070=(a090*a063);
  a082=(a117*a070);
  a069=(a099*a045);
  a125=(a101*a073);
  a069=(a069+a125);
  a069=(2.*a069);
  a069=(a004*a069);
  a125=(a141*a069);
  a082=(a082+a125);
  a125=(a090*a069);
  a122=(a094*a125);
  a082=(a082+a122);
  a122=(a099*a052);
  a113=(a101*a038);
  a122=(a122+a113);
  a122=(2.*a122);
  a122=(a004*a122);
  a113=(a005*a122);
  a082=(a082+a113);
  a113=(a090*a122);
  a053=(a135*a113);
  a082=(a082+a053);
  a053=(a143*a063);
  a082=(a082+a053);
  a082=(-a082);
  if (res[2]!=0) res[2][54]=a082;
  a082=(a115*a069);
  a053=(a097*a063);
  a001=(a117*a053);
  a082=(a082+a001);
  a001=(a097*a069);
  a049=(a094*a001);
  a082=(a082+a049);
  a049=(a111*a122);
  a082=(a082+a049);
  a049=(a097*a122);
  a095=(a135*a049);
  a082=(a082+a095);
  a095=(a103*a063);
  a082=(a082+a095);
  if (res[2]!=0) res[2][55]=a082;
  a070=(a103*a070);
  a053=(a143*a053);
  a070=(a070-a053);
  a001=(a141*a001);
  a070=(a070-a001);
  a125=(a115*a125);
  a070=(a070+a125);
  a049=(a005*a049);
  a070=(a070-a049);
  a113=(a111*a113);
  a070=(a070+a113);
  if (res[2]!=0) res[2][56]=a070;
  a067=(a067+a080);
  a067=(a027*a067);
  a078=(a078+a067);
  a078=(a078-a071);
  a035=(a116*a035);
  a071=(a099*a063);
  a067=(a148*a071);
  a035=(a035-a067);
  a045=(a015*a045);
  a067=(a101*a069);
  a080=(a155*a067);
  a045=(a045+a080);
  a035=(a035+a045);
  a073=(a158*a073);
  a069=(a099*a069);
  a045=(a156*a069);
  a073=(a073+a045);
  a035=(a035-a073);
  a052=(a130*a052);
  a073=(a101*a122);
  a045=(a161*a073);
  a052=(a052+a045);
  a035=(a035+a052);
  a038=(a016*a038);
  a122=(a099*a122);
  a052=(a162*a122);
  a038=(a038+a052);
  a035=(a035-a038);
  a014=(a126*a014);
  a063=(a101*a063);
  a038=(a139*a063);
  a014=(a014-a038);
  a035=(a035-a014);
  a078=(a078+a035);
  if (res[2]!=0) res[2][57]=a078;
  a078=(a126*a017);
  a063=(a084*a063);
  a078=(a078-a063);
  a063=(a015*a066);
  a067=(a022*a067);
  a063=(a063+a067);
  a067=(a130*a032);
  a073=(a134*a073);
  a067=(a067+a073);
  a063=(a063+a067);
  a078=(a078-a063);
  a083=(a083+a078);
  if (res[2]!=0) res[2][58]=a083;
  a085=(a085-a064);
  a085=(a027*a085);
  a056=(a056+a085);
  a056=(a051+a056);
  a066=(a158*a066);
  a069=(a022*a069);
  a066=(a066+a069);
  a017=(a116*a017);
  a071=(a084*a071);
  a017=(a017-a071);
  a066=(a066-a017);
  a032=(a016*a032);
  a122=(a134*a122);
  a032=(a032+a122);
  a066=(a066+a032);
  a056=(a056+a066);
  if (res[2]!=0) res[2][59]=a056;
  if (res[2]!=0) res[2][60]=a033;
  if (res[2]!=0) res[2][61]=a033;
  if (res[2]!=0) res[2][62]=a033;
  a140=(a140*a059);
  a065=(a065*a140);
  a065=(a057-a065);
  a056=(a121*a065);
  a079=(a079*a140);
  a079=(a079+a040);
  a066=(a131*a079);
  a027=(a027*a059);
  a009=(a009*a027);
  a144=(a144*a140);
  a144=(a009-a144);
  a027=(a120*a144);
  a066=(a066+a027);
  a056=(a056-a066);
  a066=(a162*a056);
  a027=(a110*a065);
  a059=(a093*a079);
  a032=(a109*a144);
  a059=(a059+a032);
  a027=(a027-a059);
  a059=(a156*a027);
  a066=(a066+a059);
  a065=(a102*a065);
  a079=(a124*a079);
  a144=(a100*a144);
  a079=(a079+a144);
  a065=(a065-a079);
  a079=(a148*a065);
  a066=(a066+a079);
  if (res[2]!=0) res[2][63]=a066;
  a086=(a086*a140);
  a086=(a075-a086);
  a066=(a131*a086);
  a088=(a088*a140);
  a057=(a057-a088);
  a088=(a120*a057);
  a066=(a066+a088);
  a054=(a054*a140);
  a088=(a121*a054);
  a066=(a066+a088);
  a088=(a134*a066);
  a079=(a093*a086);
  a144=(a109*a057);
  a079=(a079+a144);
  a144=(a110*a054);
  a079=(a079+a144);
  a144=(a022*a079);
  a088=(a088+a144);
  a086=(a124*a086);
  a057=(a100*a057);
  a086=(a086+a057);
  a054=(a102*a054);
  a086=(a086+a054);
  a054=(a084*a086);
  a088=(a088+a054);
  if (res[2]!=0) res[2][64]=a088;
  a061=(a061*a140);
  a040=(a040-a061);
  a061=(a120*a040);
  a003=(a003*a140);
  a009=(a009-a003);
  a003=(a131*a009);
  a061=(a061-a003);
  a072=(a072*a140);
  a075=(a075-a072);
  a072=(a121*a075);
  a061=(a061+a072);
  a072=(a161*a061);
  a140=(a109*a040);
  a003=(a093*a009);
  a140=(a140-a003);
  a003=(a110*a075);
  a140=(a140+a003);
  a003=(a155*a140);
  a072=(a072+a003);
  a040=(a100*a040);
  a009=(a124*a009);
  a040=(a040-a009);
  a075=(a102*a075);
  a040=(a040+a075);
  a075=(a139*a040);
  a072=(a072+a075);
  if (res[2]!=0) res[2][65]=a072;
  a072=(a099*a065);
  a075=(a101*a086);
  a072=(a072+a075);
  a072=(2.*a072);
  a072=(a004*a072);
  a075=(a090*a072);
  a009=(a117*a075);
  a003=(a099*a027);
  a088=(a101*a079);
  a003=(a003+a088);
  a003=(2.*a003);
  a003=(a004*a003);
  a088=(a141*a003);
  a009=(a009+a088);
  a088=(a090*a003);
  a054=(a094*a088);
  a009=(a009+a054);
  a054=(a099*a056);
  a057=(a101*a066);
  a054=(a054+a057);
  a054=(2.*a054);
  a054=(a004*a054);
  a057=(a005*a054);
  a009=(a009+a057);
  a057=(a090*a054);
  a144=(a135*a057);
  a009=(a009+a144);
  a144=(a143*a072);
  a009=(a009+a144);
  a009=(-a009);
  if (res[2]!=0) res[2][66]=a009;
  a009=(a115*a003);
  a144=(a097*a072);
  a059=(a117*a144);
  a009=(a009+a059);
  a059=(a097*a003);
  a032=(a094*a059);
  a009=(a009+a032);
  a032=(a111*a054);
  a009=(a009+a032);
  a032=(a097*a054);
  a122=(a135*a032);
  a009=(a009+a122);
  a122=(a103*a072);
  a009=(a009+a122);
  if (res[2]!=0) res[2][67]=a009;
  a075=(a103*a075);
  a144=(a143*a144);
  a075=(a075-a144);
  a059=(a141*a059);
  a075=(a075-a059);
  a088=(a115*a088);
  a075=(a075+a088);
  a032=(a005*a032);
  a075=(a075-a032);
  a057=(a111*a057);
  a075=(a075+a057);
  if (res[2]!=0) res[2][68]=a075;
  a087=(a087-a074);
  a087=(a060*a087);
  a077=(a077+a087);
  a076=(a076+a077);
  a086=(a116*a086);
  a077=(a099*a072);
  a087=(a148*a077);
  a086=(a086-a087);
  a027=(a015*a027);
  a087=(a101*a003);
  a074=(a155*a087);
  a027=(a027+a074);
  a086=(a086+a027);
  a079=(a158*a079);
  a003=(a099*a003);
  a027=(a156*a003);
  a079=(a079+a027);
  a086=(a086-a079);
  a056=(a130*a056);
  a079=(a101*a054);
  a027=(a161*a079);
  a056=(a056+a027);
  a086=(a086+a056);
  a066=(a016*a066);
  a054=(a099*a054);
  a056=(a162*a054);
  a066=(a066+a056);
  a086=(a086-a066);
  a065=(a126*a065);
  a072=(a101*a072);
  a066=(a139*a072);
  a065=(a065-a066);
  a086=(a086-a065);
  a076=(a076+a086);
  if (res[2]!=0) res[2][69]=a076;
  a064=(a064+a089);
  a060=(a060*a064);
  a058=(a058+a060);
  a058=(a058-a051);
  a051=(a126*a040);
  a072=(a084*a072);
  a051=(a051-a072);
  a072=(a015*a140);
  a087=(a022*a087);
  a072=(a072+a087);
  a087=(a130*a061);
  a079=(a134*a079);
  a087=(a087+a079);
  a072=(a072+a087);
  a051=(a051-a072);
  a058=(a058+a051);
  if (res[2]!=0) res[2][70]=a058;
  a140=(a158*a140);
  a003=(a022*a003);
  a140=(a140+a003);
  a040=(a116*a040);
  a077=(a084*a077);
  a040=(a040-a077);
  a140=(a140-a040);
  a061=(a016*a061);
  a054=(a134*a054);
  a061=(a061+a054);
  a140=(a140+a061);
  a081=(a081+a140);
  if (res[2]!=0) res[2][71]=a081;
  a081=(a127*a119);
  a140=(a123*a114);
  a081=(a081-a140);
  a140=(a135*a081);
  a061=(a127*a108);
  a054=(a123*a105);
  a061=(a061-a054);
  a054=(a094*a061);
  a140=(a140+a054);
  a054=(a127*a062);
  a040=(a123*a092);
  a054=(a054-a040);
  a040=(a117*a054);
  a140=(a140+a040);
  if (res[3]!=0) res[3][0]=a140;
  a140=(a133*a119);
  a040=(a096*a114);
  a140=(a140-a040);
  a040=(a111*a140);
  a077=(a133*a108);
  a003=(a096*a105);
  a077=(a077-a003);
  a003=(a115*a077);
  a040=(a040+a003);
  a003=(a133*a062);
  a058=(a096*a092);
  a003=(a003-a058);
  a058=(a103*a003);
  a040=(a040+a058);
  if (res[3]!=0) res[3][1]=a040;
  a040=(a024*a119);
  a058=(a011*a114);
  a040=(a040-a058);
  a058=(a005*a040);
  a051=(a024*a108);
  a072=(a011*a105);
  a051=(a051-a072);
  a072=(a141*a051);
  a058=(a058+a072);
  a072=(a024*a062);
  a087=(a011*a092);
  a072=(a072-a087);
  a087=(a143*a072);
  a058=(a058+a087);
  if (res[3]!=0) res[3][2]=a058;
  if (res[3]!=0) res[3][3]=a033;
  if (res[3]!=0) res[3][4]=a033;
  if (res[3]!=0) res[3][5]=a033;
  a058=(a150*a003);
  a087=(a090*a054);
  a079=(a097*a072);
  a087=(a087+a079);
  a087=(a087-a003);
  a087=(2.*a087);
  a087=(a004*a087);
  a079=(a090*a087);
  a060=(a117*a079);
  a058=(a058+a060);
  a060=(a154*a061);
  a064=(a090*a061);
  a089=(a097*a051);
  a064=(a064+a089);
  a064=(a064-a077);
  a064=(2.*a064);
  a064=(a004*a064);
  a089=(a141*a064);
  a060=(a060+a089);
  a058=(a058+a060);
  a060=(a157*a077);
  a089=(a090*a064);
  a076=(a094*a089);
  a060=(a060+a076);
  a058=(a058+a060);
  a060=(a159*a081);
  a076=(a090*a081);
  a086=(a097*a040);
  a076=(a076+a086);
  a076=(a076-a140);
  a076=(2.*a076);
  a076=(a004*a076);
  a086=(a005*a076);
  a060=(a060+a086);
  a058=(a058+a060);
  a060=(a163*a140);
  a086=(a090*a076);
  a065=(a135*a086);
  a060=(a060+a065);
  a058=(a058+a060);
  a060=(a028*a054);
  a065=(a143*a087);
  a060=(a060+a065);
  a058=(a058+a060);
  a058=(-a058);
  if (res[3]!=0) res[3][6]=a058;
  a058=(a154*a051);
  a060=(a115*a064);
  a058=(a058+a060);
  a003=(a129*a003);
  a060=(a097*a087);
  a065=(a117*a060);
  a003=(a003-a065);
  a058=(a058-a003);
  a077=(a020*a077);
  a003=(a097*a064);
  a065=(a094*a003);
  a077=(a077+a065);
  a058=(a058+a077);
  a077=(a159*a040);
  a065=(a111*a076);
  a077=(a077+a065);
  a058=(a058+a077);
  a140=(a112*a140);
  a077=(a097*a076);
  a065=(a135*a077);
  a140=(a140+a065);
  a058=(a058+a140);
  a140=(a028*a072);
  a065=(a103*a087);
  a140=(a140+a065);
  a058=(a058+a140);
  if (res[3]!=0) res[3][7]=a058;
  a054=(a129*a054);
  a060=(a143*a060);
  a054=(a054-a060);
  a072=(a150*a072);
  a079=(a103*a079);
  a072=(a072+a079);
  a054=(a054+a072);
  a061=(a020*a061);
  a003=(a141*a003);
  a061=(a061+a003);
  a054=(a054-a061);
  a051=(a157*a051);
  a089=(a115*a089);
  a051=(a051+a089);
  a054=(a054+a051);
  a081=(a112*a081);
  a077=(a005*a077);
  a081=(a081+a077);
  a054=(a054-a081);
  a040=(a163*a040);
  a086=(a111*a086);
  a040=(a040+a086);
  a054=(a054+a040);
  if (res[3]!=0) res[3][8]=a054;
  a054=(a101*a064);
  a040=(a155*a054);
  a086=(a099*a087);
  a081=(a148*a086);
  a040=(a040-a081);
  a064=(a099*a064);
  a081=(a156*a064);
  a040=(a040-a081);
  a081=(a101*a076);
  a077=(a161*a081);
  a040=(a040+a077);
  a076=(a099*a076);
  a077=(a162*a076);
  a040=(a040-a077);
  a087=(a101*a087);
  a077=(a139*a087);
  a040=(a040+a077);
  if (res[3]!=0) res[3][9]=a040;
  a087=(a084*a087);
  a054=(a022*a054);
  a081=(a134*a081);
  a054=(a054+a081);
  a087=(a087+a054);
  a087=(-a087);
  if (res[3]!=0) res[3][10]=a087;
  a064=(a022*a064);
  a086=(a084*a086);
  a064=(a064+a086);
  a076=(a134*a076);
  a064=(a064+a076);
  if (res[3]!=0) res[3][11]=a064;
  a064=(a123*a118);
  a076=(a132*a119);
  a064=(a064-a076);
  a076=(a135*a064);
  a086=(a123*a107);
  a087=(a132*a108);
  a086=(a086-a087);
  a087=(a094*a086);
  a076=(a076+a087);
  a123=(a123*a098);
  a087=(a132*a062);
  a123=(a123-a087);
  a087=(a117*a123);
  a076=(a076+a087);
  if (res[3]!=0) res[3][12]=a076;
  a076=(a096*a118);
  a087=(a106*a119);
  a076=(a076-a087);
  a087=(a111*a076);
  a054=(a096*a107);
  a081=(a106*a108);
  a054=(a054-a081);
  a081=(a115*a054);
  a087=(a087+a081);
  a096=(a096*a098);
  a081=(a106*a062);
  a096=(a096-a081);
  a081=(a103*a096);
  a087=(a087+a081);
  if (res[3]!=0) res[3][13]=a087;
  a087=(a011*a118);
  a119=(a043*a119);
  a087=(a087-a119);
  a119=(a005*a087);
  a081=(a011*a107);
  a108=(a043*a108);
  a081=(a081-a108);
  a108=(a141*a081);
  a119=(a119+a108);
  a011=(a011*a098);
  a062=(a043*a062);
  a011=(a011-a062);
  a062=(a143*a011);
  a119=(a119+a062);
  if (res[3]!=0) res[3][14]=a119;
  if (res[3]!=0) res[3][15]=a033;
  if (res[3]!=0) res[3][16]=a033;
  if (res[3]!=0) res[3][17]=a033;
  a119=(a150*a096);
  a062=(a090*a123);
  a108=(a097*a011);
  a062=(a062+a108);
  a062=(a062-a096);
  a062=(2.*a062);
  a062=(a004*a062);
  a108=(a090*a062);
  a040=(a117*a108);
  a119=(a119+a040);
  a040=(a154*a086);
  a077=(a090*a086);
  a051=(a097*a081);
  a077=(a077+a051);
  a077=(a077-a054);
  a077=(2.*a077);
  a077=(a004*a077);
  a051=(a141*a077);
  a040=(a040+a051);
  a119=(a119+a040);
  a040=(a157*a054);
  a051=(a090*a077);
  a089=(a094*a051);
  a040=(a040+a089);
  a119=(a119+a040);
  a040=(a159*a064);
  a089=(a090*a064);
  a061=(a097*a087);
  a089=(a089+a061);
  a089=(a089-a076);
  a089=(2.*a089);
  a089=(a004*a089);
  a061=(a005*a089);
  a040=(a040+a061);
  a119=(a119+a040);
  a040=(a163*a076);
  a061=(a090*a089);
  a003=(a135*a061);
  a040=(a040+a003);
  a119=(a119+a040);
  a040=(a028*a123);
  a003=(a143*a062);
  a040=(a040+a003);
  a119=(a119+a040);
  a119=(-a119);
  if (res[3]!=0) res[3][18]=a119;
  a119=(a154*a081);
  a040=(a115*a077);
  a119=(a119+a040);
  a096=(a129*a096);
  a040=(a097*a062);
  a003=(a117*a040);
  a096=(a096-a003);
  a119=(a119-a096);
  a054=(a020*a054);
  a096=(a097*a077);
  a003=(a094*a096);
  a054=(a054+a003);
  a119=(a119+a054);
  a054=(a159*a087);
  a003=(a111*a089);
  a054=(a054+a003);
  a119=(a119+a054);
  a076=(a112*a076);
  a054=(a097*a089);
  a003=(a135*a054);
  a076=(a076+a003);
  a119=(a119+a076);
  a076=(a028*a011);
  a003=(a103*a062);
  a076=(a076+a003);
  a119=(a119+a076);
  if (res[3]!=0) res[3][19]=a119;
  a123=(a129*a123);
  a040=(a143*a040);
  a123=(a123-a040);
  a011=(a150*a011);
  a108=(a103*a108);
  a011=(a011+a108);
  a123=(a123+a011);
  a086=(a020*a086);
  a096=(a141*a096);
  a086=(a086+a096);
  a123=(a123-a086);
  a081=(a157*a081);
  a051=(a115*a051);
  a081=(a081+a051);
  a123=(a123+a081);
  a064=(a112*a064);
  a054=(a005*a054);
  a064=(a064+a054);
  a123=(a123-a064);
  a087=(a163*a087);
  a061=(a111*a061);
  a087=(a087+a061);
  a123=(a123+a087);
  if (res[3]!=0) res[3][20]=a123;
  a123=(a101*a077);
  a087=(a155*a123);
  a061=(a099*a062);
  a064=(a148*a061);
  a087=(a087-a064);
  a077=(a099*a077);
  a064=(a156*a077);
  a087=(a087-a064);
  a064=(a101*a089);
  a054=(a161*a064);
  a087=(a087+a054);
  a089=(a099*a089);
  a054=(a162*a089);
  a087=(a087-a054);
  a062=(a101*a062);
  a054=(a139*a062);
  a087=(a087+a054);
  if (res[3]!=0) res[3][21]=a087;
  a062=(a084*a062);
  a123=(a022*a123);
  a064=(a134*a064);
  a123=(a123+a064);
  a062=(a062+a123);
  a062=(-a062);
  if (res[3]!=0) res[3][22]=a062;
  a077=(a022*a077);
  a061=(a084*a061);
  a077=(a077+a061);
  a089=(a134*a089);
  a077=(a077+a089);
  if (res[3]!=0) res[3][23]=a077;
  a077=(a132*a114);
  a089=(a127*a118);
  a077=(a077-a089);
  a089=(a135*a077);
  a061=(a132*a105);
  a062=(a127*a107);
  a061=(a061-a062);
  a062=(a094*a061);
  a089=(a089+a062);
  a132=(a132*a092);
  a127=(a127*a098);
  a132=(a132-a127);
  a127=(a117*a132);
  a089=(a089+a127);
  if (res[3]!=0) res[3][24]=a089;
  a089=(a106*a114);
  a127=(a133*a118);
  a089=(a089-a127);
  a127=(a111*a089);
  a062=(a106*a105);
  a123=(a133*a107);
  a062=(a062-a123);
  a123=(a115*a062);
  a127=(a127+a123);
  a106=(a106*a092);
  a133=(a133*a098);
  a106=(a106-a133);
  a133=(a103*a106);
  a127=(a127+a133);
  if (res[3]!=0) res[3][25]=a127;
  a114=(a043*a114);
  a118=(a024*a118);
  a114=(a114-a118);
  a118=(a005*a114);
  a105=(a043*a105);
  a107=(a024*a107);
  a105=(a105-a107);
  a107=(a141*a105);
  a118=(a118+a107);
  a043=(a043*a092);
  a024=(a024*a098);
  a043=(a043-a024);
  a024=(a143*a043);
  a118=(a118+a024);
  if (res[3]!=0) res[3][26]=a118;
  if (res[3]!=0) res[3][27]=a033;
  if (res[3]!=0) res[3][28]=a033;
  if (res[3]!=0) res[3][29]=a033;
  a118=(a150*a106);
  a024=(a090*a132);
  a098=(a097*a043);
  a024=(a024+a098);
  a024=(a024-a106);
  a024=(2.*a024);
  a024=(a004*a024);
  a098=(a090*a024);
  a092=(a117*a098);
  a118=(a118+a092);
  a092=(a154*a061);
  a107=(a090*a061);
  a127=(a097*a105);
  a107=(a107+a127);
  a107=(a107-a062);
  a107=(2.*a107);
  a107=(a004*a107);
  a127=(a141*a107);
  a092=(a092+a127);
  a118=(a118+a092);
  a092=(a157*a062);
  a127=(a090*a107);
  a133=(a094*a127);
  a092=(a092+a133);
  a118=(a118+a092);
  a092=(a159*a077);
  a133=(a090*a077);
  a123=(a097*a114);
  a133=(a133+a123);
  a133=(a133-a089);
  a133=(2.*a133);
  a133=(a004*a133);
  a123=(a005*a133);
  a092=(a092+a123);
  a118=(a118+a092);
  a092=(a163*a089);
  a123=(a090*a133);
  a064=(a135*a123);
  a092=(a092+a064);
  a118=(a118+a092);
  a092=(a028*a132);
  a064=(a143*a024);
  a092=(a092+a064);
  a118=(a118+a092);
  a118=(-a118);
  if (res[3]!=0) res[3][30]=a118;
  a154=(a154*a105);
  a118=(a115*a107);
  a154=(a154+a118);
  a106=(a129*a106);
  a118=(a097*a024);
  a092=(a117*a118);
  a106=(a106-a092);
  a154=(a154-a106);
  a062=(a020*a062);
  a106=(a097*a107);
  a092=(a094*a106);
  a062=(a062+a092);
  a154=(a154+a062);
  a159=(a159*a114);
  a062=(a111*a133);
  a159=(a159+a062);
  a154=(a154+a159);
  a089=(a112*a089);
  a159=(a097*a133);
  a062=(a135*a159);
  a089=(a089+a062);
  a154=(a154+a089);
  a028=(a028*a043);
  a089=(a103*a024);
  a028=(a028+a089);
  a154=(a154+a028);
  if (res[3]!=0) res[3][31]=a154;
  a129=(a129*a132);
  a118=(a143*a118);
  a129=(a129-a118);
  a150=(a150*a043);
  a098=(a103*a098);
  a150=(a150+a098);
  a129=(a129+a150);
  a020=(a020*a061);
  a106=(a141*a106);
  a020=(a020+a106);
  a129=(a129-a020);
  a157=(a157*a105);
  a127=(a115*a127);
  a157=(a157+a127);
  a129=(a129+a157);
  a112=(a112*a077);
  a159=(a005*a159);
  a112=(a112+a159);
  a129=(a129-a112);
  a163=(a163*a114);
  a123=(a111*a123);
  a163=(a163+a123);
  a129=(a129+a163);
  if (res[3]!=0) res[3][32]=a129;
  a129=(a101*a107);
  a163=(a155*a129);
  a123=(a099*a024);
  a114=(a148*a123);
  a163=(a163-a114);
  a107=(a099*a107);
  a114=(a156*a107);
  a163=(a163-a114);
  a114=(a101*a133);
  a112=(a161*a114);
  a163=(a163+a112);
  a133=(a099*a133);
  a112=(a162*a133);
  a163=(a163-a112);
  a024=(a101*a024);
  a112=(a139*a024);
  a163=(a163+a112);
  if (res[3]!=0) res[3][33]=a163;
  a024=(a084*a024);
  a129=(a022*a129);
  a114=(a134*a114);
  a129=(a129+a114);
  a024=(a024+a129);
  a024=(-a024);
  if (res[3]!=0) res[3][34]=a024;
  a107=(a022*a107);
  a123=(a084*a123);
  a107=(a107+a123);
  a133=(a134*a133);
  a107=(a107+a133);
  if (res[3]!=0) res[3][35]=a107;
  if (res[3]!=0) res[3][36]=a033;
  if (res[3]!=0) res[3][37]=a033;
  if (res[3]!=0) res[3][38]=a033;
  a107=(a145*a121);
  a133=(a146*a120);
  a107=(a107-a133);
  a133=(a162*a107);
  a123=(a145*a110);
  a024=(a146*a109);
  a123=(a123-a024);
  a024=(a156*a123);
  a133=(a133+a024);
  a024=(a145*a102);
  a129=(a146*a100);
  a024=(a024-a129);
  a129=(a148*a024);
  a133=(a133+a129);
  if (res[3]!=0) res[3][39]=a133;
  a133=(a050*a121);
  a129=(a149*a120);
  a133=(a133-a129);
  a129=(a134*a133);
  a114=(a050*a110);
  a163=(a149*a109);
  a114=(a114-a163);
  a163=(a022*a114);
  a129=(a129+a163);
  a163=(a050*a102);
  a112=(a149*a100);
  a163=(a163-a112);
  a112=(a084*a163);
  a129=(a129+a112);
  if (res[3]!=0) res[3][40]=a129;
  a129=(a068*a121);
  a112=(a055*a120);
  a129=(a129-a112);
  a112=(a161*a129);
  a159=(a068*a110);
  a077=(a055*a109);
  a159=(a159-a077);
  a077=(a155*a159);
  a112=(a112+a077);
  a077=(a068*a102);
  a157=(a055*a100);
  a077=(a077-a157);
  a157=(a139*a077);
  a112=(a112+a157);
  if (res[3]!=0) res[3][41]=a112;
  a112=(a099*a024);
  a157=(a101*a163);
  a112=(a112+a157);
  a112=(2.*a112);
  a112=(a004*a112);
  a157=(a090*a112);
  a127=(a117*a157);
  a105=(a099*a123);
  a020=(a101*a114);
  a105=(a105+a020);
  a105=(2.*a105);
  a105=(a004*a105);
  a020=(a141*a105);
  a127=(a127+a020);
  a020=(a090*a105);
  a106=(a094*a020);
  a127=(a127+a106);
  a106=(a099*a107);
  a061=(a101*a133);
  a106=(a106+a061);
  a106=(2.*a106);
  a106=(a004*a106);
  a061=(a005*a106);
  a127=(a127+a061);
  a061=(a090*a106);
  a150=(a135*a061);
  a127=(a127+a150);
  a150=(a143*a112);
  a127=(a127+a150);
  a127=(-a127);
  if (res[3]!=0) res[3][42]=a127;
  a127=(a115*a105);
  a150=(a097*a112);
  a098=(a117*a150);
  a127=(a127+a098);
  a098=(a097*a105);
  a043=(a094*a098);
  a127=(a127+a043);
  a043=(a111*a106);
  a127=(a127+a043);
  a043=(a097*a106);
  a118=(a135*a043);
  a127=(a127+a118);
  a118=(a103*a112);
  a127=(a127+a118);
  if (res[3]!=0) res[3][43]=a127;
  a157=(a103*a157);
  a150=(a143*a150);
  a157=(a157-a150);
  a098=(a141*a098);
  a157=(a157-a098);
  a020=(a115*a020);
  a157=(a157+a020);
  a043=(a005*a043);
  a157=(a157-a043);
  a061=(a111*a061);
  a157=(a157+a061);
  if (res[3]!=0) res[3][44]=a157;
  a163=(a116*a163);
  a157=(a099*a112);
  a061=(a148*a157);
  a163=(a163-a061);
  a123=(a015*a123);
  a061=(a101*a105);
  a043=(a155*a061);
  a123=(a123+a043);
  a163=(a163+a123);
  a114=(a158*a114);
  a105=(a099*a105);
  a123=(a156*a105);
  a114=(a114+a123);
  a163=(a163-a114);
  a107=(a130*a107);
  a114=(a101*a106);
  a123=(a161*a114);
  a107=(a107+a123);
  a163=(a163+a107);
  a133=(a016*a133);
  a106=(a099*a106);
  a107=(a162*a106);
  a133=(a133+a107);
  a163=(a163-a133);
  a024=(a126*a024);
  a112=(a101*a112);
  a133=(a139*a112);
  a024=(a024-a133);
  a163=(a163-a024);
  if (res[3]!=0) res[3][45]=a163;
  a163=(a126*a077);
  a112=(a084*a112);
  a163=(a163-a112);
  a112=(a015*a159);
  a061=(a022*a061);
  a112=(a112+a061);
  a061=(a130*a129);
  a114=(a134*a114);
  a061=(a061+a114);
  a112=(a112+a061);
  a163=(a163-a112);
  if (res[3]!=0) res[3][46]=a163;
  a159=(a158*a159);
  a105=(a022*a105);
  a159=(a159+a105);
  a077=(a116*a077);
  a157=(a084*a157);
  a077=(a077-a157);
  a159=(a159-a077);
  a129=(a016*a129);
  a106=(a134*a106);
  a129=(a129+a106);
  a159=(a159+a129);
  if (res[3]!=0) res[3][47]=a159;
  if (res[3]!=0) res[3][48]=a033;
  if (res[3]!=0) res[3][49]=a033;
  if (res[3]!=0) res[3][50]=a033;
  a159=(a146*a131);
  a129=(a137*a121);
  a159=(a159-a129);
  a129=(a162*a159);
  a106=(a146*a093);
  a077=(a137*a110);
  a106=(a106-a077);
  a077=(a156*a106);
  a129=(a129+a077);
  a146=(a146*a124);
  a077=(a137*a102);
  a146=(a146-a077);
  a077=(a148*a146);
  a129=(a129+a077);
  if (res[3]!=0) res[3][51]=a129;
  a129=(a149*a131);
  a077=(a147*a121);
  a129=(a129-a077);
  a077=(a134*a129);
  a157=(a149*a093);
  a105=(a147*a110);
  a157=(a157-a105);
  a105=(a022*a157);
  a077=(a077+a105);
  a149=(a149*a124);
  a105=(a147*a102);
  a149=(a149-a105);
  a105=(a084*a149);
  a077=(a077+a105);
  if (res[3]!=0) res[3][52]=a077;
  a077=(a055*a131);
  a121=(a007*a121);
  a077=(a077-a121);
  a121=(a161*a077);
  a105=(a055*a093);
  a110=(a007*a110);
  a105=(a105-a110);
  a110=(a155*a105);
  a121=(a121+a110);
  a055=(a055*a124);
  a102=(a007*a102);
  a055=(a055-a102);
  a102=(a139*a055);
  a121=(a121+a102);
  if (res[3]!=0) res[3][53]=a121;
  a121=(a099*a146);
  a102=(a101*a149);
  a121=(a121+a102);
  a121=(2.*a121);
  a121=(a004*a121);
  a102=(a090*a121);
  a110=(a117*a102);
  a163=(a099*a106);
  a112=(a101*a157);
  a163=(a163+a112);
  a163=(2.*a163);
  a163=(a004*a163);
  a112=(a141*a163);
  a110=(a110+a112);
  a112=(a090*a163);
  a061=(a094*a112);
  a110=(a110+a061);
  a061=(a099*a159);
  a114=(a101*a129);
  a061=(a061+a114);
  a061=(2.*a061);
  a061=(a004*a061);
  a114=(a005*a061);
  a110=(a110+a114);
  a114=(a090*a061);
  a024=(a135*a114);
  a110=(a110+a024);
  a024=(a143*a121);
  a110=(a110+a024);
  a110=(-a110);
  if (res[3]!=0) res[3][54]=a110;
  a110=(a115*a163);
  a024=(a097*a121);
  a133=(a117*a024);
  a110=(a110+a133);
  a133=(a097*a163);
  a107=(a094*a133);
  a110=(a110+a107);
  a107=(a111*a061);
  a110=(a110+a107);
  a107=(a097*a061);
  a123=(a135*a107);
  a110=(a110+a123);
  a123=(a103*a121);
  a110=(a110+a123);
  if (res[3]!=0) res[3][55]=a110;
  a102=(a103*a102);
  a024=(a143*a024);
  a102=(a102-a024);
  a133=(a141*a133);
  a102=(a102-a133);
  a112=(a115*a112);
  a102=(a102+a112);
  a107=(a005*a107);
  a102=(a102-a107);
  a114=(a111*a114);
  a102=(a102+a114);
  if (res[3]!=0) res[3][56]=a102;
  a149=(a116*a149);
  a102=(a099*a121);
  a114=(a148*a102);
  a149=(a149-a114);
  a106=(a015*a106);
  a114=(a101*a163);
  a107=(a155*a114);
  a106=(a106+a107);
  a149=(a149+a106);
  a157=(a158*a157);
  a163=(a099*a163);
  a106=(a156*a163);
  a157=(a157+a106);
  a149=(a149-a157);
  a159=(a130*a159);
  a157=(a101*a061);
  a106=(a161*a157);
  a159=(a159+a106);
  a149=(a149+a159);
  a129=(a016*a129);
  a061=(a099*a061);
  a159=(a162*a061);
  a129=(a129+a159);
  a149=(a149-a129);
  a146=(a126*a146);
  a121=(a101*a121);
  a129=(a139*a121);
  a146=(a146-a129);
  a149=(a149-a146);
  if (res[3]!=0) res[3][57]=a149;
  a149=(a126*a055);
  a121=(a084*a121);
  a149=(a149-a121);
  a121=(a015*a105);
  a114=(a022*a114);
  a121=(a121+a114);
  a114=(a130*a077);
  a157=(a134*a157);
  a114=(a114+a157);
  a121=(a121+a114);
  a149=(a149-a121);
  if (res[3]!=0) res[3][58]=a149;
  a105=(a158*a105);
  a163=(a022*a163);
  a105=(a105+a163);
  a055=(a116*a055);
  a102=(a084*a102);
  a055=(a055-a102);
  a105=(a105-a055);
  a077=(a016*a077);
  a061=(a134*a061);
  a077=(a077+a061);
  a105=(a105+a077);
  if (res[3]!=0) res[3][59]=a105;
  if (res[3]!=0) res[3][60]=a033;
  if (res[3]!=0) res[3][61]=a033;
  if (res[3]!=0) res[3][62]=a033;
  a105=(a137*a120);
  a077=(a145*a131);
  a105=(a105-a077);
  a077=(a162*a105);
  a061=(a137*a109);
  a055=(a145*a093);
  a061=(a061-a055);
  a055=(a156*a061);
  a077=(a077+a055);
  a137=(a137*a100);
  a145=(a145*a124);
  a137=(a137-a145);
  a145=(a148*a137);
  a077=(a077+a145);
  if (res[3]!=0) res[3][63]=a077;
  a077=(a147*a120);
  a145=(a050*a131);
  a077=(a077-a145);
  a145=(a134*a077);
  a055=(a147*a109);
  a102=(a050*a093);
  a055=(a055-a102);
  a102=(a022*a055);
  a145=(a145+a102);
  a147=(a147*a100);
  a050=(a050*a124);
  a147=(a147-a050);
  a050=(a084*a147);
  a145=(a145+a050);
  if (res[3]!=0) res[3][64]=a145;
  a120=(a007*a120);
  a131=(a068*a131);
  a120=(a120-a131);
  a131=(a161*a120);
  a109=(a007*a109);
  a093=(a068*a093);
  a109=(a109-a093);
  a093=(a155*a109);
  a131=(a131+a093);
  a007=(a007*a100);
  a068=(a068*a124);
  a007=(a007-a068);
  a068=(a139*a007);
  a131=(a131+a068);
  if (res[3]!=0) res[3][65]=a131;
  a131=(a099*a137);
  a068=(a101*a147);
  a131=(a131+a068);
  a131=(2.*a131);
  a131=(a004*a131);
  a068=(a090*a131);
  a124=(a117*a068);
  a100=(a099*a061);
  a093=(a101*a055);
  a100=(a100+a093);
  a100=(2.*a100);
  a100=(a004*a100);
  a093=(a141*a100);
  a124=(a124+a093);
  a093=(a090*a100);
  a145=(a094*a093);
  a124=(a124+a145);
  a145=(a099*a105);
  a050=(a101*a077);
  a145=(a145+a050);
  a145=(2.*a145);
  a004=(a004*a145);
  a145=(a005*a004);
  a124=(a124+a145);
  a090=(a090*a004);
  a145=(a135*a090);
  a124=(a124+a145);
  a145=(a143*a131);
  a124=(a124+a145);
  a124=(-a124);
  if (res[3]!=0) res[3][66]=a124;
  a124=(a115*a100);
  a145=(a097*a131);
  a117=(a117*a145);
  a124=(a124+a117);
  a117=(a097*a100);
  a094=(a094*a117);
  a124=(a124+a094);
  a094=(a111*a004);
  a124=(a124+a094);
  a097=(a097*a004);
  a135=(a135*a097);
  a124=(a124+a135);
  a135=(a103*a131);
  a124=(a124+a135);
  if (res[3]!=0) res[3][67]=a124;
  a103=(a103*a068);
  a143=(a143*a145);
  a103=(a103-a143);
  a141=(a141*a117);
  a103=(a103-a141);
  a115=(a115*a093);
  a103=(a103+a115);
  a005=(a005*a097);
  a103=(a103-a005);
  a111=(a111*a090);
  a103=(a103+a111);
  if (res[3]!=0) res[3][68]=a103;
  a147=(a116*a147);
  a103=(a099*a131);
  a148=(a148*a103);
  a147=(a147-a148);
  a061=(a015*a061);
  a148=(a101*a100);
  a155=(a155*a148);
  a061=(a061+a155);
  a147=(a147+a061);
  a055=(a158*a055);
  a100=(a099*a100);
  a156=(a156*a100);
  a055=(a055+a156);
  a147=(a147-a055);
  a105=(a130*a105);
  a055=(a101*a004);
  a161=(a161*a055);
  a105=(a105+a161);
  a147=(a147+a105);
  a077=(a016*a077);
  a099=(a099*a004);
  a162=(a162*a099);
  a077=(a077+a162);
  a147=(a147-a077);
  a137=(a126*a137);
  a101=(a101*a131);
  a139=(a139*a101);
  a137=(a137-a139);
  a147=(a147-a137);
  if (res[3]!=0) res[3][69]=a147;
  a126=(a126*a007);
  a101=(a084*a101);
  a126=(a126-a101);
  a015=(a015*a109);
  a148=(a022*a148);
  a015=(a015+a148);
  a130=(a130*a120);
  a055=(a134*a055);
  a130=(a130+a055);
  a015=(a015+a130);
  a126=(a126-a015);
  if (res[3]!=0) res[3][70]=a126;
  a158=(a158*a109);
  a022=(a022*a100);
  a158=(a158+a022);
  a116=(a116*a007);
  a084=(a084*a103);
  a116=(a116-a084);
  a158=(a158-a116);
  a016=(a016*a120);
  a134=(a134*a099);
  a016=(a016+a134);
  a158=(a158+a016);
  if (res[3]!=0) res[3][71]=a158;
  if (res[3]!=0) res[3][72]=a033;
  if (res[3]!=0) res[3][73]=a033;
  if (res[3]!=0) res[3][74]=a033;
  if (res[3]!=0) res[3][75]=a033;
  if (res[3]!=0) res[3][76]=a033;
  if (res[3]!=0) res[3][77]=a033;
  if (res[3]!=0) res[3][78]=a033;
  if (res[3]!=0) res[3][79]=a033;
  if (res[3]!=0) res[3][80]=a033;
  if (res[3]!=0) res[3][81]=a033;
  if (res[3]!=0) res[3][82]=a033;
  if (res[3]!=0) res[3][83]=a033;
  if (res[3]!=0) res[3][84]=a033;
  if (res[3]!=0) res[3][85]=a033;
  if (res[3]!=0) res[3][86]=a033;
  if (res[3]!=0) res[3][87]=a033;
  if (res[3]!=0) res[3][88]=a033;
  if (res[3]!=0) res[3][89]=a033;
  if (res[3]!=0) res[3][90]=a033;
  if (res[3]!=0) res[3][91]=a033;
  if (res[3]!=0) res[3][92]=a033;
  if (res[3]!=0) res[3][93]=a033;
  if (res[3]!=0) res[3][94]=a033;
  if (res[3]!=0) res[3][95]=a033;
  if (res[3]!=0) res[3][96]=a033;
  if (res[3]!=0) res[3][97]=a033;
  if (res[3]!=0) res[3][98]=a033;
  if (res[3]!=0) res[3][99]=a033;
  if (res[3]!=0) res[3][100]=a033;
  if (res[3]!=0) res[3][101]=a033;
  if (res[3]!=0) res[3][102]=a033;
  if (res[3]!=0) res[3][103]=a033;
  if (res[3]!=0) res[3][104]=a033;
  if (res[3]!=0) res[3][105]=a033;
  if (res[3]!=0) res[3][106]=a033;
  if (res[3]!=0) res[3][107]=a033;
  if (res[3]!=0) res[3][108]=a033;
  if (res[3]!=0) res[3][109]=a033;
  if (res[3]!=0) res[3][110]=a033;
  if (res[3]!=0) res[3][111]=a033;
  if (res[3]!=0) res[3][112]=a033;
  if (res[3]!=0) res[3][113]=a033;
  if (res[3]!=0) res[3][114]=a033;
  if (res[3]!=0) res[3][115]=a033;
  if (res[3]!=0) res[3][116]=a033;
  if (res[3]!=0) res[3][117]=a033;
  if (res[3]!=0) res[3][118]=a033;
  if (res[3]!=0) res[3][119]=a033;
  if (res[3]!=0) res[3][120]=a033;
  if (res[3]!=0) res[3][121]=a033;
  if (res[3]!=0) res[3][122]=a033;
  if (res[3]!=0) res[3][123]=a033;
  if (res[3]!=0) res[3][124]=a033;
  if (res[3]!=0) res[3][125]=a033;
  if (res[3]!=0) res[3][126]=a033;
  if (res[3]!=0) res[3][127]=a033;
  if (res[3]!=0) res[3][128]=a033;
  if (res[3]!=0) res[3][129]=a033;
  if (res[3]!=0) res[3][130]=a033;
  if (res[3]!=0) res[3][131]=a033;
  if (res[3]!=0) res[3][132]=a033;
  if (res[3]!=0) res[3][133]=a033;
  if (res[3]!=0) res[3][134]=a033;
  if (res[3]!=0) res[3][135]=a033;
  if (res[3]!=0) res[3][136]=a033;
  if (res[3]!=0) res[3][137]=a033;
  if (res[3]!=0) res[3][138]=a033;
  if (res[3]!=0) res[3][139]=a033;
  if (res[3]!=0) res[3][140]=a033;
  if (res[3]!=0) res[3][141]=a033;
  if (res[3]!=0) res[3][142]=a033;
  if (res[3]!=0) res[3][143]=a033;
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

CASADI_SYMBOL_EXPORT casadi_int step_partials_n_out(void) { return 4;}

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
    case 0: return "J";
    case 1: return "Fs";
    case 2: return "Yz";
    case 3: return "Ys";
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
    case 0: return casadi_s1;
    case 1: return casadi_s4;
    case 2: return casadi_s4;
    case 3: return casadi_s5;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int step_partials_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 4;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int step_partials_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 4*sizeof(casadi_real*);
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

#define HPGEN_ABI 3
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
#define HPGEN_THETA_MAX 0.05
/* simplified Newton stops when its error estimate is below this * tol * (1 + |z|) */
#define HPGEN_SIMPLIFIED_TOL 0.01

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
    long long predictor;         /* 1: start step k+1 from the extrapolated last solutions (else z_k) */
} hpgen_options;

/* A run in progress: the state, the Newton start and the Newton memory. Advancing a run by
   n1 steps and then by n2 steps gives bitwise the same result as by n1 + n2 steps. */
typedef struct hpgen_run {
    double g[HPGEN_NN], p[HPGEN_D];  /* (g_k, p_k) */
    double z[HPGEN_NZ];              /* solution of the last step (or the initial guess) */
    double zprev[HPGEN_NZ];          /* solutions of the two steps before (predictor) */
    double zprev2[HPGEN_NZ];
    double lu[HPGEN_NZ * HPGEN_NZ];  /* J^{-1} of the last Jacobian (simplified Newton) */
    int piv[HPGEN_NZ];
    long long k;                     /* steps done */
    long long have_prev;             /* how many of zprev, zprev2 are valid (0, 1, 2) */
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
static int hpgen_k_step_partials(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1, double* out2, double* out3);

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

/* step_partials(z[6], g[36], p[6], h[1]) -> (J[36], Fs[72], Yz[72], Ys[144]) */
#define HPGEN_STEP_PARTIALS_SZ_ARG 4
#define HPGEN_STEP_PARTIALS_SZ_RES 4
#define HPGEN_STEP_PARTIALS_SZ_IW 0
#define HPGEN_STEP_PARTIALS_SZ_W 168
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_step_partials exports it */
static int hpgen_k_step_partials(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1, double* out2, double* out3) {
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
    res[3] = out3;
    flag = step_partials(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_step_partials(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1, double* out2, double* out3) {
    return hpgen_k_step_partials(in0, in1, in2, in3, out0, out1, out2, out3);
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

/* every x_i finite: the sum of the entries is finite iff every entry is (unless it
   overflows), one test instead of one branch per entry on the common path */
static int hpgen_all_finite(const double* x, int n) {
    double s = 0.0;
    int i;
    for (i = 0; i < n; ++i) s += x[i];
    if (s - s == 0.0) return 1;
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
   times cond(J) here. A <- J^{-1} and b <- J^{-1} b (the adjugate applied to b alongside
   the division). Returns 1 if det J is zero or not finite (then so is some entry of J:
   every entry enters det). */
static int hpgen_lu_factor_solve(double* A, int* piv, double* b, int keep) {
#if HPGEN_NZ == 1
    double r;
    if (!(A[0] != 0.0) || !isfinite(A[0])) return 1;
    r = 1.0 / A[0];
    A[0] = r;
    b[0] *= r;
#elif HPGEN_NZ == 2
    const double a = A[0], c = A[1], bb = A[2], d = A[3], det = a * d - bb * c;
    const double x0 = d * b[0] - bb * b[1], x1 = a * b[1] - c * b[0];
    double r;
    if (!(det != 0.0) || !isfinite(det)) return 1;
    r = 1.0 / det;
    A[0] = d * r; A[2] = -bb * r; A[1] = -c * r; A[3] = a * r;
    b[0] = x0 * r; b[1] = x1 * r;
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
    A[0] = c00 * r; A[1] = c01 * r; A[2] = c02 * r;
    A[3] = c10 * r; A[4] = c11 * r; A[5] = c12 * r;
    A[6] = c20 * r; A[7] = c21 * r; A[8] = c22 * r;
#endif
    (void)piv; (void)keep;
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
            /* linear convergence: the error left is about theta/(1 - theta) dn; ask it to be
               <= HPGEN_SIMPLIFIED_TOL tol, the round-off level full Newton reaches */
            double th = dn / dprev;
            if (dn <= HPGEN_SIMPLIFIED_TOL * o->tol * (1.0 + zn)) return HPGEN_OK;
            if (it > 1 && th < 1.0 && th / (1.0 - th) * dn <= HPGEN_SIMPLIFIED_TOL * o->tol * (1.0 + zn))
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
    code = hpgen_newton(g, p, hv, z, o, lu, piv, lu_valid, iters, jacs, rnorm);
    if (code != HPGEN_OK) {
        *lu_valid = 0;
        /* a failure at an iterate outside tau's domain is reported as a domain error */
        if (!hpgen_k_margin(z, hv, m) && m[0] <= 0.0) return HPGEN_DOMAIN;
        return code;
    }
    if (hpgen_k_margin(z, hv, m)) return HPGEN_NONFINITE;
    if (!(m[0] > 0.0)) return HPGEN_DOMAIN;
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

/* One step of run r with hv = {h}: the Newton start from the predictor, the step, and on
   success the run moved to (g_{k+1}, p_{k+1}) (with_g = 0: p_{k+1} only); o for the steps
   after the first, full (o with full Newton) for the first. Updates the counters of st;
   returns the status code. */
static int hpgen_run_step(hpgen_run* r, const double* hv, const hpgen_options* o,
                          const hpgen_options* full, hpgen_status* st, int with_g) {
    double g1[HPGEN_NN], p1[HPGEN_D], zs[HPGEN_NZ], res;
    long long it;
    int i, code;
    /* start: the polynomial through the last solutions, extrapolated one step (quadratic
       3 z_k - 3 z_{k-1} + z_{k-2} once three exist, linear 2 z_k - z_{k-1} before) */
    if (o->predictor && r->have_prev >= 2)
        for (i = 0; i < HPGEN_NZ; ++i) zs[i] = 3.0 * (r->z[i] - r->zprev[i]) + r->zprev2[i];
    else if (o->predictor && r->have_prev == 1)
        for (i = 0; i < HPGEN_NZ; ++i) zs[i] = 2.0 * r->z[i] - r->zprev[i];
    else
        for (i = 0; i < HPGEN_NZ; ++i) zs[i] = r->z[i];
    /* the first step starts from the crude guess kernel: full Newton */
    code = hpgen_step_core(r->g, r->p, hv, zs, r->k == 0 ? full : o, r->lu, r->piv,
                           &r->lu_valid, g1, p1, &it, &st->jacobians, &res, r->k == 0, with_g);
    st->iterations = it;
    st->total_iterations += it;
    st->residual = res;
    if (code != HPGEN_OK) { st->code = code; st->step = r->k; return code; }
    memcpy(r->zprev2, r->zprev, sizeof r->z);
    memcpy(r->zprev, r->z, sizeof r->z);
    memcpy(r->z, zs, sizeof r->z);
    if (r->have_prev < 2) r->have_prev += 1;
    if (with_g) memcpy(r->g, g1, sizeof g1);
    memcpy(r->p, p1, sizeof p1);
    r->k += 1;
    return HPGEN_OK;
}

/* Advance a run by `steps` steps of size h (warm-started: each Newton starts from the previous
   solution, or from the extrapolation of the last three). The state after global step k is
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
   k > 0 from the predictor of hpgen_run_step (o->predictor) with o's Newton, whose simplified
   iterations use J^{-1} of the previous step's converged z; dev[k] = max |update(z_k) -
   record k+1| (the caller checks that the records are this module's steps). At the
   converged z_k: (J, Fs, Yz, Ys) = step_partials(z_k), J inverted once (and kept as the
   next step's Newton matrix), A_k = Ys - Yz J^{-1} Fs, 2D x 2D column-major
   at A + k 4 D^2. Returns the steps done (K, or the failing step with st->code set). */
HPGEN_EXPORT long long hpgen_linearize(long long K, const double* g_rec, const double* p_rec,
                                       double h, double* z, const hpgen_options* o,
                                       double* A, double* dev, hpgen_status* st) {
    enum { S = 2 * HPGEN_D };
    double hv[1], g1[HPGEN_NN], p1[HPGEN_D], J[HPGEN_NZ * HPGEN_NZ], Fs[HPGEN_NZ * S],
        Yz[S * HPGEN_NZ], Ys[S * S], zlast[HPGEN_NZ], zprev[HPGEN_NZ], zprev2[HPGEN_NZ], res;
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
        /* the start: the extrapolation of hpgen_run_step through z_{k-1}, z_{k-2}, z_{k-3} */
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
        if (hpgen_k_step_partials(z, g, p, hv, J, Fs, Yz, Ys)
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
