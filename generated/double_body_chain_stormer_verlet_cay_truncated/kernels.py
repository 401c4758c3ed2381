# hpgen generated module double_body_chain_stormer_verlet_cay_truncated -- do not edit, regenerate with hpgen
# model: double_body_chain
# options: tableau=stormer-verlet, tau=cay, rkmk=truncated
# hpgen version: 0.1.0
# content hash: 88154e1ec22a70ad8718c558ab81bbd7966c4d51a3ada72cb3d576aa0598abde
"""Python backend of the hpgen module double_body_chain_stormer_verlet_cay_truncated: straight-line kernels printed from the
CasADi SX algorithms (same operations, same order as the C backend). Each kernel first runs a
fast body (inlined constants and single-use values, plain ``/`` and math calls); if that
raises, a safe body recomputes the outputs instruction by instruction with C semantics.

Calling convention: every kernel takes flat float sequences (matrices column-major, h a
1-sequence) and returns a list of numpy float64 arrays, one per output, dense column-major.
Math that would raise in Python (division by zero, log(0), overflow, ...) returns the C99
IEEE result (inf/nan) instead, so non-finite values surface as they do in C.

RAW[name] is the same kernel without the conversions, for the runtime's Newton loop: it
takes lists or tuples of exactly the declared sizes holding Python floats (not checked) and
returns a list of lists of Python floats, one per output; the values are those of the
public kernel (the public kernel is RAW[name] plus input checks and numpy outputs).
Imports only math and numpy.
"""
import math

import numpy

N = 6
D = 6
NZ = 6


_NDARRAY = numpy.ndarray
_F64 = numpy.dtype(numpy.float64)
_type = type
_fromiter = numpy.fromiter


def _vec(a, size, name):
    """a as a flat sequence of `size` Python floats: a float64 array of shape (size,) through
    tolist(), a list or tuple of exactly `size` Python floats as it is, anything else
    through numpy.asarray(a, float64)."""
    t = type(a)
    if t is _NDARRAY:
        if a.dtype is _F64 and a.shape == (size,):
            return a.tolist()
    elif (t is list or t is tuple) and len(a) == size:
        for x in a:
            if type(x) is not float:
                break
        else:
            return a
    v = numpy.asarray(a, dtype=numpy.float64)
    if v.shape != (size,):
        raise ValueError(f"{name}: expected a flat sequence of {size} values, got shape "
                         f"{v.shape}")
    return v.tolist()


def _ieee(fn, *args):
    with numpy.errstate(all="ignore"):
        return float(fn(*[numpy.float64(a) for a in args]))


def _div(x, y):
    return _ieee(numpy.divide, x, y)


def _wrap1(fn, fallback):
    def f(x):
        try:
            return fn(x)
        except (ValueError, OverflowError):
            return _ieee(fallback, x)
    return f


_exp = _wrap1(math.exp, numpy.exp)
_log = _wrap1(math.log, numpy.log)
_sqrt = _wrap1(math.sqrt, numpy.sqrt)
_sin = _wrap1(math.sin, numpy.sin)
_cos = _wrap1(math.cos, numpy.cos)
_tan = _wrap1(math.tan, numpy.tan)
_asin = _wrap1(math.asin, numpy.arcsin)
_acos = _wrap1(math.acos, numpy.arccos)
_sinh = _wrap1(math.sinh, numpy.sinh)
_cosh = _wrap1(math.cosh, numpy.cosh)
_acosh = _wrap1(math.acosh, numpy.arccosh)
_atanh = _wrap1(math.atanh, numpy.arctanh)
_log1p = _wrap1(math.log1p, numpy.log1p)
_expm1 = _wrap1(math.expm1, numpy.expm1)

# the raw operations of the fast kernel bodies (they raise where C returns inf/nan)
_f_exp = math.exp
_f_log = math.log
_f_sqrt = math.sqrt
_f_sin = math.sin
_f_cos = math.cos
_f_tan = math.tan
_f_asin = math.asin
_f_acos = math.acos
_f_sinh = math.sinh
_f_cosh = math.cosh
_f_acosh = math.acosh
_f_atanh = math.atanh
_f_log1p = math.log1p
_f_expm1 = math.expm1
_f_fabs = math.fabs
_f_pow = math.pow
_f_fmod = math.fmod
_f_remainder = math.remainder


def _pow(x, y):
    try:
        return math.pow(x, y)
    except (ValueError, OverflowError):
        return _ieee(numpy.power, x, y)


def _fmod(x, y):
    try:
        return math.fmod(x, y)
    except ValueError:
        return math.nan


def _remainder(x, y):
    try:
        return math.remainder(x, y)
    except ValueError:
        return math.nan


def _floor(x):
    return float(math.floor(x)) if math.isfinite(x) and x != 0.0 else x


def _ceil(x):
    if not math.isfinite(x) or x == 0.0:
        return x
    return math.copysign(float(math.ceil(x)), x)


def _sign(x):
    return -1.0 if x < 0.0 else (1.0 if x > 0.0 else x)


def _fmin(x, y):
    return x if (x <= y or y != y) else y


def _fmax(x, y):
    return x if (x >= y or y != y) else y


def _printme(x, y):
    print("|> %.15g : %.15g" % (y, x))
    return x


def _raw_residual(z, g, p, h):
    """residual on lists of Python floats -> [F[6]] as lists (see RAW)"""
    w0, w1, w2, w3, w4, w5 = z
    w17, w12, w8, _, _, _, w16, w11, w7, _, _, _, w18, w13, w6, _, _, _, _, _, _, w23, w22, w21, _, _, _, w19, w14, w9, _, _, _, w20, w15, w10 = g
    w24, w25, w26, w27, w28, w29 = p
    w30, = h
    r0 = [0.0] * 6
    w31 = w30 * w0
    w0 = 0.9 * w0
    w32 = w30 * w1
    w33 = (w32 * w31) * 0.25
    w34 = w30 * w2
    w35 = w34 * 0.5
    w36 = w32 * 0.5
    w37 = (w34 * w31) * 0.25
    w2 = 0.2 * w2
    w38 = (2.0 * (((((1.3 + (0.05 * w7)) + (0.1 * w8)) - w6) + ((-0.1) * w9)) + ((-0.3) * w10))) * w30
    w39 = 0.05 * w38
    w40 = (2.0 * (((((0.05 * w11) + (0.1 * w12)) - w13) + ((-0.1) * w14)) + ((-0.3) * w15))) * w30
    w41 = 0.05 * w40
    w42 = (2.0 * (((((0.05 * w16) + (0.1 * w17)) - w18) + ((-0.1) * w19)) + ((-0.3) * w20))) * w30
    w43 = 0.05 * w42
    w44 = w38 + (0.5 * w30)
    r0[0] = (w24 - ((((1.0 + ((w31 * w31) * 0.25)) * w0) + ((w33 - w35) * w1)) + ((w36 + w37) * w2))) - ((((((w6 * w39) + (w11 * w40)) + (w13 * w41)) + (w16 * w42)) + (w18 * w43)) + (w7 * w44))
    w24 = (w34 * w32) * 0.25
    w31 = w31 * 0.5
    w45 = ((-0.05) * w30) - (0.1 * w38)
    w46 = 0.1 * w40
    w47 = 0.1 * w42
    r0[1] = (w25 - ((((w35 + w33) * w0) + ((1.0 + ((w32 * w32) * 0.25)) * w1)) + ((w24 - w31) * w2))) + ((((((w12 * w40) - (w6 * w45)) + (w13 * w46)) + (w17 * w42)) + (w18 * w47)) + (w8 * w44))
    r0[2] = (w26 - ((((w37 - w36) * w0) + ((w31 + w24) * w1)) + ((1.0 + ((w34 * w34) * 0.25)) * w2))) + ((((((w7 * w45) + (w8 * w39)) - (w11 * w46)) + (w12 * w41)) - (w16 * w47)) + (w17 * w43))
    w0 = w30 * w3
    w1 = 0.6 * w3
    w2 = w30 * w4
    w3 = (w2 * w0) * 0.25
    w6 = w30 * w5
    w7 = w6 * 0.5
    w4 = 0.5 * w4
    w8 = w2 * 0.5
    w11 = (w6 * w0) * 0.25
    w5 = 0.15 * w5
    w12 = ((-0.03) * w30) - ((-0.1) * w38)
    w13 = (-0.3) * w40
    w16 = (-0.1) * w40
    w17 = (-0.3) * w42
    w18 = (-0.1) * w42
    w24 = (0.30000000000000004 * w30) - ((-0.3) * w38)
    r0[3] = (w27 - ((((1.0 + ((w0 * w0) * 0.25)) * w1) + ((w3 - w7) * w4)) + ((w8 + w11) * w5))) + ((((((w10 * w12) + (w14 * w13)) - (w15 * w16)) + (w19 * w17)) - (w20 * w18)) - (w9 * w24))
    w9 = (w6 * w2) * 0.25
    w0 = w0 * 0.5
    r0[4] = (w28 - ((((w7 + w3) * w1) + ((1.0 + ((w2 * w2) * 0.25)) * w4)) + ((w9 - w0) * w5))) + ((w21 * w24) - ((w22 * w13) + (w23 * w17)))
    r0[5] = (w29 - ((((w11 - w8) * w1) + ((w0 + w9) * w4)) + ((1.0 + ((w6 * w6) * 0.25)) * w5))) + (((w22 * w16) - (w21 * w12)) + (w23 * w18))
    return [r0]


