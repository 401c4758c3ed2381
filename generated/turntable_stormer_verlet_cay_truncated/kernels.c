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
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43;
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
  a13=(a06/a13);
  a18=arg[2]? arg[2][0] : 0;
  a19=2.;
  a20=(a10/a19);
  a21=(a15*a00);
  a22=(a21/a06);
  a22=(a20+a22);
  a23=(a00/a19);
  a24=(a13*a23);
  a25=1.;
  a26=(a17+a12);
  a26=(a26/a19);
  a26=(a13*a26);
  a26=(a25-a26);
  a26=(a02*a26);
  a27=arg[1]? arg[1][5] : 0;
  a28=(a00*a10);
  a29=(a28/a19);
  a29=(a15+a29);
  a29=(a13*a29);
  a29=(a27*a29);
  a26=(a26+a29);
  a29=arg[1]? arg[1][8] : 0;
  a30=(a00*a15);
  a31=(a30/a19);
  a31=(a31-a10);
  a31=(a13*a31);
  a31=(a29*a31);
  a26=(a26+a31);
  a31=-7.4999999999999997e-02;
  a31=(a31*a04);
  a21=(a21/a19);
  a21=(a10+a21);
  a21=(a13*a21);
  a21=(a02*a21);
  a32=(a15*a10);
  a33=(a32/a19);
  a33=(a33-a00);
  a33=(a13*a33);
  a33=(a27*a33);
  a21=(a21+a33);
  a33=(a12+a08);
  a33=(a33/a19);
  a33=(a13*a33);
  a33=(a25-a33);
  a33=(a29*a33);
  a21=(a21+a33);
  a33=(a01*a21);
  a16=(a16+a33);
  a16=(2.*a16);
  a33=1.6666666666666666e-01;
  a33=(a33*a04);
  a16=(a16*a33);
  a34=(a01*a16);
  a34=(a31+a34);
  a35=(a26*a34);
  a36=-4.4999999999999998e-02;
  a36=(a36*a04);
  a37=(a01*a26);
  a07=(a07+a37);
  a07=(2.*a07);
  a07=(a07*a05);
  a37=(a01*a07);
  a37=(a36+a37);
  a38=(a21*a37);
  a35=(a35-a38);
  a35=(a35/a04);
  a38=(a24*a35);
  a39=(a13*a20);
  a40=2.9999999999999999e-02;
  a40=(a40*a04);
  a41=(a10*a00);
  a42=(a41/a19);
  a42=(a42-a15);
  a42=(a13*a42);
  a42=(a02*a42);
  a43=(a17+a08);
  a43=(a43/a19);
  a43=(a13*a43);
  a43=(a25-a43);
  a43=(a27*a43);
  a42=(a42+a43);
  a10=(a10*a15);
  a43=(a10/a19);
  a00=(a00+a43);
  a00=(a13*a00);
  a00=(a29*a00);
  a42=(a42+a00);
  a00=(a01*a42);
  a11=(a11+a00);
  a11=(2.*a11);
  a00=2.5000000000000000e-01;
  a00=(a00*a04);
  a11=(a11*a00);
  a43=(a01*a11);
  a43=(a40+a43);
  a21=(a21*a43);
  a34=(a42*a34);
  a21=(a21-a34);
  a21=(a21/a04);
  a34=(a39*a21);
  a38=(a38-a34);
  a42=(a42*a37);
  a26=(a26*a43);
  a42=(a42-a26);
  a42=(a42/a04);
  a26=(a13*a42);
  a38=(a38+a26);
  a38=(a04*a38);
  a22=(a22*a38);
  a41=(a41/a06);
  a15=(a15/a19);
  a41=(a41-a15);
  a19=(a13*a15);
  a26=(a19*a21);
  a43=(a13*a35);
  a26=(a26+a43);
  a43=(a24*a42);
  a26=(a26-a43);
  a26=(a04*a26);
  a41=(a41*a26);
  a22=(a22+a41);
  a08=(a08/a06);
  a08=(a25+a08);
  a21=(a13*a21);
  a35=(a19*a35);
  a21=(a21-a35);
  a42=(a39*a42);
  a21=(a21+a42);
  a21=(a04*a21);
  a08=(a08*a21);
  a22=(a22+a08);
  a08=(a01*a27);
  a09=(a09+a08);
  a09=(2.*a09);
  a09=(a09*a00);
  a00=(a01*a09);
  a40=(a40+a00);
  a00=(a29*a40);
  a08=(a01*a29);
  a14=(a14+a08);
  a14=(2.*a14);
  a14=(a14*a33);
  a33=(a01*a14);
  a31=(a31+a33);
  a33=(a27*a31);
  a00=(a00-a33);
  a22=(a22+a00);
  a18=(a18+a22);
  a22=(a13*a18);
  a00=arg[2]? arg[2][1] : 0;
  a32=(a32/a06);
  a32=(a32-a23);
  a32=(a32*a38);
  a12=(a12/a06);
  a12=(a25+a12);
  a12=(a12*a26);
  a32=(a32+a12);
  a28=(a28/a06);
  a15=(a15+a28);
  a15=(a15*a21);
  a32=(a32+a15);
  a31=(a02*a31);
  a15=(a01*a03);
  a36=(a36+a15);
  a29=(a29*a36);
  a31=(a31-a29);
  a32=(a32+a31);
  a00=(a00+a32);
  a32=(a19*a00);
  a22=(a22+a32);
  a32=arg[2]? arg[2][2] : 0;
  a17=(a17/a06);
  a25=(a25+a17);
  a25=(a25*a38);
  a10=(a10/a06);
  a23=(a23+a10);
  a23=(a23*a26);
  a25=(a25+a23);
  a30=(a30/a06);
  a30=(a30-a20);
  a30=(a30*a21);
  a25=(a25+a30);
  a27=(a27*a36);
  a02=(a02*a40);
  a27=(a27-a02);
  a25=(a25+a27);
  a32=(a32+a25);
  a25=(a39*a32);
  a22=(a22-a25);
  a22=(a04*a22);
  a22=(a01*a22);
  a21=(a04*a21);
  a21=(a01*a21);
  a22=(a22-a21);
  a03=(a03-a22);
  a03=(a03/a05);
  if (res[0]!=0) res[0][0]=a03;
  a03=(a13*a00);
  a19=(a19*a18);
  a03=(a03-a19);
  a19=(a24*a32);
  a03=(a03+a19);
  a03=(a04*a03);
  a03=(a01*a03);
  a26=(a04*a26);
  a26=(a01*a26);
  a03=(a03-a26);
  a09=(a09-a03);
  a09=(a09/a05);
  if (res[0]!=0) res[0][1]=a09;
  a39=(a39*a18);
  a24=(a24*a00);
  a39=(a39-a24);
  a13=(a13*a32);
  a39=(a39+a13);
  a39=(a04*a39);
  a39=(a01*a39);
  a04=(a04*a38);
  a01=(a01*a04);
  a39=(a39-a01);
  a14=(a14-a39);
  a14=(a14/a05);
  if (res[0]!=0) res[0][2]=a14;
  a07=(a07-a22);
  a07=(a07/a05);
  if (res[0]!=0) res[0][3]=a07;
  a11=(a11-a03);
  a11=(a11/a05);
  if (res[0]!=0) res[0][4]=a11;
  a16=(a16-a39);
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
  casadi_real a108, a109, a110, a111, a112, a113, a114, a115, a116, a117, a118, a119;
  casadi_real a120, a121, a122, a123, a124, a125, a126;
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
  a018=(a006/a013);
  a019=arg[2]? arg[2][0] : 0;
  a020=2.;
  a021=(a010/a020);
  a022=(a015*a000);
  a023=(a022/a006);
  a023=(a021+a023);
  a024=(a000/a020);
  a025=(a018*a024);
  a026=1.;
  a027=(a017+a012);
  a027=(a027/a020);
  a028=(a018*a027);
  a028=(a026-a028);
  a028=(a002*a028);
  a029=arg[1]? arg[1][5] : 0;
  a030=(a000*a010);
  a031=(a030/a020);
  a031=(a015+a031);
  a032=(a018*a031);
  a032=(a029*a032);
  a028=(a028+a032);
  a032=arg[1]? arg[1][8] : 0;
  a033=(a000*a015);
  a034=(a033/a020);
  a034=(a034-a010);
  a035=(a018*a034);
  a035=(a032*a035);
  a028=(a028+a035);
  a035=-7.4999999999999997e-02;
  a035=(a035*a004);
  a022=(a022/a020);
  a022=(a010+a022);
  a036=(a018*a022);
  a036=(a002*a036);
  a037=(a015*a010);
  a038=(a037/a020);
  a038=(a038-a000);
  a039=(a018*a038);
  a039=(a029*a039);
  a036=(a036+a039);
  a039=(a012+a008);
  a039=(a039/a020);
  a040=(a018*a039);
  a040=(a026-a040);
  a040=(a032*a040);
  a036=(a036+a040);
  a040=(a001*a036);
  a016=(a016+a040);
  a016=(2.*a016);
  a040=1.6666666666666666e-01;
  a040=(a040*a004);
  a016=(a016*a040);
  a041=(a001*a016);
  a041=(a035+a041);
  a042=(a028*a041);
  a043=-4.4999999999999998e-02;
  a043=(a043*a004);
  a044=(a001*a028);
  a007=(a007+a044);
  a007=(2.*a007);
  a007=(a007*a005);
  a044=(a001*a007);
  a044=(a043+a044);
  a045=(a036*a044);
  a042=(a042-a045);
  a042=(a042/a004);
  a045=(a025*a042);
  a046=(a018*a021);
  a047=2.9999999999999999e-02;
  a047=(a047*a004);
  a048=(a010*a000);
  a049=(a048/a020);
  a049=(a049-a015);
  a050=(a018*a049);
  a050=(a002*a050);
  a051=(a017+a008);
  a051=(a051/a020);
  a052=(a018*a051);
  a052=(a026-a052);
  a052=(a029*a052);
  a050=(a050+a052);
  a052=(a010*a015);
  a053=(a052/a020);
  a053=(a000+a053);
  a054=(a018*a053);
  a054=(a032*a054);
  a050=(a050+a054);
  a054=(a001*a050);
  a011=(a011+a054);
  a011=(2.*a011);
  a054=2.5000000000000000e-01;
  a055=(a054*a004);
  a011=(a011*a055);
  a056=(a001*a011);
  a056=(a047+a056);
  a057=(a036*a056);
  a058=(a050*a041);
  a057=(a057-a058);
  a057=(a057/a004);
  a058=(a046*a057);
  a045=(a045-a058);
  a058=(a050*a044);
  a059=(a028*a056);
  a058=(a058-a059);
  a058=(a058/a004);
  a059=(a018*a058);
  a045=(a045+a059);
  a045=(a004*a045);
  a059=(a023*a045);
  a048=(a048/a006);
  a020=(a015/a020);
  a048=(a048-a020);
  a060=(a018*a020);
  a061=(a060*a057);
  a062=(a018*a042);
  a061=(a061+a062);
  a062=(a025*a058);
  a061=(a061-a062);
  a061=(a004*a061);
  a062=(a048*a061);
  a059=(a059+a062);
  a008=(a008/a006);
  a008=(a026+a008);
  a062=(a018*a057);
  a063=(a060*a042);
  a062=(a062-a063);
  a063=(a046*a058);
  a062=(a062+a063);
  a062=(a004*a062);
  a063=(a008*a062);
  a059=(a059+a063);
  a063=(a001*a029);
  a009=(a009+a063);
  a009=(2.*a009);
  a009=(a009*a055);
  a063=(a001*a009);
  a047=(a047+a063);
  a063=(a032*a047);
  a064=(a001*a032);
  a014=(a014+a064);
  a014=(2.*a014);
  a014=(a014*a040);
  a064=(a001*a014);
  a035=(a035+a064);
  a064=(a029*a035);
  a063=(a063-a064);
  a059=(a059+a063);
  a019=(a019+a059);
  a059=(a018*a019);
  a063=arg[2]? arg[2][1] : 0;
  a037=(a037/a006);
  a037=(a037-a024);
  a064=(a037*a045);
  a012=(a012/a006);
  a012=(a026+a012);
  a065=(a012*a061);
  a064=(a064+a065);
  a030=(a030/a006);
  a030=(a020+a030);
  a065=(a030*a062);
  a064=(a064+a065);
  a035=(a002*a035);
  a065=(a001*a003);
  a043=(a043+a065);
  a065=(a032*a043);
  a035=(a035-a065);
  a064=(a064+a035);
  a063=(a063+a064);
  a064=(a060*a063);
  a059=(a059+a064);
  a064=arg[2]? arg[2][2] : 0;
  a017=(a017/a006);
  a017=(a026+a017);
  a035=(a017*a045);
  a052=(a052/a006);
  a052=(a024+a052);
  a065=(a052*a061);
  a035=(a035+a065);
  a033=(a033/a006);
  a033=(a033-a021);
  a006=(a033*a062);
  a035=(a035+a006);
  a043=(a029*a043);
  a047=(a002*a047);
  a043=(a043-a047);
  a035=(a035+a043);
  a064=(a064+a035);
  a035=(a046*a064);
  a059=(a059-a035);
  a059=(a004*a059);
  a059=(a001*a059);
  a035=(a004*a062);
  a035=(a001*a035);
  a059=(a059-a035);
  a003=(a003-a059);
  a003=(a003/a005);
  if (res[0]!=0) res[0][0]=a003;
  a003=(a018*a063);
  a035=(a060*a019);
  a003=(a003-a035);
  a035=(a025*a064);
  a003=(a003+a035);
  a003=(a004*a003);
  a003=(a001*a003);
  a035=(a004*a061);
  a035=(a001*a035);
  a003=(a003-a035);
  a009=(a009-a003);
  a009=(a009/a005);
  if (res[0]!=0) res[0][1]=a009;
  a009=(a046*a019);
  a035=(a025*a063);
  a009=(a009-a035);
  a035=(a018*a064);
  a009=(a009+a035);
  a009=(a004*a009);
  a009=(a001*a009);
  a035=(a004*a045);
  a035=(a001*a035);
  a009=(a009-a035);
  a014=(a014-a009);
  a014=(a014/a005);
  if (res[0]!=0) res[0][2]=a014;
  a007=(a007-a059);
  a007=(a007/a005);
  if (res[0]!=0) res[0][3]=a007;
  a011=(a011-a003);
  a011=(a011/a005);
  if (res[0]!=0) res[0][4]=a011;
  a016=(a016-a009);
  a016=(a016/a005);
  if (res[0]!=0) res[0][5]=a016;
  a016=(a015*a005);
  a009=(a054*a016);
  a011=(a045*a009);
  a003=(a018*a055);
  a013=(a018/a013);
  a007=(2.*a000);
  a007=(a007*a005);
  a059=(a013*a007);
  a014=(a024*a059);
  a014=(a003-a014);
  a035=(a042*a014);
  a043=(a027*a059);
  a043=(a002*a043);
  a047=(a010*a005);
  a006=(a001*a047);
  a006=(a018*a006);
  a065=(a031*a059);
  a065=(a006-a065);
  a065=(a029*a065);
  a043=(a043+a065);
  a016=(a001*a016);
  a016=(a018*a016);
  a065=(a034*a059);
  a065=(a016-a065);
  a065=(a032*a065);
  a043=(a043+a065);
  a065=(a041*a043);
  a066=(a022*a059);
  a066=(a016-a066);
  a066=(a002*a066);
  a067=(a038*a059);
  a068=(a018*a005);
  a067=(a067+a068);
  a067=(a029*a067);
  a066=(a066-a067);
  a067=(a001*a007);
  a067=(a018*a067);
  a069=(a039*a059);
  a069=(a067-a069);
  a069=(a032*a069);
  a066=(a066-a069);
  a069=(a040*a066);
  a070=(a001*a069);
  a071=(a028*a070);
  a065=(a065+a071);
  a071=(a044*a066);
  a072=(a005*a043);
  a073=(a001*a072);
  a074=(a036*a073);
  a074=(a071+a074);
  a074=(a065-a074);
  a074=(a074/a004);
  a075=(a025*a074);
  a075=(a035+a075);
  a066=(a056*a066);
  a076=(a049*a059);
  a076=(a006-a076);
  a076=(a002*a076);
  a077=(a051*a059);
  a067=(a067-a077);
  a067=(a029*a067);
  a076=(a076-a067);
  a067=(a053*a059);
  a067=(a068-a067);
  a067=(a032*a067);
  a076=(a076+a067);
  a067=(a055*a076);
  a077=(a001*a067);
  a078=(a036*a077);
  a066=(a066+a078);
  a078=(a041*a076);
  a070=(a050*a070);
  a078=(a078+a070);
  a066=(a066-a078);
  a066=(a066/a004);
  a078=(a046*a066);
  a070=(a021*a059);
  a079=(a057*a070);
  a078=(a078-a079);
  a075=(a075-a078);
  a076=(a044*a076);
  a073=(a050*a073);
  a073=(a076+a073);
  a079=(a056*a043);
  a077=(a028*a077);
  a079=(a079+a077);
  a073=(a073-a079);
  a073=(a073/a004);
  a077=(a018*a073);
  a080=(a058*a059);
  a077=(a077-a080);
  a075=(a075+a077);
  a075=(a004*a075);
  a077=(a023*a075);
  a077=(a011+a077);
  a047=(a054*a047);
  a081=(a061*a047);
  a082=(a060*a066);
  a083=(a020*a059);
  a084=(a057*a083);
  a082=(a082-a084);
  a084=(a018*a074);
  a085=(a042*a059);
  a084=(a084-a085);
  a084=(a082+a084);
  a086=(a058*a014);
  a087=(a025*a073);
  a087=(a086+a087);
  a084=(a084-a087);
  a084=(a004*a084);
  a087=(a048*a084);
  a087=(a081+a087);
  a077=(a077+a087);
  a007=(a054*a007);
  a007=(a062*a007);
  a066=(a018*a066);
  a087=(a057*a059);
  a066=(a066-a087);
  a074=(a060*a074);
  a087=(a042*a083);
  a074=(a074-a087);
  a074=(a066-a074);
  a073=(a046*a073);
  a088=(a058*a070);
  a073=(a073-a088);
  a074=(a074+a073);
  a074=(a004*a074);
  a073=(a008*a074);
  a073=(a007+a073);
  a077=(a077+a073);
  a073=(a018*a077);
  a089=(a019*a059);
  a073=(a073-a089);
  a090=(a037*a075);
  a091=(a045*a055);
  a090=(a090-a091);
  a092=(a012*a084);
  a090=(a090+a092);
  a092=(a062*a047);
  a093=(a030*a074);
  a093=(a092+a093);
  a090=(a090+a093);
  a093=(a032*a005);
  a090=(a090-a093);
  a093=(a060*a090);
  a094=(a063*a083);
  a093=(a093-a094);
  a073=(a073+a093);
  a093=(a017*a075);
  a095=(a061*a055);
  a096=(a052*a084);
  a096=(a095+a096);
  a093=(a093+a096);
  a096=(a062*a009);
  a097=(a033*a074);
  a097=(a096+a097);
  a093=(a093+a097);
  a097=(a029*a005);
  a093=(a093+a097);
  a097=(a046*a093);
  a098=(a064*a070);
  a097=(a097-a098);
  a073=(a073-a097);
  a073=(a004*a073);
  a073=(a001*a073);
  a074=(a004*a074);
  a074=(a001*a074);
  a073=(a073-a074);
  a074=(a004-a073);
  a074=(a074/a005);
  if (res[1]!=0) res[1][0]=a074;
  a074=(a018*a090);
  a097=(a063*a059);
  a074=(a074-a097);
  a099=(a060*a077);
  a083=(a019*a083);
  a099=(a099-a083);
  a074=(a074-a099);
  a099=(a064*a014);
  a100=(a025*a093);
  a100=(a099+a100);
  a074=(a074+a100);
  a074=(a004*a074);
  a074=(a001*a074);
  a084=(a004*a084);
  a084=(a001*a084);
  a074=(a074-a084);
  a084=(a074/a005);
  a084=(-a084);
  if (res[1]!=0) res[1][1]=a084;
  a077=(a046*a077);
  a070=(a019*a070);
  a077=(a077-a070);
  a014=(a063*a014);
  a090=(a025*a090);
  a090=(a014+a090);
  a077=(a077-a090);
  a093=(a018*a093);
  a059=(a064*a059);
  a093=(a093-a059);
  a077=(a077+a093);
  a077=(a004*a077);
  a077=(a001*a077);
  a075=(a004*a075);
  a075=(a001*a075);
  a077=(a077-a075);
  a075=(a077/a005);
  a075=(-a075);
  if (res[1]!=0) res[1][2]=a075;
  a072=(a072-a073);
  a072=(a072/a005);
  if (res[1]!=0) res[1][3]=a072;
  a074=(a067-a074);
  a074=(a074/a005);
  if (res[1]!=0) res[1][4]=a074;
  a077=(a069-a077);
  a077=(a077/a005);
  if (res[1]!=0) res[1][5]=a077;
  a000=(a000*a005);
  a077=(a001*a000);
  a077=(a018*a077);
  a010=(2.*a010);
  a010=(a010*a005);
  a074=(a013*a010);
  a072=(a031*a074);
  a072=(a077-a072);
  a072=(a029*a072);
  a073=(a001*a010);
  a073=(a018*a073);
  a075=(a027*a074);
  a075=(a073-a075);
  a075=(a002*a075);
  a072=(a072-a075);
  a075=(a034*a074);
  a075=(a075+a068);
  a075=(a032*a075);
  a072=(a072-a075);
  a075=(a041*a072);
  a093=(a022*a074);
  a093=(a068-a093);
  a093=(a002*a093);
  a090=(a038*a074);
  a090=(a016-a090);
  a090=(a029*a090);
  a093=(a093+a090);
  a090=(a039*a074);
  a073=(a073-a090);
  a073=(a032*a073);
  a093=(a093-a073);
  a073=(a040*a093);
  a090=(a001*a073);
  a084=(a028*a090);
  a075=(a075+a084);
  a084=(a044*a093);
  a100=(a005*a072);
  a101=(a001*a100);
  a102=(a036*a101);
  a084=(a084+a102);
  a075=(a075-a084);
  a075=(a075/a004);
  a084=(a025*a075);
  a102=(a024*a074);
  a103=(a042*a102);
  a084=(a084-a103);
  a103=(a021*a074);
  a103=(a003-a103);
  a104=(a057*a103);
  a093=(a056*a093);
  a105=(a049*a074);
  a105=(a077-a105);
  a105=(a002*a105);
  a106=(a051*a074);
  a106=(a029*a106);
  a105=(a105+a106);
  a106=(a053*a074);
  a016=(a016-a106);
  a016=(a032*a016);
  a105=(a105+a016);
  a016=(a055*a105);
  a106=(a001*a016);
  a107=(a036*a106);
  a107=(a093+a107);
  a108=(a041*a105);
  a090=(a050*a090);
  a108=(a108+a090);
  a107=(a107-a108);
  a107=(a107/a004);
  a090=(a046*a107);
  a090=(a104+a090);
  a090=(a084-a090);
  a109=(a044*a105);
  a101=(a050*a101);
  a109=(a109+a101);
  a072=(a056*a072);
  a106=(a028*a106);
  a106=(a072+a106);
  a106=(a109-a106);
  a106=(a106/a004);
  a101=(a018*a106);
  a110=(a058*a074);
  a101=(a101-a110);
  a090=(a090+a101);
  a090=(a004*a090);
  a101=(a023*a090);
  a101=(a091+a101);
  a000=(a054*a000);
  a111=(a061*a000);
  a112=(a060*a107);
  a113=(a020*a074);
  a114=(a057*a113);
  a112=(a112-a114);
  a115=(a018*a075);
  a116=(a042*a074);
  a115=(a115-a116);
  a112=(a112+a115);
  a116=(a025*a106);
  a117=(a058*a102);
  a116=(a116-a117);
  a112=(a112-a116);
  a112=(a004*a112);
  a116=(a048*a112);
  a116=(a111+a116);
  a101=(a101+a116);
  a107=(a018*a107);
  a116=(a057*a074);
  a107=(a107-a116);
  a075=(a060*a075);
  a118=(a042*a113);
  a075=(a075-a118);
  a107=(a107-a075);
  a118=(a058*a103);
  a106=(a046*a106);
  a106=(a118+a106);
  a107=(a107+a106);
  a107=(a004*a107);
  a106=(a008*a107);
  a101=(a101+a106);
  a106=(a032*a055);
  a101=(a101+a106);
  a106=(a018*a101);
  a119=(a019*a074);
  a106=(a106-a119);
  a120=(a037*a090);
  a120=(a011+a120);
  a010=(a054*a010);
  a010=(a061*a010);
  a121=(a012*a112);
  a121=(a010+a121);
  a120=(a120+a121);
  a121=(a062*a000);
  a122=(a030*a107);
  a122=(a121+a122);
  a120=(a120+a122);
  a122=(a060*a120);
  a123=(a063*a113);
  a122=(a122-a123);
  a106=(a106+a122);
  a122=(a064*a103);
  a124=(a017*a090);
  a061=(a061*a009);
  a009=(a052*a112);
  a009=(a061+a009);
  a124=(a124+a009);
  a009=(a033*a107);
  a062=(a062*a055);
  a009=(a009-a062);
  a124=(a124+a009);
  a009=(a002*a055);
  a124=(a124-a009);
  a009=(a046*a124);
  a009=(a122+a009);
  a106=(a106-a009);
  a106=(a004*a106);
  a106=(a001*a106);
  a107=(a004*a107);
  a107=(a001*a107);
  a106=(a106-a107);
  a107=(a106/a005);
  a107=(-a107);
  if (res[1]!=0) res[1][6]=a107;
  a107=(a018*a120);
  a009=(a063*a074);
  a107=(a107-a009);
  a125=(a060*a101);
  a113=(a019*a113);
  a125=(a125-a113);
  a107=(a107-a125);
  a125=(a025*a124);
  a126=(a064*a102);
  a125=(a125-a126);
  a107=(a107+a125);
  a107=(a004*a107);
  a107=(a001*a107);
  a112=(a004*a112);
  a112=(a001*a112);
  a107=(a107-a112);
  a112=(a005-a107);
  a112=(a112/a005);
  if (res[1]!=0) res[1][7]=a112;
  a103=(a019*a103);
  a101=(a046*a101);
  a101=(a103+a101);
  a120=(a025*a120);
  a102=(a063*a102);
  a120=(a120-a102);
  a101=(a101-a120);
  a124=(a018*a124);
  a074=(a064*a074);
  a124=(a124-a074);
  a101=(a101+a124);
  a101=(a004*a101);
  a101=(a001*a101);
  a090=(a004*a090);
  a090=(a001*a090);
  a101=(a101-a090);
  a090=(a101/a005);
  a090=(-a090);
  if (res[1]!=0) res[1][8]=a090;
  a106=(a100-a106);
  a106=(a106/a005);
  if (res[1]!=0) res[1][9]=a106;
  a016=(a016-a107);
  a016=(a016/a005);
  if (res[1]!=0) res[1][10]=a016;
  a101=(a073-a101);
  a101=(a101/a005);
  if (res[1]!=0) res[1][11]=a101;
  a000=(a045*a000);
  a015=(2.*a015);
  a015=(a015*a005);
  a013=(a013*a015);
  a031=(a031*a013);
  a031=(a068-a031);
  a031=(a029*a031);
  a101=(a001*a015);
  a101=(a018*a101);
  a027=(a027*a013);
  a027=(a101-a027);
  a027=(a002*a027);
  a031=(a031-a027);
  a034=(a034*a013);
  a034=(a077-a034);
  a034=(a032*a034);
  a031=(a031+a034);
  a034=(a041*a031);
  a022=(a022*a013);
  a077=(a077-a022);
  a077=(a002*a077);
  a038=(a038*a013);
  a038=(a006-a038);
  a038=(a029*a038);
  a077=(a077+a038);
  a039=(a039*a013);
  a039=(a032*a039);
  a077=(a077+a039);
  a039=(a040*a077);
  a038=(a001*a039);
  a022=(a028*a038);
  a022=(a034+a022);
  a027=(a044*a077);
  a016=(a005*a031);
  a107=(a001*a016);
  a106=(a036*a107);
  a027=(a027+a106);
  a022=(a022-a027);
  a022=(a022/a004);
  a106=(a025*a022);
  a024=(a024*a013);
  a090=(a042*a024);
  a106=(a106-a090);
  a124=(a056*a077);
  a053=(a053*a013);
  a006=(a006-a053);
  a032=(a032*a006);
  a049=(a049*a013);
  a049=(a049+a068);
  a049=(a002*a049);
  a051=(a051*a013);
  a101=(a101-a051);
  a101=(a029*a101);
  a049=(a049+a101);
  a032=(a032-a049);
  a049=(a055*a032);
  a101=(a001*a049);
  a051=(a036*a101);
  a124=(a124+a051);
  a041=(a041*a032);
  a038=(a050*a038);
  a038=(a041+a038);
  a038=(a124-a038);
  a038=(a038/a004);
  a051=(a046*a038);
  a021=(a021*a013);
  a068=(a057*a021);
  a051=(a051-a068);
  a106=(a106-a051);
  a044=(a044*a032);
  a107=(a050*a107);
  a044=(a044+a107);
  a056=(a056*a031);
  a101=(a028*a101);
  a056=(a056+a101);
  a044=(a044-a056);
  a044=(a044/a004);
  a056=(a018*a044);
  a101=(a058*a013);
  a056=(a056-a101);
  a106=(a106+a056);
  a106=(a004*a106);
  a101=(a023*a106);
  a101=(a000+a101);
  a020=(a020*a013);
  a003=(a003-a020);
  a020=(a057*a003);
  a031=(a060*a038);
  a031=(a020+a031);
  a107=(a018*a022);
  a032=(a042*a013);
  a107=(a107-a032);
  a031=(a031+a107);
  a107=(a025*a044);
  a051=(a058*a024);
  a107=(a107-a051);
  a031=(a031-a107);
  a031=(a004*a031);
  a051=(a048*a031);
  a051=(a051-a095);
  a101=(a101+a051);
  a038=(a018*a038);
  a057=(a057*a013);
  a038=(a038-a057);
  a042=(a042*a003);
  a022=(a060*a022);
  a022=(a042+a022);
  a038=(a038-a022);
  a044=(a046*a044);
  a058=(a058*a021);
  a044=(a044-a058);
  a038=(a038+a044);
  a038=(a004*a038);
  a058=(a008*a038);
  a101=(a101+a058);
  a029=(a029*a040);
  a101=(a101-a029);
  a029=(a018*a101);
  a058=(a019*a013);
  a029=(a029-a058);
  a022=(a063*a003);
  a047=(a045*a047);
  a051=(a037*a106);
  a051=(a047+a051);
  a006=(a012*a031);
  a051=(a051+a006);
  a006=(a030*a038);
  a006=(a062+a006);
  a051=(a051+a006);
  a002=(a002*a040);
  a051=(a051+a002);
  a002=(a060*a051);
  a002=(a022+a002);
  a029=(a029+a002);
  a054=(a054*a015);
  a045=(a045*a054);
  a054=(a017*a106);
  a054=(a045+a054);
  a015=(a052*a031);
  a015=(a081+a015);
  a054=(a054+a015);
  a015=(a033*a038);
  a015=(a121+a015);
  a054=(a054+a015);
  a015=(a046*a054);
  a002=(a064*a021);
  a015=(a015-a002);
  a029=(a029-a015);
  a029=(a004*a029);
  a029=(a001*a029);
  a038=(a004*a038);
  a038=(a001*a038);
  a029=(a029-a038);
  a038=(a029/a005);
  a038=(-a038);
  if (res[1]!=0) res[1][12]=a038;
  a038=(a018*a051);
  a015=(a063*a013);
  a038=(a038-a015);
  a003=(a019*a003);
  a006=(a060*a101);
  a006=(a003+a006);
  a038=(a038-a006);
  a006=(a025*a054);
  a053=(a064*a024);
  a006=(a006-a053);
  a038=(a038+a006);
  a038=(a004*a038);
  a038=(a001*a038);
  a031=(a004*a031);
  a031=(a001*a031);
  a038=(a038-a031);
  a031=(a038/a005);
  a031=(-a031);
  if (res[1]!=0) res[1][13]=a031;
  a031=3.3333333333333331e-01;
  a031=(a031*a004);
  a101=(a046*a101);
  a019=(a019*a021);
  a101=(a101-a019);
  a051=(a025*a051);
  a063=(a063*a024);
  a051=(a051-a063);
  a101=(a101-a051);
  a054=(a018*a054);
  a064=(a064*a013);
  a054=(a054-a064);
  a101=(a101+a054);
  a101=(a004*a101);
  a101=(a001*a101);
  a106=(a004*a106);
  a106=(a001*a106);
  a101=(a101-a106);
  a031=(a031-a101);
  a031=(a031/a005);
  if (res[1]!=0) res[1][14]=a031;
  a029=(a016-a029);
  a029=(a029/a005);
  if (res[1]!=0) res[1][15]=a029;
  a038=(a049-a038);
  a038=(a038/a005);
  if (res[1]!=0) res[1][16]=a038;
  a039=(a039-a101);
  a039=(a039/a005);
  if (res[1]!=0) res[1][17]=a039;
  a043=(a001*a043);
  a043=(a026+a043);
  a043=(2.*a043);
  a043=(a005*a043);
  a039=(a001*a043);
  a101=(a036*a039);
  a071=(a071+a101);
  a065=(a065-a071);
  a065=(a065/a004);
  a071=(a025*a065);
  a035=(a035+a071);
  a035=(a035-a078);
  a039=(a050*a039);
  a076=(a076+a039);
  a076=(a076-a079);
  a076=(a076/a004);
  a079=(a018*a076);
  a079=(a079-a080);
  a035=(a035+a079);
  a035=(a004*a035);
  a079=(a023*a035);
  a079=(a011+a079);
  a080=(a018*a065);
  a080=(a080-a085);
  a082=(a082+a080);
  a080=(a025*a076);
  a086=(a086+a080);
  a082=(a082-a086);
  a082=(a004*a082);
  a086=(a048*a082);
  a086=(a081+a086);
  a079=(a079+a086);
  a065=(a060*a065);
  a065=(a065-a087);
  a066=(a066-a065);
  a076=(a046*a076);
  a076=(a076-a088);
  a066=(a066+a076);
  a066=(a004*a066);
  a076=(a008*a066);
  a007=(a007+a076);
  a079=(a079+a007);
  a007=(a018*a079);
  a007=(a007-a089);
  a089=(a037*a035);
  a089=(a089-a091);
  a076=(a012*a082);
  a089=(a089+a076);
  a076=(a030*a066);
  a092=(a092+a076);
  a089=(a089+a092);
  a092=(a060*a089);
  a092=(a092-a094);
  a007=(a007+a092);
  a092=(a017*a035);
  a094=(a052*a082);
  a094=(a095+a094);
  a092=(a092+a094);
  a094=(a033*a066);
  a096=(a096+a094);
  a092=(a092+a096);
  a096=(a046*a092);
  a096=(a096-a098);
  a007=(a007-a096);
  a007=(a004*a007);
  a007=(a001*a007);
  a066=(a004*a066);
  a066=(a001*a066);
  a007=(a007-a066);
  a066=(a007/a005);
  a066=(-a066);
  if (res[1]!=0) res[1][18]=a066;
  a066=(a018*a089);
  a066=(a066-a097);
  a097=(a060*a079);
  a097=(a097-a083);
  a066=(a066-a097);
  a097=(a025*a092);
  a099=(a099+a097);
  a066=(a066+a099);
  a066=(a004*a066);
  a066=(a001*a066);
  a082=(a004*a082);
  a082=(a001*a082);
  a066=(a066-a082);
  a082=(a066/a005);
  a082=(-a082);
  if (res[1]!=0) res[1][19]=a082;
  a079=(a046*a079);
  a079=(a079-a070);
  a089=(a025*a089);
  a014=(a014+a089);
  a079=(a079-a014);
  a092=(a018*a092);
  a092=(a092-a059);
  a079=(a079+a092);
  a079=(a004*a079);
  a079=(a001*a079);
  a035=(a004*a035);
  a035=(a001*a035);
  a079=(a079-a035);
  a035=(a079/a005);
  a035=(-a035);
  if (res[1]!=0) res[1][20]=a035;
  a043=(a043-a007);
  a043=(a043/a005);
  if (res[1]!=0) res[1][21]=a043;
  a067=(a067-a066);
  a067=(a067/a005);
  if (res[1]!=0) res[1][22]=a067;
  a069=(a069-a079);
  a069=(a069/a005);
  if (res[1]!=0) res[1][23]=a069;
  a105=(a001*a105);
  a105=(a026+a105);
  a105=(2.*a105);
  a055=(a055*a105);
  a105=(a001*a055);
  a036=(a036*a105);
  a093=(a093+a036);
  a093=(a093-a108);
  a093=(a093/a004);
  a108=(a046*a093);
  a104=(a104+a108);
  a084=(a084-a104);
  a105=(a028*a105);
  a072=(a072+a105);
  a109=(a109-a072);
  a109=(a109/a004);
  a072=(a018*a109);
  a072=(a072-a110);
  a084=(a084+a072);
  a084=(a004*a084);
  a072=(a023*a084);
  a091=(a091+a072);
  a072=(a060*a093);
  a072=(a072-a114);
  a072=(a072+a115);
  a115=(a025*a109);
  a115=(a115-a117);
  a072=(a072-a115);
  a072=(a004*a072);
  a115=(a048*a072);
  a111=(a111+a115);
  a091=(a091+a111);
  a093=(a018*a093);
  a093=(a093-a116);
  a093=(a093-a075);
  a109=(a046*a109);
  a118=(a118+a109);
  a093=(a093+a118);
  a093=(a004*a093);
  a118=(a008*a093);
  a091=(a091+a118);
  a118=(a018*a091);
  a118=(a118-a119);
  a119=(a037*a084);
  a011=(a011+a119);
  a119=(a012*a072);
  a010=(a010+a119);
  a011=(a011+a010);
  a010=(a030*a093);
  a010=(a121+a010);
  a011=(a011+a010);
  a010=(a060*a011);
  a010=(a010-a123);
  a118=(a118+a010);
  a010=(a017*a084);
  a123=(a052*a072);
  a061=(a061+a123);
  a010=(a010+a061);
  a061=(a033*a093);
  a061=(a061-a062);
  a010=(a010+a061);
  a061=(a046*a010);
  a122=(a122+a061);
  a118=(a118-a122);
  a118=(a004*a118);
  a118=(a001*a118);
  a093=(a004*a093);
  a093=(a001*a093);
  a118=(a118-a093);
  a093=(a118/a005);
  a093=(-a093);
  if (res[1]!=0) res[1][24]=a093;
  a093=(a018*a011);
  a093=(a093-a009);
  a009=(a060*a091);
  a009=(a009-a113);
  a093=(a093-a009);
  a009=(a025*a010);
  a009=(a009-a126);
  a093=(a093+a009);
  a093=(a004*a093);
  a093=(a001*a093);
  a072=(a004*a072);
  a072=(a001*a072);
  a093=(a093-a072);
  a072=(a093/a005);
  a072=(-a072);
  if (res[1]!=0) res[1][25]=a072;
  a091=(a046*a091);
  a103=(a103+a091);
  a011=(a025*a011);
  a011=(a011-a102);
  a103=(a103-a011);
  a010=(a018*a010);
  a010=(a010-a074);
  a103=(a103+a010);
  a103=(a004*a103);
  a103=(a001*a103);
  a084=(a004*a084);
  a084=(a001*a084);
  a103=(a103-a084);
  a084=(a103/a005);
  a084=(-a084);
  if (res[1]!=0) res[1][26]=a084;
  a100=(a100-a118);
  a100=(a100/a005);
  if (res[1]!=0) res[1][27]=a100;
  a055=(a055-a093);
  a055=(a055/a005);
  if (res[1]!=0) res[1][28]=a055;
  a073=(a073-a103);
  a073=(a073/a005);
  if (res[1]!=0) res[1][29]=a073;
  a077=(a001*a077);
  a026=(a026+a077);
  a026=(2.*a026);
  a040=(a040*a026);
  a026=(a001*a040);
  a028=(a028*a026);
  a034=(a034+a028);
  a034=(a034-a027);
  a034=(a034/a004);
  a027=(a025*a034);
  a027=(a027-a090);
  a050=(a050*a026);
  a041=(a041+a050);
  a124=(a124-a041);
  a124=(a124/a004);
  a041=(a046*a124);
  a041=(a041-a068);
  a027=(a027-a041);
  a027=(a027+a056);
  a027=(a004*a027);
  a023=(a023*a027);
  a000=(a000+a023);
  a023=(a060*a124);
  a020=(a020+a023);
  a023=(a018*a034);
  a023=(a023-a032);
  a020=(a020+a023);
  a020=(a020-a107);
  a020=(a004*a020);
  a048=(a048*a020);
  a048=(a048-a095);
  a000=(a000+a048);
  a124=(a018*a124);
  a124=(a124-a057);
  a034=(a060*a034);
  a042=(a042+a034);
  a124=(a124-a042);
  a124=(a124+a044);
  a124=(a004*a124);
  a008=(a008*a124);
  a000=(a000+a008);
  a008=(a018*a000);
  a008=(a008-a058);
  a037=(a037*a027);
  a047=(a047+a037);
  a012=(a012*a020);
  a047=(a047+a012);
  a030=(a030*a124);
  a062=(a062+a030);
  a047=(a047+a062);
  a062=(a060*a047);
  a022=(a022+a062);
  a008=(a008+a022);
  a017=(a017*a027);
  a045=(a045+a017);
  a052=(a052*a020);
  a081=(a081+a052);
  a045=(a045+a081);
  a033=(a033*a124);
  a121=(a121+a033);
  a045=(a045+a121);
  a121=(a046*a045);
  a121=(a121-a002);
  a008=(a008-a121);
  a008=(a004*a008);
  a008=(a001*a008);
  a124=(a004*a124);
  a124=(a001*a124);
  a008=(a008-a124);
  a124=(a008/a005);
  a124=(-a124);
  if (res[1]!=0) res[1][30]=a124;
  a124=(a018*a047);
  a124=(a124-a015);
  a060=(a060*a000);
  a003=(a003+a060);
  a124=(a124-a003);
  a003=(a025*a045);
  a003=(a003-a053);
  a124=(a124+a003);
  a124=(a004*a124);
  a124=(a001*a124);
  a020=(a004*a020);
  a020=(a001*a020);
  a124=(a124-a020);
  a020=(a124/a005);
  a020=(-a020);
  if (res[1]!=0) res[1][31]=a020;
  a046=(a046*a000);
  a046=(a046-a019);
  a025=(a025*a047);
  a025=(a025-a063);
  a046=(a046-a025);
  a018=(a018*a045);
  a018=(a018-a064);
  a046=(a046+a018);
  a046=(a004*a046);
  a046=(a001*a046);
  a004=(a004*a027);
  a001=(a001*a004);
  a046=(a046-a001);
  a001=(a046/a005);
  a001=(-a001);
  if (res[1]!=0) res[1][32]=a001;
  a016=(a016-a008);
  a016=(a016/a005);
  if (res[1]!=0) res[1][33]=a016;
  a049=(a049-a124);
  a049=(a049/a005);
  if (res[1]!=0) res[1][34]=a049;
  a040=(a040-a046);
  a040=(a040/a005);
  if (res[1]!=0) res[1][35]=a040;
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
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41;
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
  a13=(a02/a13);
  a18=(a17+a12);
  a19=2.;
  a18=(a18/a19);
  a18=(a13*a18);
  a18=(a01-a18);
  a20=(a00*a18);
  a21=arg[1]? arg[1][3] : 0;
  a22=(a06*a10);
  a23=(a22/a19);
  a23=(a15+a23);
  a23=(a13*a23);
  a24=(a21*a23);
  a20=(a20+a24);
  a24=arg[1]? arg[1][6] : 0;
  a25=(a06*a15);
  a26=(a25/a19);
  a26=(a26-a10);
  a26=(a13*a26);
  a27=(a24*a26);
  a20=(a20+a27);
  if (res[0]!=0) res[0][0]=a20;
  a20=arg[1]? arg[1][1] : 0;
  a27=(a20*a18);
  a28=arg[1]? arg[1][4] : 0;
  a29=(a28*a23);
  a27=(a27+a29);
  a29=arg[1]? arg[1][7] : 0;
  a30=(a29*a26);
  a27=(a27+a30);
  if (res[0]!=0) res[0][1]=a27;
  a27=arg[1]? arg[1][2] : 0;
  a18=(a27*a18);
  a30=arg[1]? arg[1][5] : 0;
  a23=(a30*a23);
  a18=(a18+a23);
  a23=arg[1]? arg[1][8] : 0;
  a26=(a23*a26);
  a18=(a18+a26);
  if (res[0]!=0) res[0][2]=a18;
  a26=(a10*a06);
  a31=(a26/a19);
  a31=(a31-a15);
  a31=(a13*a31);
  a32=(a00*a31);
  a33=(a17+a08);
  a33=(a33/a19);
  a33=(a13*a33);
  a33=(a01-a33);
  a34=(a21*a33);
  a32=(a32+a34);
  a34=(a10*a15);
  a35=(a34/a19);
  a35=(a06+a35);
  a35=(a13*a35);
  a36=(a24*a35);
  a32=(a32+a36);
  if (res[0]!=0) res[0][3]=a32;
  a32=(a20*a31);
  a36=(a28*a33);
  a32=(a32+a36);
  a36=(a29*a35);
  a32=(a32+a36);
  if (res[0]!=0) res[0][4]=a32;
  a31=(a27*a31);
  a33=(a30*a33);
  a31=(a31+a33);
  a35=(a23*a35);
  a31=(a31+a35);
  if (res[0]!=0) res[0][5]=a31;
  a35=(a15*a06);
  a33=(a35/a19);
  a33=(a10+a33);
  a33=(a13*a33);
  a00=(a00*a33);
  a32=(a15*a10);
  a36=(a32/a19);
  a36=(a36-a06);
  a36=(a13*a36);
  a21=(a21*a36);
  a00=(a00+a21);
  a21=(a12+a08);
  a21=(a21/a19);
  a21=(a13*a21);
  a21=(a01-a21);
  a24=(a24*a21);
  a00=(a00+a24);
  if (res[0]!=0) res[0][6]=a00;
  a20=(a20*a33);
  a28=(a28*a36);
  a20=(a20+a28);
  a29=(a29*a21);
  a20=(a20+a29);
  if (res[0]!=0) res[0][7]=a20;
  a33=(a27*a33);
  a36=(a30*a36);
  a33=(a33+a36);
  a21=(a23*a21);
  a33=(a33+a21);
  if (res[0]!=0) res[0][8]=a33;
  a35=(a35/a02);
  a10=(a10/a19);
  a21=(a35-a10);
  a36=(a13*a10);
  a20=arg[2]? arg[2][0] : 0;
  a35=(a10+a35);
  a06=(a06/a19);
  a29=(a13*a06);
  a28=-7.4999999999999997e-02;
  a28=(a28*a03);
  a00=(a04*a33);
  a16=(a16+a00);
  a16=(2.*a16);
  a00=1.6666666666666666e-01;
  a00=(a00*a03);
  a16=(a16*a00);
  a16=(a04*a16);
  a16=(a28+a16);
  a24=(a18*a16);
  a37=-4.4999999999999998e-02;
  a37=(a37*a03);
  a38=(a04*a18);
  a07=(a07+a38);
  a07=(2.*a07);
  a38=(a04*a03);
  a07=(a07*a38);
  a07=(a04*a07);
  a07=(a37+a07);
  a39=(a33*a07);
  a24=(a24-a39);
  a24=(a24/a03);
  a39=(a29*a24);
  a40=2.9999999999999999e-02;
  a40=(a40*a03);
  a41=(a04*a31);
  a11=(a11+a41);
  a11=(2.*a11);
  a41=2.5000000000000000e-01;
  a41=(a41*a03);
  a11=(a11*a41);
  a11=(a04*a11);
  a11=(a40+a11);
  a33=(a33*a11);
  a16=(a31*a16);
  a33=(a33-a16);
  a33=(a33/a03);
  a16=(a36*a33);
  a39=(a39-a16);
  a31=(a31*a07);
  a18=(a18*a11);
  a31=(a31-a18);
  a31=(a31/a03);
  a18=(a13*a31);
  a39=(a39+a18);
  a39=(a03*a39);
  a35=(a35*a39);
  a26=(a26/a02);
  a15=(a15/a19);
  a19=(a26-a15);
  a18=(a13*a15);
  a11=(a18*a33);
  a07=(a13*a24);
  a11=(a11+a07);
  a07=(a29*a31);
  a11=(a11-a07);
  a11=(a03*a11);
  a19=(a19*a11);
  a35=(a35+a19);
  a08=(a08/a02);
  a08=(a01+a08);
  a33=(a13*a33);
  a24=(a18*a24);
  a33=(a33-a24);
  a31=(a36*a31);
  a33=(a33+a31);
  a03=(a03*a33);
  a33=(a08*a03);
  a35=(a35+a33);
  a33=(a04*a30);
  a09=(a09+a33);
  a09=(2.*a09);
  a09=(a09*a41);
  a09=(a04*a09);
  a40=(a40+a09);
  a09=(a23*a40);
  a41=(a04*a23);
  a14=(a14+a41);
  a14=(2.*a14);
  a14=(a14*a00);
  a14=(a04*a14);
  a28=(a28+a14);
  a14=(a30*a28);
  a09=(a09-a14);
  a35=(a35+a09);
  a20=(a20+a35);
  a35=(a36*a20);
  a09=arg[2]? arg[2][1] : 0;
  a32=(a32/a02);
  a14=(a32-a06);
  a14=(a14*a39);
  a12=(a12/a02);
  a12=(a01+a12);
  a00=(a12*a11);
  a14=(a14+a00);
  a22=(a22/a02);
  a00=(a15+a22);
  a00=(a00*a03);
  a14=(a14+a00);
  a28=(a27*a28);
  a00=(a04*a27);
  a05=(a05+a00);
  a05=(2.*a05);
  a05=(a05*a38);
  a04=(a04*a05);
  a37=(a37+a04);
  a23=(a23*a37);
  a28=(a28-a23);
  a14=(a14+a28);
  a09=(a09+a14);
  a14=(a29*a09);
  a35=(a35-a14);
  a14=arg[2]? arg[2][2] : 0;
  a17=(a17/a02);
  a01=(a01+a17);
  a39=(a01*a39);
  a34=(a34/a02);
  a17=(a06+a34);
  a17=(a17*a11);
  a39=(a39+a17);
  a25=(a25/a02);
  a02=(a25-a10);
  a02=(a02*a03);
  a39=(a39+a02);
  a30=(a30*a37);
  a27=(a27*a40);
  a30=(a30-a27);
  a39=(a39+a30);
  a14=(a14+a39);
  a39=(a13*a14);
  a35=(a35+a39);
  a21=(a21*a35);
  a26=(a15+a26);
  a39=(a13*a09);
  a30=(a18*a20);
  a39=(a39-a30);
  a29=(a29*a14);
  a39=(a39+a29);
  a26=(a26*a39);
  a21=(a21+a26);
  a13=(a13*a20);
  a18=(a18*a09);
  a13=(a13+a18);
  a36=(a36*a14);
  a13=(a13-a36);
  a08=(a08*a13);
  a21=(a21+a08);
  if (res[1]!=0) res[1][0]=a21;
  a32=(a06+a32);
  a32=(a32*a35);
  a12=(a12*a39);
  a32=(a32+a12);
  a22=(a22-a15);
  a22=(a22*a13);
  a32=(a32+a22);
  if (res[1]!=0) res[1][1]=a32;
  a01=(a01*a35);
  a34=(a34-a06);
  a34=(a34*a39);
  a01=(a01+a34);
  a10=(a10+a25);
  a10=(a10*a13);
  a01=(a01+a10);
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
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42;
  a00=arg[3]? arg[3][0] : 0;
  a01=5.0000000000000000e-01;
  a02=arg[0]? arg[0][2] : 0;
  a03=(a01*a02);
  a04=arg[0]? arg[0][5] : 0;
  a05=(a01*a04);
  a03=(a03+a05);
  a03=(a00*a03);
  a05=arg[0]? arg[0][0] : 0;
  a06=(a01*a05);
  a07=arg[0]? arg[0][3] : 0;
  a08=(a01*a07);
  a06=(a06+a08);
  a06=(a00*a06);
  a08=(a03*a06);
  a09=4.;
  a10=(a08/a09);
  a11=arg[0]? arg[0][1] : 0;
  a12=(a01*a11);
  a13=arg[0]? arg[0][4] : 0;
  a14=(a01*a13);
  a12=(a12+a14);
  a12=(a00*a12);
  a14=2.;
  a15=(a12/a14);
  a16=(a10-a15);
  a17=casadi_sq(a06);
  a18=casadi_sq(a12);
  a19=(a17+a18);
  a20=casadi_sq(a03);
  a19=(a19+a20);
  a19=(a09+a19);
  a19=(a09/a19);
  a21=(a19*a15);
  a22=arg[2]? arg[2][0] : 0;
  a10=(a15+a10);
  a23=(a06/a14);
  a24=(a19*a23);
  a25=arg[1]? arg[1][2] : 0;
  a26=1.;
  a27=(a20+a18);
  a27=(a27/a14);
  a27=(a19*a27);
  a27=(a26-a27);
  a27=(a25*a27);
  a28=arg[1]? arg[1][5] : 0;
  a29=(a06*a12);
  a30=(a29/a14);
  a30=(a03+a30);
  a30=(a19*a30);
  a30=(a28*a30);
  a27=(a27+a30);
  a30=arg[1]? arg[1][8] : 0;
  a31=(a06*a03);
  a32=(a31/a14);
  a32=(a32-a12);
  a32=(a19*a32);
  a32=(a30*a32);
  a27=(a27+a32);
  a32=-7.4999999999999997e-02;
  a32=(a32*a00);
  a08=(a08/a14);
  a08=(a12+a08);
  a08=(a19*a08);
  a08=(a25*a08);
  a33=(a03*a12);
  a34=(a33/a14);
  a34=(a34-a06);
  a34=(a19*a34);
  a34=(a28*a34);
  a08=(a08+a34);
  a34=(a18+a17);
  a34=(a34/a14);
  a34=(a19*a34);
  a34=(a26-a34);
  a34=(a30*a34);
  a08=(a08+a34);
  a34=(a01*a08);
  a04=(a04+a34);
  a04=(2.*a04);
  a34=1.6666666666666666e-01;
  a34=(a34*a00);
  a04=(a04*a34);
  a04=(a01*a04);
  a04=(a32+a04);
  a35=(a27*a04);
  a36=-4.4999999999999998e-02;
  a36=(a36*a00);
  a37=(a01*a27);
  a07=(a07+a37);
  a07=(2.*a07);
  a37=(a01*a00);
  a07=(a07*a37);
  a07=(a01*a07);
  a07=(a36+a07);
  a38=(a08*a07);
  a35=(a35-a38);
  a35=(a35/a00);
  a38=(a24*a35);
  a39=2.9999999999999999e-02;
  a39=(a39*a00);
  a40=(a12*a06);
  a41=(a40/a14);
  a41=(a41-a03);
  a41=(a19*a41);
  a41=(a25*a41);
  a42=(a20+a17);
  a42=(a42/a14);
  a42=(a19*a42);
  a42=(a26-a42);
  a42=(a28*a42);
  a41=(a41+a42);
  a12=(a12*a03);
  a42=(a12/a14);
  a06=(a06+a42);
  a06=(a19*a06);
  a06=(a30*a06);
  a41=(a41+a06);
  a06=(a01*a41);
  a13=(a13+a06);
  a13=(2.*a13);
  a06=2.5000000000000000e-01;
  a06=(a06*a00);
  a13=(a13*a06);
  a13=(a01*a13);
  a13=(a39+a13);
  a08=(a08*a13);
  a04=(a41*a04);
  a08=(a08-a04);
  a08=(a08/a00);
  a04=(a21*a08);
  a38=(a38-a04);
  a41=(a41*a07);
  a27=(a27*a13);
  a41=(a41-a27);
  a41=(a41/a00);
  a27=(a19*a41);
  a38=(a38+a27);
  a38=(a00*a38);
  a10=(a10*a38);
  a40=(a40/a09);
  a03=(a03/a14);
  a14=(a40-a03);
  a27=(a19*a03);
  a13=(a27*a08);
  a07=(a19*a35);
  a13=(a13+a07);
  a07=(a24*a41);
  a13=(a13-a07);
  a13=(a00*a13);
  a14=(a14*a13);
  a10=(a10+a14);
  a17=(a17/a09);
  a17=(a26+a17);
  a08=(a19*a08);
  a35=(a27*a35);
  a08=(a08-a35);
  a41=(a21*a41);
  a08=(a08+a41);
  a00=(a00*a08);
  a08=(a17*a00);
  a10=(a10+a08);
  a08=(a01*a28);
  a11=(a11+a08);
  a11=(2.*a11);
  a11=(a11*a06);
  a11=(a01*a11);
  a39=(a39+a11);
  a11=(a30*a39);
  a06=(a01*a30);
  a02=(a02+a06);
  a02=(2.*a02);
  a02=(a02*a34);
  a02=(a01*a02);
  a32=(a32+a02);
  a02=(a28*a32);
  a11=(a11-a02);
  a10=(a10+a11);
  a22=(a22+a10);
  a10=(a21*a22);
  a11=arg[2]? arg[2][1] : 0;
  a33=(a33/a09);
  a02=(a33-a23);
  a02=(a02*a38);
  a18=(a18/a09);
  a18=(a26+a18);
  a34=(a18*a13);
  a02=(a02+a34);
  a29=(a29/a09);
  a34=(a03+a29);
  a34=(a34*a00);
  a02=(a02+a34);
  a32=(a25*a32);
  a34=(a01*a25);
  a05=(a05+a34);
  a05=(2.*a05);
  a05=(a05*a37);
  a01=(a01*a05);
  a36=(a36+a01);
  a30=(a30*a36);
  a32=(a32-a30);
  a02=(a02+a32);
  a11=(a11+a02);
  a02=(a24*a11);
  a10=(a10-a02);
  a02=arg[2]? arg[2][2] : 0;
  a20=(a20/a09);
  a26=(a26+a20);
  a38=(a26*a38);
  a12=(a12/a09);
  a20=(a23+a12);
  a20=(a20*a13);
  a38=(a38+a20);
  a31=(a31/a09);
  a09=(a31-a15);
  a09=(a09*a00);
  a38=(a38+a09);
  a28=(a28*a36);
  a25=(a25*a39);
  a28=(a28-a25);
  a38=(a38+a28);
  a02=(a02+a38);
  a38=(a19*a02);
  a10=(a10+a38);
  a16=(a16*a10);
  a40=(a03+a40);
  a38=(a19*a11);
  a28=(a27*a22);
  a38=(a38-a28);
  a24=(a24*a02);
  a38=(a38+a24);
  a40=(a40*a38);
  a16=(a16+a40);
  a19=(a19*a22);
  a27=(a27*a11);
  a19=(a19+a27);
  a21=(a21*a02);
  a19=(a19-a21);
  a17=(a17*a19);
  a16=(a16+a17);
  if (res[0]!=0) res[0][0]=a16;
  a33=(a23+a33);
  a33=(a33*a10);
  a18=(a18*a38);
  a33=(a33+a18);
  a29=(a29-a03);
  a29=(a29*a19);
  a33=(a33+a29);
  if (res[0]!=0) res[0][1]=a33;
  a26=(a26*a10);
  a12=(a12-a23);
  a12=(a12*a38);
  a26=(a26+a12);
  a15=(a15+a31);
  a15=(a15*a19);
  a26=(a26+a15);
  if (res[0]!=0) res[0][2]=a26;
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
  casadi_real a156, a157, a158, a159, a160, a161, a162, a163, a164, a165, a166, a167;
  casadi_real a168, a169, a170, a171, a172, a173, a174, a175, a176, a177, a178, a179;
  casadi_real a180, a181, a182, a183, a184, a185;
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
  a016=(a002/a011);
  a017=2.;
  a018=(a008/a017);
  a019=(a013*a004);
  a020=(a019/a002);
  a021=(a018+a020);
  a022=(a004/a017);
  a023=(a016*a022);
  a024=-7.4999999999999997e-02;
  a024=(a024*a001);
  a025=arg[1]? arg[1][2] : 0;
  a019=(a019/a017);
  a019=(a008+a019);
  a026=(a016*a019);
  a027=(a025*a026);
  a028=arg[1]? arg[1][5] : 0;
  a029=(a013*a008);
  a030=(a029/a017);
  a030=(a030-a004);
  a031=(a016*a030);
  a032=(a028*a031);
  a027=(a027+a032);
  a032=arg[1]? arg[1][8] : 0;
  a033=1.;
  a034=(a010+a006);
  a034=(a034/a017);
  a035=(a016*a034);
  a035=(a033-a035);
  a036=(a032*a035);
  a027=(a027+a036);
  a036=(a000*a027);
  a014=(a014+a036);
  a014=(2.*a014);
  a036=1.6666666666666666e-01;
  a036=(a036*a001);
  a014=(a014*a036);
  a014=(a000*a014);
  a014=(a024+a014);
  a037=(a004*a008);
  a038=(a037/a017);
  a038=(a013+a038);
  a039=(a016*a038);
  a040=(a039*a032);
  a041=(a004*a013);
  a042=(a041/a017);
  a042=(a042-a008);
  a043=(a016*a042);
  a044=(a043*a028);
  a040=(a040-a044);
  a044=(a014*a040);
  a045=(a015+a010);
  a045=(a045/a017);
  a046=(a016*a045);
  a046=(a033-a046);
  a047=(a025*a046);
  a048=(a028*a039);
  a047=(a047+a048);
  a048=(a032*a043);
  a047=(a047+a048);
  a048=(a031*a032);
  a049=(a035*a028);
  a048=(a048-a049);
  a049=(a036*a048);
  a050=(a000*a049);
  a051=(a047*a050);
  a044=(a044+a051);
  a051=-4.4999999999999998e-02;
  a051=(a051*a001);
  a052=(a000*a047);
  a005=(a005+a052);
  a005=(2.*a005);
  a052=(a000*a001);
  a005=(a005*a052);
  a005=(a000*a005);
  a005=(a051+a005);
  a053=(a005*a048);
  a054=(a052*a040);
  a055=(a000*a054);
  a056=(a027*a055);
  a053=(a053+a056);
  a044=(a044-a053);
  a044=(a044/a001);
  a053=(a023*a044);
  a056=(a016*a018);
  a057=2.9999999999999999e-02;
  a057=(a057*a001);
  a058=(a008*a004);
  a059=(a058/a017);
  a059=(a059-a013);
  a060=(a016*a059);
  a061=(a025*a060);
  a062=(a015+a006);
  a062=(a062/a017);
  a063=(a016*a062);
  a063=(a033-a063);
  a064=(a028*a063);
  a061=(a061+a064);
  a064=(a008*a013);
  a065=(a064/a017);
  a065=(a004+a065);
  a066=(a016*a065);
  a067=(a032*a066);
  a061=(a061+a067);
  a067=(a000*a061);
  a009=(a009+a067);
  a009=(2.*a009);
  a067=2.5000000000000000e-01;
  a068=(a067*a001);
  a009=(a009*a068);
  a009=(a000*a009);
  a009=(a057+a009);
  a069=(a009*a048);
  a070=(a063*a032);
  a071=(a066*a028);
  a070=(a070-a071);
  a071=(a068*a070);
  a072=(a000*a071);
  a073=(a027*a072);
  a069=(a069+a073);
  a073=(a014*a070);
  a050=(a061*a050);
  a073=(a073+a050);
  a069=(a069-a073);
  a069=(a069/a001);
  a073=(a056*a069);
  a053=(a053-a073);
  a073=(a005*a070);
  a055=(a061*a055);
  a073=(a073+a055);
  a055=(a009*a040);
  a072=(a047*a072);
  a055=(a055+a072);
  a073=(a073-a055);
  a073=(a073/a001);
  a055=(a016*a073);
  a053=(a053+a055);
  a053=(a001*a053);
  a055=(a021*a053);
  a058=(a058/a002);
  a017=(a013/a017);
  a072=(a058-a017);
  a050=(a016*a017);
  a074=(a050*a069);
  a075=(a016*a044);
  a074=(a074+a075);
  a075=(a023*a073);
  a074=(a074-a075);
  a074=(a001*a074);
  a075=(a072*a074);
  a055=(a055+a075);
  a006=(a006/a002);
  a006=(a033+a006);
  a069=(a016*a069);
  a044=(a050*a044);
  a069=(a069-a044);
  a073=(a056*a073);
  a069=(a069+a073);
  a069=(a001*a069);
  a073=(a006*a069);
  a055=(a055+a073);
  a073=(a068*a032);
  a044=(a000*a073);
  a075=(a032*a044);
  a076=(a000*a028);
  a007=(a007+a076);
  a007=(2.*a007);
  a007=(a007*a068);
  a007=(a000*a007);
  a057=(a057+a007);
  a007=(a057*a028);
  a075=(a075-a007);
  a077=(a000*a032);
  a012=(a012+a077);
  a012=(2.*a012);
  a012=(a012*a036);
  a012=(a000*a012);
  a024=(a024+a012);
  a012=(a024*a032);
  a076=(-a076);
  a076=(2.*a076);
  a076=(a036*a076);
  a078=(a000*a076);
  a079=(a028*a078);
  a079=(a012+a079);
  a075=(a075-a079);
  a055=(a055+a075);
  a075=(a016*a055);
  a029=(a029/a002);
  a079=(a029-a022);
  a080=(a079*a053);
  a010=(a010/a002);
  a010=(a033+a010);
  a081=(a010*a074);
  a080=(a080+a081);
  a037=(a037/a002);
  a081=(a017+a037);
  a082=(a081*a069);
  a080=(a080+a082);
  a078=(a025*a078);
  a082=(a000*a025);
  a003=(a003+a082);
  a003=(2.*a003);
  a003=(a003*a052);
  a003=(a000*a003);
  a051=(a051+a003);
  a003=(a051*a028);
  a078=(a078+a003);
  a080=(a080+a078);
  a078=(a050*a080);
  a075=(a075+a078);
  a015=(a015/a002);
  a015=(a033+a015);
  a078=(a015*a053);
  a064=(a064/a002);
  a003=(a022+a064);
  a083=(a003*a074);
  a078=(a078+a083);
  a041=(a041/a002);
  a002=(a041-a018);
  a083=(a002*a069);
  a078=(a078+a083);
  a083=(a051*a032);
  a044=(a025*a044);
  a083=(a083-a044);
  a078=(a078+a083);
  a083=(a056*a078);
  a075=(a075-a083);
  a083=(a001*a075);
  a083=(a000*a083);
  a069=(a001*a069);
  a069=(a000*a069);
  a083=(a083-a069);
  a069=(a083/a052);
  a069=(-a069);
  if (res[0]!=0) res[0][0]=a069;
  a069=(a016*a080);
  a044=(a050*a055);
  a069=(a069-a044);
  a044=(a023*a078);
  a069=(a069+a044);
  a044=(a001*a069);
  a044=(a000*a044);
  a074=(a001*a074);
  a074=(a000*a074);
  a044=(a044-a074);
  a073=(a073-a044);
  a073=(a073/a052);
  if (res[0]!=0) res[0][1]=a073;
  a055=(a056*a055);
  a080=(a023*a080);
  a055=(a055-a080);
  a078=(a016*a078);
  a055=(a055+a078);
  a078=(a001*a055);
  a078=(a000*a078);
  a053=(a001*a053);
  a053=(a000*a053);
  a078=(a078-a053);
  a076=(a076-a078);
  a076=(a076/a052);
  if (res[0]!=0) res[0][2]=a076;
  a054=(a054-a083);
  a054=(a054/a052);
  if (res[0]!=0) res[0][3]=a054;
  a071=(a071-a044);
  a071=(a071/a052);
  if (res[0]!=0) res[0][4]=a071;
  a049=(a049-a078);
  a049=(a049/a052);
  if (res[0]!=0) res[0][5]=a049;
  a077=(-a077);
  a077=(2.*a077);
  a077=(a052*a077);
  a049=(a043*a025);
  a078=(a046*a032);
  a049=(a049-a078);
  a078=(a014*a049);
  a071=(a035*a025);
  a044=(a026*a032);
  a071=(a071-a044);
  a044=(a036*a071);
  a054=(a000*a044);
  a083=(a047*a054);
  a078=(a078+a083);
  a083=(a005*a071);
  a076=(a052*a049);
  a053=(a000*a076);
  a080=(a027*a053);
  a083=(a083+a080);
  a078=(a078-a083);
  a078=(a078/a001);
  a083=(a023*a078);
  a080=(a009*a071);
  a073=(a066*a025);
  a074=(a060*a032);
  a073=(a073-a074);
  a074=(a068*a073);
  a084=(a000*a074);
  a085=(a027*a084);
  a080=(a080+a085);
  a085=(a014*a073);
  a054=(a061*a054);
  a085=(a085+a054);
  a080=(a080-a085);
  a080=(a080/a001);
  a085=(a056*a080);
  a083=(a083-a085);
  a085=(a005*a073);
  a053=(a061*a053);
  a085=(a085+a053);
  a053=(a009*a049);
  a084=(a047*a084);
  a053=(a053+a084);
  a085=(a085-a053);
  a085=(a085/a001);
  a053=(a016*a085);
  a083=(a083+a053);
  a083=(a001*a083);
  a053=(a021*a083);
  a084=(a050*a080);
  a054=(a016*a078);
  a084=(a084+a054);
  a054=(a023*a085);
  a084=(a084-a054);
  a084=(a001*a084);
  a054=(a072*a084);
  a053=(a053+a054);
  a080=(a016*a080);
  a078=(a050*a078);
  a080=(a080-a078);
  a085=(a056*a085);
  a080=(a080+a085);
  a080=(a001*a080);
  a085=(a006*a080);
  a053=(a053+a085);
  a085=(a057*a025);
  a078=(a036*a025);
  a054=(a000*a078);
  a086=(a028*a054);
  a085=(a085-a086);
  a053=(a053+a085);
  a085=(a016*a053);
  a086=(a079*a083);
  a087=(a010*a084);
  a086=(a086+a087);
  a087=(a081*a080);
  a086=(a086+a087);
  a054=(a025*a054);
  a054=(a054-a012);
  a012=(a051*a025);
  a087=(a000*a077);
  a088=(a032*a087);
  a088=(a012+a088);
  a054=(a054-a088);
  a086=(a086+a054);
  a054=(a050*a086);
  a085=(a085+a054);
  a054=(a015*a083);
  a088=(a003*a084);
  a054=(a054+a088);
  a088=(a002*a080);
  a054=(a054+a088);
  a087=(a028*a087);
  a088=(a057*a032);
  a087=(a087+a088);
  a054=(a054+a087);
  a087=(a056*a054);
  a085=(a085-a087);
  a087=(a001*a085);
  a087=(a000*a087);
  a080=(a001*a080);
  a080=(a000*a080);
  a087=(a087-a080);
  a077=(a077-a087);
  a077=(a077/a052);
  if (res[0]!=0) res[0][6]=a077;
  a077=(a016*a086);
  a080=(a050*a053);
  a077=(a077-a080);
  a080=(a023*a054);
  a077=(a077+a080);
  a080=(a001*a077);
  a080=(a000*a080);
  a084=(a001*a084);
  a084=(a000*a084);
  a080=(a080-a084);
  a084=(a080/a052);
  a084=(-a084);
  if (res[0]!=0) res[0][7]=a084;
  a053=(a056*a053);
  a086=(a023*a086);
  a053=(a053-a086);
  a054=(a016*a054);
  a053=(a053+a054);
  a054=(a001*a053);
  a054=(a000*a054);
  a083=(a001*a083);
  a083=(a000*a083);
  a054=(a054-a083);
  a078=(a078-a054);
  a078=(a078/a052);
  if (res[0]!=0) res[0][8]=a078;
  a076=(a076-a087);
  a076=(a076/a052);
  if (res[0]!=0) res[0][9]=a076;
  a074=(a074-a080);
  a074=(a074/a052);
  if (res[0]!=0) res[0][10]=a074;
  a044=(a044-a054);
  a044=(a044/a052);
  if (res[0]!=0) res[0][11]=a044;
  a044=(a052*a028);
  a054=(a046*a028);
  a074=(a039*a025);
  a054=(a054-a074);
  a074=(a014*a054);
  a080=(a026*a028);
  a076=(a031*a025);
  a080=(a080-a076);
  a076=(a036*a080);
  a087=(a000*a076);
  a078=(a047*a087);
  a074=(a074+a078);
  a078=(a005*a080);
  a083=(a052*a054);
  a086=(a000*a083);
  a084=(a027*a086);
  a078=(a078+a084);
  a074=(a074-a078);
  a074=(a074/a001);
  a078=(a023*a074);
  a084=(a009*a080);
  a088=(a060*a028);
  a089=(a063*a025);
  a088=(a088-a089);
  a089=(a068*a088);
  a090=(a000*a089);
  a091=(a027*a090);
  a084=(a084+a091);
  a091=(a014*a088);
  a087=(a061*a087);
  a091=(a091+a087);
  a084=(a084-a091);
  a084=(a084/a001);
  a091=(a056*a084);
  a078=(a078-a091);
  a091=(a005*a088);
  a086=(a061*a086);
  a091=(a091+a086);
  a086=(a009*a054);
  a090=(a047*a090);
  a086=(a086+a090);
  a091=(a091-a086);
  a091=(a091/a001);
  a086=(a016*a091);
  a078=(a078+a086);
  a078=(a001*a078);
  a086=(a021*a078);
  a090=(a050*a084);
  a087=(a016*a074);
  a090=(a090+a087);
  a087=(a023*a091);
  a090=(a090-a087);
  a090=(a001*a090);
  a087=(a072*a090);
  a086=(a086+a087);
  a084=(a016*a084);
  a074=(a050*a074);
  a084=(a084-a074);
  a091=(a056*a091);
  a084=(a084+a091);
  a084=(a001*a084);
  a091=(a006*a084);
  a086=(a086+a091);
  a082=(-a082);
  a082=(2.*a082);
  a082=(a068*a082);
  a091=(a000*a082);
  a074=(a032*a091);
  a087=(a024*a025);
  a074=(a074+a087);
  a086=(a086+a074);
  a074=(a016*a086);
  a087=(a079*a078);
  a092=(a010*a090);
  a087=(a087+a092);
  a092=(a081*a084);
  a087=(a087+a092);
  a092=(a024*a028);
  a093=(a000*a044);
  a094=(a032*a093);
  a092=(a092-a094);
  a087=(a087+a092);
  a092=(a050*a087);
  a074=(a074+a092);
  a092=(a015*a078);
  a094=(a003*a090);
  a092=(a092+a094);
  a094=(a002*a084);
  a092=(a092+a094);
  a093=(a028*a093);
  a093=(a093-a012);
  a091=(a025*a091);
  a007=(a007+a091);
  a093=(a093-a007);
  a092=(a092+a093);
  a093=(a056*a092);
  a074=(a074-a093);
  a093=(a001*a074);
  a093=(a000*a093);
  a084=(a001*a084);
  a084=(a000*a084);
  a093=(a093-a084);
  a044=(a044-a093);
  a044=(a044/a052);
  if (res[0]!=0) res[0][12]=a044;
  a044=(a016*a087);
  a084=(a050*a086);
  a044=(a044-a084);
  a084=(a023*a092);
  a044=(a044+a084);
  a084=(a001*a044);
  a084=(a000*a084);
  a090=(a001*a090);
  a090=(a000*a090);
  a084=(a084-a090);
  a082=(a082-a084);
  a082=(a082/a052);
  if (res[0]!=0) res[0][13]=a082;
  a086=(a056*a086);
  a087=(a023*a087);
  a086=(a086-a087);
  a092=(a016*a092);
  a086=(a086+a092);
  a092=(a001*a086);
  a092=(a000*a092);
  a078=(a001*a078);
  a078=(a000*a078);
  a092=(a092-a078);
  a078=(a092/a052);
  a078=(-a078);
  if (res[0]!=0) res[0][14]=a078;
  a083=(a083-a093);
  a083=(a083/a052);
  if (res[0]!=0) res[0][15]=a083;
  a089=(a089-a084);
  a089=(a089/a052);
  if (res[0]!=0) res[0][16]=a089;
  a076=(a076-a092);
  a076=(a076/a052);
  if (res[0]!=0) res[0][17]=a076;
  a076=(a001*a016);
  a076=(a000*a076);
  a076=(a076/a052);
  a076=(-a076);
  if (res[0]!=0) res[0][18]=a076;
  a092=(a001*a050);
  a092=(a000*a092);
  a092=(a092/a052);
  if (res[0]!=0) res[0][19]=a092;
  a089=(a001*a056);
  a089=(a000*a089);
  a089=(a089/a052);
  a084=(-a089);
  if (res[0]!=0) res[0][20]=a084;
  if (res[0]!=0) res[0][21]=a076;
  if (res[0]!=0) res[0][22]=a092;
  if (res[0]!=0) res[0][23]=a084;
  a092=(-a092);
  if (res[0]!=0) res[0][24]=a092;
  if (res[0]!=0) res[0][25]=a076;
  a084=(a001*a023);
  a084=(a000*a084);
  a084=(a084/a052);
  if (res[0]!=0) res[0][26]=a084;
  if (res[0]!=0) res[0][27]=a092;
  if (res[0]!=0) res[0][28]=a076;
  if (res[0]!=0) res[0][29]=a084;
  if (res[0]!=0) res[0][30]=a089;
  a084=(-a084);
  if (res[0]!=0) res[0][31]=a084;
  if (res[0]!=0) res[0][32]=a076;
  if (res[0]!=0) res[0][33]=a089;
  if (res[0]!=0) res[0][34]=a084;
  if (res[0]!=0) res[0][35]=a076;
  a076=arg[1]? arg[1][0] : 0;
  a084=(a076*a026);
  a089=arg[1]? arg[1][3] : 0;
  a092=(a089*a031);
  a084=(a084+a092);
  a092=arg[1]? arg[1][6] : 0;
  a083=(a092*a035);
  a084=(a084+a083);
  a083=(a008*a052);
  a093=(a000*a083);
  a093=(a016*a093);
  a011=(a016/a011);
  a078=(2.*a004);
  a078=(a078*a052);
  a087=(a011*a078);
  a082=(a059*a087);
  a082=(a093-a082);
  a090=(a076*a082);
  a007=(a000*a078);
  a007=(a016*a007);
  a091=(a062*a087);
  a091=(a007-a091);
  a012=(a089*a091);
  a090=(a090-a012);
  a012=(a016*a052);
  a094=(a065*a087);
  a094=(a012-a094);
  a095=(a092*a094);
  a090=(a090+a095);
  a090=(a084*a090);
  a095=arg[1]? arg[1][1] : 0;
  a096=(a095*a026);
  a097=arg[1]? arg[1][4] : 0;
  a098=(a097*a031);
  a096=(a096+a098);
  a098=arg[1]? arg[1][7] : 0;
  a099=(a098*a035);
  a096=(a096+a099);
  a099=(a095*a082);
  a100=(a097*a091);
  a099=(a099-a100);
  a100=(a098*a094);
  a099=(a099+a100);
  a099=(a096*a099);
  a090=(a090+a099);
  a082=(a025*a082);
  a091=(a028*a091);
  a082=(a082-a091);
  a094=(a032*a094);
  a082=(a082+a094);
  a094=(a027*a082);
  a090=(a090+a094);
  if (res[1]!=0) res[1][0]=a090;
  a094=(a076*a046);
  a091=(a089*a039);
  a094=(a094+a091);
  a091=(a092*a043);
  a094=(a094+a091);
  a091=(a013*a052);
  a099=(a000*a091);
  a099=(a016*a099);
  a100=(a019*a087);
  a100=(a099-a100);
  a101=(a076*a100);
  a102=(a030*a087);
  a102=(a102+a012);
  a103=(a089*a102);
  a101=(a101-a103);
  a103=(a034*a087);
  a007=(a007-a103);
  a103=(a092*a007);
  a101=(a101-a103);
  a101=(a094*a101);
  a103=(a095*a046);
  a104=(a097*a039);
  a103=(a103+a104);
  a104=(a098*a043);
  a103=(a103+a104);
  a104=(a095*a100);
  a105=(a097*a102);
  a104=(a104-a105);
  a105=(a098*a007);
  a104=(a104-a105);
  a104=(a103*a104);
  a101=(a101+a104);
  a100=(a025*a100);
  a102=(a028*a102);
  a100=(a100-a102);
  a007=(a032*a007);
  a100=(a100-a007);
  a007=(a047*a100);
  a101=(a101+a007);
  if (res[1]!=0) res[1][1]=a101;
  a007=(a076*a060);
  a102=(a089*a063);
  a007=(a007+a102);
  a102=(a092*a066);
  a007=(a007+a102);
  a102=(a045*a087);
  a104=(a076*a102);
  a105=(a038*a087);
  a105=(a093-a105);
  a106=(a089*a105);
  a104=(a104+a106);
  a106=(a042*a087);
  a106=(a099-a106);
  a107=(a092*a106);
  a104=(a104+a107);
  a104=(a007*a104);
  a107=(a095*a060);
  a108=(a097*a063);
  a107=(a107+a108);
  a108=(a098*a066);
  a107=(a107+a108);
  a108=(a095*a102);
  a109=(a097*a105);
  a108=(a108+a109);
  a109=(a098*a106);
  a108=(a108+a109);
  a108=(a107*a108);
  a104=(a104+a108);
  a102=(a025*a102);
  a105=(a028*a105);
  a102=(a102+a105);
  a106=(a032*a106);
  a102=(a102+a106);
  a106=(a061*a102);
  a104=(a104+a106);
  if (res[1]!=0) res[1][2]=a104;
  a106=arg[2]? arg[2][0] : 0;
  a105=(a047*a014);
  a108=(a027*a005);
  a105=(a105-a108);
  a105=(a105/a001);
  a108=(a023*a105);
  a109=(a027*a009);
  a110=(a061*a014);
  a109=(a109-a110);
  a109=(a109/a001);
  a110=(a056*a109);
  a108=(a108-a110);
  a110=(a061*a005);
  a111=(a047*a009);
  a110=(a110-a111);
  a110=(a110/a001);
  a111=(a016*a110);
  a108=(a108+a111);
  a108=(a001*a108);
  a111=(a021*a108);
  a112=(a050*a109);
  a113=(a016*a105);
  a112=(a112+a113);
  a113=(a023*a110);
  a112=(a112-a113);
  a112=(a001*a112);
  a113=(a072*a112);
  a111=(a111+a113);
  a113=(a016*a109);
  a114=(a050*a105);
  a113=(a113-a114);
  a114=(a056*a110);
  a113=(a113+a114);
  a113=(a001*a113);
  a114=(a006*a113);
  a111=(a111+a114);
  a114=(a032*a057);
  a115=(a028*a024);
  a114=(a114-a115);
  a111=(a111+a114);
  a106=(a106+a111);
  a111=(a056*a106);
  a114=arg[2]? arg[2][1] : 0;
  a115=(a079*a108);
  a116=(a010*a112);
  a115=(a115+a116);
  a116=(a081*a113);
  a115=(a115+a116);
  a024=(a025*a024);
  a116=(a032*a051);
  a024=(a024-a116);
  a115=(a115+a024);
  a114=(a114+a115);
  a115=(a023*a114);
  a111=(a111-a115);
  a115=arg[2]? arg[2][2] : 0;
  a024=(a015*a108);
  a116=(a003*a112);
  a024=(a024+a116);
  a116=(a002*a113);
  a024=(a024+a116);
  a051=(a028*a051);
  a057=(a025*a057);
  a051=(a051-a057);
  a024=(a024+a051);
  a115=(a115+a024);
  a024=(a016*a115);
  a111=(a111+a024);
  a091=(a067*a091);
  a024=(a111*a091);
  a020=(a020-a018);
  a051=(a108*a091);
  a057=(a016*a068);
  a116=(a022*a087);
  a116=(a057-a116);
  a117=(a105*a116);
  a118=(a014*a102);
  a119=(a036*a100);
  a119=(a000*a119);
  a120=(a047*a119);
  a118=(a118+a120);
  a120=(a005*a100);
  a121=(a052*a102);
  a121=(a000*a121);
  a122=(a027*a121);
  a122=(a120+a122);
  a122=(a118-a122);
  a122=(a122/a001);
  a123=(a023*a122);
  a123=(a117+a123);
  a100=(a009*a100);
  a124=(a068*a082);
  a124=(a000*a124);
  a125=(a027*a124);
  a100=(a100+a125);
  a125=(a014*a082);
  a119=(a061*a119);
  a125=(a125+a119);
  a100=(a100-a125);
  a100=(a100/a001);
  a125=(a056*a100);
  a119=(a018*a087);
  a126=(a109*a119);
  a125=(a125-a126);
  a123=(a123-a125);
  a082=(a005*a082);
  a121=(a061*a121);
  a121=(a082+a121);
  a126=(a009*a102);
  a124=(a047*a124);
  a126=(a126+a124);
  a121=(a121-a126);
  a121=(a121/a001);
  a124=(a016*a121);
  a127=(a110*a087);
  a124=(a124-a127);
  a123=(a123+a124);
  a123=(a001*a123);
  a124=(a021*a123);
  a124=(a051+a124);
  a083=(a067*a083);
  a128=(a112*a083);
  a129=(a050*a100);
  a130=(a017*a087);
  a131=(a109*a130);
  a129=(a129-a131);
  a131=(a016*a122);
  a132=(a105*a087);
  a131=(a131-a132);
  a131=(a129+a131);
  a133=(a110*a116);
  a134=(a023*a121);
  a134=(a133+a134);
  a131=(a131-a134);
  a131=(a001*a131);
  a134=(a072*a131);
  a134=(a128+a134);
  a124=(a124+a134);
  a078=(a067*a078);
  a134=(a113*a078);
  a100=(a016*a100);
  a135=(a109*a087);
  a100=(a100-a135);
  a122=(a050*a122);
  a135=(a105*a130);
  a122=(a122-a135);
  a122=(a100-a122);
  a121=(a056*a121);
  a136=(a110*a119);
  a121=(a121-a136);
  a122=(a122+a121);
  a122=(a001*a122);
  a121=(a006*a122);
  a121=(a134+a121);
  a124=(a124+a121);
  a121=(a056*a124);
  a137=(a106*a119);
  a121=(a121-a137);
  a138=(a114*a116);
  a139=(a079*a123);
  a140=(a108*a068);
  a139=(a139-a140);
  a141=(a010*a131);
  a139=(a139+a141);
  a141=(a113*a083);
  a142=(a081*a122);
  a142=(a141+a142);
  a139=(a139+a142);
  a142=(a032*a052);
  a139=(a139-a142);
  a142=(a023*a139);
  a142=(a138+a142);
  a121=(a121-a142);
  a123=(a015*a123);
  a142=(a112*a068);
  a131=(a003*a131);
  a131=(a142+a131);
  a123=(a123+a131);
  a131=(a113*a091);
  a122=(a002*a122);
  a122=(a131+a122);
  a123=(a123+a122);
  a122=(a028*a052);
  a123=(a123+a122);
  a122=(a016*a123);
  a143=(a115*a087);
  a122=(a122-a143);
  a121=(a121+a122);
  a122=(a020*a121);
  a122=(a024+a122);
  a144=(a016*a114);
  a145=(a050*a106);
  a144=(a144-a145);
  a145=(a023*a115);
  a144=(a144+a145);
  a145=(a144*a083);
  a058=(a017+a058);
  a146=(a016*a139);
  a147=(a114*a087);
  a146=(a146-a147);
  a148=(a050*a124);
  a149=(a106*a130);
  a148=(a148-a149);
  a146=(a146-a148);
  a116=(a115*a116);
  a148=(a023*a123);
  a148=(a116+a148);
  a146=(a146+a148);
  a148=(a058*a146);
  a148=(a145+a148);
  a122=(a122+a148);
  a148=(a016*a106);
  a150=(a050*a114);
  a148=(a148+a150);
  a150=(a056*a115);
  a148=(a148-a150);
  a078=(a148*a078);
  a124=(a016*a124);
  a087=(a106*a087);
  a124=(a124-a087);
  a139=(a050*a139);
  a130=(a114*a130);
  a139=(a139-a130);
  a124=(a124+a139);
  a123=(a056*a123);
  a119=(a115*a119);
  a123=(a123-a119);
  a124=(a124-a123);
  a123=(a006*a124);
  a123=(a078+a123);
  a122=(a122+a123);
  if (res[1]!=0) res[1][3]=a122;
  a122=(a111*a068);
  a029=(a022+a029);
  a123=(a029*a121);
  a123=(a122+a123);
  a139=(a010*a146);
  a123=(a123+a139);
  a139=(a148*a083);
  a037=(a037-a017);
  a150=(a037*a124);
  a150=(a139+a150);
  a123=(a123+a150);
  if (res[1]!=0) res[1][4]=a123;
  a121=(a015*a121);
  a064=(a064-a022);
  a146=(a064*a146);
  a123=(a144*a068);
  a146=(a146-a123);
  a121=(a121+a146);
  a146=(a148*a091);
  a041=(a018+a041);
  a124=(a041*a124);
  a124=(a146+a124);
  a121=(a121+a124);
  if (res[1]!=0) res[1][5]=a121;
  a004=(a004*a052);
  a121=(a000*a004);
  a121=(a016*a121);
  a008=(2.*a008);
  a008=(a008*a052);
  a124=(a011*a008);
  a150=(a059*a124);
  a150=(a121-a150);
  a151=(a076*a150);
  a152=(a062*a124);
  a153=(a089*a152);
  a151=(a151+a153);
  a153=(a065*a124);
  a153=(a099-a153);
  a154=(a092*a153);
  a151=(a151+a154);
  a151=(a084*a151);
  a154=(a095*a150);
  a155=(a097*a152);
  a154=(a154+a155);
  a155=(a098*a153);
  a154=(a154+a155);
  a154=(a096*a154);
  a151=(a151+a154);
  a150=(a025*a150);
  a152=(a028*a152);
  a150=(a150+a152);
  a153=(a032*a153);
  a150=(a150+a153);
  a153=(a027*a150);
  a151=(a151+a153);
  if (res[1]!=0) res[1][6]=a151;
  a153=(a019*a124);
  a153=(a012-a153);
  a152=(a076*a153);
  a154=(a030*a124);
  a099=(a099-a154);
  a154=(a089*a099);
  a152=(a152+a154);
  a154=(a000*a008);
  a154=(a016*a154);
  a155=(a034*a124);
  a155=(a154-a155);
  a156=(a092*a155);
  a152=(a152-a156);
  a152=(a094*a152);
  a156=(a095*a153);
  a157=(a097*a099);
  a156=(a156+a157);
  a157=(a098*a155);
  a156=(a156-a157);
  a156=(a103*a156);
  a152=(a152+a156);
  a153=(a025*a153);
  a099=(a028*a099);
  a153=(a153+a099);
  a155=(a032*a155);
  a153=(a153-a155);
  a155=(a047*a153);
  a152=(a152+a155);
  if (res[1]!=0) res[1][7]=a152;
  a155=(a038*a124);
  a155=(a121-a155);
  a099=(a089*a155);
  a156=(a045*a124);
  a154=(a154-a156);
  a156=(a076*a154);
  a099=(a099-a156);
  a156=(a042*a124);
  a156=(a156+a012);
  a157=(a092*a156);
  a099=(a099-a157);
  a099=(a007*a099);
  a157=(a097*a155);
  a158=(a095*a154);
  a157=(a157-a158);
  a158=(a098*a156);
  a157=(a157-a158);
  a157=(a107*a157);
  a099=(a099+a157);
  a155=(a028*a155);
  a154=(a025*a154);
  a155=(a155-a154);
  a156=(a032*a156);
  a155=(a155-a156);
  a156=(a061*a155);
  a099=(a099+a156);
  if (res[1]!=0) res[1][8]=a099;
  a156=(a018*a124);
  a156=(a057-a156);
  a154=(a106*a156);
  a157=(a014*a155);
  a158=(a036*a153);
  a158=(a000*a158);
  a159=(a047*a158);
  a157=(a157+a159);
  a159=(a005*a153);
  a160=(a052*a155);
  a160=(a000*a160);
  a161=(a027*a160);
  a159=(a159+a161);
  a157=(a157-a159);
  a157=(a157/a001);
  a159=(a023*a157);
  a161=(a022*a124);
  a162=(a105*a161);
  a159=(a159-a162);
  a162=(a109*a156);
  a153=(a009*a153);
  a163=(a068*a150);
  a163=(a000*a163);
  a164=(a027*a163);
  a164=(a153+a164);
  a165=(a014*a150);
  a158=(a061*a158);
  a165=(a165+a158);
  a164=(a164-a165);
  a164=(a164/a001);
  a158=(a056*a164);
  a158=(a162+a158);
  a158=(a159-a158);
  a166=(a005*a150);
  a160=(a061*a160);
  a166=(a166+a160);
  a155=(a009*a155);
  a163=(a047*a163);
  a163=(a155+a163);
  a163=(a166-a163);
  a163=(a163/a001);
  a160=(a016*a163);
  a167=(a110*a124);
  a160=(a160-a167);
  a158=(a158+a160);
  a158=(a001*a158);
  a160=(a021*a158);
  a160=(a140+a160);
  a004=(a067*a004);
  a168=(a112*a004);
  a169=(a050*a164);
  a170=(a017*a124);
  a171=(a109*a170);
  a169=(a169-a171);
  a172=(a016*a157);
  a173=(a105*a124);
  a172=(a172-a173);
  a169=(a169+a172);
  a173=(a023*a163);
  a174=(a110*a161);
  a173=(a173-a174);
  a169=(a169-a173);
  a169=(a001*a169);
  a173=(a072*a169);
  a173=(a168+a173);
  a160=(a160+a173);
  a164=(a016*a164);
  a173=(a109*a124);
  a164=(a164-a173);
  a157=(a050*a157);
  a175=(a105*a170);
  a157=(a157-a175);
  a164=(a164-a157);
  a175=(a110*a156);
  a163=(a056*a163);
  a163=(a175+a163);
  a164=(a164+a163);
  a164=(a001*a164);
  a163=(a006*a164);
  a160=(a160+a163);
  a163=(a032*a068);
  a160=(a160+a163);
  a163=(a056*a160);
  a163=(a154+a163);
  a176=(a079*a158);
  a176=(a051+a176);
  a008=(a067*a008);
  a177=(a112*a008);
  a178=(a010*a169);
  a178=(a177+a178);
  a176=(a176+a178);
  a178=(a113*a004);
  a179=(a081*a164);
  a179=(a178+a179);
  a176=(a176+a179);
  a179=(a023*a176);
  a180=(a114*a161);
  a179=(a179-a180);
  a163=(a163-a179);
  a158=(a015*a158);
  a112=(a112*a091);
  a169=(a003*a169);
  a169=(a112+a169);
  a158=(a158+a169);
  a164=(a002*a164);
  a113=(a113*a068);
  a164=(a164-a113);
  a158=(a158+a164);
  a164=(a025*a068);
  a158=(a158-a164);
  a164=(a016*a158);
  a169=(a115*a124);
  a164=(a164-a169);
  a163=(a163+a164);
  a164=(a020*a163);
  a164=(a164-a122);
  a179=(a144*a004);
  a181=(a016*a176);
  a182=(a114*a124);
  a181=(a181-a182);
  a183=(a050*a160);
  a184=(a106*a170);
  a183=(a183-a184);
  a181=(a181-a183);
  a183=(a023*a158);
  a161=(a115*a161);
  a183=(a183-a161);
  a181=(a181+a183);
  a183=(a058*a181);
  a183=(a179+a183);
  a164=(a164+a183);
  a160=(a016*a160);
  a124=(a106*a124);
  a160=(a160-a124);
  a176=(a050*a176);
  a170=(a114*a170);
  a176=(a176-a170);
  a160=(a160+a176);
  a156=(a115*a156);
  a158=(a056*a158);
  a158=(a156+a158);
  a160=(a160-a158);
  a158=(a006*a160);
  a164=(a164+a158);
  if (res[1]!=0) res[1][9]=a164;
  a164=(a029*a163);
  a164=(a024+a164);
  a008=(a144*a008);
  a158=(a010*a181);
  a158=(a008+a158);
  a164=(a164+a158);
  a158=(a148*a004);
  a176=(a037*a160);
  a176=(a158+a176);
  a164=(a164+a176);
  if (res[1]!=0) res[1][10]=a164;
  a163=(a015*a163);
  a144=(a144*a091);
  a181=(a064*a181);
  a181=(a144+a181);
  a163=(a163+a181);
  a148=(a148*a068);
  a160=(a041*a160);
  a160=(a148+a160);
  a163=(a163+a160);
  if (res[1]!=0) res[1][11]=a163;
  a013=(2.*a013);
  a013=(a013*a052);
  a011=(a011*a013);
  a065=(a065*a011);
  a065=(a093-a065);
  a163=(a092*a065);
  a059=(a059*a011);
  a059=(a059+a012);
  a160=(a076*a059);
  a181=(a000*a013);
  a181=(a016*a181);
  a062=(a062*a011);
  a062=(a181-a062);
  a091=(a089*a062);
  a160=(a160+a091);
  a163=(a163-a160);
  a163=(a084*a163);
  a160=(a098*a065);
  a091=(a095*a059);
  a164=(a097*a062);
  a091=(a091+a164);
  a160=(a160-a091);
  a160=(a096*a160);
  a163=(a163+a160);
  a065=(a032*a065);
  a059=(a025*a059);
  a062=(a028*a062);
  a059=(a059+a062);
  a065=(a065-a059);
  a059=(a027*a065);
  a163=(a163+a059);
  if (res[1]!=0) res[1][12]=a163;
  a019=(a019*a011);
  a019=(a121-a019);
  a059=(a076*a019);
  a030=(a030*a011);
  a093=(a093-a030);
  a030=(a089*a093);
  a059=(a059+a030);
  a034=(a034*a011);
  a030=(a092*a034);
  a059=(a059+a030);
  a059=(a094*a059);
  a030=(a095*a019);
  a062=(a097*a093);
  a030=(a030+a062);
  a062=(a098*a034);
  a030=(a030+a062);
  a030=(a103*a030);
  a059=(a059+a030);
  a019=(a025*a019);
  a093=(a028*a093);
  a019=(a019+a093);
  a034=(a032*a034);
  a019=(a019+a034);
  a034=(a047*a019);
  a059=(a059+a034);
  if (res[1]!=0) res[1][13]=a059;
  a038=(a038*a011);
  a012=(a012-a038);
  a038=(a089*a012);
  a045=(a045*a011);
  a181=(a181-a045);
  a045=(a076*a181);
  a038=(a038-a045);
  a042=(a042*a011);
  a121=(a121-a042);
  a042=(a092*a121);
  a038=(a038+a042);
  a038=(a007*a038);
  a042=(a097*a012);
  a045=(a095*a181);
  a042=(a042-a045);
  a045=(a098*a121);
  a042=(a042+a045);
  a042=(a107*a042);
  a038=(a038+a042);
  a012=(a028*a012);
  a181=(a025*a181);
  a012=(a012-a181);
  a032=(a032*a121);
  a012=(a012+a032);
  a032=(a061*a012);
  a038=(a038+a032);
  if (res[1]!=0) res[1][14]=a038;
  a032=(a111*a004);
  a004=(a108*a004);
  a121=(a014*a012);
  a181=(a036*a019);
  a181=(a000*a181);
  a042=(a047*a181);
  a042=(a121+a042);
  a045=(a005*a019);
  a034=(a052*a012);
  a034=(a000*a034);
  a093=(a027*a034);
  a045=(a045+a093);
  a042=(a042-a045);
  a042=(a042/a001);
  a093=(a023*a042);
  a022=(a022*a011);
  a030=(a105*a022);
  a093=(a093-a030);
  a062=(a009*a019);
  a160=(a068*a065);
  a160=(a000*a160);
  a091=(a027*a160);
  a062=(a062+a091);
  a014=(a014*a065);
  a181=(a061*a181);
  a181=(a014+a181);
  a181=(a062-a181);
  a181=(a181/a001);
  a091=(a056*a181);
  a018=(a018*a011);
  a164=(a109*a018);
  a091=(a091-a164);
  a093=(a093-a091);
  a005=(a005*a065);
  a034=(a061*a034);
  a005=(a005+a034);
  a009=(a009*a012);
  a160=(a047*a160);
  a009=(a009+a160);
  a005=(a005-a009);
  a005=(a005/a001);
  a009=(a016*a005);
  a160=(a110*a011);
  a009=(a009-a160);
  a093=(a093+a009);
  a093=(a001*a093);
  a160=(a021*a093);
  a160=(a004+a160);
  a017=(a017*a011);
  a057=(a057-a017);
  a017=(a109*a057);
  a012=(a050*a181);
  a012=(a017+a012);
  a034=(a016*a042);
  a065=(a105*a011);
  a034=(a034-a065);
  a012=(a012+a034);
  a034=(a023*a005);
  a091=(a110*a022);
  a034=(a034-a091);
  a012=(a012-a034);
  a012=(a001*a012);
  a091=(a072*a012);
  a091=(a091-a142);
  a160=(a160+a091);
  a181=(a016*a181);
  a109=(a109*a011);
  a181=(a181-a109);
  a105=(a105*a057);
  a042=(a050*a042);
  a042=(a105+a042);
  a181=(a181-a042);
  a005=(a056*a005);
  a110=(a110*a018);
  a005=(a005-a110);
  a181=(a181+a005);
  a181=(a001*a181);
  a110=(a006*a181);
  a160=(a160+a110);
  a028=(a028*a036);
  a160=(a160-a028);
  a028=(a056*a160);
  a110=(a106*a018);
  a028=(a028-a110);
  a042=(a108*a083);
  a091=(a079*a093);
  a091=(a042+a091);
  a176=(a010*a012);
  a091=(a091+a176);
  a176=(a081*a181);
  a176=(a113+a176);
  a091=(a091+a176);
  a025=(a025*a036);
  a091=(a091+a025);
  a025=(a023*a091);
  a176=(a114*a022);
  a025=(a025-a176);
  a028=(a028-a025);
  a067=(a067*a013);
  a108=(a108*a067);
  a093=(a015*a093);
  a093=(a108+a093);
  a012=(a003*a012);
  a012=(a128+a012);
  a093=(a093+a012);
  a181=(a002*a181);
  a181=(a178+a181);
  a093=(a093+a181);
  a181=(a016*a093);
  a012=(a115*a011);
  a181=(a181-a012);
  a028=(a028+a181);
  a181=(a020*a028);
  a181=(a032+a181);
  a013=(a016*a091);
  a025=(a114*a011);
  a013=(a013-a025);
  a183=(a106*a057);
  a185=(a050*a160);
  a185=(a183+a185);
  a013=(a013-a185);
  a185=(a023*a093);
  a022=(a115*a022);
  a185=(a185-a022);
  a013=(a013+a185);
  a185=(a058*a013);
  a185=(a123+a185);
  a181=(a181+a185);
  a160=(a016*a160);
  a106=(a106*a011);
  a160=(a160-a106);
  a114=(a114*a057);
  a091=(a050*a091);
  a091=(a114+a091);
  a160=(a160+a091);
  a093=(a056*a093);
  a115=(a115*a018);
  a093=(a093-a115);
  a160=(a160-a093);
  a093=(a006*a160);
  a181=(a181+a093);
  if (res[1]!=0) res[1][15]=a181;
  a083=(a111*a083);
  a181=(a029*a028);
  a181=(a083+a181);
  a093=(a010*a013);
  a181=(a181+a093);
  a093=(a037*a160);
  a093=(a093-a148);
  a181=(a181+a093);
  if (res[1]!=0) res[1][16]=a181;
  a111=(a111*a067);
  a028=(a015*a028);
  a028=(a111+a028);
  a013=(a064*a013);
  a013=(a145+a013);
  a028=(a028+a013);
  a160=(a041*a160);
  a160=(a158+a160);
  a028=(a028+a160);
  if (res[1]!=0) res[1][17]=a028;
  if (res[1]!=0) res[1][18]=a090;
  if (res[1]!=0) res[1][19]=a101;
  if (res[1]!=0) res[1][20]=a104;
  a102=(a000*a102);
  a102=(a033+a102);
  a102=(2.*a102);
  a052=(a052*a102);
  a052=(a000*a052);
  a102=(a027*a052);
  a120=(a120+a102);
  a118=(a118-a120);
  a118=(a118/a001);
  a120=(a023*a118);
  a117=(a117+a120);
  a117=(a117-a125);
  a052=(a061*a052);
  a082=(a082+a052);
  a082=(a082-a126);
  a082=(a082/a001);
  a126=(a016*a082);
  a126=(a126-a127);
  a117=(a117+a126);
  a117=(a001*a117);
  a126=(a021*a117);
  a126=(a051+a126);
  a127=(a016*a118);
  a127=(a127-a132);
  a129=(a129+a127);
  a127=(a023*a082);
  a133=(a133+a127);
  a129=(a129-a133);
  a129=(a001*a129);
  a133=(a072*a129);
  a133=(a128+a133);
  a126=(a126+a133);
  a118=(a050*a118);
  a118=(a118-a135);
  a100=(a100-a118);
  a082=(a056*a082);
  a082=(a082-a136);
  a100=(a100+a082);
  a100=(a001*a100);
  a082=(a006*a100);
  a134=(a134+a082);
  a126=(a126+a134);
  a134=(a056*a126);
  a134=(a134-a137);
  a137=(a079*a117);
  a137=(a137-a140);
  a082=(a010*a129);
  a137=(a137+a082);
  a082=(a081*a100);
  a141=(a141+a082);
  a137=(a137+a141);
  a141=(a023*a137);
  a138=(a138+a141);
  a134=(a134-a138);
  a117=(a015*a117);
  a129=(a003*a129);
  a129=(a142+a129);
  a117=(a117+a129);
  a100=(a002*a100);
  a131=(a131+a100);
  a117=(a117+a131);
  a131=(a016*a117);
  a131=(a131-a143);
  a134=(a134+a131);
  a131=(a020*a134);
  a131=(a024+a131);
  a143=(a016*a137);
  a143=(a143-a147);
  a147=(a050*a126);
  a147=(a147-a149);
  a143=(a143-a147);
  a147=(a023*a117);
  a116=(a116+a147);
  a143=(a143+a116);
  a116=(a058*a143);
  a116=(a145+a116);
  a131=(a131+a116);
  a126=(a016*a126);
  a126=(a126-a087);
  a137=(a050*a137);
  a137=(a137-a130);
  a126=(a126+a137);
  a117=(a056*a117);
  a117=(a117-a119);
  a126=(a126-a117);
  a117=(a006*a126);
  a078=(a078+a117);
  a131=(a131+a078);
  if (res[1]!=0) res[1][21]=a131;
  a131=(a029*a134);
  a131=(a122+a131);
  a078=(a010*a143);
  a131=(a131+a078);
  a078=(a037*a126);
  a139=(a139+a078);
  a131=(a131+a139);
  if (res[1]!=0) res[1][22]=a131;
  a134=(a015*a134);
  a143=(a064*a143);
  a143=(a143-a123);
  a134=(a134+a143);
  a126=(a041*a126);
  a146=(a146+a126);
  a134=(a134+a146);
  if (res[1]!=0) res[1][23]=a134;
  if (res[1]!=0) res[1][24]=a151;
  if (res[1]!=0) res[1][25]=a152;
  if (res[1]!=0) res[1][26]=a099;
  a150=(a000*a150);
  a150=(a033+a150);
  a150=(2.*a150);
  a068=(a068*a150);
  a068=(a000*a068);
  a150=(a027*a068);
  a153=(a153+a150);
  a153=(a153-a165);
  a153=(a153/a001);
  a165=(a056*a153);
  a162=(a162+a165);
  a159=(a159-a162);
  a068=(a047*a068);
  a155=(a155+a068);
  a166=(a166-a155);
  a166=(a166/a001);
  a155=(a016*a166);
  a155=(a155-a167);
  a159=(a159+a155);
  a159=(a001*a159);
  a155=(a021*a159);
  a140=(a140+a155);
  a155=(a050*a153);
  a155=(a155-a171);
  a155=(a155+a172);
  a172=(a023*a166);
  a172=(a172-a174);
  a155=(a155-a172);
  a155=(a001*a155);
  a172=(a072*a155);
  a168=(a168+a172);
  a140=(a140+a168);
  a153=(a016*a153);
  a153=(a153-a173);
  a153=(a153-a157);
  a166=(a056*a166);
  a175=(a175+a166);
  a153=(a153+a175);
  a153=(a001*a153);
  a175=(a006*a153);
  a140=(a140+a175);
  a175=(a056*a140);
  a154=(a154+a175);
  a175=(a079*a159);
  a051=(a051+a175);
  a175=(a010*a155);
  a177=(a177+a175);
  a051=(a051+a177);
  a177=(a081*a153);
  a177=(a178+a177);
  a051=(a051+a177);
  a177=(a023*a051);
  a177=(a177-a180);
  a154=(a154-a177);
  a159=(a015*a159);
  a155=(a003*a155);
  a112=(a112+a155);
  a159=(a159+a112);
  a153=(a002*a153);
  a153=(a153-a113);
  a159=(a159+a153);
  a153=(a016*a159);
  a153=(a153-a169);
  a154=(a154+a153);
  a153=(a020*a154);
  a153=(a153-a122);
  a122=(a016*a051);
  a122=(a122-a182);
  a182=(a050*a140);
  a182=(a182-a184);
  a122=(a122-a182);
  a182=(a023*a159);
  a182=(a182-a161);
  a122=(a122+a182);
  a182=(a058*a122);
  a179=(a179+a182);
  a153=(a153+a179);
  a140=(a016*a140);
  a140=(a140-a124);
  a051=(a050*a051);
  a051=(a051-a170);
  a140=(a140+a051);
  a159=(a056*a159);
  a156=(a156+a159);
  a140=(a140-a156);
  a156=(a006*a140);
  a153=(a153+a156);
  if (res[1]!=0) res[1][27]=a153;
  a153=(a029*a154);
  a024=(a024+a153);
  a153=(a010*a122);
  a008=(a008+a153);
  a024=(a024+a008);
  a008=(a037*a140);
  a008=(a158+a008);
  a024=(a024+a008);
  if (res[1]!=0) res[1][28]=a024;
  a154=(a015*a154);
  a122=(a064*a122);
  a144=(a144+a122);
  a154=(a154+a144);
  a140=(a041*a140);
  a140=(a148+a140);
  a154=(a154+a140);
  if (res[1]!=0) res[1][29]=a154;
  if (res[1]!=0) res[1][30]=a163;
  if (res[1]!=0) res[1][31]=a059;
  if (res[1]!=0) res[1][32]=a038;
  a019=(a000*a019);
  a033=(a033+a019);
  a033=(2.*a033);
  a036=(a036*a033);
  a000=(a000*a036);
  a036=(a047*a000);
  a121=(a121+a036);
  a121=(a121-a045);
  a121=(a121/a001);
  a045=(a023*a121);
  a045=(a045-a030);
  a000=(a061*a000);
  a014=(a014+a000);
  a062=(a062-a014);
  a062=(a062/a001);
  a014=(a056*a062);
  a014=(a014-a164);
  a045=(a045-a014);
  a045=(a045+a009);
  a045=(a001*a045);
  a021=(a021*a045);
  a004=(a004+a021);
  a021=(a050*a062);
  a017=(a017+a021);
  a021=(a016*a121);
  a021=(a021-a065);
  a017=(a017+a021);
  a017=(a017-a034);
  a017=(a001*a017);
  a072=(a072*a017);
  a072=(a072-a142);
  a004=(a004+a072);
  a062=(a016*a062);
  a062=(a062-a109);
  a121=(a050*a121);
  a105=(a105+a121);
  a062=(a062-a105);
  a062=(a062+a005);
  a001=(a001*a062);
  a062=(a006*a001);
  a004=(a004+a062);
  a062=(a056*a004);
  a062=(a062-a110);
  a079=(a079*a045);
  a042=(a042+a079);
  a079=(a010*a017);
  a042=(a042+a079);
  a081=(a081*a001);
  a113=(a113+a081);
  a042=(a042+a113);
  a113=(a023*a042);
  a113=(a113-a176);
  a062=(a062-a113);
  a045=(a015*a045);
  a108=(a108+a045);
  a003=(a003*a017);
  a128=(a128+a003);
  a108=(a108+a128);
  a002=(a002*a001);
  a178=(a178+a002);
  a108=(a108+a178);
  a178=(a016*a108);
  a178=(a178-a012);
  a062=(a062+a178);
  a178=(a020*a062);
  a032=(a032+a178);
  a178=(a016*a042);
  a178=(a178-a025);
  a025=(a050*a004);
  a183=(a183+a025);
  a178=(a178-a183);
  a183=(a023*a108);
  a183=(a183-a022);
  a178=(a178+a183);
  a183=(a058*a178);
  a123=(a123+a183);
  a032=(a032+a123);
  a004=(a016*a004);
  a004=(a004-a106);
  a042=(a050*a042);
  a114=(a114+a042);
  a004=(a004+a114);
  a108=(a056*a108);
  a108=(a108-a115);
  a004=(a004-a108);
  a108=(a006*a004);
  a032=(a032+a108);
  if (res[1]!=0) res[1][33]=a032;
  a032=(a029*a062);
  a083=(a083+a032);
  a032=(a010*a178);
  a083=(a083+a032);
  a032=(a037*a004);
  a032=(a032-a148);
  a083=(a083+a032);
  if (res[1]!=0) res[1][34]=a083;
  a062=(a015*a062);
  a111=(a111+a062);
  a178=(a064*a178);
  a145=(a145+a178);
  a111=(a111+a145);
  a004=(a041*a004);
  a158=(a158+a004);
  a111=(a111+a158);
  if (res[1]!=0) res[1][35]=a111;
  a111=(a063*a092);
  a158=(a066*a089);
  a111=(a111-a158);
  a111=(a084*a111);
  a158=(a063*a098);
  a004=(a066*a097);
  a158=(a158-a004);
  a158=(a096*a158);
  a111=(a111+a158);
  a070=(a027*a070);
  a111=(a111+a070);
  if (res[2]!=0) res[2][0]=a111;
  a111=(a031*a092);
  a070=(a035*a089);
  a111=(a111-a070);
  a111=(a094*a111);
  a070=(a031*a098);
  a158=(a035*a097);
  a070=(a070-a158);
  a070=(a103*a070);
  a111=(a111+a070);
  a048=(a047*a048);
  a111=(a111+a048);
  if (res[2]!=0) res[2][1]=a111;
  a111=(a039*a092);
  a048=(a043*a089);
  a111=(a111-a048);
  a111=(a007*a111);
  a048=(a039*a098);
  a070=(a043*a097);
  a048=(a048-a070);
  a048=(a107*a048);
  a111=(a111+a048);
  a040=(a061*a040);
  a111=(a111+a040);
  if (res[2]!=0) res[2][2]=a111;
  a111=(a020*a055);
  a040=(a058*a069);
  a111=(a111+a040);
  a040=(a006*a075);
  a111=(a111+a040);
  if (res[2]!=0) res[2][3]=a111;
  a111=(a029*a055);
  a040=(a010*a069);
  a111=(a111+a040);
  a040=(a037*a075);
  a111=(a111+a040);
  if (res[2]!=0) res[2][4]=a111;
  a055=(a015*a055);
  a069=(a064*a069);
  a055=(a055+a069);
  a075=(a041*a075);
  a055=(a055+a075);
  if (res[2]!=0) res[2][5]=a055;
  a055=(a066*a076);
  a075=(a060*a092);
  a055=(a055-a075);
  a055=(a084*a055);
  a066=(a066*a095);
  a075=(a060*a098);
  a066=(a066-a075);
  a066=(a096*a066);
  a055=(a055+a066);
  a073=(a027*a073);
  a055=(a055+a073);
  if (res[2]!=0) res[2][6]=a055;
  a055=(a035*a076);
  a073=(a026*a092);
  a055=(a055-a073);
  a055=(a094*a055);
  a035=(a035*a095);
  a073=(a026*a098);
  a035=(a035-a073);
  a035=(a103*a035);
  a055=(a055+a035);
  a071=(a047*a071);
  a055=(a055+a071);
  if (res[2]!=0) res[2][7]=a055;
  a055=(a043*a076);
  a092=(a046*a092);
  a055=(a055-a092);
  a055=(a007*a055);
  a043=(a043*a095);
  a098=(a046*a098);
  a043=(a043-a098);
  a043=(a107*a043);
  a055=(a055+a043);
  a049=(a061*a049);
  a055=(a055+a049);
  if (res[2]!=0) res[2][8]=a055;
  a055=(a020*a053);
  a049=(a058*a077);
  a055=(a055+a049);
  a049=(a006*a085);
  a055=(a055+a049);
  if (res[2]!=0) res[2][9]=a055;
  a055=(a029*a053);
  a049=(a010*a077);
  a055=(a055+a049);
  a049=(a037*a085);
  a055=(a055+a049);
  if (res[2]!=0) res[2][10]=a055;
  a053=(a015*a053);
  a077=(a064*a077);
  a053=(a053+a077);
  a085=(a041*a085);
  a053=(a053+a085);
  if (res[2]!=0) res[2][11]=a053;
  a053=(a060*a089);
  a085=(a063*a076);
  a053=(a053-a085);
  a084=(a084*a053);
  a060=(a060*a097);
  a063=(a063*a095);
  a060=(a060-a063);
  a096=(a096*a060);
  a084=(a084+a096);
  a027=(a027*a088);
  a084=(a084+a027);
  if (res[2]!=0) res[2][12]=a084;
  a084=(a026*a089);
  a027=(a031*a076);
  a084=(a084-a027);
  a094=(a094*a084);
  a026=(a026*a097);
  a031=(a031*a095);
  a026=(a026-a031);
  a103=(a103*a026);
  a094=(a094+a103);
  a047=(a047*a080);
  a094=(a094+a047);
  if (res[2]!=0) res[2][13]=a094;
  a089=(a046*a089);
  a076=(a039*a076);
  a089=(a089-a076);
  a007=(a007*a089);
  a046=(a046*a097);
  a039=(a039*a095);
  a046=(a046-a039);
  a107=(a107*a046);
  a007=(a007+a107);
  a061=(a061*a054);
  a007=(a007+a061);
  if (res[2]!=0) res[2][14]=a007;
  a007=(a020*a086);
  a061=(a058*a044);
  a007=(a007+a061);
  a061=(a006*a074);
  a007=(a007+a061);
  if (res[2]!=0) res[2][15]=a007;
  a007=(a029*a086);
  a061=(a010*a044);
  a007=(a007+a061);
  a061=(a037*a074);
  a007=(a007+a061);
  if (res[2]!=0) res[2][16]=a007;
  a086=(a015*a086);
  a044=(a064*a044);
  a086=(a086+a044);
  a074=(a041*a074);
  a086=(a086+a074);
  if (res[2]!=0) res[2][17]=a086;
  a086=0.;
  if (res[2]!=0) res[2][18]=a086;
  if (res[2]!=0) res[2][19]=a086;
  if (res[2]!=0) res[2][20]=a086;
  a074=(a020*a056);
  a044=(a058*a050);
  a074=(a074-a044);
  a044=(a006*a016);
  a074=(a074+a044);
  if (res[2]!=0) res[2][21]=a074;
  a074=(a029*a056);
  a044=(a010*a050);
  a074=(a074-a044);
  a044=(a037*a016);
  a074=(a074+a044);
  if (res[2]!=0) res[2][22]=a074;
  a074=(a015*a056);
  a044=(a064*a050);
  a074=(a074-a044);
  a044=(a041*a016);
  a074=(a074+a044);
  if (res[2]!=0) res[2][23]=a074;
  if (res[2]!=0) res[2][24]=a086;
  if (res[2]!=0) res[2][25]=a086;
  if (res[2]!=0) res[2][26]=a086;
  a074=(a058*a016);
  a044=(a020*a023);
  a074=(a074-a044);
  a044=(a006*a050);
  a074=(a074+a044);
  if (res[2]!=0) res[2][27]=a074;
  a074=(a010*a016);
  a044=(a029*a023);
  a074=(a074-a044);
  a044=(a037*a050);
  a074=(a074+a044);
  if (res[2]!=0) res[2][28]=a074;
  a074=(a064*a016);
  a044=(a015*a023);
  a074=(a074-a044);
  a050=(a041*a050);
  a074=(a074+a050);
  if (res[2]!=0) res[2][29]=a074;
  if (res[2]!=0) res[2][30]=a086;
  if (res[2]!=0) res[2][31]=a086;
  if (res[2]!=0) res[2][32]=a086;
  a020=(a020*a016);
  a058=(a058*a023);
  a020=(a020+a058);
  a006=(a006*a056);
  a020=(a020-a006);
  if (res[2]!=0) res[2][33]=a020;
  a029=(a029*a016);
  a010=(a010*a023);
  a029=(a029+a010);
  a037=(a037*a056);
  a029=(a029-a037);
  if (res[2]!=0) res[2][34]=a029;
  a015=(a015*a016);
  a064=(a064*a023);
  a015=(a015+a064);
  a041=(a041*a056);
  a015=(a015-a041);
  if (res[2]!=0) res[2][35]=a015;
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

