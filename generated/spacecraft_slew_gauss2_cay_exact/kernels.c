/*
 * hpgen generated module spacecraft_slew_gauss2_cay_exact -- do not edit, regenerate with hpgen
 * model: spacecraft_slew
 * options: tableau=gauss2, tau=cay, rkmk=exact
 * hpgen version: 0.1.0
 * content hash (normalized model + options): 959fcb561df343765dbe7a3e98a821542711c856204215f698928b3c81b6b42f
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
  #define CASADI_PREFIX(ID) hpgen_spacecraft_slew_gauss2_cay_exact__ ## ID
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
#define casadi_s7 CASADI_PREFIX(s7)
#define casadi_s8 CASADI_PREFIX(s8)
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
CASADI_SYMBOL_EXPORT void hpgen_spacecraft_slew_gauss2_cay_exact__casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int hpgen_spacecraft_slew_gauss2_cay_exact__casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int hpgen_spacecraft_slew_gauss2_cay_exact__casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {3, 1, 1};
static const casadi_int casadi_s2[3] = {4, 1, 1};
static const casadi_int casadi_s3[3] = {81, 1, 1};
static const casadi_int casadi_s4[3] = {1, 1, 1};
static const casadi_int casadi_s5[3] = {18, 1, 1};
static const casadi_int casadi_s6[3] = {54, 1, 1};
static const casadi_int casadi_s7[3] = {36, 1, 1};
static const casadi_int casadi_s8[3] = {24, 1, 1};

/* residual:(z[9],g[9],p[3],h[4])->(F[9]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73, a74, a75, a76, a77, a78, a79;
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
  a26=3.;
  a27=(a09*a14);
  a28=(a06*a17);
  a27=(a27-a28);
  a27=(a27/a15);
  a27=(a20+a27);
  a27=(a11*a27);
  a28=(a26*a27);
  a29=(a09*a19);
  a30=(a06*a20);
  a31=(a02*a14);
  a30=(a30-a31);
  a30=(a30/a15);
  a30=(a17+a30);
  a30=(a11*a30);
  a31=(2.*a30);
  a32=(a06*a31);
  a29=(a29-a32);
  a29=(a29/a15);
  a29=(a28-a29);
  a29=(a11*a29);
  a29=(a29-a22);
  a32=(a25*a29);
  a33=1.5000000000000002e+00;
  a34=(a00*a16);
  a35=casadi_sq(a34);
  a36=(a00*a18);
  a37=casadi_sq(a36);
  a38=(a35+a37);
  a39=(a00*a21);
  a40=casadi_sq(a39);
  a38=(a38+a40);
  a38=(a04+a38);
  a38=(a04/a38);
  a41=-6.4641016151377553e+00;
  a01=(a41*a01);
  a21=(a13*a21);
  a01=(a01+a21);
  a05=(a41*a05);
  a16=(a13*a16);
  a05=(a05+a16);
  a16=(a36*a05);
  a41=(a41*a08);
  a13=(a13*a18);
  a41=(a41+a13);
  a13=(a34*a41);
  a16=(a16-a13);
  a16=(a16/a15);
  a16=(a01+a16);
  a16=(a38*a16);
  a26=(a26*a16);
  a13=(a39*a41);
  a18=(a36*a01);
  a13=(a13-a18);
  a13=(a13/a15);
  a13=(a05+a13);
  a13=(a38*a13);
  a18=(a36*a13);
  a08=(a34*a01);
  a21=(a39*a05);
  a08=(a08-a21);
  a08=(a08/a15);
  a08=(a41+a08);
  a08=(a38*a08);
  a21=(2.*a08);
  a42=(a34*a21);
  a18=(a18-a42);
  a18=(a18/a15);
  a18=(a26-a18);
  a18=(a38*a18);
  a18=(a18-a22);
  a42=(a33*a18);
  a32=(a32+a42);
  a42=(a00*a32);
  a43=(a24*a42);
  a43=(a23+a43);
  a44=2.5000000000000000e-01;
  a29=(a33*a29);
  a45=-3.2320508075688776e+00;
  a18=(a45*a18);
  a29=(a29+a18);
  a18=(a00*a29);
  a46=(a44*a18);
  a43=(a43+a46);
  a46=(a03*a43);
  a47=(a19*a46);
  a48=(a06*a28);
  a49=(a02*a19);
  a48=(a48-a49);
  a48=(a48/a15);
  a48=(a31-a48);
  a48=(a11*a48);
  a49=arg[0]? arg[0][7] : 0;
  a48=(a48-a49);
  a50=(a33*a48);
  a51=(a34*a26);
  a52=(a39*a13);
  a51=(a51-a52);
  a51=(a51/a15);
  a51=(a21-a51);
  a51=(a38*a51);
  a51=(a51-a49);
  a52=(a45*a51);
  a50=(a50+a52);
  a47=(a47+a50);
  a52=(a06*a19);
  a53=(a09*a30);
  a52=(a52+a53);
  a53=(a02*a27);
  a52=(a52+a53);
  a52=(a52/a04);
  a53=(a00*a49);
  a53=(a03*a53);
  a48=(a25*a48);
  a51=(a33*a51);
  a48=(a48+a51);
  a51=(a00*a48);
  a54=(a24*a51);
  a54=(a53+a54);
  a50=(a00*a50);
  a55=(a44*a50);
  a54=(a54+a55);
  a55=(a52*a54);
  a47=(a47-a55);
  a55=(a02*a43);
  a56=(a09*a54);
  a55=(a55+a56);
  a56=arg[0]? arg[0][6] : 0;
  a57=(a00*a56);
  a57=(a03*a57);
  a31=(a02*a31);
  a28=(a09*a28);
  a31=(a31-a28);
  a31=(a31/a15);
  a31=(a19-a31);
  a31=(a11*a31);
  a31=(a31-a56);
  a25=(a25*a31);
  a21=(a39*a21);
  a26=(a36*a26);
  a21=(a21-a26);
  a21=(a21/a15);
  a21=(a13-a21);
  a21=(a38*a21);
  a21=(a21-a56);
  a26=(a33*a21);
  a25=(a25+a26);
  a26=(a00*a25);
  a24=(a24*a26);
  a24=(a57+a24);
  a33=(a33*a31);
  a45=(a45*a21);
  a33=(a33+a45);
  a45=(a00*a33);
  a21=(a44*a45);
  a24=(a24+a21);
  a21=(a06*a24);
  a55=(a55+a21);
  a55=(a44*a55);
  a21=(a30*a55);
  a47=(a47-a21);
  a21=(a03*a24);
  a31=(a27*a21);
  a47=(a47-a31);
  a31=(a03*a47);
  a28=(a02*a31);
  a43=(a52*a43);
  a29=(a29-a43);
  a54=(a03*a54);
  a43=(a19*a54);
  a29=(a29-a43);
  a43=(a27*a55);
  a29=(a29-a43);
  a21=(a30*a21);
  a29=(a29+a21);
  a21=(a03*a29);
  a43=(a09*a21);
  a58=(a28-a43);
  a59=(a09*a47);
  a60=(a02*a29);
  a59=(a59+a60);
  a54=(a27*a54);
  a46=(a30*a46);
  a54=(a54-a46);
  a54=(a54+a33);
  a52=(a52*a24);
  a54=(a54-a52);
  a55=(a19*a55);
  a54=(a54-a55);
  a55=(a06*a54);
  a59=(a59+a55);
  a59=(a44*a59);
  a55=(a06*a59);
  a58=(a58+a55);
  a58=(a58+a54);
  a52=-5.0000000000000000e-01;
  a24=arg[3]? arg[3][2] : 0;
  a52=(a52*a24);
  a24=arg[1]? arg[1][2] : 0;
  a33=(a09*a06);
  a33=(a33/a15);
  a33=(a33-a02);
  a33=(a11*a33);
  a46=(a24*a33);
  a60=arg[1]? arg[1][5] : 0;
  a61=1.;
  a62=(a12+a07);
  a62=(a62/a15);
  a62=(a11*a62);
  a62=(a61-a62);
  a63=(a60*a62);
  a46=(a46+a63);
  a63=arg[1]? arg[1][8] : 0;
  a64=(a09*a02);
  a64=(a64/a15);
  a64=(a06+a64);
  a64=(a11*a64);
  a65=(a63*a64);
  a46=(a46+a65);
  a65=8.4147098480789650e-01;
  a66=arg[1]? arg[1][0] : 0;
  a67=(a02*a06);
  a67=(a67/a15);
  a67=(a09+a67);
  a67=(a11*a67);
  a68=(a66*a67);
  a69=arg[1]? arg[1][3] : 0;
  a70=(a02*a09);
  a70=(a70/a15);
  a70=(a70-a06);
  a70=(a11*a70);
  a71=(a69*a70);
  a68=(a68+a71);
  a71=arg[1]? arg[1][6] : 0;
  a07=(a10+a07);
  a07=(a07/a15);
  a07=(a11*a07);
  a07=(a61-a07);
  a72=(a71*a07);
  a68=(a68+a72);
  a72=(a65*a68);
  a46=(a46+a72);
  a72=-5.4030230586813977e-01;
  a73=arg[1]? arg[1][1] : 0;
  a67=(a73*a67);
  a74=arg[1]? arg[1][4] : 0;
  a70=(a74*a70);
  a67=(a67+a70);
  a70=arg[1]? arg[1][7] : 0;
  a07=(a70*a07);
  a67=(a67+a07);
  a07=(a72*a67);
  a46=(a46+a07);
  a46=(a52*a46);
  a07=arg[3]? arg[3][3] : 0;
  a19=(a07*a19);
  a46=(a46-a19);
  a19=(a03*a00);
  a46=(a46*a19);
  a58=(a58+a46);
  a58=(a58/a00);
  if (res[0]!=0) res[0][0]=a58;
  a21=(a06*a21);
  a58=(a47+a21);
  a46=(a09*a59);
  a58=(a58+a46);
  a75=(a03*a54);
  a76=(a02*a75);
  a58=(a58-a76);
  a77=5.4030230586813977e-01;
  a68=(a77*a68);
  a12=(a12+a10);
  a12=(a12/a15);
  a12=(a11*a12);
  a12=(a61-a12);
  a10=(a24*a12);
  a78=(a06*a09);
  a78=(a78/a15);
  a78=(a02+a78);
  a78=(a11*a78);
  a79=(a60*a78);
  a10=(a10+a79);
  a79=(a06*a02);
  a79=(a79/a15);
  a79=(a79-a09);
  a11=(a11*a79);
  a79=(a63*a11);
  a10=(a10+a79);
  a68=(a68-a10);
  a67=(a65*a67);
  a68=(a68+a67);
  a68=(a52*a68);
  a30=(a07*a30);
  a68=(a68-a30);
  a68=(a68*a19);
  a58=(a58+a68);
  a58=(a58/a00);
  if (res[0]!=0) res[0][1]=a58;
  a06=(a06*a31);
  a31=(a29-a06);
  a02=(a02*a59);
  a31=(a31+a02);
  a09=(a09*a75);
  a31=(a31+a09);
  a75=(a73*a12);
  a59=(a74*a78);
  a75=(a75+a59);
  a59=(a70*a11);
  a75=(a75+a59);
  a75=(a77*a75);
  a59=(a66*a33);
  a58=(a69*a62);
  a59=(a59+a58);
  a58=(a71*a64);
  a59=(a59+a58);
  a59=(a72*a59);
  a75=(a75+a59);
  a59=-8.4147098480789650e-01;
  a12=(a66*a12);
  a78=(a69*a78);
  a12=(a12+a78);
  a11=(a71*a11);
  a12=(a12+a11);
  a12=(a59*a12);
  a75=(a75+a12);
  a33=(a73*a33);
  a62=(a74*a62);
  a33=(a33+a62);
  a64=(a70*a64);
  a33=(a33+a64);
  a33=(a59*a33);
  a75=(a75+a33);
  a75=(a52*a75);
  a27=(a07*a27);
  a75=(a75-a27);
  a75=(a75*a19);
  a31=(a31+a75);
  a31=(a31/a00);
  if (res[0]!=0) res[0][2]=a31;
  a31=(a36*a34);
  a31=(a31/a15);
  a31=(a31-a39);
  a31=(a38*a31);
  a75=(a24*a31);
  a27=(a40+a35);
  a27=(a27/a15);
  a27=(a38*a27);
  a27=(a61-a27);
  a33=(a60*a27);
  a75=(a75+a33);
  a33=(a36*a39);
  a33=(a33/a15);
  a33=(a34+a33);
  a33=(a38*a33);
  a64=(a63*a33);
  a75=(a75+a64);
  a64=(a39*a34);
  a64=(a64/a15);
  a64=(a36+a64);
  a64=(a38*a64);
  a62=(a66*a64);
  a12=(a39*a36);
  a12=(a12/a15);
  a12=(a12-a34);
  a12=(a38*a12);
  a11=(a69*a12);
  a62=(a62+a11);
  a35=(a37+a35);
  a35=(a35/a15);
  a35=(a38*a35);
  a35=(a61-a35);
  a11=(a71*a35);
  a62=(a62+a11);
  a11=(a65*a62);
  a75=(a75+a11);
  a64=(a73*a64);
  a12=(a74*a12);
  a64=(a64+a12);
  a35=(a70*a35);
  a64=(a64+a35);
  a35=(a72*a64);
  a75=(a75+a35);
  a75=(a52*a75);
  a35=(a07*a13);
  a75=(a75-a35);
  a75=(a75*a19);
  a42=(a44*a42);
  a23=(a23+a42);
  a42=-3.8675134594812879e-02;
  a18=(a42*a18);
  a23=(a23+a18);
  a18=(a03*a23);
  a35=(a08*a18);
  a25=(a25-a35);
  a51=(a44*a51);
  a53=(a53+a51);
  a50=(a42*a50);
  a53=(a53+a50);
  a50=(a03*a53);
  a51=(a16*a50);
  a25=(a25+a51);
  a51=(a34*a13);
  a35=(a36*a08);
  a51=(a51+a35);
  a35=(a39*a16);
  a51=(a51+a35);
  a51=(a51/a04);
  a26=(a44*a26);
  a57=(a57+a26);
  a42=(a42*a45);
  a57=(a57+a42);
  a42=(a51*a57);
  a25=(a25-a42);
  a42=(a39*a23);
  a45=(a36*a53);
  a42=(a42+a45);
  a45=(a34*a57);
  a42=(a42+a45);
  a42=(a44*a42);
  a45=(a13*a42);
  a25=(a25-a45);
  a75=(a75+a25);
  a18=(a13*a18);
  a48=(a48+a18);
  a53=(a51*a53);
  a48=(a48-a53);
  a53=(a08*a42);
  a48=(a48-a53);
  a57=(a03*a57);
  a53=(a16*a57);
  a48=(a48-a53);
  a53=(a03*a48);
  a18=(a39*a53);
  a75=(a75+a18);
  a45=(a34*a25);
  a26=(a36*a48);
  a45=(a45+a26);
  a51=(a51*a23);
  a32=(a32-a51);
  a13=(a13*a50);
  a32=(a32-a13);
  a42=(a16*a42);
  a32=(a32-a42);
  a57=(a08*a57);
  a32=(a32+a57);
  a57=(a39*a32);
  a45=(a45+a57);
  a45=(a44*a45);
  a57=(a34*a45);
  a75=(a75+a57);
  a42=(a03*a32);
  a13=(a36*a42);
  a75=(a75-a13);
  a75=(a75/a00);
  if (res[0]!=0) res[0][3]=a75;
  a62=(a77*a62);
  a40=(a40+a37);
  a40=(a40/a15);
  a40=(a38*a40);
  a61=(a61-a40);
  a24=(a24*a61);
  a40=(a34*a36);
  a40=(a40/a15);
  a40=(a39+a40);
  a40=(a38*a40);
  a60=(a60*a40);
  a24=(a24+a60);
  a60=(a34*a39);
  a60=(a60/a15);
  a60=(a60-a36);
  a38=(a38*a60);
  a63=(a63*a38);
  a24=(a24+a63);
  a62=(a62-a24);
  a65=(a65*a64);
  a62=(a62+a65);
  a62=(a52*a62);
  a08=(a07*a08);
  a62=(a62-a08);
  a62=(a62*a19);
  a08=(a03*a25);
  a65=(a39*a08);
  a62=(a62-a65);
  a62=(a62+a48);
  a64=(a36*a45);
  a62=(a62+a64);
  a42=(a34*a42);
  a62=(a62+a42);
  a62=(a62/a00);
  if (res[0]!=0) res[0][4]=a62;
  a62=(a73*a61);
  a24=(a74*a40);
  a62=(a62+a24);
  a24=(a70*a38);
  a62=(a62+a24);
  a77=(a77*a62);
  a62=(a66*a31);
  a24=(a69*a27);
  a62=(a62+a24);
  a24=(a71*a33);
  a62=(a62+a24);
  a72=(a72*a62);
  a77=(a77+a72);
  a66=(a66*a61);
  a69=(a69*a40);
  a66=(a66+a69);
  a71=(a71*a38);
  a66=(a66+a71);
  a66=(a59*a66);
  a77=(a77+a66);
  a73=(a73*a31);
  a74=(a74*a27);
  a73=(a73+a74);
  a70=(a70*a33);
  a73=(a73+a70);
  a59=(a59*a73);
  a77=(a77+a59);
  a52=(a52*a77);
  a07=(a07*a16);
  a52=(a52-a07);
  a52=(a52*a19);
  a36=(a36*a08);
  a52=(a52+a36);
  a34=(a34*a53);
  a52=(a52-a34);
  a39=(a39*a45);
  a52=(a52+a39);
  a52=(a52+a32);
  a52=(a52/a00);
  if (res[0]!=0) res[0][5]=a52;
  a52=arg[2]? arg[2][0] : 0;
  a20=(a03*a20);
  a01=(a03*a01);
  a20=(a20+a01);
  a20=(a00*a20);
  a01=(a03*a49);
  a45=(a20*a01);
  a17=(a03*a17);
  a41=(a03*a41);
  a17=(a17+a41);
  a17=(a00*a17);
  a41=(a03*a22);
  a53=(a17*a41);
  a45=(a45-a53);
  a14=(a03*a14);
  a05=(a03*a05);
  a14=(a14+a05);
  a00=(a00*a14);
  a14=(a20*a22);
  a05=(a17*a49);
  a14=(a14+a05);
  a05=(a00*a56);
  a14=(a14+a05);
  a44=(a44*a14);
  a14=(a00*a44);
  a45=(a45-a14);
  a45=(a45-a56);
  a45=(a45-a25);
  a45=(a45+a18);
  a45=(a45-a57);
  a45=(a45-a13);
  a45=(a45+a28);
  a45=(a45-a43);
  a45=(a45-a55);
  a45=(a45-a54);
  a52=(a52+a45);
  if (res[0]!=0) res[0][6]=a52;
  a52=arg[2]? arg[2][1] : 0;
  a41=(a00*a41);
  a41=(a41-a49);
  a49=(a17*a44);
  a41=(a41-a49);
  a03=(a03*a56);
  a56=(a20*a03);
  a41=(a41-a56);
  a41=(a41-a65);
  a41=(a41-a48);
  a41=(a41-a64);
  a41=(a41+a42);
  a41=(a41-a47);
  a41=(a41+a21);
  a41=(a41-a46);
  a41=(a41-a76);
  a52=(a52+a41);
  if (res[0]!=0) res[0][7]=a52;
  a52=arg[2]? arg[2][2] : 0;
  a17=(a17*a03);
  a00=(a00*a01);
  a22=(a22+a00);
  a20=(a20*a44);
  a22=(a22+a20);
  a17=(a17-a22);
  a17=(a17+a36);
  a17=(a17-a34);
  a17=(a17-a39);
  a17=(a17-a32);
  a17=(a17-a06);
  a17=(a17-a29);
  a17=(a17-a02);
  a17=(a17+a09);
  a52=(a52+a17);
  if (res[0]!=0) res[0][8]=a52;
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

/* residual_jacobian:(z[9],g[9],p[3],h[4])->(F[9],J[81]) */
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
  casadi_real a156, a157, a158, a159, a160, a161, a162, a163, a164, a165, a166, a167;
  casadi_real a168, a169, a170, a171, a172, a173, a174, a175, a176, a177, a178, a179;
  casadi_real a180, a181;
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
  a029=3.;
  a030=(a009*a015);
  a031=(a006*a018);
  a030=(a030-a031);
  a030=(a030/a023);
  a030=(a021+a030);
  a031=(a013*a030);
  a032=(a029*a031);
  a033=(a009*a024);
  a034=(a006*a021);
  a035=(a002*a015);
  a034=(a034-a035);
  a034=(a034/a023);
  a034=(a018+a034);
  a035=(a013*a034);
  a036=(2.*a035);
  a037=(a006*a036);
  a033=(a033-a037);
  a033=(a033/a023);
  a033=(a032-a033);
  a037=(a013*a033);
  a037=(a037-a025);
  a038=(a028*a037);
  a039=1.5000000000000002e+00;
  a040=(a000*a017);
  a041=casadi_sq(a040);
  a042=(a000*a019);
  a043=casadi_sq(a042);
  a044=(a041+a043);
  a045=(a000*a022);
  a046=casadi_sq(a045);
  a044=(a044+a046);
  a044=(a004+a044);
  a047=(a004/a044);
  a048=-6.4641016151377553e+00;
  a001=(a048*a001);
  a022=(a014*a022);
  a001=(a001+a022);
  a005=(a048*a005);
  a017=(a014*a017);
  a005=(a005+a017);
  a017=(a042*a005);
  a008=(a048*a008);
  a019=(a014*a019);
  a008=(a008+a019);
  a019=(a040*a008);
  a017=(a017-a019);
  a017=(a017/a023);
  a017=(a001+a017);
  a019=(a047*a017);
  a022=(a029*a019);
  a049=(a045*a008);
  a050=(a042*a001);
  a049=(a049-a050);
  a049=(a049/a023);
  a049=(a005+a049);
  a050=(a047*a049);
  a051=(a042*a050);
  a052=(a040*a001);
  a053=(a045*a005);
  a052=(a052-a053);
  a052=(a052/a023);
  a052=(a008+a052);
  a053=(a047*a052);
  a054=(2.*a053);
  a055=(a040*a054);
  a051=(a051-a055);
  a051=(a051/a023);
  a051=(a022-a051);
  a055=(a047*a051);
  a055=(a055-a025);
  a056=(a039*a055);
  a038=(a038+a056);
  a056=(a000*a038);
  a057=(a027*a056);
  a057=(a026+a057);
  a058=2.5000000000000000e-01;
  a037=(a039*a037);
  a059=-3.2320508075688776e+00;
  a055=(a059*a055);
  a037=(a037+a055);
  a055=(a000*a037);
  a060=(a058*a055);
  a057=(a057+a060);
  a060=(a003*a057);
  a061=(a024*a060);
  a062=(a006*a032);
  a063=(a002*a024);
  a062=(a062-a063);
  a062=(a062/a023);
  a062=(a036-a062);
  a063=(a013*a062);
  a064=arg[0]? arg[0][7] : 0;
  a063=(a063-a064);
  a065=(a039*a063);
  a066=(a040*a022);
  a067=(a045*a050);
  a066=(a066-a067);
  a066=(a066/a023);
  a066=(a054-a066);
  a067=(a047*a066);
  a067=(a067-a064);
  a068=(a059*a067);
  a065=(a065+a068);
  a061=(a061+a065);
  a068=(a006*a024);
  a069=(a009*a035);
  a068=(a068+a069);
  a069=(a002*a031);
  a068=(a068+a069);
  a068=(a068/a004);
  a069=(a000*a064);
  a069=(a003*a069);
  a063=(a028*a063);
  a067=(a039*a067);
  a063=(a063+a067);
  a067=(a000*a063);
  a070=(a027*a067);
  a070=(a069+a070);
  a065=(a000*a065);
  a071=(a058*a065);
  a070=(a070+a071);
  a071=(a068*a070);
  a061=(a061-a071);
  a071=(a002*a057);
  a072=(a009*a070);
  a071=(a071+a072);
  a072=arg[0]? arg[0][6] : 0;
  a073=(a000*a072);
  a073=(a003*a073);
  a074=(a002*a036);
  a075=(a009*a032);
  a074=(a074-a075);
  a074=(a074/a023);
  a074=(a024-a074);
  a075=(a013*a074);
  a075=(a075-a072);
  a076=(a028*a075);
  a077=(a045*a054);
  a078=(a042*a022);
  a077=(a077-a078);
  a077=(a077/a023);
  a077=(a050-a077);
  a078=(a047*a077);
  a078=(a078-a072);
  a079=(a039*a078);
  a076=(a076+a079);
  a079=(a000*a076);
  a080=(a027*a079);
  a080=(a073+a080);
  a075=(a039*a075);
  a078=(a059*a078);
  a075=(a075+a078);
  a078=(a000*a075);
  a081=(a058*a078);
  a080=(a080+a081);
  a081=(a006*a080);
  a071=(a071+a081);
  a071=(a058*a071);
  a081=(a035*a071);
  a061=(a061-a081);
  a081=(a003*a080);
  a082=(a031*a081);
  a061=(a061-a082);
  a082=(a003*a061);
  a083=(a002*a082);
  a084=(a068*a057);
  a037=(a037-a084);
  a084=(a003*a070);
  a085=(a024*a084);
  a037=(a037-a085);
  a085=(a031*a071);
  a037=(a037-a085);
  a085=(a035*a081);
  a037=(a037+a085);
  a085=(a003*a037);
  a086=(a009*a085);
  a087=(a083-a086);
  a088=(a009*a061);
  a089=(a002*a037);
  a088=(a088+a089);
  a089=(a031*a084);
  a090=(a035*a060);
  a089=(a089-a090);
  a089=(a089+a075);
  a075=(a068*a080);
  a089=(a089-a075);
  a075=(a024*a071);
  a089=(a089-a075);
  a075=(a006*a089);
  a088=(a088+a075);
  a088=(a058*a088);
  a075=(a006*a088);
  a087=(a087+a075);
  a087=(a087+a089);
  a090=-5.0000000000000000e-01;
  a091=arg[3]? arg[3][2] : 0;
  a090=(a090*a091);
  a091=arg[1]? arg[1][2] : 0;
  a092=(a009*a006);
  a092=(a092/a023);
  a092=(a092-a002);
  a093=(a013*a092);
  a094=(a091*a093);
  a095=arg[1]? arg[1][5] : 0;
  a096=1.;
  a097=(a012+a007);
  a097=(a097/a023);
  a098=(a013*a097);
  a098=(a096-a098);
  a099=(a095*a098);
  a094=(a094+a099);
  a099=arg[1]? arg[1][8] : 0;
  a100=(a009*a002);
  a100=(a100/a023);
  a100=(a006+a100);
  a101=(a013*a100);
  a102=(a099*a101);
  a094=(a094+a102);
  a102=8.4147098480789650e-01;
  a103=arg[1]? arg[1][0] : 0;
  a104=(a002*a006);
  a104=(a104/a023);
  a104=(a009+a104);
  a105=(a013*a104);
  a106=(a103*a105);
  a107=arg[1]? arg[1][3] : 0;
  a108=(a002*a009);
  a108=(a108/a023);
  a108=(a108-a006);
  a109=(a013*a108);
  a110=(a107*a109);
  a106=(a106+a110);
  a110=arg[1]? arg[1][6] : 0;
  a007=(a010+a007);
  a007=(a007/a023);
  a111=(a013*a007);
  a111=(a096-a111);
  a112=(a110*a111);
  a106=(a106+a112);
  a112=(a102*a106);
  a094=(a094+a112);
  a112=-5.4030230586813977e-01;
  a113=arg[1]? arg[1][1] : 0;
  a105=(a113*a105);
  a114=arg[1]? arg[1][4] : 0;
  a109=(a114*a109);
  a105=(a105+a109);
  a109=arg[1]? arg[1][7] : 0;
  a111=(a109*a111);
  a105=(a105+a111);
  a111=(a112*a105);
  a094=(a094+a111);
  a094=(a090*a094);
  a111=arg[3]? arg[3][3] : 0;
  a115=(a111*a024);
  a094=(a094-a115);
  a115=(a003*a000);
  a094=(a094*a115);
  a087=(a087+a094);
  a087=(a087/a000);
  if (res[0]!=0) res[0][0]=a087;
  a087=(a006*a085);
  a094=(a061+a087);
  a116=(a009*a088);
  a094=(a094+a116);
  a117=(a003*a089);
  a118=(a002*a117);
  a094=(a094-a118);
  a119=5.4030230586813977e-01;
  a106=(a119*a106);
  a012=(a012+a010);
  a012=(a012/a023);
  a010=(a013*a012);
  a010=(a096-a010);
  a120=(a091*a010);
  a121=(a006*a009);
  a121=(a121/a023);
  a121=(a002+a121);
  a122=(a013*a121);
  a123=(a095*a122);
  a120=(a120+a123);
  a123=(a006*a002);
  a123=(a123/a023);
  a123=(a123-a009);
  a124=(a013*a123);
  a125=(a099*a124);
  a120=(a120+a125);
  a106=(a106-a120);
  a105=(a102*a105);
  a106=(a106+a105);
  a106=(a090*a106);
  a105=(a111*a035);
  a106=(a106-a105);
  a106=(a106*a115);
  a094=(a094+a106);
  a094=(a094/a000);
  if (res[0]!=0) res[0][1]=a094;
  a094=(a006*a082);
  a106=(a037-a094);
  a105=(a002*a088);
  a106=(a106+a105);
  a120=(a009*a117);
  a106=(a106+a120);
  a125=(a113*a010);
  a126=(a114*a122);
  a125=(a125+a126);
  a126=(a109*a124);
  a125=(a125+a126);
  a125=(a119*a125);
  a126=(a103*a093);
  a127=(a107*a098);
  a126=(a126+a127);
  a127=(a110*a101);
  a126=(a126+a127);
  a126=(a112*a126);
  a125=(a125+a126);
  a126=-8.4147098480789650e-01;
  a010=(a103*a010);
  a122=(a107*a122);
  a010=(a010+a122);
  a124=(a110*a124);
  a010=(a010+a124);
  a010=(a126*a010);
  a125=(a125+a010);
  a093=(a113*a093);
  a098=(a114*a098);
  a093=(a093+a098);
  a101=(a109*a101);
  a093=(a093+a101);
  a093=(a126*a093);
  a125=(a125+a093);
  a125=(a090*a125);
  a093=(a111*a031);
  a125=(a125-a093);
  a125=(a125*a115);
  a106=(a106+a125);
  a106=(a106/a000);
  if (res[0]!=0) res[0][2]=a106;
  a106=(a042*a040);
  a106=(a106/a023);
  a106=(a106-a045);
  a125=(a047*a106);
  a093=(a091*a125);
  a101=(a046+a041);
  a101=(a101/a023);
  a098=(a047*a101);
  a098=(a096-a098);
  a010=(a095*a098);
  a093=(a093+a010);
  a010=(a042*a045);
  a010=(a010/a023);
  a010=(a040+a010);
  a124=(a047*a010);
  a122=(a099*a124);
  a093=(a093+a122);
  a122=(a045*a040);
  a122=(a122/a023);
  a122=(a042+a122);
  a127=(a047*a122);
  a128=(a103*a127);
  a129=(a045*a042);
  a129=(a129/a023);
  a129=(a129-a040);
  a130=(a047*a129);
  a131=(a107*a130);
  a128=(a128+a131);
  a041=(a043+a041);
  a041=(a041/a023);
  a131=(a047*a041);
  a131=(a096-a131);
  a132=(a110*a131);
  a128=(a128+a132);
  a132=(a102*a128);
  a093=(a093+a132);
  a127=(a113*a127);
  a130=(a114*a130);
  a127=(a127+a130);
  a131=(a109*a131);
  a127=(a127+a131);
  a131=(a112*a127);
  a093=(a093+a131);
  a093=(a090*a093);
  a131=(a111*a050);
  a093=(a093-a131);
  a093=(a093*a115);
  a056=(a058*a056);
  a026=(a026+a056);
  a056=-3.8675134594812879e-02;
  a055=(a056*a055);
  a026=(a026+a055);
  a055=(a003*a026);
  a131=(a053*a055);
  a076=(a076-a131);
  a067=(a058*a067);
  a069=(a069+a067);
  a065=(a056*a065);
  a069=(a069+a065);
  a065=(a003*a069);
  a067=(a019*a065);
  a076=(a076+a067);
  a067=(a040*a050);
  a131=(a042*a053);
  a067=(a067+a131);
  a131=(a045*a019);
  a067=(a067+a131);
  a067=(a067/a004);
  a079=(a058*a079);
  a073=(a073+a079);
  a078=(a056*a078);
  a073=(a073+a078);
  a078=(a067*a073);
  a076=(a076-a078);
  a078=(a045*a026);
  a079=(a042*a069);
  a078=(a078+a079);
  a079=(a040*a073);
  a078=(a078+a079);
  a078=(a058*a078);
  a079=(a050*a078);
  a076=(a076-a079);
  a093=(a093+a076);
  a079=(a050*a055);
  a063=(a063+a079);
  a079=(a067*a069);
  a063=(a063-a079);
  a079=(a053*a078);
  a063=(a063-a079);
  a079=(a003*a073);
  a004=(a019*a079);
  a063=(a063-a004);
  a004=(a003*a063);
  a131=(a045*a004);
  a093=(a093+a131);
  a130=(a040*a076);
  a132=(a042*a063);
  a130=(a130+a132);
  a132=(a067*a026);
  a038=(a038-a132);
  a132=(a050*a065);
  a038=(a038-a132);
  a132=(a019*a078);
  a038=(a038-a132);
  a132=(a053*a079);
  a038=(a038+a132);
  a132=(a045*a038);
  a130=(a130+a132);
  a130=(a058*a130);
  a132=(a040*a130);
  a093=(a093+a132);
  a133=(a003*a038);
  a134=(a042*a133);
  a093=(a093-a134);
  a093=(a093/a000);
  if (res[0]!=0) res[0][3]=a093;
  a128=(a119*a128);
  a046=(a046+a043);
  a046=(a046/a023);
  a043=(a047*a046);
  a043=(a096-a043);
  a093=(a091*a043);
  a135=(a040*a042);
  a135=(a135/a023);
  a135=(a045+a135);
  a136=(a047*a135);
  a137=(a095*a136);
  a093=(a093+a137);
  a137=(a040*a045);
  a137=(a137/a023);
  a137=(a137-a042);
  a023=(a047*a137);
  a138=(a099*a023);
  a093=(a093+a138);
  a128=(a128-a093);
  a127=(a102*a127);
  a128=(a128+a127);
  a128=(a090*a128);
  a127=(a111*a053);
  a128=(a128-a127);
  a128=(a128*a115);
  a127=(a003*a076);
  a093=(a045*a127);
  a128=(a128-a093);
  a128=(a128+a063);
  a138=(a042*a130);
  a128=(a128+a138);
  a139=(a040*a133);
  a128=(a128+a139);
  a128=(a128/a000);
  if (res[0]!=0) res[0][4]=a128;
  a128=(a113*a043);
  a140=(a114*a136);
  a128=(a128+a140);
  a140=(a109*a023);
  a128=(a128+a140);
  a128=(a119*a128);
  a140=(a103*a125);
  a141=(a107*a098);
  a140=(a140+a141);
  a141=(a110*a124);
  a140=(a140+a141);
  a140=(a112*a140);
  a128=(a128+a140);
  a043=(a103*a043);
  a136=(a107*a136);
  a043=(a043+a136);
  a023=(a110*a023);
  a043=(a043+a023);
  a043=(a126*a043);
  a128=(a128+a043);
  a125=(a113*a125);
  a098=(a114*a098);
  a125=(a125+a098);
  a124=(a109*a124);
  a125=(a125+a124);
  a125=(a126*a125);
  a128=(a128+a125);
  a128=(a090*a128);
  a125=(a111*a019);
  a128=(a128-a125);
  a128=(a128*a115);
  a125=(a042*a127);
  a128=(a128+a125);
  a124=(a040*a004);
  a128=(a128-a124);
  a098=(a045*a130);
  a128=(a128+a098);
  a128=(a128+a038);
  a128=(a128/a000);
  if (res[0]!=0) res[0][5]=a128;
  a128=arg[2]? arg[2][0] : 0;
  a043=(a003*a021);
  a023=(a003*a001);
  a043=(a043+a023);
  a043=(a000*a043);
  a023=(a003*a064);
  a136=(a043*a023);
  a140=(a003*a018);
  a141=(a003*a008);
  a140=(a140+a141);
  a140=(a000*a140);
  a141=(a003*a025);
  a142=(a140*a141);
  a136=(a136-a142);
  a142=(a003*a015);
  a143=(a003*a005);
  a142=(a142+a143);
  a142=(a000*a142);
  a143=(a043*a025);
  a144=(a140*a064);
  a143=(a143+a144);
  a144=(a142*a072);
  a143=(a143+a144);
  a143=(a058*a143);
  a144=(a142*a143);
  a136=(a136-a144);
  a136=(a136-a072);
  a136=(a136-a076);
  a136=(a136+a131);
  a136=(a136-a132);
  a136=(a136-a134);
  a136=(a136+a083);
  a136=(a136-a086);
  a136=(a136-a075);
  a136=(a136-a089);
  a128=(a128+a136);
  if (res[0]!=0) res[0][6]=a128;
  a128=arg[2]? arg[2][1] : 0;
  a136=(a142*a141);
  a136=(a136-a064);
  a075=(a140*a143);
  a136=(a136-a075);
  a075=(a003*a072);
  a086=(a043*a075);
  a136=(a136-a086);
  a136=(a136-a093);
  a136=(a136-a063);
  a136=(a136-a138);
  a136=(a136+a139);
  a136=(a136-a061);
  a136=(a136+a087);
  a136=(a136-a116);
  a136=(a136-a118);
  a128=(a128+a136);
  if (res[0]!=0) res[0][7]=a128;
  a128=arg[2]? arg[2][2] : 0;
  a136=(a140*a075);
  a118=(a142*a023);
  a118=(a025+a118);
  a116=(a043*a143);
  a118=(a118+a116);
  a136=(a136-a118);
  a136=(a136+a125);
  a136=(a136-a124);
  a136=(a136-a098);
  a136=(a136-a038);
  a136=(a136-a094);
  a136=(a136-a037);
  a136=(a136-a105);
  a136=(a136+a120);
  a128=(a128+a136);
  if (res[0]!=0) res[0][8]=a128;
  a128=(a014*a013);
  a011=(a013/a011);
  a136=(2.*a006);
  a136=(a136*a000);
  a120=(a011*a136);
  a105=(a020*a120);
  a105=(a128-a105);
  a094=(a060*a105);
  a098=(a014*a009);
  a018=(a018*a000);
  a124=(a098-a018);
  a124=(a003*a124);
  a124=(a013*a124);
  a125=(a030*a120);
  a124=(a124-a125);
  a125=(a029*a124);
  a118=(a009*a105);
  a036=(a036*a000);
  a021=(a021*a000);
  a116=(a014*a002);
  a087=(a021-a116);
  a087=(a003*a087);
  a087=(a013*a087);
  a139=(a034*a120);
  a087=(a087-a139);
  a139=(2.*a087);
  a138=(a006*a139);
  a138=(a036+a138);
  a118=(a118-a138);
  a118=(a003*a118);
  a118=(a125-a118);
  a118=(a013*a118);
  a138=(a033*a120);
  a118=(a118-a138);
  a138=(a028*a118);
  a093=(a059*a042);
  a093=(a047*a093);
  a086=(a029*a093);
  a048=(a048*a047);
  a083=(a042*a048);
  a134=(a059*a045);
  a134=(a047*a134);
  a132=(-a134);
  a132=(2.*a132);
  a131=(a040*a132);
  a131=(a083-a131);
  a131=(a003*a131);
  a131=(a086-a131);
  a131=(a047*a131);
  a144=(a039*a131);
  a138=(a138+a144);
  a144=(a000*a138);
  a145=(a027*a144);
  a118=(a039*a118);
  a131=(a059*a131);
  a118=(a118+a131);
  a131=(a000*a118);
  a146=(a058*a131);
  a145=(a145+a146);
  a146=(a003*a145);
  a147=(a024*a146);
  a094=(a094+a147);
  a032=(a032*a000);
  a147=(a006*a125);
  a147=(a032+a147);
  a148=(a002*a105);
  a147=(a147-a148);
  a147=(a003*a147);
  a147=(a139-a147);
  a147=(a013*a147);
  a148=(a062*a120);
  a147=(a147-a148);
  a148=(a039*a147);
  a149=(a040*a086);
  a150=(a045*a048);
  a149=(a149-a150);
  a149=(a003*a149);
  a149=(a132-a149);
  a149=(a047*a149);
  a151=(a059*a149);
  a148=(a148+a151);
  a094=(a094+a148);
  a151=(a024*a000);
  a152=(a006*a105);
  a152=(a151+a152);
  a153=(a009*a087);
  a152=(a152+a153);
  a153=(a002*a124);
  a152=(a152+a153);
  a152=(a058*a152);
  a153=(a070*a152);
  a147=(a028*a147);
  a149=(a039*a149);
  a147=(a147+a149);
  a149=(a000*a147);
  a154=(a027*a149);
  a148=(a000*a148);
  a155=(a058*a148);
  a154=(a154+a155);
  a155=(a068*a154);
  a153=(a153+a155);
  a094=(a094-a153);
  a153=(a071*a087);
  a155=(a002*a145);
  a156=(a009*a154);
  a155=(a155+a156);
  a156=(a080*a000);
  a139=(a002*a139);
  a125=(a009*a125);
  a139=(a139-a125);
  a139=(a003*a139);
  a139=(a105-a139);
  a139=(a013*a139);
  a125=(a074*a120);
  a139=(a139-a125);
  a125=(a028*a139);
  a132=(a045*a132);
  a086=(a042*a086);
  a132=(a132-a086);
  a132=(a003*a132);
  a132=(a048-a132);
  a132=(a047*a132);
  a086=(a039*a132);
  a125=(a125+a086);
  a086=(a000*a125);
  a157=(a027*a086);
  a139=(a039*a139);
  a132=(a059*a132);
  a139=(a139+a132);
  a132=(a000*a139);
  a158=(a058*a132);
  a157=(a157+a158);
  a158=(a006*a157);
  a156=(a156+a158);
  a155=(a155+a156);
  a155=(a058*a155);
  a156=(a035*a155);
  a153=(a153+a156);
  a094=(a094-a153);
  a153=(a081*a124);
  a156=(a003*a157);
  a158=(a031*a156);
  a153=(a153+a158);
  a094=(a094-a153);
  a153=(a003*a094);
  a158=(a002*a153);
  a159=(a057*a152);
  a145=(a068*a145);
  a159=(a159+a145);
  a118=(a118-a159);
  a159=(a084*a105);
  a154=(a003*a154);
  a145=(a024*a154);
  a159=(a159+a145);
  a118=(a118-a159);
  a159=(a071*a124);
  a145=(a031*a155);
  a159=(a159+a145);
  a118=(a118-a159);
  a159=(a081*a087);
  a156=(a035*a156);
  a159=(a159+a156);
  a118=(a118+a159);
  a159=(a003*a118);
  a156=(a009*a159);
  a145=(a158-a156);
  a088=(a088*a000);
  a160=(a009*a094);
  a161=(a002*a118);
  a160=(a160+a161);
  a089=(a089*a000);
  a161=(a084*a124);
  a154=(a031*a154);
  a161=(a161+a154);
  a154=(a060*a087);
  a146=(a035*a146);
  a154=(a154+a146);
  a161=(a161-a154);
  a161=(a161+a139);
  a152=(a080*a152);
  a157=(a068*a157);
  a152=(a152+a157);
  a161=(a161-a152);
  a152=(a071*a105);
  a155=(a024*a155);
  a152=(a152+a155);
  a161=(a161-a152);
  a152=(a006*a161);
  a089=(a089+a152);
  a160=(a160+a089);
  a160=(a058*a160);
  a089=(a006*a160);
  a089=(a088+a089);
  a145=(a145+a089);
  a145=(a145+a161);
  a152=(a009*a000);
  a152=(a003*a152);
  a152=(a013*a152);
  a155=(a092*a120);
  a155=(a152-a155);
  a157=(a091*a155);
  a136=(a003*a136);
  a136=(a013*a136);
  a139=(a097*a120);
  a139=(a136-a139);
  a154=(a095*a139);
  a157=(a157-a154);
  a154=(a013*a000);
  a146=(a100*a120);
  a146=(a154-a146);
  a162=(a099*a146);
  a157=(a157+a162);
  a162=(a002*a000);
  a162=(a003*a162);
  a162=(a013*a162);
  a163=(a104*a120);
  a163=(a162-a163);
  a164=(a103*a163);
  a165=(a108*a120);
  a165=(a165+a154);
  a166=(a107*a165);
  a164=(a164-a166);
  a166=(a007*a120);
  a136=(a136-a166);
  a166=(a110*a136);
  a164=(a164-a166);
  a166=(a102*a164);
  a157=(a157+a166);
  a163=(a113*a163);
  a165=(a114*a165);
  a163=(a163-a165);
  a136=(a109*a136);
  a163=(a163-a136);
  a136=(a112*a163);
  a157=(a157+a136);
  a157=(a090*a157);
  a105=(a111*a105);
  a157=(a157-a105);
  a157=(a115*a157);
  a145=(a145+a157);
  a145=(a145/a000);
  if (res[1]!=0) res[1][0]=a145;
  a085=(a085*a000);
  a159=(a006*a159);
  a159=(a085+a159);
  a145=(a094+a159);
  a157=(a009*a160);
  a145=(a145+a157);
  a105=(a003*a161);
  a136=(a002*a105);
  a145=(a145-a136);
  a164=(a119*a164);
  a165=(a012*a120);
  a166=(a091*a165);
  a167=(a121*a120);
  a167=(a152-a167);
  a168=(a095*a167);
  a166=(a166+a168);
  a120=(a123*a120);
  a120=(a162-a120);
  a168=(a099*a120);
  a166=(a166+a168);
  a164=(a164-a166);
  a163=(a102*a163);
  a164=(a164+a163);
  a164=(a090*a164);
  a087=(a111*a087);
  a164=(a164-a087);
  a164=(a115*a164);
  a145=(a145+a164);
  a145=(a145/a000);
  if (res[1]!=0) res[1][1]=a145;
  a082=(a082*a000);
  a153=(a006*a153);
  a153=(a082+a153);
  a145=(a118-a153);
  a160=(a002*a160);
  a145=(a145+a160);
  a105=(a009*a105);
  a145=(a145+a105);
  a164=(a113*a165);
  a087=(a114*a167);
  a164=(a164+a087);
  a087=(a109*a120);
  a164=(a164+a087);
  a164=(a119*a164);
  a087=(a103*a155);
  a163=(a107*a139);
  a087=(a087-a163);
  a163=(a110*a146);
  a087=(a087+a163);
  a087=(a112*a087);
  a164=(a164+a087);
  a165=(a103*a165);
  a167=(a107*a167);
  a165=(a165+a167);
  a120=(a110*a120);
  a165=(a165+a120);
  a165=(a126*a165);
  a164=(a164+a165);
  a155=(a113*a155);
  a139=(a114*a139);
  a155=(a155-a139);
  a146=(a109*a146);
  a155=(a155+a146);
  a155=(a126*a155);
  a164=(a164+a155);
  a164=(a090*a164);
  a124=(a111*a124);
  a164=(a164-a124);
  a164=(a115*a164);
  a145=(a145+a164);
  a145=(a145/a000);
  if (res[1]!=0) res[1][2]=a145;
  a144=(a058*a144);
  a131=(a056*a131);
  a144=(a144+a131);
  a131=(a003*a144);
  a145=(a053*a131);
  a164=(a055*a134);
  a145=(a145-a164);
  a125=(a125-a145);
  a145=(a065*a093);
  a149=(a058*a149);
  a148=(a056*a148);
  a149=(a149+a148);
  a148=(a003*a149);
  a124=(a019*a148);
  a124=(a145+a124);
  a125=(a125+a124);
  a124=(a040*a048);
  a155=(a042*a134);
  a124=(a124-a155);
  a146=(a045*a093);
  a124=(a124+a146);
  a124=(a058*a124);
  a139=(a073*a124);
  a086=(a058*a086);
  a132=(a056*a132);
  a086=(a086+a132);
  a132=(a067*a086);
  a139=(a139+a132);
  a125=(a125-a139);
  a139=(a078*a048);
  a132=(a045*a144);
  a165=(a042*a149);
  a132=(a132+a165);
  a165=(a040*a086);
  a132=(a132+a165);
  a132=(a058*a132);
  a165=(a050*a132);
  a165=(a139+a165);
  a125=(a125-a165);
  a165=(a111*a048);
  a165=(a115*a165);
  a120=(a125-a165);
  a167=(a055*a048);
  a131=(a050*a131);
  a131=(a167+a131);
  a147=(a147+a131);
  a131=(a069*a124);
  a149=(a067*a149);
  a131=(a131+a149);
  a147=(a147-a131);
  a131=(a053*a132);
  a149=(a078*a134);
  a131=(a131-a149);
  a147=(a147-a131);
  a131=(a079*a093);
  a086=(a003*a086);
  a087=(a019*a086);
  a131=(a131+a087);
  a147=(a147-a131);
  a131=(a003*a147);
  a087=(a045*a131);
  a120=(a120+a087);
  a163=(a040*a125);
  a166=(a042*a147);
  a163=(a163+a166);
  a124=(a026*a124);
  a144=(a067*a144);
  a124=(a124+a144);
  a138=(a138-a124);
  a124=(a065*a048);
  a148=(a050*a148);
  a148=(a124+a148);
  a138=(a138-a148);
  a148=(a078*a093);
  a132=(a019*a132);
  a132=(a148+a132);
  a138=(a138-a132);
  a086=(a053*a086);
  a132=(a079*a134);
  a086=(a086-a132);
  a138=(a138+a086);
  a086=(a045*a138);
  a163=(a163+a086);
  a163=(a058*a163);
  a086=(a040*a163);
  a120=(a120+a086);
  a132=(a003*a138);
  a144=(a042*a132);
  a120=(a120-a144);
  a120=(a120/a000);
  if (res[1]!=0) res[1][3]=a120;
  a120=(a111*a134);
  a120=(a115*a120);
  a166=(a003*a125);
  a168=(a045*a166);
  a169=(a120-a168);
  a169=(a169+a147);
  a170=(a042*a163);
  a169=(a169+a170);
  a132=(a040*a132);
  a169=(a169+a132);
  a169=(a169/a000);
  if (res[1]!=0) res[1][4]=a169;
  a166=(a042*a166);
  a169=(a111*a093);
  a169=(a115*a169);
  a171=(a166-a169);
  a131=(a040*a131);
  a171=(a171-a131);
  a163=(a045*a163);
  a171=(a171+a163);
  a171=(a171+a138);
  a171=(a171/a000);
  if (res[1]!=0) res[1][5]=a171;
  a171=-1.7320508075688774e+00;
  a172=(a171*a000);
  a173=(a143*a172);
  a174=(a072*a172);
  a174=(a058*a174);
  a175=(a142*a174);
  a175=(a173+a175);
  a175=(a175+a125);
  a087=(a087-a175);
  a087=(a087-a086);
  a087=(a087-a144);
  a087=(a087+a158);
  a087=(a087-a156);
  a087=(a087-a089);
  a087=(a087-a161);
  if (res[1]!=0) res[1][6]=a087;
  a087=(a141*a172);
  a161=(a140*a174);
  a161=(a087-a161);
  a161=(a161-a168);
  a161=(a161-a147);
  a161=(a161-a170);
  a161=(a161+a132);
  a161=(a161-a094);
  a161=(a161+a159);
  a161=(a161-a157);
  a161=(a161-a136);
  if (res[1]!=0) res[1][7]=a161;
  a161=(a023*a172);
  a174=(a043*a174);
  a174=(a161+a174);
  a166=(a166-a174);
  a166=(a166-a131);
  a166=(a166-a163);
  a166=(a166-a138);
  a166=(a166-a153);
  a166=(a166-a118);
  a166=(a166-a160);
  a166=(a166+a105);
  if (res[1]!=0) res[1][8]=a166;
  a116=(a116-a021);
  a116=(a003*a116);
  a116=(a013*a116);
  a021=(2.*a009);
  a021=(a021*a000);
  a166=(a011*a021);
  a105=(a020*a166);
  a116=(a116-a105);
  a105=(a060*a116);
  a015=(a015*a000);
  a160=(a014*a006);
  a118=(a015-a160);
  a118=(a003*a118);
  a118=(a013*a118);
  a153=(a030*a166);
  a118=(a118-a153);
  a153=(a029*a118);
  a138=(a009*a116);
  a138=(a151+a138);
  a163=(a034*a166);
  a163=(a128-a163);
  a131=(2.*a163);
  a174=(a006*a131);
  a138=(a138-a174);
  a138=(a003*a138);
  a138=(a153-a138);
  a138=(a013*a138);
  a174=(a033*a166);
  a138=(a138-a174);
  a174=(a028*a138);
  a136=(a059*a040);
  a136=(a047*a136);
  a157=(a029*a136);
  a159=-1.2928203230275511e+01;
  a159=(a159*a047);
  a094=(a040*a159);
  a155=(a155-a094);
  a155=(a003*a155);
  a155=(a157+a155);
  a155=(a047*a155);
  a094=(a039*a155);
  a174=(a174-a094);
  a094=(a000*a174);
  a132=(a027*a094);
  a138=(a039*a138);
  a155=(a059*a155);
  a138=(a138-a155);
  a155=(a000*a138);
  a170=(a058*a155);
  a132=(a132+a170);
  a170=(a003*a132);
  a147=(a024*a170);
  a105=(a105+a147);
  a147=(a006*a153);
  a168=(a002*a116);
  a147=(a147-a168);
  a147=(a003*a147);
  a147=(a131-a147);
  a147=(a013*a147);
  a168=(a062*a166);
  a147=(a147-a168);
  a168=(a039*a147);
  a089=(a040*a157);
  a156=(a045*a134);
  a089=(a089+a156);
  a089=(a003*a089);
  a089=(a159+a089);
  a089=(a047*a089);
  a156=(a059*a089);
  a168=(a168+a156);
  a105=(a105+a168);
  a156=(a006*a116);
  a158=(a035*a000);
  a144=(a009*a163);
  a158=(a158+a144);
  a156=(a156+a158);
  a158=(a002*a118);
  a156=(a156+a158);
  a156=(a058*a156);
  a158=(a070*a156);
  a147=(a028*a147);
  a089=(a039*a089);
  a147=(a147+a089);
  a089=(a000*a147);
  a144=(a027*a089);
  a168=(a000*a168);
  a086=(a058*a168);
  a144=(a144+a086);
  a086=(a068*a144);
  a158=(a158+a086);
  a105=(a105-a158);
  a158=(a071*a163);
  a086=(a002*a132);
  a175=(a070*a000);
  a125=(a009*a144);
  a175=(a175+a125);
  a086=(a086+a175);
  a131=(a002*a131);
  a153=(a009*a153);
  a032=(a032+a153);
  a131=(a131-a032);
  a131=(a003*a131);
  a131=(a116-a131);
  a131=(a013*a131);
  a032=(a074*a166);
  a131=(a131-a032);
  a032=(a028*a131);
  a159=(a045*a159);
  a157=(a042*a157);
  a159=(a159+a157);
  a159=(a003*a159);
  a159=(a134-a159);
  a159=(a047*a159);
  a157=(a039*a159);
  a032=(a032+a157);
  a157=(a000*a032);
  a153=(a027*a157);
  a131=(a039*a131);
  a159=(a059*a159);
  a131=(a131+a159);
  a159=(a000*a131);
  a175=(a058*a159);
  a153=(a153+a175);
  a175=(a006*a153);
  a086=(a086+a175);
  a086=(a058*a086);
  a175=(a035*a086);
  a158=(a158+a175);
  a105=(a105-a158);
  a158=(a081*a118);
  a175=(a003*a153);
  a125=(a031*a175);
  a158=(a158+a125);
  a105=(a105-a158);
  a158=(a003*a105);
  a125=(a002*a158);
  a176=(a057*a156);
  a132=(a068*a132);
  a176=(a176+a132);
  a138=(a138-a176);
  a176=(a084*a116);
  a144=(a003*a144);
  a132=(a024*a144);
  a176=(a176+a132);
  a138=(a138-a176);
  a176=(a071*a118);
  a132=(a031*a086);
  a176=(a176+a132);
  a138=(a138-a176);
  a176=(a081*a163);
  a175=(a035*a175);
  a176=(a176+a175);
  a138=(a138+a176);
  a176=(a003*a138);
  a175=(a009*a176);
  a085=(a085+a175);
  a175=(a125-a085);
  a061=(a061*a000);
  a132=(a009*a105);
  a061=(a061+a132);
  a132=(a002*a138);
  a061=(a061+a132);
  a132=(a084*a118);
  a144=(a031*a144);
  a132=(a132+a144);
  a144=(a060*a163);
  a170=(a035*a170);
  a144=(a144+a170);
  a132=(a132-a144);
  a132=(a132+a131);
  a156=(a080*a156);
  a153=(a068*a153);
  a156=(a156+a153);
  a132=(a132-a156);
  a156=(a071*a116);
  a086=(a024*a086);
  a156=(a156+a086);
  a132=(a132-a156);
  a156=(a006*a132);
  a061=(a061+a156);
  a061=(a058*a061);
  a156=(a006*a061);
  a175=(a175+a156);
  a175=(a175+a132);
  a086=(a006*a000);
  a086=(a003*a086);
  a086=(a013*a086);
  a153=(a092*a166);
  a153=(a086-a153);
  a131=(a091*a153);
  a144=(a097*a166);
  a170=(a095*a144);
  a131=(a131+a170);
  a170=(a100*a166);
  a170=(a162-a170);
  a177=(a099*a170);
  a131=(a131+a177);
  a177=(a104*a166);
  a177=(a154-a177);
  a178=(a103*a177);
  a179=(a108*a166);
  a162=(a162-a179);
  a179=(a107*a162);
  a178=(a178+a179);
  a021=(a003*a021);
  a021=(a013*a021);
  a179=(a007*a166);
  a179=(a021-a179);
  a180=(a110*a179);
  a178=(a178-a180);
  a180=(a102*a178);
  a131=(a131+a180);
  a177=(a113*a177);
  a162=(a114*a162);
  a177=(a177+a162);
  a179=(a109*a179);
  a177=(a177-a179);
  a179=(a112*a177);
  a131=(a131+a179);
  a131=(a090*a131);
  a116=(a111*a116);
  a131=(a131-a116);
  a131=(a115*a131);
  a175=(a175+a131);
  a175=(a175/a000);
  if (res[1]!=0) res[1][9]=a175;
  a176=(a006*a176);
  a175=(a105+a176);
  a131=(a009*a061);
  a131=(a088+a131);
  a175=(a175+a131);
  a116=(a003*a132);
  a179=(a002*a116);
  a175=(a175-a179);
  a178=(a119*a178);
  a162=(a121*a166);
  a162=(a086-a162);
  a180=(a095*a162);
  a181=(a012*a166);
  a021=(a021-a181);
  a181=(a091*a021);
  a180=(a180-a181);
  a166=(a123*a166);
  a166=(a166+a154);
  a181=(a099*a166);
  a180=(a180-a181);
  a178=(a178-a180);
  a177=(a102*a177);
  a178=(a178+a177);
  a178=(a090*a178);
  a163=(a111*a163);
  a178=(a178-a163);
  a178=(a115*a178);
  a175=(a175+a178);
  a175=(a175/a000);
  if (res[1]!=0) res[1][10]=a175;
  a158=(a006*a158);
  a175=(a138-a158);
  a061=(a002*a061);
  a175=(a175+a061);
  a117=(a117*a000);
  a116=(a009*a116);
  a116=(a117+a116);
  a175=(a175+a116);
  a178=(a114*a162);
  a163=(a113*a021);
  a178=(a178-a163);
  a163=(a109*a166);
  a178=(a178-a163);
  a178=(a119*a178);
  a163=(a103*a153);
  a177=(a107*a144);
  a163=(a163+a177);
  a177=(a110*a170);
  a163=(a163+a177);
  a163=(a112*a163);
  a178=(a178+a163);
  a162=(a107*a162);
  a021=(a103*a021);
  a162=(a162-a021);
  a166=(a110*a166);
  a162=(a162-a166);
  a162=(a126*a162);
  a178=(a178+a162);
  a153=(a113*a153);
  a144=(a114*a144);
  a153=(a153+a144);
  a170=(a109*a170);
  a153=(a153+a170);
  a153=(a126*a153);
  a178=(a178+a153);
  a178=(a090*a178);
  a118=(a111*a118);
  a178=(a178-a118);
  a178=(a115*a178);
  a175=(a175+a178);
  a175=(a175/a000);
  if (res[1]!=0) res[1][11]=a175;
  a094=(a058*a094);
  a155=(a056*a155);
  a094=(a094+a155);
  a155=(a003*a094);
  a175=(a053*a155);
  a167=(a167+a175);
  a032=(a032-a167);
  a089=(a058*a089);
  a168=(a056*a168);
  a089=(a089+a168);
  a168=(a003*a089);
  a167=(a019*a168);
  a175=(a065*a136);
  a167=(a167-a175);
  a032=(a032+a167);
  a167=(a040*a134);
  a167=(a167+a083);
  a083=(a045*a136);
  a167=(a167-a083);
  a167=(a058*a167);
  a083=(a073*a167);
  a157=(a058*a157);
  a159=(a056*a159);
  a157=(a157+a159);
  a159=(a067*a157);
  a083=(a083+a159);
  a032=(a032-a083);
  a083=(a045*a094);
  a159=(a042*a089);
  a083=(a083+a159);
  a159=(a040*a157);
  a083=(a083+a159);
  a083=(a058*a083);
  a159=(a050*a083);
  a149=(a149+a159);
  a032=(a032-a149);
  a120=(a032-a120);
  a155=(a050*a155);
  a164=(a164+a155);
  a147=(a147+a164);
  a164=(a069*a167);
  a089=(a067*a089);
  a164=(a164+a089);
  a147=(a147-a164);
  a164=(a053*a083);
  a164=(a139+a164);
  a147=(a147-a164);
  a157=(a003*a157);
  a164=(a019*a157);
  a089=(a079*a136);
  a164=(a164-a089);
  a147=(a147-a164);
  a164=(a003*a147);
  a155=(a045*a164);
  a120=(a120+a155);
  a149=(a040*a032);
  a159=(a042*a147);
  a149=(a149+a159);
  a167=(a026*a167);
  a094=(a067*a094);
  a167=(a167+a094);
  a174=(a174-a167);
  a134=(a065*a134);
  a168=(a050*a168);
  a134=(a134+a168);
  a174=(a174-a134);
  a083=(a019*a083);
  a134=(a078*a136);
  a083=(a083-a134);
  a174=(a174-a083);
  a048=(a079*a048);
  a157=(a053*a157);
  a157=(a048+a157);
  a174=(a174+a157);
  a157=(a045*a174);
  a149=(a149+a157);
  a149=(a058*a149);
  a157=(a040*a149);
  a120=(a120+a157);
  a083=(a003*a174);
  a168=(a042*a083);
  a120=(a120-a168);
  a120=(a120/a000);
  if (res[1]!=0) res[1][12]=a120;
  a120=(a003*a032);
  a167=(a045*a120);
  a094=(a165+a167);
  a094=(a147-a094);
  a159=(a042*a149);
  a094=(a094+a159);
  a083=(a040*a083);
  a094=(a094+a083);
  a094=(a094/a000);
  if (res[1]!=0) res[1][13]=a094;
  a094=(a111*a136);
  a094=(a115*a094);
  a120=(a042*a120);
  a175=(a094+a120);
  a164=(a040*a164);
  a175=(a175-a164);
  a149=(a045*a149);
  a175=(a175+a149);
  a175=(a175+a174);
  a175=(a175/a000);
  if (res[1]!=0) res[1][14]=a175;
  a175=(a064*a172);
  a175=(a058*a175);
  a178=(a142*a175);
  a087=(a087+a178);
  a087=(a087+a032);
  a155=(a155-a087);
  a155=(a155-a157);
  a155=(a155-a168);
  a155=(a155+a125);
  a155=(a155-a085);
  a155=(a155-a156);
  a155=(a155-a132);
  if (res[1]!=0) res[1][15]=a155;
  a155=(a140*a175);
  a155=(a173+a155);
  a155=(a155+a167);
  a155=(a155+a147);
  a155=(a155+a159);
  a083=(a083-a155);
  a083=(a083-a105);
  a083=(a083+a176);
  a083=(a083-a131);
  a083=(a083-a179);
  if (res[1]!=0) res[1][16]=a083;
  a083=(a075*a172);
  a175=(a043*a175);
  a175=(a083-a175);
  a175=(a175+a120);
  a175=(a175-a164);
  a175=(a175-a149);
  a175=(a175-a174);
  a175=(a175-a158);
  a175=(a175-a138);
  a175=(a175-a061);
  a175=(a175+a116);
  if (res[1]!=0) res[1][17]=a175;
  a018=(a018-a098);
  a018=(a003*a018);
  a018=(a013*a018);
  a098=(2.*a002);
  a098=(a098*a000);
  a011=(a011*a098);
  a020=(a020*a011);
  a018=(a018-a020);
  a020=(a060*a018);
  a030=(a030*a011);
  a128=(a128-a030);
  a030=(a029*a128);
  a175=(a009*a018);
  a160=(a160-a015);
  a160=(a003*a160);
  a160=(a013*a160);
  a034=(a034*a011);
  a160=(a160-a034);
  a034=(2.*a160);
  a015=(a006*a034);
  a175=(a175-a015);
  a175=(a003*a175);
  a175=(a030-a175);
  a175=(a013*a175);
  a033=(a033*a011);
  a175=(a175-a033);
  a033=(a028*a175);
  a015=-1.9392304845413264e+01;
  a015=(a015*a047);
  a116=(a042*a093);
  a061=(2.*a136);
  a138=(a040*a061);
  a116=(a116+a138);
  a116=(a003*a116);
  a116=(a015+a116);
  a116=(a047*a116);
  a138=(a039*a116);
  a033=(a033+a138);
  a138=(a000*a033);
  a158=(a027*a138);
  a175=(a039*a175);
  a116=(a059*a116);
  a175=(a175+a116);
  a116=(a000*a175);
  a174=(a058*a116);
  a158=(a158+a174);
  a174=(a003*a158);
  a149=(a024*a174);
  a020=(a020+a149);
  a149=(a006*a030);
  a164=(a002*a018);
  a151=(a151+a164);
  a149=(a149-a151);
  a149=(a003*a149);
  a149=(a034-a149);
  a149=(a013*a149);
  a062=(a062*a011);
  a149=(a149-a062);
  a062=(a039*a149);
  a151=(a040*a015);
  a151=(a151+a146);
  a151=(a003*a151);
  a151=(a061-a151);
  a151=(a047*a151);
  a146=(a059*a151);
  a062=(a062+a146);
  a020=(a020+a062);
  a146=(a006*a018);
  a164=(a009*a160);
  a146=(a146+a164);
  a164=(a031*a000);
  a120=(a002*a128);
  a164=(a164+a120);
  a146=(a146+a164);
  a146=(a058*a146);
  a164=(a070*a146);
  a149=(a028*a149);
  a151=(a039*a151);
  a149=(a149+a151);
  a151=(a000*a149);
  a120=(a027*a151);
  a062=(a000*a062);
  a179=(a058*a062);
  a120=(a120+a179);
  a179=(a068*a120);
  a164=(a164+a179);
  a020=(a020-a164);
  a164=(a071*a160);
  a179=(a057*a000);
  a131=(a002*a158);
  a179=(a179+a131);
  a131=(a009*a120);
  a179=(a179+a131);
  a034=(a002*a034);
  a036=(a036+a034);
  a030=(a009*a030);
  a036=(a036-a030);
  a036=(a003*a036);
  a036=(a018-a036);
  a036=(a013*a036);
  a074=(a074*a011);
  a036=(a036-a074);
  a074=(a028*a036);
  a061=(a045*a061);
  a015=(a042*a015);
  a061=(a061-a015);
  a061=(a003*a061);
  a061=(a093+a061);
  a061=(a047*a061);
  a015=(a039*a061);
  a074=(a074-a015);
  a015=(a000*a074);
  a030=(a027*a015);
  a036=(a039*a036);
  a061=(a059*a061);
  a036=(a036-a061);
  a061=(a000*a036);
  a034=(a058*a061);
  a030=(a030+a034);
  a034=(a006*a030);
  a179=(a179+a034);
  a179=(a058*a179);
  a034=(a035*a179);
  a164=(a164+a034);
  a020=(a020-a164);
  a164=(a081*a128);
  a034=(a003*a030);
  a131=(a031*a034);
  a164=(a164+a131);
  a020=(a020-a164);
  a164=(a003*a020);
  a131=(a002*a164);
  a082=(a082+a131);
  a131=(a057*a146);
  a158=(a068*a158);
  a131=(a131+a158);
  a175=(a175-a131);
  a131=(a084*a018);
  a120=(a003*a120);
  a158=(a024*a120);
  a131=(a131+a158);
  a175=(a175-a131);
  a131=(a071*a128);
  a158=(a031*a179);
  a131=(a131+a158);
  a175=(a175-a131);
  a131=(a081*a160);
  a034=(a035*a034);
  a131=(a131+a034);
  a175=(a175+a131);
  a131=(a003*a175);
  a034=(a009*a131);
  a158=(a082-a034);
  a176=(a009*a020);
  a037=(a037*a000);
  a105=(a002*a175);
  a037=(a037+a105);
  a176=(a176+a037);
  a037=(a084*a128);
  a120=(a031*a120);
  a037=(a037+a120);
  a120=(a060*a160);
  a174=(a035*a174);
  a120=(a120+a174);
  a037=(a037-a120);
  a037=(a037+a036);
  a146=(a080*a146);
  a030=(a068*a030);
  a146=(a146+a030);
  a037=(a037-a146);
  a146=(a071*a018);
  a179=(a024*a179);
  a146=(a146+a179);
  a037=(a037-a146);
  a146=(a006*a037);
  a176=(a176+a146);
  a176=(a058*a176);
  a146=(a006*a176);
  a158=(a158+a146);
  a158=(a158+a037);
  a100=(a100*a011);
  a100=(a152-a100);
  a179=(a099*a100);
  a092=(a092*a011);
  a092=(a092+a154);
  a030=(a091*a092);
  a098=(a003*a098);
  a098=(a013*a098);
  a097=(a097*a011);
  a097=(a098-a097);
  a036=(a095*a097);
  a030=(a030+a036);
  a179=(a179-a030);
  a104=(a104*a011);
  a104=(a086-a104);
  a030=(a103*a104);
  a108=(a108*a011);
  a152=(a152-a108);
  a108=(a107*a152);
  a030=(a030+a108);
  a007=(a007*a011);
  a108=(a110*a007);
  a030=(a030+a108);
  a108=(a102*a030);
  a179=(a179+a108);
  a104=(a113*a104);
  a152=(a114*a152);
  a104=(a104+a152);
  a007=(a109*a007);
  a104=(a104+a007);
  a007=(a112*a104);
  a179=(a179+a007);
  a179=(a090*a179);
  a018=(a111*a018);
  a179=(a179-a018);
  a179=(a115*a179);
  a158=(a158+a179);
  a158=(a158/a000);
  if (res[1]!=0) res[1][18]=a158;
  a131=(a006*a131);
  a158=(a020+a131);
  a179=(a009*a176);
  a158=(a158+a179);
  a018=(a003*a037);
  a007=(a002*a018);
  a117=(a117+a007);
  a158=(a158-a117);
  a030=(a119*a030);
  a121=(a121*a011);
  a154=(a154-a121);
  a121=(a095*a154);
  a012=(a012*a011);
  a098=(a098-a012);
  a012=(a091*a098);
  a121=(a121-a012);
  a123=(a123*a011);
  a086=(a086-a123);
  a123=(a099*a086);
  a121=(a121+a123);
  a030=(a030-a121);
  a104=(a102*a104);
  a030=(a030+a104);
  a030=(a090*a030);
  a160=(a111*a160);
  a030=(a030-a160);
  a030=(a115*a030);
  a158=(a158+a030);
  a158=(a158/a000);
  if (res[1]!=0) res[1][19]=a158;
  a164=(a006*a164);
  a158=(a175-a164);
  a176=(a002*a176);
  a088=(a088+a176);
  a158=(a158+a088);
  a018=(a009*a018);
  a158=(a158+a018);
  a176=(a114*a154);
  a030=(a113*a098);
  a176=(a176-a030);
  a030=(a109*a086);
  a176=(a176+a030);
  a176=(a119*a176);
  a030=(a110*a100);
  a160=(a103*a092);
  a104=(a107*a097);
  a160=(a160+a104);
  a030=(a030-a160);
  a030=(a112*a030);
  a176=(a176+a030);
  a154=(a107*a154);
  a098=(a103*a098);
  a154=(a154-a098);
  a086=(a110*a086);
  a154=(a154+a086);
  a154=(a126*a154);
  a176=(a176+a154);
  a100=(a109*a100);
  a092=(a113*a092);
  a097=(a114*a097);
  a092=(a092+a097);
  a100=(a100-a092);
  a100=(a126*a100);
  a176=(a176+a100);
  a176=(a090*a176);
  a128=(a111*a128);
  a176=(a176-a128);
  a176=(a115*a176);
  a158=(a158+a176);
  a158=(a158/a000);
  if (res[1]!=0) res[1][20]=a158;
  a158=(a055*a136);
  a138=(a058*a138);
  a116=(a056*a116);
  a138=(a138+a116);
  a116=(a003*a138);
  a176=(a053*a116);
  a158=(a158+a176);
  a074=(a074-a158);
  a151=(a058*a151);
  a062=(a056*a062);
  a151=(a151+a062);
  a062=(a003*a151);
  a158=(a019*a062);
  a124=(a124+a158);
  a074=(a074+a124);
  a136=(a042*a136);
  a124=(a040*a093);
  a136=(a136-a124);
  a136=(a136+a150);
  a136=(a058*a136);
  a150=(a073*a136);
  a015=(a058*a015);
  a061=(a056*a061);
  a015=(a015+a061);
  a061=(a067*a015);
  a150=(a150+a061);
  a074=(a074-a150);
  a150=(a045*a138);
  a061=(a042*a151);
  a150=(a150+a061);
  a061=(a040*a015);
  a150=(a150+a061);
  a150=(a058*a150);
  a061=(a050*a150);
  a061=(a061-a148);
  a074=(a074-a061);
  a169=(a169+a074);
  a116=(a050*a116);
  a093=(a055*a093);
  a116=(a116-a093);
  a149=(a149+a116);
  a116=(a069*a136);
  a151=(a067*a151);
  a116=(a116+a151);
  a149=(a149-a116);
  a116=(a053*a150);
  a134=(a134+a116);
  a149=(a149-a134);
  a015=(a003*a015);
  a134=(a019*a015);
  a048=(a048+a134);
  a149=(a149-a048);
  a048=(a003*a149);
  a134=(a045*a048);
  a169=(a169+a134);
  a116=(a040*a074);
  a151=(a042*a149);
  a116=(a116+a151);
  a136=(a026*a136);
  a138=(a067*a138);
  a136=(a136+a138);
  a033=(a033-a136);
  a062=(a050*a062);
  a062=(a062-a145);
  a033=(a033-a062);
  a150=(a019*a150);
  a139=(a139+a150);
  a033=(a033-a139);
  a015=(a053*a015);
  a089=(a089+a015);
  a033=(a033+a089);
  a089=(a045*a033);
  a116=(a116+a089);
  a116=(a058*a116);
  a089=(a040*a116);
  a169=(a169+a089);
  a015=(a003*a033);
  a139=(a042*a015);
  a169=(a169-a139);
  a169=(a169/a000);
  if (res[1]!=0) res[1][21]=a169;
  a169=(a003*a074);
  a150=(a045*a169);
  a094=(a094+a150);
  a094=(a149-a094);
  a062=(a042*a116);
  a094=(a094+a062);
  a015=(a040*a015);
  a094=(a094+a015);
  a094=(a094/a000);
  if (res[1]!=0) res[1][22]=a094;
  a169=(a042*a169);
  a165=(a169-a165);
  a048=(a040*a048);
  a165=(a165-a048);
  a116=(a045*a116);
  a165=(a165+a116);
  a165=(a165+a033);
  a165=(a165/a000);
  if (res[1]!=0) res[1][23]=a165;
  a172=(a025*a172);
  a172=(a058*a172);
  a165=(a142*a172);
  a161=(a161-a165);
  a161=(a161-a074);
  a161=(a161+a134);
  a161=(a161-a089);
  a161=(a161-a139);
  a161=(a161+a082);
  a161=(a161-a034);
  a161=(a161-a146);
  a161=(a161-a037);
  if (res[1]!=0) res[1][24]=a161;
  a161=(a140*a172);
  a161=(a161+a083);
  a161=(a161+a150);
  a161=(a161+a149);
  a161=(a161+a062);
  a015=(a015-a161);
  a015=(a015-a020);
  a015=(a015+a131);
  a015=(a015-a179);
  a015=(a015-a117);
  if (res[1]!=0) res[1][25]=a015;
  a172=(a043*a172);
  a173=(a173+a172);
  a169=(a169-a173);
  a169=(a169-a048);
  a169=(a169-a116);
  a169=(a169-a033);
  a169=(a169-a164);
  a169=(a169-a175);
  a169=(a169-a088);
  a169=(a169+a018);
  if (res[1]!=0) res[1][26]=a169;
  a016=(a016*a013);
  a169=(a060*a016);
  a018=(a028*a009);
  a018=(a013*a018);
  a088=(a029*a018);
  a175=(a009*a016);
  a164=(a028*a002);
  a164=(a013*a164);
  a033=(-a164);
  a033=(2.*a033);
  a116=(a006*a033);
  a116=(a175-a116);
  a116=(a003*a116);
  a116=(a088-a116);
  a116=(a013*a116);
  a048=(a028*a116);
  a173=(a014*a042);
  a008=(a008*a000);
  a172=(a173-a008);
  a172=(a003*a172);
  a172=(a047*a172);
  a044=(a047/a044);
  a015=(2.*a040);
  a015=(a015*a000);
  a117=(a044*a015);
  a179=(a017*a117);
  a172=(a172-a179);
  a179=(a029*a172);
  a131=(a014*a047);
  a020=(a049*a117);
  a020=(a131-a020);
  a161=(a042*a020);
  a054=(a054*a000);
  a001=(a001*a000);
  a062=(a014*a045);
  a149=(a001-a062);
  a149=(a003*a149);
  a149=(a047*a149);
  a150=(a052*a117);
  a149=(a149-a150);
  a150=(2.*a149);
  a083=(a040*a150);
  a083=(a054+a083);
  a161=(a161-a083);
  a161=(a003*a161);
  a161=(a179-a161);
  a161=(a047*a161);
  a083=(a051*a117);
  a161=(a161-a083);
  a083=(a039*a161);
  a048=(a048+a083);
  a083=(a000*a048);
  a037=(a027*a083);
  a116=(a039*a116);
  a161=(a059*a161);
  a116=(a116+a161);
  a161=(a000*a116);
  a146=(a058*a161);
  a037=(a037+a146);
  a146=(a003*a037);
  a034=(a024*a146);
  a034=(a169+a034);
  a082=(a006*a088);
  a139=(a002*a016);
  a082=(a082-a139);
  a082=(a003*a082);
  a082=(a033-a082);
  a082=(a013*a082);
  a089=(a039*a082);
  a022=(a022*a000);
  a134=(a040*a179);
  a134=(a022+a134);
  a074=(a045*a020);
  a134=(a134-a074);
  a134=(a003*a134);
  a134=(a150-a134);
  a134=(a047*a134);
  a074=(a066*a117);
  a134=(a134-a074);
  a074=(a059*a134);
  a089=(a089+a074);
  a034=(a034+a089);
  a074=(a006*a016);
  a165=(a009*a164);
  a074=(a074-a165);
  a094=(a002*a018);
  a074=(a074+a094);
  a074=(a058*a074);
  a145=(a070*a074);
  a082=(a028*a082);
  a134=(a039*a134);
  a082=(a082+a134);
  a134=(a000*a082);
  a136=(a027*a134);
  a089=(a000*a089);
  a138=(a058*a089);
  a136=(a136+a138);
  a138=(a068*a136);
  a145=(a145+a138);
  a034=(a034-a145);
  a145=(a002*a037);
  a138=(a009*a136);
  a145=(a145+a138);
  a033=(a002*a033);
  a088=(a009*a088);
  a033=(a033-a088);
  a033=(a003*a033);
  a033=(a016-a033);
  a033=(a013*a033);
  a088=(a028*a033);
  a150=(a045*a150);
  a179=(a042*a179);
  a150=(a150-a179);
  a150=(a003*a150);
  a150=(a020-a150);
  a150=(a047*a150);
  a179=(a077*a117);
  a150=(a150-a179);
  a179=(a039*a150);
  a088=(a088+a179);
  a179=(a000*a088);
  a138=(a027*a179);
  a033=(a039*a033);
  a150=(a059*a150);
  a033=(a033+a150);
  a150=(a000*a033);
  a151=(a058*a150);
  a138=(a138+a151);
  a151=(a006*a138);
  a145=(a145+a151);
  a145=(a058*a145);
  a151=(a035*a145);
  a093=(a071*a164);
  a151=(a151-a093);
  a034=(a034-a151);
  a151=(a081*a018);
  a061=(a003*a138);
  a148=(a031*a061);
  a151=(a151+a148);
  a034=(a034-a151);
  a151=(a003*a034);
  a148=(a002*a151);
  a124=(a057*a074);
  a037=(a068*a037);
  a124=(a124+a037);
  a116=(a116-a124);
  a124=(a084*a016);
  a136=(a003*a136);
  a037=(a024*a136);
  a037=(a124+a037);
  a116=(a116-a037);
  a037=(a071*a018);
  a158=(a031*a145);
  a158=(a037+a158);
  a116=(a116-a158);
  a061=(a035*a061);
  a158=(a081*a164);
  a061=(a061-a158);
  a116=(a116+a061);
  a061=(a003*a116);
  a158=(a009*a061);
  a176=(a148-a158);
  a128=(a009*a034);
  a100=(a002*a116);
  a128=(a128+a100);
  a100=(a084*a018);
  a136=(a031*a136);
  a136=(a100+a136);
  a146=(a035*a146);
  a092=(a060*a164);
  a146=(a146-a092);
  a136=(a136-a146);
  a136=(a136+a033);
  a074=(a080*a074);
  a138=(a068*a138);
  a074=(a074+a138);
  a136=(a136-a074);
  a074=(a071*a016);
  a145=(a024*a145);
  a145=(a074+a145);
  a136=(a136-a145);
  a145=(a006*a136);
  a128=(a128+a145);
  a128=(a058*a128);
  a145=(a006*a128);
  a176=(a176+a145);
  a176=(a176+a136);
  a138=(a111*a016);
  a138=(a115*a138);
  a176=(a176-a138);
  a176=(a176/a000);
  if (res[1]!=0) res[1][27]=a176;
  a061=(a006*a061);
  a176=(a034+a061);
  a033=(a009*a128);
  a176=(a176+a033);
  a146=(a003*a136);
  a097=(a002*a146);
  a176=(a176-a097);
  a154=(a111*a164);
  a154=(a115*a154);
  a176=(a176+a154);
  a176=(a176/a000);
  if (res[1]!=0) res[1][28]=a176;
  a151=(a006*a151);
  a176=(a116-a151);
  a128=(a002*a128);
  a176=(a176+a128);
  a146=(a009*a146);
  a176=(a176+a146);
  a086=(a111*a018);
  a086=(a115*a086);
  a176=(a176-a086);
  a176=(a176/a000);
  if (res[1]!=0) res[1][29]=a176;
  a176=(a042*a000);
  a176=(a003*a176);
  a176=(a047*a176);
  a098=(a106*a117);
  a098=(a176-a098);
  a030=(a091*a098);
  a015=(a003*a015);
  a015=(a047*a015);
  a160=(a101*a117);
  a160=(a015-a160);
  a104=(a095*a160);
  a030=(a030-a104);
  a104=(a047*a000);
  a121=(a010*a117);
  a121=(a104-a121);
  a123=(a099*a121);
  a030=(a030+a123);
  a123=(a045*a000);
  a123=(a003*a123);
  a123=(a047*a123);
  a011=(a122*a117);
  a011=(a123-a011);
  a012=(a103*a011);
  a007=(a129*a117);
  a007=(a007+a104);
  a152=(a107*a007);
  a012=(a012-a152);
  a152=(a041*a117);
  a015=(a015-a152);
  a152=(a110*a015);
  a012=(a012-a152);
  a152=(a102*a012);
  a030=(a030+a152);
  a011=(a113*a011);
  a007=(a114*a007);
  a011=(a011-a007);
  a015=(a109*a015);
  a011=(a011-a015);
  a015=(a112*a011);
  a030=(a030+a015);
  a030=(a090*a030);
  a015=(a111*a020);
  a030=(a030-a015);
  a030=(a115*a030);
  a015=(a055*a149);
  a083=(a058*a083);
  a161=(a056*a161);
  a083=(a083+a161);
  a161=(a003*a083);
  a007=(a053*a161);
  a015=(a015+a007);
  a088=(a088-a015);
  a015=(a065*a172);
  a134=(a058*a134);
  a089=(a056*a089);
  a134=(a134+a089);
  a089=(a003*a134);
  a007=(a019*a089);
  a015=(a015+a007);
  a088=(a088+a015);
  a015=(a050*a000);
  a007=(a040*a020);
  a007=(a015+a007);
  a152=(a042*a149);
  a007=(a007+a152);
  a152=(a045*a172);
  a007=(a007+a152);
  a007=(a058*a007);
  a152=(a073*a007);
  a179=(a058*a179);
  a150=(a056*a150);
  a179=(a179+a150);
  a150=(a067*a179);
  a152=(a152+a150);
  a088=(a088-a152);
  a152=(a078*a020);
  a150=(a045*a083);
  a108=(a042*a134);
  a150=(a150+a108);
  a108=(a073*a000);
  a036=(a040*a179);
  a108=(a108+a036);
  a150=(a150+a108);
  a150=(a058*a150);
  a108=(a050*a150);
  a152=(a152+a108);
  a088=(a088-a152);
  a030=(a030+a088);
  a152=(a055*a020);
  a161=(a050*a161);
  a152=(a152+a161);
  a082=(a082+a152);
  a152=(a069*a007);
  a134=(a067*a134);
  a152=(a152+a134);
  a082=(a082-a152);
  a152=(a078*a149);
  a134=(a053*a150);
  a152=(a152+a134);
  a082=(a082-a152);
  a152=(a079*a172);
  a179=(a003*a179);
  a134=(a019*a179);
  a152=(a152+a134);
  a082=(a082-a152);
  a152=(a003*a082);
  a134=(a045*a152);
  a030=(a030+a134);
  a130=(a130*a000);
  a076=(a076*a000);
  a161=(a040*a088);
  a076=(a076+a161);
  a161=(a042*a082);
  a076=(a076+a161);
  a007=(a026*a007);
  a083=(a067*a083);
  a007=(a007+a083);
  a048=(a048-a007);
  a020=(a065*a020);
  a089=(a050*a089);
  a020=(a020+a089);
  a048=(a048-a020);
  a020=(a078*a172);
  a150=(a019*a150);
  a020=(a020+a150);
  a048=(a048-a020);
  a020=(a079*a149);
  a179=(a053*a179);
  a020=(a020+a179);
  a048=(a048+a020);
  a020=(a045*a048);
  a076=(a076+a020);
  a076=(a058*a076);
  a020=(a040*a076);
  a020=(a130+a020);
  a030=(a030+a020);
  a179=(a003*a048);
  a150=(a042*a179);
  a030=(a030-a150);
  a030=(a030/a000);
  if (res[1]!=0) res[1][30]=a030;
  a012=(a119*a012);
  a030=(a046*a117);
  a089=(a091*a030);
  a007=(a135*a117);
  a007=(a176-a007);
  a083=(a095*a007);
  a089=(a089+a083);
  a117=(a137*a117);
  a117=(a123-a117);
  a083=(a099*a117);
  a089=(a089+a083);
  a012=(a012-a089);
  a011=(a102*a011);
  a012=(a012+a011);
  a012=(a090*a012);
  a149=(a111*a149);
  a012=(a012-a149);
  a012=(a115*a012);
  a149=(a003*a088);
  a011=(a045*a149);
  a012=(a012-a011);
  a012=(a012+a082);
  a089=(a042*a076);
  a012=(a012+a089);
  a133=(a133*a000);
  a179=(a040*a179);
  a179=(a133+a179);
  a012=(a012+a179);
  a012=(a012/a000);
  if (res[1]!=0) res[1][31]=a012;
  a012=(a113*a030);
  a083=(a114*a007);
  a012=(a012+a083);
  a083=(a109*a117);
  a012=(a012+a083);
  a012=(a119*a012);
  a083=(a103*a098);
  a161=(a107*a160);
  a083=(a083-a161);
  a161=(a110*a121);
  a083=(a083+a161);
  a083=(a112*a083);
  a012=(a012+a083);
  a030=(a103*a030);
  a007=(a107*a007);
  a030=(a030+a007);
  a117=(a110*a117);
  a030=(a030+a117);
  a030=(a126*a030);
  a012=(a012+a030);
  a098=(a113*a098);
  a160=(a114*a160);
  a098=(a098-a160);
  a121=(a109*a121);
  a098=(a098+a121);
  a098=(a126*a098);
  a012=(a012+a098);
  a012=(a090*a012);
  a172=(a111*a172);
  a012=(a012-a172);
  a012=(a115*a012);
  a149=(a042*a149);
  a012=(a012+a149);
  a004=(a004*a000);
  a152=(a040*a152);
  a152=(a004+a152);
  a012=(a012-a152);
  a076=(a045*a076);
  a012=(a012+a076);
  a012=(a012+a048);
  a012=(a012/a000);
  if (res[1]!=0) res[1][32]=a012;
  a012=1.7320508075688774e+00;
  a172=(a012*a000);
  a143=(a143*a172);
  a072=(a072*a172);
  a072=(a058*a072);
  a098=(a142*a072);
  a098=(a143+a098);
  a098=(a098+a088);
  a134=(a134-a098);
  a134=(a134-a020);
  a134=(a134-a150);
  a134=(a134+a148);
  a134=(a134-a158);
  a134=(a134-a145);
  a134=(a134-a136);
  if (res[1]!=0) res[1][33]=a134;
  a141=(a141*a172);
  a134=(a140*a072);
  a134=(a141-a134);
  a134=(a134-a011);
  a134=(a134-a082);
  a134=(a134-a089);
  a134=(a134+a179);
  a134=(a134-a034);
  a134=(a134+a061);
  a134=(a134-a033);
  a134=(a134-a097);
  if (res[1]!=0) res[1][34]=a134;
  a023=(a023*a172);
  a072=(a043*a072);
  a072=(a023+a072);
  a149=(a149-a072);
  a149=(a149-a152);
  a149=(a149-a076);
  a149=(a149-a048);
  a149=(a149-a151);
  a149=(a149-a116);
  a149=(a149-a128);
  a149=(a149+a146);
  if (res[1]!=0) res[1][35]=a149;
  a005=(a005*a000);
  a014=(a014*a040);
  a149=(a005-a014);
  a149=(a003*a149);
  a149=(a047*a149);
  a146=(2.*a042);
  a146=(a146*a000);
  a128=(a044*a146);
  a116=(a017*a128);
  a149=(a149-a116);
  a116=(a029*a149);
  a062=(a062-a001);
  a062=(a003*a062);
  a062=(a047*a062);
  a001=(a049*a128);
  a062=(a062-a001);
  a001=(a042*a062);
  a001=(a015+a001);
  a151=(a052*a128);
  a151=(a131-a151);
  a048=(2.*a151);
  a076=(a040*a048);
  a001=(a001-a076);
  a001=(a003*a001);
  a001=(a116-a001);
  a001=(a047*a001);
  a076=(a051*a128);
  a001=(a001-a076);
  a076=(a039*a001);
  a152=(a028*a006);
  a152=(a013*a152);
  a072=(a029*a152);
  a134=9.2820323027550877e-01;
  a134=(a134*a013);
  a097=(a006*a134);
  a165=(a165-a097);
  a165=(a003*a165);
  a165=(a072+a165);
  a165=(a013*a165);
  a097=(a028*a165);
  a076=(a076-a097);
  a097=(a000*a076);
  a033=(a027*a097);
  a001=(a059*a001);
  a165=(a039*a165);
  a001=(a001-a165);
  a165=(a000*a001);
  a061=(a058*a165);
  a033=(a033+a061);
  a061=(a003*a033);
  a034=(a024*a061);
  a092=(a092+a034);
  a034=(a006*a072);
  a179=(a002*a164);
  a034=(a034+a179);
  a034=(a003*a034);
  a034=(a134+a034);
  a034=(a013*a034);
  a179=(a039*a034);
  a089=(a040*a116);
  a082=(a045*a062);
  a089=(a089-a082);
  a089=(a003*a089);
  a089=(a048-a089);
  a089=(a047*a089);
  a082=(a066*a128);
  a089=(a089-a082);
  a082=(a059*a089);
  a179=(a179+a082);
  a092=(a092+a179);
  a082=(a006*a164);
  a082=(a082+a175);
  a175=(a002*a152);
  a082=(a082-a175);
  a082=(a058*a082);
  a175=(a070*a082);
  a034=(a028*a034);
  a089=(a039*a089);
  a034=(a034+a089);
  a089=(a000*a034);
  a011=(a027*a089);
  a179=(a000*a179);
  a136=(a058*a179);
  a011=(a011+a136);
  a136=(a068*a011);
  a175=(a175+a136);
  a092=(a092-a175);
  a175=(a002*a033);
  a136=(a009*a011);
  a175=(a175+a136);
  a134=(a002*a134);
  a072=(a009*a072);
  a134=(a134+a072);
  a134=(a003*a134);
  a134=(a164-a134);
  a134=(a013*a134);
  a072=(a028*a134);
  a048=(a045*a048);
  a116=(a042*a116);
  a022=(a022+a116);
  a048=(a048-a022);
  a048=(a003*a048);
  a048=(a062-a048);
  a048=(a047*a048);
  a022=(a077*a128);
  a048=(a048-a022);
  a022=(a039*a048);
  a072=(a072+a022);
  a022=(a000*a072);
  a116=(a027*a022);
  a134=(a039*a134);
  a048=(a059*a048);
  a134=(a134+a048);
  a048=(a000*a134);
  a136=(a058*a048);
  a116=(a116+a136);
  a136=(a006*a116);
  a175=(a175+a136);
  a175=(a058*a175);
  a136=(a035*a175);
  a136=(a074+a136);
  a092=(a092-a136);
  a136=(a003*a116);
  a145=(a031*a136);
  a158=(a081*a152);
  a145=(a145-a158);
  a092=(a092-a145);
  a145=(a003*a092);
  a148=(a002*a145);
  a150=(a057*a082);
  a033=(a068*a033);
  a150=(a150+a033);
  a001=(a001-a150);
  a164=(a084*a164);
  a011=(a003*a011);
  a150=(a024*a011);
  a164=(a164+a150);
  a001=(a001-a164);
  a164=(a031*a175);
  a071=(a071*a152);
  a164=(a164-a071);
  a001=(a001-a164);
  a081=(a081*a016);
  a136=(a035*a136);
  a136=(a081+a136);
  a001=(a001+a136);
  a136=(a003*a001);
  a016=(a009*a136);
  a164=(a148-a016);
  a150=(a009*a092);
  a033=(a002*a001);
  a150=(a150+a033);
  a011=(a031*a011);
  a084=(a084*a152);
  a011=(a011-a084);
  a061=(a035*a061);
  a169=(a169+a061);
  a011=(a011-a169);
  a011=(a011+a134);
  a082=(a080*a082);
  a116=(a068*a116);
  a082=(a082+a116);
  a011=(a011-a082);
  a175=(a024*a175);
  a093=(a093+a175);
  a011=(a011-a093);
  a093=(a006*a011);
  a150=(a150+a093);
  a150=(a058*a150);
  a093=(a006*a150);
  a164=(a164+a093);
  a164=(a164+a011);
  a164=(a164-a154);
  a164=(a164/a000);
  if (res[1]!=0) res[1][36]=a164;
  a136=(a006*a136);
  a164=(a092+a136);
  a154=(a009*a150);
  a164=(a164+a154);
  a175=(a003*a011);
  a082=(a002*a175);
  a164=(a164-a082);
  a164=(a164-a138);
  a164=(a164/a000);
  if (res[1]!=0) res[1][37]=a164;
  a145=(a006*a145);
  a164=(a001-a145);
  a150=(a002*a150);
  a164=(a164+a150);
  a175=(a009*a175);
  a164=(a164+a175);
  a116=(a111*a152);
  a116=(a115*a116);
  a164=(a164+a116);
  a164=(a164/a000);
  if (res[1]!=0) res[1][38]=a164;
  a164=(a040*a000);
  a164=(a003*a164);
  a164=(a047*a164);
  a134=(a106*a128);
  a134=(a164-a134);
  a169=(a091*a134);
  a061=(a101*a128);
  a084=(a095*a061);
  a169=(a169+a084);
  a084=(a010*a128);
  a084=(a123-a084);
  a033=(a099*a084);
  a169=(a169+a033);
  a033=(a122*a128);
  a033=(a104-a033);
  a020=(a103*a033);
  a098=(a129*a128);
  a123=(a123-a098);
  a098=(a107*a123);
  a020=(a020+a098);
  a146=(a003*a146);
  a146=(a047*a146);
  a098=(a041*a128);
  a098=(a146-a098);
  a088=(a110*a098);
  a020=(a020-a088);
  a088=(a102*a020);
  a169=(a169+a088);
  a033=(a113*a033);
  a123=(a114*a123);
  a033=(a033+a123);
  a098=(a109*a098);
  a033=(a033-a098);
  a098=(a112*a033);
  a169=(a169+a098);
  a169=(a090*a169);
  a098=(a111*a062);
  a169=(a169-a098);
  a169=(a115*a169);
  a098=(a055*a151);
  a097=(a058*a097);
  a165=(a056*a165);
  a097=(a097+a165);
  a165=(a003*a097);
  a123=(a053*a165);
  a098=(a098+a123);
  a072=(a072-a098);
  a098=(a065*a149);
  a089=(a058*a089);
  a179=(a056*a179);
  a089=(a089+a179);
  a179=(a003*a089);
  a123=(a019*a179);
  a098=(a098+a123);
  a072=(a072+a098);
  a098=(a040*a062);
  a123=(a053*a000);
  a088=(a042*a151);
  a123=(a123+a088);
  a098=(a098+a123);
  a123=(a045*a149);
  a098=(a098+a123);
  a098=(a058*a098);
  a123=(a073*a098);
  a022=(a058*a022);
  a048=(a056*a048);
  a022=(a022+a048);
  a048=(a067*a022);
  a123=(a123+a048);
  a072=(a072-a123);
  a123=(a078*a062);
  a048=(a045*a097);
  a088=(a069*a000);
  a121=(a042*a089);
  a088=(a088+a121);
  a048=(a048+a088);
  a088=(a040*a022);
  a048=(a048+a088);
  a048=(a058*a048);
  a088=(a050*a048);
  a123=(a123+a088);
  a072=(a072-a123);
  a169=(a169+a072);
  a123=(a055*a062);
  a165=(a050*a165);
  a123=(a123+a165);
  a034=(a034+a123);
  a123=(a069*a098);
  a089=(a067*a089);
  a123=(a123+a089);
  a034=(a034-a123);
  a123=(a078*a151);
  a089=(a053*a048);
  a123=(a123+a089);
  a034=(a034-a123);
  a123=(a079*a149);
  a022=(a003*a022);
  a089=(a019*a022);
  a123=(a123+a089);
  a034=(a034-a123);
  a123=(a003*a034);
  a089=(a045*a123);
  a169=(a169+a089);
  a165=(a040*a072);
  a063=(a063*a000);
  a088=(a042*a034);
  a063=(a063+a088);
  a165=(a165+a063);
  a098=(a026*a098);
  a097=(a067*a097);
  a098=(a098+a097);
  a076=(a076-a098);
  a062=(a065*a062);
  a179=(a050*a179);
  a062=(a062+a179);
  a076=(a076-a062);
  a062=(a078*a149);
  a048=(a019*a048);
  a062=(a062+a048);
  a076=(a076-a062);
  a062=(a079*a151);
  a022=(a053*a022);
  a062=(a062+a022);
  a076=(a076+a062);
  a062=(a045*a076);
  a165=(a165+a062);
  a165=(a058*a165);
  a062=(a040*a165);
  a169=(a169+a062);
  a022=(a003*a076);
  a048=(a042*a022);
  a133=(a133+a048);
  a169=(a169-a133);
  a169=(a169/a000);
  if (res[1]!=0) res[1][39]=a169;
  a020=(a119*a020);
  a169=(a135*a128);
  a169=(a164-a169);
  a048=(a095*a169);
  a179=(a046*a128);
  a146=(a146-a179);
  a179=(a091*a146);
  a048=(a048-a179);
  a128=(a137*a128);
  a128=(a128+a104);
  a179=(a099*a128);
  a048=(a048-a179);
  a020=(a020-a048);
  a033=(a102*a033);
  a020=(a020+a033);
  a020=(a090*a020);
  a151=(a111*a151);
  a020=(a020-a151);
  a020=(a115*a020);
  a151=(a003*a072);
  a033=(a045*a151);
  a020=(a020-a033);
  a020=(a020+a034);
  a048=(a042*a165);
  a048=(a130+a048);
  a020=(a020+a048);
  a022=(a040*a022);
  a020=(a020+a022);
  a020=(a020/a000);
  if (res[1]!=0) res[1][40]=a020;
  a020=(a114*a169);
  a179=(a113*a146);
  a020=(a020-a179);
  a179=(a109*a128);
  a020=(a020-a179);
  a020=(a119*a020);
  a179=(a103*a134);
  a098=(a107*a061);
  a179=(a179+a098);
  a098=(a110*a084);
  a179=(a179+a098);
  a179=(a112*a179);
  a020=(a020+a179);
  a169=(a107*a169);
  a146=(a103*a146);
  a169=(a169-a146);
  a128=(a110*a128);
  a169=(a169-a128);
  a169=(a126*a169);
  a020=(a020+a169);
  a134=(a113*a134);
  a061=(a114*a061);
  a134=(a134+a061);
  a084=(a109*a084);
  a134=(a134+a084);
  a134=(a126*a134);
  a020=(a020+a134);
  a020=(a090*a020);
  a149=(a111*a149);
  a020=(a020-a149);
  a020=(a115*a020);
  a127=(a127*a000);
  a151=(a042*a151);
  a151=(a127+a151);
  a020=(a020+a151);
  a123=(a040*a123);
  a020=(a020-a123);
  a165=(a045*a165);
  a020=(a020+a165);
  a020=(a020+a076);
  a020=(a020/a000);
  if (res[1]!=0) res[1][41]=a020;
  a064=(a064*a172);
  a064=(a058*a064);
  a020=(a142*a064);
  a141=(a141+a020);
  a141=(a141+a072);
  a089=(a089-a141);
  a089=(a089-a062);
  a089=(a089-a133);
  a089=(a089+a148);
  a089=(a089-a016);
  a089=(a089-a093);
  a089=(a089-a011);
  if (res[1]!=0) res[1][42]=a089;
  a089=(a140*a064);
  a089=(a143+a089);
  a089=(a089+a033);
  a089=(a089+a034);
  a089=(a089+a048);
  a022=(a022-a089);
  a022=(a022-a092);
  a022=(a022+a136);
  a022=(a022-a154);
  a022=(a022-a082);
  if (res[1]!=0) res[1][43]=a022;
  a075=(a075*a172);
  a064=(a043*a064);
  a064=(a075-a064);
  a064=(a064+a151);
  a064=(a064-a123);
  a064=(a064-a165);
  a064=(a064-a076);
  a064=(a064-a145);
  a064=(a064-a001);
  a064=(a064-a150);
  a064=(a064+a175);
  if (res[1]!=0) res[1][44]=a064;
  a064=1.3923048454132632e+00;
  a064=(a064*a013);
  a175=(a009*a018);
  a150=(2.*a152);
  a001=(a006*a150);
  a175=(a175+a001);
  a175=(a003*a175);
  a175=(a064+a175);
  a175=(a013*a175);
  a001=(a028*a175);
  a145=(2.*a045);
  a145=(a145*a000);
  a044=(a044*a145);
  a017=(a017*a044);
  a131=(a131-a017);
  a029=(a029*a131);
  a008=(a008-a173);
  a008=(a003*a008);
  a008=(a047*a008);
  a049=(a049*a044);
  a008=(a008-a049);
  a049=(a042*a008);
  a014=(a014-a005);
  a014=(a003*a014);
  a014=(a047*a014);
  a052=(a052*a044);
  a014=(a014-a052);
  a052=(2.*a014);
  a005=(a040*a052);
  a049=(a049-a005);
  a049=(a003*a049);
  a049=(a029-a049);
  a049=(a047*a049);
  a051=(a051*a044);
  a049=(a049-a051);
  a051=(a039*a049);
  a001=(a001+a051);
  a051=(a000*a001);
  a005=(a027*a051);
  a175=(a039*a175);
  a049=(a059*a049);
  a175=(a175+a049);
  a049=(a000*a175);
  a173=(a058*a049);
  a005=(a005+a173);
  a173=(a003*a005);
  a017=(a024*a173);
  a076=(a060*a018);
  a017=(a017-a076);
  a076=(a006*a064);
  a076=(a076+a094);
  a076=(a003*a076);
  a076=(a150-a076);
  a076=(a013*a076);
  a094=(a039*a076);
  a165=(a040*a029);
  a123=(a045*a008);
  a015=(a015+a123);
  a165=(a165-a015);
  a165=(a003*a165);
  a165=(a052-a165);
  a165=(a047*a165);
  a066=(a066*a044);
  a165=(a165-a066);
  a066=(a059*a165);
  a094=(a094+a066);
  a017=(a017+a094);
  a066=(a009*a152);
  a015=(a006*a018);
  a066=(a066-a015);
  a066=(a066+a139);
  a066=(a058*a066);
  a070=(a070*a066);
  a076=(a028*a076);
  a165=(a039*a165);
  a076=(a076+a165);
  a165=(a000*a076);
  a139=(a027*a165);
  a094=(a000*a094);
  a015=(a058*a094);
  a139=(a139+a015);
  a015=(a068*a139);
  a070=(a070+a015);
  a017=(a017-a070);
  a070=(a002*a005);
  a015=(a009*a139);
  a070=(a070+a015);
  a052=(a045*a052);
  a054=(a054+a052);
  a029=(a042*a029);
  a054=(a054-a029);
  a054=(a003*a054);
  a054=(a008-a054);
  a054=(a047*a054);
  a077=(a077*a044);
  a054=(a054-a077);
  a077=(a039*a054);
  a150=(a002*a150);
  a064=(a009*a064);
  a150=(a150-a064);
  a150=(a003*a150);
  a018=(a018+a150);
  a013=(a013*a018);
  a028=(a028*a013);
  a077=(a077-a028);
  a028=(a000*a077);
  a027=(a027*a028);
  a059=(a059*a054);
  a039=(a039*a013);
  a059=(a059-a039);
  a039=(a000*a059);
  a013=(a058*a039);
  a027=(a027+a013);
  a013=(a006*a027);
  a070=(a070+a013);
  a070=(a058*a070);
  a013=(a035*a070);
  a071=(a071+a013);
  a017=(a017-a071);
  a071=(a003*a027);
  a013=(a031*a071);
  a081=(a081+a013);
  a017=(a017-a081);
  a081=(a003*a017);
  a013=(a002*a081);
  a057=(a057*a066);
  a005=(a068*a005);
  a057=(a057+a005);
  a175=(a175-a057);
  a139=(a003*a139);
  a057=(a024*a139);
  a057=(a057-a100);
  a175=(a175-a057);
  a057=(a031*a070);
  a074=(a074+a057);
  a175=(a175-a074);
  a071=(a035*a071);
  a158=(a158+a071);
  a175=(a175+a158);
  a158=(a003*a175);
  a071=(a009*a158);
  a074=(a013-a071);
  a057=(a009*a017);
  a100=(a002*a175);
  a057=(a057+a100);
  a139=(a031*a139);
  a124=(a124+a139);
  a060=(a060*a152);
  a173=(a035*a173);
  a060=(a060+a173);
  a124=(a124-a060);
  a124=(a124+a059);
  a080=(a080*a066);
  a027=(a068*a027);
  a080=(a080+a027);
  a124=(a124-a080);
  a070=(a024*a070);
  a070=(a070-a037);
  a124=(a124-a070);
  a070=(a006*a124);
  a057=(a057+a070);
  a057=(a058*a057);
  a070=(a006*a057);
  a074=(a074+a070);
  a074=(a074+a124);
  a074=(a074+a086);
  a074=(a074/a000);
  if (res[1]!=0) res[1][45]=a074;
  a158=(a006*a158);
  a074=(a017+a158);
  a086=(a009*a057);
  a074=(a074+a086);
  a037=(a003*a124);
  a080=(a002*a037);
  a074=(a074-a080);
  a074=(a074-a116);
  a074=(a074/a000);
  if (res[1]!=0) res[1][46]=a074;
  a081=(a006*a081);
  a074=(a175-a081);
  a057=(a002*a057);
  a074=(a074+a057);
  a037=(a009*a037);
  a074=(a074+a037);
  a074=(a074-a138);
  a074=(a074/a000);
  if (res[1]!=0) res[1][47]=a074;
  a010=(a010*a044);
  a010=(a176-a010);
  a074=(a099*a010);
  a106=(a106*a044);
  a106=(a106+a104);
  a138=(a091*a106);
  a145=(a003*a145);
  a047=(a047*a145);
  a101=(a101*a044);
  a101=(a047-a101);
  a145=(a095*a101);
  a138=(a138+a145);
  a074=(a074-a138);
  a122=(a122*a044);
  a122=(a164-a122);
  a138=(a103*a122);
  a129=(a129*a044);
  a176=(a176-a129);
  a129=(a107*a176);
  a138=(a138+a129);
  a041=(a041*a044);
  a129=(a110*a041);
  a138=(a138+a129);
  a129=(a102*a138);
  a074=(a074+a129);
  a122=(a113*a122);
  a176=(a114*a176);
  a122=(a122+a176);
  a041=(a109*a041);
  a122=(a122+a041);
  a041=(a112*a122);
  a074=(a074+a041);
  a074=(a090*a074);
  a041=(a111*a008);
  a074=(a074-a041);
  a074=(a115*a074);
  a041=(a055*a014);
  a051=(a058*a051);
  a049=(a056*a049);
  a051=(a051+a049);
  a049=(a003*a051);
  a176=(a053*a049);
  a041=(a041+a176);
  a077=(a077-a041);
  a041=(a065*a131);
  a165=(a058*a165);
  a094=(a056*a094);
  a165=(a165+a094);
  a094=(a003*a165);
  a176=(a019*a094);
  a041=(a041+a176);
  a077=(a077+a041);
  a041=(a040*a008);
  a176=(a042*a014);
  a041=(a041+a176);
  a176=(a019*a000);
  a129=(a045*a131);
  a176=(a176+a129);
  a041=(a041+a176);
  a041=(a058*a041);
  a073=(a073*a041);
  a028=(a058*a028);
  a056=(a056*a039);
  a028=(a028+a056);
  a056=(a067*a028);
  a073=(a073+a056);
  a077=(a077-a073);
  a073=(a078*a008);
  a056=(a026*a000);
  a039=(a045*a051);
  a056=(a056+a039);
  a039=(a042*a165);
  a056=(a056+a039);
  a039=(a040*a028);
  a056=(a056+a039);
  a056=(a058*a056);
  a039=(a050*a056);
  a073=(a073+a039);
  a077=(a077-a073);
  a074=(a074+a077);
  a055=(a055*a008);
  a049=(a050*a049);
  a055=(a055+a049);
  a076=(a076+a055);
  a069=(a069*a041);
  a165=(a067*a165);
  a069=(a069+a165);
  a076=(a076-a069);
  a069=(a078*a014);
  a165=(a053*a056);
  a069=(a069+a165);
  a076=(a076-a069);
  a069=(a079*a131);
  a028=(a003*a028);
  a165=(a019*a028);
  a069=(a069+a165);
  a076=(a076-a069);
  a069=(a003*a076);
  a165=(a045*a069);
  a004=(a004+a165);
  a074=(a074+a004);
  a165=(a040*a077);
  a055=(a042*a076);
  a165=(a165+a055);
  a038=(a038*a000);
  a026=(a026*a041);
  a051=(a067*a051);
  a026=(a026+a051);
  a001=(a001-a026);
  a065=(a065*a008);
  a094=(a050*a094);
  a065=(a065+a094);
  a001=(a001-a065);
  a078=(a078*a131);
  a056=(a019*a056);
  a078=(a078+a056);
  a001=(a001-a078);
  a079=(a079*a014);
  a028=(a053*a028);
  a079=(a079+a028);
  a001=(a001+a079);
  a079=(a045*a001);
  a038=(a038+a079);
  a165=(a165+a038);
  a165=(a058*a165);
  a038=(a040*a165);
  a074=(a074+a038);
  a079=(a003*a001);
  a028=(a042*a079);
  a074=(a074-a028);
  a074=(a074/a000);
  if (res[1]!=0) res[1][48]=a074;
  a138=(a119*a138);
  a135=(a135*a044);
  a104=(a104-a135);
  a095=(a095*a104);
  a046=(a046*a044);
  a047=(a047-a046);
  a091=(a091*a047);
  a095=(a095-a091);
  a137=(a137*a044);
  a164=(a164-a137);
  a099=(a099*a164);
  a095=(a095+a099);
  a138=(a138-a095);
  a102=(a102*a122);
  a138=(a138+a102);
  a138=(a090*a138);
  a014=(a111*a014);
  a138=(a138-a014);
  a138=(a115*a138);
  a014=(a003*a077);
  a102=(a045*a014);
  a127=(a127+a102);
  a138=(a138-a127);
  a138=(a138+a076);
  a102=(a042*a165);
  a138=(a138+a102);
  a079=(a040*a079);
  a138=(a138+a079);
  a138=(a138/a000);
  if (res[1]!=0) res[1][49]=a138;
  a138=(a114*a104);
  a122=(a113*a047);
  a138=(a138-a122);
  a122=(a109*a164);
  a138=(a138+a122);
  a119=(a119*a138);
  a138=(a110*a010);
  a122=(a103*a106);
  a095=(a107*a101);
  a122=(a122+a095);
  a138=(a138-a122);
  a112=(a112*a138);
  a119=(a119+a112);
  a107=(a107*a104);
  a103=(a103*a047);
  a107=(a107-a103);
  a110=(a110*a164);
  a107=(a107+a110);
  a107=(a126*a107);
  a119=(a119+a107);
  a109=(a109*a010);
  a113=(a113*a106);
  a114=(a114*a101);
  a113=(a113+a114);
  a109=(a109-a113);
  a126=(a126*a109);
  a119=(a119+a126);
  a090=(a090*a119);
  a111=(a111*a131);
  a090=(a090-a111);
  a090=(a115*a090);
  a014=(a042*a014);
  a090=(a090+a014);
  a069=(a040*a069);
  a090=(a090-a069);
  a165=(a045*a165);
  a130=(a130+a165);
  a090=(a090+a130);
  a090=(a090+a001);
  a090=(a090/a000);
  if (res[1]!=0) res[1][50]=a090;
  a025=(a025*a172);
  a025=(a058*a025);
  a172=(a142*a025);
  a023=(a023-a172);
  a023=(a023-a077);
  a023=(a023+a004);
  a023=(a023-a038);
  a023=(a023-a028);
  a023=(a023+a013);
  a023=(a023-a071);
  a023=(a023-a070);
  a023=(a023-a124);
  if (res[1]!=0) res[1][51]=a023;
  a023=(a140*a025);
  a023=(a023+a075);
  a023=(a023+a127);
  a023=(a023+a076);
  a023=(a023+a102);
  a079=(a079-a023);
  a079=(a079-a017);
  a079=(a079+a158);
  a079=(a079-a086);
  a079=(a079-a080);
  if (res[1]!=0) res[1][52]=a079;
  a025=(a043*a025);
  a143=(a143+a025);
  a014=(a014-a143);
  a014=(a014-a069);
  a014=(a014-a130);
  a014=(a014-a001);
  a014=(a014-a081);
  a014=(a014-a175);
  a014=(a014-a057);
  a014=(a014+a037);
  if (res[1]!=0) res[1][53]=a014;
  a014=-9.3301270189221941e-01;
  a014=(a014*a000);
  a014=(a115+a014);
  a037=4.3301270189221935e-01;
  a037=(a037*a000);
  a014=(a014+a037);
  a037=(a003*a014);
  a057=(a035*a037);
  a175=(a006*a014);
  a175=(a058*a175);
  a081=(a031*a175);
  a081=(a057-a081);
  a001=(a002*a081);
  a130=(a035*a175);
  a069=(a031*a037);
  a130=(a130+a069);
  a143=(a009*a130);
  a001=(a001-a143);
  a068=(a068*a014);
  a012=(a012-a068);
  a175=(a024*a175);
  a175=(a012-a175);
  a068=(a006*a175);
  a001=(a001+a068);
  a001=(a058*a001);
  a068=(a006*a001);
  a143=(a003*a130);
  a025=(a002*a143);
  a079=(a003*a081);
  a080=(a009*a079);
  a086=(a025+a080);
  a086=(a068-a086);
  a086=(a086+a175);
  a086=(a086/a000);
  if (res[1]!=0) res[1][54]=a086;
  a079=(a006*a079);
  a086=(a079-a130);
  a158=(a009*a001);
  a086=(a086+a158);
  a017=(a003*a175);
  a023=(a002*a017);
  a086=(a086-a023);
  a086=(a086/a000);
  if (res[1]!=0) res[1][55]=a086;
  a143=(a006*a143);
  a086=(a081+a143);
  a001=(a002*a001);
  a086=(a086+a001);
  a017=(a009*a017);
  a086=(a086+a017);
  a086=(a086/a000);
  if (res[1]!=0) res[1][56]=a086;
  a086=-4.3301270189221935e-01;
  a086=(a086*a000);
  a115=(a115+a086);
  a086=-6.6987298107780674e-02;
  a086=(a086*a000);
  a115=(a115+a086);
  a067=(a067*a115);
  a171=(a171-a067);
  a067=(a040*a115);
  a067=(a058*a067);
  a086=(a050*a067);
  a086=(a171-a086);
  a102=(a053*a067);
  a076=(a003*a115);
  a127=(a019*a076);
  a102=(a102+a127);
  a075=(a003*a102);
  a124=(a045*a075);
  a070=(a086-a124);
  a071=(a040*a086);
  a013=(a042*a102);
  a071=(a071-a013);
  a013=(a053*a076);
  a067=(a019*a067);
  a067=(a013-a067);
  a028=(a045*a067);
  a071=(a071+a028);
  a071=(a058*a071);
  a028=(a040*a071);
  a070=(a070+a028);
  a038=(a003*a067);
  a004=(a042*a038);
  a070=(a070-a004);
  a070=(a070/a000);
  if (res[1]!=0) res[1][57]=a070;
  a070=(a042*a071);
  a077=(a003*a086);
  a172=(a045*a077);
  a090=(a172+a102);
  a090=(a070-a090);
  a038=(a040*a038);
  a090=(a090+a038);
  a090=(a090/a000);
  if (res[1]!=0) res[1][58]=a090;
  a077=(a042*a077);
  a075=(a040*a075);
  a090=(a077+a075);
  a071=(a045*a071);
  a090=(a090+a071);
  a090=(a090+a067);
  a090=(a090/a000);
  if (res[1]!=0) res[1][59]=a090;
  a090=-1.;
  a165=(a058*a142);
  a111=(a142*a165);
  a111=(a090-a111);
  a111=(a111-a086);
  a111=(a111-a124);
  a111=(a111-a028);
  a111=(a111-a004);
  a111=(a111-a025);
  a111=(a111-a080);
  a111=(a111-a068);
  a111=(a111-a175);
  if (res[1]!=0) res[1][60]=a111;
  a111=(a140*a165);
  a175=(a003*a043);
  a111=(a111+a175);
  a111=(a111+a172);
  a102=(a102-a111);
  a102=(a102-a070);
  a102=(a102+a038);
  a102=(a102+a130);
  a102=(a102+a079);
  a102=(a102-a158);
  a102=(a102-a023);
  if (res[1]!=0) res[1][61]=a102;
  a102=(a003*a140);
  a165=(a043*a165);
  a165=(a102-a165);
  a165=(a165+a077);
  a165=(a165+a075);
  a165=(a165-a071);
  a165=(a165-a067);
  a165=(a165+a143);
  a165=(a165-a081);
  a165=(a165-a001);
  a165=(a165+a017);
  if (res[1]!=0) res[1][62]=a165;
  a165=(a009*a014);
  a165=(a058*a165);
  a017=(a035*a165);
  a017=(a012-a017);
  a001=(a003*a017);
  a081=(a002*a001);
  a037=(a024*a037);
  a143=(a031*a165);
  a143=(a037+a143);
  a067=(a003*a143);
  a071=(a009*a067);
  a075=(a081+a071);
  a077=(a009*a017);
  a023=(a002*a143);
  a077=(a077-a023);
  a165=(a024*a165);
  a069=(a069-a165);
  a165=(a006*a069);
  a077=(a077+a165);
  a077=(a058*a077);
  a165=(a006*a077);
  a075=(a075+a165);
  a075=(a075+a069);
  a075=(a075/a000);
  if (res[1]!=0) res[1][63]=a075;
  a067=(a006*a067);
  a075=(a017-a067);
  a023=(a009*a077);
  a075=(a075+a023);
  a158=(a003*a069);
  a079=(a002*a158);
  a075=(a075-a079);
  a075=(a075/a000);
  if (res[1]!=0) res[1][64]=a075;
  a077=(a002*a077);
  a001=(a006*a001);
  a075=(a143+a001);
  a075=(a077-a075);
  a158=(a009*a158);
  a075=(a075+a158);
  a075=(a075/a000);
  if (res[1]!=0) res[1][65]=a075;
  a075=(a042*a115);
  a075=(a058*a075);
  a130=(a050*a075);
  a127=(a127-a130);
  a130=(a053*a075);
  a130=(a171-a130);
  a038=(a003*a130);
  a070=(a045*a038);
  a111=(a127+a070);
  a172=(a040*a127);
  a068=(a042*a130);
  a172=(a172+a068);
  a076=(a050*a076);
  a075=(a019*a075);
  a075=(a076+a075);
  a068=(a045*a075);
  a172=(a172-a068);
  a172=(a058*a172);
  a068=(a040*a172);
  a111=(a111+a068);
  a080=(a003*a075);
  a025=(a042*a080);
  a111=(a111+a025);
  a111=(a111/a000);
  if (res[1]!=0) res[1][66]=a111;
  a111=(a003*a127);
  a004=(a045*a111);
  a028=(a130-a004);
  a124=(a042*a172);
  a028=(a028+a124);
  a080=(a040*a080);
  a028=(a028-a080);
  a028=(a028/a000);
  if (res[1]!=0) res[1][67]=a028;
  a111=(a042*a111);
  a038=(a040*a038);
  a028=(a111-a038);
  a172=(a045*a172);
  a028=(a028+a172);
  a028=(a028-a075);
  a028=(a028/a000);
  if (res[1]!=0) res[1][68]=a028;
  a028=(a058*a140);
  a086=(a142*a028);
  a175=(a175-a086);
  a175=(a175-a127);
  a175=(a175+a070);
  a175=(a175-a068);
  a175=(a175+a025);
  a175=(a175+a081);
  a175=(a175+a071);
  a175=(a175-a165);
  a175=(a175-a069);
  if (res[1]!=0) res[1][69]=a175;
  a175=(a140*a028);
  a090=(a090-a175);
  a090=(a090-a004);
  a090=(a090-a130);
  a090=(a090-a124);
  a090=(a090-a080);
  a090=(a090-a017);
  a090=(a090-a067);
  a090=(a090-a023);
  a090=(a090-a079);
  if (res[1]!=0) res[1][70]=a090;
  a090=(a003*a142);
  a028=(a043*a028);
  a028=(a090+a028);
  a111=(a111-a028);
  a111=(a111-a038);
  a111=(a111-a172);
  a111=(a111+a075);
  a111=(a111-a001);
  a111=(a111+a143);
  a111=(a111-a077);
  a111=(a111+a158);
  if (res[1]!=0) res[1][71]=a111;
  a014=(a002*a014);
  a014=(a058*a014);
  a035=(a035*a014);
  a037=(a037-a035);
  a035=(a003*a037);
  a111=(a002*a035);
  a031=(a031*a014);
  a012=(a012-a031);
  a031=(a003*a012);
  a158=(a009*a031);
  a077=(a111-a158);
  a143=(a009*a037);
  a001=(a002*a012);
  a143=(a143+a001);
  a024=(a024*a014);
  a057=(a057+a024);
  a024=(a006*a057);
  a143=(a143-a024);
  a143=(a058*a143);
  a024=(a006*a143);
  a077=(a077+a024);
  a077=(a077-a057);
  a077=(a077/a000);
  if (res[1]!=0) res[1][72]=a077;
  a031=(a006*a031);
  a077=(a037+a031);
  a014=(a009*a143);
  a077=(a077+a014);
  a001=(a003*a057);
  a075=(a002*a001);
  a077=(a077+a075);
  a077=(a077/a000);
  if (res[1]!=0) res[1][73]=a077;
  a006=(a006*a035);
  a035=(a012-a006);
  a002=(a002*a143);
  a035=(a035+a002);
  a009=(a009*a001);
  a035=(a035-a009);
  a035=(a035/a000);
  if (res[1]!=0) res[1][74]=a035;
  a115=(a045*a115);
  a115=(a058*a115);
  a053=(a053*a115);
  a076=(a076-a053);
  a053=(a003*a076);
  a035=(a045*a053);
  a050=(a050*a115);
  a013=(a013+a050);
  a050=(a035-a013);
  a001=(a042*a076);
  a143=(a040*a013);
  a001=(a001-a143);
  a019=(a019*a115);
  a171=(a171-a019);
  a019=(a045*a171);
  a001=(a001+a019);
  a001=(a058*a001);
  a019=(a040*a001);
  a050=(a050+a019);
  a115=(a003*a171);
  a143=(a042*a115);
  a050=(a050-a143);
  a050=(a050/a000);
  if (res[1]!=0) res[1][75]=a050;
  a003=(a003*a013);
  a050=(a045*a003);
  a077=(a050+a076);
  a172=(a042*a001);
  a077=(a077+a172);
  a115=(a040*a115);
  a077=(a077+a115);
  a077=(a077/a000);
  if (res[1]!=0) res[1][76]=a077;
  a045=(a045*a001);
  a042=(a042*a003);
  a040=(a040*a053);
  a053=(a042+a040);
  a053=(a045-a053);
  a053=(a053+a171);
  a053=(a053/a000);
  if (res[1]!=0) res[1][77]=a053;
  a058=(a058*a043);
  a142=(a142*a058);
  a102=(a102+a142);
  a013=(a013-a102);
  a013=(a013+a035);
  a013=(a013-a019);
  a013=(a013-a143);
  a013=(a013+a111);
  a013=(a013-a158);
  a013=(a013-a024);
  a013=(a013+a057);
  if (res[1]!=0) res[1][78]=a013;
  a140=(a140*a058);
  a090=(a090-a140);
  a090=(a090+a050);
  a090=(a090-a076);
  a090=(a090-a172);
  a090=(a090+a115);
  a090=(a090-a037);
  a090=(a090+a031);
  a090=(a090-a014);
  a090=(a090+a075);
  if (res[1]!=0) res[1][79]=a090;
  a043=(a043*a058);
  a096=(a096+a043);
  a096=(a096+a042);
  a096=(a096+a040);
  a096=(a096+a045);
  a096=(a096+a171);
  a096=(a096+a006);
  a096=(a096+a012);
  a096=(a096+a002);
  a096=(a096+a009);
  a096=(-a096);
  if (res[1]!=0) res[1][80]=a096;
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