def residual(z, g, p, h):
    """residual(z[6], g[36], p[6], h[1]) -> [F[6]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (6,):
        z = z.tolist()
    else:
        z = _vec(z, 6, "residual: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "residual: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (6,):
        p = p.tolist()
    else:
        p = _vec(p, 6, "residual: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "residual: h")
    _r = _raw_residual(z, g, p, h)
    return [_fromiter(_r[0], _F64, 6)]


def _raw_jacobian(z, g, p, h):
    """jacobian on lists of Python floats -> [J[36]] as lists (see RAW)"""
    w0, w1, w2, w3, w4, w5 = z
    w6, = h
    r0 = [0.0] * 36
    w7 = 0.9 * w0
    w0 = w6 * w0
    w8 = w6 * w1
    w9 = 0.25 * (w8 * w6)
    w10 = w1 * w9
    w11 = 0.2 * w2
    w2 = w6 * w2
    w12 = 0.25 * (w2 * w6)
    w13 = w11 * w12
    r0[0] = -((((w7 * (0.25 * ((2.0 * w0) * w6))) + (0.9 * (1.0 + ((w0 * w0) * 0.25)))) + w10) + w13)
    w14 = w2 * 0.5
    w15 = (w0 * w8) * 0.25
    w16 = 0.5 * w6
    w17 = w11 * w16
    r0[1] = -(((w7 * w9) + (0.9 * (w14 + w15))) - w17)
    w18 = (w0 * w2) * 0.25
    w19 = w8 * 0.5
    w20 = w1 * w16
    r0[2] = -(((w7 * w12) + (0.9 * (w18 - w19))) + w20)
    r0[3] = 0.0
    r0[4] = 0.0
    r0[5] = 0.0
    w21 = 0.25 * (w0 * w6)
    r0[6] = -(((w1 * w21) + (w15 - w14)) + w17)
    w14 = w7 * w21
    r0[7] = -((w14 + ((w1 * (0.25 * ((2.0 * w8) * w6))) + (1.0 + ((w8 * w8) * 0.25)))) + w13)
    w0 = w0 * 0.5
    w8 = (w8 * w2) * 0.25
    w7 = w7 * w16
    r0[8] = -(((w1 * w12) + (w0 + w8)) - w7)
    r0[9] = 0.0
    r0[10] = 0.0
    r0[11] = 0.0
    r0[12] = -(((w11 * w21) + (0.2 * (w19 + w18))) - w20)
    r0[13] = -(w7 + ((w11 * w9) + (0.2 * (w8 - w0))))
    r0[14] = -((w14 + w10) + ((w11 * (0.25 * ((2.0 * w2) * w6))) + (0.2 * (1.0 + ((w2 * w2) * 0.25)))))
    r0[15] = 0.0
    r0[16] = 0.0
    r0[17] = 0.0
    r0[18] = 0.0
    r0[19] = 0.0
    r0[20] = 0.0
    w0 = 0.6 * w3
    w1 = w6 * w3
    w2 = 0.5 * w4
    w3 = w6 * w4
    w4 = 0.25 * (w3 * w6)
    w7 = w2 * w4
    w8 = 0.15 * w5
    w5 = w6 * w5
    w9 = 0.25 * (w5 * w6)
    w10 = w8 * w9
    r0[21] = -((((w0 * (0.25 * ((2.0 * w1) * w6))) + (0.6 * (1.0 + ((w1 * w1) * 0.25)))) + w7) + w10)
    w11 = w5 * 0.5
    w12 = (w1 * w3) * 0.25
    w13 = w8 * w16
    r0[22] = -(((w0 * w4) + (0.6 * (w11 + w12))) - w13)
    w14 = (w1 * w5) * 0.25
    w15 = w3 * 0.5
    w17 = w2 * w16
    r0[23] = -(((w0 * w9) + (0.6 * (w14 - w15))) + w17)
    r0[24] = 0.0
    r0[25] = 0.0
    r0[26] = 0.0
    w18 = 0.25 * (w1 * w6)
    r0[27] = -(((w2 * w18) + (0.5 * (w12 - w11))) + w13)
    w11 = w0 * w18
    r0[28] = -((w11 + ((w2 * (0.25 * ((2.0 * w3) * w6))) + (0.5 * (1.0 + ((w3 * w3) * 0.25))))) + w10)
    w1 = w1 * 0.5
    w3 = (w3 * w5) * 0.25
    w0 = w0 * w16
    r0[29] = -(((w2 * w9) + (0.5 * (w1 + w3))) - w0)
    r0[30] = 0.0
    r0[31] = 0.0
    r0[32] = 0.0
    r0[33] = -(((w8 * w18) + (0.15 * (w15 + w14))) - w17)
    r0[34] = -(w0 + ((w8 * w4) + (0.15 * (w3 - w1))))
    r0[35] = -((w11 + w7) + ((w8 * (0.25 * ((2.0 * w5) * w6))) + (0.15 * (1.0 + ((w5 * w5) * 0.25)))))
    return [r0]


def jacobian(z, g, p, h):
    """jacobian(z[6], g[36], p[6], h[1]) -> [J[36]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (6,):
        z = z.tolist()
    else:
        z = _vec(z, 6, "jacobian: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "jacobian: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (6,):
        p = p.tolist()
    else:
        p = _vec(p, 6, "jacobian: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "jacobian: h")
    _r = _raw_jacobian(z, g, p, h)
    return [_fromiter(_r[0], _F64, 36)]


def _raw_residual_jacobian(z, g, p, h):
    """residual_jacobian on lists of Python floats -> [F[6], J[36]] as lists (see RAW)"""
    w0, w1, w2, w3, w4, w5 = z
    w17, w12, w8, _, _, _, w16, w11, w7, _, _, _, w18, w13, w6, _, _, _, _, _, _, w23, w22, w21, _, _, _, w19, w14, w9, _, _, _, w20, w15, w10 = g
    w24, w25, w26, w27, w28, w29 = p
    w30, = h
    r0 = [0.0] * 6
    r1 = [0.0] * 36
    w31 = w30 * w0
    w32 = 1.0 + ((w31 * w31) * 0.25)
    w0 = 0.9 * w0
    w33 = w30 * w1
    w34 = (w33 * w31) * 0.25
    w35 = w30 * w2
    w36 = w35 * 0.5
    w37 = w34 - w36
    w38 = w33 * 0.5
    w39 = (w35 * w31) * 0.25
    w40 = w38 + w39
    w2 = 0.2 * w2
    w41 = (2.0 * (((((1.3 + (0.05 * w7)) + (0.1 * w8)) - w6) + ((-0.1) * w9)) + ((-0.3) * w10))) * w30
    w42 = 0.05 * w41
    w43 = (2.0 * (((((0.05 * w11) + (0.1 * w12)) - w13) + ((-0.1) * w14)) + ((-0.3) * w15))) * w30
    w44 = 0.05 * w43
    w45 = (2.0 * (((((0.05 * w16) + (0.1 * w17)) - w18) + ((-0.1) * w19)) + ((-0.3) * w20))) * w30
    w46 = 0.05 * w45
    w47 = 0.5 * w30
    w48 = w41 + w47
    r0[0] = (w24 - (((w32 * w0) + (w37 * w1)) + (w40 * w2))) - ((((((w6 * w42) + (w11 * w43)) + (w13 * w44)) + (w16 * w45)) + (w18 * w46)) + (w7 * w48))
    w24 = w36 + w34
    w34 = 1.0 + ((w33 * w33) * 0.25)
    w36 = (w35 * w33) * 0.25
    w49 = w31 * 0.5
    w50 = w36 - w49
    w51 = ((-0.05) * w30) - (0.1 * w41)
    w52 = 0.1 * w43
    w53 = 0.1 * w45
    r0[1] = (w25 - (((w24 * w0) + (w34 * w1)) + (w50 * w2))) + ((((((w12 * w43) - (w6 * w51)) + (w13 * w52)) + (w17 * w45)) + (w18 * w53)) + (w8 * w48))
    w6 = w39 - w38
    w13 = w49 + w36
    w18 = 1.0 + ((w35 * w35) * 0.25)
    r0[2] = (w26 - (((w6 * w0) + (w13 * w1)) + (w18 * w2))) + ((((((w7 * w51) + (w8 * w42)) - (w11 * w52)) + (w12 * w44)) - (w16 * w53)) + (w17 * w46))
    w7 = w30 * w3
    w8 = 1.0 + ((w7 * w7) * 0.25)
    w3 = 0.6 * w3
    w11 = w30 * w4
    w12 = (w11 * w7) * 0.25
    w16 = w30 * w5
    w17 = w16 * 0.5
    w25 = w12 - w17
    w4 = 0.5 * w4
    w26 = w11 * 0.5
    w36 = (w16 * w7) * 0.25
    w38 = w26 + w36
    w5 = 0.15 * w5
    w39 = ((-0.03) * w30) - ((-0.1) * w41)
    w42 = (-0.3) * w43
    w43 = (-0.1) * w43
    w44 = (-0.3) * w45
    w45 = (-0.1) * w45
    w41 = (0.30000000000000004 * w30) - ((-0.3) * w41)
    r0[3] = (w27 - (((w8 * w3) + (w25 * w4)) + (w38 * w5))) + ((((((w10 * w39) + (w14 * w42)) - (w15 * w43)) + (w19 * w44)) - (w20 * w45)) - (w9 * w41))
    w9 = w17 + w12
    w10 = 1.0 + ((w11 * w11) * 0.25)
    w12 = (w16 * w11) * 0.25
    w14 = w7 * 0.5
    w15 = w12 - w14
    r0[4] = (w28 - (((w9 * w3) + (w10 * w4)) + (w15 * w5))) + ((w21 * w41) - ((w22 * w42) + (w23 * w44)))
    w17 = w36 - w26
    w12 = w14 + w12
    w14 = 1.0 + ((w16 * w16) * 0.25)
    r0[5] = (w29 - (((w17 * w3) + (w12 * w4)) + (w14 * w5))) + (((w22 * w43) - (w21 * w39)) + (w23 * w45))
    w19 = 0.25 * (w33 * w30)
    w20 = w1 * w19
    w21 = 0.25 * (w35 * w30)
    w22 = w2 * w21
    r1[0] = -((((w0 * (0.25 * ((2.0 * w31) * w30))) + (0.9 * w32)) + w20) + w22)
    w23 = w2 * w47
    r1[1] = -(((w0 * w19) + (0.9 * w24)) - w23)
    w24 = w1 * w47
    r1[2] = -(((w0 * w21) + (0.9 * w6)) + w24)
    r1[3] = 0.0
    r1[4] = 0.0
    r1[5] = 0.0
    w6 = 0.25 * (w31 * w30)
    r1[6] = -(((w1 * w6) + w37) + w23)
    w23 = w0 * w6
    r1[7] = -((w23 + ((w1 * (0.25 * ((2.0 * w33) * w30))) + w34)) + w22)
    w0 = w0 * w47
    r1[8] = -(((w1 * w21) + w13) - w0)
    r1[9] = 0.0
    r1[10] = 0.0
    r1[11] = 0.0
    r1[12] = -(((w2 * w6) + (0.2 * w40)) - w24)
    r1[13] = -(w0 + ((w2 * w19) + (0.2 * w50)))
    r1[14] = -((w23 + w20) + ((w2 * (0.25 * ((2.0 * w35) * w30))) + (0.2 * w18)))
    r1[15] = 0.0
    r1[16] = 0.0
    r1[17] = 0.0
    r1[18] = 0.0
    r1[19] = 0.0
    r1[20] = 0.0
    w0 = 0.25 * (w11 * w30)
    w1 = w4 * w0
    w2 = 0.25 * (w16 * w30)
    w6 = w5 * w2
    r1[21] = -((((w3 * (0.25 * ((2.0 * w7) * w30))) + (0.6 * w8)) + w1) + w6)
    w8 = w5 * w47
    r1[22] = -(((w3 * w0) + (0.6 * w9)) - w8)
    w9 = w4 * w47
    r1[23] = -(((w3 * w2) + (0.6 * w17)) + w9)
    r1[24] = 0.0
    r1[25] = 0.0
    r1[26] = 0.0
    w7 = 0.25 * (w7 * w30)
    r1[27] = -(((w4 * w7) + (0.5 * w25)) + w8)
    w8 = w3 * w7
    r1[28] = -((w8 + ((w4 * (0.25 * ((2.0 * w11) * w30))) + (0.5 * w10))) + w6)
    w3 = w3 * w47
    r1[29] = -(((w4 * w2) + (0.5 * w12)) - w3)
    r1[30] = 0.0
    r1[31] = 0.0
    r1[32] = 0.0
    r1[33] = -(((w5 * w7) + (0.15 * w38)) - w9)
    r1[34] = -(w3 + ((w5 * w0) + (0.15 * w15)))
    r1[35] = -((w8 + w1) + ((w5 * (0.25 * ((2.0 * w16) * w30))) + (0.15 * w14)))
    return [r0, r1]


def residual_jacobian(z, g, p, h):
    """residual_jacobian(z[6], g[36], p[6], h[1]) -> [F[6], J[36]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (6,):
        z = z.tolist()
    else:
        z = _vec(z, 6, "residual_jacobian: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "residual_jacobian: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (6,):
        p = p.tolist()
    else:
        p = _vec(p, 6, "residual_jacobian: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "residual_jacobian: h")
    _r = _raw_residual_jacobian(z, g, p, h)
    return [_fromiter(_r[0], _F64, 6), _fromiter(_r[1], _F64, 36)]


def _raw_update(z, g, p, h):
    """update on lists of Python floats -> [g1[36], p1[6]] as lists (see RAW)"""
    try:
        w0, w1, w2, w3, w4, w5 = z
        w6, w9, w12, w15, w18, w21, w7, w10, w13, w16, w19, w22, w8, w11, w14, w17, w20, w23, w24, w27, w30, w33, w36, w39, w25, w28, w31, w34, w37, w40, w26, w29, w32, w35, w38, w41 = g
        w42, = h
        r0 = [0.0] * 36
        r1 = [0.0] * 6
        w43 = w42 * w0
        w44 = w43 * w43
        w45 = w42 * w1
        w46 = w45 * w45
        w47 = w44 + w46
        w48 = w42 * w2
        w49 = w48 * w48
        w50 = 4.0 / (4.0 + (w47 + w49))
        w51 = 1.0 - (w50 * ((w49 + w46) * 0.5))
        w52 = w43 * w45
        w53 = w52 * 0.5
        w54 = w50 * (w48 + w53)
        w55 = w43 * w48
        w56 = w55 * 0.5
        w57 = w50 * (w56 - w45)
        w58 = ((w6 * w51) + (w7 * w54)) + (w8 * w57)
        r0[0] = w58
        w59 = ((w9 * w51) + (w10 * w54)) + (w11 * w57)
        r0[1] = w59
        w60 = ((w12 * w51) + (w13 * w54)) + (w14 * w57)
        r0[2] = w60
        r0[3] = ((w15 * w51) + (w16 * w54)) + (w17 * w57)
        r0[4] = ((w18 * w51) + (w19 * w54)) + (w20 * w57)
        r0[5] = ((w21 * w51) + (w22 * w54)) + (w23 * w57)
        w51 = w50 * (w53 - w48)
        w53 = 1.0 - (w50 * ((w49 + w44) * 0.5))
        w54 = w45 * w48
        w57 = w54 * 0.5
        w61 = w50 * (w43 + w57)
        w62 = ((w6 * w51) + (w7 * w53)) + (w8 * w61)
        r0[6] = w62
        w63 = ((w9 * w51) + (w10 * w53)) + (w11 * w61)
        r0[7] = w63
        w64 = ((w12 * w51) + (w13 * w53)) + (w14 * w61)
        r0[8] = w64
        r0[9] = ((w15 * w51) + (w16 * w53)) + (w17 * w61)
        r0[10] = ((w18 * w51) + (w19 * w53)) + (w20 * w61)
        r0[11] = ((w21 * w51) + (w22 * w53)) + (w23 * w61)
        w51 = w50 * (w45 + w56)
        w53 = w50 * (w57 - w43)
        w47 = 1.0 - (w50 * (w47 * 0.5))
        w6 = ((w6 * w51) + (w7 * w53)) + (w8 * w47)
        r0[12] = w6
        w7 = ((w9 * w51) + (w10 * w53)) + (w11 * w47)
        r0[13] = w7
        w8 = ((w12 * w51) + (w13 * w53)) + (w14 * w47)
        r0[14] = w8
        r0[15] = ((w15 * w51) + (w16 * w53)) + (w17 * w47)
        r0[16] = ((w18 * w51) + (w19 * w53)) + (w20 * w47)
        r0[17] = ((w21 * w51) + (w22 * w53)) + (w23 * w47)
        w9 = w42 * w3
        w10 = w9 * w9
        w11 = w42 * w4
        w12 = w11 * w11
        w13 = w10 + w12
        w14 = w42 * w5
        w15 = w14 * w14
        w16 = 4.0 / (4.0 + (w13 + w15))
        w17 = 1.0 - (w16 * ((w15 + w12) * 0.5))
        w18 = w9 * w11
        w19 = w18 * 0.5
        w20 = w16 * (w14 + w19)
        w21 = w9 * w14
        w22 = w21 * 0.5
        w23 = w16 * (w22 - w11)
        r0[18] = ((w24 * w17) + (w25 * w20)) + (w26 * w23)
        r0[19] = ((w27 * w17) + (w28 * w20)) + (w29 * w23)
        r0[20] = ((w30 * w17) + (w31 * w20)) + (w32 * w23)
        w47 = ((w33 * w17) + (w34 * w20)) + (w35 * w23)
        r0[21] = w47
        w50 = ((w36 * w17) + (w37 * w20)) + (w38 * w23)
        r0[22] = w50
        w17 = ((w39 * w17) + (w40 * w20)) + (w41 * w23)
        r0[23] = w17
        w19 = w16 * (w19 - w14)
        w20 = 1.0 - (w16 * ((w15 + w10) * 0.5))
        w23 = w11 * w14
        w51 = w23 * 0.5
        w53 = w16 * (w9 + w51)
        r0[24] = ((w24 * w19) + (w25 * w20)) + (w26 * w53)
        r0[25] = ((w27 * w19) + (w28 * w20)) + (w29 * w53)
        r0[26] = ((w30 * w19) + (w31 * w20)) + (w32 * w53)
        w56 = ((w33 * w19) + (w34 * w20)) + (w35 * w53)
        r0[27] = w56
        w57 = ((w36 * w19) + (w37 * w20)) + (w38 * w53)
        r0[28] = w57
        w19 = ((w39 * w19) + (w40 * w20)) + (w41 * w53)
        r0[29] = w19
        w20 = w16 * (w11 + w22)
        w22 = w16 * (w51 - w9)
        w13 = 1.0 - (w16 * (w13 * 0.5))
        r0[30] = ((w24 * w20) + (w25 * w22)) + (w26 * w13)
        r0[31] = ((w27 * w20) + (w28 * w22)) + (w29 * w13)
        r0[32] = ((w30 * w20) + (w31 * w22)) + (w32 * w13)
        w16 = ((w33 * w20) + (w34 * w22)) + (w35 * w13)
        r0[33] = w16
        w24 = ((w36 * w20) + (w37 * w22)) + (w38 * w13)
        r0[34] = w24
        w13 = ((w39 * w20) + (w40 * w22)) + (w41 * w13)
        r0[35] = w13
        w0 = 0.9 * w0
        w20 = w48 * 0.5
        w22 = w52 * 0.25
        w25 = w55 * 0.25
        w26 = w45 * 0.5
        w2 = 0.2 * w2
        w27 = (2.0 * (((((1.3 + (0.05 * w64)) + (0.1 * w60)) - w8) + ((-0.1) * w19)) + ((-0.3) * w13))) * w42
        w28 = 0.05 * w27
        w29 = (2.0 * (((((0.05 * w63) + (0.1 * w59)) - w7) + ((-0.1) * w57)) + ((-0.3) * w24))) * w42
        w30 = 0.05 * w29
        w31 = (2.0 * (((((0.05 * w62) + (0.1 * w58)) - w6) + ((-0.1) * w56)) + ((-0.3) * w16))) * w42
        w32 = 0.05 * w31
        w33 = w27 + (0.5 * w42)
        r1[0] = ((((1.0 + (w44 * 0.25)) * w0) + ((w20 + w22) * w1)) + ((w25 - w26) * w2)) - ((((((w8 * w28) + (w63 * w29)) + (w7 * w30)) + (w62 * w31)) + (w6 * w32)) + (w64 * w33))
        w34 = w43 * 0.5
        w35 = w54 * 0.25
        w36 = ((-0.05) * w42) - (0.1 * w27)
        w37 = 0.1 * w29
        w38 = 0.1 * w31
        r1[1] = ((((w22 - w20) * w0) + ((1.0 + (w46 * 0.25)) * w1)) + ((w34 + w35) * w2)) + ((((((w59 * w29) - (w8 * w36)) + (w7 * w37)) + (w58 * w31)) + (w6 * w38)) + (w60 * w33))
        r1[2] = ((((w26 + w25) * w0) + ((w35 - w34) * w1)) + ((1.0 + (w49 * 0.25)) * w2)) + ((((((w64 * w36) + (w60 * w28)) - (w63 * w37)) + (w59 * w30)) - (w62 * w38)) + (w58 * w32))
        w0 = 0.6 * w3
        w1 = w14 * 0.5
        w2 = w18 * 0.25
        w3 = 0.5 * w4
        w4 = w21 * 0.25
        w6 = w11 * 0.5
        w5 = 0.15 * w5
        w7 = ((-0.03) * w42) - ((-0.1) * w27)
        w8 = (-0.3) * w29
        w11 = (-0.1) * w29
        w14 = (-0.3) * w31
        w18 = (-0.1) * w31
        w20 = (0.30000000000000004 * w42) - ((-0.3) * w27)
        r1[3] = ((((1.0 + (w10 * 0.25)) * w0) + ((w1 + w2) * w3)) + ((w4 - w6) * w5)) + ((((((w13 * w7) + (w57 * w8)) - (w24 * w11)) + (w56 * w14)) - (w16 * w18)) - (w19 * w20))
        w9 = w9 * 0.5
        w10 = w23 * 0.25
        r1[4] = ((((w2 - w1) * w0) + ((1.0 + (w12 * 0.25)) * w3)) + ((w9 + w10) * w5)) + ((w17 * w20) - ((w50 * w8) + (w47 * w14)))
        r1[5] = ((((w6 + w4) * w0) + ((w10 - w9) * w3)) + ((1.0 + (w15 * 0.25)) * w5)) + (((w50 * w11) - (w17 * w7)) + (w47 * w18))
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 36
        r1 = [0.0] * 6
        w0 = g[0]
        w1 = 1.0
        w2 = 4.0
        w3 = h[0]
        w4 = z[0]
        w5 = w3 * w4
        w6 = w5 * w5
        w7 = z[1]
        w8 = w3 * w7
        w9 = w8 * w8
        w10 = w6 + w9
        w11 = z[2]
        w12 = w3 * w11
        w13 = w12 * w12
        w10 = w10 + w13
        w10 = w2 + w10
        w10 = w2 / w10 if w10 else _div(w2, w10)
        w14 = w13 + w9
        w15 = 2.0
        w14 = w14 / w15 if w15 else _div(w14, w15)
        w14 = w10 * w14
        w14 = w1 - w14
        w16 = w0 * w14
        w17 = g[6]
        w18 = w5 * w8
        w19 = w18 / w15 if w15 else _div(w18, w15)
        w19 = w12 + w19
        w19 = w10 * w19
        w20 = w17 * w19
        w16 = w16 + w20
        w20 = g[12]
        w21 = w5 * w12
        w22 = w21 / w15 if w15 else _div(w21, w15)
        w22 = w22 - w8
        w22 = w10 * w22
        w23 = w20 * w22
        w16 = w16 + w23
        r0[0] = w16
        w23 = g[1]
        w24 = w23 * w14
        w25 = g[7]
        w26 = w25 * w19
        w24 = w24 + w26
        w26 = g[13]
        w27 = w26 * w22
        w24 = w24 + w27
        r0[1] = w24
        w27 = g[2]
        w28 = w27 * w14
        w29 = g[8]
        w30 = w29 * w19
        w28 = w28 + w30
        w30 = g[14]
        w31 = w30 * w22
        w28 = w28 + w31
        r0[2] = w28
        w31 = g[3]
        w32 = w31 * w14
        w33 = g[9]
        w34 = w33 * w19
        w32 = w32 + w34
        w34 = g[15]
        w35 = w34 * w22
        w32 = w32 + w35
        r0[3] = w32
        w32 = g[4]
        w35 = w32 * w14
        w36 = g[10]
        w37 = w36 * w19
        w35 = w35 + w37
        w37 = g[16]
        w38 = w37 * w22
        w35 = w35 + w38
        r0[4] = w35
        w35 = g[5]
        w14 = w35 * w14
        w38 = g[11]
        w19 = w38 * w19
        w14 = w14 + w19
        w19 = g[17]
        w22 = w19 * w22
        w14 = w14 + w22
        r0[5] = w14
        w14 = w8 * w5
        w22 = w14 / w15 if w15 else _div(w14, w15)
        w22 = w22 - w12
        w22 = w10 * w22
        w39 = w0 * w22
        w40 = w13 + w6
        w40 = w40 / w15 if w15 else _div(w40, w15)
        w40 = w10 * w40
        w40 = w1 - w40
        w41 = w17 * w40
        w39 = w39 + w41
        w41 = w8 * w12
        w42 = w41 / w15 if w15 else _div(w41, w15)
        w42 = w5 + w42
        w42 = w10 * w42
        w43 = w20 * w42
        w39 = w39 + w43
        r0[6] = w39
        w43 = w23 * w22
        w44 = w25 * w40
        w43 = w43 + w44
        w44 = w26 * w42
        w43 = w43 + w44
        r0[7] = w43
        w44 = w27 * w22
        w45 = w29 * w40
        w44 = w44 + w45
        w45 = w30 * w42
        w44 = w44 + w45
        r0[8] = w44
        w45 = w31 * w22
        w46 = w33 * w40
        w45 = w45 + w46
        w46 = w34 * w42
        w45 = w45 + w46
        r0[9] = w45
        w45 = w32 * w22
        w46 = w36 * w40
        w45 = w45 + w46
        w46 = w37 * w42
        w45 = w45 + w46
        r0[10] = w45
        w22 = w35 * w22
        w40 = w38 * w40
        w22 = w22 + w40
        w42 = w19 * w42
        w22 = w22 + w42
        r0[11] = w22
        w22 = w12 * w5
        w42 = w22 / w15 if w15 else _div(w22, w15)
        w42 = w8 + w42
        w42 = w10 * w42
        w0 = w0 * w42
        w40 = w12 * w8
        w45 = w40 / w15 if w15 else _div(w40, w15)
        w45 = w45 - w5
        w45 = w10 * w45
        w17 = w17 * w45
        w0 = w0 + w17
        w17 = w9 + w6
        w17 = w17 / w15 if w15 else _div(w17, w15)
        w10 = w10 * w17
        w10 = w1 - w10
        w20 = w20 * w10
        w0 = w0 + w20
        r0[12] = w0
        w23 = w23 * w42
        w25 = w25 * w45
        w23 = w23 + w25
        w26 = w26 * w10
        w23 = w23 + w26
        r0[13] = w23
        w27 = w27 * w42
        w29 = w29 * w45
        w27 = w27 + w29
        w30 = w30 * w10
        w27 = w27 + w30
        r0[14] = w27
        w31 = w31 * w42
        w33 = w33 * w45
        w31 = w31 + w33
        w34 = w34 * w10
        w31 = w31 + w34
        r0[15] = w31
        w32 = w32 * w42
        w36 = w36 * w45
        w32 = w32 + w36
        w37 = w37 * w10
        w32 = w32 + w37
        r0[16] = w32
        w35 = w35 * w42
        w38 = w38 * w45
        w35 = w35 + w38
        w19 = w19 * w10
        w35 = w35 + w19
        r0[17] = w35
        w35 = g[18]
        w19 = z[3]
        w10 = w3 * w19
        w38 = w10 * w10
        w45 = z[4]
        w42 = w3 * w45
        w32 = w42 * w42
        w37 = w38 + w32
        w36 = z[5]
        w31 = w3 * w36
        w34 = w31 * w31
        w37 = w37 + w34
        w37 = w2 + w37
        w37 = w2 / w37 if w37 else _div(w2, w37)
        w33 = w34 + w32
        w33 = w33 / w15 if w15 else _div(w33, w15)
        w33 = w37 * w33
        w33 = w1 - w33
        w30 = w35 * w33
        w29 = g[24]
        w26 = w10 * w42
        w25 = w26 / w15 if w15 else _div(w26, w15)
        w25 = w31 + w25
        w25 = w37 * w25
        w20 = w29 * w25
        w30 = w30 + w20
        w20 = g[30]
        w17 = w10 * w31
        w46 = w17 / w15 if w15 else _div(w17, w15)
        w46 = w46 - w42
        w46 = w37 * w46
        w47 = w20 * w46
        w30 = w30 + w47
        r0[18] = w30
        w30 = g[19]
        w47 = w30 * w33
        w48 = g[25]
        w49 = w48 * w25
        w47 = w47 + w49
        w49 = g[31]
        w50 = w49 * w46
        w47 = w47 + w50
        r0[19] = w47
        w47 = g[20]
        w50 = w47 * w33
        w51 = g[26]
        w52 = w51 * w25
        w50 = w50 + w52
        w52 = g[32]
        w53 = w52 * w46
        w50 = w50 + w53
        r0[20] = w50
        w50 = g[21]
        w53 = w50 * w33
        w54 = g[27]
        w55 = w54 * w25
        w53 = w53 + w55
        w55 = g[33]
        w56 = w55 * w46
        w53 = w53 + w56
        r0[21] = w53
        w56 = g[22]
        w57 = w56 * w33
        w58 = g[28]
        w59 = w58 * w25
        w57 = w57 + w59
        w59 = g[34]
        w60 = w59 * w46
        w57 = w57 + w60
        r0[22] = w57
        w60 = g[23]
        w33 = w60 * w33
        w61 = g[29]
        w25 = w61 * w25
        w33 = w33 + w25
        w25 = g[35]
        w46 = w25 * w46
        w33 = w33 + w46
        r0[23] = w33
        w46 = w42 * w10
        w62 = w46 / w15 if w15 else _div(w46, w15)
        w62 = w62 - w31
        w62 = w37 * w62
        w63 = w35 * w62
        w64 = w34 + w38
        w64 = w64 / w15 if w15 else _div(w64, w15)
        w64 = w37 * w64
        w64 = w1 - w64
        w65 = w29 * w64
        w63 = w63 + w65
        w65 = w42 * w31
        w66 = w65 / w15 if w15 else _div(w65, w15)
        w66 = w10 + w66
        w66 = w37 * w66
        w67 = w20 * w66
        w63 = w63 + w67
        r0[24] = w63
        w63 = w30 * w62
        w67 = w48 * w64
        w63 = w63 + w67
        w67 = w49 * w66
        w63 = w63 + w67
        r0[25] = w63
        w63 = w47 * w62
        w67 = w51 * w64
        w63 = w63 + w67
        w67 = w52 * w66
        w63 = w63 + w67
        r0[26] = w63
        w63 = w50 * w62
        w67 = w54 * w64
        w63 = w63 + w67
        w67 = w55 * w66
        w63 = w63 + w67
        r0[27] = w63
        w67 = w56 * w62
        w68 = w58 * w64
        w67 = w67 + w68
        w68 = w59 * w66
        w67 = w67 + w68
        r0[28] = w67
        w62 = w60 * w62
        w64 = w61 * w64
        w62 = w62 + w64
        w66 = w25 * w66
        w62 = w62 + w66
        r0[29] = w62
        w66 = w31 * w10
        w64 = w66 / w15 if w15 else _div(w66, w15)
        w64 = w42 + w64
        w64 = w37 * w64
        w35 = w35 * w64
        w68 = w31 * w42
        w69 = w68 / w15 if w15 else _div(w68, w15)
        w69 = w69 - w10
        w69 = w37 * w69
        w29 = w29 * w69
        w35 = w35 + w29
        w29 = w32 + w38
        w29 = w29 / w15 if w15 else _div(w29, w15)
        w37 = w37 * w29
        w37 = w1 - w37
        w20 = w20 * w37
        w35 = w35 + w20
        r0[30] = w35
        w30 = w30 * w64
        w48 = w48 * w69
        w30 = w30 + w48
        w49 = w49 * w37
        w30 = w30 + w49
        r0[31] = w30
        w47 = w47 * w64
        w51 = w51 * w69
        w47 = w47 + w51
        w52 = w52 * w37
        w47 = w47 + w52
        r0[32] = w47
        w50 = w50 * w64
        w54 = w54 * w69
        w50 = w50 + w54
        w55 = w55 * w37
        w50 = w50 + w55
        r0[33] = w50
        w56 = w56 * w64
        w58 = w58 * w69
        w56 = w56 + w58
        w59 = w59 * w37
        w56 = w56 + w59
        r0[34] = w56
        w60 = w60 * w64
        w61 = w61 * w69
        w60 = w60 + w61
        w25 = w25 * w37
        w60 = w60 + w25
        r0[35] = w60
        w6 = w6 / w2 if w2 else _div(w6, w2)
        w6 = w1 + w6
        w25 = 0.9
        w25 = w25 * w4
        w6 = w6 * w25
        w12 = w12 / w15 if w15 else _div(w12, w15)
        w14 = w14 / w2 if w2 else _div(w14, w2)
        w14 = w12 + w14
        w14 = w14 * w7
        w6 = w6 + w14
        w22 = w22 / w2 if w2 else _div(w22, w2)
        w8 = w8 / w15 if w15 else _div(w8, w15)
        w22 = w22 - w8
        w14 = 0.2
        w14 = w14 * w11
        w22 = w22 * w14
        w6 = w6 + w22
        w22 = 0.05
        w11 = 1.3
        w4 = w22 * w44
        w11 = w11 + w4
        w4 = 0.1
        w37 = w4 * w28
        w11 = w11 + w37
        w11 = w11 - w27
        w37 = -0.1
        w61 = w37 * w62
        w11 = w11 + w61
        w61 = -0.3
        w69 = w61 * w60
        w11 = w11 + w69
        w11 = 2.0 * w11
        w11 = w11 * w3
        w69 = w22 * w11
        w64 = w27 * w69
        w59 = w22 * w43
        w58 = w4 * w24
        w59 = w59 + w58
        w59 = w59 - w23
        w58 = w37 * w67
        w59 = w59 + w58
        w58 = w61 * w56
        w59 = w59 + w58
        w59 = 2.0 * w59
        w59 = w59 * w3
        w58 = w43 * w59
        w64 = w64 + w58
        w58 = w22 * w59
        w55 = w23 * w58
        w64 = w64 + w55
        w55 = w22 * w39
        w54 = w4 * w16
        w55 = w55 + w54
        w55 = w55 - w0
        w54 = w37 * w63
        w55 = w55 + w54
        w54 = w61 * w50
        w55 = w55 + w54
        w55 = 2.0 * w55
        w55 = w55 * w3
        w54 = w39 * w55
        w64 = w64 + w54
        w22 = w22 * w55
        w54 = w0 * w22
        w64 = w64 + w54
        w54 = 0.5
        w47 = w54 * w3
        w47 = w11 + w47
        w52 = w44 * w47
        w64 = w64 + w52
        w6 = w6 - w64
        r1[0] = w6
        w18 = w18 / w2 if w2 else _div(w18, w2)
        w18 = w18 - w12
        w18 = w18 * w25
        w9 = w9 / w2 if w2 else _div(w9, w2)
        w9 = w1 + w9
        w9 = w9 * w7
        w18 = w18 + w9
        w5 = w5 / w15 if w15 else _div(w5, w15)
        w40 = w40 / w2 if w2 else _div(w40, w2)
        w40 = w5 + w40
        w40 = w40 * w14
        w18 = w18 + w40
        w40 = w24 * w59
        w9 = -0.05
        w9 = w9 * w3
        w12 = w4 * w11
        w9 = w9 - w12
        w27 = w27 * w9
        w40 = w40 - w27
        w27 = w4 * w59
        w23 = w23 * w27
        w40 = w40 + w23
        w23 = w16 * w55
        w40 = w40 + w23
        w4 = w4 * w55
        w0 = w0 * w4
        w40 = w40 + w0
        w47 = w28 * w47
        w40 = w40 + w47
        w18 = w18 + w40
        r1[1] = w18
        w21 = w21 / w2 if w2 else _div(w21, w2)
        w8 = w8 + w21
        w8 = w8 * w25
        w41 = w41 / w2 if w2 else _div(w41, w2)
        w41 = w41 - w5
        w41 = w41 * w7
        w8 = w8 + w41
        w13 = w13 / w2 if w2 else _div(w13, w2)
        w13 = w1 + w13
        w13 = w13 * w14
        w8 = w8 + w13
        w44 = w44 * w9
        w28 = w28 * w69
        w44 = w44 + w28
        w43 = w43 * w27
        w44 = w44 - w43
        w24 = w24 * w58
        w44 = w44 + w24
        w39 = w39 * w4
        w44 = w44 - w39
        w16 = w16 * w22
        w44 = w44 + w16
        w8 = w8 + w44
        r1[2] = w8
        w38 = w38 / w2 if w2 else _div(w38, w2)
        w38 = w1 + w38
        w8 = 0.6
        w8 = w8 * w19
        w38 = w38 * w8
        w31 = w31 / w15 if w15 else _div(w31, w15)
        w46 = w46 / w2 if w2 else _div(w46, w2)
        w46 = w31 + w46
        w54 = w54 * w45
        w46 = w46 * w54
        w38 = w38 + w46
        w66 = w66 / w2 if w2 else _div(w66, w2)
        w42 = w42 / w15 if w15 else _div(w42, w15)
        w66 = w66 - w42
        w46 = 0.15
        w46 = w46 * w36
        w66 = w66 * w46
        w38 = w38 + w66
        w66 = -0.03
        w66 = w66 * w3
        w36 = w37 * w11
        w66 = w66 - w36
        w60 = w60 * w66
        w36 = w61 * w59
        w67 = w67 * w36
        w60 = w60 + w67
        w59 = w37 * w59
        w56 = w56 * w59
        w60 = w60 - w56
        w56 = w61 * w55
        w63 = w63 * w56
        w60 = w60 + w63
        w37 = w37 * w55
        w50 = w50 * w37
        w60 = w60 - w50
        w50 = 0.30000000000000004
        w50 = w50 * w3
        w61 = w61 * w11
        w50 = w50 - w61
        w62 = w62 * w50
        w60 = w60 - w62
        w38 = w38 + w60
        r1[3] = w38
        w26 = w26 / w2 if w2 else _div(w26, w2)
        w26 = w26 - w31
        w26 = w26 * w8
        w32 = w32 / w2 if w2 else _div(w32, w2)
        w32 = w1 + w32
        w32 = w32 * w54
        w26 = w26 + w32
        w10 = w10 / w15 if w15 else _div(w10, w15)
        w68 = w68 / w2 if w2 else _div(w68, w2)
        w68 = w10 + w68
        w68 = w68 * w46
        w26 = w26 + w68
        w50 = w33 * w50
        w36 = w57 * w36
        w56 = w53 * w56
        w36 = w36 + w56
        w50 = w50 - w36
        w26 = w26 + w50
        r1[4] = w26
        w17 = w17 / w2 if w2 else _div(w17, w2)
        w42 = w42 + w17
        w42 = w42 * w8
        w65 = w65 / w2 if w2 else _div(w65, w2)
        w65 = w65 - w10
        w65 = w65 * w54
        w42 = w42 + w65
        w34 = w34 / w2 if w2 else _div(w34, w2)
        w1 = w1 + w34
        w1 = w1 * w46
        w42 = w42 + w1
        w57 = w57 * w59
        w33 = w33 * w66
        w57 = w57 - w33
        w53 = w53 * w37
        w57 = w57 + w53
        w42 = w42 + w57
        r1[5] = w42
    return [r0, r1]


def update(z, g, p, h):
    """update(z[6], g[36], p[6], h[1]) -> [g1[36], p1[6]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (6,):
        z = z.tolist()
    else:
        z = _vec(z, 6, "update: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "update: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (6,):
        p = p.tolist()
    else:
        p = _vec(p, 6, "update: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "update: h")
    _r = _raw_update(z, g, p, h)
    return [_fromiter(_r[0], _F64, 36), _fromiter(_r[1], _F64, 6)]


def _raw_guess(xi, g, p, h):
    """guess on lists of Python floats -> [z0[6]] as lists (see RAW)"""
    w0, w1, w2, w3, w4, w5 = xi
    r0 = [0.0] * 6
    r0[0] = w0
    r0[1] = w1
    r0[2] = w2
    r0[3] = w3
    r0[4] = w4
    r0[5] = w5
    return [r0]


def guess(xi, g, p, h):
    """guess(xi[6], g[36], p[6], h[1]) -> [z0[6]]"""
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (6,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 6, "guess: xi")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "guess: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (6,):
        p = p.tolist()
    else:
        p = _vec(p, 6, "guess: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "guess: h")
    _r = _raw_guess(xi, g, p, h)
    return [_fromiter(_r[0], _F64, 6)]


def _raw_legendre(g, xi):
    """legendre on lists of Python floats -> [mu[6]] as lists (see RAW)"""
    w0, w1, w2, w3, w4, w5 = xi
    r0 = [0.0] * 6
    r0[0] = 0.9 * w0
    r0[1] = w1
    r0[2] = 0.2 * w2
    r0[3] = 0.6 * w3
    r0[4] = 0.5 * w4
    r0[5] = 0.15 * w5
    return [r0]


def legendre(g, xi):
    """legendre(g[36], xi[6]) -> [mu[6]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "legendre: g")
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (6,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 6, "legendre: xi")
    _r = _raw_legendre(g, xi)
    return [_fromiter(_r[0], _F64, 6)]


def _raw_hessian(g, xi):
    """hessian on lists of Python floats -> [H[36]] as lists (see RAW)"""
    r0 = [0.0] * 36
    r0[0] = 0.9
    r0[1] = 0.0
    r0[2] = 0.0
    r0[3] = 0.0
    r0[4] = 0.0
    r0[5] = 0.0
    r0[6] = 0.0
    r0[7] = 1.0
    r0[8] = 0.0
    r0[9] = 0.0
    r0[10] = 0.0
    r0[11] = 0.0
    r0[12] = 0.0
    r0[13] = 0.0
    r0[14] = 0.2
    r0[15] = 0.0
    r0[16] = 0.0
    r0[17] = 0.0
    r0[18] = 0.0
    r0[19] = 0.0
    r0[20] = 0.0
    r0[21] = 0.6
    r0[22] = 0.0
    r0[23] = 0.0
    r0[24] = 0.0
    r0[25] = 0.0
    r0[26] = 0.0
    r0[27] = 0.0
    r0[28] = 0.5
    r0[29] = 0.0
    r0[30] = 0.0
    r0[31] = 0.0
    r0[32] = 0.0
    r0[33] = 0.0
    r0[34] = 0.0
    r0[35] = 0.15
    return [r0]


def hessian(g, xi):
    """hessian(g[36], xi[6]) -> [H[36]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "hessian: g")
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (6,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 6, "hessian: xi")
    _r = _raw_hessian(g, xi)
    return [_fromiter(_r[0], _F64, 36)]


def _raw_energy(g, xi):
    """energy on lists of Python floats -> [E[1]] as lists (see RAW)"""
    w3, w8, w13, _, _, _, w2, w7, w12, _, _, _, w4, w9, w0, _, _, _, _, _, _, _, _, _, _, _, _, w5, w10, w14, _, _, _, w6, w11, w1 = g
    w15, w16, w17, w18, w19, w20 = xi
    r0 = [0.0] * 1
    w16 = w16 * w16
    w2 = ((((0.05 * w2) + (0.1 * w3)) - w4) + ((-0.1) * w5)) + ((-0.3) * w6)
    w3 = ((((0.05 * w7) + (0.1 * w8)) - w9) + ((-0.1) * w10)) + ((-0.3) * w11)
    w4 = ((((1.3 + (0.05 * w12)) + (0.1 * w13)) - w0) + ((-0.1) * w14)) + ((-0.3) * w1)
    r0[0] = (((((((0.9 * w15) * w15) + w16) + ((0.2 * w17) * w17)) + ((0.6 * w18) * w18)) + ((0.5 * w19) * w19)) + ((0.15 * w20) * w20)) - (((((((((((((0.25 * (w19 * w19)) + (0.5 * w16)) + w0) + (0.6000000000000001 * w1)) + (0.1 * (w17 * w17))) + (0.075 * (w20 * w20))) + (0.3 * (w18 * w18))) + (0.45 * (w15 * w15))) + ((-2.0) * (w2 * w2))) + ((-2.0) * (w3 * w3))) + ((-2.0) * (w4 * w4))) + ((-0.06) * w14)) + ((-0.1) * w13))
    return [r0]


def energy(g, xi):
    """energy(g[36], xi[6]) -> [E[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "energy: g")
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (6,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 6, "energy: xi")
    _r = _raw_energy(g, xi)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_momentum(g, p):
    """momentum on lists of Python floats -> [m[6]] as lists (see RAW)"""
    w8, w5, w4, _, _, _, w7, w1, w3, _, _, _, w6, w2, w0, _, _, _, _, _, _, w17, w14, w13, _, _, _, w16, w10, w12, _, _, _, w15, w11, w9 = g
    w18, w19, w20, w21, w22, w23 = p
    r0 = [0.0] * 6
    r0[0] = ((((w0 * w1) - (w2 * w3)) * w18) + (((w4 * w2) - (w5 * w0)) * w19)) + (((w3 * w5) - (w1 * w4)) * w20)
    r0[1] = ((((w6 * w3) - (w0 * w7)) * w18) + (((w8 * w0) - (w4 * w6)) * w19)) + (((w7 * w4) - (w3 * w8)) * w20)
    r0[2] = ((((w2 * w7) - (w6 * w1)) * w18) + (((w5 * w6) - (w8 * w2)) * w19)) + (((w1 * w8) - (w7 * w5)) * w20)
    r0[3] = ((((w9 * w10) - (w11 * w12)) * w21) + (((w13 * w11) - (w14 * w9)) * w22)) + (((w12 * w14) - (w10 * w13)) * w23)
    r0[4] = ((((w15 * w12) - (w9 * w16)) * w21) + (((w17 * w9) - (w13 * w15)) * w22)) + (((w16 * w13) - (w12 * w17)) * w23)
    r0[5] = ((((w11 * w16) - (w15 * w10)) * w21) + (((w14 * w15) - (w17 * w11)) * w22)) + (((w10 * w17) - (w16 * w14)) * w23)
    return [r0]


def momentum(g, p):
    """momentum(g[36], p[6]) -> [m[6]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "momentum: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (6,):
        p = p.tolist()
    else:
        p = _vec(p, 6, "momentum: p")
    _r = _raw_momentum(g, p)
    return [_fromiter(_r[0], _F64, 6)]


def _raw_defect(g):
    """defect on lists of Python floats -> [e[1]] as lists (see RAW)"""
    w18, w19, w20, w0, w1, w2, w21, w22, w23, w3, w4, w5, w24, w25, w26, w6, w7, w8, w9, w10, w11, w27, w28, w29, w12, w13, w14, w30, w31, w32, w15, w16, w17, w33, w34, w35 = g
    r0 = [0.0] * 1
    w36 = _f_fabs((((w21 * w18) + (w22 * w19)) + (w23 * w20)))
    w37 = _f_fabs((((w24 * w18) + (w25 * w19)) + (w26 * w20)))
    w38 = _f_fabs((((w24 * w21) + (w25 * w22)) + (w26 * w23)))
    w39 = _f_fabs((((w30 * w27) + (w31 * w28)) + (w32 * w29)))
    w40 = _f_fabs((((w33 * w27) + (w34 * w28)) + (w35 * w29)))
    w41 = _f_fabs((((w33 * w30) + (w34 * w31)) + (w35 * w32)))
    r0[0] = _fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax(0.0, (_f_fabs(w0)))), (_f_fabs(w1)))), (_f_fabs(w2)))), 0.0)), 0.0)), 0.0)), (_f_fabs(w3)))), (_f_fabs(w4)))), (_f_fabs(w5)))), 0.0)), 0.0)), 0.0)), (_f_fabs(w6)))), (_f_fabs(w7)))), (_f_fabs(w8)))), (_f_fabs(w9)))), (_f_fabs(w10)))), (_f_fabs(w11)))), 0.0)), 0.0)), 0.0)), (_f_fabs(w12)))), (_f_fabs(w13)))), (_f_fabs(w14)))), 0.0)), 0.0)), 0.0)), (_f_fabs(w15)))), (_f_fabs(w16)))), (_f_fabs(w17)))), 0.0)), 0.0)), 0.0)), (_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_f_fabs(((((w18 * w18) + (w19 * w19)) + (w20 * w20)) - 1.0))), w36)), w37)), w36)), (_f_fabs(((((w21 * w21) + (w22 * w22)) + (w23 * w23)) - 1.0))))), w38)), w37)), w38)), (_f_fabs(((((w24 * w24) + (w25 * w25)) + (w26 * w26)) - 1.0))))), (_f_fabs(((((w18 * ((w22 * w26) - (w25 * w23))) - (w21 * ((w19 * w26) - (w25 * w20)))) + (w24 * ((w19 * w23) - (w22 * w20)))) - 1.0))))))), (_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_f_fabs(((((w27 * w27) + (w28 * w28)) + (w29 * w29)) - 1.0))), w39)), w40)), w39)), (_f_fabs(((((w30 * w30) + (w31 * w31)) + (w32 * w32)) - 1.0))))), w41)), w40)), w41)), (_f_fabs(((((w33 * w33) + (w34 * w34)) + (w35 * w35)) - 1.0))))), (_f_fabs(((((w27 * ((w31 * w35) - (w34 * w32))) - (w30 * ((w28 * w35) - (w34 * w29)))) + (w33 * ((w28 * w32) - (w31 * w29)))) - 1.0))))))
    return [r0]


