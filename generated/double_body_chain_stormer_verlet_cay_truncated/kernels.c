/*
 * hpgen generated module double_body_chain_stormer_verlet_cay_truncated -- do not edit, regenerate with hpgen
 * model: double_body_chain
 * options: tableau=stormer-verlet, tau=cay, rkmk=truncated
 * hpgen version: 0.1.0
 * content hash: 05c0c407c549797f48db77cd1c626e9d8eb5077bed9e5a668c9c48c84019522d
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
CASADI_SYMBOL_EXPORT void hpgen_double_body_chain_stormer_verlet_cay_truncated__casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int hpgen_double_body_chain_stormer_verlet_cay_truncated__casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int hpgen_double_body_chain_stormer_verlet_cay_truncated__casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {30, 1, 1};
static const casadi_int casadi_s1[3] = {36, 1, 1};
static const casadi_int casadi_s2[3] = {6, 1, 1};
static const casadi_int casadi_s3[3] = {1, 1, 1};
static const casadi_int casadi_s4[3] = {900, 1, 1};

/* residual:(z[30],g[36],p[6],h)->(F[30]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73, a74, a75, a76, a77, a78, a79, a80, a81, a82, a83;
  casadi_real a84, a85, a86, a87, a88, a89, a90, a91, a92, a93, a94, a95;
  casadi_real a96;
  a00=arg[0]? arg[0][0] : 0;
  a01=(2.*a00);
  a02=2.2500000000000001e-01;
  a03=arg[3]? arg[3][0] : 0;
  a02=(a02*a03);
  a01=(a01*a02);
  a04=5.0000000000000000e-01;
  a05=arg[0]? arg[0][24] : 0;
  a06=(a03*a05);
  a06=(a04*a06);
  a07=arg[0]? arg[0][18] : 0;
  a07=(a03*a07);
  a08=(a03*a07);
  a08=(a04*a08);
  a06=(a06+a08);
  a01=(a01-a06);
  a08=(a04*a03);
  a01=(a01/a08);
  if (res[0]!=0) res[0][0]=a01;
  a01=arg[0]? arg[0][1] : 0;
  a09=(2.*a01);
  a10=2.5000000000000000e-01;
  a10=(a10*a03);
  a09=(a09*a10);
  a11=arg[0]? arg[0][25] : 0;
  a12=(a03*a11);
  a12=(a04*a12);
  a13=arg[0]? arg[0][19] : 0;
  a13=(a03*a13);
  a14=(a03*a13);
  a14=(a04*a14);
  a12=(a12+a14);
  a09=(a09-a12);
  a09=(a09/a08);
  if (res[0]!=0) res[0][1]=a09;
  a09=arg[0]? arg[0][2] : 0;
  a14=(2.*a09);
  a15=5.0000000000000003e-02;
  a16=(a15*a03);
  a14=(a14*a16);
  a17=arg[0]? arg[0][26] : 0;
  a18=(a03*a17);
  a18=(a04*a18);
  a19=arg[0]? arg[0][20] : 0;
  a19=(a03*a19);
  a20=(a03*a19);
  a20=(a04*a20);
  a18=(a18+a20);
  a14=(a14-a18);
  a14=(a14/a08);
  if (res[0]!=0) res[0][2]=a14;
  a14=arg[0]? arg[0][3] : 0;
  a20=(2.*a14);
  a21=1.4999999999999999e-01;
  a21=(a21*a03);
  a20=(a20*a21);
  a22=arg[0]? arg[0][27] : 0;
  a23=(a03*a22);
  a23=(a04*a23);
  a24=arg[0]? arg[0][21] : 0;
  a24=(a03*a24);
  a25=(a03*a24);
  a25=(a04*a25);
  a23=(a23+a25);
  a20=(a20-a23);
  a20=(a20/a08);
  if (res[0]!=0) res[0][3]=a20;
  a20=arg[0]? arg[0][4] : 0;
  a25=(2.*a20);
  a26=1.2500000000000000e-01;
  a26=(a26*a03);
  a25=(a25*a26);
  a27=arg[0]? arg[0][28] : 0;
  a28=(a03*a27);
  a28=(a04*a28);
  a29=arg[0]? arg[0][22] : 0;
  a29=(a03*a29);
  a30=(a03*a29);
  a30=(a04*a30);
  a28=(a28+a30);
  a25=(a25-a28);
  a25=(a25/a08);
  if (res[0]!=0) res[0][4]=a25;
  a25=arg[0]? arg[0][5] : 0;
  a30=(2.*a25);
  a31=3.7499999999999999e-02;
  a31=(a31*a03);
  a30=(a30*a31);
  a32=arg[0]? arg[0][29] : 0;
  a33=(a03*a32);
  a33=(a04*a33);
  a34=arg[0]? arg[0][23] : 0;
  a34=(a03*a34);
  a35=(a03*a34);
  a35=(a04*a35);
  a33=(a33+a35);
  a30=(a30-a33);
  a30=(a30/a08);
  if (res[0]!=0) res[0][5]=a30;
  a30=arg[0]? arg[0][6] : 0;
  a35=(2.*a30);
  a35=(a35*a02);
  a35=(a35-a06);
  a35=(a35/a08);
  if (res[0]!=0) res[0][6]=a35;
  a35=arg[0]? arg[0][7] : 0;
  a06=(2.*a35);
  a06=(a06*a10);
  a06=(a06-a12);
  a06=(a06/a08);
  if (res[0]!=0) res[0][7]=a06;
  a06=arg[0]? arg[0][8] : 0;
  a12=(2.*a06);
  a12=(a12*a16);
  a12=(a12-a18);
  a12=(a12/a08);
  if (res[0]!=0) res[0][8]=a12;
  a12=arg[0]? arg[0][9] : 0;
  a18=(2.*a12);
  a18=(a18*a21);
  a18=(a18-a23);
  a18=(a18/a08);
  if (res[0]!=0) res[0][9]=a18;
  a18=arg[0]? arg[0][10] : 0;
  a23=(2.*a18);
  a23=(a23*a26);
  a23=(a23-a28);
  a23=(a23/a08);
  if (res[0]!=0) res[0][10]=a23;
  a23=arg[0]? arg[0][11] : 0;
  a28=(2.*a23);
  a28=(a28*a31);
  a28=(a28-a33);
  a28=(a28/a08);
  if (res[0]!=0) res[0][11]=a28;
  a28=arg[0]? arg[0][12] : 0;
  a28=(a03*a28);
  a33=arg[1]? arg[1][14] : 0;
  a31=1.3000000000000000e+00;
  a26=arg[1]? arg[1][8] : 0;
  a21=(a15*a26);
  a21=(a31+a21);
  a16=1.0000000000000001e-01;
  a10=arg[1]? arg[1][2] : 0;
  a02=(a16*a10);
  a21=(a21+a02);
  a21=(a21-a33);
  a02=-1.0000000000000001e-01;
  a36=arg[1]? arg[1][29] : 0;
  a37=(a02*a36);
  a21=(a21+a37);
  a37=-2.9999999999999999e-01;
  a38=arg[1]? arg[1][35] : 0;
  a39=(a37*a38);
  a21=(a21+a39);
  a21=(2.*a21);
  a21=(a21*a03);
  a39=(a15*a21);
  a40=(a33*a39);
  a40=(a28-a40);
  a41=arg[1]? arg[1][7] : 0;
  a42=(a15*a41);
  a43=arg[1]? arg[1][1] : 0;
  a44=(a16*a43);
  a42=(a42+a44);
  a44=arg[1]? arg[1][13] : 0;
  a42=(a42-a44);
  a45=arg[1]? arg[1][28] : 0;
  a46=(a02*a45);
  a42=(a42+a46);
  a46=arg[1]? arg[1][34] : 0;
  a47=(a37*a46);
  a42=(a42+a47);
  a42=(2.*a42);
  a42=(a42*a03);
  a47=(a41*a42);
  a40=(a40-a47);
  a47=(a15*a42);
  a48=(a44*a47);
  a40=(a40-a48);
  a48=arg[1]? arg[1][6] : 0;
  a49=(a15*a48);
  a50=arg[1]? arg[1][0] : 0;
  a51=(a16*a50);
  a49=(a49+a51);
  a51=arg[1]? arg[1][12] : 0;
  a49=(a49-a51);
  a52=arg[1]? arg[1][27] : 0;
  a53=(a02*a52);
  a49=(a49+a53);
  a53=arg[1]? arg[1][33] : 0;
  a54=(a37*a53);
  a49=(a49+a54);
  a49=(2.*a49);
  a49=(a49*a03);
  a54=(a48*a49);
  a40=(a40-a54);
  a54=(a15*a49);
  a55=(a51*a54);
  a40=(a40-a55);
  a55=(a21+a08);
  a56=(a26*a55);
  a40=(a40-a56);
  a40=(a40/a03);
  if (res[0]!=0) res[0][12]=a40;
  a40=arg[0]? arg[0][13] : 0;
  a40=(a03*a40);
  a56=-5.0000000000000003e-02;
  a56=(a56*a03);
  a57=(a16*a21);
  a57=(a56-a57);
  a58=(a33*a57);
  a58=(a40-a58);
  a59=(a43*a42);
  a58=(a58+a59);
  a59=(a16*a42);
  a60=(a44*a59);
  a58=(a58+a60);
  a60=(a50*a49);
  a58=(a58+a60);
  a60=(a16*a49);
  a61=(a51*a60);
  a58=(a58+a61);
  a55=(a10*a55);
  a58=(a58+a55);
  a58=(a58/a03);
  if (res[0]!=0) res[0][13]=a58;
  a58=arg[0]? arg[0][14] : 0;
  a58=(a03*a58);
  a57=(a26*a57);
  a57=(a58+a57);
  a39=(a10*a39);
  a57=(a57+a39);
  a59=(a41*a59);
  a57=(a57-a59);
  a47=(a43*a47);
  a57=(a57+a47);
  a60=(a48*a60);
  a57=(a57-a60);
  a54=(a50*a54);
  a57=(a57+a54);
  a57=(a57/a03);
  if (res[0]!=0) res[0][14]=a57;
  a57=arg[0]? arg[0][15] : 0;
  a57=(a03*a57);
  a54=-2.9999999999999999e-02;
  a54=(a54*a03);
  a60=(a02*a21);
  a60=(a54-a60);
  a47=(a38*a60);
  a47=(a57+a47);
  a59=(a37*a42);
  a39=(a45*a59);
  a47=(a47+a39);
  a42=(a02*a42);
  a39=(a46*a42);
  a47=(a47-a39);
  a39=(a37*a49);
  a55=(a52*a39);
  a47=(a47+a55);
  a49=(a02*a49);
  a55=(a53*a49);
  a47=(a47-a55);
  a55=3.0000000000000004e-01;
  a55=(a55*a03);
  a21=(a37*a21);
  a21=(a55-a21);
  a61=(a36*a21);
  a47=(a47-a61);
  a47=(a47/a03);
  if (res[0]!=0) res[0][15]=a47;
  a47=arg[0]? arg[0][16] : 0;
  a47=(a03*a47);
  a61=arg[1]? arg[1][22] : 0;
  a59=(a61*a59);
  a59=(a47-a59);
  a62=arg[1]? arg[1][21] : 0;
  a39=(a62*a39);
  a59=(a59-a39);
  a39=arg[1]? arg[1][23] : 0;
  a21=(a39*a21);
  a59=(a59+a21);
  a59=(a59/a03);
  if (res[0]!=0) res[0][16]=a59;
  a59=arg[0]? arg[0][17] : 0;
  a59=(a03*a59);
  a60=(a39*a60);
  a60=(a59-a60);
  a42=(a61*a42);
  a60=(a60+a42);
  a49=(a62*a49);
  a60=(a60+a49);
  a60=(a60/a03);
  if (res[0]!=0) res[0][17]=a60;
  a09=(a04*a09);
  a06=(a04*a06);
  a09=(a09+a06);
  a09=(a03*a09);
  a00=(a04*a00);
  a30=(a04*a30);
  a00=(a00+a30);
  a00=(a03*a00);
  a30=(a09*a00);
  a06=4.;
  a60=(a30/a06);
  a01=(a04*a01);
  a35=(a04*a35);
  a01=(a01+a35);
  a01=(a03*a01);
  a35=2.;
  a49=(a01/a35);
  a42=(a60-a49);
  a42=(a42*a19);
  a21=(a09/a35);
  a63=(a01*a00);
  a64=(a63/a06);
  a65=(a21+a64);
  a65=(a65*a13);
  a42=(a42+a65);
  a65=1.;
  a66=casadi_sq(a00);
  a67=(a66/a06);
  a67=(a65+a67);
  a68=(a67*a07);
  a42=(a42+a68);
  a69=casadi_sq(a01);
  a70=(a66+a69);
  a71=casadi_sq(a09);
  a70=(a70+a71);
  a70=(a06+a70);
  a70=(a06/a70);
  a30=(a30/a35);
  a30=(a01+a30);
  a30=(a70*a30);
  a72=(a10*a30);
  a73=(a09*a01);
  a74=(a73/a35);
  a74=(a74-a00);
  a74=(a70*a74);
  a75=(a26*a74);
  a72=(a72+a75);
  a75=(a69+a66);
  a75=(a75/a35);
  a75=(a70*a75);
  a75=(a65-a75);
  a76=(a33*a75);
  a72=(a72+a76);
  a63=(a63/a35);
  a63=(a63-a09);
  a63=(a70*a63);
  a76=(a10*a63);
  a66=(a71+a66);
  a66=(a66/a35);
  a66=(a70*a66);
  a66=(a65-a66);
  a77=(a26*a66);
  a76=(a76+a77);
  a77=(a01*a09);
  a78=(a77/a35);
  a78=(a00+a78);
  a78=(a70*a78);
  a79=(a33*a78);
  a76=(a76+a79);
  a79=(a15*a76);
  a31=(a31+a79);
  a79=(a71+a69);
  a79=(a79/a35);
  a79=(a70*a79);
  a79=(a65-a79);
  a10=(a10*a79);
  a80=(a00*a01);
  a81=(a80/a35);
  a81=(a09+a81);
  a81=(a70*a81);
  a26=(a26*a81);
  a10=(a10+a26);
  a09=(a00*a09);
  a26=(a09/a35);
  a26=(a26-a01);
  a70=(a70*a26);
  a33=(a33*a70);
  a10=(a10+a33);
  a33=(a16*a10);
  a31=(a31+a33);
  a31=(a31-a72);
  a14=(a04*a14);
  a12=(a04*a12);
  a14=(a14+a12);
  a14=(a03*a14);
  a12=casadi_sq(a14);
  a20=(a04*a20);
  a18=(a04*a18);
  a20=(a20+a18);
  a20=(a03*a20);
  a18=casadi_sq(a20);
  a33=(a12+a18);
  a25=(a04*a25);
  a04=(a04*a23);
  a25=(a25+a04);
  a25=(a03*a25);
  a04=casadi_sq(a25);
  a33=(a33+a04);
  a33=(a06+a33);
  a33=(a06/a33);
  a23=(a20*a14);
  a26=(a23/a35);
  a26=(a26-a25);
  a26=(a33*a26);
  a01=(a39*a26);
  a82=(a04+a12);
  a82=(a82/a35);
  a82=(a33*a82);
  a82=(a65-a82);
  a83=(a36*a82);
  a01=(a01+a83);
  a83=(a20*a25);
  a84=(a83/a35);
  a84=(a14+a84);
  a84=(a33*a84);
  a85=(a38*a84);
  a01=(a01+a85);
  a85=(a02*a01);
  a31=(a31+a85);
  a85=(a25*a14);
  a86=(a85/a35);
  a86=(a20+a86);
  a86=(a33*a86);
  a87=(a39*a86);
  a88=(a25*a20);
  a89=(a88/a35);
  a89=(a89-a14);
  a89=(a33*a89);
  a90=(a36*a89);
  a87=(a87+a90);
  a90=(a18+a12);
  a90=(a90/a35);
  a90=(a33*a90);
  a90=(a65-a90);
  a91=(a38*a90);
  a87=(a87+a91);
  a91=(a37*a87);
  a31=(a31+a91);
  a31=(2.*a31);
  a31=(a31*a03);
  a91=(a15*a31);
  a92=(a72*a91);
  a42=(a42-a92);
  a92=(a43*a63);
  a93=(a41*a66);
  a92=(a92+a93);
  a93=(a44*a78);
  a92=(a92+a93);
  a93=(a15*a92);
  a94=(a43*a79);
  a95=(a41*a81);
  a94=(a94+a95);
  a95=(a44*a70);
  a94=(a94+a95);
  a95=(a16*a94);
  a93=(a93+a95);
  a43=(a43*a30);
  a41=(a41*a74);
  a43=(a43+a41);
  a44=(a44*a75);
  a43=(a43+a44);
  a93=(a93-a43);
  a44=(a61*a26);
  a41=(a45*a82);
  a44=(a44+a41);
  a41=(a46*a84);
  a44=(a44+a41);
  a41=(a02*a44);
  a93=(a93+a41);
  a41=(a61*a86);
  a95=(a45*a89);
  a41=(a41+a95);
  a95=(a46*a90);
  a41=(a41+a95);
  a95=(a37*a41);
  a93=(a93+a95);
  a93=(2.*a93);
  a93=(a93*a03);
  a95=(a92*a93);
  a42=(a42-a95);
  a95=(a15*a93);
  a96=(a43*a95);
  a42=(a42-a96);
  a63=(a50*a63);
  a66=(a48*a66);
  a63=(a63+a66);
  a78=(a51*a78);
  a63=(a63+a78);
  a78=(a15*a63);
  a79=(a50*a79);
  a81=(a48*a81);
  a79=(a79+a81);
  a70=(a51*a70);
  a79=(a79+a70);
  a70=(a16*a79);
  a78=(a78+a70);
  a50=(a50*a30);
  a48=(a48*a74);
  a50=(a50+a48);
  a51=(a51*a75);
  a50=(a50+a51);
  a78=(a78-a50);
  a26=(a62*a26);
  a82=(a52*a82);
  a26=(a26+a82);
  a84=(a53*a84);
  a26=(a26+a84);
  a84=(a02*a26);
  a78=(a78+a84);
  a86=(a62*a86);
  a89=(a52*a89);
  a86=(a86+a89);
  a90=(a53*a90);
  a86=(a86+a90);
  a90=(a37*a86);
  a78=(a78+a90);
  a78=(2.*a78);
  a78=(a78*a03);
  a90=(a63*a78);
  a42=(a42-a90);
  a15=(a15*a78);
  a90=(a50*a15);
  a42=(a42-a90);
  a08=(a31+a08);
  a90=(a76*a08);
  a42=(a42-a90);
  a42=(a42/a03);
  if (res[0]!=0) res[0][18]=a42;
  a00=(a00/a35);
  a73=(a73/a06);
  a42=(a00+a73);
  a42=(a42*a19);
  a69=(a69/a06);
  a69=(a65+a69);
  a90=(a69*a13);
  a42=(a42+a90);
  a80=(a80/a06);
  a89=(a80-a21);
  a89=(a89*a07);
  a42=(a42+a89);
  a89=(a16*a31);
  a56=(a56-a89);
  a72=(a72*a56);
  a42=(a42-a72);
  a72=(a94*a93);
  a42=(a42+a72);
  a72=(a16*a93);
  a43=(a43*a72);
  a42=(a42+a43);
  a43=(a79*a78);
  a42=(a42+a43);
  a16=(a16*a78);
  a50=(a50*a16);
  a42=(a42+a50);
  a08=(a10*a08);
  a42=(a42+a08);
  a42=(a42/a03);
  if (res[0]!=0) res[0][19]=a42;
  a71=(a71/a06);
  a71=(a65+a71);
  a42=(a71*a19);
  a77=(a77/a06);
  a08=(a77-a00);
  a08=(a08*a13);
  a08=(a42+a08);
  a09=(a09/a06);
  a50=(a49+a09);
  a50=(a50*a07);
  a08=(a08+a50);
  a76=(a76*a56);
  a08=(a08+a76);
  a10=(a10*a91);
  a08=(a08+a10);
  a92=(a92*a72);
  a08=(a08-a92);
  a94=(a94*a95);
  a08=(a08+a94);
  a63=(a63*a16);
  a08=(a08-a63);
  a79=(a79*a15);
  a08=(a08+a79);
  a08=(a08/a03);
  if (res[0]!=0) res[0][20]=a08;
  a85=(a85/a06);
  a08=(a20/a35);
  a79=(a85-a08);
  a79=(a79*a34);
  a15=(a25/a35);
  a23=(a23/a06);
  a63=(a15+a23);
  a63=(a63*a29);
  a79=(a79+a63);
  a12=(a12/a06);
  a12=(a65+a12);
  a63=(a12*a24);
  a79=(a79+a63);
  a16=(a02*a31);
  a54=(a54-a16);
  a87=(a87*a54);
  a79=(a79+a87);
  a87=(a37*a93);
  a44=(a44*a87);
  a79=(a79+a44);
  a93=(a02*a93);
  a41=(a41*a93);
  a79=(a79-a41);
  a41=(a37*a78);
  a26=(a26*a41);
  a79=(a79+a26);
  a02=(a02*a78);
  a86=(a86*a02);
  a79=(a79-a86);
  a37=(a37*a31);
  a55=(a55-a37);
  a01=(a01*a55);
  a79=(a79-a01);
  a79=(a79/a03);
  if (res[0]!=0) res[0][21]=a79;
  a79=(a14/a35);
  a88=(a88/a06);
  a01=(a79+a88);
  a01=(a01*a34);
  a37=(a18/a06);
  a37=(a65+a37);
  a31=(a37*a29);
  a01=(a01+a31);
  a86=(a14*a20);
  a78=(a86/a06);
  a26=(a78-a15);
  a26=(a26*a24);
  a01=(a01+a26);
  a18=(a04+a18);
  a18=(a18/a35);
  a18=(a33*a18);
  a18=(a65-a18);
  a61=(a61*a18);
  a86=(a86/a35);
  a86=(a25+a86);
  a86=(a33*a86);
  a45=(a45*a86);
  a61=(a61+a45);
  a14=(a14*a25);
  a35=(a14/a35);
  a35=(a35-a20);
  a33=(a33*a35);
  a46=(a46*a33);
  a61=(a61+a46);
  a87=(a61*a87);
  a01=(a01-a87);
  a62=(a62*a18);
  a52=(a52*a86);
  a62=(a62+a52);
  a53=(a53*a33);
  a62=(a62+a53);
  a41=(a62*a41);
  a01=(a01-a41);
  a39=(a39*a18);
  a36=(a36*a86);
  a39=(a39+a36);
  a38=(a38*a33);
  a39=(a39+a38);
  a55=(a39*a55);
  a01=(a01+a55);
  a01=(a01/a03);
  if (res[0]!=0) res[0][22]=a01;
  a04=(a04/a06);
  a65=(a65+a04);
  a04=(a65*a34);
  a83=(a83/a06);
  a01=(a83-a79);
  a01=(a01*a29);
  a01=(a04+a01);
  a14=(a14/a06);
  a06=(a08+a14);
  a06=(a06*a24);
  a01=(a01+a06);
  a39=(a39*a54);
  a01=(a01-a39);
  a61=(a61*a93);
  a01=(a01+a61);
  a62=(a62*a02);
  a01=(a01+a62);
  a01=(a01/a03);
  if (res[0]!=0) res[0][23]=a01;
  a01=arg[2]? arg[2][0] : 0;
  a60=(a49+a60);
  a03=(a60*a17);
  a64=(a64-a21);
  a62=(a64*a11);
  a03=(a03+a62);
  a67=(a67*a05);
  a03=(a03+a67);
  a60=(a60*a19);
  a03=(a03+a60);
  a64=(a64*a13);
  a03=(a03+a64);
  a03=(a03+a68);
  a03=(a03+a28);
  a01=(a01-a03);
  if (res[0]!=0) res[0][24]=a01;
  a01=arg[2]? arg[2][1] : 0;
  a73=(a73-a00);
  a03=(a73*a17);
  a69=(a69*a11);
  a03=(a03+a69);
  a21=(a21+a80);
  a80=(a21*a05);
  a03=(a03+a80);
  a73=(a73*a19);
  a03=(a03+a73);
  a03=(a03+a90);
  a21=(a21*a07);
  a03=(a03+a21);
  a03=(a03+a40);
  a01=(a01-a03);
  if (res[0]!=0) res[0][25]=a01;
  a01=arg[2]? arg[2][2] : 0;
  a71=(a71*a17);
  a00=(a00+a77);
  a11=(a00*a11);
  a71=(a71+a11);
  a09=(a09-a49);
  a05=(a09*a05);
  a71=(a71+a05);
  a71=(a71+a42);
  a00=(a00*a13);
  a71=(a71+a00);
  a09=(a09*a07);
  a71=(a71+a09);
  a71=(a71+a58);
  a01=(a01-a71);
  if (res[0]!=0) res[0][26]=a01;
  a01=arg[2]? arg[2][3] : 0;
  a85=(a08+a85);
  a71=(a85*a32);
  a23=(a23-a15);
  a58=(a23*a27);
  a71=(a71+a58);
  a12=(a12*a22);
  a71=(a71+a12);
  a85=(a85*a34);
  a71=(a71+a85);
  a23=(a23*a29);
  a71=(a71+a23);
  a71=(a71+a63);
  a71=(a71+a57);
  a01=(a01-a71);
  if (res[0]!=0) res[0][27]=a01;
  a01=arg[2]? arg[2][4] : 0;
  a88=(a88-a79);
  a71=(a88*a32);
  a37=(a37*a27);
  a71=(a71+a37);
  a15=(a15+a78);
  a78=(a15*a22);
  a71=(a71+a78);
  a88=(a88*a34);
  a71=(a71+a88);
  a71=(a71+a31);
  a15=(a15*a24);
  a71=(a71+a15);
  a71=(a71+a47);
  a01=(a01-a71);
  if (res[0]!=0) res[0][28]=a01;
  a01=arg[2]? arg[2][5] : 0;
  a65=(a65*a32);
  a79=(a79+a83);
  a27=(a79*a27);
  a65=(a65+a27);
  a14=(a14-a08);
  a22=(a14*a22);
  a65=(a65+a22);
  a65=(a65+a04);
  a79=(a79*a29);
  a65=(a65+a79);
  a14=(a14*a24);
  a65=(a65+a14);
  a65=(a65+a59);
  a01=(a01-a65);
  if (res[0]!=0) res[0][29]=a01;
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

/* jacobian:(z[30],g[36],p[6],h)->(J[900]) */
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
  casadi_real a156, a157, a158, a159, a160, a161;
  a000=4.5000000000000001e-01;
  a001=arg[3]? arg[3][0] : 0;
  a000=(a000*a001);
  a002=5.0000000000000000e-01;
  a003=(a002*a001);
  a000=(a000/a003);
  if (res[0]!=0) res[0][0]=a000;
  a004=0.;
  if (res[0]!=0) res[0][1]=a004;
  if (res[0]!=0) res[0][2]=a004;
  if (res[0]!=0) res[0][3]=a004;
  if (res[0]!=0) res[0][4]=a004;
  if (res[0]!=0) res[0][5]=a004;
  if (res[0]!=0) res[0][6]=a004;
  if (res[0]!=0) res[0][7]=a004;
  if (res[0]!=0) res[0][8]=a004;
  if (res[0]!=0) res[0][9]=a004;
  if (res[0]!=0) res[0][10]=a004;
  if (res[0]!=0) res[0][11]=a004;
  if (res[0]!=0) res[0][12]=a004;
  if (res[0]!=0) res[0][13]=a004;
  if (res[0]!=0) res[0][14]=a004;
  if (res[0]!=0) res[0][15]=a004;
  if (res[0]!=0) res[0][16]=a004;
  if (res[0]!=0) res[0][17]=a004;
  a005=arg[0]? arg[0][20] : 0;
  a005=(a001*a005);
  a006=2.5000000000000000e-01;
  a007=arg[0]? arg[0][2] : 0;
  a007=(a002*a007);
  a008=arg[0]? arg[0][8] : 0;
  a008=(a002*a008);
  a007=(a007+a008);
  a007=(a001*a007);
  a008=(a007*a003);
  a009=(a006*a008);
  a010=(a005*a009);
  a011=arg[0]? arg[0][19] : 0;
  a011=(a001*a011);
  a012=arg[0]? arg[0][1] : 0;
  a012=(a002*a012);
  a013=arg[0]? arg[0][7] : 0;
  a013=(a002*a013);
  a012=(a012+a013);
  a012=(a001*a012);
  a013=(a012*a003);
  a014=(a006*a013);
  a015=(a011*a014);
  a016=(a010+a015);
  a017=arg[0]? arg[0][18] : 0;
  a017=(a001*a017);
  a018=arg[0]? arg[0][0] : 0;
  a018=(a002*a018);
  a019=arg[0]? arg[0][6] : 0;
  a019=(a002*a019);
  a018=(a018+a019);
  a018=(a001*a018);
  a019=(2.*a018);
  a019=(a019*a003);
  a020=(a006*a019);
  a021=(a017*a020);
  a016=(a016+a021);
  a022=5.0000000000000003e-02;
  a023=1.3000000000000000e+00;
  a024=arg[1]? arg[1][2] : 0;
  a025=4.;
  a026=casadi_sq(a018);
  a027=casadi_sq(a012);
  a028=(a026+a027);
  a029=casadi_sq(a007);
  a028=(a028+a029);
  a028=(a025+a028);
  a030=(a025/a028);
  a031=(a012*a018);
  a032=2.;
  a033=(a031/a032);
  a033=(a033-a007);
  a034=(a030*a033);
  a035=(a024*a034);
  a036=arg[1]? arg[1][8] : 0;
  a037=1.;
  a038=(a029+a026);
  a038=(a038/a032);
  a039=(a030*a038);
  a039=(a037-a039);
  a040=(a036*a039);
  a035=(a035+a040);
  a040=arg[1]? arg[1][14] : 0;
  a041=(a012*a007);
  a042=(a041/a032);
  a042=(a018+a042);
  a043=(a030*a042);
  a044=(a040*a043);
  a035=(a035+a044);
  a044=(a022*a035);
  a023=(a023+a044);
  a044=1.0000000000000001e-01;
  a045=(a029+a027);
  a045=(a045/a032);
  a046=(a030*a045);
  a046=(a037-a046);
  a047=(a024*a046);
  a048=(a018*a012);
  a049=(a048/a032);
  a049=(a007+a049);
  a050=(a030*a049);
  a051=(a036*a050);
  a047=(a047+a051);
  a051=(a018*a007);
  a052=(a051/a032);
  a052=(a052-a012);
  a053=(a030*a052);
  a054=(a040*a053);
  a047=(a047+a054);
  a054=(a044*a047);
  a023=(a023+a054);
  a054=(a007*a018);
  a055=(a054/a032);
  a055=(a012+a055);
  a056=(a030*a055);
  a057=(a024*a056);
  a058=(a007*a012);
  a059=(a058/a032);
  a059=(a059-a018);
  a060=(a030*a059);
  a061=(a036*a060);
  a057=(a057+a061);
  a061=(a027+a026);
  a061=(a061/a032);
  a062=(a030*a061);
  a062=(a037-a062);
  a063=(a040*a062);
  a057=(a057+a063);
  a023=(a023-a057);
  a063=-1.0000000000000001e-01;
  a064=arg[1]? arg[1][23] : 0;
  a065=arg[0]? arg[0][3] : 0;
  a065=(a002*a065);
  a066=arg[0]? arg[0][9] : 0;
  a066=(a002*a066);
  a065=(a065+a066);
  a065=(a001*a065);
  a066=casadi_sq(a065);
  a067=arg[0]? arg[0][4] : 0;
  a067=(a002*a067);
  a068=arg[0]? arg[0][10] : 0;
  a068=(a002*a068);
  a067=(a067+a068);
  a067=(a001*a067);
  a068=casadi_sq(a067);
  a069=(a066+a068);
  a070=arg[0]? arg[0][5] : 0;
  a070=(a002*a070);
  a071=arg[0]? arg[0][11] : 0;
  a071=(a002*a071);
  a070=(a070+a071);
  a070=(a001*a070);
  a071=casadi_sq(a070);
  a069=(a069+a071);
  a069=(a025+a069);
  a072=(a025/a069);
  a073=(a067*a065);
  a074=(a073/a032);
  a074=(a074-a070);
  a075=(a072*a074);
  a076=(a064*a075);
  a077=arg[1]? arg[1][29] : 0;
  a078=(a071+a066);
  a078=(a078/a032);
  a079=(a072*a078);
  a079=(a037-a079);
  a080=(a077*a079);
  a076=(a076+a080);
  a080=arg[1]? arg[1][35] : 0;
  a081=(a067*a070);
  a082=(a081/a032);
  a082=(a065+a082);
  a083=(a072*a082);
  a084=(a080*a083);
  a076=(a076+a084);
  a084=(a063*a076);
  a023=(a023+a084);
  a084=-2.9999999999999999e-01;
  a085=(a070*a065);
  a086=(a085/a032);
  a086=(a067+a086);
  a087=(a072*a086);
  a088=(a064*a087);
  a089=(a070*a067);
  a090=(a089/a032);
  a090=(a090-a065);
  a091=(a072*a090);
  a092=(a077*a091);
  a088=(a088+a092);
  a092=(a068+a066);
  a092=(a092/a032);
  a093=(a072*a092);
  a093=(a037-a093);
  a094=(a080*a093);
  a088=(a088+a094);
  a094=(a084*a088);
  a023=(a023+a094);
  a023=(2.*a023);
  a023=(a023*a001);
  a094=(a022*a023);
  a008=(a002*a008);
  a008=(a030*a008);
  a028=(a030/a028);
  a095=(a028*a019);
  a096=(a055*a095);
  a096=(a008-a096);
  a097=(a024*a096);
  a098=(a059*a095);
  a099=(a030*a003);
  a098=(a098+a099);
  a100=(a036*a098);
  a097=(a097-a100);
  a019=(a002*a019);
  a019=(a030*a019);
  a100=(a061*a095);
  a100=(a019-a100);
  a101=(a040*a100);
  a097=(a097-a101);
  a101=(a094*a097);
  a013=(a002*a013);
  a013=(a030*a013);
  a102=(a033*a095);
  a102=(a013-a102);
  a103=(a024*a102);
  a104=(a038*a095);
  a019=(a019-a104);
  a104=(a036*a019);
  a103=(a103-a104);
  a104=(a042*a095);
  a104=(a099-a104);
  a105=(a040*a104);
  a103=(a103+a105);
  a105=(a022*a103);
  a106=(a045*a095);
  a107=(a024*a106);
  a108=(a049*a095);
  a108=(a013-a108);
  a109=(a036*a108);
  a107=(a107+a109);
  a095=(a052*a095);
  a095=(a008-a095);
  a109=(a040*a095);
  a107=(a107+a109);
  a109=(a044*a107);
  a105=(a105+a109);
  a105=(a105-a097);
  a105=(2.*a105);
  a105=(a001*a105);
  a109=(a022*a105);
  a110=(a057*a109);
  a101=(a101+a110);
  a016=(a016-a101);
  a101=arg[1]? arg[1][1] : 0;
  a110=(a101*a034);
  a111=arg[1]? arg[1][7] : 0;
  a112=(a111*a039);
  a110=(a110+a112);
  a112=arg[1]? arg[1][13] : 0;
  a113=(a112*a043);
  a110=(a110+a113);
  a113=(a022*a110);
  a114=(a101*a046);
  a115=(a111*a050);
  a114=(a114+a115);
  a115=(a112*a053);
  a114=(a114+a115);
  a115=(a044*a114);
  a113=(a113+a115);
  a115=(a101*a056);
  a116=(a111*a060);
  a115=(a115+a116);
  a116=(a112*a062);
  a115=(a115+a116);
  a113=(a113-a115);
  a116=arg[1]? arg[1][22] : 0;
  a117=(a116*a075);
  a118=arg[1]? arg[1][28] : 0;
  a119=(a118*a079);
  a117=(a117+a119);
  a119=arg[1]? arg[1][34] : 0;
  a120=(a119*a083);
  a117=(a117+a120);
  a120=(a063*a117);
  a113=(a113+a120);
  a120=(a116*a087);
  a121=(a118*a091);
  a120=(a120+a121);
  a121=(a119*a093);
  a120=(a120+a121);
  a121=(a084*a120);
  a113=(a113+a121);
  a113=(2.*a113);
  a113=(a113*a001);
  a121=(a101*a102);
  a122=(a111*a019);
  a121=(a121-a122);
  a122=(a112*a104);
  a121=(a121+a122);
  a122=(a113*a121);
  a123=(a022*a121);
  a124=(a101*a106);
  a125=(a111*a108);
  a124=(a124+a125);
  a125=(a112*a095);
  a124=(a124+a125);
  a125=(a044*a124);
  a123=(a123+a125);
  a125=(a101*a096);
  a126=(a111*a098);
  a125=(a125-a126);
  a126=(a112*a100);
  a125=(a125-a126);
  a123=(a123-a125);
  a123=(2.*a123);
  a123=(a001*a123);
  a126=(a110*a123);
  a122=(a122+a126);
  a016=(a016-a122);
  a122=(a022*a113);
  a126=(a122*a125);
  a127=(a022*a123);
  a128=(a115*a127);
  a126=(a126+a128);
  a016=(a016-a126);
  a126=arg[1]? arg[1][0] : 0;
  a034=(a126*a034);
  a128=arg[1]? arg[1][6] : 0;
  a039=(a128*a039);
  a034=(a034+a039);
  a039=arg[1]? arg[1][12] : 0;
  a043=(a039*a043);
  a034=(a034+a043);
  a043=(a022*a034);
  a046=(a126*a046);
  a050=(a128*a050);
  a046=(a046+a050);
  a053=(a039*a053);
  a046=(a046+a053);
  a053=(a044*a046);
  a043=(a043+a053);
  a056=(a126*a056);
  a060=(a128*a060);
  a056=(a056+a060);
  a062=(a039*a062);
  a056=(a056+a062);
  a043=(a043-a056);
  a062=arg[1]? arg[1][21] : 0;
  a075=(a062*a075);
  a060=arg[1]? arg[1][27] : 0;
  a079=(a060*a079);
  a075=(a075+a079);
  a079=arg[1]? arg[1][33] : 0;
  a083=(a079*a083);
  a075=(a075+a083);
  a083=(a063*a075);
  a043=(a043+a083);
  a087=(a062*a087);
  a091=(a060*a091);
  a087=(a087+a091);
  a093=(a079*a093);
  a087=(a087+a093);
  a093=(a084*a087);
  a043=(a043+a093);
  a043=(2.*a043);
  a043=(a043*a001);
  a102=(a126*a102);
  a019=(a128*a019);
  a102=(a102-a019);
  a104=(a039*a104);
  a102=(a102+a104);
  a104=(a043*a102);
  a019=(a022*a102);
  a106=(a126*a106);
  a108=(a128*a108);
  a106=(a106+a108);
  a095=(a039*a095);
  a106=(a106+a095);
  a095=(a044*a106);
  a019=(a019+a095);
  a096=(a126*a096);
  a098=(a128*a098);
  a096=(a096-a098);
  a100=(a039*a100);
  a096=(a096-a100);
  a019=(a019-a096);
  a019=(2.*a019);
  a019=(a001*a019);
  a100=(a034*a019);
  a104=(a104+a100);
  a016=(a016-a104);
  a104=(a022*a043);
  a100=(a104*a096);
  a098=(a022*a019);
  a095=(a056*a098);
  a100=(a100+a095);
  a016=(a016-a100);
  a100=(a023+a003);
  a095=(a100*a103);
  a108=(a035*a105);
  a095=(a095+a108);
  a016=(a016-a095);
  a016=(a016/a001);
  if (res[0]!=0) res[0][18]=a016;
  a095=(a006*a001);
  a108=(a005*a095);
  a093=(a017*a014);
  a091=(a108+a093);
  a083=-5.0000000000000003e-02;
  a083=(a083*a001);
  a053=(a044*a023);
  a083=(a083-a053);
  a097=(a083*a097);
  a053=(a044*a105);
  a050=(a057*a053);
  a097=(a097-a050);
  a091=(a091-a097);
  a097=(a113*a124);
  a050=(a114*a123);
  a097=(a097+a050);
  a091=(a091+a097);
  a097=(a044*a113);
  a125=(a097*a125);
  a050=(a044*a123);
  a129=(a115*a050);
  a125=(a125+a129);
  a091=(a091+a125);
  a125=(a043*a106);
  a129=(a046*a019);
  a125=(a125+a129);
  a091=(a091+a125);
  a125=(a044*a043);
  a096=(a125*a096);
  a129=(a044*a019);
  a130=(a056*a129);
  a096=(a096+a130);
  a091=(a091+a096);
  a096=(a100*a107);
  a130=(a047*a105);
  a096=(a096+a130);
  a091=(a091+a096);
  a091=(a091/a001);
  if (res[0]!=0) res[0][19]=a091;
  a096=(a017*a009);
  a130=(a011*a095);
  a131=(a096-a130);
  a103=(a083*a103);
  a053=(a035*a053);
  a103=(a103-a053);
  a131=(a131+a103);
  a107=(a094*a107);
  a109=(a047*a109);
  a107=(a107+a109);
  a131=(a131+a107);
  a121=(a097*a121);
  a050=(a110*a050);
  a121=(a121+a050);
  a131=(a131-a121);
  a124=(a122*a124);
  a127=(a114*a127);
  a124=(a124+a127);
  a131=(a131+a124);
  a102=(a125*a102);
  a129=(a034*a129);
  a102=(a102+a129);
  a131=(a131-a102);
  a106=(a104*a106);
  a098=(a046*a098);
  a106=(a106+a098);
  a131=(a131+a106);
  a131=(a131/a001);
  if (res[0]!=0) res[0][20]=a131;
  a106=(a084*a123);
  a098=(a117*a106);
  a102=(a063*a105);
  a129=(a088*a102);
  a098=(a098-a129);
  a123=(a063*a123);
  a129=(a120*a123);
  a098=(a098-a129);
  a129=(a084*a019);
  a124=(a075*a129);
  a098=(a098+a124);
  a019=(a063*a019);
  a124=(a087*a019);
  a098=(a098-a124);
  a105=(a084*a105);
  a124=(a076*a105);
  a098=(a098+a124);
  a098=(a098/a001);
  if (res[0]!=0) res[0][21]=a098;
  a124=(a071+a068);
  a124=(a124/a032);
  a127=(a072*a124);
  a127=(a037-a127);
  a121=(a116*a127);
  a050=(a065*a067);
  a107=(a050/a032);
  a107=(a070+a107);
  a109=(a072*a107);
  a103=(a118*a109);
  a121=(a121+a103);
  a103=(a065*a070);
  a053=(a103/a032);
  a053=(a053-a067);
  a132=(a072*a053);
  a133=(a119*a132);
  a121=(a121+a133);
  a106=(a121*a106);
  a133=(a062*a127);
  a134=(a060*a109);
  a133=(a133+a134);
  a134=(a079*a132);
  a133=(a133+a134);
  a129=(a133*a129);
  a106=(a106+a129);
  a127=(a064*a127);
  a109=(a077*a109);
  a127=(a127+a109);
  a132=(a080*a132);
  a127=(a127+a132);
  a105=(a127*a105);
  a106=(a106+a105);
  a106=(a106/a001);
  a106=(-a106);
  if (res[0]!=0) res[0][22]=a106;
  a102=(a127*a102);
  a123=(a121*a123);
  a102=(a102+a123);
  a019=(a133*a019);
  a102=(a102+a019);
  a102=(a102/a001);
  if (res[0]!=0) res[0][23]=a102;
  a019=arg[0]? arg[0][26] : 0;
  a123=(a019*a009);
  a105=arg[0]? arg[0][25] : 0;
  a132=(a105*a014);
  a109=(a123+a132);
  a129=arg[0]? arg[0][24] : 0;
  a020=(a129*a020);
  a109=(a109+a020);
  a109=(a109+a010);
  a109=(a109+a015);
  a109=(a109+a021);
  a109=(-a109);
  if (res[0]!=0) res[0][24]=a109;
  a021=(a129*a014);
  a020=(a019*a095);
  a021=(a021-a020);
  a021=(a021-a108);
  a021=(a021+a093);
  a021=(-a021);
  if (res[0]!=0) res[0][25]=a021;
  a093=(a105*a095);
  a134=(a129*a009);
  a134=(a093+a134);
  a134=(a134+a130);
  a134=(a134+a096);
  a134=(-a134);
  if (res[0]!=0) res[0][26]=a134;
  if (res[0]!=0) res[0][27]=a004;
  if (res[0]!=0) res[0][28]=a004;
  if (res[0]!=0) res[0][29]=a004;
  if (res[0]!=0) res[0][30]=a004;
  if (res[0]!=0) res[0][31]=a037;
  if (res[0]!=0) res[0][32]=a004;
  if (res[0]!=0) res[0][33]=a004;
  if (res[0]!=0) res[0][34]=a004;
  if (res[0]!=0) res[0][35]=a004;
  if (res[0]!=0) res[0][36]=a004;
  if (res[0]!=0) res[0][37]=a004;
  if (res[0]!=0) res[0][38]=a004;
  if (res[0]!=0) res[0][39]=a004;
  if (res[0]!=0) res[0][40]=a004;
  if (res[0]!=0) res[0][41]=a004;
  if (res[0]!=0) res[0][42]=a004;
  if (res[0]!=0) res[0][43]=a004;
  if (res[0]!=0) res[0][44]=a004;
  if (res[0]!=0) res[0][45]=a004;
  if (res[0]!=0) res[0][46]=a004;
  if (res[0]!=0) res[0][47]=a004;
  a096=(a018*a003);
  a135=(a006*a096);
  a136=(a011*a135);
  a137=(a136-a108);
  a138=(2.*a012);
  a138=(a138*a003);
  a139=(a028*a138);
  a140=(a055*a139);
  a140=(a099-a140);
  a141=(a024*a140);
  a142=(a059*a139);
  a142=(a008-a142);
  a143=(a036*a142);
  a141=(a141+a143);
  a143=(a002*a138);
  a143=(a030*a143);
  a144=(a061*a139);
  a144=(a143-a144);
  a145=(a040*a144);
  a141=(a141-a145);
  a145=(a094*a141);
  a096=(a002*a096);
  a096=(a030*a096);
  a146=(a033*a139);
  a146=(a096-a146);
  a147=(a024*a146);
  a148=(a038*a139);
  a149=(a036*a148);
  a147=(a147+a149);
  a149=(a042*a139);
  a008=(a008-a149);
  a149=(a040*a008);
  a147=(a147+a149);
  a149=(a022*a147);
  a150=(a049*a139);
  a150=(a096-a150);
  a151=(a036*a150);
  a152=(a045*a139);
  a143=(a143-a152);
  a152=(a024*a143);
  a151=(a151-a152);
  a139=(a052*a139);
  a139=(a139+a099);
  a152=(a040*a139);
  a151=(a151-a152);
  a152=(a044*a151);
  a149=(a149+a152);
  a149=(a149-a141);
  a149=(2.*a149);
  a149=(a001*a149);
  a152=(a022*a149);
  a153=(a057*a152);
  a145=(a145+a153);
  a137=(a137-a145);
  a145=(a101*a146);
  a153=(a111*a148);
  a145=(a145+a153);
  a153=(a112*a008);
  a145=(a145+a153);
  a153=(a113*a145);
  a154=(a022*a145);
  a155=(a111*a150);
  a156=(a101*a143);
  a155=(a155-a156);
  a156=(a112*a139);
  a155=(a155-a156);
  a156=(a044*a155);
  a154=(a154+a156);
  a156=(a101*a140);
  a157=(a111*a142);
  a156=(a156+a157);
  a157=(a112*a144);
  a156=(a156-a157);
  a154=(a154-a156);
  a154=(2.*a154);
  a154=(a001*a154);
  a157=(a110*a154);
  a153=(a153+a157);
  a137=(a137-a153);
  a153=(a122*a156);
  a157=(a022*a154);
  a158=(a115*a157);
  a153=(a153+a158);
  a137=(a137-a153);
  a146=(a126*a146);
  a148=(a128*a148);
  a146=(a146+a148);
  a008=(a039*a008);
  a146=(a146+a008);
  a008=(a043*a146);
  a148=(a022*a146);
  a150=(a128*a150);
  a143=(a126*a143);
  a150=(a150-a143);
  a139=(a039*a139);
  a150=(a150-a139);
  a139=(a044*a150);
  a148=(a148+a139);
  a140=(a126*a140);
  a142=(a128*a142);
  a140=(a140+a142);
  a144=(a039*a144);
  a140=(a140-a144);
  a148=(a148-a140);
  a148=(2.*a148);
  a148=(a001*a148);
  a144=(a034*a148);
  a008=(a008+a144);
  a137=(a137-a008);
  a008=(a104*a140);
  a144=(a022*a148);
  a142=(a056*a144);
  a008=(a008+a142);
  a137=(a137-a008);
  a008=(a100*a147);
  a142=(a035*a149);
  a008=(a008+a142);
  a137=(a137-a008);
  a137=(a137/a001);
  if (res[0]!=0) res[0][48]=a137;
  a138=(a006*a138);
  a008=(a011*a138);
  a142=(a010+a008);
  a139=(a017*a135);
  a142=(a142+a139);
  a141=(a083*a141);
  a143=(a044*a149);
  a153=(a057*a143);
  a141=(a141-a153);
  a142=(a142-a141);
  a141=(a113*a155);
  a153=(a114*a154);
  a141=(a141+a153);
  a142=(a142+a141);
  a156=(a097*a156);
  a141=(a044*a154);
  a153=(a115*a141);
  a156=(a156+a153);
  a142=(a142+a156);
  a156=(a043*a150);
  a153=(a046*a148);
  a156=(a156+a153);
  a142=(a142+a156);
  a140=(a125*a140);
  a156=(a044*a148);
  a153=(a056*a156);
  a140=(a140+a153);
  a142=(a142+a140);
  a140=(a100*a151);
  a153=(a047*a149);
  a140=(a140+a153);
  a142=(a142+a140);
  a142=(a142/a001);
  if (res[0]!=0) res[0][49]=a142;
  a011=(a011*a009);
  a017=(a017*a095);
  a140=(a011+a017);
  a147=(a083*a147);
  a143=(a035*a143);
  a147=(a147-a143);
  a140=(a140+a147);
  a151=(a094*a151);
  a152=(a047*a152);
  a151=(a151+a152);
  a140=(a140+a151);
  a145=(a097*a145);
  a141=(a110*a141);
  a145=(a145+a141);
  a140=(a140-a145);
  a155=(a122*a155);
  a157=(a114*a157);
  a155=(a155+a157);
  a140=(a140+a155);
  a146=(a125*a146);
  a156=(a034*a156);
  a146=(a146+a156);
  a140=(a140-a146);
  a150=(a104*a150);
  a144=(a046*a144);
  a150=(a150+a144);
  a140=(a140+a150);
  a140=(a140/a001);
  if (res[0]!=0) res[0][50]=a140;
  a150=(a084*a154);
  a144=(a117*a150);
  a146=(a063*a149);
  a156=(a088*a146);
  a144=(a144-a156);
  a154=(a063*a154);
  a156=(a120*a154);
  a144=(a144-a156);
  a156=(a084*a148);
  a155=(a075*a156);
  a144=(a144+a155);
  a148=(a063*a148);
  a155=(a087*a148);
  a144=(a144-a155);
  a149=(a084*a149);
  a155=(a076*a149);
  a144=(a144+a155);
  a144=(a144/a001);
  if (res[0]!=0) res[0][51]=a144;
  a150=(a121*a150);
  a156=(a133*a156);
  a150=(a150+a156);
  a149=(a127*a149);
  a150=(a150+a149);
  a150=(a150/a001);
  a150=(-a150);
  if (res[0]!=0) res[0][52]=a150;
  a146=(a127*a146);
  a154=(a121*a154);
  a146=(a146+a154);
  a148=(a133*a148);
  a146=(a146+a148);
  a146=(a146/a001);
  if (res[0]!=0) res[0][53]=a146;
  a148=(a105*a135);
  a020=(a020+a148);
  a020=(a020+a108);
  a020=(a020+a136);
  a020=(-a020);
  if (res[0]!=0) res[0][54]=a020;
  a138=(a105*a138);
  a123=(a123+a138);
  a138=(a129*a135);
  a123=(a123+a138);
  a123=(a123+a010);
  a123=(a123+a008);
  a123=(a123+a139);
  a123=(-a123);
  if (res[0]!=0) res[0][55]=a123;
  a105=(a105*a009);
  a129=(a129*a095);
  a105=(a105-a129);
  a105=(a105+a011);
  a105=(a105-a017);
  a105=(-a105);
  if (res[0]!=0) res[0][56]=a105;
  if (res[0]!=0) res[0][57]=a004;
  if (res[0]!=0) res[0][58]=a004;
  if (res[0]!=0) res[0][59]=a004;
  if (res[0]!=0) res[0][60]=a004;
  if (res[0]!=0) res[0][61]=a004;
  a011=(a044*a001);
  a011=(a011/a003);
  if (res[0]!=0) res[0][62]=a011;
  if (res[0]!=0) res[0][63]=a004;
  if (res[0]!=0) res[0][64]=a004;
  if (res[0]!=0) res[0][65]=a004;
  if (res[0]!=0) res[0][66]=a004;
  if (res[0]!=0) res[0][67]=a004;
  if (res[0]!=0) res[0][68]=a004;
  if (res[0]!=0) res[0][69]=a004;
  if (res[0]!=0) res[0][70]=a004;
  if (res[0]!=0) res[0][71]=a004;
  if (res[0]!=0) res[0][72]=a004;
  if (res[0]!=0) res[0][73]=a004;
  if (res[0]!=0) res[0][74]=a004;
  if (res[0]!=0) res[0][75]=a004;
  if (res[0]!=0) res[0][76]=a004;
  if (res[0]!=0) res[0][77]=a004;
  a009=(a005*a135);
  a008=(a009+a130);
  a010=(2.*a007);
  a010=(a010*a003);
  a028=(a028*a010);
  a055=(a055*a028);
  a055=(a096-a055);
  a136=(a024*a055);
  a059=(a059*a028);
  a059=(a013-a059);
  a108=(a036*a059);
  a136=(a136+a108);
  a061=(a061*a028);
  a108=(a040*a061);
  a136=(a136+a108);
  a108=(a094*a136);
  a042=(a042*a028);
  a013=(a013-a042);
  a042=(a040*a013);
  a033=(a033*a028);
  a033=(a033+a099);
  a148=(a024*a033);
  a154=(a002*a010);
  a030=(a030*a154);
  a038=(a038*a028);
  a038=(a030-a038);
  a154=(a036*a038);
  a148=(a148+a154);
  a042=(a042-a148);
  a148=(a022*a042);
  a049=(a049*a028);
  a099=(a099-a049);
  a036=(a036*a099);
  a045=(a045*a028);
  a030=(a030-a045);
  a024=(a024*a030);
  a036=(a036-a024);
  a052=(a052*a028);
  a096=(a096-a052);
  a040=(a040*a096);
  a036=(a036+a040);
  a040=(a044*a036);
  a148=(a148+a040);
  a148=(a148-a136);
  a148=(2.*a148);
  a148=(a001*a148);
  a040=(a022*a148);
  a052=(a057*a040);
  a108=(a108+a052);
  a008=(a008-a108);
  a108=(a112*a013);
  a052=(a101*a033);
  a028=(a111*a038);
  a052=(a052+a028);
  a108=(a108-a052);
  a052=(a113*a108);
  a028=(a022*a108);
  a024=(a111*a099);
  a045=(a101*a030);
  a024=(a024-a045);
  a045=(a112*a096);
  a024=(a024+a045);
  a045=(a044*a024);
  a028=(a028+a045);
  a101=(a101*a055);
  a111=(a111*a059);
  a101=(a101+a111);
  a112=(a112*a061);
  a101=(a101+a112);
  a028=(a028-a101);
  a028=(2.*a028);
  a028=(a001*a028);
  a112=(a110*a028);
  a052=(a052+a112);
  a008=(a008-a052);
  a052=(a122*a101);
  a112=(a022*a028);
  a111=(a115*a112);
  a052=(a052+a111);
  a008=(a008-a052);
  a013=(a039*a013);
  a033=(a126*a033);
  a038=(a128*a038);
  a033=(a033+a038);
  a013=(a013-a033);
  a033=(a043*a013);
  a038=(a022*a013);
  a099=(a128*a099);
  a030=(a126*a030);
  a099=(a099-a030);
  a096=(a039*a096);
  a099=(a099+a096);
  a096=(a044*a099);
  a038=(a038+a096);
  a126=(a126*a055);
  a128=(a128*a059);
  a126=(a126+a128);
  a039=(a039*a061);
  a126=(a126+a039);
  a038=(a038-a126);
  a038=(2.*a038);
  a038=(a001*a038);
  a039=(a034*a038);
  a033=(a033+a039);
  a008=(a008-a033);
  a033=(a104*a126);
  a039=(a022*a038);
  a061=(a056*a039);
  a033=(a033+a061);
  a008=(a008-a033);
  a033=(a100*a042);
  a061=(a035*a148);
  a033=(a033+a061);
  a008=(a008-a033);
  a008=(a008/a001);
  if (res[0]!=0) res[0][78]=a008;
  a033=(a005*a014);
  a061=(a033-a017);
  a136=(a083*a136);
  a128=(a044*a148);
  a059=(a057*a128);
  a136=(a136-a059);
  a061=(a061-a136);
  a136=(a113*a024);
  a059=(a114*a028);
  a136=(a136+a059);
  a061=(a061+a136);
  a101=(a097*a101);
  a136=(a044*a028);
  a059=(a115*a136);
  a101=(a101+a059);
  a061=(a061+a101);
  a101=(a043*a099);
  a059=(a046*a038);
  a101=(a101+a059);
  a061=(a061+a101);
  a126=(a125*a126);
  a101=(a044*a038);
  a059=(a056*a101);
  a126=(a126+a059);
  a061=(a061+a126);
  a100=(a100*a036);
  a126=(a047*a148);
  a100=(a100+a126);
  a061=(a061+a100);
  a061=(a061/a001);
  if (res[0]!=0) res[0][79]=a061;
  a010=(a006*a010);
  a005=(a005*a010);
  a100=(a005+a015);
  a100=(a100+a139);
  a083=(a083*a042);
  a128=(a035*a128);
  a083=(a083-a128);
  a100=(a100+a083);
  a094=(a094*a036);
  a040=(a047*a040);
  a094=(a094+a040);
  a100=(a100+a094);
  a097=(a097*a108);
  a136=(a110*a136);
  a097=(a097+a136);
  a100=(a100-a097);
  a122=(a122*a024);
  a112=(a114*a112);
  a122=(a122+a112);
  a100=(a100+a122);
  a125=(a125*a013);
  a101=(a034*a101);
  a125=(a125+a101);
  a100=(a100-a125);
  a104=(a104*a099);
  a039=(a046*a039);
  a104=(a104+a039);
  a100=(a100+a104);
  a100=(a100/a001);
  if (res[0]!=0) res[0][80]=a100;
  a104=(a084*a028);
  a039=(a117*a104);
  a099=(a063*a148);
  a125=(a088*a099);
  a039=(a039-a125);
  a028=(a063*a028);
  a125=(a120*a028);
  a039=(a039-a125);
  a125=(a084*a038);
  a101=(a075*a125);
  a039=(a039+a101);
  a038=(a063*a038);
  a101=(a087*a038);
  a039=(a039-a101);
  a148=(a084*a148);
  a101=(a076*a148);
  a039=(a039+a101);
  a039=(a039/a001);
  if (res[0]!=0) res[0][81]=a039;
  a104=(a121*a104);
  a125=(a133*a125);
  a104=(a104+a125);
  a148=(a127*a148);
  a104=(a104+a148);
  a104=(a104/a001);
  a104=(-a104);
  if (res[0]!=0) res[0][82]=a104;
  a099=(a127*a099);
  a028=(a121*a028);
  a099=(a099+a028);
  a038=(a133*a038);
  a099=(a099+a038);
  a099=(a099/a001);
  if (res[0]!=0) res[0][83]=a099;
  a135=(a019*a135);
  a135=(a135-a093);
  a135=(a135+a009);
  a135=(a135-a130);
  a135=(-a135);
  if (res[0]!=0) res[0][84]=a135;
  a014=(a019*a014);
  a014=(a014+a129);
  a014=(a014+a033);
  a014=(a014+a017);
  a014=(-a014);
  if (res[0]!=0) res[0][85]=a014;
  a019=(a019*a010);
  a019=(a019+a132);
  a019=(a019+a138);
  a019=(a019+a005);
  a019=(a019+a015);
  a019=(a019+a139);
  a019=(-a019);
  if (res[0]!=0) res[0][86]=a019;
  if (res[0]!=0) res[0][87]=a004;
  if (res[0]!=0) res[0][88]=a004;
  if (res[0]!=0) res[0][89]=a004;
  if (res[0]!=0) res[0][90]=a004;
  if (res[0]!=0) res[0][91]=a004;
  if (res[0]!=0) res[0][92]=a004;
  a139=2.9999999999999999e-01;
  a139=(a139*a001);
  a139=(a139/a003);
  if (res[0]!=0) res[0][93]=a139;
  if (res[0]!=0) res[0][94]=a004;
  if (res[0]!=0) res[0][95]=a004;
  if (res[0]!=0) res[0][96]=a004;
  if (res[0]!=0) res[0][97]=a004;
  if (res[0]!=0) res[0][98]=a004;
  if (res[0]!=0) res[0][99]=a004;
  if (res[0]!=0) res[0][100]=a004;
  if (res[0]!=0) res[0][101]=a004;
  if (res[0]!=0) res[0][102]=a004;
  if (res[0]!=0) res[0][103]=a004;
  if (res[0]!=0) res[0][104]=a004;
  if (res[0]!=0) res[0][105]=a004;
  if (res[0]!=0) res[0][106]=a004;
  if (res[0]!=0) res[0][107]=a004;
  a015=(a067*a003);
  a005=(a002*a015);
  a005=(a072*a005);
  a069=(a072/a069);
  a138=(2.*a065);
  a138=(a138*a003);
  a132=(a069*a138);
  a010=(a074*a132);
  a010=(a005-a010);
  a017=(a064*a010);
  a033=(a002*a138);
  a033=(a072*a033);
  a129=(a078*a132);
  a129=(a033-a129);
  a130=(a077*a129);
  a017=(a017-a130);
  a130=(a072*a003);
  a009=(a082*a132);
  a009=(a130-a009);
  a093=(a080*a009);
  a017=(a017+a093);
  a093=(a063*a017);
  a038=(a070*a003);
  a028=(a002*a038);
  a028=(a072*a028);
  a148=(a086*a132);
  a148=(a028-a148);
  a125=(a064*a148);
  a101=(a090*a132);
  a101=(a101+a130);
  a013=(a077*a101);
  a125=(a125-a013);
  a013=(a092*a132);
  a033=(a033-a013);
  a013=(a080*a033);
  a125=(a125-a013);
  a013=(a084*a125);
  a093=(a093+a013);
  a093=(2.*a093);
  a093=(a001*a093);
  a013=(a022*a093);
  a122=(a057*a013);
  a112=(a116*a010);
  a024=(a118*a129);
  a112=(a112-a024);
  a024=(a119*a009);
  a112=(a112+a024);
  a024=(a063*a112);
  a097=(a116*a148);
  a136=(a118*a101);
  a097=(a097-a136);
  a136=(a119*a033);
  a097=(a097-a136);
  a136=(a084*a097);
  a024=(a024+a136);
  a024=(2.*a024);
  a024=(a001*a024);
  a136=(a110*a024);
  a122=(a122+a136);
  a136=(a022*a024);
  a108=(a115*a136);
  a122=(a122+a108);
  a010=(a062*a010);
  a129=(a060*a129);
  a010=(a010-a129);
  a009=(a079*a009);
  a010=(a010+a009);
  a009=(a063*a010);
  a148=(a062*a148);
  a101=(a060*a101);
  a148=(a148-a101);
  a033=(a079*a033);
  a148=(a148-a033);
  a033=(a084*a148);
  a009=(a009+a033);
  a009=(2.*a009);
  a009=(a001*a009);
  a033=(a034*a009);
  a122=(a122+a033);
  a033=(a022*a009);
  a101=(a056*a033);
  a122=(a122+a101);
  a101=(a035*a093);
  a122=(a122+a101);
  a122=(a122/a001);
  a122=(-a122);
  if (res[0]!=0) res[0][108]=a122;
  a101=(a044*a093);
  a129=(a057*a101);
  a108=(a114*a024);
  a129=(a129+a108);
  a108=(a044*a024);
  a094=(a115*a108);
  a129=(a129+a094);
  a094=(a046*a009);
  a129=(a129+a094);
  a094=(a044*a009);
  a040=(a056*a094);
  a129=(a129+a040);
  a040=(a047*a093);
  a129=(a129+a040);
  a129=(a129/a001);
  if (res[0]!=0) res[0][109]=a129;
  a013=(a047*a013);
  a101=(a035*a101);
  a013=(a013-a101);
  a108=(a110*a108);
  a013=(a013-a108);
  a136=(a114*a136);
  a013=(a013+a136);
  a094=(a034*a094);
  a013=(a013-a094);
  a033=(a046*a033);
  a013=(a013+a033);
  a013=(a013/a001);
  if (res[0]!=0) res[0][110]=a013;
  a033=arg[0]? arg[0][23] : 0;
  a033=(a001*a033);
  a038=(a006*a038);
  a094=(a033*a038);
  a136=arg[0]? arg[0][22] : 0;
  a136=(a001*a136);
  a015=(a006*a015);
  a108=(a136*a015);
  a101=(a094+a108);
  a040=arg[0]? arg[0][21] : 0;
  a040=(a001*a040);
  a138=(a006*a138);
  a036=(a040*a138);
  a101=(a101+a036);
  a083=-2.9999999999999999e-02;
  a083=(a083*a001);
  a128=(a063*a023);
  a083=(a083-a128);
  a125=(a083*a125);
  a128=(a063*a093);
  a042=(a088*a128);
  a125=(a125-a042);
  a101=(a101+a125);
  a125=(a084*a113);
  a112=(a125*a112);
  a042=(a084*a024);
  a126=(a117*a042);
  a112=(a112+a126);
  a101=(a101+a112);
  a113=(a063*a113);
  a097=(a113*a097);
  a024=(a063*a024);
  a112=(a120*a024);
  a097=(a097+a112);
  a101=(a101-a097);
  a097=(a084*a043);
  a010=(a097*a010);
  a112=(a084*a009);
  a126=(a075*a112);
  a010=(a010+a126);
  a101=(a101+a010);
  a043=(a063*a043);
  a148=(a043*a148);
  a009=(a063*a009);
  a010=(a087*a009);
  a148=(a148+a010);
  a101=(a101-a148);
  a148=3.0000000000000004e-01;
  a148=(a148*a001);
  a023=(a084*a023);
  a148=(a148-a023);
  a017=(a148*a017);
  a093=(a084*a093);
  a023=(a076*a093);
  a017=(a017-a023);
  a101=(a101-a017);
  a101=(a101/a001);
  if (res[0]!=0) res[0][111]=a101;
  a017=(a033*a095);
  a023=(a040*a015);
  a010=(a017+a023);
  a126=(a124*a132);
  a059=(a116*a126);
  a055=(a107*a132);
  a055=(a005-a055);
  a096=(a118*a055);
  a059=(a059+a096);
  a132=(a053*a132);
  a132=(a028-a132);
  a096=(a119*a132);
  a059=(a059+a096);
  a096=(a125*a059);
  a042=(a121*a042);
  a096=(a096+a042);
  a010=(a010-a096);
  a096=(a062*a126);
  a042=(a060*a055);
  a096=(a096+a042);
  a042=(a079*a132);
  a096=(a096+a042);
  a042=(a097*a096);
  a112=(a133*a112);
  a042=(a042+a112);
  a010=(a010-a042);
  a126=(a064*a126);
  a055=(a077*a055);
  a126=(a126+a055);
  a132=(a080*a132);
  a126=(a126+a132);
  a132=(a148*a126);
  a093=(a127*a093);
  a132=(a132-a093);
  a010=(a010+a132);
  a010=(a010/a001);
  if (res[0]!=0) res[0][112]=a010;
  a132=(a040*a038);
  a093=(a136*a095);
  a055=(a132-a093);
  a126=(a083*a126);
  a128=(a127*a128);
  a126=(a126-a128);
  a055=(a055-a126);
  a059=(a113*a059);
  a024=(a121*a024);
  a059=(a059+a024);
  a055=(a055+a059);
  a096=(a043*a096);
  a009=(a133*a009);
  a096=(a096+a009);
  a055=(a055+a096);
  a055=(a055/a001);
  if (res[0]!=0) res[0][113]=a055;
  if (res[0]!=0) res[0][114]=a004;
  if (res[0]!=0) res[0][115]=a004;
  if (res[0]!=0) res[0][116]=a004;
  a096=arg[0]? arg[0][29] : 0;
  a009=(a096*a038);
  a059=arg[0]? arg[0][28] : 0;
  a024=(a059*a015);
  a126=(a009+a024);
  a128=arg[0]? arg[0][27] : 0;
  a138=(a128*a138);
  a126=(a126+a138);
  a126=(a126+a094);
  a126=(a126+a108);
  a126=(a126+a036);
  a126=(-a126);
  if (res[0]!=0) res[0][117]=a126;
  a036=(a128*a015);
  a138=(a096*a095);
  a036=(a036-a138);
  a036=(a036-a017);
  a036=(a036+a023);
  a036=(-a036);
  if (res[0]!=0) res[0][118]=a036;
  a023=(a059*a095);
  a042=(a128*a038);
  a042=(a023+a042);
  a042=(a042+a093);
  a042=(a042+a132);
  a042=(-a042);
  if (res[0]!=0) res[0][119]=a042;
  if (res[0]!=0) res[0][120]=a004;
  if (res[0]!=0) res[0][121]=a004;
  if (res[0]!=0) res[0][122]=a004;
  if (res[0]!=0) res[0][123]=a004;
  a132=(a095/a003);
  if (res[0]!=0) res[0][124]=a132;
  if (res[0]!=0) res[0][125]=a004;
  if (res[0]!=0) res[0][126]=a004;
  if (res[0]!=0) res[0][127]=a004;
  if (res[0]!=0) res[0][128]=a004;
  if (res[0]!=0) res[0][129]=a004;
  if (res[0]!=0) res[0][130]=a004;
  if (res[0]!=0) res[0][131]=a004;
  if (res[0]!=0) res[0][132]=a004;
  if (res[0]!=0) res[0][133]=a004;
  if (res[0]!=0) res[0][134]=a004;
  if (res[0]!=0) res[0][135]=a004;
  if (res[0]!=0) res[0][136]=a004;
  if (res[0]!=0) res[0][137]=a004;
  a112=(a065*a003);
  a030=(a002*a112);
  a030=(a072*a030);
  a052=(2.*a067);
  a052=(a052*a003);
  a111=(a069*a052);
  a045=(a074*a111);
  a045=(a030-a045);
  a049=(a064*a045);
  a154=(a078*a111);
  a149=(a077*a154);
  a049=(a049+a149);
  a149=(a082*a111);
  a149=(a028-a149);
  a156=(a080*a149);
  a049=(a049+a156);
  a156=(a063*a049);
  a155=(a086*a111);
  a155=(a130-a155);
  a157=(a064*a155);
  a145=(a090*a111);
  a028=(a028-a145);
  a145=(a077*a028);
  a157=(a157+a145);
  a145=(a002*a052);
  a145=(a072*a145);
  a141=(a092*a111);
  a141=(a145-a141);
  a151=(a080*a141);
  a157=(a157-a151);
  a151=(a084*a157);
  a156=(a156+a151);
  a156=(2.*a156);
  a156=(a001*a156);
  a151=(a022*a156);
  a152=(a057*a151);
  a147=(a116*a045);
  a143=(a118*a154);
  a147=(a147+a143);
  a143=(a119*a149);
  a147=(a147+a143);
  a143=(a063*a147);
  a153=(a116*a155);
  a158=(a118*a028);
  a153=(a153+a158);
  a158=(a119*a141);
  a153=(a153-a158);
  a158=(a084*a153);
  a143=(a143+a158);
  a143=(2.*a143);
  a143=(a001*a143);
  a158=(a110*a143);
  a152=(a152+a158);
  a158=(a022*a143);
  a159=(a115*a158);
  a152=(a152+a159);
  a045=(a062*a045);
  a154=(a060*a154);
  a045=(a045+a154);
  a149=(a079*a149);
  a045=(a045+a149);
  a149=(a063*a045);
  a155=(a062*a155);
  a028=(a060*a028);
  a155=(a155+a028);
  a141=(a079*a141);
  a155=(a155-a141);
  a141=(a084*a155);
  a149=(a149+a141);
  a149=(2.*a149);
  a149=(a001*a149);
  a141=(a034*a149);
  a152=(a152+a141);
  a141=(a022*a149);
  a028=(a056*a141);
  a152=(a152+a028);
  a028=(a035*a156);
  a152=(a152+a028);
  a152=(a152/a001);
  a152=(-a152);
  if (res[0]!=0) res[0][138]=a152;
  a028=(a044*a156);
  a154=(a057*a028);
  a159=(a114*a143);
  a154=(a154+a159);
  a159=(a044*a143);
  a160=(a115*a159);
  a154=(a154+a160);
  a160=(a046*a149);
  a154=(a154+a160);
  a160=(a044*a149);
  a161=(a056*a160);
  a154=(a154+a161);
  a161=(a047*a156);
  a154=(a154+a161);
  a154=(a154/a001);
  if (res[0]!=0) res[0][139]=a154;
  a151=(a047*a151);
  a028=(a035*a028);
  a151=(a151-a028);
  a159=(a110*a159);
  a151=(a151-a159);
  a158=(a114*a158);
  a151=(a151+a158);
  a160=(a034*a160);
  a151=(a151-a160);
  a141=(a046*a141);
  a151=(a151+a141);
  a151=(a151/a001);
  if (res[0]!=0) res[0][140]=a151;
  a112=(a006*a112);
  a141=(a136*a112);
  a160=(a141-a017);
  a157=(a083*a157);
  a158=(a063*a156);
  a159=(a088*a158);
  a157=(a157-a159);
  a160=(a160+a157);
  a147=(a125*a147);
  a157=(a084*a143);
  a159=(a117*a157);
  a147=(a147+a159);
  a160=(a160+a147);
  a153=(a113*a153);
  a143=(a063*a143);
  a147=(a120*a143);
  a153=(a153+a147);
  a160=(a160-a153);
  a045=(a097*a045);
  a153=(a084*a149);
  a147=(a075*a153);
  a045=(a045+a147);
  a160=(a160+a045);
  a155=(a043*a155);
  a149=(a063*a149);
  a045=(a087*a149);
  a155=(a155+a045);
  a160=(a160-a155);
  a049=(a148*a049);
  a156=(a084*a156);
  a155=(a076*a156);
  a049=(a049-a155);
  a160=(a160-a049);
  a160=(a160/a001);
  if (res[0]!=0) res[0][141]=a160;
  a052=(a006*a052);
  a049=(a136*a052);
  a155=(a094+a049);
  a045=(a040*a112);
  a155=(a155+a045);
  a147=(a107*a111);
  a147=(a030-a147);
  a159=(a118*a147);
  a028=(a124*a111);
  a145=(a145-a028);
  a028=(a116*a145);
  a159=(a159-a028);
  a111=(a053*a111);
  a111=(a111+a130);
  a028=(a119*a111);
  a159=(a159-a028);
  a028=(a125*a159);
  a157=(a121*a157);
  a028=(a028+a157);
  a155=(a155-a028);
  a028=(a060*a147);
  a157=(a062*a145);
  a028=(a028-a157);
  a157=(a079*a111);
  a028=(a028-a157);
  a157=(a097*a028);
  a153=(a133*a153);
  a157=(a157+a153);
  a155=(a155-a157);
  a147=(a077*a147);
  a145=(a064*a145);
  a147=(a147-a145);
  a111=(a080*a111);
  a147=(a147-a111);
  a111=(a148*a147);
  a156=(a127*a156);
  a111=(a111-a156);
  a155=(a155+a111);
  a155=(a155/a001);
  if (res[0]!=0) res[0][142]=a155;
  a136=(a136*a038);
  a040=(a040*a095);
  a111=(a136+a040);
  a147=(a083*a147);
  a158=(a127*a158);
  a147=(a147-a158);
  a111=(a111-a147);
  a159=(a113*a159);
  a143=(a121*a143);
  a159=(a159+a143);
  a111=(a111+a159);
  a028=(a043*a028);
  a149=(a133*a149);
  a028=(a028+a149);
  a111=(a111+a028);
  a111=(a111/a001);
  if (res[0]!=0) res[0][143]=a111;
  if (res[0]!=0) res[0][144]=a004;
  if (res[0]!=0) res[0][145]=a004;
  if (res[0]!=0) res[0][146]=a004;
  a028=(a059*a112);
  a138=(a138+a028);
  a138=(a138+a017);
  a138=(a138+a141);
  a138=(-a138);
  if (res[0]!=0) res[0][147]=a138;
  a052=(a059*a052);
  a009=(a009+a052);
  a052=(a128*a112);
  a009=(a009+a052);
  a009=(a009+a094);
  a009=(a009+a049);
  a009=(a009+a045);
  a009=(-a009);
  if (res[0]!=0) res[0][148]=a009;
  a059=(a059*a038);
  a128=(a128*a095);
  a059=(a059-a128);
  a059=(a059+a136);
  a059=(a059-a040);
  a059=(-a059);
  if (res[0]!=0) res[0][149]=a059;
  if (res[0]!=0) res[0][150]=a004;
  if (res[0]!=0) res[0][151]=a004;
  if (res[0]!=0) res[0][152]=a004;
  if (res[0]!=0) res[0][153]=a004;
  if (res[0]!=0) res[0][154]=a004;
  a136=7.4999999999999997e-02;
  a136=(a136*a001);
  a136=(a136/a003);
  if (res[0]!=0) res[0][155]=a136;
  if (res[0]!=0) res[0][156]=a004;
  if (res[0]!=0) res[0][157]=a004;
  if (res[0]!=0) res[0][158]=a004;
  if (res[0]!=0) res[0][159]=a004;
  if (res[0]!=0) res[0][160]=a004;
  if (res[0]!=0) res[0][161]=a004;
  if (res[0]!=0) res[0][162]=a004;
  if (res[0]!=0) res[0][163]=a004;
  if (res[0]!=0) res[0][164]=a004;
  if (res[0]!=0) res[0][165]=a004;
  if (res[0]!=0) res[0][166]=a004;
  if (res[0]!=0) res[0][167]=a004;
  a095=(2.*a070);
  a095=(a095*a003);
  a069=(a069*a095);
  a082=(a082*a069);
  a082=(a005-a082);
  a038=(a080*a082);
  a074=(a074*a069);
  a074=(a074+a130);
  a049=(a064*a074);
  a094=(a002*a095);
  a072=(a072*a094);
  a078=(a078*a069);
  a078=(a072-a078);
  a094=(a077*a078);
  a049=(a049+a094);
  a038=(a038-a049);
  a049=(a063*a038);
  a086=(a086*a069);
  a086=(a030-a086);
  a094=(a064*a086);
  a090=(a090*a069);
  a005=(a005-a090);
  a090=(a077*a005);
  a094=(a094+a090);
  a092=(a092*a069);
  a090=(a080*a092);
  a094=(a094+a090);
  a090=(a084*a094);
  a049=(a049+a090);
  a049=(2.*a049);
  a049=(a001*a049);
  a090=(a022*a049);
  a141=(a057*a090);
  a017=(a119*a082);
  a028=(a116*a074);
  a149=(a118*a078);
  a028=(a028+a149);
  a017=(a017-a028);
  a028=(a063*a017);
  a149=(a116*a086);
  a159=(a118*a005);
  a149=(a149+a159);
  a159=(a119*a092);
  a149=(a149+a159);
  a159=(a084*a149);
  a028=(a028+a159);
  a028=(2.*a028);
  a028=(a001*a028);
  a159=(a110*a028);
  a141=(a141+a159);
  a159=(a022*a028);
  a143=(a115*a159);
  a141=(a141+a143);
  a082=(a079*a082);
  a074=(a062*a074);
  a078=(a060*a078);
  a074=(a074+a078);
  a082=(a082-a074);
  a074=(a063*a082);
  a086=(a062*a086);
  a005=(a060*a005);
  a086=(a086+a005);
  a092=(a079*a092);
  a086=(a086+a092);
  a092=(a084*a086);
  a074=(a074+a092);
  a074=(2.*a074);
  a074=(a001*a074);
  a092=(a034*a074);
  a141=(a141+a092);
  a022=(a022*a074);
  a092=(a056*a022);
  a141=(a141+a092);
  a092=(a035*a049);
  a141=(a141+a092);
  a141=(a141/a001);
  a141=(-a141);
  if (res[0]!=0) res[0][168]=a141;
  a092=(a044*a049);
  a057=(a057*a092);
  a005=(a114*a028);
  a057=(a057+a005);
  a005=(a044*a028);
  a115=(a115*a005);
  a057=(a057+a115);
  a115=(a046*a074);
  a057=(a057+a115);
  a044=(a044*a074);
  a056=(a056*a044);
  a057=(a057+a056);
  a056=(a047*a049);
  a057=(a057+a056);
  a057=(a057/a001);
  if (res[0]!=0) res[0][169]=a057;
  a047=(a047*a090);
  a035=(a035*a092);
  a047=(a047-a035);
  a110=(a110*a005);
  a047=(a047-a110);
  a114=(a114*a159);
  a047=(a047+a114);
  a034=(a034*a044);
  a047=(a047-a034);
  a046=(a046*a022);
  a047=(a047+a046);
  a047=(a047/a001);
  if (res[0]!=0) res[0][170]=a047;
  a046=(a033*a112);
  a022=(a046+a093);
  a094=(a083*a094);
  a034=(a063*a049);
  a088=(a088*a034);
  a094=(a094-a088);
  a022=(a022+a094);
  a017=(a125*a017);
  a094=(a084*a028);
  a117=(a117*a094);
  a017=(a017+a117);
  a022=(a022+a017);
  a149=(a113*a149);
  a028=(a063*a028);
  a120=(a120*a028);
  a149=(a149+a120);
  a022=(a022-a149);
  a082=(a097*a082);
  a149=(a084*a074);
  a075=(a075*a149);
  a082=(a082+a075);
  a022=(a022+a082);
  a086=(a043*a086);
  a063=(a063*a074);
  a087=(a087*a063);
  a086=(a086+a087);
  a022=(a022-a086);
  a038=(a148*a038);
  a084=(a084*a049);
  a076=(a076*a084);
  a038=(a038-a076);
  a022=(a022-a038);
  a022=(a022/a001);
  if (res[0]!=0) res[0][171]=a022;
  a038=(a033*a015);
  a076=(a038-a040);
  a107=(a107*a069);
  a130=(a130-a107);
  a118=(a118*a130);
  a124=(a124*a069);
  a072=(a072-a124);
  a116=(a116*a072);
  a118=(a118-a116);
  a053=(a053*a069);
  a030=(a030-a053);
  a119=(a119*a030);
  a118=(a118+a119);
  a125=(a125*a118);
  a094=(a121*a094);
  a125=(a125+a094);
  a076=(a076-a125);
  a060=(a060*a130);
  a062=(a062*a072);
  a060=(a060-a062);
  a079=(a079*a030);
  a060=(a060+a079);
  a097=(a097*a060);
  a149=(a133*a149);
  a097=(a097+a149);
  a076=(a076-a097);
  a077=(a077*a130);
  a064=(a064*a072);
  a077=(a077-a064);
  a080=(a080*a030);
  a077=(a077+a080);
  a148=(a148*a077);
  a084=(a127*a084);
  a148=(a148-a084);
  a076=(a076+a148);
  a076=(a076/a001);
  if (res[0]!=0) res[0][172]=a076;
  a006=(a006*a095);
  a033=(a033*a006);
  a095=(a033+a108);
  a095=(a095+a045);
  a083=(a083*a077);
  a127=(a127*a034);
  a083=(a083-a127);
  a095=(a095-a083);
  a113=(a113*a118);
  a121=(a121*a028);
  a113=(a113+a121);
  a095=(a095+a113);
  a043=(a043*a060);
  a133=(a133*a063);
  a043=(a043+a133);
  a095=(a095+a043);
  a095=(a095/a001);
  if (res[0]!=0) res[0][173]=a095;
  if (res[0]!=0) res[0][174]=a004;
  if (res[0]!=0) res[0][175]=a004;
  if (res[0]!=0) res[0][176]=a004;
  a112=(a096*a112);
  a112=(a112-a023);
  a112=(a112+a046);
  a112=(a112-a093);
  a112=(-a112);
  if (res[0]!=0) res[0][177]=a112;
  a015=(a096*a015);
  a015=(a015+a128);
  a015=(a015+a038);
  a015=(a015+a040);
  a015=(-a015);
  if (res[0]!=0) res[0][178]=a015;
  a096=(a096*a006);
  a096=(a096+a024);
  a096=(a096+a052);
  a096=(a096+a033);
  a096=(a096+a108);
  a096=(a096+a045);
  a096=(-a096);
  if (res[0]!=0) res[0][179]=a096;
  if (res[0]!=0) res[0][180]=a004;
  if (res[0]!=0) res[0][181]=a004;
  if (res[0]!=0) res[0][182]=a004;
  if (res[0]!=0) res[0][183]=a004;
  if (res[0]!=0) res[0][184]=a004;
  if (res[0]!=0) res[0][185]=a004;
  if (res[0]!=0) res[0][186]=a000;
  if (res[0]!=0) res[0][187]=a004;
  if (res[0]!=0) res[0][188]=a004;
  if (res[0]!=0) res[0][189]=a004;
  if (res[0]!=0) res[0][190]=a004;
  if (res[0]!=0) res[0][191]=a004;
  if (res[0]!=0) res[0][192]=a004;
  if (res[0]!=0) res[0][193]=a004;
  if (res[0]!=0) res[0][194]=a004;
  if (res[0]!=0) res[0][195]=a004;
  if (res[0]!=0) res[0][196]=a004;
  if (res[0]!=0) res[0][197]=a004;
  if (res[0]!=0) res[0][198]=a016;
  if (res[0]!=0) res[0][199]=a091;
  if (res[0]!=0) res[0][200]=a131;
  if (res[0]!=0) res[0][201]=a098;
  if (res[0]!=0) res[0][202]=a106;
  if (res[0]!=0) res[0][203]=a102;
  if (res[0]!=0) res[0][204]=a109;
  if (res[0]!=0) res[0][205]=a021;
  if (res[0]!=0) res[0][206]=a134;
  if (res[0]!=0) res[0][207]=a004;
  if (res[0]!=0) res[0][208]=a004;
  if (res[0]!=0) res[0][209]=a004;
  if (res[0]!=0) res[0][210]=a004;
  if (res[0]!=0) res[0][211]=a004;
  if (res[0]!=0) res[0][212]=a004;
  if (res[0]!=0) res[0][213]=a004;
  if (res[0]!=0) res[0][214]=a004;
  if (res[0]!=0) res[0][215]=a004;
  if (res[0]!=0) res[0][216]=a004;
  if (res[0]!=0) res[0][217]=a037;
  if (res[0]!=0) res[0][218]=a004;
  if (res[0]!=0) res[0][219]=a004;
  if (res[0]!=0) res[0][220]=a004;
  if (res[0]!=0) res[0][221]=a004;
  if (res[0]!=0) res[0][222]=a004;
  if (res[0]!=0) res[0][223]=a004;
  if (res[0]!=0) res[0][224]=a004;
  if (res[0]!=0) res[0][225]=a004;
  if (res[0]!=0) res[0][226]=a004;
  if (res[0]!=0) res[0][227]=a004;
  if (res[0]!=0) res[0][228]=a137;
  if (res[0]!=0) res[0][229]=a142;
  if (res[0]!=0) res[0][230]=a140;
  if (res[0]!=0) res[0][231]=a144;
  if (res[0]!=0) res[0][232]=a150;
  if (res[0]!=0) res[0][233]=a146;
  if (res[0]!=0) res[0][234]=a020;
  if (res[0]!=0) res[0][235]=a123;
  if (res[0]!=0) res[0][236]=a105;
  if (res[0]!=0) res[0][237]=a004;
  if (res[0]!=0) res[0][238]=a004;
  if (res[0]!=0) res[0][239]=a004;
  if (res[0]!=0) res[0][240]=a004;
  if (res[0]!=0) res[0][241]=a004;
  if (res[0]!=0) res[0][242]=a004;
  if (res[0]!=0) res[0][243]=a004;
  if (res[0]!=0) res[0][244]=a004;
  if (res[0]!=0) res[0][245]=a004;
  if (res[0]!=0) res[0][246]=a004;
  if (res[0]!=0) res[0][247]=a004;
  if (res[0]!=0) res[0][248]=a011;
  if (res[0]!=0) res[0][249]=a004;
  if (res[0]!=0) res[0][250]=a004;
  if (res[0]!=0) res[0][251]=a004;
  if (res[0]!=0) res[0][252]=a004;
  if (res[0]!=0) res[0][253]=a004;
  if (res[0]!=0) res[0][254]=a004;
  if (res[0]!=0) res[0][255]=a004;
  if (res[0]!=0) res[0][256]=a004;
  if (res[0]!=0) res[0][257]=a004;
  if (res[0]!=0) res[0][258]=a008;
  if (res[0]!=0) res[0][259]=a061;
  if (res[0]!=0) res[0][260]=a100;
  if (res[0]!=0) res[0][261]=a039;
  if (res[0]!=0) res[0][262]=a104;
  if (res[0]!=0) res[0][263]=a099;
  if (res[0]!=0) res[0][264]=a135;
  if (res[0]!=0) res[0][265]=a014;
  if (res[0]!=0) res[0][266]=a019;
  if (res[0]!=0) res[0][267]=a004;
  if (res[0]!=0) res[0][268]=a004;
  if (res[0]!=0) res[0][269]=a004;
  if (res[0]!=0) res[0][270]=a004;
  if (res[0]!=0) res[0][271]=a004;
  if (res[0]!=0) res[0][272]=a004;
  if (res[0]!=0) res[0][273]=a004;
  if (res[0]!=0) res[0][274]=a004;
  if (res[0]!=0) res[0][275]=a004;
  if (res[0]!=0) res[0][276]=a004;
  if (res[0]!=0) res[0][277]=a004;
  if (res[0]!=0) res[0][278]=a004;
  if (res[0]!=0) res[0][279]=a139;
  if (res[0]!=0) res[0][280]=a004;
  if (res[0]!=0) res[0][281]=a004;
  if (res[0]!=0) res[0][282]=a004;
  if (res[0]!=0) res[0][283]=a004;
  if (res[0]!=0) res[0][284]=a004;
  if (res[0]!=0) res[0][285]=a004;
  if (res[0]!=0) res[0][286]=a004;
  if (res[0]!=0) res[0][287]=a004;
  if (res[0]!=0) res[0][288]=a122;
  if (res[0]!=0) res[0][289]=a129;
  if (res[0]!=0) res[0][290]=a013;
  if (res[0]!=0) res[0][291]=a101;
  if (res[0]!=0) res[0][292]=a010;
  if (res[0]!=0) res[0][293]=a055;
  if (res[0]!=0) res[0][294]=a004;
  if (res[0]!=0) res[0][295]=a004;
  if (res[0]!=0) res[0][296]=a004;
  if (res[0]!=0) res[0][297]=a126;
  if (res[0]!=0) res[0][298]=a036;
  if (res[0]!=0) res[0][299]=a042;
  if (res[0]!=0) res[0][300]=a004;
  if (res[0]!=0) res[0][301]=a004;
  if (res[0]!=0) res[0][302]=a004;
  if (res[0]!=0) res[0][303]=a004;
  if (res[0]!=0) res[0][304]=a004;
  if (res[0]!=0) res[0][305]=a004;
  if (res[0]!=0) res[0][306]=a004;
  if (res[0]!=0) res[0][307]=a004;
  if (res[0]!=0) res[0][308]=a004;
  if (res[0]!=0) res[0][309]=a004;
  if (res[0]!=0) res[0][310]=a132;
  if (res[0]!=0) res[0][311]=a004;
  if (res[0]!=0) res[0][312]=a004;
  if (res[0]!=0) res[0][313]=a004;
  if (res[0]!=0) res[0][314]=a004;
  if (res[0]!=0) res[0][315]=a004;
  if (res[0]!=0) res[0][316]=a004;
  if (res[0]!=0) res[0][317]=a004;
  if (res[0]!=0) res[0][318]=a152;
  if (res[0]!=0) res[0][319]=a154;
  if (res[0]!=0) res[0][320]=a151;
  if (res[0]!=0) res[0][321]=a160;
  if (res[0]!=0) res[0][322]=a155;
  if (res[0]!=0) res[0][323]=a111;
  if (res[0]!=0) res[0][324]=a004;
  if (res[0]!=0) res[0][325]=a004;
  if (res[0]!=0) res[0][326]=a004;
  if (res[0]!=0) res[0][327]=a138;
  if (res[0]!=0) res[0][328]=a009;
  if (res[0]!=0) res[0][329]=a059;
  if (res[0]!=0) res[0][330]=a004;
  if (res[0]!=0) res[0][331]=a004;
  if (res[0]!=0) res[0][332]=a004;
  if (res[0]!=0) res[0][333]=a004;
  if (res[0]!=0) res[0][334]=a004;
  if (res[0]!=0) res[0][335]=a004;
  if (res[0]!=0) res[0][336]=a004;
  if (res[0]!=0) res[0][337]=a004;
  if (res[0]!=0) res[0][338]=a004;
  if (res[0]!=0) res[0][339]=a004;
  if (res[0]!=0) res[0][340]=a004;
  if (res[0]!=0) res[0][341]=a136;
  if (res[0]!=0) res[0][342]=a004;
  if (res[0]!=0) res[0][343]=a004;
  if (res[0]!=0) res[0][344]=a004;
  if (res[0]!=0) res[0][345]=a004;
  if (res[0]!=0) res[0][346]=a004;
  if (res[0]!=0) res[0][347]=a004;
  if (res[0]!=0) res[0][348]=a141;
  if (res[0]!=0) res[0][349]=a057;
  if (res[0]!=0) res[0][350]=a047;
  if (res[0]!=0) res[0][351]=a022;
  if (res[0]!=0) res[0][352]=a076;
  if (res[0]!=0) res[0][353]=a095;
  if (res[0]!=0) res[0][354]=a004;
  if (res[0]!=0) res[0][355]=a004;
  if (res[0]!=0) res[0][356]=a004;
  if (res[0]!=0) res[0][357]=a112;
  if (res[0]!=0) res[0][358]=a015;
  if (res[0]!=0) res[0][359]=a096;
  if (res[0]!=0) res[0][360]=a004;
  if (res[0]!=0) res[0][361]=a004;
  if (res[0]!=0) res[0][362]=a004;
  if (res[0]!=0) res[0][363]=a004;
  if (res[0]!=0) res[0][364]=a004;
  if (res[0]!=0) res[0][365]=a004;
  if (res[0]!=0) res[0][366]=a004;
  if (res[0]!=0) res[0][367]=a004;
  if (res[0]!=0) res[0][368]=a004;
  if (res[0]!=0) res[0][369]=a004;
  if (res[0]!=0) res[0][370]=a004;
  if (res[0]!=0) res[0][371]=a004;
  if (res[0]!=0) res[0][372]=a037;
  if (res[0]!=0) res[0][373]=a004;
  if (res[0]!=0) res[0][374]=a004;
  if (res[0]!=0) res[0][375]=a004;
  if (res[0]!=0) res[0][376]=a004;
  if (res[0]!=0) res[0][377]=a004;
  if (res[0]!=0) res[0][378]=a004;
  if (res[0]!=0) res[0][379]=a004;
  if (res[0]!=0) res[0][380]=a004;
  if (res[0]!=0) res[0][381]=a004;
  if (res[0]!=0) res[0][382]=a004;
  if (res[0]!=0) res[0][383]=a004;
  a096=(-a001);
  if (res[0]!=0) res[0][384]=a096;
  if (res[0]!=0) res[0][385]=a004;
  if (res[0]!=0) res[0][386]=a004;
  if (res[0]!=0) res[0][387]=a004;
  if (res[0]!=0) res[0][388]=a004;
  if (res[0]!=0) res[0][389]=a004;
  if (res[0]!=0) res[0][390]=a004;
  if (res[0]!=0) res[0][391]=a004;
  if (res[0]!=0) res[0][392]=a004;
  if (res[0]!=0) res[0][393]=a004;
  if (res[0]!=0) res[0][394]=a004;
  if (res[0]!=0) res[0][395]=a004;
  if (res[0]!=0) res[0][396]=a004;
  if (res[0]!=0) res[0][397]=a004;
  if (res[0]!=0) res[0][398]=a004;
  if (res[0]!=0) res[0][399]=a004;
  if (res[0]!=0) res[0][400]=a004;
  if (res[0]!=0) res[0][401]=a004;
  if (res[0]!=0) res[0][402]=a004;
  if (res[0]!=0) res[0][403]=a037;
  if (res[0]!=0) res[0][404]=a004;
  if (res[0]!=0) res[0][405]=a004;
  if (res[0]!=0) res[0][406]=a004;
  if (res[0]!=0) res[0][407]=a004;
  if (res[0]!=0) res[0][408]=a004;
  if (res[0]!=0) res[0][409]=a004;
  if (res[0]!=0) res[0][410]=a004;
  if (res[0]!=0) res[0][411]=a004;
  if (res[0]!=0) res[0][412]=a004;
  if (res[0]!=0) res[0][413]=a004;
  if (res[0]!=0) res[0][414]=a004;
  if (res[0]!=0) res[0][415]=a096;
  if (res[0]!=0) res[0][416]=a004;
  if (res[0]!=0) res[0][417]=a004;
  if (res[0]!=0) res[0][418]=a004;
  if (res[0]!=0) res[0][419]=a004;
  if (res[0]!=0) res[0][420]=a004;
  if (res[0]!=0) res[0][421]=a004;
  if (res[0]!=0) res[0][422]=a004;
  if (res[0]!=0) res[0][423]=a004;
  if (res[0]!=0) res[0][424]=a004;
  if (res[0]!=0) res[0][425]=a004;
  if (res[0]!=0) res[0][426]=a004;
  if (res[0]!=0) res[0][427]=a004;
  if (res[0]!=0) res[0][428]=a004;
  if (res[0]!=0) res[0][429]=a004;
  if (res[0]!=0) res[0][430]=a004;
  if (res[0]!=0) res[0][431]=a004;
  if (res[0]!=0) res[0][432]=a004;
  if (res[0]!=0) res[0][433]=a004;
  if (res[0]!=0) res[0][434]=a037;
  if (res[0]!=0) res[0][435]=a004;
  if (res[0]!=0) res[0][436]=a004;
  if (res[0]!=0) res[0][437]=a004;
  if (res[0]!=0) res[0][438]=a004;
  if (res[0]!=0) res[0][439]=a004;
  if (res[0]!=0) res[0][440]=a004;
  if (res[0]!=0) res[0][441]=a004;
  if (res[0]!=0) res[0][442]=a004;
  if (res[0]!=0) res[0][443]=a004;
  if (res[0]!=0) res[0][444]=a004;
  if (res[0]!=0) res[0][445]=a004;
  if (res[0]!=0) res[0][446]=a096;
  if (res[0]!=0) res[0][447]=a004;
  if (res[0]!=0) res[0][448]=a004;
  if (res[0]!=0) res[0][449]=a004;
  if (res[0]!=0) res[0][450]=a004;
  if (res[0]!=0) res[0][451]=a004;
  if (res[0]!=0) res[0][452]=a004;
  if (res[0]!=0) res[0][453]=a004;
  if (res[0]!=0) res[0][454]=a004;
  if (res[0]!=0) res[0][455]=a004;
  if (res[0]!=0) res[0][456]=a004;
  if (res[0]!=0) res[0][457]=a004;
  if (res[0]!=0) res[0][458]=a004;
  if (res[0]!=0) res[0][459]=a004;
  if (res[0]!=0) res[0][460]=a004;
  if (res[0]!=0) res[0][461]=a004;
  if (res[0]!=0) res[0][462]=a004;
  if (res[0]!=0) res[0][463]=a004;
  if (res[0]!=0) res[0][464]=a004;
  if (res[0]!=0) res[0][465]=a037;
  if (res[0]!=0) res[0][466]=a004;
  if (res[0]!=0) res[0][467]=a004;
  if (res[0]!=0) res[0][468]=a004;
  if (res[0]!=0) res[0][469]=a004;
  if (res[0]!=0) res[0][470]=a004;
  if (res[0]!=0) res[0][471]=a004;
  if (res[0]!=0) res[0][472]=a004;
  if (res[0]!=0) res[0][473]=a004;
  if (res[0]!=0) res[0][474]=a004;
  if (res[0]!=0) res[0][475]=a004;
  if (res[0]!=0) res[0][476]=a004;
  if (res[0]!=0) res[0][477]=a096;
  if (res[0]!=0) res[0][478]=a004;
  if (res[0]!=0) res[0][479]=a004;
  if (res[0]!=0) res[0][480]=a004;
  if (res[0]!=0) res[0][481]=a004;
  if (res[0]!=0) res[0][482]=a004;
  if (res[0]!=0) res[0][483]=a004;
  if (res[0]!=0) res[0][484]=a004;
  if (res[0]!=0) res[0][485]=a004;
  if (res[0]!=0) res[0][486]=a004;
  if (res[0]!=0) res[0][487]=a004;
  if (res[0]!=0) res[0][488]=a004;
  if (res[0]!=0) res[0][489]=a004;
  if (res[0]!=0) res[0][490]=a004;
  if (res[0]!=0) res[0][491]=a004;
  if (res[0]!=0) res[0][492]=a004;
  if (res[0]!=0) res[0][493]=a004;
  if (res[0]!=0) res[0][494]=a004;
  if (res[0]!=0) res[0][495]=a004;
  if (res[0]!=0) res[0][496]=a037;
  if (res[0]!=0) res[0][497]=a004;
  if (res[0]!=0) res[0][498]=a004;
  if (res[0]!=0) res[0][499]=a004;
  if (res[0]!=0) res[0][500]=a004;
  if (res[0]!=0) res[0][501]=a004;
  if (res[0]!=0) res[0][502]=a004;
  if (res[0]!=0) res[0][503]=a004;
  if (res[0]!=0) res[0][504]=a004;
  if (res[0]!=0) res[0][505]=a004;
  if (res[0]!=0) res[0][506]=a004;
  if (res[0]!=0) res[0][507]=a004;
  if (res[0]!=0) res[0][508]=a096;
  if (res[0]!=0) res[0][509]=a004;
  if (res[0]!=0) res[0][510]=a004;
  if (res[0]!=0) res[0][511]=a004;
  if (res[0]!=0) res[0][512]=a004;
  if (res[0]!=0) res[0][513]=a004;
  if (res[0]!=0) res[0][514]=a004;
  if (res[0]!=0) res[0][515]=a004;
  if (res[0]!=0) res[0][516]=a004;
  if (res[0]!=0) res[0][517]=a004;
  if (res[0]!=0) res[0][518]=a004;
  if (res[0]!=0) res[0][519]=a004;
  if (res[0]!=0) res[0][520]=a004;
  if (res[0]!=0) res[0][521]=a004;
  if (res[0]!=0) res[0][522]=a004;
  if (res[0]!=0) res[0][523]=a004;
  if (res[0]!=0) res[0][524]=a004;
  if (res[0]!=0) res[0][525]=a004;
  if (res[0]!=0) res[0][526]=a004;
  if (res[0]!=0) res[0][527]=a037;
  if (res[0]!=0) res[0][528]=a004;
  if (res[0]!=0) res[0][529]=a004;
  if (res[0]!=0) res[0][530]=a004;
  if (res[0]!=0) res[0][531]=a004;
  if (res[0]!=0) res[0][532]=a004;
  if (res[0]!=0) res[0][533]=a004;
  if (res[0]!=0) res[0][534]=a004;
  if (res[0]!=0) res[0][535]=a004;
  if (res[0]!=0) res[0][536]=a004;
  if (res[0]!=0) res[0][537]=a004;
  if (res[0]!=0) res[0][538]=a004;
  if (res[0]!=0) res[0][539]=a096;
  a096=casadi_sq(a001);
  a002=(a002*a096);
  a002=(a002/a003);
  a002=(-a002);
  if (res[0]!=0) res[0][540]=a002;
  if (res[0]!=0) res[0][541]=a004;
  if (res[0]!=0) res[0][542]=a004;
  if (res[0]!=0) res[0][543]=a004;
  if (res[0]!=0) res[0][544]=a004;
  if (res[0]!=0) res[0][545]=a004;
  if (res[0]!=0) res[0][546]=a002;
  if (res[0]!=0) res[0][547]=a004;
  if (res[0]!=0) res[0][548]=a004;
  if (res[0]!=0) res[0][549]=a004;
  if (res[0]!=0) res[0][550]=a004;
  if (res[0]!=0) res[0][551]=a004;
  if (res[0]!=0) res[0][552]=a004;
  if (res[0]!=0) res[0][553]=a004;
  if (res[0]!=0) res[0][554]=a004;
  if (res[0]!=0) res[0][555]=a004;
  if (res[0]!=0) res[0][556]=a004;
  if (res[0]!=0) res[0][557]=a004;
  a026=(a026/a025);
  a026=(a037+a026);
  if (res[0]!=0) res[0][558]=a026;
  a048=(a048/a025);
  a007=(a007/a032);
  a003=(a048-a007);
  if (res[0]!=0) res[0][559]=a003;
  a012=(a012/a032);
  a051=(a051/a025);
  a003=(a012+a051);
  if (res[0]!=0) res[0][560]=a003;
  if (res[0]!=0) res[0][561]=a004;
  if (res[0]!=0) res[0][562]=a004;
  if (res[0]!=0) res[0][563]=a004;
  a003=(a026*a001);
  a003=(-a003);
  if (res[0]!=0) res[0][564]=a003;
  a048=(a007+a048);
  a003=(a048*a001);
  a003=(-a003);
  if (res[0]!=0) res[0][565]=a003;
  a051=(a051-a012);
  a003=(a051*a001);
  a003=(-a003);
  if (res[0]!=0) res[0][566]=a003;
  if (res[0]!=0) res[0][567]=a004;
  if (res[0]!=0) res[0][568]=a004;
  if (res[0]!=0) res[0][569]=a004;
  if (res[0]!=0) res[0][570]=a004;
  if (res[0]!=0) res[0][571]=a002;
  if (res[0]!=0) res[0][572]=a004;
  if (res[0]!=0) res[0][573]=a004;
  if (res[0]!=0) res[0][574]=a004;
  if (res[0]!=0) res[0][575]=a004;
  if (res[0]!=0) res[0][576]=a004;
  if (res[0]!=0) res[0][577]=a002;
  if (res[0]!=0) res[0][578]=a004;
  if (res[0]!=0) res[0][579]=a004;
  if (res[0]!=0) res[0][580]=a004;
  if (res[0]!=0) res[0][581]=a004;
  if (res[0]!=0) res[0][582]=a004;
  if (res[0]!=0) res[0][583]=a004;
  if (res[0]!=0) res[0][584]=a004;
  if (res[0]!=0) res[0][585]=a004;
  if (res[0]!=0) res[0][586]=a004;
  if (res[0]!=0) res[0][587]=a004;
  a031=(a031/a025);
  a003=(a007+a031);
  if (res[0]!=0) res[0][588]=a003;
  a027=(a027/a025);
  a027=(a037+a027);
  if (res[0]!=0) res[0][589]=a027;
  a041=(a041/a025);
  a018=(a018/a032);
  a003=(a041-a018);
  if (res[0]!=0) res[0][590]=a003;
  if (res[0]!=0) res[0][591]=a004;
  if (res[0]!=0) res[0][592]=a004;
  if (res[0]!=0) res[0][593]=a004;
  a031=(a031-a007);
  a007=(a031*a001);
  a007=(-a007);
  if (res[0]!=0) res[0][594]=a007;
  a007=(a027*a001);
  a007=(-a007);
  if (res[0]!=0) res[0][595]=a007;
  a041=(a018+a041);
  a007=(a041*a001);
  a007=(-a007);
  if (res[0]!=0) res[0][596]=a007;
  if (res[0]!=0) res[0][597]=a004;
  if (res[0]!=0) res[0][598]=a004;
  if (res[0]!=0) res[0][599]=a004;
  if (res[0]!=0) res[0][600]=a004;
  if (res[0]!=0) res[0][601]=a004;
  if (res[0]!=0) res[0][602]=a002;
  if (res[0]!=0) res[0][603]=a004;
  if (res[0]!=0) res[0][604]=a004;
  if (res[0]!=0) res[0][605]=a004;
  if (res[0]!=0) res[0][606]=a004;
  if (res[0]!=0) res[0][607]=a004;
  if (res[0]!=0) res[0][608]=a002;
  if (res[0]!=0) res[0][609]=a004;
  if (res[0]!=0) res[0][610]=a004;
  if (res[0]!=0) res[0][611]=a004;
  if (res[0]!=0) res[0][612]=a004;
  if (res[0]!=0) res[0][613]=a004;
  if (res[0]!=0) res[0][614]=a004;
  if (res[0]!=0) res[0][615]=a004;
  if (res[0]!=0) res[0][616]=a004;
  if (res[0]!=0) res[0][617]=a004;
  a054=(a054/a025);
  a007=(a054-a012);
  if (res[0]!=0) res[0][618]=a007;
  a058=(a058/a025);
  a007=(a018+a058);
  if (res[0]!=0) res[0][619]=a007;
  a029=(a029/a025);
  a029=(a037+a029);
  if (res[0]!=0) res[0][620]=a029;
  if (res[0]!=0) res[0][621]=a004;
  if (res[0]!=0) res[0][622]=a004;
  if (res[0]!=0) res[0][623]=a004;
  a012=(a012+a054);
  a054=(a012*a001);
  a054=(-a054);
  if (res[0]!=0) res[0][624]=a054;
  a058=(a058-a018);
  a018=(a058*a001);
  a018=(-a018);
  if (res[0]!=0) res[0][625]=a018;
  a018=(a029*a001);
  a018=(-a018);
  if (res[0]!=0) res[0][626]=a018;
  if (res[0]!=0) res[0][627]=a004;
  if (res[0]!=0) res[0][628]=a004;
  if (res[0]!=0) res[0][629]=a004;
  if (res[0]!=0) res[0][630]=a004;
  if (res[0]!=0) res[0][631]=a004;
  if (res[0]!=0) res[0][632]=a004;
  if (res[0]!=0) res[0][633]=a002;
  if (res[0]!=0) res[0][634]=a004;
  if (res[0]!=0) res[0][635]=a004;
  if (res[0]!=0) res[0][636]=a004;
  if (res[0]!=0) res[0][637]=a004;
  if (res[0]!=0) res[0][638]=a004;
  if (res[0]!=0) res[0][639]=a002;
  if (res[0]!=0) res[0][640]=a004;
  if (res[0]!=0) res[0][641]=a004;
  if (res[0]!=0) res[0][642]=a004;
  if (res[0]!=0) res[0][643]=a004;
  if (res[0]!=0) res[0][644]=a004;
  if (res[0]!=0) res[0][645]=a004;
  if (res[0]!=0) res[0][646]=a004;
  if (res[0]!=0) res[0][647]=a004;
  if (res[0]!=0) res[0][648]=a004;
  if (res[0]!=0) res[0][649]=a004;
  if (res[0]!=0) res[0][650]=a004;
  a066=(a066/a025);
  a066=(a037+a066);
  if (res[0]!=0) res[0][651]=a066;
  a050=(a050/a025);
  a070=(a070/a032);
  a018=(a050-a070);
  if (res[0]!=0) res[0][652]=a018;
  a067=(a067/a032);
  a103=(a103/a025);
  a018=(a067+a103);
  if (res[0]!=0) res[0][653]=a018;
  if (res[0]!=0) res[0][654]=a004;
  if (res[0]!=0) res[0][655]=a004;
  if (res[0]!=0) res[0][656]=a004;
  a018=(a066*a001);
  a018=(-a018);
  if (res[0]!=0) res[0][657]=a018;
  a050=(a070+a050);
  a018=(a050*a001);
  a018=(-a018);
  if (res[0]!=0) res[0][658]=a018;
  a103=(a103-a067);
  a018=(a103*a001);
  a018=(-a018);
  if (res[0]!=0) res[0][659]=a018;
  if (res[0]!=0) res[0][660]=a004;
  if (res[0]!=0) res[0][661]=a004;
  if (res[0]!=0) res[0][662]=a004;
  if (res[0]!=0) res[0][663]=a004;
  if (res[0]!=0) res[0][664]=a002;
  if (res[0]!=0) res[0][665]=a004;
  if (res[0]!=0) res[0][666]=a004;
  if (res[0]!=0) res[0][667]=a004;
  if (res[0]!=0) res[0][668]=a004;
  if (res[0]!=0) res[0][669]=a004;
  if (res[0]!=0) res[0][670]=a002;
  if (res[0]!=0) res[0][671]=a004;
  if (res[0]!=0) res[0][672]=a004;
  if (res[0]!=0) res[0][673]=a004;
  if (res[0]!=0) res[0][674]=a004;
  if (res[0]!=0) res[0][675]=a004;
  if (res[0]!=0) res[0][676]=a004;
  if (res[0]!=0) res[0][677]=a004;
  if (res[0]!=0) res[0][678]=a004;
  if (res[0]!=0) res[0][679]=a004;
  if (res[0]!=0) res[0][680]=a004;
  a073=(a073/a025);
  a018=(a070+a073);
  if (res[0]!=0) res[0][681]=a018;
  a068=(a068/a025);
  a068=(a037+a068);
  if (res[0]!=0) res[0][682]=a068;
  a081=(a081/a025);
  a065=(a065/a032);
  a032=(a081-a065);
  if (res[0]!=0) res[0][683]=a032;
  if (res[0]!=0) res[0][684]=a004;
  if (res[0]!=0) res[0][685]=a004;
  if (res[0]!=0) res[0][686]=a004;
  a073=(a073-a070);
  a070=(a073*a001);
  a070=(-a070);
  if (res[0]!=0) res[0][687]=a070;
  a070=(a068*a001);
  a070=(-a070);
  if (res[0]!=0) res[0][688]=a070;
  a081=(a065+a081);
  a070=(a081*a001);
  a070=(-a070);
  if (res[0]!=0) res[0][689]=a070;
  if (res[0]!=0) res[0][690]=a004;
  if (res[0]!=0) res[0][691]=a004;
  if (res[0]!=0) res[0][692]=a004;
  if (res[0]!=0) res[0][693]=a004;
  if (res[0]!=0) res[0][694]=a004;
  if (res[0]!=0) res[0][695]=a002;
  if (res[0]!=0) res[0][696]=a004;
  if (res[0]!=0) res[0][697]=a004;
  if (res[0]!=0) res[0][698]=a004;
  if (res[0]!=0) res[0][699]=a004;
  if (res[0]!=0) res[0][700]=a004;
  if (res[0]!=0) res[0][701]=a002;
  if (res[0]!=0) res[0][702]=a004;
  if (res[0]!=0) res[0][703]=a004;
  if (res[0]!=0) res[0][704]=a004;
  if (res[0]!=0) res[0][705]=a004;
  if (res[0]!=0) res[0][706]=a004;
  if (res[0]!=0) res[0][707]=a004;
  if (res[0]!=0) res[0][708]=a004;
  if (res[0]!=0) res[0][709]=a004;
  if (res[0]!=0) res[0][710]=a004;
  a085=(a085/a025);
  a002=(a085-a067);
  if (res[0]!=0) res[0][711]=a002;
  a089=(a089/a025);
  a002=(a065+a089);
  if (res[0]!=0) res[0][712]=a002;
  a071=(a071/a025);
  a037=(a037+a071);
  if (res[0]!=0) res[0][713]=a037;
  if (res[0]!=0) res[0][714]=a004;
  if (res[0]!=0) res[0][715]=a004;
  if (res[0]!=0) res[0][716]=a004;
  a067=(a067+a085);
  a085=(a067*a001);
  a085=(-a085);
  if (res[0]!=0) res[0][717]=a085;
  a089=(a089-a065);
  a065=(a089*a001);
  a065=(-a065);
  if (res[0]!=0) res[0][718]=a065;
  a001=(a037*a001);
  a001=(-a001);
  if (res[0]!=0) res[0][719]=a001;
  a001=-1.;
  if (res[0]!=0) res[0][720]=a001;
  if (res[0]!=0) res[0][721]=a004;
  if (res[0]!=0) res[0][722]=a004;
  if (res[0]!=0) res[0][723]=a004;
  if (res[0]!=0) res[0][724]=a004;
  if (res[0]!=0) res[0][725]=a004;
  if (res[0]!=0) res[0][726]=a001;
  if (res[0]!=0) res[0][727]=a004;
  if (res[0]!=0) res[0][728]=a004;
  if (res[0]!=0) res[0][729]=a004;
  if (res[0]!=0) res[0][730]=a004;
  if (res[0]!=0) res[0][731]=a004;
  if (res[0]!=0) res[0][732]=a004;
  if (res[0]!=0) res[0][733]=a004;
  if (res[0]!=0) res[0][734]=a004;
  if (res[0]!=0) res[0][735]=a004;
  if (res[0]!=0) res[0][736]=a004;
  if (res[0]!=0) res[0][737]=a004;
  if (res[0]!=0) res[0][738]=a004;
  if (res[0]!=0) res[0][739]=a004;
  if (res[0]!=0) res[0][740]=a004;
  if (res[0]!=0) res[0][741]=a004;
  if (res[0]!=0) res[0][742]=a004;
  if (res[0]!=0) res[0][743]=a004;
  a026=(-a026);
  if (res[0]!=0) res[0][744]=a026;
  a048=(-a048);
  if (res[0]!=0) res[0][745]=a048;
  a051=(-a051);
  if (res[0]!=0) res[0][746]=a051;
  if (res[0]!=0) res[0][747]=a004;
  if (res[0]!=0) res[0][748]=a004;
  if (res[0]!=0) res[0][749]=a004;
  if (res[0]!=0) res[0][750]=a004;
  if (res[0]!=0) res[0][751]=a001;
  if (res[0]!=0) res[0][752]=a004;
  if (res[0]!=0) res[0][753]=a004;
  if (res[0]!=0) res[0][754]=a004;
  if (res[0]!=0) res[0][755]=a004;
  if (res[0]!=0) res[0][756]=a004;
  if (res[0]!=0) res[0][757]=a001;
  if (res[0]!=0) res[0][758]=a004;
  if (res[0]!=0) res[0][759]=a004;
  if (res[0]!=0) res[0][760]=a004;
  if (res[0]!=0) res[0][761]=a004;
  if (res[0]!=0) res[0][762]=a004;
  if (res[0]!=0) res[0][763]=a004;
  if (res[0]!=0) res[0][764]=a004;
  if (res[0]!=0) res[0][765]=a004;
  if (res[0]!=0) res[0][766]=a004;
  if (res[0]!=0) res[0][767]=a004;
  if (res[0]!=0) res[0][768]=a004;
  if (res[0]!=0) res[0][769]=a004;
  if (res[0]!=0) res[0][770]=a004;
  if (res[0]!=0) res[0][771]=a004;
  if (res[0]!=0) res[0][772]=a004;
  if (res[0]!=0) res[0][773]=a004;
  a031=(-a031);
  if (res[0]!=0) res[0][774]=a031;
  a027=(-a027);
  if (res[0]!=0) res[0][775]=a027;
  a041=(-a041);
  if (res[0]!=0) res[0][776]=a041;
  if (res[0]!=0) res[0][777]=a004;
  if (res[0]!=0) res[0][778]=a004;
  if (res[0]!=0) res[0][779]=a004;
  if (res[0]!=0) res[0][780]=a004;
  if (res[0]!=0) res[0][781]=a004;
  if (res[0]!=0) res[0][782]=a001;
  if (res[0]!=0) res[0][783]=a004;
  if (res[0]!=0) res[0][784]=a004;
  if (res[0]!=0) res[0][785]=a004;
  if (res[0]!=0) res[0][786]=a004;
  if (res[0]!=0) res[0][787]=a004;
  if (res[0]!=0) res[0][788]=a001;
  if (res[0]!=0) res[0][789]=a004;
  if (res[0]!=0) res[0][790]=a004;
  if (res[0]!=0) res[0][791]=a004;
  if (res[0]!=0) res[0][792]=a004;
  if (res[0]!=0) res[0][793]=a004;
  if (res[0]!=0) res[0][794]=a004;
  if (res[0]!=0) res[0][795]=a004;
  if (res[0]!=0) res[0][796]=a004;
  if (res[0]!=0) res[0][797]=a004;
  if (res[0]!=0) res[0][798]=a004;
  if (res[0]!=0) res[0][799]=a004;
  if (res[0]!=0) res[0][800]=a004;
  if (res[0]!=0) res[0][801]=a004;
  if (res[0]!=0) res[0][802]=a004;
  if (res[0]!=0) res[0][803]=a004;
  a012=(-a012);
  if (res[0]!=0) res[0][804]=a012;
  a058=(-a058);
  if (res[0]!=0) res[0][805]=a058;
  a029=(-a029);
  if (res[0]!=0) res[0][806]=a029;
  if (res[0]!=0) res[0][807]=a004;
  if (res[0]!=0) res[0][808]=a004;
  if (res[0]!=0) res[0][809]=a004;
  if (res[0]!=0) res[0][810]=a004;
  if (res[0]!=0) res[0][811]=a004;
  if (res[0]!=0) res[0][812]=a004;
  if (res[0]!=0) res[0][813]=a001;
  if (res[0]!=0) res[0][814]=a004;
  if (res[0]!=0) res[0][815]=a004;
  if (res[0]!=0) res[0][816]=a004;
  if (res[0]!=0) res[0][817]=a004;
  if (res[0]!=0) res[0][818]=a004;
  if (res[0]!=0) res[0][819]=a001;
  if (res[0]!=0) res[0][820]=a004;
  if (res[0]!=0) res[0][821]=a004;
  if (res[0]!=0) res[0][822]=a004;
  if (res[0]!=0) res[0][823]=a004;
  if (res[0]!=0) res[0][824]=a004;
  if (res[0]!=0) res[0][825]=a004;
  if (res[0]!=0) res[0][826]=a004;
  if (res[0]!=0) res[0][827]=a004;
  if (res[0]!=0) res[0][828]=a004;
  if (res[0]!=0) res[0][829]=a004;
  if (res[0]!=0) res[0][830]=a004;
  if (res[0]!=0) res[0][831]=a004;
  if (res[0]!=0) res[0][832]=a004;
  if (res[0]!=0) res[0][833]=a004;
  if (res[0]!=0) res[0][834]=a004;
  if (res[0]!=0) res[0][835]=a004;
  if (res[0]!=0) res[0][836]=a004;
  a066=(-a066);
  if (res[0]!=0) res[0][837]=a066;
  a050=(-a050);
  if (res[0]!=0) res[0][838]=a050;
  a103=(-a103);
  if (res[0]!=0) res[0][839]=a103;
  if (res[0]!=0) res[0][840]=a004;
  if (res[0]!=0) res[0][841]=a004;
  if (res[0]!=0) res[0][842]=a004;
  if (res[0]!=0) res[0][843]=a004;
  if (res[0]!=0) res[0][844]=a001;
  if (res[0]!=0) res[0][845]=a004;
  if (res[0]!=0) res[0][846]=a004;
  if (res[0]!=0) res[0][847]=a004;
  if (res[0]!=0) res[0][848]=a004;
  if (res[0]!=0) res[0][849]=a004;
  if (res[0]!=0) res[0][850]=a001;
  if (res[0]!=0) res[0][851]=a004;
  if (res[0]!=0) res[0][852]=a004;
  if (res[0]!=0) res[0][853]=a004;
  if (res[0]!=0) res[0][854]=a004;
  if (res[0]!=0) res[0][855]=a004;
  if (res[0]!=0) res[0][856]=a004;
  if (res[0]!=0) res[0][857]=a004;
  if (res[0]!=0) res[0][858]=a004;
  if (res[0]!=0) res[0][859]=a004;
  if (res[0]!=0) res[0][860]=a004;
  if (res[0]!=0) res[0][861]=a004;
  if (res[0]!=0) res[0][862]=a004;
  if (res[0]!=0) res[0][863]=a004;
  if (res[0]!=0) res[0][864]=a004;
  if (res[0]!=0) res[0][865]=a004;
  if (res[0]!=0) res[0][866]=a004;
  a073=(-a073);
  if (res[0]!=0) res[0][867]=a073;
  a068=(-a068);
  if (res[0]!=0) res[0][868]=a068;
  a081=(-a081);
  if (res[0]!=0) res[0][869]=a081;
  if (res[0]!=0) res[0][870]=a004;
  if (res[0]!=0) res[0][871]=a004;
  if (res[0]!=0) res[0][872]=a004;
  if (res[0]!=0) res[0][873]=a004;
  if (res[0]!=0) res[0][874]=a004;
  if (res[0]!=0) res[0][875]=a001;
  if (res[0]!=0) res[0][876]=a004;
  if (res[0]!=0) res[0][877]=a004;
  if (res[0]!=0) res[0][878]=a004;
  if (res[0]!=0) res[0][879]=a004;
  if (res[0]!=0) res[0][880]=a004;
  if (res[0]!=0) res[0][881]=a001;
  if (res[0]!=0) res[0][882]=a004;
  if (res[0]!=0) res[0][883]=a004;
  if (res[0]!=0) res[0][884]=a004;
  if (res[0]!=0) res[0][885]=a004;
  if (res[0]!=0) res[0][886]=a004;
  if (res[0]!=0) res[0][887]=a004;
  if (res[0]!=0) res[0][888]=a004;
  if (res[0]!=0) res[0][889]=a004;
  if (res[0]!=0) res[0][890]=a004;
  if (res[0]!=0) res[0][891]=a004;
  if (res[0]!=0) res[0][892]=a004;
  if (res[0]!=0) res[0][893]=a004;
  if (res[0]!=0) res[0][894]=a004;
  if (res[0]!=0) res[0][895]=a004;
  if (res[0]!=0) res[0][896]=a004;
  a067=(-a067);
  if (res[0]!=0) res[0][897]=a067;
  a089=(-a089);
  if (res[0]!=0) res[0][898]=a089;
  a037=(-a037);
  if (res[0]!=0) res[0][899]=a037;
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

