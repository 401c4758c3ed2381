/*
 * hpgen generated module driven_pendulum_gauss2_cay_exact -- do not edit, regenerate with hpgen
 * model: driven_pendulum
 * options: tableau=gauss2, tau=cay, rkmk=exact
 * hpgen version: 0.1.0
 * content hash (normalized model + options): b76f001c568489b54c25240c2e6bce8e6b4f732e81abe16fca3e42f6b849b2ff
 *
 * C backend: the model's sizes, CasADi's generated kernels (symbols hidden) and their
 * wrappers hpgen_kernel_<name> (exported), then hpgen's C runtime (hpgen/runtime/c:
 * hpgen_runtime.h, hpgen_runtime.c), compiled with them as one translation unit; the
 * contract with hpgen.runtime is hpgen.abi.
 */
/* the model (hpgen_runtime.h) */
#define HPGEN_N 2
#define HPGEN_D 1
#define HPGEN_NZ 3
/* an open model (forces, control inputs, runtime parameters or t): every h input of the
   kernels is the step vector hv = [h, t_k, u (M), params (P)] (hpgen.abi), which the run
   holds and fills before each step: t_k = t0 + k h, u_k the run's input row k (or its only
   row), params set once (hpgen_run_set_inputs) */
#define HPGEN_OPEN 1
#define HPGEN_M 0
#define HPGEN_P 1
/* the scene's record row (kernel record): its width and what it needs */
#define HPGEN_W 7
#define HPGEN_RECORD_USES_XI 1
#define HPGEN_LEGENDRE_QUADRATIC 1
/* neither the step (residual, p_{k+1}) nor the record row use g: hpgen_advance_record does
   not reconstruct the group at all */
#define HPGEN_SKIP_G 0
/* the step's kernels are small: inlined into the step */
#define HPGEN_FLATTEN 1
#define HPGEN_HASH "b76f001c568489b54c25240c2e6bce8e6b4f732e81abe16fca3e42f6b849b2ff"
#define HPGEN_SPARSE 0
#include "hpgen_runtime.h"

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
  #define CASADI_PREFIX(ID) hpgen_driven_pendulum_gauss2_cay_exact__ ## ID
#endif

#include <math.h>

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int int
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
CASADI_SYMBOL_EXPORT void hpgen_driven_pendulum_gauss2_cay_exact__casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int hpgen_driven_pendulum_gauss2_cay_exact__casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int hpgen_driven_pendulum_gauss2_cay_exact__casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {4, 1, 1};
static const casadi_int casadi_s2[3] = {1, 1, 1};
static const casadi_int casadi_s3[3] = {9, 1, 1};
static const casadi_int casadi_s4[3] = {7, 1, 1};
static const casadi_int casadi_s5[3] = {6, 1, 1};

