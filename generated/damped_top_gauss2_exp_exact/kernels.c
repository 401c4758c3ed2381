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
  a111=(a071*a111);
  a145=(a048*a111);
  a135=(a070*a135);
  a154=(a048*a135);
  a066=(a145+a154);
  a066=(a150*a066);
  a060=(a060+a066);
  a066=(a048/a053);
  a164=(a061*a164);
  a009=(a009*a164);
  a063=(a093*a166);
  a009=(a009-a063);
  a063=(a054*a169);
  a009=(a009-a063);
  a063=(a093*a005);
  a009=(a009-a063);
  a111=(a012*a111);
  a009=(a009+a111);
  a111=(a072*a168);
  a009=(a009-a111);
  a111=(a054*a141);
  a009=(a009-a111);
  a111=(a072*a065);
  a009=(a009-a111);
  a135=(a008*a135);
  a009=(a009+a135);
  a066=(a066*a009);
  a066=(a049*a066);
  a135=(a019*a066);
  a009=(a009/a053);
  a135=(a135-a009);
  a053=(a032*a135);
  a111=(a045*a053);
  a063=(a027*a135);
  a092=(a020*a063);
  a092=(a042*a092);
  a111=(a111+a092);
  a092=(a039*a063);
  a111=(a111+a092);
  a092=(a020*a135);
  a092=(a036*a092);
  a111=(a111+a092);
  a092=(a033*a135);
  a111=(a111+a092);
  a032=(a032*a009);
  a092=(a029*a032);
  a111=(a111+a092);
  a092=(a027*a009);
  a073=(a020*a092);
  a073=(a025*a073);
  a111=(a111+a073);
  a073=(a022*a092);
  a111=(a111+a073);
  a034=(a034*a066);
  a013=(a056*a013);
  a053=(a047*a053);
  a066=(2.*a020);
  a027=(2.*a027);
  a046=(a046*a135);
  a046=(a027*a046);
  a040=(a040*a135);
  a046=(a046+a040);
  a046=(a066*a046);
  a053=(a053+a046);
  a043=(a043*a063);
  a053=(a053+a043);
  a037=(a037*a135);
  a053=(a053+a037);
  a053=(a013*a053);
  a034=(a034+a053);
  a032=(a031*a032);
  a030=(a030*a009);
  a027=(a027*a030);
  a023=(a023*a009);
  a027=(a027+a023);
  a066=(a066*a027);
  a032=(a032+a066);
  a026=(a026*a092);
  a032=(a032+a026);
  a017=(a017*a009);
  a032=(a032+a017);
  a013=(a013*a032);
  a034=(a034+a013);
  a034=(a018*a034);
  a111=(a111+a034);
  a020=(a020*a009);
  a020=(a016*a020);
  a111=(a111+a020);
  a009=(a001*a009);
  a111=(a111+a009);
  a150=(a150*a111);
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
  a048=(a048*a164);
  a154=(a048+a154);
  a154=(a065*a154);
  a169=(a169+a154);
  a065=(a065*a111);
  a169=(a169+a065);
  a086=(a086*a169);
  a058=(a058+a086);
  a166=(a084*a166);
  a005=(a056*a005);
  a166=(a166+a005);
  a005=(2.*a004);
  a048=(a048+a145);
  a048=(a005*a048);
  a166=(a166+a048);
  a166=(a166+a059);
  a170=(a011*a170);
  a166=(a166-a170);
  a168=(a007*a168);
  a166=(a166-a168);
  a005=(a005*a111);
  a166=(a166+a005);
  a089=(a089*a166);
  a058=(a058+a089);
  a005=arg[3]? arg[3][2] : 0;
  a070=(a005*a070);
  a070=(a070*a082);
  a058=(a058-a070);
  a070=arg[1]? arg[1][2] : 0;
  a072=(a062*a072);
  a019=(a019*a014);
  a019=(a050-a019);
  a052=(a052*a019);
  a011=(a052*a011);
  a019=(a072-a011);
  a019=(a070*a019);
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
  a071=(a005*a071);
  a071=(a071*a082);
  a100=(a100-a071);
  a008=(a062*a008);
  a008=(a050-a008);
  a008=(a070*a008);
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
  a061=(a005*a061);
  a061=(a061*a082);
  a107=(a107-a061);
  a107=(a107/a002);
  if (res[0]!=0) res[0][2]=a107;
  a107=(a138*a144);
  a134=(a120*a134);
  a134=(a050-a134);
  a128=(a128*a134);
  a134=(a128*a115);
  a061=(a107-a134);
  a061=(a070*a061);
  a109=(a138*a116);
  a109=(a050-a109);
  a109=(a014*a109);
  a061=(a061+a109);
  a109=(a128*a110);
  a100=(a138*a151);
  a109=(a109+a100);
  a109=(a012*a109);
  a061=(a061+a109);
  a061=(a061*a082);
  a109=(a005*a069);
  a109=(a109*a082);
  a061=(a061-a109);
  a140=(a018*a140);
  a081=(a081+a140);
  a140=-3.8675134594812879e-02;
  a165=(a140*a165);
  a081=(a081+a165);
  a165=(a143*a081);
  a109=(a129*a165);
  a152=(a018*a152);
  a088=(a088+a152);
  a146=(a140*a146);
  a088=(a088+a146);
  a146=(a137*a088);
  a152=(a129*a146);
  a109=(a109+a152);
  a152=(a112*a109);
  a064=(a064-a152);
  a152=(a069*a088);
  a100=(a084*a152);
  a064=(a064+a100);
  a100=(a069*a081);
  a008=(a129*a100);
  a139=(a018*a139);
  a091=(a091+a139);
  a140=(a140*a105);
  a091=(a091+a140);
  a140=(a137*a091);
  a105=(a129*a140);
  a008=(a008+a105);
  a105=(a110*a008);
  a064=(a064-a105);
  a105=(a143*a091);
  a139=(a056*a105);
  a064=(a064+a139);
  a139=(2.*a115);
  a088=(a143*a088);
  a062=(a129*a088);
  a069=(a069*a091);
  a091=(a129*a069);
  a052=(a062+a091);
  a052=(a139*a052);
  a064=(a064+a052);
  a052=(a129/a118);
  a081=(a137*a081);
  a114=(a114*a081);
  a007=(a151*a165);
  a114=(a114-a007);
  a007=(a136*a100);
  a114=(a114-a007);
  a151=(a151*a146);
  a114=(a114-a151);
  a116=(a116*a088);
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
  a088=(a121*a116);
  a088=(a025*a088);
  a069=(a069+a088);
  a088=(a022*a116);
  a069=(a069+a088);
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
  a061=(a061+a010);
  a100=(a056*a100);
  a094=(a094+a100);
  a109=(a115*a109);
  a094=(a094-a109);
  a140=(a084*a140);
  a094=(a094+a140);
  a152=(a129*a152);
  a105=(a129*a105);
  a152=(a152+a105);
  a105=(a110*a152);
  a094=(a094-a105);
  a105=(2.*a112);
  a129=(a129*a081);
  a091=(a129+a091);
  a091=(a105*a091);
  a094=(a094+a091);
  a105=(a105*a069);
  a094=(a094+a105);
  a148=(a148*a094);
  a061=(a061+a148);
  a165=(a084*a165);
  a163=(a163+a165);
  a146=(a056*a146);
  a163=(a163+a146);
  a110=(2.*a110);
  a129=(a129+a062);
  a129=(a110*a129);
  a163=(a163+a129);
  a115=(a115*a008);
  a163=(a163-a115);
  a152=(a112*a152);
  a163=(a163-a152);
  a110=(a110*a069);
  a163=(a163+a110);
  a149=(a149*a163);
  a061=(a061+a149);
  a061=(a061/a002);
  if (res[0]!=0) res[0][3]=a061;
  a156=(a156*a064);
  a143=(a005*a143);
  a143=(a143*a082);
  a113=(a138*a113);
  a113=(a050-a113);
  a070=(a070*a113);
  a134=(a134+a107);
  a014=(a014*a134);
  a070=(a070+a014);
  a138=(a138*a136);
  a128=(a128*a112);
  a138=(a138-a128);
  a012=(a012*a138);
  a070=(a070+a012);
  a070=(a070*a082);
  a143=(a143+a070);
  a156=(a156-a143);
  a157=(a157*a094);
  a156=(a156+a157);
  a159=(a159*a163);
  a156=(a156+a159);
  a156=(a156/a002);
  if (res[0]!=0) res[0][4]=a156;
  a095=(a095*a064);
  a005=(a005*a137);
  a005=(a005*a082);
  a005=(a095-a005);
  a160=(a160*a094);
  a005=(a005+a160);
  a162=(a162*a163);
  a005=(a005+a162);
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
  a162=casadi_sq(a075);
  a160=(a003+a162);
  a077=(a056*a077);
  a142=(a056*a142);
  a077=(a077+a142);
  a002=(a002*a077);
  a077=casadi_sq(a002);
  a142=(a160+a077);
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
  a005=(a005-a006);
  if (res[0]!=0) res[0][6]=a005;
  a005=arg[2]? arg[2][1] : 0;
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
  a005=(a005-a006);
  if (res[0]!=0) res[0][7]=a005;
  a005=arg[2]? arg[2][2] : 0;
  a000=(a000*a160);
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
  casadi_real a348, a349, a350, a351, a352, a353, a354, a355, a356, a357, a358, a359;
  casadi_real a360, a361, a362, a363, a364, a365, a366, a367;
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
  a200=arg[3]? arg[3][2] : 0;
  a227=(a200*a070);
  a227=(a227*a083);
  a215=(a215-a227);
  a227=arg[1]? arg[1][2] : 0;
  a228=(a062*a072);
  a229=(a019*a014);
  a229=(a050-a229);
  a230=(a052*a229);
  a231=(a230*a011);
  a232=(a228-a231);
  a232=(a227*a232);
  a233=arg[1]? arg[1][5] : 0;
  a234=(a062*a012);
  a234=(a050-a234);
  a234=(a233*a234);
  a232=(a232+a234);
  a234=arg[1]? arg[1][8] : 0;
  a235=(a230*a004);
  a236=(a062*a095);
  a235=(a235+a236);
  a235=(a234*a235);
  a232=(a232+a235);
  a232=(a232*a083);
  a215=(a215+a232);
  a215=(a215/a002);
  if (res[0]!=0) res[0][0]=a215;
  a215=(a102*a109);
  a232=(a104*a222);
  a215=(a215+a232);
  a235=(a106*a225);
  a215=(a215+a235);
  a235=(a200*a071);
  a235=(a235*a083);
  a215=(a215-a235);
  a235=(a062*a008);
  a235=(a050-a235);
  a235=(a227*a235);
  a231=(a231+a228);
  a231=(a233*a231);
  a235=(a235+a231);
  a231=(a062*a054);
  a228=(a230*a007);
  a231=(a231-a228);
  a231=(a234*a231);
  a235=(a235+a231);
  a235=(a235*a083);
  a215=(a215-a235);
  a215=(a215/a002);
  if (res[0]!=0) res[0][1]=a215;
  a215=(a108*a109);
  a235=(a111*a222);
  a235=(a215+a235);
  a231=(a113*a225);
  a235=(a235+a231);
  a231=(a200*a061);
  a231=(a231*a083);
  a235=(a235-a231);
  a235=(a235/a002);
  if (res[0]!=0) res[0][2]=a235;
  a235=(a143*a149);
  a231=(a125*a139);
  a231=(a050-a231);
  a228=(a133*a231);
  a236=(a228*a120);
  a237=(a235-a236);
  a237=(a227*a237);
  a238=(a143*a121);
  a238=(a050-a238);
  a238=(a233*a238);
  a237=(a237+a238);
  a238=(a228*a115);
  a239=(a143*a160);
  a238=(a238+a239);
  a238=(a234*a238);
  a237=(a237+a238);
  a237=(a237*a083);
  a238=(a200*a069);
  a238=(a238*a083);
  a237=(a237-a238);
  a158=(a018*a158);
  a158=(a082+a158);
  a238=-3.8675134594812879e-02;
  a179=(a238*a179);
  a158=(a158+a179);
  a179=(a148*a158);
  a239=(a134*a179);
  a185=(a018*a185);
  a185=(a089+a185);
  a184=(a238*a184);
  a185=(a185+a184);
  a184=(a142*a185);
  a240=(a134*a184);
  a239=(a239+a240);
  a240=(a117*a239);
  a093=(a093-a240);
  a240=(a069*a185);
  a241=(a085*a240);
  a093=(a093+a241);
  a241=(a069*a158);
  a242=(a134*a241);
  a194=(a018*a194);
  a194=(a092+a194);
  a193=(a238*a193);
  a194=(a194+a193);
  a193=(a142*a194);
  a243=(a134*a193);
  a242=(a242+a243);
  a243=(a115*a242);
  a093=(a093-a243);
  a243=(a148*a194);
  a244=(a056*a243);
  a093=(a093+a244);
  a244=(2.*a120);
  a245=(a148*a185);
  a246=(a134*a245);
  a247=(a069*a194);
  a248=(a134*a247);
  a249=(a246+a248);
  a250=(a244*a249);
  a093=(a093+a250);
  a250=(a134/a123);
  a251=(a142*a158);
  a252=(a119*a251);
  a253=(a160*a179);
  a252=(a252-a253);
  a253=(a141*a241);
  a252=(a252-a253);
  a253=(a160*a184);
  a252=(a252-a253);
  a253=(a121*a245);
  a252=(a252+a253);
  a253=(a149*a240);
  a252=(a252-a253);
  a253=(a141*a193);
  a252=(a252-a253);
  a253=(a149*a243);
  a252=(a252-a253);
  a253=(a118*a247);
  a252=(a252+a253);
  a253=(a250*a252);
  a253=(a049*a253);
  a254=(a125*a253);
  a255=(a252/a123);
  a254=(a254-a255);
  a256=(a131*a254);
  a257=(a045*a256);
  a258=(a129*a254);
  a259=(a126*a258);
  a259=(a042*a259);
  a257=(a257+a259);
  a259=(a039*a258);
  a257=(a257+a259);
  a259=(a126*a254);
  a259=(a036*a259);
  a257=(a257+a259);
  a259=(a033*a254);
  a257=(a257+a259);
  a259=(a131*a255);
  a260=(a029*a259);
  a257=(a257+a260);
  a260=(a129*a255);
  a261=(a126*a260);
  a261=(a025*a261);
  a257=(a257+a261);
  a261=(a022*a260);
  a257=(a257+a261);
  a261=(a132*a253);
  a122=(a056*a122);
  a256=(a047*a256);
  a262=(2.*a126);
  a263=(2.*a129);
  a264=(a130*a254);
  a265=(a263*a264);
  a266=(a127*a254);
  a265=(a265+a266);
  a266=(a262*a265);
  a256=(a256+a266);
  a266=(a128*a258);
  a256=(a256+a266);
  a266=(a124*a254);
  a256=(a256+a266);
  a266=(a122*a256);
  a261=(a261+a266);
  a259=(a031*a259);
  a266=(a138*a255);
  a267=(a263*a266);
  a268=(a136*a255);
  a267=(a267+a268);
  a268=(a262*a267);
  a259=(a259+a268);
  a268=(a137*a260);
  a259=(a259+a268);
  a268=(a135*a255);
  a259=(a259+a268);
  a268=(a122*a259);
  a261=(a261+a268);
  a261=(a018*a261);
  a257=(a257+a261);
  a261=(a126*a255);
  a261=(a016*a261);
  a257=(a257+a261);
  a261=(a001*a255);
  a257=(a257+a261);
  a261=(a244*a257);
  a093=(a093+a261);
  a261=(a153*a093);
  a237=(a237+a261);
  a261=(a056*a241);
  a183=(a183+a261);
  a261=(a120*a239);
  a183=(a183-a261);
  a261=(a085*a193);
  a183=(a183+a261);
  a261=(a134*a240);
  a268=(a134*a243);
  a261=(a261+a268);
  a268=(a115*a261);
  a183=(a183-a268);
  a268=(2.*a117);
  a269=(a134*a251);
  a248=(a269+a248);
  a270=(a268*a248);
  a183=(a183+a270);
  a270=(a268*a257);
  a183=(a183+a270);
  a270=(a156*a183);
  a237=(a237+a270);
  a270=(a085*a179);
  a192=(a192+a270);
  a270=(a056*a184);
  a192=(a192+a270);
  a270=(2.*a115);
  a269=(a269+a246);
  a246=(a270*a269);
  a192=(a192+a246);
  a246=(a120*a242);
  a192=(a192-a246);
  a246=(a117*a261);
  a192=(a192-a246);
  a246=(a270*a257);
  a192=(a192+a246);
  a246=(a157*a192);
  a237=(a237+a246);
  a237=(a237/a002);
  if (res[0]!=0) res[0][3]=a237;
  a237=(a166*a093);
  a271=(a200*a148);
  a271=(a271*a083);
  a272=(a143*a118);
  a272=(a050-a272);
  a272=(a227*a272);
  a236=(a236+a235);
  a236=(a233*a236);
  a272=(a272+a236);
  a236=(a143*a141);
  a235=(a228*a117);
  a236=(a236-a235);
  a236=(a234*a236);
  a272=(a272+a236);
  a272=(a272*a083);
  a271=(a271+a272);
  a237=(a237-a271);
  a271=(a167*a183);
  a237=(a237+a271);
  a272=(a169*a192);
  a237=(a237+a272);
  a237=(a237/a002);
  if (res[0]!=0) res[0][4]=a237;
  a237=(a171*a093);
  a272=(a200*a142);
  a272=(a272*a083);
  a272=(a237-a272);
  a236=(a173*a183);
  a272=(a272+a236);
  a236=(a175*a192);
  a272=(a272+a236);
  a272=(a272/a002);
  if (res[0]!=0) res[0][5]=a272;
  a272=arg[2]? arg[2][0] : 0;
  a236=(a056*a075);
  a235=(a056*a006);
  a236=(a236+a235);
  a236=(a002*a236);
  a235=(a056*a236);
  a273=(a056*a067);
  a274=(a056*a003);
  a273=(a273+a274);
  a273=(a002*a273);
  a274=casadi_sq(a273);
  a275=casadi_sq(a236);
  a276=(a274+a275);
  a277=(a056*a077);
  a278=(a056*a010);
  a277=(a277+a278);
  a277=(a002*a277);
  a278=casadi_sq(a277);
  a279=(a276+a278);
  a280=(a001*a279);
  a281=(a016*a279);
  a015=(a015+a281);
  a281=(a018*a279);
  a282=casadi_sq(a281);
  a283=(a015*a282);
  a280=(a280+a283);
  a283=(a022*a279);
  a021=(a021+a283);
  a283=(a025*a279);
  a024=(a024+a283);
  a283=(a024*a282);
  a021=(a021+a283);
  a283=casadi_sq(a282);
  a284=(a021*a283);
  a280=(a280+a284);
  a284=(a029*a279);
  a028=(a028+a284);
  a284=(a031*a282);
  a028=(a028+a284);
  a284=casadi_sq(a283);
  a285=(a028*a284);
  a280=(a280+a285);
  a285=(a033*a279);
  a286=(a036*a279);
  a035=(a035+a286);
  a286=(a035*a282);
  a285=(a285+a286);
  a286=(a039*a279);
  a038=(a038+a286);
  a286=(a042*a279);
  a041=(a041+a286);
  a286=(a041*a282);
  a038=(a038+a286);
  a286=(a038*a283);
  a285=(a285+a286);
  a286=(a045*a279);
  a044=(a044+a286);
  a286=(a047*a282);
  a044=(a044+a286);
  a286=(a044*a284);
  a285=(a285+a286);
  a280=(a280-a285);
  a000=(a000+a280);
  a051=(a051+a285);
  a285=(a281*a051);
  a285=(a050-a285);
  a285=(a049*a285);
  a000=(a000/a285);
  a280=(a273*a277);
  a286=(a000*a280);
  a235=(a235+a286);
  a287=(a235*a081);
  a288=(a085*a277);
  a289=(a273*a236);
  a290=(a000*a289);
  a288=(a288+a290);
  a291=(a288*a088);
  a287=(a287+a291);
  a275=(a275+a278);
  a291=(a000*a275);
  a291=(a050-a291);
  a292=(a291*a091);
  a287=(a287+a292);
  a152=(a152+a076);
  a292=(a152*a093);
  a287=(a287+a292);
  a155=(a155+a154);
  a292=(a155*a183);
  a287=(a287+a292);
  a287=(a287+a246);
  a057=(a057+a055);
  a246=(a057*a109);
  a287=(a287+a246);
  a086=(a086+a084);
  a246=(a086*a222);
  a287=(a287+a246);
  a287=(a287+a191);
  a272=(a272-a287);
  if (res[0]!=0) res[0][6]=a272;
  a272=arg[2]? arg[2][1] : 0;
  a287=(a085*a273);
  a191=(a236*a277);
  a246=(a000*a191);
  a287=(a287+a246);
  a292=(a287*a081);
  a278=(a278+a274);
  a274=(a000*a278);
  a274=(a050-a274);
  a293=(a274*a088);
  a292=(a292+a293);
  a293=(a056*a277);
  a293=(a293+a290);
  a290=(a293*a091);
  a292=(a292+a290);
  a165=(a165+a164);
  a290=(a165*a093);
  a292=(a292+a290);
  a292=(a292+a271);
  a168=(a168+a154);
  a154=(a168*a192);
  a292=(a292+a154);
  a101=(a101+a100);
  a154=(a101*a109);
  a292=(a292+a154);
  a292=(a292+a232);
  a105=(a105+a084);
  a084=(a105*a225);
  a292=(a292+a084);
  a272=(a272-a292);
  if (res[0]!=0) res[0][7]=a272;
  a272=arg[2]? arg[2][2] : 0;
  a292=(a000*a276);
  a050=(a050-a292);
  a292=(a050*a081);
  a084=(a056*a273);
  a084=(a084+a246);
  a246=(a084*a088);
  a292=(a292+a246);
  a246=(a085*a236);
  a246=(a246+a286);
  a286=(a246*a091);
  a292=(a292+a286);
  a292=(a292+a237);
  a172=(a172+a164);
  a164=(a172*a183);
  a292=(a292+a164);
  a174=(a174+a076);
  a076=(a174*a192);
  a292=(a292+a076);
  a292=(a292+a215);
  a110=(a110+a100);
  a100=(a110*a222);
  a292=(a292+a100);
  a112=(a112+a055);
  a055=(a112*a225);
  a292=(a292+a055);
  a272=(a272-a292);
  if (res[0]!=0) res[0][8]=a272;
  a272=(a226*a002);
  a292=(a001*a272);
  a055=(a016*a272);
  a100=(a020*a055);
  a215=(a018*a272);
  a076=(a013*a215);
  a164=(a017*a076);
  a100=(a100+a164);
  a292=(a292+a100);
  a100=(a022*a272);
  a164=(a025*a272);
  a237=(a020*a164);
  a286=(a026*a076);
  a237=(a237+a286);
  a100=(a100+a237);
  a237=(a027*a100);
  a286=(a216*a076);
  a232=(a023*a286);
  a237=(a237+a232);
  a292=(a292+a237);
  a237=(a029*a272);
  a232=(a031*a076);
  a237=(a237+a232);
  a232=(a032*a237);
  a154=(a217*a286);
  a271=(a030*a154);
  a232=(a232+a271);
  a292=(a292+a232);
  a232=(a033*a272);
  a271=(a036*a272);
  a290=(a020*a271);
  a294=(a037*a076);
  a290=(a290+a294);
  a232=(a232+a290);
  a290=(a039*a272);
  a294=(a042*a272);
  a295=(a020*a294);
  a296=(a043*a076);
  a295=(a295+a296);
  a290=(a290+a295);
  a295=(a027*a290);
  a296=(a040*a286);
  a295=(a295+a296);
  a232=(a232+a295);
  a295=(a045*a272);
  a296=(a047*a076);
  a295=(a295+a296);
  a296=(a032*a295);
  a297=(a046*a154);
  a296=(a296+a297);
  a232=(a232+a296);
  a296=(a292-a232);
  a296=(a296/a053);
  a297=(a034*a215);
  a298=(a019*a232);
  a297=(a297+a298);
  a298=(a049*a297);
  a299=(a204*a298);
  a296=(a296+a299);
  a299=(a054*a296);
  a300=(a011*a002);
  a301=(a048*a300);
  a299=(a299+a301);
  a302=(a109*a299);
  a303=(a052*a292);
  a304=(a014*a297);
  a303=(a303-a304);
  a303=(a232+a303);
  a303=(a018*a303);
  a304=(a054*a303);
  a305=(a060*a300);
  a304=(a304+a305);
  a306=(2.*a052);
  a307=(a306*a297);
  a307=(a056*a307);
  a308=(a007*a307);
  a309=(a304+a308);
  a310=(a079*a309);
  a311=(a066*a065);
  a312=(a008*a303);
  a313=(a067*a312);
  a311=(a311-a313);
  a313=(a072*a303);
  a314=(a007*a002);
  a315=(a060*a314);
  a313=(a313+a315);
  a316=(a011*a307);
  a317=(a313-a316);
  a318=(a075*a317);
  a311=(a311+a318);
  a309=(a077*a309);
  a311=(a311+a309);
  a309=(2.*a311);
  a309=(a080*a309);
  a318=(a082*a299);
  a319=(a072*a296);
  a320=(a048*a314);
  a319=(a319+a320);
  a321=(a089*a319);
  a318=(a318+a321);
  a321=(a008*a296);
  a322=(a092*a321);
  a318=(a318-a322);
  a309=(a309-a318);
  a309=(a309/a083);
  a318=(a064*a309);
  a310=(a310+a318);
  a318=(a062*a002);
  a322=(a004*a307);
  a322=(a318-a322);
  a323=(a095*a303);
  a324=(a322+a323);
  a325=(a098*a324);
  a313=(a313+a316);
  a316=(a067*a313);
  a326=(a066*a073);
  a316=(a316+a326);
  a326=(a012*a303);
  a327=(a060*a272);
  a326=(a326+a327);
  a328=(a075*a326);
  a316=(a316-a328);
  a324=(a077*a324);
  a316=(a316+a324);
  a324=(2.*a316);
  a324=(a099*a324);
  a328=(a095*a296);
  a329=(a085*a002);
  a330=(a328-a329);
  a331=(a082*a330);
  a332=(a012*a296);
  a333=(a048*a272);
  a332=(a332+a333);
  a334=(a089*a332);
  a331=(a331-a334);
  a334=(a092*a319);
  a331=(a331+a334);
  a324=(a324-a331);
  a324=(a324/a083);
  a331=(a097*a324);
  a325=(a325+a331);
  a310=(a310+a325);
  a304=(a304-a308);
  a308=(a067*a304);
  a325=(a066*a063);
  a308=(a308+a325);
  a323=(a323-a322);
  a322=(a075*a323);
  a308=(a308+a322);
  a303=(a009*a303);
  a303=(a303+a327);
  a327=(a077*a303);
  a308=(a308-a327);
  a327=(2.*a308);
  a327=(a107*a327);
  a322=(a328-a083);
  a325=(a089*a322);
  a331=(a009*a296);
  a331=(a331+a333);
  a333=(a082*a331);
  a325=(a325-a333);
  a333=(a092*a299);
  a325=(a325+a333);
  a327=(a327-a325);
  a327=(a327/a083);
  a325=(a103*a327);
  a303=(a094*a303);
  a325=(a325-a303);
  a310=(a310+a325);
  a325=(a059*a310);
  a303=-1.2928203230275511e+01;
  a333=(a303*a146);
  a333=(a080*a333);
  a333=(a333/a083);
  a334=(a145*a333);
  a335=(a303*a150);
  a335=(a099*a335);
  a335=(a335/a083);
  a336=(a162*a335);
  a334=(a334+a336);
  a336=(a303*a144);
  a336=(a107*a336);
  a336=(a336/a083);
  a337=(a170*a336);
  a334=(a334+a337);
  a337=(a114*a334);
  a325=(a325+a337);
  a337=(a180*a296);
  a338=(a178*a316);
  a310=(a177*a310);
  a334=(a059*a334);
  a310=(a310+a334);
  a334=(a002*a310);
  a339=(a176*a334);
  a340=(a002*a325);
  a341=(a018*a340);
  a339=(a339+a341);
  a341=(a071*a339);
  a338=(a338+a341);
  a341=(a048*a338);
  a337=(a337+a341);
  a341=(a187*a296);
  a342=(a186*a308);
  a317=(a079*a317);
  a343=(a074*a309);
  a317=(a317+a343);
  a343=(a005*a324);
  a326=(a098*a326);
  a343=(a343-a326);
  a317=(a317+a343);
  a323=(a094*a323);
  a343=(a096*a327);
  a323=(a323+a343);
  a317=(a317+a323);
  a323=(a177*a317);
  a343=(a151*a333);
  a326=(a116*a335);
  a343=(a343+a326);
  a326=(a161*a336);
  a343=(a343+a326);
  a326=(a059*a343);
  a323=(a323+a326);
  a326=(a002*a323);
  a344=(a176*a326);
  a317=(a059*a317);
  a343=(a114*a343);
  a317=(a317+a343);
  a343=(a002*a317);
  a345=(a018*a343);
  a344=(a344+a345);
  a345=(a061*a344);
  a342=(a342+a345);
  a345=(a048*a342);
  a341=(a341+a345);
  a337=(a337+a341);
  a341=(a007*a337);
  a325=(a325-a341);
  a341=(a186*a311);
  a345=(a070*a344);
  a341=(a341+a345);
  a345=(a085*a341);
  a325=(a325+a345);
  a190=(a190*a002);
  a345=(a189*a296);
  a346=(a178*a311);
  a347=(a070*a339);
  a346=(a346+a347);
  a347=(a048*a346);
  a345=(a345+a347);
  a347=(a196*a296);
  a348=(a195*a308);
  a309=(a065*a309);
  a312=(a079*a312);
  a309=(a309-a312);
  a313=(a098*a313);
  a324=(a073*a324);
  a313=(a313+a324);
  a309=(a309+a313);
  a304=(a094*a304);
  a327=(a063*a327);
  a304=(a304+a327);
  a309=(a309+a304);
  a304=(a177*a309);
  a333=(a146*a333);
  a335=(a150*a335);
  a333=(a333+a335);
  a336=(a144*a336);
  a333=(a333+a336);
  a336=(a059*a333);
  a304=(a304+a336);
  a336=(a002*a304);
  a335=(a176*a336);
  a309=(a059*a309);
  a333=(a114*a333);
  a309=(a309+a333);
  a333=(a002*a309);
  a327=(a018*a333);
  a335=(a335+a327);
  a327=(a061*a335);
  a348=(a348+a327);
  a327=(a048*a348);
  a347=(a347+a327);
  a345=(a345+a347);
  a347=(a004*a345);
  a347=(a190+a347);
  a325=(a325-a347);
  a347=(a195*a316);
  a327=(a071*a335);
  a347=(a347+a327);
  a327=(a056*a347);
  a325=(a325+a327);
  a327=(a199*a296);
  a313=(a186*a316);
  a344=(a071*a344);
  a313=(a313+a344);
  a344=(a048*a313);
  a327=(a327+a344);
  a344=(a201*a296);
  a324=(a195*a311);
  a335=(a070*a335);
  a324=(a324+a335);
  a335=(a048*a324);
  a344=(a344+a335);
  a335=(a327+a344);
  a335=(a198*a335);
  a325=(a325+a335);
  a335=(a208*a154);
  a312=(a207*a215);
  a349=(a296/a053);
  a350=(a204/a053);
  a351=(a350*a298);
  a349=(a349+a351);
  a349=(a206*a349);
  a351=(a205*a272);
  a352=(a178*a308);
  a339=(a061*a339);
  a352=(a352+a339);
  a339=(a009*a352);
  a351=(a351+a339);
  a339=(a095*a338);
  a351=(a351-a339);
  a339=(a189*a300);
  a353=(a054*a346);
  a339=(a339+a353);
  a351=(a351-a339);
  a339=(a095*a342);
  a351=(a351-a339);
  a339=(a199*a272);
  a313=(a012*a313);
  a339=(a339+a313);
  a351=(a351+a339);
  a339=(a188*a314);
  a313=(a072*a341);
  a339=(a339+a313);
  a351=(a351-a339);
  a339=(a196*a300);
  a313=(a054*a348);
  a339=(a339+a313);
  a351=(a351-a339);
  a339=(a197*a314);
  a313=(a072*a347);
  a339=(a339+a313);
  a351=(a351-a339);
  a324=(a008*a324);
  a351=(a351+a324);
  a324=(a204*a351);
  a349=(a349+a324);
  a349=(a049*a349);
  a324=(a019*a349);
  a312=(a312+a324);
  a351=(a351/a053);
  a324=(a209/a053);
  a298=(a324*a298);
  a351=(a351+a298);
  a312=(a312-a351);
  a298=(a032*a312);
  a335=(a335+a298);
  a298=(a045*a335);
  a339=(a212*a076);
  a313=(a208*a286);
  a353=(a027*a312);
  a313=(a313+a353);
  a353=(a020*a313);
  a339=(a339+a353);
  a339=(a042*a339);
  a298=(a298+a339);
  a339=(a039*a313);
  a298=(a298+a339);
  a339=(a208*a076);
  a353=(a020*a312);
  a339=(a339+a353);
  a339=(a036*a339);
  a298=(a298+a339);
  a339=(a033*a312);
  a298=(a298+a339);
  a154=(a209*a154);
  a339=(a032*a351);
  a154=(a154+a339);
  a339=(a029*a154);
  a298=(a298+a339);
  a339=(a214*a076);
  a353=(a209*a286);
  a354=(a027*a351);
  a353=(a353+a354);
  a354=(a020*a353);
  a339=(a339+a354);
  a339=(a025*a339);
  a298=(a298+a339);
  a339=(a022*a353);
  a298=(a298+a339);
  a232=(a207*a232);
  a349=(a034*a349);
  a232=(a232+a349);
  a349=(a056*a272);
  a339=(a210*a349);
  a335=(a047*a335);
  a354=(2.*a076);
  a355=(a219*a354);
  a286=(2.*a286);
  a356=(a218*a286);
  a295=(a208*a295);
  a357=(a046*a312);
  a295=(a295+a357);
  a295=(a217*a295);
  a356=(a356+a295);
  a290=(a208*a290);
  a295=(a040*a312);
  a290=(a290+a295);
  a356=(a356+a290);
  a356=(a216*a356);
  a355=(a355+a356);
  a335=(a335+a355);
  a294=(a212*a294);
  a313=(a043*a313);
  a294=(a294+a313);
  a335=(a335+a294);
  a271=(a208*a271);
  a312=(a037*a312);
  a271=(a271+a312);
  a335=(a335+a271);
  a335=(a013*a335);
  a339=(a339+a335);
  a232=(a232+a339);
  a349=(a213*a349);
  a154=(a031*a154);
  a354=(a221*a354);
  a286=(a220*a286);
  a237=(a209*a237);
  a339=(a030*a351);
  a237=(a237+a339);
  a237=(a217*a237);
  a286=(a286+a237);
  a100=(a209*a100);
  a237=(a023*a351);
  a100=(a100+a237);
  a286=(a286+a100);
  a286=(a216*a286);
  a354=(a354+a286);
  a154=(a154+a354);
  a164=(a214*a164);
  a353=(a026*a353);
  a164=(a164+a353);
  a154=(a154+a164);
  a055=(a209*a055);
  a164=(a017*a351);
  a055=(a055+a164);
  a154=(a154+a055);
  a154=(a013*a154);
  a349=(a349+a154);
  a232=(a232+a349);
  a232=(a018*a232);
  a298=(a298+a232);
  a076=(a209*a076);
  a232=(a020*a351);
  a076=(a076+a232);
  a076=(a016*a076);
  a298=(a298+a076);
  a351=(a001*a351);
  a298=(a298+a351);
  a351=(a198*a298);
  a325=(a325+a351);
  a351=(a058*a325);
  a351=(a302+a351);
  a076=(a222*a319);
  a346=(a056*a346);
  a346=(a346+a317);
  a337=(a011*a337);
  a346=(a346-a337);
  a348=(a085*a348);
  a346=(a346+a348);
  a182=(a182*a002);
  a348=(a188*a296);
  a341=(a048*a341);
  a348=(a348+a341);
  a341=(a197*a296);
  a347=(a048*a347);
  a341=(a341+a347);
  a348=(a348+a341);
  a341=(a004*a348);
  a341=(a182+a341);
  a346=(a346-a341);
  a296=(a205*a296);
  a352=(a048*a352);
  a296=(a296+a352);
  a344=(a296+a344);
  a344=(a223*a344);
  a346=(a346+a344);
  a344=(a223*a298);
  a346=(a346+a344);
  a344=(a087*a346);
  a344=(a076+a344);
  a351=(a351+a344);
  a338=(a085*a338);
  a342=(a056*a342);
  a338=(a338+a342);
  a342=(2.*a002);
  a224=(a224*a342);
  a296=(a296+a327);
  a296=(a226*a296);
  a224=(a224+a296);
  a338=(a338+a224);
  a338=(a338+a309);
  a345=(a011*a345);
  a338=(a338-a345);
  a348=(a007*a348);
  a338=(a338-a348);
  a211=(a211*a342);
  a298=(a226*a298);
  a298=(a211+a298);
  a338=(a338+a298);
  a298=(a090*a338);
  a321=(a225*a321);
  a298=(a298-a321);
  a351=(a351+a298);
  a311=(a200*a311);
  a311=(a083*a311);
  a351=(a351-a311);
  a311=(a062*a314);
  a321=(a072*a307);
  a321=(a311-a321);
  a297=(a229*a297);
  a215=(a014*a215);
  a292=(a019*a292);
  a215=(a215+a292);
  a215=(a052*a215);
  a297=(a297+a215);
  a215=(a011*a297);
  a292=(a321+a215);
  a292=(a227*a292);
  a272=(a062*a272);
  a348=(a012*a307);
  a272=(a272-a348);
  a272=(a233*a272);
  a292=(a292-a272);
  a230=(a230*a002);
  a272=(a004*a297);
  a272=(a230-a272);
  a348=(a095*a307);
  a272=(a272-a348);
  a272=(a234*a272);
  a292=(a292+a272);
  a292=(a083*a292);
  a351=(a351+a292);
  a351=(a351/a002);
  if (res[1]!=0) res[1][0]=a351;
  a330=(a109*a330);
  a351=(a102*a325);
  a330=(a330+a351);
  a351=(a104*a346);
  a332=(a222*a332);
  a351=(a351-a332);
  a330=(a330+a351);
  a319=(a225*a319);
  a332=(a106*a338);
  a332=(a319+a332);
  a330=(a330+a332);
  a316=(a200*a316);
  a316=(a083*a316);
  a330=(a330-a316);
  a316=(a008*a307);
  a316=(a227*a316);
  a321=(a321-a215);
  a321=(a233*a321);
  a316=(a316+a321);
  a321=(a062*a300);
  a307=(a054*a307);
  a307=(a321-a307);
  a297=(a007*a297);
  a307=(a307+a297);
  a307=(a234*a307);
  a316=(a316+a307);
  a316=(a083*a316);
  a330=(a330-a316);
  a330=(a330/a002);
  if (res[1]!=0) res[1][1]=a330;
  a330=(a108*a325);
  a331=(a109*a331);
  a330=(a330-a331);
  a322=(a222*a322);
  a331=(a111*a346);
  a322=(a322+a331);
  a322=(a330+a322);
  a299=(a225*a299);
  a331=(a113*a338);
  a331=(a299+a331);
  a322=(a322+a331);
  a308=(a200*a308);
  a308=(a083*a308);
  a322=(a322-a308);
  a322=(a322/a002);
  if (res[1]!=0) res[1][2]=a322;
  a322=(a147*a150);
  a308=(a158*a322);
  a334=(a018*a334);
  a340=(a238*a340);
  a334=(a334+a340);
  a340=(a148*a334);
  a308=(a308+a340);
  a340=(a134*a308);
  a331=(a147*a144);
  a316=(a185*a331);
  a326=(a018*a326);
  a343=(a238*a343);
  a326=(a326+a343);
  a343=(a142*a326);
  a316=(a316+a343);
  a343=(a134*a316);
  a340=(a340+a343);
  a343=(a117*a340);
  a310=(a310-a343);
  a343=(a147*a146);
  a307=(a185*a343);
  a297=(a069*a326);
  a307=(a307+a297);
  a297=(a085*a307);
  a310=(a310+a297);
  a297=(a158*a343);
  a215=(a069*a334);
  a297=(a297+a215);
  a215=(a134*a297);
  a332=(a194*a331);
  a336=(a018*a336);
  a333=(a238*a333);
  a336=(a336+a333);
  a333=(a142*a336);
  a332=(a332+a333);
  a333=(a134*a332);
  a215=(a215+a333);
  a333=(a115*a215);
  a310=(a310-a333);
  a333=(a194*a322);
  a292=(a148*a336);
  a333=(a333+a292);
  a292=(a056*a333);
  a310=(a310+a292);
  a292=(a185*a322);
  a326=(a148*a326);
  a292=(a292+a326);
  a326=(a134*a292);
  a272=(a194*a343);
  a336=(a069*a336);
  a272=(a272+a336);
  a336=(a134*a272);
  a348=(a326+a336);
  a348=(a244*a348);
  a310=(a310+a348);
  a348=(a158*a331);
  a334=(a142*a334);
  a348=(a348+a334);
  a334=(a119*a348);
  a345=(a160*a308);
  a334=(a334-a345);
  a345=(a141*a297);
  a334=(a334-a345);
  a345=(a160*a316);
  a334=(a334-a345);
  a292=(a121*a292);
  a334=(a334+a292);
  a292=(a149*a307);
  a334=(a334-a292);
  a292=(a141*a332);
  a334=(a334-a292);
  a292=(a149*a333);
  a334=(a334-a292);
  a272=(a118*a272);
  a334=(a334+a272);
  a272=(a250*a334);
  a272=(a049*a272);
  a292=(a125*a272);
  a334=(a334/a123);
  a292=(a292-a334);
  a345=(a131*a292);
  a309=(a045*a345);
  a224=(a129*a292);
  a296=(a126*a224);
  a296=(a042*a296);
  a309=(a309+a296);
  a296=(a039*a224);
  a309=(a309+a296);
  a296=(a126*a292);
  a296=(a036*a296);
  a309=(a309+a296);
  a296=(a033*a292);
  a309=(a309+a296);
  a296=(a131*a334);
  a327=(a029*a296);
  a309=(a309+a327);
  a327=(a129*a334);
  a344=(a126*a327);
  a344=(a025*a344);
  a309=(a309+a344);
  a344=(a022*a327);
  a309=(a309+a344);
  a272=(a132*a272);
  a345=(a047*a345);
  a344=(a130*a292);
  a344=(a263*a344);
  a352=(a127*a292);
  a344=(a344+a352);
  a344=(a262*a344);
  a345=(a345+a344);
  a224=(a128*a224);
  a345=(a345+a224);
  a292=(a124*a292);
  a345=(a345+a292);
  a345=(a122*a345);
  a272=(a272+a345);
  a296=(a031*a296);
  a345=(a138*a334);
  a345=(a263*a345);
  a292=(a136*a334);
  a345=(a345+a292);
  a345=(a262*a345);
  a296=(a296+a345);
  a327=(a137*a327);
  a296=(a296+a327);
  a327=(a135*a334);
  a296=(a296+a327);
  a296=(a122*a296);
  a272=(a272+a296);
  a272=(a018*a272);
  a309=(a309+a272);
  a272=(a126*a334);
  a272=(a016*a272);
  a309=(a309+a272);
  a334=(a001*a334);
  a309=(a309+a334);
  a334=(a244*a309);
  a310=(a310+a334);
  a334=(a153*a310);
  a343=(a200*a343);
  a343=(a083*a343);
  a334=(a334-a343);
  a297=(a056*a297);
  a323=(a323+a297);
  a340=(a120*a340);
  a323=(a323-a340);
  a332=(a085*a332);
  a323=(a323+a332);
  a307=(a134*a307);
  a333=(a134*a333);
  a307=(a307+a333);
  a333=(a115*a307);
  a323=(a323-a333);
  a348=(a134*a348);
  a336=(a348+a336);
  a336=(a268*a336);
  a323=(a323+a336);
  a336=(a268*a309);
  a323=(a323+a336);
  a336=(a156*a323);
  a334=(a334+a336);
  a308=(a085*a308);
  a304=(a304+a308);
  a316=(a056*a316);
  a304=(a304+a316);
  a348=(a348+a326);
  a348=(a270*a348);
  a304=(a304+a348);
  a215=(a120*a215);
  a304=(a304-a215);
  a307=(a117*a307);
  a304=(a304-a307);
  a309=(a270*a309);
  a304=(a304+a309);
  a309=(a157*a304);
  a334=(a334+a309);
  a334=(a334/a002);
  if (res[1]!=0) res[1][3]=a334;
  a334=(a166*a310);
  a322=(a200*a322);
  a322=(a083*a322);
  a334=(a334-a322);
  a322=(a167*a323);
  a334=(a334+a322);
  a307=(a169*a304);
  a334=(a334+a307);
  a334=(a334/a002);
  if (res[1]!=0) res[1][4]=a334;
  a334=(a171*a310);
  a331=(a200*a331);
  a331=(a083*a331);
  a331=(a334-a331);
  a307=(a173*a323);
  a331=(a331+a307);
  a307=(a175*a304);
  a331=(a331+a307);
  a331=(a331/a002);
  if (res[1]!=0) res[1][5]=a331;
  a331=(2.*a273);
  a307=-1.7320508075688774e+00;
  a307=(a307*a002);
  a215=(a331*a307);
  a348=(a001*a215);
  a326=(a016*a215);
  a326=(a282*a326);
  a279=(a056*a279);
  a316=(a018*a215);
  a308=(a279*a316);
  a336=(a015*a308);
  a326=(a326+a336);
  a348=(a348+a326);
  a326=(a022*a215);
  a336=(a025*a215);
  a336=(a282*a336);
  a333=(a024*a308);
  a336=(a336+a333);
  a326=(a326+a336);
  a326=(a283*a326);
  a336=(2.*a282);
  a333=(a336*a308);
  a332=(a021*a333);
  a326=(a326+a332);
  a348=(a348+a326);
  a326=(a029*a215);
  a332=(a031*a308);
  a326=(a326+a332);
  a326=(a284*a326);
  a332=(2.*a283);
  a340=(a332*a333);
  a297=(a028*a340);
  a326=(a326+a297);
  a348=(a348+a326);
  a326=(a033*a215);
  a297=(a036*a215);
  a297=(a282*a297);
  a343=(a035*a308);
  a297=(a297+a343);
  a326=(a326+a297);
  a297=(a039*a215);
  a343=(a042*a215);
  a343=(a282*a343);
  a272=(a041*a308);
  a343=(a343+a272);
  a297=(a297+a343);
  a297=(a283*a297);
  a333=(a038*a333);
  a297=(a297+a333);
  a326=(a326+a297);
  a297=(a045*a215);
  a308=(a047*a308);
  a297=(a297+a308);
  a297=(a284*a297);
  a340=(a044*a340);
  a297=(a297+a340);
  a326=(a326+a297);
  a348=(a348-a326);
  a348=(a348/a285);
  a297=(a000/a285);
  a316=(a051*a316);
  a326=(a281*a326);
  a316=(a316+a326);
  a316=(a049*a316);
  a316=(a297*a316);
  a348=(a348+a316);
  a316=(a280*a348);
  a326=(a277*a307);
  a326=(a000*a326);
  a316=(a316+a326);
  a340=(a081*a316);
  a308=(a289*a348);
  a333=(a236*a307);
  a333=(a000*a333);
  a308=(a308+a333);
  a343=(a088*a308);
  a340=(a340+a343);
  a343=(a275*a348);
  a343=(a091*a343);
  a340=(a340-a343);
  a343=(a152*a310);
  a340=(a340+a343);
  a343=(a155*a323);
  a340=(a340+a343);
  a340=(a340+a309);
  a309=(a057*a325);
  a302=(a302+a309);
  a340=(a340+a302);
  a302=(a086*a346);
  a076=(a076+a302);
  a340=(a340+a076);
  a340=(a340+a298);
  a340=(-a340);
  if (res[1]!=0) res[1][6]=a340;
  a340=8.6602540378443871e-01;
  a340=(a340*a002);
  a298=(a191*a348);
  a076=(a340+a298);
  a076=(a081*a076);
  a302=(a278*a348);
  a215=(a000*a215);
  a302=(a302+a215);
  a302=(a088*a302);
  a076=(a076-a302);
  a308=(a091*a308);
  a076=(a076+a308);
  a310=(a165*a310);
  a076=(a076+a310);
  a076=(a076+a322);
  a322=(a168*a304);
  a076=(a076+a322);
  a322=(a329+a328);
  a322=(a109*a322);
  a325=(a101*a325);
  a322=(a322+a325);
  a076=(a076+a322);
  a076=(a076+a351);
  a351=(a105*a338);
  a319=(a319+a351);
  a076=(a076+a319);
  a076=(-a076);
  if (res[1]!=0) res[1][7]=a076;
  a076=-8.6602540378443871e-01;
  a076=(a076*a002);
  a298=(a076+a298);
  a298=(a088*a298);
  a348=(a276*a348);
  a348=(a348+a215);
  a348=(a081*a348);
  a298=(a298-a348);
  a316=(a091*a316);
  a298=(a298+a316);
  a298=(a298+a334);
  a323=(a172*a323);
  a298=(a298+a323);
  a304=(a174*a304);
  a298=(a298+a304);
  a298=(a298+a330);
  a328=(a083+a328);
  a328=(a222*a328);
  a346=(a110*a346);
  a328=(a328+a346);
  a298=(a298+a328);
  a338=(a112*a338);
  a299=(a299+a338);
  a298=(a298+a299);
  a298=(-a298);
  if (res[1]!=0) res[1][8]=a298;
  a298=(a223*a002);
  a299=(a001*a298);
  a338=(a016*a298);
  a328=(a020*a338);
  a346=(a018*a298);
  a330=(a013*a346);
  a304=(a017*a330);
  a328=(a328+a304);
  a299=(a299+a328);
  a328=(a022*a298);
  a304=(a025*a298);
  a323=(a020*a304);
  a334=(a026*a330);
  a323=(a323+a334);
  a328=(a328+a323);
  a323=(a027*a328);
  a334=(a216*a330);
  a316=(a023*a334);
  a323=(a323+a316);
  a299=(a299+a323);
  a323=(a029*a298);
  a316=(a031*a330);
  a323=(a323+a316);
  a316=(a032*a323);
  a348=(a217*a334);
  a215=(a030*a348);
  a316=(a316+a215);
  a299=(a299+a316);
  a316=(a033*a298);
  a215=(a036*a298);
  a319=(a020*a215);
  a351=(a037*a330);
  a319=(a319+a351);
  a316=(a316+a319);
  a319=(a039*a298);
  a351=(a042*a298);
  a322=(a020*a351);
  a325=(a043*a330);
  a322=(a322+a325);
  a319=(a319+a322);
  a322=(a027*a319);
  a325=(a040*a334);
  a322=(a322+a325);
  a316=(a316+a322);
  a322=(a045*a298);
  a325=(a047*a330);
  a322=(a322+a325);
  a325=(a032*a322);
  a310=(a046*a348);
  a325=(a325+a310);
  a316=(a316+a325);
  a325=(a299-a316);
  a325=(a325/a053);
  a310=(a034*a346);
  a308=(a019*a316);
  a310=(a310+a308);
  a308=(a049*a310);
  a302=(a204*a308);
  a325=(a325+a302);
  a302=(a054*a325);
  a309=(a302-a083);
  a343=(a109*a309);
  a272=(a052*a299);
  a296=(a014*a310);
  a272=(a272-a296);
  a272=(a316+a272);
  a272=(a018*a272);
  a296=(a054*a272);
  a327=(a306*a310);
  a327=(a056*a327);
  a345=(a007*a327);
  a345=(a318-a345);
  a292=(a296-a345);
  a224=(a079*a292);
  a344=(a072*a272);
  a352=(a004*a002);
  a341=(a060*a352);
  a344=(a344+a341);
  a347=(a011*a327);
  a337=(a344-a347);
  a317=(a075*a337);
  a232=(a066*a074);
  a317=(a317+a232);
  a232=(a008*a272);
  a349=(a060*a298);
  a232=(a232+a349);
  a154=(a067*a232);
  a317=(a317-a154);
  a292=(a077*a292);
  a317=(a317+a292);
  a292=(2.*a317);
  a292=(a080*a292);
  a309=(a082*a309);
  a154=(a072*a325);
  a055=(a048*a352);
  a154=(a154+a055);
  a164=(a089*a154);
  a309=(a309+a164);
  a164=(a008*a325);
  a353=(a048*a298);
  a164=(a164+a353);
  a354=(a092*a164);
  a309=(a309-a354);
  a292=(a292-a309);
  a292=(a292/a083);
  a309=(a064*a292);
  a224=(a224+a309);
  a309=(a095*a272);
  a309=(a309+a305);
  a305=(a004*a327);
  a354=(a309-a305);
  a286=(a098*a354);
  a344=(a344+a347);
  a347=(a067*a344);
  a100=(a066*a005);
  a237=(a012*a272);
  a339=(a075*a237);
  a100=(a100-a339);
  a347=(a347+a100);
  a354=(a077*a354);
  a347=(a347+a354);
  a354=(2.*a347);
  a354=(a099*a354);
  a100=(a095*a325);
  a100=(a100+a301);
  a301=(a082*a100);
  a339=(a012*a325);
  a335=(a089*a339);
  a301=(a301-a335);
  a335=(a092*a154);
  a301=(a301+a335);
  a354=(a354-a301);
  a354=(a354/a083);
  a301=(a097*a354);
  a286=(a286+a301);
  a224=(a224+a286);
  a345=(a345+a296);
  a296=(a067*a345);
  a309=(a309+a305);
  a305=(a075*a309);
  a286=(a066*a096);
  a305=(a305+a286);
  a296=(a296+a305);
  a272=(a009*a272);
  a272=(a272+a349);
  a349=(a077*a272);
  a296=(a296-a349);
  a349=(2.*a296);
  a349=(a107*a349);
  a305=(a089*a100);
  a286=(a009*a325);
  a286=(a286+a353);
  a353=(a082*a286);
  a305=(a305-a353);
  a353=(a302-a329);
  a301=(a092*a353);
  a305=(a305+a301);
  a349=(a349-a305);
  a349=(a349/a083);
  a305=(a103*a349);
  a272=(a094*a272);
  a305=(a305-a272);
  a224=(a224+a305);
  a305=(a059*a224);
  a272=(a303*a151);
  a272=(a080*a272);
  a272=(a272/a083);
  a301=(a145*a272);
  a335=(a303*a116);
  a335=(a099*a335);
  a335=(a335/a083);
  a271=(a162*a335);
  a301=(a301+a271);
  a271=(a303*a161);
  a271=(a107*a271);
  a271=(a271/a083);
  a312=(a170*a271);
  a301=(a301+a312);
  a312=(a114*a301);
  a305=(a305+a312);
  a181=(a181*a002);
  a312=(a180*a325);
  a294=(a178*a347);
  a224=(a177*a224);
  a301=(a059*a301);
  a224=(a224+a301);
  a301=(a002*a224);
  a313=(a176*a301);
  a355=(a002*a305);
  a356=(a018*a355);
  a313=(a313+a356);
  a356=(a071*a313);
  a294=(a294+a356);
  a356=(a048*a294);
  a312=(a312+a356);
  a356=(a187*a325);
  a290=(a186*a296);
  a337=(a079*a337);
  a295=(a074*a292);
  a337=(a337+a295);
  a295=(a005*a354);
  a237=(a098*a237);
  a295=(a295-a237);
  a337=(a337+a295);
  a309=(a094*a309);
  a295=(a096*a349);
  a309=(a309+a295);
  a337=(a337+a309);
  a309=(a177*a337);
  a295=(a151*a272);
  a237=(a116*a335);
  a295=(a295+a237);
  a237=(a161*a271);
  a295=(a295+a237);
  a237=(a059*a295);
  a309=(a309+a237);
  a237=(a002*a309);
  a357=(a176*a237);
  a337=(a059*a337);
  a295=(a114*a295);
  a337=(a337+a295);
  a295=(a002*a337);
  a358=(a018*a295);
  a357=(a357+a358);
  a358=(a061*a357);
  a290=(a290+a358);
  a358=(a048*a290);
  a356=(a356+a358);
  a312=(a312+a356);
  a356=(a007*a312);
  a356=(a181+a356);
  a305=(a305-a356);
  a356=(a186*a317);
  a358=(a070*a357);
  a356=(a356+a358);
  a358=(a085*a356);
  a305=(a305+a358);
  a358=(a189*a325);
  a359=(a178*a317);
  a360=(a070*a313);
  a359=(a359+a360);
  a360=(a048*a359);
  a358=(a358+a360);
  a360=(a196*a325);
  a361=(a195*a296);
  a292=(a065*a292);
  a232=(a079*a232);
  a292=(a292-a232);
  a344=(a098*a344);
  a354=(a073*a354);
  a344=(a344+a354);
  a292=(a292+a344);
  a345=(a094*a345);
  a349=(a063*a349);
  a345=(a345+a349);
  a292=(a292+a345);
  a345=(a177*a292);
  a272=(a146*a272);
  a335=(a150*a335);
  a272=(a272+a335);
  a271=(a144*a271);
  a272=(a272+a271);
  a271=(a059*a272);
  a345=(a345+a271);
  a271=(a002*a345);
  a335=(a176*a271);
  a292=(a059*a292);
  a272=(a114*a272);
  a292=(a292+a272);
  a272=(a002*a292);
  a349=(a018*a272);
  a335=(a335+a349);
  a349=(a061*a335);
  a361=(a361+a349);
  a349=(a048*a361);
  a360=(a360+a349);
  a358=(a358+a360);
  a360=(a004*a358);
  a305=(a305-a360);
  a360=(a195*a347);
  a349=(a071*a335);
  a360=(a360+a349);
  a349=(a056*a360);
  a305=(a305+a349);
  a349=(a199*a325);
  a344=(a186*a347);
  a357=(a071*a357);
  a344=(a344+a357);
  a357=(a048*a344);
  a349=(a349+a357);
  a357=(a201*a325);
  a354=(a195*a317);
  a335=(a070*a335);
  a354=(a354+a335);
  a335=(a048*a354);
  a357=(a357+a335);
  a335=(a349+a357);
  a335=(a198*a335);
  a305=(a305+a335);
  a335=(a208*a348);
  a232=(a207*a346);
  a362=(a325/a053);
  a363=(a350*a308);
  a362=(a362+a363);
  a362=(a206*a362);
  a363=(a205*a298);
  a364=(a178*a296);
  a313=(a061*a313);
  a364=(a364+a313);
  a313=(a009*a364);
  a363=(a363+a313);
  a313=(a180*a300);
  a365=(a095*a294);
  a313=(a313+a365);
  a363=(a363-a313);
  a313=(a054*a359);
  a363=(a363-a313);
  a300=(a187*a300);
  a313=(a095*a290);
  a300=(a300+a313);
  a363=(a363-a300);
  a344=(a012*a344);
  a363=(a363+a344);
  a344=(a188*a352);
  a300=(a072*a356);
  a344=(a344+a300);
  a363=(a363-a344);
  a344=(a054*a361);
  a363=(a363-a344);
  a344=(a197*a352);
  a300=(a072*a360);
  a344=(a344+a300);
  a363=(a363-a344);
  a344=(a201*a298);
  a354=(a008*a354);
  a344=(a344+a354);
  a363=(a363+a344);
  a344=(a204*a363);
  a362=(a362+a344);
  a362=(a049*a362);
  a344=(a019*a362);
  a232=(a232+a344);
  a363=(a363/a053);
  a308=(a324*a308);
  a363=(a363+a308);
  a232=(a232-a363);
  a308=(a032*a232);
  a335=(a335+a308);
  a308=(a045*a335);
  a344=(a212*a330);
  a354=(a208*a334);
  a300=(a027*a232);
  a354=(a354+a300);
  a300=(a020*a354);
  a344=(a344+a300);
  a344=(a042*a344);
  a308=(a308+a344);
  a344=(a039*a354);
  a308=(a308+a344);
  a344=(a208*a330);
  a300=(a020*a232);
  a344=(a344+a300);
  a344=(a036*a344);
  a308=(a308+a344);
  a344=(a033*a232);
  a308=(a308+a344);
  a348=(a209*a348);
  a344=(a032*a363);
  a348=(a348+a344);
  a344=(a029*a348);
  a308=(a308+a344);
  a344=(a214*a330);
  a300=(a209*a334);
  a313=(a027*a363);
  a300=(a300+a313);
  a313=(a020*a300);
  a344=(a344+a313);
  a344=(a025*a344);
  a308=(a308+a344);
  a344=(a022*a300);
  a308=(a308+a344);
  a316=(a207*a316);
  a362=(a034*a362);
  a316=(a316+a362);
  a362=(a056*a298);
  a344=(a210*a362);
  a335=(a047*a335);
  a313=(2.*a330);
  a365=(a219*a313);
  a334=(2.*a334);
  a366=(a218*a334);
  a322=(a208*a322);
  a367=(a046*a232);
  a322=(a322+a367);
  a322=(a217*a322);
  a366=(a366+a322);
  a319=(a208*a319);
  a322=(a040*a232);
  a319=(a319+a322);
  a366=(a366+a319);
  a366=(a216*a366);
  a365=(a365+a366);
  a335=(a335+a365);
  a351=(a212*a351);
  a354=(a043*a354);
  a351=(a351+a354);
  a335=(a335+a351);
  a215=(a208*a215);
  a232=(a037*a232);
  a215=(a215+a232);
  a335=(a335+a215);
  a335=(a013*a335);
  a344=(a344+a335);
  a316=(a316+a344);
  a362=(a213*a362);
  a348=(a031*a348);
  a313=(a221*a313);
  a334=(a220*a334);
  a323=(a209*a323);
  a344=(a030*a363);
  a323=(a323+a344);
  a323=(a217*a323);
  a334=(a334+a323);
  a328=(a209*a328);
  a323=(a023*a363);
  a328=(a328+a323);
  a334=(a334+a328);
  a334=(a216*a334);
  a313=(a313+a334);
  a348=(a348+a313);
  a304=(a214*a304);
  a300=(a026*a300);
  a304=(a304+a300);
  a348=(a348+a304);
  a338=(a209*a338);
  a304=(a017*a363);
  a338=(a338+a304);
  a348=(a348+a338);
  a348=(a013*a348);
  a362=(a362+a348);
  a316=(a316+a362);
  a316=(a018*a316);
  a308=(a308+a316);
  a330=(a209*a330);
  a316=(a020*a363);
  a330=(a330+a316);
  a330=(a016*a330);
  a308=(a308+a330);
  a363=(a001*a363);
  a308=(a308+a363);
  a363=(a198*a308);
  a305=(a305+a363);
  a363=(a058*a305);
  a343=(a343+a363);
  a363=(a222*a154);
  a359=(a056*a359);
  a359=(a359+a337);
  a312=(a011*a312);
  a359=(a359-a312);
  a361=(a085*a361);
  a359=(a359+a361);
  a361=(a188*a325);
  a356=(a048*a356);
  a361=(a361+a356);
  a356=(a197*a325);
  a360=(a048*a360);
  a356=(a356+a360);
  a361=(a361+a356);
  a356=(a004*a361);
  a359=(a359-a356);
  a202=(a202*a342);
  a325=(a205*a325);
  a364=(a048*a364);
  a325=(a325+a364);
  a357=(a325+a357);
  a357=(a223*a357);
  a202=(a202+a357);
  a359=(a359+a202);
  a202=(a223*a308);
  a202=(a211+a202);
  a359=(a359+a202);
  a202=(a087*a359);
  a202=(a363+a202);
  a343=(a343+a202);
  a294=(a085*a294);
  a290=(a056*a290);
  a294=(a294+a290);
  a325=(a325+a349);
  a325=(a226*a325);
  a294=(a294+a325);
  a294=(a294+a292);
  a358=(a011*a358);
  a294=(a294-a358);
  a361=(a007*a361);
  a182=(a182+a361);
  a294=(a294-a182);
  a308=(a226*a308);
  a294=(a294+a308);
  a308=(a090*a294);
  a164=(a225*a164);
  a308=(a308-a164);
  a343=(a343+a308);
  a317=(a200*a317);
  a317=(a083*a317);
  a343=(a343-a317);
  a317=(a062*a352);
  a164=(a072*a327);
  a164=(a317-a164);
  a310=(a229*a310);
  a346=(a014*a346);
  a299=(a019*a299);
  a346=(a346+a299);
  a346=(a052*a346);
  a310=(a310+a346);
  a346=(a011*a310);
  a299=(a164+a346);
  a299=(a227*a299);
  a182=(a012*a327);
  a182=(a233*a182);
  a299=(a299+a182);
  a182=(a095*a327);
  a321=(a321-a182);
  a182=(a004*a310);
  a321=(a321-a182);
  a321=(a234*a321);
  a299=(a299+a321);
  a299=(a083*a299);
  a343=(a343+a299);
  a343=(a343/a002);
  if (res[1]!=0) res[1][9]=a343;
  a343=(a109*a100);
  a299=(a102*a305);
  a299=(a343+a299);
  a321=(a104*a359);
  a339=(a222*a339);
  a321=(a321-a339);
  a299=(a299+a321);
  a154=(a225*a154);
  a339=(a106*a294);
  a339=(a154+a339);
  a299=(a299+a339);
  a347=(a200*a347);
  a347=(a083*a347);
  a299=(a299-a347);
  a164=(a164-a346);
  a164=(a233*a164);
  a298=(a062*a298);
  a346=(a008*a327);
  a298=(a298-a346);
  a298=(a227*a298);
  a164=(a164-a298);
  a327=(a054*a327);
  a310=(a007*a310);
  a310=(a230-a310);
  a327=(a327+a310);
  a327=(a234*a327);
  a164=(a164-a327);
  a164=(a083*a164);
  a299=(a299-a164);
  a299=(a299/a002);
  if (res[1]!=0) res[1][10]=a299;
  a299=(a108*a305);
  a286=(a109*a286);
  a299=(a299-a286);
  a100=(a222*a100);
  a286=(a111*a359);
  a286=(a100+a286);
  a286=(a299+a286);
  a353=(a225*a353);
  a164=(a113*a294);
  a353=(a353+a164);
  a286=(a286+a353);
  a296=(a200*a296);
  a296=(a083*a296);
  a286=(a286-a296);
  a286=(a286/a002);
  if (res[1]!=0) res[1][11]=a286;
  a286=(a147*a116);
  a296=(a158*a286);
  a301=(a018*a301);
  a355=(a238*a355);
  a301=(a301+a355);
  a355=(a148*a301);
  a296=(a296+a355);
  a355=(a134*a296);
  a353=(a147*a161);
  a164=(a185*a353);
  a237=(a018*a237);
  a295=(a238*a295);
  a237=(a237+a295);
  a295=(a142*a237);
  a164=(a164+a295);
  a295=(a134*a164);
  a355=(a355+a295);
  a295=(a117*a355);
  a224=(a224-a295);
  a295=(a147*a151);
  a327=(a185*a295);
  a310=(a069*a237);
  a327=(a327+a310);
  a310=(a085*a327);
  a224=(a224+a310);
  a310=(a158*a295);
  a298=(a069*a301);
  a310=(a310+a298);
  a298=(a134*a310);
  a346=(a194*a353);
  a271=(a018*a271);
  a272=(a238*a272);
  a271=(a271+a272);
  a272=(a142*a271);
  a346=(a346+a272);
  a272=(a134*a346);
  a298=(a298+a272);
  a272=(a115*a298);
  a224=(a224-a272);
  a272=(a194*a286);
  a347=(a148*a271);
  a272=(a272+a347);
  a347=(a056*a272);
  a224=(a224+a347);
  a347=(a185*a286);
  a237=(a148*a237);
  a347=(a347+a237);
  a237=(a134*a347);
  a339=(a194*a295);
  a271=(a069*a271);
  a339=(a339+a271);
  a271=(a134*a339);
  a182=(a237+a271);
  a182=(a244*a182);
  a224=(a224+a182);
  a182=(a158*a353);
  a301=(a142*a301);
  a182=(a182+a301);
  a301=(a119*a182);
  a361=(a160*a296);
  a301=(a301-a361);
  a361=(a141*a310);
  a301=(a301-a361);
  a361=(a160*a164);
  a301=(a301-a361);
  a347=(a121*a347);
  a301=(a301+a347);
  a347=(a149*a327);
  a301=(a301-a347);
  a347=(a141*a346);
  a301=(a301-a347);
  a347=(a149*a272);
  a301=(a301-a347);
  a339=(a118*a339);
  a301=(a301+a339);
  a339=(a250*a301);
  a339=(a049*a339);
  a347=(a125*a339);
  a301=(a301/a123);
  a347=(a347-a301);
  a361=(a131*a347);
  a358=(a045*a361);
  a292=(a129*a347);
  a325=(a126*a292);
  a325=(a042*a325);
  a358=(a358+a325);
  a325=(a039*a292);
  a358=(a358+a325);
  a325=(a126*a347);
  a325=(a036*a325);
  a358=(a358+a325);
  a325=(a033*a347);
  a358=(a358+a325);
  a325=(a131*a301);
  a349=(a029*a325);
  a358=(a358+a349);
  a349=(a129*a301);
  a290=(a126*a349);
  a290=(a025*a290);
  a358=(a358+a290);
  a290=(a022*a349);
  a358=(a358+a290);
  a339=(a132*a339);
  a361=(a047*a361);
  a290=(a130*a347);
  a290=(a263*a290);
  a202=(a127*a347);
  a290=(a290+a202);
  a290=(a262*a290);
  a361=(a361+a290);
  a292=(a128*a292);
  a361=(a361+a292);
  a347=(a124*a347);
  a361=(a361+a347);
  a361=(a122*a361);
  a339=(a339+a361);
  a325=(a031*a325);
  a361=(a138*a301);
  a361=(a263*a361);
  a347=(a136*a301);
  a361=(a361+a347);
  a361=(a262*a361);
  a325=(a325+a361);
  a349=(a137*a349);
  a325=(a325+a349);
  a349=(a135*a301);
  a325=(a325+a349);
  a325=(a122*a325);
  a339=(a339+a325);
  a339=(a018*a339);
  a358=(a358+a339);
  a339=(a126*a301);
  a339=(a016*a339);
  a358=(a358+a339);
  a301=(a001*a301);
  a358=(a358+a301);
  a301=(a244*a358);
  a224=(a224+a301);
  a301=(a153*a224);
  a295=(a200*a295);
  a295=(a083*a295);
  a301=(a301-a295);
  a310=(a056*a310);
  a309=(a309+a310);
  a355=(a120*a355);
  a309=(a309-a355);
  a346=(a085*a346);
  a309=(a309+a346);
  a327=(a134*a327);
  a272=(a134*a272);
  a327=(a327+a272);
  a272=(a115*a327);
  a309=(a309-a272);
  a182=(a134*a182);
  a271=(a182+a271);
  a271=(a268*a271);
  a309=(a309+a271);
  a271=(a268*a358);
  a309=(a309+a271);
  a271=(a156*a309);
  a301=(a301+a271);
  a296=(a085*a296);
  a345=(a345+a296);
  a164=(a056*a164);
  a345=(a345+a164);
  a182=(a182+a237);
  a182=(a270*a182);
  a345=(a345+a182);
  a298=(a120*a298);
  a345=(a345-a298);
  a327=(a117*a327);
  a345=(a345-a327);
  a358=(a270*a358);
  a345=(a345+a358);
  a358=(a157*a345);
  a301=(a301+a358);
  a301=(a301/a002);
  if (res[1]!=0) res[1][12]=a301;
  a301=(a166*a224);
  a286=(a200*a286);
  a286=(a083*a286);
  a301=(a301-a286);
  a286=(a167*a309);
  a301=(a301+a286);
  a327=(a169*a345);
  a301=(a301+a327);
  a301=(a301/a002);
  if (res[1]!=0) res[1][13]=a301;
  a301=(a171*a224);
  a353=(a200*a353);
  a353=(a083*a353);
  a353=(a301-a353);
  a327=(a173*a309);
  a353=(a353+a327);
  a327=(a175*a345);
  a353=(a353+a327);
  a353=(a353/a002);
  if (res[1]!=0) res[1][14]=a353;
  a353=(2.*a236);
  a327=(a353*a307);
  a298=(a001*a327);
  a182=(a016*a327);
  a182=(a282*a182);
  a237=(a018*a327);
  a164=(a279*a237);
  a296=(a015*a164);
  a182=(a182+a296);
  a298=(a298+a182);
  a182=(a022*a327);
  a296=(a025*a327);
  a296=(a282*a296);
  a271=(a024*a164);
  a296=(a296+a271);
  a182=(a182+a296);
  a182=(a283*a182);
  a296=(a336*a164);
  a271=(a021*a296);
  a182=(a182+a271);
  a298=(a298+a182);
  a182=(a029*a327);
  a271=(a031*a164);
  a182=(a182+a271);
  a182=(a284*a182);
  a271=(a332*a296);
  a272=(a028*a271);
  a182=(a182+a272);
  a298=(a298+a182);
  a182=(a033*a327);
  a272=(a036*a327);
  a272=(a282*a272);
  a346=(a035*a164);
  a272=(a272+a346);
  a182=(a182+a272);
  a272=(a039*a327);
  a346=(a042*a327);
  a346=(a282*a346);
  a355=(a041*a164);
  a346=(a346+a355);
  a272=(a272+a346);
  a272=(a283*a272);
  a296=(a038*a296);
  a272=(a272+a296);
  a182=(a182+a272);
  a272=(a045*a327);
  a164=(a047*a164);
  a272=(a272+a164);
  a272=(a284*a272);
  a271=(a044*a271);
  a272=(a272+a271);
  a182=(a182+a272);
  a298=(a298-a182);
  a298=(a298/a285);
  a237=(a051*a237);
  a182=(a281*a182);
  a237=(a237+a182);
  a237=(a049*a237);
  a237=(a297*a237);
  a298=(a298+a237);
  a237=(a280*a298);
  a182=(a076+a237);
  a182=(a081*a182);
  a272=(a289*a298);
  a271=(a273*a307);
  a271=(a000*a271);
  a272=(a272+a271);
  a164=(a088*a272);
  a182=(a182+a164);
  a164=(a275*a298);
  a327=(a000*a327);
  a164=(a164+a327);
  a164=(a091*a164);
  a182=(a182-a164);
  a164=(a152*a224);
  a182=(a182+a164);
  a164=(a155*a309);
  a182=(a182+a164);
  a182=(a182+a358);
  a358=(a083+a302);
  a358=(a109*a358);
  a164=(a057*a305);
  a358=(a358+a164);
  a182=(a182+a358);
  a358=(a086*a359);
  a363=(a363+a358);
  a182=(a182+a363);
  a182=(a182+a308);
  a182=(-a182);
  if (res[1]!=0) res[1][15]=a182;
  a182=(a191*a298);
  a182=(a182+a326);
  a326=(a081*a182);
  a308=(a278*a298);
  a308=(a088*a308);
  a326=(a326-a308);
  a272=(a091*a272);
  a326=(a326+a272);
  a224=(a165*a224);
  a326=(a326+a224);
  a326=(a326+a286);
  a286=(a168*a345);
  a326=(a326+a286);
  a305=(a101*a305);
  a343=(a343+a305);
  a326=(a326+a343);
  a326=(a326+a321);
  a321=(a105*a294);
  a154=(a154+a321);
  a326=(a326+a154);
  a326=(-a326);
  if (res[1]!=0) res[1][16]=a326;
  a182=(a088*a182);
  a298=(a276*a298);
  a298=(a298+a327);
  a298=(a081*a298);
  a182=(a182-a298);
  a237=(a340+a237);
  a237=(a091*a237);
  a182=(a182+a237);
  a182=(a182+a301);
  a309=(a172*a309);
  a182=(a182+a309);
  a345=(a174*a345);
  a182=(a182+a345);
  a182=(a182+a299);
  a359=(a110*a359);
  a100=(a100+a359);
  a182=(a182+a100);
  a302=(a329+a302);
  a302=(a225*a302);
  a294=(a112*a294);
  a302=(a302+a294);
  a182=(a182+a302);
  a182=(-a182);
  if (res[1]!=0) res[1][17]=a182;
  a182=(a198*a002);
  a302=(a001*a182);
  a294=(a016*a182);
  a100=(a020*a294);
  a359=(a018*a182);
  a299=(a013*a359);
  a345=(a017*a299);
  a100=(a100+a345);
  a302=(a302+a100);
  a100=(a022*a182);
  a345=(a025*a182);
  a309=(a020*a345);
  a301=(a026*a299);
  a309=(a309+a301);
  a100=(a100+a309);
  a309=(a027*a100);
  a301=(a216*a299);
  a237=(a023*a301);
  a309=(a309+a237);
  a302=(a302+a309);
  a309=(a029*a182);
  a237=(a031*a299);
  a309=(a309+a237);
  a237=(a032*a309);
  a298=(a217*a301);
  a327=(a030*a298);
  a237=(a237+a327);
  a302=(a302+a237);
  a237=(a033*a182);
  a327=(a036*a182);
  a326=(a020*a327);
  a154=(a037*a299);
  a326=(a326+a154);
  a237=(a237+a326);
  a326=(a039*a182);
  a154=(a042*a182);
  a321=(a020*a154);
  a343=(a043*a299);
  a321=(a321+a343);
  a326=(a326+a321);
  a321=(a027*a326);
  a343=(a040*a301);
  a321=(a321+a343);
  a237=(a237+a321);
  a321=(a045*a182);
  a343=(a047*a299);
  a321=(a321+a343);
  a343=(a032*a321);
  a305=(a046*a298);
  a343=(a343+a305);
  a237=(a237+a343);
  a343=(a302-a237);
  a343=(a343/a053);
  a305=(a034*a359);
  a286=(a019*a237);
  a305=(a305+a286);
  a286=(a049*a305);
  a224=(a204*a286);
  a343=(a343+a224);
  a224=(a054*a343);
  a224=(a224+a055);
  a055=(a109*a224);
  a272=(a052*a302);
  a308=(a014*a305);
  a272=(a272-a308);
  a272=(a237+a272);
  a272=(a018*a272);
  a308=(a054*a272);
  a308=(a308+a341);
  a306=(a306*a305);
  a306=(a056*a306);
  a341=(a007*a306);
  a363=(a308+a341);
  a358=(a079*a363);
  a164=(a011*a306);
  a318=(a318-a164);
  a164=(a072*a272);
  a296=(a318+a164);
  a346=(a075*a296);
  a355=(a008*a272);
  a060=(a060*a182);
  a355=(a355+a060);
  a310=(a067*a355);
  a346=(a346-a310);
  a363=(a077*a363);
  a310=(a066*a064);
  a363=(a363+a310);
  a346=(a346+a363);
  a363=(2.*a346);
  a363=(a080*a363);
  a310=(a082*a224);
  a295=(a072*a343);
  a339=(a295-a329);
  a325=(a089*a339);
  a310=(a310+a325);
  a325=(a008*a343);
  a349=(a048*a182);
  a325=(a325+a349);
  a361=(a092*a325);
  a310=(a310-a361);
  a363=(a363-a310);
  a363=(a363/a083);
  a310=(a064*a363);
  a358=(a358+a310);
  a310=(a095*a272);
  a310=(a310+a315);
  a315=(a004*a306);
  a361=(a310-a315);
  a347=(a098*a361);
  a164=(a164-a318);
  a318=(a067*a164);
  a292=(a012*a272);
  a292=(a292+a060);
  a060=(a075*a292);
  a318=(a318-a060);
  a361=(a077*a361);
  a060=(a066*a097);
  a361=(a361+a060);
  a318=(a318+a361);
  a361=(2.*a318);
  a361=(a099*a361);
  a060=(a095*a343);
  a060=(a060+a320);
  a320=(a082*a060);
  a290=(a012*a343);
  a290=(a290+a349);
  a349=(a089*a290);
  a320=(a320-a349);
  a349=(a295-a083);
  a202=(a092*a349);
  a320=(a320+a202);
  a361=(a361-a320);
  a361=(a361/a083);
  a320=(a097*a361);
  a347=(a347+a320);
  a358=(a358+a347);
  a308=(a308-a341);
  a067=(a067*a308);
  a310=(a310+a315);
  a075=(a075*a310);
  a067=(a067+a075);
  a075=(a066*a103);
  a272=(a009*a272);
  a077=(a077*a272);
  a075=(a075-a077);
  a067=(a067+a075);
  a075=(2.*a067);
  a075=(a107*a075);
  a077=(a089*a060);
  a315=(a009*a343);
  a341=(a082*a315);
  a077=(a077-a341);
  a341=(a092*a224);
  a077=(a077+a341);
  a075=(a075-a077);
  a075=(a075/a083);
  a077=(a103*a075);
  a272=(a094*a272);
  a077=(a077-a272);
  a358=(a358+a077);
  a077=(a059*a358);
  a272=(a303*a145);
  a272=(a080*a272);
  a272=(a272/a083);
  a341=(a145*a272);
  a347=(a303*a162);
  a347=(a099*a347);
  a347=(a347/a083);
  a320=(a162*a347);
  a341=(a341+a320);
  a303=(a303*a170);
  a303=(a107*a303);
  a303=(a303/a083);
  a320=(a170*a303);
  a341=(a341+a320);
  a320=(a114*a341);
  a077=(a077+a320);
  a320=(a180*a343);
  a202=(a178*a318);
  a358=(a177*a358);
  a341=(a059*a341);
  a358=(a358+a341);
  a341=(a002*a358);
  a357=(a176*a341);
  a364=(a002*a077);
  a356=(a018*a364);
  a357=(a357+a356);
  a356=(a071*a357);
  a202=(a202+a356);
  a356=(a048*a202);
  a320=(a320+a356);
  a356=(a187*a343);
  a360=(a186*a067);
  a296=(a079*a296);
  a312=(a074*a363);
  a296=(a296+a312);
  a312=(a005*a361);
  a292=(a098*a292);
  a312=(a312-a292);
  a296=(a296+a312);
  a310=(a094*a310);
  a312=(a096*a075);
  a310=(a310+a312);
  a296=(a296+a310);
  a310=(a177*a296);
  a312=(a151*a272);
  a292=(a116*a347);
  a312=(a312+a292);
  a292=(a161*a303);
  a312=(a312+a292);
  a292=(a059*a312);
  a310=(a310+a292);
  a292=(a002*a310);
  a337=(a176*a292);
  a296=(a059*a296);
  a312=(a114*a312);
  a296=(a296+a312);
  a312=(a002*a296);
  a330=(a018*a312);
  a337=(a337+a330);
  a330=(a061*a337);
  a360=(a360+a330);
  a330=(a048*a360);
  a356=(a356+a330);
  a320=(a320+a356);
  a356=(a007*a320);
  a077=(a077-a356);
  a356=(a186*a346);
  a330=(a070*a337);
  a356=(a356+a330);
  a330=(a085*a356);
  a077=(a077+a330);
  a330=(a189*a343);
  a316=(a178*a346);
  a362=(a070*a357);
  a316=(a316+a362);
  a362=(a048*a316);
  a330=(a330+a362);
  a362=(a196*a343);
  a348=(a195*a067);
  a363=(a065*a363);
  a079=(a079*a355);
  a363=(a363-a079);
  a098=(a098*a164);
  a361=(a073*a361);
  a098=(a098+a361);
  a363=(a363+a098);
  a094=(a094*a308);
  a075=(a063*a075);
  a094=(a094+a075);
  a363=(a363+a094);
  a094=(a177*a363);
  a272=(a146*a272);
  a347=(a150*a347);
  a272=(a272+a347);
  a303=(a144*a303);
  a272=(a272+a303);
  a303=(a059*a272);
  a094=(a094+a303);
  a303=(a002*a094);
  a347=(a176*a303);
  a363=(a059*a363);
  a272=(a114*a272);
  a363=(a363+a272);
  a272=(a002*a363);
  a075=(a018*a272);
  a347=(a347+a075);
  a075=(a061*a347);
  a348=(a348+a075);
  a075=(a048*a348);
  a362=(a362+a075);
  a330=(a330+a362);
  a362=(a004*a330);
  a077=(a077-a362);
  a362=(a195*a318);
  a075=(a071*a347);
  a362=(a362+a075);
  a075=(a056*a362);
  a077=(a077+a075);
  a203=(a203*a342);
  a075=(a199*a343);
  a308=(a186*a318);
  a337=(a071*a337);
  a308=(a308+a337);
  a337=(a048*a308);
  a075=(a075+a337);
  a337=(a201*a343);
  a098=(a195*a346);
  a347=(a070*a347);
  a098=(a098+a347);
  a347=(a048*a098);
  a337=(a337+a347);
  a347=(a075+a337);
  a347=(a198*a347);
  a203=(a203+a347);
  a077=(a077+a203);
  a203=(a208*a298);
  a347=(a207*a359);
  a361=(a343/a053);
  a350=(a350*a286);
  a361=(a361+a350);
  a206=(a206*a361);
  a361=(a178*a067);
  a357=(a061*a357);
  a361=(a361+a357);
  a357=(a009*a361);
  a180=(a180*a314);
  a350=(a095*a202);
  a180=(a180+a350);
  a357=(a357-a180);
  a189=(a189*a352);
  a180=(a054*a316);
  a189=(a189+a180);
  a357=(a357-a189);
  a187=(a187*a314);
  a314=(a095*a360);
  a187=(a187+a314);
  a357=(a357-a187);
  a199=(a199*a182);
  a308=(a012*a308);
  a199=(a199+a308);
  a357=(a357+a199);
  a199=(a072*a356);
  a357=(a357-a199);
  a196=(a196*a352);
  a352=(a054*a348);
  a196=(a196+a352);
  a357=(a357-a196);
  a196=(a072*a362);
  a357=(a357-a196);
  a201=(a201*a182);
  a098=(a008*a098);
  a201=(a201+a098);
  a357=(a357+a201);
  a201=(a204*a357);
  a206=(a206+a201);
  a206=(a049*a206);
  a201=(a019*a206);
  a347=(a347+a201);
  a357=(a357/a053);
  a324=(a324*a286);
  a357=(a357+a324);
  a347=(a347-a357);
  a324=(a032*a347);
  a203=(a203+a324);
  a324=(a045*a203);
  a286=(a212*a299);
  a201=(a208*a301);
  a098=(a027*a347);
  a201=(a201+a098);
  a098=(a020*a201);
  a286=(a286+a098);
  a286=(a042*a286);
  a324=(a324+a286);
  a286=(a039*a201);
  a324=(a324+a286);
  a286=(a208*a299);
  a098=(a020*a347);
  a286=(a286+a098);
  a286=(a036*a286);
  a324=(a324+a286);
  a286=(a033*a347);
  a324=(a324+a286);
  a298=(a209*a298);
  a286=(a032*a357);
  a298=(a298+a286);
  a286=(a029*a298);
  a324=(a324+a286);
  a286=(a214*a299);
  a098=(a209*a301);
  a196=(a027*a357);
  a098=(a098+a196);
  a196=(a020*a098);
  a286=(a286+a196);
  a286=(a025*a286);
  a324=(a324+a286);
  a286=(a022*a098);
  a324=(a324+a286);
  a207=(a207*a237);
  a206=(a034*a206);
  a207=(a207+a206);
  a206=(a056*a182);
  a210=(a210*a206);
  a203=(a047*a203);
  a237=(2.*a299);
  a219=(a219*a237);
  a301=(2.*a301);
  a218=(a218*a301);
  a321=(a208*a321);
  a286=(a046*a347);
  a321=(a321+a286);
  a321=(a217*a321);
  a218=(a218+a321);
  a326=(a208*a326);
  a321=(a040*a347);
  a326=(a326+a321);
  a218=(a218+a326);
  a218=(a216*a218);
  a219=(a219+a218);
  a203=(a203+a219);
  a212=(a212*a154);
  a201=(a043*a201);
  a212=(a212+a201);
  a203=(a203+a212);
  a208=(a208*a327);
  a347=(a037*a347);
  a208=(a208+a347);
  a203=(a203+a208);
  a203=(a013*a203);
  a210=(a210+a203);
  a207=(a207+a210);
  a213=(a213*a206);
  a298=(a031*a298);
  a221=(a221*a237);
  a220=(a220*a301);
  a309=(a209*a309);
  a301=(a030*a357);
  a309=(a309+a301);
  a309=(a217*a309);
  a220=(a220+a309);
  a100=(a209*a100);
  a309=(a023*a357);
  a100=(a100+a309);
  a220=(a220+a100);
  a220=(a216*a220);
  a221=(a221+a220);
  a298=(a298+a221);
  a214=(a214*a345);
  a098=(a026*a098);
  a214=(a214+a098);
  a298=(a298+a214);
  a294=(a209*a294);
  a214=(a017*a357);
  a294=(a294+a214);
  a298=(a298+a294);
  a298=(a013*a298);
  a213=(a213+a298);
  a207=(a207+a213);
  a207=(a018*a207);
  a324=(a324+a207);
  a209=(a209*a299);
  a299=(a020*a357);
  a209=(a209+a299);
  a209=(a016*a209);
  a324=(a324+a209);
  a357=(a001*a357);
  a324=(a324+a357);
  a357=(a198*a324);
  a211=(a211+a357);
  a077=(a077+a211);
  a211=(a058*a077);
  a211=(a055+a211);
  a339=(a222*a339);
  a316=(a056*a316);
  a316=(a316+a296);
  a320=(a011*a320);
  a181=(a181+a320);
  a316=(a316-a181);
  a348=(a085*a348);
  a316=(a316+a348);
  a188=(a188*a343);
  a356=(a048*a356);
  a188=(a188+a356);
  a197=(a197*a343);
  a362=(a048*a362);
  a197=(a197+a362);
  a188=(a188+a197);
  a197=(a004*a188);
  a316=(a316-a197);
  a205=(a205*a343);
  a361=(a048*a361);
  a205=(a205+a361);
  a337=(a205+a337);
  a337=(a223*a337);
  a316=(a316+a337);
  a337=(a223*a324);
  a316=(a316+a337);
  a337=(a087*a316);
  a339=(a339+a337);
  a211=(a211+a339);
  a202=(a085*a202);
  a360=(a056*a360);
  a202=(a202+a360);
  a205=(a205+a075);
  a205=(a226*a205);
  a202=(a202+a205);
  a202=(a202+a363);
  a330=(a011*a330);
  a190=(a190+a330);
  a202=(a202-a190);
  a188=(a007*a188);
  a202=(a202-a188);
  a324=(a226*a324);
  a202=(a202+a324);
  a324=(a090*a202);
  a325=(a225*a325);
  a324=(a324-a325);
  a211=(a211+a324);
  a346=(a200*a346);
  a346=(a083*a346);
  a211=(a211-a346);
  a346=(a095*a306);
  a311=(a311-a346);
  a229=(a229*a305);
  a014=(a014*a359);
  a302=(a019*a302);
  a014=(a014+a302);
  a052=(a052*a014);
  a229=(a229+a052);
  a052=(a004*a229);
  a311=(a311-a052);
  a311=(a234*a311);
  a052=(a072*a306);
  a014=(a011*a229);
  a230=(a230-a014);
  a014=(a052+a230);
  a014=(a227*a014);
  a062=(a062*a182);
  a182=(a012*a306);
  a182=(a062-a182);
  a182=(a233*a182);
  a014=(a014+a182);
  a311=(a311-a014);
  a311=(a083*a311);
  a211=(a211+a311);
  a211=(a211/a002);
  if (res[1]!=0) res[1][18]=a211;
  a211=(a109*a060);
  a311=(a102*a077);
  a311=(a211+a311);
  a014=(a104*a316);
  a290=(a222*a290);
  a014=(a014-a290);
  a311=(a311+a014);
  a349=(a225*a349);
  a290=(a106*a202);
  a349=(a349+a290);
  a311=(a311+a349);
  a318=(a200*a318);
  a318=(a083*a318);
  a311=(a311-a318);
  a230=(a230-a052);
  a230=(a233*a230);
  a052=(a008*a306);
  a062=(a062-a052);
  a062=(a227*a062);
  a230=(a230-a062);
  a306=(a054*a306);
  a317=(a317-a306);
  a229=(a007*a229);
  a317=(a317+a229);
  a317=(a234*a317);
  a230=(a230+a317);
  a230=(a083*a230);
  a311=(a311-a230);
  a311=(a311/a002);
  if (res[1]!=0) res[1][19]=a311;
  a311=(a108*a077);
  a109=(a109*a315);
  a311=(a311-a109);
  a060=(a222*a060);
  a109=(a111*a316);
  a109=(a060+a109);
  a109=(a311+a109);
  a224=(a225*a224);
  a315=(a113*a202);
  a315=(a224+a315);
  a109=(a109+a315);
  a067=(a200*a067);
  a067=(a083*a067);
  a109=(a109-a067);
  a109=(a109/a002);
  if (res[1]!=0) res[1][20]=a109;
  a109=(a147*a162);
  a067=(a158*a109);
  a341=(a018*a341);
  a364=(a238*a364);
  a341=(a341+a364);
  a364=(a148*a341);
  a067=(a067+a364);
  a364=(a134*a067);
  a315=(a147*a170);
  a230=(a185*a315);
  a292=(a018*a292);
  a312=(a238*a312);
  a292=(a292+a312);
  a312=(a142*a292);
  a230=(a230+a312);
  a312=(a134*a230);
  a364=(a364+a312);
  a312=(a117*a364);
  a358=(a358-a312);
  a147=(a147*a145);
  a312=(a185*a147);
  a317=(a069*a292);
  a312=(a312+a317);
  a317=(a085*a312);
  a358=(a358+a317);
  a317=(a158*a147);
  a229=(a069*a341);
  a317=(a317+a229);
  a229=(a134*a317);
  a306=(a194*a315);
  a303=(a018*a303);
  a272=(a238*a272);
  a303=(a303+a272);
  a272=(a142*a303);
  a306=(a306+a272);
  a272=(a134*a306);
  a229=(a229+a272);
  a272=(a115*a229);
  a358=(a358-a272);
  a272=(a194*a109);
  a062=(a148*a303);
  a272=(a272+a062);
  a062=(a056*a272);
  a358=(a358+a062);
  a062=(a185*a109);
  a292=(a148*a292);
  a062=(a062+a292);
  a292=(a134*a062);
  a052=(a194*a147);
  a303=(a069*a303);
  a052=(a052+a303);
  a303=(a134*a052);
  a318=(a292+a303);
  a318=(a244*a318);
  a358=(a358+a318);
  a318=(a158*a315);
  a341=(a142*a341);
  a318=(a318+a341);
  a341=(a119*a318);
  a349=(a160*a067);
  a341=(a341-a349);
  a349=(a141*a317);
  a341=(a341-a349);
  a349=(a160*a230);
  a341=(a341-a349);
  a062=(a121*a062);
  a341=(a341+a062);
  a062=(a149*a312);
  a341=(a341-a062);
  a062=(a141*a306);
  a341=(a341-a062);
  a062=(a149*a272);
  a341=(a341-a062);
  a052=(a118*a052);
  a341=(a341+a052);
  a052=(a250*a341);
  a052=(a049*a052);
  a062=(a125*a052);
  a341=(a341/a123);
  a062=(a062-a341);
  a349=(a131*a062);
  a290=(a045*a349);
  a182=(a129*a062);
  a302=(a126*a182);
  a302=(a042*a302);
  a290=(a290+a302);
  a302=(a039*a182);
  a290=(a290+a302);
  a302=(a126*a062);
  a302=(a036*a302);
  a290=(a290+a302);
  a302=(a033*a062);
  a290=(a290+a302);
  a302=(a131*a341);
  a359=(a029*a302);
  a290=(a290+a359);
  a359=(a129*a341);
  a305=(a126*a359);
  a305=(a025*a305);
  a290=(a290+a305);
  a305=(a022*a359);
  a290=(a290+a305);
  a052=(a132*a052);
  a349=(a047*a349);
  a305=(a130*a062);
  a305=(a263*a305);
  a346=(a127*a062);
  a305=(a305+a346);
  a305=(a262*a305);
  a349=(a349+a305);
  a182=(a128*a182);
  a349=(a349+a182);
  a062=(a124*a062);
  a349=(a349+a062);
  a349=(a122*a349);
  a052=(a052+a349);
  a302=(a031*a302);
  a349=(a138*a341);
  a349=(a263*a349);
  a062=(a136*a341);
  a349=(a349+a062);
  a349=(a262*a349);
  a302=(a302+a349);
  a359=(a137*a359);
  a302=(a302+a359);
  a359=(a135*a341);
  a302=(a302+a359);
  a302=(a122*a302);
  a052=(a052+a302);
  a052=(a018*a052);
  a290=(a290+a052);
  a052=(a126*a341);
  a052=(a016*a052);
  a290=(a290+a052);
  a341=(a001*a341);
  a290=(a290+a341);
  a341=(a244*a290);
  a358=(a358+a341);
  a341=(a153*a358);
  a147=(a200*a147);
  a147=(a083*a147);
  a341=(a341-a147);
  a317=(a056*a317);
  a310=(a310+a317);
  a364=(a120*a364);
  a310=(a310-a364);
  a306=(a085*a306);
  a310=(a310+a306);
  a312=(a134*a312);
  a272=(a134*a272);
  a312=(a312+a272);
  a272=(a115*a312);
  a310=(a310-a272);
  a318=(a134*a318);
  a303=(a318+a303);
  a303=(a268*a303);
  a310=(a310+a303);
  a303=(a268*a290);
  a310=(a310+a303);
  a303=(a156*a310);
  a341=(a341+a303);
  a067=(a085*a067);
  a094=(a094+a067);
  a230=(a056*a230);
  a094=(a094+a230);
  a318=(a318+a292);
  a318=(a270*a318);
  a094=(a094+a318);
  a229=(a120*a229);
  a094=(a094-a229);
  a312=(a117*a312);
  a094=(a094-a312);
  a290=(a270*a290);
  a094=(a094+a290);
  a290=(a157*a094);
  a341=(a341+a290);
  a341=(a341/a002);
  if (res[1]!=0) res[1][21]=a341;
  a341=(a166*a358);
  a109=(a200*a109);
  a109=(a083*a109);
  a341=(a341-a109);
  a109=(a167*a310);
  a341=(a341+a109);
  a312=(a169*a094);
  a341=(a341+a312);
  a341=(a341/a002);
  if (res[1]!=0) res[1][22]=a341;
  a341=(a171*a358);
  a315=(a200*a315);
  a315=(a083*a315);
  a315=(a341-a315);
  a312=(a173*a310);
  a315=(a315+a312);
  a312=(a175*a094);
  a315=(a315+a312);
  a315=(a315/a002);
  if (res[1]!=0) res[1][23]=a315;
  a315=(2.*a277);
  a307=(a315*a307);
  a312=(a001*a307);
  a229=(a016*a307);
  a229=(a282*a229);
  a318=(a018*a307);
  a292=(a279*a318);
  a230=(a015*a292);
  a229=(a229+a230);
  a312=(a312+a229);
  a229=(a022*a307);
  a230=(a025*a307);
  a230=(a282*a230);
  a067=(a024*a292);
  a230=(a230+a067);
  a229=(a229+a230);
  a229=(a283*a229);
  a230=(a336*a292);
  a067=(a021*a230);
  a229=(a229+a067);
  a312=(a312+a229);
  a229=(a029*a307);
  a067=(a031*a292);
  a229=(a229+a067);
  a229=(a284*a229);
  a067=(a332*a230);
  a303=(a028*a067);
  a229=(a229+a303);
  a312=(a312+a229);
  a229=(a033*a307);
  a303=(a036*a307);
  a303=(a282*a303);
  a272=(a035*a292);
  a303=(a303+a272);
  a229=(a229+a303);
  a303=(a039*a307);
  a272=(a042*a307);
  a272=(a282*a272);
  a306=(a041*a292);
  a272=(a272+a306);
  a303=(a303+a272);
  a303=(a283*a303);
  a230=(a038*a230);
  a303=(a303+a230);
  a229=(a229+a303);
  a303=(a045*a307);
  a292=(a047*a292);
  a303=(a303+a292);
  a303=(a284*a303);
  a067=(a044*a067);
  a303=(a303+a067);
  a229=(a229+a303);
  a312=(a312-a229);
  a312=(a312/a285);
  a318=(a051*a318);
  a229=(a281*a229);
  a318=(a318+a229);
  a318=(a049*a318);
  a318=(a297*a318);
  a312=(a312+a318);
  a318=(a280*a312);
  a318=(a318+a271);
  a271=(a081*a318);
  a229=(a289*a312);
  a303=(a340+a229);
  a303=(a088*a303);
  a271=(a271+a303);
  a303=(a275*a312);
  a307=(a000*a307);
  a303=(a303+a307);
  a303=(a091*a303);
  a271=(a271-a303);
  a303=(a152*a358);
  a271=(a271+a303);
  a303=(a155*a310);
  a271=(a271+a303);
  a271=(a271+a290);
  a290=(a057*a077);
  a055=(a055+a290);
  a271=(a271+a055);
  a055=(a329+a295);
  a222=(a222*a055);
  a055=(a086*a316);
  a222=(a222+a055);
  a271=(a271+a222);
  a271=(a271+a324);
  a271=(-a271);
  if (res[1]!=0) res[1][24]=a271;
  a271=(a191*a312);
  a271=(a271+a333);
  a333=(a081*a271);
  a324=(a278*a312);
  a324=(a324+a307);
  a324=(a088*a324);
  a333=(a333-a324);
  a229=(a076+a229);
  a229=(a091*a229);
  a333=(a333+a229);
  a358=(a165*a358);
  a333=(a333+a358);
  a333=(a333+a109);
  a109=(a168*a094);
  a333=(a333+a109);
  a077=(a101*a077);
  a211=(a211+a077);
  a333=(a333+a211);
  a333=(a333+a014);
  a295=(a083+a295);
  a225=(a225*a295);
  a295=(a105*a202);
  a225=(a225+a295);
  a333=(a333+a225);
  a333=(-a333);
  if (res[1]!=0) res[1][25]=a333;
  a271=(a088*a271);
  a312=(a276*a312);
  a312=(a081*a312);
  a271=(a271-a312);
  a318=(a091*a318);
  a271=(a271+a318);
  a271=(a271+a341);
  a310=(a172*a310);
  a271=(a271+a310);
  a094=(a174*a094);
  a271=(a271+a094);
  a271=(a271+a311);
  a316=(a110*a316);
  a060=(a060+a316);
  a271=(a271+a060);
  a202=(a112*a202);
  a224=(a224+a202);
  a271=(a271+a224);
  a271=(-a271);
  if (res[1]!=0) res[1][26]=a271;
  a271=9.2820323027550877e-01;
  a224=(a271*a065);
  a224=(a080*a224);
  a224=(a224/a083);
  a202=(a064*a224);
  a060=(a271*a073);
  a060=(a099*a060);
  a060=(a060/a083);
  a316=(a097*a060);
  a202=(a202+a316);
  a316=(a271*a063);
  a316=(a107*a316);
  a316=(a316/a083);
  a311=(a103*a316);
  a202=(a202+a311);
  a311=(a059*a202);
  a094=(a270*a002);
  a310=(a033*a094);
  a341=(a036*a094);
  a318=(a126*a341);
  a312=(a018*a094);
  a333=(a122*a312);
  a225=(a124*a333);
  a318=(a318+a225);
  a310=(a310+a318);
  a318=(a039*a094);
  a225=(a042*a094);
  a295=(a126*a225);
  a014=(a128*a333);
  a295=(a295+a014);
  a318=(a318+a295);
  a295=(a129*a318);
  a014=(a262*a333);
  a211=(a127*a014);
  a295=(a295+a211);
  a310=(a310+a295);
  a295=(a045*a094);
  a211=(a047*a333);
  a295=(a295+a211);
  a211=(a131*a295);
  a077=(a263*a014);
  a109=(a130*a077);
  a211=(a211+a109);
  a310=(a310+a211);
  a211=(a001*a094);
  a109=(a016*a094);
  a358=(a126*a109);
  a229=(a135*a333);
  a358=(a358+a229);
  a211=(a211+a358);
  a358=(a022*a094);
  a229=(a025*a094);
  a324=(a126*a229);
  a307=(a137*a333);
  a324=(a324+a307);
  a358=(a358+a324);
  a324=(a129*a358);
  a307=(a136*a014);
  a324=(a324+a307);
  a211=(a211+a324);
  a324=(a029*a094);
  a307=(a031*a333);
  a324=(a324+a307);
  a307=(a131*a324);
  a222=(a138*a077);
  a307=(a307+a222);
  a211=(a211+a307);
  a307=(a133*a211);
  a222=(a132*a312);
  a055=(a125*a310);
  a222=(a222+a055);
  a055=(a139*a222);
  a307=(a307-a055);
  a307=(a310+a307);
  a307=(a018*a307);
  a055=(a141*a307);
  a290=(a120*a002);
  a303=(a140*a290);
  a055=(a055+a303);
  a067=(2.*a133);
  a292=(a067*a222);
  a292=(a056*a292);
  a230=(a117*a292);
  a272=(a055+a230);
  a306=(a078*a272);
  a364=(a066*a146);
  a317=(a118*a307);
  a147=(a003*a317);
  a364=(a364-a147);
  a147=(a149*a307);
  a052=(a117*a002);
  a302=(a140*a052);
  a147=(a147+a302);
  a359=(a120*a292);
  a349=(a147-a359);
  a062=(a006*a349);
  a364=(a364+a062);
  a272=(a010*a272);
  a364=(a364+a272);
  a272=(2.*a364);
  a272=(a080*a272);
  a062=(a211-a310);
  a062=(a062/a123);
  a182=(a049*a222);
  a305=(a250*a182);
  a062=(a062+a305);
  a305=(a141*a062);
  a346=(a134*a290);
  a305=(a305+a346);
  a325=(a082*a305);
  a272=(a272-a325);
  a325=(a149*a062);
  a188=(a134*a052);
  a325=(a325+a188);
  a190=(a089*a325);
  a272=(a272-a190);
  a190=(a118*a062);
  a330=(a092*a190);
  a272=(a272+a330);
  a272=(a272/a083);
  a330=(a145*a272);
  a306=(a306+a330);
  a330=(a143*a002);
  a363=(a115*a292);
  a363=(a330-a363);
  a205=(a160*a307);
  a075=(a363+a205);
  a360=(a163*a075);
  a147=(a147+a359);
  a359=(a003*a147);
  a339=(a066*a150);
  a359=(a359+a339);
  a339=(a121*a307);
  a337=(a140*a094);
  a339=(a339+a337);
  a361=(a006*a339);
  a359=(a359-a361);
  a075=(a010*a075);
  a359=(a359+a075);
  a075=(2.*a359);
  a075=(a099*a075);
  a361=(a160*a062);
  a343=(a361-a329);
  a197=(a082*a343);
  a075=(a075-a197);
  a197=(a121*a062);
  a362=(a134*a094);
  a197=(a197+a362);
  a356=(a089*a197);
  a075=(a075+a356);
  a356=(a092*a325);
  a075=(a075-a356);
  a075=(a075/a083);
  a356=(a162*a075);
  a360=(a360+a356);
  a306=(a306+a360);
  a055=(a055-a230);
  a230=(a003*a055);
  a360=(a066*a144);
  a230=(a230+a360);
  a205=(a205-a363);
  a363=(a006*a205);
  a230=(a230+a363);
  a307=(a119*a307);
  a307=(a307+a337);
  a337=(a010*a307);
  a230=(a230-a337);
  a337=(2.*a230);
  a337=(a107*a337);
  a363=(a119*a062);
  a363=(a363+a362);
  a362=(a082*a363);
  a337=(a337+a362);
  a362=(a361-a083);
  a360=(a089*a362);
  a337=(a337-a360);
  a360=(a092*a305);
  a337=(a337-a360);
  a337=(a337/a083);
  a360=(a170*a337);
  a307=(a159*a307);
  a360=(a360-a307);
  a306=(a306+a360);
  a360=(a114*a306);
  a311=(a311+a360);
  a360=(a068*a073);
  a307=(a178*a360);
  a202=(a177*a202);
  a306=(a059*a306);
  a202=(a202+a306);
  a306=(a002*a202);
  a356=(a176*a306);
  a348=(a002*a311);
  a181=(a018*a348);
  a356=(a356+a181);
  a181=(a071*a356);
  a307=(a307+a181);
  a181=(a048*a307);
  a320=(a068*a063);
  a296=(a186*a320);
  a357=(a074*a224);
  a209=(a005*a060);
  a357=(a357+a209);
  a209=(a096*a316);
  a357=(a357+a209);
  a209=(a177*a357);
  a349=(a078*a349);
  a299=(a151*a272);
  a349=(a349+a299);
  a299=(a116*a075);
  a339=(a163*a339);
  a299=(a299-a339);
  a349=(a349+a299);
  a205=(a159*a205);
  a299=(a161*a337);
  a205=(a205+a299);
  a349=(a349+a205);
  a205=(a059*a349);
  a209=(a209+a205);
  a205=(a002*a209);
  a299=(a176*a205);
  a357=(a059*a357);
  a349=(a114*a349);
  a357=(a357+a349);
  a349=(a002*a357);
  a339=(a018*a349);
  a299=(a299+a339);
  a339=(a061*a299);
  a296=(a296+a339);
  a339=(a048*a296);
  a181=(a181+a339);
  a339=(a007*a181);
  a311=(a311-a339);
  a339=(a068*a065);
  a207=(a186*a339);
  a213=(a070*a299);
  a207=(a207+a213);
  a213=(a085*a207);
  a311=(a311+a213);
  a213=(a178*a339);
  a298=(a070*a356);
  a213=(a213+a298);
  a298=(a048*a213);
  a294=(a195*a320);
  a224=(a065*a224);
  a060=(a073*a060);
  a224=(a224+a060);
  a316=(a063*a316);
  a224=(a224+a316);
  a316=(a177*a224);
  a272=(a146*a272);
  a317=(a078*a317);
  a272=(a272-a317);
  a147=(a163*a147);
  a075=(a150*a075);
  a147=(a147+a075);
  a272=(a272+a147);
  a055=(a159*a055);
  a337=(a144*a337);
  a055=(a055+a337);
  a272=(a272+a055);
  a055=(a059*a272);
  a316=(a316+a055);
  a055=(a002*a316);
  a337=(a176*a055);
  a224=(a059*a224);
  a272=(a114*a272);
  a224=(a224+a272);
  a272=(a002*a224);
  a147=(a018*a272);
  a337=(a337+a147);
  a147=(a061*a337);
  a294=(a294+a147);
  a147=(a048*a294);
  a298=(a298+a147);
  a147=(a004*a298);
  a311=(a311-a147);
  a147=(a195*a360);
  a075=(a071*a337);
  a147=(a147+a075);
  a075=(a056*a147);
  a311=(a311+a075);
  a075=(a186*a360);
  a299=(a071*a299);
  a075=(a075+a299);
  a299=(a048*a075);
  a317=(a195*a339);
  a337=(a070*a337);
  a317=(a317+a337);
  a337=(a048*a317);
  a060=(a299+a337);
  a060=(a198*a060);
  a311=(a311+a060);
  a060=(a178*a320);
  a356=(a061*a356);
  a060=(a060+a356);
  a356=(a009*a060);
  a214=(a095*a307);
  a356=(a356-a214);
  a214=(a054*a213);
  a356=(a356-a214);
  a214=(a095*a296);
  a356=(a356-a214);
  a075=(a012*a075);
  a356=(a356+a075);
  a075=(a072*a207);
  a356=(a356-a075);
  a075=(a054*a294);
  a356=(a356-a075);
  a075=(a072*a147);
  a356=(a356-a075);
  a317=(a008*a317);
  a356=(a356+a317);
  a317=(a204*a356);
  a317=(a049*a317);
  a075=(a019*a317);
  a356=(a356/a053);
  a075=(a075-a356);
  a214=(a032*a075);
  a098=(a045*a214);
  a345=(a027*a075);
  a221=(a020*a345);
  a221=(a042*a221);
  a098=(a098+a221);
  a221=(a039*a345);
  a098=(a098+a221);
  a221=(a020*a075);
  a221=(a036*a221);
  a098=(a098+a221);
  a221=(a033*a075);
  a098=(a098+a221);
  a221=(a032*a356);
  a220=(a029*a221);
  a098=(a098+a220);
  a220=(a027*a356);
  a100=(a020*a220);
  a100=(a025*a100);
  a098=(a098+a100);
  a100=(a022*a220);
  a098=(a098+a100);
  a317=(a034*a317);
  a214=(a047*a214);
  a100=(a046*a075);
  a100=(a217*a100);
  a309=(a040*a075);
  a100=(a100+a309);
  a100=(a216*a100);
  a214=(a214+a100);
  a345=(a043*a345);
  a214=(a214+a345);
  a075=(a037*a075);
  a214=(a214+a075);
  a214=(a013*a214);
  a317=(a317+a214);
  a221=(a031*a221);
  a214=(a030*a356);
  a214=(a217*a214);
  a075=(a023*a356);
  a214=(a214+a075);
  a214=(a216*a214);
  a221=(a221+a214);
  a220=(a026*a220);
  a221=(a221+a220);
  a220=(a017*a356);
  a221=(a221+a220);
  a221=(a013*a221);
  a317=(a317+a221);
  a317=(a018*a317);
  a098=(a098+a317);
  a317=(a020*a356);
  a317=(a016*a317);
  a098=(a098+a317);
  a356=(a001*a356);
  a098=(a098+a356);
  a356=(a198*a098);
  a311=(a311+a356);
  a356=(a058*a311);
  a213=(a056*a213);
  a213=(a213+a357);
  a181=(a011*a181);
  a213=(a213-a181);
  a294=(a085*a294);
  a213=(a213+a294);
  a207=(a048*a207);
  a147=(a048*a147);
  a207=(a207+a147);
  a147=(a004*a207);
  a213=(a213-a147);
  a060=(a048*a060);
  a337=(a060+a337);
  a337=(a223*a337);
  a213=(a213+a337);
  a337=(a223*a098);
  a213=(a213+a337);
  a337=(a087*a213);
  a356=(a356+a337);
  a307=(a085*a307);
  a296=(a056*a296);
  a307=(a307+a296);
  a060=(a060+a299);
  a060=(a226*a060);
  a307=(a307+a060);
  a307=(a307+a224);
  a298=(a011*a298);
  a307=(a307-a298);
  a207=(a007*a207);
  a307=(a307-a207);
  a098=(a226*a098);
  a307=(a307+a098);
  a098=(a090*a307);
  a356=(a356+a098);
  a339=(a200*a339);
  a339=(a083*a339);
  a356=(a356-a339);
  a356=(a356/a002);
  if (res[1]!=0) res[1][27]=a356;
  a356=(a102*a311);
  a339=(a104*a213);
  a356=(a356+a339);
  a207=(a106*a307);
  a356=(a356+a207);
  a360=(a200*a360);
  a360=(a083*a360);
  a356=(a356-a360);
  a356=(a356/a002);
  if (res[1]!=0) res[1][28]=a356;
  a356=(a108*a311);
  a360=(a111*a213);
  a360=(a356+a360);
  a207=(a113*a307);
  a360=(a360+a207);
  a320=(a200*a320);
  a320=(a083*a320);
  a360=(a360-a320);
  a360=(a360/a002);
  if (res[1]!=0) res[1][29]=a360;
  a360=(a143*a052);
  a320=(a149*a292);
  a320=(a360-a320);
  a222=(a231*a222);
  a207=(a139*a312);
  a211=(a125*a211);
  a207=(a207+a211);
  a207=(a133*a207);
  a222=(a222+a207);
  a207=(a120*a222);
  a211=(a320+a207);
  a211=(a227*a211);
  a298=(a143*a094);
  a224=(a121*a292);
  a298=(a298-a224);
  a298=(a233*a298);
  a211=(a211-a298);
  a228=(a228*a002);
  a298=(a115*a222);
  a298=(a228-a298);
  a224=(a160*a292);
  a298=(a298-a224);
  a298=(a234*a298);
  a211=(a211+a298);
  a211=(a083*a211);
  a298=(a200*a364);
  a298=(a083*a298);
  a211=(a211-a298);
  a298=(a093*a305);
  a224=(a179*a062);
  a060=(a158*a359);
  a306=(a018*a306);
  a348=(a238*a348);
  a306=(a306+a348);
  a348=(a148*a306);
  a060=(a060+a348);
  a348=(a134*a060);
  a224=(a224+a348);
  a348=(a184*a062);
  a299=(a185*a230);
  a205=(a018*a205);
  a349=(a238*a349);
  a205=(a205+a349);
  a349=(a142*a205);
  a299=(a299+a349);
  a349=(a134*a299);
  a348=(a348+a349);
  a224=(a224+a348);
  a348=(a117*a224);
  a202=(a202-a348);
  a348=(a185*a364);
  a349=(a069*a205);
  a348=(a348+a349);
  a349=(a085*a348);
  a202=(a202+a349);
  a242=(a242*a002);
  a349=(a241*a062);
  a296=(a158*a364);
  a337=(a069*a306);
  a296=(a296+a337);
  a337=(a134*a296);
  a349=(a349+a337);
  a337=(a193*a062);
  a147=(a194*a230);
  a055=(a018*a055);
  a272=(a238*a272);
  a055=(a055+a272);
  a272=(a142*a055);
  a147=(a147+a272);
  a272=(a134*a147);
  a337=(a337+a272);
  a349=(a349+a337);
  a337=(a115*a349);
  a337=(a242+a337);
  a202=(a202-a337);
  a337=(a194*a359);
  a272=(a148*a055);
  a337=(a337+a272);
  a272=(a056*a337);
  a202=(a202+a272);
  a272=(a245*a062);
  a294=(a185*a359);
  a205=(a148*a205);
  a294=(a294+a205);
  a205=(a134*a294);
  a272=(a272+a205);
  a205=(a247*a062);
  a364=(a194*a364);
  a055=(a069*a055);
  a364=(a364+a055);
  a055=(a134*a364);
  a205=(a205+a055);
  a055=(a272+a205);
  a055=(a244*a055);
  a202=(a202+a055);
  a055=(a254*a077);
  a312=(a253*a312);
  a181=(a062/a123);
  a357=(a250/a123);
  a317=(a357*a182);
  a181=(a181+a317);
  a181=(a252*a181);
  a317=(a251*a094);
  a221=(a158*a230);
  a306=(a142*a306);
  a221=(a221+a306);
  a306=(a119*a221);
  a317=(a317+a306);
  a306=(a160*a060);
  a317=(a317-a306);
  a306=(a241*a290);
  a220=(a141*a296);
  a306=(a306+a220);
  a317=(a317-a306);
  a306=(a160*a299);
  a317=(a317-a306);
  a306=(a245*a094);
  a294=(a121*a294);
  a306=(a306+a294);
  a317=(a317+a306);
  a306=(a240*a052);
  a294=(a149*a348);
  a306=(a306+a294);
  a317=(a317-a306);
  a306=(a193*a290);
  a294=(a141*a147);
  a306=(a306+a294);
  a317=(a317-a306);
  a306=(a243*a052);
  a294=(a149*a337);
  a306=(a306+a294);
  a317=(a317-a306);
  a364=(a118*a364);
  a317=(a317+a364);
  a364=(a250*a317);
  a181=(a181+a364);
  a181=(a049*a181);
  a364=(a125*a181);
  a312=(a312+a364);
  a317=(a317/a123);
  a364=(a255/a123);
  a182=(a364*a182);
  a317=(a317+a182);
  a312=(a312-a317);
  a182=(a131*a312);
  a055=(a055+a182);
  a182=(a045*a055);
  a306=(a258*a333);
  a294=(a254*a014);
  a220=(a129*a312);
  a294=(a294+a220);
  a220=(a126*a294);
  a306=(a306+a220);
  a306=(a042*a306);
  a182=(a182+a306);
  a306=(a039*a294);
  a182=(a182+a306);
  a306=(a254*a333);
  a220=(a126*a312);
  a306=(a306+a220);
  a306=(a036*a306);
  a182=(a182+a306);
  a306=(a033*a312);
  a182=(a182+a306);
  a077=(a255*a077);
  a306=(a131*a317);
  a077=(a077+a306);
  a306=(a029*a077);
  a182=(a182+a306);
  a306=(a260*a333);
  a220=(a255*a014);
  a214=(a129*a317);
  a220=(a220+a214);
  a214=(a126*a220);
  a306=(a306+a214);
  a306=(a025*a306);
  a182=(a182+a306);
  a306=(a022*a220);
  a182=(a182+a306);
  a310=(a253*a310);
  a181=(a132*a181);
  a310=(a310+a181);
  a094=(a056*a094);
  a181=(a256*a094);
  a055=(a047*a055);
  a306=(2.*a333);
  a214=(a265*a306);
  a014=(2.*a014);
  a075=(a264*a014);
  a295=(a254*a295);
  a345=(a130*a312);
  a295=(a295+a345);
  a295=(a263*a295);
  a075=(a075+a295);
  a318=(a254*a318);
  a295=(a127*a312);
  a318=(a318+a295);
  a075=(a075+a318);
  a075=(a262*a075);
  a214=(a214+a075);
  a055=(a055+a214);
  a225=(a258*a225);
  a294=(a128*a294);
  a225=(a225+a294);
  a055=(a055+a225);
  a341=(a254*a341);
  a312=(a124*a312);
  a341=(a341+a312);
  a055=(a055+a341);
  a055=(a122*a055);
  a181=(a181+a055);
  a310=(a310+a181);
  a094=(a259*a094);
  a077=(a031*a077);
  a306=(a267*a306);
  a014=(a266*a014);
  a324=(a255*a324);
  a181=(a138*a317);
  a324=(a324+a181);
  a324=(a263*a324);
  a014=(a014+a324);
  a358=(a255*a358);
  a324=(a136*a317);
  a358=(a358+a324);
  a014=(a014+a358);
  a014=(a262*a014);
  a306=(a306+a014);
  a077=(a077+a306);
  a229=(a260*a229);
  a220=(a137*a220);
  a229=(a229+a220);
  a077=(a077+a229);
  a109=(a255*a109);
  a229=(a135*a317);
  a109=(a109+a229);
  a077=(a077+a109);
  a077=(a122*a077);
  a094=(a094+a077);
  a310=(a310+a094);
  a310=(a018*a310);
  a182=(a182+a310);
  a333=(a255*a333);
  a310=(a126*a317);
  a333=(a333+a310);
  a333=(a016*a333);
  a182=(a182+a333);
  a317=(a001*a317);
  a182=(a182+a317);
  a317=(a244*a182);
  a202=(a202+a317);
  a317=(a153*a202);
  a317=(a298+a317);
  a211=(a211+a317);
  a317=(a183*a325);
  a296=(a056*a296);
  a209=(a209+a296);
  a224=(a120*a224);
  a209=(a209-a224);
  a147=(a085*a147);
  a209=(a209+a147);
  a261=(a261*a002);
  a147=(a240*a062);
  a348=(a134*a348);
  a147=(a147+a348);
  a348=(a243*a062);
  a337=(a134*a337);
  a348=(a348+a337);
  a147=(a147+a348);
  a348=(a115*a147);
  a348=(a261+a348);
  a209=(a209-a348);
  a062=(a251*a062);
  a221=(a134*a221);
  a062=(a062+a221);
  a205=(a062+a205);
  a205=(a268*a205);
  a209=(a209+a205);
  a205=(a268*a182);
  a209=(a209+a205);
  a205=(a156*a209);
  a205=(a317+a205);
  a211=(a211+a205);
  a060=(a085*a060);
  a316=(a316+a060);
  a299=(a056*a299);
  a316=(a316+a299);
  a269=(a269*a342);
  a062=(a062+a272);
  a062=(a270*a062);
  a269=(a269+a062);
  a316=(a316+a269);
  a349=(a120*a349);
  a316=(a316-a349);
  a147=(a117*a147);
  a316=(a316-a147);
  a257=(a257*a342);
  a182=(a270*a182);
  a182=(a257+a182);
  a316=(a316+a182);
  a182=(a157*a316);
  a190=(a192*a190);
  a182=(a182-a190);
  a211=(a211+a182);
  a211=(a211/a002);
  if (res[1]!=0) res[1][30]=a211;
  a343=(a093*a343);
  a211=(a166*a202);
  a343=(a343+a211);
  a359=(a200*a359);
  a359=(a083*a359);
  a211=(a118*a292);
  a211=(a227*a211);
  a320=(a320-a207);
  a320=(a233*a320);
  a211=(a211+a320);
  a320=(a143*a290);
  a292=(a141*a292);
  a292=(a320-a292);
  a222=(a117*a222);
  a292=(a292+a222);
  a292=(a234*a292);
  a211=(a211+a292);
  a211=(a083*a211);
  a359=(a359+a211);
  a343=(a343-a359);
  a359=(a167*a209);
  a197=(a183*a197);
  a359=(a359-a197);
  a343=(a343+a359);
  a325=(a192*a325);
  a197=(a169*a316);
  a197=(a325+a197);
  a343=(a343+a197);
  a343=(a343/a002);
  if (res[1]!=0) res[1][31]=a343;
  a343=(a171*a202);
  a363=(a093*a363);
  a343=(a343-a363);
  a230=(a200*a230);
  a230=(a083*a230);
  a230=(a343-a230);
  a362=(a183*a362);
  a363=(a173*a209);
  a362=(a362+a363);
  a230=(a230+a362);
  a305=(a192*a305);
  a362=(a175*a316);
  a362=(a305+a362);
  a230=(a230+a362);
  a230=(a230/a002);
  if (res[1]!=0) res[1][32]=a230;
  a230=1.7320508075688774e+00;
  a230=(a230*a002);
  a331=(a331*a230);
  a362=(a001*a331);
  a363=(a016*a331);
  a363=(a282*a363);
  a197=(a018*a331);
  a211=(a279*a197);
  a292=(a015*a211);
  a363=(a363+a292);
  a362=(a362+a363);
  a363=(a022*a331);
  a292=(a025*a331);
  a292=(a282*a292);
  a222=(a024*a211);
  a292=(a292+a222);
  a363=(a363+a292);
  a363=(a283*a363);
  a292=(a336*a211);
  a222=(a021*a292);
  a363=(a363+a222);
  a362=(a362+a363);
  a363=(a029*a331);
  a222=(a031*a211);
  a363=(a363+a222);
  a363=(a284*a363);
  a222=(a332*a292);
  a207=(a028*a222);
  a363=(a363+a207);
  a362=(a362+a363);
  a363=(a033*a331);
  a207=(a036*a331);
  a207=(a282*a207);
  a190=(a035*a211);
  a207=(a207+a190);
  a363=(a363+a207);
  a207=(a039*a331);
  a190=(a042*a331);
  a190=(a282*a190);
  a147=(a041*a211);
  a190=(a190+a147);
  a207=(a207+a190);
  a207=(a283*a207);
  a292=(a038*a292);
  a207=(a207+a292);
  a363=(a363+a207);
  a207=(a045*a331);
  a211=(a047*a211);
  a207=(a207+a211);
  a207=(a284*a207);
  a222=(a044*a222);
  a207=(a207+a222);
  a363=(a363+a207);
  a362=(a362-a363);
  a362=(a362/a285);
  a197=(a051*a197);
  a363=(a281*a363);
  a197=(a197+a363);
  a197=(a049*a197);
  a197=(a297*a197);
  a362=(a362+a197);
  a197=(a280*a362);
  a277=(a277*a230);
  a277=(a000*a277);
  a197=(a197+a277);
  a363=(a081*a197);
  a207=(a289*a362);
  a236=(a236*a230);
  a236=(a000*a236);
  a207=(a207+a236);
  a222=(a088*a207);
  a363=(a363+a222);
  a222=(a275*a362);
  a222=(a091*a222);
  a363=(a363-a222);
  a222=(a152*a202);
  a298=(a298+a222);
  a363=(a363+a298);
  a298=(a155*a209);
  a317=(a317+a298);
  a363=(a363+a317);
  a363=(a363+a182);
  a182=(a057*a311);
  a363=(a363+a182);
  a182=(a086*a213);
  a363=(a363+a182);
  a363=(a363+a098);
  a363=(-a363);
  if (res[1]!=0) res[1][33]=a363;
  a363=(a191*a362);
  a098=(a076+a363);
  a098=(a081*a098);
  a182=(a278*a362);
  a331=(a000*a331);
  a182=(a182+a331);
  a182=(a088*a182);
  a098=(a098-a182);
  a207=(a091*a207);
  a098=(a098+a207);
  a207=(a329+a361);
  a207=(a093*a207);
  a202=(a165*a202);
  a207=(a207+a202);
  a098=(a098+a207);
  a098=(a098+a359);
  a359=(a168*a316);
  a325=(a325+a359);
  a098=(a098+a325);
  a311=(a101*a311);
  a098=(a098+a311);
  a098=(a098+a339);
  a339=(a105*a307);
  a098=(a098+a339);
  a098=(-a098);
  if (res[1]!=0) res[1][34]=a098;
  a363=(a340+a363);
  a363=(a088*a363);
  a362=(a276*a362);
  a362=(a362+a331);
  a362=(a081*a362);
  a363=(a363-a362);
  a197=(a091*a197);
  a363=(a363+a197);
  a363=(a363+a343);
  a361=(a083+a361);
  a361=(a183*a361);
  a209=(a172*a209);
  a361=(a361+a209);
  a363=(a363+a361);
  a316=(a174*a316);
  a305=(a305+a316);
  a363=(a363+a305);
  a363=(a363+a356);
  a213=(a110*a213);
  a363=(a363+a213);
  a307=(a112*a307);
  a363=(a363+a307);
  a363=(-a363);
  if (res[1]!=0) res[1][35]=a363;
  a363=(a271*a074);
  a363=(a080*a363);
  a363=(a363/a083);
  a307=(a064*a363);
  a213=(a271*a005);
  a213=(a099*a213);
  a213=(a213/a083);
  a356=(a097*a213);
  a307=(a307+a356);
  a356=(a271*a096);
  a356=(a107*a356);
  a356=(a356/a083);
  a305=(a103*a356);
  a307=(a307+a305);
  a305=(a059*a307);
  a316=(a268*a002);
  a361=(a033*a316);
  a209=(a036*a316);
  a343=(a126*a209);
  a197=(a018*a316);
  a362=(a122*a197);
  a331=(a124*a362);
  a343=(a343+a331);
  a361=(a361+a343);
  a343=(a039*a316);
  a331=(a042*a316);
  a098=(a126*a331);
  a339=(a128*a362);
  a098=(a098+a339);
  a343=(a343+a098);
  a098=(a129*a343);
  a339=(a262*a362);
  a311=(a127*a339);
  a098=(a098+a311);
  a361=(a361+a098);
  a098=(a045*a316);
  a311=(a047*a362);
  a098=(a098+a311);
  a311=(a131*a098);
  a325=(a263*a339);
  a359=(a130*a325);
  a311=(a311+a359);
  a361=(a361+a311);
  a311=(a001*a316);
  a359=(a016*a316);
  a207=(a126*a359);
  a202=(a135*a362);
  a207=(a207+a202);
  a311=(a311+a207);
  a207=(a022*a316);
  a202=(a025*a316);
  a182=(a126*a202);
  a317=(a137*a362);
  a182=(a182+a317);
  a207=(a207+a182);
  a182=(a129*a207);
  a317=(a136*a339);
  a182=(a182+a317);
  a311=(a311+a182);
  a182=(a029*a316);
  a317=(a031*a362);
  a182=(a182+a317);
  a317=(a131*a182);
  a298=(a138*a325);
  a317=(a317+a298);
  a311=(a311+a317);
  a317=(a133*a311);
  a298=(a132*a197);
  a222=(a125*a361);
  a298=(a298+a222);
  a222=(a139*a298);
  a317=(a317-a222);
  a317=(a361+a317);
  a317=(a018*a317);
  a222=(a141*a317);
  a211=(a067*a298);
  a211=(a056*a211);
  a292=(a117*a211);
  a292=(a330-a292);
  a190=(a222-a292);
  a147=(a078*a190);
  a349=(a149*a317);
  a269=(a115*a002);
  a062=(a140*a269);
  a349=(a349+a062);
  a272=(a120*a211);
  a299=(a349-a272);
  a060=(a006*a299);
  a205=(a066*a151);
  a060=(a060+a205);
  a205=(a118*a317);
  a221=(a140*a316);
  a205=(a205+a221);
  a348=(a003*a205);
  a060=(a060-a348);
  a190=(a010*a190);
  a060=(a060+a190);
  a190=(2.*a060);
  a190=(a080*a190);
  a348=(a311-a361);
  a348=(a348/a123);
  a337=(a049*a298);
  a224=(a250*a337);
  a348=(a348+a224);
  a224=(a141*a348);
  a296=(a224-a083);
  a333=(a082*a296);
  a190=(a190-a333);
  a333=(a149*a348);
  a310=(a134*a269);
  a333=(a333+a310);
  a094=(a089*a333);
  a190=(a190-a094);
  a094=(a118*a348);
  a077=(a134*a316);
  a094=(a094+a077);
  a109=(a092*a094);
  a190=(a190+a109);
  a190=(a190/a083);
  a109=(a145*a190);
  a147=(a147+a109);
  a109=(a160*a317);
  a109=(a109+a303);
  a303=(a115*a211);
  a229=(a109-a303);
  a220=(a163*a229);
  a349=(a349+a272);
  a272=(a003*a349);
  a306=(a066*a116);
  a014=(a121*a317);
  a358=(a006*a014);
  a306=(a306-a358);
  a272=(a272+a306);
  a229=(a010*a229);
  a272=(a272+a229);
  a229=(2.*a272);
  a229=(a099*a229);
  a306=(a160*a348);
  a306=(a306+a346);
  a346=(a082*a306);
  a229=(a229-a346);
  a346=(a121*a348);
  a358=(a089*a346);
  a229=(a229+a358);
  a358=(a092*a333);
  a229=(a229-a358);
  a229=(a229/a083);
  a358=(a162*a229);
  a220=(a220+a358);
  a147=(a147+a220);
  a292=(a292+a222);
  a222=(a003*a292);
  a109=(a109+a303);
  a303=(a006*a109);
  a220=(a066*a161);
  a303=(a303+a220);
  a222=(a222+a303);
  a317=(a119*a317);
  a317=(a317+a221);
  a221=(a010*a317);
  a222=(a222-a221);
  a221=(2.*a222);
  a221=(a107*a221);
  a303=(a119*a348);
  a303=(a303+a077);
  a077=(a082*a303);
  a221=(a221+a077);
  a077=(a089*a306);
  a221=(a221-a077);
  a077=(a224-a329);
  a220=(a092*a077);
  a221=(a221-a220);
  a221=(a221/a083);
  a220=(a170*a221);
  a317=(a159*a317);
  a220=(a220-a317);
  a147=(a147+a220);
  a220=(a114*a147);
  a305=(a305+a220);
  a220=(a068*a005);
  a317=(a178*a220);
  a307=(a177*a307);
  a147=(a059*a147);
  a307=(a307+a147);
  a147=(a002*a307);
  a358=(a176*a147);
  a324=(a002*a305);
  a181=(a018*a324);
  a358=(a358+a181);
  a181=(a071*a358);
  a317=(a317+a181);
  a181=(a048*a317);
  a055=(a068*a096);
  a341=(a186*a055);
  a312=(a074*a363);
  a225=(a005*a213);
  a312=(a312+a225);
  a225=(a096*a356);
  a312=(a312+a225);
  a225=(a177*a312);
  a299=(a078*a299);
  a294=(a151*a190);
  a299=(a299+a294);
  a294=(a116*a229);
  a014=(a163*a014);
  a294=(a294-a014);
  a299=(a299+a294);
  a109=(a159*a109);
  a294=(a161*a221);
  a109=(a109+a294);
  a299=(a299+a109);
  a109=(a059*a299);
  a225=(a225+a109);
  a109=(a002*a225);
  a294=(a176*a109);
  a312=(a059*a312);
  a299=(a114*a299);
  a312=(a312+a299);
  a299=(a002*a312);
  a014=(a018*a299);
  a294=(a294+a014);
  a014=(a061*a294);
  a341=(a341+a014);
  a014=(a048*a341);
  a181=(a181+a014);
  a014=(a007*a181);
  a305=(a305-a014);
  a014=(a068*a074);
  a214=(a186*a014);
  a075=(a070*a294);
  a214=(a214+a075);
  a075=(a085*a214);
  a305=(a305+a075);
  a075=(a178*a014);
  a318=(a070*a358);
  a075=(a075+a318);
  a318=(a048*a075);
  a295=(a195*a055);
  a363=(a065*a363);
  a213=(a073*a213);
  a363=(a363+a213);
  a356=(a063*a356);
  a363=(a363+a356);
  a356=(a177*a363);
  a190=(a146*a190);
  a205=(a078*a205);
  a190=(a190-a205);
  a349=(a163*a349);
  a229=(a150*a229);
  a349=(a349+a229);
  a190=(a190+a349);
  a292=(a159*a292);
  a221=(a144*a221);
  a292=(a292+a221);
  a190=(a190+a292);
  a292=(a059*a190);
  a356=(a356+a292);
  a292=(a002*a356);
  a221=(a176*a292);
  a363=(a059*a363);
  a190=(a114*a190);
  a363=(a363+a190);
  a190=(a002*a363);
  a349=(a018*a190);
  a221=(a221+a349);
  a349=(a061*a221);
  a295=(a295+a349);
  a349=(a048*a295);
  a318=(a318+a349);
  a349=(a004*a318);
  a305=(a305-a349);
  a349=(a195*a220);
  a229=(a071*a221);
  a349=(a349+a229);
  a229=(a056*a349);
  a305=(a305+a229);
  a229=(a186*a220);
  a294=(a071*a294);
  a229=(a229+a294);
  a294=(a048*a229);
  a205=(a195*a014);
  a221=(a070*a221);
  a205=(a205+a221);
  a221=(a048*a205);
  a213=(a294+a221);
  a213=(a198*a213);
  a305=(a305+a213);
  a213=(a178*a055);
  a358=(a061*a358);
  a213=(a213+a358);
  a358=(a009*a213);
  a345=(a095*a317);
  a358=(a358-a345);
  a345=(a054*a075);
  a358=(a358-a345);
  a345=(a095*a341);
  a358=(a358-a345);
  a229=(a012*a229);
  a358=(a358+a229);
  a229=(a072*a214);
  a358=(a358-a229);
  a229=(a054*a295);
  a358=(a358-a229);
  a229=(a072*a349);
  a358=(a358-a229);
  a205=(a008*a205);
  a358=(a358+a205);
  a205=(a204*a358);
  a205=(a049*a205);
  a229=(a019*a205);
  a358=(a358/a053);
  a229=(a229-a358);
  a345=(a032*a229);
  a100=(a045*a345);
  a309=(a027*a229);
  a301=(a020*a309);
  a301=(a042*a301);
  a100=(a100+a301);
  a301=(a039*a309);
  a100=(a100+a301);
  a301=(a020*a229);
  a301=(a036*a301);
  a100=(a100+a301);
  a301=(a033*a229);
  a100=(a100+a301);
  a301=(a032*a358);
  a237=(a029*a301);
  a100=(a100+a237);
  a237=(a027*a358);
  a206=(a020*a237);
  a206=(a025*a206);
  a100=(a100+a206);
  a206=(a022*a237);
  a100=(a100+a206);
  a205=(a034*a205);
  a345=(a047*a345);
  a206=(a046*a229);
  a206=(a217*a206);
  a210=(a040*a229);
  a206=(a206+a210);
  a206=(a216*a206);
  a345=(a345+a206);
  a309=(a043*a309);
  a345=(a345+a309);
  a229=(a037*a229);
  a345=(a345+a229);
  a345=(a013*a345);
  a205=(a205+a345);
  a301=(a031*a301);
  a345=(a030*a358);
  a345=(a217*a345);
  a229=(a023*a358);
  a345=(a345+a229);
  a345=(a216*a345);
  a301=(a301+a345);
  a237=(a026*a237);
  a301=(a301+a237);
  a237=(a017*a358);
  a301=(a301+a237);
  a301=(a013*a301);
  a205=(a205+a301);
  a205=(a018*a205);
  a100=(a100+a205);
  a205=(a020*a358);
  a205=(a016*a205);
  a100=(a100+a205);
  a358=(a001*a358);
  a100=(a100+a358);
  a358=(a198*a100);
  a305=(a305+a358);
  a358=(a058*a305);
  a075=(a056*a075);
  a075=(a075+a312);
  a181=(a011*a181);
  a075=(a075-a181);
  a295=(a085*a295);
  a075=(a075+a295);
  a214=(a048*a214);
  a349=(a048*a349);
  a214=(a214+a349);
  a349=(a004*a214);
  a075=(a075-a349);
  a213=(a048*a213);
  a221=(a213+a221);
  a221=(a223*a221);
  a075=(a075+a221);
  a221=(a223*a100);
  a075=(a075+a221);
  a221=(a087*a075);
  a358=(a358+a221);
  a317=(a085*a317);
  a341=(a056*a341);
  a317=(a317+a341);
  a213=(a213+a294);
  a213=(a226*a213);
  a317=(a317+a213);
  a317=(a317+a363);
  a318=(a011*a318);
  a317=(a317-a318);
  a214=(a007*a214);
  a317=(a317-a214);
  a100=(a226*a100);
  a317=(a317+a100);
  a100=(a090*a317);
  a358=(a358+a100);
  a014=(a200*a014);
  a014=(a083*a014);
  a358=(a358-a014);
  a358=(a358/a002);
  if (res[1]!=0) res[1][36]=a358;
  a358=(a102*a305);
  a014=(a104*a075);
  a358=(a358+a014);
  a214=(a106*a317);
  a358=(a358+a214);
  a220=(a200*a220);
  a220=(a083*a220);
  a358=(a358-a220);
  a358=(a358/a002);
  if (res[1]!=0) res[1][37]=a358;
  a358=(a108*a305);
  a220=(a111*a075);
  a220=(a358+a220);
  a214=(a113*a317);
  a220=(a220+a214);
  a055=(a200*a055);
  a055=(a083*a055);
  a220=(a220-a055);
  a220=(a220/a002);
  if (res[1]!=0) res[1][38]=a220;
  a220=(a143*a269);
  a055=(a149*a211);
  a055=(a220-a055);
  a298=(a231*a298);
  a214=(a139*a197);
  a311=(a125*a311);
  a214=(a214+a311);
  a214=(a133*a214);
  a298=(a298+a214);
  a214=(a120*a298);
  a311=(a055+a214);
  a311=(a227*a311);
  a318=(a121*a211);
  a318=(a233*a318);
  a311=(a311+a318);
  a318=(a160*a211);
  a320=(a320-a318);
  a318=(a115*a298);
  a320=(a320-a318);
  a320=(a234*a320);
  a311=(a311+a320);
  a311=(a083*a311);
  a320=(a200*a060);
  a320=(a083*a320);
  a311=(a311-a320);
  a296=(a093*a296);
  a239=(a239*a002);
  a320=(a179*a348);
  a318=(a158*a272);
  a147=(a018*a147);
  a324=(a238*a324);
  a147=(a147+a324);
  a324=(a148*a147);
  a318=(a318+a324);
  a324=(a134*a318);
  a320=(a320+a324);
  a324=(a184*a348);
  a363=(a185*a222);
  a109=(a018*a109);
  a299=(a238*a299);
  a109=(a109+a299);
  a299=(a142*a109);
  a363=(a363+a299);
  a299=(a134*a363);
  a324=(a324+a299);
  a320=(a320+a324);
  a324=(a117*a320);
  a324=(a239+a324);
  a307=(a307-a324);
  a324=(a185*a060);
  a299=(a069*a109);
  a324=(a324+a299);
  a299=(a085*a324);
  a307=(a307+a299);
  a299=(a241*a348);
  a213=(a158*a060);
  a294=(a069*a147);
  a213=(a213+a294);
  a294=(a134*a213);
  a299=(a299+a294);
  a294=(a193*a348);
  a341=(a194*a222);
  a292=(a018*a292);
  a190=(a238*a190);
  a292=(a292+a190);
  a190=(a142*a292);
  a341=(a341+a190);
  a190=(a134*a341);
  a294=(a294+a190);
  a299=(a299+a294);
  a294=(a115*a299);
  a307=(a307-a294);
  a294=(a194*a272);
  a190=(a148*a292);
  a294=(a294+a190);
  a190=(a056*a294);
  a307=(a307+a190);
  a190=(a245*a348);
  a221=(a185*a272);
  a109=(a148*a109);
  a221=(a221+a109);
  a109=(a134*a221);
  a190=(a190+a109);
  a109=(a247*a348);
  a060=(a194*a060);
  a292=(a069*a292);
  a060=(a060+a292);
  a292=(a134*a060);
  a109=(a109+a292);
  a292=(a190+a109);
  a292=(a244*a292);
  a307=(a307+a292);
  a292=(a254*a325);
  a197=(a253*a197);
  a349=(a348/a123);
  a295=(a357*a337);
  a349=(a349+a295);
  a349=(a252*a349);
  a295=(a251*a316);
  a181=(a158*a222);
  a147=(a142*a147);
  a181=(a181+a147);
  a147=(a119*a181);
  a295=(a295+a147);
  a147=(a179*a290);
  a312=(a160*a318);
  a147=(a147+a312);
  a295=(a295-a147);
  a147=(a141*a213);
  a295=(a295-a147);
  a290=(a184*a290);
  a147=(a160*a363);
  a290=(a290+a147);
  a295=(a295-a290);
  a221=(a121*a221);
  a295=(a295+a221);
  a221=(a240*a269);
  a290=(a149*a324);
  a221=(a221+a290);
  a295=(a295-a221);
  a221=(a141*a341);
  a295=(a295-a221);
  a221=(a243*a269);
  a290=(a149*a294);
  a221=(a221+a290);
  a295=(a295-a221);
  a221=(a247*a316);
  a060=(a118*a060);
  a221=(a221+a060);
  a295=(a295+a221);
  a221=(a250*a295);
  a349=(a349+a221);
  a349=(a049*a349);
  a221=(a125*a349);
  a197=(a197+a221);
  a295=(a295/a123);
  a337=(a364*a337);
  a295=(a295+a337);
  a197=(a197-a295);
  a337=(a131*a197);
  a292=(a292+a337);
  a337=(a045*a292);
  a221=(a258*a362);
  a060=(a254*a339);
  a290=(a129*a197);
  a060=(a060+a290);
  a290=(a126*a060);
  a221=(a221+a290);
  a221=(a042*a221);
  a337=(a337+a221);
  a221=(a039*a060);
  a337=(a337+a221);
  a221=(a254*a362);
  a290=(a126*a197);
  a221=(a221+a290);
  a221=(a036*a221);
  a337=(a337+a221);
  a221=(a033*a197);
  a337=(a337+a221);
  a325=(a255*a325);
  a221=(a131*a295);
  a325=(a325+a221);
  a221=(a029*a325);
  a337=(a337+a221);
  a221=(a260*a362);
  a290=(a255*a339);
  a147=(a129*a295);
  a290=(a290+a147);
  a147=(a126*a290);
  a221=(a221+a147);
  a221=(a025*a221);
  a337=(a337+a221);
  a221=(a022*a290);
  a337=(a337+a221);
  a361=(a253*a361);
  a349=(a132*a349);
  a361=(a361+a349);
  a349=(a056*a316);
  a221=(a256*a349);
  a292=(a047*a292);
  a147=(2.*a362);
  a312=(a265*a147);
  a339=(2.*a339);
  a205=(a264*a339);
  a098=(a254*a098);
  a301=(a130*a197);
  a098=(a098+a301);
  a098=(a263*a098);
  a205=(a205+a098);
  a343=(a254*a343);
  a098=(a127*a197);
  a343=(a343+a098);
  a205=(a205+a343);
  a205=(a262*a205);
  a312=(a312+a205);
  a292=(a292+a312);
  a331=(a258*a331);
  a060=(a128*a060);
  a331=(a331+a060);
  a292=(a292+a331);
  a209=(a254*a209);
  a197=(a124*a197);
  a209=(a209+a197);
  a292=(a292+a209);
  a292=(a122*a292);
  a221=(a221+a292);
  a361=(a361+a221);
  a349=(a259*a349);
  a325=(a031*a325);
  a147=(a267*a147);
  a339=(a266*a339);
  a182=(a255*a182);
  a221=(a138*a295);
  a182=(a182+a221);
  a182=(a263*a182);
  a339=(a339+a182);
  a207=(a255*a207);
  a182=(a136*a295);
  a207=(a207+a182);
  a339=(a339+a207);
  a339=(a262*a339);
  a147=(a147+a339);
  a325=(a325+a147);
  a202=(a260*a202);
  a290=(a137*a290);
  a202=(a202+a290);
  a325=(a325+a202);
  a359=(a255*a359);
  a202=(a135*a295);
  a359=(a359+a202);
  a325=(a325+a359);
  a325=(a122*a325);
  a349=(a349+a325);
  a361=(a361+a349);
  a361=(a018*a361);
  a337=(a337+a361);
  a362=(a255*a362);
  a361=(a126*a295);
  a362=(a362+a361);
  a362=(a016*a362);
  a337=(a337+a362);
  a295=(a001*a295);
  a337=(a337+a295);
  a295=(a244*a337);
  a307=(a307+a295);
  a295=(a153*a307);
  a296=(a296+a295);
  a311=(a311+a296);
  a296=(a183*a333);
  a213=(a056*a213);
  a225=(a225+a213);
  a320=(a120*a320);
  a225=(a225-a320);
  a341=(a085*a341);
  a225=(a225+a341);
  a341=(a240*a348);
  a324=(a134*a324);
  a341=(a341+a324);
  a324=(a243*a348);
  a294=(a134*a294);
  a324=(a324+a294);
  a341=(a341+a324);
  a324=(a115*a341);
  a225=(a225-a324);
  a248=(a248*a342);
  a348=(a251*a348);
  a181=(a134*a181);
  a348=(a348+a181);
  a109=(a348+a109);
  a109=(a268*a109);
  a248=(a248+a109);
  a225=(a225+a248);
  a248=(a268*a337);
  a248=(a257+a248);
  a225=(a225+a248);
  a248=(a156*a225);
  a248=(a296+a248);
  a311=(a311+a248);
  a318=(a085*a318);
  a356=(a356+a318);
  a363=(a056*a363);
  a356=(a356+a363);
  a348=(a348+a190);
  a348=(a270*a348);
  a356=(a356+a348);
  a299=(a120*a299);
  a356=(a356-a299);
  a341=(a117*a341);
  a261=(a261+a341);
  a356=(a356-a261);
  a337=(a270*a337);
  a356=(a356+a337);
  a337=(a157*a356);
  a094=(a192*a094);
  a337=(a337-a094);
  a311=(a311+a337);
  a311=(a311/a002);
  if (res[1]!=0) res[1][39]=a311;
  a311=(a093*a306);
  a094=(a166*a307);
  a094=(a311+a094);
  a272=(a200*a272);
  a272=(a083*a272);
  a055=(a055-a214);
  a055=(a233*a055);
  a316=(a143*a316);
  a214=(a118*a211);
  a316=(a316-a214);
  a316=(a227*a316);
  a055=(a055-a316);
  a211=(a141*a211);
  a298=(a117*a298);
  a298=(a228-a298);
  a211=(a211+a298);
  a211=(a234*a211);
  a055=(a055-a211);
  a055=(a083*a055);
  a272=(a272+a055);
  a094=(a094-a272);
  a272=(a167*a225);
  a346=(a183*a346);
  a272=(a272-a346);
  a094=(a094+a272);
  a333=(a192*a333);
  a346=(a169*a356);
  a346=(a333+a346);
  a094=(a094+a346);
  a094=(a094/a002);
  if (res[1]!=0) res[1][40]=a094;
  a094=(a171*a307);
  a303=(a093*a303);
  a094=(a094-a303);
  a222=(a200*a222);
  a222=(a083*a222);
  a222=(a094-a222);
  a306=(a183*a306);
  a303=(a173*a225);
  a303=(a306+a303);
  a222=(a222+a303);
  a077=(a192*a077);
  a303=(a175*a356);
  a077=(a077+a303);
  a222=(a222+a077);
  a222=(a222/a002);
  if (res[1]!=0) res[1][41]=a222;
  a353=(a353*a230);
  a222=(a001*a353);
  a077=(a016*a353);
  a077=(a282*a077);
  a303=(a018*a353);
  a346=(a279*a303);
  a055=(a015*a346);
  a077=(a077+a055);
  a222=(a222+a077);
  a077=(a022*a353);
  a055=(a025*a353);
  a055=(a282*a055);
  a211=(a024*a346);
  a055=(a055+a211);
  a077=(a077+a055);
  a077=(a283*a077);
  a055=(a336*a346);
  a211=(a021*a055);
  a077=(a077+a211);
  a222=(a222+a077);
  a077=(a029*a353);
  a211=(a031*a346);
  a077=(a077+a211);
  a077=(a284*a077);
  a211=(a332*a055);
  a298=(a028*a211);
  a077=(a077+a298);
  a222=(a222+a077);
  a077=(a033*a353);
  a298=(a036*a353);
  a298=(a282*a298);
  a316=(a035*a346);
  a298=(a298+a316);
  a077=(a077+a298);
  a298=(a039*a353);
  a316=(a042*a353);
  a316=(a282*a316);
  a214=(a041*a346);
  a316=(a316+a214);
  a298=(a298+a316);
  a298=(a283*a298);
  a055=(a038*a055);
  a298=(a298+a055);
  a077=(a077+a298);
  a298=(a045*a353);
  a346=(a047*a346);
  a298=(a298+a346);
  a298=(a284*a298);
  a211=(a044*a211);
  a298=(a298+a211);
  a077=(a077+a298);
  a222=(a222-a077);
  a222=(a222/a285);
  a303=(a051*a303);
  a077=(a281*a077);
  a303=(a303+a077);
  a303=(a049*a303);
  a303=(a297*a303);
  a222=(a222+a303);
  a303=(a280*a222);
  a077=(a340+a303);
  a077=(a081*a077);
  a298=(a289*a222);
  a273=(a273*a230);
  a273=(a000*a273);
  a298=(a298+a273);
  a211=(a088*a298);
  a077=(a077+a211);
  a211=(a275*a222);
  a353=(a000*a353);
  a211=(a211+a353);
  a211=(a091*a211);
  a077=(a077-a211);
  a211=(a083+a224);
  a211=(a093*a211);
  a346=(a152*a307);
  a211=(a211+a346);
  a077=(a077+a211);
  a211=(a155*a225);
  a296=(a296+a211);
  a077=(a077+a296);
  a077=(a077+a337);
  a337=(a057*a305);
  a077=(a077+a337);
  a337=(a086*a075);
  a077=(a077+a337);
  a077=(a077+a100);
  a077=(-a077);
  if (res[1]!=0) res[1][42]=a077;
  a077=(a191*a222);
  a077=(a077+a277);
  a277=(a081*a077);
  a100=(a278*a222);
  a100=(a088*a100);
  a277=(a277-a100);
  a298=(a091*a298);
  a277=(a277+a298);
  a307=(a165*a307);
  a311=(a311+a307);
  a277=(a277+a311);
  a277=(a277+a272);
  a272=(a168*a356);
  a333=(a333+a272);
  a277=(a277+a333);
  a305=(a101*a305);
  a277=(a277+a305);
  a277=(a277+a014);
  a014=(a105*a317);
  a277=(a277+a014);
  a277=(-a277);
  if (res[1]!=0) res[1][43]=a277;
  a077=(a088*a077);
  a222=(a276*a222);
  a222=(a222+a353);
  a222=(a081*a222);
  a077=(a077-a222);
  a303=(a076+a303);
  a303=(a091*a303);
  a077=(a077+a303);
  a077=(a077+a094);
  a225=(a172*a225);
  a306=(a306+a225);
  a077=(a077+a306);
  a224=(a329+a224);
  a224=(a192*a224);
  a356=(a174*a356);
  a224=(a224+a356);
  a077=(a077+a224);
  a077=(a077+a358);
  a075=(a110*a075);
  a077=(a077+a075);
  a317=(a112*a317);
  a077=(a077+a317);
  a077=(-a077);
  if (res[1]!=0) res[1][44]=a077;
  a077=(a271*a064);
  a077=(a080*a077);
  a077=(a077/a083);
  a317=(a064*a077);
  a075=(a271*a097);
  a075=(a099*a075);
  a075=(a075/a083);
  a358=(a097*a075);
  a317=(a317+a358);
  a271=(a271*a103);
  a271=(a107*a271);
  a271=(a271/a083);
  a358=(a103*a271);
  a317=(a317+a358);
  a358=(a059*a317);
  a224=(a244*a002);
  a356=(a033*a224);
  a306=(a036*a224);
  a225=(a126*a306);
  a094=(a018*a224);
  a303=(a122*a094);
  a222=(a124*a303);
  a225=(a225+a222);
  a356=(a356+a225);
  a225=(a039*a224);
  a222=(a042*a224);
  a353=(a126*a222);
  a277=(a128*a303);
  a353=(a353+a277);
  a225=(a225+a353);
  a353=(a129*a225);
  a277=(a262*a303);
  a014=(a127*a277);
  a353=(a353+a014);
  a356=(a356+a353);
  a353=(a045*a224);
  a014=(a047*a303);
  a353=(a353+a014);
  a014=(a131*a353);
  a305=(a263*a277);
  a333=(a130*a305);
  a014=(a014+a333);
  a356=(a356+a014);
  a014=(a001*a224);
  a333=(a016*a224);
  a272=(a126*a333);
  a311=(a135*a303);
  a272=(a272+a311);
  a014=(a014+a272);
  a272=(a022*a224);
  a311=(a025*a224);
  a307=(a126*a311);
  a298=(a137*a303);
  a307=(a307+a298);
  a272=(a272+a307);
  a307=(a129*a272);
  a298=(a136*a277);
  a307=(a307+a298);
  a014=(a014+a307);
  a307=(a029*a224);
  a298=(a031*a303);
  a307=(a307+a298);
  a298=(a131*a307);
  a100=(a138*a305);
  a298=(a298+a100);
  a014=(a014+a298);
  a298=(a133*a014);
  a100=(a132*a094);
  a337=(a125*a356);
  a100=(a100+a337);
  a337=(a139*a100);
  a298=(a298-a337);
  a298=(a356+a298);
  a298=(a018*a298);
  a337=(a141*a298);
  a337=(a337+a062);
  a067=(a067*a100);
  a067=(a056*a067);
  a062=(a117*a067);
  a296=(a337+a062);
  a211=(a078*a296);
  a346=(a120*a067);
  a330=(a330-a346);
  a346=(a149*a298);
  a055=(a330+a346);
  a316=(a006*a055);
  a214=(a118*a298);
  a140=(a140*a224);
  a214=(a214+a140);
  a261=(a003*a214);
  a316=(a316-a261);
  a296=(a010*a296);
  a261=(a066*a145);
  a296=(a296+a261);
  a316=(a316+a296);
  a296=(2.*a316);
  a080=(a080*a296);
  a296=(a014-a356);
  a296=(a296/a123);
  a261=(a049*a100);
  a341=(a250*a261);
  a296=(a296+a341);
  a341=(a141*a296);
  a341=(a341+a310);
  a310=(a082*a341);
  a080=(a080-a310);
  a310=(a149*a296);
  a299=(a310-a329);
  a348=(a089*a299);
  a080=(a080-a348);
  a348=(a118*a296);
  a190=(a134*a224);
  a348=(a348+a190);
  a363=(a092*a348);
  a080=(a080+a363);
  a080=(a080/a083);
  a363=(a145*a080);
  a211=(a211+a363);
  a363=(a160*a298);
  a363=(a363+a302);
  a302=(a115*a067);
  a318=(a363-a302);
  a248=(a163*a318);
  a346=(a346-a330);
  a330=(a003*a346);
  a109=(a121*a298);
  a109=(a109+a140);
  a140=(a006*a109);
  a330=(a330-a140);
  a318=(a010*a318);
  a140=(a066*a162);
  a318=(a318+a140);
  a330=(a330+a318);
  a318=(2.*a330);
  a099=(a099*a318);
  a318=(a160*a296);
  a318=(a318+a188);
  a188=(a082*a318);
  a099=(a099-a188);
  a188=(a121*a296);
  a188=(a188+a190);
  a190=(a089*a188);
  a099=(a099+a190);
  a190=(a310-a083);
  a140=(a092*a190);
  a099=(a099-a140);
  a099=(a099/a083);
  a140=(a162*a099);
  a248=(a248+a140);
  a211=(a211+a248);
  a337=(a337-a062);
  a003=(a003*a337);
  a363=(a363+a302);
  a006=(a006*a363);
  a003=(a003+a006);
  a066=(a066*a170);
  a298=(a119*a298);
  a010=(a010*a298);
  a066=(a066-a010);
  a003=(a003+a066);
  a066=(2.*a003);
  a107=(a107*a066);
  a066=(a119*a296);
  a082=(a082*a066);
  a107=(a107+a082);
  a089=(a089*a318);
  a107=(a107-a089);
  a092=(a092*a341);
  a107=(a107-a092);
  a107=(a107/a083);
  a092=(a170*a107);
  a298=(a159*a298);
  a092=(a092-a298);
  a211=(a211+a092);
  a092=(a114*a211);
  a358=(a358+a092);
  a092=(a068*a097);
  a298=(a178*a092);
  a317=(a177*a317);
  a211=(a059*a211);
  a317=(a317+a211);
  a211=(a002*a317);
  a089=(a176*a211);
  a082=(a002*a358);
  a010=(a018*a082);
  a089=(a089+a010);
  a010=(a071*a089);
  a298=(a298+a010);
  a010=(a048*a298);
  a006=(a068*a103);
  a302=(a186*a006);
  a062=(a074*a077);
  a248=(a005*a075);
  a062=(a062+a248);
  a248=(a096*a271);
  a062=(a062+a248);
  a248=(a177*a062);
  a055=(a078*a055);
  a140=(a151*a080);
  a055=(a055+a140);
  a140=(a116*a099);
  a109=(a163*a109);
  a140=(a140-a109);
  a055=(a055+a140);
  a363=(a159*a363);
  a140=(a161*a107);
  a363=(a363+a140);
  a055=(a055+a363);
  a363=(a059*a055);
  a248=(a248+a363);
  a363=(a002*a248);
  a140=(a176*a363);
  a062=(a059*a062);
  a055=(a114*a055);
  a062=(a062+a055);
  a055=(a002*a062);
  a109=(a018*a055);
  a140=(a140+a109);
  a109=(a061*a140);
  a302=(a302+a109);
  a109=(a048*a302);
  a010=(a010+a109);
  a109=(a007*a010);
  a358=(a358-a109);
  a068=(a068*a064);
  a109=(a186*a068);
  a181=(a070*a140);
  a109=(a109+a181);
  a181=(a085*a109);
  a358=(a358+a181);
  a181=(a178*a068);
  a324=(a070*a089);
  a181=(a181+a324);
  a324=(a048*a181);
  a294=(a195*a006);
  a077=(a065*a077);
  a075=(a073*a075);
  a077=(a077+a075);
  a271=(a063*a271);
  a077=(a077+a271);
  a271=(a177*a077);
  a080=(a146*a080);
  a078=(a078*a214);
  a080=(a080-a078);
  a163=(a163*a346);
  a099=(a150*a099);
  a163=(a163+a099);
  a080=(a080+a163);
  a159=(a159*a337);
  a107=(a144*a107);
  a159=(a159+a107);
  a080=(a080+a159);
  a159=(a059*a080);
  a271=(a271+a159);
  a159=(a002*a271);
  a107=(a176*a159);
  a077=(a059*a077);
  a080=(a114*a080);
  a077=(a077+a080);
  a080=(a002*a077);
  a337=(a018*a080);
  a107=(a107+a337);
  a337=(a061*a107);
  a294=(a294+a337);
  a337=(a048*a294);
  a324=(a324+a337);
  a337=(a004*a324);
  a358=(a358-a337);
  a337=(a195*a092);
  a163=(a071*a107);
  a337=(a337+a163);
  a163=(a056*a337);
  a358=(a358+a163);
  a186=(a186*a092);
  a140=(a071*a140);
  a186=(a186+a140);
  a140=(a048*a186);
  a195=(a195*a068);
  a107=(a070*a107);
  a195=(a195+a107);
  a107=(a048*a195);
  a163=(a140+a107);
  a163=(a198*a163);
  a358=(a358+a163);
  a178=(a178*a006);
  a089=(a061*a089);
  a178=(a178+a089);
  a089=(a009*a178);
  a163=(a095*a298);
  a089=(a089-a163);
  a163=(a054*a181);
  a089=(a089-a163);
  a163=(a095*a302);
  a089=(a089-a163);
  a186=(a012*a186);
  a089=(a089+a186);
  a186=(a072*a109);
  a089=(a089-a186);
  a186=(a054*a294);
  a089=(a089-a186);
  a186=(a072*a337);
  a089=(a089-a186);
  a195=(a008*a195);
  a089=(a089+a195);
  a195=(a204*a089);
  a195=(a049*a195);
  a186=(a019*a195);
  a089=(a089/a053);
  a186=(a186-a089);
  a163=(a032*a186);
  a099=(a045*a163);
  a346=(a027*a186);
  a078=(a020*a346);
  a078=(a042*a078);
  a099=(a099+a078);
  a078=(a039*a346);
  a099=(a099+a078);
  a078=(a020*a186);
  a078=(a036*a078);
  a099=(a099+a078);
  a078=(a033*a186);
  a099=(a099+a078);
  a078=(a032*a089);
  a214=(a029*a078);
  a099=(a099+a214);
  a214=(a027*a089);
  a075=(a020*a214);
  a075=(a025*a075);
  a099=(a099+a075);
  a075=(a022*a214);
  a099=(a099+a075);
  a195=(a034*a195);
  a163=(a047*a163);
  a075=(a046*a186);
  a075=(a217*a075);
  a320=(a040*a186);
  a075=(a075+a320);
  a075=(a216*a075);
  a163=(a163+a075);
  a346=(a043*a346);
  a163=(a163+a346);
  a186=(a037*a186);
  a163=(a163+a186);
  a163=(a013*a163);
  a195=(a195+a163);
  a078=(a031*a078);
  a163=(a030*a089);
  a163=(a217*a163);
  a186=(a023*a089);
  a163=(a163+a186);
  a163=(a216*a163);
  a078=(a078+a163);
  a214=(a026*a214);
  a078=(a078+a214);
  a214=(a017*a089);
  a078=(a078+a214);
  a078=(a013*a078);
  a195=(a195+a078);
  a195=(a018*a195);
  a099=(a099+a195);
  a195=(a020*a089);
  a195=(a016*a195);
  a099=(a099+a195);
  a089=(a001*a089);
  a099=(a099+a089);
  a089=(a198*a099);
  a358=(a358+a089);
  a089=(a058*a358);
  a181=(a056*a181);
  a181=(a181+a062);
  a010=(a011*a010);
  a181=(a181-a010);
  a294=(a085*a294);
  a181=(a181+a294);
  a109=(a048*a109);
  a337=(a048*a337);
  a109=(a109+a337);
  a337=(a004*a109);
  a181=(a181-a337);
  a178=(a048*a178);
  a107=(a178+a107);
  a107=(a223*a107);
  a181=(a181+a107);
  a107=(a223*a099);
  a181=(a181+a107);
  a107=(a087*a181);
  a089=(a089+a107);
  a298=(a085*a298);
  a302=(a056*a302);
  a298=(a298+a302);
  a178=(a178+a140);
  a178=(a226*a178);
  a298=(a298+a178);
  a298=(a298+a077);
  a324=(a011*a324);
  a298=(a298-a324);
  a109=(a007*a109);
  a298=(a298-a109);
  a099=(a226*a099);
  a298=(a298+a099);
  a099=(a090*a298);
  a089=(a089+a099);
  a068=(a200*a068);
  a068=(a083*a068);
  a089=(a089-a068);
  a089=(a089/a002);
  if (res[1]!=0) res[1][45]=a089;
  a089=(a102*a358);
  a068=(a104*a181);
  a089=(a089+a068);
  a109=(a106*a298);
  a089=(a089+a109);
  a092=(a200*a092);
  a092=(a083*a092);
  a089=(a089-a092);
  a089=(a089/a002);
  if (res[1]!=0) res[1][46]=a089;
  a089=(a108*a358);
  a092=(a111*a181);
  a092=(a089+a092);
  a109=(a113*a298);
  a092=(a092+a109);
  a006=(a200*a006);
  a006=(a083*a006);
  a092=(a092-a006);
  a092=(a092/a002);
  if (res[1]!=0) res[1][47]=a092;
  a092=(a160*a067);
  a360=(a360-a092);
  a231=(a231*a100);
  a139=(a139*a094);
  a014=(a125*a014);
  a139=(a139+a014);
  a133=(a133*a139);
  a231=(a231+a133);
  a133=(a115*a231);
  a360=(a360-a133);
  a360=(a234*a360);
  a133=(a149*a067);
  a139=(a120*a231);
  a228=(a228-a139);
  a139=(a133+a228);
  a139=(a227*a139);
  a143=(a143*a224);
  a014=(a121*a067);
  a014=(a143-a014);
  a014=(a233*a014);
  a139=(a139+a014);
  a360=(a360-a139);
  a360=(a083*a360);
  a139=(a200*a316);
  a139=(a083*a139);
  a360=(a360-a139);
  a139=(a093*a341);
  a014=(a179*a296);
  a100=(a158*a330);
  a211=(a018*a211);
  a082=(a238*a082);
  a211=(a211+a082);
  a082=(a148*a211);
  a100=(a100+a082);
  a082=(a134*a100);
  a014=(a014+a082);
  a082=(a184*a296);
  a092=(a185*a003);
  a363=(a018*a363);
  a055=(a238*a055);
  a363=(a363+a055);
  a055=(a142*a363);
  a092=(a092+a055);
  a055=(a134*a092);
  a082=(a082+a055);
  a014=(a014+a082);
  a082=(a117*a014);
  a317=(a317-a082);
  a082=(a185*a316);
  a055=(a069*a363);
  a082=(a082+a055);
  a055=(a085*a082);
  a317=(a317+a055);
  a055=(a241*a296);
  a006=(a158*a316);
  a109=(a069*a211);
  a006=(a006+a109);
  a109=(a134*a006);
  a055=(a055+a109);
  a109=(a193*a296);
  a324=(a194*a003);
  a159=(a018*a159);
  a080=(a238*a080);
  a159=(a159+a080);
  a080=(a142*a159);
  a324=(a324+a080);
  a080=(a134*a324);
  a109=(a109+a080);
  a055=(a055+a109);
  a109=(a115*a055);
  a317=(a317-a109);
  a109=(a194*a330);
  a080=(a148*a159);
  a109=(a109+a080);
  a080=(a056*a109);
  a317=(a317+a080);
  a249=(a249*a342);
  a342=(a245*a296);
  a185=(a185*a330);
  a363=(a148*a363);
  a185=(a185+a363);
  a363=(a134*a185);
  a342=(a342+a363);
  a363=(a247*a296);
  a194=(a194*a316);
  a159=(a069*a159);
  a194=(a194+a159);
  a159=(a134*a194);
  a363=(a363+a159);
  a159=(a342+a363);
  a159=(a244*a159);
  a249=(a249+a159);
  a317=(a317+a249);
  a249=(a254*a305);
  a094=(a253*a094);
  a159=(a296/a123);
  a357=(a357*a261);
  a159=(a159+a357);
  a252=(a252*a159);
  a158=(a158*a003);
  a211=(a142*a211);
  a158=(a158+a211);
  a211=(a119*a158);
  a179=(a179*a052);
  a159=(a160*a100);
  a179=(a179+a159);
  a211=(a211-a179);
  a241=(a241*a269);
  a179=(a141*a006);
  a241=(a241+a179);
  a211=(a211-a241);
  a184=(a184*a052);
  a052=(a160*a092);
  a184=(a184+a052);
  a211=(a211-a184);
  a245=(a245*a224);
  a185=(a121*a185);
  a245=(a245+a185);
  a211=(a211+a245);
  a245=(a149*a082);
  a211=(a211-a245);
  a193=(a193*a269);
  a269=(a141*a324);
  a193=(a193+a269);
  a211=(a211-a193);
  a193=(a149*a109);
  a211=(a211-a193);
  a247=(a247*a224);
  a194=(a118*a194);
  a247=(a247+a194);
  a211=(a211+a247);
  a247=(a250*a211);
  a252=(a252+a247);
  a252=(a049*a252);
  a247=(a125*a252);
  a094=(a094+a247);
  a211=(a211/a123);
  a364=(a364*a261);
  a211=(a211+a364);
  a094=(a094-a211);
  a364=(a131*a094);
  a249=(a249+a364);
  a364=(a045*a249);
  a261=(a258*a303);
  a247=(a254*a277);
  a194=(a129*a094);
  a247=(a247+a194);
  a194=(a126*a247);
  a261=(a261+a194);
  a261=(a042*a261);
  a364=(a364+a261);
  a261=(a039*a247);
  a364=(a364+a261);
  a261=(a254*a303);
  a194=(a126*a094);
  a261=(a261+a194);
  a261=(a036*a261);
  a364=(a364+a261);
  a261=(a033*a094);
  a364=(a364+a261);
  a305=(a255*a305);
  a261=(a131*a211);
  a305=(a305+a261);
  a261=(a029*a305);
  a364=(a364+a261);
  a261=(a260*a303);
  a194=(a255*a277);
  a193=(a129*a211);
  a194=(a194+a193);
  a193=(a126*a194);
  a261=(a261+a193);
  a261=(a025*a261);
  a364=(a364+a261);
  a261=(a022*a194);
  a364=(a364+a261);
  a253=(a253*a356);
  a252=(a132*a252);
  a253=(a253+a252);
  a224=(a056*a224);
  a256=(a256*a224);
  a249=(a047*a249);
  a252=(2.*a303);
  a265=(a265*a252);
  a277=(2.*a277);
  a264=(a264*a277);
  a353=(a254*a353);
  a356=(a130*a094);
  a353=(a353+a356);
  a353=(a263*a353);
  a264=(a264+a353);
  a225=(a254*a225);
  a353=(a127*a094);
  a225=(a225+a353);
  a264=(a264+a225);
  a264=(a262*a264);
  a265=(a265+a264);
  a249=(a249+a265);
  a258=(a258*a222);
  a247=(a128*a247);
  a258=(a258+a247);
  a249=(a249+a258);
  a254=(a254*a306);
  a094=(a124*a094);
  a254=(a254+a094);
  a249=(a249+a254);
  a249=(a122*a249);
  a256=(a256+a249);
  a253=(a253+a256);
  a259=(a259*a224);
  a305=(a031*a305);
  a267=(a267*a252);
  a266=(a266*a277);
  a307=(a255*a307);
  a277=(a138*a211);
  a307=(a307+a277);
  a307=(a263*a307);
  a266=(a266+a307);
  a272=(a255*a272);
  a307=(a136*a211);
  a272=(a272+a307);
  a266=(a266+a272);
  a266=(a262*a266);
  a267=(a267+a266);
  a305=(a305+a267);
  a260=(a260*a311);
  a194=(a137*a194);
  a260=(a260+a194);
  a305=(a305+a260);
  a333=(a255*a333);
  a260=(a135*a211);
  a333=(a333+a260);
  a305=(a305+a333);
  a305=(a122*a305);
  a259=(a259+a305);
  a253=(a253+a259);
  a253=(a018*a253);
  a364=(a364+a253);
  a255=(a255*a303);
  a303=(a126*a211);
  a255=(a255+a303);
  a255=(a016*a255);
  a364=(a364+a255);
  a211=(a001*a211);
  a364=(a364+a211);
  a211=(a244*a364);
  a257=(a257+a211);
  a317=(a317+a257);
  a257=(a153*a317);
  a257=(a139+a257);
  a360=(a360+a257);
  a299=(a183*a299);
  a006=(a056*a006);
  a248=(a248+a006);
  a014=(a120*a014);
  a239=(a239+a014);
  a248=(a248-a239);
  a324=(a085*a324);
  a248=(a248+a324);
  a240=(a240*a296);
  a082=(a134*a082);
  a240=(a240+a082);
  a243=(a243*a296);
  a109=(a134*a109);
  a243=(a243+a109);
  a240=(a240+a243);
  a243=(a115*a240);
  a248=(a248-a243);
  a251=(a251*a296);
  a158=(a134*a158);
  a251=(a251+a158);
  a363=(a251+a363);
  a363=(a268*a363);
  a248=(a248+a363);
  a363=(a268*a364);
  a248=(a248+a363);
  a363=(a156*a248);
  a299=(a299+a363);
  a360=(a360+a299);
  a100=(a085*a100);
  a271=(a271+a100);
  a092=(a056*a092);
  a271=(a271+a092);
  a251=(a251+a342);
  a251=(a270*a251);
  a271=(a271+a251);
  a055=(a120*a055);
  a242=(a242+a055);
  a271=(a271-a242);
  a240=(a117*a240);
  a271=(a271-a240);
  a364=(a270*a364);
  a271=(a271+a364);
  a364=(a157*a271);
  a348=(a192*a348);
  a364=(a364-a348);
  a360=(a360+a364);
  a360=(a360/a002);
  if (res[1]!=0) res[1][48]=a360;
  a360=(a093*a318);
  a348=(a166*a317);
  a348=(a360+a348);
  a330=(a200*a330);
  a330=(a083*a330);
  a228=(a228-a133);
  a233=(a233*a228);
  a228=(a118*a067);
  a143=(a143-a228);
  a227=(a227*a143);
  a233=(a233-a227);
  a067=(a141*a067);
  a220=(a220-a067);
  a231=(a117*a231);
  a220=(a220+a231);
  a234=(a234*a220);
  a233=(a233+a234);
  a233=(a083*a233);
  a330=(a330+a233);
  a348=(a348-a330);
  a330=(a167*a248);
  a188=(a183*a188);
  a330=(a330-a188);
  a348=(a348+a330);
  a190=(a192*a190);
  a188=(a169*a271);
  a190=(a190+a188);
  a348=(a348+a190);
  a348=(a348/a002);
  if (res[1]!=0) res[1][49]=a348;
  a348=(a171*a317);
  a093=(a093*a066);
  a348=(a348-a093);
  a200=(a200*a003);
  a200=(a083*a200);
  a200=(a348-a200);
  a318=(a183*a318);
  a003=(a173*a248);
  a003=(a318+a003);
  a200=(a200+a003);
  a341=(a192*a341);
  a003=(a175*a271);
  a003=(a341+a003);
  a200=(a200+a003);
  a200=(a200/a002);
  if (res[1]!=0) res[1][50]=a200;
  a315=(a315*a230);
  a230=(a001*a315);
  a200=(a016*a315);
  a200=(a282*a200);
  a003=(a018*a315);
  a279=(a279*a003);
  a015=(a015*a279);
  a200=(a200+a015);
  a230=(a230+a200);
  a200=(a022*a315);
  a015=(a025*a315);
  a015=(a282*a015);
  a024=(a024*a279);
  a015=(a015+a024);
  a200=(a200+a015);
  a200=(a283*a200);
  a336=(a336*a279);
  a021=(a021*a336);
  a200=(a200+a021);
  a230=(a230+a200);
  a200=(a029*a315);
  a021=(a031*a279);
  a200=(a200+a021);
  a200=(a284*a200);
  a332=(a332*a336);
  a028=(a028*a332);
  a200=(a200+a028);
  a230=(a230+a200);
  a200=(a033*a315);
  a028=(a036*a315);
  a028=(a282*a028);
  a035=(a035*a279);
  a028=(a028+a035);
  a200=(a200+a028);
  a028=(a039*a315);
  a035=(a042*a315);
  a282=(a282*a035);
  a041=(a041*a279);
  a282=(a282+a041);
  a028=(a028+a282);
  a283=(a283*a028);
  a038=(a038*a336);
  a283=(a283+a038);
  a200=(a200+a283);
  a283=(a045*a315);
  a279=(a047*a279);
  a283=(a283+a279);
  a284=(a284*a283);
  a044=(a044*a332);
  a284=(a284+a044);
  a200=(a200+a284);
  a230=(a230-a200);
  a230=(a230/a285);
  a051=(a051*a003);
  a281=(a281*a200);
  a051=(a051+a281);
  a051=(a049*a051);
  a297=(a297*a051);
  a230=(a230+a297);
  a280=(a280*a230);
  a280=(a280+a273);
  a273=(a081*a280);
  a289=(a289*a230);
  a076=(a076+a289);
  a076=(a088*a076);
  a273=(a273+a076);
  a275=(a275*a230);
  a000=(a000*a315);
  a275=(a275+a000);
  a275=(a091*a275);
  a273=(a273-a275);
  a275=(a152*a317);
  a139=(a139+a275);
  a273=(a273+a139);
  a329=(a329+a310);
  a183=(a183*a329);
  a329=(a155*a248);
  a183=(a183+a329);
  a273=(a273+a183);
  a273=(a273+a364);
  a364=(a057*a358);
  a273=(a273+a364);
  a364=(a086*a181);
  a273=(a273+a364);
  a273=(a273+a099);
  a273=(-a273);
  if (res[1]!=0) res[1][51]=a273;
  a191=(a191*a230);
  a191=(a191+a236);
  a236=(a081*a191);
  a278=(a278*a230);
  a278=(a278+a000);
  a278=(a088*a278);
  a236=(a236-a278);
  a340=(a340+a289);
  a340=(a091*a340);
  a236=(a236+a340);
  a317=(a165*a317);
  a360=(a360+a317);
  a236=(a236+a360);
  a236=(a236+a330);
  a310=(a083+a310);
  a192=(a192*a310);
  a310=(a168*a271);
  a192=(a192+a310);
  a236=(a236+a192);
  a358=(a101*a358);
  a236=(a236+a358);
  a236=(a236+a068);
  a068=(a105*a298);
  a236=(a236+a068);
  a236=(-a236);
  if (res[1]!=0) res[1][52]=a236;
  a088=(a088*a191);
  a276=(a276*a230);
  a081=(a081*a276);
  a088=(a088-a081);
  a091=(a091*a280);
  a088=(a088+a091);
  a088=(a088+a348);
  a248=(a172*a248);
  a318=(a318+a248);
  a088=(a088+a318);
  a271=(a174*a271);
  a341=(a341+a271);
  a088=(a088+a341);
  a088=(a088+a089);
  a181=(a110*a181);
  a088=(a088+a181);
  a298=(a112*a298);
  a088=(a088+a298);
  a088=(-a088);
  if (res[1]!=0) res[1][53]=a088;
  a088=(a064*a090);
  a298=(a097*a106);
  a088=(a088+a298);
  a298=(a103*a113);
  a088=(a088+a298);
  a298=(a177*a088);
  a181=(a145*a157);
  a089=(a162*a169);
  a181=(a181+a089);
  a089=(a170*a175);
  a181=(a181+a089);
  a089=(a059*a181);
  a298=(a298+a089);
  a089=(a002*a298);
  a341=(a176*a089);
  a088=(a059*a088);
  a181=(a114*a181);
  a088=(a088+a181);
  a181=(a002*a088);
  a271=(a018*a181);
  a341=(a341+a271);
  a271=(a071*a341);
  a318=(a048*a271);
  a248=(a074*a090);
  a348=(a005*a106);
  a248=(a248+a348);
  a348=(a096*a113);
  a248=(a248+a348);
  a348=(a177*a248);
  a091=(a151*a157);
  a280=(a116*a169);
  a091=(a091+a280);
  a280=(a161*a175);
  a091=(a091+a280);
  a280=(a059*a091);
  a348=(a348+a280);
  a280=(a002*a348);
  a081=(a176*a280);
  a248=(a059*a248);
  a091=(a114*a091);
  a248=(a248+a091);
  a091=(a002*a248);
  a276=(a018*a091);
  a081=(a081+a276);
  a276=(a061*a081);
  a230=(a048*a276);
  a318=(a318+a230);
  a230=(a007*a318);
  a230=(a230-a088);
  a088=(a070*a081);
  a191=(a085*a088);
  a230=(a230-a191);
  a191=(a065*a090);
  a236=(a073*a106);
  a191=(a191+a236);
  a236=(a063*a113);
  a191=(a191+a236);
  a236=(a177*a191);
  a068=(a146*a157);
  a358=(a150*a169);
  a068=(a068+a358);
  a358=(a144*a175);
  a068=(a068+a358);
  a358=(a059*a068);
  a236=(a236+a358);
  a358=(a002*a236);
  a192=(a176*a358);
  a192=(a083-a192);
  a191=(a059*a191);
  a068=(a114*a068);
  a191=(a191+a068);
  a068=(a002*a191);
  a310=(a018*a068);
  a192=(a192-a310);
  a310=(a061*a192);
  a330=(a048*a310);
  a360=(a070*a341);
  a317=(a048*a360);
  a330=(a330-a317);
  a317=(a004*a330);
  a230=(a230-a317);
  a317=(a071*a192);
  a340=(a056*a317);
  a230=(a230+a340);
  a192=(a070*a192);
  a340=(a048*a192);
  a081=(a071*a081);
  a289=(a048*a081);
  a278=(a340-a289);
  a278=(a198*a278);
  a230=(a230+a278);
  a278=(a095*a271);
  a341=(a061*a341);
  a000=(a009*a341);
  a278=(a278-a000);
  a000=(a054*a360);
  a278=(a278+a000);
  a000=(a095*a276);
  a278=(a278+a000);
  a081=(a012*a081);
  a278=(a278-a081);
  a081=(a072*a088);
  a278=(a278+a081);
  a081=(a054*a310);
  a278=(a278-a081);
  a081=(a072*a317);
  a278=(a278-a081);
  a192=(a008*a192);
  a278=(a278+a192);
  a192=(a204*a278);
  a192=(a049*a192);
  a081=(a019*a192);
  a278=(a278/a053);
  a081=(a081-a278);
  a000=(a032*a081);
  a273=(a045*a000);
  a099=(a027*a081);
  a364=(a020*a099);
  a364=(a042*a364);
  a273=(a273+a364);
  a364=(a039*a099);
  a273=(a273+a364);
  a364=(a020*a081);
  a364=(a036*a364);
  a273=(a273+a364);
  a364=(a033*a081);
  a273=(a273+a364);
  a364=(a032*a278);
  a183=(a029*a364);
  a273=(a273+a183);
  a183=(a027*a278);
  a329=(a020*a183);
  a329=(a025*a329);
  a273=(a273+a329);
  a329=(a022*a183);
  a273=(a273+a329);
  a192=(a034*a192);
  a000=(a047*a000);
  a329=(a046*a081);
  a329=(a217*a329);
  a139=(a040*a081);
  a329=(a329+a139);
  a329=(a216*a329);
  a000=(a000+a329);
  a099=(a043*a099);
  a000=(a000+a099);
  a081=(a037*a081);
  a000=(a000+a081);
  a000=(a013*a000);
  a192=(a192+a000);
  a364=(a031*a364);
  a000=(a030*a278);
  a000=(a217*a000);
  a081=(a023*a278);
  a000=(a000+a081);
  a000=(a216*a000);
  a364=(a364+a000);
  a183=(a026*a183);
  a364=(a364+a183);
  a183=(a017*a278);
  a364=(a364+a183);
  a364=(a013*a364);
  a192=(a192+a364);
  a192=(a018*a192);
  a273=(a273+a192);
  a192=(a020*a278);
  a192=(a016*a192);
  a273=(a273+a192);
  a278=(a001*a278);
  a273=(a273+a278);
  a278=(a198*a273);
  a230=(a230+a278);
  a278=(a058*a230);
  a318=(a011*a318);
  a360=(a056*a360);
  a360=(a360+a248);
  a318=(a318-a360);
  a310=(a085*a310);
  a318=(a318+a310);
  a317=(a048*a317);
  a088=(a048*a088);
  a317=(a317-a088);
  a088=(a004*a317);
  a318=(a318-a088);
  a341=(a048*a341);
  a340=(a340-a341);
  a340=(a223*a340);
  a318=(a318+a340);
  a340=(a223*a273);
  a318=(a318+a340);
  a340=(a087*a318);
  a278=(a278+a340);
  a273=(a226*a273);
  a271=(a085*a271);
  a276=(a056*a276);
  a271=(a271+a276);
  a341=(a341+a289);
  a341=(a226*a341);
  a271=(a271+a341);
  a271=(a271+a191);
  a330=(a011*a330);
  a271=(a271+a330);
  a317=(a007*a317);
  a271=(a271+a317);
  a273=(a273-a271);
  a271=(a090*a273);
  a278=(a278+a271);
  a278=(a278/a002);
  if (res[1]!=0) res[1][54]=a278;
  a278=(a102*a230);
  a317=(a104*a318);
  a278=(a278+a317);
  a330=(a106*a273);
  a278=(a278+a330);
  a278=(a278/a002);
  if (res[1]!=0) res[1][55]=a278;
  a278=(a108*a230);
  a330=(a111*a318);
  a330=(a278+a330);
  a191=(a113*a273);
  a330=(a330+a191);
  a330=(a330/a002);
  if (res[1]!=0) res[1][56]=a330;
  a089=(a018*a089);
  a181=(a238*a181);
  a089=(a089+a181);
  a181=(a148*a089);
  a330=(a134*a181);
  a280=(a018*a280);
  a091=(a238*a091);
  a280=(a280+a091);
  a091=(a142*a280);
  a191=(a134*a091);
  a330=(a330+a191);
  a191=(a117*a330);
  a191=(a191-a298);
  a298=(a069*a280);
  a341=(a085*a298);
  a191=(a191-a341);
  a358=(a018*a358);
  a358=(a083-a358);
  a068=(a238*a068);
  a358=(a358-a068);
  a068=(a142*a358);
  a341=(a134*a068);
  a289=(a069*a089);
  a276=(a134*a289);
  a341=(a341-a276);
  a276=(a115*a341);
  a191=(a191-a276);
  a276=(a148*a358);
  a340=(a056*a276);
  a191=(a191+a340);
  a358=(a069*a358);
  a340=(a134*a358);
  a280=(a148*a280);
  a088=(a134*a280);
  a310=(a340-a088);
  a310=(a244*a310);
  a191=(a191+a310);
  a310=(a160*a181);
  a089=(a142*a089);
  a360=(a119*a089);
  a310=(a310-a360);
  a360=(a141*a289);
  a310=(a310+a360);
  a360=(a160*a091);
  a310=(a310+a360);
  a280=(a121*a280);
  a310=(a310-a280);
  a280=(a149*a298);
  a310=(a310+a280);
  a280=(a141*a068);
  a310=(a310-a280);
  a280=(a149*a276);
  a310=(a310-a280);
  a358=(a118*a358);
  a310=(a310+a358);
  a358=(a250*a310);
  a358=(a049*a358);
  a280=(a125*a358);
  a310=(a310/a123);
  a280=(a280-a310);
  a360=(a131*a280);
  a248=(a045*a360);
  a192=(a129*a280);
  a364=(a126*a192);
  a364=(a042*a364);
  a248=(a248+a364);
  a364=(a039*a192);
  a248=(a248+a364);
  a364=(a126*a280);
  a364=(a036*a364);
  a248=(a248+a364);
  a364=(a033*a280);
  a248=(a248+a364);
  a364=(a131*a310);
  a183=(a029*a364);
  a248=(a248+a183);
  a183=(a129*a310);
  a000=(a126*a183);
  a000=(a025*a000);
  a248=(a248+a000);
  a000=(a022*a183);
  a248=(a248+a000);
  a358=(a132*a358);
  a360=(a047*a360);
  a000=(a130*a280);
  a000=(a263*a000);
  a081=(a127*a280);
  a000=(a000+a081);
  a000=(a262*a000);
  a360=(a360+a000);
  a192=(a128*a192);
  a360=(a360+a192);
  a280=(a124*a280);
  a360=(a360+a280);
  a360=(a122*a360);
  a358=(a358+a360);
  a364=(a031*a364);
  a360=(a138*a310);
  a360=(a263*a360);
  a280=(a136*a310);
  a360=(a360+a280);
  a360=(a262*a360);
  a364=(a364+a360);
  a183=(a137*a183);
  a364=(a364+a183);
  a183=(a135*a310);
  a364=(a364+a183);
  a364=(a122*a364);
  a358=(a358+a364);
  a358=(a018*a358);
  a248=(a248+a358);
  a358=(a126*a310);
  a358=(a016*a358);
  a248=(a248+a358);
  a310=(a001*a310);
  a248=(a248+a310);
  a310=(a244*a248);
  a191=(a191+a310);
  a310=(a153*a191);
  a330=(a120*a330);
  a289=(a056*a289);
  a348=(a348+a289);
  a330=(a330-a348);
  a068=(a085*a068);
  a330=(a330+a068);
  a276=(a134*a276);
  a298=(a134*a298);
  a276=(a276-a298);
  a298=(a115*a276);
  a330=(a330-a298);
  a089=(a134*a089);
  a340=(a340-a089);
  a340=(a268*a340);
  a330=(a330+a340);
  a340=(a268*a248);
  a330=(a330+a340);
  a340=(a156*a330);
  a310=(a310+a340);
  a248=(a270*a248);
  a181=(a085*a181);
  a236=(a236+a181);
  a091=(a056*a091);
  a236=(a236+a091);
  a089=(a089+a088);
  a089=(a270*a089);
  a236=(a236+a089);
  a341=(a120*a341);
  a236=(a236+a341);
  a276=(a117*a276);
  a236=(a236+a276);
  a248=(a248-a236);
  a236=(a157*a248);
  a310=(a310+a236);
  a310=(a310/a002);
  if (res[1]!=0) res[1][57]=a310;
  a310=(a166*a191);
  a276=(a167*a330);
  a310=(a310+a276);
  a341=(a169*a248);
  a310=(a310+a341);
  a310=(a310/a002);
  if (res[1]!=0) res[1][58]=a310;
  a310=(a171*a191);
  a341=(a173*a330);
  a341=(a310+a341);
  a089=(a175*a248);
  a341=(a341+a089);
  a341=(a341/a002);
  if (res[1]!=0) res[1][59]=a341;
  a341=(a152*a191);
  a291=(a291+a341);
  a341=(a155*a330);
  a291=(a291+a341);
  a291=(a291+a236);
  a236=(a057*a230);
  a291=(a291+a236);
  a236=(a086*a318);
  a291=(a291+a236);
  a291=(a291+a271);
  a291=(-a291);
  if (res[1]!=0) res[1][60]=a291;
  a191=(a165*a191);
  a293=(a293+a191);
  a293=(a293+a276);
  a276=(a168*a248);
  a293=(a293+a276);
  a230=(a101*a230);
  a293=(a293+a230);
  a293=(a293+a317);
  a317=(a105*a273);
  a293=(a293+a317);
  a293=(-a293);
  if (res[1]!=0) res[1][61]=a293;
  a246=(a246+a310);
  a330=(a172*a330);
  a246=(a246+a330);
  a248=(a174*a248);
  a246=(a246+a248);
  a246=(a246+a278);
  a318=(a110*a318);
  a246=(a246+a318);
  a273=(a112*a273);
  a246=(a246+a273);
  a246=(-a246);
  if (res[1]!=0) res[1][62]=a246;
  a246=(a074*a087);
  a273=(a005*a104);
  a246=(a246+a273);
  a273=(a096*a111);
  a246=(a246+a273);
  a273=(a177*a246);
  a318=(a151*a156);
  a278=(a116*a167);
  a318=(a318+a278);
  a278=(a161*a173);
  a318=(a318+a278);
  a278=(a059*a318);
  a273=(a273+a278);
  a278=(a002*a273);
  a248=(a176*a278);
  a248=(a083-a248);
  a246=(a059*a246);
  a318=(a114*a318);
  a246=(a246+a318);
  a318=(a002*a246);
  a330=(a018*a318);
  a248=(a248-a330);
  a330=(a070*a248);
  a310=(a085*a330);
  a293=(a064*a087);
  a317=(a097*a104);
  a293=(a293+a317);
  a317=(a103*a111);
  a293=(a293+a317);
  a317=(a059*a293);
  a230=(a145*a156);
  a276=(a162*a167);
  a230=(a230+a276);
  a276=(a170*a173);
  a230=(a230+a276);
  a276=(a114*a230);
  a317=(a317+a276);
  a276=(a061*a248);
  a191=(a048*a276);
  a293=(a177*a293);
  a230=(a059*a230);
  a293=(a293+a230);
  a230=(a002*a293);
  a291=(a176*a230);
  a271=(a002*a317);
  a236=(a018*a271);
  a291=(a291+a236);
  a236=(a071*a291);
  a341=(a048*a236);
  a191=(a191-a341);
  a341=(a007*a191);
  a317=(a317+a341);
  a310=(a310-a317);
  a317=(a070*a291);
  a341=(a048*a317);
  a089=(a065*a087);
  a088=(a073*a104);
  a089=(a089+a088);
  a088=(a063*a111);
  a089=(a089+a088);
  a088=(a177*a089);
  a091=(a146*a156);
  a181=(a150*a167);
  a091=(a091+a181);
  a181=(a144*a173);
  a091=(a091+a181);
  a181=(a059*a091);
  a088=(a088+a181);
  a181=(a002*a088);
  a340=(a176*a181);
  a089=(a059*a089);
  a091=(a114*a091);
  a089=(a089+a091);
  a091=(a002*a089);
  a298=(a018*a091);
  a340=(a340+a298);
  a298=(a061*a340);
  a068=(a048*a298);
  a341=(a341+a068);
  a068=(a004*a341);
  a310=(a310+a068);
  a068=(a071*a340);
  a348=(a056*a068);
  a310=(a310-a348);
  a248=(a071*a248);
  a348=(a048*a248);
  a340=(a070*a340);
  a289=(a048*a340);
  a358=(a348-a289);
  a358=(a198*a358);
  a310=(a310+a358);
  a358=(a095*a236);
  a291=(a061*a291);
  a364=(a009*a291);
  a358=(a358-a364);
  a364=(a054*a317);
  a358=(a358+a364);
  a364=(a095*a276);
  a358=(a358-a364);
  a248=(a012*a248);
  a358=(a358+a248);
  a248=(a072*a330);
  a358=(a358-a248);
  a248=(a054*a298);
  a358=(a358+a248);
  a248=(a072*a068);
  a358=(a358+a248);
  a340=(a008*a340);
  a358=(a358-a340);
  a340=(a204*a358);
  a340=(a049*a340);
  a248=(a019*a340);
  a358=(a358/a053);
  a248=(a248-a358);
  a364=(a032*a248);
  a183=(a045*a364);
  a360=(a027*a248);
  a280=(a020*a360);
  a280=(a042*a280);
  a183=(a183+a280);
  a280=(a039*a360);
  a183=(a183+a280);
  a280=(a020*a248);
  a280=(a036*a280);
  a183=(a183+a280);
  a280=(a033*a248);
  a183=(a183+a280);
  a280=(a032*a358);
  a192=(a029*a280);
  a183=(a183+a192);
  a192=(a027*a358);
  a000=(a020*a192);
  a000=(a025*a000);
  a183=(a183+a000);
  a000=(a022*a192);
  a183=(a183+a000);
  a340=(a034*a340);
  a364=(a047*a364);
  a000=(a046*a248);
  a000=(a217*a000);
  a081=(a040*a248);
  a000=(a000+a081);
  a000=(a216*a000);
  a364=(a364+a000);
  a360=(a043*a360);
  a364=(a364+a360);
  a248=(a037*a248);
  a364=(a364+a248);
  a364=(a013*a364);
  a340=(a340+a364);
  a280=(a031*a280);
  a364=(a030*a358);
  a364=(a217*a364);
  a248=(a023*a358);
  a364=(a364+a248);
  a364=(a216*a364);
  a280=(a280+a364);
  a192=(a026*a192);
  a280=(a280+a192);
  a192=(a017*a358);
  a280=(a280+a192);
  a280=(a013*a280);
  a340=(a340+a280);
  a340=(a018*a340);
  a183=(a183+a340);
  a340=(a020*a358);
  a340=(a016*a340);
  a183=(a183+a340);
  a358=(a001*a358);
  a183=(a183+a358);
  a358=(a198*a183);
  a310=(a310+a358);
  a358=(a058*a310);
  a340=(a223*a183);
  a317=(a056*a317);
  a317=(a317+a246);
  a191=(a011*a191);
  a317=(a317+a191);
  a298=(a085*a298);
  a317=(a317+a298);
  a330=(a048*a330);
  a068=(a048*a068);
  a330=(a330-a068);
  a068=(a004*a330);
  a317=(a317+a068);
  a291=(a048*a291);
  a289=(a291+a289);
  a289=(a223*a289);
  a317=(a317+a289);
  a340=(a340-a317);
  a317=(a087*a340);
  a358=(a358+a317);
  a276=(a056*a276);
  a236=(a085*a236);
  a276=(a276-a236);
  a348=(a348-a291);
  a348=(a226*a348);
  a276=(a276+a348);
  a276=(a276-a089);
  a341=(a011*a341);
  a276=(a276+a341);
  a330=(a007*a330);
  a276=(a276-a330);
  a183=(a226*a183);
  a276=(a276+a183);
  a183=(a090*a276);
  a358=(a358+a183);
  a358=(a358/a002);
  if (res[1]!=0) res[1][63]=a358;
  a358=(a102*a310);
  a330=(a104*a340);
  a358=(a358+a330);
  a341=(a106*a276);
  a358=(a358+a341);
  a358=(a358/a002);
  if (res[1]!=0) res[1][64]=a358;
  a358=(a108*a310);
  a341=(a111*a340);
  a341=(a358+a341);
  a089=(a113*a276);
  a341=(a341+a089);
  a341=(a341/a002);
  if (res[1]!=0) res[1][65]=a341;
  a278=(a018*a278);
  a278=(a083-a278);
  a318=(a238*a318);
  a278=(a278-a318);
  a318=(a069*a278);
  a341=(a085*a318);
  a089=(a142*a278);
  a348=(a134*a089);
  a230=(a018*a230);
  a271=(a238*a271);
  a230=(a230+a271);
  a271=(a148*a230);
  a291=(a134*a271);
  a348=(a348-a291);
  a291=(a117*a348);
  a293=(a293+a291);
  a341=(a341-a293);
  a293=(a069*a230);
  a291=(a134*a293);
  a181=(a018*a181);
  a091=(a238*a091);
  a181=(a181+a091);
  a091=(a142*a181);
  a236=(a134*a091);
  a291=(a291+a236);
  a236=(a115*a291);
  a341=(a341+a236);
  a236=(a148*a181);
  a317=(a056*a236);
  a341=(a341-a317);
  a278=(a148*a278);
  a317=(a134*a278);
  a181=(a069*a181);
  a289=(a134*a181);
  a068=(a317-a289);
  a068=(a244*a068);
  a341=(a341+a068);
  a068=(a160*a271);
  a230=(a142*a230);
  a298=(a119*a230);
  a068=(a068-a298);
  a298=(a141*a293);
  a068=(a068+a298);
  a298=(a160*a089);
  a068=(a068-a298);
  a278=(a121*a278);
  a068=(a068+a278);
  a278=(a149*a318);
  a068=(a068-a278);
  a278=(a141*a091);
  a068=(a068+a278);
  a278=(a149*a236);
  a068=(a068+a278);
  a181=(a118*a181);
  a068=(a068-a181);
  a181=(a250*a068);
  a181=(a049*a181);
  a278=(a125*a181);
  a068=(a068/a123);
  a278=(a278-a068);
  a298=(a131*a278);
  a191=(a045*a298);
  a246=(a129*a278);
  a280=(a126*a246);
  a280=(a042*a280);
  a191=(a191+a280);
  a280=(a039*a246);
  a191=(a191+a280);
  a280=(a126*a278);
  a280=(a036*a280);
  a191=(a191+a280);
  a280=(a033*a278);
  a191=(a191+a280);
  a280=(a131*a068);
  a192=(a029*a280);
  a191=(a191+a192);
  a192=(a129*a068);
  a364=(a126*a192);
  a364=(a025*a364);
  a191=(a191+a364);
  a364=(a022*a192);
  a191=(a191+a364);
  a181=(a132*a181);
  a298=(a047*a298);
  a364=(a130*a278);
  a364=(a263*a364);
  a248=(a127*a278);
  a364=(a364+a248);
  a364=(a262*a364);
  a298=(a298+a364);
  a246=(a128*a246);
  a298=(a298+a246);
  a278=(a124*a278);
  a298=(a298+a278);
  a298=(a122*a298);
  a181=(a181+a298);
  a280=(a031*a280);
  a298=(a138*a068);
  a298=(a263*a298);
  a278=(a136*a068);
  a298=(a298+a278);
  a298=(a262*a298);
  a280=(a280+a298);
  a192=(a137*a192);
  a280=(a280+a192);
  a192=(a135*a068);
  a280=(a280+a192);
  a280=(a122*a280);
  a181=(a181+a280);
  a181=(a018*a181);
  a191=(a191+a181);
  a181=(a126*a068);
  a181=(a016*a181);
  a191=(a191+a181);
  a068=(a001*a068);
  a191=(a191+a068);
  a068=(a244*a191);
  a341=(a341+a068);
  a068=(a153*a341);
  a181=(a268*a191);
  a293=(a056*a293);
  a273=(a273+a293);
  a348=(a120*a348);
  a273=(a273+a348);
  a091=(a085*a091);
  a273=(a273+a091);
  a318=(a134*a318);
  a236=(a134*a236);
  a318=(a318-a236);
  a236=(a115*a318);
  a273=(a273+a236);
  a230=(a134*a230);
  a289=(a230+a289);
  a289=(a268*a289);
  a273=(a273+a289);
  a181=(a181-a273);
  a273=(a156*a181);
  a068=(a068+a273);
  a089=(a056*a089);
  a271=(a085*a271);
  a088=(a088+a271);
  a089=(a089-a088);
  a317=(a317-a230);
  a317=(a270*a317);
  a089=(a089+a317);
  a291=(a120*a291);
  a089=(a089+a291);
  a318=(a117*a318);
  a089=(a089-a318);
  a191=(a270*a191);
  a089=(a089+a191);
  a191=(a157*a089);
  a068=(a068+a191);
  a068=(a068/a002);
  if (res[1]!=0) res[1][66]=a068;
  a068=(a166*a341);
  a318=(a167*a181);
  a068=(a068+a318);
  a291=(a169*a089);
  a068=(a068+a291);
  a068=(a068/a002);
  if (res[1]!=0) res[1][67]=a068;
  a068=(a171*a341);
  a291=(a173*a181);
  a291=(a068+a291);
  a317=(a175*a089);
  a291=(a291+a317);
  a291=(a291/a002);
  if (res[1]!=0) res[1][68]=a291;
  a291=(a152*a341);
  a288=(a288+a291);
  a291=(a155*a181);
  a288=(a288+a291);
  a288=(a288+a191);
  a191=(a057*a310);
  a288=(a288+a191);
  a191=(a086*a340);
  a288=(a288+a191);
  a288=(a288+a183);
  a288=(-a288);
  if (res[1]!=0) res[1][69]=a288;
  a341=(a165*a341);
  a274=(a274+a341);
  a274=(a274+a318);
  a318=(a168*a089);
  a274=(a274+a318);
  a310=(a101*a310);
  a274=(a274+a310);
  a274=(a274+a330);
  a330=(a105*a276);
  a274=(a274+a330);
  a274=(-a274);
  if (res[1]!=0) res[1][70]=a274;
  a084=(a084+a068);
  a181=(a172*a181);
  a084=(a084+a181);
  a089=(a174*a089);
  a084=(a084+a089);
  a084=(a084+a358);
  a340=(a110*a340);
  a084=(a084+a340);
  a276=(a112*a276);
  a084=(a084+a276);
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
  a276=(a095*a084);
  a009=(a009-a276);
  a162=(a070*a162);
  a276=(a054*a162);
  a009=(a009-a276);
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
  a145=(a238*a145);
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
  a151=(a238*a151);
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
  a238=(a238*a114);
  a144=(a144+a238);
  a142=(a142*a144);
  a141=(a141*a142);
  a119=(a119+a141);
  a148=(a148*a144);
  a149=(a149*a148);
  a119=(a119+a149);
  a069=(a069*a144);
  a118=(a118*a069);
  a119=(a119-a118);
  a250=(a250*a119);
  a049=(a049*a250);
  a125=(a125*a049);
  a119=(a119/a123);
  a125=(a125-a119);
  a123=(a131*a125);
  a045=(a045*a123);
  a250=(a129*a125);
  a118=(a126*a250);
  a042=(a042*a118);
  a045=(a045+a042);
  a039=(a039*a250);
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
  a130=(a263*a130);
  a127=(a127*a125);
  a130=(a130+a127);
  a130=(a262*a130);
  a047=(a047+a130);
  a128=(a128*a250);
  a047=(a047+a128);
  a124=(a124*a125);
  a047=(a047+a124);
  a047=(a122*a047);
  a132=(a132+a047);
  a031=(a031*a131);
  a138=(a138*a119);
  a263=(a263*a138);
  a136=(a136*a119);
  a263=(a263+a136);
  a262=(a262*a263);
  a031=(a031+a262);
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
  a001=(a244*a045);
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
  a244=(a244*a126);
  a103=(a103+a244);
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
  a069=(a268*a069);
  a083=(a083+a069);
  a268=(a268*a045);
  a083=(a083+a268);
  a156=(a156*a083);
  a153=(a153+a156);
  a085=(a085*a170);
  a085=(a085-a177);
  a056=(a056*a151);
  a085=(a085-a056);
  a134=(a134-a160);
  a134=(a270*a134);
  a085=(a085+a134);
  a120=(a120*a016);
  a085=(a085-a120);
  a117=(a117*a161);
  a085=(a085+a117);
  a270=(a270*a045);
  a085=(a085+a270);
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
  a235=(a235+a152);
  a155=(a155*a083);
  a235=(a235+a155);
  a235=(a235+a157);
  a057=(a057*a009);
  a235=(a235+a057);
  a086=(a086*a162);
  a235=(a235+a086);
  a235=(a235+a090);
  a235=(-a235);
  if (res[1]!=0) res[1][78]=a235;
  a165=(a165*a001);
  a287=(a287+a165);
  a287=(a287+a167);
  a168=(a168*a085);
  a287=(a287+a168);
  a101=(a101*a009);
  a287=(a287+a101);
  a287=(a287+a104);
  a105=(a105*a084);
  a287=(a287+a105);
  a287=(-a287);
  if (res[1]!=0) res[1][79]=a287;
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
  casadi_real a324, a325, a326, a327, a328, a329, a330, a331, a332, a333, a334, a335;
  casadi_real a336, a337, a338, a339, a340, a341, a342, a343, a344, a345, a346, a347;
  casadi_real a348, a349, a350, a351, a352, a353, a354, a355, a356, a357, a358, a359;
  casadi_real a360, a361, a362, a363, a364, a365, a366, a367, a368, a369, a370, a371;
  casadi_real a372, a373, a374, a375, a376, a377, a378, a379, a380, a381, a382, a383;
  casadi_real a384, a385, a386, a387, a388, a389, a390, a391, a392, a393, a394, a395;
  casadi_real a396, a397, a398, a399, a400, a401, a402;
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
  a169=(2.*a181);
  a193=(a004*a001);
  a169=(a169*a193);
  a043=(a043-a019);
  a043=(a179+a043);
  a019=(a158*a037);
  a043=(a043/a019);
  a188=(a043*a067);
  a183=(a000*a009);
  a184=(a188-a183);
  a165=(a001*a144);
  a165=(a000*a165);
  a189=(a184*a165);
  a151=(a043*a063);
  a160=(a187*a013);
  a196=(a151-a160);
  a155=(a001*a180);
  a155=(a000*a155);
  a190=(a196*a155);
  a189=(a189+a190);
  a190=(a043*a010);
  a190=(a003-a190);
  a157=(a001*a171);
  a157=(a000*a157);
  a194=(a190*a157);
  a189=(a189+a194);
  a169=(a169-a189);
  a169=(a169/a002);
  a189=(a146*a169);
  a194=(a038*a006);
  a178=(a124*a061);
  a192=(a194+a178);
  a148=(a148-a139);
  a139=(a148*a041);
  a150=(a124*a007);
  a150=(a003-a150);
  a191=(a150*a117);
  a139=(a139+a191);
  a191=(a192*a123);
  a139=(a139+a191);
  a191=(2.*a139);
  a195=1.2500000000000000e+00;
  a195=(a195*a001);
  a191=(a191*a195);
  a136=(a043*a061);
  a185=(a187*a006);
  a197=(a136-a185);
  a198=(a197*a165);
  a199=(a043*a007);
  a199=(a003-a199);
  a200=(a199*a155);
  a198=(a198+a200);
  a200=(a000*a013);
  a201=(a151-a200);
  a202=(a201*a157);
  a198=(a198+a202);
  a191=(a191-a198);
  a191=(a191/a002);
  a198=(a192*a191);
  a189=(a189+a198);
  a198=(a124*a011);
  a198=(a003-a198);
  a140=(a140+a162);
  a162=(a140*a041);
  a178=(a178-a194);
  a194=(a178*a117);
  a162=(a162+a194);
  a194=(a198*a123);
  a162=(a162+a194);
  a194=(2.*a162);
  a202=1.5000000000000000e+00;
  a202=(a202*a001);
  a194=(a194*a202);
  a203=(a043*a011);
  a203=(a003-a203);
  a204=(a203*a165);
  a205=(a000*a006);
  a206=(a136-a205);
  a207=(a206*a155);
  a204=(a204+a207);
  a207=(a187*a009);
  a208=(a188-a207);
  a209=(a208*a157);
  a204=(a204+a209);
  a194=(a194-a204);
  a194=(a194/a002);
  a204=(a198*a194);
  a189=(a189+a204);
  a204=(a149*a189);
  a209=-3.2320508075688776e+00;
  a210=(a090*a099);
  a210=(a089+a210);
  a210=(a004*a210);
  a211=(a210*a108);
  a212=(a091*a073);
  a213=(a211-a212);
  a214=(a210*a074);
  a214=(a003-a214);
  a215=(a214*a114);
  a216=(a091*a077);
  a217=(a210*a104);
  a218=(a216+a217);
  a219=(a218*a119);
  a215=(a215+a219);
  a219=(a213*a113);
  a215=(a215+a219);
  a219=(2.*a215);
  a219=(a219*a193);
  a094=(a094-a081);
  a179=(a179+a094);
  a094=(a158*a090);
  a179=(a179/a094);
  a081=(a179*a108);
  a220=(a000*a073);
  a221=(a081-a220);
  a222=(a221*a165);
  a219=(a219-a222);
  a222=(a179*a104);
  a223=(a187*a077);
  a224=(a222-a223);
  a225=(a224*a155);
  a219=(a219-a225);
  a225=(a179*a074);
  a225=(a003-a225);
  a226=(a225*a157);
  a219=(a219-a226);
  a219=(a219/a002);
  a226=(a213*a219);
  a227=(a091*a070);
  a228=(a210*a103);
  a229=(a227+a228);
  a217=(a217-a216);
  a216=(a217*a114);
  a230=(a210*a071);
  a230=(a003-a230);
  a231=(a230*a119);
  a216=(a216+a231);
  a231=(a229*a113);
  a216=(a216+a231);
  a231=(2.*a216);
  a231=(a231*a195);
  a232=(a179*a103);
  a233=(a187*a070);
  a234=(a232-a233);
  a235=(a234*a165);
  a231=(a231-a235);
  a235=(a179*a071);
  a235=(a003-a235);
  a236=(a235*a155);
  a231=(a231-a236);
  a236=(a000*a077);
  a237=(a222-a236);
  a238=(a237*a157);
  a231=(a231-a238);
  a231=(a231/a002);
  a238=(a229*a231);
  a226=(a226+a238);
  a238=(a210*a075);
  a238=(a003-a238);
  a212=(a212+a211);
  a211=(a212*a114);
  a228=(a228-a227);
  a227=(a228*a119);
  a211=(a211+a227);
  a227=(a238*a113);
  a211=(a211+a227);
  a227=(2.*a211);
  a227=(a227*a202);
  a239=(a179*a075);
  a003=(a003-a239);
  a239=(a003*a165);
  a227=(a227-a239);
  a239=(a000*a070);
  a240=(a232-a239);
  a241=(a240*a155);
  a227=(a227-a241);
  a241=(a187*a073);
  a242=(a081-a241);
  a243=(a242*a157);
  a227=(a227-a243);
  a227=(a227/a002);
  a243=(a238*a227);
  a226=(a226+a243);
  a243=(a209*a226);
  a204=(a204+a243);
  a243=5.3867513459481287e-01;
  a244=2.3205080756887719e-01;
  a189=(a244*a189);
  a226=(a149*a226);
  a189=(a189+a226);
  a226=(a001*a189);
  a245=(a243*a226);
  a245=(a165+a245);
  a246=(a001*a204);
  a247=(a004*a246);
  a245=(a245+a247);
  a247=(a139*a245);
  a248=(a043*a247);
  a249=(a145*a169);
  a250=(a150*a191);
  a249=(a249+a250);
  a250=(a178*a194);
  a249=(a249+a250);
  a250=(a244*a249);
  a251=(a218*a219);
  a252=(a230*a231);
  a251=(a251+a252);
  a252=(a228*a227);
  a251=(a251+a252);
  a252=(a149*a251);
  a250=(a250+a252);
  a252=(a001*a250);
  a253=(a243*a252);
  a253=(a155+a253);
  a249=(a149*a249);
  a251=(a209*a251);
  a249=(a249+a251);
  a251=(a001*a249);
  a254=(a004*a251);
  a253=(a253+a254);
  a254=(a162*a253);
  a255=(a043*a254);
  a248=(a248+a255);
  a255=(a009*a248);
  a255=(a204-a255);
  a256=(a181*a253);
  a257=(a187*a256);
  a255=(a255+a257);
  a257=(a181*a245);
  a258=(a043*a257);
  a259=(a172*a169);
  a260=(a148*a191);
  a259=(a259+a260);
  a260=(a140*a194);
  a259=(a259+a260);
  a260=(a244*a259);
  a261=(a214*a219);
  a262=(a217*a231);
  a261=(a261+a262);
  a262=(a212*a227);
  a261=(a261+a262);
  a262=(a149*a261);
  a260=(a260+a262);
  a262=(a001*a260);
  a263=(a243*a262);
  a263=(a157+a263);
  a259=(a149*a259);
  a261=(a209*a261);
  a259=(a259+a261);
  a261=(a001*a259);
  a264=(a004*a261);
  a263=(a263+a264);
  a264=(a162*a263);
  a265=(a043*a264);
  a258=(a258+a265);
  a265=(a006*a258);
  a255=(a255-a265);
  a265=(a139*a263);
  a266=(a000*a265);
  a255=(a255+a266);
  a266=(2.*a013);
  a267=(a139*a253);
  a268=(a043*a267);
  a269=(a181*a263);
  a270=(a043*a269);
  a271=(a268+a270);
  a272=(a266*a271);
  a255=(a255+a272);
  a272=(a043/a019);
  a273=(a162*a245);
  a274=(a011*a273);
  a275=(a061*a247);
  a274=(a274-a275);
  a275=(a067*a257);
  a274=(a274-a275);
  a275=(a061*a254);
  a274=(a274-a275);
  a275=(a007*a267);
  a274=(a274+a275);
  a275=(a063*a256);
  a274=(a274-a275);
  a275=(a067*a264);
  a274=(a274-a275);
  a275=(a063*a265);
  a274=(a274-a275);
  a275=(a010*a269);
  a274=(a274+a275);
  a275=(a272*a274);
  a275=(a158*a275);
  a276=(a016*a275);
  a277=(a274/a019);
  a276=(a276-a277);
  a278=(a035*a276);
  a279=(a032*a278);
  a280=(a030*a276);
  a281=(a023*a280);
  a281=(a028*a281);
  a279=(a279+a281);
  a281=(a025*a280);
  a279=(a279+a281);
  a281=(a023*a276);
  a281=(a021*a281);
  a279=(a279+a281);
  a281=(a018*a276);
  a279=(a279+a281);
  a281=(a035*a277);
  a282=(a054*a281);
  a279=(a279+a282);
  a282=(a030*a277);
  a283=(a023*a282);
  a283=(a051*a283);
  a279=(a279+a283);
  a283=(a048*a282);
  a279=(a279+a283);
  a283=(a036*a275);
  a015=(a000*a015);
  a278=(a034*a278);
  a284=(2.*a023);
  a285=(2.*a030);
  a286=(a033*a276);
  a287=(a285*a286);
  a288=(a026*a276);
  a287=(a287+a288);
  a288=(a284*a287);
  a278=(a278+a288);
  a288=(a029*a280);
  a278=(a278+a288);
  a288=(a022*a276);
  a278=(a278+a288);
  a288=(a015*a278);
  a283=(a283+a288);
  a281=(a056*a281);
  a288=(a055*a277);
  a289=(a285*a288);
  a290=(a049*a277);
  a289=(a289+a290);
  a290=(a284*a289);
  a281=(a281+a290);
  a290=(a052*a282);
  a281=(a281+a290);
  a290=(a046*a277);
  a281=(a281+a290);
  a290=(a015*a281);
  a283=(a283+a290);
  a283=(a004*a283);
  a279=(a279+a283);
  a283=(a023*a277);
  a283=(a045*a283);
  a279=(a279+a283);
  a283=(a042*a277);
  a279=(a279+a283);
  a283=(a266*a279);
  a255=(a255+a283);
  a283=(2.*a006);
  a290=(a283*a005);
  a291=(2.*a009);
  a292=(a291*a008);
  a293=(a290+a292);
  a294=(a266*a012);
  a295=(a293+a294);
  a296=(a042*a295);
  a297=(a045*a295);
  a298=(a023*a297);
  a299=(a004*a295);
  a300=(a015*a299);
  a301=(a046*a300);
  a298=(a298+a301);
  a296=(a296+a298);
  a298=(a048*a295);
  a301=(a051*a295);
  a302=(a023*a301);
  a303=(a052*a300);
  a302=(a302+a303);
  a298=(a298+a302);
  a302=(a030*a298);
  a303=(a284*a300);
  a304=(a049*a303);
  a302=(a302+a304);
  a296=(a296+a302);
  a302=(a054*a295);
  a304=(a056*a300);
  a302=(a302+a304);
  a304=(a035*a302);
  a305=(a285*a303);
  a306=(a055*a305);
  a304=(a304+a306);
  a296=(a296+a304);
  a304=(a018*a295);
  a306=(a021*a295);
  a307=(a023*a306);
  a308=(a022*a300);
  a307=(a307+a308);
  a304=(a304+a307);
  a307=(a025*a295);
  a308=(a028*a295);
  a309=(a023*a308);
  a310=(a029*a300);
  a309=(a309+a310);
  a307=(a307+a309);
  a309=(a030*a307);
  a310=(a026*a303);
  a309=(a309+a310);
  a304=(a304+a309);
  a309=(a032*a295);
  a310=(a034*a300);
  a309=(a309+a310);
  a310=(a035*a309);
  a311=(a033*a305);
  a310=(a310+a311);
  a304=(a304+a310);
  a310=(a296-a304);
  a310=(a310/a019);
  a311=(a036*a299);
  a312=(a016*a304);
  a311=(a311+a312);
  a312=(a158*a311);
  a313=(a272*a312);
  a310=(a310+a313);
  a313=(a067*a310);
  a314=(a013*a005);
  a315=(a006*a012);
  a314=(a314+a315);
  a315=(a043*a314);
  a313=(a313+a315);
  a315=(a000*a008);
  a316=(a313-a315);
  a317=(a255*a316);
  a318=(a037*a296);
  a319=(a057*a311);
  a318=(a318-a319);
  a318=(a304+a318);
  a318=(a004*a318);
  a319=(a067*a318);
  a320=(a124*a314);
  a319=(a319+a320);
  a320=(a038*a008);
  a321=(2.*a037);
  a321=(a321*a311);
  a321=(a000*a321);
  a322=(a009*a321);
  a320=(a320-a322);
  a322=(a319-a320);
  a323=(a169*a322);
  a324=(a038*a012);
  a325=(a013*a321);
  a324=(a324-a325);
  a325=(a063*a318);
  a326=(a009*a005);
  a327=(a006*a008);
  a326=(a326+a327);
  a327=(a124*a326);
  a325=(a325+a327);
  a327=(a324+a325);
  a328=(a117*a327);
  a329=(a010*a318);
  a292=(a292+a294);
  a330=(a124*a292);
  a329=(a329+a330);
  a330=(a041*a329);
  a328=(a328-a330);
  a322=(a123*a322);
  a328=(a328+a322);
  a322=(2.*a328);
  a322=(a193*a322);
  a330=(a000*a181);
  a322=(a322+a330);
  a316=(a165*a316);
  a330=(a000*a144);
  a331=(a184*a330);
  a316=(a316+a331);
  a331=(a063*a310);
  a332=(a043*a326);
  a331=(a331+a332);
  a332=(a187*a012);
  a333=(a331-a332);
  a334=(a155*a333);
  a335=(a000*a180);
  a336=(a196*a335);
  a334=(a334+a336);
  a316=(a316+a334);
  a334=(a000*a171);
  a336=(a190*a334);
  a337=(a010*a310);
  a338=(a043*a292);
  a337=(a337+a338);
  a338=(a157*a337);
  a336=(a336-a338);
  a316=(a316+a336);
  a322=(a322-a316);
  a322=(a322/a002);
  a316=(a169/a002);
  a316=(a000*a316);
  a322=(a322-a316);
  a146=(a146*a322);
  a323=(a323+a146);
  a146=(a038*a005);
  a316=(a006*a321);
  a146=(a146-a316);
  a316=(a061*a318);
  a336=(a013*a008);
  a338=(a009*a012);
  a336=(a336+a338);
  a338=(a124*a336);
  a316=(a316+a338);
  a338=(a146+a316);
  a339=(a191*a338);
  a325=(a325-a324);
  a324=(a041*a325);
  a340=(a007*a318);
  a294=(a294+a290);
  a290=(a124*a294);
  a340=(a340+a290);
  a290=(a117*a340);
  a324=(a324-a290);
  a338=(a123*a338);
  a324=(a324+a338);
  a338=(2.*a324);
  a338=(a195*a338);
  a290=2.5000000000000000e+00;
  a341=(a290*a139);
  a338=(a338+a341);
  a341=(a061*a310);
  a342=(a043*a336);
  a341=(a341+a342);
  a342=(a187*a005);
  a343=(a341-a342);
  a344=(a165*a343);
  a345=(a197*a330);
  a344=(a344+a345);
  a345=(a199*a335);
  a346=(a007*a310);
  a347=(a043*a294);
  a346=(a346+a347);
  a347=(a155*a346);
  a345=(a345-a347);
  a344=(a344+a345);
  a345=(a000*a012);
  a347=(a331-a345);
  a348=(a157*a347);
  a349=(a201*a334);
  a348=(a348+a349);
  a344=(a344+a348);
  a338=(a338-a344);
  a338=(a338/a002);
  a344=(a191/a002);
  a344=(a000*a344);
  a338=(a338-a344);
  a192=(a192*a338);
  a339=(a339+a192);
  a323=(a323+a339);
  a320=(a320+a319);
  a041=(a041*a320);
  a316=(a316-a146);
  a117=(a117*a316);
  a041=(a041+a117);
  a318=(a011*a318);
  a124=(a124*a293);
  a318=(a318+a124);
  a123=(a123*a318);
  a041=(a041-a123);
  a123=(2.*a041);
  a123=(a202*a123);
  a124=3.;
  a117=(a124*a162);
  a123=(a123+a117);
  a117=(a203*a330);
  a146=(a011*a310);
  a319=(a043*a293);
  a146=(a146+a319);
  a319=(a165*a146);
  a117=(a117-a319);
  a319=(a000*a005);
  a339=(a341-a319);
  a192=(a155*a339);
  a344=(a206*a335);
  a192=(a192+a344);
  a117=(a117+a192);
  a192=(a187*a008);
  a344=(a313-a192);
  a348=(a157*a344);
  a349=(a208*a334);
  a348=(a348+a349);
  a117=(a117+a348);
  a123=(a123-a117);
  a123=(a123/a002);
  a117=(a194/a002);
  a117=(a000*a117);
  a123=(a123-a117);
  a198=(a198*a123);
  a318=(a194*a318);
  a198=(a198-a318);
  a323=(a323+a198);
  a198=(a149*a323);
  a318=(2.*a070);
  a117=(a318*a069);
  a348=(2.*a073);
  a349=(a348*a072);
  a350=(a117+a349);
  a351=(2.*a077);
  a352=(a351*a076);
  a353=(a350+a352);
  a354=(a018*a353);
  a355=(a021*a353);
  a356=(a083*a355);
  a079=(a000*a079);
  a357=(a004*a353);
  a358=(a079*a357);
  a359=(a082*a358);
  a356=(a356+a359);
  a354=(a354+a356);
  a356=(a025*a353);
  a359=(a028*a353);
  a360=(a083*a359);
  a361=(a085*a358);
  a360=(a360+a361);
  a356=(a356+a360);
  a360=(a086*a356);
  a361=(2.*a083);
  a362=(a361*a358);
  a363=(a084*a362);
  a360=(a360+a363);
  a354=(a354+a360);
  a360=(a032*a353);
  a363=(a034*a358);
  a360=(a360+a363);
  a363=(a088*a360);
  a364=(2.*a086);
  a365=(a364*a362);
  a366=(a087*a365);
  a363=(a363+a366);
  a354=(a354+a363);
  a363=(a042*a353);
  a366=(a045*a353);
  a367=(a083*a366);
  a368=(a095*a358);
  a367=(a367+a368);
  a363=(a363+a367);
  a367=(a048*a353);
  a368=(a051*a353);
  a369=(a083*a368);
  a370=(a097*a358);
  a369=(a369+a370);
  a367=(a367+a369);
  a369=(a086*a367);
  a370=(a096*a362);
  a369=(a369+a370);
  a363=(a363+a369);
  a369=(a054*a353);
  a370=(a056*a358);
  a369=(a369+a370);
  a370=(a088*a369);
  a371=(a098*a365);
  a370=(a370+a371);
  a363=(a363+a370);
  a370=(a090*a363);
  a371=(a089*a357);
  a372=(a080*a354);
  a371=(a371+a372);
  a372=(a099*a371);
  a370=(a370-a372);
  a370=(a354+a370);
  a370=(a004*a370);
  a372=(a108*a370);
  a373=(a077*a069);
  a374=(a070*a076);
  a373=(a373+a374);
  a374=(a210*a373);
  a372=(a372+a374);
  a374=(a091*a072);
  a375=(2.*a090);
  a375=(a375*a371);
  a375=(a000*a375);
  a376=(a073*a375);
  a374=(a374-a376);
  a376=(a372-a374);
  a377=(a219*a376);
  a378=(a091*a076);
  a379=(a077*a375);
  a378=(a378-a379);
  a379=(a104*a370);
  a380=(a073*a069);
  a381=(a070*a072);
  a380=(a380+a381);
  a381=(a210*a380);
  a379=(a379+a381);
  a381=(a378+a379);
  a382=(a119*a381);
  a383=(a074*a370);
  a349=(a349+a352);
  a384=(a210*a349);
  a383=(a383+a384);
  a384=(a114*a383);
  a382=(a382-a384);
  a376=(a113*a376);
  a382=(a382+a376);
  a376=(2.*a382);
  a193=(a193*a376);
  a376=(a000*a215);
  a193=(a193+a376);
  a376=(a363-a354);
  a376=(a376/a094);
  a384=(a179/a094);
  a385=(a158*a371);
  a386=(a384*a385);
  a376=(a376+a386);
  a386=(a108*a376);
  a387=(a179*a373);
  a386=(a386+a387);
  a387=(a000*a072);
  a388=(a386-a387);
  a389=(a165*a388);
  a390=(a221*a330);
  a389=(a389+a390);
  a193=(a193-a389);
  a389=(a104*a376);
  a390=(a179*a380);
  a389=(a389+a390);
  a390=(a187*a076);
  a391=(a389-a390);
  a392=(a155*a391);
  a393=(a224*a335);
  a392=(a392+a393);
  a193=(a193-a392);
  a392=(a225*a334);
  a393=(a074*a376);
  a394=(a179*a349);
  a393=(a393+a394);
  a394=(a157*a393);
  a392=(a392-a394);
  a193=(a193-a392);
  a193=(a193/a002);
  a392=(a219/a002);
  a392=(a000*a392);
  a193=(a193-a392);
  a213=(a213*a193);
  a377=(a377+a213);
  a213=(a091*a069);
  a392=(a070*a375);
  a213=(a213-a392);
  a392=(a103*a370);
  a394=(a077*a072);
  a395=(a073*a076);
  a394=(a394+a395);
  a395=(a210*a394);
  a392=(a392+a395);
  a395=(a213+a392);
  a396=(a231*a395);
  a379=(a379-a378);
  a378=(a114*a379);
  a397=(a071*a370);
  a352=(a352+a117);
  a117=(a210*a352);
  a397=(a397+a117);
  a117=(a119*a397);
  a378=(a378-a117);
  a395=(a113*a395);
  a378=(a378+a395);
  a395=(2.*a378);
  a195=(a195*a395);
  a290=(a290*a216);
  a195=(a195+a290);
  a290=(a103*a376);
  a395=(a179*a394);
  a290=(a290+a395);
  a395=(a187*a069);
  a117=(a290-a395);
  a398=(a165*a117);
  a399=(a234*a330);
  a398=(a398+a399);
  a195=(a195-a398);
  a398=(a235*a335);
  a399=(a071*a376);
  a400=(a179*a352);
  a399=(a399+a400);
  a400=(a155*a399);
  a398=(a398-a400);
  a195=(a195-a398);
  a398=(a000*a076);
  a400=(a389-a398);
  a401=(a157*a400);
  a402=(a237*a334);
  a401=(a401+a402);
  a195=(a195-a401);
  a195=(a195/a002);
  a401=(a231/a002);
  a401=(a000*a401);
  a195=(a195-a401);
  a229=(a229*a195);
  a396=(a396+a229);
  a377=(a377+a396);
  a374=(a374+a372);
  a114=(a114*a374);
  a392=(a392-a213);
  a119=(a119*a392);
  a114=(a114+a119);
  a370=(a075*a370);
  a210=(a210*a350);
  a370=(a370+a210);
  a113=(a113*a370);
  a114=(a114-a113);
  a113=(2.*a114);
  a202=(a202*a113);
  a124=(a124*a211);
  a202=(a202+a124);
  a124=(a003*a330);
  a113=(a075*a376);
  a210=(a179*a350);
  a113=(a113+a210);
  a210=(a165*a113);
  a124=(a124-a210);
  a202=(a202-a124);
  a124=(a000*a069);
  a210=(a290-a124);
  a119=(a155*a210);
  a213=(a240*a335);
  a119=(a119+a213);
  a202=(a202-a119);
  a119=(a187*a072);
  a213=(a386-a119);
  a372=(a157*a213);
  a396=(a242*a334);
  a372=(a372+a396);
  a202=(a202-a372);
  a202=(a202/a002);
  a372=(a227/a002);
  a372=(a000*a372);
  a202=(a202-a372);
  a238=(a238*a202);
  a370=(a227*a370);
  a238=(a238-a370);
  a377=(a377+a238);
  a238=(a209*a377);
  a198=(a198+a238);
  a238=(a248*a008);
  a370=(a247*a310);
  a372=(a245*a324);
  a323=(a244*a323);
  a377=(a149*a377);
  a323=(a323+a377);
  a377=(a001*a323);
  a377=(a189+a377);
  a396=(a243*a377);
  a396=(a330+a396);
  a229=(a001*a198);
  a204=(a204+a229);
  a229=(a004*a204);
  a396=(a396+a229);
  a229=(a139*a396);
  a372=(a372+a229);
  a229=(a043*a372);
  a370=(a370+a229);
  a229=(a254*a310);
  a401=(a253*a041);
  a327=(a169*a327);
  a145=(a145*a322);
  a327=(a327+a145);
  a150=(a150*a338);
  a340=(a191*a340);
  a150=(a150-a340);
  a327=(a327+a150);
  a316=(a194*a316);
  a178=(a178*a123);
  a316=(a316+a178);
  a327=(a327+a316);
  a316=(a244*a327);
  a381=(a219*a381);
  a218=(a218*a193);
  a381=(a381+a218);
  a230=(a230*a195);
  a397=(a231*a397);
  a230=(a230-a397);
  a381=(a381+a230);
  a392=(a227*a392);
  a228=(a228*a202);
  a392=(a392+a228);
  a381=(a381+a392);
  a392=(a149*a381);
  a316=(a316+a392);
  a392=(a001*a316);
  a392=(a250+a392);
  a228=(a243*a392);
  a228=(a335+a228);
  a327=(a149*a327);
  a381=(a209*a381);
  a327=(a327+a381);
  a381=(a001*a327);
  a381=(a249+a381);
  a230=(a004*a381);
  a228=(a228+a230);
  a230=(a162*a228);
  a401=(a401+a230);
  a230=(a043*a401);
  a229=(a229+a230);
  a370=(a370+a229);
  a229=(a009*a370);
  a238=(a238+a229);
  a198=(a198-a238);
  a238=(a253*a328);
  a229=(a181*a228);
  a238=(a238+a229);
  a229=(a187*a238);
  a198=(a198+a229);
  a229=(a258*a005);
  a230=(a257*a310);
  a397=(a245*a328);
  a218=(a181*a396);
  a397=(a397+a218);
  a218=(a043*a397);
  a230=(a230+a218);
  a218=(a264*a310);
  a178=(a263*a041);
  a172=(a172*a322);
  a169=(a169*a329);
  a172=(a172-a169);
  a191=(a191*a325);
  a148=(a148*a338);
  a191=(a191+a148);
  a172=(a172+a191);
  a194=(a194*a320);
  a140=(a140*a123);
  a194=(a194+a140);
  a172=(a172+a194);
  a244=(a244*a172);
  a214=(a214*a193);
  a219=(a219*a383);
  a214=(a214-a219);
  a231=(a231*a379);
  a217=(a217*a195);
  a231=(a231+a217);
  a214=(a214+a231);
  a227=(a227*a374);
  a212=(a212*a202);
  a227=(a227+a212);
  a214=(a214+a227);
  a227=(a149*a214);
  a244=(a244+a227);
  a227=(a001*a244);
  a227=(a260+a227);
  a243=(a243*a227);
  a243=(a334+a243);
  a149=(a149*a172);
  a209=(a209*a214);
  a149=(a149+a209);
  a209=(a001*a149);
  a209=(a259+a209);
  a214=(a004*a209);
  a243=(a243+a214);
  a214=(a162*a243);
  a178=(a178+a214);
  a214=(a043*a178);
  a218=(a218+a214);
  a230=(a230+a218);
  a218=(a006*a230);
  a229=(a229+a218);
  a198=(a198-a229);
  a229=(a263*a324);
  a218=(a139*a243);
  a229=(a229+a218);
  a218=(a000*a229);
  a198=(a198+a218);
  a218=(2.*a012);
  a271=(a271*a218);
  a214=(a267*a310);
  a253=(a253*a324);
  a228=(a139*a228);
  a253=(a253+a228);
  a228=(a043*a253);
  a214=(a214+a228);
  a228=(a269*a310);
  a263=(a263*a328);
  a243=(a181*a243);
  a263=(a263+a243);
  a243=(a043*a263);
  a228=(a228+a243);
  a243=(a214+a228);
  a243=(a266*a243);
  a271=(a271+a243);
  a198=(a198+a271);
  a218=(a279*a218);
  a271=(a276*a305);
  a243=(a275*a299);
  a172=(a310/a019);
  a212=(a272/a019);
  a212=(a212*a312);
  a172=(a172+a212);
  a274=(a274*a172);
  a293=(a273*a293);
  a245=(a245*a041);
  a396=(a162*a396);
  a245=(a245+a396);
  a011=(a011*a245);
  a293=(a293+a011);
  a011=(a247*a336);
  a396=(a061*a372);
  a011=(a011+a396);
  a293=(a293-a011);
  a011=(a257*a314);
  a396=(a067*a397);
  a011=(a011+a396);
  a293=(a293-a011);
  a011=(a254*a336);
  a396=(a061*a401);
  a011=(a011+a396);
  a293=(a293-a011);
  a267=(a267*a294);
  a253=(a007*a253);
  a267=(a267+a253);
  a293=(a293+a267);
  a267=(a256*a326);
  a253=(a063*a238);
  a267=(a267+a253);
  a293=(a293-a267);
  a267=(a264*a314);
  a253=(a067*a178);
  a267=(a267+a253);
  a293=(a293-a267);
  a267=(a265*a326);
  a253=(a063*a229);
  a267=(a267+a253);
  a293=(a293-a267);
  a269=(a269*a292);
  a263=(a010*a263);
  a269=(a269+a263);
  a293=(a293+a269);
  a272=(a272*a293);
  a274=(a274+a272);
  a274=(a158*a274);
  a272=(a016*a274);
  a243=(a243+a272);
  a293=(a293/a019);
  a019=(a277/a019);
  a019=(a019*a312);
  a293=(a293+a019);
  a243=(a243-a293);
  a019=(a035*a243);
  a271=(a271+a019);
  a019=(a032*a271);
  a312=(a280*a300);
  a272=(a276*a303);
  a269=(a030*a243);
  a272=(a272+a269);
  a269=(a023*a272);
  a312=(a312+a269);
  a312=(a028*a312);
  a019=(a019+a312);
  a312=(a025*a272);
  a019=(a019+a312);
  a312=(a276*a300);
  a269=(a023*a243);
  a312=(a312+a269);
  a312=(a021*a312);
  a019=(a019+a312);
  a312=(a018*a243);
  a019=(a019+a312);
  a305=(a277*a305);
  a035=(a035*a293);
  a305=(a305+a035);
  a035=(a054*a305);
  a019=(a019+a035);
  a035=(a282*a300);
  a312=(a277*a303);
  a030=(a030*a293);
  a312=(a312+a030);
  a030=(a023*a312);
  a035=(a035+a030);
  a035=(a051*a035);
  a019=(a019+a035);
  a035=(a048*a312);
  a019=(a019+a035);
  a275=(a275*a304);
  a036=(a036*a274);
  a275=(a275+a036);
  a295=(a000*a295);
  a278=(a278*a295);
  a271=(a034*a271);
  a036=(2.*a300);
  a287=(a287*a036);
  a303=(2.*a303);
  a286=(a286*a303);
  a309=(a276*a309);
  a033=(a033*a243);
  a309=(a309+a033);
  a309=(a285*a309);
  a286=(a286+a309);
  a307=(a276*a307);
  a026=(a026*a243);
  a307=(a307+a026);
  a286=(a286+a307);
  a286=(a284*a286);
  a287=(a287+a286);
  a271=(a271+a287);
  a280=(a280*a308);
  a029=(a029*a272);
  a280=(a280+a029);
  a271=(a271+a280);
  a276=(a276*a306);
  a022=(a022*a243);
  a276=(a276+a022);
  a271=(a271+a276);
  a271=(a015*a271);
  a278=(a278+a271);
  a275=(a275+a278);
  a281=(a281*a295);
  a305=(a056*a305);
  a289=(a289*a036);
  a288=(a288*a303);
  a302=(a277*a302);
  a055=(a055*a293);
  a302=(a302+a055);
  a285=(a285*a302);
  a288=(a288+a285);
  a298=(a277*a298);
  a049=(a049*a293);
  a298=(a298+a049);
  a288=(a288+a298);
  a284=(a284*a288);
  a289=(a289+a284);
  a305=(a305+a289);
  a282=(a282*a301);
  a052=(a052*a312);
  a282=(a282+a052);
  a305=(a305+a282);
  a297=(a277*a297);
  a046=(a046*a293);
  a297=(a297+a046);
  a305=(a305+a297);
  a015=(a015*a305);
  a281=(a281+a015);
  a275=(a275+a281);
  a275=(a004*a275);
  a019=(a019+a275);
  a277=(a277*a300);
  a023=(a023*a293);
  a277=(a277+a023);
  a277=(a045*a277);
  a019=(a019+a277);
  a293=(a042*a293);
  a019=(a019+a293);
  a266=(a266*a019);
  a218=(a218+a266);
  a198=(a198+a218);
  a218=(a184*a198);
  a317=(a317+a218);
  a257=(a000*a257);
  a257=(a257+a249);
  a249=(a013*a248);
  a257=(a257-a249);
  a264=(a187*a264);
  a257=(a257+a264);
  a264=(a043*a256);
  a249=(a043*a265);
  a264=(a264+a249);
  a249=(a006*a264);
  a257=(a257-a249);
  a249=(a043*a273);
  a270=(a249+a270);
  a218=(a291*a270);
  a257=(a257+a218);
  a218=(a291*a279);
  a257=(a257+a218);
  a333=(a257*a333);
  a397=(a000*a397);
  a397=(a397+a327);
  a248=(a248*a012);
  a370=(a013*a370);
  a248=(a248+a370);
  a397=(a397-a248);
  a178=(a187*a178);
  a397=(a397+a178);
  a178=(a264*a005);
  a256=(a256*a310);
  a238=(a043*a238);
  a256=(a256+a238);
  a265=(a265*a310);
  a229=(a043*a229);
  a265=(a265+a229);
  a256=(a256+a265);
  a265=(a006*a256);
  a178=(a178+a265);
  a397=(a397-a178);
  a178=(2.*a008);
  a270=(a270*a178);
  a273=(a273*a310);
  a043=(a043*a245);
  a273=(a273+a043);
  a228=(a273+a228);
  a228=(a291*a228);
  a270=(a270+a228);
  a397=(a397+a270);
  a178=(a279*a178);
  a291=(a291*a019);
  a178=(a178+a291);
  a397=(a397+a178);
  a178=(a196*a397);
  a333=(a333+a178);
  a317=(a317+a333);
  a372=(a187*a372);
  a401=(a000*a401);
  a372=(a372+a401);
  a249=(a249+a268);
  a268=(2.*a005);
  a401=(a249*a268);
  a273=(a273+a214);
  a273=(a283*a273);
  a401=(a401+a273);
  a372=(a372+a401);
  a372=(a372+a149);
  a149=(a258*a012);
  a230=(a013*a230);
  a149=(a149+a230);
  a372=(a372-a149);
  a149=(a264*a008);
  a256=(a009*a256);
  a149=(a149+a256);
  a372=(a372-a149);
  a268=(a279*a268);
  a019=(a283*a019);
  a268=(a268+a019);
  a372=(a372+a268);
  a268=(a190*a372);
  a247=(a187*a247);
  a254=(a000*a254);
  a247=(a247+a254);
  a249=(a283*a249);
  a247=(a247+a249);
  a247=(a247+a259);
  a258=(a013*a258);
  a247=(a247-a258);
  a264=(a009*a264);
  a247=(a247-a264);
  a283=(a283*a279);
  a247=(a247+a283);
  a337=(a247*a337);
  a268=(a268-a337);
  a317=(a317+a268);
  a337=arg[3]? arg[3][2] : 0;
  a328=(a337*a328);
  a328=(a002*a328);
  a283=(a337*a181);
  a279=(a000*a283);
  a328=(a328+a279);
  a317=(a317-a328);
  a326=(a038*a326);
  a063=(a063*a321);
  a326=(a326-a063);
  a012=(a059*a012);
  a058=(a058*a311);
  a057=(a057*a299);
  a016=(a016*a296);
  a057=(a057+a016);
  a037=(a037*a057);
  a058=(a058+a037);
  a013=(a013*a058);
  a012=(a012-a013);
  a013=(a326-a012);
  a013=(a107*a013);
  a294=(a038*a294);
  a007=(a007*a321);
  a294=(a294-a007);
  a294=(a062*a294);
  a013=(a013-a294);
  a005=(a059*a005);
  a006=(a006*a058);
  a005=(a005-a006);
  a336=(a038*a336);
  a061=(a061*a321);
  a336=(a336-a061);
  a005=(a005+a336);
  a005=(a040*a005);
  a013=(a013+a005);
  a013=(a002*a013);
  a064=(a107*a064);
  a039=(a062*a039);
  a064=(a064+a039);
  a060=(a040*a060);
  a064=(a064+a060);
  a060=(a000*a064);
  a013=(a013+a060);
  a317=(a317+a013);
  a317=(a317/a001);
  a184=(a184*a255);
  a196=(a196*a257);
  a184=(a184+a196);
  a190=(a190*a247);
  a184=(a184+a190);
  a283=(a283*a002);
  a184=(a184-a283);
  a064=(a064*a002);
  a184=(a184+a064);
  a184=(a184/a001);
  a184=(a184/a001);
  a317=(a317-a184);
  if (res[3]!=0) res[3][0]=a317;
  a343=(a255*a343);
  a317=(a197*a198);
  a343=(a343+a317);
  a317=(a199*a397);
  a346=(a257*a346);
  a317=(a317-a346);
  a343=(a343+a317);
  a347=(a247*a347);
  a346=(a201*a372);
  a347=(a347+a346);
  a343=(a343+a347);
  a324=(a337*a324);
  a324=(a002*a324);
  a347=(a337*a139);
  a346=(a000*a347);
  a324=(a324+a346);
  a343=(a343-a324);
  a012=(a012+a326);
  a012=(a062*a012);
  a292=(a038*a292);
  a010=(a010*a321);
  a292=(a292-a010);
  a292=(a107*a292);
  a012=(a012-a292);
  a038=(a038*a314);
  a067=(a067*a321);
  a038=(a038-a067);
  a059=(a059*a008);
  a009=(a009*a058);
  a059=(a059-a009);
  a038=(a038-a059);
  a038=(a040*a038);
  a012=(a012+a038);
  a012=(a002*a012);
  a014=(a107*a014);
  a065=(a062*a065);
  a014=(a014+a065);
  a068=(a040*a068);
  a014=(a014+a068);
  a068=(a000*a014);
  a012=(a012+a068);
  a343=(a343-a012);
  a343=(a343/a001);
  a197=(a197*a255);
  a199=(a199*a257);
  a197=(a197+a199);
  a201=(a201*a247);
  a197=(a197+a201);
  a347=(a347*a002);
  a197=(a197-a347);
  a014=(a014*a002);
  a197=(a197-a014);
  a197=(a197/a001);
  a197=(a197/a001);
  a343=(a343-a197);
  if (res[3]!=0) res[3][1]=a343;
  a343=(a203*a198);
  a146=(a255*a146);
  a343=(a343-a146);
  a339=(a257*a339);
  a146=(a206*a397);
  a339=(a339+a146);
  a339=(a343+a339);
  a344=(a247*a344);
  a146=(a208*a372);
  a344=(a344+a146);
  a339=(a339+a344);
  a041=(a337*a041);
  a041=(a002*a041);
  a344=(a337*a162);
  a146=(a000*a344);
  a041=(a041+a146);
  a339=(a339-a041);
  a339=(a339/a001);
  a203=(a203*a255);
  a206=(a206*a257);
  a203=(a203+a206);
  a208=(a208*a247);
  a203=(a203+a208);
  a344=(a344*a002);
  a203=(a203-a344);
  a203=(a203/a001);
  a203=(a203/a001);
  a339=(a339-a203);
  if (res[3]!=0) res[3][2]=a339;
  a339=(a091*a380);
  a203=(a104*a375);
  a339=(a339-a203);
  a203=(a101*a076);
  a100=(a100*a371);
  a099=(a099*a357);
  a363=(a080*a363);
  a099=(a099+a363);
  a090=(a090*a099);
  a100=(a100+a090);
  a090=(a077*a100);
  a203=(a203-a090);
  a090=(a339-a203);
  a090=(a107*a090);
  a099=(a091*a352);
  a363=(a071*a375);
  a099=(a099-a363);
  a099=(a062*a099);
  a090=(a090-a099);
  a099=(a101*a069);
  a363=(a070*a100);
  a099=(a099-a363);
  a363=(a091*a394);
  a371=(a103*a375);
  a363=(a363-a371);
  a099=(a099+a363);
  a099=(a040*a099);
  a090=(a090+a099);
  a090=(a002*a090);
  a105=(a107*a105);
  a092=(a062*a092);
  a105=(a105+a092);
  a102=(a040*a102);
  a105=(a105+a102);
  a102=(a000*a105);
  a090=(a090+a102);
  a102=(a337*a382);
  a102=(a002*a102);
  a092=(a337*a215);
  a099=(a000*a092);
  a102=(a102+a099);
  a090=(a090-a102);
  a226=(a004*a226);
  a165=(a165+a226);
  a226=-3.8675134594812879e-02;
  a246=(a226*a246);
  a165=(a165+a246);
  a246=(a216*a165);
  a102=(a179*a246);
  a252=(a004*a252);
  a155=(a155+a252);
  a251=(a226*a251);
  a155=(a155+a251);
  a251=(a211*a155);
  a252=(a179*a251);
  a102=(a102+a252);
  a252=(a073*a102);
  a189=(a189-a252);
  a252=(a215*a155);
  a099=(a187*a252);
  a189=(a189+a099);
  a099=(a215*a165);
  a363=(a179*a099);
  a262=(a004*a262);
  a157=(a157+a262);
  a261=(a226*a261);
  a157=(a157+a261);
  a261=(a211*a157);
  a262=(a179*a261);
  a363=(a363+a262);
  a262=(a070*a363);
  a189=(a189-a262);
  a262=(a216*a157);
  a371=(a000*a262);
  a189=(a189+a371);
  a371=(a216*a155);
  a344=(a179*a371);
  a208=(a215*a157);
  a206=(a179*a208);
  a041=(a344+a206);
  a146=(a351*a041);
  a189=(a189+a146);
  a146=(a211*a165);
  a197=(a075*a146);
  a014=(a103*a246);
  a197=(a197-a014);
  a014=(a108*a099);
  a197=(a197-a014);
  a014=(a103*a251);
  a197=(a197-a014);
  a014=(a071*a371);
  a197=(a197+a014);
  a014=(a104*a252);
  a197=(a197-a014);
  a014=(a108*a261);
  a197=(a197-a014);
  a014=(a104*a262);
  a197=(a197-a014);
  a014=(a074*a208);
  a197=(a197+a014);
  a014=(a384*a197);
  a014=(a158*a014);
  a347=(a080*a014);
  a201=(a197/a094);
  a347=(a347-a201);
  a199=(a088*a347);
  a012=(a032*a199);
  a068=(a086*a347);
  a065=(a083*a068);
  a065=(a028*a065);
  a012=(a012+a065);
  a065=(a025*a068);
  a012=(a012+a065);
  a065=(a083*a347);
  a065=(a021*a065);
  a012=(a012+a065);
  a065=(a018*a347);
  a012=(a012+a065);
  a065=(a088*a201);
  a038=(a054*a065);
  a012=(a012+a038);
  a038=(a086*a201);
  a059=(a083*a038);
  a059=(a051*a059);
  a012=(a012+a059);
  a059=(a048*a038);
  a012=(a012+a059);
  a059=(a089*a014);
  a199=(a034*a199);
  a009=(a087*a347);
  a058=(a364*a009);
  a008=(a084*a347);
  a058=(a058+a008);
  a008=(a361*a058);
  a199=(a199+a008);
  a008=(a085*a068);
  a199=(a199+a008);
  a008=(a082*a347);
  a199=(a199+a008);
  a008=(a079*a199);
  a059=(a059+a008);
  a065=(a056*a065);
  a008=(a098*a201);
  a067=(a364*a008);
  a321=(a096*a201);
  a067=(a067+a321);
  a321=(a361*a067);
  a065=(a065+a321);
  a321=(a097*a038);
  a065=(a065+a321);
  a321=(a095*a201);
  a065=(a065+a321);
  a321=(a079*a065);
  a059=(a059+a321);
  a059=(a004*a059);
  a012=(a012+a059);
  a059=(a083*a201);
  a059=(a045*a059);
  a012=(a012+a059);
  a059=(a042*a201);
  a012=(a012+a059);
  a059=(a351*a012);
  a189=(a189+a059);
  a388=(a189*a388);
  a059=(a102*a072);
  a321=(a246*a376);
  a314=(a165*a378);
  a377=(a004*a377);
  a330=(a330+a377);
  a204=(a226*a204);
  a330=(a330+a204);
  a204=(a216*a330);
  a314=(a314+a204);
  a204=(a179*a314);
  a321=(a321+a204);
  a204=(a251*a376);
  a377=(a155*a114);
  a392=(a004*a392);
  a335=(a335+a392);
  a381=(a226*a381);
  a335=(a335+a381);
  a381=(a211*a335);
  a377=(a377+a381);
  a381=(a179*a377);
  a204=(a204+a381);
  a321=(a321+a204);
  a204=(a073*a321);
  a059=(a059+a204);
  a323=(a323-a059);
  a059=(a155*a382);
  a204=(a215*a335);
  a059=(a059+a204);
  a204=(a187*a059);
  a323=(a323+a204);
  a204=(a363*a069);
  a381=(a099*a376);
  a392=(a165*a382);
  a292=(a215*a330);
  a392=(a392+a292);
  a292=(a179*a392);
  a381=(a381+a292);
  a292=(a261*a376);
  a010=(a157*a114);
  a227=(a004*a227);
  a334=(a334+a227);
  a226=(a226*a209);
  a334=(a334+a226);
  a226=(a211*a334);
  a010=(a010+a226);
  a226=(a179*a010);
  a292=(a292+a226);
  a381=(a381+a292);
  a292=(a070*a381);
  a204=(a204+a292);
  a323=(a323-a204);
  a204=(a157*a378);
  a292=(a216*a334);
  a204=(a204+a292);
  a292=(a000*a204);
  a323=(a323+a292);
  a292=(2.*a076);
  a041=(a041*a292);
  a226=(a371*a376);
  a155=(a155*a378);
  a335=(a216*a335);
  a155=(a155+a335);
  a335=(a179*a155);
  a226=(a226+a335);
  a335=(a208*a376);
  a157=(a157*a382);
  a334=(a215*a334);
  a157=(a157+a334);
  a334=(a179*a157);
  a335=(a335+a334);
  a334=(a226+a335);
  a334=(a351*a334);
  a041=(a041+a334);
  a323=(a323+a041);
  a292=(a012*a292);
  a041=(a347*a365);
  a357=(a014*a357);
  a334=(a376/a094);
  a382=(a384/a094);
  a382=(a382*a385);
  a334=(a334+a382);
  a197=(a197*a334);
  a350=(a146*a350);
  a165=(a165*a114);
  a330=(a211*a330);
  a165=(a165+a330);
  a075=(a075*a165);
  a350=(a350+a075);
  a075=(a246*a394);
  a330=(a103*a314);
  a075=(a075+a330);
  a350=(a350-a075);
  a075=(a099*a373);
  a330=(a108*a392);
  a075=(a075+a330);
  a350=(a350-a075);
  a394=(a251*a394);
  a103=(a103*a377);
  a394=(a394+a103);
  a350=(a350-a394);
  a371=(a371*a352);
  a071=(a071*a155);
  a371=(a371+a071);
  a350=(a350+a371);
  a371=(a252*a380);
  a071=(a104*a059);
  a371=(a371+a071);
  a350=(a350-a371);
  a371=(a261*a373);
  a071=(a108*a010);
  a371=(a371+a071);
  a350=(a350-a371);
  a380=(a262*a380);
  a104=(a104*a204);
  a380=(a380+a104);
  a350=(a350-a380);
  a208=(a208*a349);
  a157=(a074*a157);
  a208=(a208+a157);
  a350=(a350+a208);
  a384=(a384*a350);
  a197=(a197+a384);
  a197=(a158*a197);
  a080=(a080*a197);
  a357=(a357+a080);
  a350=(a350/a094);
  a094=(a201/a094);
  a094=(a094*a385);
  a350=(a350+a094);
  a357=(a357-a350);
  a094=(a088*a357);
  a041=(a041+a094);
  a094=(a032*a041);
  a385=(a068*a358);
  a080=(a347*a362);
  a384=(a086*a357);
  a080=(a080+a384);
  a384=(a083*a080);
  a385=(a385+a384);
  a385=(a028*a385);
  a094=(a094+a385);
  a385=(a025*a080);
  a094=(a094+a385);
  a385=(a347*a358);
  a384=(a083*a357);
  a385=(a385+a384);
  a385=(a021*a385);
  a094=(a094+a385);
  a385=(a018*a357);
  a094=(a094+a385);
  a365=(a201*a365);
  a088=(a088*a350);
  a365=(a365+a088);
  a088=(a054*a365);
  a094=(a094+a088);
  a088=(a038*a358);
  a385=(a201*a362);
  a086=(a086*a350);
  a385=(a385+a086);
  a086=(a083*a385);
  a088=(a088+a086);
  a088=(a051*a088);
  a094=(a094+a088);
  a088=(a048*a385);
  a094=(a094+a088);
  a014=(a014*a354);
  a089=(a089*a197);
  a014=(a014+a089);
  a353=(a000*a353);
  a199=(a199*a353);
  a041=(a034*a041);
  a089=(2.*a358);
  a058=(a058*a089);
  a362=(2.*a362);
  a009=(a009*a362);
  a360=(a347*a360);
  a087=(a087*a357);
  a360=(a360+a087);
  a360=(a364*a360);
  a009=(a009+a360);
  a356=(a347*a356);
  a084=(a084*a357);
  a356=(a356+a084);
  a009=(a009+a356);
  a009=(a361*a009);
  a058=(a058+a009);
  a041=(a041+a058);
  a068=(a068*a359);
  a085=(a085*a080);
  a068=(a068+a085);
  a041=(a041+a068);
  a347=(a347*a355);
  a082=(a082*a357);
  a347=(a347+a082);
  a041=(a041+a347);
  a041=(a079*a041);
  a199=(a199+a041);
  a014=(a014+a199);
  a065=(a065*a353);
  a365=(a056*a365);
  a067=(a067*a089);
  a008=(a008*a362);
  a369=(a201*a369);
  a098=(a098*a350);
  a369=(a369+a098);
  a364=(a364*a369);
  a008=(a008+a364);
  a367=(a201*a367);
  a096=(a096*a350);
  a367=(a367+a096);
  a008=(a008+a367);
  a361=(a361*a008);
  a067=(a067+a361);
  a365=(a365+a067);
  a038=(a038*a368);
  a097=(a097*a385);
  a038=(a038+a097);
  a365=(a365+a038);
  a366=(a201*a366);
  a095=(a095*a350);
  a366=(a366+a095);
  a365=(a365+a366);
  a079=(a079*a365);
  a065=(a065+a079);
  a014=(a014+a065);
  a014=(a004*a014);
  a094=(a094+a014);
  a201=(a201*a358);
  a083=(a083*a350);
  a201=(a201+a083);
  a201=(a045*a201);
  a094=(a094+a201);
  a350=(a042*a350);
  a094=(a094+a350);
  a351=(a351*a094);
  a292=(a292+a351);
  a323=(a323+a292);
  a292=(a221*a323);
  a388=(a388+a292);
  a090=(a090+a388);
  a099=(a000*a099);
  a250=(a250+a099);
  a099=(a077*a102);
  a250=(a250-a099);
  a261=(a187*a261);
  a250=(a250+a261);
  a261=(a179*a252);
  a099=(a179*a262);
  a261=(a261+a099);
  a099=(a070*a261);
  a250=(a250-a099);
  a099=(a179*a146);
  a206=(a099+a206);
  a388=(a348*a206);
  a250=(a250+a388);
  a388=(a348*a012);
  a250=(a250+a388);
  a391=(a250*a391);
  a392=(a000*a392);
  a316=(a316+a392);
  a102=(a102*a076);
  a321=(a077*a321);
  a102=(a102+a321);
  a316=(a316-a102);
  a010=(a187*a010);
  a316=(a316+a010);
  a010=(a261*a069);
  a252=(a252*a376);
  a059=(a179*a059);
  a252=(a252+a059);
  a262=(a262*a376);
  a204=(a179*a204);
  a262=(a262+a204);
  a252=(a252+a262);
  a070=(a070*a252);
  a010=(a010+a070);
  a316=(a316-a010);
  a010=(2.*a072);
  a206=(a206*a010);
  a146=(a146*a376);
  a179=(a179*a165);
  a146=(a146+a179);
  a335=(a146+a335);
  a335=(a348*a335);
  a206=(a206+a335);
  a316=(a316+a206);
  a010=(a012*a010);
  a348=(a348*a094);
  a010=(a010+a348);
  a316=(a316+a010);
  a010=(a224*a316);
  a391=(a391+a010);
  a090=(a090+a391);
  a314=(a187*a314);
  a244=(a244+a314);
  a377=(a000*a377);
  a244=(a244+a377);
  a099=(a099+a344);
  a069=(2.*a069);
  a344=(a099*a069);
  a146=(a146+a226);
  a146=(a318*a146);
  a344=(a344+a146);
  a244=(a244+a344);
  a076=(a363*a076);
  a381=(a077*a381);
  a076=(a076+a381);
  a244=(a244-a076);
  a076=(a261*a072);
  a252=(a073*a252);
  a076=(a076+a252);
  a244=(a244-a076);
  a069=(a012*a069);
  a094=(a318*a094);
  a069=(a069+a094);
  a244=(a244+a069);
  a069=(a225*a244);
  a246=(a187*a246);
  a260=(a260+a246);
  a251=(a000*a251);
  a260=(a260+a251);
  a099=(a318*a099);
  a260=(a260+a099);
  a077=(a077*a363);
  a260=(a260-a077);
  a261=(a073*a261);
  a260=(a260-a261);
  a318=(a318*a012);
  a260=(a260+a318);
  a393=(a260*a393);
  a069=(a069-a393);
  a090=(a090+a069);
  a090=(a090/a001);
  a105=(a105*a002);
  a092=(a092*a002);
  a105=(a105-a092);
  a221=(a221*a189);
  a105=(a105+a221);
  a224=(a224*a250);
  a105=(a105+a224);
  a225=(a225*a260);
  a105=(a105+a225);
  a105=(a105/a001);
  a105=(a105/a001);
  a090=(a090-a105);
  if (res[3]!=0) res[3][3]=a090;
  a117=(a189*a117);
  a090=(a234*a323);
  a117=(a117+a090);
  a378=(a337*a378);
  a378=(a002*a378);
  a090=(a337*a216);
  a105=(a000*a090);
  a378=(a378+a105);
  a203=(a203+a339);
  a203=(a062*a203);
  a349=(a091*a349);
  a074=(a074*a375);
  a349=(a349-a074);
  a349=(a107*a349);
  a203=(a203-a349);
  a091=(a091*a373);
  a108=(a108*a375);
  a091=(a091-a108);
  a101=(a101*a072);
  a073=(a073*a100);
  a101=(a101-a073);
  a091=(a091-a101);
  a091=(a040*a091);
  a203=(a203+a091);
  a203=(a002*a203);
  a078=(a107*a078);
  a106=(a062*a106);
  a078=(a078+a106);
  a109=(a040*a109);
  a078=(a078+a109);
  a109=(a000*a078);
  a203=(a203+a109);
  a378=(a378+a203);
  a117=(a117-a378);
  a378=(a235*a316);
  a399=(a250*a399);
  a378=(a378-a399);
  a117=(a117+a378);
  a400=(a260*a400);
  a399=(a237*a244);
  a400=(a400+a399);
  a117=(a117+a400);
  a117=(a117/a001);
  a234=(a234*a189);
  a090=(a090*a002);
  a078=(a078*a002);
  a090=(a090+a078);
  a234=(a234-a090);
  a235=(a235*a250);
  a234=(a234+a235);
  a237=(a237*a260);
  a234=(a234+a237);
  a234=(a234/a001);
  a234=(a234/a001);
  a117=(a117-a234);
  if (res[3]!=0) res[3][4]=a117;
  a117=(a003*a323);
  a113=(a189*a113);
  a117=(a117-a113);
  a114=(a337*a114);
  a114=(a002*a114);
  a337=(a337*a211);
  a113=(a000*a337);
  a114=(a114+a113);
  a114=(a117-a114);
  a210=(a250*a210);
  a113=(a240*a316);
  a210=(a210+a113);
  a114=(a114+a210);
  a213=(a260*a213);
  a210=(a242*a244);
  a213=(a213+a210);
  a114=(a114+a213);
  a114=(a114/a001);
  a003=(a003*a189);
  a337=(a337*a002);
  a003=(a003-a337);
  a240=(a240*a250);
  a003=(a003+a240);
  a242=(a242*a260);
  a003=(a003+a242);
  a003=(a003/a001);
  a003=(a003/a001);
  a114=(a114-a003);
  if (res[3]!=0) res[3][5]=a114;
  a114=(a000*a118);
  a154=(a154*a112);
  a167=(a167*a118);
  a003=(a154+a167);
  a186=(a186*a111);
  a242=(a003+a186);
  a042=(a042*a242);
  a045=(a045*a242);
  a045=(a128*a045);
  a004=(a004*a242);
  a125=(a125*a004);
  a044=(a044*a125);
  a045=(a045+a044);
  a042=(a042+a045);
  a048=(a048*a242);
  a051=(a051*a242);
  a051=(a128*a051);
  a050=(a050*a125);
  a051=(a051+a050);
  a048=(a048+a051);
  a048=(a129*a048);
  a161=(a161*a125);
  a047=(a047*a161);
  a048=(a048+a047);
  a042=(a042+a048);
  a054=(a054*a242);
  a056=(a056*a125);
  a054=(a054+a056);
  a054=(a130*a054);
  a163=(a163*a161);
  a053=(a053*a163);
  a054=(a054+a053);
  a042=(a042+a054);
  a018=(a018*a242);
  a021=(a021*a242);
  a021=(a128*a021);
  a020=(a020*a125);
  a021=(a021+a020);
  a018=(a018+a021);
  a025=(a025*a242);
  a028=(a028*a242);
  a128=(a128*a028);
  a027=(a027*a125);
  a128=(a128+a027);
  a025=(a025+a128);
  a129=(a129*a025);
  a024=(a024*a161);
  a129=(a129+a024);
  a018=(a018+a129);
  a032=(a032*a242);
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
  a387=(a387+a386);
  a387=(a189*a387);
  a220=(a220+a081);
  a220=(a220*a323);
  a387=(a387+a220);
  a018=(a018+a387);
  a390=(a390+a389);
  a390=(a250*a390);
  a223=(a223+a222);
  a223=(a223*a316);
  a390=(a390+a223);
  a018=(a018+a390);
  a018=(a018+a069);
  a315=(a315+a313);
  a315=(a255*a315);
  a183=(a183+a188);
  a183=(a183*a198);
  a315=(a315+a183);
  a018=(a018+a315);
  a332=(a332+a331);
  a332=(a257*a332);
  a160=(a160+a151);
  a160=(a160*a397);
  a332=(a332+a160);
  a018=(a018+a332);
  a018=(a018+a268);
  a018=(-a018);
  if (res[3]!=0) res[3][6]=a018;
  a018=(a187*a112);
  a268=(a143*a130);
  a332=(a093*a118);
  a160=(a120*a111);
  a332=(a332+a160);
  a160=(a132*a332);
  a268=(a268+a160);
  a160=(a018+a268);
  a160=(a144*a160);
  a315=(a116*a130);
  a186=(a186+a154);
  a154=(a132*a186);
  a315=(a315+a154);
  a315=(a180*a315);
  a160=(a160-a315);
  a154=(a000*a111);
  a183=(a154+a031);
  a183=(a171*a183);
  a160=(a160+a183);
  a395=(a395+a290);
  a189=(a189*a395);
  a233=(a233+a232);
  a233=(a233*a323);
  a189=(a189+a233);
  a160=(a160+a189);
  a160=(a160+a378);
  a398=(a398+a389);
  a398=(a260*a398);
  a236=(a236+a222);
  a236=(a236*a244);
  a398=(a398+a236);
  a160=(a160+a398);
  a342=(a342+a341);
  a255=(a255*a342);
  a185=(a185+a136);
  a185=(a185*a198);
  a255=(a255+a185);
  a160=(a160+a255);
  a160=(a160+a317);
  a345=(a345+a331);
  a345=(a247*a345);
  a200=(a200+a151);
  a200=(a200*a372);
  a345=(a345+a200);
  a160=(a160+a345);
  a160=(-a160);
  if (res[3]!=0) res[3][7]=a160;
  a160=(a000*a112);
  a345=(a160+a268);
  a345=(a180*a345);
  a130=(a122*a130);
  a132=(a132*a003);
  a130=(a130+a132);
  a130=(a144*a130);
  a345=(a345-a130);
  a187=(a187*a118);
  a132=(a187+a127);
  a132=(a171*a132);
  a345=(a345+a132);
  a345=(a345+a117);
  a124=(a124+a290);
  a250=(a250*a124);
  a239=(a239+a232);
  a239=(a239*a316);
  a250=(a250+a239);
  a345=(a345+a250);
  a119=(a119+a386);
  a260=(a260*a119);
  a241=(a241+a081);
  a241=(a241*a244);
  a260=(a260+a241);
  a345=(a345+a260);
  a345=(a345+a343);
  a319=(a319+a341);
  a257=(a257*a319);
  a205=(a205+a136);
  a205=(a205*a397);
  a257=(a257+a205);
  a345=(a345+a257);
  a192=(a192+a313);
  a247=(a247*a192);
  a207=(a207+a188);
  a207=(a207*a372);
  a247=(a247+a207);
  a345=(a345+a247);
  a345=(-a345);
  if (res[3]!=0) res[3][8]=a345;
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
  a215=(a002*a215);
  a215=(a215/a001);
  a215=(-a215);
  if (res[3]!=0) res[3][21]=a215;
  a216=(a002*a216);
  a216=(a216/a001);
  a216=(-a216);
  if (res[3]!=0) res[3][22]=a216;
  a002=(a002*a211);
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
  a332=(a137*a332);
  a143=(a143*a000);
  a332=(a332-a143);
  a143=(a112+a332);
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
  a332=(a332-a112);
  a112=(a142*a332);
  a120=(a120+a112);
  a003=(a137*a003);
  a122=(a122*a000);
  a003=(a003-a122);
  a122=(a147*a003);
  a120=(a120-a122);
  a164=(a164*a120);
  a120=(a173*a138);
  a122=(a175*a332);
  a120=(a120+a122);
  a122=(a176*a003);
  a120=(a120-a122);
  a170=(a170*a120);
  a164=(a164+a170);
  a138=(a107*a138);
  a332=(a062*a332);
  a138=(a138+a332);
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
  a018=(a268-a018);
  a144=(a144*a018);
  a144=(a144-a315);
  a031=(a031-a154);
  a031=(a171*a031);
  a144=(a144+a031);
  if (res[4]!=0) res[4][4]=a144;
  a268=(a268-a160);
  a180=(a180*a268);
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
#define HPGEN_RESIDUAL_JACOBIAN_SZ_W 368
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
#define HPGEN_STEP_PARTIALS_SZ_W 403
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