def defect(g):
    """defect(g[36]) -> [e[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "defect: g")
    _r = _raw_defect(g)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_margin(z, h):
    """margin on lists of Python floats -> [m[1]] as lists (see RAW)"""
    w0, w1, w2, w3, w4, w5 = z
    w6, = h
    r0 = [0.0] * 1
    w0 = w6 * w0
    w1 = w6 * w1
    w2 = w6 * w2
    w3 = w6 * w3
    w4 = w6 * w4
    w5 = w6 * w5
    w0 = _fmin((_fmin(1.0, (4.0 - (((w0 * w0) + (w1 * w1)) + (w2 * w2))))), (4.0 - (((w3 * w3) + (w4 * w4)) + (w5 * w5))))
    r0[0] = _fmin((_fmin((_fmin((_fmin(1.0, w0)), w0)), w0)), w0)
    return [r0]


def margin(z, h):
    """margin(z[6], h[1]) -> [m[1]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (6,):
        z = z.tolist()
    else:
        z = _vec(z, 6, "margin: z")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "margin: h")
    _r = _raw_margin(z, h)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_section(g, p):
    """section on lists of Python floats -> [s[1]] as lists (see RAW)"""
    r0 = [0.0] * 1
    r0[0] = 1.0
    return [r0]


def section(g, p):
    """section(g[36], p[6]) -> [s[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "section: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (6,):
        p = p.tolist()
    else:
        p = _vec(p, 6, "section: p")
    _r = _raw_section(g, p)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_chart_point(z, g, h, theta):
    """chart_point on lists of Python floats -> [g_theta[36]] as lists (see RAW)"""
    try:
        w0, w1, w2, w3, w4, w5 = z
        w6, w9, w12, w15, w18, w21, w7, w10, w13, w16, w19, w22, w8, w11, w14, w17, w20, w23, w24, w27, w30, w33, w36, w39, w25, w28, w31, w34, w37, w40, w26, w29, w32, w35, w38, w41 = g
        w42, = h
        w43, = theta
        r0 = [0.0] * 36
        w0 = w43 * (w42 * w0)
        w44 = w0 * w0
        w1 = w43 * (w42 * w1)
        w45 = w1 * w1
        w46 = w44 + w45
        w2 = w43 * (w42 * w2)
        w47 = w2 * w2
        w48 = 4.0 / (4.0 + (w46 + w47))
        w45 = 1.0 - (w48 * ((w47 + w45) * 0.5))
        w49 = (w0 * w1) * 0.5
        w50 = w48 * (w2 + w49)
        w51 = (w0 * w2) * 0.5
        w52 = w48 * (w51 - w1)
        r0[0] = ((w6 * w45) + (w7 * w50)) + (w8 * w52)
        r0[1] = ((w9 * w45) + (w10 * w50)) + (w11 * w52)
        r0[2] = ((w12 * w45) + (w13 * w50)) + (w14 * w52)
        r0[3] = ((w15 * w45) + (w16 * w50)) + (w17 * w52)
        r0[4] = ((w18 * w45) + (w19 * w50)) + (w20 * w52)
        r0[5] = ((w21 * w45) + (w22 * w50)) + (w23 * w52)
        w45 = w48 * (w49 - w2)
        w44 = 1.0 - (w48 * ((w47 + w44) * 0.5))
        w2 = (w1 * w2) * 0.5
        w47 = w48 * (w0 + w2)
        r0[6] = ((w6 * w45) + (w7 * w44)) + (w8 * w47)
        r0[7] = ((w9 * w45) + (w10 * w44)) + (w11 * w47)
        r0[8] = ((w12 * w45) + (w13 * w44)) + (w14 * w47)
        r0[9] = ((w15 * w45) + (w16 * w44)) + (w17 * w47)
        r0[10] = ((w18 * w45) + (w19 * w44)) + (w20 * w47)
        r0[11] = ((w21 * w45) + (w22 * w44)) + (w23 * w47)
        w1 = w48 * (w1 + w51)
        w0 = w48 * (w2 - w0)
        w2 = 1.0 - (w48 * (w46 * 0.5))
        r0[12] = ((w6 * w1) + (w7 * w0)) + (w8 * w2)
        r0[13] = ((w9 * w1) + (w10 * w0)) + (w11 * w2)
        r0[14] = ((w12 * w1) + (w13 * w0)) + (w14 * w2)
        r0[15] = ((w15 * w1) + (w16 * w0)) + (w17 * w2)
        r0[16] = ((w18 * w1) + (w19 * w0)) + (w20 * w2)
        r0[17] = ((w21 * w1) + (w22 * w0)) + (w23 * w2)
        w0 = w43 * (w42 * w3)
        w1 = w0 * w0
        w2 = w43 * (w42 * w4)
        w3 = w2 * w2
        w4 = w1 + w3
        w5 = w43 * (w42 * w5)
        w6 = w5 * w5
        w7 = 4.0 / (4.0 + (w4 + w6))
        w3 = 1.0 - (w7 * ((w6 + w3) * 0.5))
        w8 = (w0 * w2) * 0.5
        w9 = w7 * (w5 + w8)
        w10 = (w0 * w5) * 0.5
        w11 = w7 * (w10 - w2)
        r0[18] = ((w24 * w3) + (w25 * w9)) + (w26 * w11)
        r0[19] = ((w27 * w3) + (w28 * w9)) + (w29 * w11)
        r0[20] = ((w30 * w3) + (w31 * w9)) + (w32 * w11)
        r0[21] = ((w33 * w3) + (w34 * w9)) + (w35 * w11)
        r0[22] = ((w36 * w3) + (w37 * w9)) + (w38 * w11)
        r0[23] = ((w39 * w3) + (w40 * w9)) + (w41 * w11)
        w3 = w7 * (w8 - w5)
        w1 = 1.0 - (w7 * ((w6 + w1) * 0.5))
        w5 = (w2 * w5) * 0.5
        w6 = w7 * (w0 + w5)
        r0[24] = ((w24 * w3) + (w25 * w1)) + (w26 * w6)
        r0[25] = ((w27 * w3) + (w28 * w1)) + (w29 * w6)
        r0[26] = ((w30 * w3) + (w31 * w1)) + (w32 * w6)
        r0[27] = ((w33 * w3) + (w34 * w1)) + (w35 * w6)
        r0[28] = ((w36 * w3) + (w37 * w1)) + (w38 * w6)
        r0[29] = ((w39 * w3) + (w40 * w1)) + (w41 * w6)
        w1 = w7 * (w2 + w10)
        w0 = w7 * (w5 - w0)
        w2 = 1.0 - (w7 * (w4 * 0.5))
        r0[30] = ((w24 * w1) + (w25 * w0)) + (w26 * w2)
        r0[31] = ((w27 * w1) + (w28 * w0)) + (w29 * w2)
        r0[32] = ((w30 * w1) + (w31 * w0)) + (w32 * w2)
        r0[33] = ((w33 * w1) + (w34 * w0)) + (w35 * w2)
        r0[34] = ((w36 * w1) + (w37 * w0)) + (w38 * w2)
        r0[35] = ((w39 * w1) + (w40 * w0)) + (w41 * w2)
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 36
        w0 = g[0]
        w1 = 1.0
        w2 = 4.0
        w3 = theta[0]
        w4 = h[0]
        w5 = z[0]
        w5 = w4 * w5
        w5 = w3 * w5
        w6 = w5 * w5
        w7 = z[1]
        w7 = w4 * w7
        w7 = w3 * w7
        w8 = w7 * w7
        w9 = w6 + w8
        w10 = z[2]
        w10 = w4 * w10
        w10 = w3 * w10
        w11 = w10 * w10
        w9 = w9 + w11
        w9 = w2 + w9
        w9 = w2 / w9 if w9 else _div(w2, w9)
        w12 = w11 + w8
        w13 = 2.0
        w12 = w12 / w13 if w13 else _div(w12, w13)
        w12 = w9 * w12
        w12 = w1 - w12
        w14 = w0 * w12
        w15 = g[6]
        w16 = w5 * w7
        w16 = w16 / w13 if w13 else _div(w16, w13)
        w16 = w10 + w16
        w16 = w9 * w16
        w17 = w15 * w16
        w14 = w14 + w17
        w17 = g[12]
        w18 = w5 * w10
        w18 = w18 / w13 if w13 else _div(w18, w13)
        w18 = w18 - w7
        w18 = w9 * w18
        w19 = w17 * w18
        w14 = w14 + w19
        r0[0] = w14
        w14 = g[1]
        w19 = w14 * w12
        w20 = g[7]
        w21 = w20 * w16
        w19 = w19 + w21
        w21 = g[13]
        w22 = w21 * w18
        w19 = w19 + w22
        r0[1] = w19
        w19 = g[2]
        w22 = w19 * w12
        w23 = g[8]
        w24 = w23 * w16
        w22 = w22 + w24
        w24 = g[14]
        w25 = w24 * w18
        w22 = w22 + w25
        r0[2] = w22
        w22 = g[3]
        w25 = w22 * w12
        w26 = g[9]
        w27 = w26 * w16
        w25 = w25 + w27
        w27 = g[15]
        w28 = w27 * w18
        w25 = w25 + w28
        r0[3] = w25
        w25 = g[4]
        w28 = w25 * w12
        w29 = g[10]
        w30 = w29 * w16
        w28 = w28 + w30
        w30 = g[16]
        w31 = w30 * w18
        w28 = w28 + w31
        r0[4] = w28
        w28 = g[5]
        w12 = w28 * w12
        w31 = g[11]
        w16 = w31 * w16
        w12 = w12 + w16
        w16 = g[17]
        w18 = w16 * w18
        w12 = w12 + w18
        r0[5] = w12
        w12 = w7 * w5
        w12 = w12 / w13 if w13 else _div(w12, w13)
        w12 = w12 - w10
        w12 = w9 * w12
        w18 = w0 * w12
        w11 = w11 + w6
        w11 = w11 / w13 if w13 else _div(w11, w13)
        w11 = w9 * w11
        w11 = w1 - w11
        w32 = w15 * w11
        w18 = w18 + w32
        w32 = w7 * w10
        w32 = w32 / w13 if w13 else _div(w32, w13)
        w32 = w5 + w32
        w32 = w9 * w32
        w33 = w17 * w32
        w18 = w18 + w33
        r0[6] = w18
        w18 = w14 * w12
        w33 = w20 * w11
        w18 = w18 + w33
        w33 = w21 * w32
        w18 = w18 + w33
        r0[7] = w18
        w18 = w19 * w12
        w33 = w23 * w11
        w18 = w18 + w33
        w33 = w24 * w32
        w18 = w18 + w33
        r0[8] = w18
        w18 = w22 * w12
        w33 = w26 * w11
        w18 = w18 + w33
        w33 = w27 * w32
        w18 = w18 + w33
        r0[9] = w18
        w18 = w25 * w12
        w33 = w29 * w11
        w18 = w18 + w33
        w33 = w30 * w32
        w18 = w18 + w33
        r0[10] = w18
        w12 = w28 * w12
        w11 = w31 * w11
        w12 = w12 + w11
        w32 = w16 * w32
        w12 = w12 + w32
        r0[11] = w12
        w12 = w10 * w5
        w12 = w12 / w13 if w13 else _div(w12, w13)
        w12 = w7 + w12
        w12 = w9 * w12
        w0 = w0 * w12
        w10 = w10 * w7
        w10 = w10 / w13 if w13 else _div(w10, w13)
        w10 = w10 - w5
        w10 = w9 * w10
        w15 = w15 * w10
        w0 = w0 + w15
        w8 = w8 + w6
        w8 = w8 / w13 if w13 else _div(w8, w13)
        w9 = w9 * w8
        w9 = w1 - w9
        w17 = w17 * w9
        w0 = w0 + w17
        r0[12] = w0
        w14 = w14 * w12
        w20 = w20 * w10
        w14 = w14 + w20
        w21 = w21 * w9
        w14 = w14 + w21
        r0[13] = w14
        w19 = w19 * w12
        w23 = w23 * w10
        w19 = w19 + w23
        w24 = w24 * w9
        w19 = w19 + w24
        r0[14] = w19
        w22 = w22 * w12
        w26 = w26 * w10
        w22 = w22 + w26
        w27 = w27 * w9
        w22 = w22 + w27
        r0[15] = w22
        w25 = w25 * w12
        w29 = w29 * w10
        w25 = w25 + w29
        w30 = w30 * w9
        w25 = w25 + w30
        r0[16] = w25
        w28 = w28 * w12
        w31 = w31 * w10
        w28 = w28 + w31
        w16 = w16 * w9
        w28 = w28 + w16
        r0[17] = w28
        w28 = g[18]
        w16 = z[3]
        w16 = w4 * w16
        w16 = w3 * w16
        w9 = w16 * w16
        w31 = z[4]
        w31 = w4 * w31
        w31 = w3 * w31
        w10 = w31 * w31
        w12 = w9 + w10
        w25 = z[5]
        w4 = w4 * w25
        w3 = w3 * w4
        w4 = w3 * w3
        w12 = w12 + w4
        w12 = w2 + w12
        w2 = w2 / w12 if w12 else _div(w2, w12)
        w12 = w4 + w10
        w12 = w12 / w13 if w13 else _div(w12, w13)
        w12 = w2 * w12
        w12 = w1 - w12
        w25 = w28 * w12
        w30 = g[24]
        w29 = w16 * w31
        w29 = w29 / w13 if w13 else _div(w29, w13)
        w29 = w3 + w29
        w29 = w2 * w29
        w22 = w30 * w29
        w25 = w25 + w22
        w22 = g[30]
        w27 = w16 * w3
        w27 = w27 / w13 if w13 else _div(w27, w13)
        w27 = w27 - w31
        w27 = w2 * w27
        w26 = w22 * w27
        w25 = w25 + w26
        r0[18] = w25
        w25 = g[19]
        w26 = w25 * w12
        w19 = g[25]
        w24 = w19 * w29
        w26 = w26 + w24
        w24 = g[31]
        w23 = w24 * w27
        w26 = w26 + w23
        r0[19] = w26
        w26 = g[20]
        w23 = w26 * w12
        w14 = g[26]
        w21 = w14 * w29
        w23 = w23 + w21
        w21 = g[32]
        w20 = w21 * w27
        w23 = w23 + w20
        r0[20] = w23
        w23 = g[21]
        w20 = w23 * w12
        w0 = g[27]
        w17 = w0 * w29
        w20 = w20 + w17
        w17 = g[33]
        w8 = w17 * w27
        w20 = w20 + w8
        r0[21] = w20
        w20 = g[22]
        w8 = w20 * w12
        w6 = g[28]
        w15 = w6 * w29
        w8 = w8 + w15
        w15 = g[34]
        w5 = w15 * w27
        w8 = w8 + w5
        r0[22] = w8
        w8 = g[23]
        w12 = w8 * w12
        w5 = g[29]
        w29 = w5 * w29
        w12 = w12 + w29
        w29 = g[35]
        w27 = w29 * w27
        w12 = w12 + w27
        r0[23] = w12
        w12 = w31 * w16
        w12 = w12 / w13 if w13 else _div(w12, w13)
        w12 = w12 - w3
        w12 = w2 * w12
        w27 = w28 * w12
        w4 = w4 + w9
        w4 = w4 / w13 if w13 else _div(w4, w13)
        w4 = w2 * w4
        w4 = w1 - w4
        w7 = w30 * w4
        w27 = w27 + w7
        w7 = w31 * w3
        w7 = w7 / w13 if w13 else _div(w7, w13)
        w7 = w16 + w7
        w7 = w2 * w7
        w32 = w22 * w7
        w27 = w27 + w32
        r0[24] = w27
        w27 = w25 * w12
        w32 = w19 * w4
        w27 = w27 + w32
        w32 = w24 * w7
        w27 = w27 + w32
        r0[25] = w27
        w27 = w26 * w12
        w32 = w14 * w4
        w27 = w27 + w32
        w32 = w21 * w7
        w27 = w27 + w32
        r0[26] = w27
        w27 = w23 * w12
        w32 = w0 * w4
        w27 = w27 + w32
        w32 = w17 * w7
        w27 = w27 + w32
        r0[27] = w27
        w27 = w20 * w12
        w32 = w6 * w4
        w27 = w27 + w32
        w32 = w15 * w7
        w27 = w27 + w32
        r0[28] = w27
        w12 = w8 * w12
        w4 = w5 * w4
        w12 = w12 + w4
        w7 = w29 * w7
        w12 = w12 + w7
        r0[29] = w12
        w12 = w3 * w16
        w12 = w12 / w13 if w13 else _div(w12, w13)
        w12 = w31 + w12
        w12 = w2 * w12
        w28 = w28 * w12
        w3 = w3 * w31
        w3 = w3 / w13 if w13 else _div(w3, w13)
        w3 = w3 - w16
        w3 = w2 * w3
        w30 = w30 * w3
        w28 = w28 + w30
        w10 = w10 + w9
        w10 = w10 / w13 if w13 else _div(w10, w13)
        w2 = w2 * w10
        w1 = w1 - w2
        w22 = w22 * w1
        w28 = w28 + w22
        r0[30] = w28
        w25 = w25 * w12
        w19 = w19 * w3
        w25 = w25 + w19
        w24 = w24 * w1
        w25 = w25 + w24
        r0[31] = w25
        w26 = w26 * w12
        w14 = w14 * w3
        w26 = w26 + w14
        w21 = w21 * w1
        w26 = w26 + w21
        r0[32] = w26
        w23 = w23 * w12
        w0 = w0 * w3
        w23 = w23 + w0
        w17 = w17 * w1
        w23 = w23 + w17
        r0[33] = w23
        w20 = w20 * w12
        w6 = w6 * w3
        w20 = w20 + w6
        w15 = w15 * w1
        w20 = w20 + w15
        r0[34] = w20
        w8 = w8 * w12
        w5 = w5 * w3
        w8 = w8 + w5
        w29 = w29 * w1
        w8 = w8 + w29
        r0[35] = w8
    return [r0]


def chart_point(z, g, h, theta):
    """chart_point(z[6], g[36], h[1], theta[1]) -> [g_theta[36]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (6,):
        z = z.tolist()
    else:
        z = _vec(z, 6, "chart_point: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "chart_point: g")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "chart_point: h")
    if _type(theta) is _NDARRAY and theta.dtype is _F64 and theta.shape == (1,):
        theta = theta.tolist()
    else:
        theta = _vec(theta, 1, "chart_point: theta")
    _r = _raw_chart_point(z, g, h, theta)
    return [_fromiter(_r[0], _F64, 36)]


def _raw_observe(g, p):
    """observe on lists of Python floats -> [xi[6], E[1], m[6], e[1]] as lists (see RAW)"""
    try:
        w3, w8, w13, w18, w19, w20, w2, w7, w12, w21, w22, w23, w4, w9, w0, w24, w25, w26, w27, w28, w29, w17, w16, w15, w30, w31, w32, w5, w10, w14, w33, w34, w35, w6, w11, w1 = g
        w36, w37, w38, w39, w40, w41 = p
        r0 = [0.0] * 6
        r1 = [0.0] * 1
        r2 = [0.0] * 6
        r3 = [0.0] * 1
        w42 = w36 / 0.9
        r0[0] = w42
        r0[1] = w37
        w43 = w38 / 0.2
        r0[2] = w43
        w44 = w39 / 0.6
        r0[3] = w44
        w45 = 2.0 * (-w40)
        r0[4] = -w45
        w46 = w41 / 0.15
        r0[5] = w46
        w47 = w37 * w37
        w48 = ((((0.05 * w2) + (0.1 * w3)) - w4) + ((-0.1) * w5)) + ((-0.3) * w6)
        w49 = ((((0.05 * w7) + (0.1 * w8)) - w9) + ((-0.1) * w10)) + ((-0.3) * w11)
        w50 = ((((1.3 + (0.05 * w12)) + (0.1 * w13)) - w0) + ((-0.1) * w14)) + ((-0.3) * w1)
        r1[0] = ((((((w36 * w42) + w47) + (w38 * w43)) + (w39 * w44)) - (w40 * w45)) + (w41 * w46)) - (((((((((((((0.25 * (w45 * w45)) + (0.5 * w47)) + w0) + (0.6000000000000001 * w1)) + (0.1 * (w43 * w43))) + (0.075 * (w46 * w46))) + (0.3 * (w44 * w44))) + (0.45 * (w42 * w42))) + ((-2.0) * (w48 * w48))) + ((-2.0) * (w49 * w49))) + ((-2.0) * (w50 * w50))) + ((-0.06) * w14)) + ((-0.1) * w13))
        w42 = (w0 * w7) - (w9 * w12)
        w43 = w13 * w9
        w44 = w8 * w0
        w45 = (w12 * w8) - (w7 * w13)
        r2[0] = ((w42 * w36) + ((w43 - w44) * w37)) + (w45 * w38)
        r2[1] = ((((w4 * w12) - (w0 * w2)) * w36) + (((w3 * w0) - (w13 * w4)) * w37)) + (((w2 * w13) - (w12 * w3)) * w38)
        r2[2] = ((((w9 * w2) - (w4 * w7)) * w36) + (((w8 * w4) - (w3 * w9)) * w37)) + (((w7 * w3) - (w2 * w8)) * w38)
        w36 = (w1 * w10) - (w11 * w14)
        w37 = w15 * w11
        w38 = w16 * w1
        w46 = (w14 * w16) - (w10 * w15)
        r2[3] = ((w36 * w39) + ((w37 - w38) * w40)) + (w46 * w41)
        r2[4] = ((((w6 * w14) - (w1 * w5)) * w39) + (((w17 * w1) - (w15 * w6)) * w40)) + (((w5 * w15) - (w14 * w17)) * w41)
        r2[5] = ((((w11 * w5) - (w6 * w10)) * w39) + (((w16 * w6) - (w17 * w11)) * w40)) + (((w10 * w17) - (w5 * w16)) * w41)
        w39 = _f_fabs((((w2 * w3) + (w7 * w8)) + (w12 * w13)))
        w40 = _f_fabs((((w4 * w3) + (w9 * w8)) + (w0 * w13)))
        w41 = _f_fabs((((w4 * w2) + (w9 * w7)) + (w0 * w12)))
        w47 = _f_fabs((((w5 * w17) + (w10 * w16)) + (w14 * w15)))
        w48 = _f_fabs((((w6 * w17) + (w11 * w16)) + (w1 * w15)))
        w49 = _f_fabs((((w6 * w5) + (w11 * w10)) + (w1 * w14)))
        r3[0] = _fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax(0.0, (_f_fabs(w18)))), (_f_fabs(w19)))), (_f_fabs(w20)))), 0.0)), 0.0)), 0.0)), (_f_fabs(w21)))), (_f_fabs(w22)))), (_f_fabs(w23)))), 0.0)), 0.0)), 0.0)), (_f_fabs(w24)))), (_f_fabs(w25)))), (_f_fabs(w26)))), (_f_fabs(w27)))), (_f_fabs(w28)))), (_f_fabs(w29)))), 0.0)), 0.0)), 0.0)), (_f_fabs(w30)))), (_f_fabs(w31)))), (_f_fabs(w32)))), 0.0)), 0.0)), 0.0)), (_f_fabs(w33)))), (_f_fabs(w34)))), (_f_fabs(w35)))), 0.0)), 0.0)), 0.0)), (_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_f_fabs(((((w3 * w3) + (w8 * w8)) + (w13 * w13)) - 1.0))), w39)), w40)), w39)), (_f_fabs(((((w2 * w2) + (w7 * w7)) + (w12 * w12)) - 1.0))))), w41)), w40)), w41)), (_f_fabs(((((w4 * w4) + (w9 * w9)) + (w0 * w0)) - 1.0))))), (_f_fabs(((((w3 * w42) - (w2 * (w44 - w43))) + (w4 * w45)) - 1.0))))))), (_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_f_fabs(((((w17 * w17) + (w16 * w16)) + (w15 * w15)) - 1.0))), w47)), w48)), w47)), (_f_fabs(((((w5 * w5) + (w10 * w10)) + (w14 * w14)) - 1.0))))), w49)), w48)), w49)), (_f_fabs(((((w6 * w6) + (w11 * w11)) + (w1 * w1)) - 1.0))))), (_f_fabs(((((w17 * w36) - (w5 * (w38 - w37))) + (w6 * w46)) - 1.0))))))
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 6
        r1 = [0.0] * 1
        r2 = [0.0] * 6
        r3 = [0.0] * 1
        w0 = p[0]
        w1 = 0.9
        w1 = w0 / w1 if w1 else _div(w0, w1)
        r0[0] = w1
        w2 = p[1]
        r0[1] = w2
        w3 = p[2]
        w4 = 0.2
        w4 = w3 / w4 if w4 else _div(w3, w4)
        r0[2] = w4
        w5 = p[3]
        w6 = 0.6
        w6 = w5 / w6 if w6 else _div(w5, w6)
        r0[3] = w6
        w7 = p[4]
        w8 = -w7
        w8 = 2.0 * w8
        w9 = -w8
        r0[4] = w9
        w9 = p[5]
        w10 = 0.15
        w10 = w9 / w10 if w10 else _div(w9, w10)
        r0[5] = w10
        w11 = w0 * w1
        w12 = w2 * w2
        w11 = w11 + w12
        w13 = w3 * w4
        w11 = w11 + w13
        w13 = w5 * w6
        w11 = w11 + w13
        w13 = w7 * w8
        w11 = w11 - w13
        w13 = w9 * w10
        w11 = w11 + w13
        w13 = 0.25
        w8 = w8 * w8
        w13 = w13 * w8
        w8 = 0.5
        w8 = w8 * w12
        w13 = w13 + w8
        w8 = g[14]
        w13 = w13 + w8
        w12 = 0.6000000000000001
        w14 = g[35]
        w12 = w12 * w14
        w13 = w13 + w12
        w12 = 0.1
        w4 = w4 * w4
        w4 = w12 * w4
        w13 = w13 + w4
        w4 = 0.075
        w10 = w10 * w10
        w4 = w4 * w10
        w13 = w13 + w4
        w4 = 0.3
        w6 = w6 * w6
        w4 = w4 * w6
        w13 = w13 + w4
        w4 = 0.45
        w1 = w1 * w1
        w4 = w4 * w1
        w13 = w13 + w4
        w4 = -2.0
        w1 = 0.05
        w6 = g[6]
        w10 = w1 * w6
        w15 = g[0]
        w16 = w12 * w15
        w10 = w10 + w16
        w16 = g[12]
        w10 = w10 - w16
        w17 = -0.1
        w18 = g[27]
        w19 = w17 * w18
        w10 = w10 + w19
        w19 = -0.3
        w20 = g[33]
        w21 = w19 * w20
        w10 = w10 + w21
        w10 = w10 * w10
        w10 = w4 * w10
        w13 = w13 + w10
        w10 = g[7]
        w21 = w1 * w10
        w22 = g[1]
        w23 = w12 * w22
        w21 = w21 + w23
        w23 = g[13]
        w21 = w21 - w23
        w24 = g[28]
        w25 = w17 * w24
        w21 = w21 + w25
        w25 = g[34]
        w26 = w19 * w25
        w21 = w21 + w26
        w21 = w21 * w21
        w21 = w4 * w21
        w13 = w13 + w21
        w21 = 1.3
        w26 = g[8]
        w1 = w1 * w26
        w21 = w21 + w1
        w1 = g[2]
        w12 = w12 * w1
        w21 = w21 + w12
        w21 = w21 - w8
        w12 = g[29]
        w27 = w17 * w12
        w21 = w21 + w27
        w19 = w19 * w14
        w21 = w21 + w19
        w21 = w21 * w21
        w4 = w4 * w21
        w13 = w13 + w4
        w4 = -0.06
        w4 = w4 * w12
        w13 = w13 + w4
        w17 = w17 * w1
        w13 = w13 + w17
        w11 = w11 - w13
        r1[0] = w11
        w11 = w8 * w10
        w13 = w23 * w26
        w11 = w11 - w13
        w11 = w11 * w0
        w17 = w1 * w23
        w4 = w22 * w8
        w17 = w17 - w4
        w17 = w17 * w2
        w11 = w11 + w17
        w17 = w26 * w22
        w21 = w10 * w1
        w17 = w17 - w21
        w17 = w17 * w3
        w11 = w11 + w17
        r2[0] = w11
        w11 = w16 * w26
        w17 = w8 * w6
        w11 = w11 - w17
        w11 = w11 * w0
        w17 = w15 * w8
        w19 = w1 * w16
        w17 = w17 - w19
        w17 = w17 * w2
        w11 = w11 + w17
        w17 = w6 * w1
        w19 = w26 * w15
        w17 = w17 - w19
        w17 = w17 * w3
        w11 = w11 + w17
        r2[1] = w11
        w11 = w23 * w6
        w17 = w16 * w10
        w11 = w11 - w17
        w11 = w11 * w0
        w0 = w22 * w16
        w17 = w15 * w23
        w0 = w0 - w17
        w0 = w0 * w2
        w11 = w11 + w0
        w0 = w10 * w15
        w2 = w6 * w22
        w0 = w0 - w2
        w0 = w0 * w3
        w11 = w11 + w0
        r2[2] = w11
        w11 = w14 * w24
        w0 = w25 * w12
        w11 = w11 - w0
        w11 = w11 * w5
        w3 = g[23]
        w2 = w3 * w25
        w17 = g[22]
        w19 = w17 * w14
        w2 = w2 - w19
        w2 = w2 * w7
        w11 = w11 + w2
        w2 = w12 * w17
        w27 = w24 * w3
        w2 = w2 - w27
        w2 = w2 * w9
        w11 = w11 + w2
        r2[3] = w11
        w11 = w20 * w12
        w2 = w14 * w18
        w11 = w11 - w2
        w11 = w11 * w5
        w2 = g[21]
        w28 = w2 * w14
        w29 = w3 * w20
        w28 = w28 - w29
        w28 = w28 * w7
        w11 = w11 + w28
        w28 = w18 * w3
        w29 = w12 * w2
        w28 = w28 - w29
        w28 = w28 * w9
        w11 = w11 + w28
        r2[4] = w11
        w11 = w25 * w18
        w28 = w20 * w24
        w11 = w11 - w28
        w11 = w11 * w5
        w5 = w17 * w20
        w28 = w2 * w25
        w5 = w5 - w28
        w5 = w5 * w7
        w11 = w11 + w5
        w5 = w24 * w2
        w7 = w18 * w17
        w5 = w5 - w7
        w5 = w5 * w9
        w11 = w11 + w5
        r2[5] = w11
        w11 = 0.0
        w5 = g[3]
        w5 = math.fabs(w5)
        w5 = _fmax(w11, w5)
        w9 = g[4]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w9 = g[5]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w5 = _fmax(w5, w11)
        w5 = _fmax(w5, w11)
        w5 = _fmax(w5, w11)
        w9 = g[9]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w9 = g[10]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w9 = g[11]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w5 = _fmax(w5, w11)
        w5 = _fmax(w5, w11)
        w5 = _fmax(w5, w11)
        w9 = g[15]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w9 = g[16]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w9 = g[17]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w9 = g[18]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w9 = g[19]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w9 = g[20]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w5 = _fmax(w5, w11)
        w5 = _fmax(w5, w11)
        w5 = _fmax(w5, w11)
        w9 = g[24]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w9 = g[25]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w9 = g[26]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w5 = _fmax(w5, w11)
        w5 = _fmax(w5, w11)
        w5 = _fmax(w5, w11)
        w9 = g[30]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w9 = g[31]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w9 = g[32]
        w9 = math.fabs(w9)
        w5 = _fmax(w5, w9)
        w5 = _fmax(w5, w11)
        w5 = _fmax(w5, w11)
        w5 = _fmax(w5, w11)
        w11 = w15 * w15
        w9 = w22 * w22
        w11 = w11 + w9
        w9 = w1 * w1
        w11 = w11 + w9
        w9 = 1.0
        w11 = w11 - w9
        w11 = math.fabs(w11)
        w7 = w6 * w15
        w28 = w10 * w22
        w7 = w7 + w28
        w28 = w26 * w1
        w7 = w7 + w28
        w7 = math.fabs(w7)
        w11 = _fmax(w11, w7)
        w7 = w16 * w15
        w28 = w23 * w22
        w7 = w7 + w28
        w28 = w8 * w1
        w7 = w7 + w28
        w7 = math.fabs(w7)
        w11 = _fmax(w11, w7)
        w7 = w15 * w6
        w28 = w22 * w10
        w7 = w7 + w28
        w28 = w1 * w26
        w7 = w7 + w28
        w7 = math.fabs(w7)
        w11 = _fmax(w11, w7)
        w7 = w6 * w6
        w28 = w10 * w10
        w7 = w7 + w28
        w28 = w26 * w26
        w7 = w7 + w28
        w7 = w7 - w9
        w7 = math.fabs(w7)
        w11 = _fmax(w11, w7)
        w7 = w16 * w6
        w28 = w23 * w10
        w7 = w7 + w28
        w28 = w8 * w26
        w7 = w7 + w28
        w7 = math.fabs(w7)
        w11 = _fmax(w11, w7)
        w7 = w15 * w16
        w28 = w22 * w23
        w7 = w7 + w28
        w28 = w1 * w8
        w7 = w7 + w28
        w7 = math.fabs(w7)
        w11 = _fmax(w11, w7)
        w7 = w6 * w16
        w28 = w10 * w23
        w7 = w7 + w28
        w28 = w26 * w8
        w7 = w7 + w28
        w7 = math.fabs(w7)
        w11 = _fmax(w11, w7)
        w7 = w16 * w16
        w28 = w23 * w23
        w7 = w7 + w28
        w28 = w8 * w8
        w7 = w7 + w28
        w7 = w7 - w9
        w7 = math.fabs(w7)
        w11 = _fmax(w11, w7)
        w10 = w10 * w8
        w10 = w10 - w13
        w15 = w15 * w10
        w23 = w23 * w1
        w4 = w4 - w23
        w6 = w6 * w4
        w15 = w15 - w6
        w22 = w22 * w26
        w22 = w22 - w21
        w16 = w16 * w22
        w15 = w15 + w16
        w15 = w15 - w9
        w15 = math.fabs(w15)
        w11 = _fmax(w11, w15)
        w5 = _fmax(w5, w11)
        w11 = w2 * w2
        w15 = w17 * w17
        w11 = w11 + w15
        w15 = w3 * w3
        w11 = w11 + w15
        w11 = w11 - w9
        w11 = math.fabs(w11)
        w15 = w18 * w2
        w16 = w24 * w17
        w15 = w15 + w16
        w16 = w12 * w3
        w15 = w15 + w16
        w15 = math.fabs(w15)
        w11 = _fmax(w11, w15)
        w15 = w20 * w2
        w16 = w25 * w17
        w15 = w15 + w16
        w16 = w14 * w3
        w15 = w15 + w16
        w15 = math.fabs(w15)
        w11 = _fmax(w11, w15)
        w15 = w2 * w18
        w16 = w17 * w24
        w15 = w15 + w16
        w16 = w3 * w12
        w15 = w15 + w16
        w15 = math.fabs(w15)
        w11 = _fmax(w11, w15)
        w15 = w18 * w18
        w16 = w24 * w24
        w15 = w15 + w16
        w16 = w12 * w12
        w15 = w15 + w16
        w15 = w15 - w9
        w15 = math.fabs(w15)
        w11 = _fmax(w11, w15)
        w15 = w20 * w18
        w16 = w25 * w24
        w15 = w15 + w16
        w16 = w14 * w12
        w15 = w15 + w16
        w15 = math.fabs(w15)
        w11 = _fmax(w11, w15)
        w15 = w2 * w20
        w16 = w17 * w25
        w15 = w15 + w16
        w16 = w3 * w14
        w15 = w15 + w16
        w15 = math.fabs(w15)
        w11 = _fmax(w11, w15)
        w15 = w18 * w20
        w16 = w24 * w25
        w15 = w15 + w16
        w16 = w12 * w14
        w15 = w15 + w16
        w15 = math.fabs(w15)
        w11 = _fmax(w11, w15)
        w15 = w20 * w20
        w16 = w25 * w25
        w15 = w15 + w16
        w16 = w14 * w14
        w15 = w15 + w16
        w15 = w15 - w9
        w15 = math.fabs(w15)
        w11 = _fmax(w11, w15)
        w24 = w24 * w14
        w24 = w24 - w0
        w2 = w2 * w24
        w25 = w25 * w3
        w19 = w19 - w25
        w18 = w18 * w19
        w2 = w2 - w18
        w17 = w17 * w12
        w17 = w17 - w27
        w20 = w20 * w17
        w2 = w2 + w20
        w2 = w2 - w9
        w2 = math.fabs(w2)
        w11 = _fmax(w11, w2)
        w5 = _fmax(w5, w11)
        r3[0] = w5
    return [r0, r1, r2, r3]