/* residual:(z[3],g[4],p,h[3])->(F[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27;
  a00=1.;
  a01=arg[3]? arg[3][0] : 0;
  a02=arg[0]? arg[0][0] : 0;
  a03=(a01*a02);
  a04=casadi_sq(a03);
  a05=4.;
  a04=(a04/a05);
  a06=(a00+a04);
  a07=1.5000000000000002e+00;
  a08=3.0000000000000004e+00;
  a09=(a08*a02);
  a10=4.6410161513775439e-01;
  a11=arg[0]? arg[0][1] : 0;
  a10=(a10*a11);
  a09=(a09+a10);
  a10=(a09/a06);
  a12=(a10/a06);
  a13=arg[0]? arg[0][2] : 0;
  a12=(a12-a13);
  a14=(a07*a12);
  a15=-3.2320508075688776e+00;
  a16=-6.4641016151377553e+00;
  a16=(a16*a02);
  a08=(a08*a11);
  a16=(a16+a08);
  a11=(a01*a11);
  a08=casadi_sq(a11);
  a08=(a08/a05);
  a02=(a00+a08);
  a17=(a16/a02);
  a18=(a17/a02);
  a18=(a18-a13);
  a15=(a15*a18);
  a14=(a14+a15);
  a15=(2.*a03);
  a19=2.5000000000000000e-01;
  a20=5.0000000000000000e-01;
  a21=(a01*a13);
  a21=(a20*a21);
  a22=5.3867513459481287e-01;
  a23=2.3205080756887719e-01;
  a23=(a23*a12);
  a07=(a07*a18);
  a23=(a23+a07);
  a07=(a01*a23);
  a22=(a22*a07);
  a22=(a21+a22);
  a18=(a01*a14);
  a12=(a19*a18);
  a22=(a22+a12);
  a22=(a10*a22);
  a22=(a19*a22);
  a15=(a15*a22);
  a14=(a14-a15);
  a14=(a06*a14);
  a15=-5.0000000000000000e-01;
  a10=(a15*a10);
  a22=arg[3]? arg[3][2] : 0;
  a12=6.6666666666666663e-01;
  a24=arg[3]? arg[3][1] : 0;
  a25=2.1132486540518713e-01;
  a25=(a25*a01);
  a25=(a24+a25);
  a25=(a12*a25);
  a25=cos(a25);
  a25=(a22*a25);
  a10=(a10+a25);
  a25=(a20*a01);
  a10=(a10*a25);
  a10=(a14+a10);
  a26=arg[1]? arg[1][2] : 0;
  a04=(a00-a04);
  a04=(a04/a06);
  a04=(a26*a04);
  a27=arg[1]? arg[1][0] : 0;
  a03=(a03/a06);
  a03=(a27*a03);
  a04=(a04-a03);
  a04=(a04*a25);
  a10=(a10+a04);
  a10=(a10/a01);
  if (res[0]!=0) res[0][0]=a10;
  a15=(a15*a17);
  a10=7.8867513459481287e-01;
  a10=(a10*a01);
  a24=(a24+a10);
  a12=(a12*a24);
  a12=cos(a12);
  a22=(a22*a12);
  a15=(a15+a22);
  a15=(a15*a25);
  a08=(a00-a08);
  a08=(a08/a02);
  a26=(a26*a08);
  a08=(a11/a02);
  a27=(a27*a08);
  a26=(a26-a27);
  a26=(a26*a25);
  a15=(a15+a26);
  a11=(2.*a11);
  a07=(a19*a07);
  a21=(a21+a07);
  a07=-3.8675134594812879e-02;
  a07=(a07*a18);
  a21=(a21+a07);
  a17=(a17*a21);
  a19=(a19*a17);
  a11=(a11*a19);
  a23=(a23-a11);
  a02=(a02*a23);
  a15=(a15+a02);
  a15=(a15/a01);
  if (res[0]!=0) res[0][1]=a15;
  a15=arg[2]? arg[2][0] : 0;
  a09=(a20*a09);
  a20=(a20*a16);
  a09=(a09+a20);
  a01=(a01*a09);
  a01=casadi_sq(a01);
  a01=(a01/a05);
  a00=(a00+a01);
  a00=(a00*a13);
  a00=(a00+a02);
  a00=(a00+a14);
  a15=(a15-a00);
  if (res[0]!=0) res[0][2]=a15;
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
    case 3: return casadi_s0;
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

/* residual_jacobian:(z[3],g[4],p,h[3])->(F[3],J[9]) */
static int casadi_f1(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43;
  a00=1.;
  a01=arg[3]? arg[3][0] : 0;
  a02=arg[0]? arg[0][0] : 0;
  a03=(a01*a02);
  a04=casadi_sq(a03);
  a05=4.;
  a04=(a04/a05);
  a06=(a00+a04);
  a07=1.5000000000000002e+00;
  a08=3.0000000000000004e+00;
  a09=(a08*a02);
  a10=4.6410161513775439e-01;
  a11=arg[0]? arg[0][1] : 0;
  a12=(a10*a11);
  a09=(a09+a12);
  a12=(a09/a06);
  a13=(a12/a06);
  a14=arg[0]? arg[0][2] : 0;
  a15=(a13-a14);
  a16=(a07*a15);
  a17=-3.2320508075688776e+00;
  a18=-6.4641016151377553e+00;
  a02=(a18*a02);
  a19=(a08*a11);
  a02=(a02+a19);
  a11=(a01*a11);
  a19=casadi_sq(a11);
  a19=(a19/a05);
  a20=(a00+a19);
  a21=(a02/a20);
  a22=(a21/a20);
  a23=(a22-a14);
  a24=(a17*a23);
  a16=(a16+a24);
  a24=(2.*a03);
  a25=2.5000000000000000e-01;
  a26=5.0000000000000000e-01;
  a27=(a01*a14);
  a27=(a26*a27);
  a28=5.3867513459481287e-01;
  a29=2.3205080756887719e-01;
  a15=(a29*a15);
  a23=(a07*a23);
  a15=(a15+a23);
  a23=(a01*a15);
  a30=(a28*a23);
  a30=(a27+a30);
  a31=(a01*a16);
  a32=(a25*a31);
  a30=(a30+a32);
  a32=(a12*a30);
  a32=(a25*a32);
  a33=(a24*a32);
  a16=(a16-a33);
  a33=(a06*a16);
  a34=-5.0000000000000000e-01;
  a35=(a34*a12);
  a36=arg[3]? arg[3][2] : 0;
  a37=6.6666666666666663e-01;
  a38=arg[3]? arg[3][1] : 0;
  a39=2.1132486540518713e-01;
  a39=(a39*a01);
  a39=(a38+a39);
  a39=(a37*a39);
  a39=cos(a39);
  a39=(a36*a39);
  a35=(a35+a39);
  a39=(a26*a01);
  a35=(a35*a39);
  a35=(a33+a35);
  a40=arg[1]? arg[1][2] : 0;
  a04=(a00-a04);
  a04=(a04/a06);
  a41=(a40*a04);
  a42=arg[1]? arg[1][0] : 0;
  a03=(a03/a06);
  a43=(a42*a03);
  a41=(a41-a43);
  a41=(a41*a39);
  a35=(a35+a41);
  a35=(a35/a01);
  if (res[0]!=0) res[0][0]=a35;
  a35=(a34*a21);
  a41=7.8867513459481287e-01;
  a41=(a41*a01);
  a38=(a38+a41);
  a37=(a37*a38);
  a37=cos(a37);
  a36=(a36*a37);
  a35=(a35+a36);
  a35=(a35*a39);
  a19=(a00-a19);
  a19=(a19/a20);
  a36=(a40*a19);
  a37=(a11/a20);
  a38=(a42*a37);
  a36=(a36-a38);
  a36=(a36*a39);
  a35=(a35+a36);
  a11=(2.*a11);
  a23=(a25*a23);
  a27=(a27+a23);
  a23=-3.8675134594812879e-02;
  a31=(a23*a31);
  a27=(a27+a31);
  a31=(a21*a27);
  a31=(a25*a31);
  a36=(a11*a31);
  a15=(a15-a36);
  a36=(a20*a15);
  a35=(a35+a36);
  a35=(a35/a01);
  if (res[0]!=0) res[0][1]=a35;
  a35=arg[2]? arg[2][0] : 0;
  a09=(a26*a09);
  a26=(a26*a02);
  a09=(a09+a26);
  a09=(a01*a09);
  a26=casadi_sq(a09);
  a26=(a26/a05);
  a00=(a00+a26);
  a26=(a00*a14);
  a26=(a26+a36);
  a26=(a26+a33);
  a35=(a35-a26);
  if (res[0]!=0) res[0][2]=a35;
  a35=(a24*a01);
  a35=(a25*a35);
  a16=(a16*a35);
  a26=(a08/a06);
  a33=(a13*a35);
  a26=(a26-a33);
  a33=(a26/a06);
  a13=(a13/a06);
  a13=(a13*a35);
  a33=(a33-a13);
  a13=(a07*a33);
  a18=(a18/a20);
  a36=(a18/a20);
  a05=(a17*a36);
  a13=(a13+a05);
  a05=(2.*a01);
  a32=(a32*a05);
  a02=(a30*a26);
  a33=(a29*a33);
  a36=(a07*a36);
  a33=(a33+a36);
  a36=(a01*a33);
  a38=(a28*a36);
  a41=(a01*a13);
  a43=(a25*a41);
  a38=(a38+a43);
  a38=(a12*a38);
  a02=(a02+a38);
  a02=(a25*a02);
  a02=(a24*a02);
  a32=(a32+a02);
  a13=(a13-a32);
  a13=(a06*a13);
  a16=(a16+a13);
  a26=(a34*a26);
  a26=(a39*a26);
  a26=(a16+a26);
  a13=(a35/a06);
  a04=(a04/a06);
  a04=(a04*a35);
  a13=(a13+a04);
  a13=(a40*a13);
  a04=(a01/a06);
  a03=(a03/a06);
  a03=(a03*a35);
  a04=(a04-a03);
  a04=(a42*a04);
  a13=(a13+a04);
  a13=(a39*a13);
  a26=(a26-a13);
  a26=(a26/a01);
  if (res[1]!=0) res[1][0]=a26;
  a26=(a34*a18);
  a26=(a39*a26);
  a18=(a27*a18);
  a36=(a25*a36);
  a41=(a23*a41);
  a36=(a36+a41);
  a36=(a21*a36);
  a18=(a18+a36);
  a18=(a25*a18);
  a18=(a11*a18);
  a33=(a33-a18);
  a33=(a20*a33);
  a26=(a26+a33);
  a26=(a26/a01);
  if (res[1]!=0) res[1][1]=a26;
  a09=(2.*a09);
  a26=-1.7320508075688774e+00;
  a18=(a26*a01);
  a18=(a09*a18);
  a18=(a25*a18);
  a18=(a14*a18);
  a18=(a18+a33);
  a18=(a18+a16);
  a18=(-a18);
  if (res[1]!=0) res[1][2]=a18;
  a10=(a10/a06);
  a18=(a10/a06);
  a16=(a07*a18);
  a08=(a08/a20);
  a33=(a11*a01);
  a33=(a25*a33);
  a36=(a22*a33);
  a08=(a08-a36);
  a36=(a08/a20);
  a22=(a22/a20);
  a22=(a22*a33);
  a36=(a36-a22);
  a17=(a17*a36);
  a16=(a16+a17);
  a30=(a30*a10);
  a29=(a29*a18);
  a07=(a07*a36);
  a29=(a29+a07);
  a07=(a01*a29);
  a28=(a28*a07);
  a36=(a01*a16);
  a18=(a25*a36);
  a28=(a28+a18);
  a28=(a12*a28);
  a30=(a30+a28);
  a30=(a25*a30);
  a30=(a24*a30);
  a16=(a16-a30);
  a16=(a06*a16);
  a10=(a34*a10);
  a10=(a39*a10);
  a10=(a16+a10);
  a10=(a10/a01);
  if (res[1]!=0) res[1][3]=a10;
  a34=(a34*a08);
  a34=(a39*a34);
  a10=(a33/a20);
  a19=(a19/a20);
  a19=(a19*a33);
  a10=(a10+a19);
  a40=(a40*a10);
  a10=(a01/a20);
  a37=(a37/a20);
  a37=(a37*a33);
  a10=(a10-a37);
  a42=(a42*a10);
  a40=(a40+a42);
  a40=(a39*a40);
  a34=(a34-a40);
  a15=(a15*a33);
  a31=(a31*a05);
  a27=(a27*a08);
  a07=(a25*a07);
  a23=(a23*a36);
  a07=(a07+a23);
  a07=(a21*a07);
  a27=(a27+a07);
  a27=(a25*a27);
  a27=(a11*a27);
  a31=(a31+a27);
  a29=(a29-a31);
  a29=(a20*a29);
  a15=(a15+a29);
  a34=(a34+a15);
  a34=(a34/a01);
  if (res[1]!=0) res[1][4]=a34;
  a34=1.7320508075688774e+00;
  a29=(a34*a01);
  a09=(a09*a29);
  a09=(a25*a09);
  a14=(a14*a09);
  a14=(a14+a15);
  a14=(a14+a16);
  a14=(-a14);
  if (res[1]!=0) res[1][5]=a14;
  a14=-9.3301270189221941e-01;
  a14=(a14*a01);
  a14=(a39+a14);
  a16=4.3301270189221935e-01;
  a16=(a16*a01);
  a14=(a14+a16);
  a12=(a12*a14);
  a12=(a25*a12);
  a24=(a24*a12);
  a34=(a34-a24);
  a06=(a06*a34);
  a34=(a06/a01);
  if (res[1]!=0) res[1][6]=a34;
  a34=-4.3301270189221935e-01;
  a34=(a34*a01);
  a39=(a39+a34);
  a34=-6.6987298107780674e-02;
  a34=(a34*a01);
  a39=(a39+a34);
  a21=(a21*a39);
  a25=(a25*a21);
  a11=(a11*a25);
  a26=(a26-a11);
  a20=(a20*a26);
  a01=(a20/a01);
  if (res[1]!=0) res[1][7]=a01;
  a00=(a00+a20);
  a00=(a00+a06);
  a00=(-a00);
  if (res[1]!=0) res[1][8]=a00;
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
    case 2: return casadi_s2;
    case 3: return casadi_s0;
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

/* update:(z[3],g[4],p,h[3])->(g1[4],p1) */
static int casadi_f2(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4, a5, a6, a7, a8;
  a0=arg[1]? arg[1][0] : 0;
  a1=1.;
  a2=arg[3]? arg[3][0] : 0;
  a3=5.0000000000000000e-01;
  a4=3.0000000000000004e+00;
  a5=arg[0]? arg[0][0] : 0;
  a6=(a4*a5);
  a7=4.6410161513775439e-01;
  a8=arg[0]? arg[0][1] : 0;
  a7=(a7*a8);
  a6=(a6+a7);
  a6=(a3*a6);
  a7=-6.4641016151377553e+00;
  a7=(a7*a5);
  a4=(a4*a8);
  a7=(a7+a4);
  a3=(a3*a7);
  a6=(a6+a3);
  a2=(a2*a6);
  a6=casadi_sq(a2);
  a3=4.;
  a6=(a6/a3);
  a3=(a1-a6);
  a1=(a1+a6);
  a3=(a3/a1);
  a6=(a0*a3);
  a7=arg[1]? arg[1][2] : 0;
  a2=(a2/a1);
  a4=(a7*a2);
  a6=(a6+a4);
  if (res[0]!=0) res[0][0]=a6;
  a6=arg[1]? arg[1][1] : 0;
  a4=(a6*a3);
  a8=arg[1]? arg[1][3] : 0;
  a5=(a8*a2);
  a4=(a4+a5);
  if (res[0]!=0) res[0][1]=a4;
  a7=(a7*a3);
  a0=(a0*a2);
  a7=(a7-a0);
  if (res[0]!=0) res[0][2]=a7;
  a8=(a8*a3);
  a6=(a6*a2);
  a8=(a8-a6);
  if (res[0]!=0) res[0][3]=a8;
  a8=arg[0]? arg[0][2] : 0;
  a1=(a1*a8);
  if (res[1]!=0) res[1][0]=a1;
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
    case 3: return casadi_s0;
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

/* guess:(xi,g[4],p,h[3])->(z0[3]) */
static int casadi_f3(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1;
  a0=2.1132486540518713e-01;
  a1=arg[0]? arg[0][0] : 0;
  a0=(a0*a1);
  if (res[0]!=0) res[0][0]=a0;
  a0=7.8867513459481287e-01;
  a0=(a0*a1);
  if (res[0]!=0) res[0][1]=a0;
  a0=arg[2]? arg[2][0] : 0;
  if (res[0]!=0) res[0][2]=a0;
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
    case 3: return casadi_s0;
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

/* legendre:(g[4],xi,h[3])->(mu) */
static int casadi_f4(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0;
  a0=arg[1]? arg[1][0] : 0;
  if (res[0]!=0) res[0][0]=a0;
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
    case 0: return casadi_s1;
    case 1: return casadi_s2;
    case 2: return casadi_s0;
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

/* hessian:(g[4],xi,h[3])->(H) */
static int casadi_f5(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0;
  a0=1.;
  if (res[0]!=0) res[0][0]=a0;
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
    case 0: return casadi_s1;
    case 1: return casadi_s2;
    case 2: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* hessian_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
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

/* energy:(g[4],xi,h[3])->(E) */
static int casadi_f6(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2;
  a0=arg[1]? arg[1][0] : 0;
  a0=casadi_sq(a0);
  a1=5.0000000000000000e-01;
  a1=(a1*a0);
  a2=arg[0]? arg[0][0] : 0;
  a1=(a1+a2);
  a0=(a0-a1);
  if (res[0]!=0) res[0][0]=a0;
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
    case 0: return casadi_s1;
    case 1: return casadi_s2;
    case 2: return casadi_s0;
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

/* momentum:(g[4],p)->(m) */
static int casadi_f7(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2;
  a0=arg[0]? arg[0][3] : 0;
  a1=arg[0]? arg[0][0] : 0;
  a0=(a0*a1);
  a1=arg[0]? arg[0][2] : 0;
  a2=arg[0]? arg[0][1] : 0;
  a1=(a1*a2);
  a0=(a0-a1);
  a1=arg[1]? arg[1][0] : 0;
  a0=(a0*a1);
  if (res[0]!=0) res[0][0]=a0;
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

/* defect:(g[4])->(e) */
static int casadi_f8(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4, a5, a6, a7;
  a0=arg[0]? arg[0][0] : 0;
  a1=casadi_sq(a0);
  a2=arg[0]? arg[0][1] : 0;
  a3=casadi_sq(a2);
  a1=(a1+a3);
  a3=1.;
  a1=(a1-a3);
  a1=casadi_fabs(a1);
  a4=arg[0]? arg[0][2] : 0;
  a5=(a4*a0);
  a6=arg[0]? arg[0][3] : 0;
  a7=(a6*a2);
  a5=(a5+a7);
  a5=casadi_fabs(a5);
  a1=casadi_fmax(a1,a5);
  a5=(a0*a4);
  a7=(a2*a6);
  a5=(a5+a7);
  a5=casadi_fabs(a5);
  a1=casadi_fmax(a1,a5);
  a5=casadi_sq(a4);
  a7=casadi_sq(a6);
  a5=(a5+a7);
  a5=(a5-a3);
  a5=casadi_fabs(a5);
  a1=casadi_fmax(a1,a5);
  a0=(a0*a6);
  a4=(a4*a2);
  a0=(a0-a4);
  a0=(a0-a3);
  a0=casadi_fabs(a0);
  a1=casadi_fmax(a1,a0);
  if (res[0]!=0) res[0][0]=a1;
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

/* margin:(z[3],h[3])->(m) */
static int casadi_f9(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4, a5, a6, a7, a8;
  a0=1.;
  a1=4.;
  a2=arg[1]? arg[1][0] : 0;
  a3=arg[0]? arg[0][0] : 0;
  a4=(a2*a3);
  a4=casadi_sq(a4);
  a4=(a1-a4);
  a0=casadi_fmin(a0,a4);
  a0=casadi_fmin(a0,a4);
  a4=arg[0]? arg[0][1] : 0;
  a5=(a2*a4);
  a5=casadi_sq(a5);
  a5=(a1-a5);
  a0=casadi_fmin(a0,a5);
  a0=casadi_fmin(a0,a5);
  a5=5.0000000000000000e-01;
  a6=3.0000000000000004e+00;
  a7=(a6*a3);
  a8=4.6410161513775439e-01;
  a8=(a8*a4);
  a7=(a7+a8);
  a7=(a5*a7);
  a8=-6.4641016151377553e+00;
  a8=(a8*a3);
  a6=(a6*a4);
  a8=(a8+a6);
  a5=(a5*a8);
  a7=(a7+a5);
  a2=(a2*a7);
  a2=casadi_sq(a2);
  a1=(a1-a2);
  a0=casadi_fmin(a0,a1);
  a0=casadi_fmin(a0,a1);
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
    case 1: return casadi_s0;
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

/* section:(g[4],p)->(s) */
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
    case 1: return casadi_s2;
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

/* chart_point:(z[3],g[4],h[3],theta)->(g_theta[4]) */
static int casadi_f11(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4, a5, a6, a7, a8, a9;
  a0=arg[1]? arg[1][0] : 0;
  a1=1.;
  a2=arg[3]? arg[3][0] : 0;
  a3=arg[2]? arg[2][0] : 0;
  a4=5.0000000000000000e-01;
  a5=3.0000000000000004e+00;
  a6=arg[0]? arg[0][0] : 0;
  a7=(a5*a6);
  a8=4.6410161513775439e-01;
  a9=arg[0]? arg[0][1] : 0;
  a8=(a8*a9);
  a7=(a7+a8);
  a7=(a4*a7);
  a8=-6.4641016151377553e+00;
  a8=(a8*a6);
  a5=(a5*a9);
  a8=(a8+a5);
  a4=(a4*a8);
  a7=(a7+a4);
  a3=(a3*a7);
  a2=(a2*a3);
  a3=casadi_sq(a2);
  a7=4.;
  a3=(a3/a7);
  a7=(a1-a3);
  a1=(a1+a3);
  a7=(a7/a1);
  a3=(a0*a7);
  a4=arg[1]? arg[1][2] : 0;
  a2=(a2/a1);
  a1=(a4*a2);
  a3=(a3+a1);
  if (res[0]!=0) res[0][0]=a3;
  a3=arg[1]? arg[1][1] : 0;
  a1=(a3*a7);
  a8=arg[1]? arg[1][3] : 0;
  a5=(a8*a2);
  a1=(a1+a5);
  if (res[0]!=0) res[0][1]=a1;
  a4=(a4*a7);
  a0=(a0*a2);
  a4=(a4-a0);
  if (res[0]!=0) res[0][2]=a4;
  a8=(a8*a7);
  a3=(a3*a2);
  a8=(a8-a3);
  if (res[0]!=0) res[0][3]=a8;
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
    case 2: return casadi_s0;
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

/* observe:(g[4],p,h[3])->(xi,E,m,e) */
static int casadi_f12(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4, a5, a6, a7, a8;
  a0=arg[1]? arg[1][0] : 0;
  if (res[0]!=0) res[0][0]=a0;
  a1=casadi_sq(a0);
  a2=5.0000000000000000e-01;
  a2=(a2*a1);
  a3=arg[0]? arg[0][0] : 0;
  a2=(a2+a3);
  a1=(a1-a2);
  if (res[1]!=0) res[1][0]=a1;
  a1=arg[0]? arg[0][3] : 0;
  a2=(a1*a3);
  a4=arg[0]? arg[0][2] : 0;
  a5=arg[0]? arg[0][1] : 0;
  a6=(a4*a5);
  a2=(a2-a6);
  a2=(a2*a0);
  if (res[2]!=0) res[2][0]=a2;
  a2=casadi_sq(a3);
  a0=casadi_sq(a5);
  a2=(a2+a0);
  a0=1.;
  a2=(a2-a0);
  a2=casadi_fabs(a2);
  a7=(a4*a3);
  a8=(a1*a5);
  a7=(a7+a8);
  a7=casadi_fabs(a7);
  a2=casadi_fmax(a2,a7);
  a7=(a3*a4);
  a5=(a5*a1);
  a7=(a7+a5);
  a7=casadi_fabs(a7);
  a2=casadi_fmax(a2,a7);
  a4=casadi_sq(a4);
  a7=casadi_sq(a1);
  a4=(a4+a7);
  a4=(a4-a0);
  a4=casadi_fabs(a4);
  a2=casadi_fmax(a2,a4);
  a3=(a3*a1);
  a3=(a3-a6);
  a3=(a3-a0);
  a3=casadi_fabs(a3);
  a2=casadi_fmax(a2,a3);
  if (res[3]!=0) res[3][0]=a2;
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
    case 0: return casadi_s1;
    case 1: return casadi_s2;
    case 2: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* observe_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    case 1: return casadi_s2;
    case 2: return casadi_s2;
    case 3: return casadi_s2;
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

/* update_p:(z[3],g[4],p,h[3])->(p1) */
static int casadi_f13(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4, a5, a6, a7;
  a0=1.;
  a1=arg[3]? arg[3][0] : 0;
  a2=5.0000000000000000e-01;
  a3=3.0000000000000004e+00;
  a4=arg[0]? arg[0][0] : 0;
  a5=(a3*a4);
  a6=4.6410161513775439e-01;
  a7=arg[0]? arg[0][1] : 0;
  a6=(a6*a7);
  a5=(a5+a6);
  a5=(a2*a5);
  a6=-6.4641016151377553e+00;
  a6=(a6*a4);
  a3=(a3*a7);
  a6=(a6+a3);
  a2=(a2*a6);
  a5=(a5+a2);
  a1=(a1*a5);
  a1=casadi_sq(a1);
  a5=4.;
  a1=(a1/a5);
  a0=(a0+a1);
  a1=arg[0]? arg[0][2] : 0;
  a0=(a0*a1);
  if (res[0]!=0) res[0][0]=a0;
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
    case 2: return casadi_s2;
    case 3: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* update_p_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
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

/* velocity_step:(g[4],p,xi,h[3])->(xi1) */
static int casadi_f14(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1;
  a0=arg[2]? arg[2][0] : 0;
  a1=arg[1]? arg[1][0] : 0;
  a1=(a0-a1);
  a0=(a0-a1);
  if (res[0]!=0) res[0][0]=a0;
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
    case 0: return casadi_s1;
    case 1: return casadi_s2;
    case 2: return casadi_s2;
    case 3: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* velocity_step_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
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

/* record:(g[4],p,xi,h[3])->(row[7]) */
static int casadi_f15(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4;
  a0=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a0;
  a1=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a1;
  a1=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a1;
  a1=arg[0]? arg[0][3] : 0;
  if (res[0]!=0) res[0][3]=a1;
  a1=arg[1]? arg[1][0] : 0;
  if (res[0]!=0) res[0][4]=a1;
  a1=arg[2]? arg[2][0] : 0;
  a2=casadi_sq(a1);
  a3=5.0000000000000000e-01;
  a3=(a3*a2);
  a3=(a3+a0);
  a2=(a2-a3);
  if (res[0]!=0) res[0][5]=a2;
  a2=-5.0000000000000000e-01;
  a2=(a2*a1);
  a3=arg[3]? arg[3][2] : 0;
  a0=6.6666666666666663e-01;
  a4=arg[3]? arg[3][1] : 0;
  a0=(a0*a4);
  a0=cos(a0);
  a3=(a3*a0);
  a2=(a2+a3);
  a2=(a2*a1);
  if (res[0]!=0) res[0][6]=a2;
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
    case 0: return casadi_s1;
    case 1: return casadi_s2;
    case 2: return casadi_s2;
    case 3: return casadi_s0;
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

/* step_partials:(z[3],g[4],p,h[3])->(Fs[6],Yz[6],Ys[4],FH[9],YH[6]) */
static int casadi_f16(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50;
  a00=5.0000000000000000e-01;
  a01=arg[3]? arg[3][0] : 0;
  a02=(a00*a01);
  a03=1.;
  a04=arg[0]? arg[0][0] : 0;
  a05=(a01*a04);
  a06=casadi_sq(a05);
  a07=4.;
  a06=(a06/a07);
  a08=(a03-a06);
  a06=(a03+a06);
  a08=(a08/a06);
  a09=arg[1]? arg[1][0] : 0;
  a10=(a08*a09);
  a11=(a05/a06);
  a12=arg[1]? arg[1][2] : 0;
  a13=(a11*a12);
  a10=(a10+a13);
  a10=(a02*a10);
  a10=(a10/a01);
  a10=(-a10);
  if (res[0]!=0) res[0][0]=a10;
  a10=arg[0]? arg[0][1] : 0;
  a13=(a01*a10);
  a14=casadi_sq(a13);
  a14=(a14/a07);
  a15=(a03-a14);
  a14=(a03+a14);
  a15=(a15/a14);
  a16=(a15*a09);
  a17=(a13/a14);
  a18=(a17*a12);
  a16=(a16+a18);
  a16=(a02*a16);
  a16=(a16/a01);
  a16=(-a16);
  if (res[0]!=0) res[0][1]=a16;
  a16=0.;
  if (res[0]!=0) res[0][2]=a16;
  if (res[0]!=0) res[0][3]=a16;
  if (res[0]!=0) res[0][4]=a16;
  if (res[0]!=0) res[0][5]=a03;
  a18=3.0000000000000004e+00;
  a19=(a18*a04);
  a20=4.6410161513775439e-01;
  a20=(a20*a10);
  a19=(a19+a20);
  a20=(a00*a19);
  a21=-6.4641016151377553e+00;
  a21=(a21*a04);
  a18=(a18*a10);
  a21=(a21+a18);
  a18=(a00*a21);
  a20=(a20+a18);
  a18=(a01*a20);
  a22=casadi_sq(a18);
  a22=(a22/a07);
  a07=(a03-a22);
  a03=(a03+a22);
  a07=(a07/a03);
  a22=(a12*a07);
  a23=(a18/a03);
  a24=(a09*a23);
  a22=(a22-a24);
  a24=-1.7320508075688774e+00;
  a24=(a24*a01);
  a25=(a24/a03);
  a26=(a23/a03);
  a27=2.5000000000000000e-01;
  a18=(2.*a18);
  a24=(a18*a24);
  a24=(a27*a24);
  a28=(a26*a24);
  a25=(a25-a28);
  a28=(a12*a25);
  a29=(a24/a03);
  a30=(a07/a03);
  a31=(a30*a24);
  a29=(a29+a31);
  a31=(a09*a29);
  a28=(a28-a31);
  a28=(a22*a28);
  a31=arg[1]? arg[1][3] : 0;
  a32=(a31*a07);
  a33=arg[1]? arg[1][1] : 0;
  a34=(a33*a23);
  a32=(a32-a34);
  a25=(a31*a25);
  a29=(a33*a29);
  a25=(a25-a29);
  a25=(a32*a25);
  a28=(a28+a25);
  if (res[1]!=0) res[1][0]=a28;
  a28=arg[0]? arg[0][2] : 0;
  a24=(a28*a24);
  if (res[1]!=0) res[1][1]=a24;
  a24=1.7320508075688774e+00;
  a24=(a24*a01);
  a25=(a24/a03);
  a24=(a18*a24);
  a24=(a27*a24);
  a29=(a26*a24);
  a25=(a25-a29);
  a29=(a12*a25);
  a34=(a24/a03);
  a35=(a30*a24);
  a34=(a34+a35);
  a35=(a09*a34);
  a29=(a29-a35);
  a29=(a22*a29);
  a25=(a31*a25);
  a34=(a33*a34);
  a25=(a25-a34);
  a25=(a32*a25);
  a29=(a29+a25);
  if (res[1]!=0) res[1][2]=a29;
  a24=(a28*a24);
  if (res[1]!=0) res[1][3]=a24;
  if (res[1]!=0) res[1][4]=a16;
  if (res[1]!=0) res[1][5]=a03;
  a24=(a07*a12);
  a29=(a23*a09);
  a24=(a24-a29);
  a24=(a22*a24);
  a07=(a07*a31);
  a23=(a23*a33);
  a07=(a07-a23);
  a07=(a32*a07);
  a24=(a24+a07);
  if (res[2]!=0) res[2][0]=a24;
  if (res[2]!=0) res[2][1]=a16;
  if (res[2]!=0) res[2][2]=a16;
  if (res[2]!=0) res[2][3]=a16;
  a24=1.5000000000000002e+00;
  a19=(a19/a06);
  a07=(a19/a06);
  a23=(a07-a28);
  a29=(a24*a23);
  a25=-3.2320508075688776e+00;
  a21=(a21/a14);
  a34=(a21/a14);
  a35=(a34-a28);
  a36=(a25*a35);
  a29=(a29+a36);
  a05=(2.*a05);
  a36=(a01*a28);
  a36=(a00*a36);
  a37=5.3867513459481287e-01;
  a38=2.3205080756887719e-01;
  a23=(a38*a23);
  a35=(a24*a35);
  a23=(a23+a35);
  a35=(a01*a23);
  a39=(a37*a35);
  a39=(a36+a39);
  a40=(a01*a29);
  a41=(a27*a40);
  a39=(a39+a41);
  a41=(a19*a39);
  a41=(a27*a41);
  a42=(a05*a41);
  a42=(a29-a42);
  a43=(a05*a04);
  a43=(a27*a43);
  a44=(a42*a43);
  a45=(a07*a43);
  a46=(a45/a06);
  a07=(a07/a06);
  a07=(a07*a43);
  a46=(a46+a07);
  a07=(a24*a46);
  a13=(2.*a13);
  a47=(a13*a10);
  a47=(a27*a47);
  a48=(a34*a47);
  a49=(a48/a14);
  a34=(a34/a14);
  a34=(a34*a47);
  a49=(a49+a34);
  a25=(a25*a49);
  a07=(a07+a25);
  a25=(2.*a04);
  a41=(a41*a25);
  a25=(a00*a28);
  a38=(a38*a46);
  a24=(a24*a49);
  a38=(a38+a24);
  a24=(a01*a38);
  a24=(a23-a24);
  a37=(a37*a24);
  a37=(a25+a37);
  a49=(a01*a07);
  a29=(a29-a49);
  a49=(a27*a29);
  a37=(a37+a49);
  a37=(a19*a37);
  a39=(a39*a45);
  a37=(a37-a39);
  a37=(a27*a37);
  a05=(a05*a37);
  a41=(a41+a05);
  a07=(a07+a41);
  a07=(a06*a07);
  a44=(a44-a07);
  a07=-5.0000000000000000e-01;
  a19=(a07*a19);
  a41=arg[3]? arg[3][2] : 0;
  a05=6.6666666666666663e-01;
  a37=arg[3]? arg[3][1] : 0;
  a39=2.1132486540518713e-01;
  a39=(a39*a01);
  a39=(a37+a39);
  a39=(a05*a39);
  a49=cos(a39);
  a46=(a41*a49);
  a19=(a19+a46);
  a46=(a00*a19);
  a45=(a07*a45);
  a34=1.4088324360345808e-01;
  a39=sin(a39);
  a34=(a34*a39);
  a34=(a41*a34);
  a45=(a45+a34);
  a45=(a02*a45);
  a46=(a46-a45);
  a46=(a44+a46);
  a45=(a12*a08);
  a34=(a09*a11);
  a45=(a45-a34);
  a34=(a00*a45);
  a50=(a43/a06);
  a08=(a08/a06);
  a08=(a08*a43);
  a50=(a50+a08);
  a50=(a12*a50);
  a04=(a04/a06);
  a11=(a11/a06);
  a11=(a11*a43);
  a04=(a04-a11);
  a04=(a09*a04);
  a50=(a50+a04);
  a50=(a02*a50);
  a34=(a34-a50);
  a46=(a46+a34);
  a46=(a46/a01);
  a06=(a06*a42);
  a19=(a19*a02);
  a06=(a06+a19);
  a45=(a45*a02);
  a06=(a06+a45);
  a06=(a06/a01);
  a06=(a06/a01);
  a46=(a46-a06);
  if (res[3]!=0) res[3][0]=a46;
  a46=(a07*a21);
  a06=7.8867513459481287e-01;
  a06=(a06*a01);
  a37=(a37+a06);
  a37=(a05*a37);
  a06=cos(a37);
  a45=(a41*a06);
  a46=(a46+a45);
  a45=(a00*a46);
  a07=(a07*a48);
  a19=5.2578342306320858e-01;
  a37=sin(a37);
  a19=(a19*a37);
  a19=(a41*a19);
  a07=(a07+a19);
  a07=(a02*a07);
  a45=(a45-a07);
  a07=(a12*a15);
  a19=(a09*a17);
  a07=(a07-a19);
  a00=(a00*a07);
  a19=(a47/a14);
  a15=(a15/a14);
  a15=(a15*a47);
  a19=(a19+a15);
  a19=(a12*a19);
  a15=(a10/a14);
  a17=(a17/a14);
  a17=(a17*a47);
  a15=(a15-a17);
  a15=(a09*a15);
  a19=(a19+a15);
  a19=(a02*a19);
  a00=(a00-a19);
  a45=(a45+a00);
  a35=(a27*a35);
  a36=(a36+a35);
  a35=-3.8675134594812879e-02;
  a40=(a35*a40);
  a36=(a36+a40);
  a40=(a21*a36);
  a40=(a27*a40);
  a00=(a13*a40);
  a23=(a23-a00);
  a47=(a23*a47);
  a10=(2.*a10);
  a40=(a40*a10);
  a24=(a27*a24);
  a25=(a25+a24);
  a35=(a35*a29);
  a25=(a25+a35);
  a21=(a21*a25);
  a36=(a36*a48);
  a21=(a21-a36);
  a21=(a27*a21);
  a13=(a13*a21);
  a40=(a40+a13);
  a38=(a38+a40);
  a38=(a14*a38);
  a47=(a47-a38);
  a45=(a45+a47);
  a45=(a45/a01);
  a46=(a46*a02);
  a07=(a07*a02);
  a46=(a46+a07);
  a14=(a14*a23);
  a46=(a46+a14);
  a46=(a46/a01);
  a46=(a46/a01);
  a45=(a45-a46);
  if (res[3]!=0) res[3][1]=a45;
  a18=(a18*a20);
  a27=(a27*a18);
  a28=(a28*a27);
  a47=(a28+a47);
  a47=(a47+a44);
  a47=(-a47);
  if (res[3]!=0) res[3][2]=a47;
  a39=(a05*a39);
  a39=(a41*a39);
  a39=(a02*a39);
  a39=(a39/a01);
  a39=(-a39);
  if (res[3]!=0) res[3][3]=a39;
  a05=(a05*a37);
  a41=(a41*a05);
  a41=(a02*a41);
  a41=(a41/a01);
  a41=(-a41);
  if (res[3]!=0) res[3][4]=a41;
  if (res[3]!=0) res[3][5]=a16;
  a49=(a02*a49);
  a49=(a49/a01);
  if (res[3]!=0) res[3][6]=a49;
  a02=(a02*a06);
  a02=(a02/a01);
  if (res[3]!=0) res[3][7]=a02;
  if (res[3]!=0) res[3][8]=a16;
  a20=(a20/a03);
  a26=(a26*a27);
  a20=(a20-a26);
  a12=(a12*a20);
  a03=(a27/a03);
  a30=(a30*a27);
  a03=(a03+a30);
  a09=(a09*a03);
  a12=(a12-a09);
  a22=(a22*a12);
  a31=(a31*a20);
  a33=(a33*a03);
  a31=(a31-a33);
  a32=(a32*a31);
  a22=(a22+a32);
  if (res[4]!=0) res[4][0]=a22;
  if (res[4]!=0) res[4][1]=a28;
  if (res[4]!=0) res[4][2]=a16;
  if (res[4]!=0) res[4][3]=a16;
  if (res[4]!=0) res[4][4]=a16;
  if (res[4]!=0) res[4][5]=a16;
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
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* step_partials_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s5;
    case 1: return casadi_s5;
    case 2: return casadi_s1;
    case 3: return casadi_s3;
    case 4: return casadi_s5;
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
#endif

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

/* residual(z[3], g[4], p[1], h[3]) -> (F[3]) */
#define HPGEN_RESIDUAL_SZ_ARG 4
#define HPGEN_RESIDUAL_SZ_RES 1
#define HPGEN_RESIDUAL_SZ_IW 0
#define HPGEN_RESIDUAL_SZ_W 28
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

/* jacobian(z[3], g[4], p[1], h[3]) -> (J[9]) */
/* = output 1 of residual_jacobian (the same CasADi algorithm; its other outputs are
   computed into scratch and dropped) */
HPGEN_EXPORT int hpgen_kernel_jacobian(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    double scratch[HPGEN_NZ];
    return hpgen_k_residual_jacobian(in0, in1, in2, in3, scratch, out0);
}

/* residual_jacobian(z[3], g[4], p[1], h[3]) -> (F[3], J[9]) */
#define HPGEN_RESIDUAL_JACOBIAN_SZ_ARG 4
#define HPGEN_RESIDUAL_JACOBIAN_SZ_RES 2
#define HPGEN_RESIDUAL_JACOBIAN_SZ_IW 0
#define HPGEN_RESIDUAL_JACOBIAN_SZ_W 44
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

/* update(z[3], g[4], p[1], h[3]) -> (g1[4], p1[1]) */
#define HPGEN_UPDATE_SZ_ARG 4
#define HPGEN_UPDATE_SZ_RES 2
#define HPGEN_UPDATE_SZ_IW 0
#define HPGEN_UPDATE_SZ_W 9
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

/* guess(xi[1], g[4], p[1], h[3]) -> (z0[3]) */
#define HPGEN_GUESS_SZ_ARG 4
#define HPGEN_GUESS_SZ_RES 1
#define HPGEN_GUESS_SZ_IW 0
#define HPGEN_GUESS_SZ_W 2
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

/* legendre(g[4], xi[1], h[3]) -> (mu[1]) */
#define HPGEN_LEGENDRE_SZ_ARG 3
#define HPGEN_LEGENDRE_SZ_RES 1
#define HPGEN_LEGENDRE_SZ_IW 0
#define HPGEN_LEGENDRE_SZ_W 1
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

/* hessian(g[4], xi[1], h[3]) -> (H[1]) */
#define HPGEN_HESSIAN_SZ_ARG 3
#define HPGEN_HESSIAN_SZ_RES 1
#define HPGEN_HESSIAN_SZ_IW 0
#define HPGEN_HESSIAN_SZ_W 1
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

/* energy(g[4], xi[1], h[3]) -> (E[1]) */
#define HPGEN_ENERGY_SZ_ARG 3
#define HPGEN_ENERGY_SZ_RES 1
#define HPGEN_ENERGY_SZ_IW 0
#define HPGEN_ENERGY_SZ_W 3
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

/* momentum(g[4], p[1]) -> (m[1]) */
#define HPGEN_MOMENTUM_SZ_ARG 2
#define HPGEN_MOMENTUM_SZ_RES 1
#define HPGEN_MOMENTUM_SZ_IW 0
#define HPGEN_MOMENTUM_SZ_W 3
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

/* defect(g[4]) -> (e[1]) */
#define HPGEN_DEFECT_SZ_ARG 1
#define HPGEN_DEFECT_SZ_RES 1
#define HPGEN_DEFECT_SZ_IW 0
#define HPGEN_DEFECT_SZ_W 8
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

/* margin(z[3], h[3]) -> (m[1]) */
#define HPGEN_MARGIN_SZ_ARG 2
#define HPGEN_MARGIN_SZ_RES 1
#define HPGEN_MARGIN_SZ_IW 0
#define HPGEN_MARGIN_SZ_W 9
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

/* section(g[4], p[1]) -> (s[1]) */
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

/* chart_point(z[3], g[4], h[3], theta[1]) -> (g_theta[4]) */
#define HPGEN_CHART_POINT_SZ_ARG 4
#define HPGEN_CHART_POINT_SZ_RES 1
#define HPGEN_CHART_POINT_SZ_IW 0
#define HPGEN_CHART_POINT_SZ_W 10
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

/* observe(g[4], p[1], h[3]) -> (xi[1], E[1], m[1], e[1]) */
#define HPGEN_OBSERVE_SZ_ARG 3
#define HPGEN_OBSERVE_SZ_RES 4
#define HPGEN_OBSERVE_SZ_IW 0
#define HPGEN_OBSERVE_SZ_W 9
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

/* update_p(z[3], g[4], p[1], h[3]) -> (p1[1]) */
#define HPGEN_UPDATE_P_SZ_ARG 4
#define HPGEN_UPDATE_P_SZ_RES 1
#define HPGEN_UPDATE_P_SZ_IW 0
#define HPGEN_UPDATE_P_SZ_W 8
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

/* velocity_step(g[4], p[1], xi[1], h[3]) -> (xi1[1]) */
#define HPGEN_VELOCITY_STEP_SZ_ARG 4
#define HPGEN_VELOCITY_STEP_SZ_RES 1
#define HPGEN_VELOCITY_STEP_SZ_IW 0
#define HPGEN_VELOCITY_STEP_SZ_W 2
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

/* record(g[4], p[1], xi[1], h[3]) -> (row[7]) */
#define HPGEN_RECORD_SZ_ARG 4
#define HPGEN_RECORD_SZ_RES 1
#define HPGEN_RECORD_SZ_IW 0
#define HPGEN_RECORD_SZ_W 5
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

/* step_partials(z[3], g[4], p[1], h[3]) -> (Fs[6], Yz[6], Ys[4], FH[9], YH[6]) */
#define HPGEN_STEP_PARTIALS_SZ_ARG 4
#define HPGEN_STEP_PARTIALS_SZ_RES 5
#define HPGEN_STEP_PARTIALS_SZ_IW 0
#define HPGEN_STEP_PARTIALS_SZ_W 51
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

#include "hpgen_runtime.c"