/* update:(z[9],g[9],p[3],h[4])->(g1[9],p1[3]) */
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

/* guess:(xi[3],g[9],p[3],h[4])->(z0[9]) */
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

/* legendre:(g[9],xi[3],h[4])->(mu[3]) */
static int casadi_f4(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1;
  a0=arg[1]? arg[1][0] : 0;
  if (res[0]!=0) res[0][0]=a0;
  a0=arg[1]? arg[1][1] : 0;
  a0=(2.*a0);
  if (res[0]!=0) res[0][1]=a0;
  a0=3.;
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

CASADI_SYMBOL_EXPORT casadi_int legendre_n_in(void) { return 3;}

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
    case 2: return "h";
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
    case 2: return casadi_s2;
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
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int legendre_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* hessian:(g[9],xi[3],h[4])->(H[9]) */
static int casadi_f5(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1;
  a0=1.;
  if (res[0]!=0) res[0][0]=a0;
  a0=0.;
  if (res[0]!=0) res[0][1]=a0;
  if (res[0]!=0) res[0][2]=a0;
  if (res[0]!=0) res[0][3]=a0;
  a1=2.;
  if (res[0]!=0) res[0][4]=a1;
  if (res[0]!=0) res[0][5]=a0;
  if (res[0]!=0) res[0][6]=a0;
  if (res[0]!=0) res[0][7]=a0;
  a0=3.;
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

CASADI_SYMBOL_EXPORT casadi_int hessian_n_in(void) { return 3;}

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
    case 2: return "h";
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
    case 2: return casadi_s2;
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
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int hessian_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* energy:(g[9],xi[3],h[4])->(E) */
static int casadi_f6(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4;
  a0=arg[1]? arg[1][0] : 0;
  a0=casadi_sq(a0);
  a1=arg[1]? arg[1][1] : 0;
  a2=(2.*a1);
  a2=(a2*a1);
  a2=(a0+a2);
  a3=3.;
  a4=arg[1]? arg[1][2] : 0;
  a3=(a3*a4);
  a3=(a3*a4);
  a2=(a2+a3);
  a3=5.0000000000000000e-01;
  a3=(a3*a0);
  a1=casadi_sq(a1);
  a3=(a3+a1);
  a1=1.5000000000000000e+00;
  a4=casadi_sq(a4);
  a1=(a1*a4);
  a3=(a3+a1);
  a2=(a2-a3);
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

CASADI_SYMBOL_EXPORT casadi_int energy_n_in(void) { return 3;}

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
    case 2: return "h";
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
    case 2: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* energy_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int energy_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int energy_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3*sizeof(const casadi_real*);
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
    case 0: return casadi_s4;
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

/* margin:(z[9],h[4])->(m) */
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
    case 0: return casadi_s4;
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
    case 0: return casadi_s4;
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

/* chart_point:(z[9],g[9],h[4],theta)->(g_theta[9]) */
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
    case 3: return casadi_s4;
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

/* observe:(g[9],p[3],h[4])->(xi[3],E,m[3],e) */
static int casadi_f12(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17;
  a00=arg[1]? arg[1][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=arg[1]? arg[1][1] : 0;
  a02=2.;
  a02=(a01/a02);
  if (res[0]!=0) res[0][1]=a02;
  a03=arg[1]? arg[1][2] : 0;
  a04=3.;
  a04=(a03/a04);
  if (res[0]!=0) res[0][2]=a04;
  a05=casadi_sq(a00);
  a06=(a01*a02);
  a06=(a05+a06);
  a07=(a03*a04);
  a06=(a06+a07);
  a07=5.0000000000000000e-01;
  a07=(a07*a05);
  a02=casadi_sq(a02);
  a07=(a07+a02);
  a02=1.5000000000000000e+00;
  a04=casadi_sq(a04);
  a02=(a02*a04);
  a07=(a07+a02);
  a06=(a06-a07);
  if (res[1]!=0) res[1][0]=a06;
  a06=arg[0]? arg[0][8] : 0;
  a07=arg[0]? arg[0][4] : 0;
  a02=(a06*a07);
  a04=arg[0]? arg[0][7] : 0;
  a05=arg[0]? arg[0][5] : 0;
  a08=(a04*a05);
  a02=(a02-a08);
  a02=(a02*a00);
  a09=arg[0]? arg[0][2] : 0;
  a10=(a09*a04);
  a11=arg[0]? arg[0][1] : 0;
  a12=(a11*a06);
  a10=(a10-a12);
  a10=(a10*a01);
  a02=(a02+a10);
  a10=(a05*a11);
  a13=(a07*a09);
  a10=(a10-a13);
  a10=(a10*a03);
  a02=(a02+a10);
  if (res[2]!=0) res[2][0]=a02;
  a02=arg[0]? arg[0][6] : 0;
  a10=(a02*a05);
  a14=arg[0]? arg[0][3] : 0;
  a15=(a06*a14);
  a10=(a10-a15);
  a10=(a10*a00);
  a15=arg[0]? arg[0][0] : 0;
  a16=(a15*a06);
  a17=(a09*a02);
  a16=(a16-a17);
  a16=(a16*a01);
  a10=(a10+a16);
  a16=(a14*a09);
  a17=(a05*a15);
  a16=(a16-a17);
  a16=(a16*a03);
  a10=(a10+a16);
  if (res[2]!=0) res[2][1]=a10;
  a10=(a04*a14);
  a16=(a02*a07);
  a10=(a10-a16);
  a10=(a10*a00);
  a00=(a11*a02);
  a16=(a15*a04);
  a00=(a00-a16);
  a00=(a00*a01);
  a10=(a10+a00);
  a00=(a07*a15);
  a01=(a14*a11);
  a00=(a00-a01);
  a00=(a00*a03);
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
  a03=(a14*a15);
  a01=(a07*a11);
  a03=(a03+a01);
  a01=(a05*a09);
  a03=(a03+a01);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=(a02*a15);
  a01=(a04*a11);
  a03=(a03+a01);
  a01=(a06*a09);
  a03=(a03+a01);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=(a15*a14);
  a01=(a11*a07);
  a03=(a03+a01);
  a01=(a09*a05);
  a03=(a03+a01);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=casadi_sq(a14);
  a01=casadi_sq(a07);
  a03=(a03+a01);
  a01=casadi_sq(a05);
  a03=(a03+a01);
  a03=(a03-a00);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=(a02*a14);
  a01=(a04*a07);
  a03=(a03+a01);
  a01=(a06*a05);
  a03=(a03+a01);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=(a15*a02);
  a01=(a11*a04);
  a03=(a03+a01);
  a01=(a09*a06);
  a03=(a03+a01);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=(a14*a02);
  a01=(a07*a04);
  a03=(a03+a01);
  a01=(a05*a06);
  a03=(a03+a01);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=casadi_sq(a02);
  a01=casadi_sq(a04);
  a03=(a03+a01);
  a01=casadi_sq(a06);
  a03=(a03+a01);
  a03=(a03-a00);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a07=(a07*a06);
  a07=(a07-a08);
  a15=(a15*a07);
  a04=(a04*a09);
  a12=(a12-a04);
  a14=(a14*a12);
  a15=(a15-a14);
  a11=(a11*a05);
  a11=(a11-a13);
  a02=(a02*a11);
  a15=(a15+a02);
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

CASADI_SYMBOL_EXPORT casadi_int observe_n_in(void) { return 3;}

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
    case 2: return "h";
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
    case 2: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* observe_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    case 1: return casadi_s4;
    case 2: return casadi_s1;
    case 3: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int observe_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 4;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int observe_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 4*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* update_p:(z[9],g[9],p[3],h[4])->(p1[3]) */
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

/* velocity_step:(g[9],p[3],xi[3],h[4])->(xi1[3]) */
static int casadi_f14(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3;
  a0=arg[2]? arg[2][0] : 0;
  a1=arg[1]? arg[1][0] : 0;
  a1=(a0-a1);
  a0=(a0-a1);
  if (res[0]!=0) res[0][0]=a0;
  a0=arg[2]? arg[2][1] : 0;
  a1=(2.*a0);
  a2=arg[1]? arg[1][1] : 0;
  a1=(a1-a2);
  a2=2.;
  a1=(a1/a2);
  a0=(a0-a1);
  if (res[0]!=0) res[0][1]=a0;
  a0=arg[2]? arg[2][2] : 0;
  a1=3.;
  a2=(a1*a0);
  a3=arg[1]? arg[1][2] : 0;
  a2=(a2-a3);
  a2=(a2/a1);
  a0=(a0-a2);
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

CASADI_SYMBOL_EXPORT casadi_int velocity_step_n_in(void) { return 4;}

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
    case 3: return "h";
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
    case 3: return casadi_s2;
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
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int velocity_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* record:(g[9],p[3],xi[3],h[4])->(row[18]) */
static int casadi_f15(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22;
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
  a12=arg[2]? arg[2][0] : 0;
  a13=casadi_sq(a12);
  a14=arg[2]? arg[2][1] : 0;
  a15=(2.*a14);
  a15=(a15*a14);
  a15=(a13+a15);
  a16=3.;
  a17=arg[2]? arg[2][2] : 0;
  a16=(a16*a17);
  a16=(a16*a17);
  a15=(a15+a16);
  a16=5.0000000000000000e-01;
  a13=(a16*a13);
  a18=casadi_sq(a14);
  a13=(a13+a18);
  a18=1.5000000000000000e+00;
  a19=casadi_sq(a17);
  a18=(a18*a19);
  a13=(a13+a18);
  a15=(a15-a13);
  if (res[0]!=0) res[0][12]=a15;
  a15=-5.0000000000000000e-01;
  a13=arg[3]? arg[3][2] : 0;
  a13=(a15*a13);
  a18=8.4147098480789650e-01;
  a19=(a18*a06);
  a19=(a05+a19);
  a20=-5.4030230586813977e-01;
  a21=(a20*a07);
  a19=(a19+a21);
  a19=(a13*a19);
  a21=arg[3]? arg[3][3] : 0;
  a22=(a21*a12);
  a19=(a19-a22);
  a19=(a19*a12);
  a12=5.4030230586813977e-01;
  a22=(a12*a06);
  a22=(a22-a02);
  a18=(a18*a07);
  a22=(a22+a18);
  a22=(a13*a22);
  a18=(a21*a14);
  a22=(a22-a18);
  a22=(a22*a14);
  a19=(a19+a22);
  a12=(a12*a01);
  a20=(a20*a03);
  a12=(a12+a20);
  a20=-8.4147098480789650e-01;
  a22=(a20*a00);
  a12=(a12+a22);
  a20=(a20*a04);
  a12=(a12+a20);
  a13=(a13*a12);
  a21=(a21*a17);
  a13=(a13-a21);
  a13=(a13*a17);
  a19=(a19+a13);
  if (res[0]!=0) res[0][13]=a19;
  a19=(a08*a04);
  a13=(a07*a05);
  a19=(a19-a13);
  a19=(a19*a09);
  a13=(a02*a07);
  a17=(a01*a08);
  a13=(a13-a17);
  a13=(a13*a10);
  a19=(a19+a13);
  a13=(a05*a01);
  a17=(a04*a02);
  a13=(a13-a17);
  a13=(a13*a11);
  a19=(a19+a13);
  if (res[0]!=0) res[0][14]=a19;
  a19=(a06*a05);
  a13=(a08*a03);
  a19=(a19-a13);
  a19=(a19*a09);
  a13=(a00*a08);
  a17=(a02*a06);
  a13=(a13-a17);
  a13=(a13*a10);
  a19=(a19+a13);
  a02=(a03*a02);
  a05=(a05*a00);
  a02=(a02-a05);
  a02=(a02*a11);
  a19=(a19+a02);
  if (res[0]!=0) res[0][15]=a19;
  a19=(a07*a03);
  a02=(a06*a04);
  a19=(a19-a02);
  a19=(a19*a09);
  a06=(a01*a06);
  a07=(a00*a07);
  a06=(a06-a07);
  a06=(a06*a10);
  a19=(a19+a06);
  a06=(a04*a00);
  a10=(a03*a01);
  a06=(a06-a10);
  a06=(a06*a11);
  a19=(a19+a06);
  if (res[0]!=0) res[0][16]=a19;
  a16=(a16*a08);
  a15=(a15+a16);
  a16=2.7015115293406988e-01;
  a00=(a16*a00);
  a15=(a15+a00);
  a16=(a16*a04);
  a15=(a15+a16);
  a16=4.2073549240394825e-01;
  a16=(a16*a01);
  a15=(a15+a16);
  a16=-4.2073549240394825e-01;
  a16=(a16*a03);
  a15=(a15+a16);
  if (res[0]!=0) res[0][17]=a15;
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

CASADI_SYMBOL_EXPORT casadi_int record_n_in(void) { return 4;}

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
    case 3: return "h";
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
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* record_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s5;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int record_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int record_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* step_partials:(z[9],g[9],p[3],h[4])->(Fs[54],Yz[54],Ys[36],FH[36],YH[24]) */
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
  casadi_real a168, a169, a170, a171, a172, a173, a174, a175, a176, a177, a178, a179;
  casadi_real a180;
  a000=5.0000000000000000e-01;
  a001=arg[3]? arg[3][0] : 0;
  a002=(a000*a001);
  a003=-5.0000000000000000e-01;
  a004=arg[3]? arg[3][2] : 0;
  a004=(a003*a004);
  a005=1.;
  a006=4.;
  a007=arg[0]? arg[0][0] : 0;
  a008=(a001*a007);
  a009=casadi_sq(a008);
  a010=arg[0]? arg[0][1] : 0;
  a011=(a001*a010);
  a012=casadi_sq(a011);
  a013=(a009+a012);
  a014=arg[0]? arg[0][2] : 0;
  a015=(a001*a014);
  a016=casadi_sq(a015);
  a013=(a013+a016);
  a013=(a006+a013);
  a017=(a006/a013);
  a018=(a016+a009);
  a019=2.;
  a018=(a018/a019);
  a020=(a017*a018);
  a020=(a005-a020);
  a021=arg[1]? arg[1][8] : 0;
  a022=(a020*a021);
  a023=(a011*a015);
  a023=(a023/a019);
  a023=(a008+a023);
  a024=(a017*a023);
  a025=arg[1]? arg[1][5] : 0;
  a026=(a024*a025);
  a022=(a022-a026);
  a026=8.4147098480789650e-01;
  a027=(a015*a011);
  a027=(a027/a019);
  a027=(a027-a008);
  a028=(a017*a027);
  a029=arg[1]? arg[1][6] : 0;
  a030=(a028*a029);
  a009=(a012+a009);
  a009=(a009/a019);
  a031=(a017*a009);
  a031=(a005-a031);
  a032=arg[1]? arg[1][3] : 0;
  a033=(a031*a032);
  a030=(a030-a033);
  a033=(a026*a030);
  a022=(a022+a033);
  a033=-5.4030230586813977e-01;
  a034=arg[1]? arg[1][7] : 0;
  a035=(a028*a034);
  a036=arg[1]? arg[1][4] : 0;
  a037=(a031*a036);
  a035=(a035-a037);
  a037=(a033*a035);
  a022=(a022+a037);
  a022=(a004*a022);
  a022=(a002*a022);
  a022=(a022/a001);
  if (res[0]!=0) res[0][0]=a022;
  a022=5.4030230586813977e-01;
  a030=(a022*a030);
  a037=(a008*a011);
  a037=(a037/a019);
  a037=(a015+a037);
  a038=(a017*a037);
  a039=(a038*a021);
  a040=(a008*a015);
  a040=(a040/a019);
  a040=(a040-a011);
  a041=(a017*a040);
  a042=(a041*a025);
  a039=(a039-a042);
  a030=(a030-a039);
  a035=(a026*a035);
  a030=(a030+a035);
  a030=(a004*a030);
  a030=(a002*a030);
  a030=(a030/a001);
  if (res[0]!=0) res[0][1]=a030;
  a030=(a038*a034);
  a035=(a041*a036);
  a030=(a030-a035);
  a030=(a022*a030);
  a035=(a020*a029);
  a039=(a024*a032);
  a035=(a035-a039);
  a035=(a033*a035);
  a030=(a030+a035);
  a035=-8.4147098480789650e-01;
  a039=(a038*a029);
  a042=(a041*a032);
  a039=(a039-a042);
  a039=(a035*a039);
  a030=(a030+a039);
  a039=(a020*a034);
  a042=(a024*a036);
  a039=(a039-a042);
  a039=(a035*a039);
  a030=(a030+a039);
  a030=(a004*a030);
  a030=(a002*a030);
  a030=(a030/a001);
  if (res[0]!=0) res[0][2]=a030;
  a030=arg[0]? arg[0][3] : 0;
  a039=(a001*a030);
  a042=casadi_sq(a039);
  a043=arg[0]? arg[0][4] : 0;
  a044=(a001*a043);
  a045=casadi_sq(a044);
  a046=(a042+a045);
  a047=arg[0]? arg[0][5] : 0;
  a048=(a001*a047);
  a049=casadi_sq(a048);
  a046=(a046+a049);
  a046=(a006+a046);
  a050=(a006/a046);
  a051=(a049+a042);
  a051=(a051/a019);
  a052=(a050*a051);
  a052=(a005-a052);
  a053=(a052*a021);
  a054=(a044*a048);
  a054=(a054/a019);
  a054=(a039+a054);
  a055=(a050*a054);
  a056=(a055*a025);
  a053=(a053-a056);
  a056=(a048*a044);
  a056=(a056/a019);
  a056=(a056-a039);
  a057=(a050*a056);
  a058=(a057*a029);
  a042=(a045+a042);
  a042=(a042/a019);
  a059=(a050*a042);
  a059=(a005-a059);
  a060=(a059*a032);
  a058=(a058-a060);
  a060=(a026*a058);
  a053=(a053+a060);
  a060=(a057*a034);
  a061=(a059*a036);
  a060=(a060-a061);
  a061=(a033*a060);
  a053=(a053+a061);
  a053=(a004*a053);
  a053=(a002*a053);
  a053=(a053/a001);
  if (res[0]!=0) res[0][3]=a053;
  a058=(a022*a058);
  a053=(a039*a044);
  a053=(a053/a019);
  a053=(a048+a053);
  a061=(a050*a053);
  a062=(a061*a021);
  a063=(a039*a048);
  a063=(a063/a019);
  a063=(a063-a044);
  a064=(a050*a063);
  a065=(a064*a025);
  a062=(a062-a065);
  a058=(a058-a062);
  a060=(a026*a060);
  a058=(a058+a060);
  a058=(a004*a058);
  a058=(a002*a058);
  a058=(a058/a001);
  if (res[0]!=0) res[0][4]=a058;
  a058=(a061*a034);
  a060=(a064*a036);
  a058=(a058-a060);
  a058=(a022*a058);
  a060=(a052*a029);
  a062=(a055*a032);
  a060=(a060-a062);
  a060=(a033*a060);
  a058=(a058+a060);
  a060=(a061*a029);
  a062=(a064*a032);
  a060=(a060-a062);
  a060=(a035*a060);
  a058=(a058+a060);
  a060=(a052*a034);
  a062=(a055*a036);
  a060=(a060-a062);
  a060=(a035*a060);
  a058=(a058+a060);
  a058=(a004*a058);
  a058=(a002*a058);
  a058=(a058/a001);
  if (res[0]!=0) res[0][5]=a058;
  a058=0.;
  if (res[0]!=0) res[0][6]=a058;
  if (res[0]!=0) res[0][7]=a058;
  if (res[0]!=0) res[0][8]=a058;
  a060=arg[1]? arg[1][2] : 0;
  a062=(a024*a060);
  a065=(a011*a008);
  a065=(a065/a019);
  a065=(a065-a015);
  a066=(a017*a065);
  a067=(a066*a021);
  a062=(a062-a067);
  a067=arg[1]? arg[1][0] : 0;
  a068=(a031*a067);
  a069=(a015*a008);
  a069=(a069/a019);
  a069=(a011+a069);
  a070=(a017*a069);
  a071=(a070*a029);
  a068=(a068-a071);
  a071=(a026*a068);
  a062=(a062+a071);
  a071=arg[1]? arg[1][1] : 0;
  a072=(a031*a071);
  a073=(a070*a034);
  a072=(a072-a073);
  a073=(a033*a072);
  a062=(a062+a073);
  a062=(a004*a062);
  a062=(a002*a062);
  a062=(a062/a001);
  if (res[0]!=0) res[0][9]=a062;
  a068=(a022*a068);
  a062=(a041*a060);
  a016=(a016+a012);
  a016=(a016/a019);
  a012=(a017*a016);
  a012=(a005-a012);
  a073=(a012*a021);
  a062=(a062-a073);
  a068=(a068-a062);
  a072=(a026*a072);
  a068=(a068+a072);
  a068=(a004*a068);
  a068=(a002*a068);
  a068=(a068/a001);
  if (res[0]!=0) res[0][10]=a068;
  a068=(a041*a071);
  a072=(a012*a034);
  a068=(a068-a072);
  a068=(a022*a068);
  a072=(a024*a067);
  a062=(a066*a029);
  a072=(a072-a062);
  a072=(a033*a072);
  a068=(a068+a072);
  a072=(a041*a067);
  a062=(a012*a029);
  a072=(a072-a062);
  a072=(a035*a072);
  a068=(a068+a072);
  a072=(a024*a071);
  a062=(a066*a034);
  a072=(a072-a062);
  a072=(a035*a072);
  a068=(a068+a072);
  a068=(a004*a068);
  a068=(a002*a068);
  a068=(a068/a001);
  if (res[0]!=0) res[0][11]=a068;
  a068=(a055*a060);
  a072=(a044*a039);
  a072=(a072/a019);
  a072=(a072-a048);
  a062=(a050*a072);
  a073=(a062*a021);
  a068=(a068-a073);
  a073=(a059*a067);
  a074=(a048*a039);
  a074=(a074/a019);
  a074=(a044+a074);
  a075=(a050*a074);
  a076=(a075*a029);
  a073=(a073-a076);
  a076=(a026*a073);
  a068=(a068+a076);
  a076=(a059*a071);
  a077=(a075*a034);
  a076=(a076-a077);
  a077=(a033*a076);
  a068=(a068+a077);
  a068=(a004*a068);
  a068=(a002*a068);
  a068=(a068/a001);
  if (res[0]!=0) res[0][12]=a068;
  a073=(a022*a073);
  a068=(a064*a060);
  a049=(a049+a045);
  a049=(a049/a019);
  a045=(a050*a049);
  a045=(a005-a045);
  a077=(a045*a021);
  a068=(a068-a077);
  a073=(a073-a068);
  a076=(a026*a076);
  a073=(a073+a076);
  a073=(a004*a073);
  a073=(a002*a073);
  a073=(a073/a001);
  if (res[0]!=0) res[0][13]=a073;
  a073=(a064*a071);
  a076=(a045*a034);
  a073=(a073-a076);
  a073=(a022*a073);
  a076=(a055*a067);
  a068=(a062*a029);
  a076=(a076-a068);
  a076=(a033*a076);
  a073=(a073+a076);
  a076=(a064*a067);
  a068=(a045*a029);
  a076=(a076-a068);
  a076=(a035*a076);
  a073=(a073+a076);
  a076=(a055*a071);
  a068=(a062*a034);
  a076=(a076-a068);
  a076=(a035*a076);
  a073=(a073+a076);
  a073=(a004*a073);
  a073=(a002*a073);
  a073=(a073/a001);
  if (res[0]!=0) res[0][14]=a073;
  if (res[0]!=0) res[0][15]=a058;
  if (res[0]!=0) res[0][16]=a058;
  if (res[0]!=0) res[0][17]=a058;
  a073=(a066*a025);
  a076=(a020*a060);
  a073=(a073-a076);
  a076=(a070*a032);
  a068=(a028*a067);
  a076=(a076-a068);
  a068=(a026*a076);
  a073=(a073+a068);
  a068=(a070*a036);
  a077=(a028*a071);
  a068=(a068-a077);
  a077=(a033*a068);
  a073=(a073+a077);
  a073=(a004*a073);
  a073=(a002*a073);
  a073=(a073/a001);
  if (res[0]!=0) res[0][18]=a073;
  a076=(a022*a076);
  a073=(a012*a025);
  a077=(a038*a060);
  a073=(a073-a077);
  a076=(a076-a073);
  a068=(a026*a068);
  a076=(a076+a068);
  a076=(a004*a076);
  a076=(a002*a076);
  a076=(a076/a001);
  if (res[0]!=0) res[0][19]=a076;
  a076=(a012*a036);
  a068=(a038*a071);
  a076=(a076-a068);
  a076=(a022*a076);
  a068=(a066*a032);
  a073=(a020*a067);
  a068=(a068-a073);
  a068=(a033*a068);
  a076=(a076+a068);
  a068=(a012*a032);
  a073=(a038*a067);
  a068=(a068-a073);
  a068=(a035*a068);
  a076=(a076+a068);
  a068=(a066*a036);
  a073=(a020*a071);
  a068=(a068-a073);
  a068=(a035*a068);
  a076=(a076+a068);
  a076=(a004*a076);
  a076=(a002*a076);
  a076=(a076/a001);
  if (res[0]!=0) res[0][20]=a076;
  a076=(a062*a025);
  a068=(a052*a060);
  a076=(a076-a068);
  a068=(a075*a032);
  a073=(a057*a067);
  a068=(a068-a073);
  a073=(a026*a068);
  a076=(a076+a073);
  a073=(a075*a036);
  a077=(a057*a071);
  a073=(a073-a077);
  a077=(a033*a073);
  a076=(a076+a077);
  a076=(a004*a076);
  a076=(a002*a076);
  a076=(a076/a001);
  if (res[0]!=0) res[0][21]=a076;
  a068=(a022*a068);
  a076=(a045*a025);
  a077=(a061*a060);
  a076=(a076-a077);
  a068=(a068-a076);
  a073=(a026*a073);
  a068=(a068+a073);
  a068=(a004*a068);
  a068=(a002*a068);
  a068=(a068/a001);
  if (res[0]!=0) res[0][22]=a068;
  a068=(a045*a036);
  a073=(a061*a071);
  a068=(a068-a073);
  a068=(a022*a068);
  a073=(a062*a032);
  a076=(a052*a067);
  a073=(a073-a076);
  a073=(a033*a073);
  a068=(a068+a073);
  a073=(a045*a032);
  a076=(a061*a067);
  a073=(a073-a076);
  a073=(a035*a073);
  a068=(a068+a073);
  a073=(a062*a036);
  a076=(a052*a071);
  a073=(a073-a076);
  a073=(a035*a073);
  a068=(a068+a073);
  a068=(a004*a068);
  a068=(a002*a068);
  a068=(a068/a001);
  if (res[0]!=0) res[0][23]=a068;
  if (res[0]!=0) res[0][24]=a058;
  if (res[0]!=0) res[0][25]=a058;
  if (res[0]!=0) res[0][26]=a058;
  if (res[0]!=0) res[0][27]=a058;
  if (res[0]!=0) res[0][28]=a058;
  if (res[0]!=0) res[0][29]=a058;
  if (res[0]!=0) res[0][30]=a058;
  if (res[0]!=0) res[0][31]=a058;
  if (res[0]!=0) res[0][32]=a058;
  if (res[0]!=0) res[0][33]=a005;
  if (res[0]!=0) res[0][34]=a058;
  if (res[0]!=0) res[0][35]=a058;
  if (res[0]!=0) res[0][36]=a058;
  if (res[0]!=0) res[0][37]=a058;
  if (res[0]!=0) res[0][38]=a058;
  if (res[0]!=0) res[0][39]=a058;
  if (res[0]!=0) res[0][40]=a058;
  if (res[0]!=0) res[0][41]=a058;
  if (res[0]!=0) res[0][42]=a058;
  if (res[0]!=0) res[0][43]=a005;
  if (res[0]!=0) res[0][44]=a058;
  if (res[0]!=0) res[0][45]=a058;
  if (res[0]!=0) res[0][46]=a058;
  if (res[0]!=0) res[0][47]=a058;
  if (res[0]!=0) res[0][48]=a058;
  if (res[0]!=0) res[0][49]=a058;
  if (res[0]!=0) res[0][50]=a058;
  if (res[0]!=0) res[0][51]=a058;
  if (res[0]!=0) res[0][52]=a058;
  if (res[0]!=0) res[0][53]=a005;
  a068=3.0000000000000004e+00;
  a073=(a068*a007);
  a076=4.6410161513775439e-01;
  a077=(a076*a030);
  a073=(a073+a077);
  a077=(a000*a073);
  a078=-6.4641016151377553e+00;
  a079=(a078*a007);
  a080=(a068*a030);
  a079=(a079+a080);
  a080=(a000*a079);
  a077=(a077+a080);
  a080=(a001*a077);
  a081=casadi_sq(a080);
  a082=(a068*a010);
  a083=(a076*a043);
  a082=(a082+a083);
  a083=(a000*a082);
  a084=(a078*a010);
  a085=(a068*a043);
  a084=(a084+a085);
  a085=(a000*a084);
  a083=(a083+a085);
  a085=(a001*a083);
  a086=casadi_sq(a085);
  a087=(a081+a086);
  a088=(a068*a014);
  a076=(a076*a047);
  a088=(a088+a076);
  a076=(a000*a088);
  a078=(a078*a014);
  a068=(a068*a047);
  a078=(a078+a068);
  a068=(a000*a078);
  a076=(a076+a068);
  a068=(a001*a076);
  a089=casadi_sq(a068);
  a087=(a087+a089);
  a087=(a006+a087);
  a090=(a006/a087);
  a091=(a068*a080);
  a091=(a091/a019);
  a091=(a085+a091);
  a092=(a090*a091);
  a093=(a067*a092);
  a094=(a068*a085);
  a094=(a094/a019);
  a094=(a094-a080);
  a095=(a090*a094);
  a096=(a032*a095);
  a093=(a093+a096);
  a096=(a086+a081);
  a096=(a096/a019);
  a097=(a090*a096);
  a097=(a005-a097);
  a098=(a029*a097);
  a093=(a093+a098);
  a098=-1.7320508075688774e+00;
  a098=(a098*a001);
  a099=(a085*a098);
  a099=(a000*a099);
  a099=(a090*a099);
  a100=(a085*a080);
  a100=(a100/a019);
  a100=(a100-a068);
  a087=(a090/a087);
  a101=(2.*a080);
  a102=(a101*a098);
  a103=(a087*a102);
  a104=(a100*a103);
  a104=(a099-a104);
  a105=(a067*a104);
  a102=(a000*a102);
  a102=(a090*a102);
  a081=(a089+a081);
  a081=(a081/a019);
  a106=(a081*a103);
  a106=(a102-a106);
  a107=(a032*a106);
  a105=(a105-a107);
  a107=(a090*a098);
  a108=(a085*a068);
  a108=(a108/a019);
  a108=(a080+a108);
  a109=(a108*a103);
  a109=(a107-a109);
  a110=(a029*a109);
  a105=(a105+a110);
  a105=(a093*a105);
  a110=(a071*a092);
  a111=(a036*a095);
  a110=(a110+a111);
  a111=(a034*a097);
  a110=(a110+a111);
  a111=(a071*a104);
  a112=(a036*a106);
  a111=(a111-a112);
  a112=(a034*a109);
  a111=(a111+a112);
  a111=(a110*a111);
  a105=(a105+a111);
  a111=(a060*a092);
  a112=(a025*a095);
  a111=(a111+a112);
  a112=(a021*a097);
  a111=(a111+a112);
  a104=(a060*a104);
  a106=(a025*a106);
  a104=(a104-a106);
  a109=(a021*a109);
  a104=(a104+a109);
  a104=(a111*a104);
  a105=(a105+a104);
  if (res[1]!=0) res[1][0]=a105;
  a089=(a089+a086);
  a089=(a089/a019);
  a086=(a090*a089);
  a086=(a005-a086);
  a105=(a067*a086);
  a104=(a080*a085);
  a104=(a104/a019);
  a104=(a068+a104);
  a109=(a090*a104);
  a106=(a032*a109);
  a105=(a105+a106);
  a106=(a080*a068);
  a106=(a106/a019);
  a106=(a106-a085);
  a112=(a090*a106);
  a113=(a029*a112);
  a105=(a105+a113);
  a113=(a068*a098);
  a113=(a000*a113);
  a113=(a090*a113);
  a114=(a091*a103);
  a114=(a113-a114);
  a115=(a067*a114);
  a116=(a094*a103);
  a116=(a116+a107);
  a117=(a032*a116);
  a115=(a115-a117);
  a117=(a096*a103);
  a102=(a102-a117);
  a117=(a029*a102);
  a115=(a115-a117);
  a115=(a105*a115);
  a117=(a071*a086);
  a118=(a036*a109);
  a117=(a117+a118);
  a118=(a034*a112);
  a117=(a117+a118);
  a118=(a071*a114);
  a119=(a036*a116);
  a118=(a118-a119);
  a119=(a034*a102);
  a118=(a118-a119);
  a118=(a117*a118);
  a115=(a115+a118);
  a118=(a060*a086);
  a119=(a025*a109);
  a118=(a118+a119);
  a119=(a021*a112);
  a118=(a118+a119);
  a114=(a060*a114);
  a116=(a025*a116);
  a114=(a114-a116);
  a102=(a021*a102);
  a114=(a114-a102);
  a114=(a118*a114);
  a115=(a115+a114);
  if (res[1]!=0) res[1][1]=a115;
  a115=(a090*a100);
  a114=(a067*a115);
  a102=(a090*a081);
  a102=(a005-a102);
  a116=(a032*a102);
  a114=(a114+a116);
  a116=(a090*a108);
  a119=(a029*a116);
  a114=(a114+a119);
  a119=(a089*a103);
  a120=(a067*a119);
  a121=(a104*a103);
  a121=(a099-a121);
  a122=(a032*a121);
  a120=(a120+a122);
  a103=(a106*a103);
  a103=(a113-a103);
  a122=(a029*a103);
  a120=(a120+a122);
  a120=(a114*a120);
  a122=(a071*a115);
  a123=(a036*a102);
  a122=(a122+a123);
  a123=(a034*a116);
  a122=(a122+a123);
  a123=(a071*a119);
  a124=(a036*a121);
  a123=(a123+a124);
  a124=(a034*a103);
  a123=(a123+a124);
  a123=(a122*a123);
  a120=(a120+a123);
  a123=(a060*a115);
  a124=(a025*a102);
  a123=(a123+a124);
  a124=(a021*a116);
  a123=(a123+a124);
  a119=(a060*a119);
  a121=(a025*a121);
  a119=(a119+a121);
  a103=(a021*a103);
  a119=(a119+a103);
  a119=(a123*a119);
  a120=(a120+a119);
  if (res[1]!=0) res[1][2]=a120;
  a120=2.5000000000000000e-01;
  a119=arg[0]? arg[0][8] : 0;
  a103=(a068*a119);
  a121=arg[0]? arg[0][7] : 0;
  a124=(a085*a121);
  a103=(a103+a124);
  a124=arg[0]? arg[0][6] : 0;
  a125=(a080*a124);
  a103=(a103+a125);
  a103=(a120*a103);
  a125=(a103*a098);
  a126=(a124*a098);
  a126=(a120*a126);
  a127=(a080*a126);
  a127=(a125+a127);
  if (res[1]!=0) res[1][3]=a127;
  a127=(a000*a119);
  a128=(a127*a098);
  a129=(a085*a126);
  a129=(a128+a129);
  if (res[1]!=0) res[1][4]=a129;
  a126=(a068*a126);
  a129=(a000*a121);
  a130=(a129*a098);
  a126=(a126-a130);
  if (res[1]!=0) res[1][5]=a126;
  a126=(a080*a098);
  a126=(a000*a126);
  a126=(a090*a126);
  a131=(2.*a085);
  a132=(a131*a098);
  a133=(a087*a132);
  a134=(a100*a133);
  a134=(a126-a134);
  a135=(a067*a134);
  a136=(a081*a133);
  a137=(a032*a136);
  a135=(a135+a137);
  a137=(a108*a133);
  a137=(a113-a137);
  a138=(a029*a137);
  a135=(a135+a138);
  a135=(a093*a135);
  a138=(a071*a134);
  a139=(a036*a136);
  a138=(a138+a139);
  a139=(a034*a137);
  a138=(a138+a139);
  a138=(a110*a138);
  a135=(a135+a138);
  a134=(a060*a134);
  a136=(a025*a136);
  a134=(a134+a136);
  a137=(a021*a137);
  a134=(a134+a137);
  a134=(a111*a134);
  a135=(a135+a134);
  if (res[1]!=0) res[1][6]=a135;
  a135=(a091*a133);
  a135=(a107-a135);
  a134=(a067*a135);
  a137=(a094*a133);
  a113=(a113-a137);
  a137=(a032*a113);
  a134=(a134+a137);
  a132=(a000*a132);
  a132=(a090*a132);
  a137=(a096*a133);
  a137=(a132-a137);
  a136=(a029*a137);
  a134=(a134-a136);
  a134=(a105*a134);
  a136=(a071*a135);
  a138=(a036*a113);
  a136=(a136+a138);
  a138=(a034*a137);
  a136=(a136-a138);
  a136=(a117*a136);
  a134=(a134+a136);
  a135=(a060*a135);
  a113=(a025*a113);
  a135=(a135+a113);
  a137=(a021*a137);
  a135=(a135-a137);
  a135=(a118*a135);
  a134=(a134+a135);
  if (res[1]!=0) res[1][7]=a134;
  a134=(a104*a133);
  a134=(a126-a134);
  a135=(a032*a134);
  a137=(a089*a133);
  a132=(a132-a137);
  a137=(a067*a132);
  a135=(a135-a137);
  a133=(a106*a133);
  a133=(a133+a107);
  a137=(a029*a133);
  a135=(a135-a137);
  a135=(a114*a135);
  a137=(a036*a134);
  a113=(a071*a132);
  a137=(a137-a113);
  a113=(a034*a133);
  a137=(a137-a113);
  a137=(a122*a137);
  a135=(a135+a137);
  a134=(a025*a134);
  a132=(a060*a132);
  a134=(a134-a132);
  a133=(a021*a133);
  a134=(a134-a133);
  a134=(a123*a134);
  a135=(a135+a134);
  if (res[1]!=0) res[1][8]=a135;
  a135=(a121*a098);
  a135=(a120*a135);
  a134=(a080*a135);
  a134=(a134-a128);
  if (res[1]!=0) res[1][9]=a134;
  a134=(a085*a135);
  a134=(a125+a134);
  if (res[1]!=0) res[1][10]=a134;
  a135=(a068*a135);
  a134=(a000*a124);
  a128=(a134*a098);
  a135=(a135+a128);
  if (res[1]!=0) res[1][11]=a135;
  a135=(2.*a068);
  a133=(a135*a098);
  a132=(a087*a133);
  a137=(a108*a132);
  a137=(a099-a137);
  a113=(a029*a137);
  a136=(a100*a132);
  a136=(a136+a107);
  a138=(a067*a136);
  a133=(a000*a133);
  a133=(a090*a133);
  a139=(a081*a132);
  a139=(a133-a139);
  a140=(a032*a139);
  a138=(a138+a140);
  a113=(a113-a138);
  a113=(a093*a113);
  a138=(a034*a137);
  a140=(a071*a136);
  a141=(a036*a139);
  a140=(a140+a141);
  a138=(a138-a140);
  a138=(a110*a138);
  a113=(a113+a138);
  a137=(a021*a137);
  a136=(a060*a136);
  a139=(a025*a139);
  a136=(a136+a139);
  a137=(a137-a136);
  a137=(a111*a137);
  a113=(a113+a137);
  if (res[1]!=0) res[1][12]=a113;
  a113=(a091*a132);
  a113=(a126-a113);
  a137=(a067*a113);
  a136=(a094*a132);
  a099=(a099-a136);
  a136=(a032*a099);
  a137=(a137+a136);
  a136=(a096*a132);
  a139=(a029*a136);
  a137=(a137+a139);
  a137=(a105*a137);
  a139=(a071*a113);
  a138=(a036*a099);
  a139=(a139+a138);
  a138=(a034*a136);
  a139=(a139+a138);
  a139=(a117*a139);
  a137=(a137+a139);
  a113=(a060*a113);
  a099=(a025*a099);
  a113=(a113+a099);
  a136=(a021*a136);
  a113=(a113+a136);
  a113=(a118*a113);
  a137=(a137+a113);
  if (res[1]!=0) res[1][13]=a137;
  a137=(a104*a132);
  a107=(a107-a137);
  a137=(a032*a107);
  a113=(a089*a132);
  a133=(a133-a113);
  a113=(a067*a133);
  a137=(a137-a113);
  a132=(a106*a132);
  a126=(a126-a132);
  a132=(a029*a126);
  a137=(a137+a132);
  a137=(a114*a137);
  a132=(a036*a107);
  a113=(a071*a133);
  a132=(a132-a113);
  a113=(a034*a126);
  a132=(a132+a113);
  a132=(a122*a132);
  a137=(a137+a132);
  a107=(a025*a107);
  a133=(a060*a133);
  a107=(a107-a133);
  a126=(a021*a126);
  a107=(a107+a126);
  a107=(a123*a107);
  a137=(a137+a107);
  if (res[1]!=0) res[1][14]=a137;
  a098=(a119*a098);
  a098=(a120*a098);
  a137=(a080*a098);
  a130=(a130+a137);
  if (res[1]!=0) res[1][15]=a130;
  a130=(a085*a098);
  a130=(a130-a128);
  if (res[1]!=0) res[1][16]=a130;
  a098=(a068*a098);
  a125=(a125+a098);
  if (res[1]!=0) res[1][17]=a125;
  a125=1.7320508075688774e+00;
  a125=(a125*a001);
  a098=(a085*a125);
  a098=(a000*a098);
  a098=(a090*a098);
  a130=(a101*a125);
  a128=(a087*a130);
  a137=(a100*a128);
  a137=(a098-a137);
  a107=(a067*a137);
  a130=(a000*a130);
  a130=(a090*a130);
  a126=(a081*a128);
  a126=(a130-a126);
  a133=(a032*a126);
  a107=(a107-a133);
  a133=(a090*a125);
  a132=(a108*a128);
  a132=(a133-a132);
  a113=(a029*a132);
  a107=(a107+a113);
  a107=(a093*a107);
  a113=(a071*a137);
  a136=(a036*a126);
  a113=(a113-a136);
  a136=(a034*a132);
  a113=(a113+a136);
  a113=(a110*a113);
  a107=(a107+a113);
  a137=(a060*a137);
  a126=(a025*a126);
  a137=(a137-a126);
  a132=(a021*a132);
  a137=(a137+a132);
  a137=(a111*a137);
  a107=(a107+a137);
  if (res[1]!=0) res[1][18]=a107;
  a107=(a068*a125);
  a107=(a000*a107);
  a107=(a090*a107);
  a137=(a091*a128);
  a137=(a107-a137);
  a132=(a067*a137);
  a126=(a094*a128);
  a126=(a126+a133);
  a113=(a032*a126);
  a132=(a132-a113);
  a113=(a096*a128);
  a130=(a130-a113);
  a113=(a029*a130);
  a132=(a132-a113);
  a132=(a105*a132);
  a113=(a071*a137);
  a136=(a036*a126);
  a113=(a113-a136);
  a136=(a034*a130);
  a113=(a113-a136);
  a113=(a117*a113);
  a132=(a132+a113);
  a137=(a060*a137);
  a126=(a025*a126);
  a137=(a137-a126);
  a130=(a021*a130);
  a137=(a137-a130);
  a137=(a118*a137);
  a132=(a132+a137);
  if (res[1]!=0) res[1][19]=a132;
  a132=(a089*a128);
  a137=(a067*a132);
  a130=(a104*a128);
  a130=(a098-a130);
  a126=(a032*a130);
  a137=(a137+a126);
  a128=(a106*a128);
  a128=(a107-a128);
  a126=(a029*a128);
  a137=(a137+a126);
  a137=(a114*a137);
  a126=(a071*a132);
  a113=(a036*a130);
  a126=(a126+a113);
  a113=(a034*a128);
  a126=(a126+a113);
  a126=(a122*a126);
  a137=(a137+a126);
  a132=(a060*a132);
  a130=(a025*a130);
  a132=(a132+a130);
  a128=(a021*a128);
  a132=(a132+a128);
  a132=(a123*a132);
  a137=(a137+a132);
  if (res[1]!=0) res[1][20]=a137;
  a137=(a103*a125);
  a132=(a124*a125);
  a132=(a120*a132);
  a128=(a080*a132);
  a128=(a137+a128);
  if (res[1]!=0) res[1][21]=a128;
  a128=(a127*a125);
  a130=(a085*a132);
  a130=(a128+a130);
  if (res[1]!=0) res[1][22]=a130;
  a132=(a068*a132);
  a130=(a129*a125);
  a132=(a132-a130);
  if (res[1]!=0) res[1][23]=a132;
  a132=(a080*a125);
  a132=(a000*a132);
  a132=(a090*a132);
  a126=(a131*a125);
  a113=(a087*a126);
  a136=(a100*a113);
  a136=(a132-a136);
  a099=(a067*a136);
  a139=(a081*a113);
  a138=(a032*a139);
  a099=(a099+a138);
  a138=(a108*a113);
  a138=(a107-a138);
  a140=(a029*a138);
  a099=(a099+a140);
  a099=(a093*a099);
  a140=(a071*a136);
  a141=(a036*a139);
  a140=(a140+a141);
  a141=(a034*a138);
  a140=(a140+a141);
  a140=(a110*a140);
  a099=(a099+a140);
  a136=(a060*a136);
  a139=(a025*a139);
  a136=(a136+a139);
  a138=(a021*a138);
  a136=(a136+a138);
  a136=(a111*a136);
  a099=(a099+a136);
  if (res[1]!=0) res[1][24]=a099;
  a099=(a091*a113);
  a099=(a133-a099);
  a136=(a067*a099);
  a138=(a094*a113);
  a107=(a107-a138);
  a138=(a032*a107);
  a136=(a136+a138);
  a126=(a000*a126);
  a126=(a090*a126);
  a138=(a096*a113);
  a138=(a126-a138);
  a139=(a029*a138);
  a136=(a136-a139);
  a136=(a105*a136);
  a139=(a071*a099);
  a140=(a036*a107);
  a139=(a139+a140);
  a140=(a034*a138);
  a139=(a139-a140);
  a139=(a117*a139);
  a136=(a136+a139);
  a099=(a060*a099);
  a107=(a025*a107);
  a099=(a099+a107);
  a138=(a021*a138);
  a099=(a099-a138);
  a099=(a118*a099);
  a136=(a136+a099);
  if (res[1]!=0) res[1][25]=a136;
  a136=(a104*a113);
  a136=(a132-a136);
  a099=(a032*a136);
  a138=(a089*a113);
  a126=(a126-a138);
  a138=(a067*a126);
  a099=(a099-a138);
  a113=(a106*a113);
  a113=(a113+a133);
  a138=(a029*a113);
  a099=(a099-a138);
  a099=(a114*a099);
  a138=(a036*a136);
  a107=(a071*a126);
  a138=(a138-a107);
  a107=(a034*a113);
  a138=(a138-a107);
  a138=(a122*a138);
  a099=(a099+a138);
  a136=(a025*a136);
  a126=(a060*a126);
  a136=(a136-a126);
  a113=(a021*a113);
  a136=(a136-a113);
  a136=(a123*a136);
  a099=(a099+a136);
  if (res[1]!=0) res[1][26]=a099;
  a099=(a121*a125);
  a099=(a120*a099);
  a136=(a080*a099);
  a136=(a136-a128);
  if (res[1]!=0) res[1][27]=a136;
  a136=(a085*a099);
  a136=(a137+a136);
  if (res[1]!=0) res[1][28]=a136;
  a099=(a068*a099);
  a136=(a134*a125);
  a099=(a099+a136);
  if (res[1]!=0) res[1][29]=a099;
  a099=(a135*a125);
  a128=(a087*a099);
  a113=(a108*a128);
  a113=(a098-a113);
  a126=(a029*a113);
  a138=(a100*a128);
  a138=(a138+a133);
  a107=(a067*a138);
  a099=(a000*a099);
  a099=(a090*a099);
  a139=(a081*a128);
  a139=(a099-a139);
  a140=(a032*a139);
  a107=(a107+a140);
  a126=(a126-a107);
  a126=(a093*a126);
  a107=(a034*a113);
  a140=(a071*a138);
  a141=(a036*a139);
  a140=(a140+a141);
  a107=(a107-a140);
  a107=(a110*a107);
  a126=(a126+a107);
  a113=(a021*a113);
  a138=(a060*a138);
  a139=(a025*a139);
  a138=(a138+a139);
  a113=(a113-a138);
  a113=(a111*a113);
  a126=(a126+a113);
  if (res[1]!=0) res[1][30]=a126;
  a126=(a091*a128);
  a126=(a132-a126);
  a113=(a067*a126);
  a138=(a094*a128);
  a098=(a098-a138);
  a138=(a032*a098);
  a113=(a113+a138);
  a138=(a096*a128);
  a139=(a029*a138);
  a113=(a113+a139);
  a113=(a105*a113);
  a139=(a071*a126);
  a107=(a036*a098);
  a139=(a139+a107);
  a107=(a034*a138);
  a139=(a139+a107);
  a139=(a117*a139);
  a113=(a113+a139);
  a126=(a060*a126);
  a098=(a025*a098);
  a126=(a126+a098);
  a138=(a021*a138);
  a126=(a126+a138);
  a126=(a118*a126);
  a113=(a113+a126);
  if (res[1]!=0) res[1][31]=a113;
  a113=(a104*a128);
  a133=(a133-a113);
  a113=(a032*a133);
  a126=(a089*a128);
  a099=(a099-a126);
  a126=(a067*a099);
  a113=(a113-a126);
  a128=(a106*a128);
  a132=(a132-a128);
  a128=(a029*a132);
  a113=(a113+a128);
  a113=(a114*a113);
  a128=(a036*a133);
  a126=(a071*a099);
  a128=(a128-a126);
  a126=(a034*a132);
  a128=(a128+a126);
  a128=(a122*a128);
  a113=(a113+a128);
  a133=(a025*a133);
  a099=(a060*a099);
  a133=(a133-a099);
  a132=(a021*a132);
  a133=(a133+a132);
  a133=(a123*a133);
  a113=(a113+a133);
  if (res[1]!=0) res[1][32]=a113;
  a125=(a119*a125);
  a125=(a120*a125);
  a113=(a080*a125);
  a130=(a130+a113);
  if (res[1]!=0) res[1][33]=a130;
  a130=(a085*a125);
  a130=(a130-a136);
  if (res[1]!=0) res[1][34]=a130;
  a125=(a068*a125);
  a137=(a137+a125);
  if (res[1]!=0) res[1][35]=a137;
  if (res[1]!=0) res[1][36]=a058;
  if (res[1]!=0) res[1][37]=a058;
  if (res[1]!=0) res[1][38]=a058;
  a137=(a120*a080);
  a125=(a080*a137);
  a125=(a125+a005);
  if (res[1]!=0) res[1][39]=a125;
  a125=(a085*a137);
  a130=(a000*a068);
  a125=(a125-a130);
  if (res[1]!=0) res[1][40]=a125;
  a137=(a068*a137);
  a125=(a000*a085);
  a137=(a137+a125);
  if (res[1]!=0) res[1][41]=a137;
  if (res[1]!=0) res[1][42]=a058;
  if (res[1]!=0) res[1][43]=a058;
  if (res[1]!=0) res[1][44]=a058;
  a137=(a120*a085);
  a136=(a080*a137);
  a130=(a130+a136);
  if (res[1]!=0) res[1][45]=a130;
  a130=(a085*a137);
  a130=(a005+a130);
  if (res[1]!=0) res[1][46]=a130;
  a137=(a068*a137);
  a130=(a000*a080);
  a137=(a137-a130);
  if (res[1]!=0) res[1][47]=a137;
  if (res[1]!=0) res[1][48]=a058;
  if (res[1]!=0) res[1][49]=a058;
  if (res[1]!=0) res[1][50]=a058;
  a137=(a120*a068);
  a136=(a080*a137);
  a136=(a136-a125);
  if (res[1]!=0) res[1][51]=a136;
  a136=(a085*a137);
  a130=(a130+a136);
  if (res[1]!=0) res[1][52]=a130;
  a137=(a068*a137);
  a005=(a005+a137);
  if (res[1]!=0) res[1][53]=a005;
  a005=(a102*a029);
  a137=(a116*a032);
  a005=(a005-a137);
  a005=(a093*a005);
  a137=(a102*a034);
  a130=(a116*a036);
  a137=(a137-a130);
  a137=(a110*a137);
  a005=(a005+a137);
  a137=(a102*a021);
  a130=(a116*a025);
  a137=(a137-a130);
  a137=(a111*a137);
  a005=(a005+a137);
  if (res[2]!=0) res[2][0]=a005;
  a005=(a095*a029);
  a137=(a097*a032);
  a005=(a005-a137);
  a005=(a105*a005);
  a137=(a095*a034);
  a130=(a097*a036);
  a137=(a137-a130);
  a137=(a117*a137);
  a005=(a005+a137);
  a137=(a095*a021);
  a130=(a097*a025);
  a137=(a137-a130);
  a137=(a118*a137);
  a005=(a005+a137);
  if (res[2]!=0) res[2][1]=a005;
  a005=(a109*a029);
  a137=(a112*a032);
  a005=(a005-a137);
  a005=(a114*a005);
  a137=(a109*a034);
  a130=(a112*a036);
  a137=(a137-a130);
  a137=(a122*a137);
  a005=(a005+a137);
  a137=(a109*a021);
  a130=(a112*a025);
  a137=(a137-a130);
  a137=(a123*a137);
  a005=(a005+a137);
  if (res[2]!=0) res[2][2]=a005;
  if (res[2]!=0) res[2][3]=a058;
  if (res[2]!=0) res[2][4]=a058;
  if (res[2]!=0) res[2][5]=a058;
  a005=(a116*a067);
  a137=(a115*a029);
  a005=(a005-a137);
  a005=(a093*a005);
  a137=(a116*a071);
  a130=(a115*a034);
  a137=(a137-a130);
  a137=(a110*a137);
  a005=(a005+a137);
  a116=(a116*a060);
  a137=(a115*a021);
  a116=(a116-a137);
  a116=(a111*a116);
  a005=(a005+a116);
  if (res[2]!=0) res[2][6]=a005;
  a005=(a097*a067);
  a116=(a092*a029);
  a005=(a005-a116);
  a005=(a105*a005);
  a116=(a097*a071);
  a137=(a092*a034);
  a116=(a116-a137);
  a116=(a117*a116);
  a005=(a005+a116);
  a097=(a097*a060);
  a116=(a092*a021);
  a097=(a097-a116);
  a097=(a118*a097);
  a005=(a005+a097);
  if (res[2]!=0) res[2][7]=a005;
  a005=(a112*a067);
  a097=(a086*a029);
  a005=(a005-a097);
  a005=(a114*a005);
  a097=(a112*a071);
  a116=(a086*a034);
  a097=(a097-a116);
  a097=(a122*a097);
  a005=(a005+a097);
  a112=(a112*a060);
  a097=(a086*a021);
  a112=(a112-a097);
  a112=(a123*a112);
  a005=(a005+a112);
  if (res[2]!=0) res[2][8]=a005;
  if (res[2]!=0) res[2][9]=a058;
  if (res[2]!=0) res[2][10]=a058;
  if (res[2]!=0) res[2][11]=a058;
  a005=(a115*a032);
  a112=(a102*a067);
  a005=(a005-a112);
  a005=(a093*a005);
  a112=(a115*a036);
  a097=(a102*a071);
  a112=(a112-a097);
  a112=(a110*a112);
  a005=(a005+a112);
  a115=(a115*a025);
  a102=(a102*a060);
  a115=(a115-a102);
  a115=(a111*a115);
  a005=(a005+a115);
  if (res[2]!=0) res[2][12]=a005;
  a005=(a092*a032);
  a115=(a095*a067);
  a005=(a005-a115);
  a005=(a105*a005);
  a115=(a092*a036);
  a102=(a095*a071);
  a115=(a115-a102);
  a115=(a117*a115);
  a005=(a005+a115);
  a092=(a092*a025);
  a095=(a095*a060);
  a092=(a092-a095);
  a092=(a118*a092);
  a005=(a005+a092);
  if (res[2]!=0) res[2][13]=a005;
  a005=(a086*a032);
  a092=(a109*a067);
  a005=(a005-a092);
  a005=(a114*a005);
  a092=(a086*a036);
  a095=(a109*a071);
  a092=(a092-a095);
  a092=(a122*a092);
  a005=(a005+a092);
  a086=(a086*a025);
  a109=(a109*a060);
  a086=(a086-a109);
  a086=(a123*a086);
  a005=(a005+a086);
  if (res[2]!=0) res[2][14]=a005;
  if (res[2]!=0) res[2][15]=a058;
  if (res[2]!=0) res[2][16]=a058;
  if (res[2]!=0) res[2][17]=a058;
  if (res[2]!=0) res[2][18]=a058;
  if (res[2]!=0) res[2][19]=a058;
  if (res[2]!=0) res[2][20]=a058;
  if (res[2]!=0) res[2][21]=a058;
  if (res[2]!=0) res[2][22]=a058;
  if (res[2]!=0) res[2][23]=a058;
  if (res[2]!=0) res[2][24]=a058;
  if (res[2]!=0) res[2][25]=a058;
  if (res[2]!=0) res[2][26]=a058;
  if (res[2]!=0) res[2][27]=a058;
  if (res[2]!=0) res[2][28]=a058;
  if (res[2]!=0) res[2][29]=a058;
  if (res[2]!=0) res[2][30]=a058;
  if (res[2]!=0) res[2][31]=a058;
  if (res[2]!=0) res[2][32]=a058;
  if (res[2]!=0) res[2][33]=a058;
  if (res[2]!=0) res[2][34]=a058;
  if (res[2]!=0) res[2][35]=a058;
  a005=(a015*a082);
  a086=(a011*a088);
  a005=(a005-a086);
  a005=(a005/a019);
  a005=(a073+a005);
  a086=(a017*a005);
  a109=(a001*a119);
  a109=(a000*a109);
  a092=5.3867513459481287e-01;
  a095=2.3205080756887719e-01;
  a115=3.;
  a102=(a011*a073);
  a112=(a008*a082);
  a102=(a102-a112);
  a102=(a102/a019);
  a102=(a088+a102);
  a112=(a017*a102);
  a097=(a115*a112);
  a116=(a011*a086);
  a137=(a008*a088);
  a130=(a015*a073);
  a137=(a137-a130);
  a137=(a137/a019);
  a137=(a082+a137);
  a130=(a017*a137);
  a136=(2.*a130);
  a125=(a008*a136);
  a116=(a116-a125);
  a116=(a116/a019);
  a116=(a097-a116);
  a125=(a017*a116);
  a125=(a125-a119);
  a113=(a095*a125);
  a133=1.5000000000000002e+00;
  a132=(a044*a079);
  a099=(a039*a084);
  a132=(a132-a099);
  a132=(a132/a019);
  a132=(a078+a132);
  a099=(a050*a132);
  a128=(a115*a099);
  a126=(a048*a084);
  a138=(a044*a078);
  a126=(a126-a138);
  a126=(a126/a019);
  a126=(a079+a126);
  a138=(a050*a126);
  a098=(a044*a138);
  a139=(a039*a078);
  a107=(a048*a079);
  a139=(a139-a107);
  a139=(a139/a019);
  a139=(a084+a139);
  a107=(a050*a139);
  a140=(2.*a107);
  a141=(a039*a140);
  a098=(a098-a141);
  a098=(a098/a019);
  a098=(a128-a098);
  a141=(a050*a098);
  a141=(a141-a119);
  a142=(a133*a141);
  a113=(a113+a142);
  a142=(a001*a113);
  a143=(a092*a142);
  a143=(a109+a143);
  a125=(a133*a125);
  a144=-3.2320508075688776e+00;
  a141=(a144*a141);
  a125=(a125+a141);
  a141=(a001*a125);
  a145=(a120*a141);
  a143=(a143+a145);
  a145=(a000*a143);
  a146=(a086*a145);
  a147=(a008*a097);
  a148=(a015*a086);
  a147=(a147-a148);
  a147=(a147/a019);
  a147=(a136-a147);
  a148=(a017*a147);
  a148=(a148-a121);
  a149=(a133*a148);
  a150=(a039*a128);
  a151=(a048*a138);
  a150=(a150-a151);
  a150=(a150/a019);
  a150=(a140-a150);
  a151=(a050*a150);
  a151=(a151-a121);
  a152=(a144*a151);
  a149=(a149+a152);
  a146=(a146+a149);
  a152=(a008*a086);
  a153=(a011*a130);
  a152=(a152+a153);
  a153=(a015*a112);
  a152=(a152+a153);
  a152=(a152/a006);
  a153=(a001*a121);
  a153=(a000*a153);
  a148=(a095*a148);
  a151=(a133*a151);
  a148=(a148+a151);
  a151=(a001*a148);
  a154=(a092*a151);
  a154=(a153+a154);
  a155=(a001*a149);
  a156=(a120*a155);
  a154=(a154+a156);
  a156=(a152*a154);
  a146=(a146-a156);
  a156=(a015*a143);
  a157=(a011*a154);
  a156=(a156+a157);
  a157=(a001*a124);
  a157=(a000*a157);
  a158=(a015*a136);
  a159=(a011*a097);
  a158=(a158-a159);
  a158=(a158/a019);
  a158=(a086-a158);
  a159=(a017*a158);
  a159=(a159-a124);
  a160=(a095*a159);
  a161=(a048*a140);
  a162=(a044*a128);
  a161=(a161-a162);
  a161=(a161/a019);
  a161=(a138-a161);
  a019=(a050*a161);
  a019=(a019-a124);
  a162=(a133*a019);
  a160=(a160+a162);
  a162=(a001*a160);
  a163=(a092*a162);
  a163=(a157+a163);
  a159=(a133*a159);
  a019=(a144*a019);
  a159=(a159+a019);
  a019=(a001*a159);
  a164=(a120*a019);
  a163=(a163+a164);
  a164=(a008*a163);
  a156=(a156+a164);
  a156=(a120*a156);
  a164=(a130*a156);
  a146=(a146-a164);
  a164=(a000*a163);
  a165=(a112*a164);
  a146=(a146-a165);
  a165=(a000*a146);
  a166=(a165*a014);
  a167=(a082*a014);
  a168=(a088*a010);
  a167=(a167-a168);
  a167=(a000*a167);
  a167=(a017*a167);
  a013=(a017/a013);
  a168=(2.*a008);
  a168=(a168*a007);
  a169=(2.*a011);
  a169=(a169*a010);
  a170=(a168+a169);
  a171=(2.*a015);
  a171=(a171*a014);
  a170=(a170+a171);
  a013=(a013*a170);
  a005=(a005*a013);
  a167=(a167-a005);
  a005=(a145*a167);
  a170=(a073*a010);
  a082=(a082*a007);
  a170=(a170-a082);
  a170=(a000*a170);
  a170=(a017*a170);
  a102=(a102*a013);
  a170=(a170-a102);
  a102=(a115*a170);
  a082=(a086*a010);
  a172=(a011*a167);
  a082=(a082+a172);
  a172=(a136*a007);
  a088=(a088*a007);
  a073=(a073*a014);
  a088=(a088-a073);
  a088=(a000*a088);
  a088=(a017*a088);
  a137=(a137*a013);
  a088=(a088-a137);
  a137=(2.*a088);
  a073=(a008*a137);
  a172=(a172+a073);
  a082=(a082-a172);
  a082=(a000*a082);
  a082=(a102-a082);
  a082=(a017*a082);
  a116=(a116*a013);
  a082=(a082-a116);
  a116=(a095*a082);
  a172=(a079*a043);
  a073=(a084*a030);
  a172=(a172-a073);
  a172=(a000*a172);
  a172=(a050*a172);
  a046=(a050/a046);
  a073=(2.*a039);
  a073=(a073*a030);
  a173=(2.*a044);
  a173=(a173*a043);
  a174=(a073+a173);
  a175=(2.*a048);
  a175=(a175*a047);
  a174=(a174+a175);
  a046=(a046*a174);
  a132=(a132*a046);
  a172=(a172-a132);
  a115=(a115*a172);
  a132=(a138*a043);
  a084=(a084*a047);
  a174=(a078*a043);
  a084=(a084-a174);
  a084=(a000*a084);
  a084=(a050*a084);
  a126=(a126*a046);
  a084=(a084-a126);
  a126=(a044*a084);
  a132=(a132+a126);
  a126=(a140*a030);
  a078=(a078*a030);
  a079=(a079*a047);
  a078=(a078-a079);
  a078=(a000*a078);
  a078=(a050*a078);
  a139=(a139*a046);
  a078=(a078-a139);
  a139=(2.*a078);
  a079=(a039*a139);
  a126=(a126+a079);
  a132=(a132-a126);
  a132=(a000*a132);
  a132=(a115-a132);
  a132=(a050*a132);
  a098=(a098*a046);
  a132=(a132-a098);
  a098=(a133*a132);
  a116=(a116+a098);
  a098=(a001*a116);
  a098=(a113+a098);
  a126=(a092*a098);
  a126=(a127+a126);
  a082=(a133*a082);
  a132=(a144*a132);
  a082=(a082+a132);
  a132=(a001*a082);
  a132=(a125+a132);
  a079=(a120*a132);
  a126=(a126+a079);
  a079=(a000*a126);
  a174=(a086*a079);
  a005=(a005+a174);
  a174=(a097*a007);
  a176=(a008*a102);
  a174=(a174+a176);
  a176=(a086*a014);
  a177=(a015*a167);
  a176=(a176+a177);
  a174=(a174-a176);
  a174=(a000*a174);
  a174=(a137-a174);
  a174=(a017*a174);
  a147=(a147*a013);
  a174=(a174-a147);
  a147=(a133*a174);
  a176=(a128*a030);
  a177=(a039*a115);
  a176=(a176+a177);
  a177=(a138*a047);
  a178=(a048*a084);
  a177=(a177+a178);
  a176=(a176-a177);
  a176=(a000*a176);
  a176=(a139-a176);
  a176=(a050*a176);
  a150=(a150*a046);
  a176=(a176-a150);
  a150=(a144*a176);
  a147=(a147+a150);
  a005=(a005+a147);
  a150=(a086*a007);
  a177=(a008*a167);
  a150=(a150+a177);
  a177=(a130*a010);
  a178=(a011*a088);
  a177=(a177+a178);
  a150=(a150+a177);
  a177=(a112*a014);
  a178=(a015*a170);
  a177=(a177+a178);
  a150=(a150+a177);
  a150=(a120*a150);
  a177=(a154*a150);
  a174=(a095*a174);
  a176=(a133*a176);
  a174=(a174+a176);
  a176=(a001*a174);
  a176=(a148+a176);
  a178=(a092*a176);
  a178=(a129+a178);
  a147=(a001*a147);
  a149=(a149+a147);
  a147=(a120*a149);
  a178=(a178+a147);
  a147=(a152*a178);
  a177=(a177+a147);
  a005=(a005-a177);
  a177=(a156*a088);
  a147=(a143*a014);
  a179=(a015*a126);
  a147=(a147+a179);
  a179=(a154*a010);
  a180=(a011*a178);
  a179=(a179+a180);
  a147=(a147+a179);
  a179=(a163*a007);
  a136=(a136*a014);
  a137=(a015*a137);
  a136=(a136+a137);
  a097=(a097*a010);
  a102=(a011*a102);
  a097=(a097+a102);
  a136=(a136-a097);
  a136=(a000*a136);
  a136=(a167-a136);
  a136=(a017*a136);
  a158=(a158*a013);
  a136=(a136-a158);
  a095=(a095*a136);
  a140=(a140*a047);
  a139=(a048*a139);
  a140=(a140+a139);
  a128=(a128*a043);
  a115=(a044*a115);
  a128=(a128+a115);
  a140=(a140-a128);
  a140=(a000*a140);
  a140=(a084-a140);
  a140=(a050*a140);
  a161=(a161*a046);
  a140=(a140-a161);
  a161=(a133*a140);
  a095=(a095+a161);
  a161=(a001*a095);
  a161=(a160+a161);
  a092=(a092*a161);
  a092=(a134+a092);
  a133=(a133*a136);
  a144=(a144*a140);
  a133=(a133+a144);
  a144=(a001*a133);
  a144=(a159+a144);
  a140=(a120*a144);
  a092=(a092+a140);
  a140=(a008*a092);
  a179=(a179+a140);
  a147=(a147+a179);
  a147=(a120*a147);
  a179=(a130*a147);
  a177=(a177+a179);
  a005=(a005-a177);
  a177=(a164*a170);
  a179=(a000*a092);
  a140=(a112*a179);
  a177=(a177+a140);
  a005=(a005-a177);
  a177=(a000*a005);
  a140=(a015*a177);
  a166=(a166+a140);
  a140=(a152*a143);
  a125=(a125-a140);
  a154=(a000*a154);
  a140=(a086*a154);
  a125=(a125-a140);
  a140=(a112*a156);
  a125=(a125-a140);
  a140=(a130*a164);
  a125=(a125+a140);
  a140=(a000*a125);
  a136=(a140*a010);
  a143=(a143*a150);
  a126=(a152*a126);
  a143=(a143+a126);
  a082=(a082-a143);
  a143=(a154*a167);
  a178=(a000*a178);
  a126=(a086*a178);
  a143=(a143+a126);
  a082=(a082-a143);
  a143=(a156*a170);
  a126=(a112*a147);
  a143=(a143+a126);
  a082=(a082-a143);
  a164=(a164*a088);
  a179=(a130*a179);
  a164=(a164+a179);
  a082=(a082+a164);
  a164=(a000*a082);
  a179=(a011*a164);
  a136=(a136+a179);
  a179=(a166-a136);
  a143=(a011*a146);
  a126=(a015*a125);
  a143=(a143+a126);
  a126=(a112*a154);
  a128=(a130*a145);
  a126=(a126-a128);
  a126=(a126+a159);
  a159=(a152*a163);
  a126=(a126-a159);
  a159=(a086*a156);
  a126=(a126-a159);
  a159=(a008*a126);
  a143=(a143+a159);
  a143=(a120*a143);
  a159=(a143*a007);
  a128=(a146*a010);
  a115=(a011*a005);
  a128=(a128+a115);
  a115=(a125*a014);
  a139=(a015*a082);
  a115=(a115+a139);
  a128=(a128+a115);
  a115=(a126*a007);
  a154=(a154*a170);
  a178=(a112*a178);
  a154=(a154+a178);
  a145=(a145*a088);
  a079=(a130*a079);
  a145=(a145+a079);
  a154=(a154-a145);
  a154=(a154+a133);
  a163=(a163*a150);
  a152=(a152*a092);
  a163=(a163+a152);
  a154=(a154-a163);
  a156=(a156*a167);
  a147=(a086*a147);
  a156=(a156+a147);
  a154=(a154-a156);
  a156=(a008*a154);
  a115=(a115+a156);
  a128=(a128+a115);
  a128=(a120*a128);
  a115=(a008*a128);
  a159=(a159+a115);
  a179=(a179+a159);
  a179=(a179+a154);
  a115=(a008*a010);
  a156=(a011*a007);
  a147=(a115+a156);
  a147=(a000*a147);
  a147=(a147-a014);
  a147=(a017*a147);
  a065=(a065*a013);
  a147=(a147-a065);
  a065=(a060*a147);
  a163=(a171+a168);
  a163=(a000*a163);
  a163=(a017*a163);
  a018=(a018*a013);
  a163=(a163-a018);
  a018=(a025*a163);
  a065=(a065-a018);
  a018=(a015*a010);
  a152=(a011*a014);
  a092=(a018+a152);
  a092=(a000*a092);
  a092=(a007+a092);
  a092=(a017*a092);
  a023=(a023*a013);
  a092=(a092-a023);
  a023=(a021*a092);
  a065=(a065+a023);
  a023=(a008*a014);
  a150=(a015*a007);
  a133=(a023+a150);
  a133=(a000*a133);
  a133=(a010+a133);
  a133=(a017*a133);
  a069=(a069*a013);
  a133=(a133-a069);
  a069=(a067*a133);
  a152=(a152+a018);
  a152=(a000*a152);
  a152=(a152-a007);
  a152=(a017*a152);
  a027=(a027*a013);
  a152=(a152-a027);
  a027=(a032*a152);
  a069=(a069+a027);
  a168=(a169+a168);
  a168=(a000*a168);
  a168=(a017*a168);
  a009=(a009*a013);
  a168=(a168-a009);
  a009=(a029*a168);
  a069=(a069-a009);
  a009=(a026*a069);
  a065=(a065+a009);
  a133=(a071*a133);
  a152=(a036*a152);
  a133=(a133+a152);
  a168=(a034*a168);
  a133=(a133-a168);
  a168=(a033*a133);
  a065=(a065+a168);
  a065=(a004*a065);
  a168=arg[3]? arg[3][3] : 0;
  a167=(a168*a167);
  a065=(a065-a167);
  a065=(a002*a065);
  a167=(a060*a066);
  a152=(a025*a020);
  a167=(a167+a152);
  a152=(a021*a024);
  a167=(a167+a152);
  a152=(a067*a070);
  a009=(a032*a028);
  a152=(a152+a009);
  a009=(a029*a031);
  a152=(a152+a009);
  a009=(a026*a152);
  a167=(a167+a009);
  a070=(a071*a070);
  a028=(a036*a028);
  a070=(a070+a028);
  a031=(a034*a031);
  a070=(a070+a031);
  a031=(a033*a070);
  a167=(a167+a031);
  a031=(a004*a167);
  a028=(a168*a086);
  a031=(a031-a028);
  a028=(a000*a031);
  a065=(a065+a028);
  a179=(a179+a065);
  a179=(a179/a001);
  a065=(a015*a165);
  a028=(a011*a140);
  a065=(a065-a028);
  a028=(a008*a143);
  a065=(a065+a028);
  a065=(a065+a126);
  a031=(a031*a002);
  a065=(a065+a031);
  a065=(a065/a001);
  a065=(a065/a001);
  a179=(a179-a065);
  if (res[3]!=0) res[3][0]=a179;
  a179=(a140*a007);
  a164=(a008*a164);
  a179=(a179+a164);
  a164=(a005+a179);
  a065=(a143*a010);
  a031=(a011*a128);
  a065=(a065+a031);
  a164=(a164+a065);
  a126=(a000*a126);
  a031=(a126*a014);
  a028=(a000*a154);
  a009=(a015*a028);
  a031=(a031+a009);
  a164=(a164-a031);
  a069=(a022*a069);
  a156=(a156+a115);
  a156=(a000*a156);
  a156=(a014+a156);
  a156=(a017*a156);
  a037=(a037*a013);
  a156=(a156-a037);
  a037=(a025*a156);
  a171=(a171+a169);
  a171=(a000*a171);
  a171=(a017*a171);
  a016=(a016*a013);
  a171=(a171-a016);
  a016=(a060*a171);
  a037=(a037-a016);
  a150=(a150+a023);
  a150=(a000*a150);
  a150=(a150-a010);
  a017=(a017*a150);
  a040=(a040*a013);
  a017=(a017-a040);
  a040=(a021*a017);
  a037=(a037+a040);
  a069=(a069-a037);
  a133=(a026*a133);
  a069=(a069+a133);
  a069=(a004*a069);
  a088=(a168*a088);
  a069=(a069-a088);
  a069=(a002*a069);
  a152=(a022*a152);
  a088=(a060*a012);
  a133=(a025*a038);
  a088=(a088+a133);
  a133=(a021*a041);
  a088=(a088+a133);
  a152=(a152-a088);
  a070=(a026*a070);
  a152=(a152+a070);
  a070=(a004*a152);
  a088=(a168*a130);
  a070=(a070-a088);
  a088=(a000*a070);
  a069=(a069+a088);
  a164=(a164+a069);
  a164=(a164/a001);
  a140=(a008*a140);
  a146=(a146+a140);
  a140=(a011*a143);
  a146=(a146+a140);
  a140=(a015*a126);
  a146=(a146-a140);
  a070=(a070*a002);
  a146=(a146+a070);
  a146=(a146/a001);
  a146=(a146/a001);
  a164=(a164-a146);
  if (res[3]!=0) res[3][1]=a164;
  a007=(a165*a007);
  a177=(a008*a177);
  a007=(a007+a177);
  a177=(a082-a007);
  a014=(a143*a014);
  a128=(a015*a128);
  a014=(a014+a128);
  a177=(a177+a014);
  a010=(a126*a010);
  a028=(a011*a028);
  a010=(a010+a028);
  a177=(a177+a010);
  a028=(a036*a156);
  a128=(a071*a171);
  a028=(a028-a128);
  a128=(a034*a017);
  a028=(a028+a128);
  a028=(a022*a028);
  a128=(a067*a147);
  a164=(a032*a163);
  a128=(a128-a164);
  a164=(a029*a092);
  a128=(a128+a164);
  a128=(a033*a128);
  a028=(a028+a128);
  a156=(a032*a156);
  a171=(a067*a171);
  a156=(a156-a171);
  a017=(a029*a017);
  a156=(a156+a017);
  a156=(a035*a156);
  a028=(a028+a156);
  a147=(a071*a147);
  a163=(a036*a163);
  a147=(a147-a163);
  a092=(a034*a092);
  a147=(a147+a092);
  a147=(a035*a147);
  a028=(a028+a147);
  a028=(a004*a028);
  a170=(a168*a170);
  a028=(a028-a170);
  a028=(a002*a028);
  a170=(a071*a012);
  a147=(a036*a038);
  a170=(a170+a147);
  a147=(a034*a041);
  a170=(a170+a147);
  a170=(a022*a170);
  a147=(a067*a066);
  a092=(a032*a020);
  a147=(a147+a092);
  a092=(a029*a024);
  a147=(a147+a092);
  a147=(a033*a147);
  a170=(a170+a147);
  a012=(a067*a012);
  a038=(a032*a038);
  a012=(a012+a038);
  a041=(a029*a041);
  a012=(a012+a041);
  a012=(a035*a012);
  a170=(a170+a012);
  a066=(a071*a066);
  a020=(a036*a020);
  a066=(a066+a020);
  a024=(a034*a024);
  a066=(a066+a024);
  a066=(a035*a066);
  a170=(a170+a066);
  a066=(a004*a170);
  a024=(a168*a112);
  a066=(a066-a024);
  a024=(a000*a066);
  a028=(a028+a024);
  a177=(a177+a028);
  a177=(a177/a001);
  a008=(a008*a165);
  a125=(a125-a008);
  a015=(a015*a143);
  a125=(a125+a015);
  a011=(a011*a126);
  a125=(a125+a011);
  a066=(a066*a002);
  a125=(a125+a066);
  a125=(a125/a001);
  a125=(a125/a001);
  a177=(a177-a125);
  if (res[3]!=0) res[3][2]=a177;
  a177=(a039*a043);
  a125=(a044*a030);
  a066=(a177+a125);
  a066=(a000*a066);
  a066=(a066-a047);
  a066=(a050*a066);
  a072=(a072*a046);
  a066=(a066-a072);
  a072=(a060*a066);
  a011=(a175+a073);
  a011=(a000*a011);
  a011=(a050*a011);
  a051=(a051*a046);
  a011=(a011-a051);
  a051=(a025*a011);
  a072=(a072-a051);
  a051=(a048*a043);
  a126=(a044*a047);
  a015=(a051+a126);
  a015=(a000*a015);
  a015=(a030+a015);
  a015=(a050*a015);
  a054=(a054*a046);
  a015=(a015-a054);
  a054=(a021*a015);
  a072=(a072+a054);
  a054=(a039*a047);
  a143=(a048*a030);
  a008=(a054+a143);
  a008=(a000*a008);
  a008=(a043+a008);
  a008=(a050*a008);
  a074=(a074*a046);
  a008=(a008-a074);
  a074=(a067*a008);
  a126=(a126+a051);
  a126=(a000*a126);
  a126=(a126-a030);
  a126=(a050*a126);
  a056=(a056*a046);
  a126=(a126-a056);
  a056=(a032*a126);
  a074=(a074+a056);
  a073=(a173+a073);
  a073=(a000*a073);
  a073=(a050*a073);
  a042=(a042*a046);
  a073=(a073-a042);
  a042=(a029*a073);
  a074=(a074-a042);
  a042=(a026*a074);
  a072=(a072+a042);
  a008=(a071*a008);
  a126=(a036*a126);
  a008=(a008+a126);
  a073=(a034*a073);
  a008=(a008-a073);
  a073=(a033*a008);
  a072=(a072+a073);
  a072=(a004*a072);
  a073=(a168*a084);
  a072=(a072-a073);
  a072=(a002*a072);
  a073=(a060*a062);
  a126=(a025*a052);
  a073=(a073+a126);
  a126=(a021*a055);
  a073=(a073+a126);
  a126=(a067*a075);
  a042=(a032*a057);
  a126=(a126+a042);
  a042=(a029*a059);
  a126=(a126+a042);
  a042=(a026*a126);
  a073=(a073+a042);
  a075=(a071*a075);
  a057=(a036*a057);
  a075=(a075+a057);
  a059=(a034*a059);
  a075=(a075+a059);
  a059=(a033*a075);
  a073=(a073+a059);
  a059=(a004*a073);
  a057=(a168*a138);
  a059=(a059-a057);
  a057=(a000*a059);
  a072=(a072+a057);
  a142=(a120*a142);
  a109=(a109+a142);
  a142=-3.8675134594812879e-02;
  a141=(a142*a141);
  a109=(a109+a141);
  a141=(a000*a109);
  a057=(a141*a078);
  a098=(a120*a098);
  a098=(a127+a098);
  a132=(a142*a132);
  a098=(a098+a132);
  a132=(a000*a098);
  a042=(a107*a132);
  a057=(a057+a042);
  a095=(a095-a057);
  a151=(a120*a151);
  a153=(a153+a151);
  a155=(a142*a155);
  a153=(a153+a155);
  a155=(a000*a153);
  a151=(a155*a172);
  a176=(a120*a176);
  a176=(a129+a176);
  a149=(a142*a149);
  a176=(a176+a149);
  a149=(a000*a176);
  a057=(a099*a149);
  a151=(a151+a057);
  a095=(a095+a151);
  a162=(a120*a162);
  a157=(a157+a162);
  a019=(a142*a019);
  a157=(a157+a019);
  a019=(a138*a030);
  a162=(a039*a084);
  a019=(a019+a162);
  a162=(a107*a043);
  a151=(a044*a078);
  a162=(a162+a151);
  a019=(a019+a162);
  a162=(a099*a047);
  a151=(a048*a172);
  a162=(a162+a151);
  a019=(a019+a162);
  a019=(a120*a019);
  a162=(a157*a019);
  a151=(a039*a138);
  a057=(a044*a107);
  a151=(a151+a057);
  a057=(a048*a099);
  a151=(a151+a057);
  a151=(a151/a006);
  a161=(a120*a161);
  a161=(a134+a161);
  a142=(a142*a144);
  a161=(a161+a142);
  a142=(a151*a161);
  a162=(a162+a142);
  a095=(a095-a162);
  a162=(a048*a109);
  a142=(a044*a153);
  a162=(a162+a142);
  a142=(a039*a157);
  a162=(a162+a142);
  a162=(a120*a162);
  a142=(a162*a084);
  a144=(a109*a047);
  a006=(a048*a098);
  a144=(a144+a006);
  a006=(a153*a043);
  a057=(a044*a176);
  a006=(a006+a057);
  a144=(a144+a006);
  a006=(a157*a030);
  a057=(a039*a161);
  a006=(a006+a057);
  a144=(a144+a006);
  a144=(a120*a144);
  a006=(a138*a144);
  a142=(a142+a006);
  a095=(a095-a142);
  a072=(a072+a095);
  a142=(a138*a141);
  a148=(a148+a142);
  a142=(a151*a153);
  a148=(a148-a142);
  a142=(a107*a162);
  a148=(a148-a142);
  a142=(a000*a157);
  a006=(a099*a142);
  a148=(a148-a006);
  a006=(a000*a148);
  a057=(a006*a047);
  a042=(a141*a084);
  a132=(a138*a132);
  a042=(a042+a132);
  a174=(a174+a042);
  a153=(a153*a019);
  a176=(a151*a176);
  a153=(a153+a176);
  a174=(a174-a153);
  a153=(a162*a078);
  a176=(a107*a144);
  a153=(a153+a176);
  a174=(a174-a153);
  a153=(a142*a172);
  a161=(a000*a161);
  a176=(a099*a161);
  a153=(a153+a176);
  a174=(a174-a153);
  a153=(a000*a174);
  a176=(a048*a153);
  a057=(a057+a176);
  a072=(a072+a057);
  a141=(a107*a141);
  a160=(a160-a141);
  a141=(a099*a155);
  a160=(a160+a141);
  a157=(a151*a157);
  a160=(a160-a157);
  a157=(a138*a162);
  a160=(a160-a157);
  a157=(a039*a160);
  a141=(a044*a148);
  a157=(a157+a141);
  a141=(a151*a109);
  a113=(a113-a141);
  a141=(a138*a155);
  a113=(a113-a141);
  a141=(a099*a162);
  a113=(a113-a141);
  a141=(a107*a142);
  a113=(a113+a141);
  a141=(a048*a113);
  a157=(a157+a141);
  a157=(a120*a157);
  a141=(a157*a030);
  a176=(a160*a030);
  a042=(a039*a095);
  a176=(a176+a042);
  a042=(a148*a043);
  a132=(a044*a174);
  a042=(a042+a132);
  a176=(a176+a042);
  a042=(a113*a047);
  a109=(a109*a019);
  a151=(a151*a098);
  a109=(a109+a151);
  a116=(a116-a109);
  a155=(a155*a084);
  a149=(a138*a149);
  a155=(a155+a149);
  a116=(a116-a155);
  a162=(a162*a172);
  a144=(a099*a144);
  a162=(a162+a144);
  a116=(a116-a162);
  a142=(a142*a078);
  a161=(a107*a161);
  a142=(a142+a161);
  a116=(a116+a142);
  a142=(a048*a116);
  a042=(a042+a142);
  a176=(a176+a042);
  a176=(a120*a176);
  a042=(a039*a176);
  a141=(a141+a042);
  a072=(a072+a141);
  a042=(a000*a113);
  a142=(a042*a043);
  a161=(a000*a116);
  a162=(a044*a161);
  a142=(a142+a162);
  a072=(a072-a142);
  a072=(a072/a001);
  a059=(a059*a002);
  a059=(a059+a160);
  a162=(a048*a006);
  a059=(a059+a162);
  a162=(a039*a157);
  a059=(a059+a162);
  a162=(a044*a042);
  a059=(a059-a162);
  a059=(a059/a001);
  a059=(a059/a001);
  a072=(a072-a059);
  if (res[3]!=0) res[3][3]=a072;
  a074=(a022*a074);
  a125=(a125+a177);
  a125=(a000*a125);
  a125=(a047+a125);
  a125=(a050*a125);
  a053=(a053*a046);
  a125=(a125-a053);
  a053=(a025*a125);
  a175=(a175+a173);
  a175=(a000*a175);
  a175=(a050*a175);
  a049=(a049*a046);
  a175=(a175-a049);
  a049=(a060*a175);
  a053=(a053-a049);
  a143=(a143+a054);
  a143=(a000*a143);
  a143=(a143-a043);
  a050=(a050*a143);
  a063=(a063*a046);
  a050=(a050-a063);
  a063=(a021*a050);
  a053=(a053+a063);
  a074=(a074-a053);
  a008=(a026*a008);
  a074=(a074+a008);
  a074=(a004*a074);
  a078=(a168*a078);
  a074=(a074-a078);
  a074=(a002*a074);
  a126=(a022*a126);
  a078=(a060*a045);
  a008=(a025*a061);
  a078=(a078+a008);
  a008=(a021*a064);
  a078=(a078+a008);
  a126=(a126-a078);
  a026=(a026*a075);
  a126=(a126+a026);
  a026=(a004*a126);
  a075=(a168*a107);
  a026=(a026-a075);
  a075=(a000*a026);
  a074=(a074+a075);
  a160=(a000*a160);
  a075=(a160*a047);
  a078=(a000*a095);
  a008=(a048*a078);
  a075=(a075+a008);
  a074=(a074-a075);
  a074=(a074+a174);
  a008=(a157*a043);
  a053=(a044*a176);
  a008=(a008+a053);
  a074=(a074+a008);
  a053=(a042*a030);
  a161=(a039*a161);
  a053=(a053+a161);
  a074=(a074+a053);
  a074=(a074/a001);
  a026=(a026*a002);
  a161=(a048*a160);
  a026=(a026-a161);
  a026=(a026+a148);
  a148=(a044*a157);
  a026=(a026+a148);
  a042=(a039*a042);
  a026=(a026+a042);
  a026=(a026/a001);
  a026=(a026/a001);
  a074=(a074-a026);
  if (res[3]!=0) res[3][4]=a074;
  a074=(a036*a125);
  a026=(a071*a175);
  a074=(a074-a026);
  a026=(a034*a050);
  a074=(a074+a026);
  a074=(a022*a074);
  a026=(a067*a066);
  a042=(a032*a011);
  a026=(a026-a042);
  a042=(a029*a015);
  a026=(a026+a042);
  a026=(a033*a026);
  a074=(a074+a026);
  a125=(a032*a125);
  a175=(a067*a175);
  a125=(a125-a175);
  a050=(a029*a050);
  a125=(a125+a050);
  a125=(a035*a125);
  a074=(a074+a125);
  a066=(a071*a066);
  a011=(a036*a011);
  a066=(a066-a011);
  a015=(a034*a015);
  a066=(a066+a015);
  a066=(a035*a066);
  a074=(a074+a066);
  a074=(a004*a074);
  a172=(a168*a172);
  a074=(a074-a172);
  a074=(a002*a074);
  a172=(a071*a045);
  a066=(a036*a061);
  a172=(a172+a066);
  a066=(a034*a064);
  a172=(a172+a066);
  a022=(a022*a172);
  a172=(a067*a062);
  a066=(a032*a052);
  a172=(a172+a066);
  a066=(a029*a055);
  a172=(a172+a066);
  a033=(a033*a172);
  a022=(a022+a033);
  a045=(a067*a045);
  a061=(a032*a061);
  a045=(a045+a061);
  a064=(a029*a064);
  a045=(a045+a064);
  a045=(a035*a045);
  a022=(a022+a045);
  a062=(a071*a062);
  a052=(a036*a052);
  a062=(a062+a052);
  a055=(a034*a055);
  a062=(a062+a055);
  a035=(a035*a062);
  a022=(a022+a035);
  a004=(a004*a022);
  a168=(a168*a099);
  a004=(a004-a168);
  a168=(a000*a004);
  a074=(a074+a168);
  a043=(a160*a043);
  a078=(a044*a078);
  a043=(a043+a078);
  a074=(a074+a043);
  a030=(a006*a030);
  a153=(a039*a153);
  a030=(a030+a153);
  a074=(a074-a030);
  a047=(a157*a047);
  a176=(a048*a176);
  a047=(a047+a176);
  a074=(a074+a047);
  a074=(a074+a116);
  a074=(a074/a001);
  a004=(a004*a002);
  a044=(a044*a160);
  a004=(a004+a044);
  a039=(a039*a006);
  a004=(a004-a039);
  a048=(a048*a157);
  a004=(a004+a048);
  a004=(a004+a113);
  a004=(a004/a001);
  a004=(a004/a001);
  a074=(a074-a004);
  if (res[3]!=0) res[3][5]=a074;
  a074=(a129*a076);
  a004=(a127*a083);
  a074=(a074-a004);
  a004=(a103*a077);
  a119=(a119*a076);
  a121=(a121*a083);
  a119=(a119+a121);
  a124=(a124*a077);
  a119=(a119+a124);
  a120=(a120*a119);
  a119=(a080*a120);
  a004=(a004+a119);
  a119=(a074-a004);
  a119=(a119-a095);
  a119=(a119+a057);
  a119=(a119-a141);
  a119=(a119-a142);
  a119=(a119+a166);
  a119=(a119-a136);
  a119=(a119-a159);
  a119=(a119-a154);
  if (res[3]!=0) res[3][6]=a119;
  a127=(a127*a077);
  a119=(a103*a083);
  a154=(a085*a120);
  a119=(a119+a154);
  a154=(a127-a119);
  a159=(a134*a076);
  a154=(a154-a159);
  a154=(a154-a075);
  a154=(a154-a174);
  a154=(a154-a008);
  a154=(a154+a053);
  a154=(a154-a005);
  a154=(a154+a179);
  a154=(a154-a065);
  a154=(a154-a031);
  if (res[3]!=0) res[3][7]=a154;
  a134=(a134*a083);
  a129=(a129*a077);
  a103=(a103*a076);
  a120=(a068*a120);
  a103=(a103+a120);
  a120=(a129+a103);
  a120=(a134-a120);
  a120=(a120+a043);
  a120=(a120-a030);
  a120=(a120-a047);
  a120=(a120-a116);
  a120=(a120-a007);
  a120=(a120-a082);
  a120=(a120-a014);
  a120=(a120+a010);
  if (res[3]!=0) res[3][8]=a120;
  if (res[3]!=0) res[3][9]=a058;
  if (res[3]!=0) res[3][10]=a058;
  if (res[3]!=0) res[3][11]=a058;
  if (res[3]!=0) res[3][12]=a058;
  if (res[3]!=0) res[3][13]=a058;
  if (res[3]!=0) res[3][14]=a058;
  if (res[3]!=0) res[3][15]=a058;
  if (res[3]!=0) res[3][16]=a058;
  if (res[3]!=0) res[3][17]=a058;
  a167=(a003*a167);
  a167=(a002*a167);
  a167=(a167/a001);
  if (res[3]!=0) res[3][18]=a167;
  a152=(a003*a152);
  a152=(a002*a152);
  a152=(a152/a001);
  if (res[3]!=0) res[3][19]=a152;
  a170=(a003*a170);
  a170=(a002*a170);
  a170=(a170/a001);
  if (res[3]!=0) res[3][20]=a170;
  a073=(a003*a073);
  a073=(a002*a073);
  a073=(a073/a001);
  if (res[3]!=0) res[3][21]=a073;
  a126=(a003*a126);
  a126=(a002*a126);
  a126=(a126/a001);
  if (res[3]!=0) res[3][22]=a126;
  a003=(a003*a022);
  a003=(a002*a003);
  a003=(a003/a001);
  if (res[3]!=0) res[3][23]=a003;
  if (res[3]!=0) res[3][24]=a058;
  if (res[3]!=0) res[3][25]=a058;
  if (res[3]!=0) res[3][26]=a058;
  a086=(a002*a086);
  a086=(a086/a001);
  a086=(-a086);
  if (res[3]!=0) res[3][27]=a086;
  a130=(a002*a130);
  a130=(a130/a001);
  a130=(-a130);
  if (res[3]!=0) res[3][28]=a130;
  a112=(a002*a112);
  a112=(a112/a001);
  a112=(-a112);
  if (res[3]!=0) res[3][29]=a112;
  a138=(a002*a138);
  a138=(a138/a001);
  a138=(-a138);
  if (res[3]!=0) res[3][30]=a138;
  a107=(a002*a107);
  a107=(a107/a001);
  a107=(-a107);
  if (res[3]!=0) res[3][31]=a107;
  a002=(a002*a099);
  a002=(a002/a001);
  a002=(-a002);
  if (res[3]!=0) res[3][32]=a002;
  if (res[3]!=0) res[3][33]=a058;
  if (res[3]!=0) res[3][34]=a058;
  if (res[3]!=0) res[3][35]=a058;
  a002=(a080*a083);
  a001=(a085*a077);
  a099=(a002+a001);
  a099=(a000*a099);
  a099=(a099-a076);
  a099=(a090*a099);
  a101=(a101*a077);
  a131=(a131*a083);
  a107=(a101+a131);
  a135=(a135*a076);
  a107=(a107+a135);
  a087=(a087*a107);
  a100=(a100*a087);
  a099=(a099-a100);
  a100=(a067*a099);
  a107=(a135+a101);
  a107=(a000*a107);
  a107=(a090*a107);
  a081=(a081*a087);
  a107=(a107-a081);
  a081=(a032*a107);
  a100=(a100-a081);
  a081=(a068*a083);
  a085=(a085*a076);
  a138=(a081+a085);
  a138=(a000*a138);
  a138=(a077+a138);
  a138=(a090*a138);
  a108=(a108*a087);
  a138=(a138-a108);
  a108=(a029*a138);
  a100=(a100+a108);
  a093=(a093*a100);
  a100=(a071*a099);
  a108=(a036*a107);
  a100=(a100-a108);
  a108=(a034*a138);
  a100=(a100+a108);
  a110=(a110*a100);
  a093=(a093+a110);
  a099=(a060*a099);
  a107=(a025*a107);
  a099=(a099-a107);
  a138=(a021*a138);
  a099=(a099+a138);
  a111=(a111*a099);
  a093=(a093+a111);
  if (res[4]!=0) res[4][0]=a093;
  a080=(a080*a076);
  a068=(a068*a077);
  a093=(a080+a068);
  a093=(a000*a093);
  a093=(a083+a093);
  a093=(a090*a093);
  a091=(a091*a087);
  a093=(a093-a091);
  a091=(a067*a093);
  a085=(a085+a081);
  a085=(a000*a085);
  a085=(a085-a077);
  a085=(a090*a085);
  a094=(a094*a087);
  a085=(a085-a094);
  a094=(a032*a085);
  a091=(a091+a094);
  a101=(a131+a101);
  a101=(a000*a101);
  a101=(a090*a101);
  a096=(a096*a087);
  a101=(a101-a096);
  a096=(a029*a101);
  a091=(a091-a096);
  a105=(a105*a091);
  a091=(a071*a093);
  a096=(a036*a085);
  a091=(a091+a096);
  a096=(a034*a101);
  a091=(a091-a096);
  a117=(a117*a091);
  a105=(a105+a117);
  a093=(a060*a093);
  a085=(a025*a085);
  a093=(a093+a085);
  a101=(a021*a101);
  a093=(a093-a101);
  a118=(a118*a093);
  a105=(a105+a118);
  if (res[4]!=0) res[4][1]=a105;
  a001=(a001+a002);
  a001=(a000*a001);
  a076=(a076+a001);
  a076=(a090*a076);
  a104=(a104*a087);
  a076=(a076-a104);
  a032=(a032*a076);
  a135=(a135+a131);
  a135=(a000*a135);
  a135=(a090*a135);
  a089=(a089*a087);
  a135=(a135-a089);
  a067=(a067*a135);
  a032=(a032-a067);
  a068=(a068+a080);
  a000=(a000*a068);
  a000=(a000-a083);
  a090=(a090*a000);
  a106=(a106*a087);
  a090=(a090-a106);
  a029=(a029*a090);
  a032=(a032+a029);
  a114=(a114*a032);
  a036=(a036*a076);
  a071=(a071*a135);
  a036=(a036-a071);
  a034=(a034*a090);
  a036=(a036+a034);
  a122=(a122*a036);
  a114=(a114+a122);
  a025=(a025*a076);
  a060=(a060*a135);
  a025=(a025-a060);
  a021=(a021*a090);
  a025=(a025+a021);
  a123=(a123*a025);
  a114=(a114+a123);
  if (res[4]!=0) res[4][2]=a114;
  a074=(a074+a004);
  if (res[4]!=0) res[4][3]=a074;
  a127=(a127+a119);
  a127=(a127-a159);
  if (res[4]!=0) res[4][4]=a127;
  a103=(a103-a129);
  a103=(a103+a134);
  if (res[4]!=0) res[4][5]=a103;
  if (res[4]!=0) res[4][6]=a058;
  if (res[4]!=0) res[4][7]=a058;
  if (res[4]!=0) res[4][8]=a058;
  if (res[4]!=0) res[4][9]=a058;
  if (res[4]!=0) res[4][10]=a058;
  if (res[4]!=0) res[4][11]=a058;
  if (res[4]!=0) res[4][12]=a058;
  if (res[4]!=0) res[4][13]=a058;
  if (res[4]!=0) res[4][14]=a058;
  if (res[4]!=0) res[4][15]=a058;
  if (res[4]!=0) res[4][16]=a058;
  if (res[4]!=0) res[4][17]=a058;
  if (res[4]!=0) res[4][18]=a058;
  if (res[4]!=0) res[4][19]=a058;
  if (res[4]!=0) res[4][20]=a058;
  if (res[4]!=0) res[4][21]=a058;
  if (res[4]!=0) res[4][22]=a058;
  if (res[4]!=0) res[4][23]=a058;
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

CASADI_SYMBOL_EXPORT casadi_int step_partials_n_out(void) { return 5;}

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
    case 3: return "FH";
    case 4: return "YH";
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
    case 0: return casadi_s6;
    case 1: return casadi_s6;
    case 2: return casadi_s7;
    case 3: return casadi_s7;
    case 4: return casadi_s8;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int step_partials_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 5;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int step_partials_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 5*sizeof(casadi_real*);
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
/* an open model (forces, control inputs, runtime parameters or t): every h input of the
   kernels is the step vector hv = [h, t_k, u (M), params (P)] (hpgen.abi), which the run
   holds and fills before each step: t_k = t0 + k h, u_k the run's input row k (or its only
   row), params set once (hpgen_run_set_inputs) */
#define HPGEN_M 0
#define HPGEN_P 2
#define HPGEN_H (2 + HPGEN_M + HPGEN_P)
#define HPGEN_OK 0
#define HPGEN_NO_CONVERGENCE 1
#define HPGEN_NONFINITE 2
#define HPGEN_DOMAIN 3
#define HPGEN_RECORD 4
/* the scene's record row (kernel record): its width and what it needs */
#define HPGEN_W 18
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
    double hv[HPGEN_H];              /* the step vector of the current step */
    double t0;                       /* the time of step 0 */
    const double* U;                 /* the input rows (M doubles each; the caller keeps them) */
    long long u_rows;                /* 1: one row for every step; else row k for step k */
} hpgen_run;

HPGEN_EXPORT const char* hpgen_hash(void) { return "959fcb561df343765dbe7a3e98a821542711c856204215f698928b3c81b6b42f"; }

/* out[0..3] = ABI version, n, d, nz */
HPGEN_EXPORT void hpgen_dims(long long* out) {
    out[0] = HPGEN_ABI; out[1] = HPGEN_N; out[2] = HPGEN_D; out[3] = HPGEN_NZ;
}

/* ---- kernel wrappers: dense column-major arguments, CasADi work arrays on the stack ---- */
static int hpgen_k_residual(const double* in0, const double* in1, const double* in2, const double* in3, double* out0);
static int hpgen_k_residual_jacobian(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1);
static int hpgen_k_update(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1);
static int hpgen_k_guess(const double* in0, const double* in1, const double* in2, const double* in3, double* out0);
static int hpgen_k_legendre(const double* in0, const double* in1, const double* in2, double* out0);
static int hpgen_k_hessian(const double* in0, const double* in1, const double* in2, double* out0);
static int hpgen_k_energy(const double* in0, const double* in1, const double* in2, double* out0);
static int hpgen_k_momentum(const double* in0, const double* in1, double* out0);
static int hpgen_k_defect(const double* in0, double* out0);
static int hpgen_k_margin(const double* in0, const double* in1, double* out0);
static int hpgen_k_section(const double* in0, const double* in1, double* out0);
static int hpgen_k_chart_point(const double* in0, const double* in1, const double* in2, const double* in3, double* out0);
static int hpgen_k_observe(const double* in0, const double* in1, const double* in2, double* out0, double* out1, double* out2, double* out3);
static int hpgen_k_update_p(const double* in0, const double* in1, const double* in2, const double* in3, double* out0);
static int hpgen_k_velocity_step(const double* in0, const double* in1, const double* in2, const double* in3, double* out0);
static int hpgen_k_record(const double* in0, const double* in1, const double* in2, const double* in3, double* out0);
static int hpgen_k_step_partials(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1, double* out2, double* out3, double* out4);

/* residual(z[9], g[9], p[3], h[4]) -> (F[9]) */
#define HPGEN_RESIDUAL_SZ_ARG 4
#define HPGEN_RESIDUAL_SZ_RES 1
#define HPGEN_RESIDUAL_SZ_IW 0
#define HPGEN_RESIDUAL_SZ_W 80
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

/* jacobian(z[9], g[9], p[3], h[4]) -> (J[81]) */
/* = output 1 of residual_jacobian (the same CasADi algorithm; its other outputs are
   computed into scratch and dropped) */
HPGEN_EXPORT int hpgen_kernel_jacobian(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    double scratch[HPGEN_NZ];
    return hpgen_k_residual_jacobian(in0, in1, in2, in3, scratch, out0);
}

/* residual_jacobian(z[9], g[9], p[3], h[4]) -> (F[9], J[81]) */
#define HPGEN_RESIDUAL_JACOBIAN_SZ_ARG 4
#define HPGEN_RESIDUAL_JACOBIAN_SZ_RES 2
#define HPGEN_RESIDUAL_JACOBIAN_SZ_IW 0
#define HPGEN_RESIDUAL_JACOBIAN_SZ_W 182
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

/* update(z[9], g[9], p[3], h[4]) -> (g1[9], p1[3]) */
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

/* guess(xi[3], g[9], p[3], h[4]) -> (z0[9]) */
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

/* legendre(g[9], xi[3], h[4]) -> (mu[3]) */
#define HPGEN_LEGENDRE_SZ_ARG 3
#define HPGEN_LEGENDRE_SZ_RES 1
#define HPGEN_LEGENDRE_SZ_IW 0
#define HPGEN_LEGENDRE_SZ_W 2
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_legendre exports it */
static int hpgen_k_legendre(const double* in0, const double* in1, const double* in2, double* out0) {
    const casadi_real* arg[HPGEN_LEGENDRE_SZ_ARG + 1];
    casadi_real* res[HPGEN_LEGENDRE_SZ_RES + 1];
    casadi_int iw[HPGEN_LEGENDRE_SZ_IW + 1];
    casadi_real w[HPGEN_LEGENDRE_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    res[0] = out0;
    flag = legendre(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_legendre(const double* in0, const double* in1, const double* in2, double* out0) {
    return hpgen_k_legendre(in0, in1, in2, out0);
}

/* hessian(g[9], xi[3], h[4]) -> (H[9]) */
#define HPGEN_HESSIAN_SZ_ARG 3
#define HPGEN_HESSIAN_SZ_RES 1
#define HPGEN_HESSIAN_SZ_IW 0
#define HPGEN_HESSIAN_SZ_W 2
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_hessian exports it */
static int hpgen_k_hessian(const double* in0, const double* in1, const double* in2, double* out0) {
    const casadi_real* arg[HPGEN_HESSIAN_SZ_ARG + 1];
    casadi_real* res[HPGEN_HESSIAN_SZ_RES + 1];
    casadi_int iw[HPGEN_HESSIAN_SZ_IW + 1];
    casadi_real w[HPGEN_HESSIAN_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    res[0] = out0;
    flag = hessian(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_hessian(const double* in0, const double* in1, const double* in2, double* out0) {
    return hpgen_k_hessian(in0, in1, in2, out0);
}

/* energy(g[9], xi[3], h[4]) -> (E[1]) */
#define HPGEN_ENERGY_SZ_ARG 3
#define HPGEN_ENERGY_SZ_RES 1
#define HPGEN_ENERGY_SZ_IW 0
#define HPGEN_ENERGY_SZ_W 5
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_energy exports it */
static int hpgen_k_energy(const double* in0, const double* in1, const double* in2, double* out0) {
    const casadi_real* arg[HPGEN_ENERGY_SZ_ARG + 1];
    casadi_real* res[HPGEN_ENERGY_SZ_RES + 1];
    casadi_int iw[HPGEN_ENERGY_SZ_IW + 1];
    casadi_real w[HPGEN_ENERGY_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    res[0] = out0;
    flag = energy(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_energy(const double* in0, const double* in1, const double* in2, double* out0) {
    return hpgen_k_energy(in0, in1, in2, out0);
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

/* margin(z[9], h[4]) -> (m[1]) */
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

/* chart_point(z[9], g[9], h[4], theta[1]) -> (g_theta[9]) */
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

/* observe(g[9], p[3], h[4]) -> (xi[3], E[1], m[3], e[1]) */
#define HPGEN_OBSERVE_SZ_ARG 3
#define HPGEN_OBSERVE_SZ_RES 4
#define HPGEN_OBSERVE_SZ_IW 0
#define HPGEN_OBSERVE_SZ_W 18
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_observe exports it */
static int hpgen_k_observe(const double* in0, const double* in1, const double* in2, double* out0, double* out1, double* out2, double* out3) {
    const casadi_real* arg[HPGEN_OBSERVE_SZ_ARG + 1];
    casadi_real* res[HPGEN_OBSERVE_SZ_RES + 1];
    casadi_int iw[HPGEN_OBSERVE_SZ_IW + 1];
    casadi_real w[HPGEN_OBSERVE_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    res[0] = out0;
    res[1] = out1;
    res[2] = out2;
    res[3] = out3;
    flag = observe(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_observe(const double* in0, const double* in1, const double* in2, double* out0, double* out1, double* out2, double* out3) {
    return hpgen_k_observe(in0, in1, in2, out0, out1, out2, out3);
}

/* update_p(z[9], g[9], p[3], h[4]) -> (p1[3]) */
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

/* velocity_step(g[9], p[3], xi[3], h[4]) -> (xi1[3]) */
#define HPGEN_VELOCITY_STEP_SZ_ARG 4
#define HPGEN_VELOCITY_STEP_SZ_RES 1
#define HPGEN_VELOCITY_STEP_SZ_IW 0
#define HPGEN_VELOCITY_STEP_SZ_W 4
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_velocity_step exports it */
static int hpgen_k_velocity_step(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    const casadi_real* arg[HPGEN_VELOCITY_STEP_SZ_ARG + 1];
    casadi_real* res[HPGEN_VELOCITY_STEP_SZ_RES + 1];
    casadi_int iw[HPGEN_VELOCITY_STEP_SZ_IW + 1];
    casadi_real w[HPGEN_VELOCITY_STEP_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    arg[3] = in3;
    res[0] = out0;
    flag = velocity_step(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_velocity_step(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    return hpgen_k_velocity_step(in0, in1, in2, in3, out0);
}

/* record(g[9], p[3], xi[3], h[4]) -> (row[18]) */
#define HPGEN_RECORD_SZ_ARG 4
#define HPGEN_RECORD_SZ_RES 1
#define HPGEN_RECORD_SZ_IW 0
#define HPGEN_RECORD_SZ_W 23
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_record exports it */
static int hpgen_k_record(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    const casadi_real* arg[HPGEN_RECORD_SZ_ARG + 1];
    casadi_real* res[HPGEN_RECORD_SZ_RES + 1];
    casadi_int iw[HPGEN_RECORD_SZ_IW + 1];
    casadi_real w[HPGEN_RECORD_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    arg[3] = in3;
    res[0] = out0;
    flag = record(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_record(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    return hpgen_k_record(in0, in1, in2, in3, out0);
}

/* step_partials(z[9], g[9], p[3], h[4]) -> (Fs[54], Yz[54], Ys[36], FH[36], YH[24]) */
#define HPGEN_STEP_PARTIALS_SZ_ARG 4
#define HPGEN_STEP_PARTIALS_SZ_RES 5
#define HPGEN_STEP_PARTIALS_SZ_IW 0
#define HPGEN_STEP_PARTIALS_SZ_W 181
/* the step calls this static body (inlinable: an exported symbol in a -fPIC library can be
   interposed, so calls to it are never inlined); hpgen_kernel_step_partials exports it */
static int hpgen_k_step_partials(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1, double* out2, double* out3, double* out4) {
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
    res[4] = out4;
    flag = step_partials(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

HPGEN_EXPORT int hpgen_kernel_step_partials(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1, double* out2, double* out3, double* out4) {
    return hpgen_k_step_partials(in0, in1, in2, in3, out0, out1, out2, out3, out4);
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
/* (open model: hv is the step vector [h, t, u, params] of the step) */
HPGEN_EXPORT int hpgen_step(const double* g, const double* p, const double* hv, double* z,
                            const hpgen_options* o, double* g1, double* p1, hpgen_status* st) {
    double lu[HPGEN_NZ * HPGEN_NZ];
    int piv[HPGEN_NZ];
    long long it, valid = 0;
    double r;
    int code;
    hpgen_status_init(st);
    if (!hpgen_options_ok(o)) { st->code = HPGEN_INVALID; return HPGEN_INVALID; }
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

/* An open run's inputs: start time t0, input rows U (u_rows of M doubles: 1 = the same row
   for every step, else row k for step k; the caller keeps U alive while the run steps) and
   the P runtime parameters. A run must have them before its first step. */
HPGEN_EXPORT void hpgen_run_set_inputs(hpgen_run* r, double t0, const double* U,
                                       long long u_rows, const double* params) {
    int i;
    r->t0 = t0;
    r->U = U;
    r->u_rows = u_rows;
    for (i = 0; i < HPGEN_P; ++i) r->hv[2 + HPGEN_M + i] = params[i];
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
    hpgen_k_velocity_step(g, p, x0, hv, xi);
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
    /* the step vector of step k: [h, t0 + k h, u_k, params] */
    if (r->u_rows < 1 || (r->u_rows > 1 && r->k >= r->u_rows)) {
        st->code = HPGEN_INVALID; st->step = r->k; return HPGEN_INVALID;
    }
    r->hv[0] = hv[0];
    r->hv[1] = r->t0 + (double)r->k * hv[0];
    for (i = 0; i < HPGEN_M; ++i) r->hv[2 + i] = r->U[(r->u_rows == 1 ? 0 : r->k) * HPGEN_M + i];
    hv = r->hv;
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
            if (hpgen_k_chart_point(r->z, g0, r->hv, th, g_rec + j * HPGEN_NN)) {
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
static int hpgen_velocity(const double* g, const double* p, double* xi, const double* hv) {
    double x1[HPGEN_D], dprev = HUGE_VAL;
    int i, it;
    for (i = 0; i < HPGEN_D; ++i) xi[i] = 0.0;
    for (it = 1; it <= 50; ++it) {
        double dn = 0.0, xn;
        if (hpgen_k_velocity_step(g, p, xi, hv, x1) || !hpgen_all_finite(x1, HPGEN_D))
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
static int hpgen_record_row(const double* g, const double* p, double* row, const double* hv) {
    double xi[HPGEN_D];
#if HPGEN_RECORD_USES_XI
    if (hpgen_velocity(g, p, xi, hv) != HPGEN_OK) {
        int i;
        for (i = 0; i < HPGEN_W; ++i) row[i] = NAN;
        return HPGEN_RECORD;
    }
#else
    memset(xi, 0, sizeof xi);
#endif
    if (hpgen_k_record(g, p, xi, hv, row) || !hpgen_all_finite(row, HPGEN_W)) return HPGEN_RECORD;
    return HPGEN_OK;
}

/* The record row at (g, p) (the start of a run: record 0). Returns the status code. */
/* (open model: hv is the step vector at the record's time, [h, t, u, params]) */
HPGEN_EXPORT int hpgen_record(const double* g, const double* p, double* row, const double* hv) {
    return hpgen_record_row(g, p, row, hv);
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
            r->hv[1] = r->t0 + (double)r->k * h;      /* the record's time */
            if (hpgen_record_row(r->g, r->p, row, r->hv) != HPGEN_OK) {
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
   at A + k 4 D^2. Open module: step k's step vector is hv_rec + k H, and with the
   step vector's partials (FH, YH) also B_k = YH_c - Yz J^{-1} FH_c over the step vector's
   columns c = c0 .. c0 + nc - 1 (the inputs or the runtime parameters), 2D x nc
   column-major at B + k 2 D nc. Returns the steps done (K, or the failing step with
   st->code set). */
HPGEN_EXPORT long long hpgen_linearize(long long K, const double* g_rec, const double* p_rec,
                                       const double* hv_rec, long long c0, long long nc,
                                       double* z, const hpgen_options* o, double* A,
                                       double* B, double* dev, hpgen_status* st) {
    enum { S = 2 * HPGEN_D };
    double g1[HPGEN_NN], p1[HPGEN_D], J[HPGEN_NZ * HPGEN_NZ], Fs[HPGEN_NZ * S],
        Yz[S * HPGEN_NZ], Ys[S * S], FH[HPGEN_NZ * HPGEN_H], YH[S * HPGEN_H],
        zlast[HPGEN_NZ], zprev[HPGEN_NZ] = {0.0}, zprev2[HPGEN_NZ] = {0.0}, res;
    int piv[HPGEN_NZ];
    long long k, it, valid = 0;
    int i, j, l, code;
    hpgen_options full;
    hpgen_status_init(st);
    if (K < 0 || c0 < 2 || nc < 0 || c0 + nc > HPGEN_H || !hpgen_options_ok(o)) {
        st->code = HPGEN_INVALID; return 0;
    }
    full = *o;
    full.simplified = 0;
    for (k = 0; k < K; ++k) {
        const double* g = g_rec + k * HPGEN_NN;
        const double* p = p_rec + k * HPGEN_D;
        const double* hv = hv_rec + k * HPGEN_H;
        double* Bk = B + k * S * nc;
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
        if (hpgen_kernel_jacobian(z, g, p, hv, J)
            || hpgen_k_step_partials(z, g, p, hv, Fs, Yz, Ys, FH, YH)
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
        for (j = 0; j < nc; ++j) {
            double* f = FH + (c0 + j) * HPGEN_NZ;
            hpgen_lu_apply(J, piv, f);
            for (i = 0; i < S; ++i) {
                double a = YH[i + (c0 + j) * S];
                for (l = 0; l < HPGEN_NZ; ++l) a -= Yz[i + l * S] * f[l];
                Bk[i + j * S] = a;
            }
        }
        if (!hpgen_all_finite(Bk, S * nc)) { st->code = HPGEN_NONFINITE; st->step = k; return k; }
        memcpy(zprev2, zprev, sizeof zprev);
        memcpy(zprev, zlast, sizeof zprev);
    }
    st->step = K;
    return K;
}
