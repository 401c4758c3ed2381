/*
 * hpgen generated module damped_top_gauss2_exp_exact -- do not edit, regenerate with hpgen
 * model: damped_top
 * options: tableau=gauss2, tau=exp, rkmk=exact
 * hpgen version: 0.1.0
 * content hash (normalized model + options): 077574fc559797718a5a0fe360c3bed1af91704de6da2cf7ff6cd2b08ee4e5f6
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
  #define CASADI_PREFIX(ID) hpgen_damped_top_gauss2_exp_exact__ ## ID
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
CASADI_SYMBOL_EXPORT void hpgen_damped_top_gauss2_exp_exact__casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int hpgen_damped_top_gauss2_exp_exact__casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int hpgen_damped_top_gauss2_exp_exact__casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {3, 1, 1};
static const casadi_int casadi_s2[3] = {81, 1, 1};
static const casadi_int casadi_s3[3] = {1, 1, 1};
static const casadi_int casadi_s4[3] = {19, 1, 1};
static const casadi_int casadi_s5[3] = {54, 1, 1};
static const casadi_int casadi_s6[3] = {36, 1, 1};
static const casadi_int casadi_s7[3] = {27, 1, 1};
static const casadi_int casadi_s8[3] = {18, 1, 1};

/* residual:(z[9],g[9],p[3],h[3])->(F[9]) */
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
  casadi_real a108, a109, a110, a111, a112, a113, a114, a115, a116, a117, a118, a119;
  casadi_real a120, a121, a122, a123, a124, a125, a126, a127, a128, a129, a130, a131;
  casadi_real a132, a133, a134, a135;
  a000=3.3333333333333331e-01;
  a001=-1.0416666666666666e-02;
  a002=arg[3]? arg[3][0] : 0;
  a003=arg[0]? arg[0][0] : 0;
  a004=(a002*a003);
  a005=casadi_sq(a004);
  a006=arg[0]? arg[0][1] : 0;
  a007=(a002*a006);
  a008=casadi_sq(a007);
  a009=(a005+a008);
  a010=arg[0]? arg[0][2] : 0;
  a011=(a002*a010);
  a012=casadi_sq(a011);
  a013=(a009+a012);
  a014=(a001*a013);
  a015=1.3888888888888889e-03;
  a016=-6.2003968253968254e-06;
  a017=(a016*a013);
  a017=(a015+a017);
  a018=2.5000000000000000e-01;
  a019=(a018*a013);
  a020=casadi_sq(a019);
  a021=(a017*a020);
  a014=(a014+a021);
  a021=2.7557319223985888e-07;
  a022=-5.2191892469670250e-10;
  a023=(a022*a013);
  a023=(a021+a023);
  a024=1.1470745597729725e-11;
  a025=-1.1948693330968463e-14;
  a026=(a025*a013);
  a026=(a024+a026);
  a027=(a026*a020);
  a023=(a023+a027);
  a027=casadi_sq(a020);
  a028=(a023*a027);
  a014=(a014+a028);
  a028=1.5619206968586225e-16;
  a029=-1.0275794058280412e-19;
  a030=(a029*a013);
  a030=(a028+a030);
  a031=8.8967913924505741e-22;
  a032=(a031*a020);
  a030=(a030+a032);
  a032=casadi_sq(a027);
  a033=(a030*a032);
  a014=(a014+a033);
  a033=-2.0833333333333333e-03;
  a034=(a033*a013);
  a035=1.9841269841269841e-04;
  a036=-6.8893298059964731e-07;
  a037=(a036*a013);
  a037=(a035+a037);
  a038=(a037*a020);
  a034=(a034+a038);
  a038=2.5052108385441720e-08;
  a039=-4.0147609592054033e-11;
  a040=(a039*a013);
  a040=(a038+a040);
  a041=7.6471637318198164e-13;
  a042=-7.0286431358638015e-16;
  a043=(a042*a013);
  a043=(a041+a043);
  a044=(a043*a020);
  a040=(a040+a044);
  a044=(a040*a027);
  a034=(a034+a044);
  a044=8.2206352466243295e-18;
  a045=-4.8932352658478156e-21;
  a046=(a045*a013);
  a046=(a044+a046);
  a047=3.8681701706306841e-23;
  a048=(a047*a020);
  a046=(a046+a048);
  a048=(a046*a032);
  a034=(a034+a048);
  a048=(a014-a034);
  a048=(a000+a048);
  a049=4.;
  a050=1.;
  a051=1.6666666666666666e-01;
  a034=(a051+a034);
  a052=(a019*a034);
  a052=(a050-a052);
  a053=(a049*a052);
  a048=(a048/a053);
  a054=(a004*a011);
  a055=(a048*a054);
  a056=5.0000000000000000e-01;
  a057=(a056*a007);
  a058=(a055-a057);
  a059=1.5000000000000002e+00;
  a014=(a056+a014);
  a060=(a052*a014);
  a060=(a034+a060);
  a060=(a018*a060);
  a061=(a060*a054);
  a062=casadi_sq(a052);
  a062=(a056*a062);
  a063=(a062*a007);
  a064=(a061-a063);
  a008=(a008+a012);
  a065=(a060*a008);
  a065=(a050-a065);
  a066=3.0000000000000004e+00;
  a067=(a066*a003);
  a068=4.6410161513775439e-01;
  a069=arg[0]? arg[0][3] : 0;
  a070=(a068*a069);
  a067=(a067+a070);
  a070=(a065*a067);
  a071=(a062*a011);
  a072=(a004*a007);
  a073=(a060*a072);
  a074=(a071+a073);
  a075=(a066*a006);
  a076=arg[0]? arg[0][4] : 0;
  a077=(a068*a076);
  a075=(a075+a077);
  a077=(a074*a075);
  a070=(a070+a077);
  a077=(a066*a010);
  a078=arg[0]? arg[0][5] : 0;
  a068=(a068*a078);
  a077=(a077+a068);
  a068=(a064*a077);
  a070=(a070+a068);
  a064=(a064*a070);
  a068=(a062*a004);
  a079=(a007*a011);
  a080=(a060*a079);
  a081=(a068+a080);
  a082=5.;
  a073=(a073-a071);
  a071=(a073*a067);
  a012=(a012+a005);
  a005=(a060*a012);
  a005=(a050-a005);
  a083=(a005*a075);
  a071=(a071+a083);
  a083=(a081*a077);
  a071=(a071+a083);
  a083=(a082*a071);
  a081=(a081*a083);
  a064=(a064+a081);
  a060=(a060*a009);
  a060=(a050-a060);
  a081=6.;
  a063=(a063+a061);
  a061=(a063*a067);
  a080=(a080-a068);
  a068=(a080*a075);
  a061=(a061+a068);
  a068=(a060*a077);
  a061=(a061+a068);
  a068=(a081*a061);
  a060=(a060*a068);
  a064=(a064+a060);
  a060=arg[0]? arg[0][8] : 0;
  a064=(a064-a060);
  a084=(a059*a064);
  a085=-3.2320508075688776e+00;
  a086=(a002*a069);
  a087=casadi_sq(a086);
  a088=(a002*a076);
  a089=casadi_sq(a088);
  a090=(a087+a089);
  a091=(a002*a078);
  a092=casadi_sq(a091);
  a093=(a090+a092);
  a094=(a033*a093);
  a095=(a036*a093);
  a095=(a035+a095);
  a096=(a018*a093);
  a097=casadi_sq(a096);
  a098=(a095*a097);
  a094=(a094+a098);
  a098=(a039*a093);
  a098=(a038+a098);
  a099=(a042*a093);
  a099=(a041+a099);
  a100=(a099*a097);
  a098=(a098+a100);
  a100=casadi_sq(a097);
  a101=(a098*a100);
  a094=(a094+a101);
  a101=(a045*a093);
  a101=(a044+a101);
  a102=(a047*a097);
  a101=(a101+a102);
  a102=casadi_sq(a100);
  a103=(a101*a102);
  a094=(a094+a103);
  a103=(a051+a094);
  a104=(a096*a103);
  a104=(a050-a104);
  a105=(a001*a093);
  a106=(a016*a093);
  a106=(a015+a106);
  a107=(a106*a097);
  a105=(a105+a107);
  a107=(a022*a093);
  a107=(a021+a107);
  a108=(a025*a093);
  a108=(a024+a108);
  a109=(a108*a097);
  a107=(a107+a109);
  a109=(a107*a100);
  a105=(a105+a109);
  a109=(a029*a093);
  a109=(a028+a109);
  a110=(a031*a097);
  a109=(a109+a110);
  a110=(a109*a102);
  a105=(a105+a110);
  a110=(a056+a105);
  a111=(a104*a110);
  a111=(a103+a111);
  a111=(a018*a111);
  a112=(a086*a091);
  a113=(a111*a112);
  a114=casadi_sq(a104);
  a114=(a056*a114);
  a115=(a114*a088);
  a116=(a113-a115);
  a089=(a089+a092);
  a117=(a111*a089);
  a117=(a050-a117);
  a118=-6.4641016151377553e+00;
  a003=(a118*a003);
  a069=(a066*a069);
  a003=(a003+a069);
  a069=(a117*a003);
  a119=(a114*a091);
  a120=(a086*a088);
  a121=(a111*a120);
  a122=(a119+a121);
  a006=(a118*a006);
  a076=(a066*a076);
  a006=(a006+a076);
  a076=(a122*a006);
  a069=(a069+a076);
  a118=(a118*a010);
  a066=(a066*a078);
  a118=(a118+a066);
  a066=(a116*a118);
  a069=(a069+a066);
  a116=(a116*a069);
  a066=(a114*a086);
  a078=(a088*a091);
  a010=(a111*a078);
  a076=(a066+a010);
  a121=(a121-a119);
  a119=(a121*a003);
  a092=(a092+a087);
  a087=(a111*a092);
  a087=(a050-a087);
  a123=(a087*a006);
  a119=(a119+a123);
  a123=(a076*a118);
  a119=(a119+a123);
  a082=(a082*a119);
  a076=(a076*a082);
  a116=(a116+a076);
  a111=(a111*a090);
  a111=(a050-a111);
  a115=(a115+a113);
  a113=(a115*a003);
  a010=(a010-a066);
  a066=(a010*a006);
  a113=(a113+a066);
  a066=(a111*a118);
  a113=(a113+a066);
  a081=(a081*a113);
  a111=(a111*a081);
  a116=(a116+a111);
  a116=(a116-a060);
  a111=(a085*a116);
  a084=(a084+a111);
  a111=(a002*a060);
  a111=(a056*a111);
  a066=5.3867513459481287e-01;
  a076=2.3205080756887719e-01;
  a064=(a076*a064);
  a116=(a059*a116);
  a064=(a064+a116);
  a116=(a002*a064);
  a123=(a066*a116);
  a123=(a111+a123);
  a124=(a002*a084);
  a125=(a018*a124);
  a123=(a123+a125);
  a125=(a071*a123);
  a126=(a048*a125);
  a127=arg[0]? arg[0][7] : 0;
  a128=(a002*a127);
  a128=(a056*a128);
  a074=(a074*a070);
  a005=(a005*a083);
  a074=(a074+a005);
  a080=(a080*a068);
  a074=(a074+a080);
  a074=(a074-a127);
  a080=(a076*a074);
  a122=(a122*a069);
  a087=(a087*a082);
  a122=(a122+a087);
  a010=(a010*a081);
  a122=(a122+a010);
  a122=(a122-a127);
  a010=(a059*a122);
  a080=(a080+a010);
  a010=(a002*a080);
  a087=(a066*a010);
  a087=(a128+a087);
  a074=(a059*a074);
  a122=(a085*a122);
  a074=(a074+a122);
  a122=(a002*a074);
  a005=(a018*a122);
  a087=(a087+a005);
  a005=(a061*a087);
  a129=(a048*a005);
  a126=(a126+a129);
  a129=(a007*a126);
  a084=(a084-a129);
  a129=-5.0000000000000000e-01;
  a130=(a070*a087);
  a131=(a129*a130);
  a084=(a084+a131);
  a131=(a070*a123);
  a132=(a048*a131);
  a133=arg[0]? arg[0][6] : 0;
  a134=(a002*a133);
  a134=(a056*a134);
  a065=(a065*a070);
  a073=(a073*a083);
  a065=(a065+a073);
  a063=(a063*a068);
  a065=(a065+a063);
  a065=(a065-a133);
  a076=(a076*a065);
  a117=(a117*a069);
  a121=(a121*a082);
  a117=(a117+a121);
  a115=(a115*a081);
  a117=(a117+a115);
  a117=(a117-a133);
  a115=(a059*a117);
  a076=(a076+a115);
  a115=(a002*a076);
  a066=(a066*a115);
  a066=(a134+a066);
  a059=(a059*a065);
  a085=(a085*a117);
  a059=(a059+a085);
  a085=(a002*a059);
  a117=(a018*a085);
  a066=(a066+a117);
  a117=(a061*a066);
  a065=(a048*a117);
  a132=(a132+a065);
  a065=(a004*a132);
  a084=(a084-a065);
  a065=(a071*a066);
  a081=(a056*a065);
  a084=(a084+a081);
  a081=(2.*a011);
  a087=(a071*a087);
  a121=(a048*a087);
  a066=(a070*a066);
  a082=(a048*a066);
  a063=(a121+a082);
  a063=(a081*a063);
  a084=(a084+a063);
  a063=(a048/a053);
  a123=(a061*a123);
  a068=(a009*a123);
  a073=(a079*a125);
  a068=(a068-a073);
  a073=(a054*a131);
  a068=(a068-a073);
  a073=(a079*a005);
  a068=(a068-a073);
  a087=(a012*a087);
  a068=(a068+a087);
  a087=(a072*a130);
  a068=(a068-a087);
  a087=(a054*a117);
  a068=(a068-a087);
  a087=(a072*a065);
  a068=(a068-a087);
  a066=(a008*a066);
  a068=(a068+a066);
  a063=(a063*a068);
  a063=(a049*a063);
  a066=(a019*a063);
  a068=(a068/a053);
  a066=(a066-a068);
  a053=(a032*a066);
  a087=(a045*a053);
  a073=(a027*a066);
  a083=(a020*a073);
  a083=(a042*a083);
  a087=(a087+a083);
  a083=(a039*a073);
  a087=(a087+a083);
  a083=(a020*a066);
  a083=(a036*a083);
  a087=(a087+a083);
  a083=(a033*a066);
  a087=(a087+a083);
  a032=(a032*a068);
  a083=(a029*a032);
  a087=(a087+a083);
  a083=(a027*a068);
  a135=(a020*a083);
  a135=(a025*a135);
  a087=(a087+a135);
  a135=(a022*a083);
  a087=(a087+a135);
  a034=(a034*a063);
  a013=(a056*a013);
  a053=(a047*a053);
  a063=(2.*a020);
  a027=(2.*a027);
  a046=(a046*a066);
  a046=(a027*a046);
  a040=(a040*a066);
  a046=(a046+a040);
  a046=(a063*a046);
  a053=(a053+a046);
  a043=(a043*a073);
  a053=(a053+a043);
  a037=(a037*a066);
  a053=(a053+a037);
  a053=(a013*a053);
  a034=(a034+a053);
  a032=(a031*a032);
  a030=(a030*a068);
  a027=(a027*a030);
  a023=(a023*a068);
  a027=(a027+a023);
  a063=(a063*a027);
  a032=(a032+a063);
  a026=(a026*a083);
  a032=(a032+a026);
  a017=(a017*a068);
  a032=(a032+a017);
  a013=(a013*a032);
  a034=(a034+a013);
  a034=(a018*a034);
  a087=(a087+a034);
  a020=(a020*a068);
  a020=(a016*a020);
  a087=(a087+a020);
  a068=(a001*a068);
  a087=(a087+a068);
  a081=(a081*a087);
  a084=(a084+a081);
  a058=(a058*a084);
  a081=(a048*a072);
  a068=(a129*a011);
  a020=(a081-a068);
  a131=(a056*a131);
  a131=(a131+a074);
  a126=(a011*a126);
  a131=(a131-a126);
  a117=(a129*a117);
  a131=(a131+a117);
  a130=(a048*a130);
  a065=(a048*a065);
  a130=(a130+a065);
  a065=(a004*a130);
  a131=(a131-a065);
  a065=(2.*a007);
  a123=(a048*a123);
  a082=(a123+a082);
  a082=(a065*a082);
  a131=(a131+a082);
  a065=(a065*a087);
  a131=(a131+a065);
  a020=(a020*a131);
  a058=(a058+a020);
  a020=(a048*a008);
  a020=(a050-a020);
  a125=(a129*a125);
  a005=(a056*a005);
  a125=(a125+a005);
  a005=(2.*a004);
  a123=(a123+a121);
  a123=(a005*a123);
  a125=(a125+a123);
  a125=(a125+a059);
  a132=(a011*a132);
  a125=(a125-a132);
  a130=(a007*a130);
  a125=(a125-a130);
  a005=(a005*a087);
  a125=(a125+a005);
  a020=(a020*a125);
  a058=(a058+a020);
  a005=arg[3]? arg[3][2] : 0;
  a070=(a005*a070);
  a087=(a056*a002);
  a070=(a070*a087);
  a058=(a058-a070);
  a070=arg[1]? arg[1][2] : 0;
  a072=(a062*a072);
  a019=(a019*a014);
  a019=(a050-a019);
  a052=(a052*a019);
  a019=(a052*a011);
  a014=(a072-a019);
  a014=(a070*a014);
  a130=arg[1]? arg[1][5] : 0;
  a132=(a062*a012);
  a132=(a050-a132);
  a132=(a130*a132);
  a014=(a014+a132);
  a132=arg[1]? arg[1][8] : 0;
  a059=(a052*a004);
  a123=(a062*a079);
  a059=(a059+a123);
  a059=(a132*a059);
  a014=(a014+a059);
  a014=(a014*a087);
  a058=(a058+a014);
  a058=(a058/a002);
  if (res[0]!=0) res[0][0]=a058;
  a079=(a048*a079);
  a058=(a129*a004);
  a014=(a079-a058);
  a014=(a014*a084);
  a012=(a048*a012);
  a012=(a050-a012);
  a012=(a012*a131);
  a014=(a014+a012);
  a011=(a056*a011);
  a059=(a081-a011);
  a059=(a059*a125);
  a014=(a014+a059);
  a071=(a005*a071);
  a071=(a071*a087);
  a014=(a014-a071);
  a008=(a062*a008);
  a008=(a050-a008);
  a008=(a070*a008);
  a019=(a019+a072);
  a019=(a130*a019);
  a008=(a008+a019);
  a062=(a062*a054);
  a052=(a052*a007);
  a062=(a062-a052);
  a062=(a132*a062);
  a008=(a008+a062);
  a008=(a008*a087);
  a014=(a014-a008);
  a014=(a014/a002);
  if (res[0]!=0) res[0][1]=a014;
  a048=(a048*a009);
  a048=(a050-a048);
  a048=(a048*a084);
  a004=(a056*a004);
  a009=(a079-a004);
  a009=(a009*a131);
  a009=(a048+a009);
  a007=(a129*a007);
  a014=(a055-a007);
  a014=(a014*a125);
  a009=(a009+a014);
  a061=(a005*a061);
  a061=(a061*a087);
  a009=(a009-a061);
  a009=(a009/a002);
  if (res[0]!=0) res[0][2]=a009;
  a009=(a114*a120);
  a110=(a096*a110);
  a110=(a050-a110);
  a110=(a104*a110);
  a061=(a110*a091);
  a014=(a009-a061);
  a014=(a070*a014);
  a008=(a114*a092);
  a008=(a050-a008);
  a008=(a130*a008);
  a014=(a014+a008);
  a008=(a110*a086);
  a062=(a114*a078);
  a008=(a008+a062);
  a008=(a132*a008);
  a014=(a014+a008);
  a014=(a014*a087);
  a008=(a005*a069);
  a008=(a008*a087);
  a014=(a014-a008);
  a105=(a105-a094);
  a105=(a000+a105);
  a104=(a049*a104);
  a105=(a105/a104);
  a094=(a105*a112);
  a008=(a056*a088);
  a062=(a094-a008);
  a116=(a018*a116);
  a111=(a111+a116);
  a116=-3.8675134594812879e-02;
  a124=(a116*a124);
  a111=(a111+a124);
  a124=(a119*a111);
  a052=(a105*a124);
  a010=(a018*a010);
  a128=(a128+a010);
  a122=(a116*a122);
  a128=(a128+a122);
  a122=(a113*a128);
  a010=(a105*a122);
  a052=(a052+a010);
  a010=(a088*a052);
  a064=(a064-a010);
  a010=(a069*a128);
  a054=(a129*a010);
  a064=(a064+a054);
  a054=(a069*a111);
  a019=(a105*a054);
  a115=(a018*a115);
  a134=(a134+a115);
  a116=(a116*a085);
  a134=(a134+a116);
  a116=(a113*a134);
  a085=(a105*a116);
  a019=(a019+a085);
  a085=(a086*a019);
  a064=(a064-a085);
  a085=(a119*a134);
  a115=(a056*a085);
  a064=(a064+a115);
  a115=(2.*a091);
  a128=(a119*a128);
  a072=(a105*a128);
  a069=(a069*a134);
  a134=(a105*a069);
  a071=(a072+a134);
  a071=(a115*a071);
  a064=(a064+a071);
  a071=(a105/a104);
  a111=(a113*a111);
  a059=(a090*a111);
  a123=(a078*a124);
  a059=(a059-a123);
  a123=(a112*a054);
  a059=(a059-a123);
  a123=(a078*a122);
  a059=(a059-a123);
  a128=(a092*a128);
  a059=(a059+a128);
  a128=(a120*a010);
  a059=(a059-a128);
  a128=(a112*a116);
  a059=(a059-a128);
  a128=(a120*a085);
  a059=(a059-a128);
  a069=(a089*a069);
  a059=(a059+a069);
  a071=(a071*a059);
  a071=(a049*a071);
  a096=(a096*a071);
  a059=(a059/a104);
  a096=(a096-a059);
  a104=(a102*a096);
  a069=(a045*a104);
  a128=(a100*a096);
  a123=(a097*a128);
  a123=(a042*a123);
  a069=(a069+a123);
  a123=(a039*a128);
  a069=(a069+a123);
  a123=(a097*a096);
  a123=(a036*a123);
  a069=(a069+a123);
  a123=(a033*a096);
  a069=(a069+a123);
  a102=(a102*a059);
  a123=(a029*a102);
  a069=(a069+a123);
  a123=(a100*a059);
  a121=(a097*a123);
  a121=(a025*a121);
  a069=(a069+a121);
  a121=(a022*a123);
  a069=(a069+a121);
  a103=(a103*a071);
  a093=(a056*a093);
  a104=(a047*a104);
  a071=(2.*a097);
  a100=(2.*a100);
  a101=(a101*a096);
  a101=(a100*a101);
  a098=(a098*a096);
  a101=(a101+a098);
  a101=(a071*a101);
  a104=(a104+a101);
  a099=(a099*a128);
  a104=(a104+a099);
  a095=(a095*a096);
  a104=(a104+a095);
  a104=(a093*a104);
  a103=(a103+a104);
  a102=(a031*a102);
  a109=(a109*a059);
  a100=(a100*a109);
  a107=(a107*a059);
  a100=(a100+a107);
  a071=(a071*a100);
  a102=(a102+a071);
  a108=(a108*a123);
  a102=(a102+a108);
  a106=(a106*a059);
  a102=(a102+a106);
  a093=(a093*a102);
  a103=(a103+a093);
  a103=(a018*a103);
  a069=(a069+a103);
  a097=(a097*a059);
  a097=(a016*a097);
  a069=(a069+a097);
  a059=(a001*a059);
  a069=(a069+a059);
  a115=(a115*a069);
  a064=(a064+a115);
  a062=(a062*a064);
  a014=(a014+a062);
  a120=(a105*a120);
  a062=(a129*a091);
  a115=(a120-a062);
  a054=(a056*a054);
  a080=(a080+a054);
  a052=(a091*a052);
  a080=(a080-a052);
  a116=(a129*a116);
  a080=(a080+a116);
  a010=(a105*a010);
  a085=(a105*a085);
  a010=(a010+a085);
  a085=(a086*a010);
  a080=(a080-a085);
  a085=(2.*a088);
  a111=(a105*a111);
  a134=(a111+a134);
  a134=(a085*a134);
  a080=(a080+a134);
  a085=(a085*a069);
  a080=(a080+a085);
  a115=(a115*a080);
  a014=(a014+a115);
  a115=(a105*a089);
  a115=(a050-a115);
  a124=(a129*a124);
  a076=(a076+a124);
  a122=(a056*a122);
  a076=(a076+a122);
  a122=(2.*a086);
  a111=(a111+a072);
  a111=(a122*a111);
  a076=(a076+a111);
  a019=(a091*a019);
  a076=(a076-a019);
  a010=(a088*a010);
  a076=(a076-a010);
  a122=(a122*a069);
  a076=(a076+a122);
  a115=(a115*a076);
  a014=(a014+a115);
  a014=(a014/a002);
  if (res[0]!=0) res[0][3]=a014;
  a078=(a105*a078);
  a014=(a129*a086);
  a122=(a078-a014);
  a122=(a122*a064);
  a119=(a005*a119);
  a119=(a119*a087);
  a089=(a114*a089);
  a089=(a050-a089);
  a070=(a070*a089);
  a061=(a061+a009);
  a130=(a130*a061);
  a070=(a070+a130);
  a114=(a114*a112);
  a110=(a110*a088);
  a114=(a114-a110);
  a132=(a132*a114);
  a070=(a070+a132);
  a070=(a070*a087);
  a119=(a119+a070);
  a122=(a122-a119);
  a092=(a105*a092);
  a092=(a050-a092);
  a092=(a092*a080);
  a122=(a122+a092);
  a091=(a056*a091);
  a119=(a120-a091);
  a119=(a119*a076);
  a122=(a122+a119);
  a122=(a122/a002);
  if (res[0]!=0) res[0][4]=a122;
  a105=(a105*a090);
  a105=(a050-a105);
  a105=(a105*a064);
  a005=(a005*a113);
  a005=(a005*a087);
  a005=(a105-a005);
  a086=(a056*a086);
  a087=(a078-a086);
  a087=(a087*a080);
  a005=(a005+a087);
  a088=(a129*a088);
  a087=(a094-a088);
  a087=(a087*a076);
  a005=(a005+a087);
  a005=(a005/a002);
  if (res[0]!=0) res[0][5]=a005;
  a005=arg[2]? arg[2][0] : 0;
  a075=(a056*a075);
  a006=(a056*a006);
  a075=(a075+a006);
  a075=(a002*a075);
  a006=(a056*a075);
  a067=(a056*a067);
  a003=(a056*a003);
  a067=(a067+a003);
  a067=(a002*a067);
  a003=casadi_sq(a067);
  a087=casadi_sq(a075);
  a113=(a003+a087);
  a077=(a056*a077);
  a118=(a056*a118);
  a077=(a077+a118);
  a002=(a002*a077);
  a077=casadi_sq(a002);
  a118=(a113+a077);
  a001=(a001*a118);
  a016=(a016*a118);
  a015=(a015+a016);
  a018=(a018*a118);
  a016=casadi_sq(a018);
  a015=(a015*a016);
  a001=(a001+a015);
  a022=(a022*a118);
  a021=(a021+a022);
  a025=(a025*a118);
  a024=(a024+a025);
  a024=(a024*a016);
  a021=(a021+a024);
  a024=casadi_sq(a016);
  a021=(a021*a024);
  a001=(a001+a021);
  a029=(a029*a118);
  a028=(a028+a029);
  a031=(a031*a016);
  a028=(a028+a031);
  a031=casadi_sq(a024);
  a028=(a028*a031);
  a001=(a001+a028);
  a033=(a033*a118);
  a036=(a036*a118);
  a035=(a035+a036);
  a035=(a035*a016);
  a033=(a033+a035);
  a039=(a039*a118);
  a038=(a038+a039);
  a042=(a042*a118);
  a041=(a041+a042);
  a041=(a041*a016);
  a038=(a038+a041);
  a038=(a038*a024);
  a033=(a033+a038);
  a045=(a045*a118);
  a044=(a044+a045);
  a047=(a047*a016);
  a044=(a044+a047);
  a044=(a044*a031);
  a033=(a033+a044);
  a001=(a001-a033);
  a000=(a000+a001);
  a051=(a051+a033);
  a018=(a018*a051);
  a018=(a050-a018);
  a049=(a049*a018);
  a000=(a000/a049);
  a049=(a067*a002);
  a049=(a000*a049);
  a006=(a006+a049);
  a006=(a006*a060);
  a018=(a129*a002);
  a051=(a067*a075);
  a051=(a000*a051);
  a018=(a018+a051);
  a018=(a018*a127);
  a006=(a006+a018);
  a087=(a087+a077);
  a087=(a000*a087);
  a087=(a050-a087);
  a087=(a087*a133);
  a006=(a006+a087);
  a008=(a008+a094);
  a008=(a008*a064);
  a006=(a006+a008);
  a062=(a062+a120);
  a062=(a062*a080);
  a006=(a006+a062);
  a006=(a006+a115);
  a057=(a057+a055);
  a057=(a057*a084);
  a006=(a006+a057);
  a068=(a068+a081);
  a068=(a068*a131);
  a006=(a006+a068);
  a006=(a006+a020);
  a005=(a005-a006);
  if (res[0]!=0) res[0][6]=a005;
  a005=arg[2]? arg[2][1] : 0;
  a006=(a129*a067);
  a020=(a075*a002);
  a020=(a000*a020);
  a006=(a006+a020);
  a006=(a006*a060);
  a077=(a077+a003);
  a077=(a000*a077);
  a077=(a050-a077);
  a077=(a077*a127);
  a006=(a006+a077);
  a002=(a056*a002);
  a002=(a002+a051);
  a002=(a002*a133);
  a006=(a006+a002);
  a014=(a014+a078);
  a014=(a014*a064);
  a006=(a006+a014);
  a006=(a006+a092);
  a091=(a091+a120);
  a091=(a091*a076);
  a006=(a006+a091);
  a058=(a058+a079);
  a058=(a058*a084);
  a006=(a006+a058);
  a006=(a006+a012);
  a011=(a011+a081);
  a011=(a011*a125);
  a006=(a006+a011);
  a005=(a005-a006);
  if (res[0]!=0) res[0][7]=a005;
  a005=arg[2]? arg[2][2] : 0;
  a000=(a000*a113);
  a050=(a050-a000);
  a050=(a050*a060);
  a056=(a056*a067);
  a056=(a056+a020);
  a056=(a056*a127);
  a050=(a050+a056);
  a129=(a129*a075);
  a129=(a129+a049);
  a129=(a129*a133);
  a050=(a050+a129);
  a050=(a050+a105);
  a086=(a086+a078);
  a086=(a086*a080);
  a050=(a050+a086);
  a088=(a088+a094);
  a088=(a088*a076);
  a050=(a050+a088);
  a050=(a050+a048);
  a004=(a004+a079);
  a004=(a004*a131);
  a050=(a050+a004);
  a007=(a007+a055);
  a007=(a007*a125);
  a050=(a050+a007);
  a005=(a005-a050);
  if (res[0]!=0) res[0][8]=a005;
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
    case 3: return casadi_s1;
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

/* residual_jacobian:(z[9],g[9],p[3],h[3])->(F[9],J[81]) */
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
  casadi_real a240, a241, a242, a243, a244, a245, a246, a247, a248, a249, a250, a251;
  casadi_real a252, a253, a254, a255, a256, a257, a258, a259, a260, a261, a262, a263;
  casadi_real a264, a265, a266, a267, a268, a269, a270, a271, a272, a273, a274, a275;
  casadi_real a276, a277, a278, a279, a280, a281, a282, a283, a284, a285, a286, a287;
  casadi_real a288, a289, a290, a291, a292, a293, a294, a295, a296, a297, a298, a299;
  casadi_real a300, a301, a302, a303, a304, a305, a306, a307, a308, a309, a310, a311;
  casadi_real a312, a313, a314, a315, a316, a317, a318, a319, a320, a321, a322, a323;
  casadi_real a324, a325, a326, a327, a328, a329, a330, a331, a332, a333, a334, a335;
  casadi_real a336, a337, a338, a339, a340, a341, a342, a343, a344, a345, a346, a347;
  casadi_real a348, a349, a350, a351, a352, a353, a354, a355, a356, a357, a358;
  a000=3.3333333333333331e-01;
  a001=-1.0416666666666666e-02;
  a002=arg[3]? arg[3][0] : 0;
  a003=arg[0]? arg[0][0] : 0;
  a004=(a002*a003);
  a005=casadi_sq(a004);
  a006=arg[0]? arg[0][1] : 0;
  a007=(a002*a006);
  a008=casadi_sq(a007);
  a009=(a005+a008);
  a010=arg[0]? arg[0][2] : 0;
  a011=(a002*a010);
  a012=casadi_sq(a011);
  a013=(a009+a012);
  a014=(a001*a013);
  a015=1.3888888888888889e-03;
  a016=-6.2003968253968254e-06;
  a017=(a016*a013);
  a017=(a015+a017);
  a018=2.5000000000000000e-01;
  a019=(a018*a013);
  a020=casadi_sq(a019);
  a021=(a017*a020);
  a014=(a014+a021);
  a021=2.7557319223985888e-07;
  a022=-5.2191892469670250e-10;
  a023=(a022*a013);
  a023=(a021+a023);
  a024=1.1470745597729725e-11;
  a025=-1.1948693330968463e-14;
  a026=(a025*a013);
  a026=(a024+a026);
  a027=(a026*a020);
  a023=(a023+a027);
  a027=casadi_sq(a020);
  a028=(a023*a027);
  a014=(a014+a028);
  a028=1.5619206968586225e-16;
  a029=-1.0275794058280412e-19;
  a030=(a029*a013);
  a030=(a028+a030);
  a031=8.8967913924505741e-22;
  a032=(a031*a020);
  a030=(a030+a032);
  a032=casadi_sq(a027);
  a033=(a030*a032);
  a014=(a014+a033);
  a033=-2.0833333333333333e-03;
  a034=(a033*a013);
  a035=1.9841269841269841e-04;
  a036=-6.8893298059964731e-07;
  a037=(a036*a013);
  a037=(a035+a037);
  a038=(a037*a020);
  a034=(a034+a038);
  a038=2.5052108385441720e-08;
  a039=-4.0147609592054033e-11;
  a040=(a039*a013);
  a040=(a038+a040);
  a041=7.6471637318198164e-13;
  a042=-7.0286431358638015e-16;
  a043=(a042*a013);
  a043=(a041+a043);
  a044=(a043*a020);
  a040=(a040+a044);
  a044=(a040*a027);
  a034=(a034+a044);
  a044=8.2206352466243295e-18;
  a045=-4.8932352658478156e-21;
  a046=(a045*a013);
  a046=(a044+a046);
  a047=3.8681701706306841e-23;
  a048=(a047*a020);
  a046=(a046+a048);
  a048=(a046*a032);
  a034=(a034+a048);
  a048=(a014-a034);
  a048=(a000+a048);
  a049=4.;
  a050=1.;
  a051=1.6666666666666666e-01;
  a034=(a051+a034);
  a052=(a019*a034);
  a052=(a050-a052);
  a053=(a049*a052);
  a048=(a048/a053);
  a054=(a004*a011);
  a055=(a048*a054);
  a056=5.0000000000000000e-01;
  a057=(a056*a007);
  a058=(a055-a057);
  a059=1.5000000000000002e+00;
  a014=(a056+a014);
  a060=(a052*a014);
  a060=(a034+a060);
  a060=(a018*a060);
  a061=(a060*a054);
  a062=casadi_sq(a052);
  a062=(a056*a062);
  a063=(a062*a007);
  a064=(a061-a063);
  a008=(a008+a012);
  a065=(a060*a008);
  a065=(a050-a065);
  a066=3.0000000000000004e+00;
  a067=(a066*a003);
  a068=4.6410161513775439e-01;
  a069=arg[0]? arg[0][3] : 0;
  a070=(a068*a069);
  a067=(a067+a070);
  a070=(a065*a067);
  a071=(a062*a011);
  a072=(a004*a007);
  a073=(a060*a072);
  a074=(a071+a073);
  a075=(a066*a006);
  a076=arg[0]? arg[0][4] : 0;
  a077=(a068*a076);
  a075=(a075+a077);
  a077=(a074*a075);
  a070=(a070+a077);
  a077=(a066*a010);
  a078=arg[0]? arg[0][5] : 0;
  a079=(a068*a078);
  a077=(a077+a079);
  a079=(a064*a077);
  a070=(a070+a079);
  a079=(a064*a070);
  a080=(a062*a004);
  a081=(a007*a011);
  a082=(a060*a081);
  a083=(a080+a082);
  a084=5.;
  a073=(a073-a071);
  a071=(a073*a067);
  a012=(a012+a005);
  a005=(a060*a012);
  a005=(a050-a005);
  a085=(a005*a075);
  a071=(a071+a085);
  a085=(a083*a077);
  a071=(a071+a085);
  a085=(a084*a071);
  a086=(a083*a085);
  a079=(a079+a086);
  a086=(a060*a009);
  a086=(a050-a086);
  a087=6.;
  a063=(a063+a061);
  a061=(a063*a067);
  a082=(a082-a080);
  a080=(a082*a075);
  a061=(a061+a080);
  a080=(a086*a077);
  a061=(a061+a080);
  a080=(a087*a061);
  a088=(a086*a080);
  a079=(a079+a088);
  a088=arg[0]? arg[0][8] : 0;
  a079=(a079-a088);
  a089=(a059*a079);
  a090=-3.2320508075688776e+00;
  a091=(a002*a069);
  a092=casadi_sq(a091);
  a093=(a002*a076);
  a094=casadi_sq(a093);
  a095=(a092+a094);
  a096=(a002*a078);
  a097=casadi_sq(a096);
  a098=(a095+a097);
  a099=(a033*a098);
  a100=(a036*a098);
  a100=(a035+a100);
  a101=(a018*a098);
  a102=casadi_sq(a101);
  a103=(a100*a102);
  a099=(a099+a103);
  a103=(a039*a098);
  a103=(a038+a103);
  a104=(a042*a098);
  a104=(a041+a104);
  a105=(a104*a102);
  a103=(a103+a105);
  a105=casadi_sq(a102);
  a106=(a103*a105);
  a099=(a099+a106);
  a106=(a045*a098);
  a106=(a044+a106);
  a107=(a047*a102);
  a106=(a106+a107);
  a107=casadi_sq(a105);
  a108=(a106*a107);
  a099=(a099+a108);
  a108=(a051+a099);
  a109=(a101*a108);
  a109=(a050-a109);
  a110=(a001*a098);
  a111=(a016*a098);
  a111=(a015+a111);
  a112=(a111*a102);
  a110=(a110+a112);
  a112=(a022*a098);
  a112=(a021+a112);
  a113=(a025*a098);
  a113=(a024+a113);
  a114=(a113*a102);
  a112=(a112+a114);
  a114=(a112*a105);
  a110=(a110+a114);
  a114=(a029*a098);
  a114=(a028+a114);
  a115=(a031*a102);
  a114=(a114+a115);
  a115=(a114*a107);
  a110=(a110+a115);
  a115=(a056+a110);
  a116=(a109*a115);
  a116=(a108+a116);
  a116=(a018*a116);
  a117=(a091*a096);
  a118=(a116*a117);
  a119=casadi_sq(a109);
  a119=(a056*a119);
  a120=(a119*a093);
  a121=(a118-a120);
  a094=(a094+a097);
  a122=(a116*a094);
  a122=(a050-a122);
  a123=-6.4641016151377553e+00;
  a003=(a123*a003);
  a069=(a066*a069);
  a003=(a003+a069);
  a069=(a122*a003);
  a124=(a119*a096);
  a125=(a091*a093);
  a126=(a116*a125);
  a127=(a124+a126);
  a006=(a123*a006);
  a076=(a066*a076);
  a006=(a006+a076);
  a076=(a127*a006);
  a069=(a069+a076);
  a010=(a123*a010);
  a078=(a066*a078);
  a010=(a010+a078);
  a078=(a121*a010);
  a069=(a069+a078);
  a078=(a121*a069);
  a076=(a119*a091);
  a128=(a093*a096);
  a129=(a116*a128);
  a130=(a076+a129);
  a126=(a126-a124);
  a124=(a126*a003);
  a097=(a097+a092);
  a092=(a116*a097);
  a092=(a050-a092);
  a131=(a092*a006);
  a124=(a124+a131);
  a131=(a130*a010);
  a124=(a124+a131);
  a131=(a084*a124);
  a132=(a130*a131);
  a078=(a078+a132);
  a132=(a116*a095);
  a132=(a050-a132);
  a120=(a120+a118);
  a118=(a120*a003);
  a129=(a129-a076);
  a076=(a129*a006);
  a118=(a118+a076);
  a076=(a132*a010);
  a118=(a118+a076);
  a076=(a087*a118);
  a133=(a132*a076);
  a078=(a078+a133);
  a078=(a078-a088);
  a133=(a090*a078);
  a089=(a089+a133);
  a133=(a002*a088);
  a133=(a056*a133);
  a134=5.3867513459481287e-01;
  a135=2.3205080756887719e-01;
  a079=(a135*a079);
  a078=(a059*a078);
  a079=(a079+a078);
  a078=(a002*a079);
  a136=(a134*a078);
  a136=(a133+a136);
  a137=(a002*a089);
  a138=(a018*a137);
  a136=(a136+a138);
  a138=(a071*a136);
  a139=(a048*a138);
  a140=arg[0]? arg[0][7] : 0;
  a141=(a002*a140);
  a141=(a056*a141);
  a142=(a074*a070);
  a143=(a005*a085);
  a142=(a142+a143);
  a143=(a082*a080);
  a142=(a142+a143);
  a142=(a142-a140);
  a143=(a135*a142);
  a144=(a127*a069);
  a145=(a092*a131);
  a144=(a144+a145);
  a145=(a129*a076);
  a144=(a144+a145);
  a144=(a144-a140);
  a145=(a059*a144);
  a143=(a143+a145);
  a145=(a002*a143);
  a146=(a134*a145);
  a146=(a141+a146);
  a142=(a059*a142);
  a144=(a090*a144);
  a142=(a142+a144);
  a144=(a002*a142);
  a147=(a018*a144);
  a146=(a146+a147);
  a147=(a061*a146);
  a148=(a048*a147);
  a139=(a139+a148);
  a148=(a007*a139);
  a089=(a089-a148);
  a148=-5.0000000000000000e-01;
  a149=(a070*a146);
  a150=(a148*a149);
  a089=(a089+a150);
  a150=(a070*a136);
  a151=(a048*a150);
  a152=arg[0]? arg[0][6] : 0;
  a153=(a002*a152);
  a153=(a056*a153);
  a154=(a065*a070);
  a155=(a073*a085);
  a154=(a154+a155);
  a155=(a063*a080);
  a154=(a154+a155);
  a154=(a154-a152);
  a155=(a135*a154);
  a156=(a122*a069);
  a157=(a126*a131);
  a156=(a156+a157);
  a157=(a120*a076);
  a156=(a156+a157);
  a156=(a156-a152);
  a157=(a059*a156);
  a155=(a155+a157);
  a157=(a002*a155);
  a158=(a134*a157);
  a158=(a153+a158);
  a154=(a059*a154);
  a156=(a090*a156);
  a154=(a154+a156);
  a156=(a002*a154);
  a159=(a018*a156);
  a158=(a158+a159);
  a159=(a061*a158);
  a160=(a048*a159);
  a151=(a151+a160);
  a160=(a004*a151);
  a089=(a089-a160);
  a160=(a071*a158);
  a161=(a056*a160);
  a089=(a089+a161);
  a161=(2.*a011);
  a162=(a071*a146);
  a163=(a048*a162);
  a164=(a070*a158);
  a165=(a048*a164);
  a166=(a163+a165);
  a167=(a161*a166);
  a089=(a089+a167);
  a167=(a048/a053);
  a168=(a061*a136);
  a169=(a009*a168);
  a170=(a081*a138);
  a169=(a169-a170);
  a170=(a054*a150);
  a169=(a169-a170);
  a170=(a081*a147);
  a169=(a169-a170);
  a170=(a012*a162);
  a169=(a169+a170);
  a170=(a072*a149);
  a169=(a169-a170);
  a170=(a054*a159);
  a169=(a169-a170);
  a170=(a072*a160);
  a169=(a169-a170);
  a170=(a008*a164);
  a169=(a169+a170);
  a170=(a167*a169);
  a170=(a049*a170);
  a171=(a019*a170);
  a172=(a169/a053);
  a171=(a171-a172);
  a173=(a032*a171);
  a174=(a045*a173);
  a175=(a027*a171);
  a176=(a020*a175);
  a176=(a042*a176);
  a174=(a174+a176);
  a176=(a039*a175);
  a174=(a174+a176);
  a176=(a020*a171);
  a176=(a036*a176);
  a174=(a174+a176);
  a176=(a033*a171);
  a174=(a174+a176);
  a176=(a032*a172);
  a177=(a029*a176);
  a174=(a174+a177);
  a177=(a027*a172);
  a178=(a020*a177);
  a178=(a025*a178);
  a174=(a174+a178);
  a178=(a022*a177);
  a174=(a174+a178);
  a178=(a034*a170);
  a013=(a056*a013);
  a173=(a047*a173);
  a179=(2.*a020);
  a180=(2.*a027);
  a181=(a046*a171);
  a182=(a180*a181);
  a183=(a040*a171);
  a182=(a182+a183);
  a183=(a179*a182);
  a173=(a173+a183);
  a183=(a043*a175);
  a173=(a173+a183);
  a183=(a037*a171);
  a173=(a173+a183);
  a183=(a013*a173);
  a178=(a178+a183);
  a176=(a031*a176);
  a183=(a030*a172);
  a184=(a180*a183);
  a185=(a023*a172);
  a184=(a184+a185);
  a185=(a179*a184);
  a176=(a176+a185);
  a185=(a026*a177);
  a176=(a176+a185);
  a185=(a017*a172);
  a176=(a176+a185);
  a185=(a013*a176);
  a178=(a178+a185);
  a178=(a018*a178);
  a174=(a174+a178);
  a178=(a020*a172);
  a178=(a016*a178);
  a174=(a174+a178);
  a178=(a001*a172);
  a174=(a174+a178);
  a178=(a161*a174);
  a089=(a089+a178);
  a178=(a058*a089);
  a185=(a048*a072);
  a186=(a148*a011);
  a187=(a185-a186);
  a188=(a056*a150);
  a188=(a188+a142);
  a142=(a011*a139);
  a188=(a188-a142);
  a142=(a148*a159);
  a188=(a188+a142);
  a142=(a048*a149);
  a189=(a048*a160);
  a142=(a142+a189);
  a189=(a004*a142);
  a188=(a188-a189);
  a189=(2.*a007);
  a190=(a048*a168);
  a165=(a190+a165);
  a191=(a189*a165);
  a188=(a188+a191);
  a191=(a189*a174);
  a188=(a188+a191);
  a191=(a187*a188);
  a178=(a178+a191);
  a191=(a048*a008);
  a191=(a050-a191);
  a192=(a148*a138);
  a193=(a056*a147);
  a192=(a192+a193);
  a193=(2.*a004);
  a190=(a190+a163);
  a163=(a193*a190);
  a192=(a192+a163);
  a192=(a192+a154);
  a154=(a011*a151);
  a192=(a192-a154);
  a154=(a007*a142);
  a192=(a192-a154);
  a154=(a193*a174);
  a192=(a192+a154);
  a154=(a191*a192);
  a178=(a178+a154);
  a163=arg[3]? arg[3][2] : 0;
  a194=(a163*a070);
  a195=(a056*a002);
  a194=(a194*a195);
  a178=(a178-a194);
  a194=arg[1]? arg[1][2] : 0;
  a196=(a062*a072);
  a197=(a019*a014);
  a197=(a050-a197);
  a198=(a052*a197);
  a199=(a198*a011);
  a200=(a196-a199);
  a200=(a194*a200);
  a201=arg[1]? arg[1][5] : 0;
  a202=(a062*a012);
  a202=(a050-a202);
  a202=(a201*a202);
  a200=(a200+a202);
  a202=arg[1]? arg[1][8] : 0;
  a203=(a198*a004);
  a204=(a062*a081);
  a203=(a203+a204);
  a203=(a202*a203);
  a200=(a200+a203);
  a200=(a200*a195);
  a178=(a178+a200);
  a178=(a178/a002);
  if (res[0]!=0) res[0][0]=a178;
  a178=(a048*a081);
  a200=(a148*a004);
  a203=(a178-a200);
  a204=(a203*a089);
  a205=(a048*a012);
  a205=(a050-a205);
  a206=(a205*a188);
  a204=(a204+a206);
  a207=(a056*a011);
  a208=(a185-a207);
  a209=(a208*a192);
  a204=(a204+a209);
  a209=(a163*a071);
  a209=(a209*a195);
  a204=(a204-a209);
  a209=(a062*a008);
  a209=(a050-a209);
  a209=(a194*a209);
  a199=(a199+a196);
  a199=(a201*a199);
  a209=(a209+a199);
  a199=(a062*a054);
  a196=(a198*a007);
  a199=(a199-a196);
  a199=(a202*a199);
  a209=(a209+a199);
  a209=(a209*a195);
  a204=(a204-a209);
  a204=(a204/a002);
  if (res[0]!=0) res[0][1]=a204;
  a204=(a048*a009);
  a204=(a050-a204);
  a209=(a204*a089);
  a199=(a056*a004);
  a196=(a178-a199);
  a210=(a196*a188);
  a210=(a209+a210);
  a211=(a148*a007);
  a212=(a055-a211);
  a213=(a212*a192);
  a210=(a210+a213);
  a213=(a163*a061);
  a213=(a213*a195);
  a210=(a210-a213);
  a210=(a210/a002);
  if (res[0]!=0) res[0][2]=a210;
  a210=(a119*a125);
  a213=(a101*a115);
  a213=(a050-a213);
  a214=(a109*a213);
  a215=(a214*a096);
  a216=(a210-a215);
  a216=(a194*a216);
  a217=(a119*a097);
  a217=(a050-a217);
  a217=(a201*a217);
  a216=(a216+a217);
  a217=(a214*a091);
  a218=(a119*a128);
  a217=(a217+a218);
  a217=(a202*a217);
  a216=(a216+a217);
  a216=(a216*a195);
  a217=(a163*a069);
  a217=(a217*a195);
  a216=(a216-a217);
  a110=(a110-a099);
  a110=(a000+a110);
  a099=(a049*a109);
  a110=(a110/a099);
  a217=(a110*a117);
  a218=(a056*a093);
  a219=(a217-a218);
  a078=(a018*a078);
  a133=(a133+a078);
  a078=-3.8675134594812879e-02;
  a137=(a078*a137);
  a133=(a133+a137);
  a137=(a124*a133);
  a220=(a110*a137);
  a145=(a018*a145);
  a141=(a141+a145);
  a144=(a078*a144);
  a141=(a141+a144);
  a144=(a118*a141);
  a145=(a110*a144);
  a220=(a220+a145);
  a145=(a093*a220);
  a079=(a079-a145);
  a145=(a069*a141);
  a221=(a148*a145);
  a079=(a079+a221);
  a221=(a069*a133);
  a222=(a110*a221);
  a157=(a018*a157);
  a153=(a153+a157);
  a156=(a078*a156);
  a153=(a153+a156);
  a156=(a118*a153);
  a157=(a110*a156);
  a222=(a222+a157);
  a157=(a091*a222);
  a079=(a079-a157);
  a157=(a124*a153);
  a223=(a056*a157);
  a079=(a079+a223);
  a223=(2.*a096);
  a224=(a124*a141);
  a225=(a110*a224);
  a226=(a069*a153);
  a227=(a110*a226);
  a228=(a225+a227);
  a229=(a223*a228);
  a079=(a079+a229);
  a229=(a110/a099);
  a230=(a118*a133);
  a231=(a095*a230);
  a232=(a128*a137);
  a231=(a231-a232);
  a232=(a117*a221);
  a231=(a231-a232);
  a232=(a128*a144);
  a231=(a231-a232);
  a232=(a097*a224);
  a231=(a231+a232);
  a232=(a125*a145);
  a231=(a231-a232);
  a232=(a117*a156);
  a231=(a231-a232);
  a232=(a125*a157);
  a231=(a231-a232);
  a232=(a094*a226);
  a231=(a231+a232);
  a232=(a229*a231);
  a232=(a049*a232);
  a233=(a101*a232);
  a234=(a231/a099);
  a233=(a233-a234);
  a235=(a107*a233);
  a236=(a045*a235);
  a237=(a105*a233);
  a238=(a102*a237);
  a238=(a042*a238);
  a236=(a236+a238);
  a238=(a039*a237);
  a236=(a236+a238);
  a238=(a102*a233);
  a238=(a036*a238);
  a236=(a236+a238);
  a238=(a033*a233);
  a236=(a236+a238);
  a238=(a107*a234);
  a239=(a029*a238);
  a236=(a236+a239);
  a239=(a105*a234);
  a240=(a102*a239);
  a240=(a025*a240);
  a236=(a236+a240);
  a240=(a022*a239);
  a236=(a236+a240);
  a240=(a108*a232);
  a098=(a056*a098);
  a235=(a047*a235);
  a241=(2.*a102);
  a242=(2.*a105);
  a243=(a106*a233);
  a244=(a242*a243);
  a245=(a103*a233);
  a244=(a244+a245);
  a245=(a241*a244);
  a235=(a235+a245);
  a245=(a104*a237);
  a235=(a235+a245);
  a245=(a100*a233);
  a235=(a235+a245);
  a245=(a098*a235);
  a240=(a240+a245);
  a238=(a031*a238);
  a245=(a114*a234);
  a246=(a242*a245);
  a247=(a112*a234);
  a246=(a246+a247);
  a247=(a241*a246);
  a238=(a238+a247);
  a247=(a113*a239);
  a238=(a238+a247);
  a247=(a111*a234);
  a238=(a238+a247);
  a247=(a098*a238);
  a240=(a240+a247);
  a240=(a018*a240);
  a236=(a236+a240);
  a240=(a102*a234);
  a240=(a016*a240);
  a236=(a236+a240);
  a240=(a001*a234);
  a236=(a236+a240);
  a240=(a223*a236);
  a079=(a079+a240);
  a240=(a219*a079);
  a216=(a216+a240);
  a240=(a110*a125);
  a247=(a148*a096);
  a248=(a240-a247);
  a249=(a056*a221);
  a143=(a143+a249);
  a249=(a096*a220);
  a143=(a143-a249);
  a249=(a148*a156);
  a143=(a143+a249);
  a249=(a110*a145);
  a250=(a110*a157);
  a249=(a249+a250);
  a250=(a091*a249);
  a143=(a143-a250);
  a250=(2.*a093);
  a251=(a110*a230);
  a227=(a251+a227);
  a252=(a250*a227);
  a143=(a143+a252);
  a252=(a250*a236);
  a143=(a143+a252);
  a252=(a248*a143);
  a216=(a216+a252);
  a252=(a110*a094);
  a252=(a050-a252);
  a253=(a148*a137);
  a155=(a155+a253);
  a253=(a056*a144);
  a155=(a155+a253);
  a253=(2.*a091);
  a251=(a251+a225);
  a225=(a253*a251);
  a155=(a155+a225);
  a225=(a096*a222);
  a155=(a155-a225);
  a225=(a093*a249);
  a155=(a155-a225);
  a225=(a253*a236);
  a155=(a155+a225);
  a225=(a252*a155);
  a216=(a216+a225);
  a216=(a216/a002);
  if (res[0]!=0) res[0][3]=a216;
  a216=(a110*a128);
  a254=(a148*a091);
  a255=(a216-a254);
  a256=(a255*a079);
  a257=(a163*a124);
  a257=(a257*a195);
  a258=(a119*a094);
  a258=(a050-a258);
  a258=(a194*a258);
  a215=(a215+a210);
  a215=(a201*a215);
  a258=(a258+a215);
  a215=(a119*a117);
  a210=(a214*a093);
  a215=(a215-a210);
  a215=(a202*a215);
  a258=(a258+a215);
  a258=(a258*a195);
  a257=(a257+a258);
  a256=(a256-a257);
  a257=(a110*a097);
  a257=(a050-a257);
  a258=(a257*a143);
  a256=(a256+a258);
  a215=(a056*a096);
  a210=(a240-a215);
  a259=(a210*a155);
  a256=(a256+a259);
  a256=(a256/a002);
  if (res[0]!=0) res[0][4]=a256;
  a256=(a110*a095);
  a256=(a050-a256);
  a259=(a256*a079);
  a260=(a163*a118);
  a260=(a260*a195);
  a260=(a259-a260);
  a261=(a056*a091);
  a262=(a216-a261);
  a263=(a262*a143);
  a260=(a260+a263);
  a263=(a148*a093);
  a264=(a217-a263);
  a265=(a264*a155);
  a260=(a260+a265);
  a260=(a260/a002);
  if (res[0]!=0) res[0][5]=a260;
  a260=arg[2]? arg[2][0] : 0;
  a265=(a056*a075);
  a266=(a056*a006);
  a265=(a265+a266);
  a265=(a002*a265);
  a266=(a056*a265);
  a267=(a056*a067);
  a268=(a056*a003);
  a267=(a267+a268);
  a267=(a002*a267);
  a268=casadi_sq(a267);
  a269=casadi_sq(a265);
  a270=(a268+a269);
  a271=(a056*a077);
  a272=(a056*a010);
  a271=(a271+a272);
  a271=(a002*a271);
  a272=casadi_sq(a271);
  a273=(a270+a272);
  a274=(a001*a273);
  a275=(a016*a273);
  a015=(a015+a275);
  a275=(a018*a273);
  a276=casadi_sq(a275);
  a277=(a015*a276);
  a274=(a274+a277);
  a277=(a022*a273);
  a021=(a021+a277);
  a277=(a025*a273);
  a024=(a024+a277);
  a277=(a024*a276);
  a021=(a021+a277);
  a277=casadi_sq(a276);
  a278=(a021*a277);
  a274=(a274+a278);
  a278=(a029*a273);
  a028=(a028+a278);
  a278=(a031*a276);
  a028=(a028+a278);
  a278=casadi_sq(a277);
  a279=(a028*a278);
  a274=(a274+a279);
  a279=(a033*a273);
  a280=(a036*a273);
  a035=(a035+a280);
  a280=(a035*a276);
  a279=(a279+a280);
  a280=(a039*a273);
  a038=(a038+a280);
  a280=(a042*a273);
  a041=(a041+a280);
  a280=(a041*a276);
  a038=(a038+a280);
  a280=(a038*a277);
  a279=(a279+a280);
  a280=(a045*a273);
  a044=(a044+a280);
  a280=(a047*a276);
  a044=(a044+a280);
  a280=(a044*a278);
  a279=(a279+a280);
  a274=(a274-a279);
  a000=(a000+a274);
  a051=(a051+a279);
  a279=(a275*a051);
  a279=(a050-a279);
  a279=(a049*a279);
  a000=(a000/a279);
  a274=(a267*a271);
  a280=(a000*a274);
  a266=(a266+a280);
  a281=(a266*a088);
  a282=(a148*a271);
  a283=(a267*a265);
  a284=(a000*a283);
  a282=(a282+a284);
  a285=(a282*a140);
  a281=(a281+a285);
  a269=(a269+a272);
  a285=(a000*a269);
  a285=(a050-a285);
  a286=(a285*a152);
  a281=(a281+a286);
  a218=(a218+a217);
  a286=(a218*a079);
  a281=(a281+a286);
  a247=(a247+a240);
  a286=(a247*a143);
  a281=(a281+a286);
  a281=(a281+a225);
  a057=(a057+a055);
  a225=(a057*a089);
  a281=(a281+a225);
  a186=(a186+a185);
  a225=(a186*a188);
  a281=(a281+a225);
  a281=(a281+a154);
  a260=(a260-a281);
  if (res[0]!=0) res[0][6]=a260;
  a260=arg[2]? arg[2][1] : 0;
  a281=(a148*a267);
  a154=(a265*a271);
  a225=(a000*a154);
  a281=(a281+a225);
  a286=(a281*a088);
  a272=(a272+a268);
  a268=(a000*a272);
  a268=(a050-a268);
  a287=(a268*a140);
  a286=(a286+a287);
  a287=(a056*a271);
  a287=(a287+a284);
  a284=(a287*a152);
  a286=(a286+a284);
  a254=(a254+a216);
  a284=(a254*a079);
  a286=(a286+a284);
  a286=(a286+a258);
  a215=(a215+a240);
  a240=(a215*a155);
  a286=(a286+a240);
  a200=(a200+a178);
  a240=(a200*a089);
  a286=(a286+a240);
  a286=(a286+a206);
  a207=(a207+a185);
  a185=(a207*a192);
  a286=(a286+a185);
  a260=(a260-a286);
  if (res[0]!=0) res[0][7]=a260;
  a260=arg[2]? arg[2][2] : 0;
  a286=(a000*a270);
  a050=(a050-a286);
  a286=(a050*a088);
  a185=(a056*a267);
  a185=(a185+a225);
  a225=(a185*a140);
  a286=(a286+a225);
  a225=(a148*a265);
  a225=(a225+a280);
  a280=(a225*a152);
  a286=(a286+a280);
  a286=(a286+a259);
  a261=(a261+a216);
  a216=(a261*a143);
  a286=(a286+a216);
  a263=(a263+a217);
  a217=(a263*a155);
  a286=(a286+a217);
  a286=(a286+a209);
  a199=(a199+a178);
  a178=(a199*a188);
  a286=(a286+a178);
  a211=(a211+a055);
  a055=(a211*a192);
  a286=(a286+a055);
  a260=(a260-a286);
  if (res[0]!=0) res[0][8]=a260;
  a260=(a193*a002);
  a286=(a001*a260);
  a055=(a016*a260);
  a178=(a020*a055);
  a209=(a018*a260);
  a217=(a013*a209);
  a216=(a017*a217);
  a178=(a178+a216);
  a286=(a286+a178);
  a178=(a022*a260);
  a216=(a025*a260);
  a259=(a020*a216);
  a280=(a026*a217);
  a259=(a259+a280);
  a178=(a178+a259);
  a259=(a027*a178);
  a280=(a179*a217);
  a206=(a023*a280);
  a259=(a259+a206);
  a286=(a286+a259);
  a259=(a029*a260);
  a206=(a031*a217);
  a259=(a259+a206);
  a206=(a032*a259);
  a240=(a180*a280);
  a258=(a030*a240);
  a206=(a206+a258);
  a286=(a286+a206);
  a206=(a033*a260);
  a258=(a036*a260);
  a284=(a020*a258);
  a288=(a037*a217);
  a284=(a284+a288);
  a206=(a206+a284);
  a284=(a039*a260);
  a288=(a042*a260);
  a289=(a020*a288);
  a290=(a043*a217);
  a289=(a289+a290);
  a284=(a284+a289);
  a289=(a027*a284);
  a290=(a040*a280);
  a289=(a289+a290);
  a206=(a206+a289);
  a289=(a045*a260);
  a290=(a047*a217);
  a289=(a289+a290);
  a290=(a032*a289);
  a291=(a046*a240);
  a290=(a290+a291);
  a206=(a206+a290);
  a290=(a286-a206);
  a290=(a290/a053);
  a291=(a034*a209);
  a292=(a019*a206);
  a291=(a291+a292);
  a292=(a049*a291);
  a293=(a167*a292);
  a290=(a290+a293);
  a293=(a054*a290);
  a294=(a011*a002);
  a295=(a048*a294);
  a293=(a293+a295);
  a296=(a089*a293);
  a297=(a052*a286);
  a298=(a014*a291);
  a297=(a297-a298);
  a297=(a206+a297);
  a297=(a018*a297);
  a298=(a054*a297);
  a299=(a060*a294);
  a298=(a298+a299);
  a300=(2.*a052);
  a301=(a300*a291);
  a301=(a056*a301);
  a302=(a007*a301);
  a303=(a298+a302);
  a304=(a070*a303);
  a305=(a066*a065);
  a306=(a008*a297);
  a307=(a067*a306);
  a305=(a305-a307);
  a307=(a072*a297);
  a308=(a007*a002);
  a309=(a060*a308);
  a307=(a307+a309);
  a310=(a011*a301);
  a311=(a307-a310);
  a312=(a075*a311);
  a305=(a305+a312);
  a303=(a077*a303);
  a305=(a305+a303);
  a303=(a064*a305);
  a304=(a304+a303);
  a303=(a062*a002);
  a312=(a004*a301);
  a312=(a303-a312);
  a313=(a081*a297);
  a314=(a312+a313);
  a315=(a085*a314);
  a307=(a307+a310);
  a310=(a067*a307);
  a316=(a066*a073);
  a310=(a310+a316);
  a316=(a012*a297);
  a317=(a060*a260);
  a316=(a316+a317);
  a318=(a075*a316);
  a310=(a310-a318);
  a314=(a077*a314);
  a310=(a310+a314);
  a314=(a084*a310);
  a318=(a083*a314);
  a315=(a315+a318);
  a304=(a304+a315);
  a298=(a298-a302);
  a302=(a067*a298);
  a315=(a066*a063);
  a302=(a302+a315);
  a313=(a313-a312);
  a312=(a075*a313);
  a302=(a302+a312);
  a297=(a009*a297);
  a297=(a297+a317);
  a317=(a077*a297);
  a302=(a302-a317);
  a317=(a087*a302);
  a312=(a086*a317);
  a297=(a080*a297);
  a312=(a312-a297);
  a304=(a304+a312);
  a312=(a059*a304);
  a297=(a123*a122);
  a315=(a121*a297);
  a318=-3.2320508075688778e+01;
  a319=(a318*a126);
  a320=(a130*a319);
  a315=(a315+a320);
  a320=-3.8784609690826528e+01;
  a321=(a320*a120);
  a322=(a132*a321);
  a315=(a315+a322);
  a322=(a090*a315);
  a312=(a312+a322);
  a322=(a138*a290);
  a323=(a136*a310);
  a304=(a135*a304);
  a315=(a059*a315);
  a304=(a304+a315);
  a315=(a002*a304);
  a324=(a134*a315);
  a325=(a002*a312);
  a326=(a018*a325);
  a324=(a324+a326);
  a326=(a071*a324);
  a323=(a323+a326);
  a326=(a048*a323);
  a322=(a322+a326);
  a326=(a147*a290);
  a327=(a146*a302);
  a311=(a070*a311);
  a328=(a074*a305);
  a311=(a311+a328);
  a328=(a005*a314);
  a316=(a085*a316);
  a328=(a328-a316);
  a311=(a311+a328);
  a313=(a080*a313);
  a328=(a082*a317);
  a313=(a313+a328);
  a311=(a311+a313);
  a313=(a135*a311);
  a328=(a127*a297);
  a316=(a092*a319);
  a328=(a328+a316);
  a316=(a129*a321);
  a328=(a328+a316);
  a316=(a059*a328);
  a313=(a313+a316);
  a316=(a002*a313);
  a329=(a134*a316);
  a311=(a059*a311);
  a328=(a090*a328);
  a311=(a311+a328);
  a328=(a002*a311);
  a330=(a018*a328);
  a329=(a329+a330);
  a330=(a061*a329);
  a327=(a327+a330);
  a330=(a048*a327);
  a326=(a326+a330);
  a322=(a322+a326);
  a326=(a007*a322);
  a312=(a312-a326);
  a326=(a146*a305);
  a330=(a070*a329);
  a326=(a326+a330);
  a330=(a148*a326);
  a312=(a312+a330);
  a151=(a151*a002);
  a330=(a150*a290);
  a331=(a136*a305);
  a332=(a070*a324);
  a331=(a331+a332);
  a332=(a048*a331);
  a330=(a330+a332);
  a332=(a159*a290);
  a333=(a158*a302);
  a334=(a065*a305);
  a306=(a070*a306);
  a334=(a334-a306);
  a307=(a085*a307);
  a314=(a073*a314);
  a307=(a307+a314);
  a334=(a334+a307);
  a298=(a080*a298);
  a317=(a063*a317);
  a298=(a298+a317);
  a334=(a334+a298);
  a298=(a135*a334);
  a317=(a122*a297);
  a319=(a126*a319);
  a317=(a317+a319);
  a321=(a120*a321);
  a317=(a317+a321);
  a321=(a059*a317);
  a298=(a298+a321);
  a321=(a002*a298);
  a319=(a134*a321);
  a334=(a059*a334);
  a317=(a090*a317);
  a334=(a334+a317);
  a317=(a002*a334);
  a307=(a018*a317);
  a319=(a319+a307);
  a307=(a061*a319);
  a333=(a333+a307);
  a307=(a048*a333);
  a332=(a332+a307);
  a330=(a330+a332);
  a332=(a004*a330);
  a332=(a151+a332);
  a312=(a312-a332);
  a332=(a158*a310);
  a307=(a071*a319);
  a332=(a332+a307);
  a307=(a056*a332);
  a312=(a312+a307);
  a307=(a162*a290);
  a314=(a146*a310);
  a329=(a071*a329);
  a314=(a314+a329);
  a329=(a048*a314);
  a307=(a307+a329);
  a329=(a164*a290);
  a306=(a158*a305);
  a319=(a070*a319);
  a306=(a306+a319);
  a319=(a048*a306);
  a329=(a329+a319);
  a319=(a307+a329);
  a319=(a161*a319);
  a312=(a312+a319);
  a319=(a171*a240);
  a335=(a170*a209);
  a336=(a290/a053);
  a337=(a167/a053);
  a338=(a337*a292);
  a336=(a336+a338);
  a336=(a169*a336);
  a338=(a168*a260);
  a339=(a136*a302);
  a324=(a061*a324);
  a339=(a339+a324);
  a324=(a009*a339);
  a338=(a338+a324);
  a324=(a081*a323);
  a338=(a338-a324);
  a324=(a150*a294);
  a340=(a054*a331);
  a324=(a324+a340);
  a338=(a338-a324);
  a324=(a081*a327);
  a338=(a338-a324);
  a324=(a162*a260);
  a314=(a012*a314);
  a324=(a324+a314);
  a338=(a338+a324);
  a324=(a149*a308);
  a314=(a072*a326);
  a324=(a324+a314);
  a338=(a338-a324);
  a324=(a159*a294);
  a314=(a054*a333);
  a324=(a324+a314);
  a338=(a338-a324);
  a324=(a160*a308);
  a314=(a072*a332);
  a324=(a324+a314);
  a338=(a338-a324);
  a306=(a008*a306);
  a338=(a338+a306);
  a306=(a167*a338);
  a336=(a336+a306);
  a336=(a049*a336);
  a306=(a019*a336);
  a335=(a335+a306);
  a338=(a338/a053);
  a306=(a172/a053);
  a292=(a306*a292);
  a338=(a338+a292);
  a335=(a335-a338);
  a292=(a032*a335);
  a319=(a319+a292);
  a292=(a045*a319);
  a324=(a175*a217);
  a314=(a171*a280);
  a340=(a027*a335);
  a314=(a314+a340);
  a340=(a020*a314);
  a324=(a324+a340);
  a324=(a042*a324);
  a292=(a292+a324);
  a324=(a039*a314);
  a292=(a292+a324);
  a324=(a171*a217);
  a340=(a020*a335);
  a324=(a324+a340);
  a324=(a036*a324);
  a292=(a292+a324);
  a324=(a033*a335);
  a292=(a292+a324);
  a240=(a172*a240);
  a324=(a032*a338);
  a240=(a240+a324);
  a324=(a029*a240);
  a292=(a292+a324);
  a324=(a177*a217);
  a340=(a172*a280);
  a341=(a027*a338);
  a340=(a340+a341);
  a341=(a020*a340);
  a324=(a324+a341);
  a324=(a025*a324);
  a292=(a292+a324);
  a324=(a022*a340);
  a292=(a292+a324);
  a206=(a170*a206);
  a336=(a034*a336);
  a206=(a206+a336);
  a336=(a056*a260);
  a324=(a173*a336);
  a319=(a047*a319);
  a341=(2.*a217);
  a342=(a182*a341);
  a280=(2.*a280);
  a343=(a181*a280);
  a289=(a171*a289);
  a344=(a046*a335);
  a289=(a289+a344);
  a289=(a180*a289);
  a343=(a343+a289);
  a284=(a171*a284);
  a289=(a040*a335);
  a284=(a284+a289);
  a343=(a343+a284);
  a343=(a179*a343);
  a342=(a342+a343);
  a319=(a319+a342);
  a288=(a175*a288);
  a314=(a043*a314);
  a288=(a288+a314);
  a319=(a319+a288);
  a258=(a171*a258);
  a335=(a037*a335);
  a258=(a258+a335);
  a319=(a319+a258);
  a319=(a013*a319);
  a324=(a324+a319);
  a206=(a206+a324);
  a336=(a176*a336);
  a240=(a031*a240);
  a341=(a184*a341);
  a280=(a183*a280);
  a259=(a172*a259);
  a324=(a030*a338);
  a259=(a259+a324);
  a259=(a180*a259);
  a280=(a280+a259);
  a178=(a172*a178);
  a259=(a023*a338);
  a178=(a178+a259);
  a280=(a280+a178);
  a280=(a179*a280);
  a341=(a341+a280);
  a240=(a240+a341);
  a216=(a177*a216);
  a340=(a026*a340);
  a216=(a216+a340);
  a240=(a240+a216);
  a055=(a172*a055);
  a216=(a017*a338);
  a055=(a055+a216);
  a240=(a240+a055);
  a240=(a013*a240);
  a336=(a336+a240);
  a206=(a206+a336);
  a206=(a018*a206);
  a292=(a292+a206);
  a217=(a172*a217);
  a206=(a020*a338);
  a217=(a217+a206);
  a217=(a016*a217);
  a292=(a292+a217);
  a338=(a001*a338);
  a292=(a292+a338);
  a338=(a161*a292);
  a312=(a312+a338);
  a338=(a058*a312);
  a338=(a296+a338);
  a217=(a072*a290);
  a206=(a048*a308);
  a217=(a217+a206);
  a336=(a188*a217);
  a331=(a056*a331);
  a331=(a331+a311);
  a322=(a011*a322);
  a331=(a331-a322);
  a333=(a148*a333);
  a331=(a331+a333);
  a142=(a142*a002);
  a333=(a149*a290);
  a326=(a048*a326);
  a333=(a333+a326);
  a326=(a160*a290);
  a332=(a048*a332);
  a326=(a326+a332);
  a333=(a333+a326);
  a326=(a004*a333);
  a326=(a142+a326);
  a331=(a331-a326);
  a326=(a168*a290);
  a339=(a048*a339);
  a326=(a326+a339);
  a329=(a326+a329);
  a329=(a189*a329);
  a331=(a331+a329);
  a329=(a189*a292);
  a331=(a331+a329);
  a329=(a187*a331);
  a329=(a336+a329);
  a338=(a338+a329);
  a323=(a148*a323);
  a327=(a056*a327);
  a323=(a323+a327);
  a327=(2.*a002);
  a190=(a190*a327);
  a326=(a326+a307);
  a326=(a193*a326);
  a190=(a190+a326);
  a323=(a323+a190);
  a323=(a323+a334);
  a330=(a011*a330);
  a323=(a323-a330);
  a333=(a007*a333);
  a323=(a323-a333);
  a174=(a174*a327);
  a292=(a193*a292);
  a292=(a174+a292);
  a323=(a323+a292);
  a292=(a191*a323);
  a333=(a008*a290);
  a333=(a192*a333);
  a292=(a292-a333);
  a338=(a338+a292);
  a305=(a163*a305);
  a305=(a195*a305);
  a338=(a338-a305);
  a305=(a062*a308);
  a333=(a072*a301);
  a333=(a305-a333);
  a291=(a197*a291);
  a209=(a014*a209);
  a286=(a019*a286);
  a209=(a209+a286);
  a209=(a052*a209);
  a291=(a291+a209);
  a209=(a011*a291);
  a286=(a333+a209);
  a286=(a194*a286);
  a330=(a062*a260);
  a334=(a012*a301);
  a330=(a330-a334);
  a330=(a201*a330);
  a286=(a286-a330);
  a198=(a198*a002);
  a330=(a004*a291);
  a330=(a198-a330);
  a334=(a081*a301);
  a330=(a330-a334);
  a330=(a202*a330);
  a286=(a286+a330);
  a286=(a195*a286);
  a338=(a338+a286);
  a338=(a338/a002);
  if (res[1]!=0) res[1][0]=a338;
  a338=(a081*a290);
  a286=(a148*a002);
  a330=(a338-a286);
  a330=(a089*a330);
  a334=(a203*a312);
  a330=(a330+a334);
  a334=(a205*a331);
  a190=(a012*a290);
  a260=(a048*a260);
  a190=(a190+a260);
  a190=(a188*a190);
  a334=(a334-a190);
  a330=(a330+a334);
  a217=(a192*a217);
  a190=(a208*a323);
  a190=(a217+a190);
  a330=(a330+a190);
  a310=(a163*a310);
  a310=(a195*a310);
  a330=(a330-a310);
  a310=(a008*a301);
  a310=(a194*a310);
  a333=(a333-a209);
  a333=(a201*a333);
  a310=(a310+a333);
  a333=(a062*a294);
  a301=(a054*a301);
  a301=(a333-a301);
  a291=(a007*a291);
  a301=(a301+a291);
  a301=(a202*a301);
  a310=(a310+a301);
  a310=(a195*a310);
  a330=(a330-a310);
  a330=(a330/a002);
  if (res[1]!=0) res[1][1]=a330;
  a330=(a204*a312);
  a290=(a009*a290);
  a290=(a290+a260);
  a290=(a089*a290);
  a330=(a330-a290);
  a290=(a338-a195);
  a290=(a188*a290);
  a260=(a196*a331);
  a290=(a290+a260);
  a290=(a330+a290);
  a293=(a192*a293);
  a260=(a212*a323);
  a260=(a293+a260);
  a290=(a290+a260);
  a302=(a163*a302);
  a302=(a195*a302);
  a290=(a290-a302);
  a290=(a290/a002);
  if (res[1]!=0) res[1][2]=a290;
  a290=(a123*a126);
  a302=(a133*a290);
  a315=(a018*a315);
  a325=(a078*a325);
  a315=(a315+a325);
  a325=(a124*a315);
  a302=(a302+a325);
  a325=(a110*a302);
  a260=(a123*a120);
  a310=(a141*a260);
  a316=(a018*a316);
  a328=(a078*a328);
  a316=(a316+a328);
  a328=(a118*a316);
  a310=(a310+a328);
  a328=(a110*a310);
  a325=(a325+a328);
  a328=(a093*a325);
  a304=(a304-a328);
  a328=(a141*a297);
  a301=(a069*a316);
  a328=(a328+a301);
  a301=(a148*a328);
  a304=(a304+a301);
  a301=(a133*a297);
  a291=(a069*a315);
  a301=(a301+a291);
  a291=(a110*a301);
  a209=(a153*a260);
  a321=(a018*a321);
  a317=(a078*a317);
  a321=(a321+a317);
  a317=(a118*a321);
  a209=(a209+a317);
  a317=(a110*a209);
  a291=(a291+a317);
  a317=(a091*a291);
  a304=(a304-a317);
  a317=(a153*a290);
  a190=(a124*a321);
  a317=(a317+a190);
  a190=(a056*a317);
  a304=(a304+a190);
  a190=(a141*a290);
  a316=(a124*a316);
  a190=(a190+a316);
  a316=(a110*a190);
  a326=(a153*a297);
  a321=(a069*a321);
  a326=(a326+a321);
  a321=(a110*a326);
  a307=(a316+a321);
  a307=(a223*a307);
  a304=(a304+a307);
  a307=(a133*a260);
  a315=(a118*a315);
  a307=(a307+a315);
  a315=(a095*a307);
  a329=(a128*a302);
  a315=(a315-a329);
  a329=(a117*a301);
  a315=(a315-a329);
  a329=(a128*a310);
  a315=(a315-a329);
  a190=(a097*a190);
  a315=(a315+a190);
  a190=(a125*a328);
  a315=(a315-a190);
  a190=(a117*a209);
  a315=(a315-a190);
  a190=(a125*a317);
  a315=(a315-a190);
  a326=(a094*a326);
  a315=(a315+a326);
  a326=(a229*a315);
  a326=(a049*a326);
  a190=(a101*a326);
  a315=(a315/a099);
  a190=(a190-a315);
  a329=(a107*a190);
  a339=(a045*a329);
  a332=(a105*a190);
  a322=(a102*a332);
  a322=(a042*a322);
  a339=(a339+a322);
  a322=(a039*a332);
  a339=(a339+a322);
  a322=(a102*a190);
  a322=(a036*a322);
  a339=(a339+a322);
  a322=(a033*a190);
  a339=(a339+a322);
  a322=(a107*a315);
  a311=(a029*a322);
  a339=(a339+a311);
  a311=(a105*a315);
  a240=(a102*a311);
  a240=(a025*a240);
  a339=(a339+a240);
  a240=(a022*a311);
  a339=(a339+a240);
  a326=(a108*a326);
  a329=(a047*a329);
  a240=(a106*a190);
  a240=(a242*a240);
  a055=(a103*a190);
  a240=(a240+a055);
  a240=(a241*a240);
  a329=(a329+a240);
  a332=(a104*a332);
  a329=(a329+a332);
  a190=(a100*a190);
  a329=(a329+a190);
  a329=(a098*a329);
  a326=(a326+a329);
  a322=(a031*a322);
  a329=(a114*a315);
  a329=(a242*a329);
  a190=(a112*a315);
  a329=(a329+a190);
  a329=(a241*a329);
  a322=(a322+a329);
  a311=(a113*a311);
  a322=(a322+a311);
  a311=(a111*a315);
  a322=(a322+a311);
  a322=(a098*a322);
  a326=(a326+a322);
  a326=(a018*a326);
  a339=(a339+a326);
  a326=(a102*a315);
  a326=(a016*a326);
  a339=(a339+a326);
  a315=(a001*a315);
  a339=(a339+a315);
  a315=(a223*a339);
  a304=(a304+a315);
  a315=(a219*a304);
  a297=(a163*a297);
  a297=(a195*a297);
  a315=(a315-a297);
  a301=(a056*a301);
  a313=(a313+a301);
  a325=(a096*a325);
  a313=(a313-a325);
  a209=(a148*a209);
  a313=(a313+a209);
  a328=(a110*a328);
  a317=(a110*a317);
  a328=(a328+a317);
  a317=(a091*a328);
  a313=(a313-a317);
  a307=(a110*a307);
  a321=(a307+a321);
  a321=(a250*a321);
  a313=(a313+a321);
  a321=(a250*a339);
  a313=(a313+a321);
  a321=(a248*a313);
  a315=(a315+a321);
  a302=(a148*a302);
  a298=(a298+a302);
  a310=(a056*a310);
  a298=(a298+a310);
  a307=(a307+a316);
  a307=(a253*a307);
  a298=(a298+a307);
  a291=(a096*a291);
  a298=(a298-a291);
  a328=(a093*a328);
  a298=(a298-a328);
  a339=(a253*a339);
  a298=(a298+a339);
  a339=(a252*a298);
  a315=(a315+a339);
  a315=(a315/a002);
  if (res[1]!=0) res[1][3]=a315;
  a315=(a255*a304);
  a290=(a163*a290);
  a290=(a195*a290);
  a315=(a315-a290);
  a290=(a257*a313);
  a315=(a315+a290);
  a328=(a210*a298);
  a315=(a315+a328);
  a315=(a315/a002);
  if (res[1]!=0) res[1][4]=a315;
  a315=(a256*a304);
  a260=(a163*a260);
  a260=(a195*a260);
  a260=(a315-a260);
  a328=(a262*a313);
  a260=(a260+a328);
  a328=(a264*a298);
  a260=(a260+a328);
  a260=(a260/a002);
  if (res[1]!=0) res[1][5]=a260;
  a260=(2.*a267);
  a328=-1.7320508075688774e+00;
  a291=(a328*a002);
  a307=(a260*a291);
  a316=(a001*a307);
  a310=(a016*a307);
  a310=(a276*a310);
  a273=(a056*a273);
  a302=(a018*a307);
  a321=(a273*a302);
  a317=(a015*a321);
  a310=(a310+a317);
  a316=(a316+a310);
  a310=(a022*a307);
  a317=(a025*a307);
  a317=(a276*a317);
  a209=(a024*a321);
  a317=(a317+a209);
  a310=(a310+a317);
  a310=(a277*a310);
  a317=(2.*a276);
  a209=(a317*a321);
  a325=(a021*a209);
  a310=(a310+a325);
  a316=(a316+a310);
  a310=(a029*a307);
  a325=(a031*a321);
  a310=(a310+a325);
  a310=(a278*a310);
  a325=(2.*a277);
  a301=(a325*a209);
  a297=(a028*a301);
  a310=(a310+a297);
  a316=(a316+a310);
  a310=(a033*a307);
  a297=(a036*a307);
  a297=(a276*a297);
  a326=(a035*a321);
  a297=(a297+a326);
  a310=(a310+a297);
  a297=(a039*a307);
  a326=(a042*a307);
  a326=(a276*a326);
  a322=(a041*a321);
  a326=(a326+a322);
  a297=(a297+a326);
  a297=(a277*a297);
  a209=(a038*a209);
  a297=(a297+a209);
  a310=(a310+a297);
  a297=(a045*a307);
  a321=(a047*a321);
  a297=(a297+a321);
  a297=(a278*a297);
  a301=(a044*a301);
  a297=(a297+a301);
  a310=(a310+a297);
  a316=(a316-a310);
  a316=(a316/a279);
  a297=(a000/a279);
  a302=(a051*a302);
  a310=(a275*a310);
  a302=(a302+a310);
  a302=(a049*a302);
  a302=(a297*a302);
  a316=(a316+a302);
  a302=(a274*a316);
  a310=(a271*a291);
  a310=(a000*a310);
  a302=(a302+a310);
  a301=(a088*a302);
  a321=(a283*a316);
  a209=(a265*a291);
  a209=(a000*a209);
  a321=(a321+a209);
  a326=(a140*a321);
  a301=(a301+a326);
  a326=(a269*a316);
  a326=(a152*a326);
  a301=(a301-a326);
  a326=(a218*a304);
  a301=(a301+a326);
  a326=(a247*a313);
  a301=(a301+a326);
  a301=(a301+a339);
  a339=(a057*a312);
  a296=(a296+a339);
  a301=(a301+a296);
  a296=(a186*a331);
  a336=(a336+a296);
  a301=(a301+a336);
  a301=(a301+a292);
  a301=(-a301);
  if (res[1]!=0) res[1][6]=a301;
  a301=8.6602540378443871e-01;
  a301=(a301*a002);
  a292=(a154*a316);
  a336=(a301+a292);
  a336=(a088*a336);
  a296=(a272*a316);
  a307=(a000*a307);
  a296=(a296+a307);
  a296=(a140*a296);
  a336=(a336-a296);
  a321=(a152*a321);
  a336=(a336+a321);
  a304=(a254*a304);
  a336=(a336+a304);
  a336=(a336+a290);
  a290=(a215*a298);
  a336=(a336+a290);
  a290=(a286+a338);
  a290=(a089*a290);
  a312=(a200*a312);
  a290=(a290+a312);
  a336=(a336+a290);
  a336=(a336+a334);
  a334=(a207*a323);
  a217=(a217+a334);
  a336=(a336+a217);
  a336=(-a336);
  if (res[1]!=0) res[1][7]=a336;
  a336=-8.6602540378443871e-01;
  a336=(a336*a002);
  a292=(a336+a292);
  a292=(a140*a292);
  a316=(a270*a316);
  a316=(a316+a307);
  a316=(a088*a316);
  a292=(a292-a316);
  a302=(a152*a302);
  a292=(a292+a302);
  a292=(a292+a315);
  a313=(a261*a313);
  a292=(a292+a313);
  a298=(a263*a298);
  a292=(a292+a298);
  a292=(a292+a330);
  a338=(a195+a338);
  a338=(a188*a338);
  a331=(a199*a331);
  a338=(a338+a331);
  a292=(a292+a338);
  a323=(a211*a323);
  a293=(a293+a323);
  a292=(a292+a293);
  a292=(-a292);
  if (res[1]!=0) res[1][8]=a292;
  a292=(a189*a002);
  a293=(a001*a292);
  a323=(a016*a292);
  a338=(a020*a323);
  a331=(a018*a292);
  a330=(a013*a331);
  a298=(a017*a330);
  a338=(a338+a298);
  a293=(a293+a338);
  a338=(a022*a292);
  a298=(a025*a292);
  a313=(a020*a298);
  a315=(a026*a330);
  a313=(a313+a315);
  a338=(a338+a313);
  a313=(a027*a338);
  a315=(a179*a330);
  a302=(a023*a315);
  a313=(a313+a302);
  a293=(a293+a313);
  a313=(a029*a292);
  a302=(a031*a330);
  a313=(a313+a302);
  a302=(a032*a313);
  a316=(a180*a315);
  a307=(a030*a316);
  a302=(a302+a307);
  a293=(a293+a302);
  a302=(a033*a292);
  a307=(a036*a292);
  a217=(a020*a307);
  a334=(a037*a330);
  a217=(a217+a334);
  a302=(a302+a217);
  a217=(a039*a292);
  a334=(a042*a292);
  a290=(a020*a334);
  a312=(a043*a330);
  a290=(a290+a312);
  a217=(a217+a290);
  a290=(a027*a217);
  a312=(a040*a315);
  a290=(a290+a312);
  a302=(a302+a290);
  a290=(a045*a292);
  a312=(a047*a330);
  a290=(a290+a312);
  a312=(a032*a290);
  a304=(a046*a316);
  a312=(a312+a304);
  a302=(a302+a312);
  a312=(a293-a302);
  a312=(a312/a053);
  a304=(a034*a331);
  a321=(a019*a302);
  a304=(a304+a321);
  a321=(a049*a304);
  a296=(a167*a321);
  a312=(a312+a296);
  a296=(a054*a312);
  a339=(a296-a195);
  a339=(a089*a339);
  a326=(a052*a293);
  a322=(a014*a304);
  a326=(a326-a322);
  a326=(a302+a326);
  a326=(a018*a326);
  a322=(a054*a326);
  a311=(a300*a304);
  a311=(a056*a311);
  a329=(a007*a311);
  a329=(a303-a329);
  a190=(a322-a329);
  a332=(a070*a190);
  a240=(a072*a326);
  a055=(a004*a002);
  a216=(a060*a055);
  a240=(a240+a216);
  a340=(a011*a311);
  a341=(a240-a340);
  a280=(a075*a341);
  a178=(a066*a074);
  a280=(a280+a178);
  a178=(a008*a326);
  a259=(a060*a292);
  a178=(a178+a259);
  a324=(a067*a178);
  a280=(a280-a324);
  a190=(a077*a190);
  a280=(a280+a190);
  a190=(a064*a280);
  a332=(a332+a190);
  a190=(a081*a326);
  a190=(a190+a299);
  a299=(a004*a311);
  a324=(a190-a299);
  a319=(a085*a324);
  a240=(a240+a340);
  a340=(a067*a240);
  a258=(a066*a005);
  a335=(a012*a326);
  a288=(a075*a335);
  a258=(a258-a288);
  a340=(a340+a258);
  a324=(a077*a324);
  a340=(a340+a324);
  a324=(a084*a340);
  a258=(a083*a324);
  a319=(a319+a258);
  a332=(a332+a319);
  a329=(a329+a322);
  a322=(a067*a329);
  a190=(a190+a299);
  a299=(a075*a190);
  a319=(a066*a082);
  a299=(a299+a319);
  a322=(a322+a299);
  a326=(a009*a326);
  a326=(a326+a259);
  a259=(a077*a326);
  a322=(a322-a259);
  a259=(a087*a322);
  a299=(a086*a259);
  a326=(a080*a326);
  a299=(a299-a326);
  a332=(a332+a299);
  a299=(a059*a332);
  a326=(a123*a127);
  a319=(a121*a326);
  a258=(a318*a092);
  a288=(a130*a258);
  a319=(a319+a288);
  a288=(a320*a129);
  a314=(a132*a288);
  a319=(a319+a314);
  a314=(a090*a319);
  a299=(a299+a314);
  a139=(a139*a002);
  a314=(a138*a312);
  a342=(a136*a340);
  a332=(a135*a332);
  a319=(a059*a319);
  a332=(a332+a319);
  a319=(a002*a332);
  a343=(a134*a319);
  a284=(a002*a299);
  a289=(a018*a284);
  a343=(a343+a289);
  a289=(a071*a343);
  a342=(a342+a289);
  a289=(a048*a342);
  a314=(a314+a289);
  a289=(a147*a312);
  a344=(a146*a322);
  a341=(a070*a341);
  a345=(a074*a280);
  a341=(a341+a345);
  a345=(a005*a324);
  a335=(a085*a335);
  a345=(a345-a335);
  a341=(a341+a345);
  a190=(a080*a190);
  a345=(a082*a259);
  a190=(a190+a345);
  a341=(a341+a190);
  a190=(a135*a341);
  a345=(a127*a326);
  a335=(a092*a258);
  a345=(a345+a335);
  a335=(a129*a288);
  a345=(a345+a335);
  a335=(a059*a345);
  a190=(a190+a335);
  a335=(a002*a190);
  a346=(a134*a335);
  a341=(a059*a341);
  a345=(a090*a345);
  a341=(a341+a345);
  a345=(a002*a341);
  a347=(a018*a345);
  a346=(a346+a347);
  a347=(a061*a346);
  a344=(a344+a347);
  a347=(a048*a344);
  a289=(a289+a347);
  a314=(a314+a289);
  a289=(a007*a314);
  a289=(a139+a289);
  a299=(a299-a289);
  a289=(a146*a280);
  a347=(a070*a346);
  a289=(a289+a347);
  a347=(a148*a289);
  a299=(a299+a347);
  a347=(a150*a312);
  a348=(a136*a280);
  a349=(a070*a343);
  a348=(a348+a349);
  a349=(a048*a348);
  a347=(a347+a349);
  a349=(a159*a312);
  a350=(a158*a322);
  a351=(a065*a280);
  a178=(a070*a178);
  a351=(a351-a178);
  a240=(a085*a240);
  a324=(a073*a324);
  a240=(a240+a324);
  a351=(a351+a240);
  a329=(a080*a329);
  a259=(a063*a259);
  a329=(a329+a259);
  a351=(a351+a329);
  a329=(a135*a351);
  a259=(a122*a326);
  a258=(a126*a258);
  a259=(a259+a258);
  a288=(a120*a288);
  a259=(a259+a288);
  a288=(a059*a259);
  a329=(a329+a288);
  a288=(a002*a329);
  a258=(a134*a288);
  a351=(a059*a351);
  a259=(a090*a259);
  a351=(a351+a259);
  a259=(a002*a351);
  a240=(a018*a259);
  a258=(a258+a240);
  a240=(a061*a258);
  a350=(a350+a240);
  a240=(a048*a350);
  a349=(a349+a240);
  a347=(a347+a349);
  a349=(a004*a347);
  a299=(a299-a349);
  a349=(a158*a340);
  a240=(a071*a258);
  a349=(a349+a240);
  a240=(a056*a349);
  a299=(a299+a240);
  a240=(a162*a312);
  a324=(a146*a340);
  a346=(a071*a346);
  a324=(a324+a346);
  a346=(a048*a324);
  a240=(a240+a346);
  a346=(a164*a312);
  a178=(a158*a280);
  a258=(a070*a258);
  a178=(a178+a258);
  a258=(a048*a178);
  a346=(a346+a258);
  a258=(a240+a346);
  a258=(a161*a258);
  a299=(a299+a258);
  a258=(a171*a316);
  a352=(a170*a331);
  a353=(a312/a053);
  a354=(a337*a321);
  a353=(a353+a354);
  a353=(a169*a353);
  a354=(a168*a292);
  a355=(a136*a322);
  a343=(a061*a343);
  a355=(a355+a343);
  a343=(a009*a355);
  a354=(a354+a343);
  a343=(a138*a294);
  a356=(a081*a342);
  a343=(a343+a356);
  a354=(a354-a343);
  a343=(a054*a348);
  a354=(a354-a343);
  a294=(a147*a294);
  a343=(a081*a344);
  a294=(a294+a343);
  a354=(a354-a294);
  a324=(a012*a324);
  a354=(a354+a324);
  a324=(a149*a055);
  a294=(a072*a289);
  a324=(a324+a294);
  a354=(a354-a324);
  a324=(a054*a350);
  a354=(a354-a324);
  a324=(a160*a055);
  a294=(a072*a349);
  a324=(a324+a294);
  a354=(a354-a324);
  a324=(a164*a292);
  a178=(a008*a178);
  a324=(a324+a178);
  a354=(a354+a324);
  a324=(a167*a354);
  a353=(a353+a324);
  a353=(a049*a353);
  a324=(a019*a353);
  a352=(a352+a324);
  a354=(a354/a053);
  a321=(a306*a321);
  a354=(a354+a321);
  a352=(a352-a354);
  a321=(a032*a352);
  a258=(a258+a321);
  a321=(a045*a258);
  a324=(a175*a330);
  a178=(a171*a315);
  a294=(a027*a352);
  a178=(a178+a294);
  a294=(a020*a178);
  a324=(a324+a294);
  a324=(a042*a324);
  a321=(a321+a324);
  a324=(a039*a178);
  a321=(a321+a324);
  a324=(a171*a330);
  a294=(a020*a352);
  a324=(a324+a294);
  a324=(a036*a324);
  a321=(a321+a324);
  a324=(a033*a352);
  a321=(a321+a324);
  a316=(a172*a316);
  a324=(a032*a354);
  a316=(a316+a324);
  a324=(a029*a316);
  a321=(a321+a324);
  a324=(a177*a330);
  a294=(a172*a315);
  a343=(a027*a354);
  a294=(a294+a343);
  a343=(a020*a294);
  a324=(a324+a343);
  a324=(a025*a324);
  a321=(a321+a324);
  a324=(a022*a294);
  a321=(a321+a324);
  a302=(a170*a302);
  a353=(a034*a353);
  a302=(a302+a353);
  a353=(a056*a292);
  a324=(a173*a353);
  a258=(a047*a258);
  a343=(2.*a330);
  a356=(a182*a343);
  a315=(2.*a315);
  a357=(a181*a315);
  a290=(a171*a290);
  a358=(a046*a352);
  a290=(a290+a358);
  a290=(a180*a290);
  a357=(a357+a290);
  a217=(a171*a217);
  a290=(a040*a352);
  a217=(a217+a290);
  a357=(a357+a217);
  a357=(a179*a357);
  a356=(a356+a357);
  a258=(a258+a356);
  a334=(a175*a334);
  a178=(a043*a178);
  a334=(a334+a178);
  a258=(a258+a334);
  a307=(a171*a307);
  a352=(a037*a352);
  a307=(a307+a352);
  a258=(a258+a307);
  a258=(a013*a258);
  a324=(a324+a258);
  a302=(a302+a324);
  a353=(a176*a353);
  a316=(a031*a316);
  a343=(a184*a343);
  a315=(a183*a315);
  a313=(a172*a313);
  a324=(a030*a354);
  a313=(a313+a324);
  a313=(a180*a313);
  a315=(a315+a313);
  a338=(a172*a338);
  a313=(a023*a354);
  a338=(a338+a313);
  a315=(a315+a338);
  a315=(a179*a315);
  a343=(a343+a315);
  a316=(a316+a343);
  a298=(a177*a298);
  a294=(a026*a294);
  a298=(a298+a294);
  a316=(a316+a298);
  a323=(a172*a323);
  a298=(a017*a354);
  a323=(a323+a298);
  a316=(a316+a323);
  a316=(a013*a316);
  a353=(a353+a316);
  a302=(a302+a353);
  a302=(a018*a302);
  a321=(a321+a302);
  a330=(a172*a330);
  a302=(a020*a354);
  a330=(a330+a302);
  a330=(a016*a330);
  a321=(a321+a330);
  a354=(a001*a354);
  a321=(a321+a354);
  a354=(a161*a321);
  a299=(a299+a354);
  a354=(a058*a299);
  a339=(a339+a354);
  a354=(a072*a312);
  a330=(a048*a055);
  a354=(a354+a330);
  a302=(a188*a354);
  a348=(a056*a348);
  a348=(a348+a341);
  a314=(a011*a314);
  a348=(a348-a314);
  a350=(a148*a350);
  a348=(a348+a350);
  a350=(a149*a312);
  a289=(a048*a289);
  a350=(a350+a289);
  a289=(a160*a312);
  a349=(a048*a349);
  a289=(a289+a349);
  a350=(a350+a289);
  a289=(a004*a350);
  a348=(a348-a289);
  a165=(a165*a327);
  a289=(a168*a312);
  a355=(a048*a355);
  a289=(a289+a355);
  a346=(a289+a346);
  a346=(a189*a346);
  a165=(a165+a346);
  a348=(a348+a165);
  a165=(a189*a321);
  a165=(a174+a165);
  a348=(a348+a165);
  a165=(a187*a348);
  a165=(a302+a165);
  a339=(a339+a165);
  a342=(a148*a342);
  a344=(a056*a344);
  a342=(a342+a344);
  a289=(a289+a240);
  a289=(a193*a289);
  a342=(a342+a289);
  a342=(a342+a351);
  a347=(a011*a347);
  a342=(a342-a347);
  a350=(a007*a350);
  a142=(a142+a350);
  a342=(a342-a142);
  a321=(a193*a321);
  a342=(a342+a321);
  a321=(a191*a342);
  a142=(a008*a312);
  a350=(a048*a292);
  a142=(a142+a350);
  a142=(a192*a142);
  a321=(a321-a142);
  a339=(a339+a321);
  a280=(a163*a280);
  a280=(a195*a280);
  a339=(a339-a280);
  a280=(a062*a055);
  a142=(a072*a311);
  a142=(a280-a142);
  a304=(a197*a304);
  a331=(a014*a331);
  a293=(a019*a293);
  a331=(a331+a293);
  a331=(a052*a331);
  a304=(a304+a331);
  a331=(a011*a304);
  a293=(a142+a331);
  a293=(a194*a293);
  a347=(a012*a311);
  a347=(a201*a347);
  a293=(a293+a347);
  a347=(a081*a311);
  a333=(a333-a347);
  a347=(a004*a304);
  a333=(a333-a347);
  a333=(a202*a333);
  a293=(a293+a333);
  a293=(a195*a293);
  a339=(a339+a293);
  a339=(a339/a002);
  if (res[1]!=0) res[1][9]=a339;
  a339=(a081*a312);
  a339=(a339+a295);
  a295=(a089*a339);
  a293=(a203*a299);
  a293=(a295+a293);
  a333=(a205*a348);
  a347=(a012*a312);
  a347=(a188*a347);
  a333=(a333-a347);
  a293=(a293+a333);
  a354=(a192*a354);
  a347=(a208*a342);
  a347=(a354+a347);
  a293=(a293+a347);
  a340=(a163*a340);
  a340=(a195*a340);
  a293=(a293-a340);
  a142=(a142-a331);
  a142=(a201*a142);
  a292=(a062*a292);
  a331=(a008*a311);
  a292=(a292-a331);
  a292=(a194*a292);
  a142=(a142-a292);
  a311=(a054*a311);
  a304=(a007*a304);
  a304=(a198-a304);
  a311=(a311+a304);
  a311=(a202*a311);
  a142=(a142-a311);
  a142=(a195*a142);
  a293=(a293-a142);
  a293=(a293/a002);
  if (res[1]!=0) res[1][10]=a293;
  a293=(a204*a299);
  a312=(a009*a312);
  a312=(a312+a350);
  a312=(a089*a312);
  a293=(a293-a312);
  a339=(a188*a339);
  a312=(a196*a348);
  a312=(a339+a312);
  a312=(a293+a312);
  a350=(a296-a286);
  a350=(a192*a350);
  a142=(a212*a342);
  a350=(a350+a142);
  a312=(a312+a350);
  a322=(a163*a322);
  a322=(a195*a322);
  a312=(a312-a322);
  a312=(a312/a002);
  if (res[1]!=0) res[1][11]=a312;
  a312=(a123*a092);
  a322=(a133*a312);
  a319=(a018*a319);
  a284=(a078*a284);
  a319=(a319+a284);
  a284=(a124*a319);
  a322=(a322+a284);
  a284=(a110*a322);
  a350=(a123*a129);
  a142=(a141*a350);
  a335=(a018*a335);
  a345=(a078*a345);
  a335=(a335+a345);
  a345=(a118*a335);
  a142=(a142+a345);
  a345=(a110*a142);
  a284=(a284+a345);
  a345=(a093*a284);
  a332=(a332-a345);
  a345=(a141*a326);
  a311=(a069*a335);
  a345=(a345+a311);
  a311=(a148*a345);
  a332=(a332+a311);
  a311=(a133*a326);
  a304=(a069*a319);
  a311=(a311+a304);
  a304=(a110*a311);
  a292=(a153*a350);
  a288=(a018*a288);
  a259=(a078*a259);
  a288=(a288+a259);
  a259=(a118*a288);
  a292=(a292+a259);
  a259=(a110*a292);
  a304=(a304+a259);
  a259=(a091*a304);
  a332=(a332-a259);
  a259=(a153*a312);
  a331=(a124*a288);
  a259=(a259+a331);
  a331=(a056*a259);
  a332=(a332+a331);
  a331=(a141*a312);
  a335=(a124*a335);
  a331=(a331+a335);
  a335=(a110*a331);
  a340=(a153*a326);
  a288=(a069*a288);
  a340=(a340+a288);
  a288=(a110*a340);
  a347=(a335+a288);
  a347=(a223*a347);
  a332=(a332+a347);
  a347=(a133*a350);
  a319=(a118*a319);
  a347=(a347+a319);
  a319=(a095*a347);
  a351=(a128*a322);
  a319=(a319-a351);
  a351=(a117*a311);
  a319=(a319-a351);
  a351=(a128*a142);
  a319=(a319-a351);
  a331=(a097*a331);
  a319=(a319+a331);
  a331=(a125*a345);
  a319=(a319-a331);
  a331=(a117*a292);
  a319=(a319-a331);
  a331=(a125*a259);
  a319=(a319-a331);
  a340=(a094*a340);
  a319=(a319+a340);
  a340=(a229*a319);
  a340=(a049*a340);
  a331=(a101*a340);
  a319=(a319/a099);
  a331=(a331-a319);
  a351=(a107*a331);
  a289=(a045*a351);
  a240=(a105*a331);
  a344=(a102*a240);
  a344=(a042*a344);
  a289=(a289+a344);
  a344=(a039*a240);
  a289=(a289+a344);
  a344=(a102*a331);
  a344=(a036*a344);
  a289=(a289+a344);
  a344=(a033*a331);
  a289=(a289+a344);
  a344=(a107*a319);
  a165=(a029*a344);
  a289=(a289+a165);
  a165=(a105*a319);
  a346=(a102*a165);
  a346=(a025*a346);
  a289=(a289+a346);
  a346=(a022*a165);
  a289=(a289+a346);
  a340=(a108*a340);
  a351=(a047*a351);
  a346=(a106*a331);
  a346=(a242*a346);
  a355=(a103*a331);
  a346=(a346+a355);
  a346=(a241*a346);
  a351=(a351+a346);
  a240=(a104*a240);
  a351=(a351+a240);
  a331=(a100*a331);
  a351=(a351+a331);
  a351=(a098*a351);
  a340=(a340+a351);
  a344=(a031*a344);
  a351=(a114*a319);
  a351=(a242*a351);
  a331=(a112*a319);
  a351=(a351+a331);
  a351=(a241*a351);
  a344=(a344+a351);
  a165=(a113*a165);
  a344=(a344+a165);
  a165=(a111*a319);
  a344=(a344+a165);
  a344=(a098*a344);
  a340=(a340+a344);
  a340=(a018*a340);
  a289=(a289+a340);
  a340=(a102*a319);
  a340=(a016*a340);
  a289=(a289+a340);
  a319=(a001*a319);
  a289=(a289+a319);
  a319=(a223*a289);
  a332=(a332+a319);
  a319=(a219*a332);
  a326=(a163*a326);
  a326=(a195*a326);
  a319=(a319-a326);
  a311=(a056*a311);
  a190=(a190+a311);
  a284=(a096*a284);
  a190=(a190-a284);
  a292=(a148*a292);
  a190=(a190+a292);
  a345=(a110*a345);
  a259=(a110*a259);
  a345=(a345+a259);
  a259=(a091*a345);
  a190=(a190-a259);
  a347=(a110*a347);
  a288=(a347+a288);
  a288=(a250*a288);
  a190=(a190+a288);
  a288=(a250*a289);
  a190=(a190+a288);
  a288=(a248*a190);
  a319=(a319+a288);
  a322=(a148*a322);
  a329=(a329+a322);
  a142=(a056*a142);
  a329=(a329+a142);
  a347=(a347+a335);
  a347=(a253*a347);
  a329=(a329+a347);
  a304=(a096*a304);
  a329=(a329-a304);
  a345=(a093*a345);
  a329=(a329-a345);
  a289=(a253*a289);
  a329=(a329+a289);
  a289=(a252*a329);
  a319=(a319+a289);
  a319=(a319/a002);
  if (res[1]!=0) res[1][12]=a319;
  a319=(a255*a332);
  a312=(a163*a312);
  a312=(a195*a312);
  a319=(a319-a312);
  a312=(a257*a190);
  a319=(a319+a312);
  a345=(a210*a329);
  a319=(a319+a345);
  a319=(a319/a002);
  if (res[1]!=0) res[1][13]=a319;
  a319=(a256*a332);
  a350=(a163*a350);
  a350=(a195*a350);
  a350=(a319-a350);
  a345=(a262*a190);
  a350=(a350+a345);
  a345=(a264*a329);
  a350=(a350+a345);
  a350=(a350/a002);
  if (res[1]!=0) res[1][14]=a350;
  a350=(2.*a265);
  a345=(a350*a291);
  a304=(a001*a345);
  a347=(a016*a345);
  a347=(a276*a347);
  a335=(a018*a345);
  a142=(a273*a335);
  a322=(a015*a142);
  a347=(a347+a322);
  a304=(a304+a347);
  a347=(a022*a345);
  a322=(a025*a345);
  a322=(a276*a322);
  a288=(a024*a142);
  a322=(a322+a288);
  a347=(a347+a322);
  a347=(a277*a347);
  a322=(a317*a142);
  a288=(a021*a322);
  a347=(a347+a288);
  a304=(a304+a347);
  a347=(a029*a345);
  a288=(a031*a142);
  a347=(a347+a288);
  a347=(a278*a347);
  a288=(a325*a322);
  a259=(a028*a288);
  a347=(a347+a259);
  a304=(a304+a347);
  a347=(a033*a345);
  a259=(a036*a345);
  a259=(a276*a259);
  a292=(a035*a142);
  a259=(a259+a292);
  a347=(a347+a259);
  a259=(a039*a345);
  a292=(a042*a345);
  a292=(a276*a292);
  a284=(a041*a142);
  a292=(a292+a284);
  a259=(a259+a292);
  a259=(a277*a259);
  a322=(a038*a322);
  a259=(a259+a322);
  a347=(a347+a259);
  a259=(a045*a345);
  a142=(a047*a142);
  a259=(a259+a142);
  a259=(a278*a259);
  a288=(a044*a288);
  a259=(a259+a288);
  a347=(a347+a259);
  a304=(a304-a347);
  a304=(a304/a279);
  a335=(a051*a335);
  a347=(a275*a347);
  a335=(a335+a347);
  a335=(a049*a335);
  a335=(a297*a335);
  a304=(a304+a335);
  a335=(a274*a304);
  a347=(a336+a335);
  a347=(a088*a347);
  a259=(a283*a304);
  a288=(a267*a291);
  a288=(a000*a288);
  a259=(a259+a288);
  a142=(a140*a259);
  a347=(a347+a142);
  a142=(a269*a304);
  a345=(a000*a345);
  a142=(a142+a345);
  a142=(a152*a142);
  a347=(a347-a142);
  a142=(a218*a332);
  a347=(a347+a142);
  a142=(a247*a190);
  a347=(a347+a142);
  a347=(a347+a289);
  a289=(a195+a296);
  a289=(a089*a289);
  a142=(a057*a299);
  a289=(a289+a142);
  a347=(a347+a289);
  a289=(a186*a348);
  a302=(a302+a289);
  a347=(a347+a302);
  a347=(a347+a321);
  a347=(-a347);
  if (res[1]!=0) res[1][15]=a347;
  a347=(a154*a304);
  a347=(a347+a310);
  a310=(a088*a347);
  a321=(a272*a304);
  a321=(a140*a321);
  a310=(a310-a321);
  a259=(a152*a259);
  a310=(a310+a259);
  a332=(a254*a332);
  a310=(a310+a332);
  a310=(a310+a312);
  a312=(a215*a329);
  a310=(a310+a312);
  a299=(a200*a299);
  a295=(a295+a299);
  a310=(a310+a295);
  a310=(a310+a333);
  a333=(a207*a342);
  a354=(a354+a333);
  a310=(a310+a354);
  a310=(-a310);
  if (res[1]!=0) res[1][16]=a310;
  a347=(a140*a347);
  a304=(a270*a304);
  a304=(a304+a345);
  a304=(a088*a304);
  a347=(a347-a304);
  a335=(a301+a335);
  a335=(a152*a335);
  a347=(a347+a335);
  a347=(a347+a319);
  a190=(a261*a190);
  a347=(a347+a190);
  a329=(a263*a329);
  a347=(a347+a329);
  a347=(a347+a293);
  a348=(a199*a348);
  a339=(a339+a348);
  a347=(a347+a339);
  a296=(a286+a296);
  a296=(a192*a296);
  a342=(a211*a342);
  a296=(a296+a342);
  a347=(a347+a296);
  a347=(-a347);
  if (res[1]!=0) res[1][17]=a347;
  a347=(a161*a002);
  a296=(a001*a347);
  a342=(a016*a347);
  a339=(a020*a342);
  a348=(a018*a347);
  a293=(a013*a348);
  a329=(a017*a293);
  a339=(a339+a329);
  a296=(a296+a339);
  a339=(a022*a347);
  a329=(a025*a347);
  a190=(a020*a329);
  a319=(a026*a293);
  a190=(a190+a319);
  a339=(a339+a190);
  a190=(a027*a339);
  a319=(a179*a293);
  a335=(a023*a319);
  a190=(a190+a335);
  a296=(a296+a190);
  a190=(a029*a347);
  a335=(a031*a293);
  a190=(a190+a335);
  a335=(a032*a190);
  a304=(a180*a319);
  a345=(a030*a304);
  a335=(a335+a345);
  a296=(a296+a335);
  a335=(a033*a347);
  a345=(a036*a347);
  a310=(a020*a345);
  a354=(a037*a293);
  a310=(a310+a354);
  a335=(a335+a310);
  a310=(a039*a347);
  a354=(a042*a347);
  a333=(a020*a354);
  a295=(a043*a293);
  a333=(a333+a295);
  a310=(a310+a333);
  a333=(a027*a310);
  a295=(a040*a319);
  a333=(a333+a295);
  a335=(a335+a333);
  a333=(a045*a347);
  a295=(a047*a293);
  a333=(a333+a295);
  a295=(a032*a333);
  a299=(a046*a304);
  a295=(a295+a299);
  a335=(a335+a295);
  a295=(a296-a335);
  a295=(a295/a053);
  a299=(a034*a348);
  a312=(a019*a335);
  a299=(a299+a312);
  a312=(a049*a299);
  a332=(a167*a312);
  a295=(a295+a332);
  a332=(a054*a295);
  a332=(a332+a330);
  a330=(a089*a332);
  a259=(a052*a296);
  a321=(a014*a299);
  a259=(a259-a321);
  a259=(a335+a259);
  a259=(a018*a259);
  a321=(a054*a259);
  a321=(a321+a216);
  a300=(a300*a299);
  a300=(a056*a300);
  a216=(a007*a300);
  a302=(a321+a216);
  a289=(a070*a302);
  a142=(a011*a300);
  a303=(a303-a142);
  a142=(a072*a259);
  a322=(a303+a142);
  a292=(a075*a322);
  a284=(a008*a259);
  a060=(a060*a347);
  a284=(a284+a060);
  a311=(a067*a284);
  a292=(a292-a311);
  a302=(a077*a302);
  a311=(a066*a064);
  a302=(a302+a311);
  a292=(a292+a302);
  a302=(a064*a292);
  a289=(a289+a302);
  a302=(a081*a259);
  a302=(a302+a309);
  a309=(a004*a300);
  a311=(a302-a309);
  a326=(a085*a311);
  a142=(a142-a303);
  a303=(a067*a142);
  a340=(a012*a259);
  a340=(a340+a060);
  a060=(a075*a340);
  a303=(a303-a060);
  a311=(a077*a311);
  a060=(a066*a083);
  a311=(a311+a060);
  a303=(a303+a311);
  a311=(a084*a303);
  a060=(a083*a311);
  a326=(a326+a060);
  a289=(a289+a326);
  a321=(a321-a216);
  a067=(a067*a321);
  a302=(a302+a309);
  a075=(a075*a302);
  a067=(a067+a075);
  a075=(a066*a086);
  a259=(a009*a259);
  a077=(a077*a259);
  a075=(a075-a077);
  a067=(a067+a075);
  a075=(a087*a067);
  a077=(a086*a075);
  a259=(a080*a259);
  a077=(a077-a259);
  a289=(a289+a077);
  a077=(a059*a289);
  a259=(a123*a121);
  a309=(a121*a259);
  a318=(a318*a130);
  a216=(a130*a318);
  a309=(a309+a216);
  a320=(a320*a132);
  a216=(a132*a320);
  a309=(a309+a216);
  a216=(a090*a309);
  a077=(a077+a216);
  a216=(a138*a295);
  a326=(a136*a303);
  a289=(a135*a289);
  a309=(a059*a309);
  a289=(a289+a309);
  a309=(a002*a289);
  a060=(a134*a309);
  a344=(a002*a077);
  a165=(a018*a344);
  a060=(a060+a165);
  a165=(a071*a060);
  a326=(a326+a165);
  a165=(a048*a326);
  a216=(a216+a165);
  a165=(a147*a295);
  a351=(a146*a067);
  a322=(a070*a322);
  a331=(a074*a292);
  a322=(a322+a331);
  a331=(a005*a311);
  a340=(a085*a340);
  a331=(a331-a340);
  a322=(a322+a331);
  a302=(a080*a302);
  a331=(a082*a075);
  a302=(a302+a331);
  a322=(a322+a302);
  a302=(a135*a322);
  a331=(a127*a259);
  a340=(a092*a318);
  a331=(a331+a340);
  a340=(a129*a320);
  a331=(a331+a340);
  a340=(a059*a331);
  a302=(a302+a340);
  a340=(a002*a302);
  a240=(a134*a340);
  a322=(a059*a322);
  a331=(a090*a331);
  a322=(a322+a331);
  a331=(a002*a322);
  a346=(a018*a331);
  a240=(a240+a346);
  a346=(a061*a240);
  a351=(a351+a346);
  a346=(a048*a351);
  a165=(a165+a346);
  a216=(a216+a165);
  a165=(a007*a216);
  a077=(a077-a165);
  a165=(a146*a292);
  a346=(a070*a240);
  a165=(a165+a346);
  a346=(a148*a165);
  a077=(a077+a346);
  a346=(a150*a295);
  a355=(a136*a292);
  a349=(a070*a060);
  a355=(a355+a349);
  a349=(a048*a355);
  a346=(a346+a349);
  a349=(a159*a295);
  a314=(a158*a067);
  a341=(a065*a292);
  a284=(a070*a284);
  a341=(a341-a284);
  a085=(a085*a142);
  a311=(a073*a311);
  a085=(a085+a311);
  a341=(a341+a085);
  a080=(a080*a321);
  a075=(a063*a075);
  a080=(a080+a075);
  a341=(a341+a080);
  a080=(a135*a341);
  a075=(a122*a259);
  a318=(a126*a318);
  a075=(a075+a318);
  a320=(a120*a320);
  a075=(a075+a320);
  a320=(a059*a075);
  a080=(a080+a320);
  a320=(a002*a080);
  a318=(a134*a320);
  a341=(a059*a341);
  a075=(a090*a075);
  a341=(a341+a075);
  a075=(a002*a341);
  a321=(a018*a075);
  a318=(a318+a321);
  a321=(a061*a318);
  a314=(a314+a321);
  a321=(a048*a314);
  a349=(a349+a321);
  a346=(a346+a349);
  a349=(a004*a346);
  a077=(a077-a349);
  a349=(a158*a303);
  a321=(a071*a318);
  a349=(a349+a321);
  a321=(a056*a349);
  a077=(a077+a321);
  a166=(a166*a327);
  a321=(a162*a295);
  a085=(a146*a303);
  a240=(a071*a240);
  a085=(a085+a240);
  a240=(a048*a085);
  a321=(a321+a240);
  a240=(a164*a295);
  a311=(a158*a292);
  a318=(a070*a318);
  a311=(a311+a318);
  a318=(a048*a311);
  a240=(a240+a318);
  a318=(a321+a240);
  a318=(a161*a318);
  a166=(a166+a318);
  a077=(a077+a166);
  a166=(a171*a304);
  a318=(a170*a348);
  a142=(a295/a053);
  a337=(a337*a312);
  a142=(a142+a337);
  a169=(a169*a142);
  a142=(a136*a067);
  a060=(a061*a060);
  a142=(a142+a060);
  a060=(a009*a142);
  a138=(a138*a308);
  a337=(a081*a326);
  a138=(a138+a337);
  a060=(a060-a138);
  a150=(a150*a055);
  a138=(a054*a355);
  a150=(a150+a138);
  a060=(a060-a150);
  a147=(a147*a308);
  a308=(a081*a351);
  a147=(a147+a308);
  a060=(a060-a147);
  a162=(a162*a347);
  a085=(a012*a085);
  a162=(a162+a085);
  a060=(a060+a162);
  a162=(a072*a165);
  a060=(a060-a162);
  a159=(a159*a055);
  a055=(a054*a314);
  a159=(a159+a055);
  a060=(a060-a159);
  a159=(a072*a349);
  a060=(a060-a159);
  a164=(a164*a347);
  a311=(a008*a311);
  a164=(a164+a311);
  a060=(a060+a164);
  a164=(a167*a060);
  a169=(a169+a164);
  a169=(a049*a169);
  a164=(a019*a169);
  a318=(a318+a164);
  a060=(a060/a053);
  a306=(a306*a312);
  a060=(a060+a306);
  a318=(a318-a060);
  a306=(a032*a318);
  a166=(a166+a306);
  a306=(a045*a166);
  a312=(a175*a293);
  a164=(a171*a319);
  a311=(a027*a318);
  a164=(a164+a311);
  a311=(a020*a164);
  a312=(a312+a311);
  a312=(a042*a312);
  a306=(a306+a312);
  a312=(a039*a164);
  a306=(a306+a312);
  a312=(a171*a293);
  a311=(a020*a318);
  a312=(a312+a311);
  a312=(a036*a312);
  a306=(a306+a312);
  a312=(a033*a318);
  a306=(a306+a312);
  a304=(a172*a304);
  a312=(a032*a060);
  a304=(a304+a312);
  a312=(a029*a304);
  a306=(a306+a312);
  a312=(a177*a293);
  a311=(a172*a319);
  a159=(a027*a060);
  a311=(a311+a159);
  a159=(a020*a311);
  a312=(a312+a159);
  a312=(a025*a312);
  a306=(a306+a312);
  a312=(a022*a311);
  a306=(a306+a312);
  a170=(a170*a335);
  a169=(a034*a169);
  a170=(a170+a169);
  a169=(a056*a347);
  a173=(a173*a169);
  a166=(a047*a166);
  a335=(2.*a293);
  a182=(a182*a335);
  a319=(2.*a319);
  a181=(a181*a319);
  a333=(a171*a333);
  a312=(a046*a318);
  a333=(a333+a312);
  a333=(a180*a333);
  a181=(a181+a333);
  a310=(a171*a310);
  a333=(a040*a318);
  a310=(a310+a333);
  a181=(a181+a310);
  a181=(a179*a181);
  a182=(a182+a181);
  a166=(a166+a182);
  a175=(a175*a354);
  a164=(a043*a164);
  a175=(a175+a164);
  a166=(a166+a175);
  a171=(a171*a345);
  a318=(a037*a318);
  a171=(a171+a318);
  a166=(a166+a171);
  a166=(a013*a166);
  a173=(a173+a166);
  a170=(a170+a173);
  a176=(a176*a169);
  a304=(a031*a304);
  a184=(a184*a335);
  a183=(a183*a319);
  a190=(a172*a190);
  a319=(a030*a060);
  a190=(a190+a319);
  a190=(a180*a190);
  a183=(a183+a190);
  a339=(a172*a339);
  a190=(a023*a060);
  a339=(a339+a190);
  a183=(a183+a339);
  a183=(a179*a183);
  a184=(a184+a183);
  a304=(a304+a184);
  a177=(a177*a329);
  a311=(a026*a311);
  a177=(a177+a311);
  a304=(a304+a177);
  a342=(a172*a342);
  a177=(a017*a060);
  a342=(a342+a177);
  a304=(a304+a342);
  a304=(a013*a304);
  a176=(a176+a304);
  a170=(a170+a176);
  a170=(a018*a170);
  a306=(a306+a170);
  a172=(a172*a293);
  a293=(a020*a060);
  a172=(a172+a293);
  a172=(a016*a172);
  a306=(a306+a172);
  a060=(a001*a060);
  a306=(a306+a060);
  a060=(a161*a306);
  a174=(a174+a060);
  a077=(a077+a174);
  a174=(a058*a077);
  a174=(a330+a174);
  a060=(a072*a295);
  a172=(a060-a286);
  a172=(a188*a172);
  a355=(a056*a355);
  a355=(a355+a322);
  a216=(a011*a216);
  a139=(a139+a216);
  a355=(a355-a139);
  a314=(a148*a314);
  a355=(a355+a314);
  a149=(a149*a295);
  a165=(a048*a165);
  a149=(a149+a165);
  a160=(a160*a295);
  a349=(a048*a349);
  a160=(a160+a349);
  a149=(a149+a160);
  a160=(a004*a149);
  a355=(a355-a160);
  a168=(a168*a295);
  a142=(a048*a142);
  a168=(a168+a142);
  a240=(a168+a240);
  a240=(a189*a240);
  a355=(a355+a240);
  a240=(a189*a306);
  a355=(a355+a240);
  a240=(a187*a355);
  a172=(a172+a240);
  a174=(a174+a172);
  a326=(a148*a326);
  a351=(a056*a351);
  a326=(a326+a351);
  a168=(a168+a321);
  a168=(a193*a168);
  a326=(a326+a168);
  a326=(a326+a341);
  a346=(a011*a346);
  a151=(a151+a346);
  a326=(a326-a151);
  a149=(a007*a149);
  a326=(a326-a149);
  a306=(a193*a306);
  a326=(a326+a306);
  a306=(a191*a326);
  a149=(a008*a295);
  a151=(a048*a347);
  a149=(a149+a151);
  a149=(a192*a149);
  a306=(a306-a149);
  a174=(a174+a306);
  a292=(a163*a292);
  a292=(a195*a292);
  a174=(a174-a292);
  a292=(a081*a300);
  a305=(a305-a292);
  a197=(a197*a299);
  a014=(a014*a348);
  a296=(a019*a296);
  a014=(a014+a296);
  a052=(a052*a014);
  a197=(a197+a052);
  a052=(a004*a197);
  a305=(a305-a052);
  a305=(a202*a305);
  a052=(a072*a300);
  a014=(a011*a197);
  a198=(a198-a014);
  a014=(a052+a198);
  a014=(a194*a014);
  a062=(a062*a347);
  a347=(a012*a300);
  a347=(a062-a347);
  a347=(a201*a347);
  a014=(a014+a347);
  a305=(a305-a014);
  a305=(a195*a305);
  a174=(a174+a305);
  a174=(a174/a002);
  if (res[1]!=0) res[1][18]=a174;
  a174=(a081*a295);
  a174=(a174+a206);
  a206=(a089*a174);
  a305=(a203*a077);
  a305=(a206+a305);
  a014=(a205*a355);
  a347=(a012*a295);
  a347=(a347+a151);
  a347=(a188*a347);
  a014=(a014-a347);
  a305=(a305+a014);
  a347=(a060-a195);
  a347=(a192*a347);
  a151=(a208*a326);
  a347=(a347+a151);
  a305=(a305+a347);
  a303=(a163*a303);
  a303=(a195*a303);
  a305=(a305-a303);
  a198=(a198-a052);
  a198=(a201*a198);
  a052=(a008*a300);
  a062=(a062-a052);
  a062=(a194*a062);
  a198=(a198-a062);
  a300=(a054*a300);
  a280=(a280-a300);
  a197=(a007*a197);
  a280=(a280+a197);
  a280=(a202*a280);
  a198=(a198+a280);
  a198=(a195*a198);
  a305=(a305-a198);
  a305=(a305/a002);
  if (res[1]!=0) res[1][19]=a305;
  a305=(a204*a077);
  a295=(a009*a295);
  a089=(a089*a295);
  a305=(a305-a089);
  a174=(a188*a174);
  a089=(a196*a355);
  a089=(a174+a089);
  a089=(a305+a089);
  a332=(a192*a332);
  a295=(a212*a326);
  a295=(a332+a295);
  a089=(a089+a295);
  a067=(a163*a067);
  a067=(a195*a067);
  a089=(a089-a067);
  a089=(a089/a002);
  if (res[1]!=0) res[1][20]=a089;
  a089=(a123*a130);
  a067=(a133*a089);
  a309=(a018*a309);
  a344=(a078*a344);
  a309=(a309+a344);
  a344=(a124*a309);
  a067=(a067+a344);
  a344=(a110*a067);
  a123=(a123*a132);
  a295=(a141*a123);
  a340=(a018*a340);
  a331=(a078*a331);
  a340=(a340+a331);
  a331=(a118*a340);
  a295=(a295+a331);
  a331=(a110*a295);
  a344=(a344+a331);
  a331=(a093*a344);
  a289=(a289-a331);
  a331=(a141*a259);
  a198=(a069*a340);
  a331=(a331+a198);
  a198=(a148*a331);
  a289=(a289+a198);
  a198=(a133*a259);
  a280=(a069*a309);
  a198=(a198+a280);
  a280=(a110*a198);
  a197=(a153*a123);
  a320=(a018*a320);
  a075=(a078*a075);
  a320=(a320+a075);
  a075=(a118*a320);
  a197=(a197+a075);
  a075=(a110*a197);
  a280=(a280+a075);
  a075=(a091*a280);
  a289=(a289-a075);
  a075=(a153*a089);
  a300=(a124*a320);
  a075=(a075+a300);
  a300=(a056*a075);
  a289=(a289+a300);
  a300=(a141*a089);
  a340=(a124*a340);
  a300=(a300+a340);
  a340=(a110*a300);
  a062=(a153*a259);
  a320=(a069*a320);
  a062=(a062+a320);
  a320=(a110*a062);
  a052=(a340+a320);
  a052=(a223*a052);
  a289=(a289+a052);
  a052=(a133*a123);
  a309=(a118*a309);
  a052=(a052+a309);
  a309=(a095*a052);
  a303=(a128*a067);
  a309=(a309-a303);
  a303=(a117*a198);
  a309=(a309-a303);
  a303=(a128*a295);
  a309=(a309-a303);
  a300=(a097*a300);
  a309=(a309+a300);
  a300=(a125*a331);
  a309=(a309-a300);
  a300=(a117*a197);
  a309=(a309-a300);
  a300=(a125*a075);
  a309=(a309-a300);
  a062=(a094*a062);
  a309=(a309+a062);
  a062=(a229*a309);
  a062=(a049*a062);
  a300=(a101*a062);
  a309=(a309/a099);
  a300=(a300-a309);
  a303=(a107*a300);
  a347=(a045*a303);
  a151=(a105*a300);
  a296=(a102*a151);
  a296=(a042*a296);
  a347=(a347+a296);
  a296=(a039*a151);
  a347=(a347+a296);
  a296=(a102*a300);
  a296=(a036*a296);
  a347=(a347+a296);
  a296=(a033*a300);
  a347=(a347+a296);
  a296=(a107*a309);
  a348=(a029*a296);
  a347=(a347+a348);
  a348=(a105*a309);
  a299=(a102*a348);
  a299=(a025*a299);
  a347=(a347+a299);
  a299=(a022*a348);
  a347=(a347+a299);
  a062=(a108*a062);
  a303=(a047*a303);
  a299=(a106*a300);
  a299=(a242*a299);
  a292=(a103*a300);
  a299=(a299+a292);
  a299=(a241*a299);
  a303=(a303+a299);
  a151=(a104*a151);
  a303=(a303+a151);
  a300=(a100*a300);
  a303=(a303+a300);
  a303=(a098*a303);
  a062=(a062+a303);
  a296=(a031*a296);
  a303=(a114*a309);
  a303=(a242*a303);
  a300=(a112*a309);
  a303=(a303+a300);
  a303=(a241*a303);
  a296=(a296+a303);
  a348=(a113*a348);
  a296=(a296+a348);
  a348=(a111*a309);
  a296=(a296+a348);
  a296=(a098*a296);
  a062=(a062+a296);
  a062=(a018*a062);
  a347=(a347+a062);
  a062=(a102*a309);
  a062=(a016*a062);
  a347=(a347+a062);
  a309=(a001*a309);
  a347=(a347+a309);
  a309=(a223*a347);
  a289=(a289+a309);
  a309=(a219*a289);
  a259=(a163*a259);
  a259=(a195*a259);
  a309=(a309-a259);
  a198=(a056*a198);
  a302=(a302+a198);
  a344=(a096*a344);
  a302=(a302-a344);
  a197=(a148*a197);
  a302=(a302+a197);
  a331=(a110*a331);
  a075=(a110*a075);
  a331=(a331+a075);
  a075=(a091*a331);
  a302=(a302-a075);
  a052=(a110*a052);
  a320=(a052+a320);
  a320=(a250*a320);
  a302=(a302+a320);
  a320=(a250*a347);
  a302=(a302+a320);
  a320=(a248*a302);
  a309=(a309+a320);
  a067=(a148*a067);
  a080=(a080+a067);
  a295=(a056*a295);
  a080=(a080+a295);
  a052=(a052+a340);
  a052=(a253*a052);
  a080=(a080+a052);
  a280=(a096*a280);
  a080=(a080-a280);
  a331=(a093*a331);
  a080=(a080-a331);
  a347=(a253*a347);
  a080=(a080+a347);
  a347=(a252*a080);
  a309=(a309+a347);
  a309=(a309/a002);
  if (res[1]!=0) res[1][21]=a309;
  a309=(a255*a289);
  a089=(a163*a089);
  a089=(a195*a089);
  a309=(a309-a089);
  a089=(a257*a302);
  a309=(a309+a089);
  a331=(a210*a080);
  a309=(a309+a331);
  a309=(a309/a002);
  if (res[1]!=0) res[1][22]=a309;
  a309=(a256*a289);
  a123=(a163*a123);
  a123=(a195*a123);
  a123=(a309-a123);
  a331=(a262*a302);
  a123=(a123+a331);
  a331=(a264*a080);
  a123=(a123+a331);
  a123=(a123/a002);
  if (res[1]!=0) res[1][23]=a123;
  a123=(2.*a271);
  a291=(a123*a291);
  a331=(a001*a291);
  a280=(a016*a291);
  a280=(a276*a280);
  a052=(a018*a291);
  a340=(a273*a052);
  a295=(a015*a340);
  a280=(a280+a295);
  a331=(a331+a280);
  a280=(a022*a291);
  a295=(a025*a291);
  a295=(a276*a295);
  a067=(a024*a340);
  a295=(a295+a067);
  a280=(a280+a295);
  a280=(a277*a280);
  a295=(a317*a340);
  a067=(a021*a295);
  a280=(a280+a067);
  a331=(a331+a280);
  a280=(a029*a291);
  a067=(a031*a340);
  a280=(a280+a067);
  a280=(a278*a280);
  a067=(a325*a295);
  a320=(a028*a067);
  a280=(a280+a320);
  a331=(a331+a280);
  a280=(a033*a291);
  a320=(a036*a291);
  a320=(a276*a320);
  a075=(a035*a340);
  a320=(a320+a075);
  a280=(a280+a320);
  a320=(a039*a291);
  a075=(a042*a291);
  a075=(a276*a075);
  a197=(a041*a340);
  a075=(a075+a197);
  a320=(a320+a075);
  a320=(a277*a320);
  a295=(a038*a295);
  a320=(a320+a295);
  a280=(a280+a320);
  a320=(a045*a291);
  a340=(a047*a340);
  a320=(a320+a340);
  a320=(a278*a320);
  a067=(a044*a067);
  a320=(a320+a067);
  a280=(a280+a320);
  a331=(a331-a280);
  a331=(a331/a279);
  a052=(a051*a052);
  a280=(a275*a280);
  a052=(a052+a280);
  a052=(a049*a052);
  a052=(a297*a052);
  a331=(a331+a052);
  a052=(a274*a331);
  a052=(a052+a288);
  a288=(a088*a052);
  a280=(a283*a331);
  a320=(a301+a280);
  a320=(a140*a320);
  a288=(a288+a320);
  a320=(a269*a331);
  a291=(a000*a291);
  a320=(a320+a291);
  a320=(a152*a320);
  a288=(a288-a320);
  a320=(a218*a289);
  a288=(a288+a320);
  a320=(a247*a302);
  a288=(a288+a320);
  a288=(a288+a347);
  a347=(a057*a077);
  a330=(a330+a347);
  a288=(a288+a330);
  a330=(a286+a060);
  a188=(a188*a330);
  a330=(a186*a355);
  a188=(a188+a330);
  a288=(a288+a188);
  a288=(a288+a306);
  a288=(-a288);
  if (res[1]!=0) res[1][24]=a288;
  a288=(a154*a331);
  a288=(a288+a209);
  a209=(a088*a288);
  a306=(a272*a331);
  a306=(a306+a291);
  a306=(a140*a306);
  a209=(a209-a306);
  a280=(a336+a280);
  a280=(a152*a280);
  a209=(a209+a280);
  a289=(a254*a289);
  a209=(a209+a289);
  a209=(a209+a089);
  a089=(a215*a080);
  a209=(a209+a089);
  a077=(a200*a077);
  a206=(a206+a077);
  a209=(a209+a206);
  a209=(a209+a014);
  a060=(a195+a060);
  a192=(a192*a060);
  a060=(a207*a326);
  a192=(a192+a060);
  a209=(a209+a192);
  a209=(-a209);
  if (res[1]!=0) res[1][25]=a209;
  a288=(a140*a288);
  a331=(a270*a331);
  a331=(a088*a331);
  a288=(a288-a331);
  a052=(a152*a052);
  a288=(a288+a052);
  a288=(a288+a309);
  a302=(a261*a302);
  a288=(a288+a302);
  a080=(a263*a080);
  a288=(a288+a080);
  a288=(a288+a305);
  a355=(a199*a355);
  a174=(a174+a355);
  a288=(a288+a174);
  a326=(a211*a326);
  a332=(a332+a326);
  a288=(a288+a332);
  a288=(-a288);
  if (res[1]!=0) res[1][26]=a288;
  a288=(a068*a065);
  a332=(a064*a288);
  a326=2.3205080756887719e+00;
  a174=(a326*a073);
  a355=(a083*a174);
  a332=(a332+a355);
  a355=2.7846096908265263e+00;
  a305=(a355*a063);
  a080=(a086*a305);
  a332=(a332+a080);
  a080=(a059*a332);
  a302=(a253*a002);
  a309=(a033*a302);
  a052=(a036*a302);
  a331=(a102*a052);
  a209=(a018*a302);
  a192=(a098*a209);
  a060=(a100*a192);
  a331=(a331+a060);
  a309=(a309+a331);
  a331=(a039*a302);
  a060=(a042*a302);
  a014=(a102*a060);
  a206=(a104*a192);
  a014=(a014+a206);
  a331=(a331+a014);
  a014=(a105*a331);
  a206=(a241*a192);
  a077=(a103*a206);
  a014=(a014+a077);
  a309=(a309+a014);
  a014=(a045*a302);
  a077=(a047*a192);
  a014=(a014+a077);
  a077=(a107*a014);
  a089=(a242*a206);
  a289=(a106*a089);
  a077=(a077+a289);
  a309=(a309+a077);
  a077=(a001*a302);
  a289=(a016*a302);
  a280=(a102*a289);
  a306=(a111*a192);
  a280=(a280+a306);
  a077=(a077+a280);
  a280=(a022*a302);
  a306=(a025*a302);
  a291=(a102*a306);
  a188=(a113*a192);
  a291=(a291+a188);
  a280=(a280+a291);
  a291=(a105*a280);
  a188=(a112*a206);
  a291=(a291+a188);
  a077=(a077+a291);
  a291=(a029*a302);
  a188=(a031*a192);
  a291=(a291+a188);
  a188=(a107*a291);
  a330=(a114*a089);
  a188=(a188+a330);
  a077=(a077+a188);
  a188=(a109*a077);
  a330=(a108*a209);
  a347=(a101*a309);
  a330=(a330+a347);
  a347=(a115*a330);
  a188=(a188-a347);
  a188=(a309+a188);
  a188=(a018*a188);
  a347=(a117*a188);
  a320=(a096*a002);
  a067=(a116*a320);
  a347=(a347+a067);
  a340=(2.*a109);
  a295=(a340*a330);
  a295=(a056*a295);
  a075=(a093*a295);
  a197=(a347+a075);
  a344=(a069*a197);
  a198=(a066*a122);
  a259=(a094*a188);
  a062=(a003*a259);
  a198=(a198-a062);
  a062=(a125*a188);
  a296=(a093*a002);
  a348=(a116*a296);
  a062=(a062+a348);
  a303=(a096*a295);
  a300=(a062-a303);
  a151=(a006*a300);
  a198=(a198+a151);
  a197=(a010*a197);
  a198=(a198+a197);
  a197=(a121*a198);
  a344=(a344+a197);
  a197=(a119*a002);
  a151=(a091*a295);
  a151=(a197-a151);
  a299=(a128*a188);
  a292=(a151+a299);
  a149=(a131*a292);
  a062=(a062+a303);
  a303=(a003*a062);
  a346=(a066*a126);
  a303=(a303+a346);
  a346=(a097*a188);
  a341=(a116*a302);
  a346=(a346+a341);
  a168=(a006*a346);
  a303=(a303-a168);
  a292=(a010*a292);
  a303=(a303+a292);
  a292=(a084*a303);
  a168=(a130*a292);
  a149=(a149+a168);
  a344=(a344+a149);
  a347=(a347-a075);
  a075=(a003*a347);
  a149=(a066*a120);
  a075=(a075+a149);
  a299=(a299-a151);
  a151=(a006*a299);
  a075=(a075+a151);
  a188=(a095*a188);
  a188=(a188+a341);
  a341=(a010*a188);
  a075=(a075-a341);
  a341=(a087*a075);
  a151=(a132*a341);
  a188=(a076*a188);
  a151=(a151-a188);
  a344=(a344+a151);
  a151=(a090*a344);
  a080=(a080+a151);
  a151=(a068*a073);
  a188=(a136*a151);
  a332=(a135*a332);
  a344=(a059*a344);
  a332=(a332+a344);
  a344=(a002*a332);
  a149=(a134*a344);
  a168=(a002*a080);
  a321=(a018*a168);
  a149=(a149+a321);
  a321=(a071*a149);
  a188=(a188+a321);
  a321=(a048*a188);
  a351=(a068*a063);
  a172=(a146*a351);
  a240=(a074*a288);
  a142=(a005*a174);
  a240=(a240+a142);
  a142=(a082*a305);
  a240=(a240+a142);
  a142=(a135*a240);
  a300=(a069*a300);
  a160=(a127*a198);
  a300=(a300+a160);
  a160=(a092*a292);
  a346=(a131*a346);
  a160=(a160-a346);
  a300=(a300+a160);
  a299=(a076*a299);
  a160=(a129*a341);
  a299=(a299+a160);
  a300=(a300+a299);
  a299=(a059*a300);
  a142=(a142+a299);
  a299=(a002*a142);
  a160=(a134*a299);
  a240=(a059*a240);
  a300=(a090*a300);
  a240=(a240+a300);
  a300=(a002*a240);
  a346=(a018*a300);
  a160=(a160+a346);
  a346=(a061*a160);
  a172=(a172+a346);
  a346=(a048*a172);
  a321=(a321+a346);
  a346=(a007*a321);
  a080=(a080-a346);
  a346=(a146*a288);
  a349=(a070*a160);
  a346=(a346+a349);
  a349=(a148*a346);
  a080=(a080+a349);
  a349=(a136*a288);
  a165=(a070*a149);
  a349=(a349+a165);
  a165=(a048*a349);
  a314=(a158*a351);
  a139=(a065*a288);
  a174=(a073*a174);
  a139=(a139+a174);
  a305=(a063*a305);
  a139=(a139+a305);
  a305=(a135*a139);
  a174=(a122*a198);
  a259=(a069*a259);
  a174=(a174-a259);
  a062=(a131*a062);
  a292=(a126*a292);
  a062=(a062+a292);
  a174=(a174+a062);
  a347=(a076*a347);
  a341=(a120*a341);
  a347=(a347+a341);
  a174=(a174+a347);
  a347=(a059*a174);
  a305=(a305+a347);
  a347=(a002*a305);
  a341=(a134*a347);
  a139=(a059*a139);
  a174=(a090*a174);
  a139=(a139+a174);
  a174=(a002*a139);
  a062=(a018*a174);
  a341=(a341+a062);
  a062=(a061*a341);
  a314=(a314+a062);
  a062=(a048*a314);
  a165=(a165+a062);
  a062=(a004*a165);
  a080=(a080-a062);
  a062=(a158*a151);
  a292=(a071*a341);
  a062=(a062+a292);
  a292=(a056*a062);
  a080=(a080+a292);
  a292=(a146*a151);
  a160=(a071*a160);
  a292=(a292+a160);
  a160=(a048*a292);
  a259=(a158*a288);
  a341=(a070*a341);
  a259=(a259+a341);
  a341=(a048*a259);
  a216=(a160+a341);
  a216=(a161*a216);
  a080=(a080+a216);
  a216=(a136*a351);
  a149=(a061*a149);
  a216=(a216+a149);
  a149=(a009*a216);
  a322=(a081*a188);
  a149=(a149-a322);
  a322=(a054*a349);
  a149=(a149-a322);
  a322=(a081*a172);
  a149=(a149-a322);
  a292=(a012*a292);
  a149=(a149+a292);
  a292=(a072*a346);
  a149=(a149-a292);
  a292=(a054*a314);
  a149=(a149-a292);
  a292=(a072*a062);
  a149=(a149-a292);
  a259=(a008*a259);
  a149=(a149+a259);
  a259=(a167*a149);
  a259=(a049*a259);
  a292=(a019*a259);
  a149=(a149/a053);
  a292=(a292-a149);
  a322=(a032*a292);
  a293=(a045*a322);
  a170=(a027*a292);
  a176=(a020*a170);
  a176=(a042*a176);
  a293=(a293+a176);
  a176=(a039*a170);
  a293=(a293+a176);
  a176=(a020*a292);
  a176=(a036*a176);
  a293=(a293+a176);
  a176=(a033*a292);
  a293=(a293+a176);
  a176=(a032*a149);
  a304=(a029*a176);
  a293=(a293+a304);
  a304=(a027*a149);
  a342=(a020*a304);
  a342=(a025*a342);
  a293=(a293+a342);
  a342=(a022*a304);
  a293=(a293+a342);
  a259=(a034*a259);
  a322=(a047*a322);
  a342=(a046*a292);
  a342=(a180*a342);
  a177=(a040*a292);
  a342=(a342+a177);
  a342=(a179*a342);
  a322=(a322+a342);
  a170=(a043*a170);
  a322=(a322+a170);
  a292=(a037*a292);
  a322=(a322+a292);
  a322=(a013*a322);
  a259=(a259+a322);
  a176=(a031*a176);
  a322=(a030*a149);
  a322=(a180*a322);
  a292=(a023*a149);
  a322=(a322+a292);
  a322=(a179*a322);
  a176=(a176+a322);
  a304=(a026*a304);
  a176=(a176+a304);
  a304=(a017*a149);
  a176=(a176+a304);
  a176=(a013*a176);
  a259=(a259+a176);
  a259=(a018*a259);
  a293=(a293+a259);
  a259=(a020*a149);
  a259=(a016*a259);
  a293=(a293+a259);
  a149=(a001*a149);
  a293=(a293+a149);
  a149=(a161*a293);
  a080=(a080+a149);
  a149=(a058*a080);
  a349=(a056*a349);
  a349=(a349+a240);
  a321=(a011*a321);
  a349=(a349-a321);
  a314=(a148*a314);
  a349=(a349+a314);
  a346=(a048*a346);
  a062=(a048*a062);
  a346=(a346+a062);
  a062=(a004*a346);
  a349=(a349-a062);
  a216=(a048*a216);
  a341=(a216+a341);
  a341=(a189*a341);
  a349=(a349+a341);
  a341=(a189*a293);
  a349=(a349+a341);
  a341=(a187*a349);
  a149=(a149+a341);
  a188=(a148*a188);
  a172=(a056*a172);
  a188=(a188+a172);
  a216=(a216+a160);
  a216=(a193*a216);
  a188=(a188+a216);
  a188=(a188+a139);
  a165=(a011*a165);
  a188=(a188-a165);
  a346=(a007*a346);
  a188=(a188-a346);
  a293=(a193*a293);
  a188=(a188+a293);
  a293=(a191*a188);
  a149=(a149+a293);
  a288=(a163*a288);
  a288=(a195*a288);
  a149=(a149-a288);
  a149=(a149/a002);
  if (res[1]!=0) res[1][27]=a149;
  a149=(a203*a080);
  a288=(a205*a349);
  a149=(a149+a288);
  a346=(a208*a188);
  a149=(a149+a346);
  a151=(a163*a151);
  a151=(a195*a151);
  a149=(a149-a151);
  a149=(a149/a002);
  if (res[1]!=0) res[1][28]=a149;
  a149=(a204*a080);
  a151=(a196*a349);
  a151=(a149+a151);
  a346=(a212*a188);
  a151=(a151+a346);
  a351=(a163*a351);
  a351=(a195*a351);
  a151=(a151-a351);
  a151=(a151/a002);
  if (res[1]!=0) res[1][29]=a151;
  a151=(a119*a296);
  a351=(a125*a295);
  a351=(a151-a351);
  a346=(a213*a330);
  a165=(a115*a209);
  a139=(a101*a077);
  a165=(a165+a139);
  a165=(a109*a165);
  a346=(a346+a165);
  a165=(a096*a346);
  a139=(a351+a165);
  a139=(a194*a139);
  a216=(a119*a302);
  a160=(a097*a295);
  a216=(a216-a160);
  a216=(a201*a216);
  a139=(a139-a216);
  a214=(a214*a002);
  a216=(a091*a346);
  a216=(a214-a216);
  a160=(a128*a295);
  a216=(a216-a160);
  a216=(a202*a216);
  a139=(a139+a216);
  a139=(a195*a139);
  a216=(a163*a198);
  a216=(a195*a216);
  a139=(a139-a216);
  a077=(a077-a309);
  a077=(a077/a099);
  a330=(a049*a330);
  a216=(a229*a330);
  a077=(a077+a216);
  a216=(a117*a077);
  a160=(a110*a320);
  a216=(a216+a160);
  a172=(a079*a216);
  a341=(a137*a077);
  a062=(a133*a303);
  a344=(a018*a344);
  a168=(a078*a168);
  a344=(a344+a168);
  a168=(a124*a344);
  a062=(a062+a168);
  a168=(a110*a062);
  a341=(a341+a168);
  a168=(a144*a077);
  a314=(a141*a075);
  a299=(a018*a299);
  a300=(a078*a300);
  a299=(a299+a300);
  a300=(a118*a299);
  a314=(a314+a300);
  a300=(a110*a314);
  a168=(a168+a300);
  a341=(a341+a168);
  a168=(a093*a341);
  a332=(a332-a168);
  a168=(a141*a198);
  a300=(a069*a299);
  a168=(a168+a300);
  a300=(a148*a168);
  a332=(a332+a300);
  a222=(a222*a002);
  a300=(a221*a077);
  a321=(a133*a198);
  a240=(a069*a344);
  a321=(a321+a240);
  a240=(a110*a321);
  a300=(a300+a240);
  a240=(a156*a077);
  a259=(a153*a075);
  a347=(a018*a347);
  a174=(a078*a174);
  a347=(a347+a174);
  a174=(a118*a347);
  a259=(a259+a174);
  a174=(a110*a259);
  a240=(a240+a174);
  a300=(a300+a240);
  a240=(a091*a300);
  a240=(a222+a240);
  a332=(a332-a240);
  a240=(a153*a303);
  a174=(a124*a347);
  a240=(a240+a174);
  a174=(a056*a240);
  a332=(a332+a174);
  a174=(a224*a077);
  a176=(a141*a303);
  a299=(a124*a299);
  a176=(a176+a299);
  a299=(a110*a176);
  a174=(a174+a299);
  a299=(a226*a077);
  a198=(a153*a198);
  a347=(a069*a347);
  a198=(a198+a347);
  a347=(a110*a198);
  a299=(a299+a347);
  a347=(a174+a299);
  a347=(a223*a347);
  a332=(a332+a347);
  a347=(a233*a089);
  a209=(a232*a209);
  a304=(a077/a099);
  a322=(a229/a099);
  a292=(a322*a330);
  a304=(a304+a292);
  a304=(a231*a304);
  a292=(a230*a302);
  a170=(a133*a075);
  a344=(a118*a344);
  a170=(a170+a344);
  a344=(a095*a170);
  a292=(a292+a344);
  a344=(a128*a062);
  a292=(a292-a344);
  a344=(a221*a320);
  a342=(a117*a321);
  a344=(a344+a342);
  a292=(a292-a344);
  a344=(a128*a314);
  a292=(a292-a344);
  a344=(a224*a302);
  a176=(a097*a176);
  a344=(a344+a176);
  a292=(a292+a344);
  a344=(a145*a296);
  a176=(a125*a168);
  a344=(a344+a176);
  a292=(a292-a344);
  a344=(a156*a320);
  a176=(a117*a259);
  a344=(a344+a176);
  a292=(a292-a344);
  a344=(a157*a296);
  a176=(a125*a240);
  a344=(a344+a176);
  a292=(a292-a344);
  a198=(a094*a198);
  a292=(a292+a198);
  a198=(a229*a292);
  a304=(a304+a198);
  a304=(a049*a304);
  a198=(a101*a304);
  a209=(a209+a198);
  a292=(a292/a099);
  a198=(a234/a099);
  a330=(a198*a330);
  a292=(a292+a330);
  a209=(a209-a292);
  a330=(a107*a209);
  a347=(a347+a330);
  a330=(a045*a347);
  a344=(a237*a192);
  a176=(a233*a206);
  a342=(a105*a209);
  a176=(a176+a342);
  a342=(a102*a176);
  a344=(a344+a342);
  a344=(a042*a344);
  a330=(a330+a344);
  a344=(a039*a176);
  a330=(a330+a344);
  a344=(a233*a192);
  a342=(a102*a209);
  a344=(a344+a342);
  a344=(a036*a344);
  a330=(a330+a344);
  a344=(a033*a209);
  a330=(a330+a344);
  a089=(a234*a089);
  a344=(a107*a292);
  a089=(a089+a344);
  a344=(a029*a089);
  a330=(a330+a344);
  a344=(a239*a192);
  a342=(a234*a206);
  a177=(a105*a292);
  a342=(a342+a177);
  a177=(a102*a342);
  a344=(a344+a177);
  a344=(a025*a344);
  a330=(a330+a344);
  a344=(a022*a342);
  a330=(a330+a344);
  a309=(a232*a309);
  a304=(a108*a304);
  a309=(a309+a304);
  a304=(a056*a302);
  a344=(a235*a304);
  a347=(a047*a347);
  a177=(2.*a192);
  a311=(a244*a177);
  a206=(2.*a206);
  a329=(a243*a206);
  a014=(a233*a014);
  a184=(a106*a209);
  a014=(a014+a184);
  a014=(a242*a014);
  a329=(a329+a014);
  a331=(a233*a331);
  a014=(a103*a209);
  a331=(a331+a014);
  a329=(a329+a331);
  a329=(a241*a329);
  a311=(a311+a329);
  a347=(a347+a311);
  a060=(a237*a060);
  a176=(a104*a176);
  a060=(a060+a176);
  a347=(a347+a060);
  a052=(a233*a052);
  a209=(a100*a209);
  a052=(a052+a209);
  a347=(a347+a052);
  a347=(a098*a347);
  a344=(a344+a347);
  a309=(a309+a344);
  a304=(a238*a304);
  a089=(a031*a089);
  a177=(a246*a177);
  a206=(a245*a206);
  a291=(a234*a291);
  a344=(a114*a292);
  a291=(a291+a344);
  a291=(a242*a291);
  a206=(a206+a291);
  a280=(a234*a280);
  a291=(a112*a292);
  a280=(a280+a291);
  a206=(a206+a280);
  a206=(a241*a206);
  a177=(a177+a206);
  a089=(a089+a177);
  a306=(a239*a306);
  a342=(a113*a342);
  a306=(a306+a342);
  a089=(a089+a306);
  a289=(a234*a289);
  a306=(a111*a292);
  a289=(a289+a306);
  a089=(a089+a289);
  a089=(a098*a089);
  a304=(a304+a089);
  a309=(a309+a304);
  a309=(a018*a309);
  a330=(a330+a309);
  a192=(a234*a192);
  a309=(a102*a292);
  a192=(a192+a309);
  a192=(a016*a192);
  a330=(a330+a192);
  a292=(a001*a292);
  a330=(a330+a292);
  a292=(a223*a330);
  a332=(a332+a292);
  a292=(a219*a332);
  a292=(a172+a292);
  a139=(a139+a292);
  a292=(a125*a077);
  a192=(a110*a296);
  a292=(a292+a192);
  a309=(a143*a292);
  a321=(a056*a321);
  a142=(a142+a321);
  a341=(a096*a341);
  a142=(a142-a341);
  a259=(a148*a259);
  a142=(a142+a259);
  a249=(a249*a002);
  a259=(a145*a077);
  a168=(a110*a168);
  a259=(a259+a168);
  a168=(a157*a077);
  a240=(a110*a240);
  a168=(a168+a240);
  a259=(a259+a168);
  a168=(a091*a259);
  a168=(a249+a168);
  a142=(a142-a168);
  a168=(a230*a077);
  a170=(a110*a170);
  a168=(a168+a170);
  a299=(a168+a299);
  a299=(a250*a299);
  a142=(a142+a299);
  a299=(a250*a330);
  a142=(a142+a299);
  a299=(a248*a142);
  a299=(a309+a299);
  a139=(a139+a299);
  a062=(a148*a062);
  a305=(a305+a062);
  a314=(a056*a314);
  a305=(a305+a314);
  a251=(a251*a327);
  a168=(a168+a174);
  a168=(a253*a168);
  a251=(a251+a168);
  a305=(a305+a251);
  a300=(a096*a300);
  a305=(a305-a300);
  a259=(a093*a259);
  a305=(a305-a259);
  a236=(a236*a327);
  a330=(a253*a330);
  a330=(a236+a330);
  a305=(a305+a330);
  a330=(a252*a305);
  a259=(a094*a077);
  a259=(a155*a259);
  a330=(a330-a259);
  a139=(a139+a330);
  a139=(a139/a002);
  if (res[1]!=0) res[1][30]=a139;
  a139=(a128*a077);
  a259=(a139-a286);
  a259=(a079*a259);
  a300=(a255*a332);
  a259=(a259+a300);
  a303=(a163*a303);
  a303=(a195*a303);
  a300=(a094*a295);
  a300=(a194*a300);
  a351=(a351-a165);
  a351=(a201*a351);
  a300=(a300+a351);
  a351=(a119*a320);
  a295=(a117*a295);
  a295=(a351-a295);
  a346=(a093*a346);
  a295=(a295+a346);
  a295=(a202*a295);
  a300=(a300+a295);
  a300=(a195*a300);
  a303=(a303+a300);
  a259=(a259-a303);
  a303=(a257*a142);
  a300=(a097*a077);
  a302=(a110*a302);
  a300=(a300+a302);
  a300=(a143*a300);
  a303=(a303-a300);
  a259=(a259+a303);
  a292=(a155*a292);
  a300=(a210*a305);
  a300=(a292+a300);
  a259=(a259+a300);
  a259=(a259/a002);
  if (res[1]!=0) res[1][31]=a259;
  a259=(a256*a332);
  a077=(a095*a077);
  a077=(a077+a302);
  a077=(a079*a077);
  a259=(a259-a077);
  a075=(a163*a075);
  a075=(a195*a075);
  a075=(a259-a075);
  a077=(a139-a195);
  a077=(a143*a077);
  a302=(a262*a142);
  a077=(a077+a302);
  a075=(a075+a077);
  a216=(a155*a216);
  a077=(a264*a305);
  a077=(a216+a077);
  a075=(a075+a077);
  a075=(a075/a002);
  if (res[1]!=0) res[1][32]=a075;
  a075=1.7320508075688774e+00;
  a077=(a075*a002);
  a260=(a260*a077);
  a302=(a001*a260);
  a300=(a016*a260);
  a300=(a276*a300);
  a295=(a018*a260);
  a346=(a273*a295);
  a165=(a015*a346);
  a300=(a300+a165);
  a302=(a302+a300);
  a300=(a022*a260);
  a165=(a025*a260);
  a165=(a276*a165);
  a251=(a024*a346);
  a165=(a165+a251);
  a300=(a300+a165);
  a300=(a277*a300);
  a165=(a317*a346);
  a251=(a021*a165);
  a300=(a300+a251);
  a302=(a302+a300);
  a300=(a029*a260);
  a251=(a031*a346);
  a300=(a300+a251);
  a300=(a278*a300);
  a251=(a325*a165);
  a168=(a028*a251);
  a300=(a300+a168);
  a302=(a302+a300);
  a300=(a033*a260);
  a168=(a036*a260);
  a168=(a276*a168);
  a174=(a035*a346);
  a168=(a168+a174);
  a300=(a300+a168);
  a168=(a039*a260);
  a174=(a042*a260);
  a174=(a276*a174);
  a314=(a041*a346);
  a174=(a174+a314);
  a168=(a168+a174);
  a168=(a277*a168);
  a165=(a038*a165);
  a168=(a168+a165);
  a300=(a300+a168);
  a168=(a045*a260);
  a346=(a047*a346);
  a168=(a168+a346);
  a168=(a278*a168);
  a251=(a044*a251);
  a168=(a168+a251);
  a300=(a300+a168);
  a302=(a302-a300);
  a302=(a302/a279);
  a295=(a051*a295);
  a300=(a275*a300);
  a295=(a295+a300);
  a295=(a049*a295);
  a295=(a297*a295);
  a302=(a302+a295);
  a295=(a274*a302);
  a271=(a271*a077);
  a271=(a000*a271);
  a295=(a295+a271);
  a300=(a088*a295);
  a168=(a283*a302);
  a265=(a265*a077);
  a265=(a000*a265);
  a168=(a168+a265);
  a251=(a140*a168);
  a300=(a300+a251);
  a251=(a269*a302);
  a251=(a152*a251);
  a300=(a300-a251);
  a251=(a218*a332);
  a172=(a172+a251);
  a300=(a300+a172);
  a172=(a247*a142);
  a309=(a309+a172);
  a300=(a300+a309);
  a300=(a300+a330);
  a330=(a057*a080);
  a300=(a300+a330);
  a330=(a186*a349);
  a300=(a300+a330);
  a300=(a300+a293);
  a300=(-a300);
  if (res[1]!=0) res[1][33]=a300;
  a300=(a154*a302);
  a293=(a336+a300);
  a293=(a088*a293);
  a330=(a272*a302);
  a260=(a000*a260);
  a330=(a330+a260);
  a330=(a140*a330);
  a293=(a293-a330);
  a168=(a152*a168);
  a293=(a293+a168);
  a168=(a286+a139);
  a168=(a079*a168);
  a332=(a254*a332);
  a168=(a168+a332);
  a293=(a293+a168);
  a293=(a293+a303);
  a303=(a215*a305);
  a292=(a292+a303);
  a293=(a293+a292);
  a080=(a200*a080);
  a293=(a293+a080);
  a293=(a293+a288);
  a288=(a207*a188);
  a293=(a293+a288);
  a293=(-a293);
  if (res[1]!=0) res[1][34]=a293;
  a300=(a301+a300);
  a300=(a140*a300);
  a302=(a270*a302);
  a302=(a302+a260);
  a302=(a088*a302);
  a300=(a300-a302);
  a295=(a152*a295);
  a300=(a300+a295);
  a300=(a300+a259);
  a139=(a195+a139);
  a139=(a143*a139);
  a142=(a261*a142);
  a139=(a139+a142);
  a300=(a300+a139);
  a305=(a263*a305);
  a216=(a216+a305);
  a300=(a300+a216);
  a300=(a300+a149);
  a349=(a199*a349);
  a300=(a300+a349);
  a188=(a211*a188);
  a300=(a300+a188);
  a300=(-a300);
  if (res[1]!=0) res[1][35]=a300;
  a300=(a068*a074);
  a188=(a064*a300);
  a349=(a326*a005);
  a149=(a083*a349);
  a188=(a188+a149);
  a149=(a355*a082);
  a216=(a086*a149);
  a188=(a188+a216);
  a216=(a059*a188);
  a305=(a250*a002);
  a139=(a033*a305);
  a142=(a036*a305);
  a259=(a102*a142);
  a295=(a018*a305);
  a302=(a098*a295);
  a260=(a100*a302);
  a259=(a259+a260);
  a139=(a139+a259);
  a259=(a039*a305);
  a260=(a042*a305);
  a293=(a102*a260);
  a288=(a104*a302);
  a293=(a293+a288);
  a259=(a259+a293);
  a293=(a105*a259);
  a288=(a241*a302);
  a080=(a103*a288);
  a293=(a293+a080);
  a139=(a139+a293);
  a293=(a045*a305);
  a080=(a047*a302);
  a293=(a293+a080);
  a080=(a107*a293);
  a292=(a242*a288);
  a303=(a106*a292);
  a080=(a080+a303);
  a139=(a139+a080);
  a080=(a001*a305);
  a303=(a016*a305);
  a168=(a102*a303);
  a332=(a111*a302);
  a168=(a168+a332);
  a080=(a080+a168);
  a168=(a022*a305);
  a332=(a025*a305);
  a330=(a102*a332);
  a309=(a113*a302);
  a330=(a330+a309);
  a168=(a168+a330);
  a330=(a105*a168);
  a309=(a112*a288);
  a330=(a330+a309);
  a080=(a080+a330);
  a330=(a029*a305);
  a309=(a031*a302);
  a330=(a330+a309);
  a309=(a107*a330);
  a172=(a114*a292);
  a309=(a309+a172);
  a080=(a080+a309);
  a309=(a109*a080);
  a172=(a108*a295);
  a251=(a101*a139);
  a172=(a172+a251);
  a251=(a115*a172);
  a309=(a309-a251);
  a309=(a139+a309);
  a309=(a018*a309);
  a251=(a117*a309);
  a346=(a340*a172);
  a346=(a056*a346);
  a165=(a093*a346);
  a165=(a197-a165);
  a174=(a251-a165);
  a314=(a069*a174);
  a062=(a125*a309);
  a299=(a091*a002);
  a170=(a116*a299);
  a062=(a062+a170);
  a240=(a096*a346);
  a341=(a062-a240);
  a321=(a006*a341);
  a304=(a066*a127);
  a321=(a321+a304);
  a304=(a094*a309);
  a089=(a116*a305);
  a304=(a304+a089);
  a289=(a003*a304);
  a321=(a321-a289);
  a174=(a010*a174);
  a321=(a321+a174);
  a174=(a121*a321);
  a314=(a314+a174);
  a174=(a128*a309);
  a174=(a174+a067);
  a067=(a091*a346);
  a289=(a174-a067);
  a306=(a131*a289);
  a062=(a062+a240);
  a240=(a003*a062);
  a342=(a066*a092);
  a177=(a097*a309);
  a206=(a006*a177);
  a342=(a342-a206);
  a240=(a240+a342);
  a289=(a010*a289);
  a240=(a240+a289);
  a289=(a084*a240);
  a342=(a130*a289);
  a306=(a306+a342);
  a314=(a314+a306);
  a165=(a165+a251);
  a251=(a003*a165);
  a174=(a174+a067);
  a067=(a006*a174);
  a306=(a066*a129);
  a067=(a067+a306);
  a251=(a251+a067);
  a309=(a095*a309);
  a309=(a309+a089);
  a089=(a010*a309);
  a251=(a251-a089);
  a089=(a087*a251);
  a067=(a132*a089);
  a309=(a076*a309);
  a067=(a067-a309);
  a314=(a314+a067);
  a067=(a090*a314);
  a216=(a216+a067);
  a067=(a068*a005);
  a309=(a136*a067);
  a188=(a135*a188);
  a314=(a059*a314);
  a188=(a188+a314);
  a314=(a002*a188);
  a306=(a134*a314);
  a342=(a002*a216);
  a206=(a018*a342);
  a306=(a306+a206);
  a206=(a071*a306);
  a309=(a309+a206);
  a206=(a048*a309);
  a280=(a068*a082);
  a291=(a146*a280);
  a344=(a074*a300);
  a347=(a005*a349);
  a344=(a344+a347);
  a347=(a082*a149);
  a344=(a344+a347);
  a347=(a135*a344);
  a341=(a069*a341);
  a052=(a127*a321);
  a341=(a341+a052);
  a052=(a092*a289);
  a177=(a131*a177);
  a052=(a052-a177);
  a341=(a341+a052);
  a174=(a076*a174);
  a052=(a129*a089);
  a174=(a174+a052);
  a341=(a341+a174);
  a174=(a059*a341);
  a347=(a347+a174);
  a174=(a002*a347);
  a052=(a134*a174);
  a344=(a059*a344);
  a341=(a090*a341);
  a344=(a344+a341);
  a341=(a002*a344);
  a177=(a018*a341);
  a052=(a052+a177);
  a177=(a061*a052);
  a291=(a291+a177);
  a177=(a048*a291);
  a206=(a206+a177);
  a177=(a007*a206);
  a216=(a216-a177);
  a177=(a146*a300);
  a209=(a070*a052);
  a177=(a177+a209);
  a209=(a148*a177);
  a216=(a216+a209);
  a209=(a136*a300);
  a060=(a070*a306);
  a209=(a209+a060);
  a060=(a048*a209);
  a176=(a158*a280);
  a311=(a065*a300);
  a349=(a073*a349);
  a311=(a311+a349);
  a149=(a063*a149);
  a311=(a311+a149);
  a149=(a135*a311);
  a349=(a122*a321);
  a304=(a069*a304);
  a349=(a349-a304);
  a062=(a131*a062);
  a289=(a126*a289);
  a062=(a062+a289);
  a349=(a349+a062);
  a165=(a076*a165);
  a089=(a120*a089);
  a165=(a165+a089);
  a349=(a349+a165);
  a165=(a059*a349);
  a149=(a149+a165);
  a165=(a002*a149);
  a089=(a134*a165);
  a311=(a059*a311);
  a349=(a090*a349);
  a311=(a311+a349);
  a349=(a002*a311);
  a062=(a018*a349);
  a089=(a089+a062);
  a062=(a061*a089);
  a176=(a176+a062);
  a062=(a048*a176);
  a060=(a060+a062);
  a062=(a004*a060);
  a216=(a216-a062);
  a062=(a158*a067);
  a289=(a071*a089);
  a062=(a062+a289);
  a289=(a056*a062);
  a216=(a216+a289);
  a289=(a146*a067);
  a052=(a071*a052);
  a289=(a289+a052);
  a052=(a048*a289);
  a304=(a158*a300);
  a089=(a070*a089);
  a304=(a304+a089);
  a089=(a048*a304);
  a329=(a052+a089);
  a329=(a161*a329);
  a216=(a216+a329);
  a329=(a136*a280);
  a306=(a061*a306);
  a329=(a329+a306);
  a306=(a009*a329);
  a331=(a081*a309);
  a306=(a306-a331);
  a331=(a054*a209);
  a306=(a306-a331);
  a331=(a081*a291);
  a306=(a306-a331);
  a289=(a012*a289);
  a306=(a306+a289);
  a289=(a072*a177);
  a306=(a306-a289);
  a289=(a054*a176);
  a306=(a306-a289);
  a289=(a072*a062);
  a306=(a306-a289);
  a304=(a008*a304);
  a306=(a306+a304);
  a304=(a167*a306);
  a304=(a049*a304);
  a289=(a019*a304);
  a306=(a306/a053);
  a289=(a289-a306);
  a331=(a032*a289);
  a014=(a045*a331);
  a184=(a027*a289);
  a183=(a020*a184);
  a183=(a042*a183);
  a014=(a014+a183);
  a183=(a039*a184);
  a014=(a014+a183);
  a183=(a020*a289);
  a183=(a036*a183);
  a014=(a014+a183);
  a183=(a033*a289);
  a014=(a014+a183);
  a183=(a032*a306);
  a339=(a029*a183);
  a014=(a014+a339);
  a339=(a027*a306);
  a190=(a020*a339);
  a190=(a025*a190);
  a014=(a014+a190);
  a190=(a022*a339);
  a014=(a014+a190);
  a304=(a034*a304);
  a331=(a047*a331);
  a190=(a046*a289);
  a190=(a180*a190);
  a319=(a040*a289);
  a190=(a190+a319);
  a190=(a179*a190);
  a331=(a331+a190);
  a184=(a043*a184);
  a331=(a331+a184);
  a289=(a037*a289);
  a331=(a331+a289);
  a331=(a013*a331);
  a304=(a304+a331);
  a183=(a031*a183);
  a331=(a030*a306);
  a331=(a180*a331);
  a289=(a023*a306);
  a331=(a331+a289);
  a331=(a179*a331);
  a183=(a183+a331);
  a339=(a026*a339);
  a183=(a183+a339);
  a339=(a017*a306);
  a183=(a183+a339);
  a183=(a013*a183);
  a304=(a304+a183);
  a304=(a018*a304);
  a014=(a014+a304);
  a304=(a020*a306);
  a304=(a016*a304);
  a014=(a014+a304);
  a306=(a001*a306);
  a014=(a014+a306);
  a306=(a161*a014);
  a216=(a216+a306);
  a306=(a058*a216);
  a209=(a056*a209);
  a209=(a209+a344);
  a206=(a011*a206);
  a209=(a209-a206);
  a176=(a148*a176);
  a209=(a209+a176);
  a177=(a048*a177);
  a062=(a048*a062);
  a177=(a177+a062);
  a062=(a004*a177);
  a209=(a209-a062);
  a329=(a048*a329);
  a089=(a329+a089);
  a089=(a189*a089);
  a209=(a209+a089);
  a089=(a189*a014);
  a209=(a209+a089);
  a089=(a187*a209);
  a306=(a306+a089);
  a309=(a148*a309);
  a291=(a056*a291);
  a309=(a309+a291);
  a329=(a329+a052);
  a329=(a193*a329);
  a309=(a309+a329);
  a309=(a309+a311);
  a060=(a011*a060);
  a309=(a309-a060);
  a177=(a007*a177);
  a309=(a309-a177);
  a014=(a193*a014);
  a309=(a309+a014);
  a014=(a191*a309);
  a306=(a306+a014);
  a300=(a163*a300);
  a300=(a195*a300);
  a306=(a306-a300);
  a306=(a306/a002);
  if (res[1]!=0) res[1][36]=a306;
  a306=(a203*a216);
  a300=(a205*a209);
  a306=(a306+a300);
  a177=(a208*a309);
  a306=(a306+a177);
  a067=(a163*a067);
  a067=(a195*a067);
  a306=(a306-a067);
  a306=(a306/a002);
  if (res[1]!=0) res[1][37]=a306;
  a306=(a204*a216);
  a067=(a196*a209);
  a067=(a306+a067);
  a177=(a212*a309);
  a067=(a067+a177);
  a280=(a163*a280);
  a280=(a195*a280);
  a067=(a067-a280);
  a067=(a067/a002);
  if (res[1]!=0) res[1][38]=a067;
  a067=(a119*a299);
  a280=(a125*a346);
  a280=(a067-a280);
  a177=(a213*a172);
  a060=(a115*a295);
  a311=(a101*a080);
  a060=(a060+a311);
  a060=(a109*a060);
  a177=(a177+a060);
  a060=(a096*a177);
  a311=(a280+a060);
  a311=(a194*a311);
  a329=(a097*a346);
  a329=(a201*a329);
  a311=(a311+a329);
  a329=(a128*a346);
  a351=(a351-a329);
  a329=(a091*a177);
  a351=(a351-a329);
  a351=(a202*a351);
  a311=(a311+a351);
  a311=(a195*a311);
  a351=(a163*a321);
  a351=(a195*a351);
  a311=(a311-a351);
  a080=(a080-a139);
  a080=(a080/a099);
  a172=(a049*a172);
  a351=(a229*a172);
  a080=(a080+a351);
  a351=(a117*a080);
  a329=(a351-a195);
  a329=(a079*a329);
  a220=(a220*a002);
  a052=(a137*a080);
  a291=(a133*a240);
  a314=(a018*a314);
  a342=(a078*a342);
  a314=(a314+a342);
  a342=(a124*a314);
  a291=(a291+a342);
  a342=(a110*a291);
  a052=(a052+a342);
  a342=(a144*a080);
  a089=(a141*a251);
  a174=(a018*a174);
  a341=(a078*a341);
  a174=(a174+a341);
  a341=(a118*a174);
  a089=(a089+a341);
  a341=(a110*a089);
  a342=(a342+a341);
  a052=(a052+a342);
  a342=(a093*a052);
  a342=(a220+a342);
  a188=(a188-a342);
  a342=(a141*a321);
  a341=(a069*a174);
  a342=(a342+a341);
  a341=(a148*a342);
  a188=(a188+a341);
  a341=(a221*a080);
  a062=(a133*a321);
  a176=(a069*a314);
  a062=(a062+a176);
  a176=(a110*a062);
  a341=(a341+a176);
  a176=(a156*a080);
  a206=(a153*a251);
  a165=(a018*a165);
  a349=(a078*a349);
  a165=(a165+a349);
  a349=(a118*a165);
  a206=(a206+a349);
  a349=(a110*a206);
  a176=(a176+a349);
  a341=(a341+a176);
  a176=(a091*a341);
  a188=(a188-a176);
  a176=(a153*a240);
  a349=(a124*a165);
  a176=(a176+a349);
  a349=(a056*a176);
  a188=(a188+a349);
  a349=(a224*a080);
  a344=(a141*a240);
  a174=(a124*a174);
  a344=(a344+a174);
  a174=(a110*a344);
  a349=(a349+a174);
  a174=(a226*a080);
  a321=(a153*a321);
  a165=(a069*a165);
  a321=(a321+a165);
  a165=(a110*a321);
  a174=(a174+a165);
  a165=(a349+a174);
  a165=(a223*a165);
  a188=(a188+a165);
  a165=(a233*a292);
  a295=(a232*a295);
  a304=(a080/a099);
  a183=(a322*a172);
  a304=(a304+a183);
  a304=(a231*a304);
  a183=(a230*a305);
  a339=(a133*a251);
  a314=(a118*a314);
  a339=(a339+a314);
  a314=(a095*a339);
  a183=(a183+a314);
  a314=(a137*a320);
  a331=(a128*a291);
  a314=(a314+a331);
  a183=(a183-a314);
  a314=(a117*a062);
  a183=(a183-a314);
  a320=(a144*a320);
  a314=(a128*a089);
  a320=(a320+a314);
  a183=(a183-a320);
  a344=(a097*a344);
  a183=(a183+a344);
  a344=(a145*a299);
  a320=(a125*a342);
  a344=(a344+a320);
  a183=(a183-a344);
  a344=(a117*a206);
  a183=(a183-a344);
  a344=(a157*a299);
  a320=(a125*a176);
  a344=(a344+a320);
  a183=(a183-a344);
  a344=(a226*a305);
  a321=(a094*a321);
  a344=(a344+a321);
  a183=(a183+a344);
  a344=(a229*a183);
  a304=(a304+a344);
  a304=(a049*a304);
  a344=(a101*a304);
  a295=(a295+a344);
  a183=(a183/a099);
  a172=(a198*a172);
  a183=(a183+a172);
  a295=(a295-a183);
  a172=(a107*a295);
  a165=(a165+a172);
  a172=(a045*a165);
  a344=(a237*a302);
  a321=(a233*a288);
  a320=(a105*a295);
  a321=(a321+a320);
  a320=(a102*a321);
  a344=(a344+a320);
  a344=(a042*a344);
  a172=(a172+a344);
  a344=(a039*a321);
  a172=(a172+a344);
  a344=(a233*a302);
  a320=(a102*a295);
  a344=(a344+a320);
  a344=(a036*a344);
  a172=(a172+a344);
  a344=(a033*a295);
  a172=(a172+a344);
  a292=(a234*a292);
  a344=(a107*a183);
  a292=(a292+a344);
  a344=(a029*a292);
  a172=(a172+a344);
  a344=(a239*a302);
  a320=(a234*a288);
  a314=(a105*a183);
  a320=(a320+a314);
  a314=(a102*a320);
  a344=(a344+a314);
  a344=(a025*a344);
  a172=(a172+a344);
  a344=(a022*a320);
  a172=(a172+a344);
  a139=(a232*a139);
  a304=(a108*a304);
  a139=(a139+a304);
  a304=(a056*a305);
  a344=(a235*a304);
  a165=(a047*a165);
  a314=(2.*a302);
  a331=(a244*a314);
  a288=(2.*a288);
  a289=(a243*a288);
  a293=(a233*a293);
  a184=(a106*a295);
  a293=(a293+a184);
  a293=(a242*a293);
  a289=(a289+a293);
  a259=(a233*a259);
  a293=(a103*a295);
  a259=(a259+a293);
  a289=(a289+a259);
  a289=(a241*a289);
  a331=(a331+a289);
  a165=(a165+a331);
  a260=(a237*a260);
  a321=(a104*a321);
  a260=(a260+a321);
  a165=(a165+a260);
  a142=(a233*a142);
  a295=(a100*a295);
  a142=(a142+a295);
  a165=(a165+a142);
  a165=(a098*a165);
  a344=(a344+a165);
  a139=(a139+a344);
  a304=(a238*a304);
  a292=(a031*a292);
  a314=(a246*a314);
  a288=(a245*a288);
  a330=(a234*a330);
  a344=(a114*a183);
  a330=(a330+a344);
  a330=(a242*a330);
  a288=(a288+a330);
  a168=(a234*a168);
  a330=(a112*a183);
  a168=(a168+a330);
  a288=(a288+a168);
  a288=(a241*a288);
  a314=(a314+a288);
  a292=(a292+a314);
  a332=(a239*a332);
  a320=(a113*a320);
  a332=(a332+a320);
  a292=(a292+a332);
  a303=(a234*a303);
  a332=(a111*a183);
  a303=(a303+a332);
  a292=(a292+a303);
  a292=(a098*a292);
  a304=(a304+a292);
  a139=(a139+a304);
  a139=(a018*a139);
  a172=(a172+a139);
  a302=(a234*a302);
  a139=(a102*a183);
  a302=(a302+a139);
  a302=(a016*a302);
  a172=(a172+a302);
  a183=(a001*a183);
  a172=(a172+a183);
  a183=(a223*a172);
  a188=(a188+a183);
  a183=(a219*a188);
  a329=(a329+a183);
  a311=(a311+a329);
  a329=(a125*a080);
  a183=(a110*a299);
  a329=(a329+a183);
  a302=(a143*a329);
  a062=(a056*a062);
  a347=(a347+a062);
  a052=(a096*a052);
  a347=(a347-a052);
  a206=(a148*a206);
  a347=(a347+a206);
  a206=(a145*a080);
  a342=(a110*a342);
  a206=(a206+a342);
  a342=(a157*a080);
  a176=(a110*a176);
  a342=(a342+a176);
  a206=(a206+a342);
  a342=(a091*a206);
  a347=(a347-a342);
  a227=(a227*a327);
  a342=(a230*a080);
  a339=(a110*a339);
  a342=(a342+a339);
  a174=(a342+a174);
  a174=(a250*a174);
  a227=(a227+a174);
  a347=(a347+a227);
  a227=(a250*a172);
  a227=(a236+a227);
  a347=(a347+a227);
  a227=(a248*a347);
  a227=(a302+a227);
  a311=(a311+a227);
  a291=(a148*a291);
  a149=(a149+a291);
  a089=(a056*a089);
  a149=(a149+a089);
  a342=(a342+a349);
  a342=(a253*a342);
  a149=(a149+a342);
  a341=(a096*a341);
  a149=(a149-a341);
  a206=(a093*a206);
  a249=(a249+a206);
  a149=(a149-a249);
  a172=(a253*a172);
  a149=(a149+a172);
  a172=(a252*a149);
  a249=(a094*a080);
  a206=(a110*a305);
  a249=(a249+a206);
  a249=(a155*a249);
  a172=(a172-a249);
  a311=(a311+a172);
  a311=(a311/a002);
  if (res[1]!=0) res[1][39]=a311;
  a311=(a128*a080);
  a311=(a311+a160);
  a160=(a079*a311);
  a249=(a255*a188);
  a249=(a160+a249);
  a240=(a163*a240);
  a240=(a195*a240);
  a280=(a280-a060);
  a280=(a201*a280);
  a305=(a119*a305);
  a060=(a094*a346);
  a305=(a305-a060);
  a305=(a194*a305);
  a280=(a280-a305);
  a346=(a117*a346);
  a177=(a093*a177);
  a177=(a214-a177);
  a346=(a346+a177);
  a346=(a202*a346);
  a280=(a280-a346);
  a280=(a195*a280);
  a240=(a240+a280);
  a249=(a249-a240);
  a240=(a257*a347);
  a280=(a097*a080);
  a280=(a143*a280);
  a240=(a240-a280);
  a249=(a249+a240);
  a329=(a155*a329);
  a280=(a210*a149);
  a280=(a329+a280);
  a249=(a249+a280);
  a249=(a249/a002);
  if (res[1]!=0) res[1][40]=a249;
  a249=(a256*a188);
  a080=(a095*a080);
  a080=(a080+a206);
  a080=(a079*a080);
  a249=(a249-a080);
  a251=(a163*a251);
  a251=(a195*a251);
  a251=(a249-a251);
  a311=(a143*a311);
  a080=(a262*a347);
  a080=(a311+a080);
  a251=(a251+a080);
  a080=(a351-a286);
  a080=(a155*a080);
  a206=(a264*a149);
  a080=(a080+a206);
  a251=(a251+a080);
  a251=(a251/a002);
  if (res[1]!=0) res[1][41]=a251;
  a350=(a350*a077);
  a251=(a001*a350);
  a080=(a016*a350);
  a080=(a276*a080);
  a206=(a018*a350);
  a280=(a273*a206);
  a346=(a015*a280);
  a080=(a080+a346);
  a251=(a251+a080);
  a080=(a022*a350);
  a346=(a025*a350);
  a346=(a276*a346);
  a177=(a024*a280);
  a346=(a346+a177);
  a080=(a080+a346);
  a080=(a277*a080);
  a346=(a317*a280);
  a177=(a021*a346);
  a080=(a080+a177);
  a251=(a251+a080);
  a080=(a029*a350);
  a177=(a031*a280);
  a080=(a080+a177);
  a080=(a278*a080);
  a177=(a325*a346);
  a305=(a028*a177);
  a080=(a080+a305);
  a251=(a251+a080);
  a080=(a033*a350);
  a305=(a036*a350);
  a305=(a276*a305);
  a060=(a035*a280);
  a305=(a305+a060);
  a080=(a080+a305);
  a305=(a039*a350);
  a060=(a042*a350);
  a060=(a276*a060);
  a341=(a041*a280);
  a060=(a060+a341);
  a305=(a305+a060);
  a305=(a277*a305);
  a346=(a038*a346);
  a305=(a305+a346);
  a080=(a080+a305);
  a305=(a045*a350);
  a280=(a047*a280);
  a305=(a305+a280);
  a305=(a278*a305);
  a177=(a044*a177);
  a305=(a305+a177);
  a080=(a080+a305);
  a251=(a251-a080);
  a251=(a251/a279);
  a206=(a051*a206);
  a080=(a275*a080);
  a206=(a206+a080);
  a206=(a049*a206);
  a206=(a297*a206);
  a251=(a251+a206);
  a206=(a274*a251);
  a080=(a301+a206);
  a080=(a088*a080);
  a305=(a283*a251);
  a267=(a267*a077);
  a267=(a000*a267);
  a305=(a305+a267);
  a177=(a140*a305);
  a080=(a080+a177);
  a177=(a269*a251);
  a350=(a000*a350);
  a177=(a177+a350);
  a177=(a152*a177);
  a080=(a080-a177);
  a177=(a195+a351);
  a177=(a079*a177);
  a280=(a218*a188);
  a177=(a177+a280);
  a080=(a080+a177);
  a177=(a247*a347);
  a302=(a302+a177);
  a080=(a080+a302);
  a080=(a080+a172);
  a172=(a057*a216);
  a080=(a080+a172);
  a172=(a186*a209);
  a080=(a080+a172);
  a080=(a080+a014);
  a080=(-a080);
  if (res[1]!=0) res[1][42]=a080;
  a080=(a154*a251);
  a080=(a080+a271);
  a271=(a088*a080);
  a014=(a272*a251);
  a014=(a140*a014);
  a271=(a271-a014);
  a305=(a152*a305);
  a271=(a271+a305);
  a188=(a254*a188);
  a160=(a160+a188);
  a271=(a271+a160);
  a271=(a271+a240);
  a240=(a215*a149);
  a329=(a329+a240);
  a271=(a271+a329);
  a216=(a200*a216);
  a271=(a271+a216);
  a271=(a271+a300);
  a300=(a207*a309);
  a271=(a271+a300);
  a271=(-a271);
  if (res[1]!=0) res[1][43]=a271;
  a080=(a140*a080);
  a251=(a270*a251);
  a251=(a251+a350);
  a251=(a088*a251);
  a080=(a080-a251);
  a206=(a336+a206);
  a206=(a152*a206);
  a080=(a080+a206);
  a080=(a080+a249);
  a347=(a261*a347);
  a311=(a311+a347);
  a080=(a080+a311);
  a351=(a286+a351);
  a351=(a155*a351);
  a149=(a263*a149);
  a351=(a351+a149);
  a080=(a080+a351);
  a080=(a080+a306);
  a209=(a199*a209);
  a080=(a080+a209);
  a309=(a211*a309);
  a080=(a080+a309);
  a080=(-a080);
  if (res[1]!=0) res[1][44]=a080;
  a080=(a068*a064);
  a064=(a064*a080);
  a326=(a326*a083);
  a309=(a083*a326);
  a064=(a064+a309);
  a355=(a355*a086);
  a309=(a086*a355);
  a064=(a064+a309);
  a309=(a059*a064);
  a209=(a223*a002);
  a306=(a033*a209);
  a351=(a036*a209);
  a149=(a102*a351);
  a311=(a018*a209);
  a347=(a098*a311);
  a249=(a100*a347);
  a149=(a149+a249);
  a306=(a306+a149);
  a149=(a039*a209);
  a249=(a042*a209);
  a206=(a102*a249);
  a251=(a104*a347);
  a206=(a206+a251);
  a149=(a149+a206);
  a206=(a105*a149);
  a251=(a241*a347);
  a350=(a103*a251);
  a206=(a206+a350);
  a306=(a306+a206);
  a206=(a045*a209);
  a350=(a047*a347);
  a206=(a206+a350);
  a350=(a107*a206);
  a271=(a242*a251);
  a300=(a106*a271);
  a350=(a350+a300);
  a306=(a306+a350);
  a350=(a001*a209);
  a300=(a016*a209);
  a216=(a102*a300);
  a329=(a111*a347);
  a216=(a216+a329);
  a350=(a350+a216);
  a216=(a022*a209);
  a329=(a025*a209);
  a240=(a102*a329);
  a160=(a113*a347);
  a240=(a240+a160);
  a216=(a216+a240);
  a240=(a105*a216);
  a160=(a112*a251);
  a240=(a240+a160);
  a350=(a350+a240);
  a240=(a029*a209);
  a160=(a031*a347);
  a240=(a240+a160);
  a160=(a107*a240);
  a188=(a114*a271);
  a160=(a160+a188);
  a350=(a350+a160);
  a160=(a109*a350);
  a188=(a108*a311);
  a305=(a101*a306);
  a188=(a188+a305);
  a305=(a115*a188);
  a160=(a160-a305);
  a160=(a306+a160);
  a160=(a018*a160);
  a305=(a117*a160);
  a305=(a305+a170);
  a340=(a340*a188);
  a340=(a056*a340);
  a170=(a093*a340);
  a014=(a305+a170);
  a172=(a069*a014);
  a302=(a096*a340);
  a197=(a197-a302);
  a302=(a125*a160);
  a177=(a197+a302);
  a280=(a006*a177);
  a346=(a094*a160);
  a116=(a116*a209);
  a346=(a346+a116);
  a060=(a003*a346);
  a280=(a280-a060);
  a014=(a010*a014);
  a060=(a066*a121);
  a014=(a014+a060);
  a280=(a280+a014);
  a121=(a121*a280);
  a172=(a172+a121);
  a121=(a128*a160);
  a121=(a121+a348);
  a348=(a091*a340);
  a014=(a121-a348);
  a060=(a131*a014);
  a302=(a302-a197);
  a197=(a003*a302);
  a341=(a097*a160);
  a341=(a341+a116);
  a116=(a006*a341);
  a197=(a197-a116);
  a014=(a010*a014);
  a116=(a066*a130);
  a014=(a014+a116);
  a197=(a197+a014);
  a084=(a084*a197);
  a130=(a130*a084);
  a060=(a060+a130);
  a172=(a172+a060);
  a305=(a305-a170);
  a003=(a003*a305);
  a121=(a121+a348);
  a006=(a006*a121);
  a003=(a003+a006);
  a066=(a066*a132);
  a160=(a095*a160);
  a010=(a010*a160);
  a066=(a066-a010);
  a003=(a003+a066);
  a087=(a087*a003);
  a132=(a132*a087);
  a160=(a076*a160);
  a132=(a132-a160);
  a172=(a172+a132);
  a132=(a090*a172);
  a309=(a309+a132);
  a083=(a068*a083);
  a132=(a136*a083);
  a064=(a135*a064);
  a172=(a059*a172);
  a064=(a064+a172);
  a172=(a002*a064);
  a160=(a134*a172);
  a066=(a002*a309);
  a010=(a018*a066);
  a160=(a160+a010);
  a010=(a071*a160);
  a132=(a132+a010);
  a010=(a048*a132);
  a068=(a068*a086);
  a086=(a146*a068);
  a074=(a074*a080);
  a005=(a005*a326);
  a074=(a074+a005);
  a082=(a082*a355);
  a074=(a074+a082);
  a082=(a135*a074);
  a177=(a069*a177);
  a127=(a127*a280);
  a177=(a177+a127);
  a092=(a092*a084);
  a341=(a131*a341);
  a092=(a092-a341);
  a177=(a177+a092);
  a121=(a076*a121);
  a129=(a129*a087);
  a121=(a121+a129);
  a177=(a177+a121);
  a121=(a059*a177);
  a082=(a082+a121);
  a121=(a002*a082);
  a129=(a134*a121);
  a074=(a059*a074);
  a177=(a090*a177);
  a074=(a074+a177);
  a177=(a002*a074);
  a092=(a018*a177);
  a129=(a129+a092);
  a092=(a061*a129);
  a086=(a086+a092);
  a092=(a048*a086);
  a010=(a010+a092);
  a092=(a007*a010);
  a309=(a309-a092);
  a092=(a146*a080);
  a341=(a070*a129);
  a092=(a092+a341);
  a341=(a148*a092);
  a309=(a309+a341);
  a341=(a136*a080);
  a127=(a070*a160);
  a341=(a341+a127);
  a127=(a048*a341);
  a005=(a158*a068);
  a065=(a065*a080);
  a073=(a073*a326);
  a065=(a065+a073);
  a063=(a063*a355);
  a065=(a065+a063);
  a135=(a135*a065);
  a122=(a122*a280);
  a346=(a069*a346);
  a122=(a122-a346);
  a131=(a131*a302);
  a126=(a126*a084);
  a131=(a131+a126);
  a122=(a122+a131);
  a076=(a076*a305);
  a120=(a120*a087);
  a076=(a076+a120);
  a122=(a122+a076);
  a076=(a059*a122);
  a135=(a135+a076);
  a076=(a002*a135);
  a134=(a134*a076);
  a059=(a059*a065);
  a090=(a090*a122);
  a059=(a059+a090);
  a090=(a002*a059);
  a122=(a018*a090);
  a134=(a134+a122);
  a122=(a061*a134);
  a005=(a005+a122);
  a122=(a048*a005);
  a127=(a127+a122);
  a122=(a004*a127);
  a309=(a309-a122);
  a122=(a158*a083);
  a065=(a071*a134);
  a122=(a122+a065);
  a065=(a056*a122);
  a309=(a309+a065);
  a146=(a146*a083);
  a129=(a071*a129);
  a146=(a146+a129);
  a129=(a048*a146);
  a158=(a158*a080);
  a134=(a070*a134);
  a158=(a158+a134);
  a134=(a048*a158);
  a065=(a129+a134);
  a065=(a161*a065);
  a309=(a309+a065);
  a136=(a136*a068);
  a160=(a061*a160);
  a136=(a136+a160);
  a160=(a009*a136);
  a065=(a081*a132);
  a160=(a160-a065);
  a065=(a054*a341);
  a160=(a160-a065);
  a065=(a081*a086);
  a160=(a160-a065);
  a146=(a012*a146);
  a160=(a160+a146);
  a146=(a072*a092);
  a160=(a160-a146);
  a146=(a054*a005);
  a160=(a160-a146);
  a146=(a072*a122);
  a160=(a160-a146);
  a158=(a008*a158);
  a160=(a160+a158);
  a158=(a167*a160);
  a158=(a049*a158);
  a146=(a019*a158);
  a160=(a160/a053);
  a146=(a146-a160);
  a065=(a032*a146);
  a120=(a045*a065);
  a087=(a027*a146);
  a305=(a020*a087);
  a305=(a042*a305);
  a120=(a120+a305);
  a305=(a039*a087);
  a120=(a120+a305);
  a305=(a020*a146);
  a305=(a036*a305);
  a120=(a120+a305);
  a305=(a033*a146);
  a120=(a120+a305);
  a305=(a032*a160);
  a131=(a029*a305);
  a120=(a120+a131);
  a131=(a027*a160);
  a126=(a020*a131);
  a126=(a025*a126);
  a120=(a120+a126);
  a126=(a022*a131);
  a120=(a120+a126);
  a158=(a034*a158);
  a065=(a047*a065);
  a126=(a046*a146);
  a126=(a180*a126);
  a084=(a040*a146);
  a126=(a126+a084);
  a126=(a179*a126);
  a065=(a065+a126);
  a087=(a043*a087);
  a065=(a065+a087);
  a146=(a037*a146);
  a065=(a065+a146);
  a065=(a013*a065);
  a158=(a158+a065);
  a305=(a031*a305);
  a065=(a030*a160);
  a065=(a180*a065);
  a146=(a023*a160);
  a065=(a065+a146);
  a065=(a179*a065);
  a305=(a305+a065);
  a131=(a026*a131);
  a305=(a305+a131);
  a131=(a017*a160);
  a305=(a305+a131);
  a305=(a013*a305);
  a158=(a158+a305);
  a158=(a018*a158);
  a120=(a120+a158);
  a158=(a020*a160);
  a158=(a016*a158);
  a120=(a120+a158);
  a160=(a001*a160);
  a120=(a120+a160);
  a160=(a161*a120);
  a309=(a309+a160);
  a160=(a058*a309);
  a341=(a056*a341);
  a341=(a341+a074);
  a010=(a011*a010);
  a341=(a341-a010);
  a005=(a148*a005);
  a341=(a341+a005);
  a092=(a048*a092);
  a122=(a048*a122);
  a092=(a092+a122);
  a122=(a004*a092);
  a341=(a341-a122);
  a136=(a048*a136);
  a134=(a136+a134);
  a134=(a189*a134);
  a341=(a341+a134);
  a134=(a189*a120);
  a341=(a341+a134);
  a134=(a187*a341);
  a160=(a160+a134);
  a132=(a148*a132);
  a086=(a056*a086);
  a132=(a132+a086);
  a136=(a136+a129);
  a136=(a193*a136);
  a132=(a132+a136);
  a132=(a132+a059);
  a127=(a011*a127);
  a132=(a132-a127);
  a092=(a007*a092);
  a132=(a132-a092);
  a120=(a193*a120);
  a132=(a132+a120);
  a120=(a191*a132);
  a160=(a160+a120);
  a080=(a163*a080);
  a080=(a195*a080);
  a160=(a160-a080);
  a160=(a160/a002);
  if (res[1]!=0) res[1][45]=a160;
  a160=(a203*a309);
  a080=(a205*a341);
  a160=(a160+a080);
  a092=(a208*a132);
  a160=(a160+a092);
  a083=(a163*a083);
  a083=(a195*a083);
  a160=(a160-a083);
  a160=(a160/a002);
  if (res[1]!=0) res[1][46]=a160;
  a160=(a204*a309);
  a083=(a196*a341);
  a083=(a160+a083);
  a092=(a212*a132);
  a083=(a083+a092);
  a068=(a163*a068);
  a068=(a195*a068);
  a083=(a083-a068);
  a083=(a083/a002);
  if (res[1]!=0) res[1][47]=a083;
  a083=(a128*a340);
  a151=(a151-a083);
  a213=(a213*a188);
  a115=(a115*a311);
  a083=(a101*a350);
  a115=(a115+a083);
  a109=(a109*a115);
  a213=(a213+a109);
  a109=(a091*a213);
  a151=(a151-a109);
  a151=(a202*a151);
  a109=(a125*a340);
  a115=(a096*a213);
  a214=(a214-a115);
  a115=(a109+a214);
  a115=(a194*a115);
  a119=(a119*a209);
  a083=(a097*a340);
  a083=(a119-a083);
  a083=(a201*a083);
  a115=(a115+a083);
  a151=(a151-a115);
  a151=(a195*a151);
  a115=(a163*a280);
  a115=(a195*a115);
  a151=(a151-a115);
  a350=(a350-a306);
  a350=(a350/a099);
  a188=(a049*a188);
  a115=(a229*a188);
  a350=(a350+a115);
  a115=(a117*a350);
  a115=(a115+a183);
  a183=(a079*a115);
  a083=(a137*a350);
  a068=(a133*a197);
  a172=(a018*a172);
  a066=(a078*a066);
  a172=(a172+a066);
  a066=(a124*a172);
  a068=(a068+a066);
  a066=(a110*a068);
  a083=(a083+a066);
  a066=(a144*a350);
  a092=(a141*a003);
  a121=(a018*a121);
  a177=(a078*a177);
  a121=(a121+a177);
  a177=(a118*a121);
  a092=(a092+a177);
  a177=(a110*a092);
  a066=(a066+a177);
  a083=(a083+a066);
  a066=(a093*a083);
  a064=(a064-a066);
  a066=(a141*a280);
  a177=(a069*a121);
  a066=(a066+a177);
  a177=(a148*a066);
  a064=(a064+a177);
  a177=(a221*a350);
  a127=(a133*a280);
  a059=(a069*a172);
  a127=(a127+a059);
  a059=(a110*a127);
  a177=(a177+a059);
  a059=(a156*a350);
  a136=(a153*a003);
  a076=(a018*a076);
  a078=(a078*a090);
  a076=(a076+a078);
  a078=(a118*a076);
  a136=(a136+a078);
  a078=(a110*a136);
  a059=(a059+a078);
  a177=(a177+a059);
  a059=(a091*a177);
  a064=(a064-a059);
  a059=(a153*a197);
  a078=(a124*a076);
  a059=(a059+a078);
  a078=(a056*a059);
  a064=(a064+a078);
  a228=(a228*a327);
  a327=(a224*a350);
  a141=(a141*a197);
  a121=(a124*a121);
  a141=(a141+a121);
  a121=(a110*a141);
  a327=(a327+a121);
  a121=(a226*a350);
  a153=(a153*a280);
  a076=(a069*a076);
  a153=(a153+a076);
  a076=(a110*a153);
  a121=(a121+a076);
  a076=(a327+a121);
  a076=(a223*a076);
  a228=(a228+a076);
  a064=(a064+a228);
  a228=(a233*a271);
  a311=(a232*a311);
  a076=(a350/a099);
  a322=(a322*a188);
  a076=(a076+a322);
  a231=(a231*a076);
  a133=(a133*a003);
  a172=(a118*a172);
  a133=(a133+a172);
  a172=(a095*a133);
  a137=(a137*a296);
  a076=(a128*a068);
  a137=(a137+a076);
  a172=(a172-a137);
  a221=(a221*a299);
  a137=(a117*a127);
  a221=(a221+a137);
  a172=(a172-a221);
  a144=(a144*a296);
  a296=(a128*a092);
  a144=(a144+a296);
  a172=(a172-a144);
  a224=(a224*a209);
  a141=(a097*a141);
  a224=(a224+a141);
  a172=(a172+a224);
  a224=(a125*a066);
  a172=(a172-a224);
  a156=(a156*a299);
  a299=(a117*a136);
  a156=(a156+a299);
  a172=(a172-a156);
  a156=(a125*a059);
  a172=(a172-a156);
  a226=(a226*a209);
  a153=(a094*a153);
  a226=(a226+a153);
  a172=(a172+a226);
  a226=(a229*a172);
  a231=(a231+a226);
  a231=(a049*a231);
  a226=(a101*a231);
  a311=(a311+a226);
  a172=(a172/a099);
  a198=(a198*a188);
  a172=(a172+a198);
  a311=(a311-a172);
  a198=(a107*a311);
  a228=(a228+a198);
  a198=(a045*a228);
  a188=(a237*a347);
  a226=(a233*a251);
  a153=(a105*a311);
  a226=(a226+a153);
  a153=(a102*a226);
  a188=(a188+a153);
  a188=(a042*a188);
  a198=(a198+a188);
  a188=(a039*a226);
  a198=(a198+a188);
  a188=(a233*a347);
  a153=(a102*a311);
  a188=(a188+a153);
  a188=(a036*a188);
  a198=(a198+a188);
  a188=(a033*a311);
  a198=(a198+a188);
  a271=(a234*a271);
  a188=(a107*a172);
  a271=(a271+a188);
  a188=(a029*a271);
  a198=(a198+a188);
  a188=(a239*a347);
  a153=(a234*a251);
  a156=(a105*a172);
  a153=(a153+a156);
  a156=(a102*a153);
  a188=(a188+a156);
  a188=(a025*a188);
  a198=(a198+a188);
  a188=(a022*a153);
  a198=(a198+a188);
  a232=(a232*a306);
  a231=(a108*a231);
  a232=(a232+a231);
  a231=(a056*a209);
  a235=(a235*a231);
  a228=(a047*a228);
  a306=(2.*a347);
  a244=(a244*a306);
  a251=(2.*a251);
  a243=(a243*a251);
  a206=(a233*a206);
  a188=(a106*a311);
  a206=(a206+a188);
  a206=(a242*a206);
  a243=(a243+a206);
  a149=(a233*a149);
  a206=(a103*a311);
  a149=(a149+a206);
  a243=(a243+a149);
  a243=(a241*a243);
  a244=(a244+a243);
  a228=(a228+a244);
  a237=(a237*a249);
  a226=(a104*a226);
  a237=(a237+a226);
  a228=(a228+a237);
  a233=(a233*a351);
  a311=(a100*a311);
  a233=(a233+a311);
  a228=(a228+a233);
  a228=(a098*a228);
  a235=(a235+a228);
  a232=(a232+a235);
  a238=(a238*a231);
  a271=(a031*a271);
  a246=(a246*a306);
  a245=(a245*a251);
  a240=(a234*a240);
  a251=(a114*a172);
  a240=(a240+a251);
  a240=(a242*a240);
  a245=(a245+a240);
  a216=(a234*a216);
  a240=(a112*a172);
  a216=(a216+a240);
  a245=(a245+a216);
  a245=(a241*a245);
  a246=(a246+a245);
  a271=(a271+a246);
  a239=(a239*a329);
  a153=(a113*a153);
  a239=(a239+a153);
  a271=(a271+a239);
  a300=(a234*a300);
  a239=(a111*a172);
  a300=(a300+a239);
  a271=(a271+a300);
  a271=(a098*a271);
  a238=(a238+a271);
  a232=(a232+a238);
  a232=(a018*a232);
  a198=(a198+a232);
  a234=(a234*a347);
  a347=(a102*a172);
  a234=(a234+a347);
  a234=(a016*a234);
  a198=(a198+a234);
  a172=(a001*a172);
  a198=(a198+a172);
  a172=(a223*a198);
  a236=(a236+a172);
  a064=(a064+a236);
  a236=(a219*a064);
  a236=(a183+a236);
  a151=(a151+a236);
  a236=(a125*a350);
  a172=(a236-a286);
  a172=(a143*a172);
  a127=(a056*a127);
  a082=(a082+a127);
  a083=(a096*a083);
  a220=(a220+a083);
  a082=(a082-a220);
  a136=(a148*a136);
  a082=(a082+a136);
  a145=(a145*a350);
  a066=(a110*a066);
  a145=(a145+a066);
  a157=(a157*a350);
  a059=(a110*a059);
  a157=(a157+a059);
  a145=(a145+a157);
  a157=(a091*a145);
  a082=(a082-a157);
  a230=(a230*a350);
  a133=(a110*a133);
  a230=(a230+a133);
  a121=(a230+a121);
  a121=(a250*a121);
  a082=(a082+a121);
  a121=(a250*a198);
  a082=(a082+a121);
  a121=(a248*a082);
  a172=(a172+a121);
  a151=(a151+a172);
  a068=(a148*a068);
  a135=(a135+a068);
  a092=(a056*a092);
  a135=(a135+a092);
  a230=(a230+a327);
  a230=(a253*a230);
  a135=(a135+a230);
  a177=(a096*a177);
  a222=(a222+a177);
  a135=(a135-a222);
  a145=(a093*a145);
  a135=(a135-a145);
  a198=(a253*a198);
  a135=(a135+a198);
  a198=(a252*a135);
  a145=(a094*a350);
  a209=(a110*a209);
  a145=(a145+a209);
  a145=(a155*a145);
  a198=(a198-a145);
  a151=(a151+a198);
  a151=(a151/a002);
  if (res[1]!=0) res[1][48]=a151;
  a151=(a128*a350);
  a151=(a151+a192);
  a192=(a079*a151);
  a145=(a255*a064);
  a145=(a192+a145);
  a197=(a163*a197);
  a197=(a195*a197);
  a214=(a214-a109);
  a201=(a201*a214);
  a214=(a094*a340);
  a119=(a119-a214);
  a194=(a194*a119);
  a201=(a201-a194);
  a340=(a117*a340);
  a067=(a067-a340);
  a213=(a093*a213);
  a067=(a067+a213);
  a202=(a202*a067);
  a201=(a201+a202);
  a201=(a195*a201);
  a197=(a197+a201);
  a145=(a145-a197);
  a197=(a257*a082);
  a201=(a097*a350);
  a201=(a201+a209);
  a201=(a143*a201);
  a197=(a197-a201);
  a145=(a145+a197);
  a201=(a236-a195);
  a201=(a155*a201);
  a209=(a210*a135);
  a201=(a201+a209);
  a145=(a145+a201);
  a145=(a145/a002);
  if (res[1]!=0) res[1][49]=a145;
  a145=(a256*a064);
  a350=(a095*a350);
  a079=(a079*a350);
  a145=(a145-a079);
  a163=(a163*a003);
  a163=(a195*a163);
  a163=(a145-a163);
  a151=(a143*a151);
  a003=(a262*a082);
  a003=(a151+a003);
  a163=(a163+a003);
  a115=(a155*a115);
  a003=(a264*a135);
  a003=(a115+a003);
  a163=(a163+a003);
  a163=(a163/a002);
  if (res[1]!=0) res[1][50]=a163;
  a123=(a123*a077);
  a077=(a001*a123);
  a163=(a016*a123);
  a163=(a276*a163);
  a003=(a018*a123);
  a273=(a273*a003);
  a015=(a015*a273);
  a163=(a163+a015);
  a077=(a077+a163);
  a163=(a022*a123);
  a015=(a025*a123);
  a015=(a276*a015);
  a024=(a024*a273);
  a015=(a015+a024);
  a163=(a163+a015);
  a163=(a277*a163);
  a317=(a317*a273);
  a021=(a021*a317);
  a163=(a163+a021);
  a077=(a077+a163);
  a163=(a029*a123);
  a021=(a031*a273);
  a163=(a163+a021);
  a163=(a278*a163);
  a325=(a325*a317);
  a028=(a028*a325);
  a163=(a163+a028);
  a077=(a077+a163);
  a163=(a033*a123);
  a028=(a036*a123);
  a028=(a276*a028);
  a035=(a035*a273);
  a028=(a028+a035);
  a163=(a163+a028);
  a028=(a039*a123);
  a035=(a042*a123);
  a276=(a276*a035);
  a041=(a041*a273);
  a276=(a276+a041);
  a028=(a028+a276);
  a277=(a277*a028);
  a038=(a038*a317);
  a277=(a277+a038);
  a163=(a163+a277);
  a277=(a045*a123);
  a273=(a047*a273);
  a277=(a277+a273);
  a278=(a278*a277);
  a044=(a044*a325);
  a278=(a278+a044);
  a163=(a163+a278);
  a077=(a077-a163);
  a077=(a077/a279);
  a051=(a051*a003);
  a275=(a275*a163);
  a051=(a051+a275);
  a051=(a049*a051);
  a297=(a297*a051);
  a077=(a077+a297);
  a274=(a274*a077);
  a274=(a274+a267);
  a267=(a088*a274);
  a283=(a283*a077);
  a336=(a336+a283);
  a336=(a140*a336);
  a267=(a267+a336);
  a269=(a269*a077);
  a000=(a000*a123);
  a269=(a269+a000);
  a269=(a152*a269);
  a267=(a267-a269);
  a269=(a218*a064);
  a183=(a183+a269);
  a267=(a267+a183);
  a286=(a286+a236);
  a143=(a143*a286);
  a286=(a247*a082);
  a143=(a143+a286);
  a267=(a267+a143);
  a267=(a267+a198);
  a198=(a057*a309);
  a267=(a267+a198);
  a198=(a186*a341);
  a267=(a267+a198);
  a267=(a267+a120);
  a267=(-a267);
  if (res[1]!=0) res[1][51]=a267;
  a154=(a154*a077);
  a154=(a154+a265);
  a265=(a088*a154);
  a272=(a272*a077);
  a272=(a272+a000);
  a272=(a140*a272);
  a265=(a265-a272);
  a301=(a301+a283);
  a301=(a152*a301);
  a265=(a265+a301);
  a064=(a254*a064);
  a192=(a192+a064);
  a265=(a265+a192);
  a265=(a265+a197);
  a236=(a195+a236);
  a155=(a155*a236);
  a236=(a215*a135);
  a155=(a155+a236);
  a265=(a265+a155);
  a309=(a200*a309);
  a265=(a265+a309);
  a265=(a265+a080);
  a080=(a207*a132);
  a265=(a265+a080);
  a265=(-a265);
  if (res[1]!=0) res[1][52]=a265;
  a140=(a140*a154);
  a270=(a270*a077);
  a088=(a088*a270);
  a140=(a140-a088);
  a152=(a152*a274);
  a140=(a140+a152);
  a140=(a140+a145);
  a082=(a261*a082);
  a151=(a151+a082);
  a140=(a140+a151);
  a135=(a263*a135);
  a115=(a115+a135);
  a140=(a140+a115);
  a140=(a140+a160);
  a341=(a199*a341);
  a140=(a140+a341);
  a132=(a211*a132);
  a140=(a140+a132);
  a140=(-a140);
  if (res[1]!=0) res[1][53]=a140;
  a140=-9.3301270189221941e-01;
  a140=(a140*a002);
  a140=(a195+a140);
  a132=4.3301270189221935e-01;
  a132=(a132*a002);
  a140=(a140+a132);
  a071=(a071*a140);
  a132=(a056*a071);
  a061=(a061*a140);
  a341=(a048*a061);
  a160=(a004*a341);
  a132=(a132-a160);
  a070=(a070*a140);
  a140=(a048*a070);
  a160=(a161*a140);
  a132=(a132+a160);
  a008=(a008*a070);
  a160=(a054*a061);
  a115=(a072*a071);
  a160=(a160+a115);
  a008=(a008-a160);
  a160=(a167*a008);
  a160=(a049*a160);
  a115=(a019*a160);
  a008=(a008/a053);
  a115=(a115-a008);
  a135=(a032*a115);
  a151=(a045*a135);
  a082=(a027*a115);
  a145=(a020*a082);
  a145=(a042*a145);
  a151=(a151+a145);
  a145=(a039*a082);
  a151=(a151+a145);
  a145=(a020*a115);
  a145=(a036*a145);
  a151=(a151+a145);
  a145=(a033*a115);
  a151=(a151+a145);
  a145=(a032*a008);
  a152=(a029*a145);
  a151=(a151+a152);
  a152=(a027*a008);
  a274=(a020*a152);
  a274=(a025*a274);
  a151=(a151+a274);
  a274=(a022*a152);
  a151=(a151+a274);
  a160=(a034*a160);
  a135=(a047*a135);
  a274=(a046*a115);
  a274=(a180*a274);
  a088=(a040*a115);
  a274=(a274+a088);
  a274=(a179*a274);
  a135=(a135+a274);
  a082=(a043*a082);
  a135=(a135+a082);
  a115=(a037*a115);
  a135=(a135+a115);
  a135=(a013*a135);
  a160=(a160+a135);
  a145=(a031*a145);
  a135=(a030*a008);
  a135=(a180*a135);
  a115=(a023*a008);
  a135=(a135+a115);
  a135=(a179*a135);
  a145=(a145+a135);
  a152=(a026*a152);
  a145=(a145+a152);
  a152=(a017*a008);
  a145=(a145+a152);
  a145=(a013*a145);
  a160=(a160+a145);
  a160=(a018*a160);
  a151=(a151+a160);
  a160=(a020*a008);
  a160=(a016*a160);
  a151=(a151+a160);
  a008=(a001*a008);
  a151=(a151+a008);
  a008=(a161*a151);
  a132=(a132+a008);
  a008=(a058*a132);
  a160=(a148*a061);
  a048=(a048*a071);
  a145=(a004*a048);
  a160=(a160-a145);
  a145=(a189*a140);
  a160=(a160+a145);
  a145=(a189*a151);
  a160=(a160+a145);
  a145=(a187*a160);
  a008=(a008+a145);
  a145=(a011*a341);
  a145=(a075-a145);
  a152=(a007*a048);
  a135=(a145-a152);
  a151=(a193*a151);
  a135=(a135+a151);
  a151=(a191*a135);
  a008=(a008+a151);
  a008=(a008/a002);
  if (res[1]!=0) res[1][54]=a008;
  a008=(a203*a132);
  a115=(a205*a160);
  a008=(a008+a115);
  a082=(a208*a135);
  a008=(a008+a082);
  a008=(a008/a002);
  if (res[1]!=0) res[1][55]=a008;
  a008=(a204*a132);
  a082=(a196*a160);
  a082=(a008+a082);
  a274=(a212*a135);
  a082=(a082+a274);
  a082=(a082/a002);
  if (res[1]!=0) res[1][56]=a082;
  a082=-4.3301270189221935e-01;
  a082=(a082*a002);
  a195=(a195+a082);
  a082=-6.6987298107780674e-02;
  a082=(a082*a002);
  a195=(a195+a082);
  a124=(a124*a195);
  a082=(a056*a124);
  a118=(a118*a195);
  a274=(a110*a118);
  a088=(a091*a274);
  a082=(a082-a088);
  a069=(a069*a195);
  a195=(a110*a069);
  a088=(a223*a195);
  a082=(a082+a088);
  a094=(a094*a069);
  a088=(a117*a118);
  a270=(a125*a124);
  a088=(a088+a270);
  a094=(a094-a088);
  a088=(a229*a094);
  a088=(a049*a088);
  a270=(a101*a088);
  a094=(a094/a099);
  a270=(a270-a094);
  a077=(a107*a270);
  a154=(a045*a077);
  a265=(a105*a270);
  a080=(a102*a265);
  a080=(a042*a080);
  a154=(a154+a080);
  a080=(a039*a265);
  a154=(a154+a080);
  a080=(a102*a270);
  a080=(a036*a080);
  a154=(a154+a080);
  a080=(a033*a270);
  a154=(a154+a080);
  a080=(a107*a094);
  a309=(a029*a080);
  a154=(a154+a309);
  a309=(a105*a094);
  a155=(a102*a309);
  a155=(a025*a155);
  a154=(a154+a155);
  a155=(a022*a309);
  a154=(a154+a155);
  a088=(a108*a088);
  a077=(a047*a077);
  a155=(a106*a270);
  a155=(a242*a155);
  a236=(a103*a270);
  a155=(a155+a236);
  a155=(a241*a155);
  a077=(a077+a155);
  a265=(a104*a265);
  a077=(a077+a265);
  a270=(a100*a270);
  a077=(a077+a270);
  a077=(a098*a077);
  a088=(a088+a077);
  a080=(a031*a080);
  a077=(a114*a094);
  a077=(a242*a077);
  a270=(a112*a094);
  a077=(a077+a270);
  a077=(a241*a077);
  a080=(a080+a077);
  a309=(a113*a309);
  a080=(a080+a309);
  a309=(a111*a094);
  a080=(a080+a309);
  a080=(a098*a080);
  a088=(a088+a080);
  a088=(a018*a088);
  a154=(a154+a088);
  a088=(a102*a094);
  a088=(a016*a088);
  a154=(a154+a088);
  a094=(a001*a094);
  a154=(a154+a094);
  a094=(a223*a154);
  a082=(a082+a094);
  a094=(a219*a082);
  a088=(a148*a118);
  a110=(a110*a124);
  a080=(a091*a110);
  a088=(a088-a080);
  a080=(a250*a195);
  a088=(a088+a080);
  a080=(a250*a154);
  a088=(a088+a080);
  a080=(a248*a088);
  a094=(a094+a080);
  a080=(a096*a274);
  a080=(a328-a080);
  a309=(a093*a110);
  a077=(a080-a309);
  a154=(a253*a154);
  a077=(a077+a154);
  a154=(a252*a077);
  a094=(a094+a154);
  a094=(a094/a002);
  if (res[1]!=0) res[1][57]=a094;
  a094=(a255*a082);
  a270=(a257*a088);
  a094=(a094+a270);
  a265=(a210*a077);
  a094=(a094+a265);
  a094=(a094/a002);
  if (res[1]!=0) res[1][58]=a094;
  a094=(a256*a082);
  a265=(a262*a088);
  a265=(a094+a265);
  a155=(a264*a077);
  a265=(a265+a155);
  a265=(a265/a002);
  if (res[1]!=0) res[1][59]=a265;
  a265=(a218*a082);
  a285=(a285+a265);
  a265=(a247*a088);
  a285=(a285+a265);
  a285=(a285+a154);
  a154=(a057*a132);
  a285=(a285+a154);
  a154=(a186*a160);
  a285=(a285+a154);
  a285=(a285+a151);
  a285=(-a285);
  if (res[1]!=0) res[1][60]=a285;
  a082=(a254*a082);
  a287=(a287+a082);
  a287=(a287+a270);
  a270=(a215*a077);
  a287=(a287+a270);
  a132=(a200*a132);
  a287=(a287+a132);
  a287=(a287+a115);
  a115=(a207*a135);
  a287=(a287+a115);
  a287=(-a287);
  if (res[1]!=0) res[1][61]=a287;
  a225=(a225+a094);
  a088=(a261*a088);
  a225=(a225+a088);
  a077=(a263*a077);
  a225=(a225+a077);
  a225=(a225+a008);
  a160=(a199*a160);
  a225=(a225+a160);
  a135=(a211*a135);
  a225=(a225+a135);
  a225=(-a225);
  if (res[1]!=0) res[1][62]=a225;
  a225=(a148*a070);
  a135=(a007*a341);
  a225=(a225-a135);
  a135=(a161*a048);
  a225=(a225+a135);
  a012=(a012*a071);
  a135=(a081*a061);
  a012=(a012-a135);
  a072=(a072*a070);
  a012=(a012-a072);
  a072=(a167*a012);
  a072=(a049*a072);
  a135=(a019*a072);
  a012=(a012/a053);
  a135=(a135-a012);
  a160=(a032*a135);
  a008=(a045*a160);
  a077=(a027*a135);
  a088=(a020*a077);
  a088=(a042*a088);
  a008=(a008+a088);
  a088=(a039*a077);
  a008=(a008+a088);
  a088=(a020*a135);
  a088=(a036*a088);
  a008=(a008+a088);
  a088=(a033*a135);
  a008=(a008+a088);
  a088=(a032*a012);
  a094=(a029*a088);
  a008=(a008+a094);
  a094=(a027*a012);
  a287=(a020*a094);
  a287=(a025*a287);
  a008=(a008+a287);
  a287=(a022*a094);
  a008=(a008+a287);
  a072=(a034*a072);
  a160=(a047*a160);
  a287=(a046*a135);
  a287=(a180*a287);
  a115=(a040*a135);
  a287=(a287+a115);
  a287=(a179*a287);
  a160=(a160+a287);
  a077=(a043*a077);
  a160=(a160+a077);
  a135=(a037*a135);
  a160=(a160+a135);
  a160=(a013*a160);
  a072=(a072+a160);
  a088=(a031*a088);
  a160=(a030*a012);
  a160=(a180*a160);
  a135=(a023*a012);
  a160=(a160+a135);
  a160=(a179*a160);
  a088=(a088+a160);
  a094=(a026*a094);
  a088=(a088+a094);
  a094=(a017*a012);
  a088=(a088+a094);
  a088=(a013*a088);
  a072=(a072+a088);
  a072=(a018*a072);
  a008=(a008+a072);
  a072=(a020*a012);
  a072=(a016*a072);
  a008=(a008+a072);
  a012=(a001*a012);
  a008=(a008+a012);
  a012=(a161*a008);
  a225=(a225+a012);
  a012=(a058*a225);
  a004=(a004*a140);
  a145=(a145-a004);
  a072=(a189*a008);
  a145=(a145+a072);
  a072=(a187*a145);
  a012=(a012+a072);
  a072=(a056*a061);
  a088=(a193*a048);
  a072=(a072+a088);
  a007=(a007*a140);
  a072=(a072-a007);
  a008=(a193*a008);
  a072=(a072+a008);
  a008=(a191*a072);
  a012=(a012+a008);
  a012=(a012/a002);
  if (res[1]!=0) res[1][63]=a012;
  a012=(a203*a225);
  a007=(a205*a145);
  a012=(a012+a007);
  a088=(a208*a072);
  a012=(a012+a088);
  a012=(a012/a002);
  if (res[1]!=0) res[1][64]=a012;
  a012=(a204*a225);
  a088=(a196*a145);
  a088=(a012+a088);
  a094=(a212*a072);
  a088=(a088+a094);
  a088=(a088/a002);
  if (res[1]!=0) res[1][65]=a088;
  a088=(a148*a069);
  a094=(a093*a274);
  a088=(a088-a094);
  a094=(a223*a110);
  a088=(a088+a094);
  a097=(a097*a124);
  a094=(a128*a118);
  a097=(a097-a094);
  a125=(a125*a069);
  a097=(a097-a125);
  a125=(a229*a097);
  a125=(a049*a125);
  a094=(a101*a125);
  a097=(a097/a099);
  a094=(a094-a097);
  a160=(a107*a094);
  a135=(a045*a160);
  a077=(a105*a094);
  a287=(a102*a077);
  a287=(a042*a287);
  a135=(a135+a287);
  a287=(a039*a077);
  a135=(a135+a287);
  a287=(a102*a094);
  a287=(a036*a287);
  a135=(a135+a287);
  a287=(a033*a094);
  a135=(a135+a287);
  a287=(a107*a097);
  a115=(a029*a287);
  a135=(a135+a115);
  a115=(a105*a097);
  a132=(a102*a115);
  a132=(a025*a132);
  a135=(a135+a132);
  a132=(a022*a115);
  a135=(a135+a132);
  a125=(a108*a125);
  a160=(a047*a160);
  a132=(a106*a094);
  a132=(a242*a132);
  a270=(a103*a094);
  a132=(a132+a270);
  a132=(a241*a132);
  a160=(a160+a132);
  a077=(a104*a077);
  a160=(a160+a077);
  a094=(a100*a094);
  a160=(a160+a094);
  a160=(a098*a160);
  a125=(a125+a160);
  a287=(a031*a287);
  a160=(a114*a097);
  a160=(a242*a160);
  a094=(a112*a097);
  a160=(a160+a094);
  a160=(a241*a160);
  a287=(a287+a160);
  a115=(a113*a115);
  a287=(a287+a115);
  a115=(a111*a097);
  a287=(a287+a115);
  a287=(a098*a287);
  a125=(a125+a287);
  a125=(a018*a125);
  a135=(a135+a125);
  a125=(a102*a097);
  a125=(a016*a125);
  a135=(a135+a125);
  a097=(a001*a097);
  a135=(a135+a097);
  a097=(a223*a135);
  a088=(a088+a097);
  a097=(a219*a088);
  a091=(a091*a195);
  a080=(a080-a091);
  a125=(a250*a135);
  a080=(a080+a125);
  a125=(a248*a080);
  a097=(a097+a125);
  a125=(a056*a118);
  a287=(a253*a110);
  a125=(a125+a287);
  a093=(a093*a195);
  a125=(a125-a093);
  a135=(a253*a135);
  a125=(a125+a135);
  a135=(a252*a125);
  a097=(a097+a135);
  a097=(a097/a002);
  if (res[1]!=0) res[1][66]=a097;
  a097=(a255*a088);
  a093=(a257*a080);
  a097=(a097+a093);
  a287=(a210*a125);
  a097=(a097+a287);
  a097=(a097/a002);
  if (res[1]!=0) res[1][67]=a097;
  a097=(a256*a088);
  a287=(a262*a080);
  a287=(a097+a287);
  a115=(a264*a125);
  a287=(a287+a115);
  a287=(a287/a002);
  if (res[1]!=0) res[1][68]=a287;
  a287=(a218*a088);
  a282=(a282+a287);
  a287=(a247*a080);
  a282=(a282+a287);
  a282=(a282+a135);
  a135=(a057*a225);
  a282=(a282+a135);
  a135=(a186*a145);
  a282=(a282+a135);
  a282=(a282+a008);
  a282=(-a282);
  if (res[1]!=0) res[1][69]=a282;
  a088=(a254*a088);
  a268=(a268+a088);
  a268=(a268+a093);
  a093=(a215*a125);
  a268=(a268+a093);
  a225=(a200*a225);
  a268=(a268+a225);
  a268=(a268+a007);
  a007=(a207*a072);
  a268=(a268+a007);
  a268=(-a268);
  if (res[1]!=0) res[1][70]=a268;
  a185=(a185+a097);
  a080=(a261*a080);
  a185=(a185+a080);
  a125=(a263*a125);
  a185=(a185+a125);
  a185=(a185+a012);
  a145=(a199*a145);
  a185=(a185+a145);
  a072=(a211*a072);
  a185=(a185+a072);
  a185=(-a185);
  if (res[1]!=0) res[1][71]=a185;
  a075=(a075-a152);
  a075=(a075-a004);
  a009=(a009*a061);
  a081=(a081*a071);
  a009=(a009-a081);
  a054=(a054*a070);
  a009=(a009-a054);
  a167=(a167*a009);
  a167=(a049*a167);
  a019=(a019*a167);
  a009=(a009/a053);
  a019=(a019-a009);
  a053=(a032*a019);
  a054=(a045*a053);
  a081=(a027*a019);
  a061=(a020*a081);
  a061=(a042*a061);
  a054=(a054+a061);
  a061=(a039*a081);
  a054=(a054+a061);
  a061=(a020*a019);
  a061=(a036*a061);
  a054=(a054+a061);
  a061=(a033*a019);
  a054=(a054+a061);
  a032=(a032*a009);
  a061=(a029*a032);
  a054=(a054+a061);
  a027=(a027*a009);
  a061=(a020*a027);
  a061=(a025*a061);
  a054=(a054+a061);
  a061=(a022*a027);
  a054=(a054+a061);
  a034=(a034*a167);
  a053=(a047*a053);
  a046=(a046*a019);
  a046=(a180*a046);
  a040=(a040*a019);
  a046=(a046+a040);
  a046=(a179*a046);
  a053=(a053+a046);
  a043=(a043*a081);
  a053=(a053+a043);
  a037=(a037*a019);
  a053=(a053+a037);
  a053=(a013*a053);
  a034=(a034+a053);
  a032=(a031*a032);
  a030=(a030*a009);
  a180=(a180*a030);
  a023=(a023*a009);
  a180=(a180+a023);
  a179=(a179*a180);
  a032=(a032+a179);
  a026=(a026*a027);
  a032=(a032+a026);
  a017=(a017*a009);
  a032=(a032+a017);
  a013=(a013*a032);
  a034=(a034+a013);
  a034=(a018*a034);
  a054=(a054+a034);
  a020=(a020*a009);
  a020=(a016*a020);
  a054=(a054+a020);
  a009=(a001*a009);
  a054=(a054+a009);
  a161=(a161*a054);
  a075=(a075+a161);
  a058=(a058*a075);
  a070=(a056*a070);
  a048=(a011*a048);
  a070=(a070-a048);
  a048=(a189*a341);
  a070=(a070+a048);
  a189=(a189*a054);
  a070=(a070+a189);
  a187=(a187*a070);
  a058=(a058+a187);
  a071=(a148*a071);
  a341=(a193*a341);
  a071=(a071+a341);
  a011=(a011*a140);
  a071=(a071-a011);
  a193=(a193*a054);
  a071=(a071+a193);
  a191=(a191*a071);
  a058=(a058+a191);
  a058=(a058/a002);
  if (res[1]!=0) res[1][72]=a058;
  a203=(a203*a075);
  a205=(a205*a070);
  a203=(a203+a205);
  a208=(a208*a071);
  a203=(a203+a208);
  a203=(a203/a002);
  if (res[1]!=0) res[1][73]=a203;
  a204=(a204*a075);
  a196=(a196*a070);
  a196=(a204+a196);
  a212=(a212*a071);
  a196=(a196+a212);
  a196=(a196/a002);
  if (res[1]!=0) res[1][74]=a196;
  a328=(a328-a309);
  a328=(a328-a091);
  a095=(a095*a118);
  a128=(a128*a124);
  a095=(a095-a128);
  a117=(a117*a069);
  a095=(a095-a117);
  a229=(a229*a095);
  a049=(a049*a229);
  a101=(a101*a049);
  a095=(a095/a099);
  a101=(a101-a095);
  a099=(a107*a101);
  a045=(a045*a099);
  a229=(a105*a101);
  a117=(a102*a229);
  a042=(a042*a117);
  a045=(a045+a042);
  a039=(a039*a229);
  a045=(a045+a039);
  a039=(a102*a101);
  a036=(a036*a039);
  a045=(a045+a036);
  a033=(a033*a101);
  a045=(a045+a033);
  a107=(a107*a095);
  a029=(a029*a107);
  a045=(a045+a029);
  a105=(a105*a095);
  a029=(a102*a105);
  a025=(a025*a029);
  a045=(a045+a025);
  a022=(a022*a105);
  a045=(a045+a022);
  a108=(a108*a049);
  a047=(a047*a099);
  a106=(a106*a101);
  a106=(a242*a106);
  a103=(a103*a101);
  a106=(a106+a103);
  a106=(a241*a106);
  a047=(a047+a106);
  a104=(a104*a229);
  a047=(a047+a104);
  a100=(a100*a101);
  a047=(a047+a100);
  a047=(a098*a047);
  a108=(a108+a047);
  a031=(a031*a107);
  a114=(a114*a095);
  a242=(a242*a114);
  a112=(a112*a095);
  a242=(a242+a112);
  a241=(a241*a242);
  a031=(a031+a241);
  a113=(a113*a105);
  a031=(a031+a113);
  a111=(a111*a095);
  a031=(a031+a111);
  a098=(a098*a031);
  a108=(a108+a098);
  a018=(a018*a108);
  a045=(a045+a018);
  a102=(a102*a095);
  a016=(a016*a102);
  a045=(a045+a016);
  a001=(a001*a095);
  a045=(a045+a001);
  a223=(a223*a045);
  a328=(a328+a223);
  a219=(a219*a328);
  a056=(a056*a069);
  a110=(a096*a110);
  a056=(a056-a110);
  a110=(a250*a274);
  a056=(a056+a110);
  a250=(a250*a045);
  a056=(a056+a250);
  a248=(a248*a056);
  a219=(a219+a248);
  a148=(a148*a124);
  a274=(a253*a274);
  a148=(a148+a274);
  a096=(a096*a195);
  a148=(a148-a096);
  a253=(a253*a045);
  a148=(a148+a253);
  a252=(a252*a148);
  a219=(a219+a252);
  a219=(a219/a002);
  if (res[1]!=0) res[1][75]=a219;
  a255=(a255*a328);
  a257=(a257*a056);
  a255=(a255+a257);
  a210=(a210*a148);
  a255=(a255+a210);
  a255=(a255/a002);
  if (res[1]!=0) res[1][76]=a255;
  a256=(a256*a328);
  a262=(a262*a056);
  a262=(a256+a262);
  a264=(a264*a148);
  a262=(a262+a264);
  a262=(a262/a002);
  if (res[1]!=0) res[1][77]=a262;
  a218=(a218*a328);
  a266=(a266+a218);
  a247=(a247*a056);
  a266=(a266+a247);
  a266=(a266+a252);
  a057=(a057*a075);
  a266=(a266+a057);
  a186=(a186*a070);
  a266=(a266+a186);
  a266=(a266+a191);
  a266=(-a266);
  if (res[1]!=0) res[1][78]=a266;
  a254=(a254*a328);
  a281=(a281+a254);
  a281=(a281+a257);
  a215=(a215*a148);
  a281=(a281+a215);
  a200=(a200*a075);
  a281=(a281+a200);
  a281=(a281+a205);
  a207=(a207*a071);
  a281=(a281+a207);
  a281=(-a281);
  if (res[1]!=0) res[1][79]=a281;
  a050=(a050+a256);
  a261=(a261*a056);
  a050=(a050+a261);
  a263=(a263*a148);
  a050=(a050+a263);
  a050=(a050+a204);
  a199=(a199*a070);
  a050=(a050+a199);
  a211=(a211*a071);
  a050=(a050+a211);
  a050=(-a050);
  if (res[1]!=0) res[1][80]=a050;
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
    case 3: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* residual_jacobian_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s2;
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

/* update:(z[9],g[9],p[3],h[3])->(g1[9],p1[3]) */
static int casadi_f2(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32;
  a00=arg[1]? arg[1][0] : 0;
  a01=1.;
  a02=5.0000000000000000e-01;
  a03=2.5000000000000000e-01;
  a04=arg[3]? arg[3][0] : 0;
  a05=3.0000000000000004e+00;
  a06=arg[0]? arg[0][0] : 0;
  a07=(a05*a06);
  a08=4.6410161513775439e-01;
  a09=arg[0]? arg[0][3] : 0;
  a10=(a08*a09);
  a07=(a07+a10);
  a07=(a02*a07);
  a10=-6.4641016151377553e+00;
  a06=(a10*a06);
  a09=(a05*a09);
  a06=(a06+a09);
  a06=(a02*a06);
  a07=(a07+a06);
  a07=(a04*a07);
  a06=casadi_sq(a07);
  a09=arg[0]? arg[0][1] : 0;
  a11=(a05*a09);
  a12=arg[0]? arg[0][4] : 0;
  a13=(a08*a12);
  a11=(a11+a13);
  a11=(a02*a11);
  a09=(a10*a09);
  a12=(a05*a12);
  a09=(a09+a12);
  a09=(a02*a09);
  a11=(a11+a09);
  a11=(a04*a11);
  a09=casadi_sq(a11);
  a12=(a06+a09);
  a13=arg[0]? arg[0][2] : 0;
  a14=(a05*a13);
  a15=arg[0]? arg[0][5] : 0;
  a08=(a08*a15);
  a14=(a14+a08);
  a14=(a02*a14);
  a10=(a10*a13);
  a05=(a05*a15);
  a10=(a10+a05);
  a10=(a02*a10);
  a14=(a14+a10);
  a04=(a04*a14);
  a14=casadi_sq(a04);
  a10=(a12+a14);
  a03=(a03*a10);
  a05=1.6666666666666666e-01;
  a15=-2.0833333333333333e-03;
  a15=(a15*a10);
  a13=1.9841269841269841e-04;
  a08=-6.8893298059964731e-07;
  a08=(a08*a10);
  a13=(a13+a08);
  a08=casadi_sq(a03);
  a13=(a13*a08);
  a15=(a15+a13);
  a13=2.5052108385441720e-08;
  a16=-4.0147609592054033e-11;
  a16=(a16*a10);
  a13=(a13+a16);
  a16=7.6471637318198164e-13;
  a17=-7.0286431358638015e-16;
  a17=(a17*a10);
  a16=(a16+a17);
  a16=(a16*a08);
  a13=(a13+a16);
  a16=casadi_sq(a08);
  a13=(a13*a16);
  a15=(a15+a13);
  a13=8.2206352466243295e-18;
  a17=-4.8932352658478156e-21;
  a17=(a17*a10);
  a13=(a13+a17);
  a17=3.8681701706306841e-23;
  a17=(a17*a08);
  a13=(a13+a17);
  a17=casadi_sq(a16);
  a13=(a13*a17);
  a15=(a15+a13);
  a05=(a05+a15);
  a05=(a03*a05);
  a05=(a01-a05);
  a13=casadi_sq(a05);
  a13=(a02*a13);
  a09=(a09+a14);
  a18=(a13*a09);
  a18=(a01-a18);
  a19=(a00*a18);
  a20=arg[1]? arg[1][3] : 0;
  a21=-1.0416666666666666e-02;
  a21=(a21*a10);
  a22=1.3888888888888889e-03;
  a23=-6.2003968253968254e-06;
  a23=(a23*a10);
  a22=(a22+a23);
  a22=(a22*a08);
  a21=(a21+a22);
  a22=2.7557319223985888e-07;
  a23=-5.2191892469670250e-10;
  a23=(a23*a10);
  a22=(a22+a23);
  a23=1.1470745597729725e-11;
  a24=-1.1948693330968463e-14;
  a24=(a24*a10);
  a23=(a23+a24);
  a23=(a23*a08);
  a22=(a22+a23);
  a22=(a22*a16);
  a21=(a21+a22);
  a22=1.5619206968586225e-16;
  a16=-1.0275794058280412e-19;
  a16=(a16*a10);
  a22=(a22+a16);
  a16=8.8967913924505741e-22;
  a16=(a16*a08);
  a22=(a22+a16);
  a22=(a22*a17);
  a21=(a21+a22);
  a22=(a02+a21);
  a03=(a03*a22);
  a03=(a01-a03);
  a03=(a05*a03);
  a22=(a03*a04);
  a17=(a07*a11);
  a16=(a13*a17);
  a08=(a22+a16);
  a10=(a20*a08);
  a19=(a19+a10);
  a10=arg[1]? arg[1][6] : 0;
  a23=(a07*a04);
  a24=(a13*a23);
  a25=(a03*a11);
  a26=(a24-a25);
  a27=(a10*a26);
  a19=(a19+a27);
  if (res[0]!=0) res[0][0]=a19;
  a19=arg[1]? arg[1][1] : 0;
  a27=(a19*a18);
  a28=arg[1]? arg[1][4] : 0;
  a29=(a28*a08);
  a27=(a27+a29);
  a29=arg[1]? arg[1][7] : 0;
  a30=(a29*a26);
  a27=(a27+a30);
  if (res[0]!=0) res[0][1]=a27;
  a27=arg[1]? arg[1][2] : 0;
  a18=(a27*a18);
  a30=arg[1]? arg[1][5] : 0;
  a08=(a30*a08);
  a18=(a18+a08);
  a08=arg[1]? arg[1][8] : 0;
  a26=(a08*a26);
  a18=(a18+a26);
  if (res[0]!=0) res[0][2]=a18;
  a16=(a16-a22);
  a22=(a00*a16);
  a14=(a14+a06);
  a06=(a13*a14);
  a06=(a01-a06);
  a18=(a20*a06);
  a22=(a22+a18);
  a03=(a03*a07);
  a18=(a11*a04);
  a26=(a13*a18);
  a31=(a03+a26);
  a32=(a10*a31);
  a22=(a22+a32);
  if (res[0]!=0) res[0][3]=a22;
  a22=(a19*a16);
  a32=(a28*a06);
  a22=(a22+a32);
  a32=(a29*a31);
  a22=(a22+a32);
  if (res[0]!=0) res[0][4]=a22;
  a16=(a27*a16);
  a06=(a30*a06);
  a16=(a16+a06);
  a31=(a08*a31);
  a16=(a16+a31);
  if (res[0]!=0) res[0][5]=a16;
  a25=(a25+a24);
  a00=(a00*a25);
  a26=(a26-a03);
  a20=(a20*a26);
  a00=(a00+a20);
  a13=(a13*a12);
  a13=(a01-a13);
  a10=(a10*a13);
  a00=(a00+a10);
  if (res[0]!=0) res[0][6]=a00;
  a19=(a19*a25);
  a28=(a28*a26);
  a19=(a19+a28);
  a29=(a29*a13);
  a19=(a19+a29);
  if (res[0]!=0) res[0][7]=a19;
  a27=(a27*a25);
  a30=(a30*a26);
  a27=(a27+a30);
  a08=(a08*a13);
  a27=(a27+a08);
  if (res[0]!=0) res[0][8]=a27;
  a27=3.3333333333333331e-01;
  a21=(a21-a15);
  a27=(a27+a21);
  a21=4.;
  a21=(a21*a05);
  a27=(a27/a21);
  a23=(a27*a23);
  a21=(a02*a11);
  a21=(a23-a21);
  a05=arg[0]? arg[0][8] : 0;
  a21=(a21*a05);
  a17=(a27*a17);
  a15=-5.0000000000000000e-01;
  a08=(a15*a04);
  a08=(a17-a08);
  a13=arg[0]? arg[0][7] : 0;
  a08=(a08*a13);
  a21=(a21+a08);
  a09=(a27*a09);
  a09=(a01-a09);
  a08=arg[0]? arg[0][6] : 0;
  a09=(a09*a08);
  a21=(a21+a09);
  if (res[1]!=0) res[1][0]=a21;
  a18=(a27*a18);
  a21=(a15*a07);
  a21=(a18-a21);
  a21=(a21*a05);
  a14=(a27*a14);
  a14=(a01-a14);
  a14=(a14*a13);
  a21=(a21+a14);
  a04=(a02*a04);
  a17=(a17-a04);
  a17=(a17*a08);
  a21=(a21+a17);
  if (res[1]!=0) res[1][1]=a21;
  a27=(a27*a12);
  a01=(a01-a27);
  a01=(a01*a05);
  a02=(a02*a07);
  a18=(a18-a02);
  a18=(a18*a13);
  a01=(a01+a18);
  a15=(a15*a11);
  a23=(a23-a15);
  a23=(a23*a08);
  a01=(a01+a23);
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
    case 3: return casadi_s1;
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

/* guess:(xi[3],g[9],p[3],h[3])->(z0[9]) */
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
    case 3: return casadi_s1;
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

/* legendre:(g[9],xi[3],h[3])->(mu[3]) */
static int casadi_f4(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1;
  a0=arg[1]? arg[1][0] : 0;
  if (res[0]!=0) res[0][0]=a0;
  a0=5.;
  a1=arg[1]? arg[1][1] : 0;
  a0=(a0*a1);
  if (res[0]!=0) res[0][1]=a0;
  a0=6.;
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
    case 2: return casadi_s1;
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

/* hessian:(g[9],xi[3],h[3])->(H[9]) */
static int casadi_f5(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1;
  a0=1.;
  if (res[0]!=0) res[0][0]=a0;
  a0=0.;
  if (res[0]!=0) res[0][1]=a0;
  if (res[0]!=0) res[0][2]=a0;
  if (res[0]!=0) res[0][3]=a0;
  a1=5.;
  if (res[0]!=0) res[0][4]=a1;
  if (res[0]!=0) res[0][5]=a0;
  if (res[0]!=0) res[0][6]=a0;
  if (res[0]!=0) res[0][7]=a0;
  a0=6.;
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
    case 2: return casadi_s1;
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

/* energy:(g[9],xi[3],h[3])->(E) */
static int casadi_f6(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4;
  a0=arg[1]? arg[1][0] : 0;
  a0=casadi_sq(a0);
  a1=5.;
  a2=arg[1]? arg[1][1] : 0;
  a1=(a1*a2);
  a1=(a1*a2);
  a1=(a0+a1);
  a3=6.;
  a4=arg[1]? arg[1][2] : 0;
  a3=(a3*a4);
  a3=(a3*a4);
  a1=(a1+a3);
  a3=5.0000000000000000e-01;
  a3=(a3*a0);
  a0=3.;
  a4=casadi_sq(a4);
  a0=(a0*a4);
  a3=(a3+a0);
  a0=2.5000000000000000e+00;
  a2=casadi_sq(a2);
  a0=(a0*a2);
  a3=(a3+a0);
  a0=arg[0]? arg[0][8] : 0;
  a3=(a3-a0);
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
    case 2: return casadi_s1;
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

/* margin:(z[9],h[3])->(m) */
static int casadi_f9(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14;
  a00=1.;
  a01=9.8696044010893580e+00;
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
  a07=6.2831853071795862e+00;
  a04=(a04/a07);
  a00=casadi_fmin(a00,a04);
  a00=casadi_fmin(a00,a04);
  a04=arg[0]? arg[0][3] : 0;
  a08=(a02*a04);
  a08=casadi_sq(a08);
  a09=arg[0]? arg[0][4] : 0;
  a10=(a02*a09);
  a10=casadi_sq(a10);
  a08=(a08+a10);
  a10=arg[0]? arg[0][5] : 0;
  a11=(a02*a10);
  a11=casadi_sq(a11);
  a08=(a08+a11);
  a08=(a01-a08);
  a08=(a08/a07);
  a00=casadi_fmin(a00,a08);
  a00=casadi_fmin(a00,a08);
  a08=5.0000000000000000e-01;
  a11=3.0000000000000004e+00;
  a12=(a11*a03);
  a13=4.6410161513775439e-01;
  a14=(a13*a04);
  a12=(a12+a14);
  a12=(a08*a12);
  a14=-6.4641016151377553e+00;
  a03=(a14*a03);
  a04=(a11*a04);
  a03=(a03+a04);
  a03=(a08*a03);
  a12=(a12+a03);
  a12=(a02*a12);
  a12=casadi_sq(a12);
  a03=(a11*a05);
  a04=(a13*a09);
  a03=(a03+a04);
  a03=(a08*a03);
  a05=(a14*a05);
  a09=(a11*a09);
  a05=(a05+a09);
  a05=(a08*a05);
  a03=(a03+a05);
  a03=(a02*a03);
  a03=casadi_sq(a03);
  a12=(a12+a03);
  a03=(a11*a06);
  a13=(a13*a10);
  a03=(a03+a13);
  a03=(a08*a03);
  a14=(a14*a06);
  a11=(a11*a10);
  a14=(a14+a11);
  a08=(a08*a14);
  a03=(a03+a08);
  a02=(a02*a03);
  a02=casadi_sq(a02);
  a12=(a12+a02);
  a01=(a01-a12);
  a01=(a01/a07);
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
    case 1: return casadi_s1;
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
    case 0: return casadi_s0;
    case 1: return casadi_s1;
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

/* chart_point:(z[9],g[9],h[3],theta)->(g_theta[9]) */
static int casadi_f11(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  a00=arg[1]? arg[1][0] : 0;
  a01=1.;
  a02=5.0000000000000000e-01;
  a03=2.5000000000000000e-01;
  a04=arg[3]? arg[3][0] : 0;
  a05=arg[2]? arg[2][0] : 0;
  a06=3.0000000000000004e+00;
  a07=arg[0]? arg[0][0] : 0;
  a08=(a06*a07);
  a09=4.6410161513775439e-01;
  a10=arg[0]? arg[0][3] : 0;
  a11=(a09*a10);
  a08=(a08+a11);
  a08=(a02*a08);
  a11=-6.4641016151377553e+00;
  a07=(a11*a07);
  a10=(a06*a10);
  a07=(a07+a10);
  a07=(a02*a07);
  a08=(a08+a07);
  a08=(a05*a08);
  a08=(a04*a08);
  a07=casadi_sq(a08);
  a10=arg[0]? arg[0][1] : 0;
  a12=(a06*a10);
  a13=arg[0]? arg[0][4] : 0;
  a14=(a09*a13);
  a12=(a12+a14);
  a12=(a02*a12);
  a10=(a11*a10);
  a13=(a06*a13);
  a10=(a10+a13);
  a10=(a02*a10);
  a12=(a12+a10);
  a12=(a05*a12);
  a12=(a04*a12);
  a10=casadi_sq(a12);
  a13=(a07+a10);
  a14=arg[0]? arg[0][2] : 0;
  a15=(a06*a14);
  a16=arg[0]? arg[0][5] : 0;
  a09=(a09*a16);
  a15=(a15+a09);
  a15=(a02*a15);
  a11=(a11*a14);
  a06=(a06*a16);
  a11=(a11+a06);
  a11=(a02*a11);
  a15=(a15+a11);
  a05=(a05*a15);
  a04=(a04*a05);
  a05=casadi_sq(a04);
  a15=(a13+a05);
  a03=(a03*a15);
  a11=1.6666666666666666e-01;
  a06=-2.0833333333333333e-03;
  a06=(a06*a15);
  a16=1.9841269841269841e-04;
  a14=-6.8893298059964731e-07;
  a14=(a14*a15);
  a16=(a16+a14);
  a14=casadi_sq(a03);
  a16=(a16*a14);
  a06=(a06+a16);
  a16=2.5052108385441720e-08;
  a09=-4.0147609592054033e-11;
  a09=(a09*a15);
  a16=(a16+a09);
  a09=7.6471637318198164e-13;
  a17=-7.0286431358638015e-16;
  a17=(a17*a15);
  a09=(a09+a17);
  a09=(a09*a14);
  a16=(a16+a09);
  a09=casadi_sq(a14);
  a16=(a16*a09);
  a06=(a06+a16);
  a16=8.2206352466243295e-18;
  a17=-4.8932352658478156e-21;
  a17=(a17*a15);
  a16=(a16+a17);
  a17=3.8681701706306841e-23;
  a17=(a17*a14);
  a16=(a16+a17);
  a17=casadi_sq(a09);
  a16=(a16*a17);
  a06=(a06+a16);
  a11=(a11+a06);
  a11=(a03*a11);
  a11=(a01-a11);
  a06=casadi_sq(a11);
  a06=(a02*a06);
  a10=(a10+a05);
  a10=(a06*a10);
  a10=(a01-a10);
  a16=(a00*a10);
  a18=arg[1]? arg[1][3] : 0;
  a19=-1.0416666666666666e-02;
  a19=(a19*a15);
  a20=1.3888888888888889e-03;
  a21=-6.2003968253968254e-06;
  a21=(a21*a15);
  a20=(a20+a21);
  a20=(a20*a14);
  a19=(a19+a20);
  a20=2.7557319223985888e-07;
  a21=-5.2191892469670250e-10;
  a21=(a21*a15);
  a20=(a20+a21);
  a21=1.1470745597729725e-11;
  a22=-1.1948693330968463e-14;
  a22=(a22*a15);
  a21=(a21+a22);
  a21=(a21*a14);
  a20=(a20+a21);
  a20=(a20*a09);
  a19=(a19+a20);
  a20=1.5619206968586225e-16;
  a09=-1.0275794058280412e-19;
  a09=(a09*a15);
  a20=(a20+a09);
  a09=8.8967913924505741e-22;
  a09=(a09*a14);
  a20=(a20+a09);
  a20=(a20*a17);
  a19=(a19+a20);
  a02=(a02+a19);
  a03=(a03*a02);
  a03=(a01-a03);
  a11=(a11*a03);
  a03=(a11*a04);
  a02=(a08*a12);
  a02=(a06*a02);
  a19=(a03+a02);
  a20=(a18*a19);
  a16=(a16+a20);
  a20=arg[1]? arg[1][6] : 0;
  a17=(a08*a04);
  a17=(a06*a17);
  a09=(a11*a12);
  a14=(a17-a09);
  a15=(a20*a14);
  a16=(a16+a15);
  if (res[0]!=0) res[0][0]=a16;
  a16=arg[1]? arg[1][1] : 0;
  a15=(a16*a10);
  a21=arg[1]? arg[1][4] : 0;
  a22=(a21*a19);
  a15=(a15+a22);
  a22=arg[1]? arg[1][7] : 0;
  a23=(a22*a14);
  a15=(a15+a23);
  if (res[0]!=0) res[0][1]=a15;
  a15=arg[1]? arg[1][2] : 0;
  a10=(a15*a10);
  a23=arg[1]? arg[1][5] : 0;
  a19=(a23*a19);
  a10=(a10+a19);
  a19=arg[1]? arg[1][8] : 0;
  a14=(a19*a14);
  a10=(a10+a14);
  if (res[0]!=0) res[0][2]=a10;
  a02=(a02-a03);
  a03=(a00*a02);
  a05=(a05+a07);
  a05=(a06*a05);
  a05=(a01-a05);
  a07=(a18*a05);
  a03=(a03+a07);
  a11=(a11*a08);
  a12=(a12*a04);
  a12=(a06*a12);
  a04=(a11+a12);
  a08=(a20*a04);
  a03=(a03+a08);
  if (res[0]!=0) res[0][3]=a03;
  a03=(a16*a02);
  a08=(a21*a05);
  a03=(a03+a08);
  a08=(a22*a04);
  a03=(a03+a08);
  if (res[0]!=0) res[0][4]=a03;
  a02=(a15*a02);
  a05=(a23*a05);
  a02=(a02+a05);
  a04=(a19*a04);
  a02=(a02+a04);
  if (res[0]!=0) res[0][5]=a02;
  a09=(a09+a17);
  a00=(a00*a09);
  a12=(a12-a11);
  a18=(a18*a12);
  a00=(a00+a18);
  a06=(a06*a13);
  a01=(a01-a06);
  a20=(a20*a01);
  a00=(a00+a20);
  if (res[0]!=0) res[0][6]=a00;
  a16=(a16*a09);
  a21=(a21*a12);
  a16=(a16+a21);
  a22=(a22*a01);
  a16=(a16+a22);
  if (res[0]!=0) res[0][7]=a16;
  a15=(a15*a09);
  a23=(a23*a12);
  a15=(a15+a23);
  a19=(a19*a01);
  a15=(a15+a19);
  if (res[0]!=0) res[0][8]=a15;
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
    case 2: return casadi_s1;
    case 3: return casadi_s3;
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

/* observe:(g[9],p[3],h[3])->(xi[3],E,m[3],e) */
static int casadi_f12(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17;
  a00=arg[1]? arg[1][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=arg[1]? arg[1][1] : 0;
  a02=5.;
  a02=(a01/a02);
  if (res[0]!=0) res[0][1]=a02;
  a03=arg[1]? arg[1][2] : 0;
  a04=6.;
  a04=(a03/a04);
  if (res[0]!=0) res[0][2]=a04;
  a05=casadi_sq(a00);
  a06=(a01*a02);
  a06=(a05+a06);
  a07=(a03*a04);
  a06=(a06+a07);
  a07=5.0000000000000000e-01;
  a07=(a07*a05);
  a05=3.;
  a04=casadi_sq(a04);
  a05=(a05*a04);
  a07=(a07+a05);
  a05=2.5000000000000000e+00;
  a02=casadi_sq(a02);
  a05=(a05*a02);
  a07=(a07+a05);
  a05=arg[0]? arg[0][8] : 0;
  a07=(a07-a05);
  a06=(a06-a07);
  if (res[1]!=0) res[1][0]=a06;
  a06=arg[0]? arg[0][4] : 0;
  a07=(a05*a06);
  a02=arg[0]? arg[0][7] : 0;
  a04=arg[0]? arg[0][5] : 0;
  a08=(a02*a04);
  a07=(a07-a08);
  a07=(a07*a00);
  a09=arg[0]? arg[0][2] : 0;
  a10=(a09*a02);
  a11=arg[0]? arg[0][1] : 0;
  a12=(a11*a05);
  a10=(a10-a12);
  a10=(a10*a01);
  a07=(a07+a10);
  a10=(a04*a11);
  a13=(a06*a09);
  a10=(a10-a13);
  a10=(a10*a03);
  a07=(a07+a10);
  if (res[2]!=0) res[2][0]=a07;
  a07=arg[0]? arg[0][6] : 0;
  a10=(a07*a04);
  a14=arg[0]? arg[0][3] : 0;
  a15=(a05*a14);
  a10=(a10-a15);
  a10=(a10*a00);
  a15=arg[0]? arg[0][0] : 0;
  a16=(a15*a05);
  a17=(a09*a07);
  a16=(a16-a17);
  a16=(a16*a01);
  a10=(a10+a16);
  a16=(a14*a09);
  a17=(a04*a15);
  a16=(a16-a17);
  a16=(a16*a03);
  a10=(a10+a16);
  if (res[2]!=0) res[2][1]=a10;
  a10=(a02*a14);
  a16=(a07*a06);
  a10=(a10-a16);
  a10=(a10*a00);
  a00=(a11*a07);
  a16=(a15*a02);
  a00=(a00-a16);
  a00=(a00*a01);
  a10=(a10+a00);
  a00=(a06*a15);
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
  a01=(a06*a11);
  a03=(a03+a01);
  a01=(a04*a09);
  a03=(a03+a01);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=(a07*a15);
  a01=(a02*a11);
  a03=(a03+a01);
  a01=(a05*a09);
  a03=(a03+a01);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=(a15*a14);
  a01=(a11*a06);
  a03=(a03+a01);
  a01=(a09*a04);
  a03=(a03+a01);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=casadi_sq(a14);
  a01=casadi_sq(a06);
  a03=(a03+a01);
  a01=casadi_sq(a04);
  a03=(a03+a01);
  a03=(a03-a00);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=(a07*a14);
  a01=(a02*a06);
  a03=(a03+a01);
  a01=(a05*a04);
  a03=(a03+a01);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=(a15*a07);
  a01=(a11*a02);
  a03=(a03+a01);
  a01=(a09*a05);
  a03=(a03+a01);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=(a14*a07);
  a01=(a06*a02);
  a03=(a03+a01);
  a01=(a04*a05);
  a03=(a03+a01);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a03=casadi_sq(a07);
  a01=casadi_sq(a02);
  a03=(a03+a01);
  a01=casadi_sq(a05);
  a03=(a03+a01);
  a03=(a03-a00);
  a03=casadi_fabs(a03);
  a10=casadi_fmax(a10,a03);
  a06=(a06*a05);
  a06=(a06-a08);
  a15=(a15*a06);
  a02=(a02*a09);
  a12=(a12-a02);
  a14=(a14*a12);
  a15=(a15-a14);
  a11=(a11*a04);
  a11=(a11-a13);
  a07=(a07*a11);
  a15=(a15+a07);
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
    case 2: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* observe_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    case 1: return casadi_s3;
    case 2: return casadi_s1;
    case 3: return casadi_s3;
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

/* update_p:(z[9],g[9],p[3],h[3])->(p1[3]) */
static int casadi_f13(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18;
  a00=3.3333333333333331e-01;
  a01=-1.0416666666666666e-02;
  a02=arg[3]? arg[3][0] : 0;
  a03=5.0000000000000000e-01;
  a04=3.0000000000000004e+00;
  a05=arg[0]? arg[0][0] : 0;
  a06=(a04*a05);
  a07=4.6410161513775439e-01;
  a08=arg[0]? arg[0][3] : 0;
  a09=(a07*a08);
  a06=(a06+a09);
  a06=(a03*a06);
  a09=-6.4641016151377553e+00;
  a05=(a09*a05);
  a08=(a04*a08);
  a05=(a05+a08);
  a05=(a03*a05);
  a06=(a06+a05);
  a06=(a02*a06);
  a05=casadi_sq(a06);
  a08=arg[0]? arg[0][1] : 0;
  a10=(a04*a08);
  a11=arg[0]? arg[0][4] : 0;
  a12=(a07*a11);
  a10=(a10+a12);
  a10=(a03*a10);
  a08=(a09*a08);
  a11=(a04*a11);
  a08=(a08+a11);
  a08=(a03*a08);
  a10=(a10+a08);
  a10=(a02*a10);
  a08=casadi_sq(a10);
  a11=(a05+a08);
  a12=arg[0]? arg[0][2] : 0;
  a13=(a04*a12);
  a14=arg[0]? arg[0][5] : 0;
  a07=(a07*a14);
  a13=(a13+a07);
  a13=(a03*a13);
  a09=(a09*a12);
  a04=(a04*a14);
  a09=(a09+a04);
  a09=(a03*a09);
  a13=(a13+a09);
  a02=(a02*a13);
  a13=casadi_sq(a02);
  a09=(a11+a13);
  a01=(a01*a09);
  a04=1.3888888888888889e-03;
  a14=-6.2003968253968254e-06;
  a14=(a14*a09);
  a04=(a04+a14);
  a14=2.5000000000000000e-01;
  a14=(a14*a09);
  a12=casadi_sq(a14);
  a04=(a04*a12);
  a01=(a01+a04);
  a04=2.7557319223985888e-07;
  a07=-5.2191892469670250e-10;
  a07=(a07*a09);
  a04=(a04+a07);
  a07=1.1470745597729725e-11;
  a15=-1.1948693330968463e-14;
  a15=(a15*a09);
  a07=(a07+a15);
  a07=(a07*a12);
  a04=(a04+a07);
  a07=casadi_sq(a12);
  a04=(a04*a07);
  a01=(a01+a04);
  a04=1.5619206968586225e-16;
  a15=-1.0275794058280412e-19;
  a15=(a15*a09);
  a04=(a04+a15);
  a15=8.8967913924505741e-22;
  a15=(a15*a12);
  a04=(a04+a15);
  a15=casadi_sq(a07);
  a04=(a04*a15);
  a01=(a01+a04);
  a04=-2.0833333333333333e-03;
  a04=(a04*a09);
  a16=1.9841269841269841e-04;
  a17=-6.8893298059964731e-07;
  a17=(a17*a09);
  a16=(a16+a17);
  a16=(a16*a12);
  a04=(a04+a16);
  a16=2.5052108385441720e-08;
  a17=-4.0147609592054033e-11;
  a17=(a17*a09);
  a16=(a16+a17);
  a17=7.6471637318198164e-13;
  a18=-7.0286431358638015e-16;
  a18=(a18*a09);
  a17=(a17+a18);
  a17=(a17*a12);
  a16=(a16+a17);
  a16=(a16*a07);
  a04=(a04+a16);
  a16=8.2206352466243295e-18;
  a07=-4.8932352658478156e-21;
  a07=(a07*a09);
  a16=(a16+a07);
  a07=3.8681701706306841e-23;
  a07=(a07*a12);
  a16=(a16+a07);
  a16=(a16*a15);
  a04=(a04+a16);
  a01=(a01-a04);
  a00=(a00+a01);
  a01=4.;
  a16=1.;
  a15=1.6666666666666666e-01;
  a15=(a15+a04);
  a14=(a14*a15);
  a14=(a16-a14);
  a01=(a01*a14);
  a00=(a00/a01);
  a01=(a06*a02);
  a01=(a00*a01);
  a14=(a03*a10);
  a14=(a01-a14);
  a15=arg[0]? arg[0][8] : 0;
  a14=(a14*a15);
  a04=(a06*a10);
  a04=(a00*a04);
  a07=-5.0000000000000000e-01;
  a12=(a07*a02);
  a12=(a04-a12);
  a09=arg[0]? arg[0][7] : 0;
  a12=(a12*a09);
  a14=(a14+a12);
  a08=(a08+a13);
  a08=(a00*a08);
  a08=(a16-a08);
  a12=arg[0]? arg[0][6] : 0;
  a08=(a08*a12);
  a14=(a14+a08);
  if (res[0]!=0) res[0][0]=a14;
  a14=(a10*a02);
  a14=(a00*a14);
  a08=(a07*a06);
  a08=(a14-a08);
  a08=(a08*a15);
  a13=(a13+a05);
  a13=(a00*a13);
  a13=(a16-a13);
  a13=(a13*a09);
  a08=(a08+a13);
  a02=(a03*a02);
  a04=(a04-a02);
  a04=(a04*a12);
  a08=(a08+a04);
  if (res[0]!=0) res[0][1]=a08;
  a00=(a00*a11);
  a16=(a16-a00);
  a16=(a16*a15);
  a03=(a03*a06);
  a14=(a14-a03);
  a14=(a14*a09);
  a16=(a16+a14);
  a07=(a07*a10);
  a01=(a01-a07);
  a01=(a01*a12);
  a16=(a16+a01);
  if (res[0]!=0) res[0][2]=a16;
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
    case 3: return casadi_s1;
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

/* velocity_step:(g[9],p[3],xi[3],h[3])->(xi1[3]) */
static int casadi_f14(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3;
  a0=arg[2]? arg[2][0] : 0;
  a1=arg[1]? arg[1][0] : 0;
  a1=(a0-a1);
  a0=(a0-a1);
  if (res[0]!=0) res[0][0]=a0;
  a0=arg[2]? arg[2][1] : 0;
  a1=5.;
  a2=(a1*a0);
  a3=arg[1]? arg[1][1] : 0;
  a2=(a2-a3);
  a2=(a2/a1);
  a0=(a0-a2);
  if (res[0]!=0) res[0][1]=a0;
  a0=arg[2]? arg[2][2] : 0;
  a2=6.;
  a1=(a2*a0);
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
    case 3: return casadi_s1;
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

/* record:(g[9],p[3],xi[3],h[3])->(row[19]) */
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
  a13=casadi_sq(a12);
  a14=5.;
  a15=arg[2]? arg[2][1] : 0;
  a14=(a14*a15);
  a14=(a14*a15);
  a14=(a13+a14);
  a16=6.;
  a17=arg[2]? arg[2][2] : 0;
  a16=(a16*a17);
  a16=(a16*a17);
  a14=(a14+a16);
  a16=5.0000000000000000e-01;
  a16=(a16*a13);
  a13=3.;
  a18=casadi_sq(a17);
  a13=(a13*a18);
  a16=(a16+a13);
  a13=2.5000000000000000e+00;
  a18=casadi_sq(a15);
  a13=(a13*a18);
  a16=(a16+a13);
  a16=(a16-a08);
  a14=(a14-a16);
  if (res[0]!=0) res[0][12]=a14;
  a14=arg[3]? arg[3][2] : 0;
  a16=(a14*a12);
  a16=(a16*a12);
  a12=(a14*a15);
  a12=(a12*a15);
  a16=(a16+a12);
  a14=(a14*a17);
  a14=(a14*a17);
  a16=(a16+a14);
  a16=(-a16);
  if (res[0]!=0) res[0][13]=a16;
  if (res[0]!=0) res[0][14]=a16;
  a16=(a08*a04);
  a14=(a07*a05);
  a16=(a16-a14);
  a16=(a16*a09);
  a14=(a02*a07);
  a17=(a01*a08);
  a14=(a14-a17);
  a14=(a14*a10);
  a16=(a16+a14);
  a14=(a05*a01);
  a17=(a04*a02);
  a14=(a14-a17);
  a14=(a14*a11);
  a16=(a16+a14);
  if (res[0]!=0) res[0][15]=a16;
  a16=(a06*a05);
  a14=(a08*a03);
  a16=(a16-a14);
  a16=(a16*a09);
  a14=(a00*a08);
  a17=(a02*a06);
  a14=(a14-a17);
  a14=(a14*a10);
  a16=(a16+a14);
  a02=(a03*a02);
  a05=(a05*a00);
  a02=(a02-a05);
  a02=(a02*a11);
  a16=(a16+a02);
  if (res[0]!=0) res[0][16]=a16;
  a16=(a07*a03);
  a02=(a06*a04);
  a16=(a16-a02);
  a16=(a16*a09);
  a06=(a01*a06);
  a07=(a00*a07);
  a06=(a06-a07);
  a06=(a06*a10);
  a16=(a16+a06);
  a04=(a04*a00);
  a03=(a03*a01);
  a04=(a04-a03);
  a04=(a04*a11);
  a16=(a16+a04);
  if (res[0]!=0) res[0][17]=a16;
  if (res[0]!=0) res[0][18]=a08;
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
    case 3: return casadi_s1;
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

/* step_partials:(z[9],g[9],p[3],h[3])->(Fs[54],Yz[54],Ys[36],FH[27],YH[18]) */
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
  casadi_real a276, a277, a278, a279, a280, a281, a282, a283, a284, a285, a286, a287;
  casadi_real a288, a289, a290, a291, a292, a293, a294, a295, a296, a297, a298, a299;
  casadi_real a300, a301, a302, a303, a304, a305, a306, a307, a308, a309, a310, a311;
  casadi_real a312, a313, a314, a315, a316, a317, a318, a319, a320, a321, a322, a323;
  casadi_real a324, a325, a326, a327, a328, a329, a330, a331, a332;
  a000=5.0000000000000000e-01;
  a001=arg[3]? arg[3][0] : 0;
  a002=(a000*a001);
  a003=1.;
  a004=2.5000000000000000e-01;
  a005=arg[0]? arg[0][0] : 0;
  a006=(a001*a005);
  a007=casadi_sq(a006);
  a008=arg[0]? arg[0][1] : 0;
  a009=(a001*a008);
  a010=casadi_sq(a009);
  a011=(a007+a010);
  a012=arg[0]? arg[0][2] : 0;
  a013=(a001*a012);
  a014=casadi_sq(a013);
  a015=(a011+a014);
  a016=(a004*a015);
  a017=1.6666666666666666e-01;
  a018=-2.0833333333333333e-03;
  a019=(a018*a015);
  a020=1.9841269841269841e-04;
  a021=-6.8893298059964731e-07;
  a022=(a021*a015);
  a022=(a020+a022);
  a023=casadi_sq(a016);
  a024=(a022*a023);
  a019=(a019+a024);
  a024=2.5052108385441720e-08;
  a025=-4.0147609592054033e-11;
  a026=(a025*a015);
  a026=(a024+a026);
  a027=7.6471637318198164e-13;
  a028=-7.0286431358638015e-16;
  a029=(a028*a015);
  a029=(a027+a029);
  a030=(a029*a023);
  a026=(a026+a030);
  a030=casadi_sq(a023);
  a031=(a026*a030);
  a019=(a019+a031);
  a031=8.2206352466243295e-18;
  a032=-4.8932352658478156e-21;
  a033=(a032*a015);
  a033=(a031+a033);
  a034=3.8681701706306841e-23;
  a035=(a034*a023);
  a033=(a033+a035);
  a035=casadi_sq(a030);
  a036=(a033*a035);
  a019=(a019+a036);
  a036=(a017+a019);
  a037=(a016*a036);
  a037=(a003-a037);
  a038=casadi_sq(a037);
  a038=(a000*a038);
  a007=(a014+a007);
  a039=(a038*a007);
  a039=(a003-a039);
  a040=arg[1]? arg[1][8] : 0;
  a041=(a039*a040);
  a042=-1.0416666666666666e-02;
  a043=(a042*a015);
  a044=1.3888888888888889e-03;
  a045=-6.2003968253968254e-06;
  a046=(a045*a015);
  a046=(a044+a046);
  a047=(a046*a023);
  a043=(a043+a047);
  a047=2.7557319223985888e-07;
  a048=-5.2191892469670250e-10;
  a049=(a048*a015);
  a049=(a047+a049);
  a050=1.1470745597729725e-11;
  a051=-1.1948693330968463e-14;
  a052=(a051*a015);
  a052=(a050+a052);
  a053=(a052*a023);
  a049=(a049+a053);
  a053=(a049*a030);
  a043=(a043+a053);
  a053=1.5619206968586225e-16;
  a054=-1.0275794058280412e-19;
  a055=(a054*a015);
  a055=(a053+a055);
  a056=8.8967913924505741e-22;
  a057=(a056*a023);
  a055=(a055+a057);
  a057=(a055*a035);
  a043=(a043+a057);
  a057=(a000+a043);
  a058=(a016*a057);
  a058=(a003-a058);
  a059=(a037*a058);
  a060=(a059*a006);
  a061=(a009*a013);
  a062=(a038*a061);
  a060=(a060+a062);
  a062=arg[1]? arg[1][5] : 0;
  a063=(a060*a062);
  a041=(a041-a063);
  a041=(a002*a041);
  a041=(a041/a001);
  if (res[0]!=0) res[0][0]=a041;
  a041=(a059*a013);
  a063=(a006*a009);
  a064=(a038*a063);
  a065=(a041+a064);
  a066=(a065*a040);
  a067=(a006*a013);
  a068=(a038*a067);
  a069=(a059*a009);
  a068=(a068-a069);
  a069=(a068*a062);
  a066=(a066-a069);
  a066=(a002*a066);
  a066=(a066/a001);
  a066=(-a066);
  if (res[0]!=0) res[0][1]=a066;
  a066=0.;
  if (res[0]!=0) res[0][2]=a066;
  a069=arg[0]? arg[0][3] : 0;
  a070=(a001*a069);
  a071=casadi_sq(a070);
  a072=arg[0]? arg[0][4] : 0;
  a073=(a001*a072);
  a074=casadi_sq(a073);
  a075=(a071+a074);
  a076=arg[0]? arg[0][5] : 0;
  a077=(a001*a076);
  a078=casadi_sq(a077);
  a079=(a075+a078);
  a080=(a004*a079);
  a081=(a018*a079);
  a082=(a021*a079);
  a082=(a020+a082);
  a083=casadi_sq(a080);
  a084=(a082*a083);
  a081=(a081+a084);
  a084=(a025*a079);
  a084=(a024+a084);
  a085=(a028*a079);
  a085=(a027+a085);
  a086=(a085*a083);
  a084=(a084+a086);
  a086=casadi_sq(a083);
  a087=(a084*a086);
  a081=(a081+a087);
  a087=(a032*a079);
  a087=(a031+a087);
  a088=(a034*a083);
  a087=(a087+a088);
  a088=casadi_sq(a086);
  a089=(a087*a088);
  a081=(a081+a089);
  a089=(a017+a081);
  a090=(a080*a089);
  a090=(a003-a090);
  a091=casadi_sq(a090);
  a091=(a000*a091);
  a071=(a078+a071);
  a092=(a091*a071);
  a092=(a003-a092);
  a093=(a092*a040);
  a094=(a042*a079);
  a095=(a045*a079);
  a095=(a044+a095);
  a096=(a095*a083);
  a094=(a094+a096);
  a096=(a048*a079);
  a096=(a047+a096);
  a097=(a051*a079);
  a097=(a050+a097);
  a098=(a097*a083);
  a096=(a096+a098);
  a098=(a096*a086);
  a094=(a094+a098);
  a098=(a054*a079);
  a098=(a053+a098);
  a099=(a056*a083);
  a098=(a098+a099);
  a099=(a098*a088);
  a094=(a094+a099);
  a099=(a000+a094);
  a100=(a080*a099);
  a100=(a003-a100);
  a101=(a090*a100);
  a102=(a101*a070);
  a103=(a073*a077);
  a104=(a091*a103);
  a102=(a102+a104);
  a104=(a102*a062);
  a093=(a093-a104);
  a093=(a002*a093);
  a093=(a093/a001);
  if (res[0]!=0) res[0][3]=a093;
  a093=(a101*a077);
  a104=(a070*a073);
  a105=(a091*a104);
  a106=(a093+a105);
  a107=(a106*a040);
  a108=(a070*a077);
  a109=(a091*a108);
  a110=(a101*a073);
  a109=(a109-a110);
  a110=(a109*a062);
  a107=(a107-a110);
  a107=(a002*a107);
  a107=(a107/a001);
  a107=(-a107);
  if (res[0]!=0) res[0][4]=a107;
  if (res[0]!=0) res[0][5]=a066;
  if (res[0]!=0) res[0][6]=a066;
  if (res[0]!=0) res[0][7]=a066;
  if (res[0]!=0) res[0][8]=a066;
  a107=arg[1]? arg[1][2] : 0;
  a110=(a060*a107);
  a064=(a064-a041);
  a041=(a064*a040);
  a110=(a110-a041);
  a110=(a002*a110);
  a110=(a110/a001);
  if (res[0]!=0) res[0][9]=a110;
  a110=(a068*a107);
  a010=(a010+a014);
  a014=(a038*a010);
  a014=(a003-a014);
  a041=(a014*a040);
  a110=(a110-a041);
  a110=(a002*a110);
  a110=(a110/a001);
  a110=(-a110);
  if (res[0]!=0) res[0][10]=a110;
  if (res[0]!=0) res[0][11]=a066;
  a110=(a102*a107);
  a105=(a105-a093);
  a093=(a105*a040);
  a110=(a110-a093);
  a110=(a002*a110);
  a110=(a110/a001);
  if (res[0]!=0) res[0][12]=a110;
  a110=(a109*a107);
  a074=(a074+a078);
  a078=(a091*a074);
  a078=(a003-a078);
  a093=(a078*a040);
  a110=(a110-a093);
  a110=(a002*a110);
  a110=(a110/a001);
  a110=(-a110);
  if (res[0]!=0) res[0][13]=a110;
  if (res[0]!=0) res[0][14]=a066;
  if (res[0]!=0) res[0][15]=a066;
  if (res[0]!=0) res[0][16]=a066;
  if (res[0]!=0) res[0][17]=a066;
  a110=(a064*a062);
  a093=(a039*a107);
  a110=(a110-a093);
  a110=(a002*a110);
  a110=(a110/a001);
  if (res[0]!=0) res[0][18]=a110;
  a110=(a014*a062);
  a093=(a065*a107);
  a110=(a110-a093);
  a110=(a002*a110);
  a110=(a110/a001);
  a110=(-a110);
  if (res[0]!=0) res[0][19]=a110;
  if (res[0]!=0) res[0][20]=a066;
  a110=(a105*a062);
  a093=(a092*a107);
  a110=(a110-a093);
  a110=(a002*a110);
  a110=(a110/a001);
  if (res[0]!=0) res[0][21]=a110;
  a110=(a078*a062);
  a093=(a106*a107);
  a110=(a110-a093);
  a110=(a002*a110);
  a110=(a110/a001);
  a110=(-a110);
  if (res[0]!=0) res[0][22]=a110;
  if (res[0]!=0) res[0][23]=a066;
  if (res[0]!=0) res[0][24]=a066;
  if (res[0]!=0) res[0][25]=a066;
  if (res[0]!=0) res[0][26]=a066;
  if (res[0]!=0) res[0][27]=a066;
  if (res[0]!=0) res[0][28]=a066;
  if (res[0]!=0) res[0][29]=a066;
  if (res[0]!=0) res[0][30]=a066;
  if (res[0]!=0) res[0][31]=a066;
  if (res[0]!=0) res[0][32]=a066;
  if (res[0]!=0) res[0][33]=a003;
  if (res[0]!=0) res[0][34]=a066;
  if (res[0]!=0) res[0][35]=a066;
  if (res[0]!=0) res[0][36]=a066;
  if (res[0]!=0) res[0][37]=a066;
  if (res[0]!=0) res[0][38]=a066;
  if (res[0]!=0) res[0][39]=a066;
  if (res[0]!=0) res[0][40]=a066;
  if (res[0]!=0) res[0][41]=a066;
  if (res[0]!=0) res[0][42]=a066;
  if (res[0]!=0) res[0][43]=a003;
  if (res[0]!=0) res[0][44]=a066;
  if (res[0]!=0) res[0][45]=a066;
  if (res[0]!=0) res[0][46]=a066;
  if (res[0]!=0) res[0][47]=a066;
  if (res[0]!=0) res[0][48]=a066;
  if (res[0]!=0) res[0][49]=a066;
  if (res[0]!=0) res[0][50]=a066;
  if (res[0]!=0) res[0][51]=a066;
  if (res[0]!=0) res[0][52]=a066;
  if (res[0]!=0) res[0][53]=a003;
  a110=arg[1]? arg[1][0] : 0;
  a093=3.0000000000000004e+00;
  a041=(a093*a005);
  a111=4.6410161513775439e-01;
  a112=(a111*a069);
  a041=(a041+a112);
  a112=(a000*a041);
  a113=-6.4641016151377553e+00;
  a114=(a113*a005);
  a115=(a093*a069);
  a114=(a114+a115);
  a115=(a000*a114);
  a112=(a112+a115);
  a115=(a001*a112);
  a116=casadi_sq(a115);
  a117=(a093*a008);
  a118=(a111*a072);
  a117=(a117+a118);
  a118=(a000*a117);
  a119=(a113*a008);
  a120=(a093*a072);
  a119=(a119+a120);
  a120=(a000*a119);
  a118=(a118+a120);
  a120=(a001*a118);
  a121=casadi_sq(a120);
  a122=(a116+a121);
  a123=(a093*a012);
  a111=(a111*a076);
  a123=(a123+a111);
  a111=(a000*a123);
  a113=(a113*a012);
  a093=(a093*a076);
  a113=(a113+a093);
  a093=(a000*a113);
  a111=(a111+a093);
  a093=(a001*a111);
  a124=casadi_sq(a093);
  a125=(a122+a124);
  a126=(a004*a125);
  a127=(a018*a125);
  a128=(a021*a125);
  a020=(a020+a128);
  a128=casadi_sq(a126);
  a129=(a020*a128);
  a127=(a127+a129);
  a129=(a025*a125);
  a024=(a024+a129);
  a129=(a028*a125);
  a027=(a027+a129);
  a129=(a027*a128);
  a024=(a024+a129);
  a129=casadi_sq(a128);
  a130=(a024*a129);
  a127=(a127+a130);
  a130=(a032*a125);
  a031=(a031+a130);
  a130=(a034*a128);
  a031=(a031+a130);
  a130=casadi_sq(a129);
  a131=(a031*a130);
  a127=(a127+a131);
  a017=(a017+a127);
  a131=(a126*a017);
  a131=(a003-a131);
  a132=(a042*a125);
  a133=(a045*a125);
  a044=(a044+a133);
  a133=(a044*a128);
  a132=(a132+a133);
  a133=(a048*a125);
  a047=(a047+a133);
  a133=(a051*a125);
  a050=(a050+a133);
  a133=(a050*a128);
  a047=(a047+a133);
  a133=(a047*a129);
  a132=(a132+a133);
  a133=(a054*a125);
  a053=(a053+a133);
  a133=(a056*a128);
  a053=(a053+a133);
  a133=(a053*a130);
  a132=(a132+a133);
  a133=(a000+a132);
  a134=(a126*a133);
  a134=(a003-a134);
  a135=(a131*a134);
  a136=(a135*a120);
  a137=casadi_sq(a131);
  a137=(a000*a137);
  a138=(a115*a093);
  a139=(a137*a138);
  a140=(a136+a139);
  a141=(a110*a140);
  a142=arg[1]? arg[1][3] : 0;
  a143=(a120*a093);
  a144=(a137*a143);
  a145=(a135*a115);
  a146=(a144-a145);
  a147=(a142*a146);
  a141=(a141+a147);
  a147=arg[1]? arg[1][6] : 0;
  a148=(a137*a122);
  a148=(a003-a148);
  a149=(a147*a148);
  a141=(a141+a149);
  a149=-1.7320508075688774e+00;
  a149=(a149*a001);
  a150=(a120*a149);
  a151=(a137*a150);
  a152=(a115*a120);
  a153=(2.*a131);
  a154=(2.*a115);
  a155=(a154*a149);
  a156=(a004*a155);
  a157=(a017*a156);
  a158=(a018*a155);
  a159=(a021*a155);
  a159=(a128*a159);
  a125=(a000*a125);
  a160=(a125*a156);
  a161=(a020*a160);
  a159=(a159+a161);
  a158=(a158+a159);
  a159=(a025*a155);
  a161=(a028*a155);
  a161=(a128*a161);
  a162=(a027*a160);
  a161=(a161+a162);
  a159=(a159+a161);
  a159=(a129*a159);
  a161=(2.*a128);
  a162=(a161*a160);
  a163=(a024*a162);
  a159=(a159+a163);
  a158=(a158+a159);
  a159=(a032*a155);
  a163=(a034*a160);
  a159=(a159+a163);
  a159=(a130*a159);
  a163=(2.*a129);
  a164=(a163*a162);
  a165=(a031*a164);
  a159=(a159+a165);
  a158=(a158+a159);
  a159=(a126*a158);
  a157=(a157+a159);
  a159=(a153*a157);
  a159=(a000*a159);
  a165=(a152*a159);
  a165=(a151-a165);
  a166=(a134*a157);
  a156=(a133*a156);
  a167=(a042*a155);
  a168=(a045*a155);
  a168=(a128*a168);
  a169=(a044*a160);
  a168=(a168+a169);
  a167=(a167+a168);
  a168=(a048*a155);
  a169=(a051*a155);
  a169=(a128*a169);
  a170=(a050*a160);
  a169=(a169+a170);
  a168=(a168+a169);
  a168=(a129*a168);
  a162=(a047*a162);
  a168=(a168+a162);
  a167=(a167+a168);
  a168=(a054*a155);
  a160=(a056*a160);
  a168=(a168+a160);
  a168=(a130*a168);
  a164=(a053*a164);
  a168=(a168+a164);
  a167=(a167+a168);
  a168=(a126*a167);
  a156=(a156+a168);
  a156=(a131*a156);
  a166=(a166+a156);
  a156=(a093*a166);
  a168=(a165+a156);
  a164=(a110*a168);
  a160=(a137*a155);
  a116=(a124+a116);
  a162=(a116*a159);
  a162=(a160-a162);
  a169=(a142*a162);
  a164=(a164-a169);
  a169=(a135*a149);
  a170=(a115*a166);
  a170=(a169-a170);
  a171=(a143*a159);
  a172=(a170-a171);
  a173=(a147*a172);
  a164=(a164+a173);
  a164=(a141*a164);
  a173=arg[1]? arg[1][1] : 0;
  a174=(a173*a140);
  a175=arg[1]? arg[1][4] : 0;
  a176=(a175*a146);
  a174=(a174+a176);
  a176=arg[1]? arg[1][7] : 0;
  a177=(a176*a148);
  a174=(a174+a177);
  a177=(a173*a168);
  a178=(a175*a162);
  a177=(a177-a178);
  a178=(a176*a172);
  a177=(a177+a178);
  a177=(a174*a177);
  a164=(a164+a177);
  a177=(a107*a140);
  a178=(a062*a146);
  a177=(a177+a178);
  a178=(a040*a148);
  a177=(a177+a178);
  a168=(a107*a168);
  a162=(a062*a162);
  a168=(a168-a162);
  a172=(a040*a172);
  a168=(a168+a172);
  a168=(a177*a168);
  a164=(a164+a168);
  if (res[1]!=0) res[1][0]=a164;
  a121=(a121+a124);
  a124=(a137*a121);
  a124=(a003-a124);
  a164=(a110*a124);
  a168=(a135*a093);
  a172=(a137*a152);
  a162=(a168+a172);
  a178=(a142*a162);
  a164=(a164+a178);
  a139=(a139-a136);
  a136=(a147*a139);
  a164=(a164+a136);
  a136=(a093*a149);
  a178=(a137*a136);
  a179=(a138*a159);
  a179=(a178-a179);
  a166=(a120*a166);
  a180=(a179-a166);
  a181=(a110*a180);
  a171=(a171+a170);
  a170=(a142*a171);
  a181=(a181-a170);
  a170=(a122*a159);
  a160=(a160-a170);
  a170=(a147*a160);
  a181=(a181-a170);
  a181=(a164*a181);
  a170=(a173*a124);
  a182=(a175*a162);
  a170=(a170+a182);
  a182=(a176*a139);
  a170=(a170+a182);
  a182=(a173*a180);
  a183=(a175*a171);
  a182=(a182-a183);
  a183=(a176*a160);
  a182=(a182-a183);
  a182=(a170*a182);
  a181=(a181+a182);
  a182=(a107*a124);
  a183=(a062*a162);
  a182=(a182+a183);
  a183=(a040*a139);
  a182=(a182+a183);
  a180=(a107*a180);
  a171=(a062*a171);
  a180=(a180-a171);
  a160=(a040*a160);
  a180=(a180-a160);
  a180=(a182*a180);
  a181=(a181+a180);
  if (res[1]!=0) res[1][1]=a181;
  a172=(a172-a168);
  a168=(a110*a172);
  a181=(a137*a116);
  a181=(a003-a181);
  a180=(a142*a181);
  a168=(a168+a180);
  a145=(a145+a144);
  a144=(a147*a145);
  a168=(a168+a144);
  a159=(a121*a159);
  a144=(a110*a159);
  a165=(a165-a156);
  a156=(a142*a165);
  a144=(a144+a156);
  a179=(a179+a166);
  a166=(a147*a179);
  a144=(a144+a166);
  a144=(a168*a144);
  a166=(a173*a172);
  a156=(a175*a181);
  a166=(a166+a156);
  a156=(a176*a145);
  a166=(a166+a156);
  a156=(a173*a159);
  a180=(a175*a165);
  a156=(a156+a180);
  a180=(a176*a179);
  a156=(a156+a180);
  a156=(a166*a156);
  a144=(a144+a156);
  a156=(a107*a172);
  a180=(a062*a181);
  a156=(a156+a180);
  a180=(a040*a145);
  a156=(a156+a180);
  a159=(a107*a159);
  a165=(a062*a165);
  a159=(a159+a165);
  a179=(a040*a179);
  a159=(a159+a179);
  a159=(a156*a159);
  a144=(a144+a159);
  if (res[1]!=0) res[1][2]=a144;
  a144=arg[0]? arg[0][8] : 0;
  a167=(a167-a158);
  a158=4.;
  a159=(a158*a131);
  a167=(a167/a159);
  a179=3.3333333333333331e-01;
  a132=(a132-a127);
  a132=(a179+a132);
  a132=(a132/a159);
  a127=(a132/a159);
  a157=(a158*a157);
  a157=(a127*a157);
  a167=(a167+a157);
  a157=(a138*a167);
  a136=(a132*a136);
  a157=(a157+a136);
  a165=(a144*a157);
  a180=arg[0]? arg[0][7] : 0;
  a160=(a152*a167);
  a150=(a132*a150);
  a160=(a160+a150);
  a171=(a180*a160);
  a165=(a165+a171);
  a171=arg[0]? arg[0][6] : 0;
  a183=(a121*a167);
  a183=(a171*a183);
  a165=(a165-a183);
  if (res[1]!=0) res[1][3]=a165;
  a165=(a143*a167);
  a183=8.6602540378443871e-01;
  a183=(a183*a001);
  a184=(a165-a183);
  a184=(a144*a184);
  a185=(a116*a167);
  a155=(a132*a155);
  a185=(a185+a155);
  a185=(a180*a185);
  a184=(a184-a185);
  a160=(a171*a160);
  a184=(a184+a160);
  if (res[1]!=0) res[1][4]=a184;
  a184=-8.6602540378443871e-01;
  a184=(a184*a001);
  a165=(a165-a184);
  a165=(a180*a165);
  a167=(a122*a167);
  a167=(a167+a155);
  a167=(a144*a167);
  a165=(a165-a167);
  a157=(a171*a157);
  a165=(a165+a157);
  if (res[1]!=0) res[1][5]=a165;
  a165=(a115*a149);
  a157=(a137*a165);
  a167=(2.*a120);
  a155=(a167*a149);
  a160=(a004*a155);
  a185=(a017*a160);
  a186=(a018*a155);
  a187=(a021*a155);
  a187=(a128*a187);
  a188=(a125*a160);
  a189=(a020*a188);
  a187=(a187+a189);
  a186=(a186+a187);
  a187=(a025*a155);
  a189=(a028*a155);
  a189=(a128*a189);
  a190=(a027*a188);
  a189=(a189+a190);
  a187=(a187+a189);
  a187=(a129*a187);
  a189=(a161*a188);
  a190=(a024*a189);
  a187=(a187+a190);
  a186=(a186+a187);
  a187=(a032*a155);
  a190=(a034*a188);
  a187=(a187+a190);
  a187=(a130*a187);
  a190=(a163*a189);
  a191=(a031*a190);
  a187=(a187+a191);
  a186=(a186+a187);
  a187=(a126*a186);
  a185=(a185+a187);
  a187=(a153*a185);
  a187=(a000*a187);
  a191=(a152*a187);
  a191=(a157-a191);
  a192=(a134*a185);
  a160=(a133*a160);
  a193=(a042*a155);
  a194=(a045*a155);
  a194=(a128*a194);
  a195=(a044*a188);
  a194=(a194+a195);
  a193=(a193+a194);
  a194=(a048*a155);
  a195=(a051*a155);
  a195=(a128*a195);
  a196=(a050*a188);
  a195=(a195+a196);
  a194=(a194+a195);
  a194=(a129*a194);
  a189=(a047*a189);
  a194=(a194+a189);
  a193=(a193+a194);
  a194=(a054*a155);
  a188=(a056*a188);
  a194=(a194+a188);
  a194=(a130*a194);
  a190=(a053*a190);
  a194=(a194+a190);
  a193=(a193+a194);
  a194=(a126*a193);
  a160=(a160+a194);
  a160=(a131*a160);
  a192=(a192+a160);
  a160=(a093*a192);
  a194=(a191+a160);
  a190=(a110*a194);
  a188=(a116*a187);
  a189=(a142*a188);
  a190=(a190+a189);
  a189=(a143*a187);
  a178=(a178-a189);
  a189=(a115*a192);
  a195=(a178-a189);
  a196=(a147*a195);
  a190=(a190+a196);
  a190=(a141*a190);
  a196=(a173*a194);
  a197=(a175*a188);
  a196=(a196+a197);
  a197=(a176*a195);
  a196=(a196+a197);
  a196=(a174*a196);
  a190=(a190+a196);
  a194=(a107*a194);
  a188=(a062*a188);
  a194=(a194+a188);
  a195=(a040*a195);
  a194=(a194+a195);
  a194=(a177*a194);
  a190=(a190+a194);
  if (res[1]!=0) res[1][6]=a190;
  a192=(a120*a192);
  a192=(a169-a192);
  a190=(a138*a187);
  a194=(a192-a190);
  a195=(a110*a194);
  a178=(a178+a189);
  a189=(a142*a178);
  a195=(a195+a189);
  a189=(a137*a155);
  a188=(a122*a187);
  a188=(a189-a188);
  a196=(a147*a188);
  a195=(a195-a196);
  a195=(a164*a195);
  a196=(a173*a194);
  a197=(a175*a178);
  a196=(a196+a197);
  a197=(a176*a188);
  a196=(a196-a197);
  a196=(a170*a196);
  a195=(a195+a196);
  a194=(a107*a194);
  a178=(a062*a178);
  a194=(a194+a178);
  a188=(a040*a188);
  a194=(a194-a188);
  a194=(a182*a194);
  a195=(a195+a194);
  if (res[1]!=0) res[1][7]=a195;
  a191=(a191-a160);
  a160=(a142*a191);
  a187=(a121*a187);
  a189=(a189-a187);
  a187=(a110*a189);
  a160=(a160-a187);
  a190=(a190+a192);
  a192=(a147*a190);
  a160=(a160-a192);
  a160=(a168*a160);
  a192=(a175*a191);
  a187=(a173*a189);
  a192=(a192-a187);
  a187=(a176*a190);
  a192=(a192-a187);
  a192=(a166*a192);
  a160=(a160+a192);
  a191=(a062*a191);
  a189=(a107*a189);
  a191=(a191-a189);
  a190=(a040*a190);
  a191=(a191-a190);
  a191=(a156*a191);
  a160=(a160+a191);
  if (res[1]!=0) res[1][8]=a160;
  a193=(a193-a186);
  a193=(a193/a159);
  a185=(a158*a185);
  a185=(a127*a185);
  a193=(a193+a185);
  a185=(a138*a193);
  a186=(a185-a184);
  a186=(a144*a186);
  a160=(a152*a193);
  a165=(a132*a165);
  a160=(a160+a165);
  a191=(a180*a160);
  a186=(a186+a191);
  a191=(a121*a193);
  a155=(a132*a155);
  a191=(a191+a155);
  a191=(a171*a191);
  a186=(a186-a191);
  if (res[1]!=0) res[1][9]=a186;
  a186=(a143*a193);
  a186=(a186+a136);
  a136=(a144*a186);
  a191=(a116*a193);
  a191=(a180*a191);
  a136=(a136-a191);
  a160=(a171*a160);
  a136=(a136+a160);
  if (res[1]!=0) res[1][10]=a136;
  a186=(a180*a186);
  a193=(a122*a193);
  a193=(a193+a155);
  a193=(a144*a193);
  a186=(a186-a193);
  a185=(a185-a183);
  a185=(a171*a185);
  a186=(a186+a185);
  if (res[1]!=0) res[1][11]=a186;
  a186=(2.*a093);
  a149=(a186*a149);
  a185=(a004*a149);
  a193=(a017*a185);
  a155=(a018*a149);
  a136=(a021*a149);
  a136=(a128*a136);
  a160=(a125*a185);
  a191=(a020*a160);
  a136=(a136+a191);
  a155=(a155+a136);
  a136=(a025*a149);
  a191=(a028*a149);
  a191=(a128*a191);
  a190=(a027*a160);
  a191=(a191+a190);
  a136=(a136+a191);
  a136=(a129*a136);
  a191=(a161*a160);
  a190=(a024*a191);
  a136=(a136+a190);
  a155=(a155+a136);
  a136=(a032*a149);
  a190=(a034*a160);
  a136=(a136+a190);
  a136=(a130*a136);
  a190=(a163*a191);
  a189=(a031*a190);
  a136=(a136+a189);
  a155=(a155+a136);
  a136=(a126*a155);
  a193=(a193+a136);
  a136=(a153*a193);
  a136=(a000*a136);
  a189=(a143*a136);
  a151=(a151-a189);
  a189=(a134*a193);
  a185=(a133*a185);
  a192=(a042*a149);
  a187=(a045*a149);
  a187=(a128*a187);
  a195=(a044*a160);
  a187=(a187+a195);
  a192=(a192+a187);
  a187=(a048*a149);
  a195=(a051*a149);
  a195=(a128*a195);
  a194=(a050*a160);
  a195=(a195+a194);
  a187=(a187+a195);
  a187=(a129*a187);
  a191=(a047*a191);
  a187=(a187+a191);
  a192=(a192+a187);
  a187=(a054*a149);
  a160=(a056*a160);
  a187=(a187+a160);
  a187=(a130*a187);
  a190=(a053*a190);
  a187=(a187+a190);
  a192=(a192+a187);
  a187=(a126*a192);
  a185=(a185+a187);
  a185=(a131*a185);
  a189=(a189+a185);
  a185=(a115*a189);
  a187=(a151-a185);
  a190=(a147*a187);
  a160=(a152*a136);
  a191=(a093*a189);
  a169=(a169-a191);
  a191=(a160+a169);
  a195=(a110*a191);
  a194=(a137*a149);
  a188=(a116*a136);
  a188=(a194-a188);
  a178=(a142*a188);
  a195=(a195+a178);
  a190=(a190-a195);
  a190=(a141*a190);
  a195=(a176*a187);
  a178=(a173*a191);
  a196=(a175*a188);
  a178=(a178+a196);
  a195=(a195-a178);
  a195=(a174*a195);
  a190=(a190+a195);
  a187=(a040*a187);
  a191=(a107*a191);
  a188=(a062*a188);
  a191=(a191+a188);
  a187=(a187-a191);
  a187=(a177*a187);
  a190=(a190+a187);
  if (res[1]!=0) res[1][12]=a190;
  a190=(a138*a136);
  a157=(a157-a190);
  a189=(a120*a189);
  a190=(a157-a189);
  a187=(a110*a190);
  a151=(a151+a185);
  a185=(a142*a151);
  a187=(a187+a185);
  a185=(a122*a136);
  a191=(a147*a185);
  a187=(a187+a191);
  a187=(a164*a187);
  a191=(a173*a190);
  a188=(a175*a151);
  a191=(a191+a188);
  a188=(a176*a185);
  a191=(a191+a188);
  a191=(a170*a191);
  a187=(a187+a191);
  a190=(a107*a190);
  a151=(a062*a151);
  a190=(a190+a151);
  a185=(a040*a185);
  a190=(a190+a185);
  a190=(a182*a190);
  a187=(a187+a190);
  if (res[1]!=0) res[1][13]=a187;
  a169=(a169-a160);
  a160=(a142*a169);
  a136=(a121*a136);
  a194=(a194-a136);
  a136=(a110*a194);
  a160=(a160-a136);
  a157=(a157+a189);
  a189=(a147*a157);
  a160=(a160+a189);
  a160=(a168*a160);
  a189=(a175*a169);
  a136=(a173*a194);
  a189=(a189-a136);
  a136=(a176*a157);
  a189=(a189+a136);
  a189=(a166*a189);
  a160=(a160+a189);
  a169=(a062*a169);
  a194=(a107*a194);
  a169=(a169-a194);
  a157=(a040*a157);
  a169=(a169+a157);
  a169=(a156*a169);
  a160=(a160+a169);
  if (res[1]!=0) res[1][14]=a160;
  a192=(a192-a155);
  a192=(a192/a159);
  a193=(a158*a193);
  a193=(a127*a193);
  a192=(a192+a193);
  a193=(a138*a192);
  a193=(a193+a165);
  a165=(a144*a193);
  a155=(a152*a192);
  a160=(a155-a183);
  a160=(a180*a160);
  a165=(a165+a160);
  a160=(a121*a192);
  a149=(a132*a149);
  a160=(a160+a149);
  a160=(a171*a160);
  a165=(a165-a160);
  if (res[1]!=0) res[1][15]=a165;
  a165=(a143*a192);
  a165=(a165+a150);
  a150=(a144*a165);
  a160=(a116*a192);
  a160=(a160+a149);
  a160=(a180*a160);
  a150=(a150-a160);
  a155=(a155-a184);
  a155=(a171*a155);
  a150=(a150+a155);
  if (res[1]!=0) res[1][16]=a150;
  a165=(a180*a165);
  a192=(a122*a192);
  a192=(a144*a192);
  a165=(a165-a192);
  a193=(a171*a193);
  a165=(a165+a193);
  if (res[1]!=0) res[1][17]=a165;
  a165=1.7320508075688774e+00;
  a165=(a165*a001);
  a193=(a120*a165);
  a192=(a137*a193);
  a150=(a154*a165);
  a155=(a004*a150);
  a160=(a017*a155);
  a149=(a018*a150);
  a169=(a021*a150);
  a169=(a128*a169);
  a157=(a125*a155);
  a194=(a020*a157);
  a169=(a169+a194);
  a149=(a149+a169);
  a169=(a025*a150);
  a194=(a028*a150);
  a194=(a128*a194);
  a189=(a027*a157);
  a194=(a194+a189);
  a169=(a169+a194);
  a169=(a129*a169);
  a194=(a161*a157);
  a189=(a024*a194);
  a169=(a169+a189);
  a149=(a149+a169);
  a169=(a032*a150);
  a189=(a034*a157);
  a169=(a169+a189);
  a169=(a130*a169);
  a189=(a163*a194);
  a136=(a031*a189);
  a169=(a169+a136);
  a149=(a149+a169);
  a169=(a126*a149);
  a160=(a160+a169);
  a169=(a153*a160);
  a169=(a000*a169);
  a136=(a152*a169);
  a136=(a192-a136);
  a187=(a134*a160);
  a155=(a133*a155);
  a190=(a042*a150);
  a185=(a045*a150);
  a185=(a128*a185);
  a151=(a044*a157);
  a185=(a185+a151);
  a190=(a190+a185);
  a185=(a048*a150);
  a151=(a051*a150);
  a151=(a128*a151);
  a191=(a050*a157);
  a151=(a151+a191);
  a185=(a185+a151);
  a185=(a129*a185);
  a194=(a047*a194);
  a185=(a185+a194);
  a190=(a190+a185);
  a185=(a054*a150);
  a157=(a056*a157);
  a185=(a185+a157);
  a185=(a130*a185);
  a189=(a053*a189);
  a185=(a185+a189);
  a190=(a190+a185);
  a185=(a126*a190);
  a155=(a155+a185);
  a155=(a131*a155);
  a187=(a187+a155);
  a155=(a093*a187);
  a185=(a136+a155);
  a189=(a110*a185);
  a157=(a137*a150);
  a194=(a116*a169);
  a194=(a157-a194);
  a151=(a142*a194);
  a189=(a189-a151);
  a151=(a135*a165);
  a191=(a115*a187);
  a191=(a151-a191);
  a188=(a143*a169);
  a195=(a191-a188);
  a178=(a147*a195);
  a189=(a189+a178);
  a189=(a141*a189);
  a178=(a173*a185);
  a196=(a175*a194);
  a178=(a178-a196);
  a196=(a176*a195);
  a178=(a178+a196);
  a178=(a174*a178);
  a189=(a189+a178);
  a185=(a107*a185);
  a194=(a062*a194);
  a185=(a185-a194);
  a195=(a040*a195);
  a185=(a185+a195);
  a185=(a177*a185);
  a189=(a189+a185);
  if (res[1]!=0) res[1][18]=a189;
  a189=(a093*a165);
  a185=(a137*a189);
  a195=(a138*a169);
  a195=(a185-a195);
  a187=(a120*a187);
  a194=(a195-a187);
  a178=(a110*a194);
  a188=(a188+a191);
  a191=(a142*a188);
  a178=(a178-a191);
  a191=(a122*a169);
  a157=(a157-a191);
  a191=(a147*a157);
  a178=(a178-a191);
  a178=(a164*a178);
  a191=(a173*a194);
  a196=(a175*a188);
  a191=(a191-a196);
  a196=(a176*a157);
  a191=(a191-a196);
  a191=(a170*a191);
  a178=(a178+a191);
  a194=(a107*a194);
  a188=(a062*a188);
  a194=(a194-a188);
  a157=(a040*a157);
  a194=(a194-a157);
  a194=(a182*a194);
  a178=(a178+a194);
  if (res[1]!=0) res[1][19]=a178;
  a169=(a121*a169);
  a178=(a110*a169);
  a136=(a136-a155);
  a155=(a142*a136);
  a178=(a178+a155);
  a195=(a195+a187);
  a187=(a147*a195);
  a178=(a178+a187);
  a178=(a168*a178);
  a187=(a173*a169);
  a155=(a175*a136);
  a187=(a187+a155);
  a155=(a176*a195);
  a187=(a187+a155);
  a187=(a166*a187);
  a178=(a178+a187);
  a169=(a107*a169);
  a136=(a062*a136);
  a169=(a169+a136);
  a195=(a040*a195);
  a169=(a169+a195);
  a169=(a156*a169);
  a178=(a178+a169);
  if (res[1]!=0) res[1][20]=a178;
  a190=(a190-a149);
  a190=(a190/a159);
  a160=(a158*a160);
  a160=(a127*a160);
  a190=(a190+a160);
  a160=(a138*a190);
  a189=(a132*a189);
  a160=(a160+a189);
  a149=(a144*a160);
  a178=(a152*a190);
  a193=(a132*a193);
  a178=(a178+a193);
  a169=(a180*a178);
  a149=(a149+a169);
  a169=(a121*a190);
  a169=(a171*a169);
  a149=(a149-a169);
  if (res[1]!=0) res[1][21]=a149;
  a149=(a143*a190);
  a169=(a149-a184);
  a169=(a144*a169);
  a195=(a116*a190);
  a150=(a132*a150);
  a195=(a195+a150);
  a195=(a180*a195);
  a169=(a169-a195);
  a178=(a171*a178);
  a169=(a169+a178);
  if (res[1]!=0) res[1][22]=a169;
  a149=(a149-a183);
  a149=(a180*a149);
  a190=(a122*a190);
  a190=(a190+a150);
  a190=(a144*a190);
  a149=(a149-a190);
  a160=(a171*a160);
  a149=(a149+a160);
  if (res[1]!=0) res[1][23]=a149;
  a149=(a115*a165);
  a160=(a137*a149);
  a190=(a167*a165);
  a150=(a004*a190);
  a169=(a017*a150);
  a178=(a018*a190);
  a195=(a021*a190);
  a195=(a128*a195);
  a136=(a125*a150);
  a187=(a020*a136);
  a195=(a195+a187);
  a178=(a178+a195);
  a195=(a025*a190);
  a187=(a028*a190);
  a187=(a128*a187);
  a155=(a027*a136);
  a187=(a187+a155);
  a195=(a195+a187);
  a195=(a129*a195);
  a187=(a161*a136);
  a155=(a024*a187);
  a195=(a195+a155);
  a178=(a178+a195);
  a195=(a032*a190);
  a155=(a034*a136);
  a195=(a195+a155);
  a195=(a130*a195);
  a155=(a163*a187);
  a194=(a031*a155);
  a195=(a195+a194);
  a178=(a178+a195);
  a195=(a126*a178);
  a169=(a169+a195);
  a195=(a153*a169);
  a195=(a000*a195);
  a194=(a152*a195);
  a194=(a160-a194);
  a157=(a134*a169);
  a150=(a133*a150);
  a188=(a042*a190);
  a191=(a045*a190);
  a191=(a128*a191);
  a196=(a044*a136);
  a191=(a191+a196);
  a188=(a188+a191);
  a191=(a048*a190);
  a196=(a051*a190);
  a196=(a128*a196);
  a197=(a050*a136);
  a196=(a196+a197);
  a191=(a191+a196);
  a191=(a129*a191);
  a187=(a047*a187);
  a191=(a191+a187);
  a188=(a188+a191);
  a191=(a054*a190);
  a136=(a056*a136);
  a191=(a191+a136);
  a191=(a130*a191);
  a155=(a053*a155);
  a191=(a191+a155);
  a188=(a188+a191);
  a191=(a126*a188);
  a150=(a150+a191);
  a150=(a131*a150);
  a157=(a157+a150);
  a150=(a093*a157);
  a191=(a194+a150);
  a155=(a110*a191);
  a136=(a116*a195);
  a187=(a142*a136);
  a155=(a155+a187);
  a187=(a143*a195);
  a185=(a185-a187);
  a187=(a115*a157);
  a196=(a185-a187);
  a197=(a147*a196);
  a155=(a155+a197);
  a155=(a141*a155);
  a197=(a173*a191);
  a198=(a175*a136);
  a197=(a197+a198);
  a198=(a176*a196);
  a197=(a197+a198);
  a197=(a174*a197);
  a155=(a155+a197);
  a191=(a107*a191);
  a136=(a062*a136);
  a191=(a191+a136);
  a196=(a040*a196);
  a191=(a191+a196);
  a191=(a177*a191);
  a155=(a155+a191);
  if (res[1]!=0) res[1][24]=a155;
  a157=(a120*a157);
  a157=(a151-a157);
  a155=(a138*a195);
  a191=(a157-a155);
  a196=(a110*a191);
  a185=(a185+a187);
  a187=(a142*a185);
  a196=(a196+a187);
  a187=(a137*a190);
  a136=(a122*a195);
  a136=(a187-a136);
  a197=(a147*a136);
  a196=(a196-a197);
  a196=(a164*a196);
  a197=(a173*a191);
  a198=(a175*a185);
  a197=(a197+a198);
  a198=(a176*a136);
  a197=(a197-a198);
  a197=(a170*a197);
  a196=(a196+a197);
  a191=(a107*a191);
  a185=(a062*a185);
  a191=(a191+a185);
  a136=(a040*a136);
  a191=(a191-a136);
  a191=(a182*a191);
  a196=(a196+a191);
  if (res[1]!=0) res[1][25]=a196;
  a194=(a194-a150);
  a150=(a142*a194);
  a195=(a121*a195);
  a187=(a187-a195);
  a195=(a110*a187);
  a150=(a150-a195);
  a155=(a155+a157);
  a157=(a147*a155);
  a150=(a150-a157);
  a150=(a168*a150);
  a157=(a175*a194);
  a195=(a173*a187);
  a157=(a157-a195);
  a195=(a176*a155);
  a157=(a157-a195);
  a157=(a166*a157);
  a150=(a150+a157);
  a194=(a062*a194);
  a187=(a107*a187);
  a194=(a194-a187);
  a155=(a040*a155);
  a194=(a194-a155);
  a194=(a156*a194);
  a150=(a150+a194);
  if (res[1]!=0) res[1][26]=a150;
  a188=(a188-a178);
  a188=(a188/a159);
  a169=(a158*a169);
  a169=(a127*a169);
  a188=(a188+a169);
  a169=(a138*a188);
  a178=(a169-a183);
  a178=(a144*a178);
  a150=(a152*a188);
  a149=(a132*a149);
  a150=(a150+a149);
  a194=(a180*a150);
  a178=(a178+a194);
  a194=(a121*a188);
  a190=(a132*a190);
  a194=(a194+a190);
  a194=(a171*a194);
  a178=(a178-a194);
  if (res[1]!=0) res[1][27]=a178;
  a178=(a143*a188);
  a178=(a178+a189);
  a189=(a144*a178);
  a194=(a116*a188);
  a194=(a180*a194);
  a189=(a189-a194);
  a150=(a171*a150);
  a189=(a189+a150);
  if (res[1]!=0) res[1][28]=a189;
  a178=(a180*a178);
  a188=(a122*a188);
  a188=(a188+a190);
  a188=(a144*a188);
  a178=(a178-a188);
  a169=(a169-a184);
  a169=(a171*a169);
  a178=(a178+a169);
  if (res[1]!=0) res[1][29]=a178;
  a165=(a186*a165);
  a178=(a004*a165);
  a169=(a017*a178);
  a188=(a018*a165);
  a190=(a021*a165);
  a190=(a128*a190);
  a189=(a125*a178);
  a150=(a020*a189);
  a190=(a190+a150);
  a188=(a188+a190);
  a190=(a025*a165);
  a150=(a028*a165);
  a150=(a128*a150);
  a194=(a027*a189);
  a150=(a150+a194);
  a190=(a190+a150);
  a190=(a129*a190);
  a150=(a161*a189);
  a194=(a024*a150);
  a190=(a190+a194);
  a188=(a188+a190);
  a190=(a032*a165);
  a194=(a034*a189);
  a190=(a190+a194);
  a190=(a130*a190);
  a194=(a163*a150);
  a155=(a031*a194);
  a190=(a190+a155);
  a188=(a188+a190);
  a190=(a126*a188);
  a169=(a169+a190);
  a190=(a153*a169);
  a190=(a000*a190);
  a155=(a143*a190);
  a192=(a192-a155);
  a155=(a134*a169);
  a178=(a133*a178);
  a187=(a042*a165);
  a157=(a045*a165);
  a157=(a128*a157);
  a195=(a044*a189);
  a157=(a157+a195);
  a187=(a187+a157);
  a157=(a048*a165);
  a195=(a051*a165);
  a195=(a128*a195);
  a196=(a050*a189);
  a195=(a195+a196);
  a157=(a157+a195);
  a157=(a129*a157);
  a150=(a047*a150);
  a157=(a157+a150);
  a187=(a187+a157);
  a157=(a054*a165);
  a189=(a056*a189);
  a157=(a157+a189);
  a157=(a130*a157);
  a194=(a053*a194);
  a157=(a157+a194);
  a187=(a187+a157);
  a157=(a126*a187);
  a178=(a178+a157);
  a178=(a131*a178);
  a155=(a155+a178);
  a178=(a115*a155);
  a157=(a192-a178);
  a194=(a147*a157);
  a189=(a152*a190);
  a150=(a093*a155);
  a151=(a151-a150);
  a150=(a189+a151);
  a195=(a110*a150);
  a196=(a137*a165);
  a191=(a116*a190);
  a191=(a196-a191);
  a136=(a142*a191);
  a195=(a195+a136);
  a194=(a194-a195);
  a194=(a141*a194);
  a195=(a176*a157);
  a136=(a173*a150);
  a185=(a175*a191);
  a136=(a136+a185);
  a195=(a195-a136);
  a195=(a174*a195);
  a194=(a194+a195);
  a157=(a040*a157);
  a150=(a107*a150);
  a191=(a062*a191);
  a150=(a150+a191);
  a157=(a157-a150);
  a157=(a177*a157);
  a194=(a194+a157);
  if (res[1]!=0) res[1][30]=a194;
  a194=(a138*a190);
  a160=(a160-a194);
  a155=(a120*a155);
  a194=(a160-a155);
  a157=(a110*a194);
  a192=(a192+a178);
  a178=(a142*a192);
  a157=(a157+a178);
  a178=(a122*a190);
  a150=(a147*a178);
  a157=(a157+a150);
  a157=(a164*a157);
  a150=(a173*a194);
  a191=(a175*a192);
  a150=(a150+a191);
  a191=(a176*a178);
  a150=(a150+a191);
  a150=(a170*a150);
  a157=(a157+a150);
  a194=(a107*a194);
  a192=(a062*a192);
  a194=(a194+a192);
  a178=(a040*a178);
  a194=(a194+a178);
  a194=(a182*a194);
  a157=(a157+a194);
  if (res[1]!=0) res[1][31]=a157;
  a151=(a151-a189);
  a189=(a142*a151);
  a190=(a121*a190);
  a196=(a196-a190);
  a190=(a110*a196);
  a189=(a189-a190);
  a160=(a160+a155);
  a155=(a147*a160);
  a189=(a189+a155);
  a189=(a168*a189);
  a155=(a175*a151);
  a190=(a173*a196);
  a155=(a155-a190);
  a190=(a176*a160);
  a155=(a155+a190);
  a155=(a166*a155);
  a189=(a189+a155);
  a151=(a062*a151);
  a196=(a107*a196);
  a151=(a151-a196);
  a160=(a040*a160);
  a151=(a151+a160);
  a151=(a156*a151);
  a189=(a189+a151);
  if (res[1]!=0) res[1][32]=a189;
  a187=(a187-a188);
  a187=(a187/a159);
  a169=(a158*a169);
  a169=(a127*a169);
  a187=(a187+a169);
  a169=(a138*a187);
  a169=(a169+a149);
  a149=(a144*a169);
  a188=(a152*a187);
  a184=(a188-a184);
  a184=(a180*a184);
  a149=(a149+a184);
  a184=(a121*a187);
  a165=(a132*a165);
  a184=(a184+a165);
  a184=(a171*a184);
  a149=(a149-a184);
  if (res[1]!=0) res[1][33]=a149;
  a149=(a143*a187);
  a149=(a149+a193);
  a193=(a144*a149);
  a184=(a116*a187);
  a184=(a184+a165);
  a184=(a180*a184);
  a193=(a193-a184);
  a188=(a188-a183);
  a188=(a171*a188);
  a193=(a193+a188);
  if (res[1]!=0) res[1][34]=a193;
  a149=(a180*a149);
  a187=(a122*a187);
  a187=(a144*a187);
  a149=(a149-a187);
  a169=(a171*a169);
  a149=(a149+a169);
  if (res[1]!=0) res[1][35]=a149;
  if (res[1]!=0) res[1][36]=a066;
  if (res[1]!=0) res[1][37]=a066;
  if (res[1]!=0) res[1][38]=a066;
  a149=(a132*a121);
  a149=(a003-a149);
  if (res[1]!=0) res[1][39]=a149;
  a149=(a132*a152);
  a169=(a000*a093);
  a169=(a149-a169);
  if (res[1]!=0) res[1][40]=a169;
  a169=(a132*a138);
  a187=-5.0000000000000000e-01;
  a193=(a187*a120);
  a193=(a169-a193);
  if (res[1]!=0) res[1][41]=a193;
  if (res[1]!=0) res[1][42]=a066;
  if (res[1]!=0) res[1][43]=a066;
  if (res[1]!=0) res[1][44]=a066;
  a193=(a187*a093);
  a149=(a149-a193);
  if (res[1]!=0) res[1][45]=a149;
  a149=(a132*a116);
  a149=(a003-a149);
  if (res[1]!=0) res[1][46]=a149;
  a149=(a132*a143);
  a193=(a000*a115);
  a193=(a149-a193);
  if (res[1]!=0) res[1][47]=a193;
  if (res[1]!=0) res[1][48]=a066;
  if (res[1]!=0) res[1][49]=a066;
  if (res[1]!=0) res[1][50]=a066;
  a193=(a000*a120);
  a169=(a169-a193);
  if (res[1]!=0) res[1][51]=a169;
  a169=(a187*a115);
  a149=(a149-a169);
  if (res[1]!=0) res[1][52]=a149;
  a149=(a132*a122);
  a149=(a003-a149);
  if (res[1]!=0) res[1][53]=a149;
  a149=(a181*a147);
  a169=(a145*a142);
  a149=(a149-a169);
  a149=(a141*a149);
  a169=(a181*a176);
  a193=(a145*a175);
  a169=(a169-a193);
  a169=(a174*a169);
  a149=(a149+a169);
  a169=(a181*a040);
  a193=(a145*a062);
  a169=(a169-a193);
  a169=(a177*a169);
  a149=(a149+a169);
  if (res[2]!=0) res[2][0]=a149;
  a149=(a146*a147);
  a169=(a148*a142);
  a149=(a149-a169);
  a149=(a164*a149);
  a169=(a146*a176);
  a193=(a148*a175);
  a169=(a169-a193);
  a169=(a170*a169);
  a149=(a149+a169);
  a169=(a146*a040);
  a193=(a148*a062);
  a169=(a169-a193);
  a169=(a182*a169);
  a149=(a149+a169);
  if (res[2]!=0) res[2][1]=a149;
  a149=(a162*a147);
  a169=(a139*a142);
  a149=(a149-a169);
  a149=(a168*a149);
  a169=(a162*a176);
  a193=(a139*a175);
  a169=(a169-a193);
  a169=(a166*a169);
  a149=(a149+a169);
  a169=(a162*a040);
  a193=(a139*a062);
  a169=(a169-a193);
  a169=(a156*a169);
  a149=(a149+a169);
  if (res[2]!=0) res[2][2]=a149;
  if (res[2]!=0) res[2][3]=a066;
  if (res[2]!=0) res[2][4]=a066;
  if (res[2]!=0) res[2][5]=a066;
  a149=(a145*a110);
  a169=(a172*a147);
  a149=(a149-a169);
  a149=(a141*a149);
  a169=(a145*a173);
  a193=(a172*a176);
  a169=(a169-a193);
  a169=(a174*a169);
  a149=(a149+a169);
  a145=(a145*a107);
  a169=(a172*a040);
  a145=(a145-a169);
  a145=(a177*a145);
  a149=(a149+a145);
  if (res[2]!=0) res[2][6]=a149;
  a149=(a148*a110);
  a145=(a140*a147);
  a149=(a149-a145);
  a149=(a164*a149);
  a145=(a148*a173);
  a169=(a140*a176);
  a145=(a145-a169);
  a145=(a170*a145);
  a149=(a149+a145);
  a148=(a148*a107);
  a145=(a140*a040);
  a148=(a148-a145);
  a148=(a182*a148);
  a149=(a149+a148);
  if (res[2]!=0) res[2][7]=a149;
  a149=(a139*a110);
  a148=(a124*a147);
  a149=(a149-a148);
  a149=(a168*a149);
  a148=(a139*a173);
  a145=(a124*a176);
  a148=(a148-a145);
  a148=(a166*a148);
  a149=(a149+a148);
  a139=(a139*a107);
  a148=(a124*a040);
  a139=(a139-a148);
  a139=(a156*a139);
  a149=(a149+a139);
  if (res[2]!=0) res[2][8]=a149;
  if (res[2]!=0) res[2][9]=a066;
  if (res[2]!=0) res[2][10]=a066;
  if (res[2]!=0) res[2][11]=a066;
  a149=(a172*a142);
  a139=(a181*a110);
  a149=(a149-a139);
  a149=(a141*a149);
  a139=(a172*a175);
  a148=(a181*a173);
  a139=(a139-a148);
  a139=(a174*a139);
  a149=(a149+a139);
  a172=(a172*a062);
  a181=(a181*a107);
  a172=(a172-a181);
  a172=(a177*a172);
  a149=(a149+a172);
  if (res[2]!=0) res[2][12]=a149;
  a149=(a140*a142);
  a172=(a146*a110);
  a149=(a149-a172);
  a149=(a164*a149);
  a172=(a140*a175);
  a181=(a146*a173);
  a172=(a172-a181);
  a172=(a170*a172);
  a149=(a149+a172);
  a140=(a140*a062);
  a146=(a146*a107);
  a140=(a140-a146);
  a140=(a182*a140);
  a149=(a149+a140);
  if (res[2]!=0) res[2][13]=a149;
  a149=(a124*a142);
  a140=(a162*a110);
  a149=(a149-a140);
  a149=(a168*a149);
  a140=(a124*a175);
  a146=(a162*a173);
  a140=(a140-a146);
  a140=(a166*a140);
  a149=(a149+a140);
  a124=(a124*a062);
  a162=(a162*a107);
  a124=(a124-a162);
  a124=(a156*a124);
  a149=(a149+a124);
  if (res[2]!=0) res[2][14]=a149;
  if (res[2]!=0) res[2][15]=a066;
  if (res[2]!=0) res[2][16]=a066;
  if (res[2]!=0) res[2][17]=a066;
  if (res[2]!=0) res[2][18]=a066;
  if (res[2]!=0) res[2][19]=a066;
  if (res[2]!=0) res[2][20]=a066;
  if (res[2]!=0) res[2][21]=a066;
  if (res[2]!=0) res[2][22]=a066;
  if (res[2]!=0) res[2][23]=a066;
  if (res[2]!=0) res[2][24]=a066;
  if (res[2]!=0) res[2][25]=a066;
  if (res[2]!=0) res[2][26]=a066;
  if (res[2]!=0) res[2][27]=a066;
  if (res[2]!=0) res[2][28]=a066;
  if (res[2]!=0) res[2][29]=a066;
  if (res[2]!=0) res[2][30]=a066;
  if (res[2]!=0) res[2][31]=a066;
  if (res[2]!=0) res[2][32]=a066;
  if (res[2]!=0) res[2][33]=a066;
  if (res[2]!=0) res[2][34]=a066;
  if (res[2]!=0) res[2][35]=a066;
  a149=1.5000000000000002e+00;
  a124=(a037*a057);
  a124=(a036+a124);
  a124=(a004*a124);
  a162=(a124*a067);
  a140=(a038*a009);
  a146=(a162-a140);
  a172=(a124*a010);
  a172=(a003-a172);
  a181=(a172*a041);
  a139=(a038*a013);
  a148=(a124*a063);
  a145=(a139+a148);
  a169=(a145*a117);
  a181=(a181+a169);
  a169=(a146*a123);
  a181=(a181+a169);
  a169=(a146*a181);
  a193=(a038*a006);
  a188=(a124*a061);
  a183=(a193+a188);
  a184=5.;
  a148=(a148-a139);
  a139=(a148*a041);
  a165=(a124*a007);
  a165=(a003-a165);
  a189=(a165*a117);
  a139=(a139+a189);
  a189=(a183*a123);
  a139=(a139+a189);
  a189=(a184*a139);
  a151=(a183*a189);
  a169=(a169+a151);
  a151=(a124*a011);
  a151=(a003-a151);
  a160=6.;
  a140=(a140+a162);
  a162=(a140*a041);
  a188=(a188-a193);
  a193=(a188*a117);
  a162=(a162+a193);
  a193=(a151*a123);
  a162=(a162+a193);
  a193=(a160*a162);
  a196=(a151*a193);
  a169=(a169+a196);
  a169=(a169-a144);
  a196=(a149*a169);
  a155=-3.2320508075688776e+00;
  a190=(a090*a099);
  a190=(a089+a190);
  a190=(a004*a190);
  a157=(a190*a108);
  a194=(a091*a073);
  a178=(a157-a194);
  a192=(a190*a074);
  a192=(a003-a192);
  a150=(a192*a114);
  a191=(a091*a077);
  a195=(a190*a104);
  a136=(a191+a195);
  a185=(a136*a119);
  a150=(a150+a185);
  a185=(a178*a113);
  a150=(a150+a185);
  a185=(a178*a150);
  a197=(a091*a070);
  a198=(a190*a103);
  a199=(a197+a198);
  a195=(a195-a191);
  a191=(a195*a114);
  a200=(a190*a071);
  a200=(a003-a200);
  a201=(a200*a119);
  a191=(a191+a201);
  a201=(a199*a113);
  a191=(a191+a201);
  a201=(a184*a191);
  a202=(a199*a201);
  a185=(a185+a202);
  a202=(a190*a075);
  a202=(a003-a202);
  a194=(a194+a157);
  a157=(a194*a114);
  a198=(a198-a197);
  a197=(a198*a119);
  a157=(a157+a197);
  a197=(a202*a113);
  a157=(a157+a197);
  a197=(a160*a157);
  a203=(a202*a197);
  a185=(a185+a203);
  a185=(a185-a144);
  a203=(a155*a185);
  a196=(a196+a203);
  a043=(a043-a019);
  a043=(a179+a043);
  a019=(a158*a037);
  a043=(a043/a019);
  a203=(a001*a144);
  a203=(a000*a203);
  a204=5.3867513459481287e-01;
  a205=2.3205080756887719e-01;
  a169=(a205*a169);
  a185=(a149*a185);
  a169=(a169+a185);
  a185=(a001*a169);
  a206=(a204*a185);
  a206=(a203+a206);
  a207=(a001*a196);
  a208=(a004*a207);
  a206=(a206+a208);
  a208=(a139*a206);
  a209=(a043*a208);
  a210=(a001*a180);
  a210=(a000*a210);
  a211=(a145*a181);
  a212=(a165*a189);
  a211=(a211+a212);
  a212=(a188*a193);
  a211=(a211+a212);
  a211=(a211-a180);
  a212=(a205*a211);
  a213=(a136*a150);
  a214=(a200*a201);
  a213=(a213+a214);
  a214=(a198*a197);
  a213=(a213+a214);
  a213=(a213-a180);
  a214=(a149*a213);
  a212=(a212+a214);
  a214=(a001*a212);
  a215=(a204*a214);
  a215=(a210+a215);
  a211=(a149*a211);
  a213=(a155*a213);
  a211=(a211+a213);
  a213=(a001*a211);
  a216=(a004*a213);
  a215=(a215+a216);
  a216=(a162*a215);
  a217=(a043*a216);
  a209=(a209+a217);
  a217=(a009*a209);
  a217=(a196-a217);
  a218=(a181*a215);
  a219=(a187*a218);
  a217=(a217+a219);
  a219=(a181*a206);
  a220=(a043*a219);
  a221=(a001*a171);
  a221=(a000*a221);
  a222=(a172*a181);
  a223=(a148*a189);
  a222=(a222+a223);
  a223=(a140*a193);
  a222=(a222+a223);
  a222=(a222-a171);
  a223=(a205*a222);
  a224=(a192*a150);
  a225=(a195*a201);
  a224=(a224+a225);
  a225=(a194*a197);
  a224=(a224+a225);
  a224=(a224-a171);
  a225=(a149*a224);
  a223=(a223+a225);
  a225=(a001*a223);
  a226=(a204*a225);
  a226=(a221+a226);
  a222=(a149*a222);
  a224=(a155*a224);
  a222=(a222+a224);
  a224=(a001*a222);
  a227=(a004*a224);
  a226=(a226+a227);
  a227=(a162*a226);
  a228=(a043*a227);
  a220=(a220+a228);
  a228=(a006*a220);
  a217=(a217-a228);
  a228=(a139*a226);
  a229=(a000*a228);
  a217=(a217+a229);
  a229=(2.*a013);
  a230=(a139*a215);
  a231=(a043*a230);
  a232=(a181*a226);
  a233=(a043*a232);
  a234=(a231+a233);
  a235=(a229*a234);
  a217=(a217+a235);
  a235=(a043/a019);
  a236=(a162*a206);
  a237=(a011*a236);
  a238=(a061*a208);
  a237=(a237-a238);
  a238=(a067*a219);
  a237=(a237-a238);
  a238=(a061*a216);
  a237=(a237-a238);
  a238=(a007*a230);
  a237=(a237+a238);
  a238=(a063*a218);
  a237=(a237-a238);
  a238=(a067*a227);
  a237=(a237-a238);
  a238=(a063*a228);
  a237=(a237-a238);
  a238=(a010*a232);
  a237=(a237+a238);
  a238=(a235*a237);
  a238=(a158*a238);
  a239=(a016*a238);
  a240=(a237/a019);
  a239=(a239-a240);
  a241=(a035*a239);
  a242=(a032*a241);
  a243=(a030*a239);
  a244=(a023*a243);
  a244=(a028*a244);
  a242=(a242+a244);
  a244=(a025*a243);
  a242=(a242+a244);
  a244=(a023*a239);
  a244=(a021*a244);
  a242=(a242+a244);
  a244=(a018*a239);
  a242=(a242+a244);
  a244=(a035*a240);
  a245=(a054*a244);
  a242=(a242+a245);
  a245=(a030*a240);
  a246=(a023*a245);
  a246=(a051*a246);
  a242=(a242+a246);
  a246=(a048*a245);
  a242=(a242+a246);
  a246=(a036*a238);
  a015=(a000*a015);
  a241=(a034*a241);
  a247=(2.*a023);
  a248=(2.*a030);
  a249=(a033*a239);
  a250=(a248*a249);
  a251=(a026*a239);
  a250=(a250+a251);
  a251=(a247*a250);
  a241=(a241+a251);
  a251=(a029*a243);
  a241=(a241+a251);
  a251=(a022*a239);
  a241=(a241+a251);
  a251=(a015*a241);
  a246=(a246+a251);
  a244=(a056*a244);
  a251=(a055*a240);
  a252=(a248*a251);
  a253=(a049*a240);
  a252=(a252+a253);
  a253=(a247*a252);
  a244=(a244+a253);
  a253=(a052*a245);
  a244=(a244+a253);
  a253=(a046*a240);
  a244=(a244+a253);
  a253=(a015*a244);
  a246=(a246+a253);
  a246=(a004*a246);
  a242=(a242+a246);
  a246=(a023*a240);
  a246=(a045*a246);
  a242=(a242+a246);
  a246=(a042*a240);
  a242=(a242+a246);
  a246=(a229*a242);
  a217=(a217+a246);
  a246=(2.*a006);
  a253=(a246*a005);
  a254=(2.*a009);
  a255=(a254*a008);
  a256=(a253+a255);
  a257=(a229*a012);
  a258=(a256+a257);
  a259=(a042*a258);
  a260=(a045*a258);
  a261=(a023*a260);
  a262=(a004*a258);
  a263=(a015*a262);
  a264=(a046*a263);
  a261=(a261+a264);
  a259=(a259+a261);
  a261=(a048*a258);
  a264=(a051*a258);
  a265=(a023*a264);
  a266=(a052*a263);
  a265=(a265+a266);
  a261=(a261+a265);
  a265=(a030*a261);
  a266=(a247*a263);
  a267=(a049*a266);
  a265=(a265+a267);
  a259=(a259+a265);
  a265=(a054*a258);
  a267=(a056*a263);
  a265=(a265+a267);
  a267=(a035*a265);
  a268=(a248*a266);
  a269=(a055*a268);
  a267=(a267+a269);
  a259=(a259+a267);
  a267=(a018*a258);
  a269=(a021*a258);
  a270=(a023*a269);
  a271=(a022*a263);
  a270=(a270+a271);
  a267=(a267+a270);
  a270=(a025*a258);
  a271=(a028*a258);
  a272=(a023*a271);
  a273=(a029*a263);
  a272=(a272+a273);
  a270=(a270+a272);
  a272=(a030*a270);
  a273=(a026*a266);
  a272=(a272+a273);
  a267=(a267+a272);
  a272=(a032*a258);
  a273=(a034*a263);
  a272=(a272+a273);
  a273=(a035*a272);
  a274=(a033*a268);
  a273=(a273+a274);
  a267=(a267+a273);
  a273=(a259-a267);
  a273=(a273/a019);
  a274=(a036*a262);
  a275=(a016*a267);
  a274=(a274+a275);
  a275=(a158*a274);
  a276=(a235*a275);
  a273=(a273+a276);
  a276=(a067*a273);
  a277=(a013*a005);
  a278=(a006*a012);
  a277=(a277+a278);
  a278=(a043*a277);
  a276=(a276+a278);
  a278=(a000*a008);
  a279=(a276-a278);
  a279=(a217*a279);
  a280=(a043*a067);
  a281=(a000*a009);
  a282=(a280-a281);
  a283=(a037*a259);
  a284=(a057*a274);
  a283=(a283-a284);
  a283=(a267+a283);
  a283=(a004*a283);
  a284=(a067*a283);
  a285=(a124*a277);
  a284=(a284+a285);
  a285=(a038*a008);
  a286=(2.*a037);
  a286=(a286*a274);
  a286=(a000*a286);
  a287=(a009*a286);
  a285=(a285-a287);
  a287=(a284-a285);
  a288=(a181*a287);
  a289=(a038*a012);
  a290=(a013*a286);
  a289=(a289-a290);
  a290=(a063*a283);
  a291=(a009*a005);
  a292=(a006*a008);
  a291=(a291+a292);
  a292=(a124*a291);
  a290=(a290+a292);
  a292=(a289+a290);
  a293=(a117*a292);
  a294=(a010*a283);
  a255=(a255+a257);
  a295=(a124*a255);
  a294=(a294+a295);
  a295=(a041*a294);
  a293=(a293-a295);
  a287=(a123*a287);
  a293=(a293+a287);
  a146=(a146*a293);
  a288=(a288+a146);
  a146=(a038*a005);
  a287=(a006*a286);
  a146=(a146-a287);
  a287=(a061*a283);
  a295=(a013*a008);
  a296=(a009*a012);
  a295=(a295+a296);
  a296=(a124*a295);
  a287=(a287+a296);
  a296=(a146+a287);
  a297=(a189*a296);
  a290=(a290-a289);
  a289=(a041*a290);
  a298=(a007*a283);
  a257=(a257+a253);
  a253=(a124*a257);
  a298=(a298+a253);
  a253=(a117*a298);
  a289=(a289-a253);
  a296=(a123*a296);
  a289=(a289+a296);
  a296=(a184*a289);
  a183=(a183*a296);
  a297=(a297+a183);
  a288=(a288+a297);
  a285=(a285+a284);
  a041=(a041*a285);
  a287=(a287-a146);
  a117=(a117*a287);
  a041=(a041+a117);
  a283=(a011*a283);
  a124=(a124*a256);
  a283=(a283+a124);
  a123=(a123*a283);
  a041=(a041-a123);
  a123=(a160*a041);
  a151=(a151*a123);
  a283=(a193*a283);
  a151=(a151-a283);
  a288=(a288+a151);
  a151=(a149*a288);
  a283=(2.*a070);
  a124=(a283*a069);
  a117=(2.*a073);
  a146=(a117*a072);
  a284=(a124+a146);
  a297=(2.*a077);
  a183=(a297*a076);
  a253=(a284+a183);
  a299=(a018*a253);
  a300=(a021*a253);
  a301=(a083*a300);
  a079=(a000*a079);
  a302=(a004*a253);
  a303=(a079*a302);
  a304=(a082*a303);
  a301=(a301+a304);
  a299=(a299+a301);
  a301=(a025*a253);
  a304=(a028*a253);
  a305=(a083*a304);
  a306=(a085*a303);
  a305=(a305+a306);
  a301=(a301+a305);
  a305=(a086*a301);
  a306=(2.*a083);
  a307=(a306*a303);
  a308=(a084*a307);
  a305=(a305+a308);
  a299=(a299+a305);
  a305=(a032*a253);
  a308=(a034*a303);
  a305=(a305+a308);
  a308=(a088*a305);
  a309=(2.*a086);
  a310=(a309*a307);
  a311=(a087*a310);
  a308=(a308+a311);
  a299=(a299+a308);
  a308=(a042*a253);
  a311=(a045*a253);
  a312=(a083*a311);
  a313=(a095*a303);
  a312=(a312+a313);
  a308=(a308+a312);
  a312=(a048*a253);
  a313=(a051*a253);
  a314=(a083*a313);
  a315=(a097*a303);
  a314=(a314+a315);
  a312=(a312+a314);
  a314=(a086*a312);
  a315=(a096*a307);
  a314=(a314+a315);
  a308=(a308+a314);
  a314=(a054*a253);
  a315=(a056*a303);
  a314=(a314+a315);
  a315=(a088*a314);
  a316=(a098*a310);
  a315=(a315+a316);
  a308=(a308+a315);
  a315=(a090*a308);
  a316=(a089*a302);
  a317=(a080*a299);
  a316=(a316+a317);
  a317=(a099*a316);
  a315=(a315-a317);
  a315=(a299+a315);
  a315=(a004*a315);
  a317=(a108*a315);
  a318=(a077*a069);
  a319=(a070*a076);
  a318=(a318+a319);
  a319=(a190*a318);
  a317=(a317+a319);
  a319=(a091*a072);
  a320=(2.*a090);
  a320=(a320*a316);
  a320=(a000*a320);
  a321=(a073*a320);
  a319=(a319-a321);
  a321=(a317-a319);
  a322=(a150*a321);
  a323=(a091*a076);
  a324=(a077*a320);
  a323=(a323-a324);
  a324=(a104*a315);
  a325=(a073*a069);
  a326=(a070*a072);
  a325=(a325+a326);
  a326=(a190*a325);
  a324=(a324+a326);
  a326=(a323+a324);
  a327=(a119*a326);
  a328=(a074*a315);
  a146=(a146+a183);
  a329=(a190*a146);
  a328=(a328+a329);
  a329=(a114*a328);
  a327=(a327-a329);
  a321=(a113*a321);
  a327=(a327+a321);
  a178=(a178*a327);
  a322=(a322+a178);
  a178=(a091*a069);
  a321=(a070*a320);
  a178=(a178-a321);
  a321=(a103*a315);
  a329=(a077*a072);
  a330=(a073*a076);
  a329=(a329+a330);
  a330=(a190*a329);
  a321=(a321+a330);
  a330=(a178+a321);
  a331=(a201*a330);
  a324=(a324-a323);
  a323=(a114*a324);
  a332=(a071*a315);
  a183=(a183+a124);
  a124=(a190*a183);
  a332=(a332+a124);
  a124=(a119*a332);
  a323=(a323-a124);
  a330=(a113*a330);
  a323=(a323+a330);
  a184=(a184*a323);
  a199=(a199*a184);
  a331=(a331+a199);
  a322=(a322+a331);
  a319=(a319+a317);
  a114=(a114*a319);
  a321=(a321-a178);
  a119=(a119*a321);
  a114=(a114+a119);
  a315=(a075*a315);
  a190=(a190*a284);
  a315=(a315+a190);
  a113=(a113*a315);
  a114=(a114-a113);
  a160=(a160*a114);
  a202=(a202*a160);
  a315=(a197*a315);
  a202=(a202-a315);
  a322=(a322+a202);
  a202=(a155*a322);
  a151=(a151+a202);
  a202=(a209*a008);
  a315=(a208*a273);
  a113=(a206*a289);
  a190=(a000*a144);
  a288=(a205*a288);
  a322=(a149*a322);
  a288=(a288+a322);
  a322=(a001*a288);
  a322=(a169+a322);
  a119=(a204*a322);
  a119=(a190+a119);
  a178=(a001*a151);
  a196=(a196+a178);
  a178=(a004*a196);
  a119=(a119+a178);
  a178=(a139*a119);
  a113=(a113+a178);
  a178=(a043*a113);
  a315=(a315+a178);
  a178=(a216*a273);
  a317=(a215*a041);
  a331=(a000*a180);
  a292=(a181*a292);
  a145=(a145*a293);
  a292=(a292+a145);
  a165=(a165*a296);
  a298=(a189*a298);
  a165=(a165-a298);
  a292=(a292+a165);
  a287=(a193*a287);
  a188=(a188*a123);
  a287=(a287+a188);
  a292=(a292+a287);
  a287=(a205*a292);
  a326=(a150*a326);
  a136=(a136*a327);
  a326=(a326+a136);
  a200=(a200*a184);
  a332=(a201*a332);
  a200=(a200-a332);
  a326=(a326+a200);
  a321=(a197*a321);
  a198=(a198*a160);
  a321=(a321+a198);
  a326=(a326+a321);
  a321=(a149*a326);
  a287=(a287+a321);
  a321=(a001*a287);
  a321=(a212+a321);
  a198=(a204*a321);
  a198=(a331+a198);
  a292=(a149*a292);
  a326=(a155*a326);
  a292=(a292+a326);
  a326=(a001*a292);
  a326=(a211+a326);
  a200=(a004*a326);
  a198=(a198+a200);
  a200=(a162*a198);
  a317=(a317+a200);
  a200=(a043*a317);
  a178=(a178+a200);
  a315=(a315+a178);
  a178=(a009*a315);
  a202=(a202+a178);
  a151=(a151-a202);
  a202=(a215*a293);
  a178=(a181*a198);
  a202=(a202+a178);
  a178=(a187*a202);
  a151=(a151+a178);
  a178=(a220*a005);
  a200=(a219*a273);
  a332=(a206*a293);
  a136=(a181*a119);
  a332=(a332+a136);
  a136=(a043*a332);
  a200=(a200+a136);
  a136=(a227*a273);
  a188=(a226*a041);
  a165=(a000*a171);
  a172=(a172*a293);
  a294=(a181*a294);
  a172=(a172-a294);
  a189=(a189*a290);
  a148=(a148*a296);
  a189=(a189+a148);
  a172=(a172+a189);
  a193=(a193*a285);
  a140=(a140*a123);
  a193=(a193+a140);
  a172=(a172+a193);
  a205=(a205*a172);
  a192=(a192*a327);
  a328=(a150*a328);
  a192=(a192-a328);
  a201=(a201*a324);
  a195=(a195*a184);
  a201=(a201+a195);
  a192=(a192+a201);
  a197=(a197*a319);
  a194=(a194*a160);
  a197=(a197+a194);
  a192=(a192+a197);
  a197=(a149*a192);
  a205=(a205+a197);
  a197=(a001*a205);
  a197=(a223+a197);
  a204=(a204*a197);
  a204=(a165+a204);
  a149=(a149*a172);
  a155=(a155*a192);
  a149=(a149+a155);
  a155=(a001*a149);
  a155=(a222+a155);
  a192=(a004*a155);
  a204=(a204+a192);
  a192=(a162*a204);
  a188=(a188+a192);
  a192=(a043*a188);
  a136=(a136+a192);
  a200=(a200+a136);
  a136=(a006*a200);
  a178=(a178+a136);
  a151=(a151-a178);
  a178=(a226*a289);
  a136=(a139*a204);
  a178=(a178+a136);
  a136=(a000*a178);
  a151=(a151+a136);
  a136=(2.*a012);
  a234=(a234*a136);
  a192=(a230*a273);
  a215=(a215*a289);
  a198=(a139*a198);
  a215=(a215+a198);
  a198=(a043*a215);
  a192=(a192+a198);
  a198=(a232*a273);
  a226=(a226*a293);
  a204=(a181*a204);
  a226=(a226+a204);
  a204=(a043*a226);
  a198=(a198+a204);
  a204=(a192+a198);
  a204=(a229*a204);
  a234=(a234+a204);
  a151=(a151+a234);
  a136=(a242*a136);
  a234=(a239*a268);
  a204=(a238*a262);
  a172=(a273/a019);
  a194=(a235/a019);
  a194=(a194*a275);
  a172=(a172+a194);
  a237=(a237*a172);
  a172=(a236*a256);
  a206=(a206*a041);
  a119=(a162*a119);
  a206=(a206+a119);
  a119=(a011*a206);
  a172=(a172+a119);
  a119=(a208*a295);
  a194=(a061*a113);
  a119=(a119+a194);
  a172=(a172-a119);
  a119=(a219*a277);
  a194=(a067*a332);
  a119=(a119+a194);
  a172=(a172-a119);
  a119=(a216*a295);
  a194=(a061*a317);
  a119=(a119+a194);
  a172=(a172-a119);
  a230=(a230*a257);
  a215=(a007*a215);
  a230=(a230+a215);
  a172=(a172+a230);
  a230=(a218*a291);
  a215=(a063*a202);
  a230=(a230+a215);
  a172=(a172-a230);
  a230=(a227*a277);
  a215=(a067*a188);
  a230=(a230+a215);
  a172=(a172-a230);
  a230=(a228*a291);
  a215=(a063*a178);
  a230=(a230+a215);
  a172=(a172-a230);
  a232=(a232*a255);
  a226=(a010*a226);
  a232=(a232+a226);
  a172=(a172+a232);
  a235=(a235*a172);
  a237=(a237+a235);
  a237=(a158*a237);
  a235=(a016*a237);
  a204=(a204+a235);
  a172=(a172/a019);
  a019=(a240/a019);
  a019=(a019*a275);
  a172=(a172+a019);
  a204=(a204-a172);
  a019=(a035*a204);
  a234=(a234+a019);
  a019=(a032*a234);
  a275=(a243*a263);
  a235=(a239*a266);
  a232=(a030*a204);
  a235=(a235+a232);
  a232=(a023*a235);
  a275=(a275+a232);
  a275=(a028*a275);
  a019=(a019+a275);
  a275=(a025*a235);
  a019=(a019+a275);
  a275=(a239*a263);
  a232=(a023*a204);
  a275=(a275+a232);
  a275=(a021*a275);
  a019=(a019+a275);
  a275=(a018*a204);
  a019=(a019+a275);
  a268=(a240*a268);
  a035=(a035*a172);
  a268=(a268+a035);
  a035=(a054*a268);
  a019=(a019+a035);
  a035=(a245*a263);
  a275=(a240*a266);
  a030=(a030*a172);
  a275=(a275+a030);
  a030=(a023*a275);
  a035=(a035+a030);
  a035=(a051*a035);
  a019=(a019+a035);
  a035=(a048*a275);
  a019=(a019+a035);
  a238=(a238*a267);
  a036=(a036*a237);
  a238=(a238+a036);
  a258=(a000*a258);
  a241=(a241*a258);
  a234=(a034*a234);
  a036=(2.*a263);
  a250=(a250*a036);
  a266=(2.*a266);
  a249=(a249*a266);
  a272=(a239*a272);
  a033=(a033*a204);
  a272=(a272+a033);
  a272=(a248*a272);
  a249=(a249+a272);
  a270=(a239*a270);
  a026=(a026*a204);
  a270=(a270+a026);
  a249=(a249+a270);
  a249=(a247*a249);
  a250=(a250+a249);
  a234=(a234+a250);
  a243=(a243*a271);
  a029=(a029*a235);
  a243=(a243+a029);
  a234=(a234+a243);
  a239=(a239*a269);
  a022=(a022*a204);
  a239=(a239+a022);
  a234=(a234+a239);
  a234=(a015*a234);
  a241=(a241+a234);
  a238=(a238+a241);
  a244=(a244*a258);
  a268=(a056*a268);
  a252=(a252*a036);
  a251=(a251*a266);
  a265=(a240*a265);
  a055=(a055*a172);
  a265=(a265+a055);
  a248=(a248*a265);
  a251=(a251+a248);
  a261=(a240*a261);
  a049=(a049*a172);
  a261=(a261+a049);
  a251=(a251+a261);
  a247=(a247*a251);
  a252=(a252+a247);
  a268=(a268+a252);
  a245=(a245*a264);
  a052=(a052*a275);
  a245=(a245+a052);
  a268=(a268+a245);
  a260=(a240*a260);
  a046=(a046*a172);
  a260=(a260+a046);
  a268=(a268+a260);
  a015=(a015*a268);
  a244=(a244+a015);
  a238=(a238+a244);
  a238=(a004*a238);
  a019=(a019+a238);
  a240=(a240*a263);
  a023=(a023*a172);
  a240=(a240+a023);
  a240=(a045*a240);
  a019=(a019+a240);
  a172=(a042*a172);
  a019=(a019+a172);
  a229=(a229*a019);
  a136=(a136+a229);
  a151=(a151+a136);
  a136=(a282*a151);
  a279=(a279+a136);
  a219=(a000*a219);
  a219=(a219+a211);
  a211=(a013*a209);
  a219=(a219-a211);
  a227=(a187*a227);
  a219=(a219+a227);
  a227=(a043*a218);
  a211=(a043*a228);
  a227=(a227+a211);
  a211=(a006*a227);
  a219=(a219-a211);
  a211=(a043*a236);
  a233=(a211+a233);
  a136=(a254*a233);
  a219=(a219+a136);
  a136=(a254*a242);
  a219=(a219+a136);
  a136=(a063*a273);
  a229=(a043*a291);
  a136=(a136+a229);
  a229=(a187*a012);
  a172=(a136-a229);
  a172=(a219*a172);
  a240=(a043*a063);
  a023=(a187*a013);
  a263=(a240-a023);
  a332=(a000*a332);
  a332=(a332+a292);
  a209=(a209*a012);
  a315=(a013*a315);
  a209=(a209+a315);
  a332=(a332-a209);
  a188=(a187*a188);
  a332=(a332+a188);
  a188=(a227*a005);
  a218=(a218*a273);
  a202=(a043*a202);
  a218=(a218+a202);
  a228=(a228*a273);
  a178=(a043*a178);
  a228=(a228+a178);
  a218=(a218+a228);
  a228=(a006*a218);
  a188=(a188+a228);
  a332=(a332-a188);
  a188=(2.*a008);
  a233=(a233*a188);
  a236=(a236*a273);
  a206=(a043*a206);
  a236=(a236+a206);
  a198=(a236+a198);
  a198=(a254*a198);
  a233=(a233+a198);
  a332=(a332+a233);
  a188=(a242*a188);
  a254=(a254*a019);
  a188=(a188+a254);
  a332=(a332+a188);
  a188=(a263*a332);
  a172=(a172+a188);
  a279=(a279+a172);
  a172=(a043*a010);
  a172=(a003-a172);
  a113=(a187*a113);
  a317=(a000*a317);
  a113=(a113+a317);
  a211=(a211+a231);
  a231=(2.*a005);
  a317=(a211*a231);
  a236=(a236+a192);
  a236=(a246*a236);
  a317=(a317+a236);
  a113=(a113+a317);
  a113=(a113+a149);
  a149=(a220*a012);
  a200=(a013*a200);
  a149=(a149+a200);
  a113=(a113-a149);
  a149=(a227*a008);
  a218=(a009*a218);
  a149=(a149+a218);
  a113=(a113-a149);
  a231=(a242*a231);
  a019=(a246*a019);
  a231=(a231+a019);
  a113=(a113+a231);
  a231=(a172*a113);
  a208=(a187*a208);
  a216=(a000*a216);
  a208=(a208+a216);
  a211=(a246*a211);
  a208=(a208+a211);
  a208=(a208+a222);
  a220=(a013*a220);
  a208=(a208-a220);
  a227=(a009*a227);
  a208=(a208-a227);
  a246=(a246*a242);
  a208=(a208+a246);
  a246=(a010*a273);
  a242=(a043*a255);
  a246=(a246+a242);
  a246=(a208*a246);
  a231=(a231-a246);
  a279=(a279+a231);
  a246=arg[3]? arg[3][2] : 0;
  a293=(a246*a293);
  a293=(a002*a293);
  a242=(a246*a181);
  a227=(a000*a242);
  a293=(a293+a227);
  a279=(a279-a293);
  a291=(a038*a291);
  a063=(a063*a286);
  a291=(a291-a063);
  a063=(a059*a012);
  a058=(a058*a274);
  a057=(a057*a262);
  a016=(a016*a259);
  a057=(a057+a016);
  a037=(a037*a057);
  a058=(a058+a037);
  a037=(a013*a058);
  a063=(a063-a037);
  a037=(a291-a063);
  a037=(a107*a037);
  a057=(a038*a257);
  a016=(a007*a286);
  a057=(a057-a016);
  a057=(a062*a057);
  a037=(a037-a057);
  a057=(a059*a005);
  a016=(a006*a058);
  a057=(a057-a016);
  a016=(a038*a295);
  a259=(a061*a286);
  a016=(a016-a259);
  a057=(a057+a016);
  a057=(a040*a057);
  a037=(a037+a057);
  a037=(a002*a037);
  a064=(a107*a064);
  a039=(a062*a039);
  a064=(a064+a039);
  a060=(a040*a060);
  a064=(a064+a060);
  a060=(a000*a064);
  a037=(a037+a060);
  a279=(a279+a037);
  a279=(a279/a001);
  a282=(a282*a217);
  a263=(a263*a219);
  a282=(a282+a263);
  a172=(a172*a208);
  a282=(a282+a172);
  a242=(a242*a002);
  a282=(a282-a242);
  a064=(a064*a002);
  a282=(a282+a064);
  a282=(a282/a001);
  a282=(a282/a001);
  a279=(a279-a282);
  if (res[3]!=0) res[3][0]=a279;
  a279=(a061*a273);
  a295=(a043*a295);
  a279=(a279+a295);
  a295=(a187*a005);
  a282=(a279-a295);
  a282=(a217*a282);
  a061=(a043*a061);
  a064=(a187*a006);
  a242=(a061-a064);
  a172=(a242*a151);
  a282=(a282+a172);
  a172=(a043*a007);
  a172=(a003-a172);
  a263=(a172*a332);
  a007=(a007*a273);
  a257=(a043*a257);
  a007=(a007+a257);
  a007=(a219*a007);
  a263=(a263-a007);
  a282=(a282+a263);
  a012=(a000*a012);
  a007=(a136-a012);
  a007=(a208*a007);
  a013=(a000*a013);
  a257=(a240-a013);
  a037=(a257*a113);
  a007=(a007+a037);
  a282=(a282+a007);
  a289=(a246*a289);
  a289=(a002*a289);
  a007=(a246*a139);
  a037=(a000*a007);
  a289=(a289+a037);
  a282=(a282-a289);
  a063=(a063+a291);
  a063=(a062*a063);
  a255=(a038*a255);
  a010=(a010*a286);
  a255=(a255-a010);
  a255=(a107*a255);
  a063=(a063-a255);
  a038=(a038*a277);
  a067=(a067*a286);
  a038=(a038-a067);
  a059=(a059*a008);
  a058=(a009*a058);
  a059=(a059-a058);
  a038=(a038-a059);
  a038=(a040*a038);
  a063=(a063+a038);
  a063=(a002*a063);
  a014=(a107*a014);
  a065=(a062*a065);
  a014=(a014+a065);
  a068=(a040*a068);
  a014=(a014+a068);
  a068=(a000*a014);
  a063=(a063+a068);
  a282=(a282-a063);
  a282=(a282/a001);
  a242=(a242*a217);
  a172=(a172*a219);
  a242=(a242+a172);
  a257=(a257*a208);
  a242=(a242+a257);
  a007=(a007*a002);
  a242=(a242-a007);
  a014=(a014*a002);
  a242=(a242-a014);
  a242=(a242/a001);
  a242=(a242/a001);
  a282=(a282-a242);
  if (res[3]!=0) res[3][1]=a282;
  a282=(a043*a011);
  a282=(a003-a282);
  a242=(a282*a151);
  a011=(a011*a273);
  a043=(a043*a256);
  a011=(a011+a043);
  a011=(a217*a011);
  a242=(a242-a011);
  a005=(a000*a005);
  a011=(a279-a005);
  a011=(a219*a011);
  a006=(a000*a006);
  a043=(a061-a006);
  a256=(a043*a332);
  a011=(a011+a256);
  a011=(a242+a011);
  a008=(a187*a008);
  a256=(a276-a008);
  a256=(a208*a256);
  a009=(a187*a009);
  a273=(a280-a009);
  a014=(a273*a113);
  a256=(a256+a014);
  a011=(a011+a256);
  a041=(a246*a041);
  a041=(a002*a041);
  a256=(a246*a162);
  a014=(a000*a256);
  a041=(a041+a014);
  a011=(a011-a041);
  a011=(a011/a001);
  a282=(a282*a217);
  a043=(a043*a219);
  a282=(a282+a043);
  a273=(a273*a208);
  a282=(a282+a273);
  a256=(a256*a002);
  a282=(a282-a256);
  a282=(a282/a001);
  a282=(a282/a001);
  a011=(a011-a282);
  if (res[3]!=0) res[3][2]=a011;
  a011=(a091*a325);
  a282=(a104*a320);
  a011=(a011-a282);
  a282=(a101*a076);
  a100=(a100*a316);
  a099=(a099*a302);
  a256=(a080*a308);
  a099=(a099+a256);
  a099=(a090*a099);
  a100=(a100+a099);
  a099=(a077*a100);
  a282=(a282-a099);
  a099=(a011-a282);
  a099=(a107*a099);
  a256=(a091*a183);
  a273=(a071*a320);
  a256=(a256-a273);
  a256=(a062*a256);
  a099=(a099-a256);
  a256=(a101*a069);
  a273=(a070*a100);
  a256=(a256-a273);
  a273=(a091*a329);
  a043=(a103*a320);
  a273=(a273-a043);
  a256=(a256+a273);
  a256=(a040*a256);
  a099=(a099+a256);
  a099=(a002*a099);
  a105=(a107*a105);
  a092=(a062*a092);
  a105=(a105+a092);
  a102=(a040*a102);
  a105=(a105+a102);
  a102=(a000*a105);
  a099=(a099+a102);
  a102=(a246*a327);
  a102=(a002*a102);
  a092=(a246*a150);
  a256=(a000*a092);
  a102=(a102+a256);
  a099=(a099-a102);
  a094=(a094-a081);
  a179=(a179+a094);
  a090=(a158*a090);
  a179=(a179/a090);
  a185=(a004*a185);
  a203=(a203+a185);
  a185=-3.8675134594812879e-02;
  a207=(a185*a207);
  a203=(a203+a207);
  a207=(a191*a203);
  a094=(a179*a207);
  a214=(a004*a214);
  a210=(a210+a214);
  a213=(a185*a213);
  a210=(a210+a213);
  a213=(a157*a210);
  a214=(a179*a213);
  a094=(a094+a214);
  a214=(a073*a094);
  a169=(a169-a214);
  a214=(a150*a210);
  a081=(a187*a214);
  a169=(a169+a081);
  a081=(a150*a203);
  a102=(a179*a081);
  a225=(a004*a225);
  a221=(a221+a225);
  a224=(a185*a224);
  a221=(a221+a224);
  a224=(a157*a221);
  a225=(a179*a224);
  a102=(a102+a225);
  a225=(a070*a102);
  a169=(a169-a225);
  a225=(a191*a221);
  a256=(a000*a225);
  a169=(a169+a256);
  a256=(a191*a210);
  a273=(a179*a256);
  a043=(a150*a221);
  a041=(a179*a043);
  a014=(a273+a041);
  a007=(a297*a014);
  a169=(a169+a007);
  a007=(a179/a090);
  a257=(a157*a203);
  a172=(a075*a257);
  a063=(a103*a207);
  a172=(a172-a063);
  a063=(a108*a081);
  a172=(a172-a063);
  a063=(a103*a213);
  a172=(a172-a063);
  a063=(a071*a256);
  a172=(a172+a063);
  a063=(a104*a214);
  a172=(a172-a063);
  a063=(a108*a224);
  a172=(a172-a063);
  a063=(a104*a225);
  a172=(a172-a063);
  a063=(a074*a043);
  a172=(a172+a063);
  a063=(a007*a172);
  a063=(a158*a063);
  a068=(a080*a063);
  a065=(a172/a090);
  a068=(a068-a065);
  a038=(a088*a068);
  a059=(a032*a038);
  a058=(a086*a068);
  a067=(a083*a058);
  a067=(a028*a067);
  a059=(a059+a067);
  a067=(a025*a058);
  a059=(a059+a067);
  a067=(a083*a068);
  a067=(a021*a067);
  a059=(a059+a067);
  a067=(a018*a068);
  a059=(a059+a067);
  a067=(a088*a065);
  a286=(a054*a067);
  a059=(a059+a286);
  a286=(a086*a065);
  a277=(a083*a286);
  a277=(a051*a277);
  a059=(a059+a277);
  a277=(a048*a286);
  a059=(a059+a277);
  a277=(a089*a063);
  a038=(a034*a038);
  a255=(a087*a068);
  a010=(a309*a255);
  a291=(a084*a068);
  a010=(a010+a291);
  a291=(a306*a010);
  a038=(a038+a291);
  a291=(a085*a058);
  a038=(a038+a291);
  a291=(a082*a068);
  a038=(a038+a291);
  a291=(a079*a038);
  a277=(a277+a291);
  a067=(a056*a067);
  a291=(a098*a065);
  a289=(a309*a291);
  a037=(a096*a065);
  a289=(a289+a037);
  a037=(a306*a289);
  a067=(a067+a037);
  a037=(a097*a286);
  a067=(a067+a037);
  a037=(a095*a065);
  a067=(a067+a037);
  a037=(a079*a067);
  a277=(a277+a037);
  a277=(a004*a277);
  a059=(a059+a277);
  a277=(a083*a065);
  a277=(a045*a277);
  a059=(a059+a277);
  a277=(a042*a065);
  a059=(a059+a277);
  a277=(a297*a059);
  a169=(a169+a277);
  a308=(a308-a299);
  a308=(a308/a090);
  a316=(a158*a316);
  a277=(a007*a316);
  a308=(a308+a277);
  a277=(a108*a308);
  a037=(a179*a318);
  a277=(a277+a037);
  a037=(a000*a072);
  a060=(a277-a037);
  a060=(a169*a060);
  a039=(a179*a108);
  a057=(a000*a073);
  a016=(a039-a057);
  a259=(a094*a072);
  a262=(a207*a308);
  a274=(a203*a323);
  a322=(a004*a322);
  a190=(a190+a322);
  a196=(a185*a196);
  a190=(a190+a196);
  a196=(a191*a190);
  a274=(a274+a196);
  a196=(a179*a274);
  a262=(a262+a196);
  a196=(a213*a308);
  a322=(a210*a114);
  a321=(a004*a321);
  a331=(a331+a321);
  a326=(a185*a326);
  a331=(a331+a326);
  a326=(a157*a331);
  a322=(a322+a326);
  a326=(a179*a322);
  a196=(a196+a326);
  a262=(a262+a196);
  a196=(a073*a262);
  a259=(a259+a196);
  a288=(a288-a259);
  a259=(a210*a327);
  a196=(a150*a331);
  a259=(a259+a196);
  a196=(a187*a259);
  a288=(a288+a196);
  a196=(a102*a069);
  a326=(a081*a308);
  a321=(a203*a327);
  a293=(a150*a190);
  a321=(a321+a293);
  a293=(a179*a321);
  a326=(a326+a293);
  a293=(a224*a308);
  a227=(a221*a114);
  a197=(a004*a197);
  a165=(a165+a197);
  a185=(a185*a155);
  a165=(a165+a185);
  a185=(a157*a165);
  a227=(a227+a185);
  a185=(a179*a227);
  a293=(a293+a185);
  a326=(a326+a293);
  a293=(a070*a326);
  a196=(a196+a293);
  a288=(a288-a196);
  a196=(a221*a323);
  a293=(a191*a165);
  a196=(a196+a293);
  a293=(a000*a196);
  a288=(a288+a293);
  a293=(2.*a076);
  a014=(a014*a293);
  a185=(a256*a308);
  a210=(a210*a323);
  a331=(a191*a331);
  a210=(a210+a331);
  a331=(a179*a210);
  a185=(a185+a331);
  a331=(a043*a308);
  a221=(a221*a327);
  a165=(a150*a165);
  a221=(a221+a165);
  a165=(a179*a221);
  a331=(a331+a165);
  a165=(a185+a331);
  a165=(a297*a165);
  a014=(a014+a165);
  a288=(a288+a014);
  a293=(a059*a293);
  a014=(a068*a310);
  a302=(a063*a302);
  a165=(a308/a090);
  a327=(a007/a090);
  a327=(a327*a316);
  a165=(a165+a327);
  a172=(a172*a165);
  a165=(a257*a284);
  a203=(a203*a114);
  a190=(a157*a190);
  a203=(a203+a190);
  a190=(a075*a203);
  a165=(a165+a190);
  a190=(a207*a329);
  a327=(a103*a274);
  a190=(a190+a327);
  a165=(a165-a190);
  a190=(a081*a318);
  a327=(a108*a321);
  a190=(a190+a327);
  a165=(a165-a190);
  a190=(a213*a329);
  a327=(a103*a322);
  a190=(a190+a327);
  a165=(a165-a190);
  a256=(a256*a183);
  a210=(a071*a210);
  a256=(a256+a210);
  a165=(a165+a256);
  a256=(a214*a325);
  a210=(a104*a259);
  a256=(a256+a210);
  a165=(a165-a256);
  a256=(a224*a318);
  a210=(a108*a227);
  a256=(a256+a210);
  a165=(a165-a256);
  a256=(a225*a325);
  a210=(a104*a196);
  a256=(a256+a210);
  a165=(a165-a256);
  a043=(a043*a146);
  a221=(a074*a221);
  a043=(a043+a221);
  a165=(a165+a043);
  a007=(a007*a165);
  a172=(a172+a007);
  a172=(a158*a172);
  a080=(a080*a172);
  a302=(a302+a080);
  a165=(a165/a090);
  a090=(a065/a090);
  a090=(a090*a316);
  a165=(a165+a090);
  a302=(a302-a165);
  a090=(a088*a302);
  a014=(a014+a090);
  a090=(a032*a014);
  a316=(a058*a303);
  a080=(a068*a307);
  a007=(a086*a302);
  a080=(a080+a007);
  a007=(a083*a080);
  a316=(a316+a007);
  a316=(a028*a316);
  a090=(a090+a316);
  a316=(a025*a080);
  a090=(a090+a316);
  a316=(a068*a303);
  a007=(a083*a302);
  a316=(a316+a007);
  a316=(a021*a316);
  a090=(a090+a316);
  a316=(a018*a302);
  a090=(a090+a316);
  a310=(a065*a310);
  a088=(a088*a165);
  a310=(a310+a088);
  a088=(a054*a310);
  a090=(a090+a088);
  a088=(a286*a303);
  a316=(a065*a307);
  a086=(a086*a165);
  a316=(a316+a086);
  a086=(a083*a316);
  a088=(a088+a086);
  a088=(a051*a088);
  a090=(a090+a088);
  a088=(a048*a316);
  a090=(a090+a088);
  a063=(a063*a299);
  a089=(a089*a172);
  a063=(a063+a089);
  a253=(a000*a253);
  a038=(a038*a253);
  a014=(a034*a014);
  a089=(2.*a303);
  a010=(a010*a089);
  a307=(2.*a307);
  a255=(a255*a307);
  a305=(a068*a305);
  a087=(a087*a302);
  a305=(a305+a087);
  a305=(a309*a305);
  a255=(a255+a305);
  a301=(a068*a301);
  a084=(a084*a302);
  a301=(a301+a084);
  a255=(a255+a301);
  a255=(a306*a255);
  a010=(a010+a255);
  a014=(a014+a010);
  a058=(a058*a304);
  a085=(a085*a080);
  a058=(a058+a085);
  a014=(a014+a058);
  a068=(a068*a300);
  a082=(a082*a302);
  a068=(a068+a082);
  a014=(a014+a068);
  a014=(a079*a014);
  a038=(a038+a014);
  a063=(a063+a038);
  a067=(a067*a253);
  a310=(a056*a310);
  a289=(a289*a089);
  a291=(a291*a307);
  a314=(a065*a314);
  a098=(a098*a165);
  a314=(a314+a098);
  a309=(a309*a314);
  a291=(a291+a309);
  a312=(a065*a312);
  a096=(a096*a165);
  a312=(a312+a096);
  a291=(a291+a312);
  a306=(a306*a291);
  a289=(a289+a306);
  a310=(a310+a289);
  a286=(a286*a313);
  a097=(a097*a316);
  a286=(a286+a097);
  a310=(a310+a286);
  a311=(a065*a311);
  a095=(a095*a165);
  a311=(a311+a095);
  a310=(a310+a311);
  a079=(a079*a310);
  a067=(a067+a079);
  a063=(a063+a067);
  a063=(a004*a063);
  a090=(a090+a063);
  a065=(a065*a303);
  a083=(a083*a165);
  a065=(a065+a083);
  a065=(a045*a065);
  a090=(a090+a065);
  a165=(a042*a165);
  a090=(a090+a165);
  a297=(a297*a090);
  a293=(a293+a297);
  a288=(a288+a293);
  a293=(a016*a288);
  a060=(a060+a293);
  a099=(a099+a060);
  a081=(a000*a081);
  a212=(a212+a081);
  a081=(a077*a094);
  a212=(a212-a081);
  a224=(a187*a224);
  a212=(a212+a224);
  a224=(a179*a214);
  a081=(a179*a225);
  a224=(a224+a081);
  a081=(a070*a224);
  a212=(a212-a081);
  a081=(a179*a257);
  a041=(a081+a041);
  a060=(a117*a041);
  a212=(a212+a060);
  a060=(a117*a059);
  a212=(a212+a060);
  a060=(a104*a308);
  a325=(a179*a325);
  a060=(a060+a325);
  a325=(a187*a076);
  a293=(a060-a325);
  a293=(a212*a293);
  a104=(a179*a104);
  a297=(a187*a077);
  a165=(a104-a297);
  a321=(a000*a321);
  a287=(a287+a321);
  a094=(a094*a076);
  a262=(a077*a262);
  a094=(a094+a262);
  a287=(a287-a094);
  a227=(a187*a227);
  a287=(a287+a227);
  a227=(a224*a069);
  a214=(a214*a308);
  a259=(a179*a259);
  a214=(a214+a259);
  a225=(a225*a308);
  a196=(a179*a196);
  a225=(a225+a196);
  a214=(a214+a225);
  a225=(a070*a214);
  a227=(a227+a225);
  a287=(a287-a227);
  a227=(2.*a072);
  a041=(a041*a227);
  a257=(a257*a308);
  a203=(a179*a203);
  a257=(a257+a203);
  a331=(a257+a331);
  a331=(a117*a331);
  a041=(a041+a331);
  a287=(a287+a041);
  a227=(a059*a227);
  a117=(a117*a090);
  a227=(a227+a117);
  a287=(a287+a227);
  a227=(a165*a287);
  a293=(a293+a227);
  a099=(a099+a293);
  a293=(a179*a074);
  a293=(a003-a293);
  a274=(a187*a274);
  a205=(a205+a274);
  a322=(a000*a322);
  a205=(a205+a322);
  a081=(a081+a273);
  a273=(2.*a069);
  a322=(a081*a273);
  a257=(a257+a185);
  a257=(a283*a257);
  a322=(a322+a257);
  a205=(a205+a322);
  a322=(a102*a076);
  a326=(a077*a326);
  a322=(a322+a326);
  a205=(a205-a322);
  a322=(a224*a072);
  a214=(a073*a214);
  a322=(a322+a214);
  a205=(a205-a322);
  a273=(a059*a273);
  a090=(a283*a090);
  a273=(a273+a090);
  a205=(a205+a273);
  a273=(a293*a205);
  a207=(a187*a207);
  a223=(a223+a207);
  a213=(a000*a213);
  a223=(a223+a213);
  a081=(a283*a081);
  a223=(a223+a081);
  a102=(a077*a102);
  a223=(a223-a102);
  a224=(a073*a224);
  a223=(a223-a224);
  a283=(a283*a059);
  a223=(a223+a283);
  a283=(a074*a308);
  a059=(a179*a146);
  a283=(a283+a059);
  a283=(a223*a283);
  a273=(a273-a283);
  a099=(a099+a273);
  a099=(a099/a001);
  a105=(a105*a002);
  a092=(a092*a002);
  a105=(a105-a092);
  a016=(a016*a169);
  a105=(a105+a016);
  a165=(a165*a212);
  a105=(a105+a165);
  a293=(a293*a223);
  a105=(a105+a293);
  a105=(a105/a001);
  a105=(a105/a001);
  a099=(a099-a105);
  if (res[3]!=0) res[3][3]=a099;
  a099=(a103*a308);
  a329=(a179*a329);
  a099=(a099+a329);
  a329=(a187*a069);
  a105=(a099-a329);
  a105=(a169*a105);
  a103=(a179*a103);
  a293=(a187*a070);
  a165=(a103-a293);
  a016=(a165*a288);
  a105=(a105+a016);
  a323=(a246*a323);
  a323=(a002*a323);
  a016=(a246*a191);
  a092=(a000*a016);
  a323=(a323+a092);
  a282=(a282+a011);
  a282=(a062*a282);
  a146=(a091*a146);
  a074=(a074*a320);
  a146=(a146-a074);
  a146=(a107*a146);
  a282=(a282-a146);
  a091=(a091*a318);
  a108=(a108*a320);
  a091=(a091-a108);
  a101=(a101*a072);
  a100=(a073*a100);
  a101=(a101-a100);
  a091=(a091-a101);
  a091=(a040*a091);
  a282=(a282+a091);
  a282=(a002*a282);
  a078=(a107*a078);
  a106=(a062*a106);
  a078=(a078+a106);
  a109=(a040*a109);
  a078=(a078+a109);
  a109=(a000*a078);
  a282=(a282+a109);
  a323=(a323+a282);
  a105=(a105-a323);
  a323=(a179*a071);
  a323=(a003-a323);
  a282=(a323*a287);
  a071=(a071*a308);
  a183=(a179*a183);
  a071=(a071+a183);
  a071=(a212*a071);
  a282=(a282-a071);
  a105=(a105+a282);
  a076=(a000*a076);
  a071=(a060-a076);
  a071=(a223*a071);
  a077=(a000*a077);
  a183=(a104-a077);
  a109=(a183*a205);
  a071=(a071+a109);
  a105=(a105+a071);
  a105=(a105/a001);
  a165=(a165*a169);
  a016=(a016*a002);
  a078=(a078*a002);
  a016=(a016+a078);
  a165=(a165-a016);
  a323=(a323*a212);
  a165=(a165+a323);
  a183=(a183*a223);
  a165=(a165+a183);
  a165=(a165/a001);
  a165=(a165/a001);
  a105=(a105-a165);
  if (res[3]!=0) res[3][4]=a105;
  a105=(a179*a075);
  a003=(a003-a105);
  a105=(a003*a288);
  a075=(a075*a308);
  a179=(a179*a284);
  a075=(a075+a179);
  a075=(a169*a075);
  a105=(a105-a075);
  a114=(a246*a114);
  a114=(a002*a114);
  a246=(a246*a157);
  a075=(a000*a246);
  a114=(a114+a075);
  a114=(a105-a114);
  a069=(a000*a069);
  a075=(a099-a069);
  a075=(a212*a075);
  a070=(a000*a070);
  a179=(a103-a070);
  a284=(a179*a287);
  a075=(a075+a284);
  a114=(a114+a075);
  a072=(a187*a072);
  a075=(a277-a072);
  a075=(a223*a075);
  a073=(a187*a073);
  a284=(a039-a073);
  a308=(a284*a205);
  a075=(a075+a308);
  a114=(a114+a075);
  a114=(a114/a001);
  a003=(a003*a169);
  a246=(a246*a002);
  a003=(a003-a246);
  a179=(a179*a212);
  a003=(a003+a179);
  a284=(a284*a223);
  a003=(a003+a284);
  a003=(a003/a001);
  a003=(a003/a001);
  a114=(a114-a003);
  if (res[3]!=0) res[3][5]=a114;
  a114=(a000*a118);
  a154=(a154*a112);
  a167=(a167*a118);
  a003=(a154+a167);
  a186=(a186*a111);
  a284=(a003+a186);
  a042=(a042*a284);
  a045=(a045*a284);
  a045=(a128*a045);
  a004=(a004*a284);
  a125=(a125*a004);
  a044=(a044*a125);
  a045=(a045+a044);
  a042=(a042+a045);
  a048=(a048*a284);
  a051=(a051*a284);
  a051=(a128*a051);
  a050=(a050*a125);
  a051=(a051+a050);
  a048=(a048+a051);
  a048=(a129*a048);
  a161=(a161*a125);
  a047=(a047*a161);
  a048=(a048+a047);
  a042=(a042+a048);
  a054=(a054*a284);
  a056=(a056*a125);
  a054=(a054+a056);
  a054=(a130*a054);
  a163=(a163*a161);
  a053=(a053*a163);
  a054=(a054+a053);
  a042=(a042+a054);
  a018=(a018*a284);
  a021=(a021*a284);
  a021=(a128*a021);
  a020=(a020*a125);
  a021=(a021+a020);
  a018=(a018+a021);
  a025=(a025*a284);
  a028=(a028*a284);
  a128=(a128*a028);
  a027=(a027*a125);
  a128=(a128+a027);
  a025=(a025+a128);
  a129=(a129*a025);
  a024=(a024*a161);
  a129=(a129+a024);
  a018=(a018+a129);
  a032=(a032*a284);
  a034=(a034*a125);
  a032=(a032+a034);
  a130=(a130*a032);
  a031=(a031*a163);
  a130=(a130+a031);
  a018=(a018+a130);
  a130=(a042-a018);
  a130=(a130/a159);
  a017=(a017*a004);
  a018=(a126*a018);
  a017=(a017+a018);
  a158=(a158*a017);
  a127=(a127*a158);
  a130=(a130+a127);
  a127=(a138*a130);
  a158=(a093*a112);
  a018=(a115*a111);
  a158=(a158+a018);
  a018=(a132*a158);
  a127=(a127+a018);
  a018=(a114+a127);
  a018=(a144*a018);
  a159=(a187*a111);
  a031=(a152*a130);
  a163=(a120*a112);
  a032=(a115*a118);
  a163=(a163+a032);
  a032=(a132*a163);
  a031=(a031+a032);
  a032=(a159+a031);
  a032=(a180*a032);
  a018=(a018+a032);
  a032=(a121*a130);
  a167=(a167+a186);
  a034=(a132*a167);
  a032=(a032+a034);
  a032=(a171*a032);
  a018=(a018-a032);
  a037=(a037+a277);
  a037=(a169*a037);
  a057=(a057+a039);
  a057=(a057*a288);
  a037=(a037+a057);
  a018=(a018+a037);
  a325=(a325+a060);
  a325=(a212*a325);
  a297=(a297+a104);
  a297=(a297*a287);
  a325=(a325+a297);
  a018=(a018+a325);
  a018=(a018+a273);
  a278=(a278+a276);
  a278=(a217*a278);
  a281=(a281+a280);
  a281=(a281*a151);
  a278=(a278+a281);
  a018=(a018+a278);
  a229=(a229+a136);
  a229=(a219*a229);
  a023=(a023+a240);
  a023=(a023*a332);
  a229=(a229+a023);
  a018=(a018+a229);
  a018=(a018+a231);
  a018=(-a018);
  if (res[3]!=0) res[3][6]=a018;
  a018=(a187*a112);
  a231=(a143*a130);
  a229=(a093*a118);
  a023=(a120*a111);
  a229=(a229+a023);
  a023=(a132*a229);
  a231=(a231+a023);
  a023=(a018+a231);
  a023=(a144*a023);
  a278=(a116*a130);
  a186=(a186+a154);
  a154=(a132*a186);
  a278=(a278+a154);
  a278=(a180*a278);
  a023=(a023-a278);
  a154=(a000*a111);
  a281=(a154+a031);
  a281=(a171*a281);
  a023=(a023+a281);
  a329=(a329+a099);
  a169=(a169*a329);
  a293=(a293+a103);
  a293=(a293*a288);
  a169=(a169+a293);
  a023=(a023+a169);
  a023=(a023+a282);
  a076=(a076+a060);
  a076=(a223*a076);
  a077=(a077+a104);
  a077=(a077*a205);
  a076=(a076+a077);
  a023=(a023+a076);
  a295=(a295+a279);
  a217=(a217*a295);
  a064=(a064+a061);
  a064=(a064*a151);
  a217=(a217+a064);
  a023=(a023+a217);
  a023=(a023+a263);
  a012=(a012+a136);
  a012=(a208*a012);
  a013=(a013+a240);
  a013=(a013*a113);
  a012=(a012+a013);
  a023=(a023+a012);
  a023=(-a023);
  if (res[3]!=0) res[3][7]=a023;
  a023=(a000*a112);
  a012=(a023+a231);
  a012=(a180*a012);
  a130=(a122*a130);
  a132=(a132*a003);
  a130=(a130+a132);
  a130=(a144*a130);
  a012=(a012-a130);
  a187=(a187*a118);
  a132=(a187+a127);
  a132=(a171*a132);
  a012=(a012+a132);
  a012=(a012+a105);
  a069=(a069+a099);
  a212=(a212*a069);
  a070=(a070+a103);
  a070=(a070*a287);
  a212=(a212+a070);
  a012=(a012+a212);
  a072=(a072+a277);
  a223=(a223*a072);
  a073=(a073+a039);
  a073=(a073*a205);
  a223=(a223+a073);
  a012=(a012+a223);
  a012=(a012+a242);
  a005=(a005+a279);
  a219=(a219*a005);
  a006=(a006+a061);
  a006=(a006*a332);
  a219=(a219+a006);
  a012=(a012+a219);
  a008=(a008+a276);
  a208=(a208*a008);
  a009=(a009+a280);
  a009=(a009*a113);
  a208=(a208+a009);
  a012=(a012+a208);
  a012=(-a012);
  if (res[3]!=0) res[3][8]=a012;
  if (res[3]!=0) res[3][9]=a066;
  if (res[3]!=0) res[3][10]=a066;
  if (res[3]!=0) res[3][11]=a066;
  if (res[3]!=0) res[3][12]=a066;
  if (res[3]!=0) res[3][13]=a066;
  if (res[3]!=0) res[3][14]=a066;
  if (res[3]!=0) res[3][15]=a066;
  if (res[3]!=0) res[3][16]=a066;
  if (res[3]!=0) res[3][17]=a066;
  a181=(a002*a181);
  a181=(a181/a001);
  a181=(-a181);
  if (res[3]!=0) res[3][18]=a181;
  a139=(a002*a139);
  a139=(a139/a001);
  a139=(-a139);
  if (res[3]!=0) res[3][19]=a139;
  a162=(a002*a162);
  a162=(a162/a001);
  a162=(-a162);
  if (res[3]!=0) res[3][20]=a162;
  a150=(a002*a150);
  a150=(a150/a001);
  a150=(-a150);
  if (res[3]!=0) res[3][21]=a150;
  a191=(a002*a191);
  a191=(a191/a001);
  a191=(-a191);
  if (res[3]!=0) res[3][22]=a191;
  a002=(a002*a157);
  a002=(a002/a001);
  a002=(-a002);
  if (res[3]!=0) res[3][23]=a002;
  if (res[3]!=0) res[3][24]=a066;
  if (res[3]!=0) res[3][25]=a066;
  if (res[3]!=0) res[3][26]=a066;
  a163=(a137*a163);
  a153=(a153*a017);
  a000=(a000*a153);
  a152=(a152*a000);
  a163=(a163-a152);
  a111=(a135*a111);
  a134=(a134*a017);
  a133=(a133*a004);
  a126=(a126*a042);
  a133=(a133+a126);
  a131=(a131*a133);
  a134=(a134+a131);
  a093=(a093*a134);
  a111=(a111-a093);
  a093=(a163-a111);
  a131=(a110*a093);
  a186=(a137*a186);
  a116=(a116*a000);
  a186=(a186-a116);
  a116=(a142*a186);
  a131=(a131-a116);
  a112=(a135*a112);
  a115=(a115*a134);
  a112=(a112-a115);
  a229=(a137*a229);
  a143=(a143*a000);
  a229=(a229-a143);
  a143=(a112+a229);
  a115=(a147*a143);
  a131=(a131+a115);
  a141=(a141*a131);
  a131=(a173*a093);
  a115=(a175*a186);
  a131=(a131-a115);
  a115=(a176*a143);
  a131=(a131+a115);
  a174=(a174*a131);
  a141=(a141+a174);
  a093=(a107*a093);
  a186=(a062*a186);
  a093=(a093-a186);
  a143=(a040*a143);
  a093=(a093+a143);
  a177=(a177*a093);
  a141=(a141+a177);
  if (res[4]!=0) res[4][0]=a141;
  a135=(a135*a118);
  a120=(a120*a134);
  a135=(a135-a120);
  a158=(a137*a158);
  a138=(a138*a000);
  a158=(a158-a138);
  a138=(a135+a158);
  a120=(a110*a138);
  a229=(a229-a112);
  a112=(a142*a229);
  a120=(a120+a112);
  a003=(a137*a003);
  a122=(a122*a000);
  a003=(a003-a122);
  a122=(a147*a003);
  a120=(a120-a122);
  a164=(a164*a120);
  a120=(a173*a138);
  a122=(a175*a229);
  a120=(a120+a122);
  a122=(a176*a003);
  a120=(a120-a122);
  a170=(a170*a120);
  a164=(a164+a170);
  a138=(a107*a138);
  a229=(a062*a229);
  a138=(a138+a229);
  a003=(a040*a003);
  a138=(a138-a003);
  a182=(a182*a138);
  a164=(a164+a182);
  if (res[4]!=0) res[4][1]=a164;
  a111=(a111+a163);
  a142=(a142*a111);
  a137=(a137*a167);
  a121=(a121*a000);
  a137=(a137-a121);
  a110=(a110*a137);
  a142=(a142-a110);
  a158=(a158-a135);
  a147=(a147*a158);
  a142=(a142+a147);
  a168=(a168*a142);
  a175=(a175*a111);
  a173=(a173*a137);
  a175=(a175-a173);
  a176=(a176*a158);
  a175=(a175+a176);
  a166=(a166*a175);
  a168=(a168+a166);
  a062=(a062*a111);
  a107=(a107*a137);
  a062=(a062-a107);
  a040=(a040*a158);
  a062=(a062+a040);
  a156=(a156*a062);
  a168=(a168+a156);
  if (res[4]!=0) res[4][2]=a168;
  a114=(a127-a114);
  a114=(a144*a114);
  a159=(a031-a159);
  a159=(a180*a159);
  a114=(a114+a159);
  a114=(a114-a032);
  if (res[4]!=0) res[4][3]=a114;
  a018=(a231-a018);
  a144=(a144*a018);
  a144=(a144-a278);
  a031=(a031-a154);
  a031=(a171*a031);
  a144=(a144+a031);
  if (res[4]!=0) res[4][4]=a144;
  a231=(a231-a023);
  a180=(a180*a231);
  a180=(a180-a130);
  a127=(a127-a187);
  a171=(a171*a127);
  a180=(a180+a171);
  if (res[4]!=0) res[4][5]=a180;
  if (res[4]!=0) res[4][6]=a066;
  if (res[4]!=0) res[4][7]=a066;
  if (res[4]!=0) res[4][8]=a066;
  if (res[4]!=0) res[4][9]=a066;
  if (res[4]!=0) res[4][10]=a066;
  if (res[4]!=0) res[4][11]=a066;
  if (res[4]!=0) res[4][12]=a066;
  if (res[4]!=0) res[4][13]=a066;
  if (res[4]!=0) res[4][14]=a066;
  if (res[4]!=0) res[4][15]=a066;
  if (res[4]!=0) res[4][16]=a066;
  if (res[4]!=0) res[4][17]=a066;
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
    case 3: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* step_partials_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s5;
    case 1: return casadi_s5;
    case 2: return casadi_s6;
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
#define HPGEN_P 1
#define HPGEN_H (2 + HPGEN_M + HPGEN_P)
#define HPGEN_OK 0
#define HPGEN_NO_CONVERGENCE 1
#define HPGEN_NONFINITE 2
#define HPGEN_DOMAIN 3
#define HPGEN_RECORD 4
/* the scene's record row (kernel record): its width and what it needs */
#define HPGEN_W 19
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

HPGEN_EXPORT const char* hpgen_hash(void) { return "077574fc559797718a5a0fe360c3bed1af91704de6da2cf7ff6cd2b08ee4e5f6"; }

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

/* residual(z[9], g[9], p[3], h[3]) -> (F[9]) */
#define HPGEN_RESIDUAL_SZ_ARG 4
#define HPGEN_RESIDUAL_SZ_RES 1
#define HPGEN_RESIDUAL_SZ_IW 0
#define HPGEN_RESIDUAL_SZ_W 136
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

/* jacobian(z[9], g[9], p[3], h[3]) -> (J[81]) */
/* = output 1 of residual_jacobian (the same CasADi algorithm; its other outputs are
   computed into scratch and dropped) */
HPGEN_EXPORT int hpgen_kernel_jacobian(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    double scratch[HPGEN_NZ];
    return hpgen_k_residual_jacobian(in0, in1, in2, in3, scratch, out0);
}

/* residual_jacobian(z[9], g[9], p[3], h[3]) -> (F[9], J[81]) */
#define HPGEN_RESIDUAL_JACOBIAN_SZ_ARG 4
#define HPGEN_RESIDUAL_JACOBIAN_SZ_RES 2
#define HPGEN_RESIDUAL_JACOBIAN_SZ_IW 0
#define HPGEN_RESIDUAL_JACOBIAN_SZ_W 359
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

/* update(z[9], g[9], p[3], h[3]) -> (g1[9], p1[3]) */
#define HPGEN_UPDATE_SZ_ARG 4
#define HPGEN_UPDATE_SZ_RES 2
#define HPGEN_UPDATE_SZ_IW 0
#define HPGEN_UPDATE_SZ_W 33
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

/* guess(xi[3], g[9], p[3], h[3]) -> (z0[9]) */
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

/* legendre(g[9], xi[3], h[3]) -> (mu[3]) */
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

/* hessian(g[9], xi[3], h[3]) -> (H[9]) */
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

/* energy(g[9], xi[3], h[3]) -> (E[1]) */
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

/* margin(z[9], h[3]) -> (m[1]) */
#define HPGEN_MARGIN_SZ_ARG 2
#define HPGEN_MARGIN_SZ_RES 1
#define HPGEN_MARGIN_SZ_IW 0
#define HPGEN_MARGIN_SZ_W 15
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

/* chart_point(z[9], g[9], h[3], theta[1]) -> (g_theta[9]) */
#define HPGEN_CHART_POINT_SZ_ARG 4
#define HPGEN_CHART_POINT_SZ_RES 1
#define HPGEN_CHART_POINT_SZ_IW 0
#define HPGEN_CHART_POINT_SZ_W 24
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

/* observe(g[9], p[3], h[3]) -> (xi[3], E[1], m[3], e[1]) */
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

/* update_p(z[9], g[9], p[3], h[3]) -> (p1[3]) */
#define HPGEN_UPDATE_P_SZ_ARG 4
#define HPGEN_UPDATE_P_SZ_RES 1
#define HPGEN_UPDATE_P_SZ_IW 0
#define HPGEN_UPDATE_P_SZ_W 19
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

/* velocity_step(g[9], p[3], xi[3], h[3]) -> (xi1[3]) */
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

/* record(g[9], p[3], xi[3], h[3]) -> (row[19]) */
#define HPGEN_RECORD_SZ_ARG 4
#define HPGEN_RECORD_SZ_RES 1
#define HPGEN_RECORD_SZ_IW 0
#define HPGEN_RECORD_SZ_W 19
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

/* step_partials(z[9], g[9], p[3], h[3]) -> (Fs[54], Yz[54], Ys[36], FH[27], YH[18]) */
#define HPGEN_STEP_PARTIALS_SZ_ARG 4
#define HPGEN_STEP_PARTIALS_SZ_RES 5
#define HPGEN_STEP_PARTIALS_SZ_IW 0
#define HPGEN_STEP_PARTIALS_SZ_W 333
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
