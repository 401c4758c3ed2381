/*
 * hpgen generated module lagrange_top_gauss2_cay_exact -- do not edit, regenerate with hpgen
 * model: lagrange_top
 * options: tableau=gauss2, tau=cay, rkmk=exact
 * hpgen version: 0.1.0
 * content hash: db5230382775f98282ae41904036d1840a33e101a8a16c37ee276fba0916c4f9
 *
 * C backend: CasADi's generated kernels (symbols hidden) + dense LU, Newton, hpgen_step and
 * hpgen_simulate (exported). Conventions: all arrays are double, matrices column-major
 * (g[i + j*n]), h is a scalar at the API and a 1-vector for the kernels. No static mutable
 * state: every function is thread-safe; work arrays live on the stack, sized at codegen time.
 * Status codes: 0 ok, 1 Newton did not converge, 2 non-finite value (or singular Jacobian),
 * 3 tau out of its domain (margin(z, h) <= 0 after convergence), -1 invalid argument.
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
  return fmax(x, y);
#endif
}

casadi_real casadi_fmin(casadi_real x, casadi_real y) {
/* Pre-c99 compatibility */
#if __STDC_VERSION__ < 199901L
  return x<y ? x : y;
#else
  return fmin(x, y);
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

static const casadi_int casadi_s0[3] = {24, 1, 1};
static const casadi_int casadi_s1[3] = {9, 1, 1};
static const casadi_int casadi_s2[3] = {3, 1, 1};
static const casadi_int casadi_s3[3] = {1, 1, 1};
static const casadi_int casadi_s4[3] = {576, 1, 1};