#define HPGEN_ABI 5
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
    double dz0[HPGEN_NZ];            /* predictor: z_j - G_j of the last three steps j = k-1, */
    double dz1[HPGEN_NZ];            /* k-2, k-3 (G_j the guess at step j's start, see */
    double dz2[HPGEN_NZ];            /* hpgen_run_step) */
    double lu[HPGEN_NZ * HPGEN_NZ];  /* J^{-1} of the last Jacobian (simplified Newton) */
    int piv[HPGEN_NZ];
    long long k;                     /* steps done */
    long long have_prev;             /* how many of dz0, dz1, dz2 are valid (0..3) */
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
#define HPGEN_RESIDUAL_SZ_W 44
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
#define HPGEN_RESIDUAL_JACOBIAN_SZ_W 127
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
#define HPGEN_UPDATE_SZ_W 42
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
#define HPGEN_UPDATE_P_SZ_W 43
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
#define HPGEN_STEP_PARTIALS_SZ_W 186
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

/* One step of run r with hv = {h}: the Newton start from the predictor, the step, and on
   success the run moved to (g_{k+1}, p_{k+1}) (with_g = 0: p_{k+1} only); o for the steps
   after the first, full (o with full Newton) for the first. Updates the counters of st;
   returns the status code.
   Predictor: z_k = G_k + dz_k with G_k = hpgen_predictor_base(g_k, p_k) (exact in p, O(1))
   and dz_k = z_k - G_k small (O(h)) and smooth in k; the start is G_k plus the polynomial
   through the last dz extrapolated one step (quadratic 3 (dz_{k-1} - dz_{k-2}) + dz_{k-3}
   once three exist, linear, then constant before). Extrapolating z itself (the predictor
   before) left errors 5-7x larger on the heavy top (docs/performance.md). */
