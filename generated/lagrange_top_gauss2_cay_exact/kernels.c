/*
 * hpgen generated module lagrange_top_gauss2_cay_exact -- do not edit, regenerate with hpgen
 * model: lagrange_top
 * options: tableau=gauss2, tau=cay, rkmk=exact
 * hpgen version: 0.1.0
 * content hash (normalized model + options): 72a44fd1ee755e2c4425d908d39fb933f3430a0480e798986ddd5164069c3cd9
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
  #define CASADI_PREFIX(ID) hpgen_lagrange_top_gauss2_cay_exact__ ## ID
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
#define casadi_s6 CASADI_PREFIX(s6)
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
CASADI_SYMBOL_EXPORT void hpgen_lagrange_top_gauss2_cay_exact__casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int hpgen_lagrange_top_gauss2_cay_exact__casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int hpgen_lagrange_top_gauss2_cay_exact__casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {3, 1, 1};
static const casadi_int casadi_s2[3] = {1, 1, 1};
static const casadi_int casadi_s3[3] = {81, 1, 1};
static const casadi_int casadi_s4[3] = {16, 1, 1};
static const casadi_int casadi_s5[3] = {54, 1, 1};
static const casadi_int casadi_s6[3] = {36, 1, 1};

/* residual:(z[9],g[9],p[3],h)->(F[9]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60;
  a00=arg[3]? arg[3][0] : 0;
  a01=arg[0]? arg[0][2] : 0;
  a02=(a00*a01);
  a03=5.0000000000000000e-01;
  a04=4.;
  a05=arg[0]? arg[0][0] : 0;
  a06=(a00*a05);
  a07=casadi_sq(a06);
  a08=arg[0]? arg[0][1] : 0;
  a09=(a00*a08);
  a10=casadi_sq(a09);
  a11=(a07+a10);
  a12=casadi_sq(a02);
  a11=(a11+a12);
  a11=(a04+a11);
  a11=(a04/a11);
  a13=3.0000000000000004e+00;
  a14=(a13*a05);
  a15=4.6410161513775439e-01;
  a16=arg[0]? arg[0][3] : 0;
  a17=(a15*a16);
  a14=(a14+a17);
  a17=(a13*a08);
  a18=arg[0]? arg[0][4] : 0;
  a19=(a15*a18);
  a17=(a17+a19);
  a19=(a02*a17);
  a20=(a13*a01);
  a21=arg[0]? arg[0][5] : 0;
  a15=(a15*a21);
  a20=(a20+a15);
  a15=(a09*a20);
  a19=(a19-a15);
  a15=2.;
  a19=(a19/a15);
  a19=(a14+a19);
  a19=(a11*a19);
  a22=arg[0]? arg[0][8] : 0;
  a23=(a00*a22);
  a23=(a03*a23);
  a24=5.3867513459481287e-01;
  a25=2.3205080756887719e-01;
  a26=1.5234375000000000e+01;
  a27=(a09*a14);
  a28=(a06*a17);
  a27=(a27-a28);
  a27=(a27/a15);
  a27=(a20+a27);
  a27=(a11*a27);
  a28=(a26*a27);
  a29=(a26*a19);
  a30=(a09*a29);
  a31=4.6875000000000000e-01;
  a32=(a06*a20);
  a33=(a02*a14);
  a32=(a32-a33);
  a32=(a32/a15);
  a32=(a17+a32);
  a32=(a11*a32);
  a33=(a31*a32);
  a34=(a06*a33);
  a30=(a30-a34);
  a30=(a30/a15);
  a30=(a28-a30);
  a30=(a11*a30);
  a30=(a30-a22);
  a34=(a25*a30);
  a35=1.5000000000000002e+00;
  a36=(a00*a16);
  a37=casadi_sq(a36);
  a38=(a00*a18);
  a39=casadi_sq(a38);
  a40=(a37+a39);
  a41=(a00*a21);
  a42=casadi_sq(a41);
  a40=(a40+a42);
  a40=(a04+a40);
  a40=(a04/a40);
  a43=-6.4641016151377553e+00;
  a01=(a43*a01);
  a21=(a13*a21);
  a01=(a01+a21);
  a05=(a43*a05);
  a16=(a13*a16);
  a05=(a05+a16);
  a16=(a38*a05);
  a43=(a43*a08);
  a13=(a13*a18);
  a43=(a43+a13);
  a13=(a36*a43);
  a16=(a16-a13);
  a16=(a16/a15);
  a16=(a01+a16);
  a16=(a40*a16);
  a13=(a26*a16);
  a18=(a41*a43);
  a08=(a38*a01);
  a18=(a18-a08);
  a18=(a18/a15);
  a18=(a05+a18);
  a18=(a40*a18);
  a26=(a26*a18);
  a08=(a38*a26);
  a21=(a36*a01);
  a44=(a41*a05);
  a21=(a21-a44);
  a21=(a21/a15);
  a21=(a43+a21);
  a21=(a40*a21);
  a31=(a31*a21);
  a44=(a36*a31);
  a08=(a08-a44);
  a08=(a08/a15);
  a08=(a13-a08);
  a08=(a40*a08);
  a08=(a08-a22);
  a44=(a35*a08);
  a34=(a34+a44);
  a44=(a00*a34);
  a45=(a24*a44);
  a45=(a23+a45);
  a46=2.5000000000000000e-01;
  a30=(a35*a30);
  a47=-3.2320508075688776e+00;
  a08=(a47*a08);
  a30=(a30+a08);
  a08=(a00*a30);
  a48=(a46*a08);
  a45=(a45+a48);
  a48=(a03*a45);
  a49=(a19*a48);
  a50=(a06*a28);
  a51=(a02*a29);
  a50=(a50-a51);
  a50=(a50/a15);
  a50=(a33-a50);
  a50=(a11*a50);
  a51=arg[0]? arg[0][7] : 0;
  a50=(a50-a51);
  a52=(a35*a50);
  a53=(a36*a13);
  a54=(a41*a26);
  a53=(a53-a54);
  a53=(a53/a15);
  a53=(a31-a53);
  a53=(a40*a53);
  a53=(a53-a51);
  a54=(a47*a53);
  a52=(a52+a54);
  a49=(a49+a52);
  a54=(a06*a19);
  a55=(a09*a32);
  a54=(a54+a55);
  a55=(a02*a27);
  a54=(a54+a55);
  a54=(a54/a04);
  a55=(a00*a51);
  a55=(a03*a55);
  a50=(a25*a50);
  a53=(a35*a53);
  a50=(a50+a53);
  a53=(a00*a50);
  a56=(a24*a53);
  a56=(a55+a56);
  a52=(a00*a52);
  a57=(a46*a52);
  a56=(a56+a57);
  a57=(a54*a56);
  a49=(a49-a57);
  a57=(a02*a45);
  a58=(a09*a56);
  a57=(a57+a58);
  a58=arg[0]? arg[0][6] : 0;
  a59=(a00*a58);
  a59=(a03*a59);
  a33=(a02*a33);
  a28=(a09*a28);
  a33=(a33-a28);
  a33=(a33/a15);
  a29=(a29-a33);
  a29=(a11*a29);
  a29=(a29-a58);
  a25=(a25*a29);
  a31=(a41*a31);
  a13=(a38*a13);
  a31=(a31-a13);
  a31=(a31/a15);
  a26=(a26-a31);
  a26=(a40*a26);
  a26=(a26-a58);
  a31=(a35*a26);
  a25=(a25+a31);
  a31=(a00*a25);
  a24=(a24*a31);
  a24=(a59+a24);
  a35=(a35*a29);
  a47=(a47*a26);
  a35=(a35+a47);
  a47=(a00*a35);
  a26=(a46*a47);
  a24=(a24+a26);
  a26=(a06*a24);
  a57=(a57+a26);
  a57=(a46*a57);
  a26=(a32*a57);
  a49=(a49-a26);
  a26=(a03*a24);
  a29=(a27*a26);
  a49=(a49-a29);
  a29=(a03*a49);
  a13=(a02*a29);
  a45=(a54*a45);
  a30=(a30-a45);
  a56=(a03*a56);
  a45=(a19*a56);
  a30=(a30-a45);
  a45=(a27*a57);
  a30=(a30-a45);
  a26=(a32*a26);
  a30=(a30+a26);
  a26=(a03*a30);
  a45=(a09*a26);
  a33=(a13-a45);
  a28=(a09*a49);
  a60=(a02*a30);
  a28=(a28+a60);
  a27=(a27*a56);
  a32=(a32*a48);
  a27=(a27-a32);
  a27=(a27+a35);
  a54=(a54*a24);
  a27=(a27-a54);
  a19=(a19*a57);
  a27=(a27-a19);
  a19=(a06*a27);
  a28=(a28+a19);
  a28=(a46*a28);
  a19=(a06*a28);
  a33=(a33+a19);
  a33=(a33+a27);
  a57=arg[1]? arg[1][2] : 0;
  a54=(a02*a06);
  a54=(a54/a15);
  a54=(a09+a54);
  a54=(a11*a54);
  a54=(a57*a54);
  a24=arg[1]? arg[1][5] : 0;
  a35=(a02*a09);
  a35=(a35/a15);
  a35=(a35-a06);
  a35=(a11*a35);
  a35=(a24*a35);
  a54=(a54+a35);
  a35=arg[1]? arg[1][8] : 0;
  a32=1.;
  a07=(a10+a07);
  a07=(a07/a15);
  a07=(a11*a07);
  a07=(a32-a07);
  a07=(a35*a07);
  a54=(a54+a07);
  a07=-7.3575000000000003e+01;
  a07=(a07*a00);
  a54=(a54*a07);
  a33=(a33+a54);
  a33=(a33/a00);
  if (res[0]!=0) res[0][0]=a33;
  a26=(a06*a26);
  a33=(a49+a26);
  a54=(a09*a28);
  a33=(a33+a54);
  a48=(a03*a27);
  a56=(a02*a48);
  a33=(a33-a56);
  a33=(a33/a00);
  if (res[0]!=0) res[0][1]=a33;
  a29=(a06*a29);
  a33=(a30-a29);
  a28=(a02*a28);
  a33=(a33+a28);
  a48=(a09*a48);
  a33=(a33+a48);
  a12=(a12+a10);
  a12=(a12/a15);
  a12=(a11*a12);
  a12=(a32-a12);
  a12=(a57*a12);
  a10=(a06*a09);
  a10=(a10/a15);
  a10=(a02+a10);
  a10=(a11*a10);
  a10=(a24*a10);
  a12=(a12+a10);
  a06=(a06*a02);
  a06=(a06/a15);
  a06=(a06-a09);
  a11=(a11*a06);
  a11=(a35*a11);
  a12=(a12+a11);
  a12=(a12*a07);
  a33=(a33-a12);
  a33=(a33/a00);
  if (res[0]!=0) res[0][2]=a33;
  a33=(a41*a36);
  a33=(a33/a15);
  a33=(a38+a33);
  a33=(a40*a33);
  a33=(a57*a33);
  a12=(a41*a38);
  a12=(a12/a15);
  a12=(a12-a36);
  a12=(a40*a12);
  a12=(a24*a12);
  a33=(a33+a12);
  a37=(a39+a37);
  a37=(a37/a15);
  a37=(a40*a37);
  a37=(a32-a37);
  a37=(a35*a37);
  a33=(a33+a37);
  a33=(a33*a07);
  a44=(a46*a44);
  a23=(a23+a44);
  a44=-3.8675134594812879e-02;
  a08=(a44*a08);
  a23=(a23+a08);
  a08=(a03*a23);
  a37=(a21*a08);
  a25=(a25-a37);
  a53=(a46*a53);
  a55=(a55+a53);
  a52=(a44*a52);
  a55=(a55+a52);
  a52=(a03*a55);
  a53=(a16*a52);
  a25=(a25+a53);
  a53=(a36*a18);
  a37=(a38*a21);
  a53=(a53+a37);
  a37=(a41*a16);
  a53=(a53+a37);
  a53=(a53/a04);
  a31=(a46*a31);
  a59=(a59+a31);
  a44=(a44*a47);
  a59=(a59+a44);
  a44=(a53*a59);
  a25=(a25-a44);
  a44=(a41*a23);
  a47=(a38*a55);
  a44=(a44+a47);
  a47=(a36*a59);
  a44=(a44+a47);
  a44=(a46*a44);
  a47=(a18*a44);
  a25=(a25-a47);
  a33=(a33+a25);
  a08=(a18*a08);
  a50=(a50+a08);
  a55=(a53*a55);
  a50=(a50-a55);
  a55=(a21*a44);
  a50=(a50-a55);
  a59=(a03*a59);
  a55=(a16*a59);
  a50=(a50-a55);
  a55=(a03*a50);
  a08=(a41*a55);
  a33=(a33+a08);
  a47=(a36*a25);
  a31=(a38*a50);
  a47=(a47+a31);
  a53=(a53*a23);
  a34=(a34-a53);
  a18=(a18*a52);
  a34=(a34-a18);
  a16=(a16*a44);
  a34=(a34-a16);
  a21=(a21*a59);
  a34=(a34+a21);
  a21=(a41*a34);
  a47=(a47+a21);
  a47=(a46*a47);
  a21=(a36*a47);
  a33=(a33+a21);
  a59=(a03*a34);
  a16=(a38*a59);
  a33=(a33-a16);
  a33=(a33/a00);
  if (res[0]!=0) res[0][3]=a33;
  a33=(a03*a25);
  a44=(a41*a33);
  a18=(a50-a44);
  a52=(a38*a47);
  a18=(a18+a52);
  a59=(a36*a59);
  a18=(a18+a59);
  a18=(a18/a00);
  if (res[0]!=0) res[0][4]=a18;
  a33=(a38*a33);
  a42=(a42+a39);
  a42=(a42/a15);
  a42=(a40*a42);
  a32=(a32-a42);
  a57=(a57*a32);
  a32=(a36*a38);
  a32=(a32/a15);
  a32=(a41+a32);
  a32=(a40*a32);
  a24=(a24*a32);
  a57=(a57+a24);
  a24=(a36*a41);
  a24=(a24/a15);
  a24=(a24-a38);
  a40=(a40*a24);
  a35=(a35*a40);
  a57=(a57+a35);
  a57=(a57*a07);
  a57=(a33-a57);
  a36=(a36*a55);
  a57=(a57-a36);
  a41=(a41*a47);
  a57=(a57+a41);
  a57=(a57+a34);
  a57=(a57/a00);
  if (res[0]!=0) res[0][5]=a57;
  a57=arg[2]? arg[2][0] : 0;
  a20=(a03*a20);
  a01=(a03*a01);
  a20=(a20+a01);
  a20=(a00*a20);
  a01=(a03*a51);
  a47=(a20*a01);
  a17=(a03*a17);
  a43=(a03*a43);
  a17=(a17+a43);
  a17=(a00*a17);
  a43=(a03*a22);
  a55=(a17*a43);
  a47=(a47-a55);
  a14=(a03*a14);
  a05=(a03*a05);
  a14=(a14+a05);
  a00=(a00*a14);
  a14=(a20*a22);
  a05=(a17*a51);
  a14=(a14+a05);
  a05=(a00*a58);
  a14=(a14+a05);
  a46=(a46*a14);
  a14=(a00*a46);
  a47=(a47-a14);
  a47=(a47-a58);
  a47=(a47-a25);
  a47=(a47+a08);
  a47=(a47-a21);
  a47=(a47-a16);
  a47=(a47+a13);
  a47=(a47-a45);
  a47=(a47-a19);
  a47=(a47-a27);
  a57=(a57+a47);
  if (res[0]!=0) res[0][6]=a57;
  a57=arg[2]? arg[2][1] : 0;
  a43=(a00*a43);
  a43=(a43-a51);
  a51=(a17*a46);
  a43=(a43-a51);
  a03=(a03*a58);
  a58=(a20*a03);
  a43=(a43-a58);
  a43=(a43-a44);
  a43=(a43-a50);
  a43=(a43-a52);
  a43=(a43+a59);
  a43=(a43-a49);
  a43=(a43+a26);
  a43=(a43-a54);
  a43=(a43-a56);
  a57=(a57+a43);
  if (res[0]!=0) res[0][7]=a57;
  a57=arg[2]? arg[2][2] : 0;
  a17=(a17*a03);
  a00=(a00*a01);
  a22=(a22+a00);
  a20=(a20*a46);
  a22=(a22+a20);
  a17=(a17-a22);
  a17=(a17+a33);
  a17=(a17-a36);
  a17=(a17-a41);
  a17=(a17-a34);
  a17=(a17-a29);
  a17=(a17-a30);
  a17=(a17-a28);
  a17=(a17+a48);
  a57=(a57+a17);
  if (res[0]!=0) res[0][8]=a57;
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
    case 1: return casadi_s0;
    case 2: return casadi_s1;
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

/* residual_jacobian:(z[9],g[9],p[3],h)->(F[9],J[81]) */
static int casadi_f1(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
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
  casadi_real a156, a157, a158, a159;
  a000=arg[3]? arg[3][0] : 0;
  a001=arg[0]? arg[0][2] : 0;
  a002=(a000*a001);
  a003=5.0000000000000000e-01;
  a004=4.;
  a005=arg[0]? arg[0][0] : 0;
  a006=(a000*a005);
  a007=casadi_sq(a006);
  a008=arg[0]? arg[0][1] : 0;
  a009=(a000*a008);
  a010=casadi_sq(a009);
  a011=(a007+a010);
  a012=casadi_sq(a002);
  a011=(a011+a012);
  a011=(a004+a011);
  a013=(a004/a011);
  a014=3.0000000000000004e+00;
  a015=(a014*a005);
  a016=4.6410161513775439e-01;
  a017=arg[0]? arg[0][3] : 0;
  a018=(a016*a017);
  a015=(a015+a018);
  a018=(a014*a008);
  a019=arg[0]? arg[0][4] : 0;
  a020=(a016*a019);
  a018=(a018+a020);
  a020=(a002*a018);
  a021=(a014*a001);
  a022=arg[0]? arg[0][5] : 0;
  a023=(a016*a022);
  a021=(a021+a023);
  a023=(a009*a021);
  a020=(a020-a023);
  a023=2.;
  a020=(a020/a023);
  a020=(a015+a020);
  a024=(a013*a020);
  a025=arg[0]? arg[0][8] : 0;
  a026=(a000*a025);
  a026=(a003*a026);
  a027=5.3867513459481287e-01;
  a028=2.3205080756887719e-01;
  a029=1.5234375000000000e+01;
  a030=(a009*a015);
  a031=(a006*a018);
  a030=(a030-a031);
  a030=(a030/a023);
  a030=(a021+a030);
  a031=(a013*a030);
  a032=(a029*a031);
  a033=(a029*a024);
  a034=(a009*a033);
  a035=4.6875000000000000e-01;
  a036=(a006*a021);
  a037=(a002*a015);
  a036=(a036-a037);
  a036=(a036/a023);
  a036=(a018+a036);
  a037=(a013*a036);
  a038=(a035*a037);
  a039=(a006*a038);
  a034=(a034-a039);
  a034=(a034/a023);
  a034=(a032-a034);
  a039=(a013*a034);
  a039=(a039-a025);
  a040=(a028*a039);
  a041=1.5000000000000002e+00;
  a042=(a000*a017);
  a043=casadi_sq(a042);
  a044=(a000*a019);
  a045=casadi_sq(a044);
  a046=(a043+a045);
  a047=(a000*a022);
  a048=casadi_sq(a047);
  a046=(a046+a048);
  a046=(a004+a046);
  a049=(a004/a046);
  a050=-6.4641016151377553e+00;
  a001=(a050*a001);
  a022=(a014*a022);
  a001=(a001+a022);
  a005=(a050*a005);
  a017=(a014*a017);
  a005=(a005+a017);
  a017=(a044*a005);
  a008=(a050*a008);
  a019=(a014*a019);
  a008=(a008+a019);
  a019=(a042*a008);
  a017=(a017-a019);
  a017=(a017/a023);
  a017=(a001+a017);
  a019=(a049*a017);
  a022=(a029*a019);
  a051=(a047*a008);
  a052=(a044*a001);
  a051=(a051-a052);
  a051=(a051/a023);
  a051=(a005+a051);
  a052=(a049*a051);
  a053=(a029*a052);
  a054=(a044*a053);
  a055=(a042*a001);
  a056=(a047*a005);
  a055=(a055-a056);
  a055=(a055/a023);
  a055=(a008+a055);
  a056=(a049*a055);
  a057=(a035*a056);
  a058=(a042*a057);
  a054=(a054-a058);
  a054=(a054/a023);
  a054=(a022-a054);
  a058=(a049*a054);
  a058=(a058-a025);
  a059=(a041*a058);
  a040=(a040+a059);
  a059=(a000*a040);
  a060=(a027*a059);
  a060=(a026+a060);
  a061=2.5000000000000000e-01;
  a039=(a041*a039);
  a062=-3.2320508075688776e+00;
  a058=(a062*a058);
  a039=(a039+a058);
  a058=(a000*a039);
  a063=(a061*a058);
  a060=(a060+a063);
  a063=(a003*a060);
  a064=(a024*a063);
  a065=(a006*a032);
  a066=(a002*a033);
  a065=(a065-a066);
  a065=(a065/a023);
  a065=(a038-a065);
  a066=(a013*a065);
  a067=arg[0]? arg[0][7] : 0;
  a066=(a066-a067);
  a068=(a041*a066);
  a069=(a042*a022);
  a070=(a047*a053);
  a069=(a069-a070);
  a069=(a069/a023);
  a069=(a057-a069);
  a070=(a049*a069);
  a070=(a070-a067);
  a071=(a062*a070);
  a068=(a068+a071);
  a064=(a064+a068);
  a071=(a006*a024);
  a072=(a009*a037);
  a071=(a071+a072);
  a072=(a002*a031);
  a071=(a071+a072);
  a071=(a071/a004);
  a072=(a000*a067);
  a072=(a003*a072);
  a066=(a028*a066);
  a070=(a041*a070);
  a066=(a066+a070);
  a070=(a000*a066);
  a073=(a027*a070);
  a073=(a072+a073);
  a068=(a000*a068);
  a074=(a061*a068);
  a073=(a073+a074);
  a074=(a071*a073);
  a064=(a064-a074);
  a074=(a002*a060);
  a075=(a009*a073);
  a074=(a074+a075);
  a075=arg[0]? arg[0][6] : 0;
  a076=(a000*a075);
  a076=(a003*a076);
  a077=(a002*a038);
  a078=(a009*a032);
  a077=(a077-a078);
  a077=(a077/a023);
  a077=(a033-a077);
  a078=(a013*a077);
  a078=(a078-a075);
  a079=(a028*a078);
  a080=(a047*a057);
  a081=(a044*a022);
  a080=(a080-a081);
  a080=(a080/a023);
  a080=(a053-a080);
  a081=(a049*a080);
  a081=(a081-a075);
  a082=(a041*a081);
  a079=(a079+a082);
  a082=(a000*a079);
  a083=(a027*a082);
  a083=(a076+a083);
  a078=(a041*a078);
  a081=(a062*a081);
  a078=(a078+a081);
  a081=(a000*a078);
  a084=(a061*a081);
  a083=(a083+a084);
  a084=(a006*a083);
  a074=(a074+a084);
  a074=(a061*a074);
  a084=(a037*a074);
  a064=(a064-a084);
  a084=(a003*a083);
  a085=(a031*a084);
  a064=(a064-a085);
  a085=(a003*a064);
  a086=(a002*a085);
  a087=(a071*a060);
  a039=(a039-a087);
  a087=(a003*a073);
  a088=(a024*a087);
  a039=(a039-a088);
  a088=(a031*a074);
  a039=(a039-a088);
  a088=(a037*a084);
  a039=(a039+a088);
  a088=(a003*a039);
  a089=(a009*a088);
  a090=(a086-a089);
  a091=(a009*a064);
  a092=(a002*a039);
  a091=(a091+a092);
  a092=(a031*a087);
  a093=(a037*a063);
  a092=(a092-a093);
  a092=(a092+a078);
  a078=(a071*a083);
  a092=(a092-a078);
  a078=(a024*a074);
  a092=(a092-a078);
  a078=(a006*a092);
  a091=(a091+a078);
  a091=(a061*a091);
  a078=(a006*a091);
  a090=(a090+a078);
  a090=(a090+a092);
  a093=arg[1]? arg[1][2] : 0;
  a094=(a002*a006);
  a094=(a094/a023);
  a094=(a009+a094);
  a095=(a013*a094);
  a095=(a093*a095);
  a096=arg[1]? arg[1][5] : 0;
  a097=(a002*a009);
  a097=(a097/a023);
  a097=(a097-a006);
  a098=(a013*a097);
  a098=(a096*a098);
  a095=(a095+a098);
  a098=arg[1]? arg[1][8] : 0;
  a099=1.;
  a007=(a010+a007);
  a007=(a007/a023);
  a100=(a013*a007);
  a100=(a099-a100);
  a100=(a098*a100);
  a095=(a095+a100);
  a100=-7.3575000000000003e+01;
  a100=(a100*a000);
  a095=(a095*a100);
  a090=(a090+a095);
  a090=(a090/a000);
  if (res[0]!=0) res[0][0]=a090;
  a090=(a006*a088);
  a095=(a064+a090);
  a101=(a009*a091);
  a095=(a095+a101);
  a102=(a003*a092);
  a103=(a002*a102);
  a095=(a095-a103);
  a095=(a095/a000);
  if (res[0]!=0) res[0][1]=a095;
  a095=(a006*a085);
  a104=(a039-a095);
  a105=(a002*a091);
  a104=(a104+a105);
  a106=(a009*a102);
  a104=(a104+a106);
  a012=(a012+a010);
  a012=(a012/a023);
  a010=(a013*a012);
  a010=(a099-a010);
  a010=(a093*a010);
  a107=(a006*a009);
  a107=(a107/a023);
  a107=(a002+a107);
  a108=(a013*a107);
  a108=(a096*a108);
  a010=(a010+a108);
  a108=(a006*a002);
  a108=(a108/a023);
  a108=(a108-a009);
  a109=(a013*a108);
  a109=(a098*a109);
  a010=(a010+a109);
  a010=(a010*a100);
  a104=(a104-a010);
  a104=(a104/a000);
  if (res[0]!=0) res[0][2]=a104;
  a104=(a047*a042);
  a104=(a104/a023);
  a104=(a044+a104);
  a010=(a049*a104);
  a010=(a093*a010);
  a109=(a047*a044);
  a109=(a109/a023);
  a109=(a109-a042);
  a110=(a049*a109);
  a110=(a096*a110);
  a010=(a010+a110);
  a043=(a045+a043);
  a043=(a043/a023);
  a110=(a049*a043);
  a110=(a099-a110);
  a110=(a098*a110);
  a010=(a010+a110);
  a010=(a010*a100);
  a059=(a061*a059);
  a026=(a026+a059);
  a059=-3.8675134594812879e-02;
  a058=(a059*a058);
  a026=(a026+a058);
  a058=(a003*a026);
  a110=(a056*a058);
  a079=(a079-a110);
  a070=(a061*a070);
  a072=(a072+a070);
  a068=(a059*a068);
  a072=(a072+a068);
  a068=(a003*a072);
  a070=(a019*a068);
  a079=(a079+a070);
  a070=(a042*a052);
  a110=(a044*a056);
  a070=(a070+a110);
  a110=(a047*a019);
  a070=(a070+a110);
  a070=(a070/a004);
  a082=(a061*a082);
  a076=(a076+a082);
  a081=(a059*a081);
  a076=(a076+a081);
  a081=(a070*a076);
  a079=(a079-a081);
  a081=(a047*a026);
  a082=(a044*a072);
  a081=(a081+a082);
  a082=(a042*a076);
  a081=(a081+a082);
  a081=(a061*a081);
  a082=(a052*a081);
  a079=(a079-a082);
  a010=(a010+a079);
  a082=(a052*a058);
  a066=(a066+a082);
  a082=(a070*a072);
  a066=(a066-a082);
  a082=(a056*a081);
  a066=(a066-a082);
  a082=(a003*a076);
  a004=(a019*a082);
  a066=(a066-a004);
  a004=(a003*a066);
  a110=(a047*a004);
  a010=(a010+a110);
  a111=(a042*a079);
  a112=(a044*a066);
  a111=(a111+a112);
  a112=(a070*a026);
  a040=(a040-a112);
  a112=(a052*a068);
  a040=(a040-a112);
  a112=(a019*a081);
  a040=(a040-a112);
  a112=(a056*a082);
  a040=(a040+a112);
  a112=(a047*a040);
  a111=(a111+a112);
  a111=(a061*a111);
  a112=(a042*a111);
  a010=(a010+a112);
  a113=(a003*a040);
  a114=(a044*a113);
  a010=(a010-a114);
  a010=(a010/a000);
  if (res[0]!=0) res[0][3]=a010;
  a010=(a003*a079);
  a115=(a047*a010);
  a116=(a066-a115);
  a117=(a044*a111);
  a116=(a116+a117);
  a118=(a042*a113);
  a116=(a116+a118);
  a116=(a116/a000);
  if (res[0]!=0) res[0][4]=a116;
  a116=(a044*a010);
  a048=(a048+a045);
  a048=(a048/a023);
  a045=(a049*a048);
  a045=(a099-a045);
  a045=(a093*a045);
  a119=(a042*a044);
  a119=(a119/a023);
  a119=(a047+a119);
  a120=(a049*a119);
  a120=(a096*a120);
  a045=(a045+a120);
  a120=(a042*a047);
  a120=(a120/a023);
  a120=(a120-a044);
  a023=(a049*a120);
  a023=(a098*a023);
  a045=(a045+a023);
  a045=(a045*a100);
  a045=(a116-a045);
  a023=(a042*a004);
  a045=(a045-a023);
  a121=(a047*a111);
  a045=(a045+a121);
  a045=(a045+a040);
  a045=(a045/a000);
  if (res[0]!=0) res[0][5]=a045;
  a045=arg[2]? arg[2][0] : 0;
  a122=(a003*a021);
  a123=(a003*a001);
  a122=(a122+a123);
  a122=(a000*a122);
  a123=(a003*a067);
  a124=(a122*a123);
  a125=(a003*a018);
  a126=(a003*a008);
  a125=(a125+a126);
  a125=(a000*a125);
  a126=(a003*a025);
  a127=(a125*a126);
  a124=(a124-a127);
  a127=(a003*a015);
  a128=(a003*a005);
  a127=(a127+a128);
  a127=(a000*a127);
  a128=(a122*a025);
  a129=(a125*a067);
  a128=(a128+a129);
  a129=(a127*a075);
  a128=(a128+a129);
  a128=(a061*a128);
  a129=(a127*a128);
  a124=(a124-a129);
  a124=(a124-a075);
  a124=(a124-a079);
  a124=(a124+a110);
  a124=(a124-a112);
  a124=(a124-a114);
  a124=(a124+a086);
  a124=(a124-a089);
  a124=(a124-a078);
  a124=(a124-a092);
  a045=(a045+a124);
  if (res[0]!=0) res[0][6]=a045;
  a045=arg[2]? arg[2][1] : 0;
  a124=(a127*a126);
  a124=(a124-a067);
  a078=(a125*a128);
  a124=(a124-a078);
  a078=(a003*a075);
  a089=(a122*a078);
  a124=(a124-a089);
  a124=(a124-a115);
  a124=(a124-a066);
  a124=(a124-a117);
  a124=(a124+a118);
  a124=(a124-a064);
  a124=(a124+a090);
  a124=(a124-a101);
  a124=(a124-a103);
  a045=(a045+a124);
  if (res[0]!=0) res[0][7]=a045;
  a045=arg[2]? arg[2][2] : 0;
  a124=(a125*a078);
  a103=(a127*a123);
  a103=(a025+a103);
  a101=(a122*a128);
  a103=(a103+a101);
  a124=(a124-a103);
  a124=(a124+a116);
  a124=(a124-a023);
  a124=(a124-a121);
  a124=(a124-a040);
  a124=(a124-a095);
  a124=(a124-a039);
  a124=(a124-a105);
  a124=(a124+a106);
  a045=(a045+a124);
  if (res[0]!=0) res[0][8]=a045;
  a045=(a014*a013);
  a011=(a013/a011);
  a124=(2.*a006);
  a124=(a124*a000);
  a106=(a011*a124);
  a105=(a020*a106);
  a105=(a045-a105);
  a095=(a063*a105);
  a121=(a014*a009);
  a018=(a018*a000);
  a023=(a121-a018);
  a023=(a003*a023);
  a023=(a013*a023);
  a116=(a030*a106);
  a023=(a023-a116);
  a116=(a029*a023);
  a103=(a029*a105);
  a101=(a009*a103);
  a038=(a038*a000);
  a021=(a021*a000);
  a090=(a014*a002);
  a118=(a021-a090);
  a118=(a003*a118);
  a118=(a013*a118);
  a117=(a036*a106);
  a118=(a118-a117);
  a117=(a035*a118);
  a115=(a006*a117);
  a115=(a038+a115);
  a101=(a101-a115);
  a101=(a003*a101);
  a101=(a116-a101);
  a101=(a013*a101);
  a115=(a034*a106);
  a101=(a101-a115);
  a115=(a028*a101);
  a089=(a062*a044);
  a089=(a049*a089);
  a086=(a029*a089);
  a114=-9.8476548043114235e+01;
  a114=(a114*a049);
  a112=(a044*a114);
  a110=(a062*a047);
  a110=(a049*a110);
  a129=(a035*a110);
  a130=(a042*a129);
  a130=(a112+a130);
  a130=(a003*a130);
  a130=(a086-a130);
  a130=(a049*a130);
  a131=(a041*a130);
  a115=(a115+a131);
  a131=(a000*a115);
  a132=(a027*a131);
  a101=(a041*a101);
  a130=(a062*a130);
  a101=(a101+a130);
  a130=(a000*a101);
  a133=(a061*a130);
  a132=(a132+a133);
  a133=(a003*a132);
  a134=(a024*a133);
  a095=(a095+a134);
  a032=(a032*a000);
  a134=(a006*a116);
  a134=(a032+a134);
  a135=(a002*a103);
  a134=(a134-a135);
  a134=(a003*a134);
  a134=(a117-a134);
  a134=(a013*a134);
  a135=(a065*a106);
  a134=(a134-a135);
  a135=(a041*a134);
  a136=(a042*a086);
  a137=(a047*a114);
  a136=(a136-a137);
  a136=(a003*a136);
  a136=(a129+a136);
  a136=(a049*a136);
  a137=(a062*a136);
  a135=(a135-a137);
  a095=(a095+a135);
  a137=(a024*a000);
  a138=(a006*a105);
  a137=(a137+a138);
  a138=(a009*a118);
  a137=(a137+a138);
  a138=(a002*a023);
  a137=(a137+a138);
  a137=(a061*a137);
  a138=(a073*a137);
  a134=(a028*a134);
  a136=(a041*a136);
  a134=(a134-a136);
  a136=(a000*a134);
  a139=(a027*a136);
  a135=(a000*a135);
  a140=(a061*a135);
  a139=(a139+a140);
  a140=(a071*a139);
  a138=(a138+a140);
  a095=(a095-a138);
  a138=(a074*a118);
  a140=(a002*a132);
  a141=(a009*a139);
  a140=(a140+a141);
  a141=(a083*a000);
  a117=(a002*a117);
  a116=(a009*a116);
  a117=(a117-a116);
  a117=(a003*a117);
  a103=(a103-a117);
  a103=(a013*a103);
  a117=(a077*a106);
  a103=(a103-a117);
  a117=(a028*a103);
  a129=(a047*a129);
  a116=(a044*a086);
  a129=(a129+a116);
  a129=(a003*a129);
  a129=(a114+a129);
  a129=(a049*a129);
  a142=(a041*a129);
  a117=(a117+a142);
  a142=(a000*a117);
  a143=(a027*a142);
  a103=(a041*a103);
  a129=(a062*a129);
  a103=(a103+a129);
  a129=(a000*a103);
  a144=(a061*a129);
  a143=(a143+a144);
  a144=(a006*a143);
  a141=(a141+a144);
  a140=(a140+a141);
  a140=(a061*a140);
  a141=(a037*a140);
  a138=(a138+a141);
  a095=(a095-a138);
  a138=(a084*a023);
  a141=(a003*a143);
  a144=(a031*a141);
  a138=(a138+a144);
  a095=(a095-a138);
  a138=(a003*a095);
  a144=(a002*a138);
  a145=(a060*a137);
  a132=(a071*a132);
  a145=(a145+a132);
  a101=(a101-a145);
  a145=(a087*a105);
  a139=(a003*a139);
  a132=(a024*a139);
  a145=(a145+a132);
  a101=(a101-a145);
  a145=(a074*a023);
  a132=(a031*a140);
  a145=(a145+a132);
  a101=(a101-a145);
  a145=(a084*a118);
  a141=(a037*a141);
  a145=(a145+a141);
  a101=(a101+a145);
  a145=(a003*a101);
  a141=(a009*a145);
  a132=(a144-a141);
  a091=(a091*a000);
  a146=(a009*a095);
  a147=(a002*a101);
  a146=(a146+a147);
  a092=(a092*a000);
  a023=(a087*a023);
  a139=(a031*a139);
  a023=(a023+a139);
  a118=(a063*a118);
  a133=(a037*a133);
  a118=(a118+a133);
  a023=(a023-a118);
  a023=(a023+a103);
  a137=(a083*a137);
  a143=(a071*a143);
  a137=(a137+a143);
  a023=(a023-a137);
  a105=(a074*a105);
  a140=(a024*a140);
  a105=(a105+a140);
  a023=(a023-a105);
  a105=(a006*a023);
  a092=(a092+a105);
  a146=(a146+a092);
  a146=(a061*a146);
  a092=(a006*a146);
  a092=(a091+a092);
  a132=(a132+a092);
  a132=(a132+a023);
  a105=(a002*a000);
  a105=(a003*a105);
  a105=(a013*a105);
  a140=(a094*a106);
  a140=(a105-a140);
  a140=(a093*a140);
  a137=(a097*a106);
  a143=(a013*a000);
  a137=(a137+a143);
  a137=(a096*a137);
  a140=(a140-a137);
  a124=(a003*a124);
  a124=(a013*a124);
  a137=(a007*a106);
  a124=(a124-a137);
  a124=(a098*a124);
  a140=(a140-a124);
  a140=(a100*a140);
  a132=(a132+a140);
  a132=(a132/a000);
  if (res[1]!=0) res[1][0]=a132;
  a088=(a088*a000);
  a145=(a006*a145);
  a145=(a088+a145);
  a132=(a095+a145);
  a140=(a009*a146);
  a132=(a132+a140);
  a124=(a003*a023);
  a137=(a002*a124);
  a132=(a132-a137);
  a132=(a132/a000);
  if (res[1]!=0) res[1][1]=a132;
  a085=(a085*a000);
  a138=(a006*a138);
  a138=(a085+a138);
  a132=(a101-a138);
  a146=(a002*a146);
  a132=(a132+a146);
  a124=(a009*a124);
  a132=(a132+a124);
  a103=(a012*a106);
  a103=(a093*a103);
  a118=(a009*a000);
  a118=(a003*a118);
  a118=(a013*a118);
  a133=(a107*a106);
  a133=(a118-a133);
  a133=(a096*a133);
  a103=(a103+a133);
  a106=(a108*a106);
  a106=(a105-a106);
  a106=(a098*a106);
  a103=(a103+a106);
  a103=(a100*a103);
  a132=(a132-a103);
  a132=(a132/a000);
  if (res[1]!=0) res[1][2]=a132;
  a131=(a061*a131);
  a130=(a059*a130);
  a131=(a131+a130);
  a130=(a003*a131);
  a132=(a056*a130);
  a103=(a058*a110);
  a132=(a132-a103);
  a117=(a117-a132);
  a132=(a068*a089);
  a136=(a061*a136);
  a135=(a059*a135);
  a136=(a136+a135);
  a135=(a003*a136);
  a106=(a019*a135);
  a106=(a132+a106);
  a117=(a117+a106);
  a050=(a050*a049);
  a106=(a042*a050);
  a133=(a044*a110);
  a106=(a106-a133);
  a133=(a047*a089);
  a106=(a106+a133);
  a106=(a061*a106);
  a133=(a076*a106);
  a142=(a061*a142);
  a129=(a059*a129);
  a142=(a142+a129);
  a129=(a070*a142);
  a133=(a133+a129);
  a117=(a117-a133);
  a133=(a081*a050);
  a129=(a047*a131);
  a139=(a044*a136);
  a129=(a129+a139);
  a139=(a042*a142);
  a129=(a129+a139);
  a129=(a061*a129);
  a139=(a052*a129);
  a139=(a133+a139);
  a117=(a117-a139);
  a139=(a058*a050);
  a130=(a052*a130);
  a130=(a139+a130);
  a134=(a134+a130);
  a130=(a072*a106);
  a136=(a070*a136);
  a130=(a130+a136);
  a134=(a134-a130);
  a130=(a056*a129);
  a136=(a081*a110);
  a130=(a130-a136);
  a134=(a134-a130);
  a130=(a082*a089);
  a142=(a003*a142);
  a147=(a019*a142);
  a130=(a130+a147);
  a134=(a134-a130);
  a130=(a003*a134);
  a147=(a047*a130);
  a148=(a117+a147);
  a149=(a042*a117);
  a150=(a044*a134);
  a149=(a149+a150);
  a106=(a026*a106);
  a131=(a070*a131);
  a106=(a106+a131);
  a115=(a115-a106);
  a106=(a068*a050);
  a135=(a052*a135);
  a135=(a106+a135);
  a115=(a115-a135);
  a135=(a081*a089);
  a129=(a019*a129);
  a129=(a135+a129);
  a115=(a115-a129);
  a142=(a056*a142);
  a129=(a082*a110);
  a142=(a142-a129);
  a115=(a115+a142);
  a142=(a047*a115);
  a149=(a149+a142);
  a149=(a061*a149);
  a142=(a042*a149);
  a148=(a148+a142);
  a129=(a003*a115);
  a131=(a044*a129);
  a148=(a148-a131);
  a148=(a148/a000);
  if (res[1]!=0) res[1][3]=a148;
  a148=(a003*a117);
  a150=(a047*a148);
  a151=(a134-a150);
  a152=(a044*a149);
  a151=(a151+a152);
  a129=(a042*a129);
  a151=(a151+a129);
  a151=(a151/a000);
  if (res[1]!=0) res[1][4]=a151;
  a148=(a044*a148);
  a130=(a042*a130);
  a151=(a148-a130);
  a149=(a047*a149);
  a151=(a151+a149);
  a151=(a151+a115);
  a151=(a151/a000);
  if (res[1]!=0) res[1][5]=a151;
  a151=-1.7320508075688774e+00;
  a153=(a151*a000);
  a154=(a128*a153);
  a155=(a075*a153);
  a155=(a061*a155);
  a156=(a127*a155);
  a156=(a154+a156);
  a156=(a156+a117);
  a147=(a147-a156);
  a147=(a147-a142);
  a147=(a147-a131);
  a147=(a147+a144);
  a147=(a147-a141);
  a147=(a147-a092);
  a147=(a147-a023);
  if (res[1]!=0) res[1][6]=a147;
  a147=(a126*a153);
  a023=(a125*a155);
  a023=(a147-a023);
  a023=(a023-a150);
  a023=(a023-a134);
  a023=(a023-a152);
  a023=(a023+a129);
  a023=(a023-a095);
  a023=(a023+a145);
  a023=(a023-a140);
  a023=(a023-a137);
  if (res[1]!=0) res[1][7]=a023;
  a023=(a123*a153);
  a155=(a122*a155);
  a155=(a023+a155);
  a148=(a148-a155);
  a148=(a148-a130);
  a148=(a148-a149);
  a148=(a148-a115);
  a148=(a148-a138);
  a148=(a148-a101);
  a148=(a148-a146);
  a148=(a148+a124);
  if (res[1]!=0) res[1][8]=a148;
  a090=(a090-a021);
  a090=(a003*a090);
  a090=(a013*a090);
  a021=(2.*a009);
  a021=(a021*a000);
  a148=(a011*a021);
  a124=(a020*a148);
  a090=(a090-a124);
  a124=(a063*a090);
  a015=(a015*a000);
  a146=(a014*a006);
  a101=(a015-a146);
  a101=(a003*a101);
  a101=(a013*a101);
  a138=(a030*a148);
  a101=(a101-a138);
  a138=(a029*a101);
  a033=(a033*a000);
  a115=(a029*a090);
  a149=(a009*a115);
  a149=(a033+a149);
  a130=(a036*a148);
  a130=(a045-a130);
  a155=(a035*a130);
  a137=(a006*a155);
  a149=(a149-a137);
  a149=(a003*a149);
  a149=(a138-a149);
  a149=(a013*a149);
  a137=(a034*a148);
  a149=(a149-a137);
  a137=(a028*a149);
  a140=(a062*a042);
  a140=(a049*a140);
  a145=(a029*a140);
  a095=(a029*a110);
  a129=(a044*a095);
  a152=-3.0300476320958230e+00;
  a152=(a152*a049);
  a134=(a042*a152);
  a129=(a129-a134);
  a129=(a003*a129);
  a129=(a145+a129);
  a129=(a049*a129);
  a134=(a041*a129);
  a137=(a137-a134);
  a134=(a000*a137);
  a150=(a027*a134);
  a149=(a041*a149);
  a129=(a062*a129);
  a149=(a149-a129);
  a129=(a000*a149);
  a092=(a061*a129);
  a150=(a150+a092);
  a092=(a003*a150);
  a141=(a024*a092);
  a124=(a124+a141);
  a141=(a006*a138);
  a144=(a002*a115);
  a141=(a141-a144);
  a141=(a003*a141);
  a141=(a155-a141);
  a141=(a013*a141);
  a144=(a065*a148);
  a141=(a141-a144);
  a144=(a041*a141);
  a131=(a042*a145);
  a142=(a047*a095);
  a131=(a131+a142);
  a131=(a003*a131);
  a131=(a152+a131);
  a131=(a049*a131);
  a142=(a062*a131);
  a144=(a144+a142);
  a124=(a124+a144);
  a142=(a006*a090);
  a156=(a037*a000);
  a117=(a009*a130);
  a156=(a156+a117);
  a142=(a142+a156);
  a156=(a002*a101);
  a142=(a142+a156);
  a142=(a061*a142);
  a156=(a073*a142);
  a141=(a028*a141);
  a131=(a041*a131);
  a141=(a141+a131);
  a131=(a000*a141);
  a117=(a027*a131);
  a144=(a000*a144);
  a157=(a061*a144);
  a117=(a117+a157);
  a157=(a071*a117);
  a156=(a156+a157);
  a124=(a124-a156);
  a156=(a074*a130);
  a157=(a002*a150);
  a158=(a073*a000);
  a159=(a009*a117);
  a158=(a158+a159);
  a157=(a157+a158);
  a155=(a002*a155);
  a138=(a009*a138);
  a032=(a032+a138);
  a155=(a155-a032);
  a155=(a003*a155);
  a115=(a115-a155);
  a115=(a013*a115);
  a155=(a077*a148);
  a115=(a115-a155);
  a155=(a028*a115);
  a152=(a047*a152);
  a145=(a044*a145);
  a152=(a152+a145);
  a152=(a003*a152);
  a095=(a095-a152);
  a095=(a049*a095);
  a152=(a041*a095);
  a155=(a155+a152);
  a152=(a000*a155);
  a145=(a027*a152);
  a115=(a041*a115);
  a095=(a062*a095);
  a115=(a115+a095);
  a095=(a000*a115);
  a032=(a061*a095);
  a145=(a145+a032);
  a032=(a006*a145);
  a157=(a157+a032);
  a157=(a061*a157);
  a032=(a037*a157);
  a156=(a156+a032);
  a124=(a124-a156);
  a156=(a084*a101);
  a032=(a003*a145);
  a138=(a031*a032);
  a156=(a156+a138);
  a124=(a124-a156);
  a156=(a003*a124);
  a138=(a002*a156);
  a158=(a060*a142);
  a150=(a071*a150);
  a158=(a158+a150);
  a149=(a149-a158);
  a158=(a087*a090);
  a117=(a003*a117);
  a150=(a024*a117);
  a158=(a158+a150);
  a149=(a149-a158);
  a158=(a074*a101);
  a150=(a031*a157);
  a158=(a158+a150);
  a149=(a149-a158);
  a158=(a084*a130);
  a032=(a037*a032);
  a158=(a158+a032);
  a149=(a149+a158);
  a158=(a003*a149);
  a032=(a009*a158);
  a088=(a088+a032);
  a032=(a138-a088);
  a064=(a064*a000);
  a150=(a009*a124);
  a064=(a064+a150);
  a150=(a002*a149);
  a064=(a064+a150);
  a101=(a087*a101);
  a117=(a031*a117);
  a101=(a101+a117);
  a130=(a063*a130);
  a092=(a037*a092);
  a130=(a130+a092);
  a101=(a101-a130);
  a101=(a101+a115);
  a142=(a083*a142);
  a145=(a071*a145);
  a142=(a142+a145);
  a101=(a101-a142);
  a090=(a074*a090);
  a157=(a024*a157);
  a090=(a090+a157);
  a101=(a101-a090);
  a090=(a006*a101);
  a064=(a064+a090);
  a064=(a061*a064);
  a090=(a006*a064);
  a032=(a032+a090);
  a032=(a032+a101);
  a157=(a094*a148);
  a157=(a143-a157);
  a157=(a093*a157);
  a142=(a097*a148);
  a105=(a105-a142);
  a105=(a096*a105);
  a157=(a157+a105);
  a021=(a003*a021);
  a021=(a013*a021);
  a105=(a007*a148);
  a105=(a021-a105);
  a105=(a098*a105);
  a157=(a157-a105);
  a157=(a100*a157);
  a032=(a032+a157);
  a032=(a032/a000);
  if (res[1]!=0) res[1][9]=a032;
  a158=(a006*a158);
  a032=(a124+a158);
  a157=(a009*a064);
  a157=(a091+a157);
  a032=(a032+a157);
  a105=(a003*a101);
  a142=(a002*a105);
  a032=(a032-a142);
  a032=(a032/a000);
  if (res[1]!=0) res[1][10]=a032;
  a156=(a006*a156);
  a032=(a149-a156);
  a064=(a002*a064);
  a032=(a032+a064);
  a102=(a102*a000);
  a105=(a009*a105);
  a105=(a102+a105);
  a032=(a032+a105);
  a145=(a006*a000);
  a145=(a003*a145);
  a145=(a013*a145);
  a115=(a107*a148);
  a115=(a145-a115);
  a115=(a096*a115);
  a130=(a012*a148);
  a021=(a021-a130);
  a021=(a093*a021);
  a115=(a115-a021);
  a148=(a108*a148);
  a148=(a148+a143);
  a148=(a098*a148);
  a115=(a115-a148);
  a115=(a100*a115);
  a032=(a032-a115);
  a032=(a032/a000);
  if (res[1]!=0) res[1][11]=a032;
  a134=(a061*a134);
  a129=(a059*a129);
  a134=(a134+a129);
  a129=(a003*a134);
  a032=(a056*a129);
  a139=(a139+a032);
  a155=(a155-a139);
  a131=(a061*a131);
  a144=(a059*a144);
  a131=(a131+a144);
  a144=(a003*a131);
  a139=(a019*a144);
  a032=(a068*a140);
  a139=(a139-a032);
  a155=(a155+a139);
  a139=(a042*a110);
  a032=(a044*a050);
  a139=(a139+a032);
  a032=(a047*a140);
  a139=(a139-a032);
  a139=(a061*a139);
  a032=(a076*a139);
  a152=(a061*a152);
  a095=(a059*a095);
  a152=(a152+a095);
  a095=(a070*a152);
  a032=(a032+a095);
  a155=(a155-a032);
  a032=(a047*a134);
  a095=(a044*a131);
  a032=(a032+a095);
  a095=(a042*a152);
  a032=(a032+a095);
  a032=(a061*a032);
  a095=(a052*a032);
  a136=(a136+a095);
  a155=(a155-a136);
  a129=(a052*a129);
  a103=(a103+a129);
  a141=(a141+a103);
  a103=(a072*a139);
  a131=(a070*a131);
  a103=(a103+a131);
  a141=(a141-a103);
  a103=(a056*a032);
  a103=(a133+a103);
  a141=(a141-a103);
  a152=(a003*a152);
  a103=(a019*a152);
  a131=(a082*a140);
  a103=(a103-a131);
  a141=(a141-a103);
  a103=(a003*a141);
  a129=(a047*a103);
  a136=(a155+a129);
  a095=(a042*a155);
  a115=(a044*a141);
  a095=(a095+a115);
  a139=(a026*a139);
  a134=(a070*a134);
  a139=(a139+a134);
  a137=(a137-a139);
  a110=(a068*a110);
  a144=(a052*a144);
  a110=(a110+a144);
  a137=(a137-a110);
  a032=(a019*a032);
  a110=(a081*a140);
  a032=(a032-a110);
  a137=(a137-a032);
  a032=(a082*a050);
  a152=(a056*a152);
  a152=(a032+a152);
  a137=(a137+a152);
  a152=(a047*a137);
  a095=(a095+a152);
  a095=(a061*a095);
  a152=(a042*a095);
  a136=(a136+a152);
  a144=(a003*a137);
  a139=(a044*a144);
  a136=(a136-a139);
  a136=(a136/a000);
  if (res[1]!=0) res[1][12]=a136;
  a136=(a003*a155);
  a134=(a047*a136);
  a115=(a141-a134);
  a148=(a044*a095);
  a115=(a115+a148);
  a144=(a042*a144);
  a115=(a115+a144);
  a115=(a115/a000);
  if (res[1]!=0) res[1][13]=a115;
  a136=(a044*a136);
  a103=(a042*a103);
  a115=(a136-a103);
  a095=(a047*a095);
  a115=(a115+a095);
  a115=(a115+a137);
  a115=(a115/a000);
  if (res[1]!=0) res[1][14]=a115;
  a115=(a067*a153);
  a115=(a061*a115);
  a021=(a127*a115);
  a147=(a147+a021);
  a147=(a147+a155);
  a129=(a129-a147);
  a129=(a129-a152);
  a129=(a129-a139);
  a129=(a129+a138);
  a129=(a129-a088);
  a129=(a129-a090);
  a129=(a129-a101);
  if (res[1]!=0) res[1][15]=a129;
  a129=(a125*a115);
  a129=(a154+a129);
  a129=(a129+a134);
  a129=(a129+a141);
  a129=(a129+a148);
  a144=(a144-a129);
  a144=(a144-a124);
  a144=(a144+a158);
  a144=(a144-a157);
  a144=(a144-a142);
  if (res[1]!=0) res[1][16]=a144;
  a144=(a078*a153);
  a115=(a122*a115);
  a115=(a144-a115);
  a115=(a115+a136);
  a115=(a115-a103);
  a115=(a115-a095);
  a115=(a115-a137);
  a115=(a115-a156);
  a115=(a115-a149);
  a115=(a115-a064);
  a115=(a115+a105);
  if (res[1]!=0) res[1][17]=a115;
  a018=(a018-a121);
  a018=(a003*a018);
  a018=(a013*a018);
  a121=(2.*a002);
  a121=(a121*a000);
  a011=(a011*a121);
  a020=(a020*a011);
  a018=(a018-a020);
  a020=(a063*a018);
  a030=(a030*a011);
  a045=(a045-a030);
  a030=(a029*a045);
  a115=(a029*a018);
  a105=(a009*a115);
  a146=(a146-a015);
  a146=(a003*a146);
  a146=(a013*a146);
  a036=(a036*a011);
  a146=(a146-a036);
  a036=(a035*a146);
  a015=(a006*a036);
  a105=(a105-a015);
  a105=(a003*a105);
  a105=(a030-a105);
  a105=(a013*a105);
  a034=(a034*a011);
  a105=(a105-a034);
  a034=(a028*a105);
  a015=(a035*a140);
  a064=(a042*a015);
  a116=(a116+a064);
  a116=(a003*a116);
  a116=(a114+a116);
  a116=(a049*a116);
  a064=(a041*a116);
  a034=(a034+a064);
  a064=(a000*a034);
  a149=(a027*a064);
  a105=(a041*a105);
  a116=(a062*a116);
  a105=(a105+a116);
  a116=(a000*a105);
  a156=(a061*a116);
  a149=(a149+a156);
  a156=(a003*a149);
  a137=(a024*a156);
  a020=(a020+a137);
  a137=(a006*a030);
  a095=(a002*a115);
  a033=(a033+a095);
  a137=(a137-a033);
  a137=(a003*a137);
  a137=(a036-a137);
  a137=(a013*a137);
  a065=(a065*a011);
  a137=(a137-a065);
  a065=(a041*a137);
  a114=(a042*a114);
  a033=(a047*a086);
  a114=(a114+a033);
  a114=(a003*a114);
  a114=(a015-a114);
  a114=(a049*a114);
  a033=(a062*a114);
  a065=(a065+a033);
  a020=(a020+a065);
  a033=(a006*a018);
  a095=(a009*a146);
  a033=(a033+a095);
  a095=(a031*a000);
  a103=(a002*a045);
  a095=(a095+a103);
  a033=(a033+a095);
  a033=(a061*a033);
  a095=(a073*a033);
  a137=(a028*a137);
  a114=(a041*a114);
  a137=(a137+a114);
  a114=(a000*a137);
  a103=(a027*a114);
  a065=(a000*a065);
  a136=(a061*a065);
  a103=(a103+a136);
  a136=(a071*a103);
  a095=(a095+a136);
  a020=(a020-a095);
  a095=(a074*a146);
  a136=(a060*a000);
  a142=(a002*a149);
  a136=(a136+a142);
  a142=(a009*a103);
  a136=(a136+a142);
  a036=(a002*a036);
  a038=(a038+a036);
  a030=(a009*a030);
  a038=(a038-a030);
  a038=(a003*a038);
  a115=(a115-a038);
  a115=(a013*a115);
  a077=(a077*a011);
  a115=(a115-a077);
  a077=(a028*a115);
  a015=(a047*a015);
  a015=(a015-a112);
  a015=(a003*a015);
  a086=(a086+a015);
  a086=(a049*a086);
  a015=(a041*a086);
  a077=(a077-a015);
  a015=(a000*a077);
  a112=(a027*a015);
  a115=(a041*a115);
  a086=(a062*a086);
  a115=(a115-a086);
  a086=(a000*a115);
  a038=(a061*a086);
  a112=(a112+a038);
  a038=(a006*a112);
  a136=(a136+a038);
  a136=(a061*a136);
  a038=(a037*a136);
  a095=(a095+a038);
  a020=(a020-a095);
  a095=(a084*a045);
  a038=(a003*a112);
  a030=(a031*a038);
  a095=(a095+a030);
  a020=(a020-a095);
  a095=(a003*a020);
  a030=(a002*a095);
  a085=(a085+a030);
  a030=(a060*a033);
  a149=(a071*a149);
  a030=(a030+a149);
  a105=(a105-a030);
  a030=(a087*a018);
  a103=(a003*a103);
  a149=(a024*a103);
  a030=(a030+a149);
  a105=(a105-a030);
  a030=(a074*a045);
  a149=(a031*a136);
  a030=(a030+a149);
  a105=(a105-a030);
  a030=(a084*a146);
  a038=(a037*a038);
  a030=(a030+a038);
  a105=(a105+a030);
  a030=(a003*a105);
  a038=(a009*a030);
  a149=(a085-a038);
  a036=(a009*a020);
  a039=(a039*a000);
  a142=(a002*a105);
  a039=(a039+a142);
  a036=(a036+a039);
  a045=(a087*a045);
  a103=(a031*a103);
  a045=(a045+a103);
  a146=(a063*a146);
  a156=(a037*a156);
  a146=(a146+a156);
  a045=(a045-a146);
  a045=(a045+a115);
  a033=(a083*a033);
  a112=(a071*a112);
  a033=(a033+a112);
  a045=(a045-a033);
  a018=(a074*a018);
  a136=(a024*a136);
  a018=(a018+a136);
  a045=(a045-a018);
  a018=(a006*a045);
  a036=(a036+a018);
  a036=(a061*a036);
  a018=(a006*a036);
  a149=(a149+a018);
  a149=(a149+a045);
  a094=(a094*a011);
  a094=(a145-a094);
  a094=(a093*a094);
  a097=(a097*a011);
  a118=(a118-a097);
  a118=(a096*a118);
  a094=(a094+a118);
  a007=(a007*a011);
  a007=(a098*a007);
  a094=(a094+a007);
  a094=(a100*a094);
  a149=(a149+a094);
  a149=(a149/a000);
  if (res[1]!=0) res[1][18]=a149;
  a030=(a006*a030);
  a149=(a020+a030);
  a094=(a009*a036);
  a149=(a149+a094);
  a007=(a003*a045);
  a118=(a002*a007);
  a102=(a102+a118);
  a149=(a149-a102);
  a149=(a149/a000);
  if (res[1]!=0) res[1][19]=a149;
  a095=(a006*a095);
  a149=(a105-a095);
  a036=(a002*a036);
  a091=(a091+a036);
  a149=(a149+a091);
  a007=(a009*a007);
  a149=(a149+a007);
  a107=(a107*a011);
  a143=(a143-a107);
  a143=(a096*a143);
  a121=(a003*a121);
  a121=(a013*a121);
  a012=(a012*a011);
  a121=(a121-a012);
  a121=(a093*a121);
  a143=(a143-a121);
  a108=(a108*a011);
  a145=(a145-a108);
  a145=(a098*a145);
  a143=(a143+a145);
  a143=(a100*a143);
  a149=(a149-a143);
  a149=(a149/a000);
  if (res[1]!=0) res[1][20]=a149;
  a149=(a058*a140);
  a064=(a061*a064);
  a116=(a059*a116);
  a064=(a064+a116);
  a116=(a003*a064);
  a143=(a056*a116);
  a149=(a149+a143);
  a077=(a077-a149);
  a114=(a061*a114);
  a065=(a059*a065);
  a114=(a114+a065);
  a065=(a003*a114);
  a149=(a019*a065);
  a106=(a106+a149);
  a077=(a077+a106);
  a140=(a044*a140);
  a106=(a042*a089);
  a140=(a140-a106);
  a050=(a047*a050);
  a140=(a140+a050);
  a140=(a061*a140);
  a050=(a076*a140);
  a015=(a061*a015);
  a086=(a059*a086);
  a015=(a015+a086);
  a086=(a070*a015);
  a050=(a050+a086);
  a077=(a077-a050);
  a050=(a047*a064);
  a086=(a044*a114);
  a050=(a050+a086);
  a086=(a042*a015);
  a050=(a050+a086);
  a050=(a061*a050);
  a086=(a052*a050);
  a086=(a086-a135);
  a077=(a077-a086);
  a116=(a052*a116);
  a089=(a058*a089);
  a116=(a116-a089);
  a137=(a137+a116);
  a116=(a072*a140);
  a114=(a070*a114);
  a116=(a116+a114);
  a137=(a137-a116);
  a116=(a056*a050);
  a110=(a110+a116);
  a137=(a137-a110);
  a015=(a003*a015);
  a110=(a019*a015);
  a032=(a032+a110);
  a137=(a137-a032);
  a032=(a003*a137);
  a110=(a047*a032);
  a116=(a077+a110);
  a114=(a042*a077);
  a089=(a044*a137);
  a114=(a114+a089);
  a140=(a026*a140);
  a064=(a070*a064);
  a140=(a140+a064);
  a034=(a034-a140);
  a065=(a052*a065);
  a065=(a065-a132);
  a034=(a034-a065);
  a050=(a019*a050);
  a133=(a133+a050);
  a034=(a034-a133);
  a015=(a056*a015);
  a131=(a131+a015);
  a034=(a034+a131);
  a131=(a047*a034);
  a114=(a114+a131);
  a114=(a061*a114);
  a131=(a042*a114);
  a116=(a116+a131);
  a015=(a003*a034);
  a133=(a044*a015);
  a116=(a116-a133);
  a116=(a116/a000);
  if (res[1]!=0) res[1][21]=a116;
  a116=(a003*a077);
  a050=(a047*a116);
  a065=(a137-a050);
  a132=(a044*a114);
  a065=(a065+a132);
  a015=(a042*a015);
  a065=(a065+a015);
  a065=(a065/a000);
  if (res[1]!=0) res[1][22]=a065;
  a116=(a044*a116);
  a032=(a042*a032);
  a065=(a116-a032);
  a114=(a047*a114);
  a065=(a065+a114);
  a065=(a065+a034);
  a065=(a065/a000);
  if (res[1]!=0) res[1][23]=a065;
  a153=(a025*a153);
  a153=(a061*a153);
  a065=(a127*a153);
  a023=(a023-a065);
  a023=(a023-a077);
  a023=(a023+a110);
  a023=(a023-a131);
  a023=(a023-a133);
  a023=(a023+a085);
  a023=(a023-a038);
  a023=(a023-a018);
  a023=(a023-a045);
  if (res[1]!=0) res[1][24]=a023;
  a023=(a125*a153);
  a023=(a023+a144);
  a023=(a023+a050);
  a023=(a023+a137);
  a023=(a023+a132);
  a015=(a015-a023);
  a015=(a015-a020);
  a015=(a015+a030);
  a015=(a015-a094);
  a015=(a015-a102);
  if (res[1]!=0) res[1][25]=a015;
  a153=(a122*a153);
  a154=(a154+a153);
  a116=(a116-a154);
  a116=(a116-a032);
  a116=(a116-a114);
  a116=(a116-a034);
  a116=(a116-a095);
  a116=(a116-a105);
  a116=(a116-a091);
  a116=(a116+a007);
  if (res[1]!=0) res[1][26]=a116;
  a016=(a016*a013);
  a116=(a063*a016);
  a007=(a028*a009);
  a007=(a013*a007);
  a091=(a029*a007);
  a105=7.0702980431142270e+00;
  a105=(a105*a013);
  a095=(a009*a105);
  a034=(a028*a002);
  a034=(a013*a034);
  a114=(a035*a034);
  a032=(a006*a114);
  a032=(a095+a032);
  a032=(a003*a032);
  a032=(a091-a032);
  a032=(a013*a032);
  a154=(a028*a032);
  a153=(a014*a044);
  a008=(a008*a000);
  a015=(a153-a008);
  a015=(a003*a015);
  a015=(a049*a015);
  a046=(a049/a046);
  a102=(2.*a042);
  a102=(a102*a000);
  a094=(a046*a102);
  a030=(a017*a094);
  a015=(a015-a030);
  a030=(a029*a015);
  a020=(a014*a049);
  a023=(a051*a094);
  a023=(a020-a023);
  a132=(a029*a023);
  a137=(a044*a132);
  a057=(a057*a000);
  a001=(a001*a000);
  a050=(a014*a047);
  a144=(a001-a050);
  a144=(a003*a144);
  a144=(a049*a144);
  a045=(a055*a094);
  a144=(a144-a045);
  a045=(a035*a144);
  a018=(a042*a045);
  a018=(a057+a018);
  a137=(a137-a018);
  a137=(a003*a137);
  a137=(a030-a137);
  a137=(a049*a137);
  a018=(a054*a094);
  a137=(a137-a018);
  a018=(a041*a137);
  a154=(a154+a018);
  a018=(a000*a154);
  a038=(a027*a018);
  a032=(a041*a032);
  a137=(a062*a137);
  a032=(a032+a137);
  a137=(a000*a032);
  a085=(a061*a137);
  a038=(a038+a085);
  a085=(a003*a038);
  a133=(a024*a085);
  a133=(a116+a133);
  a022=(a022*a000);
  a131=(a042*a030);
  a131=(a022+a131);
  a110=(a047*a132);
  a131=(a131-a110);
  a131=(a003*a131);
  a131=(a045-a131);
  a131=(a049*a131);
  a110=(a069*a094);
  a131=(a131-a110);
  a110=(a062*a131);
  a077=(a006*a091);
  a065=(a002*a105);
  a077=(a077-a065);
  a077=(a003*a077);
  a077=(a114+a077);
  a077=(a013*a077);
  a065=(a041*a077);
  a110=(a110-a065);
  a133=(a133+a110);
  a065=(a006*a016);
  a140=(a009*a034);
  a065=(a065-a140);
  a140=(a002*a007);
  a065=(a065+a140);
  a065=(a061*a065);
  a140=(a073*a065);
  a131=(a041*a131);
  a077=(a028*a077);
  a131=(a131-a077);
  a077=(a000*a131);
  a064=(a027*a077);
  a110=(a000*a110);
  a089=(a061*a110);
  a064=(a064+a089);
  a089=(a071*a064);
  a140=(a140+a089);
  a133=(a133-a140);
  a140=(a002*a038);
  a089=(a009*a064);
  a140=(a140+a089);
  a114=(a002*a114);
  a089=(a009*a091);
  a114=(a114+a089);
  a114=(a003*a114);
  a114=(a105+a114);
  a114=(a013*a114);
  a086=(a028*a114);
  a045=(a047*a045);
  a030=(a044*a030);
  a045=(a045-a030);
  a045=(a003*a045);
  a132=(a132-a045);
  a132=(a049*a132);
  a045=(a080*a094);
  a132=(a132-a045);
  a045=(a041*a132);
  a086=(a086+a045);
  a045=(a000*a086);
  a030=(a027*a045);
  a114=(a041*a114);
  a132=(a062*a132);
  a114=(a114+a132);
  a132=(a000*a114);
  a135=(a061*a132);
  a030=(a030+a135);
  a135=(a006*a030);
  a140=(a140+a135);
  a140=(a061*a140);
  a135=(a037*a140);
  a106=(a074*a034);
  a135=(a135-a106);
  a133=(a133-a135);
  a135=(a084*a007);
  a149=(a003*a030);
  a143=(a031*a149);
  a135=(a135+a143);
  a133=(a133-a135);
  a135=(a003*a133);
  a143=(a002*a135);
  a145=(a060*a065);
  a038=(a071*a038);
  a145=(a145+a038);
  a032=(a032-a145);
  a145=(a087*a016);
  a064=(a003*a064);
  a038=(a024*a064);
  a038=(a145+a038);
  a032=(a032-a038);
  a038=(a074*a007);
  a108=(a031*a140);
  a108=(a038+a108);
  a032=(a032-a108);
  a149=(a037*a149);
  a108=(a084*a034);
  a149=(a149-a108);
  a032=(a032+a149);
  a149=(a003*a032);
  a108=(a009*a149);
  a011=(a143-a108);
  a121=(a009*a133);
  a012=(a002*a032);
  a121=(a121+a012);
  a012=(a087*a007);
  a064=(a031*a064);
  a064=(a012+a064);
  a085=(a037*a085);
  a107=(a063*a034);
  a085=(a085-a107);
  a064=(a064-a085);
  a064=(a064+a114);
  a065=(a083*a065);
  a030=(a071*a030);
  a065=(a065+a030);
  a064=(a064-a065);
  a065=(a074*a016);
  a140=(a024*a140);
  a140=(a065+a140);
  a064=(a064-a140);
  a140=(a006*a064);
  a121=(a121+a140);
  a121=(a061*a121);
  a140=(a006*a121);
  a011=(a011+a140);
  a011=(a011+a064);
  a011=(a011/a000);
  if (res[1]!=0) res[1][27]=a011;
  a149=(a006*a149);
  a011=(a133+a149);
  a030=(a009*a121);
  a011=(a011+a030);
  a114=(a003*a064);
  a085=(a002*a114);
  a011=(a011-a085);
  a011=(a011/a000);
  if (res[1]!=0) res[1][28]=a011;
  a135=(a006*a135);
  a011=(a032-a135);
  a121=(a002*a121);
  a011=(a011+a121);
  a114=(a009*a114);
  a011=(a011+a114);
  a011=(a011/a000);
  if (res[1]!=0) res[1][29]=a011;
  a011=(a047*a000);
  a011=(a003*a011);
  a011=(a049*a011);
  a036=(a104*a094);
  a036=(a011-a036);
  a036=(a093*a036);
  a118=(a109*a094);
  a097=(a049*a000);
  a118=(a118+a097);
  a118=(a096*a118);
  a036=(a036-a118);
  a102=(a003*a102);
  a102=(a049*a102);
  a118=(a043*a094);
  a102=(a102-a118);
  a102=(a098*a102);
  a036=(a036-a102);
  a036=(a100*a036);
  a102=(a058*a144);
  a018=(a061*a018);
  a137=(a059*a137);
  a018=(a018+a137);
  a137=(a003*a018);
  a118=(a056*a137);
  a102=(a102+a118);
  a086=(a086-a102);
  a102=(a068*a015);
  a077=(a061*a077);
  a110=(a059*a110);
  a077=(a077+a110);
  a110=(a003*a077);
  a118=(a019*a110);
  a102=(a102+a118);
  a086=(a086+a102);
  a102=(a052*a000);
  a118=(a042*a023);
  a102=(a102+a118);
  a118=(a044*a144);
  a102=(a102+a118);
  a118=(a047*a015);
  a102=(a102+a118);
  a102=(a061*a102);
  a118=(a076*a102);
  a045=(a061*a045);
  a132=(a059*a132);
  a045=(a045+a132);
  a132=(a070*a045);
  a118=(a118+a132);
  a086=(a086-a118);
  a118=(a081*a023);
  a132=(a047*a018);
  a136=(a044*a077);
  a132=(a132+a136);
  a136=(a076*a000);
  a033=(a042*a045);
  a136=(a136+a033);
  a132=(a132+a136);
  a132=(a061*a132);
  a136=(a052*a132);
  a118=(a118+a136);
  a086=(a086-a118);
  a036=(a036+a086);
  a118=(a058*a023);
  a137=(a052*a137);
  a118=(a118+a137);
  a131=(a131+a118);
  a118=(a072*a102);
  a077=(a070*a077);
  a118=(a118+a077);
  a131=(a131-a118);
  a118=(a081*a144);
  a077=(a056*a132);
  a118=(a118+a077);
  a131=(a131-a118);
  a118=(a082*a015);
  a045=(a003*a045);
  a077=(a019*a045);
  a118=(a118+a077);
  a131=(a131-a118);
  a118=(a003*a131);
  a077=(a047*a118);
  a036=(a036+a077);
  a111=(a111*a000);
  a079=(a079*a000);
  a137=(a042*a086);
  a079=(a079+a137);
  a137=(a044*a131);
  a079=(a079+a137);
  a102=(a026*a102);
  a018=(a070*a018);
  a102=(a102+a018);
  a154=(a154-a102);
  a023=(a068*a023);
  a110=(a052*a110);
  a023=(a023+a110);
  a154=(a154-a023);
  a015=(a081*a015);
  a132=(a019*a132);
  a015=(a015+a132);
  a154=(a154-a015);
  a144=(a082*a144);
  a045=(a056*a045);
  a144=(a144+a045);
  a154=(a154+a144);
  a144=(a047*a154);
  a079=(a079+a144);
  a079=(a061*a079);
  a144=(a042*a079);
  a144=(a111+a144);
  a036=(a036+a144);
  a045=(a003*a154);
  a015=(a044*a045);
  a036=(a036-a015);
  a036=(a036/a000);
  if (res[1]!=0) res[1][30]=a036;
  a036=(a003*a086);
  a132=(a047*a036);
  a023=(a131-a132);
  a110=(a044*a079);
  a023=(a023+a110);
  a113=(a113*a000);
  a045=(a042*a045);
  a045=(a113+a045);
  a023=(a023+a045);
  a023=(a023/a000);
  if (res[1]!=0) res[1][31]=a023;
  a036=(a044*a036);
  a023=(a048*a094);
  a023=(a093*a023);
  a102=(a044*a000);
  a102=(a003*a102);
  a102=(a049*a102);
  a018=(a119*a094);
  a018=(a102-a018);
  a018=(a096*a018);
  a023=(a023+a018);
  a094=(a120*a094);
  a094=(a011-a094);
  a094=(a098*a094);
  a023=(a023+a094);
  a023=(a100*a023);
  a023=(a036-a023);
  a004=(a004*a000);
  a118=(a042*a118);
  a118=(a004+a118);
  a023=(a023-a118);
  a079=(a047*a079);
  a023=(a023+a079);
  a023=(a023+a154);
  a023=(a023/a000);
  if (res[1]!=0) res[1][32]=a023;
  a023=1.7320508075688774e+00;
  a094=(a023*a000);
  a128=(a128*a094);
  a075=(a075*a094);
  a075=(a061*a075);
  a018=(a127*a075);
  a018=(a128+a018);
  a018=(a018+a086);
  a077=(a077-a018);
  a077=(a077-a144);
  a077=(a077-a015);
  a077=(a077+a143);
  a077=(a077-a108);
  a077=(a077-a140);
  a077=(a077-a064);
  if (res[1]!=0) res[1][33]=a077;
  a126=(a126*a094);
  a077=(a125*a075);
  a077=(a126-a077);
  a077=(a077-a132);
  a077=(a077-a131);
  a077=(a077-a110);
  a077=(a077+a045);
  a077=(a077-a133);
  a077=(a077+a149);
  a077=(a077-a030);
  a077=(a077-a085);
  if (res[1]!=0) res[1][34]=a077;
  a123=(a123*a094);
  a075=(a122*a075);
  a075=(a123+a075);
  a036=(a036-a075);
  a036=(a036-a118);
  a036=(a036-a079);
  a036=(a036-a154);
  a036=(a036-a135);
  a036=(a036-a032);
  a036=(a036-a121);
  a036=(a036+a114);
  if (res[1]!=0) res[1][35]=a036;
  a005=(a005*a000);
  a014=(a014*a042);
  a036=(a005-a014);
  a036=(a003*a036);
  a036=(a049*a036);
  a114=(2.*a044);
  a114=(a114*a000);
  a121=(a046*a114);
  a032=(a017*a121);
  a036=(a036-a032);
  a032=(a029*a036);
  a053=(a053*a000);
  a050=(a050-a001);
  a050=(a003*a050);
  a050=(a049*a050);
  a001=(a051*a121);
  a050=(a050-a001);
  a001=(a029*a050);
  a135=(a044*a001);
  a135=(a053+a135);
  a154=(a055*a121);
  a154=(a020-a154);
  a079=(a035*a154);
  a118=(a042*a079);
  a135=(a135-a118);
  a135=(a003*a135);
  a135=(a032-a135);
  a135=(a049*a135);
  a118=(a054*a121);
  a135=(a135-a118);
  a118=(a041*a135);
  a075=(a028*a006);
  a075=(a013*a075);
  a077=(a029*a075);
  a085=(a029*a034);
  a030=(a009*a085);
  a149=2.1754763209582237e-01;
  a149=(a149*a013);
  a133=(a006*a149);
  a030=(a030-a133);
  a030=(a003*a030);
  a030=(a077+a030);
  a030=(a013*a030);
  a133=(a028*a030);
  a118=(a118-a133);
  a133=(a000*a118);
  a045=(a027*a133);
  a135=(a062*a135);
  a030=(a041*a030);
  a135=(a135-a030);
  a030=(a000*a135);
  a110=(a061*a030);
  a045=(a045+a110);
  a110=(a003*a045);
  a131=(a024*a110);
  a107=(a107+a131);
  a131=(a006*a077);
  a132=(a002*a085);
  a131=(a131+a132);
  a131=(a003*a131);
  a131=(a149+a131);
  a131=(a013*a131);
  a132=(a041*a131);
  a064=(a042*a032);
  a140=(a047*a001);
  a064=(a064-a140);
  a064=(a003*a064);
  a064=(a079-a064);
  a064=(a049*a064);
  a140=(a069*a121);
  a064=(a064-a140);
  a140=(a062*a064);
  a132=(a132+a140);
  a107=(a107+a132);
  a140=(a006*a034);
  a108=(a009*a016);
  a140=(a140+a108);
  a108=(a002*a075);
  a140=(a140-a108);
  a140=(a061*a140);
  a108=(a073*a140);
  a131=(a028*a131);
  a064=(a041*a064);
  a131=(a131+a064);
  a064=(a000*a131);
  a143=(a027*a064);
  a132=(a000*a132);
  a015=(a061*a132);
  a143=(a143+a015);
  a015=(a071*a143);
  a108=(a108+a015);
  a107=(a107-a108);
  a108=(a002*a045);
  a015=(a009*a143);
  a108=(a108+a015);
  a149=(a002*a149);
  a077=(a009*a077);
  a149=(a149+a077);
  a149=(a003*a149);
  a085=(a085-a149);
  a085=(a013*a085);
  a149=(a028*a085);
  a079=(a047*a079);
  a032=(a044*a032);
  a022=(a022+a032);
  a079=(a079-a022);
  a079=(a003*a079);
  a001=(a001-a079);
  a001=(a049*a001);
  a079=(a080*a121);
  a001=(a001-a079);
  a079=(a041*a001);
  a149=(a149+a079);
  a079=(a000*a149);
  a022=(a027*a079);
  a085=(a041*a085);
  a001=(a062*a001);
  a085=(a085+a001);
  a001=(a000*a085);
  a032=(a061*a001);
  a022=(a022+a032);
  a032=(a006*a022);
  a108=(a108+a032);
  a108=(a061*a108);
  a032=(a037*a108);
  a032=(a065+a032);
  a107=(a107-a032);
  a032=(a003*a022);
  a077=(a031*a032);
  a015=(a084*a075);
  a077=(a077-a015);
  a107=(a107-a077);
  a077=(a003*a107);
  a144=(a002*a077);
  a018=(a060*a140);
  a045=(a071*a045);
  a018=(a018+a045);
  a135=(a135-a018);
  a034=(a087*a034);
  a143=(a003*a143);
  a018=(a024*a143);
  a034=(a034+a018);
  a135=(a135-a034);
  a034=(a031*a108);
  a074=(a074*a075);
  a034=(a034-a074);
  a135=(a135-a034);
  a084=(a084*a016);
  a032=(a037*a032);
  a032=(a084+a032);
  a135=(a135+a032);
  a032=(a003*a135);
  a034=(a009*a032);
  a018=(a144-a034);
  a045=(a009*a107);
  a086=(a002*a135);
  a045=(a045+a086);
  a143=(a031*a143);
  a087=(a087*a075);
  a143=(a143-a087);
  a110=(a037*a110);
  a116=(a116+a110);
  a143=(a143-a116);
  a143=(a143+a085);
  a140=(a083*a140);
  a022=(a071*a022);
  a140=(a140+a022);
  a143=(a143-a140);
  a108=(a024*a108);
  a106=(a106+a108);
  a143=(a143-a106);
  a106=(a006*a143);
  a045=(a045+a106);
  a045=(a061*a045);
  a106=(a006*a045);
  a018=(a018+a106);
  a018=(a018+a143);
  a018=(a018/a000);
  if (res[1]!=0) res[1][36]=a018;
  a032=(a006*a032);
  a018=(a107+a032);
  a108=(a009*a045);
  a018=(a018+a108);
  a140=(a003*a143);
  a022=(a002*a140);
  a018=(a018-a022);
  a018=(a018/a000);
  if (res[1]!=0) res[1][37]=a018;
  a077=(a006*a077);
  a018=(a135-a077);
  a045=(a002*a045);
  a018=(a018+a045);
  a140=(a009*a140);
  a018=(a018+a140);
  a018=(a018/a000);
  if (res[1]!=0) res[1][38]=a018;
  a018=(a104*a121);
  a018=(a097-a018);
  a018=(a093*a018);
  a085=(a109*a121);
  a011=(a011-a085);
  a011=(a096*a011);
  a018=(a018+a011);
  a114=(a003*a114);
  a114=(a049*a114);
  a011=(a043*a121);
  a011=(a114-a011);
  a011=(a098*a011);
  a018=(a018-a011);
  a018=(a100*a018);
  a011=(a058*a154);
  a133=(a061*a133);
  a030=(a059*a030);
  a133=(a133+a030);
  a030=(a003*a133);
  a085=(a056*a030);
  a011=(a011+a085);
  a149=(a149-a011);
  a011=(a068*a036);
  a064=(a061*a064);
  a132=(a059*a132);
  a064=(a064+a132);
  a132=(a003*a064);
  a085=(a019*a132);
  a011=(a011+a085);
  a149=(a149+a011);
  a011=(a042*a050);
  a085=(a056*a000);
  a116=(a044*a154);
  a085=(a085+a116);
  a011=(a011+a085);
  a085=(a047*a036);
  a011=(a011+a085);
  a011=(a061*a011);
  a085=(a076*a011);
  a079=(a061*a079);
  a001=(a059*a001);
  a079=(a079+a001);
  a001=(a070*a079);
  a085=(a085+a001);
  a149=(a149-a085);
  a085=(a081*a050);
  a001=(a047*a133);
  a116=(a072*a000);
  a110=(a044*a064);
  a116=(a116+a110);
  a001=(a001+a116);
  a116=(a042*a079);
  a001=(a001+a116);
  a001=(a061*a001);
  a116=(a052*a001);
  a085=(a085+a116);
  a149=(a149-a085);
  a018=(a018+a149);
  a085=(a058*a050);
  a030=(a052*a030);
  a085=(a085+a030);
  a131=(a131+a085);
  a085=(a072*a011);
  a064=(a070*a064);
  a085=(a085+a064);
  a131=(a131-a085);
  a085=(a081*a154);
  a064=(a056*a001);
  a085=(a085+a064);
  a131=(a131-a085);
  a085=(a082*a036);
  a079=(a003*a079);
  a064=(a019*a079);
  a085=(a085+a064);
  a131=(a131-a085);
  a085=(a003*a131);
  a064=(a047*a085);
  a018=(a018+a064);
  a030=(a042*a149);
  a066=(a066*a000);
  a116=(a044*a131);
  a066=(a066+a116);
  a030=(a030+a066);
  a011=(a026*a011);
  a133=(a070*a133);
  a011=(a011+a133);
  a118=(a118-a011);
  a050=(a068*a050);
  a132=(a052*a132);
  a050=(a050+a132);
  a118=(a118-a050);
  a036=(a081*a036);
  a001=(a019*a001);
  a036=(a036+a001);
  a118=(a118-a036);
  a154=(a082*a154);
  a079=(a056*a079);
  a154=(a154+a079);
  a118=(a118+a154);
  a154=(a047*a118);
  a030=(a030+a154);
  a030=(a061*a030);
  a154=(a042*a030);
  a018=(a018+a154);
  a079=(a003*a118);
  a036=(a044*a079);
  a113=(a113+a036);
  a018=(a018-a113);
  a018=(a018/a000);
  if (res[1]!=0) res[1][39]=a018;
  a018=(a003*a149);
  a036=(a047*a018);
  a001=(a131-a036);
  a050=(a044*a030);
  a050=(a111+a050);
  a001=(a001+a050);
  a079=(a042*a079);
  a001=(a001+a079);
  a001=(a001/a000);
  if (res[1]!=0) res[1][40]=a001;
  a010=(a010*a000);
  a018=(a044*a018);
  a018=(a010+a018);
  a001=(a042*a000);
  a001=(a003*a001);
  a001=(a049*a001);
  a132=(a119*a121);
  a132=(a001-a132);
  a132=(a096*a132);
  a011=(a048*a121);
  a114=(a114-a011);
  a114=(a093*a114);
  a132=(a132-a114);
  a121=(a120*a121);
  a121=(a121+a097);
  a121=(a098*a121);
  a132=(a132-a121);
  a132=(a100*a132);
  a132=(a018-a132);
  a085=(a042*a085);
  a132=(a132-a085);
  a030=(a047*a030);
  a132=(a132+a030);
  a132=(a132+a118);
  a132=(a132/a000);
  if (res[1]!=0) res[1][41]=a132;
  a067=(a067*a094);
  a067=(a061*a067);
  a132=(a127*a067);
  a126=(a126+a132);
  a126=(a126+a149);
  a064=(a064-a126);
  a064=(a064-a154);
  a064=(a064-a113);
  a064=(a064+a144);
  a064=(a064-a034);
  a064=(a064-a106);
  a064=(a064-a143);
  if (res[1]!=0) res[1][42]=a064;
  a064=(a125*a067);
  a064=(a128+a064);
  a064=(a064+a036);
  a064=(a064+a131);
  a064=(a064+a050);
  a079=(a079-a064);
  a079=(a079-a107);
  a079=(a079+a032);
  a079=(a079-a108);
  a079=(a079-a022);
  if (res[1]!=0) res[1][43]=a079;
  a078=(a078*a094);
  a067=(a122*a067);
  a067=(a078-a067);
  a067=(a067+a018);
  a067=(a067-a085);
  a067=(a067-a030);
  a067=(a067-a118);
  a067=(a067-a077);
  a067=(a067-a135);
  a067=(a067-a045);
  a067=(a067+a140);
  if (res[1]!=0) res[1][44]=a067;
  a067=(a035*a075);
  a140=(a006*a067);
  a089=(a089+a140);
  a089=(a003*a089);
  a089=(a105+a089);
  a089=(a013*a089);
  a140=(a028*a089);
  a045=(2.*a047);
  a045=(a045*a000);
  a046=(a046*a045);
  a017=(a017*a046);
  a020=(a020-a017);
  a017=(a029*a020);
  a008=(a008-a153);
  a008=(a003*a008);
  a008=(a049*a008);
  a051=(a051*a046);
  a008=(a008-a051);
  a029=(a029*a008);
  a051=(a044*a029);
  a014=(a014-a005);
  a014=(a003*a014);
  a014=(a049*a014);
  a055=(a055*a046);
  a014=(a014-a055);
  a035=(a035*a014);
  a055=(a042*a035);
  a051=(a051-a055);
  a051=(a003*a051);
  a051=(a017-a051);
  a051=(a049*a051);
  a054=(a054*a046);
  a051=(a051-a054);
  a054=(a041*a051);
  a140=(a140+a054);
  a054=(a000*a140);
  a055=(a027*a054);
  a089=(a041*a089);
  a051=(a062*a051);
  a089=(a089+a051);
  a051=(a000*a089);
  a005=(a061*a051);
  a055=(a055+a005);
  a005=(a003*a055);
  a153=(a024*a005);
  a135=(a063*a007);
  a153=(a153-a135);
  a105=(a006*a105);
  a135=(a002*a091);
  a105=(a105+a135);
  a105=(a003*a105);
  a105=(a067-a105);
  a105=(a013*a105);
  a135=(a041*a105);
  a077=(a042*a017);
  a118=(a047*a029);
  a053=(a053+a118);
  a077=(a077-a053);
  a077=(a003*a077);
  a077=(a035-a077);
  a077=(a049*a077);
  a069=(a069*a046);
  a077=(a077-a069);
  a069=(a062*a077);
  a135=(a135+a069);
  a153=(a153+a135);
  a069=(a009*a075);
  a007=(a006*a007);
  a069=(a069-a007);
  a016=(a002*a016);
  a069=(a069+a016);
  a069=(a061*a069);
  a073=(a073*a069);
  a105=(a028*a105);
  a077=(a041*a077);
  a105=(a105+a077);
  a077=(a000*a105);
  a016=(a027*a077);
  a135=(a000*a135);
  a007=(a061*a135);
  a016=(a016+a007);
  a007=(a071*a016);
  a073=(a073+a007);
  a153=(a153-a073);
  a073=(a002*a055);
  a007=(a009*a016);
  a073=(a073+a007);
  a035=(a047*a035);
  a057=(a057+a035);
  a017=(a044*a017);
  a057=(a057-a017);
  a057=(a003*a057);
  a029=(a029-a057);
  a029=(a049*a029);
  a080=(a080*a046);
  a029=(a029-a080);
  a080=(a041*a029);
  a067=(a002*a067);
  a067=(a067-a095);
  a067=(a003*a067);
  a091=(a091+a067);
  a013=(a013*a091);
  a028=(a028*a013);
  a080=(a080-a028);
  a028=(a000*a080);
  a027=(a027*a028);
  a062=(a062*a029);
  a041=(a041*a013);
  a062=(a062-a041);
  a041=(a000*a062);
  a013=(a061*a041);
  a027=(a027+a013);
  a013=(a006*a027);
  a073=(a073+a013);
  a073=(a061*a073);
  a013=(a037*a073);
  a074=(a074+a013);
  a153=(a153-a074);
  a074=(a003*a027);
  a013=(a031*a074);
  a084=(a084+a013);
  a153=(a153-a084);
  a084=(a003*a153);
  a013=(a002*a084);
  a060=(a060*a069);
  a055=(a071*a055);
  a060=(a060+a055);
  a089=(a089-a060);
  a016=(a003*a016);
  a060=(a024*a016);
  a060=(a060-a012);
  a089=(a089-a060);
  a060=(a031*a073);
  a065=(a065+a060);
  a089=(a089-a065);
  a074=(a037*a074);
  a015=(a015+a074);
  a089=(a089+a015);
  a015=(a003*a089);
  a074=(a009*a015);
  a065=(a013-a074);
  a060=(a009*a153);
  a012=(a002*a089);
  a060=(a060+a012);
  a016=(a031*a016);
  a145=(a145+a016);
  a063=(a063*a075);
  a005=(a037*a005);
  a063=(a063+a005);
  a145=(a145-a063);
  a145=(a145+a062);
  a083=(a083*a069);
  a027=(a071*a027);
  a083=(a083+a027);
  a145=(a145-a083);
  a073=(a024*a073);
  a073=(a073-a038);
  a145=(a145-a073);
  a073=(a006*a145);
  a060=(a060+a073);
  a060=(a061*a060);
  a073=(a006*a060);
  a065=(a065+a073);
  a065=(a065+a145);
  a065=(a065/a000);
  if (res[1]!=0) res[1][45]=a065;
  a015=(a006*a015);
  a065=(a153+a015);
  a038=(a009*a060);
  a065=(a065+a038);
  a083=(a003*a145);
  a027=(a002*a083);
  a065=(a065-a027);
  a065=(a065/a000);
  if (res[1]!=0) res[1][46]=a065;
  a084=(a006*a084);
  a065=(a089-a084);
  a060=(a002*a060);
  a065=(a065+a060);
  a083=(a009*a083);
  a065=(a065+a083);
  a065=(a065/a000);
  if (res[1]!=0) res[1][47]=a065;
  a104=(a104*a046);
  a104=(a001-a104);
  a104=(a093*a104);
  a109=(a109*a046);
  a102=(a102-a109);
  a102=(a096*a102);
  a104=(a104+a102);
  a043=(a043*a046);
  a043=(a098*a043);
  a104=(a104+a043);
  a104=(a100*a104);
  a043=(a058*a014);
  a054=(a061*a054);
  a051=(a059*a051);
  a054=(a054+a051);
  a051=(a003*a054);
  a102=(a056*a051);
  a043=(a043+a102);
  a080=(a080-a043);
  a043=(a068*a020);
  a077=(a061*a077);
  a135=(a059*a135);
  a077=(a077+a135);
  a135=(a003*a077);
  a102=(a019*a135);
  a043=(a043+a102);
  a080=(a080+a043);
  a043=(a042*a008);
  a102=(a044*a014);
  a043=(a043+a102);
  a102=(a019*a000);
  a109=(a047*a020);
  a102=(a102+a109);
  a043=(a043+a102);
  a043=(a061*a043);
  a076=(a076*a043);
  a028=(a061*a028);
  a059=(a059*a041);
  a028=(a028+a059);
  a059=(a070*a028);
  a076=(a076+a059);
  a080=(a080-a076);
  a076=(a081*a008);
  a059=(a026*a000);
  a041=(a047*a054);
  a059=(a059+a041);
  a041=(a044*a077);
  a059=(a059+a041);
  a041=(a042*a028);
  a059=(a059+a041);
  a059=(a061*a059);
  a041=(a052*a059);
  a076=(a076+a041);
  a080=(a080-a076);
  a104=(a104+a080);
  a058=(a058*a008);
  a051=(a052*a051);
  a058=(a058+a051);
  a105=(a105+a058);
  a072=(a072*a043);
  a077=(a070*a077);
  a072=(a072+a077);
  a105=(a105-a072);
  a072=(a081*a014);
  a077=(a056*a059);
  a072=(a072+a077);
  a105=(a105-a072);
  a072=(a082*a020);
  a028=(a003*a028);
  a077=(a019*a028);
  a072=(a072+a077);
  a105=(a105-a072);
  a072=(a003*a105);
  a077=(a047*a072);
  a004=(a004+a077);
  a104=(a104+a004);
  a077=(a042*a080);
  a058=(a044*a105);
  a077=(a077+a058);
  a040=(a040*a000);
  a026=(a026*a043);
  a054=(a070*a054);
  a026=(a026+a054);
  a140=(a140-a026);
  a068=(a068*a008);
  a135=(a052*a135);
  a068=(a068+a135);
  a140=(a140-a068);
  a081=(a081*a020);
  a059=(a019*a059);
  a081=(a081+a059);
  a140=(a140-a081);
  a082=(a082*a014);
  a028=(a056*a028);
  a082=(a082+a028);
  a140=(a140+a082);
  a082=(a047*a140);
  a040=(a040+a082);
  a077=(a077+a040);
  a077=(a061*a077);
  a040=(a042*a077);
  a104=(a104+a040);
  a082=(a003*a140);
  a028=(a044*a082);
  a104=(a104-a028);
  a104=(a104/a000);
  if (res[1]!=0) res[1][48]=a104;
  a104=(a003*a080);
  a014=(a047*a104);
  a010=(a010+a014);
  a014=(a105-a010);
  a081=(a044*a077);
  a014=(a014+a081);
  a082=(a042*a082);
  a014=(a014+a082);
  a014=(a014/a000);
  if (res[1]!=0) res[1][49]=a014;
  a104=(a044*a104);
  a119=(a119*a046);
  a097=(a097-a119);
  a096=(a096*a097);
  a045=(a003*a045);
  a049=(a049*a045);
  a048=(a048*a046);
  a049=(a049-a048);
  a093=(a093*a049);
  a096=(a096-a093);
  a120=(a120*a046);
  a001=(a001-a120);
  a098=(a098*a001);
  a096=(a096+a098);
  a100=(a100*a096);
  a100=(a104-a100);
  a072=(a042*a072);
  a100=(a100-a072);
  a077=(a047*a077);
  a111=(a111+a077);
  a100=(a100+a111);
  a100=(a100+a140);
  a100=(a100/a000);
  if (res[1]!=0) res[1][50]=a100;
  a025=(a025*a094);
  a025=(a061*a025);
  a094=(a127*a025);
  a123=(a123-a094);
  a123=(a123-a080);
  a123=(a123+a004);
  a123=(a123-a040);
  a123=(a123-a028);
  a123=(a123+a013);
  a123=(a123-a074);
  a123=(a123-a073);
  a123=(a123-a145);
  if (res[1]!=0) res[1][51]=a123;
  a123=(a125*a025);
  a123=(a123+a078);
  a123=(a123+a010);
  a123=(a123+a105);
  a123=(a123+a081);
  a082=(a082-a123);
  a082=(a082-a153);
  a082=(a082+a015);
  a082=(a082-a038);
  a082=(a082-a027);
  if (res[1]!=0) res[1][52]=a082;
  a025=(a122*a025);
  a128=(a128+a025);
  a104=(a104-a128);
  a104=(a104-a072);
  a104=(a104-a111);
  a104=(a104-a140);
  a104=(a104-a084);
  a104=(a104-a089);
  a104=(a104-a060);
  a104=(a104+a083);
  if (res[1]!=0) res[1][53]=a104;
  a104=(a003*a000);
  a083=-9.3301270189221941e-01;
  a083=(a083*a000);
  a083=(a104+a083);
  a060=4.3301270189221935e-01;
  a060=(a060*a000);
  a083=(a083+a060);
  a060=(a003*a083);
  a089=(a037*a060);
  a084=(a006*a083);
  a084=(a061*a084);
  a140=(a031*a084);
  a140=(a089-a140);
  a111=(a002*a140);
  a072=(a037*a084);
  a128=(a031*a060);
  a072=(a072+a128);
  a025=(a009*a072);
  a111=(a111-a025);
  a071=(a071*a083);
  a023=(a023-a071);
  a084=(a024*a084);
  a084=(a023-a084);
  a071=(a006*a084);
  a111=(a111+a071);
  a111=(a061*a111);
  a071=(a006*a111);
  a025=(a003*a072);
  a082=(a002*a025);
  a027=(a003*a140);
  a038=(a009*a027);
  a015=(a082+a038);
  a015=(a071-a015);
  a015=(a015+a084);
  a015=(a015/a000);
  if (res[1]!=0) res[1][54]=a015;
  a027=(a006*a027);
  a015=(a027-a072);
  a153=(a009*a111);
  a015=(a015+a153);
  a123=(a003*a084);
  a081=(a002*a123);
  a015=(a015-a081);
  a015=(a015/a000);
  if (res[1]!=0) res[1][55]=a015;
  a025=(a006*a025);
  a015=(a140+a025);
  a111=(a002*a111);
  a015=(a015+a111);
  a123=(a009*a123);
  a015=(a015+a123);
  a015=(a015/a000);
  if (res[1]!=0) res[1][56]=a015;
  a015=-4.3301270189221935e-01;
  a015=(a015*a000);
  a104=(a104+a015);
  a015=-6.6987298107780674e-02;
  a015=(a015*a000);
  a104=(a104+a015);
  a070=(a070*a104);
  a151=(a151-a070);
  a070=(a042*a104);
  a070=(a061*a070);
  a015=(a052*a070);
  a015=(a151-a015);
  a105=(a056*a070);
  a010=(a003*a104);
  a078=(a019*a010);
  a105=(a105+a078);
  a145=(a003*a105);
  a073=(a047*a145);
  a074=(a015-a073);
  a013=(a042*a015);
  a028=(a044*a105);
  a013=(a013-a028);
  a028=(a056*a010);
  a070=(a019*a070);
  a070=(a028-a070);
  a040=(a047*a070);
  a013=(a013+a040);
  a013=(a061*a013);
  a040=(a042*a013);
  a074=(a074+a040);
  a004=(a003*a070);
  a080=(a044*a004);
  a074=(a074-a080);
  a074=(a074/a000);
  if (res[1]!=0) res[1][57]=a074;
  a074=(a044*a013);
  a094=(a003*a015);
  a100=(a047*a094);
  a077=(a105+a100);
  a077=(a074-a077);
  a004=(a042*a004);
  a077=(a077+a004);
  a077=(a077/a000);
  if (res[1]!=0) res[1][58]=a077;
  a094=(a044*a094);
  a145=(a042*a145);
  a077=(a094+a145);
  a013=(a047*a013);
  a077=(a077+a013);
  a077=(a077+a070);
  a077=(a077/a000);
  if (res[1]!=0) res[1][59]=a077;
  a077=-1.;
  a096=(a061*a127);
  a098=(a127*a096);
  a098=(a077-a098);
  a098=(a098-a015);
  a098=(a098-a073);
  a098=(a098-a040);
  a098=(a098-a080);
  a098=(a098-a082);
  a098=(a098-a038);
  a098=(a098-a071);
  a098=(a098-a084);
  if (res[1]!=0) res[1][60]=a098;
  a098=(a125*a096);
  a084=(a003*a122);
  a098=(a098+a084);
  a098=(a098+a100);
  a105=(a105-a098);
  a105=(a105-a074);
  a105=(a105+a004);
  a105=(a105+a072);
  a105=(a105+a027);
  a105=(a105-a153);
  a105=(a105-a081);
  if (res[1]!=0) res[1][61]=a105;
  a105=(a003*a125);
  a096=(a122*a096);
  a096=(a105-a096);
  a096=(a096+a094);
  a096=(a096+a145);
  a096=(a096-a013);
  a096=(a096-a070);
  a096=(a096+a025);
  a096=(a096-a140);
  a096=(a096-a111);
  a096=(a096+a123);
  if (res[1]!=0) res[1][62]=a096;
  a096=(a009*a083);
  a096=(a061*a096);
  a123=(a037*a096);
  a123=(a023-a123);
  a111=(a003*a123);
  a140=(a002*a111);
  a060=(a024*a060);
  a025=(a031*a096);
  a025=(a060+a025);
  a070=(a003*a025);
  a013=(a009*a070);
  a145=(a140+a013);
  a094=(a009*a123);
  a081=(a002*a025);
  a094=(a094-a081);
  a096=(a024*a096);
  a128=(a128-a096);
  a096=(a006*a128);
  a094=(a094+a096);
  a094=(a061*a094);
  a096=(a006*a094);
  a145=(a145+a096);
  a145=(a145+a128);
  a145=(a145/a000);
  if (res[1]!=0) res[1][63]=a145;
  a070=(a006*a070);
  a145=(a123-a070);
  a081=(a009*a094);
  a145=(a145+a081);
  a153=(a003*a128);
  a027=(a002*a153);
  a145=(a145-a027);
  a145=(a145/a000);
  if (res[1]!=0) res[1][64]=a145;
  a094=(a002*a094);
  a111=(a006*a111);
  a145=(a025+a111);
  a145=(a094-a145);
  a153=(a009*a153);
  a145=(a145+a153);
  a145=(a145/a000);
  if (res[1]!=0) res[1][65]=a145;
  a145=(a044*a104);
  a145=(a061*a145);
  a072=(a052*a145);
  a078=(a078-a072);
  a072=(a056*a145);
  a072=(a151-a072);
  a004=(a003*a072);
  a074=(a047*a004);
  a098=(a078+a074);
  a100=(a042*a078);
  a071=(a044*a072);
  a100=(a100+a071);
  a010=(a052*a010);
  a145=(a019*a145);
  a145=(a010+a145);
  a071=(a047*a145);
  a100=(a100-a071);
  a100=(a061*a100);
  a071=(a042*a100);
  a098=(a098+a071);
  a038=(a003*a145);
  a082=(a044*a038);
  a098=(a098+a082);
  a098=(a098/a000);
  if (res[1]!=0) res[1][66]=a098;
  a098=(a003*a078);
  a080=(a047*a098);
  a040=(a072-a080);
  a073=(a044*a100);
  a040=(a040+a073);
  a038=(a042*a038);
  a040=(a040-a038);
  a040=(a040/a000);
  if (res[1]!=0) res[1][67]=a040;
  a098=(a044*a098);
  a004=(a042*a004);
  a040=(a098-a004);
  a100=(a047*a100);
  a040=(a040+a100);
  a040=(a040-a145);
  a040=(a040/a000);
  if (res[1]!=0) res[1][68]=a040;
  a040=(a061*a125);
  a015=(a127*a040);
  a084=(a084-a015);
  a084=(a084-a078);
  a084=(a084+a074);
  a084=(a084-a071);
  a084=(a084+a082);
  a084=(a084+a140);
  a084=(a084+a013);
  a084=(a084-a096);
  a084=(a084-a128);
  if (res[1]!=0) res[1][69]=a084;
  a084=(a125*a040);
  a077=(a077-a084);
  a077=(a077-a080);
  a077=(a077-a072);
  a077=(a077-a073);
  a077=(a077-a038);
  a077=(a077-a123);
  a077=(a077-a070);
  a077=(a077-a081);
  a077=(a077-a027);
  if (res[1]!=0) res[1][70]=a077;
  a077=(a003*a127);
  a040=(a122*a040);
  a040=(a077+a040);
  a098=(a098-a040);
  a098=(a098-a004);
  a098=(a098-a100);
  a098=(a098+a145);
  a098=(a098-a111);
  a098=(a098+a025);
  a098=(a098-a094);
  a098=(a098+a153);
  if (res[1]!=0) res[1][71]=a098;
  a083=(a002*a083);
  a083=(a061*a083);
  a037=(a037*a083);
  a060=(a060-a037);
  a037=(a003*a060);
  a098=(a002*a037);
  a031=(a031*a083);
  a023=(a023-a031);
  a031=(a003*a023);
  a153=(a009*a031);
  a094=(a098-a153);
  a025=(a009*a060);
  a111=(a002*a023);
  a025=(a025+a111);
  a024=(a024*a083);
  a089=(a089+a024);
  a024=(a006*a089);
  a025=(a025-a024);
  a025=(a061*a025);
  a024=(a006*a025);
  a094=(a094+a024);
  a094=(a094-a089);
  a094=(a094/a000);
  if (res[1]!=0) res[1][72]=a094;
  a031=(a006*a031);
  a094=(a060+a031);
  a083=(a009*a025);
  a094=(a094+a083);
  a111=(a003*a089);
  a145=(a002*a111);
  a094=(a094+a145);
  a094=(a094/a000);
  if (res[1]!=0) res[1][73]=a094;
  a006=(a006*a037);
  a037=(a023-a006);
  a002=(a002*a025);
  a037=(a037+a002);
  a009=(a009*a111);
  a037=(a037-a009);
  a037=(a037/a000);
  if (res[1]!=0) res[1][74]=a037;
  a104=(a047*a104);
  a104=(a061*a104);
  a056=(a056*a104);
  a010=(a010-a056);
  a056=(a003*a010);
  a037=(a047*a056);
  a052=(a052*a104);
  a028=(a028+a052);
  a052=(a037-a028);
  a111=(a044*a010);
  a025=(a042*a028);
  a111=(a111-a025);
  a019=(a019*a104);
  a151=(a151-a019);
  a019=(a047*a151);
  a111=(a111+a019);
  a111=(a061*a111);
  a019=(a042*a111);
  a052=(a052+a019);
  a104=(a003*a151);
  a025=(a044*a104);
  a052=(a052-a025);
  a052=(a052/a000);
  if (res[1]!=0) res[1][75]=a052;
  a003=(a003*a028);
  a052=(a047*a003);
  a094=(a010+a052);
  a100=(a044*a111);
  a094=(a094+a100);
  a104=(a042*a104);
  a094=(a094+a104);
  a094=(a094/a000);
  if (res[1]!=0) res[1][76]=a094;
  a047=(a047*a111);
  a044=(a044*a003);
  a042=(a042*a056);
  a056=(a044+a042);
  a056=(a047-a056);
  a056=(a056+a151);
  a056=(a056/a000);
  if (res[1]!=0) res[1][77]=a056;
  a061=(a061*a122);
  a127=(a127*a061);
  a105=(a105+a127);
  a028=(a028-a105);
  a028=(a028+a037);
  a028=(a028-a019);
  a028=(a028-a025);
  a028=(a028+a098);
  a028=(a028-a153);
  a028=(a028-a024);
  a028=(a028+a089);
  if (res[1]!=0) res[1][78]=a028;
  a125=(a125*a061);
  a077=(a077-a125);
  a077=(a077+a052);
  a077=(a077-a010);
  a077=(a077-a100);
  a077=(a077+a104);
  a077=(a077-a060);
  a077=(a077+a031);
  a077=(a077-a083);
  a077=(a077+a145);
  if (res[1]!=0) res[1][79]=a077;
  a122=(a122*a061);
  a099=(a099+a122);
  a099=(a099+a044);
  a099=(a099+a042);
  a099=(a099+a047);
  a099=(a099+a151);
  a099=(a099+a006);
  a099=(a099+a023);
  a099=(a099+a002);
  a099=(a099+a009);
  a099=(-a099);
  if (res[1]!=0) res[1][80]=a099;
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
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* residual_jacobian_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s3;
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

/* update:(z[9],g[9],p[3],h)->(g1[9],p1[3]) */
static int casadi_f2(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22;
  a00=arg[1]? arg[1][0] : 0;
  a01=1.;
  a02=4.;
  a03=arg[3]? arg[3][0] : 0;
  a04=5.0000000000000000e-01;
  a05=3.0000000000000004e+00;
  a06=arg[0]? arg[0][0] : 0;
  a07=(a05*a06);
  a08=4.6410161513775439e-01;
  a09=arg[0]? arg[0][3] : 0;
  a10=(a08*a09);
  a07=(a07+a10);
  a07=(a04*a07);
  a10=-6.4641016151377553e+00;
  a06=(a10*a06);
  a09=(a05*a09);
  a06=(a06+a09);
  a06=(a04*a06);
  a07=(a07+a06);
  a07=(a03*a07);
  a06=casadi_sq(a07);
  a09=arg[0]? arg[0][1] : 0;
  a11=(a05*a09);
  a12=arg[0]? arg[0][4] : 0;
  a13=(a08*a12);
  a11=(a11+a13);
  a11=(a04*a11);
  a09=(a10*a09);
  a12=(a05*a12);
  a09=(a09+a12);
  a09=(a04*a09);
  a11=(a11+a09);
  a11=(a03*a11);
  a09=casadi_sq(a11);
  a12=(a06+a09);
  a13=arg[0]? arg[0][2] : 0;
  a14=(a05*a13);
  a15=arg[0]? arg[0][5] : 0;
  a08=(a08*a15);
  a14=(a14+a08);
  a14=(a04*a14);
  a10=(a10*a13);
  a05=(a05*a15);
  a10=(a10+a05);
  a10=(a04*a10);
  a14=(a14+a10);
  a03=(a03*a14);
  a14=casadi_sq(a03);
  a12=(a12+a14);
  a12=(a02+a12);
  a02=(a02/a12);
  a12=(a14+a09);
  a10=2.;
  a12=(a12/a10);
  a12=(a02*a12);
  a12=(a01-a12);
  a05=(a00*a12);
  a15=arg[1]? arg[1][3] : 0;
  a13=(a07*a11);
  a13=(a13/a10);
  a13=(a03+a13);
  a13=(a02*a13);
  a08=(a15*a13);
  a05=(a05+a08);
  a08=arg[1]? arg[1][6] : 0;
  a16=(a07*a03);
  a16=(a16/a10);
  a16=(a16-a11);
  a16=(a02*a16);
  a17=(a08*a16);
  a05=(a05+a17);
  if (res[0]!=0) res[0][0]=a05;
  a05=arg[1]? arg[1][1] : 0;
  a17=(a05*a12);
  a18=arg[1]? arg[1][4] : 0;
  a19=(a18*a13);
  a17=(a17+a19);
  a19=arg[1]? arg[1][7] : 0;
  a20=(a19*a16);
  a17=(a17+a20);
  if (res[0]!=0) res[0][1]=a17;
  a17=arg[1]? arg[1][2] : 0;
  a12=(a17*a12);
  a20=arg[1]? arg[1][5] : 0;
  a13=(a20*a13);
  a12=(a12+a13);
  a13=arg[1]? arg[1][8] : 0;
  a16=(a13*a16);
  a12=(a12+a16);
  if (res[0]!=0) res[0][2]=a12;
  a12=(a11*a07);
  a12=(a12/a10);
  a12=(a12-a03);
  a12=(a02*a12);
  a16=(a00*a12);
  a14=(a14+a06);
  a14=(a14/a10);
  a14=(a02*a14);
  a14=(a01-a14);
  a21=(a15*a14);
  a16=(a16+a21);
  a21=(a11*a03);
  a21=(a21/a10);
  a21=(a07+a21);
  a21=(a02*a21);
  a22=(a08*a21);
  a16=(a16+a22);
  if (res[0]!=0) res[0][3]=a16;
  a16=(a05*a12);
  a22=(a18*a14);
  a16=(a16+a22);
  a22=(a19*a21);
  a16=(a16+a22);
  if (res[0]!=0) res[0][4]=a16;
  a12=(a17*a12);
  a14=(a20*a14);
  a12=(a12+a14);
  a21=(a13*a21);
  a12=(a12+a21);
  if (res[0]!=0) res[0][5]=a12;
  a12=(a03*a07);
  a12=(a12/a10);
  a12=(a11+a12);
  a12=(a02*a12);
  a00=(a00*a12);
  a21=(a03*a11);
  a21=(a21/a10);
  a21=(a21-a07);
  a21=(a02*a21);
  a15=(a15*a21);
  a00=(a00+a15);
  a09=(a09+a06);
  a09=(a09/a10);
  a02=(a02*a09);
  a01=(a01-a02);
  a08=(a08*a01);
  a00=(a00+a08);
  if (res[0]!=0) res[0][6]=a00;
  a05=(a05*a12);
  a18=(a18*a21);
  a05=(a05+a18);
  a19=(a19*a01);
  a05=(a05+a19);
  if (res[0]!=0) res[0][7]=a05;
  a17=(a17*a12);
  a20=(a20*a21);
  a17=(a17+a20);
  a13=(a13*a01);
  a17=(a17+a13);
  if (res[0]!=0) res[0][8]=a17;
  a17=arg[0]? arg[0][7] : 0;
  a13=(a04*a17);
  a01=(a03*a13);
  a20=arg[0]? arg[0][8] : 0;
  a21=(a04*a20);
  a12=(a11*a21);
  a01=(a01-a12);
  a12=2.5000000000000000e-01;
  a05=(a03*a20);
  a19=(a11*a17);
  a05=(a05+a19);
  a19=arg[0]? arg[0][6] : 0;
  a18=(a07*a19);
  a05=(a05+a18);
  a12=(a12*a05);
  a05=(a07*a12);
  a01=(a01+a05);
  a01=(a01+a19);
  if (res[1]!=0) res[1][0]=a01;
  a21=(a07*a21);
  a21=(a21+a17);
  a17=(a11*a12);
  a21=(a21+a17);
  a04=(a04*a19);
  a19=(a03*a04);
  a21=(a21-a19);
  if (res[1]!=0) res[1][1]=a21;
  a07=(a07*a13);
  a20=(a20-a07);
  a03=(a03*a12);
  a20=(a20+a03);
  a11=(a11*a04);
  a20=(a20+a11);
  if (res[1]!=0) res[1][2]=a20;
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
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* update_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
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

/* guess:(xi[3],g[9],p[3],h)->(z0[9]) */
static int casadi_f3(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3;
  a0=2.1132486540518713e-01;
  a1=arg[0]? arg[0][0] : 0;
  a2=(a0*a1);
  if (res[0]!=0) res[0][0]=a2;
  a2=arg[0]? arg[0][1] : 0;
  a3=(a0*a2);
  if (res[0]!=0) res[0][1]=a3;
  a3=arg[0]? arg[0][2] : 0;
  a0=(a0*a3);
  if (res[0]!=0) res[0][2]=a0;
  a0=7.8867513459481287e-01;
  a1=(a0*a1);
  if (res[0]!=0) res[0][3]=a1;
  a2=(a0*a2);
  if (res[0]!=0) res[0][4]=a2;
  a0=(a0*a3);
  if (res[0]!=0) res[0][5]=a0;
  a0=arg[2]? arg[2][0] : 0;
  if (res[0]!=0) res[0][6]=a0;
  a0=arg[2]? arg[2][1] : 0;
  if (res[0]!=0) res[0][7]=a0;
  a0=arg[2]? arg[2][2] : 0;
  if (res[0]!=0) res[0][8]=a0;
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
    case 0: return casadi_s1;
    case 1: return casadi_s0;
    case 2: return casadi_s1;
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

/* legendre:(g[9],xi[3])->(mu[3]) */
static int casadi_f4(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2;
  a0=1.5234375000000000e+01;
  a1=arg[1]? arg[1][0] : 0;
  a1=(a0*a1);
  if (res[0]!=0) res[0][0]=a1;
  a1=4.6875000000000000e-01;
  a2=arg[1]? arg[1][1] : 0;
  a1=(a1*a2);
  if (res[0]!=0) res[0][1]=a1;
  a1=arg[1]? arg[1][2] : 0;
  a0=(a0*a1);
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
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* legendre_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
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
  casadi_real a0, a1, a2;
  a0=1.5234375000000000e+01;
  if (res[0]!=0) res[0][0]=a0;
  a1=0.;
  if (res[0]!=0) res[0][1]=a1;
  if (res[0]!=0) res[0][2]=a1;
  if (res[0]!=0) res[0][3]=a1;
  a2=4.6875000000000000e-01;
  if (res[0]!=0) res[0][4]=a2;
  if (res[0]!=0) res[0][5]=a1;
  if (res[0]!=0) res[0][6]=a1;
  if (res[0]!=0) res[0][7]=a1;
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
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* hessian_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
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
  casadi_real a0, a1, a2, a3, a4;
  a0=1.5234375000000000e+01;
  a1=arg[1]? arg[1][0] : 0;
  a2=(a0*a1);
  a2=(a2*a1);
  a3=4.6875000000000000e-01;
  a4=arg[1]? arg[1][1] : 0;
  a3=(a3*a4);
  a3=(a3*a4);
  a2=(a2+a3);
  a3=arg[1]? arg[1][2] : 0;
  a0=(a0*a3);
  a0=(a0*a3);
  a2=(a2+a0);
  a0=2.3437500000000000e-01;
  a4=casadi_sq(a4);
  a0=(a0*a4);
  a4=7.6171875000000000e+00;
  a1=casadi_sq(a1);
  a1=(a4*a1);
  a0=(a0+a1);
  a3=casadi_sq(a3);
  a4=(a4*a3);
  a0=(a0+a4);
  a4=-1.4715000000000001e+02;
  a3=arg[0]? arg[0][5] : 0;
  a4=(a4*a3);
  a0=(a0+a4);
  a2=(a2-a0);
  if (res[0]!=0) res[0][0]=a2;
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
    case 0: return casadi_s0;
    case 1: return casadi_s1;
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
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* momentum_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
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
    case 0: return casadi_s0;
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

/* margin:(z[9],h)->(m) */
static int casadi_f9(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13;
  a00=1.;
  a01=4.;
  a02=arg[1]? arg[1][0] : 0;
  a03=arg[0]? arg[0][0] : 0;
  a04=(a02*a03);
  a04=casadi_sq(a04);
  a05=arg[0]? arg[0][1] : 0;
  a06=(a02*a05);
  a06=casadi_sq(a06);
  a04=(a04+a06);
  a06=arg[0]? arg[0][2] : 0;
  a07=(a02*a06);
  a07=casadi_sq(a07);
  a04=(a04+a07);
  a04=(a01-a04);
  a00=casadi_fmin(a00,a04);
  a00=casadi_fmin(a00,a04);
  a04=arg[0]? arg[0][3] : 0;
  a07=(a02*a04);
  a07=casadi_sq(a07);
  a08=arg[0]? arg[0][4] : 0;
  a09=(a02*a08);
  a09=casadi_sq(a09);
  a07=(a07+a09);
  a09=arg[0]? arg[0][5] : 0;
  a10=(a02*a09);
  a10=casadi_sq(a10);
  a07=(a07+a10);
  a07=(a01-a07);
  a00=casadi_fmin(a00,a07);
  a00=casadi_fmin(a00,a07);
  a07=5.0000000000000000e-01;
  a10=3.0000000000000004e+00;
  a11=(a10*a03);
  a12=4.6410161513775439e-01;
  a13=(a12*a04);
  a11=(a11+a13);
  a11=(a07*a11);
  a13=-6.4641016151377553e+00;
  a03=(a13*a03);
  a04=(a10*a04);
  a03=(a03+a04);
  a03=(a07*a03);
  a11=(a11+a03);
  a11=(a02*a11);
  a11=casadi_sq(a11);
  a03=(a10*a05);
  a04=(a12*a08);
  a03=(a03+a04);
  a03=(a07*a03);
  a05=(a13*a05);
  a08=(a10*a08);
  a05=(a05+a08);
  a05=(a07*a05);
  a03=(a03+a05);
  a03=(a02*a03);
  a03=casadi_sq(a03);
  a11=(a11+a03);
  a03=(a10*a06);
  a12=(a12*a09);
  a03=(a03+a12);
  a03=(a07*a03);
  a13=(a13*a06);
  a10=(a10*a09);
  a13=(a13+a10);
  a07=(a07*a13);
  a03=(a03+a07);
  a02=(a02*a03);
  a02=casadi_sq(a02);
  a11=(a11+a02);
  a01=(a01-a11);
  a00=casadi_fmin(a00,a01);
  a00=casadi_fmin(a00,a01);
  if (res[0]!=0) res[0][0]=a00;
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

/* section:(g[9],p[3])->(s) */
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
    case 0: return casadi_s0;
    case 1: return casadi_s1;
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

/* chart_point:(z[9],g[9],h,theta)->(g_theta[9]) */
static int casadi_f11(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21;
  a00=arg[1]? arg[1][0] : 0;
  a01=1.;
  a02=4.;
  a03=arg[3]? arg[3][0] : 0;
  a04=arg[2]? arg[2][0] : 0;
  a05=5.0000000000000000e-01;
  a06=3.0000000000000004e+00;
  a07=arg[0]? arg[0][0] : 0;
  a08=(a06*a07);
  a09=4.6410161513775439e-01;
  a10=arg[0]? arg[0][3] : 0;
  a11=(a09*a10);
  a08=(a08+a11);
  a08=(a05*a08);
  a11=-6.4641016151377553e+00;
  a07=(a11*a07);
  a10=(a06*a10);
  a07=(a07+a10);
  a07=(a05*a07);
  a08=(a08+a07);
  a08=(a04*a08);
  a08=(a03*a08);
  a07=casadi_sq(a08);
  a10=arg[0]? arg[0][1] : 0;
  a12=(a06*a10);
  a13=arg[0]? arg[0][4] : 0;
  a14=(a09*a13);
  a12=(a12+a14);
  a12=(a05*a12);
  a10=(a11*a10);
  a13=(a06*a13);
  a10=(a10+a13);
  a10=(a05*a10);
  a12=(a12+a10);
  a12=(a04*a12);
  a12=(a03*a12);
  a10=casadi_sq(a12);
  a13=(a07+a10);
  a14=arg[0]? arg[0][2] : 0;
  a15=(a06*a14);
  a16=arg[0]? arg[0][5] : 0;
  a09=(a09*a16);
  a15=(a15+a09);
  a15=(a05*a15);
  a11=(a11*a14);
  a06=(a06*a16);
  a11=(a11+a06);
  a05=(a05*a11);
  a15=(a15+a05);
  a04=(a04*a15);
  a03=(a03*a04);
  a04=casadi_sq(a03);
  a13=(a13+a04);
  a13=(a02+a13);
  a02=(a02/a13);
  a13=(a04+a10);
  a15=2.;
  a13=(a13/a15);
  a13=(a02*a13);
  a13=(a01-a13);
  a05=(a00*a13);
  a11=arg[1]? arg[1][3] : 0;
  a06=(a08*a12);
  a06=(a06/a15);
  a06=(a03+a06);
  a06=(a02*a06);
  a16=(a11*a06);
  a05=(a05+a16);
  a16=arg[1]? arg[1][6] : 0;
  a14=(a08*a03);
  a14=(a14/a15);
  a14=(a14-a12);
  a14=(a02*a14);
  a09=(a16*a14);
  a05=(a05+a09);
  if (res[0]!=0) res[0][0]=a05;
  a05=arg[1]? arg[1][1] : 0;
  a09=(a05*a13);
  a17=arg[1]? arg[1][4] : 0;
  a18=(a17*a06);
  a09=(a09+a18);
  a18=arg[1]? arg[1][7] : 0;
  a19=(a18*a14);
  a09=(a09+a19);
  if (res[0]!=0) res[0][1]=a09;
  a09=arg[1]? arg[1][2] : 0;
  a13=(a09*a13);
  a19=arg[1]? arg[1][5] : 0;
  a06=(a19*a06);
  a13=(a13+a06);
  a06=arg[1]? arg[1][8] : 0;
  a14=(a06*a14);
  a13=(a13+a14);
  if (res[0]!=0) res[0][2]=a13;
  a13=(a12*a08);
  a13=(a13/a15);
  a13=(a13-a03);
  a13=(a02*a13);
  a14=(a00*a13);
  a04=(a04+a07);
  a04=(a04/a15);
  a04=(a02*a04);
  a04=(a01-a04);
  a20=(a11*a04);
  a14=(a14+a20);
  a20=(a12*a03);
  a20=(a20/a15);
  a20=(a08+a20);
  a20=(a02*a20);
  a21=(a16*a20);
  a14=(a14+a21);
  if (res[0]!=0) res[0][3]=a14;
  a14=(a05*a13);
  a21=(a17*a04);
  a14=(a14+a21);
  a21=(a18*a20);
  a14=(a14+a21);
  if (res[0]!=0) res[0][4]=a14;
  a13=(a09*a13);
  a04=(a19*a04);
  a13=(a13+a04);
  a20=(a06*a20);
  a13=(a13+a20);
  if (res[0]!=0) res[0][5]=a13;
  a13=(a03*a08);
  a13=(a13/a15);
  a13=(a12+a13);
  a13=(a02*a13);
  a00=(a00*a13);
  a03=(a03*a12);
  a03=(a03/a15);
  a03=(a03-a08);
  a03=(a02*a03);
  a11=(a11*a03);
  a00=(a00+a11);
  a10=(a10+a07);
  a10=(a10/a15);
  a02=(a02*a10);
  a01=(a01-a02);
  a16=(a16*a01);
  a00=(a00+a16);
  if (res[0]!=0) res[0][6]=a00;
  a05=(a05*a13);
  a17=(a17*a03);
  a05=(a05+a17);
  a18=(a18*a01);
  a05=(a05+a18);
  if (res[0]!=0) res[0][7]=a05;
  a09=(a09*a13);
  a19=(a19*a03);
  a09=(a09+a19);
  a06=(a06*a01);
  a09=(a09+a06);
  if (res[0]!=0) res[0][8]=a09;
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
    case 1: return casadi_s0;
    case 2: return casadi_s2;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* chart_point_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
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

/* observe:(g[9],p[3])->(xi[3],E,m[3],e) */
static int casadi_f12(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17;
  a00=arg[1]? arg[1][0] : 0;
  a01=1.5234375000000000e+01;
  a02=(a00/a01);
  if (res[0]!=0) res[0][0]=a02;
  a03=arg[1]? arg[1][1] : 0;
  a04=4.6875000000000000e-01;
  a04=(a03/a04);
  if (res[0]!=0) res[0][1]=a04;
  a05=arg[1]? arg[1][2] : 0;
  a01=(a05/a01);
  if (res[0]!=0) res[0][2]=a01;
  a06=(a00*a02);
  a07=(a03*a04);
  a06=(a06+a07);
  a07=(a05*a01);
  a06=(a06+a07);
  a07=2.3437500000000000e-01;
  a04=casadi_sq(a04);
  a07=(a07*a04);
  a04=7.6171875000000000e+00;
  a02=casadi_sq(a02);
  a02=(a04*a02);
  a07=(a07+a02);
  a01=casadi_sq(a01);
  a04=(a04*a01);
  a07=(a07+a04);
  a04=-1.4715000000000001e+02;
  a01=arg[0]? arg[0][5] : 0;
  a04=(a04*a01);
  a07=(a07+a04);
  a06=(a06-a07);
  if (res[1]!=0) res[1][0]=a06;
  a06=arg[0]? arg[0][8] : 0;
  a07=arg[0]? arg[0][4] : 0;
  a04=(a06*a07);
  a02=arg[0]? arg[0][7] : 0;
  a08=(a02*a01);
  a04=(a04-a08);
  a04=(a04*a00);
  a09=arg[0]? arg[0][2] : 0;
  a10=(a09*a02);
  a11=arg[0]? arg[0][1] : 0;
  a12=(a11*a06);
  a10=(a10-a12);
  a10=(a10*a03);
  a04=(a04+a10);
  a10=(a01*a11);
  a13=(a07*a09);
  a10=(a10-a13);
  a10=(a10*a05);
  a04=(a04+a10);
  if (res[2]!=0) res[2][0]=a04;
  a04=arg[0]? arg[0][6] : 0;
  a10=(a04*a01);
  a14=arg[0]? arg[0][3] : 0;
  a15=(a06*a14);
  a10=(a10-a15);
  a10=(a10*a00);
  a15=arg[0]? arg[0][0] : 0;
  a16=(a15*a06);
  a17=(a09*a04);
  a16=(a16-a17);
  a16=(a16*a03);
  a10=(a10+a16);
  a16=(a14*a09);
  a17=(a01*a15);
  a16=(a16-a17);
  a16=(a16*a05);
  a10=(a10+a16);
  if (res[2]!=0) res[2][1]=a10;
  a10=(a02*a14);
  a16=(a04*a07);
  a10=(a10-a16);
  a10=(a10*a00);
  a00=(a11*a04);
  a16=(a15*a02);
  a00=(a00-a16);
  a00=(a00*a03);
  a10=(a10+a00);
  a00=(a07*a15);
  a03=(a14*a11);
  a00=(a00-a03);
  a00=(a00*a05);
  a10=(a10+a00);
  if (res[2]!=0) res[2][2]=a10;
  a10=casadi_sq(a15);
  a00=casadi_sq(a11);
  a10=(a10+a00);
  a00=casadi_sq(a09);
  a10=(a10+a00);
  a00=1.;
  a10=(a10-a00);
  a10=casadi_fabs(a10);
  a05=(a14*a15);
  a03=(a07*a11);
  a05=(a05+a03);
  a03=(a01*a09);
  a05=(a05+a03);
  a05=casadi_fabs(a05);
  a10=casadi_fmax(a10,a05);
  a05=(a04*a15);
  a03=(a02*a11);
  a05=(a05+a03);
  a03=(a06*a09);
  a05=(a05+a03);
  a05=casadi_fabs(a05);
  a10=casadi_fmax(a10,a05);
  a05=(a15*a14);
  a03=(a11*a07);
  a05=(a05+a03);
  a03=(a09*a01);
  a05=(a05+a03);
  a05=casadi_fabs(a05);
  a10=casadi_fmax(a10,a05);
  a05=casadi_sq(a14);
  a03=casadi_sq(a07);
  a05=(a05+a03);
  a03=casadi_sq(a01);
  a05=(a05+a03);
  a05=(a05-a00);
  a05=casadi_fabs(a05);
  a10=casadi_fmax(a10,a05);
  a05=(a04*a14);
  a03=(a02*a07);
  a05=(a05+a03);
  a03=(a06*a01);
  a05=(a05+a03);
  a05=casadi_fabs(a05);
  a10=casadi_fmax(a10,a05);
  a05=(a15*a04);
  a03=(a11*a02);
  a05=(a05+a03);
  a03=(a09*a06);
  a05=(a05+a03);
  a05=casadi_fabs(a05);
  a10=casadi_fmax(a10,a05);
  a05=(a14*a04);
  a03=(a07*a02);
  a05=(a05+a03);
  a03=(a01*a06);
  a05=(a05+a03);
  a05=casadi_fabs(a05);
  a10=casadi_fmax(a10,a05);
  a05=casadi_sq(a04);
  a03=casadi_sq(a02);
  a05=(a05+a03);
  a03=casadi_sq(a06);
  a05=(a05+a03);
  a05=(a05-a00);
  a05=casadi_fabs(a05);
  a10=casadi_fmax(a10,a05);
  a07=(a07*a06);
  a07=(a07-a08);
  a15=(a15*a07);
  a02=(a02*a09);
  a12=(a12-a02);
  a14=(a14*a12);
  a15=(a15-a14);
  a11=(a11*a01);
  a11=(a11-a13);
  a04=(a04*a11);
  a15=(a15+a04);
  a15=(a15-a00);
  a15=casadi_fabs(a15);
  a10=casadi_fmax(a10,a15);
  if (res[3]!=0) res[3][0]=a10;
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
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* observe_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    case 1: return casadi_s2;
    case 2: return casadi_s1;
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

/* update_p:(z[9],g[9],p[3],h)->(p1[3]) */
static int casadi_f13(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14;
  a00=arg[3]? arg[3][0] : 0;
  a01=5.0000000000000000e-01;
  a02=3.0000000000000004e+00;
  a03=arg[0]? arg[0][2] : 0;
  a04=(a02*a03);
  a05=4.6410161513775439e-01;
  a06=arg[0]? arg[0][5] : 0;
  a07=(a05*a06);
  a04=(a04+a07);
  a04=(a01*a04);
  a07=-6.4641016151377553e+00;
  a03=(a07*a03);
  a06=(a02*a06);
  a03=(a03+a06);
  a03=(a01*a03);
  a04=(a04+a03);
  a04=(a00*a04);
  a03=arg[0]? arg[0][7] : 0;
  a06=(a01*a03);
  a08=(a04*a06);
  a09=arg[0]? arg[0][1] : 0;
  a10=(a02*a09);
  a11=arg[0]? arg[0][4] : 0;
  a12=(a05*a11);
  a10=(a10+a12);
  a10=(a01*a10);
  a09=(a07*a09);
  a11=(a02*a11);
  a09=(a09+a11);
  a09=(a01*a09);
  a10=(a10+a09);
  a10=(a00*a10);
  a09=arg[0]? arg[0][8] : 0;
  a11=(a01*a09);
  a12=(a10*a11);
  a08=(a08-a12);
  a12=arg[0]? arg[0][0] : 0;
  a13=(a02*a12);
  a14=arg[0]? arg[0][3] : 0;
  a05=(a05*a14);
  a13=(a13+a05);
  a13=(a01*a13);
  a07=(a07*a12);
  a02=(a02*a14);
  a07=(a07+a02);
  a07=(a01*a07);
  a13=(a13+a07);
  a00=(a00*a13);
  a13=2.5000000000000000e-01;
  a07=(a04*a09);
  a02=(a10*a03);
  a07=(a07+a02);
  a02=arg[0]? arg[0][6] : 0;
  a14=(a00*a02);
  a07=(a07+a14);
  a13=(a13*a07);
  a07=(a00*a13);
  a08=(a08+a07);
  a08=(a08+a02);
  if (res[0]!=0) res[0][0]=a08;
  a11=(a00*a11);
  a11=(a11+a03);
  a03=(a10*a13);
  a11=(a11+a03);
  a01=(a01*a02);
  a02=(a04*a01);
  a11=(a11-a02);
  if (res[0]!=0) res[0][1]=a11;
  a00=(a00*a06);
  a09=(a09-a00);
  a04=(a04*a13);
  a09=(a09+a04);
  a10=(a10*a01);
  a09=(a09+a10);
  if (res[0]!=0) res[0][2]=a09;
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
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* update_p_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
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

/* velocity_step:(g[9],p[3],xi[3])->(xi1[3]) */
static int casadi_f14(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4;
  a0=arg[2]? arg[2][0] : 0;
  a1=1.5234375000000000e+01;
  a2=(a1*a0);
  a3=arg[1]? arg[1][0] : 0;
  a2=(a2-a3);
  a2=(a2/a1);
  a0=(a0-a2);
  if (res[0]!=0) res[0][0]=a0;
  a0=arg[2]? arg[2][1] : 0;
  a2=4.6875000000000000e-01;
  a3=(a2*a0);
  a4=arg[1]? arg[1][1] : 0;
  a3=(a3-a4);
  a3=(a3/a2);
  a0=(a0-a3);
  if (res[0]!=0) res[0][1]=a0;
  a0=arg[2]? arg[2][2] : 0;
  a3=(a1*a0);
  a2=arg[1]? arg[1][2] : 0;
  a3=(a3-a2);
  a3=(a3/a1);
  a0=(a0-a3);
  if (res[0]!=0) res[0][2]=a0;
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
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* velocity_step_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
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

/* record:(g[9],p[3],xi[3])->(row[16]) */
static int casadi_f15(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16;
  a00=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a02;
  a03=arg[0]? arg[0][3] : 0;
  if (res[0]!=0) res[0][3]=a03;
  a04=arg[0]? arg[0][4] : 0;
  if (res[0]!=0) res[0][4]=a04;
  a05=arg[0]? arg[0][5] : 0;
  if (res[0]!=0) res[0][5]=a05;
  a06=arg[0]? arg[0][6] : 0;
  if (res[0]!=0) res[0][6]=a06;
  a07=arg[0]? arg[0][7] : 0;
  if (res[0]!=0) res[0][7]=a07;
  a08=arg[0]? arg[0][8] : 0;
  if (res[0]!=0) res[0][8]=a08;
  a09=arg[1]? arg[1][0] : 0;
  if (res[0]!=0) res[0][9]=a09;
  a10=arg[1]? arg[1][1] : 0;
  if (res[0]!=0) res[0][10]=a10;
  a11=arg[1]? arg[1][2] : 0;
  if (res[0]!=0) res[0][11]=a11;
  a12=1.5234375000000000e+01;
  a13=arg[2]? arg[2][0] : 0;
  a14=(a12*a13);
  a14=(a14*a13);
  a15=4.6875000000000000e-01;
  a16=arg[2]? arg[2][1] : 0;
  a15=(a15*a16);
  a15=(a15*a16);
  a14=(a14+a15);
  a15=arg[2]? arg[2][2] : 0;
  a12=(a12*a15);
  a12=(a12*a15);
  a14=(a14+a12);
  a12=2.3437500000000000e-01;
  a16=casadi_sq(a16);
  a12=(a12*a16);
  a16=7.6171875000000000e+00;
  a13=casadi_sq(a13);
  a13=(a16*a13);
  a12=(a12+a13);
  a15=casadi_sq(a15);
  a16=(a16*a15);
  a12=(a12+a16);
  a16=-1.4715000000000001e+02;
  a16=(a16*a05);
  a12=(a12+a16);
  a14=(a14-a12);
  if (res[0]!=0) res[0][12]=a14;
  a14=(a08*a04);
  a12=(a07*a05);
  a14=(a14-a12);
  a14=(a14*a09);
  a12=(a02*a07);
  a16=(a01*a08);
  a12=(a12-a16);
  a12=(a12*a10);
  a14=(a14+a12);
  a12=(a05*a01);
  a16=(a04*a02);
  a12=(a12-a16);
  a12=(a12*a11);
  a14=(a14+a12);
  if (res[0]!=0) res[0][13]=a14;
  a14=(a06*a05);
  a12=(a08*a03);
  a14=(a14-a12);
  a14=(a14*a09);
  a08=(a00*a08);
  a12=(a02*a06);
  a08=(a08-a12);
  a08=(a08*a10);
  a14=(a14+a08);
  a02=(a03*a02);
  a05=(a05*a00);
  a02=(a02-a05);
  a02=(a02*a11);
  a14=(a14+a02);
  if (res[0]!=0) res[0][14]=a14;
  a14=(a07*a03);
  a02=(a06*a04);
  a14=(a14-a02);
  a14=(a14*a09);
  a06=(a01*a06);
  a07=(a00*a07);
  a06=(a06-a07);
  a06=(a06*a10);
  a14=(a14+a06);
  a04=(a04*a00);
  a03=(a03*a01);
  a04=(a04-a03);
  a04=(a04*a11);
  a14=(a14+a04);
  if (res[0]!=0) res[0][15]=a14;
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
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* record_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
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

/* step_partials:(z[9],g[9],p[3],h)->(Fs[54],Yz[54],Ys[36]) */
static int casadi_f16(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  a00=-7.3575000000000003e+01;
  a01=arg[3]? arg[3][0] : 0;
  a00=(a00*a01);
  a02=4.;
  a03=arg[0]? arg[0][0] : 0;
  a04=(a01*a03);
  a05=casadi_sq(a04);
  a06=arg[0]? arg[0][1] : 0;
  a07=(a01*a06);
  a08=casadi_sq(a07);
  a09=(a05+a08);
  a10=arg[0]? arg[0][2] : 0;
  a11=(a01*a10);
  a12=casadi_sq(a11);
  a09=(a09+a12);
  a09=(a02+a09);
  a09=(a02/a09);
  a13=(a11*a07);
  a14=2.;
  a13=(a13/a14);
  a13=(a13-a04);
  a13=(a09*a13);
  a15=arg[1]? arg[1][8] : 0;
  a16=(a13*a15);
  a17=1.;
  a05=(a08+a05);
  a05=(a05/a14);
  a05=(a09*a05);
  a05=(a17-a05);
  a18=arg[1]? arg[1][5] : 0;
  a19=(a05*a18);
  a16=(a16-a19);
  a16=(a00*a16);
  a16=(a16/a01);
  if (res[0]!=0) res[0][0]=a16;
  a16=0.;
  if (res[0]!=0) res[0][1]=a16;
  a19=(a04*a07);
  a19=(a19/a14);
  a19=(a11+a19);
  a19=(a09*a19);
  a20=(a19*a15);
  a21=(a04*a11);
  a21=(a21/a14);
  a21=(a21-a07);
  a21=(a09*a21);
  a22=(a21*a18);
  a20=(a20-a22);
  a20=(a00*a20);
  a20=(a20/a01);
  a20=(-a20);
  if (res[0]!=0) res[0][2]=a20;
  a20=arg[0]? arg[0][3] : 0;
  a22=(a01*a20);
  a23=casadi_sq(a22);
  a24=arg[0]? arg[0][4] : 0;
  a25=(a01*a24);
  a26=casadi_sq(a25);
  a27=(a23+a26);
  a28=arg[0]? arg[0][5] : 0;
  a29=(a01*a28);
  a30=casadi_sq(a29);
  a27=(a27+a30);
  a27=(a02+a27);
  a27=(a02/a27);
  a31=(a29*a25);
  a31=(a31/a14);
  a31=(a31-a22);
  a31=(a27*a31);
  a32=(a31*a15);
  a23=(a26+a23);
  a23=(a23/a14);
  a23=(a27*a23);
  a23=(a17-a23);
  a33=(a23*a18);
  a32=(a32-a33);
  a32=(a00*a32);
  a32=(a32/a01);
  if (res[0]!=0) res[0][3]=a32;
  if (res[0]!=0) res[0][4]=a16;
  a32=(a22*a25);
  a32=(a32/a14);
  a32=(a29+a32);
  a32=(a27*a32);
  a33=(a32*a15);
  a34=(a22*a29);
  a34=(a34/a14);
  a34=(a34-a25);
  a34=(a27*a34);
  a35=(a34*a18);
  a33=(a33-a35);
  a33=(a00*a33);
  a33=(a33/a01);
  a33=(-a33);
  if (res[0]!=0) res[0][5]=a33;
  if (res[0]!=0) res[0][6]=a16;
  if (res[0]!=0) res[0][7]=a16;
  if (res[0]!=0) res[0][8]=a16;
  a33=arg[1]? arg[1][2] : 0;
  a05=(a05*a33);
  a11=(a11*a04);
  a11=(a11/a14);
  a07=(a07+a11);
  a07=(a09*a07);
  a11=(a07*a15);
  a05=(a05-a11);
  a05=(a00*a05);
  a05=(a05/a01);
  if (res[0]!=0) res[0][9]=a05;
  if (res[0]!=0) res[0][10]=a16;
  a21=(a21*a33);
  a12=(a12+a08);
  a12=(a12/a14);
  a09=(a09*a12);
  a09=(a17-a09);
  a12=(a09*a15);
  a21=(a21-a12);
  a21=(a00*a21);
  a21=(a21/a01);
  a21=(-a21);
  if (res[0]!=0) res[0][11]=a21;
  a23=(a23*a33);
  a29=(a29*a22);
  a29=(a29/a14);
  a25=(a25+a29);
  a25=(a27*a25);
  a29=(a25*a15);
  a23=(a23-a29);
  a23=(a00*a23);
  a23=(a23/a01);
  if (res[0]!=0) res[0][12]=a23;
  if (res[0]!=0) res[0][13]=a16;
  a34=(a34*a33);
  a30=(a30+a26);
  a30=(a30/a14);
  a27=(a27*a30);
  a27=(a17-a27);
  a30=(a27*a15);
  a34=(a34-a30);
  a34=(a00*a34);
  a34=(a34/a01);
  a34=(-a34);
  if (res[0]!=0) res[0][14]=a34;
  if (res[0]!=0) res[0][15]=a16;
  if (res[0]!=0) res[0][16]=a16;
  if (res[0]!=0) res[0][17]=a16;
  a07=(a07*a18);
  a13=(a13*a33);
  a07=(a07-a13);
  a07=(a00*a07);
  a07=(a07/a01);
  if (res[0]!=0) res[0][18]=a07;
  if (res[0]!=0) res[0][19]=a16;
  a09=(a09*a18);
  a19=(a19*a33);
  a09=(a09-a19);
  a09=(a00*a09);
  a09=(a09/a01);
  a09=(-a09);
  if (res[0]!=0) res[0][20]=a09;
  a25=(a25*a18);
  a31=(a31*a33);
  a25=(a25-a31);
  a25=(a00*a25);
  a25=(a25/a01);
  if (res[0]!=0) res[0][21]=a25;
  if (res[0]!=0) res[0][22]=a16;
  a27=(a27*a18);
  a32=(a32*a33);
  a27=(a27-a32);
  a00=(a00*a27);
  a00=(a00/a01);
  a00=(-a00);
  if (res[0]!=0) res[0][23]=a00;
  if (res[0]!=0) res[0][24]=a16;
  if (res[0]!=0) res[0][25]=a16;
  if (res[0]!=0) res[0][26]=a16;
  if (res[0]!=0) res[0][27]=a16;
  if (res[0]!=0) res[0][28]=a16;
  if (res[0]!=0) res[0][29]=a16;
  if (res[0]!=0) res[0][30]=a16;
  if (res[0]!=0) res[0][31]=a16;
  if (res[0]!=0) res[0][32]=a16;
  if (res[0]!=0) res[0][33]=a17;
  if (res[0]!=0) res[0][34]=a16;
  if (res[0]!=0) res[0][35]=a16;
  if (res[0]!=0) res[0][36]=a16;
  if (res[0]!=0) res[0][37]=a16;
  if (res[0]!=0) res[0][38]=a16;
  if (res[0]!=0) res[0][39]=a16;
  if (res[0]!=0) res[0][40]=a16;
  if (res[0]!=0) res[0][41]=a16;
  if (res[0]!=0) res[0][42]=a16;
  if (res[0]!=0) res[0][43]=a17;
  if (res[0]!=0) res[0][44]=a16;
  if (res[0]!=0) res[0][45]=a16;
  if (res[0]!=0) res[0][46]=a16;
  if (res[0]!=0) res[0][47]=a16;
  if (res[0]!=0) res[0][48]=a16;
  if (res[0]!=0) res[0][49]=a16;
  if (res[0]!=0) res[0][50]=a16;
  if (res[0]!=0) res[0][51]=a16;
  if (res[0]!=0) res[0][52]=a16;
  if (res[0]!=0) res[0][53]=a17;
  a00=arg[1]? arg[1][0] : 0;
  a27=5.0000000000000000e-01;
  a32=3.0000000000000004e+00;
  a25=(a32*a03);
  a31=4.6410161513775439e-01;
  a09=(a31*a20);
  a25=(a25+a09);
  a25=(a27*a25);
  a09=-6.4641016151377553e+00;
  a03=(a09*a03);
  a20=(a32*a20);
  a03=(a03+a20);
  a03=(a27*a03);
  a25=(a25+a03);
  a25=(a01*a25);
  a03=casadi_sq(a25);
  a20=(a32*a06);
  a19=(a31*a24);
  a20=(a20+a19);
  a20=(a27*a20);
  a06=(a09*a06);
  a24=(a32*a24);
  a06=(a06+a24);
  a06=(a27*a06);
  a20=(a20+a06);
  a20=(a01*a20);
  a06=casadi_sq(a20);
  a24=(a03+a06);
  a19=(a32*a10);
  a31=(a31*a28);
  a19=(a19+a31);
  a19=(a27*a19);
  a09=(a09*a10);
  a32=(a32*a28);
  a09=(a09+a32);
  a09=(a27*a09);
  a19=(a19+a09);
  a19=(a01*a19);
  a09=casadi_sq(a19);
  a24=(a24+a09);
  a24=(a02+a24);
  a02=(a02/a24);
  a32=(a19*a25);
  a32=(a32/a14);
  a32=(a20+a32);
  a28=(a02*a32);
  a10=(a00*a28);
  a31=arg[1]? arg[1][3] : 0;
  a07=(a19*a20);
  a07=(a07/a14);
  a07=(a07-a25);
  a13=(a02*a07);
  a34=(a31*a13);
  a10=(a10+a34);
  a34=arg[1]? arg[1][6] : 0;
  a30=(a06+a03);
  a30=(a30/a14);
  a26=(a02*a30);
  a26=(a17-a26);
  a23=(a34*a26);
  a10=(a10+a23);
  a23=-1.7320508075688774e+00;
  a23=(a23*a01);
  a29=(a20*a23);
  a29=(a27*a29);
  a29=(a02*a29);
  a22=(a20*a25);
  a22=(a22/a14);
  a22=(a22-a19);
  a24=(a02/a24);
  a21=(2.*a25);
  a12=(a21*a23);
  a08=(a24*a12);
  a05=(a22*a08);
  a05=(a29-a05);
  a11=(a00*a05);
  a12=(a27*a12);
  a12=(a02*a12);
  a03=(a09+a03);
  a03=(a03/a14);
  a04=(a03*a08);
  a04=(a12-a04);
  a35=(a31*a04);
  a11=(a11-a35);
  a35=(a02*a23);
  a36=(a20*a19);
  a36=(a36/a14);
  a36=(a25+a36);
  a37=(a36*a08);
  a37=(a35-a37);
  a38=(a34*a37);
  a11=(a11+a38);
  a11=(a10*a11);
  a38=arg[1]? arg[1][1] : 0;
  a39=(a38*a28);
  a40=arg[1]? arg[1][4] : 0;
  a41=(a40*a13);
  a39=(a39+a41);
  a41=arg[1]? arg[1][7] : 0;
  a42=(a41*a26);
  a39=(a39+a42);
  a42=(a38*a05);
  a43=(a40*a04);
  a42=(a42-a43);
  a43=(a41*a37);
  a42=(a42+a43);
  a42=(a39*a42);
  a11=(a11+a42);
  a42=(a33*a28);
  a43=(a18*a13);
  a42=(a42+a43);
  a43=(a15*a26);
  a42=(a42+a43);
  a05=(a33*a05);
  a04=(a18*a04);
  a05=(a05-a04);
  a37=(a15*a37);
  a05=(a05+a37);
  a05=(a42*a05);
  a11=(a11+a05);
  if (res[1]!=0) res[1][0]=a11;
  a09=(a09+a06);
  a09=(a09/a14);
  a06=(a02*a09);
  a06=(a17-a06);
  a11=(a00*a06);
  a05=(a25*a20);
  a05=(a05/a14);
  a05=(a19+a05);
  a37=(a02*a05);
  a04=(a31*a37);
  a11=(a11+a04);
  a04=(a25*a19);
  a04=(a04/a14);
  a04=(a04-a20);
  a14=(a02*a04);
  a43=(a34*a14);
  a11=(a11+a43);
  a43=(a19*a23);
  a43=(a27*a43);
  a43=(a02*a43);
  a44=(a32*a08);
  a44=(a43-a44);
  a45=(a00*a44);
  a46=(a07*a08);
  a46=(a46+a35);
  a47=(a31*a46);
  a45=(a45-a47);
  a47=(a30*a08);
  a12=(a12-a47);
  a47=(a34*a12);
  a45=(a45-a47);
  a45=(a11*a45);
  a47=(a38*a06);
  a48=(a40*a37);
  a47=(a47+a48);
  a48=(a41*a14);
  a47=(a47+a48);
  a48=(a38*a44);
  a49=(a40*a46);
  a48=(a48-a49);
  a49=(a41*a12);
  a48=(a48-a49);
  a48=(a47*a48);
  a45=(a45+a48);
  a48=(a33*a06);
  a49=(a18*a37);
  a48=(a48+a49);
  a49=(a15*a14);
  a48=(a48+a49);
  a44=(a33*a44);
  a46=(a18*a46);
  a44=(a44-a46);
  a12=(a15*a12);
  a44=(a44-a12);
  a44=(a48*a44);
  a45=(a45+a44);
  if (res[1]!=0) res[1][1]=a45;
  a45=(a02*a22);
  a44=(a00*a45);
  a12=(a02*a03);
  a12=(a17-a12);
  a46=(a31*a12);
  a44=(a44+a46);
  a46=(a02*a36);
  a49=(a34*a46);
  a44=(a44+a49);
  a49=(a09*a08);
  a50=(a00*a49);
  a51=(a05*a08);
  a51=(a29-a51);
  a52=(a31*a51);
  a50=(a50+a52);
  a08=(a04*a08);
  a08=(a43-a08);
  a52=(a34*a08);
  a50=(a50+a52);
  a50=(a44*a50);
  a52=(a38*a45);
  a53=(a40*a12);
  a52=(a52+a53);
  a53=(a41*a46);
  a52=(a52+a53);
  a53=(a38*a49);
  a54=(a40*a51);
  a53=(a53+a54);
  a54=(a41*a08);
  a53=(a53+a54);
  a53=(a52*a53);
  a50=(a50+a53);
  a53=(a33*a45);
  a54=(a18*a12);
  a53=(a53+a54);
  a54=(a15*a46);
  a53=(a53+a54);
  a49=(a33*a49);
  a51=(a18*a51);
  a49=(a49+a51);
  a08=(a15*a08);
  a49=(a49+a08);
  a49=(a53*a49);
  a50=(a50+a49);
  if (res[1]!=0) res[1][2]=a50;
  a50=2.5000000000000000e-01;
  a49=arg[0]? arg[0][8] : 0;
  a08=(a19*a49);
  a51=arg[0]? arg[0][7] : 0;
  a54=(a20*a51);
  a08=(a08+a54);
  a54=arg[0]? arg[0][6] : 0;
  a55=(a25*a54);
  a08=(a08+a55);
  a08=(a50*a08);
  a55=(a08*a23);
  a56=(a54*a23);
  a56=(a50*a56);
  a57=(a25*a56);
  a57=(a55+a57);
  if (res[1]!=0) res[1][3]=a57;
  a57=(a27*a49);
  a58=(a57*a23);
  a59=(a20*a56);
  a59=(a58+a59);
  if (res[1]!=0) res[1][4]=a59;
  a56=(a19*a56);
  a59=(a27*a51);
  a60=(a59*a23);
  a56=(a56-a60);
  if (res[1]!=0) res[1][5]=a56;
  a56=(a25*a23);
  a56=(a27*a56);
  a56=(a02*a56);
  a61=(2.*a20);
  a62=(a61*a23);
  a63=(a24*a62);
  a64=(a22*a63);
  a64=(a56-a64);
  a65=(a00*a64);
  a66=(a03*a63);
  a67=(a31*a66);
  a65=(a65+a67);
  a67=(a36*a63);
  a67=(a43-a67);
  a68=(a34*a67);
  a65=(a65+a68);
  a65=(a10*a65);
  a68=(a38*a64);
  a69=(a40*a66);
  a68=(a68+a69);
  a69=(a41*a67);
  a68=(a68+a69);
  a68=(a39*a68);
  a65=(a65+a68);
  a64=(a33*a64);
  a66=(a18*a66);
  a64=(a64+a66);
  a67=(a15*a67);
  a64=(a64+a67);
  a64=(a42*a64);
  a65=(a65+a64);
  if (res[1]!=0) res[1][6]=a65;
  a65=(a32*a63);
  a65=(a35-a65);
  a64=(a00*a65);
  a67=(a07*a63);
  a43=(a43-a67);
  a67=(a31*a43);
  a64=(a64+a67);
  a62=(a27*a62);
  a62=(a02*a62);
  a67=(a30*a63);
  a67=(a62-a67);
  a66=(a34*a67);
  a64=(a64-a66);
  a64=(a11*a64);
  a66=(a38*a65);
  a68=(a40*a43);
  a66=(a66+a68);
  a68=(a41*a67);
  a66=(a66-a68);
  a66=(a47*a66);
  a64=(a64+a66);
  a65=(a33*a65);
  a43=(a18*a43);
  a65=(a65+a43);
  a67=(a15*a67);
  a65=(a65-a67);
  a65=(a48*a65);
  a64=(a64+a65);
  if (res[1]!=0) res[1][7]=a64;
  a64=(a05*a63);
  a64=(a56-a64);
  a65=(a31*a64);
  a67=(a09*a63);
  a62=(a62-a67);
  a67=(a00*a62);
  a65=(a65-a67);
  a63=(a04*a63);
  a63=(a63+a35);
  a67=(a34*a63);
  a65=(a65-a67);
  a65=(a44*a65);
  a67=(a40*a64);
  a43=(a38*a62);
  a67=(a67-a43);
  a43=(a41*a63);
  a67=(a67-a43);
  a67=(a52*a67);
  a65=(a65+a67);
  a64=(a18*a64);
  a62=(a33*a62);
  a64=(a64-a62);
  a63=(a15*a63);
  a64=(a64-a63);
  a64=(a53*a64);
  a65=(a65+a64);
  if (res[1]!=0) res[1][8]=a65;
  a65=(a51*a23);
  a65=(a50*a65);
  a64=(a25*a65);
  a64=(a64-a58);
  if (res[1]!=0) res[1][9]=a64;
  a64=(a20*a65);
  a64=(a55+a64);
  if (res[1]!=0) res[1][10]=a64;
  a65=(a19*a65);
  a64=(a27*a54);
  a58=(a64*a23);
  a65=(a65+a58);
  if (res[1]!=0) res[1][11]=a65;
  a65=(2.*a19);
  a63=(a65*a23);
  a62=(a24*a63);
  a67=(a36*a62);
  a67=(a29-a67);
  a43=(a34*a67);
  a66=(a22*a62);
  a66=(a66+a35);
  a68=(a00*a66);
  a63=(a27*a63);
  a63=(a02*a63);
  a69=(a03*a62);
  a69=(a63-a69);
  a70=(a31*a69);
  a68=(a68+a70);
  a43=(a43-a68);
  a43=(a10*a43);
  a68=(a41*a67);
  a70=(a38*a66);
  a71=(a40*a69);
  a70=(a70+a71);
  a68=(a68-a70);
  a68=(a39*a68);
  a43=(a43+a68);
  a67=(a15*a67);
  a66=(a33*a66);
  a69=(a18*a69);
  a66=(a66+a69);
  a67=(a67-a66);
  a67=(a42*a67);
  a43=(a43+a67);
  if (res[1]!=0) res[1][12]=a43;
  a43=(a32*a62);
  a43=(a56-a43);
  a67=(a00*a43);
  a66=(a07*a62);
  a29=(a29-a66);
  a66=(a31*a29);
  a67=(a67+a66);
  a66=(a30*a62);
  a69=(a34*a66);
  a67=(a67+a69);
  a67=(a11*a67);
  a69=(a38*a43);
  a68=(a40*a29);
  a69=(a69+a68);
  a68=(a41*a66);
  a69=(a69+a68);
  a69=(a47*a69);
  a67=(a67+a69);
  a43=(a33*a43);
  a29=(a18*a29);
  a43=(a43+a29);
  a66=(a15*a66);
  a43=(a43+a66);
  a43=(a48*a43);
  a67=(a67+a43);
  if (res[1]!=0) res[1][13]=a67;
  a67=(a05*a62);
  a35=(a35-a67);
  a67=(a31*a35);
  a43=(a09*a62);
  a63=(a63-a43);
  a43=(a00*a63);
  a67=(a67-a43);
  a62=(a04*a62);
  a56=(a56-a62);
  a62=(a34*a56);
  a67=(a67+a62);
  a67=(a44*a67);
  a62=(a40*a35);
  a43=(a38*a63);
  a62=(a62-a43);
  a43=(a41*a56);
  a62=(a62+a43);
  a62=(a52*a62);
  a67=(a67+a62);
  a35=(a18*a35);
  a63=(a33*a63);
  a35=(a35-a63);
  a56=(a15*a56);
  a35=(a35+a56);
  a35=(a53*a35);
  a67=(a67+a35);
  if (res[1]!=0) res[1][14]=a67;
  a23=(a49*a23);
  a23=(a50*a23);
  a67=(a25*a23);
  a60=(a60+a67);
  if (res[1]!=0) res[1][15]=a60;
  a60=(a20*a23);
  a60=(a60-a58);
  if (res[1]!=0) res[1][16]=a60;
  a23=(a19*a23);
  a55=(a55+a23);
  if (res[1]!=0) res[1][17]=a55;
  a55=1.7320508075688774e+00;
  a55=(a55*a01);
  a01=(a20*a55);
  a01=(a27*a01);
  a01=(a02*a01);
  a21=(a21*a55);
  a23=(a24*a21);
  a60=(a22*a23);
  a60=(a01-a60);
  a58=(a00*a60);
  a21=(a27*a21);
  a21=(a02*a21);
  a67=(a03*a23);
  a67=(a21-a67);
  a35=(a31*a67);
  a58=(a58-a35);
  a35=(a02*a55);
  a56=(a36*a23);
  a56=(a35-a56);
  a63=(a34*a56);
  a58=(a58+a63);
  a58=(a10*a58);
  a63=(a38*a60);
  a62=(a40*a67);
  a63=(a63-a62);
  a62=(a41*a56);
  a63=(a63+a62);
  a63=(a39*a63);
  a58=(a58+a63);
  a60=(a33*a60);
  a67=(a18*a67);
  a60=(a60-a67);
  a56=(a15*a56);
  a60=(a60+a56);
  a60=(a42*a60);
  a58=(a58+a60);
  if (res[1]!=0) res[1][18]=a58;
  a58=(a19*a55);
  a58=(a27*a58);
  a58=(a02*a58);
  a60=(a32*a23);
  a60=(a58-a60);
  a56=(a00*a60);
  a67=(a07*a23);
  a67=(a67+a35);
  a63=(a31*a67);
  a56=(a56-a63);
  a63=(a30*a23);
  a21=(a21-a63);
  a63=(a34*a21);
  a56=(a56-a63);
  a56=(a11*a56);
  a63=(a38*a60);
  a62=(a40*a67);
  a63=(a63-a62);
  a62=(a41*a21);
  a63=(a63-a62);
  a63=(a47*a63);
  a56=(a56+a63);
  a60=(a33*a60);
  a67=(a18*a67);
  a60=(a60-a67);
  a21=(a15*a21);
  a60=(a60-a21);
  a60=(a48*a60);
  a56=(a56+a60);
  if (res[1]!=0) res[1][19]=a56;
  a56=(a09*a23);
  a60=(a00*a56);
  a21=(a05*a23);
  a21=(a01-a21);
  a67=(a31*a21);
  a60=(a60+a67);
  a23=(a04*a23);
  a23=(a58-a23);
  a67=(a34*a23);
  a60=(a60+a67);
  a60=(a44*a60);
  a67=(a38*a56);
  a63=(a40*a21);
  a67=(a67+a63);
  a63=(a41*a23);
  a67=(a67+a63);
  a67=(a52*a67);
  a60=(a60+a67);
  a56=(a33*a56);
  a21=(a18*a21);
  a56=(a56+a21);
  a23=(a15*a23);
  a56=(a56+a23);
  a56=(a53*a56);
  a60=(a60+a56);
  if (res[1]!=0) res[1][20]=a60;
  a08=(a08*a55);
  a54=(a54*a55);
  a54=(a50*a54);
  a60=(a25*a54);
  a60=(a08+a60);
  if (res[1]!=0) res[1][21]=a60;
  a57=(a57*a55);
  a60=(a20*a54);
  a60=(a57+a60);
  if (res[1]!=0) res[1][22]=a60;
  a54=(a19*a54);
  a59=(a59*a55);
  a54=(a54-a59);
  if (res[1]!=0) res[1][23]=a54;
  a54=(a25*a55);
  a54=(a27*a54);
  a54=(a02*a54);
  a61=(a61*a55);
  a60=(a24*a61);
  a56=(a22*a60);
  a56=(a54-a56);
  a23=(a00*a56);
  a21=(a03*a60);
  a67=(a31*a21);
  a23=(a23+a67);
  a67=(a36*a60);
  a67=(a58-a67);
  a63=(a34*a67);
  a23=(a23+a63);
  a23=(a10*a23);
  a63=(a38*a56);
  a62=(a40*a21);
  a63=(a63+a62);
  a62=(a41*a67);
  a63=(a63+a62);
  a63=(a39*a63);
  a23=(a23+a63);
  a56=(a33*a56);
  a21=(a18*a21);
  a56=(a56+a21);
  a67=(a15*a67);
  a56=(a56+a67);
  a56=(a42*a56);
  a23=(a23+a56);
  if (res[1]!=0) res[1][24]=a23;
  a23=(a32*a60);
  a23=(a35-a23);
  a56=(a00*a23);
  a67=(a07*a60);
  a58=(a58-a67);
  a67=(a31*a58);
  a56=(a56+a67);
  a61=(a27*a61);
  a61=(a02*a61);
  a67=(a30*a60);
  a67=(a61-a67);
  a21=(a34*a67);
  a56=(a56-a21);
  a56=(a11*a56);
  a21=(a38*a23);
  a63=(a40*a58);
  a21=(a21+a63);
  a63=(a41*a67);
  a21=(a21-a63);
  a21=(a47*a21);
  a56=(a56+a21);
  a23=(a33*a23);
  a58=(a18*a58);
  a23=(a23+a58);
  a67=(a15*a67);
  a23=(a23-a67);
  a23=(a48*a23);
  a56=(a56+a23);
  if (res[1]!=0) res[1][25]=a56;
  a56=(a05*a60);
  a56=(a54-a56);
  a23=(a31*a56);
  a67=(a09*a60);
  a61=(a61-a67);
  a67=(a00*a61);
  a23=(a23-a67);
  a60=(a04*a60);
  a60=(a60+a35);
  a67=(a34*a60);
  a23=(a23-a67);
  a23=(a44*a23);
  a67=(a40*a56);
  a58=(a38*a61);
  a67=(a67-a58);
  a58=(a41*a60);
  a67=(a67-a58);
  a67=(a52*a67);
  a23=(a23+a67);
  a56=(a18*a56);
  a61=(a33*a61);
  a56=(a56-a61);
  a60=(a15*a60);
  a56=(a56-a60);
  a56=(a53*a56);
  a23=(a23+a56);
  if (res[1]!=0) res[1][26]=a23;
  a51=(a51*a55);
  a51=(a50*a51);
  a23=(a25*a51);
  a23=(a23-a57);
  if (res[1]!=0) res[1][27]=a23;
  a23=(a20*a51);
  a23=(a08+a23);
  if (res[1]!=0) res[1][28]=a23;
  a51=(a19*a51);
  a64=(a64*a55);
  a51=(a51+a64);
  if (res[1]!=0) res[1][29]=a51;
  a65=(a65*a55);
  a24=(a24*a65);
  a36=(a36*a24);
  a36=(a01-a36);
  a51=(a34*a36);
  a22=(a22*a24);
  a22=(a22+a35);
  a23=(a00*a22);
  a65=(a27*a65);
  a02=(a02*a65);
  a03=(a03*a24);
  a03=(a02-a03);
  a65=(a31*a03);
  a23=(a23+a65);
  a51=(a51-a23);
  a51=(a10*a51);
  a23=(a41*a36);
  a65=(a38*a22);
  a57=(a40*a03);
  a65=(a65+a57);
  a23=(a23-a65);
  a23=(a39*a23);
  a51=(a51+a23);
  a36=(a15*a36);
  a22=(a33*a22);
  a03=(a18*a03);
  a22=(a22+a03);
  a36=(a36-a22);
  a36=(a42*a36);
  a51=(a51+a36);
  if (res[1]!=0) res[1][30]=a51;
  a32=(a32*a24);
  a32=(a54-a32);
  a51=(a00*a32);
  a07=(a07*a24);
  a01=(a01-a07);
  a07=(a31*a01);
  a51=(a51+a07);
  a30=(a30*a24);
  a07=(a34*a30);
  a51=(a51+a07);
  a51=(a11*a51);
  a07=(a38*a32);
  a36=(a40*a01);
  a07=(a07+a36);
  a36=(a41*a30);
  a07=(a07+a36);
  a07=(a47*a07);
  a51=(a51+a07);
  a32=(a33*a32);
  a01=(a18*a01);
  a32=(a32+a01);
  a30=(a15*a30);
  a32=(a32+a30);
  a32=(a48*a32);
  a51=(a51+a32);
  if (res[1]!=0) res[1][31]=a51;
  a05=(a05*a24);
  a35=(a35-a05);
  a05=(a31*a35);
  a09=(a09*a24);
  a02=(a02-a09);
  a09=(a00*a02);
  a05=(a05-a09);
  a04=(a04*a24);
  a54=(a54-a04);
  a04=(a34*a54);
  a05=(a05+a04);
  a05=(a44*a05);
  a04=(a40*a35);
  a24=(a38*a02);
  a04=(a04-a24);
  a24=(a41*a54);
  a04=(a04+a24);
  a04=(a52*a04);
  a05=(a05+a04);
  a35=(a18*a35);
  a02=(a33*a02);
  a35=(a35-a02);
  a54=(a15*a54);
  a35=(a35+a54);
  a35=(a53*a35);
  a05=(a05+a35);
  if (res[1]!=0) res[1][32]=a05;
  a49=(a49*a55);
  a49=(a50*a49);
  a55=(a25*a49);
  a59=(a59+a55);
  if (res[1]!=0) res[1][33]=a59;
  a59=(a20*a49);
  a59=(a59-a64);
  if (res[1]!=0) res[1][34]=a59;
  a49=(a19*a49);
  a08=(a08+a49);
  if (res[1]!=0) res[1][35]=a08;
  if (res[1]!=0) res[1][36]=a16;
  if (res[1]!=0) res[1][37]=a16;
  if (res[1]!=0) res[1][38]=a16;
  a08=(a50*a25);
  a49=(a25*a08);
  a49=(a49+a17);
  if (res[1]!=0) res[1][39]=a49;
  a49=(a20*a08);
  a59=(a27*a19);
  a49=(a49-a59);
  if (res[1]!=0) res[1][40]=a49;
  a08=(a19*a08);
  a49=(a27*a20);
  a08=(a08+a49);
  if (res[1]!=0) res[1][41]=a08;
  if (res[1]!=0) res[1][42]=a16;
  if (res[1]!=0) res[1][43]=a16;
  if (res[1]!=0) res[1][44]=a16;
  a08=(a50*a20);
  a64=(a25*a08);
  a59=(a59+a64);
  if (res[1]!=0) res[1][45]=a59;
  a59=(a20*a08);
  a59=(a17+a59);
  if (res[1]!=0) res[1][46]=a59;
  a08=(a19*a08);
  a27=(a27*a25);
  a08=(a08-a27);
  if (res[1]!=0) res[1][47]=a08;
  if (res[1]!=0) res[1][48]=a16;
  if (res[1]!=0) res[1][49]=a16;
  if (res[1]!=0) res[1][50]=a16;
  a50=(a50*a19);
  a25=(a25*a50);
  a25=(a25-a49);
  if (res[1]!=0) res[1][51]=a25;
  a20=(a20*a50);
  a27=(a27+a20);
  if (res[1]!=0) res[1][52]=a27;
  a19=(a19*a50);
  a17=(a17+a19);
  if (res[1]!=0) res[1][53]=a17;
  a17=(a12*a34);
  a19=(a46*a31);
  a17=(a17-a19);
  a17=(a10*a17);
  a19=(a12*a41);
  a50=(a46*a40);
  a19=(a19-a50);
  a19=(a39*a19);
  a17=(a17+a19);
  a19=(a12*a15);
  a50=(a46*a18);
  a19=(a19-a50);
  a19=(a42*a19);
  a17=(a17+a19);
  if (res[2]!=0) res[2][0]=a17;
  a17=(a13*a34);
  a19=(a26*a31);
  a17=(a17-a19);
  a17=(a11*a17);
  a19=(a13*a41);
  a50=(a26*a40);
  a19=(a19-a50);
  a19=(a47*a19);
  a17=(a17+a19);
  a19=(a13*a15);
  a50=(a26*a18);
  a19=(a19-a50);
  a19=(a48*a19);
  a17=(a17+a19);
  if (res[2]!=0) res[2][1]=a17;
  a17=(a37*a34);
  a19=(a14*a31);
  a17=(a17-a19);
  a17=(a44*a17);
  a19=(a37*a41);
  a50=(a14*a40);
  a19=(a19-a50);
  a19=(a52*a19);
  a17=(a17+a19);
  a19=(a37*a15);
  a50=(a14*a18);
  a19=(a19-a50);
  a19=(a53*a19);
  a17=(a17+a19);
  if (res[2]!=0) res[2][2]=a17;
  if (res[2]!=0) res[2][3]=a16;
  if (res[2]!=0) res[2][4]=a16;
  if (res[2]!=0) res[2][5]=a16;
  a17=(a46*a00);
  a19=(a45*a34);
  a17=(a17-a19);
  a17=(a10*a17);
  a19=(a46*a38);
  a50=(a45*a41);
  a19=(a19-a50);
  a19=(a39*a19);
  a17=(a17+a19);
  a46=(a46*a33);
  a19=(a45*a15);
  a46=(a46-a19);
  a46=(a42*a46);
  a17=(a17+a46);
  if (res[2]!=0) res[2][6]=a17;
  a17=(a26*a00);
  a46=(a28*a34);
  a17=(a17-a46);
  a17=(a11*a17);
  a46=(a26*a38);
  a19=(a28*a41);
  a46=(a46-a19);
  a46=(a47*a46);
  a17=(a17+a46);
  a26=(a26*a33);
  a46=(a28*a15);
  a26=(a26-a46);
  a26=(a48*a26);
  a17=(a17+a26);
  if (res[2]!=0) res[2][7]=a17;
  a17=(a14*a00);
  a34=(a06*a34);
  a17=(a17-a34);
  a17=(a44*a17);
  a34=(a14*a38);
  a41=(a06*a41);
  a34=(a34-a41);
  a34=(a52*a34);
  a17=(a17+a34);
  a14=(a14*a33);
  a15=(a06*a15);
  a14=(a14-a15);
  a14=(a53*a14);
  a17=(a17+a14);
  if (res[2]!=0) res[2][8]=a17;
  if (res[2]!=0) res[2][9]=a16;
  if (res[2]!=0) res[2][10]=a16;
  if (res[2]!=0) res[2][11]=a16;
  a17=(a45*a31);
  a14=(a12*a00);
  a17=(a17-a14);
  a10=(a10*a17);
  a17=(a45*a40);
  a14=(a12*a38);
  a17=(a17-a14);
  a39=(a39*a17);
  a10=(a10+a39);
  a45=(a45*a18);
  a12=(a12*a33);
  a45=(a45-a12);
  a42=(a42*a45);
  a10=(a10+a42);
  if (res[2]!=0) res[2][12]=a10;
  a10=(a28*a31);
  a42=(a13*a00);
  a10=(a10-a42);
  a11=(a11*a10);
  a10=(a28*a40);
  a42=(a13*a38);
  a10=(a10-a42);
  a47=(a47*a10);
  a11=(a11+a47);
  a28=(a28*a18);
  a13=(a13*a33);
  a28=(a28-a13);
  a48=(a48*a28);
  a11=(a11+a48);
  if (res[2]!=0) res[2][13]=a11;
  a31=(a06*a31);
  a00=(a37*a00);
  a31=(a31-a00);
  a44=(a44*a31);
  a40=(a06*a40);
  a38=(a37*a38);
  a40=(a40-a38);
  a52=(a52*a40);
  a44=(a44+a52);
  a06=(a06*a18);
  a37=(a37*a33);
  a06=(a06-a37);
  a53=(a53*a06);
  a44=(a44+a53);
  if (res[2]!=0) res[2][14]=a44;
  if (res[2]!=0) res[2][15]=a16;
  if (res[2]!=0) res[2][16]=a16;
  if (res[2]!=0) res[2][17]=a16;
  if (res[2]!=0) res[2][18]=a16;
  if (res[2]!=0) res[2][19]=a16;
  if (res[2]!=0) res[2][20]=a16;
  if (res[2]!=0) res[2][21]=a16;
  if (res[2]!=0) res[2][22]=a16;
  if (res[2]!=0) res[2][23]=a16;
  if (res[2]!=0) res[2][24]=a16;
  if (res[2]!=0) res[2][25]=a16;
  if (res[2]!=0) res[2][26]=a16;
  if (res[2]!=0) res[2][27]=a16;
  if (res[2]!=0) res[2][28]=a16;
  if (res[2]!=0) res[2][29]=a16;
  if (res[2]!=0) res[2][30]=a16;
  if (res[2]!=0) res[2][31]=a16;
  if (res[2]!=0) res[2][32]=a16;
  if (res[2]!=0) res[2][33]=a16;
  if (res[2]!=0) res[2][34]=a16;
  if (res[2]!=0) res[2][35]=a16;
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
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* step_partials_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s5;
    case 1: return casadi_s5;
    case 2: return casadi_s6;
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
#define HPGEN_N 3
#define HPGEN_NN (HPGEN_N * HPGEN_N)
#define HPGEN_D 3
#define HPGEN_NZ 9
#define HPGEN_OK 0
#define HPGEN_NO_CONVERGENCE 1
#define HPGEN_NONFINITE 2
#define HPGEN_DOMAIN 3
#define HPGEN_RECORD 4
/* the scene's record row (kernel record): its width and what it needs */
#define HPGEN_W 16
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

HPGEN_EXPORT const char* hpgen_hash(void) { return "72a44fd1ee755e2c4425d908d39fb933f3430a0480e798986ddd5164069c3cd9"; }

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

/* residual(z[9], g[9], p[3], h[1]) -> (F[9]) */
#define HPGEN_RESIDUAL_SZ_ARG 4
#define HPGEN_RESIDUAL_SZ_RES 1
#define HPGEN_RESIDUAL_SZ_IW 0
#define HPGEN_RESIDUAL_SZ_W 61
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

/* jacobian(z[9], g[9], p[3], h[1]) -> (J[81]) */
/* = output 1 of residual_jacobian (the same CasADi algorithm; its other outputs are
   computed into scratch and dropped) */
HPGEN_EXPORT int hpgen_kernel_jacobian(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    double scratch[HPGEN_NZ];
    return hpgen_k_residual_jacobian(in0, in1, in2, in3, scratch, out0);
}

/* residual_jacobian(z[9], g[9], p[3], h[1]) -> (F[9], J[81]) */
#define HPGEN_RESIDUAL_JACOBIAN_SZ_ARG 4
#define HPGEN_RESIDUAL_JACOBIAN_SZ_RES 2
#define HPGEN_RESIDUAL_JACOBIAN_SZ_IW 0
#define HPGEN_RESIDUAL_JACOBIAN_SZ_W 160
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

/* update(z[9], g[9], p[3], h[1]) -> (g1[9], p1[3]) */
#define HPGEN_UPDATE_SZ_ARG 4
#define HPGEN_UPDATE_SZ_RES 2
#define HPGEN_UPDATE_SZ_IW 0
#define HPGEN_UPDATE_SZ_W 23
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

/* guess(xi[3], g[9], p[3], h[1]) -> (z0[9]) */
#define HPGEN_GUESS_SZ_ARG 4
#define HPGEN_GUESS_SZ_RES 1
#define HPGEN_GUESS_SZ_IW 0
#define HPGEN_GUESS_SZ_W 4
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

/* legendre(g[9], xi[3]) -> (mu[3]) */
#define HPGEN_LEGENDRE_SZ_ARG 2
#define HPGEN_LEGENDRE_SZ_RES 1
#define HPGEN_LEGENDRE_SZ_IW 0
#define HPGEN_LEGENDRE_SZ_W 3
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

/* hessian(g[9], xi[3]) -> (H[9]) */
#define HPGEN_HESSIAN_SZ_ARG 2
#define HPGEN_HESSIAN_SZ_RES 1
#define HPGEN_HESSIAN_SZ_IW 0
#define HPGEN_HESSIAN_SZ_W 3
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

/* energy(g[9], xi[3]) -> (E[1]) */
#define HPGEN_ENERGY_SZ_ARG 2
#define HPGEN_ENERGY_SZ_RES 1
#define HPGEN_ENERGY_SZ_IW 0
#define HPGEN_ENERGY_SZ_W 5
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

/* momentum(g[9], p[3]) -> (m[3]) */
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

/* defect(g[9]) -> (e[1]) */
#define HPGEN_DEFECT_SZ_ARG 1
#define HPGEN_DEFECT_SZ_RES 1
#define HPGEN_DEFECT_SZ_IW 0
#define HPGEN_DEFECT_SZ_W 13
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

/* margin(z[9], h[1]) -> (m[1]) */
#define HPGEN_MARGIN_SZ_ARG 2
#define HPGEN_MARGIN_SZ_RES 1
#define HPGEN_MARGIN_SZ_IW 0
#define HPGEN_MARGIN_SZ_W 14
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

/* section(g[9], p[3]) -> (s[1]) */
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

/* chart_point(z[9], g[9], h[1], theta[1]) -> (g_theta[9]) */
#define HPGEN_CHART_POINT_SZ_ARG 4
#define HPGEN_CHART_POINT_SZ_RES 1
#define HPGEN_CHART_POINT_SZ_IW 0
#define HPGEN_CHART_POINT_SZ_W 22
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

/* observe(g[9], p[3]) -> (xi[3], E[1], m[3], e[1]) */
#define HPGEN_OBSERVE_SZ_ARG 2
#define HPGEN_OBSERVE_SZ_RES 4
#define HPGEN_OBSERVE_SZ_IW 0
#define HPGEN_OBSERVE_SZ_W 18
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

/* update_p(z[9], g[9], p[3], h[1]) -> (p1[3]) */
#define HPGEN_UPDATE_P_SZ_ARG 4
#define HPGEN_UPDATE_P_SZ_RES 1
#define HPGEN_UPDATE_P_SZ_IW 0
#define HPGEN_UPDATE_P_SZ_W 15
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

/* velocity_step(g[9], p[3], xi[3]) -> (xi1[3]) */
#define HPGEN_VELOCITY_STEP_SZ_ARG 3
#define HPGEN_VELOCITY_STEP_SZ_RES 1
#define HPGEN_VELOCITY_STEP_SZ_IW 0
#define HPGEN_VELOCITY_STEP_SZ_W 5
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

/* record(g[9], p[3], xi[3]) -> (row[16]) */
#define HPGEN_RECORD_SZ_ARG 3
#define HPGEN_RECORD_SZ_RES 1
#define HPGEN_RECORD_SZ_IW 0
#define HPGEN_RECORD_SZ_W 17
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

/* step_partials(z[9], g[9], p[3], h[1]) -> (Fs[54], Yz[54], Ys[36]) */
#define HPGEN_STEP_PARTIALS_SZ_ARG 4
#define HPGEN_STEP_PARTIALS_SZ_RES 3
#define HPGEN_STEP_PARTIALS_SZ_IW 0
#define HPGEN_STEP_PARTIALS_SZ_W 72
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