/* residual:(z[24],g[9],p[3],h)->(F[24]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a014, a015, a016, a017, a018, a019, a020, a021, a022, a023;
  casadi_real a024, a025, a026, a027, a028, a029, a030, a031, a032, a033, a034, a035;
  casadi_real a036, a037, a038, a039, a040, a041, a042, a043, a044, a045, a046, a047;
  casadi_real a048, a049, a050, a051, a052, a053, a054, a055, a056, a057, a058, a059;
  casadi_real a060, a061, a062, a063, a064, a065, a066, a067, a068, a069, a070, a071;
  casadi_real a072, a073, a074, a075, a076, a077, a078, a079, a080, a081, a082, a083;
  casadi_real a084, a085, a086, a087, a088, a089, a090, a091, a092, a093, a094, a095;
  casadi_real a096, a097, a098, a099, a100;
  a000=arg[0]? arg[0][0] : 0;
  a001=(2.*a000);
  a002=3.8085937500000000e+00;
  a003=arg[3]? arg[3][0] : 0;
  a002=(a002*a003);
  a001=(a001*a002);
  a004=arg[0]? arg[0][17] : 0;
  a005=(a003*a004);
  a006=arg[0]? arg[0][15] : 0;
  a007=(a003*a006);
  a008=(a005*a007);
  a009=4.;
  a010=(a008/a009);
  a011=arg[0]? arg[0][16] : 0;
  a012=(a003*a011);
  a013=2.;
  a014=(a012/a013);
  a015=(a010-a014);
  a016=5.0000000000000000e-01;
  a017=arg[0]? arg[0][14] : 0;
  a018=(a003*a017);
  a018=(a016*a018);
  a019=5.3867513459481287e-01;
  a020=arg[0]? arg[0][11] : 0;
  a020=(a003*a020);
  a021=(a003*a020);
  a022=(a019*a021);
  a022=(a018+a022);
  a023=2.5000000000000000e-01;
  a024=arg[0]? arg[0][8] : 0;
  a024=(a003*a024);
  a025=(a003*a024);
  a026=(a023*a025);
  a022=(a022+a026);
  a026=(a015*a022);
  a027=(a005/a013);
  a028=(a012*a007);
  a028=(a028/a009);
  a029=(a027+a028);
  a030=arg[0]? arg[0][13] : 0;
  a031=(a003*a030);
  a031=(a016*a031);
  a032=arg[0]? arg[0][10] : 0;
  a032=(a003*a032);
  a033=(a003*a032);
  a034=(a019*a033);
  a034=(a031+a034);
  a035=arg[0]? arg[0][7] : 0;
  a035=(a003*a035);
  a036=(a003*a035);
  a037=(a023*a036);
  a034=(a034+a037);
  a037=(a029*a034);
  a026=(a026+a037);
  a037=1.;
  a038=casadi_sq(a007);
  a039=(a038/a009);
  a039=(a037+a039);
  a040=arg[0]? arg[0][12] : 0;
  a041=(a003*a040);
  a041=(a016*a041);
  a042=arg[0]? arg[0][9] : 0;
  a042=(a003*a042);
  a043=(a003*a042);
  a044=(a019*a043);
  a044=(a041+a044);
  a045=arg[0]? arg[0][6] : 0;
  a045=(a003*a045);
  a046=(a003*a045);
  a047=(a023*a046);
  a044=(a044+a047);
  a047=(a039*a044);
  a026=(a026+a047);
  a001=(a001-a026);
  a026=(a016*a003);
  a001=(a001/a026);
  if (res[0]!=0) res[0][0]=a001;
  a001=arg[0]? arg[0][1] : 0;
  a047=(2.*a001);
  a048=1.1718750000000000e-01;
  a048=(a048*a003);
  a047=(a047*a048);
  a049=(a007/a013);
  a050=(a005*a012);
  a051=(a050/a009);
  a052=(a049+a051);
  a053=(a052*a022);
  a054=casadi_sq(a012);
  a055=(a054/a009);
  a055=(a037+a055);
  a056=(a055*a034);
  a053=(a053+a056);
  a056=(a007*a012);
  a057=(a056/a009);
  a058=(a057-a027);
  a059=(a058*a044);
  a053=(a053+a059);
  a047=(a047-a053);
  a047=(a047/a026);
  if (res[0]!=0) res[0][1]=a047;
  a047=arg[0]? arg[0][2] : 0;
  a053=(2.*a047);
  a053=(a053*a002);
  a059=casadi_sq(a005);
  a060=(a059/a009);
  a060=(a037+a060);
  a061=(a060*a022);
  a062=(a012*a005);
  a062=(a062/a009);
  a063=(a062-a049);
  a064=(a063*a034);
  a061=(a061+a064);
  a064=(a007*a005);
  a065=(a064/a009);
  a066=(a014+a065);
  a067=(a066*a044);
  a061=(a061+a067);
  a053=(a053-a061);
  a053=(a053/a026);
  if (res[0]!=0) res[0][2]=a053;
  a053=arg[0]? arg[0][3] : 0;
  a061=(2.*a053);
  a061=(a061*a002);
  a067=arg[0]? arg[0][20] : 0;
  a068=(a003*a067);
  a069=arg[0]? arg[0][18] : 0;
  a070=(a003*a069);
  a071=(a068*a070);
  a072=(a071/a009);
  a073=arg[0]? arg[0][19] : 0;
  a074=(a003*a073);
  a075=(a074/a013);
  a076=(a072-a075);
  a021=(a023*a021);
  a018=(a018+a021);
  a021=-3.8675134594812879e-02;
  a025=(a021*a025);
  a018=(a018+a025);
  a025=(a076*a018);
  a061=(a061-a025);
  a025=(a068/a013);
  a077=(a074*a070);
  a077=(a077/a009);
  a078=(a025+a077);
  a033=(a023*a033);
  a031=(a031+a033);
  a036=(a021*a036);
  a031=(a031+a036);
  a036=(a078*a031);
  a061=(a061-a036);
  a036=casadi_sq(a070);
  a033=(a036/a009);
  a033=(a037+a033);
  a043=(a023*a043);
  a041=(a041+a043);
  a046=(a021*a046);
  a041=(a041+a046);
  a046=(a033*a041);
  a061=(a061-a046);
  a061=(a061/a026);
  if (res[0]!=0) res[0][3]=a061;
  a061=arg[0]? arg[0][4] : 0;
  a046=(2.*a061);
  a046=(a046*a048);
  a048=(a070/a013);
  a043=(a068*a074);
  a079=(a043/a009);
  a080=(a048+a079);
  a081=(a080*a018);
  a046=(a046-a081);
  a081=casadi_sq(a074);
  a082=(a081/a009);
  a082=(a037+a082);
  a083=(a082*a031);
  a046=(a046-a083);
  a083=(a070*a074);
  a084=(a083/a009);
  a085=(a084-a025);
  a086=(a085*a041);
  a046=(a046-a086);
  a046=(a046/a026);
  if (res[0]!=0) res[0][4]=a046;
  a046=arg[0]? arg[0][5] : 0;
  a086=(2.*a046);
  a086=(a086*a002);
  a002=casadi_sq(a068);
  a087=(a002/a009);
  a087=(a037+a087);
  a088=(a087*a018);
  a086=(a086-a088);
  a088=(a074*a068);
  a088=(a088/a009);
  a089=(a088-a048);
  a090=(a089*a031);
  a086=(a086-a090);
  a090=(a070*a068);
  a091=(a090/a009);
  a092=(a075+a091);
  a093=(a092*a041);
  a086=(a086-a093);
  a086=(a086/a026);
  if (res[0]!=0) res[0][5]=a086;
  a086=(2.*a005);
  a026=(a047*a022);
  a026=(a023*a026);
  a086=(a086*a026);
  a024=(a024-a086);
  a086=(a001*a022);
  a026=(a023*a086);
  a093=(a012*a026);
  a024=(a024-a093);
  a022=(a000*a022);
  a093=(a023*a022);
  a094=(a007*a093);
  a024=(a024-a094);
  a094=(a047*a034);
  a095=(a023*a094);
  a096=(a012*a095);
  a024=(a024-a096);
  a096=(a000*a034);
  a097=(a016*a096);
  a024=(a024-a097);
  a097=(a047*a044);
  a098=(a023*a097);
  a099=(a007*a098);
  a024=(a024-a099);
  a099=(a001*a044);
  a100=(a016*a099);
  a024=(a024+a100);
  a100=(a015*a024);
  a022=(a016*a022);
  a026=(a005*a026);
  a022=(a022-a026);
  a022=(a022+a035);
  a095=(a005*a095);
  a022=(a022-a095);
  a095=(2.*a012);
  a034=(a001*a034);
  a034=(a023*a034);
  a095=(a095*a034);
  a022=(a022-a095);
  a096=(a023*a096);
  a095=(a007*a096);
  a022=(a022-a095);
  a097=(a016*a097);
  a022=(a022-a097);
  a099=(a023*a099);
  a097=(a007*a099);
  a022=(a022-a097);
  a097=(a029*a022);
  a100=(a100+a097);
  a094=(a016*a094);
  a086=(a016*a086);
  a093=(a005*a093);
  a086=(a086+a093);
  a094=(a094-a086);
  a096=(a012*a096);
  a094=(a094-a096);
  a094=(a094+a045);
  a098=(a005*a098);
  a094=(a094-a098);
  a099=(a012*a099);
  a094=(a094-a099);
  a099=(2.*a007);
  a044=(a000*a044);
  a044=(a023*a044);
  a099=(a099*a044);
  a094=(a094-a099);
  a099=(a039*a094);
  a100=(a100+a099);
  a044=arg[1]? arg[1][2] : 0;
  a098=(a038+a054);
  a098=(a098+a059);
  a098=(a009+a098);
  a098=(a009/a098);
  a008=(a008/a013);
  a008=(a012+a008);
  a008=(a098*a008);
  a008=(a044*a008);
  a045=arg[1]? arg[1][5] : 0;
  a050=(a050/a013);
  a050=(a050-a007);
  a050=(a098*a050);
  a050=(a045*a050);
  a008=(a008+a050);
  a050=arg[1]? arg[1][8] : 0;
  a038=(a054+a038);
  a038=(a038/a013);
  a038=(a098*a038);
  a038=(a037-a038);
  a038=(a050*a038);
  a008=(a008+a038);
  a038=-7.3575000000000003e+01;
  a038=(a038*a003);
  a008=(a008*a038);
  a100=(a100+a008);
  a100=(a100/a003);
  if (res[0]!=0) res[0][6]=a100;
  a100=(a052*a024);
  a008=(a055*a022);
  a100=(a100+a008);
  a007=(a058*a094);
  a100=(a100+a007);
  a100=(a100/a003);
  if (res[0]!=0) res[0][7]=a100;
  a100=(a060*a024);
  a007=(a063*a022);
  a007=(a100+a007);
  a096=(a066*a094);
  a007=(a007+a096);
  a059=(a059+a054);
  a059=(a059/a013);
  a059=(a098*a059);
  a059=(a037-a059);
  a059=(a044*a059);
  a056=(a056/a013);
  a005=(a005+a056);
  a005=(a098*a005);
  a005=(a045*a005);
  a059=(a059+a005);
  a064=(a064/a013);
  a064=(a064-a012);
  a098=(a098*a064);
  a098=(a050*a098);
  a059=(a059+a098);
  a059=(a059*a038);
  a007=(a007-a059);
  a007=(a007/a003);
  if (res[0]!=0) res[0][8]=a007;
  a007=(a036+a081);
  a007=(a007+a002);
  a007=(a009+a007);
  a007=(a009/a007);
  a071=(a071/a013);
  a071=(a074+a071);
  a071=(a007*a071);
  a071=(a044*a071);
  a043=(a043/a013);
  a043=(a043-a070);
  a043=(a007*a043);
  a043=(a045*a043);
  a071=(a071+a043);
  a036=(a081+a036);
  a036=(a036/a013);
  a036=(a007*a036);
  a036=(a037-a036);
  a036=(a050*a036);
  a071=(a071+a036);
  a071=(a071*a038);
  a036=(2.*a068);
  a043=(a046*a018);
  a043=(a023*a043);
  a036=(a036*a043);
  a020=(a020-a036);
  a036=(a061*a018);
  a043=(a023*a036);
  a059=(a074*a043);
  a020=(a020-a059);
  a018=(a053*a018);
  a059=(a023*a018);
  a098=(a070*a059);
  a020=(a020-a098);
  a098=(a046*a031);
  a064=(a023*a098);
  a012=(a074*a064);
  a020=(a020-a012);
  a012=(a053*a031);
  a005=(a016*a012);
  a020=(a020-a005);
  a005=(a046*a041);
  a056=(a023*a005);
  a054=(a070*a056);
  a020=(a020-a054);
  a054=(a061*a041);
  a096=(a016*a054);
  a020=(a020+a096);
  a096=(a076*a020);
  a071=(a071+a096);
  a043=(a068*a043);
  a032=(a032-a043);
  a018=(a016*a018);
  a032=(a032+a018);
  a064=(a068*a064);
  a032=(a032-a064);
  a064=(2.*a074);
  a031=(a061*a031);
  a031=(a023*a031);
  a064=(a064*a031);
  a032=(a032-a064);
  a012=(a023*a012);
  a064=(a070*a012);
  a032=(a032-a064);
  a005=(a016*a005);
  a032=(a032-a005);
  a054=(a023*a054);
  a005=(a070*a054);
  a032=(a032-a005);
  a005=(a078*a032);
  a071=(a071+a005);
  a036=(a016*a036);
  a042=(a042-a036);
  a059=(a068*a059);
  a042=(a042-a059);
  a098=(a016*a098);
  a042=(a042+a098);
  a012=(a074*a012);
  a042=(a042-a012);
  a056=(a068*a056);
  a042=(a042-a056);
  a054=(a074*a054);
  a042=(a042-a054);
  a070=(2.*a070);
  a041=(a053*a041);
  a041=(a023*a041);
  a070=(a070*a041);
  a042=(a042-a070);
  a070=(a033*a042);
  a071=(a071+a070);
  a071=(a071/a003);
  if (res[0]!=0) res[0][9]=a071;
  a071=(a080*a020);
  a041=(a082*a032);
  a071=(a071+a041);
  a054=(a085*a042);
  a071=(a071+a054);
  a071=(a071/a003);
  if (res[0]!=0) res[0][10]=a071;
  a071=(a087*a020);
  a002=(a002+a081);
  a002=(a002/a013);
  a002=(a007*a002);
  a002=(a037-a002);
  a044=(a044*a002);
  a083=(a083/a013);
  a068=(a068+a083);
  a068=(a007*a068);
  a045=(a045*a068);
  a044=(a044+a045);
  a090=(a090/a013);
  a090=(a090-a074);
  a007=(a007*a090);
  a050=(a050*a007);
  a044=(a044+a050);
  a044=(a044*a038);
  a044=(a071-a044);
  a038=(a089*a032);
  a044=(a044+a038);
  a038=(a092*a042);
  a044=(a044+a038);
  a044=(a044/a003);
  if (res[0]!=0) res[0][11]=a044;
  a044=arg[2]? arg[2][0] : 0;
  a038=arg[0]? arg[0][22] : 0;
  a050=(a003*a038);
  a007=(a050/a013);
  a090=arg[0]? arg[0][23] : 0;
  a074=(a003*a090);
  a045=arg[0]? arg[0][21] : 0;
  a003=(a003*a045);
  a068=(a074*a003);
  a068=(a068/a009);
  a068=(a007+a068);
  a068=(a068*a017);
  a083=(a050*a003);
  a083=(a083/a009);
  a002=(a074/a013);
  a083=(a083-a002);
  a083=(a083*a030);
  a068=(a068+a083);
  a083=casadi_sq(a003);
  a083=(a083/a009);
  a083=(a037+a083);
  a083=(a083*a040);
  a068=(a068+a083);
  a072=(a075+a072);
  a072=(a072*a020);
  a068=(a068+a072);
  a077=(a077-a025);
  a077=(a077*a032);
  a068=(a068+a077);
  a068=(a068+a070);
  a010=(a014+a010);
  a010=(a010*a024);
  a068=(a068+a010);
  a028=(a028-a027);
  a028=(a028*a022);
  a068=(a068+a028);
  a068=(a068+a099);
  a044=(a044-a068);
  if (res[0]!=0) res[0][12]=a044;
  a044=arg[2]? arg[2][1] : 0;
  a068=(a074*a050);
  a068=(a068/a009);
  a013=(a003/a013);
  a068=(a068-a013);
  a068=(a068*a017);
  a099=casadi_sq(a050);
  a099=(a099/a009);
  a099=(a037+a099);
  a099=(a099*a030);
  a068=(a068+a099);
  a099=(a003*a050);
  a099=(a099/a009);
  a002=(a002+a099);
  a002=(a002*a040);
  a068=(a068+a002);
  a079=(a079-a048);
  a079=(a079*a020);
  a068=(a068+a079);
  a068=(a068+a041);
  a025=(a025+a084);
  a025=(a025*a042);
  a068=(a068+a025);
  a051=(a051-a049);
  a051=(a051*a024);
  a068=(a068+a051);
  a068=(a068+a008);
  a027=(a027+a057);
  a027=(a027*a094);
  a068=(a068+a027);
  a044=(a044-a068);
  if (res[0]!=0) res[0][13]=a044;
  a044=arg[2]? arg[2][2] : 0;
  a068=casadi_sq(a074);
  a068=(a068/a009);
  a037=(a037+a068);
  a037=(a037*a017);
  a050=(a050*a074);
  a050=(a050/a009);
  a013=(a013+a050);
  a013=(a013*a030);
  a037=(a037+a013);
  a003=(a003*a074);
  a003=(a003/a009);
  a003=(a003-a007);
  a003=(a003*a040);
  a037=(a037+a003);
  a037=(a037+a071);
  a048=(a048+a088);
  a048=(a048*a032);
  a037=(a037+a048);
  a091=(a091-a075);
  a091=(a091*a042);
  a037=(a037+a091);
  a037=(a037+a100);
  a049=(a049+a062);
  a049=(a049*a022);
  a037=(a037+a049);
  a065=(a065-a014);
  a065=(a065*a094);
  a037=(a037+a065);
  a044=(a044-a037);
  if (res[0]!=0) res[0][14]=a044;
  a039=(a039*a000);
  a058=(a058*a001);
  a039=(a039+a058);
  a066=(a066*a047);
  a039=(a039+a066);
  a066=(a023*a039);
  a033=(a033*a053);
  a085=(a085*a061);
  a033=(a033+a085);
  a092=(a092*a046);
  a033=(a033+a092);
  a092=(a021*a033);
  a066=(a066+a092);
  a006=(a006-a066);
  if (res[0]!=0) res[0][15]=a006;
  a029=(a029*a000);
  a055=(a055*a001);
  a029=(a029+a055);
  a063=(a063*a047);
  a029=(a029+a063);
  a063=(a023*a029);
  a078=(a078*a053);
  a082=(a082*a061);
  a078=(a078+a082);
  a089=(a089*a046);
  a078=(a078+a089);
  a089=(a021*a078);
  a063=(a063+a089);
  a011=(a011-a063);
  if (res[0]!=0) res[0][16]=a011;
  a015=(a015*a000);
  a052=(a052*a001);
  a015=(a015+a052);
  a060=(a060*a047);
  a015=(a015+a060);
  a060=(a023*a015);
  a076=(a076*a053);
  a080=(a080*a061);
  a076=(a076+a080);
  a087=(a087*a046);
  a076=(a076+a087);
  a021=(a021*a076);
  a060=(a060+a021);
  a004=(a004-a060);
  if (res[0]!=0) res[0][17]=a004;
  a004=(a019*a039);
  a060=(a023*a033);
  a004=(a004+a060);
  a069=(a069-a004);
  if (res[0]!=0) res[0][18]=a069;
  a069=(a019*a029);
  a004=(a023*a078);
  a069=(a069+a004);
  a073=(a073-a069);
  if (res[0]!=0) res[0][19]=a073;
  a019=(a019*a015);
  a023=(a023*a076);
  a019=(a019+a023);
  a067=(a067-a019);
  if (res[0]!=0) res[0][20]=a067;
  a039=(a016*a039);
  a033=(a016*a033);
  a039=(a039+a033);
  a045=(a045-a039);
  if (res[0]!=0) res[0][21]=a045;
  a029=(a016*a029);
  a078=(a016*a078);
  a029=(a029+a078);
  a038=(a038-a029);
  if (res[0]!=0) res[0][22]=a038;
  a015=(a016*a015);
  a016=(a016*a076);
  a015=(a015+a016);
  a090=(a090-a015);
  if (res[0]!=0) res[0][23]=a090;
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

/* jacobian:(z[24],g[9],p[3],h)->(J[576]) */
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
  casadi_real a120, a121, a122, a123, a124, a125, a126, a127, a128, a129, a130;
  a000=7.6171875000000000e+00;
  a001=arg[3]? arg[3][0] : 0;
  a000=(a000*a001);
  a002=5.0000000000000000e-01;
  a003=(a002*a001);
  a000=(a000/a003);
  if (res[0]!=0) res[0][0]=a000;
  a004=0.;
  if (res[0]!=0) res[0][1]=a004;
  if (res[0]!=0) res[0][2]=a004;
  if (res[0]!=0) res[0][3]=a004;
  if (res[0]!=0) res[0][4]=a004;
  if (res[0]!=0) res[0][5]=a004;
  a005=arg[0]? arg[0][17] : 0;
  a005=(a001*a005);
  a006=2.;
  a007=(a005/a006);
  a008=arg[0]? arg[0][16] : 0;
  a008=(a001*a008);
  a009=arg[0]? arg[0][15] : 0;
  a009=(a001*a009);
  a010=(a008*a009);
  a011=4.;
  a010=(a010/a011);
  a012=(a007+a010);
  a013=arg[0]? arg[0][14] : 0;
  a014=(a001*a013);
  a014=(a002*a014);
  a015=5.3867513459481287e-01;
  a016=arg[0]? arg[0][11] : 0;
  a016=(a001*a016);
  a017=(a001*a016);
  a018=(a015*a017);
  a018=(a014+a018);
  a019=2.5000000000000000e-01;
  a020=arg[0]? arg[0][8] : 0;
  a020=(a001*a020);
  a021=(a001*a020);
  a022=(a019*a021);
  a018=(a018+a022);
  a022=(a002*a018);
  a023=arg[0]? arg[0][13] : 0;
  a024=(a001*a023);
  a024=(a002*a024);
  a025=arg[0]? arg[0][10] : 0;
  a025=(a001*a025);
  a026=(a001*a025);
  a027=(a015*a026);
  a027=(a024+a027);
  a028=arg[0]? arg[0][7] : 0;
  a028=(a001*a028);
  a029=(a001*a028);
  a030=(a019*a029);
  a027=(a027+a030);
  a030=(a019*a027);
  a031=(a009*a030);
  a031=(a022-a031);
  a032=(a012*a031);
  a033=(a005*a009);
  a034=(a033/a011);
  a035=(a008/a006);
  a036=(a034-a035);
  a037=(a019*a018);
  a038=(a009*a037);
  a039=(a002*a027);
  a038=(a038+a039);
  a040=(a036*a038);
  a032=(a032-a040);
  a040=1.;
  a041=casadi_sq(a009);
  a042=(a041/a011);
  a042=(a040+a042);
  a043=(a005*a037);
  a044=(a008*a030);
  a045=(a043+a044);
  a046=(2.*a009);
  a047=arg[0]? arg[0][12] : 0;
  a048=(a001*a047);
  a048=(a002*a048);
  a049=arg[0]? arg[0][9] : 0;
  a049=(a001*a049);
  a050=(a001*a049);
  a051=(a015*a050);
  a051=(a048+a051);
  a052=arg[0]? arg[0][6] : 0;
  a052=(a001*a052);
  a053=(a001*a052);
  a054=(a019*a053);
  a051=(a051+a054);
  a054=(a019*a051);
  a055=(a046*a054);
  a045=(a045+a055);
  a055=(a042*a045);
  a032=(a032-a055);
  a032=(a032/a001);
  if (res[0]!=0) res[0][6]=a032;
  a032=casadi_sq(a008);
  a056=(a032/a011);
  a056=(a040+a056);
  a057=(a056*a031);
  a058=(a009/a006);
  a059=(a005*a008);
  a060=(a059/a011);
  a061=(a058+a060);
  a062=(a061*a038);
  a062=(a057-a062);
  a063=(a009*a008);
  a064=(a063/a011);
  a065=(a064-a007);
  a066=(a065*a045);
  a062=(a062-a066);
  a062=(a062/a001);
  if (res[0]!=0) res[0][7]=a062;
  a062=(a008*a005);
  a062=(a062/a011);
  a066=(a062-a058);
  a067=(a066*a031);
  a068=casadi_sq(a005);
  a069=(a068/a011);
  a069=(a040+a069);
  a070=(a069*a038);
  a067=(a067-a070);
  a071=(a009*a005);
  a072=(a071/a011);
  a073=(a035+a072);
  a074=(a073*a045);
  a067=(a067-a074);
  a067=(a067/a001);
  if (res[0]!=0) res[0][8]=a067;
  if (res[0]!=0) res[0][9]=a004;
  if (res[0]!=0) res[0][10]=a004;
  if (res[0]!=0) res[0][11]=a004;
  a010=(a010-a007);
  a067=(a010*a031);
  a034=(a035+a034);
  a074=(a034*a038);
  a067=(a067-a074);
  a067=(a067-a055);
  a067=(-a067);
  if (res[0]!=0) res[0][12]=a067;
  a060=(a060-a058);
  a038=(a060*a038);
  a057=(a057-a038);
  a007=(a007+a064);
  a064=(a007*a045);
  a057=(a057-a064);
  a057=(-a057);
  if (res[0]!=0) res[0][13]=a057;
  a058=(a058+a062);
  a031=(a058*a031);
  a031=(a031-a070);
  a072=(a072-a035);
  a045=(a072*a045);
  a031=(a031-a045);
  a031=(-a031);
  if (res[0]!=0) res[0][14]=a031;
  a031=(a019*a042);
  a031=(-a031);
  if (res[0]!=0) res[0][15]=a031;
  a031=(a019*a012);
  a031=(-a031);
  if (res[0]!=0) res[0][16]=a031;
  a031=(a019*a036);
  a031=(-a031);
  if (res[0]!=0) res[0][17]=a031;
  a031=(a015*a042);
  a031=(-a031);
  if (res[0]!=0) res[0][18]=a031;
  a031=(a015*a012);
  a031=(-a031);
  if (res[0]!=0) res[0][19]=a031;
  a031=(a015*a036);
  a031=(-a031);
  if (res[0]!=0) res[0][20]=a031;
  a031=(a002*a042);
  a031=(-a031);
  if (res[0]!=0) res[0][21]=a031;
  a031=(a002*a012);
  a031=(-a031);
  if (res[0]!=0) res[0][22]=a031;
  a031=(a002*a036);
  a031=(-a031);
  if (res[0]!=0) res[0][23]=a031;
  if (res[0]!=0) res[0][24]=a004;
  a031=2.3437500000000000e-01;
  a031=(a031*a001);
  a031=(a031/a003);
  if (res[0]!=0) res[0][25]=a031;
  if (res[0]!=0) res[0][26]=a004;
  if (res[0]!=0) res[0][27]=a004;
  if (res[0]!=0) res[0][28]=a004;
  if (res[0]!=0) res[0][29]=a004;
  a045=(a002*a051);
  a035=(a008*a037);
  a035=(a045-a035);
  a070=(a036*a035);
  a062=(2.*a008);
  a057=(a062*a030);
  a043=(a043+a057);
  a057=(a009*a054);
  a043=(a043+a057);
  a064=(a012*a043);
  a070=(a070-a064);
  a064=(a008*a054);
  a022=(a022+a064);
  a064=(a042*a022);
  a070=(a070-a064);
  a070=(a070/a001);
  if (res[0]!=0) res[0][30]=a070;
  a070=(a061*a035);
  a038=(a056*a043);
  a070=(a070-a038);
  a067=(a065*a022);
  a070=(a070-a067);
  a070=(a070/a001);
  if (res[0]!=0) res[0][31]=a070;
  a070=(a069*a035);
  a067=(a066*a043);
  a067=(a070-a067);
  a055=(a073*a022);
  a067=(a067-a055);
  a067=(a067/a001);
  if (res[0]!=0) res[0][32]=a067;
  if (res[0]!=0) res[0][33]=a004;
  if (res[0]!=0) res[0][34]=a004;
  if (res[0]!=0) res[0][35]=a004;
  a067=(a034*a035);
  a055=(a010*a043);
  a067=(a067-a055);
  a067=(a067-a064);
  a067=(-a067);
  if (res[0]!=0) res[0][36]=a067;
  a035=(a060*a035);
  a035=(a035-a038);
  a038=(a007*a022);
  a035=(a035-a038);
  a035=(-a035);
  if (res[0]!=0) res[0][37]=a035;
  a043=(a058*a043);
  a070=(a070-a043);
  a022=(a072*a022);
  a070=(a070-a022);
  a070=(-a070);
  if (res[0]!=0) res[0][38]=a070;
  a070=(a019*a065);
  a070=(-a070);
  if (res[0]!=0) res[0][39]=a070;
  a070=(a019*a056);
  a070=(-a070);
  if (res[0]!=0) res[0][40]=a070;
  a070=(a019*a061);
  a070=(-a070);
  if (res[0]!=0) res[0][41]=a070;
  a070=(a015*a065);
  a070=(-a070);
  if (res[0]!=0) res[0][42]=a070;
  a070=(a015*a056);
  a070=(-a070);
  if (res[0]!=0) res[0][43]=a070;
  a070=(a015*a061);
  a070=(-a070);
  if (res[0]!=0) res[0][44]=a070;
  a070=(a002*a065);
  a070=(-a070);
  if (res[0]!=0) res[0][45]=a070;
  a070=(a002*a056);
  a070=(-a070);
  if (res[0]!=0) res[0][46]=a070;
  a070=(a002*a061);
  a070=(-a070);
  if (res[0]!=0) res[0][47]=a070;
  if (res[0]!=0) res[0][48]=a004;
  if (res[0]!=0) res[0][49]=a004;
  if (res[0]!=0) res[0][50]=a000;
  if (res[0]!=0) res[0][51]=a004;
  if (res[0]!=0) res[0][52]=a004;
  if (res[0]!=0) res[0][53]=a004;
  a054=(a005*a054);
  a039=(a039-a054);
  a054=(a042*a039);
  a070=(2.*a005);
  a037=(a070*a037);
  a037=(a037+a044);
  a037=(a037+a057);
  a057=(a036*a037);
  a030=(a005*a030);
  a030=(a030+a045);
  a045=(a012*a030);
  a057=(a057+a045);
  a057=(a054-a057);
  a057=(a057/a001);
  if (res[0]!=0) res[0][54]=a057;
  a057=(a065*a039);
  a045=(a061*a037);
  a044=(a056*a030);
  a045=(a045+a044);
  a057=(a057-a045);
  a057=(a057/a001);
  if (res[0]!=0) res[0][55]=a057;
  a057=(a073*a039);
  a045=(a069*a037);
  a022=(a066*a030);
  a022=(a045+a022);
  a057=(a057-a022);
  a057=(a057/a001);
  if (res[0]!=0) res[0][56]=a057;
  if (res[0]!=0) res[0][57]=a004;
  if (res[0]!=0) res[0][58]=a004;
  if (res[0]!=0) res[0][59]=a004;
  a057=(a034*a037);
  a022=(a010*a030);
  a057=(a057+a022);
  a054=(a054-a057);
  a054=(-a054);
  if (res[0]!=0) res[0][60]=a054;
  a054=(a007*a039);
  a037=(a060*a037);
  a037=(a037+a044);
  a054=(a054-a037);
  a054=(-a054);
  if (res[0]!=0) res[0][61]=a054;
  a039=(a072*a039);
  a030=(a058*a030);
  a045=(a045+a030);
  a039=(a039-a045);
  a039=(-a039);
  if (res[0]!=0) res[0][62]=a039;
  a039=(a019*a073);
  a039=(-a039);
  if (res[0]!=0) res[0][63]=a039;
  a039=(a019*a066);
  a039=(-a039);
  if (res[0]!=0) res[0][64]=a039;
  a039=(a019*a069);
  a039=(-a039);
  if (res[0]!=0) res[0][65]=a039;
  a039=(a015*a073);
  a039=(-a039);
  if (res[0]!=0) res[0][66]=a039;
  a039=(a015*a066);
  a039=(-a039);
  if (res[0]!=0) res[0][67]=a039;
  a039=(a015*a069);
  a039=(-a039);
  if (res[0]!=0) res[0][68]=a039;
  a039=(a002*a073);
  a039=(-a039);
  if (res[0]!=0) res[0][69]=a039;
  a039=(a002*a066);
  a039=(-a039);
  if (res[0]!=0) res[0][70]=a039;
  a039=(a002*a069);
  a039=(-a039);
  if (res[0]!=0) res[0][71]=a039;
  if (res[0]!=0) res[0][72]=a004;
  if (res[0]!=0) res[0][73]=a004;
  if (res[0]!=0) res[0][74]=a004;
  if (res[0]!=0) res[0][75]=a000;
  if (res[0]!=0) res[0][76]=a004;
  if (res[0]!=0) res[0][77]=a004;
  if (res[0]!=0) res[0][78]=a004;
  if (res[0]!=0) res[0][79]=a004;
  if (res[0]!=0) res[0][80]=a004;
  a039=arg[0]? arg[0][20] : 0;
  a039=(a001*a039);
  a045=(a039/a006);
  a030=arg[0]? arg[0][19] : 0;
  a030=(a001*a030);
  a054=arg[0]? arg[0][18] : 0;
  a054=(a001*a054);
  a037=(a030*a054);
  a037=(a037/a011);
  a044=(a045+a037);
  a017=(a019*a017);
  a014=(a014+a017);
  a017=-3.8675134594812879e-02;
  a021=(a017*a021);
  a014=(a014+a021);
  a021=(a002*a014);
  a026=(a019*a026);
  a024=(a024+a026);
  a029=(a017*a029);
  a024=(a024+a029);
  a029=(a019*a024);
  a026=(a054*a029);
  a026=(a021-a026);
  a057=(a044*a026);
  a022=(a039*a054);
  a043=(a022/a011);
  a035=(a030/a006);
  a038=(a043-a035);
  a067=(a019*a014);
  a064=(a054*a067);
  a055=(a002*a024);
  a064=(a064+a055);
  a074=(a038*a064);
  a057=(a057-a074);
  a074=casadi_sq(a054);
  a075=(a074/a011);
  a075=(a040+a075);
  a076=(a039*a067);
  a077=(a030*a029);
  a078=(a076+a077);
  a079=(2.*a054);
  a050=(a019*a050);
  a048=(a048+a050);
  a053=(a017*a053);
  a048=(a048+a053);
  a053=(a019*a048);
  a050=(a079*a053);
  a078=(a078+a050);
  a050=(a075*a078);
  a057=(a057-a050);
  a057=(a057/a001);
  if (res[0]!=0) res[0][81]=a057;
  a057=casadi_sq(a030);
  a080=(a057/a011);
  a080=(a040+a080);
  a081=(a080*a026);
  a082=(a054/a006);
  a083=(a039*a030);
  a084=(a083/a011);
  a085=(a082+a084);
  a086=(a085*a064);
  a086=(a081-a086);
  a087=(a054*a030);
  a088=(a087/a011);
  a089=(a088-a045);
  a090=(a089*a078);
  a086=(a086-a090);
  a086=(a086/a001);
  if (res[0]!=0) res[0][82]=a086;
  a086=(a030*a039);
  a086=(a086/a011);
  a090=(a086-a082);
  a091=(a090*a026);
  a092=casadi_sq(a039);
  a093=(a092/a011);
  a093=(a040+a093);
  a094=(a093*a064);
  a091=(a091-a094);
  a095=(a054*a039);
  a096=(a095/a011);
  a097=(a035+a096);
  a098=(a097*a078);
  a091=(a091-a098);
  a091=(a091/a001);
  if (res[0]!=0) res[0][83]=a091;
  a037=(a037-a045);
  a091=(a037*a026);
  a043=(a035+a043);
  a098=(a043*a064);
  a091=(a091-a098);
  a091=(a091-a050);
  a091=(-a091);
  if (res[0]!=0) res[0][84]=a091;
  a084=(a084-a082);
  a064=(a084*a064);
  a081=(a081-a064);
  a045=(a045+a088);
  a088=(a045*a078);
  a081=(a081-a088);
  a081=(-a081);
  if (res[0]!=0) res[0][85]=a081;
  a082=(a082+a086);
  a026=(a082*a026);
  a026=(a026-a094);
  a096=(a096-a035);
  a078=(a096*a078);
  a026=(a026-a078);
  a026=(-a026);
  if (res[0]!=0) res[0][86]=a026;
  a026=(a017*a075);
  a026=(-a026);
  if (res[0]!=0) res[0][87]=a026;
  a026=(a017*a044);
  a026=(-a026);
  if (res[0]!=0) res[0][88]=a026;
  a026=(a017*a038);
  a026=(-a026);
  if (res[0]!=0) res[0][89]=a026;
  a026=(a019*a075);
  a026=(-a026);
  if (res[0]!=0) res[0][90]=a026;
  a026=(a019*a044);
  a026=(-a026);
  if (res[0]!=0) res[0][91]=a026;
  a026=(a019*a038);
  a026=(-a026);
  if (res[0]!=0) res[0][92]=a026;
  a026=(a002*a075);
  a026=(-a026);
  if (res[0]!=0) res[0][93]=a026;
  a026=(a002*a044);
  a026=(-a026);
  if (res[0]!=0) res[0][94]=a026;
  a026=(a002*a038);
  a026=(-a026);
  if (res[0]!=0) res[0][95]=a026;
  if (res[0]!=0) res[0][96]=a004;
  if (res[0]!=0) res[0][97]=a004;
  if (res[0]!=0) res[0][98]=a004;
  if (res[0]!=0) res[0][99]=a004;
  if (res[0]!=0) res[0][100]=a031;
  if (res[0]!=0) res[0][101]=a004;
  if (res[0]!=0) res[0][102]=a004;
  if (res[0]!=0) res[0][103]=a004;
  if (res[0]!=0) res[0][104]=a004;
  a031=(a002*a048);
  a026=(a030*a067);
  a026=(a031-a026);
  a078=(a038*a026);
  a035=(2.*a030);
  a094=(a035*a029);
  a076=(a076+a094);
  a094=(a054*a053);
  a076=(a076+a094);
  a086=(a044*a076);
  a078=(a078-a086);
  a086=(a030*a053);
  a021=(a021+a086);
  a086=(a075*a021);
  a078=(a078-a086);
  a078=(a078/a001);
  if (res[0]!=0) res[0][105]=a078;
  a078=(a085*a026);
  a081=(a080*a076);
  a078=(a078-a081);
  a088=(a089*a021);
  a078=(a078-a088);
  a078=(a078/a001);
  if (res[0]!=0) res[0][106]=a078;
  a078=(a093*a026);
  a088=(a090*a076);
  a088=(a078-a088);
  a064=(a097*a021);
  a088=(a088-a064);
  a088=(a088/a001);
  if (res[0]!=0) res[0][107]=a088;
  a088=(a043*a026);
  a064=(a037*a076);
  a088=(a088-a064);
  a088=(a088-a086);
  a088=(-a088);
  if (res[0]!=0) res[0][108]=a088;
  a026=(a084*a026);
  a026=(a026-a081);
  a081=(a045*a021);
  a026=(a026-a081);
  a026=(-a026);
  if (res[0]!=0) res[0][109]=a026;
  a076=(a082*a076);
  a078=(a078-a076);
  a021=(a096*a021);
  a078=(a078-a021);
  a078=(-a078);
  if (res[0]!=0) res[0][110]=a078;
  a078=(a017*a089);
  a078=(-a078);
  if (res[0]!=0) res[0][111]=a078;
  a078=(a017*a080);
  a078=(-a078);
  if (res[0]!=0) res[0][112]=a078;
  a078=(a017*a085);
  a078=(-a078);
  if (res[0]!=0) res[0][113]=a078;
  a078=(a019*a089);
  a078=(-a078);
  if (res[0]!=0) res[0][114]=a078;
  a078=(a019*a080);
  a078=(-a078);
  if (res[0]!=0) res[0][115]=a078;
  a078=(a019*a085);
  a078=(-a078);
  if (res[0]!=0) res[0][116]=a078;
  a078=(a002*a089);
  a078=(-a078);
  if (res[0]!=0) res[0][117]=a078;
  a078=(a002*a080);
  a078=(-a078);
  if (res[0]!=0) res[0][118]=a078;
  a078=(a002*a085);
  a078=(-a078);
  if (res[0]!=0) res[0][119]=a078;
  if (res[0]!=0) res[0][120]=a004;
  if (res[0]!=0) res[0][121]=a004;
  if (res[0]!=0) res[0][122]=a004;
  if (res[0]!=0) res[0][123]=a004;
  if (res[0]!=0) res[0][124]=a004;
  if (res[0]!=0) res[0][125]=a000;
  if (res[0]!=0) res[0][126]=a004;
  if (res[0]!=0) res[0][127]=a004;
  if (res[0]!=0) res[0][128]=a004;
  a053=(a039*a053);
  a055=(a055-a053);
  a053=(a075*a055);
  a000=(2.*a039);
  a067=(a000*a067);
  a067=(a067+a077);
  a067=(a067+a094);
  a094=(a038*a067);
  a029=(a039*a029);
  a029=(a029+a031);
  a031=(a044*a029);
  a094=(a094+a031);
  a094=(a053-a094);
  a094=(a094/a001);
  if (res[0]!=0) res[0][129]=a094;
  a094=(a089*a055);
  a031=(a085*a067);
  a077=(a080*a029);
  a031=(a031+a077);
  a094=(a094-a031);
  a094=(a094/a001);
  if (res[0]!=0) res[0][130]=a094;
  a094=(a097*a055);
  a031=(a093*a067);
  a078=(a090*a029);
  a078=(a031+a078);
  a094=(a094-a078);
  a094=(a094/a001);
  if (res[0]!=0) res[0][131]=a094;
  a094=(a043*a067);
  a078=(a037*a029);
  a094=(a094+a078);
  a053=(a053-a094);
  a053=(-a053);
  if (res[0]!=0) res[0][132]=a053;
  a053=(a045*a055);
  a067=(a084*a067);
  a067=(a067+a077);
  a053=(a053-a067);
  a053=(-a053);
  if (res[0]!=0) res[0][133]=a053;
  a055=(a096*a055);
  a029=(a082*a029);
  a031=(a031+a029);
  a055=(a055-a031);
  a055=(-a055);
  if (res[0]!=0) res[0][134]=a055;
  a055=(a017*a097);
  a055=(-a055);
  if (res[0]!=0) res[0][135]=a055;
  a055=(a017*a090);
  a055=(-a055);
  if (res[0]!=0) res[0][136]=a055;
  a055=(a017*a093);
  a055=(-a055);
  if (res[0]!=0) res[0][137]=a055;
  a055=(a019*a097);
  a055=(-a055);
  if (res[0]!=0) res[0][138]=a055;
  a055=(a019*a090);
  a055=(-a055);
  if (res[0]!=0) res[0][139]=a055;
  a055=(a019*a093);
  a055=(-a055);
  if (res[0]!=0) res[0][140]=a055;
  a055=(a002*a097);
  a055=(-a055);
  if (res[0]!=0) res[0][141]=a055;
  a055=(a002*a090);
  a055=(-a055);
  if (res[0]!=0) res[0][142]=a055;
  a055=(a002*a093);
  a055=(-a055);
  if (res[0]!=0) res[0][143]=a055;
  a055=casadi_sq(a001);
  a031=(a019*a055);
  a029=(a042*a031);
  a029=(a029/a003);
  a029=(-a029);
  if (res[0]!=0) res[0][144]=a029;
  a029=(a065*a031);
  a029=(a029/a003);
  a029=(-a029);
  if (res[0]!=0) res[0][145]=a029;
  a029=(a073*a031);
  a029=(a029/a003);
  a029=(-a029);
  if (res[0]!=0) res[0][146]=a029;
  a029=(a017*a055);
  a053=(a075*a029);
  a053=(a053/a003);
  a053=(-a053);
  if (res[0]!=0) res[0][147]=a053;
  a053=(a089*a029);
  a053=(a053/a003);
  a053=(-a053);
  if (res[0]!=0) res[0][148]=a053;
  a053=(a097*a029);
  a053=(a053/a003);
  a053=(-a053);
  if (res[0]!=0) res[0][149]=a053;
  a053=arg[0]? arg[0][1] : 0;
  a067=(a053*a031);
  a077=(a002*a067);
  a094=arg[0]? arg[0][2] : 0;
  a078=(a094*a031);
  a021=(a019*a078);
  a076=(a009*a021);
  a076=(a077-a076);
  a026=(a036*a076);
  a078=(a002*a078);
  a067=(a019*a067);
  a081=(a009*a067);
  a081=(a078+a081);
  a088=(a012*a081);
  a026=(a026-a088);
  a088=(a005*a021);
  a088=(a001-a088);
  a086=(a008*a067);
  a064=(a088-a086);
  a091=arg[0]? arg[0][0] : 0;
  a050=(a091*a031);
  a098=(a019*a050);
  a099=(a046*a098);
  a064=(a064-a099);
  a099=(a042*a064);
  a026=(a026+a099);
  a026=(a026/a001);
  if (res[0]!=0) res[0][150]=a026;
  a026=(a061*a076);
  a100=(a056*a081);
  a026=(a026-a100);
  a101=(a065*a064);
  a026=(a026+a101);
  a026=(a026/a001);
  if (res[0]!=0) res[0][151]=a026;
  a026=(a069*a076);
  a101=(a066*a081);
  a101=(a026-a101);
  a102=(a073*a064);
  a101=(a101+a102);
  a101=(a101/a001);
  if (res[0]!=0) res[0][152]=a101;
  a101=arg[0]? arg[0][4] : 0;
  a102=(a101*a029);
  a103=(a002*a102);
  a104=arg[0]? arg[0][5] : 0;
  a105=(a104*a029);
  a106=(a019*a105);
  a107=(a054*a106);
  a107=(a103-a107);
  a108=(a038*a107);
  a105=(a002*a105);
  a102=(a019*a102);
  a109=(a054*a102);
  a109=(a105+a109);
  a110=(a044*a109);
  a108=(a108-a110);
  a110=(a039*a106);
  a111=(a030*a102);
  a112=(a110+a111);
  a113=arg[0]? arg[0][3] : 0;
  a114=(a113*a029);
  a115=(a019*a114);
  a116=(a079*a115);
  a112=(a112+a116);
  a116=(a075*a112);
  a108=(a108-a116);
  a108=(a108/a001);
  if (res[0]!=0) res[0][153]=a108;
  a108=(a085*a107);
  a117=(a080*a109);
  a108=(a108-a117);
  a118=(a089*a112);
  a108=(a108-a118);
  a108=(a108/a001);
  if (res[0]!=0) res[0][154]=a108;
  a108=(a093*a107);
  a118=(a090*a109);
  a118=(a108-a118);
  a119=(a097*a112);
  a118=(a118-a119);
  a118=(a118/a001);
  if (res[0]!=0) res[0][155]=a118;
  a118=(a043*a107);
  a119=(a037*a109);
  a118=(a118-a119);
  a118=(a118-a116);
  a116=(a034*a076);
  a118=(a118+a116);
  a116=(a010*a081);
  a118=(a118-a116);
  a118=(a118+a099);
  a118=(-a118);
  if (res[0]!=0) res[0][156]=a118;
  a107=(a084*a107);
  a107=(a107-a117);
  a117=(a045*a112);
  a107=(a107-a117);
  a076=(a060*a076);
  a107=(a107+a076);
  a107=(a107-a100);
  a100=(a007*a064);
  a107=(a107+a100);
  a107=(-a107);
  if (res[0]!=0) res[0][157]=a107;
  a109=(a082*a109);
  a108=(a108-a109);
  a112=(a096*a112);
  a108=(a108-a112);
  a108=(a108+a026);
  a081=(a058*a081);
  a108=(a108-a081);
  a064=(a072*a064);
  a108=(a108+a064);
  a108=(-a108);
  if (res[0]!=0) res[0][158]=a108;
  if (res[0]!=0) res[0][159]=a004;
  if (res[0]!=0) res[0][160]=a004;
  if (res[0]!=0) res[0][161]=a004;
  if (res[0]!=0) res[0][162]=a004;
  if (res[0]!=0) res[0][163]=a004;
  if (res[0]!=0) res[0][164]=a004;
  if (res[0]!=0) res[0][165]=a004;
  if (res[0]!=0) res[0][166]=a004;
  if (res[0]!=0) res[0][167]=a004;
  a108=(a012*a031);
  a108=(a108/a003);
  a108=(-a108);
  if (res[0]!=0) res[0][168]=a108;
  a108=(a056*a031);
  a108=(a108/a003);
  a108=(-a108);
  if (res[0]!=0) res[0][169]=a108;
  a108=(a066*a031);
  a108=(a108/a003);
  a108=(-a108);
  if (res[0]!=0) res[0][170]=a108;
  a108=(a044*a029);
  a108=(a108/a003);
  a108=(-a108);
  if (res[0]!=0) res[0][171]=a108;
  a108=(a080*a029);
  a108=(a108/a003);
  a108=(-a108);
  if (res[0]!=0) res[0][172]=a108;
  a108=(a090*a029);
  a108=(a108/a003);
  a108=(-a108);
  if (res[0]!=0) res[0][173]=a108;
  a108=(a062*a067);
  a088=(a088-a108);
  a108=(a009*a098);
  a088=(a088-a108);
  a064=(a012*a088);
  a081=(a008*a021);
  a050=(a002*a050);
  a081=(a081+a050);
  a026=(a036*a081);
  a064=(a064-a026);
  a026=(a008*a098);
  a078=(a078-a026);
  a026=(a042*a078);
  a064=(a064+a026);
  a064=(a064/a001);
  if (res[0]!=0) res[0][174]=a064;
  a064=(a056*a088);
  a112=(a061*a081);
  a112=(a064-a112);
  a109=(a065*a078);
  a112=(a112+a109);
  a112=(a112/a001);
  if (res[0]!=0) res[0][175]=a112;
  a112=(a066*a088);
  a109=(a069*a081);
  a112=(a112-a109);
  a107=(a073*a078);
  a112=(a112+a107);
  a112=(a112/a001);
  if (res[0]!=0) res[0][176]=a112;
  a112=(a030*a115);
  a105=(a105-a112);
  a112=(a075*a105);
  a107=(a030*a106);
  a114=(a002*a114);
  a107=(a107+a114);
  a100=(a038*a107);
  a076=(a035*a102);
  a110=(a110+a076);
  a076=(a054*a115);
  a110=(a110+a076);
  a117=(a044*a110);
  a100=(a100+a117);
  a100=(a112-a100);
  a100=(a100/a001);
  if (res[0]!=0) res[0][177]=a100;
  a100=(a089*a105);
  a117=(a085*a107);
  a118=(a080*a110);
  a117=(a117+a118);
  a100=(a100-a117);
  a100=(a100/a001);
  if (res[0]!=0) res[0][178]=a100;
  a100=(a097*a105);
  a117=(a093*a107);
  a099=(a090*a110);
  a099=(a117+a099);
  a100=(a100-a099);
  a100=(a100/a001);
  if (res[0]!=0) res[0][179]=a100;
  a100=(a043*a107);
  a099=(a037*a110);
  a100=(a100+a099);
  a112=(a112-a100);
  a100=(a034*a081);
  a112=(a112-a100);
  a100=(a010*a088);
  a112=(a112+a100);
  a112=(a112+a026);
  a112=(-a112);
  if (res[0]!=0) res[0][180]=a112;
  a112=(a045*a105);
  a107=(a084*a107);
  a107=(a107+a118);
  a112=(a112-a107);
  a081=(a060*a081);
  a112=(a112-a081);
  a112=(a112+a064);
  a064=(a007*a078);
  a112=(a112+a064);
  a112=(-a112);
  if (res[0]!=0) res[0][181]=a112;
  a105=(a096*a105);
  a110=(a082*a110);
  a117=(a117+a110);
  a105=(a105-a117);
  a105=(a105-a109);
  a088=(a058*a088);
  a105=(a105+a088);
  a078=(a072*a078);
  a105=(a105+a078);
  a105=(-a105);
  if (res[0]!=0) res[0][182]=a105;
  if (res[0]!=0) res[0][183]=a004;
  if (res[0]!=0) res[0][184]=a004;
  if (res[0]!=0) res[0][185]=a004;
  if (res[0]!=0) res[0][186]=a004;
  if (res[0]!=0) res[0][187]=a004;
  if (res[0]!=0) res[0][188]=a004;
  if (res[0]!=0) res[0][189]=a004;
  if (res[0]!=0) res[0][190]=a004;
  if (res[0]!=0) res[0][191]=a004;
  a105=(a036*a031);
  a105=(a105/a003);
  a105=(-a105);
  if (res[0]!=0) res[0][192]=a105;
  a105=(a061*a031);
  a105=(a105/a003);
  a105=(-a105);
  if (res[0]!=0) res[0][193]=a105;
  a105=(a069*a031);
  a105=(a105/a003);
  a105=(-a105);
  if (res[0]!=0) res[0][194]=a105;
  a105=(a038*a029);
  a105=(a105/a003);
  a105=(-a105);
  if (res[0]!=0) res[0][195]=a105;
  a105=(a085*a029);
  a105=(a105/a003);
  a105=(-a105);
  if (res[0]!=0) res[0][196]=a105;
  a029=(a093*a029);
  a029=(a029/a003);
  a029=(-a029);
  if (res[0]!=0) res[0][197]=a029;
  a021=(a070*a021);
  a021=(a001-a021);
  a021=(a021-a086);
  a021=(a021-a108);
  a108=(a036*a021);
  a067=(a005*a067);
  a050=(a050-a067);
  a067=(a012*a050);
  a108=(a108+a067);
  a098=(a005*a098);
  a077=(a077+a098);
  a098=(a042*a077);
  a108=(a108-a098);
  a108=(a108/a001);
  if (res[0]!=0) res[0][198]=a108;
  a108=(a061*a021);
  a067=(a056*a050);
  a108=(a108+a067);
  a086=(a065*a077);
  a108=(a108-a086);
  a108=(a108/a001);
  if (res[0]!=0) res[0][199]=a108;
  a108=(a069*a021);
  a086=(a066*a050);
  a086=(a108+a086);
  a029=(a073*a077);
  a086=(a086-a029);
  a086=(a086/a001);
  if (res[0]!=0) res[0][200]=a086;
  a102=(a039*a102);
  a114=(a114-a102);
  a102=(a044*a114);
  a106=(a000*a106);
  a106=(a106+a111);
  a106=(a106+a076);
  a076=(a038*a106);
  a102=(a102-a076);
  a115=(a039*a115);
  a103=(a103+a115);
  a115=(a075*a103);
  a102=(a102-a115);
  a102=(a102/a001);
  if (res[0]!=0) res[0][201]=a102;
  a102=(a080*a114);
  a076=(a085*a106);
  a076=(a102-a076);
  a111=(a089*a103);
  a076=(a076-a111);
  a076=(a076/a001);
  if (res[0]!=0) res[0][202]=a076;
  a076=(a090*a114);
  a111=(a093*a106);
  a076=(a076-a111);
  a086=(a097*a103);
  a076=(a076-a086);
  a076=(a076/a001);
  if (res[0]!=0) res[0][203]=a076;
  a076=(a037*a114);
  a086=(a043*a106);
  a076=(a076-a086);
  a076=(a076-a115);
  a115=(a034*a021);
  a076=(a076+a115);
  a115=(a010*a050);
  a076=(a076+a115);
  a076=(a076-a098);
  a076=(-a076);
  if (res[0]!=0) res[0][204]=a076;
  a106=(a084*a106);
  a102=(a102-a106);
  a106=(a045*a103);
  a102=(a102-a106);
  a021=(a060*a021);
  a102=(a102+a021);
  a102=(a102+a067);
  a067=(a007*a077);
  a102=(a102-a067);
  a102=(-a102);
  if (res[0]!=0) res[0][205]=a102;
  a114=(a082*a114);
  a114=(a114-a111);
  a103=(a096*a103);
  a114=(a114-a103);
  a114=(a114+a108);
  a050=(a058*a050);
  a114=(a114+a050);
  a077=(a072*a077);
  a114=(a114-a077);
  a114=(-a114);
  if (res[0]!=0) res[0][206]=a114;
  if (res[0]!=0) res[0][207]=a004;
  if (res[0]!=0) res[0][208]=a004;
  if (res[0]!=0) res[0][209]=a004;
  if (res[0]!=0) res[0][210]=a004;
  if (res[0]!=0) res[0][211]=a004;
  if (res[0]!=0) res[0][212]=a004;
  if (res[0]!=0) res[0][213]=a004;
  if (res[0]!=0) res[0][214]=a004;
  if (res[0]!=0) res[0][215]=a004;
  a055=(a015*a055);
  a114=(a042*a055);
  a114=(a114/a003);
  a114=(-a114);
  if (res[0]!=0) res[0][216]=a114;
  a114=(a065*a055);
  a114=(a114/a003);
  a114=(-a114);
  if (res[0]!=0) res[0][217]=a114;
  a114=(a073*a055);
  a114=(a114/a003);
  a114=(-a114);
  if (res[0]!=0) res[0][218]=a114;
  a114=(a075*a031);
  a114=(a114/a003);
  a114=(-a114);
  if (res[0]!=0) res[0][219]=a114;
  a114=(a089*a031);
  a114=(a114/a003);
  a114=(-a114);
  if (res[0]!=0) res[0][220]=a114;
  a114=(a097*a031);
  a114=(a114/a003);
  a114=(-a114);
  if (res[0]!=0) res[0][221]=a114;
  a114=(a053*a055);
  a077=(a002*a114);
  a050=(a094*a055);
  a108=(a019*a050);
  a103=(a009*a108);
  a103=(a077-a103);
  a111=(a036*a103);
  a050=(a002*a050);
  a114=(a019*a114);
  a102=(a009*a114);
  a102=(a050+a102);
  a067=(a012*a102);
  a111=(a111-a067);
  a067=(a005*a108);
  a021=(a008*a114);
  a106=(a067+a021);
  a076=(a091*a055);
  a098=(a019*a076);
  a115=(a046*a098);
  a106=(a106+a115);
  a115=(a042*a106);
  a111=(a111-a115);
  a111=(a111/a001);
  if (res[0]!=0) res[0][222]=a111;
  a111=(a061*a103);
  a086=(a056*a102);
  a111=(a111-a086);
  a029=(a065*a106);
  a111=(a111-a029);
  a111=(a111/a001);
  if (res[0]!=0) res[0][223]=a111;
  a111=(a069*a103);
  a029=(a066*a102);
  a029=(a111-a029);
  a105=(a073*a106);
  a029=(a029-a105);
  a029=(a029/a001);
  if (res[0]!=0) res[0][224]=a029;
  a029=(a101*a031);
  a105=(a002*a029);
  a078=(a104*a031);
  a088=(a019*a078);
  a109=(a054*a088);
  a109=(a105-a109);
  a117=(a038*a109);
  a078=(a002*a078);
  a029=(a019*a029);
  a110=(a054*a029);
  a110=(a078+a110);
  a112=(a044*a110);
  a117=(a117-a112);
  a112=(a039*a088);
  a112=(a001-a112);
  a064=(a030*a029);
  a081=(a112-a064);
  a107=(a113*a031);
  a118=(a019*a107);
  a026=(a079*a118);
  a081=(a081-a026);
  a026=(a075*a081);
  a117=(a117+a026);
  a117=(a117/a001);
  if (res[0]!=0) res[0][225]=a117;
  a117=(a085*a109);
  a100=(a080*a110);
  a117=(a117-a100);
  a099=(a089*a081);
  a117=(a117+a099);
  a117=(a117/a001);
  if (res[0]!=0) res[0][226]=a117;
  a117=(a093*a109);
  a099=(a090*a110);
  a099=(a117-a099);
  a116=(a097*a081);
  a099=(a099+a116);
  a099=(a099/a001);
  if (res[0]!=0) res[0][227]=a099;
  a099=(a043*a109);
  a116=(a037*a110);
  a099=(a099-a116);
  a099=(a099+a026);
  a026=(a034*a103);
  a099=(a099+a026);
  a026=(a010*a102);
  a099=(a099-a026);
  a099=(a099-a115);
  a099=(-a099);
  if (res[0]!=0) res[0][228]=a099;
  a109=(a084*a109);
  a109=(a109-a100);
  a100=(a045*a081);
  a109=(a109+a100);
  a103=(a060*a103);
  a109=(a109+a103);
  a109=(a109-a086);
  a086=(a007*a106);
  a109=(a109-a086);
  a109=(-a109);
  if (res[0]!=0) res[0][229]=a109;
  a110=(a082*a110);
  a117=(a117-a110);
  a081=(a096*a081);
  a117=(a117+a081);
  a117=(a117+a111);
  a102=(a058*a102);
  a117=(a117-a102);
  a106=(a072*a106);
  a117=(a117-a106);
  a117=(-a117);
  if (res[0]!=0) res[0][230]=a117;
  if (res[0]!=0) res[0][231]=a004;
  if (res[0]!=0) res[0][232]=a004;
  if (res[0]!=0) res[0][233]=a004;
  if (res[0]!=0) res[0][234]=a004;
  if (res[0]!=0) res[0][235]=a004;
  if (res[0]!=0) res[0][236]=a004;
  if (res[0]!=0) res[0][237]=a004;
  if (res[0]!=0) res[0][238]=a004;
  if (res[0]!=0) res[0][239]=a004;
  a117=(a012*a055);
  a117=(a117/a003);
  a117=(-a117);
  if (res[0]!=0) res[0][240]=a117;
  a117=(a056*a055);
  a117=(a117/a003);
  a117=(-a117);
  if (res[0]!=0) res[0][241]=a117;
  a117=(a066*a055);
  a117=(a117/a003);
  a117=(-a117);
  if (res[0]!=0) res[0][242]=a117;
  a117=(a044*a031);
  a117=(a117/a003);
  a117=(-a117);
  if (res[0]!=0) res[0][243]=a117;
  a117=(a080*a031);
  a117=(a117/a003);
  a117=(-a117);
  if (res[0]!=0) res[0][244]=a117;
  a117=(a090*a031);
  a117=(a117/a003);
  a117=(-a117);
  if (res[0]!=0) res[0][245]=a117;
  a117=(a008*a098);
  a050=(a050-a117);
  a117=(a042*a050);
  a106=(a008*a108);
  a076=(a002*a076);
  a106=(a106+a076);
  a102=(a036*a106);
  a111=(a062*a114);
  a067=(a067+a111);
  a111=(a009*a098);
  a067=(a067+a111);
  a081=(a012*a067);
  a102=(a102+a081);
  a102=(a117-a102);
  a102=(a102/a001);
  if (res[0]!=0) res[0][246]=a102;
  a102=(a065*a050);
  a081=(a061*a106);
  a110=(a056*a067);
  a081=(a081+a110);
  a102=(a102-a081);
  a102=(a102/a001);
  if (res[0]!=0) res[0][247]=a102;
  a102=(a073*a050);
  a081=(a069*a106);
  a109=(a066*a067);
  a109=(a081+a109);
  a102=(a102-a109);
  a102=(a102/a001);
  if (res[0]!=0) res[0][248]=a102;
  a102=(a035*a029);
  a112=(a112-a102);
  a102=(a054*a118);
  a112=(a112-a102);
  a109=(a044*a112);
  a086=(a030*a088);
  a107=(a002*a107);
  a086=(a086+a107);
  a103=(a038*a086);
  a109=(a109-a103);
  a103=(a030*a118);
  a078=(a078-a103);
  a103=(a075*a078);
  a109=(a109+a103);
  a109=(a109/a001);
  if (res[0]!=0) res[0][249]=a109;
  a109=(a080*a112);
  a100=(a085*a086);
  a100=(a109-a100);
  a099=(a089*a078);
  a100=(a100+a099);
  a100=(a100/a001);
  if (res[0]!=0) res[0][250]=a100;
  a100=(a090*a112);
  a099=(a093*a086);
  a100=(a100-a099);
  a115=(a097*a078);
  a100=(a100+a115);
  a100=(a100/a001);
  if (res[0]!=0) res[0][251]=a100;
  a100=(a037*a112);
  a115=(a043*a086);
  a100=(a100-a115);
  a100=(a100+a103);
  a103=(a034*a106);
  a100=(a100-a103);
  a103=(a010*a067);
  a100=(a100-a103);
  a100=(a100+a117);
  a100=(-a100);
  if (res[0]!=0) res[0][252]=a100;
  a086=(a084*a086);
  a109=(a109-a086);
  a086=(a045*a078);
  a109=(a109+a086);
  a106=(a060*a106);
  a109=(a109-a106);
  a109=(a109-a110);
  a110=(a007*a050);
  a109=(a109+a110);
  a109=(-a109);
  if (res[0]!=0) res[0][253]=a109;
  a112=(a082*a112);
  a112=(a112-a099);
  a078=(a096*a078);
  a112=(a112+a078);
  a112=(a112-a081);
  a067=(a058*a067);
  a112=(a112-a067);
  a050=(a072*a050);
  a112=(a112+a050);
  a112=(-a112);
  if (res[0]!=0) res[0][254]=a112;
  if (res[0]!=0) res[0][255]=a004;
  if (res[0]!=0) res[0][256]=a004;
  if (res[0]!=0) res[0][257]=a004;
  if (res[0]!=0) res[0][258]=a004;
  if (res[0]!=0) res[0][259]=a004;
  if (res[0]!=0) res[0][260]=a004;
  if (res[0]!=0) res[0][261]=a004;
  if (res[0]!=0) res[0][262]=a004;
  if (res[0]!=0) res[0][263]=a004;
  a112=(a036*a055);
  a112=(a112/a003);
  a112=(-a112);
  if (res[0]!=0) res[0][264]=a112;
  a112=(a061*a055);
  a112=(a112/a003);
  a112=(-a112);
  if (res[0]!=0) res[0][265]=a112;
  a055=(a069*a055);
  a055=(a055/a003);
  a055=(-a055);
  if (res[0]!=0) res[0][266]=a055;
  a055=(a038*a031);
  a055=(a055/a003);
  a055=(-a055);
  if (res[0]!=0) res[0][267]=a055;
  a055=(a085*a031);
  a055=(a055/a003);
  a055=(-a055);
  if (res[0]!=0) res[0][268]=a055;
  a031=(a093*a031);
  a031=(a031/a003);
  a031=(-a031);
  if (res[0]!=0) res[0][269]=a031;
  a114=(a005*a114);
  a076=(a076-a114);
  a114=(a012*a076);
  a108=(a070*a108);
  a108=(a108+a021);
  a108=(a108+a111);
  a111=(a036*a108);
  a114=(a114-a111);
  a098=(a005*a098);
  a077=(a077+a098);
  a098=(a042*a077);
  a114=(a114-a098);
  a114=(a114/a001);
  if (res[0]!=0) res[0][270]=a114;
  a114=(a056*a076);
  a111=(a061*a108);
  a111=(a114-a111);
  a021=(a065*a077);
  a111=(a111-a021);
  a111=(a111/a001);
  if (res[0]!=0) res[0][271]=a111;
  a111=(a066*a076);
  a021=(a069*a108);
  a111=(a111-a021);
  a031=(a073*a077);
  a111=(a111-a031);
  a111=(a111/a001);
  if (res[0]!=0) res[0][272]=a111;
  a088=(a000*a088);
  a088=(a001-a088);
  a088=(a088-a064);
  a088=(a088-a102);
  a102=(a038*a088);
  a029=(a039*a029);
  a107=(a107-a029);
  a029=(a044*a107);
  a102=(a102+a029);
  a118=(a039*a118);
  a105=(a105+a118);
  a118=(a075*a105);
  a102=(a102-a118);
  a102=(a102/a001);
  if (res[0]!=0) res[0][273]=a102;
  a102=(a085*a088);
  a029=(a080*a107);
  a102=(a102+a029);
  a064=(a089*a105);
  a102=(a102-a064);
  a102=(a102/a001);
  if (res[0]!=0) res[0][274]=a102;
  a102=(a093*a088);
  a064=(a090*a107);
  a064=(a102+a064);
  a111=(a097*a105);
  a064=(a064-a111);
  a064=(a064/a001);
  if (res[0]!=0) res[0][275]=a064;
  a064=(a043*a088);
  a111=(a037*a107);
  a064=(a064+a111);
  a064=(a064-a118);
  a118=(a034*a108);
  a064=(a064-a118);
  a118=(a010*a076);
  a064=(a064+a118);
  a064=(a064-a098);
  a064=(-a064);
  if (res[0]!=0) res[0][276]=a064;
  a088=(a084*a088);
  a088=(a088+a029);
  a029=(a045*a105);
  a088=(a088-a029);
  a108=(a060*a108);
  a088=(a088-a108);
  a088=(a088+a114);
  a114=(a007*a077);
  a088=(a088-a114);
  a088=(-a088);
  if (res[0]!=0) res[0][277]=a088;
  a107=(a082*a107);
  a102=(a102+a107);
  a105=(a096*a105);
  a102=(a102-a105);
  a102=(a102-a021);
  a076=(a058*a076);
  a102=(a102+a076);
  a077=(a072*a077);
  a102=(a102-a077);
  a102=(-a102);
  if (res[0]!=0) res[0][278]=a102;
  if (res[0]!=0) res[0][279]=a004;
  if (res[0]!=0) res[0][280]=a004;
  if (res[0]!=0) res[0][281]=a004;
  if (res[0]!=0) res[0][282]=a004;
  if (res[0]!=0) res[0][283]=a004;
  if (res[0]!=0) res[0][284]=a004;
  if (res[0]!=0) res[0][285]=a004;
  if (res[0]!=0) res[0][286]=a004;
  if (res[0]!=0) res[0][287]=a004;
  a102=(-a042);
  if (res[0]!=0) res[0][288]=a102;
  a102=(-a065);
  if (res[0]!=0) res[0][289]=a102;
  a102=(-a073);
  if (res[0]!=0) res[0][290]=a102;
  a102=(-a075);
  if (res[0]!=0) res[0][291]=a102;
  a102=(-a089);
  if (res[0]!=0) res[0][292]=a102;
  a102=(-a097);
  if (res[0]!=0) res[0][293]=a102;
  a102=(a053*a003);
  a077=(a002*a102);
  a076=(a094*a003);
  a021=(a019*a076);
  a105=(a009*a021);
  a105=(a077-a105);
  a107=(a036*a105);
  a088=(a002*a076);
  a114=(a019*a102);
  a108=(a009*a114);
  a108=(a088+a108);
  a029=(a012*a108);
  a107=(a107-a029);
  a029=(a005*a021);
  a064=(a008*a114);
  a098=(a029+a064);
  a118=(a091*a003);
  a111=(a019*a118);
  a031=(a046*a111);
  a098=(a098+a031);
  a031=(a042*a098);
  a107=(a107-a031);
  a107=(a107/a001);
  if (res[0]!=0) res[0][294]=a107;
  a107=(a061*a105);
  a055=(a056*a108);
  a107=(a107-a055);
  a112=(a065*a098);
  a107=(a107-a112);
  a107=(a107/a001);
  if (res[0]!=0) res[0][295]=a107;
  a107=(a069*a105);
  a112=(a066*a108);
  a112=(a107-a112);
  a050=(a073*a098);
  a112=(a112-a050);
  a112=(a112/a001);
  if (res[0]!=0) res[0][296]=a112;
  a112=(a101*a003);
  a050=(a002*a112);
  a067=(a104*a003);
  a081=(a019*a067);
  a078=(a054*a081);
  a078=(a050-a078);
  a099=(a038*a078);
  a109=(a002*a067);
  a110=(a019*a112);
  a106=(a054*a110);
  a106=(a109+a106);
  a086=(a044*a106);
  a099=(a099-a086);
  a086=(a039*a081);
  a100=(a030*a110);
  a117=(a086+a100);
  a103=(a113*a003);
  a115=(a019*a103);
  a026=(a079*a115);
  a117=(a117+a026);
  a026=(a075*a117);
  a099=(a099-a026);
  a099=(a099/a001);
  if (res[0]!=0) res[0][297]=a099;
  a099=(a085*a078);
  a116=(a080*a106);
  a099=(a099-a116);
  a119=(a089*a117);
  a099=(a099-a119);
  a099=(a099/a001);
  if (res[0]!=0) res[0][298]=a099;
  a099=(a093*a078);
  a119=(a090*a106);
  a119=(a099-a119);
  a120=(a097*a117);
  a119=(a119-a120);
  a119=(a119/a001);
  if (res[0]!=0) res[0][299]=a119;
  a119=arg[0]? arg[0][21] : 0;
  a119=(a001*a119);
  a120=casadi_sq(a119);
  a120=(a120/a011);
  a120=(a040+a120);
  a121=(a043*a078);
  a120=(a120+a121);
  a121=(a037*a106);
  a120=(a120-a121);
  a120=(a120-a026);
  a026=(a034*a105);
  a120=(a120+a026);
  a026=(a010*a108);
  a120=(a120-a026);
  a120=(a120-a031);
  a120=(-a120);
  if (res[0]!=0) res[0][300]=a120;
  a120=arg[0]? arg[0][23] : 0;
  a120=(a001*a120);
  a031=(a120/a006);
  a026=arg[0]? arg[0][22] : 0;
  a026=(a001*a026);
  a121=(a119*a026);
  a121=(a121/a011);
  a121=(a031+a121);
  a078=(a084*a078);
  a121=(a121+a078);
  a121=(a121-a116);
  a116=(a045*a117);
  a121=(a121-a116);
  a105=(a060*a105);
  a121=(a121+a105);
  a121=(a121-a055);
  a055=(a007*a098);
  a121=(a121-a055);
  a121=(-a121);
  if (res[0]!=0) res[0][301]=a121;
  a121=(a119*a120);
  a121=(a121/a011);
  a055=(a026/a006);
  a121=(a121-a055);
  a121=(a121+a099);
  a106=(a082*a106);
  a121=(a121-a106);
  a117=(a096*a117);
  a121=(a121-a117);
  a121=(a121+a107);
  a108=(a058*a108);
  a121=(a121-a108);
  a098=(a072*a098);
  a121=(a121-a098);
  a121=(-a121);
  if (res[0]!=0) res[0][302]=a121;
  if (res[0]!=0) res[0][303]=a004;
  if (res[0]!=0) res[0][304]=a004;
  if (res[0]!=0) res[0][305]=a004;
  if (res[0]!=0) res[0][306]=a004;
  if (res[0]!=0) res[0][307]=a004;
  if (res[0]!=0) res[0][308]=a004;
  if (res[0]!=0) res[0][309]=a004;
  if (res[0]!=0) res[0][310]=a004;
  if (res[0]!=0) res[0][311]=a004;
  a121=(-a012);
  if (res[0]!=0) res[0][312]=a121;
  a121=(-a056);
  if (res[0]!=0) res[0][313]=a121;
  a121=(-a066);
  if (res[0]!=0) res[0][314]=a121;
  a121=(-a044);
  if (res[0]!=0) res[0][315]=a121;
  a121=(-a080);
  if (res[0]!=0) res[0][316]=a121;
  a121=(-a090);
  if (res[0]!=0) res[0][317]=a121;
  a121=(a008*a111);
  a088=(a088-a121);
  a121=(a042*a088);
  a098=(a008*a021);
  a108=(a002*a118);
  a098=(a098+a108);
  a107=(a036*a098);
  a117=(a062*a114);
  a029=(a029+a117);
  a117=(a009*a111);
  a029=(a029+a117);
  a106=(a012*a029);
  a107=(a107+a106);
  a107=(a121-a107);
  a107=(a107/a001);
  if (res[0]!=0) res[0][318]=a107;
  a107=(a065*a088);
  a106=(a061*a098);
  a099=(a056*a029);
  a106=(a106+a099);
  a107=(a107-a106);
  a107=(a107/a001);
  if (res[0]!=0) res[0][319]=a107;
  a107=(a073*a088);
  a106=(a069*a098);
  a105=(a066*a029);
  a105=(a106+a105);
  a107=(a107-a105);
  a107=(a107/a001);
  if (res[0]!=0) res[0][320]=a107;
  a107=(a030*a115);
  a109=(a109-a107);
  a107=(a075*a109);
  a105=(a030*a081);
  a116=(a002*a103);
  a105=(a105+a116);
  a078=(a038*a105);
  a122=(a035*a110);
  a086=(a086+a122);
  a122=(a054*a115);
  a086=(a086+a122);
  a123=(a044*a086);
  a078=(a078+a123);
  a078=(a107-a078);
  a078=(a078/a001);
  if (res[0]!=0) res[0][321]=a078;
  a078=(a089*a109);
  a123=(a085*a105);
  a124=(a080*a086);
  a123=(a123+a124);
  a078=(a078-a123);
  a078=(a078/a001);
  if (res[0]!=0) res[0][322]=a078;
  a078=(a097*a109);
  a123=(a093*a105);
  a125=(a090*a086);
  a125=(a123+a125);
  a078=(a078-a125);
  a078=(a078/a001);
  if (res[0]!=0) res[0][323]=a078;
  a078=(a026*a119);
  a078=(a078/a011);
  a078=(a078-a031);
  a031=(a043*a105);
  a078=(a078-a031);
  a031=(a037*a086);
  a078=(a078-a031);
  a078=(a078+a107);
  a107=(a034*a098);
  a078=(a078-a107);
  a107=(a010*a029);
  a078=(a078-a107);
  a078=(a078+a121);
  a078=(-a078);
  if (res[0]!=0) res[0][324]=a078;
  a078=casadi_sq(a026);
  a078=(a078/a011);
  a078=(a040+a078);
  a105=(a084*a105);
  a078=(a078-a105);
  a078=(a078-a124);
  a124=(a045*a109);
  a078=(a078+a124);
  a098=(a060*a098);
  a078=(a078-a098);
  a078=(a078-a099);
  a099=(a007*a088);
  a078=(a078+a099);
  a078=(-a078);
  if (res[0]!=0) res[0][325]=a078;
  a078=(a119/a006);
  a099=(a026*a120);
  a099=(a099/a011);
  a099=(a078+a099);
  a099=(a099-a123);
  a086=(a082*a086);
  a099=(a099-a086);
  a109=(a096*a109);
  a099=(a099+a109);
  a099=(a099-a106);
  a029=(a058*a029);
  a099=(a099-a029);
  a088=(a072*a088);
  a099=(a099+a088);
  a099=(-a099);
  if (res[0]!=0) res[0][326]=a099;
  if (res[0]!=0) res[0][327]=a004;
  if (res[0]!=0) res[0][328]=a004;
  if (res[0]!=0) res[0][329]=a004;
  if (res[0]!=0) res[0][330]=a004;
  if (res[0]!=0) res[0][331]=a004;
  if (res[0]!=0) res[0][332]=a004;
  if (res[0]!=0) res[0][333]=a004;
  if (res[0]!=0) res[0][334]=a004;
  if (res[0]!=0) res[0][335]=a004;
  a099=(-a036);
  if (res[0]!=0) res[0][336]=a099;
  a099=(-a061);
  if (res[0]!=0) res[0][337]=a099;
  a099=(-a069);
  if (res[0]!=0) res[0][338]=a099;
  a099=(-a038);
  if (res[0]!=0) res[0][339]=a099;
  a099=(-a085);
  if (res[0]!=0) res[0][340]=a099;
  a099=(-a093);
  if (res[0]!=0) res[0][341]=a099;
  a114=(a005*a114);
  a108=(a108-a114);
  a114=(a012*a108);
  a021=(a070*a021);
  a021=(a021+a064);
  a021=(a021+a117);
  a117=(a036*a021);
  a114=(a114-a117);
  a111=(a005*a111);
  a077=(a077+a111);
  a111=(a042*a077);
  a114=(a114-a111);
  a114=(a114/a001);
  if (res[0]!=0) res[0][342]=a114;
  a114=(a056*a108);
  a117=(a061*a021);
  a117=(a114-a117);
  a064=(a065*a077);
  a117=(a117-a064);
  a117=(a117/a001);
  if (res[0]!=0) res[0][343]=a117;
  a117=(a066*a108);
  a064=(a069*a021);
  a117=(a117-a064);
  a099=(a073*a077);
  a117=(a117-a099);
  a117=(a117/a001);
  if (res[0]!=0) res[0][344]=a117;
  a110=(a039*a110);
  a116=(a116-a110);
  a110=(a044*a116);
  a081=(a000*a081);
  a081=(a081+a100);
  a081=(a081+a122);
  a122=(a038*a081);
  a110=(a110-a122);
  a115=(a039*a115);
  a050=(a050+a115);
  a115=(a075*a050);
  a110=(a110-a115);
  a110=(a110/a001);
  if (res[0]!=0) res[0][345]=a110;
  a110=(a080*a116);
  a122=(a085*a081);
  a122=(a110-a122);
  a100=(a089*a050);
  a122=(a122-a100);
  a122=(a122/a001);
  if (res[0]!=0) res[0][346]=a122;
  a122=(a090*a116);
  a100=(a093*a081);
  a122=(a122-a100);
  a117=(a097*a050);
  a122=(a122-a117);
  a122=(a122/a001);
  if (res[0]!=0) res[0][347]=a122;
  a122=(a120*a119);
  a122=(a122/a011);
  a055=(a055+a122);
  a122=(a043*a081);
  a055=(a055-a122);
  a122=(a037*a116);
  a055=(a055+a122);
  a055=(a055-a115);
  a115=(a034*a021);
  a055=(a055-a115);
  a115=(a010*a108);
  a055=(a055+a115);
  a055=(a055-a111);
  a055=(-a055);
  if (res[0]!=0) res[0][348]=a055;
  a055=(a120*a026);
  a055=(a055/a011);
  a055=(a055-a078);
  a081=(a084*a081);
  a055=(a055-a081);
  a055=(a055+a110);
  a110=(a045*a050);
  a055=(a055-a110);
  a021=(a060*a021);
  a055=(a055-a021);
  a055=(a055+a114);
  a114=(a007*a077);
  a055=(a055-a114);
  a055=(-a055);
  if (res[0]!=0) res[0][349]=a055;
  a055=casadi_sq(a120);
  a055=(a055/a011);
  a055=(a040+a055);
  a055=(a055-a100);
  a116=(a082*a116);
  a055=(a055+a116);
  a050=(a096*a050);
  a055=(a055-a050);
  a055=(a055-a064);
  a108=(a058*a108);
  a055=(a055+a108);
  a077=(a072*a077);
  a055=(a055-a077);
  a055=(-a055);
  if (res[0]!=0) res[0][350]=a055;
  if (res[0]!=0) res[0][351]=a004;
  if (res[0]!=0) res[0][352]=a004;
  if (res[0]!=0) res[0][353]=a004;
  if (res[0]!=0) res[0][354]=a004;
  if (res[0]!=0) res[0][355]=a004;
  if (res[0]!=0) res[0][356]=a004;
  if (res[0]!=0) res[0][357]=a004;
  if (res[0]!=0) res[0][358]=a004;
  if (res[0]!=0) res[0][359]=a004;
  a055=(a005*a001);
  a077=(a019*a055);
  a108=(a018*a077);
  a064=(a008*a001);
  a050=(a019*a064);
  a116=(a027*a050);
  a100=(a108+a116);
  a114=(a046*a001);
  a021=(a019*a114);
  a110=(a051*a021);
  a100=(a100+a110);
  a100=(a100/a003);
  a100=(-a100);
  if (res[0]!=0) res[0][360]=a100;
  a100=(a018*a003);
  a110=(a051*a050);
  a110=(a100+a110);
  a110=(a110/a003);
  a110=(-a110);
  if (res[0]!=0) res[0][361]=a110;
  a110=(a051*a077);
  a081=(a027*a003);
  a110=(a110-a081);
  a110=(a110/a003);
  a110=(-a110);
  if (res[0]!=0) res[0][362]=a110;
  if (res[0]!=0) res[0][363]=a004;
  if (res[0]!=0) res[0][364]=a004;
  if (res[0]!=0) res[0][365]=a004;
  a110=(a094*a018);
  a110=(a019*a110);
  a078=(a070*a110);
  a020=(a020-a078);
  a078=(a053*a018);
  a111=(a019*a078);
  a115=(a008*a111);
  a020=(a020-a115);
  a115=(a091*a018);
  a122=(a019*a115);
  a117=(a009*a122);
  a020=(a020-a117);
  a117=(a094*a027);
  a099=(a019*a117);
  a088=(a008*a099);
  a020=(a020-a088);
  a088=(a091*a027);
  a029=(a002*a088);
  a020=(a020-a029);
  a029=(a094*a051);
  a106=(a019*a029);
  a109=(a009*a106);
  a020=(a020-a109);
  a109=(a053*a051);
  a086=(a002*a109);
  a020=(a020+a086);
  a086=(a020*a077);
  a123=(a122*a001);
  a098=(a106*a001);
  a123=(a123+a098);
  a098=(a036*a123);
  a098=(a086-a098);
  a115=(a002*a115);
  a124=(a005*a111);
  a115=(a115-a124);
  a115=(a115+a028);
  a028=(a005*a099);
  a115=(a115-a028);
  a028=(a053*a027);
  a028=(a019*a028);
  a124=(a062*a028);
  a115=(a115-a124);
  a088=(a019*a088);
  a124=(a009*a088);
  a115=(a115-a124);
  a029=(a002*a029);
  a115=(a115-a029);
  a109=(a019*a109);
  a029=(a009*a109);
  a115=(a115-a029);
  a029=(a115*a050);
  a124=(a088*a001);
  a105=(a109*a001);
  a124=(a124+a105);
  a105=(a012*a124);
  a105=(a029-a105);
  a098=(a098+a105);
  a117=(a002*a117);
  a078=(a002*a078);
  a122=(a005*a122);
  a078=(a078+a122);
  a117=(a117-a078);
  a088=(a008*a088);
  a117=(a117-a088);
  a117=(a117+a052);
  a106=(a005*a106);
  a117=(a117-a106);
  a109=(a008*a109);
  a117=(a117-a109);
  a109=(a091*a051);
  a109=(a019*a109);
  a046=(a046*a109);
  a117=(a117-a046);
  a046=(a117*a021);
  a106=(2.*a001);
  a109=(a109*a106);
  a052=(a042*a109);
  a046=(a046-a052);
  a098=(a098+a046);
  a052=-7.3575000000000003e+01;
  a052=(a052*a001);
  a088=arg[1]? arg[1][2] : 0;
  a078=(a041+a032);
  a078=(a078+a068);
  a078=(a011+a078);
  a122=(a011/a078);
  a055=(a002*a055);
  a055=(a122*a055);
  a033=(a033/a006);
  a033=(a008+a033);
  a078=(a122/a078);
  a105=(a078*a114);
  a121=(a033*a105);
  a121=(a055-a121);
  a121=(a088*a121);
  a107=arg[1]? arg[1][5] : 0;
  a059=(a059/a006);
  a059=(a059-a009);
  a031=(a059*a105);
  a125=(a122*a001);
  a031=(a031+a125);
  a031=(a107*a031);
  a121=(a121-a031);
  a031=arg[1]? arg[1][8] : 0;
  a114=(a002*a114);
  a114=(a122*a114);
  a041=(a032+a041);
  a041=(a041/a006);
  a126=(a041*a105);
  a114=(a114-a126);
  a114=(a031*a114);
  a121=(a121-a114);
  a121=(a052*a121);
  a098=(a098+a121);
  a098=(a098/a001);
  if (res[0]!=0) res[0][366]=a098;
  a098=(a020*a003);
  a121=(a061*a123);
  a121=(a098-a121);
  a114=(a056*a124);
  a121=(a121-a114);
  a126=(a117*a050);
  a127=(a065*a109);
  a127=(a126-a127);
  a121=(a121+a127);
  a121=(a121/a001);
  if (res[0]!=0) res[0][367]=a121;
  a121=(a117*a077);
  a127=(a073*a109);
  a127=(a121-a127);
  a128=(a069*a123);
  a129=(a115*a003);
  a130=(a066*a124);
  a130=(a129+a130);
  a130=(a128+a130);
  a127=(a127-a130);
  a068=(a068+a032);
  a068=(a068/a006);
  a032=(a068*a105);
  a032=(a088*a032);
  a064=(a002*a064);
  a064=(a122*a064);
  a063=(a063/a006);
  a005=(a005+a063);
  a063=(a005*a105);
  a063=(a064-a063);
  a063=(a107*a063);
  a032=(a032+a063);
  a071=(a071/a006);
  a071=(a071-a008);
  a105=(a071*a105);
  a105=(a055-a105);
  a105=(a031*a105);
  a032=(a032+a105);
  a032=(a052*a032);
  a127=(a127-a032);
  a127=(a127/a001);
  if (res[0]!=0) res[0][368]=a127;
  if (res[0]!=0) res[0][369]=a004;
  if (res[0]!=0) res[0][370]=a004;
  if (res[0]!=0) res[0][371]=a004;
  a127=(a034*a123);
  a127=(a086-a127);
  a032=(a010*a124);
  a032=(a029-a032);
  a127=(a127+a032);
  a127=(a127+a046);
  a127=(-a127);
  if (res[0]!=0) res[0][372]=a127;
  a127=(a007*a109);
  a126=(a126-a127);
  a127=(a060*a123);
  a127=(a098+a127);
  a127=(a127+a114);
  a126=(a126-a127);
  a126=(-a126);
  if (res[0]!=0) res[0][373]=a126;
  a126=(a058*a124);
  a126=(a129-a126);
  a126=(a126-a128);
  a109=(a072*a109);
  a121=(a121-a109);
  a126=(a126+a121);
  a126=(-a126);
  if (res[0]!=0) res[0][374]=a126;
  a021=(a091*a021);
  a126=(a053*a050);
  a021=(a021+a126);
  a121=(a094*a077);
  a021=(a021+a121);
  a109=(a019*a021);
  a109=(a040-a109);
  if (res[0]!=0) res[0][375]=a109;
  a109=(a091*a050);
  a109=(a109-a076);
  a128=(a019*a109);
  a128=(-a128);
  if (res[0]!=0) res[0][376]=a128;
  a128=(a091*a077);
  a128=(a128+a102);
  a127=(a019*a128);
  a127=(-a127);
  if (res[0]!=0) res[0][377]=a127;
  a127=(a015*a021);
  a127=(-a127);
  if (res[0]!=0) res[0][378]=a127;
  a127=(a015*a109);
  a127=(-a127);
  if (res[0]!=0) res[0][379]=a127;
  a127=(a015*a128);
  a127=(-a127);
  if (res[0]!=0) res[0][380]=a127;
  a021=(a002*a021);
  a021=(-a021);
  if (res[0]!=0) res[0][381]=a021;
  a109=(a002*a109);
  a109=(-a109);
  if (res[0]!=0) res[0][382]=a109;
  a128=(a002*a128);
  a128=(-a128);
  if (res[0]!=0) res[0][383]=a128;
  a009=(a009*a001);
  a128=(a019*a009);
  a109=(a027*a128);
  a109=(a109-a100);
  a109=(a109/a003);
  a109=(-a109);
  if (res[0]!=0) res[0][384]=a109;
  a062=(a062*a001);
  a109=(a019*a062);
  a100=(a027*a109);
  a108=(a108+a100);
  a100=(a051*a128);
  a108=(a108+a100);
  a108=(a108/a003);
  a108=(-a108);
  if (res[0]!=0) res[0][385]=a108;
  a027=(a027*a077);
  a051=(a051*a003);
  a027=(a027+a051);
  a027=(a027/a003);
  a027=(-a027);
  if (res[0]!=0) res[0][386]=a027;
  if (res[0]!=0) res[0][387]=a004;
  if (res[0]!=0) res[0][388]=a004;
  if (res[0]!=0) res[0][389]=a004;
  a027=(a115*a128);
  a028=(a028*a106);
  a108=(a012*a028);
  a108=(a027-a108);
  a111=(a111*a001);
  a099=(a099*a001);
  a111=(a111+a099);
  a099=(a036*a111);
  a099=(a098+a099);
  a108=(a108-a099);
  a099=(a042*a124);
  a108=(a108-a099);
  a021=(a078*a062);
  a127=(a033*a021);
  a127=(a125-a127);
  a127=(a088*a127);
  a114=(a059*a021);
  a055=(a055-a114);
  a055=(a107*a055);
  a127=(a127+a055);
  a062=(a002*a062);
  a062=(a122*a062);
  a055=(a041*a021);
  a055=(a062-a055);
  a055=(a031*a055);
  a127=(a127-a055);
  a127=(a052*a127);
  a108=(a108+a127);
  a108=(a108/a001);
  if (res[0]!=0) res[0][390]=a108;
  a108=(a061*a111);
  a108=(a086-a108);
  a127=(a115*a109);
  a055=(a056*a028);
  a127=(a127-a055);
  a108=(a108+a127);
  a055=(a117*a128);
  a114=(a065*a124);
  a114=(a055-a114);
  a108=(a108+a114);
  a108=(a108/a001);
  if (res[0]!=0) res[0][391]=a108;
  a115=(a115*a077);
  a108=(a066*a028);
  a108=(a115-a108);
  a114=(a069*a111);
  a108=(a108-a114);
  a117=(a117*a003);
  a046=(a073*a124);
  a046=(a117-a046);
  a108=(a108+a046);
  a009=(a002*a009);
  a009=(a122*a009);
  a046=(a005*a021);
  a046=(a009-a046);
  a046=(a107*a046);
  a032=(a068*a021);
  a062=(a062-a032);
  a062=(a088*a062);
  a046=(a046-a062);
  a021=(a071*a021);
  a021=(a021+a125);
  a021=(a031*a021);
  a046=(a046-a021);
  a046=(a052*a046);
  a108=(a108-a046);
  a108=(a108/a001);
  if (res[0]!=0) res[0][392]=a108;
  if (res[0]!=0) res[0][393]=a004;
  if (res[0]!=0) res[0][394]=a004;
  if (res[0]!=0) res[0][395]=a004;
  a108=(a034*a111);
  a098=(a098-a108);
  a108=(a010*a028);
  a027=(a027-a108);
  a098=(a098+a027);
  a098=(a098-a099);
  a098=(-a098);
  if (res[0]!=0) res[0][396]=a098;
  a098=(a060*a111);
  a086=(a086-a098);
  a086=(a086+a127);
  a127=(a007*a124);
  a127=(a055-a127);
  a086=(a086+a127);
  a086=(-a086);
  if (res[0]!=0) res[0][397]=a086;
  a028=(a058*a028);
  a115=(a115-a028);
  a115=(a115-a114);
  a124=(a072*a124);
  a124=(a117+a124);
  a115=(a115-a124);
  a115=(-a115);
  if (res[0]!=0) res[0][398]=a115;
  a115=(a053*a128);
  a115=(a115+a076);
  a076=(a019*a115);
  a076=(-a076);
  if (res[0]!=0) res[0][399]=a076;
  a091=(a091*a128);
  a109=(a053*a109);
  a109=(a091+a109);
  a109=(a109+a121);
  a121=(a019*a109);
  a121=(a040-a121);
  if (res[0]!=0) res[0][400]=a121;
  a053=(a053*a077);
  a053=(a053-a118);
  a077=(a019*a053);
  a077=(-a077);
  if (res[0]!=0) res[0][401]=a077;
  a077=(a015*a115);
  a077=(-a077);
  if (res[0]!=0) res[0][402]=a077;
  a077=(a015*a109);
  a077=(-a077);
  if (res[0]!=0) res[0][403]=a077;
  a077=(a015*a053);
  a077=(-a077);
  if (res[0]!=0) res[0][404]=a077;
  a115=(a002*a115);
  a115=(-a115);
  if (res[0]!=0) res[0][405]=a115;
  a109=(a002*a109);
  a109=(-a109);
  if (res[0]!=0) res[0][406]=a109;
  a053=(a002*a053);
  a053=(-a053);
  if (res[0]!=0) res[0][407]=a053;
  a053=(a018*a128);
  a053=(a053+a081);
  a053=(a053/a003);
  a053=(-a053);
  if (res[0]!=0) res[0][408]=a053;
  a053=(a018*a050);
  a053=(a053-a051);
  a053=(a053/a003);
  a053=(-a053);
  if (res[0]!=0) res[0][409]=a053;
  a070=(a070*a001);
  a053=(a019*a070);
  a018=(a018*a053);
  a018=(a018+a116);
  a018=(a018+a100);
  a018=(a018/a003);
  a018=(-a018);
  if (res[0]!=0) res[0][410]=a018;
  if (res[0]!=0) res[0][411]=a004;
  if (res[0]!=0) res[0][412]=a004;
  if (res[0]!=0) res[0][413]=a004;
  a018=(a020*a128);
  a110=(a110*a106);
  a036=(a036*a110);
  a036=(a018-a036);
  a012=(a012*a111);
  a012=(a129-a012);
  a036=(a036+a012);
  a042=(a042*a123);
  a036=(a036-a042);
  a078=(a078*a070);
  a033=(a033*a078);
  a033=(a009-a033);
  a033=(a088*a033);
  a059=(a059*a078);
  a064=(a064-a059);
  a064=(a107*a064);
  a033=(a033+a064);
  a041=(a041*a078);
  a041=(a031*a041);
  a033=(a033+a041);
  a033=(a052*a033);
  a036=(a036+a033);
  a036=(a036/a001);
  if (res[0]!=0) res[0][414]=a036;
  a036=(a020*a050);
  a061=(a061*a110);
  a061=(a036-a061);
  a056=(a056*a111);
  a061=(a061-a056);
  a065=(a065*a123);
  a065=(a117+a065);
  a061=(a061-a065);
  a061=(a061/a001);
  if (res[0]!=0) res[0][415]=a061;
  a020=(a020*a053);
  a069=(a069*a110);
  a020=(a020-a069);
  a066=(a066*a111);
  a066=(a029-a066);
  a066=(a020+a066);
  a073=(a073*a123);
  a073=(a055-a073);
  a066=(a066+a073);
  a005=(a005*a078);
  a125=(a125-a005);
  a125=(a107*a125);
  a070=(a002*a070);
  a122=(a122*a070);
  a068=(a068*a078);
  a122=(a122-a068);
  a122=(a088*a122);
  a125=(a125-a122);
  a071=(a071*a078);
  a009=(a009-a071);
  a009=(a031*a009);
  a125=(a125+a009);
  a125=(a052*a125);
  a066=(a066-a125);
  a066=(a066/a001);
  if (res[0]!=0) res[0][416]=a066;
  if (res[0]!=0) res[0][417]=a004;
  if (res[0]!=0) res[0][418]=a004;
  if (res[0]!=0) res[0][419]=a004;
  a034=(a034*a110);
  a018=(a018-a034);
  a010=(a010*a111);
  a129=(a129+a010);
  a018=(a018-a129);
  a018=(a018-a042);
  a018=(-a018);
  if (res[0]!=0) res[0][420]=a018;
  a060=(a060*a110);
  a036=(a036-a060);
  a036=(a036-a056);
  a007=(a007*a123);
  a117=(a117-a007);
  a036=(a036+a117);
  a036=(-a036);
  if (res[0]!=0) res[0][421]=a036;
  a058=(a058*a111);
  a029=(a029-a058);
  a020=(a020+a029);
  a072=(a072*a123);
  a055=(a055-a072);
  a020=(a020+a055);
  a020=(-a020);
  if (res[0]!=0) res[0][422]=a020;
  a128=(a094*a128);
  a128=(a128-a102);
  a102=(a019*a128);
  a102=(-a102);
  if (res[0]!=0) res[0][423]=a102;
  a050=(a094*a050);
  a118=(a118+a050);
  a050=(a019*a118);
  a050=(-a050);
  if (res[0]!=0) res[0][424]=a050;
  a091=(a091+a126);
  a094=(a094*a053);
  a091=(a091+a094);
  a094=(a019*a091);
  a094=(a040-a094);
  if (res[0]!=0) res[0][425]=a094;
  a094=(a015*a128);
  a094=(-a094);
  if (res[0]!=0) res[0][426]=a094;
  a094=(a015*a118);
  a094=(-a094);
  if (res[0]!=0) res[0][427]=a094;
  a015=(a015*a091);
  a015=(-a015);
  if (res[0]!=0) res[0][428]=a015;
  a128=(a002*a128);
  a128=(-a128);
  if (res[0]!=0) res[0][429]=a128;
  a118=(a002*a118);
  a118=(-a118);
  if (res[0]!=0) res[0][430]=a118;
  a091=(a002*a091);
  a091=(-a091);
  if (res[0]!=0) res[0][431]=a091;
  if (res[0]!=0) res[0][432]=a004;
  if (res[0]!=0) res[0][433]=a004;
  if (res[0]!=0) res[0][434]=a004;
  a091=(a039*a001);
  a118=(a019*a091);
  a128=(a014*a118);
  a015=(a030*a001);
  a094=(a019*a015);
  a053=(a024*a094);
  a126=(a128+a053);
  a050=(a079*a001);
  a102=(a019*a050);
  a020=(a048*a102);
  a126=(a126+a020);
  a126=(a126/a003);
  a126=(-a126);
  if (res[0]!=0) res[0][435]=a126;
  a126=(a014*a003);
  a020=(a048*a094);
  a020=(a126+a020);
  a020=(a020/a003);
  a020=(-a020);
  if (res[0]!=0) res[0][436]=a020;
  a020=(a024*a003);
  a055=(a048*a118);
  a055=(a020-a055);
  a055=(a055/a003);
  if (res[0]!=0) res[0][437]=a055;
  if (res[0]!=0) res[0][438]=a004;
  if (res[0]!=0) res[0][439]=a004;
  if (res[0]!=0) res[0][440]=a004;
  a055=(a074+a057);
  a055=(a055+a092);
  a055=(a011+a055);
  a011=(a011/a055);
  a091=(a002*a091);
  a091=(a011*a091);
  a022=(a022/a006);
  a022=(a030+a022);
  a055=(a011/a055);
  a072=(a055*a050);
  a123=(a022*a072);
  a123=(a091-a123);
  a123=(a088*a123);
  a083=(a083/a006);
  a083=(a083-a054);
  a029=(a083*a072);
  a058=(a011*a001);
  a029=(a029+a058);
  a029=(a107*a029);
  a123=(a123-a029);
  a050=(a002*a050);
  a050=(a011*a050);
  a074=(a057+a074);
  a074=(a074/a006);
  a029=(a074*a072);
  a050=(a050-a029);
  a050=(a031*a050);
  a123=(a123-a050);
  a123=(a052*a123);
  a050=(a104*a014);
  a050=(a019*a050);
  a029=(a000*a050);
  a016=(a016-a029);
  a029=(a101*a014);
  a111=(a019*a029);
  a036=(a030*a111);
  a016=(a016-a036);
  a036=(a113*a014);
  a117=(a019*a036);
  a007=(a054*a117);
  a016=(a016-a007);
  a007=(a104*a024);
  a056=(a019*a007);
  a060=(a030*a056);
  a016=(a016-a060);
  a060=(a113*a024);
  a110=(a002*a060);
  a016=(a016-a110);
  a110=(a104*a048);
  a018=(a019*a110);
  a042=(a054*a018);
  a016=(a016-a042);
  a042=(a101*a048);
  a129=(a002*a042);
  a016=(a016+a129);
  a129=(a016*a118);
  a010=(a117*a001);
  a034=(a018*a001);
  a010=(a010+a034);
  a034=(a038*a010);
  a034=(a129-a034);
  a123=(a123+a034);
  a034=(a039*a111);
  a025=(a025-a034);
  a036=(a002*a036);
  a025=(a025+a036);
  a036=(a039*a056);
  a025=(a025-a036);
  a036=(a101*a024);
  a036=(a019*a036);
  a034=(a035*a036);
  a025=(a025-a034);
  a060=(a019*a060);
  a034=(a054*a060);
  a025=(a025-a034);
  a110=(a002*a110);
  a025=(a025-a110);
  a042=(a019*a042);
  a110=(a054*a042);
  a025=(a025-a110);
  a110=(a025*a094);
  a034=(a060*a001);
  a066=(a042*a001);
  a034=(a034+a066);
  a066=(a044*a034);
  a066=(a110-a066);
  a123=(a123+a066);
  a029=(a002*a029);
  a049=(a049-a029);
  a117=(a039*a117);
  a049=(a049-a117);
  a007=(a002*a007);
  a049=(a049+a007);
  a060=(a030*a060);
  a049=(a049-a060);
  a018=(a039*a018);
  a049=(a049-a018);
  a042=(a030*a042);
  a049=(a049-a042);
  a042=(a113*a048);
  a042=(a019*a042);
  a079=(a079*a042);
  a049=(a049-a079);
  a079=(a049*a102);
  a042=(a042*a106);
  a018=(a075*a042);
  a079=(a079-a018);
  a123=(a123+a079);
  a123=(a123/a001);
  if (res[0]!=0) res[0][441]=a123;
  a123=(a016*a003);
  a018=(a085*a010);
  a018=(a123-a018);
  a060=(a080*a034);
  a018=(a018-a060);
  a007=(a049*a094);
  a117=(a089*a042);
  a117=(a007-a117);
  a018=(a018+a117);
  a018=(a018/a001);
  if (res[0]!=0) res[0][442]=a018;
  a018=(a049*a118);
  a117=(a097*a042);
  a117=(a018-a117);
  a029=(a093*a010);
  a092=(a092+a057);
  a092=(a092/a006);
  a057=(a092*a072);
  a057=(a088*a057);
  a015=(a002*a015);
  a015=(a011*a015);
  a087=(a087/a006);
  a039=(a039+a087);
  a087=(a039*a072);
  a087=(a015-a087);
  a087=(a107*a087);
  a057=(a057+a087);
  a095=(a095/a006);
  a095=(a095-a030);
  a072=(a095*a072);
  a072=(a091-a072);
  a072=(a031*a072);
  a057=(a057+a072);
  a057=(a052*a057);
  a057=(a029+a057);
  a072=(a025*a003);
  a030=(a090*a034);
  a030=(a072+a030);
  a057=(a057+a030);
  a117=(a117-a057);
  a117=(a117/a001);
  if (res[0]!=0) res[0][443]=a117;
  a117=(a043*a010);
  a117=(a129-a117);
  a057=(a037*a034);
  a057=(a110-a057);
  a117=(a117+a057);
  a117=(a117+a079);
  a117=(-a117);
  if (res[0]!=0) res[0][444]=a117;
  a117=(a045*a042);
  a007=(a007-a117);
  a117=(a084*a010);
  a117=(a123+a117);
  a117=(a117+a060);
  a007=(a007-a117);
  a007=(-a007);
  if (res[0]!=0) res[0][445]=a007;
  a007=(a082*a034);
  a007=(a072-a007);
  a007=(a007-a029);
  a042=(a096*a042);
  a018=(a018-a042);
  a007=(a007+a018);
  a007=(-a007);
  if (res[0]!=0) res[0][446]=a007;
  a102=(a113*a102);
  a007=(a101*a094);
  a102=(a102+a007);
  a018=(a104*a118);
  a102=(a102+a018);
  a042=(a017*a102);
  a042=(-a042);
  if (res[0]!=0) res[0][447]=a042;
  a042=(a113*a094);
  a042=(a042-a067);
  a029=(a017*a042);
  a029=(-a029);
  if (res[0]!=0) res[0][448]=a029;
  a029=(a113*a118);
  a029=(a029+a112);
  a117=(a017*a029);
  a117=(-a117);
  if (res[0]!=0) res[0][449]=a117;
  a117=(a019*a102);
  a117=(a040-a117);
  if (res[0]!=0) res[0][450]=a117;
  a117=(a019*a042);
  a117=(-a117);
  if (res[0]!=0) res[0][451]=a117;
  a117=(a019*a029);
  a117=(-a117);
  if (res[0]!=0) res[0][452]=a117;
  a102=(a002*a102);
  a102=(-a102);
  if (res[0]!=0) res[0][453]=a102;
  a042=(a002*a042);
  a042=(-a042);
  if (res[0]!=0) res[0][454]=a042;
  a029=(a002*a029);
  a029=(-a029);
  if (res[0]!=0) res[0][455]=a029;
  if (res[0]!=0) res[0][456]=a004;
  if (res[0]!=0) res[0][457]=a004;
  if (res[0]!=0) res[0][458]=a004;
  a054=(a054*a001);
  a029=(a019*a054);
  a042=(a024*a029);
  a126=(a126-a042);
  a126=(a126/a003);
  if (res[0]!=0) res[0][459]=a126;
  a035=(a035*a001);
  a126=(a019*a035);
  a042=(a024*a126);
  a128=(a128+a042);
  a042=(a048*a029);
  a128=(a128+a042);
  a128=(a128/a003);
  a128=(-a128);
  if (res[0]!=0) res[0][460]=a128;
  a024=(a024*a118);
  a048=(a048*a003);
  a024=(a024+a048);
  a024=(a024/a003);
  a024=(-a024);
  if (res[0]!=0) res[0][461]=a024;
  if (res[0]!=0) res[0][462]=a004;
  if (res[0]!=0) res[0][463]=a004;
  if (res[0]!=0) res[0][464]=a004;
  a024=(a055*a035);
  a128=(a022*a024);
  a128=(a058-a128);
  a128=(a088*a128);
  a102=(a083*a024);
  a091=(a091-a102);
  a091=(a107*a091);
  a128=(a128+a091);
  a035=(a002*a035);
  a035=(a011*a035);
  a091=(a074*a024);
  a091=(a035-a091);
  a091=(a031*a091);
  a128=(a128-a091);
  a128=(a052*a128);
  a111=(a111*a001);
  a056=(a056*a001);
  a111=(a111+a056);
  a056=(a038*a111);
  a056=(a123+a056);
  a128=(a128-a056);
  a056=(a025*a029);
  a036=(a036*a106);
  a091=(a044*a036);
  a091=(a056-a091);
  a128=(a128+a091);
  a091=(a075*a034);
  a128=(a128-a091);
  a128=(a128/a001);
  if (res[0]!=0) res[0][465]=a128;
  a128=(a085*a111);
  a128=(a129-a128);
  a102=(a025*a126);
  a117=(a080*a036);
  a102=(a102-a117);
  a128=(a128+a102);
  a117=(a049*a029);
  a060=(a089*a034);
  a060=(a117-a060);
  a128=(a128+a060);
  a128=(a128/a001);
  if (res[0]!=0) res[0][466]=a128;
  a025=(a025*a118);
  a128=(a090*a036);
  a128=(a025-a128);
  a060=(a093*a111);
  a054=(a002*a054);
  a054=(a011*a054);
  a079=(a039*a024);
  a079=(a054-a079);
  a079=(a107*a079);
  a057=(a092*a024);
  a035=(a035-a057);
  a035=(a088*a035);
  a079=(a079-a035);
  a024=(a095*a024);
  a024=(a024+a058);
  a024=(a031*a024);
  a079=(a079-a024);
  a079=(a052*a079);
  a079=(a060+a079);
  a128=(a128-a079);
  a049=(a049*a003);
  a079=(a097*a034);
  a079=(a049-a079);
  a128=(a128+a079);
  a128=(a128/a001);
  if (res[0]!=0) res[0][467]=a128;
  a128=(a043*a111);
  a123=(a123-a128);
  a128=(a037*a036);
  a056=(a056-a128);
  a123=(a123+a056);
  a123=(a123-a091);
  a123=(-a123);
  if (res[0]!=0) res[0][468]=a123;
  a123=(a084*a111);
  a129=(a129-a123);
  a129=(a129+a102);
  a102=(a045*a034);
  a102=(a117-a102);
  a129=(a129+a102);
  a129=(-a129);
  if (res[0]!=0) res[0][469]=a129;
  a036=(a082*a036);
  a025=(a025-a036);
  a025=(a025-a060);
  a034=(a096*a034);
  a034=(a049+a034);
  a025=(a025-a034);
  a025=(-a025);
  if (res[0]!=0) res[0][470]=a025;
  a025=(a101*a029);
  a025=(a025+a067);
  a067=(a017*a025);
  a067=(-a067);
  if (res[0]!=0) res[0][471]=a067;
  a113=(a113*a029);
  a126=(a101*a126);
  a126=(a113+a126);
  a126=(a126+a018);
  a018=(a017*a126);
  a018=(-a018);
  if (res[0]!=0) res[0][472]=a018;
  a101=(a101*a118);
  a101=(a101-a103);
  a118=(a017*a101);
  a118=(-a118);
  if (res[0]!=0) res[0][473]=a118;
  a118=(a019*a025);
  a118=(-a118);
  if (res[0]!=0) res[0][474]=a118;
  a118=(a019*a126);
  a118=(a040-a118);
  if (res[0]!=0) res[0][475]=a118;
  a118=(a019*a101);
  a118=(-a118);
  if (res[0]!=0) res[0][476]=a118;
  a025=(a002*a025);
  a025=(-a025);
  if (res[0]!=0) res[0][477]=a025;
  a126=(a002*a126);
  a126=(-a126);
  if (res[0]!=0) res[0][478]=a126;
  a101=(a002*a101);
  a101=(-a101);
  if (res[0]!=0) res[0][479]=a101;
  if (res[0]!=0) res[0][480]=a004;
  if (res[0]!=0) res[0][481]=a004;
  if (res[0]!=0) res[0][482]=a004;
  a101=(a014*a029);
  a101=(a101+a020);
  a101=(a101/a003);
  a101=(-a101);
  if (res[0]!=0) res[0][483]=a101;
  a101=(a014*a094);
  a048=(a048-a101);
  a048=(a048/a003);
  if (res[0]!=0) res[0][484]=a048;
  a000=(a000*a001);
  a048=(a019*a000);
  a014=(a014*a048);
  a014=(a014+a053);
  a014=(a014+a042);
  a014=(a014/a003);
  a014=(-a014);
  if (res[0]!=0) res[0][485]=a014;
  if (res[0]!=0) res[0][486]=a004;
  if (res[0]!=0) res[0][487]=a004;
  if (res[0]!=0) res[0][488]=a004;
  a055=(a055*a000);
  a022=(a022*a055);
  a022=(a054-a022);
  a022=(a088*a022);
  a083=(a083*a055);
  a015=(a015-a083);
  a015=(a107*a015);
  a022=(a022+a015);
  a074=(a074*a055);
  a074=(a031*a074);
  a022=(a022+a074);
  a022=(a052*a022);
  a074=(a016*a029);
  a050=(a050*a106);
  a038=(a038*a050);
  a038=(a074-a038);
  a022=(a022+a038);
  a044=(a044*a111);
  a044=(a072-a044);
  a022=(a022+a044);
  a075=(a075*a010);
  a022=(a022-a075);
  a022=(a022/a001);
  if (res[0]!=0) res[0][489]=a022;
  a022=(a016*a094);
  a085=(a085*a050);
  a085=(a022-a085);
  a080=(a080*a111);
  a085=(a085-a080);
  a089=(a089*a010);
  a089=(a049+a089);
  a085=(a085-a089);
  a085=(a085/a001);
  if (res[0]!=0) res[0][490]=a085;
  a016=(a016*a048);
  a093=(a093*a050);
  a016=(a016-a093);
  a039=(a039*a055);
  a058=(a058-a039);
  a107=(a107*a058);
  a000=(a002*a000);
  a011=(a011*a000);
  a092=(a092*a055);
  a011=(a011-a092);
  a088=(a088*a011);
  a107=(a107-a088);
  a095=(a095*a055);
  a054=(a054-a095);
  a031=(a031*a054);
  a107=(a107+a031);
  a052=(a052*a107);
  a052=(a016-a052);
  a090=(a090*a111);
  a090=(a110-a090);
  a052=(a052+a090);
  a097=(a097*a010);
  a097=(a117-a097);
  a052=(a052+a097);
  a052=(a052/a001);
  if (res[0]!=0) res[0][491]=a052;
  a043=(a043*a050);
  a074=(a074-a043);
  a037=(a037*a111);
  a072=(a072+a037);
  a074=(a074-a072);
  a074=(a074-a075);
  a074=(-a074);
  if (res[0]!=0) res[0][492]=a074;
  a084=(a084*a050);
  a022=(a022-a084);
  a022=(a022-a080);
  a045=(a045*a010);
  a049=(a049-a045);
  a022=(a022+a049);
  a022=(-a022);
  if (res[0]!=0) res[0][493]=a022;
  a082=(a082*a111);
  a110=(a110-a082);
  a016=(a016+a110);
  a096=(a096*a010);
  a117=(a117-a096);
  a016=(a016+a117);
  a016=(-a016);
  if (res[0]!=0) res[0][494]=a016;
  a029=(a104*a029);
  a029=(a029-a112);
  a112=(a017*a029);
  a112=(-a112);
  if (res[0]!=0) res[0][495]=a112;
  a094=(a104*a094);
  a103=(a103+a094);
  a094=(a017*a103);
  a094=(-a094);
  if (res[0]!=0) res[0][496]=a094;
  a113=(a113+a007);
  a104=(a104*a048);
  a113=(a113+a104);
  a017=(a017*a113);
  a017=(-a017);
  if (res[0]!=0) res[0][497]=a017;
  a017=(a019*a029);
  a017=(-a017);
  if (res[0]!=0) res[0][498]=a017;
  a017=(a019*a103);
  a017=(-a017);
  if (res[0]!=0) res[0][499]=a017;
  a017=(a019*a113);
  a017=(a040-a017);
  if (res[0]!=0) res[0][500]=a017;
  a029=(a002*a029);
  a029=(-a029);
  if (res[0]!=0) res[0][501]=a029;
  a103=(a002*a103);
  a103=(-a103);
  if (res[0]!=0) res[0][502]=a103;
  a002=(a002*a113);
  a002=(-a002);
  if (res[0]!=0) res[0][503]=a002;
  if (res[0]!=0) res[0][504]=a004;
  if (res[0]!=0) res[0][505]=a004;
  if (res[0]!=0) res[0][506]=a004;
  if (res[0]!=0) res[0][507]=a004;
  if (res[0]!=0) res[0][508]=a004;
  if (res[0]!=0) res[0][509]=a004;
  if (res[0]!=0) res[0][510]=a004;
  if (res[0]!=0) res[0][511]=a004;
  if (res[0]!=0) res[0][512]=a004;
  if (res[0]!=0) res[0][513]=a004;
  if (res[0]!=0) res[0][514]=a004;
  if (res[0]!=0) res[0][515]=a004;
  a002=(a120*a001);
  a002=(a019*a002);
  a113=(a013*a002);
  a103=(a026*a001);
  a103=(a019*a103);
  a029=(a023*a103);
  a017=(a113+a029);
  a104=(2.*a119);
  a104=(a104*a001);
  a104=(a019*a104);
  a104=(a047*a104);
  a017=(a017+a104);
  a017=(-a017);
  if (res[0]!=0) res[0][516]=a017;
  a017=(a047*a103);
  a104=(a013*a003);
  a017=(a017-a104);
  a017=(-a017);
  if (res[0]!=0) res[0][517]=a017;
  a017=(a023*a003);
  a048=(a047*a002);
  a048=(a017+a048);
  a048=(-a048);
  if (res[0]!=0) res[0][518]=a048;
  if (res[0]!=0) res[0][519]=a004;
  if (res[0]!=0) res[0][520]=a004;
  if (res[0]!=0) res[0][521]=a004;
  if (res[0]!=0) res[0][522]=a004;
  if (res[0]!=0) res[0][523]=a004;
  if (res[0]!=0) res[0][524]=a004;
  if (res[0]!=0) res[0][525]=a040;
  if (res[0]!=0) res[0][526]=a004;
  if (res[0]!=0) res[0][527]=a004;
  if (res[0]!=0) res[0][528]=a004;
  if (res[0]!=0) res[0][529]=a004;
  if (res[0]!=0) res[0][530]=a004;
  if (res[0]!=0) res[0][531]=a004;
  if (res[0]!=0) res[0][532]=a004;
  if (res[0]!=0) res[0][533]=a004;
  if (res[0]!=0) res[0][534]=a004;
  if (res[0]!=0) res[0][535]=a004;
  if (res[0]!=0) res[0][536]=a004;
  if (res[0]!=0) res[0][537]=a004;
  if (res[0]!=0) res[0][538]=a004;
  if (res[0]!=0) res[0][539]=a004;
  a119=(a119*a001);
  a119=(a019*a119);
  a048=(a023*a119);
  a104=(a104+a048);
  a104=(-a104);
  if (res[0]!=0) res[0][540]=a104;
  a026=(2.*a026);
  a026=(a026*a001);
  a026=(a019*a026);
  a026=(a023*a026);
  a113=(a113+a026);
  a026=(a047*a119);
  a113=(a113+a026);
  a113=(-a113);
  if (res[0]!=0) res[0][541]=a113;
  a023=(a023*a002);
  a047=(a047*a003);
  a023=(a023-a047);
  a023=(-a023);
  if (res[0]!=0) res[0][542]=a023;
  if (res[0]!=0) res[0][543]=a004;
  if (res[0]!=0) res[0][544]=a004;
  if (res[0]!=0) res[0][545]=a004;
  if (res[0]!=0) res[0][546]=a004;
  if (res[0]!=0) res[0][547]=a004;
  if (res[0]!=0) res[0][548]=a004;
  if (res[0]!=0) res[0][549]=a004;
  if (res[0]!=0) res[0][550]=a040;
  if (res[0]!=0) res[0][551]=a004;
  if (res[0]!=0) res[0][552]=a004;
  if (res[0]!=0) res[0][553]=a004;
  if (res[0]!=0) res[0][554]=a004;
  if (res[0]!=0) res[0][555]=a004;
  if (res[0]!=0) res[0][556]=a004;
  if (res[0]!=0) res[0][557]=a004;
  if (res[0]!=0) res[0][558]=a004;
  if (res[0]!=0) res[0][559]=a004;
  if (res[0]!=0) res[0][560]=a004;
  if (res[0]!=0) res[0][561]=a004;
  if (res[0]!=0) res[0][562]=a004;
  if (res[0]!=0) res[0][563]=a004;
  a119=(a013*a119);
  a119=(a119-a017);
  a119=(-a119);
  if (res[0]!=0) res[0][564]=a119;
  a103=(a013*a103);
  a103=(a103+a047);
  a103=(-a103);
  if (res[0]!=0) res[0][565]=a103;
  a120=(2.*a120);
  a120=(a120*a001);
  a019=(a019*a120);
  a013=(a013*a019);
  a013=(a013+a029);
  a013=(a013+a026);
  a013=(-a013);
  if (res[0]!=0) res[0][566]=a013;
  if (res[0]!=0) res[0][567]=a004;
  if (res[0]!=0) res[0][568]=a004;
  if (res[0]!=0) res[0][569]=a004;
  if (res[0]!=0) res[0][570]=a004;
  if (res[0]!=0) res[0][571]=a004;
  if (res[0]!=0) res[0][572]=a004;
  if (res[0]!=0) res[0][573]=a004;
  if (res[0]!=0) res[0][574]=a004;
  if (res[0]!=0) res[0][575]=a040;
  return 0;
}

