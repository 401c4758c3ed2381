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
  casadi_real a132, a133, a134, a135, a136, a137, a138, a139, a140, a141, a142, a143;
  casadi_real a144, a145, a146, a147, a148, a149, a150, a151, a152, a153, a154, a155;
  casadi_real a156, a157, a158, a159, a160, a161, a162, a163, a164, a165, a166, a167;
  casadi_real a168, a169, a170;
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
  a068=(2.*a070);
  a079=(a018*a002);
  a068=(a068*a079);
  a080=arg[0]? arg[0][8] : 0;
  a081=(a002*a080);
  a081=(a056*a081);
  a082=(a058*a081);
  a083=(a048*a072);
  a084=-5.0000000000000000e-01;
  a085=(a084*a011);
  a086=(a083-a085);
  a087=arg[0]? arg[0][7] : 0;
  a088=(a002*a087);
  a088=(a056*a088);
  a089=(a086*a088);
  a082=(a082+a089);
  a089=(a048*a008);
  a089=(a050-a089);
  a090=arg[0]? arg[0][6] : 0;
  a091=(a002*a090);
  a091=(a056*a091);
  a092=(a089*a091);
  a082=(a082+a092);
  a068=(a068-a082);
  a082=(a056*a002);
  a068=(a068/a082);
  a064=(a064*a068);
  a092=(a062*a004);
  a093=(a007*a011);
  a094=(a060*a093);
  a095=(a092+a094);
  a073=(a073-a071);
  a071=(a073*a067);
  a012=(a012+a005);
  a005=(a060*a012);
  a005=(a050-a005);
  a096=(a005*a075);
  a071=(a071+a096);
  a096=(a095*a077);
  a071=(a071+a096);
  a096=(2.*a071);
  a097=1.2500000000000000e+00;
  a097=(a097*a002);
  a096=(a096*a097);
  a098=(a048*a093);
  a099=(a084*a004);
  a100=(a098-a099);
  a101=(a100*a081);
  a102=(a048*a012);
  a102=(a050-a102);
  a103=(a102*a088);
  a101=(a101+a103);
  a103=(a056*a011);
  a104=(a083-a103);
  a105=(a104*a091);
  a101=(a101+a105);
  a096=(a096-a101);
  a096=(a096/a082);
  a095=(a095*a096);
  a064=(a064+a095);
  a060=(a060*a009);
  a060=(a050-a060);
  a063=(a063+a061);
  a061=(a063*a067);
  a094=(a094-a092);
  a092=(a094*a075);
  a061=(a061+a092);
  a092=(a060*a077);
  a061=(a061+a092);
  a092=(2.*a061);
  a095=1.5000000000000000e+00;
  a095=(a095*a002);
  a092=(a092*a095);
  a101=(a048*a009);
  a101=(a050-a101);
  a105=(a101*a081);
  a106=(a056*a004);
  a107=(a098-a106);
  a108=(a107*a088);
  a105=(a105+a108);
  a108=(a084*a007);
  a109=(a055-a108);
  a110=(a109*a091);
  a105=(a105+a110);
  a092=(a092-a105);
  a092=(a092/a082);
  a060=(a060*a092);
  a064=(a064+a060);
  a060=(a059*a064);
  a105=-3.2320508075688776e+00;
  a110=(a002*a069);
  a111=casadi_sq(a110);
  a112=(a002*a076);
  a113=casadi_sq(a112);
  a114=(a111+a113);
  a115=(a002*a078);
  a116=casadi_sq(a115);
  a117=(a114+a116);
  a118=(a033*a117);
  a119=(a036*a117);
  a119=(a035+a119);
  a120=(a018*a117);
  a121=casadi_sq(a120);
  a122=(a119*a121);
  a118=(a118+a122);
  a122=(a039*a117);
  a122=(a038+a122);
  a123=(a042*a117);
  a123=(a041+a123);
  a124=(a123*a121);
  a122=(a122+a124);
  a124=casadi_sq(a121);
  a125=(a122*a124);
  a118=(a118+a125);
  a125=(a045*a117);
  a125=(a044+a125);
  a126=(a047*a121);
  a125=(a125+a126);
  a126=casadi_sq(a124);
  a127=(a125*a126);
  a118=(a118+a127);
  a127=(a051+a118);
  a128=(a120*a127);
  a128=(a050-a128);
  a129=(a001*a117);
  a130=(a016*a117);
  a130=(a015+a130);
  a131=(a130*a121);
  a129=(a129+a131);
  a131=(a022*a117);
  a131=(a021+a131);
  a132=(a025*a117);
  a132=(a024+a132);
  a133=(a132*a121);
  a131=(a131+a133);
  a133=(a131*a124);
  a129=(a129+a133);
  a133=(a029*a117);
  a133=(a028+a133);
  a134=(a031*a121);
  a133=(a133+a134);
  a134=(a133*a126);
  a129=(a129+a134);
  a134=(a056+a129);
  a135=(a128*a134);
  a135=(a127+a135);
  a135=(a018*a135);
  a136=(a110*a115);
  a137=(a135*a136);
  a138=casadi_sq(a128);
  a138=(a056*a138);
  a139=(a138*a112);
  a140=(a137-a139);
  a113=(a113+a116);
  a141=(a135*a113);
  a141=(a050-a141);
  a142=-6.4641016151377553e+00;
  a003=(a142*a003);
  a069=(a066*a069);
  a003=(a003+a069);
  a069=(a141*a003);
  a143=(a138*a115);
  a144=(a110*a112);
  a145=(a135*a144);
  a146=(a143+a145);
  a006=(a142*a006);
  a076=(a066*a076);
  a006=(a006+a076);
  a076=(a146*a006);
  a069=(a069+a076);
  a142=(a142*a010);
  a066=(a066*a078);
  a142=(a142+a066);
  a066=(a140*a142);
  a069=(a069+a066);
  a066=(2.*a069);
  a066=(a066*a079);
  a129=(a129-a118);
  a129=(a000+a129);
  a118=(a049*a128);
  a129=(a129/a118);
  a079=(a129*a136);
  a078=(a056*a112);
  a010=(a079-a078);
  a076=(a010*a081);
  a066=(a066-a076);
  a076=(a129*a144);
  a147=(a084*a115);
  a148=(a076-a147);
  a149=(a148*a088);
  a066=(a066-a149);
  a149=(a129*a113);
  a149=(a050-a149);
  a150=(a149*a091);
  a066=(a066-a150);
  a066=(a066/a082);
  a140=(a140*a066);
  a150=(a138*a110);
  a151=(a112*a115);
  a152=(a135*a151);
  a153=(a150+a152);
  a145=(a145-a143);
  a143=(a145*a003);
  a116=(a116+a111);
  a111=(a135*a116);
  a111=(a050-a111);
  a154=(a111*a006);
  a143=(a143+a154);
  a154=(a153*a142);
  a143=(a143+a154);
  a154=(2.*a143);
  a154=(a154*a097);
  a097=(a129*a151);
  a155=(a084*a110);
  a156=(a097-a155);
  a157=(a156*a081);
  a154=(a154-a157);
  a157=(a129*a116);
  a157=(a050-a157);
  a158=(a157*a088);
  a154=(a154-a158);
  a158=(a056*a115);
  a159=(a076-a158);
  a160=(a159*a091);
  a154=(a154-a160);
  a154=(a154/a082);
  a153=(a153*a154);
  a140=(a140+a153);
  a135=(a135*a114);
  a135=(a050-a135);
  a139=(a139+a137);
  a137=(a139*a003);
  a152=(a152-a150);
  a150=(a152*a006);
  a137=(a137+a150);
  a150=(a135*a142);
  a137=(a137+a150);
  a150=(2.*a137);
  a150=(a150*a095);
  a095=(a129*a114);
  a095=(a050-a095);
  a153=(a095*a081);
  a150=(a150-a153);
  a153=(a056*a110);
  a160=(a097-a153);
  a161=(a160*a088);
  a150=(a150-a161);
  a161=(a084*a112);
  a162=(a079-a161);
  a163=(a162*a091);
  a150=(a150-a163);
  a150=(a150/a082);
  a135=(a135*a150);
  a140=(a140+a135);
  a135=(a105*a140);
  a060=(a060+a135);
  a135=5.3867513459481287e-01;
  a163=2.3205080756887719e-01;
  a064=(a163*a064);
  a140=(a059*a140);
  a064=(a064+a140);
  a140=(a002*a064);
  a164=(a135*a140);
  a164=(a081+a164);
  a165=(a002*a060);
  a166=(a018*a165);
  a164=(a164+a166);
  a166=(a071*a164);
  a167=(a048*a166);
  a074=(a074*a068);
  a005=(a005*a096);
  a074=(a074+a005);
  a094=(a094*a092);
  a074=(a074+a094);
  a094=(a163*a074);
  a146=(a146*a066);
  a111=(a111*a154);
  a146=(a146+a111);
  a152=(a152*a150);
  a146=(a146+a152);
  a152=(a059*a146);
  a094=(a094+a152);
  a152=(a002*a094);
  a111=(a135*a152);
  a111=(a088+a111);
  a074=(a059*a074);
  a146=(a105*a146);
  a074=(a074+a146);
  a146=(a002*a074);
  a005=(a018*a146);
  a111=(a111+a005);
  a005=(a061*a111);
  a168=(a048*a005);
  a167=(a167+a168);
  a168=(a007*a167);
  a060=(a060-a168);
  a168=(a070*a111);
  a169=(a084*a168);
  a060=(a060+a169);
  a169=(a070*a164);
  a170=(a048*a169);
  a065=(a065*a068);
  a073=(a073*a096);
  a065=(a065+a073);
  a063=(a063*a092);
  a065=(a065+a063);
  a163=(a163*a065);
  a141=(a141*a066);
  a145=(a145*a154);
  a141=(a141+a145);
  a139=(a139*a150);
  a141=(a141+a139);
  a139=(a059*a141);
  a163=(a163+a139);
  a139=(a002*a163);
  a135=(a135*a139);
  a135=(a091+a135);
  a059=(a059*a065);
  a105=(a105*a141);
  a059=(a059+a105);
  a105=(a002*a059);
  a141=(a018*a105);
  a135=(a135+a141);
  a141=(a061*a135);
  a065=(a048*a141);
  a170=(a170+a065);
  a065=(a004*a170);
  a060=(a060-a065);
  a065=(a071*a135);
  a150=(a056*a065);
  a060=(a060+a150);
  a150=(2.*a011);
  a071=(a071*a111);
  a111=(a048*a071);
  a070=(a070*a135);
  a135=(a048*a070);
  a145=(a111+a135);
  a145=(a150*a145);
  a060=(a060+a145);
  a145=(a048/a053);
  a061=(a061*a164);
  a009=(a009*a061);
  a164=(a093*a166);
  a009=(a009-a164);
  a164=(a054*a169);
  a009=(a009-a164);
  a164=(a093*a005);
  a009=(a009-a164);
  a071=(a012*a071);
  a009=(a009+a071);
  a071=(a072*a168);
  a009=(a009-a071);
  a071=(a054*a141);
  a009=(a009-a071);
  a071=(a072*a065);
  a009=(a009-a071);
  a070=(a008*a070);
  a009=(a009+a070);
  a145=(a145*a009);
  a145=(a049*a145);
  a070=(a019*a145);
  a009=(a009/a053);
  a070=(a070-a009);
  a053=(a032*a070);
  a071=(a045*a053);
  a164=(a027*a070);
  a154=(a020*a164);
  a154=(a042*a154);
  a071=(a071+a154);
  a154=(a039*a164);
  a071=(a071+a154);
  a154=(a020*a070);
  a154=(a036*a154);
  a071=(a071+a154);
  a154=(a033*a070);
  a071=(a071+a154);
  a032=(a032*a009);
  a154=(a029*a032);
  a071=(a071+a154);
  a154=(a027*a009);
  a066=(a020*a154);
  a066=(a025*a066);
  a071=(a071+a066);
  a066=(a022*a154);
  a071=(a071+a066);
  a034=(a034*a145);
  a013=(a056*a013);
  a053=(a047*a053);
  a145=(2.*a020);
  a027=(2.*a027);
  a046=(a046*a070);
  a046=(a027*a046);
  a040=(a040*a070);
  a046=(a046+a040);
  a046=(a145*a046);
  a053=(a053+a046);
  a043=(a043*a164);
  a053=(a053+a043);
  a037=(a037*a070);
  a053=(a053+a037);
  a053=(a013*a053);
  a034=(a034+a053);
  a032=(a031*a032);
  a030=(a030*a009);
  a027=(a027*a030);
  a023=(a023*a009);
  a027=(a027+a023);
  a145=(a145*a027);
  a032=(a032+a145);
  a026=(a026*a154);
  a032=(a032+a026);
  a017=(a017*a009);
  a032=(a032+a017);
  a013=(a013*a032);
  a034=(a034+a013);
  a034=(a018*a034);
  a071=(a071+a034);
  a020=(a020*a009);
  a020=(a016*a020);
  a071=(a071+a020);
  a009=(a001*a009);
  a071=(a071+a009);
  a150=(a150*a071);
  a060=(a060+a150);
  a058=(a058*a060);
  a169=(a056*a169);
  a169=(a169+a074);
  a167=(a011*a167);
  a169=(a169-a167);
  a141=(a084*a141);
  a169=(a169+a141);
  a168=(a048*a168);
  a065=(a048*a065);
  a168=(a168+a065);
  a065=(a004*a168);
  a169=(a169-a065);
  a065=(2.*a007);
  a048=(a048*a061);
  a135=(a048+a135);
  a135=(a065*a135);
  a169=(a169+a135);
  a065=(a065*a071);
  a169=(a169+a065);
  a086=(a086*a169);
  a058=(a058+a086);
  a166=(a084*a166);
  a005=(a056*a005);
  a166=(a166+a005);
  a005=(2.*a004);
  a048=(a048+a111);
  a048=(a005*a048);
  a166=(a166+a048);
  a166=(a166+a059);
  a170=(a011*a170);
  a166=(a166-a170);
  a168=(a007*a168);
  a166=(a166-a168);
  a005=(a005*a071);
  a166=(a166+a005);
  a089=(a089*a166);
  a058=(a058+a089);
  a005=arg[1]? arg[1][2] : 0;
  a072=(a062*a072);
  a019=(a019*a014);
  a019=(a050-a019);
  a052=(a052*a019);
  a011=(a052*a011);
  a019=(a072-a011);
  a019=(a005*a019);
  a014=arg[1]? arg[1][5] : 0;
  a012=(a062*a012);
  a012=(a050-a012);
  a012=(a014*a012);
  a019=(a019+a012);
  a012=arg[1]? arg[1][8] : 0;
  a004=(a052*a004);
  a093=(a062*a093);
  a004=(a004+a093);
  a004=(a012*a004);
  a019=(a019+a004);
  a019=(a019*a082);
  a058=(a058+a019);
  a058=(a058/a002);
  if (res[0]!=0) res[0][0]=a058;
  a100=(a100*a060);
  a102=(a102*a169);
  a100=(a100+a102);
  a104=(a104*a166);
  a100=(a100+a104);
  a008=(a062*a008);
  a008=(a050-a008);
  a008=(a005*a008);
  a011=(a011+a072);
  a011=(a014*a011);
  a008=(a008+a011);
  a062=(a062*a054);
  a052=(a052*a007);
  a062=(a062-a052);
  a062=(a012*a062);
  a008=(a008+a062);
  a008=(a008*a082);
  a100=(a100-a008);
  a100=(a100/a002);
  if (res[0]!=0) res[0][1]=a100;
  a101=(a101*a060);
  a107=(a107*a169);
  a107=(a101+a107);
  a109=(a109*a166);
  a107=(a107+a109);
  a107=(a107/a002);
  if (res[0]!=0) res[0][2]=a107;
  a107=(a138*a144);
  a134=(a120*a134);
  a134=(a050-a134);
  a128=(a128*a134);
  a134=(a128*a115);
  a109=(a107-a134);
  a109=(a005*a109);
  a100=(a138*a116);
  a100=(a050-a100);
  a100=(a014*a100);
  a109=(a109+a100);
  a100=(a128*a110);
  a008=(a138*a151);
  a100=(a100+a008);
  a100=(a012*a100);
  a109=(a109+a100);
  a109=(a109*a082);
  a140=(a018*a140);
  a081=(a081+a140);
  a140=-3.8675134594812879e-02;
  a165=(a140*a165);
  a081=(a081+a165);
  a165=(a143*a081);
  a100=(a129*a165);
  a152=(a018*a152);
  a088=(a088+a152);
  a146=(a140*a146);
  a088=(a088+a146);
  a146=(a137*a088);
  a152=(a129*a146);
  a100=(a100+a152);
  a152=(a112*a100);
  a064=(a064-a152);
  a152=(a069*a088);
  a008=(a084*a152);
  a064=(a064+a008);
  a008=(a069*a081);
  a062=(a129*a008);
  a139=(a018*a139);
  a091=(a091+a139);
  a140=(a140*a105);
  a091=(a091+a140);
  a140=(a137*a091);
  a105=(a129*a140);
  a062=(a062+a105);
  a105=(a110*a062);
  a064=(a064-a105);
  a105=(a143*a091);
  a139=(a056*a105);
  a064=(a064+a139);
  a139=(2.*a115);
  a143=(a143*a088);
  a088=(a129*a143);
  a069=(a069*a091);
  a091=(a129*a069);
  a052=(a088+a091);
  a052=(a139*a052);
  a064=(a064+a052);
  a052=(a129/a118);
  a137=(a137*a081);
  a114=(a114*a137);
  a081=(a151*a165);
  a114=(a114-a081);
  a081=(a136*a008);
  a114=(a114-a081);
  a151=(a151*a146);
  a114=(a114-a151);
  a116=(a116*a143);
  a114=(a114+a116);
  a116=(a144*a152);
  a114=(a114-a116);
  a116=(a136*a140);
  a114=(a114-a116);
  a144=(a144*a105);
  a114=(a114-a144);
  a069=(a113*a069);
  a114=(a114+a069);
  a052=(a052*a114);
  a052=(a049*a052);
  a120=(a120*a052);
  a114=(a114/a118);
  a120=(a120-a114);
  a118=(a126*a120);
  a069=(a045*a118);
  a144=(a124*a120);
  a116=(a121*a144);
  a116=(a042*a116);
  a069=(a069+a116);
  a116=(a039*a144);
  a069=(a069+a116);
  a116=(a121*a120);
  a116=(a036*a116);
  a069=(a069+a116);
  a116=(a033*a120);
  a069=(a069+a116);
  a126=(a126*a114);
  a116=(a029*a126);
  a069=(a069+a116);
  a116=(a124*a114);
  a143=(a121*a116);
  a143=(a025*a143);
  a069=(a069+a143);
  a143=(a022*a116);
  a069=(a069+a143);
  a127=(a127*a052);
  a117=(a056*a117);
  a118=(a047*a118);
  a052=(2.*a121);
  a124=(2.*a124);
  a125=(a125*a120);
  a125=(a124*a125);
  a122=(a122*a120);
  a125=(a125+a122);
  a125=(a052*a125);
  a118=(a118+a125);
  a123=(a123*a144);
  a118=(a118+a123);
  a119=(a119*a120);
  a118=(a118+a119);
  a118=(a117*a118);
  a127=(a127+a118);
  a126=(a031*a126);
  a133=(a133*a114);
  a124=(a124*a133);
  a131=(a131*a114);
  a124=(a124+a131);
  a052=(a052*a124);
  a126=(a126+a052);
  a132=(a132*a116);
  a126=(a126+a132);
  a130=(a130*a114);
  a126=(a126+a130);
  a117=(a117*a126);
  a127=(a127+a117);
  a127=(a018*a127);
  a069=(a069+a127);
  a121=(a121*a114);
  a121=(a016*a121);
  a069=(a069+a121);
  a114=(a001*a114);
  a069=(a069+a114);
  a139=(a139*a069);
  a064=(a064+a139);
  a010=(a010*a064);
  a109=(a109+a010);
  a008=(a056*a008);
  a094=(a094+a008);
  a100=(a115*a100);
  a094=(a094-a100);
  a140=(a084*a140);
  a094=(a094+a140);
  a152=(a129*a152);
  a105=(a129*a105);
  a152=(a152+a105);
  a105=(a110*a152);
  a094=(a094-a105);
  a105=(2.*a112);
  a129=(a129*a137);
  a091=(a129+a091);
  a091=(a105*a091);
  a094=(a094+a091);
  a105=(a105*a069);
  a094=(a094+a105);
  a148=(a148*a094);
  a109=(a109+a148);
  a165=(a084*a165);
  a163=(a163+a165);
  a146=(a056*a146);
  a163=(a163+a146);
  a110=(2.*a110);
  a129=(a129+a088);
  a129=(a110*a129);
  a163=(a163+a129);
  a115=(a115*a062);
  a163=(a163-a115);
  a152=(a112*a152);
  a163=(a163-a152);
  a110=(a110*a069);
  a163=(a163+a110);
  a149=(a149*a163);
  a109=(a109+a149);
  a109=(a109/a002);
  if (res[0]!=0) res[0][3]=a109;
  a156=(a156*a064);
  a113=(a138*a113);
  a113=(a050-a113);
  a005=(a005*a113);
  a134=(a134+a107);
  a014=(a014*a134);
  a005=(a005+a014);
  a138=(a138*a136);
  a128=(a128*a112);
  a138=(a138-a128);
  a012=(a012*a138);
  a005=(a005+a012);
  a005=(a005*a082);
  a156=(a156-a005);
  a157=(a157*a094);
  a156=(a156+a157);
  a159=(a159*a163);
  a156=(a156+a159);
  a156=(a156/a002);
  if (res[0]!=0) res[0][4]=a156;
  a095=(a095*a064);
  a160=(a160*a094);
  a160=(a095+a160);
  a162=(a162*a163);
  a160=(a160+a162);
  a160=(a160/a002);
  if (res[0]!=0) res[0][5]=a160;
  a160=arg[2]? arg[2][0] : 0;
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
  a162=casadi_sq(a075);
  a156=(a003+a162);
  a077=(a056*a077);
  a142=(a056*a142);
  a077=(a077+a142);
  a002=(a002*a077);
  a077=casadi_sq(a002);
  a142=(a156+a077);
  a001=(a001*a142);
  a016=(a016*a142);
  a015=(a015+a016);
  a018=(a018*a142);
  a016=casadi_sq(a018);
  a015=(a015*a016);
  a001=(a001+a015);
  a022=(a022*a142);
  a021=(a021+a022);
  a025=(a025*a142);
  a024=(a024+a025);
  a024=(a024*a016);
  a021=(a021+a024);
  a024=casadi_sq(a016);
  a021=(a021*a024);
  a001=(a001+a021);
  a029=(a029*a142);
  a028=(a028+a029);
  a031=(a031*a016);
  a028=(a028+a031);
  a031=casadi_sq(a024);
  a028=(a028*a031);
  a001=(a001+a028);
  a033=(a033*a142);
  a036=(a036*a142);
  a035=(a035+a036);
  a035=(a035*a016);
  a033=(a033+a035);
  a039=(a039*a142);
  a038=(a038+a039);
  a042=(a042*a142);
  a041=(a041+a042);
  a041=(a041*a016);
  a038=(a038+a041);
  a038=(a038*a024);
  a033=(a033+a038);
  a045=(a045*a142);
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
  a006=(a006*a080);
  a018=(a084*a002);
  a051=(a067*a075);
  a051=(a000*a051);
  a018=(a018+a051);
  a018=(a018*a087);
  a006=(a006+a018);
  a162=(a162+a077);
  a162=(a000*a162);
  a162=(a050-a162);
  a162=(a162*a090);
  a006=(a006+a162);
  a078=(a078+a079);
  a078=(a078*a064);
  a006=(a006+a078);
  a147=(a147+a076);
  a147=(a147*a094);
  a006=(a006+a147);
  a006=(a006+a149);
  a057=(a057+a055);
  a057=(a057*a060);
  a006=(a006+a057);
  a085=(a085+a083);
  a085=(a085*a169);
  a006=(a006+a085);
  a006=(a006+a089);
  a160=(a160-a006);
  if (res[0]!=0) res[0][6]=a160;
  a160=arg[2]? arg[2][1] : 0;
  a006=(a084*a067);
  a089=(a075*a002);
  a089=(a000*a089);
  a006=(a006+a089);
  a006=(a006*a080);
  a077=(a077+a003);
  a077=(a000*a077);
  a077=(a050-a077);
  a077=(a077*a087);
  a006=(a006+a077);
  a002=(a056*a002);
  a002=(a002+a051);
  a002=(a002*a090);
  a006=(a006+a002);
  a155=(a155+a097);
  a155=(a155*a064);
  a006=(a006+a155);
  a006=(a006+a157);
  a158=(a158+a076);
  a158=(a158*a163);
  a006=(a006+a158);
  a099=(a099+a098);
  a099=(a099*a060);
  a006=(a006+a099);
  a006=(a006+a102);
  a103=(a103+a083);
  a103=(a103*a166);
  a006=(a006+a103);
  a160=(a160-a006);
  if (res[0]!=0) res[0][7]=a160;
  a160=arg[2]? arg[2][2] : 0;
  a000=(a000*a156);
  a050=(a050-a000);
  a050=(a050*a080);
  a056=(a056*a067);
  a056=(a056+a089);
  a056=(a056*a087);
  a050=(a050+a056);
  a084=(a084*a075);
  a084=(a084+a049);
  a084=(a084*a090);
  a050=(a050+a084);
  a050=(a050+a095);
  a153=(a153+a097);
  a153=(a153*a094);
  a050=(a050+a153);
  a161=(a161+a079);
  a161=(a161*a163);
  a050=(a050+a161);
  a050=(a050+a101);
  a106=(a106+a098);
  a106=(a106*a169);
  a050=(a050+a106);
  a108=(a108+a055);
  a108=(a108*a166);
  a050=(a050+a108);
  a160=(a160-a050);
  if (res[0]!=0) res[0][8]=a160;
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
  casadi_real a348, a349, a350, a351, a352, a353, a354, a355, a356, a357, a358, a359;
  casadi_real a360, a361, a362, a363;
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
  a079=(2.*a070);
  a080=(a018*a002);
  a079=(a079*a080);
  a081=arg[0]? arg[0][8] : 0;
  a082=(a002*a081);
  a082=(a056*a082);
  a083=(a058*a082);
  a084=(a048*a072);
  a085=-5.0000000000000000e-01;
  a086=(a085*a011);
  a087=(a084-a086);
  a088=arg[0]? arg[0][7] : 0;
  a089=(a002*a088);
  a089=(a056*a089);
  a090=(a087*a089);
  a083=(a083+a090);
  a090=(a048*a008);
  a090=(a050-a090);
  a091=arg[0]? arg[0][6] : 0;
  a092=(a002*a091);
  a092=(a056*a092);
  a093=(a090*a092);
  a083=(a083+a093);
  a079=(a079-a083);
  a083=(a056*a002);
  a079=(a079/a083);
  a093=(a064*a079);
  a094=(a062*a004);
  a095=(a007*a011);
  a096=(a060*a095);
  a097=(a094+a096);
  a073=(a073-a071);
  a071=(a073*a067);
  a012=(a012+a005);
  a005=(a060*a012);
  a005=(a050-a005);
  a098=(a005*a075);
  a071=(a071+a098);
  a098=(a097*a077);
  a071=(a071+a098);
  a098=(2.*a071);
  a099=1.2500000000000000e+00;
  a099=(a099*a002);
  a098=(a098*a099);
  a100=(a048*a095);
  a101=(a085*a004);
  a102=(a100-a101);
  a103=(a102*a082);
  a104=(a048*a012);
  a104=(a050-a104);
  a105=(a104*a089);
  a103=(a103+a105);
  a105=(a056*a011);
  a106=(a084-a105);
  a107=(a106*a092);
  a103=(a103+a107);
  a098=(a098-a103);
  a098=(a098/a083);
  a103=(a097*a098);
  a093=(a093+a103);
  a103=(a060*a009);
  a103=(a050-a103);
  a063=(a063+a061);
  a061=(a063*a067);
  a096=(a096-a094);
  a094=(a096*a075);
  a061=(a061+a094);
  a094=(a103*a077);
  a061=(a061+a094);
  a094=(2.*a061);
  a107=1.5000000000000000e+00;
  a107=(a107*a002);
  a094=(a094*a107);
  a108=(a048*a009);
  a108=(a050-a108);
  a109=(a108*a082);
  a110=(a056*a004);
  a111=(a100-a110);
  a112=(a111*a089);
  a109=(a109+a112);
  a112=(a085*a007);
  a113=(a055-a112);
  a114=(a113*a092);
  a109=(a109+a114);
  a094=(a094-a109);
  a094=(a094/a083);
  a109=(a103*a094);
  a093=(a093+a109);
  a109=(a059*a093);
  a114=-3.2320508075688776e+00;
  a115=(a002*a069);
  a116=casadi_sq(a115);
  a117=(a002*a076);
  a118=casadi_sq(a117);
  a119=(a116+a118);
  a120=(a002*a078);
  a121=casadi_sq(a120);
  a122=(a119+a121);
  a123=(a033*a122);
  a124=(a036*a122);
  a124=(a035+a124);
  a125=(a018*a122);
  a126=casadi_sq(a125);
  a127=(a124*a126);
  a123=(a123+a127);
  a127=(a039*a122);
  a127=(a038+a127);
  a128=(a042*a122);
  a128=(a041+a128);
  a129=(a128*a126);
  a127=(a127+a129);
  a129=casadi_sq(a126);
  a130=(a127*a129);
  a123=(a123+a130);
  a130=(a045*a122);
  a130=(a044+a130);
  a131=(a047*a126);
  a130=(a130+a131);
  a131=casadi_sq(a129);
  a132=(a130*a131);
  a123=(a123+a132);
  a132=(a051+a123);
  a133=(a125*a132);
  a133=(a050-a133);
  a134=(a001*a122);
  a135=(a016*a122);
  a135=(a015+a135);
  a136=(a135*a126);
  a134=(a134+a136);
  a136=(a022*a122);
  a136=(a021+a136);
  a137=(a025*a122);
  a137=(a024+a137);
  a138=(a137*a126);
  a136=(a136+a138);
  a138=(a136*a129);
  a134=(a134+a138);
  a138=(a029*a122);
  a138=(a028+a138);
  a139=(a031*a126);
  a138=(a138+a139);
  a139=(a138*a131);
  a134=(a134+a139);
  a139=(a056+a134);
  a140=(a133*a139);
  a140=(a132+a140);
  a140=(a018*a140);
  a141=(a115*a120);
  a142=(a140*a141);
  a143=casadi_sq(a133);
  a143=(a056*a143);
  a144=(a143*a117);
  a145=(a142-a144);
  a118=(a118+a121);
  a146=(a140*a118);
  a146=(a050-a146);
  a147=-6.4641016151377553e+00;
  a003=(a147*a003);
  a069=(a066*a069);
  a003=(a003+a069);
  a069=(a146*a003);
  a148=(a143*a120);
  a149=(a115*a117);
  a150=(a140*a149);
  a151=(a148+a150);
  a006=(a147*a006);
  a076=(a066*a076);
  a006=(a006+a076);
  a076=(a151*a006);
  a069=(a069+a076);
  a010=(a147*a010);
  a078=(a066*a078);
  a010=(a010+a078);
  a078=(a145*a010);
  a069=(a069+a078);
  a078=(2.*a069);
  a078=(a078*a080);
  a134=(a134-a123);
  a134=(a000+a134);
  a123=(a049*a133);
  a134=(a134/a123);
  a076=(a134*a141);
  a152=(a056*a117);
  a153=(a076-a152);
  a154=(a153*a082);
  a078=(a078-a154);
  a154=(a134*a149);
  a155=(a085*a120);
  a156=(a154-a155);
  a157=(a156*a089);
  a078=(a078-a157);
  a157=(a134*a118);
  a157=(a050-a157);
  a158=(a157*a092);
  a078=(a078-a158);
  a078=(a078/a083);
  a158=(a145*a078);
  a159=(a143*a115);
  a160=(a117*a120);
  a161=(a140*a160);
  a162=(a159+a161);
  a150=(a150-a148);
  a148=(a150*a003);
  a121=(a121+a116);
  a116=(a140*a121);
  a116=(a050-a116);
  a163=(a116*a006);
  a148=(a148+a163);
  a163=(a162*a010);
  a148=(a148+a163);
  a163=(2.*a148);
  a163=(a163*a099);
  a164=(a134*a160);
  a165=(a085*a115);
  a166=(a164-a165);
  a167=(a166*a082);
  a163=(a163-a167);
  a167=(a134*a121);
  a167=(a050-a167);
  a168=(a167*a089);
  a163=(a163-a168);
  a168=(a056*a120);
  a169=(a154-a168);
  a170=(a169*a092);
  a163=(a163-a170);
  a163=(a163/a083);
  a170=(a162*a163);
  a158=(a158+a170);
  a170=(a140*a119);
  a170=(a050-a170);
  a144=(a144+a142);
  a142=(a144*a003);
  a161=(a161-a159);
  a159=(a161*a006);
  a142=(a142+a159);
  a159=(a170*a010);
  a142=(a142+a159);
  a159=(2.*a142);
  a159=(a159*a107);
  a171=(a134*a119);
  a171=(a050-a171);
  a172=(a171*a082);
  a159=(a159-a172);
  a172=(a056*a115);
  a173=(a164-a172);
  a174=(a173*a089);
  a159=(a159-a174);
  a174=(a085*a117);
  a175=(a076-a174);
  a176=(a175*a092);
  a159=(a159-a176);
  a159=(a159/a083);
  a176=(a170*a159);
  a158=(a158+a176);
  a176=(a114*a158);
  a109=(a109+a176);
  a176=5.3867513459481287e-01;
  a177=2.3205080756887719e-01;
  a093=(a177*a093);
  a158=(a059*a158);
  a093=(a093+a158);
  a158=(a002*a093);
  a178=(a176*a158);
  a178=(a082+a178);
  a179=(a002*a109);
  a180=(a018*a179);
  a178=(a178+a180);
  a180=(a071*a178);
  a181=(a048*a180);
  a182=(a074*a079);
  a183=(a005*a098);
  a182=(a182+a183);
  a183=(a096*a094);
  a182=(a182+a183);
  a183=(a177*a182);
  a184=(a151*a078);
  a185=(a116*a163);
  a184=(a184+a185);
  a185=(a161*a159);
  a184=(a184+a185);
  a185=(a059*a184);
  a183=(a183+a185);
  a185=(a002*a183);
  a186=(a176*a185);
  a186=(a089+a186);
  a182=(a059*a182);
  a184=(a114*a184);
  a182=(a182+a184);
  a184=(a002*a182);
  a187=(a018*a184);
  a186=(a186+a187);
  a187=(a061*a186);
  a188=(a048*a187);
  a181=(a181+a188);
  a188=(a007*a181);
  a109=(a109-a188);
  a188=(a070*a186);
  a189=(a085*a188);
  a109=(a109+a189);
  a189=(a070*a178);
  a190=(a048*a189);
  a191=(a065*a079);
  a192=(a073*a098);
  a191=(a191+a192);
  a192=(a063*a094);
  a191=(a191+a192);
  a192=(a177*a191);
  a193=(a146*a078);
  a194=(a150*a163);
  a193=(a193+a194);
  a194=(a144*a159);
  a193=(a193+a194);
  a194=(a059*a193);
  a192=(a192+a194);
  a194=(a002*a192);
  a195=(a176*a194);
  a195=(a092+a195);
  a191=(a059*a191);
  a193=(a114*a193);
  a191=(a191+a193);
  a193=(a002*a191);
  a196=(a018*a193);
  a195=(a195+a196);
  a196=(a061*a195);
  a197=(a048*a196);
  a190=(a190+a197);
  a197=(a004*a190);
  a109=(a109-a197);
  a197=(a071*a195);
  a198=(a056*a197);
  a109=(a109+a198);
  a198=(2.*a011);
  a199=(a071*a186);
  a200=(a048*a199);
  a201=(a070*a195);
  a202=(a048*a201);
  a203=(a200+a202);
  a204=(a198*a203);
  a109=(a109+a204);
  a204=(a048/a053);
  a205=(a061*a178);
  a206=(a009*a205);
  a207=(a095*a180);
  a206=(a206-a207);
  a207=(a054*a189);
  a206=(a206-a207);
  a207=(a095*a187);
  a206=(a206-a207);
  a207=(a012*a199);
  a206=(a206+a207);
  a207=(a072*a188);
  a206=(a206-a207);
  a207=(a054*a196);
  a206=(a206-a207);
  a207=(a072*a197);
  a206=(a206-a207);
  a207=(a008*a201);
  a206=(a206+a207);
  a207=(a204*a206);
  a207=(a049*a207);
  a208=(a019*a207);
  a209=(a206/a053);
  a208=(a208-a209);
  a210=(a032*a208);
  a211=(a045*a210);
  a212=(a027*a208);
  a213=(a020*a212);
  a213=(a042*a213);
  a211=(a211+a213);
  a213=(a039*a212);
  a211=(a211+a213);
  a213=(a020*a208);
  a213=(a036*a213);
  a211=(a211+a213);
  a213=(a033*a208);
  a211=(a211+a213);
  a213=(a032*a209);
  a214=(a029*a213);
  a211=(a211+a214);
  a214=(a027*a209);
  a215=(a020*a214);
  a215=(a025*a215);
  a211=(a211+a215);
  a215=(a022*a214);
  a211=(a211+a215);
  a215=(a034*a207);
  a013=(a056*a013);
  a210=(a047*a210);
  a216=(2.*a020);
  a217=(2.*a027);
  a218=(a046*a208);
  a219=(a217*a218);
  a220=(a040*a208);
  a219=(a219+a220);
  a220=(a216*a219);
  a210=(a210+a220);
  a220=(a043*a212);
  a210=(a210+a220);
  a220=(a037*a208);
  a210=(a210+a220);
  a220=(a013*a210);
  a215=(a215+a220);
  a213=(a031*a213);
  a220=(a030*a209);
  a221=(a217*a220);
  a222=(a023*a209);
  a221=(a221+a222);
  a222=(a216*a221);
  a213=(a213+a222);
  a222=(a026*a214);
  a213=(a213+a222);
  a222=(a017*a209);
  a213=(a213+a222);
  a222=(a013*a213);
  a215=(a215+a222);
  a215=(a018*a215);
  a211=(a211+a215);
  a215=(a020*a209);
  a215=(a016*a215);
  a211=(a211+a215);
  a215=(a001*a209);
  a211=(a211+a215);
  a215=(a198*a211);
  a109=(a109+a215);
  a215=(a058*a109);
  a222=(a056*a189);
  a222=(a222+a182);
  a182=(a011*a181);
  a222=(a222-a182);
  a182=(a085*a196);
  a222=(a222+a182);
  a182=(a048*a188);
  a223=(a048*a197);
  a182=(a182+a223);
  a223=(a004*a182);
  a222=(a222-a223);
  a223=(2.*a007);
  a224=(a048*a205);
  a202=(a224+a202);
  a225=(a223*a202);
  a222=(a222+a225);
  a225=(a223*a211);
  a222=(a222+a225);
  a225=(a087*a222);
  a215=(a215+a225);
  a225=(a085*a180);
  a226=(a056*a187);
  a225=(a225+a226);
  a226=(2.*a004);
  a224=(a224+a200);
  a200=(a226*a224);
  a225=(a225+a200);
  a225=(a225+a191);
  a191=(a011*a190);
  a225=(a225-a191);
  a191=(a007*a182);
  a225=(a225-a191);
  a191=(a226*a211);
  a225=(a225+a191);
  a191=(a090*a225);
  a215=(a215+a191);
  a200=arg[1]? arg[1][2] : 0;
  a227=(a062*a072);
  a228=(a019*a014);
  a228=(a050-a228);
  a229=(a052*a228);
  a230=(a229*a011);
  a231=(a227-a230);
  a231=(a200*a231);
  a232=arg[1]? arg[1][5] : 0;
  a233=(a062*a012);
  a233=(a050-a233);
  a233=(a232*a233);
  a231=(a231+a233);
  a233=arg[1]? arg[1][8] : 0;
  a234=(a229*a004);
  a235=(a062*a095);
  a234=(a234+a235);
  a234=(a233*a234);
  a231=(a231+a234);
  a231=(a231*a083);
  a215=(a215+a231);
  a215=(a215/a002);
  if (res[0]!=0) res[0][0]=a215;
  a215=(a102*a109);
  a231=(a104*a222);
  a215=(a215+a231);
  a234=(a106*a225);
  a215=(a215+a234);
  a234=(a062*a008);
  a234=(a050-a234);
  a234=(a200*a234);
  a230=(a230+a227);
  a230=(a232*a230);
  a234=(a234+a230);
  a230=(a062*a054);
  a227=(a229*a007);
  a230=(a230-a227);
  a230=(a233*a230);
  a234=(a234+a230);
  a234=(a234*a083);
  a215=(a215-a234);
  a215=(a215/a002);
  if (res[0]!=0) res[0][1]=a215;
  a215=(a108*a109);
  a234=(a111*a222);
  a234=(a215+a234);
  a230=(a113*a225);
  a234=(a234+a230);
  a234=(a234/a002);
  if (res[0]!=0) res[0][2]=a234;
  a234=(a143*a149);
  a230=(a125*a139);
  a230=(a050-a230);
  a227=(a133*a230);
  a235=(a227*a120);
  a236=(a234-a235);
  a236=(a200*a236);
  a237=(a143*a121);
  a237=(a050-a237);
  a237=(a232*a237);
  a236=(a236+a237);
  a237=(a227*a115);
  a238=(a143*a160);
  a237=(a237+a238);
  a237=(a233*a237);
  a236=(a236+a237);
  a236=(a236*a083);
  a158=(a018*a158);
  a158=(a082+a158);
  a237=-3.8675134594812879e-02;
  a179=(a237*a179);
  a158=(a158+a179);
  a179=(a148*a158);
  a238=(a134*a179);
  a185=(a018*a185);
  a185=(a089+a185);
  a184=(a237*a184);
  a185=(a185+a184);
  a184=(a142*a185);
  a239=(a134*a184);
  a238=(a238+a239);
  a239=(a117*a238);
  a093=(a093-a239);
  a239=(a069*a185);
  a240=(a085*a239);
  a093=(a093+a240);
  a240=(a069*a158);
  a241=(a134*a240);
  a194=(a018*a194);
  a194=(a092+a194);
  a193=(a237*a193);
  a194=(a194+a193);
  a193=(a142*a194);
  a242=(a134*a193);
  a241=(a241+a242);
  a242=(a115*a241);
  a093=(a093-a242);
  a242=(a148*a194);
  a243=(a056*a242);
  a093=(a093+a243);
  a243=(2.*a120);
  a244=(a148*a185);
  a245=(a134*a244);
  a246=(a069*a194);
  a247=(a134*a246);
  a248=(a245+a247);
  a249=(a243*a248);
  a093=(a093+a249);
  a249=(a134/a123);
  a250=(a142*a158);
  a251=(a119*a250);
  a252=(a160*a179);
  a251=(a251-a252);
  a252=(a141*a240);
  a251=(a251-a252);
  a252=(a160*a184);
  a251=(a251-a252);
  a252=(a121*a244);
  a251=(a251+a252);
  a252=(a149*a239);
  a251=(a251-a252);
  a252=(a141*a193);
  a251=(a251-a252);
  a252=(a149*a242);
  a251=(a251-a252);
  a252=(a118*a246);
  a251=(a251+a252);
  a252=(a249*a251);
  a252=(a049*a252);
  a253=(a125*a252);
  a254=(a251/a123);
  a253=(a253-a254);
  a255=(a131*a253);
  a256=(a045*a255);
  a257=(a129*a253);
  a258=(a126*a257);
  a258=(a042*a258);
  a256=(a256+a258);
  a258=(a039*a257);
  a256=(a256+a258);
  a258=(a126*a253);
  a258=(a036*a258);
  a256=(a256+a258);
  a258=(a033*a253);
  a256=(a256+a258);
  a258=(a131*a254);
  a259=(a029*a258);
  a256=(a256+a259);
  a259=(a129*a254);
  a260=(a126*a259);
  a260=(a025*a260);
  a256=(a256+a260);
  a260=(a022*a259);
  a256=(a256+a260);
  a260=(a132*a252);
  a122=(a056*a122);
  a255=(a047*a255);
  a261=(2.*a126);
  a262=(2.*a129);
  a263=(a130*a253);
  a264=(a262*a263);
  a265=(a127*a253);
  a264=(a264+a265);
  a265=(a261*a264);
  a255=(a255+a265);
  a265=(a128*a257);
  a255=(a255+a265);
  a265=(a124*a253);
  a255=(a255+a265);
  a265=(a122*a255);
  a260=(a260+a265);
  a258=(a031*a258);
  a265=(a138*a254);
  a266=(a262*a265);
  a267=(a136*a254);
  a266=(a266+a267);
  a267=(a261*a266);
  a258=(a258+a267);
  a267=(a137*a259);
  a258=(a258+a267);
  a267=(a135*a254);
  a258=(a258+a267);
  a267=(a122*a258);
  a260=(a260+a267);
  a260=(a018*a260);
  a256=(a256+a260);
  a260=(a126*a254);
  a260=(a016*a260);
  a256=(a256+a260);
  a260=(a001*a254);
  a256=(a256+a260);
  a260=(a243*a256);
  a093=(a093+a260);
  a260=(a153*a093);
  a236=(a236+a260);
  a260=(a056*a240);
  a183=(a183+a260);
  a260=(a120*a238);
  a183=(a183-a260);
  a260=(a085*a193);
  a183=(a183+a260);
  a260=(a134*a239);
  a267=(a134*a242);
  a260=(a260+a267);
  a267=(a115*a260);
  a183=(a183-a267);
  a267=(2.*a117);
  a268=(a134*a250);
  a247=(a268+a247);
  a269=(a267*a247);
  a183=(a183+a269);
  a269=(a267*a256);
  a183=(a183+a269);
  a269=(a156*a183);
  a236=(a236+a269);
  a269=(a085*a179);
  a192=(a192+a269);
  a269=(a056*a184);
  a192=(a192+a269);
  a269=(2.*a115);
  a268=(a268+a245);
  a245=(a269*a268);
  a192=(a192+a245);
  a245=(a120*a241);
  a192=(a192-a245);
  a245=(a117*a260);
  a192=(a192-a245);
  a245=(a269*a256);
  a192=(a192+a245);
  a245=(a157*a192);
  a236=(a236+a245);
  a236=(a236/a002);
  if (res[0]!=0) res[0][3]=a236;
  a236=(a166*a093);
  a270=(a143*a118);
  a270=(a050-a270);
  a270=(a200*a270);
  a235=(a235+a234);
  a235=(a232*a235);
  a270=(a270+a235);
  a235=(a143*a141);
  a234=(a227*a117);
  a235=(a235-a234);
  a235=(a233*a235);
  a270=(a270+a235);
  a270=(a270*a083);
  a236=(a236-a270);
  a270=(a167*a183);
  a236=(a236+a270);
  a235=(a169*a192);
  a236=(a236+a235);
  a236=(a236/a002);
  if (res[0]!=0) res[0][4]=a236;
  a236=(a171*a093);
  a235=(a173*a183);
  a235=(a236+a235);
  a234=(a175*a192);
  a235=(a235+a234);
  a235=(a235/a002);
  if (res[0]!=0) res[0][5]=a235;
  a235=arg[2]? arg[2][0] : 0;
  a234=(a056*a075);
  a271=(a056*a006);
  a234=(a234+a271);
  a234=(a002*a234);
  a271=(a056*a234);
  a272=(a056*a067);
  a273=(a056*a003);
  a272=(a272+a273);
  a272=(a002*a272);
  a273=casadi_sq(a272);
  a274=casadi_sq(a234);
  a275=(a273+a274);
  a276=(a056*a077);
  a277=(a056*a010);
  a276=(a276+a277);
  a276=(a002*a276);
  a277=casadi_sq(a276);
  a278=(a275+a277);
  a279=(a001*a278);
  a280=(a016*a278);
  a015=(a015+a280);
  a280=(a018*a278);
  a281=casadi_sq(a280);
  a282=(a015*a281);
  a279=(a279+a282);
  a282=(a022*a278);
  a021=(a021+a282);
  a282=(a025*a278);
  a024=(a024+a282);
  a282=(a024*a281);
  a021=(a021+a282);
  a282=casadi_sq(a281);
  a283=(a021*a282);
  a279=(a279+a283);
  a283=(a029*a278);
  a028=(a028+a283);
  a283=(a031*a281);
  a028=(a028+a283);
  a283=casadi_sq(a282);
  a284=(a028*a283);
  a279=(a279+a284);
  a284=(a033*a278);
  a285=(a036*a278);
  a035=(a035+a285);
  a285=(a035*a281);
  a284=(a284+a285);
  a285=(a039*a278);
  a038=(a038+a285);
  a285=(a042*a278);
  a041=(a041+a285);
  a285=(a041*a281);
  a038=(a038+a285);
  a285=(a038*a282);
  a284=(a284+a285);
  a285=(a045*a278);
  a044=(a044+a285);
  a285=(a047*a281);
  a044=(a044+a285);
  a285=(a044*a283);
  a284=(a284+a285);
  a279=(a279-a284);
  a000=(a000+a279);
  a051=(a051+a284);
  a284=(a280*a051);
  a284=(a050-a284);
  a284=(a049*a284);
  a000=(a000/a284);
  a279=(a272*a276);
  a285=(a000*a279);
  a271=(a271+a285);
  a286=(a271*a081);
  a287=(a085*a276);
  a288=(a272*a234);
  a289=(a000*a288);
  a287=(a287+a289);
  a290=(a287*a088);
  a286=(a286+a290);
  a274=(a274+a277);
  a290=(a000*a274);
  a290=(a050-a290);
  a291=(a290*a091);
  a286=(a286+a291);
  a152=(a152+a076);
  a291=(a152*a093);
  a286=(a286+a291);
  a155=(a155+a154);
  a291=(a155*a183);
  a286=(a286+a291);
  a286=(a286+a245);
  a057=(a057+a055);
  a245=(a057*a109);
  a286=(a286+a245);
  a086=(a086+a084);
  a245=(a086*a222);
  a286=(a286+a245);
  a286=(a286+a191);
  a235=(a235-a286);
  if (res[0]!=0) res[0][6]=a235;
  a235=arg[2]? arg[2][1] : 0;
  a286=(a085*a272);
  a191=(a234*a276);
  a245=(a000*a191);
  a286=(a286+a245);
  a291=(a286*a081);
  a277=(a277+a273);
  a273=(a000*a277);
  a273=(a050-a273);
  a292=(a273*a088);
  a291=(a291+a292);
  a292=(a056*a276);
  a292=(a292+a289);
  a289=(a292*a091);
  a291=(a291+a289);
  a165=(a165+a164);
  a289=(a165*a093);
  a291=(a291+a289);
  a291=(a291+a270);
  a168=(a168+a154);
  a154=(a168*a192);
  a291=(a291+a154);
  a101=(a101+a100);
  a154=(a101*a109);
  a291=(a291+a154);
  a291=(a291+a231);
  a105=(a105+a084);
  a084=(a105*a225);
  a291=(a291+a084);
  a235=(a235-a291);
  if (res[0]!=0) res[0][7]=a235;
  a235=arg[2]? arg[2][2] : 0;
  a291=(a000*a275);
  a050=(a050-a291);
  a291=(a050*a081);
  a084=(a056*a272);
  a084=(a084+a245);
  a245=(a084*a088);
  a291=(a291+a245);
  a245=(a085*a234);
  a245=(a245+a285);
  a285=(a245*a091);
  a291=(a291+a285);
  a291=(a291+a236);
  a172=(a172+a164);
  a164=(a172*a183);
  a291=(a291+a164);
  a174=(a174+a076);
  a076=(a174*a192);
  a291=(a291+a076);
  a291=(a291+a215);
  a110=(a110+a100);
  a100=(a110*a222);
  a291=(a291+a100);
  a112=(a112+a055);
  a055=(a112*a225);
  a291=(a291+a055);
  a235=(a235-a291);
  if (res[0]!=0) res[0][8]=a235;
  a235=(a226*a002);
  a291=(a001*a235);
  a055=(a016*a235);
  a100=(a020*a055);
  a215=(a018*a235);
  a076=(a013*a215);
  a164=(a017*a076);
  a100=(a100+a164);
  a291=(a291+a100);
  a100=(a022*a235);
  a164=(a025*a235);
  a236=(a020*a164);
  a285=(a026*a076);
  a236=(a236+a285);
  a100=(a100+a236);
  a236=(a027*a100);
  a285=(a216*a076);
  a231=(a023*a285);
  a236=(a236+a231);
  a291=(a291+a236);
  a236=(a029*a235);
  a231=(a031*a076);
  a236=(a236+a231);
  a231=(a032*a236);
  a154=(a217*a285);
  a270=(a030*a154);
  a231=(a231+a270);
  a291=(a291+a231);
  a231=(a033*a235);
  a270=(a036*a235);
  a289=(a020*a270);
  a293=(a037*a076);
  a289=(a289+a293);
  a231=(a231+a289);
  a289=(a039*a235);
  a293=(a042*a235);
  a294=(a020*a293);
  a295=(a043*a076);
  a294=(a294+a295);
  a289=(a289+a294);
  a294=(a027*a289);
  a295=(a040*a285);
  a294=(a294+a295);
  a231=(a231+a294);
  a294=(a045*a235);
  a295=(a047*a076);
  a294=(a294+a295);
  a295=(a032*a294);
  a296=(a046*a154);
  a295=(a295+a296);
  a231=(a231+a295);
  a295=(a291-a231);
  a295=(a295/a053);
  a296=(a034*a215);
  a297=(a019*a231);
  a296=(a296+a297);
  a297=(a049*a296);
  a298=(a204*a297);
  a295=(a295+a298);
  a298=(a054*a295);
  a299=(a011*a002);
  a300=(a048*a299);
  a298=(a298+a300);
  a301=(a109*a298);
  a302=(a052*a291);
  a303=(a014*a296);
  a302=(a302-a303);
  a302=(a231+a302);
  a302=(a018*a302);
  a303=(a054*a302);
  a304=(a060*a299);
  a303=(a303+a304);
  a305=(2.*a052);
  a306=(a305*a296);
  a306=(a056*a306);
  a307=(a007*a306);
  a308=(a303+a307);
  a309=(a079*a308);
  a310=(a066*a065);
  a311=(a008*a302);
  a312=(a067*a311);
  a310=(a310-a312);
  a312=(a072*a302);
  a313=(a007*a002);
  a314=(a060*a313);
  a312=(a312+a314);
  a315=(a011*a306);
  a316=(a312-a315);
  a317=(a075*a316);
  a310=(a310+a317);
  a308=(a077*a308);
  a310=(a310+a308);
  a308=(2.*a310);
  a308=(a080*a308);
  a317=(a082*a298);
  a318=(a072*a295);
  a319=(a048*a313);
  a318=(a318+a319);
  a320=(a089*a318);
  a317=(a317+a320);
  a320=(a008*a295);
  a321=(a092*a320);
  a317=(a317-a321);
  a308=(a308-a317);
  a308=(a308/a083);
  a317=(a064*a308);
  a309=(a309+a317);
  a317=(a062*a002);
  a321=(a004*a306);
  a321=(a317-a321);
  a322=(a095*a302);
  a323=(a321+a322);
  a324=(a098*a323);
  a312=(a312+a315);
  a315=(a067*a312);
  a325=(a066*a073);
  a315=(a315+a325);
  a325=(a012*a302);
  a326=(a060*a235);
  a325=(a325+a326);
  a327=(a075*a325);
  a315=(a315-a327);
  a323=(a077*a323);
  a315=(a315+a323);
  a323=(2.*a315);
  a323=(a099*a323);
  a327=(a095*a295);
  a328=(a085*a002);
  a329=(a327-a328);
  a330=(a082*a329);
  a331=(a012*a295);
  a332=(a048*a235);
  a331=(a331+a332);
  a333=(a089*a331);
  a330=(a330-a333);
  a333=(a092*a318);
  a330=(a330+a333);
  a323=(a323-a330);
  a323=(a323/a083);
  a330=(a097*a323);
  a324=(a324+a330);
  a309=(a309+a324);
  a303=(a303-a307);
  a307=(a067*a303);
  a324=(a066*a063);
  a307=(a307+a324);
  a322=(a322-a321);
  a321=(a075*a322);
  a307=(a307+a321);
  a302=(a009*a302);
  a302=(a302+a326);
  a326=(a077*a302);
  a307=(a307-a326);
  a326=(2.*a307);
  a326=(a107*a326);
  a321=(a327-a083);
  a324=(a089*a321);
  a330=(a009*a295);
  a330=(a330+a332);
  a332=(a082*a330);
  a324=(a324-a332);
  a332=(a092*a298);
  a324=(a324+a332);
  a326=(a326-a324);
  a326=(a326/a083);
  a324=(a103*a326);
  a302=(a094*a302);
  a324=(a324-a302);
  a309=(a309+a324);
  a324=(a059*a309);
  a302=-1.2928203230275511e+01;
  a332=(a302*a146);
  a332=(a080*a332);
  a332=(a332/a083);
  a333=(a145*a332);
  a334=(a302*a150);
  a334=(a099*a334);
  a334=(a334/a083);
  a335=(a162*a334);
  a333=(a333+a335);
  a335=(a302*a144);
  a335=(a107*a335);
  a335=(a335/a083);
  a336=(a170*a335);
  a333=(a333+a336);
  a336=(a114*a333);
  a324=(a324+a336);
  a336=(a180*a295);
  a337=(a178*a315);
  a309=(a177*a309);
  a333=(a059*a333);
  a309=(a309+a333);
  a333=(a002*a309);
  a338=(a176*a333);
  a339=(a002*a324);
  a340=(a018*a339);
  a338=(a338+a340);
  a340=(a071*a338);
  a337=(a337+a340);
  a340=(a048*a337);
  a336=(a336+a340);
  a340=(a187*a295);
  a341=(a186*a307);
  a316=(a079*a316);
  a342=(a074*a308);
  a316=(a316+a342);
  a342=(a005*a323);
  a325=(a098*a325);
  a342=(a342-a325);
  a316=(a316+a342);
  a322=(a094*a322);
  a342=(a096*a326);
  a322=(a322+a342);
  a316=(a316+a322);
  a322=(a177*a316);
  a342=(a151*a332);
  a325=(a116*a334);
  a342=(a342+a325);
  a325=(a161*a335);
  a342=(a342+a325);
  a325=(a059*a342);
  a322=(a322+a325);
  a325=(a002*a322);
  a343=(a176*a325);
  a316=(a059*a316);
  a342=(a114*a342);
  a316=(a316+a342);
  a342=(a002*a316);
  a344=(a018*a342);
  a343=(a343+a344);
  a344=(a061*a343);
  a341=(a341+a344);
  a344=(a048*a341);
  a340=(a340+a344);
  a336=(a336+a340);
  a340=(a007*a336);
  a324=(a324-a340);
  a340=(a186*a310);
  a344=(a070*a343);
  a340=(a340+a344);
  a344=(a085*a340);
  a324=(a324+a344);
  a190=(a190*a002);
  a344=(a189*a295);
  a345=(a178*a310);
  a346=(a070*a338);
  a345=(a345+a346);
  a346=(a048*a345);
  a344=(a344+a346);
  a346=(a196*a295);
  a347=(a195*a307);
  a308=(a065*a308);
  a311=(a079*a311);
  a308=(a308-a311);
  a312=(a098*a312);
  a323=(a073*a323);
  a312=(a312+a323);
  a308=(a308+a312);
  a303=(a094*a303);
  a326=(a063*a326);
  a303=(a303+a326);
  a308=(a308+a303);
  a303=(a177*a308);
  a332=(a146*a332);
  a334=(a150*a334);
  a332=(a332+a334);
  a335=(a144*a335);
  a332=(a332+a335);
  a335=(a059*a332);
  a303=(a303+a335);
  a335=(a002*a303);
  a334=(a176*a335);
  a308=(a059*a308);
  a332=(a114*a332);
  a308=(a308+a332);
  a332=(a002*a308);
  a326=(a018*a332);
  a334=(a334+a326);
  a326=(a061*a334);
  a347=(a347+a326);
  a326=(a048*a347);
  a346=(a346+a326);
  a344=(a344+a346);
  a346=(a004*a344);
  a346=(a190+a346);
  a324=(a324-a346);
  a346=(a195*a315);
  a326=(a071*a334);
  a346=(a346+a326);
  a326=(a056*a346);
  a324=(a324+a326);
  a326=(a199*a295);
  a315=(a186*a315);
  a343=(a071*a343);
  a315=(a315+a343);
  a343=(a048*a315);
  a326=(a326+a343);
  a343=(a201*a295);
  a310=(a195*a310);
  a334=(a070*a334);
  a310=(a310+a334);
  a334=(a048*a310);
  a343=(a343+a334);
  a334=(a326+a343);
  a334=(a198*a334);
  a324=(a324+a334);
  a334=(a208*a154);
  a312=(a207*a215);
  a323=(a295/a053);
  a311=(a204/a053);
  a348=(a311*a297);
  a323=(a323+a348);
  a323=(a206*a323);
  a348=(a205*a235);
  a307=(a178*a307);
  a338=(a061*a338);
  a307=(a307+a338);
  a338=(a009*a307);
  a348=(a348+a338);
  a338=(a095*a337);
  a348=(a348-a338);
  a338=(a189*a299);
  a349=(a054*a345);
  a338=(a338+a349);
  a348=(a348-a338);
  a338=(a095*a341);
  a348=(a348-a338);
  a338=(a199*a235);
  a315=(a012*a315);
  a338=(a338+a315);
  a348=(a348+a338);
  a338=(a188*a313);
  a315=(a072*a340);
  a338=(a338+a315);
  a348=(a348-a338);
  a338=(a196*a299);
  a315=(a054*a347);
  a338=(a338+a315);
  a348=(a348-a338);
  a338=(a197*a313);
  a315=(a072*a346);
  a338=(a338+a315);
  a348=(a348-a338);
  a310=(a008*a310);
  a348=(a348+a310);
  a310=(a204*a348);
  a323=(a323+a310);
  a323=(a049*a323);
  a310=(a019*a323);
  a312=(a312+a310);
  a348=(a348/a053);
  a310=(a209/a053);
  a297=(a310*a297);
  a348=(a348+a297);
  a312=(a312-a348);
  a297=(a032*a312);
  a334=(a334+a297);
  a297=(a045*a334);
  a338=(a212*a076);
  a315=(a208*a285);
  a349=(a027*a312);
  a315=(a315+a349);
  a349=(a020*a315);
  a338=(a338+a349);
  a338=(a042*a338);
  a297=(a297+a338);
  a338=(a039*a315);
  a297=(a297+a338);
  a338=(a208*a076);
  a349=(a020*a312);
  a338=(a338+a349);
  a338=(a036*a338);
  a297=(a297+a338);
  a338=(a033*a312);
  a297=(a297+a338);
  a154=(a209*a154);
  a338=(a032*a348);
  a154=(a154+a338);
  a338=(a029*a154);
  a297=(a297+a338);
  a338=(a214*a076);
  a349=(a209*a285);
  a350=(a027*a348);
  a349=(a349+a350);
  a350=(a020*a349);
  a338=(a338+a350);
  a338=(a025*a338);
  a297=(a297+a338);
  a338=(a022*a349);
  a297=(a297+a338);
  a231=(a207*a231);
  a323=(a034*a323);
  a231=(a231+a323);
  a323=(a056*a235);
  a338=(a210*a323);
  a334=(a047*a334);
  a350=(2.*a076);
  a351=(a219*a350);
  a285=(2.*a285);
  a352=(a218*a285);
  a294=(a208*a294);
  a353=(a046*a312);
  a294=(a294+a353);
  a294=(a217*a294);
  a352=(a352+a294);
  a289=(a208*a289);
  a294=(a040*a312);
  a289=(a289+a294);
  a352=(a352+a289);
  a352=(a216*a352);
  a351=(a351+a352);
  a334=(a334+a351);
  a293=(a212*a293);
  a315=(a043*a315);
  a293=(a293+a315);
  a334=(a334+a293);
  a270=(a208*a270);
  a312=(a037*a312);
  a270=(a270+a312);
  a334=(a334+a270);
  a334=(a013*a334);
  a338=(a338+a334);
  a231=(a231+a338);
  a323=(a213*a323);
  a154=(a031*a154);
  a350=(a221*a350);
  a285=(a220*a285);
  a236=(a209*a236);
  a338=(a030*a348);
  a236=(a236+a338);
  a236=(a217*a236);
  a285=(a285+a236);
  a100=(a209*a100);
  a236=(a023*a348);
  a100=(a100+a236);
  a285=(a285+a100);
  a285=(a216*a285);
  a350=(a350+a285);
  a154=(a154+a350);
  a164=(a214*a164);
  a349=(a026*a349);
  a164=(a164+a349);
  a154=(a154+a164);
  a055=(a209*a055);
  a164=(a017*a348);
  a055=(a055+a164);
  a154=(a154+a055);
  a154=(a013*a154);
  a323=(a323+a154);
  a231=(a231+a323);
  a231=(a018*a231);
  a297=(a297+a231);
  a076=(a209*a076);
  a231=(a020*a348);
  a076=(a076+a231);
  a076=(a016*a076);
  a297=(a297+a076);
  a348=(a001*a348);
  a297=(a297+a348);
  a348=(a198*a297);
  a324=(a324+a348);
  a348=(a058*a324);
  a348=(a301+a348);
  a076=(a222*a318);
  a345=(a056*a345);
  a345=(a345+a316);
  a336=(a011*a336);
  a345=(a345-a336);
  a347=(a085*a347);
  a345=(a345+a347);
  a182=(a182*a002);
  a347=(a188*a295);
  a340=(a048*a340);
  a347=(a347+a340);
  a340=(a197*a295);
  a346=(a048*a346);
  a340=(a340+a346);
  a347=(a347+a340);
  a340=(a004*a347);
  a340=(a182+a340);
  a345=(a345-a340);
  a295=(a205*a295);
  a307=(a048*a307);
  a295=(a295+a307);
  a343=(a295+a343);
  a343=(a223*a343);
  a345=(a345+a343);
  a343=(a223*a297);
  a345=(a345+a343);
  a343=(a087*a345);
  a343=(a076+a343);
  a348=(a348+a343);
  a337=(a085*a337);
  a341=(a056*a341);
  a337=(a337+a341);
  a341=(2.*a002);
  a224=(a224*a341);
  a295=(a295+a326);
  a295=(a226*a295);
  a224=(a224+a295);
  a337=(a337+a224);
  a337=(a337+a308);
  a344=(a011*a344);
  a337=(a337-a344);
  a347=(a007*a347);
  a337=(a337-a347);
  a211=(a211*a341);
  a297=(a226*a297);
  a297=(a211+a297);
  a337=(a337+a297);
  a297=(a090*a337);
  a320=(a225*a320);
  a297=(a297-a320);
  a348=(a348+a297);
  a320=(a062*a313);
  a347=(a072*a306);
  a347=(a320-a347);
  a296=(a228*a296);
  a215=(a014*a215);
  a291=(a019*a291);
  a215=(a215+a291);
  a215=(a052*a215);
  a296=(a296+a215);
  a215=(a011*a296);
  a291=(a347+a215);
  a291=(a200*a291);
  a235=(a062*a235);
  a344=(a012*a306);
  a235=(a235-a344);
  a235=(a232*a235);
  a291=(a291-a235);
  a229=(a229*a002);
  a235=(a004*a296);
  a235=(a229-a235);
  a344=(a095*a306);
  a235=(a235-a344);
  a235=(a233*a235);
  a291=(a291+a235);
  a291=(a083*a291);
  a348=(a348+a291);
  a348=(a348/a002);
  if (res[1]!=0) res[1][0]=a348;
  a329=(a109*a329);
  a348=(a102*a324);
  a329=(a329+a348);
  a348=(a104*a345);
  a331=(a222*a331);
  a348=(a348-a331);
  a329=(a329+a348);
  a318=(a225*a318);
  a331=(a106*a337);
  a331=(a318+a331);
  a329=(a329+a331);
  a331=(a008*a306);
  a331=(a200*a331);
  a347=(a347-a215);
  a347=(a232*a347);
  a331=(a331+a347);
  a347=(a062*a299);
  a306=(a054*a306);
  a306=(a347-a306);
  a296=(a007*a296);
  a306=(a306+a296);
  a306=(a233*a306);
  a331=(a331+a306);
  a331=(a083*a331);
  a329=(a329-a331);
  a329=(a329/a002);
  if (res[1]!=0) res[1][1]=a329;
  a329=(a108*a324);
  a330=(a109*a330);
  a329=(a329-a330);
  a321=(a222*a321);
  a330=(a111*a345);
  a321=(a321+a330);
  a321=(a329+a321);
  a298=(a225*a298);
  a330=(a113*a337);
  a330=(a298+a330);
  a321=(a321+a330);
  a321=(a321/a002);
  if (res[1]!=0) res[1][2]=a321;
  a321=(a147*a150);
  a330=(a158*a321);
  a333=(a018*a333);
  a339=(a237*a339);
  a333=(a333+a339);
  a339=(a148*a333);
  a330=(a330+a339);
  a339=(a134*a330);
  a331=(a147*a144);
  a306=(a185*a331);
  a325=(a018*a325);
  a342=(a237*a342);
  a325=(a325+a342);
  a342=(a142*a325);
  a306=(a306+a342);
  a342=(a134*a306);
  a339=(a339+a342);
  a342=(a117*a339);
  a309=(a309-a342);
  a342=(a147*a146);
  a296=(a185*a342);
  a215=(a069*a325);
  a296=(a296+a215);
  a215=(a085*a296);
  a309=(a309+a215);
  a215=(a158*a342);
  a291=(a069*a333);
  a215=(a215+a291);
  a291=(a134*a215);
  a235=(a194*a331);
  a335=(a018*a335);
  a332=(a237*a332);
  a335=(a335+a332);
  a332=(a142*a335);
  a235=(a235+a332);
  a332=(a134*a235);
  a291=(a291+a332);
  a332=(a115*a291);
  a309=(a309-a332);
  a332=(a194*a321);
  a344=(a148*a335);
  a332=(a332+a344);
  a344=(a056*a332);
  a309=(a309+a344);
  a321=(a185*a321);
  a325=(a148*a325);
  a321=(a321+a325);
  a325=(a134*a321);
  a342=(a194*a342);
  a335=(a069*a335);
  a342=(a342+a335);
  a335=(a134*a342);
  a344=(a325+a335);
  a344=(a243*a344);
  a309=(a309+a344);
  a331=(a158*a331);
  a333=(a142*a333);
  a331=(a331+a333);
  a333=(a119*a331);
  a344=(a160*a330);
  a333=(a333-a344);
  a344=(a141*a215);
  a333=(a333-a344);
  a344=(a160*a306);
  a333=(a333-a344);
  a321=(a121*a321);
  a333=(a333+a321);
  a321=(a149*a296);
  a333=(a333-a321);
  a321=(a141*a235);
  a333=(a333-a321);
  a321=(a149*a332);
  a333=(a333-a321);
  a342=(a118*a342);
  a333=(a333+a342);
  a342=(a249*a333);
  a342=(a049*a342);
  a321=(a125*a342);
  a333=(a333/a123);
  a321=(a321-a333);
  a344=(a131*a321);
  a308=(a045*a344);
  a224=(a129*a321);
  a295=(a126*a224);
  a295=(a042*a295);
  a308=(a308+a295);
  a295=(a039*a224);
  a308=(a308+a295);
  a295=(a126*a321);
  a295=(a036*a295);
  a308=(a308+a295);
  a295=(a033*a321);
  a308=(a308+a295);
  a295=(a131*a333);
  a326=(a029*a295);
  a308=(a308+a326);
  a326=(a129*a333);
  a343=(a126*a326);
  a343=(a025*a343);
  a308=(a308+a343);
  a343=(a022*a326);
  a308=(a308+a343);
  a342=(a132*a342);
  a344=(a047*a344);
  a343=(a130*a321);
  a343=(a262*a343);
  a307=(a127*a321);
  a343=(a343+a307);
  a343=(a261*a343);
  a344=(a344+a343);
  a224=(a128*a224);
  a344=(a344+a224);
  a321=(a124*a321);
  a344=(a344+a321);
  a344=(a122*a344);
  a342=(a342+a344);
  a295=(a031*a295);
  a344=(a138*a333);
  a344=(a262*a344);
  a321=(a136*a333);
  a344=(a344+a321);
  a344=(a261*a344);
  a295=(a295+a344);
  a326=(a137*a326);
  a295=(a295+a326);
  a326=(a135*a333);
  a295=(a295+a326);
  a295=(a122*a295);
  a342=(a342+a295);
  a342=(a018*a342);
  a308=(a308+a342);
  a342=(a126*a333);
  a342=(a016*a342);
  a308=(a308+a342);
  a333=(a001*a333);
  a308=(a308+a333);
  a333=(a243*a308);
  a309=(a309+a333);
  a333=(a153*a309);
  a215=(a056*a215);
  a322=(a322+a215);
  a339=(a120*a339);
  a322=(a322-a339);
  a235=(a085*a235);
  a322=(a322+a235);
  a296=(a134*a296);
  a332=(a134*a332);
  a296=(a296+a332);
  a332=(a115*a296);
  a322=(a322-a332);
  a331=(a134*a331);
  a335=(a331+a335);
  a335=(a267*a335);
  a322=(a322+a335);
  a335=(a267*a308);
  a322=(a322+a335);
  a335=(a156*a322);
  a333=(a333+a335);
  a330=(a085*a330);
  a303=(a303+a330);
  a306=(a056*a306);
  a303=(a303+a306);
  a331=(a331+a325);
  a331=(a269*a331);
  a303=(a303+a331);
  a291=(a120*a291);
  a303=(a303-a291);
  a296=(a117*a296);
  a303=(a303-a296);
  a308=(a269*a308);
  a303=(a303+a308);
  a308=(a157*a303);
  a333=(a333+a308);
  a333=(a333/a002);
  if (res[1]!=0) res[1][3]=a333;
  a333=(a166*a309);
  a296=(a167*a322);
  a333=(a333+a296);
  a291=(a169*a303);
  a333=(a333+a291);
  a333=(a333/a002);
  if (res[1]!=0) res[1][4]=a333;
  a333=(a171*a309);
  a291=(a173*a322);
  a291=(a333+a291);
  a331=(a175*a303);
  a291=(a291+a331);
  a291=(a291/a002);
  if (res[1]!=0) res[1][5]=a291;
  a291=(2.*a272);
  a331=-1.7320508075688774e+00;
  a331=(a331*a002);
  a325=(a291*a331);
  a306=(a001*a325);
  a330=(a016*a325);
  a330=(a281*a330);
  a278=(a056*a278);
  a335=(a018*a325);
  a332=(a278*a335);
  a235=(a015*a332);
  a330=(a330+a235);
  a306=(a306+a330);
  a330=(a022*a325);
  a235=(a025*a325);
  a235=(a281*a235);
  a339=(a024*a332);
  a235=(a235+a339);
  a330=(a330+a235);
  a330=(a282*a330);
  a235=(2.*a281);
  a339=(a235*a332);
  a215=(a021*a339);
  a330=(a330+a215);
  a306=(a306+a330);
  a330=(a029*a325);
  a215=(a031*a332);
  a330=(a330+a215);
  a330=(a283*a330);
  a215=(2.*a282);
  a342=(a215*a339);
  a295=(a028*a342);
  a330=(a330+a295);
  a306=(a306+a330);
  a330=(a033*a325);
  a295=(a036*a325);
  a295=(a281*a295);
  a326=(a035*a332);
  a295=(a295+a326);
  a330=(a330+a295);
  a295=(a039*a325);
  a326=(a042*a325);
  a326=(a281*a326);
  a344=(a041*a332);
  a326=(a326+a344);
  a295=(a295+a326);
  a295=(a282*a295);
  a339=(a038*a339);
  a295=(a295+a339);
  a330=(a330+a295);
  a295=(a045*a325);
  a332=(a047*a332);
  a295=(a295+a332);
  a295=(a283*a295);
  a342=(a044*a342);
  a295=(a295+a342);
  a330=(a330+a295);
  a306=(a306-a330);
  a306=(a306/a284);
  a295=(a000/a284);
  a335=(a051*a335);
  a330=(a280*a330);
  a335=(a335+a330);
  a335=(a049*a335);
  a335=(a295*a335);
  a306=(a306+a335);
  a335=(a279*a306);
  a330=(a276*a331);
  a330=(a000*a330);
  a335=(a335+a330);
  a342=(a081*a335);
  a332=(a288*a306);
  a339=(a234*a331);
  a339=(a000*a339);
  a332=(a332+a339);
  a326=(a088*a332);
  a342=(a342+a326);
  a326=(a274*a306);
  a326=(a091*a326);
  a342=(a342-a326);
  a326=(a152*a309);
  a342=(a342+a326);
  a326=(a155*a322);
  a342=(a342+a326);
  a342=(a342+a308);
  a308=(a057*a324);
  a301=(a301+a308);
  a342=(a342+a301);
  a301=(a086*a345);
  a076=(a076+a301);
  a342=(a342+a076);
  a342=(a342+a297);
  a342=(-a342);
  if (res[1]!=0) res[1][6]=a342;
  a342=8.6602540378443871e-01;
  a342=(a342*a002);
  a297=(a191*a306);
  a076=(a342+a297);
  a076=(a081*a076);
  a301=(a277*a306);
  a325=(a000*a325);
  a301=(a301+a325);
  a301=(a088*a301);
  a076=(a076-a301);
  a332=(a091*a332);
  a076=(a076+a332);
  a309=(a165*a309);
  a076=(a076+a309);
  a076=(a076+a296);
  a296=(a168*a303);
  a076=(a076+a296);
  a296=(a328+a327);
  a296=(a109*a296);
  a324=(a101*a324);
  a296=(a296+a324);
  a076=(a076+a296);
  a076=(a076+a348);
  a348=(a105*a337);
  a318=(a318+a348);
  a076=(a076+a318);
  a076=(-a076);
  if (res[1]!=0) res[1][7]=a076;
  a076=-8.6602540378443871e-01;
  a076=(a076*a002);
  a297=(a076+a297);
  a297=(a088*a297);
  a306=(a275*a306);
  a306=(a306+a325);
  a306=(a081*a306);
  a297=(a297-a306);
  a335=(a091*a335);
  a297=(a297+a335);
  a297=(a297+a333);
  a322=(a172*a322);
  a297=(a297+a322);
  a303=(a174*a303);
  a297=(a297+a303);
  a297=(a297+a329);
  a327=(a083+a327);
  a327=(a222*a327);
  a345=(a110*a345);
  a327=(a327+a345);
  a297=(a297+a327);
  a337=(a112*a337);
  a298=(a298+a337);
  a297=(a297+a298);
  a297=(-a297);
  if (res[1]!=0) res[1][8]=a297;
  a297=(a223*a002);
  a298=(a001*a297);
  a337=(a016*a297);
  a327=(a020*a337);
  a345=(a018*a297);
  a329=(a013*a345);
  a303=(a017*a329);
  a327=(a327+a303);
  a298=(a298+a327);
  a327=(a022*a297);
  a303=(a025*a297);
  a322=(a020*a303);
  a333=(a026*a329);
  a322=(a322+a333);
  a327=(a327+a322);
  a322=(a027*a327);
  a333=(a216*a329);
  a335=(a023*a333);
  a322=(a322+a335);
  a298=(a298+a322);
  a322=(a029*a297);
  a335=(a031*a329);
  a322=(a322+a335);
  a335=(a032*a322);
  a306=(a217*a333);
  a325=(a030*a306);
  a335=(a335+a325);
  a298=(a298+a335);
  a335=(a033*a297);
  a325=(a036*a297);
  a318=(a020*a325);
  a348=(a037*a329);
  a318=(a318+a348);
  a335=(a335+a318);
  a318=(a039*a297);
  a348=(a042*a297);
  a296=(a020*a348);
  a324=(a043*a329);
  a296=(a296+a324);
  a318=(a318+a296);
  a296=(a027*a318);
  a324=(a040*a333);
  a296=(a296+a324);
  a335=(a335+a296);
  a296=(a045*a297);
  a324=(a047*a329);
  a296=(a296+a324);
  a324=(a032*a296);
  a309=(a046*a306);
  a324=(a324+a309);
  a335=(a335+a324);
  a324=(a298-a335);
  a324=(a324/a053);
  a309=(a034*a345);
  a332=(a019*a335);
  a309=(a309+a332);
  a332=(a049*a309);
  a301=(a204*a332);
  a324=(a324+a301);
  a301=(a054*a324);
  a308=(a301-a083);
  a326=(a109*a308);
  a344=(a052*a298);
  a321=(a014*a309);
  a344=(a344-a321);
  a344=(a335+a344);
  a344=(a018*a344);
  a321=(a054*a344);
  a224=(a305*a309);
  a224=(a056*a224);
  a343=(a007*a224);
  a343=(a317-a343);
  a307=(a321-a343);
  a340=(a079*a307);
  a346=(a072*a344);
  a336=(a004*a002);
  a316=(a060*a336);
  a346=(a346+a316);
  a231=(a011*a224);
  a323=(a346-a231);
  a154=(a075*a323);
  a055=(a066*a074);
  a154=(a154+a055);
  a055=(a008*a344);
  a164=(a060*a297);
  a055=(a055+a164);
  a349=(a067*a055);
  a154=(a154-a349);
  a307=(a077*a307);
  a154=(a154+a307);
  a307=(2.*a154);
  a307=(a080*a307);
  a308=(a082*a308);
  a349=(a072*a324);
  a350=(a048*a336);
  a349=(a349+a350);
  a285=(a089*a349);
  a308=(a308+a285);
  a285=(a008*a324);
  a100=(a048*a297);
  a285=(a285+a100);
  a236=(a092*a285);
  a308=(a308-a236);
  a307=(a307-a308);
  a307=(a307/a083);
  a308=(a064*a307);
  a340=(a340+a308);
  a308=(a095*a344);
  a308=(a308+a304);
  a304=(a004*a224);
  a236=(a308-a304);
  a338=(a098*a236);
  a346=(a346+a231);
  a231=(a067*a346);
  a334=(a066*a005);
  a270=(a012*a344);
  a312=(a075*a270);
  a334=(a334-a312);
  a231=(a231+a334);
  a236=(a077*a236);
  a231=(a231+a236);
  a236=(2.*a231);
  a236=(a099*a236);
  a334=(a095*a324);
  a334=(a334+a300);
  a300=(a082*a334);
  a312=(a012*a324);
  a293=(a089*a312);
  a300=(a300-a293);
  a293=(a092*a349);
  a300=(a300+a293);
  a236=(a236-a300);
  a236=(a236/a083);
  a300=(a097*a236);
  a338=(a338+a300);
  a340=(a340+a338);
  a343=(a343+a321);
  a321=(a067*a343);
  a308=(a308+a304);
  a304=(a075*a308);
  a338=(a066*a096);
  a304=(a304+a338);
  a321=(a321+a304);
  a344=(a009*a344);
  a344=(a344+a164);
  a164=(a077*a344);
  a321=(a321-a164);
  a164=(2.*a321);
  a164=(a107*a164);
  a304=(a089*a334);
  a338=(a009*a324);
  a338=(a338+a100);
  a100=(a082*a338);
  a304=(a304-a100);
  a100=(a301-a328);
  a300=(a092*a100);
  a304=(a304+a300);
  a164=(a164-a304);
  a164=(a164/a083);
  a304=(a103*a164);
  a344=(a094*a344);
  a304=(a304-a344);
  a340=(a340+a304);
  a304=(a059*a340);
  a344=(a302*a151);
  a344=(a080*a344);
  a344=(a344/a083);
  a300=(a145*a344);
  a293=(a302*a116);
  a293=(a099*a293);
  a293=(a293/a083);
  a315=(a162*a293);
  a300=(a300+a315);
  a315=(a302*a161);
  a315=(a107*a315);
  a315=(a315/a083);
  a351=(a170*a315);
  a300=(a300+a351);
  a351=(a114*a300);
  a304=(a304+a351);
  a181=(a181*a002);
  a351=(a180*a324);
  a352=(a178*a231);
  a340=(a177*a340);
  a300=(a059*a300);
  a340=(a340+a300);
  a300=(a002*a340);
  a289=(a176*a300);
  a294=(a002*a304);
  a353=(a018*a294);
  a289=(a289+a353);
  a353=(a071*a289);
  a352=(a352+a353);
  a353=(a048*a352);
  a351=(a351+a353);
  a353=(a187*a324);
  a354=(a186*a321);
  a323=(a079*a323);
  a355=(a074*a307);
  a323=(a323+a355);
  a355=(a005*a236);
  a270=(a098*a270);
  a355=(a355-a270);
  a323=(a323+a355);
  a308=(a094*a308);
  a355=(a096*a164);
  a308=(a308+a355);
  a323=(a323+a308);
  a308=(a177*a323);
  a355=(a151*a344);
  a270=(a116*a293);
  a355=(a355+a270);
  a270=(a161*a315);
  a355=(a355+a270);
  a270=(a059*a355);
  a308=(a308+a270);
  a270=(a002*a308);
  a356=(a176*a270);
  a323=(a059*a323);
  a355=(a114*a355);
  a323=(a323+a355);
  a355=(a002*a323);
  a357=(a018*a355);
  a356=(a356+a357);
  a357=(a061*a356);
  a354=(a354+a357);
  a357=(a048*a354);
  a353=(a353+a357);
  a351=(a351+a353);
  a353=(a007*a351);
  a353=(a181+a353);
  a304=(a304-a353);
  a353=(a186*a154);
  a357=(a070*a356);
  a353=(a353+a357);
  a357=(a085*a353);
  a304=(a304+a357);
  a357=(a189*a324);
  a358=(a178*a154);
  a359=(a070*a289);
  a358=(a358+a359);
  a359=(a048*a358);
  a357=(a357+a359);
  a359=(a196*a324);
  a360=(a195*a321);
  a307=(a065*a307);
  a055=(a079*a055);
  a307=(a307-a055);
  a346=(a098*a346);
  a236=(a073*a236);
  a346=(a346+a236);
  a307=(a307+a346);
  a343=(a094*a343);
  a164=(a063*a164);
  a343=(a343+a164);
  a307=(a307+a343);
  a343=(a177*a307);
  a344=(a146*a344);
  a293=(a150*a293);
  a344=(a344+a293);
  a315=(a144*a315);
  a344=(a344+a315);
  a315=(a059*a344);
  a343=(a343+a315);
  a315=(a002*a343);
  a293=(a176*a315);
  a307=(a059*a307);
  a344=(a114*a344);
  a307=(a307+a344);
  a344=(a002*a307);
  a164=(a018*a344);
  a293=(a293+a164);
  a164=(a061*a293);
  a360=(a360+a164);
  a164=(a048*a360);
  a359=(a359+a164);
  a357=(a357+a359);
  a359=(a004*a357);
  a304=(a304-a359);
  a359=(a195*a231);
  a164=(a071*a293);
  a359=(a359+a164);
  a164=(a056*a359);
  a304=(a304+a164);
  a164=(a199*a324);
  a231=(a186*a231);
  a356=(a071*a356);
  a231=(a231+a356);
  a356=(a048*a231);
  a164=(a164+a356);
  a356=(a201*a324);
  a154=(a195*a154);
  a293=(a070*a293);
  a154=(a154+a293);
  a293=(a048*a154);
  a356=(a356+a293);
  a293=(a164+a356);
  a293=(a198*a293);
  a304=(a304+a293);
  a293=(a208*a306);
  a346=(a207*a345);
  a236=(a324/a053);
  a055=(a311*a332);
  a236=(a236+a055);
  a236=(a206*a236);
  a055=(a205*a297);
  a321=(a178*a321);
  a289=(a061*a289);
  a321=(a321+a289);
  a289=(a009*a321);
  a055=(a055+a289);
  a289=(a180*a299);
  a361=(a095*a352);
  a289=(a289+a361);
  a055=(a055-a289);
  a289=(a054*a358);
  a055=(a055-a289);
  a299=(a187*a299);
  a289=(a095*a354);
  a299=(a299+a289);
  a055=(a055-a299);
  a231=(a012*a231);
  a055=(a055+a231);
  a231=(a188*a336);
  a299=(a072*a353);
  a231=(a231+a299);
  a055=(a055-a231);
  a231=(a054*a360);
  a055=(a055-a231);
  a231=(a197*a336);
  a299=(a072*a359);
  a231=(a231+a299);
  a055=(a055-a231);
  a231=(a201*a297);
  a154=(a008*a154);
  a231=(a231+a154);
  a055=(a055+a231);
  a231=(a204*a055);
  a236=(a236+a231);
  a236=(a049*a236);
  a231=(a019*a236);
  a346=(a346+a231);
  a055=(a055/a053);
  a332=(a310*a332);
  a055=(a055+a332);
  a346=(a346-a055);
  a332=(a032*a346);
  a293=(a293+a332);
  a332=(a045*a293);
  a231=(a212*a329);
  a154=(a208*a333);
  a299=(a027*a346);
  a154=(a154+a299);
  a299=(a020*a154);
  a231=(a231+a299);
  a231=(a042*a231);
  a332=(a332+a231);
  a231=(a039*a154);
  a332=(a332+a231);
  a231=(a208*a329);
  a299=(a020*a346);
  a231=(a231+a299);
  a231=(a036*a231);
  a332=(a332+a231);
  a231=(a033*a346);
  a332=(a332+a231);
  a306=(a209*a306);
  a231=(a032*a055);
  a306=(a306+a231);
  a231=(a029*a306);
  a332=(a332+a231);
  a231=(a214*a329);
  a299=(a209*a333);
  a289=(a027*a055);
  a299=(a299+a289);
  a289=(a020*a299);
  a231=(a231+a289);
  a231=(a025*a231);
  a332=(a332+a231);
  a231=(a022*a299);
  a332=(a332+a231);
  a335=(a207*a335);
  a236=(a034*a236);
  a335=(a335+a236);
  a236=(a056*a297);
  a231=(a210*a236);
  a293=(a047*a293);
  a289=(2.*a329);
  a361=(a219*a289);
  a333=(2.*a333);
  a362=(a218*a333);
  a296=(a208*a296);
  a363=(a046*a346);
  a296=(a296+a363);
  a296=(a217*a296);
  a362=(a362+a296);
  a318=(a208*a318);
  a296=(a040*a346);
  a318=(a318+a296);
  a362=(a362+a318);
  a362=(a216*a362);
  a361=(a361+a362);
  a293=(a293+a361);
  a348=(a212*a348);
  a154=(a043*a154);
  a348=(a348+a154);
  a293=(a293+a348);
  a325=(a208*a325);
  a346=(a037*a346);
  a325=(a325+a346);
  a293=(a293+a325);
  a293=(a013*a293);
  a231=(a231+a293);
  a335=(a335+a231);
  a236=(a213*a236);
  a306=(a031*a306);
  a289=(a221*a289);
  a333=(a220*a333);
  a322=(a209*a322);
  a231=(a030*a055);
  a322=(a322+a231);
  a322=(a217*a322);
  a333=(a333+a322);
  a327=(a209*a327);
  a322=(a023*a055);
  a327=(a327+a322);
  a333=(a333+a327);
  a333=(a216*a333);
  a289=(a289+a333);
  a306=(a306+a289);
  a303=(a214*a303);
  a299=(a026*a299);
  a303=(a303+a299);
  a306=(a306+a303);
  a337=(a209*a337);
  a303=(a017*a055);
  a337=(a337+a303);
  a306=(a306+a337);
  a306=(a013*a306);
  a236=(a236+a306);
  a335=(a335+a236);
  a335=(a018*a335);
  a332=(a332+a335);
  a329=(a209*a329);
  a335=(a020*a055);
  a329=(a329+a335);
  a329=(a016*a329);
  a332=(a332+a329);
  a055=(a001*a055);
  a332=(a332+a055);
  a055=(a198*a332);
  a304=(a304+a055);
  a055=(a058*a304);
  a326=(a326+a055);
  a055=(a222*a349);
  a358=(a056*a358);
  a358=(a358+a323);
  a351=(a011*a351);
  a358=(a358-a351);
  a360=(a085*a360);
  a358=(a358+a360);
  a360=(a188*a324);
  a353=(a048*a353);
  a360=(a360+a353);
  a353=(a197*a324);
  a359=(a048*a359);
  a353=(a353+a359);
  a360=(a360+a353);
  a353=(a004*a360);
  a358=(a358-a353);
  a202=(a202*a341);
  a324=(a205*a324);
  a321=(a048*a321);
  a324=(a324+a321);
  a356=(a324+a356);
  a356=(a223*a356);
  a202=(a202+a356);
  a358=(a358+a202);
  a202=(a223*a332);
  a202=(a211+a202);
  a358=(a358+a202);
  a202=(a087*a358);
  a202=(a055+a202);
  a326=(a326+a202);
  a352=(a085*a352);
  a354=(a056*a354);
  a352=(a352+a354);
  a324=(a324+a164);
  a324=(a226*a324);
  a352=(a352+a324);
  a352=(a352+a307);
  a357=(a011*a357);
  a352=(a352-a357);
  a360=(a007*a360);
  a182=(a182+a360);
  a352=(a352-a182);
  a332=(a226*a332);
  a352=(a352+a332);
  a332=(a090*a352);
  a285=(a225*a285);
  a332=(a332-a285);
  a326=(a326+a332);
  a285=(a062*a336);
  a182=(a072*a224);
  a182=(a285-a182);
  a309=(a228*a309);
  a345=(a014*a345);
  a298=(a019*a298);
  a345=(a345+a298);
  a345=(a052*a345);
  a309=(a309+a345);
  a345=(a011*a309);
  a298=(a182+a345);
  a298=(a200*a298);
  a360=(a012*a224);
  a360=(a232*a360);
  a298=(a298+a360);
  a360=(a095*a224);
  a347=(a347-a360);
  a360=(a004*a309);
  a347=(a347-a360);
  a347=(a233*a347);
  a298=(a298+a347);
  a298=(a083*a298);
  a326=(a326+a298);
  a326=(a326/a002);
  if (res[1]!=0) res[1][9]=a326;
  a326=(a109*a334);
  a298=(a102*a304);
  a298=(a326+a298);
  a347=(a104*a358);
  a312=(a222*a312);
  a347=(a347-a312);
  a298=(a298+a347);
  a349=(a225*a349);
  a312=(a106*a352);
  a312=(a349+a312);
  a298=(a298+a312);
  a182=(a182-a345);
  a182=(a232*a182);
  a297=(a062*a297);
  a345=(a008*a224);
  a297=(a297-a345);
  a297=(a200*a297);
  a182=(a182-a297);
  a224=(a054*a224);
  a309=(a007*a309);
  a309=(a229-a309);
  a224=(a224+a309);
  a224=(a233*a224);
  a182=(a182-a224);
  a182=(a083*a182);
  a298=(a298-a182);
  a298=(a298/a002);
  if (res[1]!=0) res[1][10]=a298;
  a298=(a108*a304);
  a338=(a109*a338);
  a298=(a298-a338);
  a334=(a222*a334);
  a338=(a111*a358);
  a338=(a334+a338);
  a338=(a298+a338);
  a100=(a225*a100);
  a182=(a113*a352);
  a100=(a100+a182);
  a338=(a338+a100);
  a338=(a338/a002);
  if (res[1]!=0) res[1][11]=a338;
  a338=(a147*a116);
  a100=(a158*a338);
  a300=(a018*a300);
  a294=(a237*a294);
  a300=(a300+a294);
  a294=(a148*a300);
  a100=(a100+a294);
  a294=(a134*a100);
  a182=(a147*a161);
  a224=(a185*a182);
  a270=(a018*a270);
  a355=(a237*a355);
  a270=(a270+a355);
  a355=(a142*a270);
  a224=(a224+a355);
  a355=(a134*a224);
  a294=(a294+a355);
  a355=(a117*a294);
  a340=(a340-a355);
  a355=(a147*a151);
  a309=(a185*a355);
  a297=(a069*a270);
  a309=(a309+a297);
  a297=(a085*a309);
  a340=(a340+a297);
  a297=(a158*a355);
  a345=(a069*a300);
  a297=(a297+a345);
  a345=(a134*a297);
  a312=(a194*a182);
  a315=(a018*a315);
  a344=(a237*a344);
  a315=(a315+a344);
  a344=(a142*a315);
  a312=(a312+a344);
  a344=(a134*a312);
  a345=(a345+a344);
  a344=(a115*a345);
  a340=(a340-a344);
  a344=(a194*a338);
  a360=(a148*a315);
  a344=(a344+a360);
  a360=(a056*a344);
  a340=(a340+a360);
  a338=(a185*a338);
  a270=(a148*a270);
  a338=(a338+a270);
  a270=(a134*a338);
  a355=(a194*a355);
  a315=(a069*a315);
  a355=(a355+a315);
  a315=(a134*a355);
  a360=(a270+a315);
  a360=(a243*a360);
  a340=(a340+a360);
  a182=(a158*a182);
  a300=(a142*a300);
  a182=(a182+a300);
  a300=(a119*a182);
  a360=(a160*a100);
  a300=(a300-a360);
  a360=(a141*a297);
  a300=(a300-a360);
  a360=(a160*a224);
  a300=(a300-a360);
  a338=(a121*a338);
  a300=(a300+a338);
  a338=(a149*a309);
  a300=(a300-a338);
  a338=(a141*a312);
  a300=(a300-a338);
  a338=(a149*a344);
  a300=(a300-a338);
  a355=(a118*a355);
  a300=(a300+a355);
  a355=(a249*a300);
  a355=(a049*a355);
  a338=(a125*a355);
  a300=(a300/a123);
  a338=(a338-a300);
  a360=(a131*a338);
  a357=(a045*a360);
  a307=(a129*a338);
  a324=(a126*a307);
  a324=(a042*a324);
  a357=(a357+a324);
  a324=(a039*a307);
  a357=(a357+a324);
  a324=(a126*a338);
  a324=(a036*a324);
  a357=(a357+a324);
  a324=(a033*a338);
  a357=(a357+a324);
  a324=(a131*a300);
  a164=(a029*a324);
  a357=(a357+a164);
  a164=(a129*a300);
  a354=(a126*a164);
  a354=(a025*a354);
  a357=(a357+a354);
  a354=(a022*a164);
  a357=(a357+a354);
  a355=(a132*a355);
  a360=(a047*a360);
  a354=(a130*a338);
  a354=(a262*a354);
  a202=(a127*a338);
  a354=(a354+a202);
  a354=(a261*a354);
  a360=(a360+a354);
  a307=(a128*a307);
  a360=(a360+a307);
  a338=(a124*a338);
  a360=(a360+a338);
  a360=(a122*a360);
  a355=(a355+a360);
  a324=(a031*a324);
  a360=(a138*a300);
  a360=(a262*a360);
  a338=(a136*a300);
  a360=(a360+a338);
  a360=(a261*a360);
  a324=(a324+a360);
  a164=(a137*a164);
  a324=(a324+a164);
  a164=(a135*a300);
  a324=(a324+a164);
  a324=(a122*a324);
  a355=(a355+a324);
  a355=(a018*a355);
  a357=(a357+a355);
  a355=(a126*a300);
  a355=(a016*a355);
  a357=(a357+a355);
  a300=(a001*a300);
  a357=(a357+a300);
  a300=(a243*a357);
  a340=(a340+a300);
  a300=(a153*a340);
  a297=(a056*a297);
  a308=(a308+a297);
  a294=(a120*a294);
  a308=(a308-a294);
  a312=(a085*a312);
  a308=(a308+a312);
  a309=(a134*a309);
  a344=(a134*a344);
  a309=(a309+a344);
  a344=(a115*a309);
  a308=(a308-a344);
  a182=(a134*a182);
  a315=(a182+a315);
  a315=(a267*a315);
  a308=(a308+a315);
  a315=(a267*a357);
  a308=(a308+a315);
  a315=(a156*a308);
  a300=(a300+a315);
  a100=(a085*a100);
  a343=(a343+a100);
  a224=(a056*a224);
  a343=(a343+a224);
  a182=(a182+a270);
  a182=(a269*a182);
  a343=(a343+a182);
  a345=(a120*a345);
  a343=(a343-a345);
  a309=(a117*a309);
  a343=(a343-a309);
  a357=(a269*a357);
  a343=(a343+a357);
  a357=(a157*a343);
  a300=(a300+a357);
  a300=(a300/a002);
  if (res[1]!=0) res[1][12]=a300;
  a300=(a166*a340);
  a309=(a167*a308);
  a300=(a300+a309);
  a345=(a169*a343);
  a300=(a300+a345);
  a300=(a300/a002);
  if (res[1]!=0) res[1][13]=a300;
  a300=(a171*a340);
  a345=(a173*a308);
  a345=(a300+a345);
  a182=(a175*a343);
  a345=(a345+a182);
  a345=(a345/a002);
  if (res[1]!=0) res[1][14]=a345;
  a345=(2.*a234);
  a182=(a345*a331);
  a270=(a001*a182);
  a224=(a016*a182);
  a224=(a281*a224);
  a100=(a018*a182);
  a315=(a278*a100);
  a344=(a015*a315);
  a224=(a224+a344);
  a270=(a270+a224);
  a224=(a022*a182);
  a344=(a025*a182);
  a344=(a281*a344);
  a312=(a024*a315);
  a344=(a344+a312);
  a224=(a224+a344);
  a224=(a282*a224);
  a344=(a235*a315);
  a312=(a021*a344);
  a224=(a224+a312);
  a270=(a270+a224);
  a224=(a029*a182);
  a312=(a031*a315);
  a224=(a224+a312);
  a224=(a283*a224);
  a312=(a215*a344);
  a294=(a028*a312);
  a224=(a224+a294);
  a270=(a270+a224);
  a224=(a033*a182);
  a294=(a036*a182);
  a294=(a281*a294);
  a297=(a035*a315);
  a294=(a294+a297);
  a224=(a224+a294);
  a294=(a039*a182);
  a297=(a042*a182);
  a297=(a281*a297);
  a355=(a041*a315);
  a297=(a297+a355);
  a294=(a294+a297);
  a294=(a282*a294);
  a344=(a038*a344);
  a294=(a294+a344);
  a224=(a224+a294);
  a294=(a045*a182);
  a315=(a047*a315);
  a294=(a294+a315);
  a294=(a283*a294);
  a312=(a044*a312);
  a294=(a294+a312);
  a224=(a224+a294);
  a270=(a270-a224);
  a270=(a270/a284);
  a100=(a051*a100);
  a224=(a280*a224);
  a100=(a100+a224);
  a100=(a049*a100);
  a100=(a295*a100);
  a270=(a270+a100);
  a100=(a279*a270);
  a224=(a076+a100);
  a224=(a081*a224);
  a294=(a288*a270);
  a312=(a272*a331);
  a312=(a000*a312);
  a294=(a294+a312);
  a315=(a088*a294);
  a224=(a224+a315);
  a315=(a274*a270);
  a182=(a000*a182);
  a315=(a315+a182);
  a315=(a091*a315);
  a224=(a224-a315);
  a315=(a152*a340);
  a224=(a224+a315);
  a315=(a155*a308);
  a224=(a224+a315);
  a224=(a224+a357);
  a357=(a083+a301);
  a357=(a109*a357);
  a315=(a057*a304);
  a357=(a357+a315);
  a224=(a224+a357);
  a357=(a086*a358);
  a055=(a055+a357);
  a224=(a224+a055);
  a224=(a224+a332);
  a224=(-a224);
  if (res[1]!=0) res[1][15]=a224;
  a224=(a191*a270);
  a224=(a224+a330);
  a330=(a081*a224);
  a332=(a277*a270);
  a332=(a088*a332);
  a330=(a330-a332);
  a294=(a091*a294);
  a330=(a330+a294);
  a340=(a165*a340);
  a330=(a330+a340);
  a330=(a330+a309);
  a309=(a168*a343);
  a330=(a330+a309);
  a304=(a101*a304);
  a326=(a326+a304);
  a330=(a330+a326);
  a330=(a330+a347);
  a347=(a105*a352);
  a349=(a349+a347);
  a330=(a330+a349);
  a330=(-a330);
  if (res[1]!=0) res[1][16]=a330;
  a224=(a088*a224);
  a270=(a275*a270);
  a270=(a270+a182);
  a270=(a081*a270);
  a224=(a224-a270);
  a100=(a342+a100);
  a100=(a091*a100);
  a224=(a224+a100);
  a224=(a224+a300);
  a308=(a172*a308);
  a224=(a224+a308);
  a343=(a174*a343);
  a224=(a224+a343);
  a224=(a224+a298);
  a358=(a110*a358);
  a334=(a334+a358);
  a224=(a224+a334);
  a301=(a328+a301);
  a301=(a225*a301);
  a352=(a112*a352);
  a301=(a301+a352);
  a224=(a224+a301);
  a224=(-a224);
  if (res[1]!=0) res[1][17]=a224;
  a224=(a198*a002);
  a301=(a001*a224);
  a352=(a016*a224);
  a334=(a020*a352);
  a358=(a018*a224);
  a298=(a013*a358);
  a343=(a017*a298);
  a334=(a334+a343);
  a301=(a301+a334);
  a334=(a022*a224);
  a343=(a025*a224);
  a308=(a020*a343);
  a300=(a026*a298);
  a308=(a308+a300);
  a334=(a334+a308);
  a308=(a027*a334);
  a300=(a216*a298);
  a100=(a023*a300);
  a308=(a308+a100);
  a301=(a301+a308);
  a308=(a029*a224);
  a100=(a031*a298);
  a308=(a308+a100);
  a100=(a032*a308);
  a270=(a217*a300);
  a182=(a030*a270);
  a100=(a100+a182);
  a301=(a301+a100);
  a100=(a033*a224);
  a182=(a036*a224);
  a330=(a020*a182);
  a349=(a037*a298);
  a330=(a330+a349);
  a100=(a100+a330);
  a330=(a039*a224);
  a349=(a042*a224);
  a347=(a020*a349);
  a326=(a043*a298);
  a347=(a347+a326);
  a330=(a330+a347);
  a347=(a027*a330);
  a326=(a040*a300);
  a347=(a347+a326);
  a100=(a100+a347);
  a347=(a045*a224);
  a326=(a047*a298);
  a347=(a347+a326);
  a326=(a032*a347);
  a304=(a046*a270);
  a326=(a326+a304);
  a100=(a100+a326);
  a326=(a301-a100);
  a326=(a326/a053);
  a304=(a034*a358);
  a309=(a019*a100);
  a304=(a304+a309);
  a309=(a049*a304);
  a340=(a204*a309);
  a326=(a326+a340);
  a340=(a054*a326);
  a340=(a340+a350);
  a350=(a109*a340);
  a294=(a052*a301);
  a332=(a014*a304);
  a294=(a294-a332);
  a294=(a100+a294);
  a294=(a018*a294);
  a332=(a054*a294);
  a332=(a332+a316);
  a305=(a305*a304);
  a305=(a056*a305);
  a316=(a007*a305);
  a055=(a332+a316);
  a357=(a079*a055);
  a315=(a011*a305);
  a317=(a317-a315);
  a315=(a072*a294);
  a344=(a317+a315);
  a297=(a075*a344);
  a355=(a008*a294);
  a060=(a060*a224);
  a355=(a355+a060);
  a324=(a067*a355);
  a297=(a297-a324);
  a055=(a077*a055);
  a324=(a066*a064);
  a055=(a055+a324);
  a297=(a297+a055);
  a055=(2.*a297);
  a055=(a080*a055);
  a324=(a082*a340);
  a164=(a072*a326);
  a360=(a164-a328);
  a338=(a089*a360);
  a324=(a324+a338);
  a338=(a008*a326);
  a307=(a048*a224);
  a338=(a338+a307);
  a354=(a092*a338);
  a324=(a324-a354);
  a055=(a055-a324);
  a055=(a055/a083);
  a324=(a064*a055);
  a357=(a357+a324);
  a324=(a095*a294);
  a324=(a324+a314);
  a314=(a004*a305);
  a354=(a324-a314);
  a202=(a098*a354);
  a315=(a315-a317);
  a317=(a067*a315);
  a356=(a012*a294);
  a356=(a356+a060);
  a060=(a075*a356);
  a317=(a317-a060);
  a354=(a077*a354);
  a060=(a066*a097);
  a354=(a354+a060);
  a317=(a317+a354);
  a354=(2.*a317);
  a354=(a099*a354);
  a060=(a095*a326);
  a060=(a060+a319);
  a319=(a082*a060);
  a321=(a012*a326);
  a321=(a321+a307);
  a307=(a089*a321);
  a319=(a319-a307);
  a307=(a164-a083);
  a353=(a092*a307);
  a319=(a319+a353);
  a354=(a354-a319);
  a354=(a354/a083);
  a319=(a097*a354);
  a202=(a202+a319);
  a357=(a357+a202);
  a332=(a332-a316);
  a067=(a067*a332);
  a324=(a324+a314);
  a075=(a075*a324);
  a067=(a067+a075);
  a075=(a066*a103);
  a294=(a009*a294);
  a077=(a077*a294);
  a075=(a075-a077);
  a067=(a067+a075);
  a075=(2.*a067);
  a075=(a107*a075);
  a077=(a089*a060);
  a314=(a009*a326);
  a316=(a082*a314);
  a077=(a077-a316);
  a316=(a092*a340);
  a077=(a077+a316);
  a075=(a075-a077);
  a075=(a075/a083);
  a077=(a103*a075);
  a294=(a094*a294);
  a077=(a077-a294);
  a357=(a357+a077);
  a077=(a059*a357);
  a294=(a302*a145);
  a294=(a080*a294);
  a294=(a294/a083);
  a316=(a145*a294);
  a202=(a302*a162);
  a202=(a099*a202);
  a202=(a202/a083);
  a319=(a162*a202);
  a316=(a316+a319);
  a302=(a302*a170);
  a302=(a107*a302);
  a302=(a302/a083);
  a319=(a170*a302);
  a316=(a316+a319);
  a319=(a114*a316);
  a077=(a077+a319);
  a319=(a180*a326);
  a353=(a178*a317);
  a357=(a177*a357);
  a316=(a059*a316);
  a357=(a357+a316);
  a316=(a002*a357);
  a359=(a176*a316);
  a351=(a002*a077);
  a323=(a018*a351);
  a359=(a359+a323);
  a323=(a071*a359);
  a353=(a353+a323);
  a323=(a048*a353);
  a319=(a319+a323);
  a323=(a187*a326);
  a329=(a186*a067);
  a344=(a079*a344);
  a335=(a074*a055);
  a344=(a344+a335);
  a335=(a005*a354);
  a356=(a098*a356);
  a335=(a335-a356);
  a344=(a344+a335);
  a324=(a094*a324);
  a335=(a096*a075);
  a324=(a324+a335);
  a344=(a344+a324);
  a324=(a177*a344);
  a335=(a151*a294);
  a356=(a116*a202);
  a335=(a335+a356);
  a356=(a161*a302);
  a335=(a335+a356);
  a356=(a059*a335);
  a324=(a324+a356);
  a356=(a002*a324);
  a236=(a176*a356);
  a344=(a059*a344);
  a335=(a114*a335);
  a344=(a344+a335);
  a335=(a002*a344);
  a306=(a018*a335);
  a236=(a236+a306);
  a306=(a061*a236);
  a329=(a329+a306);
  a306=(a048*a329);
  a323=(a323+a306);
  a319=(a319+a323);
  a323=(a007*a319);
  a077=(a077-a323);
  a323=(a186*a297);
  a306=(a070*a236);
  a323=(a323+a306);
  a306=(a085*a323);
  a077=(a077+a306);
  a306=(a189*a326);
  a337=(a178*a297);
  a303=(a070*a359);
  a337=(a337+a303);
  a303=(a048*a337);
  a306=(a306+a303);
  a303=(a196*a326);
  a299=(a195*a067);
  a055=(a065*a055);
  a079=(a079*a355);
  a055=(a055-a079);
  a098=(a098*a315);
  a354=(a073*a354);
  a098=(a098+a354);
  a055=(a055+a098);
  a094=(a094*a332);
  a075=(a063*a075);
  a094=(a094+a075);
  a055=(a055+a094);
  a094=(a177*a055);
  a294=(a146*a294);
  a202=(a150*a202);
  a294=(a294+a202);
  a302=(a144*a302);
  a294=(a294+a302);
  a302=(a059*a294);
  a094=(a094+a302);
  a302=(a002*a094);
  a202=(a176*a302);
  a055=(a059*a055);
  a294=(a114*a294);
  a055=(a055+a294);
  a294=(a002*a055);
  a075=(a018*a294);
  a202=(a202+a075);
  a075=(a061*a202);
  a299=(a299+a075);
  a075=(a048*a299);
  a303=(a303+a075);
  a306=(a306+a303);
  a303=(a004*a306);
  a077=(a077-a303);
  a303=(a195*a317);
  a075=(a071*a202);
  a303=(a303+a075);
  a075=(a056*a303);
  a077=(a077+a075);
  a203=(a203*a341);
  a075=(a199*a326);
  a317=(a186*a317);
  a236=(a071*a236);
  a317=(a317+a236);
  a236=(a048*a317);
  a075=(a075+a236);
  a236=(a201*a326);
  a297=(a195*a297);
  a202=(a070*a202);
  a297=(a297+a202);
  a202=(a048*a297);
  a236=(a236+a202);
  a202=(a075+a236);
  a202=(a198*a202);
  a203=(a203+a202);
  a077=(a077+a203);
  a203=(a208*a270);
  a202=(a207*a358);
  a332=(a326/a053);
  a311=(a311*a309);
  a332=(a332+a311);
  a206=(a206*a332);
  a067=(a178*a067);
  a359=(a061*a359);
  a067=(a067+a359);
  a359=(a009*a067);
  a180=(a180*a313);
  a332=(a095*a353);
  a180=(a180+a332);
  a359=(a359-a180);
  a189=(a189*a336);
  a180=(a054*a337);
  a189=(a189+a180);
  a359=(a359-a189);
  a187=(a187*a313);
  a313=(a095*a329);
  a187=(a187+a313);
  a359=(a359-a187);
  a199=(a199*a224);
  a317=(a012*a317);
  a199=(a199+a317);
  a359=(a359+a199);
  a199=(a072*a323);
  a359=(a359-a199);
  a196=(a196*a336);
  a336=(a054*a299);
  a196=(a196+a336);
  a359=(a359-a196);
  a196=(a072*a303);
  a359=(a359-a196);
  a201=(a201*a224);
  a297=(a008*a297);
  a201=(a201+a297);
  a359=(a359+a201);
  a201=(a204*a359);
  a206=(a206+a201);
  a206=(a049*a206);
  a201=(a019*a206);
  a202=(a202+a201);
  a359=(a359/a053);
  a310=(a310*a309);
  a359=(a359+a310);
  a202=(a202-a359);
  a310=(a032*a202);
  a203=(a203+a310);
  a310=(a045*a203);
  a309=(a212*a298);
  a201=(a208*a300);
  a297=(a027*a202);
  a201=(a201+a297);
  a297=(a020*a201);
  a309=(a309+a297);
  a309=(a042*a309);
  a310=(a310+a309);
  a309=(a039*a201);
  a310=(a310+a309);
  a309=(a208*a298);
  a297=(a020*a202);
  a309=(a309+a297);
  a309=(a036*a309);
  a310=(a310+a309);
  a309=(a033*a202);
  a310=(a310+a309);
  a270=(a209*a270);
  a309=(a032*a359);
  a270=(a270+a309);
  a309=(a029*a270);
  a310=(a310+a309);
  a309=(a214*a298);
  a297=(a209*a300);
  a196=(a027*a359);
  a297=(a297+a196);
  a196=(a020*a297);
  a309=(a309+a196);
  a309=(a025*a309);
  a310=(a310+a309);
  a309=(a022*a297);
  a310=(a310+a309);
  a207=(a207*a100);
  a206=(a034*a206);
  a207=(a207+a206);
  a206=(a056*a224);
  a210=(a210*a206);
  a203=(a047*a203);
  a100=(2.*a298);
  a219=(a219*a100);
  a300=(2.*a300);
  a218=(a218*a300);
  a347=(a208*a347);
  a309=(a046*a202);
  a347=(a347+a309);
  a347=(a217*a347);
  a218=(a218+a347);
  a330=(a208*a330);
  a347=(a040*a202);
  a330=(a330+a347);
  a218=(a218+a330);
  a218=(a216*a218);
  a219=(a219+a218);
  a203=(a203+a219);
  a212=(a212*a349);
  a201=(a043*a201);
  a212=(a212+a201);
  a203=(a203+a212);
  a208=(a208*a182);
  a202=(a037*a202);
  a208=(a208+a202);
  a203=(a203+a208);
  a203=(a013*a203);
  a210=(a210+a203);
  a207=(a207+a210);
  a213=(a213*a206);
  a270=(a031*a270);
  a221=(a221*a100);
  a220=(a220*a300);
  a308=(a209*a308);
  a300=(a030*a359);
  a308=(a308+a300);
  a308=(a217*a308);
  a220=(a220+a308);
  a334=(a209*a334);
  a308=(a023*a359);
  a334=(a334+a308);
  a220=(a220+a334);
  a220=(a216*a220);
  a221=(a221+a220);
  a270=(a270+a221);
  a214=(a214*a343);
  a297=(a026*a297);
  a214=(a214+a297);
  a270=(a270+a214);
  a352=(a209*a352);
  a214=(a017*a359);
  a352=(a352+a214);
  a270=(a270+a352);
  a270=(a013*a270);
  a213=(a213+a270);
  a207=(a207+a213);
  a207=(a018*a207);
  a310=(a310+a207);
  a209=(a209*a298);
  a298=(a020*a359);
  a209=(a209+a298);
  a209=(a016*a209);
  a310=(a310+a209);
  a359=(a001*a359);
  a310=(a310+a359);
  a359=(a198*a310);
  a211=(a211+a359);
  a077=(a077+a211);
  a211=(a058*a077);
  a211=(a350+a211);
  a360=(a222*a360);
  a337=(a056*a337);
  a337=(a337+a344);
  a319=(a011*a319);
  a181=(a181+a319);
  a337=(a337-a181);
  a299=(a085*a299);
  a337=(a337+a299);
  a188=(a188*a326);
  a323=(a048*a323);
  a188=(a188+a323);
  a197=(a197*a326);
  a303=(a048*a303);
  a197=(a197+a303);
  a188=(a188+a197);
  a197=(a004*a188);
  a337=(a337-a197);
  a205=(a205*a326);
  a067=(a048*a067);
  a205=(a205+a067);
  a236=(a205+a236);
  a236=(a223*a236);
  a337=(a337+a236);
  a236=(a223*a310);
  a337=(a337+a236);
  a236=(a087*a337);
  a360=(a360+a236);
  a211=(a211+a360);
  a353=(a085*a353);
  a329=(a056*a329);
  a353=(a353+a329);
  a205=(a205+a075);
  a205=(a226*a205);
  a353=(a353+a205);
  a353=(a353+a055);
  a306=(a011*a306);
  a190=(a190+a306);
  a353=(a353-a190);
  a188=(a007*a188);
  a353=(a353-a188);
  a310=(a226*a310);
  a353=(a353+a310);
  a310=(a090*a353);
  a338=(a225*a338);
  a310=(a310-a338);
  a211=(a211+a310);
  a338=(a095*a305);
  a320=(a320-a338);
  a228=(a228*a304);
  a014=(a014*a358);
  a301=(a019*a301);
  a014=(a014+a301);
  a052=(a052*a014);
  a228=(a228+a052);
  a052=(a004*a228);
  a320=(a320-a052);
  a320=(a233*a320);
  a052=(a072*a305);
  a014=(a011*a228);
  a229=(a229-a014);
  a014=(a052+a229);
  a014=(a200*a014);
  a062=(a062*a224);
  a224=(a012*a305);
  a224=(a062-a224);
  a224=(a232*a224);
  a014=(a014+a224);
  a320=(a320-a014);
  a320=(a083*a320);
  a211=(a211+a320);
  a211=(a211/a002);
  if (res[1]!=0) res[1][18]=a211;
  a211=(a109*a060);
  a320=(a102*a077);
  a320=(a211+a320);
  a014=(a104*a337);
  a321=(a222*a321);
  a014=(a014-a321);
  a320=(a320+a014);
  a307=(a225*a307);
  a321=(a106*a353);
  a307=(a307+a321);
  a320=(a320+a307);
  a229=(a229-a052);
  a229=(a232*a229);
  a052=(a008*a305);
  a062=(a062-a052);
  a062=(a200*a062);
  a229=(a229-a062);
  a305=(a054*a305);
  a285=(a285-a305);
  a228=(a007*a228);
  a285=(a285+a228);
  a285=(a233*a285);
  a229=(a229+a285);
  a229=(a083*a229);
  a320=(a320-a229);
  a320=(a320/a002);
  if (res[1]!=0) res[1][19]=a320;
  a320=(a108*a077);
  a109=(a109*a314);
  a320=(a320-a109);
  a060=(a222*a060);
  a109=(a111*a337);
  a109=(a060+a109);
  a109=(a320+a109);
  a340=(a225*a340);
  a314=(a113*a353);
  a314=(a340+a314);
  a109=(a109+a314);
  a109=(a109/a002);
  if (res[1]!=0) res[1][20]=a109;
  a109=(a147*a162);
  a314=(a158*a109);
  a316=(a018*a316);
  a351=(a237*a351);
  a316=(a316+a351);
  a351=(a148*a316);
  a314=(a314+a351);
  a351=(a134*a314);
  a229=(a147*a170);
  a285=(a185*a229);
  a356=(a018*a356);
  a335=(a237*a335);
  a356=(a356+a335);
  a335=(a142*a356);
  a285=(a285+a335);
  a335=(a134*a285);
  a351=(a351+a335);
  a335=(a117*a351);
  a357=(a357-a335);
  a147=(a147*a145);
  a335=(a185*a147);
  a228=(a069*a356);
  a335=(a335+a228);
  a228=(a085*a335);
  a357=(a357+a228);
  a228=(a158*a147);
  a305=(a069*a316);
  a228=(a228+a305);
  a305=(a134*a228);
  a062=(a194*a229);
  a302=(a018*a302);
  a294=(a237*a294);
  a302=(a302+a294);
  a294=(a142*a302);
  a062=(a062+a294);
  a294=(a134*a062);
  a305=(a305+a294);
  a294=(a115*a305);
  a357=(a357-a294);
  a294=(a194*a109);
  a052=(a148*a302);
  a294=(a294+a052);
  a052=(a056*a294);
  a357=(a357+a052);
  a109=(a185*a109);
  a356=(a148*a356);
  a109=(a109+a356);
  a356=(a134*a109);
  a147=(a194*a147);
  a302=(a069*a302);
  a147=(a147+a302);
  a302=(a134*a147);
  a052=(a356+a302);
  a052=(a243*a052);
  a357=(a357+a052);
  a229=(a158*a229);
  a316=(a142*a316);
  a229=(a229+a316);
  a316=(a119*a229);
  a052=(a160*a314);
  a316=(a316-a052);
  a052=(a141*a228);
  a316=(a316-a052);
  a052=(a160*a285);
  a316=(a316-a052);
  a109=(a121*a109);
  a316=(a316+a109);
  a109=(a149*a335);
  a316=(a316-a109);
  a109=(a141*a062);
  a316=(a316-a109);
  a109=(a149*a294);
  a316=(a316-a109);
  a147=(a118*a147);
  a316=(a316+a147);
  a147=(a249*a316);
  a147=(a049*a147);
  a109=(a125*a147);
  a316=(a316/a123);
  a109=(a109-a316);
  a052=(a131*a109);
  a307=(a045*a052);
  a321=(a129*a109);
  a224=(a126*a321);
  a224=(a042*a224);
  a307=(a307+a224);
  a224=(a039*a321);
  a307=(a307+a224);
  a224=(a126*a109);
  a224=(a036*a224);
  a307=(a307+a224);
  a224=(a033*a109);
  a307=(a307+a224);
  a224=(a131*a316);
  a301=(a029*a224);
  a307=(a307+a301);
  a301=(a129*a316);
  a358=(a126*a301);
  a358=(a025*a358);
  a307=(a307+a358);
  a358=(a022*a301);
  a307=(a307+a358);
  a147=(a132*a147);
  a052=(a047*a052);
  a358=(a130*a109);
  a358=(a262*a358);
  a304=(a127*a109);
  a358=(a358+a304);
  a358=(a261*a358);
  a052=(a052+a358);
  a321=(a128*a321);
  a052=(a052+a321);
  a109=(a124*a109);
  a052=(a052+a109);
  a052=(a122*a052);
  a147=(a147+a052);
  a224=(a031*a224);
  a052=(a138*a316);
  a052=(a262*a052);
  a109=(a136*a316);
  a052=(a052+a109);
  a052=(a261*a052);
  a224=(a224+a052);
  a301=(a137*a301);
  a224=(a224+a301);
  a301=(a135*a316);
  a224=(a224+a301);
  a224=(a122*a224);
  a147=(a147+a224);
  a147=(a018*a147);
  a307=(a307+a147);
  a147=(a126*a316);
  a147=(a016*a147);
  a307=(a307+a147);
  a316=(a001*a316);
  a307=(a307+a316);
  a316=(a243*a307);
  a357=(a357+a316);
  a316=(a153*a357);
  a228=(a056*a228);
  a324=(a324+a228);
  a351=(a120*a351);
  a324=(a324-a351);
  a062=(a085*a062);
  a324=(a324+a062);
  a335=(a134*a335);
  a294=(a134*a294);
  a335=(a335+a294);
  a294=(a115*a335);
  a324=(a324-a294);
  a229=(a134*a229);
  a302=(a229+a302);
  a302=(a267*a302);
  a324=(a324+a302);
  a302=(a267*a307);
  a324=(a324+a302);
  a302=(a156*a324);
  a316=(a316+a302);
  a314=(a085*a314);
  a094=(a094+a314);
  a285=(a056*a285);
  a094=(a094+a285);
  a229=(a229+a356);
  a229=(a269*a229);
  a094=(a094+a229);
  a305=(a120*a305);
  a094=(a094-a305);
  a335=(a117*a335);
  a094=(a094-a335);
  a307=(a269*a307);
  a094=(a094+a307);
  a307=(a157*a094);
  a316=(a316+a307);
  a316=(a316/a002);
  if (res[1]!=0) res[1][21]=a316;
  a316=(a166*a357);
  a335=(a167*a324);
  a316=(a316+a335);
  a305=(a169*a094);
  a316=(a316+a305);
  a316=(a316/a002);
  if (res[1]!=0) res[1][22]=a316;
  a316=(a171*a357);
  a305=(a173*a324);
  a305=(a316+a305);
  a229=(a175*a094);
  a305=(a305+a229);
  a305=(a305/a002);
  if (res[1]!=0) res[1][23]=a305;
  a305=(2.*a276);
  a331=(a305*a331);
  a229=(a001*a331);
  a356=(a016*a331);
  a356=(a281*a356);
  a285=(a018*a331);
  a314=(a278*a285);
  a302=(a015*a314);
  a356=(a356+a302);
  a229=(a229+a356);
  a356=(a022*a331);
  a302=(a025*a331);
  a302=(a281*a302);
  a294=(a024*a314);
  a302=(a302+a294);
  a356=(a356+a302);
  a356=(a282*a356);
  a302=(a235*a314);
  a294=(a021*a302);
  a356=(a356+a294);
  a229=(a229+a356);
  a356=(a029*a331);
  a294=(a031*a314);
  a356=(a356+a294);
  a356=(a283*a356);
  a294=(a215*a302);
  a062=(a028*a294);
  a356=(a356+a062);
  a229=(a229+a356);
  a356=(a033*a331);
  a062=(a036*a331);
  a062=(a281*a062);
  a351=(a035*a314);
  a062=(a062+a351);
  a356=(a356+a062);
  a062=(a039*a331);
  a351=(a042*a331);
  a351=(a281*a351);
  a228=(a041*a314);
  a351=(a351+a228);
  a062=(a062+a351);
  a062=(a282*a062);
  a302=(a038*a302);
  a062=(a062+a302);
  a356=(a356+a062);
  a062=(a045*a331);
  a314=(a047*a314);
  a062=(a062+a314);
  a062=(a283*a062);
  a294=(a044*a294);
  a062=(a062+a294);
  a356=(a356+a062);
  a229=(a229-a356);
  a229=(a229/a284);
  a285=(a051*a285);
  a356=(a280*a356);
  a285=(a285+a356);
  a285=(a049*a285);
  a285=(a295*a285);
  a229=(a229+a285);
  a285=(a279*a229);
  a285=(a285+a312);
  a312=(a081*a285);
  a356=(a288*a229);
  a062=(a342+a356);
  a062=(a088*a062);
  a312=(a312+a062);
  a062=(a274*a229);
  a331=(a000*a331);
  a062=(a062+a331);
  a062=(a091*a062);
  a312=(a312-a062);
  a062=(a152*a357);
  a312=(a312+a062);
  a062=(a155*a324);
  a312=(a312+a062);
  a312=(a312+a307);
  a307=(a057*a077);
  a350=(a350+a307);
  a312=(a312+a350);
  a350=(a328+a164);
  a222=(a222*a350);
  a350=(a086*a337);
  a222=(a222+a350);
  a312=(a312+a222);
  a312=(a312+a310);
  a312=(-a312);
  if (res[1]!=0) res[1][24]=a312;
  a312=(a191*a229);
  a312=(a312+a339);
  a339=(a081*a312);
  a310=(a277*a229);
  a310=(a310+a331);
  a310=(a088*a310);
  a339=(a339-a310);
  a356=(a076+a356);
  a356=(a091*a356);
  a339=(a339+a356);
  a357=(a165*a357);
  a339=(a339+a357);
  a339=(a339+a335);
  a335=(a168*a094);
  a339=(a339+a335);
  a077=(a101*a077);
  a211=(a211+a077);
  a339=(a339+a211);
  a339=(a339+a014);
  a164=(a083+a164);
  a225=(a225*a164);
  a164=(a105*a353);
  a225=(a225+a164);
  a339=(a339+a225);
  a339=(-a339);
  if (res[1]!=0) res[1][25]=a339;
  a312=(a088*a312);
  a229=(a275*a229);
  a229=(a081*a229);
  a312=(a312-a229);
  a285=(a091*a285);
  a312=(a312+a285);
  a312=(a312+a316);
  a324=(a172*a324);
  a312=(a312+a324);
  a094=(a174*a094);
  a312=(a312+a094);
  a312=(a312+a320);
  a337=(a110*a337);
  a060=(a060+a337);
  a312=(a312+a060);
  a353=(a112*a353);
  a340=(a340+a353);
  a312=(a312+a340);
  a312=(-a312);
  if (res[1]!=0) res[1][26]=a312;
  a312=9.2820323027550877e-01;
  a340=(a312*a065);
  a340=(a080*a340);
  a340=(a340/a083);
  a353=(a064*a340);
  a060=(a312*a073);
  a060=(a099*a060);
  a060=(a060/a083);
  a337=(a097*a060);
  a353=(a353+a337);
  a337=(a312*a063);
  a337=(a107*a337);
  a337=(a337/a083);
  a320=(a103*a337);
  a353=(a353+a320);
  a320=(a059*a353);
  a094=(a269*a002);
  a324=(a033*a094);
  a316=(a036*a094);
  a285=(a126*a316);
  a229=(a018*a094);
  a339=(a122*a229);
  a225=(a124*a339);
  a285=(a285+a225);
  a324=(a324+a285);
  a285=(a039*a094);
  a225=(a042*a094);
  a164=(a126*a225);
  a014=(a128*a339);
  a164=(a164+a014);
  a285=(a285+a164);
  a164=(a129*a285);
  a014=(a261*a339);
  a211=(a127*a014);
  a164=(a164+a211);
  a324=(a324+a164);
  a164=(a045*a094);
  a211=(a047*a339);
  a164=(a164+a211);
  a211=(a131*a164);
  a077=(a262*a014);
  a335=(a130*a077);
  a211=(a211+a335);
  a324=(a324+a211);
  a211=(a001*a094);
  a335=(a016*a094);
  a357=(a126*a335);
  a356=(a135*a339);
  a357=(a357+a356);
  a211=(a211+a357);
  a357=(a022*a094);
  a356=(a025*a094);
  a310=(a126*a356);
  a331=(a137*a339);
  a310=(a310+a331);
  a357=(a357+a310);
  a310=(a129*a357);
  a331=(a136*a014);
  a310=(a310+a331);
  a211=(a211+a310);
  a310=(a029*a094);
  a331=(a031*a339);
  a310=(a310+a331);
  a331=(a131*a310);
  a222=(a138*a077);
  a331=(a331+a222);
  a211=(a211+a331);
  a331=(a133*a211);
  a222=(a132*a229);
  a350=(a125*a324);
  a222=(a222+a350);
  a350=(a139*a222);
  a331=(a331-a350);
  a331=(a324+a331);
  a331=(a018*a331);
  a350=(a141*a331);
  a307=(a120*a002);
  a062=(a140*a307);
  a350=(a350+a062);
  a294=(2.*a133);
  a314=(a294*a222);
  a314=(a056*a314);
  a302=(a117*a314);
  a351=(a350+a302);
  a228=(a078*a351);
  a147=(a066*a146);
  a224=(a118*a331);
  a301=(a003*a224);
  a147=(a147-a301);
  a301=(a149*a331);
  a052=(a117*a002);
  a109=(a140*a052);
  a301=(a301+a109);
  a321=(a120*a314);
  a358=(a301-a321);
  a304=(a006*a358);
  a147=(a147+a304);
  a351=(a010*a351);
  a147=(a147+a351);
  a351=(2.*a147);
  a351=(a080*a351);
  a304=(a211-a324);
  a304=(a304/a123);
  a338=(a049*a222);
  a188=(a249*a338);
  a304=(a304+a188);
  a188=(a141*a304);
  a190=(a134*a307);
  a188=(a188+a190);
  a306=(a082*a188);
  a351=(a351-a306);
  a306=(a149*a304);
  a055=(a134*a052);
  a306=(a306+a055);
  a205=(a089*a306);
  a351=(a351-a205);
  a205=(a118*a304);
  a075=(a092*a205);
  a351=(a351+a075);
  a351=(a351/a083);
  a075=(a145*a351);
  a228=(a228+a075);
  a075=(a143*a002);
  a329=(a115*a314);
  a329=(a075-a329);
  a360=(a160*a331);
  a236=(a329+a360);
  a067=(a163*a236);
  a301=(a301+a321);
  a321=(a003*a301);
  a326=(a066*a150);
  a321=(a321+a326);
  a326=(a121*a331);
  a197=(a140*a094);
  a326=(a326+a197);
  a303=(a006*a326);
  a321=(a321-a303);
  a236=(a010*a236);
  a321=(a321+a236);
  a236=(2.*a321);
  a236=(a099*a236);
  a303=(a160*a304);
  a323=(a303-a328);
  a299=(a082*a323);
  a236=(a236-a299);
  a299=(a121*a304);
  a181=(a134*a094);
  a299=(a299+a181);
  a319=(a089*a299);
  a236=(a236+a319);
  a319=(a092*a306);
  a236=(a236-a319);
  a236=(a236/a083);
  a319=(a162*a236);
  a067=(a067+a319);
  a228=(a228+a067);
  a350=(a350-a302);
  a302=(a003*a350);
  a067=(a066*a144);
  a302=(a302+a067);
  a360=(a360-a329);
  a329=(a006*a360);
  a302=(a302+a329);
  a331=(a119*a331);
  a331=(a331+a197);
  a197=(a010*a331);
  a302=(a302-a197);
  a197=(2.*a302);
  a197=(a107*a197);
  a329=(a119*a304);
  a329=(a329+a181);
  a181=(a082*a329);
  a197=(a197+a181);
  a181=(a303-a083);
  a067=(a089*a181);
  a197=(a197-a067);
  a067=(a092*a188);
  a197=(a197-a067);
  a197=(a197/a083);
  a067=(a170*a197);
  a331=(a159*a331);
  a067=(a067-a331);
  a228=(a228+a067);
  a067=(a114*a228);
  a320=(a320+a067);
  a067=(a068*a073);
  a331=(a178*a067);
  a353=(a177*a353);
  a228=(a059*a228);
  a353=(a353+a228);
  a228=(a002*a353);
  a319=(a176*a228);
  a344=(a002*a320);
  a359=(a018*a344);
  a319=(a319+a359);
  a359=(a071*a319);
  a331=(a331+a359);
  a359=(a048*a331);
  a209=(a068*a063);
  a298=(a186*a209);
  a207=(a074*a340);
  a213=(a005*a060);
  a207=(a207+a213);
  a213=(a096*a337);
  a207=(a207+a213);
  a213=(a177*a207);
  a358=(a078*a358);
  a270=(a151*a351);
  a358=(a358+a270);
  a270=(a116*a236);
  a326=(a163*a326);
  a270=(a270-a326);
  a358=(a358+a270);
  a360=(a159*a360);
  a270=(a161*a197);
  a360=(a360+a270);
  a358=(a358+a360);
  a360=(a059*a358);
  a213=(a213+a360);
  a360=(a002*a213);
  a270=(a176*a360);
  a207=(a059*a207);
  a358=(a114*a358);
  a207=(a207+a358);
  a358=(a002*a207);
  a326=(a018*a358);
  a270=(a270+a326);
  a326=(a061*a270);
  a298=(a298+a326);
  a326=(a048*a298);
  a359=(a359+a326);
  a326=(a007*a359);
  a320=(a320-a326);
  a326=(a068*a065);
  a352=(a186*a326);
  a214=(a070*a270);
  a352=(a352+a214);
  a214=(a085*a352);
  a320=(a320+a214);
  a214=(a178*a326);
  a297=(a070*a319);
  a214=(a214+a297);
  a297=(a048*a214);
  a343=(a195*a209);
  a340=(a065*a340);
  a060=(a073*a060);
  a340=(a340+a060);
  a337=(a063*a337);
  a340=(a340+a337);
  a337=(a177*a340);
  a351=(a146*a351);
  a224=(a078*a224);
  a351=(a351-a224);
  a301=(a163*a301);
  a236=(a150*a236);
  a301=(a301+a236);
  a351=(a351+a301);
  a350=(a159*a350);
  a197=(a144*a197);
  a350=(a350+a197);
  a351=(a351+a350);
  a350=(a059*a351);
  a337=(a337+a350);
  a350=(a002*a337);
  a197=(a176*a350);
  a340=(a059*a340);
  a351=(a114*a351);
  a340=(a340+a351);
  a351=(a002*a340);
  a301=(a018*a351);
  a197=(a197+a301);
  a301=(a061*a197);
  a343=(a343+a301);
  a301=(a048*a343);
  a297=(a297+a301);
  a301=(a004*a297);
  a320=(a320-a301);
  a301=(a195*a067);
  a236=(a071*a197);
  a301=(a301+a236);
  a236=(a056*a301);
  a320=(a320+a236);
  a067=(a186*a067);
  a270=(a071*a270);
  a067=(a067+a270);
  a270=(a048*a067);
  a326=(a195*a326);
  a197=(a070*a197);
  a326=(a326+a197);
  a197=(a048*a326);
  a236=(a270+a197);
  a236=(a198*a236);
  a320=(a320+a236);
  a209=(a178*a209);
  a319=(a061*a319);
  a209=(a209+a319);
  a319=(a009*a209);
  a236=(a095*a331);
  a319=(a319-a236);
  a236=(a054*a214);
  a319=(a319-a236);
  a236=(a095*a298);
  a319=(a319-a236);
  a067=(a012*a067);
  a319=(a319+a067);
  a067=(a072*a352);
  a319=(a319-a067);
  a067=(a054*a343);
  a319=(a319-a067);
  a067=(a072*a301);
  a319=(a319-a067);
  a326=(a008*a326);
  a319=(a319+a326);
  a326=(a204*a319);
  a326=(a049*a326);
  a067=(a019*a326);
  a319=(a319/a053);
  a067=(a067-a319);
  a236=(a032*a067);
  a224=(a045*a236);
  a060=(a027*a067);
  a221=(a020*a060);
  a221=(a042*a221);
  a224=(a224+a221);
  a221=(a039*a060);
  a224=(a224+a221);
  a221=(a020*a067);
  a221=(a036*a221);
  a224=(a224+a221);
  a221=(a033*a067);
  a224=(a224+a221);
  a221=(a032*a319);
  a220=(a029*a221);
  a224=(a224+a220);
  a220=(a027*a319);
  a334=(a020*a220);
  a334=(a025*a334);
  a224=(a224+a334);
  a334=(a022*a220);
  a224=(a224+a334);
  a326=(a034*a326);
  a236=(a047*a236);
  a334=(a046*a067);
  a334=(a217*a334);
  a308=(a040*a067);
  a334=(a334+a308);
  a334=(a216*a334);
  a236=(a236+a334);
  a060=(a043*a060);
  a236=(a236+a060);
  a067=(a037*a067);
  a236=(a236+a067);
  a236=(a013*a236);
  a326=(a326+a236);
  a221=(a031*a221);
  a236=(a030*a319);
  a236=(a217*a236);
  a067=(a023*a319);
  a236=(a236+a067);
  a236=(a216*a236);
  a221=(a221+a236);
  a220=(a026*a220);
  a221=(a221+a220);
  a220=(a017*a319);
  a221=(a221+a220);
  a221=(a013*a221);
  a326=(a326+a221);
  a326=(a018*a326);
  a224=(a224+a326);
  a326=(a020*a319);
  a326=(a016*a326);
  a224=(a224+a326);
  a319=(a001*a319);
  a224=(a224+a319);
  a319=(a198*a224);
  a320=(a320+a319);
  a319=(a058*a320);
  a214=(a056*a214);
  a214=(a214+a207);
  a359=(a011*a359);
  a214=(a214-a359);
  a343=(a085*a343);
  a214=(a214+a343);
  a352=(a048*a352);
  a301=(a048*a301);
  a352=(a352+a301);
  a301=(a004*a352);
  a214=(a214-a301);
  a209=(a048*a209);
  a197=(a209+a197);
  a197=(a223*a197);
  a214=(a214+a197);
  a197=(a223*a224);
  a214=(a214+a197);
  a197=(a087*a214);
  a319=(a319+a197);
  a331=(a085*a331);
  a298=(a056*a298);
  a331=(a331+a298);
  a209=(a209+a270);
  a209=(a226*a209);
  a331=(a331+a209);
  a331=(a331+a340);
  a297=(a011*a297);
  a331=(a331-a297);
  a352=(a007*a352);
  a331=(a331-a352);
  a224=(a226*a224);
  a331=(a331+a224);
  a224=(a090*a331);
  a319=(a319+a224);
  a319=(a319/a002);
  if (res[1]!=0) res[1][27]=a319;
  a319=(a102*a320);
  a352=(a104*a214);
  a319=(a319+a352);
  a297=(a106*a331);
  a319=(a319+a297);
  a319=(a319/a002);
  if (res[1]!=0) res[1][28]=a319;
  a319=(a108*a320);
  a297=(a111*a214);
  a297=(a319+a297);
  a340=(a113*a331);
  a297=(a297+a340);
  a297=(a297/a002);
  if (res[1]!=0) res[1][29]=a297;
  a297=(a143*a052);
  a340=(a149*a314);
  a340=(a297-a340);
  a222=(a230*a222);
  a209=(a139*a229);
  a211=(a125*a211);
  a209=(a209+a211);
  a209=(a133*a209);
  a222=(a222+a209);
  a209=(a120*a222);
  a211=(a340+a209);
  a211=(a200*a211);
  a270=(a143*a094);
  a298=(a121*a314);
  a270=(a270-a298);
  a270=(a232*a270);
  a211=(a211-a270);
  a227=(a227*a002);
  a270=(a115*a222);
  a270=(a227-a270);
  a298=(a160*a314);
  a270=(a270-a298);
  a270=(a233*a270);
  a211=(a211+a270);
  a211=(a083*a211);
  a270=(a093*a188);
  a298=(a179*a304);
  a197=(a158*a321);
  a228=(a018*a228);
  a344=(a237*a344);
  a228=(a228+a344);
  a344=(a148*a228);
  a197=(a197+a344);
  a344=(a134*a197);
  a298=(a298+a344);
  a344=(a184*a304);
  a301=(a185*a302);
  a360=(a018*a360);
  a358=(a237*a358);
  a360=(a360+a358);
  a358=(a142*a360);
  a301=(a301+a358);
  a358=(a134*a301);
  a344=(a344+a358);
  a298=(a298+a344);
  a344=(a117*a298);
  a353=(a353-a344);
  a344=(a185*a147);
  a358=(a069*a360);
  a344=(a344+a358);
  a358=(a085*a344);
  a353=(a353+a358);
  a241=(a241*a002);
  a358=(a240*a304);
  a343=(a158*a147);
  a359=(a069*a228);
  a343=(a343+a359);
  a359=(a134*a343);
  a358=(a358+a359);
  a359=(a193*a304);
  a207=(a194*a302);
  a350=(a018*a350);
  a351=(a237*a351);
  a350=(a350+a351);
  a351=(a142*a350);
  a207=(a207+a351);
  a351=(a134*a207);
  a359=(a359+a351);
  a358=(a358+a359);
  a359=(a115*a358);
  a359=(a241+a359);
  a353=(a353-a359);
  a359=(a194*a321);
  a351=(a148*a350);
  a359=(a359+a351);
  a351=(a056*a359);
  a353=(a353+a351);
  a351=(a244*a304);
  a321=(a185*a321);
  a360=(a148*a360);
  a321=(a321+a360);
  a360=(a134*a321);
  a351=(a351+a360);
  a360=(a246*a304);
  a147=(a194*a147);
  a350=(a069*a350);
  a147=(a147+a350);
  a350=(a134*a147);
  a360=(a360+a350);
  a350=(a351+a360);
  a350=(a243*a350);
  a353=(a353+a350);
  a350=(a253*a077);
  a229=(a252*a229);
  a326=(a304/a123);
  a221=(a249/a123);
  a220=(a221*a338);
  a326=(a326+a220);
  a326=(a251*a326);
  a220=(a250*a094);
  a302=(a158*a302);
  a228=(a142*a228);
  a302=(a302+a228);
  a228=(a119*a302);
  a220=(a220+a228);
  a228=(a160*a197);
  a220=(a220-a228);
  a228=(a240*a307);
  a236=(a141*a343);
  a228=(a228+a236);
  a220=(a220-a228);
  a228=(a160*a301);
  a220=(a220-a228);
  a228=(a244*a094);
  a321=(a121*a321);
  a228=(a228+a321);
  a220=(a220+a228);
  a228=(a239*a052);
  a321=(a149*a344);
  a228=(a228+a321);
  a220=(a220-a228);
  a228=(a193*a307);
  a321=(a141*a207);
  a228=(a228+a321);
  a220=(a220-a228);
  a228=(a242*a052);
  a321=(a149*a359);
  a228=(a228+a321);
  a220=(a220-a228);
  a147=(a118*a147);
  a220=(a220+a147);
  a147=(a249*a220);
  a326=(a326+a147);
  a326=(a049*a326);
  a147=(a125*a326);
  a229=(a229+a147);
  a220=(a220/a123);
  a147=(a254/a123);
  a338=(a147*a338);
  a220=(a220+a338);
  a229=(a229-a220);
  a338=(a131*a229);
  a350=(a350+a338);
  a338=(a045*a350);
  a228=(a257*a339);
  a321=(a253*a014);
  a236=(a129*a229);
  a321=(a321+a236);
  a236=(a126*a321);
  a228=(a228+a236);
  a228=(a042*a228);
  a338=(a338+a228);
  a228=(a039*a321);
  a338=(a338+a228);
  a228=(a253*a339);
  a236=(a126*a229);
  a228=(a228+a236);
  a228=(a036*a228);
  a338=(a338+a228);
  a228=(a033*a229);
  a338=(a338+a228);
  a077=(a254*a077);
  a228=(a131*a220);
  a077=(a077+a228);
  a228=(a029*a077);
  a338=(a338+a228);
  a228=(a259*a339);
  a236=(a254*a014);
  a067=(a129*a220);
  a236=(a236+a067);
  a067=(a126*a236);
  a228=(a228+a067);
  a228=(a025*a228);
  a338=(a338+a228);
  a228=(a022*a236);
  a338=(a338+a228);
  a324=(a252*a324);
  a326=(a132*a326);
  a324=(a324+a326);
  a094=(a056*a094);
  a326=(a255*a094);
  a350=(a047*a350);
  a228=(2.*a339);
  a067=(a264*a228);
  a014=(2.*a014);
  a060=(a263*a014);
  a164=(a253*a164);
  a334=(a130*a229);
  a164=(a164+a334);
  a164=(a262*a164);
  a060=(a060+a164);
  a285=(a253*a285);
  a164=(a127*a229);
  a285=(a285+a164);
  a060=(a060+a285);
  a060=(a261*a060);
  a067=(a067+a060);
  a350=(a350+a067);
  a225=(a257*a225);
  a321=(a128*a321);
  a225=(a225+a321);
  a350=(a350+a225);
  a316=(a253*a316);
  a229=(a124*a229);
  a316=(a316+a229);
  a350=(a350+a316);
  a350=(a122*a350);
  a326=(a326+a350);
  a324=(a324+a326);
  a094=(a258*a094);
  a077=(a031*a077);
  a228=(a266*a228);
  a014=(a265*a014);
  a310=(a254*a310);
  a326=(a138*a220);
  a310=(a310+a326);
  a310=(a262*a310);
  a014=(a014+a310);
  a357=(a254*a357);
  a310=(a136*a220);
  a357=(a357+a310);
  a014=(a014+a357);
  a014=(a261*a014);
  a228=(a228+a014);
  a077=(a077+a228);
  a356=(a259*a356);
  a236=(a137*a236);
  a356=(a356+a236);
  a077=(a077+a356);
  a335=(a254*a335);
  a356=(a135*a220);
  a335=(a335+a356);
  a077=(a077+a335);
  a077=(a122*a077);
  a094=(a094+a077);
  a324=(a324+a094);
  a324=(a018*a324);
  a338=(a338+a324);
  a339=(a254*a339);
  a324=(a126*a220);
  a339=(a339+a324);
  a339=(a016*a339);
  a338=(a338+a339);
  a220=(a001*a220);
  a338=(a338+a220);
  a220=(a243*a338);
  a353=(a353+a220);
  a220=(a153*a353);
  a220=(a270+a220);
  a211=(a211+a220);
  a220=(a183*a306);
  a343=(a056*a343);
  a213=(a213+a343);
  a298=(a120*a298);
  a213=(a213-a298);
  a207=(a085*a207);
  a213=(a213+a207);
  a260=(a260*a002);
  a207=(a239*a304);
  a344=(a134*a344);
  a207=(a207+a344);
  a344=(a242*a304);
  a359=(a134*a359);
  a344=(a344+a359);
  a207=(a207+a344);
  a344=(a115*a207);
  a344=(a260+a344);
  a213=(a213-a344);
  a304=(a250*a304);
  a302=(a134*a302);
  a304=(a304+a302);
  a360=(a304+a360);
  a360=(a267*a360);
  a213=(a213+a360);
  a360=(a267*a338);
  a213=(a213+a360);
  a360=(a156*a213);
  a360=(a220+a360);
  a211=(a211+a360);
  a197=(a085*a197);
  a337=(a337+a197);
  a301=(a056*a301);
  a337=(a337+a301);
  a268=(a268*a341);
  a304=(a304+a351);
  a304=(a269*a304);
  a268=(a268+a304);
  a337=(a337+a268);
  a358=(a120*a358);
  a337=(a337-a358);
  a207=(a117*a207);
  a337=(a337-a207);
  a256=(a256*a341);
  a338=(a269*a338);
  a338=(a256+a338);
  a337=(a337+a338);
  a338=(a157*a337);
  a205=(a192*a205);
  a338=(a338-a205);
  a211=(a211+a338);
  a211=(a211/a002);
  if (res[1]!=0) res[1][30]=a211;
  a323=(a093*a323);
  a211=(a166*a353);
  a323=(a323+a211);
  a211=(a118*a314);
  a211=(a200*a211);
  a340=(a340-a209);
  a340=(a232*a340);
  a211=(a211+a340);
  a340=(a143*a307);
  a314=(a141*a314);
  a314=(a340-a314);
  a222=(a117*a222);
  a314=(a314+a222);
  a314=(a233*a314);
  a211=(a211+a314);
  a211=(a083*a211);
  a323=(a323-a211);
  a211=(a167*a213);
  a299=(a183*a299);
  a211=(a211-a299);
  a323=(a323+a211);
  a306=(a192*a306);
  a299=(a169*a337);
  a299=(a306+a299);
  a323=(a323+a299);
  a323=(a323/a002);
  if (res[1]!=0) res[1][31]=a323;
  a323=(a171*a353);
  a329=(a093*a329);
  a323=(a323-a329);
  a181=(a183*a181);
  a329=(a173*a213);
  a181=(a181+a329);
  a181=(a323+a181);
  a188=(a192*a188);
  a329=(a175*a337);
  a329=(a188+a329);
  a181=(a181+a329);
  a181=(a181/a002);
  if (res[1]!=0) res[1][32]=a181;
  a181=1.7320508075688774e+00;
  a181=(a181*a002);
  a291=(a291*a181);
  a329=(a001*a291);
  a299=(a016*a291);
  a299=(a281*a299);
  a314=(a018*a291);
  a222=(a278*a314);
  a209=(a015*a222);
  a299=(a299+a209);
  a329=(a329+a299);
  a299=(a022*a291);
  a209=(a025*a291);
  a209=(a281*a209);
  a205=(a024*a222);
  a209=(a209+a205);
  a299=(a299+a209);
  a299=(a282*a299);
  a209=(a235*a222);
  a205=(a021*a209);
  a299=(a299+a205);
  a329=(a329+a299);
  a299=(a029*a291);
  a205=(a031*a222);
  a299=(a299+a205);
  a299=(a283*a299);
  a205=(a215*a209);
  a207=(a028*a205);
  a299=(a299+a207);
  a329=(a329+a299);
  a299=(a033*a291);
  a207=(a036*a291);
  a207=(a281*a207);
  a358=(a035*a222);
  a207=(a207+a358);
  a299=(a299+a207);
  a207=(a039*a291);
  a358=(a042*a291);
  a358=(a281*a358);
  a268=(a041*a222);
  a358=(a358+a268);
  a207=(a207+a358);
  a207=(a282*a207);
  a209=(a038*a209);
  a207=(a207+a209);
  a299=(a299+a207);
  a207=(a045*a291);
  a222=(a047*a222);
  a207=(a207+a222);
  a207=(a283*a207);
  a205=(a044*a205);
  a207=(a207+a205);
  a299=(a299+a207);
  a329=(a329-a299);
  a329=(a329/a284);
  a314=(a051*a314);
  a299=(a280*a299);
  a314=(a314+a299);
  a314=(a049*a314);
  a314=(a295*a314);
  a329=(a329+a314);
  a314=(a279*a329);
  a276=(a276*a181);
  a276=(a000*a276);
  a314=(a314+a276);
  a299=(a081*a314);
  a207=(a288*a329);
  a234=(a234*a181);
  a234=(a000*a234);
  a207=(a207+a234);
  a205=(a088*a207);
  a299=(a299+a205);
  a205=(a274*a329);
  a205=(a091*a205);
  a299=(a299-a205);
  a205=(a152*a353);
  a270=(a270+a205);
  a299=(a299+a270);
  a270=(a155*a213);
  a220=(a220+a270);
  a299=(a299+a220);
  a299=(a299+a338);
  a338=(a057*a320);
  a299=(a299+a338);
  a338=(a086*a214);
  a299=(a299+a338);
  a299=(a299+a224);
  a299=(-a299);
  if (res[1]!=0) res[1][33]=a299;
  a299=(a191*a329);
  a224=(a076+a299);
  a224=(a081*a224);
  a338=(a277*a329);
  a291=(a000*a291);
  a338=(a338+a291);
  a338=(a088*a338);
  a224=(a224-a338);
  a207=(a091*a207);
  a224=(a224+a207);
  a207=(a328+a303);
  a207=(a093*a207);
  a353=(a165*a353);
  a207=(a207+a353);
  a224=(a224+a207);
  a224=(a224+a211);
  a211=(a168*a337);
  a306=(a306+a211);
  a224=(a224+a306);
  a320=(a101*a320);
  a224=(a224+a320);
  a224=(a224+a352);
  a352=(a105*a331);
  a224=(a224+a352);
  a224=(-a224);
  if (res[1]!=0) res[1][34]=a224;
  a299=(a342+a299);
  a299=(a088*a299);
  a329=(a275*a329);
  a329=(a329+a291);
  a329=(a081*a329);
  a299=(a299-a329);
  a314=(a091*a314);
  a299=(a299+a314);
  a299=(a299+a323);
  a303=(a083+a303);
  a303=(a183*a303);
  a213=(a172*a213);
  a303=(a303+a213);
  a299=(a299+a303);
  a337=(a174*a337);
  a188=(a188+a337);
  a299=(a299+a188);
  a299=(a299+a319);
  a214=(a110*a214);
  a299=(a299+a214);
  a331=(a112*a331);
  a299=(a299+a331);
  a299=(-a299);
  if (res[1]!=0) res[1][35]=a299;
  a299=(a312*a074);
  a299=(a080*a299);
  a299=(a299/a083);
  a331=(a064*a299);
  a214=(a312*a005);
  a214=(a099*a214);
  a214=(a214/a083);
  a319=(a097*a214);
  a331=(a331+a319);
  a319=(a312*a096);
  a319=(a107*a319);
  a319=(a319/a083);
  a188=(a103*a319);
  a331=(a331+a188);
  a188=(a059*a331);
  a337=(a267*a002);
  a303=(a033*a337);
  a213=(a036*a337);
  a323=(a126*a213);
  a314=(a018*a337);
  a329=(a122*a314);
  a291=(a124*a329);
  a323=(a323+a291);
  a303=(a303+a323);
  a323=(a039*a337);
  a291=(a042*a337);
  a224=(a126*a291);
  a352=(a128*a329);
  a224=(a224+a352);
  a323=(a323+a224);
  a224=(a129*a323);
  a352=(a261*a329);
  a320=(a127*a352);
  a224=(a224+a320);
  a303=(a303+a224);
  a224=(a045*a337);
  a320=(a047*a329);
  a224=(a224+a320);
  a320=(a131*a224);
  a306=(a262*a352);
  a211=(a130*a306);
  a320=(a320+a211);
  a303=(a303+a320);
  a320=(a001*a337);
  a211=(a016*a337);
  a207=(a126*a211);
  a353=(a135*a329);
  a207=(a207+a353);
  a320=(a320+a207);
  a207=(a022*a337);
  a353=(a025*a337);
  a338=(a126*a353);
  a220=(a137*a329);
  a338=(a338+a220);
  a207=(a207+a338);
  a338=(a129*a207);
  a220=(a136*a352);
  a338=(a338+a220);
  a320=(a320+a338);
  a338=(a029*a337);
  a220=(a031*a329);
  a338=(a338+a220);
  a220=(a131*a338);
  a270=(a138*a306);
  a220=(a220+a270);
  a320=(a320+a220);
  a220=(a133*a320);
  a270=(a132*a314);
  a205=(a125*a303);
  a270=(a270+a205);
  a205=(a139*a270);
  a220=(a220-a205);
  a220=(a303+a220);
  a220=(a018*a220);
  a205=(a141*a220);
  a222=(a294*a270);
  a222=(a056*a222);
  a209=(a117*a222);
  a209=(a075-a209);
  a358=(a205-a209);
  a268=(a078*a358);
  a304=(a149*a220);
  a351=(a115*a002);
  a301=(a140*a351);
  a304=(a304+a301);
  a197=(a120*a222);
  a360=(a304-a197);
  a302=(a006*a360);
  a344=(a066*a151);
  a302=(a302+a344);
  a344=(a118*a220);
  a359=(a140*a337);
  a344=(a344+a359);
  a298=(a003*a344);
  a302=(a302-a298);
  a358=(a010*a358);
  a302=(a302+a358);
  a358=(2.*a302);
  a358=(a080*a358);
  a298=(a320-a303);
  a298=(a298/a123);
  a343=(a049*a270);
  a339=(a249*a343);
  a298=(a298+a339);
  a339=(a141*a298);
  a324=(a339-a083);
  a094=(a082*a324);
  a358=(a358-a094);
  a094=(a149*a298);
  a077=(a134*a351);
  a094=(a094+a077);
  a335=(a089*a094);
  a358=(a358-a335);
  a335=(a118*a298);
  a356=(a134*a337);
  a335=(a335+a356);
  a236=(a092*a335);
  a358=(a358+a236);
  a358=(a358/a083);
  a236=(a145*a358);
  a268=(a268+a236);
  a236=(a160*a220);
  a236=(a236+a062);
  a062=(a115*a222);
  a228=(a236-a062);
  a014=(a163*a228);
  a304=(a304+a197);
  a197=(a003*a304);
  a357=(a066*a116);
  a310=(a121*a220);
  a326=(a006*a310);
  a357=(a357-a326);
  a197=(a197+a357);
  a228=(a010*a228);
  a197=(a197+a228);
  a228=(2.*a197);
  a228=(a099*a228);
  a357=(a160*a298);
  a357=(a357+a190);
  a190=(a082*a357);
  a228=(a228-a190);
  a190=(a121*a298);
  a326=(a089*a190);
  a228=(a228+a326);
  a326=(a092*a094);
  a228=(a228-a326);
  a228=(a228/a083);
  a326=(a162*a228);
  a014=(a014+a326);
  a268=(a268+a014);
  a209=(a209+a205);
  a205=(a003*a209);
  a236=(a236+a062);
  a062=(a006*a236);
  a014=(a066*a161);
  a062=(a062+a014);
  a205=(a205+a062);
  a220=(a119*a220);
  a220=(a220+a359);
  a359=(a010*a220);
  a205=(a205-a359);
  a359=(2.*a205);
  a359=(a107*a359);
  a062=(a119*a298);
  a062=(a062+a356);
  a356=(a082*a062);
  a359=(a359+a356);
  a356=(a089*a357);
  a359=(a359-a356);
  a356=(a339-a328);
  a014=(a092*a356);
  a359=(a359-a014);
  a359=(a359/a083);
  a014=(a170*a359);
  a220=(a159*a220);
  a014=(a014-a220);
  a268=(a268+a014);
  a014=(a114*a268);
  a188=(a188+a014);
  a014=(a068*a005);
  a220=(a178*a014);
  a331=(a177*a331);
  a268=(a059*a268);
  a331=(a331+a268);
  a268=(a002*a331);
  a326=(a176*a268);
  a350=(a002*a188);
  a316=(a018*a350);
  a326=(a326+a316);
  a316=(a071*a326);
  a220=(a220+a316);
  a316=(a048*a220);
  a229=(a068*a096);
  a225=(a186*a229);
  a321=(a074*a299);
  a067=(a005*a214);
  a321=(a321+a067);
  a067=(a096*a319);
  a321=(a321+a067);
  a067=(a177*a321);
  a360=(a078*a360);
  a060=(a151*a358);
  a360=(a360+a060);
  a060=(a116*a228);
  a310=(a163*a310);
  a060=(a060-a310);
  a360=(a360+a060);
  a236=(a159*a236);
  a060=(a161*a359);
  a236=(a236+a060);
  a360=(a360+a236);
  a236=(a059*a360);
  a067=(a067+a236);
  a236=(a002*a067);
  a060=(a176*a236);
  a321=(a059*a321);
  a360=(a114*a360);
  a321=(a321+a360);
  a360=(a002*a321);
  a310=(a018*a360);
  a060=(a060+a310);
  a310=(a061*a060);
  a225=(a225+a310);
  a310=(a048*a225);
  a316=(a316+a310);
  a310=(a007*a316);
  a188=(a188-a310);
  a310=(a068*a074);
  a285=(a186*a310);
  a164=(a070*a060);
  a285=(a285+a164);
  a164=(a085*a285);
  a188=(a188+a164);
  a164=(a178*a310);
  a334=(a070*a326);
  a164=(a164+a334);
  a334=(a048*a164);
  a308=(a195*a229);
  a299=(a065*a299);
  a214=(a073*a214);
  a299=(a299+a214);
  a319=(a063*a319);
  a299=(a299+a319);
  a319=(a177*a299);
  a358=(a146*a358);
  a344=(a078*a344);
  a358=(a358-a344);
  a304=(a163*a304);
  a228=(a150*a228);
  a304=(a304+a228);
  a358=(a358+a304);
  a209=(a159*a209);
  a359=(a144*a359);
  a209=(a209+a359);
  a358=(a358+a209);
  a209=(a059*a358);
  a319=(a319+a209);
  a209=(a002*a319);
  a359=(a176*a209);
  a299=(a059*a299);
  a358=(a114*a358);
  a299=(a299+a358);
  a358=(a002*a299);
  a304=(a018*a358);
  a359=(a359+a304);
  a304=(a061*a359);
  a308=(a308+a304);
  a304=(a048*a308);
  a334=(a334+a304);
  a304=(a004*a334);
  a188=(a188-a304);
  a304=(a195*a014);
  a228=(a071*a359);
  a304=(a304+a228);
  a228=(a056*a304);
  a188=(a188+a228);
  a014=(a186*a014);
  a060=(a071*a060);
  a014=(a014+a060);
  a060=(a048*a014);
  a310=(a195*a310);
  a359=(a070*a359);
  a310=(a310+a359);
  a359=(a048*a310);
  a228=(a060+a359);
  a228=(a198*a228);
  a188=(a188+a228);
  a229=(a178*a229);
  a326=(a061*a326);
  a229=(a229+a326);
  a326=(a009*a229);
  a228=(a095*a220);
  a326=(a326-a228);
  a228=(a054*a164);
  a326=(a326-a228);
  a228=(a095*a225);
  a326=(a326-a228);
  a014=(a012*a014);
  a326=(a326+a014);
  a014=(a072*a285);
  a326=(a326-a014);
  a014=(a054*a308);
  a326=(a326-a014);
  a014=(a072*a304);
  a326=(a326-a014);
  a310=(a008*a310);
  a326=(a326+a310);
  a310=(a204*a326);
  a310=(a049*a310);
  a014=(a019*a310);
  a326=(a326/a053);
  a014=(a014-a326);
  a228=(a032*a014);
  a344=(a045*a228);
  a214=(a027*a014);
  a300=(a020*a214);
  a300=(a042*a300);
  a344=(a344+a300);
  a300=(a039*a214);
  a344=(a344+a300);
  a300=(a020*a014);
  a300=(a036*a300);
  a344=(a344+a300);
  a300=(a033*a014);
  a344=(a344+a300);
  a300=(a032*a326);
  a100=(a029*a300);
  a344=(a344+a100);
  a100=(a027*a326);
  a206=(a020*a100);
  a206=(a025*a206);
  a344=(a344+a206);
  a206=(a022*a100);
  a344=(a344+a206);
  a310=(a034*a310);
  a228=(a047*a228);
  a206=(a046*a014);
  a206=(a217*a206);
  a210=(a040*a014);
  a206=(a206+a210);
  a206=(a216*a206);
  a228=(a228+a206);
  a214=(a043*a214);
  a228=(a228+a214);
  a014=(a037*a014);
  a228=(a228+a014);
  a228=(a013*a228);
  a310=(a310+a228);
  a300=(a031*a300);
  a228=(a030*a326);
  a228=(a217*a228);
  a014=(a023*a326);
  a228=(a228+a014);
  a228=(a216*a228);
  a300=(a300+a228);
  a100=(a026*a100);
  a300=(a300+a100);
  a100=(a017*a326);
  a300=(a300+a100);
  a300=(a013*a300);
  a310=(a310+a300);
  a310=(a018*a310);
  a344=(a344+a310);
  a310=(a020*a326);
  a310=(a016*a310);
  a344=(a344+a310);
  a326=(a001*a326);
  a344=(a344+a326);
  a326=(a198*a344);
  a188=(a188+a326);
  a326=(a058*a188);
  a164=(a056*a164);
  a164=(a164+a321);
  a316=(a011*a316);
  a164=(a164-a316);
  a308=(a085*a308);
  a164=(a164+a308);
  a285=(a048*a285);
  a304=(a048*a304);
  a285=(a285+a304);
  a304=(a004*a285);
  a164=(a164-a304);
  a229=(a048*a229);
  a359=(a229+a359);
  a359=(a223*a359);
  a164=(a164+a359);
  a359=(a223*a344);
  a164=(a164+a359);
  a359=(a087*a164);
  a326=(a326+a359);
  a220=(a085*a220);
  a225=(a056*a225);
  a220=(a220+a225);
  a229=(a229+a060);
  a229=(a226*a229);
  a220=(a220+a229);
  a220=(a220+a299);
  a334=(a011*a334);
  a220=(a220-a334);
  a285=(a007*a285);
  a220=(a220-a285);
  a344=(a226*a344);
  a220=(a220+a344);
  a344=(a090*a220);
  a326=(a326+a344);
  a326=(a326/a002);
  if (res[1]!=0) res[1][36]=a326;
  a326=(a102*a188);
  a285=(a104*a164);
  a326=(a326+a285);
  a334=(a106*a220);
  a326=(a326+a334);
  a326=(a326/a002);
  if (res[1]!=0) res[1][37]=a326;
  a326=(a108*a188);
  a334=(a111*a164);
  a334=(a326+a334);
  a299=(a113*a220);
  a334=(a334+a299);
  a334=(a334/a002);
  if (res[1]!=0) res[1][38]=a334;
  a334=(a143*a351);
  a299=(a149*a222);
  a299=(a334-a299);
  a270=(a230*a270);
  a229=(a139*a314);
  a320=(a125*a320);
  a229=(a229+a320);
  a229=(a133*a229);
  a270=(a270+a229);
  a229=(a120*a270);
  a320=(a299+a229);
  a320=(a200*a320);
  a060=(a121*a222);
  a060=(a232*a060);
  a320=(a320+a060);
  a060=(a160*a222);
  a340=(a340-a060);
  a060=(a115*a270);
  a340=(a340-a060);
  a340=(a233*a340);
  a320=(a320+a340);
  a320=(a083*a320);
  a324=(a093*a324);
  a238=(a238*a002);
  a340=(a179*a298);
  a060=(a158*a197);
  a268=(a018*a268);
  a350=(a237*a350);
  a268=(a268+a350);
  a350=(a148*a268);
  a060=(a060+a350);
  a350=(a134*a060);
  a340=(a340+a350);
  a350=(a184*a298);
  a225=(a185*a205);
  a236=(a018*a236);
  a360=(a237*a360);
  a236=(a236+a360);
  a360=(a142*a236);
  a225=(a225+a360);
  a360=(a134*a225);
  a350=(a350+a360);
  a340=(a340+a350);
  a350=(a117*a340);
  a350=(a238+a350);
  a331=(a331-a350);
  a350=(a185*a302);
  a360=(a069*a236);
  a350=(a350+a360);
  a360=(a085*a350);
  a331=(a331+a360);
  a360=(a240*a298);
  a359=(a158*a302);
  a304=(a069*a268);
  a359=(a359+a304);
  a304=(a134*a359);
  a360=(a360+a304);
  a304=(a193*a298);
  a308=(a194*a205);
  a209=(a018*a209);
  a358=(a237*a358);
  a209=(a209+a358);
  a358=(a142*a209);
  a308=(a308+a358);
  a358=(a134*a308);
  a304=(a304+a358);
  a360=(a360+a304);
  a304=(a115*a360);
  a331=(a331-a304);
  a304=(a194*a197);
  a358=(a148*a209);
  a304=(a304+a358);
  a358=(a056*a304);
  a331=(a331+a358);
  a358=(a244*a298);
  a197=(a185*a197);
  a236=(a148*a236);
  a197=(a197+a236);
  a236=(a134*a197);
  a358=(a358+a236);
  a236=(a246*a298);
  a302=(a194*a302);
  a209=(a069*a209);
  a302=(a302+a209);
  a209=(a134*a302);
  a236=(a236+a209);
  a209=(a358+a236);
  a209=(a243*a209);
  a331=(a331+a209);
  a209=(a253*a306);
  a314=(a252*a314);
  a316=(a298/a123);
  a321=(a221*a343);
  a316=(a316+a321);
  a316=(a251*a316);
  a321=(a250*a337);
  a205=(a158*a205);
  a268=(a142*a268);
  a205=(a205+a268);
  a268=(a119*a205);
  a321=(a321+a268);
  a268=(a179*a307);
  a310=(a160*a060);
  a268=(a268+a310);
  a321=(a321-a268);
  a268=(a141*a359);
  a321=(a321-a268);
  a307=(a184*a307);
  a268=(a160*a225);
  a307=(a307+a268);
  a321=(a321-a307);
  a197=(a121*a197);
  a321=(a321+a197);
  a197=(a239*a351);
  a307=(a149*a350);
  a197=(a197+a307);
  a321=(a321-a197);
  a197=(a141*a308);
  a321=(a321-a197);
  a197=(a242*a351);
  a307=(a149*a304);
  a197=(a197+a307);
  a321=(a321-a197);
  a197=(a246*a337);
  a302=(a118*a302);
  a197=(a197+a302);
  a321=(a321+a197);
  a197=(a249*a321);
  a316=(a316+a197);
  a316=(a049*a316);
  a197=(a125*a316);
  a314=(a314+a197);
  a321=(a321/a123);
  a343=(a147*a343);
  a321=(a321+a343);
  a314=(a314-a321);
  a343=(a131*a314);
  a209=(a209+a343);
  a343=(a045*a209);
  a197=(a257*a329);
  a302=(a253*a352);
  a307=(a129*a314);
  a302=(a302+a307);
  a307=(a126*a302);
  a197=(a197+a307);
  a197=(a042*a197);
  a343=(a343+a197);
  a197=(a039*a302);
  a343=(a343+a197);
  a197=(a253*a329);
  a307=(a126*a314);
  a197=(a197+a307);
  a197=(a036*a197);
  a343=(a343+a197);
  a197=(a033*a314);
  a343=(a343+a197);
  a306=(a254*a306);
  a197=(a131*a321);
  a306=(a306+a197);
  a197=(a029*a306);
  a343=(a343+a197);
  a197=(a259*a329);
  a307=(a254*a352);
  a268=(a129*a321);
  a307=(a307+a268);
  a268=(a126*a307);
  a197=(a197+a268);
  a197=(a025*a197);
  a343=(a343+a197);
  a197=(a022*a307);
  a343=(a343+a197);
  a303=(a252*a303);
  a316=(a132*a316);
  a303=(a303+a316);
  a316=(a056*a337);
  a197=(a255*a316);
  a209=(a047*a209);
  a268=(2.*a329);
  a310=(a264*a268);
  a352=(2.*a352);
  a300=(a263*a352);
  a224=(a253*a224);
  a100=(a130*a314);
  a224=(a224+a100);
  a224=(a262*a224);
  a300=(a300+a224);
  a323=(a253*a323);
  a224=(a127*a314);
  a323=(a323+a224);
  a300=(a300+a323);
  a300=(a261*a300);
  a310=(a310+a300);
  a209=(a209+a310);
  a291=(a257*a291);
  a302=(a128*a302);
  a291=(a291+a302);
  a209=(a209+a291);
  a213=(a253*a213);
  a314=(a124*a314);
  a213=(a213+a314);
  a209=(a209+a213);
  a209=(a122*a209);
  a197=(a197+a209);
  a303=(a303+a197);
  a316=(a258*a316);
  a306=(a031*a306);
  a268=(a266*a268);
  a352=(a265*a352);
  a338=(a254*a338);
  a197=(a138*a321);
  a338=(a338+a197);
  a338=(a262*a338);
  a352=(a352+a338);
  a207=(a254*a207);
  a338=(a136*a321);
  a207=(a207+a338);
  a352=(a352+a207);
  a352=(a261*a352);
  a268=(a268+a352);
  a306=(a306+a268);
  a353=(a259*a353);
  a307=(a137*a307);
  a353=(a353+a307);
  a306=(a306+a353);
  a211=(a254*a211);
  a353=(a135*a321);
  a211=(a211+a353);
  a306=(a306+a211);
  a306=(a122*a306);
  a316=(a316+a306);
  a303=(a303+a316);
  a303=(a018*a303);
  a343=(a343+a303);
  a329=(a254*a329);
  a303=(a126*a321);
  a329=(a329+a303);
  a329=(a016*a329);
  a343=(a343+a329);
  a321=(a001*a321);
  a343=(a343+a321);
  a321=(a243*a343);
  a331=(a331+a321);
  a321=(a153*a331);
  a324=(a324+a321);
  a320=(a320+a324);
  a324=(a183*a094);
  a359=(a056*a359);
  a067=(a067+a359);
  a340=(a120*a340);
  a067=(a067-a340);
  a308=(a085*a308);
  a067=(a067+a308);
  a308=(a239*a298);
  a350=(a134*a350);
  a308=(a308+a350);
  a350=(a242*a298);
  a304=(a134*a304);
  a350=(a350+a304);
  a308=(a308+a350);
  a350=(a115*a308);
  a067=(a067-a350);
  a247=(a247*a341);
  a298=(a250*a298);
  a205=(a134*a205);
  a298=(a298+a205);
  a236=(a298+a236);
  a236=(a267*a236);
  a247=(a247+a236);
  a067=(a067+a247);
  a247=(a267*a343);
  a247=(a256+a247);
  a067=(a067+a247);
  a247=(a156*a067);
  a247=(a324+a247);
  a320=(a320+a247);
  a060=(a085*a060);
  a319=(a319+a060);
  a225=(a056*a225);
  a319=(a319+a225);
  a298=(a298+a358);
  a298=(a269*a298);
  a319=(a319+a298);
  a360=(a120*a360);
  a319=(a319-a360);
  a308=(a117*a308);
  a260=(a260+a308);
  a319=(a319-a260);
  a343=(a269*a343);
  a319=(a319+a343);
  a343=(a157*a319);
  a335=(a192*a335);
  a343=(a343-a335);
  a320=(a320+a343);
  a320=(a320/a002);
  if (res[1]!=0) res[1][39]=a320;
  a320=(a093*a357);
  a335=(a166*a331);
  a335=(a320+a335);
  a299=(a299-a229);
  a299=(a232*a299);
  a337=(a143*a337);
  a229=(a118*a222);
  a337=(a337-a229);
  a337=(a200*a337);
  a299=(a299-a337);
  a222=(a141*a222);
  a270=(a117*a270);
  a270=(a227-a270);
  a222=(a222+a270);
  a222=(a233*a222);
  a299=(a299-a222);
  a299=(a083*a299);
  a335=(a335-a299);
  a299=(a167*a067);
  a190=(a183*a190);
  a299=(a299-a190);
  a335=(a335+a299);
  a094=(a192*a094);
  a190=(a169*a319);
  a190=(a094+a190);
  a335=(a335+a190);
  a335=(a335/a002);
  if (res[1]!=0) res[1][40]=a335;
  a335=(a171*a331);
  a062=(a093*a062);
  a335=(a335-a062);
  a357=(a183*a357);
  a062=(a173*a067);
  a062=(a357+a062);
  a062=(a335+a062);
  a356=(a192*a356);
  a190=(a175*a319);
  a356=(a356+a190);
  a062=(a062+a356);
  a062=(a062/a002);
  if (res[1]!=0) res[1][41]=a062;
  a345=(a345*a181);
  a062=(a001*a345);
  a356=(a016*a345);
  a356=(a281*a356);
  a190=(a018*a345);
  a222=(a278*a190);
  a270=(a015*a222);
  a356=(a356+a270);
  a062=(a062+a356);
  a356=(a022*a345);
  a270=(a025*a345);
  a270=(a281*a270);
  a337=(a024*a222);
  a270=(a270+a337);
  a356=(a356+a270);
  a356=(a282*a356);
  a270=(a235*a222);
  a337=(a021*a270);
  a356=(a356+a337);
  a062=(a062+a356);
  a356=(a029*a345);
  a337=(a031*a222);
  a356=(a356+a337);
  a356=(a283*a356);
  a337=(a215*a270);
  a229=(a028*a337);
  a356=(a356+a229);
  a062=(a062+a356);
  a356=(a033*a345);
  a229=(a036*a345);
  a229=(a281*a229);
  a260=(a035*a222);
  a229=(a229+a260);
  a356=(a356+a229);
  a229=(a039*a345);
  a260=(a042*a345);
  a260=(a281*a260);
  a308=(a041*a222);
  a260=(a260+a308);
  a229=(a229+a260);
  a229=(a282*a229);
  a270=(a038*a270);
  a229=(a229+a270);
  a356=(a356+a229);
  a229=(a045*a345);
  a222=(a047*a222);
  a229=(a229+a222);
  a229=(a283*a229);
  a337=(a044*a337);
  a229=(a229+a337);
  a356=(a356+a229);
  a062=(a062-a356);
  a062=(a062/a284);
  a190=(a051*a190);
  a356=(a280*a356);
  a190=(a190+a356);
  a190=(a049*a190);
  a190=(a295*a190);
  a062=(a062+a190);
  a190=(a279*a062);
  a356=(a342+a190);
  a356=(a081*a356);
  a229=(a288*a062);
  a272=(a272*a181);
  a272=(a000*a272);
  a229=(a229+a272);
  a337=(a088*a229);
  a356=(a356+a337);
  a337=(a274*a062);
  a345=(a000*a345);
  a337=(a337+a345);
  a337=(a091*a337);
  a356=(a356-a337);
  a337=(a083+a339);
  a337=(a093*a337);
  a222=(a152*a331);
  a337=(a337+a222);
  a356=(a356+a337);
  a337=(a155*a067);
  a324=(a324+a337);
  a356=(a356+a324);
  a356=(a356+a343);
  a343=(a057*a188);
  a356=(a356+a343);
  a343=(a086*a164);
  a356=(a356+a343);
  a356=(a356+a344);
  a356=(-a356);
  if (res[1]!=0) res[1][42]=a356;
  a356=(a191*a062);
  a356=(a356+a276);
  a276=(a081*a356);
  a344=(a277*a062);
  a344=(a088*a344);
  a276=(a276-a344);
  a229=(a091*a229);
  a276=(a276+a229);
  a331=(a165*a331);
  a320=(a320+a331);
  a276=(a276+a320);
  a276=(a276+a299);
  a299=(a168*a319);
  a094=(a094+a299);
  a276=(a276+a094);
  a188=(a101*a188);
  a276=(a276+a188);
  a276=(a276+a285);
  a285=(a105*a220);
  a276=(a276+a285);
  a276=(-a276);
  if (res[1]!=0) res[1][43]=a276;
  a356=(a088*a356);
  a062=(a275*a062);
  a062=(a062+a345);
  a062=(a081*a062);
  a356=(a356-a062);
  a190=(a076+a190);
  a190=(a091*a190);
  a356=(a356+a190);
  a356=(a356+a335);
  a067=(a172*a067);
  a357=(a357+a067);
  a356=(a356+a357);
  a339=(a328+a339);
  a339=(a192*a339);
  a319=(a174*a319);
  a339=(a339+a319);
  a356=(a356+a339);
  a356=(a356+a326);
  a164=(a110*a164);
  a356=(a356+a164);
  a220=(a112*a220);
  a356=(a356+a220);
  a356=(-a356);
  if (res[1]!=0) res[1][44]=a356;
  a356=(a312*a064);
  a356=(a080*a356);
  a356=(a356/a083);
  a220=(a064*a356);
  a164=(a312*a097);
  a164=(a099*a164);
  a164=(a164/a083);
  a326=(a097*a164);
  a220=(a220+a326);
  a312=(a312*a103);
  a312=(a107*a312);
  a312=(a312/a083);
  a326=(a103*a312);
  a220=(a220+a326);
  a326=(a059*a220);
  a339=(a243*a002);
  a319=(a033*a339);
  a357=(a036*a339);
  a067=(a126*a357);
  a335=(a018*a339);
  a190=(a122*a335);
  a062=(a124*a190);
  a067=(a067+a062);
  a319=(a319+a067);
  a067=(a039*a339);
  a062=(a042*a339);
  a345=(a126*a062);
  a276=(a128*a190);
  a345=(a345+a276);
  a067=(a067+a345);
  a345=(a129*a067);
  a276=(a261*a190);
  a285=(a127*a276);
  a345=(a345+a285);
  a319=(a319+a345);
  a345=(a045*a339);
  a285=(a047*a190);
  a345=(a345+a285);
  a285=(a131*a345);
  a188=(a262*a276);
  a094=(a130*a188);
  a285=(a285+a094);
  a319=(a319+a285);
  a285=(a001*a339);
  a094=(a016*a339);
  a299=(a126*a094);
  a320=(a135*a190);
  a299=(a299+a320);
  a285=(a285+a299);
  a299=(a022*a339);
  a320=(a025*a339);
  a331=(a126*a320);
  a229=(a137*a190);
  a331=(a331+a229);
  a299=(a299+a331);
  a331=(a129*a299);
  a229=(a136*a276);
  a331=(a331+a229);
  a285=(a285+a331);
  a331=(a029*a339);
  a229=(a031*a190);
  a331=(a331+a229);
  a229=(a131*a331);
  a344=(a138*a188);
  a229=(a229+a344);
  a285=(a285+a229);
  a229=(a133*a285);
  a344=(a132*a335);
  a343=(a125*a319);
  a344=(a344+a343);
  a343=(a139*a344);
  a229=(a229-a343);
  a229=(a319+a229);
  a229=(a018*a229);
  a343=(a141*a229);
  a343=(a343+a301);
  a294=(a294*a344);
  a294=(a056*a294);
  a301=(a117*a294);
  a324=(a343+a301);
  a337=(a078*a324);
  a222=(a120*a294);
  a075=(a075-a222);
  a222=(a149*a229);
  a270=(a075+a222);
  a260=(a006*a270);
  a308=(a118*a229);
  a140=(a140*a339);
  a308=(a308+a140);
  a360=(a003*a308);
  a260=(a260-a360);
  a324=(a010*a324);
  a360=(a066*a145);
  a324=(a324+a360);
  a260=(a260+a324);
  a324=(2.*a260);
  a080=(a080*a324);
  a324=(a285-a319);
  a324=(a324/a123);
  a360=(a049*a344);
  a298=(a249*a360);
  a324=(a324+a298);
  a298=(a141*a324);
  a298=(a298+a077);
  a077=(a082*a298);
  a080=(a080-a077);
  a077=(a149*a324);
  a358=(a077-a328);
  a225=(a089*a358);
  a080=(a080-a225);
  a225=(a118*a324);
  a060=(a134*a339);
  a225=(a225+a060);
  a247=(a092*a225);
  a080=(a080+a247);
  a080=(a080/a083);
  a247=(a145*a080);
  a337=(a337+a247);
  a247=(a160*a229);
  a247=(a247+a109);
  a109=(a115*a294);
  a236=(a247-a109);
  a205=(a163*a236);
  a222=(a222-a075);
  a075=(a003*a222);
  a350=(a121*a229);
  a350=(a350+a140);
  a140=(a006*a350);
  a075=(a075-a140);
  a236=(a010*a236);
  a140=(a066*a162);
  a236=(a236+a140);
  a075=(a075+a236);
  a236=(2.*a075);
  a099=(a099*a236);
  a236=(a160*a324);
  a236=(a236+a055);
  a055=(a082*a236);
  a099=(a099-a055);
  a055=(a121*a324);
  a055=(a055+a060);
  a060=(a089*a055);
  a099=(a099+a060);
  a060=(a077-a083);
  a140=(a092*a060);
  a099=(a099-a140);
  a099=(a099/a083);
  a140=(a162*a099);
  a205=(a205+a140);
  a337=(a337+a205);
  a343=(a343-a301);
  a003=(a003*a343);
  a247=(a247+a109);
  a006=(a006*a247);
  a003=(a003+a006);
  a066=(a066*a170);
  a229=(a119*a229);
  a010=(a010*a229);
  a066=(a066-a010);
  a003=(a003+a066);
  a066=(2.*a003);
  a107=(a107*a066);
  a066=(a119*a324);
  a082=(a082*a066);
  a107=(a107+a082);
  a089=(a089*a236);
  a107=(a107-a089);
  a092=(a092*a298);
  a107=(a107-a092);
  a107=(a107/a083);
  a092=(a170*a107);
  a229=(a159*a229);
  a092=(a092-a229);
  a337=(a337+a092);
  a092=(a114*a337);
  a326=(a326+a092);
  a092=(a068*a097);
  a229=(a178*a092);
  a220=(a177*a220);
  a337=(a059*a337);
  a220=(a220+a337);
  a337=(a002*a220);
  a089=(a176*a337);
  a082=(a002*a326);
  a010=(a018*a082);
  a089=(a089+a010);
  a010=(a071*a089);
  a229=(a229+a010);
  a010=(a048*a229);
  a006=(a068*a103);
  a109=(a186*a006);
  a301=(a074*a356);
  a205=(a005*a164);
  a301=(a301+a205);
  a205=(a096*a312);
  a301=(a301+a205);
  a205=(a177*a301);
  a270=(a078*a270);
  a140=(a151*a080);
  a270=(a270+a140);
  a140=(a116*a099);
  a350=(a163*a350);
  a140=(a140-a350);
  a270=(a270+a140);
  a247=(a159*a247);
  a140=(a161*a107);
  a247=(a247+a140);
  a270=(a270+a247);
  a247=(a059*a270);
  a205=(a205+a247);
  a247=(a002*a205);
  a140=(a176*a247);
  a301=(a059*a301);
  a270=(a114*a270);
  a301=(a301+a270);
  a270=(a002*a301);
  a350=(a018*a270);
  a140=(a140+a350);
  a350=(a061*a140);
  a109=(a109+a350);
  a350=(a048*a109);
  a010=(a010+a350);
  a350=(a007*a010);
  a326=(a326-a350);
  a068=(a068*a064);
  a350=(a186*a068);
  a304=(a070*a140);
  a350=(a350+a304);
  a304=(a085*a350);
  a326=(a326+a304);
  a304=(a178*a068);
  a340=(a070*a089);
  a304=(a304+a340);
  a340=(a048*a304);
  a359=(a195*a006);
  a356=(a065*a356);
  a164=(a073*a164);
  a356=(a356+a164);
  a312=(a063*a312);
  a356=(a356+a312);
  a312=(a177*a356);
  a080=(a146*a080);
  a078=(a078*a308);
  a080=(a080-a078);
  a163=(a163*a222);
  a099=(a150*a099);
  a163=(a163+a099);
  a080=(a080+a163);
  a159=(a159*a343);
  a107=(a144*a107);
  a159=(a159+a107);
  a080=(a080+a159);
  a159=(a059*a080);
  a312=(a312+a159);
  a159=(a002*a312);
  a107=(a176*a159);
  a356=(a059*a356);
  a080=(a114*a080);
  a356=(a356+a080);
  a080=(a002*a356);
  a343=(a018*a080);
  a107=(a107+a343);
  a343=(a061*a107);
  a359=(a359+a343);
  a343=(a048*a359);
  a340=(a340+a343);
  a343=(a004*a340);
  a326=(a326-a343);
  a343=(a195*a092);
  a163=(a071*a107);
  a343=(a343+a163);
  a163=(a056*a343);
  a326=(a326+a163);
  a186=(a186*a092);
  a140=(a071*a140);
  a186=(a186+a140);
  a140=(a048*a186);
  a195=(a195*a068);
  a107=(a070*a107);
  a195=(a195+a107);
  a107=(a048*a195);
  a068=(a140+a107);
  a068=(a198*a068);
  a326=(a326+a068);
  a178=(a178*a006);
  a089=(a061*a089);
  a178=(a178+a089);
  a089=(a009*a178);
  a006=(a095*a229);
  a089=(a089-a006);
  a006=(a054*a304);
  a089=(a089-a006);
  a006=(a095*a109);
  a089=(a089-a006);
  a186=(a012*a186);
  a089=(a089+a186);
  a186=(a072*a350);
  a089=(a089-a186);
  a186=(a054*a359);
  a089=(a089-a186);
  a186=(a072*a343);
  a089=(a089-a186);
  a195=(a008*a195);
  a089=(a089+a195);
  a195=(a204*a089);
  a195=(a049*a195);
  a186=(a019*a195);
  a089=(a089/a053);
  a186=(a186-a089);
  a006=(a032*a186);
  a068=(a045*a006);
  a092=(a027*a186);
  a163=(a020*a092);
  a163=(a042*a163);
  a068=(a068+a163);
  a163=(a039*a092);
  a068=(a068+a163);
  a163=(a020*a186);
  a163=(a036*a163);
  a068=(a068+a163);
  a163=(a033*a186);
  a068=(a068+a163);
  a163=(a032*a089);
  a099=(a029*a163);
  a068=(a068+a099);
  a099=(a027*a089);
  a222=(a020*a099);
  a222=(a025*a222);
  a068=(a068+a222);
  a222=(a022*a099);
  a068=(a068+a222);
  a195=(a034*a195);
  a006=(a047*a006);
  a222=(a046*a186);
  a222=(a217*a222);
  a078=(a040*a186);
  a222=(a222+a078);
  a222=(a216*a222);
  a006=(a006+a222);
  a092=(a043*a092);
  a006=(a006+a092);
  a186=(a037*a186);
  a006=(a006+a186);
  a006=(a013*a006);
  a195=(a195+a006);
  a163=(a031*a163);
  a006=(a030*a089);
  a006=(a217*a006);
  a186=(a023*a089);
  a006=(a006+a186);
  a006=(a216*a006);
  a163=(a163+a006);
  a099=(a026*a099);
  a163=(a163+a099);
  a099=(a017*a089);
  a163=(a163+a099);
  a163=(a013*a163);
  a195=(a195+a163);
  a195=(a018*a195);
  a068=(a068+a195);
  a195=(a020*a089);
  a195=(a016*a195);
  a068=(a068+a195);
  a089=(a001*a089);
  a068=(a068+a089);
  a089=(a198*a068);
  a326=(a326+a089);
  a089=(a058*a326);
  a304=(a056*a304);
  a304=(a304+a301);
  a010=(a011*a010);
  a304=(a304-a010);
  a359=(a085*a359);
  a304=(a304+a359);
  a350=(a048*a350);
  a343=(a048*a343);
  a350=(a350+a343);
  a343=(a004*a350);
  a304=(a304-a343);
  a178=(a048*a178);
  a107=(a178+a107);
  a107=(a223*a107);
  a304=(a304+a107);
  a107=(a223*a068);
  a304=(a304+a107);
  a107=(a087*a304);
  a089=(a089+a107);
  a229=(a085*a229);
  a109=(a056*a109);
  a229=(a229+a109);
  a178=(a178+a140);
  a178=(a226*a178);
  a229=(a229+a178);
  a229=(a229+a356);
  a340=(a011*a340);
  a229=(a229-a340);
  a350=(a007*a350);
  a229=(a229-a350);
  a068=(a226*a068);
  a229=(a229+a068);
  a068=(a090*a229);
  a089=(a089+a068);
  a089=(a089/a002);
  if (res[1]!=0) res[1][45]=a089;
  a089=(a102*a326);
  a350=(a104*a304);
  a089=(a089+a350);
  a340=(a106*a229);
  a089=(a089+a340);
  a089=(a089/a002);
  if (res[1]!=0) res[1][46]=a089;
  a089=(a108*a326);
  a340=(a111*a304);
  a340=(a089+a340);
  a356=(a113*a229);
  a340=(a340+a356);
  a340=(a340/a002);
  if (res[1]!=0) res[1][47]=a340;
  a340=(a160*a294);
  a297=(a297-a340);
  a230=(a230*a344);
  a139=(a139*a335);
  a285=(a125*a285);
  a139=(a139+a285);
  a133=(a133*a139);
  a230=(a230+a133);
  a133=(a115*a230);
  a297=(a297-a133);
  a297=(a233*a297);
  a133=(a149*a294);
  a139=(a120*a230);
  a227=(a227-a139);
  a139=(a133+a227);
  a139=(a200*a139);
  a143=(a143*a339);
  a285=(a121*a294);
  a285=(a143-a285);
  a285=(a232*a285);
  a139=(a139+a285);
  a297=(a297-a139);
  a297=(a083*a297);
  a139=(a093*a298);
  a285=(a179*a324);
  a344=(a158*a075);
  a337=(a018*a337);
  a082=(a237*a082);
  a337=(a337+a082);
  a082=(a148*a337);
  a344=(a344+a082);
  a082=(a134*a344);
  a285=(a285+a082);
  a082=(a184*a324);
  a340=(a185*a003);
  a247=(a018*a247);
  a270=(a237*a270);
  a247=(a247+a270);
  a270=(a142*a247);
  a340=(a340+a270);
  a270=(a134*a340);
  a082=(a082+a270);
  a285=(a285+a082);
  a082=(a117*a285);
  a220=(a220-a082);
  a082=(a185*a260);
  a270=(a069*a247);
  a082=(a082+a270);
  a270=(a085*a082);
  a220=(a220+a270);
  a270=(a240*a324);
  a356=(a158*a260);
  a178=(a069*a337);
  a356=(a356+a178);
  a178=(a134*a356);
  a270=(a270+a178);
  a178=(a193*a324);
  a140=(a194*a003);
  a159=(a018*a159);
  a080=(a237*a080);
  a159=(a159+a080);
  a080=(a142*a159);
  a140=(a140+a080);
  a080=(a134*a140);
  a178=(a178+a080);
  a270=(a270+a178);
  a178=(a115*a270);
  a220=(a220-a178);
  a178=(a194*a075);
  a080=(a148*a159);
  a178=(a178+a080);
  a080=(a056*a178);
  a220=(a220+a080);
  a248=(a248*a341);
  a341=(a244*a324);
  a185=(a185*a075);
  a247=(a148*a247);
  a185=(a185+a247);
  a247=(a134*a185);
  a341=(a341+a247);
  a247=(a246*a324);
  a194=(a194*a260);
  a159=(a069*a159);
  a194=(a194+a159);
  a159=(a134*a194);
  a247=(a247+a159);
  a159=(a341+a247);
  a159=(a243*a159);
  a248=(a248+a159);
  a220=(a220+a248);
  a248=(a253*a188);
  a335=(a252*a335);
  a159=(a324/a123);
  a221=(a221*a360);
  a159=(a159+a221);
  a251=(a251*a159);
  a158=(a158*a003);
  a337=(a142*a337);
  a158=(a158+a337);
  a337=(a119*a158);
  a179=(a179*a052);
  a003=(a160*a344);
  a179=(a179+a003);
  a337=(a337-a179);
  a240=(a240*a351);
  a179=(a141*a356);
  a240=(a240+a179);
  a337=(a337-a240);
  a184=(a184*a052);
  a052=(a160*a340);
  a184=(a184+a052);
  a337=(a337-a184);
  a244=(a244*a339);
  a185=(a121*a185);
  a244=(a244+a185);
  a337=(a337+a244);
  a244=(a149*a082);
  a337=(a337-a244);
  a193=(a193*a351);
  a351=(a141*a140);
  a193=(a193+a351);
  a337=(a337-a193);
  a193=(a149*a178);
  a337=(a337-a193);
  a246=(a246*a339);
  a194=(a118*a194);
  a246=(a246+a194);
  a337=(a337+a246);
  a246=(a249*a337);
  a251=(a251+a246);
  a251=(a049*a251);
  a246=(a125*a251);
  a335=(a335+a246);
  a337=(a337/a123);
  a147=(a147*a360);
  a337=(a337+a147);
  a335=(a335-a337);
  a147=(a131*a335);
  a248=(a248+a147);
  a147=(a045*a248);
  a360=(a257*a190);
  a246=(a253*a276);
  a194=(a129*a335);
  a246=(a246+a194);
  a194=(a126*a246);
  a360=(a360+a194);
  a360=(a042*a360);
  a147=(a147+a360);
  a360=(a039*a246);
  a147=(a147+a360);
  a360=(a253*a190);
  a194=(a126*a335);
  a360=(a360+a194);
  a360=(a036*a360);
  a147=(a147+a360);
  a360=(a033*a335);
  a147=(a147+a360);
  a188=(a254*a188);
  a360=(a131*a337);
  a188=(a188+a360);
  a360=(a029*a188);
  a147=(a147+a360);
  a360=(a259*a190);
  a194=(a254*a276);
  a193=(a129*a337);
  a194=(a194+a193);
  a193=(a126*a194);
  a360=(a360+a193);
  a360=(a025*a360);
  a147=(a147+a360);
  a360=(a022*a194);
  a147=(a147+a360);
  a252=(a252*a319);
  a251=(a132*a251);
  a252=(a252+a251);
  a339=(a056*a339);
  a255=(a255*a339);
  a248=(a047*a248);
  a251=(2.*a190);
  a264=(a264*a251);
  a276=(2.*a276);
  a263=(a263*a276);
  a345=(a253*a345);
  a319=(a130*a335);
  a345=(a345+a319);
  a345=(a262*a345);
  a263=(a263+a345);
  a067=(a253*a067);
  a345=(a127*a335);
  a067=(a067+a345);
  a263=(a263+a067);
  a263=(a261*a263);
  a264=(a264+a263);
  a248=(a248+a264);
  a257=(a257*a062);
  a246=(a128*a246);
  a257=(a257+a246);
  a248=(a248+a257);
  a253=(a253*a357);
  a335=(a124*a335);
  a253=(a253+a335);
  a248=(a248+a253);
  a248=(a122*a248);
  a255=(a255+a248);
  a252=(a252+a255);
  a258=(a258*a339);
  a188=(a031*a188);
  a266=(a266*a251);
  a265=(a265*a276);
  a331=(a254*a331);
  a276=(a138*a337);
  a331=(a331+a276);
  a331=(a262*a331);
  a265=(a265+a331);
  a299=(a254*a299);
  a331=(a136*a337);
  a299=(a299+a331);
  a265=(a265+a299);
  a265=(a261*a265);
  a266=(a266+a265);
  a188=(a188+a266);
  a259=(a259*a320);
  a194=(a137*a194);
  a259=(a259+a194);
  a188=(a188+a259);
  a094=(a254*a094);
  a259=(a135*a337);
  a094=(a094+a259);
  a188=(a188+a094);
  a188=(a122*a188);
  a258=(a258+a188);
  a252=(a252+a258);
  a252=(a018*a252);
  a147=(a147+a252);
  a254=(a254*a190);
  a190=(a126*a337);
  a254=(a254+a190);
  a254=(a016*a254);
  a147=(a147+a254);
  a337=(a001*a337);
  a147=(a147+a337);
  a337=(a243*a147);
  a256=(a256+a337);
  a220=(a220+a256);
  a256=(a153*a220);
  a256=(a139+a256);
  a297=(a297+a256);
  a358=(a183*a358);
  a356=(a056*a356);
  a205=(a205+a356);
  a285=(a120*a285);
  a238=(a238+a285);
  a205=(a205-a238);
  a140=(a085*a140);
  a205=(a205+a140);
  a239=(a239*a324);
  a082=(a134*a082);
  a239=(a239+a082);
  a242=(a242*a324);
  a178=(a134*a178);
  a242=(a242+a178);
  a239=(a239+a242);
  a242=(a115*a239);
  a205=(a205-a242);
  a250=(a250*a324);
  a158=(a134*a158);
  a250=(a250+a158);
  a247=(a250+a247);
  a247=(a267*a247);
  a205=(a205+a247);
  a247=(a267*a147);
  a205=(a205+a247);
  a247=(a156*a205);
  a358=(a358+a247);
  a297=(a297+a358);
  a344=(a085*a344);
  a312=(a312+a344);
  a340=(a056*a340);
  a312=(a312+a340);
  a250=(a250+a341);
  a250=(a269*a250);
  a312=(a312+a250);
  a270=(a120*a270);
  a241=(a241+a270);
  a312=(a312-a241);
  a239=(a117*a239);
  a312=(a312-a239);
  a147=(a269*a147);
  a312=(a312+a147);
  a147=(a157*a312);
  a225=(a192*a225);
  a147=(a147-a225);
  a297=(a297+a147);
  a297=(a297/a002);
  if (res[1]!=0) res[1][48]=a297;
  a297=(a093*a236);
  a225=(a166*a220);
  a225=(a297+a225);
  a227=(a227-a133);
  a232=(a232*a227);
  a227=(a118*a294);
  a143=(a143-a227);
  a200=(a200*a143);
  a232=(a232-a200);
  a294=(a141*a294);
  a334=(a334-a294);
  a230=(a117*a230);
  a334=(a334+a230);
  a233=(a233*a334);
  a232=(a232+a233);
  a232=(a083*a232);
  a225=(a225-a232);
  a232=(a167*a205);
  a055=(a183*a055);
  a232=(a232-a055);
  a225=(a225+a232);
  a060=(a192*a060);
  a055=(a169*a312);
  a060=(a060+a055);
  a225=(a225+a060);
  a225=(a225/a002);
  if (res[1]!=0) res[1][49]=a225;
  a225=(a171*a220);
  a093=(a093*a066);
  a225=(a225-a093);
  a236=(a183*a236);
  a093=(a173*a205);
  a093=(a236+a093);
  a093=(a225+a093);
  a298=(a192*a298);
  a066=(a175*a312);
  a066=(a298+a066);
  a093=(a093+a066);
  a093=(a093/a002);
  if (res[1]!=0) res[1][50]=a093;
  a305=(a305*a181);
  a181=(a001*a305);
  a093=(a016*a305);
  a093=(a281*a093);
  a066=(a018*a305);
  a278=(a278*a066);
  a015=(a015*a278);
  a093=(a093+a015);
  a181=(a181+a093);
  a093=(a022*a305);
  a015=(a025*a305);
  a015=(a281*a015);
  a024=(a024*a278);
  a015=(a015+a024);
  a093=(a093+a015);
  a093=(a282*a093);
  a235=(a235*a278);
  a021=(a021*a235);
  a093=(a093+a021);
  a181=(a181+a093);
  a093=(a029*a305);
  a021=(a031*a278);
  a093=(a093+a021);
  a093=(a283*a093);
  a215=(a215*a235);
  a028=(a028*a215);
  a093=(a093+a028);
  a181=(a181+a093);
  a093=(a033*a305);
  a028=(a036*a305);
  a028=(a281*a028);
  a035=(a035*a278);
  a028=(a028+a035);
  a093=(a093+a028);
  a028=(a039*a305);
  a035=(a042*a305);
  a281=(a281*a035);
  a041=(a041*a278);
  a281=(a281+a041);
  a028=(a028+a281);
  a282=(a282*a028);
  a038=(a038*a235);
  a282=(a282+a038);
  a093=(a093+a282);
  a282=(a045*a305);
  a278=(a047*a278);
  a282=(a282+a278);
  a283=(a283*a282);
  a044=(a044*a215);
  a283=(a283+a044);
  a093=(a093+a283);
  a181=(a181-a093);
  a181=(a181/a284);
  a051=(a051*a066);
  a280=(a280*a093);
  a051=(a051+a280);
  a051=(a049*a051);
  a295=(a295*a051);
  a181=(a181+a295);
  a279=(a279*a181);
  a279=(a279+a272);
  a272=(a081*a279);
  a288=(a288*a181);
  a076=(a076+a288);
  a076=(a088*a076);
  a272=(a272+a076);
  a274=(a274*a181);
  a000=(a000*a305);
  a274=(a274+a000);
  a274=(a091*a274);
  a272=(a272-a274);
  a274=(a152*a220);
  a139=(a139+a274);
  a272=(a272+a139);
  a328=(a328+a077);
  a183=(a183*a328);
  a328=(a155*a205);
  a183=(a183+a328);
  a272=(a272+a183);
  a272=(a272+a147);
  a147=(a057*a326);
  a272=(a272+a147);
  a147=(a086*a304);
  a272=(a272+a147);
  a272=(a272+a068);
  a272=(-a272);
  if (res[1]!=0) res[1][51]=a272;
  a191=(a191*a181);
  a191=(a191+a234);
  a234=(a081*a191);
  a277=(a277*a181);
  a277=(a277+a000);
  a277=(a088*a277);
  a234=(a234-a277);
  a342=(a342+a288);
  a342=(a091*a342);
  a234=(a234+a342);
  a220=(a165*a220);
  a297=(a297+a220);
  a234=(a234+a297);
  a234=(a234+a232);
  a077=(a083+a077);
  a192=(a192*a077);
  a077=(a168*a312);
  a192=(a192+a077);
  a234=(a234+a192);
  a326=(a101*a326);
  a234=(a234+a326);
  a234=(a234+a350);
  a350=(a105*a229);
  a234=(a234+a350);
  a234=(-a234);
  if (res[1]!=0) res[1][52]=a234;
  a088=(a088*a191);
  a275=(a275*a181);
  a081=(a081*a275);
  a088=(a088-a081);
  a091=(a091*a279);
  a088=(a088+a091);
  a088=(a088+a225);
  a205=(a172*a205);
  a236=(a236+a205);
  a088=(a088+a236);
  a312=(a174*a312);
  a298=(a298+a312);
  a088=(a088+a298);
  a088=(a088+a089);
  a304=(a110*a304);
  a088=(a088+a304);
  a229=(a112*a229);
  a088=(a088+a229);
  a088=(-a088);
  if (res[1]!=0) res[1][53]=a088;
  a088=(a064*a090);
  a229=(a097*a106);
  a088=(a088+a229);
  a229=(a103*a113);
  a088=(a088+a229);
  a229=(a177*a088);
  a304=(a145*a157);
  a089=(a162*a169);
  a304=(a304+a089);
  a089=(a170*a175);
  a304=(a304+a089);
  a089=(a059*a304);
  a229=(a229+a089);
  a089=(a002*a229);
  a298=(a176*a089);
  a088=(a059*a088);
  a304=(a114*a304);
  a088=(a088+a304);
  a304=(a002*a088);
  a312=(a018*a304);
  a298=(a298+a312);
  a312=(a071*a298);
  a236=(a048*a312);
  a205=(a074*a090);
  a225=(a005*a106);
  a205=(a205+a225);
  a225=(a096*a113);
  a205=(a205+a225);
  a225=(a177*a205);
  a091=(a151*a157);
  a279=(a116*a169);
  a091=(a091+a279);
  a279=(a161*a175);
  a091=(a091+a279);
  a279=(a059*a091);
  a225=(a225+a279);
  a279=(a002*a225);
  a081=(a176*a279);
  a205=(a059*a205);
  a091=(a114*a091);
  a205=(a205+a091);
  a091=(a002*a205);
  a275=(a018*a091);
  a081=(a081+a275);
  a275=(a061*a081);
  a181=(a048*a275);
  a236=(a236+a181);
  a181=(a007*a236);
  a181=(a181-a088);
  a088=(a070*a081);
  a191=(a085*a088);
  a181=(a181-a191);
  a191=(a065*a090);
  a234=(a073*a106);
  a191=(a191+a234);
  a234=(a063*a113);
  a191=(a191+a234);
  a234=(a177*a191);
  a350=(a146*a157);
  a326=(a150*a169);
  a350=(a350+a326);
  a326=(a144*a175);
  a350=(a350+a326);
  a326=(a059*a350);
  a234=(a234+a326);
  a326=(a002*a234);
  a192=(a176*a326);
  a192=(a083-a192);
  a191=(a059*a191);
  a350=(a114*a350);
  a191=(a191+a350);
  a350=(a002*a191);
  a077=(a018*a350);
  a192=(a192-a077);
  a077=(a061*a192);
  a232=(a048*a077);
  a297=(a070*a298);
  a220=(a048*a297);
  a232=(a232-a220);
  a220=(a004*a232);
  a181=(a181-a220);
  a220=(a071*a192);
  a342=(a056*a220);
  a181=(a181+a342);
  a192=(a070*a192);
  a342=(a048*a192);
  a081=(a071*a081);
  a288=(a048*a081);
  a277=(a342-a288);
  a277=(a198*a277);
  a181=(a181+a277);
  a277=(a095*a312);
  a298=(a061*a298);
  a000=(a009*a298);
  a277=(a277-a000);
  a000=(a054*a297);
  a277=(a277+a000);
  a000=(a095*a275);
  a277=(a277+a000);
  a081=(a012*a081);
  a277=(a277-a081);
  a081=(a072*a088);
  a277=(a277+a081);
  a081=(a054*a077);
  a277=(a277-a081);
  a081=(a072*a220);
  a277=(a277-a081);
  a192=(a008*a192);
  a277=(a277+a192);
  a192=(a204*a277);
  a192=(a049*a192);
  a081=(a019*a192);
  a277=(a277/a053);
  a081=(a081-a277);
  a000=(a032*a081);
  a272=(a045*a000);
  a068=(a027*a081);
  a147=(a020*a068);
  a147=(a042*a147);
  a272=(a272+a147);
  a147=(a039*a068);
  a272=(a272+a147);
  a147=(a020*a081);
  a147=(a036*a147);
  a272=(a272+a147);
  a147=(a033*a081);
  a272=(a272+a147);
  a147=(a032*a277);
  a183=(a029*a147);
  a272=(a272+a183);
  a183=(a027*a277);
  a328=(a020*a183);
  a328=(a025*a328);
  a272=(a272+a328);
  a328=(a022*a183);
  a272=(a272+a328);
  a192=(a034*a192);
  a000=(a047*a000);
  a328=(a046*a081);
  a328=(a217*a328);
  a139=(a040*a081);
  a328=(a328+a139);
  a328=(a216*a328);
  a000=(a000+a328);
  a068=(a043*a068);
  a000=(a000+a068);
  a081=(a037*a081);
  a000=(a000+a081);
  a000=(a013*a000);
  a192=(a192+a000);
  a147=(a031*a147);
  a000=(a030*a277);
  a000=(a217*a000);
  a081=(a023*a277);
  a000=(a000+a081);
  a000=(a216*a000);
  a147=(a147+a000);
  a183=(a026*a183);
  a147=(a147+a183);
  a183=(a017*a277);
  a147=(a147+a183);
  a147=(a013*a147);
  a192=(a192+a147);
  a192=(a018*a192);
  a272=(a272+a192);
  a192=(a020*a277);
  a192=(a016*a192);
  a272=(a272+a192);
  a277=(a001*a277);
  a272=(a272+a277);
  a277=(a198*a272);
  a181=(a181+a277);
  a277=(a058*a181);
  a236=(a011*a236);
  a297=(a056*a297);
  a297=(a297+a205);
  a236=(a236-a297);
  a077=(a085*a077);
  a236=(a236+a077);
  a220=(a048*a220);
  a088=(a048*a088);
  a220=(a220-a088);
  a088=(a004*a220);
  a236=(a236-a088);
  a298=(a048*a298);
  a342=(a342-a298);
  a342=(a223*a342);
  a236=(a236+a342);
  a342=(a223*a272);
  a236=(a236+a342);
  a342=(a087*a236);
  a277=(a277+a342);
  a272=(a226*a272);
  a312=(a085*a312);
  a275=(a056*a275);
  a312=(a312+a275);
  a298=(a298+a288);
  a298=(a226*a298);
  a312=(a312+a298);
  a312=(a312+a191);
  a232=(a011*a232);
  a312=(a312+a232);
  a220=(a007*a220);
  a312=(a312+a220);
  a272=(a272-a312);
  a312=(a090*a272);
  a277=(a277+a312);
  a277=(a277/a002);
  if (res[1]!=0) res[1][54]=a277;
  a277=(a102*a181);
  a220=(a104*a236);
  a277=(a277+a220);
  a232=(a106*a272);
  a277=(a277+a232);
  a277=(a277/a002);
  if (res[1]!=0) res[1][55]=a277;
  a277=(a108*a181);
  a232=(a111*a236);
  a232=(a277+a232);
  a191=(a113*a272);
  a232=(a232+a191);
  a232=(a232/a002);
  if (res[1]!=0) res[1][56]=a232;
  a089=(a018*a089);
  a304=(a237*a304);
  a089=(a089+a304);
  a304=(a148*a089);
  a232=(a134*a304);
  a279=(a018*a279);
  a091=(a237*a091);
  a279=(a279+a091);
  a091=(a142*a279);
  a191=(a134*a091);
  a232=(a232+a191);
  a191=(a117*a232);
  a191=(a191-a229);
  a229=(a069*a279);
  a298=(a085*a229);
  a191=(a191-a298);
  a326=(a018*a326);
  a326=(a083-a326);
  a350=(a237*a350);
  a326=(a326-a350);
  a350=(a142*a326);
  a298=(a134*a350);
  a288=(a069*a089);
  a275=(a134*a288);
  a298=(a298-a275);
  a275=(a115*a298);
  a191=(a191-a275);
  a275=(a148*a326);
  a342=(a056*a275);
  a191=(a191+a342);
  a326=(a069*a326);
  a342=(a134*a326);
  a279=(a148*a279);
  a088=(a134*a279);
  a077=(a342-a088);
  a077=(a243*a077);
  a191=(a191+a077);
  a077=(a160*a304);
  a089=(a142*a089);
  a297=(a119*a089);
  a077=(a077-a297);
  a297=(a141*a288);
  a077=(a077+a297);
  a297=(a160*a091);
  a077=(a077+a297);
  a279=(a121*a279);
  a077=(a077-a279);
  a279=(a149*a229);
  a077=(a077+a279);
  a279=(a141*a350);
  a077=(a077-a279);
  a279=(a149*a275);
  a077=(a077-a279);
  a326=(a118*a326);
  a077=(a077+a326);
  a326=(a249*a077);
  a326=(a049*a326);
  a279=(a125*a326);
  a077=(a077/a123);
  a279=(a279-a077);
  a297=(a131*a279);
  a205=(a045*a297);
  a192=(a129*a279);
  a147=(a126*a192);
  a147=(a042*a147);
  a205=(a205+a147);
  a147=(a039*a192);
  a205=(a205+a147);
  a147=(a126*a279);
  a147=(a036*a147);
  a205=(a205+a147);
  a147=(a033*a279);
  a205=(a205+a147);
  a147=(a131*a077);
  a183=(a029*a147);
  a205=(a205+a183);
  a183=(a129*a077);
  a000=(a126*a183);
  a000=(a025*a000);
  a205=(a205+a000);
  a000=(a022*a183);
  a205=(a205+a000);
  a326=(a132*a326);
  a297=(a047*a297);
  a000=(a130*a279);
  a000=(a262*a000);
  a081=(a127*a279);
  a000=(a000+a081);
  a000=(a261*a000);
  a297=(a297+a000);
  a192=(a128*a192);
  a297=(a297+a192);
  a279=(a124*a279);
  a297=(a297+a279);
  a297=(a122*a297);
  a326=(a326+a297);
  a147=(a031*a147);
  a297=(a138*a077);
  a297=(a262*a297);
  a279=(a136*a077);
  a297=(a297+a279);
  a297=(a261*a297);
  a147=(a147+a297);
  a183=(a137*a183);
  a147=(a147+a183);
  a183=(a135*a077);
  a147=(a147+a183);
  a147=(a122*a147);
  a326=(a326+a147);
  a326=(a018*a326);
  a205=(a205+a326);
  a326=(a126*a077);
  a326=(a016*a326);
  a205=(a205+a326);
  a077=(a001*a077);
  a205=(a205+a077);
  a077=(a243*a205);
  a191=(a191+a077);
  a077=(a153*a191);
  a232=(a120*a232);
  a288=(a056*a288);
  a225=(a225+a288);
  a232=(a232-a225);
  a350=(a085*a350);
  a232=(a232+a350);
  a275=(a134*a275);
  a229=(a134*a229);
  a275=(a275-a229);
  a229=(a115*a275);
  a232=(a232-a229);
  a089=(a134*a089);
  a342=(a342-a089);
  a342=(a267*a342);
  a232=(a232+a342);
  a342=(a267*a205);
  a232=(a232+a342);
  a342=(a156*a232);
  a077=(a077+a342);
  a205=(a269*a205);
  a304=(a085*a304);
  a234=(a234+a304);
  a091=(a056*a091);
  a234=(a234+a091);
  a089=(a089+a088);
  a089=(a269*a089);
  a234=(a234+a089);
  a298=(a120*a298);
  a234=(a234+a298);
  a275=(a117*a275);
  a234=(a234+a275);
  a205=(a205-a234);
  a234=(a157*a205);
  a077=(a077+a234);
  a077=(a077/a002);
  if (res[1]!=0) res[1][57]=a077;
  a077=(a166*a191);
  a275=(a167*a232);
  a077=(a077+a275);
  a298=(a169*a205);
  a077=(a077+a298);
  a077=(a077/a002);
  if (res[1]!=0) res[1][58]=a077;
  a077=(a171*a191);
  a298=(a173*a232);
  a298=(a077+a298);
  a089=(a175*a205);
  a298=(a298+a089);
  a298=(a298/a002);
  if (res[1]!=0) res[1][59]=a298;
  a298=(a152*a191);
  a290=(a290+a298);
  a298=(a155*a232);
  a290=(a290+a298);
  a290=(a290+a234);
  a234=(a057*a181);
  a290=(a290+a234);
  a234=(a086*a236);
  a290=(a290+a234);
  a290=(a290+a312);
  a290=(-a290);
  if (res[1]!=0) res[1][60]=a290;
  a191=(a165*a191);
  a292=(a292+a191);
  a292=(a292+a275);
  a275=(a168*a205);
  a292=(a292+a275);
  a181=(a101*a181);
  a292=(a292+a181);
  a292=(a292+a220);
  a220=(a105*a272);
  a292=(a292+a220);
  a292=(-a292);
  if (res[1]!=0) res[1][61]=a292;
  a245=(a245+a077);
  a232=(a172*a232);
  a245=(a245+a232);
  a205=(a174*a205);
  a245=(a245+a205);
  a245=(a245+a277);
  a236=(a110*a236);
  a245=(a245+a236);
  a272=(a112*a272);
  a245=(a245+a272);
  a245=(-a245);
  if (res[1]!=0) res[1][62]=a245;
  a245=(a074*a087);
  a272=(a005*a104);
  a245=(a245+a272);
  a272=(a096*a111);
  a245=(a245+a272);
  a272=(a177*a245);
  a236=(a151*a156);
  a277=(a116*a167);
  a236=(a236+a277);
  a277=(a161*a173);
  a236=(a236+a277);
  a277=(a059*a236);
  a272=(a272+a277);
  a277=(a002*a272);
  a205=(a176*a277);
  a205=(a083-a205);
  a245=(a059*a245);
  a236=(a114*a236);
  a245=(a245+a236);
  a236=(a002*a245);
  a232=(a018*a236);
  a205=(a205-a232);
  a232=(a070*a205);
  a077=(a085*a232);
  a292=(a064*a087);
  a220=(a097*a104);
  a292=(a292+a220);
  a220=(a103*a111);
  a292=(a292+a220);
  a220=(a059*a292);
  a181=(a145*a156);
  a275=(a162*a167);
  a181=(a181+a275);
  a275=(a170*a173);
  a181=(a181+a275);
  a275=(a114*a181);
  a220=(a220+a275);
  a275=(a061*a205);
  a191=(a048*a275);
  a292=(a177*a292);
  a181=(a059*a181);
  a292=(a292+a181);
  a181=(a002*a292);
  a290=(a176*a181);
  a312=(a002*a220);
  a234=(a018*a312);
  a290=(a290+a234);
  a234=(a071*a290);
  a298=(a048*a234);
  a191=(a191-a298);
  a298=(a007*a191);
  a220=(a220+a298);
  a077=(a077-a220);
  a220=(a070*a290);
  a298=(a048*a220);
  a089=(a065*a087);
  a088=(a073*a104);
  a089=(a089+a088);
  a088=(a063*a111);
  a089=(a089+a088);
  a088=(a177*a089);
  a091=(a146*a156);
  a304=(a150*a167);
  a091=(a091+a304);
  a304=(a144*a173);
  a091=(a091+a304);
  a304=(a059*a091);
  a088=(a088+a304);
  a304=(a002*a088);
  a342=(a176*a304);
  a089=(a059*a089);
  a091=(a114*a091);
  a089=(a089+a091);
  a091=(a002*a089);
  a229=(a018*a091);
  a342=(a342+a229);
  a229=(a061*a342);
  a350=(a048*a229);
  a298=(a298+a350);
  a350=(a004*a298);
  a077=(a077+a350);
  a350=(a071*a342);
  a225=(a056*a350);
  a077=(a077-a225);
  a205=(a071*a205);
  a225=(a048*a205);
  a342=(a070*a342);
  a288=(a048*a342);
  a326=(a225-a288);
  a326=(a198*a326);
  a077=(a077+a326);
  a326=(a095*a234);
  a290=(a061*a290);
  a147=(a009*a290);
  a326=(a326-a147);
  a147=(a054*a220);
  a326=(a326+a147);
  a147=(a095*a275);
  a326=(a326-a147);
  a205=(a012*a205);
  a326=(a326+a205);
  a205=(a072*a232);
  a326=(a326-a205);
  a205=(a054*a229);
  a326=(a326+a205);
  a205=(a072*a350);
  a326=(a326+a205);
  a342=(a008*a342);
  a326=(a326-a342);
  a342=(a204*a326);
  a342=(a049*a342);
  a205=(a019*a342);
  a326=(a326/a053);
  a205=(a205-a326);
  a147=(a032*a205);
  a183=(a045*a147);
  a297=(a027*a205);
  a279=(a020*a297);
  a279=(a042*a279);
  a183=(a183+a279);
  a279=(a039*a297);
  a183=(a183+a279);
  a279=(a020*a205);
  a279=(a036*a279);
  a183=(a183+a279);
  a279=(a033*a205);
  a183=(a183+a279);
  a279=(a032*a326);
  a192=(a029*a279);
  a183=(a183+a192);
  a192=(a027*a326);
  a000=(a020*a192);
  a000=(a025*a000);
  a183=(a183+a000);
  a000=(a022*a192);
  a183=(a183+a000);
  a342=(a034*a342);
  a147=(a047*a147);
  a000=(a046*a205);
  a000=(a217*a000);
  a081=(a040*a205);
  a000=(a000+a081);
  a000=(a216*a000);
  a147=(a147+a000);
  a297=(a043*a297);
  a147=(a147+a297);
  a205=(a037*a205);
  a147=(a147+a205);
  a147=(a013*a147);
  a342=(a342+a147);
  a279=(a031*a279);
  a147=(a030*a326);
  a147=(a217*a147);
  a205=(a023*a326);
  a147=(a147+a205);
  a147=(a216*a147);
  a279=(a279+a147);
  a192=(a026*a192);
  a279=(a279+a192);
  a192=(a017*a326);
  a279=(a279+a192);
  a279=(a013*a279);
  a342=(a342+a279);
  a342=(a018*a342);
  a183=(a183+a342);
  a342=(a020*a326);
  a342=(a016*a342);
  a183=(a183+a342);
  a326=(a001*a326);
  a183=(a183+a326);
  a326=(a198*a183);
  a077=(a077+a326);
  a326=(a058*a077);
  a342=(a223*a183);
  a220=(a056*a220);
  a220=(a220+a245);
  a191=(a011*a191);
  a220=(a220+a191);
  a229=(a085*a229);
  a220=(a220+a229);
  a232=(a048*a232);
  a350=(a048*a350);
  a232=(a232-a350);
  a350=(a004*a232);
  a220=(a220+a350);
  a290=(a048*a290);
  a288=(a290+a288);
  a288=(a223*a288);
  a220=(a220+a288);
  a342=(a342-a220);
  a220=(a087*a342);
  a326=(a326+a220);
  a275=(a056*a275);
  a234=(a085*a234);
  a275=(a275-a234);
  a225=(a225-a290);
  a225=(a226*a225);
  a275=(a275+a225);
  a275=(a275-a089);
  a298=(a011*a298);
  a275=(a275+a298);
  a232=(a007*a232);
  a275=(a275-a232);
  a183=(a226*a183);
  a275=(a275+a183);
  a183=(a090*a275);
  a326=(a326+a183);
  a326=(a326/a002);
  if (res[1]!=0) res[1][63]=a326;
  a326=(a102*a077);
  a232=(a104*a342);
  a326=(a326+a232);
  a298=(a106*a275);
  a326=(a326+a298);
  a326=(a326/a002);
  if (res[1]!=0) res[1][64]=a326;
  a326=(a108*a077);
  a298=(a111*a342);
  a298=(a326+a298);
  a089=(a113*a275);
  a298=(a298+a089);
  a298=(a298/a002);
  if (res[1]!=0) res[1][65]=a298;
  a277=(a018*a277);
  a277=(a083-a277);
  a236=(a237*a236);
  a277=(a277-a236);
  a236=(a069*a277);
  a298=(a085*a236);
  a089=(a142*a277);
  a225=(a134*a089);
  a181=(a018*a181);
  a312=(a237*a312);
  a181=(a181+a312);
  a312=(a148*a181);
  a290=(a134*a312);
  a225=(a225-a290);
  a290=(a117*a225);
  a292=(a292+a290);
  a298=(a298-a292);
  a292=(a069*a181);
  a290=(a134*a292);
  a304=(a018*a304);
  a091=(a237*a091);
  a304=(a304+a091);
  a091=(a142*a304);
  a234=(a134*a091);
  a290=(a290+a234);
  a234=(a115*a290);
  a298=(a298+a234);
  a234=(a148*a304);
  a220=(a056*a234);
  a298=(a298-a220);
  a277=(a148*a277);
  a220=(a134*a277);
  a304=(a069*a304);
  a288=(a134*a304);
  a350=(a220-a288);
  a350=(a243*a350);
  a298=(a298+a350);
  a350=(a160*a312);
  a181=(a142*a181);
  a229=(a119*a181);
  a350=(a350-a229);
  a229=(a141*a292);
  a350=(a350+a229);
  a229=(a160*a089);
  a350=(a350-a229);
  a277=(a121*a277);
  a350=(a350+a277);
  a277=(a149*a236);
  a350=(a350-a277);
  a277=(a141*a091);
  a350=(a350+a277);
  a277=(a149*a234);
  a350=(a350+a277);
  a304=(a118*a304);
  a350=(a350-a304);
  a304=(a249*a350);
  a304=(a049*a304);
  a277=(a125*a304);
  a350=(a350/a123);
  a277=(a277-a350);
  a229=(a131*a277);
  a191=(a045*a229);
  a245=(a129*a277);
  a279=(a126*a245);
  a279=(a042*a279);
  a191=(a191+a279);
  a279=(a039*a245);
  a191=(a191+a279);
  a279=(a126*a277);
  a279=(a036*a279);
  a191=(a191+a279);
  a279=(a033*a277);
  a191=(a191+a279);
  a279=(a131*a350);
  a192=(a029*a279);
  a191=(a191+a192);
  a192=(a129*a350);
  a147=(a126*a192);
  a147=(a025*a147);
  a191=(a191+a147);
  a147=(a022*a192);
  a191=(a191+a147);
  a304=(a132*a304);
  a229=(a047*a229);
  a147=(a130*a277);
  a147=(a262*a147);
  a205=(a127*a277);
  a147=(a147+a205);
  a147=(a261*a147);
  a229=(a229+a147);
  a245=(a128*a245);
  a229=(a229+a245);
  a277=(a124*a277);
  a229=(a229+a277);
  a229=(a122*a229);
  a304=(a304+a229);
  a279=(a031*a279);
  a229=(a138*a350);
  a229=(a262*a229);
  a277=(a136*a350);
  a229=(a229+a277);
  a229=(a261*a229);
  a279=(a279+a229);
  a192=(a137*a192);
  a279=(a279+a192);
  a192=(a135*a350);
  a279=(a279+a192);
  a279=(a122*a279);
  a304=(a304+a279);
  a304=(a018*a304);
  a191=(a191+a304);
  a304=(a126*a350);
  a304=(a016*a304);
  a191=(a191+a304);
  a350=(a001*a350);
  a191=(a191+a350);
  a350=(a243*a191);
  a298=(a298+a350);
  a350=(a153*a298);
  a304=(a267*a191);
  a292=(a056*a292);
  a272=(a272+a292);
  a225=(a120*a225);
  a272=(a272+a225);
  a091=(a085*a091);
  a272=(a272+a091);
  a236=(a134*a236);
  a234=(a134*a234);
  a236=(a236-a234);
  a234=(a115*a236);
  a272=(a272+a234);
  a181=(a134*a181);
  a288=(a181+a288);
  a288=(a267*a288);
  a272=(a272+a288);
  a304=(a304-a272);
  a272=(a156*a304);
  a350=(a350+a272);
  a089=(a056*a089);
  a312=(a085*a312);
  a088=(a088+a312);
  a089=(a089-a088);
  a220=(a220-a181);
  a220=(a269*a220);
  a089=(a089+a220);
  a290=(a120*a290);
  a089=(a089+a290);
  a236=(a117*a236);
  a089=(a089-a236);
  a191=(a269*a191);
  a089=(a089+a191);
  a191=(a157*a089);
  a350=(a350+a191);
  a350=(a350/a002);
  if (res[1]!=0) res[1][66]=a350;
  a350=(a166*a298);
  a236=(a167*a304);
  a350=(a350+a236);
  a290=(a169*a089);
  a350=(a350+a290);
  a350=(a350/a002);
  if (res[1]!=0) res[1][67]=a350;
  a350=(a171*a298);
  a290=(a173*a304);
  a290=(a350+a290);
  a220=(a175*a089);
  a290=(a290+a220);
  a290=(a290/a002);
  if (res[1]!=0) res[1][68]=a290;
  a290=(a152*a298);
  a287=(a287+a290);
  a290=(a155*a304);
  a287=(a287+a290);
  a287=(a287+a191);
  a191=(a057*a077);
  a287=(a287+a191);
  a191=(a086*a342);
  a287=(a287+a191);
  a287=(a287+a183);
  a287=(-a287);
  if (res[1]!=0) res[1][69]=a287;
  a298=(a165*a298);
  a273=(a273+a298);
  a273=(a273+a236);
  a236=(a168*a089);
  a273=(a273+a236);
  a077=(a101*a077);
  a273=(a273+a077);
  a273=(a273+a232);
  a232=(a105*a275);
  a273=(a273+a232);
  a273=(-a273);
  if (res[1]!=0) res[1][70]=a273;
  a084=(a084+a350);
  a304=(a172*a304);
  a084=(a084+a304);
  a089=(a174*a089);
  a084=(a084+a089);
  a084=(a084+a326);
  a342=(a110*a342);
  a084=(a084+a342);
  a275=(a112*a275);
  a084=(a084+a275);
  a084=(-a084);
  if (res[1]!=0) res[1][71]=a084;
  a064=(a064*a058);
  a097=(a097*a102);
  a064=(a064+a097);
  a103=(a103*a108);
  a064=(a064+a103);
  a103=(a177*a064);
  a145=(a145*a153);
  a162=(a162*a166);
  a145=(a145+a162);
  a170=(a170*a171);
  a145=(a145+a170);
  a170=(a059*a145);
  a103=(a103+a170);
  a170=(a002*a103);
  a162=(a176*a170);
  a162=(a083-a162);
  a064=(a059*a064);
  a145=(a114*a145);
  a064=(a064+a145);
  a145=(a002*a064);
  a097=(a018*a145);
  a162=(a162-a097);
  a097=(a061*a162);
  a009=(a009*a097);
  a084=(a071*a162);
  a275=(a095*a084);
  a009=(a009-a275);
  a162=(a070*a162);
  a275=(a054*a162);
  a009=(a009-a275);
  a074=(a074*a058);
  a005=(a005*a102);
  a074=(a074+a005);
  a096=(a096*a108);
  a074=(a074+a096);
  a096=(a177*a074);
  a151=(a151*a153);
  a116=(a116*a166);
  a151=(a151+a116);
  a161=(a161*a171);
  a151=(a151+a161);
  a161=(a059*a151);
  a096=(a096+a161);
  a161=(a002*a096);
  a116=(a176*a161);
  a074=(a059*a074);
  a151=(a114*a151);
  a074=(a074+a151);
  a151=(a002*a074);
  a005=(a018*a151);
  a116=(a116+a005);
  a005=(a061*a116);
  a095=(a095*a005);
  a009=(a009+a095);
  a095=(a071*a116);
  a012=(a012*a095);
  a009=(a009-a012);
  a116=(a070*a116);
  a012=(a072*a116);
  a009=(a009+a012);
  a065=(a065*a058);
  a073=(a073*a102);
  a065=(a065+a073);
  a063=(a063*a108);
  a065=(a065+a063);
  a177=(a177*a065);
  a146=(a146*a153);
  a150=(a150*a166);
  a146=(a146+a150);
  a144=(a144*a171);
  a146=(a146+a144);
  a144=(a059*a146);
  a177=(a177+a144);
  a144=(a002*a177);
  a176=(a176*a144);
  a059=(a059*a065);
  a114=(a114*a146);
  a059=(a059+a114);
  a114=(a002*a059);
  a146=(a018*a114);
  a176=(a176+a146);
  a061=(a061*a176);
  a054=(a054*a061);
  a009=(a009+a054);
  a071=(a071*a176);
  a072=(a072*a071);
  a009=(a009+a072);
  a070=(a070*a176);
  a008=(a008*a070);
  a009=(a009-a008);
  a204=(a204*a009);
  a204=(a049*a204);
  a019=(a019*a204);
  a009=(a009/a053);
  a019=(a019-a009);
  a053=(a032*a019);
  a008=(a045*a053);
  a176=(a027*a019);
  a072=(a020*a176);
  a072=(a042*a072);
  a008=(a008+a072);
  a072=(a039*a176);
  a008=(a008+a072);
  a072=(a020*a019);
  a072=(a036*a072);
  a008=(a008+a072);
  a072=(a033*a019);
  a008=(a008+a072);
  a032=(a032*a009);
  a072=(a029*a032);
  a008=(a008+a072);
  a027=(a027*a009);
  a072=(a020*a027);
  a072=(a025*a072);
  a008=(a008+a072);
  a072=(a022*a027);
  a008=(a008+a072);
  a034=(a034*a204);
  a053=(a047*a053);
  a046=(a046*a019);
  a046=(a217*a046);
  a040=(a040*a019);
  a046=(a046+a040);
  a046=(a216*a046);
  a053=(a053+a046);
  a043=(a043*a176);
  a053=(a053+a043);
  a037=(a037*a019);
  a053=(a053+a037);
  a053=(a013*a053);
  a034=(a034+a053);
  a032=(a031*a032);
  a030=(a030*a009);
  a217=(a217*a030);
  a023=(a023*a009);
  a217=(a217+a023);
  a216=(a216*a217);
  a032=(a032+a216);
  a026=(a026*a027);
  a032=(a032+a026);
  a017=(a017*a009);
  a032=(a032+a017);
  a013=(a013*a032);
  a034=(a034+a013);
  a034=(a018*a034);
  a008=(a008+a034);
  a020=(a020*a009);
  a020=(a016*a020);
  a008=(a008+a020);
  a009=(a001*a009);
  a008=(a008+a009);
  a009=(a198*a008);
  a020=(a048*a084);
  a034=(a048*a005);
  a020=(a020-a034);
  a034=(a007*a020);
  a064=(a064+a034);
  a034=(a085*a116);
  a064=(a064+a034);
  a034=(a048*a162);
  a013=(a048*a061);
  a034=(a034-a013);
  a013=(a004*a034);
  a064=(a064+a013);
  a013=(a056*a071);
  a064=(a064+a013);
  a095=(a048*a095);
  a070=(a048*a070);
  a013=(a095+a070);
  a198=(a198*a013);
  a064=(a064+a198);
  a009=(a009-a064);
  a058=(a058*a009);
  a162=(a056*a162);
  a162=(a162-a074);
  a020=(a011*a020);
  a162=(a162-a020);
  a061=(a085*a061);
  a162=(a162-a061);
  a116=(a048*a116);
  a071=(a048*a071);
  a116=(a116+a071);
  a004=(a004*a116);
  a162=(a162+a004);
  a048=(a048*a097);
  a070=(a048-a070);
  a070=(a223*a070);
  a162=(a162+a070);
  a223=(a223*a008);
  a162=(a162+a223);
  a087=(a087*a162);
  a058=(a058+a087);
  a084=(a085*a084);
  a005=(a056*a005);
  a084=(a084-a005);
  a048=(a048-a095);
  a048=(a226*a048);
  a084=(a084+a048);
  a084=(a084-a059);
  a011=(a011*a034);
  a084=(a084-a011);
  a007=(a007*a116);
  a084=(a084+a007);
  a226=(a226*a008);
  a084=(a084+a226);
  a090=(a090*a084);
  a058=(a058+a090);
  a058=(a058/a002);
  if (res[1]!=0) res[1][72]=a058;
  a102=(a102*a009);
  a104=(a104*a162);
  a102=(a102+a104);
  a106=(a106*a084);
  a102=(a102+a106);
  a102=(a102/a002);
  if (res[1]!=0) res[1][73]=a102;
  a108=(a108*a009);
  a111=(a111*a162);
  a111=(a108+a111);
  a113=(a113*a084);
  a111=(a111+a113);
  a111=(a111/a002);
  if (res[1]!=0) res[1][74]=a111;
  a170=(a018*a170);
  a083=(a083-a170);
  a145=(a237*a145);
  a083=(a083-a145);
  a145=(a142*a083);
  a119=(a119*a145);
  a170=(a148*a083);
  a111=(a160*a170);
  a119=(a119-a111);
  a083=(a069*a083);
  a111=(a141*a083);
  a119=(a119-a111);
  a161=(a018*a161);
  a151=(a237*a151);
  a161=(a161+a151);
  a151=(a142*a161);
  a160=(a160*a151);
  a119=(a119+a160);
  a160=(a148*a161);
  a121=(a121*a160);
  a119=(a119-a121);
  a161=(a069*a161);
  a121=(a149*a161);
  a119=(a119+a121);
  a144=(a018*a144);
  a237=(a237*a114);
  a144=(a144+a237);
  a142=(a142*a144);
  a141=(a141*a142);
  a119=(a119+a141);
  a148=(a148*a144);
  a149=(a149*a148);
  a119=(a119+a149);
  a069=(a069*a144);
  a118=(a118*a069);
  a119=(a119-a118);
  a249=(a249*a119);
  a049=(a049*a249);
  a125=(a125*a049);
  a119=(a119/a123);
  a125=(a125-a119);
  a123=(a131*a125);
  a045=(a045*a123);
  a249=(a129*a125);
  a118=(a126*a249);
  a042=(a042*a118);
  a045=(a045+a042);
  a039=(a039*a249);
  a045=(a045+a039);
  a039=(a126*a125);
  a036=(a036*a039);
  a045=(a045+a036);
  a033=(a033*a125);
  a045=(a045+a033);
  a131=(a131*a119);
  a029=(a029*a131);
  a045=(a045+a029);
  a129=(a129*a119);
  a029=(a126*a129);
  a025=(a025*a029);
  a045=(a045+a025);
  a022=(a022*a129);
  a045=(a045+a022);
  a132=(a132*a049);
  a047=(a047*a123);
  a130=(a130*a125);
  a130=(a262*a130);
  a127=(a127*a125);
  a130=(a130+a127);
  a130=(a261*a130);
  a047=(a047+a130);
  a128=(a128*a249);
  a047=(a047+a128);
  a124=(a124*a125);
  a047=(a047+a124);
  a047=(a122*a047);
  a132=(a132+a047);
  a031=(a031*a131);
  a138=(a138*a119);
  a262=(a262*a138);
  a136=(a136*a119);
  a262=(a262+a136);
  a261=(a261*a262);
  a031=(a031+a261);
  a137=(a137*a129);
  a031=(a031+a137);
  a135=(a135*a119);
  a031=(a031+a135);
  a122=(a122*a031);
  a132=(a132+a122);
  a018=(a018*a132);
  a045=(a045+a018);
  a126=(a126*a119);
  a016=(a016*a126);
  a045=(a045+a016);
  a001=(a001*a119);
  a045=(a045+a001);
  a001=(a243*a045);
  a119=(a134*a170);
  a016=(a134*a151);
  a119=(a119-a016);
  a016=(a117*a119);
  a103=(a103+a016);
  a016=(a085*a161);
  a103=(a103+a016);
  a016=(a134*a083);
  a126=(a134*a142);
  a016=(a016-a126);
  a126=(a115*a016);
  a103=(a103+a126);
  a126=(a056*a148);
  a103=(a103+a126);
  a160=(a134*a160);
  a069=(a134*a069);
  a126=(a160+a069);
  a243=(a243*a126);
  a103=(a103+a243);
  a001=(a001-a103);
  a153=(a153*a001);
  a083=(a056*a083);
  a083=(a083-a096);
  a119=(a120*a119);
  a083=(a083-a119);
  a142=(a085*a142);
  a083=(a083-a142);
  a161=(a134*a161);
  a148=(a134*a148);
  a161=(a161+a148);
  a115=(a115*a161);
  a083=(a083+a115);
  a134=(a134*a145);
  a069=(a134-a069);
  a069=(a267*a069);
  a083=(a083+a069);
  a267=(a267*a045);
  a083=(a083+a267);
  a156=(a156*a083);
  a153=(a153+a156);
  a085=(a085*a170);
  a085=(a085-a177);
  a056=(a056*a151);
  a085=(a085-a056);
  a134=(a134-a160);
  a134=(a269*a134);
  a085=(a085+a134);
  a120=(a120*a016);
  a085=(a085-a120);
  a117=(a117*a161);
  a085=(a085+a117);
  a269=(a269*a045);
  a085=(a085+a269);
  a157=(a157*a085);
  a153=(a153+a157);
  a153=(a153/a002);
  if (res[1]!=0) res[1][75]=a153;
  a166=(a166*a001);
  a167=(a167*a083);
  a166=(a166+a167);
  a169=(a169*a085);
  a166=(a166+a169);
  a166=(a166/a002);
  if (res[1]!=0) res[1][76]=a166;
  a171=(a171*a001);
  a173=(a173*a083);
  a173=(a171+a173);
  a175=(a175*a085);
  a173=(a173+a175);
  a173=(a173/a002);
  if (res[1]!=0) res[1][77]=a173;
  a152=(a152*a001);
  a271=(a271+a152);
  a155=(a155*a083);
  a271=(a271+a155);
  a271=(a271+a157);
  a057=(a057*a009);
  a271=(a271+a057);
  a086=(a086*a162);
  a271=(a271+a086);
  a271=(a271+a090);
  a271=(-a271);
  if (res[1]!=0) res[1][78]=a271;
  a165=(a165*a001);
  a286=(a286+a165);
  a286=(a286+a167);
  a168=(a168*a085);
  a286=(a286+a168);
  a101=(a101*a009);
  a286=(a286+a101);
  a286=(a286+a104);
  a105=(a105*a084);
  a286=(a286+a105);
  a286=(-a286);
  if (res[1]!=0) res[1][79]=a286;
  a050=(a050+a171);
  a172=(a172*a083);
  a050=(a050+a172);
  a174=(a174*a085);
  a050=(a050+a174);
  a050=(a050+a108);
  a110=(a110*a162);
  a050=(a050+a110);
  a112=(a112*a084);
  a050=(a050+a112);
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
#define HPGEN_RESIDUAL_SZ_W 171
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
#define HPGEN_RESIDUAL_JACOBIAN_SZ_W 364
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
