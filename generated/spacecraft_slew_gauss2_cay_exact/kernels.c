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
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a014, a015, a016, a017, a018, a019, a020, a021, a022, a023;
  casadi_real a024, a025, a026, a027, a028, a029, a030, a031, a032, a033, a034, a035;
  casadi_real a036, a037, a038, a039, a040, a041, a042, a043, a044, a045, a046, a047;
  casadi_real a048, a049, a050, a051, a052, a053, a054, a055, a056, a057, a058, a059;
  casadi_real a060, a061, a062, a063, a064, a065, a066, a067, a068, a069, a070, a071;
  casadi_real a072, a073, a074, a075, a076, a077, a078, a079, a080, a081, a082, a083;
  casadi_real a084, a085, a086, a087, a088, a089, a090, a091, a092, a093, a094, a095;
  casadi_real a096, a097, a098, a099, a100, a101, a102, a103, a104, a105, a106, a107;
  casadi_real a108, a109, a110, a111, a112, a113, a114, a115, a116, a117;
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
  a031=5.0000000000000000e-01;
  a032=(a031*a000);
  a022=(a022*a032);
  a033=(a002*a009);
  a034=(a033/a006);
  a035=(a018+a034);
  a036=arg[0]? arg[0][8] : 0;
  a037=(a000*a036);
  a037=(a031*a037);
  a038=(a035*a037);
  a039=1.;
  a040=(a015/a006);
  a040=(a039+a040);
  a041=arg[0]? arg[0][7] : 0;
  a042=(a000*a041);
  a042=(a031*a042);
  a043=(a040*a042);
  a038=(a038+a043);
  a043=(a004*a009);
  a044=(a043/a006);
  a045=(a044-a025);
  a046=arg[0]? arg[0][6] : 0;
  a047=(a000*a046);
  a047=(a031*a047);
  a048=(a045*a047);
  a038=(a038+a048);
  a022=(a022-a038);
  a022=(a022/a032);
  a038=(a019*a022);
  a048=(a016*a011);
  a049=(a016*a027);
  a050=(a026*a021);
  a049=(a049+a050);
  a050=(a048*a029);
  a049=(a049-a050);
  a050=(2.*a049);
  a051=2.5000000000000000e-01;
  a052=(a051*a000);
  a050=(a050*a052);
  a053=(a012*a037);
  a054=(a009*a004);
  a055=(a054/a006);
  a056=(a025+a055);
  a057=(a056*a042);
  a053=(a053+a057);
  a057=(a014/a006);
  a057=(a039+a057);
  a058=(a057*a047);
  a053=(a053+a058);
  a050=(a050-a053);
  a050=(a050/a032);
  a053=(a048*a050);
  a038=(a038-a053);
  a053=(a048*a027);
  a058=(a019*a021);
  a053=(a053-a058);
  a058=(a016*a029);
  a053=(a053+a058);
  a058=(2.*a053);
  a059=7.5000000000000000e-01;
  a059=(a059*a000);
  a058=(a058*a059);
  a060=(a017/a006);
  a060=(a039+a060);
  a061=(a060*a037);
  a062=(a009*a002);
  a063=(a062/a006);
  a064=(a063-a018);
  a065=(a064*a042);
  a061=(a061+a065);
  a065=(a004*a002);
  a066=(a065/a006);
  a067=(a011+a066);
  a068=(a067*a047);
  a061=(a061+a068);
  a058=(a058-a061);
  a058=(a058/a032);
  a061=(a016*a058);
  a038=(a038+a061);
  a061=(a013*a038);
  a068=-3.2320508075688776e+00;
  a069=(a000*a028);
  a070=casadi_sq(a069);
  a071=(a000*a023);
  a072=casadi_sq(a071);
  a073=(a070+a072);
  a074=(a000*a030);
  a075=casadi_sq(a074);
  a073=(a073+a075);
  a073=(a006+a073);
  a073=(a006/a073);
  a076=(a069/a010);
  a077=(a073*a076);
  a078=-6.4641016151377553e+00;
  a008=(a078*a008);
  a023=(a020*a023);
  a008=(a008+a023);
  a023=(a073*a008);
  a079=(a074/a010);
  a080=(a073*a079);
  a003=(a078*a003);
  a028=(a020*a028);
  a003=(a003+a028);
  a028=(a080*a003);
  a023=(a023-a028);
  a078=(a078*a001);
  a020=(a020*a030);
  a078=(a078+a020);
  a020=(a077*a078);
  a023=(a023+a020);
  a020=(2.*a023);
  a020=(a020*a032);
  a030=(a074*a071);
  a001=(a030/a006);
  a028=(a076+a001);
  a081=(a028*a037);
  a020=(a020-a081);
  a081=(a072/a006);
  a081=(a039+a081);
  a082=(a081*a042);
  a020=(a020-a082);
  a082=(a069*a071);
  a083=(a082/a006);
  a084=(a083-a079);
  a085=(a084*a047);
  a020=(a020-a085);
  a020=(a020/a032);
  a085=(a077*a020);
  a086=(a071/a010);
  a087=(a073*a086);
  a088=(a073*a003);
  a089=(a080*a008);
  a088=(a088+a089);
  a089=(a087*a078);
  a088=(a088-a089);
  a089=(2.*a088);
  a089=(a089*a052);
  a052=(a074*a069);
  a090=(a052/a006);
  a091=(a090-a086);
  a092=(a091*a037);
  a089=(a089-a092);
  a092=(a071*a069);
  a093=(a092/a006);
  a094=(a079+a093);
  a095=(a094*a042);
  a089=(a089-a095);
  a095=(a070/a006);
  a095=(a039+a095);
  a096=(a095*a047);
  a089=(a089-a096);
  a089=(a089/a032);
  a096=(a087*a089);
  a085=(a085-a096);
  a096=(a087*a003);
  a097=(a077*a008);
  a096=(a096-a097);
  a097=(a073*a078);
  a096=(a096+a097);
  a097=(2.*a096);
  a097=(a097*a059);
  a059=(a075/a006);
  a059=(a039+a059);
  a098=(a059*a037);
  a097=(a097-a098);
  a098=(a071*a074);
  a099=(a098/a006);
  a100=(a099-a076);
  a101=(a100*a042);
  a097=(a097-a101);
  a101=(a069*a074);
  a102=(a101/a006);
  a103=(a086+a102);
  a104=(a103*a047);
  a097=(a097-a104);
  a097=(a097/a032);
  a104=(a073*a097);
  a085=(a085+a104);
  a104=(a068*a085);
  a061=(a061+a104);
  a104=(2.*a002);
  a105=5.3867513459481287e-01;
  a106=2.3205080756887719e-01;
  a038=(a106*a038);
  a085=(a013*a085);
  a038=(a038+a085);
  a085=(a000*a038);
  a107=(a105*a085);
  a107=(a037+a107);
  a108=(a000*a061);
  a109=(a051*a108);
  a107=(a107+a109);
  a109=(a053*a107);
  a109=(a051*a109);
  a104=(a104*a109);
  a061=(a061-a104);
  a104=(a024*a107);
  a109=(a051*a104);
  a110=(a009*a109);
  a061=(a061-a110);
  a107=(a049*a107);
  a110=(a051*a107);
  a111=(a004*a110);
  a061=(a061-a111);
  a111=(a026*a050);
  a112=(a016*a022);
  a111=(a111+a112);
  a019=(a019*a058);
  a111=(a111-a019);
  a019=(a106*a111);
  a112=(a080*a089);
  a113=(a073*a020);
  a112=(a112+a113);
  a077=(a077*a097);
  a112=(a112-a077);
  a077=(a013*a112);
  a019=(a019+a077);
  a077=(a000*a019);
  a113=(a105*a077);
  a113=(a042+a113);
  a111=(a013*a111);
  a112=(a068*a112);
  a111=(a111+a112);
  a112=(a000*a111);
  a114=(a051*a112);
  a113=(a113+a114);
  a114=(a053*a113);
  a115=(a051*a114);
  a116=(a009*a115);
  a061=(a061-a116);
  a116=(a049*a113);
  a117=(a031*a116);
  a061=(a061-a117);
  a050=(a016*a050);
  a026=(a026*a022);
  a050=(a050-a026);
  a048=(a048*a058);
  a050=(a050+a048);
  a106=(a106*a050);
  a089=(a073*a089);
  a080=(a080*a020);
  a089=(a089-a080);
  a087=(a087*a097);
  a089=(a089+a087);
  a087=(a013*a089);
  a106=(a106+a087);
  a087=(a000*a106);
  a105=(a105*a087);
  a105=(a047+a105);
  a013=(a013*a050);
  a068=(a068*a089);
  a013=(a013+a068);
  a068=(a000*a013);
  a089=(a051*a068);
  a105=(a105+a089);
  a089=(a053*a105);
  a050=(a051*a089);
  a097=(a004*a050);
  a061=(a061-a097);
  a097=(a024*a105);
  a080=(a031*a097);
  a061=(a061+a080);
  a012=(a012*a061);
  a107=(a031*a107);
  a109=(a002*a109);
  a107=(a107-a109);
  a107=(a107+a111);
  a115=(a002*a115);
  a107=(a107-a115);
  a115=(2.*a009);
  a113=(a024*a113);
  a113=(a051*a113);
  a115=(a115*a113);
  a107=(a107-a115);
  a116=(a051*a116);
  a115=(a004*a116);
  a107=(a107-a115);
  a089=(a031*a089);
  a107=(a107-a089);
  a097=(a051*a097);
  a089=(a004*a097);
  a107=(a107-a089);
  a056=(a056*a107);
  a012=(a012+a056);
  a114=(a031*a114);
  a104=(a031*a104);
  a110=(a002*a110);
  a104=(a104+a110);
  a114=(a114-a104);
  a116=(a009*a116);
  a114=(a114-a116);
  a114=(a114+a013);
  a050=(a002*a050);
  a114=(a114-a050);
  a097=(a009*a097);
  a114=(a114-a097);
  a097=(2.*a004);
  a105=(a049*a105);
  a105=(a051*a105);
  a097=(a097*a105);
  a114=(a114-a097);
  a057=(a057*a114);
  a012=(a012+a057);
  a097=-5.0000000000000000e-01;
  a105=arg[3]? arg[3][2] : 0;
  a097=(a097*a105);
  a105=arg[1]? arg[1][2] : 0;
  a054=(a054/a010);
  a054=(a054-a002);
  a054=(a016*a054);
  a050=(a105*a054);
  a013=arg[1]? arg[1][5] : 0;
  a116=(a017+a014);
  a116=(a116/a010);
  a116=(a016*a116);
  a116=(a039-a116);
  a104=(a013*a116);
  a050=(a050+a104);
  a104=arg[1]? arg[1][8] : 0;
  a062=(a062/a010);
  a062=(a004+a062);
  a062=(a016*a062);
  a110=(a104*a062);
  a050=(a050+a110);
  a110=8.4147098480789650e-01;
  a056=arg[1]? arg[1][0] : 0;
  a005=(a005/a010);
  a005=(a009+a005);
  a005=(a016*a005);
  a089=(a056*a005);
  a115=arg[1]? arg[1][3] : 0;
  a033=(a033/a010);
  a033=(a033-a004);
  a033=(a016*a033);
  a004=(a115*a033);
  a089=(a089+a004);
  a004=arg[1]? arg[1][6] : 0;
  a014=(a015+a014);
  a014=(a014/a010);
  a014=(a016*a014);
  a014=(a039-a014);
  a113=(a004*a014);
  a089=(a089+a113);
  a113=(a110*a089);
  a050=(a050+a113);
  a113=-5.4030230586813977e-01;
  a111=arg[1]? arg[1][1] : 0;
  a005=(a111*a005);
  a109=arg[1]? arg[1][4] : 0;
  a033=(a109*a033);
  a005=(a005+a033);
  a033=arg[1]? arg[1][7] : 0;
  a014=(a033*a014);
  a005=(a005+a014);
  a014=(a113*a005);
  a050=(a050+a014);
  a050=(a097*a050);
  a014=arg[3]? arg[3][3] : 0;
  a049=(a014*a049);
  a050=(a050-a049);
  a050=(a050*a032);
  a012=(a012+a050);
  a012=(a012/a000);
  if (res[0]!=0) res[0][0]=a012;
  a035=(a035*a061);
  a040=(a040*a107);
  a035=(a035+a040);
  a045=(a045*a114);
  a035=(a035+a045);
  a045=5.4030230586813977e-01;
  a089=(a045*a089);
  a017=(a017+a015);
  a017=(a017/a010);
  a017=(a016*a017);
  a017=(a039-a017);
  a015=(a105*a017);
  a043=(a043/a010);
  a002=(a002+a043);
  a002=(a016*a002);
  a043=(a013*a002);
  a015=(a015+a043);
  a065=(a065/a010);
  a065=(a065-a009);
  a016=(a016*a065);
  a065=(a104*a016);
  a015=(a015+a065);
  a089=(a089-a015);
  a005=(a110*a005);
  a089=(a089+a005);
  a089=(a097*a089);
  a024=(a014*a024);
  a089=(a089-a024);
  a089=(a089*a032);
  a035=(a035+a089);
  a035=(a035/a000);
  if (res[0]!=0) res[0][1]=a035;
  a060=(a060*a061);
  a064=(a064*a107);
  a064=(a060+a064);
  a067=(a067*a114);
  a064=(a064+a067);
  a067=(a111*a017);
  a035=(a109*a002);
  a067=(a067+a035);
  a035=(a033*a016);
  a067=(a067+a035);
  a067=(a045*a067);
  a035=(a056*a054);
  a089=(a115*a116);
  a035=(a035+a089);
  a089=(a004*a062);
  a035=(a035+a089);
  a035=(a113*a035);
  a067=(a067+a035);
  a035=-8.4147098480789650e-01;
  a017=(a056*a017);
  a002=(a115*a002);
  a017=(a017+a002);
  a016=(a004*a016);
  a017=(a017+a016);
  a017=(a035*a017);
  a067=(a067+a017);
  a054=(a111*a054);
  a116=(a109*a116);
  a054=(a054+a116);
  a062=(a033*a062);
  a054=(a054+a062);
  a054=(a035*a054);
  a067=(a067+a054);
  a067=(a097*a067);
  a053=(a014*a053);
  a067=(a067-a053);
  a067=(a067*a032);
  a064=(a064+a067);
  a064=(a064/a000);
  if (res[0]!=0) res[0][2]=a064;
  a092=(a092/a010);
  a092=(a092-a074);
  a092=(a073*a092);
  a064=(a105*a092);
  a067=(a075+a070);
  a067=(a067/a010);
  a067=(a073*a067);
  a067=(a039-a067);
  a053=(a013*a067);
  a064=(a064+a053);
  a098=(a098/a010);
  a098=(a069+a098);
  a098=(a073*a098);
  a053=(a104*a098);
  a064=(a064+a053);
  a052=(a052/a010);
  a052=(a071+a052);
  a052=(a073*a052);
  a053=(a056*a052);
  a030=(a030/a010);
  a030=(a030-a069);
  a030=(a073*a030);
  a054=(a115*a030);
  a053=(a053+a054);
  a070=(a072+a070);
  a070=(a070/a010);
  a070=(a073*a070);
  a070=(a039-a070);
  a054=(a004*a070);
  a053=(a053+a054);
  a054=(a110*a053);
  a064=(a064+a054);
  a052=(a111*a052);
  a030=(a109*a030);
  a052=(a052+a030);
  a070=(a033*a070);
  a052=(a052+a070);
  a070=(a113*a052);
  a064=(a064+a070);
  a064=(a097*a064);
  a070=(a014*a088);
  a064=(a064-a070);
  a064=(a064*a032);
  a070=(2.*a074);
  a085=(a051*a085);
  a037=(a037+a085);
  a085=-3.8675134594812879e-02;
  a108=(a085*a108);
  a037=(a037+a108);
  a108=(a096*a037);
  a108=(a051*a108);
  a070=(a070*a108);
  a038=(a038-a070);
  a070=(a023*a037);
  a108=(a051*a070);
  a030=(a071*a108);
  a038=(a038-a030);
  a037=(a088*a037);
  a030=(a051*a037);
  a054=(a069*a030);
  a038=(a038-a054);
  a077=(a051*a077);
  a042=(a042+a077);
  a112=(a085*a112);
  a042=(a042+a112);
  a112=(a096*a042);
  a077=(a051*a112);
  a054=(a071*a077);
  a038=(a038-a054);
  a054=(a088*a042);
  a062=(a031*a054);
  a038=(a038-a062);
  a087=(a051*a087);
  a047=(a047+a087);
  a085=(a085*a068);
  a047=(a047+a085);
  a085=(a096*a047);
  a068=(a051*a085);
  a087=(a069*a068);
  a038=(a038-a087);
  a087=(a023*a047);
  a062=(a031*a087);
  a038=(a038+a062);
  a091=(a091*a038);
  a064=(a064+a091);
  a108=(a074*a108);
  a019=(a019-a108);
  a037=(a031*a037);
  a019=(a019+a037);
  a077=(a074*a077);
  a019=(a019-a077);
  a077=(2.*a071);
  a042=(a023*a042);
  a042=(a051*a042);
  a077=(a077*a042);
  a019=(a019-a077);
  a054=(a051*a054);
  a077=(a069*a054);
  a019=(a019-a077);
  a085=(a031*a085);
  a019=(a019-a085);
  a087=(a051*a087);
  a085=(a069*a087);
  a019=(a019-a085);
  a094=(a094*a019);
  a064=(a064+a094);
  a070=(a031*a070);
  a106=(a106-a070);
  a030=(a074*a030);
  a106=(a106-a030);
  a112=(a031*a112);
  a106=(a106+a112);
  a054=(a071*a054);
  a106=(a106-a054);
  a068=(a074*a068);
  a106=(a106-a068);
  a087=(a071*a087);
  a106=(a106-a087);
  a069=(2.*a069);
  a088=(a088*a047);
  a051=(a051*a088);
  a069=(a069*a051);
  a106=(a106-a069);
  a095=(a095*a106);
  a064=(a064+a095);
  a064=(a064/a000);
  if (res[0]!=0) res[0][3]=a064;
  a053=(a045*a053);
  a075=(a075+a072);
  a075=(a075/a010);
  a075=(a073*a075);
  a075=(a039-a075);
  a105=(a105*a075);
  a082=(a082/a010);
  a074=(a074+a082);
  a074=(a073*a074);
  a013=(a013*a074);
  a105=(a105+a013);
  a101=(a101/a010);
  a101=(a101-a071);
  a073=(a073*a101);
  a104=(a104*a073);
  a105=(a105+a104);
  a053=(a053-a105);
  a110=(a110*a052);
  a053=(a053+a110);
  a053=(a097*a053);
  a023=(a014*a023);
  a053=(a053-a023);
  a053=(a053*a032);
  a028=(a028*a038);
  a053=(a053+a028);
  a081=(a081*a019);
  a053=(a053+a081);
  a084=(a084*a106);
  a053=(a053+a084);
  a053=(a053/a000);
  if (res[0]!=0) res[0][4]=a053;
  a053=(a111*a075);
  a084=(a109*a074);
  a053=(a053+a084);
  a084=(a033*a073);
  a053=(a053+a084);
  a045=(a045*a053);
  a053=(a056*a092);
  a084=(a115*a067);
  a053=(a053+a084);
  a084=(a004*a098);
  a053=(a053+a084);
  a113=(a113*a053);
  a045=(a045+a113);
  a056=(a056*a075);
  a115=(a115*a074);
  a056=(a056+a115);
  a004=(a004*a073);
  a056=(a056+a004);
  a056=(a035*a056);
  a045=(a045+a056);
  a111=(a111*a092);
  a109=(a109*a067);
  a111=(a111+a109);
  a033=(a033*a098);
  a111=(a111+a033);
  a035=(a035*a111);
  a045=(a045+a035);
  a097=(a097*a045);
  a014=(a014*a096);
  a097=(a097-a014);
  a097=(a097*a032);
  a059=(a059*a038);
  a097=(a097+a059);
  a100=(a100*a019);
  a097=(a097+a100);
  a103=(a103*a106);
  a097=(a097+a103);
  a097=(a097/a000);
  if (res[0]!=0) res[0][5]=a097;
  a097=arg[2]? arg[2][0] : 0;
  a021=(a031*a021);
  a008=(a031*a008);
  a021=(a021+a008);
  a021=(a000*a021);
  a008=(a021/a010);
  a029=(a031*a029);
  a078=(a031*a078);
  a029=(a029+a078);
  a029=(a000*a029);
  a027=(a031*a027);
  a031=(a031*a003);
  a027=(a027+a031);
  a000=(a000*a027);
  a027=(a029*a000);
  a027=(a027/a006);
  a027=(a008+a027);
  a027=(a027*a036);
  a031=(a021*a000);
  a031=(a031/a006);
  a003=(a029/a010);
  a031=(a031-a003);
  a031=(a031*a041);
  a027=(a027+a031);
  a031=casadi_sq(a000);
  a031=(a031/a006);
  a031=(a039+a031);
  a031=(a031*a046);
  a027=(a027+a031);
  a090=(a086+a090);
  a090=(a090*a038);
  a027=(a027+a090);
  a093=(a093-a079);
  a093=(a093*a019);
  a027=(a027+a093);
  a027=(a027+a095);
  a007=(a011+a007);
  a007=(a007*a061);
  a027=(a027+a007);
  a055=(a055-a025);
  a055=(a055*a107);
  a027=(a027+a055);
  a027=(a027+a057);
  a097=(a097-a027);
  if (res[0]!=0) res[0][6]=a097;
  a097=arg[2]? arg[2][1] : 0;
  a027=(a029*a021);
  a027=(a027/a006);
  a010=(a000/a010);
  a027=(a027-a010);
  a027=(a027*a036);
  a057=casadi_sq(a021);
  a057=(a057/a006);
  a057=(a039+a057);
  a057=(a057*a041);
  a027=(a027+a057);
  a057=(a000*a021);
  a057=(a057/a006);
  a003=(a003+a057);
  a003=(a003*a046);
  a027=(a027+a003);
  a001=(a001-a076);
  a001=(a001*a038);
  a027=(a027+a001);
  a027=(a027+a081);
  a079=(a079+a083);
  a079=(a079*a106);
  a027=(a027+a079);
  a034=(a034-a018);
  a034=(a034*a061);
  a027=(a027+a034);
  a027=(a027+a040);
  a025=(a025+a044);
  a025=(a025*a114);
  a027=(a027+a025);
  a097=(a097-a027);
  if (res[0]!=0) res[0][7]=a097;
  a097=arg[2]? arg[2][2] : 0;
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
  a039=(a039+a059);
  a076=(a076+a099);
  a076=(a076*a019);
  a039=(a039+a076);
  a102=(a102-a086);
  a102=(a102*a106);
  a039=(a039+a102);
  a039=(a039+a060);
  a018=(a018+a063);
  a018=(a018*a107);
  a039=(a039+a018);
  a066=(a066-a011);
  a066=(a066*a114);
  a039=(a039+a066);
  a097=(a097-a039);
  if (res[0]!=0) res[0][8]=a097;
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
  casadi_real a180, a181, a182, a183, a184, a185, a186, a187, a188, a189, a190, a191;
  casadi_real a192, a193, a194, a195, a196, a197, a198, a199, a200, a201, a202, a203;
  casadi_real a204, a205, a206, a207, a208, a209, a210, a211, a212, a213, a214, a215;
  casadi_real a216, a217, a218, a219, a220, a221, a222, a223, a224, a225, a226, a227;
  casadi_real a228, a229, a230, a231, a232, a233, a234, a235, a236, a237, a238, a239;
  casadi_real a240, a241, a242, a243, a244, a245, a246;
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
  a033=5.0000000000000000e-01;
  a034=(a033*a000);
  a032=(a032*a034);
  a035=(a002*a009);
  a036=(a035/a006);
  a037=(a019+a036);
  a038=arg[0]? arg[0][8] : 0;
  a039=(a000*a038);
  a039=(a033*a039);
  a040=(a037*a039);
  a041=1.;
  a042=(a015/a006);
  a042=(a041+a042);
  a043=arg[0]? arg[0][7] : 0;
  a044=(a000*a043);
  a044=(a033*a044);
  a045=(a042*a044);
  a040=(a040+a045);
  a045=(a004*a009);
  a046=(a045/a006);
  a047=(a046-a026);
  a048=arg[0]? arg[0][6] : 0;
  a049=(a000*a048);
  a049=(a033*a049);
  a050=(a047*a049);
  a040=(a040+a050);
  a032=(a032-a040);
  a032=(a032/a034);
  a040=(a020*a032);
  a050=(a018*a011);
  a051=(a018*a028);
  a052=(a027*a022);
  a051=(a051+a052);
  a052=(a050*a030);
  a051=(a051-a052);
  a052=(2.*a051);
  a053=2.5000000000000000e-01;
  a054=(a053*a000);
  a052=(a052*a054);
  a055=(a012*a039);
  a056=(a009*a004);
  a057=(a056/a006);
  a058=(a026+a057);
  a059=(a058*a044);
  a055=(a055+a059);
  a059=(a014/a006);
  a059=(a041+a059);
  a060=(a059*a049);
  a055=(a055+a060);
  a052=(a052-a055);
  a052=(a052/a034);
  a055=(a050*a052);
  a040=(a040-a055);
  a055=(a050*a028);
  a060=(a020*a022);
  a055=(a055-a060);
  a060=(a018*a030);
  a055=(a055+a060);
  a060=(2.*a055);
  a061=7.5000000000000000e-01;
  a061=(a061*a000);
  a060=(a060*a061);
  a062=(a017/a006);
  a062=(a041+a062);
  a063=(a062*a039);
  a064=(a009*a002);
  a065=(a064/a006);
  a066=(a065-a019);
  a067=(a066*a044);
  a063=(a063+a067);
  a067=(a004*a002);
  a068=(a067/a006);
  a069=(a011+a068);
  a070=(a069*a049);
  a063=(a063+a070);
  a060=(a060-a063);
  a060=(a060/a034);
  a063=(a018*a060);
  a040=(a040+a063);
  a063=(a013*a040);
  a070=-3.2320508075688776e+00;
  a071=(a000*a029);
  a072=casadi_sq(a071);
  a073=(a000*a024);
  a074=casadi_sq(a073);
  a075=(a072+a074);
  a076=(a000*a031);
  a077=casadi_sq(a076);
  a075=(a075+a077);
  a075=(a006+a075);
  a078=(a006/a075);
  a079=(a071/a010);
  a080=(a078*a079);
  a081=-6.4641016151377553e+00;
  a008=(a081*a008);
  a024=(a021*a024);
  a008=(a008+a024);
  a024=(a078*a008);
  a082=(a076/a010);
  a083=(a078*a082);
  a003=(a081*a003);
  a029=(a021*a029);
  a003=(a003+a029);
  a029=(a083*a003);
  a024=(a024-a029);
  a001=(a081*a001);
  a031=(a021*a031);
  a001=(a001+a031);
  a031=(a080*a001);
  a024=(a024+a031);
  a031=(2.*a024);
  a031=(a031*a034);
  a029=(a076*a073);
  a084=(a029/a006);
  a085=(a079+a084);
  a086=(a085*a039);
  a031=(a031-a086);
  a086=(a074/a006);
  a086=(a041+a086);
  a087=(a086*a044);
  a031=(a031-a087);
  a087=(a071*a073);
  a088=(a087/a006);
  a089=(a088-a082);
  a090=(a089*a049);
  a031=(a031-a090);
  a031=(a031/a034);
  a090=(a080*a031);
  a091=(a073/a010);
  a092=(a078*a091);
  a093=(a078*a003);
  a094=(a083*a008);
  a093=(a093+a094);
  a094=(a092*a001);
  a093=(a093-a094);
  a094=(2.*a093);
  a094=(a094*a054);
  a095=(a076*a071);
  a096=(a095/a006);
  a097=(a096-a091);
  a098=(a097*a039);
  a094=(a094-a098);
  a098=(a073*a071);
  a099=(a098/a006);
  a100=(a082+a099);
  a101=(a100*a044);
  a094=(a094-a101);
  a101=(a072/a006);
  a101=(a041+a101);
  a102=(a101*a049);
  a094=(a094-a102);
  a094=(a094/a034);
  a102=(a092*a094);
  a090=(a090-a102);
  a102=(a092*a003);
  a103=(a080*a008);
  a102=(a102-a103);
  a103=(a078*a001);
  a102=(a102+a103);
  a103=(2.*a102);
  a103=(a103*a061);
  a104=(a077/a006);
  a104=(a041+a104);
  a105=(a104*a039);
  a103=(a103-a105);
  a105=(a073*a076);
  a106=(a105/a006);
  a107=(a106-a079);
  a108=(a107*a044);
  a103=(a103-a108);
  a108=(a071*a076);
  a109=(a108/a006);
  a110=(a091+a109);
  a111=(a110*a049);
  a103=(a103-a111);
  a103=(a103/a034);
  a111=(a078*a103);
  a090=(a090+a111);
  a111=(a070*a090);
  a063=(a063+a111);
  a111=(2.*a002);
  a112=5.3867513459481287e-01;
  a113=2.3205080756887719e-01;
  a040=(a113*a040);
  a090=(a013*a090);
  a040=(a040+a090);
  a090=(a000*a040);
  a114=(a112*a090);
  a114=(a039+a114);
  a115=(a000*a063);
  a116=(a053*a115);
  a114=(a114+a116);
  a116=(a055*a114);
  a116=(a053*a116);
  a117=(a111*a116);
  a063=(a063-a117);
  a117=(a025*a114);
  a118=(a053*a117);
  a119=(a009*a118);
  a063=(a063-a119);
  a119=(a051*a114);
  a120=(a053*a119);
  a121=(a004*a120);
  a063=(a063-a121);
  a121=(a027*a052);
  a122=(a018*a032);
  a121=(a121+a122);
  a122=(a020*a060);
  a121=(a121-a122);
  a122=(a113*a121);
  a123=(a083*a094);
  a124=(a078*a031);
  a123=(a123+a124);
  a124=(a080*a103);
  a123=(a123-a124);
  a124=(a013*a123);
  a122=(a122+a124);
  a124=(a000*a122);
  a125=(a112*a124);
  a125=(a044+a125);
  a121=(a013*a121);
  a123=(a070*a123);
  a121=(a121+a123);
  a123=(a000*a121);
  a126=(a053*a123);
  a125=(a125+a126);
  a126=(a055*a125);
  a127=(a053*a126);
  a128=(a009*a127);
  a063=(a063-a128);
  a128=(a051*a125);
  a129=(a033*a128);
  a063=(a063-a129);
  a129=(a018*a052);
  a130=(a027*a032);
  a129=(a129-a130);
  a130=(a050*a060);
  a129=(a129+a130);
  a130=(a113*a129);
  a131=(a078*a094);
  a132=(a083*a031);
  a131=(a131-a132);
  a132=(a092*a103);
  a131=(a131+a132);
  a132=(a013*a131);
  a130=(a130+a132);
  a132=(a000*a130);
  a133=(a112*a132);
  a133=(a049+a133);
  a129=(a013*a129);
  a131=(a070*a131);
  a129=(a129+a131);
  a131=(a000*a129);
  a134=(a053*a131);
  a133=(a133+a134);
  a134=(a055*a133);
  a135=(a053*a134);
  a136=(a004*a135);
  a063=(a063-a136);
  a136=(a025*a133);
  a137=(a033*a136);
  a063=(a063+a137);
  a137=(a012*a063);
  a119=(a033*a119);
  a138=(a002*a118);
  a119=(a119-a138);
  a119=(a119+a121);
  a121=(a002*a127);
  a119=(a119-a121);
  a121=(2.*a009);
  a138=(a025*a125);
  a138=(a053*a138);
  a139=(a121*a138);
  a119=(a119-a139);
  a128=(a053*a128);
  a139=(a004*a128);
  a119=(a119-a139);
  a134=(a033*a134);
  a119=(a119-a134);
  a136=(a053*a136);
  a134=(a004*a136);
  a119=(a119-a134);
  a134=(a058*a119);
  a137=(a137+a134);
  a126=(a033*a126);
  a117=(a033*a117);
  a134=(a002*a120);
  a117=(a117+a134);
  a126=(a126-a117);
  a117=(a009*a128);
  a126=(a126-a117);
  a126=(a126+a129);
  a129=(a002*a135);
  a126=(a126-a129);
  a129=(a009*a136);
  a126=(a126-a129);
  a129=(2.*a004);
  a117=(a051*a133);
  a117=(a053*a117);
  a134=(a129*a117);
  a126=(a126-a134);
  a134=(a059*a126);
  a137=(a137+a134);
  a139=-5.0000000000000000e-01;
  a140=arg[3]? arg[3][2] : 0;
  a139=(a139*a140);
  a140=arg[1]? arg[1][2] : 0;
  a056=(a056/a010);
  a056=(a056-a002);
  a141=(a018*a056);
  a142=(a140*a141);
  a143=arg[1]? arg[1][5] : 0;
  a144=(a017+a014);
  a144=(a144/a010);
  a145=(a018*a144);
  a145=(a041-a145);
  a146=(a143*a145);
  a142=(a142+a146);
  a146=arg[1]? arg[1][8] : 0;
  a064=(a064/a010);
  a064=(a004+a064);
  a147=(a018*a064);
  a148=(a146*a147);
  a142=(a142+a148);
  a148=8.4147098480789650e-01;
  a149=arg[1]? arg[1][0] : 0;
  a005=(a005/a010);
  a005=(a009+a005);
  a150=(a018*a005);
  a151=(a149*a150);
  a152=arg[1]? arg[1][3] : 0;
  a035=(a035/a010);
  a035=(a035-a004);
  a153=(a018*a035);
  a154=(a152*a153);
  a151=(a151+a154);
  a154=arg[1]? arg[1][6] : 0;
  a014=(a015+a014);
  a014=(a014/a010);
  a155=(a018*a014);
  a155=(a041-a155);
  a156=(a154*a155);
  a151=(a151+a156);
  a156=(a148*a151);
  a142=(a142+a156);
  a156=-5.4030230586813977e-01;
  a157=arg[1]? arg[1][1] : 0;
  a150=(a157*a150);
  a158=arg[1]? arg[1][4] : 0;
  a153=(a158*a153);
  a150=(a150+a153);
  a153=arg[1]? arg[1][7] : 0;
  a155=(a153*a155);
  a150=(a150+a155);
  a155=(a156*a150);
  a142=(a142+a155);
  a142=(a139*a142);
  a155=arg[3]? arg[3][3] : 0;
  a159=(a155*a051);
  a142=(a142-a159);
  a142=(a142*a034);
  a137=(a137+a142);
  a137=(a137/a000);
  if (res[0]!=0) res[0][0]=a137;
  a137=(a037*a063);
  a142=(a042*a119);
  a137=(a137+a142);
  a159=(a047*a126);
  a137=(a137+a159);
  a159=5.4030230586813977e-01;
  a151=(a159*a151);
  a017=(a017+a015);
  a017=(a017/a010);
  a015=(a018*a017);
  a015=(a041-a015);
  a160=(a140*a015);
  a045=(a045/a010);
  a045=(a002+a045);
  a161=(a018*a045);
  a162=(a143*a161);
  a160=(a160+a162);
  a067=(a067/a010);
  a067=(a067-a009);
  a162=(a018*a067);
  a163=(a146*a162);
  a160=(a160+a163);
  a151=(a151-a160);
  a150=(a148*a150);
  a151=(a151+a150);
  a151=(a139*a151);
  a150=(a155*a025);
  a151=(a151-a150);
  a151=(a151*a034);
  a137=(a137+a151);
  a137=(a137/a000);
  if (res[0]!=0) res[0][1]=a137;
  a137=(a062*a063);
  a151=(a066*a119);
  a151=(a137+a151);
  a150=(a069*a126);
  a151=(a151+a150);
  a150=(a157*a015);
  a160=(a158*a161);
  a150=(a150+a160);
  a160=(a153*a162);
  a150=(a150+a160);
  a150=(a159*a150);
  a160=(a149*a141);
  a163=(a152*a145);
  a160=(a160+a163);
  a163=(a154*a147);
  a160=(a160+a163);
  a160=(a156*a160);
  a150=(a150+a160);
  a160=-8.4147098480789650e-01;
  a015=(a149*a015);
  a161=(a152*a161);
  a015=(a015+a161);
  a162=(a154*a162);
  a015=(a015+a162);
  a015=(a160*a015);
  a150=(a150+a015);
  a141=(a157*a141);
  a145=(a158*a145);
  a141=(a141+a145);
  a147=(a153*a147);
  a141=(a141+a147);
  a141=(a160*a141);
  a150=(a150+a141);
  a150=(a139*a150);
  a141=(a155*a055);
  a150=(a150-a141);
  a150=(a150*a034);
  a151=(a151+a150);
  a151=(a151/a000);
  if (res[0]!=0) res[0][2]=a151;
  a098=(a098/a010);
  a098=(a098-a076);
  a151=(a078*a098);
  a150=(a140*a151);
  a141=(a077+a072);
  a141=(a141/a010);
  a147=(a078*a141);
  a147=(a041-a147);
  a145=(a143*a147);
  a150=(a150+a145);
  a105=(a105/a010);
  a105=(a071+a105);
  a145=(a078*a105);
  a015=(a146*a145);
  a150=(a150+a015);
  a095=(a095/a010);
  a095=(a073+a095);
  a015=(a078*a095);
  a162=(a149*a015);
  a029=(a029/a010);
  a029=(a029-a071);
  a161=(a078*a029);
  a163=(a152*a161);
  a162=(a162+a163);
  a072=(a074+a072);
  a072=(a072/a010);
  a163=(a078*a072);
  a163=(a041-a163);
  a164=(a154*a163);
  a162=(a162+a164);
  a164=(a148*a162);
  a150=(a150+a164);
  a015=(a157*a015);
  a161=(a158*a161);
  a015=(a015+a161);
  a163=(a153*a163);
  a015=(a015+a163);
  a163=(a156*a015);
  a150=(a150+a163);
  a150=(a139*a150);
  a163=(a155*a093);
  a150=(a150-a163);
  a150=(a150*a034);
  a163=(2.*a076);
  a090=(a053*a090);
  a090=(a039+a090);
  a161=-3.8675134594812879e-02;
  a115=(a161*a115);
  a090=(a090+a115);
  a115=(a102*a090);
  a115=(a053*a115);
  a164=(a163*a115);
  a040=(a040-a164);
  a164=(a024*a090);
  a165=(a053*a164);
  a166=(a073*a165);
  a040=(a040-a166);
  a166=(a093*a090);
  a167=(a053*a166);
  a168=(a071*a167);
  a040=(a040-a168);
  a124=(a053*a124);
  a124=(a044+a124);
  a123=(a161*a123);
  a124=(a124+a123);
  a123=(a102*a124);
  a168=(a053*a123);
  a169=(a073*a168);
  a040=(a040-a169);
  a169=(a093*a124);
  a170=(a033*a169);
  a040=(a040-a170);
  a132=(a053*a132);
  a132=(a049+a132);
  a131=(a161*a131);
  a132=(a132+a131);
  a131=(a102*a132);
  a170=(a053*a131);
  a171=(a071*a170);
  a040=(a040-a171);
  a171=(a024*a132);
  a172=(a033*a171);
  a040=(a040+a172);
  a172=(a097*a040);
  a150=(a150+a172);
  a172=(a076*a165);
  a122=(a122-a172);
  a166=(a033*a166);
  a122=(a122+a166);
  a166=(a076*a168);
  a122=(a122-a166);
  a166=(2.*a073);
  a172=(a024*a124);
  a172=(a053*a172);
  a173=(a166*a172);
  a122=(a122-a173);
  a169=(a053*a169);
  a173=(a071*a169);
  a122=(a122-a173);
  a131=(a033*a131);
  a122=(a122-a131);
  a171=(a053*a171);
  a131=(a071*a171);
  a122=(a122-a131);
  a131=(a100*a122);
  a150=(a150+a131);
  a164=(a033*a164);
  a130=(a130-a164);
  a164=(a076*a167);
  a130=(a130-a164);
  a123=(a033*a123);
  a130=(a130+a123);
  a123=(a073*a169);
  a130=(a130-a123);
  a123=(a076*a170);
  a130=(a130-a123);
  a123=(a073*a171);
  a130=(a130-a123);
  a123=(2.*a071);
  a164=(a093*a132);
  a164=(a053*a164);
  a131=(a123*a164);
  a130=(a130-a131);
  a131=(a101*a130);
  a150=(a150+a131);
  a150=(a150/a000);
  if (res[0]!=0) res[0][3]=a150;
  a162=(a159*a162);
  a077=(a077+a074);
  a077=(a077/a010);
  a074=(a078*a077);
  a074=(a041-a074);
  a150=(a140*a074);
  a087=(a087/a010);
  a087=(a076+a087);
  a173=(a078*a087);
  a174=(a143*a173);
  a150=(a150+a174);
  a108=(a108/a010);
  a108=(a108-a073);
  a174=(a078*a108);
  a175=(a146*a174);
  a150=(a150+a175);
  a162=(a162-a150);
  a015=(a148*a015);
  a162=(a162+a015);
  a162=(a139*a162);
  a015=(a155*a024);
  a162=(a162-a015);
  a162=(a162*a034);
  a015=(a085*a040);
  a162=(a162+a015);
  a015=(a086*a122);
  a162=(a162+a015);
  a150=(a089*a130);
  a162=(a162+a150);
  a162=(a162/a000);
  if (res[0]!=0) res[0][4]=a162;
  a162=(a157*a074);
  a150=(a158*a173);
  a162=(a162+a150);
  a150=(a153*a174);
  a162=(a162+a150);
  a162=(a159*a162);
  a150=(a149*a151);
  a175=(a152*a147);
  a150=(a150+a175);
  a175=(a154*a145);
  a150=(a150+a175);
  a150=(a156*a150);
  a162=(a162+a150);
  a074=(a149*a074);
  a173=(a152*a173);
  a074=(a074+a173);
  a174=(a154*a174);
  a074=(a074+a174);
  a074=(a160*a074);
  a162=(a162+a074);
  a151=(a157*a151);
  a147=(a158*a147);
  a151=(a151+a147);
  a145=(a153*a145);
  a151=(a151+a145);
  a151=(a160*a151);
  a162=(a162+a151);
  a162=(a139*a162);
  a151=(a155*a102);
  a162=(a162-a151);
  a162=(a162*a034);
  a151=(a104*a040);
  a162=(a162+a151);
  a145=(a107*a122);
  a162=(a162+a145);
  a145=(a110*a130);
  a162=(a162+a145);
  a162=(a162/a000);
  if (res[0]!=0) res[0][5]=a162;
  a162=arg[2]? arg[2][0] : 0;
  a145=(a033*a022);
  a147=(a033*a008);
  a145=(a145+a147);
  a145=(a000*a145);
  a147=(a145/a010);
  a074=(a033*a030);
  a174=(a033*a001);
  a074=(a074+a174);
  a074=(a000*a074);
  a174=(a033*a028);
  a173=(a033*a003);
  a174=(a174+a173);
  a174=(a000*a174);
  a173=(a074*a174);
  a173=(a173/a006);
  a173=(a147+a173);
  a150=(a173*a038);
  a175=(a145*a174);
  a175=(a175/a006);
  a176=(a074/a010);
  a175=(a175-a176);
  a177=(a175*a043);
  a150=(a150+a177);
  a177=casadi_sq(a174);
  a177=(a177/a006);
  a177=(a041+a177);
  a178=(a177*a048);
  a150=(a150+a178);
  a096=(a091+a096);
  a178=(a096*a040);
  a150=(a150+a178);
  a099=(a099-a082);
  a178=(a099*a122);
  a150=(a150+a178);
  a150=(a150+a131);
  a007=(a011+a007);
  a131=(a007*a063);
  a150=(a150+a131);
  a057=(a057-a026);
  a131=(a057*a119);
  a150=(a150+a131);
  a150=(a150+a134);
  a162=(a162-a150);
  if (res[0]!=0) res[0][6]=a162;
  a162=arg[2]? arg[2][1] : 0;
  a150=(a074*a145);
  a150=(a150/a006);
  a010=(a174/a010);
  a150=(a150-a010);
  a134=(a150*a038);
  a131=casadi_sq(a145);
  a131=(a131/a006);
  a131=(a041+a131);
  a178=(a131*a043);
  a134=(a134+a178);
  a178=(a174*a145);
  a178=(a178/a006);
  a176=(a176+a178);
  a178=(a176*a048);
  a134=(a134+a178);
  a084=(a084-a079);
  a178=(a084*a040);
  a134=(a134+a178);
  a134=(a134+a015);
  a088=(a082+a088);
  a015=(a088*a130);
  a134=(a134+a015);
  a036=(a036-a019);
  a015=(a036*a063);
  a134=(a134+a015);
  a134=(a134+a142);
  a046=(a026+a046);
  a142=(a046*a126);
  a134=(a134+a142);
  a162=(a162-a134);
  if (res[0]!=0) res[0][7]=a162;
  a162=arg[2]? arg[2][2] : 0;
  a134=casadi_sq(a074);
  a134=(a134/a006);
  a041=(a041+a134);
  a134=(a041*a038);
  a142=(a145*a074);
  a142=(a142/a006);
  a010=(a010+a142);
  a142=(a010*a043);
  a134=(a134+a142);
  a142=(a174*a074);
  a142=(a142/a006);
  a142=(a142-a147);
  a147=(a142*a048);
  a134=(a134+a147);
  a134=(a134+a151);
  a106=(a079+a106);
  a151=(a106*a122);
  a134=(a134+a151);
  a109=(a109-a091);
  a151=(a109*a130);
  a134=(a134+a151);
  a134=(a134+a137);
  a065=(a019+a065);
  a137=(a065*a119);
  a134=(a134+a137);
  a068=(a068-a011);
  a137=(a068*a126);
  a134=(a134+a137);
  a162=(a162-a134);
  if (res[0]!=0) res[0][8]=a162;
  a162=(a002*a000);
  a134=(a053*a162);
  a137=(a063*a134);
  a151=(a018*a034);
  a016=(a018/a016);
  a147=(a129*a000);
  a006=(a016*a147);
  a015=(a019*a006);
  a015=(a151-a015);
  a178=(a032*a015);
  a179=(a030*a015);
  a180=(a022*a006);
  a181=(a021*a027);
  a182=(a026*a006);
  a183=(a028*a182);
  a183=(a181-a183);
  a180=(a180+a183);
  a179=(a179-a180);
  a180=(2.*a179);
  a180=(a034*a180);
  a183=(a039*a034);
  a184=(a009*a000);
  a185=(a053*a184);
  a186=(a049*a185);
  a186=(a183+a186);
  a180=(a180-a186);
  a180=(a180/a034);
  a186=(a020*a180);
  a178=(a178+a186);
  a186=(a021*a018);
  a187=(a028*a006);
  a187=(a186-a187);
  a188=(a022*a182);
  a187=(a187-a188);
  a188=(a011*a006);
  a189=(a030*a188);
  a187=(a187+a189);
  a189=(2.*a187);
  a189=(a054*a189);
  a190=(a039*a134);
  a191=(a044*a185);
  a192=(a190+a191);
  a193=(a053*a147);
  a194=(a049*a193);
  a192=(a192+a194);
  a189=(a189-a192);
  a189=(a189/a034);
  a192=(a050*a189);
  a194=(a052*a188);
  a192=(a192-a194);
  a178=(a178-a192);
  a192=(a021*a050);
  a194=(a028*a188);
  a194=(a192-a194);
  a195=(a022*a015);
  a194=(a194-a195);
  a195=(a030*a006);
  a194=(a194-a195);
  a195=(2.*a194);
  a195=(a061*a195);
  a196=(a049*a134);
  a197=(a044*a034);
  a196=(a196-a197);
  a195=(a195-a196);
  a195=(a195/a034);
  a196=(a018*a195);
  a198=(a060*a006);
  a196=(a196-a198);
  a178=(a178+a196);
  a196=(a013*a178);
  a198=(a081*a083);
  a199=(-a198);
  a199=(2.*a199);
  a200=(a080*a199);
  a201=-1.2928203230275511e+01;
  a202=(a201*a078);
  a203=(a054*a202);
  a203=(a203/a034);
  a204=(a092*a203);
  a200=(a200-a204);
  a204=(a201*a092);
  a204=(a061*a204);
  a204=(a204/a034);
  a205=(a078*a204);
  a200=(a200+a205);
  a205=(a070*a200);
  a196=(a196+a205);
  a205=(a114*a194);
  a178=(a113*a178);
  a200=(a013*a200);
  a178=(a178+a200);
  a200=(a000*a178);
  a206=(a112*a200);
  a207=(a000*a196);
  a208=(a053*a207);
  a206=(a206+a208);
  a208=(a055*a206);
  a205=(a205+a208);
  a205=(a053*a205);
  a205=(a111*a205);
  a196=(a196-a205);
  a205=(a114*a179);
  a208=(a025*a206);
  a205=(a205+a208);
  a208=(a053*a205);
  a209=(a009*a208);
  a196=(a196-a209);
  a120=(a120*a000);
  a209=(a114*a187);
  a206=(a051*a206);
  a209=(a209+a206);
  a206=(a053*a209);
  a210=(a004*a206);
  a210=(a120+a210);
  a196=(a196-a210);
  a210=(a125*a194);
  a211=(a027*a189);
  a212=(a052*a182);
  a211=(a211-a212);
  a212=(a018*a180);
  a213=(a032*a006);
  a212=(a212-a213);
  a211=(a211+a212);
  a015=(a060*a015);
  a212=(a020*a195);
  a015=(a015+a212);
  a211=(a211-a015);
  a015=(a113*a211);
  a212=(a083*a203);
  a213=(a078*a199);
  a212=(a212+a213);
  a213=(a080*a204);
  a212=(a212-a213);
  a213=(a013*a212);
  a015=(a015+a213);
  a213=(a000*a015);
  a214=(a112*a213);
  a211=(a013*a211);
  a212=(a070*a212);
  a211=(a211+a212);
  a212=(a000*a211);
  a215=(a053*a212);
  a214=(a214+a215);
  a215=(a055*a214);
  a210=(a210+a215);
  a215=(a053*a210);
  a216=(a009*a215);
  a196=(a196-a216);
  a216=(a125*a187);
  a217=(a051*a214);
  a216=(a216+a217);
  a217=(a033*a216);
  a196=(a196-a217);
  a135=(a135*a000);
  a217=(a133*a194);
  a189=(a018*a189);
  a218=(a052*a006);
  a189=(a189-a218);
  a180=(a027*a180);
  a182=(a032*a182);
  a180=(a180-a182);
  a189=(a189-a180);
  a195=(a050*a195);
  a188=(a060*a188);
  a195=(a195-a188);
  a189=(a189+a195);
  a195=(a113*a189);
  a203=(a078*a203);
  a199=(a083*a199);
  a203=(a203-a199);
  a204=(a092*a204);
  a203=(a203+a204);
  a204=(a013*a203);
  a195=(a195+a204);
  a204=(a000*a195);
  a199=(a112*a204);
  a189=(a013*a189);
  a203=(a070*a203);
  a189=(a189+a203);
  a203=(a000*a189);
  a188=(a053*a203);
  a199=(a199+a188);
  a188=(a055*a199);
  a217=(a217+a188);
  a188=(a053*a217);
  a180=(a004*a188);
  a180=(a135+a180);
  a196=(a196-a180);
  a180=(a133*a179);
  a182=(a025*a199);
  a180=(a180+a182);
  a182=(a033*a180);
  a196=(a196+a182);
  a182=(a012*a196);
  a182=(a137+a182);
  a218=(a119*a185);
  a209=(a033*a209);
  a208=(a002*a208);
  a209=(a209-a208);
  a209=(a209+a211);
  a215=(a002*a215);
  a209=(a209-a215);
  a215=(a125*a179);
  a214=(a025*a214);
  a215=(a215+a214);
  a215=(a053*a215);
  a215=(a121*a215);
  a209=(a209-a215);
  a128=(a128*a000);
  a216=(a053*a216);
  a215=(a004*a216);
  a215=(a128+a215);
  a209=(a209-a215);
  a217=(a033*a217);
  a209=(a209-a217);
  a136=(a136*a000);
  a180=(a053*a180);
  a217=(a004*a180);
  a217=(a136+a217);
  a209=(a209-a217);
  a217=(a058*a209);
  a217=(a218+a217);
  a182=(a182+a217);
  a193=(a126*a193);
  a210=(a033*a210);
  a205=(a033*a205);
  a206=(a002*a206);
  a205=(a205+a206);
  a210=(a210-a205);
  a216=(a009*a216);
  a210=(a210-a216);
  a210=(a210+a189);
  a188=(a002*a188);
  a210=(a210-a188);
  a180=(a009*a180);
  a210=(a210-a180);
  a180=(2.*a000);
  a117=(a117*a180);
  a188=(a133*a187);
  a199=(a051*a199);
  a188=(a188+a199);
  a188=(a053*a188);
  a188=(a129*a188);
  a117=(a117+a188);
  a210=(a210-a117);
  a117=(a059*a210);
  a193=(a193+a117);
  a182=(a182+a193);
  a184=(a033*a184);
  a184=(a018*a184);
  a117=(a056*a006);
  a117=(a184-a117);
  a188=(a140*a117);
  a147=(a033*a147);
  a147=(a018*a147);
  a199=(a144*a006);
  a199=(a147-a199);
  a189=(a143*a199);
  a188=(a188-a189);
  a189=(a018*a000);
  a216=(a064*a006);
  a216=(a189-a216);
  a205=(a146*a216);
  a188=(a188+a205);
  a162=(a033*a162);
  a162=(a018*a162);
  a205=(a005*a006);
  a205=(a162-a205);
  a206=(a149*a205);
  a217=(a035*a006);
  a217=(a217+a189);
  a215=(a152*a217);
  a206=(a206-a215);
  a215=(a014*a006);
  a147=(a147-a215);
  a215=(a154*a147);
  a206=(a206-a215);
  a215=(a148*a206);
  a188=(a188+a215);
  a205=(a157*a205);
  a217=(a158*a217);
  a205=(a205-a217);
  a147=(a153*a147);
  a205=(a205-a147);
  a147=(a156*a205);
  a188=(a188+a147);
  a188=(a139*a188);
  a187=(a155*a187);
  a188=(a188-a187);
  a188=(a034*a188);
  a182=(a182+a188);
  a182=(a182/a000);
  if (res[1]!=0) res[1][0]=a182;
  a182=(a063*a034);
  a188=(a037*a196);
  a188=(a182+a188);
  a187=(a042*a209);
  a188=(a188+a187);
  a147=(a126*a185);
  a217=(a047*a210);
  a217=(a147+a217);
  a188=(a188+a217);
  a206=(a159*a206);
  a217=(a017*a006);
  a215=(a140*a217);
  a214=(a045*a006);
  a214=(a184-a214);
  a211=(a143*a214);
  a215=(a215+a211);
  a006=(a067*a006);
  a006=(a162-a006);
  a211=(a146*a006);
  a215=(a215+a211);
  a206=(a206-a215);
  a205=(a148*a205);
  a206=(a206+a205);
  a206=(a139*a206);
  a179=(a155*a179);
  a206=(a206-a179);
  a206=(a034*a206);
  a188=(a188+a206);
  a188=(a188/a000);
  if (res[1]!=0) res[1][1]=a188;
  a188=(a062*a196);
  a206=(a066*a209);
  a179=(a119*a034);
  a206=(a206-a179);
  a206=(a188+a206);
  a205=(a126*a134);
  a215=(a069*a210);
  a215=(a205+a215);
  a206=(a206+a215);
  a215=(a157*a217);
  a211=(a158*a214);
  a215=(a215+a211);
  a211=(a153*a006);
  a215=(a215+a211);
  a215=(a159*a215);
  a211=(a149*a117);
  a208=(a152*a199);
  a211=(a211-a208);
  a208=(a154*a216);
  a211=(a211+a208);
  a211=(a156*a211);
  a215=(a215+a211);
  a217=(a149*a217);
  a214=(a152*a214);
  a217=(a217+a214);
  a006=(a154*a006);
  a217=(a217+a006);
  a217=(a160*a217);
  a215=(a215+a217);
  a117=(a157*a117);
  a199=(a158*a199);
  a117=(a117-a199);
  a216=(a153*a216);
  a117=(a117+a216);
  a117=(a160*a117);
  a215=(a215+a117);
  a215=(a139*a215);
  a194=(a155*a194);
  a215=(a215-a194);
  a215=(a034*a215);
  a206=(a206+a215);
  a206=(a206/a000);
  if (res[1]!=0) res[1][2]=a206;
  a206=(a081*a092);
  a215=(a090*a206);
  a200=(a053*a200);
  a207=(a161*a207);
  a200=(a200+a207);
  a207=(a102*a200);
  a207=(a215+a207);
  a207=(a053*a207);
  a207=(a163*a207);
  a178=(a178-a207);
  a207=(a024*a200);
  a194=(a090*a198);
  a207=(a207-a194);
  a117=(a053*a207);
  a216=(a073*a117);
  a178=(a178-a216);
  a216=(a081*a078);
  a199=(a090*a216);
  a200=(a093*a200);
  a200=(a199+a200);
  a217=(a053*a200);
  a006=(a071*a217);
  a178=(a178-a006);
  a006=(a124*a206);
  a213=(a053*a213);
  a212=(a161*a212);
  a213=(a213+a212);
  a212=(a102*a213);
  a212=(a006+a212);
  a214=(a053*a212);
  a211=(a073*a214);
  a178=(a178-a211);
  a211=(a124*a216);
  a208=(a093*a213);
  a208=(a211+a208);
  a219=(a033*a208);
  a178=(a178-a219);
  a219=(a132*a206);
  a204=(a053*a204);
  a203=(a161*a203);
  a204=(a204+a203);
  a203=(a102*a204);
  a203=(a219+a203);
  a220=(a053*a203);
  a221=(a071*a220);
  a178=(a178-a221);
  a221=(a024*a204);
  a222=(a132*a198);
  a221=(a221-a222);
  a223=(a033*a221);
  a178=(a178+a223);
  a223=(a097*a178);
  a224=(a155*a216);
  a224=(a034*a224);
  a223=(a223-a224);
  a117=(a076*a117);
  a015=(a015-a117);
  a200=(a033*a200);
  a015=(a015+a200);
  a214=(a076*a214);
  a015=(a015-a214);
  a213=(a024*a213);
  a214=(a124*a198);
  a213=(a213-a214);
  a213=(a053*a213);
  a213=(a166*a213);
  a015=(a015-a213);
  a208=(a053*a208);
  a213=(a071*a208);
  a015=(a015-a213);
  a203=(a033*a203);
  a015=(a015-a203);
  a221=(a053*a221);
  a203=(a071*a221);
  a015=(a015-a203);
  a203=(a100*a015);
  a223=(a223+a203);
  a207=(a033*a207);
  a195=(a195-a207);
  a217=(a076*a217);
  a195=(a195-a217);
  a212=(a033*a212);
  a195=(a195+a212);
  a208=(a073*a208);
  a195=(a195-a208);
  a220=(a076*a220);
  a195=(a195-a220);
  a221=(a073*a221);
  a195=(a195-a221);
  a216=(a132*a216);
  a204=(a093*a204);
  a204=(a216+a204);
  a204=(a053*a204);
  a204=(a123*a204);
  a195=(a195-a204);
  a204=(a101*a195);
  a223=(a223+a204);
  a223=(a223/a000);
  if (res[1]!=0) res[1][3]=a223;
  a198=(a155*a198);
  a198=(a034*a198);
  a223=(a085*a178);
  a223=(a198+a223);
  a221=(a086*a015);
  a223=(a223+a221);
  a220=(a089*a195);
  a223=(a223+a220);
  a223=(a223/a000);
  if (res[1]!=0) res[1][4]=a223;
  a223=(a104*a178);
  a220=(a155*a206);
  a220=(a034*a220);
  a208=(a223-a220);
  a212=(a107*a015);
  a208=(a208+a212);
  a212=(a110*a195);
  a208=(a208+a212);
  a208=(a208/a000);
  if (res[1]!=0) res[1][5]=a208;
  a208=-1.7320508075688774e+00;
  a208=(a208*a000);
  a212=(a074*a208);
  a212=(a053*a212);
  a217=(a038*a212);
  a207=(a145*a208);
  a207=(a053*a207);
  a203=(a043*a207);
  a213=(a217+a203);
  a200=(2.*a174);
  a117=(a200*a208);
  a117=(a053*a117);
  a117=(a048*a117);
  a213=(a213+a117);
  a117=(a096*a178);
  a213=(a213+a117);
  a117=(a099*a015);
  a213=(a213+a117);
  a213=(a213+a204);
  a204=(a007*a196);
  a204=(a137+a204);
  a213=(a213+a204);
  a204=(a057*a209);
  a204=(a218+a204);
  a213=(a213+a204);
  a213=(a213+a193);
  a213=(-a213);
  if (res[1]!=0) res[1][6]=a213;
  a213=(a048*a207);
  a193=-8.6602540378443871e-01;
  a193=(a193*a000);
  a204=(a038*a193);
  a213=(a213-a204);
  a178=(a084*a178);
  a213=(a213+a178);
  a213=(a213+a221);
  a221=(a088*a195);
  a213=(a213+a221);
  a196=(a036*a196);
  a196=(a196-a182);
  a213=(a213+a196);
  a213=(a213+a187);
  a187=(a046*a210);
  a147=(a147+a187);
  a213=(a213+a147);
  a213=(-a213);
  if (res[1]!=0) res[1][7]=a213;
  a213=(a043*a193);
  a147=(a048*a212);
  a147=(a213+a147);
  a147=(a147+a223);
  a015=(a106*a015);
  a147=(a147+a015);
  a195=(a109*a195);
  a147=(a147+a195);
  a147=(a147+a188);
  a209=(a065*a209);
  a209=(a179+a209);
  a147=(a147+a209);
  a210=(a068*a210);
  a205=(a205+a210);
  a147=(a147+a205);
  a147=(-a147);
  if (res[1]!=0) res[1][8]=a147;
  a147=(a121*a000);
  a205=(a016*a147);
  a210=(a022*a205);
  a210=(a186-a210);
  a209=(a026*a205);
  a188=(a028*a209);
  a210=(a210+a188);
  a188=(a019*a205);
  a195=(a030*a188);
  a210=(a210-a195);
  a195=(2.*a210);
  a195=(a034*a195);
  a015=(a053*a147);
  a223=(a044*a015);
  a190=(a190+a223);
  a223=(a004*a000);
  a187=(a053*a223);
  a196=(a049*a187);
  a190=(a190+a196);
  a195=(a195-a190);
  a195=(a195/a034);
  a190=(a020*a195);
  a221=(a032*a188);
  a190=(a190-a221);
  a221=(a011*a205);
  a221=(a151-a221);
  a178=(a052*a221);
  a117=(a022*a209);
  a181=(a181-a117);
  a117=(a028*a205);
  a181=(a181-a117);
  a117=(a030*a221);
  a181=(a181-a117);
  a117=(2.*a181);
  a117=(a054*a117);
  a225=(a044*a187);
  a225=(a225-a183);
  a117=(a117-a225);
  a117=(a117/a034);
  a225=(a050*a117);
  a178=(a178+a225);
  a190=(a190-a178);
  a178=(a028*a221);
  a225=(a021*a020);
  a226=(a022*a188);
  a226=(a225-a226);
  a178=(a178-a226);
  a226=(a030*a205);
  a178=(a178-a226);
  a226=(2.*a178);
  a226=(a061*a226);
  a227=(a044*a134);
  a228=(a049*a034);
  a227=(a227+a228);
  a226=(a226-a227);
  a226=(a226/a034);
  a227=(a018*a226);
  a229=(a060*a205);
  a227=(a227-a229);
  a190=(a190+a227);
  a227=(a013*a190);
  a229=(a080*a202);
  a230=(a201*a083);
  a230=(a054*a230);
  a230=(a230/a034);
  a231=(a092*a230);
  a229=(a229-a231);
  a081=(a081*a080);
  a231=(-a081);
  a231=(2.*a231);
  a231=(a061*a231);
  a231=(a231/a034);
  a232=(a078*a231);
  a229=(a229+a232);
  a232=(a070*a229);
  a227=(a227+a232);
  a232=(a114*a178);
  a190=(a113*a190);
  a229=(a013*a229);
  a190=(a190+a229);
  a229=(a000*a190);
  a233=(a112*a229);
  a234=(a000*a227);
  a235=(a053*a234);
  a233=(a233+a235);
  a235=(a055*a233);
  a232=(a232+a235);
  a232=(a053*a232);
  a232=(a111*a232);
  a227=(a227-a232);
  a118=(a118*a000);
  a232=(a114*a210);
  a235=(a025*a233);
  a232=(a232+a235);
  a235=(a053*a232);
  a236=(a009*a235);
  a236=(a118+a236);
  a227=(a227-a236);
  a236=(a114*a181);
  a233=(a051*a233);
  a236=(a236+a233);
  a233=(a053*a236);
  a237=(a004*a233);
  a227=(a227-a237);
  a127=(a127*a000);
  a237=(a125*a178);
  a238=(a027*a117);
  a239=(a052*a209);
  a238=(a238-a239);
  a239=(a018*a195);
  a240=(a032*a205);
  a239=(a239-a240);
  a238=(a238+a239);
  a239=(a020*a226);
  a188=(a060*a188);
  a239=(a239-a188);
  a238=(a238-a239);
  a239=(a113*a238);
  a188=(a083*a230);
  a240=(a078*a202);
  a188=(a188+a240);
  a240=(a080*a231);
  a188=(a188-a240);
  a240=(a013*a188);
  a239=(a239+a240);
  a240=(a000*a239);
  a241=(a112*a240);
  a238=(a013*a238);
  a188=(a070*a188);
  a238=(a238+a188);
  a188=(a000*a238);
  a242=(a053*a188);
  a241=(a241+a242);
  a242=(a055*a241);
  a237=(a237+a242);
  a242=(a053*a237);
  a243=(a009*a242);
  a243=(a127+a243);
  a227=(a227-a243);
  a243=(a125*a181);
  a244=(a051*a241);
  a243=(a243+a244);
  a244=(a033*a243);
  a227=(a227-a244);
  a244=(a133*a178);
  a117=(a018*a117);
  a245=(a052*a205);
  a117=(a117-a245);
  a195=(a027*a195);
  a209=(a032*a209);
  a195=(a195-a209);
  a117=(a117-a195);
  a221=(a060*a221);
  a226=(a050*a226);
  a221=(a221+a226);
  a117=(a117+a221);
  a221=(a113*a117);
  a230=(a078*a230);
  a226=(a083*a202);
  a230=(a230-a226);
  a231=(a092*a231);
  a230=(a230+a231);
  a231=(a013*a230);
  a221=(a221+a231);
  a231=(a000*a221);
  a226=(a112*a231);
  a117=(a013*a117);
  a230=(a070*a230);
  a117=(a117+a230);
  a230=(a000*a117);
  a195=(a053*a230);
  a226=(a226+a195);
  a195=(a055*a226);
  a244=(a244+a195);
  a195=(a053*a244);
  a209=(a004*a195);
  a227=(a227-a209);
  a209=(a133*a210);
  a245=(a025*a226);
  a209=(a209+a245);
  a245=(a033*a209);
  a227=(a227+a245);
  a245=(a012*a227);
  a245=(a245-a182);
  a246=(a119*a187);
  a236=(a033*a236);
  a235=(a002*a235);
  a236=(a236-a235);
  a236=(a236+a238);
  a242=(a002*a242);
  a236=(a236-a242);
  a138=(a138*a180);
  a242=(a125*a210);
  a241=(a025*a241);
  a242=(a242+a241);
  a242=(a053*a242);
  a242=(a121*a242);
  a138=(a138+a242);
  a236=(a236-a138);
  a243=(a053*a243);
  a138=(a004*a243);
  a236=(a236-a138);
  a244=(a033*a244);
  a236=(a236-a244);
  a209=(a053*a209);
  a244=(a004*a209);
  a236=(a236-a244);
  a244=(a058*a236);
  a244=(a246+a244);
  a245=(a245+a244);
  a237=(a033*a237);
  a232=(a033*a232);
  a233=(a002*a233);
  a232=(a232+a233);
  a237=(a237-a232);
  a243=(a009*a243);
  a128=(a128+a243);
  a237=(a237-a128);
  a237=(a237+a117);
  a195=(a002*a195);
  a237=(a237-a195);
  a209=(a009*a209);
  a136=(a136+a209);
  a237=(a237-a136);
  a136=(a133*a181);
  a226=(a051*a226);
  a136=(a136+a226);
  a136=(a053*a136);
  a136=(a129*a136);
  a237=(a237-a136);
  a136=(a059*a237);
  a245=(a245+a136);
  a223=(a033*a223);
  a223=(a018*a223);
  a226=(a056*a205);
  a226=(a223-a226);
  a209=(a140*a226);
  a195=(a144*a205);
  a117=(a143*a195);
  a209=(a209+a117);
  a117=(a064*a205);
  a117=(a162-a117);
  a128=(a146*a117);
  a209=(a209+a128);
  a128=(a005*a205);
  a128=(a189-a128);
  a243=(a149*a128);
  a232=(a035*a205);
  a162=(a162-a232);
  a232=(a152*a162);
  a243=(a243+a232);
  a147=(a033*a147);
  a147=(a018*a147);
  a232=(a014*a205);
  a232=(a147-a232);
  a233=(a154*a232);
  a243=(a243-a233);
  a233=(a148*a243);
  a209=(a209+a233);
  a128=(a157*a128);
  a162=(a158*a162);
  a128=(a128+a162);
  a232=(a153*a232);
  a128=(a128-a232);
  a232=(a156*a128);
  a209=(a209+a232);
  a209=(a139*a209);
  a181=(a155*a181);
  a209=(a209-a181);
  a209=(a034*a209);
  a245=(a245+a209);
  a245=(a245/a000);
  if (res[1]!=0) res[1][9]=a245;
  a245=(a037*a227);
  a245=(a137+a245);
  a015=(a119*a015);
  a209=(a042*a236);
  a015=(a015+a209);
  a245=(a245+a015);
  a209=(a126*a187);
  a181=(a047*a237);
  a181=(a209+a181);
  a245=(a245+a181);
  a243=(a159*a243);
  a181=(a045*a205);
  a181=(a223-a181);
  a232=(a143*a181);
  a162=(a017*a205);
  a147=(a147-a162);
  a162=(a140*a147);
  a232=(a232-a162);
  a205=(a067*a205);
  a205=(a205+a189);
  a162=(a146*a205);
  a232=(a232-a162);
  a243=(a243-a232);
  a128=(a148*a128);
  a243=(a243+a128);
  a243=(a139*a243);
  a210=(a155*a210);
  a243=(a243-a210);
  a243=(a034*a243);
  a245=(a245+a243);
  a245=(a245/a000);
  if (res[1]!=0) res[1][10]=a245;
  a245=(a062*a227);
  a119=(a119*a134);
  a134=(a066*a236);
  a134=(a119+a134);
  a134=(a245+a134);
  a126=(a126*a034);
  a243=(a069*a237);
  a243=(a126+a243);
  a134=(a134+a243);
  a243=(a158*a181);
  a210=(a157*a147);
  a243=(a243-a210);
  a210=(a153*a205);
  a243=(a243-a210);
  a243=(a159*a243);
  a210=(a149*a226);
  a128=(a152*a195);
  a210=(a210+a128);
  a128=(a154*a117);
  a210=(a210+a128);
  a210=(a156*a210);
  a243=(a243+a210);
  a181=(a152*a181);
  a147=(a149*a147);
  a181=(a181-a147);
  a205=(a154*a205);
  a181=(a181-a205);
  a181=(a160*a181);
  a243=(a243+a181);
  a226=(a157*a226);
  a195=(a158*a195);
  a226=(a226+a195);
  a117=(a153*a117);
  a226=(a226+a117);
  a226=(a160*a226);
  a243=(a243+a226);
  a243=(a139*a243);
  a178=(a155*a178);
  a243=(a243-a178);
  a243=(a034*a243);
  a134=(a134+a243);
  a134=(a134/a000);
  if (res[1]!=0) res[1][11]=a134;
  a229=(a053*a229);
  a234=(a161*a234);
  a229=(a229+a234);
  a234=(a102*a229);
  a134=(a090*a081);
  a234=(a234-a134);
  a234=(a053*a234);
  a234=(a163*a234);
  a190=(a190-a234);
  a234=(a024*a229);
  a234=(a199+a234);
  a243=(a053*a234);
  a178=(a073*a243);
  a190=(a190-a178);
  a229=(a093*a229);
  a194=(a194+a229);
  a229=(a053*a194);
  a178=(a071*a229);
  a190=(a190-a178);
  a240=(a053*a240);
  a188=(a161*a188);
  a240=(a240+a188);
  a188=(a102*a240);
  a178=(a124*a081);
  a188=(a188-a178);
  a226=(a053*a188);
  a117=(a073*a226);
  a190=(a190-a117);
  a117=(a093*a240);
  a214=(a214+a117);
  a117=(a033*a214);
  a190=(a190-a117);
  a231=(a053*a231);
  a230=(a161*a230);
  a231=(a231+a230);
  a230=(a102*a231);
  a117=(a132*a081);
  a230=(a230-a117);
  a195=(a053*a230);
  a181=(a071*a195);
  a190=(a190-a181);
  a181=(a024*a231);
  a181=(a216+a181);
  a205=(a033*a181);
  a190=(a190+a205);
  a205=(a097*a190);
  a205=(a205-a198);
  a243=(a076*a243);
  a239=(a239-a243);
  a194=(a033*a194);
  a239=(a239+a194);
  a226=(a076*a226);
  a239=(a239-a226);
  a240=(a024*a240);
  a240=(a211+a240);
  a240=(a053*a240);
  a240=(a166*a240);
  a239=(a239-a240);
  a214=(a053*a214);
  a240=(a071*a214);
  a239=(a239-a240);
  a230=(a033*a230);
  a239=(a239-a230);
  a181=(a053*a181);
  a230=(a071*a181);
  a239=(a239-a230);
  a230=(a100*a239);
  a205=(a205+a230);
  a234=(a033*a234);
  a221=(a221-a234);
  a229=(a076*a229);
  a221=(a221-a229);
  a188=(a033*a188);
  a221=(a221+a188);
  a214=(a073*a214);
  a221=(a221-a214);
  a195=(a076*a195);
  a221=(a221-a195);
  a181=(a073*a181);
  a221=(a221-a181);
  a231=(a093*a231);
  a222=(a222+a231);
  a222=(a053*a222);
  a222=(a123*a222);
  a221=(a221-a222);
  a222=(a101*a221);
  a205=(a205+a222);
  a205=(a205/a000);
  if (res[1]!=0) res[1][12]=a205;
  a205=(a085*a190);
  a205=(a205-a224);
  a231=(a086*a239);
  a205=(a205+a231);
  a181=(a089*a221);
  a205=(a205+a181);
  a205=(a205/a000);
  if (res[1]!=0) res[1][13]=a205;
  a081=(a155*a081);
  a081=(a034*a081);
  a205=(a104*a190);
  a181=(a081+a205);
  a195=(a107*a239);
  a181=(a181+a195);
  a195=(a110*a221);
  a181=(a181+a195);
  a181=(a181/a000);
  if (res[1]!=0) res[1][14]=a181;
  a181=(a174*a208);
  a181=(a053*a181);
  a195=(a043*a181);
  a204=(a204+a195);
  a195=(a096*a190);
  a204=(a204+a195);
  a195=(a099*a239);
  a204=(a204+a195);
  a204=(a204+a222);
  a222=(a007*a227);
  a182=(a182+a222);
  a204=(a204+a182);
  a182=(a057*a236);
  a246=(a246+a182);
  a204=(a204+a246);
  a204=(a204+a136);
  a204=(-a204);
  if (res[1]!=0) res[1][15]=a204;
  a204=(2.*a145);
  a136=(a204*a208);
  a136=(a053*a136);
  a136=(a043*a136);
  a217=(a217+a136);
  a136=(a048*a181);
  a217=(a217+a136);
  a190=(a084*a190);
  a217=(a217+a190);
  a217=(a217+a231);
  a231=(a088*a221);
  a217=(a217+a231);
  a227=(a036*a227);
  a137=(a137+a227);
  a217=(a217+a137);
  a217=(a217+a015);
  a015=(a046*a237);
  a015=(a209+a015);
  a217=(a217+a015);
  a217=(-a217);
  if (res[1]!=0) res[1][16]=a217;
  a212=(a043*a212);
  a193=(a048*a193);
  a212=(a212-a193);
  a212=(a212+a205);
  a239=(a106*a239);
  a212=(a212+a239);
  a221=(a109*a221);
  a212=(a212+a221);
  a212=(a212+a245);
  a236=(a065*a236);
  a119=(a119+a236);
  a212=(a212+a119);
  a237=(a068*a237);
  a237=(a237-a126);
  a212=(a212+a237);
  a212=(-a212);
  if (res[1]!=0) res[1][17]=a212;
  a212=(a063*a187);
  a237=(a111*a000);
  a016=(a016*a237);
  a019=(a019*a016);
  a119=(a030*a019);
  a225=(a225-a119);
  a119=(a022*a016);
  a026=(a026*a016);
  a151=(a151-a026);
  a026=(a028*a151);
  a119=(a119+a026);
  a225=(a225-a119);
  a119=(2.*a225);
  a119=(a034*a119);
  a026=(a039*a185);
  a026=(a026-a228);
  a119=(a119-a026);
  a119=(a119/a034);
  a026=(a020*a119);
  a236=(a032*a019);
  a026=(a026-a236);
  a236=(a022*a151);
  a245=(a028*a016);
  a236=(a236-a245);
  a011=(a011*a016);
  a245=(a030*a011);
  a192=(a192-a245);
  a236=(a236-a192);
  a192=(2.*a236);
  a192=(a054*a192);
  a187=(a039*a187);
  a187=(a187+a197);
  a192=(a192-a187);
  a192=(a192/a034);
  a187=(a050*a192);
  a245=(a052*a011);
  a187=(a187-a245);
  a026=(a026-a187);
  a022=(a022*a019);
  a028=(a028*a011);
  a022=(a022-a028);
  a030=(a030*a016);
  a186=(a186-a030);
  a022=(a022+a186);
  a186=(2.*a022);
  a186=(a061*a186);
  a030=(a053*a237);
  a028=(a039*a030);
  a028=(a028+a191);
  a028=(a028+a196);
  a186=(a186-a028);
  a186=(a186/a034);
  a028=(a018*a186);
  a196=(a060*a016);
  a028=(a028-a196);
  a026=(a026+a028);
  a028=(a013*a026);
  a201=(a201*a080);
  a196=(a080*a201);
  a206=(-a206);
  a206=(2.*a206);
  a206=(a054*a206);
  a206=(a206/a034);
  a191=(a092*a206);
  a196=(a196-a191);
  a202=(a061*a202);
  a202=(a202/a034);
  a191=(a078*a202);
  a196=(a196+a191);
  a191=(a070*a196);
  a028=(a028+a191);
  a116=(a116*a180);
  a191=(a114*a022);
  a026=(a113*a026);
  a196=(a013*a196);
  a026=(a026+a196);
  a196=(a000*a026);
  a187=(a112*a196);
  a245=(a000*a028);
  a221=(a053*a245);
  a187=(a187+a221);
  a221=(a055*a187);
  a191=(a191+a221);
  a191=(a053*a191);
  a191=(a111*a191);
  a116=(a116+a191);
  a028=(a028-a116);
  a116=(a114*a225);
  a191=(a025*a187);
  a116=(a116+a191);
  a191=(a053*a116);
  a221=(a009*a191);
  a028=(a028-a221);
  a221=(a114*a236);
  a187=(a051*a187);
  a221=(a221+a187);
  a187=(a053*a221);
  a239=(a004*a187);
  a028=(a028-a239);
  a239=(a125*a022);
  a205=(a052*a151);
  a217=(a027*a192);
  a205=(a205+a217);
  a217=(a018*a119);
  a015=(a032*a016);
  a217=(a217-a015);
  a205=(a205+a217);
  a217=(a020*a186);
  a019=(a060*a019);
  a217=(a217-a019);
  a205=(a205-a217);
  a217=(a113*a205);
  a019=(a083*a206);
  a015=(a078*a201);
  a019=(a019+a015);
  a015=(a080*a202);
  a019=(a019-a015);
  a015=(a013*a019);
  a217=(a217+a015);
  a015=(a000*a217);
  a137=(a112*a015);
  a205=(a013*a205);
  a019=(a070*a019);
  a205=(a205+a019);
  a019=(a000*a205);
  a227=(a053*a019);
  a137=(a137+a227);
  a227=(a055*a137);
  a239=(a239+a227);
  a227=(a053*a239);
  a231=(a009*a227);
  a028=(a028-a231);
  a231=(a125*a236);
  a190=(a051*a137);
  a231=(a231+a190);
  a190=(a033*a231);
  a028=(a028-a190);
  a190=(a133*a022);
  a192=(a018*a192);
  a052=(a052*a016);
  a192=(a192-a052);
  a032=(a032*a151);
  a119=(a027*a119);
  a032=(a032+a119);
  a192=(a192-a032);
  a186=(a050*a186);
  a060=(a060*a011);
  a186=(a186-a060);
  a192=(a192+a186);
  a186=(a113*a192);
  a206=(a078*a206);
  a201=(a083*a201);
  a206=(a206-a201);
  a202=(a092*a202);
  a206=(a206+a202);
  a202=(a013*a206);
  a186=(a186+a202);
  a202=(a000*a186);
  a201=(a112*a202);
  a192=(a013*a192);
  a206=(a070*a206);
  a192=(a192+a206);
  a206=(a000*a192);
  a060=(a053*a206);
  a201=(a201+a060);
  a060=(a055*a201);
  a190=(a190+a060);
  a060=(a053*a190);
  a011=(a004*a060);
  a028=(a028-a011);
  a011=(a133*a225);
  a032=(a025*a201);
  a011=(a011+a032);
  a032=(a033*a011);
  a028=(a028+a032);
  a032=(a012*a028);
  a032=(a212+a032);
  a221=(a033*a221);
  a191=(a002*a191);
  a118=(a118+a191);
  a221=(a221-a118);
  a221=(a221+a205);
  a227=(a002*a227);
  a127=(a127+a227);
  a221=(a221-a127);
  a127=(a125*a225);
  a137=(a025*a137);
  a127=(a127+a137);
  a127=(a053*a127);
  a127=(a121*a127);
  a221=(a221-a127);
  a231=(a053*a231);
  a127=(a004*a231);
  a221=(a221-a127);
  a190=(a033*a190);
  a221=(a221-a190);
  a011=(a053*a011);
  a190=(a004*a011);
  a221=(a221-a190);
  a190=(a058*a221);
  a190=(a179+a190);
  a032=(a032+a190);
  a239=(a033*a239);
  a116=(a033*a116);
  a187=(a002*a187);
  a120=(a120+a187);
  a116=(a116+a120);
  a239=(a239-a116);
  a231=(a009*a231);
  a239=(a239-a231);
  a239=(a239+a192);
  a060=(a002*a060);
  a135=(a135+a060);
  a239=(a239-a135);
  a011=(a009*a011);
  a239=(a239-a011);
  a011=(a133*a236);
  a201=(a051*a201);
  a011=(a011+a201);
  a011=(a053*a011);
  a011=(a129*a011);
  a239=(a239-a011);
  a011=(a059*a239);
  a032=(a032+a011);
  a064=(a064*a016);
  a064=(a184-a064);
  a201=(a146*a064);
  a056=(a056*a016);
  a056=(a056+a189);
  a135=(a140*a056);
  a237=(a033*a237);
  a237=(a018*a237);
  a144=(a144*a016);
  a144=(a237-a144);
  a060=(a143*a144);
  a135=(a135+a060);
  a201=(a201-a135);
  a005=(a005*a016);
  a005=(a223-a005);
  a135=(a149*a005);
  a035=(a035*a016);
  a184=(a184-a035);
  a035=(a152*a184);
  a135=(a135+a035);
  a014=(a014*a016);
  a035=(a154*a014);
  a135=(a135+a035);
  a035=(a148*a135);
  a201=(a201+a035);
  a005=(a157*a005);
  a184=(a158*a184);
  a005=(a005+a184);
  a014=(a153*a014);
  a005=(a005+a014);
  a014=(a156*a005);
  a201=(a201+a014);
  a201=(a139*a201);
  a236=(a155*a236);
  a201=(a201-a236);
  a201=(a034*a201);
  a032=(a032+a201);
  a032=(a032/a000);
  if (res[1]!=0) res[1][18]=a032;
  a185=(a063*a185);
  a032=(a037*a028);
  a032=(a185+a032);
  a201=(a042*a221);
  a032=(a032+a201);
  a236=(a047*a239);
  a236=(a236-a126);
  a032=(a032+a236);
  a135=(a159*a135);
  a045=(a045*a016);
  a189=(a189-a045);
  a045=(a143*a189);
  a017=(a017*a016);
  a237=(a237-a017);
  a017=(a140*a237);
  a045=(a045-a017);
  a067=(a067*a016);
  a223=(a223-a067);
  a067=(a146*a223);
  a045=(a045+a067);
  a135=(a135-a045);
  a005=(a148*a005);
  a135=(a135+a005);
  a135=(a139*a135);
  a225=(a155*a225);
  a135=(a135-a225);
  a135=(a034*a135);
  a032=(a032+a135);
  a032=(a032/a000);
  if (res[1]!=0) res[1][19]=a032;
  a063=(a063*a030);
  a030=(a062*a028);
  a063=(a063+a030);
  a030=(a066*a221);
  a030=(a218+a030);
  a030=(a063+a030);
  a032=(a069*a239);
  a032=(a209+a032);
  a030=(a030+a032);
  a032=(a158*a189);
  a135=(a157*a237);
  a032=(a032-a135);
  a135=(a153*a223);
  a032=(a032+a135);
  a032=(a159*a032);
  a135=(a154*a064);
  a225=(a149*a056);
  a005=(a152*a144);
  a225=(a225+a005);
  a135=(a135-a225);
  a135=(a156*a135);
  a032=(a032+a135);
  a189=(a152*a189);
  a237=(a149*a237);
  a189=(a189-a237);
  a223=(a154*a223);
  a189=(a189+a223);
  a189=(a160*a189);
  a032=(a032+a189);
  a064=(a153*a064);
  a056=(a157*a056);
  a144=(a158*a144);
  a056=(a056+a144);
  a064=(a064-a056);
  a064=(a160*a064);
  a032=(a032+a064);
  a032=(a139*a032);
  a022=(a155*a022);
  a032=(a032-a022);
  a032=(a034*a032);
  a030=(a030+a032);
  a030=(a030/a000);
  if (res[1]!=0) res[1][20]=a030;
  a196=(a053*a196);
  a245=(a161*a245);
  a196=(a196+a245);
  a245=(a102*a196);
  a199=(a199+a245);
  a199=(a053*a199);
  a199=(a163*a199);
  a026=(a026-a199);
  a199=(a024*a196);
  a134=(a134+a199);
  a199=(a053*a134);
  a245=(a073*a199);
  a026=(a026-a245);
  a196=(a093*a196);
  a196=(a196-a215);
  a215=(a053*a196);
  a245=(a071*a215);
  a026=(a026-a245);
  a015=(a053*a015);
  a019=(a161*a019);
  a015=(a015+a019);
  a019=(a102*a015);
  a211=(a211+a019);
  a019=(a053*a211);
  a245=(a073*a019);
  a026=(a026-a245);
  a245=(a093*a015);
  a245=(a245-a006);
  a006=(a033*a245);
  a026=(a026-a006);
  a202=(a053*a202);
  a206=(a161*a206);
  a202=(a202+a206);
  a206=(a102*a202);
  a216=(a216+a206);
  a206=(a053*a216);
  a006=(a071*a206);
  a026=(a026-a006);
  a006=(a024*a202);
  a117=(a117+a006);
  a006=(a033*a117);
  a026=(a026+a006);
  a006=(a097*a026);
  a220=(a220+a006);
  a199=(a076*a199);
  a217=(a217-a199);
  a196=(a033*a196);
  a217=(a217+a196);
  a019=(a076*a019);
  a217=(a217-a019);
  a015=(a024*a015);
  a178=(a178+a015);
  a178=(a053*a178);
  a178=(a166*a178);
  a217=(a217-a178);
  a245=(a053*a245);
  a178=(a071*a245);
  a217=(a217-a178);
  a216=(a033*a216);
  a217=(a217-a216);
  a117=(a053*a117);
  a216=(a071*a117);
  a217=(a217-a216);
  a216=(a100*a217);
  a220=(a220+a216);
  a134=(a033*a134);
  a186=(a186-a134);
  a215=(a076*a215);
  a186=(a186-a215);
  a211=(a033*a211);
  a186=(a186+a211);
  a245=(a073*a245);
  a186=(a186-a245);
  a206=(a076*a206);
  a186=(a186-a206);
  a117=(a073*a117);
  a186=(a186-a117);
  a202=(a093*a202);
  a202=(a202-a219);
  a202=(a053*a202);
  a202=(a123*a202);
  a186=(a186-a202);
  a202=(a101*a186);
  a220=(a220+a202);
  a220=(a220/a000);
  if (res[1]!=0) res[1][21]=a220;
  a220=(a085*a026);
  a220=(a220-a081);
  a081=(a086*a217);
  a220=(a220+a081);
  a219=(a089*a186);
  a220=(a220+a219);
  a220=(a220/a000);
  if (res[1]!=0) res[1][22]=a220;
  a220=(a104*a026);
  a224=(a220-a224);
  a219=(a107*a217);
  a224=(a224+a219);
  a219=(a110*a186);
  a224=(a224+a219);
  a224=(a224/a000);
  if (res[1]!=0) res[1][23]=a224;
  a181=(a038*a181);
  a181=(a181-a213);
  a213=(a096*a026);
  a181=(a181+a213);
  a213=(a099*a217);
  a181=(a181+a213);
  a181=(a181+a202);
  a202=(a007*a028);
  a212=(a212+a202);
  a181=(a181+a212);
  a212=(a057*a221);
  a212=(a212-a179);
  a181=(a181+a212);
  a181=(a181+a011);
  a181=(-a181);
  if (res[1]!=0) res[1][24]=a181;
  a207=(a038*a207);
  a207=(a207+a193);
  a026=(a084*a026);
  a207=(a207+a026);
  a207=(a207+a081);
  a081=(a088*a186);
  a207=(a207+a081);
  a028=(a036*a028);
  a185=(a185+a028);
  a207=(a207+a185);
  a207=(a207+a201);
  a201=(a046*a239);
  a126=(a126+a201);
  a207=(a207+a126);
  a207=(-a207);
  if (res[1]!=0) res[1][25]=a207;
  a207=(2.*a074);
  a208=(a207*a208);
  a208=(a053*a208);
  a208=(a038*a208);
  a208=(a208+a203);
  a208=(a208+a136);
  a208=(a208+a220);
  a217=(a106*a217);
  a208=(a208+a217);
  a186=(a109*a186);
  a208=(a208+a186);
  a208=(a208+a063);
  a221=(a065*a221);
  a218=(a218+a221);
  a208=(a208+a218);
  a239=(a068*a239);
  a209=(a209+a239);
  a208=(a208+a209);
  a208=(-a208);
  if (res[1]!=0) res[1][26]=a208;
  a208=(a023*a027);
  a209=(-a208);
  a209=(2.*a209);
  a239=(a020*a209);
  a218=9.2820323027550877e-01;
  a221=(a218*a018);
  a063=(a054*a221);
  a063=(a063/a034);
  a186=(a050*a063);
  a239=(a239-a186);
  a186=(a218*a050);
  a186=(a061*a186);
  a186=(a186/a034);
  a217=(a018*a186);
  a239=(a239+a217);
  a217=(a013*a239);
  a220=(a078*a034);
  a075=(a078/a075);
  a136=(a123*a000);
  a203=(a075*a136);
  a126=(a079*a203);
  a126=(a220-a126);
  a201=(a031*a126);
  a185=(a001*a126);
  a028=(a008*a203);
  a081=(a021*a083);
  a026=(a082*a203);
  a193=(a003*a026);
  a193=(a081-a193);
  a028=(a028+a193);
  a185=(a185-a028);
  a028=(2.*a185);
  a028=(a034*a028);
  a028=(a028-a183);
  a193=(a073*a000);
  a181=(a053*a193);
  a011=(a049*a181);
  a028=(a028-a011);
  a028=(a028/a034);
  a011=(a080*a028);
  a201=(a201+a011);
  a011=(a021*a078);
  a212=(a003*a203);
  a212=(a011-a212);
  a179=(a008*a026);
  a212=(a212-a179);
  a179=(a091*a203);
  a202=(a001*a179);
  a212=(a212+a202);
  a202=(2.*a212);
  a202=(a054*a202);
  a213=(a076*a000);
  a224=(a053*a213);
  a219=(a039*a224);
  a202=(a202-a219);
  a117=(a044*a181);
  a202=(a202-a117);
  a206=(a053*a136);
  a245=(a049*a206);
  a202=(a202-a245);
  a202=(a202/a034);
  a245=(a092*a202);
  a211=(a094*a179);
  a245=(a245-a211);
  a201=(a201-a245);
  a245=(a021*a092);
  a211=(a003*a179);
  a211=(a245-a211);
  a215=(a008*a126);
  a211=(a211-a215);
  a215=(a001*a203);
  a211=(a211-a215);
  a215=(2.*a211);
  a215=(a061*a215);
  a215=(a215+a197);
  a134=(a049*a224);
  a215=(a215-a134);
  a215=(a215/a034);
  a134=(a078*a215);
  a216=(a103*a203);
  a134=(a134-a216);
  a201=(a201+a134);
  a134=(a070*a201);
  a217=(a217+a134);
  a134=(a023*a050);
  a216=(a114*a134);
  a239=(a113*a239);
  a201=(a013*a201);
  a239=(a239+a201);
  a201=(a000*a239);
  a178=(a112*a201);
  a015=(a000*a217);
  a019=(a053*a015);
  a178=(a178+a019);
  a019=(a055*a178);
  a019=(a216+a019);
  a019=(a053*a019);
  a019=(a111*a019);
  a217=(a217-a019);
  a019=(a025*a178);
  a196=(a114*a208);
  a019=(a019-a196);
  a199=(a053*a019);
  a006=(a009*a199);
  a217=(a217-a006);
  a006=(a023*a018);
  a030=(a114*a006);
  a178=(a051*a178);
  a178=(a030+a178);
  a032=(a053*a178);
  a022=(a004*a032);
  a217=(a217-a022);
  a022=(a125*a134);
  a064=(a027*a063);
  a056=(a018*a209);
  a064=(a064+a056);
  a056=(a020*a186);
  a064=(a064-a056);
  a056=(a113*a064);
  a144=(a083*a202);
  a189=(a094*a026);
  a144=(a144-a189);
  a189=(a078*a028);
  a223=(a031*a203);
  a189=(a189-a223);
  a144=(a144+a189);
  a126=(a103*a126);
  a189=(a080*a215);
  a126=(a126+a189);
  a144=(a144-a126);
  a126=(a013*a144);
  a056=(a056+a126);
  a126=(a000*a056);
  a189=(a112*a126);
  a064=(a013*a064);
  a144=(a070*a144);
  a064=(a064+a144);
  a144=(a000*a064);
  a223=(a053*a144);
  a189=(a189+a223);
  a223=(a055*a189);
  a223=(a022+a223);
  a237=(a053*a223);
  a135=(a009*a237);
  a217=(a217-a135);
  a135=(a125*a006);
  a225=(a051*a189);
  a225=(a135+a225);
  a005=(a033*a225);
  a217=(a217-a005);
  a005=(a133*a134);
  a063=(a018*a063);
  a209=(a027*a209);
  a063=(a063-a209);
  a186=(a050*a186);
  a063=(a063+a186);
  a186=(a113*a063);
  a202=(a078*a202);
  a209=(a094*a203);
  a202=(a202-a209);
  a028=(a083*a028);
  a026=(a031*a026);
  a028=(a028-a026);
  a202=(a202-a028);
  a215=(a092*a215);
  a179=(a103*a179);
  a215=(a215-a179);
  a202=(a202+a215);
  a215=(a013*a202);
  a186=(a186+a215);
  a215=(a000*a186);
  a179=(a112*a215);
  a063=(a013*a063);
  a202=(a070*a202);
  a063=(a063+a202);
  a202=(a000*a063);
  a028=(a053*a202);
  a179=(a179+a028);
  a028=(a055*a179);
  a028=(a005+a028);
  a026=(a053*a028);
  a209=(a004*a026);
  a217=(a217-a209);
  a209=(a025*a179);
  a045=(a133*a208);
  a209=(a209-a045);
  a067=(a033*a209);
  a217=(a217+a067);
  a067=(a012*a217);
  a178=(a033*a178);
  a199=(a002*a199);
  a178=(a178-a199);
  a178=(a178+a064);
  a237=(a002*a237);
  a178=(a178-a237);
  a189=(a025*a189);
  a237=(a125*a208);
  a189=(a189-a237);
  a189=(a053*a189);
  a189=(a121*a189);
  a178=(a178-a189);
  a225=(a053*a225);
  a189=(a004*a225);
  a178=(a178-a189);
  a028=(a033*a028);
  a178=(a178-a028);
  a209=(a053*a209);
  a028=(a004*a209);
  a178=(a178-a028);
  a028=(a058*a178);
  a067=(a067+a028);
  a223=(a033*a223);
  a019=(a033*a019);
  a032=(a002*a032);
  a019=(a019+a032);
  a223=(a223-a019);
  a225=(a009*a225);
  a223=(a223-a225);
  a223=(a223+a063);
  a026=(a002*a026);
  a223=(a223-a026);
  a209=(a009*a209);
  a223=(a223-a209);
  a209=(a133*a006);
  a179=(a051*a179);
  a179=(a209+a179);
  a179=(a053*a179);
  a179=(a129*a179);
  a223=(a223-a179);
  a179=(a059*a223);
  a067=(a067+a179);
  a006=(a155*a006);
  a006=(a034*a006);
  a067=(a067-a006);
  a067=(a067/a000);
  if (res[1]!=0) res[1][27]=a067;
  a067=(a037*a217);
  a026=(a042*a178);
  a067=(a067+a026);
  a063=(a047*a223);
  a067=(a067+a063);
  a208=(a155*a208);
  a208=(a034*a208);
  a067=(a067+a208);
  a067=(a067/a000);
  if (res[1]!=0) res[1][28]=a067;
  a067=(a062*a217);
  a063=(a066*a178);
  a063=(a067+a063);
  a225=(a069*a223);
  a063=(a063+a225);
  a225=(a155*a134);
  a225=(a034*a225);
  a063=(a063-a225);
  a063=(a063/a000);
  if (res[1]!=0) res[1][29]=a063;
  a193=(a033*a193);
  a193=(a078*a193);
  a063=(a098*a203);
  a063=(a193-a063);
  a019=(a140*a063);
  a136=(a033*a136);
  a136=(a078*a136);
  a032=(a141*a203);
  a032=(a136-a032);
  a028=(a143*a032);
  a019=(a019-a028);
  a028=(a078*a000);
  a189=(a105*a203);
  a189=(a028-a189);
  a064=(a146*a189);
  a019=(a019+a064);
  a213=(a033*a213);
  a213=(a078*a213);
  a064=(a095*a203);
  a064=(a213-a064);
  a199=(a149*a064);
  a016=(a029*a203);
  a016=(a016+a028);
  a017=(a152*a016);
  a199=(a199-a017);
  a017=(a072*a203);
  a136=(a136-a017);
  a017=(a154*a136);
  a199=(a199-a017);
  a017=(a148*a199);
  a019=(a019+a017);
  a064=(a157*a064);
  a016=(a158*a016);
  a064=(a064-a016);
  a136=(a153*a136);
  a064=(a064-a136);
  a136=(a156*a064);
  a019=(a019+a136);
  a019=(a139*a019);
  a136=(a155*a212);
  a019=(a019-a136);
  a019=(a034*a019);
  a136=(a040*a224);
  a016=(a090*a211);
  a201=(a053*a201);
  a015=(a161*a015);
  a201=(a201+a015);
  a015=(a102*a201);
  a016=(a016+a015);
  a016=(a053*a016);
  a016=(a163*a016);
  a239=(a239-a016);
  a016=(a090*a185);
  a015=(a024*a201);
  a016=(a016+a015);
  a015=(a053*a016);
  a017=(a073*a015);
  a239=(a239-a017);
  a167=(a167*a000);
  a017=(a090*a212);
  a201=(a093*a201);
  a017=(a017+a201);
  a201=(a053*a017);
  a236=(a071*a201);
  a236=(a167+a236);
  a239=(a239-a236);
  a236=(a124*a211);
  a126=(a053*a126);
  a144=(a161*a144);
  a126=(a126+a144);
  a144=(a102*a126);
  a236=(a236+a144);
  a144=(a053*a236);
  a014=(a073*a144);
  a239=(a239-a014);
  a014=(a124*a212);
  a184=(a093*a126);
  a014=(a014+a184);
  a184=(a033*a014);
  a239=(a239-a184);
  a170=(a170*a000);
  a184=(a132*a211);
  a215=(a053*a215);
  a202=(a161*a202);
  a215=(a215+a202);
  a202=(a102*a215);
  a184=(a184+a202);
  a202=(a053*a184);
  a035=(a071*a202);
  a035=(a170+a035);
  a239=(a239-a035);
  a035=(a132*a185);
  a060=(a024*a215);
  a035=(a035+a060);
  a060=(a033*a035);
  a239=(a239+a060);
  a060=(a097*a239);
  a060=(a136+a060);
  a019=(a019+a060);
  a060=(a122*a181);
  a015=(a076*a015);
  a056=(a056-a015);
  a017=(a033*a017);
  a056=(a056+a017);
  a144=(a076*a144);
  a056=(a056-a144);
  a144=(a124*a185);
  a126=(a024*a126);
  a144=(a144+a126);
  a144=(a053*a144);
  a144=(a166*a144);
  a056=(a056-a144);
  a169=(a169*a000);
  a014=(a053*a014);
  a144=(a071*a014);
  a144=(a169+a144);
  a056=(a056-a144);
  a184=(a033*a184);
  a056=(a056-a184);
  a171=(a171*a000);
  a035=(a053*a035);
  a184=(a071*a035);
  a184=(a171+a184);
  a056=(a056-a184);
  a184=(a100*a056);
  a184=(a060+a184);
  a019=(a019+a184);
  a206=(a130*a206);
  a016=(a033*a016);
  a186=(a186-a016);
  a201=(a076*a201);
  a186=(a186-a201);
  a236=(a033*a236);
  a186=(a186+a236);
  a014=(a073*a014);
  a186=(a186-a014);
  a202=(a076*a202);
  a186=(a186-a202);
  a035=(a073*a035);
  a186=(a186-a035);
  a164=(a164*a180);
  a212=(a132*a212);
  a215=(a093*a215);
  a212=(a212+a215);
  a212=(a053*a212);
  a212=(a123*a212);
  a164=(a164+a212);
  a186=(a186-a164);
  a164=(a101*a186);
  a206=(a206+a164);
  a019=(a019+a206);
  a019=(a019/a000);
  if (res[1]!=0) res[1][30]=a019;
  a199=(a159*a199);
  a019=(a077*a203);
  a164=(a140*a019);
  a212=(a087*a203);
  a212=(a193-a212);
  a215=(a143*a212);
  a164=(a164+a215);
  a203=(a108*a203);
  a203=(a213-a203);
  a215=(a146*a203);
  a164=(a164+a215);
  a199=(a199-a164);
  a064=(a148*a064);
  a199=(a199+a064);
  a199=(a139*a199);
  a185=(a155*a185);
  a199=(a199-a185);
  a199=(a034*a199);
  a185=(a040*a034);
  a064=(a085*a239);
  a064=(a185+a064);
  a199=(a199+a064);
  a064=(a086*a056);
  a199=(a199+a064);
  a164=(a130*a181);
  a215=(a089*a186);
  a215=(a164+a215);
  a199=(a199+a215);
  a199=(a199/a000);
  if (res[1]!=0) res[1][31]=a199;
  a199=(a157*a019);
  a215=(a158*a212);
  a199=(a199+a215);
  a215=(a153*a203);
  a199=(a199+a215);
  a199=(a159*a199);
  a215=(a149*a063);
  a035=(a152*a032);
  a215=(a215-a035);
  a035=(a154*a189);
  a215=(a215+a035);
  a215=(a156*a215);
  a199=(a199+a215);
  a019=(a149*a019);
  a212=(a152*a212);
  a019=(a019+a212);
  a203=(a154*a203);
  a019=(a019+a203);
  a019=(a160*a019);
  a199=(a199+a019);
  a063=(a157*a063);
  a032=(a158*a032);
  a063=(a063-a032);
  a189=(a153*a189);
  a063=(a063+a189);
  a063=(a160*a063);
  a199=(a199+a063);
  a199=(a139*a199);
  a211=(a155*a211);
  a199=(a199-a211);
  a199=(a034*a199);
  a211=(a104*a239);
  a199=(a199+a211);
  a063=(a107*a056);
  a189=(a122*a034);
  a063=(a063-a189);
  a199=(a199+a063);
  a063=(a130*a224);
  a032=(a110*a186);
  a032=(a063+a032);
  a199=(a199+a032);
  a199=(a199/a000);
  if (res[1]!=0) res[1][32]=a199;
  a199=1.7320508075688774e+00;
  a199=(a199*a000);
  a074=(a074*a199);
  a074=(a053*a074);
  a032=(a038*a074);
  a145=(a145*a199);
  a145=(a053*a145);
  a019=(a043*a145);
  a203=(a032+a019);
  a200=(a200*a199);
  a200=(a053*a200);
  a200=(a048*a200);
  a203=(a203+a200);
  a200=(a096*a239);
  a200=(a136+a200);
  a203=(a203+a200);
  a200=(a099*a056);
  a200=(a060+a200);
  a203=(a203+a200);
  a203=(a203+a206);
  a206=(a007*a217);
  a203=(a203+a206);
  a206=(a057*a178);
  a203=(a203+a206);
  a203=(a203+a179);
  a203=(-a203);
  if (res[1]!=0) res[1][33]=a203;
  a203=(a048*a145);
  a179=8.6602540378443871e-01;
  a179=(a179*a000);
  a206=(a038*a179);
  a203=(a203-a206);
  a239=(a084*a239);
  a239=(a239-a185);
  a203=(a203+a239);
  a203=(a203+a064);
  a064=(a088*a186);
  a164=(a164+a064);
  a203=(a203+a164);
  a217=(a036*a217);
  a203=(a203+a217);
  a203=(a203+a026);
  a026=(a046*a223);
  a203=(a203+a026);
  a203=(-a203);
  if (res[1]!=0) res[1][34]=a203;
  a203=(a043*a179);
  a026=(a048*a074);
  a026=(a203+a026);
  a026=(a026+a211);
  a056=(a106*a056);
  a056=(a189+a056);
  a026=(a026+a056);
  a186=(a109*a186);
  a063=(a063+a186);
  a026=(a026+a063);
  a026=(a026+a067);
  a178=(a065*a178);
  a026=(a026+a178);
  a223=(a068*a223);
  a026=(a026+a223);
  a026=(-a026);
  if (res[1]!=0) res[1][35]=a026;
  a026=(a020*a221);
  a223=(a218*a027);
  a223=(a054*a223);
  a223=(a223/a034);
  a178=(a050*a223);
  a026=(a026-a178);
  a023=(a023*a020);
  a178=(-a023);
  a178=(2.*a178);
  a178=(a061*a178);
  a178=(a178/a034);
  a067=(a018*a178);
  a026=(a026+a067);
  a067=(a013*a026);
  a063=(a166*a000);
  a186=(a075*a063);
  a056=(a008*a186);
  a056=(a011-a056);
  a211=(a082*a186);
  a217=(a003*a211);
  a056=(a056+a217);
  a217=(a079*a186);
  a164=(a001*a217);
  a056=(a056-a164);
  a164=(2.*a056);
  a164=(a034*a164);
  a164=(a164-a219);
  a219=(a053*a063);
  a064=(a044*a219);
  a164=(a164-a064);
  a064=(a071*a000);
  a239=(a053*a064);
  a049=(a049*a239);
  a164=(a164-a049);
  a164=(a164/a034);
  a200=(a080*a164);
  a212=(a031*a217);
  a200=(a200-a212);
  a212=(a091*a186);
  a212=(a220-a212);
  a215=(a094*a212);
  a035=(a008*a211);
  a081=(a081-a035);
  a035=(a003*a186);
  a081=(a081-a035);
  a035=(a001*a212);
  a081=(a081-a035);
  a035=(2.*a081);
  a035=(a054*a035);
  a035=(a035+a183);
  a183=(a044*a239);
  a035=(a035-a183);
  a035=(a035/a034);
  a183=(a092*a035);
  a215=(a215+a183);
  a200=(a200-a215);
  a215=(a003*a212);
  a021=(a021*a080);
  a183=(a008*a217);
  a183=(a021-a183);
  a215=(a215-a183);
  a183=(a001*a186);
  a215=(a215-a183);
  a183=(2.*a215);
  a183=(a061*a183);
  a044=(a044*a224);
  a183=(a183-a044);
  a183=(a183-a228);
  a183=(a183/a034);
  a044=(a078*a183);
  a202=(a103*a186);
  a044=(a044-a202);
  a200=(a200+a044);
  a044=(a070*a200);
  a067=(a067+a044);
  a026=(a113*a026);
  a200=(a013*a200);
  a026=(a026+a200);
  a200=(a000*a026);
  a044=(a112*a200);
  a202=(a000*a067);
  a014=(a053*a202);
  a044=(a044+a014);
  a014=(a055*a044);
  a114=(a114*a023);
  a014=(a014-a114);
  a014=(a053*a014);
  a014=(a111*a014);
  a067=(a067-a014);
  a014=(a025*a044);
  a014=(a030+a014);
  a236=(a053*a014);
  a201=(a009*a236);
  a067=(a067-a201);
  a044=(a051*a044);
  a196=(a196+a044);
  a044=(a053*a196);
  a201=(a004*a044);
  a067=(a067-a201);
  a201=(a027*a223);
  a016=(a018*a221);
  a201=(a201+a016);
  a016=(a020*a178);
  a201=(a201-a016);
  a016=(a113*a201);
  a184=(a083*a035);
  a144=(a094*a211);
  a184=(a184-a144);
  a144=(a078*a164);
  a126=(a031*a186);
  a144=(a144-a126);
  a184=(a184+a144);
  a144=(a080*a183);
  a217=(a103*a217);
  a144=(a144-a217);
  a184=(a184-a144);
  a144=(a013*a184);
  a016=(a016+a144);
  a144=(a000*a016);
  a217=(a112*a144);
  a201=(a013*a201);
  a184=(a070*a184);
  a201=(a201+a184);
  a184=(a000*a201);
  a126=(a053*a184);
  a217=(a217+a126);
  a126=(a055*a217);
  a125=(a125*a023);
  a126=(a126-a125);
  a017=(a053*a126);
  a015=(a009*a017);
  a067=(a067-a015);
  a015=(a051*a217);
  a237=(a237+a015);
  a015=(a033*a237);
  a067=(a067-a015);
  a223=(a018*a223);
  a015=(a027*a221);
  a223=(a223-a015);
  a178=(a050*a178);
  a223=(a223+a178);
  a178=(a113*a223);
  a035=(a078*a035);
  a015=(a094*a186);
  a035=(a035-a015);
  a164=(a083*a164);
  a211=(a031*a211);
  a164=(a164-a211);
  a035=(a035-a164);
  a212=(a103*a212);
  a183=(a092*a183);
  a212=(a212+a183);
  a035=(a035+a212);
  a212=(a013*a035);
  a178=(a178+a212);
  a212=(a000*a178);
  a183=(a112*a212);
  a223=(a013*a223);
  a035=(a070*a035);
  a223=(a223+a035);
  a035=(a000*a223);
  a164=(a053*a035);
  a183=(a183+a164);
  a164=(a055*a183);
  a133=(a133*a023);
  a164=(a164-a133);
  a211=(a053*a164);
  a015=(a004*a211);
  a067=(a067-a015);
  a015=(a025*a183);
  a015=(a209+a015);
  a192=(a033*a015);
  a067=(a067+a192);
  a192=(a012*a067);
  a196=(a033*a196);
  a236=(a002*a236);
  a196=(a196-a236);
  a196=(a196+a201);
  a017=(a002*a017);
  a196=(a196-a017);
  a217=(a025*a217);
  a217=(a135+a217);
  a217=(a053*a217);
  a217=(a121*a217);
  a196=(a196-a217);
  a237=(a053*a237);
  a217=(a004*a237);
  a196=(a196-a217);
  a164=(a033*a164);
  a196=(a196-a164);
  a015=(a053*a015);
  a164=(a004*a015);
  a196=(a196-a164);
  a164=(a058*a196);
  a192=(a192+a164);
  a126=(a033*a126);
  a014=(a033*a014);
  a044=(a002*a044);
  a014=(a014+a044);
  a126=(a126-a014);
  a237=(a009*a237);
  a126=(a126-a237);
  a126=(a126+a223);
  a211=(a002*a211);
  a126=(a126-a211);
  a015=(a009*a015);
  a126=(a126-a015);
  a183=(a051*a183);
  a045=(a045+a183);
  a045=(a053*a045);
  a045=(a129*a045);
  a126=(a126-a045);
  a045=(a059*a126);
  a192=(a192+a045);
  a192=(a192-a208);
  a192=(a192/a000);
  if (res[1]!=0) res[1][36]=a192;
  a192=(a037*a067);
  a208=(a042*a196);
  a192=(a192+a208);
  a183=(a047*a126);
  a192=(a192+a183);
  a192=(a192-a006);
  a192=(a192/a000);
  if (res[1]!=0) res[1][37]=a192;
  a192=(a062*a067);
  a183=(a066*a196);
  a183=(a192+a183);
  a015=(a069*a126);
  a183=(a183+a015);
  a023=(a155*a023);
  a023=(a034*a023);
  a183=(a183+a023);
  a183=(a183/a000);
  if (res[1]!=0) res[1][38]=a183;
  a064=(a033*a064);
  a064=(a078*a064);
  a183=(a098*a186);
  a183=(a064-a183);
  a015=(a140*a183);
  a211=(a141*a186);
  a223=(a143*a211);
  a015=(a015+a223);
  a223=(a105*a186);
  a223=(a213-a223);
  a237=(a146*a223);
  a015=(a015+a237);
  a237=(a095*a186);
  a237=(a028-a237);
  a014=(a149*a237);
  a044=(a029*a186);
  a213=(a213-a044);
  a044=(a152*a213);
  a014=(a014+a044);
  a063=(a033*a063);
  a063=(a078*a063);
  a044=(a072*a186);
  a044=(a063-a044);
  a164=(a154*a044);
  a014=(a014-a164);
  a164=(a148*a014);
  a015=(a015+a164);
  a237=(a157*a237);
  a213=(a158*a213);
  a237=(a237+a213);
  a044=(a153*a044);
  a237=(a237-a044);
  a044=(a156*a237);
  a015=(a015+a044);
  a015=(a139*a015);
  a044=(a155*a081);
  a015=(a015-a044);
  a015=(a034*a015);
  a044=(a090*a215);
  a200=(a053*a200);
  a202=(a161*a202);
  a200=(a200+a202);
  a202=(a102*a200);
  a044=(a044+a202);
  a044=(a053*a044);
  a044=(a163*a044);
  a026=(a026-a044);
  a165=(a165*a000);
  a044=(a090*a056);
  a202=(a024*a200);
  a044=(a044+a202);
  a202=(a053*a044);
  a213=(a073*a202);
  a213=(a165+a213);
  a026=(a026-a213);
  a213=(a090*a081);
  a200=(a093*a200);
  a213=(a213+a200);
  a200=(a053*a213);
  a164=(a071*a200);
  a026=(a026-a164);
  a168=(a168*a000);
  a164=(a124*a215);
  a144=(a053*a144);
  a184=(a161*a184);
  a144=(a144+a184);
  a184=(a102*a144);
  a164=(a164+a184);
  a184=(a053*a164);
  a217=(a073*a184);
  a217=(a168+a217);
  a026=(a026-a217);
  a217=(a124*a081);
  a017=(a093*a144);
  a217=(a217+a017);
  a017=(a033*a217);
  a026=(a026-a017);
  a017=(a132*a215);
  a212=(a053*a212);
  a035=(a161*a035);
  a212=(a212+a035);
  a035=(a102*a212);
  a017=(a017+a035);
  a035=(a053*a017);
  a201=(a071*a035);
  a026=(a026-a201);
  a201=(a132*a056);
  a236=(a024*a212);
  a201=(a201+a236);
  a236=(a033*a201);
  a026=(a026+a236);
  a236=(a097*a026);
  a236=(a236-a185);
  a015=(a015+a236);
  a236=(a122*a239);
  a202=(a076*a202);
  a016=(a016-a202);
  a213=(a033*a213);
  a016=(a016+a213);
  a184=(a076*a184);
  a016=(a016-a184);
  a172=(a172*a180);
  a184=(a124*a056);
  a144=(a024*a144);
  a184=(a184+a144);
  a184=(a053*a184);
  a184=(a166*a184);
  a172=(a172+a184);
  a016=(a016-a172);
  a217=(a053*a217);
  a172=(a071*a217);
  a016=(a016-a172);
  a017=(a033*a017);
  a016=(a016-a017);
  a201=(a053*a201);
  a017=(a071*a201);
  a016=(a016-a017);
  a017=(a100*a016);
  a017=(a236+a017);
  a015=(a015+a017);
  a044=(a033*a044);
  a178=(a178-a044);
  a200=(a076*a200);
  a178=(a178-a200);
  a164=(a033*a164);
  a178=(a178+a164);
  a217=(a073*a217);
  a169=(a169+a217);
  a178=(a178-a169);
  a035=(a076*a035);
  a178=(a178-a035);
  a201=(a073*a201);
  a171=(a171+a201);
  a178=(a178-a171);
  a081=(a132*a081);
  a212=(a093*a212);
  a081=(a081+a212);
  a081=(a053*a081);
  a081=(a123*a081);
  a178=(a178-a081);
  a081=(a101*a178);
  a015=(a015+a081);
  a015=(a015/a000);
  if (res[1]!=0) res[1][39]=a015;
  a014=(a159*a014);
  a015=(a087*a186);
  a015=(a064-a015);
  a212=(a143*a015);
  a171=(a077*a186);
  a063=(a063-a171);
  a171=(a140*a063);
  a212=(a212-a171);
  a186=(a108*a186);
  a186=(a186+a028);
  a171=(a146*a186);
  a212=(a212-a171);
  a014=(a014-a212);
  a237=(a148*a237);
  a014=(a014+a237);
  a014=(a139*a014);
  a056=(a155*a056);
  a014=(a014-a056);
  a014=(a034*a014);
  a056=(a085*a026);
  a056=(a136+a056);
  a014=(a014+a056);
  a219=(a122*a219);
  a056=(a086*a016);
  a219=(a219+a056);
  a014=(a014+a219);
  a056=(a130*a239);
  a237=(a089*a178);
  a237=(a056+a237);
  a014=(a014+a237);
  a014=(a014/a000);
  if (res[1]!=0) res[1][40]=a014;
  a014=(a158*a015);
  a237=(a157*a063);
  a014=(a014-a237);
  a237=(a153*a186);
  a014=(a014-a237);
  a014=(a159*a014);
  a237=(a149*a183);
  a212=(a152*a211);
  a237=(a237+a212);
  a212=(a154*a223);
  a237=(a237+a212);
  a237=(a156*a237);
  a014=(a014+a237);
  a015=(a152*a015);
  a063=(a149*a063);
  a015=(a015-a063);
  a186=(a154*a186);
  a015=(a015-a186);
  a015=(a160*a015);
  a014=(a014+a015);
  a183=(a157*a183);
  a211=(a158*a211);
  a183=(a183+a211);
  a223=(a153*a223);
  a183=(a183+a223);
  a183=(a160*a183);
  a014=(a014+a183);
  a014=(a139*a014);
  a215=(a155*a215);
  a014=(a014-a215);
  a014=(a034*a014);
  a215=(a104*a026);
  a014=(a014+a215);
  a122=(a122*a224);
  a224=(a107*a016);
  a224=(a122+a224);
  a014=(a014+a224);
  a130=(a130*a034);
  a224=(a110*a178);
  a224=(a130+a224);
  a014=(a014+a224);
  a014=(a014/a000);
  if (res[1]!=0) res[1][41]=a014;
  a174=(a174*a199);
  a174=(a053*a174);
  a014=(a043*a174);
  a206=(a206+a014);
  a014=(a096*a026);
  a185=(a185+a014);
  a206=(a206+a185);
  a185=(a099*a016);
  a236=(a236+a185);
  a206=(a206+a236);
  a206=(a206+a081);
  a081=(a007*a067);
  a206=(a206+a081);
  a081=(a057*a196);
  a206=(a206+a081);
  a206=(a206+a045);
  a206=(-a206);
  if (res[1]!=0) res[1][42]=a206;
  a204=(a204*a199);
  a204=(a053*a204);
  a204=(a043*a204);
  a032=(a032+a204);
  a204=(a048*a174);
  a032=(a032+a204);
  a026=(a084*a026);
  a136=(a136+a026);
  a032=(a032+a136);
  a032=(a032+a219);
  a219=(a088*a178);
  a219=(a056+a219);
  a032=(a032+a219);
  a067=(a036*a067);
  a032=(a032+a067);
  a032=(a032+a208);
  a208=(a046*a126);
  a032=(a032+a208);
  a032=(-a032);
  if (res[1]!=0) res[1][43]=a032;
  a043=(a043*a074);
  a048=(a048*a179);
  a043=(a043-a048);
  a043=(a043+a215);
  a016=(a106*a016);
  a122=(a122+a016);
  a043=(a043+a122);
  a178=(a109*a178);
  a178=(a178-a130);
  a043=(a043+a178);
  a043=(a043+a192);
  a196=(a065*a196);
  a043=(a043+a196);
  a126=(a068*a126);
  a043=(a043+a126);
  a043=(-a043);
  if (res[1]!=0) res[1][44]=a043;
  a218=(a218*a020);
  a043=(a020*a218);
  a134=(-a134);
  a134=(2.*a134);
  a134=(a054*a134);
  a134=(a134/a034);
  a126=(a050*a134);
  a043=(a043-a126);
  a221=(a061*a221);
  a221=(a221/a034);
  a126=(a018*a221);
  a043=(a043+a126);
  a126=(a013*a043);
  a196=(a163*a000);
  a075=(a075*a196);
  a079=(a079*a075);
  a192=(a001*a079);
  a021=(a021-a192);
  a192=(a008*a075);
  a082=(a082*a075);
  a220=(a220-a082);
  a082=(a003*a220);
  a192=(a192+a082);
  a021=(a021-a192);
  a192=(2.*a021);
  a192=(a034*a192);
  a082=(a039*a181);
  a192=(a192-a082);
  a192=(a192+a228);
  a192=(a192/a034);
  a228=(a080*a192);
  a082=(a031*a079);
  a228=(a228-a082);
  a082=(a008*a220);
  a178=(a003*a075);
  a082=(a082-a178);
  a091=(a091*a075);
  a178=(a001*a091);
  a245=(a245-a178);
  a082=(a082-a245);
  a245=(2.*a082);
  a054=(a054*a245);
  a245=(a039*a239);
  a054=(a054-a245);
  a054=(a054-a197);
  a054=(a054/a034);
  a197=(a092*a054);
  a245=(a094*a091);
  a197=(a197-a245);
  a228=(a228-a197);
  a008=(a008*a079);
  a003=(a003*a091);
  a008=(a008-a003);
  a001=(a001*a075);
  a011=(a011-a001);
  a008=(a008+a011);
  a011=(2.*a008);
  a061=(a061*a011);
  a011=(a053*a196);
  a039=(a039*a011);
  a061=(a061-a039);
  a061=(a061-a117);
  a061=(a061-a049);
  a061=(a061/a034);
  a049=(a078*a061);
  a117=(a103*a075);
  a049=(a049-a117);
  a228=(a228+a049);
  a049=(a070*a228);
  a126=(a126+a049);
  a043=(a113*a043);
  a228=(a013*a228);
  a043=(a043+a228);
  a228=(a000*a043);
  a049=(a112*a228);
  a117=(a000*a126);
  a039=(a053*a117);
  a049=(a049+a039);
  a039=(a055*a049);
  a030=(a030+a039);
  a030=(a053*a030);
  a030=(a111*a030);
  a126=(a126-a030);
  a030=(a025*a049);
  a114=(a114+a030);
  a030=(a053*a114);
  a039=(a009*a030);
  a126=(a126-a039);
  a049=(a051*a049);
  a049=(a049-a216);
  a216=(a053*a049);
  a039=(a004*a216);
  a126=(a126-a039);
  a039=(a027*a134);
  a001=(a018*a218);
  a039=(a039+a001);
  a001=(a020*a221);
  a039=(a039-a001);
  a001=(a113*a039);
  a003=(a094*a220);
  a197=(a083*a054);
  a003=(a003+a197);
  a197=(a078*a192);
  a245=(a031*a075);
  a197=(a197-a245);
  a003=(a003+a197);
  a197=(a080*a061);
  a079=(a103*a079);
  a197=(a197-a079);
  a003=(a003-a197);
  a197=(a013*a003);
  a001=(a001+a197);
  a197=(a000*a001);
  a079=(a112*a197);
  a039=(a013*a039);
  a003=(a070*a003);
  a039=(a039+a003);
  a003=(a000*a039);
  a245=(a053*a003);
  a079=(a079+a245);
  a245=(a055*a079);
  a135=(a135+a245);
  a245=(a053*a135);
  a178=(a009*a245);
  a126=(a126-a178);
  a178=(a051*a079);
  a178=(a178-a022);
  a022=(a033*a178);
  a126=(a126-a022);
  a134=(a018*a134);
  a218=(a027*a218);
  a134=(a134-a218);
  a221=(a050*a221);
  a134=(a134+a221);
  a221=(a113*a134);
  a054=(a078*a054);
  a094=(a094*a075);
  a054=(a054-a094);
  a031=(a031*a220);
  a192=(a083*a192);
  a031=(a031+a192);
  a054=(a054-a031);
  a061=(a092*a061);
  a103=(a103*a091);
  a061=(a061-a103);
  a054=(a054+a061);
  a061=(a013*a054);
  a221=(a221+a061);
  a061=(a000*a221);
  a103=(a112*a061);
  a134=(a013*a134);
  a054=(a070*a054);
  a134=(a134+a054);
  a054=(a000*a134);
  a091=(a053*a054);
  a103=(a103+a091);
  a091=(a055*a103);
  a209=(a209+a091);
  a091=(a053*a209);
  a031=(a004*a091);
  a126=(a126-a031);
  a031=(a025*a103);
  a133=(a133+a031);
  a031=(a033*a133);
  a126=(a126+a031);
  a031=(a012*a126);
  a049=(a033*a049);
  a030=(a002*a030);
  a049=(a049-a030);
  a049=(a049+a039);
  a245=(a002*a245);
  a049=(a049-a245);
  a079=(a025*a079);
  a125=(a125+a079);
  a125=(a053*a125);
  a125=(a121*a125);
  a049=(a049-a125);
  a178=(a053*a178);
  a125=(a004*a178);
  a049=(a049-a125);
  a209=(a033*a209);
  a049=(a049-a209);
  a133=(a053*a133);
  a209=(a004*a133);
  a049=(a049-a209);
  a209=(a058*a049);
  a031=(a031+a209);
  a135=(a033*a135);
  a114=(a033*a114);
  a216=(a002*a216);
  a114=(a114+a216);
  a135=(a135-a114);
  a178=(a009*a178);
  a135=(a135-a178);
  a135=(a135+a134);
  a091=(a002*a091);
  a135=(a135-a091);
  a133=(a009*a133);
  a135=(a135-a133);
  a103=(a051*a103);
  a103=(a103-a005);
  a103=(a053*a103);
  a103=(a129*a103);
  a135=(a135-a103);
  a103=(a059*a135);
  a031=(a031+a103);
  a031=(a031+a225);
  a031=(a031/a000);
  if (res[1]!=0) res[1][45]=a031;
  a031=(a037*a126);
  a225=(a042*a049);
  a031=(a031+a225);
  a005=(a047*a135);
  a031=(a031+a005);
  a031=(a031-a023);
  a031=(a031/a000);
  if (res[1]!=0) res[1][46]=a031;
  a031=(a062*a126);
  a023=(a066*a049);
  a023=(a031+a023);
  a005=(a069*a135);
  a023=(a023+a005);
  a023=(a023-a006);
  a023=(a023/a000);
  if (res[1]!=0) res[1][47]=a023;
  a105=(a105*a075);
  a105=(a193-a105);
  a023=(a146*a105);
  a098=(a098*a075);
  a098=(a098+a028);
  a006=(a140*a098);
  a196=(a033*a196);
  a196=(a078*a196);
  a141=(a141*a075);
  a141=(a196-a141);
  a005=(a143*a141);
  a006=(a006+a005);
  a023=(a023-a006);
  a095=(a095*a075);
  a095=(a064-a095);
  a006=(a149*a095);
  a029=(a029*a075);
  a193=(a193-a029);
  a029=(a152*a193);
  a006=(a006+a029);
  a072=(a072*a075);
  a029=(a154*a072);
  a006=(a006+a029);
  a029=(a148*a006);
  a023=(a023+a029);
  a095=(a157*a095);
  a193=(a158*a193);
  a095=(a095+a193);
  a072=(a153*a072);
  a095=(a095+a072);
  a072=(a156*a095);
  a023=(a023+a072);
  a023=(a139*a023);
  a072=(a155*a082);
  a023=(a023-a072);
  a023=(a034*a023);
  a239=(a040*a239);
  a115=(a115*a180);
  a180=(a090*a008);
  a228=(a053*a228);
  a117=(a161*a117);
  a228=(a228+a117);
  a117=(a102*a228);
  a180=(a180+a117);
  a180=(a053*a180);
  a180=(a163*a180);
  a115=(a115+a180);
  a043=(a043-a115);
  a115=(a090*a021);
  a180=(a024*a228);
  a115=(a115+a180);
  a180=(a053*a115);
  a117=(a073*a180);
  a043=(a043-a117);
  a090=(a090*a082);
  a228=(a093*a228);
  a090=(a090+a228);
  a228=(a053*a090);
  a117=(a071*a228);
  a043=(a043-a117);
  a117=(a124*a008);
  a197=(a053*a197);
  a003=(a161*a003);
  a197=(a197+a003);
  a003=(a102*a197);
  a117=(a117+a003);
  a003=(a053*a117);
  a072=(a073*a003);
  a043=(a043-a072);
  a072=(a124*a082);
  a193=(a093*a197);
  a072=(a072+a193);
  a193=(a033*a072);
  a043=(a043-a193);
  a193=(a132*a008);
  a061=(a053*a061);
  a054=(a161*a054);
  a061=(a061+a054);
  a054=(a102*a061);
  a193=(a193+a054);
  a054=(a053*a193);
  a029=(a071*a054);
  a043=(a043-a029);
  a029=(a132*a021);
  a005=(a024*a061);
  a029=(a029+a005);
  a005=(a033*a029);
  a043=(a043+a005);
  a005=(a097*a043);
  a005=(a239+a005);
  a023=(a023+a005);
  a180=(a076*a180);
  a165=(a165+a180);
  a001=(a001-a165);
  a090=(a033*a090);
  a001=(a001+a090);
  a003=(a076*a003);
  a168=(a168+a003);
  a001=(a001-a168);
  a124=(a124*a021);
  a197=(a024*a197);
  a124=(a124+a197);
  a124=(a053*a124);
  a124=(a166*a124);
  a001=(a001-a124);
  a072=(a053*a072);
  a124=(a071*a072);
  a001=(a001-a124);
  a193=(a033*a193);
  a001=(a001-a193);
  a029=(a053*a029);
  a193=(a071*a029);
  a001=(a001-a193);
  a193=(a100*a001);
  a193=(a189+a193);
  a023=(a023+a193);
  a115=(a033*a115);
  a221=(a221-a115);
  a228=(a076*a228);
  a167=(a167+a228);
  a221=(a221-a167);
  a117=(a033*a117);
  a221=(a221+a117);
  a072=(a073*a072);
  a221=(a221-a072);
  a054=(a076*a054);
  a170=(a170+a054);
  a221=(a221-a170);
  a029=(a073*a029);
  a221=(a221-a029);
  a132=(a132*a082);
  a061=(a093*a061);
  a132=(a132+a061);
  a132=(a053*a132);
  a132=(a123*a132);
  a221=(a221-a132);
  a132=(a101*a221);
  a023=(a023+a132);
  a023=(a023/a000);
  if (res[1]!=0) res[1][48]=a023;
  a006=(a159*a006);
  a087=(a087*a075);
  a028=(a028-a087);
  a143=(a143*a028);
  a077=(a077*a075);
  a196=(a196-a077);
  a140=(a140*a196);
  a143=(a143-a140);
  a108=(a108*a075);
  a064=(a064-a108);
  a146=(a146*a064);
  a143=(a143+a146);
  a006=(a006-a143);
  a148=(a148*a095);
  a006=(a006+a148);
  a006=(a139*a006);
  a021=(a155*a021);
  a006=(a006-a021);
  a006=(a034*a006);
  a181=(a040*a181);
  a021=(a085*a043);
  a021=(a181+a021);
  a006=(a006+a021);
  a021=(a086*a001);
  a006=(a006+a021);
  a148=(a089*a221);
  a148=(a148-a130);
  a006=(a006+a148);
  a006=(a006/a000);
  if (res[1]!=0) res[1][49]=a006;
  a006=(a158*a028);
  a148=(a157*a196);
  a006=(a006-a148);
  a148=(a153*a064);
  a006=(a006+a148);
  a159=(a159*a006);
  a006=(a154*a105);
  a148=(a149*a098);
  a095=(a152*a141);
  a148=(a148+a095);
  a006=(a006-a148);
  a156=(a156*a006);
  a159=(a159+a156);
  a152=(a152*a028);
  a149=(a149*a196);
  a152=(a152-a149);
  a154=(a154*a064);
  a152=(a152+a154);
  a152=(a160*a152);
  a159=(a159+a152);
  a153=(a153*a105);
  a157=(a157*a098);
  a158=(a158*a141);
  a157=(a157+a158);
  a153=(a153-a157);
  a160=(a160*a153);
  a159=(a159+a160);
  a139=(a139*a159);
  a155=(a155*a008);
  a139=(a139-a155);
  a139=(a034*a139);
  a040=(a040*a011);
  a011=(a104*a043);
  a040=(a040+a011);
  a139=(a139+a040);
  a011=(a107*a001);
  a011=(a060+a011);
  a139=(a139+a011);
  a011=(a110*a221);
  a011=(a056+a011);
  a139=(a139+a011);
  a139=(a139/a000);
  if (res[1]!=0) res[1][50]=a139;
  a174=(a038*a174);
  a174=(a174-a203);
  a203=(a096*a043);
  a239=(a239+a203);
  a174=(a174+a239);
  a239=(a099*a001);
  a239=(a239-a189);
  a174=(a174+a239);
  a174=(a174+a132);
  a132=(a007*a126);
  a174=(a174+a132);
  a132=(a057*a049);
  a174=(a174+a132);
  a174=(a174+a103);
  a174=(-a174);
  if (res[1]!=0) res[1][51]=a174;
  a145=(a038*a145);
  a145=(a145+a048);
  a043=(a084*a043);
  a181=(a181+a043);
  a145=(a145+a181);
  a145=(a145+a021);
  a021=(a088*a221);
  a130=(a130+a021);
  a145=(a145+a130);
  a126=(a036*a126);
  a145=(a145+a126);
  a145=(a145+a225);
  a225=(a046*a135);
  a145=(a145+a225);
  a145=(-a145);
  if (res[1]!=0) res[1][52]=a145;
  a207=(a207*a199);
  a207=(a053*a207);
  a038=(a038*a207);
  a038=(a038+a019);
  a038=(a038+a204);
  a038=(a038+a040);
  a001=(a106*a001);
  a060=(a060+a001);
  a038=(a038+a060);
  a221=(a109*a221);
  a056=(a056+a221);
  a038=(a038+a056);
  a038=(a038+a031);
  a049=(a065*a049);
  a038=(a038+a049);
  a135=(a068*a135);
  a038=(a038+a135);
  a038=(-a038);
  if (res[1]!=0) res[1][53]=a038;
  a038=(a050*a059);
  a135=(a020*a047);
  a038=(a038-a135);
  a135=(a018*a069);
  a038=(a038-a135);
  a135=(a013*a038);
  a049=(a092*a101);
  a031=(a080*a089);
  a049=(a049-a031);
  a031=(a078*a110);
  a049=(a049-a031);
  a031=(a070*a049);
  a135=(a135+a031);
  a038=(a113*a038);
  a049=(a013*a049);
  a038=(a038+a049);
  a049=(a000*a038);
  a031=(a112*a049);
  a056=(a000*a135);
  a221=(a053*a056);
  a031=(a031+a221);
  a221=(a055*a031);
  a221=(a053*a221);
  a221=(a111*a221);
  a135=(a135-a221);
  a221=(a025*a031);
  a060=(a053*a221);
  a001=(a009*a060);
  a135=(a135-a001);
  a031=(a051*a031);
  a001=(a053*a031);
  a040=(a004*a001);
  a135=(a135-a040);
  a040=(a020*a069);
  a204=(a027*a059);
  a019=(a018*a047);
  a204=(a204+a019);
  a040=(a040-a204);
  a204=(a113*a040);
  a019=(a080*a110);
  a207=(a083*a101);
  a199=(a078*a089);
  a207=(a207+a199);
  a019=(a019-a207);
  a207=(a013*a019);
  a204=(a204+a207);
  a207=(a000*a204);
  a199=(a112*a207);
  a040=(a013*a040);
  a019=(a070*a019);
  a040=(a040+a019);
  a019=(a000*a040);
  a145=(a053*a019);
  a199=(a199+a145);
  a145=(a055*a199);
  a225=(a053*a145);
  a126=(a009*a225);
  a135=(a135-a126);
  a126=(a051*a199);
  a130=(a033*a126);
  a135=(a135-a130);
  a130=(a027*a047);
  a021=(a018*a059);
  a130=(a130-a021);
  a021=(a050*a069);
  a130=(a130-a021);
  a021=(a113*a130);
  a181=(a083*a089);
  a043=(a078*a101);
  a181=(a181-a043);
  a043=(a092*a110);
  a181=(a181-a043);
  a043=(a013*a181);
  a021=(a021+a043);
  a043=(a000*a021);
  a048=(a112*a043);
  a048=(a034+a048);
  a130=(a013*a130);
  a181=(a070*a181);
  a130=(a130+a181);
  a181=(a000*a130);
  a174=(a053*a181);
  a048=(a048+a174);
  a174=(a055*a048);
  a103=(a053*a174);
  a132=(a004*a103);
  a135=(a135-a132);
  a132=(a025*a048);
  a239=(a033*a132);
  a135=(a135+a239);
  a239=(a012*a135);
  a031=(a033*a031);
  a060=(a002*a060);
  a031=(a031-a060);
  a031=(a031+a040);
  a225=(a002*a225);
  a031=(a031-a225);
  a199=(a025*a199);
  a199=(a053*a199);
  a199=(a121*a199);
  a031=(a031-a199);
  a126=(a053*a126);
  a199=(a004*a126);
  a031=(a031-a199);
  a174=(a033*a174);
  a031=(a031-a174);
  a132=(a053*a132);
  a174=(a004*a132);
  a031=(a031-a174);
  a174=(a058*a031);
  a239=(a239+a174);
  a145=(a033*a145);
  a221=(a033*a221);
  a001=(a002*a001);
  a221=(a221+a001);
  a145=(a145-a221);
  a126=(a009*a126);
  a145=(a145-a126);
  a145=(a145+a130);
  a103=(a002*a103);
  a145=(a145-a103);
  a132=(a009*a132);
  a145=(a145-a132);
  a048=(a051*a048);
  a048=(a053*a048);
  a048=(a129*a048);
  a145=(a145-a048);
  a048=(a059*a145);
  a239=(a239+a048);
  a239=(a239/a000);
  if (res[1]!=0) res[1][54]=a239;
  a239=(a037*a135);
  a132=(a042*a031);
  a239=(a239+a132);
  a103=(a047*a145);
  a239=(a239+a103);
  a239=(a239/a000);
  if (res[1]!=0) res[1][55]=a239;
  a239=(a062*a135);
  a103=(a066*a031);
  a103=(a239+a103);
  a130=(a069*a145);
  a103=(a103+a130);
  a103=(a103/a000);
  if (res[1]!=0) res[1][56]=a103;
  a049=(a053*a049);
  a056=(a161*a056);
  a049=(a049+a056);
  a056=(a102*a049);
  a056=(a053*a056);
  a056=(a163*a056);
  a038=(a038-a056);
  a056=(a024*a049);
  a103=(a053*a056);
  a130=(a073*a103);
  a038=(a038-a130);
  a049=(a093*a049);
  a130=(a053*a049);
  a126=(a071*a130);
  a038=(a038-a126);
  a207=(a053*a207);
  a019=(a161*a019);
  a207=(a207+a019);
  a019=(a102*a207);
  a126=(a053*a019);
  a221=(a073*a126);
  a038=(a038-a221);
  a221=(a093*a207);
  a001=(a033*a221);
  a038=(a038-a001);
  a043=(a053*a043);
  a043=(a034+a043);
  a181=(a161*a181);
  a043=(a043+a181);
  a181=(a102*a043);
  a001=(a053*a181);
  a174=(a071*a001);
  a038=(a038-a174);
  a174=(a024*a043);
  a199=(a033*a174);
  a038=(a038+a199);
  a199=(a097*a038);
  a103=(a076*a103);
  a204=(a204-a103);
  a049=(a033*a049);
  a204=(a204+a049);
  a126=(a076*a126);
  a204=(a204-a126);
  a207=(a024*a207);
  a207=(a053*a207);
  a207=(a166*a207);
  a204=(a204-a207);
  a221=(a053*a221);
  a207=(a071*a221);
  a204=(a204-a207);
  a181=(a033*a181);
  a204=(a204-a181);
  a174=(a053*a174);
  a181=(a071*a174);
  a204=(a204-a181);
  a181=(a100*a204);
  a199=(a199+a181);
  a056=(a033*a056);
  a021=(a021-a056);
  a130=(a076*a130);
  a021=(a021-a130);
  a019=(a033*a019);
  a021=(a021+a019);
  a221=(a073*a221);
  a021=(a021-a221);
  a001=(a076*a001);
  a021=(a021-a001);
  a174=(a073*a174);
  a021=(a021-a174);
  a043=(a093*a043);
  a043=(a053*a043);
  a043=(a123*a043);
  a021=(a021-a043);
  a043=(a101*a021);
  a199=(a199+a043);
  a199=(a199/a000);
  if (res[1]!=0) res[1][57]=a199;
  a199=(a085*a038);
  a174=(a086*a204);
  a199=(a199+a174);
  a001=(a089*a021);
  a199=(a199+a001);
  a199=(a199/a000);
  if (res[1]!=0) res[1][58]=a199;
  a199=(a104*a038);
  a001=(a107*a204);
  a001=(a199+a001);
  a221=(a110*a021);
  a001=(a001+a221);
  a001=(a001/a000);
  if (res[1]!=0) res[1][59]=a001;
  a001=(a096*a038);
  a177=(a177+a001);
  a001=(a099*a204);
  a177=(a177+a001);
  a177=(a177+a043);
  a043=(a007*a135);
  a177=(a177+a043);
  a043=(a057*a031);
  a177=(a177+a043);
  a177=(a177+a048);
  a177=(-a177);
  if (res[1]!=0) res[1][60]=a177;
  a038=(a084*a038);
  a176=(a176+a038);
  a176=(a176+a174);
  a174=(a088*a021);
  a176=(a176+a174);
  a135=(a036*a135);
  a176=(a176+a135);
  a176=(a176+a132);
  a132=(a046*a145);
  a176=(a176+a132);
  a176=(-a176);
  if (res[1]!=0) res[1][61]=a176;
  a142=(a142+a199);
  a204=(a106*a204);
  a142=(a142+a204);
  a021=(a109*a021);
  a142=(a142+a021);
  a142=(a142+a239);
  a031=(a065*a031);
  a142=(a142+a031);
  a145=(a068*a145);
  a142=(a142+a145);
  a142=(-a142);
  if (res[1]!=0) res[1][62]=a142;
  a142=(a050*a058);
  a145=(a020*a042);
  a142=(a142-a145);
  a145=(a018*a066);
  a142=(a142-a145);
  a145=(a013*a142);
  a031=(a092*a100);
  a239=(a080*a086);
  a031=(a031-a239);
  a239=(a078*a107);
  a031=(a031-a239);
  a239=(a070*a031);
  a145=(a145+a239);
  a142=(a113*a142);
  a031=(a013*a031);
  a142=(a142+a031);
  a031=(a000*a142);
  a239=(a112*a031);
  a021=(a000*a145);
  a204=(a053*a021);
  a239=(a239+a204);
  a204=(a055*a239);
  a204=(a053*a204);
  a204=(a111*a204);
  a145=(a145-a204);
  a204=(a025*a239);
  a199=(a053*a204);
  a176=(a009*a199);
  a145=(a145-a176);
  a239=(a051*a239);
  a176=(a053*a239);
  a132=(a004*a176);
  a145=(a145-a132);
  a132=(a020*a066);
  a135=(a027*a058);
  a174=(a018*a042);
  a135=(a135+a174);
  a132=(a132-a135);
  a135=(a113*a132);
  a174=(a080*a107);
  a038=(a083*a100);
  a177=(a078*a086);
  a038=(a038+a177);
  a174=(a174-a038);
  a038=(a013*a174);
  a135=(a135+a038);
  a038=(a000*a135);
  a177=(a112*a038);
  a177=(a034+a177);
  a132=(a013*a132);
  a174=(a070*a174);
  a132=(a132+a174);
  a174=(a000*a132);
  a048=(a053*a174);
  a177=(a177+a048);
  a048=(a055*a177);
  a043=(a053*a048);
  a001=(a009*a043);
  a145=(a145-a001);
  a001=(a051*a177);
  a221=(a033*a001);
  a145=(a145-a221);
  a221=(a027*a042);
  a019=(a018*a058);
  a221=(a221-a019);
  a019=(a050*a066);
  a221=(a221-a019);
  a019=(a113*a221);
  a130=(a083*a086);
  a056=(a078*a100);
  a130=(a130-a056);
  a056=(a092*a107);
  a130=(a130-a056);
  a056=(a013*a130);
  a019=(a019+a056);
  a056=(a000*a019);
  a181=(a112*a056);
  a221=(a013*a221);
  a130=(a070*a130);
  a221=(a221+a130);
  a130=(a000*a221);
  a207=(a053*a130);
  a181=(a181+a207);
  a207=(a055*a181);
  a126=(a053*a207);
  a049=(a004*a126);
  a145=(a145-a049);
  a049=(a025*a181);
  a103=(a033*a049);
  a145=(a145+a103);
  a103=(a012*a145);
  a239=(a033*a239);
  a199=(a002*a199);
  a239=(a239-a199);
  a239=(a239+a132);
  a043=(a002*a043);
  a239=(a239-a043);
  a177=(a025*a177);
  a177=(a053*a177);
  a177=(a121*a177);
  a239=(a239-a177);
  a001=(a053*a001);
  a177=(a004*a001);
  a239=(a239-a177);
  a207=(a033*a207);
  a239=(a239-a207);
  a049=(a053*a049);
  a207=(a004*a049);
  a239=(a239-a207);
  a207=(a058*a239);
  a103=(a103+a207);
  a048=(a033*a048);
  a204=(a033*a204);
  a176=(a002*a176);
  a204=(a204+a176);
  a048=(a048-a204);
  a001=(a009*a001);
  a048=(a048-a001);
  a048=(a048+a221);
  a126=(a002*a126);
  a048=(a048-a126);
  a049=(a009*a049);
  a048=(a048-a049);
  a181=(a051*a181);
  a181=(a053*a181);
  a181=(a129*a181);
  a048=(a048-a181);
  a181=(a059*a048);
  a103=(a103+a181);
  a103=(a103/a000);
  if (res[1]!=0) res[1][63]=a103;
  a103=(a037*a145);
  a049=(a042*a239);
  a103=(a103+a049);
  a126=(a047*a048);
  a103=(a103+a126);
  a103=(a103/a000);
  if (res[1]!=0) res[1][64]=a103;
  a103=(a062*a145);
  a126=(a066*a239);
  a126=(a103+a126);
  a221=(a069*a048);
  a126=(a126+a221);
  a126=(a126/a000);
  if (res[1]!=0) res[1][65]=a126;
  a031=(a053*a031);
  a021=(a161*a021);
  a031=(a031+a021);
  a021=(a102*a031);
  a021=(a053*a021);
  a021=(a163*a021);
  a142=(a142-a021);
  a021=(a024*a031);
  a126=(a053*a021);
  a221=(a073*a126);
  a142=(a142-a221);
  a031=(a093*a031);
  a221=(a053*a031);
  a001=(a071*a221);
  a142=(a142-a001);
  a038=(a053*a038);
  a038=(a034+a038);
  a174=(a161*a174);
  a038=(a038+a174);
  a174=(a102*a038);
  a001=(a053*a174);
  a204=(a073*a001);
  a142=(a142-a204);
  a204=(a093*a038);
  a176=(a033*a204);
  a142=(a142-a176);
  a056=(a053*a056);
  a130=(a161*a130);
  a056=(a056+a130);
  a130=(a102*a056);
  a176=(a053*a130);
  a207=(a071*a176);
  a142=(a142-a207);
  a207=(a024*a056);
  a177=(a033*a207);
  a142=(a142+a177);
  a177=(a097*a142);
  a126=(a076*a126);
  a135=(a135-a126);
  a031=(a033*a031);
  a135=(a135+a031);
  a001=(a076*a001);
  a135=(a135-a001);
  a038=(a024*a038);
  a038=(a053*a038);
  a038=(a166*a038);
  a135=(a135-a038);
  a204=(a053*a204);
  a038=(a071*a204);
  a135=(a135-a038);
  a130=(a033*a130);
  a135=(a135-a130);
  a207=(a053*a207);
  a130=(a071*a207);
  a135=(a135-a130);
  a130=(a100*a135);
  a177=(a177+a130);
  a021=(a033*a021);
  a019=(a019-a021);
  a221=(a076*a221);
  a019=(a019-a221);
  a174=(a033*a174);
  a019=(a019+a174);
  a204=(a073*a204);
  a019=(a019-a204);
  a176=(a076*a176);
  a019=(a019-a176);
  a207=(a073*a207);
  a019=(a019-a207);
  a056=(a093*a056);
  a056=(a053*a056);
  a056=(a123*a056);
  a019=(a019-a056);
  a056=(a101*a019);
  a177=(a177+a056);
  a177=(a177/a000);
  if (res[1]!=0) res[1][66]=a177;
  a177=(a085*a142);
  a207=(a086*a135);
  a177=(a177+a207);
  a176=(a089*a019);
  a177=(a177+a176);
  a177=(a177/a000);
  if (res[1]!=0) res[1][67]=a177;
  a177=(a104*a142);
  a176=(a107*a135);
  a176=(a177+a176);
  a204=(a110*a019);
  a176=(a176+a204);
  a176=(a176/a000);
  if (res[1]!=0) res[1][68]=a176;
  a176=(a096*a142);
  a175=(a175+a176);
  a176=(a099*a135);
  a175=(a175+a176);
  a175=(a175+a056);
  a056=(a007*a145);
  a175=(a175+a056);
  a056=(a057*a239);
  a175=(a175+a056);
  a175=(a175+a181);
  a175=(-a175);
  if (res[1]!=0) res[1][69]=a175;
  a142=(a084*a142);
  a131=(a131+a142);
  a131=(a131+a207);
  a207=(a088*a019);
  a131=(a131+a207);
  a145=(a036*a145);
  a131=(a131+a145);
  a131=(a131+a049);
  a049=(a046*a048);
  a131=(a131+a049);
  a131=(-a131);
  if (res[1]!=0) res[1][70]=a131;
  a010=(a010+a177);
  a135=(a106*a135);
  a010=(a010+a135);
  a019=(a109*a019);
  a010=(a010+a019);
  a010=(a010+a103);
  a239=(a065*a239);
  a010=(a010+a239);
  a048=(a068*a048);
  a010=(a010+a048);
  a010=(-a010);
  if (res[1]!=0) res[1][71]=a010;
  a010=(a050*a012);
  a048=(a020*a037);
  a010=(a010-a048);
  a048=(a018*a062);
  a010=(a010-a048);
  a048=(a013*a010);
  a239=(a092*a097);
  a103=(a080*a085);
  a239=(a239-a103);
  a103=(a078*a104);
  a239=(a239-a103);
  a103=(a070*a239);
  a048=(a048+a103);
  a010=(a113*a010);
  a239=(a013*a239);
  a010=(a010+a239);
  a239=(a000*a010);
  a103=(a112*a239);
  a103=(a034+a103);
  a019=(a000*a048);
  a135=(a053*a019);
  a103=(a103+a135);
  a135=(a055*a103);
  a135=(a053*a135);
  a111=(a111*a135);
  a048=(a048-a111);
  a111=(a025*a103);
  a135=(a053*a111);
  a177=(a009*a135);
  a048=(a048-a177);
  a103=(a051*a103);
  a177=(a053*a103);
  a131=(a004*a177);
  a048=(a048-a131);
  a020=(a020*a062);
  a131=(a027*a012);
  a049=(a018*a037);
  a131=(a131+a049);
  a020=(a020-a131);
  a131=(a113*a020);
  a080=(a080*a104);
  a049=(a083*a097);
  a145=(a078*a085);
  a049=(a049+a145);
  a080=(a080-a049);
  a049=(a013*a080);
  a131=(a131+a049);
  a049=(a000*a131);
  a145=(a112*a049);
  a020=(a013*a020);
  a080=(a070*a080);
  a020=(a020+a080);
  a080=(a000*a020);
  a207=(a053*a080);
  a145=(a145+a207);
  a207=(a055*a145);
  a142=(a053*a207);
  a175=(a009*a142);
  a048=(a048-a175);
  a175=(a051*a145);
  a181=(a033*a175);
  a048=(a048-a181);
  a027=(a027*a037);
  a018=(a018*a012);
  a027=(a027-a018);
  a050=(a050*a062);
  a027=(a027-a050);
  a113=(a113*a027);
  a083=(a083*a085);
  a078=(a078*a097);
  a083=(a083-a078);
  a092=(a092*a104);
  a083=(a083-a092);
  a092=(a013*a083);
  a113=(a113+a092);
  a092=(a000*a113);
  a112=(a112*a092);
  a013=(a013*a027);
  a070=(a070*a083);
  a013=(a013+a070);
  a070=(a000*a013);
  a083=(a053*a070);
  a112=(a112+a083);
  a055=(a055*a112);
  a083=(a053*a055);
  a027=(a004*a083);
  a048=(a048-a027);
  a027=(a025*a112);
  a078=(a033*a027);
  a048=(a048+a078);
  a012=(a012*a048);
  a103=(a033*a103);
  a135=(a002*a135);
  a103=(a103-a135);
  a103=(a103+a020);
  a142=(a002*a142);
  a103=(a103-a142);
  a025=(a025*a145);
  a025=(a053*a025);
  a121=(a121*a025);
  a103=(a103-a121);
  a175=(a053*a175);
  a121=(a004*a175);
  a103=(a103-a121);
  a055=(a033*a055);
  a103=(a103-a055);
  a027=(a053*a027);
  a004=(a004*a027);
  a103=(a103-a004);
  a058=(a058*a103);
  a012=(a012+a058);
  a207=(a033*a207);
  a111=(a033*a111);
  a177=(a002*a177);
  a111=(a111+a177);
  a207=(a207-a111);
  a175=(a009*a175);
  a207=(a207-a175);
  a207=(a207+a013);
  a002=(a002*a083);
  a207=(a207-a002);
  a009=(a009*a027);
  a207=(a207-a009);
  a051=(a051*a112);
  a051=(a053*a051);
  a129=(a129*a051);
  a207=(a207-a129);
  a059=(a059*a207);
  a012=(a012+a059);
  a012=(a012/a000);
  if (res[1]!=0) res[1][72]=a012;
  a037=(a037*a048);
  a042=(a042*a103);
  a037=(a037+a042);
  a047=(a047*a207);
  a037=(a037+a047);
  a037=(a037/a000);
  if (res[1]!=0) res[1][73]=a037;
  a062=(a062*a048);
  a066=(a066*a103);
  a066=(a062+a066);
  a069=(a069*a207);
  a066=(a066+a069);
  a066=(a066/a000);
  if (res[1]!=0) res[1][74]=a066;
  a239=(a053*a239);
  a034=(a034+a239);
  a019=(a161*a019);
  a034=(a034+a019);
  a019=(a102*a034);
  a019=(a053*a019);
  a163=(a163*a019);
  a010=(a010-a163);
  a163=(a024*a034);
  a019=(a053*a163);
  a239=(a073*a019);
  a010=(a010-a239);
  a034=(a093*a034);
  a239=(a053*a034);
  a066=(a071*a239);
  a010=(a010-a066);
  a049=(a053*a049);
  a080=(a161*a080);
  a049=(a049+a080);
  a080=(a102*a049);
  a066=(a053*a080);
  a069=(a073*a066);
  a010=(a010-a069);
  a069=(a093*a049);
  a037=(a033*a069);
  a010=(a010-a037);
  a092=(a053*a092);
  a161=(a161*a070);
  a092=(a092+a161);
  a102=(a102*a092);
  a161=(a053*a102);
  a070=(a071*a161);
  a010=(a010-a070);
  a070=(a024*a092);
  a037=(a033*a070);
  a010=(a010+a037);
  a097=(a097*a010);
  a019=(a076*a019);
  a131=(a131-a019);
  a034=(a033*a034);
  a131=(a131+a034);
  a066=(a076*a066);
  a131=(a131-a066);
  a024=(a024*a049);
  a024=(a053*a024);
  a166=(a166*a024);
  a131=(a131-a166);
  a069=(a053*a069);
  a166=(a071*a069);
  a131=(a131-a166);
  a102=(a033*a102);
  a131=(a131-a102);
  a070=(a053*a070);
  a071=(a071*a070);
  a131=(a131-a071);
  a100=(a100*a131);
  a097=(a097+a100);
  a163=(a033*a163);
  a113=(a113-a163);
  a239=(a076*a239);
  a113=(a113-a239);
  a033=(a033*a080);
  a113=(a113+a033);
  a069=(a073*a069);
  a113=(a113-a069);
  a076=(a076*a161);
  a113=(a113-a076);
  a073=(a073*a070);
  a113=(a113-a073);
  a093=(a093*a092);
  a053=(a053*a093);
  a123=(a123*a053);
  a113=(a113-a123);
  a101=(a101*a113);
  a097=(a097+a101);
  a097=(a097/a000);
  if (res[1]!=0) res[1][75]=a097;
  a085=(a085*a010);
  a086=(a086*a131);
  a085=(a085+a086);
  a089=(a089*a113);
  a085=(a085+a089);
  a085=(a085/a000);
  if (res[1]!=0) res[1][76]=a085;
  a104=(a104*a010);
  a107=(a107*a131);
  a107=(a104+a107);
  a110=(a110*a113);
  a107=(a107+a110);
  a107=(a107/a000);
  if (res[1]!=0) res[1][77]=a107;
  a096=(a096*a010);
  a173=(a173+a096);
  a099=(a099*a131);
  a173=(a173+a099);
  a173=(a173+a101);
  a007=(a007*a048);
  a173=(a173+a007);
  a057=(a057*a103);
  a173=(a173+a057);
  a173=(a173+a059);
  a173=(-a173);
  if (res[1]!=0) res[1][78]=a173;
  a084=(a084*a010);
  a150=(a150+a084);
  a150=(a150+a086);
  a088=(a088*a113);
  a150=(a150+a088);
  a036=(a036*a048);
  a150=(a150+a036);
  a150=(a150+a042);
  a046=(a046*a207);
  a150=(a150+a046);
  a150=(-a150);
  if (res[1]!=0) res[1][79]=a150;
  a041=(a041+a104);
  a106=(a106*a131);
  a041=(a041+a106);
  a109=(a109*a113);
  a041=(a041+a109);
  a041=(a041+a062);
  a065=(a065*a103);
  a041=(a041+a065);
  a068=(a068*a207);
  a041=(a041+a068);
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

