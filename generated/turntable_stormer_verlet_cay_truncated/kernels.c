/*
 * hpgen generated module turntable_stormer_verlet_cay_truncated -- do not edit, regenerate with hpgen
 * model: turntable
 * options: tableau=stormer-verlet, tau=cay, rkmk=truncated
 * hpgen version: 0.1.0
 * content hash (normalized model + options): ace86d66f6af117c072f373783f17d2341e5676df083791d5d67c5ad6f67f369
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
CASADI_SYMBOL_EXPORT void hpgen_turntable_stormer_verlet_cay_truncated__casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int hpgen_turntable_stormer_verlet_cay_truncated__casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int hpgen_turntable_stormer_verlet_cay_truncated__casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {6, 1, 1};
static const casadi_int casadi_s1[3] = {9, 1, 1};
static const casadi_int casadi_s2[3] = {3, 1, 1};
static const casadi_int casadi_s3[3] = {1, 1, 1};
static const casadi_int casadi_s4[3] = {36, 1, 1};
static const casadi_int casadi_s5[3] = {16, 1, 1};

/* residual:(z[6],g[9],p[3],h)->(F[6]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  a00=arg[0]? arg[0][0] : 0;
  a01=5.0000000000000000e-01;
  a02=arg[1]? arg[1][2] : 0;
  a03=(a01*a02);
  a03=(a00+a03);
  a03=(2.*a03);
  a04=arg[3]? arg[3][0] : 0;
  a05=(a01*a04);
  a03=(a03*a05);
  a06=4.;
  a00=(a01*a00);
  a07=arg[0]? arg[0][3] : 0;
  a08=(a01*a07);
  a00=(a00+a08);
  a00=(a04*a00);
  a08=casadi_sq(a00);
  a09=arg[0]? arg[0][1] : 0;
  a10=(a01*a09);
  a11=arg[0]? arg[0][4] : 0;
  a12=(a01*a11);
  a10=(a10+a12);
  a10=(a04*a10);
  a12=casadi_sq(a10);
  a13=(a08+a12);
  a14=arg[0]? arg[0][2] : 0;
  a15=(a01*a14);
  a16=arg[0]? arg[0][5] : 0;
  a17=(a01*a16);
  a15=(a15+a17);
  a15=(a04*a15);
  a17=casadi_sq(a15);
  a13=(a13+a17);
  a13=(a06+a13);
  a06=(a06/a13);
  a13=arg[2]? arg[2][0] : 0;
  a18=2.;
  a19=(a00/a18);
  a19=(a06*a19);
  a20=1.;
  a21=(a17+a12);
  a21=(a21/a18);
  a21=(a06*a21);
  a21=(a20-a21);
  a21=(a02*a21);
  a22=arg[1]? arg[1][5] : 0;
  a23=(a00*a10);
  a23=(a23/a18);
  a23=(a15+a23);
  a23=(a06*a23);
  a23=(a22*a23);
  a21=(a21+a23);
  a23=arg[1]? arg[1][8] : 0;
  a24=(a00*a15);
  a24=(a24/a18);
  a24=(a24-a10);
  a24=(a06*a24);
  a24=(a23*a24);
  a21=(a21+a24);
  a24=-7.4999999999999997e-02;
  a24=(a24*a04);
  a25=(a15*a00);
  a25=(a25/a18);
  a25=(a10+a25);
  a25=(a06*a25);
  a25=(a02*a25);
  a26=(a15*a10);
  a26=(a26/a18);
  a26=(a26-a00);
  a26=(a06*a26);
  a26=(a22*a26);
  a25=(a25+a26);
  a12=(a12+a08);
  a12=(a12/a18);
  a12=(a06*a12);
  a12=(a20-a12);
  a12=(a23*a12);
  a25=(a25+a12);
  a12=(a01*a25);
  a16=(a16+a12);
  a16=(2.*a16);
  a12=1.6666666666666666e-01;
  a12=(a12*a04);
  a16=(a16*a12);
  a26=(a01*a16);
  a26=(a24+a26);
  a27=(a21*a26);
  a28=-4.4999999999999998e-02;
  a28=(a28*a04);
  a29=(a01*a21);
  a07=(a07+a29);
  a07=(2.*a07);
  a07=(a07*a05);
  a29=(a01*a07);
  a29=(a28+a29);
  a30=(a25*a29);
  a27=(a27-a30);
  a27=(a27/a04);
  a30=(a19*a27);
  a31=(a10/a18);
  a31=(a06*a31);
  a32=2.9999999999999999e-02;
  a32=(a32*a04);
  a33=(a10*a00);
  a33=(a33/a18);
  a33=(a33-a15);
  a33=(a06*a33);
  a33=(a02*a33);
  a17=(a17+a08);
  a17=(a17/a18);
  a17=(a06*a17);
  a20=(a20-a17);
  a20=(a22*a20);
  a33=(a33+a20);
  a20=(a10*a15);
  a20=(a20/a18);
  a20=(a00+a20);
  a20=(a06*a20);
  a20=(a23*a20);
  a33=(a33+a20);
  a20=(a01*a33);
  a11=(a11+a20);
  a11=(2.*a11);
  a20=2.5000000000000000e-01;
  a17=(a20*a04);
  a11=(a11*a17);
  a08=(a01*a11);
  a08=(a32+a08);
  a25=(a25*a08);
  a26=(a33*a26);
  a25=(a25-a26);
  a25=(a25/a04);
  a26=(a31*a25);
  a30=(a30-a26);
  a33=(a33*a29);
  a21=(a21*a08);
  a33=(a33-a21);
  a33=(a33/a04);
  a21=(a06*a33);
  a30=(a30+a21);
  a30=(a04*a30);
  a21=(a01*a30);
  a08=(a10*a21);
  a18=(a15/a18);
  a18=(a06*a18);
  a29=(a18*a25);
  a26=(a06*a27);
  a29=(a29+a26);
  a26=(a19*a33);
  a29=(a29-a26);
  a29=(a04*a29);
  a26=(a01*a29);
  a34=(a15*a26);
  a08=(a08-a34);
  a34=(a15*a30);
  a35=(a10*a29);
  a34=(a34+a35);
  a25=(a06*a25);
  a27=(a18*a27);
  a25=(a25-a27);
  a33=(a31*a33);
  a25=(a25+a33);
  a25=(a04*a25);
  a33=(a00*a25);
  a34=(a34+a33);
  a20=(a20*a34);
  a34=(a00*a20);
  a08=(a08+a34);
  a08=(a08+a25);
  a34=(a01*a22);
  a09=(a09+a34);
  a09=(2.*a09);
  a09=(a09*a17);
  a17=(a01*a09);
  a32=(a32+a17);
  a17=(a23*a32);
  a34=(a01*a23);
  a14=(a14+a34);
  a14=(2.*a14);
  a14=(a14*a12);
  a12=(a01*a14);
  a24=(a24+a12);
  a12=(a22*a24);
  a17=(a17-a12);
  a08=(a08+a17);
  a13=(a13+a08);
  a08=(a06*a13);
  a17=arg[2]? arg[2][1] : 0;
  a21=(a00*a21);
  a21=(a29-a21);
  a12=(a10*a20);
  a21=(a21+a12);
  a12=(a01*a25);
  a34=(a15*a12);
  a21=(a21+a34);
  a24=(a02*a24);
  a34=(a01*a03);
  a28=(a28+a34);
  a23=(a23*a28);
  a24=(a24-a23);
  a21=(a21+a24);
  a17=(a17+a21);
  a21=(a18*a17);
  a08=(a08+a21);
  a21=arg[2]? arg[2][2] : 0;
  a00=(a00*a26);
  a00=(a30+a00);
  a15=(a15*a20);
  a00=(a00+a15);
  a10=(a10*a12);
  a00=(a00-a10);
  a22=(a22*a28);
  a02=(a02*a32);
  a22=(a22-a02);
  a00=(a00+a22);
  a21=(a21+a00);
  a00=(a31*a21);
  a08=(a08-a00);
  a08=(a04*a08);
  a08=(a01*a08);
  a25=(a04*a25);
  a25=(a01*a25);
  a08=(a08-a25);
  a03=(a03-a08);
  a03=(a03/a05);
  if (res[0]!=0) res[0][0]=a03;
  a03=(a06*a17);
  a18=(a18*a13);
  a03=(a03-a18);
  a18=(a19*a21);
  a03=(a03+a18);
  a03=(a04*a03);
  a03=(a01*a03);
  a29=(a04*a29);
  a29=(a01*a29);
  a03=(a03-a29);
  a09=(a09-a03);
  a09=(a09/a05);
  if (res[0]!=0) res[0][1]=a09;
  a31=(a31*a13);
  a19=(a19*a17);
  a31=(a31-a19);
  a06=(a06*a21);
  a31=(a31+a06);
  a31=(a04*a31);
  a31=(a01*a31);
  a04=(a04*a30);
  a01=(a01*a04);
  a31=(a31-a01);
  a14=(a14-a31);
  a14=(a14/a05);
  if (res[0]!=0) res[0][2]=a14;
  a07=(a07-a08);
  a07=(a07/a05);
  if (res[0]!=0) res[0][3]=a07;
  a11=(a11-a03);
  a11=(a11/a05);
  if (res[0]!=0) res[0][4]=a11;
  a16=(a16-a31);
  a16=(a16/a05);
  if (res[0]!=0) res[0][5]=a16;
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

/* residual_jacobian:(z[6],g[9],p[3],h)->(F[6],J[36]) */
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
  casadi_real a108, a109, a110, a111;
  a000=arg[0]? arg[0][0] : 0;
  a001=5.0000000000000000e-01;
  a002=arg[1]? arg[1][2] : 0;
  a003=(a001*a002);
  a003=(a000+a003);
  a003=(2.*a003);
  a004=arg[3]? arg[3][0] : 0;
  a005=(a001*a004);
  a003=(a003*a005);
  a006=4.;
  a000=(a001*a000);
  a007=arg[0]? arg[0][3] : 0;
  a008=(a001*a007);
  a000=(a000+a008);
  a000=(a004*a000);
  a008=casadi_sq(a000);
  a009=arg[0]? arg[0][1] : 0;
  a010=(a001*a009);
  a011=arg[0]? arg[0][4] : 0;
  a012=(a001*a011);
  a010=(a010+a012);
  a010=(a004*a010);
  a012=casadi_sq(a010);
  a013=(a008+a012);
  a014=arg[0]? arg[0][2] : 0;
  a015=(a001*a014);
  a016=arg[0]? arg[0][5] : 0;
  a017=(a001*a016);
  a015=(a015+a017);
  a015=(a004*a015);
  a017=casadi_sq(a015);
  a013=(a013+a017);
  a013=(a006+a013);
  a006=(a006/a013);
  a018=arg[2]? arg[2][0] : 0;
  a019=2.;
  a020=(a000/a019);
  a021=(a006*a020);
  a022=1.;
  a023=(a017+a012);
  a023=(a023/a019);
  a024=(a006*a023);
  a024=(a022-a024);
  a024=(a002*a024);
  a025=arg[1]? arg[1][5] : 0;
  a026=(a000*a010);
  a026=(a026/a019);
  a026=(a015+a026);
  a027=(a006*a026);
  a027=(a025*a027);
  a024=(a024+a027);
  a027=arg[1]? arg[1][8] : 0;
  a028=(a000*a015);
  a028=(a028/a019);
  a028=(a028-a010);
  a029=(a006*a028);
  a029=(a027*a029);
  a024=(a024+a029);
  a029=-7.4999999999999997e-02;
  a029=(a029*a004);
  a030=(a015*a000);
  a030=(a030/a019);
  a030=(a010+a030);
  a031=(a006*a030);
  a031=(a002*a031);
  a032=(a015*a010);
  a032=(a032/a019);
  a032=(a032-a000);
  a033=(a006*a032);
  a033=(a025*a033);
  a031=(a031+a033);
  a012=(a012+a008);
  a012=(a012/a019);
  a033=(a006*a012);
  a033=(a022-a033);
  a033=(a027*a033);
  a031=(a031+a033);
  a033=(a001*a031);
  a016=(a016+a033);
  a016=(2.*a016);
  a033=1.6666666666666666e-01;
  a033=(a033*a004);
  a016=(a016*a033);
  a034=(a001*a016);
  a034=(a029+a034);
  a035=(a024*a034);
  a036=-4.4999999999999998e-02;
  a036=(a036*a004);
  a037=(a001*a024);
  a007=(a007+a037);
  a007=(2.*a007);
  a007=(a007*a005);
  a037=(a001*a007);
  a037=(a036+a037);
  a038=(a031*a037);
  a035=(a035-a038);
  a035=(a035/a004);
  a038=(a021*a035);
  a039=(a010/a019);
  a040=(a006*a039);
  a041=2.9999999999999999e-02;
  a041=(a041*a004);
  a042=(a010*a000);
  a042=(a042/a019);
  a042=(a042-a015);
  a043=(a006*a042);
  a043=(a002*a043);
  a017=(a017+a008);
  a017=(a017/a019);
  a008=(a006*a017);
  a008=(a022-a008);
  a008=(a025*a008);
  a043=(a043+a008);
  a008=(a010*a015);
  a008=(a008/a019);
  a008=(a000+a008);
  a044=(a006*a008);
  a044=(a027*a044);
  a043=(a043+a044);
  a044=(a001*a043);
  a011=(a011+a044);
  a011=(2.*a011);
  a044=2.5000000000000000e-01;
  a045=(a044*a004);
  a011=(a011*a045);
  a046=(a001*a011);
  a046=(a041+a046);
  a047=(a031*a046);
  a048=(a043*a034);
  a047=(a047-a048);
  a047=(a047/a004);
  a048=(a040*a047);
  a038=(a038-a048);
  a048=(a043*a037);
  a049=(a024*a046);
  a048=(a048-a049);
  a048=(a048/a004);
  a049=(a006*a048);
  a038=(a038+a049);
  a038=(a004*a038);
  a049=(a001*a038);
  a050=(a010*a049);
  a019=(a015/a019);
  a051=(a006*a019);
  a052=(a051*a047);
  a053=(a006*a035);
  a052=(a052+a053);
  a053=(a021*a048);
  a052=(a052-a053);
  a052=(a004*a052);
  a053=(a001*a052);
  a054=(a015*a053);
  a050=(a050-a054);
  a054=(a015*a038);
  a055=(a010*a052);
  a054=(a054+a055);
  a055=(a006*a047);
  a056=(a051*a035);
  a055=(a055-a056);
  a056=(a040*a048);
  a055=(a055+a056);
  a055=(a004*a055);
  a056=(a000*a055);
  a054=(a054+a056);
  a054=(a044*a054);
  a056=(a000*a054);
  a050=(a050+a056);
  a050=(a050+a055);
  a056=(a001*a025);
  a009=(a009+a056);
  a009=(2.*a009);
  a009=(a009*a045);
  a056=(a001*a009);
  a041=(a041+a056);
  a056=(a027*a041);
  a057=(a001*a027);
  a014=(a014+a057);
  a014=(2.*a014);
  a014=(a014*a033);
  a057=(a001*a014);
  a029=(a029+a057);
  a057=(a025*a029);
  a056=(a056-a057);
  a050=(a050+a056);
  a018=(a018+a050);
  a050=(a006*a018);
  a056=arg[2]? arg[2][1] : 0;
  a057=(a000*a049);
  a057=(a052-a057);
  a058=(a010*a054);
  a057=(a057+a058);
  a058=(a001*a055);
  a059=(a015*a058);
  a057=(a057+a059);
  a029=(a002*a029);
  a059=(a001*a003);
  a036=(a036+a059);
  a059=(a027*a036);
  a029=(a029-a059);
  a057=(a057+a029);
  a056=(a056+a057);
  a057=(a051*a056);
  a050=(a050+a057);
  a057=arg[2]? arg[2][2] : 0;
  a029=(a000*a053);
  a029=(a038+a029);
  a059=(a015*a054);
  a029=(a029+a059);
  a059=(a010*a058);
  a029=(a029-a059);
  a036=(a025*a036);
  a041=(a002*a041);
  a036=(a036-a041);
  a029=(a029+a036);
  a057=(a057+a029);
  a029=(a040*a057);
  a050=(a050-a029);
  a050=(a004*a050);
  a050=(a001*a050);
  a029=(a004*a055);
  a029=(a001*a029);
  a050=(a050-a029);
  a003=(a003-a050);
  a003=(a003/a005);
  if (res[0]!=0) res[0][0]=a003;
  a003=(a006*a056);
  a029=(a051*a018);
  a003=(a003-a029);
  a029=(a021*a057);
  a003=(a003+a029);
  a003=(a004*a003);
  a003=(a001*a003);
  a029=(a004*a052);
  a029=(a001*a029);
  a003=(a003-a029);
  a009=(a009-a003);
  a009=(a009/a005);
  if (res[0]!=0) res[0][1]=a009;
  a009=(a040*a018);
  a029=(a021*a056);
  a009=(a009-a029);
  a029=(a006*a057);
  a009=(a009+a029);
  a009=(a004*a009);
  a009=(a001*a009);
  a029=(a004*a038);
  a029=(a001*a029);
  a009=(a009-a029);
  a014=(a014-a009);
  a014=(a014/a005);
  if (res[0]!=0) res[0][2]=a014;
  a007=(a007-a050);
  a007=(a007/a005);
  if (res[0]!=0) res[0][3]=a007;
  a011=(a011-a003);
  a011=(a011/a005);
  if (res[0]!=0) res[0][4]=a011;
  a016=(a016-a009);
  a016=(a016/a005);
  if (res[0]!=0) res[0][5]=a016;
  a016=(a006*a045);
  a013=(a006/a013);
  a009=(2.*a000);
  a009=(a009*a005);
  a011=(a013*a009);
  a003=(a020*a011);
  a003=(a016-a003);
  a007=(a035*a003);
  a050=(a023*a011);
  a050=(a002*a050);
  a014=(a010*a005);
  a014=(a001*a014);
  a014=(a006*a014);
  a029=(a026*a011);
  a029=(a014-a029);
  a029=(a025*a029);
  a050=(a050+a029);
  a029=(a015*a005);
  a029=(a001*a029);
  a029=(a006*a029);
  a036=(a028*a011);
  a036=(a029-a036);
  a036=(a027*a036);
  a050=(a050+a036);
  a036=(a034*a050);
  a041=(a030*a011);
  a041=(a029-a041);
  a041=(a002*a041);
  a059=(a032*a011);
  a060=(a006*a005);
  a059=(a059+a060);
  a059=(a025*a059);
  a041=(a041-a059);
  a009=(a001*a009);
  a009=(a006*a009);
  a059=(a012*a011);
  a059=(a009-a059);
  a059=(a027*a059);
  a041=(a041-a059);
  a059=(a033*a041);
  a061=(a001*a059);
  a062=(a024*a061);
  a036=(a036+a062);
  a062=(a037*a041);
  a063=(a005*a050);
  a064=(a001*a063);
  a065=(a031*a064);
  a065=(a062+a065);
  a065=(a036-a065);
  a065=(a065/a004);
  a066=(a021*a065);
  a066=(a007+a066);
  a041=(a046*a041);
  a067=(a042*a011);
  a067=(a014-a067);
  a067=(a002*a067);
  a068=(a017*a011);
  a009=(a009-a068);
  a009=(a025*a009);
  a067=(a067-a009);
  a009=(a008*a011);
  a009=(a060-a009);
  a009=(a027*a009);
  a067=(a067+a009);
  a009=(a045*a067);
  a068=(a001*a009);
  a069=(a031*a068);
  a041=(a041+a069);
  a069=(a034*a067);
  a061=(a043*a061);
  a069=(a069+a061);
  a041=(a041-a069);
  a041=(a041/a004);
  a069=(a040*a041);
  a061=(a039*a011);
  a070=(a047*a061);
  a069=(a069-a070);
  a066=(a066-a069);
  a067=(a037*a067);
  a064=(a043*a064);
  a064=(a067+a064);
  a070=(a046*a050);
  a068=(a024*a068);
  a070=(a070+a068);
  a064=(a064-a070);
  a064=(a064/a004);
  a068=(a006*a064);
  a071=(a048*a011);
  a068=(a068-a071);
  a066=(a066+a068);
  a066=(a004*a066);
  a068=(a001*a066);
  a072=(a010*a068);
  a073=(a051*a041);
  a074=(a019*a011);
  a075=(a047*a074);
  a073=(a073-a075);
  a075=(a006*a065);
  a076=(a035*a011);
  a075=(a075-a076);
  a075=(a073+a075);
  a077=(a048*a003);
  a078=(a021*a064);
  a078=(a077+a078);
  a075=(a075-a078);
  a075=(a004*a075);
  a078=(a001*a075);
  a079=(a015*a078);
  a072=(a072-a079);
  a054=(a054*a005);
  a079=(a015*a066);
  a080=(a010*a075);
  a079=(a079+a080);
  a055=(a055*a005);
  a041=(a006*a041);
  a080=(a047*a011);
  a041=(a041-a080);
  a065=(a051*a065);
  a080=(a035*a074);
  a065=(a065-a080);
  a065=(a041-a065);
  a064=(a040*a064);
  a081=(a048*a061);
  a064=(a064-a081);
  a065=(a065+a064);
  a065=(a004*a065);
  a064=(a000*a065);
  a064=(a055+a064);
  a079=(a079+a064);
  a079=(a044*a079);
  a064=(a000*a079);
  a064=(a054+a064);
  a072=(a072+a064);
  a072=(a072+a065);
  a064=(a006*a072);
  a082=(a018*a011);
  a064=(a064-a082);
  a049=(a049*a005);
  a068=(a000*a068);
  a068=(a049+a068);
  a068=(a075-a068);
  a083=(a010*a079);
  a068=(a068+a083);
  a083=(a001*a065);
  a084=(a015*a083);
  a068=(a068+a084);
  a084=(a027*a005);
  a068=(a068-a084);
  a084=(a051*a068);
  a085=(a056*a074);
  a084=(a084-a085);
  a064=(a064+a084);
  a053=(a053*a005);
  a078=(a000*a078);
  a078=(a053+a078);
  a078=(a066+a078);
  a079=(a015*a079);
  a078=(a078+a079);
  a083=(a010*a083);
  a078=(a078-a083);
  a083=(a025*a005);
  a078=(a078+a083);
  a083=(a040*a078);
  a079=(a057*a061);
  a083=(a083-a079);
  a064=(a064-a083);
  a064=(a004*a064);
  a064=(a001*a064);
  a065=(a004*a065);
  a065=(a001*a065);
  a064=(a064-a065);
  a065=(a004-a064);
  a065=(a065/a005);
  if (res[1]!=0) res[1][0]=a065;
  a065=(a006*a068);
  a083=(a056*a011);
  a065=(a065-a083);
  a084=(a051*a072);
  a074=(a018*a074);
  a084=(a084-a074);
  a065=(a065-a084);
  a084=(a057*a003);
  a086=(a021*a078);
  a086=(a084+a086);
  a065=(a065+a086);
  a065=(a004*a065);
  a065=(a001*a065);
  a075=(a004*a075);
  a075=(a001*a075);
  a065=(a065-a075);
  a075=(a065/a005);
  a075=(-a075);
  if (res[1]!=0) res[1][1]=a075;
  a072=(a040*a072);
  a061=(a018*a061);
  a072=(a072-a061);
  a003=(a056*a003);
  a068=(a021*a068);
  a068=(a003+a068);
  a072=(a072-a068);
  a078=(a006*a078);
  a011=(a057*a011);
  a078=(a078-a011);
  a072=(a072+a078);
  a072=(a004*a072);
  a072=(a001*a072);
  a066=(a004*a066);
  a066=(a001*a066);
  a072=(a072-a066);
  a066=(a072/a005);
  a066=(-a066);
  if (res[1]!=0) res[1][2]=a066;
  a063=(a063-a064);
  a063=(a063/a005);
  if (res[1]!=0) res[1][3]=a063;
  a065=(a009-a065);
  a065=(a065/a005);
  if (res[1]!=0) res[1][4]=a065;
  a072=(a059-a072);
  a072=(a072/a005);
  if (res[1]!=0) res[1][5]=a072;
  a072=(a000*a005);
  a072=(a001*a072);
  a072=(a006*a072);
  a065=(2.*a010);
  a065=(a065*a005);
  a063=(a013*a065);
  a064=(a026*a063);
  a064=(a072-a064);
  a064=(a025*a064);
  a065=(a001*a065);
  a065=(a006*a065);
  a066=(a023*a063);
  a066=(a065-a066);
  a066=(a002*a066);
  a064=(a064-a066);
  a066=(a028*a063);
  a066=(a066+a060);
  a066=(a027*a066);
  a064=(a064-a066);
  a066=(a034*a064);
  a078=(a030*a063);
  a078=(a060-a078);
  a078=(a002*a078);
  a068=(a032*a063);
  a068=(a029-a068);
  a068=(a025*a068);
  a078=(a078+a068);
  a068=(a012*a063);
  a065=(a065-a068);
  a065=(a027*a065);
  a078=(a078-a065);
  a065=(a033*a078);
  a068=(a001*a065);
  a075=(a024*a068);
  a066=(a066+a075);
  a075=(a037*a078);
  a086=(a005*a064);
  a087=(a001*a086);
  a088=(a031*a087);
  a075=(a075+a088);
  a066=(a066-a075);
  a066=(a066/a004);
  a075=(a021*a066);
  a088=(a020*a063);
  a089=(a035*a088);
  a075=(a075-a089);
  a089=(a039*a063);
  a089=(a016-a089);
  a090=(a047*a089);
  a078=(a046*a078);
  a091=(a042*a063);
  a091=(a072-a091);
  a091=(a002*a091);
  a092=(a017*a063);
  a092=(a025*a092);
  a091=(a091+a092);
  a092=(a008*a063);
  a029=(a029-a092);
  a029=(a027*a029);
  a091=(a091+a029);
  a029=(a045*a091);
  a092=(a001*a029);
  a093=(a031*a092);
  a093=(a078+a093);
  a094=(a034*a091);
  a068=(a043*a068);
  a094=(a094+a068);
  a093=(a093-a094);
  a093=(a093/a004);
  a068=(a040*a093);
  a068=(a090+a068);
  a068=(a075-a068);
  a095=(a037*a091);
  a087=(a043*a087);
  a095=(a095+a087);
  a064=(a046*a064);
  a092=(a024*a092);
  a092=(a064+a092);
  a092=(a095-a092);
  a092=(a092/a004);
  a087=(a006*a092);
  a096=(a048*a063);
  a087=(a087-a096);
  a068=(a068+a087);
  a068=(a004*a068);
  a087=(a001*a068);
  a097=(a010*a087);
  a097=(a049+a097);
  a098=(a051*a093);
  a099=(a019*a063);
  a100=(a047*a099);
  a098=(a098-a100);
  a101=(a006*a066);
  a102=(a035*a063);
  a101=(a101-a102);
  a098=(a098+a101);
  a102=(a021*a092);
  a103=(a048*a088);
  a102=(a102-a103);
  a098=(a098-a102);
  a098=(a004*a098);
  a102=(a001*a098);
  a104=(a015*a102);
  a097=(a097-a104);
  a104=(a015*a068);
  a052=(a052*a005);
  a105=(a010*a098);
  a105=(a052+a105);
  a104=(a104+a105);
  a093=(a006*a093);
  a105=(a047*a063);
  a093=(a093-a105);
  a066=(a051*a066);
  a106=(a035*a099);
  a066=(a066-a106);
  a093=(a093-a066);
  a106=(a048*a089);
  a092=(a040*a092);
  a092=(a106+a092);
  a093=(a093+a092);
  a093=(a004*a093);
  a092=(a000*a093);
  a104=(a104+a092);
  a104=(a044*a104);
  a092=(a000*a104);
  a097=(a097+a092);
  a097=(a097+a093);
  a092=(a027*a045);
  a097=(a097+a092);
  a092=(a006*a097);
  a107=(a018*a063);
  a092=(a092-a107);
  a087=(a000*a087);
  a087=(a098-a087);
  a108=(a010*a104);
  a108=(a054+a108);
  a087=(a087+a108);
  a108=(a001*a093);
  a109=(a015*a108);
  a087=(a087+a109);
  a109=(a051*a087);
  a110=(a056*a099);
  a109=(a109-a110);
  a092=(a092+a109);
  a109=(a057*a089);
  a102=(a000*a102);
  a102=(a068+a102);
  a104=(a015*a104);
  a102=(a102+a104);
  a058=(a058*a005);
  a108=(a010*a108);
  a108=(a058+a108);
  a102=(a102-a108);
  a108=(a002*a045);
  a102=(a102-a108);
  a108=(a040*a102);
  a108=(a109+a108);
  a092=(a092-a108);
  a092=(a004*a092);
  a092=(a001*a092);
  a093=(a004*a093);
  a093=(a001*a093);
  a092=(a092-a093);
  a093=(a092/a005);
  a093=(-a093);
  if (res[1]!=0) res[1][6]=a093;
  a093=(a006*a087);
  a108=(a056*a063);
  a093=(a093-a108);
  a104=(a051*a097);
  a099=(a018*a099);
  a104=(a104-a099);
  a093=(a093-a104);
  a104=(a021*a102);
  a111=(a057*a088);
  a104=(a104-a111);
  a093=(a093+a104);
  a093=(a004*a093);
  a093=(a001*a093);
  a098=(a004*a098);
  a098=(a001*a098);
  a093=(a093-a098);
  a098=(a005-a093);
  a098=(a098/a005);
  if (res[1]!=0) res[1][7]=a098;
  a089=(a018*a089);
  a097=(a040*a097);
  a097=(a089+a097);
  a087=(a021*a087);
  a088=(a056*a088);
  a087=(a087-a088);
  a097=(a097-a087);
  a102=(a006*a102);
  a063=(a057*a063);
  a102=(a102-a063);
  a097=(a097+a102);
  a097=(a004*a097);
  a097=(a001*a097);
  a068=(a004*a068);
  a068=(a001*a068);
  a097=(a097-a068);
  a068=(a097/a005);
  a068=(-a068);
  if (res[1]!=0) res[1][8]=a068;
  a092=(a086-a092);
  a092=(a092/a005);
  if (res[1]!=0) res[1][9]=a092;
  a029=(a029-a093);
  a029=(a029/a005);
  if (res[1]!=0) res[1][10]=a029;
  a097=(a065-a097);
  a097=(a097/a005);
  if (res[1]!=0) res[1][11]=a097;
  a097=(2.*a015);
  a097=(a097*a005);
  a013=(a013*a097);
  a026=(a026*a013);
  a026=(a060-a026);
  a026=(a025*a026);
  a097=(a001*a097);
  a097=(a006*a097);
  a023=(a023*a013);
  a023=(a097-a023);
  a023=(a002*a023);
  a026=(a026-a023);
  a028=(a028*a013);
  a028=(a072-a028);
  a028=(a027*a028);
  a026=(a026+a028);
  a028=(a034*a026);
  a030=(a030*a013);
  a072=(a072-a030);
  a072=(a002*a072);
  a032=(a032*a013);
  a032=(a014-a032);
  a032=(a025*a032);
  a072=(a072+a032);
  a012=(a012*a013);
  a012=(a027*a012);
  a072=(a072+a012);
  a012=(a033*a072);
  a032=(a001*a012);
  a030=(a024*a032);
  a030=(a028+a030);
  a023=(a037*a072);
  a029=(a005*a026);
  a093=(a001*a029);
  a092=(a031*a093);
  a023=(a023+a092);
  a030=(a030-a023);
  a030=(a030/a004);
  a092=(a021*a030);
  a020=(a020*a013);
  a068=(a035*a020);
  a092=(a092-a068);
  a102=(a046*a072);
  a008=(a008*a013);
  a014=(a014-a008);
  a027=(a027*a014);
  a042=(a042*a013);
  a042=(a042+a060);
  a042=(a002*a042);
  a017=(a017*a013);
  a097=(a097-a017);
  a097=(a025*a097);
  a042=(a042+a097);
  a027=(a027-a042);
  a042=(a045*a027);
  a097=(a001*a042);
  a017=(a031*a097);
  a102=(a102+a017);
  a034=(a034*a027);
  a032=(a043*a032);
  a032=(a034+a032);
  a032=(a102-a032);
  a032=(a032/a004);
  a017=(a040*a032);
  a039=(a039*a013);
  a060=(a047*a039);
  a017=(a017-a060);
  a092=(a092-a017);
  a037=(a037*a027);
  a093=(a043*a093);
  a037=(a037+a093);
  a046=(a046*a026);
  a097=(a024*a097);
  a046=(a046+a097);
  a037=(a037-a046);
  a037=(a037/a004);
  a046=(a006*a037);
  a097=(a048*a013);
  a046=(a046-a097);
  a092=(a092+a046);
  a092=(a004*a092);
  a097=(a001*a092);
  a026=(a010*a097);
  a019=(a019*a013);
  a016=(a016-a019);
  a019=(a047*a016);
  a093=(a051*a032);
  a093=(a019+a093);
  a027=(a006*a030);
  a017=(a035*a013);
  a027=(a027-a017);
  a093=(a093+a027);
  a027=(a021*a037);
  a014=(a048*a020);
  a027=(a027-a014);
  a093=(a093-a027);
  a093=(a004*a093);
  a014=(a001*a093);
  a008=(a015*a014);
  a008=(a053+a008);
  a026=(a026-a008);
  a038=(a038*a005);
  a008=(a015*a092);
  a008=(a038+a008);
  a087=(a010*a093);
  a008=(a008+a087);
  a032=(a006*a032);
  a047=(a047*a013);
  a032=(a032-a047);
  a035=(a035*a016);
  a030=(a051*a030);
  a030=(a035+a030);
  a032=(a032-a030);
  a037=(a040*a037);
  a048=(a048*a039);
  a037=(a037-a048);
  a032=(a032+a037);
  a032=(a004*a032);
  a048=(a000*a032);
  a008=(a008+a048);
  a008=(a044*a008);
  a048=(a000*a008);
  a026=(a026+a048);
  a026=(a026+a032);
  a025=(a025*a033);
  a026=(a026-a025);
  a025=(a006*a026);
  a048=(a018*a013);
  a025=(a025-a048);
  a030=(a056*a016);
  a097=(a000*a097);
  a097=(a093-a097);
  a087=(a010*a008);
  a097=(a097+a087);
  a087=(a001*a032);
  a098=(a015*a087);
  a098=(a058+a098);
  a097=(a097+a098);
  a002=(a002*a033);
  a097=(a097+a002);
  a002=(a051*a097);
  a002=(a030+a002);
  a025=(a025+a002);
  a014=(a000*a014);
  a014=(a092+a014);
  a008=(a015*a008);
  a008=(a054+a008);
  a014=(a014+a008);
  a087=(a010*a087);
  a014=(a014-a087);
  a087=(a040*a014);
  a008=(a057*a039);
  a087=(a087-a008);
  a025=(a025-a087);
  a025=(a004*a025);
  a025=(a001*a025);
  a032=(a004*a032);
  a032=(a001*a032);
  a025=(a025-a032);
  a032=(a025/a005);
  a032=(-a032);
  if (res[1]!=0) res[1][12]=a032;
  a032=(a006*a097);
  a087=(a056*a013);
  a032=(a032-a087);
  a016=(a018*a016);
  a002=(a051*a026);
  a002=(a016+a002);
  a032=(a032-a002);
  a002=(a021*a014);
  a098=(a057*a020);
  a002=(a002-a098);
  a032=(a032+a002);
  a032=(a004*a032);
  a032=(a001*a032);
  a093=(a004*a093);
  a093=(a001*a093);
  a032=(a032-a093);
  a093=(a032/a005);
  a093=(-a093);
  if (res[1]!=0) res[1][13]=a093;
  a093=3.3333333333333331e-01;
  a093=(a093*a004);
  a026=(a040*a026);
  a018=(a018*a039);
  a026=(a026-a018);
  a097=(a021*a097);
  a056=(a056*a020);
  a097=(a097-a056);
  a026=(a026-a097);
  a014=(a006*a014);
  a057=(a057*a013);
  a014=(a014-a057);
  a026=(a026+a014);
  a026=(a004*a026);
  a026=(a001*a026);
  a092=(a004*a092);
  a092=(a001*a092);
  a026=(a026-a092);
  a093=(a093-a026);
  a093=(a093/a005);
  if (res[1]!=0) res[1][14]=a093;
  a025=(a029-a025);
  a025=(a025/a005);
  if (res[1]!=0) res[1][15]=a025;
  a032=(a042-a032);
  a032=(a032/a005);
  if (res[1]!=0) res[1][16]=a032;
  a012=(a012-a026);
  a012=(a012/a005);
  if (res[1]!=0) res[1][17]=a012;
  a050=(a001*a050);
  a050=(a022+a050);
  a050=(2.*a050);
  a050=(a005*a050);
  a012=(a001*a050);
  a026=(a031*a012);
  a062=(a062+a026);
  a036=(a036-a062);
  a036=(a036/a004);
  a062=(a021*a036);
  a007=(a007+a062);
  a007=(a007-a069);
  a012=(a043*a012);
  a067=(a067+a012);
  a067=(a067-a070);
  a067=(a067/a004);
  a070=(a006*a067);
  a070=(a070-a071);
  a007=(a007+a070);
  a007=(a004*a007);
  a070=(a001*a007);
  a071=(a010*a070);
  a012=(a006*a036);
  a012=(a012-a076);
  a073=(a073+a012);
  a012=(a021*a067);
  a077=(a077+a012);
  a073=(a073-a077);
  a073=(a004*a073);
  a077=(a001*a073);
  a012=(a015*a077);
  a071=(a071-a012);
  a012=(a015*a007);
  a076=(a010*a073);
  a012=(a012+a076);
  a036=(a051*a036);
  a036=(a036-a080);
  a041=(a041-a036);
  a067=(a040*a067);
  a067=(a067-a081);
  a041=(a041+a067);
  a041=(a004*a041);
  a067=(a000*a041);
  a055=(a055+a067);
  a012=(a012+a055);
  a012=(a044*a012);
  a055=(a000*a012);
  a055=(a054+a055);
  a071=(a071+a055);
  a071=(a071+a041);
  a055=(a006*a071);
  a055=(a055-a082);
  a070=(a000*a070);
  a070=(a049+a070);
  a070=(a073-a070);
  a082=(a010*a012);
  a070=(a070+a082);
  a082=(a001*a041);
  a067=(a015*a082);
  a070=(a070+a067);
  a067=(a051*a070);
  a067=(a067-a085);
  a055=(a055+a067);
  a077=(a000*a077);
  a077=(a053+a077);
  a077=(a007+a077);
  a012=(a015*a012);
  a077=(a077+a012);
  a082=(a010*a082);
  a077=(a077-a082);
  a082=(a040*a077);
  a082=(a082-a079);
  a055=(a055-a082);
  a055=(a004*a055);
  a055=(a001*a055);
  a041=(a004*a041);
  a041=(a001*a041);
  a055=(a055-a041);
  a041=(a055/a005);
  a041=(-a041);
  if (res[1]!=0) res[1][18]=a041;
  a041=(a006*a070);
  a041=(a041-a083);
  a083=(a051*a071);
  a083=(a083-a074);
  a041=(a041-a083);
  a083=(a021*a077);
  a084=(a084+a083);
  a041=(a041+a084);
  a041=(a004*a041);
  a041=(a001*a041);
  a073=(a004*a073);
  a073=(a001*a073);
  a041=(a041-a073);
  a073=(a041/a005);
  a073=(-a073);
  if (res[1]!=0) res[1][19]=a073;
  a071=(a040*a071);
  a071=(a071-a061);
  a070=(a021*a070);
  a003=(a003+a070);
  a071=(a071-a003);
  a077=(a006*a077);
  a077=(a077-a011);
  a071=(a071+a077);
  a071=(a004*a071);
  a071=(a001*a071);
  a007=(a004*a007);
  a007=(a001*a007);
  a071=(a071-a007);
  a007=(a071/a005);
  a007=(-a007);
  if (res[1]!=0) res[1][20]=a007;
  a050=(a050-a055);
  a050=(a050/a005);
  if (res[1]!=0) res[1][21]=a050;
  a009=(a009-a041);
  a009=(a009/a005);
  if (res[1]!=0) res[1][22]=a009;
  a059=(a059-a071);
  a059=(a059/a005);
  if (res[1]!=0) res[1][23]=a059;
  a091=(a001*a091);
  a091=(a022+a091);
  a091=(2.*a091);
  a045=(a045*a091);
  a091=(a001*a045);
  a031=(a031*a091);
  a078=(a078+a031);
  a078=(a078-a094);
  a078=(a078/a004);
  a094=(a040*a078);
  a090=(a090+a094);
  a075=(a075-a090);
  a091=(a024*a091);
  a064=(a064+a091);
  a095=(a095-a064);
  a095=(a095/a004);
  a064=(a006*a095);
  a064=(a064-a096);
  a075=(a075+a064);
  a075=(a004*a075);
  a064=(a001*a075);
  a096=(a010*a064);
  a049=(a049+a096);
  a096=(a051*a078);
  a096=(a096-a100);
  a096=(a096+a101);
  a101=(a021*a095);
  a101=(a101-a103);
  a096=(a096-a101);
  a096=(a004*a096);
  a101=(a001*a096);
  a103=(a015*a101);
  a049=(a049-a103);
  a103=(a015*a075);
  a100=(a010*a096);
  a052=(a052+a100);
  a103=(a103+a052);
  a078=(a006*a078);
  a078=(a078-a105);
  a078=(a078-a066);
  a095=(a040*a095);
  a106=(a106+a095);
  a078=(a078+a106);
  a078=(a004*a078);
  a106=(a000*a078);
  a103=(a103+a106);
  a103=(a044*a103);
  a106=(a000*a103);
  a049=(a049+a106);
  a049=(a049+a078);
  a106=(a006*a049);
  a106=(a106-a107);
  a064=(a000*a064);
  a064=(a096-a064);
  a107=(a010*a103);
  a107=(a054+a107);
  a064=(a064+a107);
  a107=(a001*a078);
  a095=(a015*a107);
  a064=(a064+a095);
  a095=(a051*a064);
  a095=(a095-a110);
  a106=(a106+a095);
  a101=(a000*a101);
  a101=(a075+a101);
  a103=(a015*a103);
  a101=(a101+a103);
  a107=(a010*a107);
  a107=(a058+a107);
  a101=(a101-a107);
  a107=(a040*a101);
  a109=(a109+a107);
  a106=(a106-a109);
  a106=(a004*a106);
  a106=(a001*a106);
  a078=(a004*a078);
  a078=(a001*a078);
  a106=(a106-a078);
  a078=(a106/a005);
  a078=(-a078);
  if (res[1]!=0) res[1][24]=a078;
  a078=(a006*a064);
  a078=(a078-a108);
  a108=(a051*a049);
  a108=(a108-a099);
  a078=(a078-a108);
  a108=(a021*a101);
  a108=(a108-a111);
  a078=(a078+a108);
  a078=(a004*a078);
  a078=(a001*a078);
  a096=(a004*a096);
  a096=(a001*a096);
  a078=(a078-a096);
  a096=(a078/a005);
  a096=(-a096);
  if (res[1]!=0) res[1][25]=a096;
  a049=(a040*a049);
  a089=(a089+a049);
  a064=(a021*a064);
  a064=(a064-a088);
  a089=(a089-a064);
  a101=(a006*a101);
  a101=(a101-a063);
  a089=(a089+a101);
  a089=(a004*a089);
  a089=(a001*a089);
  a075=(a004*a075);
  a075=(a001*a075);
  a089=(a089-a075);
  a075=(a089/a005);
  a075=(-a075);
  if (res[1]!=0) res[1][26]=a075;
  a086=(a086-a106);
  a086=(a086/a005);
  if (res[1]!=0) res[1][27]=a086;
  a045=(a045-a078);
  a045=(a045/a005);
  if (res[1]!=0) res[1][28]=a045;
  a065=(a065-a089);
  a065=(a065/a005);
  if (res[1]!=0) res[1][29]=a065;
  a072=(a001*a072);
  a022=(a022+a072);
  a022=(2.*a022);
  a033=(a033*a022);
  a022=(a001*a033);
  a024=(a024*a022);
  a028=(a028+a024);
  a028=(a028-a023);
  a028=(a028/a004);
  a023=(a021*a028);
  a023=(a023-a068);
  a043=(a043*a022);
  a034=(a034+a043);
  a102=(a102-a034);
  a102=(a102/a004);
  a034=(a040*a102);
  a034=(a034-a060);
  a023=(a023-a034);
  a023=(a023+a046);
  a023=(a004*a023);
  a046=(a001*a023);
  a034=(a010*a046);
  a060=(a051*a102);
  a019=(a019+a060);
  a060=(a006*a028);
  a060=(a060-a017);
  a019=(a019+a060);
  a019=(a019-a027);
  a019=(a004*a019);
  a027=(a001*a019);
  a060=(a015*a027);
  a053=(a053+a060);
  a034=(a034-a053);
  a053=(a015*a023);
  a038=(a038+a053);
  a053=(a010*a019);
  a038=(a038+a053);
  a102=(a006*a102);
  a102=(a102-a047);
  a028=(a051*a028);
  a035=(a035+a028);
  a102=(a102-a035);
  a102=(a102+a037);
  a102=(a004*a102);
  a037=(a000*a102);
  a038=(a038+a037);
  a044=(a044*a038);
  a038=(a000*a044);
  a034=(a034+a038);
  a034=(a034+a102);
  a038=(a006*a034);
  a038=(a038-a048);
  a046=(a000*a046);
  a046=(a019-a046);
  a048=(a010*a044);
  a046=(a046+a048);
  a048=(a001*a102);
  a037=(a015*a048);
  a058=(a058+a037);
  a046=(a046+a058);
  a058=(a051*a046);
  a030=(a030+a058);
  a038=(a038+a030);
  a000=(a000*a027);
  a000=(a023+a000);
  a015=(a015*a044);
  a054=(a054+a015);
  a000=(a000+a054);
  a010=(a010*a048);
  a000=(a000-a010);
  a010=(a040*a000);
  a010=(a010-a008);
  a038=(a038-a010);
  a038=(a004*a038);
  a038=(a001*a038);
  a102=(a004*a102);
  a102=(a001*a102);
  a038=(a038-a102);
  a102=(a038/a005);
  a102=(-a102);
  if (res[1]!=0) res[1][30]=a102;
  a102=(a006*a046);
  a102=(a102-a087);
  a051=(a051*a034);
  a016=(a016+a051);
  a102=(a102-a016);
  a016=(a021*a000);
  a016=(a016-a098);
  a102=(a102+a016);
  a102=(a004*a102);
  a102=(a001*a102);
  a019=(a004*a019);
  a019=(a001*a019);
  a102=(a102-a019);
  a019=(a102/a005);
  a019=(-a019);
  if (res[1]!=0) res[1][31]=a019;
  a040=(a040*a034);
  a040=(a040-a018);
  a021=(a021*a046);
  a021=(a021-a056);
  a040=(a040-a021);
  a006=(a006*a000);
  a006=(a006-a057);
  a040=(a040+a006);
  a040=(a004*a040);
  a040=(a001*a040);
  a004=(a004*a023);
  a001=(a001*a004);
  a040=(a040-a001);
  a001=(a040/a005);
  a001=(-a001);
  if (res[1]!=0) res[1][32]=a001;
  a029=(a029-a038);
  a029=(a029/a005);
  if (res[1]!=0) res[1][33]=a029;
  a042=(a042-a102);
  a042=(a042/a005);
  if (res[1]!=0) res[1][34]=a042;
  a033=(a033-a040);
  a033=(a033/a005);
  if (res[1]!=0) res[1][35]=a033;
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
    case 3: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* residual_jacobian_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s4;
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