CASADI_SYMBOL_EXPORT int jacobian(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f1(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int jacobian_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void jacobian_release(int mem) {
}

CASADI_SYMBOL_EXPORT void jacobian_incref(void) {
}

CASADI_SYMBOL_EXPORT void jacobian_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int jacobian_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int jacobian_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real jacobian_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* jacobian_name_in(casadi_int i) {
  switch (i) {
    case 0: return "z";
    case 1: return "g";
    case 2: return "p";
    case 3: return "h";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* jacobian_name_out(casadi_int i) {
  switch (i) {
    case 0: return "J";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* jacobian_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* jacobian_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int jacobian_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int jacobian_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}

/* update:(z[24],g[9],p[3],h)->(g1[9],p1[3]) */
static int casadi_f2(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27;
  a00=arg[1]? arg[1][0] : 0;
  a01=1.;
  a02=4.;
  a03=arg[3]? arg[3][0] : 0;
  a04=arg[0]? arg[0][21] : 0;
  a04=(a03*a04);
  a05=casadi_sq(a04);
  a06=arg[0]? arg[0][22] : 0;
  a06=(a03*a06);
  a07=casadi_sq(a06);
  a08=(a05+a07);
  a09=arg[0]? arg[0][23] : 0;
  a03=(a03*a09);
  a09=casadi_sq(a03);
  a08=(a08+a09);
  a08=(a02+a08);
  a08=(a02/a08);
  a10=(a09+a07);
  a11=2.;
  a10=(a10/a11);
  a10=(a08*a10);
  a10=(a01-a10);
  a12=(a00*a10);
  a13=arg[1]? arg[1][3] : 0;
  a14=(a04*a06);
  a15=(a14/a11);
  a15=(a03+a15);
  a15=(a08*a15);
  a16=(a13*a15);
  a12=(a12+a16);
  a16=arg[1]? arg[1][6] : 0;
  a17=(a04*a03);
  a18=(a17/a11);
  a18=(a18-a06);
  a18=(a08*a18);
  a19=(a16*a18);
  a12=(a12+a19);
  if (res[0]!=0) res[0][0]=a12;
  a12=arg[1]? arg[1][1] : 0;
  a19=(a12*a10);
  a20=arg[1]? arg[1][4] : 0;
  a21=(a20*a15);
  a19=(a19+a21);
  a21=arg[1]? arg[1][7] : 0;
  a22=(a21*a18);
  a19=(a19+a22);
  if (res[0]!=0) res[0][1]=a19;
  a19=arg[1]? arg[1][2] : 0;
  a10=(a19*a10);
  a22=arg[1]? arg[1][5] : 0;
  a15=(a22*a15);
  a10=(a10+a15);
  a15=arg[1]? arg[1][8] : 0;
  a18=(a15*a18);
  a10=(a10+a18);
  if (res[0]!=0) res[0][2]=a10;
  a10=(a06*a04);
  a18=(a10/a11);
  a18=(a18-a03);
  a18=(a08*a18);
  a23=(a00*a18);
  a24=(a09+a05);
  a24=(a24/a11);
  a24=(a08*a24);
  a24=(a01-a24);
  a25=(a13*a24);
  a23=(a23+a25);
  a25=(a06*a03);
  a26=(a25/a11);
  a26=(a04+a26);
  a26=(a08*a26);
  a27=(a16*a26);
  a23=(a23+a27);
  if (res[0]!=0) res[0][3]=a23;
  a23=(a12*a18);
  a27=(a20*a24);
  a23=(a23+a27);
  a27=(a21*a26);
  a23=(a23+a27);
  if (res[0]!=0) res[0][4]=a23;
  a18=(a19*a18);
  a24=(a22*a24);
  a18=(a18+a24);
  a26=(a15*a26);
  a18=(a18+a26);
  if (res[0]!=0) res[0][5]=a18;
  a18=(a03*a04);
  a26=(a18/a11);
  a26=(a06+a26);
  a26=(a08*a26);
  a00=(a00*a26);
  a24=(a03*a06);
  a23=(a24/a11);
  a23=(a23-a04);
  a23=(a08*a23);
  a13=(a13*a23);
  a00=(a00+a13);
  a13=(a07+a05);
  a13=(a13/a11);
  a08=(a08*a13);
  a08=(a01-a08);
  a16=(a16*a08);
  a00=(a00+a16);
  if (res[0]!=0) res[0][6]=a00;
  a12=(a12*a26);
  a20=(a20*a23);
  a12=(a12+a20);
  a21=(a21*a08);
  a12=(a12+a21);
  if (res[0]!=0) res[0][7]=a12;
  a19=(a19*a26);
  a22=(a22*a23);
  a19=(a19+a22);
  a15=(a15*a08);
  a19=(a19+a15);
  if (res[0]!=0) res[0][8]=a19;
  a18=(a18/a02);
  a06=(a06/a11);
  a18=(a18-a06);
  a19=arg[0]? arg[0][14] : 0;
  a18=(a18*a19);
  a03=(a03/a11);
  a10=(a10/a02);
  a10=(a03+a10);
  a15=arg[0]? arg[0][13] : 0;
  a10=(a10*a15);
  a18=(a18+a10);
  a05=(a05/a02);
  a05=(a01+a05);
  a10=arg[0]? arg[0][12] : 0;
  a05=(a05*a10);
  a18=(a18+a05);
  if (res[1]!=0) res[1][0]=a18;
  a04=(a04/a11);
  a24=(a24/a02);
  a24=(a04+a24);
  a24=(a24*a19);
  a07=(a07/a02);
  a07=(a01+a07);
  a07=(a07*a15);
  a24=(a24+a07);
  a14=(a14/a02);
  a14=(a14-a03);
  a14=(a14*a10);
  a24=(a24+a14);
  if (res[1]!=0) res[1][1]=a24;
  a09=(a09/a02);
  a01=(a01+a09);
  a01=(a01*a19);
  a25=(a25/a02);
  a25=(a25-a04);
  a25=(a25*a15);
  a01=(a01+a25);
  a17=(a17/a02);
  a06=(a06+a17);
  a06=(a06*a10);
  a01=(a01+a06);
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

/* guess:(xi[3],g[9],p[3],h)->(z0[24]) */
static int casadi_f3(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4;
  a0=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a0;
  a1=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a1;
  a2=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a2;
  if (res[0]!=0) res[0][3]=a0;
  if (res[0]!=0) res[0][4]=a1;
  if (res[0]!=0) res[0][5]=a2;
  a3=0.;
  if (res[0]!=0) res[0][6]=a3;
  if (res[0]!=0) res[0][7]=a3;
  if (res[0]!=0) res[0][8]=a3;
  if (res[0]!=0) res[0][9]=a3;
  if (res[0]!=0) res[0][10]=a3;
  if (res[0]!=0) res[0][11]=a3;
  a3=arg[2]? arg[2][0] : 0;
  if (res[0]!=0) res[0][12]=a3;
  a3=arg[2]? arg[2][1] : 0;
  if (res[0]!=0) res[0][13]=a3;
  a3=arg[2]? arg[2][2] : 0;
  if (res[0]!=0) res[0][14]=a3;
  a3=2.1132486540518713e-01;
  a4=(a3*a0);
  if (res[0]!=0) res[0][15]=a4;
  a4=(a3*a1);
  if (res[0]!=0) res[0][16]=a4;
  a3=(a3*a2);
  if (res[0]!=0) res[0][17]=a3;
  a3=7.8867513459481287e-01;
  a4=(a3*a0);
  if (res[0]!=0) res[0][18]=a4;
  a4=(a3*a1);
  if (res[0]!=0) res[0][19]=a4;
  a3=(a3*a2);
  if (res[0]!=0) res[0][20]=a3;
  if (res[0]!=0) res[0][21]=a0;
  if (res[0]!=0) res[0][22]=a1;
  if (res[0]!=0) res[0][23]=a2;
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

/* margin:(z[24],h)->(m) */
static int casadi_f9(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4;
  a0=1.;
  a1=4.;
  a2=arg[1]? arg[1][0] : 0;
  a3=arg[0]? arg[0][15] : 0;
  a3=(a2*a3);
  a3=casadi_sq(a3);
  a4=arg[0]? arg[0][16] : 0;
  a4=(a2*a4);
  a4=casadi_sq(a4);
  a3=(a3+a4);
  a4=arg[0]? arg[0][17] : 0;
  a4=(a2*a4);
  a4=casadi_sq(a4);
  a3=(a3+a4);
  a3=(a1-a3);
  a0=casadi_fmin(a0,a3);
  a0=casadi_fmin(a0,a3);
  a3=arg[0]? arg[0][18] : 0;
  a3=(a2*a3);
  a3=casadi_sq(a3);
  a4=arg[0]? arg[0][19] : 0;
  a4=(a2*a4);
  a4=casadi_sq(a4);
  a3=(a3+a4);
  a4=arg[0]? arg[0][20] : 0;
  a4=(a2*a4);
  a4=casadi_sq(a4);
  a3=(a3+a4);
  a3=(a1-a3);
  a0=casadi_fmin(a0,a3);
  a0=casadi_fmin(a0,a3);
  a3=arg[0]? arg[0][21] : 0;
  a3=(a2*a3);
  a3=casadi_sq(a3);
  a4=arg[0]? arg[0][22] : 0;
  a4=(a2*a4);
  a4=casadi_sq(a4);
  a3=(a3+a4);
  a4=arg[0]? arg[0][23] : 0;
  a2=(a2*a4);
  a2=casadi_sq(a2);
  a3=(a3+a2);
  a1=(a1-a3);
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



/* ======================= end of CasADi-generated code =================================== */
#if defined(__GNUC__)
#pragma GCC visibility pop
#define HPGEN_EXPORT __attribute__((visibility("default")))
#else
#define HPGEN_EXPORT
#endif

#define HPGEN_ABI 1
#define HPGEN_N 3
#define HPGEN_NN (HPGEN_N * HPGEN_N)
#define HPGEN_D 3
#define HPGEN_NZ 24
#define HPGEN_OK 0
#define HPGEN_NO_CONVERGENCE 1
#define HPGEN_NONFINITE 2
#define HPGEN_DOMAIN 3
#define HPGEN_INVALID (-1)
/* Newton stalls at round-off: stop when |dz| stopped decreasing while below this * (1+|z|) */
#define HPGEN_ROUNDOFF_FLOOR 1e-11

typedef struct hpgen_status {
    long long code;              /* HPGEN_OK, ... */
    long long step;              /* failing step index, or steps done on success */
    long long iterations;        /* Newton iterations of the last step attempted */
    long long total_iterations;  /* Newton iterations over all steps */
    double residual;             /* inf-norm of the last residual evaluated */
} hpgen_status;

HPGEN_EXPORT const char* hpgen_hash(void) { return "db5230382775f98282ae41904036d1840a33e101a8a16c37ee276fba0916c4f9"; }

/* out[0..3] = ABI version, n, d, nz */
HPGEN_EXPORT void hpgen_dims(long long* out) {
    out[0] = HPGEN_ABI; out[1] = HPGEN_N; out[2] = HPGEN_D; out[3] = HPGEN_NZ;
}

/* ---- kernel wrappers: dense column-major arguments, CasADi work arrays on the stack ---- */

/* residual(z[24], g[9], p[3], h[1]) -> (F[24]) */
#define HPGEN_RESIDUAL_SZ_ARG 4
#define HPGEN_RESIDUAL_SZ_RES 1
#define HPGEN_RESIDUAL_SZ_IW 0
#define HPGEN_RESIDUAL_SZ_W 101
HPGEN_EXPORT int hpgen_kernel_residual(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
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

/* jacobian(z[24], g[9], p[3], h[1]) -> (J[576]) */
#define HPGEN_JACOBIAN_SZ_ARG 4
#define HPGEN_JACOBIAN_SZ_RES 1
#define HPGEN_JACOBIAN_SZ_IW 0
#define HPGEN_JACOBIAN_SZ_W 131
HPGEN_EXPORT int hpgen_kernel_jacobian(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
    const casadi_real* arg[HPGEN_JACOBIAN_SZ_ARG + 1];
    casadi_real* res[HPGEN_JACOBIAN_SZ_RES + 1];
    casadi_int iw[HPGEN_JACOBIAN_SZ_IW + 1];
    casadi_real w[HPGEN_JACOBIAN_SZ_W + 1];
    int flag, i = 0;
    arg[0] = in0;
    arg[1] = in1;
    arg[2] = in2;
    arg[3] = in3;
    res[0] = out0;
    flag = jacobian(arg, res, iw, w, 0);
    (void)i;
    return flag;
}

/* update(z[24], g[9], p[3], h[1]) -> (g1[9], p1[3]) */
#define HPGEN_UPDATE_SZ_ARG 4
#define HPGEN_UPDATE_SZ_RES 2
#define HPGEN_UPDATE_SZ_IW 0
#define HPGEN_UPDATE_SZ_W 28
HPGEN_EXPORT int hpgen_kernel_update(const double* in0, const double* in1, const double* in2, const double* in3, double* out0, double* out1) {
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

/* guess(xi[3], g[9], p[3], h[1]) -> (z0[24]) */
#define HPGEN_GUESS_SZ_ARG 4
#define HPGEN_GUESS_SZ_RES 1
#define HPGEN_GUESS_SZ_IW 0
#define HPGEN_GUESS_SZ_W 5
HPGEN_EXPORT int hpgen_kernel_guess(const double* in0, const double* in1, const double* in2, const double* in3, double* out0) {
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

/* legendre(g[9], xi[3]) -> (mu[3]) */
#define HPGEN_LEGENDRE_SZ_ARG 2
#define HPGEN_LEGENDRE_SZ_RES 1
#define HPGEN_LEGENDRE_SZ_IW 0
#define HPGEN_LEGENDRE_SZ_W 3
HPGEN_EXPORT int hpgen_kernel_legendre(const double* in0, const double* in1, double* out0) {
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

/* hessian(g[9], xi[3]) -> (H[9]) */
#define HPGEN_HESSIAN_SZ_ARG 2
#define HPGEN_HESSIAN_SZ_RES 1
#define HPGEN_HESSIAN_SZ_IW 0
#define HPGEN_HESSIAN_SZ_W 3
HPGEN_EXPORT int hpgen_kernel_hessian(const double* in0, const double* in1, double* out0) {
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

/* energy(g[9], xi[3]) -> (E[1]) */
#define HPGEN_ENERGY_SZ_ARG 2
#define HPGEN_ENERGY_SZ_RES 1
#define HPGEN_ENERGY_SZ_IW 0
#define HPGEN_ENERGY_SZ_W 5
HPGEN_EXPORT int hpgen_kernel_energy(const double* in0, const double* in1, double* out0) {
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

/* momentum(g[9], p[3]) -> (m[3]) */
#define HPGEN_MOMENTUM_SZ_ARG 2
#define HPGEN_MOMENTUM_SZ_RES 1
#define HPGEN_MOMENTUM_SZ_IW 0
#define HPGEN_MOMENTUM_SZ_W 14
HPGEN_EXPORT int hpgen_kernel_momentum(const double* in0, const double* in1, double* out0) {
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

/* defect(g[9]) -> (e[1]) */
#define HPGEN_DEFECT_SZ_ARG 1
#define HPGEN_DEFECT_SZ_RES 1
#define HPGEN_DEFECT_SZ_IW 0
#define HPGEN_DEFECT_SZ_W 13
HPGEN_EXPORT int hpgen_kernel_defect(const double* in0, double* out0) {
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

/* margin(z[24], h[1]) -> (m[1]) */
#define HPGEN_MARGIN_SZ_ARG 2
#define HPGEN_MARGIN_SZ_RES 1
#define HPGEN_MARGIN_SZ_IW 0
#define HPGEN_MARGIN_SZ_W 5
HPGEN_EXPORT int hpgen_kernel_margin(const double* in0, const double* in1, double* out0) {
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

static int hpgen_all_finite(const double* x, int n) {
    int i;
    for (i = 0; i < n; ++i) if (!isfinite(x[i])) return 0;
    return 1;
}

/* Solve A x = b in place: LU with partial pivoting (pivot: first row of largest |a_ik|, as
   LAPACK). A is NZ x NZ column-major and is overwritten; b is overwritten by x.
   Returns 1 if a pivot is exactly zero (singular A). */
static int hpgen_lu_solve(double* A, double* b) {
    const int n = HPGEN_NZ;
    int i, j, k;
    for (k = 0; k < n; ++k) {
        int piv = k;
        double amax = fabs(A[k + k * n]);
        for (i = k + 1; i < n; ++i) {
            double a = fabs(A[i + k * n]);
            if (a > amax) { amax = a; piv = i; }
        }
        if (amax == 0.0) return 1;
        if (piv != k) {
            double t;
            for (j = 0; j < n; ++j) { t = A[k + j * n]; A[k + j * n] = A[piv + j * n]; A[piv + j * n] = t; }
            t = b[k]; b[k] = b[piv]; b[piv] = t;
        }
        for (i = k + 1; i < n; ++i) A[i + k * n] /= A[k + k * n];
        for (j = k + 1; j < n; ++j) {
            double a = A[k + j * n];
            if (a != 0.0) for (i = k + 1; i < n; ++i) A[i + j * n] -= A[i + k * n] * a;
        }
        for (i = k + 1; i < n; ++i) b[i] -= A[i + k * n] * b[k];
    }
    for (k = n - 1; k >= 0; --k) {
        double s = b[k];
        for (j = k + 1; j < n; ++j) s -= A[k + j * n] * b[j];
        b[k] = s / A[k + k * n];
    }
    return 0;
}

/* Newton on residual(z, g, p, h) = 0 from z (in/out): z <- z - J^{-1} F; converged when
   |dz| <= tol (1 + |z|), or when |dz| stopped decreasing while |dz| <= 1e-11 (1 + |z|)
   (round-off floor); inf-norms. Returns a status code. */
static int hpgen_newton(const double* g, const double* p, const double* hv, double* z,
                        double tol, long long maxit, long long* iters, double* rnorm) {
    double F[HPGEN_NZ], J[HPGEN_NZ * HPGEN_NZ];
    double dprev = HUGE_VAL;
    long long it;
    int i;
    *iters = 0;
    *rnorm = NAN;
    for (it = 1; it <= maxit; ++it) {
        double dn, zn;
        *iters = it;
        if (hpgen_kernel_residual(z, g, p, hv, F) || hpgen_kernel_jacobian(z, g, p, hv, J))
            return HPGEN_NONFINITE;
        *rnorm = hpgen_norm_inf(F, HPGEN_NZ);
        if (!isfinite(*rnorm) || !hpgen_all_finite(J, HPGEN_NZ * HPGEN_NZ))
            return HPGEN_NONFINITE;
        if (hpgen_lu_solve(J, F)) return HPGEN_NONFINITE;
        for (i = 0; i < HPGEN_NZ; ++i) z[i] -= F[i];
        dn = hpgen_norm_inf(F, HPGEN_NZ);
        zn = hpgen_norm_inf(z, HPGEN_NZ);
        if (!isfinite(dn) || !isfinite(zn)) return HPGEN_NONFINITE;
        if (dn <= tol * (1.0 + zn)) return HPGEN_OK;
        if (it > 1 && dn >= dprev && dn <= HPGEN_ROUNDOFF_FLOOR * (1.0 + zn)) return HPGEN_OK;
        dprev = dn;
    }
    return HPGEN_NO_CONVERGENCE;
}

/* One step: margin(z, h) > 0 at the start, Newton from z (in/out), margin(z, h) > 0 at the
   solution, then update -> (g1, p1). */
static int hpgen_step_core(const double* g, const double* p, const double* hv, double* z,
                           double tol, long long maxit, double* g1, double* p1,
                           long long* iters, double* rnorm, int check_start) {
    double m[1];
    int code;
    /* a start outside tau's domain means h is too large for the chart: do not let Newton
       wander to a spurious root from there. Only needed for a start that is not the previous
       step's solution (whose margin, same h, was checked after it converged). */
    if (check_start && !hpgen_kernel_margin(z, hv, m) && m[0] <= 0.0) {
        *iters = 0; *rnorm = NAN;
        return HPGEN_DOMAIN;
    }
    code = hpgen_newton(g, p, hv, z, tol, maxit, iters, rnorm);
    if (code != HPGEN_OK) {
        /* a failure at an iterate outside tau's domain is reported as a domain error */
        if (!hpgen_kernel_margin(z, hv, m) && m[0] <= 0.0) return HPGEN_DOMAIN;
        return code;
    }
    if (hpgen_kernel_margin(z, hv, m)) return HPGEN_NONFINITE;
    if (!(m[0] > 0.0)) return HPGEN_DOMAIN;
    if (hpgen_kernel_update(z, g, p, hv, g1, p1)) return HPGEN_NONFINITE;
    if (!hpgen_all_finite(g1, HPGEN_NN) || !hpgen_all_finite(p1, HPGEN_D))
        return HPGEN_NONFINITE;
    return HPGEN_OK;
}

static void hpgen_status_init(hpgen_status* st) {
    st->code = HPGEN_OK; st->step = 0; st->iterations = 0; st->total_iterations = 0;
    st->residual = 0.0;
}

/* One step from (g, p) with step size h; z: Newton start in, solution out. Returns the code. */
HPGEN_EXPORT int hpgen_step(const double* g, const double* p, double h, double* z, double tol,
                            long long maxit, double* g1, double* p1, hpgen_status* st) {
    double hv[1];
    long long it;
    double r;
    int code;
    hpgen_status_init(st);
    if (maxit < 1) { st->code = HPGEN_INVALID; return HPGEN_INVALID; }
    hv[0] = h;
    code = hpgen_step_core(g, p, hv, z, tol, maxit, g1, p1, &it, &r, 1);
    st->code = code; st->iterations = it; st->total_iterations = it; st->residual = r;
    return code;
}

/* All steps in one call, warm-started (each Newton starts from the previous solution z, in/out).
   Records (g, p) at steps 0, every, 2 every, ... into g_rec[(steps/every + 1) * NN] and
   p_rec[(steps/every + 1) * D]. Stops at the first failed step. Returns the steps done. */
HPGEN_EXPORT long long hpgen_simulate(const double* g0, const double* p0, double h, double* z,
                                      long long steps, long long every, double tol,
                                      long long maxit, double* g_rec, double* p_rec,
                                      hpgen_status* st) {
    double g[HPGEN_NN], p[HPGEN_D], g1[HPGEN_NN], p1[HPGEN_D], hv[1];
    long long k, it;
    double r;
    hpgen_status_init(st);
    if (steps < 0 || every < 1 || maxit < 1) { st->code = HPGEN_INVALID; return 0; }
    hv[0] = h;
    memcpy(g, g0, sizeof g);
    memcpy(p, p0, sizeof p);
    memcpy(g_rec, g, sizeof g);
    memcpy(p_rec, p, sizeof p);
    for (k = 0; k < steps; ++k) {
        int code = hpgen_step_core(g, p, hv, z, tol, maxit, g1, p1, &it, &r, k == 0);
        st->iterations = it;
        st->total_iterations += it;
        st->residual = r;
        if (code != HPGEN_OK) { st->code = code; st->step = k; return k; }
        memcpy(g, g1, sizeof g);
        memcpy(p, p1, sizeof p);
        if ((k + 1) % every == 0) {
            long long rec = (k + 1) / every;
            memcpy(g_rec + rec * HPGEN_NN, g, sizeof g);
            memcpy(p_rec + rec * HPGEN_D, p, sizeof p);
        }
    }
    st->step = steps;
    return steps;
}
