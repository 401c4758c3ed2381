/*
 * hpgen generated module free_rigid_body_stormer_verlet_cay_truncated -- do not edit, regenerate with hpgen
 * model: free_rigid_body
 * options: tableau=stormer-verlet, tau=cay, rkmk=truncated
 * hpgen version: 0.1.0
 * content hash (normalized model + options): 3b5e8c59678a8d08dcfbeb794dc549e09d951a1bd2a11e84fefde85f6aa301ff
 *
 * C backend: the model's sizes, CasADi's generated kernels (symbols hidden) and their
 * wrappers hpgen_kernel_<name> (exported), then hpgen's C runtime (hpgen/runtime/c:
 * hpgen_runtime.h, hpgen_runtime.c), compiled with them as one translation unit; the
 * contract with hpgen.runtime is hpgen.abi.
 */
/* the model (hpgen_runtime.h) */
#define HPGEN_N 3
#define HPGEN_D 3
#define HPGEN_NZ 3
#define HPGEN_OPEN 0
/* the scene's record row (kernel record): its width and what it needs */
#define HPGEN_W 16
#define HPGEN_RECORD_USES_XI 1
#define HPGEN_LEGENDRE_QUADRATIC 1
/* neither the step (residual, p_{k+1}) nor the record row use g: hpgen_advance_record does
   not reconstruct the group at all */
#define HPGEN_SKIP_G 0
/* the step's kernels are small: inlined into the step */
#define HPGEN_FLATTEN 1
#define HPGEN_HASH "3b5e8c59678a8d08dcfbeb794dc549e09d951a1bd2a11e84fefde85f6aa301ff"
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
  #define CASADI_PREFIX(ID) hpgen_free_rigid_body_stormer_verlet_cay_truncated__ ## ID
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
CASADI_SYMBOL_EXPORT void hpgen_free_rigid_body_stormer_verlet_cay_truncated__casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int hpgen_free_rigid_body_stormer_verlet_cay_truncated__casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int hpgen_free_rigid_body_stormer_verlet_cay_truncated__casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {9, 1, 1};
static const casadi_int casadi_s2[3] = {1, 1, 1};
static const casadi_int casadi_s3[3] = {16, 1, 1};
static const casadi_int casadi_s4[3] = {18, 1, 1};
static const casadi_int casadi_s5[3] = {36, 1, 1};