/* update:(z[6],g[9],p[3],h)->(g1[9],p1[3]) */
static int casadi_f2(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31;
  a00=arg[1]? arg[1][0] : 0;
  a01=1.;
  a02=4.;
  a03=arg[3]? arg[3][0] : 0;
  a04=5.0000000000000000e-01;
  a05=arg[0]? arg[0][0] : 0;
  a06=(a04*a05);
  a07=arg[0]? arg[0][3] : 0;
  a08=(a04*a07);
  a06=(a06+a08);
  a06=(a03*a06);
  a08=casadi_sq(a06);
  a09=arg[0]? arg[0][1] : 0;
  a10=(a04*a09);
  a11=arg[0]? arg[0][4] : 0;
  a12=(a04*a11);
  a10=(a10+a12);
  a10=(a03*a10);
  a12=casadi_sq(a10);
  a13=(a08+a12);
  a14=arg[0]? arg[0][2] : 0;
  a15=(a04*a14);
  a16=arg[0]? arg[0][5] : 0;
  a17=(a04*a16);
  a15=(a15+a17);
  a15=(a03*a15);
  a17=casadi_sq(a15);
  a13=(a13+a17);
  a13=(a02+a13);
  a02=(a02/a13);
  a13=(a17+a12);
  a18=2.;
  a13=(a13/a18);
  a13=(a02*a13);
  a13=(a01-a13);
  a19=(a00*a13);
  a20=arg[1]? arg[1][3] : 0;
  a21=(a06*a10);
  a21=(a21/a18);
  a21=(a15+a21);
  a21=(a02*a21);
  a22=(a20*a21);
  a19=(a19+a22);
  a22=arg[1]? arg[1][6] : 0;
  a23=(a06*a15);
  a23=(a23/a18);
  a23=(a23-a10);
  a23=(a02*a23);
  a24=(a22*a23);
  a19=(a19+a24);
  if (res[0]!=0) res[0][0]=a19;
  a19=arg[1]? arg[1][1] : 0;
  a24=(a19*a13);
  a25=arg[1]? arg[1][4] : 0;
  a26=(a25*a21);
  a24=(a24+a26);
  a26=arg[1]? arg[1][7] : 0;
  a27=(a26*a23);
  a24=(a24+a27);
  if (res[0]!=0) res[0][1]=a24;
  a24=arg[1]? arg[1][2] : 0;
  a13=(a24*a13);
  a27=arg[1]? arg[1][5] : 0;
  a21=(a27*a21);
  a13=(a13+a21);
  a21=arg[1]? arg[1][8] : 0;
  a23=(a21*a23);
  a13=(a13+a23);
  if (res[0]!=0) res[0][2]=a13;
  a23=(a10*a06);
  a23=(a23/a18);
  a23=(a23-a15);
  a23=(a02*a23);
  a28=(a00*a23);
  a17=(a17+a08);
  a17=(a17/a18);
  a17=(a02*a17);
  a17=(a01-a17);
  a29=(a20*a17);
  a28=(a28+a29);
  a29=(a10*a15);
  a29=(a29/a18);
  a29=(a06+a29);
  a29=(a02*a29);
  a30=(a22*a29);
  a28=(a28+a30);
  if (res[0]!=0) res[0][3]=a28;
  a28=(a19*a23);
  a30=(a25*a17);
  a28=(a28+a30);
  a30=(a26*a29);
  a28=(a28+a30);
  if (res[0]!=0) res[0][4]=a28;
  a23=(a24*a23);
  a17=(a27*a17);
  a23=(a23+a17);
  a29=(a21*a29);
  a23=(a23+a29);
  if (res[0]!=0) res[0][5]=a23;
  a29=(a15*a06);
  a29=(a29/a18);
  a29=(a10+a29);
  a29=(a02*a29);
  a00=(a00*a29);
  a17=(a15*a10);
  a17=(a17/a18);
  a17=(a17-a06);
  a17=(a02*a17);
  a20=(a20*a17);
  a00=(a00+a20);
  a12=(a12+a08);
  a12=(a12/a18);
  a12=(a02*a12);
  a01=(a01-a12);
  a22=(a22*a01);
  a00=(a00+a22);
  if (res[0]!=0) res[0][6]=a00;
  a19=(a19*a29);
  a25=(a25*a17);
  a19=(a19+a25);
  a26=(a26*a01);
  a19=(a19+a26);
  if (res[0]!=0) res[0][7]=a19;
  a29=(a24*a29);
  a17=(a27*a17);
  a29=(a29+a17);
  a01=(a21*a01);
  a29=(a29+a01);
  if (res[0]!=0) res[0][8]=a29;
  a01=arg[2]? arg[2][1] : 0;
  a17=(a15/a18);
  a17=(a02*a17);
  a19=2.9999999999999999e-02;
  a19=(a19*a03);
  a26=(a04*a23);
  a11=(a11+a26);
  a11=(2.*a11);
  a26=2.5000000000000000e-01;
  a25=(a26*a03);
  a11=(a11*a25);
  a11=(a04*a11);
  a11=(a19+a11);
  a00=(a29*a11);
  a22=-7.4999999999999997e-02;
  a22=(a22*a03);
  a12=(a04*a29);
  a16=(a16+a12);
  a16=(2.*a16);
  a12=1.6666666666666666e-01;
  a12=(a12*a03);
  a16=(a16*a12);
  a16=(a04*a16);
  a16=(a22+a16);
  a08=(a23*a16);
  a00=(a00-a08);
  a00=(a00/a03);
  a08=(a17*a00);
  a16=(a13*a16);
  a20=-4.4999999999999998e-02;
  a20=(a20*a03);
  a28=(a04*a13);
  a07=(a07+a28);
  a07=(2.*a07);
  a28=(a04*a03);
  a07=(a07*a28);
  a07=(a04*a07);
  a07=(a20+a07);
  a29=(a29*a07);
  a16=(a16-a29);
  a16=(a16/a03);
  a29=(a02*a16);
  a08=(a08+a29);
  a29=(a06/a18);
  a29=(a02*a29);
  a23=(a23*a07);
  a13=(a13*a11);
  a23=(a23-a13);
  a23=(a23/a03);
  a13=(a29*a23);
  a08=(a08-a13);
  a08=(a03*a08);
  a13=(a29*a16);
  a18=(a10/a18);
  a18=(a02*a18);
  a11=(a18*a00);
  a13=(a13-a11);
  a11=(a02*a23);
  a13=(a13+a11);
  a13=(a03*a13);
  a11=(a04*a13);
  a07=(a06*a11);
  a07=(a08-a07);
  a30=(a15*a13);
  a31=(a10*a08);
  a30=(a30+a31);
  a00=(a02*a00);
  a16=(a17*a16);
  a00=(a00-a16);
  a23=(a18*a23);
  a00=(a00+a23);
  a03=(a03*a00);
  a00=(a06*a03);
  a30=(a30+a00);
  a30=(a26*a30);
  a00=(a10*a30);
  a07=(a07+a00);
  a00=(a04*a03);
  a23=(a15*a00);
  a07=(a07+a23);
  a23=(a04*a21);
  a14=(a14+a23);
  a14=(2.*a14);
  a14=(a14*a12);
  a14=(a04*a14);
  a22=(a22+a14);
  a14=(a24*a22);
  a12=(a04*a24);
  a05=(a05+a12);
  a05=(2.*a05);
  a05=(a05*a28);
  a05=(a04*a05);
  a20=(a20+a05);
  a05=(a21*a20);
  a14=(a14-a05);
  a07=(a07+a14);
  a01=(a01+a07);
  a07=(a02*a01);
  a14=arg[2]? arg[2][0] : 0;
  a11=(a10*a11);
  a08=(a04*a08);
  a05=(a15*a08);
  a11=(a11-a05);
  a05=(a06*a30);
  a11=(a11+a05);
  a11=(a11+a03);
  a03=(a04*a27);
  a09=(a09+a03);
  a09=(2.*a09);
  a09=(a09*a25);
  a09=(a04*a09);
  a19=(a19+a09);
  a21=(a21*a19);
  a22=(a27*a22);
  a21=(a21-a22);
  a11=(a11+a21);
  a14=(a14+a11);
  a11=(a17*a14);
  a07=(a07-a11);
  a11=arg[2]? arg[2][2] : 0;
  a08=(a06*a08);
  a13=(a13+a08);
  a30=(a15*a30);
  a13=(a13+a30);
  a00=(a10*a00);
  a13=(a13-a00);
  a27=(a27*a20);
  a24=(a24*a19);
  a27=(a27-a24);
  a13=(a13+a27);
  a11=(a11+a13);
  a13=(a29*a11);
  a07=(a07+a13);
  a13=(a04*a07);
  a27=(a15*a13);
  a24=(a18*a14);
  a29=(a29*a01);
  a24=(a24-a29);
  a29=(a02*a11);
  a24=(a24+a29);
  a29=(a04*a24);
  a19=(a10*a29);
  a27=(a27-a19);
  a19=(a15*a24);
  a20=(a10*a07);
  a19=(a19+a20);
  a02=(a02*a14);
  a17=(a17*a01);
  a02=(a02+a17);
  a18=(a18*a11);
  a02=(a02-a18);
  a18=(a06*a02);
  a19=(a19+a18);
  a26=(a26*a19);
  a19=(a06*a26);
  a27=(a27+a19);
  a27=(a27+a02);
  if (res[1]!=0) res[1][0]=a27;
  a29=(a06*a29);
  a29=(a29+a07);
  a07=(a10*a26);
  a29=(a29+a07);
  a04=(a04*a02);
  a02=(a15*a04);
  a29=(a29-a02);
  if (res[1]!=0) res[1][1]=a29;
  a06=(a06*a13);
  a24=(a24-a06);
  a15=(a15*a26);
  a24=(a24+a15);
  a10=(a10*a04);
  a24=(a24+a10);
  if (res[1]!=0) res[1][2]=a24;
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

/* guess:(xi[3],g[9],p[3],h)->(z0[6]) */
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

/* margin:(z[6],h)->(m) */
static int casadi_f9(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4, a5, a6;
  a0=1.;
  a1=4.;
  a2=arg[1]? arg[1][0] : 0;
  a3=5.0000000000000000e-01;
  a4=arg[0]? arg[0][0] : 0;
  a4=(a3*a4);
  a5=arg[0]? arg[0][3] : 0;
  a5=(a3*a5);
  a4=(a4+a5);
  a4=(a2*a4);
  a4=casadi_sq(a4);
  a5=arg[0]? arg[0][1] : 0;
  a5=(a3*a5);
  a6=arg[0]? arg[0][4] : 0;
  a6=(a3*a6);
  a5=(a5+a6);
  a5=(a2*a5);
  a5=casadi_sq(a5);
  a4=(a4+a5);
  a5=arg[0]? arg[0][2] : 0;
  a5=(a3*a5);
  a6=arg[0]? arg[0][5] : 0;
  a3=(a3*a6);
  a5=(a5+a3);
  a2=(a2*a5);
  a2=casadi_sq(a2);
  a4=(a4+a2);
  a1=(a1-a4);
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
    case 1: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* section_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
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

/* chart_point:(z[6],g[9],h,theta)->(g_theta[9]) */
static int casadi_f11(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21;
  a00=arg[1]? arg[1][0] : 0;
  a01=1.;
  a02=4.;
  a03=arg[3]? arg[3][0] : 0;
  a04=arg[2]? arg[2][0] : 0;
  a05=5.0000000000000000e-01;
  a06=arg[0]? arg[0][0] : 0;
  a06=(a05*a06);
  a07=arg[0]? arg[0][3] : 0;
  a07=(a05*a07);
  a06=(a06+a07);
  a06=(a04*a06);
  a06=(a03*a06);
  a07=casadi_sq(a06);
  a08=arg[0]? arg[0][1] : 0;
  a08=(a05*a08);
  a09=arg[0]? arg[0][4] : 0;
  a09=(a05*a09);
  a08=(a08+a09);
  a08=(a04*a08);
  a08=(a03*a08);
  a09=casadi_sq(a08);
  a10=(a07+a09);
  a11=arg[0]? arg[0][2] : 0;
  a11=(a05*a11);
  a12=arg[0]? arg[0][5] : 0;
  a05=(a05*a12);
  a11=(a11+a05);
  a04=(a04*a11);
  a03=(a03*a04);
  a04=casadi_sq(a03);
  a10=(a10+a04);
  a10=(a02+a10);
  a02=(a02/a10);
  a10=(a04+a09);
  a11=2.;
  a10=(a10/a11);
  a10=(a02*a10);
  a10=(a01-a10);
  a05=(a00*a10);
  a12=arg[1]? arg[1][3] : 0;
  a13=(a06*a08);
  a13=(a13/a11);
  a13=(a03+a13);
  a13=(a02*a13);
  a14=(a12*a13);
  a05=(a05+a14);
  a14=arg[1]? arg[1][6] : 0;
  a15=(a06*a03);
  a15=(a15/a11);
  a15=(a15-a08);
  a15=(a02*a15);
  a16=(a14*a15);
  a05=(a05+a16);
  if (res[0]!=0) res[0][0]=a05;
  a05=arg[1]? arg[1][1] : 0;
  a16=(a05*a10);
  a17=arg[1]? arg[1][4] : 0;
  a18=(a17*a13);
  a16=(a16+a18);
  a18=arg[1]? arg[1][7] : 0;
  a19=(a18*a15);
  a16=(a16+a19);
  if (res[0]!=0) res[0][1]=a16;
  a16=arg[1]? arg[1][2] : 0;
  a10=(a16*a10);
  a19=arg[1]? arg[1][5] : 0;
  a13=(a19*a13);
  a10=(a10+a13);
  a13=arg[1]? arg[1][8] : 0;
  a15=(a13*a15);
  a10=(a10+a15);
  if (res[0]!=0) res[0][2]=a10;
  a10=(a08*a06);
  a10=(a10/a11);
  a10=(a10-a03);
  a10=(a02*a10);
  a15=(a00*a10);
  a04=(a04+a07);
  a04=(a04/a11);
  a04=(a02*a04);
  a04=(a01-a04);
  a20=(a12*a04);
  a15=(a15+a20);
  a20=(a08*a03);
  a20=(a20/a11);
  a20=(a06+a20);
  a20=(a02*a20);
  a21=(a14*a20);
  a15=(a15+a21);
  if (res[0]!=0) res[0][3]=a15;
  a15=(a05*a10);
  a21=(a17*a04);
  a15=(a15+a21);
  a21=(a18*a20);
  a15=(a15+a21);
  if (res[0]!=0) res[0][4]=a15;
  a10=(a16*a10);
  a04=(a19*a04);
  a10=(a10+a04);
  a20=(a13*a20);
  a10=(a10+a20);
  if (res[0]!=0) res[0][5]=a10;
  a10=(a03*a06);
  a10=(a10/a11);
  a10=(a08+a10);
  a10=(a02*a10);
  a00=(a00*a10);
  a03=(a03*a08);
  a03=(a03/a11);
  a03=(a03-a06);
  a03=(a02*a03);
  a12=(a12*a03);
  a00=(a00+a12);
  a09=(a09+a07);
  a09=(a09/a11);
  a02=(a02*a09);
  a01=(a01-a02);
  a14=(a14*a01);
  a00=(a00+a14);
  if (res[0]!=0) res[0][6]=a00;
  a05=(a05*a10);
  a17=(a17*a03);
  a05=(a05+a17);
  a18=(a18*a01);
  a05=(a05+a18);
  if (res[0]!=0) res[0][7]=a05;
  a16=(a16*a10);
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
    case 2: return casadi_s3;
    case 3: return casadi_s3;
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
  a00=arg[0]? arg[0][2] : 0;
  a01=arg[1]? arg[1][0] : 0;
  a02=(a00-a01);
  a03=2.;
  a02=(a02/a03);
  a03=(-a02);
  if (res[0]!=0) res[0][0]=a03;
  a03=5.0000000000000000e-01;
  a04=arg[0]? arg[0][5] : 0;
  a05=(a03*a04);
  a06=arg[1]? arg[1][1] : 0;
  a07=(a05-a06);
  a08=(-a07);
  if (res[0]!=0) res[0][1]=a08;
  a08=3.3333333333333331e-01;
  a09=arg[0]? arg[0][8] : 0;
  a10=(a08*a09);
  a11=arg[1]? arg[1][2] : 0;
  a10=(a10-a11);
  a12=6.6666666666666663e-01;
  a10=(a10/a12);
  a13=(-a10);
  if (res[0]!=0) res[0][2]=a13;
  a13=(a03*a00);
  a13=(a13-a02);
  a14=(2.*a13);
  a14=(a14*a02);
  a05=(a05-a07);
  a07=(a05*a07);
  a14=(a14+a07);
  a07=(a03*a09);
  a07=(a07-a10);
  a12=(a12*a07);
  a12=(a12*a10);
  a14=(a14+a12);
  a05=casadi_sq(a05);
  a03=(a03*a05);
  a13=casadi_sq(a13);
  a03=(a03+a13);
  a13=5.9999999999999998e-02;
  a13=(a13*a04);
  a03=(a03+a13);
  a07=casadi_sq(a07);
  a08=(a08*a07);
  a03=(a03+a08);
  a08=-8.9999999999999997e-02;
  a08=(a08*a00);
  a03=(a03+a08);
  a08=-1.4999999999999999e-01;
  a08=(a08*a09);
  a03=(a03+a08);
  a14=(a14+a03);
  a14=(-a14);
  if (res[1]!=0) res[1][0]=a14;
  a14=arg[0]? arg[0][4] : 0;
  a03=(a09*a14);
  a08=arg[0]? arg[0][7] : 0;
  a07=(a08*a04);
  a03=(a03-a07);
  a03=(a03*a01);
  a13=(a00*a08);
  a05=arg[0]? arg[0][1] : 0;
  a12=(a05*a09);
  a13=(a13-a12);
  a13=(a13*a06);
  a03=(a03+a13);
  a13=(a04*a05);
  a10=(a14*a00);
  a13=(a13-a10);
  a13=(a13*a11);
  a03=(a03+a13);
  if (res[2]!=0) res[2][0]=a03;
  a03=arg[0]? arg[0][6] : 0;
  a13=(a03*a04);
  a02=arg[0]? arg[0][3] : 0;
  a15=(a09*a02);
  a13=(a13-a15);
  a13=(a13*a01);
  a15=arg[0]? arg[0][0] : 0;
  a16=(a15*a09);
  a17=(a00*a03);
  a16=(a16-a17);
  a16=(a16*a06);
  a13=(a13+a16);
  a16=(a02*a00);
  a17=(a04*a15);
  a16=(a16-a17);
  a16=(a16*a11);
  a13=(a13+a16);
  if (res[2]!=0) res[2][1]=a13;
  a13=(a08*a02);
  a16=(a03*a14);
  a13=(a13-a16);
  a13=(a13*a01);
  a01=(a05*a03);
  a16=(a15*a08);
  a01=(a01-a16);
  a01=(a01*a06);
  a13=(a13+a01);
  a01=(a14*a15);
  a06=(a02*a05);
  a01=(a01-a06);
  a01=(a01*a11);
  a13=(a13+a01);
  if (res[2]!=0) res[2][2]=a13;
  a13=casadi_sq(a15);
  a01=casadi_sq(a05);
  a13=(a13+a01);
  a01=casadi_sq(a00);
  a13=(a13+a01);
  a01=1.;
  a13=(a13-a01);
  a13=casadi_fabs(a13);
  a11=(a02*a15);
  a06=(a14*a05);
  a11=(a11+a06);
  a06=(a04*a00);
  a11=(a11+a06);
  a11=casadi_fabs(a11);
  a13=casadi_fmax(a13,a11);
  a11=(a03*a15);
  a06=(a08*a05);
  a11=(a11+a06);
  a06=(a09*a00);
  a11=(a11+a06);
  a11=casadi_fabs(a11);
  a13=casadi_fmax(a13,a11);
  a11=(a15*a02);
  a06=(a05*a14);
  a11=(a11+a06);
  a06=(a00*a04);
  a11=(a11+a06);
  a11=casadi_fabs(a11);
  a13=casadi_fmax(a13,a11);
  a11=casadi_sq(a02);
  a06=casadi_sq(a14);
  a11=(a11+a06);
  a06=casadi_sq(a04);
  a11=(a11+a06);
  a11=(a11-a01);
  a11=casadi_fabs(a11);
  a13=casadi_fmax(a13,a11);
  a11=(a03*a02);
  a06=(a08*a14);
  a11=(a11+a06);
  a06=(a09*a04);
  a11=(a11+a06);
  a11=casadi_fabs(a11);
  a13=casadi_fmax(a13,a11);
  a11=(a15*a03);
  a06=(a05*a08);
  a11=(a11+a06);
  a06=(a00*a09);
  a11=(a11+a06);
  a11=casadi_fabs(a11);
  a13=casadi_fmax(a13,a11);
  a11=(a02*a03);
  a06=(a14*a08);
  a11=(a11+a06);
  a06=(a04*a09);
  a11=(a11+a06);
  a11=casadi_fabs(a11);
  a13=casadi_fmax(a13,a11);
  a11=casadi_sq(a03);
  a06=casadi_sq(a08);
  a11=(a11+a06);
  a06=casadi_sq(a09);
  a11=(a11+a06);
  a11=(a11-a01);
  a11=casadi_fabs(a11);
  a13=casadi_fmax(a13,a11);
  a14=(a14*a09);
  a14=(a14-a07);
  a15=(a15*a14);
  a08=(a08*a00);
  a12=(a12-a08);
  a02=(a02*a12);
  a15=(a15-a02);
  a05=(a05*a04);
  a05=(a05-a10);
  a03=(a03*a05);
  a15=(a15+a03);
  a15=(a15-a01);
  a15=casadi_fabs(a15);
  a13=casadi_fmax(a13,a15);
  if (res[3]!=0) res[3][0]=a13;
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
    case 1: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* observe_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    case 1: return casadi_s3;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
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

/* update_p:(z[6],g[9],p[3],h)->(p1[3]) */
static int casadi_f13(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31;
  a00=arg[3]? arg[3][0] : 0;
  a01=5.0000000000000000e-01;
  a02=arg[0]? arg[0][2] : 0;
  a03=(a01*a02);
  a04=arg[0]? arg[0][5] : 0;
  a05=(a01*a04);
  a03=(a03+a05);
  a03=(a00*a03);
  a05=4.;
  a06=arg[0]? arg[0][0] : 0;
  a07=(a01*a06);
  a08=arg[0]? arg[0][3] : 0;
  a09=(a01*a08);
  a07=(a07+a09);
  a07=(a00*a07);
  a09=casadi_sq(a07);
  a10=arg[0]? arg[0][1] : 0;
  a11=(a01*a10);
  a12=arg[0]? arg[0][4] : 0;
  a13=(a01*a12);
  a11=(a11+a13);
  a11=(a00*a11);
  a13=casadi_sq(a11);
  a14=(a09+a13);
  a15=casadi_sq(a03);
  a14=(a14+a15);
  a14=(a05+a14);
  a05=(a05/a14);
  a14=arg[2]? arg[2][1] : 0;
  a16=2.;
  a17=(a03/a16);
  a17=(a05*a17);
  a18=arg[1]? arg[1][2] : 0;
  a19=(a03*a07);
  a19=(a19/a16);
  a19=(a11+a19);
  a19=(a05*a19);
  a19=(a18*a19);
  a20=arg[1]? arg[1][5] : 0;
  a21=(a03*a11);
  a21=(a21/a16);
  a21=(a21-a07);
  a21=(a05*a21);
  a21=(a20*a21);
  a19=(a19+a21);
  a21=arg[1]? arg[1][8] : 0;
  a22=1.;
  a23=(a13+a09);
  a23=(a23/a16);
  a23=(a05*a23);
  a23=(a22-a23);
  a23=(a21*a23);
  a19=(a19+a23);
  a23=2.9999999999999999e-02;
  a23=(a23*a00);
  a24=(a11*a07);
  a24=(a24/a16);
  a24=(a24-a03);
  a24=(a05*a24);
  a24=(a18*a24);
  a09=(a15+a09);
  a09=(a09/a16);
  a09=(a05*a09);
  a09=(a22-a09);
  a09=(a20*a09);
  a24=(a24+a09);
  a09=(a11*a03);
  a09=(a09/a16);
  a09=(a07+a09);
  a09=(a05*a09);
  a09=(a21*a09);
  a24=(a24+a09);
  a09=(a01*a24);
  a12=(a12+a09);
  a12=(2.*a12);
  a09=2.5000000000000000e-01;
  a25=(a09*a00);
  a12=(a12*a25);
  a12=(a01*a12);
  a12=(a23+a12);
  a26=(a19*a12);
  a27=-7.4999999999999997e-02;
  a27=(a27*a00);
  a28=(a01*a19);
  a04=(a04+a28);
  a04=(2.*a04);
  a28=1.6666666666666666e-01;
  a28=(a28*a00);
  a04=(a04*a28);
  a04=(a01*a04);
  a04=(a27+a04);
  a29=(a24*a04);
  a26=(a26-a29);
  a26=(a26/a00);
  a29=(a17*a26);
  a15=(a15+a13);
  a15=(a15/a16);
  a15=(a05*a15);
  a22=(a22-a15);
  a22=(a18*a22);
  a15=(a07*a11);
  a15=(a15/a16);
  a15=(a03+a15);
  a15=(a05*a15);
  a15=(a20*a15);
  a22=(a22+a15);
  a15=(a07*a03);
  a15=(a15/a16);
  a15=(a15-a11);
  a15=(a05*a15);
  a15=(a21*a15);
  a22=(a22+a15);
  a04=(a22*a04);
  a15=-4.4999999999999998e-02;
  a15=(a15*a00);
  a13=(a01*a22);
  a08=(a08+a13);
  a08=(2.*a08);
  a13=(a01*a00);
  a08=(a08*a13);
  a08=(a01*a08);
  a08=(a15+a08);
  a19=(a19*a08);
  a04=(a04-a19);
  a04=(a04/a00);
  a19=(a05*a04);
  a29=(a29+a19);
  a19=(a07/a16);
  a19=(a05*a19);
  a24=(a24*a08);
  a22=(a22*a12);
  a24=(a24-a22);
  a24=(a24/a00);
  a22=(a19*a24);
  a29=(a29-a22);
  a29=(a00*a29);
  a22=(a19*a04);
  a16=(a11/a16);
  a16=(a05*a16);
  a12=(a16*a26);
  a22=(a22-a12);
  a12=(a05*a24);
  a22=(a22+a12);
  a22=(a00*a22);
  a12=(a01*a22);
  a08=(a07*a12);
  a08=(a29-a08);
  a30=(a03*a22);
  a31=(a11*a29);
  a30=(a30+a31);
  a26=(a05*a26);
  a04=(a17*a04);
  a26=(a26-a04);
  a24=(a16*a24);
  a26=(a26+a24);
  a00=(a00*a26);
  a26=(a07*a00);
  a30=(a30+a26);
  a30=(a09*a30);
  a26=(a11*a30);
  a08=(a08+a26);
  a26=(a01*a00);
  a24=(a03*a26);
  a08=(a08+a24);
  a24=(a01*a21);
  a02=(a02+a24);
  a02=(2.*a02);
  a02=(a02*a28);
  a02=(a01*a02);
  a27=(a27+a02);
  a02=(a18*a27);
  a28=(a01*a18);
  a06=(a06+a28);
  a06=(2.*a06);
  a06=(a06*a13);
  a06=(a01*a06);
  a15=(a15+a06);
  a06=(a21*a15);
  a02=(a02-a06);
  a08=(a08+a02);
  a14=(a14+a08);
  a08=(a05*a14);
  a02=arg[2]? arg[2][0] : 0;
  a12=(a11*a12);
  a29=(a01*a29);
  a06=(a03*a29);
  a12=(a12-a06);
  a06=(a07*a30);
  a12=(a12+a06);
  a12=(a12+a00);
  a00=(a01*a20);
  a10=(a10+a00);
  a10=(2.*a10);
  a10=(a10*a25);
  a10=(a01*a10);
  a23=(a23+a10);
  a21=(a21*a23);
  a27=(a20*a27);
  a21=(a21-a27);
  a12=(a12+a21);
  a02=(a02+a12);
  a12=(a17*a02);
  a08=(a08-a12);
  a12=arg[2]? arg[2][2] : 0;
  a29=(a07*a29);
  a22=(a22+a29);
  a30=(a03*a30);
  a22=(a22+a30);
  a26=(a11*a26);
  a22=(a22-a26);
  a20=(a20*a15);
  a18=(a18*a23);
  a20=(a20-a18);
  a22=(a22+a20);
  a12=(a12+a22);
  a22=(a19*a12);
  a08=(a08+a22);
  a22=(a01*a08);
  a20=(a03*a22);
  a18=(a16*a02);
  a19=(a19*a14);
  a18=(a18-a19);
  a19=(a05*a12);
  a18=(a18+a19);
  a19=(a01*a18);
  a23=(a11*a19);
  a20=(a20-a23);
  a23=(a03*a18);
  a15=(a11*a08);
  a23=(a23+a15);
  a05=(a05*a02);
  a17=(a17*a14);
  a05=(a05+a17);
  a16=(a16*a12);
  a05=(a05-a16);
  a16=(a07*a05);
  a23=(a23+a16);
  a09=(a09*a23);
  a23=(a07*a09);
  a20=(a20+a23);
  a20=(a20+a05);
  if (res[0]!=0) res[0][0]=a20;
  a19=(a07*a19);
  a19=(a19+a08);
  a08=(a11*a09);
  a19=(a19+a08);
  a01=(a01*a05);
  a05=(a03*a01);
  a19=(a19-a05);
  if (res[0]!=0) res[0][1]=a19;
  a07=(a07*a22);
  a18=(a18-a07);
  a03=(a03*a09);
  a18=(a18+a03);
  a11=(a11*a01);
  a18=(a18+a11);
  if (res[0]!=0) res[0][2]=a18;
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
    case 3: return casadi_s3;
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

/* velocity_step:(g[9],p[3],xi[3])->(xi1[3]) */
static int casadi_f14(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3;
  a0=arg[2]? arg[2][0] : 0;
  a1=5.0000000000000000e-01;
  a2=arg[0]? arg[0][2] : 0;
  a2=(a1*a2);
  a2=(a0+a2);
  a2=(2.*a2);
  a3=arg[1]? arg[1][0] : 0;
  a2=(a2-a3);
  a3=2.;
  a2=(a2/a3);
  a0=(a0-a2);
  if (res[0]!=0) res[0][0]=a0;
  a0=arg[2]? arg[2][1] : 0;
  a2=arg[0]? arg[0][5] : 0;
  a2=(a1*a2);
  a2=(a0+a2);
  a3=arg[1]? arg[1][1] : 0;
  a2=(a2-a3);
  a0=(a0-a2);
  if (res[0]!=0) res[0][1]=a0;
  a0=arg[2]? arg[2][2] : 0;
  a2=6.6666666666666663e-01;
  a3=arg[0]? arg[0][8] : 0;
  a1=(a1*a3);
  a1=(a0+a1);
  a1=(a2*a1);
  a3=arg[1]? arg[1][2] : 0;
  a1=(a1-a3);
  a1=(a1/a2);
  a0=(a0-a1);
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
    case 1: return casadi_s2;
    case 2: return casadi_s2;
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
  casadi_real a12, a13, a14, a15, a16, a17, a18;
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
  a13=5.0000000000000000e-01;
  a14=(a13*a02);
  a14=(a12+a14);
  a15=(2.*a14);
  a15=(a15*a12);
  a12=arg[2]? arg[2][1] : 0;
  a16=(a13*a05);
  a16=(a12+a16);
  a12=(a16*a12);
  a15=(a15+a12);
  a12=6.6666666666666663e-01;
  a17=arg[2]? arg[2][2] : 0;
  a18=(a13*a08);
  a18=(a17+a18);
  a12=(a12*a18);
  a12=(a12*a17);
  a15=(a15+a12);
  a16=casadi_sq(a16);
  a13=(a13*a16);
  a14=casadi_sq(a14);
  a13=(a13+a14);
  a14=5.9999999999999998e-02;
  a14=(a14*a05);
  a13=(a13+a14);
  a14=3.3333333333333331e-01;
  a18=casadi_sq(a18);
  a14=(a14*a18);
  a13=(a13+a14);
  a14=-8.9999999999999997e-02;
  a14=(a14*a02);
  a13=(a13+a14);
  a14=-1.4999999999999999e-01;
  a14=(a14*a08);
  a13=(a13+a14);
  a15=(a15-a13);
  if (res[0]!=0) res[0][12]=a15;
  a15=(a08*a04);
  a13=(a07*a05);
  a15=(a15-a13);
  a15=(a15*a09);
  a13=(a02*a07);
  a14=(a01*a08);
  a13=(a13-a14);
  a13=(a13*a10);
  a15=(a15+a13);
  a13=(a05*a01);
  a14=(a04*a02);
  a13=(a13-a14);
  a13=(a13*a11);
  a15=(a15+a13);
  if (res[0]!=0) res[0][13]=a15;
  a15=(a06*a05);
  a13=(a08*a03);
  a15=(a15-a13);
  a15=(a15*a09);
  a08=(a00*a08);
  a13=(a02*a06);
  a08=(a08-a13);
  a08=(a08*a10);
  a15=(a15+a08);
  a02=(a03*a02);
  a05=(a05*a00);
  a02=(a02-a05);
  a02=(a02*a11);
  a15=(a15+a02);
  if (res[0]!=0) res[0][14]=a15;
  a15=(a07*a03);
  a02=(a06*a04);
  a15=(a15-a02);
  a15=(a15*a09);
  a06=(a01*a06);
  a07=(a00*a07);
  a06=(a06-a07);
  a06=(a06*a10);
  a15=(a15+a06);
  a04=(a04*a00);
  a03=(a03*a01);
  a04=(a04-a03);
  a04=(a04*a11);
  a15=(a15+a04);
  if (res[0]!=0) res[0][15]=a15;
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
    case 1: return casadi_s2;
    case 2: return casadi_s2;
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

/* step_partials:(z[6],g[9],p[3],h)->(Fs[36],Yz[36],Ys[36]) */
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
  casadi_real a156, a157, a158, a159, a160;
  a000=5.0000000000000000e-01;
  a001=arg[3]? arg[3][0] : 0;
  a002=4.;
  a003=arg[0]? arg[0][0] : 0;
  a004=(a000*a003);
  a005=arg[0]? arg[0][3] : 0;
  a006=(a000*a005);
  a004=(a004+a006);
  a004=(a001*a004);
  a006=casadi_sq(a004);
  a007=arg[0]? arg[0][1] : 0;
  a008=(a000*a007);
  a009=arg[0]? arg[0][4] : 0;
  a010=(a000*a009);
  a008=(a008+a010);
  a008=(a001*a008);
  a010=casadi_sq(a008);
  a011=(a006+a010);
  a012=arg[0]? arg[0][2] : 0;
  a013=(a000*a012);
  a014=arg[0]? arg[0][5] : 0;
  a015=(a000*a014);
  a013=(a013+a015);
  a013=(a001*a013);
  a015=casadi_sq(a013);
  a011=(a011+a015);
  a011=(a002+a011);
  a002=(a002/a011);
  a016=2.;
  a017=(a004/a016);
  a018=(a002*a017);
  a019=-7.4999999999999997e-02;
  a019=(a019*a001);
  a020=arg[1]? arg[1][2] : 0;
  a021=(a013*a004);
  a021=(a021/a016);
  a021=(a008+a021);
  a022=(a002*a021);
  a023=(a020*a022);
  a024=arg[1]? arg[1][5] : 0;
  a025=(a013*a008);
  a025=(a025/a016);
  a025=(a025-a004);
  a026=(a002*a025);
  a027=(a024*a026);
  a023=(a023+a027);
  a027=arg[1]? arg[1][8] : 0;
  a028=1.;
  a029=(a010+a006);
  a029=(a029/a016);
  a030=(a002*a029);
  a030=(a028-a030);
  a031=(a027*a030);
  a023=(a023+a031);
  a031=(a000*a023);
  a014=(a014+a031);
  a014=(2.*a014);
  a031=1.6666666666666666e-01;
  a031=(a031*a001);
  a014=(a014*a031);
  a014=(a000*a014);
  a014=(a019+a014);
  a032=(a004*a008);
  a032=(a032/a016);
  a032=(a013+a032);
  a033=(a002*a032);
  a034=(a033*a027);
  a035=(a004*a013);
  a035=(a035/a016);
  a035=(a035-a008);
  a036=(a002*a035);
  a037=(a036*a024);
  a034=(a034-a037);
  a037=(a014*a034);
  a010=(a015+a010);
  a010=(a010/a016);
  a038=(a002*a010);
  a038=(a028-a038);
  a039=(a020*a038);
  a040=(a024*a033);
  a039=(a039+a040);
  a040=(a027*a036);
  a039=(a039+a040);
  a040=(a026*a027);
  a041=(a030*a024);
  a040=(a040-a041);
  a041=(a031*a040);
  a042=(a000*a041);
  a043=(a039*a042);
  a037=(a037+a043);
  a043=-4.4999999999999998e-02;
  a043=(a043*a001);
  a044=(a000*a039);
  a005=(a005+a044);
  a005=(2.*a005);
  a044=(a000*a001);
  a005=(a005*a044);
  a005=(a000*a005);
  a005=(a043+a005);
  a045=(a005*a040);
  a046=(a044*a034);
  a047=(a000*a046);
  a048=(a023*a047);
  a045=(a045+a048);
  a037=(a037-a045);
  a037=(a037/a001);
  a045=(a018*a037);
  a048=(a008/a016);
  a049=(a002*a048);
  a050=2.9999999999999999e-02;
  a050=(a050*a001);
  a051=(a008*a004);
  a051=(a051/a016);
  a051=(a051-a013);
  a052=(a002*a051);
  a053=(a020*a052);
  a015=(a015+a006);
  a015=(a015/a016);
  a006=(a002*a015);
  a006=(a028-a006);
  a054=(a024*a006);
  a053=(a053+a054);
  a054=(a008*a013);
  a054=(a054/a016);
  a054=(a004+a054);
  a055=(a002*a054);
  a056=(a027*a055);
  a053=(a053+a056);
  a056=(a000*a053);
  a009=(a009+a056);
  a009=(2.*a009);
  a056=2.5000000000000000e-01;
  a057=(a056*a001);
  a009=(a009*a057);
  a009=(a000*a009);
  a009=(a050+a009);
  a058=(a009*a040);
  a059=(a006*a027);
  a060=(a055*a024);
  a059=(a059-a060);
  a060=(a057*a059);
  a061=(a000*a060);
  a062=(a023*a061);
  a058=(a058+a062);
  a062=(a014*a059);
  a042=(a053*a042);
  a062=(a062+a042);
  a058=(a058-a062);
  a058=(a058/a001);
  a062=(a049*a058);
  a045=(a045-a062);
  a062=(a005*a059);
  a047=(a053*a047);
  a062=(a062+a047);
  a047=(a009*a034);
  a061=(a039*a061);
  a047=(a047+a061);
  a062=(a062-a047);
  a062=(a062/a001);
  a047=(a002*a062);
  a045=(a045+a047);
  a045=(a001*a045);
  a047=(a000*a045);
  a061=(a008*a047);
  a016=(a013/a016);
  a042=(a002*a016);
  a063=(a042*a058);
  a064=(a002*a037);
  a063=(a063+a064);
  a064=(a018*a062);
  a063=(a063-a064);
  a063=(a001*a063);
  a064=(a000*a063);
  a065=(a013*a064);
  a061=(a061-a065);
  a065=(a013*a045);
  a066=(a008*a063);
  a065=(a065+a066);
  a058=(a002*a058);
  a037=(a042*a037);
  a058=(a058-a037);
  a062=(a049*a062);
  a058=(a058+a062);
  a058=(a001*a058);
  a062=(a004*a058);
  a065=(a065+a062);
  a065=(a056*a065);
  a062=(a004*a065);
  a061=(a061+a062);
  a061=(a061+a058);
  a062=(a057*a027);
  a037=(a000*a062);
  a066=(a027*a037);
  a067=(a000*a024);
  a007=(a007+a067);
  a007=(2.*a007);
  a007=(a007*a057);
  a007=(a000*a007);
  a050=(a050+a007);
  a007=(a050*a024);
  a066=(a066-a007);
  a068=(a000*a027);
  a012=(a012+a068);
  a012=(2.*a012);
  a012=(a012*a031);
  a012=(a000*a012);
  a019=(a019+a012);
  a012=(a019*a027);
  a067=(-a067);
  a067=(2.*a067);
  a067=(a031*a067);
  a069=(a000*a067);
  a070=(a024*a069);
  a070=(a012+a070);
  a066=(a066-a070);
  a061=(a061+a066);
  a066=(a002*a061);
  a047=(a004*a047);
  a047=(a063-a047);
  a070=(a008*a065);
  a047=(a047+a070);
  a070=(a000*a058);
  a071=(a013*a070);
  a047=(a047+a071);
  a069=(a020*a069);
  a071=(a000*a020);
  a003=(a003+a071);
  a003=(2.*a003);
  a003=(a003*a044);
  a003=(a000*a003);
  a043=(a043+a003);
  a003=(a043*a024);
  a069=(a069+a003);
  a047=(a047+a069);
  a069=(a042*a047);
  a066=(a066+a069);
  a064=(a004*a064);
  a064=(a045+a064);
  a065=(a013*a065);
  a064=(a064+a065);
  a070=(a008*a070);
  a064=(a064-a070);
  a070=(a043*a027);
  a037=(a020*a037);
  a070=(a070-a037);
  a064=(a064+a070);
  a070=(a049*a064);
  a066=(a066-a070);
  a070=(a001*a066);
  a070=(a000*a070);
  a058=(a001*a058);
  a058=(a000*a058);
  a070=(a070-a058);
  a058=(a070/a044);
  a058=(-a058);
  if (res[0]!=0) res[0][0]=a058;
  a058=(a002*a047);
  a037=(a042*a061);
  a058=(a058-a037);
  a037=(a018*a064);
  a058=(a058+a037);
  a037=(a001*a058);
  a037=(a000*a037);
  a063=(a001*a063);
  a063=(a000*a063);
  a037=(a037-a063);
  a062=(a062-a037);
  a062=(a062/a044);
  if (res[0]!=0) res[0][1]=a062;
  a061=(a049*a061);
  a047=(a018*a047);
  a061=(a061-a047);
  a064=(a002*a064);
  a061=(a061+a064);
  a064=(a001*a061);
  a064=(a000*a064);
  a045=(a001*a045);
  a045=(a000*a045);
  a064=(a064-a045);
  a067=(a067-a064);
  a067=(a067/a044);
  if (res[0]!=0) res[0][2]=a067;
  a046=(a046-a070);
  a046=(a046/a044);
  if (res[0]!=0) res[0][3]=a046;
  a060=(a060-a037);
  a060=(a060/a044);
  if (res[0]!=0) res[0][4]=a060;
  a041=(a041-a064);
  a041=(a041/a044);
  if (res[0]!=0) res[0][5]=a041;
  a068=(-a068);
  a068=(2.*a068);
  a068=(a044*a068);
  a041=(a036*a020);
  a064=(a038*a027);
  a041=(a041-a064);
  a064=(a014*a041);
  a060=(a030*a020);
  a037=(a022*a027);
  a060=(a060-a037);
  a037=(a031*a060);
  a046=(a000*a037);
  a070=(a039*a046);
  a064=(a064+a070);
  a070=(a005*a060);
  a067=(a044*a041);
  a045=(a000*a067);
  a047=(a023*a045);
  a070=(a070+a047);
  a064=(a064-a070);
  a064=(a064/a001);
  a070=(a018*a064);
  a047=(a009*a060);
  a062=(a055*a020);
  a063=(a052*a027);
  a062=(a062-a063);
  a063=(a057*a062);
  a065=(a000*a063);
  a069=(a023*a065);
  a047=(a047+a069);
  a069=(a014*a062);
  a046=(a053*a046);
  a069=(a069+a046);
  a047=(a047-a069);
  a047=(a047/a001);
  a069=(a049*a047);
  a070=(a070-a069);
  a069=(a005*a062);
  a045=(a053*a045);
  a069=(a069+a045);
  a045=(a009*a041);
  a065=(a039*a065);
  a045=(a045+a065);
  a069=(a069-a045);
  a069=(a069/a001);
  a045=(a002*a069);
  a070=(a070+a045);
  a070=(a001*a070);
  a045=(a000*a070);
  a065=(a008*a045);
  a046=(a042*a047);
  a003=(a002*a064);
  a046=(a046+a003);
  a003=(a018*a069);
  a046=(a046-a003);
  a046=(a001*a046);
  a003=(a000*a046);
  a072=(a013*a003);
  a065=(a065-a072);
  a072=(a013*a070);
  a073=(a008*a046);
  a072=(a072+a073);
  a047=(a002*a047);
  a064=(a042*a064);
  a047=(a047-a064);
  a069=(a049*a069);
  a047=(a047+a069);
  a047=(a001*a047);
  a069=(a004*a047);
  a072=(a072+a069);
  a072=(a056*a072);
  a069=(a004*a072);
  a065=(a065+a069);
  a065=(a065+a047);
  a069=(a050*a020);
  a064=(a031*a020);
  a073=(a000*a064);
  a074=(a024*a073);
  a069=(a069-a074);
  a065=(a065+a069);
  a069=(a002*a065);
  a045=(a004*a045);
  a045=(a046-a045);
  a074=(a008*a072);
  a045=(a045+a074);
  a074=(a000*a047);
  a075=(a013*a074);
  a045=(a045+a075);
  a073=(a020*a073);
  a073=(a073-a012);
  a012=(a043*a020);
  a075=(a000*a068);
  a076=(a027*a075);
  a076=(a012+a076);
  a073=(a073-a076);
  a045=(a045+a073);
  a073=(a042*a045);
  a069=(a069+a073);
  a003=(a004*a003);
  a003=(a070+a003);
  a072=(a013*a072);
  a003=(a003+a072);
  a074=(a008*a074);
  a003=(a003-a074);
  a075=(a024*a075);
  a074=(a050*a027);
  a075=(a075+a074);
  a003=(a003+a075);
  a075=(a049*a003);
  a069=(a069-a075);
  a075=(a001*a069);
  a075=(a000*a075);
  a047=(a001*a047);
  a047=(a000*a047);
  a075=(a075-a047);
  a068=(a068-a075);
  a068=(a068/a044);
  if (res[0]!=0) res[0][6]=a068;
  a068=(a002*a045);
  a047=(a042*a065);
  a068=(a068-a047);
  a047=(a018*a003);
  a068=(a068+a047);
  a047=(a001*a068);
  a047=(a000*a047);
  a046=(a001*a046);
  a046=(a000*a046);
  a047=(a047-a046);
  a046=(a047/a044);
  a046=(-a046);
  if (res[0]!=0) res[0][7]=a046;
  a065=(a049*a065);
  a045=(a018*a045);
  a065=(a065-a045);
  a003=(a002*a003);
  a065=(a065+a003);
  a003=(a001*a065);
  a003=(a000*a003);
  a070=(a001*a070);
  a070=(a000*a070);
  a003=(a003-a070);
  a064=(a064-a003);
  a064=(a064/a044);
  if (res[0]!=0) res[0][8]=a064;
  a067=(a067-a075);
  a067=(a067/a044);
  if (res[0]!=0) res[0][9]=a067;
  a063=(a063-a047);
  a063=(a063/a044);
  if (res[0]!=0) res[0][10]=a063;
  a037=(a037-a003);
  a037=(a037/a044);
  if (res[0]!=0) res[0][11]=a037;
  a037=(a044*a024);
  a003=(a038*a024);
  a063=(a033*a020);
  a003=(a003-a063);
  a063=(a014*a003);
  a047=(a022*a024);
  a067=(a026*a020);
  a047=(a047-a067);
  a067=(a031*a047);
  a075=(a000*a067);
  a064=(a039*a075);
  a063=(a063+a064);
  a064=(a005*a047);
  a070=(a044*a003);
  a045=(a000*a070);
  a046=(a023*a045);
  a064=(a064+a046);
  a063=(a063-a064);
  a063=(a063/a001);
  a064=(a018*a063);
  a046=(a009*a047);
  a074=(a052*a024);
  a072=(a006*a020);
  a074=(a074-a072);
  a072=(a057*a074);
  a073=(a000*a072);
  a076=(a023*a073);
  a046=(a046+a076);
  a076=(a014*a074);
  a075=(a053*a075);
  a076=(a076+a075);
  a046=(a046-a076);
  a046=(a046/a001);
  a076=(a049*a046);
  a064=(a064-a076);
  a076=(a005*a074);
  a045=(a053*a045);
  a076=(a076+a045);
  a045=(a009*a003);
  a073=(a039*a073);
  a045=(a045+a073);
  a076=(a076-a045);
  a076=(a076/a001);
  a045=(a002*a076);
  a064=(a064+a045);
  a064=(a001*a064);
  a045=(a000*a064);
  a073=(a008*a045);
  a075=(a042*a046);
  a077=(a002*a063);
  a075=(a075+a077);
  a077=(a018*a076);
  a075=(a075-a077);
  a075=(a001*a075);
  a077=(a000*a075);
  a078=(a013*a077);
  a073=(a073-a078);
  a078=(a013*a064);
  a079=(a008*a075);
  a078=(a078+a079);
  a046=(a002*a046);
  a063=(a042*a063);
  a046=(a046-a063);
  a076=(a049*a076);
  a046=(a046+a076);
  a046=(a001*a046);
  a076=(a004*a046);
  a078=(a078+a076);
  a078=(a056*a078);
  a076=(a004*a078);
  a073=(a073+a076);
  a073=(a073+a046);
  a071=(-a071);
  a071=(2.*a071);
  a071=(a057*a071);
  a076=(a000*a071);
  a063=(a027*a076);
  a079=(a019*a020);
  a063=(a063+a079);
  a073=(a073+a063);
  a063=(a002*a073);
  a045=(a004*a045);
  a045=(a075-a045);
  a079=(a008*a078);
  a045=(a045+a079);
  a079=(a000*a046);
  a080=(a013*a079);
  a045=(a045+a080);
  a080=(a019*a024);
  a081=(a000*a037);
  a082=(a027*a081);
  a080=(a080-a082);
  a045=(a045+a080);
  a080=(a042*a045);
  a063=(a063+a080);
  a077=(a004*a077);
  a077=(a064+a077);
  a078=(a013*a078);
  a077=(a077+a078);
  a079=(a008*a079);
  a077=(a077-a079);
  a081=(a024*a081);
  a081=(a081-a012);
  a076=(a020*a076);
  a007=(a007+a076);
  a081=(a081-a007);
  a077=(a077+a081);
  a081=(a049*a077);
  a063=(a063-a081);
  a081=(a001*a063);
  a081=(a000*a081);
  a046=(a001*a046);
  a046=(a000*a046);
  a081=(a081-a046);
  a037=(a037-a081);
  a037=(a037/a044);
  if (res[0]!=0) res[0][12]=a037;
  a037=(a002*a045);
  a046=(a042*a073);
  a037=(a037-a046);
  a046=(a018*a077);
  a037=(a037+a046);
  a046=(a001*a037);
  a046=(a000*a046);
  a075=(a001*a075);
  a075=(a000*a075);
  a046=(a046-a075);
  a071=(a071-a046);
  a071=(a071/a044);
  if (res[0]!=0) res[0][13]=a071;
  a073=(a049*a073);
  a045=(a018*a045);
  a073=(a073-a045);
  a077=(a002*a077);
  a073=(a073+a077);
  a077=(a001*a073);
  a077=(a000*a077);
  a064=(a001*a064);
  a064=(a000*a064);
  a077=(a077-a064);
  a064=(a077/a044);
  a064=(-a064);
  if (res[0]!=0) res[0][14]=a064;
  a070=(a070-a081);
  a070=(a070/a044);
  if (res[0]!=0) res[0][15]=a070;
  a072=(a072-a046);
  a072=(a072/a044);
  if (res[0]!=0) res[0][16]=a072;
  a067=(a067-a077);
  a067=(a067/a044);
  if (res[0]!=0) res[0][17]=a067;
  a067=(a001*a002);
  a067=(a000*a067);
  a067=(a067/a044);
  a067=(-a067);
  if (res[0]!=0) res[0][18]=a067;
  a077=(a001*a042);
  a077=(a000*a077);
  a077=(a077/a044);
  if (res[0]!=0) res[0][19]=a077;
  a072=(a001*a049);
  a072=(a000*a072);
  a072=(a072/a044);
  a046=(-a072);
  if (res[0]!=0) res[0][20]=a046;
  if (res[0]!=0) res[0][21]=a067;
  if (res[0]!=0) res[0][22]=a077;
  if (res[0]!=0) res[0][23]=a046;
  a077=(-a077);
  if (res[0]!=0) res[0][24]=a077;
  if (res[0]!=0) res[0][25]=a067;
  a046=(a001*a018);
  a046=(a000*a046);
  a046=(a046/a044);
  if (res[0]!=0) res[0][26]=a046;
  if (res[0]!=0) res[0][27]=a077;
  if (res[0]!=0) res[0][28]=a067;
  if (res[0]!=0) res[0][29]=a046;
  if (res[0]!=0) res[0][30]=a072;
  a046=(-a046);
  if (res[0]!=0) res[0][31]=a046;
  if (res[0]!=0) res[0][32]=a067;
  if (res[0]!=0) res[0][33]=a072;
  if (res[0]!=0) res[0][34]=a046;
  if (res[0]!=0) res[0][35]=a067;
  a067=arg[1]? arg[1][0] : 0;
  a046=(a067*a022);
  a072=arg[1]? arg[1][3] : 0;
  a077=(a072*a026);
  a046=(a046+a077);
  a077=arg[1]? arg[1][6] : 0;
  a070=(a077*a030);
  a046=(a046+a070);
  a070=(a008*a044);
  a070=(a000*a070);
  a070=(a002*a070);
  a011=(a002/a011);
  a081=(2.*a004);
  a081=(a081*a044);
  a064=(a011*a081);
  a045=(a051*a064);
  a045=(a070-a045);
  a071=(a067*a045);
  a081=(a000*a081);
  a081=(a002*a081);
  a075=(a015*a064);
  a075=(a081-a075);
  a007=(a072*a075);
  a071=(a071-a007);
  a007=(a002*a044);
  a076=(a054*a064);
  a076=(a007-a076);
  a012=(a077*a076);
  a071=(a071+a012);
  a071=(a046*a071);
  a012=arg[1]? arg[1][1] : 0;
  a079=(a012*a022);
  a078=arg[1]? arg[1][4] : 0;
  a080=(a078*a026);
  a079=(a079+a080);
  a080=arg[1]? arg[1][7] : 0;
  a082=(a080*a030);
  a079=(a079+a082);
  a082=(a012*a045);
  a083=(a078*a075);
  a082=(a082-a083);
  a083=(a080*a076);
  a082=(a082+a083);
  a082=(a079*a082);
  a071=(a071+a082);
  a045=(a020*a045);
  a075=(a024*a075);
  a045=(a045-a075);
  a076=(a027*a076);
  a045=(a045+a076);
  a076=(a023*a045);
  a071=(a071+a076);
  if (res[1]!=0) res[1][0]=a071;
  a076=(a067*a038);
  a075=(a072*a033);
  a076=(a076+a075);
  a075=(a077*a036);
  a076=(a076+a075);
  a075=(a013*a044);
  a075=(a000*a075);
  a075=(a002*a075);
  a082=(a021*a064);
  a082=(a075-a082);
  a083=(a067*a082);
  a084=(a025*a064);
  a084=(a084+a007);
  a085=(a072*a084);
  a083=(a083-a085);
  a085=(a029*a064);
  a081=(a081-a085);
  a085=(a077*a081);
  a083=(a083-a085);
  a083=(a076*a083);
  a085=(a012*a038);
  a086=(a078*a033);
  a085=(a085+a086);
  a086=(a080*a036);
  a085=(a085+a086);
  a086=(a012*a082);
  a087=(a078*a084);
  a086=(a086-a087);
  a087=(a080*a081);
  a086=(a086-a087);
  a086=(a085*a086);
  a083=(a083+a086);
  a082=(a020*a082);
  a084=(a024*a084);
  a082=(a082-a084);
  a081=(a027*a081);
  a082=(a082-a081);
  a081=(a039*a082);
  a083=(a083+a081);
  if (res[1]!=0) res[1][1]=a083;
  a081=(a067*a052);
  a084=(a072*a006);
  a081=(a081+a084);
  a084=(a077*a055);
  a081=(a081+a084);
  a084=(a010*a064);
  a086=(a067*a084);
  a087=(a032*a064);
  a087=(a070-a087);
  a088=(a072*a087);
  a086=(a086+a088);
  a088=(a035*a064);
  a088=(a075-a088);
  a089=(a077*a088);
  a086=(a086+a089);
  a086=(a081*a086);
  a089=(a012*a052);
  a090=(a078*a006);
  a089=(a089+a090);
  a090=(a080*a055);
  a089=(a089+a090);
  a090=(a012*a084);
  a091=(a078*a087);
  a090=(a090+a091);
  a091=(a080*a088);
  a090=(a090+a091);
  a090=(a089*a090);
  a086=(a086+a090);
  a084=(a020*a084);
  a087=(a024*a087);
  a084=(a084+a087);
  a088=(a027*a088);
  a084=(a084+a088);
  a088=(a053*a084);
  a086=(a086+a088);
  if (res[1]!=0) res[1][2]=a086;
  a088=(a009*a082);
  a087=(a057*a045);
  a087=(a000*a087);
  a090=(a023*a087);
  a088=(a088+a090);
  a090=(a014*a045);
  a091=(a031*a082);
  a091=(a000*a091);
  a092=(a053*a091);
  a090=(a090+a092);
  a088=(a088-a090);
  a088=(a088/a001);
  a090=(a042*a088);
  a092=(a023*a009);
  a093=(a053*a014);
  a092=(a092-a093);
  a092=(a092/a001);
  a093=(a016*a064);
  a094=(a092*a093);
  a090=(a090-a094);
  a094=(a014*a084);
  a091=(a039*a091);
  a094=(a094+a091);
  a082=(a005*a082);
  a091=(a044*a084);
  a091=(a000*a091);
  a095=(a023*a091);
  a095=(a082+a095);
  a095=(a094-a095);
  a095=(a095/a001);
  a096=(a002*a095);
  a097=(a039*a014);
  a098=(a023*a005);
  a097=(a097-a098);
  a097=(a097/a001);
  a098=(a097*a064);
  a096=(a096-a098);
  a096=(a090+a096);
  a099=(a053*a005);
  a100=(a039*a009);
  a099=(a099-a100);
  a099=(a099/a001);
  a100=(a002*a057);
  a101=(a017*a064);
  a101=(a100-a101);
  a102=(a099*a101);
  a045=(a005*a045);
  a091=(a053*a091);
  a091=(a045+a091);
  a103=(a009*a084);
  a087=(a039*a087);
  a103=(a103+a087);
  a091=(a091-a103);
  a091=(a091/a001);
  a087=(a018*a091);
  a087=(a102+a087);
  a096=(a096-a087);
  a096=(a001*a096);
  a087=(a018*a097);
  a104=(a049*a092);
  a087=(a087-a104);
  a104=(a002*a099);
  a087=(a087+a104);
  a087=(a001*a087);
  a104=(a000*a087);
  a105=(a104*a044);
  a106=(a097*a101);
  a107=(a018*a095);
  a107=(a106+a107);
  a108=(a049*a088);
  a109=(a048*a064);
  a110=(a092*a109);
  a108=(a108-a110);
  a107=(a107-a108);
  a110=(a002*a091);
  a111=(a099*a064);
  a110=(a110-a111);
  a107=(a107+a110);
  a107=(a001*a107);
  a110=(a000*a107);
  a112=(a004*a110);
  a112=(a105+a112);
  a112=(a096-a112);
  a113=(a013*a107);
  a114=(a008*a096);
  a113=(a113+a114);
  a114=(a002*a092);
  a115=(a042*a097);
  a114=(a114-a115);
  a115=(a049*a099);
  a114=(a114+a115);
  a114=(a001*a114);
  a115=(a114*a044);
  a088=(a002*a088);
  a116=(a092*a064);
  a088=(a088-a116);
  a095=(a042*a095);
  a116=(a097*a093);
  a095=(a095-a116);
  a095=(a088-a095);
  a091=(a049*a091);
  a117=(a099*a109);
  a091=(a091-a117);
  a095=(a095+a091);
  a095=(a001*a095);
  a091=(a004*a095);
  a091=(a115+a091);
  a113=(a113+a091);
  a113=(a056*a113);
  a091=(a008*a113);
  a112=(a112+a091);
  a091=(a000*a095);
  a118=(a013*a091);
  a112=(a112+a118);
  a118=(a027*a044);
  a112=(a112-a118);
  a118=(a002*a112);
  a119=arg[2]? arg[2][1] : 0;
  a120=(a042*a092);
  a121=(a002*a097);
  a120=(a120+a121);
  a121=(a018*a099);
  a120=(a120-a121);
  a120=(a001*a120);
  a121=(a004*a104);
  a121=(a120-a121);
  a122=(a013*a087);
  a123=(a008*a120);
  a122=(a122+a123);
  a123=(a004*a114);
  a122=(a122+a123);
  a122=(a056*a122);
  a123=(a008*a122);
  a121=(a121+a123);
  a123=(a000*a114);
  a124=(a013*a123);
  a121=(a121+a124);
  a124=(a020*a019);
  a125=(a027*a043);
  a124=(a124-a125);
  a121=(a121+a124);
  a119=(a119+a121);
  a121=(a119*a064);
  a118=(a118-a121);
  a110=(a008*a110);
  a096=(a000*a096);
  a124=(a013*a096);
  a110=(a110-a124);
  a124=(a122*a044);
  a125=(a004*a113);
  a125=(a124+a125);
  a110=(a110+a125);
  a110=(a110+a095);
  a095=(a042*a110);
  a125=arg[2]? arg[2][0] : 0;
  a104=(a008*a104);
  a126=(a000*a120);
  a127=(a013*a126);
  a104=(a104-a127);
  a127=(a004*a122);
  a104=(a104+a127);
  a104=(a104+a114);
  a114=(a027*a050);
  a019=(a024*a019);
  a114=(a114-a019);
  a104=(a104+a114);
  a125=(a125+a104);
  a104=(a125*a093);
  a095=(a095-a104);
  a118=(a118-a095);
  a095=arg[2]? arg[2][2] : 0;
  a114=(a004*a126);
  a114=(a087+a114);
  a122=(a013*a122);
  a114=(a114+a122);
  a122=(a008*a123);
  a114=(a114-a122);
  a043=(a024*a043);
  a050=(a020*a050);
  a043=(a043-a050);
  a114=(a114+a043);
  a095=(a095+a114);
  a114=(a095*a101);
  a126=(a126*a044);
  a096=(a004*a096);
  a096=(a126+a096);
  a107=(a107+a096);
  a113=(a013*a113);
  a107=(a107+a113);
  a091=(a008*a091);
  a107=(a107-a091);
  a091=(a024*a044);
  a107=(a107+a091);
  a091=(a018*a107);
  a091=(a114+a091);
  a118=(a118+a091);
  a091=(a000*a118);
  a113=(a013*a091);
  a096=(a049*a110);
  a043=(a125*a109);
  a096=(a096-a043);
  a101=(a119*a101);
  a050=(a018*a112);
  a050=(a101+a050);
  a096=(a096-a050);
  a050=(a002*a107);
  a122=(a095*a064);
  a050=(a050-a122);
  a096=(a096+a050);
  a050=(a000*a096);
  a019=(a008*a050);
  a113=(a113-a019);
  a019=(a049*a125);
  a127=(a018*a119);
  a019=(a019-a127);
  a127=(a002*a095);
  a019=(a019+a127);
  a127=(a013*a019);
  a128=(a002*a119);
  a129=(a042*a125);
  a128=(a128-a129);
  a129=(a018*a095);
  a128=(a128+a129);
  a129=(a008*a128);
  a127=(a127+a129);
  a129=(a002*a125);
  a130=(a042*a119);
  a129=(a129+a130);
  a130=(a049*a095);
  a129=(a129-a130);
  a130=(a004*a129);
  a127=(a127+a130);
  a127=(a056*a127);
  a127=(a127*a044);
  a130=(a013*a096);
  a131=(a008*a118);
  a130=(a130+a131);
  a131=(a129*a044);
  a110=(a002*a110);
  a064=(a125*a064);
  a110=(a110-a064);
  a112=(a042*a112);
  a093=(a119*a093);
  a112=(a112-a093);
  a110=(a110+a112);
  a107=(a049*a107);
  a109=(a095*a109);
  a107=(a107-a109);
  a110=(a110-a107);
  a107=(a004*a110);
  a107=(a131+a107);
  a130=(a130+a107);
  a130=(a056*a130);
  a107=(a004*a130);
  a107=(a127+a107);
  a113=(a113+a107);
  a113=(a113+a110);
  if (res[1]!=0) res[1][3]=a113;
  a113=(a000*a019);
  a113=(a113*a044);
  a050=(a004*a050);
  a050=(a113+a050);
  a050=(a050+a118);
  a118=(a008*a130);
  a050=(a050+a118);
  a110=(a000*a110);
  a118=(a013*a110);
  a050=(a050-a118);
  if (res[1]!=0) res[1][4]=a050;
  a050=(a000*a128);
  a050=(a050*a044);
  a091=(a004*a091);
  a091=(a050+a091);
  a096=(a096-a091);
  a130=(a013*a130);
  a096=(a096+a130);
  a110=(a008*a110);
  a096=(a096+a110);
  if (res[1]!=0) res[1][5]=a096;
  a096=(a004*a044);
  a096=(a000*a096);
  a096=(a002*a096);
  a110=(2.*a008);
  a110=(a110*a044);
  a130=(a011*a110);
  a091=(a051*a130);
  a091=(a096-a091);
  a118=(a067*a091);
  a107=(a015*a130);
  a112=(a072*a107);
  a118=(a118+a112);
  a112=(a054*a130);
  a112=(a075-a112);
  a132=(a077*a112);
  a118=(a118+a132);
  a118=(a046*a118);
  a132=(a012*a091);
  a133=(a078*a107);
  a132=(a132+a133);
  a133=(a080*a112);
  a132=(a132+a133);
  a132=(a079*a132);
  a118=(a118+a132);
  a091=(a020*a091);
  a107=(a024*a107);
  a091=(a091+a107);
  a112=(a027*a112);
  a091=(a091+a112);
  a112=(a023*a091);
  a118=(a118+a112);
  if (res[1]!=0) res[1][6]=a118;
  a112=(a021*a130);
  a112=(a007-a112);
  a107=(a067*a112);
  a132=(a025*a130);
  a075=(a075-a132);
  a132=(a072*a075);
  a107=(a107+a132);
  a110=(a000*a110);
  a110=(a002*a110);
  a132=(a029*a130);
  a132=(a110-a132);
  a133=(a077*a132);
  a107=(a107-a133);
  a107=(a076*a107);
  a133=(a012*a112);
  a134=(a078*a075);
  a133=(a133+a134);
  a134=(a080*a132);
  a133=(a133-a134);
  a133=(a085*a133);
  a107=(a107+a133);
  a112=(a020*a112);
  a075=(a024*a075);
  a112=(a112+a075);
  a132=(a027*a132);
  a112=(a112-a132);
  a132=(a039*a112);
  a107=(a107+a132);
  if (res[1]!=0) res[1][7]=a107;
  a132=(a032*a130);
  a132=(a096-a132);
  a075=(a072*a132);
  a133=(a010*a130);
  a110=(a110-a133);
  a133=(a067*a110);
  a075=(a075-a133);
  a133=(a035*a130);
  a133=(a133+a007);
  a134=(a077*a133);
  a075=(a075-a134);
  a075=(a081*a075);
  a134=(a078*a132);
  a135=(a012*a110);
  a134=(a134-a135);
  a135=(a080*a133);
  a134=(a134-a135);
  a134=(a089*a134);
  a075=(a075+a134);
  a132=(a024*a132);
  a110=(a020*a110);
  a132=(a132-a110);
  a133=(a027*a133);
  a132=(a132-a133);
  a133=(a053*a132);
  a075=(a075+a133);
  if (res[1]!=0) res[1][8]=a075;
  a133=(a009*a112);
  a110=(a057*a091);
  a110=(a000*a110);
  a134=(a023*a110);
  a134=(a133+a134);
  a135=(a014*a091);
  a136=(a031*a112);
  a136=(a000*a136);
  a137=(a053*a136);
  a135=(a135+a137);
  a134=(a134-a135);
  a134=(a134/a001);
  a137=(a042*a134);
  a138=(a016*a130);
  a139=(a092*a138);
  a137=(a137-a139);
  a140=(a014*a132);
  a136=(a039*a136);
  a140=(a140+a136);
  a112=(a005*a112);
  a136=(a044*a132);
  a136=(a000*a136);
  a141=(a023*a136);
  a112=(a112+a141);
  a140=(a140-a112);
  a140=(a140/a001);
  a112=(a002*a140);
  a141=(a097*a130);
  a112=(a112-a141);
  a137=(a137+a112);
  a141=(a005*a091);
  a136=(a053*a136);
  a141=(a141+a136);
  a132=(a009*a132);
  a110=(a039*a110);
  a110=(a132+a110);
  a110=(a141-a110);
  a110=(a110/a001);
  a136=(a018*a110);
  a142=(a017*a130);
  a143=(a099*a142);
  a136=(a136-a143);
  a137=(a137-a136);
  a137=(a001*a137);
  a136=(a018*a140);
  a144=(a097*a142);
  a136=(a136-a144);
  a144=(a048*a130);
  a144=(a100-a144);
  a145=(a092*a144);
  a146=(a049*a134);
  a146=(a145+a146);
  a146=(a136-a146);
  a147=(a002*a110);
  a148=(a099*a130);
  a147=(a147-a148);
  a146=(a146+a147);
  a146=(a001*a146);
  a147=(a000*a146);
  a149=(a004*a147);
  a149=(a137-a149);
  a150=(a013*a146);
  a120=(a120*a044);
  a151=(a008*a137);
  a151=(a120+a151);
  a150=(a150+a151);
  a134=(a002*a134);
  a151=(a092*a130);
  a134=(a134-a151);
  a140=(a042*a140);
  a152=(a097*a138);
  a140=(a140-a152);
  a134=(a134-a140);
  a152=(a099*a144);
  a110=(a049*a110);
  a110=(a152+a110);
  a134=(a134+a110);
  a134=(a001*a134);
  a110=(a004*a134);
  a150=(a150+a110);
  a150=(a056*a150);
  a110=(a008*a150);
  a110=(a124+a110);
  a149=(a149+a110);
  a110=(a000*a134);
  a153=(a013*a110);
  a149=(a149+a153);
  a153=(a002*a149);
  a154=(a119*a130);
  a153=(a153-a154);
  a147=(a008*a147);
  a147=(a105+a147);
  a137=(a000*a137);
  a155=(a013*a137);
  a147=(a147-a155);
  a155=(a004*a150);
  a147=(a147+a155);
  a147=(a147+a134);
  a134=(a027*a057);
  a147=(a147+a134);
  a134=(a042*a147);
  a155=(a125*a138);
  a134=(a134-a155);
  a153=(a153-a134);
  a137=(a004*a137);
  a146=(a146+a137);
  a150=(a013*a150);
  a146=(a146+a150);
  a123=(a123*a044);
  a110=(a008*a110);
  a110=(a123+a110);
  a146=(a146-a110);
  a110=(a020*a057);
  a146=(a146-a110);
  a110=(a018*a146);
  a150=(a095*a142);
  a110=(a110-a150);
  a153=(a153+a110);
  a110=(a000*a153);
  a137=(a013*a110);
  a134=(a125*a144);
  a156=(a049*a147);
  a156=(a134+a156);
  a157=(a018*a149);
  a142=(a119*a142);
  a157=(a157-a142);
  a156=(a156-a157);
  a157=(a002*a146);
  a158=(a095*a130);
  a157=(a157-a158);
  a156=(a156+a157);
  a157=(a000*a156);
  a159=(a008*a157);
  a159=(a113+a159);
  a137=(a137-a159);
  a159=(a013*a156);
  a128=(a128*a044);
  a160=(a008*a153);
  a160=(a128+a160);
  a159=(a159+a160);
  a147=(a002*a147);
  a130=(a125*a130);
  a147=(a147-a130);
  a149=(a042*a149);
  a138=(a119*a138);
  a149=(a149-a138);
  a147=(a147+a149);
  a144=(a095*a144);
  a146=(a049*a146);
  a146=(a144+a146);
  a147=(a147-a146);
  a146=(a004*a147);
  a159=(a159+a146);
  a159=(a056*a159);
  a146=(a004*a159);
  a137=(a137+a146);
  a137=(a137+a147);
  if (res[1]!=0) res[1][9]=a137;
  a157=(a004*a157);
  a157=(a157+a153);
  a153=(a008*a159);
  a153=(a127+a153);
  a157=(a157+a153);
  a147=(a000*a147);
  a153=(a013*a147);
  a157=(a157-a153);
  if (res[1]!=0) res[1][10]=a157;
  a110=(a004*a110);
  a156=(a156-a110);
  a159=(a013*a159);
  a156=(a156+a159);
  a129=(a000*a129);
  a129=(a129*a044);
  a147=(a008*a147);
  a147=(a129+a147);
  a156=(a156+a147);
  if (res[1]!=0) res[1][11]=a156;
  a156=(2.*a013);
  a156=(a156*a044);
  a011=(a011*a156);
  a054=(a054*a011);
  a054=(a070-a054);
  a147=(a077*a054);
  a051=(a051*a011);
  a051=(a051+a007);
  a159=(a067*a051);
  a156=(a000*a156);
  a156=(a002*a156);
  a015=(a015*a011);
  a015=(a156-a015);
  a110=(a072*a015);
  a159=(a159+a110);
  a147=(a147-a159);
  a147=(a046*a147);
  a159=(a080*a054);
  a110=(a012*a051);
  a157=(a078*a015);
  a110=(a110+a157);
  a159=(a159-a110);
  a159=(a079*a159);
  a147=(a147+a159);
  a054=(a027*a054);
  a051=(a020*a051);
  a015=(a024*a015);
  a051=(a051+a015);
  a054=(a054-a051);
  a051=(a023*a054);
  a147=(a147+a051);
  if (res[1]!=0) res[1][12]=a147;
  a021=(a021*a011);
  a021=(a096-a021);
  a051=(a067*a021);
  a025=(a025*a011);
  a070=(a070-a025);
  a025=(a072*a070);
  a051=(a051+a025);
  a029=(a029*a011);
  a025=(a077*a029);
  a051=(a051+a025);
  a051=(a076*a051);
  a025=(a012*a021);
  a015=(a078*a070);
  a025=(a025+a015);
  a015=(a080*a029);
  a025=(a025+a015);
  a025=(a085*a025);
  a051=(a051+a025);
  a021=(a020*a021);
  a070=(a024*a070);
  a021=(a021+a070);
  a029=(a027*a029);
  a021=(a021+a029);
  a029=(a039*a021);
  a051=(a051+a029);
  if (res[1]!=0) res[1][13]=a051;
  a032=(a032*a011);
  a007=(a007-a032);
  a032=(a072*a007);
  a010=(a010*a011);
  a156=(a156-a010);
  a010=(a067*a156);
  a032=(a032-a010);
  a035=(a035*a011);
  a096=(a096-a035);
  a035=(a077*a096);
  a032=(a032+a035);
  a032=(a081*a032);
  a035=(a078*a007);
  a010=(a012*a156);
  a035=(a035-a010);
  a010=(a080*a096);
  a035=(a035+a010);
  a035=(a089*a035);
  a032=(a032+a035);
  a007=(a024*a007);
  a156=(a020*a156);
  a007=(a007-a156);
  a027=(a027*a096);
  a007=(a007+a027);
  a027=(a053*a007);
  a032=(a032+a027);
  if (res[1]!=0) res[1][14]=a032;
  a016=(a016*a011);
  a100=(a100-a016);
  a016=(a092*a100);
  a027=(a009*a021);
  a096=(a057*a054);
  a096=(a000*a096);
  a156=(a023*a096);
  a027=(a027+a156);
  a156=(a014*a054);
  a035=(a031*a021);
  a035=(a000*a035);
  a010=(a053*a035);
  a010=(a156+a010);
  a010=(a027-a010);
  a010=(a010/a001);
  a029=(a042*a010);
  a029=(a016+a029);
  a014=(a014*a007);
  a035=(a039*a035);
  a035=(a014+a035);
  a070=(a005*a021);
  a025=(a044*a007);
  a025=(a000*a025);
  a015=(a023*a025);
  a070=(a070+a015);
  a035=(a035-a070);
  a035=(a035/a001);
  a015=(a002*a035);
  a159=(a097*a011);
  a015=(a015-a159);
  a029=(a029+a015);
  a005=(a005*a054);
  a025=(a053*a025);
  a005=(a005+a025);
  a009=(a009*a007);
  a096=(a039*a096);
  a009=(a009+a096);
  a005=(a005-a009);
  a005=(a005/a001);
  a009=(a018*a005);
  a017=(a017*a011);
  a096=(a099*a017);
  a009=(a009-a096);
  a029=(a029-a009);
  a029=(a001*a029);
  a096=(a018*a035);
  a007=(a097*a017);
  a096=(a096-a007);
  a025=(a049*a010);
  a048=(a048*a011);
  a054=(a092*a048);
  a025=(a025-a054);
  a096=(a096-a025);
  a025=(a002*a005);
  a015=(a099*a011);
  a025=(a025-a015);
  a096=(a096+a025);
  a096=(a001*a096);
  a015=(a000*a096);
  a110=(a004*a015);
  a110=(a029-a110);
  a087=(a087*a044);
  a157=(a013*a096);
  a157=(a087+a157);
  a153=(a008*a029);
  a157=(a157+a153);
  a010=(a002*a010);
  a092=(a092*a011);
  a010=(a010-a092);
  a097=(a097*a100);
  a035=(a042*a035);
  a035=(a097+a035);
  a010=(a010-a035);
  a005=(a049*a005);
  a099=(a099*a048);
  a005=(a005-a099);
  a010=(a010+a005);
  a010=(a001*a010);
  a099=(a004*a010);
  a157=(a157+a099);
  a157=(a056*a157);
  a099=(a008*a157);
  a110=(a110+a099);
  a099=(a000*a010);
  a035=(a013*a099);
  a035=(a123+a035);
  a110=(a110+a035);
  a020=(a020*a031);
  a110=(a110+a020);
  a020=(a002*a110);
  a035=(a119*a011);
  a020=(a020-a035);
  a153=(a125*a100);
  a015=(a008*a015);
  a029=(a000*a029);
  a137=(a013*a029);
  a137=(a126+a137);
  a015=(a015-a137);
  a137=(a004*a157);
  a015=(a015+a137);
  a015=(a015+a010);
  a024=(a024*a031);
  a015=(a015-a024);
  a024=(a042*a015);
  a024=(a153+a024);
  a020=(a020-a024);
  a029=(a004*a029);
  a096=(a096+a029);
  a157=(a013*a157);
  a157=(a124+a157);
  a096=(a096+a157);
  a099=(a008*a099);
  a096=(a096-a099);
  a099=(a018*a096);
  a157=(a095*a017);
  a099=(a099-a157);
  a020=(a020+a099);
  a099=(a000*a020);
  a029=(a013*a099);
  a029=(a050+a029);
  a024=(a049*a015);
  a010=(a125*a048);
  a024=(a024-a010);
  a137=(a018*a110);
  a017=(a119*a017);
  a137=(a137-a017);
  a024=(a024-a137);
  a137=(a002*a096);
  a146=(a095*a011);
  a137=(a137-a146);
  a024=(a024+a137);
  a137=(a000*a024);
  a149=(a008*a137);
  a029=(a029-a149);
  a019=(a019*a044);
  a149=(a013*a024);
  a149=(a019+a149);
  a160=(a008*a020);
  a149=(a149+a160);
  a015=(a002*a015);
  a125=(a125*a011);
  a015=(a015-a125);
  a119=(a119*a100);
  a110=(a042*a110);
  a110=(a119+a110);
  a015=(a015+a110);
  a096=(a049*a096);
  a095=(a095*a048);
  a096=(a096-a095);
  a015=(a015-a096);
  a096=(a004*a015);
  a149=(a149+a096);
  a149=(a056*a149);
  a096=(a004*a149);
  a029=(a029+a096);
  a029=(a029+a015);
  if (res[1]!=0) res[1][15]=a029;
  a137=(a004*a137);
  a137=(a137+a020);
  a020=(a008*a149);
  a137=(a137+a020);
  a015=(a000*a015);
  a020=(a013*a015);
  a020=(a129+a020);
  a137=(a137-a020);
  if (res[1]!=0) res[1][16]=a137;
  a099=(a004*a099);
  a024=(a024-a099);
  a149=(a013*a149);
  a149=(a127+a149);
  a024=(a024+a149);
  a015=(a008*a015);
  a024=(a024+a015);
  if (res[1]!=0) res[1][17]=a024;
  if (res[1]!=0) res[1][18]=a071;
  if (res[1]!=0) res[1][19]=a083;
  if (res[1]!=0) res[1][20]=a086;
  a084=(a000*a084);
  a084=(a028+a084);
  a084=(2.*a084);
  a044=(a044*a084);
  a044=(a000*a044);
  a084=(a023*a044);
  a082=(a082+a084);
  a094=(a094-a082);
  a094=(a094/a001);
  a082=(a002*a094);
  a082=(a082-a098);
  a090=(a090+a082);
  a044=(a053*a044);
  a045=(a045+a044);
  a045=(a045-a103);
  a045=(a045/a001);
  a103=(a018*a045);
  a102=(a102+a103);
  a090=(a090-a102);
  a090=(a001*a090);
  a102=(a018*a094);
  a106=(a106+a102);
  a106=(a106-a108);
  a108=(a002*a045);
  a108=(a108-a111);
  a106=(a106+a108);
  a106=(a001*a106);
  a108=(a000*a106);
  a111=(a004*a108);
  a111=(a105+a111);
  a111=(a090-a111);
  a102=(a013*a106);
  a103=(a008*a090);
  a102=(a102+a103);
  a094=(a042*a094);
  a094=(a094-a116);
  a088=(a088-a094);
  a045=(a049*a045);
  a045=(a045-a117);
  a088=(a088+a045);
  a088=(a001*a088);
  a045=(a004*a088);
  a115=(a115+a045);
  a102=(a102+a115);
  a102=(a056*a102);
  a115=(a008*a102);
  a111=(a111+a115);
  a115=(a000*a088);
  a045=(a013*a115);
  a111=(a111+a045);
  a045=(a002*a111);
  a045=(a045-a121);
  a108=(a008*a108);
  a090=(a000*a090);
  a121=(a013*a090);
  a108=(a108-a121);
  a121=(a004*a102);
  a121=(a124+a121);
  a108=(a108+a121);
  a108=(a108+a088);
  a088=(a042*a108);
  a088=(a088-a104);
  a045=(a045-a088);
  a090=(a004*a090);
  a090=(a126+a090);
  a106=(a106+a090);
  a102=(a013*a102);
  a106=(a106+a102);
  a115=(a008*a115);
  a106=(a106-a115);
  a115=(a018*a106);
  a114=(a114+a115);
  a045=(a045+a114);
  a114=(a000*a045);
  a115=(a013*a114);
  a102=(a049*a108);
  a102=(a102-a043);
  a043=(a018*a111);
  a101=(a101+a043);
  a102=(a102-a101);
  a101=(a002*a106);
  a101=(a101-a122);
  a102=(a102+a101);
  a101=(a000*a102);
  a122=(a008*a101);
  a115=(a115-a122);
  a122=(a013*a102);
  a043=(a008*a045);
  a122=(a122+a043);
  a108=(a002*a108);
  a108=(a108-a064);
  a111=(a042*a111);
  a111=(a111-a093);
  a108=(a108+a111);
  a106=(a049*a106);
  a106=(a106-a109);
  a108=(a108-a106);
  a106=(a004*a108);
  a131=(a131+a106);
  a122=(a122+a131);
  a122=(a056*a122);
  a131=(a004*a122);
  a131=(a127+a131);
  a115=(a115+a131);
  a115=(a115+a108);
  if (res[1]!=0) res[1][21]=a115;
  a101=(a004*a101);
  a101=(a113+a101);
  a101=(a101+a045);
  a045=(a008*a122);
  a101=(a101+a045);
  a108=(a000*a108);
  a045=(a013*a108);
  a101=(a101-a045);
  if (res[1]!=0) res[1][22]=a101;
  a114=(a004*a114);
  a114=(a050+a114);
  a102=(a102-a114);
  a122=(a013*a122);
  a102=(a102+a122);
  a108=(a008*a108);
  a102=(a102+a108);
  if (res[1]!=0) res[1][23]=a102;
  if (res[1]!=0) res[1][24]=a118;
  if (res[1]!=0) res[1][25]=a107;
  if (res[1]!=0) res[1][26]=a075;
  a091=(a000*a091);
  a091=(a028+a091);
  a091=(2.*a091);
  a057=(a057*a091);
  a057=(a000*a057);
  a091=(a023*a057);
  a133=(a133+a091);
  a133=(a133-a135);
  a133=(a133/a001);
  a135=(a042*a133);
  a135=(a135-a139);
  a135=(a135+a112);
  a057=(a039*a057);
  a132=(a132+a057);
  a141=(a141-a132);
  a141=(a141/a001);
  a132=(a018*a141);
  a132=(a132-a143);
  a135=(a135-a132);
  a135=(a001*a135);
  a132=(a049*a133);
  a145=(a145+a132);
  a136=(a136-a145);
  a145=(a002*a141);
  a145=(a145-a148);
  a136=(a136+a145);
  a136=(a001*a136);
  a145=(a000*a136);
  a148=(a004*a145);
  a148=(a135-a148);
  a132=(a013*a136);
  a143=(a008*a135);
  a120=(a120+a143);
  a132=(a132+a120);
  a133=(a002*a133);
  a133=(a133-a151);
  a133=(a133-a140);
  a141=(a049*a141);
  a152=(a152+a141);
  a133=(a133+a152);
  a133=(a001*a133);
  a152=(a004*a133);
  a132=(a132+a152);
  a132=(a056*a132);
  a152=(a008*a132);
  a152=(a124+a152);
  a148=(a148+a152);
  a152=(a000*a133);
  a141=(a013*a152);
  a148=(a148+a141);
  a141=(a002*a148);
  a141=(a141-a154);
  a145=(a008*a145);
  a105=(a105+a145);
  a135=(a000*a135);
  a145=(a013*a135);
  a105=(a105-a145);
  a145=(a004*a132);
  a105=(a105+a145);
  a105=(a105+a133);
  a133=(a042*a105);
  a133=(a133-a155);
  a141=(a141-a133);
  a135=(a004*a135);
  a136=(a136+a135);
  a132=(a013*a132);
  a136=(a136+a132);
  a152=(a008*a152);
  a152=(a123+a152);
  a136=(a136-a152);
  a152=(a018*a136);
  a152=(a152-a150);
  a141=(a141+a152);
  a152=(a000*a141);
  a150=(a013*a152);
  a132=(a049*a105);
  a134=(a134+a132);
  a132=(a018*a148);
  a132=(a132-a142);
  a134=(a134-a132);
  a132=(a002*a136);
  a132=(a132-a158);
  a134=(a134+a132);
  a132=(a000*a134);
  a158=(a008*a132);
  a113=(a113+a158);
  a150=(a150-a113);
  a113=(a013*a134);
  a158=(a008*a141);
  a128=(a128+a158);
  a113=(a113+a128);
  a105=(a002*a105);
  a105=(a105-a130);
  a148=(a042*a148);
  a148=(a148-a138);
  a105=(a105+a148);
  a136=(a049*a136);
  a144=(a144+a136);
  a105=(a105-a144);
  a144=(a004*a105);
  a113=(a113+a144);
  a113=(a056*a113);
  a144=(a004*a113);
  a150=(a150+a144);
  a150=(a150+a105);
  if (res[1]!=0) res[1][27]=a150;
  a132=(a004*a132);
  a132=(a132+a141);
  a141=(a008*a113);
  a141=(a127+a141);
  a132=(a132+a141);
  a105=(a000*a105);
  a141=(a013*a105);
  a132=(a132-a141);
  if (res[1]!=0) res[1][28]=a132;
  a152=(a004*a152);
  a134=(a134-a152);
  a113=(a013*a113);
  a134=(a134+a113);
  a105=(a008*a105);
  a105=(a129+a105);
  a134=(a134+a105);
  if (res[1]!=0) res[1][29]=a134;
  if (res[1]!=0) res[1][30]=a147;
  if (res[1]!=0) res[1][31]=a051;
  if (res[1]!=0) res[1][32]=a032;
  a021=(a000*a021);
  a028=(a028+a021);
  a028=(2.*a028);
  a031=(a031*a028);
  a031=(a000*a031);
  a028=(a053*a031);
  a156=(a156+a028);
  a027=(a027-a156);
  a027=(a027/a001);
  a156=(a042*a027);
  a016=(a016+a156);
  a031=(a039*a031);
  a014=(a014+a031);
  a014=(a014-a070);
  a014=(a014/a001);
  a070=(a002*a014);
  a070=(a070-a159);
  a016=(a016+a070);
  a016=(a016-a009);
  a016=(a001*a016);
  a009=(a018*a014);
  a009=(a009-a007);
  a007=(a049*a027);
  a007=(a007-a054);
  a009=(a009-a007);
  a009=(a009+a025);
  a009=(a001*a009);
  a025=(a000*a009);
  a007=(a004*a025);
  a007=(a016-a007);
  a054=(a013*a009);
  a087=(a087+a054);
  a054=(a008*a016);
  a087=(a087+a054);
  a027=(a002*a027);
  a027=(a027-a092);
  a014=(a042*a014);
  a097=(a097+a014);
  a027=(a027-a097);
  a027=(a027+a005);
  a001=(a001*a027);
  a027=(a004*a001);
  a087=(a087+a027);
  a087=(a056*a087);
  a027=(a008*a087);
  a007=(a007+a027);
  a027=(a000*a001);
  a005=(a013*a027);
  a123=(a123+a005);
  a007=(a007+a123);
  a123=(a002*a007);
  a123=(a123-a035);
  a025=(a008*a025);
  a016=(a000*a016);
  a035=(a013*a016);
  a126=(a126+a035);
  a025=(a025-a126);
  a126=(a004*a087);
  a025=(a025+a126);
  a025=(a025+a001);
  a001=(a042*a025);
  a153=(a153+a001);
  a123=(a123-a153);
  a016=(a004*a016);
  a009=(a009+a016);
  a087=(a013*a087);
  a124=(a124+a087);
  a009=(a009+a124);
  a027=(a008*a027);
  a009=(a009-a027);
  a027=(a018*a009);
  a027=(a027-a157);
  a123=(a123+a027);
  a027=(a000*a123);
  a157=(a013*a027);
  a050=(a050+a157);
  a157=(a049*a025);
  a157=(a157-a010);
  a010=(a018*a007);
  a010=(a010-a017);
  a157=(a157-a010);
  a010=(a002*a009);
  a010=(a010-a146);
  a157=(a157+a010);
  a010=(a000*a157);
  a146=(a008*a010);
  a050=(a050-a146);
  a146=(a013*a157);
  a019=(a019+a146);
  a146=(a008*a123);
  a019=(a019+a146);
  a025=(a002*a025);
  a025=(a025-a125);
  a007=(a042*a007);
  a119=(a119+a007);
  a025=(a025+a119);
  a009=(a049*a009);
  a009=(a009-a095);
  a025=(a025-a009);
  a009=(a004*a025);
  a019=(a019+a009);
  a019=(a056*a019);
  a009=(a004*a019);
  a050=(a050+a009);
  a050=(a050+a025);
  if (res[1]!=0) res[1][33]=a050;
  a010=(a004*a010);
  a010=(a010+a123);
  a123=(a008*a019);
  a010=(a010+a123);
  a025=(a000*a025);
  a123=(a013*a025);
  a129=(a129+a123);
  a010=(a010-a129);
  if (res[1]!=0) res[1][34]=a010;
  a027=(a004*a027);
  a157=(a157-a027);
  a019=(a013*a019);
  a127=(a127+a019);
  a157=(a157+a127);
  a025=(a008*a025);
  a157=(a157+a025);
  if (res[1]!=0) res[1][35]=a157;
  a157=(a006*a077);
  a025=(a055*a072);
  a157=(a157-a025);
  a157=(a046*a157);
  a025=(a006*a080);
  a127=(a055*a078);
  a025=(a025-a127);
  a025=(a079*a025);
  a157=(a157+a025);
  a059=(a023*a059);
  a157=(a157+a059);
  if (res[2]!=0) res[2][0]=a157;
  a157=(a026*a077);
  a059=(a030*a072);
  a157=(a157-a059);
  a157=(a076*a157);
  a059=(a026*a080);
  a025=(a030*a078);
  a059=(a059-a025);
  a059=(a085*a059);
  a157=(a157+a059);
  a040=(a039*a040);
  a157=(a157+a040);
  if (res[2]!=0) res[2][1]=a157;
  a157=(a033*a077);
  a040=(a036*a072);
  a157=(a157-a040);
  a157=(a081*a157);
  a040=(a033*a080);
  a059=(a036*a078);
  a040=(a040-a059);
  a040=(a089*a040);
  a157=(a157+a040);
  a034=(a053*a034);
  a157=(a157+a034);
  if (res[2]!=0) res[2][2]=a157;
  a157=(a000*a058);
  a034=(a013*a157);
  a040=(a000*a061);
  a059=(a008*a040);
  a034=(a034-a059);
  a059=(a013*a061);
  a025=(a008*a058);
  a059=(a059+a025);
  a025=(a004*a066);
  a059=(a059+a025);
  a059=(a056*a059);
  a025=(a004*a059);
  a034=(a034+a025);
  a034=(a034+a066);
  if (res[2]!=0) res[2][3]=a034;
  a040=(a004*a040);
  a040=(a040+a058);
  a058=(a008*a059);
  a040=(a040+a058);
  a066=(a000*a066);
  a058=(a013*a066);
  a040=(a040-a058);
  if (res[2]!=0) res[2][4]=a040;
  a157=(a004*a157);
  a061=(a061-a157);
  a059=(a013*a059);
  a061=(a061+a059);
  a066=(a008*a066);
  a061=(a061+a066);
  if (res[2]!=0) res[2][5]=a061;
  a061=(a055*a067);
  a066=(a052*a077);
  a061=(a061-a066);
  a061=(a046*a061);
  a055=(a055*a012);
  a066=(a052*a080);
  a055=(a055-a066);
  a055=(a079*a055);
  a061=(a061+a055);
  a062=(a023*a062);
  a061=(a061+a062);
  if (res[2]!=0) res[2][6]=a061;
  a061=(a030*a067);
  a062=(a022*a077);
  a061=(a061-a062);
  a061=(a076*a061);
  a030=(a030*a012);
  a062=(a022*a080);
  a030=(a030-a062);
  a030=(a085*a030);
  a061=(a061+a030);
  a060=(a039*a060);
  a061=(a061+a060);
  if (res[2]!=0) res[2][7]=a061;
  a061=(a036*a067);
  a077=(a038*a077);
  a061=(a061-a077);
  a061=(a081*a061);
  a036=(a036*a012);
  a080=(a038*a080);
  a036=(a036-a080);
  a036=(a089*a036);
  a061=(a061+a036);
  a041=(a053*a041);
  a061=(a061+a041);
  if (res[2]!=0) res[2][8]=a061;
  a061=(a000*a068);
  a041=(a013*a061);
  a036=(a000*a065);
  a080=(a008*a036);
  a041=(a041-a080);
  a080=(a013*a065);
  a077=(a008*a068);
  a080=(a080+a077);
  a077=(a004*a069);
  a080=(a080+a077);
  a080=(a056*a080);
  a077=(a004*a080);
  a041=(a041+a077);
  a041=(a041+a069);
  if (res[2]!=0) res[2][9]=a041;
  a036=(a004*a036);
  a036=(a036+a068);
  a068=(a008*a080);
  a036=(a036+a068);
  a069=(a000*a069);
  a068=(a013*a069);
  a036=(a036-a068);
  if (res[2]!=0) res[2][10]=a036;
  a061=(a004*a061);
  a065=(a065-a061);
  a080=(a013*a080);
  a065=(a065+a080);
  a069=(a008*a069);
  a065=(a065+a069);
  if (res[2]!=0) res[2][11]=a065;
  a065=(a052*a072);
  a069=(a006*a067);
  a065=(a065-a069);
  a046=(a046*a065);
  a052=(a052*a078);
  a006=(a006*a012);
  a052=(a052-a006);
  a079=(a079*a052);
  a046=(a046+a079);
  a023=(a023*a074);
  a046=(a046+a023);
  if (res[2]!=0) res[2][12]=a046;
  a046=(a022*a072);
  a023=(a026*a067);
  a046=(a046-a023);
  a076=(a076*a046);
  a022=(a022*a078);
  a026=(a026*a012);
  a022=(a022-a026);
  a085=(a085*a022);
  a076=(a076+a085);
  a039=(a039*a047);
  a076=(a076+a039);
  if (res[2]!=0) res[2][13]=a076;
  a072=(a038*a072);
  a067=(a033*a067);
  a072=(a072-a067);
  a081=(a081*a072);
  a038=(a038*a078);
  a033=(a033*a012);
  a038=(a038-a033);
  a089=(a089*a038);
  a081=(a081+a089);
  a053=(a053*a003);
  a081=(a081+a053);
  if (res[2]!=0) res[2][14]=a081;
  a081=(a000*a037);
  a053=(a013*a081);
  a003=(a000*a073);
  a089=(a008*a003);
  a053=(a053-a089);
  a089=(a013*a073);
  a038=(a008*a037);
  a089=(a089+a038);
  a038=(a004*a063);
  a089=(a089+a038);
  a089=(a056*a089);
  a038=(a004*a089);
  a053=(a053+a038);
  a053=(a053+a063);
  if (res[2]!=0) res[2][15]=a053;
  a003=(a004*a003);
  a003=(a003+a037);
  a037=(a008*a089);
  a003=(a003+a037);
  a063=(a000*a063);
  a037=(a013*a063);
  a003=(a003-a037);
  if (res[2]!=0) res[2][16]=a003;
  a081=(a004*a081);
  a073=(a073-a081);
  a089=(a013*a089);
  a073=(a073+a089);
  a063=(a008*a063);
  a073=(a073+a063);
  if (res[2]!=0) res[2][17]=a073;
  a073=0.;
  if (res[2]!=0) res[2][18]=a073;
  if (res[2]!=0) res[2][19]=a073;
  if (res[2]!=0) res[2][20]=a073;
  a063=(a013*a049);
  a089=(a008*a042);
  a063=(a063-a089);
  a089=(a004*a002);
  a063=(a063+a089);
  a063=(a056*a063);
  a089=(a004*a063);
  a081=(a000*a042);
  a003=(a013*a081);
  a037=(a000*a049);
  a053=(a008*a037);
  a038=(a003+a053);
  a089=(a089-a038);
  a089=(a089+a002);
  if (res[2]!=0) res[2][21]=a089;
  a089=(a004*a037);
  a089=(a089-a042);
  a038=(a008*a063);
  a089=(a089+a038);
  a038=(a000*a002);
  a033=(a013*a038);
  a089=(a089-a033);
  if (res[2]!=0) res[2][22]=a089;
  a089=(a004*a081);
  a089=(a049+a089);
  a063=(a013*a063);
  a089=(a089+a063);
  a063=(a008*a038);
  a089=(a089+a063);
  if (res[2]!=0) res[2][23]=a089;
  if (res[2]!=0) res[2][24]=a073;
  if (res[2]!=0) res[2][25]=a073;
  if (res[2]!=0) res[2][26]=a073;
  a000=(a000*a018);
  a089=(a008*a000);
  a033=(a033+a089);
  a089=(a008*a002);
  a012=(a013*a018);
  a089=(a089-a012);
  a012=(a004*a042);
  a089=(a089+a012);
  a089=(a056*a089);
  a012=(a004*a089);
  a033=(a033+a012);
  a033=(a033+a042);
  if (res[2]!=0) res[2][27]=a033;
  a033=(a004*a000);
  a033=(a002-a033);
  a042=(a008*a089);
  a042=(a033+a042);
  a042=(a042-a003);
  if (res[2]!=0) res[2][28]=a042;
  a089=(a013*a089);
  a038=(a004*a038);
  a042=(a018+a038);
  a089=(a089-a042);
  a081=(a008*a081);
  a089=(a089+a081);
  if (res[2]!=0) res[2][29]=a089;
  if (res[2]!=0) res[2][30]=a073;
  if (res[2]!=0) res[2][31]=a073;
  if (res[2]!=0) res[2][32]=a073;
  a000=(a013*a000);
  a000=(a000-a063);
  a002=(a013*a002);
  a063=(a008*a018);
  a002=(a002+a063);
  a063=(a004*a049);
  a002=(a002-a063);
  a056=(a056*a002);
  a004=(a004*a056);
  a000=(a000+a004);
  a000=(a000-a049);
  if (res[2]!=0) res[2][33]=a000;
  a038=(a038+a018);
  a008=(a008*a056);
  a038=(a038+a008);
  a037=(a013*a037);
  a038=(a038+a037);
  if (res[2]!=0) res[2][34]=a038;
  a013=(a013*a056);
  a033=(a033+a013);
  a033=(a033-a053);
  if (res[2]!=0) res[2][35]=a033;
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
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* step_partials_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    case 1: return casadi_s4;
    case 2: return casadi_s4;
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
#define HPGEN_NZ 6
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

HPGEN_EXPORT const char* hpgen_hash(void) { return "ace86d66f6af117c072f373783f17d2341e5676df083791d5d67c5ad6f67f369"; }

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

/* residual(z[6], g[9], p[3], h[1]) -> (F[6]) */
#define HPGEN_RESIDUAL_SZ_ARG 4
#define HPGEN_RESIDUAL_SZ_RES 1
#define HPGEN_RESIDUAL_SZ_IW 0
#define HPGEN_RESIDUAL_SZ_W 36
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

/* jacobian(z[6], g[9], p[3], h[1]) -> (J[36]) */
/* = output 1 of residual_jacobian (the same CasADi algorithm; its other outputs are
   computed into scratch and dropped) */
HPGEN_EXPORT int hpgen_kernel_jacobian(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    double scratch[HPGEN_NZ];
    return hpgen_k_residual_jacobian(in0, in1, in2, in3, scratch, out0);
}

/* residual_jacobian(z[6], g[9], p[3], h[1]) -> (F[6], J[36]) */
#define HPGEN_RESIDUAL_JACOBIAN_SZ_ARG 4
#define HPGEN_RESIDUAL_JACOBIAN_SZ_RES 2
#define HPGEN_RESIDUAL_JACOBIAN_SZ_IW 0
#define HPGEN_RESIDUAL_JACOBIAN_SZ_W 112
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

/* update(z[6], g[9], p[3], h[1]) -> (g1[9], p1[3]) */
#define HPGEN_UPDATE_SZ_ARG 4
#define HPGEN_UPDATE_SZ_RES 2
#define HPGEN_UPDATE_SZ_IW 0
#define HPGEN_UPDATE_SZ_W 32
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

/* guess(xi[3], g[9], p[3], h[1]) -> (z0[6]) */
#define HPGEN_GUESS_SZ_ARG 4
#define HPGEN_GUESS_SZ_RES 1
#define HPGEN_GUESS_SZ_IW 0
#define HPGEN_GUESS_SZ_W 3
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
#define HPGEN_LEGENDRE_SZ_W 4
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
#define HPGEN_ENERGY_SZ_W 10
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

/* margin(z[6], h[1]) -> (m[1]) */
#define HPGEN_MARGIN_SZ_ARG 2
#define HPGEN_MARGIN_SZ_RES 1
#define HPGEN_MARGIN_SZ_IW 0
#define HPGEN_MARGIN_SZ_W 7
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

/* chart_point(z[6], g[9], h[1], theta[1]) -> (g_theta[9]) */
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

/* update_p(z[6], g[9], p[3], h[1]) -> (p1[3]) */
#define HPGEN_UPDATE_P_SZ_ARG 4
#define HPGEN_UPDATE_P_SZ_RES 1
#define HPGEN_UPDATE_P_SZ_IW 0
#define HPGEN_UPDATE_P_SZ_W 32
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
#define HPGEN_RECORD_SZ_W 19
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

/* step_partials(z[6], g[9], p[3], h[1]) -> (Fs[36], Yz[36], Ys[36]) */
#define HPGEN_STEP_PARTIALS_SZ_ARG 4
#define HPGEN_STEP_PARTIALS_SZ_RES 3
#define HPGEN_STEP_PARTIALS_SZ_IW 0
#define HPGEN_STEP_PARTIALS_SZ_W 161
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