def observe(g, p):
    """observe(g[36], p[6]) -> [xi[6], E[1], m[6], e[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "observe: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (6,):
        p = p.tolist()
    else:
        p = _vec(p, 6, "observe: p")
    _r = _raw_observe(g, p)
    return [_fromiter(_r[0], _F64, 6), _fromiter(_r[1], _F64, 1), _fromiter(_r[2], _F64, 6), _fromiter(_r[3], _F64, 1)]


def _raw_update_p(z, g, p, h):
    """update_p on lists of Python floats -> [p1[6]] as lists (see RAW)"""
    try:
        w0, w2, w1, w3, w4, w5 = z
        w18, w12, w6, _, _, _, w19, w13, w7, _, _, _, w20, w14, w8, _, _, _, _, _, _, w21, w15, w9, _, _, _, w22, w16, w10, _, _, _, w23, w17, w11 = g
        w24, = h
        r0 = [0.0] * 6
        w25 = w24 * w0
        w26 = w25 * w25
        w0 = 0.9 * w0
        w27 = w24 * w1
        w28 = w27 * 0.5
        w29 = w24 * w2
        w30 = w29 * w25
        w31 = w30 * 0.25
        w32 = w27 * w25
        w33 = w32 * 0.25
        w34 = w29 * 0.5
        w1 = 0.2 * w1
        w35 = w29 * w29
        w36 = w26 + w35
        w37 = w27 * w27
        w38 = 4.0 / (4.0 + (w36 + w37))
        w32 = w32 * 0.5
        w39 = w38 * (w29 + w32)
        w40 = w27 * w29
        w41 = w40 * 0.5
        w42 = w38 * (w41 - w25)
        w36 = 1.0 - (w38 * (w36 * 0.5))
        w43 = ((w6 * w39) + (w7 * w42)) + (w8 * w36)
        w30 = w30 * 0.5
        w44 = w38 * (w30 - w27)
        w45 = 1.0 - (w38 * ((w37 + w26) * 0.5))
        w41 = w38 * (w25 + w41)
        w46 = ((w6 * w44) + (w7 * w45)) + (w8 * w41)
        w47 = 1.0 - (w38 * ((w37 + w35) * 0.5))
        w27 = w38 * (w27 + w30)
        w29 = w38 * (w32 - w29)
        w6 = ((w6 * w47) + (w7 * w27)) + (w8 * w29)
        w7 = w24 * w3
        w8 = w7 * w7
        w30 = w24 * w4
        w32 = w30 * w30
        w38 = w8 + w32
        w48 = w24 * w5
        w49 = w48 * w48
        w50 = 4.0 / (4.0 + (w38 + w49))
        w51 = w30 * w7
        w52 = w51 * 0.5
        w53 = w50 * (w52 - w48)
        w54 = 1.0 - (w50 * ((w49 + w8) * 0.5))
        w55 = w30 * w48
        w56 = w55 * 0.5
        w57 = w50 * (w7 + w56)
        w58 = ((w9 * w53) + (w10 * w54)) + (w11 * w57)
        w59 = w48 * w7
        w60 = w59 * 0.5
        w61 = w50 * (w30 + w60)
        w56 = w50 * (w56 - w7)
        w38 = 1.0 - (w50 * (w38 * 0.5))
        w62 = ((w9 * w61) + (w10 * w56)) + (w11 * w38)
        w63 = (2.0 * (((((1.3 + (0.05 * w46)) + (0.1 * w6)) - w43) + ((-0.1) * w58)) + ((-0.3) * w62))) * w24
        w64 = 0.05 * w63
        w65 = ((w12 * w44) + (w13 * w45)) + (w14 * w41)
        w66 = ((w12 * w47) + (w13 * w27)) + (w14 * w29)
        w12 = ((w12 * w39) + (w13 * w42)) + (w14 * w36)
        w13 = ((w15 * w53) + (w16 * w54)) + (w17 * w57)
        w14 = ((w15 * w61) + (w16 * w56)) + (w17 * w38)
        w67 = (2.0 * (((((0.05 * w65) + (0.1 * w66)) - w12) + ((-0.1) * w13)) + ((-0.3) * w14))) * w24
        w68 = 0.05 * w67
        w41 = ((w18 * w44) + (w19 * w45)) + (w20 * w41)
        w27 = ((w18 * w47) + (w19 * w27)) + (w20 * w29)
        w18 = ((w18 * w39) + (w19 * w42)) + (w20 * w36)
        w19 = ((w21 * w53) + (w22 * w54)) + (w23 * w57)
        w20 = ((w21 * w61) + (w22 * w56)) + (w23 * w38)
        w29 = (2.0 * (((((0.05 * w41) + (0.1 * w27)) - w18) + ((-0.1) * w19)) + ((-0.3) * w20))) * w24
        w36 = 0.05 * w29
        w38 = w63 + (0.5 * w24)
        r0[0] = ((((1.0 + (w26 * 0.25)) * w0) + ((w28 + w31) * w2)) + ((w33 - w34) * w1)) - ((((((w43 * w64) + (w65 * w67)) + (w12 * w68)) + (w41 * w29)) + (w18 * w36)) + (w46 * w38))
        w25 = w25 * 0.5
        w26 = w40 * 0.25
        w39 = ((-0.05) * w24) - (0.1 * w63)
        w40 = 0.1 * w67
        w42 = 0.1 * w29
        r0[1] = ((((w31 - w28) * w0) + ((1.0 + (w35 * 0.25)) * w2)) + ((w25 + w26) * w1)) + ((((((w66 * w67) - (w43 * w39)) + (w12 * w40)) + (w27 * w29)) + (w18 * w42)) + (w6 * w38))
        r0[2] = ((((w34 + w33) * w0) + ((w26 - w25) * w2)) + ((1.0 + (w37 * 0.25)) * w1)) + ((((((w46 * w39) + (w6 * w64)) - (w65 * w40)) + (w66 * w68)) - (w41 * w42)) + (w27 * w36))
        w0 = 0.6 * w3
        w1 = w48 * 0.5
        w2 = w51 * 0.25
        w3 = 0.5 * w4
        w4 = w59 * 0.25
        w6 = w30 * 0.5
        w5 = 0.15 * w5
        w12 = ((-0.03) * w24) - ((-0.1) * w63)
        w18 = (-0.3) * w67
        w25 = (-0.1) * w67
        w26 = (-0.3) * w29
        w27 = (-0.1) * w29
        w24 = (0.30000000000000004 * w24) - ((-0.3) * w63)
        r0[3] = ((((1.0 + (w8 * 0.25)) * w0) + ((w1 + w2) * w3)) + ((w4 - w6) * w5)) + ((((((w62 * w12) + (w13 * w18)) - (w14 * w25)) + (w19 * w26)) - (w20 * w27)) - (w58 * w24))
        w7 = w7 * 0.5
        w8 = w55 * 0.25
        w13 = 1.0 - (w50 * ((w49 + w32) * 0.5))
        w14 = w50 * (w48 + w52)
        w19 = w50 * (w60 - w30)
        w9 = ((w9 * w13) + (w10 * w14)) + (w11 * w19)
        w10 = ((w15 * w13) + (w16 * w14)) + (w17 * w19)
        w11 = ((w21 * w13) + (w22 * w14)) + (w23 * w19)
        r0[4] = ((((w2 - w1) * w0) + ((1.0 + (w32 * 0.25)) * w3)) + ((w7 + w8) * w5)) + ((w9 * w24) - ((w10 * w18) + (w11 * w26)))
        r0[5] = ((((w6 + w4) * w0) + ((w8 - w7) * w3)) + ((1.0 + (w49 * 0.25)) * w5)) + (((w10 * w25) - (w9 * w12)) + (w11 * w27))
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 6
        w0 = 1.0
        w1 = h[0]
        w2 = z[0]
        w3 = w1 * w2
        w4 = w3 * w3
        w5 = 4.0
        w6 = w4 / w5 if w5 else _div(w4, w5)
        w6 = w0 + w6
        w7 = 0.9
        w7 = w7 * w2
        w6 = w6 * w7
        w2 = z[2]
        w8 = w1 * w2
        w9 = 2.0
        w10 = w8 / w9 if w9 else _div(w8, w9)
        w11 = z[1]
        w12 = w1 * w11
        w13 = w12 * w3
        w14 = w13 / w5 if w5 else _div(w13, w5)
        w14 = w10 + w14
        w14 = w14 * w11
        w6 = w6 + w14
        w14 = w8 * w3
        w15 = w14 / w5 if w5 else _div(w14, w5)
        w16 = w12 / w9 if w9 else _div(w12, w9)
        w15 = w15 - w16
        w17 = 0.2
        w17 = w17 * w2
        w15 = w15 * w17
        w6 = w6 + w15
        w15 = g[2]
        w2 = w12 * w12
        w18 = w4 + w2
        w19 = w8 * w8
        w18 = w18 + w19
        w18 = w5 + w18
        w18 = w5 / w18 if w18 else _div(w5, w18)
        w14 = w14 / w9 if w9 else _div(w14, w9)
        w14 = w12 + w14
        w14 = w18 * w14
        w20 = w15 * w14
        w21 = g[8]
        w22 = w8 * w12
        w23 = w22 / w9 if w9 else _div(w22, w9)
        w23 = w23 - w3
        w23 = w18 * w23
        w24 = w21 * w23
        w20 = w20 + w24
        w24 = g[14]
        w25 = w2 + w4
        w25 = w25 / w9 if w9 else _div(w25, w9)
        w25 = w18 * w25
        w25 = w0 - w25
        w26 = w24 * w25
        w20 = w20 + w26
        w26 = 0.05
        w27 = 1.3
        w13 = w13 / w9 if w9 else _div(w13, w9)
        w13 = w13 - w8
        w13 = w18 * w13
        w28 = w15 * w13
        w4 = w19 + w4
        w4 = w4 / w9 if w9 else _div(w4, w9)
        w4 = w18 * w4
        w4 = w0 - w4
        w29 = w21 * w4
        w28 = w28 + w29
        w29 = w12 * w8
        w30 = w29 / w9 if w9 else _div(w29, w9)
        w30 = w3 + w30
        w30 = w18 * w30
        w31 = w24 * w30
        w28 = w28 + w31
        w31 = w26 * w28
        w27 = w27 + w31
        w31 = 0.1
        w32 = w19 + w2
        w32 = w32 / w9 if w9 else _div(w32, w9)
        w32 = w18 * w32
        w32 = w0 - w32
        w15 = w15 * w32
        w33 = w3 * w12
        w34 = w33 / w9 if w9 else _div(w33, w9)
        w34 = w8 + w34
        w34 = w18 * w34
        w21 = w21 * w34
        w15 = w15 + w21
        w8 = w3 * w8
        w21 = w8 / w9 if w9 else _div(w8, w9)
        w21 = w21 - w12
        w18 = w18 * w21
        w24 = w24 * w18
        w15 = w15 + w24
        w24 = w31 * w15
        w27 = w27 + w24
        w27 = w27 - w20
        w24 = -0.1
        w21 = g[23]
        w12 = z[3]
        w35 = w1 * w12
        w36 = w35 * w35
        w37 = z[4]
        w38 = w1 * w37
        w39 = w38 * w38
        w40 = w36 + w39
        w41 = z[5]
        w42 = w1 * w41
        w43 = w42 * w42
        w40 = w40 + w43
        w40 = w5 + w40
        w40 = w5 / w40 if w40 else _div(w5, w40)
        w44 = w38 * w35
        w45 = w44 / w9 if w9 else _div(w44, w9)
        w45 = w45 - w42
        w45 = w40 * w45
        w46 = w21 * w45
        w47 = g[29]
        w48 = w43 + w36
        w48 = w48 / w9 if w9 else _div(w48, w9)
        w48 = w40 * w48
        w48 = w0 - w48
        w49 = w47 * w48
        w46 = w46 + w49
        w49 = g[35]
        w50 = w38 * w42
        w51 = w50 / w9 if w9 else _div(w50, w9)
        w51 = w35 + w51
        w51 = w40 * w51
        w52 = w49 * w51
        w46 = w46 + w52
        w52 = w24 * w46
        w27 = w27 + w52
        w52 = -0.3
        w53 = w42 * w35
        w54 = w53 / w9 if w9 else _div(w53, w9)
        w54 = w38 + w54
        w54 = w40 * w54
        w55 = w21 * w54
        w56 = w42 * w38
        w57 = w56 / w9 if w9 else _div(w56, w9)
        w57 = w57 - w35
        w57 = w40 * w57
        w58 = w47 * w57
        w55 = w55 + w58
        w58 = w39 + w36
        w58 = w58 / w9 if w9 else _div(w58, w9)
        w58 = w40 * w58
        w58 = w0 - w58
        w59 = w49 * w58
        w55 = w55 + w59
        w59 = w52 * w55
        w27 = w27 + w59
        w27 = 2.0 * w27
        w27 = w27 * w1
        w59 = w26 * w27
        w60 = w20 * w59
        w61 = g[1]
        w62 = w61 * w13
        w63 = g[7]
        w64 = w63 * w4
        w62 = w62 + w64
        w64 = g[13]
        w65 = w64 * w30
        w62 = w62 + w65
        w65 = w26 * w62
        w66 = w61 * w32
        w67 = w63 * w34
        w66 = w66 + w67
        w67 = w64 * w18
        w66 = w66 + w67
        w67 = w31 * w66
        w65 = w65 + w67
        w61 = w61 * w14
        w63 = w63 * w23
        w61 = w61 + w63
        w64 = w64 * w25
        w61 = w61 + w64
        w65 = w65 - w61
        w64 = g[22]
        w63 = w64 * w45
        w67 = g[28]
        w68 = w67 * w48
        w63 = w63 + w68
        w68 = g[34]
        w69 = w68 * w51
        w63 = w63 + w69
        w69 = w24 * w63
        w65 = w65 + w69
        w69 = w64 * w54
        w70 = w67 * w57
        w69 = w69 + w70
        w70 = w68 * w58
        w69 = w69 + w70
        w70 = w52 * w69
        w65 = w65 + w70
        w65 = 2.0 * w65
        w65 = w65 * w1
        w70 = w62 * w65
        w60 = w60 + w70
        w70 = w26 * w65
        w71 = w61 * w70
        w60 = w60 + w71
        w71 = g[0]
        w13 = w71 * w13
        w72 = g[6]
        w4 = w72 * w4
        w13 = w13 + w4
        w4 = g[12]
        w30 = w4 * w30
        w13 = w13 + w30
        w30 = w26 * w13
        w32 = w71 * w32
        w34 = w72 * w34
        w32 = w32 + w34
        w18 = w4 * w18
        w32 = w32 + w18
        w18 = w31 * w32
        w30 = w30 + w18
        w71 = w71 * w14
        w72 = w72 * w23
        w71 = w71 + w72
        w4 = w4 * w25
        w71 = w71 + w4
        w30 = w30 - w71
        w4 = g[21]
        w45 = w4 * w45
        w25 = g[27]
        w48 = w25 * w48
        w45 = w45 + w48
        w48 = g[33]
        w51 = w48 * w51
        w45 = w45 + w51
        w51 = w24 * w45
        w30 = w30 + w51
        w54 = w4 * w54
        w57 = w25 * w57
        w54 = w54 + w57
        w58 = w48 * w58
        w54 = w54 + w58
        w58 = w52 * w54
        w30 = w30 + w58
        w30 = 2.0 * w30
        w30 = w30 * w1
        w58 = w13 * w30
        w60 = w60 + w58
        w26 = w26 * w30
        w58 = w71 * w26
        w60 = w60 + w58
        w58 = 0.5
        w57 = w58 * w1
        w57 = w27 + w57
        w51 = w28 * w57
        w60 = w60 + w51
        w6 = w6 - w60
        r0[0] = w6
        w33 = w33 / w5 if w5 else _div(w33, w5)
        w33 = w33 - w10
        w33 = w33 * w7
        w2 = w2 / w5 if w5 else _div(w2, w5)
        w2 = w0 + w2
        w2 = w2 * w11
        w33 = w33 + w2
        w3 = w3 / w9 if w9 else _div(w3, w9)
        w22 = w22 / w5 if w5 else _div(w22, w5)
        w22 = w3 + w22
        w22 = w22 * w17
        w33 = w33 + w22
        w22 = w66 * w65
        w2 = -0.05
        w2 = w2 * w1
        w10 = w31 * w27
        w2 = w2 - w10
        w20 = w20 * w2
        w22 = w22 - w20
        w20 = w31 * w65
        w61 = w61 * w20
        w22 = w22 + w61
        w61 = w32 * w30
        w22 = w22 + w61
        w31 = w31 * w30
        w71 = w71 * w31
        w22 = w22 + w71
        w57 = w15 * w57
        w22 = w22 + w57
        w33 = w33 + w22
        r0[1] = w33
        w8 = w8 / w5 if w5 else _div(w8, w5)
        w16 = w16 + w8
        w16 = w16 * w7
        w29 = w29 / w5 if w5 else _div(w29, w5)
        w29 = w29 - w3
        w29 = w29 * w11
        w16 = w16 + w29
        w19 = w19 / w5 if w5 else _div(w19, w5)
        w19 = w0 + w19
        w19 = w19 * w17
        w16 = w16 + w19
        w28 = w28 * w2
        w15 = w15 * w59
        w28 = w28 + w15
        w62 = w62 * w20
        w28 = w28 - w62
        w66 = w66 * w70
        w28 = w28 + w66
        w13 = w13 * w31
        w28 = w28 - w13
        w32 = w32 * w26
        w28 = w28 + w32
        w16 = w16 + w28
        r0[2] = w16
        w36 = w36 / w5 if w5 else _div(w36, w5)
        w36 = w0 + w36
        w16 = 0.6
        w16 = w16 * w12
        w36 = w36 * w16
        w12 = w42 / w9 if w9 else _div(w42, w9)
        w44 = w44 / w5 if w5 else _div(w44, w5)
        w44 = w12 + w44
        w58 = w58 * w37
        w44 = w44 * w58
        w36 = w36 + w44
        w53 = w53 / w5 if w5 else _div(w53, w5)
        w44 = w38 / w9 if w9 else _div(w38, w9)
        w53 = w53 - w44
        w37 = 0.15
        w37 = w37 * w41
        w53 = w53 * w37
        w36 = w36 + w53
        w53 = -0.03
        w53 = w53 * w1
        w41 = w24 * w27
        w53 = w53 - w41
        w55 = w55 * w53
        w41 = w52 * w65
        w63 = w63 * w41
        w55 = w55 + w63
        w65 = w24 * w65
        w69 = w69 * w65
        w55 = w55 - w69
        w69 = w52 * w30
        w45 = w45 * w69
        w55 = w55 + w45
        w24 = w24 * w30
        w54 = w54 * w24
        w55 = w55 - w54
        w54 = 0.30000000000000004
        w54 = w54 * w1
        w52 = w52 * w27
        w54 = w54 - w52
        w46 = w46 * w54
        w55 = w55 - w46
        w36 = w36 + w55
        r0[3] = w36
        w36 = w35 * w38
        w55 = w36 / w5 if w5 else _div(w36, w5)
        w55 = w55 - w12
        w55 = w55 * w16
        w12 = w39 / w5 if w5 else _div(w39, w5)
        w12 = w0 + w12
        w12 = w12 * w58
        w55 = w55 + w12
        w12 = w35 / w9 if w9 else _div(w35, w9)
        w56 = w56 / w5 if w5 else _div(w56, w5)
        w56 = w12 + w56
        w56 = w56 * w37
        w55 = w55 + w56
        w39 = w43 + w39
        w39 = w39 / w9 if w9 else _div(w39, w9)
        w39 = w40 * w39
        w39 = w0 - w39
        w21 = w21 * w39
        w36 = w36 / w9 if w9 else _div(w36, w9)
        w36 = w42 + w36
        w36 = w40 * w36
        w47 = w47 * w36
        w21 = w21 + w47
        w35 = w35 * w42
        w9 = w35 / w9 if w9 else _div(w35, w9)
        w9 = w9 - w38
        w40 = w40 * w9
        w49 = w49 * w40
        w21 = w21 + w49
        w54 = w21 * w54
        w64 = w64 * w39
        w67 = w67 * w36
        w64 = w64 + w67
        w68 = w68 * w40
        w64 = w64 + w68
        w41 = w64 * w41
        w4 = w4 * w39
        w25 = w25 * w36
        w4 = w4 + w25
        w48 = w48 * w40
        w4 = w4 + w48
        w69 = w4 * w69
        w41 = w41 + w69
        w54 = w54 - w41
        w55 = w55 + w54
        r0[4] = w55
        w35 = w35 / w5 if w5 else _div(w35, w5)
        w44 = w44 + w35
        w44 = w44 * w16
        w50 = w50 / w5 if w5 else _div(w50, w5)
        w50 = w50 - w12
        w50 = w50 * w58
        w44 = w44 + w50
        w43 = w43 / w5 if w5 else _div(w43, w5)
        w0 = w0 + w43
        w0 = w0 * w37
        w44 = w44 + w0
        w64 = w64 * w65
        w21 = w21 * w53
        w64 = w64 - w21
        w4 = w4 * w24
        w64 = w64 + w4
        w44 = w44 + w64
        r0[5] = w44
    return [r0]


def update_p(z, g, p, h):
    """update_p(z[6], g[36], p[6], h[1]) -> [p1[6]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (6,):
        z = z.tolist()
    else:
        z = _vec(z, 6, "update_p: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "update_p: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (6,):
        p = p.tolist()
    else:
        p = _vec(p, 6, "update_p: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "update_p: h")
    _r = _raw_update_p(z, g, p, h)
    return [_fromiter(_r[0], _F64, 6)]


def _raw_velocity_step(g, p, xi):
    """velocity_step on lists of Python floats -> [xi1[6]] as lists (see RAW)"""
    try:
        w0, w1, w2, w3, w4, w5 = p
        w6, w7, w8, w9, w10, w11 = xi
        r0 = [0.0] * 6
        r0[0] = w6 - (((0.9 * w6) - w0) / 0.9)
        r0[1] = w7 - (w7 - w1)
        r0[2] = w8 - (((0.2 * w8) - w2) / 0.2)
        r0[3] = w9 - (((0.6 * w9) - w3) / 0.6)
        r0[4] = w10 - (2.0 * ((0.5 * w10) - w4))
        r0[5] = w11 - (((0.15 * w11) - w5) / 0.15)
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 6
        w0 = xi[0]
        w1 = 0.9
        w2 = w1 * w0
        w3 = p[0]
        w2 = w2 - w3
        w2 = w2 / w1 if w1 else _div(w2, w1)
        w0 = w0 - w2
        r0[0] = w0
        w0 = xi[1]
        w2 = p[1]
        w2 = w0 - w2
        w0 = w0 - w2
        r0[1] = w0
        w0 = xi[2]
        w2 = 0.2
        w1 = w2 * w0
        w3 = p[2]
        w1 = w1 - w3
        w1 = w1 / w2 if w2 else _div(w1, w2)
        w0 = w0 - w1
        r0[2] = w0
        w0 = xi[3]
        w1 = 0.6
        w2 = w1 * w0
        w3 = p[3]
        w2 = w2 - w3
        w2 = w2 / w1 if w1 else _div(w2, w1)
        w0 = w0 - w2
        r0[3] = w0
        w0 = xi[4]
        w2 = 0.5
        w2 = w2 * w0
        w1 = p[4]
        w2 = w2 - w1
        w2 = 2.0 * w2
        w0 = w0 - w2
        r0[4] = w0
        w0 = xi[5]
        w2 = 0.15
        w1 = w2 * w0
        w3 = p[5]
        w1 = w1 - w3
        w1 = w1 / w2 if w2 else _div(w1, w2)
        w0 = w0 - w1
        r0[5] = w0
    return [r0]


def velocity_step(g, p, xi):
    """velocity_step(g[36], p[6], xi[6]) -> [xi1[6]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "velocity_step: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (6,):
        p = p.tolist()
    else:
        p = _vec(p, 6, "velocity_step: p")
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (6,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 6, "velocity_step: xi")
    _r = _raw_velocity_step(g, p, xi)
    return [_fromiter(_r[0], _F64, 6)]


def _raw_record(g, p, xi):
    """record on lists of Python floats -> [row[49]] as lists (see RAW)"""
    w0, w1, w2, w3, w4, w5, w6, w7, w8, w9, w10, w11, w12, w13, w14, w15, w16, w17, w18, w19, w20, w21, w22, w23, w24, w25, w26, w27, w28, w29, w30, w31, w32, w33, w34, w35 = g
    w36, w37, w38, w39, w40, w41 = p
    w42, w43, w44, w45, w46, w47 = xi
    r0 = [0.0] * 49
    r0[0] = w0
    r0[1] = w1
    r0[2] = w2
    r0[3] = w3
    r0[4] = w4
    r0[5] = w5
    r0[6] = w6
    r0[7] = w7
    r0[8] = w8
    r0[9] = w9
    r0[10] = w10
    r0[11] = w11
    r0[12] = w12
    r0[13] = w13
    r0[14] = w14
    r0[15] = w15
    r0[16] = w16
    r0[17] = w17
    r0[18] = w18
    r0[19] = w19
    r0[20] = w20
    r0[21] = w21
    r0[22] = w22
    r0[23] = w23
    r0[24] = w24
    r0[25] = w25
    r0[26] = w26
    r0[27] = w27
    r0[28] = w28
    r0[29] = w29
    r0[30] = w30
    r0[31] = w31
    r0[32] = w32
    r0[33] = w33
    r0[34] = w34
    r0[35] = w35
    r0[36] = w36
    r0[37] = w37
    r0[38] = w38
    r0[39] = w39
    r0[40] = w40
    r0[41] = w41
    w3 = w43 * w43
    w4 = ((((0.05 * w6) + (0.1 * w0)) - w12) + ((-0.1) * w27)) + ((-0.3) * w33)
    w5 = ((((0.05 * w7) + (0.1 * w1)) - w13) + ((-0.1) * w28)) + ((-0.3) * w34)
    w9 = ((((1.3 + (0.05 * w8)) + (0.1 * w2)) - w14) + ((-0.1) * w29)) + ((-0.3) * w35)
    r0[42] = (((((((0.9 * w42) * w42) + w3) + ((0.2 * w44) * w44)) + ((0.6 * w45) * w45)) + ((0.5 * w46) * w46)) + ((0.15 * w47) * w47)) - (((((((((((((0.25 * (w46 * w46)) + (0.5 * w3)) + w14) + (0.6000000000000001 * w35)) + (0.1 * (w44 * w44))) + (0.075 * (w47 * w47))) + (0.3 * (w45 * w45))) + (0.45 * (w42 * w42))) + ((-2.0) * (w4 * w4))) + ((-2.0) * (w5 * w5))) + ((-2.0) * (w9 * w9))) + ((-0.06) * w29)) + ((-0.1) * w2))
    r0[43] = ((((w14 * w7) - (w13 * w8)) * w36) + (((w2 * w13) - (w1 * w14)) * w37)) + (((w8 * w1) - (w7 * w2)) * w38)
    r0[44] = ((((w12 * w8) - (w14 * w6)) * w36) + (((w0 * w14) - (w2 * w12)) * w37)) + (((w6 * w2) - (w8 * w0)) * w38)
    r0[45] = ((((w13 * w6) - (w12 * w7)) * w36) + (((w1 * w12) - (w0 * w13)) * w37)) + (((w7 * w0) - (w6 * w1)) * w38)
    r0[46] = ((((w35 * w28) - (w34 * w29)) * w39) + (((w23 * w34) - (w22 * w35)) * w40)) + (((w29 * w22) - (w28 * w23)) * w41)
    r0[47] = ((((w33 * w29) - (w35 * w27)) * w39) + (((w21 * w35) - (w23 * w33)) * w40)) + (((w27 * w23) - (w29 * w21)) * w41)
    r0[48] = ((((w34 * w27) - (w33 * w28)) * w39) + (((w22 * w33) - (w21 * w34)) * w40)) + (((w28 * w21) - (w27 * w22)) * w41)
    return [r0]


def record(g, p, xi):
    """record(g[36], p[6], xi[6]) -> [row[49]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (36,):
        g = g.tolist()
    else:
        g = _vec(g, 36, "record: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (6,):
        p = p.tolist()
    else:
        p = _vec(p, 6, "record: p")
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (6,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 6, "record: xi")
    _r = _raw_record(g, p, xi)
    return [_fromiter(_r[0], _F64, 49)]


KERNELS = {
    "residual": residual,
    "jacobian": jacobian,
    "residual_jacobian": residual_jacobian,
    "update": update,
    "guess": guess,
    "legendre": legendre,
    "hessian": hessian,
    "energy": energy,
    "momentum": momentum,
    "defect": defect,
    "margin": margin,
    "section": section,
    "chart_point": chart_point,
    "observe": observe,
    "update_p": update_p,
    "velocity_step": velocity_step,
    "record": record,
}

RAW = {
    "residual": _raw_residual,
    "jacobian": _raw_jacobian,
    "residual_jacobian": _raw_residual_jacobian,
    "update": _raw_update,
    "guess": _raw_guess,
    "legendre": _raw_legendre,
    "hessian": _raw_hessian,
    "energy": _raw_energy,
    "momentum": _raw_momentum,
    "defect": _raw_defect,
    "margin": _raw_margin,
    "section": _raw_section,
    "chart_point": _raw_chart_point,
    "observe": _raw_observe,
    "update_p": _raw_update_p,
    "velocity_step": _raw_velocity_step,
    "record": _raw_record,
}


# ---- Newton's linear algebra for NZ (hpgen.codegen.pylinear: straight-line Python, the C
# template's operations in the same order), used by hpgen.runtime.newton ----
_isfinite = math.isfinite
_UNIT6 = ((1.0, 0.0, 0.0, 0.0, 0.0, 0.0), (0.0, 1.0, 0.0, 0.0, 0.0, 0.0), (0.0, 0.0, 1.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0, 1.0, 0.0), (0.0, 0.0, 0.0, 0.0, 0.0, 1.0))


def _lin_factor_solve(J, F, keep):
    s = sum(J)
    if not s - s == 0.0 and not all(map(_isfinite, J)):
        return None
    a0_0, a1_0, a2_0, a3_0, a4_0, a5_0, a0_1, a1_1, a2_1, a3_1, a4_1, a5_1, a0_2, a1_2, a2_2, a3_2, a4_2, a5_2, a0_3, a1_3, a2_3, a3_3, a4_3, a5_3, a0_4, a1_4, a2_4, a3_4, a4_4, a5_4, a0_5, a1_5, a2_5, a3_5, a4_5, a5_5, = J
    m = abs(a0_0)
    q = 0
    t = abs(a1_0)
    if t > m:
        m = t
        q = 1
    t = abs(a2_0)
    if t > m:
        m = t
        q = 2
    t = abs(a3_0)
    if t > m:
        m = t
        q = 3
    t = abs(a4_0)
    if t > m:
        m = t
        q = 4
    t = abs(a5_0)
    if t > m:
        m = t
        q = 5
    if m == 0.0:
        return None
    p0 = q
    if q == 1:
        a0_0, a0_1, a0_2, a0_3, a0_4, a0_5, a1_0, a1_1, a1_2, a1_3, a1_4, a1_5 = a1_0, a1_1, a1_2, a1_3, a1_4, a1_5, a0_0, a0_1, a0_2, a0_3, a0_4, a0_5
    elif q == 2:
        a0_0, a0_1, a0_2, a0_3, a0_4, a0_5, a2_0, a2_1, a2_2, a2_3, a2_4, a2_5 = a2_0, a2_1, a2_2, a2_3, a2_4, a2_5, a0_0, a0_1, a0_2, a0_3, a0_4, a0_5
    elif q == 3:
        a0_0, a0_1, a0_2, a0_3, a0_4, a0_5, a3_0, a3_1, a3_2, a3_3, a3_4, a3_5 = a3_0, a3_1, a3_2, a3_3, a3_4, a3_5, a0_0, a0_1, a0_2, a0_3, a0_4, a0_5
    elif q == 4:
        a0_0, a0_1, a0_2, a0_3, a0_4, a0_5, a4_0, a4_1, a4_2, a4_3, a4_4, a4_5 = a4_0, a4_1, a4_2, a4_3, a4_4, a4_5, a0_0, a0_1, a0_2, a0_3, a0_4, a0_5
    elif q == 5:
        a0_0, a0_1, a0_2, a0_3, a0_4, a0_5, a5_0, a5_1, a5_2, a5_3, a5_4, a5_5 = a5_0, a5_1, a5_2, a5_3, a5_4, a5_5, a0_0, a0_1, a0_2, a0_3, a0_4, a0_5
    r = 1.0 / a0_0
    a0_0 = r
    a1_0 = a1_0 * r
    a2_0 = a2_0 * r
    a3_0 = a3_0 * r
    a4_0 = a4_0 * r
    a5_0 = a5_0 * r
    if a0_1 != 0.0:
        a1_1 = a1_1 - a1_0 * a0_1
        a2_1 = a2_1 - a2_0 * a0_1
        a3_1 = a3_1 - a3_0 * a0_1
        a4_1 = a4_1 - a4_0 * a0_1
        a5_1 = a5_1 - a5_0 * a0_1
    if a0_2 != 0.0:
        a1_2 = a1_2 - a1_0 * a0_2
        a2_2 = a2_2 - a2_0 * a0_2
        a3_2 = a3_2 - a3_0 * a0_2
        a4_2 = a4_2 - a4_0 * a0_2
        a5_2 = a5_2 - a5_0 * a0_2
    if a0_3 != 0.0:
        a1_3 = a1_3 - a1_0 * a0_3
        a2_3 = a2_3 - a2_0 * a0_3
        a3_3 = a3_3 - a3_0 * a0_3
        a4_3 = a4_3 - a4_0 * a0_3
        a5_3 = a5_3 - a5_0 * a0_3
    if a0_4 != 0.0:
        a1_4 = a1_4 - a1_0 * a0_4
        a2_4 = a2_4 - a2_0 * a0_4
        a3_4 = a3_4 - a3_0 * a0_4
        a4_4 = a4_4 - a4_0 * a0_4
        a5_4 = a5_4 - a5_0 * a0_4
    if a0_5 != 0.0:
        a1_5 = a1_5 - a1_0 * a0_5
        a2_5 = a2_5 - a2_0 * a0_5
        a3_5 = a3_5 - a3_0 * a0_5
        a4_5 = a4_5 - a4_0 * a0_5
        a5_5 = a5_5 - a5_0 * a0_5
    m = abs(a1_1)
    q = 1
    t = abs(a2_1)
    if t > m:
        m = t
        q = 2
    t = abs(a3_1)
    if t > m:
        m = t
        q = 3
    t = abs(a4_1)
    if t > m:
        m = t
        q = 4
    t = abs(a5_1)
    if t > m:
        m = t
        q = 5
    if m == 0.0:
        return None
    p1 = q
    if q == 2:
        a1_0, a1_1, a1_2, a1_3, a1_4, a1_5, a2_0, a2_1, a2_2, a2_3, a2_4, a2_5 = a2_0, a2_1, a2_2, a2_3, a2_4, a2_5, a1_0, a1_1, a1_2, a1_3, a1_4, a1_5
    elif q == 3:
        a1_0, a1_1, a1_2, a1_3, a1_4, a1_5, a3_0, a3_1, a3_2, a3_3, a3_4, a3_5 = a3_0, a3_1, a3_2, a3_3, a3_4, a3_5, a1_0, a1_1, a1_2, a1_3, a1_4, a1_5
    elif q == 4:
        a1_0, a1_1, a1_2, a1_3, a1_4, a1_5, a4_0, a4_1, a4_2, a4_3, a4_4, a4_5 = a4_0, a4_1, a4_2, a4_3, a4_4, a4_5, a1_0, a1_1, a1_2, a1_3, a1_4, a1_5
    elif q == 5:
        a1_0, a1_1, a1_2, a1_3, a1_4, a1_5, a5_0, a5_1, a5_2, a5_3, a5_4, a5_5 = a5_0, a5_1, a5_2, a5_3, a5_4, a5_5, a1_0, a1_1, a1_2, a1_3, a1_4, a1_5
    r = 1.0 / a1_1
    a1_1 = r
    a2_1 = a2_1 * r
    a3_1 = a3_1 * r
    a4_1 = a4_1 * r
    a5_1 = a5_1 * r
    if a1_2 != 0.0:
        a2_2 = a2_2 - a2_1 * a1_2
        a3_2 = a3_2 - a3_1 * a1_2
        a4_2 = a4_2 - a4_1 * a1_2
        a5_2 = a5_2 - a5_1 * a1_2
    if a1_3 != 0.0:
        a2_3 = a2_3 - a2_1 * a1_3
        a3_3 = a3_3 - a3_1 * a1_3
        a4_3 = a4_3 - a4_1 * a1_3
        a5_3 = a5_3 - a5_1 * a1_3
    if a1_4 != 0.0:
        a2_4 = a2_4 - a2_1 * a1_4
        a3_4 = a3_4 - a3_1 * a1_4
        a4_4 = a4_4 - a4_1 * a1_4
        a5_4 = a5_4 - a5_1 * a1_4
    if a1_5 != 0.0:
        a2_5 = a2_5 - a2_1 * a1_5
        a3_5 = a3_5 - a3_1 * a1_5
        a4_5 = a4_5 - a4_1 * a1_5
        a5_5 = a5_5 - a5_1 * a1_5
    m = abs(a2_2)
    q = 2
    t = abs(a3_2)
    if t > m:
        m = t
        q = 3
    t = abs(a4_2)
    if t > m:
        m = t
        q = 4
    t = abs(a5_2)
    if t > m:
        m = t
        q = 5
    if m == 0.0:
        return None
    p2 = q
    if q == 3:
        a2_0, a2_1, a2_2, a2_3, a2_4, a2_5, a3_0, a3_1, a3_2, a3_3, a3_4, a3_5 = a3_0, a3_1, a3_2, a3_3, a3_4, a3_5, a2_0, a2_1, a2_2, a2_3, a2_4, a2_5
    elif q == 4:
        a2_0, a2_1, a2_2, a2_3, a2_4, a2_5, a4_0, a4_1, a4_2, a4_3, a4_4, a4_5 = a4_0, a4_1, a4_2, a4_3, a4_4, a4_5, a2_0, a2_1, a2_2, a2_3, a2_4, a2_5
    elif q == 5:
        a2_0, a2_1, a2_2, a2_3, a2_4, a2_5, a5_0, a5_1, a5_2, a5_3, a5_4, a5_5 = a5_0, a5_1, a5_2, a5_3, a5_4, a5_5, a2_0, a2_1, a2_2, a2_3, a2_4, a2_5
    r = 1.0 / a2_2
    a2_2 = r
    a3_2 = a3_2 * r
    a4_2 = a4_2 * r
    a5_2 = a5_2 * r
    if a2_3 != 0.0:
        a3_3 = a3_3 - a3_2 * a2_3
        a4_3 = a4_3 - a4_2 * a2_3
        a5_3 = a5_3 - a5_2 * a2_3
    if a2_4 != 0.0:
        a3_4 = a3_4 - a3_2 * a2_4
        a4_4 = a4_4 - a4_2 * a2_4
        a5_4 = a5_4 - a5_2 * a2_4
    if a2_5 != 0.0:
        a3_5 = a3_5 - a3_2 * a2_5
        a4_5 = a4_5 - a4_2 * a2_5
        a5_5 = a5_5 - a5_2 * a2_5
    m = abs(a3_3)
    q = 3
    t = abs(a4_3)
    if t > m:
        m = t
        q = 4
    t = abs(a5_3)
    if t > m:
        m = t
        q = 5
    if m == 0.0:
        return None
    p3 = q
    if q == 4:
        a3_0, a3_1, a3_2, a3_3, a3_4, a3_5, a4_0, a4_1, a4_2, a4_3, a4_4, a4_5 = a4_0, a4_1, a4_2, a4_3, a4_4, a4_5, a3_0, a3_1, a3_2, a3_3, a3_4, a3_5
    elif q == 5:
        a3_0, a3_1, a3_2, a3_3, a3_4, a3_5, a5_0, a5_1, a5_2, a5_3, a5_4, a5_5 = a5_0, a5_1, a5_2, a5_3, a5_4, a5_5, a3_0, a3_1, a3_2, a3_3, a3_4, a3_5
    r = 1.0 / a3_3
    a3_3 = r
    a4_3 = a4_3 * r
    a5_3 = a5_3 * r
    if a3_4 != 0.0:
        a4_4 = a4_4 - a4_3 * a3_4
        a5_4 = a5_4 - a5_3 * a3_4
    if a3_5 != 0.0:
        a4_5 = a4_5 - a4_3 * a3_5
        a5_5 = a5_5 - a5_3 * a3_5
    m = abs(a4_4)
    q = 4
    t = abs(a5_4)
    if t > m:
        m = t
        q = 5
    if m == 0.0:
        return None
    p4 = q
    if q == 5:
        a4_0, a4_1, a4_2, a4_3, a4_4, a4_5, a5_0, a5_1, a5_2, a5_3, a5_4, a5_5 = a5_0, a5_1, a5_2, a5_3, a5_4, a5_5, a4_0, a4_1, a4_2, a4_3, a4_4, a4_5
    r = 1.0 / a4_4
    a4_4 = r
    a5_4 = a5_4 * r
    if a4_5 != 0.0:
        a5_5 = a5_5 - a5_4 * a4_5
    m = abs(a5_5)
    q = 5
    if m == 0.0:
        return None
    p5 = q
    r = 1.0 / a5_5
    a5_5 = r
    perm = list(range(6))
    perm[0], perm[p0] = perm[p0], perm[0]
    perm[1], perm[p1] = perm[p1], perm[1]
    perm[2], perm[p2] = perm[p2], perm[2]
    perm[3], perm[p3] = perm[p3], perm[3]
    perm[4], perm[p4] = perm[p4], perm[4]
    perm[5], perm[p5] = perm[p5], perm[5]
    b0, b1, b2, b3, b4, b5, = [F[i] for i in perm]
    b1 = b1 - a1_0 * b0
    b2 = b2 - a2_0 * b0
    b3 = b3 - a3_0 * b0
    b4 = b4 - a4_0 * b0
    b5 = b5 - a5_0 * b0
    b2 = b2 - a2_1 * b1
    b3 = b3 - a3_1 * b1
    b4 = b4 - a4_1 * b1
    b5 = b5 - a5_1 * b1
    b3 = b3 - a3_2 * b2
    b4 = b4 - a4_2 * b2
    b5 = b5 - a5_2 * b2
    b4 = b4 - a4_3 * b3
    b5 = b5 - a5_3 * b3
    b5 = b5 - a5_4 * b4
    b5 = b5 * a5_5
    b4 = (b4 - a4_5 * b5) * a4_4
    b3 = (b3 - a3_4 * b4 - a3_5 * b5) * a3_3
    b2 = (b2 - a2_3 * b3 - a2_4 * b4 - a2_5 * b5) * a2_2
    b1 = (b1 - a1_2 * b2 - a1_3 * b3 - a1_4 * b4 - a1_5 * b5) * a1_1
    b0 = (b0 - a0_1 * b1 - a0_2 * b2 - a0_3 * b3 - a0_4 * b4 - a0_5 * b5) * a0_0
    dz = [b0, b1, b2, b3, b4, b5]
    if not keep:
        return dz, None
    inv = [0] * 6
    for i, q in enumerate(perm):
        inv[q] = i
    x0_0, x1_0, x2_0, x3_0, x4_0, x5_0, = _UNIT6[inv[0]]
    if x0_0 != 0.0:
        x1_0 = x1_0 - a1_0 * x0_0
        x2_0 = x2_0 - a2_0 * x0_0
        x3_0 = x3_0 - a3_0 * x0_0
        x4_0 = x4_0 - a4_0 * x0_0
        x5_0 = x5_0 - a5_0 * x0_0
    if x1_0 != 0.0:
        x2_0 = x2_0 - a2_1 * x1_0
        x3_0 = x3_0 - a3_1 * x1_0
        x4_0 = x4_0 - a4_1 * x1_0
        x5_0 = x5_0 - a5_1 * x1_0
    if x2_0 != 0.0:
        x3_0 = x3_0 - a3_2 * x2_0
        x4_0 = x4_0 - a4_2 * x2_0
        x5_0 = x5_0 - a5_2 * x2_0
    if x3_0 != 0.0:
        x4_0 = x4_0 - a4_3 * x3_0
        x5_0 = x5_0 - a5_3 * x3_0
    if x4_0 != 0.0:
        x5_0 = x5_0 - a5_4 * x4_0
    x5_0 = x5_0 * a5_5
    x0_0 = x0_0 - a0_5 * x5_0
    x1_0 = x1_0 - a1_5 * x5_0
    x2_0 = x2_0 - a2_5 * x5_0
    x3_0 = x3_0 - a3_5 * x5_0
    x4_0 = x4_0 - a4_5 * x5_0
    x4_0 = x4_0 * a4_4
    x0_0 = x0_0 - a0_4 * x4_0
    x1_0 = x1_0 - a1_4 * x4_0
    x2_0 = x2_0 - a2_4 * x4_0
    x3_0 = x3_0 - a3_4 * x4_0
    x3_0 = x3_0 * a3_3
    x0_0 = x0_0 - a0_3 * x3_0
    x1_0 = x1_0 - a1_3 * x3_0
    x2_0 = x2_0 - a2_3 * x3_0
    x2_0 = x2_0 * a2_2
    x0_0 = x0_0 - a0_2 * x2_0
    x1_0 = x1_0 - a1_2 * x2_0
    x1_0 = x1_0 * a1_1
    x0_0 = x0_0 - a0_1 * x1_0
    x0_0 = x0_0 * a0_0
    x0_1, x1_1, x2_1, x3_1, x4_1, x5_1, = _UNIT6[inv[1]]
    if x0_1 != 0.0:
        x1_1 = x1_1 - a1_0 * x0_1
        x2_1 = x2_1 - a2_0 * x0_1
        x3_1 = x3_1 - a3_0 * x0_1
        x4_1 = x4_1 - a4_0 * x0_1
        x5_1 = x5_1 - a5_0 * x0_1
    if x1_1 != 0.0:
        x2_1 = x2_1 - a2_1 * x1_1
        x3_1 = x3_1 - a3_1 * x1_1
        x4_1 = x4_1 - a4_1 * x1_1
        x5_1 = x5_1 - a5_1 * x1_1
    if x2_1 != 0.0:
        x3_1 = x3_1 - a3_2 * x2_1
        x4_1 = x4_1 - a4_2 * x2_1
        x5_1 = x5_1 - a5_2 * x2_1
    if x3_1 != 0.0:
        x4_1 = x4_1 - a4_3 * x3_1
        x5_1 = x5_1 - a5_3 * x3_1
    if x4_1 != 0.0:
        x5_1 = x5_1 - a5_4 * x4_1
    x5_1 = x5_1 * a5_5
    x0_1 = x0_1 - a0_5 * x5_1
    x1_1 = x1_1 - a1_5 * x5_1
    x2_1 = x2_1 - a2_5 * x5_1
    x3_1 = x3_1 - a3_5 * x5_1
    x4_1 = x4_1 - a4_5 * x5_1
    x4_1 = x4_1 * a4_4
    x0_1 = x0_1 - a0_4 * x4_1
    x1_1 = x1_1 - a1_4 * x4_1
    x2_1 = x2_1 - a2_4 * x4_1
    x3_1 = x3_1 - a3_4 * x4_1
    x3_1 = x3_1 * a3_3
    x0_1 = x0_1 - a0_3 * x3_1
    x1_1 = x1_1 - a1_3 * x3_1
    x2_1 = x2_1 - a2_3 * x3_1
    x2_1 = x2_1 * a2_2
    x0_1 = x0_1 - a0_2 * x2_1
    x1_1 = x1_1 - a1_2 * x2_1
    x1_1 = x1_1 * a1_1
    x0_1 = x0_1 - a0_1 * x1_1
    x0_1 = x0_1 * a0_0
    x0_2, x1_2, x2_2, x3_2, x4_2, x5_2, = _UNIT6[inv[2]]
    if x0_2 != 0.0:
        x1_2 = x1_2 - a1_0 * x0_2
        x2_2 = x2_2 - a2_0 * x0_2
        x3_2 = x3_2 - a3_0 * x0_2
        x4_2 = x4_2 - a4_0 * x0_2
        x5_2 = x5_2 - a5_0 * x0_2
    if x1_2 != 0.0:
        x2_2 = x2_2 - a2_1 * x1_2
        x3_2 = x3_2 - a3_1 * x1_2
        x4_2 = x4_2 - a4_1 * x1_2
        x5_2 = x5_2 - a5_1 * x1_2
    if x2_2 != 0.0:
        x3_2 = x3_2 - a3_2 * x2_2
        x4_2 = x4_2 - a4_2 * x2_2
        x5_2 = x5_2 - a5_2 * x2_2
    if x3_2 != 0.0:
        x4_2 = x4_2 - a4_3 * x3_2
        x5_2 = x5_2 - a5_3 * x3_2
    if x4_2 != 0.0:
        x5_2 = x5_2 - a5_4 * x4_2
    x5_2 = x5_2 * a5_5
    x0_2 = x0_2 - a0_5 * x5_2
    x1_2 = x1_2 - a1_5 * x5_2
    x2_2 = x2_2 - a2_5 * x5_2
    x3_2 = x3_2 - a3_5 * x5_2
    x4_2 = x4_2 - a4_5 * x5_2
    x4_2 = x4_2 * a4_4
    x0_2 = x0_2 - a0_4 * x4_2
    x1_2 = x1_2 - a1_4 * x4_2
    x2_2 = x2_2 - a2_4 * x4_2
    x3_2 = x3_2 - a3_4 * x4_2
    x3_2 = x3_2 * a3_3
    x0_2 = x0_2 - a0_3 * x3_2
    x1_2 = x1_2 - a1_3 * x3_2
    x2_2 = x2_2 - a2_3 * x3_2
    x2_2 = x2_2 * a2_2
    x0_2 = x0_2 - a0_2 * x2_2
    x1_2 = x1_2 - a1_2 * x2_2
    x1_2 = x1_2 * a1_1
    x0_2 = x0_2 - a0_1 * x1_2
    x0_2 = x0_2 * a0_0
    x0_3, x1_3, x2_3, x3_3, x4_3, x5_3, = _UNIT6[inv[3]]
    if x0_3 != 0.0:
        x1_3 = x1_3 - a1_0 * x0_3
        x2_3 = x2_3 - a2_0 * x0_3
        x3_3 = x3_3 - a3_0 * x0_3
        x4_3 = x4_3 - a4_0 * x0_3
        x5_3 = x5_3 - a5_0 * x0_3
    if x1_3 != 0.0:
        x2_3 = x2_3 - a2_1 * x1_3
        x3_3 = x3_3 - a3_1 * x1_3
        x4_3 = x4_3 - a4_1 * x1_3
        x5_3 = x5_3 - a5_1 * x1_3
    if x2_3 != 0.0:
        x3_3 = x3_3 - a3_2 * x2_3
        x4_3 = x4_3 - a4_2 * x2_3
        x5_3 = x5_3 - a5_2 * x2_3
    if x3_3 != 0.0:
        x4_3 = x4_3 - a4_3 * x3_3
        x5_3 = x5_3 - a5_3 * x3_3
    if x4_3 != 0.0:
        x5_3 = x5_3 - a5_4 * x4_3
    x5_3 = x5_3 * a5_5
    x0_3 = x0_3 - a0_5 * x5_3
    x1_3 = x1_3 - a1_5 * x5_3
    x2_3 = x2_3 - a2_5 * x5_3
    x3_3 = x3_3 - a3_5 * x5_3
    x4_3 = x4_3 - a4_5 * x5_3
    x4_3 = x4_3 * a4_4
    x0_3 = x0_3 - a0_4 * x4_3
    x1_3 = x1_3 - a1_4 * x4_3
    x2_3 = x2_3 - a2_4 * x4_3
    x3_3 = x3_3 - a3_4 * x4_3
    x3_3 = x3_3 * a3_3
    x0_3 = x0_3 - a0_3 * x3_3
    x1_3 = x1_3 - a1_3 * x3_3
    x2_3 = x2_3 - a2_3 * x3_3
    x2_3 = x2_3 * a2_2
    x0_3 = x0_3 - a0_2 * x2_3
    x1_3 = x1_3 - a1_2 * x2_3
    x1_3 = x1_3 * a1_1
    x0_3 = x0_3 - a0_1 * x1_3
    x0_3 = x0_3 * a0_0
    x0_4, x1_4, x2_4, x3_4, x4_4, x5_4, = _UNIT6[inv[4]]
    if x0_4 != 0.0:
        x1_4 = x1_4 - a1_0 * x0_4
        x2_4 = x2_4 - a2_0 * x0_4
        x3_4 = x3_4 - a3_0 * x0_4
        x4_4 = x4_4 - a4_0 * x0_4
        x5_4 = x5_4 - a5_0 * x0_4
    if x1_4 != 0.0:
        x2_4 = x2_4 - a2_1 * x1_4
        x3_4 = x3_4 - a3_1 * x1_4
        x4_4 = x4_4 - a4_1 * x1_4
        x5_4 = x5_4 - a5_1 * x1_4
    if x2_4 != 0.0:
        x3_4 = x3_4 - a3_2 * x2_4
        x4_4 = x4_4 - a4_2 * x2_4
        x5_4 = x5_4 - a5_2 * x2_4
    if x3_4 != 0.0:
        x4_4 = x4_4 - a4_3 * x3_4
        x5_4 = x5_4 - a5_3 * x3_4
    if x4_4 != 0.0:
        x5_4 = x5_4 - a5_4 * x4_4
    x5_4 = x5_4 * a5_5
    x0_4 = x0_4 - a0_5 * x5_4
    x1_4 = x1_4 - a1_5 * x5_4
    x2_4 = x2_4 - a2_5 * x5_4
    x3_4 = x3_4 - a3_5 * x5_4
    x4_4 = x4_4 - a4_5 * x5_4
    x4_4 = x4_4 * a4_4
    x0_4 = x0_4 - a0_4 * x4_4
    x1_4 = x1_4 - a1_4 * x4_4
    x2_4 = x2_4 - a2_4 * x4_4
    x3_4 = x3_4 - a3_4 * x4_4
    x3_4 = x3_4 * a3_3
    x0_4 = x0_4 - a0_3 * x3_4
    x1_4 = x1_4 - a1_3 * x3_4
    x2_4 = x2_4 - a2_3 * x3_4
    x2_4 = x2_4 * a2_2
    x0_4 = x0_4 - a0_2 * x2_4
    x1_4 = x1_4 - a1_2 * x2_4
    x1_4 = x1_4 * a1_1
    x0_4 = x0_4 - a0_1 * x1_4
    x0_4 = x0_4 * a0_0
    x0_5, x1_5, x2_5, x3_5, x4_5, x5_5, = _UNIT6[inv[5]]
    if x0_5 != 0.0:
        x1_5 = x1_5 - a1_0 * x0_5
        x2_5 = x2_5 - a2_0 * x0_5
        x3_5 = x3_5 - a3_0 * x0_5
        x4_5 = x4_5 - a4_0 * x0_5
        x5_5 = x5_5 - a5_0 * x0_5
    if x1_5 != 0.0:
        x2_5 = x2_5 - a2_1 * x1_5
        x3_5 = x3_5 - a3_1 * x1_5
        x4_5 = x4_5 - a4_1 * x1_5
        x5_5 = x5_5 - a5_1 * x1_5
    if x2_5 != 0.0:
        x3_5 = x3_5 - a3_2 * x2_5
        x4_5 = x4_5 - a4_2 * x2_5
        x5_5 = x5_5 - a5_2 * x2_5
    if x3_5 != 0.0:
        x4_5 = x4_5 - a4_3 * x3_5
        x5_5 = x5_5 - a5_3 * x3_5
    if x4_5 != 0.0:
        x5_5 = x5_5 - a5_4 * x4_5
    x5_5 = x5_5 * a5_5
    x0_5 = x0_5 - a0_5 * x5_5
    x1_5 = x1_5 - a1_5 * x5_5
    x2_5 = x2_5 - a2_5 * x5_5
    x3_5 = x3_5 - a3_5 * x5_5
    x4_5 = x4_5 - a4_5 * x5_5
    x4_5 = x4_5 * a4_4
    x0_5 = x0_5 - a0_4 * x4_5
    x1_5 = x1_5 - a1_4 * x4_5
    x2_5 = x2_5 - a2_4 * x4_5
    x3_5 = x3_5 - a3_4 * x4_5
    x3_5 = x3_5 * a3_3
    x0_5 = x0_5 - a0_3 * x3_5
    x1_5 = x1_5 - a1_3 * x3_5
    x2_5 = x2_5 - a2_3 * x3_5
    x2_5 = x2_5 * a2_2
    x0_5 = x0_5 - a0_2 * x2_5
    x1_5 = x1_5 - a1_2 * x2_5
    x1_5 = x1_5 * a1_1
    x0_5 = x0_5 - a0_1 * x1_5
    x0_5 = x0_5 * a0_0
    X = (x0_0, x1_0, x2_0, x3_0, x4_0, x5_0, x0_1, x1_1, x2_1, x3_1, x4_1, x5_1, x0_2, x1_2, x2_2, x3_2, x4_2, x5_2, x0_3, x1_3, x2_3, x3_3, x4_3, x5_3, x0_4, x1_4, x2_4, x3_4, x4_4, x5_4, x0_5, x1_5, x2_5, x3_5, x4_5, x5_5,)
    s = sum(X)
    if not s - s == 0.0 and not all(map(_isfinite, X)):
        return None
    return dz, X


def _lin_apply(f, F):
    a0_0, a1_0, a2_0, a3_0, a4_0, a5_0, a0_1, a1_1, a2_1, a3_1, a4_1, a5_1, a0_2, a1_2, a2_2, a3_2, a4_2, a5_2, a0_3, a1_3, a2_3, a3_3, a4_3, a5_3, a0_4, a1_4, a2_4, a3_4, a4_4, a5_4, a0_5, a1_5, a2_5, a3_5, a4_5, a5_5, = f
    c0, c1, c2, c3, c4, c5, = F
    b0 = a0_0 * c0 + a0_1 * c1 + a0_2 * c2 + a0_3 * c3 + a0_4 * c4 + a0_5 * c5
    b1 = a1_0 * c0 + a1_1 * c1 + a1_2 * c2 + a1_3 * c3 + a1_4 * c4 + a1_5 * c5
    b2 = a2_0 * c0 + a2_1 * c1 + a2_2 * c2 + a2_3 * c3 + a2_4 * c4 + a2_5 * c5
    b3 = a3_0 * c0 + a3_1 * c1 + a3_2 * c2 + a3_3 * c3 + a3_4 * c4 + a3_5 * c5
    b4 = a4_0 * c0 + a4_1 * c1 + a4_2 * c2 + a4_3 * c3 + a4_4 * c4 + a4_5 * c5
    b5 = a5_0 * c0 + a5_1 * c1 + a5_2 * c2 + a5_3 * c3 + a5_4 * c4 + a5_5 * c5
    return [b0, b1, b2, b3, b4, b5]


def _lin_update(f, F, z):
    a0_0, a1_0, a2_0, a3_0, a4_0, a5_0, a0_1, a1_1, a2_1, a3_1, a4_1, a5_1, a0_2, a1_2, a2_2, a3_2, a4_2, a5_2, a0_3, a1_3, a2_3, a3_3, a4_3, a5_3, a0_4, a1_4, a2_4, a3_4, a4_4, a5_4, a0_5, a1_5, a2_5, a3_5, a4_5, a5_5, = f
    c0, c1, c2, c3, c4, c5, = F
    b0 = a0_0 * c0 + a0_1 * c1 + a0_2 * c2 + a0_3 * c3 + a0_4 * c4 + a0_5 * c5
    b1 = a1_0 * c0 + a1_1 * c1 + a1_2 * c2 + a1_3 * c3 + a1_4 * c4 + a1_5 * c5
    b2 = a2_0 * c0 + a2_1 * c1 + a2_2 * c2 + a2_3 * c3 + a2_4 * c4 + a2_5 * c5
    b3 = a3_0 * c0 + a3_1 * c1 + a3_2 * c2 + a3_3 * c3 + a3_4 * c4 + a3_5 * c5
    b4 = a4_0 * c0 + a4_1 * c1 + a4_2 * c2 + a4_3 * c3 + a4_4 * c4 + a4_5 * c5
    b5 = a5_0 * c0 + a5_1 * c1 + a5_2 * c2 + a5_3 * c3 + a5_4 * c4 + a5_5 * c5
    z0, z1, z2, z3, z4, z5, = z
    z0 = z0 - b0
    z1 = z1 - b1
    z2 = z2 - b2
    z3 = z3 - b3
    z4 = z4 - b4
    z5 = z5 - b5
    s = b0 + b1 + b2 + b3 + b4 + b5
    t = z0 + z1 + z2 + z3 + z4 + z5
    if not (s - s == 0.0 and t - t == 0.0):
        return None
    dn = 0.0
    t = b0 if b0 >= 0.0 else -b0
    if t > dn:
        dn = t
    t = b1 if b1 >= 0.0 else -b1
    if t > dn:
        dn = t
    t = b2 if b2 >= 0.0 else -b2
    if t > dn:
        dn = t
    t = b3 if b3 >= 0.0 else -b3
    if t > dn:
        dn = t
    t = b4 if b4 >= 0.0 else -b4
    if t > dn:
        dn = t
    t = b5 if b5 >= 0.0 else -b5
    if t > dn:
        dn = t
    zn = 0.0
    t = z0 if z0 >= 0.0 else -z0
    if t > zn:
        zn = t
    t = z1 if z1 >= 0.0 else -z1
    if t > zn:
        zn = t
    t = z2 if z2 >= 0.0 else -z2
    if t > zn:
        zn = t
    t = z3 if z3 >= 0.0 else -z3
    if t > zn:
        zn = t
    t = z4 if z4 >= 0.0 else -z4
    if t > zn:
        zn = t
    t = z5 if z5 >= 0.0 else -z5
    if t > zn:
        zn = t
    return [z0, z1, z2, z3, z4, z5], dn, zn


def _lin_finish(dz, z):
    b0, b1, b2, b3, b4, b5, = dz
    z0, z1, z2, z3, z4, z5, = z
    z0 = z0 - b0
    z1 = z1 - b1
    z2 = z2 - b2
    z3 = z3 - b3
    z4 = z4 - b4
    z5 = z5 - b5
    s = b0 + b1 + b2 + b3 + b4 + b5
    t = z0 + z1 + z2 + z3 + z4 + z5
    if not (s - s == 0.0 and t - t == 0.0):
        return None
    dn = 0.0
    t = b0 if b0 >= 0.0 else -b0
    if t > dn:
        dn = t
    t = b1 if b1 >= 0.0 else -b1
    if t > dn:
        dn = t
    t = b2 if b2 >= 0.0 else -b2
    if t > dn:
        dn = t
    t = b3 if b3 >= 0.0 else -b3
    if t > dn:
        dn = t
    t = b4 if b4 >= 0.0 else -b4
    if t > dn:
        dn = t
    t = b5 if b5 >= 0.0 else -b5
    if t > dn:
        dn = t
    zn = 0.0
    t = z0 if z0 >= 0.0 else -z0
    if t > zn:
        zn = t
    t = z1 if z1 >= 0.0 else -z1
    if t > zn:
        zn = t
    t = z2 if z2 >= 0.0 else -z2
    if t > zn:
        zn = t
    t = z3 if z3 >= 0.0 else -z3
    if t > zn:
        zn = t
    t = z4 if z4 >= 0.0 else -z4
    if t > zn:
        zn = t
    t = z5 if z5 >= 0.0 else -z5
    if t > zn:
        zn = t
    return [z0, z1, z2, z3, z4, z5], dn, zn

LINEAR = (_lin_factor_solve, _lin_apply, _lin_update, _lin_finish)