/* residual:(z[3],g[9],p[3],h)->(F[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13;
  a00=arg[2]? arg[2][0] : 0;
  a01=arg[3]? arg[3][0] : 0;
  a02=arg[0]? arg[0][2] : 0;
  a03=(a01*a02);
  a04=5.0000000000000000e-01;
  a05=arg[0]? arg[0][1] : 0;
  a04=(a04*a05);
  a06=(a03*a04);
  a07=(a01*a05);
  a08=3.3333333333333331e-01;
  a08=(a08*a02);
  a09=(a07*a08);
  a06=(a06-a09);
  a09=arg[0]? arg[0][0] : 0;
  a01=(a01*a09);
  a10=2.5000000000000000e-01;
  a11=6.6666666666666663e-01;
  a11=(a11*a02);
  a02=(a03*a11);
  a12=(a07*a05);
  a02=(a02+a12);
  a12=(2.*a09);
  a13=(a01*a12);
  a02=(a02+a13);
  a10=(a10*a02);
  a02=(a01*a10);
  a06=(a06-a02);
  a06=(a06-a12);
  a00=(a00+a06);
  if (res[0]!=0) res[0][0]=a00;
  a00=arg[2]? arg[2][1] : 0;
  a08=(a01*a08);
  a08=(a08-a05);
  a05=(a07*a10);
  a08=(a08-a05);
  a05=(a03*a09);
  a08=(a08-a05);
  a00=(a00+a08);
  if (res[0]!=0) res[0][1]=a00;
  a00=arg[2]? arg[2][2] : 0;
  a07=(a07*a09);
  a01=(a01*a04);
  a11=(a11+a01);
  a03=(a03*a10);
  a11=(a11+a03);
  a07=(a07-a11);
  a00=(a00+a07);
  if (res[0]!=0) res[0][2]=a00;
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

/* residual_jacobian:(z[3],g[9],p[3],h)->(F[3],J[9]) */
static int casadi_f1(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18;
  a00=arg[2]? arg[2][0] : 0;
  a01=arg[3]? arg[3][0] : 0;
  a02=arg[0]? arg[0][2] : 0;
  a03=(a01*a02);
  a04=5.0000000000000000e-01;
  a05=arg[0]? arg[0][1] : 0;
  a06=(a04*a05);
  a07=(a03*a06);
  a08=(a01*a05);
  a09=3.3333333333333331e-01;
  a10=(a09*a02);
  a11=(a08*a10);
  a07=(a07-a11);
  a11=arg[0]? arg[0][0] : 0;
  a12=(a01*a11);
  a13=2.5000000000000000e-01;
  a14=6.6666666666666663e-01;
  a02=(a14*a02);
  a15=(a03*a02);
  a16=(a08*a05);
  a15=(a15+a16);
  a16=(2.*a11);
  a17=(a12*a16);
  a15=(a15+a17);
  a15=(a13*a15);
  a17=(a12*a15);
  a07=(a07-a17);
  a07=(a07-a16);
  a00=(a00+a07);
  if (res[0]!=0) res[0][0]=a00;
  a00=arg[2]? arg[2][1] : 0;
  a07=(a12*a10);
  a07=(a07-a05);
  a17=(a08*a15);
  a07=(a07-a17);
  a17=(a03*a11);
  a07=(a07-a17);
  a00=(a00+a07);
  if (res[0]!=0) res[0][1]=a00;
  a00=arg[2]? arg[2][2] : 0;
  a07=(a08*a11);
  a17=(a12*a06);
  a17=(a02+a17);
  a18=(a03*a15);
  a17=(a17+a18);
  a07=(a07-a17);
  a00=(a00+a07);
  if (res[0]!=0) res[0][2]=a00;
  a00=-2.;
  a15=(a15*a01);
  a16=(a16*a01);
  a07=(2.*a12);
  a16=(a16+a07);
  a16=(a13*a16);
  a07=(a12*a16);
  a07=(a15+a07);
  a00=(a00-a07);
  if (res[1]!=0) res[1][0]=a00;
  a10=(a10*a01);
  a00=(a08*a16);
  a00=(a10-a00);
  a00=(a00-a03);
  if (res[1]!=0) res[1][1]=a00;
  a06=(a06*a01);
  a16=(a03*a16);
  a16=(a06+a16);
  a16=(a08-a16);
  if (res[1]!=0) res[1][2]=a16;
  a16=(a04*a03);
  a16=(a16-a10);
  a05=(a05*a01);
  a05=(a04*a05);
  a10=(a12*a05);
  a16=(a16-a10);
  if (res[1]!=0) res[1][3]=a16;
  a16=-1.;
  a10=(a08*a05);
  a10=(a15+a10);
  a16=(a16-a10);
  if (res[1]!=0) res[1][4]=a16;
  a11=(a11*a01);
  a04=(a04*a12);
  a05=(a03*a05);
  a04=(a04+a05);
  a04=(a11-a04);
  if (res[1]!=0) res[1][5]=a04;
  a04=(a09*a08);
  a06=(a06-a04);
  a02=(a02*a01);
  a01=(a14*a03);
  a02=(a02+a01);
  a13=(a13*a02);
  a02=(a12*a13);
  a06=(a06-a02);
  if (res[1]!=0) res[1][6]=a06;
  a09=(a09*a12);
  a08=(a08*a13);
  a09=(a09-a08);
  a09=(a09-a11);
  if (res[1]!=0) res[1][7]=a09;
  a03=(a03*a13);
  a15=(a15+a03);
  a14=(a14+a15);
  a14=(-a14);
  if (res[1]!=0) res[1][8]=a14;
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

/* update:(z[3],g[9],p[3],h)->(g1[9],p1[3]) */
static int casadi_f2(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24;
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
  a03=(a03*a11);
  a12=casadi_sq(a03);
  a10=(a10+a12);
  a10=(a02+a10);
  a02=(a02/a10);
  a10=(a12+a09);
  a13=2.;
  a10=(a10/a13);
  a10=(a02*a10);
  a10=(a01-a10);
  a14=(a00*a10);
  a15=arg[1]? arg[1][3] : 0;
  a16=(a05*a08);
  a16=(a16/a13);
  a16=(a03+a16);
  a16=(a02*a16);
  a17=(a15*a16);
  a14=(a14+a17);
  a17=arg[1]? arg[1][6] : 0;
  a18=(a05*a03);
  a18=(a18/a13);
  a18=(a18-a08);
  a18=(a02*a18);
  a19=(a17*a18);
  a14=(a14+a19);
  if (res[0]!=0) res[0][0]=a14;
  a14=arg[1]? arg[1][1] : 0;
  a19=(a14*a10);
  a20=arg[1]? arg[1][4] : 0;
  a21=(a20*a16);
  a19=(a19+a21);
  a21=arg[1]? arg[1][7] : 0;
  a22=(a21*a18);
  a19=(a19+a22);
  if (res[0]!=0) res[0][1]=a19;
  a19=arg[1]? arg[1][2] : 0;
  a10=(a19*a10);
  a22=arg[1]? arg[1][5] : 0;
  a16=(a22*a16);
  a10=(a10+a16);
  a16=arg[1]? arg[1][8] : 0;
  a18=(a16*a18);
  a10=(a10+a18);
  if (res[0]!=0) res[0][2]=a10;
  a10=(a08*a05);
  a10=(a10/a13);
  a10=(a10-a03);
  a10=(a02*a10);
  a18=(a00*a10);
  a12=(a12+a06);
  a12=(a12/a13);
  a12=(a02*a12);
  a12=(a01-a12);
  a23=(a15*a12);
  a18=(a18+a23);
  a23=(a08*a03);
  a23=(a23/a13);
  a23=(a05+a23);
  a23=(a02*a23);
  a24=(a17*a23);
  a18=(a18+a24);
  if (res[0]!=0) res[0][3]=a18;
  a18=(a14*a10);
  a24=(a20*a12);
  a18=(a18+a24);
  a24=(a21*a23);
  a18=(a18+a24);
  if (res[0]!=0) res[0][4]=a18;
  a10=(a19*a10);
  a12=(a22*a12);
  a10=(a10+a12);
  a23=(a16*a23);
  a10=(a10+a23);
  if (res[0]!=0) res[0][5]=a10;
  a10=(a03*a05);
  a10=(a10/a13);
  a10=(a08+a10);
  a10=(a02*a10);
  a00=(a00*a10);
  a23=(a03*a08);
  a23=(a23/a13);
  a23=(a23-a05);
  a23=(a02*a23);
  a15=(a15*a23);
  a00=(a00+a15);
  a09=(a09+a06);
  a09=(a09/a13);
  a02=(a02*a09);
  a01=(a01-a02);
  a17=(a17*a01);
  a00=(a00+a17);
  if (res[0]!=0) res[0][6]=a00;
  a14=(a14*a10);
  a20=(a20*a23);
  a14=(a14+a20);
  a21=(a21*a01);
  a14=(a14+a21);
  if (res[0]!=0) res[0][7]=a14;
  a19=(a19*a10);
  a22=(a22*a23);
  a19=(a19+a22);
  a16=(a16*a01);
  a19=(a19+a16);
  if (res[0]!=0) res[0][8]=a19;
  a19=5.0000000000000000e-01;
  a19=(a19*a07);
  a16=(a03*a19);
  a01=3.3333333333333331e-01;
  a01=(a01*a11);
  a22=(a08*a01);
  a16=(a16-a22);
  a22=2.5000000000000000e-01;
  a23=6.6666666666666663e-01;
  a23=(a23*a11);
  a11=(a03*a23);
  a10=(a08*a07);
  a11=(a11+a10);
  a10=(2.*a04);
  a14=(a05*a10);
  a11=(a11+a14);
  a22=(a22*a11);
  a11=(a05*a22);
  a16=(a16+a11);
  a16=(a16+a10);
  if (res[1]!=0) res[1][0]=a16;
  a01=(a05*a01);
  a01=(a01+a07);
  a07=(a08*a22);
  a01=(a01+a07);
  a07=(a03*a04);
  a01=(a01-a07);
  if (res[1]!=0) res[1][1]=a01;
  a05=(a05*a19);
  a23=(a23-a05);
  a03=(a03*a22);
  a23=(a23+a03);
  a08=(a08*a04);
  a23=(a23+a08);
  if (res[1]!=0) res[1][2]=a23;
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

/* guess:(xi[3],g[9],p[3],h)->(z0[3]) */
static int casadi_f3(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0;
  a0=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a0;
  a0=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a0;
  a0=arg[0]? arg[0][2] : 0;
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

/* legendre:(g[9],xi[3])->(mu[3]) */
static int casadi_f4(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1;
  a0=arg[1]? arg[1][0] : 0;
  a0=(2.*a0);
  if (res[0]!=0) res[0][0]=a0;
  a0=arg[1]? arg[1][1] : 0;
  if (res[0]!=0) res[0][1]=a0;
  a0=6.6666666666666663e-01;
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

/* energy:(g[9],xi[3])->(E) */
static int casadi_f6(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4;
  a0=arg[1]? arg[1][0] : 0;
  a1=(2.*a0);
  a1=(a1*a0);
  a2=arg[1]? arg[1][1] : 0;
  a2=casadi_sq(a2);
  a1=(a1+a2);
  a3=6.6666666666666663e-01;
  a4=arg[1]? arg[1][2] : 0;
  a3=(a3*a4);
  a3=(a3*a4);
  a1=(a1+a3);
  a3=5.0000000000000000e-01;
  a3=(a3*a2);
  a0=casadi_sq(a0);
  a3=(a3+a0);
  a0=3.3333333333333331e-01;
  a4=casadi_sq(a4);
  a0=(a0*a4);
  a3=(a3+a0);
  a1=(a1-a3);
  if (res[0]!=0) res[0][0]=a1;
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

/* margin:(z[3],h)->(m) */
static int casadi_f9(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4;
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
  a2=(a2*a4);
  a2=casadi_sq(a2);
  a3=(a3+a2);
  a1=(a1-a3);
  a0=casadi_fmin(a0,a1);
  a0=casadi_fmin(a0,a1);
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

/* chart_point:(z[3],g[9],h,theta)->(g_theta[9]) */
static int casadi_f11(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21;
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
  a04=(a04*a10);
  a03=(a03*a04);
  a04=casadi_sq(a03);
  a09=(a09+a04);
  a09=(a02+a09);
  a02=(a02/a09);
  a09=(a04+a08);
  a10=2.;
  a09=(a09/a10);
  a09=(a02*a09);
  a09=(a01-a09);
  a11=(a00*a09);
  a12=arg[1]? arg[1][3] : 0;
  a13=(a05*a07);
  a13=(a13/a10);
  a13=(a03+a13);
  a13=(a02*a13);
  a14=(a12*a13);
  a11=(a11+a14);
  a14=arg[1]? arg[1][6] : 0;
  a15=(a05*a03);
  a15=(a15/a10);
  a15=(a15-a07);
  a15=(a02*a15);
  a16=(a14*a15);
  a11=(a11+a16);
  if (res[0]!=0) res[0][0]=a11;
  a11=arg[1]? arg[1][1] : 0;
  a16=(a11*a09);
  a17=arg[1]? arg[1][4] : 0;
  a18=(a17*a13);
  a16=(a16+a18);
  a18=arg[1]? arg[1][7] : 0;
  a19=(a18*a15);
  a16=(a16+a19);
  if (res[0]!=0) res[0][1]=a16;
  a16=arg[1]? arg[1][2] : 0;
  a09=(a16*a09);
  a19=arg[1]? arg[1][5] : 0;
  a13=(a19*a13);
  a09=(a09+a13);
  a13=arg[1]? arg[1][8] : 0;
  a15=(a13*a15);
  a09=(a09+a15);
  if (res[0]!=0) res[0][2]=a09;
  a09=(a07*a05);
  a09=(a09/a10);
  a09=(a09-a03);
  a09=(a02*a09);
  a15=(a00*a09);
  a04=(a04+a06);
  a04=(a04/a10);
  a04=(a02*a04);
  a04=(a01-a04);
  a20=(a12*a04);
  a15=(a15+a20);
  a20=(a07*a03);
  a20=(a20/a10);
  a20=(a05+a20);
  a20=(a02*a20);
  a21=(a14*a20);
  a15=(a15+a21);
  if (res[0]!=0) res[0][3]=a15;
  a15=(a11*a09);
  a21=(a17*a04);
  a15=(a15+a21);
  a21=(a18*a20);
  a15=(a15+a21);
  if (res[0]!=0) res[0][4]=a15;
  a09=(a16*a09);
  a04=(a19*a04);
  a09=(a09+a04);
  a20=(a13*a20);
  a09=(a09+a20);
  if (res[0]!=0) res[0][5]=a09;
  a09=(a03*a05);
  a09=(a09/a10);
  a09=(a07+a09);
  a09=(a02*a09);
  a00=(a00*a09);
  a03=(a03*a07);
  a03=(a03/a10);
  a03=(a03-a05);
  a03=(a02*a03);
  a12=(a12*a03);
  a00=(a00+a12);
  a08=(a08+a06);
  a08=(a08/a10);
  a02=(a02*a08);
  a01=(a01-a02);
  a14=(a14*a01);
  a00=(a00+a14);
  if (res[0]!=0) res[0][6]=a00;
  a11=(a11*a09);
  a17=(a17*a03);
  a11=(a11+a17);
  a18=(a18*a01);
  a11=(a11+a18);
  if (res[0]!=0) res[0][7]=a11;
  a16=(a16*a09);
  a19=(a19*a03);
  a16=(a16+a19);
  a13=(a13*a01);
  a16=(a16+a13);
  if (res[0]!=0) res[0][8]=a16;
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

/* observe:(g[9],p[3])->(xi[3],E,m[3],e) */
static int casadi_f12(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17;
  a00=arg[1]? arg[1][0] : 0;
  a01=2.;
  a01=(a00/a01);
  if (res[0]!=0) res[0][0]=a01;
  a02=arg[1]? arg[1][1] : 0;
  if (res[0]!=0) res[0][1]=a02;
  a03=arg[1]? arg[1][2] : 0;
  a04=6.6666666666666663e-01;
  a04=(a03/a04);
  if (res[0]!=0) res[0][2]=a04;
  a05=(a00*a01);
  a06=casadi_sq(a02);
  a05=(a05+a06);
  a07=(a03*a04);
  a05=(a05+a07);
  a07=5.0000000000000000e-01;
  a07=(a07*a06);
  a01=casadi_sq(a01);
  a07=(a07+a01);
  a01=3.3333333333333331e-01;
  a04=casadi_sq(a04);
  a01=(a01*a04);
  a07=(a07+a01);
  a05=(a05-a07);
  if (res[1]!=0) res[1][0]=a05;
  a05=arg[0]? arg[0][8] : 0;
  a07=arg[0]? arg[0][4] : 0;
  a01=(a05*a07);
  a04=arg[0]? arg[0][7] : 0;
  a06=arg[0]? arg[0][5] : 0;
  a08=(a04*a06);
  a01=(a01-a08);
  a01=(a01*a00);
  a09=arg[0]? arg[0][2] : 0;
  a10=(a09*a04);
  a11=arg[0]? arg[0][1] : 0;
  a12=(a11*a05);
  a10=(a10-a12);
  a10=(a10*a02);
  a01=(a01+a10);
  a10=(a06*a11);
  a13=(a07*a09);
  a10=(a10-a13);
  a10=(a10*a03);
  a01=(a01+a10);
  if (res[2]!=0) res[2][0]=a01;
  a01=arg[0]? arg[0][6] : 0;
  a10=(a01*a06);
  a14=arg[0]? arg[0][3] : 0;
  a15=(a05*a14);
  a10=(a10-a15);
  a10=(a10*a00);
  a15=arg[0]? arg[0][0] : 0;
  a16=(a15*a05);
  a17=(a09*a01);
  a16=(a16-a17);
  a16=(a16*a02);
  a10=(a10+a16);
  a16=(a14*a09);
  a17=(a06*a15);
  a16=(a16-a17);
  a16=(a16*a03);
  a10=(a10+a16);
  if (res[2]!=0) res[2][1]=a10;
  a10=(a04*a14);
  a16=(a01*a07);
  a10=(a10-a16);
  a10=(a10*a00);
  a00=(a11*a01);
  a16=(a15*a04);
  a00=(a00-a16);
  a00=(a00*a02);
  a10=(a10+a00);
  a00=(a07*a15);
  a02=(a14*a11);
  a00=(a00-a02);
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
  a02=(a07*a11);
  a03=(a03+a02);
  a02=(a06*a09);
  a03=(a03+a02);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=(a01*a15);
  a02=(a04*a11);
  a03=(a03+a02);
  a02=(a05*a09);
  a03=(a03+a02);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=(a15*a14);
  a02=(a11*a07);
  a03=(a03+a02);
  a02=(a09*a06);
  a03=(a03+a02);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=casadi_sq(a14);
  a02=casadi_sq(a07);
  a03=(a03+a02);
  a02=casadi_sq(a06);
  a03=(a03+a02);
  a03=(a03-a00);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=(a01*a14);
  a02=(a04*a07);
  a03=(a03+a02);
  a02=(a05*a06);
  a03=(a03+a02);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=(a15*a01);
  a02=(a11*a04);
  a03=(a03+a02);
  a02=(a09*a05);
  a03=(a03+a02);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=(a14*a01);
  a02=(a07*a04);
  a03=(a03+a02);
  a02=(a06*a05);
  a03=(a03+a02);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=casadi_sq(a01);
  a02=casadi_sq(a04);
  a03=(a03+a02);
  a02=casadi_sq(a05);
  a03=(a03+a02);
  a03=(a03-a00);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a07=(a07*a05);
  a07=(a07-a08);
  a15=(a15*a07);
  a04=(a04*a09);
  a12=(a12-a04);
  a14=(a14*a12);
  a15=(a15-a14);
  a11=(a11*a06);
  a11=(a11-a13);
  a01=(a01*a11);
  a15=(a15+a01);
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

/* update_p:(z[3],g[9],p[3],h)->(p1[3]) */
static int casadi_f13(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12;
  a00=arg[3]? arg[3][0] : 0;
  a01=arg[0]? arg[0][2] : 0;
  a02=(a00*a01);
  a03=5.0000000000000000e-01;
  a04=arg[0]? arg[0][1] : 0;
  a03=(a03*a04);
  a05=(a02*a03);
  a06=(a00*a04);
  a07=3.3333333333333331e-01;
  a07=(a07*a01);
  a08=(a06*a07);
  a05=(a05-a08);
  a08=arg[0]? arg[0][0] : 0;
  a00=(a00*a08);
  a09=2.5000000000000000e-01;
  a10=6.6666666666666663e-01;
  a10=(a10*a01);
  a01=(a02*a10);
  a11=(a06*a04);
  a01=(a01+a11);
  a11=(2.*a08);
  a12=(a00*a11);
  a01=(a01+a12);
  a09=(a09*a01);
  a01=(a00*a09);
  a05=(a05+a01);
  a05=(a05+a11);
  if (res[0]!=0) res[0][0]=a05;
  a07=(a00*a07);
  a07=(a07+a04);
  a04=(a06*a09);
  a07=(a07+a04);
  a04=(a02*a08);
  a07=(a07-a04);
  if (res[0]!=0) res[0][1]=a07;
  a00=(a00*a03);
  a10=(a10-a00);
  a02=(a02*a09);
  a10=(a10+a02);
  a06=(a06*a08);
  a10=(a10+a06);
  if (res[0]!=0) res[0][2]=a10;
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

/* velocity_step:(g[9],p[3],xi[3])->(xi1[3]) */
static int casadi_f14(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3;
  a0=arg[2]? arg[2][0] : 0;
  a1=(2.*a0);
  a2=arg[1]? arg[1][0] : 0;
  a1=(a1-a2);
  a2=2.;
  a1=(a1/a2);
  a0=(a0-a1);
  if (res[0]!=0) res[0][0]=a0;
  a0=arg[2]? arg[2][1] : 0;
  a1=arg[1]? arg[1][1] : 0;
  a1=(a0-a1);
  a0=(a0-a1);
  if (res[0]!=0) res[0][1]=a0;
  a0=arg[2]? arg[2][2] : 0;
  a1=6.6666666666666663e-01;
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
  a12=arg[2]? arg[2][0] : 0;
  a13=(2.*a12);
  a13=(a13*a12);
  a14=arg[2]? arg[2][1] : 0;
  a14=casadi_sq(a14);
  a13=(a13+a14);
  a15=6.6666666666666663e-01;
  a16=arg[2]? arg[2][2] : 0;
  a15=(a15*a16);
  a15=(a15*a16);
  a13=(a13+a15);
  a15=5.0000000000000000e-01;
  a15=(a15*a14);
  a12=casadi_sq(a12);
  a15=(a15+a12);
  a12=3.3333333333333331e-01;
  a16=casadi_sq(a16);
  a12=(a12*a16);
  a15=(a15+a12);
  a13=(a13-a15);
  if (res[0]!=0) res[0][12]=a13;
  a13=(a08*a04);
  a15=(a07*a05);
  a13=(a13-a15);
  a13=(a13*a09);
  a15=(a02*a07);
  a12=(a01*a08);
  a15=(a15-a12);
  a15=(a15*a10);
  a13=(a13+a15);
  a15=(a05*a01);
  a12=(a04*a02);
  a15=(a15-a12);
  a15=(a15*a11);
  a13=(a13+a15);
  if (res[0]!=0) res[0][13]=a13;
  a13=(a06*a05);
  a15=(a08*a03);
  a13=(a13-a15);
  a13=(a13*a09);
  a08=(a00*a08);
  a15=(a02*a06);
  a08=(a08-a15);
  a08=(a08*a10);
  a13=(a13+a08);
  a02=(a03*a02);
  a05=(a05*a00);
  a02=(a02-a05);
  a02=(a02*a11);
  a13=(a13+a02);
  if (res[0]!=0) res[0][14]=a13;
  a13=(a07*a03);
  a02=(a06*a04);
  a13=(a13-a02);
  a13=(a13*a09);
  a06=(a01*a06);
  a07=(a00*a07);
  a06=(a06-a07);
  a06=(a06*a10);
  a13=(a13+a06);
  a04=(a04*a00);
  a03=(a03*a01);
  a04=(a04-a03);
  a04=(a04*a11);
  a13=(a13+a04);
  if (res[0]!=0) res[0][15]=a13;
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

/* step_partials:(z[3],g[9],p[3],h)->(Fs[18],Yz[18],Ys[36]) */
static int casadi_f16(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65;
  a00=0.;
  if (res[0]!=0) res[0][0]=a00;
  if (res[0]!=0) res[0][1]=a00;
  if (res[0]!=0) res[0][2]=a00;
  if (res[0]!=0) res[0][3]=a00;
  if (res[0]!=0) res[0][4]=a00;
  if (res[0]!=0) res[0][5]=a00;
  if (res[0]!=0) res[0][6]=a00;
  if (res[0]!=0) res[0][7]=a00;
  if (res[0]!=0) res[0][8]=a00;
  a01=1.;
  if (res[0]!=0) res[0][9]=a01;
  if (res[0]!=0) res[0][10]=a00;
  if (res[0]!=0) res[0][11]=a00;
  if (res[0]!=0) res[0][12]=a00;
  if (res[0]!=0) res[0][13]=a01;
  if (res[0]!=0) res[0][14]=a00;
  if (res[0]!=0) res[0][15]=a00;
  if (res[0]!=0) res[0][16]=a00;
  if (res[0]!=0) res[0][17]=a01;
  a02=arg[1]? arg[1][0] : 0;
  a03=4.;
  a04=arg[3]? arg[3][0] : 0;
  a05=arg[0]? arg[0][0] : 0;
  a06=(a04*a05);
  a07=casadi_sq(a06);
  a08=arg[0]? arg[0][1] : 0;
  a09=(a04*a08);
  a10=casadi_sq(a09);
  a11=(a07+a10);
  a12=arg[0]? arg[0][2] : 0;
  a13=(a04*a12);
  a14=casadi_sq(a13);
  a11=(a11+a14);
  a11=(a03+a11);
  a03=(a03/a11);
  a15=(a13*a06);
  a16=2.;
  a15=(a15/a16);
  a15=(a09+a15);
  a17=(a03*a15);
  a18=(a02*a17);
  a19=arg[1]? arg[1][3] : 0;
  a20=(a13*a09);
  a20=(a20/a16);
  a20=(a20-a06);
  a21=(a03*a20);
  a22=(a19*a21);
  a18=(a18+a22);
  a22=arg[1]? arg[1][6] : 0;
  a23=(a10+a07);
  a23=(a23/a16);
  a24=(a03*a23);
  a24=(a01-a24);
  a25=(a22*a24);
  a18=(a18+a25);
  a25=5.0000000000000000e-01;
  a26=(a09*a04);
  a26=(a25*a26);
  a26=(a03*a26);
  a27=(a09*a06);
  a27=(a27/a16);
  a27=(a27-a13);
  a11=(a03/a11);
  a28=(2.*a06);
  a29=(a28*a04);
  a30=(a11*a29);
  a31=(a27*a30);
  a31=(a26-a31);
  a32=(a02*a31);
  a29=(a25*a29);
  a29=(a03*a29);
  a07=(a14+a07);
  a07=(a07/a16);
  a33=(a07*a30);
  a33=(a29-a33);
  a34=(a19*a33);
  a32=(a32-a34);
  a34=(a03*a04);
  a35=(a09*a13);
  a35=(a35/a16);
  a35=(a06+a35);
  a36=(a35*a30);
  a36=(a34-a36);
  a37=(a22*a36);
  a32=(a32+a37);
  a32=(a18*a32);
  a37=arg[1]? arg[1][1] : 0;
  a38=(a37*a17);
  a39=arg[1]? arg[1][4] : 0;
  a40=(a39*a21);
  a38=(a38+a40);
  a40=arg[1]? arg[1][7] : 0;
  a41=(a40*a24);
  a38=(a38+a41);
  a41=(a37*a31);
  a42=(a39*a33);
  a41=(a41-a42);
  a42=(a40*a36);
  a41=(a41+a42);
  a41=(a38*a41);
  a32=(a32+a41);
  a41=arg[1]? arg[1][2] : 0;
  a42=(a41*a17);
  a43=arg[1]? arg[1][5] : 0;
  a44=(a43*a21);
  a42=(a42+a44);
  a44=arg[1]? arg[1][8] : 0;
  a45=(a44*a24);
  a42=(a42+a45);
  a31=(a41*a31);
  a33=(a43*a33);
  a31=(a31-a33);
  a36=(a44*a36);
  a31=(a31+a36);
  a31=(a42*a31);
  a32=(a32+a31);
  if (res[1]!=0) res[1][0]=a32;
  a14=(a14+a10);
  a14=(a14/a16);
  a10=(a03*a14);
  a10=(a01-a10);
  a32=(a02*a10);
  a31=(a06*a09);
  a31=(a31/a16);
  a31=(a13+a31);
  a36=(a03*a31);
  a33=(a19*a36);
  a32=(a32+a33);
  a33=(a06*a13);
  a33=(a33/a16);
  a33=(a33-a09);
  a45=(a03*a33);
  a46=(a22*a45);
  a32=(a32+a46);
  a46=(a13*a04);
  a46=(a25*a46);
  a46=(a03*a46);
  a47=(a15*a30);
  a47=(a46-a47);
  a48=(a02*a47);
  a49=(a20*a30);
  a49=(a49+a34);
  a50=(a19*a49);
  a48=(a48-a50);
  a50=(a23*a30);
  a29=(a29-a50);
  a50=(a22*a29);
  a48=(a48-a50);
  a48=(a32*a48);
  a50=(a37*a10);
  a51=(a39*a36);
  a50=(a50+a51);
  a51=(a40*a45);
  a50=(a50+a51);
  a51=(a37*a47);
  a52=(a39*a49);
  a51=(a51-a52);
  a52=(a40*a29);
  a51=(a51-a52);
  a51=(a50*a51);
  a48=(a48+a51);
  a51=(a41*a10);
  a52=(a43*a36);
  a51=(a51+a52);
  a52=(a44*a45);
  a51=(a51+a52);
  a47=(a41*a47);
  a49=(a43*a49);
  a47=(a47-a49);
  a29=(a44*a29);
  a47=(a47-a29);
  a47=(a51*a47);
  a48=(a48+a47);
  if (res[1]!=0) res[1][1]=a48;
  a48=(a03*a27);
  a47=(a02*a48);
  a29=(a03*a07);
  a29=(a01-a29);
  a49=(a19*a29);
  a47=(a47+a49);
  a49=(a03*a35);
  a52=(a22*a49);
  a47=(a47+a52);
  a52=(a14*a30);
  a53=(a02*a52);
  a54=(a31*a30);
  a54=(a26-a54);
  a55=(a19*a54);
  a53=(a53+a55);
  a30=(a33*a30);
  a30=(a46-a30);
  a55=(a22*a30);
  a53=(a53+a55);
  a53=(a47*a53);
  a55=(a37*a48);
  a56=(a39*a29);
  a55=(a55+a56);
  a56=(a40*a49);
  a55=(a55+a56);
  a56=(a37*a52);
  a57=(a39*a54);
  a56=(a56+a57);
  a57=(a40*a30);
  a56=(a56+a57);
  a56=(a55*a56);
  a53=(a53+a56);
  a56=(a41*a48);
  a57=(a43*a29);
  a56=(a56+a57);
  a57=(a44*a49);
  a56=(a56+a57);
  a52=(a41*a52);
  a54=(a43*a54);
  a52=(a52+a54);
  a30=(a44*a30);
  a52=(a52+a30);
  a52=(a56*a52);
  a53=(a53+a52);
  if (res[1]!=0) res[1][2]=a53;
  a53=2.5000000000000000e-01;
  a52=6.6666666666666663e-01;
  a30=(a52*a12);
  a54=(a13*a30);
  a57=(a09*a08);
  a54=(a54+a57);
  a57=(2.*a05);
  a58=(a06*a57);
  a54=(a54+a58);
  a54=(a53*a54);
  a54=(a54*a04);
  a57=(a57*a04);
  a57=(a57+a28);
  a57=(a53*a57);
  a28=(a06*a57);
  a28=(a54+a28);
  a28=(a28+a16);
  if (res[1]!=0) res[1][3]=a28;
  a28=3.3333333333333331e-01;
  a12=(a28*a12);
  a12=(a12*a04);
  a16=(a09*a57);
  a16=(a12+a16);
  a16=(a16-a13);
  if (res[1]!=0) res[1][4]=a16;
  a57=(a13*a57);
  a16=(a25*a08);
  a16=(a16*a04);
  a57=(a57-a16);
  a57=(a57+a09);
  if (res[1]!=0) res[1][5]=a57;
  a57=(a06*a04);
  a57=(a25*a57);
  a57=(a03*a57);
  a58=(2.*a09);
  a58=(a58*a04);
  a59=(a11*a58);
  a60=(a27*a59);
  a60=(a57-a60);
  a61=(a02*a60);
  a62=(a07*a59);
  a63=(a19*a62);
  a61=(a61+a63);
  a63=(a35*a59);
  a63=(a46-a63);
  a64=(a22*a63);
  a61=(a61+a64);
  a61=(a18*a61);
  a64=(a37*a60);
  a65=(a39*a62);
  a64=(a64+a65);
  a65=(a40*a63);
  a64=(a64+a65);
  a64=(a38*a64);
  a61=(a61+a64);
  a60=(a41*a60);
  a62=(a43*a62);
  a60=(a60+a62);
  a63=(a44*a63);
  a60=(a60+a63);
  a60=(a42*a60);
  a61=(a61+a60);
  if (res[1]!=0) res[1][6]=a61;
  a61=(a15*a59);
  a61=(a34-a61);
  a60=(a02*a61);
  a63=(a20*a59);
  a46=(a46-a63);
  a63=(a19*a46);
  a60=(a60+a63);
  a58=(a25*a58);
  a58=(a03*a58);
  a63=(a23*a59);
  a63=(a58-a63);
  a62=(a22*a63);
  a60=(a60-a62);
  a60=(a32*a60);
  a62=(a37*a61);
  a64=(a39*a46);
  a62=(a62+a64);
  a64=(a40*a63);
  a62=(a62-a64);
  a62=(a50*a62);
  a60=(a60+a62);
  a61=(a41*a61);
  a46=(a43*a46);
  a61=(a61+a46);
  a63=(a44*a63);
  a61=(a61-a63);
  a61=(a51*a61);
  a60=(a60+a61);
  if (res[1]!=0) res[1][7]=a60;
  a60=(a31*a59);
  a60=(a57-a60);
  a61=(a19*a60);
  a63=(a14*a59);
  a58=(a58-a63);
  a63=(a02*a58);
  a61=(a61-a63);
  a59=(a33*a59);
  a59=(a59+a34);
  a63=(a22*a59);
  a61=(a61-a63);
  a61=(a47*a61);
  a63=(a39*a60);
  a46=(a37*a58);
  a63=(a63-a46);
  a46=(a40*a59);
  a63=(a63-a46);
  a63=(a55*a63);
  a61=(a61+a63);
  a60=(a43*a60);
  a58=(a41*a58);
  a60=(a60-a58);
  a59=(a44*a59);
  a60=(a60-a59);
  a60=(a56*a60);
  a61=(a61+a60);
  if (res[1]!=0) res[1][8]=a61;
  a61=(a25*a13);
  a61=(a61-a12);
  a08=(a08*a04);
  a08=(a25*a08);
  a12=(a06*a08);
  a61=(a61+a12);
  if (res[1]!=0) res[1][9]=a61;
  a61=(a09*a08);
  a61=(a54+a61);
  a01=(a01+a61);
  if (res[1]!=0) res[1][10]=a01;
  a08=(a13*a08);
  a01=(a25*a06);
  a08=(a08-a01);
  a05=(a05*a04);
  a08=(a08+a05);
  if (res[1]!=0) res[1][11]=a08;
  a08=(2.*a13);
  a08=(a08*a04);
  a11=(a11*a08);
  a35=(a35*a11);
  a35=(a26-a35);
  a01=(a22*a35);
  a27=(a27*a11);
  a27=(a27+a34);
  a61=(a02*a27);
  a25=(a25*a08);
  a03=(a03*a25);
  a07=(a07*a11);
  a07=(a03-a07);
  a25=(a19*a07);
  a61=(a61+a25);
  a01=(a01-a61);
  a01=(a18*a01);
  a61=(a40*a35);
  a25=(a37*a27);
  a08=(a39*a07);
  a25=(a25+a08);
  a61=(a61-a25);
  a61=(a38*a61);
  a01=(a01+a61);
  a35=(a44*a35);
  a27=(a41*a27);
  a07=(a43*a07);
  a27=(a27+a07);
  a35=(a35-a27);
  a35=(a42*a35);
  a01=(a01+a35);
  if (res[1]!=0) res[1][12]=a01;
  a15=(a15*a11);
  a15=(a57-a15);
  a01=(a02*a15);
  a20=(a20*a11);
  a26=(a26-a20);
  a20=(a19*a26);
  a01=(a01+a20);
  a23=(a23*a11);
  a20=(a22*a23);
  a01=(a01+a20);
  a01=(a32*a01);
  a20=(a37*a15);
  a35=(a39*a26);
  a20=(a20+a35);
  a35=(a40*a23);
  a20=(a20+a35);
  a20=(a50*a20);
  a01=(a01+a20);
  a15=(a41*a15);
  a26=(a43*a26);
  a15=(a15+a26);
  a23=(a44*a23);
  a15=(a15+a23);
  a15=(a51*a15);
  a01=(a01+a15);
  if (res[1]!=0) res[1][13]=a01;
  a31=(a31*a11);
  a34=(a34-a31);
  a31=(a19*a34);
  a14=(a14*a11);
  a03=(a03-a14);
  a14=(a02*a03);
  a31=(a31-a14);
  a33=(a33*a11);
  a57=(a57-a33);
  a33=(a22*a57);
  a31=(a31+a33);
  a31=(a47*a31);
  a33=(a39*a34);
  a11=(a37*a03);
  a33=(a33-a11);
  a11=(a40*a57);
  a33=(a33+a11);
  a33=(a55*a33);
  a31=(a31+a33);
  a34=(a43*a34);
  a03=(a41*a03);
  a34=(a34-a03);
  a57=(a44*a57);
  a34=(a34+a57);
  a34=(a56*a34);
  a31=(a31+a34);
  if (res[1]!=0) res[1][14]=a31;
  a31=(a28*a09);
  a16=(a16-a31);
  a30=(a30*a04);
  a04=(a52*a13);
  a30=(a30+a04);
  a53=(a53*a30);
  a30=(a06*a53);
  a16=(a16+a30);
  if (res[1]!=0) res[1][15]=a16;
  a28=(a28*a06);
  a09=(a09*a53);
  a28=(a28+a09);
  a28=(a28-a05);
  if (res[1]!=0) res[1][16]=a28;
  a13=(a13*a53);
  a54=(a54+a13);
  a52=(a52+a54);
  if (res[1]!=0) res[1][17]=a52;
  a52=(a29*a22);
  a54=(a49*a19);
  a52=(a52-a54);
  a52=(a18*a52);
  a54=(a29*a40);
  a13=(a49*a39);
  a54=(a54-a13);
  a54=(a38*a54);
  a52=(a52+a54);
  a54=(a29*a44);
  a13=(a49*a43);
  a54=(a54-a13);
  a54=(a42*a54);
  a52=(a52+a54);
  if (res[2]!=0) res[2][0]=a52;
  a52=(a21*a22);
  a54=(a24*a19);
  a52=(a52-a54);
  a52=(a32*a52);
  a54=(a21*a40);
  a13=(a24*a39);
  a54=(a54-a13);
  a54=(a50*a54);
  a52=(a52+a54);
  a54=(a21*a44);
  a13=(a24*a43);
  a54=(a54-a13);
  a54=(a51*a54);
  a52=(a52+a54);
  if (res[2]!=0) res[2][1]=a52;
  a52=(a36*a22);
  a54=(a45*a19);
  a52=(a52-a54);
  a52=(a47*a52);
  a54=(a36*a40);
  a13=(a45*a39);
  a54=(a54-a13);
  a54=(a55*a54);
  a52=(a52+a54);
  a54=(a36*a44);
  a13=(a45*a43);
  a54=(a54-a13);
  a54=(a56*a54);
  a52=(a52+a54);
  if (res[2]!=0) res[2][2]=a52;
  if (res[2]!=0) res[2][3]=a00;
  if (res[2]!=0) res[2][4]=a00;
  if (res[2]!=0) res[2][5]=a00;
  a52=(a49*a02);
  a54=(a48*a22);
  a52=(a52-a54);
  a52=(a18*a52);
  a54=(a49*a37);
  a13=(a48*a40);
  a54=(a54-a13);
  a54=(a38*a54);
  a52=(a52+a54);
  a49=(a49*a41);
  a54=(a48*a44);
  a49=(a49-a54);
  a49=(a42*a49);
  a52=(a52+a49);
  if (res[2]!=0) res[2][6]=a52;
  a52=(a24*a02);
  a49=(a17*a22);
  a52=(a52-a49);
  a52=(a32*a52);
  a49=(a24*a37);
  a54=(a17*a40);
  a49=(a49-a54);
  a49=(a50*a49);
  a52=(a52+a49);
  a24=(a24*a41);
  a49=(a17*a44);
  a24=(a24-a49);
  a24=(a51*a24);
  a52=(a52+a24);
  if (res[2]!=0) res[2][7]=a52;
  a52=(a45*a02);
  a22=(a10*a22);
  a52=(a52-a22);
  a52=(a47*a52);
  a22=(a45*a37);
  a40=(a10*a40);
  a22=(a22-a40);
  a22=(a55*a22);
  a52=(a52+a22);
  a45=(a45*a41);
  a44=(a10*a44);
  a45=(a45-a44);
  a45=(a56*a45);
  a52=(a52+a45);
  if (res[2]!=0) res[2][8]=a52;
  if (res[2]!=0) res[2][9]=a00;
  if (res[2]!=0) res[2][10]=a00;
  if (res[2]!=0) res[2][11]=a00;
  a52=(a48*a19);
  a45=(a29*a02);
  a52=(a52-a45);
  a18=(a18*a52);
  a52=(a48*a39);
  a45=(a29*a37);
  a52=(a52-a45);
  a38=(a38*a52);
  a18=(a18+a38);
  a48=(a48*a43);
  a29=(a29*a41);
  a48=(a48-a29);
  a42=(a42*a48);
  a18=(a18+a42);
  if (res[2]!=0) res[2][12]=a18;
  a18=(a17*a19);
  a42=(a21*a02);
  a18=(a18-a42);
  a32=(a32*a18);
  a18=(a17*a39);
  a42=(a21*a37);
  a18=(a18-a42);
  a50=(a50*a18);
  a32=(a32+a50);
  a17=(a17*a43);
  a21=(a21*a41);
  a17=(a17-a21);
  a51=(a51*a17);
  a32=(a32+a51);
  if (res[2]!=0) res[2][13]=a32;
  a19=(a10*a19);
  a02=(a36*a02);
  a19=(a19-a02);
  a47=(a47*a19);
  a39=(a10*a39);
  a37=(a36*a37);
  a39=(a39-a37);
  a55=(a55*a39);
  a47=(a47+a55);
  a10=(a10*a43);
  a36=(a36*a41);
  a10=(a10-a36);
  a56=(a56*a10);
  a47=(a47+a56);
  if (res[2]!=0) res[2][14]=a47;
  if (res[2]!=0) res[2][15]=a00;
  if (res[2]!=0) res[2][16]=a00;
  if (res[2]!=0) res[2][17]=a00;
  if (res[2]!=0) res[2][18]=a00;
  if (res[2]!=0) res[2][19]=a00;
  if (res[2]!=0) res[2][20]=a00;
  if (res[2]!=0) res[2][21]=a00;
  if (res[2]!=0) res[2][22]=a00;
  if (res[2]!=0) res[2][23]=a00;
  if (res[2]!=0) res[2][24]=a00;
  if (res[2]!=0) res[2][25]=a00;
  if (res[2]!=0) res[2][26]=a00;
  if (res[2]!=0) res[2][27]=a00;
  if (res[2]!=0) res[2][28]=a00;
  if (res[2]!=0) res[2][29]=a00;
  if (res[2]!=0) res[2][30]=a00;
  if (res[2]!=0) res[2][31]=a00;
  if (res[2]!=0) res[2][32]=a00;
  if (res[2]!=0) res[2][33]=a00;
  if (res[2]!=0) res[2][34]=a00;
  if (res[2]!=0) res[2][35]=a00;
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
#endif

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

/* residual(z[3], g[9], p[3], h[1]) -> (F[3]) */
#define HPGEN_RESIDUAL_SZ_ARG 4
#define HPGEN_RESIDUAL_SZ_RES 1
#define HPGEN_RESIDUAL_SZ_IW 0
#define HPGEN_RESIDUAL_SZ_W 14
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

/* jacobian(z[3], g[9], p[3], h[1]) -> (J[9]) */
/* = output 1 of residual_jacobian (the same CasADi algorithm; its other outputs are
   computed into scratch and dropped) */
HPGEN_EXPORT int hpgen_kernel_jacobian(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    double scratch[HPGEN_NZ];
    return hpgen_k_residual_jacobian(in0, in1, in2, in3, scratch, out0);
}

/* residual_jacobian(z[3], g[9], p[3], h[1]) -> (F[3], J[9]) */
#define HPGEN_RESIDUAL_JACOBIAN_SZ_ARG 4
#define HPGEN_RESIDUAL_JACOBIAN_SZ_RES 2
#define HPGEN_RESIDUAL_JACOBIAN_SZ_IW 0
#define HPGEN_RESIDUAL_JACOBIAN_SZ_W 19
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

/* update(z[3], g[9], p[3], h[1]) -> (g1[9], p1[3]) */
#define HPGEN_UPDATE_SZ_ARG 4
#define HPGEN_UPDATE_SZ_RES 2
#define HPGEN_UPDATE_SZ_IW 0
#define HPGEN_UPDATE_SZ_W 25
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

/* guess(xi[3], g[9], p[3], h[1]) -> (z0[3]) */
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

/* legendre(g[9], xi[3]) -> (mu[3]) */
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

/* hessian(g[9], xi[3]) -> (H[9]) */
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

/* margin(z[3], h[1]) -> (m[1]) */
#define HPGEN_MARGIN_SZ_ARG 2
#define HPGEN_MARGIN_SZ_RES 1
#define HPGEN_MARGIN_SZ_IW 0
#define HPGEN_MARGIN_SZ_W 5
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

/* chart_point(z[3], g[9], h[1], theta[1]) -> (g_theta[9]) */
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

/* update_p(z[3], g[9], p[3], h[1]) -> (p1[3]) */
#define HPGEN_UPDATE_P_SZ_ARG 4
#define HPGEN_UPDATE_P_SZ_RES 1
#define HPGEN_UPDATE_P_SZ_IW 0
#define HPGEN_UPDATE_P_SZ_W 13
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

/* step_partials(z[3], g[9], p[3], h[1]) -> (Fs[18], Yz[18], Ys[36]) */
#define HPGEN_STEP_PARTIALS_SZ_ARG 4
#define HPGEN_STEP_PARTIALS_SZ_RES 3
#define HPGEN_STEP_PARTIALS_SZ_IW 0
#define HPGEN_STEP_PARTIALS_SZ_W 66
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

/* ---- the step's kernels on HPGEN_L lanes (hpgen.codegen.lanes; hpgen_lanes.c runs them) */
#define HPGEN_L 8
HPGEN_LANES_BEGIN
#define HPGEN_LANE_RESIDUAL 1

/* residual_jacobian(z, g, p, h) -> (F, J), 8 lanes: x[i * 8 + lane] */
static void hpgen_lane_residual_jacobian(const double* restrict in0, const double* restrict in1, const double* restrict in2, const double* restrict in3, double* restrict out0, double* restrict out1) {
    int l;
    (void)in0; (void)in1; (void)in2; (void)in3;
    for (l = 0; l < 8; ++l) {
        double a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11;
        double a12, a13, a14, a15, a16, a17, a18;
        a0 = in2[0 + l];
        a1 = in3[0 + l];
        a2 = in0[16 + l];
        a3 = (a1*a2);
        a4 = 0.5;
        a5 = in0[8 + l];
        a6 = (a4*a5);
        a7 = (a3*a6);
        a8 = (a1*a5);
        a9 = 0.3333333333333333;
        a10 = (a9*a2);
        a11 = (a8*a10);
        a7 = (a7-a11);
        a11 = in0[0 + l];
        a12 = (a1*a11);
        a13 = 0.25;
        a14 = 0.6666666666666666;
        a2 = (a14*a2);
        a15 = (a3*a2);
        a16 = (a8*a5);
        a15 = (a15+a16);
        a16 = (2.*a11);
        a17 = (a12*a16);
        a15 = (a15+a17);
        a15 = (a13*a15);
        a17 = (a12*a15);
        a7 = (a7-a17);
        a7 = (a7-a16);
        a0 = (a0+a7);
        out0[0 + l] = a0;
        a0 = in2[8 + l];
        a7 = (a12*a10);
        a7 = (a7-a5);
        a17 = (a8*a15);
        a7 = (a7-a17);
        a17 = (a3*a11);
        a7 = (a7-a17);
        a0 = (a0+a7);
        out0[8 + l] = a0;
        a0 = in2[16 + l];
        a7 = (a8*a11);
        a17 = (a12*a6);
        a17 = (a2+a17);
        a18 = (a3*a15);
        a17 = (a17+a18);
        a7 = (a7-a17);
        a0 = (a0+a7);
        out0[16 + l] = a0;
        a0 = -2.0;
        a15 = (a15*a1);
        a16 = (a16*a1);
        a7 = (2.*a12);
        a16 = (a16+a7);
        a16 = (a13*a16);
        a7 = (a12*a16);
        a7 = (a15+a7);
        a0 = (a0-a7);
        out1[0 + l] = a0;
        a10 = (a10*a1);
        a0 = (a8*a16);
        a0 = (a10-a0);
        a0 = (a0-a3);
        out1[8 + l] = a0;
        a6 = (a6*a1);
        a16 = (a3*a16);
        a16 = (a6+a16);
        a16 = (a8-a16);
        out1[16 + l] = a16;
        a16 = (a4*a3);
        a16 = (a16-a10);
        a5 = (a5*a1);
        a5 = (a4*a5);
        a10 = (a12*a5);
        a16 = (a16-a10);
        out1[24 + l] = a16;
        a16 = -1.0;
        a10 = (a8*a5);
        a10 = (a15+a10);
        a16 = (a16-a10);
        out1[32 + l] = a16;
        a11 = (a11*a1);
        a4 = (a4*a12);
        a5 = (a3*a5);
        a4 = (a4+a5);
        a4 = (a11-a4);
        out1[40 + l] = a4;
        a4 = (a9*a8);
        a6 = (a6-a4);
        a2 = (a2*a1);
        a1 = (a14*a3);
        a2 = (a2+a1);
        a13 = (a13*a2);
        a2 = (a12*a13);
        a6 = (a6-a2);
        out1[48 + l] = a6;
        a9 = (a9*a12);
        a8 = (a8*a13);
        a9 = (a9-a8);
        a9 = (a9-a11);
        out1[56 + l] = a9;
        a3 = (a3*a13);
        a15 = (a15+a3);
        a14 = (a14+a15);
        a14 = (-a14);
        out1[64 + l] = a14;
        (void)a0, (void)a1, (void)a2, (void)a3, (void)a4, (void)a5, (void)a6, (void)a7, (void)a8, (void)a9, (void)a10, (void)a11, (void)a12, (void)a13, (void)a14, (void)a15, (void)a16, (void)a17, (void)a18;
    }
}

/* residual(z, g, p, h) -> (F), 8 lanes: x[i * 8 + lane] */
static void hpgen_lane_residual(const double* restrict in0, const double* restrict in1, const double* restrict in2, const double* restrict in3, double* restrict out0) {
    int l;
    (void)in0; (void)in1; (void)in2; (void)in3;
    for (l = 0; l < 8; ++l) {
        double a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11;
        double a12, a13;
        a0 = in2[0 + l];
        a1 = in3[0 + l];
        a2 = in0[16 + l];
        a3 = (a1*a2);
        a4 = 0.5;
        a5 = in0[8 + l];
        a4 = (a4*a5);
        a6 = (a3*a4);
        a7 = (a1*a5);
        a8 = 0.3333333333333333;
        a8 = (a8*a2);
        a9 = (a7*a8);
        a6 = (a6-a9);
        a9 = in0[0 + l];
        a1 = (a1*a9);
        a10 = 0.25;
        a11 = 0.6666666666666666;
        a11 = (a11*a2);
        a2 = (a3*a11);
        a12 = (a7*a5);
        a2 = (a2+a12);
        a12 = (2.*a9);
        a13 = (a1*a12);
        a2 = (a2+a13);
        a10 = (a10*a2);
        a2 = (a1*a10);
        a6 = (a6-a2);
        a6 = (a6-a12);
        a0 = (a0+a6);
        out0[0 + l] = a0;
        a0 = in2[8 + l];
        a8 = (a1*a8);
        a8 = (a8-a5);
        a5 = (a7*a10);
        a8 = (a8-a5);
        a5 = (a3*a9);
        a8 = (a8-a5);
        a0 = (a0+a8);
        out0[8 + l] = a0;
        a0 = in2[16 + l];
        a7 = (a7*a9);
        a1 = (a1*a4);
        a11 = (a11+a1);
        a3 = (a3*a10);
        a11 = (a11+a3);
        a7 = (a7-a11);
        a0 = (a0+a7);
        out0[16 + l] = a0;
        (void)a0, (void)a1, (void)a2, (void)a3, (void)a4, (void)a5, (void)a6, (void)a7, (void)a8, (void)a9, (void)a10, (void)a11, (void)a12, (void)a13;
    }
}

/* margin(z, h) -> (m), 8 lanes: x[i * 8 + lane] */
static void hpgen_lane_margin(const double* restrict in0, const double* restrict in1, double* restrict out0) {
    int l;
    (void)in0; (void)in1;
    for (l = 0; l < 8; ++l) {
        double a0, a1, a2, a3, a4;
        a0 = 1.0;
        a1 = 4.0;
        a2 = in1[0 + l];
        a3 = in0[0 + l];
        a3 = (a2*a3);
        a3 = (a3*a3);
        a4 = in0[8 + l];
        a4 = (a2*a4);
        a4 = (a4*a4);
        a3 = (a3+a4);
        a4 = in0[16 + l];
        a2 = (a2*a4);
        a2 = (a2*a2);
        a3 = (a3+a2);
        a1 = (a1-a3);
        a0 = ((a0<a1 || a1!=a1) ? a0 : a1);
        a0 = ((a0<a1 || a1!=a1) ? a0 : a1);
        a0 = ((a0<a1 || a1!=a1) ? a0 : a1);
        a0 = ((a0<a1 || a1!=a1) ? a0 : a1);
        out0[0 + l] = a0;
        (void)a0, (void)a1, (void)a2, (void)a3, (void)a4;
    }
}

/* update(z, g, p, h) -> (g1, p1), 8 lanes: x[i * 8 + lane] */
static void hpgen_lane_update(const double* restrict in0, const double* restrict in1, const double* restrict in2, const double* restrict in3, double* restrict out0, double* restrict out1) {
    int l;
    (void)in0; (void)in1; (void)in2; (void)in3;
    for (l = 0; l < 8; ++l) {
        double a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11;
        double a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
        double a24;
        a0 = in1[0 + l];
        a1 = 1.0;
        a2 = 4.0;
        a3 = in3[0 + l];
        a4 = in0[0 + l];
        a5 = (a3*a4);
        a6 = (a5*a5);
        a7 = in0[8 + l];
        a8 = (a3*a7);
        a9 = (a8*a8);
        a10 = (a6+a9);
        a11 = in0[16 + l];
        a3 = (a3*a11);
        a12 = (a3*a3);
        a10 = (a10+a12);
        a10 = (a2+a10);
        a2 = (a2/a10);
        a10 = (a12+a9);
        a13 = 2.0;
        a10 = (a10/a13);
        a10 = (a2*a10);
        a10 = (a1-a10);
        a14 = (a0*a10);
        a15 = in1[24 + l];
        a16 = (a5*a8);
        a16 = (a16/a13);
        a16 = (a3+a16);
        a16 = (a2*a16);
        a17 = (a15*a16);
        a14 = (a14+a17);
        a17 = in1[48 + l];
        a18 = (a5*a3);
        a18 = (a18/a13);
        a18 = (a18-a8);
        a18 = (a2*a18);
        a19 = (a17*a18);
        a14 = (a14+a19);
        out0[0 + l] = a14;
        a14 = in1[8 + l];
        a19 = (a14*a10);
        a20 = in1[32 + l];
        a21 = (a20*a16);
        a19 = (a19+a21);
        a21 = in1[56 + l];
        a22 = (a21*a18);
        a19 = (a19+a22);
        out0[8 + l] = a19;
        a19 = in1[16 + l];
        a10 = (a19*a10);
        a22 = in1[40 + l];
        a16 = (a22*a16);
        a10 = (a10+a16);
        a16 = in1[64 + l];
        a18 = (a16*a18);
        a10 = (a10+a18);
        out0[16 + l] = a10;
        a10 = (a8*a5);
        a10 = (a10/a13);
        a10 = (a10-a3);
        a10 = (a2*a10);
        a18 = (a0*a10);
        a12 = (a12+a6);
        a12 = (a12/a13);
        a12 = (a2*a12);
        a12 = (a1-a12);
        a23 = (a15*a12);
        a18 = (a18+a23);
        a23 = (a8*a3);
        a23 = (a23/a13);
        a23 = (a5+a23);
        a23 = (a2*a23);
        a24 = (a17*a23);
        a18 = (a18+a24);
        out0[24 + l] = a18;
        a18 = (a14*a10);
        a24 = (a20*a12);
        a18 = (a18+a24);
        a24 = (a21*a23);
        a18 = (a18+a24);
        out0[32 + l] = a18;
        a10 = (a19*a10);
        a12 = (a22*a12);
        a10 = (a10+a12);
        a23 = (a16*a23);
        a10 = (a10+a23);
        out0[40 + l] = a10;
        a10 = (a3*a5);
        a10 = (a10/a13);
        a10 = (a8+a10);
        a10 = (a2*a10);
        a0 = (a0*a10);
        a23 = (a3*a8);
        a23 = (a23/a13);
        a23 = (a23-a5);
        a23 = (a2*a23);
        a15 = (a15*a23);
        a0 = (a0+a15);
        a9 = (a9+a6);
        a9 = (a9/a13);
        a2 = (a2*a9);
        a1 = (a1-a2);
        a17 = (a17*a1);
        a0 = (a0+a17);
        out0[48 + l] = a0;
        a14 = (a14*a10);
        a20 = (a20*a23);
        a14 = (a14+a20);
        a21 = (a21*a1);
        a14 = (a14+a21);
        out0[56 + l] = a14;
        a19 = (a19*a10);
        a22 = (a22*a23);
        a19 = (a19+a22);
        a16 = (a16*a1);
        a19 = (a19+a16);
        out0[64 + l] = a19;
        a19 = 0.5;
        a19 = (a19*a7);
        a16 = (a3*a19);
        a1 = 0.3333333333333333;
        a1 = (a1*a11);
        a22 = (a8*a1);
        a16 = (a16-a22);
        a22 = 0.25;
        a23 = 0.6666666666666666;
        a23 = (a23*a11);
        a11 = (a3*a23);
        a10 = (a8*a7);
        a11 = (a11+a10);
        a10 = (2.*a4);
        a14 = (a5*a10);
        a11 = (a11+a14);
        a22 = (a22*a11);
        a11 = (a5*a22);
        a16 = (a16+a11);
        a16 = (a16+a10);
        out1[0 + l] = a16;
        a1 = (a5*a1);
        a1 = (a1+a7);
        a7 = (a8*a22);
        a1 = (a1+a7);
        a7 = (a3*a4);
        a1 = (a1-a7);
        out1[8 + l] = a1;
        a5 = (a5*a19);
        a23 = (a23-a5);
        a3 = (a3*a22);
        a23 = (a23+a3);
        a8 = (a8*a4);
        a23 = (a23+a8);
        out1[16 + l] = a23;
        (void)a0, (void)a1, (void)a2, (void)a3, (void)a4, (void)a5, (void)a6, (void)a7, (void)a8, (void)a9, (void)a10, (void)a11, (void)a12, (void)a13, (void)a14, (void)a15, (void)a16, (void)a17, (void)a18, (void)a19, (void)a20, (void)a21, (void)a22, (void)a23, (void)a24;
    }
}

HPGEN_LANES_END

#include "hpgen_runtime.c"
