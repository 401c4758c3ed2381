/*
 * hpgen generated module turntable_stormer_verlet_cay_truncated -- do not edit, regenerate with hpgen
 * model: turntable
 * options: tableau=stormer-verlet, tau=cay, rkmk=truncated
 * hpgen version: 0.1.0
 * content hash: 05de9e8f33b5ccf128e0cf5c52c38a2eadfd45e6027d470444395b130d93c442
 *
 * C backend: CasADi's generated kernels (symbols hidden) + dense LU, Newton, hpgen_step and
 * hpgen_simulate (exported). Conventions: all arrays are double, matrices column-major
 * (g[i + j*n]), h is a scalar at the API and a 1-vector for the kernels. No static mutable
 * state: every function is thread-safe; work arrays live on the stack, sized at codegen time.
 * Status codes: 0 ok, 1 Newton did not converge, 2 non-finite value (or singular Jacobian),
 * 3 tau out of its domain (margin(z, h) <= 0 after convergence), -1 invalid argument.
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
  #define CASADI_PREFIX(ID) hpgen_turntable_stormer_verlet_cay_truncated__ ## ID
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
#define casadi_s0 CASADI_PREFIX(s0)
#define casadi_s1 CASADI_PREFIX(s1)
#define casadi_s2 CASADI_PREFIX(s2)
#define casadi_s3 CASADI_PREFIX(s3)
#define casadi_s4 CASADI_PREFIX(s4)
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
  return fmax(x, y);
#endif
}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void hpgen_turntable_stormer_verlet_cay_truncated__casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int hpgen_turntable_stormer_verlet_cay_truncated__casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int hpgen_turntable_stormer_verlet_cay_truncated__casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {15, 1, 1};
static const casadi_int casadi_s1[3] = {9, 1, 1};
static const casadi_int casadi_s2[3] = {3, 1, 1};
static const casadi_int casadi_s3[3] = {1, 1, 1};
static const casadi_int casadi_s4[3] = {225, 1, 1};

/* residual:(z[15],g[9],p[3],h)->(F[15]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39;
  a00=arg[0]? arg[0][0] : 0;
  a01=5.0000000000000000e-01;
  a02=arg[1]? arg[1][2] : 0;
  a03=(a01*a02);
  a03=(a00+a03);
  a03=(2.*a03);
  a04=arg[3]? arg[3][0] : 0;
  a05=(a01*a04);
  a03=(a03*a05);
  a06=arg[0]? arg[0][12] : 0;
  a07=(a04*a06);
  a07=(a01*a07);
  a08=arg[0]? arg[0][9] : 0;
  a08=(a04*a08);
  a09=(a04*a08);
  a09=(a01*a09);
  a07=(a07+a09);
  a09=(a03-a07);
  a09=(a09/a05);
  if (res[0]!=0) res[0][0]=a09;
  a09=arg[0]? arg[0][1] : 0;
  a10=arg[1]? arg[1][5] : 0;
  a11=(a01*a10);
  a11=(a09+a11);
  a11=(2.*a11);
  a12=2.5000000000000000e-01;
  a12=(a12*a04);
  a11=(a11*a12);
  a13=arg[0]? arg[0][13] : 0;
  a14=(a04*a13);
  a14=(a01*a14);
  a15=arg[0]? arg[0][10] : 0;
  a15=(a04*a15);
  a16=(a04*a15);
  a16=(a01*a16);
  a14=(a14+a16);
  a16=(a11-a14);
  a16=(a16/a05);
  if (res[0]!=0) res[0][1]=a16;
  a16=arg[0]? arg[0][2] : 0;
  a17=arg[1]? arg[1][8] : 0;
  a18=(a01*a17);
  a18=(a16+a18);
  a18=(2.*a18);
  a19=1.6666666666666666e-01;
  a19=(a19*a04);
  a18=(a18*a19);
  a20=arg[0]? arg[0][14] : 0;
  a21=(a04*a20);
  a21=(a01*a21);
  a22=arg[0]? arg[0][11] : 0;
  a22=(a04*a22);
  a23=(a04*a22);
  a23=(a01*a23);
  a21=(a21+a23);
  a23=(a18-a21);
  a23=(a23/a05);
  if (res[0]!=0) res[0][2]=a23;
  a23=arg[0]? arg[0][3] : 0;
  a24=1.;
  a25=4.;
  a00=(a01*a00);
  a26=(a01*a23);
  a00=(a00+a26);
  a00=(a04*a00);
  a26=casadi_sq(a00);
  a09=(a01*a09);
  a27=arg[0]? arg[0][4] : 0;
  a28=(a01*a27);
  a09=(a09+a28);
  a09=(a04*a09);
  a28=casadi_sq(a09);
  a29=(a26+a28);
  a16=(a01*a16);
  a30=arg[0]? arg[0][5] : 0;
  a31=(a01*a30);
  a16=(a16+a31);
  a16=(a04*a16);
  a31=casadi_sq(a16);
  a29=(a29+a31);
  a29=(a25+a29);
  a29=(a25/a29);
  a32=(a31+a28);
  a33=2.;
  a32=(a32/a33);
  a32=(a29*a32);
  a32=(a24-a32);
  a32=(a02*a32);
  a34=(a00*a09);
  a35=(a34/a33);
  a35=(a16+a35);
  a35=(a29*a35);
  a35=(a10*a35);
  a32=(a32+a35);
  a35=(a00*a16);
  a36=(a35/a33);
  a36=(a36-a09);
  a36=(a29*a36);
  a36=(a17*a36);
  a32=(a32+a36);
  a36=(a01*a32);
  a23=(a23+a36);
  a23=(2.*a23);
  a23=(a23*a05);
  a07=(a23-a07);
  a07=(a07/a05);
  if (res[0]!=0) res[0][3]=a07;
  a07=(a09*a00);
  a36=(a07/a33);
  a36=(a36-a16);
  a36=(a29*a36);
  a36=(a02*a36);
  a37=(a31+a26);
  a37=(a37/a33);
  a37=(a29*a37);
  a37=(a24-a37);
  a37=(a10*a37);
  a36=(a36+a37);
  a37=(a09*a16);
  a38=(a37/a33);
  a38=(a00+a38);
  a38=(a29*a38);
  a38=(a17*a38);
  a36=(a36+a38);
  a38=(a01*a36);
  a27=(a27+a38);
  a27=(2.*a27);
  a27=(a27*a12);
  a14=(a27-a14);
  a14=(a14/a05);
  if (res[0]!=0) res[0][4]=a14;
  a14=(a16*a00);
  a12=(a14/a33);
  a12=(a09+a12);
  a12=(a29*a12);
  a12=(a02*a12);
  a38=(a16*a09);
  a39=(a38/a33);
  a39=(a39-a00);
  a39=(a29*a39);
  a39=(a10*a39);
  a12=(a12+a39);
  a39=(a28+a26);
  a39=(a39/a33);
  a29=(a29*a39);
  a29=(a24-a29);
  a29=(a17*a29);
  a12=(a12+a29);
  a29=(a01*a12);
  a30=(a30+a29);
  a30=(2.*a30);
  a30=(a30*a19);
  a21=(a30-a21);
  a21=(a21/a05);
  if (res[0]!=0) res[0][5]=a21;
  a21=arg[0]? arg[0][6] : 0;
  a21=(a04*a21);
  a05=-7.4999999999999997e-02;
  a05=(a05*a04);
  a18=(a01*a18);
  a18=(a05+a18);
  a19=(a10*a18);
  a19=(a21-a19);
  a29=2.9999999999999999e-02;
  a29=(a29*a04);
  a11=(a01*a11);
  a11=(a29+a11);
  a39=(a17*a11);
  a19=(a19+a39);
  a19=(a19/a04);
  if (res[0]!=0) res[0][6]=a19;
  a19=arg[0]? arg[0][7] : 0;
  a19=(a04*a19);
  a18=(a02*a18);
  a18=(a19+a18);
  a39=-4.4999999999999998e-02;
  a39=(a39*a04);
  a03=(a01*a03);
  a03=(a39+a03);
  a17=(a17*a03);
  a18=(a18-a17);
  a18=(a18/a04);
  if (res[0]!=0) res[0][7]=a18;
  a18=arg[0]? arg[0][8] : 0;
  a18=(a04*a18);
  a10=(a10*a03);
  a10=(a18+a10);
  a02=(a02*a11);
  a10=(a10-a02);
  a10=(a10/a04);
  if (res[0]!=0) res[0][8]=a10;
  a14=(a14/a25);
  a09=(a09/a33);
  a10=(a14-a09);
  a10=(a10*a22);
  a16=(a16/a33);
  a07=(a07/a25);
  a02=(a16+a07);
  a02=(a02*a15);
  a10=(a10+a02);
  a26=(a26/a25);
  a26=(a24+a26);
  a02=(a26*a08);
  a10=(a10+a02);
  a30=(a01*a30);
  a05=(a05+a30);
  a30=(a36*a05);
  a10=(a10-a30);
  a27=(a01*a27);
  a29=(a29+a27);
  a27=(a12*a29);
  a10=(a10+a27);
  a10=(a10/a04);
  if (res[0]!=0) res[0][9]=a10;
  a00=(a00/a33);
  a38=(a38/a25);
  a33=(a00+a38);
  a33=(a33*a22);
  a28=(a28/a25);
  a28=(a24+a28);
  a10=(a28*a15);
  a33=(a33+a10);
  a34=(a34/a25);
  a27=(a34-a16);
  a27=(a27*a08);
  a33=(a33+a27);
  a05=(a32*a05);
  a33=(a33+a05);
  a01=(a01*a23);
  a39=(a39+a01);
  a12=(a12*a39);
  a33=(a33-a12);
  a33=(a33/a04);
  if (res[0]!=0) res[0][10]=a33;
  a31=(a31/a25);
  a24=(a24+a31);
  a31=(a24*a22);
  a37=(a37/a25);
  a33=(a37-a00);
  a33=(a33*a15);
  a33=(a31+a33);
  a35=(a35/a25);
  a25=(a09+a35);
  a25=(a25*a08);
  a33=(a33+a25);
  a36=(a36*a39);
  a33=(a33+a36);
  a32=(a32*a29);
  a33=(a33-a32);
  a33=(a33/a04);
  if (res[0]!=0) res[0][11]=a33;
  a33=arg[2]? arg[2][0] : 0;
  a14=(a09+a14);
  a04=(a14*a20);
  a07=(a07-a16);
  a32=(a07*a13);
  a04=(a04+a32);
  a26=(a26*a06);
  a04=(a04+a26);
  a14=(a14*a22);
  a04=(a04+a14);
  a07=(a07*a15);
  a04=(a04+a07);
  a04=(a04+a02);
  a04=(a04+a21);
  a33=(a33-a04);
  if (res[0]!=0) res[0][12]=a33;
  a33=arg[2]? arg[2][1] : 0;
  a38=(a38-a00);
  a04=(a38*a20);
  a28=(a28*a13);
  a04=(a04+a28);
  a16=(a16+a34);
  a34=(a16*a06);
  a04=(a04+a34);
  a38=(a38*a22);
  a04=(a04+a38);
  a04=(a04+a10);
  a16=(a16*a08);
  a04=(a04+a16);
  a04=(a04+a19);
  a33=(a33-a04);
  if (res[0]!=0) res[0][13]=a33;
  a33=arg[2]? arg[2][2] : 0;
  a24=(a24*a20);
  a00=(a00+a37);
  a13=(a00*a13);
  a24=(a24+a13);
  a35=(a35-a09);
  a06=(a35*a06);
  a24=(a24+a06);
  a24=(a24+a31);
  a00=(a00*a15);
  a24=(a24+a00);
  a35=(a35*a08);
  a24=(a24+a35);
  a24=(a24+a18);
  a33=(a33-a24);
  if (res[0]!=0) res[0][14]=a33;
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
    case 2: return casadi_s2;
    case 3: return casadi_s3;
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

/* jacobian:(z[15],g[9],p[3],h)->(J[225]) */
static int casadi_f1(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73, a74, a75, a76, a77, a78, a79, a80, a81, a82, a83;
  casadi_real a84, a85, a86, a87;
  a00=2.;
  if (res[0]!=0) res[0][0]=a00;
  a01=0.;
  if (res[0]!=0) res[0][1]=a01;
  if (res[0]!=0) res[0][2]=a01;
  a02=arg[1]? arg[1][2] : 0;
  a03=arg[3]? arg[3][0] : 0;
  a04=5.0000000000000000e-01;
  a05=arg[0]? arg[0][2] : 0;
  a05=(a04*a05);
  a06=arg[0]? arg[0][5] : 0;
  a07=(a04*a06);
  a05=(a05+a07);
  a05=(a03*a05);
  a07=casadi_sq(a05);
  a08=arg[0]? arg[0][1] : 0;
  a08=(a04*a08);
  a09=arg[0]? arg[0][4] : 0;
  a10=(a04*a09);
  a08=(a08+a10);
  a08=(a03*a08);
  a10=casadi_sq(a08);
  a11=(a07+a10);
  a11=(a11/a00);
  a12=4.;
  a13=arg[0]? arg[0][0] : 0;
  a13=(a04*a13);
  a14=arg[0]? arg[0][3] : 0;
  a15=(a04*a14);
  a13=(a13+a15);
  a13=(a03*a13);
  a15=casadi_sq(a13);
  a16=(a15+a10);
  a16=(a16+a07);
  a16=(a12+a16);
  a17=(a12/a16);
  a16=(a17/a16);
  a18=(2.*a13);
  a19=(a04*a03);
  a18=(a18*a19);
  a20=(a16*a18);
  a21=(a11*a20);
  a21=(a02*a21);
  a22=arg[1]? arg[1][5] : 0;
  a23=(a08*a19);
  a24=(a04*a23);
  a24=(a17*a24);
  a25=(a13*a08);
  a26=(a25/a00);
  a26=(a05+a26);
  a27=(a26*a20);
  a27=(a24-a27);
  a27=(a22*a27);
  a21=(a21+a27);
  a27=arg[1]? arg[1][8] : 0;
  a28=(a05*a19);
  a29=(a04*a28);
  a29=(a17*a29);
  a30=(a13*a05);
  a31=(a30/a00);
  a31=(a31-a08);
  a32=(a31*a20);
  a32=(a29-a32);
  a32=(a27*a32);
  a21=(a21+a32);
  if (res[0]!=0) res[0][3]=a21;
  a32=2.5000000000000000e-01;
  a33=(a32*a03);
  a34=(a08*a13);
  a35=(a34/a00);
  a35=(a35-a05);
  a36=(a35*a20);
  a36=(a24-a36);
  a36=(a02*a36);
  a37=(a04*a18);
  a37=(a17*a37);
  a38=(a07+a15);
  a38=(a38/a00);
  a39=(a38*a20);
  a39=(a37-a39);
  a39=(a22*a39);
  a36=(a36-a39);
  a39=(a17*a19);
  a40=(a08*a05);
  a41=(a40/a00);
  a41=(a13+a41);
  a42=(a41*a20);
  a42=(a39-a42);
  a42=(a27*a42);
  a36=(a36+a42);
  a42=(a33*a36);
  a43=(a42/a19);
  if (res[0]!=0) res[0][4]=a43;
  a44=1.6666666666666666e-01;
  a44=(a44*a03);
  a45=(a05*a13);
  a46=(a45/a00);
  a46=(a08+a46);
  a47=(a46*a20);
  a47=(a29-a47);
  a47=(a02*a47);
  a48=(a05*a08);
  a49=(a48/a00);
  a49=(a49-a13);
  a50=(a49*a20);
  a50=(a50+a39);
  a50=(a22*a50);
  a47=(a47-a50);
  a50=(a10+a15);
  a50=(a50/a00);
  a20=(a50*a20);
  a37=(a37-a20);
  a37=(a27*a37);
  a47=(a47-a37);
  a37=(a44*a47);
  a20=(a37/a19);
  if (res[0]!=0) res[0][5]=a20;
  if (res[0]!=0) res[0][6]=a01;
  a51=(a27*a19);
  a51=(a51/a03);
  a51=(-a51);
  if (res[0]!=0) res[0][7]=a51;
  a51=(a22*a19);
  a51=(a51/a03);
  if (res[0]!=0) res[0][8]=a51;
  a51=arg[0]? arg[0][11] : 0;
  a51=(a03*a51);
  a28=(a32*a28);
  a52=(a51*a28);
  a53=arg[0]? arg[0][10] : 0;
  a53=(a03*a53);
  a23=(a32*a23);
  a54=(a53*a23);
  a55=(a52+a54);
  a56=arg[0]? arg[0][9] : 0;
  a56=(a03*a56);
  a18=(a32*a18);
  a57=(a56*a18);
  a55=(a55+a57);
  a58=-7.4999999999999997e-02;
  a58=(a58*a03);
  a59=(a17*a46);
  a59=(a02*a59);
  a60=(a17*a49);
  a60=(a22*a60);
  a59=(a59+a60);
  a60=1.;
  a61=(a17*a50);
  a61=(a60-a61);
  a61=(a27*a61);
  a59=(a59+a61);
  a61=(a04*a59);
  a06=(a06+a61);
  a06=(2.*a06);
  a06=(a06*a44);
  a06=(a04*a06);
  a58=(a58+a06);
  a06=(a58*a36);
  a61=(a17*a35);
  a61=(a02*a61);
  a62=(a17*a38);
  a62=(a60-a62);
  a62=(a22*a62);
  a61=(a61+a62);
  a62=(a17*a41);
  a62=(a27*a62);
  a61=(a61+a62);
  a37=(a04*a37);
  a62=(a61*a37);
  a06=(a06+a62);
  a55=(a55-a06);
  a06=2.9999999999999999e-02;
  a06=(a06*a03);
  a62=(a04*a61);
  a09=(a09+a62);
  a09=(2.*a09);
  a09=(a09*a33);
  a09=(a04*a09);
  a06=(a06+a09);
  a09=(a06*a47);
  a42=(a04*a42);
  a62=(a59*a42);
  a09=(a09+a62);
  a55=(a55+a09);
  a55=(a55/a03);
  if (res[0]!=0) res[0][9]=a55;
  a09=(a51*a33);
  a62=(a56*a23);
  a63=(a09+a62);
  a64=(a58*a21);
  a65=(a17*a11);
  a65=(a60-a65);
  a65=(a02*a65);
  a66=(a17*a26);
  a66=(a22*a66);
  a65=(a65+a66);
  a66=(a17*a31);
  a66=(a27*a66);
  a65=(a65+a66);
  a37=(a65*a37);
  a64=(a64+a37);
  a63=(a63+a64);
  a64=-4.4999999999999998e-02;
  a64=(a64*a03);
  a37=(a04*a65);
  a14=(a14+a37);
  a14=(2.*a14);
  a14=(a14*a19);
  a14=(a04*a14);
  a64=(a64+a14);
  a47=(a64*a47);
  a14=(a19*a21);
  a14=(a04*a14);
  a37=(a59*a14);
  a37=(a47+a37);
  a37=(a63-a37);
  a37=(a37/a03);
  if (res[0]!=0) res[0][10]=a37;
  a37=(a56*a28);
  a66=(a53*a33);
  a67=(a37-a66);
  a36=(a64*a36);
  a14=(a61*a14);
  a14=(a36+a14);
  a14=(a67+a14);
  a68=(a06*a21);
  a42=(a65*a42);
  a68=(a68+a42);
  a14=(a14-a68);
  a14=(a14/a03);
  if (res[0]!=0) res[0][11]=a14;
  a14=arg[0]? arg[0][14] : 0;
  a42=(a14*a28);
  a69=arg[0]? arg[0][13] : 0;
  a70=(a69*a23);
  a71=(a42+a70);
  a72=arg[0]? arg[0][12] : 0;
  a18=(a72*a18);
  a71=(a71+a18);
  a71=(a71+a52);
  a71=(a71+a54);
  a71=(a71+a57);
  a71=(-a71);
  if (res[0]!=0) res[0][12]=a71;
  a57=(a72*a23);
  a18=(a14*a33);
  a57=(a57-a18);
  a57=(a57-a09);
  a57=(a57+a62);
  a57=(-a57);
  if (res[0]!=0) res[0][13]=a57;
  a62=(a69*a33);
  a73=(a72*a28);
  a73=(a62+a73);
  a73=(a73+a66);
  a73=(a73+a37);
  a73=(-a73);
  if (res[0]!=0) res[0][14]=a73;
  if (res[0]!=0) res[0][15]=a01;
  if (res[0]!=0) res[0][16]=a60;
  if (res[0]!=0) res[0][17]=a01;
  a37=(a13*a19);
  a74=(a04*a37);
  a74=(a17*a74);
  a75=(2.*a08);
  a75=(a75*a19);
  a76=(a16*a75);
  a77=(a26*a76);
  a77=(a74-a77);
  a77=(a22*a77);
  a78=(a04*a75);
  a78=(a17*a78);
  a79=(a11*a76);
  a79=(a78-a79);
  a79=(a02*a79);
  a77=(a77-a79);
  a79=(a31*a76);
  a79=(a79+a39);
  a79=(a27*a79);
  a77=(a77-a79);
  if (res[0]!=0) res[0][18]=a77;
  a79=(a35*a76);
  a79=(a74-a79);
  a79=(a02*a79);
  a80=(a38*a76);
  a80=(a22*a80);
  a79=(a79+a80);
  a80=(a41*a76);
  a80=(a29-a80);
  a80=(a27*a80);
  a79=(a79+a80);
  a80=(a33*a79);
  a81=(a80/a19);
  if (res[0]!=0) res[0][19]=a81;
  a81=(a46*a76);
  a81=(a39-a81);
  a81=(a02*a81);
  a82=(a49*a76);
  a29=(a29-a82);
  a29=(a22*a29);
  a81=(a81+a29);
  a76=(a50*a76);
  a78=(a78-a76);
  a78=(a27*a78);
  a81=(a81-a78);
  a78=(a44*a81);
  a76=(a78/a19);
  if (res[0]!=0) res[0][20]=a76;
  a29=(a27*a33);
  a29=(a29/a03);
  if (res[0]!=0) res[0][21]=a29;
  if (res[0]!=0) res[0][22]=a01;
  a29=(a02*a33);
  a29=(a29/a03);
  a29=(-a29);
  if (res[0]!=0) res[0][23]=a29;
  a37=(a32*a37);
  a29=(a53*a37);
  a82=(a29-a09);
  a83=(a58*a79);
  a78=(a04*a78);
  a84=(a61*a78);
  a83=(a83+a84);
  a82=(a82-a83);
  a83=(a06*a81);
  a80=(a04*a80);
  a84=(a59*a80);
  a84=(a83+a84);
  a84=(a82+a84);
  a84=(a84/a03);
  if (res[0]!=0) res[0][24]=a84;
  a75=(a32*a75);
  a84=(a53*a75);
  a85=(a52+a84);
  a86=(a56*a37);
  a85=(a85+a86);
  a87=(a58*a77);
  a78=(a65*a78);
  a87=(a87+a78);
  a85=(a85+a87);
  a81=(a64*a81);
  a87=(a19*a77);
  a87=(a04*a87);
  a78=(a59*a87);
  a81=(a81+a78);
  a85=(a85-a81);
  a85=(a85/a03);
  if (res[0]!=0) res[0][25]=a85;
  a53=(a53*a28);
  a56=(a56*a33);
  a81=(a53+a56);
  a78=(a64*a79);
  a87=(a61*a87);
  a78=(a78+a87);
  a81=(a81+a78);
  a78=(a06*a77);
  a80=(a65*a80);
  a80=(a78+a80);
  a80=(a81-a80);
  a80=(a80/a03);
  if (res[0]!=0) res[0][26]=a80;
  a80=(a69*a37);
  a18=(a18+a80);
  a18=(a18+a09);
  a18=(a18+a29);
  a18=(-a18);
  if (res[0]!=0) res[0][27]=a18;
  a75=(a69*a75);
  a42=(a42+a75);
  a75=(a72*a37);
  a42=(a42+a75);
  a42=(a42+a52);
  a42=(a42+a84);
  a42=(a42+a86);
  a42=(-a42);
  if (res[0]!=0) res[0][28]=a42;
  a69=(a69*a28);
  a72=(a72*a33);
  a69=(a69-a72);
  a69=(a69+a53);
  a69=(a69-a56);
  a69=(-a69);
  if (res[0]!=0) res[0][29]=a69;
  if (res[0]!=0) res[0][30]=a01;
  if (res[0]!=0) res[0][31]=a01;
  a53=3.3333333333333331e-01;
  a53=(a53*a03);
  a53=(a53/a19);
  if (res[0]!=0) res[0][32]=a53;
  a53=(2.*a05);
  a53=(a53*a19);
  a16=(a16*a53);
  a26=(a26*a16);
  a26=(a39-a26);
  a26=(a22*a26);
  a28=(a04*a53);
  a17=(a17*a28);
  a11=(a11*a16);
  a11=(a17-a11);
  a11=(a02*a11);
  a26=(a26-a11);
  a31=(a31*a16);
  a31=(a74-a31);
  a31=(a27*a31);
  a26=(a26+a31);
  if (res[0]!=0) res[0][33]=a26;
  a41=(a41*a16);
  a41=(a24-a41);
  a41=(a27*a41);
  a35=(a35*a16);
  a35=(a35+a39);
  a35=(a02*a35);
  a38=(a38*a16);
  a17=(a17-a38);
  a17=(a22*a17);
  a35=(a35+a17);
  a41=(a41-a35);
  a35=(a33*a41);
  a17=(a35/a19);
  if (res[0]!=0) res[0][34]=a17;
  a46=(a46*a16);
  a74=(a74-a46);
  a74=(a02*a74);
  a49=(a49*a16);
  a24=(a24-a49);
  a24=(a22*a24);
  a74=(a74+a24);
  a50=(a50*a16);
  a27=(a27*a50);
  a74=(a74+a27);
  a27=(a44*a74);
  a50=(a27/a19);
  if (res[0]!=0) res[0][35]=a50;
  a22=(a22*a44);
  a22=(a22/a03);
  a22=(-a22);
  if (res[0]!=0) res[0][36]=a22;
  a02=(a02*a44);
  a02=(a02/a03);
  if (res[0]!=0) res[0][37]=a02;
  if (res[0]!=0) res[0][38]=a01;
  a02=(a51*a37);
  a22=(a02+a66);
  a50=(a58*a41);
  a27=(a04*a27);
  a16=(a61*a27);
  a16=(a50+a16);
  a16=(a22-a16);
  a24=(a06*a74);
  a35=(a04*a35);
  a49=(a59*a35);
  a24=(a24+a49);
  a16=(a16+a24);
  a16=(a16/a03);
  if (res[0]!=0) res[0][39]=a16;
  a16=(a51*a23);
  a49=(a16-a56);
  a58=(a58*a26);
  a27=(a65*a27);
  a27=(a58+a27);
  a27=(a49+a27);
  a46=(a64*a74);
  a38=(a19*a26);
  a38=(a04*a38);
  a39=(a59*a38);
  a46=(a46+a39);
  a27=(a27-a46);
  a27=(a27/a03);
  if (res[0]!=0) res[0][40]=a27;
  a32=(a32*a53);
  a51=(a51*a32);
  a53=(a51+a54);
  a53=(a53+a86);
  a64=(a64*a41);
  a38=(a61*a38);
  a64=(a64+a38);
  a53=(a53+a64);
  a06=(a06*a26);
  a35=(a65*a35);
  a06=(a06+a35);
  a53=(a53-a06);
  a53=(a53/a03);
  if (res[0]!=0) res[0][41]=a53;
  a37=(a14*a37);
  a37=(a37-a62);
  a37=(a37+a02);
  a37=(a37-a66);
  a37=(-a37);
  if (res[0]!=0) res[0][42]=a37;
  a23=(a14*a23);
  a23=(a23+a72);
  a23=(a23+a16);
  a23=(a23+a56);
  a23=(-a23);
  if (res[0]!=0) res[0][43]=a23;
  a14=(a14*a32);
  a14=(a14+a70);
  a14=(a14+a75);
  a14=(a14+a51);
  a14=(a14+a54);
  a14=(a14+a86);
  a14=(-a14);
  if (res[0]!=0) res[0][44]=a14;
  if (res[0]!=0) res[0][45]=a01;
  if (res[0]!=0) res[0][46]=a01;
  if (res[0]!=0) res[0][47]=a01;
  a21=(a04*a21);
  a21=(a60+a21);
  a21=(2.*a21);
  if (res[0]!=0) res[0][48]=a21;
  if (res[0]!=0) res[0][49]=a43;
  if (res[0]!=0) res[0][50]=a20;
  if (res[0]!=0) res[0][51]=a01;
  if (res[0]!=0) res[0][52]=a01;
  if (res[0]!=0) res[0][53]=a01;
  if (res[0]!=0) res[0][54]=a55;
  a21=(a19*a21);
  a21=(a04*a21);
  a55=(a59*a21);
  a47=(a47+a55);
  a63=(a63-a47);
  a63=(a63/a03);
  if (res[0]!=0) res[0][55]=a63;
  a21=(a61*a21);
  a36=(a36+a21);
  a67=(a67+a36);
  a67=(a67-a68);
  a67=(a67/a03);
  if (res[0]!=0) res[0][56]=a67;
  if (res[0]!=0) res[0][57]=a71;
  if (res[0]!=0) res[0][58]=a57;
  if (res[0]!=0) res[0][59]=a73;
  if (res[0]!=0) res[0][60]=a01;
  if (res[0]!=0) res[0][61]=a01;
  if (res[0]!=0) res[0][62]=a01;
  if (res[0]!=0) res[0][63]=a77;
  a79=(a04*a79);
  a79=(a60+a79);
  a79=(2.*a79);
  a33=(a33*a79);
  a79=(a33/a19);
  if (res[0]!=0) res[0][64]=a79;
  if (res[0]!=0) res[0][65]=a76;
  if (res[0]!=0) res[0][66]=a01;
  if (res[0]!=0) res[0][67]=a01;
  if (res[0]!=0) res[0][68]=a01;
  a33=(a04*a33);
  a59=(a59*a33);
  a83=(a83+a59);
  a82=(a82+a83);
  a82=(a82/a03);
  if (res[0]!=0) res[0][69]=a82;
  if (res[0]!=0) res[0][70]=a85;
  a33=(a65*a33);
  a78=(a78+a33);
  a81=(a81-a78);
  a81=(a81/a03);
  if (res[0]!=0) res[0][71]=a81;
  if (res[0]!=0) res[0][72]=a18;
  if (res[0]!=0) res[0][73]=a42;
  if (res[0]!=0) res[0][74]=a69;
  if (res[0]!=0) res[0][75]=a01;
  if (res[0]!=0) res[0][76]=a01;
  if (res[0]!=0) res[0][77]=a01;
  if (res[0]!=0) res[0][78]=a26;
  if (res[0]!=0) res[0][79]=a17;
  a74=(a04*a74);
  a74=(a60+a74);
  a74=(2.*a74);
  a44=(a44*a74);
  a74=(a44/a19);
  if (res[0]!=0) res[0][80]=a74;
  if (res[0]!=0) res[0][81]=a01;
  if (res[0]!=0) res[0][82]=a01;
  if (res[0]!=0) res[0][83]=a01;
  a44=(a04*a44);
  a61=(a61*a44);
  a50=(a50+a61);
  a22=(a22-a50);
  a22=(a22+a24);
  a22=(a22/a03);
  if (res[0]!=0) res[0][84]=a22;
  a65=(a65*a44);
  a58=(a58+a65);
  a49=(a49+a58);
  a49=(a49-a46);
  a49=(a49/a03);
  if (res[0]!=0) res[0][85]=a49;
  if (res[0]!=0) res[0][86]=a53;
  if (res[0]!=0) res[0][87]=a37;
  if (res[0]!=0) res[0][88]=a23;
  if (res[0]!=0) res[0][89]=a14;
  if (res[0]!=0) res[0][90]=a01;
  if (res[0]!=0) res[0][91]=a01;
  if (res[0]!=0) res[0][92]=a01;
  if (res[0]!=0) res[0][93]=a01;
  if (res[0]!=0) res[0][94]=a01;
  if (res[0]!=0) res[0][95]=a01;
  if (res[0]!=0) res[0][96]=a60;
  if (res[0]!=0) res[0][97]=a01;
  if (res[0]!=0) res[0][98]=a01;
  if (res[0]!=0) res[0][99]=a01;
  if (res[0]!=0) res[0][100]=a01;
  if (res[0]!=0) res[0][101]=a01;
  a14=(-a03);
  if (res[0]!=0) res[0][102]=a14;
  if (res[0]!=0) res[0][103]=a01;
  if (res[0]!=0) res[0][104]=a01;
  if (res[0]!=0) res[0][105]=a01;
  if (res[0]!=0) res[0][106]=a01;
  if (res[0]!=0) res[0][107]=a01;
  if (res[0]!=0) res[0][108]=a01;
  if (res[0]!=0) res[0][109]=a01;
  if (res[0]!=0) res[0][110]=a01;
  if (res[0]!=0) res[0][111]=a01;
  if (res[0]!=0) res[0][112]=a60;
  if (res[0]!=0) res[0][113]=a01;
  if (res[0]!=0) res[0][114]=a01;
  if (res[0]!=0) res[0][115]=a01;
  if (res[0]!=0) res[0][116]=a01;
  if (res[0]!=0) res[0][117]=a01;
  if (res[0]!=0) res[0][118]=a14;
  if (res[0]!=0) res[0][119]=a01;
  if (res[0]!=0) res[0][120]=a01;
  if (res[0]!=0) res[0][121]=a01;
  if (res[0]!=0) res[0][122]=a01;
  if (res[0]!=0) res[0][123]=a01;
  if (res[0]!=0) res[0][124]=a01;
  if (res[0]!=0) res[0][125]=a01;
  if (res[0]!=0) res[0][126]=a01;
  if (res[0]!=0) res[0][127]=a01;
  if (res[0]!=0) res[0][128]=a60;
  if (res[0]!=0) res[0][129]=a01;
  if (res[0]!=0) res[0][130]=a01;
  if (res[0]!=0) res[0][131]=a01;
  if (res[0]!=0) res[0][132]=a01;
  if (res[0]!=0) res[0][133]=a01;
  if (res[0]!=0) res[0][134]=a14;
  a14=casadi_sq(a03);
  a04=(a04*a14);
  a04=(a04/a19);
  a04=(-a04);
  if (res[0]!=0) res[0][135]=a04;
  if (res[0]!=0) res[0][136]=a01;
  if (res[0]!=0) res[0][137]=a01;
  if (res[0]!=0) res[0][138]=a04;
  if (res[0]!=0) res[0][139]=a01;
  if (res[0]!=0) res[0][140]=a01;
  if (res[0]!=0) res[0][141]=a01;
  if (res[0]!=0) res[0][142]=a01;
  if (res[0]!=0) res[0][143]=a01;
  a15=(a15/a12);
  a15=(a60+a15);
  if (res[0]!=0) res[0][144]=a15;
  a25=(a25/a12);
  a05=(a05/a00);
  a19=(a25-a05);
  if (res[0]!=0) res[0][145]=a19;
  a08=(a08/a00);
  a30=(a30/a12);
  a19=(a08+a30);
  if (res[0]!=0) res[0][146]=a19;
  a19=(a15*a03);
  a19=(-a19);
  if (res[0]!=0) res[0][147]=a19;
  a25=(a05+a25);
  a19=(a25*a03);
  a19=(-a19);
  if (res[0]!=0) res[0][148]=a19;
  a30=(a30-a08);
  a19=(a30*a03);
  a19=(-a19);
  if (res[0]!=0) res[0][149]=a19;
  if (res[0]!=0) res[0][150]=a01;
  if (res[0]!=0) res[0][151]=a04;
  if (res[0]!=0) res[0][152]=a01;
  if (res[0]!=0) res[0][153]=a01;
  if (res[0]!=0) res[0][154]=a04;
  if (res[0]!=0) res[0][155]=a01;
  if (res[0]!=0) res[0][156]=a01;
  if (res[0]!=0) res[0][157]=a01;
  if (res[0]!=0) res[0][158]=a01;
  a34=(a34/a12);
  a19=(a05+a34);
  if (res[0]!=0) res[0][159]=a19;
  a10=(a10/a12);
  a10=(a60+a10);
  if (res[0]!=0) res[0][160]=a10;
  a40=(a40/a12);
  a13=(a13/a00);
  a00=(a40-a13);
  if (res[0]!=0) res[0][161]=a00;
  a34=(a34-a05);
  a05=(a34*a03);
  a05=(-a05);
  if (res[0]!=0) res[0][162]=a05;
  a05=(a10*a03);
  a05=(-a05);
  if (res[0]!=0) res[0][163]=a05;
  a40=(a13+a40);
  a05=(a40*a03);
  a05=(-a05);
  if (res[0]!=0) res[0][164]=a05;
  if (res[0]!=0) res[0][165]=a01;
  if (res[0]!=0) res[0][166]=a01;
  if (res[0]!=0) res[0][167]=a04;
  if (res[0]!=0) res[0][168]=a01;
  if (res[0]!=0) res[0][169]=a01;
  if (res[0]!=0) res[0][170]=a04;
  if (res[0]!=0) res[0][171]=a01;
  if (res[0]!=0) res[0][172]=a01;
  if (res[0]!=0) res[0][173]=a01;
  a45=(a45/a12);
  a04=(a45-a08);
  if (res[0]!=0) res[0][174]=a04;
  a48=(a48/a12);
  a04=(a13+a48);
  if (res[0]!=0) res[0][175]=a04;
  a07=(a07/a12);
  a60=(a60+a07);
  if (res[0]!=0) res[0][176]=a60;
  a08=(a08+a45);
  a45=(a08*a03);
  a45=(-a45);
  if (res[0]!=0) res[0][177]=a45;
  a48=(a48-a13);
  a13=(a48*a03);
  a13=(-a13);
  if (res[0]!=0) res[0][178]=a13;
  a03=(a60*a03);
  a03=(-a03);
  if (res[0]!=0) res[0][179]=a03;
  a03=-1.;
  if (res[0]!=0) res[0][180]=a03;
  if (res[0]!=0) res[0][181]=a01;
  if (res[0]!=0) res[0][182]=a01;
  if (res[0]!=0) res[0][183]=a03;
  if (res[0]!=0) res[0][184]=a01;
  if (res[0]!=0) res[0][185]=a01;
  if (res[0]!=0) res[0][186]=a01;
  if (res[0]!=0) res[0][187]=a01;
  if (res[0]!=0) res[0][188]=a01;
  if (res[0]!=0) res[0][189]=a01;
  if (res[0]!=0) res[0][190]=a01;
  if (res[0]!=0) res[0][191]=a01;
  a15=(-a15);
  if (res[0]!=0) res[0][192]=a15;
  a25=(-a25);
  if (res[0]!=0) res[0][193]=a25;
  a30=(-a30);
  if (res[0]!=0) res[0][194]=a30;
  if (res[0]!=0) res[0][195]=a01;
  if (res[0]!=0) res[0][196]=a03;
  if (res[0]!=0) res[0][197]=a01;
  if (res[0]!=0) res[0][198]=a01;
  if (res[0]!=0) res[0][199]=a03;
  if (res[0]!=0) res[0][200]=a01;
  if (res[0]!=0) res[0][201]=a01;
  if (res[0]!=0) res[0][202]=a01;
  if (res[0]!=0) res[0][203]=a01;
  if (res[0]!=0) res[0][204]=a01;
  if (res[0]!=0) res[0][205]=a01;
  if (res[0]!=0) res[0][206]=a01;
  a34=(-a34);
  if (res[0]!=0) res[0][207]=a34;
  a10=(-a10);
  if (res[0]!=0) res[0][208]=a10;
  a40=(-a40);
  if (res[0]!=0) res[0][209]=a40;
  if (res[0]!=0) res[0][210]=a01;
  if (res[0]!=0) res[0][211]=a01;
  if (res[0]!=0) res[0][212]=a03;
  if (res[0]!=0) res[0][213]=a01;
  if (res[0]!=0) res[0][214]=a01;
  if (res[0]!=0) res[0][215]=a03;
  if (res[0]!=0) res[0][216]=a01;
  if (res[0]!=0) res[0][217]=a01;
  if (res[0]!=0) res[0][218]=a01;
  if (res[0]!=0) res[0][219]=a01;
  if (res[0]!=0) res[0][220]=a01;
  if (res[0]!=0) res[0][221]=a01;
  a08=(-a08);
  if (res[0]!=0) res[0][222]=a08;
  a48=(-a48);
  if (res[0]!=0) res[0][223]=a48;
  a60=(-a60);
  if (res[0]!=0) res[0][224]=a60;
  return 0;
}