/* update:(z[9],g[9],p[3],h[4])->(g1[9],p1[3]) */
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
  casadi_real a180, a181, a182, a183, a184, a185, a186, a187, a188, a189, a190, a191;
  casadi_real a192, a193, a194, a195, a196, a197, a198, a199, a200, a201, a202, a203;
  casadi_real a204, a205, a206, a207, a208, a209, a210, a211, a212, a213, a214, a215;
  casadi_real a216, a217, a218, a219, a220, a221, a222, a223, a224, a225, a226, a227;
  casadi_real a228, a229, a230, a231, a232, a233, a234, a235, a236, a237, a238, a239;
  casadi_real a240, a241, a242, a243, a244, a245, a246, a247, a248, a249, a250, a251;
  casadi_real a252, a253, a254, a255, a256, a257, a258, a259, a260, a261, a262, a263;
  casadi_real a264, a265, a266, a267, a268, a269, a270, a271, a272, a273, a274, a275;
  casadi_real a276, a277, a278, a279, a280, a281, a282;
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
  a024=(a023/a019);
  a024=(a008+a024);
  a025=(a017*a024);
  a026=arg[1]? arg[1][5] : 0;
  a027=(a025*a026);
  a022=(a022-a027);
  a027=8.4147098480789650e-01;
  a028=(a015*a011);
  a029=(a028/a019);
  a029=(a029-a008);
  a030=(a017*a029);
  a031=arg[1]? arg[1][6] : 0;
  a032=(a030*a031);
  a033=(a012+a009);
  a033=(a033/a019);
  a034=(a017*a033);
  a034=(a005-a034);
  a035=arg[1]? arg[1][3] : 0;
  a036=(a034*a035);
  a032=(a032-a036);
  a036=(a027*a032);
  a022=(a022+a036);
  a036=-5.4030230586813977e-01;
  a037=arg[1]? arg[1][7] : 0;
  a038=(a030*a037);
  a039=arg[1]? arg[1][4] : 0;
  a040=(a034*a039);
  a038=(a038-a040);
  a040=(a036*a038);
  a022=(a022+a040);
  a022=(a004*a022);
  a022=(a002*a022);
  a022=(a022/a001);
  if (res[0]!=0) res[0][0]=a022;
  a022=5.4030230586813977e-01;
  a032=(a022*a032);
  a040=(a008*a011);
  a041=(a040/a019);
  a041=(a015+a041);
  a042=(a017*a041);
  a043=(a042*a021);
  a044=(a008*a015);
  a045=(a044/a019);
  a045=(a045-a011);
  a046=(a017*a045);
  a047=(a046*a026);
  a043=(a043-a047);
  a032=(a032-a043);
  a038=(a027*a038);
  a032=(a032+a038);
  a032=(a004*a032);
  a032=(a002*a032);
  a032=(a032/a001);
  if (res[0]!=0) res[0][1]=a032;
  a032=(a042*a037);
  a038=(a046*a039);
  a032=(a032-a038);
  a032=(a022*a032);
  a038=(a020*a031);
  a043=(a025*a035);
  a038=(a038-a043);
  a038=(a036*a038);
  a032=(a032+a038);
  a038=-8.4147098480789650e-01;
  a043=(a042*a031);
  a047=(a046*a035);
  a043=(a043-a047);
  a043=(a038*a043);
  a032=(a032+a043);
  a043=(a020*a037);
  a047=(a025*a039);
  a043=(a043-a047);
  a043=(a038*a043);
  a032=(a032+a043);
  a032=(a004*a032);
  a032=(a002*a032);
  a032=(a032/a001);
  if (res[0]!=0) res[0][2]=a032;
  a032=arg[0]? arg[0][3] : 0;
  a043=(a001*a032);
  a047=casadi_sq(a043);
  a048=arg[0]? arg[0][4] : 0;
  a049=(a001*a048);
  a050=casadi_sq(a049);
  a051=(a047+a050);
  a052=arg[0]? arg[0][5] : 0;
  a053=(a001*a052);
  a054=casadi_sq(a053);
  a051=(a051+a054);
  a051=(a006+a051);
  a055=(a006/a051);
  a056=(a054+a047);
  a056=(a056/a019);
  a057=(a055*a056);
  a057=(a005-a057);
  a058=(a057*a021);
  a059=(a049*a053);
  a060=(a059/a019);
  a060=(a043+a060);
  a061=(a055*a060);
  a062=(a061*a026);
  a058=(a058-a062);
  a062=(a053*a049);
  a063=(a062/a019);
  a063=(a063-a043);
  a064=(a055*a063);
  a065=(a064*a031);
  a066=(a050+a047);
  a066=(a066/a019);
  a067=(a055*a066);
  a067=(a005-a067);
  a068=(a067*a035);
  a065=(a065-a068);
  a068=(a027*a065);
  a058=(a058+a068);
  a068=(a064*a037);
  a069=(a067*a039);
  a068=(a068-a069);
  a069=(a036*a068);
  a058=(a058+a069);
  a058=(a004*a058);
  a058=(a002*a058);
  a058=(a058/a001);
  if (res[0]!=0) res[0][3]=a058;
  a065=(a022*a065);
  a058=(a043*a049);
  a069=(a058/a019);
  a069=(a053+a069);
  a070=(a055*a069);
  a071=(a070*a021);
  a072=(a043*a053);
  a073=(a072/a019);
  a073=(a073-a049);
  a074=(a055*a073);
  a075=(a074*a026);
  a071=(a071-a075);
  a065=(a065-a071);
  a068=(a027*a068);
  a065=(a065+a068);
  a065=(a004*a065);
  a065=(a002*a065);
  a065=(a065/a001);
  if (res[0]!=0) res[0][4]=a065;
  a065=(a070*a037);
  a068=(a074*a039);
  a065=(a065-a068);
  a065=(a022*a065);
  a068=(a057*a031);
  a071=(a061*a035);
  a068=(a068-a071);
  a068=(a036*a068);
  a065=(a065+a068);
  a068=(a070*a031);
  a071=(a074*a035);
  a068=(a068-a071);
  a068=(a038*a068);
  a065=(a065+a068);
  a068=(a057*a037);
  a071=(a061*a039);
  a068=(a068-a071);
  a068=(a038*a068);
  a065=(a065+a068);
  a065=(a004*a065);
  a065=(a002*a065);
  a065=(a065/a001);
  if (res[0]!=0) res[0][5]=a065;
  a065=0.;
  if (res[0]!=0) res[0][6]=a065;
  if (res[0]!=0) res[0][7]=a065;
  if (res[0]!=0) res[0][8]=a065;
  a068=arg[1]? arg[1][2] : 0;
  a071=(a025*a068);
  a075=(a011*a008);
  a076=(a075/a019);
  a076=(a076-a015);
  a077=(a017*a076);
  a078=(a077*a021);
  a071=(a071-a078);
  a078=arg[1]? arg[1][0] : 0;
  a079=(a034*a078);
  a080=(a015*a008);
  a081=(a080/a019);
  a081=(a011+a081);
  a082=(a017*a081);
  a083=(a082*a031);
  a079=(a079-a083);
  a083=(a027*a079);
  a071=(a071+a083);
  a083=arg[1]? arg[1][1] : 0;
  a084=(a034*a083);
  a085=(a082*a037);
  a084=(a084-a085);
  a085=(a036*a084);
  a071=(a071+a085);
  a071=(a004*a071);
  a071=(a002*a071);
  a071=(a071/a001);
  if (res[0]!=0) res[0][9]=a071;
  a079=(a022*a079);
  a071=(a046*a068);
  a085=(a016+a012);
  a085=(a085/a019);
  a086=(a017*a085);
  a086=(a005-a086);
  a087=(a086*a021);
  a071=(a071-a087);
  a079=(a079-a071);
  a084=(a027*a084);
  a079=(a079+a084);
  a079=(a004*a079);
  a079=(a002*a079);
  a079=(a079/a001);
  if (res[0]!=0) res[0][10]=a079;
  a079=(a046*a083);
  a084=(a086*a037);
  a079=(a079-a084);
  a079=(a022*a079);
  a084=(a025*a078);
  a071=(a077*a031);
  a084=(a084-a071);
  a084=(a036*a084);
  a079=(a079+a084);
  a084=(a046*a078);
  a071=(a086*a031);
  a084=(a084-a071);
  a084=(a038*a084);
  a079=(a079+a084);
  a084=(a025*a083);
  a071=(a077*a037);
  a084=(a084-a071);
  a084=(a038*a084);
  a079=(a079+a084);
  a079=(a004*a079);
  a079=(a002*a079);
  a079=(a079/a001);
  if (res[0]!=0) res[0][11]=a079;
  a079=(a061*a068);
  a084=(a049*a043);
  a071=(a084/a019);
  a071=(a071-a053);
  a087=(a055*a071);
  a088=(a087*a021);
  a079=(a079-a088);
  a088=(a067*a078);
  a089=(a053*a043);
  a090=(a089/a019);
  a090=(a049+a090);
  a091=(a055*a090);
  a092=(a091*a031);
  a088=(a088-a092);
  a092=(a027*a088);
  a079=(a079+a092);
  a092=(a067*a083);
  a093=(a091*a037);
  a092=(a092-a093);
  a093=(a036*a092);
  a079=(a079+a093);
  a079=(a004*a079);
  a079=(a002*a079);
  a079=(a079/a001);
  if (res[0]!=0) res[0][12]=a079;
  a088=(a022*a088);
  a079=(a074*a068);
  a093=(a054+a050);
  a093=(a093/a019);
  a094=(a055*a093);
  a094=(a005-a094);
  a095=(a094*a021);
  a079=(a079-a095);
  a088=(a088-a079);
  a092=(a027*a092);
  a088=(a088+a092);
  a088=(a004*a088);
  a088=(a002*a088);
  a088=(a088/a001);
  if (res[0]!=0) res[0][13]=a088;
  a088=(a074*a083);
  a092=(a094*a037);
  a088=(a088-a092);
  a088=(a022*a088);
  a092=(a061*a078);
  a079=(a087*a031);
  a092=(a092-a079);
  a092=(a036*a092);
  a088=(a088+a092);
  a092=(a074*a078);
  a079=(a094*a031);
  a092=(a092-a079);
  a092=(a038*a092);
  a088=(a088+a092);
  a092=(a061*a083);
  a079=(a087*a037);
  a092=(a092-a079);
  a092=(a038*a092);
  a088=(a088+a092);
  a088=(a004*a088);
  a088=(a002*a088);
  a088=(a088/a001);
  if (res[0]!=0) res[0][14]=a088;
  if (res[0]!=0) res[0][15]=a065;
  if (res[0]!=0) res[0][16]=a065;
  if (res[0]!=0) res[0][17]=a065;
  a088=(a077*a026);
  a092=(a020*a068);
  a088=(a088-a092);
  a092=(a082*a035);
  a079=(a030*a078);
  a092=(a092-a079);
  a079=(a027*a092);
  a088=(a088+a079);
  a079=(a082*a039);
  a095=(a030*a083);
  a079=(a079-a095);
  a095=(a036*a079);
  a088=(a088+a095);
  a088=(a004*a088);
  a088=(a002*a088);
  a088=(a088/a001);
  if (res[0]!=0) res[0][18]=a088;
  a092=(a022*a092);
  a088=(a086*a026);
  a095=(a042*a068);
  a088=(a088-a095);
  a092=(a092-a088);
  a079=(a027*a079);
  a092=(a092+a079);
  a092=(a004*a092);
  a092=(a002*a092);
  a092=(a092/a001);
  if (res[0]!=0) res[0][19]=a092;
  a092=(a086*a039);
  a079=(a042*a083);
  a092=(a092-a079);
  a092=(a022*a092);
  a079=(a077*a035);
  a088=(a020*a078);
  a079=(a079-a088);
  a079=(a036*a079);
  a092=(a092+a079);
  a079=(a086*a035);
  a088=(a042*a078);
  a079=(a079-a088);
  a079=(a038*a079);
  a092=(a092+a079);
  a079=(a077*a039);
  a088=(a020*a083);
  a079=(a079-a088);
  a079=(a038*a079);
  a092=(a092+a079);
  a092=(a004*a092);
  a092=(a002*a092);
  a092=(a092/a001);
  if (res[0]!=0) res[0][20]=a092;
  a092=(a087*a026);
  a079=(a057*a068);
  a092=(a092-a079);
  a079=(a091*a035);
  a088=(a064*a078);
  a079=(a079-a088);
  a088=(a027*a079);
  a092=(a092+a088);
  a088=(a091*a039);
  a095=(a064*a083);
  a088=(a088-a095);
  a095=(a036*a088);
  a092=(a092+a095);
  a092=(a004*a092);
  a092=(a002*a092);
  a092=(a092/a001);
  if (res[0]!=0) res[0][21]=a092;
  a079=(a022*a079);
  a092=(a094*a026);
  a095=(a070*a068);
  a092=(a092-a095);
  a079=(a079-a092);
  a088=(a027*a088);
  a079=(a079+a088);
  a079=(a004*a079);
  a079=(a002*a079);
  a079=(a079/a001);
  if (res[0]!=0) res[0][22]=a079;
  a079=(a094*a039);
  a088=(a070*a083);
  a079=(a079-a088);
  a079=(a022*a079);
  a088=(a087*a035);
  a092=(a057*a078);
  a088=(a088-a092);
  a088=(a036*a088);
  a079=(a079+a088);
  a088=(a094*a035);
  a092=(a070*a078);
  a088=(a088-a092);
  a088=(a038*a088);
  a079=(a079+a088);
  a088=(a087*a039);
  a092=(a057*a083);
  a088=(a088-a092);
  a088=(a038*a088);
  a079=(a079+a088);
  a079=(a004*a079);
  a079=(a002*a079);
  a079=(a079/a001);
  if (res[0]!=0) res[0][23]=a079;
  if (res[0]!=0) res[0][24]=a065;
  if (res[0]!=0) res[0][25]=a065;
  if (res[0]!=0) res[0][26]=a065;
  if (res[0]!=0) res[0][27]=a065;
  if (res[0]!=0) res[0][28]=a065;
  if (res[0]!=0) res[0][29]=a065;
  if (res[0]!=0) res[0][30]=a065;
  if (res[0]!=0) res[0][31]=a065;
  if (res[0]!=0) res[0][32]=a065;
  if (res[0]!=0) res[0][33]=a005;
  if (res[0]!=0) res[0][34]=a065;
  if (res[0]!=0) res[0][35]=a065;
  if (res[0]!=0) res[0][36]=a065;
  if (res[0]!=0) res[0][37]=a065;
  if (res[0]!=0) res[0][38]=a065;
  if (res[0]!=0) res[0][39]=a065;
  if (res[0]!=0) res[0][40]=a065;
  if (res[0]!=0) res[0][41]=a065;
  if (res[0]!=0) res[0][42]=a065;
  if (res[0]!=0) res[0][43]=a005;
  if (res[0]!=0) res[0][44]=a065;
  if (res[0]!=0) res[0][45]=a065;
  if (res[0]!=0) res[0][46]=a065;
  if (res[0]!=0) res[0][47]=a065;
  if (res[0]!=0) res[0][48]=a065;
  if (res[0]!=0) res[0][49]=a065;
  if (res[0]!=0) res[0][50]=a065;
  if (res[0]!=0) res[0][51]=a065;
  if (res[0]!=0) res[0][52]=a065;
  if (res[0]!=0) res[0][53]=a005;
  a079=3.0000000000000004e+00;
  a088=(a079*a007);
  a092=4.6410161513775439e-01;
  a095=(a092*a032);
  a088=(a088+a095);
  a095=(a000*a088);
  a096=-6.4641016151377553e+00;
  a097=(a096*a007);
  a098=(a079*a032);
  a097=(a097+a098);
  a098=(a000*a097);
  a095=(a095+a098);
  a098=(a001*a095);
  a099=casadi_sq(a098);
  a100=(a079*a010);
  a101=(a092*a048);
  a100=(a100+a101);
  a101=(a000*a100);
  a102=(a096*a010);
  a103=(a079*a048);
  a102=(a102+a103);
  a103=(a000*a102);
  a101=(a101+a103);
  a103=(a001*a101);
  a104=casadi_sq(a103);
  a105=(a099+a104);
  a106=(a079*a014);
  a092=(a092*a052);
  a106=(a106+a092);
  a092=(a000*a106);
  a096=(a096*a014);
  a079=(a079*a052);
  a096=(a096+a079);
  a079=(a000*a096);
  a092=(a092+a079);
  a079=(a001*a092);
  a107=casadi_sq(a079);
  a105=(a105+a107);
  a105=(a006+a105);
  a108=(a006/a105);
  a109=(a079*a098);
  a110=(a109/a019);
  a110=(a103+a110);
  a111=(a108*a110);
  a112=(a078*a111);
  a113=(a079*a103);
  a114=(a113/a019);
  a114=(a114-a098);
  a115=(a108*a114);
  a116=(a035*a115);
  a112=(a112+a116);
  a116=(a104+a099);
  a116=(a116/a019);
  a117=(a108*a116);
  a117=(a005-a117);
  a118=(a031*a117);
  a112=(a112+a118);
  a118=-1.7320508075688774e+00;
  a118=(a118*a001);
  a119=(a103*a118);
  a120=(a000*a119);
  a120=(a108*a120);
  a121=(a103*a098);
  a122=(a121/a019);
  a122=(a122-a079);
  a105=(a108/a105);
  a123=(2.*a098);
  a124=(a123*a118);
  a125=(a105*a124);
  a126=(a122*a125);
  a126=(a120-a126);
  a127=(a078*a126);
  a128=(a000*a124);
  a128=(a108*a128);
  a129=(a107+a099);
  a129=(a129/a019);
  a130=(a129*a125);
  a130=(a128-a130);
  a131=(a035*a130);
  a127=(a127-a131);
  a131=(a108*a118);
  a132=(a103*a079);
  a133=(a132/a019);
  a133=(a098+a133);
  a134=(a133*a125);
  a134=(a131-a134);
  a135=(a031*a134);
  a127=(a127+a135);
  a127=(a112*a127);
  a135=(a083*a111);
  a136=(a039*a115);
  a135=(a135+a136);
  a136=(a037*a117);
  a135=(a135+a136);
  a136=(a083*a126);
  a137=(a039*a130);
  a136=(a136-a137);
  a137=(a037*a134);
  a136=(a136+a137);
  a136=(a135*a136);
  a127=(a127+a136);
  a136=(a068*a111);
  a137=(a026*a115);
  a136=(a136+a137);
  a137=(a021*a117);
  a136=(a136+a137);
  a126=(a068*a126);
  a130=(a026*a130);
  a126=(a126-a130);
  a134=(a021*a134);
  a126=(a126+a134);
  a126=(a136*a126);
  a127=(a127+a126);
  if (res[1]!=0) res[1][0]=a127;
  a127=(a107+a104);
  a127=(a127/a019);
  a126=(a108*a127);
  a126=(a005-a126);
  a134=(a078*a126);
  a130=(a098*a103);
  a137=(a130/a019);
  a137=(a079+a137);
  a138=(a108*a137);
  a139=(a035*a138);
  a134=(a134+a139);
  a139=(a098*a079);
  a140=(a139/a019);
  a140=(a140-a103);
  a141=(a108*a140);
  a142=(a031*a141);
  a134=(a134+a142);
  a142=(a079*a118);
  a143=(a000*a142);
  a143=(a108*a143);
  a144=(a110*a125);
  a144=(a143-a144);
  a145=(a078*a144);
  a146=(a114*a125);
  a146=(a146+a131);
  a147=(a035*a146);
  a145=(a145-a147);
  a147=(a116*a125);
  a128=(a128-a147);
  a147=(a031*a128);
  a145=(a145-a147);
  a145=(a134*a145);
  a147=(a083*a126);
  a148=(a039*a138);
  a147=(a147+a148);
  a148=(a037*a141);
  a147=(a147+a148);
  a148=(a083*a144);
  a149=(a039*a146);
  a148=(a148-a149);
  a149=(a037*a128);
  a148=(a148-a149);
  a148=(a147*a148);
  a145=(a145+a148);
  a148=(a068*a126);
  a149=(a026*a138);
  a148=(a148+a149);
  a149=(a021*a141);
  a148=(a148+a149);
  a144=(a068*a144);
  a146=(a026*a146);
  a144=(a144-a146);
  a128=(a021*a128);
  a144=(a144-a128);
  a144=(a148*a144);
  a145=(a145+a144);
  if (res[1]!=0) res[1][1]=a145;
  a145=(a108*a122);
  a144=(a078*a145);
  a128=(a108*a129);
  a128=(a005-a128);
  a146=(a035*a128);
  a144=(a144+a146);
  a146=(a108*a133);
  a149=(a031*a146);
  a144=(a144+a149);
  a149=(a127*a125);
  a150=(a078*a149);
  a151=(a137*a125);
  a151=(a120-a151);
  a152=(a035*a151);
  a150=(a150+a152);
  a125=(a140*a125);
  a125=(a143-a125);
  a152=(a031*a125);
  a150=(a150+a152);
  a150=(a144*a150);
  a152=(a083*a145);
  a153=(a039*a128);
  a152=(a152+a153);
  a153=(a037*a146);
  a152=(a152+a153);
  a153=(a083*a149);
  a154=(a039*a151);
  a153=(a153+a154);
  a154=(a037*a125);
  a153=(a153+a154);
  a153=(a152*a153);
  a150=(a150+a153);
  a153=(a068*a145);
  a154=(a026*a128);
  a153=(a153+a154);
  a154=(a021*a146);
  a153=(a153+a154);
  a149=(a068*a149);
  a151=(a026*a151);
  a149=(a149+a151);
  a125=(a021*a125);
  a149=(a149+a125);
  a149=(a153*a149);
  a150=(a150+a149);
  if (res[1]!=0) res[1][2]=a150;
  a150=arg[0]? arg[0][8] : 0;
  a149=2.5000000000000000e-01;
  a142=(a149*a142);
  a125=(a150*a142);
  a151=arg[0]? arg[0][7] : 0;
  a119=(a149*a119);
  a154=(a151*a119);
  a155=(a125+a154);
  a156=arg[0]? arg[0][6] : 0;
  a124=(a149*a124);
  a124=(a156*a124);
  a155=(a155+a124);
  if (res[1]!=0) res[1][3]=a155;
  a155=-8.6602540378443871e-01;
  a155=(a155*a001);
  a124=(a150*a155);
  a157=(a156*a119);
  a157=(a124+a157);
  if (res[1]!=0) res[1][4]=a157;
  a157=(a156*a142);
  a158=(a151*a155);
  a157=(a157-a158);
  if (res[1]!=0) res[1][5]=a157;
  a157=(a098*a118);
  a159=(a000*a157);
  a159=(a108*a159);
  a160=(2.*a103);
  a161=(a160*a118);
  a162=(a105*a161);
  a163=(a122*a162);
  a163=(a159-a163);
  a164=(a078*a163);
  a165=(a129*a162);
  a166=(a035*a165);
  a164=(a164+a166);
  a166=(a133*a162);
  a166=(a143-a166);
  a167=(a031*a166);
  a164=(a164+a167);
  a164=(a112*a164);
  a167=(a083*a163);
  a168=(a039*a165);
  a167=(a167+a168);
  a168=(a037*a166);
  a167=(a167+a168);
  a167=(a135*a167);
  a164=(a164+a167);
  a163=(a068*a163);
  a165=(a026*a165);
  a163=(a163+a165);
  a166=(a021*a166);
  a163=(a163+a166);
  a163=(a136*a163);
  a164=(a164+a163);
  if (res[1]!=0) res[1][6]=a164;
  a164=(a110*a162);
  a164=(a131-a164);
  a163=(a078*a164);
  a166=(a114*a162);
  a143=(a143-a166);
  a166=(a035*a143);
  a163=(a163+a166);
  a166=(a000*a161);
  a166=(a108*a166);
  a165=(a116*a162);
  a165=(a166-a165);
  a167=(a031*a165);
  a163=(a163-a167);
  a163=(a134*a163);
  a167=(a083*a164);
  a168=(a039*a143);
  a167=(a167+a168);
  a168=(a037*a165);
  a167=(a167-a168);
  a167=(a147*a167);
  a163=(a163+a167);
  a164=(a068*a164);
  a143=(a026*a143);
  a164=(a164+a143);
  a165=(a021*a165);
  a164=(a164-a165);
  a164=(a148*a164);
  a163=(a163+a164);
  if (res[1]!=0) res[1][7]=a163;
  a163=(a137*a162);
  a163=(a159-a163);
  a164=(a035*a163);
  a165=(a127*a162);
  a166=(a166-a165);
  a165=(a078*a166);
  a164=(a164-a165);
  a162=(a140*a162);
  a162=(a162+a131);
  a165=(a031*a162);
  a164=(a164-a165);
  a164=(a144*a164);
  a165=(a039*a163);
  a143=(a083*a166);
  a165=(a165-a143);
  a143=(a037*a162);
  a165=(a165-a143);
  a165=(a152*a165);
  a164=(a164+a165);
  a163=(a026*a163);
  a166=(a068*a166);
  a163=(a163-a166);
  a162=(a021*a162);
  a163=(a163-a162);
  a163=(a153*a163);
  a164=(a164+a163);
  if (res[1]!=0) res[1][8]=a164;
  a157=(a149*a157);
  a164=(a151*a157);
  a164=(a164-a124);
  if (res[1]!=0) res[1][9]=a164;
  a161=(a149*a161);
  a161=(a151*a161);
  a125=(a125+a161);
  a161=(a156*a157);
  a125=(a125+a161);
  if (res[1]!=0) res[1][10]=a125;
  a142=(a151*a142);
  a155=(a156*a155);
  a142=(a142+a155);
  if (res[1]!=0) res[1][11]=a142;
  a142=(2.*a079);
  a118=(a142*a118);
  a125=(a105*a118);
  a164=(a133*a125);
  a164=(a120-a164);
  a124=(a031*a164);
  a163=(a122*a125);
  a163=(a163+a131);
  a162=(a078*a163);
  a166=(a000*a118);
  a166=(a108*a166);
  a165=(a129*a125);
  a165=(a166-a165);
  a143=(a035*a165);
  a162=(a162+a143);
  a124=(a124-a162);
  a124=(a112*a124);
  a162=(a037*a164);
  a143=(a083*a163);
  a167=(a039*a165);
  a143=(a143+a167);
  a162=(a162-a143);
  a162=(a135*a162);
  a124=(a124+a162);
  a164=(a021*a164);
  a163=(a068*a163);
  a165=(a026*a165);
  a163=(a163+a165);
  a164=(a164-a163);
  a164=(a136*a164);
  a124=(a124+a164);
  if (res[1]!=0) res[1][12]=a124;
  a124=(a110*a125);
  a124=(a159-a124);
  a164=(a078*a124);
  a163=(a114*a125);
  a120=(a120-a163);
  a163=(a035*a120);
  a164=(a164+a163);
  a163=(a116*a125);
  a165=(a031*a163);
  a164=(a164+a165);
  a164=(a134*a164);
  a165=(a083*a124);
  a162=(a039*a120);
  a165=(a165+a162);
  a162=(a037*a163);
  a165=(a165+a162);
  a165=(a147*a165);
  a164=(a164+a165);
  a124=(a068*a124);
  a120=(a026*a120);
  a124=(a124+a120);
  a163=(a021*a163);
  a124=(a124+a163);
  a124=(a148*a124);
  a164=(a164+a124);
  if (res[1]!=0) res[1][13]=a164;
  a164=(a137*a125);
  a131=(a131-a164);
  a164=(a035*a131);
  a124=(a127*a125);
  a166=(a166-a124);
  a124=(a078*a166);
  a164=(a164-a124);
  a125=(a140*a125);
  a159=(a159-a125);
  a125=(a031*a159);
  a164=(a164+a125);
  a164=(a144*a164);
  a125=(a039*a131);
  a124=(a083*a166);
  a125=(a125-a124);
  a124=(a037*a159);
  a125=(a125+a124);
  a125=(a152*a125);
  a164=(a164+a125);
  a131=(a026*a131);
  a166=(a068*a166);
  a131=(a131-a166);
  a159=(a021*a159);
  a131=(a131+a159);
  a131=(a153*a131);
  a164=(a164+a131);
  if (res[1]!=0) res[1][14]=a164;
  a157=(a150*a157);
  a157=(a157+a158);
  if (res[1]!=0) res[1][15]=a157;
  a119=(a150*a119);
  a119=(a119-a155);
  if (res[1]!=0) res[1][16]=a119;
  a118=(a149*a118);
  a118=(a150*a118);
  a118=(a118+a154);
  a118=(a118+a161);
  if (res[1]!=0) res[1][17]=a118;
  a118=1.7320508075688774e+00;
  a118=(a118*a001);
  a161=(a103*a118);
  a154=(a000*a161);
  a154=(a108*a154);
  a119=(a123*a118);
  a155=(a105*a119);
  a157=(a122*a155);
  a157=(a154-a157);
  a158=(a078*a157);
  a164=(a000*a119);
  a164=(a108*a164);
  a131=(a129*a155);
  a131=(a164-a131);
  a159=(a035*a131);
  a158=(a158-a159);
  a159=(a108*a118);
  a166=(a133*a155);
  a166=(a159-a166);
  a125=(a031*a166);
  a158=(a158+a125);
  a158=(a112*a158);
  a125=(a083*a157);
  a124=(a039*a131);
  a125=(a125-a124);
  a124=(a037*a166);
  a125=(a125+a124);
  a125=(a135*a125);
  a158=(a158+a125);
  a157=(a068*a157);
  a131=(a026*a131);
  a157=(a157-a131);
  a166=(a021*a166);
  a157=(a157+a166);
  a157=(a136*a157);
  a158=(a158+a157);
  if (res[1]!=0) res[1][18]=a158;
  a158=(a079*a118);
  a157=(a000*a158);
  a157=(a108*a157);
  a166=(a110*a155);
  a166=(a157-a166);
  a131=(a078*a166);
  a125=(a114*a155);
  a125=(a125+a159);
  a124=(a035*a125);
  a131=(a131-a124);
  a124=(a116*a155);
  a164=(a164-a124);
  a124=(a031*a164);
  a131=(a131-a124);
  a131=(a134*a131);
  a124=(a083*a166);
  a163=(a039*a125);
  a124=(a124-a163);
  a163=(a037*a164);
  a124=(a124-a163);
  a124=(a147*a124);
  a131=(a131+a124);
  a166=(a068*a166);
  a125=(a026*a125);
  a166=(a166-a125);
  a164=(a021*a164);
  a166=(a166-a164);
  a166=(a148*a166);
  a131=(a131+a166);
  if (res[1]!=0) res[1][19]=a131;
  a131=(a127*a155);
  a166=(a078*a131);
  a164=(a137*a155);
  a164=(a154-a164);
  a125=(a035*a164);
  a166=(a166+a125);
  a155=(a140*a155);
  a155=(a157-a155);
  a125=(a031*a155);
  a166=(a166+a125);
  a166=(a144*a166);
  a125=(a083*a131);
  a124=(a039*a164);
  a125=(a125+a124);
  a124=(a037*a155);
  a125=(a125+a124);
  a125=(a152*a125);
  a166=(a166+a125);
  a131=(a068*a131);
  a164=(a026*a164);
  a131=(a131+a164);
  a155=(a021*a155);
  a131=(a131+a155);
  a131=(a153*a131);
  a166=(a166+a131);
  if (res[1]!=0) res[1][20]=a166;
  a158=(a149*a158);
  a166=(a150*a158);
  a161=(a149*a161);
  a131=(a151*a161);
  a155=(a166+a131);
  a119=(a149*a119);
  a119=(a156*a119);
  a155=(a155+a119);
  if (res[1]!=0) res[1][21]=a155;
  a155=8.6602540378443871e-01;
  a155=(a155*a001);
  a119=(a150*a155);
  a164=(a156*a161);
  a164=(a119+a164);
  if (res[1]!=0) res[1][22]=a164;
  a164=(a156*a158);
  a125=(a151*a155);
  a164=(a164-a125);
  if (res[1]!=0) res[1][23]=a164;
  a164=(a098*a118);
  a124=(a000*a164);
  a124=(a108*a124);
  a163=(a160*a118);
  a120=(a105*a163);
  a165=(a122*a120);
  a165=(a124-a165);
  a162=(a078*a165);
  a143=(a129*a120);
  a167=(a035*a143);
  a162=(a162+a167);
  a167=(a133*a120);
  a167=(a157-a167);
  a168=(a031*a167);
  a162=(a162+a168);
  a162=(a112*a162);
  a168=(a083*a165);
  a169=(a039*a143);
  a168=(a168+a169);
  a169=(a037*a167);
  a168=(a168+a169);
  a168=(a135*a168);
  a162=(a162+a168);
  a165=(a068*a165);
  a143=(a026*a143);
  a165=(a165+a143);
  a167=(a021*a167);
  a165=(a165+a167);
  a165=(a136*a165);
  a162=(a162+a165);
  if (res[1]!=0) res[1][24]=a162;
  a162=(a110*a120);
  a162=(a159-a162);
  a165=(a078*a162);
  a167=(a114*a120);
  a157=(a157-a167);
  a167=(a035*a157);
  a165=(a165+a167);
  a167=(a000*a163);
  a167=(a108*a167);
  a143=(a116*a120);
  a143=(a167-a143);
  a168=(a031*a143);
  a165=(a165-a168);
  a165=(a134*a165);
  a168=(a083*a162);
  a169=(a039*a157);
  a168=(a168+a169);
  a169=(a037*a143);
  a168=(a168-a169);
  a168=(a147*a168);
  a165=(a165+a168);
  a162=(a068*a162);
  a157=(a026*a157);
  a162=(a162+a157);
  a143=(a021*a143);
  a162=(a162-a143);
  a162=(a148*a162);
  a165=(a165+a162);
  if (res[1]!=0) res[1][25]=a165;
  a165=(a137*a120);
  a165=(a124-a165);
  a162=(a035*a165);
  a143=(a127*a120);
  a167=(a167-a143);
  a143=(a078*a167);
  a162=(a162-a143);
  a120=(a140*a120);
  a120=(a120+a159);
  a143=(a031*a120);
  a162=(a162-a143);
  a162=(a144*a162);
  a143=(a039*a165);
  a157=(a083*a167);
  a143=(a143-a157);
  a157=(a037*a120);
  a143=(a143-a157);
  a143=(a152*a143);
  a162=(a162+a143);
  a165=(a026*a165);
  a167=(a068*a167);
  a165=(a165-a167);
  a120=(a021*a120);
  a165=(a165-a120);
  a165=(a153*a165);
  a162=(a162+a165);
  if (res[1]!=0) res[1][26]=a162;
  a164=(a149*a164);
  a162=(a151*a164);
  a162=(a162-a119);
  if (res[1]!=0) res[1][27]=a162;
  a163=(a149*a163);
  a163=(a151*a163);
  a166=(a166+a163);
  a163=(a156*a164);
  a166=(a166+a163);
  if (res[1]!=0) res[1][28]=a166;
  a158=(a151*a158);
  a155=(a156*a155);
  a158=(a158+a155);
  if (res[1]!=0) res[1][29]=a158;
  a118=(a142*a118);
  a158=(a105*a118);
  a166=(a133*a158);
  a166=(a154-a166);
  a162=(a031*a166);
  a119=(a122*a158);
  a119=(a119+a159);
  a165=(a078*a119);
  a120=(a000*a118);
  a120=(a108*a120);
  a167=(a129*a158);
  a167=(a120-a167);
  a143=(a035*a167);
  a165=(a165+a143);
  a162=(a162-a165);
  a162=(a112*a162);
  a165=(a037*a166);
  a143=(a083*a119);
  a157=(a039*a167);
  a143=(a143+a157);
  a165=(a165-a143);
  a165=(a135*a165);
  a162=(a162+a165);
  a166=(a021*a166);
  a119=(a068*a119);
  a167=(a026*a167);
  a119=(a119+a167);
  a166=(a166-a119);
  a166=(a136*a166);
  a162=(a162+a166);
  if (res[1]!=0) res[1][30]=a162;
  a162=(a110*a158);
  a162=(a124-a162);
  a166=(a078*a162);
  a119=(a114*a158);
  a154=(a154-a119);
  a119=(a035*a154);
  a166=(a166+a119);
  a119=(a116*a158);
  a167=(a031*a119);
  a166=(a166+a167);
  a166=(a134*a166);
  a167=(a083*a162);
  a165=(a039*a154);
  a167=(a167+a165);
  a165=(a037*a119);
  a167=(a167+a165);
  a167=(a147*a167);
  a166=(a166+a167);
  a162=(a068*a162);
  a154=(a026*a154);
  a162=(a162+a154);
  a119=(a021*a119);
  a162=(a162+a119);
  a162=(a148*a162);
  a166=(a166+a162);
  if (res[1]!=0) res[1][31]=a166;
  a166=(a137*a158);
  a159=(a159-a166);
  a166=(a035*a159);
  a162=(a127*a158);
  a120=(a120-a162);
  a162=(a078*a120);
  a166=(a166-a162);
  a158=(a140*a158);
  a124=(a124-a158);
  a158=(a031*a124);
  a166=(a166+a158);
  a166=(a144*a166);
  a158=(a039*a159);
  a162=(a083*a120);
  a158=(a158-a162);
  a162=(a037*a124);
  a158=(a158+a162);
  a158=(a152*a158);
  a166=(a166+a158);
  a159=(a026*a159);
  a120=(a068*a120);
  a159=(a159-a120);
  a124=(a021*a124);
  a159=(a159+a124);
  a159=(a153*a159);
  a166=(a166+a159);
  if (res[1]!=0) res[1][32]=a166;
  a164=(a150*a164);
  a164=(a164+a125);
  if (res[1]!=0) res[1][33]=a164;
  a161=(a150*a161);
  a161=(a161-a155);
  if (res[1]!=0) res[1][34]=a161;
  a118=(a149*a118);
  a118=(a150*a118);
  a118=(a118+a131);
  a118=(a118+a163);
  if (res[1]!=0) res[1][35]=a118;
  if (res[1]!=0) res[1][36]=a065;
  if (res[1]!=0) res[1][37]=a065;
  if (res[1]!=0) res[1][38]=a065;
  a099=(a099/a006);
  a099=(a005+a099);
  if (res[1]!=0) res[1][39]=a099;
  a130=(a130/a006);
  a099=(a079/a019);
  a130=(a130-a099);
  if (res[1]!=0) res[1][40]=a130;
  a130=(a103/a019);
  a139=(a139/a006);
  a139=(a130+a139);
  if (res[1]!=0) res[1][41]=a139;
  if (res[1]!=0) res[1][42]=a065;
  if (res[1]!=0) res[1][43]=a065;
  if (res[1]!=0) res[1][44]=a065;
  a121=(a121/a006);
  a099=(a099+a121);
  if (res[1]!=0) res[1][45]=a099;
  a104=(a104/a006);
  a104=(a005+a104);
  if (res[1]!=0) res[1][46]=a104;
  a132=(a132/a006);
  a104=(a098/a019);
  a132=(a132-a104);
  if (res[1]!=0) res[1][47]=a132;
  if (res[1]!=0) res[1][48]=a065;
  if (res[1]!=0) res[1][49]=a065;
  if (res[1]!=0) res[1][50]=a065;
  a109=(a109/a006);
  a109=(a109-a130);
  if (res[1]!=0) res[1][51]=a109;
  a113=(a113/a006);
  a104=(a104+a113);
  if (res[1]!=0) res[1][52]=a104;
  a107=(a107/a006);
  a107=(a005+a107);
  if (res[1]!=0) res[1][53]=a107;
  a107=(a128*a031);
  a104=(a146*a035);
  a107=(a107-a104);
  a107=(a112*a107);
  a104=(a128*a037);
  a113=(a146*a039);
  a104=(a104-a113);
  a104=(a135*a104);
  a107=(a107+a104);
  a104=(a128*a021);
  a113=(a146*a026);
  a104=(a104-a113);
  a104=(a136*a104);
  a107=(a107+a104);
  if (res[2]!=0) res[2][0]=a107;
  a107=(a115*a031);
  a104=(a117*a035);
  a107=(a107-a104);
  a107=(a134*a107);
  a104=(a115*a037);
  a113=(a117*a039);
  a104=(a104-a113);
  a104=(a147*a104);
  a107=(a107+a104);
  a104=(a115*a021);
  a113=(a117*a026);
  a104=(a104-a113);
  a104=(a148*a104);
  a107=(a107+a104);
  if (res[2]!=0) res[2][1]=a107;
  a107=(a138*a031);
  a104=(a141*a035);
  a107=(a107-a104);
  a107=(a144*a107);
  a104=(a138*a037);
  a113=(a141*a039);
  a104=(a104-a113);
  a104=(a152*a104);
  a107=(a107+a104);
  a104=(a138*a021);
  a113=(a141*a026);
  a104=(a104-a113);
  a104=(a153*a104);
  a107=(a107+a104);
  if (res[2]!=0) res[2][2]=a107;
  if (res[2]!=0) res[2][3]=a065;
  if (res[2]!=0) res[2][4]=a065;
  if (res[2]!=0) res[2][5]=a065;
  a107=(a146*a078);
  a104=(a145*a031);
  a107=(a107-a104);
  a107=(a112*a107);
  a104=(a146*a083);
  a113=(a145*a037);
  a104=(a104-a113);
  a104=(a135*a104);
  a107=(a107+a104);
  a146=(a146*a068);
  a104=(a145*a021);
  a146=(a146-a104);
  a146=(a136*a146);
  a107=(a107+a146);
  if (res[2]!=0) res[2][6]=a107;
  a107=(a117*a078);
  a146=(a111*a031);
  a107=(a107-a146);
  a107=(a134*a107);
  a146=(a117*a083);
  a104=(a111*a037);
  a146=(a146-a104);
  a146=(a147*a146);
  a107=(a107+a146);
  a117=(a117*a068);
  a146=(a111*a021);
  a117=(a117-a146);
  a117=(a148*a117);
  a107=(a107+a117);
  if (res[2]!=0) res[2][7]=a107;
  a107=(a141*a078);
  a117=(a126*a031);
  a107=(a107-a117);
  a107=(a144*a107);
  a117=(a141*a083);
  a146=(a126*a037);
  a117=(a117-a146);
  a117=(a152*a117);
  a107=(a107+a117);
  a141=(a141*a068);
  a117=(a126*a021);
  a141=(a141-a117);
  a141=(a153*a141);
  a107=(a107+a141);
  if (res[2]!=0) res[2][8]=a107;
  if (res[2]!=0) res[2][9]=a065;
  if (res[2]!=0) res[2][10]=a065;
  if (res[2]!=0) res[2][11]=a065;
  a107=(a145*a035);
  a141=(a128*a078);
  a107=(a107-a141);
  a107=(a112*a107);
  a141=(a145*a039);
  a117=(a128*a083);
  a141=(a141-a117);
  a141=(a135*a141);
  a107=(a107+a141);
  a145=(a145*a026);
  a128=(a128*a068);
  a145=(a145-a128);
  a145=(a136*a145);
  a107=(a107+a145);
  if (res[2]!=0) res[2][12]=a107;
  a107=(a111*a035);
  a145=(a115*a078);
  a107=(a107-a145);
  a107=(a134*a107);
  a145=(a111*a039);
  a128=(a115*a083);
  a145=(a145-a128);
  a145=(a147*a145);
  a107=(a107+a145);
  a111=(a111*a026);
  a115=(a115*a068);
  a111=(a111-a115);
  a111=(a148*a111);
  a107=(a107+a111);
  if (res[2]!=0) res[2][13]=a107;
  a107=(a126*a035);
  a111=(a138*a078);
  a107=(a107-a111);
  a107=(a144*a107);
  a111=(a126*a039);
  a115=(a138*a083);
  a111=(a111-a115);
  a111=(a152*a111);
  a107=(a107+a111);
  a126=(a126*a026);
  a138=(a138*a068);
  a126=(a126-a138);
  a126=(a153*a126);
  a107=(a107+a126);
  if (res[2]!=0) res[2][14]=a107;
  if (res[2]!=0) res[2][15]=a065;
  if (res[2]!=0) res[2][16]=a065;
  if (res[2]!=0) res[2][17]=a065;
  if (res[2]!=0) res[2][18]=a065;
  if (res[2]!=0) res[2][19]=a065;
  if (res[2]!=0) res[2][20]=a065;
  if (res[2]!=0) res[2][21]=a065;
  if (res[2]!=0) res[2][22]=a065;
  if (res[2]!=0) res[2][23]=a065;
  if (res[2]!=0) res[2][24]=a065;
  if (res[2]!=0) res[2][25]=a065;
  if (res[2]!=0) res[2][26]=a065;
  if (res[2]!=0) res[2][27]=a065;
  if (res[2]!=0) res[2][28]=a065;
  if (res[2]!=0) res[2][29]=a065;
  if (res[2]!=0) res[2][30]=a065;
  if (res[2]!=0) res[2][31]=a065;
  if (res[2]!=0) res[2][32]=a065;
  if (res[2]!=0) res[2][33]=a065;
  if (res[2]!=0) res[2][34]=a065;
  if (res[2]!=0) res[2][35]=a065;
  a107=1.5000000000000002e+00;
  a126=(a008/a019);
  a138=(a017*a126);
  a111=(a017*a100);
  a115=(a015/a019);
  a145=(a017*a115);
  a128=(a145*a088);
  a111=(a111-a128);
  a128=(a138*a106);
  a111=(a111+a128);
  a128=(2.*a111);
  a128=(a128*a002);
  a028=(a028/a006);
  a141=(a126+a028);
  a117=(a001*a150);
  a117=(a000*a117);
  a146=(a141*a117);
  a012=(a012/a006);
  a012=(a005+a012);
  a104=(a001*a151);
  a104=(a000*a104);
  a113=(a012*a104);
  a146=(a146+a113);
  a040=(a040/a006);
  a113=(a040-a115);
  a109=(a001*a156);
  a109=(a000*a109);
  a130=(a113*a109);
  a146=(a146+a130);
  a128=(a128-a146);
  a128=(a128/a002);
  a146=(a138*a128);
  a130=(a011/a019);
  a132=(a017*a130);
  a099=(a017*a088);
  a121=(a145*a100);
  a099=(a099+a121);
  a121=(a132*a106);
  a099=(a099-a121);
  a121=(2.*a099);
  a139=(a149*a001);
  a121=(a121*a139);
  a080=(a080/a006);
  a118=(a080-a130);
  a163=(a118*a117);
  a075=(a075/a006);
  a131=(a115+a075);
  a161=(a131*a104);
  a163=(a163+a161);
  a009=(a009/a006);
  a009=(a005+a009);
  a161=(a009*a109);
  a163=(a163+a161);
  a121=(a121-a163);
  a121=(a121/a002);
  a163=(a132*a121);
  a146=(a146-a163);
  a163=(a132*a088);
  a161=(a138*a100);
  a163=(a163-a161);
  a161=(a017*a106);
  a163=(a163+a161);
  a161=(2.*a163);
  a155=7.5000000000000000e-01;
  a155=(a155*a001);
  a161=(a161*a155);
  a016=(a016/a006);
  a016=(a005+a016);
  a164=(a016*a117);
  a023=(a023/a006);
  a125=(a023-a126);
  a166=(a125*a104);
  a164=(a164+a166);
  a044=(a044/a006);
  a166=(a130+a044);
  a159=(a166*a109);
  a164=(a164+a159);
  a161=(a161-a164);
  a161=(a161/a002);
  a164=(a017*a161);
  a146=(a146+a164);
  a164=(a107*a146);
  a159=-3.2320508075688776e+00;
  a124=(a043/a019);
  a120=(a055*a124);
  a158=(a055*a102);
  a162=(a053/a019);
  a119=(a055*a162);
  a154=(a119*a097);
  a158=(a158-a154);
  a154=(a120*a096);
  a158=(a158+a154);
  a154=(2.*a158);
  a154=(a154*a002);
  a062=(a062/a006);
  a167=(a124+a062);
  a165=(a167*a117);
  a154=(a154-a165);
  a050=(a050/a006);
  a050=(a005+a050);
  a165=(a050*a104);
  a154=(a154-a165);
  a058=(a058/a006);
  a165=(a058-a162);
  a143=(a165*a109);
  a154=(a154-a143);
  a154=(a154/a002);
  a143=(a120*a154);
  a019=(a049/a019);
  a157=(a055*a019);
  a168=(a055*a097);
  a169=(a119*a102);
  a168=(a168+a169);
  a169=(a157*a096);
  a168=(a168-a169);
  a169=(2.*a168);
  a169=(a169*a139);
  a089=(a089/a006);
  a170=(a089-a019);
  a171=(a170*a117);
  a169=(a169-a171);
  a084=(a084/a006);
  a171=(a162+a084);
  a172=(a171*a104);
  a169=(a169-a172);
  a047=(a047/a006);
  a047=(a005+a047);
  a172=(a047*a109);
  a169=(a169-a172);
  a169=(a169/a002);
  a172=(a157*a169);
  a143=(a143-a172);
  a172=(a157*a097);
  a173=(a120*a102);
  a172=(a172-a173);
  a173=(a055*a096);
  a172=(a172+a173);
  a173=(2.*a172);
  a173=(a173*a155);
  a054=(a054/a006);
  a005=(a005+a054);
  a054=(a005*a117);
  a173=(a173-a054);
  a059=(a059/a006);
  a054=(a059-a124);
  a174=(a054*a104);
  a173=(a173-a174);
  a072=(a072/a006);
  a006=(a019+a072);
  a174=(a006*a109);
  a173=(a173-a174);
  a173=(a173/a002);
  a174=(a055*a173);
  a143=(a143+a174);
  a174=(a159*a143);
  a164=(a164+a174);
  a174=(2.*a015);
  a175=5.3867513459481287e-01;
  a176=2.3205080756887719e-01;
  a146=(a176*a146);
  a143=(a107*a143);
  a146=(a146+a143);
  a143=(a001*a146);
  a177=(a175*a143);
  a177=(a117+a177);
  a178=(a001*a164);
  a179=(a149*a178);
  a177=(a177+a179);
  a179=(a163*a177);
  a179=(a149*a179);
  a180=(a174*a179);
  a180=(a164-a180);
  a181=(a111*a177);
  a182=(a149*a181);
  a183=(a011*a182);
  a180=(a180-a183);
  a183=(a099*a177);
  a184=(a149*a183);
  a185=(a008*a184);
  a180=(a180-a185);
  a185=(a145*a121);
  a186=(a017*a128);
  a185=(a185+a186);
  a186=(a138*a161);
  a185=(a185-a186);
  a186=(a176*a185);
  a187=(a119*a169);
  a188=(a055*a154);
  a187=(a187+a188);
  a188=(a120*a173);
  a187=(a187-a188);
  a188=(a107*a187);
  a186=(a186+a188);
  a188=(a001*a186);
  a189=(a175*a188);
  a189=(a104+a189);
  a185=(a107*a185);
  a187=(a159*a187);
  a185=(a185+a187);
  a187=(a001*a185);
  a190=(a149*a187);
  a189=(a189+a190);
  a190=(a163*a189);
  a191=(a149*a190);
  a192=(a011*a191);
  a180=(a180-a192);
  a192=(a099*a189);
  a193=(a000*a192);
  a180=(a180-a193);
  a193=(a017*a121);
  a194=(a145*a128);
  a193=(a193-a194);
  a194=(a132*a161);
  a193=(a193+a194);
  a194=(a176*a193);
  a195=(a055*a169);
  a196=(a119*a154);
  a195=(a195-a196);
  a196=(a157*a173);
  a195=(a195+a196);
  a196=(a107*a195);
  a194=(a194+a196);
  a196=(a001*a194);
  a197=(a175*a196);
  a197=(a109+a197);
  a193=(a107*a193);
  a195=(a159*a195);
  a193=(a193+a195);
  a195=(a001*a193);
  a198=(a149*a195);
  a197=(a197+a198);
  a198=(a163*a197);
  a199=(a149*a198);
  a200=(a008*a199);
  a180=(a180-a200);
  a200=(a111*a197);
  a201=(a000*a200);
  a180=(a180+a201);
  a201=(a008*a014);
  a202=(a015*a007);
  a203=(a201+a202);
  a204=(a149*a203);
  a205=(a000*a010);
  a206=(a204-a205);
  a207=(a180*a206);
  a208=(a000*a007);
  a209=(a017*a208);
  a013=(a017/a013);
  a210=(2.*a008);
  a211=(a210*a007);
  a212=(2.*a011);
  a213=(a212*a010);
  a214=(a211+a213);
  a215=(a174*a014);
  a214=(a214+a215);
  a013=(a013*a214);
  a214=(a126*a013);
  a209=(a209-a214);
  a214=(a128*a209);
  a216=(a106*a209);
  a217=(a100*a013);
  a218=(a000*a014);
  a219=(a017*a218);
  a220=(a115*a013);
  a219=(a219-a220);
  a220=(a088*a219);
  a217=(a217+a220);
  a216=(a216-a217);
  a217=(2.*a216);
  a217=(a002*a217);
  a217=(a217+a111);
  a220=(a011*a014);
  a221=(a015*a010);
  a222=(a220+a221);
  a223=(a149*a222);
  a224=(a208+a223);
  a225=(a117*a224);
  a226=(a000*a150);
  a227=(a141*a226);
  a225=(a225+a227);
  a227=(a149*a213);
  a228=(a104*a227);
  a229=(a000*a151);
  a230=(a012*a229);
  a228=(a228+a230);
  a225=(a225+a228);
  a228=(a011*a007);
  a230=(a008*a010);
  a231=(a228+a230);
  a232=(a149*a231);
  a233=(a232-a218);
  a234=(a109*a233);
  a235=(a000*a156);
  a236=(a113*a235);
  a234=(a234+a236);
  a225=(a225+a234);
  a217=(a217-a225);
  a217=(a217/a002);
  a225=(a128/a002);
  a225=(a000*a225);
  a217=(a217-a225);
  a225=(a138*a217);
  a214=(a214+a225);
  a225=(a017*a205);
  a234=(a130*a013);
  a225=(a225-a234);
  a234=(a121*a225);
  a236=(a100*a219);
  a237=(a088*a013);
  a236=(a236-a237);
  a237=(a106*a225);
  a236=(a236-a237);
  a237=(2.*a236);
  a237=(a139*a237);
  a238=(a000*a099);
  a237=(a237+a238);
  a206=(a117*a206);
  a238=(a118*a226);
  a206=(a206+a238);
  a230=(a230+a228);
  a228=(a149*a230);
  a238=(a218+a228);
  a239=(a104*a238);
  a240=(a131*a229);
  a239=(a239+a240);
  a206=(a206+a239);
  a239=(a149*a211);
  a240=(a109*a239);
  a241=(a009*a235);
  a240=(a240+a241);
  a206=(a206+a240);
  a237=(a237-a206);
  a237=(a237/a002);
  a206=(a121/a002);
  a206=(a000*a206);
  a237=(a237-a206);
  a206=(a132*a237);
  a234=(a234+a206);
  a214=(a214-a234);
  a088=(a088*a225);
  a100=(a100*a209);
  a088=(a088-a100);
  a106=(a106*a013);
  a088=(a088-a106);
  a106=(2.*a088);
  a106=(a155*a106);
  a100=1.5000000000000000e+00;
  a234=(a100*a163);
  a106=(a106+a234);
  a234=(a149*a215);
  a206=(a117*a234);
  a240=(a016*a226);
  a206=(a206+a240);
  a221=(a221+a220);
  a220=(a149*a221);
  a240=(a220-a208);
  a241=(a104*a240);
  a242=(a125*a229);
  a241=(a241+a242);
  a206=(a206+a241);
  a202=(a202+a201);
  a201=(a149*a202);
  a241=(a205+a201);
  a242=(a109*a241);
  a243=(a166*a235);
  a242=(a242+a243);
  a206=(a206+a242);
  a106=(a106-a206);
  a106=(a106/a002);
  a206=(a161/a002);
  a206=(a000*a206);
  a106=(a106-a206);
  a206=(a017*a106);
  a242=(a161*a013);
  a206=(a206-a242);
  a214=(a214+a206);
  a206=(a107*a214);
  a242=(a000*a032);
  a243=(a055*a242);
  a051=(a055/a051);
  a244=(2.*a043);
  a245=(a244*a032);
  a246=(2.*a049);
  a247=(a246*a048);
  a248=(a245+a247);
  a249=(2.*a053);
  a250=(a249*a052);
  a248=(a248+a250);
  a051=(a051*a248);
  a248=(a124*a051);
  a243=(a243-a248);
  a248=(a154*a243);
  a251=(a096*a243);
  a252=(a102*a051);
  a253=(a000*a052);
  a254=(a055*a253);
  a255=(a162*a051);
  a254=(a254-a255);
  a255=(a097*a254);
  a252=(a252+a255);
  a251=(a251-a252);
  a252=(2.*a251);
  a252=(a002*a252);
  a252=(a252+a158);
  a255=(a049*a052);
  a256=(a053*a048);
  a257=(a255+a256);
  a258=(a149*a257);
  a259=(a242+a258);
  a260=(a117*a259);
  a261=(a167*a226);
  a260=(a260+a261);
  a252=(a252-a260);
  a260=(a149*a247);
  a261=(a104*a260);
  a262=(a050*a229);
  a261=(a261+a262);
  a252=(a252-a261);
  a261=(a049*a032);
  a262=(a043*a048);
  a263=(a261+a262);
  a264=(a149*a263);
  a265=(a264-a253);
  a266=(a109*a265);
  a267=(a165*a235);
  a266=(a266+a267);
  a252=(a252-a266);
  a252=(a252/a002);
  a266=(a154/a002);
  a266=(a000*a266);
  a252=(a252-a266);
  a266=(a120*a252);
  a248=(a248+a266);
  a266=(a000*a048);
  a267=(a055*a266);
  a268=(a019*a051);
  a267=(a267-a268);
  a268=(a169*a267);
  a269=(a102*a254);
  a270=(a097*a051);
  a269=(a269-a270);
  a270=(a096*a267);
  a269=(a269-a270);
  a270=(2.*a269);
  a139=(a139*a270);
  a270=(a000*a168);
  a139=(a139+a270);
  a270=(a043*a052);
  a271=(a053*a032);
  a272=(a270+a271);
  a273=(a149*a272);
  a274=(a273-a266);
  a275=(a117*a274);
  a276=(a170*a226);
  a275=(a275+a276);
  a139=(a139-a275);
  a262=(a262+a261);
  a261=(a149*a262);
  a275=(a253+a261);
  a276=(a104*a275);
  a277=(a171*a229);
  a276=(a276+a277);
  a139=(a139-a276);
  a276=(a149*a245);
  a277=(a109*a276);
  a278=(a047*a235);
  a277=(a277+a278);
  a139=(a139-a277);
  a139=(a139/a002);
  a277=(a169/a002);
  a277=(a000*a277);
  a139=(a139-a277);
  a277=(a157*a139);
  a268=(a268+a277);
  a248=(a248-a268);
  a097=(a097*a267);
  a102=(a102*a243);
  a097=(a097-a102);
  a096=(a096*a051);
  a097=(a097-a096);
  a096=(2.*a097);
  a155=(a155*a096);
  a100=(a100*a172);
  a155=(a155+a100);
  a100=(a149*a250);
  a096=(a117*a100);
  a102=(a005*a226);
  a096=(a096+a102);
  a155=(a155-a096);
  a256=(a256+a255);
  a255=(a149*a256);
  a096=(a255-a242);
  a102=(a104*a096);
  a268=(a054*a229);
  a102=(a102+a268);
  a155=(a155-a102);
  a271=(a271+a270);
  a270=(a149*a271);
  a102=(a266+a270);
  a268=(a109*a102);
  a277=(a006*a235);
  a268=(a268+a277);
  a155=(a155-a268);
  a155=(a155/a002);
  a268=(a173/a002);
  a268=(a000*a268);
  a155=(a155-a268);
  a268=(a055*a155);
  a277=(a173*a051);
  a268=(a268-a277);
  a248=(a248+a268);
  a268=(a159*a248);
  a206=(a206+a268);
  a268=(2.*a014);
  a179=(a179*a268);
  a268=(a177*a088);
  a214=(a176*a214);
  a248=(a107*a248);
  a214=(a214+a248);
  a248=(a001*a214);
  a248=(a146+a248);
  a277=(a175*a248);
  a277=(a226+a277);
  a278=(a001*a206);
  a164=(a164+a278);
  a278=(a149*a164);
  a277=(a277+a278);
  a278=(a163*a277);
  a268=(a268+a278);
  a268=(a149*a268);
  a174=(a174*a268);
  a179=(a179+a174);
  a206=(a206-a179);
  a179=(a182*a010);
  a174=(a177*a216);
  a268=(a111*a277);
  a174=(a174+a268);
  a268=(a149*a174);
  a278=(a011*a268);
  a179=(a179+a278);
  a206=(a206-a179);
  a179=(a184*a007);
  a177=(a177*a236);
  a277=(a099*a277);
  a177=(a177+a277);
  a277=(a149*a177);
  a278=(a008*a277);
  a179=(a179+a278);
  a206=(a206-a179);
  a179=(a191*a010);
  a278=(a189*a088);
  a279=(a121*a219);
  a280=(a145*a237);
  a279=(a279+a280);
  a280=(a017*a217);
  a281=(a128*a013);
  a280=(a280-a281);
  a279=(a279+a280);
  a209=(a161*a209);
  a138=(a138*a106);
  a209=(a209+a138);
  a279=(a279-a209);
  a209=(a176*a279);
  a138=(a169*a254);
  a280=(a119*a139);
  a138=(a138+a280);
  a280=(a055*a252);
  a281=(a154*a051);
  a280=(a280-a281);
  a138=(a138+a280);
  a243=(a173*a243);
  a120=(a120*a155);
  a243=(a243+a120);
  a138=(a138-a243);
  a243=(a107*a138);
  a209=(a209+a243);
  a243=(a001*a209);
  a243=(a186+a243);
  a120=(a175*a243);
  a120=(a229+a120);
  a279=(a107*a279);
  a138=(a159*a138);
  a279=(a279+a138);
  a138=(a001*a279);
  a138=(a185+a138);
  a280=(a149*a138);
  a120=(a120+a280);
  a280=(a163*a120);
  a278=(a278+a280);
  a280=(a149*a278);
  a281=(a011*a280);
  a179=(a179+a281);
  a206=(a206-a179);
  a179=(a189*a236);
  a281=(a099*a120);
  a179=(a179+a281);
  a281=(a000*a179);
  a206=(a206-a281);
  a281=(a199*a007);
  a282=(a197*a088);
  a237=(a017*a237);
  a121=(a121*a013);
  a237=(a237-a121);
  a128=(a128*a219);
  a145=(a145*a217);
  a128=(a128+a145);
  a237=(a237-a128);
  a161=(a161*a225);
  a132=(a132*a106);
  a161=(a161+a132);
  a237=(a237+a161);
  a176=(a176*a237);
  a139=(a055*a139);
  a169=(a169*a051);
  a139=(a139-a169);
  a154=(a154*a254);
  a119=(a119*a252);
  a154=(a154+a119);
  a139=(a139-a154);
  a173=(a173*a267);
  a157=(a157*a155);
  a173=(a173+a157);
  a139=(a139+a173);
  a173=(a107*a139);
  a176=(a176+a173);
  a173=(a001*a176);
  a173=(a194+a173);
  a175=(a175*a173);
  a175=(a235+a175);
  a107=(a107*a237);
  a159=(a159*a139);
  a107=(a107+a159);
  a159=(a001*a107);
  a159=(a193+a159);
  a139=(a149*a159);
  a175=(a175+a139);
  a139=(a163*a175);
  a282=(a282+a139);
  a139=(a149*a282);
  a237=(a008*a139);
  a281=(a281+a237);
  a206=(a206-a281);
  a281=(a197*a216);
  a237=(a111*a175);
  a281=(a281+a237);
  a237=(a000*a281);
  a206=(a206+a237);
  a237=(a118*a206);
  a207=(a207+a237);
  a183=(a000*a183);
  a237=(a015*a182);
  a183=(a183-a237);
  a183=(a183+a185);
  a185=(a015*a191);
  a183=(a183-a185);
  a185=(a111*a189);
  a185=(a149*a185);
  a237=(a212*a185);
  a183=(a183-a237);
  a192=(a149*a192);
  a237=(a008*a192);
  a183=(a183-a237);
  a198=(a000*a198);
  a183=(a183-a198);
  a200=(a149*a200);
  a198=(a008*a200);
  a183=(a183-a198);
  a238=(a183*a238);
  a177=(a000*a177);
  a182=(a182*a014);
  a268=(a015*a268);
  a182=(a182+a268);
  a177=(a177-a182);
  a177=(a177+a279);
  a191=(a191*a014);
  a280=(a015*a280);
  a191=(a191+a280);
  a177=(a177-a191);
  a191=(2.*a010);
  a185=(a185*a191);
  a189=(a189*a216);
  a120=(a111*a120);
  a189=(a189+a120);
  a189=(a149*a189);
  a212=(a212*a189);
  a185=(a185+a212);
  a177=(a177-a185);
  a185=(a192*a007);
  a179=(a149*a179);
  a212=(a008*a179);
  a185=(a185+a212);
  a177=(a177-a185);
  a282=(a000*a282);
  a177=(a177-a282);
  a282=(a200*a007);
  a281=(a149*a281);
  a008=(a008*a281);
  a282=(a282+a008);
  a177=(a177-a282);
  a282=(a131*a177);
  a238=(a238+a282);
  a207=(a207+a238);
  a190=(a000*a190);
  a181=(a000*a181);
  a238=(a015*a184);
  a181=(a181+a238);
  a190=(a190-a181);
  a181=(a011*a192);
  a190=(a190-a181);
  a190=(a190+a193);
  a193=(a015*a199);
  a190=(a190-a193);
  a193=(a011*a200);
  a190=(a190-a193);
  a193=(a099*a197);
  a193=(a149*a193);
  a181=(a210*a193);
  a190=(a190-a181);
  a239=(a190*a239);
  a278=(a000*a278);
  a174=(a000*a174);
  a184=(a184*a014);
  a277=(a015*a277);
  a184=(a184+a277);
  a174=(a174+a184);
  a278=(a278-a174);
  a192=(a192*a010);
  a179=(a011*a179);
  a192=(a192+a179);
  a278=(a278-a192);
  a278=(a278+a107);
  a199=(a199*a014);
  a015=(a015*a139);
  a199=(a199+a015);
  a278=(a278-a199);
  a200=(a200*a010);
  a011=(a011*a281);
  a200=(a200+a011);
  a278=(a278-a200);
  a200=(2.*a007);
  a193=(a193*a200);
  a197=(a197*a236);
  a175=(a099*a175);
  a197=(a197+a175);
  a197=(a149*a197);
  a210=(a210*a197);
  a193=(a193+a210);
  a278=(a278-a193);
  a193=(a009*a278);
  a239=(a239+a193);
  a207=(a207+a239);
  a230=(a000*a230);
  a230=(a230-a014);
  a230=(a017*a230);
  a076=(a076*a013);
  a230=(a230-a076);
  a076=(a068*a230);
  a193=(a215+a211);
  a193=(a000*a193);
  a193=(a017*a193);
  a018=(a018*a013);
  a193=(a193-a018);
  a018=(a026*a193);
  a076=(a076-a018);
  a221=(a000*a221);
  a221=(a007+a221);
  a221=(a017*a221);
  a024=(a024*a013);
  a221=(a221-a024);
  a024=(a021*a221);
  a076=(a076+a024);
  a203=(a000*a203);
  a203=(a010+a203);
  a203=(a017*a203);
  a081=(a081*a013);
  a203=(a203-a081);
  a081=(a078*a203);
  a222=(a000*a222);
  a222=(a222-a007);
  a222=(a017*a222);
  a029=(a029*a013);
  a222=(a222-a029);
  a029=(a035*a222);
  a081=(a081+a029);
  a211=(a213+a211);
  a211=(a000*a211);
  a211=(a017*a211);
  a033=(a033*a013);
  a211=(a211-a033);
  a033=(a031*a211);
  a081=(a081-a033);
  a033=(a027*a081);
  a076=(a076+a033);
  a203=(a083*a203);
  a222=(a039*a222);
  a203=(a203+a222);
  a211=(a037*a211);
  a203=(a203-a211);
  a211=(a036*a203);
  a076=(a076+a211);
  a076=(a004*a076);
  a211=arg[3]? arg[3][3] : 0;
  a236=(a211*a236);
  a076=(a076-a236);
  a076=(a002*a076);
  a236=(a068*a077);
  a222=(a026*a020);
  a236=(a236+a222);
  a222=(a021*a025);
  a236=(a236+a222);
  a222=(a078*a082);
  a033=(a035*a030);
  a222=(a222+a033);
  a033=(a031*a034);
  a222=(a222+a033);
  a033=(a027*a222);
  a236=(a236+a033);
  a082=(a083*a082);
  a030=(a039*a030);
  a082=(a082+a030);
  a034=(a037*a034);
  a082=(a082+a034);
  a034=(a036*a082);
  a236=(a236+a034);
  a034=(a004*a236);
  a030=(a211*a099);
  a034=(a034-a030);
  a030=(a000*a034);
  a076=(a076+a030);
  a207=(a207+a076);
  a207=(a207/a001);
  a118=(a118*a180);
  a131=(a131*a183);
  a118=(a118+a131);
  a009=(a009*a190);
  a118=(a118+a009);
  a034=(a034*a002);
  a118=(a118+a034);
  a118=(a118/a001);
  a118=(a118/a001);
  a207=(a207-a118);
  if (res[3]!=0) res[3][0]=a207;
  a224=(a180*a224);
  a207=(a141*a206);
  a224=(a224+a207);
  a227=(a183*a227);
  a207=(a012*a177);
  a227=(a227+a207);
  a224=(a224+a227);
  a233=(a190*a233);
  a207=(a113*a278);
  a233=(a233+a207);
  a224=(a224+a233);
  a081=(a022*a081);
  a231=(a000*a231);
  a014=(a014+a231);
  a014=(a017*a014);
  a041=(a041*a013);
  a014=(a014-a041);
  a041=(a026*a014);
  a215=(a215+a213);
  a215=(a000*a215);
  a215=(a017*a215);
  a085=(a085*a013);
  a215=(a215-a085);
  a085=(a068*a215);
  a041=(a041-a085);
  a202=(a000*a202);
  a202=(a202-a010);
  a017=(a017*a202);
  a045=(a045*a013);
  a017=(a017-a045);
  a045=(a021*a017);
  a041=(a041+a045);
  a081=(a081-a041);
  a203=(a027*a203);
  a081=(a081+a203);
  a081=(a004*a081);
  a216=(a211*a216);
  a081=(a081-a216);
  a081=(a002*a081);
  a222=(a022*a222);
  a216=(a068*a086);
  a203=(a026*a042);
  a216=(a216+a203);
  a203=(a021*a046);
  a216=(a216+a203);
  a222=(a222-a216);
  a082=(a027*a082);
  a222=(a222+a082);
  a082=(a004*a222);
  a216=(a211*a111);
  a082=(a082-a216);
  a216=(a000*a082);
  a081=(a081+a216);
  a224=(a224+a081);
  a224=(a224/a001);
  a141=(a141*a180);
  a012=(a012*a183);
  a141=(a141+a012);
  a113=(a113*a190);
  a141=(a141+a113);
  a082=(a082*a002);
  a141=(a141+a082);
  a141=(a141/a001);
  a141=(a141/a001);
  a224=(a224-a141);
  if (res[3]!=0) res[3][1]=a224;
  a234=(a180*a234);
  a224=(a016*a206);
  a234=(a234+a224);
  a240=(a183*a240);
  a224=(a125*a177);
  a240=(a240+a224);
  a240=(a234+a240);
  a241=(a190*a241);
  a224=(a166*a278);
  a241=(a241+a224);
  a240=(a240+a241);
  a241=(a039*a014);
  a224=(a083*a215);
  a241=(a241-a224);
  a224=(a037*a017);
  a241=(a241+a224);
  a241=(a022*a241);
  a224=(a078*a230);
  a141=(a035*a193);
  a224=(a224-a141);
  a141=(a031*a221);
  a224=(a224+a141);
  a224=(a036*a224);
  a241=(a241+a224);
  a014=(a035*a014);
  a215=(a078*a215);
  a014=(a014-a215);
  a017=(a031*a017);
  a014=(a014+a017);
  a014=(a038*a014);
  a241=(a241+a014);
  a230=(a083*a230);
  a193=(a039*a193);
  a230=(a230-a193);
  a221=(a037*a221);
  a230=(a230+a221);
  a230=(a038*a230);
  a241=(a241+a230);
  a241=(a004*a241);
  a088=(a211*a088);
  a241=(a241-a088);
  a241=(a002*a241);
  a088=(a083*a086);
  a230=(a039*a042);
  a088=(a088+a230);
  a230=(a037*a046);
  a088=(a088+a230);
  a088=(a022*a088);
  a230=(a078*a077);
  a221=(a035*a020);
  a230=(a230+a221);
  a221=(a031*a025);
  a230=(a230+a221);
  a230=(a036*a230);
  a088=(a088+a230);
  a086=(a078*a086);
  a042=(a035*a042);
  a086=(a086+a042);
  a046=(a031*a046);
  a086=(a086+a046);
  a086=(a038*a086);
  a088=(a088+a086);
  a077=(a083*a077);
  a020=(a039*a020);
  a077=(a077+a020);
  a025=(a037*a025);
  a077=(a077+a025);
  a077=(a038*a077);
  a088=(a088+a077);
  a077=(a004*a088);
  a025=(a211*a163);
  a077=(a077-a025);
  a025=(a000*a077);
  a241=(a241+a025);
  a240=(a240+a241);
  a240=(a240/a001);
  a016=(a016*a180);
  a125=(a125*a183);
  a016=(a016+a125);
  a166=(a166*a190);
  a016=(a016+a166);
  a077=(a077*a002);
  a016=(a016+a077);
  a016=(a016/a001);
  a016=(a016/a001);
  a240=(a240-a016);
  if (res[3]!=0) res[3][2]=a240;
  a262=(a000*a262);
  a262=(a262-a052);
  a262=(a055*a262);
  a071=(a071*a051);
  a262=(a262-a071);
  a071=(a068*a262);
  a240=(a250+a245);
  a240=(a000*a240);
  a240=(a055*a240);
  a056=(a056*a051);
  a240=(a240-a056);
  a056=(a026*a240);
  a071=(a071-a056);
  a256=(a000*a256);
  a256=(a032+a256);
  a256=(a055*a256);
  a060=(a060*a051);
  a256=(a256-a060);
  a060=(a021*a256);
  a071=(a071+a060);
  a272=(a000*a272);
  a272=(a048+a272);
  a272=(a055*a272);
  a090=(a090*a051);
  a272=(a272-a090);
  a090=(a078*a272);
  a257=(a000*a257);
  a257=(a257-a032);
  a257=(a055*a257);
  a063=(a063*a051);
  a257=(a257-a063);
  a063=(a035*a257);
  a090=(a090+a063);
  a245=(a247+a245);
  a245=(a000*a245);
  a245=(a055*a245);
  a066=(a066*a051);
  a245=(a245-a066);
  a066=(a031*a245);
  a090=(a090-a066);
  a066=(a027*a090);
  a071=(a071+a066);
  a272=(a083*a272);
  a257=(a039*a257);
  a272=(a272+a257);
  a245=(a037*a245);
  a272=(a272-a245);
  a245=(a036*a272);
  a071=(a071+a245);
  a071=(a004*a071);
  a245=(a211*a269);
  a071=(a071-a245);
  a071=(a002*a071);
  a245=(a068*a087);
  a257=(a026*a057);
  a245=(a245+a257);
  a257=(a021*a061);
  a245=(a245+a257);
  a257=(a078*a091);
  a066=(a035*a064);
  a257=(a257+a066);
  a066=(a031*a067);
  a257=(a257+a066);
  a066=(a027*a257);
  a245=(a245+a066);
  a091=(a083*a091);
  a064=(a039*a064);
  a091=(a091+a064);
  a067=(a037*a067);
  a091=(a091+a067);
  a067=(a036*a091);
  a245=(a245+a067);
  a067=(a004*a245);
  a064=(a211*a168);
  a067=(a067-a064);
  a064=(a000*a067);
  a071=(a071+a064);
  a143=(a149*a143);
  a117=(a117+a143);
  a143=-3.8675134594812879e-02;
  a178=(a143*a178);
  a117=(a117+a178);
  a178=(a172*a117);
  a178=(a149*a178);
  a064=(a249*a178);
  a146=(a146-a064);
  a064=(a158*a117);
  a066=(a149*a064);
  a063=(a049*a066);
  a146=(a146-a063);
  a063=(a168*a117);
  a060=(a149*a063);
  a056=(a043*a060);
  a146=(a146-a056);
  a188=(a149*a188);
  a104=(a104+a188);
  a187=(a143*a187);
  a104=(a104+a187);
  a187=(a172*a104);
  a188=(a149*a187);
  a056=(a049*a188);
  a146=(a146-a056);
  a056=(a168*a104);
  a016=(a000*a056);
  a146=(a146-a016);
  a196=(a149*a196);
  a109=(a109+a196);
  a195=(a143*a195);
  a109=(a109+a195);
  a195=(a172*a109);
  a196=(a149*a195);
  a016=(a043*a196);
  a146=(a146-a016);
  a016=(a158*a109);
  a077=(a000*a016);
  a146=(a146+a077);
  a274=(a146*a274);
  a077=(2.*a052);
  a178=(a178*a077);
  a077=(a117*a097);
  a248=(a149*a248);
  a226=(a226+a248);
  a164=(a143*a164);
  a226=(a226+a164);
  a164=(a172*a226);
  a077=(a077+a164);
  a077=(a149*a077);
  a249=(a249*a077);
  a178=(a178+a249);
  a214=(a214-a178);
  a178=(a066*a048);
  a249=(a117*a251);
  a077=(a158*a226);
  a249=(a249+a077);
  a077=(a149*a249);
  a164=(a049*a077);
  a178=(a178+a164);
  a214=(a214-a178);
  a178=(a060*a032);
  a117=(a117*a269);
  a226=(a168*a226);
  a117=(a117+a226);
  a226=(a149*a117);
  a164=(a043*a226);
  a178=(a178+a164);
  a214=(a214-a178);
  a178=(a188*a048);
  a164=(a104*a097);
  a243=(a149*a243);
  a229=(a229+a243);
  a138=(a143*a138);
  a229=(a229+a138);
  a138=(a172*a229);
  a164=(a164+a138);
  a138=(a149*a164);
  a243=(a049*a138);
  a178=(a178+a243);
  a214=(a214-a178);
  a178=(a104*a269);
  a243=(a168*a229);
  a178=(a178+a243);
  a243=(a000*a178);
  a214=(a214-a243);
  a243=(a196*a032);
  a248=(a109*a097);
  a173=(a149*a173);
  a235=(a235+a173);
  a143=(a143*a159);
  a235=(a235+a143);
  a143=(a172*a235);
  a248=(a248+a143);
  a143=(a149*a248);
  a159=(a043*a143);
  a243=(a243+a159);
  a214=(a214-a243);
  a243=(a109*a251);
  a159=(a158*a235);
  a243=(a243+a159);
  a159=(a000*a243);
  a214=(a214+a159);
  a159=(a170*a214);
  a274=(a274+a159);
  a071=(a071+a274);
  a274=(a053*a066);
  a186=(a186-a274);
  a063=(a000*a063);
  a186=(a186+a063);
  a063=(a053*a188);
  a186=(a186-a063);
  a063=(a158*a104);
  a063=(a149*a063);
  a274=(a246*a063);
  a186=(a186-a274);
  a056=(a149*a056);
  a274=(a043*a056);
  a186=(a186-a274);
  a195=(a000*a195);
  a186=(a186-a195);
  a016=(a149*a016);
  a195=(a043*a016);
  a186=(a186-a195);
  a275=(a186*a275);
  a066=(a066*a052);
  a077=(a053*a077);
  a066=(a066+a077);
  a209=(a209-a066);
  a117=(a000*a117);
  a209=(a209+a117);
  a188=(a188*a052);
  a138=(a053*a138);
  a188=(a188+a138);
  a209=(a209-a188);
  a188=(2.*a048);
  a063=(a063*a188);
  a104=(a104*a251);
  a229=(a158*a229);
  a104=(a104+a229);
  a104=(a149*a104);
  a246=(a246*a104);
  a063=(a063+a246);
  a209=(a209-a063);
  a063=(a056*a032);
  a178=(a149*a178);
  a246=(a043*a178);
  a063=(a063+a246);
  a209=(a209-a063);
  a248=(a000*a248);
  a209=(a209-a248);
  a248=(a016*a032);
  a243=(a149*a243);
  a043=(a043*a243);
  a248=(a248+a043);
  a209=(a209-a248);
  a248=(a171*a209);
  a275=(a275+a248);
  a071=(a071+a275);
  a064=(a000*a064);
  a194=(a194-a064);
  a064=(a053*a060);
  a194=(a194-a064);
  a187=(a000*a187);
  a194=(a194+a187);
  a187=(a049*a056);
  a194=(a194-a187);
  a187=(a053*a196);
  a194=(a194-a187);
  a187=(a049*a016);
  a194=(a194-a187);
  a187=(a168*a109);
  a187=(a149*a187);
  a064=(a244*a187);
  a194=(a194-a064);
  a276=(a194*a276);
  a249=(a000*a249);
  a176=(a176-a249);
  a060=(a060*a052);
  a226=(a053*a226);
  a060=(a060+a226);
  a176=(a176-a060);
  a164=(a000*a164);
  a176=(a176+a164);
  a056=(a056*a048);
  a178=(a049*a178);
  a056=(a056+a178);
  a176=(a176-a056);
  a196=(a196*a052);
  a053=(a053*a143);
  a196=(a196+a053);
  a176=(a176-a196);
  a016=(a016*a048);
  a049=(a049*a243);
  a016=(a016+a049);
  a176=(a176-a016);
  a032=(2.*a032);
  a187=(a187*a032);
  a109=(a109*a269);
  a235=(a168*a235);
  a109=(a109+a235);
  a109=(a149*a109);
  a244=(a244*a109);
  a187=(a187+a244);
  a176=(a176-a187);
  a187=(a047*a176);
  a276=(a276+a187);
  a071=(a071+a276);
  a071=(a071/a001);
  a067=(a067*a002);
  a170=(a170*a146);
  a067=(a067+a170);
  a171=(a171*a186);
  a067=(a067+a171);
  a047=(a047*a194);
  a067=(a067+a047);
  a067=(a067/a001);
  a067=(a067/a001);
  a071=(a071-a067);
  if (res[3]!=0) res[3][3]=a071;
  a090=(a022*a090);
  a263=(a000*a263);
  a052=(a052+a263);
  a052=(a055*a052);
  a069=(a069*a051);
  a052=(a052-a069);
  a069=(a026*a052);
  a250=(a250+a247);
  a250=(a000*a250);
  a250=(a055*a250);
  a093=(a093*a051);
  a250=(a250-a093);
  a093=(a068*a250);
  a069=(a069-a093);
  a271=(a000*a271);
  a271=(a271-a048);
  a055=(a055*a271);
  a073=(a073*a051);
  a055=(a055-a073);
  a073=(a021*a055);
  a069=(a069+a073);
  a090=(a090-a069);
  a272=(a027*a272);
  a090=(a090+a272);
  a090=(a004*a090);
  a251=(a211*a251);
  a090=(a090-a251);
  a090=(a002*a090);
  a257=(a022*a257);
  a251=(a068*a094);
  a272=(a026*a070);
  a251=(a251+a272);
  a272=(a021*a074);
  a251=(a251+a272);
  a257=(a257-a251);
  a027=(a027*a091);
  a257=(a257+a027);
  a027=(a004*a257);
  a091=(a211*a158);
  a027=(a027-a091);
  a091=(a000*a027);
  a090=(a090+a091);
  a259=(a146*a259);
  a091=(a167*a214);
  a259=(a259+a091);
  a090=(a090+a259);
  a260=(a186*a260);
  a259=(a050*a209);
  a260=(a260+a259);
  a090=(a090+a260);
  a265=(a194*a265);
  a259=(a165*a176);
  a265=(a265+a259);
  a090=(a090+a265);
  a090=(a090/a001);
  a027=(a027*a002);
  a167=(a167*a146);
  a027=(a027+a167);
  a050=(a050*a186);
  a027=(a027+a050);
  a165=(a165*a194);
  a027=(a027+a165);
  a027=(a027/a001);
  a027=(a027/a001);
  a090=(a090-a027);
  if (res[3]!=0) res[3][4]=a090;
  a090=(a039*a052);
  a027=(a083*a250);
  a090=(a090-a027);
  a027=(a037*a055);
  a090=(a090+a027);
  a090=(a022*a090);
  a027=(a078*a262);
  a165=(a035*a240);
  a027=(a027-a165);
  a165=(a031*a256);
  a027=(a027+a165);
  a027=(a036*a027);
  a090=(a090+a027);
  a052=(a035*a052);
  a250=(a078*a250);
  a052=(a052-a250);
  a055=(a031*a055);
  a052=(a052+a055);
  a052=(a038*a052);
  a090=(a090+a052);
  a262=(a083*a262);
  a240=(a039*a240);
  a262=(a262-a240);
  a256=(a037*a256);
  a262=(a262+a256);
  a262=(a038*a262);
  a090=(a090+a262);
  a090=(a004*a090);
  a097=(a211*a097);
  a090=(a090-a097);
  a090=(a002*a090);
  a097=(a083*a094);
  a262=(a039*a070);
  a097=(a097+a262);
  a262=(a037*a074);
  a097=(a097+a262);
  a022=(a022*a097);
  a097=(a078*a087);
  a262=(a035*a057);
  a097=(a097+a262);
  a262=(a031*a061);
  a097=(a097+a262);
  a036=(a036*a097);
  a022=(a022+a036);
  a094=(a078*a094);
  a070=(a035*a070);
  a094=(a094+a070);
  a074=(a031*a074);
  a094=(a094+a074);
  a094=(a038*a094);
  a022=(a022+a094);
  a087=(a083*a087);
  a057=(a039*a057);
  a087=(a087+a057);
  a061=(a037*a061);
  a087=(a087+a061);
  a038=(a038*a087);
  a022=(a022+a038);
  a004=(a004*a022);
  a211=(a211*a172);
  a004=(a004-a211);
  a211=(a000*a004);
  a090=(a090+a211);
  a100=(a146*a100);
  a211=(a005*a214);
  a100=(a100+a211);
  a090=(a090+a100);
  a096=(a186*a096);
  a211=(a054*a209);
  a096=(a096+a211);
  a090=(a090+a096);
  a102=(a194*a102);
  a096=(a006*a176);
  a102=(a102+a096);
  a090=(a090+a102);
  a090=(a090/a001);
  a004=(a004*a002);
  a005=(a005*a146);
  a004=(a004+a005);
  a054=(a054*a186);
  a004=(a004+a054);
  a006=(a006*a194);
  a004=(a004+a006);
  a004=(a004/a001);
  a004=(a004/a001);
  a090=(a090-a004);
  if (res[3]!=0) res[3][5]=a090;
  a090=(a000*a101);
  a004=(a098*a092);
  a006=(a079*a095);
  a054=(a004+a006);
  a005=(a149*a054);
  a102=(a090+a005);
  a102=(a150*a102);
  a098=(a098*a101);
  a096=(a103*a095);
  a211=(a098+a096);
  a038=(a149*a211);
  a087=(a000*a092);
  a061=(a038-a087);
  a061=(a151*a061);
  a102=(a102+a061);
  a123=(a123*a095);
  a061=(a149*a123);
  a061=(a156*a061);
  a102=(a102+a061);
  a273=(a266+a273);
  a273=(a146*a273);
  a089=(a019+a089);
  a089=(a089*a214);
  a273=(a273+a089);
  a102=(a102+a273);
  a261=(a261-a253);
  a261=(a186*a261);
  a084=(a084-a162);
  a084=(a084*a209);
  a261=(a261+a084);
  a102=(a102+a261);
  a102=(a102+a276);
  a204=(a205+a204);
  a204=(a180*a204);
  a080=(a130+a080);
  a080=(a080*a206);
  a204=(a204+a080);
  a102=(a102+a204);
  a228=(a228-a218);
  a228=(a183*a228);
  a075=(a075-a115);
  a075=(a075*a177);
  a228=(a228+a075);
  a102=(a102+a228);
  a102=(a102+a239);
  a102=(-a102);
  if (res[3]!=0) res[3][6]=a102;
  a103=(a103*a092);
  a079=(a079*a101);
  a102=(a103+a079);
  a239=(a149*a102);
  a228=(a000*a095);
  a075=(a239-a228);
  a075=(a150*a075);
  a160=(a160*a101);
  a204=(a149*a160);
  a204=(a151*a204);
  a075=(a075+a204);
  a096=(a096+a098);
  a098=(a149*a096);
  a080=(a087+a098);
  a080=(a156*a080);
  a075=(a075+a080);
  a258=(a258-a242);
  a146=(a146*a258);
  a062=(a062-a124);
  a062=(a062*a214);
  a146=(a146+a062);
  a075=(a075+a146);
  a075=(a075+a260);
  a253=(a253+a264);
  a253=(a194*a253);
  a162=(a162+a058);
  a162=(a162*a176);
  a253=(a253+a162);
  a075=(a075+a253);
  a223=(a223-a208);
  a180=(a180*a223);
  a028=(a028-a126);
  a028=(a028*a206);
  a180=(a180+a028);
  a075=(a075+a180);
  a075=(a075+a227);
  a218=(a218+a232);
  a218=(a190*a218);
  a115=(a115+a040);
  a115=(a115*a278);
  a218=(a218+a115);
  a075=(a075+a218);
  a075=(-a075);
  if (res[3]!=0) res[3][7]=a075;
  a142=(a142*a092);
  a075=(a149*a142);
  a075=(a150*a075);
  a079=(a079+a103);
  a103=(a149*a079);
  a218=(a228+a103);
  a218=(a151*a218);
  a218=(a075+a218);
  a006=(a006+a004);
  a149=(a149*a006);
  a004=(a149-a090);
  a004=(a156*a004);
  a218=(a218+a004);
  a218=(a218+a100);
  a242=(a242+a255);
  a186=(a186*a242);
  a124=(a124+a059);
  a124=(a124*a209);
  a186=(a186+a124);
  a218=(a218+a186);
  a270=(a270-a266);
  a194=(a194*a270);
  a072=(a072-a019);
  a072=(a072*a176);
  a194=(a194+a072);
  a218=(a218+a194);
  a218=(a218+a234);
  a208=(a208+a220);
  a183=(a183*a208);
  a126=(a126+a023);
  a126=(a126*a177);
  a183=(a183+a126);
  a218=(a218+a183);
  a201=(a201-a205);
  a190=(a190*a201);
  a044=(a044-a130);
  a044=(a044*a278);
  a190=(a190+a044);
  a218=(a218+a190);
  a218=(-a218);
  if (res[3]!=0) res[3][8]=a218;
  if (res[3]!=0) res[3][9]=a065;
  if (res[3]!=0) res[3][10]=a065;
  if (res[3]!=0) res[3][11]=a065;
  if (res[3]!=0) res[3][12]=a065;
  if (res[3]!=0) res[3][13]=a065;
  if (res[3]!=0) res[3][14]=a065;
  if (res[3]!=0) res[3][15]=a065;
  if (res[3]!=0) res[3][16]=a065;
  if (res[3]!=0) res[3][17]=a065;
  a236=(a003*a236);
  a236=(a002*a236);
  a236=(a236/a001);
  if (res[3]!=0) res[3][18]=a236;
  a222=(a003*a222);
  a222=(a002*a222);
  a222=(a222/a001);
  if (res[3]!=0) res[3][19]=a222;
  a088=(a003*a088);
  a088=(a002*a088);
  a088=(a088/a001);
  if (res[3]!=0) res[3][20]=a088;
  a245=(a003*a245);
  a245=(a002*a245);
  a245=(a245/a001);
  if (res[3]!=0) res[3][21]=a245;
  a257=(a003*a257);
  a257=(a002*a257);
  a257=(a257/a001);
  if (res[3]!=0) res[3][22]=a257;
  a003=(a003*a022);
  a003=(a002*a003);
  a003=(a003/a001);
  if (res[3]!=0) res[3][23]=a003;
  if (res[3]!=0) res[3][24]=a065;
  if (res[3]!=0) res[3][25]=a065;
  if (res[3]!=0) res[3][26]=a065;
  a099=(a002*a099);
  a099=(a099/a001);
  a099=(-a099);
  if (res[3]!=0) res[3][27]=a099;
  a111=(a002*a111);
  a111=(a111/a001);
  a111=(-a111);
  if (res[3]!=0) res[3][28]=a111;
  a163=(a002*a163);
  a163=(a163/a001);
  a163=(-a163);
  if (res[3]!=0) res[3][29]=a163;
  a168=(a002*a168);
  a168=(a168/a001);
  a168=(-a168);
  if (res[3]!=0) res[3][30]=a168;
  a158=(a002*a158);
  a158=(a158/a001);
  a158=(-a158);
  if (res[3]!=0) res[3][31]=a158;
  a002=(a002*a172);
  a002=(a002/a001);
  a002=(-a002);
  if (res[3]!=0) res[3][32]=a002;
  if (res[3]!=0) res[3][33]=a065;
  if (res[3]!=0) res[3][34]=a065;
  if (res[3]!=0) res[3][35]=a065;
  a211=(a000*a211);
  a211=(a211-a092);
  a211=(a108*a211);
  a002=(a123+a160);
  a002=(a002+a142);
  a105=(a105*a002);
  a122=(a122*a105);
  a211=(a211-a122);
  a122=(a078*a211);
  a002=(a142+a123);
  a002=(a000*a002);
  a002=(a108*a002);
  a129=(a129*a105);
  a002=(a002-a129);
  a129=(a035*a002);
  a122=(a122-a129);
  a079=(a000*a079);
  a079=(a095+a079);
  a079=(a108*a079);
  a133=(a133*a105);
  a079=(a079-a133);
  a133=(a031*a079);
  a122=(a122+a133);
  a112=(a112*a122);
  a122=(a083*a211);
  a133=(a039*a002);
  a122=(a122-a133);
  a133=(a037*a079);
  a122=(a122+a133);
  a135=(a135*a122);
  a112=(a112+a135);
  a211=(a068*a211);
  a002=(a026*a002);
  a211=(a211-a002);
  a079=(a021*a079);
  a211=(a211+a079);
  a136=(a136*a211);
  a112=(a112+a136);
  if (res[4]!=0) res[4][0]=a112;
  a054=(a000*a054);
  a054=(a101+a054);
  a054=(a108*a054);
  a110=(a110*a105);
  a054=(a054-a110);
  a110=(a078*a054);
  a102=(a000*a102);
  a102=(a102-a095);
  a102=(a108*a102);
  a114=(a114*a105);
  a102=(a102-a114);
  a114=(a035*a102);
  a110=(a110+a114);
  a123=(a160+a123);
  a123=(a000*a123);
  a123=(a108*a123);
  a116=(a116*a105);
  a123=(a123-a116);
  a116=(a031*a123);
  a110=(a110-a116);
  a134=(a134*a110);
  a110=(a083*a054);
  a116=(a039*a102);
  a110=(a110+a116);
  a116=(a037*a123);
  a110=(a110-a116);
  a147=(a147*a110);
  a134=(a134+a147);
  a054=(a068*a054);
  a102=(a026*a102);
  a054=(a054+a102);
  a123=(a021*a123);
  a054=(a054-a123);
  a148=(a148*a054);
  a134=(a134+a148);
  if (res[4]!=0) res[4][1]=a134;
  a096=(a000*a096);
  a092=(a092+a096);
  a092=(a108*a092);
  a137=(a137*a105);
  a092=(a092-a137);
  a035=(a035*a092);
  a142=(a142+a160);
  a142=(a000*a142);
  a142=(a108*a142);
  a127=(a127*a105);
  a142=(a142-a127);
  a078=(a078*a142);
  a035=(a035-a078);
  a000=(a000*a006);
  a000=(a000-a101);
  a108=(a108*a000);
  a140=(a140*a105);
  a108=(a108-a140);
  a031=(a031*a108);
  a035=(a035+a031);
  a144=(a144*a035);
  a039=(a039*a092);
  a083=(a083*a142);
  a039=(a039-a083);
  a037=(a037*a108);
  a039=(a039+a037);
  a152=(a152*a039);
  a144=(a144+a152);
  a026=(a026*a092);
  a068=(a068*a142);
  a026=(a026-a068);
  a021=(a021*a108);
  a026=(a026+a021);
  a153=(a153*a026);
  a144=(a144+a153);
  if (res[4]!=0) res[4][2]=a144;
  a005=(a005-a090);
  a005=(a150*a005);
  a038=(a087+a038);
  a038=(a151*a038);
  a005=(a005+a038);
  a005=(a005+a061);
  if (res[4]!=0) res[4][3]=a005;
  a239=(a228+a239);
  a150=(a150*a239);
  a150=(a150+a204);
  a098=(a098-a087);
  a098=(a156*a098);
  a150=(a150+a098);
  if (res[4]!=0) res[4][4]=a150;
  a103=(a103-a228);
  a151=(a151*a103);
  a075=(a075+a151);
  a090=(a090+a149);
  a156=(a156*a090);
  a075=(a075+a156);
  if (res[4]!=0) res[4][5]=a075;
  if (res[4]!=0) res[4][6]=a065;
  if (res[4]!=0) res[4][7]=a065;
  if (res[4]!=0) res[4][8]=a065;
  if (res[4]!=0) res[4][9]=a065;
  if (res[4]!=0) res[4][10]=a065;
  if (res[4]!=0) res[4][11]=a065;
  if (res[4]!=0) res[4][12]=a065;
  if (res[4]!=0) res[4][13]=a065;
  if (res[4]!=0) res[4][14]=a065;
  if (res[4]!=0) res[4][15]=a065;
  if (res[4]!=0) res[4][16]=a065;
  if (res[4]!=0) res[4][17]=a065;
  if (res[4]!=0) res[4][18]=a065;
  if (res[4]!=0) res[4][19]=a065;
  if (res[4]!=0) res[4][20]=a065;
  if (res[4]!=0) res[4][21]=a065;
  if (res[4]!=0) res[4][22]=a065;
  if (res[4]!=0) res[4][23]=a065;
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

#define HPGEN_ABI 5
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
#define HPGEN_RESIDUAL_SZ_W 118
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
#define HPGEN_RESIDUAL_JACOBIAN_SZ_W 247
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
#define HPGEN_STEP_PARTIALS_SZ_W 283
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
    /* the step vector of step k: [h, t0 + k h, u_k, params] */
    if (r->u_rows < 1 || (r->u_rows > 1 && r->k >= r->u_rows)) {
        st->code = HPGEN_INVALID; st->step = r->k; return HPGEN_INVALID;
    }
    r->hv[0] = hv[0];
    r->hv[1] = r->t0 + (double)r->k * hv[0];
    for (i = 0; i < HPGEN_M; ++i) r->hv[2 + i] = r->U[(r->u_rows == 1 ? 0 : r->k) * HPGEN_M + i];
    hv = r->hv;
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