/* update:(z[30],g[36],p[6],h)->(g1[36],p1[6]) */
static int casadi_f2(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48;
  a00=arg[1]? arg[1][0] : 0;
  a01=1.;
  a02=4.;
  a03=arg[3]? arg[3][0] : 0;
  a04=5.0000000000000000e-01;
  a05=arg[0]? arg[0][0] : 0;
  a05=(a04*a05);
  a06=arg[0]? arg[0][6] : 0;
  a06=(a04*a06);
  a05=(a05+a06);
  a05=(a03*a05);
  a06=casadi_sq(a05);
  a07=arg[0]? arg[0][1] : 0;
  a07=(a04*a07);
  a08=arg[0]? arg[0][7] : 0;
  a08=(a04*a08);
  a07=(a07+a08);
  a07=(a03*a07);
  a08=casadi_sq(a07);
  a09=(a06+a08);
  a10=arg[0]? arg[0][2] : 0;
  a10=(a04*a10);
  a11=arg[0]? arg[0][8] : 0;
  a11=(a04*a11);
  a10=(a10+a11);
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
  a17=(a16/a13);
  a17=(a10+a17);
  a17=(a09*a17);
  a18=(a15*a17);
  a14=(a14+a18);
  a18=arg[1]? arg[1][12] : 0;
  a19=(a05*a10);
  a20=(a19/a13);
  a20=(a20-a07);
  a20=(a09*a20);
  a21=(a18*a20);
  a14=(a14+a21);
  if (res[0]!=0) res[0][0]=a14;
  a14=arg[1]? arg[1][1] : 0;
  a21=(a14*a12);
  a22=arg[1]? arg[1][7] : 0;
  a23=(a22*a17);
  a21=(a21+a23);
  a23=arg[1]? arg[1][13] : 0;
  a24=(a23*a20);
  a21=(a21+a24);
  if (res[0]!=0) res[0][1]=a21;
  a21=arg[1]? arg[1][2] : 0;
  a24=(a21*a12);
  a25=arg[1]? arg[1][8] : 0;
  a26=(a25*a17);
  a24=(a24+a26);
  a26=arg[1]? arg[1][14] : 0;
  a27=(a26*a20);
  a24=(a24+a27);
  if (res[0]!=0) res[0][2]=a24;
  a24=arg[1]? arg[1][3] : 0;
  a27=(a24*a12);
  a28=arg[1]? arg[1][9] : 0;
  a29=(a28*a17);
  a27=(a27+a29);
  a29=arg[1]? arg[1][15] : 0;
  a30=(a29*a20);
  a27=(a27+a30);
  if (res[0]!=0) res[0][3]=a27;
  a27=arg[1]? arg[1][4] : 0;
  a30=(a27*a12);
  a31=arg[1]? arg[1][10] : 0;
  a32=(a31*a17);
  a30=(a30+a32);
  a32=arg[1]? arg[1][16] : 0;
  a33=(a32*a20);
  a30=(a30+a33);
  if (res[0]!=0) res[0][4]=a30;
  a30=arg[1]? arg[1][5] : 0;
  a12=(a30*a12);
  a33=arg[1]? arg[1][11] : 0;
  a17=(a33*a17);
  a12=(a12+a17);
  a17=arg[1]? arg[1][17] : 0;
  a20=(a17*a20);
  a12=(a12+a20);
  if (res[0]!=0) res[0][5]=a12;
  a12=(a07*a05);
  a20=(a12/a13);
  a20=(a20-a10);
  a20=(a09*a20);
  a34=(a00*a20);
  a35=(a11+a06);
  a35=(a35/a13);
  a35=(a09*a35);
  a35=(a01-a35);
  a36=(a15*a35);
  a34=(a34+a36);
  a36=(a07*a10);
  a37=(a36/a13);
  a37=(a05+a37);
  a37=(a09*a37);
  a38=(a18*a37);
  a34=(a34+a38);
  if (res[0]!=0) res[0][6]=a34;
  a34=(a14*a20);
  a38=(a22*a35);
  a34=(a34+a38);
  a38=(a23*a37);
  a34=(a34+a38);
  if (res[0]!=0) res[0][7]=a34;
  a34=(a21*a20);
  a38=(a25*a35);
  a34=(a34+a38);
  a38=(a26*a37);
  a34=(a34+a38);
  if (res[0]!=0) res[0][8]=a34;
  a34=(a24*a20);
  a38=(a28*a35);
  a34=(a34+a38);
  a38=(a29*a37);
  a34=(a34+a38);
  if (res[0]!=0) res[0][9]=a34;
  a34=(a27*a20);
  a38=(a31*a35);
  a34=(a34+a38);
  a38=(a32*a37);
  a34=(a34+a38);
  if (res[0]!=0) res[0][10]=a34;
  a20=(a30*a20);
  a35=(a33*a35);
  a20=(a20+a35);
  a37=(a17*a37);
  a20=(a20+a37);
  if (res[0]!=0) res[0][11]=a20;
  a20=(a10*a05);
  a37=(a20/a13);
  a37=(a07+a37);
  a37=(a09*a37);
  a00=(a00*a37);
  a35=(a10*a07);
  a34=(a35/a13);
  a34=(a34-a05);
  a34=(a09*a34);
  a15=(a15*a34);
  a00=(a00+a15);
  a15=(a08+a06);
  a15=(a15/a13);
  a09=(a09*a15);
  a09=(a01-a09);
  a18=(a18*a09);
  a00=(a00+a18);
  if (res[0]!=0) res[0][12]=a00;
  a14=(a14*a37);
  a22=(a22*a34);
  a14=(a14+a22);
  a23=(a23*a09);
  a14=(a14+a23);
  if (res[0]!=0) res[0][13]=a14;
  a21=(a21*a37);
  a25=(a25*a34);
  a21=(a21+a25);
  a26=(a26*a09);
  a21=(a21+a26);
  if (res[0]!=0) res[0][14]=a21;
  a24=(a24*a37);
  a28=(a28*a34);
  a24=(a24+a28);
  a29=(a29*a09);
  a24=(a24+a29);
  if (res[0]!=0) res[0][15]=a24;
  a27=(a27*a37);
  a31=(a31*a34);
  a27=(a27+a31);
  a32=(a32*a09);
  a27=(a27+a32);
  if (res[0]!=0) res[0][16]=a27;
  a30=(a30*a37);
  a33=(a33*a34);
  a30=(a30+a33);
  a17=(a17*a09);
  a30=(a30+a17);
  if (res[0]!=0) res[0][17]=a30;
  a30=arg[1]? arg[1][18] : 0;
  a17=arg[0]? arg[0][3] : 0;
  a17=(a04*a17);
  a09=arg[0]? arg[0][9] : 0;
  a09=(a04*a09);
  a17=(a17+a09);
  a17=(a03*a17);
  a09=casadi_sq(a17);
  a33=arg[0]? arg[0][4] : 0;
  a33=(a04*a33);
  a34=arg[0]? arg[0][10] : 0;
  a34=(a04*a34);
  a33=(a33+a34);
  a33=(a03*a33);
  a34=casadi_sq(a33);
  a37=(a09+a34);
  a27=arg[0]? arg[0][5] : 0;
  a27=(a04*a27);
  a32=arg[0]? arg[0][11] : 0;
  a04=(a04*a32);
  a27=(a27+a04);
  a03=(a03*a27);
  a27=casadi_sq(a03);
  a37=(a37+a27);
  a37=(a02+a37);
  a37=(a02/a37);
  a04=(a27+a34);
  a04=(a04/a13);
  a04=(a37*a04);
  a04=(a01-a04);
  a32=(a30*a04);
  a31=arg[1]? arg[1][24] : 0;
  a24=(a17*a33);
  a29=(a24/a13);
  a29=(a03+a29);
  a29=(a37*a29);
  a28=(a31*a29);
  a32=(a32+a28);
  a28=arg[1]? arg[1][30] : 0;
  a21=(a17*a03);
  a26=(a21/a13);
  a26=(a26-a33);
  a26=(a37*a26);
  a25=(a28*a26);
  a32=(a32+a25);
  if (res[0]!=0) res[0][18]=a32;
  a32=arg[1]? arg[1][19] : 0;
  a25=(a32*a04);
  a14=arg[1]? arg[1][25] : 0;
  a23=(a14*a29);
  a25=(a25+a23);
  a23=arg[1]? arg[1][31] : 0;
  a22=(a23*a26);
  a25=(a25+a22);
  if (res[0]!=0) res[0][19]=a25;
  a25=arg[1]? arg[1][20] : 0;
  a22=(a25*a04);
  a00=arg[1]? arg[1][26] : 0;
  a18=(a00*a29);
  a22=(a22+a18);
  a18=arg[1]? arg[1][32] : 0;
  a15=(a18*a26);
  a22=(a22+a15);
  if (res[0]!=0) res[0][20]=a22;
  a22=arg[1]? arg[1][21] : 0;
  a15=(a22*a04);
  a38=arg[1]? arg[1][27] : 0;
  a39=(a38*a29);
  a15=(a15+a39);
  a39=arg[1]? arg[1][33] : 0;
  a40=(a39*a26);
  a15=(a15+a40);
  if (res[0]!=0) res[0][21]=a15;
  a15=arg[1]? arg[1][22] : 0;
  a40=(a15*a04);
  a41=arg[1]? arg[1][28] : 0;
  a42=(a41*a29);
  a40=(a40+a42);
  a42=arg[1]? arg[1][34] : 0;
  a43=(a42*a26);
  a40=(a40+a43);
  if (res[0]!=0) res[0][22]=a40;
  a40=arg[1]? arg[1][23] : 0;
  a04=(a40*a04);
  a43=arg[1]? arg[1][29] : 0;
  a29=(a43*a29);
  a04=(a04+a29);
  a29=arg[1]? arg[1][35] : 0;
  a26=(a29*a26);
  a04=(a04+a26);
  if (res[0]!=0) res[0][23]=a04;
  a04=(a33*a17);
  a26=(a04/a13);
  a26=(a26-a03);
  a26=(a37*a26);
  a44=(a30*a26);
  a45=(a27+a09);
  a45=(a45/a13);
  a45=(a37*a45);
  a45=(a01-a45);
  a46=(a31*a45);
  a44=(a44+a46);
  a46=(a33*a03);
  a47=(a46/a13);
  a47=(a17+a47);
  a47=(a37*a47);
  a48=(a28*a47);
  a44=(a44+a48);
  if (res[0]!=0) res[0][24]=a44;
  a44=(a32*a26);
  a48=(a14*a45);
  a44=(a44+a48);
  a48=(a23*a47);
  a44=(a44+a48);
  if (res[0]!=0) res[0][25]=a44;
  a44=(a25*a26);
  a48=(a00*a45);
  a44=(a44+a48);
  a48=(a18*a47);
  a44=(a44+a48);
  if (res[0]!=0) res[0][26]=a44;
  a44=(a22*a26);
  a48=(a38*a45);
  a44=(a44+a48);
  a48=(a39*a47);
  a44=(a44+a48);
  if (res[0]!=0) res[0][27]=a44;
  a44=(a15*a26);
  a48=(a41*a45);
  a44=(a44+a48);
  a48=(a42*a47);
  a44=(a44+a48);
  if (res[0]!=0) res[0][28]=a44;
  a26=(a40*a26);
  a45=(a43*a45);
  a26=(a26+a45);
  a47=(a29*a47);
  a26=(a26+a47);
  if (res[0]!=0) res[0][29]=a26;
  a26=(a03*a17);
  a47=(a26/a13);
  a47=(a33+a47);
  a47=(a37*a47);
  a30=(a30*a47);
  a45=(a03*a33);
  a44=(a45/a13);
  a44=(a44-a17);
  a44=(a37*a44);
  a31=(a31*a44);
  a30=(a30+a31);
  a31=(a34+a09);
  a31=(a31/a13);
  a37=(a37*a31);
  a37=(a01-a37);
  a28=(a28*a37);
  a30=(a30+a28);
  if (res[0]!=0) res[0][30]=a30;
  a32=(a32*a47);
  a14=(a14*a44);
  a32=(a32+a14);
  a23=(a23*a37);
  a32=(a32+a23);
  if (res[0]!=0) res[0][31]=a32;
  a25=(a25*a47);
  a00=(a00*a44);
  a25=(a25+a00);
  a18=(a18*a37);
  a25=(a25+a18);
  if (res[0]!=0) res[0][32]=a25;
  a22=(a22*a47);
  a38=(a38*a44);
  a22=(a22+a38);
  a39=(a39*a37);
  a22=(a22+a39);
  if (res[0]!=0) res[0][33]=a22;
  a15=(a15*a47);
  a41=(a41*a44);
  a15=(a15+a41);
  a42=(a42*a37);
  a15=(a15+a42);
  if (res[0]!=0) res[0][34]=a15;
  a40=(a40*a47);
  a43=(a43*a44);
  a40=(a40+a43);
  a29=(a29*a37);
  a40=(a40+a29);
  if (res[0]!=0) res[0][35]=a40;
  a20=(a20/a02);
  a07=(a07/a13);
  a20=(a20-a07);
  a40=arg[0]? arg[0][26] : 0;
  a20=(a20*a40);
  a10=(a10/a13);
  a12=(a12/a02);
  a12=(a10+a12);
  a29=arg[0]? arg[0][25] : 0;
  a12=(a12*a29);
  a20=(a20+a12);
  a06=(a06/a02);
  a06=(a01+a06);
  a12=arg[0]? arg[0][24] : 0;
  a06=(a06*a12);
  a20=(a20+a06);
  if (res[1]!=0) res[1][0]=a20;
  a05=(a05/a13);
  a35=(a35/a02);
  a35=(a05+a35);
  a35=(a35*a40);
  a08=(a08/a02);
  a08=(a01+a08);
  a08=(a08*a29);
  a35=(a35+a08);
  a16=(a16/a02);
  a16=(a16-a10);
  a16=(a16*a12);
  a35=(a35+a16);
  if (res[1]!=0) res[1][1]=a35;
  a11=(a11/a02);
  a11=(a01+a11);
  a11=(a11*a40);
  a36=(a36/a02);
  a36=(a36-a05);
  a36=(a36*a29);
  a11=(a11+a36);
  a19=(a19/a02);
  a07=(a07+a19);
  a07=(a07*a12);
  a11=(a11+a07);
  if (res[1]!=0) res[1][2]=a11;
  a26=(a26/a02);
  a33=(a33/a13);
  a26=(a26-a33);
  a11=arg[0]? arg[0][29] : 0;
  a26=(a26*a11);
  a03=(a03/a13);
  a04=(a04/a02);
  a04=(a03+a04);
  a07=arg[0]? arg[0][28] : 0;
  a04=(a04*a07);
  a26=(a26+a04);
  a09=(a09/a02);
  a09=(a01+a09);
  a04=arg[0]? arg[0][27] : 0;
  a09=(a09*a04);
  a26=(a26+a09);
  if (res[1]!=0) res[1][3]=a26;
  a17=(a17/a13);
  a45=(a45/a02);
  a45=(a17+a45);
  a45=(a45*a11);
  a34=(a34/a02);
  a34=(a01+a34);
  a34=(a34*a07);
  a45=(a45+a34);
  a24=(a24/a02);
  a24=(a24-a03);
  a24=(a24*a04);
  a45=(a45+a24);
  if (res[1]!=0) res[1][4]=a45;
  a27=(a27/a02);
  a01=(a01+a27);
  a01=(a01*a11);
  a46=(a46/a02);
  a46=(a46-a17);
  a46=(a46*a07);
  a01=(a01+a46);
  a21=(a21/a02);
  a33=(a33+a21);
  a33=(a33*a04);
  a01=(a01+a33);
  if (res[1]!=0) res[1][5]=a01;
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

/* guess:(xi[6],g[36],p[6],h)->(z0[30]) */
static int casadi_f3(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4, a5;
  a0=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a0;
  a1=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a1;
  a2=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a2;
  a3=arg[0]? arg[0][3] : 0;
  if (res[0]!=0) res[0][3]=a3;
  a4=arg[0]? arg[0][4] : 0;
  if (res[0]!=0) res[0][4]=a4;
  a5=arg[0]? arg[0][5] : 0;
  if (res[0]!=0) res[0][5]=a5;
  if (res[0]!=0) res[0][6]=a0;
  if (res[0]!=0) res[0][7]=a1;
  if (res[0]!=0) res[0][8]=a2;
  if (res[0]!=0) res[0][9]=a3;
  if (res[0]!=0) res[0][10]=a4;
  if (res[0]!=0) res[0][11]=a5;
  a5=0.;
  if (res[0]!=0) res[0][12]=a5;
  if (res[0]!=0) res[0][13]=a5;
  if (res[0]!=0) res[0][14]=a5;
  if (res[0]!=0) res[0][15]=a5;
  if (res[0]!=0) res[0][16]=a5;
  if (res[0]!=0) res[0][17]=a5;
  if (res[0]!=0) res[0][18]=a5;
  if (res[0]!=0) res[0][19]=a5;
  if (res[0]!=0) res[0][20]=a5;
  if (res[0]!=0) res[0][21]=a5;
  if (res[0]!=0) res[0][22]=a5;
  if (res[0]!=0) res[0][23]=a5;
  a5=arg[2]? arg[2][0] : 0;
  if (res[0]!=0) res[0][24]=a5;
  a5=arg[2]? arg[2][1] : 0;
  if (res[0]!=0) res[0][25]=a5;
  a5=arg[2]? arg[2][2] : 0;
  if (res[0]!=0) res[0][26]=a5;
  a5=arg[2]? arg[2][3] : 0;
  if (res[0]!=0) res[0][27]=a5;
  a5=arg[2]? arg[2][4] : 0;
  if (res[0]!=0) res[0][28]=a5;
  a5=arg[2]? arg[2][5] : 0;
  if (res[0]!=0) res[0][29]=a5;
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

/* margin:(z[30],h)->(m) */
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
#define HPGEN_N 6
#define HPGEN_NN (HPGEN_N * HPGEN_N)
#define HPGEN_D 6
#define HPGEN_NZ 30
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

HPGEN_EXPORT const char* hpgen_hash(void) { return "05c0c407c549797f48db77cd1c626e9d8eb5077bed9e5a668c9c48c84019522d"; }

/* out[0..3] = ABI version, n, d, nz */
HPGEN_EXPORT void hpgen_dims(long long* out) {
    out[0] = HPGEN_ABI; out[1] = HPGEN_N; out[2] = HPGEN_D; out[3] = HPGEN_NZ;
}

/* ---- kernel wrappers: dense column-major arguments, CasADi work arrays on the stack ---- */

/* residual(z[30], g[36], p[6], h[1]) -> (F[30]) */
#define HPGEN_RESIDUAL_SZ_ARG 4
#define HPGEN_RESIDUAL_SZ_RES 1
#define HPGEN_RESIDUAL_SZ_IW 0
#define HPGEN_RESIDUAL_SZ_W 97
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

/* jacobian(z[30], g[36], p[6], h[1]) -> (J[900]) */
#define HPGEN_JACOBIAN_SZ_ARG 4
#define HPGEN_JACOBIAN_SZ_RES 1
#define HPGEN_JACOBIAN_SZ_IW 0
#define HPGEN_JACOBIAN_SZ_W 162
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

/* update(z[30], g[36], p[6], h[1]) -> (g1[36], p1[6]) */
#define HPGEN_UPDATE_SZ_ARG 4
#define HPGEN_UPDATE_SZ_RES 2
#define HPGEN_UPDATE_SZ_IW 0
#define HPGEN_UPDATE_SZ_W 49
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

/* guess(xi[6], g[36], p[6], h[1]) -> (z0[30]) */
#define HPGEN_GUESS_SZ_ARG 4
#define HPGEN_GUESS_SZ_RES 1
#define HPGEN_GUESS_SZ_IW 0
#define HPGEN_GUESS_SZ_W 6
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

/* legendre(g[36], xi[6]) -> (mu[6]) */
#define HPGEN_LEGENDRE_SZ_ARG 2
#define HPGEN_LEGENDRE_SZ_RES 1
#define HPGEN_LEGENDRE_SZ_IW 0
#define HPGEN_LEGENDRE_SZ_W 2
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

/* hessian(g[36], xi[6]) -> (H[36]) */
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

/* energy(g[36], xi[6]) -> (E[1]) */
#define HPGEN_ENERGY_SZ_ARG 2
#define HPGEN_ENERGY_SZ_RES 1
#define HPGEN_ENERGY_SZ_IW 0
#define HPGEN_ENERGY_SZ_W 11
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

/* momentum(g[36], p[6]) -> (m[6]) */
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

/* defect(g[36]) -> (e[1]) */
#define HPGEN_DEFECT_SZ_ARG 1
#define HPGEN_DEFECT_SZ_RES 1
#define HPGEN_DEFECT_SZ_IW 0
#define HPGEN_DEFECT_SZ_W 14
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

/* margin(z[30], h[1]) -> (m[1]) */
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