CASADI_SYMBOL_EXPORT int jacobian(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f1(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int jacobian_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void jacobian_release(int mem) {
}

CASADI_SYMBOL_EXPORT void jacobian_incref(void) {
}

CASADI_SYMBOL_EXPORT void jacobian_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int jacobian_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int jacobian_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real jacobian_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* jacobian_name_in(casadi_int i) {
  switch (i) {
    case 0: return "z";
    case 1: return "g";
    case 2: return "p";
    case 3: return "h";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* jacobian_name_out(casadi_int i) {
  switch (i) {
    case 0: return "J";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* jacobian_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* jacobian_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int jacobian_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int jacobian_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* update:(z[15],g[9],p[3],h)->(g1[9],p1[3]) */
static int casadi_f2(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27;
  a00=arg[1]? arg[1][0] : 0;
  a01=1.;
  a02=4.;
  a03=arg[3]? arg[3][0] : 0;
  a04=5.0000000000000000e-01;
  a05=arg[0]? arg[0][0] : 0;
  a05=(a04*a05);
  a06=arg[0]? arg[0][3] : 0;
  a06=(a04*a06);
  a05=(a05+a06);
  a05=(a03*a05);
  a06=casadi_sq(a05);
  a07=arg[0]? arg[0][1] : 0;
  a07=(a04*a07);
  a08=arg[0]? arg[0][4] : 0;
  a08=(a04*a08);
  a07=(a07+a08);
  a07=(a03*a07);
  a08=casadi_sq(a07);
  a09=(a06+a08);
  a10=arg[0]? arg[0][2] : 0;
  a10=(a04*a10);
  a11=arg[0]? arg[0][5] : 0;
  a04=(a04*a11);
  a10=(a10+a04);
  a03=(a03*a10);
  a10=casadi_sq(a03);
  a09=(a09+a10);
  a09=(a02+a09);
  a09=(a02/a09);
  a04=(a10+a08);
  a11=2.;
  a04=(a04/a11);
  a04=(a09*a04);
  a04=(a01-a04);
  a12=(a00*a04);
  a13=arg[1]? arg[1][3] : 0;
  a14=(a05*a07);
  a15=(a14/a11);
  a15=(a03+a15);
  a15=(a09*a15);
  a16=(a13*a15);
  a12=(a12+a16);
  a16=arg[1]? arg[1][6] : 0;
  a17=(a05*a03);
  a18=(a17/a11);
  a18=(a18-a07);
  a18=(a09*a18);
  a19=(a16*a18);
  a12=(a12+a19);
  if (res[0]!=0) res[0][0]=a12;
  a12=arg[1]? arg[1][1] : 0;
  a19=(a12*a04);
  a20=arg[1]? arg[1][4] : 0;
  a21=(a20*a15);
  a19=(a19+a21);
  a21=arg[1]? arg[1][7] : 0;
  a22=(a21*a18);
  a19=(a19+a22);
  if (res[0]!=0) res[0][1]=a19;
  a19=arg[1]? arg[1][2] : 0;
  a04=(a19*a04);
  a22=arg[1]? arg[1][5] : 0;
  a15=(a22*a15);
  a04=(a04+a15);
  a15=arg[1]? arg[1][8] : 0;
  a18=(a15*a18);
  a04=(a04+a18);
  if (res[0]!=0) res[0][2]=a04;
  a04=(a07*a05);
  a18=(a04/a11);
  a18=(a18-a03);
  a18=(a09*a18);
  a23=(a00*a18);
  a24=(a10+a06);
  a24=(a24/a11);
  a24=(a09*a24);
  a24=(a01-a24);
  a25=(a13*a24);
  a23=(a23+a25);
  a25=(a07*a03);
  a26=(a25/a11);
  a26=(a05+a26);
  a26=(a09*a26);
  a27=(a16*a26);
  a23=(a23+a27);
  if (res[0]!=0) res[0][3]=a23;
  a23=(a12*a18);
  a27=(a20*a24);
  a23=(a23+a27);
  a27=(a21*a26);
  a23=(a23+a27);
  if (res[0]!=0) res[0][4]=a23;
  a18=(a19*a18);
  a24=(a22*a24);
  a18=(a18+a24);
  a26=(a15*a26);
  a18=(a18+a26);
  if (res[0]!=0) res[0][5]=a18;
  a18=(a03*a05);
  a26=(a18/a11);
  a26=(a07+a26);
  a26=(a09*a26);
  a00=(a00*a26);
  a24=(a03*a07);
  a23=(a24/a11);
  a23=(a23-a05);
  a23=(a09*a23);
  a13=(a13*a23);
  a00=(a00+a13);
  a13=(a08+a06);
  a13=(a13/a11);
  a09=(a09*a13);
  a09=(a01-a09);
  a16=(a16*a09);
  a00=(a00+a16);
  if (res[0]!=0) res[0][6]=a00;
  a12=(a12*a26);
  a20=(a20*a23);
  a12=(a12+a20);
  a21=(a21*a09);
  a12=(a12+a21);
  if (res[0]!=0) res[0][7]=a12;
  a19=(a19*a26);
  a22=(a22*a23);
  a19=(a19+a22);
  a15=(a15*a09);
  a19=(a19+a15);
  if (res[0]!=0) res[0][8]=a19;
  a18=(a18/a02);
  a07=(a07/a11);
  a18=(a18-a07);
  a19=arg[0]? arg[0][14] : 0;
  a18=(a18*a19);
  a03=(a03/a11);
  a04=(a04/a02);
  a04=(a03+a04);
  a15=arg[0]? arg[0][13] : 0;
  a04=(a04*a15);
  a18=(a18+a04);
  a06=(a06/a02);
  a06=(a01+a06);
  a04=arg[0]? arg[0][12] : 0;
  a06=(a06*a04);
  a18=(a18+a06);
  if (res[1]!=0) res[1][0]=a18;
  a05=(a05/a11);
  a24=(a24/a02);
  a24=(a05+a24);
  a24=(a24*a19);
  a08=(a08/a02);
  a08=(a01+a08);
  a08=(a08*a15);
  a24=(a24+a08);
  a14=(a14/a02);
  a14=(a14-a03);
  a14=(a14*a04);
  a24=(a24+a14);
  if (res[1]!=0) res[1][1]=a24;
  a10=(a10/a02);
  a01=(a01+a10);
  a01=(a01*a19);
  a25=(a25/a02);
  a25=(a25-a05);
  a25=(a25*a15);
  a01=(a01+a25);
  a17=(a17/a02);
  a07=(a07+a17);
  a07=(a07*a04);
  a01=(a01+a07);
  if (res[1]!=0) res[1][2]=a01;
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
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* update_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    case 1: return casadi_s2;
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

/* guess:(xi[3],g[9],p[3],h)->(z0[15]) */
static int casadi_f3(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2;
  a0=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a0;
  a1=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a1;
  a2=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a2;
  if (res[0]!=0) res[0][3]=a0;
  if (res[0]!=0) res[0][4]=a1;
  if (res[0]!=0) res[0][5]=a2;
  a2=0.;
  if (res[0]!=0) res[0][6]=a2;
  if (res[0]!=0) res[0][7]=a2;
  if (res[0]!=0) res[0][8]=a2;
  if (res[0]!=0) res[0][9]=a2;
  if (res[0]!=0) res[0][10]=a2;
  if (res[0]!=0) res[0][11]=a2;
  a2=arg[2]? arg[2][0] : 0;
  if (res[0]!=0) res[0][12]=a2;
  a2=arg[2]? arg[2][1] : 0;
  if (res[0]!=0) res[0][13]=a2;
  a2=arg[2]? arg[2][2] : 0;
  if (res[0]!=0) res[0][14]=a2;
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
    case 0: return casadi_s2;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
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

/* legendre:(g[9],xi[3])->(mu[3]) */
static int casadi_f4(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3;
  a0=arg[1]? arg[1][0] : 0;
  a1=5.0000000000000000e-01;
  a2=arg[0]? arg[0][2] : 0;
  a2=(a1*a2);
  a0=(a0+a2);
  a0=(2.*a0);
  if (res[0]!=0) res[0][0]=a0;
  a0=arg[1]? arg[1][1] : 0;
  a2=arg[0]? arg[0][5] : 0;
  a2=(a1*a2);
  a0=(a0+a2);
  if (res[0]!=0) res[0][1]=a0;
  a0=6.6666666666666663e-01;
  a2=arg[1]? arg[1][2] : 0;
  a3=arg[0]? arg[0][8] : 0;
  a1=(a1*a3);
  a2=(a2+a1);
  a0=(a0*a2);
  if (res[0]!=0) res[0][2]=a0;
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
    case 1: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* legendre_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
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

/* hessian:(g[9],xi[3])->(H[9]) */
static int casadi_f5(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1;
  a0=2.;
  if (res[0]!=0) res[0][0]=a0;
  a0=0.;
  if (res[0]!=0) res[0][1]=a0;
  if (res[0]!=0) res[0][2]=a0;
  if (res[0]!=0) res[0][3]=a0;
  a1=1.;
  if (res[0]!=0) res[0][4]=a1;
  if (res[0]!=0) res[0][5]=a0;
  if (res[0]!=0) res[0][6]=a0;
  if (res[0]!=0) res[0][7]=a0;
  a0=6.6666666666666663e-01;
  if (res[0]!=0) res[0][8]=a0;
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
    case 1: return casadi_s2;
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

/* energy:(g[9],xi[3])->(E) */
static int casadi_f6(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4, a5, a6, a7, a8, a9;
  a0=arg[1]? arg[1][0] : 0;
  a1=5.0000000000000000e-01;
  a2=arg[0]? arg[0][2] : 0;
  a3=(a1*a2);
  a3=(a0+a3);
  a4=(2.*a3);
  a4=(a4*a0);
  a0=arg[1]? arg[1][1] : 0;
  a5=arg[0]? arg[0][5] : 0;
  a6=(a1*a5);
  a6=(a0+a6);
  a0=(a6*a0);
  a4=(a4+a0);
  a0=6.6666666666666663e-01;
  a7=arg[1]? arg[1][2] : 0;
  a8=arg[0]? arg[0][8] : 0;
  a9=(a1*a8);
  a9=(a7+a9);
  a0=(a0*a9);
  a0=(a0*a7);
  a4=(a4+a0);
  a6=casadi_sq(a6);
  a1=(a1*a6);
  a3=casadi_sq(a3);
  a1=(a1+a3);
  a3=5.9999999999999998e-02;
  a3=(a3*a5);
  a1=(a1+a3);
  a3=3.3333333333333331e-01;
  a9=casadi_sq(a9);
  a3=(a3*a9);
  a1=(a1+a3);
  a3=-8.9999999999999997e-02;
  a3=(a3*a2);
  a1=(a1+a3);
  a3=-1.4999999999999999e-01;
  a3=(a3*a8);
  a1=(a1+a3);
  a4=(a4-a1);
  if (res[0]!=0) res[0][0]=a4;
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
    case 1: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* energy_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
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

/* momentum:(g[9],p[3])->(m[3]) */
static int casadi_f7(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13;
  a00=arg[0]? arg[0][8] : 0;
  a01=arg[0]? arg[0][4] : 0;
  a02=(a00*a01);
  a03=arg[0]? arg[0][7] : 0;
  a04=arg[0]? arg[0][5] : 0;
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
  a02=arg[0]? arg[0][6] : 0;
  a07=(a02*a04);
  a11=arg[0]? arg[0][3] : 0;
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
    case 1: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* momentum_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
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

/* defect:(g[9])->(e) */
static int casadi_f8(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12;
  a00=arg[0]? arg[0][0] : 0;
  a01=casadi_sq(a00);
  a02=arg[0]? arg[0][1] : 0;
  a03=casadi_sq(a02);
  a01=(a01+a03);
  a03=arg[0]? arg[0][2] : 0;
  a04=casadi_sq(a03);
  a01=(a01+a04);
  a04=1.;
  a01=(a01-a04);
  a01=casadi_fabs(a01);
  a05=arg[0]? arg[0][3] : 0;
  a06=(a05*a00);
  a07=arg[0]? arg[0][4] : 0;
  a08=(a07*a02);
  a06=(a06+a08);
  a08=arg[0]? arg[0][5] : 0;
  a09=(a08*a03);
  a06=(a06+a09);
  a06=casadi_fabs(a06);
  a01=casadi_fmax(a01,a06);
  a06=arg[0]? arg[0][6] : 0;
  a09=(a06*a00);
  a10=arg[0]? arg[0][7] : 0;
  a11=(a10*a02);
  a09=(a09+a11);
  a11=arg[0]? arg[0][8] : 0;
  a12=(a11*a03);
  a09=(a09+a12);
  a09=casadi_fabs(a09);
  a01=casadi_fmax(a01,a09);
  a09=(a00*a05);
  a12=(a02*a07);
  a09=(a09+a12);
  a12=(a03*a08);
  a09=(a09+a12);
  a09=casadi_fabs(a09);
  a01=casadi_fmax(a01,a09);
  a09=casadi_sq(a05);
  a12=casadi_sq(a07);
  a09=(a09+a12);
  a12=casadi_sq(a08);
  a09=(a09+a12);
  a09=(a09-a04);
  a09=casadi_fabs(a09);
  a01=casadi_fmax(a01,a09);
  a09=(a06*a05);
  a12=(a10*a07);
  a09=(a09+a12);
  a12=(a11*a08);
  a09=(a09+a12);
  a09=casadi_fabs(a09);
  a01=casadi_fmax(a01,a09);
  a09=(a00*a06);
  a12=(a02*a10);
  a09=(a09+a12);
  a12=(a03*a11);
  a09=(a09+a12);
  a09=casadi_fabs(a09);
  a01=casadi_fmax(a01,a09);
  a09=(a05*a06);
  a12=(a07*a10);
  a09=(a09+a12);
  a12=(a08*a11);
  a09=(a09+a12);
  a09=casadi_fabs(a09);
  a01=casadi_fmax(a01,a09);
  a09=casadi_sq(a06);
  a12=casadi_sq(a10);
  a09=(a09+a12);
  a12=casadi_sq(a11);
  a09=(a09+a12);
  a09=(a09-a04);
  a09=casadi_fabs(a09);
  a01=casadi_fmax(a01,a09);
  a09=(a07*a11);
  a12=(a10*a08);
  a09=(a09-a12);
  a00=(a00*a09);
  a11=(a02*a11);
  a10=(a10*a03);
  a11=(a11-a10);
  a05=(a05*a11);
  a00=(a00-a05);
  a02=(a02*a08);
  a07=(a07*a03);
  a02=(a02-a07);
  a06=(a06*a02);
  a00=(a00+a06);
  a00=(a00-a04);
  a00=casadi_fabs(a00);
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
    case 0: return casadi_s3;
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

/* margin:(z[15],h)->(m) */
static int casadi_f9(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0;
  a0=1.;
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
    case 1: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* margin_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
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



/* ======================= end of CasADi-generated code =================================== */
#if defined(__GNUC__)
#pragma GCC visibility pop
#define HPGEN_EXPORT __attribute__((visibility("default")))
#else
#define HPGEN_EXPORT
#endif

#define HPGEN_ABI 1
#define HPGEN_N 3
#define HPGEN_NN (HPGEN_N * HPGEN_N)
#define HPGEN_D 3
#define HPGEN_NZ 15
#define HPGEN_OK 0
#define HPGEN_NO_CONVERGENCE 1
#define HPGEN_NONFINITE 2
#define HPGEN_DOMAIN 3
#define HPGEN_INVALID (-1)
/* Newton stalls at round-off: stop when |dz| stopped decreasing while below this * (1+|z|) */
#define HPGEN_ROUNDOFF_FLOOR 1e-11

typedef struct hpgen_status {
    long long code;              /* HPGEN_OK, ... */
    long long step;              /* failing step index, or steps done on success */
    long long iterations;        /* Newton iterations of the last step attempted */
    long long total_iterations;  /* Newton iterations over all steps */
    double residual;             /* inf-norm of the last residual evaluated */
} hpgen_status;

HPGEN_EXPORT const char* hpgen_hash(void) { return "05de9e8f33b5ccf128e0cf5c52c38a2eadfd45e6027d470444395b130d93c442"; }

/* out[0..3] = ABI version, n, d, nz */
HPGEN_EXPORT void hpgen_dims(long long* out) {
    out[0] = HPGEN_ABI; out[1] = HPGEN_N; out[2] = HPGEN_D; out[3] = HPGEN_NZ;
}

/* ---- kernel wrappers: dense column-major arguments, CasADi work arrays on the stack ---- */

/* residual(z[15], g[9], p[3], h[1]) -> (F[15]) */
#define HPGEN_RESIDUAL_SZ_ARG 4
#define HPGEN_RESIDUAL_SZ_RES 1
#define HPGEN_RESIDUAL_SZ_IW 0
#define HPGEN_RESIDUAL_SZ_W 40
HPGEN_EXPORT int hpgen_kernel_residual(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
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

/* jacobian(z[15], g[9], p[3], h[1]) -> (J[225]) */
#define HPGEN_JACOBIAN_SZ_ARG 4
#define HPGEN_JACOBIAN_SZ_RES 1
#define HPGEN_JACOBIAN_SZ_IW 0
#define HPGEN_JACOBIAN_SZ_W 88
HPGEN_EXPORT int hpgen_kernel_jacobian(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    const casadi_real* arg[HPGEN_JACOBIAN_SZ_ARG + 1];
    casadi_real* res[HPGEN_JACOBIAN_SZ_RES + 1];
    casadi_int iw[HPGEN_JACOBIAN_SZ_IW + 1];
    casadi_real w[HPGEN_JACOBIAN_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    arg[3] = in3;
    res[0] = out0;
    flag = jacobian(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

/* update(z[15], g[9], p[3], h[1]) -> (g1[9], p1[3]) */
#define HPGEN_UPDATE_SZ_ARG 4
#define HPGEN_UPDATE_SZ_RES 2
#define HPGEN_UPDATE_SZ_IW 0
#define HPGEN_UPDATE_SZ_W 28
HPGEN_EXPORT int hpgen_kernel_update(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1) {
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

/* guess(xi[3], g[9], p[3], h[1]) -> (z0[15]) */
#define HPGEN_GUESS_SZ_ARG 4
#define HPGEN_GUESS_SZ_RES 1
#define HPGEN_GUESS_SZ_IW 0
#define HPGEN_GUESS_SZ_W 3
HPGEN_EXPORT int hpgen_kernel_guess(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
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

/* legendre(g[9], xi[3]) -> (mu[3]) */
#define HPGEN_LEGENDRE_SZ_ARG 2
#define HPGEN_LEGENDRE_SZ_RES 1
#define HPGEN_LEGENDRE_SZ_IW 0
#define HPGEN_LEGENDRE_SZ_W 4
HPGEN_EXPORT int hpgen_kernel_legendre(const double* in0, const double* in1, double* out0) {
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

/* hessian(g[9], xi[3]) -> (H[9]) */
#define HPGEN_HESSIAN_SZ_ARG 2
#define HPGEN_HESSIAN_SZ_RES 1
#define HPGEN_HESSIAN_SZ_IW 0
#define HPGEN_HESSIAN_SZ_W 2
HPGEN_EXPORT int hpgen_kernel_hessian(const double* in0, const double* in1, double* out0) {
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

/* energy(g[9], xi[3]) -> (E[1]) */
#define HPGEN_ENERGY_SZ_ARG 2
#define HPGEN_ENERGY_SZ_RES 1
#define HPGEN_ENERGY_SZ_IW 0
#define HPGEN_ENERGY_SZ_W 10
HPGEN_EXPORT int hpgen_kernel_energy(const double* in0, const double* in1, double* out0) {
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

/* momentum(g[9], p[3]) -> (m[3]) */
#define HPGEN_MOMENTUM_SZ_ARG 2
#define HPGEN_MOMENTUM_SZ_RES 1
#define HPGEN_MOMENTUM_SZ_IW 0
#define HPGEN_MOMENTUM_SZ_W 14
HPGEN_EXPORT int hpgen_kernel_momentum(const double* in0, const double* in1, double* out0) {
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

/* defect(g[9]) -> (e[1]) */
#define HPGEN_DEFECT_SZ_ARG 1
#define HPGEN_DEFECT_SZ_RES 1
#define HPGEN_DEFECT_SZ_IW 0
#define HPGEN_DEFECT_SZ_W 13
HPGEN_EXPORT int hpgen_kernel_defect(const double* in0, double* out0) {
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

/* margin(z[15], h[1]) -> (m[1]) */
#define HPGEN_MARGIN_SZ_ARG 2
#define HPGEN_MARGIN_SZ_RES 1
#define HPGEN_MARGIN_SZ_IW 0
#define HPGEN_MARGIN_SZ_W 1
HPGEN_EXPORT int hpgen_kernel_margin(const double* in0, const double* in1, double* out0) {
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

static int hpgen_all_finite(const double* x, int n) {
    int i;
    for (i = 0; i < n; ++i) if (!isfinite(x[i])) return 0;
    return 1;
}

/* Solve A x = b in place: LU with partial pivoting (pivot: first row of largest |a_ik|, as
   LAPACK). A is NZ x NZ column-major and is overwritten; b is overwritten by x.
   Returns 1 if a pivot is exactly zero (singular A). */
static int hpgen_lu_solve(double* A, double* b) {
    const int n = HPGEN_NZ;
    int i, j, k;
    for (k = 0; k < n; ++k) {
        int piv = k;
        double amax = fabs(A[k + k * n]);
        for (i = k + 1; i < n; ++i) {
            double a = fabs(A[i + k * n]);
            if (a > amax) { amax = a; piv = i; }
        }
        if (amax == 0.0) return 1;
        if (piv != k) {
            double t;
            for (j = 0; j < n; ++j) { t = A[k + j * n]; A[k + j * n] = A[piv + j * n]; A[piv + j * n] = t; }
            t = b[k]; b[k] = b[piv]; b[piv] = t;
        }
        for (i = k + 1; i < n; ++i) A[i + k * n] /= A[k + k * n];
        for (j = k + 1; j < n; ++j) {
            double a = A[k + j * n];
            if (a != 0.0) for (i = k + 1; i < n; ++i) A[i + j * n] -= A[i + k * n] * a;
        }
        for (i = k + 1; i < n; ++i) b[i] -= A[i + k * n] * b[k];
    }
    for (k = n - 1; k >= 0; --k) {
        double s = b[k];
        for (j = k + 1; j < n; ++j) s -= A[k + j * n] * b[j];
        b[k] = s / A[k + k * n];
    }
    return 0;
}

/* Newton on residual(z, g, p, h) = 0 from z (in/out): z <- z - J^{-1} F; converged when
   |dz| <= tol (1 + |z|), or when |dz| stopped decreasing while |dz| <= 1e-11 (1 + |z|)
   (round-off floor); inf-norms. Returns a status code. */
static int hpgen_newton(const double* g, const double* p, const double* hv, double* z,
                        double tol, long long maxit, long long* iters, double* rnorm) {
    double F[HPGEN_NZ], J[HPGEN_NZ * HPGEN_NZ];
    double dprev = HUGE_VAL;
    long long it;
    int i;
    *iters = 0;
    *rnorm = NAN;
    for (it = 1; it <= maxit; ++it) {
        double dn, zn;
        *iters = it;
        if (hpgen_kernel_residual(z, g, p, hv, F) || hpgen_kernel_jacobian(z, g, p, hv, J))
            return HPGEN_NONFINITE;
        *rnorm = hpgen_norm_inf(F, HPGEN_NZ);
        if (!isfinite(*rnorm) || !hpgen_all_finite(J, HPGEN_NZ * HPGEN_NZ))
            return HPGEN_NONFINITE;
        if (hpgen_lu_solve(J, F)) return HPGEN_NONFINITE;
        for (i = 0; i < HPGEN_NZ; ++i) z[i] -= F[i];
        dn = hpgen_norm_inf(F, HPGEN_NZ);
        zn = hpgen_norm_inf(z, HPGEN_NZ);
        if (!isfinite(dn) || !isfinite(zn)) return HPGEN_NONFINITE;
        if (dn <= tol * (1.0 + zn)) return HPGEN_OK;
        if (it > 1 && dn >= dprev && dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + zn)) return HPGEN_OK;
        dprev = dn;
    }
    return HPGEN_NO_CONVERGENCE;
}

/* One step: Newton from z (in/out), then margin(z, h) > 0, then update -> (g1, p1). */
static int hpgen_step_core(const double* g, const double* p, const double* hv, double* z,
                           double tol, long long maxit, double* g1, double* p1,
                           long long* iters, double* rnorm) {
    double m[1];
    int code = hpgen_newton(g, p, hv, z, tol, maxit, iters, rnorm);
    if (code != HPGEN_OK) {
        /* a failure at an iterate outside tau's domain is reported as a domain error */
        if (!hpgen_kernel_margin(z, hv, m) && m[0] <= 0.0) return HPGEN_DOMAIN;
        return code;
    }
    if (hpgen_kernel_margin(z, hv, m)) return HPGEN_NONFINITE;
    if (!(m[0] > 0.0)) return HPGEN_DOMAIN;
    if (hpgen_kernel_update(z, g, p, hv, g1, p1)) return HPGEN_NONFINITE;
    if (!hpgen_all_finite(g1, HPGEN_NN) || !hpgen_all_finite(p1, HPGEN_D))
        return HPGEN_NONFINITE;
    return HPGEN_OK;
}

static void hpgen_status_init(hpgen_status* st) {
    st->code = HPGEN_OK; st->step = 0; st->iterations = 0; st->total_iterations = 0;
    st->residual = 0.0;
}

/* One step from (g, p) with step size h; z: Newton start in, solution out. Returns the code. */
HPGEN_EXPORT int hpgen_step(const double* g, const double* p, double h, double* z, double tol,
                            long long maxit, double* g1, double* p1, hpgen_status* st) {
    double hv[1];
    long long it;
    double r;
    int code;
    hpgen_status_init(st);
    if (maxit < 1) { st->code = HPGEN_INVALID; return HPGEN_INVALID; }
    hv[0] = h;
    code = hpgen_step_core(g, p, hv, z, tol, maxit, g1, p1, &it, &r);
    st->code = code; st->iterations = it; st->total_iterations = it; st->residual = r;
    return code;
}

/* All steps in one call, warm-started (each Newton starts from the previous solution z, in/out).
   Records (g, p) at steps 0, every, 2 every, ... into g_rec[(steps/every + 1) * NN] and
   p_rec[(steps/every + 1) * D]. Stops at the first failed step. Returns the steps done. */
HPGEN_EXPORT long long hpgen_simulate(const double* g0, const double* p0, double h, double* z,
                                      long long steps, long long every, double tol,
                                      long long maxit, double* g_rec, double* p_rec,
                                      hpgen_status* st) {
    double g[HPGEN_NN], p[HPGEN_D], g1[HPGEN_NN], p1[HPGEN_D], hv[1];
    long long k, it;
    double r;
    hpgen_status_init(st);
    if (steps < 0 || every < 1 || maxit < 1) { st->code = HPGEN_INVALID; return 0; }
    hv[0] = h;
    memcpy(g, g0, sizeof g);
    memcpy(p, p0, sizeof p);
    memcpy(g_rec, g, sizeof g);
    memcpy(p_rec, p, sizeof p);
    for (k = 0; k < steps; ++k) {
        int code = hpgen_step_core(g, p, hv, z, tol, maxit, g1, p1, &it, &r);
        st->iterations = it;
        st->total_iterations += it;
        st->residual = r;
        if (code != HPGEN_OK) { st->code = code; st->step = k; return k; }
        memcpy(g, g1, sizeof g);
        memcpy(p, p1, sizeof p);
        if ((k + 1) % every == 0) {
            long long rec = (k + 1) / every;
            memcpy(g_rec + rec * HPGEN_NN, g, sizeof g);
            memcpy(p_rec + rec * HPGEN_D, p, sizeof p);
        }
    }
    st->step = steps;
    return steps;
}
