/*
 * hpgen generated module heavy_top_gauss2_exp_exact -- do not edit, regenerate with hpgen
 * model: heavy_top
 * options: tableau=gauss2, tau=exp, rkmk=exact
 * hpgen version: 0.1.0
 * content hash (normalized model + options): ffef12b8e3d5ed599c071aa73ae876759b0a16495812b0c3b2d6fbb4a47bc601
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
  #define CASADI_PREFIX(ID) hpgen_heavy_top_gauss2_exp_exact__ ## ID
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
CASADI_SYMBOL_EXPORT void hpgen_heavy_top_gauss2_exp_exact__casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int hpgen_heavy_top_gauss2_exp_exact__casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int hpgen_heavy_top_gauss2_exp_exact__casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {3, 1, 1};
static const casadi_int casadi_s2[3] = {1, 1, 1};
static const casadi_int casadi_s3[3] = {81, 1, 1};
static const casadi_int casadi_s4[3] = {17, 1, 1};
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
  casadi_real a108, a109, a110, a111, a112, a113, a114, a115, a116, a117, a118, a119;
  casadi_real a120, a121, a122, a123, a124, a125, a126, a127, a128, a129, a130, a131;
  casadi_real a132, a133, a134;
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
  a071=(a071*a087);
  a087=(a048*a071);
  a070=(a070*a066);
  a066=(a048*a070);
  a121=(a087+a066);
  a121=(a081*a121);
  a084=(a084+a121);
  a121=(a048/a053);
  a061=(a061*a123);
  a123=(a009*a061);
  a082=(a079*a125);
  a123=(a123-a082);
  a082=(a054*a131);
  a123=(a123-a082);
  a082=(a079*a005);
  a123=(a123-a082);
  a071=(a012*a071);
  a123=(a123+a071);
  a071=(a072*a130);
  a123=(a123-a071);
  a071=(a054*a117);
  a123=(a123-a071);
  a071=(a072*a065);
  a123=(a123-a071);
  a070=(a008*a070);
  a123=(a123+a070);
  a121=(a121*a123);
  a121=(a049*a121);
  a070=(a019*a121);
  a123=(a123/a053);
  a070=(a070-a123);
  a053=(a032*a070);
  a071=(a045*a053);
  a082=(a027*a070);
  a063=(a020*a082);
  a063=(a042*a063);
  a071=(a071+a063);
  a063=(a039*a082);
  a071=(a071+a063);
  a063=(a020*a070);
  a063=(a036*a063);
  a071=(a071+a063);
  a063=(a033*a070);
  a071=(a071+a063);
  a032=(a032*a123);
  a063=(a029*a032);
  a071=(a071+a063);
  a063=(a027*a123);
  a068=(a020*a063);
  a068=(a025*a068);
  a071=(a071+a068);
  a068=(a022*a063);
  a071=(a071+a068);
  a034=(a034*a121);
  a013=(a056*a013);
  a053=(a047*a053);
  a121=(2.*a020);
  a027=(2.*a027);
  a046=(a046*a070);
  a046=(a027*a046);
  a040=(a040*a070);
  a046=(a046+a040);
  a046=(a121*a046);
  a053=(a053+a046);
  a043=(a043*a082);
  a053=(a053+a043);
  a037=(a037*a070);
  a053=(a053+a037);
  a053=(a013*a053);
  a034=(a034+a053);
  a032=(a031*a032);
  a030=(a030*a123);
  a027=(a027*a030);
  a023=(a023*a123);
  a027=(a027+a023);
  a121=(a121*a027);
  a032=(a032+a121);
  a026=(a026*a063);
  a032=(a032+a026);
  a017=(a017*a123);
  a032=(a032+a017);
  a013=(a013*a032);
  a034=(a034+a013);
  a034=(a018*a034);
  a071=(a071+a034);
  a020=(a020*a123);
  a020=(a016*a020);
  a071=(a071+a020);
  a123=(a001*a123);
  a071=(a071+a123);
  a081=(a081*a071);
  a084=(a084+a081);
  a058=(a058*a084);
  a081=(a048*a072);
  a123=(a129*a011);
  a020=(a081-a123);
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
  a061=(a048*a061);
  a066=(a061+a066);
  a066=(a065*a066);
  a131=(a131+a066);
  a065=(a065*a071);
  a131=(a131+a065);
  a020=(a020*a131);
  a058=(a058+a020);
  a020=(a048*a008);
  a020=(a050-a020);
  a125=(a129*a125);
  a005=(a056*a005);
  a125=(a125+a005);
  a005=(2.*a004);
  a061=(a061+a087);
  a061=(a005*a061);
  a125=(a125+a061);
  a125=(a125+a059);
  a132=(a011*a132);
  a125=(a125-a132);
  a130=(a007*a130);
  a125=(a125-a130);
  a005=(a005*a071);
  a125=(a125+a005);
  a020=(a020*a125);
  a058=(a058+a020);
  a005=arg[1]? arg[1][2] : 0;
  a072=(a062*a072);
  a019=(a019*a014);
  a019=(a050-a019);
  a052=(a052*a019);
  a019=(a052*a011);
  a014=(a072-a019);
  a014=(a005*a014);
  a071=arg[1]? arg[1][5] : 0;
  a130=(a062*a012);
  a130=(a050-a130);
  a130=(a071*a130);
  a014=(a014+a130);
  a130=arg[1]? arg[1][8] : 0;
  a132=(a052*a004);
  a059=(a062*a079);
  a132=(a132+a059);
  a132=(a130*a132);
  a014=(a014+a132);
  a132=(a056*a002);
  a014=(a014*a132);
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
  a008=(a062*a008);
  a008=(a050-a008);
  a008=(a005*a008);
  a019=(a019+a072);
  a019=(a071*a019);
  a008=(a008+a019);
  a062=(a062*a054);
  a052=(a052*a007);
  a062=(a062-a052);
  a062=(a130*a062);
  a008=(a008+a062);
  a008=(a008*a132);
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
  a009=(a009/a002);
  if (res[0]!=0) res[0][2]=a009;
  a009=(a114*a120);
  a110=(a096*a110);
  a110=(a050-a110);
  a110=(a104*a110);
  a014=(a110*a091);
  a008=(a009-a014);
  a008=(a005*a008);
  a062=(a114*a092);
  a062=(a050-a062);
  a062=(a071*a062);
  a008=(a008+a062);
  a062=(a110*a086);
  a052=(a114*a078);
  a062=(a062+a052);
  a062=(a130*a062);
  a008=(a008+a062);
  a008=(a008*a132);
  a105=(a105-a094);
  a105=(a000+a105);
  a104=(a049*a104);
  a105=(a105/a104);
  a094=(a105*a112);
  a062=(a056*a088);
  a052=(a094-a062);
  a116=(a018*a116);
  a111=(a111+a116);
  a116=-3.8675134594812879e-02;
  a124=(a116*a124);
  a111=(a111+a124);
  a124=(a119*a111);
  a054=(a105*a124);
  a010=(a018*a010);
  a128=(a128+a010);
  a122=(a116*a122);
  a128=(a128+a122);
  a122=(a113*a128);
  a010=(a105*a122);
  a054=(a054+a010);
  a010=(a088*a054);
  a064=(a064-a010);
  a010=(a069*a128);
  a019=(a129*a010);
  a064=(a064+a019);
  a019=(a069*a111);
  a072=(a105*a019);
  a115=(a018*a115);
  a134=(a134+a115);
  a116=(a116*a085);
  a134=(a134+a116);
  a116=(a113*a134);
  a085=(a105*a116);
  a072=(a072+a085);
  a085=(a086*a072);
  a064=(a064-a085);
  a085=(a119*a134);
  a115=(a056*a085);
  a064=(a064+a115);
  a115=(2.*a091);
  a119=(a119*a128);
  a128=(a105*a119);
  a069=(a069*a134);
  a134=(a105*a069);
  a059=(a128+a134);
  a059=(a115*a059);
  a064=(a064+a059);
  a059=(a105/a104);
  a113=(a113*a111);
  a111=(a090*a113);
  a061=(a078*a124);
  a111=(a111-a061);
  a061=(a112*a019);
  a111=(a111-a061);
  a061=(a078*a122);
  a111=(a111-a061);
  a119=(a092*a119);
  a111=(a111+a119);
  a119=(a120*a010);
  a111=(a111-a119);
  a119=(a112*a116);
  a111=(a111-a119);
  a119=(a120*a085);
  a111=(a111-a119);
  a069=(a089*a069);
  a111=(a111+a069);
  a059=(a059*a111);
  a059=(a049*a059);
  a096=(a096*a059);
  a111=(a111/a104);
  a096=(a096-a111);
  a104=(a102*a096);
  a069=(a045*a104);
  a119=(a100*a096);
  a061=(a097*a119);
  a061=(a042*a061);
  a069=(a069+a061);
  a061=(a039*a119);
  a069=(a069+a061);
  a061=(a097*a096);
  a061=(a036*a061);
  a069=(a069+a061);
  a061=(a033*a096);
  a069=(a069+a061);
  a102=(a102*a111);
  a061=(a029*a102);
  a069=(a069+a061);
  a061=(a100*a111);
  a087=(a097*a061);
  a087=(a025*a087);
  a069=(a069+a087);
  a087=(a022*a061);
  a069=(a069+a087);
  a103=(a103*a059);
  a093=(a056*a093);
  a104=(a047*a104);
  a059=(2.*a097);
  a100=(2.*a100);
  a101=(a101*a096);
  a101=(a100*a101);
  a098=(a098*a096);
  a101=(a101+a098);
  a101=(a059*a101);
  a104=(a104+a101);
  a099=(a099*a119);
  a104=(a104+a099);
  a095=(a095*a096);
  a104=(a104+a095);
  a104=(a093*a104);
  a103=(a103+a104);
  a102=(a031*a102);
  a109=(a109*a111);
  a100=(a100*a109);
  a107=(a107*a111);
  a100=(a100+a107);
  a059=(a059*a100);
  a102=(a102+a059);
  a108=(a108*a061);
  a102=(a102+a108);
  a106=(a106*a111);
  a102=(a102+a106);
  a093=(a093*a102);
  a103=(a103+a093);
  a103=(a018*a103);
  a069=(a069+a103);
  a097=(a097*a111);
  a097=(a016*a097);
  a069=(a069+a097);
  a111=(a001*a111);
  a069=(a069+a111);
  a115=(a115*a069);
  a064=(a064+a115);
  a052=(a052*a064);
  a008=(a008+a052);
  a120=(a105*a120);
  a052=(a129*a091);
  a115=(a120-a052);
  a019=(a056*a019);
  a080=(a080+a019);
  a054=(a091*a054);
  a080=(a080-a054);
  a116=(a129*a116);
  a080=(a080+a116);
  a010=(a105*a010);
  a085=(a105*a085);
  a010=(a010+a085);
  a085=(a086*a010);
  a080=(a080-a085);
  a085=(2.*a088);
  a113=(a105*a113);
  a134=(a113+a134);
  a134=(a085*a134);
  a080=(a080+a134);
  a085=(a085*a069);
  a080=(a080+a085);
  a115=(a115*a080);
  a008=(a008+a115);
  a115=(a105*a089);
  a115=(a050-a115);
  a124=(a129*a124);
  a076=(a076+a124);
  a122=(a056*a122);
  a076=(a076+a122);
  a122=(2.*a086);
  a113=(a113+a128);
  a113=(a122*a113);
  a076=(a076+a113);
  a072=(a091*a072);
  a076=(a076-a072);
  a010=(a088*a010);
  a076=(a076-a010);
  a122=(a122*a069);
  a076=(a076+a122);
  a115=(a115*a076);
  a008=(a008+a115);
  a008=(a008/a002);
  if (res[0]!=0) res[0][3]=a008;
  a078=(a105*a078);
  a008=(a129*a086);
  a122=(a078-a008);
  a122=(a122*a064);
  a089=(a114*a089);
  a089=(a050-a089);
  a005=(a005*a089);
  a014=(a014+a009);
  a071=(a071*a014);
  a005=(a005+a071);
  a114=(a114*a112);
  a110=(a110*a088);
  a114=(a114-a110);
  a130=(a130*a114);
  a005=(a005+a130);
  a005=(a005*a132);
  a122=(a122-a005);
  a092=(a105*a092);
  a092=(a050-a092);
  a092=(a092*a080);
  a122=(a122+a092);
  a091=(a056*a091);
  a005=(a120-a091);
  a005=(a005*a076);
  a122=(a122+a005);
  a122=(a122/a002);
  if (res[0]!=0) res[0][4]=a122;
  a105=(a105*a090);
  a105=(a050-a105);
  a105=(a105*a064);
  a086=(a056*a086);
  a090=(a078-a086);
  a090=(a090*a080);
  a090=(a105+a090);
  a088=(a129*a088);
  a122=(a094-a088);
  a122=(a122*a076);
  a090=(a090+a122);
  a090=(a090/a002);
  if (res[0]!=0) res[0][5]=a090;
  a090=arg[2]? arg[2][0] : 0;
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
  a122=casadi_sq(a075);
  a005=(a003+a122);
  a077=(a056*a077);
  a118=(a056*a118);
  a077=(a077+a118);
  a002=(a002*a077);
  a077=casadi_sq(a002);
  a118=(a005+a077);
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
  a122=(a122+a077);
  a122=(a000*a122);
  a122=(a050-a122);
  a122=(a122*a133);
  a006=(a006+a122);
  a062=(a062+a094);
  a062=(a062*a064);
  a006=(a006+a062);
  a052=(a052+a120);
  a052=(a052*a080);
  a006=(a006+a052);
  a006=(a006+a115);
  a057=(a057+a055);
  a057=(a057*a084);
  a006=(a006+a057);
  a123=(a123+a081);
  a123=(a123*a131);
  a006=(a006+a123);
  a006=(a006+a020);
  a090=(a090-a006);
  if (res[0]!=0) res[0][6]=a090;
  a090=arg[2]? arg[2][1] : 0;
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
  a008=(a008+a078);
  a008=(a008*a064);
  a006=(a006+a008);
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
  a090=(a090-a006);
  if (res[0]!=0) res[0][7]=a090;
  a090=arg[2]? arg[2][2] : 0;
  a000=(a000*a005);
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
  a090=(a090-a050);
  if (res[0]!=0) res[0][8]=a090;
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
  casadi_real a348, a349, a350, a351, a352, a353, a354;
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
  a163=arg[1]? arg[1][2] : 0;
  a194=(a062*a072);
  a195=(a019*a014);
  a195=(a050-a195);
  a196=(a052*a195);
  a197=(a196*a011);
  a198=(a194-a197);
  a198=(a163*a198);
  a199=arg[1]? arg[1][5] : 0;
  a200=(a062*a012);
  a200=(a050-a200);
  a200=(a199*a200);
  a198=(a198+a200);
  a200=arg[1]? arg[1][8] : 0;
  a201=(a196*a004);
  a202=(a062*a081);
  a201=(a201+a202);
  a201=(a200*a201);
  a198=(a198+a201);
  a201=(a056*a002);
  a198=(a198*a201);
  a178=(a178+a198);
  a178=(a178/a002);
  if (res[0]!=0) res[0][0]=a178;
  a178=(a048*a081);
  a198=(a148*a004);
  a202=(a178-a198);
  a203=(a202*a089);
  a204=(a048*a012);
  a204=(a050-a204);
  a205=(a204*a188);
  a203=(a203+a205);
  a206=(a056*a011);
  a207=(a185-a206);
  a208=(a207*a192);
  a203=(a203+a208);
  a208=(a062*a008);
  a208=(a050-a208);
  a208=(a163*a208);
  a197=(a197+a194);
  a197=(a199*a197);
  a208=(a208+a197);
  a197=(a062*a054);
  a194=(a196*a007);
  a197=(a197-a194);
  a197=(a200*a197);
  a208=(a208+a197);
  a208=(a208*a201);
  a203=(a203-a208);
  a203=(a203/a002);
  if (res[0]!=0) res[0][1]=a203;
  a203=(a048*a009);
  a203=(a050-a203);
  a208=(a203*a089);
  a197=(a056*a004);
  a194=(a178-a197);
  a209=(a194*a188);
  a209=(a208+a209);
  a210=(a148*a007);
  a211=(a055-a210);
  a212=(a211*a192);
  a209=(a209+a212);
  a209=(a209/a002);
  if (res[0]!=0) res[0][2]=a209;
  a209=(a119*a125);
  a212=(a101*a115);
  a212=(a050-a212);
  a213=(a109*a212);
  a214=(a213*a096);
  a215=(a209-a214);
  a215=(a163*a215);
  a216=(a119*a097);
  a216=(a050-a216);
  a216=(a199*a216);
  a215=(a215+a216);
  a216=(a213*a091);
  a217=(a119*a128);
  a216=(a216+a217);
  a216=(a200*a216);
  a215=(a215+a216);
  a215=(a215*a201);
  a110=(a110-a099);
  a110=(a000+a110);
  a099=(a049*a109);
  a110=(a110/a099);
  a216=(a110*a117);
  a217=(a056*a093);
  a218=(a216-a217);
  a078=(a018*a078);
  a133=(a133+a078);
  a078=-3.8675134594812879e-02;
  a137=(a078*a137);
  a133=(a133+a137);
  a137=(a124*a133);
  a219=(a110*a137);
  a145=(a018*a145);
  a141=(a141+a145);
  a144=(a078*a144);
  a141=(a141+a144);
  a144=(a118*a141);
  a145=(a110*a144);
  a219=(a219+a145);
  a145=(a093*a219);
  a079=(a079-a145);
  a145=(a069*a141);
  a220=(a148*a145);
  a079=(a079+a220);
  a220=(a069*a133);
  a221=(a110*a220);
  a157=(a018*a157);
  a153=(a153+a157);
  a156=(a078*a156);
  a153=(a153+a156);
  a156=(a118*a153);
  a157=(a110*a156);
  a221=(a221+a157);
  a157=(a091*a221);
  a079=(a079-a157);
  a157=(a124*a153);
  a222=(a056*a157);
  a079=(a079+a222);
  a222=(2.*a096);
  a223=(a124*a141);
  a224=(a110*a223);
  a225=(a069*a153);
  a226=(a110*a225);
  a227=(a224+a226);
  a228=(a222*a227);
  a079=(a079+a228);
  a228=(a110/a099);
  a229=(a118*a133);
  a230=(a095*a229);
  a231=(a128*a137);
  a230=(a230-a231);
  a231=(a117*a220);
  a230=(a230-a231);
  a231=(a128*a144);
  a230=(a230-a231);
  a231=(a097*a223);
  a230=(a230+a231);
  a231=(a125*a145);
  a230=(a230-a231);
  a231=(a117*a156);
  a230=(a230-a231);
  a231=(a125*a157);
  a230=(a230-a231);
  a231=(a094*a225);
  a230=(a230+a231);
  a231=(a228*a230);
  a231=(a049*a231);
  a232=(a101*a231);
  a233=(a230/a099);
  a232=(a232-a233);
  a234=(a107*a232);
  a235=(a045*a234);
  a236=(a105*a232);
  a237=(a102*a236);
  a237=(a042*a237);
  a235=(a235+a237);
  a237=(a039*a236);
  a235=(a235+a237);
  a237=(a102*a232);
  a237=(a036*a237);
  a235=(a235+a237);
  a237=(a033*a232);
  a235=(a235+a237);
  a237=(a107*a233);
  a238=(a029*a237);
  a235=(a235+a238);
  a238=(a105*a233);
  a239=(a102*a238);
  a239=(a025*a239);
  a235=(a235+a239);
  a239=(a022*a238);
  a235=(a235+a239);
  a239=(a108*a231);
  a098=(a056*a098);
  a234=(a047*a234);
  a240=(2.*a102);
  a241=(2.*a105);
  a242=(a106*a232);
  a243=(a241*a242);
  a244=(a103*a232);
  a243=(a243+a244);
  a244=(a240*a243);
  a234=(a234+a244);
  a244=(a104*a236);
  a234=(a234+a244);
  a244=(a100*a232);
  a234=(a234+a244);
  a244=(a098*a234);
  a239=(a239+a244);
  a237=(a031*a237);
  a244=(a114*a233);
  a245=(a241*a244);
  a246=(a112*a233);
  a245=(a245+a246);
  a246=(a240*a245);
  a237=(a237+a246);
  a246=(a113*a238);
  a237=(a237+a246);
  a246=(a111*a233);
  a237=(a237+a246);
  a246=(a098*a237);
  a239=(a239+a246);
  a239=(a018*a239);
  a235=(a235+a239);
  a239=(a102*a233);
  a239=(a016*a239);
  a235=(a235+a239);
  a239=(a001*a233);
  a235=(a235+a239);
  a239=(a222*a235);
  a079=(a079+a239);
  a239=(a218*a079);
  a215=(a215+a239);
  a239=(a110*a125);
  a246=(a148*a096);
  a247=(a239-a246);
  a248=(a056*a220);
  a143=(a143+a248);
  a248=(a096*a219);
  a143=(a143-a248);
  a248=(a148*a156);
  a143=(a143+a248);
  a248=(a110*a145);
  a249=(a110*a157);
  a248=(a248+a249);
  a249=(a091*a248);
  a143=(a143-a249);
  a249=(2.*a093);
  a250=(a110*a229);
  a226=(a250+a226);
  a251=(a249*a226);
  a143=(a143+a251);
  a251=(a249*a235);
  a143=(a143+a251);
  a251=(a247*a143);
  a215=(a215+a251);
  a251=(a110*a094);
  a251=(a050-a251);
  a252=(a148*a137);
  a155=(a155+a252);
  a252=(a056*a144);
  a155=(a155+a252);
  a252=(2.*a091);
  a250=(a250+a224);
  a224=(a252*a250);
  a155=(a155+a224);
  a224=(a096*a221);
  a155=(a155-a224);
  a224=(a093*a248);
  a155=(a155-a224);
  a224=(a252*a235);
  a155=(a155+a224);
  a224=(a251*a155);
  a215=(a215+a224);
  a215=(a215/a002);
  if (res[0]!=0) res[0][3]=a215;
  a215=(a110*a128);
  a253=(a148*a091);
  a254=(a215-a253);
  a255=(a254*a079);
  a256=(a119*a094);
  a256=(a050-a256);
  a256=(a163*a256);
  a214=(a214+a209);
  a214=(a199*a214);
  a256=(a256+a214);
  a214=(a119*a117);
  a209=(a213*a093);
  a214=(a214-a209);
  a214=(a200*a214);
  a256=(a256+a214);
  a256=(a256*a201);
  a255=(a255-a256);
  a256=(a110*a097);
  a256=(a050-a256);
  a214=(a256*a143);
  a255=(a255+a214);
  a209=(a056*a096);
  a257=(a239-a209);
  a258=(a257*a155);
  a255=(a255+a258);
  a255=(a255/a002);
  if (res[0]!=0) res[0][4]=a255;
  a255=(a110*a095);
  a255=(a050-a255);
  a258=(a255*a079);
  a259=(a056*a091);
  a260=(a215-a259);
  a261=(a260*a143);
  a261=(a258+a261);
  a262=(a148*a093);
  a263=(a216-a262);
  a264=(a263*a155);
  a261=(a261+a264);
  a261=(a261/a002);
  if (res[0]!=0) res[0][5]=a261;
  a261=arg[2]? arg[2][0] : 0;
  a264=(a056*a075);
  a265=(a056*a006);
  a264=(a264+a265);
  a264=(a002*a264);
  a265=(a056*a264);
  a266=(a056*a067);
  a267=(a056*a003);
  a266=(a266+a267);
  a266=(a002*a266);
  a267=casadi_sq(a266);
  a268=casadi_sq(a264);
  a269=(a267+a268);
  a270=(a056*a077);
  a271=(a056*a010);
  a270=(a270+a271);
  a270=(a002*a270);
  a271=casadi_sq(a270);
  a272=(a269+a271);
  a273=(a001*a272);
  a274=(a016*a272);
  a015=(a015+a274);
  a274=(a018*a272);
  a275=casadi_sq(a274);
  a276=(a015*a275);
  a273=(a273+a276);
  a276=(a022*a272);
  a021=(a021+a276);
  a276=(a025*a272);
  a024=(a024+a276);
  a276=(a024*a275);
  a021=(a021+a276);
  a276=casadi_sq(a275);
  a277=(a021*a276);
  a273=(a273+a277);
  a277=(a029*a272);
  a028=(a028+a277);
  a277=(a031*a275);
  a028=(a028+a277);
  a277=casadi_sq(a276);
  a278=(a028*a277);
  a273=(a273+a278);
  a278=(a033*a272);
  a279=(a036*a272);
  a035=(a035+a279);
  a279=(a035*a275);
  a278=(a278+a279);
  a279=(a039*a272);
  a038=(a038+a279);
  a279=(a042*a272);
  a041=(a041+a279);
  a279=(a041*a275);
  a038=(a038+a279);
  a279=(a038*a276);
  a278=(a278+a279);
  a279=(a045*a272);
  a044=(a044+a279);
  a279=(a047*a275);
  a044=(a044+a279);
  a279=(a044*a277);
  a278=(a278+a279);
  a273=(a273-a278);
  a000=(a000+a273);
  a051=(a051+a278);
  a278=(a274*a051);
  a278=(a050-a278);
  a278=(a049*a278);
  a000=(a000/a278);
  a273=(a266*a270);
  a279=(a000*a273);
  a265=(a265+a279);
  a280=(a265*a088);
  a281=(a148*a270);
  a282=(a266*a264);
  a283=(a000*a282);
  a281=(a281+a283);
  a284=(a281*a140);
  a280=(a280+a284);
  a268=(a268+a271);
  a284=(a000*a268);
  a284=(a050-a284);
  a285=(a284*a152);
  a280=(a280+a285);
  a217=(a217+a216);
  a285=(a217*a079);
  a280=(a280+a285);
  a246=(a246+a239);
  a285=(a246*a143);
  a280=(a280+a285);
  a280=(a280+a224);
  a057=(a057+a055);
  a224=(a057*a089);
  a280=(a280+a224);
  a186=(a186+a185);
  a224=(a186*a188);
  a280=(a280+a224);
  a280=(a280+a154);
  a261=(a261-a280);
  if (res[0]!=0) res[0][6]=a261;
  a261=arg[2]? arg[2][1] : 0;
  a280=(a148*a266);
  a154=(a264*a270);
  a224=(a000*a154);
  a280=(a280+a224);
  a285=(a280*a088);
  a271=(a271+a267);
  a267=(a000*a271);
  a267=(a050-a267);
  a286=(a267*a140);
  a285=(a285+a286);
  a286=(a056*a270);
  a286=(a286+a283);
  a283=(a286*a152);
  a285=(a285+a283);
  a253=(a253+a215);
  a283=(a253*a079);
  a285=(a285+a283);
  a285=(a285+a214);
  a209=(a209+a239);
  a239=(a209*a155);
  a285=(a285+a239);
  a198=(a198+a178);
  a239=(a198*a089);
  a285=(a285+a239);
  a285=(a285+a205);
  a206=(a206+a185);
  a185=(a206*a192);
  a285=(a285+a185);
  a261=(a261-a285);
  if (res[0]!=0) res[0][7]=a261;
  a261=arg[2]? arg[2][2] : 0;
  a285=(a000*a269);
  a050=(a050-a285);
  a285=(a050*a088);
  a185=(a056*a266);
  a185=(a185+a224);
  a224=(a185*a140);
  a285=(a285+a224);
  a224=(a148*a264);
  a224=(a224+a279);
  a279=(a224*a152);
  a285=(a285+a279);
  a285=(a285+a258);
  a259=(a259+a215);
  a215=(a259*a143);
  a285=(a285+a215);
  a262=(a262+a216);
  a216=(a262*a155);
  a285=(a285+a216);
  a285=(a285+a208);
  a197=(a197+a178);
  a178=(a197*a188);
  a285=(a285+a178);
  a210=(a210+a055);
  a055=(a210*a192);
  a285=(a285+a055);
  a261=(a261-a285);
  if (res[0]!=0) res[0][8]=a261;
  a261=(a193*a002);
  a285=(a001*a261);
  a055=(a016*a261);
  a178=(a020*a055);
  a208=(a018*a261);
  a216=(a013*a208);
  a215=(a017*a216);
  a178=(a178+a215);
  a285=(a285+a178);
  a178=(a022*a261);
  a215=(a025*a261);
  a258=(a020*a215);
  a279=(a026*a216);
  a258=(a258+a279);
  a178=(a178+a258);
  a258=(a027*a178);
  a279=(a179*a216);
  a205=(a023*a279);
  a258=(a258+a205);
  a285=(a285+a258);
  a258=(a029*a261);
  a205=(a031*a216);
  a258=(a258+a205);
  a205=(a032*a258);
  a239=(a180*a279);
  a214=(a030*a239);
  a205=(a205+a214);
  a285=(a285+a205);
  a205=(a033*a261);
  a214=(a036*a261);
  a283=(a020*a214);
  a287=(a037*a216);
  a283=(a283+a287);
  a205=(a205+a283);
  a283=(a039*a261);
  a287=(a042*a261);
  a288=(a020*a287);
  a289=(a043*a216);
  a288=(a288+a289);
  a283=(a283+a288);
  a288=(a027*a283);
  a289=(a040*a279);
  a288=(a288+a289);
  a205=(a205+a288);
  a288=(a045*a261);
  a289=(a047*a216);
  a288=(a288+a289);
  a289=(a032*a288);
  a290=(a046*a239);
  a289=(a289+a290);
  a205=(a205+a289);
  a289=(a285-a205);
  a289=(a289/a053);
  a290=(a034*a208);
  a291=(a019*a205);
  a290=(a290+a291);
  a291=(a049*a290);
  a292=(a167*a291);
  a289=(a289+a292);
  a292=(a054*a289);
  a293=(a011*a002);
  a294=(a048*a293);
  a292=(a292+a294);
  a295=(a089*a292);
  a296=(a052*a285);
  a297=(a014*a290);
  a296=(a296-a297);
  a296=(a205+a296);
  a296=(a018*a296);
  a297=(a054*a296);
  a298=(a060*a293);
  a297=(a297+a298);
  a299=(2.*a052);
  a300=(a299*a290);
  a300=(a056*a300);
  a301=(a007*a300);
  a302=(a297+a301);
  a303=(a070*a302);
  a304=(a066*a065);
  a305=(a008*a296);
  a306=(a067*a305);
  a304=(a304-a306);
  a306=(a072*a296);
  a307=(a007*a002);
  a308=(a060*a307);
  a306=(a306+a308);
  a309=(a011*a300);
  a310=(a306-a309);
  a311=(a075*a310);
  a304=(a304+a311);
  a302=(a077*a302);
  a304=(a304+a302);
  a302=(a064*a304);
  a303=(a303+a302);
  a302=(a062*a002);
  a311=(a004*a300);
  a311=(a302-a311);
  a312=(a081*a296);
  a313=(a311+a312);
  a314=(a085*a313);
  a306=(a306+a309);
  a309=(a067*a306);
  a315=(a066*a073);
  a309=(a309+a315);
  a315=(a012*a296);
  a316=(a060*a261);
  a315=(a315+a316);
  a317=(a075*a315);
  a309=(a309-a317);
  a313=(a077*a313);
  a309=(a309+a313);
  a313=(a084*a309);
  a317=(a083*a313);
  a314=(a314+a317);
  a303=(a303+a314);
  a297=(a297-a301);
  a301=(a067*a297);
  a314=(a066*a063);
  a301=(a301+a314);
  a312=(a312-a311);
  a311=(a075*a312);
  a301=(a301+a311);
  a296=(a009*a296);
  a296=(a296+a316);
  a316=(a077*a296);
  a301=(a301-a316);
  a316=(a087*a301);
  a311=(a086*a316);
  a296=(a080*a296);
  a311=(a311-a296);
  a303=(a303+a311);
  a311=(a059*a303);
  a296=(a123*a122);
  a314=(a121*a296);
  a317=-3.2320508075688778e+01;
  a318=(a317*a126);
  a319=(a130*a318);
  a314=(a314+a319);
  a319=-3.8784609690826528e+01;
  a320=(a319*a120);
  a321=(a132*a320);
  a314=(a314+a321);
  a321=(a090*a314);
  a311=(a311+a321);
  a321=(a138*a289);
  a322=(a136*a309);
  a303=(a135*a303);
  a314=(a059*a314);
  a303=(a303+a314);
  a314=(a002*a303);
  a323=(a134*a314);
  a324=(a002*a311);
  a325=(a018*a324);
  a323=(a323+a325);
  a325=(a071*a323);
  a322=(a322+a325);
  a325=(a048*a322);
  a321=(a321+a325);
  a325=(a147*a289);
  a326=(a146*a301);
  a310=(a070*a310);
  a327=(a074*a304);
  a310=(a310+a327);
  a327=(a005*a313);
  a315=(a085*a315);
  a327=(a327-a315);
  a310=(a310+a327);
  a312=(a080*a312);
  a327=(a082*a316);
  a312=(a312+a327);
  a310=(a310+a312);
  a312=(a135*a310);
  a327=(a127*a296);
  a315=(a092*a318);
  a327=(a327+a315);
  a315=(a129*a320);
  a327=(a327+a315);
  a315=(a059*a327);
  a312=(a312+a315);
  a315=(a002*a312);
  a328=(a134*a315);
  a310=(a059*a310);
  a327=(a090*a327);
  a310=(a310+a327);
  a327=(a002*a310);
  a329=(a018*a327);
  a328=(a328+a329);
  a329=(a061*a328);
  a326=(a326+a329);
  a329=(a048*a326);
  a325=(a325+a329);
  a321=(a321+a325);
  a325=(a007*a321);
  a311=(a311-a325);
  a325=(a146*a304);
  a329=(a070*a328);
  a325=(a325+a329);
  a329=(a148*a325);
  a311=(a311+a329);
  a151=(a151*a002);
  a329=(a150*a289);
  a330=(a136*a304);
  a331=(a070*a323);
  a330=(a330+a331);
  a331=(a048*a330);
  a329=(a329+a331);
  a331=(a159*a289);
  a332=(a158*a301);
  a333=(a065*a304);
  a305=(a070*a305);
  a333=(a333-a305);
  a306=(a085*a306);
  a313=(a073*a313);
  a306=(a306+a313);
  a333=(a333+a306);
  a297=(a080*a297);
  a316=(a063*a316);
  a297=(a297+a316);
  a333=(a333+a297);
  a297=(a135*a333);
  a316=(a122*a296);
  a318=(a126*a318);
  a316=(a316+a318);
  a320=(a120*a320);
  a316=(a316+a320);
  a320=(a059*a316);
  a297=(a297+a320);
  a320=(a002*a297);
  a318=(a134*a320);
  a333=(a059*a333);
  a316=(a090*a316);
  a333=(a333+a316);
  a316=(a002*a333);
  a306=(a018*a316);
  a318=(a318+a306);
  a306=(a061*a318);
  a332=(a332+a306);
  a306=(a048*a332);
  a331=(a331+a306);
  a329=(a329+a331);
  a331=(a004*a329);
  a331=(a151+a331);
  a311=(a311-a331);
  a331=(a158*a309);
  a306=(a071*a318);
  a331=(a331+a306);
  a306=(a056*a331);
  a311=(a311+a306);
  a306=(a162*a289);
  a309=(a146*a309);
  a328=(a071*a328);
  a309=(a309+a328);
  a328=(a048*a309);
  a306=(a306+a328);
  a328=(a164*a289);
  a304=(a158*a304);
  a318=(a070*a318);
  a304=(a304+a318);
  a318=(a048*a304);
  a328=(a328+a318);
  a318=(a306+a328);
  a318=(a161*a318);
  a311=(a311+a318);
  a318=(a171*a239);
  a313=(a170*a208);
  a305=(a289/a053);
  a334=(a167/a053);
  a335=(a334*a291);
  a305=(a305+a335);
  a305=(a169*a305);
  a335=(a168*a261);
  a301=(a136*a301);
  a323=(a061*a323);
  a301=(a301+a323);
  a323=(a009*a301);
  a335=(a335+a323);
  a323=(a081*a322);
  a335=(a335-a323);
  a323=(a150*a293);
  a336=(a054*a330);
  a323=(a323+a336);
  a335=(a335-a323);
  a323=(a081*a326);
  a335=(a335-a323);
  a323=(a162*a261);
  a309=(a012*a309);
  a323=(a323+a309);
  a335=(a335+a323);
  a323=(a149*a307);
  a309=(a072*a325);
  a323=(a323+a309);
  a335=(a335-a323);
  a323=(a159*a293);
  a309=(a054*a332);
  a323=(a323+a309);
  a335=(a335-a323);
  a323=(a160*a307);
  a309=(a072*a331);
  a323=(a323+a309);
  a335=(a335-a323);
  a304=(a008*a304);
  a335=(a335+a304);
  a304=(a167*a335);
  a305=(a305+a304);
  a305=(a049*a305);
  a304=(a019*a305);
  a313=(a313+a304);
  a335=(a335/a053);
  a304=(a172/a053);
  a291=(a304*a291);
  a335=(a335+a291);
  a313=(a313-a335);
  a291=(a032*a313);
  a318=(a318+a291);
  a291=(a045*a318);
  a323=(a175*a216);
  a309=(a171*a279);
  a336=(a027*a313);
  a309=(a309+a336);
  a336=(a020*a309);
  a323=(a323+a336);
  a323=(a042*a323);
  a291=(a291+a323);
  a323=(a039*a309);
  a291=(a291+a323);
  a323=(a171*a216);
  a336=(a020*a313);
  a323=(a323+a336);
  a323=(a036*a323);
  a291=(a291+a323);
  a323=(a033*a313);
  a291=(a291+a323);
  a239=(a172*a239);
  a323=(a032*a335);
  a239=(a239+a323);
  a323=(a029*a239);
  a291=(a291+a323);
  a323=(a177*a216);
  a336=(a172*a279);
  a337=(a027*a335);
  a336=(a336+a337);
  a337=(a020*a336);
  a323=(a323+a337);
  a323=(a025*a323);
  a291=(a291+a323);
  a323=(a022*a336);
  a291=(a291+a323);
  a205=(a170*a205);
  a305=(a034*a305);
  a205=(a205+a305);
  a305=(a056*a261);
  a323=(a173*a305);
  a318=(a047*a318);
  a337=(2.*a216);
  a338=(a182*a337);
  a279=(2.*a279);
  a339=(a181*a279);
  a288=(a171*a288);
  a340=(a046*a313);
  a288=(a288+a340);
  a288=(a180*a288);
  a339=(a339+a288);
  a283=(a171*a283);
  a288=(a040*a313);
  a283=(a283+a288);
  a339=(a339+a283);
  a339=(a179*a339);
  a338=(a338+a339);
  a318=(a318+a338);
  a287=(a175*a287);
  a309=(a043*a309);
  a287=(a287+a309);
  a318=(a318+a287);
  a214=(a171*a214);
  a313=(a037*a313);
  a214=(a214+a313);
  a318=(a318+a214);
  a318=(a013*a318);
  a323=(a323+a318);
  a205=(a205+a323);
  a305=(a176*a305);
  a239=(a031*a239);
  a337=(a184*a337);
  a279=(a183*a279);
  a258=(a172*a258);
  a323=(a030*a335);
  a258=(a258+a323);
  a258=(a180*a258);
  a279=(a279+a258);
  a178=(a172*a178);
  a258=(a023*a335);
  a178=(a178+a258);
  a279=(a279+a178);
  a279=(a179*a279);
  a337=(a337+a279);
  a239=(a239+a337);
  a215=(a177*a215);
  a336=(a026*a336);
  a215=(a215+a336);
  a239=(a239+a215);
  a055=(a172*a055);
  a215=(a017*a335);
  a055=(a055+a215);
  a239=(a239+a055);
  a239=(a013*a239);
  a305=(a305+a239);
  a205=(a205+a305);
  a205=(a018*a205);
  a291=(a291+a205);
  a216=(a172*a216);
  a205=(a020*a335);
  a216=(a216+a205);
  a216=(a016*a216);
  a291=(a291+a216);
  a335=(a001*a335);
  a291=(a291+a335);
  a335=(a161*a291);
  a311=(a311+a335);
  a335=(a058*a311);
  a335=(a295+a335);
  a216=(a072*a289);
  a205=(a048*a307);
  a216=(a216+a205);
  a305=(a188*a216);
  a330=(a056*a330);
  a330=(a330+a310);
  a321=(a011*a321);
  a330=(a330-a321);
  a332=(a148*a332);
  a330=(a330+a332);
  a142=(a142*a002);
  a332=(a149*a289);
  a325=(a048*a325);
  a332=(a332+a325);
  a325=(a160*a289);
  a331=(a048*a331);
  a325=(a325+a331);
  a332=(a332+a325);
  a325=(a004*a332);
  a325=(a142+a325);
  a330=(a330-a325);
  a325=(a168*a289);
  a301=(a048*a301);
  a325=(a325+a301);
  a328=(a325+a328);
  a328=(a189*a328);
  a330=(a330+a328);
  a328=(a189*a291);
  a330=(a330+a328);
  a328=(a187*a330);
  a328=(a305+a328);
  a335=(a335+a328);
  a322=(a148*a322);
  a326=(a056*a326);
  a322=(a322+a326);
  a326=(2.*a002);
  a190=(a190*a326);
  a325=(a325+a306);
  a325=(a193*a325);
  a190=(a190+a325);
  a322=(a322+a190);
  a322=(a322+a333);
  a329=(a011*a329);
  a322=(a322-a329);
  a332=(a007*a332);
  a322=(a322-a332);
  a174=(a174*a326);
  a291=(a193*a291);
  a291=(a174+a291);
  a322=(a322+a291);
  a291=(a191*a322);
  a332=(a008*a289);
  a332=(a192*a332);
  a291=(a291-a332);
  a335=(a335+a291);
  a332=(a062*a307);
  a329=(a072*a300);
  a329=(a332-a329);
  a290=(a195*a290);
  a208=(a014*a208);
  a285=(a019*a285);
  a208=(a208+a285);
  a208=(a052*a208);
  a290=(a290+a208);
  a208=(a011*a290);
  a285=(a329+a208);
  a285=(a163*a285);
  a333=(a062*a261);
  a190=(a012*a300);
  a333=(a333-a190);
  a333=(a199*a333);
  a285=(a285-a333);
  a196=(a196*a002);
  a333=(a004*a290);
  a333=(a196-a333);
  a190=(a081*a300);
  a333=(a333-a190);
  a333=(a200*a333);
  a285=(a285+a333);
  a285=(a201*a285);
  a335=(a335+a285);
  a335=(a335/a002);
  if (res[1]!=0) res[1][0]=a335;
  a335=(a081*a289);
  a285=(a148*a002);
  a333=(a335-a285);
  a333=(a089*a333);
  a190=(a202*a311);
  a333=(a333+a190);
  a190=(a204*a330);
  a325=(a012*a289);
  a261=(a048*a261);
  a325=(a325+a261);
  a325=(a188*a325);
  a190=(a190-a325);
  a333=(a333+a190);
  a216=(a192*a216);
  a325=(a207*a322);
  a325=(a216+a325);
  a333=(a333+a325);
  a325=(a008*a300);
  a325=(a163*a325);
  a329=(a329-a208);
  a329=(a199*a329);
  a325=(a325+a329);
  a329=(a062*a293);
  a300=(a054*a300);
  a300=(a329-a300);
  a290=(a007*a290);
  a300=(a300+a290);
  a300=(a200*a300);
  a325=(a325+a300);
  a325=(a201*a325);
  a333=(a333-a325);
  a333=(a333/a002);
  if (res[1]!=0) res[1][1]=a333;
  a333=(a203*a311);
  a289=(a009*a289);
  a289=(a289+a261);
  a289=(a089*a289);
  a333=(a333-a289);
  a289=(a335-a201);
  a289=(a188*a289);
  a261=(a194*a330);
  a289=(a289+a261);
  a289=(a333+a289);
  a292=(a192*a292);
  a261=(a211*a322);
  a261=(a292+a261);
  a289=(a289+a261);
  a289=(a289/a002);
  if (res[1]!=0) res[1][2]=a289;
  a289=(a123*a126);
  a261=(a133*a289);
  a314=(a018*a314);
  a324=(a078*a324);
  a314=(a314+a324);
  a324=(a124*a314);
  a261=(a261+a324);
  a324=(a110*a261);
  a325=(a123*a120);
  a300=(a141*a325);
  a315=(a018*a315);
  a327=(a078*a327);
  a315=(a315+a327);
  a327=(a118*a315);
  a300=(a300+a327);
  a327=(a110*a300);
  a324=(a324+a327);
  a327=(a093*a324);
  a303=(a303-a327);
  a327=(a141*a296);
  a290=(a069*a315);
  a327=(a327+a290);
  a290=(a148*a327);
  a303=(a303+a290);
  a290=(a133*a296);
  a208=(a069*a314);
  a290=(a290+a208);
  a208=(a110*a290);
  a306=(a153*a325);
  a320=(a018*a320);
  a316=(a078*a316);
  a320=(a320+a316);
  a316=(a118*a320);
  a306=(a306+a316);
  a316=(a110*a306);
  a208=(a208+a316);
  a316=(a091*a208);
  a303=(a303-a316);
  a316=(a153*a289);
  a328=(a124*a320);
  a316=(a316+a328);
  a328=(a056*a316);
  a303=(a303+a328);
  a289=(a141*a289);
  a315=(a124*a315);
  a289=(a289+a315);
  a315=(a110*a289);
  a296=(a153*a296);
  a320=(a069*a320);
  a296=(a296+a320);
  a320=(a110*a296);
  a328=(a315+a320);
  a328=(a222*a328);
  a303=(a303+a328);
  a325=(a133*a325);
  a314=(a118*a314);
  a325=(a325+a314);
  a314=(a095*a325);
  a328=(a128*a261);
  a314=(a314-a328);
  a328=(a117*a290);
  a314=(a314-a328);
  a328=(a128*a300);
  a314=(a314-a328);
  a289=(a097*a289);
  a314=(a314+a289);
  a289=(a125*a327);
  a314=(a314-a289);
  a289=(a117*a306);
  a314=(a314-a289);
  a289=(a125*a316);
  a314=(a314-a289);
  a296=(a094*a296);
  a314=(a314+a296);
  a296=(a228*a314);
  a296=(a049*a296);
  a289=(a101*a296);
  a314=(a314/a099);
  a289=(a289-a314);
  a328=(a107*a289);
  a301=(a045*a328);
  a331=(a105*a289);
  a321=(a102*a331);
  a321=(a042*a321);
  a301=(a301+a321);
  a321=(a039*a331);
  a301=(a301+a321);
  a321=(a102*a289);
  a321=(a036*a321);
  a301=(a301+a321);
  a321=(a033*a289);
  a301=(a301+a321);
  a321=(a107*a314);
  a310=(a029*a321);
  a301=(a301+a310);
  a310=(a105*a314);
  a239=(a102*a310);
  a239=(a025*a239);
  a301=(a301+a239);
  a239=(a022*a310);
  a301=(a301+a239);
  a296=(a108*a296);
  a328=(a047*a328);
  a239=(a106*a289);
  a239=(a241*a239);
  a055=(a103*a289);
  a239=(a239+a055);
  a239=(a240*a239);
  a328=(a328+a239);
  a331=(a104*a331);
  a328=(a328+a331);
  a289=(a100*a289);
  a328=(a328+a289);
  a328=(a098*a328);
  a296=(a296+a328);
  a321=(a031*a321);
  a328=(a114*a314);
  a328=(a241*a328);
  a289=(a112*a314);
  a328=(a328+a289);
  a328=(a240*a328);
  a321=(a321+a328);
  a310=(a113*a310);
  a321=(a321+a310);
  a310=(a111*a314);
  a321=(a321+a310);
  a321=(a098*a321);
  a296=(a296+a321);
  a296=(a018*a296);
  a301=(a301+a296);
  a296=(a102*a314);
  a296=(a016*a296);
  a301=(a301+a296);
  a314=(a001*a314);
  a301=(a301+a314);
  a314=(a222*a301);
  a303=(a303+a314);
  a314=(a218*a303);
  a290=(a056*a290);
  a312=(a312+a290);
  a324=(a096*a324);
  a312=(a312-a324);
  a306=(a148*a306);
  a312=(a312+a306);
  a327=(a110*a327);
  a316=(a110*a316);
  a327=(a327+a316);
  a316=(a091*a327);
  a312=(a312-a316);
  a325=(a110*a325);
  a320=(a325+a320);
  a320=(a249*a320);
  a312=(a312+a320);
  a320=(a249*a301);
  a312=(a312+a320);
  a320=(a247*a312);
  a314=(a314+a320);
  a261=(a148*a261);
  a297=(a297+a261);
  a300=(a056*a300);
  a297=(a297+a300);
  a325=(a325+a315);
  a325=(a252*a325);
  a297=(a297+a325);
  a208=(a096*a208);
  a297=(a297-a208);
  a327=(a093*a327);
  a297=(a297-a327);
  a301=(a252*a301);
  a297=(a297+a301);
  a301=(a251*a297);
  a314=(a314+a301);
  a314=(a314/a002);
  if (res[1]!=0) res[1][3]=a314;
  a314=(a254*a303);
  a327=(a256*a312);
  a314=(a314+a327);
  a208=(a257*a297);
  a314=(a314+a208);
  a314=(a314/a002);
  if (res[1]!=0) res[1][4]=a314;
  a314=(a255*a303);
  a208=(a260*a312);
  a208=(a314+a208);
  a325=(a263*a297);
  a208=(a208+a325);
  a208=(a208/a002);
  if (res[1]!=0) res[1][5]=a208;
  a208=(2.*a266);
  a325=-1.7320508075688774e+00;
  a315=(a325*a002);
  a300=(a208*a315);
  a261=(a001*a300);
  a320=(a016*a300);
  a320=(a275*a320);
  a272=(a056*a272);
  a316=(a018*a300);
  a306=(a272*a316);
  a324=(a015*a306);
  a320=(a320+a324);
  a261=(a261+a320);
  a320=(a022*a300);
  a324=(a025*a300);
  a324=(a275*a324);
  a290=(a024*a306);
  a324=(a324+a290);
  a320=(a320+a324);
  a320=(a276*a320);
  a324=(2.*a275);
  a290=(a324*a306);
  a296=(a021*a290);
  a320=(a320+a296);
  a261=(a261+a320);
  a320=(a029*a300);
  a296=(a031*a306);
  a320=(a320+a296);
  a320=(a277*a320);
  a296=(2.*a276);
  a321=(a296*a290);
  a310=(a028*a321);
  a320=(a320+a310);
  a261=(a261+a320);
  a320=(a033*a300);
  a310=(a036*a300);
  a310=(a275*a310);
  a328=(a035*a306);
  a310=(a310+a328);
  a320=(a320+a310);
  a310=(a039*a300);
  a328=(a042*a300);
  a328=(a275*a328);
  a289=(a041*a306);
  a328=(a328+a289);
  a310=(a310+a328);
  a310=(a276*a310);
  a290=(a038*a290);
  a310=(a310+a290);
  a320=(a320+a310);
  a310=(a045*a300);
  a306=(a047*a306);
  a310=(a310+a306);
  a310=(a277*a310);
  a321=(a044*a321);
  a310=(a310+a321);
  a320=(a320+a310);
  a261=(a261-a320);
  a261=(a261/a278);
  a310=(a000/a278);
  a316=(a051*a316);
  a320=(a274*a320);
  a316=(a316+a320);
  a316=(a049*a316);
  a316=(a310*a316);
  a261=(a261+a316);
  a316=(a273*a261);
  a320=(a270*a315);
  a320=(a000*a320);
  a316=(a316+a320);
  a321=(a088*a316);
  a306=(a282*a261);
  a290=(a264*a315);
  a290=(a000*a290);
  a306=(a306+a290);
  a328=(a140*a306);
  a321=(a321+a328);
  a328=(a268*a261);
  a328=(a152*a328);
  a321=(a321-a328);
  a328=(a217*a303);
  a321=(a321+a328);
  a328=(a246*a312);
  a321=(a321+a328);
  a321=(a321+a301);
  a301=(a057*a311);
  a295=(a295+a301);
  a321=(a321+a295);
  a295=(a186*a330);
  a305=(a305+a295);
  a321=(a321+a305);
  a321=(a321+a291);
  a321=(-a321);
  if (res[1]!=0) res[1][6]=a321;
  a321=8.6602540378443871e-01;
  a321=(a321*a002);
  a291=(a154*a261);
  a305=(a321+a291);
  a305=(a088*a305);
  a295=(a271*a261);
  a300=(a000*a300);
  a295=(a295+a300);
  a295=(a140*a295);
  a305=(a305-a295);
  a306=(a152*a306);
  a305=(a305+a306);
  a303=(a253*a303);
  a305=(a305+a303);
  a305=(a305+a327);
  a327=(a209*a297);
  a305=(a305+a327);
  a327=(a285+a335);
  a327=(a089*a327);
  a311=(a198*a311);
  a327=(a327+a311);
  a305=(a305+a327);
  a305=(a305+a190);
  a190=(a206*a322);
  a216=(a216+a190);
  a305=(a305+a216);
  a305=(-a305);
  if (res[1]!=0) res[1][7]=a305;
  a305=-8.6602540378443871e-01;
  a305=(a305*a002);
  a291=(a305+a291);
  a291=(a140*a291);
  a261=(a269*a261);
  a261=(a261+a300);
  a261=(a088*a261);
  a291=(a291-a261);
  a316=(a152*a316);
  a291=(a291+a316);
  a291=(a291+a314);
  a312=(a259*a312);
  a291=(a291+a312);
  a297=(a262*a297);
  a291=(a291+a297);
  a291=(a291+a333);
  a335=(a201+a335);
  a335=(a188*a335);
  a330=(a197*a330);
  a335=(a335+a330);
  a291=(a291+a335);
  a322=(a210*a322);
  a292=(a292+a322);
  a291=(a291+a292);
  a291=(-a291);
  if (res[1]!=0) res[1][8]=a291;
  a291=(a189*a002);
  a292=(a001*a291);
  a322=(a016*a291);
  a335=(a020*a322);
  a330=(a018*a291);
  a333=(a013*a330);
  a297=(a017*a333);
  a335=(a335+a297);
  a292=(a292+a335);
  a335=(a022*a291);
  a297=(a025*a291);
  a312=(a020*a297);
  a314=(a026*a333);
  a312=(a312+a314);
  a335=(a335+a312);
  a312=(a027*a335);
  a314=(a179*a333);
  a316=(a023*a314);
  a312=(a312+a316);
  a292=(a292+a312);
  a312=(a029*a291);
  a316=(a031*a333);
  a312=(a312+a316);
  a316=(a032*a312);
  a261=(a180*a314);
  a300=(a030*a261);
  a316=(a316+a300);
  a292=(a292+a316);
  a316=(a033*a291);
  a300=(a036*a291);
  a216=(a020*a300);
  a190=(a037*a333);
  a216=(a216+a190);
  a316=(a316+a216);
  a216=(a039*a291);
  a190=(a042*a291);
  a327=(a020*a190);
  a311=(a043*a333);
  a327=(a327+a311);
  a216=(a216+a327);
  a327=(a027*a216);
  a311=(a040*a314);
  a327=(a327+a311);
  a316=(a316+a327);
  a327=(a045*a291);
  a311=(a047*a333);
  a327=(a327+a311);
  a311=(a032*a327);
  a303=(a046*a261);
  a311=(a311+a303);
  a316=(a316+a311);
  a311=(a292-a316);
  a311=(a311/a053);
  a303=(a034*a330);
  a306=(a019*a316);
  a303=(a303+a306);
  a306=(a049*a303);
  a295=(a167*a306);
  a311=(a311+a295);
  a295=(a054*a311);
  a301=(a295-a201);
  a301=(a089*a301);
  a328=(a052*a292);
  a289=(a014*a303);
  a328=(a328-a289);
  a328=(a316+a328);
  a328=(a018*a328);
  a289=(a054*a328);
  a331=(a299*a303);
  a331=(a056*a331);
  a239=(a007*a331);
  a239=(a302-a239);
  a055=(a289-a239);
  a215=(a070*a055);
  a336=(a072*a328);
  a337=(a004*a002);
  a279=(a060*a337);
  a336=(a336+a279);
  a178=(a011*a331);
  a258=(a336-a178);
  a323=(a075*a258);
  a318=(a066*a074);
  a323=(a323+a318);
  a318=(a008*a328);
  a214=(a060*a291);
  a318=(a318+a214);
  a313=(a067*a318);
  a323=(a323-a313);
  a055=(a077*a055);
  a323=(a323+a055);
  a055=(a064*a323);
  a215=(a215+a055);
  a055=(a081*a328);
  a055=(a055+a298);
  a298=(a004*a331);
  a313=(a055-a298);
  a287=(a085*a313);
  a336=(a336+a178);
  a178=(a067*a336);
  a309=(a066*a005);
  a338=(a012*a328);
  a339=(a075*a338);
  a309=(a309-a339);
  a178=(a178+a309);
  a313=(a077*a313);
  a178=(a178+a313);
  a313=(a084*a178);
  a309=(a083*a313);
  a287=(a287+a309);
  a215=(a215+a287);
  a239=(a239+a289);
  a289=(a067*a239);
  a055=(a055+a298);
  a298=(a075*a055);
  a287=(a066*a082);
  a298=(a298+a287);
  a289=(a289+a298);
  a328=(a009*a328);
  a328=(a328+a214);
  a214=(a077*a328);
  a289=(a289-a214);
  a214=(a087*a289);
  a298=(a086*a214);
  a328=(a080*a328);
  a298=(a298-a328);
  a215=(a215+a298);
  a298=(a059*a215);
  a328=(a123*a127);
  a287=(a121*a328);
  a309=(a317*a092);
  a339=(a130*a309);
  a287=(a287+a339);
  a339=(a319*a129);
  a283=(a132*a339);
  a287=(a287+a283);
  a283=(a090*a287);
  a298=(a298+a283);
  a139=(a139*a002);
  a283=(a138*a311);
  a288=(a136*a178);
  a215=(a135*a215);
  a287=(a059*a287);
  a215=(a215+a287);
  a287=(a002*a215);
  a340=(a134*a287);
  a341=(a002*a298);
  a342=(a018*a341);
  a340=(a340+a342);
  a342=(a071*a340);
  a288=(a288+a342);
  a342=(a048*a288);
  a283=(a283+a342);
  a342=(a147*a311);
  a343=(a146*a289);
  a258=(a070*a258);
  a344=(a074*a323);
  a258=(a258+a344);
  a344=(a005*a313);
  a338=(a085*a338);
  a344=(a344-a338);
  a258=(a258+a344);
  a055=(a080*a055);
  a344=(a082*a214);
  a055=(a055+a344);
  a258=(a258+a055);
  a055=(a135*a258);
  a344=(a127*a328);
  a338=(a092*a309);
  a344=(a344+a338);
  a338=(a129*a339);
  a344=(a344+a338);
  a338=(a059*a344);
  a055=(a055+a338);
  a338=(a002*a055);
  a345=(a134*a338);
  a258=(a059*a258);
  a344=(a090*a344);
  a258=(a258+a344);
  a344=(a002*a258);
  a346=(a018*a344);
  a345=(a345+a346);
  a346=(a061*a345);
  a343=(a343+a346);
  a346=(a048*a343);
  a342=(a342+a346);
  a283=(a283+a342);
  a342=(a007*a283);
  a342=(a139+a342);
  a298=(a298-a342);
  a342=(a146*a323);
  a346=(a070*a345);
  a342=(a342+a346);
  a346=(a148*a342);
  a298=(a298+a346);
  a346=(a150*a311);
  a347=(a136*a323);
  a348=(a070*a340);
  a347=(a347+a348);
  a348=(a048*a347);
  a346=(a346+a348);
  a348=(a159*a311);
  a349=(a158*a289);
  a350=(a065*a323);
  a318=(a070*a318);
  a350=(a350-a318);
  a336=(a085*a336);
  a313=(a073*a313);
  a336=(a336+a313);
  a350=(a350+a336);
  a239=(a080*a239);
  a214=(a063*a214);
  a239=(a239+a214);
  a350=(a350+a239);
  a239=(a135*a350);
  a214=(a122*a328);
  a309=(a126*a309);
  a214=(a214+a309);
  a339=(a120*a339);
  a214=(a214+a339);
  a339=(a059*a214);
  a239=(a239+a339);
  a339=(a002*a239);
  a309=(a134*a339);
  a350=(a059*a350);
  a214=(a090*a214);
  a350=(a350+a214);
  a214=(a002*a350);
  a336=(a018*a214);
  a309=(a309+a336);
  a336=(a061*a309);
  a349=(a349+a336);
  a336=(a048*a349);
  a348=(a348+a336);
  a346=(a346+a348);
  a348=(a004*a346);
  a298=(a298-a348);
  a348=(a158*a178);
  a336=(a071*a309);
  a348=(a348+a336);
  a336=(a056*a348);
  a298=(a298+a336);
  a336=(a162*a311);
  a178=(a146*a178);
  a345=(a071*a345);
  a178=(a178+a345);
  a345=(a048*a178);
  a336=(a336+a345);
  a345=(a164*a311);
  a323=(a158*a323);
  a309=(a070*a309);
  a323=(a323+a309);
  a309=(a048*a323);
  a345=(a345+a309);
  a309=(a336+a345);
  a309=(a161*a309);
  a298=(a298+a309);
  a309=(a171*a261);
  a313=(a170*a330);
  a318=(a311/a053);
  a351=(a334*a306);
  a318=(a318+a351);
  a318=(a169*a318);
  a351=(a168*a291);
  a289=(a136*a289);
  a340=(a061*a340);
  a289=(a289+a340);
  a340=(a009*a289);
  a351=(a351+a340);
  a340=(a138*a293);
  a352=(a081*a288);
  a340=(a340+a352);
  a351=(a351-a340);
  a340=(a054*a347);
  a351=(a351-a340);
  a293=(a147*a293);
  a340=(a081*a343);
  a293=(a293+a340);
  a351=(a351-a293);
  a178=(a012*a178);
  a351=(a351+a178);
  a178=(a149*a337);
  a293=(a072*a342);
  a178=(a178+a293);
  a351=(a351-a178);
  a178=(a054*a349);
  a351=(a351-a178);
  a178=(a160*a337);
  a293=(a072*a348);
  a178=(a178+a293);
  a351=(a351-a178);
  a178=(a164*a291);
  a323=(a008*a323);
  a178=(a178+a323);
  a351=(a351+a178);
  a178=(a167*a351);
  a318=(a318+a178);
  a318=(a049*a318);
  a178=(a019*a318);
  a313=(a313+a178);
  a351=(a351/a053);
  a306=(a304*a306);
  a351=(a351+a306);
  a313=(a313-a351);
  a306=(a032*a313);
  a309=(a309+a306);
  a306=(a045*a309);
  a178=(a175*a333);
  a323=(a171*a314);
  a293=(a027*a313);
  a323=(a323+a293);
  a293=(a020*a323);
  a178=(a178+a293);
  a178=(a042*a178);
  a306=(a306+a178);
  a178=(a039*a323);
  a306=(a306+a178);
  a178=(a171*a333);
  a293=(a020*a313);
  a178=(a178+a293);
  a178=(a036*a178);
  a306=(a306+a178);
  a178=(a033*a313);
  a306=(a306+a178);
  a261=(a172*a261);
  a178=(a032*a351);
  a261=(a261+a178);
  a178=(a029*a261);
  a306=(a306+a178);
  a178=(a177*a333);
  a293=(a172*a314);
  a340=(a027*a351);
  a293=(a293+a340);
  a340=(a020*a293);
  a178=(a178+a340);
  a178=(a025*a178);
  a306=(a306+a178);
  a178=(a022*a293);
  a306=(a306+a178);
  a316=(a170*a316);
  a318=(a034*a318);
  a316=(a316+a318);
  a318=(a056*a291);
  a178=(a173*a318);
  a309=(a047*a309);
  a340=(2.*a333);
  a352=(a182*a340);
  a314=(2.*a314);
  a353=(a181*a314);
  a327=(a171*a327);
  a354=(a046*a313);
  a327=(a327+a354);
  a327=(a180*a327);
  a353=(a353+a327);
  a216=(a171*a216);
  a327=(a040*a313);
  a216=(a216+a327);
  a353=(a353+a216);
  a353=(a179*a353);
  a352=(a352+a353);
  a309=(a309+a352);
  a190=(a175*a190);
  a323=(a043*a323);
  a190=(a190+a323);
  a309=(a309+a190);
  a300=(a171*a300);
  a313=(a037*a313);
  a300=(a300+a313);
  a309=(a309+a300);
  a309=(a013*a309);
  a178=(a178+a309);
  a316=(a316+a178);
  a318=(a176*a318);
  a261=(a031*a261);
  a340=(a184*a340);
  a314=(a183*a314);
  a312=(a172*a312);
  a178=(a030*a351);
  a312=(a312+a178);
  a312=(a180*a312);
  a314=(a314+a312);
  a335=(a172*a335);
  a312=(a023*a351);
  a335=(a335+a312);
  a314=(a314+a335);
  a314=(a179*a314);
  a340=(a340+a314);
  a261=(a261+a340);
  a297=(a177*a297);
  a293=(a026*a293);
  a297=(a297+a293);
  a261=(a261+a297);
  a322=(a172*a322);
  a297=(a017*a351);
  a322=(a322+a297);
  a261=(a261+a322);
  a261=(a013*a261);
  a318=(a318+a261);
  a316=(a316+a318);
  a316=(a018*a316);
  a306=(a306+a316);
  a333=(a172*a333);
  a316=(a020*a351);
  a333=(a333+a316);
  a333=(a016*a333);
  a306=(a306+a333);
  a351=(a001*a351);
  a306=(a306+a351);
  a351=(a161*a306);
  a298=(a298+a351);
  a351=(a058*a298);
  a301=(a301+a351);
  a351=(a072*a311);
  a333=(a048*a337);
  a351=(a351+a333);
  a316=(a188*a351);
  a347=(a056*a347);
  a347=(a347+a258);
  a283=(a011*a283);
  a347=(a347-a283);
  a349=(a148*a349);
  a347=(a347+a349);
  a349=(a149*a311);
  a342=(a048*a342);
  a349=(a349+a342);
  a342=(a160*a311);
  a348=(a048*a348);
  a342=(a342+a348);
  a349=(a349+a342);
  a342=(a004*a349);
  a347=(a347-a342);
  a165=(a165*a326);
  a342=(a168*a311);
  a289=(a048*a289);
  a342=(a342+a289);
  a345=(a342+a345);
  a345=(a189*a345);
  a165=(a165+a345);
  a347=(a347+a165);
  a165=(a189*a306);
  a165=(a174+a165);
  a347=(a347+a165);
  a165=(a187*a347);
  a165=(a316+a165);
  a301=(a301+a165);
  a288=(a148*a288);
  a343=(a056*a343);
  a288=(a288+a343);
  a342=(a342+a336);
  a342=(a193*a342);
  a288=(a288+a342);
  a288=(a288+a350);
  a346=(a011*a346);
  a288=(a288-a346);
  a349=(a007*a349);
  a142=(a142+a349);
  a288=(a288-a142);
  a306=(a193*a306);
  a288=(a288+a306);
  a306=(a191*a288);
  a142=(a008*a311);
  a349=(a048*a291);
  a142=(a142+a349);
  a142=(a192*a142);
  a306=(a306-a142);
  a301=(a301+a306);
  a142=(a062*a337);
  a346=(a072*a331);
  a346=(a142-a346);
  a303=(a195*a303);
  a330=(a014*a330);
  a292=(a019*a292);
  a330=(a330+a292);
  a330=(a052*a330);
  a303=(a303+a330);
  a330=(a011*a303);
  a292=(a346+a330);
  a292=(a163*a292);
  a350=(a012*a331);
  a350=(a199*a350);
  a292=(a292+a350);
  a350=(a081*a331);
  a329=(a329-a350);
  a350=(a004*a303);
  a329=(a329-a350);
  a329=(a200*a329);
  a292=(a292+a329);
  a292=(a201*a292);
  a301=(a301+a292);
  a301=(a301/a002);
  if (res[1]!=0) res[1][9]=a301;
  a301=(a081*a311);
  a301=(a301+a294);
  a294=(a089*a301);
  a292=(a202*a298);
  a292=(a294+a292);
  a329=(a204*a347);
  a350=(a012*a311);
  a350=(a188*a350);
  a329=(a329-a350);
  a292=(a292+a329);
  a351=(a192*a351);
  a350=(a207*a288);
  a350=(a351+a350);
  a292=(a292+a350);
  a346=(a346-a330);
  a346=(a199*a346);
  a291=(a062*a291);
  a330=(a008*a331);
  a291=(a291-a330);
  a291=(a163*a291);
  a346=(a346-a291);
  a331=(a054*a331);
  a303=(a007*a303);
  a303=(a196-a303);
  a331=(a331+a303);
  a331=(a200*a331);
  a346=(a346-a331);
  a346=(a201*a346);
  a292=(a292-a346);
  a292=(a292/a002);
  if (res[1]!=0) res[1][10]=a292;
  a292=(a203*a298);
  a311=(a009*a311);
  a311=(a311+a349);
  a311=(a089*a311);
  a292=(a292-a311);
  a301=(a188*a301);
  a311=(a194*a347);
  a311=(a301+a311);
  a311=(a292+a311);
  a349=(a295-a285);
  a349=(a192*a349);
  a346=(a211*a288);
  a349=(a349+a346);
  a311=(a311+a349);
  a311=(a311/a002);
  if (res[1]!=0) res[1][11]=a311;
  a311=(a123*a092);
  a349=(a133*a311);
  a287=(a018*a287);
  a341=(a078*a341);
  a287=(a287+a341);
  a341=(a124*a287);
  a349=(a349+a341);
  a341=(a110*a349);
  a346=(a123*a129);
  a331=(a141*a346);
  a338=(a018*a338);
  a344=(a078*a344);
  a338=(a338+a344);
  a344=(a118*a338);
  a331=(a331+a344);
  a344=(a110*a331);
  a341=(a341+a344);
  a344=(a093*a341);
  a215=(a215-a344);
  a344=(a141*a328);
  a303=(a069*a338);
  a344=(a344+a303);
  a303=(a148*a344);
  a215=(a215+a303);
  a303=(a133*a328);
  a291=(a069*a287);
  a303=(a303+a291);
  a291=(a110*a303);
  a330=(a153*a346);
  a339=(a018*a339);
  a214=(a078*a214);
  a339=(a339+a214);
  a214=(a118*a339);
  a330=(a330+a214);
  a214=(a110*a330);
  a291=(a291+a214);
  a214=(a091*a291);
  a215=(a215-a214);
  a214=(a153*a311);
  a350=(a124*a339);
  a214=(a214+a350);
  a350=(a056*a214);
  a215=(a215+a350);
  a311=(a141*a311);
  a338=(a124*a338);
  a311=(a311+a338);
  a338=(a110*a311);
  a328=(a153*a328);
  a339=(a069*a339);
  a328=(a328+a339);
  a339=(a110*a328);
  a350=(a338+a339);
  a350=(a222*a350);
  a215=(a215+a350);
  a346=(a133*a346);
  a287=(a118*a287);
  a346=(a346+a287);
  a287=(a095*a346);
  a350=(a128*a349);
  a287=(a287-a350);
  a350=(a117*a303);
  a287=(a287-a350);
  a350=(a128*a331);
  a287=(a287-a350);
  a311=(a097*a311);
  a287=(a287+a311);
  a311=(a125*a344);
  a287=(a287-a311);
  a311=(a117*a330);
  a287=(a287-a311);
  a311=(a125*a214);
  a287=(a287-a311);
  a328=(a094*a328);
  a287=(a287+a328);
  a328=(a228*a287);
  a328=(a049*a328);
  a311=(a101*a328);
  a287=(a287/a099);
  a311=(a311-a287);
  a350=(a107*a311);
  a342=(a045*a350);
  a336=(a105*a311);
  a343=(a102*a336);
  a343=(a042*a343);
  a342=(a342+a343);
  a343=(a039*a336);
  a342=(a342+a343);
  a343=(a102*a311);
  a343=(a036*a343);
  a342=(a342+a343);
  a343=(a033*a311);
  a342=(a342+a343);
  a343=(a107*a287);
  a165=(a029*a343);
  a342=(a342+a165);
  a165=(a105*a287);
  a345=(a102*a165);
  a345=(a025*a345);
  a342=(a342+a345);
  a345=(a022*a165);
  a342=(a342+a345);
  a328=(a108*a328);
  a350=(a047*a350);
  a345=(a106*a311);
  a345=(a241*a345);
  a289=(a103*a311);
  a345=(a345+a289);
  a345=(a240*a345);
  a350=(a350+a345);
  a336=(a104*a336);
  a350=(a350+a336);
  a311=(a100*a311);
  a350=(a350+a311);
  a350=(a098*a350);
  a328=(a328+a350);
  a343=(a031*a343);
  a350=(a114*a287);
  a350=(a241*a350);
  a311=(a112*a287);
  a350=(a350+a311);
  a350=(a240*a350);
  a343=(a343+a350);
  a165=(a113*a165);
  a343=(a343+a165);
  a165=(a111*a287);
  a343=(a343+a165);
  a343=(a098*a343);
  a328=(a328+a343);
  a328=(a018*a328);
  a342=(a342+a328);
  a328=(a102*a287);
  a328=(a016*a328);
  a342=(a342+a328);
  a287=(a001*a287);
  a342=(a342+a287);
  a287=(a222*a342);
  a215=(a215+a287);
  a287=(a218*a215);
  a303=(a056*a303);
  a055=(a055+a303);
  a341=(a096*a341);
  a055=(a055-a341);
  a330=(a148*a330);
  a055=(a055+a330);
  a344=(a110*a344);
  a214=(a110*a214);
  a344=(a344+a214);
  a214=(a091*a344);
  a055=(a055-a214);
  a346=(a110*a346);
  a339=(a346+a339);
  a339=(a249*a339);
  a055=(a055+a339);
  a339=(a249*a342);
  a055=(a055+a339);
  a339=(a247*a055);
  a287=(a287+a339);
  a349=(a148*a349);
  a239=(a239+a349);
  a331=(a056*a331);
  a239=(a239+a331);
  a346=(a346+a338);
  a346=(a252*a346);
  a239=(a239+a346);
  a291=(a096*a291);
  a239=(a239-a291);
  a344=(a093*a344);
  a239=(a239-a344);
  a342=(a252*a342);
  a239=(a239+a342);
  a342=(a251*a239);
  a287=(a287+a342);
  a287=(a287/a002);
  if (res[1]!=0) res[1][12]=a287;
  a287=(a254*a215);
  a344=(a256*a055);
  a287=(a287+a344);
  a291=(a257*a239);
  a287=(a287+a291);
  a287=(a287/a002);
  if (res[1]!=0) res[1][13]=a287;
  a287=(a255*a215);
  a291=(a260*a055);
  a291=(a287+a291);
  a346=(a263*a239);
  a291=(a291+a346);
  a291=(a291/a002);
  if (res[1]!=0) res[1][14]=a291;
  a291=(2.*a264);
  a346=(a291*a315);
  a338=(a001*a346);
  a331=(a016*a346);
  a331=(a275*a331);
  a349=(a018*a346);
  a339=(a272*a349);
  a214=(a015*a339);
  a331=(a331+a214);
  a338=(a338+a331);
  a331=(a022*a346);
  a214=(a025*a346);
  a214=(a275*a214);
  a330=(a024*a339);
  a214=(a214+a330);
  a331=(a331+a214);
  a331=(a276*a331);
  a214=(a324*a339);
  a330=(a021*a214);
  a331=(a331+a330);
  a338=(a338+a331);
  a331=(a029*a346);
  a330=(a031*a339);
  a331=(a331+a330);
  a331=(a277*a331);
  a330=(a296*a214);
  a341=(a028*a330);
  a331=(a331+a341);
  a338=(a338+a331);
  a331=(a033*a346);
  a341=(a036*a346);
  a341=(a275*a341);
  a303=(a035*a339);
  a341=(a341+a303);
  a331=(a331+a341);
  a341=(a039*a346);
  a303=(a042*a346);
  a303=(a275*a303);
  a328=(a041*a339);
  a303=(a303+a328);
  a341=(a341+a303);
  a341=(a276*a341);
  a214=(a038*a214);
  a341=(a341+a214);
  a331=(a331+a341);
  a341=(a045*a346);
  a339=(a047*a339);
  a341=(a341+a339);
  a341=(a277*a341);
  a330=(a044*a330);
  a341=(a341+a330);
  a331=(a331+a341);
  a338=(a338-a331);
  a338=(a338/a278);
  a349=(a051*a349);
  a331=(a274*a331);
  a349=(a349+a331);
  a349=(a049*a349);
  a349=(a310*a349);
  a338=(a338+a349);
  a349=(a273*a338);
  a331=(a305+a349);
  a331=(a088*a331);
  a341=(a282*a338);
  a330=(a266*a315);
  a330=(a000*a330);
  a341=(a341+a330);
  a339=(a140*a341);
  a331=(a331+a339);
  a339=(a268*a338);
  a346=(a000*a346);
  a339=(a339+a346);
  a339=(a152*a339);
  a331=(a331-a339);
  a339=(a217*a215);
  a331=(a331+a339);
  a339=(a246*a055);
  a331=(a331+a339);
  a331=(a331+a342);
  a342=(a201+a295);
  a342=(a089*a342);
  a339=(a057*a298);
  a342=(a342+a339);
  a331=(a331+a342);
  a342=(a186*a347);
  a316=(a316+a342);
  a331=(a331+a316);
  a331=(a331+a306);
  a331=(-a331);
  if (res[1]!=0) res[1][15]=a331;
  a331=(a154*a338);
  a331=(a331+a320);
  a320=(a088*a331);
  a306=(a271*a338);
  a306=(a140*a306);
  a320=(a320-a306);
  a341=(a152*a341);
  a320=(a320+a341);
  a215=(a253*a215);
  a320=(a320+a215);
  a320=(a320+a344);
  a344=(a209*a239);
  a320=(a320+a344);
  a298=(a198*a298);
  a294=(a294+a298);
  a320=(a320+a294);
  a320=(a320+a329);
  a329=(a206*a288);
  a351=(a351+a329);
  a320=(a320+a351);
  a320=(-a320);
  if (res[1]!=0) res[1][16]=a320;
  a331=(a140*a331);
  a338=(a269*a338);
  a338=(a338+a346);
  a338=(a088*a338);
  a331=(a331-a338);
  a349=(a321+a349);
  a349=(a152*a349);
  a331=(a331+a349);
  a331=(a331+a287);
  a055=(a259*a055);
  a331=(a331+a055);
  a239=(a262*a239);
  a331=(a331+a239);
  a331=(a331+a292);
  a347=(a197*a347);
  a301=(a301+a347);
  a331=(a331+a301);
  a295=(a285+a295);
  a295=(a192*a295);
  a288=(a210*a288);
  a295=(a295+a288);
  a331=(a331+a295);
  a331=(-a331);
  if (res[1]!=0) res[1][17]=a331;
  a331=(a161*a002);
  a295=(a001*a331);
  a288=(a016*a331);
  a301=(a020*a288);
  a347=(a018*a331);
  a292=(a013*a347);
  a239=(a017*a292);
  a301=(a301+a239);
  a295=(a295+a301);
  a301=(a022*a331);
  a239=(a025*a331);
  a055=(a020*a239);
  a287=(a026*a292);
  a055=(a055+a287);
  a301=(a301+a055);
  a055=(a027*a301);
  a287=(a179*a292);
  a349=(a023*a287);
  a055=(a055+a349);
  a295=(a295+a055);
  a055=(a029*a331);
  a349=(a031*a292);
  a055=(a055+a349);
  a349=(a032*a055);
  a338=(a180*a287);
  a346=(a030*a338);
  a349=(a349+a346);
  a295=(a295+a349);
  a349=(a033*a331);
  a346=(a036*a331);
  a320=(a020*a346);
  a351=(a037*a292);
  a320=(a320+a351);
  a349=(a349+a320);
  a320=(a039*a331);
  a351=(a042*a331);
  a329=(a020*a351);
  a294=(a043*a292);
  a329=(a329+a294);
  a320=(a320+a329);
  a329=(a027*a320);
  a294=(a040*a287);
  a329=(a329+a294);
  a349=(a349+a329);
  a329=(a045*a331);
  a294=(a047*a292);
  a329=(a329+a294);
  a294=(a032*a329);
  a298=(a046*a338);
  a294=(a294+a298);
  a349=(a349+a294);
  a294=(a295-a349);
  a294=(a294/a053);
  a298=(a034*a347);
  a344=(a019*a349);
  a298=(a298+a344);
  a344=(a049*a298);
  a215=(a167*a344);
  a294=(a294+a215);
  a215=(a054*a294);
  a215=(a215+a333);
  a333=(a089*a215);
  a341=(a052*a295);
  a306=(a014*a298);
  a341=(a341-a306);
  a341=(a349+a341);
  a341=(a018*a341);
  a306=(a054*a341);
  a306=(a306+a279);
  a299=(a299*a298);
  a299=(a056*a299);
  a279=(a007*a299);
  a316=(a306+a279);
  a342=(a070*a316);
  a339=(a011*a299);
  a302=(a302-a339);
  a339=(a072*a341);
  a214=(a302+a339);
  a303=(a075*a214);
  a328=(a008*a341);
  a060=(a060*a331);
  a328=(a328+a060);
  a343=(a067*a328);
  a303=(a303-a343);
  a316=(a077*a316);
  a343=(a066*a064);
  a316=(a316+a343);
  a303=(a303+a316);
  a316=(a064*a303);
  a342=(a342+a316);
  a316=(a081*a341);
  a316=(a316+a308);
  a308=(a004*a299);
  a343=(a316-a308);
  a165=(a085*a343);
  a339=(a339-a302);
  a302=(a067*a339);
  a350=(a012*a341);
  a350=(a350+a060);
  a060=(a075*a350);
  a302=(a302-a060);
  a343=(a077*a343);
  a060=(a066*a083);
  a343=(a343+a060);
  a302=(a302+a343);
  a343=(a084*a302);
  a060=(a083*a343);
  a165=(a165+a060);
  a342=(a342+a165);
  a306=(a306-a279);
  a067=(a067*a306);
  a316=(a316+a308);
  a075=(a075*a316);
  a067=(a067+a075);
  a075=(a066*a086);
  a341=(a009*a341);
  a077=(a077*a341);
  a075=(a075-a077);
  a067=(a067+a075);
  a075=(a087*a067);
  a077=(a086*a075);
  a341=(a080*a341);
  a077=(a077-a341);
  a342=(a342+a077);
  a077=(a059*a342);
  a341=(a123*a121);
  a308=(a121*a341);
  a317=(a317*a130);
  a279=(a130*a317);
  a308=(a308+a279);
  a319=(a319*a132);
  a279=(a132*a319);
  a308=(a308+a279);
  a279=(a090*a308);
  a077=(a077+a279);
  a279=(a138*a294);
  a165=(a136*a302);
  a342=(a135*a342);
  a308=(a059*a308);
  a342=(a342+a308);
  a308=(a002*a342);
  a060=(a134*a308);
  a311=(a002*a077);
  a336=(a018*a311);
  a060=(a060+a336);
  a336=(a071*a060);
  a165=(a165+a336);
  a336=(a048*a165);
  a279=(a279+a336);
  a336=(a147*a294);
  a345=(a146*a067);
  a214=(a070*a214);
  a289=(a074*a303);
  a214=(a214+a289);
  a289=(a005*a343);
  a350=(a085*a350);
  a289=(a289-a350);
  a214=(a214+a289);
  a316=(a080*a316);
  a289=(a082*a075);
  a316=(a316+a289);
  a214=(a214+a316);
  a316=(a135*a214);
  a289=(a127*a341);
  a350=(a092*a317);
  a289=(a289+a350);
  a350=(a129*a319);
  a289=(a289+a350);
  a350=(a059*a289);
  a316=(a316+a350);
  a350=(a002*a316);
  a348=(a134*a350);
  a214=(a059*a214);
  a289=(a090*a289);
  a214=(a214+a289);
  a289=(a002*a214);
  a283=(a018*a289);
  a348=(a348+a283);
  a283=(a061*a348);
  a345=(a345+a283);
  a283=(a048*a345);
  a336=(a336+a283);
  a279=(a279+a336);
  a336=(a007*a279);
  a077=(a077-a336);
  a336=(a146*a303);
  a283=(a070*a348);
  a336=(a336+a283);
  a283=(a148*a336);
  a077=(a077+a283);
  a283=(a150*a294);
  a258=(a136*a303);
  a318=(a070*a060);
  a258=(a258+a318);
  a318=(a048*a258);
  a283=(a283+a318);
  a318=(a159*a294);
  a261=(a158*a067);
  a322=(a065*a303);
  a328=(a070*a328);
  a322=(a322-a328);
  a085=(a085*a339);
  a343=(a073*a343);
  a085=(a085+a343);
  a322=(a322+a085);
  a080=(a080*a306);
  a075=(a063*a075);
  a080=(a080+a075);
  a322=(a322+a080);
  a080=(a135*a322);
  a075=(a122*a341);
  a317=(a126*a317);
  a075=(a075+a317);
  a319=(a120*a319);
  a075=(a075+a319);
  a319=(a059*a075);
  a080=(a080+a319);
  a319=(a002*a080);
  a317=(a134*a319);
  a322=(a059*a322);
  a075=(a090*a075);
  a322=(a322+a075);
  a075=(a002*a322);
  a306=(a018*a075);
  a317=(a317+a306);
  a306=(a061*a317);
  a261=(a261+a306);
  a306=(a048*a261);
  a318=(a318+a306);
  a283=(a283+a318);
  a318=(a004*a283);
  a077=(a077-a318);
  a318=(a158*a302);
  a306=(a071*a317);
  a318=(a318+a306);
  a306=(a056*a318);
  a077=(a077+a306);
  a166=(a166*a326);
  a306=(a162*a294);
  a302=(a146*a302);
  a348=(a071*a348);
  a302=(a302+a348);
  a348=(a048*a302);
  a306=(a306+a348);
  a348=(a164*a294);
  a303=(a158*a303);
  a317=(a070*a317);
  a303=(a303+a317);
  a317=(a048*a303);
  a348=(a348+a317);
  a317=(a306+a348);
  a317=(a161*a317);
  a166=(a166+a317);
  a077=(a077+a166);
  a166=(a171*a338);
  a317=(a170*a347);
  a085=(a294/a053);
  a334=(a334*a344);
  a085=(a085+a334);
  a169=(a169*a085);
  a067=(a136*a067);
  a060=(a061*a060);
  a067=(a067+a060);
  a060=(a009*a067);
  a138=(a138*a307);
  a085=(a081*a165);
  a138=(a138+a085);
  a060=(a060-a138);
  a150=(a150*a337);
  a138=(a054*a258);
  a150=(a150+a138);
  a060=(a060-a150);
  a147=(a147*a307);
  a307=(a081*a345);
  a147=(a147+a307);
  a060=(a060-a147);
  a162=(a162*a331);
  a302=(a012*a302);
  a162=(a162+a302);
  a060=(a060+a162);
  a162=(a072*a336);
  a060=(a060-a162);
  a159=(a159*a337);
  a337=(a054*a261);
  a159=(a159+a337);
  a060=(a060-a159);
  a159=(a072*a318);
  a060=(a060-a159);
  a164=(a164*a331);
  a303=(a008*a303);
  a164=(a164+a303);
  a060=(a060+a164);
  a164=(a167*a060);
  a169=(a169+a164);
  a169=(a049*a169);
  a164=(a019*a169);
  a317=(a317+a164);
  a060=(a060/a053);
  a304=(a304*a344);
  a060=(a060+a304);
  a317=(a317-a060);
  a304=(a032*a317);
  a166=(a166+a304);
  a304=(a045*a166);
  a344=(a175*a292);
  a164=(a171*a287);
  a303=(a027*a317);
  a164=(a164+a303);
  a303=(a020*a164);
  a344=(a344+a303);
  a344=(a042*a344);
  a304=(a304+a344);
  a344=(a039*a164);
  a304=(a304+a344);
  a344=(a171*a292);
  a303=(a020*a317);
  a344=(a344+a303);
  a344=(a036*a344);
  a304=(a304+a344);
  a344=(a033*a317);
  a304=(a304+a344);
  a338=(a172*a338);
  a344=(a032*a060);
  a338=(a338+a344);
  a344=(a029*a338);
  a304=(a304+a344);
  a344=(a177*a292);
  a303=(a172*a287);
  a159=(a027*a060);
  a303=(a303+a159);
  a159=(a020*a303);
  a344=(a344+a159);
  a344=(a025*a344);
  a304=(a304+a344);
  a344=(a022*a303);
  a304=(a304+a344);
  a170=(a170*a349);
  a169=(a034*a169);
  a170=(a170+a169);
  a169=(a056*a331);
  a173=(a173*a169);
  a166=(a047*a166);
  a349=(2.*a292);
  a182=(a182*a349);
  a287=(2.*a287);
  a181=(a181*a287);
  a329=(a171*a329);
  a344=(a046*a317);
  a329=(a329+a344);
  a329=(a180*a329);
  a181=(a181+a329);
  a320=(a171*a320);
  a329=(a040*a317);
  a320=(a320+a329);
  a181=(a181+a320);
  a181=(a179*a181);
  a182=(a182+a181);
  a166=(a166+a182);
  a175=(a175*a351);
  a164=(a043*a164);
  a175=(a175+a164);
  a166=(a166+a175);
  a171=(a171*a346);
  a317=(a037*a317);
  a171=(a171+a317);
  a166=(a166+a171);
  a166=(a013*a166);
  a173=(a173+a166);
  a170=(a170+a173);
  a176=(a176*a169);
  a338=(a031*a338);
  a184=(a184*a349);
  a183=(a183*a287);
  a055=(a172*a055);
  a287=(a030*a060);
  a055=(a055+a287);
  a055=(a180*a055);
  a183=(a183+a055);
  a301=(a172*a301);
  a055=(a023*a060);
  a301=(a301+a055);
  a183=(a183+a301);
  a183=(a179*a183);
  a184=(a184+a183);
  a338=(a338+a184);
  a177=(a177*a239);
  a303=(a026*a303);
  a177=(a177+a303);
  a338=(a338+a177);
  a288=(a172*a288);
  a177=(a017*a060);
  a288=(a288+a177);
  a338=(a338+a288);
  a338=(a013*a338);
  a176=(a176+a338);
  a170=(a170+a176);
  a170=(a018*a170);
  a304=(a304+a170);
  a172=(a172*a292);
  a292=(a020*a060);
  a172=(a172+a292);
  a172=(a016*a172);
  a304=(a304+a172);
  a060=(a001*a060);
  a304=(a304+a060);
  a060=(a161*a304);
  a174=(a174+a060);
  a077=(a077+a174);
  a174=(a058*a077);
  a174=(a333+a174);
  a060=(a072*a294);
  a172=(a060-a285);
  a172=(a188*a172);
  a258=(a056*a258);
  a258=(a258+a214);
  a279=(a011*a279);
  a139=(a139+a279);
  a258=(a258-a139);
  a261=(a148*a261);
  a258=(a258+a261);
  a149=(a149*a294);
  a336=(a048*a336);
  a149=(a149+a336);
  a160=(a160*a294);
  a318=(a048*a318);
  a160=(a160+a318);
  a149=(a149+a160);
  a160=(a004*a149);
  a258=(a258-a160);
  a168=(a168*a294);
  a067=(a048*a067);
  a168=(a168+a067);
  a348=(a168+a348);
  a348=(a189*a348);
  a258=(a258+a348);
  a348=(a189*a304);
  a258=(a258+a348);
  a348=(a187*a258);
  a172=(a172+a348);
  a174=(a174+a172);
  a165=(a148*a165);
  a345=(a056*a345);
  a165=(a165+a345);
  a168=(a168+a306);
  a168=(a193*a168);
  a165=(a165+a168);
  a165=(a165+a322);
  a283=(a011*a283);
  a151=(a151+a283);
  a165=(a165-a151);
  a149=(a007*a149);
  a165=(a165-a149);
  a304=(a193*a304);
  a165=(a165+a304);
  a304=(a191*a165);
  a149=(a008*a294);
  a151=(a048*a331);
  a149=(a149+a151);
  a149=(a192*a149);
  a304=(a304-a149);
  a174=(a174+a304);
  a149=(a081*a299);
  a332=(a332-a149);
  a195=(a195*a298);
  a014=(a014*a347);
  a295=(a019*a295);
  a014=(a014+a295);
  a052=(a052*a014);
  a195=(a195+a052);
  a052=(a004*a195);
  a332=(a332-a052);
  a332=(a200*a332);
  a052=(a072*a299);
  a014=(a011*a195);
  a196=(a196-a014);
  a014=(a052+a196);
  a014=(a163*a014);
  a062=(a062*a331);
  a331=(a012*a299);
  a331=(a062-a331);
  a331=(a199*a331);
  a014=(a014+a331);
  a332=(a332-a014);
  a332=(a201*a332);
  a174=(a174+a332);
  a174=(a174/a002);
  if (res[1]!=0) res[1][18]=a174;
  a174=(a081*a294);
  a174=(a174+a205);
  a205=(a089*a174);
  a332=(a202*a077);
  a332=(a205+a332);
  a014=(a204*a258);
  a331=(a012*a294);
  a331=(a331+a151);
  a331=(a188*a331);
  a014=(a014-a331);
  a332=(a332+a014);
  a331=(a060-a201);
  a331=(a192*a331);
  a151=(a207*a165);
  a331=(a331+a151);
  a332=(a332+a331);
  a196=(a196-a052);
  a196=(a199*a196);
  a052=(a008*a299);
  a062=(a062-a052);
  a062=(a163*a062);
  a196=(a196-a062);
  a299=(a054*a299);
  a142=(a142-a299);
  a195=(a007*a195);
  a142=(a142+a195);
  a142=(a200*a142);
  a196=(a196+a142);
  a196=(a201*a196);
  a332=(a332-a196);
  a332=(a332/a002);
  if (res[1]!=0) res[1][19]=a332;
  a332=(a203*a077);
  a294=(a009*a294);
  a089=(a089*a294);
  a332=(a332-a089);
  a174=(a188*a174);
  a089=(a194*a258);
  a089=(a174+a089);
  a089=(a332+a089);
  a215=(a192*a215);
  a294=(a211*a165);
  a294=(a215+a294);
  a089=(a089+a294);
  a089=(a089/a002);
  if (res[1]!=0) res[1][20]=a089;
  a089=(a123*a130);
  a294=(a133*a089);
  a308=(a018*a308);
  a311=(a078*a311);
  a308=(a308+a311);
  a311=(a124*a308);
  a294=(a294+a311);
  a311=(a110*a294);
  a123=(a123*a132);
  a196=(a141*a123);
  a350=(a018*a350);
  a289=(a078*a289);
  a350=(a350+a289);
  a289=(a118*a350);
  a196=(a196+a289);
  a289=(a110*a196);
  a311=(a311+a289);
  a289=(a093*a311);
  a342=(a342-a289);
  a289=(a141*a341);
  a142=(a069*a350);
  a289=(a289+a142);
  a142=(a148*a289);
  a342=(a342+a142);
  a142=(a133*a341);
  a195=(a069*a308);
  a142=(a142+a195);
  a195=(a110*a142);
  a299=(a153*a123);
  a319=(a018*a319);
  a075=(a078*a075);
  a319=(a319+a075);
  a075=(a118*a319);
  a299=(a299+a075);
  a075=(a110*a299);
  a195=(a195+a075);
  a075=(a091*a195);
  a342=(a342-a075);
  a075=(a153*a089);
  a062=(a124*a319);
  a075=(a075+a062);
  a062=(a056*a075);
  a342=(a342+a062);
  a089=(a141*a089);
  a350=(a124*a350);
  a089=(a089+a350);
  a350=(a110*a089);
  a341=(a153*a341);
  a319=(a069*a319);
  a341=(a341+a319);
  a319=(a110*a341);
  a062=(a350+a319);
  a062=(a222*a062);
  a342=(a342+a062);
  a123=(a133*a123);
  a308=(a118*a308);
  a123=(a123+a308);
  a308=(a095*a123);
  a062=(a128*a294);
  a308=(a308-a062);
  a062=(a117*a142);
  a308=(a308-a062);
  a062=(a128*a196);
  a308=(a308-a062);
  a089=(a097*a089);
  a308=(a308+a089);
  a089=(a125*a289);
  a308=(a308-a089);
  a089=(a117*a299);
  a308=(a308-a089);
  a089=(a125*a075);
  a308=(a308-a089);
  a341=(a094*a341);
  a308=(a308+a341);
  a341=(a228*a308);
  a341=(a049*a341);
  a089=(a101*a341);
  a308=(a308/a099);
  a089=(a089-a308);
  a062=(a107*a089);
  a052=(a045*a062);
  a331=(a105*a089);
  a151=(a102*a331);
  a151=(a042*a151);
  a052=(a052+a151);
  a151=(a039*a331);
  a052=(a052+a151);
  a151=(a102*a089);
  a151=(a036*a151);
  a052=(a052+a151);
  a151=(a033*a089);
  a052=(a052+a151);
  a151=(a107*a308);
  a295=(a029*a151);
  a052=(a052+a295);
  a295=(a105*a308);
  a347=(a102*a295);
  a347=(a025*a347);
  a052=(a052+a347);
  a347=(a022*a295);
  a052=(a052+a347);
  a341=(a108*a341);
  a062=(a047*a062);
  a347=(a106*a089);
  a347=(a241*a347);
  a298=(a103*a089);
  a347=(a347+a298);
  a347=(a240*a347);
  a062=(a062+a347);
  a331=(a104*a331);
  a062=(a062+a331);
  a089=(a100*a089);
  a062=(a062+a089);
  a062=(a098*a062);
  a341=(a341+a062);
  a151=(a031*a151);
  a062=(a114*a308);
  a062=(a241*a062);
  a089=(a112*a308);
  a062=(a062+a089);
  a062=(a240*a062);
  a151=(a151+a062);
  a295=(a113*a295);
  a151=(a151+a295);
  a295=(a111*a308);
  a151=(a151+a295);
  a151=(a098*a151);
  a341=(a341+a151);
  a341=(a018*a341);
  a052=(a052+a341);
  a341=(a102*a308);
  a341=(a016*a341);
  a052=(a052+a341);
  a308=(a001*a308);
  a052=(a052+a308);
  a308=(a222*a052);
  a342=(a342+a308);
  a308=(a218*a342);
  a142=(a056*a142);
  a316=(a316+a142);
  a311=(a096*a311);
  a316=(a316-a311);
  a299=(a148*a299);
  a316=(a316+a299);
  a289=(a110*a289);
  a075=(a110*a075);
  a289=(a289+a075);
  a075=(a091*a289);
  a316=(a316-a075);
  a123=(a110*a123);
  a319=(a123+a319);
  a319=(a249*a319);
  a316=(a316+a319);
  a319=(a249*a052);
  a316=(a316+a319);
  a319=(a247*a316);
  a308=(a308+a319);
  a294=(a148*a294);
  a080=(a080+a294);
  a196=(a056*a196);
  a080=(a080+a196);
  a123=(a123+a350);
  a123=(a252*a123);
  a080=(a080+a123);
  a195=(a096*a195);
  a080=(a080-a195);
  a289=(a093*a289);
  a080=(a080-a289);
  a052=(a252*a052);
  a080=(a080+a052);
  a052=(a251*a080);
  a308=(a308+a052);
  a308=(a308/a002);
  if (res[1]!=0) res[1][21]=a308;
  a308=(a254*a342);
  a289=(a256*a316);
  a308=(a308+a289);
  a195=(a257*a080);
  a308=(a308+a195);
  a308=(a308/a002);
  if (res[1]!=0) res[1][22]=a308;
  a308=(a255*a342);
  a195=(a260*a316);
  a195=(a308+a195);
  a123=(a263*a080);
  a195=(a195+a123);
  a195=(a195/a002);
  if (res[1]!=0) res[1][23]=a195;
  a195=(2.*a270);
  a315=(a195*a315);
  a123=(a001*a315);
  a350=(a016*a315);
  a350=(a275*a350);
  a196=(a018*a315);
  a294=(a272*a196);
  a319=(a015*a294);
  a350=(a350+a319);
  a123=(a123+a350);
  a350=(a022*a315);
  a319=(a025*a315);
  a319=(a275*a319);
  a075=(a024*a294);
  a319=(a319+a075);
  a350=(a350+a319);
  a350=(a276*a350);
  a319=(a324*a294);
  a075=(a021*a319);
  a350=(a350+a075);
  a123=(a123+a350);
  a350=(a029*a315);
  a075=(a031*a294);
  a350=(a350+a075);
  a350=(a277*a350);
  a075=(a296*a319);
  a299=(a028*a075);
  a350=(a350+a299);
  a123=(a123+a350);
  a350=(a033*a315);
  a299=(a036*a315);
  a299=(a275*a299);
  a311=(a035*a294);
  a299=(a299+a311);
  a350=(a350+a299);
  a299=(a039*a315);
  a311=(a042*a315);
  a311=(a275*a311);
  a142=(a041*a294);
  a311=(a311+a142);
  a299=(a299+a311);
  a299=(a276*a299);
  a319=(a038*a319);
  a299=(a299+a319);
  a350=(a350+a299);
  a299=(a045*a315);
  a294=(a047*a294);
  a299=(a299+a294);
  a299=(a277*a299);
  a075=(a044*a075);
  a299=(a299+a075);
  a350=(a350+a299);
  a123=(a123-a350);
  a123=(a123/a278);
  a196=(a051*a196);
  a350=(a274*a350);
  a196=(a196+a350);
  a196=(a049*a196);
  a196=(a310*a196);
  a123=(a123+a196);
  a196=(a273*a123);
  a196=(a196+a330);
  a330=(a088*a196);
  a350=(a282*a123);
  a299=(a321+a350);
  a299=(a140*a299);
  a330=(a330+a299);
  a299=(a268*a123);
  a315=(a000*a315);
  a299=(a299+a315);
  a299=(a152*a299);
  a330=(a330-a299);
  a299=(a217*a342);
  a330=(a330+a299);
  a299=(a246*a316);
  a330=(a330+a299);
  a330=(a330+a052);
  a052=(a057*a077);
  a333=(a333+a052);
  a330=(a330+a333);
  a333=(a285+a060);
  a188=(a188*a333);
  a333=(a186*a258);
  a188=(a188+a333);
  a330=(a330+a188);
  a330=(a330+a304);
  a330=(-a330);
  if (res[1]!=0) res[1][24]=a330;
  a330=(a154*a123);
  a330=(a330+a290);
  a290=(a088*a330);
  a304=(a271*a123);
  a304=(a304+a315);
  a304=(a140*a304);
  a290=(a290-a304);
  a350=(a305+a350);
  a350=(a152*a350);
  a290=(a290+a350);
  a342=(a253*a342);
  a290=(a290+a342);
  a290=(a290+a289);
  a289=(a209*a080);
  a290=(a290+a289);
  a077=(a198*a077);
  a205=(a205+a077);
  a290=(a290+a205);
  a290=(a290+a014);
  a060=(a201+a060);
  a192=(a192*a060);
  a060=(a206*a165);
  a192=(a192+a060);
  a290=(a290+a192);
  a290=(-a290);
  if (res[1]!=0) res[1][25]=a290;
  a330=(a140*a330);
  a123=(a269*a123);
  a123=(a088*a123);
  a330=(a330-a123);
  a196=(a152*a196);
  a330=(a330+a196);
  a330=(a330+a308);
  a316=(a259*a316);
  a330=(a330+a316);
  a080=(a262*a080);
  a330=(a330+a080);
  a330=(a330+a332);
  a258=(a197*a258);
  a174=(a174+a258);
  a330=(a330+a174);
  a165=(a210*a165);
  a215=(a215+a165);
  a330=(a330+a215);
  a330=(-a330);
  if (res[1]!=0) res[1][26]=a330;
  a330=(a068*a065);
  a215=(a064*a330);
  a165=2.3205080756887719e+00;
  a174=(a165*a073);
  a258=(a083*a174);
  a215=(a215+a258);
  a258=2.7846096908265263e+00;
  a332=(a258*a063);
  a080=(a086*a332);
  a215=(a215+a080);
  a080=(a059*a215);
  a316=(a252*a002);
  a308=(a033*a316);
  a196=(a036*a316);
  a123=(a102*a196);
  a290=(a018*a316);
  a192=(a098*a290);
  a060=(a100*a192);
  a123=(a123+a060);
  a308=(a308+a123);
  a123=(a039*a316);
  a060=(a042*a316);
  a014=(a102*a060);
  a205=(a104*a192);
  a014=(a014+a205);
  a123=(a123+a014);
  a014=(a105*a123);
  a205=(a240*a192);
  a077=(a103*a205);
  a014=(a014+a077);
  a308=(a308+a014);
  a014=(a045*a316);
  a077=(a047*a192);
  a014=(a014+a077);
  a077=(a107*a014);
  a289=(a241*a205);
  a342=(a106*a289);
  a077=(a077+a342);
  a308=(a308+a077);
  a077=(a001*a316);
  a342=(a016*a316);
  a350=(a102*a342);
  a304=(a111*a192);
  a350=(a350+a304);
  a077=(a077+a350);
  a350=(a022*a316);
  a304=(a025*a316);
  a315=(a102*a304);
  a188=(a113*a192);
  a315=(a315+a188);
  a350=(a350+a315);
  a315=(a105*a350);
  a188=(a112*a205);
  a315=(a315+a188);
  a077=(a077+a315);
  a315=(a029*a316);
  a188=(a031*a192);
  a315=(a315+a188);
  a188=(a107*a315);
  a333=(a114*a289);
  a188=(a188+a333);
  a077=(a077+a188);
  a188=(a109*a077);
  a333=(a108*a290);
  a052=(a101*a308);
  a333=(a333+a052);
  a052=(a115*a333);
  a188=(a188-a052);
  a188=(a308+a188);
  a188=(a018*a188);
  a052=(a117*a188);
  a299=(a096*a002);
  a075=(a116*a299);
  a052=(a052+a075);
  a294=(2.*a109);
  a319=(a294*a333);
  a319=(a056*a319);
  a311=(a093*a319);
  a142=(a052+a311);
  a341=(a069*a142);
  a151=(a066*a122);
  a295=(a094*a188);
  a062=(a003*a295);
  a151=(a151-a062);
  a062=(a125*a188);
  a089=(a093*a002);
  a331=(a116*a089);
  a062=(a062+a331);
  a347=(a096*a319);
  a298=(a062-a347);
  a149=(a006*a298);
  a151=(a151+a149);
  a142=(a010*a142);
  a151=(a151+a142);
  a142=(a121*a151);
  a341=(a341+a142);
  a142=(a119*a002);
  a149=(a091*a319);
  a149=(a142-a149);
  a283=(a128*a188);
  a322=(a149+a283);
  a168=(a131*a322);
  a062=(a062+a347);
  a347=(a003*a062);
  a306=(a066*a126);
  a347=(a347+a306);
  a306=(a097*a188);
  a345=(a116*a316);
  a306=(a306+a345);
  a172=(a006*a306);
  a347=(a347-a172);
  a322=(a010*a322);
  a347=(a347+a322);
  a322=(a084*a347);
  a172=(a130*a322);
  a168=(a168+a172);
  a341=(a341+a168);
  a052=(a052-a311);
  a311=(a003*a052);
  a168=(a066*a120);
  a311=(a311+a168);
  a283=(a283-a149);
  a149=(a006*a283);
  a311=(a311+a149);
  a188=(a095*a188);
  a188=(a188+a345);
  a345=(a010*a188);
  a311=(a311-a345);
  a345=(a087*a311);
  a149=(a132*a345);
  a188=(a076*a188);
  a149=(a149-a188);
  a341=(a341+a149);
  a149=(a090*a341);
  a080=(a080+a149);
  a149=(a068*a073);
  a188=(a136*a149);
  a215=(a135*a215);
  a341=(a059*a341);
  a215=(a215+a341);
  a341=(a002*a215);
  a168=(a134*a341);
  a172=(a002*a080);
  a348=(a018*a172);
  a168=(a168+a348);
  a348=(a071*a168);
  a188=(a188+a348);
  a348=(a048*a188);
  a067=(a068*a063);
  a160=(a146*a067);
  a318=(a074*a330);
  a336=(a005*a174);
  a318=(a318+a336);
  a336=(a082*a332);
  a318=(a318+a336);
  a336=(a135*a318);
  a298=(a069*a298);
  a261=(a127*a151);
  a298=(a298+a261);
  a261=(a092*a322);
  a306=(a131*a306);
  a261=(a261-a306);
  a298=(a298+a261);
  a283=(a076*a283);
  a261=(a129*a345);
  a283=(a283+a261);
  a298=(a298+a283);
  a283=(a059*a298);
  a336=(a336+a283);
  a283=(a002*a336);
  a261=(a134*a283);
  a318=(a059*a318);
  a298=(a090*a298);
  a318=(a318+a298);
  a298=(a002*a318);
  a306=(a018*a298);
  a261=(a261+a306);
  a306=(a061*a261);
  a160=(a160+a306);
  a306=(a048*a160);
  a348=(a348+a306);
  a306=(a007*a348);
  a080=(a080-a306);
  a306=(a146*a330);
  a139=(a070*a261);
  a306=(a306+a139);
  a139=(a148*a306);
  a080=(a080+a139);
  a139=(a136*a330);
  a279=(a070*a168);
  a139=(a139+a279);
  a279=(a048*a139);
  a214=(a158*a067);
  a292=(a065*a330);
  a174=(a073*a174);
  a292=(a292+a174);
  a332=(a063*a332);
  a292=(a292+a332);
  a332=(a135*a292);
  a174=(a122*a151);
  a295=(a069*a295);
  a174=(a174-a295);
  a062=(a131*a062);
  a322=(a126*a322);
  a062=(a062+a322);
  a174=(a174+a062);
  a052=(a076*a052);
  a345=(a120*a345);
  a052=(a052+a345);
  a174=(a174+a052);
  a052=(a059*a174);
  a332=(a332+a052);
  a052=(a002*a332);
  a345=(a134*a052);
  a292=(a059*a292);
  a174=(a090*a174);
  a292=(a292+a174);
  a174=(a002*a292);
  a062=(a018*a174);
  a345=(a345+a062);
  a062=(a061*a345);
  a214=(a214+a062);
  a062=(a048*a214);
  a279=(a279+a062);
  a062=(a004*a279);
  a080=(a080-a062);
  a062=(a158*a149);
  a322=(a071*a345);
  a062=(a062+a322);
  a322=(a056*a062);
  a080=(a080+a322);
  a149=(a146*a149);
  a261=(a071*a261);
  a149=(a149+a261);
  a261=(a048*a149);
  a330=(a158*a330);
  a345=(a070*a345);
  a330=(a330+a345);
  a345=(a048*a330);
  a322=(a261+a345);
  a322=(a161*a322);
  a080=(a080+a322);
  a067=(a136*a067);
  a168=(a061*a168);
  a067=(a067+a168);
  a168=(a009*a067);
  a322=(a081*a188);
  a168=(a168-a322);
  a322=(a054*a139);
  a168=(a168-a322);
  a322=(a081*a160);
  a168=(a168-a322);
  a149=(a012*a149);
  a168=(a168+a149);
  a149=(a072*a306);
  a168=(a168-a149);
  a149=(a054*a214);
  a168=(a168-a149);
  a149=(a072*a062);
  a168=(a168-a149);
  a330=(a008*a330);
  a168=(a168+a330);
  a330=(a167*a168);
  a330=(a049*a330);
  a149=(a019*a330);
  a168=(a168/a053);
  a149=(a149-a168);
  a322=(a032*a149);
  a295=(a045*a322);
  a170=(a027*a149);
  a176=(a020*a170);
  a176=(a042*a176);
  a295=(a295+a176);
  a176=(a039*a170);
  a295=(a295+a176);
  a176=(a020*a149);
  a176=(a036*a176);
  a295=(a295+a176);
  a176=(a033*a149);
  a295=(a295+a176);
  a176=(a032*a168);
  a338=(a029*a176);
  a295=(a295+a338);
  a338=(a027*a168);
  a288=(a020*a338);
  a288=(a025*a288);
  a295=(a295+a288);
  a288=(a022*a338);
  a295=(a295+a288);
  a330=(a034*a330);
  a322=(a047*a322);
  a288=(a046*a149);
  a288=(a180*a288);
  a177=(a040*a149);
  a288=(a288+a177);
  a288=(a179*a288);
  a322=(a322+a288);
  a170=(a043*a170);
  a322=(a322+a170);
  a149=(a037*a149);
  a322=(a322+a149);
  a322=(a013*a322);
  a330=(a330+a322);
  a176=(a031*a176);
  a322=(a030*a168);
  a322=(a180*a322);
  a149=(a023*a168);
  a322=(a322+a149);
  a322=(a179*a322);
  a176=(a176+a322);
  a338=(a026*a338);
  a176=(a176+a338);
  a338=(a017*a168);
  a176=(a176+a338);
  a176=(a013*a176);
  a330=(a330+a176);
  a330=(a018*a330);
  a295=(a295+a330);
  a330=(a020*a168);
  a330=(a016*a330);
  a295=(a295+a330);
  a168=(a001*a168);
  a295=(a295+a168);
  a168=(a161*a295);
  a080=(a080+a168);
  a168=(a058*a080);
  a139=(a056*a139);
  a139=(a139+a318);
  a348=(a011*a348);
  a139=(a139-a348);
  a214=(a148*a214);
  a139=(a139+a214);
  a306=(a048*a306);
  a062=(a048*a062);
  a306=(a306+a062);
  a062=(a004*a306);
  a139=(a139-a062);
  a067=(a048*a067);
  a345=(a067+a345);
  a345=(a189*a345);
  a139=(a139+a345);
  a345=(a189*a295);
  a139=(a139+a345);
  a345=(a187*a139);
  a168=(a168+a345);
  a188=(a148*a188);
  a160=(a056*a160);
  a188=(a188+a160);
  a067=(a067+a261);
  a067=(a193*a067);
  a188=(a188+a067);
  a188=(a188+a292);
  a279=(a011*a279);
  a188=(a188-a279);
  a306=(a007*a306);
  a188=(a188-a306);
  a295=(a193*a295);
  a188=(a188+a295);
  a295=(a191*a188);
  a168=(a168+a295);
  a168=(a168/a002);
  if (res[1]!=0) res[1][27]=a168;
  a168=(a202*a080);
  a306=(a204*a139);
  a168=(a168+a306);
  a279=(a207*a188);
  a168=(a168+a279);
  a168=(a168/a002);
  if (res[1]!=0) res[1][28]=a168;
  a168=(a203*a080);
  a279=(a194*a139);
  a279=(a168+a279);
  a292=(a211*a188);
  a279=(a279+a292);
  a279=(a279/a002);
  if (res[1]!=0) res[1][29]=a279;
  a279=(a119*a089);
  a292=(a125*a319);
  a292=(a279-a292);
  a067=(a212*a333);
  a261=(a115*a290);
  a160=(a101*a077);
  a261=(a261+a160);
  a261=(a109*a261);
  a067=(a067+a261);
  a261=(a096*a067);
  a160=(a292+a261);
  a160=(a163*a160);
  a345=(a119*a316);
  a062=(a097*a319);
  a345=(a345-a062);
  a345=(a199*a345);
  a160=(a160-a345);
  a213=(a213*a002);
  a345=(a091*a067);
  a345=(a213-a345);
  a062=(a128*a319);
  a345=(a345-a062);
  a345=(a200*a345);
  a160=(a160+a345);
  a160=(a201*a160);
  a077=(a077-a308);
  a077=(a077/a099);
  a333=(a049*a333);
  a345=(a228*a333);
  a077=(a077+a345);
  a345=(a117*a077);
  a062=(a110*a299);
  a345=(a345+a062);
  a214=(a079*a345);
  a348=(a137*a077);
  a318=(a133*a347);
  a341=(a018*a341);
  a172=(a078*a172);
  a341=(a341+a172);
  a172=(a124*a341);
  a318=(a318+a172);
  a172=(a110*a318);
  a348=(a348+a172);
  a172=(a144*a077);
  a330=(a141*a311);
  a283=(a018*a283);
  a298=(a078*a298);
  a283=(a283+a298);
  a298=(a118*a283);
  a330=(a330+a298);
  a298=(a110*a330);
  a172=(a172+a298);
  a348=(a348+a172);
  a172=(a093*a348);
  a215=(a215-a172);
  a172=(a141*a151);
  a298=(a069*a283);
  a172=(a172+a298);
  a298=(a148*a172);
  a215=(a215+a298);
  a221=(a221*a002);
  a298=(a220*a077);
  a176=(a133*a151);
  a338=(a069*a341);
  a176=(a176+a338);
  a338=(a110*a176);
  a298=(a298+a338);
  a338=(a156*a077);
  a322=(a153*a311);
  a052=(a018*a052);
  a174=(a078*a174);
  a052=(a052+a174);
  a174=(a118*a052);
  a322=(a322+a174);
  a174=(a110*a322);
  a338=(a338+a174);
  a298=(a298+a338);
  a338=(a091*a298);
  a338=(a221+a338);
  a215=(a215-a338);
  a338=(a153*a347);
  a174=(a124*a052);
  a338=(a338+a174);
  a174=(a056*a338);
  a215=(a215+a174);
  a174=(a223*a077);
  a347=(a141*a347);
  a283=(a124*a283);
  a347=(a347+a283);
  a283=(a110*a347);
  a174=(a174+a283);
  a283=(a225*a077);
  a151=(a153*a151);
  a052=(a069*a052);
  a151=(a151+a052);
  a052=(a110*a151);
  a283=(a283+a052);
  a052=(a174+a283);
  a052=(a222*a052);
  a215=(a215+a052);
  a052=(a232*a289);
  a290=(a231*a290);
  a149=(a077/a099);
  a170=(a228/a099);
  a288=(a170*a333);
  a149=(a149+a288);
  a149=(a230*a149);
  a288=(a229*a316);
  a311=(a133*a311);
  a341=(a118*a341);
  a311=(a311+a341);
  a341=(a095*a311);
  a288=(a288+a341);
  a341=(a128*a318);
  a288=(a288-a341);
  a341=(a220*a299);
  a177=(a117*a176);
  a341=(a341+a177);
  a288=(a288-a341);
  a341=(a128*a330);
  a288=(a288-a341);
  a341=(a223*a316);
  a347=(a097*a347);
  a341=(a341+a347);
  a288=(a288+a341);
  a341=(a145*a089);
  a347=(a125*a172);
  a341=(a341+a347);
  a288=(a288-a341);
  a341=(a156*a299);
  a347=(a117*a322);
  a341=(a341+a347);
  a288=(a288-a341);
  a341=(a157*a089);
  a347=(a125*a338);
  a341=(a341+a347);
  a288=(a288-a341);
  a151=(a094*a151);
  a288=(a288+a151);
  a151=(a228*a288);
  a149=(a149+a151);
  a149=(a049*a149);
  a151=(a101*a149);
  a290=(a290+a151);
  a288=(a288/a099);
  a151=(a233/a099);
  a333=(a151*a333);
  a288=(a288+a333);
  a290=(a290-a288);
  a333=(a107*a290);
  a052=(a052+a333);
  a333=(a045*a052);
  a341=(a236*a192);
  a347=(a232*a205);
  a177=(a105*a290);
  a347=(a347+a177);
  a177=(a102*a347);
  a341=(a341+a177);
  a341=(a042*a341);
  a333=(a333+a341);
  a341=(a039*a347);
  a333=(a333+a341);
  a341=(a232*a192);
  a177=(a102*a290);
  a341=(a341+a177);
  a341=(a036*a341);
  a333=(a333+a341);
  a341=(a033*a290);
  a333=(a333+a341);
  a289=(a233*a289);
  a341=(a107*a288);
  a289=(a289+a341);
  a341=(a029*a289);
  a333=(a333+a341);
  a341=(a238*a192);
  a177=(a233*a205);
  a303=(a105*a288);
  a177=(a177+a303);
  a303=(a102*a177);
  a341=(a341+a303);
  a341=(a025*a341);
  a333=(a333+a341);
  a341=(a022*a177);
  a333=(a333+a341);
  a308=(a231*a308);
  a149=(a108*a149);
  a308=(a308+a149);
  a149=(a056*a316);
  a341=(a234*a149);
  a052=(a047*a052);
  a303=(2.*a192);
  a239=(a243*a303);
  a205=(2.*a205);
  a184=(a242*a205);
  a014=(a232*a014);
  a183=(a106*a290);
  a014=(a014+a183);
  a014=(a241*a014);
  a184=(a184+a014);
  a123=(a232*a123);
  a014=(a103*a290);
  a123=(a123+a014);
  a184=(a184+a123);
  a184=(a240*a184);
  a239=(a239+a184);
  a052=(a052+a239);
  a060=(a236*a060);
  a347=(a104*a347);
  a060=(a060+a347);
  a052=(a052+a060);
  a196=(a232*a196);
  a290=(a100*a290);
  a196=(a196+a290);
  a052=(a052+a196);
  a052=(a098*a052);
  a341=(a341+a052);
  a308=(a308+a341);
  a149=(a237*a149);
  a289=(a031*a289);
  a303=(a245*a303);
  a205=(a244*a205);
  a315=(a233*a315);
  a341=(a114*a288);
  a315=(a315+a341);
  a315=(a241*a315);
  a205=(a205+a315);
  a350=(a233*a350);
  a315=(a112*a288);
  a350=(a350+a315);
  a205=(a205+a350);
  a205=(a240*a205);
  a303=(a303+a205);
  a289=(a289+a303);
  a304=(a238*a304);
  a177=(a113*a177);
  a304=(a304+a177);
  a289=(a289+a304);
  a342=(a233*a342);
  a304=(a111*a288);
  a342=(a342+a304);
  a289=(a289+a342);
  a289=(a098*a289);
  a149=(a149+a289);
  a308=(a308+a149);
  a308=(a018*a308);
  a333=(a333+a308);
  a192=(a233*a192);
  a308=(a102*a288);
  a192=(a192+a308);
  a192=(a016*a192);
  a333=(a333+a192);
  a288=(a001*a288);
  a333=(a333+a288);
  a288=(a222*a333);
  a215=(a215+a288);
  a288=(a218*a215);
  a288=(a214+a288);
  a160=(a160+a288);
  a288=(a125*a077);
  a192=(a110*a089);
  a288=(a288+a192);
  a308=(a143*a288);
  a176=(a056*a176);
  a336=(a336+a176);
  a348=(a096*a348);
  a336=(a336-a348);
  a322=(a148*a322);
  a336=(a336+a322);
  a248=(a248*a002);
  a322=(a145*a077);
  a172=(a110*a172);
  a322=(a322+a172);
  a172=(a157*a077);
  a338=(a110*a338);
  a172=(a172+a338);
  a322=(a322+a172);
  a172=(a091*a322);
  a172=(a248+a172);
  a336=(a336-a172);
  a172=(a229*a077);
  a311=(a110*a311);
  a172=(a172+a311);
  a283=(a172+a283);
  a283=(a249*a283);
  a336=(a336+a283);
  a283=(a249*a333);
  a336=(a336+a283);
  a283=(a247*a336);
  a283=(a308+a283);
  a160=(a160+a283);
  a318=(a148*a318);
  a332=(a332+a318);
  a330=(a056*a330);
  a332=(a332+a330);
  a250=(a250*a326);
  a172=(a172+a174);
  a172=(a252*a172);
  a250=(a250+a172);
  a332=(a332+a250);
  a298=(a096*a298);
  a332=(a332-a298);
  a322=(a093*a322);
  a332=(a332-a322);
  a235=(a235*a326);
  a333=(a252*a333);
  a333=(a235+a333);
  a332=(a332+a333);
  a333=(a251*a332);
  a322=(a094*a077);
  a322=(a155*a322);
  a333=(a333-a322);
  a160=(a160+a333);
  a160=(a160/a002);
  if (res[1]!=0) res[1][30]=a160;
  a160=(a128*a077);
  a322=(a160-a285);
  a322=(a079*a322);
  a298=(a254*a215);
  a322=(a322+a298);
  a298=(a094*a319);
  a298=(a163*a298);
  a292=(a292-a261);
  a292=(a199*a292);
  a298=(a298+a292);
  a292=(a119*a299);
  a319=(a117*a319);
  a319=(a292-a319);
  a067=(a093*a067);
  a319=(a319+a067);
  a319=(a200*a319);
  a298=(a298+a319);
  a298=(a201*a298);
  a322=(a322-a298);
  a298=(a256*a336);
  a319=(a097*a077);
  a316=(a110*a316);
  a319=(a319+a316);
  a319=(a143*a319);
  a298=(a298-a319);
  a322=(a322+a298);
  a288=(a155*a288);
  a319=(a257*a332);
  a319=(a288+a319);
  a322=(a322+a319);
  a322=(a322/a002);
  if (res[1]!=0) res[1][31]=a322;
  a322=(a255*a215);
  a077=(a095*a077);
  a077=(a077+a316);
  a077=(a079*a077);
  a322=(a322-a077);
  a077=(a160-a201);
  a077=(a143*a077);
  a316=(a260*a336);
  a077=(a077+a316);
  a077=(a322+a077);
  a345=(a155*a345);
  a316=(a263*a332);
  a316=(a345+a316);
  a077=(a077+a316);
  a077=(a077/a002);
  if (res[1]!=0) res[1][32]=a077;
  a077=1.7320508075688774e+00;
  a316=(a077*a002);
  a208=(a208*a316);
  a319=(a001*a208);
  a067=(a016*a208);
  a067=(a275*a067);
  a261=(a018*a208);
  a250=(a272*a261);
  a172=(a015*a250);
  a067=(a067+a172);
  a319=(a319+a067);
  a067=(a022*a208);
  a172=(a025*a208);
  a172=(a275*a172);
  a174=(a024*a250);
  a172=(a172+a174);
  a067=(a067+a172);
  a067=(a276*a067);
  a172=(a324*a250);
  a174=(a021*a172);
  a067=(a067+a174);
  a319=(a319+a067);
  a067=(a029*a208);
  a174=(a031*a250);
  a067=(a067+a174);
  a067=(a277*a067);
  a174=(a296*a172);
  a330=(a028*a174);
  a067=(a067+a330);
  a319=(a319+a067);
  a067=(a033*a208);
  a330=(a036*a208);
  a330=(a275*a330);
  a318=(a035*a250);
  a330=(a330+a318);
  a067=(a067+a330);
  a330=(a039*a208);
  a318=(a042*a208);
  a318=(a275*a318);
  a283=(a041*a250);
  a318=(a318+a283);
  a330=(a330+a318);
  a330=(a276*a330);
  a172=(a038*a172);
  a330=(a330+a172);
  a067=(a067+a330);
  a330=(a045*a208);
  a250=(a047*a250);
  a330=(a330+a250);
  a330=(a277*a330);
  a174=(a044*a174);
  a330=(a330+a174);
  a067=(a067+a330);
  a319=(a319-a067);
  a319=(a319/a278);
  a261=(a051*a261);
  a067=(a274*a067);
  a261=(a261+a067);
  a261=(a049*a261);
  a261=(a310*a261);
  a319=(a319+a261);
  a261=(a273*a319);
  a270=(a270*a316);
  a270=(a000*a270);
  a261=(a261+a270);
  a067=(a088*a261);
  a330=(a282*a319);
  a264=(a264*a316);
  a264=(a000*a264);
  a330=(a330+a264);
  a174=(a140*a330);
  a067=(a067+a174);
  a174=(a268*a319);
  a174=(a152*a174);
  a067=(a067-a174);
  a174=(a217*a215);
  a214=(a214+a174);
  a067=(a067+a214);
  a214=(a246*a336);
  a308=(a308+a214);
  a067=(a067+a308);
  a067=(a067+a333);
  a333=(a057*a080);
  a067=(a067+a333);
  a333=(a186*a139);
  a067=(a067+a333);
  a067=(a067+a295);
  a067=(-a067);
  if (res[1]!=0) res[1][33]=a067;
  a067=(a154*a319);
  a295=(a305+a067);
  a295=(a088*a295);
  a333=(a271*a319);
  a208=(a000*a208);
  a333=(a333+a208);
  a333=(a140*a333);
  a295=(a295-a333);
  a330=(a152*a330);
  a295=(a295+a330);
  a330=(a285+a160);
  a330=(a079*a330);
  a215=(a253*a215);
  a330=(a330+a215);
  a295=(a295+a330);
  a295=(a295+a298);
  a298=(a209*a332);
  a288=(a288+a298);
  a295=(a295+a288);
  a080=(a198*a080);
  a295=(a295+a080);
  a295=(a295+a306);
  a306=(a206*a188);
  a295=(a295+a306);
  a295=(-a295);
  if (res[1]!=0) res[1][34]=a295;
  a067=(a321+a067);
  a067=(a140*a067);
  a319=(a269*a319);
  a319=(a319+a208);
  a319=(a088*a319);
  a067=(a067-a319);
  a261=(a152*a261);
  a067=(a067+a261);
  a067=(a067+a322);
  a160=(a201+a160);
  a160=(a143*a160);
  a336=(a259*a336);
  a160=(a160+a336);
  a067=(a067+a160);
  a332=(a262*a332);
  a345=(a345+a332);
  a067=(a067+a345);
  a067=(a067+a168);
  a139=(a197*a139);
  a067=(a067+a139);
  a188=(a210*a188);
  a067=(a067+a188);
  a067=(-a067);
  if (res[1]!=0) res[1][35]=a067;
  a067=(a068*a074);
  a188=(a064*a067);
  a139=(a165*a005);
  a168=(a083*a139);
  a188=(a188+a168);
  a168=(a258*a082);
  a345=(a086*a168);
  a188=(a188+a345);
  a345=(a059*a188);
  a332=(a249*a002);
  a160=(a033*a332);
  a336=(a036*a332);
  a322=(a102*a336);
  a261=(a018*a332);
  a319=(a098*a261);
  a208=(a100*a319);
  a322=(a322+a208);
  a160=(a160+a322);
  a322=(a039*a332);
  a208=(a042*a332);
  a295=(a102*a208);
  a306=(a104*a319);
  a295=(a295+a306);
  a322=(a322+a295);
  a295=(a105*a322);
  a306=(a240*a319);
  a080=(a103*a306);
  a295=(a295+a080);
  a160=(a160+a295);
  a295=(a045*a332);
  a080=(a047*a319);
  a295=(a295+a080);
  a080=(a107*a295);
  a288=(a241*a306);
  a298=(a106*a288);
  a080=(a080+a298);
  a160=(a160+a080);
  a080=(a001*a332);
  a298=(a016*a332);
  a330=(a102*a298);
  a215=(a111*a319);
  a330=(a330+a215);
  a080=(a080+a330);
  a330=(a022*a332);
  a215=(a025*a332);
  a333=(a102*a215);
  a308=(a113*a319);
  a333=(a333+a308);
  a330=(a330+a333);
  a333=(a105*a330);
  a308=(a112*a306);
  a333=(a333+a308);
  a080=(a080+a333);
  a333=(a029*a332);
  a308=(a031*a319);
  a333=(a333+a308);
  a308=(a107*a333);
  a214=(a114*a288);
  a308=(a308+a214);
  a080=(a080+a308);
  a308=(a109*a080);
  a214=(a108*a261);
  a174=(a101*a160);
  a214=(a214+a174);
  a174=(a115*a214);
  a308=(a308-a174);
  a308=(a160+a308);
  a308=(a018*a308);
  a174=(a117*a308);
  a250=(a294*a214);
  a250=(a056*a250);
  a172=(a093*a250);
  a172=(a142-a172);
  a318=(a174-a172);
  a283=(a069*a318);
  a311=(a125*a308);
  a338=(a091*a002);
  a348=(a116*a338);
  a311=(a311+a348);
  a176=(a096*a250);
  a149=(a311-a176);
  a289=(a006*a149);
  a342=(a066*a127);
  a289=(a289+a342);
  a342=(a094*a308);
  a304=(a116*a332);
  a342=(a342+a304);
  a177=(a003*a342);
  a289=(a289-a177);
  a318=(a010*a318);
  a289=(a289+a318);
  a318=(a121*a289);
  a283=(a283+a318);
  a318=(a128*a308);
  a318=(a318+a075);
  a075=(a091*a250);
  a177=(a318-a075);
  a303=(a131*a177);
  a311=(a311+a176);
  a176=(a003*a311);
  a205=(a066*a092);
  a350=(a097*a308);
  a315=(a006*a350);
  a205=(a205-a315);
  a176=(a176+a205);
  a177=(a010*a177);
  a176=(a176+a177);
  a177=(a084*a176);
  a205=(a130*a177);
  a303=(a303+a205);
  a283=(a283+a303);
  a172=(a172+a174);
  a174=(a003*a172);
  a318=(a318+a075);
  a075=(a006*a318);
  a303=(a066*a129);
  a075=(a075+a303);
  a174=(a174+a075);
  a308=(a095*a308);
  a308=(a308+a304);
  a304=(a010*a308);
  a174=(a174-a304);
  a304=(a087*a174);
  a075=(a132*a304);
  a308=(a076*a308);
  a075=(a075-a308);
  a283=(a283+a075);
  a075=(a090*a283);
  a345=(a345+a075);
  a075=(a068*a005);
  a308=(a136*a075);
  a188=(a135*a188);
  a283=(a059*a283);
  a188=(a188+a283);
  a283=(a002*a188);
  a303=(a134*a283);
  a205=(a002*a345);
  a315=(a018*a205);
  a303=(a303+a315);
  a315=(a071*a303);
  a308=(a308+a315);
  a315=(a048*a308);
  a341=(a068*a082);
  a052=(a146*a341);
  a196=(a074*a067);
  a290=(a005*a139);
  a196=(a196+a290);
  a290=(a082*a168);
  a196=(a196+a290);
  a290=(a135*a196);
  a149=(a069*a149);
  a060=(a127*a289);
  a149=(a149+a060);
  a060=(a092*a177);
  a350=(a131*a350);
  a060=(a060-a350);
  a149=(a149+a060);
  a318=(a076*a318);
  a060=(a129*a304);
  a318=(a318+a060);
  a149=(a149+a318);
  a318=(a059*a149);
  a290=(a290+a318);
  a318=(a002*a290);
  a060=(a134*a318);
  a196=(a059*a196);
  a149=(a090*a149);
  a196=(a196+a149);
  a149=(a002*a196);
  a350=(a018*a149);
  a060=(a060+a350);
  a350=(a061*a060);
  a052=(a052+a350);
  a350=(a048*a052);
  a315=(a315+a350);
  a350=(a007*a315);
  a345=(a345-a350);
  a350=(a146*a067);
  a347=(a070*a060);
  a350=(a350+a347);
  a347=(a148*a350);
  a345=(a345+a347);
  a347=(a136*a067);
  a239=(a070*a303);
  a347=(a347+a239);
  a239=(a048*a347);
  a184=(a158*a341);
  a123=(a065*a067);
  a139=(a073*a139);
  a123=(a123+a139);
  a168=(a063*a168);
  a123=(a123+a168);
  a168=(a135*a123);
  a139=(a122*a289);
  a342=(a069*a342);
  a139=(a139-a342);
  a311=(a131*a311);
  a177=(a126*a177);
  a311=(a311+a177);
  a139=(a139+a311);
  a172=(a076*a172);
  a304=(a120*a304);
  a172=(a172+a304);
  a139=(a139+a172);
  a172=(a059*a139);
  a168=(a168+a172);
  a172=(a002*a168);
  a304=(a134*a172);
  a123=(a059*a123);
  a139=(a090*a139);
  a123=(a123+a139);
  a139=(a002*a123);
  a311=(a018*a139);
  a304=(a304+a311);
  a311=(a061*a304);
  a184=(a184+a311);
  a311=(a048*a184);
  a239=(a239+a311);
  a311=(a004*a239);
  a345=(a345-a311);
  a311=(a158*a075);
  a177=(a071*a304);
  a311=(a311+a177);
  a177=(a056*a311);
  a345=(a345+a177);
  a075=(a146*a075);
  a060=(a071*a060);
  a075=(a075+a060);
  a060=(a048*a075);
  a067=(a158*a067);
  a304=(a070*a304);
  a067=(a067+a304);
  a304=(a048*a067);
  a177=(a060+a304);
  a177=(a161*a177);
  a345=(a345+a177);
  a341=(a136*a341);
  a303=(a061*a303);
  a341=(a341+a303);
  a303=(a009*a341);
  a177=(a081*a308);
  a303=(a303-a177);
  a177=(a054*a347);
  a303=(a303-a177);
  a177=(a081*a052);
  a303=(a303-a177);
  a075=(a012*a075);
  a303=(a303+a075);
  a075=(a072*a350);
  a303=(a303-a075);
  a075=(a054*a184);
  a303=(a303-a075);
  a075=(a072*a311);
  a303=(a303-a075);
  a067=(a008*a067);
  a303=(a303+a067);
  a067=(a167*a303);
  a067=(a049*a067);
  a075=(a019*a067);
  a303=(a303/a053);
  a075=(a075-a303);
  a177=(a032*a075);
  a342=(a045*a177);
  a014=(a027*a075);
  a183=(a020*a014);
  a183=(a042*a183);
  a342=(a342+a183);
  a183=(a039*a014);
  a342=(a342+a183);
  a183=(a020*a075);
  a183=(a036*a183);
  a342=(a342+a183);
  a183=(a033*a075);
  a342=(a342+a183);
  a183=(a032*a303);
  a301=(a029*a183);
  a342=(a342+a301);
  a301=(a027*a303);
  a055=(a020*a301);
  a055=(a025*a055);
  a342=(a342+a055);
  a055=(a022*a301);
  a342=(a342+a055);
  a067=(a034*a067);
  a177=(a047*a177);
  a055=(a046*a075);
  a055=(a180*a055);
  a287=(a040*a075);
  a055=(a055+a287);
  a055=(a179*a055);
  a177=(a177+a055);
  a014=(a043*a014);
  a177=(a177+a014);
  a075=(a037*a075);
  a177=(a177+a075);
  a177=(a013*a177);
  a067=(a067+a177);
  a183=(a031*a183);
  a177=(a030*a303);
  a177=(a180*a177);
  a075=(a023*a303);
  a177=(a177+a075);
  a177=(a179*a177);
  a183=(a183+a177);
  a301=(a026*a301);
  a183=(a183+a301);
  a301=(a017*a303);
  a183=(a183+a301);
  a183=(a013*a183);
  a067=(a067+a183);
  a067=(a018*a067);
  a342=(a342+a067);
  a067=(a020*a303);
  a067=(a016*a067);
  a342=(a342+a067);
  a303=(a001*a303);
  a342=(a342+a303);
  a303=(a161*a342);
  a345=(a345+a303);
  a303=(a058*a345);
  a347=(a056*a347);
  a347=(a347+a196);
  a315=(a011*a315);
  a347=(a347-a315);
  a184=(a148*a184);
  a347=(a347+a184);
  a350=(a048*a350);
  a311=(a048*a311);
  a350=(a350+a311);
  a311=(a004*a350);
  a347=(a347-a311);
  a341=(a048*a341);
  a304=(a341+a304);
  a304=(a189*a304);
  a347=(a347+a304);
  a304=(a189*a342);
  a347=(a347+a304);
  a304=(a187*a347);
  a303=(a303+a304);
  a308=(a148*a308);
  a052=(a056*a052);
  a308=(a308+a052);
  a341=(a341+a060);
  a341=(a193*a341);
  a308=(a308+a341);
  a308=(a308+a123);
  a239=(a011*a239);
  a308=(a308-a239);
  a350=(a007*a350);
  a308=(a308-a350);
  a342=(a193*a342);
  a308=(a308+a342);
  a342=(a191*a308);
  a303=(a303+a342);
  a303=(a303/a002);
  if (res[1]!=0) res[1][36]=a303;
  a303=(a202*a345);
  a350=(a204*a347);
  a303=(a303+a350);
  a239=(a207*a308);
  a303=(a303+a239);
  a303=(a303/a002);
  if (res[1]!=0) res[1][37]=a303;
  a303=(a203*a345);
  a239=(a194*a347);
  a239=(a303+a239);
  a123=(a211*a308);
  a239=(a239+a123);
  a239=(a239/a002);
  if (res[1]!=0) res[1][38]=a239;
  a239=(a119*a338);
  a123=(a125*a250);
  a123=(a239-a123);
  a341=(a212*a214);
  a060=(a115*a261);
  a052=(a101*a080);
  a060=(a060+a052);
  a060=(a109*a060);
  a341=(a341+a060);
  a060=(a096*a341);
  a052=(a123+a060);
  a052=(a163*a052);
  a304=(a097*a250);
  a304=(a199*a304);
  a052=(a052+a304);
  a304=(a128*a250);
  a292=(a292-a304);
  a304=(a091*a341);
  a292=(a292-a304);
  a292=(a200*a292);
  a052=(a052+a292);
  a052=(a201*a052);
  a080=(a080-a160);
  a080=(a080/a099);
  a214=(a049*a214);
  a292=(a228*a214);
  a080=(a080+a292);
  a292=(a117*a080);
  a304=(a292-a201);
  a304=(a079*a304);
  a219=(a219*a002);
  a311=(a137*a080);
  a184=(a133*a176);
  a283=(a018*a283);
  a205=(a078*a205);
  a283=(a283+a205);
  a205=(a124*a283);
  a184=(a184+a205);
  a205=(a110*a184);
  a311=(a311+a205);
  a205=(a144*a080);
  a315=(a141*a174);
  a318=(a018*a318);
  a149=(a078*a149);
  a318=(a318+a149);
  a149=(a118*a318);
  a315=(a315+a149);
  a149=(a110*a315);
  a205=(a205+a149);
  a311=(a311+a205);
  a205=(a093*a311);
  a205=(a219+a205);
  a188=(a188-a205);
  a205=(a141*a289);
  a149=(a069*a318);
  a205=(a205+a149);
  a149=(a148*a205);
  a188=(a188+a149);
  a149=(a220*a080);
  a196=(a133*a289);
  a067=(a069*a283);
  a196=(a196+a067);
  a067=(a110*a196);
  a149=(a149+a067);
  a067=(a156*a080);
  a183=(a153*a174);
  a172=(a018*a172);
  a139=(a078*a139);
  a172=(a172+a139);
  a139=(a118*a172);
  a183=(a183+a139);
  a139=(a110*a183);
  a067=(a067+a139);
  a149=(a149+a067);
  a067=(a091*a149);
  a188=(a188-a067);
  a067=(a153*a176);
  a139=(a124*a172);
  a067=(a067+a139);
  a139=(a056*a067);
  a188=(a188+a139);
  a139=(a223*a080);
  a176=(a141*a176);
  a318=(a124*a318);
  a176=(a176+a318);
  a318=(a110*a176);
  a139=(a139+a318);
  a318=(a225*a080);
  a289=(a153*a289);
  a172=(a069*a172);
  a289=(a289+a172);
  a172=(a110*a289);
  a318=(a318+a172);
  a172=(a139+a318);
  a172=(a222*a172);
  a188=(a188+a172);
  a172=(a232*a288);
  a261=(a231*a261);
  a301=(a080/a099);
  a177=(a170*a214);
  a301=(a301+a177);
  a301=(a230*a301);
  a177=(a229*a332);
  a174=(a133*a174);
  a283=(a118*a283);
  a174=(a174+a283);
  a283=(a095*a174);
  a177=(a177+a283);
  a283=(a137*a299);
  a075=(a128*a184);
  a283=(a283+a075);
  a177=(a177-a283);
  a283=(a117*a196);
  a177=(a177-a283);
  a299=(a144*a299);
  a283=(a128*a315);
  a299=(a299+a283);
  a177=(a177-a299);
  a176=(a097*a176);
  a177=(a177+a176);
  a176=(a145*a338);
  a299=(a125*a205);
  a176=(a176+a299);
  a177=(a177-a176);
  a176=(a117*a183);
  a177=(a177-a176);
  a176=(a157*a338);
  a299=(a125*a067);
  a176=(a176+a299);
  a177=(a177-a176);
  a176=(a225*a332);
  a289=(a094*a289);
  a176=(a176+a289);
  a177=(a177+a176);
  a176=(a228*a177);
  a301=(a301+a176);
  a301=(a049*a301);
  a176=(a101*a301);
  a261=(a261+a176);
  a177=(a177/a099);
  a214=(a151*a214);
  a177=(a177+a214);
  a261=(a261-a177);
  a214=(a107*a261);
  a172=(a172+a214);
  a214=(a045*a172);
  a176=(a236*a319);
  a289=(a232*a306);
  a299=(a105*a261);
  a289=(a289+a299);
  a299=(a102*a289);
  a176=(a176+a299);
  a176=(a042*a176);
  a214=(a214+a176);
  a176=(a039*a289);
  a214=(a214+a176);
  a176=(a232*a319);
  a299=(a102*a261);
  a176=(a176+a299);
  a176=(a036*a176);
  a214=(a214+a176);
  a176=(a033*a261);
  a214=(a214+a176);
  a288=(a233*a288);
  a176=(a107*a177);
  a288=(a288+a176);
  a176=(a029*a288);
  a214=(a214+a176);
  a176=(a238*a319);
  a299=(a233*a306);
  a283=(a105*a177);
  a299=(a299+a283);
  a283=(a102*a299);
  a176=(a176+a283);
  a176=(a025*a176);
  a214=(a214+a176);
  a176=(a022*a299);
  a214=(a214+a176);
  a160=(a231*a160);
  a301=(a108*a301);
  a160=(a160+a301);
  a301=(a056*a332);
  a176=(a234*a301);
  a172=(a047*a172);
  a283=(2.*a319);
  a075=(a243*a283);
  a306=(2.*a306);
  a014=(a242*a306);
  a295=(a232*a295);
  a055=(a106*a261);
  a295=(a295+a055);
  a295=(a241*a295);
  a014=(a014+a295);
  a322=(a232*a322);
  a295=(a103*a261);
  a322=(a322+a295);
  a014=(a014+a322);
  a014=(a240*a014);
  a075=(a075+a014);
  a172=(a172+a075);
  a208=(a236*a208);
  a289=(a104*a289);
  a208=(a208+a289);
  a172=(a172+a208);
  a336=(a232*a336);
  a261=(a100*a261);
  a336=(a336+a261);
  a172=(a172+a336);
  a172=(a098*a172);
  a176=(a176+a172);
  a160=(a160+a176);
  a301=(a237*a301);
  a288=(a031*a288);
  a283=(a245*a283);
  a306=(a244*a306);
  a333=(a233*a333);
  a176=(a114*a177);
  a333=(a333+a176);
  a333=(a241*a333);
  a306=(a306+a333);
  a330=(a233*a330);
  a333=(a112*a177);
  a330=(a330+a333);
  a306=(a306+a330);
  a306=(a240*a306);
  a283=(a283+a306);
  a288=(a288+a283);
  a215=(a238*a215);
  a299=(a113*a299);
  a215=(a215+a299);
  a288=(a288+a215);
  a298=(a233*a298);
  a215=(a111*a177);
  a298=(a298+a215);
  a288=(a288+a298);
  a288=(a098*a288);
  a301=(a301+a288);
  a160=(a160+a301);
  a160=(a018*a160);
  a214=(a214+a160);
  a319=(a233*a319);
  a160=(a102*a177);
  a319=(a319+a160);
  a319=(a016*a319);
  a214=(a214+a319);
  a177=(a001*a177);
  a214=(a214+a177);
  a177=(a222*a214);
  a188=(a188+a177);
  a177=(a218*a188);
  a304=(a304+a177);
  a052=(a052+a304);
  a304=(a125*a080);
  a177=(a110*a338);
  a304=(a304+a177);
  a319=(a143*a304);
  a196=(a056*a196);
  a290=(a290+a196);
  a311=(a096*a311);
  a290=(a290-a311);
  a183=(a148*a183);
  a290=(a290+a183);
  a183=(a145*a080);
  a205=(a110*a205);
  a183=(a183+a205);
  a205=(a157*a080);
  a067=(a110*a067);
  a205=(a205+a067);
  a183=(a183+a205);
  a205=(a091*a183);
  a290=(a290-a205);
  a226=(a226*a326);
  a205=(a229*a080);
  a174=(a110*a174);
  a205=(a205+a174);
  a318=(a205+a318);
  a318=(a249*a318);
  a226=(a226+a318);
  a290=(a290+a226);
  a226=(a249*a214);
  a226=(a235+a226);
  a290=(a290+a226);
  a226=(a247*a290);
  a226=(a319+a226);
  a052=(a052+a226);
  a184=(a148*a184);
  a168=(a168+a184);
  a315=(a056*a315);
  a168=(a168+a315);
  a205=(a205+a139);
  a205=(a252*a205);
  a168=(a168+a205);
  a149=(a096*a149);
  a168=(a168-a149);
  a183=(a093*a183);
  a248=(a248+a183);
  a168=(a168-a248);
  a214=(a252*a214);
  a168=(a168+a214);
  a214=(a251*a168);
  a248=(a094*a080);
  a183=(a110*a332);
  a248=(a248+a183);
  a248=(a155*a248);
  a214=(a214-a248);
  a052=(a052+a214);
  a052=(a052/a002);
  if (res[1]!=0) res[1][39]=a052;
  a052=(a128*a080);
  a052=(a052+a062);
  a062=(a079*a052);
  a248=(a254*a188);
  a248=(a062+a248);
  a123=(a123-a060);
  a123=(a199*a123);
  a332=(a119*a332);
  a060=(a094*a250);
  a332=(a332-a060);
  a332=(a163*a332);
  a123=(a123-a332);
  a250=(a117*a250);
  a341=(a093*a341);
  a341=(a213-a341);
  a250=(a250+a341);
  a250=(a200*a250);
  a123=(a123-a250);
  a123=(a201*a123);
  a248=(a248-a123);
  a123=(a256*a290);
  a250=(a097*a080);
  a250=(a143*a250);
  a123=(a123-a250);
  a248=(a248+a123);
  a304=(a155*a304);
  a250=(a257*a168);
  a250=(a304+a250);
  a248=(a248+a250);
  a248=(a248/a002);
  if (res[1]!=0) res[1][40]=a248;
  a248=(a255*a188);
  a080=(a095*a080);
  a080=(a080+a183);
  a080=(a079*a080);
  a248=(a248-a080);
  a052=(a143*a052);
  a080=(a260*a290);
  a080=(a052+a080);
  a080=(a248+a080);
  a183=(a292-a285);
  a183=(a155*a183);
  a250=(a263*a168);
  a183=(a183+a250);
  a080=(a080+a183);
  a080=(a080/a002);
  if (res[1]!=0) res[1][41]=a080;
  a291=(a291*a316);
  a080=(a001*a291);
  a183=(a016*a291);
  a183=(a275*a183);
  a250=(a018*a291);
  a341=(a272*a250);
  a332=(a015*a341);
  a183=(a183+a332);
  a080=(a080+a183);
  a183=(a022*a291);
  a332=(a025*a291);
  a332=(a275*a332);
  a060=(a024*a341);
  a332=(a332+a060);
  a183=(a183+a332);
  a183=(a276*a183);
  a332=(a324*a341);
  a060=(a021*a332);
  a183=(a183+a060);
  a080=(a080+a183);
  a183=(a029*a291);
  a060=(a031*a341);
  a183=(a183+a060);
  a183=(a277*a183);
  a060=(a296*a332);
  a149=(a028*a060);
  a183=(a183+a149);
  a080=(a080+a183);
  a183=(a033*a291);
  a149=(a036*a291);
  a149=(a275*a149);
  a205=(a035*a341);
  a149=(a149+a205);
  a183=(a183+a149);
  a149=(a039*a291);
  a205=(a042*a291);
  a205=(a275*a205);
  a139=(a041*a341);
  a205=(a205+a139);
  a149=(a149+a205);
  a149=(a276*a149);
  a332=(a038*a332);
  a149=(a149+a332);
  a183=(a183+a149);
  a149=(a045*a291);
  a341=(a047*a341);
  a149=(a149+a341);
  a149=(a277*a149);
  a060=(a044*a060);
  a149=(a149+a060);
  a183=(a183+a149);
  a080=(a080-a183);
  a080=(a080/a278);
  a250=(a051*a250);
  a183=(a274*a183);
  a250=(a250+a183);
  a250=(a049*a250);
  a250=(a310*a250);
  a080=(a080+a250);
  a250=(a273*a080);
  a183=(a321+a250);
  a183=(a088*a183);
  a149=(a282*a080);
  a266=(a266*a316);
  a266=(a000*a266);
  a149=(a149+a266);
  a060=(a140*a149);
  a183=(a183+a060);
  a060=(a268*a080);
  a291=(a000*a291);
  a060=(a060+a291);
  a060=(a152*a060);
  a183=(a183-a060);
  a060=(a201+a292);
  a060=(a079*a060);
  a341=(a217*a188);
  a060=(a060+a341);
  a183=(a183+a060);
  a060=(a246*a290);
  a319=(a319+a060);
  a183=(a183+a319);
  a183=(a183+a214);
  a214=(a057*a345);
  a183=(a183+a214);
  a214=(a186*a347);
  a183=(a183+a214);
  a183=(a183+a342);
  a183=(-a183);
  if (res[1]!=0) res[1][42]=a183;
  a183=(a154*a080);
  a183=(a183+a270);
  a270=(a088*a183);
  a342=(a271*a080);
  a342=(a140*a342);
  a270=(a270-a342);
  a149=(a152*a149);
  a270=(a270+a149);
  a188=(a253*a188);
  a062=(a062+a188);
  a270=(a270+a062);
  a270=(a270+a123);
  a123=(a209*a168);
  a304=(a304+a123);
  a270=(a270+a304);
  a345=(a198*a345);
  a270=(a270+a345);
  a270=(a270+a350);
  a350=(a206*a308);
  a270=(a270+a350);
  a270=(-a270);
  if (res[1]!=0) res[1][43]=a270;
  a183=(a140*a183);
  a080=(a269*a080);
  a080=(a080+a291);
  a080=(a088*a080);
  a183=(a183-a080);
  a250=(a305+a250);
  a250=(a152*a250);
  a183=(a183+a250);
  a183=(a183+a248);
  a290=(a259*a290);
  a052=(a052+a290);
  a183=(a183+a052);
  a292=(a285+a292);
  a292=(a155*a292);
  a168=(a262*a168);
  a292=(a292+a168);
  a183=(a183+a292);
  a183=(a183+a303);
  a347=(a197*a347);
  a183=(a183+a347);
  a308=(a210*a308);
  a183=(a183+a308);
  a183=(-a183);
  if (res[1]!=0) res[1][44]=a183;
  a183=(a068*a064);
  a064=(a064*a183);
  a165=(a165*a083);
  a308=(a083*a165);
  a064=(a064+a308);
  a258=(a258*a086);
  a308=(a086*a258);
  a064=(a064+a308);
  a308=(a059*a064);
  a347=(a222*a002);
  a303=(a033*a347);
  a292=(a036*a347);
  a168=(a102*a292);
  a052=(a018*a347);
  a290=(a098*a052);
  a248=(a100*a290);
  a168=(a168+a248);
  a303=(a303+a168);
  a168=(a039*a347);
  a248=(a042*a347);
  a250=(a102*a248);
  a080=(a104*a290);
  a250=(a250+a080);
  a168=(a168+a250);
  a250=(a105*a168);
  a080=(a240*a290);
  a291=(a103*a080);
  a250=(a250+a291);
  a303=(a303+a250);
  a250=(a045*a347);
  a291=(a047*a290);
  a250=(a250+a291);
  a291=(a107*a250);
  a270=(a241*a080);
  a350=(a106*a270);
  a291=(a291+a350);
  a303=(a303+a291);
  a291=(a001*a347);
  a350=(a016*a347);
  a345=(a102*a350);
  a304=(a111*a290);
  a345=(a345+a304);
  a291=(a291+a345);
  a345=(a022*a347);
  a304=(a025*a347);
  a123=(a102*a304);
  a062=(a113*a290);
  a123=(a123+a062);
  a345=(a345+a123);
  a123=(a105*a345);
  a062=(a112*a080);
  a123=(a123+a062);
  a291=(a291+a123);
  a123=(a029*a347);
  a062=(a031*a290);
  a123=(a123+a062);
  a062=(a107*a123);
  a188=(a114*a270);
  a062=(a062+a188);
  a291=(a291+a062);
  a062=(a109*a291);
  a188=(a108*a052);
  a149=(a101*a303);
  a188=(a188+a149);
  a149=(a115*a188);
  a062=(a062-a149);
  a062=(a303+a062);
  a062=(a018*a062);
  a149=(a117*a062);
  a149=(a149+a348);
  a294=(a294*a188);
  a294=(a056*a294);
  a348=(a093*a294);
  a342=(a149+a348);
  a214=(a069*a342);
  a319=(a096*a294);
  a142=(a142-a319);
  a319=(a125*a062);
  a060=(a142+a319);
  a341=(a006*a060);
  a332=(a094*a062);
  a116=(a116*a347);
  a332=(a332+a116);
  a205=(a003*a332);
  a341=(a341-a205);
  a342=(a010*a342);
  a205=(a066*a121);
  a342=(a342+a205);
  a341=(a341+a342);
  a121=(a121*a341);
  a214=(a214+a121);
  a121=(a128*a062);
  a121=(a121+a331);
  a331=(a091*a294);
  a342=(a121-a331);
  a205=(a131*a342);
  a319=(a319-a142);
  a142=(a003*a319);
  a139=(a097*a062);
  a139=(a139+a116);
  a116=(a006*a139);
  a142=(a142-a116);
  a342=(a010*a342);
  a116=(a066*a130);
  a342=(a342+a116);
  a142=(a142+a342);
  a084=(a084*a142);
  a130=(a130*a084);
  a205=(a205+a130);
  a214=(a214+a205);
  a149=(a149-a348);
  a003=(a003*a149);
  a121=(a121+a331);
  a006=(a006*a121);
  a003=(a003+a006);
  a066=(a066*a132);
  a062=(a095*a062);
  a010=(a010*a062);
  a066=(a066-a010);
  a003=(a003+a066);
  a087=(a087*a003);
  a132=(a132*a087);
  a062=(a076*a062);
  a132=(a132-a062);
  a214=(a214+a132);
  a132=(a090*a214);
  a308=(a308+a132);
  a083=(a068*a083);
  a132=(a136*a083);
  a064=(a135*a064);
  a214=(a059*a214);
  a064=(a064+a214);
  a214=(a002*a064);
  a062=(a134*a214);
  a066=(a002*a308);
  a010=(a018*a066);
  a062=(a062+a010);
  a010=(a071*a062);
  a132=(a132+a010);
  a010=(a048*a132);
  a068=(a068*a086);
  a086=(a146*a068);
  a074=(a074*a183);
  a005=(a005*a165);
  a074=(a074+a005);
  a082=(a082*a258);
  a074=(a074+a082);
  a082=(a135*a074);
  a060=(a069*a060);
  a127=(a127*a341);
  a060=(a060+a127);
  a092=(a092*a084);
  a139=(a131*a139);
  a092=(a092-a139);
  a060=(a060+a092);
  a121=(a076*a121);
  a129=(a129*a087);
  a121=(a121+a129);
  a060=(a060+a121);
  a121=(a059*a060);
  a082=(a082+a121);
  a121=(a002*a082);
  a129=(a134*a121);
  a074=(a059*a074);
  a060=(a090*a060);
  a074=(a074+a060);
  a060=(a002*a074);
  a092=(a018*a060);
  a129=(a129+a092);
  a092=(a061*a129);
  a086=(a086+a092);
  a092=(a048*a086);
  a010=(a010+a092);
  a092=(a007*a010);
  a308=(a308-a092);
  a092=(a146*a183);
  a139=(a070*a129);
  a092=(a092+a139);
  a139=(a148*a092);
  a308=(a308+a139);
  a139=(a136*a183);
  a127=(a070*a062);
  a139=(a139+a127);
  a127=(a048*a139);
  a005=(a158*a068);
  a065=(a065*a183);
  a073=(a073*a165);
  a065=(a065+a073);
  a063=(a063*a258);
  a065=(a065+a063);
  a135=(a135*a065);
  a122=(a122*a341);
  a332=(a069*a332);
  a122=(a122-a332);
  a131=(a131*a319);
  a126=(a126*a084);
  a131=(a131+a126);
  a122=(a122+a131);
  a076=(a076*a149);
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
  a308=(a308-a122);
  a122=(a158*a083);
  a065=(a071*a134);
  a122=(a122+a065);
  a065=(a056*a122);
  a308=(a308+a065);
  a146=(a146*a083);
  a129=(a071*a129);
  a146=(a146+a129);
  a129=(a048*a146);
  a158=(a158*a183);
  a134=(a070*a134);
  a158=(a158+a134);
  a134=(a048*a158);
  a183=(a129+a134);
  a183=(a161*a183);
  a308=(a308+a183);
  a136=(a136*a068);
  a062=(a061*a062);
  a136=(a136+a062);
  a062=(a009*a136);
  a068=(a081*a132);
  a062=(a062-a068);
  a068=(a054*a139);
  a062=(a062-a068);
  a068=(a081*a086);
  a062=(a062-a068);
  a146=(a012*a146);
  a062=(a062+a146);
  a146=(a072*a092);
  a062=(a062-a146);
  a146=(a054*a005);
  a062=(a062-a146);
  a146=(a072*a122);
  a062=(a062-a146);
  a158=(a008*a158);
  a062=(a062+a158);
  a158=(a167*a062);
  a158=(a049*a158);
  a146=(a019*a158);
  a062=(a062/a053);
  a146=(a146-a062);
  a068=(a032*a146);
  a183=(a045*a068);
  a083=(a027*a146);
  a065=(a020*a083);
  a065=(a042*a065);
  a183=(a183+a065);
  a065=(a039*a083);
  a183=(a183+a065);
  a065=(a020*a146);
  a065=(a036*a065);
  a183=(a183+a065);
  a065=(a033*a146);
  a183=(a183+a065);
  a065=(a032*a062);
  a120=(a029*a065);
  a183=(a183+a120);
  a120=(a027*a062);
  a087=(a020*a120);
  a087=(a025*a087);
  a183=(a183+a087);
  a087=(a022*a120);
  a183=(a183+a087);
  a158=(a034*a158);
  a068=(a047*a068);
  a087=(a046*a146);
  a087=(a180*a087);
  a149=(a040*a146);
  a087=(a087+a149);
  a087=(a179*a087);
  a068=(a068+a087);
  a083=(a043*a083);
  a068=(a068+a083);
  a146=(a037*a146);
  a068=(a068+a146);
  a068=(a013*a068);
  a158=(a158+a068);
  a065=(a031*a065);
  a068=(a030*a062);
  a068=(a180*a068);
  a146=(a023*a062);
  a068=(a068+a146);
  a068=(a179*a068);
  a065=(a065+a068);
  a120=(a026*a120);
  a065=(a065+a120);
  a120=(a017*a062);
  a065=(a065+a120);
  a065=(a013*a065);
  a158=(a158+a065);
  a158=(a018*a158);
  a183=(a183+a158);
  a158=(a020*a062);
  a158=(a016*a158);
  a183=(a183+a158);
  a062=(a001*a062);
  a183=(a183+a062);
  a062=(a161*a183);
  a308=(a308+a062);
  a062=(a058*a308);
  a139=(a056*a139);
  a139=(a139+a074);
  a010=(a011*a010);
  a139=(a139-a010);
  a005=(a148*a005);
  a139=(a139+a005);
  a092=(a048*a092);
  a122=(a048*a122);
  a092=(a092+a122);
  a122=(a004*a092);
  a139=(a139-a122);
  a136=(a048*a136);
  a134=(a136+a134);
  a134=(a189*a134);
  a139=(a139+a134);
  a134=(a189*a183);
  a139=(a139+a134);
  a134=(a187*a139);
  a062=(a062+a134);
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
  a183=(a193*a183);
  a132=(a132+a183);
  a183=(a191*a132);
  a062=(a062+a183);
  a062=(a062/a002);
  if (res[1]!=0) res[1][45]=a062;
  a062=(a202*a308);
  a092=(a204*a139);
  a062=(a062+a092);
  a127=(a207*a132);
  a062=(a062+a127);
  a062=(a062/a002);
  if (res[1]!=0) res[1][46]=a062;
  a062=(a203*a308);
  a127=(a194*a139);
  a127=(a062+a127);
  a059=(a211*a132);
  a127=(a127+a059);
  a127=(a127/a002);
  if (res[1]!=0) res[1][47]=a127;
  a127=(a128*a294);
  a279=(a279-a127);
  a212=(a212*a188);
  a115=(a115*a052);
  a127=(a101*a291);
  a115=(a115+a127);
  a109=(a109*a115);
  a212=(a212+a109);
  a109=(a091*a212);
  a279=(a279-a109);
  a279=(a200*a279);
  a109=(a125*a294);
  a115=(a096*a212);
  a213=(a213-a115);
  a115=(a109+a213);
  a115=(a163*a115);
  a119=(a119*a347);
  a127=(a097*a294);
  a127=(a119-a127);
  a127=(a199*a127);
  a115=(a115+a127);
  a279=(a279-a115);
  a279=(a201*a279);
  a291=(a291-a303);
  a291=(a291/a099);
  a188=(a049*a188);
  a115=(a228*a188);
  a291=(a291+a115);
  a115=(a117*a291);
  a115=(a115+a177);
  a177=(a079*a115);
  a127=(a137*a291);
  a059=(a133*a142);
  a214=(a018*a214);
  a066=(a078*a066);
  a214=(a214+a066);
  a066=(a124*a214);
  a059=(a059+a066);
  a066=(a110*a059);
  a127=(a127+a066);
  a066=(a144*a291);
  a136=(a141*a003);
  a121=(a018*a121);
  a060=(a078*a060);
  a121=(a121+a060);
  a060=(a118*a121);
  a136=(a136+a060);
  a060=(a110*a136);
  a066=(a066+a060);
  a127=(a127+a066);
  a066=(a093*a127);
  a064=(a064-a066);
  a066=(a141*a341);
  a060=(a069*a121);
  a066=(a066+a060);
  a060=(a148*a066);
  a064=(a064+a060);
  a060=(a220*a291);
  a129=(a133*a341);
  a086=(a069*a214);
  a129=(a129+a086);
  a086=(a110*a129);
  a060=(a060+a086);
  a086=(a156*a291);
  a134=(a153*a003);
  a076=(a018*a076);
  a078=(a078*a090);
  a076=(a076+a078);
  a078=(a118*a076);
  a134=(a134+a078);
  a078=(a110*a134);
  a086=(a086+a078);
  a060=(a060+a086);
  a086=(a091*a060);
  a064=(a064-a086);
  a086=(a153*a142);
  a078=(a124*a076);
  a086=(a086+a078);
  a078=(a056*a086);
  a064=(a064+a078);
  a227=(a227*a326);
  a326=(a223*a291);
  a141=(a141*a142);
  a121=(a124*a121);
  a141=(a141+a121);
  a121=(a110*a141);
  a326=(a326+a121);
  a121=(a225*a291);
  a153=(a153*a341);
  a076=(a069*a076);
  a153=(a153+a076);
  a076=(a110*a153);
  a121=(a121+a076);
  a076=(a326+a121);
  a076=(a222*a076);
  a227=(a227+a076);
  a064=(a064+a227);
  a227=(a232*a270);
  a052=(a231*a052);
  a076=(a291/a099);
  a170=(a170*a188);
  a076=(a076+a170);
  a230=(a230*a076);
  a133=(a133*a003);
  a214=(a118*a214);
  a133=(a133+a214);
  a214=(a095*a133);
  a137=(a137*a089);
  a003=(a128*a059);
  a137=(a137+a003);
  a214=(a214-a137);
  a220=(a220*a338);
  a137=(a117*a129);
  a220=(a220+a137);
  a214=(a214-a220);
  a144=(a144*a089);
  a089=(a128*a136);
  a144=(a144+a089);
  a214=(a214-a144);
  a223=(a223*a347);
  a141=(a097*a141);
  a223=(a223+a141);
  a214=(a214+a223);
  a223=(a125*a066);
  a214=(a214-a223);
  a156=(a156*a338);
  a338=(a117*a134);
  a156=(a156+a338);
  a214=(a214-a156);
  a156=(a125*a086);
  a214=(a214-a156);
  a225=(a225*a347);
  a153=(a094*a153);
  a225=(a225+a153);
  a214=(a214+a225);
  a225=(a228*a214);
  a230=(a230+a225);
  a230=(a049*a230);
  a225=(a101*a230);
  a052=(a052+a225);
  a214=(a214/a099);
  a151=(a151*a188);
  a214=(a214+a151);
  a052=(a052-a214);
  a151=(a107*a052);
  a227=(a227+a151);
  a151=(a045*a227);
  a188=(a236*a290);
  a225=(a232*a080);
  a153=(a105*a052);
  a225=(a225+a153);
  a153=(a102*a225);
  a188=(a188+a153);
  a188=(a042*a188);
  a151=(a151+a188);
  a188=(a039*a225);
  a151=(a151+a188);
  a188=(a232*a290);
  a153=(a102*a052);
  a188=(a188+a153);
  a188=(a036*a188);
  a151=(a151+a188);
  a188=(a033*a052);
  a151=(a151+a188);
  a270=(a233*a270);
  a188=(a107*a214);
  a270=(a270+a188);
  a188=(a029*a270);
  a151=(a151+a188);
  a188=(a238*a290);
  a153=(a233*a080);
  a156=(a105*a214);
  a153=(a153+a156);
  a156=(a102*a153);
  a188=(a188+a156);
  a188=(a025*a188);
  a151=(a151+a188);
  a188=(a022*a153);
  a151=(a151+a188);
  a231=(a231*a303);
  a230=(a108*a230);
  a231=(a231+a230);
  a230=(a056*a347);
  a234=(a234*a230);
  a227=(a047*a227);
  a303=(2.*a290);
  a243=(a243*a303);
  a080=(2.*a080);
  a242=(a242*a080);
  a250=(a232*a250);
  a188=(a106*a052);
  a250=(a250+a188);
  a250=(a241*a250);
  a242=(a242+a250);
  a168=(a232*a168);
  a250=(a103*a052);
  a168=(a168+a250);
  a242=(a242+a168);
  a242=(a240*a242);
  a243=(a243+a242);
  a227=(a227+a243);
  a236=(a236*a248);
  a225=(a104*a225);
  a236=(a236+a225);
  a227=(a227+a236);
  a232=(a232*a292);
  a052=(a100*a052);
  a232=(a232+a052);
  a227=(a227+a232);
  a227=(a098*a227);
  a234=(a234+a227);
  a231=(a231+a234);
  a237=(a237*a230);
  a270=(a031*a270);
  a245=(a245*a303);
  a244=(a244*a080);
  a123=(a233*a123);
  a080=(a114*a214);
  a123=(a123+a080);
  a123=(a241*a123);
  a244=(a244+a123);
  a345=(a233*a345);
  a123=(a112*a214);
  a345=(a345+a123);
  a244=(a244+a345);
  a244=(a240*a244);
  a245=(a245+a244);
  a270=(a270+a245);
  a238=(a238*a304);
  a153=(a113*a153);
  a238=(a238+a153);
  a270=(a270+a238);
  a350=(a233*a350);
  a238=(a111*a214);
  a350=(a350+a238);
  a270=(a270+a350);
  a270=(a098*a270);
  a237=(a237+a270);
  a231=(a231+a237);
  a231=(a018*a231);
  a151=(a151+a231);
  a233=(a233*a290);
  a290=(a102*a214);
  a233=(a233+a290);
  a233=(a016*a233);
  a151=(a151+a233);
  a214=(a001*a214);
  a151=(a151+a214);
  a214=(a222*a151);
  a235=(a235+a214);
  a064=(a064+a235);
  a235=(a218*a064);
  a235=(a177+a235);
  a279=(a279+a235);
  a235=(a125*a291);
  a214=(a235-a285);
  a214=(a143*a214);
  a129=(a056*a129);
  a082=(a082+a129);
  a127=(a096*a127);
  a219=(a219+a127);
  a082=(a082-a219);
  a134=(a148*a134);
  a082=(a082+a134);
  a145=(a145*a291);
  a066=(a110*a066);
  a145=(a145+a066);
  a157=(a157*a291);
  a086=(a110*a086);
  a157=(a157+a086);
  a145=(a145+a157);
  a157=(a091*a145);
  a082=(a082-a157);
  a229=(a229*a291);
  a133=(a110*a133);
  a229=(a229+a133);
  a121=(a229+a121);
  a121=(a249*a121);
  a082=(a082+a121);
  a121=(a249*a151);
  a082=(a082+a121);
  a121=(a247*a082);
  a214=(a214+a121);
  a279=(a279+a214);
  a059=(a148*a059);
  a135=(a135+a059);
  a136=(a056*a136);
  a135=(a135+a136);
  a229=(a229+a326);
  a229=(a252*a229);
  a135=(a135+a229);
  a060=(a096*a060);
  a221=(a221+a060);
  a135=(a135-a221);
  a145=(a093*a145);
  a135=(a135-a145);
  a151=(a252*a151);
  a135=(a135+a151);
  a151=(a251*a135);
  a145=(a094*a291);
  a347=(a110*a347);
  a145=(a145+a347);
  a145=(a155*a145);
  a151=(a151-a145);
  a279=(a279+a151);
  a279=(a279/a002);
  if (res[1]!=0) res[1][48]=a279;
  a279=(a128*a291);
  a279=(a279+a192);
  a192=(a079*a279);
  a145=(a254*a064);
  a145=(a192+a145);
  a213=(a213-a109);
  a199=(a199*a213);
  a213=(a094*a294);
  a119=(a119-a213);
  a163=(a163*a119);
  a199=(a199-a163);
  a294=(a117*a294);
  a239=(a239-a294);
  a212=(a093*a212);
  a239=(a239+a212);
  a200=(a200*a239);
  a199=(a199+a200);
  a199=(a201*a199);
  a145=(a145-a199);
  a199=(a256*a082);
  a200=(a097*a291);
  a200=(a200+a347);
  a200=(a143*a200);
  a199=(a199-a200);
  a145=(a145+a199);
  a200=(a235-a201);
  a200=(a155*a200);
  a347=(a257*a135);
  a200=(a200+a347);
  a145=(a145+a200);
  a145=(a145/a002);
  if (res[1]!=0) res[1][49]=a145;
  a145=(a255*a064);
  a291=(a095*a291);
  a079=(a079*a291);
  a145=(a145-a079);
  a279=(a143*a279);
  a079=(a260*a082);
  a079=(a279+a079);
  a079=(a145+a079);
  a115=(a155*a115);
  a291=(a263*a135);
  a291=(a115+a291);
  a079=(a079+a291);
  a079=(a079/a002);
  if (res[1]!=0) res[1][50]=a079;
  a195=(a195*a316);
  a316=(a001*a195);
  a079=(a016*a195);
  a079=(a275*a079);
  a291=(a018*a195);
  a272=(a272*a291);
  a015=(a015*a272);
  a079=(a079+a015);
  a316=(a316+a079);
  a079=(a022*a195);
  a015=(a025*a195);
  a015=(a275*a015);
  a024=(a024*a272);
  a015=(a015+a024);
  a079=(a079+a015);
  a079=(a276*a079);
  a324=(a324*a272);
  a021=(a021*a324);
  a079=(a079+a021);
  a316=(a316+a079);
  a079=(a029*a195);
  a021=(a031*a272);
  a079=(a079+a021);
  a079=(a277*a079);
  a296=(a296*a324);
  a028=(a028*a296);
  a079=(a079+a028);
  a316=(a316+a079);
  a079=(a033*a195);
  a028=(a036*a195);
  a028=(a275*a028);
  a035=(a035*a272);
  a028=(a028+a035);
  a079=(a079+a028);
  a028=(a039*a195);
  a035=(a042*a195);
  a275=(a275*a035);
  a041=(a041*a272);
  a275=(a275+a041);
  a028=(a028+a275);
  a276=(a276*a028);
  a038=(a038*a324);
  a276=(a276+a038);
  a079=(a079+a276);
  a276=(a045*a195);
  a272=(a047*a272);
  a276=(a276+a272);
  a277=(a277*a276);
  a044=(a044*a296);
  a277=(a277+a044);
  a079=(a079+a277);
  a316=(a316-a079);
  a316=(a316/a278);
  a051=(a051*a291);
  a274=(a274*a079);
  a051=(a051+a274);
  a051=(a049*a051);
  a310=(a310*a051);
  a316=(a316+a310);
  a273=(a273*a316);
  a273=(a273+a266);
  a266=(a088*a273);
  a282=(a282*a316);
  a305=(a305+a282);
  a305=(a140*a305);
  a266=(a266+a305);
  a268=(a268*a316);
  a000=(a000*a195);
  a268=(a268+a000);
  a268=(a152*a268);
  a266=(a266-a268);
  a268=(a217*a064);
  a177=(a177+a268);
  a266=(a266+a177);
  a285=(a285+a235);
  a143=(a143*a285);
  a285=(a246*a082);
  a143=(a143+a285);
  a266=(a266+a143);
  a266=(a266+a151);
  a151=(a057*a308);
  a266=(a266+a151);
  a151=(a186*a139);
  a266=(a266+a151);
  a266=(a266+a183);
  a266=(-a266);
  if (res[1]!=0) res[1][51]=a266;
  a154=(a154*a316);
  a154=(a154+a264);
  a264=(a088*a154);
  a271=(a271*a316);
  a271=(a271+a000);
  a271=(a140*a271);
  a264=(a264-a271);
  a321=(a321+a282);
  a321=(a152*a321);
  a264=(a264+a321);
  a064=(a253*a064);
  a192=(a192+a064);
  a264=(a264+a192);
  a264=(a264+a199);
  a235=(a201+a235);
  a155=(a155*a235);
  a235=(a209*a135);
  a155=(a155+a235);
  a264=(a264+a155);
  a308=(a198*a308);
  a264=(a264+a308);
  a264=(a264+a092);
  a092=(a206*a132);
  a264=(a264+a092);
  a264=(-a264);
  if (res[1]!=0) res[1][52]=a264;
  a140=(a140*a154);
  a269=(a269*a316);
  a088=(a088*a269);
  a140=(a140-a088);
  a152=(a152*a273);
  a140=(a140+a152);
  a140=(a140+a145);
  a082=(a259*a082);
  a279=(a279+a082);
  a140=(a140+a279);
  a135=(a262*a135);
  a115=(a115+a135);
  a140=(a140+a115);
  a140=(a140+a062);
  a139=(a197*a139);
  a140=(a140+a139);
  a132=(a210*a132);
  a140=(a140+a132);
  a140=(-a140);
  if (res[1]!=0) res[1][53]=a140;
  a140=-9.3301270189221941e-01;
  a140=(a140*a002);
  a140=(a201+a140);
  a132=4.3301270189221935e-01;
  a132=(a132*a002);
  a140=(a140+a132);
  a071=(a071*a140);
  a132=(a056*a071);
  a061=(a061*a140);
  a139=(a048*a061);
  a062=(a004*a139);
  a132=(a132-a062);
  a070=(a070*a140);
  a140=(a048*a070);
  a062=(a161*a140);
  a132=(a132+a062);
  a008=(a008*a070);
  a062=(a054*a061);
  a115=(a072*a071);
  a062=(a062+a115);
  a008=(a008-a062);
  a062=(a167*a008);
  a062=(a049*a062);
  a115=(a019*a062);
  a008=(a008/a053);
  a115=(a115-a008);
  a135=(a032*a115);
  a279=(a045*a135);
  a082=(a027*a115);
  a145=(a020*a082);
  a145=(a042*a145);
  a279=(a279+a145);
  a145=(a039*a082);
  a279=(a279+a145);
  a145=(a020*a115);
  a145=(a036*a145);
  a279=(a279+a145);
  a145=(a033*a115);
  a279=(a279+a145);
  a145=(a032*a008);
  a152=(a029*a145);
  a279=(a279+a152);
  a152=(a027*a008);
  a273=(a020*a152);
  a273=(a025*a273);
  a279=(a279+a273);
  a273=(a022*a152);
  a279=(a279+a273);
  a062=(a034*a062);
  a135=(a047*a135);
  a273=(a046*a115);
  a273=(a180*a273);
  a088=(a040*a115);
  a273=(a273+a088);
  a273=(a179*a273);
  a135=(a135+a273);
  a082=(a043*a082);
  a135=(a135+a082);
  a115=(a037*a115);
  a135=(a135+a115);
  a135=(a013*a135);
  a062=(a062+a135);
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
  a062=(a062+a145);
  a062=(a018*a062);
  a279=(a279+a062);
  a062=(a020*a008);
  a062=(a016*a062);
  a279=(a279+a062);
  a008=(a001*a008);
  a279=(a279+a008);
  a008=(a161*a279);
  a132=(a132+a008);
  a008=(a058*a132);
  a062=(a148*a061);
  a048=(a048*a071);
  a145=(a004*a048);
  a062=(a062-a145);
  a145=(a189*a140);
  a062=(a062+a145);
  a145=(a189*a279);
  a062=(a062+a145);
  a145=(a187*a062);
  a008=(a008+a145);
  a145=(a011*a139);
  a145=(a077-a145);
  a152=(a007*a048);
  a135=(a145-a152);
  a279=(a193*a279);
  a135=(a135+a279);
  a279=(a191*a135);
  a008=(a008+a279);
  a008=(a008/a002);
  if (res[1]!=0) res[1][54]=a008;
  a008=(a202*a132);
  a115=(a204*a062);
  a008=(a008+a115);
  a082=(a207*a135);
  a008=(a008+a082);
  a008=(a008/a002);
  if (res[1]!=0) res[1][55]=a008;
  a008=(a203*a132);
  a082=(a194*a062);
  a082=(a008+a082);
  a273=(a211*a135);
  a082=(a082+a273);
  a082=(a082/a002);
  if (res[1]!=0) res[1][56]=a082;
  a082=-4.3301270189221935e-01;
  a082=(a082*a002);
  a201=(a201+a082);
  a082=-6.6987298107780674e-02;
  a082=(a082*a002);
  a201=(a201+a082);
  a124=(a124*a201);
  a082=(a056*a124);
  a118=(a118*a201);
  a273=(a110*a118);
  a088=(a091*a273);
  a082=(a082-a088);
  a069=(a069*a201);
  a201=(a110*a069);
  a088=(a222*a201);
  a082=(a082+a088);
  a094=(a094*a069);
  a088=(a117*a118);
  a269=(a125*a124);
  a088=(a088+a269);
  a094=(a094-a088);
  a088=(a228*a094);
  a088=(a049*a088);
  a269=(a101*a088);
  a094=(a094/a099);
  a269=(a269-a094);
  a316=(a107*a269);
  a154=(a045*a316);
  a264=(a105*a269);
  a092=(a102*a264);
  a092=(a042*a092);
  a154=(a154+a092);
  a092=(a039*a264);
  a154=(a154+a092);
  a092=(a102*a269);
  a092=(a036*a092);
  a154=(a154+a092);
  a092=(a033*a269);
  a154=(a154+a092);
  a092=(a107*a094);
  a308=(a029*a092);
  a154=(a154+a308);
  a308=(a105*a094);
  a155=(a102*a308);
  a155=(a025*a155);
  a154=(a154+a155);
  a155=(a022*a308);
  a154=(a154+a155);
  a088=(a108*a088);
  a316=(a047*a316);
  a155=(a106*a269);
  a155=(a241*a155);
  a235=(a103*a269);
  a155=(a155+a235);
  a155=(a240*a155);
  a316=(a316+a155);
  a264=(a104*a264);
  a316=(a316+a264);
  a269=(a100*a269);
  a316=(a316+a269);
  a316=(a098*a316);
  a088=(a088+a316);
  a092=(a031*a092);
  a316=(a114*a094);
  a316=(a241*a316);
  a269=(a112*a094);
  a316=(a316+a269);
  a316=(a240*a316);
  a092=(a092+a316);
  a308=(a113*a308);
  a092=(a092+a308);
  a308=(a111*a094);
  a092=(a092+a308);
  a092=(a098*a092);
  a088=(a088+a092);
  a088=(a018*a088);
  a154=(a154+a088);
  a088=(a102*a094);
  a088=(a016*a088);
  a154=(a154+a088);
  a094=(a001*a094);
  a154=(a154+a094);
  a094=(a222*a154);
  a082=(a082+a094);
  a094=(a218*a082);
  a088=(a148*a118);
  a110=(a110*a124);
  a092=(a091*a110);
  a088=(a088-a092);
  a092=(a249*a201);
  a088=(a088+a092);
  a092=(a249*a154);
  a088=(a088+a092);
  a092=(a247*a088);
  a094=(a094+a092);
  a092=(a096*a273);
  a092=(a325-a092);
  a308=(a093*a110);
  a316=(a092-a308);
  a154=(a252*a154);
  a316=(a316+a154);
  a154=(a251*a316);
  a094=(a094+a154);
  a094=(a094/a002);
  if (res[1]!=0) res[1][57]=a094;
  a094=(a254*a082);
  a269=(a256*a088);
  a094=(a094+a269);
  a264=(a257*a316);
  a094=(a094+a264);
  a094=(a094/a002);
  if (res[1]!=0) res[1][58]=a094;
  a094=(a255*a082);
  a264=(a260*a088);
  a264=(a094+a264);
  a155=(a263*a316);
  a264=(a264+a155);
  a264=(a264/a002);
  if (res[1]!=0) res[1][59]=a264;
  a264=(a217*a082);
  a284=(a284+a264);
  a264=(a246*a088);
  a284=(a284+a264);
  a284=(a284+a154);
  a154=(a057*a132);
  a284=(a284+a154);
  a154=(a186*a062);
  a284=(a284+a154);
  a284=(a284+a279);
  a284=(-a284);
  if (res[1]!=0) res[1][60]=a284;
  a082=(a253*a082);
  a286=(a286+a082);
  a286=(a286+a269);
  a269=(a209*a316);
  a286=(a286+a269);
  a132=(a198*a132);
  a286=(a286+a132);
  a286=(a286+a115);
  a115=(a206*a135);
  a286=(a286+a115);
  a286=(-a286);
  if (res[1]!=0) res[1][61]=a286;
  a224=(a224+a094);
  a088=(a259*a088);
  a224=(a224+a088);
  a316=(a262*a316);
  a224=(a224+a316);
  a224=(a224+a008);
  a062=(a197*a062);
  a224=(a224+a062);
  a135=(a210*a135);
  a224=(a224+a135);
  a224=(-a224);
  if (res[1]!=0) res[1][62]=a224;
  a224=(a148*a070);
  a135=(a007*a139);
  a224=(a224-a135);
  a135=(a161*a048);
  a224=(a224+a135);
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
  a062=(a032*a135);
  a008=(a045*a062);
  a316=(a027*a135);
  a088=(a020*a316);
  a088=(a042*a088);
  a008=(a008+a088);
  a088=(a039*a316);
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
  a286=(a020*a094);
  a286=(a025*a286);
  a008=(a008+a286);
  a286=(a022*a094);
  a008=(a008+a286);
  a072=(a034*a072);
  a062=(a047*a062);
  a286=(a046*a135);
  a286=(a180*a286);
  a115=(a040*a135);
  a286=(a286+a115);
  a286=(a179*a286);
  a062=(a062+a286);
  a316=(a043*a316);
  a062=(a062+a316);
  a135=(a037*a135);
  a062=(a062+a135);
  a062=(a013*a062);
  a072=(a072+a062);
  a088=(a031*a088);
  a062=(a030*a012);
  a062=(a180*a062);
  a135=(a023*a012);
  a062=(a062+a135);
  a062=(a179*a062);
  a088=(a088+a062);
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
  a224=(a224+a012);
  a012=(a058*a224);
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
  a012=(a202*a224);
  a007=(a204*a145);
  a012=(a012+a007);
  a088=(a207*a072);
  a012=(a012+a088);
  a012=(a012/a002);
  if (res[1]!=0) res[1][64]=a012;
  a012=(a203*a224);
  a088=(a194*a145);
  a088=(a012+a088);
  a094=(a211*a072);
  a088=(a088+a094);
  a088=(a088/a002);
  if (res[1]!=0) res[1][65]=a088;
  a088=(a148*a069);
  a094=(a093*a273);
  a088=(a088-a094);
  a094=(a222*a110);
  a088=(a088+a094);
  a097=(a097*a124);
  a094=(a128*a118);
  a097=(a097-a094);
  a125=(a125*a069);
  a097=(a097-a125);
  a125=(a228*a097);
  a125=(a049*a125);
  a094=(a101*a125);
  a097=(a097/a099);
  a094=(a094-a097);
  a062=(a107*a094);
  a135=(a045*a062);
  a316=(a105*a094);
  a286=(a102*a316);
  a286=(a042*a286);
  a135=(a135+a286);
  a286=(a039*a316);
  a135=(a135+a286);
  a286=(a102*a094);
  a286=(a036*a286);
  a135=(a135+a286);
  a286=(a033*a094);
  a135=(a135+a286);
  a286=(a107*a097);
  a115=(a029*a286);
  a135=(a135+a115);
  a115=(a105*a097);
  a132=(a102*a115);
  a132=(a025*a132);
  a135=(a135+a132);
  a132=(a022*a115);
  a135=(a135+a132);
  a125=(a108*a125);
  a062=(a047*a062);
  a132=(a106*a094);
  a132=(a241*a132);
  a269=(a103*a094);
  a132=(a132+a269);
  a132=(a240*a132);
  a062=(a062+a132);
  a316=(a104*a316);
  a062=(a062+a316);
  a094=(a100*a094);
  a062=(a062+a094);
  a062=(a098*a062);
  a125=(a125+a062);
  a286=(a031*a286);
  a062=(a114*a097);
  a062=(a241*a062);
  a094=(a112*a097);
  a062=(a062+a094);
  a062=(a240*a062);
  a286=(a286+a062);
  a115=(a113*a115);
  a286=(a286+a115);
  a115=(a111*a097);
  a286=(a286+a115);
  a286=(a098*a286);
  a125=(a125+a286);
  a125=(a018*a125);
  a135=(a135+a125);
  a125=(a102*a097);
  a125=(a016*a125);
  a135=(a135+a125);
  a097=(a001*a097);
  a135=(a135+a097);
  a097=(a222*a135);
  a088=(a088+a097);
  a097=(a218*a088);
  a091=(a091*a201);
  a092=(a092-a091);
  a125=(a249*a135);
  a092=(a092+a125);
  a125=(a247*a092);
  a097=(a097+a125);
  a125=(a056*a118);
  a286=(a252*a110);
  a125=(a125+a286);
  a093=(a093*a201);
  a125=(a125-a093);
  a135=(a252*a135);
  a125=(a125+a135);
  a135=(a251*a125);
  a097=(a097+a135);
  a097=(a097/a002);
  if (res[1]!=0) res[1][66]=a097;
  a097=(a254*a088);
  a093=(a256*a092);
  a097=(a097+a093);
  a286=(a257*a125);
  a097=(a097+a286);
  a097=(a097/a002);
  if (res[1]!=0) res[1][67]=a097;
  a097=(a255*a088);
  a286=(a260*a092);
  a286=(a097+a286);
  a115=(a263*a125);
  a286=(a286+a115);
  a286=(a286/a002);
  if (res[1]!=0) res[1][68]=a286;
  a286=(a217*a088);
  a281=(a281+a286);
  a286=(a246*a092);
  a281=(a281+a286);
  a281=(a281+a135);
  a135=(a057*a224);
  a281=(a281+a135);
  a135=(a186*a145);
  a281=(a281+a135);
  a281=(a281+a008);
  a281=(-a281);
  if (res[1]!=0) res[1][69]=a281;
  a088=(a253*a088);
  a267=(a267+a088);
  a267=(a267+a093);
  a093=(a209*a125);
  a267=(a267+a093);
  a224=(a198*a224);
  a267=(a267+a224);
  a267=(a267+a007);
  a007=(a206*a072);
  a267=(a267+a007);
  a267=(-a267);
  if (res[1]!=0) res[1][70]=a267;
  a185=(a185+a097);
  a092=(a259*a092);
  a185=(a185+a092);
  a125=(a262*a125);
  a185=(a185+a125);
  a185=(a185+a012);
  a145=(a197*a145);
  a185=(a185+a145);
  a072=(a210*a072);
  a185=(a185+a072);
  a185=(-a185);
  if (res[1]!=0) res[1][71]=a185;
  a077=(a077-a152);
  a077=(a077-a004);
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
  a077=(a077+a161);
  a058=(a058*a077);
  a070=(a056*a070);
  a048=(a011*a048);
  a070=(a070-a048);
  a048=(a189*a139);
  a070=(a070+a048);
  a189=(a189*a054);
  a070=(a070+a189);
  a187=(a187*a070);
  a058=(a058+a187);
  a071=(a148*a071);
  a139=(a193*a139);
  a071=(a071+a139);
  a011=(a011*a140);
  a071=(a071-a011);
  a193=(a193*a054);
  a071=(a071+a193);
  a191=(a191*a071);
  a058=(a058+a191);
  a058=(a058/a002);
  if (res[1]!=0) res[1][72]=a058;
  a202=(a202*a077);
  a204=(a204*a070);
  a202=(a202+a204);
  a207=(a207*a071);
  a202=(a202+a207);
  a202=(a202/a002);
  if (res[1]!=0) res[1][73]=a202;
  a203=(a203*a077);
  a194=(a194*a070);
  a194=(a203+a194);
  a211=(a211*a071);
  a194=(a194+a211);
  a194=(a194/a002);
  if (res[1]!=0) res[1][74]=a194;
  a325=(a325-a308);
  a325=(a325-a091);
  a095=(a095*a118);
  a128=(a128*a124);
  a095=(a095-a128);
  a117=(a117*a069);
  a095=(a095-a117);
  a228=(a228*a095);
  a049=(a049*a228);
  a101=(a101*a049);
  a095=(a095/a099);
  a101=(a101-a095);
  a099=(a107*a101);
  a045=(a045*a099);
  a228=(a105*a101);
  a117=(a102*a228);
  a042=(a042*a117);
  a045=(a045+a042);
  a039=(a039*a228);
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
  a106=(a241*a106);
  a103=(a103*a101);
  a106=(a106+a103);
  a106=(a240*a106);
  a047=(a047+a106);
  a104=(a104*a228);
  a047=(a047+a104);
  a100=(a100*a101);
  a047=(a047+a100);
  a047=(a098*a047);
  a108=(a108+a047);
  a031=(a031*a107);
  a114=(a114*a095);
  a241=(a241*a114);
  a112=(a112*a095);
  a241=(a241+a112);
  a240=(a240*a241);
  a031=(a031+a240);
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
  a222=(a222*a045);
  a325=(a325+a222);
  a218=(a218*a325);
  a056=(a056*a069);
  a110=(a096*a110);
  a056=(a056-a110);
  a110=(a249*a273);
  a056=(a056+a110);
  a249=(a249*a045);
  a056=(a056+a249);
  a247=(a247*a056);
  a218=(a218+a247);
  a148=(a148*a124);
  a273=(a252*a273);
  a148=(a148+a273);
  a096=(a096*a201);
  a148=(a148-a096);
  a252=(a252*a045);
  a148=(a148+a252);
  a251=(a251*a148);
  a218=(a218+a251);
  a218=(a218/a002);
  if (res[1]!=0) res[1][75]=a218;
  a254=(a254*a325);
  a256=(a256*a056);
  a254=(a254+a256);
  a257=(a257*a148);
  a254=(a254+a257);
  a254=(a254/a002);
  if (res[1]!=0) res[1][76]=a254;
  a255=(a255*a325);
  a260=(a260*a056);
  a260=(a255+a260);
  a263=(a263*a148);
  a260=(a260+a263);
  a260=(a260/a002);
  if (res[1]!=0) res[1][77]=a260;
  a217=(a217*a325);
  a265=(a265+a217);
  a246=(a246*a056);
  a265=(a265+a246);
  a265=(a265+a251);
  a057=(a057*a077);
  a265=(a265+a057);
  a186=(a186*a070);
  a265=(a265+a186);
  a265=(a265+a191);
  a265=(-a265);
  if (res[1]!=0) res[1][78]=a265;
  a253=(a253*a325);
  a280=(a280+a253);
  a280=(a280+a256);
  a209=(a209*a148);
  a280=(a280+a209);
  a198=(a198*a077);
  a280=(a280+a198);
  a280=(a280+a204);
  a206=(a206*a071);
  a280=(a280+a206);
  a280=(-a280);
  if (res[1]!=0) res[1][79]=a280;
  a050=(a050+a255);
  a259=(a259*a056);
  a050=(a050+a259);
  a262=(a262*a148);
  a050=(a050+a262);
  a050=(a050+a203);
  a197=(a197*a070);
  a050=(a050+a197);
  a210=(a210*a071);
  a050=(a050+a210);
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

/* record:(g[9],p[3],xi[3])->(row[17]) */
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
  a12=casadi_sq(a12);
  a13=5.;
  a14=arg[2]? arg[2][1] : 0;
  a13=(a13*a14);
  a13=(a13*a14);
  a13=(a12+a13);
  a15=6.;
  a16=arg[2]? arg[2][2] : 0;
  a15=(a15*a16);
  a15=(a15*a16);
  a13=(a13+a15);
  a15=5.0000000000000000e-01;
  a15=(a15*a12);
  a12=3.;
  a16=casadi_sq(a16);
  a12=(a12*a16);
  a15=(a15+a12);
  a12=2.5000000000000000e+00;
  a14=casadi_sq(a14);
  a12=(a12*a14);
  a15=(a15+a12);
  a15=(a15-a08);
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
  a15=(a00*a08);
  a12=(a02*a06);
  a15=(a15-a12);
  a15=(a15*a10);
  a13=(a13+a15);
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
  if (res[0]!=0) res[0][16]=a08;
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
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a014, a015, a016, a017, a018, a019, a020, a021, a022, a023;
  casadi_real a024, a025, a026, a027, a028, a029, a030, a031, a032, a033, a034, a035;
  casadi_real a036, a037, a038, a039, a040, a041, a042, a043, a044, a045, a046, a047;
  casadi_real a048, a049, a050, a051, a052, a053, a054, a055, a056, a057, a058, a059;
  casadi_real a060, a061, a062, a063, a064, a065, a066, a067, a068, a069, a070, a071;
  casadi_real a072, a073, a074, a075, a076, a077, a078, a079, a080, a081, a082, a083;
  casadi_real a084, a085, a086, a087, a088, a089, a090, a091, a092, a093, a094, a095;
  casadi_real a096, a097, a098, a099, a100, a101, a102, a103, a104, a105, a106, a107;
  casadi_real a108;
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
  a011=(a011+a014);
  a015=(a004*a011);
  a016=1.6666666666666666e-01;
  a017=-2.0833333333333333e-03;
  a018=(a017*a011);
  a019=1.9841269841269841e-04;
  a020=-6.8893298059964731e-07;
  a021=(a020*a011);
  a021=(a019+a021);
  a022=casadi_sq(a015);
  a021=(a021*a022);
  a018=(a018+a021);
  a021=2.5052108385441720e-08;
  a023=-4.0147609592054033e-11;
  a024=(a023*a011);
  a024=(a021+a024);
  a025=7.6471637318198164e-13;
  a026=-7.0286431358638015e-16;
  a027=(a026*a011);
  a027=(a025+a027);
  a027=(a027*a022);
  a024=(a024+a027);
  a027=casadi_sq(a022);
  a024=(a024*a027);
  a018=(a018+a024);
  a024=8.2206352466243295e-18;
  a028=-4.8932352658478156e-21;
  a029=(a028*a011);
  a029=(a024+a029);
  a030=3.8681701706306841e-23;
  a031=(a030*a022);
  a029=(a029+a031);
  a031=casadi_sq(a027);
  a029=(a029*a031);
  a018=(a018+a029);
  a018=(a016+a018);
  a018=(a015*a018);
  a018=(a003-a018);
  a029=casadi_sq(a018);
  a029=(a000*a029);
  a007=(a014+a007);
  a007=(a029*a007);
  a007=(a003-a007);
  a032=arg[1]? arg[1][8] : 0;
  a033=(a007*a032);
  a034=-1.0416666666666666e-02;
  a035=(a034*a011);
  a036=1.3888888888888889e-03;
  a037=-6.2003968253968254e-06;
  a038=(a037*a011);
  a038=(a036+a038);
  a038=(a038*a022);
  a035=(a035+a038);
  a038=2.7557319223985888e-07;
  a039=-5.2191892469670250e-10;
  a040=(a039*a011);
  a040=(a038+a040);
  a041=1.1470745597729725e-11;
  a042=-1.1948693330968463e-14;
  a043=(a042*a011);
  a043=(a041+a043);
  a043=(a043*a022);
  a040=(a040+a043);
  a040=(a040*a027);
  a035=(a035+a040);
  a040=1.5619206968586225e-16;
  a027=-1.0275794058280412e-19;
  a011=(a027*a011);
  a011=(a040+a011);
  a043=8.8967913924505741e-22;
  a022=(a043*a022);
  a011=(a011+a022);
  a011=(a011*a031);
  a035=(a035+a011);
  a035=(a000+a035);
  a015=(a015*a035);
  a015=(a003-a015);
  a018=(a018*a015);
  a015=(a018*a006);
  a035=(a009*a013);
  a035=(a029*a035);
  a015=(a015+a035);
  a035=arg[1]? arg[1][5] : 0;
  a011=(a015*a035);
  a033=(a033-a011);
  a033=(a002*a033);
  a033=(a033/a001);
  if (res[0]!=0) res[0][0]=a033;
  a033=(a018*a013);
  a011=(a006*a009);
  a011=(a029*a011);
  a031=(a033+a011);
  a022=(a031*a032);
  a006=(a006*a013);
  a006=(a029*a006);
  a018=(a018*a009);
  a006=(a006-a018);
  a018=(a006*a035);
  a022=(a022-a018);
  a022=(a002*a022);
  a022=(a022/a001);
  a022=(-a022);
  if (res[0]!=0) res[0][1]=a022;
  a022=0.;
  if (res[0]!=0) res[0][2]=a022;
  a018=arg[0]? arg[0][3] : 0;
  a009=(a001*a018);
  a013=casadi_sq(a009);
  a044=arg[0]? arg[0][4] : 0;
  a045=(a001*a044);
  a046=casadi_sq(a045);
  a047=(a013+a046);
  a048=arg[0]? arg[0][5] : 0;
  a049=(a001*a048);
  a050=casadi_sq(a049);
  a047=(a047+a050);
  a051=(a004*a047);
  a052=(a017*a047);
  a053=(a020*a047);
  a053=(a019+a053);
  a054=casadi_sq(a051);
  a053=(a053*a054);
  a052=(a052+a053);
  a053=(a023*a047);
  a053=(a021+a053);
  a055=(a026*a047);
  a055=(a025+a055);
  a055=(a055*a054);
  a053=(a053+a055);
  a055=casadi_sq(a054);
  a053=(a053*a055);
  a052=(a052+a053);
  a053=(a028*a047);
  a053=(a024+a053);
  a056=(a030*a054);
  a053=(a053+a056);
  a056=casadi_sq(a055);
  a053=(a053*a056);
  a052=(a052+a053);
  a052=(a016+a052);
  a052=(a051*a052);
  a052=(a003-a052);
  a053=casadi_sq(a052);
  a053=(a000*a053);
  a013=(a050+a013);
  a013=(a053*a013);
  a013=(a003-a013);
  a057=(a013*a032);
  a058=(a034*a047);
  a059=(a037*a047);
  a059=(a036+a059);
  a059=(a059*a054);
  a058=(a058+a059);
  a059=(a039*a047);
  a059=(a038+a059);
  a060=(a042*a047);
  a060=(a041+a060);
  a060=(a060*a054);
  a059=(a059+a060);
  a059=(a059*a055);
  a058=(a058+a059);
  a047=(a027*a047);
  a047=(a040+a047);
  a054=(a043*a054);
  a047=(a047+a054);
  a047=(a047*a056);
  a058=(a058+a047);
  a058=(a000+a058);
  a051=(a051*a058);
  a051=(a003-a051);
  a052=(a052*a051);
  a051=(a052*a009);
  a058=(a045*a049);
  a058=(a053*a058);
  a051=(a051+a058);
  a058=(a051*a035);
  a057=(a057-a058);
  a057=(a002*a057);
  a057=(a057/a001);
  if (res[0]!=0) res[0][3]=a057;
  a057=(a052*a049);
  a058=(a009*a045);
  a058=(a053*a058);
  a047=(a057+a058);
  a056=(a047*a032);
  a009=(a009*a049);
  a009=(a053*a009);
  a052=(a052*a045);
  a009=(a009-a052);
  a052=(a009*a035);
  a056=(a056-a052);
  a056=(a002*a056);
  a056=(a056/a001);
  a056=(-a056);
  if (res[0]!=0) res[0][4]=a056;
  if (res[0]!=0) res[0][5]=a022;
  if (res[0]!=0) res[0][6]=a022;
  if (res[0]!=0) res[0][7]=a022;
  if (res[0]!=0) res[0][8]=a022;
  a056=arg[1]? arg[1][2] : 0;
  a015=(a015*a056);
  a011=(a011-a033);
  a033=(a011*a032);
  a015=(a015-a033);
  a015=(a002*a015);
  a015=(a015/a001);
  if (res[0]!=0) res[0][9]=a015;
  a006=(a006*a056);
  a010=(a010+a014);
  a029=(a029*a010);
  a029=(a003-a029);
  a010=(a029*a032);
  a006=(a006-a010);
  a006=(a002*a006);
  a006=(a006/a001);
  a006=(-a006);
  if (res[0]!=0) res[0][10]=a006;
  if (res[0]!=0) res[0][11]=a022;
  a051=(a051*a056);
  a058=(a058-a057);
  a057=(a058*a032);
  a051=(a051-a057);
  a051=(a002*a051);
  a051=(a051/a001);
  if (res[0]!=0) res[0][12]=a051;
  a009=(a009*a056);
  a046=(a046+a050);
  a053=(a053*a046);
  a053=(a003-a053);
  a046=(a053*a032);
  a009=(a009-a046);
  a009=(a002*a009);
  a009=(a009/a001);
  a009=(-a009);
  if (res[0]!=0) res[0][13]=a009;
  if (res[0]!=0) res[0][14]=a022;
  if (res[0]!=0) res[0][15]=a022;
  if (res[0]!=0) res[0][16]=a022;
  if (res[0]!=0) res[0][17]=a022;
  a011=(a011*a035);
  a007=(a007*a056);
  a011=(a011-a007);
  a011=(a002*a011);
  a011=(a011/a001);
  if (res[0]!=0) res[0][18]=a011;
  a029=(a029*a035);
  a031=(a031*a056);
  a029=(a029-a031);
  a029=(a002*a029);
  a029=(a029/a001);
  a029=(-a029);
  if (res[0]!=0) res[0][19]=a029;
  if (res[0]!=0) res[0][20]=a022;
  a058=(a058*a035);
  a013=(a013*a056);
  a058=(a058-a013);
  a058=(a002*a058);
  a058=(a058/a001);
  if (res[0]!=0) res[0][21]=a058;
  a053=(a053*a035);
  a047=(a047*a056);
  a053=(a053-a047);
  a002=(a002*a053);
  a002=(a002/a001);
  a002=(-a002);
  if (res[0]!=0) res[0][22]=a002;
  if (res[0]!=0) res[0][23]=a022;
  if (res[0]!=0) res[0][24]=a022;
  if (res[0]!=0) res[0][25]=a022;
  if (res[0]!=0) res[0][26]=a022;
  if (res[0]!=0) res[0][27]=a022;
  if (res[0]!=0) res[0][28]=a022;
  if (res[0]!=0) res[0][29]=a022;
  if (res[0]!=0) res[0][30]=a022;
  if (res[0]!=0) res[0][31]=a022;
  if (res[0]!=0) res[0][32]=a022;
  if (res[0]!=0) res[0][33]=a003;
  if (res[0]!=0) res[0][34]=a022;
  if (res[0]!=0) res[0][35]=a022;
  if (res[0]!=0) res[0][36]=a022;
  if (res[0]!=0) res[0][37]=a022;
  if (res[0]!=0) res[0][38]=a022;
  if (res[0]!=0) res[0][39]=a022;
  if (res[0]!=0) res[0][40]=a022;
  if (res[0]!=0) res[0][41]=a022;
  if (res[0]!=0) res[0][42]=a022;
  if (res[0]!=0) res[0][43]=a003;
  if (res[0]!=0) res[0][44]=a022;
  if (res[0]!=0) res[0][45]=a022;
  if (res[0]!=0) res[0][46]=a022;
  if (res[0]!=0) res[0][47]=a022;
  if (res[0]!=0) res[0][48]=a022;
  if (res[0]!=0) res[0][49]=a022;
  if (res[0]!=0) res[0][50]=a022;
  if (res[0]!=0) res[0][51]=a022;
  if (res[0]!=0) res[0][52]=a022;
  if (res[0]!=0) res[0][53]=a003;
  a002=arg[1]? arg[1][0] : 0;
  a053=3.0000000000000004e+00;
  a047=(a053*a005);
  a058=4.6410161513775439e-01;
  a013=(a058*a018);
  a047=(a047+a013);
  a047=(a000*a047);
  a013=-6.4641016151377553e+00;
  a005=(a013*a005);
  a018=(a053*a018);
  a005=(a005+a018);
  a005=(a000*a005);
  a047=(a047+a005);
  a047=(a001*a047);
  a005=casadi_sq(a047);
  a018=(a053*a008);
  a029=(a058*a044);
  a018=(a018+a029);
  a018=(a000*a018);
  a008=(a013*a008);
  a044=(a053*a044);
  a008=(a008+a044);
  a008=(a000*a008);
  a018=(a018+a008);
  a018=(a001*a018);
  a008=casadi_sq(a018);
  a044=(a005+a008);
  a029=(a053*a012);
  a058=(a058*a048);
  a029=(a029+a058);
  a029=(a000*a029);
  a013=(a013*a012);
  a053=(a053*a048);
  a013=(a013+a053);
  a013=(a000*a013);
  a029=(a029+a013);
  a029=(a001*a029);
  a013=casadi_sq(a029);
  a053=(a044+a013);
  a048=(a004*a053);
  a012=(a017*a053);
  a058=(a020*a053);
  a019=(a019+a058);
  a058=casadi_sq(a048);
  a031=(a019*a058);
  a012=(a012+a031);
  a031=(a023*a053);
  a021=(a021+a031);
  a031=(a026*a053);
  a025=(a025+a031);
  a031=(a025*a058);
  a021=(a021+a031);
  a031=casadi_sq(a058);
  a011=(a021*a031);
  a012=(a012+a011);
  a011=(a028*a053);
  a024=(a024+a011);
  a011=(a030*a058);
  a024=(a024+a011);
  a011=casadi_sq(a031);
  a007=(a024*a011);
  a012=(a012+a007);
  a016=(a016+a012);
  a007=(a048*a016);
  a007=(a003-a007);
  a009=(a034*a053);
  a046=(a037*a053);
  a036=(a036+a046);
  a046=(a036*a058);
  a009=(a009+a046);
  a046=(a039*a053);
  a038=(a038+a046);
  a046=(a042*a053);
  a041=(a041+a046);
  a046=(a041*a058);
  a038=(a038+a046);
  a046=(a038*a031);
  a009=(a009+a046);
  a046=(a027*a053);
  a040=(a040+a046);
  a046=(a043*a058);
  a040=(a040+a046);
  a046=(a040*a011);
  a009=(a009+a046);
  a046=(a000+a009);
  a050=(a048*a046);
  a050=(a003-a050);
  a051=(a007*a050);
  a057=(a051*a018);
  a006=casadi_sq(a007);
  a006=(a000*a006);
  a010=(a047*a029);
  a014=(a006*a010);
  a015=(a057+a014);
  a033=(a002*a015);
  a052=arg[1]? arg[1][3] : 0;
  a045=(a018*a029);
  a049=(a006*a045);
  a054=(a051*a047);
  a059=(a049-a054);
  a055=(a052*a059);
  a033=(a033+a055);
  a055=arg[1]? arg[1][6] : 0;
  a060=(a006*a044);
  a060=(a003-a060);
  a061=(a055*a060);
  a033=(a033+a061);
  a061=-1.7320508075688774e+00;
  a061=(a061*a001);
  a062=(a018*a061);
  a063=(a006*a062);
  a064=(a047*a018);
  a065=(2.*a007);
  a066=(2.*a047);
  a067=(a066*a061);
  a068=(a004*a067);
  a069=(a016*a068);
  a070=(a017*a067);
  a071=(a020*a067);
  a071=(a058*a071);
  a053=(a000*a053);
  a072=(a053*a068);
  a073=(a019*a072);
  a071=(a071+a073);
  a070=(a070+a071);
  a071=(a023*a067);
  a073=(a026*a067);
  a073=(a058*a073);
  a074=(a025*a072);
  a073=(a073+a074);
  a071=(a071+a073);
  a071=(a031*a071);
  a073=(2.*a058);
  a074=(a073*a072);
  a075=(a021*a074);
  a071=(a071+a075);
  a070=(a070+a071);
  a071=(a028*a067);
  a075=(a030*a072);
  a071=(a071+a075);
  a071=(a011*a071);
  a075=(2.*a031);
  a076=(a075*a074);
  a077=(a024*a076);
  a071=(a071+a077);
  a070=(a070+a071);
  a071=(a048*a070);
  a069=(a069+a071);
  a071=(a065*a069);
  a071=(a000*a071);
  a077=(a064*a071);
  a077=(a063-a077);
  a078=(a050*a069);
  a068=(a046*a068);
  a079=(a034*a067);
  a080=(a037*a067);
  a080=(a058*a080);
  a081=(a036*a072);
  a080=(a080+a081);
  a079=(a079+a080);
  a080=(a039*a067);
  a081=(a042*a067);
  a081=(a058*a081);
  a082=(a041*a072);
  a081=(a081+a082);
  a080=(a080+a081);
  a080=(a031*a080);
  a074=(a038*a074);
  a080=(a080+a074);
  a079=(a079+a080);
  a080=(a027*a067);
  a072=(a043*a072);
  a080=(a080+a072);
  a080=(a011*a080);
  a076=(a040*a076);
  a080=(a080+a076);
  a079=(a079+a080);
  a080=(a048*a079);
  a068=(a068+a080);
  a068=(a007*a068);
  a078=(a078+a068);
  a068=(a029*a078);
  a080=(a077+a068);
  a076=(a002*a080);
  a072=(a006*a067);
  a005=(a013+a005);
  a074=(a005*a071);
  a074=(a072-a074);
  a081=(a052*a074);
  a076=(a076-a081);
  a081=(a051*a061);
  a082=(a047*a078);
  a082=(a081-a082);
  a083=(a045*a071);
  a084=(a082-a083);
  a085=(a055*a084);
  a076=(a076+a085);
  a076=(a033*a076);
  a085=arg[1]? arg[1][1] : 0;
  a086=(a085*a015);
  a087=arg[1]? arg[1][4] : 0;
  a088=(a087*a059);
  a086=(a086+a088);
  a088=arg[1]? arg[1][7] : 0;
  a089=(a088*a060);
  a086=(a086+a089);
  a089=(a085*a080);
  a090=(a087*a074);
  a089=(a089-a090);
  a090=(a088*a084);
  a089=(a089+a090);
  a089=(a086*a089);
  a076=(a076+a089);
  a089=(a056*a015);
  a090=(a035*a059);
  a089=(a089+a090);
  a090=(a032*a060);
  a089=(a089+a090);
  a080=(a056*a080);
  a074=(a035*a074);
  a080=(a080-a074);
  a084=(a032*a084);
  a080=(a080+a084);
  a080=(a089*a080);
  a076=(a076+a080);
  if (res[1]!=0) res[1][0]=a076;
  a008=(a008+a013);
  a013=(a006*a008);
  a013=(a003-a013);
  a076=(a002*a013);
  a080=(a051*a029);
  a084=(a006*a064);
  a074=(a080+a084);
  a090=(a052*a074);
  a076=(a076+a090);
  a014=(a014-a057);
  a057=(a055*a014);
  a076=(a076+a057);
  a057=(a029*a061);
  a090=(a006*a057);
  a091=(a010*a071);
  a091=(a090-a091);
  a078=(a018*a078);
  a092=(a091-a078);
  a093=(a002*a092);
  a083=(a083+a082);
  a082=(a052*a083);
  a093=(a093-a082);
  a082=(a044*a071);
  a072=(a072-a082);
  a082=(a055*a072);
  a093=(a093-a082);
  a093=(a076*a093);
  a082=(a085*a013);
  a094=(a087*a074);
  a082=(a082+a094);
  a094=(a088*a014);
  a082=(a082+a094);
  a094=(a085*a092);
  a095=(a087*a083);
  a094=(a094-a095);
  a095=(a088*a072);
  a094=(a094-a095);
  a094=(a082*a094);
  a093=(a093+a094);
  a094=(a056*a013);
  a095=(a035*a074);
  a094=(a094+a095);
  a095=(a032*a014);
  a094=(a094+a095);
  a092=(a056*a092);
  a083=(a035*a083);
  a092=(a092-a083);
  a072=(a032*a072);
  a092=(a092-a072);
  a092=(a094*a092);
  a093=(a093+a092);
  if (res[1]!=0) res[1][1]=a093;
  a084=(a084-a080);
  a080=(a002*a084);
  a093=(a006*a005);
  a093=(a003-a093);
  a092=(a052*a093);
  a080=(a080+a092);
  a054=(a054+a049);
  a049=(a055*a054);
  a080=(a080+a049);
  a071=(a008*a071);
  a049=(a002*a071);
  a077=(a077-a068);
  a068=(a052*a077);
  a049=(a049+a068);
  a091=(a091+a078);
  a078=(a055*a091);
  a049=(a049+a078);
  a049=(a080*a049);
  a078=(a085*a084);
  a068=(a087*a093);
  a078=(a078+a068);
  a068=(a088*a054);
  a078=(a078+a068);
  a068=(a085*a071);
  a092=(a087*a077);
  a068=(a068+a092);
  a092=(a088*a091);
  a068=(a068+a092);
  a068=(a078*a068);
  a049=(a049+a068);
  a068=(a056*a084);
  a092=(a035*a093);
  a068=(a068+a092);
  a092=(a032*a054);
  a068=(a068+a092);
  a071=(a056*a071);
  a077=(a035*a077);
  a071=(a071+a077);
  a091=(a032*a091);
  a071=(a071+a091);
  a071=(a068*a071);
  a049=(a049+a071);
  if (res[1]!=0) res[1][2]=a049;
  a049=arg[0]? arg[0][8] : 0;
  a079=(a079-a070);
  a070=4.;
  a071=(a070*a007);
  a079=(a079/a071);
  a091=3.3333333333333331e-01;
  a009=(a009-a012);
  a091=(a091+a009);
  a091=(a091/a071);
  a009=(a091/a071);
  a069=(a070*a069);
  a069=(a009*a069);
  a079=(a079+a069);
  a069=(a010*a079);
  a057=(a091*a057);
  a069=(a069+a057);
  a012=(a049*a069);
  a077=arg[0]? arg[0][7] : 0;
  a092=(a064*a079);
  a062=(a091*a062);
  a092=(a092+a062);
  a072=(a077*a092);
  a012=(a012+a072);
  a072=arg[0]? arg[0][6] : 0;
  a083=(a008*a079);
  a083=(a072*a083);
  a012=(a012-a083);
  if (res[1]!=0) res[1][3]=a012;
  a012=(a045*a079);
  a083=8.6602540378443871e-01;
  a083=(a083*a001);
  a095=(a012-a083);
  a095=(a049*a095);
  a096=(a005*a079);
  a067=(a091*a067);
  a096=(a096+a067);
  a096=(a077*a096);
  a095=(a095-a096);
  a092=(a072*a092);
  a095=(a095+a092);
  if (res[1]!=0) res[1][4]=a095;
  a095=-8.6602540378443871e-01;
  a095=(a095*a001);
  a012=(a012-a095);
  a012=(a077*a012);
  a079=(a044*a079);
  a079=(a079+a067);
  a079=(a049*a079);
  a012=(a012-a079);
  a069=(a072*a069);
  a012=(a012+a069);
  if (res[1]!=0) res[1][5]=a012;
  a012=(a047*a061);
  a069=(a006*a012);
  a079=(2.*a018);
  a067=(a079*a061);
  a092=(a004*a067);
  a096=(a016*a092);
  a097=(a017*a067);
  a098=(a020*a067);
  a098=(a058*a098);
  a099=(a053*a092);
  a100=(a019*a099);
  a098=(a098+a100);
  a097=(a097+a098);
  a098=(a023*a067);
  a100=(a026*a067);
  a100=(a058*a100);
  a101=(a025*a099);
  a100=(a100+a101);
  a098=(a098+a100);
  a098=(a031*a098);
  a100=(a073*a099);
  a101=(a021*a100);
  a098=(a098+a101);
  a097=(a097+a098);
  a098=(a028*a067);
  a101=(a030*a099);
  a098=(a098+a101);
  a098=(a011*a098);
  a101=(a075*a100);
  a102=(a024*a101);
  a098=(a098+a102);
  a097=(a097+a098);
  a098=(a048*a097);
  a096=(a096+a098);
  a098=(a065*a096);
  a098=(a000*a098);
  a102=(a064*a098);
  a102=(a069-a102);
  a103=(a050*a096);
  a092=(a046*a092);
  a104=(a034*a067);
  a105=(a037*a067);
  a105=(a058*a105);
  a106=(a036*a099);
  a105=(a105+a106);
  a104=(a104+a105);
  a105=(a039*a067);
  a106=(a042*a067);
  a106=(a058*a106);
  a107=(a041*a099);
  a106=(a106+a107);
  a105=(a105+a106);
  a105=(a031*a105);
  a100=(a038*a100);
  a105=(a105+a100);
  a104=(a104+a105);
  a105=(a027*a067);
  a099=(a043*a099);
  a105=(a105+a099);
  a105=(a011*a105);
  a101=(a040*a101);
  a105=(a105+a101);
  a104=(a104+a105);
  a105=(a048*a104);
  a092=(a092+a105);
  a092=(a007*a092);
  a103=(a103+a092);
  a092=(a029*a103);
  a105=(a102+a092);
  a101=(a002*a105);
  a099=(a005*a098);
  a100=(a052*a099);
  a101=(a101+a100);
  a100=(a045*a098);
  a090=(a090-a100);
  a100=(a047*a103);
  a106=(a090-a100);
  a107=(a055*a106);
  a101=(a101+a107);
  a101=(a033*a101);
  a107=(a085*a105);
  a108=(a087*a099);
  a107=(a107+a108);
  a108=(a088*a106);
  a107=(a107+a108);
  a107=(a086*a107);
  a101=(a101+a107);
  a105=(a056*a105);
  a099=(a035*a099);
  a105=(a105+a099);
  a106=(a032*a106);
  a105=(a105+a106);
  a105=(a089*a105);
  a101=(a101+a105);
  if (res[1]!=0) res[1][6]=a101;
  a103=(a018*a103);
  a103=(a081-a103);
  a101=(a010*a098);
  a105=(a103-a101);
  a106=(a002*a105);
  a090=(a090+a100);
  a100=(a052*a090);
  a106=(a106+a100);
  a100=(a006*a067);
  a099=(a044*a098);
  a099=(a100-a099);
  a107=(a055*a099);
  a106=(a106-a107);
  a106=(a076*a106);
  a107=(a085*a105);
  a108=(a087*a090);
  a107=(a107+a108);
  a108=(a088*a099);
  a107=(a107-a108);
  a107=(a082*a107);
  a106=(a106+a107);
  a105=(a056*a105);
  a090=(a035*a090);
  a105=(a105+a090);
  a099=(a032*a099);
  a105=(a105-a099);
  a105=(a094*a105);
  a106=(a106+a105);
  if (res[1]!=0) res[1][7]=a106;
  a102=(a102-a092);
  a092=(a052*a102);
  a098=(a008*a098);
  a100=(a100-a098);
  a098=(a002*a100);
  a092=(a092-a098);
  a101=(a101+a103);
  a103=(a055*a101);
  a092=(a092-a103);
  a092=(a080*a092);
  a103=(a087*a102);
  a098=(a085*a100);
  a103=(a103-a098);
  a098=(a088*a101);
  a103=(a103-a098);
  a103=(a078*a103);
  a092=(a092+a103);
  a102=(a035*a102);
  a100=(a056*a100);
  a102=(a102-a100);
  a101=(a032*a101);
  a102=(a102-a101);
  a102=(a068*a102);
  a092=(a092+a102);
  if (res[1]!=0) res[1][8]=a092;
  a104=(a104-a097);
  a104=(a104/a071);
  a096=(a070*a096);
  a096=(a009*a096);
  a104=(a104+a096);
  a096=(a010*a104);
  a097=(a096-a095);
  a097=(a049*a097);
  a092=(a064*a104);
  a012=(a091*a012);
  a092=(a092+a012);
  a102=(a077*a092);
  a097=(a097+a102);
  a102=(a008*a104);
  a067=(a091*a067);
  a102=(a102+a067);
  a102=(a072*a102);
  a097=(a097-a102);
  if (res[1]!=0) res[1][9]=a097;
  a097=(a045*a104);
  a097=(a097+a057);
  a057=(a049*a097);
  a102=(a005*a104);
  a102=(a077*a102);
  a057=(a057-a102);
  a092=(a072*a092);
  a057=(a057+a092);
  if (res[1]!=0) res[1][10]=a057;
  a097=(a077*a097);
  a104=(a044*a104);
  a104=(a104+a067);
  a104=(a049*a104);
  a097=(a097-a104);
  a096=(a096-a083);
  a096=(a072*a096);
  a097=(a097+a096);
  if (res[1]!=0) res[1][11]=a097;
  a097=(2.*a029);
  a061=(a097*a061);
  a096=(a004*a061);
  a104=(a016*a096);
  a067=(a017*a061);
  a057=(a020*a061);
  a057=(a058*a057);
  a092=(a053*a096);
  a102=(a019*a092);
  a057=(a057+a102);
  a067=(a067+a057);
  a057=(a023*a061);
  a102=(a026*a061);
  a102=(a058*a102);
  a101=(a025*a092);
  a102=(a102+a101);
  a057=(a057+a102);
  a057=(a031*a057);
  a102=(a073*a092);
  a101=(a021*a102);
  a057=(a057+a101);
  a067=(a067+a057);
  a057=(a028*a061);
  a101=(a030*a092);
  a057=(a057+a101);
  a057=(a011*a057);
  a101=(a075*a102);
  a100=(a024*a101);
  a057=(a057+a100);
  a067=(a067+a057);
  a057=(a048*a067);
  a104=(a104+a057);
  a057=(a065*a104);
  a057=(a000*a057);
  a100=(a045*a057);
  a063=(a063-a100);
  a100=(a050*a104);
  a096=(a046*a096);
  a103=(a034*a061);
  a098=(a037*a061);
  a098=(a058*a098);
  a106=(a036*a092);
  a098=(a098+a106);
  a103=(a103+a098);
  a098=(a039*a061);
  a106=(a042*a061);
  a106=(a058*a106);
  a105=(a041*a092);
  a106=(a106+a105);
  a098=(a098+a106);
  a098=(a031*a098);
  a102=(a038*a102);
  a098=(a098+a102);
  a103=(a103+a098);
  a098=(a027*a061);
  a092=(a043*a092);
  a098=(a098+a092);
  a098=(a011*a098);
  a101=(a040*a101);
  a098=(a098+a101);
  a103=(a103+a098);
  a098=(a048*a103);
  a096=(a096+a098);
  a096=(a007*a096);
  a100=(a100+a096);
  a096=(a047*a100);
  a098=(a063-a096);
  a101=(a055*a098);
  a092=(a064*a057);
  a102=(a029*a100);
  a081=(a081-a102);
  a102=(a092+a081);
  a106=(a002*a102);
  a105=(a006*a061);
  a099=(a005*a057);
  a099=(a105-a099);
  a090=(a052*a099);
  a106=(a106+a090);
  a101=(a101-a106);
  a101=(a033*a101);
  a106=(a088*a098);
  a090=(a085*a102);
  a107=(a087*a099);
  a090=(a090+a107);
  a106=(a106-a090);
  a106=(a086*a106);
  a101=(a101+a106);
  a098=(a032*a098);
  a102=(a056*a102);
  a099=(a035*a099);
  a102=(a102+a099);
  a098=(a098-a102);
  a098=(a089*a098);
  a101=(a101+a098);
  if (res[1]!=0) res[1][12]=a101;
  a101=(a010*a057);
  a069=(a069-a101);
  a100=(a018*a100);
  a101=(a069-a100);
  a098=(a002*a101);
  a063=(a063+a096);
  a096=(a052*a063);
  a098=(a098+a096);
  a096=(a044*a057);
  a102=(a055*a096);
  a098=(a098+a102);
  a098=(a076*a098);
  a102=(a085*a101);
  a099=(a087*a063);
  a102=(a102+a099);
  a099=(a088*a096);
  a102=(a102+a099);
  a102=(a082*a102);
  a098=(a098+a102);
  a101=(a056*a101);
  a063=(a035*a063);
  a101=(a101+a063);
  a096=(a032*a096);
  a101=(a101+a096);
  a101=(a094*a101);
  a098=(a098+a101);
  if (res[1]!=0) res[1][13]=a098;
  a081=(a081-a092);
  a092=(a052*a081);
  a057=(a008*a057);
  a105=(a105-a057);
  a057=(a002*a105);
  a092=(a092-a057);
  a069=(a069+a100);
  a100=(a055*a069);
  a092=(a092+a100);
  a092=(a080*a092);
  a100=(a087*a081);
  a057=(a085*a105);
  a100=(a100-a057);
  a057=(a088*a069);
  a100=(a100+a057);
  a100=(a078*a100);
  a092=(a092+a100);
  a081=(a035*a081);
  a105=(a056*a105);
  a081=(a081-a105);
  a069=(a032*a069);
  a081=(a081+a069);
  a081=(a068*a081);
  a092=(a092+a081);
  if (res[1]!=0) res[1][14]=a092;
  a103=(a103-a067);
  a103=(a103/a071);
  a104=(a070*a104);
  a104=(a009*a104);
  a103=(a103+a104);
  a104=(a010*a103);
  a104=(a104+a012);
  a012=(a049*a104);
  a067=(a064*a103);
  a092=(a067-a083);
  a092=(a077*a092);
  a012=(a012+a092);
  a092=(a008*a103);
  a061=(a091*a061);
  a092=(a092+a061);
  a092=(a072*a092);
  a012=(a012-a092);
  if (res[1]!=0) res[1][15]=a012;
  a012=(a045*a103);
  a012=(a012+a062);
  a062=(a049*a012);
  a092=(a005*a103);
  a092=(a092+a061);
  a092=(a077*a092);
  a062=(a062-a092);
  a067=(a067-a095);
  a067=(a072*a067);
  a062=(a062+a067);
  if (res[1]!=0) res[1][16]=a062;
  a012=(a077*a012);
  a103=(a044*a103);
  a103=(a049*a103);
  a012=(a012-a103);
  a104=(a072*a104);
  a012=(a012+a104);
  if (res[1]!=0) res[1][17]=a012;
  a012=1.7320508075688774e+00;
  a012=(a012*a001);
  a001=(a018*a012);
  a104=(a006*a001);
  a066=(a066*a012);
  a103=(a004*a066);
  a062=(a016*a103);
  a067=(a017*a066);
  a092=(a020*a066);
  a092=(a058*a092);
  a061=(a053*a103);
  a081=(a019*a061);
  a092=(a092+a081);
  a067=(a067+a092);
  a092=(a023*a066);
  a081=(a026*a066);
  a081=(a058*a081);
  a069=(a025*a061);
  a081=(a081+a069);
  a092=(a092+a081);
  a092=(a031*a092);
  a081=(a073*a061);
  a069=(a021*a081);
  a092=(a092+a069);
  a067=(a067+a092);
  a092=(a028*a066);
  a069=(a030*a061);
  a092=(a092+a069);
  a092=(a011*a092);
  a069=(a075*a081);
  a105=(a024*a069);
  a092=(a092+a105);
  a067=(a067+a092);
  a092=(a048*a067);
  a062=(a062+a092);
  a092=(a065*a062);
  a092=(a000*a092);
  a105=(a064*a092);
  a105=(a104-a105);
  a100=(a050*a062);
  a103=(a046*a103);
  a057=(a034*a066);
  a098=(a037*a066);
  a098=(a058*a098);
  a101=(a036*a061);
  a098=(a098+a101);
  a057=(a057+a098);
  a098=(a039*a066);
  a101=(a042*a066);
  a101=(a058*a101);
  a096=(a041*a061);
  a101=(a101+a096);
  a098=(a098+a101);
  a098=(a031*a098);
  a081=(a038*a081);
  a098=(a098+a081);
  a057=(a057+a098);
  a098=(a027*a066);
  a061=(a043*a061);
  a098=(a098+a061);
  a098=(a011*a098);
  a069=(a040*a069);
  a098=(a098+a069);
  a057=(a057+a098);
  a098=(a048*a057);
  a103=(a103+a098);
  a103=(a007*a103);
  a100=(a100+a103);
  a103=(a029*a100);
  a098=(a105+a103);
  a069=(a002*a098);
  a061=(a006*a066);
  a081=(a005*a092);
  a081=(a061-a081);
  a101=(a052*a081);
  a069=(a069-a101);
  a051=(a051*a012);
  a101=(a047*a100);
  a101=(a051-a101);
  a096=(a045*a092);
  a063=(a101-a096);
  a102=(a055*a063);
  a069=(a069+a102);
  a069=(a033*a069);
  a102=(a085*a098);
  a099=(a087*a081);
  a102=(a102-a099);
  a099=(a088*a063);
  a102=(a102+a099);
  a102=(a086*a102);
  a069=(a069+a102);
  a098=(a056*a098);
  a081=(a035*a081);
  a098=(a098-a081);
  a063=(a032*a063);
  a098=(a098+a063);
  a098=(a089*a098);
  a069=(a069+a098);
  if (res[1]!=0) res[1][18]=a069;
  a069=(a029*a012);
  a098=(a006*a069);
  a063=(a010*a092);
  a063=(a098-a063);
  a100=(a018*a100);
  a081=(a063-a100);
  a102=(a002*a081);
  a096=(a096+a101);
  a101=(a052*a096);
  a102=(a102-a101);
  a101=(a044*a092);
  a061=(a061-a101);
  a101=(a055*a061);
  a102=(a102-a101);
  a102=(a076*a102);
  a101=(a085*a081);
  a099=(a087*a096);
  a101=(a101-a099);
  a099=(a088*a061);
  a101=(a101-a099);
  a101=(a082*a101);
  a102=(a102+a101);
  a081=(a056*a081);
  a096=(a035*a096);
  a081=(a081-a096);
  a061=(a032*a061);
  a081=(a081-a061);
  a081=(a094*a081);
  a102=(a102+a081);
  if (res[1]!=0) res[1][19]=a102;
  a092=(a008*a092);
  a102=(a002*a092);
  a105=(a105-a103);
  a103=(a052*a105);
  a102=(a102+a103);
  a063=(a063+a100);
  a100=(a055*a063);
  a102=(a102+a100);
  a102=(a080*a102);
  a100=(a085*a092);
  a103=(a087*a105);
  a100=(a100+a103);
  a103=(a088*a063);
  a100=(a100+a103);
  a100=(a078*a100);
  a102=(a102+a100);
  a092=(a056*a092);
  a105=(a035*a105);
  a092=(a092+a105);
  a063=(a032*a063);
  a092=(a092+a063);
  a092=(a068*a092);
  a102=(a102+a092);
  if (res[1]!=0) res[1][20]=a102;
  a057=(a057-a067);
  a057=(a057/a071);
  a062=(a070*a062);
  a062=(a009*a062);
  a057=(a057+a062);
  a062=(a010*a057);
  a069=(a091*a069);
  a062=(a062+a069);
  a067=(a049*a062);
  a102=(a064*a057);
  a001=(a091*a001);
  a102=(a102+a001);
  a092=(a077*a102);
  a067=(a067+a092);
  a092=(a008*a057);
  a092=(a072*a092);
  a067=(a067-a092);
  if (res[1]!=0) res[1][21]=a067;
  a067=(a045*a057);
  a092=(a067-a095);
  a092=(a049*a092);
  a063=(a005*a057);
  a066=(a091*a066);
  a063=(a063+a066);
  a063=(a077*a063);
  a092=(a092-a063);
  a102=(a072*a102);
  a092=(a092+a102);
  if (res[1]!=0) res[1][22]=a092;
  a067=(a067-a083);
  a067=(a077*a067);
  a057=(a044*a057);
  a057=(a057+a066);
  a057=(a049*a057);
  a067=(a067-a057);
  a062=(a072*a062);
  a067=(a067+a062);
  if (res[1]!=0) res[1][23]=a067;
  a067=(a047*a012);
  a062=(a006*a067);
  a079=(a079*a012);
  a057=(a004*a079);
  a066=(a016*a057);
  a092=(a017*a079);
  a102=(a020*a079);
  a102=(a058*a102);
  a063=(a053*a057);
  a105=(a019*a063);
  a102=(a102+a105);
  a092=(a092+a102);
  a102=(a023*a079);
  a105=(a026*a079);
  a105=(a058*a105);
  a100=(a025*a063);
  a105=(a105+a100);
  a102=(a102+a105);
  a102=(a031*a102);
  a105=(a073*a063);
  a100=(a021*a105);
  a102=(a102+a100);
  a092=(a092+a102);
  a102=(a028*a079);
  a100=(a030*a063);
  a102=(a102+a100);
  a102=(a011*a102);
  a100=(a075*a105);
  a103=(a024*a100);
  a102=(a102+a103);
  a092=(a092+a102);
  a102=(a048*a092);
  a066=(a066+a102);
  a102=(a065*a066);
  a102=(a000*a102);
  a103=(a064*a102);
  a103=(a062-a103);
  a081=(a050*a066);
  a057=(a046*a057);
  a061=(a034*a079);
  a096=(a037*a079);
  a096=(a058*a096);
  a101=(a036*a063);
  a096=(a096+a101);
  a061=(a061+a096);
  a096=(a039*a079);
  a101=(a042*a079);
  a101=(a058*a101);
  a099=(a041*a063);
  a101=(a101+a099);
  a096=(a096+a101);
  a096=(a031*a096);
  a105=(a038*a105);
  a096=(a096+a105);
  a061=(a061+a096);
  a096=(a027*a079);
  a063=(a043*a063);
  a096=(a096+a063);
  a096=(a011*a096);
  a100=(a040*a100);
  a096=(a096+a100);
  a061=(a061+a096);
  a096=(a048*a061);
  a057=(a057+a096);
  a057=(a007*a057);
  a081=(a081+a057);
  a057=(a029*a081);
  a096=(a103+a057);
  a100=(a002*a096);
  a063=(a005*a102);
  a105=(a052*a063);
  a100=(a100+a105);
  a105=(a045*a102);
  a098=(a098-a105);
  a105=(a047*a081);
  a101=(a098-a105);
  a099=(a055*a101);
  a100=(a100+a099);
  a100=(a033*a100);
  a099=(a085*a096);
  a106=(a087*a063);
  a099=(a099+a106);
  a106=(a088*a101);
  a099=(a099+a106);
  a099=(a086*a099);
  a100=(a100+a099);
  a096=(a056*a096);
  a063=(a035*a063);
  a096=(a096+a063);
  a101=(a032*a101);
  a096=(a096+a101);
  a096=(a089*a096);
  a100=(a100+a096);
  if (res[1]!=0) res[1][24]=a100;
  a081=(a018*a081);
  a081=(a051-a081);
  a100=(a010*a102);
  a096=(a081-a100);
  a101=(a002*a096);
  a098=(a098+a105);
  a105=(a052*a098);
  a101=(a101+a105);
  a105=(a006*a079);
  a063=(a044*a102);
  a063=(a105-a063);
  a099=(a055*a063);
  a101=(a101-a099);
  a101=(a076*a101);
  a099=(a085*a096);
  a106=(a087*a098);
  a099=(a099+a106);
  a106=(a088*a063);
  a099=(a099-a106);
  a099=(a082*a099);
  a101=(a101+a099);
  a096=(a056*a096);
  a098=(a035*a098);
  a096=(a096+a098);
  a063=(a032*a063);
  a096=(a096-a063);
  a096=(a094*a096);
  a101=(a101+a096);
  if (res[1]!=0) res[1][25]=a101;
  a103=(a103-a057);
  a057=(a052*a103);
  a102=(a008*a102);
  a105=(a105-a102);
  a102=(a002*a105);
  a057=(a057-a102);
  a100=(a100+a081);
  a081=(a055*a100);
  a057=(a057-a081);
  a057=(a080*a057);
  a081=(a087*a103);
  a102=(a085*a105);
  a081=(a081-a102);
  a102=(a088*a100);
  a081=(a081-a102);
  a081=(a078*a081);
  a057=(a057+a081);
  a103=(a035*a103);
  a105=(a056*a105);
  a103=(a103-a105);
  a100=(a032*a100);
  a103=(a103-a100);
  a103=(a068*a103);
  a057=(a057+a103);
  if (res[1]!=0) res[1][26]=a057;
  a061=(a061-a092);
  a061=(a061/a071);
  a066=(a070*a066);
  a066=(a009*a066);
  a061=(a061+a066);
  a066=(a010*a061);
  a092=(a066-a083);
  a092=(a049*a092);
  a057=(a064*a061);
  a067=(a091*a067);
  a057=(a057+a067);
  a103=(a077*a057);
  a092=(a092+a103);
  a103=(a008*a061);
  a079=(a091*a079);
  a103=(a103+a079);
  a103=(a072*a103);
  a092=(a092-a103);
  if (res[1]!=0) res[1][27]=a092;
  a092=(a045*a061);
  a092=(a092+a069);
  a069=(a049*a092);
  a103=(a005*a061);
  a103=(a077*a103);
  a069=(a069-a103);
  a057=(a072*a057);
  a069=(a069+a057);
  if (res[1]!=0) res[1][28]=a069;
  a092=(a077*a092);
  a061=(a044*a061);
  a061=(a061+a079);
  a061=(a049*a061);
  a092=(a092-a061);
  a066=(a066-a095);
  a066=(a072*a066);
  a092=(a092+a066);
  if (res[1]!=0) res[1][29]=a092;
  a097=(a097*a012);
  a004=(a004*a097);
  a016=(a016*a004);
  a017=(a017*a097);
  a020=(a020*a097);
  a020=(a058*a020);
  a053=(a053*a004);
  a019=(a019*a053);
  a020=(a020+a019);
  a017=(a017+a020);
  a023=(a023*a097);
  a026=(a026*a097);
  a026=(a058*a026);
  a025=(a025*a053);
  a026=(a026+a025);
  a023=(a023+a026);
  a023=(a031*a023);
  a073=(a073*a053);
  a021=(a021*a073);
  a023=(a023+a021);
  a017=(a017+a023);
  a028=(a028*a097);
  a030=(a030*a053);
  a028=(a028+a030);
  a028=(a011*a028);
  a075=(a075*a073);
  a024=(a024*a075);
  a028=(a028+a024);
  a017=(a017+a028);
  a028=(a048*a017);
  a016=(a016+a028);
  a065=(a065*a016);
  a065=(a000*a065);
  a028=(a045*a065);
  a104=(a104-a028);
  a050=(a050*a016);
  a046=(a046*a004);
  a034=(a034*a097);
  a037=(a037*a097);
  a037=(a058*a037);
  a036=(a036*a053);
  a037=(a037+a036);
  a034=(a034+a037);
  a039=(a039*a097);
  a042=(a042*a097);
  a058=(a058*a042);
  a041=(a041*a053);
  a058=(a058+a041);
  a039=(a039+a058);
  a031=(a031*a039);
  a038=(a038*a073);
  a031=(a031+a038);
  a034=(a034+a031);
  a027=(a027*a097);
  a043=(a043*a053);
  a027=(a027+a043);
  a011=(a011*a027);
  a040=(a040*a075);
  a011=(a011+a040);
  a034=(a034+a011);
  a048=(a048*a034);
  a046=(a046+a048);
  a007=(a007*a046);
  a050=(a050+a007);
  a007=(a047*a050);
  a046=(a104-a007);
  a048=(a055*a046);
  a011=(a064*a065);
  a040=(a029*a050);
  a051=(a051-a040);
  a040=(a011+a051);
  a075=(a002*a040);
  a006=(a006*a097);
  a027=(a005*a065);
  a027=(a006-a027);
  a043=(a052*a027);
  a075=(a075+a043);
  a048=(a048-a075);
  a048=(a033*a048);
  a075=(a088*a046);
  a043=(a085*a040);
  a053=(a087*a027);
  a043=(a043+a053);
  a075=(a075-a043);
  a075=(a086*a075);
  a048=(a048+a075);
  a046=(a032*a046);
  a040=(a056*a040);
  a027=(a035*a027);
  a040=(a040+a027);
  a046=(a046-a040);
  a046=(a089*a046);
  a048=(a048+a046);
  if (res[1]!=0) res[1][30]=a048;
  a048=(a010*a065);
  a062=(a062-a048);
  a050=(a018*a050);
  a048=(a062-a050);
  a046=(a002*a048);
  a104=(a104+a007);
  a007=(a052*a104);
  a046=(a046+a007);
  a007=(a044*a065);
  a040=(a055*a007);
  a046=(a046+a040);
  a046=(a076*a046);
  a040=(a085*a048);
  a027=(a087*a104);
  a040=(a040+a027);
  a027=(a088*a007);
  a040=(a040+a027);
  a040=(a082*a040);
  a046=(a046+a040);
  a048=(a056*a048);
  a104=(a035*a104);
  a048=(a048+a104);
  a007=(a032*a007);
  a048=(a048+a007);
  a048=(a094*a048);
  a046=(a046+a048);
  if (res[1]!=0) res[1][31]=a046;
  a051=(a051-a011);
  a011=(a052*a051);
  a065=(a008*a065);
  a006=(a006-a065);
  a065=(a002*a006);
  a011=(a011-a065);
  a062=(a062+a050);
  a050=(a055*a062);
  a011=(a011+a050);
  a011=(a080*a011);
  a050=(a087*a051);
  a065=(a085*a006);
  a050=(a050-a065);
  a065=(a088*a062);
  a050=(a050+a065);
  a050=(a078*a050);
  a011=(a011+a050);
  a051=(a035*a051);
  a006=(a056*a006);
  a051=(a051-a006);
  a062=(a032*a062);
  a051=(a051+a062);
  a051=(a068*a051);
  a011=(a011+a051);
  if (res[1]!=0) res[1][32]=a011;
  a034=(a034-a017);
  a034=(a034/a071);
  a070=(a070*a016);
  a009=(a009*a070);
  a034=(a034+a009);
  a009=(a010*a034);
  a009=(a009+a067);
  a067=(a049*a009);
  a070=(a064*a034);
  a095=(a070-a095);
  a095=(a077*a095);
  a067=(a067+a095);
  a095=(a008*a034);
  a097=(a091*a097);
  a095=(a095+a097);
  a095=(a072*a095);
  a067=(a067-a095);
  if (res[1]!=0) res[1][33]=a067;
  a067=(a045*a034);
  a067=(a067+a001);
  a001=(a049*a067);
  a095=(a005*a034);
  a095=(a095+a097);
  a095=(a077*a095);
  a001=(a001-a095);
  a070=(a070-a083);
  a070=(a072*a070);
  a001=(a001+a070);
  if (res[1]!=0) res[1][34]=a001;
  a077=(a077*a067);
  a034=(a044*a034);
  a049=(a049*a034);
  a077=(a077-a049);
  a072=(a072*a009);
  a077=(a077+a072);
  if (res[1]!=0) res[1][35]=a077;
  if (res[1]!=0) res[1][36]=a022;
  if (res[1]!=0) res[1][37]=a022;
  if (res[1]!=0) res[1][38]=a022;
  a008=(a091*a008);
  a008=(a003-a008);
  if (res[1]!=0) res[1][39]=a008;
  a064=(a091*a064);
  a008=(a000*a029);
  a008=(a064-a008);
  if (res[1]!=0) res[1][40]=a008;
  a010=(a091*a010);
  a008=-5.0000000000000000e-01;
  a077=(a008*a018);
  a077=(a010-a077);
  if (res[1]!=0) res[1][41]=a077;
  if (res[1]!=0) res[1][42]=a022;
  if (res[1]!=0) res[1][43]=a022;
  if (res[1]!=0) res[1][44]=a022;
  a029=(a008*a029);
  a064=(a064-a029);
  if (res[1]!=0) res[1][45]=a064;
  a005=(a091*a005);
  a005=(a003-a005);
  if (res[1]!=0) res[1][46]=a005;
  a045=(a091*a045);
  a005=(a000*a047);
  a005=(a045-a005);
  if (res[1]!=0) res[1][47]=a005;
  if (res[1]!=0) res[1][48]=a022;
  if (res[1]!=0) res[1][49]=a022;
  if (res[1]!=0) res[1][50]=a022;
  a000=(a000*a018);
  a010=(a010-a000);
  if (res[1]!=0) res[1][51]=a010;
  a008=(a008*a047);
  a045=(a045-a008);
  if (res[1]!=0) res[1][52]=a045;
  a091=(a091*a044);
  a003=(a003-a091);
  if (res[1]!=0) res[1][53]=a003;
  a003=(a093*a055);
  a091=(a054*a052);
  a003=(a003-a091);
  a003=(a033*a003);
  a091=(a093*a088);
  a044=(a054*a087);
  a091=(a091-a044);
  a091=(a086*a091);
  a003=(a003+a091);
  a091=(a093*a032);
  a044=(a054*a035);
  a091=(a091-a044);
  a091=(a089*a091);
  a003=(a003+a091);
  if (res[2]!=0) res[2][0]=a003;
  a003=(a059*a055);
  a091=(a060*a052);
  a003=(a003-a091);
  a003=(a076*a003);
  a091=(a059*a088);
  a044=(a060*a087);
  a091=(a091-a044);
  a091=(a082*a091);
  a003=(a003+a091);
  a091=(a059*a032);
  a044=(a060*a035);
  a091=(a091-a044);
  a091=(a094*a091);
  a003=(a003+a091);
  if (res[2]!=0) res[2][1]=a003;
  a003=(a074*a055);
  a091=(a014*a052);
  a003=(a003-a091);
  a003=(a080*a003);
  a091=(a074*a088);
  a044=(a014*a087);
  a091=(a091-a044);
  a091=(a078*a091);
  a003=(a003+a091);
  a091=(a074*a032);
  a044=(a014*a035);
  a091=(a091-a044);
  a091=(a068*a091);
  a003=(a003+a091);
  if (res[2]!=0) res[2][2]=a003;
  if (res[2]!=0) res[2][3]=a022;
  if (res[2]!=0) res[2][4]=a022;
  if (res[2]!=0) res[2][5]=a022;
  a003=(a054*a002);
  a091=(a084*a055);
  a003=(a003-a091);
  a003=(a033*a003);
  a091=(a054*a085);
  a044=(a084*a088);
  a091=(a091-a044);
  a091=(a086*a091);
  a003=(a003+a091);
  a054=(a054*a056);
  a091=(a084*a032);
  a054=(a054-a091);
  a054=(a089*a054);
  a003=(a003+a054);
  if (res[2]!=0) res[2][6]=a003;
  a003=(a060*a002);
  a054=(a015*a055);
  a003=(a003-a054);
  a003=(a076*a003);
  a054=(a060*a085);
  a091=(a015*a088);
  a054=(a054-a091);
  a054=(a082*a054);
  a003=(a003+a054);
  a060=(a060*a056);
  a054=(a015*a032);
  a060=(a060-a054);
  a060=(a094*a060);
  a003=(a003+a060);
  if (res[2]!=0) res[2][7]=a003;
  a003=(a014*a002);
  a055=(a013*a055);
  a003=(a003-a055);
  a003=(a080*a003);
  a055=(a014*a085);
  a088=(a013*a088);
  a055=(a055-a088);
  a055=(a078*a055);
  a003=(a003+a055);
  a014=(a014*a056);
  a032=(a013*a032);
  a014=(a014-a032);
  a014=(a068*a014);
  a003=(a003+a014);
  if (res[2]!=0) res[2][8]=a003;
  if (res[2]!=0) res[2][9]=a022;
  if (res[2]!=0) res[2][10]=a022;
  if (res[2]!=0) res[2][11]=a022;
  a003=(a084*a052);
  a014=(a093*a002);
  a003=(a003-a014);
  a033=(a033*a003);
  a003=(a084*a087);
  a014=(a093*a085);
  a003=(a003-a014);
  a086=(a086*a003);
  a033=(a033+a086);
  a084=(a084*a035);
  a093=(a093*a056);
  a084=(a084-a093);
  a089=(a089*a084);
  a033=(a033+a089);
  if (res[2]!=0) res[2][12]=a033;
  a033=(a015*a052);
  a089=(a059*a002);
  a033=(a033-a089);
  a076=(a076*a033);
  a033=(a015*a087);
  a089=(a059*a085);
  a033=(a033-a089);
  a082=(a082*a033);
  a076=(a076+a082);
  a015=(a015*a035);
  a059=(a059*a056);
  a015=(a015-a059);
  a094=(a094*a015);
  a076=(a076+a094);
  if (res[2]!=0) res[2][13]=a076;
  a052=(a013*a052);
  a002=(a074*a002);
  a052=(a052-a002);
  a080=(a080*a052);
  a087=(a013*a087);
  a085=(a074*a085);
  a087=(a087-a085);
  a078=(a078*a087);
  a080=(a080+a078);
  a013=(a013*a035);
  a074=(a074*a056);
  a013=(a013-a074);
  a068=(a068*a013);
  a080=(a080+a068);
  if (res[2]!=0) res[2][14]=a080;
  if (res[2]!=0) res[2][15]=a022;
  if (res[2]!=0) res[2][16]=a022;
  if (res[2]!=0) res[2][17]=a022;
  if (res[2]!=0) res[2][18]=a022;
  if (res[2]!=0) res[2][19]=a022;
  if (res[2]!=0) res[2][20]=a022;
  if (res[2]!=0) res[2][21]=a022;
  if (res[2]!=0) res[2][22]=a022;
  if (res[2]!=0) res[2][23]=a022;
  if (res[2]!=0) res[2][24]=a022;
  if (res[2]!=0) res[2][25]=a022;
  if (res[2]!=0) res[2][26]=a022;
  if (res[2]!=0) res[2][27]=a022;
  if (res[2]!=0) res[2][28]=a022;
  if (res[2]!=0) res[2][29]=a022;
  if (res[2]!=0) res[2][30]=a022;
  if (res[2]!=0) res[2][31]=a022;
  if (res[2]!=0) res[2][32]=a022;
  if (res[2]!=0) res[2][33]=a022;
  if (res[2]!=0) res[2][34]=a022;
  if (res[2]!=0) res[2][35]=a022;
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
#define HPGEN_W 17
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

HPGEN_EXPORT const char* hpgen_hash(void) { return "ffef12b8e3d5ed599c071aa73ae876759b0a16495812b0c3b2d6fbb4a47bc601"; }

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
#define HPGEN_RESIDUAL_SZ_W 135
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
#define HPGEN_RESIDUAL_JACOBIAN_SZ_W 355
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

/* margin(z[9], h[1]) -> (m[1]) */
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

/* chart_point(z[9], g[9], h[1], theta[1]) -> (g_theta[9]) */
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

/* record(g[9], p[3], xi[3]) -> (row[17]) */
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
#define HPGEN_STEP_PARTIALS_SZ_W 109
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