static int hpgen_run_step(hpgen_run* r, const double* hv, const hpgen_options* o,
                          const hpgen_options* full, hpgen_status* st, int with_g) {
    double g1[HPGEN_NN], p1[HPGEN_D], zs[HPGEN_NZ], G[HPGEN_NZ], res;
    long long it;
    int i, code, predicted = o->predictor && r->have_prev >= 1;
    hpgen_predictor_base(r->g, r->p, hv, G);    /* (kept up to date with or without o->predictor) */
    if (o->predictor && r->have_prev >= 3)
        for (i = 0; i < HPGEN_NZ; ++i) zs[i] = G[i] + (3.0 * (r->dz0[i] - r->dz1[i]) + r->dz2[i]);
    else if (o->predictor && r->have_prev == 2)
        for (i = 0; i < HPGEN_NZ; ++i) zs[i] = G[i] + (2.0 * r->dz0[i] - r->dz1[i]);
    else if (o->predictor && r->have_prev == 1)
        for (i = 0; i < HPGEN_NZ; ++i) zs[i] = G[i] + r->dz0[i];
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
    memcpy(r->dz2, r->dz1, sizeof r->z);
    memcpy(r->dz1, r->dz0, sizeof r->z);
    for (i = 0; i < HPGEN_NZ; ++i) r->dz0[i] = zs[i] - G[i];
    if (r->have_prev < 3) r->have_prev += 1;
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
