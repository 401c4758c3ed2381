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
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a014, a015, a016, a017, a018, a019, a020, a021, a022, a023;
  casadi_real a024, a025, a026, a027, a028, a029, a030, a031, a032, a033, a034, a035;
  casadi_real a036, a037, a038, a039, a040, a041, a042, a043, a044, a045, a046, a047;
  casadi_real a048, a049, a050, a051, a052, a053, a054, a055, a056, a057, a058, a059;
  casadi_real a060, a061, a062, a063, a064, a065, a066, a067, a068, a069, a070, a071;
  casadi_real a072, a073, a074, a075, a076, a077, a078, a079, a080, a081, a082, a083;
  casadi_real a084, a085, a086, a087, a088, a089, a090, a091, a092, a093, a094, a095;
  casadi_real a096, a097, a098, a099, a100, a101, a102, a103, a104, a105, a106, a107;
  casadi_real a108, a109, a110, a111, a112;
  a000=arg[3]? arg[3][0] : 0;
  a001=arg[0]? arg[0][2] : 0;
  a002=(a000*a001);
  a003=arg[0]? arg[0][0] : 0;
  a004=(a000*a003);
  a005=(a002*a004);
  a006=4.;
  a007=(a005/a006);
  a008=arg[0]? arg[0][1] : 0;
  a009=(a000*a008);
  a010=2.;
  a011=(a009/a010);
  a012=(a007-a011);
  a013=1.5000000000000002e+00;
  a014=casadi_sq(a004);
  a015=casadi_sq(a009);
  a016=(a014+a015);
  a017=casadi_sq(a002);
  a016=(a016+a017);
  a016=(a006+a016);
  a016=(a006/a016);
  a018=(a004/a010);
  a019=(a016*a018);
  a020=3.0000000000000004e+00;
  a021=(a020*a008);
  a022=4.6410161513775439e-01;
  a023=arg[0]? arg[0][4] : 0;
  a024=(a022*a023);
  a021=(a021+a024);
  a024=(a016*a021);
  a025=(a002/a010);
  a026=(a016*a025);
  a027=(a020*a003);
  a028=arg[0]? arg[0][3] : 0;
  a029=(a022*a028);
  a027=(a027+a029);
  a029=(a026*a027);
  a024=(a024-a029);
  a029=(a020*a001);
  a030=arg[0]? arg[0][5] : 0;
  a022=(a022*a030);
  a029=(a029+a022);
  a022=(a019*a029);
  a024=(a024+a022);
  a022=(2.*a024);
  a031=1.1718750000000000e-01;
  a031=(a031*a000);
  a022=(a022*a031);
  a032=(a002*a009);
  a033=(a032/a006);
  a034=(a018+a033);
  a035=5.0000000000000000e-01;
  a036=arg[0]? arg[0][8] : 0;
  a037=(a000*a036);
  a037=(a035*a037);
  a038=(a034*a037);
  a039=1.;
  a040=(a015/a006);
  a040=(a039+a040);
  a041=arg[0]? arg[0][7] : 0;
  a042=(a000*a041);
  a042=(a035*a042);
  a043=(a040*a042);
  a038=(a038+a043);
  a043=(a004*a009);
  a044=(a043/a006);
  a045=(a044-a025);
  a046=arg[0]? arg[0][6] : 0;
  a047=(a000*a046);
  a047=(a035*a047);
  a048=(a045*a047);
  a038=(a038+a048);
  a022=(a022-a038);
  a038=(a035*a000);
  a022=(a022/a038);
  a048=(a019*a022);
  a049=(a016*a011);
  a050=(a016*a027);
  a051=(a026*a021);
  a050=(a050+a051);
  a051=(a049*a029);
  a050=(a050-a051);
  a051=(2.*a050);
  a052=3.8085937500000000e+00;
  a052=(a052*a000);
  a051=(a051*a052);
  a053=(a012*a037);
  a054=(a009*a004);
  a054=(a054/a006);
  a055=(a025+a054);
  a056=(a055*a042);
  a053=(a053+a056);
  a056=(a014/a006);
  a056=(a039+a056);
  a057=(a056*a047);
  a053=(a053+a057);
  a051=(a051-a053);
  a051=(a051/a038);
  a053=(a049*a051);
  a048=(a048-a053);
  a053=(a049*a027);
  a057=(a019*a021);
  a053=(a053-a057);
  a057=(a016*a029);
  a053=(a053+a057);
  a057=(2.*a053);
  a057=(a057*a052);
  a058=(a017/a006);
  a058=(a039+a058);
  a059=(a058*a037);
  a060=(a009*a002);
  a060=(a060/a006);
  a061=(a060-a018);
  a062=(a061*a042);
  a059=(a059+a062);
  a062=(a004*a002);
  a063=(a062/a006);
  a064=(a011+a063);
  a065=(a064*a047);
  a059=(a059+a065);
  a057=(a057-a059);
  a057=(a057/a038);
  a059=(a016*a057);
  a048=(a048+a059);
  a059=(a013*a048);
  a065=-3.2320508075688776e+00;
  a066=(a000*a028);
  a067=casadi_sq(a066);
  a068=(a000*a023);
  a069=casadi_sq(a068);
  a070=(a067+a069);
  a071=(a000*a030);
  a072=casadi_sq(a071);
  a070=(a070+a072);
  a070=(a006+a070);
  a070=(a006/a070);
  a073=(a066/a010);
  a074=(a070*a073);
  a075=-6.4641016151377553e+00;
  a008=(a075*a008);
  a023=(a020*a023);
  a008=(a008+a023);
  a023=(a070*a008);
  a076=(a071/a010);
  a077=(a070*a076);
  a003=(a075*a003);
  a028=(a020*a028);
  a003=(a003+a028);
  a028=(a077*a003);
  a023=(a023-a028);
  a075=(a075*a001);
  a020=(a020*a030);
  a075=(a075+a020);
  a020=(a074*a075);
  a023=(a023+a020);
  a020=(2.*a023);
  a020=(a020*a031);
  a031=(a071*a068);
  a030=(a031/a006);
  a001=(a073+a030);
  a028=(a001*a037);
  a020=(a020-a028);
  a028=(a069/a006);
  a028=(a039+a028);
  a078=(a028*a042);
  a020=(a020-a078);
  a078=(a066*a068);
  a079=(a078/a006);
  a080=(a079-a076);
  a081=(a080*a047);
  a020=(a020-a081);
  a020=(a020/a038);
  a081=(a074*a020);
  a082=(a068/a010);
  a083=(a070*a082);
  a084=(a070*a003);
  a085=(a077*a008);
  a084=(a084+a085);
  a085=(a083*a075);
  a084=(a084-a085);
  a085=(2.*a084);
  a085=(a085*a052);
  a086=(a071*a066);
  a087=(a086/a006);
  a088=(a087-a082);
  a089=(a088*a037);
  a085=(a085-a089);
  a089=(a068*a066);
  a089=(a089/a006);
  a090=(a076+a089);
  a091=(a090*a042);
  a085=(a085-a091);
  a091=(a067/a006);
  a091=(a039+a091);
  a092=(a091*a047);
  a085=(a085-a092);
  a085=(a085/a038);
  a092=(a083*a085);
  a081=(a081-a092);
  a092=(a083*a003);
  a093=(a074*a008);
  a092=(a092-a093);
  a093=(a070*a075);
  a092=(a092+a093);
  a093=(2.*a092);
  a093=(a093*a052);
  a052=(a072/a006);
  a052=(a039+a052);
  a094=(a052*a037);
  a093=(a093-a094);
  a094=(a068*a071);
  a094=(a094/a006);
  a095=(a094-a073);
  a096=(a095*a042);
  a093=(a093-a096);
  a096=(a066*a071);
  a097=(a096/a006);
  a098=(a082+a097);
  a099=(a098*a047);
  a093=(a093-a099);
  a093=(a093/a038);
  a038=(a070*a093);
  a081=(a081+a038);
  a038=(a065*a081);
  a059=(a059+a038);
  a038=(2.*a002);
  a099=2.5000000000000000e-01;
  a100=5.3867513459481287e-01;
  a101=2.3205080756887719e-01;
  a048=(a101*a048);
  a081=(a013*a081);
  a048=(a048+a081);
  a081=(a000*a048);
  a102=(a100*a081);
  a102=(a037+a102);
  a103=(a000*a059);
  a104=(a099*a103);
  a102=(a102+a104);
  a104=(a053*a102);
  a104=(a099*a104);
  a038=(a038*a104);
  a059=(a059-a038);
  a038=(a024*a102);
  a104=(a099*a038);
  a105=(a009*a104);
  a059=(a059-a105);
  a102=(a050*a102);
  a105=(a099*a102);
  a106=(a004*a105);
  a059=(a059-a106);
  a106=(a026*a051);
  a107=(a016*a022);
  a106=(a106+a107);
  a019=(a019*a057);
  a106=(a106-a019);
  a019=(a101*a106);
  a107=(a077*a085);
  a108=(a070*a020);
  a107=(a107+a108);
  a074=(a074*a093);
  a107=(a107-a074);
  a074=(a013*a107);
  a019=(a019+a074);
  a074=(a000*a019);
  a108=(a100*a074);
  a108=(a042+a108);
  a106=(a013*a106);
  a107=(a065*a107);
  a106=(a106+a107);
  a107=(a000*a106);
  a109=(a099*a107);
  a108=(a108+a109);
  a109=(a053*a108);
  a110=(a099*a109);
  a111=(a009*a110);
  a059=(a059-a111);
  a111=(a050*a108);
  a112=(a035*a111);
  a059=(a059-a112);
  a051=(a016*a051);
  a026=(a026*a022);
  a051=(a051-a026);
  a049=(a049*a057);
  a051=(a051+a049);
  a101=(a101*a051);
  a085=(a070*a085);
  a077=(a077*a020);
  a085=(a085-a077);
  a083=(a083*a093);
  a085=(a085+a083);
  a083=(a013*a085);
  a101=(a101+a083);
  a083=(a000*a101);
  a100=(a100*a083);
  a100=(a047+a100);
  a013=(a013*a051);
  a065=(a065*a085);
  a013=(a013+a065);
  a065=(a000*a013);
  a085=(a099*a065);
  a100=(a100+a085);
  a053=(a053*a100);
  a085=(a099*a053);
  a051=(a004*a085);
  a059=(a059-a051);
  a051=(a024*a100);
  a093=(a035*a051);
  a059=(a059+a093);
  a012=(a012*a059);
  a102=(a035*a102);
  a104=(a002*a104);
  a102=(a102-a104);
  a102=(a102+a106);
  a110=(a002*a110);
  a102=(a102-a110);
  a110=(2.*a009);
  a024=(a024*a108);
  a024=(a099*a024);
  a110=(a110*a024);
  a102=(a102-a110);
  a111=(a099*a111);
  a110=(a004*a111);
  a102=(a102-a110);
  a053=(a035*a053);
  a102=(a102-a053);
  a051=(a099*a051);
  a053=(a004*a051);
  a102=(a102-a053);
  a055=(a055*a102);
  a012=(a012+a055);
  a109=(a035*a109);
  a038=(a035*a038);
  a105=(a002*a105);
  a038=(a038+a105);
  a109=(a109-a038);
  a111=(a009*a111);
  a109=(a109-a111);
  a109=(a109+a013);
  a085=(a002*a085);
  a109=(a109-a085);
  a051=(a009*a051);
  a109=(a109-a051);
  a051=(2.*a004);
  a050=(a050*a100);
  a050=(a099*a050);
  a051=(a051*a050);
  a109=(a109-a051);
  a056=(a056*a109);
  a012=(a012+a056);
  a051=arg[1]? arg[1][2] : 0;
  a005=(a005/a010);
  a005=(a009+a005);
  a005=(a016*a005);
  a005=(a051*a005);
  a050=arg[1]? arg[1][5] : 0;
  a032=(a032/a010);
  a032=(a032-a004);
  a032=(a016*a032);
  a032=(a050*a032);
  a005=(a005+a032);
  a032=arg[1]? arg[1][8] : 0;
  a014=(a015+a014);
  a014=(a014/a010);
  a014=(a016*a014);
  a014=(a039-a014);
  a014=(a032*a014);
  a005=(a005+a014);
  a014=-7.3575000000000003e+01;
  a014=(a014*a000);
  a005=(a005*a014);
  a012=(a012+a005);
  a012=(a012/a000);
  if (res[0]!=0) res[0][0]=a012;
  a034=(a034*a059);
  a040=(a040*a102);
  a034=(a034+a040);
  a045=(a045*a109);
  a034=(a034+a045);
  a034=(a034/a000);
  if (res[0]!=0) res[0][1]=a034;
  a058=(a058*a059);
  a061=(a061*a102);
  a061=(a058+a061);
  a064=(a064*a109);
  a061=(a061+a064);
  a017=(a017+a015);
  a017=(a017/a010);
  a017=(a016*a017);
  a017=(a039-a017);
  a017=(a051*a017);
  a043=(a043/a010);
  a002=(a002+a043);
  a002=(a016*a002);
  a002=(a050*a002);
  a017=(a017+a002);
  a062=(a062/a010);
  a062=(a062-a009);
  a016=(a016*a062);
  a016=(a032*a016);
  a017=(a017+a016);
  a017=(a017*a014);
  a061=(a061-a017);
  a061=(a061/a000);
  if (res[0]!=0) res[0][2]=a061;
  a086=(a086/a010);
  a086=(a068+a086);
  a086=(a070*a086);
  a086=(a051*a086);
  a031=(a031/a010);
  a031=(a031-a066);
  a031=(a070*a031);
  a031=(a050*a031);
  a086=(a086+a031);
  a067=(a069+a067);
  a067=(a067/a010);
  a067=(a070*a067);
  a067=(a039-a067);
  a067=(a032*a067);
  a086=(a086+a067);
  a086=(a086*a014);
  a067=(2.*a071);
  a081=(a099*a081);
  a037=(a037+a081);
  a081=-3.8675134594812879e-02;
  a103=(a081*a103);
  a037=(a037+a103);
  a103=(a092*a037);
  a103=(a099*a103);
  a067=(a067*a103);
  a048=(a048-a067);
  a067=(a023*a037);
  a103=(a099*a067);
  a031=(a068*a103);
  a048=(a048-a031);
  a037=(a084*a037);
  a031=(a099*a037);
  a061=(a066*a031);
  a048=(a048-a061);
  a074=(a099*a074);
  a042=(a042+a074);
  a107=(a081*a107);
  a042=(a042+a107);
  a107=(a092*a042);
  a074=(a099*a107);
  a061=(a068*a074);
  a048=(a048-a061);
  a061=(a084*a042);
  a017=(a035*a061);
  a048=(a048-a017);
  a083=(a099*a083);
  a047=(a047+a083);
  a081=(a081*a065);
  a047=(a047+a081);
  a092=(a092*a047);
  a081=(a099*a092);
  a065=(a066*a081);
  a048=(a048-a065);
  a065=(a023*a047);
  a083=(a035*a065);
  a048=(a048+a083);
  a088=(a088*a048);
  a086=(a086+a088);
  a103=(a071*a103);
  a019=(a019-a103);
  a037=(a035*a037);
  a019=(a019+a037);
  a074=(a071*a074);
  a019=(a019-a074);
  a074=(2.*a068);
  a023=(a023*a042);
  a023=(a099*a023);
  a074=(a074*a023);
  a019=(a019-a074);
  a061=(a099*a061);
  a074=(a066*a061);
  a019=(a019-a074);
  a092=(a035*a092);
  a019=(a019-a092);
  a065=(a099*a065);
  a092=(a066*a065);
  a019=(a019-a092);
  a090=(a090*a019);
  a086=(a086+a090);
  a067=(a035*a067);
  a101=(a101-a067);
  a031=(a071*a031);
  a101=(a101-a031);
  a107=(a035*a107);
  a101=(a101+a107);
  a061=(a068*a061);
  a101=(a101-a061);
  a081=(a071*a081);
  a101=(a101-a081);
  a065=(a068*a065);
  a101=(a101-a065);
  a066=(2.*a066);
  a084=(a084*a047);
  a099=(a099*a084);
  a066=(a066*a099);
  a101=(a101-a066);
  a091=(a091*a101);
  a086=(a086+a091);
  a086=(a086/a000);
  if (res[0]!=0) res[0][3]=a086;
  a001=(a001*a048);
  a028=(a028*a019);
  a001=(a001+a028);
  a080=(a080*a101);
  a001=(a001+a080);
  a001=(a001/a000);
  if (res[0]!=0) res[0][4]=a001;
  a052=(a052*a048);
  a072=(a072+a069);
  a072=(a072/a010);
  a072=(a070*a072);
  a072=(a039-a072);
  a051=(a051*a072);
  a078=(a078/a010);
  a071=(a071+a078);
  a071=(a070*a071);
  a050=(a050*a071);
  a051=(a051+a050);
  a096=(a096/a010);
  a096=(a096-a068);
  a070=(a070*a096);
  a032=(a032*a070);
  a051=(a051+a032);
  a051=(a051*a014);
  a051=(a052-a051);
  a095=(a095*a019);
  a051=(a051+a095);
  a098=(a098*a101);
  a051=(a051+a098);
  a051=(a051/a000);
  if (res[0]!=0) res[0][5]=a051;
  a051=arg[2]? arg[2][0] : 0;
  a021=(a035*a021);
  a008=(a035*a008);
  a021=(a021+a008);
  a021=(a000*a021);
  a008=(a021/a010);
  a029=(a035*a029);
  a075=(a035*a075);
  a029=(a029+a075);
  a029=(a000*a029);
  a027=(a035*a027);
  a035=(a035*a003);
  a027=(a027+a035);
  a000=(a000*a027);
  a027=(a029*a000);
  a027=(a027/a006);
  a027=(a008+a027);
  a027=(a027*a036);
  a035=(a021*a000);
  a035=(a035/a006);
  a003=(a029/a010);
  a035=(a035-a003);
  a035=(a035*a041);
  a027=(a027+a035);
  a035=casadi_sq(a000);
  a035=(a035/a006);
  a035=(a039+a035);
  a035=(a035*a046);
  a027=(a027+a035);
  a087=(a082+a087);
  a087=(a087*a048);
  a027=(a027+a087);
  a089=(a089-a076);
  a089=(a089*a019);
  a027=(a027+a089);
  a027=(a027+a091);
  a007=(a011+a007);
  a007=(a007*a059);
  a027=(a027+a007);
  a054=(a054-a025);
  a054=(a054*a102);
  a027=(a027+a054);
  a027=(a027+a056);
  a051=(a051-a027);
  if (res[0]!=0) res[0][6]=a051;
  a051=arg[2]? arg[2][1] : 0;
  a027=(a029*a021);
  a027=(a027/a006);
  a010=(a000/a010);
  a027=(a027-a010);
  a027=(a027*a036);
  a056=casadi_sq(a021);
  a056=(a056/a006);
  a056=(a039+a056);
  a056=(a056*a041);
  a027=(a027+a056);
  a056=(a000*a021);
  a056=(a056/a006);
  a003=(a003+a056);
  a003=(a003*a046);
  a027=(a027+a003);
  a030=(a030-a073);
  a030=(a030*a048);
  a027=(a027+a030);
  a027=(a027+a028);
  a076=(a076+a079);
  a076=(a076*a101);
  a027=(a027+a076);
  a033=(a033-a018);
  a033=(a033*a059);
  a027=(a027+a033);
  a027=(a027+a040);
  a025=(a025+a044);
  a025=(a025*a109);
  a027=(a027+a025);
  a051=(a051-a027);
  if (res[0]!=0) res[0][7]=a051;
  a051=arg[2]? arg[2][2] : 0;
  a027=casadi_sq(a029);
  a027=(a027/a006);
  a039=(a039+a027);
  a039=(a039*a036);
  a021=(a021*a029);
  a021=(a021/a006);
  a010=(a010+a021);
  a010=(a010*a041);
  a039=(a039+a010);
  a000=(a000*a029);
  a000=(a000/a006);
  a000=(a000-a008);
  a000=(a000*a046);
  a039=(a039+a000);
  a039=(a039+a052);
  a073=(a073+a094);
  a073=(a073*a019);
  a039=(a039+a073);
  a097=(a097-a082);
  a097=(a097*a101);
  a039=(a039+a097);
  a039=(a039+a058);
  a018=(a018+a060);
  a018=(a018*a102);
  a039=(a039+a018);
  a063=(a063-a011);
  a063=(a063*a109);
  a039=(a039+a063);
  a051=(a051-a039);
  if (res[0]!=0) res[0][8]=a051;
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
  casadi_real a156, a157, a158, a159, a160, a161, a162, a163, a164, a165, a166, a167;
  casadi_real a168, a169, a170, a171, a172, a173, a174, a175, a176, a177, a178, a179;
  casadi_real a180, a181, a182, a183, a184, a185, a186, a187, a188, a189, a190, a191;
  casadi_real a192, a193, a194, a195, a196, a197, a198, a199, a200, a201, a202, a203;
  casadi_real a204, a205, a206, a207, a208, a209, a210, a211, a212, a213, a214, a215;
  casadi_real a216, a217, a218, a219, a220, a221, a222, a223, a224, a225, a226, a227;
  a000=arg[3]? arg[3][0] : 0;
  a001=arg[0]? arg[0][2] : 0;
  a002=(a000*a001);
  a003=arg[0]? arg[0][0] : 0;
  a004=(a000*a003);
  a005=(a002*a004);
  a006=4.;
  a007=(a005/a006);
  a008=arg[0]? arg[0][1] : 0;
  a009=(a000*a008);
  a010=2.;
  a011=(a009/a010);
  a012=(a007-a011);
  a013=1.5000000000000002e+00;
  a014=casadi_sq(a004);
  a015=casadi_sq(a009);
  a016=(a014+a015);
  a017=casadi_sq(a002);
  a016=(a016+a017);
  a016=(a006+a016);
  a018=(a006/a016);
  a019=(a004/a010);
  a020=(a018*a019);
  a021=3.0000000000000004e+00;
  a022=(a021*a008);
  a023=4.6410161513775439e-01;
  a024=arg[0]? arg[0][4] : 0;
  a025=(a023*a024);
  a022=(a022+a025);
  a025=(a018*a022);
  a026=(a002/a010);
  a027=(a018*a026);
  a028=(a021*a003);
  a029=arg[0]? arg[0][3] : 0;
  a030=(a023*a029);
  a028=(a028+a030);
  a030=(a027*a028);
  a025=(a025-a030);
  a030=(a021*a001);
  a031=arg[0]? arg[0][5] : 0;
  a032=(a023*a031);
  a030=(a030+a032);
  a032=(a020*a030);
  a025=(a025+a032);
  a032=(2.*a025);
  a033=1.1718750000000000e-01;
  a033=(a033*a000);
  a032=(a032*a033);
  a034=(a002*a009);
  a035=(a034/a006);
  a036=(a019+a035);
  a037=5.0000000000000000e-01;
  a038=arg[0]? arg[0][8] : 0;
  a039=(a000*a038);
  a039=(a037*a039);
  a040=(a036*a039);
  a041=1.;
  a042=(a015/a006);
  a042=(a041+a042);
  a043=arg[0]? arg[0][7] : 0;
  a044=(a000*a043);
  a044=(a037*a044);
  a045=(a042*a044);
  a040=(a040+a045);
  a045=(a004*a009);
  a046=(a045/a006);
  a047=(a046-a026);
  a048=arg[0]? arg[0][6] : 0;
  a049=(a000*a048);
  a049=(a037*a049);
  a050=(a047*a049);
  a040=(a040+a050);
  a032=(a032-a040);
  a040=(a037*a000);
  a032=(a032/a040);
  a050=(a020*a032);
  a051=(a018*a011);
  a052=(a018*a028);
  a053=(a027*a022);
  a052=(a052+a053);
  a053=(a051*a030);
  a052=(a052-a053);
  a053=(2.*a052);
  a054=3.8085937500000000e+00;
  a054=(a054*a000);
  a053=(a053*a054);
  a055=(a012*a039);
  a056=(a009*a004);
  a056=(a056/a006);
  a057=(a026+a056);
  a058=(a057*a044);
  a055=(a055+a058);
  a058=(a014/a006);
  a058=(a041+a058);
  a059=(a058*a049);
  a055=(a055+a059);
  a053=(a053-a055);
  a053=(a053/a040);
  a055=(a051*a053);
  a050=(a050-a055);
  a055=(a051*a028);
  a059=(a020*a022);
  a055=(a055-a059);
  a059=(a018*a030);
  a055=(a055+a059);
  a059=(2.*a055);
  a059=(a059*a054);
  a060=(a017/a006);
  a060=(a041+a060);
  a061=(a060*a039);
  a062=(a009*a002);
  a062=(a062/a006);
  a063=(a062-a019);
  a064=(a063*a044);
  a061=(a061+a064);
  a064=(a004*a002);
  a065=(a064/a006);
  a066=(a011+a065);
  a067=(a066*a049);
  a061=(a061+a067);
  a059=(a059-a061);
  a059=(a059/a040);
  a061=(a018*a059);
  a050=(a050+a061);
  a061=(a013*a050);
  a067=-3.2320508075688776e+00;
  a068=(a000*a029);
  a069=casadi_sq(a068);
  a070=(a000*a024);
  a071=casadi_sq(a070);
  a072=(a069+a071);
  a073=(a000*a031);
  a074=casadi_sq(a073);
  a072=(a072+a074);
  a072=(a006+a072);
  a075=(a006/a072);
  a076=(a068/a010);
  a077=(a075*a076);
  a078=-6.4641016151377553e+00;
  a008=(a078*a008);
  a024=(a021*a024);
  a008=(a008+a024);
  a024=(a075*a008);
  a079=(a073/a010);
  a080=(a075*a079);
  a003=(a078*a003);
  a029=(a021*a029);
  a003=(a003+a029);
  a029=(a080*a003);
  a024=(a024-a029);
  a001=(a078*a001);
  a031=(a021*a031);
  a001=(a001+a031);
  a031=(a077*a001);
  a024=(a024+a031);
  a031=(2.*a024);
  a031=(a031*a033);
  a029=(a073*a070);
  a081=(a029/a006);
  a082=(a076+a081);
  a083=(a082*a039);
  a031=(a031-a083);
  a083=(a071/a006);
  a083=(a041+a083);
  a084=(a083*a044);
  a031=(a031-a084);
  a084=(a068*a070);
  a085=(a084/a006);
  a086=(a085-a079);
  a087=(a086*a049);
  a031=(a031-a087);
  a031=(a031/a040);
  a087=(a077*a031);
  a088=(a070/a010);
  a089=(a075*a088);
  a090=(a075*a003);
  a091=(a080*a008);
  a090=(a090+a091);
  a091=(a089*a001);
  a090=(a090-a091);
  a091=(2.*a090);
  a091=(a091*a054);
  a092=(a073*a068);
  a093=(a092/a006);
  a094=(a093-a088);
  a095=(a094*a039);
  a091=(a091-a095);
  a095=(a070*a068);
  a095=(a095/a006);
  a096=(a079+a095);
  a097=(a096*a044);
  a091=(a091-a097);
  a097=(a069/a006);
  a097=(a041+a097);
  a098=(a097*a049);
  a091=(a091-a098);
  a091=(a091/a040);
  a098=(a089*a091);
  a087=(a087-a098);
  a098=(a089*a003);
  a099=(a077*a008);
  a098=(a098-a099);
  a099=(a075*a001);
  a098=(a098+a099);
  a099=(2.*a098);
  a099=(a099*a054);
  a100=(a074/a006);
  a100=(a041+a100);
  a101=(a100*a039);
  a099=(a099-a101);
  a101=(a070*a073);
  a101=(a101/a006);
  a102=(a101-a076);
  a103=(a102*a044);
  a099=(a099-a103);
  a103=(a068*a073);
  a104=(a103/a006);
  a105=(a088+a104);
  a106=(a105*a049);
  a099=(a099-a106);
  a099=(a099/a040);
  a106=(a075*a099);
  a087=(a087+a106);
  a106=(a067*a087);
  a061=(a061+a106);
  a106=(2.*a002);
  a107=2.5000000000000000e-01;
  a108=5.3867513459481287e-01;
  a109=2.3205080756887719e-01;
  a050=(a109*a050);
  a087=(a013*a087);
  a050=(a050+a087);
  a087=(a000*a050);
  a110=(a108*a087);
  a110=(a039+a110);
  a111=(a000*a061);
  a112=(a107*a111);
  a110=(a110+a112);
  a112=(a055*a110);
  a112=(a107*a112);
  a113=(a106*a112);
  a061=(a061-a113);
  a113=(a025*a110);
  a114=(a107*a113);
  a115=(a009*a114);
  a061=(a061-a115);
  a115=(a052*a110);
  a116=(a107*a115);
  a117=(a004*a116);
  a061=(a061-a117);
  a117=(a027*a053);
  a118=(a018*a032);
  a117=(a117+a118);
  a118=(a020*a059);
  a117=(a117-a118);
  a118=(a109*a117);
  a119=(a080*a091);
  a120=(a075*a031);
  a119=(a119+a120);
  a120=(a077*a099);
  a119=(a119-a120);
  a120=(a013*a119);
  a118=(a118+a120);
  a120=(a000*a118);
  a121=(a108*a120);
  a121=(a044+a121);
  a117=(a013*a117);
  a119=(a067*a119);
  a117=(a117+a119);
  a119=(a000*a117);
  a122=(a107*a119);
  a121=(a121+a122);
  a122=(a055*a121);
  a123=(a107*a122);
  a124=(a009*a123);
  a061=(a061-a124);
  a124=(a052*a121);
  a125=(a037*a124);
  a061=(a061-a125);
  a125=(a018*a053);
  a126=(a027*a032);
  a125=(a125-a126);
  a126=(a051*a059);
  a125=(a125+a126);
  a126=(a109*a125);
  a127=(a075*a091);
  a128=(a080*a031);
  a127=(a127-a128);
  a128=(a089*a099);
  a127=(a127+a128);
  a128=(a013*a127);
  a126=(a126+a128);
  a128=(a000*a126);
  a129=(a108*a128);
  a129=(a049+a129);
  a125=(a013*a125);
  a127=(a067*a127);
  a125=(a125+a127);
  a127=(a000*a125);
  a130=(a107*a127);
  a129=(a129+a130);
  a130=(a055*a129);
  a131=(a107*a130);
  a132=(a004*a131);
  a061=(a061-a132);
  a132=(a025*a129);
  a133=(a037*a132);
  a061=(a061+a133);
  a133=(a012*a061);
  a115=(a037*a115);
  a134=(a002*a114);
  a115=(a115-a134);
  a115=(a115+a117);
  a117=(a002*a123);
  a115=(a115-a117);
  a117=(2.*a009);
  a134=(a025*a121);
  a134=(a107*a134);
  a135=(a117*a134);
  a115=(a115-a135);
  a124=(a107*a124);
  a135=(a004*a124);
  a115=(a115-a135);
  a130=(a037*a130);
  a115=(a115-a130);
  a132=(a107*a132);
  a130=(a004*a132);
  a115=(a115-a130);
  a130=(a057*a115);
  a133=(a133+a130);
  a122=(a037*a122);
  a113=(a037*a113);
  a130=(a002*a116);
  a113=(a113+a130);
  a122=(a122-a113);
  a113=(a009*a124);
  a122=(a122-a113);
  a122=(a122+a125);
  a125=(a002*a131);
  a122=(a122-a125);
  a125=(a009*a132);
  a122=(a122-a125);
  a125=(2.*a004);
  a113=(a052*a129);
  a113=(a107*a113);
  a130=(a125*a113);
  a122=(a122-a130);
  a130=(a058*a122);
  a133=(a133+a130);
  a135=arg[1]? arg[1][2] : 0;
  a005=(a005/a010);
  a005=(a009+a005);
  a136=(a018*a005);
  a136=(a135*a136);
  a137=arg[1]? arg[1][5] : 0;
  a034=(a034/a010);
  a034=(a034-a004);
  a138=(a018*a034);
  a138=(a137*a138);
  a136=(a136+a138);
  a138=arg[1]? arg[1][8] : 0;
  a014=(a015+a014);
  a014=(a014/a010);
  a139=(a018*a014);
  a139=(a041-a139);
  a139=(a138*a139);
  a136=(a136+a139);
  a139=-7.3575000000000003e+01;
  a139=(a139*a000);
  a136=(a136*a139);
  a133=(a133+a136);
  a133=(a133/a000);
  if (res[0]!=0) res[0][0]=a133;
  a133=(a036*a061);
  a136=(a042*a115);
  a133=(a133+a136);
  a140=(a047*a122);
  a133=(a133+a140);
  a133=(a133/a000);
  if (res[0]!=0) res[0][1]=a133;
  a133=(a060*a061);
  a140=(a063*a115);
  a140=(a133+a140);
  a141=(a066*a122);
  a140=(a140+a141);
  a017=(a017+a015);
  a017=(a017/a010);
  a015=(a018*a017);
  a015=(a041-a015);
  a015=(a135*a015);
  a045=(a045/a010);
  a045=(a002+a045);
  a141=(a018*a045);
  a141=(a137*a141);
  a015=(a015+a141);
  a064=(a064/a010);
  a064=(a064-a009);
  a141=(a018*a064);
  a141=(a138*a141);
  a015=(a015+a141);
  a015=(a015*a139);
  a140=(a140-a015);
  a140=(a140/a000);
  if (res[0]!=0) res[0][2]=a140;
  a092=(a092/a010);
  a092=(a070+a092);
  a140=(a075*a092);
  a140=(a135*a140);
  a029=(a029/a010);
  a029=(a029-a068);
  a015=(a075*a029);
  a015=(a137*a015);
  a140=(a140+a015);
  a069=(a071+a069);
  a069=(a069/a010);
  a015=(a075*a069);
  a015=(a041-a015);
  a015=(a138*a015);
  a140=(a140+a015);
  a140=(a140*a139);
  a015=(2.*a073);
  a087=(a107*a087);
  a087=(a039+a087);
  a141=-3.8675134594812879e-02;
  a111=(a141*a111);
  a087=(a087+a111);
  a111=(a098*a087);
  a111=(a107*a111);
  a142=(a015*a111);
  a050=(a050-a142);
  a142=(a024*a087);
  a143=(a107*a142);
  a144=(a070*a143);
  a050=(a050-a144);
  a144=(a090*a087);
  a145=(a107*a144);
  a146=(a068*a145);
  a050=(a050-a146);
  a120=(a107*a120);
  a120=(a044+a120);
  a119=(a141*a119);
  a120=(a120+a119);
  a119=(a098*a120);
  a146=(a107*a119);
  a147=(a070*a146);
  a050=(a050-a147);
  a147=(a090*a120);
  a148=(a037*a147);
  a050=(a050-a148);
  a128=(a107*a128);
  a128=(a049+a128);
  a127=(a141*a127);
  a128=(a128+a127);
  a127=(a098*a128);
  a148=(a107*a127);
  a149=(a068*a148);
  a050=(a050-a149);
  a149=(a024*a128);
  a150=(a037*a149);
  a050=(a050+a150);
  a150=(a094*a050);
  a140=(a140+a150);
  a150=(a073*a143);
  a118=(a118-a150);
  a144=(a037*a144);
  a118=(a118+a144);
  a144=(a073*a146);
  a118=(a118-a144);
  a144=(2.*a070);
  a150=(a024*a120);
  a150=(a107*a150);
  a151=(a144*a150);
  a118=(a118-a151);
  a147=(a107*a147);
  a151=(a068*a147);
  a118=(a118-a151);
  a127=(a037*a127);
  a118=(a118-a127);
  a149=(a107*a149);
  a127=(a068*a149);
  a118=(a118-a127);
  a127=(a096*a118);
  a140=(a140+a127);
  a142=(a037*a142);
  a126=(a126-a142);
  a142=(a073*a145);
  a126=(a126-a142);
  a119=(a037*a119);
  a126=(a126+a119);
  a119=(a070*a147);
  a126=(a126-a119);
  a119=(a073*a148);
  a126=(a126-a119);
  a119=(a070*a149);
  a126=(a126-a119);
  a119=(2.*a068);
  a142=(a090*a128);
  a142=(a107*a142);
  a127=(a119*a142);
  a126=(a126-a127);
  a127=(a097*a126);
  a140=(a140+a127);
  a140=(a140/a000);
  if (res[0]!=0) res[0][3]=a140;
  a140=(a082*a050);
  a151=(a083*a118);
  a140=(a140+a151);
  a152=(a086*a126);
  a140=(a140+a152);
  a140=(a140/a000);
  if (res[0]!=0) res[0][4]=a140;
  a140=(a100*a050);
  a074=(a074+a071);
  a074=(a074/a010);
  a071=(a075*a074);
  a071=(a041-a071);
  a071=(a135*a071);
  a084=(a084/a010);
  a084=(a073+a084);
  a152=(a075*a084);
  a152=(a137*a152);
  a071=(a071+a152);
  a103=(a103/a010);
  a103=(a103-a070);
  a152=(a075*a103);
  a152=(a138*a152);
  a071=(a071+a152);
  a071=(a071*a139);
  a071=(a140-a071);
  a152=(a102*a118);
  a071=(a071+a152);
  a152=(a105*a126);
  a071=(a071+a152);
  a071=(a071/a000);
  if (res[0]!=0) res[0][5]=a071;
  a071=arg[2]? arg[2][0] : 0;
  a152=(a037*a022);
  a153=(a037*a008);
  a152=(a152+a153);
  a152=(a000*a152);
  a153=(a152/a010);
  a154=(a037*a030);
  a155=(a037*a001);
  a154=(a154+a155);
  a154=(a000*a154);
  a155=(a037*a028);
  a156=(a037*a003);
  a155=(a155+a156);
  a155=(a000*a155);
  a156=(a154*a155);
  a156=(a156/a006);
  a156=(a153+a156);
  a157=(a156*a038);
  a158=(a152*a155);
  a158=(a158/a006);
  a159=(a154/a010);
  a158=(a158-a159);
  a160=(a158*a043);
  a157=(a157+a160);
  a160=casadi_sq(a155);
  a160=(a160/a006);
  a160=(a041+a160);
  a161=(a160*a048);
  a157=(a157+a161);
  a093=(a088+a093);
  a161=(a093*a050);
  a157=(a157+a161);
  a095=(a095-a079);
  a161=(a095*a118);
  a157=(a157+a161);
  a157=(a157+a127);
  a007=(a011+a007);
  a127=(a007*a061);
  a157=(a157+a127);
  a056=(a056-a026);
  a127=(a056*a115);
  a157=(a157+a127);
  a157=(a157+a130);
  a071=(a071-a157);
  if (res[0]!=0) res[0][6]=a071;
  a071=arg[2]? arg[2][1] : 0;
  a157=(a154*a152);
  a157=(a157/a006);
  a010=(a155/a010);
  a157=(a157-a010);
  a130=(a157*a038);
  a127=casadi_sq(a152);
  a127=(a127/a006);
  a127=(a041+a127);
  a161=(a127*a043);
  a130=(a130+a161);
  a161=(a155*a152);
  a161=(a161/a006);
  a159=(a159+a161);
  a161=(a159*a048);
  a130=(a130+a161);
  a081=(a081-a076);
  a161=(a081*a050);
  a130=(a130+a161);
  a130=(a130+a151);
  a085=(a079+a085);
  a151=(a085*a126);
  a130=(a130+a151);
  a035=(a035-a019);
  a151=(a035*a061);
  a130=(a130+a151);
  a130=(a130+a136);
  a046=(a026+a046);
  a136=(a046*a122);
  a130=(a130+a136);
  a071=(a071-a130);
  if (res[0]!=0) res[0][7]=a071;
  a071=arg[2]? arg[2][2] : 0;
  a130=casadi_sq(a154);
  a130=(a130/a006);
  a041=(a041+a130);
  a130=(a041*a038);
  a136=(a152*a154);
  a136=(a136/a006);
  a010=(a010+a136);
  a136=(a010*a043);
  a130=(a130+a136);
  a136=(a155*a154);
  a136=(a136/a006);
  a136=(a136-a153);
  a153=(a136*a048);
  a130=(a130+a153);
  a130=(a130+a140);
  a101=(a076+a101);
  a140=(a101*a118);
  a130=(a130+a140);
  a104=(a104-a088);
  a140=(a104*a126);
  a130=(a130+a140);
  a130=(a130+a133);
  a062=(a019+a062);
  a133=(a062*a115);
  a130=(a130+a133);
  a065=(a065-a011);
  a133=(a065*a122);
  a130=(a130+a133);
  a071=(a071-a130);
  if (res[0]!=0) res[0][8]=a071;
  a071=(a002*a000);
  a130=(a107*a071);
  a133=(a061*a130);
  a140=(a018*a040);
  a016=(a018/a016);
  a153=(a125*a000);
  a006=(a016*a153);
  a151=(a019*a006);
  a151=(a140-a151);
  a161=(a032*a151);
  a162=(a030*a151);
  a163=(a022*a006);
  a164=(a021*a027);
  a165=(a026*a006);
  a166=(a028*a165);
  a166=(a164-a166);
  a163=(a163+a166);
  a162=(a162-a163);
  a163=(2.*a162);
  a163=(a033*a163);
  a166=(a039*a040);
  a167=(a009*a000);
  a168=(a107*a167);
  a169=(a049*a168);
  a169=(a166+a169);
  a163=(a163-a169);
  a163=(a163/a040);
  a169=(a020*a163);
  a161=(a161+a169);
  a169=(a021*a018);
  a170=(a028*a006);
  a170=(a169-a170);
  a171=(a022*a165);
  a170=(a170-a171);
  a171=(a011*a006);
  a172=(a030*a171);
  a170=(a170+a172);
  a172=(2.*a170);
  a172=(a054*a172);
  a173=(a039*a130);
  a174=(a044*a168);
  a175=(a173+a174);
  a176=(a107*a153);
  a177=(a049*a176);
  a175=(a175+a177);
  a172=(a172-a175);
  a172=(a172/a040);
  a175=(a051*a172);
  a177=(a053*a171);
  a175=(a175-a177);
  a161=(a161-a175);
  a175=(a021*a051);
  a177=(a028*a171);
  a177=(a175-a177);
  a178=(a022*a151);
  a177=(a177-a178);
  a178=(a030*a006);
  a177=(a177-a178);
  a178=(2.*a177);
  a178=(a054*a178);
  a179=(a049*a130);
  a180=(a044*a040);
  a179=(a179-a180);
  a178=(a178-a179);
  a178=(a178/a040);
  a179=(a018*a178);
  a181=(a059*a006);
  a179=(a179-a181);
  a161=(a161+a179);
  a179=(a013*a161);
  a181=(a078*a080);
  a182=(-a181);
  a182=(2.*a182);
  a182=(a033*a182);
  a182=(a182/a040);
  a183=(a077*a182);
  a184=-1.2928203230275511e+01;
  a185=(a184*a075);
  a186=(a054*a185);
  a186=(a186/a040);
  a187=(a089*a186);
  a183=(a183-a187);
  a188=(a184*a089);
  a188=(a054*a188);
  a188=(a188/a040);
  a189=(a075*a188);
  a183=(a183+a189);
  a189=(a067*a183);
  a179=(a179+a189);
  a189=(a110*a177);
  a161=(a109*a161);
  a183=(a013*a183);
  a161=(a161+a183);
  a183=(a000*a161);
  a190=(a108*a183);
  a191=(a000*a179);
  a192=(a107*a191);
  a190=(a190+a192);
  a192=(a055*a190);
  a189=(a189+a192);
  a189=(a107*a189);
  a189=(a106*a189);
  a179=(a179-a189);
  a189=(a110*a162);
  a192=(a025*a190);
  a189=(a189+a192);
  a192=(a107*a189);
  a193=(a009*a192);
  a179=(a179-a193);
  a116=(a116*a000);
  a193=(a110*a170);
  a190=(a052*a190);
  a193=(a193+a190);
  a190=(a107*a193);
  a194=(a004*a190);
  a194=(a116+a194);
  a179=(a179-a194);
  a194=(a121*a177);
  a195=(a027*a172);
  a196=(a053*a165);
  a195=(a195-a196);
  a196=(a018*a163);
  a197=(a032*a006);
  a196=(a196-a197);
  a195=(a195+a196);
  a151=(a059*a151);
  a196=(a020*a178);
  a151=(a151+a196);
  a195=(a195-a151);
  a151=(a109*a195);
  a196=(a080*a186);
  a197=(a075*a182);
  a196=(a196+a197);
  a197=(a077*a188);
  a196=(a196-a197);
  a197=(a013*a196);
  a151=(a151+a197);
  a197=(a000*a151);
  a198=(a108*a197);
  a195=(a013*a195);
  a196=(a067*a196);
  a195=(a195+a196);
  a196=(a000*a195);
  a199=(a107*a196);
  a198=(a198+a199);
  a199=(a055*a198);
  a194=(a194+a199);
  a199=(a107*a194);
  a200=(a009*a199);
  a179=(a179-a200);
  a200=(a121*a170);
  a201=(a052*a198);
  a200=(a200+a201);
  a201=(a037*a200);
  a179=(a179-a201);
  a131=(a131*a000);
  a177=(a129*a177);
  a172=(a018*a172);
  a201=(a053*a006);
  a172=(a172-a201);
  a163=(a027*a163);
  a165=(a032*a165);
  a163=(a163-a165);
  a172=(a172-a163);
  a178=(a051*a178);
  a171=(a059*a171);
  a178=(a178-a171);
  a172=(a172+a178);
  a178=(a109*a172);
  a171=(a075*a186);
  a182=(a080*a182);
  a182=(a171-a182);
  a188=(a089*a188);
  a182=(a182+a188);
  a188=(a013*a182);
  a178=(a178+a188);
  a188=(a000*a178);
  a163=(a108*a188);
  a172=(a013*a172);
  a182=(a067*a182);
  a172=(a172+a182);
  a182=(a000*a172);
  a165=(a107*a182);
  a163=(a163+a165);
  a165=(a055*a163);
  a177=(a177+a165);
  a165=(a107*a177);
  a201=(a004*a165);
  a201=(a131+a201);
  a179=(a179-a201);
  a201=(a129*a162);
  a202=(a025*a163);
  a201=(a201+a202);
  a202=(a037*a201);
  a179=(a179+a202);
  a202=(a012*a179);
  a202=(a133+a202);
  a203=(a115*a168);
  a193=(a037*a193);
  a192=(a002*a192);
  a193=(a193-a192);
  a193=(a193+a195);
  a199=(a002*a199);
  a193=(a193-a199);
  a162=(a121*a162);
  a198=(a025*a198);
  a162=(a162+a198);
  a162=(a107*a162);
  a162=(a117*a162);
  a193=(a193-a162);
  a124=(a124*a000);
  a200=(a107*a200);
  a162=(a004*a200);
  a162=(a124+a162);
  a193=(a193-a162);
  a177=(a037*a177);
  a193=(a193-a177);
  a132=(a132*a000);
  a201=(a107*a201);
  a177=(a004*a201);
  a177=(a132+a177);
  a193=(a193-a177);
  a177=(a057*a193);
  a177=(a203+a177);
  a202=(a202+a177);
  a176=(a122*a176);
  a194=(a037*a194);
  a189=(a037*a189);
  a190=(a002*a190);
  a189=(a189+a190);
  a194=(a194-a189);
  a200=(a009*a200);
  a194=(a194-a200);
  a194=(a194+a172);
  a165=(a002*a165);
  a194=(a194-a165);
  a201=(a009*a201);
  a194=(a194-a201);
  a201=(2.*a000);
  a113=(a113*a201);
  a170=(a129*a170);
  a163=(a052*a163);
  a170=(a170+a163);
  a170=(a107*a170);
  a170=(a125*a170);
  a113=(a113+a170);
  a194=(a194-a113);
  a113=(a058*a194);
  a176=(a176+a113);
  a202=(a202+a176);
  a071=(a037*a071);
  a071=(a018*a071);
  a113=(a005*a006);
  a113=(a071-a113);
  a113=(a135*a113);
  a170=(a034*a006);
  a163=(a018*a000);
  a170=(a170+a163);
  a170=(a137*a170);
  a113=(a113-a170);
  a153=(a037*a153);
  a153=(a018*a153);
  a170=(a014*a006);
  a153=(a153-a170);
  a153=(a138*a153);
  a113=(a113-a153);
  a113=(a139*a113);
  a202=(a202+a113);
  a202=(a202/a000);
  if (res[1]!=0) res[1][0]=a202;
  a202=(a061*a040);
  a113=(a036*a179);
  a113=(a202+a113);
  a153=(a042*a193);
  a113=(a113+a153);
  a170=(a122*a168);
  a165=(a047*a194);
  a165=(a170+a165);
  a113=(a113+a165);
  a113=(a113/a000);
  if (res[1]!=0) res[1][1]=a113;
  a113=(a060*a179);
  a165=(a063*a193);
  a172=(a115*a040);
  a165=(a165-a172);
  a165=(a113+a165);
  a200=(a122*a130);
  a189=(a066*a194);
  a189=(a200+a189);
  a165=(a165+a189);
  a189=(a017*a006);
  a189=(a135*a189);
  a167=(a037*a167);
  a167=(a018*a167);
  a190=(a045*a006);
  a190=(a167-a190);
  a190=(a137*a190);
  a189=(a189+a190);
  a006=(a064*a006);
  a006=(a071-a006);
  a006=(a138*a006);
  a189=(a189+a006);
  a189=(a139*a189);
  a165=(a165-a189);
  a165=(a165/a000);
  if (res[1]!=0) res[1][2]=a165;
  a165=(a078*a089);
  a189=(a087*a165);
  a183=(a107*a183);
  a191=(a141*a191);
  a183=(a183+a191);
  a191=(a098*a183);
  a191=(a189+a191);
  a191=(a107*a191);
  a191=(a015*a191);
  a161=(a161-a191);
  a191=(a024*a183);
  a006=(a087*a181);
  a191=(a191-a006);
  a190=(a107*a191);
  a177=(a070*a190);
  a161=(a161-a177);
  a177=(a078*a075);
  a162=(a087*a177);
  a183=(a090*a183);
  a183=(a162+a183);
  a198=(a107*a183);
  a199=(a068*a198);
  a161=(a161-a199);
  a199=(a120*a165);
  a197=(a107*a197);
  a196=(a141*a196);
  a197=(a197+a196);
  a196=(a098*a197);
  a196=(a199+a196);
  a195=(a107*a196);
  a192=(a070*a195);
  a161=(a161-a192);
  a192=(a120*a177);
  a204=(a090*a197);
  a204=(a192+a204);
  a205=(a037*a204);
  a161=(a161-a205);
  a205=(a128*a165);
  a188=(a107*a188);
  a182=(a141*a182);
  a188=(a188+a182);
  a182=(a098*a188);
  a182=(a205+a182);
  a206=(a107*a182);
  a207=(a068*a206);
  a161=(a161-a207);
  a207=(a024*a188);
  a208=(a128*a181);
  a207=(a207-a208);
  a209=(a037*a207);
  a161=(a161+a209);
  a209=(a094*a161);
  a190=(a073*a190);
  a151=(a151-a190);
  a183=(a037*a183);
  a151=(a151+a183);
  a195=(a073*a195);
  a151=(a151-a195);
  a197=(a024*a197);
  a181=(a120*a181);
  a197=(a197-a181);
  a197=(a107*a197);
  a197=(a144*a197);
  a151=(a151-a197);
  a204=(a107*a204);
  a197=(a068*a204);
  a151=(a151-a197);
  a182=(a037*a182);
  a151=(a151-a182);
  a207=(a107*a207);
  a182=(a068*a207);
  a151=(a151-a182);
  a182=(a096*a151);
  a209=(a209+a182);
  a191=(a037*a191);
  a178=(a178-a191);
  a198=(a073*a198);
  a178=(a178-a198);
  a196=(a037*a196);
  a178=(a178+a196);
  a204=(a070*a204);
  a178=(a178-a204);
  a206=(a073*a206);
  a178=(a178-a206);
  a207=(a070*a207);
  a178=(a178-a207);
  a177=(a128*a177);
  a188=(a090*a188);
  a188=(a177+a188);
  a188=(a107*a188);
  a188=(a119*a188);
  a178=(a178-a188);
  a188=(a097*a178);
  a209=(a209+a188);
  a209=(a209/a000);
  if (res[1]!=0) res[1][3]=a209;
  a209=(a082*a161);
  a207=(a083*a151);
  a209=(a209+a207);
  a206=(a086*a178);
  a209=(a209+a206);
  a209=(a209/a000);
  if (res[1]!=0) res[1][4]=a209;
  a209=(a100*a161);
  a206=(a102*a151);
  a206=(a209+a206);
  a204=(a105*a178);
  a206=(a206+a204);
  a206=(a206/a000);
  if (res[1]!=0) res[1][5]=a206;
  a206=-1.7320508075688774e+00;
  a206=(a206*a000);
  a204=(a154*a206);
  a204=(a107*a204);
  a196=(a038*a204);
  a198=(a152*a206);
  a198=(a107*a198);
  a191=(a043*a198);
  a182=(a196+a191);
  a197=(2.*a155);
  a195=(a197*a206);
  a195=(a107*a195);
  a195=(a048*a195);
  a182=(a182+a195);
  a195=(a093*a161);
  a182=(a182+a195);
  a195=(a095*a151);
  a182=(a182+a195);
  a182=(a182+a188);
  a188=(a007*a179);
  a188=(a133+a188);
  a182=(a182+a188);
  a188=(a056*a193);
  a188=(a203+a188);
  a182=(a182+a188);
  a182=(a182+a176);
  a182=(-a182);
  if (res[1]!=0) res[1][6]=a182;
  a182=(a048*a198);
  a176=-8.6602540378443871e-01;
  a176=(a176*a000);
  a188=(a038*a176);
  a182=(a182-a188);
  a161=(a081*a161);
  a182=(a182+a161);
  a182=(a182+a207);
  a207=(a085*a178);
  a182=(a182+a207);
  a179=(a035*a179);
  a179=(a179-a202);
  a182=(a182+a179);
  a182=(a182+a153);
  a153=(a046*a194);
  a170=(a170+a153);
  a182=(a182+a170);
  a182=(-a182);
  if (res[1]!=0) res[1][7]=a182;
  a182=(a043*a176);
  a170=(a048*a204);
  a170=(a182+a170);
  a170=(a170+a209);
  a151=(a101*a151);
  a170=(a170+a151);
  a178=(a104*a178);
  a170=(a170+a178);
  a170=(a170+a113);
  a193=(a062*a193);
  a193=(a172+a193);
  a170=(a170+a193);
  a194=(a065*a194);
  a200=(a200+a194);
  a170=(a170+a200);
  a170=(-a170);
  if (res[1]!=0) res[1][8]=a170;
  a170=(a117*a000);
  a200=(a016*a170);
  a194=(a022*a200);
  a194=(a169-a194);
  a193=(a026*a200);
  a113=(a028*a193);
  a194=(a194+a113);
  a113=(a019*a200);
  a178=(a030*a113);
  a194=(a194-a178);
  a178=(2.*a194);
  a178=(a033*a178);
  a151=(a107*a170);
  a209=(a044*a151);
  a173=(a173+a209);
  a209=(a004*a000);
  a153=(a107*a209);
  a179=(a049*a153);
  a173=(a173+a179);
  a178=(a178-a173);
  a178=(a178/a040);
  a173=(a020*a178);
  a207=(a032*a113);
  a173=(a173-a207);
  a207=(a011*a200);
  a207=(a140-a207);
  a161=(a053*a207);
  a195=(a022*a193);
  a164=(a164-a195);
  a195=(a028*a200);
  a164=(a164-a195);
  a195=(a030*a207);
  a164=(a164-a195);
  a195=(2.*a164);
  a195=(a054*a195);
  a183=(a044*a153);
  a183=(a183-a166);
  a195=(a195-a183);
  a195=(a195/a040);
  a183=(a051*a195);
  a161=(a161+a183);
  a173=(a173-a161);
  a161=(a028*a207);
  a183=(a021*a020);
  a190=(a022*a113);
  a190=(a183-a190);
  a161=(a161-a190);
  a190=(a030*a200);
  a161=(a161-a190);
  a190=(2.*a161);
  a190=(a054*a190);
  a210=(a044*a130);
  a211=(a049*a040);
  a210=(a210+a211);
  a190=(a190-a210);
  a190=(a190/a040);
  a210=(a018*a190);
  a212=(a059*a200);
  a210=(a210-a212);
  a173=(a173+a210);
  a210=(a013*a173);
  a185=(a033*a185);
  a185=(a185/a040);
  a212=(a077*a185);
  a213=(a184*a080);
  a213=(a054*a213);
  a213=(a213/a040);
  a214=(a089*a213);
  a212=(a212-a214);
  a078=(a078*a077);
  a214=(-a078);
  a214=(2.*a214);
  a214=(a054*a214);
  a214=(a214/a040);
  a215=(a075*a214);
  a212=(a212+a215);
  a215=(a067*a212);
  a210=(a210+a215);
  a215=(a110*a161);
  a173=(a109*a173);
  a212=(a013*a212);
  a173=(a173+a212);
  a212=(a000*a173);
  a216=(a108*a212);
  a217=(a000*a210);
  a218=(a107*a217);
  a216=(a216+a218);
  a218=(a055*a216);
  a215=(a215+a218);
  a215=(a107*a215);
  a215=(a106*a215);
  a210=(a210-a215);
  a114=(a114*a000);
  a215=(a110*a194);
  a218=(a025*a216);
  a215=(a215+a218);
  a218=(a107*a215);
  a219=(a009*a218);
  a219=(a114+a219);
  a210=(a210-a219);
  a219=(a110*a164);
  a216=(a052*a216);
  a219=(a219+a216);
  a216=(a107*a219);
  a220=(a004*a216);
  a210=(a210-a220);
  a123=(a123*a000);
  a220=(a121*a161);
  a221=(a027*a195);
  a222=(a053*a193);
  a221=(a221-a222);
  a222=(a018*a178);
  a223=(a032*a200);
  a222=(a222-a223);
  a221=(a221+a222);
  a222=(a020*a190);
  a113=(a059*a113);
  a222=(a222-a113);
  a221=(a221-a222);
  a222=(a109*a221);
  a113=(a080*a213);
  a223=(a075*a185);
  a113=(a113+a223);
  a223=(a077*a214);
  a113=(a113-a223);
  a223=(a013*a113);
  a222=(a222+a223);
  a223=(a000*a222);
  a224=(a108*a223);
  a221=(a013*a221);
  a113=(a067*a113);
  a221=(a221+a113);
  a113=(a000*a221);
  a225=(a107*a113);
  a224=(a224+a225);
  a225=(a055*a224);
  a220=(a220+a225);
  a225=(a107*a220);
  a226=(a009*a225);
  a226=(a123+a226);
  a210=(a210-a226);
  a226=(a121*a164);
  a227=(a052*a224);
  a226=(a226+a227);
  a227=(a037*a226);
  a210=(a210-a227);
  a161=(a129*a161);
  a195=(a018*a195);
  a227=(a053*a200);
  a195=(a195-a227);
  a178=(a027*a178);
  a193=(a032*a193);
  a178=(a178-a193);
  a195=(a195-a178);
  a207=(a059*a207);
  a190=(a051*a190);
  a207=(a207+a190);
  a195=(a195+a207);
  a207=(a109*a195);
  a213=(a075*a213);
  a185=(a080*a185);
  a213=(a213-a185);
  a214=(a089*a214);
  a213=(a213+a214);
  a214=(a013*a213);
  a207=(a207+a214);
  a214=(a000*a207);
  a185=(a108*a214);
  a195=(a013*a195);
  a213=(a067*a213);
  a195=(a195+a213);
  a213=(a000*a195);
  a190=(a107*a213);
  a185=(a185+a190);
  a190=(a055*a185);
  a161=(a161+a190);
  a190=(a107*a161);
  a178=(a004*a190);
  a210=(a210-a178);
  a178=(a129*a194);
  a193=(a025*a185);
  a178=(a178+a193);
  a193=(a037*a178);
  a210=(a210+a193);
  a193=(a012*a210);
  a193=(a193-a202);
  a227=(a115*a153);
  a219=(a037*a219);
  a218=(a002*a218);
  a219=(a219-a218);
  a219=(a219+a221);
  a225=(a002*a225);
  a219=(a219-a225);
  a134=(a134*a201);
  a194=(a121*a194);
  a224=(a025*a224);
  a194=(a194+a224);
  a194=(a107*a194);
  a194=(a117*a194);
  a134=(a134+a194);
  a219=(a219-a134);
  a226=(a107*a226);
  a134=(a004*a226);
  a219=(a219-a134);
  a161=(a037*a161);
  a219=(a219-a161);
  a178=(a107*a178);
  a161=(a004*a178);
  a219=(a219-a161);
  a161=(a057*a219);
  a161=(a227+a161);
  a193=(a193+a161);
  a220=(a037*a220);
  a215=(a037*a215);
  a216=(a002*a216);
  a215=(a215+a216);
  a220=(a220-a215);
  a226=(a009*a226);
  a124=(a124+a226);
  a220=(a220-a124);
  a220=(a220+a195);
  a190=(a002*a190);
  a220=(a220-a190);
  a178=(a009*a178);
  a132=(a132+a178);
  a220=(a220-a132);
  a164=(a129*a164);
  a185=(a052*a185);
  a164=(a164+a185);
  a164=(a107*a164);
  a164=(a125*a164);
  a220=(a220-a164);
  a164=(a058*a220);
  a193=(a193+a164);
  a185=(a005*a200);
  a185=(a163-a185);
  a185=(a135*a185);
  a132=(a034*a200);
  a071=(a071-a132);
  a071=(a137*a071);
  a185=(a185+a071);
  a170=(a037*a170);
  a170=(a018*a170);
  a071=(a014*a200);
  a071=(a170-a071);
  a071=(a138*a071);
  a185=(a185-a071);
  a185=(a139*a185);
  a193=(a193+a185);
  a193=(a193/a000);
  if (res[1]!=0) res[1][9]=a193;
  a193=(a036*a210);
  a193=(a133+a193);
  a151=(a115*a151);
  a185=(a042*a219);
  a151=(a151+a185);
  a193=(a193+a151);
  a185=(a122*a153);
  a071=(a047*a220);
  a071=(a185+a071);
  a193=(a193+a071);
  a193=(a193/a000);
  if (res[1]!=0) res[1][10]=a193;
  a193=(a060*a210);
  a115=(a115*a130);
  a130=(a063*a219);
  a130=(a115+a130);
  a130=(a193+a130);
  a122=(a122*a040);
  a071=(a066*a220);
  a071=(a122+a071);
  a130=(a130+a071);
  a209=(a037*a209);
  a209=(a018*a209);
  a071=(a045*a200);
  a071=(a209-a071);
  a071=(a137*a071);
  a132=(a017*a200);
  a170=(a170-a132);
  a170=(a135*a170);
  a071=(a071-a170);
  a200=(a064*a200);
  a200=(a200+a163);
  a200=(a138*a200);
  a071=(a071-a200);
  a071=(a139*a071);
  a130=(a130-a071);
  a130=(a130/a000);
  if (res[1]!=0) res[1][11]=a130;
  a212=(a107*a212);
  a217=(a141*a217);
  a212=(a212+a217);
  a217=(a098*a212);
  a130=(a087*a078);
  a217=(a217-a130);
  a217=(a107*a217);
  a217=(a015*a217);
  a173=(a173-a217);
  a217=(a024*a212);
  a217=(a162+a217);
  a071=(a107*a217);
  a200=(a070*a071);
  a173=(a173-a200);
  a212=(a090*a212);
  a006=(a006+a212);
  a212=(a107*a006);
  a200=(a068*a212);
  a173=(a173-a200);
  a223=(a107*a223);
  a113=(a141*a113);
  a223=(a223+a113);
  a113=(a098*a223);
  a200=(a120*a078);
  a113=(a113-a200);
  a170=(a107*a113);
  a132=(a070*a170);
  a173=(a173-a132);
  a132=(a090*a223);
  a181=(a181+a132);
  a132=(a037*a181);
  a173=(a173-a132);
  a214=(a107*a214);
  a213=(a141*a213);
  a214=(a214+a213);
  a213=(a098*a214);
  a078=(a128*a078);
  a213=(a213-a078);
  a132=(a107*a213);
  a178=(a068*a132);
  a173=(a173-a178);
  a178=(a024*a214);
  a178=(a177+a178);
  a190=(a037*a178);
  a173=(a173+a190);
  a190=(a094*a173);
  a071=(a073*a071);
  a222=(a222-a071);
  a006=(a037*a006);
  a222=(a222+a006);
  a170=(a073*a170);
  a222=(a222-a170);
  a223=(a024*a223);
  a223=(a192+a223);
  a223=(a107*a223);
  a223=(a144*a223);
  a222=(a222-a223);
  a181=(a107*a181);
  a223=(a068*a181);
  a222=(a222-a223);
  a213=(a037*a213);
  a222=(a222-a213);
  a178=(a107*a178);
  a213=(a068*a178);
  a222=(a222-a213);
  a213=(a096*a222);
  a190=(a190+a213);
  a217=(a037*a217);
  a207=(a207-a217);
  a212=(a073*a212);
  a207=(a207-a212);
  a113=(a037*a113);
  a207=(a207+a113);
  a181=(a070*a181);
  a207=(a207-a181);
  a132=(a073*a132);
  a207=(a207-a132);
  a178=(a070*a178);
  a207=(a207-a178);
  a214=(a090*a214);
  a208=(a208+a214);
  a208=(a107*a208);
  a208=(a119*a208);
  a207=(a207-a208);
  a208=(a097*a207);
  a190=(a190+a208);
  a190=(a190/a000);
  if (res[1]!=0) res[1][12]=a190;
  a190=(a082*a173);
  a214=(a083*a222);
  a190=(a190+a214);
  a178=(a086*a207);
  a190=(a190+a178);
  a190=(a190/a000);
  if (res[1]!=0) res[1][13]=a190;
  a190=(a100*a173);
  a178=(a102*a222);
  a178=(a190+a178);
  a132=(a105*a207);
  a178=(a178+a132);
  a178=(a178/a000);
  if (res[1]!=0) res[1][14]=a178;
  a178=(a155*a206);
  a178=(a107*a178);
  a132=(a043*a178);
  a188=(a188+a132);
  a132=(a093*a173);
  a188=(a188+a132);
  a132=(a095*a222);
  a188=(a188+a132);
  a188=(a188+a208);
  a208=(a007*a210);
  a202=(a202+a208);
  a188=(a188+a202);
  a202=(a056*a219);
  a227=(a227+a202);
  a188=(a188+a227);
  a188=(a188+a164);
  a188=(-a188);
  if (res[1]!=0) res[1][15]=a188;
  a188=(2.*a152);
  a164=(a188*a206);
  a164=(a107*a164);
  a164=(a043*a164);
  a196=(a196+a164);
  a164=(a048*a178);
  a196=(a196+a164);
  a173=(a081*a173);
  a196=(a196+a173);
  a196=(a196+a214);
  a214=(a085*a207);
  a196=(a196+a214);
  a210=(a035*a210);
  a133=(a133+a210);
  a196=(a196+a133);
  a196=(a196+a151);
  a151=(a046*a220);
  a151=(a185+a151);
  a196=(a196+a151);
  a196=(-a196);
  if (res[1]!=0) res[1][16]=a196;
  a204=(a043*a204);
  a176=(a048*a176);
  a204=(a204-a176);
  a204=(a204+a190);
  a222=(a101*a222);
  a204=(a204+a222);
  a207=(a104*a207);
  a204=(a204+a207);
  a204=(a204+a193);
  a219=(a062*a219);
  a115=(a115+a219);
  a204=(a204+a115);
  a220=(a065*a220);
  a220=(a220-a122);
  a204=(a204+a220);
  a204=(-a204);
  if (res[1]!=0) res[1][17]=a204;
  a204=(a061*a153);
  a220=(a106*a000);
  a016=(a016*a220);
  a019=(a019*a016);
  a115=(a030*a019);
  a183=(a183-a115);
  a115=(a022*a016);
  a026=(a026*a016);
  a140=(a140-a026);
  a026=(a028*a140);
  a115=(a115+a026);
  a183=(a183-a115);
  a115=(2.*a183);
  a115=(a033*a115);
  a026=(a039*a168);
  a026=(a026-a211);
  a115=(a115-a026);
  a115=(a115/a040);
  a026=(a020*a115);
  a219=(a032*a019);
  a026=(a026-a219);
  a219=(a022*a140);
  a193=(a028*a016);
  a219=(a219-a193);
  a011=(a011*a016);
  a193=(a030*a011);
  a175=(a175-a193);
  a219=(a219-a175);
  a175=(2.*a219);
  a175=(a054*a175);
  a153=(a039*a153);
  a153=(a153+a180);
  a175=(a175-a153);
  a175=(a175/a040);
  a153=(a051*a175);
  a193=(a053*a011);
  a153=(a153-a193);
  a026=(a026-a153);
  a022=(a022*a019);
  a028=(a028*a011);
  a022=(a022-a028);
  a030=(a030*a016);
  a169=(a169-a030);
  a022=(a022+a169);
  a169=(2.*a022);
  a169=(a054*a169);
  a030=(a107*a220);
  a028=(a039*a030);
  a028=(a028+a174);
  a028=(a028+a179);
  a169=(a169-a028);
  a169=(a169/a040);
  a028=(a018*a169);
  a179=(a059*a016);
  a028=(a028-a179);
  a026=(a026+a028);
  a028=(a013*a026);
  a184=(a184*a077);
  a184=(a033*a184);
  a184=(a184/a040);
  a179=(a077*a184);
  a165=(-a165);
  a165=(2.*a165);
  a165=(a054*a165);
  a165=(a165/a040);
  a174=(a089*a165);
  a179=(a179-a174);
  a179=(a179+a171);
  a171=(a067*a179);
  a028=(a028+a171);
  a112=(a112*a201);
  a171=(a110*a022);
  a026=(a109*a026);
  a179=(a013*a179);
  a026=(a026+a179);
  a179=(a000*a026);
  a174=(a108*a179);
  a153=(a000*a028);
  a193=(a107*a153);
  a174=(a174+a193);
  a193=(a055*a174);
  a171=(a171+a193);
  a171=(a107*a171);
  a171=(a106*a171);
  a112=(a112+a171);
  a028=(a028-a112);
  a112=(a110*a183);
  a171=(a025*a174);
  a112=(a112+a171);
  a171=(a107*a112);
  a193=(a009*a171);
  a028=(a028-a193);
  a193=(a110*a219);
  a174=(a052*a174);
  a193=(a193+a174);
  a174=(a107*a193);
  a207=(a004*a174);
  a028=(a028-a207);
  a207=(a121*a022);
  a222=(a053*a140);
  a190=(a027*a175);
  a222=(a222+a190);
  a190=(a018*a115);
  a196=(a032*a016);
  a190=(a190-a196);
  a222=(a222+a190);
  a190=(a020*a169);
  a019=(a059*a019);
  a190=(a190-a019);
  a222=(a222-a190);
  a190=(a109*a222);
  a019=(a080*a165);
  a196=(a075*a184);
  a019=(a019+a196);
  a186=(a077*a186);
  a019=(a019-a186);
  a186=(a013*a019);
  a190=(a190+a186);
  a186=(a000*a190);
  a196=(a108*a186);
  a222=(a013*a222);
  a019=(a067*a019);
  a222=(a222+a019);
  a019=(a000*a222);
  a151=(a107*a019);
  a196=(a196+a151);
  a151=(a055*a196);
  a207=(a207+a151);
  a151=(a107*a207);
  a133=(a009*a151);
  a028=(a028-a133);
  a133=(a121*a219);
  a210=(a052*a196);
  a133=(a133+a210);
  a210=(a037*a133);
  a028=(a028-a210);
  a022=(a129*a022);
  a175=(a018*a175);
  a053=(a053*a016);
  a175=(a175-a053);
  a032=(a032*a140);
  a115=(a027*a115);
  a032=(a032+a115);
  a175=(a175-a032);
  a169=(a051*a169);
  a059=(a059*a011);
  a169=(a169-a059);
  a175=(a175+a169);
  a169=(a109*a175);
  a165=(a075*a165);
  a184=(a080*a184);
  a165=(a165-a184);
  a165=(a165+a187);
  a187=(a013*a165);
  a169=(a169+a187);
  a187=(a000*a169);
  a184=(a108*a187);
  a175=(a013*a175);
  a165=(a067*a165);
  a175=(a175+a165);
  a165=(a000*a175);
  a059=(a107*a165);
  a184=(a184+a059);
  a059=(a055*a184);
  a022=(a022+a059);
  a059=(a107*a022);
  a011=(a004*a059);
  a028=(a028-a011);
  a011=(a129*a183);
  a032=(a025*a184);
  a011=(a011+a032);
  a032=(a037*a011);
  a028=(a028+a032);
  a032=(a012*a028);
  a032=(a204+a032);
  a193=(a037*a193);
  a171=(a002*a171);
  a114=(a114+a171);
  a193=(a193-a114);
  a193=(a193+a222);
  a151=(a002*a151);
  a123=(a123+a151);
  a193=(a193-a123);
  a183=(a121*a183);
  a196=(a025*a196);
  a183=(a183+a196);
  a183=(a107*a183);
  a183=(a117*a183);
  a193=(a193-a183);
  a133=(a107*a133);
  a183=(a004*a133);
  a193=(a193-a183);
  a022=(a037*a022);
  a193=(a193-a022);
  a011=(a107*a011);
  a022=(a004*a011);
  a193=(a193-a022);
  a022=(a057*a193);
  a022=(a172+a022);
  a032=(a032+a022);
  a207=(a037*a207);
  a112=(a037*a112);
  a174=(a002*a174);
  a116=(a116+a174);
  a112=(a112+a116);
  a207=(a207-a112);
  a133=(a009*a133);
  a207=(a207-a133);
  a207=(a207+a175);
  a059=(a002*a059);
  a131=(a131+a059);
  a207=(a207-a131);
  a011=(a009*a011);
  a207=(a207-a011);
  a219=(a129*a219);
  a184=(a052*a184);
  a219=(a219+a184);
  a219=(a107*a219);
  a219=(a125*a219);
  a207=(a207-a219);
  a219=(a058*a207);
  a032=(a032+a219);
  a005=(a005*a016);
  a005=(a209-a005);
  a005=(a135*a005);
  a034=(a034*a016);
  a167=(a167-a034);
  a167=(a137*a167);
  a005=(a005+a167);
  a014=(a014*a016);
  a014=(a138*a014);
  a005=(a005+a014);
  a005=(a139*a005);
  a032=(a032+a005);
  a032=(a032/a000);
  if (res[1]!=0) res[1][18]=a032;
  a168=(a061*a168);
  a032=(a036*a028);
  a032=(a168+a032);
  a005=(a042*a193);
  a032=(a032+a005);
  a014=(a047*a207);
  a014=(a014-a122);
  a032=(a032+a014);
  a032=(a032/a000);
  if (res[1]!=0) res[1][19]=a032;
  a061=(a061*a030);
  a030=(a060*a028);
  a061=(a061+a030);
  a030=(a063*a193);
  a030=(a203+a030);
  a030=(a061+a030);
  a032=(a066*a207);
  a032=(a185+a032);
  a030=(a030+a032);
  a045=(a045*a016);
  a163=(a163-a045);
  a163=(a137*a163);
  a220=(a037*a220);
  a220=(a018*a220);
  a017=(a017*a016);
  a220=(a220-a017);
  a220=(a135*a220);
  a163=(a163-a220);
  a064=(a064*a016);
  a209=(a209-a064);
  a209=(a138*a209);
  a163=(a163+a209);
  a163=(a139*a163);
  a030=(a030-a163);
  a030=(a030/a000);
  if (res[1]!=0) res[1][20]=a030;
  a179=(a107*a179);
  a153=(a141*a153);
  a179=(a179+a153);
  a153=(a098*a179);
  a162=(a162+a153);
  a162=(a107*a162);
  a162=(a015*a162);
  a026=(a026-a162);
  a162=(a024*a179);
  a130=(a130+a162);
  a162=(a107*a130);
  a153=(a070*a162);
  a026=(a026-a153);
  a179=(a090*a179);
  a179=(a179-a189);
  a189=(a107*a179);
  a153=(a068*a189);
  a026=(a026-a153);
  a186=(a107*a186);
  a019=(a141*a019);
  a186=(a186+a019);
  a019=(a098*a186);
  a192=(a192+a019);
  a019=(a107*a192);
  a153=(a070*a019);
  a026=(a026-a153);
  a153=(a090*a186);
  a153=(a153-a199);
  a199=(a037*a153);
  a026=(a026-a199);
  a187=(a107*a187);
  a165=(a141*a165);
  a187=(a187+a165);
  a165=(a098*a187);
  a177=(a177+a165);
  a165=(a107*a177);
  a199=(a068*a165);
  a026=(a026-a199);
  a199=(a024*a187);
  a078=(a078+a199);
  a199=(a037*a078);
  a026=(a026+a199);
  a199=(a094*a026);
  a162=(a073*a162);
  a190=(a190-a162);
  a179=(a037*a179);
  a190=(a190+a179);
  a019=(a073*a019);
  a190=(a190-a019);
  a186=(a024*a186);
  a200=(a200+a186);
  a200=(a107*a200);
  a200=(a144*a200);
  a190=(a190-a200);
  a153=(a107*a153);
  a200=(a068*a153);
  a190=(a190-a200);
  a177=(a037*a177);
  a190=(a190-a177);
  a078=(a107*a078);
  a177=(a068*a078);
  a190=(a190-a177);
  a177=(a096*a190);
  a199=(a199+a177);
  a130=(a037*a130);
  a169=(a169-a130);
  a189=(a073*a189);
  a169=(a169-a189);
  a192=(a037*a192);
  a169=(a169+a192);
  a153=(a070*a153);
  a169=(a169-a153);
  a165=(a073*a165);
  a169=(a169-a165);
  a078=(a070*a078);
  a169=(a169-a078);
  a187=(a090*a187);
  a187=(a187-a205);
  a187=(a107*a187);
  a187=(a119*a187);
  a169=(a169-a187);
  a187=(a097*a169);
  a199=(a199+a187);
  a199=(a199/a000);
  if (res[1]!=0) res[1][21]=a199;
  a199=(a082*a026);
  a205=(a083*a190);
  a199=(a199+a205);
  a078=(a086*a169);
  a199=(a199+a078);
  a199=(a199/a000);
  if (res[1]!=0) res[1][22]=a199;
  a199=(a100*a026);
  a078=(a102*a190);
  a078=(a199+a078);
  a165=(a105*a169);
  a078=(a078+a165);
  a078=(a078/a000);
  if (res[1]!=0) res[1][23]=a078;
  a178=(a038*a178);
  a178=(a178-a182);
  a182=(a093*a026);
  a178=(a178+a182);
  a182=(a095*a190);
  a178=(a178+a182);
  a178=(a178+a187);
  a187=(a007*a028);
  a204=(a204+a187);
  a178=(a178+a204);
  a204=(a056*a193);
  a204=(a204-a172);
  a178=(a178+a204);
  a178=(a178+a219);
  a178=(-a178);
  if (res[1]!=0) res[1][24]=a178;
  a198=(a038*a198);
  a198=(a198+a176);
  a026=(a081*a026);
  a198=(a198+a026);
  a198=(a198+a205);
  a205=(a085*a169);
  a198=(a198+a205);
  a028=(a035*a028);
  a168=(a168+a028);
  a198=(a198+a168);
  a198=(a198+a005);
  a005=(a046*a207);
  a122=(a122+a005);
  a198=(a198+a122);
  a198=(-a198);
  if (res[1]!=0) res[1][25]=a198;
  a198=(2.*a154);
  a206=(a198*a206);
  a206=(a107*a206);
  a206=(a038*a206);
  a206=(a206+a191);
  a206=(a206+a164);
  a206=(a206+a199);
  a190=(a101*a190);
  a206=(a206+a190);
  a169=(a104*a169);
  a206=(a206+a169);
  a206=(a206+a061);
  a193=(a062*a193);
  a203=(a203+a193);
  a206=(a206+a203);
  a207=(a065*a207);
  a185=(a185+a207);
  a206=(a206+a185);
  a206=(-a206);
  if (res[1]!=0) res[1][26]=a206;
  a206=(a023*a027);
  a185=(-a206);
  a185=(2.*a185);
  a185=(a033*a185);
  a185=(a185/a040);
  a207=(a020*a185);
  a203=9.2820323027550877e-01;
  a193=(a203*a018);
  a061=(a054*a193);
  a061=(a061/a040);
  a169=(a051*a061);
  a207=(a207-a169);
  a190=(a203*a051);
  a190=(a054*a190);
  a190=(a190/a040);
  a199=(a018*a190);
  a207=(a207+a199);
  a199=(a013*a207);
  a164=(a075*a040);
  a072=(a075/a072);
  a191=(a119*a000);
  a122=(a072*a191);
  a005=(a076*a122);
  a005=(a164-a005);
  a168=(a031*a005);
  a028=(a001*a005);
  a205=(a008*a122);
  a026=(a021*a080);
  a176=(a079*a122);
  a178=(a003*a176);
  a178=(a026-a178);
  a205=(a205+a178);
  a028=(a028-a205);
  a205=(2.*a028);
  a205=(a033*a205);
  a205=(a205-a166);
  a178=(a070*a000);
  a219=(a107*a178);
  a204=(a049*a219);
  a205=(a205-a204);
  a205=(a205/a040);
  a204=(a077*a205);
  a168=(a168+a204);
  a204=(a021*a075);
  a172=(a003*a122);
  a172=(a204-a172);
  a187=(a008*a176);
  a172=(a172-a187);
  a187=(a088*a122);
  a182=(a001*a187);
  a172=(a172+a182);
  a182=(2.*a172);
  a182=(a054*a182);
  a078=(a073*a000);
  a165=(a107*a078);
  a153=(a039*a165);
  a182=(a182-a153);
  a192=(a044*a219);
  a182=(a182-a192);
  a189=(a107*a191);
  a130=(a049*a189);
  a182=(a182-a130);
  a182=(a182/a040);
  a130=(a089*a182);
  a177=(a091*a187);
  a130=(a130-a177);
  a168=(a168-a130);
  a130=(a021*a089);
  a177=(a003*a187);
  a177=(a130-a177);
  a200=(a008*a005);
  a177=(a177-a200);
  a200=(a001*a122);
  a177=(a177-a200);
  a200=(2.*a177);
  a200=(a054*a200);
  a200=(a200+a180);
  a186=(a049*a165);
  a200=(a200-a186);
  a200=(a200/a040);
  a186=(a075*a200);
  a019=(a099*a122);
  a186=(a186-a019);
  a168=(a168+a186);
  a186=(a067*a168);
  a199=(a199+a186);
  a186=(a023*a051);
  a019=(a110*a186);
  a207=(a109*a207);
  a168=(a013*a168);
  a207=(a207+a168);
  a168=(a000*a207);
  a179=(a108*a168);
  a162=(a000*a199);
  a030=(a107*a162);
  a179=(a179+a030);
  a030=(a055*a179);
  a030=(a019+a030);
  a030=(a107*a030);
  a030=(a106*a030);
  a199=(a199-a030);
  a030=(a025*a179);
  a163=(a110*a206);
  a030=(a030-a163);
  a209=(a107*a030);
  a064=(a009*a209);
  a199=(a199-a064);
  a064=(a023*a018);
  a016=(a110*a064);
  a179=(a052*a179);
  a179=(a016+a179);
  a220=(a107*a179);
  a017=(a004*a220);
  a199=(a199-a017);
  a017=(a121*a186);
  a045=(a027*a061);
  a032=(a018*a185);
  a045=(a045+a032);
  a032=(a020*a190);
  a045=(a045-a032);
  a032=(a109*a045);
  a014=(a080*a182);
  a167=(a091*a176);
  a014=(a014-a167);
  a167=(a075*a205);
  a034=(a031*a122);
  a167=(a167-a034);
  a014=(a014+a167);
  a005=(a099*a005);
  a167=(a077*a200);
  a005=(a005+a167);
  a014=(a014-a005);
  a005=(a013*a014);
  a032=(a032+a005);
  a005=(a000*a032);
  a167=(a108*a005);
  a045=(a013*a045);
  a014=(a067*a014);
  a045=(a045+a014);
  a014=(a000*a045);
  a034=(a107*a014);
  a167=(a167+a034);
  a034=(a055*a167);
  a034=(a017+a034);
  a184=(a107*a034);
  a011=(a009*a184);
  a199=(a199-a011);
  a011=(a121*a064);
  a131=(a052*a167);
  a131=(a011+a131);
  a059=(a037*a131);
  a199=(a199-a059);
  a059=(a129*a186);
  a175=(a018*a061);
  a185=(a027*a185);
  a185=(a175-a185);
  a190=(a051*a190);
  a185=(a185+a190);
  a190=(a109*a185);
  a182=(a075*a182);
  a133=(a091*a122);
  a182=(a182-a133);
  a205=(a080*a205);
  a176=(a031*a176);
  a205=(a205-a176);
  a182=(a182-a205);
  a200=(a089*a200);
  a187=(a099*a187);
  a200=(a200-a187);
  a182=(a182+a200);
  a200=(a013*a182);
  a190=(a190+a200);
  a200=(a000*a190);
  a187=(a108*a200);
  a185=(a013*a185);
  a182=(a067*a182);
  a185=(a185+a182);
  a182=(a000*a185);
  a205=(a107*a182);
  a187=(a187+a205);
  a205=(a055*a187);
  a205=(a059+a205);
  a176=(a107*a205);
  a133=(a004*a176);
  a199=(a199-a133);
  a133=(a025*a187);
  a112=(a129*a206);
  a133=(a133-a112);
  a116=(a037*a133);
  a199=(a199+a116);
  a116=(a012*a199);
  a179=(a037*a179);
  a209=(a002*a209);
  a179=(a179-a209);
  a179=(a179+a045);
  a184=(a002*a184);
  a179=(a179-a184);
  a167=(a025*a167);
  a206=(a121*a206);
  a167=(a167-a206);
  a167=(a107*a167);
  a167=(a117*a167);
  a179=(a179-a167);
  a131=(a107*a131);
  a167=(a004*a131);
  a179=(a179-a167);
  a205=(a037*a205);
  a179=(a179-a205);
  a133=(a107*a133);
  a205=(a004*a133);
  a179=(a179-a205);
  a205=(a057*a179);
  a116=(a116+a205);
  a034=(a037*a034);
  a030=(a037*a030);
  a220=(a002*a220);
  a030=(a030+a220);
  a034=(a034-a030);
  a131=(a009*a131);
  a034=(a034-a131);
  a034=(a034+a185);
  a176=(a002*a176);
  a034=(a034-a176);
  a133=(a009*a133);
  a034=(a034-a133);
  a064=(a129*a064);
  a187=(a052*a187);
  a187=(a064+a187);
  a187=(a107*a187);
  a187=(a125*a187);
  a034=(a034-a187);
  a187=(a058*a034);
  a116=(a116+a187);
  a116=(a116/a000);
  if (res[1]!=0) res[1][27]=a116;
  a116=(a036*a199);
  a133=(a042*a179);
  a116=(a116+a133);
  a176=(a047*a034);
  a116=(a116+a176);
  a116=(a116/a000);
  if (res[1]!=0) res[1][28]=a116;
  a116=(a060*a199);
  a176=(a063*a179);
  a176=(a116+a176);
  a185=(a066*a034);
  a176=(a176+a185);
  a176=(a176/a000);
  if (res[1]!=0) res[1][29]=a176;
  a078=(a037*a078);
  a078=(a075*a078);
  a176=(a092*a122);
  a176=(a078-a176);
  a176=(a135*a176);
  a185=(a029*a122);
  a131=(a075*a000);
  a185=(a185+a131);
  a185=(a137*a185);
  a176=(a176-a185);
  a191=(a037*a191);
  a191=(a075*a191);
  a185=(a069*a122);
  a191=(a191-a185);
  a191=(a138*a191);
  a176=(a176-a191);
  a176=(a139*a176);
  a191=(a050*a165);
  a185=(a087*a177);
  a168=(a107*a168);
  a162=(a141*a162);
  a168=(a168+a162);
  a162=(a098*a168);
  a185=(a185+a162);
  a185=(a107*a185);
  a185=(a015*a185);
  a207=(a207-a185);
  a185=(a087*a028);
  a162=(a024*a168);
  a185=(a185+a162);
  a162=(a107*a185);
  a030=(a070*a162);
  a207=(a207-a030);
  a145=(a145*a000);
  a030=(a087*a172);
  a168=(a090*a168);
  a030=(a030+a168);
  a168=(a107*a030);
  a220=(a068*a168);
  a220=(a145+a220);
  a207=(a207-a220);
  a220=(a120*a177);
  a005=(a107*a005);
  a014=(a141*a014);
  a005=(a005+a014);
  a014=(a098*a005);
  a220=(a220+a014);
  a014=(a107*a220);
  a205=(a070*a014);
  a207=(a207-a205);
  a205=(a120*a172);
  a167=(a090*a005);
  a205=(a205+a167);
  a167=(a037*a205);
  a207=(a207-a167);
  a148=(a148*a000);
  a177=(a128*a177);
  a200=(a107*a200);
  a182=(a141*a182);
  a200=(a200+a182);
  a182=(a098*a200);
  a177=(a177+a182);
  a182=(a107*a177);
  a167=(a068*a182);
  a167=(a148+a167);
  a207=(a207-a167);
  a167=(a128*a028);
  a184=(a024*a200);
  a167=(a167+a184);
  a184=(a037*a167);
  a207=(a207+a184);
  a184=(a094*a207);
  a184=(a191+a184);
  a176=(a176+a184);
  a184=(a118*a219);
  a162=(a073*a162);
  a032=(a032-a162);
  a030=(a037*a030);
  a032=(a032+a030);
  a014=(a073*a014);
  a032=(a032-a014);
  a028=(a120*a028);
  a005=(a024*a005);
  a028=(a028+a005);
  a028=(a107*a028);
  a028=(a144*a028);
  a032=(a032-a028);
  a147=(a147*a000);
  a205=(a107*a205);
  a028=(a068*a205);
  a028=(a147+a028);
  a032=(a032-a028);
  a177=(a037*a177);
  a032=(a032-a177);
  a149=(a149*a000);
  a167=(a107*a167);
  a177=(a068*a167);
  a177=(a149+a177);
  a032=(a032-a177);
  a177=(a096*a032);
  a177=(a184+a177);
  a176=(a176+a177);
  a189=(a126*a189);
  a185=(a037*a185);
  a190=(a190-a185);
  a168=(a073*a168);
  a190=(a190-a168);
  a220=(a037*a220);
  a190=(a190+a220);
  a205=(a070*a205);
  a190=(a190-a205);
  a182=(a073*a182);
  a190=(a190-a182);
  a167=(a070*a167);
  a190=(a190-a167);
  a142=(a142*a201);
  a172=(a128*a172);
  a200=(a090*a200);
  a172=(a172+a200);
  a172=(a107*a172);
  a172=(a119*a172);
  a142=(a142+a172);
  a190=(a190-a142);
  a142=(a097*a190);
  a189=(a189+a142);
  a176=(a176+a189);
  a176=(a176/a000);
  if (res[1]!=0) res[1][30]=a176;
  a176=(a050*a040);
  a142=(a082*a207);
  a142=(a176+a142);
  a172=(a083*a032);
  a142=(a142+a172);
  a200=(a126*a219);
  a167=(a086*a190);
  a167=(a200+a167);
  a142=(a142+a167);
  a142=(a142/a000);
  if (res[1]!=0) res[1][31]=a142;
  a142=(a100*a207);
  a167=(a074*a122);
  a167=(a135*a167);
  a178=(a037*a178);
  a178=(a075*a178);
  a182=(a084*a122);
  a182=(a178-a182);
  a182=(a137*a182);
  a167=(a167+a182);
  a122=(a103*a122);
  a122=(a078-a122);
  a122=(a138*a122);
  a167=(a167+a122);
  a167=(a139*a167);
  a167=(a142-a167);
  a122=(a102*a032);
  a182=(a118*a040);
  a122=(a122-a182);
  a167=(a167+a122);
  a122=(a126*a165);
  a205=(a105*a190);
  a205=(a122+a205);
  a167=(a167+a205);
  a167=(a167/a000);
  if (res[1]!=0) res[1][32]=a167;
  a167=1.7320508075688774e+00;
  a167=(a167*a000);
  a154=(a154*a167);
  a154=(a107*a154);
  a205=(a038*a154);
  a152=(a152*a167);
  a152=(a107*a152);
  a220=(a043*a152);
  a168=(a205+a220);
  a197=(a197*a167);
  a197=(a107*a197);
  a197=(a048*a197);
  a168=(a168+a197);
  a197=(a093*a207);
  a197=(a191+a197);
  a168=(a168+a197);
  a197=(a095*a032);
  a197=(a184+a197);
  a168=(a168+a197);
  a168=(a168+a189);
  a189=(a007*a199);
  a168=(a168+a189);
  a189=(a056*a179);
  a168=(a168+a189);
  a168=(a168+a187);
  a168=(-a168);
  if (res[1]!=0) res[1][33]=a168;
  a168=(a048*a152);
  a187=8.6602540378443871e-01;
  a187=(a187*a000);
  a189=(a038*a187);
  a168=(a168-a189);
  a207=(a081*a207);
  a207=(a207-a176);
  a168=(a168+a207);
  a168=(a168+a172);
  a172=(a085*a190);
  a200=(a200+a172);
  a168=(a168+a200);
  a199=(a035*a199);
  a168=(a168+a199);
  a168=(a168+a133);
  a133=(a046*a034);
  a168=(a168+a133);
  a168=(-a168);
  if (res[1]!=0) res[1][34]=a168;
  a168=(a043*a187);
  a133=(a048*a154);
  a133=(a168+a133);
  a133=(a133+a142);
  a032=(a101*a032);
  a032=(a182+a032);
  a133=(a133+a032);
  a190=(a104*a190);
  a122=(a122+a190);
  a133=(a133+a122);
  a133=(a133+a116);
  a179=(a062*a179);
  a133=(a133+a179);
  a034=(a065*a034);
  a133=(a133+a034);
  a133=(-a133);
  if (res[1]!=0) res[1][35]=a133;
  a193=(a033*a193);
  a193=(a193/a040);
  a133=(a020*a193);
  a034=(a203*a027);
  a034=(a054*a034);
  a034=(a034/a040);
  a179=(a051*a034);
  a133=(a133-a179);
  a023=(a023*a020);
  a179=(-a023);
  a179=(2.*a179);
  a179=(a054*a179);
  a179=(a179/a040);
  a116=(a018*a179);
  a133=(a133+a116);
  a116=(a013*a133);
  a122=(a144*a000);
  a190=(a072*a122);
  a032=(a008*a190);
  a032=(a204-a032);
  a142=(a079*a190);
  a199=(a003*a142);
  a032=(a032+a199);
  a199=(a076*a190);
  a200=(a001*a199);
  a032=(a032-a200);
  a200=(2.*a032);
  a200=(a033*a200);
  a200=(a200-a153);
  a153=(a107*a122);
  a172=(a044*a153);
  a200=(a200-a172);
  a172=(a068*a000);
  a207=(a107*a172);
  a049=(a049*a207);
  a200=(a200-a049);
  a200=(a200/a040);
  a197=(a077*a200);
  a185=(a031*a199);
  a197=(a197-a185);
  a185=(a088*a190);
  a185=(a164-a185);
  a177=(a091*a185);
  a028=(a008*a142);
  a026=(a026-a028);
  a028=(a003*a190);
  a026=(a026-a028);
  a028=(a001*a185);
  a026=(a026-a028);
  a028=(2.*a026);
  a028=(a054*a028);
  a028=(a028+a166);
  a166=(a044*a207);
  a028=(a028-a166);
  a028=(a028/a040);
  a166=(a089*a028);
  a177=(a177+a166);
  a197=(a197-a177);
  a177=(a003*a185);
  a021=(a021*a077);
  a166=(a008*a199);
  a166=(a021-a166);
  a177=(a177-a166);
  a166=(a001*a190);
  a177=(a177-a166);
  a166=(2.*a177);
  a166=(a054*a166);
  a044=(a044*a165);
  a166=(a166-a044);
  a166=(a166-a211);
  a166=(a166/a040);
  a044=(a075*a166);
  a005=(a099*a190);
  a044=(a044-a005);
  a197=(a197+a044);
  a044=(a067*a197);
  a116=(a116+a044);
  a133=(a109*a133);
  a197=(a013*a197);
  a133=(a133+a197);
  a197=(a000*a133);
  a044=(a108*a197);
  a005=(a000*a116);
  a014=(a107*a005);
  a044=(a044+a014);
  a014=(a055*a044);
  a110=(a110*a023);
  a014=(a014-a110);
  a014=(a107*a014);
  a014=(a106*a014);
  a116=(a116-a014);
  a014=(a025*a044);
  a014=(a016+a014);
  a030=(a107*a014);
  a162=(a009*a030);
  a116=(a116-a162);
  a044=(a052*a044);
  a163=(a163+a044);
  a044=(a107*a163);
  a162=(a004*a044);
  a116=(a116-a162);
  a162=(a027*a034);
  a045=(a018*a193);
  a162=(a162+a045);
  a045=(a020*a179);
  a162=(a162-a045);
  a045=(a109*a162);
  a209=(a080*a028);
  a174=(a091*a142);
  a209=(a209-a174);
  a174=(a075*a200);
  a022=(a031*a190);
  a174=(a174-a022);
  a209=(a209+a174);
  a174=(a077*a166);
  a199=(a099*a199);
  a174=(a174-a199);
  a209=(a209-a174);
  a174=(a013*a209);
  a045=(a045+a174);
  a174=(a000*a045);
  a199=(a108*a174);
  a162=(a013*a162);
  a209=(a067*a209);
  a162=(a162+a209);
  a209=(a000*a162);
  a022=(a107*a209);
  a199=(a199+a022);
  a022=(a055*a199);
  a121=(a121*a023);
  a022=(a022-a121);
  a183=(a107*a022);
  a196=(a009*a183);
  a116=(a116-a196);
  a196=(a052*a199);
  a206=(a206+a196);
  a196=(a037*a206);
  a116=(a116-a196);
  a034=(a018*a034);
  a193=(a027*a193);
  a034=(a034-a193);
  a179=(a051*a179);
  a034=(a034+a179);
  a179=(a109*a034);
  a028=(a075*a028);
  a193=(a091*a190);
  a028=(a028-a193);
  a200=(a080*a200);
  a142=(a031*a142);
  a200=(a200-a142);
  a028=(a028-a200);
  a185=(a099*a185);
  a166=(a089*a166);
  a185=(a185+a166);
  a028=(a028+a185);
  a185=(a013*a028);
  a179=(a179+a185);
  a185=(a000*a179);
  a166=(a108*a185);
  a034=(a013*a034);
  a028=(a067*a028);
  a034=(a034+a028);
  a028=(a000*a034);
  a200=(a107*a028);
  a166=(a166+a200);
  a200=(a055*a166);
  a129=(a129*a023);
  a200=(a200-a129);
  a023=(a107*a200);
  a142=(a004*a023);
  a116=(a116-a142);
  a142=(a025*a166);
  a142=(a064+a142);
  a193=(a037*a142);
  a116=(a116+a193);
  a193=(a012*a116);
  a163=(a037*a163);
  a030=(a002*a030);
  a163=(a163-a030);
  a163=(a163+a162);
  a183=(a002*a183);
  a163=(a163-a183);
  a199=(a025*a199);
  a199=(a011+a199);
  a199=(a107*a199);
  a199=(a117*a199);
  a163=(a163-a199);
  a206=(a107*a206);
  a199=(a004*a206);
  a163=(a163-a199);
  a200=(a037*a200);
  a163=(a163-a200);
  a142=(a107*a142);
  a200=(a004*a142);
  a163=(a163-a200);
  a200=(a057*a163);
  a193=(a193+a200);
  a022=(a037*a022);
  a014=(a037*a014);
  a044=(a002*a044);
  a014=(a014+a044);
  a022=(a022-a014);
  a206=(a009*a206);
  a022=(a022-a206);
  a022=(a022+a034);
  a023=(a002*a023);
  a022=(a022-a023);
  a142=(a009*a142);
  a022=(a022-a142);
  a166=(a052*a166);
  a112=(a112+a166);
  a112=(a107*a112);
  a112=(a125*a112);
  a022=(a022-a112);
  a112=(a058*a022);
  a193=(a193+a112);
  a193=(a193/a000);
  if (res[1]!=0) res[1][36]=a193;
  a193=(a036*a116);
  a166=(a042*a163);
  a193=(a193+a166);
  a142=(a047*a022);
  a193=(a193+a142);
  a193=(a193/a000);
  if (res[1]!=0) res[1][37]=a193;
  a193=(a060*a116);
  a142=(a063*a163);
  a142=(a193+a142);
  a023=(a066*a022);
  a142=(a142+a023);
  a142=(a142/a000);
  if (res[1]!=0) res[1][38]=a142;
  a142=(a092*a190);
  a142=(a131-a142);
  a142=(a135*a142);
  a023=(a029*a190);
  a078=(a078-a023);
  a078=(a137*a078);
  a142=(a142+a078);
  a122=(a037*a122);
  a122=(a075*a122);
  a078=(a069*a190);
  a078=(a122-a078);
  a078=(a138*a078);
  a142=(a142-a078);
  a142=(a139*a142);
  a078=(a087*a177);
  a197=(a107*a197);
  a005=(a141*a005);
  a197=(a197+a005);
  a005=(a098*a197);
  a078=(a078+a005);
  a078=(a107*a078);
  a078=(a015*a078);
  a133=(a133-a078);
  a143=(a143*a000);
  a078=(a087*a032);
  a005=(a024*a197);
  a078=(a078+a005);
  a005=(a107*a078);
  a023=(a070*a005);
  a023=(a143+a023);
  a133=(a133-a023);
  a023=(a087*a026);
  a197=(a090*a197);
  a023=(a023+a197);
  a197=(a107*a023);
  a034=(a068*a197);
  a133=(a133-a034);
  a146=(a146*a000);
  a034=(a120*a177);
  a174=(a107*a174);
  a209=(a141*a209);
  a174=(a174+a209);
  a209=(a098*a174);
  a034=(a034+a209);
  a209=(a107*a034);
  a206=(a070*a209);
  a206=(a146+a206);
  a133=(a133-a206);
  a206=(a120*a026);
  a014=(a090*a174);
  a206=(a206+a014);
  a014=(a037*a206);
  a133=(a133-a014);
  a177=(a128*a177);
  a185=(a107*a185);
  a028=(a141*a028);
  a185=(a185+a028);
  a028=(a098*a185);
  a177=(a177+a028);
  a028=(a107*a177);
  a014=(a068*a028);
  a133=(a133-a014);
  a014=(a128*a032);
  a044=(a024*a185);
  a014=(a014+a044);
  a044=(a037*a014);
  a133=(a133+a044);
  a044=(a094*a133);
  a044=(a044-a176);
  a142=(a142+a044);
  a044=(a118*a207);
  a005=(a073*a005);
  a045=(a045-a005);
  a023=(a037*a023);
  a045=(a045+a023);
  a209=(a073*a209);
  a045=(a045-a209);
  a150=(a150*a201);
  a032=(a120*a032);
  a174=(a024*a174);
  a032=(a032+a174);
  a032=(a107*a032);
  a032=(a144*a032);
  a150=(a150+a032);
  a045=(a045-a150);
  a206=(a107*a206);
  a150=(a068*a206);
  a045=(a045-a150);
  a177=(a037*a177);
  a045=(a045-a177);
  a014=(a107*a014);
  a177=(a068*a014);
  a045=(a045-a177);
  a177=(a096*a045);
  a177=(a044+a177);
  a142=(a142+a177);
  a078=(a037*a078);
  a179=(a179-a078);
  a197=(a073*a197);
  a179=(a179-a197);
  a034=(a037*a034);
  a179=(a179+a034);
  a206=(a070*a206);
  a147=(a147+a206);
  a179=(a179-a147);
  a028=(a073*a028);
  a179=(a179-a028);
  a014=(a070*a014);
  a149=(a149+a014);
  a179=(a179-a149);
  a026=(a128*a026);
  a185=(a090*a185);
  a026=(a026+a185);
  a026=(a107*a026);
  a026=(a119*a026);
  a179=(a179-a026);
  a026=(a097*a179);
  a142=(a142+a026);
  a142=(a142/a000);
  if (res[1]!=0) res[1][39]=a142;
  a142=(a082*a133);
  a142=(a191+a142);
  a153=(a118*a153);
  a185=(a083*a045);
  a153=(a153+a185);
  a142=(a142+a153);
  a185=(a126*a207);
  a149=(a086*a179);
  a149=(a185+a149);
  a142=(a142+a149);
  a142=(a142/a000);
  if (res[1]!=0) res[1][40]=a142;
  a142=(a100*a133);
  a172=(a037*a172);
  a172=(a075*a172);
  a149=(a084*a190);
  a149=(a172-a149);
  a149=(a137*a149);
  a014=(a074*a190);
  a122=(a122-a014);
  a122=(a135*a122);
  a149=(a149-a122);
  a190=(a103*a190);
  a190=(a190+a131);
  a190=(a138*a190);
  a149=(a149-a190);
  a149=(a139*a149);
  a149=(a142-a149);
  a118=(a118*a165);
  a165=(a102*a045);
  a165=(a118+a165);
  a149=(a149+a165);
  a126=(a126*a040);
  a165=(a105*a179);
  a165=(a126+a165);
  a149=(a149+a165);
  a149=(a149/a000);
  if (res[1]!=0) res[1][41]=a149;
  a155=(a155*a167);
  a155=(a107*a155);
  a149=(a043*a155);
  a189=(a189+a149);
  a149=(a093*a133);
  a176=(a176+a149);
  a189=(a189+a176);
  a176=(a095*a045);
  a044=(a044+a176);
  a189=(a189+a044);
  a189=(a189+a026);
  a026=(a007*a116);
  a189=(a189+a026);
  a026=(a056*a163);
  a189=(a189+a026);
  a189=(a189+a112);
  a189=(-a189);
  if (res[1]!=0) res[1][42]=a189;
  a188=(a188*a167);
  a188=(a107*a188);
  a188=(a043*a188);
  a205=(a205+a188);
  a188=(a048*a155);
  a205=(a205+a188);
  a133=(a081*a133);
  a191=(a191+a133);
  a205=(a205+a191);
  a205=(a205+a153);
  a153=(a085*a179);
  a153=(a185+a153);
  a205=(a205+a153);
  a116=(a035*a116);
  a205=(a205+a116);
  a205=(a205+a166);
  a166=(a046*a022);
  a205=(a205+a166);
  a205=(-a205);
  if (res[1]!=0) res[1][43]=a205;
  a043=(a043*a154);
  a048=(a048*a187);
  a043=(a043-a048);
  a043=(a043+a142);
  a045=(a101*a045);
  a118=(a118+a045);
  a043=(a043+a118);
  a179=(a104*a179);
  a179=(a179-a126);
  a043=(a043+a179);
  a043=(a043+a193);
  a163=(a062*a163);
  a043=(a043+a163);
  a022=(a065*a022);
  a043=(a043+a022);
  a043=(-a043);
  if (res[1]!=0) res[1][44]=a043;
  a203=(a203*a020);
  a203=(a033*a203);
  a203=(a203/a040);
  a043=(a020*a203);
  a186=(-a186);
  a186=(2.*a186);
  a186=(a054*a186);
  a186=(a186/a040);
  a022=(a051*a186);
  a043=(a043-a022);
  a043=(a043+a175);
  a175=(a013*a043);
  a022=(a015*a000);
  a072=(a072*a022);
  a076=(a076*a072);
  a163=(a001*a076);
  a021=(a021-a163);
  a163=(a008*a072);
  a079=(a079*a072);
  a164=(a164-a079);
  a079=(a003*a164);
  a163=(a163+a079);
  a021=(a021-a163);
  a163=(2.*a021);
  a033=(a033*a163);
  a163=(a039*a219);
  a033=(a033-a163);
  a033=(a033+a211);
  a033=(a033/a040);
  a211=(a077*a033);
  a163=(a031*a076);
  a211=(a211-a163);
  a163=(a008*a164);
  a079=(a003*a072);
  a163=(a163-a079);
  a088=(a088*a072);
  a079=(a001*a088);
  a130=(a130-a079);
  a163=(a163-a130);
  a130=(2.*a163);
  a130=(a054*a130);
  a079=(a039*a207);
  a130=(a130-a079);
  a130=(a130-a180);
  a130=(a130/a040);
  a180=(a089*a130);
  a079=(a091*a088);
  a180=(a180-a079);
  a211=(a211-a180);
  a008=(a008*a076);
  a003=(a003*a088);
  a008=(a008-a003);
  a001=(a001*a072);
  a204=(a204-a001);
  a008=(a008+a204);
  a204=(2.*a008);
  a054=(a054*a204);
  a204=(a107*a022);
  a039=(a039*a204);
  a054=(a054-a039);
  a054=(a054-a192);
  a054=(a054-a049);
  a054=(a054/a040);
  a049=(a075*a054);
  a192=(a099*a072);
  a049=(a049-a192);
  a211=(a211+a049);
  a049=(a067*a211);
  a175=(a175+a049);
  a043=(a109*a043);
  a211=(a013*a211);
  a043=(a043+a211);
  a211=(a000*a043);
  a049=(a108*a211);
  a192=(a000*a175);
  a039=(a107*a192);
  a049=(a049+a039);
  a039=(a055*a049);
  a016=(a016+a039);
  a016=(a107*a016);
  a016=(a106*a016);
  a175=(a175-a016);
  a016=(a025*a049);
  a110=(a110+a016);
  a016=(a107*a110);
  a039=(a009*a016);
  a175=(a175-a039);
  a049=(a052*a049);
  a049=(a049-a019);
  a019=(a107*a049);
  a039=(a004*a019);
  a175=(a175-a039);
  a039=(a027*a186);
  a001=(a018*a203);
  a039=(a039+a001);
  a061=(a020*a061);
  a039=(a039-a061);
  a061=(a109*a039);
  a001=(a091*a164);
  a003=(a080*a130);
  a001=(a001+a003);
  a003=(a075*a033);
  a180=(a031*a072);
  a003=(a003-a180);
  a001=(a001+a003);
  a003=(a077*a054);
  a076=(a099*a076);
  a003=(a003-a076);
  a001=(a001-a003);
  a003=(a013*a001);
  a061=(a061+a003);
  a003=(a000*a061);
  a076=(a108*a003);
  a039=(a013*a039);
  a001=(a067*a001);
  a039=(a039+a001);
  a001=(a000*a039);
  a180=(a107*a001);
  a076=(a076+a180);
  a180=(a055*a076);
  a011=(a011+a180);
  a180=(a107*a011);
  a079=(a009*a180);
  a175=(a175-a079);
  a079=(a052*a076);
  a079=(a079-a017);
  a017=(a037*a079);
  a175=(a175-a017);
  a186=(a018*a186);
  a203=(a027*a203);
  a186=(a186-a203);
  a186=(a186+a169);
  a169=(a109*a186);
  a130=(a075*a130);
  a091=(a091*a072);
  a130=(a130-a091);
  a031=(a031*a164);
  a033=(a080*a033);
  a031=(a031+a033);
  a130=(a130-a031);
  a054=(a089*a054);
  a099=(a099*a088);
  a054=(a054-a099);
  a130=(a130+a054);
  a054=(a013*a130);
  a169=(a169+a054);
  a054=(a000*a169);
  a099=(a108*a054);
  a186=(a013*a186);
  a130=(a067*a130);
  a186=(a186+a130);
  a130=(a000*a186);
  a088=(a107*a130);
  a099=(a099+a088);
  a088=(a055*a099);
  a064=(a064+a088);
  a088=(a107*a064);
  a031=(a004*a088);
  a175=(a175-a031);
  a031=(a025*a099);
  a129=(a129+a031);
  a031=(a037*a129);
  a175=(a175+a031);
  a031=(a012*a175);
  a049=(a037*a049);
  a016=(a002*a016);
  a049=(a049-a016);
  a049=(a049+a039);
  a180=(a002*a180);
  a049=(a049-a180);
  a076=(a025*a076);
  a121=(a121+a076);
  a121=(a107*a121);
  a121=(a117*a121);
  a049=(a049-a121);
  a079=(a107*a079);
  a121=(a004*a079);
  a049=(a049-a121);
  a064=(a037*a064);
  a049=(a049-a064);
  a129=(a107*a129);
  a064=(a004*a129);
  a049=(a049-a064);
  a064=(a057*a049);
  a031=(a031+a064);
  a011=(a037*a011);
  a110=(a037*a110);
  a019=(a002*a019);
  a110=(a110+a019);
  a011=(a011-a110);
  a079=(a009*a079);
  a011=(a011-a079);
  a011=(a011+a186);
  a088=(a002*a088);
  a011=(a011-a088);
  a129=(a009*a129);
  a011=(a011-a129);
  a099=(a052*a099);
  a099=(a099-a059);
  a099=(a107*a099);
  a099=(a125*a099);
  a011=(a011-a099);
  a099=(a058*a011);
  a031=(a031+a099);
  a031=(a031/a000);
  if (res[1]!=0) res[1][45]=a031;
  a031=(a036*a175);
  a059=(a042*a049);
  a031=(a031+a059);
  a129=(a047*a011);
  a031=(a031+a129);
  a031=(a031/a000);
  if (res[1]!=0) res[1][46]=a031;
  a031=(a060*a175);
  a129=(a063*a049);
  a129=(a031+a129);
  a088=(a066*a011);
  a129=(a129+a088);
  a129=(a129/a000);
  if (res[1]!=0) res[1][47]=a129;
  a092=(a092*a072);
  a092=(a172-a092);
  a092=(a135*a092);
  a029=(a029*a072);
  a178=(a178-a029);
  a178=(a137*a178);
  a092=(a092+a178);
  a069=(a069*a072);
  a069=(a138*a069);
  a092=(a092+a069);
  a092=(a139*a092);
  a207=(a050*a207);
  a111=(a111*a201);
  a201=(a087*a008);
  a211=(a107*a211);
  a192=(a141*a192);
  a211=(a211+a192);
  a192=(a098*a211);
  a201=(a201+a192);
  a201=(a107*a201);
  a201=(a015*a201);
  a111=(a111+a201);
  a043=(a043-a111);
  a111=(a087*a021);
  a201=(a024*a211);
  a111=(a111+a201);
  a201=(a107*a111);
  a192=(a070*a201);
  a043=(a043-a192);
  a087=(a087*a163);
  a211=(a090*a211);
  a087=(a087+a211);
  a211=(a107*a087);
  a192=(a068*a211);
  a043=(a043-a192);
  a192=(a120*a008);
  a003=(a107*a003);
  a001=(a141*a001);
  a003=(a003+a001);
  a001=(a098*a003);
  a192=(a192+a001);
  a001=(a107*a192);
  a069=(a070*a001);
  a043=(a043-a069);
  a069=(a120*a163);
  a178=(a090*a003);
  a069=(a069+a178);
  a178=(a037*a069);
  a043=(a043-a178);
  a008=(a128*a008);
  a054=(a107*a054);
  a130=(a141*a130);
  a054=(a054+a130);
  a130=(a098*a054);
  a008=(a008+a130);
  a130=(a107*a008);
  a178=(a068*a130);
  a043=(a043-a178);
  a178=(a128*a021);
  a029=(a024*a054);
  a178=(a178+a029);
  a029=(a037*a178);
  a043=(a043+a029);
  a029=(a094*a043);
  a029=(a207+a029);
  a092=(a092+a029);
  a201=(a073*a201);
  a143=(a143+a201);
  a061=(a061-a143);
  a087=(a037*a087);
  a061=(a061+a087);
  a001=(a073*a001);
  a146=(a146+a001);
  a061=(a061-a146);
  a120=(a120*a021);
  a003=(a024*a003);
  a120=(a120+a003);
  a120=(a107*a120);
  a120=(a144*a120);
  a061=(a061-a120);
  a069=(a107*a069);
  a120=(a068*a069);
  a061=(a061-a120);
  a008=(a037*a008);
  a061=(a061-a008);
  a178=(a107*a178);
  a008=(a068*a178);
  a061=(a061-a008);
  a008=(a096*a061);
  a008=(a182+a008);
  a092=(a092+a008);
  a111=(a037*a111);
  a169=(a169-a111);
  a211=(a073*a211);
  a145=(a145+a211);
  a169=(a169-a145);
  a192=(a037*a192);
  a169=(a169+a192);
  a069=(a070*a069);
  a169=(a169-a069);
  a130=(a073*a130);
  a148=(a148+a130);
  a169=(a169-a148);
  a178=(a070*a178);
  a169=(a169-a178);
  a128=(a128*a163);
  a054=(a090*a054);
  a128=(a128+a054);
  a128=(a107*a128);
  a128=(a119*a128);
  a169=(a169-a128);
  a128=(a097*a169);
  a092=(a092+a128);
  a092=(a092/a000);
  if (res[1]!=0) res[1][48]=a092;
  a219=(a050*a219);
  a092=(a082*a043);
  a092=(a219+a092);
  a054=(a083*a061);
  a092=(a092+a054);
  a163=(a086*a169);
  a163=(a163-a126);
  a092=(a092+a163);
  a092=(a092/a000);
  if (res[1]!=0) res[1][49]=a092;
  a050=(a050*a204);
  a204=(a100*a043);
  a050=(a050+a204);
  a084=(a084*a072);
  a131=(a131-a084);
  a137=(a137*a131);
  a022=(a037*a022);
  a022=(a075*a022);
  a074=(a074*a072);
  a022=(a022-a074);
  a135=(a135*a022);
  a137=(a137-a135);
  a103=(a103*a072);
  a172=(a172-a103);
  a138=(a138*a172);
  a137=(a137+a138);
  a139=(a139*a137);
  a139=(a050-a139);
  a137=(a102*a061);
  a137=(a184+a137);
  a139=(a139+a137);
  a137=(a105*a169);
  a137=(a185+a137);
  a139=(a139+a137);
  a139=(a139/a000);
  if (res[1]!=0) res[1][50]=a139;
  a155=(a038*a155);
  a155=(a155-a168);
  a168=(a093*a043);
  a207=(a207+a168);
  a155=(a155+a207);
  a207=(a095*a061);
  a207=(a207-a182);
  a155=(a155+a207);
  a155=(a155+a128);
  a128=(a007*a175);
  a155=(a155+a128);
  a128=(a056*a049);
  a155=(a155+a128);
  a155=(a155+a099);
  a155=(-a155);
  if (res[1]!=0) res[1][51]=a155;
  a152=(a038*a152);
  a152=(a152+a048);
  a043=(a081*a043);
  a219=(a219+a043);
  a152=(a152+a219);
  a152=(a152+a054);
  a054=(a085*a169);
  a126=(a126+a054);
  a152=(a152+a126);
  a175=(a035*a175);
  a152=(a152+a175);
  a152=(a152+a059);
  a059=(a046*a011);
  a152=(a152+a059);
  a152=(-a152);
  if (res[1]!=0) res[1][52]=a152;
  a198=(a198*a167);
  a198=(a107*a198);
  a038=(a038*a198);
  a038=(a038+a220);
  a038=(a038+a188);
  a038=(a038+a050);
  a061=(a101*a061);
  a184=(a184+a061);
  a038=(a038+a184);
  a169=(a104*a169);
  a185=(a185+a169);
  a038=(a038+a185);
  a038=(a038+a031);
  a049=(a062*a049);
  a038=(a038+a049);
  a011=(a065*a011);
  a038=(a038+a011);
  a038=(-a038);
  if (res[1]!=0) res[1][53]=a038;
  a038=(a051*a058);
  a011=(a020*a047);
  a038=(a038-a011);
  a011=(a018*a066);
  a038=(a038-a011);
  a011=(a013*a038);
  a049=(a089*a097);
  a031=(a077*a086);
  a049=(a049-a031);
  a031=(a075*a105);
  a049=(a049-a031);
  a031=(a067*a049);
  a011=(a011+a031);
  a038=(a109*a038);
  a049=(a013*a049);
  a038=(a038+a049);
  a049=(a000*a038);
  a031=(a108*a049);
  a185=(a000*a011);
  a169=(a107*a185);
  a031=(a031+a169);
  a169=(a055*a031);
  a169=(a107*a169);
  a169=(a106*a169);
  a011=(a011-a169);
  a169=(a025*a031);
  a184=(a107*a169);
  a061=(a009*a184);
  a011=(a011-a061);
  a031=(a052*a031);
  a061=(a107*a031);
  a050=(a004*a061);
  a011=(a011-a050);
  a050=(a020*a066);
  a188=(a027*a058);
  a220=(a018*a047);
  a188=(a188+a220);
  a050=(a050-a188);
  a188=(a109*a050);
  a220=(a077*a105);
  a198=(a080*a097);
  a167=(a075*a086);
  a198=(a198+a167);
  a220=(a220-a198);
  a198=(a013*a220);
  a188=(a188+a198);
  a198=(a000*a188);
  a167=(a108*a198);
  a050=(a013*a050);
  a220=(a067*a220);
  a050=(a050+a220);
  a220=(a000*a050);
  a152=(a107*a220);
  a167=(a167+a152);
  a152=(a055*a167);
  a059=(a107*a152);
  a175=(a009*a059);
  a011=(a011-a175);
  a175=(a052*a167);
  a126=(a037*a175);
  a011=(a011-a126);
  a126=(a027*a047);
  a054=(a018*a058);
  a126=(a126-a054);
  a054=(a051*a066);
  a126=(a126-a054);
  a054=(a109*a126);
  a219=(a080*a086);
  a043=(a075*a097);
  a219=(a219-a043);
  a043=(a089*a105);
  a219=(a219-a043);
  a043=(a013*a219);
  a054=(a054+a043);
  a043=(a000*a054);
  a048=(a108*a043);
  a048=(a040+a048);
  a126=(a013*a126);
  a219=(a067*a219);
  a126=(a126+a219);
  a219=(a000*a126);
  a155=(a107*a219);
  a048=(a048+a155);
  a155=(a055*a048);
  a099=(a107*a155);
  a128=(a004*a099);
  a011=(a011-a128);
  a128=(a025*a048);
  a207=(a037*a128);
  a011=(a011+a207);
  a207=(a012*a011);
  a031=(a037*a031);
  a184=(a002*a184);
  a031=(a031-a184);
  a031=(a031+a050);
  a059=(a002*a059);
  a031=(a031-a059);
  a167=(a025*a167);
  a167=(a107*a167);
  a167=(a117*a167);
  a031=(a031-a167);
  a175=(a107*a175);
  a167=(a004*a175);
  a031=(a031-a167);
  a155=(a037*a155);
  a031=(a031-a155);
  a128=(a107*a128);
  a155=(a004*a128);
  a031=(a031-a155);
  a155=(a057*a031);
  a207=(a207+a155);
  a152=(a037*a152);
  a169=(a037*a169);
  a061=(a002*a061);
  a169=(a169+a061);
  a152=(a152-a169);
  a175=(a009*a175);
  a152=(a152-a175);
  a152=(a152+a126);
  a099=(a002*a099);
  a152=(a152-a099);
  a128=(a009*a128);
  a152=(a152-a128);
  a048=(a052*a048);
  a048=(a107*a048);
  a048=(a125*a048);
  a152=(a152-a048);
  a048=(a058*a152);
  a207=(a207+a048);
  a207=(a207/a000);
  if (res[1]!=0) res[1][54]=a207;
  a207=(a036*a011);
  a128=(a042*a031);
  a207=(a207+a128);
  a099=(a047*a152);
  a207=(a207+a099);
  a207=(a207/a000);
  if (res[1]!=0) res[1][55]=a207;
  a207=(a060*a011);
  a099=(a063*a031);
  a099=(a207+a099);
  a126=(a066*a152);
  a099=(a099+a126);
  a099=(a099/a000);
  if (res[1]!=0) res[1][56]=a099;
  a049=(a107*a049);
  a185=(a141*a185);
  a049=(a049+a185);
  a185=(a098*a049);
  a185=(a107*a185);
  a185=(a015*a185);
  a038=(a038-a185);
  a185=(a024*a049);
  a099=(a107*a185);
  a126=(a070*a099);
  a038=(a038-a126);
  a049=(a090*a049);
  a126=(a107*a049);
  a175=(a068*a126);
  a038=(a038-a175);
  a198=(a107*a198);
  a220=(a141*a220);
  a198=(a198+a220);
  a220=(a098*a198);
  a175=(a107*a220);
  a169=(a070*a175);
  a038=(a038-a169);
  a169=(a090*a198);
  a061=(a037*a169);
  a038=(a038-a061);
  a043=(a107*a043);
  a043=(a040+a043);
  a219=(a141*a219);
  a043=(a043+a219);
  a219=(a098*a043);
  a061=(a107*a219);
  a155=(a068*a061);
  a038=(a038-a155);
  a155=(a024*a043);
  a167=(a037*a155);
  a038=(a038+a167);
  a167=(a094*a038);
  a099=(a073*a099);
  a188=(a188-a099);
  a049=(a037*a049);
  a188=(a188+a049);
  a175=(a073*a175);
  a188=(a188-a175);
  a198=(a024*a198);
  a198=(a107*a198);
  a198=(a144*a198);
  a188=(a188-a198);
  a169=(a107*a169);
  a198=(a068*a169);
  a188=(a188-a198);
  a219=(a037*a219);
  a188=(a188-a219);
  a155=(a107*a155);
  a219=(a068*a155);
  a188=(a188-a219);
  a219=(a096*a188);
  a167=(a167+a219);
  a185=(a037*a185);
  a054=(a054-a185);
  a126=(a073*a126);
  a054=(a054-a126);
  a220=(a037*a220);
  a054=(a054+a220);
  a169=(a070*a169);
  a054=(a054-a169);
  a061=(a073*a061);
  a054=(a054-a061);
  a155=(a070*a155);
  a054=(a054-a155);
  a043=(a090*a043);
  a043=(a107*a043);
  a043=(a119*a043);
  a054=(a054-a043);
  a043=(a097*a054);
  a167=(a167+a043);
  a167=(a167/a000);
  if (res[1]!=0) res[1][57]=a167;
  a167=(a082*a038);
  a155=(a083*a188);
  a167=(a167+a155);
  a061=(a086*a054);
  a167=(a167+a061);
  a167=(a167/a000);
  if (res[1]!=0) res[1][58]=a167;
  a167=(a100*a038);
  a061=(a102*a188);
  a061=(a167+a061);
  a169=(a105*a054);
  a061=(a061+a169);
  a061=(a061/a000);
  if (res[1]!=0) res[1][59]=a061;
  a061=(a093*a038);
  a160=(a160+a061);
  a061=(a095*a188);
  a160=(a160+a061);
  a160=(a160+a043);
  a043=(a007*a011);
  a160=(a160+a043);
  a043=(a056*a031);
  a160=(a160+a043);
  a160=(a160+a048);
  a160=(-a160);
  if (res[1]!=0) res[1][60]=a160;
  a038=(a081*a038);
  a159=(a159+a038);
  a159=(a159+a155);
  a155=(a085*a054);
  a159=(a159+a155);
  a011=(a035*a011);
  a159=(a159+a011);
  a159=(a159+a128);
  a128=(a046*a152);
  a159=(a159+a128);
  a159=(-a159);
  if (res[1]!=0) res[1][61]=a159;
  a136=(a136+a167);
  a188=(a101*a188);
  a136=(a136+a188);
  a054=(a104*a054);
  a136=(a136+a054);
  a136=(a136+a207);
  a031=(a062*a031);
  a136=(a136+a031);
  a152=(a065*a152);
  a136=(a136+a152);
  a136=(-a136);
  if (res[1]!=0) res[1][62]=a136;
  a136=(a051*a057);
  a152=(a020*a042);
  a136=(a136-a152);
  a152=(a018*a063);
  a136=(a136-a152);
  a152=(a013*a136);
  a031=(a089*a096);
  a207=(a077*a083);
  a031=(a031-a207);
  a207=(a075*a102);
  a031=(a031-a207);
  a207=(a067*a031);
  a152=(a152+a207);
  a136=(a109*a136);
  a031=(a013*a031);
  a136=(a136+a031);
  a031=(a000*a136);
  a207=(a108*a031);
  a054=(a000*a152);
  a188=(a107*a054);
  a207=(a207+a188);
  a188=(a055*a207);
  a188=(a107*a188);
  a188=(a106*a188);
  a152=(a152-a188);
  a188=(a025*a207);
  a167=(a107*a188);
  a159=(a009*a167);
  a152=(a152-a159);
  a207=(a052*a207);
  a159=(a107*a207);
  a128=(a004*a159);
  a152=(a152-a128);
  a128=(a020*a063);
  a011=(a027*a057);
  a155=(a018*a042);
  a011=(a011+a155);
  a128=(a128-a011);
  a011=(a109*a128);
  a155=(a077*a102);
  a038=(a080*a096);
  a160=(a075*a083);
  a038=(a038+a160);
  a155=(a155-a038);
  a038=(a013*a155);
  a011=(a011+a038);
  a038=(a000*a011);
  a160=(a108*a038);
  a160=(a040+a160);
  a128=(a013*a128);
  a155=(a067*a155);
  a128=(a128+a155);
  a155=(a000*a128);
  a048=(a107*a155);
  a160=(a160+a048);
  a048=(a055*a160);
  a043=(a107*a048);
  a061=(a009*a043);
  a152=(a152-a061);
  a061=(a052*a160);
  a169=(a037*a061);
  a152=(a152-a169);
  a169=(a027*a042);
  a220=(a018*a057);
  a169=(a169-a220);
  a220=(a051*a063);
  a169=(a169-a220);
  a220=(a109*a169);
  a126=(a080*a083);
  a185=(a075*a096);
  a126=(a126-a185);
  a185=(a089*a102);
  a126=(a126-a185);
  a185=(a013*a126);
  a220=(a220+a185);
  a185=(a000*a220);
  a219=(a108*a185);
  a169=(a013*a169);
  a126=(a067*a126);
  a169=(a169+a126);
  a126=(a000*a169);
  a198=(a107*a126);
  a219=(a219+a198);
  a198=(a055*a219);
  a175=(a107*a198);
  a049=(a004*a175);
  a152=(a152-a049);
  a049=(a025*a219);
  a099=(a037*a049);
  a152=(a152+a099);
  a099=(a012*a152);
  a207=(a037*a207);
  a167=(a002*a167);
  a207=(a207-a167);
  a207=(a207+a128);
  a043=(a002*a043);
  a207=(a207-a043);
  a160=(a025*a160);
  a160=(a107*a160);
  a160=(a117*a160);
  a207=(a207-a160);
  a061=(a107*a061);
  a160=(a004*a061);
  a207=(a207-a160);
  a198=(a037*a198);
  a207=(a207-a198);
  a049=(a107*a049);
  a198=(a004*a049);
  a207=(a207-a198);
  a198=(a057*a207);
  a099=(a099+a198);
  a048=(a037*a048);
  a188=(a037*a188);
  a159=(a002*a159);
  a188=(a188+a159);
  a048=(a048-a188);
  a061=(a009*a061);
  a048=(a048-a061);
  a048=(a048+a169);
  a175=(a002*a175);
  a048=(a048-a175);
  a049=(a009*a049);
  a048=(a048-a049);
  a219=(a052*a219);
  a219=(a107*a219);
  a219=(a125*a219);
  a048=(a048-a219);
  a219=(a058*a048);
  a099=(a099+a219);
  a099=(a099/a000);
  if (res[1]!=0) res[1][63]=a099;
  a099=(a036*a152);
  a049=(a042*a207);
  a099=(a099+a049);
  a175=(a047*a048);
  a099=(a099+a175);
  a099=(a099/a000);
  if (res[1]!=0) res[1][64]=a099;
  a099=(a060*a152);
  a175=(a063*a207);
  a175=(a099+a175);
  a169=(a066*a048);
  a175=(a175+a169);
  a175=(a175/a000);
  if (res[1]!=0) res[1][65]=a175;
  a031=(a107*a031);
  a054=(a141*a054);
  a031=(a031+a054);
  a054=(a098*a031);
  a054=(a107*a054);
  a054=(a015*a054);
  a136=(a136-a054);
  a054=(a024*a031);
  a175=(a107*a054);
  a169=(a070*a175);
  a136=(a136-a169);
  a031=(a090*a031);
  a169=(a107*a031);
  a061=(a068*a169);
  a136=(a136-a061);
  a038=(a107*a038);
  a038=(a040+a038);
  a155=(a141*a155);
  a038=(a038+a155);
  a155=(a098*a038);
  a061=(a107*a155);
  a188=(a070*a061);
  a136=(a136-a188);
  a188=(a090*a038);
  a159=(a037*a188);
  a136=(a136-a159);
  a185=(a107*a185);
  a126=(a141*a126);
  a185=(a185+a126);
  a126=(a098*a185);
  a159=(a107*a126);
  a198=(a068*a159);
  a136=(a136-a198);
  a198=(a024*a185);
  a160=(a037*a198);
  a136=(a136+a160);
  a160=(a094*a136);
  a175=(a073*a175);
  a011=(a011-a175);
  a031=(a037*a031);
  a011=(a011+a031);
  a061=(a073*a061);
  a011=(a011-a061);
  a038=(a024*a038);
  a038=(a107*a038);
  a038=(a144*a038);
  a011=(a011-a038);
  a188=(a107*a188);
  a038=(a068*a188);
  a011=(a011-a038);
  a126=(a037*a126);
  a011=(a011-a126);
  a198=(a107*a198);
  a126=(a068*a198);
  a011=(a011-a126);
  a126=(a096*a011);
  a160=(a160+a126);
  a054=(a037*a054);
  a220=(a220-a054);
  a169=(a073*a169);
  a220=(a220-a169);
  a155=(a037*a155);
  a220=(a220+a155);
  a188=(a070*a188);
  a220=(a220-a188);
  a159=(a073*a159);
  a220=(a220-a159);
  a198=(a070*a198);
  a220=(a220-a198);
  a185=(a090*a185);
  a185=(a107*a185);
  a185=(a119*a185);
  a220=(a220-a185);
  a185=(a097*a220);
  a160=(a160+a185);
  a160=(a160/a000);
  if (res[1]!=0) res[1][66]=a160;
  a160=(a082*a136);
  a198=(a083*a011);
  a160=(a160+a198);
  a159=(a086*a220);
  a160=(a160+a159);
  a160=(a160/a000);
  if (res[1]!=0) res[1][67]=a160;
  a160=(a100*a136);
  a159=(a102*a011);
  a159=(a160+a159);
  a188=(a105*a220);
  a159=(a159+a188);
  a159=(a159/a000);
  if (res[1]!=0) res[1][68]=a159;
  a159=(a093*a136);
  a158=(a158+a159);
  a159=(a095*a011);
  a158=(a158+a159);
  a158=(a158+a185);
  a185=(a007*a152);
  a158=(a158+a185);
  a185=(a056*a207);
  a158=(a158+a185);
  a158=(a158+a219);
  a158=(-a158);
  if (res[1]!=0) res[1][69]=a158;
  a136=(a081*a136);
  a127=(a127+a136);
  a127=(a127+a198);
  a198=(a085*a220);
  a127=(a127+a198);
  a152=(a035*a152);
  a127=(a127+a152);
  a127=(a127+a049);
  a049=(a046*a048);
  a127=(a127+a049);
  a127=(-a127);
  if (res[1]!=0) res[1][70]=a127;
  a010=(a010+a160);
  a011=(a101*a011);
  a010=(a010+a011);
  a220=(a104*a220);
  a010=(a010+a220);
  a010=(a010+a099);
  a207=(a062*a207);
  a010=(a010+a207);
  a048=(a065*a048);
  a010=(a010+a048);
  a010=(-a010);
  if (res[1]!=0) res[1][71]=a010;
  a010=(a051*a012);
  a048=(a020*a036);
  a010=(a010-a048);
  a048=(a018*a060);
  a010=(a010-a048);
  a048=(a013*a010);
  a207=(a089*a094);
  a099=(a077*a082);
  a207=(a207-a099);
  a099=(a075*a100);
  a207=(a207-a099);
  a099=(a067*a207);
  a048=(a048+a099);
  a010=(a109*a010);
  a207=(a013*a207);
  a010=(a010+a207);
  a207=(a000*a010);
  a099=(a108*a207);
  a099=(a040+a099);
  a220=(a000*a048);
  a011=(a107*a220);
  a099=(a099+a011);
  a011=(a055*a099);
  a011=(a107*a011);
  a106=(a106*a011);
  a048=(a048-a106);
  a106=(a025*a099);
  a011=(a107*a106);
  a160=(a009*a011);
  a048=(a048-a160);
  a099=(a052*a099);
  a160=(a107*a099);
  a127=(a004*a160);
  a048=(a048-a127);
  a020=(a020*a060);
  a127=(a027*a012);
  a049=(a018*a036);
  a127=(a127+a049);
  a020=(a020-a127);
  a127=(a109*a020);
  a077=(a077*a100);
  a049=(a080*a094);
  a152=(a075*a082);
  a049=(a049+a152);
  a077=(a077-a049);
  a049=(a013*a077);
  a127=(a127+a049);
  a049=(a000*a127);
  a152=(a108*a049);
  a020=(a013*a020);
  a077=(a067*a077);
  a020=(a020+a077);
  a077=(a000*a020);
  a198=(a107*a077);
  a152=(a152+a198);
  a198=(a055*a152);
  a136=(a107*a198);
  a158=(a009*a136);
  a048=(a048-a158);
  a158=(a052*a152);
  a219=(a037*a158);
  a048=(a048-a219);
  a027=(a027*a036);
  a018=(a018*a012);
  a027=(a027-a018);
  a051=(a051*a060);
  a027=(a027-a051);
  a109=(a109*a027);
  a080=(a080*a082);
  a075=(a075*a094);
  a080=(a080-a075);
  a089=(a089*a100);
  a080=(a080-a089);
  a089=(a013*a080);
  a109=(a109+a089);
  a089=(a000*a109);
  a108=(a108*a089);
  a013=(a013*a027);
  a067=(a067*a080);
  a013=(a013+a067);
  a067=(a000*a013);
  a080=(a107*a067);
  a108=(a108+a080);
  a055=(a055*a108);
  a080=(a107*a055);
  a027=(a004*a080);
  a048=(a048-a027);
  a027=(a025*a108);
  a075=(a037*a027);
  a048=(a048+a075);
  a012=(a012*a048);
  a099=(a037*a099);
  a011=(a002*a011);
  a099=(a099-a011);
  a099=(a099+a020);
  a136=(a002*a136);
  a099=(a099-a136);
  a025=(a025*a152);
  a025=(a107*a025);
  a117=(a117*a025);
  a099=(a099-a117);
  a158=(a107*a158);
  a117=(a004*a158);
  a099=(a099-a117);
  a055=(a037*a055);
  a099=(a099-a055);
  a027=(a107*a027);
  a004=(a004*a027);
  a099=(a099-a004);
  a057=(a057*a099);
  a012=(a012+a057);
  a198=(a037*a198);
  a106=(a037*a106);
  a160=(a002*a160);
  a106=(a106+a160);
  a198=(a198-a106);
  a158=(a009*a158);
  a198=(a198-a158);
  a198=(a198+a013);
  a002=(a002*a080);
  a198=(a198-a002);
  a009=(a009*a027);
  a198=(a198-a009);
  a052=(a052*a108);
  a052=(a107*a052);
  a125=(a125*a052);
  a198=(a198-a125);
  a058=(a058*a198);
  a012=(a012+a058);
  a012=(a012/a000);
  if (res[1]!=0) res[1][72]=a012;
  a036=(a036*a048);
  a042=(a042*a099);
  a036=(a036+a042);
  a047=(a047*a198);
  a036=(a036+a047);
  a036=(a036/a000);
  if (res[1]!=0) res[1][73]=a036;
  a060=(a060*a048);
  a063=(a063*a099);
  a063=(a060+a063);
  a066=(a066*a198);
  a063=(a063+a066);
  a063=(a063/a000);
  if (res[1]!=0) res[1][74]=a063;
  a207=(a107*a207);
  a040=(a040+a207);
  a220=(a141*a220);
  a040=(a040+a220);
  a220=(a098*a040);
  a220=(a107*a220);
  a015=(a015*a220);
  a010=(a010-a015);
  a015=(a024*a040);
  a220=(a107*a015);
  a207=(a070*a220);
  a010=(a010-a207);
  a040=(a090*a040);
  a207=(a107*a040);
  a063=(a068*a207);
  a010=(a010-a063);
  a049=(a107*a049);
  a077=(a141*a077);
  a049=(a049+a077);
  a077=(a098*a049);
  a063=(a107*a077);
  a066=(a070*a063);
  a010=(a010-a066);
  a066=(a090*a049);
  a036=(a037*a066);
  a010=(a010-a036);
  a089=(a107*a089);
  a141=(a141*a067);
  a089=(a089+a141);
  a098=(a098*a089);
  a141=(a107*a098);
  a067=(a068*a141);
  a010=(a010-a067);
  a067=(a024*a089);
  a036=(a037*a067);
  a010=(a010+a036);
  a094=(a094*a010);
  a220=(a073*a220);
  a127=(a127-a220);
  a040=(a037*a040);
  a127=(a127+a040);
  a063=(a073*a063);
  a127=(a127-a063);
  a024=(a024*a049);
  a024=(a107*a024);
  a144=(a144*a024);
  a127=(a127-a144);
  a066=(a107*a066);
  a144=(a068*a066);
  a127=(a127-a144);
  a098=(a037*a098);
  a127=(a127-a098);
  a067=(a107*a067);
  a068=(a068*a067);
  a127=(a127-a068);
  a096=(a096*a127);
  a094=(a094+a096);
  a015=(a037*a015);
  a109=(a109-a015);
  a207=(a073*a207);
  a109=(a109-a207);
  a037=(a037*a077);
  a109=(a109+a037);
  a066=(a070*a066);
  a109=(a109-a066);
  a073=(a073*a141);
  a109=(a109-a073);
  a070=(a070*a067);
  a109=(a109-a070);
  a090=(a090*a089);
  a107=(a107*a090);
  a119=(a119*a107);
  a109=(a109-a119);
  a097=(a097*a109);
  a094=(a094+a097);
  a094=(a094/a000);
  if (res[1]!=0) res[1][75]=a094;
  a082=(a082*a010);
  a083=(a083*a127);
  a082=(a082+a083);
  a086=(a086*a109);
  a082=(a082+a086);
  a082=(a082/a000);
  if (res[1]!=0) res[1][76]=a082;
  a100=(a100*a010);
  a102=(a102*a127);
  a102=(a100+a102);
  a105=(a105*a109);
  a102=(a102+a105);
  a102=(a102/a000);
  if (res[1]!=0) res[1][77]=a102;
  a093=(a093*a010);
  a156=(a156+a093);
  a095=(a095*a127);
  a156=(a156+a095);
  a156=(a156+a097);
  a007=(a007*a048);
  a156=(a156+a007);
  a056=(a056*a099);
  a156=(a156+a056);
  a156=(a156+a058);
  a156=(-a156);
  if (res[1]!=0) res[1][78]=a156;
  a081=(a081*a010);
  a157=(a157+a081);
  a157=(a157+a083);
  a085=(a085*a109);
  a157=(a157+a085);
  a035=(a035*a048);
  a157=(a157+a035);
  a157=(a157+a042);
  a046=(a046*a198);
  a157=(a157+a046);
  a157=(-a157);
  if (res[1]!=0) res[1][79]=a157;
  a041=(a041+a100);
  a101=(a101*a127);
  a041=(a041+a101);
  a104=(a104*a109);
  a041=(a041+a104);
  a041=(a041+a060);
  a062=(a062*a099);
  a041=(a041+a062);
  a065=(a065*a198);
  a041=(a041+a065);
  a041=(-a041);
  if (res[1]!=0) res[1][80]=a041;
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
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27;
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
  a04=(a04*a10);
  a14=(a14+a04);
  a03=(a03*a14);
  a14=casadi_sq(a03);
  a12=(a12+a14);
  a12=(a02+a12);
  a12=(a02/a12);
  a04=(a14+a09);
  a10=2.;
  a04=(a04/a10);
  a04=(a12*a04);
  a04=(a01-a04);
  a05=(a00*a04);
  a15=arg[1]? arg[1][3] : 0;
  a13=(a07*a11);
  a08=(a13/a10);
  a08=(a03+a08);
  a08=(a12*a08);
  a16=(a15*a08);
  a05=(a05+a16);
  a16=arg[1]? arg[1][6] : 0;
  a17=(a07*a03);
  a18=(a17/a10);
  a18=(a18-a11);
  a18=(a12*a18);
  a19=(a16*a18);
  a05=(a05+a19);
  if (res[0]!=0) res[0][0]=a05;
  a05=arg[1]? arg[1][1] : 0;
  a19=(a05*a04);
  a20=arg[1]? arg[1][4] : 0;
  a21=(a20*a08);
  a19=(a19+a21);
  a21=arg[1]? arg[1][7] : 0;
  a22=(a21*a18);
  a19=(a19+a22);
  if (res[0]!=0) res[0][1]=a19;
  a19=arg[1]? arg[1][2] : 0;
  a04=(a19*a04);
  a22=arg[1]? arg[1][5] : 0;
  a08=(a22*a08);
  a04=(a04+a08);
  a08=arg[1]? arg[1][8] : 0;
  a18=(a08*a18);
  a04=(a04+a18);
  if (res[0]!=0) res[0][2]=a04;
  a04=(a11*a07);
  a18=(a04/a10);
  a18=(a18-a03);
  a18=(a12*a18);
  a23=(a00*a18);
  a24=(a14+a06);
  a24=(a24/a10);
  a24=(a12*a24);
  a24=(a01-a24);
  a25=(a15*a24);
  a23=(a23+a25);
  a25=(a11*a03);
  a26=(a25/a10);
  a26=(a07+a26);
  a26=(a12*a26);
  a27=(a16*a26);
  a23=(a23+a27);
  if (res[0]!=0) res[0][3]=a23;
  a23=(a05*a18);
  a27=(a20*a24);
  a23=(a23+a27);
  a27=(a21*a26);
  a23=(a23+a27);
  if (res[0]!=0) res[0][4]=a23;
  a18=(a19*a18);
  a24=(a22*a24);
  a18=(a18+a24);
  a26=(a08*a26);
  a18=(a18+a26);
  if (res[0]!=0) res[0][5]=a18;
  a18=(a03*a07);
  a26=(a18/a10);
  a26=(a11+a26);
  a26=(a12*a26);
  a00=(a00*a26);
  a24=(a03*a11);
  a23=(a24/a10);
  a23=(a23-a07);
  a23=(a12*a23);
  a15=(a15*a23);
  a00=(a00+a15);
  a15=(a09+a06);
  a15=(a15/a10);
  a12=(a12*a15);
  a12=(a01-a12);
  a16=(a16*a12);
  a00=(a00+a16);
  if (res[0]!=0) res[0][6]=a00;
  a05=(a05*a26);
  a20=(a20*a23);
  a05=(a05+a20);
  a21=(a21*a12);
  a05=(a05+a21);
  if (res[0]!=0) res[0][7]=a05;
  a19=(a19*a26);
  a22=(a22*a23);
  a19=(a19+a22);
  a08=(a08*a12);
  a19=(a19+a08);
  if (res[0]!=0) res[0][8]=a19;
  a18=(a18/a02);
  a11=(a11/a10);
  a18=(a18-a11);
  a19=arg[0]? arg[0][8] : 0;
  a18=(a18*a19);
  a03=(a03/a10);
  a04=(a04/a02);
  a04=(a03+a04);
  a08=arg[0]? arg[0][7] : 0;
  a04=(a04*a08);
  a18=(a18+a04);
  a06=(a06/a02);
  a06=(a01+a06);
  a04=arg[0]? arg[0][6] : 0;
  a06=(a06*a04);
  a18=(a18+a06);
  if (res[1]!=0) res[1][0]=a18;
  a07=(a07/a10);
  a24=(a24/a02);
  a24=(a07+a24);
  a24=(a24*a19);
  a09=(a09/a02);
  a09=(a01+a09);
  a09=(a09*a08);
  a24=(a24+a09);
  a13=(a13/a02);
  a13=(a13-a03);
  a13=(a13*a04);
  a24=(a24+a13);
  if (res[1]!=0) res[1][1]=a24;
  a14=(a14/a02);
  a01=(a01+a14);
  a01=(a01*a19);
  a25=(a25/a02);
  a25=(a25-a07);
  a25=(a25*a08);
  a01=(a01+a25);
  a17=(a17/a02);
  a11=(a11+a17);
  a11=(a11*a04);
  a01=(a01+a11);
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
  casadi_real a12;
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
  a03=arg[0]? arg[0][0] : 0;
  a06=(a02*a03);
  a08=arg[0]? arg[0][3] : 0;
  a09=(a05*a08);
  a06=(a06+a09);
  a06=(a01*a06);
  a03=(a07*a03);
  a08=(a02*a08);
  a03=(a03+a08);
  a03=(a01*a03);
  a06=(a06+a03);
  a06=(a00*a06);
  a03=(a04*a06);
  a08=4.;
  a03=(a03/a08);
  a09=arg[0]? arg[0][1] : 0;
  a10=(a02*a09);
  a11=arg[0]? arg[0][4] : 0;
  a05=(a05*a11);
  a10=(a10+a05);
  a10=(a01*a10);
  a07=(a07*a09);
  a02=(a02*a11);
  a07=(a07+a02);
  a01=(a01*a07);
  a10=(a10+a01);
  a00=(a00*a10);
  a10=2.;
  a01=(a00/a10);
  a03=(a03-a01);
  a07=arg[0]? arg[0][8] : 0;
  a03=(a03*a07);
  a02=(a04/a10);
  a11=(a00*a06);
  a11=(a11/a08);
  a11=(a02+a11);
  a09=arg[0]? arg[0][7] : 0;
  a11=(a11*a09);
  a03=(a03+a11);
  a11=1.;
  a05=casadi_sq(a06);
  a05=(a05/a08);
  a05=(a11+a05);
  a12=arg[0]? arg[0][6] : 0;
  a05=(a05*a12);
  a03=(a03+a05);
  if (res[0]!=0) res[0][0]=a03;
  a10=(a06/a10);
  a03=(a04*a00);
  a03=(a03/a08);
  a03=(a10+a03);
  a03=(a03*a07);
  a05=casadi_sq(a00);
  a05=(a05/a08);
  a05=(a11+a05);
  a05=(a05*a09);
  a03=(a03+a05);
  a05=(a06*a00);
  a05=(a05/a08);
  a05=(a05-a02);
  a05=(a05*a12);
  a03=(a03+a05);
  if (res[0]!=0) res[0][1]=a03;
  a03=casadi_sq(a04);
  a03=(a03/a08);
  a11=(a11+a03);
  a11=(a11*a07);
  a00=(a00*a04);
  a00=(a00/a08);
  a00=(a00-a10);
  a00=(a00*a09);
  a11=(a11+a00);
  a06=(a06*a04);
  a06=(a06/a08);
  a01=(a01+a06);
  a01=(a01*a12);
  a11=(a11+a01);
  if (res[0]!=0) res[0][2]=a11;
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
  casadi_real a72, a73, a74, a75, a76, a77, a78, a79, a80, a81, a82;
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
  a32=(a02/a24);
  a28=(a19*a25);
  a10=(a28/a14);
  a10=(a20+a10);
  a31=(a32*a10);
  a07=(a00*a31);
  a13=arg[1]? arg[1][3] : 0;
  a34=(a19*a20);
  a30=(a34/a14);
  a30=(a30-a25);
  a26=(a32*a30);
  a23=(a13*a26);
  a07=(a07+a23);
  a23=arg[1]? arg[1][6] : 0;
  a29=(a06+a03);
  a29=(a29/a14);
  a22=(a32*a29);
  a22=(a17-a22);
  a21=(a23*a22);
  a07=(a07+a21);
  a21=-1.7320508075688774e+00;
  a21=(a21*a01);
  a12=(a20*a21);
  a08=(a27*a12);
  a08=(a32*a08);
  a05=(a20*a25);
  a11=(a05/a14);
  a11=(a11-a19);
  a24=(a32/a24);
  a04=(2.*a25);
  a35=(a04*a21);
  a36=(a24*a35);
  a37=(a11*a36);
  a37=(a08-a37);
  a38=(a00*a37);
  a39=(a27*a35);
  a39=(a32*a39);
  a40=(a09+a03);
  a40=(a40/a14);
  a41=(a40*a36);
  a41=(a39-a41);
  a42=(a13*a41);
  a38=(a38-a42);
  a42=(a32*a21);
  a43=(a20*a19);
  a44=(a43/a14);
  a44=(a25+a44);
  a45=(a44*a36);
  a45=(a42-a45);
  a46=(a23*a45);
  a38=(a38+a46);
  a38=(a07*a38);
  a46=arg[1]? arg[1][1] : 0;
  a47=(a46*a31);
  a48=arg[1]? arg[1][4] : 0;
  a49=(a48*a26);
  a47=(a47+a49);
  a49=arg[1]? arg[1][7] : 0;
  a50=(a49*a22);
  a47=(a47+a50);
  a50=(a46*a37);
  a51=(a48*a41);
  a50=(a50-a51);
  a51=(a49*a45);
  a50=(a50+a51);
  a50=(a47*a50);
  a38=(a38+a50);
  a50=(a33*a31);
  a51=(a18*a26);
  a50=(a50+a51);
  a51=(a15*a22);
  a50=(a50+a51);
  a37=(a33*a37);
  a41=(a18*a41);
  a37=(a37-a41);
  a45=(a15*a45);
  a37=(a37+a45);
  a37=(a50*a37);
  a38=(a38+a37);
  if (res[1]!=0) res[1][0]=a38;
  a38=(a09+a06);
  a38=(a38/a14);
  a37=(a32*a38);
  a37=(a17-a37);
  a45=(a00*a37);
  a41=(a25*a20);
  a51=(a41/a14);
  a51=(a19+a51);
  a52=(a32*a51);
  a53=(a13*a52);
  a45=(a45+a53);
  a53=(a25*a19);
  a54=(a53/a14);
  a54=(a54-a20);
  a55=(a32*a54);
  a56=(a23*a55);
  a45=(a45+a56);
  a56=(a19*a21);
  a57=(a27*a56);
  a57=(a32*a57);
  a58=(a10*a36);
  a58=(a57-a58);
  a59=(a00*a58);
  a60=(a30*a36);
  a60=(a60+a42);
  a61=(a13*a60);
  a59=(a59-a61);
  a61=(a29*a36);
  a39=(a39-a61);
  a61=(a23*a39);
  a59=(a59-a61);
  a59=(a45*a59);
  a61=(a46*a37);
  a62=(a48*a52);
  a61=(a61+a62);
  a62=(a49*a55);
  a61=(a61+a62);
  a62=(a46*a58);
  a63=(a48*a60);
  a62=(a62-a63);
  a63=(a49*a39);
  a62=(a62-a63);
  a62=(a61*a62);
  a59=(a59+a62);
  a62=(a33*a37);
  a63=(a18*a52);
  a62=(a62+a63);
  a63=(a15*a55);
  a62=(a62+a63);
  a58=(a33*a58);
  a60=(a18*a60);
  a58=(a58-a60);
  a39=(a15*a39);
  a58=(a58-a39);
  a58=(a62*a58);
  a59=(a59+a58);
  if (res[1]!=0) res[1][1]=a59;
  a59=(a32*a11);
  a58=(a00*a59);
  a39=(a32*a40);
  a39=(a17-a39);
  a60=(a13*a39);
  a58=(a58+a60);
  a60=(a32*a44);
  a63=(a23*a60);
  a58=(a58+a63);
  a63=(a38*a36);
  a64=(a00*a63);
  a65=(a51*a36);
  a65=(a08-a65);
  a66=(a13*a65);
  a64=(a64+a66);
  a36=(a54*a36);
  a36=(a57-a36);
  a66=(a23*a36);
  a64=(a64+a66);
  a64=(a58*a64);
  a66=(a46*a59);
  a67=(a48*a39);
  a66=(a66+a67);
  a67=(a49*a60);
  a66=(a66+a67);
  a67=(a46*a63);
  a68=(a48*a65);
  a67=(a67+a68);
  a68=(a49*a36);
  a67=(a67+a68);
  a67=(a66*a67);
  a64=(a64+a67);
  a67=(a33*a59);
  a68=(a18*a39);
  a67=(a67+a68);
  a68=(a15*a60);
  a67=(a67+a68);
  a63=(a33*a63);
  a65=(a18*a65);
  a63=(a63+a65);
  a36=(a15*a36);
  a63=(a63+a36);
  a63=(a67*a63);
  a64=(a64+a63);
  if (res[1]!=0) res[1][2]=a64;
  a64=arg[0]? arg[0][8] : 0;
  a63=2.5000000000000000e-01;
  a56=(a63*a56);
  a36=(a64*a56);
  a65=arg[0]? arg[0][7] : 0;
  a12=(a63*a12);
  a68=(a65*a12);
  a69=(a36+a68);
  a70=arg[0]? arg[0][6] : 0;
  a35=(a63*a35);
  a35=(a70*a35);
  a69=(a69+a35);
  if (res[1]!=0) res[1][3]=a69;
  a69=-8.6602540378443871e-01;
  a69=(a69*a01);
  a35=(a64*a69);
  a71=(a70*a12);
  a71=(a35+a71);
  if (res[1]!=0) res[1][4]=a71;
  a71=(a70*a56);
  a72=(a65*a69);
  a71=(a71-a72);
  if (res[1]!=0) res[1][5]=a71;
  a71=(a25*a21);
  a73=(a27*a71);
  a73=(a32*a73);
  a74=(2.*a20);
  a75=(a74*a21);
  a76=(a24*a75);
  a77=(a11*a76);
  a77=(a73-a77);
  a78=(a00*a77);
  a79=(a40*a76);
  a80=(a13*a79);
  a78=(a78+a80);
  a80=(a44*a76);
  a80=(a57-a80);
  a81=(a23*a80);
  a78=(a78+a81);
  a78=(a07*a78);
  a81=(a46*a77);
  a82=(a48*a79);
  a81=(a81+a82);
  a82=(a49*a80);
  a81=(a81+a82);
  a81=(a47*a81);
  a78=(a78+a81);
  a77=(a33*a77);
  a79=(a18*a79);
  a77=(a77+a79);
  a80=(a15*a80);
  a77=(a77+a80);
  a77=(a50*a77);
  a78=(a78+a77);
  if (res[1]!=0) res[1][6]=a78;
  a78=(a10*a76);
  a78=(a42-a78);
  a77=(a00*a78);
  a80=(a30*a76);
  a57=(a57-a80);
  a80=(a13*a57);
  a77=(a77+a80);
  a80=(a27*a75);
  a80=(a32*a80);
  a79=(a29*a76);
  a79=(a80-a79);
  a81=(a23*a79);
  a77=(a77-a81);
  a77=(a45*a77);
  a81=(a46*a78);
  a82=(a48*a57);
  a81=(a81+a82);
  a82=(a49*a79);
  a81=(a81-a82);
  a81=(a61*a81);
  a77=(a77+a81);
  a78=(a33*a78);
  a57=(a18*a57);
  a78=(a78+a57);
  a79=(a15*a79);
  a78=(a78-a79);
  a78=(a62*a78);
  a77=(a77+a78);
  if (res[1]!=0) res[1][7]=a77;
  a77=(a51*a76);
  a77=(a73-a77);
  a78=(a13*a77);
  a79=(a38*a76);
  a80=(a80-a79);
  a79=(a00*a80);
  a78=(a78-a79);
  a76=(a54*a76);
  a76=(a76+a42);
  a79=(a23*a76);
  a78=(a78-a79);
  a78=(a58*a78);
  a79=(a48*a77);
  a57=(a46*a80);
  a79=(a79-a57);
  a57=(a49*a76);
  a79=(a79-a57);
  a79=(a66*a79);
  a78=(a78+a79);
  a77=(a18*a77);
  a80=(a33*a80);
  a77=(a77-a80);
  a76=(a15*a76);
  a77=(a77-a76);
  a77=(a67*a77);
  a78=(a78+a77);
  if (res[1]!=0) res[1][8]=a78;
  a71=(a63*a71);
  a78=(a65*a71);
  a78=(a78-a35);
  if (res[1]!=0) res[1][9]=a78;
  a75=(a63*a75);
  a75=(a65*a75);
  a36=(a36+a75);
  a75=(a70*a71);
  a36=(a36+a75);
  if (res[1]!=0) res[1][10]=a36;
  a56=(a65*a56);
  a69=(a70*a69);
  a56=(a56+a69);
  if (res[1]!=0) res[1][11]=a56;
  a56=(2.*a19);
  a21=(a56*a21);
  a36=(a24*a21);
  a78=(a44*a36);
  a78=(a08-a78);
  a35=(a23*a78);
  a77=(a11*a36);
  a77=(a77+a42);
  a76=(a00*a77);
  a80=(a27*a21);
  a80=(a32*a80);
  a79=(a40*a36);
  a79=(a80-a79);
  a57=(a13*a79);
  a76=(a76+a57);
  a35=(a35-a76);
  a35=(a07*a35);
  a76=(a49*a78);
  a57=(a46*a77);
  a81=(a48*a79);
  a57=(a57+a81);
  a76=(a76-a57);
  a76=(a47*a76);
  a35=(a35+a76);
  a78=(a15*a78);
  a77=(a33*a77);
  a79=(a18*a79);
  a77=(a77+a79);
  a78=(a78-a77);
  a78=(a50*a78);
  a35=(a35+a78);
  if (res[1]!=0) res[1][12]=a35;
  a35=(a10*a36);
  a35=(a73-a35);
  a78=(a00*a35);
  a77=(a30*a36);
  a08=(a08-a77);
  a77=(a13*a08);
  a78=(a78+a77);
  a77=(a29*a36);
  a79=(a23*a77);
  a78=(a78+a79);
  a78=(a45*a78);
  a79=(a46*a35);
  a76=(a48*a08);
  a79=(a79+a76);
  a76=(a49*a77);
  a79=(a79+a76);
  a79=(a61*a79);
  a78=(a78+a79);
  a35=(a33*a35);
  a08=(a18*a08);
  a35=(a35+a08);
  a77=(a15*a77);
  a35=(a35+a77);
  a35=(a62*a35);
  a78=(a78+a35);
  if (res[1]!=0) res[1][13]=a78;
  a78=(a51*a36);
  a42=(a42-a78);
  a78=(a13*a42);
  a35=(a38*a36);
  a80=(a80-a35);
  a35=(a00*a80);
  a78=(a78-a35);
  a36=(a54*a36);
  a73=(a73-a36);
  a36=(a23*a73);
  a78=(a78+a36);
  a78=(a58*a78);
  a36=(a48*a42);
  a35=(a46*a80);
  a36=(a36-a35);
  a35=(a49*a73);
  a36=(a36+a35);
  a36=(a66*a36);
  a78=(a78+a36);
  a42=(a18*a42);
  a80=(a33*a80);
  a42=(a42-a80);
  a73=(a15*a73);
  a42=(a42+a73);
  a42=(a67*a42);
  a78=(a78+a42);
  if (res[1]!=0) res[1][14]=a78;
  a71=(a64*a71);
  a71=(a71+a72);
  if (res[1]!=0) res[1][15]=a71;
  a12=(a64*a12);
  a12=(a12-a69);
  if (res[1]!=0) res[1][16]=a12;
  a21=(a63*a21);
  a21=(a64*a21);
  a21=(a21+a68);
  a21=(a21+a75);
  if (res[1]!=0) res[1][17]=a21;
  a21=1.7320508075688774e+00;
  a21=(a21*a01);
  a75=(a20*a21);
  a68=(a27*a75);
  a68=(a32*a68);
  a04=(a04*a21);
  a12=(a24*a04);
  a69=(a11*a12);
  a69=(a68-a69);
  a71=(a00*a69);
  a72=(a27*a04);
  a72=(a32*a72);
  a78=(a40*a12);
  a78=(a72-a78);
  a42=(a13*a78);
  a71=(a71-a42);
  a42=(a32*a21);
  a73=(a44*a12);
  a73=(a42-a73);
  a80=(a23*a73);
  a71=(a71+a80);
  a71=(a07*a71);
  a80=(a46*a69);
  a36=(a48*a78);
  a80=(a80-a36);
  a36=(a49*a73);
  a80=(a80+a36);
  a80=(a47*a80);
  a71=(a71+a80);
  a69=(a33*a69);
  a78=(a18*a78);
  a69=(a69-a78);
  a73=(a15*a73);
  a69=(a69+a73);
  a69=(a50*a69);
  a71=(a71+a69);
  if (res[1]!=0) res[1][18]=a71;
  a71=(a19*a21);
  a69=(a27*a71);
  a69=(a32*a69);
  a73=(a10*a12);
  a73=(a69-a73);
  a78=(a00*a73);
  a80=(a30*a12);
  a80=(a80+a42);
  a36=(a13*a80);
  a78=(a78-a36);
  a36=(a29*a12);
  a72=(a72-a36);
  a36=(a23*a72);
  a78=(a78-a36);
  a78=(a45*a78);
  a36=(a46*a73);
  a35=(a48*a80);
  a36=(a36-a35);
  a35=(a49*a72);
  a36=(a36-a35);
  a36=(a61*a36);
  a78=(a78+a36);
  a73=(a33*a73);
  a80=(a18*a80);
  a73=(a73-a80);
  a72=(a15*a72);
  a73=(a73-a72);
  a73=(a62*a73);
  a78=(a78+a73);
  if (res[1]!=0) res[1][19]=a78;
  a78=(a38*a12);
  a73=(a00*a78);
  a72=(a51*a12);
  a72=(a68-a72);
  a80=(a13*a72);
  a73=(a73+a80);
  a12=(a54*a12);
  a12=(a69-a12);
  a80=(a23*a12);
  a73=(a73+a80);
  a73=(a58*a73);
  a80=(a46*a78);
  a36=(a48*a72);
  a80=(a80+a36);
  a36=(a49*a12);
  a80=(a80+a36);
  a80=(a66*a80);
  a73=(a73+a80);
  a78=(a33*a78);
  a72=(a18*a72);
  a78=(a78+a72);
  a12=(a15*a12);
  a78=(a78+a12);
  a78=(a67*a78);
  a73=(a73+a78);
  if (res[1]!=0) res[1][20]=a73;
  a71=(a63*a71);
  a73=(a64*a71);
  a75=(a63*a75);
  a78=(a65*a75);
  a12=(a73+a78);
  a04=(a63*a04);
  a04=(a70*a04);
  a12=(a12+a04);
  if (res[1]!=0) res[1][21]=a12;
  a12=8.6602540378443871e-01;
  a12=(a12*a01);
  a01=(a64*a12);
  a04=(a70*a75);
  a04=(a01+a04);
  if (res[1]!=0) res[1][22]=a04;
  a04=(a70*a71);
  a72=(a65*a12);
  a04=(a04-a72);
  if (res[1]!=0) res[1][23]=a04;
  a04=(a25*a21);
  a80=(a27*a04);
  a80=(a32*a80);
  a74=(a74*a21);
  a36=(a24*a74);
  a35=(a11*a36);
  a35=(a80-a35);
  a77=(a00*a35);
  a08=(a40*a36);
  a79=(a13*a08);
  a77=(a77+a79);
  a79=(a44*a36);
  a79=(a69-a79);
  a76=(a23*a79);
  a77=(a77+a76);
  a77=(a07*a77);
  a76=(a46*a35);
  a57=(a48*a08);
  a76=(a76+a57);
  a57=(a49*a79);
  a76=(a76+a57);
  a76=(a47*a76);
  a77=(a77+a76);
  a35=(a33*a35);
  a08=(a18*a08);
  a35=(a35+a08);
  a79=(a15*a79);
  a35=(a35+a79);
  a35=(a50*a35);
  a77=(a77+a35);
  if (res[1]!=0) res[1][24]=a77;
  a77=(a10*a36);
  a77=(a42-a77);
  a35=(a00*a77);
  a79=(a30*a36);
  a69=(a69-a79);
  a79=(a13*a69);
  a35=(a35+a79);
  a79=(a27*a74);
  a79=(a32*a79);
  a08=(a29*a36);
  a08=(a79-a08);
  a76=(a23*a08);
  a35=(a35-a76);
  a35=(a45*a35);
  a76=(a46*a77);
  a57=(a48*a69);
  a76=(a76+a57);
  a57=(a49*a08);
  a76=(a76-a57);
  a76=(a61*a76);
  a35=(a35+a76);
  a77=(a33*a77);
  a69=(a18*a69);
  a77=(a77+a69);
  a08=(a15*a08);
  a77=(a77-a08);
  a77=(a62*a77);
  a35=(a35+a77);
  if (res[1]!=0) res[1][25]=a35;
  a35=(a51*a36);
  a35=(a80-a35);
  a77=(a13*a35);
  a08=(a38*a36);
  a79=(a79-a08);
  a08=(a00*a79);
  a77=(a77-a08);
  a36=(a54*a36);
  a36=(a36+a42);
  a08=(a23*a36);
  a77=(a77-a08);
  a77=(a58*a77);
  a08=(a48*a35);
  a69=(a46*a79);
  a08=(a08-a69);
  a69=(a49*a36);
  a08=(a08-a69);
  a08=(a66*a08);
  a77=(a77+a08);
  a35=(a18*a35);
  a79=(a33*a79);
  a35=(a35-a79);
  a36=(a15*a36);
  a35=(a35-a36);
  a35=(a67*a35);
  a77=(a77+a35);
  if (res[1]!=0) res[1][26]=a77;
  a04=(a63*a04);
  a77=(a65*a04);
  a77=(a77-a01);
  if (res[1]!=0) res[1][27]=a77;
  a74=(a63*a74);
  a74=(a65*a74);
  a73=(a73+a74);
  a74=(a70*a04);
  a73=(a73+a74);
  if (res[1]!=0) res[1][28]=a73;
  a65=(a65*a71);
  a70=(a70*a12);
  a65=(a65+a70);
  if (res[1]!=0) res[1][29]=a65;
  a56=(a56*a21);
  a24=(a24*a56);
  a44=(a44*a24);
  a44=(a68-a44);
  a21=(a23*a44);
  a11=(a11*a24);
  a11=(a11+a42);
  a65=(a00*a11);
  a27=(a27*a56);
  a32=(a32*a27);
  a40=(a40*a24);
  a40=(a32-a40);
  a27=(a13*a40);
  a65=(a65+a27);
  a21=(a21-a65);
  a21=(a07*a21);
  a65=(a49*a44);
  a27=(a46*a11);
  a12=(a48*a40);
  a27=(a27+a12);
  a65=(a65-a27);
  a65=(a47*a65);
  a21=(a21+a65);
  a44=(a15*a44);
  a11=(a33*a11);
  a40=(a18*a40);
  a11=(a11+a40);
  a44=(a44-a11);
  a44=(a50*a44);
  a21=(a21+a44);
  if (res[1]!=0) res[1][30]=a21;
  a10=(a10*a24);
  a10=(a80-a10);
  a21=(a00*a10);
  a30=(a30*a24);
  a68=(a68-a30);
  a30=(a13*a68);
  a21=(a21+a30);
  a29=(a29*a24);
  a30=(a23*a29);
  a21=(a21+a30);
  a21=(a45*a21);
  a30=(a46*a10);
  a44=(a48*a68);
  a30=(a30+a44);
  a44=(a49*a29);
  a30=(a30+a44);
  a30=(a61*a30);
  a21=(a21+a30);
  a10=(a33*a10);
  a68=(a18*a68);
  a10=(a10+a68);
  a29=(a15*a29);
  a10=(a10+a29);
  a10=(a62*a10);
  a21=(a21+a10);
  if (res[1]!=0) res[1][31]=a21;
  a51=(a51*a24);
  a42=(a42-a51);
  a51=(a13*a42);
  a38=(a38*a24);
  a32=(a32-a38);
  a38=(a00*a32);
  a51=(a51-a38);
  a54=(a54*a24);
  a80=(a80-a54);
  a54=(a23*a80);
  a51=(a51+a54);
  a51=(a58*a51);
  a54=(a48*a42);
  a24=(a46*a32);
  a54=(a54-a24);
  a24=(a49*a80);
  a54=(a54+a24);
  a54=(a66*a54);
  a51=(a51+a54);
  a42=(a18*a42);
  a32=(a33*a32);
  a42=(a42-a32);
  a80=(a15*a80);
  a42=(a42+a80);
  a42=(a67*a42);
  a51=(a51+a42);
  if (res[1]!=0) res[1][32]=a51;
  a04=(a64*a04);
  a04=(a04+a72);
  if (res[1]!=0) res[1][33]=a04;
  a75=(a64*a75);
  a75=(a75-a70);
  if (res[1]!=0) res[1][34]=a75;
  a63=(a63*a56);
  a64=(a64*a63);
  a64=(a64+a78);
  a64=(a64+a74);
  if (res[1]!=0) res[1][35]=a64;
  if (res[1]!=0) res[1][36]=a16;
  if (res[1]!=0) res[1][37]=a16;
  if (res[1]!=0) res[1][38]=a16;
  a03=(a03/a02);
  a03=(a17+a03);
  if (res[1]!=0) res[1][39]=a03;
  a41=(a41/a02);
  a19=(a19/a14);
  a41=(a41-a19);
  if (res[1]!=0) res[1][40]=a41;
  a20=(a20/a14);
  a53=(a53/a02);
  a53=(a20+a53);
  if (res[1]!=0) res[1][41]=a53;
  if (res[1]!=0) res[1][42]=a16;
  if (res[1]!=0) res[1][43]=a16;
  if (res[1]!=0) res[1][44]=a16;
  a05=(a05/a02);
  a19=(a19+a05);
  if (res[1]!=0) res[1][45]=a19;
  a06=(a06/a02);
  a06=(a17+a06);
  if (res[1]!=0) res[1][46]=a06;
  a43=(a43/a02);
  a25=(a25/a14);
  a43=(a43-a25);
  if (res[1]!=0) res[1][47]=a43;
  if (res[1]!=0) res[1][48]=a16;
  if (res[1]!=0) res[1][49]=a16;
  if (res[1]!=0) res[1][50]=a16;
  a28=(a28/a02);
  a28=(a28-a20);
  if (res[1]!=0) res[1][51]=a28;
  a34=(a34/a02);
  a25=(a25+a34);
  if (res[1]!=0) res[1][52]=a25;
  a09=(a09/a02);
  a17=(a17+a09);
  if (res[1]!=0) res[1][53]=a17;
  a17=(a39*a23);
  a09=(a60*a13);
  a17=(a17-a09);
  a17=(a07*a17);
  a09=(a39*a49);
  a02=(a60*a48);
  a09=(a09-a02);
  a09=(a47*a09);
  a17=(a17+a09);
  a09=(a39*a15);
  a02=(a60*a18);
  a09=(a09-a02);
  a09=(a50*a09);
  a17=(a17+a09);
  if (res[2]!=0) res[2][0]=a17;
  a17=(a26*a23);
  a09=(a22*a13);
  a17=(a17-a09);
  a17=(a45*a17);
  a09=(a26*a49);
  a02=(a22*a48);
  a09=(a09-a02);
  a09=(a61*a09);
  a17=(a17+a09);
  a09=(a26*a15);
  a02=(a22*a18);
  a09=(a09-a02);
  a09=(a62*a09);
  a17=(a17+a09);
  if (res[2]!=0) res[2][1]=a17;
  a17=(a52*a23);
  a09=(a55*a13);
  a17=(a17-a09);
  a17=(a58*a17);
  a09=(a52*a49);
  a02=(a55*a48);
  a09=(a09-a02);
  a09=(a66*a09);
  a17=(a17+a09);
  a09=(a52*a15);
  a02=(a55*a18);
  a09=(a09-a02);
  a09=(a67*a09);
  a17=(a17+a09);
  if (res[2]!=0) res[2][2]=a17;
  if (res[2]!=0) res[2][3]=a16;
  if (res[2]!=0) res[2][4]=a16;
  if (res[2]!=0) res[2][5]=a16;
  a17=(a60*a00);
  a09=(a59*a23);
  a17=(a17-a09);
  a17=(a07*a17);
  a09=(a60*a46);
  a02=(a59*a49);
  a09=(a09-a02);
  a09=(a47*a09);
  a17=(a17+a09);
  a60=(a60*a33);
  a09=(a59*a15);
  a60=(a60-a09);
  a60=(a50*a60);
  a17=(a17+a60);
  if (res[2]!=0) res[2][6]=a17;
  a17=(a22*a00);
  a60=(a31*a23);
  a17=(a17-a60);
  a17=(a45*a17);
  a60=(a22*a46);
  a09=(a31*a49);
  a60=(a60-a09);
  a60=(a61*a60);
  a17=(a17+a60);
  a22=(a22*a33);
  a60=(a31*a15);
  a22=(a22-a60);
  a22=(a62*a22);
  a17=(a17+a22);
  if (res[2]!=0) res[2][7]=a17;
  a17=(a55*a00);
  a23=(a37*a23);
  a17=(a17-a23);
  a17=(a58*a17);
  a23=(a55*a46);
  a49=(a37*a49);
  a23=(a23-a49);
  a23=(a66*a23);
  a17=(a17+a23);
  a55=(a55*a33);
  a15=(a37*a15);
  a55=(a55-a15);
  a55=(a67*a55);
  a17=(a17+a55);
  if (res[2]!=0) res[2][8]=a17;
  if (res[2]!=0) res[2][9]=a16;
  if (res[2]!=0) res[2][10]=a16;
  if (res[2]!=0) res[2][11]=a16;
  a17=(a59*a13);
  a55=(a39*a00);
  a17=(a17-a55);
  a07=(a07*a17);
  a17=(a59*a48);
  a55=(a39*a46);
  a17=(a17-a55);
  a47=(a47*a17);
  a07=(a07+a47);
  a59=(a59*a18);
  a39=(a39*a33);
  a59=(a59-a39);
  a50=(a50*a59);
  a07=(a07+a50);
  if (res[2]!=0) res[2][12]=a07;
  a07=(a31*a13);
  a50=(a26*a00);
  a07=(a07-a50);
  a45=(a45*a07);
  a07=(a31*a48);
  a50=(a26*a46);
  a07=(a07-a50);
  a61=(a61*a07);
  a45=(a45+a61);
  a31=(a31*a18);
  a26=(a26*a33);
  a31=(a31-a26);
  a62=(a62*a31);
  a45=(a45+a62);
  if (res[2]!=0) res[2][13]=a45;
  a13=(a37*a13);
  a00=(a52*a00);
  a13=(a13-a00);
  a58=(a58*a13);
  a48=(a37*a48);
  a46=(a52*a46);
  a48=(a48-a46);
  a66=(a66*a48);
  a58=(a58+a66);
  a37=(a37*a18);
  a52=(a52*a33);
  a37=(a37-a52);
  a67=(a67*a37);
  a58=(a58+a67);
  if (res[2]!=0) res[2][14]=a58;
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

#define HPGEN_ABI 5
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
#define HPGEN_RESIDUAL_SZ_W 113
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
#define HPGEN_RESIDUAL_JACOBIAN_SZ_W 228
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
#define HPGEN_UPDATE_SZ_W 28
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
#define HPGEN_STEP_PARTIALS_SZ_W 83
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
