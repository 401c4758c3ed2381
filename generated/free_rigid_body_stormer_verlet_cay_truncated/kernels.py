# hpgen generated module free_rigid_body_stormer_verlet_cay_truncated -- do not edit, regenerate with hpgen
# model: free_rigid_body
# options: tableau=stormer-verlet, tau=cay, rkmk=truncated
# hpgen version: 0.1.0
# content hash (normalized model + options): 3b5e8c59678a8d08dcfbeb794dc549e09d951a1bd2a11e84fefde85f6aa301ff
"""Python backend of the hpgen module free_rigid_body_stormer_verlet_cay_truncated: straight-line kernels printed from the
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

N = 3
D = 3
NZ = 3


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
    """residual on lists of Python floats -> [F[3]] as lists (see RAW)"""
    w2, w1, w0 = z
    w3, w4, w5 = p
    w6, = h
    r0 = [0.0] * 3
    w7 = w6 * w0
    w8 = 0.5 * w1
    w9 = w6 * w1
    w10 = 0.3333333333333333 * w0
    w6 = w6 * w2
    w0 = 0.6666666666666666 * w0
    w11 = 2.0 * w2
    w12 = 0.25 * (((w7 * w0) + (w9 * w1)) + (w6 * w11))
    r0[0] = w3 + ((((w7 * w8) - (w9 * w10)) - (w6 * w12)) - w11)
    r0[1] = w4 + ((((w6 * w10) - w1) - (w9 * w12)) - (w7 * w2))
    r0[2] = w5 + ((w9 * w2) - ((w0 + (w6 * w8)) + (w7 * w12)))
    return [r0]


def residual(z, g, p, h):
    """residual(z[3], g[9], p[3], h[1]) -> [F[3]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "residual: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "residual: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (3,):
        p = p.tolist()
    else:
        p = _vec(p, 3, "residual: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "residual: h")
    _r = _raw_residual(z, g, p, h)
    return [_fromiter(_r[0], _F64, 3)]


def _raw_jacobian(z, g, p, h):
    """jacobian on lists of Python floats -> [J[9]] as lists (see RAW)"""
    w2, w1, w0 = z
    w3, = h
    r0 = [0.0] * 9
    w4 = w3 * w0
    w5 = 0.6666666666666666 * w0
    w6 = w3 * w1
    w7 = w3 * w2
    w2 = 2.0 * w2
    w8 = (0.25 * (((w4 * w5) + (w6 * w1)) + (w7 * w2))) * w3
    w2 = 0.25 * ((w2 * w3) + (2.0 * w7))
    r0[0] = (-2.0) - (w8 + (w7 * w2))
    w0 = (0.3333333333333333 * w0) * w3
    r0[1] = (w0 - (w6 * w2)) - w4
    w1 = (0.5 * w1) * w3
    r0[2] = w6 - (w1 + (w4 * w2))
    w2 = 0.5 * w6
    r0[3] = ((0.5 * w4) - w0) - (w7 * w2)
    r0[4] = (-1.0) - (w8 + (w6 * w2))
    r0[5] = w7 - ((0.5 * w7) + (w4 * w2))
    w0 = 0.25 * ((w5 * w3) + (0.6666666666666666 * w4))
    r0[6] = (w1 - (0.3333333333333333 * w6)) - (w7 * w0)
    r0[7] = ((0.3333333333333333 * w7) - (w6 * w0)) - w7
    r0[8] = -(0.6666666666666666 + (w8 + (w4 * w0)))
    return [r0]


def jacobian(z, g, p, h):
    """jacobian(z[3], g[9], p[3], h[1]) -> [J[9]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "jacobian: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "jacobian: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (3,):
        p = p.tolist()
    else:
        p = _vec(p, 3, "jacobian: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "jacobian: h")
    _r = _raw_jacobian(z, g, p, h)
    return [_fromiter(_r[0], _F64, 9)]


def _raw_residual_jacobian(z, g, p, h):
    """residual_jacobian on lists of Python floats -> [F[3], J[9]] as lists (see RAW)"""
    w2, w1, w0 = z
    w3, w4, w5 = p
    w6, = h
    r0 = [0.0] * 3
    r1 = [0.0] * 9
    w7 = w6 * w0
    w8 = 0.5 * w1
    w9 = w6 * w1
    w10 = 0.3333333333333333 * w0
    w11 = w6 * w2
    w0 = 0.6666666666666666 * w0
    w12 = 2.0 * w2
    w13 = 0.25 * (((w7 * w0) + (w9 * w1)) + (w11 * w12))
    r0[0] = w3 + ((((w7 * w8) - (w9 * w10)) - (w11 * w13)) - w12)
    r0[1] = w4 + ((((w11 * w10) - w1) - (w9 * w13)) - (w7 * w2))
    r0[2] = w5 + ((w9 * w2) - ((w0 + (w11 * w8)) + (w7 * w13)))
    w1 = w13 * w6
    w2 = 0.25 * ((w12 * w6) + (2.0 * w11))
    r1[0] = (-2.0) - (w1 + (w11 * w2))
    w3 = w10 * w6
    r1[1] = (w3 - (w9 * w2)) - w7
    w4 = w8 * w6
    r1[2] = w9 - (w4 + (w7 * w2))
    w2 = 0.5 * w9
    r1[3] = ((0.5 * w7) - w3) - (w11 * w2)
    r1[4] = (-1.0) - (w1 + (w9 * w2))
    r1[5] = w11 - ((0.5 * w11) + (w7 * w2))
    w0 = 0.25 * ((w0 * w6) + (0.6666666666666666 * w7))
    r1[6] = (w4 - (0.3333333333333333 * w9)) - (w11 * w0)
    r1[7] = ((0.3333333333333333 * w11) - (w9 * w0)) - w11
    r1[8] = -(0.6666666666666666 + (w1 + (w7 * w0)))
    return [r0, r1]


def residual_jacobian(z, g, p, h):
    """residual_jacobian(z[3], g[9], p[3], h[1]) -> [F[3], J[9]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "residual_jacobian: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "residual_jacobian: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (3,):
        p = p.tolist()
    else:
        p = _vec(p, 3, "residual_jacobian: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "residual_jacobian: h")
    _r = _raw_residual_jacobian(z, g, p, h)
    return [_fromiter(_r[0], _F64, 3), _fromiter(_r[1], _F64, 9)]


def _raw_update(z, g, p, h):
    """update on lists of Python floats -> [g1[9], p1[3]] as lists (see RAW)"""
    try:
        w0, w1, w2 = z
        w3, w6, w9, w4, w7, w10, w5, w8, w11 = g
        w12, = h
        r0 = [0.0] * 9
        r1 = [0.0] * 3
        w13 = w12 * w0
        w14 = w13 * w13
        w15 = w12 * w1
        w16 = w15 * w15
        w17 = w14 + w16
        w12 = w12 * w2
        w18 = w12 * w12
        w19 = 4.0 / (4.0 + (w17 + w18))
        w16 = 1.0 - (w19 * ((w18 + w16) * 0.5))
        w20 = (w13 * w15) * 0.5
        w21 = w19 * (w12 + w20)
        w22 = (w13 * w12) * 0.5
        w23 = w19 * (w22 - w15)
        r0[0] = ((w3 * w16) + (w4 * w21)) + (w5 * w23)
        r0[1] = ((w6 * w16) + (w7 * w21)) + (w8 * w23)
        r0[2] = ((w9 * w16) + (w10 * w21)) + (w11 * w23)
        w16 = w19 * (w20 - w12)
        w14 = 1.0 - (w19 * ((w18 + w14) * 0.5))
        w18 = (w15 * w12) * 0.5
        w20 = w19 * (w13 + w18)
        r0[3] = ((w3 * w16) + (w4 * w14)) + (w5 * w20)
        r0[4] = ((w6 * w16) + (w7 * w14)) + (w8 * w20)
        r0[5] = ((w9 * w16) + (w10 * w14)) + (w11 * w20)
        w14 = w19 * (w15 + w22)
        w16 = w19 * (w18 - w13)
        w17 = 1.0 - (w19 * (w17 * 0.5))
        r0[6] = ((w3 * w14) + (w4 * w16)) + (w5 * w17)
        r0[7] = ((w6 * w14) + (w7 * w16)) + (w8 * w17)
        r0[8] = ((w9 * w14) + (w10 * w16)) + (w11 * w17)
        w3 = 0.5 * w1
        w4 = 0.3333333333333333 * w2
        w2 = 0.6666666666666666 * w2
        w5 = 2.0 * w0
        w6 = 0.25 * (((w12 * w2) + (w15 * w1)) + (w13 * w5))
        r1[0] = (((w12 * w3) - (w15 * w4)) + (w13 * w6)) + w5
        r1[1] = (((w13 * w4) + w1) + (w15 * w6)) - (w12 * w0)
        r1[2] = ((w2 - (w13 * w3)) + (w12 * w6)) + (w15 * w0)
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 9
        r1 = [0.0] * 3
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
        w3 = w3 * w11
        w12 = w3 * w3
        w10 = w10 + w12
        w10 = w2 + w10
        w2 = w2 / w10 if w10 else _div(w2, w10)
        w10 = w12 + w9
        w13 = 2.0
        w10 = w10 / w13 if w13 else _div(w10, w13)
        w10 = w2 * w10
        w10 = w1 - w10
        w14 = w0 * w10
        w15 = g[3]
        w16 = w5 * w8
        w16 = w16 / w13 if w13 else _div(w16, w13)
        w16 = w3 + w16
        w16 = w2 * w16
        w17 = w15 * w16
        w14 = w14 + w17
        w17 = g[6]
        w18 = w5 * w3
        w18 = w18 / w13 if w13 else _div(w18, w13)
        w18 = w18 - w8
        w18 = w2 * w18
        w19 = w17 * w18
        w14 = w14 + w19
        r0[0] = w14
        w14 = g[1]
        w19 = w14 * w10
        w20 = g[4]
        w21 = w20 * w16
        w19 = w19 + w21
        w21 = g[7]
        w22 = w21 * w18
        w19 = w19 + w22
        r0[1] = w19
        w19 = g[2]
        w10 = w19 * w10
        w22 = g[5]
        w16 = w22 * w16
        w10 = w10 + w16
        w16 = g[8]
        w18 = w16 * w18
        w10 = w10 + w18
        r0[2] = w10
        w10 = w8 * w5
        w10 = w10 / w13 if w13 else _div(w10, w13)
        w10 = w10 - w3
        w10 = w2 * w10
        w18 = w0 * w10
        w12 = w12 + w6
        w12 = w12 / w13 if w13 else _div(w12, w13)
        w12 = w2 * w12
        w12 = w1 - w12
        w23 = w15 * w12
        w18 = w18 + w23
        w23 = w8 * w3
        w23 = w23 / w13 if w13 else _div(w23, w13)
        w23 = w5 + w23
        w23 = w2 * w23
        w24 = w17 * w23
        w18 = w18 + w24
        r0[3] = w18
        w18 = w14 * w10
        w24 = w20 * w12
        w18 = w18 + w24
        w24 = w21 * w23
        w18 = w18 + w24
        r0[4] = w18
        w10 = w19 * w10
        w12 = w22 * w12
        w10 = w10 + w12
        w23 = w16 * w23
        w10 = w10 + w23
        r0[5] = w10
        w10 = w3 * w5
        w10 = w10 / w13 if w13 else _div(w10, w13)
        w10 = w8 + w10
        w10 = w2 * w10
        w0 = w0 * w10
        w23 = w3 * w8
        w23 = w23 / w13 if w13 else _div(w23, w13)
        w23 = w23 - w5
        w23 = w2 * w23
        w15 = w15 * w23
        w0 = w0 + w15
        w9 = w9 + w6
        w9 = w9 / w13 if w13 else _div(w9, w13)
        w2 = w2 * w9
        w1 = w1 - w2
        w17 = w17 * w1
        w0 = w0 + w17
        r0[6] = w0
        w14 = w14 * w10
        w20 = w20 * w23
        w14 = w14 + w20
        w21 = w21 * w1
        w14 = w14 + w21
        r0[7] = w14
        w19 = w19 * w10
        w22 = w22 * w23
        w19 = w19 + w22
        w16 = w16 * w1
        w19 = w19 + w16
        r0[8] = w19
        w19 = 0.5
        w19 = w19 * w7
        w16 = w3 * w19
        w1 = 0.3333333333333333
        w1 = w1 * w11
        w22 = w8 * w1
        w16 = w16 - w22
        w22 = 0.25
        w23 = 0.6666666666666666
        w23 = w23 * w11
        w11 = w3 * w23
        w10 = w8 * w7
        w11 = w11 + w10
        w10 = 2.0 * w4
        w14 = w5 * w10
        w11 = w11 + w14
        w22 = w22 * w11
        w11 = w5 * w22
        w16 = w16 + w11
        w16 = w16 + w10
        r1[0] = w16
        w1 = w5 * w1
        w1 = w1 + w7
        w7 = w8 * w22
        w1 = w1 + w7
        w7 = w3 * w4
        w1 = w1 - w7
        r1[1] = w1
        w5 = w5 * w19
        w23 = w23 - w5
        w3 = w3 * w22
        w23 = w23 + w3
        w8 = w8 * w4
        w23 = w23 + w8
        r1[2] = w23
    return [r0, r1]


def update(z, g, p, h):
    """update(z[3], g[9], p[3], h[1]) -> [g1[9], p1[3]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "update: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "update: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (3,):
        p = p.tolist()
    else:
        p = _vec(p, 3, "update: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "update: h")
    _r = _raw_update(z, g, p, h)
    return [_fromiter(_r[0], _F64, 9), _fromiter(_r[1], _F64, 3)]


def _raw_guess(xi, g, p, h):
    """guess on lists of Python floats -> [z0[3]] as lists (see RAW)"""
    w0, w1, w2 = xi
    r0 = [0.0] * 3
    r0[0] = w0
    r0[1] = w1
    r0[2] = w2
    return [r0]


def guess(xi, g, p, h):
    """guess(xi[3], g[9], p[3], h[1]) -> [z0[3]]"""
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (3,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 3, "guess: xi")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "guess: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (3,):
        p = p.tolist()
    else:
        p = _vec(p, 3, "guess: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "guess: h")
    _r = _raw_guess(xi, g, p, h)
    return [_fromiter(_r[0], _F64, 3)]


def _raw_legendre(g, xi):
    """legendre on lists of Python floats -> [mu[3]] as lists (see RAW)"""
    w0, w1, w2 = xi
    r0 = [0.0] * 3
    r0[0] = 2.0 * w0
    r0[1] = w1
    r0[2] = 0.6666666666666666 * w2
    return [r0]


def legendre(g, xi):
    """legendre(g[9], xi[3]) -> [mu[3]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "legendre: g")
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (3,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 3, "legendre: xi")
    _r = _raw_legendre(g, xi)
    return [_fromiter(_r[0], _F64, 3)]


def _raw_hessian(g, xi):
    """hessian on lists of Python floats -> [H[9]] as lists (see RAW)"""
    r0 = [0.0] * 9
    r0[0] = 2.0
    r0[1] = 0.0
    r0[2] = 0.0
    r0[3] = 0.0
    r0[4] = 1.0
    r0[5] = 0.0
    r0[6] = 0.0
    r0[7] = 0.0
    r0[8] = 0.6666666666666666
    return [r0]


def hessian(g, xi):
    """hessian(g[9], xi[3]) -> [H[9]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "hessian: g")
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (3,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 3, "hessian: xi")
    _r = _raw_hessian(g, xi)
    return [_fromiter(_r[0], _F64, 9)]


def _raw_energy(g, xi):
    """energy on lists of Python floats -> [E[1]] as lists (see RAW)"""
    w0, w1, w2 = xi
    r0 = [0.0] * 1
    w1 = w1 * w1
    r0[0] = ((((2.0 * w0) * w0) + w1) + ((0.6666666666666666 * w2) * w2)) - (((0.5 * w1) + (w0 * w0)) + (0.3333333333333333 * (w2 * w2)))
    return [r0]


def energy(g, xi):
    """energy(g[9], xi[3]) -> [E[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "energy: g")
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (3,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 3, "energy: xi")
    _r = _raw_energy(g, xi)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_momentum(g, p):
    """momentum on lists of Python floats -> [m[3]] as lists (see RAW)"""
    w8, w5, w4, w7, w1, w3, w6, w2, w0 = g
    w9, w10, w11 = p
    r0 = [0.0] * 3
    r0[0] = ((((w0 * w1) - (w2 * w3)) * w9) + (((w4 * w2) - (w5 * w0)) * w10)) + (((w3 * w5) - (w1 * w4)) * w11)
    r0[1] = ((((w6 * w3) - (w0 * w7)) * w9) + (((w8 * w0) - (w4 * w6)) * w10)) + (((w7 * w4) - (w3 * w8)) * w11)
    r0[2] = ((((w2 * w7) - (w6 * w1)) * w9) + (((w5 * w6) - (w8 * w2)) * w10)) + (((w1 * w8) - (w7 * w5)) * w11)
    return [r0]


def momentum(g, p):
    """momentum(g[9], p[3]) -> [m[3]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "momentum: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (3,):
        p = p.tolist()
    else:
        p = _vec(p, 3, "momentum: p")
    _r = _raw_momentum(g, p)
    return [_fromiter(_r[0], _F64, 3)]


def _raw_defect(g):
    """defect on lists of Python floats -> [e[1]] as lists (see RAW)"""
    w0, w1, w2, w3, w4, w5, w6, w7, w8 = g
    r0 = [0.0] * 1
    w9 = _f_fabs((((w3 * w0) + (w4 * w1)) + (w5 * w2)))
    w10 = _f_fabs((((w6 * w0) + (w7 * w1)) + (w8 * w2)))
    w11 = _f_fabs((((w6 * w3) + (w7 * w4)) + (w8 * w5)))
    r0[0] = _fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_f_fabs(((((w0 * w0) + (w1 * w1)) + (w2 * w2)) - 1.0))), w9)), w10)), w9)), (_f_fabs(((((w3 * w3) + (w4 * w4)) + (w5 * w5)) - 1.0))))), w11)), w10)), w11)), (_f_fabs(((((w6 * w6) + (w7 * w7)) + (w8 * w8)) - 1.0))))), (_f_fabs(((((w0 * ((w4 * w8) - (w7 * w5))) - (w3 * ((w1 * w8) - (w7 * w2)))) + (w6 * ((w1 * w5) - (w4 * w2)))) - 1.0))))
    return [r0]


def defect(g):
    """defect(g[9]) -> [e[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "defect: g")
    _r = _raw_defect(g)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_margin(z, h):
    """margin on lists of Python floats -> [m[1]] as lists (see RAW)"""
    w0, w1, w2 = z
    w3, = h
    r0 = [0.0] * 1
    w0 = w3 * w0
    w1 = w3 * w1
    w2 = w3 * w2
    w0 = 4.0 - (((w0 * w0) + (w1 * w1)) + (w2 * w2))
    r0[0] = _fmin((_fmin((_fmin((_fmin(1.0, w0)), w0)), w0)), w0)
    return [r0]


def margin(z, h):
    """margin(z[3], h[1]) -> [m[1]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "margin: z")
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
    """section(g[9], p[3]) -> [s[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "section: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (3,):
        p = p.tolist()
    else:
        p = _vec(p, 3, "section: p")
    _r = _raw_section(g, p)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_chart_point(z, g, h, theta):
    """chart_point on lists of Python floats -> [g_theta[9]] as lists (see RAW)"""
    try:
        w0, w1, w2 = z
        w3, w6, w9, w4, w7, w10, w5, w8, w11 = g
        w12, = h
        w13, = theta
        r0 = [0.0] * 9
        w0 = w13 * (w12 * w0)
        w14 = w0 * w0
        w1 = w13 * (w12 * w1)
        w15 = w1 * w1
        w16 = w14 + w15
        w2 = w13 * (w12 * w2)
        w12 = w2 * w2
        w13 = 4.0 / (4.0 + (w16 + w12))
        w15 = 1.0 - (w13 * ((w12 + w15) * 0.5))
        w17 = (w0 * w1) * 0.5
        w18 = w13 * (w2 + w17)
        w19 = (w0 * w2) * 0.5
        w20 = w13 * (w19 - w1)
        r0[0] = ((w3 * w15) + (w4 * w18)) + (w5 * w20)
        r0[1] = ((w6 * w15) + (w7 * w18)) + (w8 * w20)
        r0[2] = ((w9 * w15) + (w10 * w18)) + (w11 * w20)
        w15 = w13 * (w17 - w2)
        w12 = 1.0 - (w13 * ((w12 + w14) * 0.5))
        w2 = (w1 * w2) * 0.5
        w14 = w13 * (w0 + w2)
        r0[3] = ((w3 * w15) + (w4 * w12)) + (w5 * w14)
        r0[4] = ((w6 * w15) + (w7 * w12)) + (w8 * w14)
        r0[5] = ((w9 * w15) + (w10 * w12)) + (w11 * w14)
        w1 = w13 * (w1 + w19)
        w0 = w13 * (w2 - w0)
        w2 = 1.0 - (w13 * (w16 * 0.5))
        r0[6] = ((w3 * w1) + (w4 * w0)) + (w5 * w2)
        r0[7] = ((w6 * w1) + (w7 * w0)) + (w8 * w2)
        r0[8] = ((w9 * w1) + (w10 * w0)) + (w11 * w2)
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 9
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
        w4 = w4 * w10
        w3 = w3 * w4
        w4 = w3 * w3
        w9 = w9 + w4
        w9 = w2 + w9
        w2 = w2 / w9 if w9 else _div(w2, w9)
        w9 = w4 + w8
        w10 = 2.0
        w9 = w9 / w10 if w10 else _div(w9, w10)
        w9 = w2 * w9
        w9 = w1 - w9
        w11 = w0 * w9
        w12 = g[3]
        w13 = w5 * w7
        w13 = w13 / w10 if w10 else _div(w13, w10)
        w13 = w3 + w13
        w13 = w2 * w13
        w14 = w12 * w13
        w11 = w11 + w14
        w14 = g[6]
        w15 = w5 * w3
        w15 = w15 / w10 if w10 else _div(w15, w10)
        w15 = w15 - w7
        w15 = w2 * w15
        w16 = w14 * w15
        w11 = w11 + w16
        r0[0] = w11
        w11 = g[1]
        w16 = w11 * w9
        w17 = g[4]
        w18 = w17 * w13
        w16 = w16 + w18
        w18 = g[7]
        w19 = w18 * w15
        w16 = w16 + w19
        r0[1] = w16
        w16 = g[2]
        w9 = w16 * w9
        w19 = g[5]
        w13 = w19 * w13
        w9 = w9 + w13
        w13 = g[8]
        w15 = w13 * w15
        w9 = w9 + w15
        r0[2] = w9
        w9 = w7 * w5
        w9 = w9 / w10 if w10 else _div(w9, w10)
        w9 = w9 - w3
        w9 = w2 * w9
        w15 = w0 * w9
        w4 = w4 + w6
        w4 = w4 / w10 if w10 else _div(w4, w10)
        w4 = w2 * w4
        w4 = w1 - w4
        w20 = w12 * w4
        w15 = w15 + w20
        w20 = w7 * w3
        w20 = w20 / w10 if w10 else _div(w20, w10)
        w20 = w5 + w20
        w20 = w2 * w20
        w21 = w14 * w20
        w15 = w15 + w21
        r0[3] = w15
        w15 = w11 * w9
        w21 = w17 * w4
        w15 = w15 + w21
        w21 = w18 * w20
        w15 = w15 + w21
        r0[4] = w15
        w9 = w16 * w9
        w4 = w19 * w4
        w9 = w9 + w4
        w20 = w13 * w20
        w9 = w9 + w20
        r0[5] = w9
        w9 = w3 * w5
        w9 = w9 / w10 if w10 else _div(w9, w10)
        w9 = w7 + w9
        w9 = w2 * w9
        w0 = w0 * w9
        w3 = w3 * w7
        w3 = w3 / w10 if w10 else _div(w3, w10)
        w3 = w3 - w5
        w3 = w2 * w3
        w12 = w12 * w3
        w0 = w0 + w12
        w8 = w8 + w6
        w8 = w8 / w10 if w10 else _div(w8, w10)
        w2 = w2 * w8
        w1 = w1 - w2
        w14 = w14 * w1
        w0 = w0 + w14
        r0[6] = w0
        w11 = w11 * w9
        w17 = w17 * w3
        w11 = w11 + w17
        w18 = w18 * w1
        w11 = w11 + w18
        r0[7] = w11
        w16 = w16 * w9
        w19 = w19 * w3
        w16 = w16 + w19
        w13 = w13 * w1
        w16 = w16 + w13
        r0[8] = w16
    return [r0]


def chart_point(z, g, h, theta):
    """chart_point(z[3], g[9], h[1], theta[1]) -> [g_theta[9]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "chart_point: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "chart_point: g")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "chart_point: h")
    if _type(theta) is _NDARRAY and theta.dtype is _F64 and theta.shape == (1,):
        theta = theta.tolist()
    else:
        theta = _vec(theta, 1, "chart_point: theta")
    _r = _raw_chart_point(z, g, h, theta)
    return [_fromiter(_r[0], _F64, 9)]


def _raw_observe(g, p):
    """observe on lists of Python floats -> [xi[3], E[1], m[3], e[1]] as lists (see RAW)"""
    try:
        w8, w5, w4, w7, w1, w3, w6, w2, w0 = g
        w9, w10, w11 = p
        r0 = [0.0] * 3
        r1 = [0.0] * 1
        r2 = [0.0] * 3
        r3 = [0.0] * 1
        w12 = w9 * 0.5
        r0[0] = w12
        r0[1] = w10
        w13 = w11 / 0.6666666666666666
        r0[2] = w13
        w14 = w10 * w10
        r1[0] = (((w9 * w12) + w14) + (w11 * w13)) - (((0.5 * w14) + (w12 * w12)) + (0.3333333333333333 * (w13 * w13)))
        w12 = (w0 * w1) - (w2 * w3)
        w13 = w4 * w2
        w14 = w5 * w0
        w15 = (w3 * w5) - (w1 * w4)
        r2[0] = ((w12 * w9) + ((w13 - w14) * w10)) + (w15 * w11)
        r2[1] = ((((w6 * w3) - (w0 * w7)) * w9) + (((w8 * w0) - (w4 * w6)) * w10)) + (((w7 * w4) - (w3 * w8)) * w11)
        r2[2] = ((((w2 * w7) - (w6 * w1)) * w9) + (((w5 * w6) - (w8 * w2)) * w10)) + (((w1 * w8) - (w7 * w5)) * w11)
        w9 = _f_fabs((((w7 * w8) + (w1 * w5)) + (w3 * w4)))
        w10 = _f_fabs((((w6 * w8) + (w2 * w5)) + (w0 * w4)))
        w11 = _f_fabs((((w6 * w7) + (w2 * w1)) + (w0 * w3)))
        r3[0] = _fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_fmax((_f_fabs(((((w8 * w8) + (w5 * w5)) + (w4 * w4)) - 1.0))), w9)), w10)), w9)), (_f_fabs(((((w7 * w7) + (w1 * w1)) + (w3 * w3)) - 1.0))))), w11)), w10)), w11)), (_f_fabs(((((w6 * w6) + (w2 * w2)) + (w0 * w0)) - 1.0))))), (_f_fabs(((((w8 * w12) - (w7 * (w14 - w13))) + (w6 * w15)) - 1.0))))
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 3
        r1 = [0.0] * 1
        r2 = [0.0] * 3
        r3 = [0.0] * 1
        w0 = p[0]
        w1 = 2.0
        w1 = w0 / w1 if w1 else _div(w0, w1)
        r0[0] = w1
        w2 = p[1]
        r0[1] = w2
        w3 = p[2]
        w4 = 0.6666666666666666
        w4 = w3 / w4 if w4 else _div(w3, w4)
        r0[2] = w4
        w5 = w0 * w1
        w6 = w2 * w2
        w5 = w5 + w6
        w7 = w3 * w4
        w5 = w5 + w7
        w7 = 0.5
        w7 = w7 * w6
        w1 = w1 * w1
        w7 = w7 + w1
        w1 = 0.3333333333333333
        w4 = w4 * w4
        w1 = w1 * w4
        w7 = w7 + w1
        w5 = w5 - w7
        r1[0] = w5
        w5 = g[8]
        w7 = g[4]
        w1 = w5 * w7
        w4 = g[7]
        w6 = g[5]
        w8 = w4 * w6
        w1 = w1 - w8
        w1 = w1 * w0
        w9 = g[2]
        w10 = w9 * w4
        w11 = g[1]
        w12 = w11 * w5
        w10 = w10 - w12
        w10 = w10 * w2
        w1 = w1 + w10
        w10 = w6 * w11
        w13 = w7 * w9
        w10 = w10 - w13
        w10 = w10 * w3
        w1 = w1 + w10
        r2[0] = w1
        w1 = g[6]
        w10 = w1 * w6
        w14 = g[3]
        w15 = w5 * w14
        w10 = w10 - w15
        w10 = w10 * w0
        w15 = g[0]
        w16 = w15 * w5
        w17 = w9 * w1
        w16 = w16 - w17
        w16 = w16 * w2
        w10 = w10 + w16
        w16 = w14 * w9
        w17 = w6 * w15
        w16 = w16 - w17
        w16 = w16 * w3
        w10 = w10 + w16
        r2[1] = w10
        w10 = w4 * w14
        w16 = w1 * w7
        w10 = w10 - w16
        w10 = w10 * w0
        w0 = w11 * w1
        w16 = w15 * w4
        w0 = w0 - w16
        w0 = w0 * w2
        w10 = w10 + w0
        w0 = w7 * w15
        w2 = w14 * w11
        w0 = w0 - w2
        w0 = w0 * w3
        w10 = w10 + w0
        r2[2] = w10
        w10 = w15 * w15
        w0 = w11 * w11
        w10 = w10 + w0
        w0 = w9 * w9
        w10 = w10 + w0
        w0 = 1.0
        w10 = w10 - w0
        w10 = math.fabs(w10)
        w3 = w14 * w15
        w2 = w7 * w11
        w3 = w3 + w2
        w2 = w6 * w9
        w3 = w3 + w2
        w3 = math.fabs(w3)
        w10 = _fmax(w10, w3)
        w3 = w1 * w15
        w2 = w4 * w11
        w3 = w3 + w2
        w2 = w5 * w9
        w3 = w3 + w2
        w3 = math.fabs(w3)
        w10 = _fmax(w10, w3)
        w3 = w15 * w14
        w2 = w11 * w7
        w3 = w3 + w2
        w2 = w9 * w6
        w3 = w3 + w2
        w3 = math.fabs(w3)
        w10 = _fmax(w10, w3)
        w3 = w14 * w14
        w2 = w7 * w7
        w3 = w3 + w2
        w2 = w6 * w6
        w3 = w3 + w2
        w3 = w3 - w0
        w3 = math.fabs(w3)
        w10 = _fmax(w10, w3)
        w3 = w1 * w14
        w2 = w4 * w7
        w3 = w3 + w2
        w2 = w5 * w6
        w3 = w3 + w2
        w3 = math.fabs(w3)
        w10 = _fmax(w10, w3)
        w3 = w15 * w1
        w2 = w11 * w4
        w3 = w3 + w2
        w2 = w9 * w5
        w3 = w3 + w2
        w3 = math.fabs(w3)
        w10 = _fmax(w10, w3)
        w3 = w14 * w1
        w2 = w7 * w4
        w3 = w3 + w2
        w2 = w6 * w5
        w3 = w3 + w2
        w3 = math.fabs(w3)
        w10 = _fmax(w10, w3)
        w3 = w1 * w1
        w2 = w4 * w4
        w3 = w3 + w2
        w2 = w5 * w5
        w3 = w3 + w2
        w3 = w3 - w0
        w3 = math.fabs(w3)
        w10 = _fmax(w10, w3)
        w7 = w7 * w5
        w7 = w7 - w8
        w15 = w15 * w7
        w4 = w4 * w9
        w12 = w12 - w4
        w14 = w14 * w12
        w15 = w15 - w14
        w11 = w11 * w6
        w11 = w11 - w13
        w1 = w1 * w11
        w15 = w15 + w1
        w15 = w15 - w0
        w15 = math.fabs(w15)
        w10 = _fmax(w10, w15)
        r3[0] = w10
    return [r0, r1, r2, r3]


def observe(g, p):
    """observe(g[9], p[3]) -> [xi[3], E[1], m[3], e[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "observe: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (3,):
        p = p.tolist()
    else:
        p = _vec(p, 3, "observe: p")
    _r = _raw_observe(g, p)
    return [_fromiter(_r[0], _F64, 3), _fromiter(_r[1], _F64, 1), _fromiter(_r[2], _F64, 3), _fromiter(_r[3], _F64, 1)]


def _raw_update_p(z, g, p, h):
    """update_p on lists of Python floats -> [p1[3]] as lists (see RAW)"""
    w2, w1, w0 = z
    w3, = h
    r0 = [0.0] * 3
    w4 = w3 * w0
    w5 = 0.5 * w1
    w6 = w3 * w1
    w7 = 0.3333333333333333 * w0
    w3 = w3 * w2
    w0 = 0.6666666666666666 * w0
    w8 = 2.0 * w2
    w9 = 0.25 * (((w4 * w0) + (w6 * w1)) + (w3 * w8))
    r0[0] = (((w4 * w5) - (w6 * w7)) + (w3 * w9)) + w8
    r0[1] = (((w3 * w7) + w1) + (w6 * w9)) - (w4 * w2)
    r0[2] = ((w0 - (w3 * w5)) + (w4 * w9)) + (w6 * w2)
    return [r0]


def update_p(z, g, p, h):
    """update_p(z[3], g[9], p[3], h[1]) -> [p1[3]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "update_p: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "update_p: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (3,):
        p = p.tolist()
    else:
        p = _vec(p, 3, "update_p: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "update_p: h")
    _r = _raw_update_p(z, g, p, h)
    return [_fromiter(_r[0], _F64, 3)]


def _raw_velocity_step(g, p, xi):
    """velocity_step on lists of Python floats -> [xi1[3]] as lists (see RAW)"""
    try:
        w0, w1, w2 = p
        w3, w4, w5 = xi
        r0 = [0.0] * 3
        r0[0] = w3 - (((2.0 * w3) - w0) * 0.5)
        r0[1] = w4 - (w4 - w1)
        r0[2] = w5 - (((0.6666666666666666 * w5) - w2) / 0.6666666666666666)
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 3
        w0 = xi[0]
        w1 = 2.0 * w0
        w2 = p[0]
        w1 = w1 - w2
        w2 = 2.0
        w1 = w1 / w2 if w2 else _div(w1, w2)
        w0 = w0 - w1
        r0[0] = w0
        w0 = xi[1]
        w1 = p[1]
        w1 = w0 - w1
        w0 = w0 - w1
        r0[1] = w0
        w0 = xi[2]
        w1 = 0.6666666666666666
        w2 = w1 * w0
        w3 = p[2]
        w2 = w2 - w3
        w2 = w2 / w1 if w1 else _div(w2, w1)
        w0 = w0 - w2
        r0[2] = w0
    return [r0]


def velocity_step(g, p, xi):
    """velocity_step(g[9], p[3], xi[3]) -> [xi1[3]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "velocity_step: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (3,):
        p = p.tolist()
    else:
        p = _vec(p, 3, "velocity_step: p")
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (3,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 3, "velocity_step: xi")
    _r = _raw_velocity_step(g, p, xi)
    return [_fromiter(_r[0], _F64, 3)]


def _raw_record(g, p, xi):
    """record on lists of Python floats -> [row[16]] as lists (see RAW)"""
    w0, w1, w2, w3, w4, w5, w6, w7, w8 = g
    w9, w10, w11 = p
    w12, w13, w14 = xi
    r0 = [0.0] * 16
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
    w13 = w13 * w13
    r0[12] = ((((2.0 * w12) * w12) + w13) + ((0.6666666666666666 * w14) * w14)) - (((0.5 * w13) + (w12 * w12)) + (0.3333333333333333 * (w14 * w14)))
    r0[13] = ((((w8 * w4) - (w7 * w5)) * w9) + (((w2 * w7) - (w1 * w8)) * w10)) + (((w5 * w1) - (w4 * w2)) * w11)
    r0[14] = ((((w6 * w5) - (w8 * w3)) * w9) + (((w0 * w8) - (w2 * w6)) * w10)) + (((w3 * w2) - (w5 * w0)) * w11)
    r0[15] = ((((w7 * w3) - (w6 * w4)) * w9) + (((w1 * w6) - (w0 * w7)) * w10)) + (((w4 * w0) - (w3 * w1)) * w11)
    return [r0]


def record(g, p, xi):
    """record(g[9], p[3], xi[3]) -> [row[16]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "record: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (3,):
        p = p.tolist()
    else:
        p = _vec(p, 3, "record: p")
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (3,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 3, "record: xi")
    _r = _raw_record(g, p, xi)
    return [_fromiter(_r[0], _F64, 16)]


def _raw_step_partials(z, g, p, h):
    """step_partials on lists of Python floats -> [Fs[18], Yz[18], Ys[36]] as lists (see RAW)"""
    try:
        w0, w1, w2 = z
        w3, w6, w9, w4, w7, w10, w5, w8, w11 = g
        w12, = h
        r0 = [0.0] * 18
        r1 = [0.0] * 18
        r2 = [0.0] * 36
        r0[0] = 0.0
        r0[1] = 0.0
        r0[2] = 0.0
        r0[3] = 0.0
        r0[4] = 0.0
        r0[5] = 0.0
        r0[6] = 0.0
        r0[7] = 0.0
        r0[8] = 0.0
        r0[9] = 1.0
        r0[10] = 0.0
        r0[11] = 0.0
        r0[12] = 0.0
        r0[13] = 1.0
        r0[14] = 0.0
        r0[15] = 0.0
        r0[16] = 0.0
        r0[17] = 1.0
        w13 = w12 * w0
        w14 = w13 * w13
        w15 = w12 * w1
        w16 = w15 * w15
        w17 = w14 + w16
        w18 = w12 * w2
        w19 = w18 * w18
        w20 = 4.0 + (w17 + w19)
        w21 = 4.0 / w20
        w22 = (w18 * w13) * 0.5
        w23 = w15 + w22
        w24 = w21 * w23
        w25 = (w18 * w15) * 0.5
        w26 = w25 - w13
        w27 = w21 * w26
        w17 = w17 * 0.5
        w28 = 1.0 - (w21 * w17)
        w29 = ((w3 * w24) + (w4 * w27)) + (w5 * w28)
        w30 = w21 * (0.5 * (w15 * w12))
        w31 = (w15 * w13) * 0.5
        w32 = w31 - w18
        w20 = w21 / w20
        w33 = 2.0 * w13
        w34 = w33 * w12
        w35 = w20 * w34
        w36 = w30 - (w32 * w35)
        w34 = w21 * (0.5 * w34)
        w14 = (w19 + w14) * 0.5
        w37 = w34 - (w14 * w35)
        w38 = w21 * w12
        w25 = w13 + w25
        w39 = w38 - (w25 * w35)
        w40 = ((w6 * w24) + (w7 * w27)) + (w8 * w28)
        w41 = ((w9 * w24) + (w10 * w27)) + (w11 * w28)
        r1[0] = ((w29 * (((w3 * w36) - (w4 * w37)) + (w5 * w39))) + (w40 * (((w6 * w36) - (w7 * w37)) + (w8 * w39)))) + (w41 * (((w9 * w36) - (w10 * w37)) + (w11 * w39)))
        w16 = (w19 + w16) * 0.5
        w19 = 1.0 - (w21 * w16)
        w31 = w18 + w31
        w36 = w21 * w31
        w22 = w22 - w15
        w37 = w21 * w22
        w39 = ((w3 * w19) + (w4 * w36)) + (w5 * w37)
        w42 = w21 * (0.5 * (w18 * w12))
        w43 = w42 - (w23 * w35)
        w44 = (w26 * w35) + w38
        w34 = w34 - (w17 * w35)
        w45 = ((w6 * w19) + (w7 * w36)) + (w8 * w37)
        w46 = ((w9 * w19) + (w10 * w36)) + (w11 * w37)
        r1[1] = ((w39 * (((w3 * w43) - (w4 * w44)) - (w5 * w34))) + (w45 * (((w6 * w43) - (w7 * w44)) - (w8 * w34)))) + (w46 * (((w9 * w43) - (w10 * w44)) - (w11 * w34)))
        w34 = w21 * w32
        w43 = 1.0 - (w21 * w14)
        w44 = w21 * w25
        w47 = ((w3 * w34) + (w4 * w43)) + (w5 * w44)
        w48 = w16 * w35
        w49 = w30 - (w31 * w35)
        w35 = w42 - (w22 * w35)
        w50 = ((w6 * w34) + (w7 * w43)) + (w8 * w44)
        w51 = ((w9 * w34) + (w10 * w43)) + (w11 * w44)
        r1[2] = ((w47 * (((w3 * w48) + (w4 * w49)) + (w5 * w35))) + (w50 * (((w6 * w48) + (w7 * w49)) + (w8 * w35)))) + (w51 * (((w9 * w48) + (w10 * w49)) + (w11 * w35)))
        w35 = 0.6666666666666666 * w2
        w0 = 2.0 * w0
        w48 = (0.25 * (((w18 * w35) + (w15 * w1)) + (w13 * w0))) * w12
        w0 = 0.25 * ((w0 * w12) + w33)
        r1[3] = (w48 + (w13 * w0)) + 2.0
        w2 = (0.3333333333333333 * w2) * w12
        r1[4] = (w2 + (w15 * w0)) - w18
        w1 = (0.5 * w1) * w12
        r1[5] = ((w18 * w0) - w1) + w15
        w0 = w21 * (0.5 * (w13 * w12))
        w33 = (2.0 * w15) * w12
        w49 = w20 * w33
        w52 = w0 - (w32 * w49)
        w53 = w14 * w49
        w54 = w42 - (w25 * w49)
        r1[6] = ((w29 * (((w3 * w52) + (w4 * w53)) + (w5 * w54))) + (w40 * (((w6 * w52) + (w7 * w53)) + (w8 * w54)))) + (w41 * (((w9 * w52) + (w10 * w53)) + (w11 * w54)))
        w52 = w38 - (w23 * w49)
        w42 = w42 - (w26 * w49)
        w33 = w21 * (0.5 * w33)
        w53 = w33 - (w17 * w49)
        r1[7] = ((w39 * (((w3 * w52) + (w4 * w42)) - (w5 * w53))) + (w45 * (((w6 * w52) + (w7 * w42)) - (w8 * w53)))) + (w46 * (((w9 * w52) + (w10 * w42)) - (w11 * w53)))
        w42 = w0 - (w31 * w49)
        w33 = w33 - (w16 * w49)
        w49 = (w22 * w49) + w38
        r1[8] = ((w47 * (((w4 * w42) - (w3 * w33)) - (w5 * w49))) + (w50 * (((w7 * w42) - (w6 * w33)) - (w8 * w49)))) + (w51 * (((w10 * w42) - (w9 * w33)) - (w11 * w49)))
        w33 = 0.5 * w15
        r1[9] = ((0.5 * w18) - w2) + (w13 * w33)
        r1[10] = 1.0 + (w48 + (w15 * w33))
        r1[11] = ((w18 * w33) - (0.5 * w13)) + w13
        w2 = (2.0 * w18) * w12
        w20 = w20 * w2
        w25 = w30 - (w25 * w20)
        w32 = (w32 * w20) + w38
        w2 = w21 * (0.5 * w2)
        w14 = w2 - (w14 * w20)
        r1[12] = ((w29 * ((w5 * w25) - ((w3 * w32) + (w4 * w14)))) + (w40 * ((w8 * w25) - ((w6 * w32) + (w7 * w14))))) + (w41 * ((w11 * w25) - ((w9 * w32) + (w10 * w14))))
        w14 = w0 - (w23 * w20)
        w21 = w30 - (w26 * w20)
        w17 = w17 * w20
        r1[13] = ((w39 * (((w3 * w14) + (w4 * w21)) + (w5 * w17))) + (w45 * (((w6 * w14) + (w7 * w21)) + (w8 * w17)))) + (w46 * (((w9 * w14) + (w10 * w21)) + (w11 * w17)))
        w14 = w38 - (w31 * w20)
        w2 = w2 - (w16 * w20)
        w0 = w0 - (w22 * w20)
        r1[14] = ((w47 * (((w4 * w14) - (w3 * w2)) + (w5 * w0))) + (w50 * (((w7 * w14) - (w6 * w2)) + (w8 * w0)))) + (w51 * (((w10 * w14) - (w9 * w2)) + (w11 * w0)))
        w0 = 0.25 * ((w35 * w12) + (0.6666666666666666 * w18))
        r1[15] = (w1 - (0.3333333333333333 * w15)) + (w13 * w0)
        r1[16] = ((0.3333333333333333 * w13) + (w15 * w0)) - w13
        r1[17] = 0.6666666666666666 + (w48 + (w18 * w0))
        r2[0] = ((w29 * ((w43 * w5) - (w44 * w4))) + (w40 * ((w43 * w8) - (w44 * w7)))) + (w41 * ((w43 * w11) - (w44 * w10)))
        r2[1] = ((w39 * ((w27 * w5) - (w28 * w4))) + (w45 * ((w27 * w8) - (w28 * w7)))) + (w46 * ((w27 * w11) - (w28 * w10)))
        r2[2] = ((w47 * ((w36 * w5) - (w37 * w4))) + (w50 * ((w36 * w8) - (w37 * w7)))) + (w51 * ((w36 * w11) - (w37 * w10)))
        r2[3] = 0.0
        r2[4] = 0.0
        r2[5] = 0.0
        r2[6] = ((w29 * ((w44 * w3) - (w34 * w5))) + (w40 * ((w44 * w6) - (w34 * w8)))) + (w41 * ((w44 * w9) - (w34 * w11)))
        r2[7] = ((w39 * ((w28 * w3) - (w24 * w5))) + (w45 * ((w28 * w6) - (w24 * w8)))) + (w46 * ((w28 * w9) - (w24 * w11)))
        r2[8] = ((w47 * ((w37 * w3) - (w19 * w5))) + (w50 * ((w37 * w6) - (w19 * w8)))) + (w51 * ((w37 * w9) - (w19 * w11)))
        r2[9] = 0.0
        r2[10] = 0.0
        r2[11] = 0.0
        r2[12] = ((w29 * ((w34 * w4) - (w43 * w3))) + (w40 * ((w34 * w7) - (w43 * w6)))) + (w41 * ((w34 * w10) - (w43 * w9)))
        r2[13] = ((w39 * ((w24 * w4) - (w27 * w3))) + (w45 * ((w24 * w7) - (w27 * w6)))) + (w46 * ((w24 * w10) - (w27 * w9)))
        r2[14] = ((w47 * ((w19 * w4) - (w36 * w3))) + (w50 * ((w19 * w7) - (w36 * w6)))) + (w51 * ((w19 * w10) - (w36 * w9)))
        r2[15] = 0.0
        r2[16] = 0.0
        r2[17] = 0.0
        r2[18] = 0.0
        r2[19] = 0.0
        r2[20] = 0.0
        r2[21] = 0.0
        r2[22] = 0.0
        r2[23] = 0.0
        r2[24] = 0.0
        r2[25] = 0.0
        r2[26] = 0.0
        r2[27] = 0.0
        r2[28] = 0.0
        r2[29] = 0.0
        r2[30] = 0.0
        r2[31] = 0.0
        r2[32] = 0.0
        r2[33] = 0.0
        r2[34] = 0.0
        r2[35] = 0.0
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 18
        r1 = [0.0] * 18
        r2 = [0.0] * 36
        w0 = 0.0
        r0[0] = w0
        r0[1] = w0
        r0[2] = w0
        r0[3] = w0
        r0[4] = w0
        r0[5] = w0
        r0[6] = w0
        r0[7] = w0
        r0[8] = w0
        w1 = 1.0
        r0[9] = w1
        r0[10] = w0
        r0[11] = w0
        r0[12] = w0
        r0[13] = w1
        r0[14] = w0
        r0[15] = w0
        r0[16] = w0
        r0[17] = w1
        w2 = g[0]
        w3 = 4.0
        w4 = h[0]
        w5 = z[0]
        w6 = w4 * w5
        w7 = w6 * w6
        w8 = z[1]
        w9 = w4 * w8
        w10 = w9 * w9
        w11 = w7 + w10
        w12 = z[2]
        w13 = w4 * w12
        w14 = w13 * w13
        w11 = w11 + w14
        w11 = w3 + w11
        w3 = w3 / w11 if w11 else _div(w3, w11)
        w15 = w13 * w6
        w16 = 2.0
        w15 = w15 / w16 if w16 else _div(w15, w16)
        w15 = w9 + w15
        w17 = w3 * w15
        w18 = w2 * w17
        w19 = g[3]
        w20 = w13 * w9
        w20 = w20 / w16 if w16 else _div(w20, w16)
        w20 = w20 - w6
        w21 = w3 * w20
        w22 = w19 * w21
        w18 = w18 + w22
        w22 = g[6]
        w23 = w10 + w7
        w23 = w23 / w16 if w16 else _div(w23, w16)
        w24 = w3 * w23
        w24 = w1 - w24
        w25 = w22 * w24
        w18 = w18 + w25
        w25 = 0.5
        w26 = w9 * w4
        w26 = w25 * w26
        w26 = w3 * w26
        w27 = w9 * w6
        w27 = w27 / w16 if w16 else _div(w27, w16)
        w27 = w27 - w13
        w11 = w3 / w11 if w11 else _div(w3, w11)
        w28 = 2.0 * w6
        w29 = w28 * w4
        w30 = w11 * w29
        w31 = w27 * w30
        w31 = w26 - w31
        w32 = w2 * w31
        w29 = w25 * w29
        w29 = w3 * w29
        w7 = w14 + w7
        w7 = w7 / w16 if w16 else _div(w7, w16)
        w33 = w7 * w30
        w33 = w29 - w33
        w34 = w19 * w33
        w32 = w32 - w34
        w34 = w3 * w4
        w35 = w9 * w13
        w35 = w35 / w16 if w16 else _div(w35, w16)
        w35 = w6 + w35
        w36 = w35 * w30
        w36 = w34 - w36
        w37 = w22 * w36
        w32 = w32 + w37
        w32 = w18 * w32
        w37 = g[1]
        w38 = w37 * w17
        w39 = g[4]
        w40 = w39 * w21
        w38 = w38 + w40
        w40 = g[7]
        w41 = w40 * w24
        w38 = w38 + w41
        w41 = w37 * w31
        w42 = w39 * w33
        w41 = w41 - w42
        w42 = w40 * w36
        w41 = w41 + w42
        w41 = w38 * w41
        w32 = w32 + w41
        w41 = g[2]
        w42 = w41 * w17
        w43 = g[5]
        w44 = w43 * w21
        w42 = w42 + w44
        w44 = g[8]
        w45 = w44 * w24
        w42 = w42 + w45
        w31 = w41 * w31
        w33 = w43 * w33
        w31 = w31 - w33
        w36 = w44 * w36
        w31 = w31 + w36
        w31 = w42 * w31
        w32 = w32 + w31
        r1[0] = w32
        w14 = w14 + w10
        w14 = w14 / w16 if w16 else _div(w14, w16)
        w10 = w3 * w14
        w10 = w1 - w10
        w32 = w2 * w10
        w31 = w6 * w9
        w31 = w31 / w16 if w16 else _div(w31, w16)
        w31 = w13 + w31
        w36 = w3 * w31
        w33 = w19 * w36
        w32 = w32 + w33
        w33 = w6 * w13
        w33 = w33 / w16 if w16 else _div(w33, w16)
        w33 = w33 - w9
        w45 = w3 * w33
        w46 = w22 * w45
        w32 = w32 + w46
        w46 = w13 * w4
        w46 = w25 * w46
        w46 = w3 * w46
        w47 = w15 * w30
        w47 = w46 - w47
        w48 = w2 * w47
        w49 = w20 * w30
        w49 = w49 + w34
        w50 = w19 * w49
        w48 = w48 - w50
        w50 = w23 * w30
        w29 = w29 - w50
        w50 = w22 * w29
        w48 = w48 - w50
        w48 = w32 * w48
        w50 = w37 * w10
        w51 = w39 * w36
        w50 = w50 + w51
        w51 = w40 * w45
        w50 = w50 + w51
        w51 = w37 * w47
        w52 = w39 * w49
        w51 = w51 - w52
        w52 = w40 * w29
        w51 = w51 - w52
        w51 = w50 * w51
        w48 = w48 + w51
        w51 = w41 * w10
        w52 = w43 * w36
        w51 = w51 + w52
        w52 = w44 * w45
        w51 = w51 + w52
        w47 = w41 * w47
        w49 = w43 * w49
        w47 = w47 - w49
        w29 = w44 * w29
        w47 = w47 - w29
        w47 = w51 * w47
        w48 = w48 + w47
        r1[1] = w48
        w48 = w3 * w27
        w47 = w2 * w48
        w29 = w3 * w7
        w29 = w1 - w29
        w49 = w19 * w29
        w47 = w47 + w49
        w49 = w3 * w35
        w52 = w22 * w49
        w47 = w47 + w52
        w52 = w14 * w30
        w53 = w2 * w52
        w54 = w31 * w30
        w54 = w26 - w54
        w55 = w19 * w54
        w53 = w53 + w55
        w30 = w33 * w30
        w30 = w46 - w30
        w55 = w22 * w30
        w53 = w53 + w55
        w53 = w47 * w53
        w55 = w37 * w48
        w56 = w39 * w29
        w55 = w55 + w56
        w56 = w40 * w49
        w55 = w55 + w56
        w56 = w37 * w52
        w57 = w39 * w54
        w56 = w56 + w57
        w57 = w40 * w30
        w56 = w56 + w57
        w56 = w55 * w56
        w53 = w53 + w56
        w56 = w41 * w48
        w57 = w43 * w29
        w56 = w56 + w57
        w57 = w44 * w49
        w56 = w56 + w57
        w52 = w41 * w52
        w54 = w43 * w54
        w52 = w52 + w54
        w30 = w44 * w30
        w52 = w52 + w30
        w52 = w56 * w52
        w53 = w53 + w52
        r1[2] = w53
        w53 = 0.25
        w52 = 0.6666666666666666
        w30 = w52 * w12
        w54 = w13 * w30
        w57 = w9 * w8
        w54 = w54 + w57
        w57 = 2.0 * w5
        w58 = w6 * w57
        w54 = w54 + w58
        w54 = w53 * w54
        w54 = w54 * w4
        w57 = w57 * w4
        w57 = w57 + w28
        w57 = w53 * w57
        w28 = w6 * w57
        w28 = w54 + w28
        w28 = w28 + w16
        r1[3] = w28
        w28 = 0.3333333333333333
        w12 = w28 * w12
        w12 = w12 * w4
        w16 = w9 * w57
        w16 = w12 + w16
        w16 = w16 - w13
        r1[4] = w16
        w57 = w13 * w57
        w16 = w25 * w8
        w16 = w16 * w4
        w57 = w57 - w16
        w57 = w57 + w9
        r1[5] = w57
        w57 = w6 * w4
        w57 = w25 * w57
        w57 = w3 * w57
        w58 = 2.0 * w9
        w58 = w58 * w4
        w59 = w11 * w58
        w60 = w27 * w59
        w60 = w57 - w60
        w61 = w2 * w60
        w62 = w7 * w59
        w63 = w19 * w62
        w61 = w61 + w63
        w63 = w35 * w59
        w63 = w46 - w63
        w64 = w22 * w63
        w61 = w61 + w64
        w61 = w18 * w61
        w64 = w37 * w60
        w65 = w39 * w62
        w64 = w64 + w65
        w65 = w40 * w63
        w64 = w64 + w65
        w64 = w38 * w64
        w61 = w61 + w64
        w60 = w41 * w60
        w62 = w43 * w62
        w60 = w60 + w62
        w63 = w44 * w63
        w60 = w60 + w63
        w60 = w42 * w60
        w61 = w61 + w60
        r1[6] = w61
        w61 = w15 * w59
        w61 = w34 - w61
        w60 = w2 * w61
        w63 = w20 * w59
        w46 = w46 - w63
        w63 = w19 * w46
        w60 = w60 + w63
        w58 = w25 * w58
        w58 = w3 * w58
        w63 = w23 * w59
        w63 = w58 - w63
        w62 = w22 * w63
        w60 = w60 - w62
        w60 = w32 * w60
        w62 = w37 * w61
        w64 = w39 * w46
        w62 = w62 + w64
        w64 = w40 * w63
        w62 = w62 - w64
        w62 = w50 * w62
        w60 = w60 + w62
        w61 = w41 * w61
        w46 = w43 * w46
        w61 = w61 + w46
        w63 = w44 * w63
        w61 = w61 - w63
        w61 = w51 * w61
        w60 = w60 + w61
        r1[7] = w60
        w60 = w31 * w59
        w60 = w57 - w60
        w61 = w19 * w60
        w63 = w14 * w59
        w58 = w58 - w63
        w63 = w2 * w58
        w61 = w61 - w63
        w59 = w33 * w59
        w59 = w59 + w34
        w63 = w22 * w59
        w61 = w61 - w63
        w61 = w47 * w61
        w63 = w39 * w60
        w46 = w37 * w58
        w63 = w63 - w46
        w46 = w40 * w59
        w63 = w63 - w46
        w63 = w55 * w63
        w61 = w61 + w63
        w60 = w43 * w60
        w58 = w41 * w58
        w60 = w60 - w58
        w59 = w44 * w59
        w60 = w60 - w59
        w60 = w56 * w60
        w61 = w61 + w60
        r1[8] = w61
        w61 = w25 * w13
        w61 = w61 - w12
        w8 = w8 * w4
        w8 = w25 * w8
        w12 = w6 * w8
        w61 = w61 + w12
        r1[9] = w61
        w61 = w9 * w8
        w61 = w54 + w61
        w1 = w1 + w61
        r1[10] = w1
        w8 = w13 * w8
        w1 = w25 * w6
        w8 = w8 - w1
        w5 = w5 * w4
        w8 = w8 + w5
        r1[11] = w8
        w8 = 2.0 * w13
        w8 = w8 * w4
        w11 = w11 * w8
        w35 = w35 * w11
        w35 = w26 - w35
        w1 = w22 * w35
        w27 = w27 * w11
        w27 = w27 + w34
        w61 = w2 * w27
        w25 = w25 * w8
        w3 = w3 * w25
        w7 = w7 * w11
        w7 = w3 - w7
        w25 = w19 * w7
        w61 = w61 + w25
        w1 = w1 - w61
        w1 = w18 * w1
        w61 = w40 * w35
        w25 = w37 * w27
        w8 = w39 * w7
        w25 = w25 + w8
        w61 = w61 - w25
        w61 = w38 * w61
        w1 = w1 + w61
        w35 = w44 * w35
        w27 = w41 * w27
        w7 = w43 * w7
        w27 = w27 + w7
        w35 = w35 - w27
        w35 = w42 * w35
        w1 = w1 + w35
        r1[12] = w1
        w15 = w15 * w11
        w15 = w57 - w15
        w1 = w2 * w15
        w20 = w20 * w11
        w26 = w26 - w20
        w20 = w19 * w26
        w1 = w1 + w20
        w23 = w23 * w11
        w20 = w22 * w23
        w1 = w1 + w20
        w1 = w32 * w1
        w20 = w37 * w15
        w35 = w39 * w26
        w20 = w20 + w35
        w35 = w40 * w23
        w20 = w20 + w35
        w20 = w50 * w20
        w1 = w1 + w20
        w15 = w41 * w15
        w26 = w43 * w26
        w15 = w15 + w26
        w23 = w44 * w23
        w15 = w15 + w23
        w15 = w51 * w15
        w1 = w1 + w15
        r1[13] = w1
        w31 = w31 * w11
        w34 = w34 - w31
        w31 = w19 * w34
        w14 = w14 * w11
        w3 = w3 - w14
        w14 = w2 * w3
        w31 = w31 - w14
        w33 = w33 * w11
        w57 = w57 - w33
        w33 = w22 * w57
        w31 = w31 + w33
        w31 = w47 * w31
        w33 = w39 * w34
        w11 = w37 * w3
        w33 = w33 - w11
        w11 = w40 * w57
        w33 = w33 + w11
        w33 = w55 * w33
        w31 = w31 + w33
        w34 = w43 * w34
        w3 = w41 * w3
        w34 = w34 - w3
        w57 = w44 * w57
        w34 = w34 + w57
        w34 = w56 * w34
        w31 = w31 + w34
        r1[14] = w31
        w31 = w28 * w9
        w16 = w16 - w31
        w30 = w30 * w4
        w4 = w52 * w13
        w30 = w30 + w4
        w53 = w53 * w30
        w30 = w6 * w53
        w16 = w16 + w30
        r1[15] = w16
        w28 = w28 * w6
        w9 = w9 * w53
        w28 = w28 + w9
        w28 = w28 - w5
        r1[16] = w28
        w13 = w13 * w53
        w54 = w54 + w13
        w52 = w52 + w54
        r1[17] = w52
        w52 = w29 * w22
        w54 = w49 * w19
        w52 = w52 - w54
        w52 = w18 * w52
        w54 = w29 * w40
        w13 = w49 * w39
        w54 = w54 - w13
        w54 = w38 * w54
        w52 = w52 + w54
        w54 = w29 * w44
        w13 = w49 * w43
        w54 = w54 - w13
        w54 = w42 * w54
        w52 = w52 + w54
        r2[0] = w52
        w52 = w21 * w22
        w54 = w24 * w19
        w52 = w52 - w54
        w52 = w32 * w52
        w54 = w21 * w40
        w13 = w24 * w39
        w54 = w54 - w13
        w54 = w50 * w54
        w52 = w52 + w54
        w54 = w21 * w44
        w13 = w24 * w43
        w54 = w54 - w13
        w54 = w51 * w54
        w52 = w52 + w54
        r2[1] = w52
        w52 = w36 * w22
        w54 = w45 * w19
        w52 = w52 - w54
        w52 = w47 * w52
        w54 = w36 * w40
        w13 = w45 * w39
        w54 = w54 - w13
        w54 = w55 * w54
        w52 = w52 + w54
        w54 = w36 * w44
        w13 = w45 * w43
        w54 = w54 - w13
        w54 = w56 * w54
        w52 = w52 + w54
        r2[2] = w52
        r2[3] = w0
        r2[4] = w0
        r2[5] = w0
        w52 = w49 * w2
        w54 = w48 * w22
        w52 = w52 - w54
        w52 = w18 * w52
        w54 = w49 * w37
        w13 = w48 * w40
        w54 = w54 - w13
        w54 = w38 * w54
        w52 = w52 + w54
        w49 = w49 * w41
        w54 = w48 * w44
        w49 = w49 - w54
        w49 = w42 * w49
        w52 = w52 + w49
        r2[6] = w52
        w52 = w24 * w2
        w49 = w17 * w22
        w52 = w52 - w49
        w52 = w32 * w52
        w49 = w24 * w37
        w54 = w17 * w40
        w49 = w49 - w54
        w49 = w50 * w49
        w52 = w52 + w49
        w24 = w24 * w41
        w49 = w17 * w44
        w24 = w24 - w49
        w24 = w51 * w24
        w52 = w52 + w24
        r2[7] = w52
        w52 = w45 * w2
        w22 = w10 * w22
        w52 = w52 - w22
        w52 = w47 * w52
        w22 = w45 * w37
        w40 = w10 * w40
        w22 = w22 - w40
        w22 = w55 * w22
        w52 = w52 + w22
        w45 = w45 * w41
        w44 = w10 * w44
        w45 = w45 - w44
        w45 = w56 * w45
        w52 = w52 + w45
        r2[8] = w52
        r2[9] = w0
        r2[10] = w0
        r2[11] = w0
        w52 = w48 * w19
        w45 = w29 * w2
        w52 = w52 - w45
        w18 = w18 * w52
        w52 = w48 * w39
        w45 = w29 * w37
        w52 = w52 - w45
        w38 = w38 * w52
        w18 = w18 + w38
        w48 = w48 * w43
        w29 = w29 * w41
        w48 = w48 - w29
        w42 = w42 * w48
        w18 = w18 + w42
        r2[12] = w18
        w18 = w17 * w19
        w42 = w21 * w2
        w18 = w18 - w42
        w32 = w32 * w18
        w18 = w17 * w39
        w42 = w21 * w37
        w18 = w18 - w42
        w50 = w50 * w18
        w32 = w32 + w50
        w17 = w17 * w43
        w21 = w21 * w41
        w17 = w17 - w21
        w51 = w51 * w17
        w32 = w32 + w51
        r2[13] = w32
        w19 = w10 * w19
        w2 = w36 * w2
        w19 = w19 - w2
        w47 = w47 * w19
        w39 = w10 * w39
        w37 = w36 * w37
        w39 = w39 - w37
        w55 = w55 * w39
        w47 = w47 + w55
        w10 = w10 * w43
        w36 = w36 * w41
        w10 = w10 - w36
        w56 = w56 * w10
        w47 = w47 + w56
        r2[14] = w47
        r2[15] = w0
        r2[16] = w0
        r2[17] = w0
        r2[18] = w0
        r2[19] = w0
        r2[20] = w0
        r2[21] = w0
        r2[22] = w0
        r2[23] = w0
        r2[24] = w0
        r2[25] = w0
        r2[26] = w0
        r2[27] = w0
        r2[28] = w0
        r2[29] = w0
        r2[30] = w0
        r2[31] = w0
        r2[32] = w0
        r2[33] = w0
        r2[34] = w0
        r2[35] = w0
    return [r0, r1, r2]


def step_partials(z, g, p, h):
    """step_partials(z[3], g[9], p[3], h[1]) -> [Fs[18], Yz[18], Ys[36]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "step_partials: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (9,):
        g = g.tolist()
    else:
        g = _vec(g, 9, "step_partials: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (3,):
        p = p.tolist()
    else:
        p = _vec(p, 3, "step_partials: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (1,):
        h = h.tolist()
    else:
        h = _vec(h, 1, "step_partials: h")
    _r = _raw_step_partials(z, g, p, h)
    return [_fromiter(_r[0], _F64, 18), _fromiter(_r[1], _F64, 18), _fromiter(_r[2], _F64, 36)]


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
    "step_partials": step_partials,
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
    "step_partials": _raw_step_partials,
}


# ---- Newton's linear algebra for NZ (hpgen.codegen.pylinear: straight-line Python, the C
# template's operations in the same order), used by hpgen.runtime.newton ----
_isfinite = math.isfinite
_UNIT3 = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))


def _lin_factor_solve(J, F, keep):
    j00, j10, j20, j01, j11, j21, j02, j12, j22 = J
    b0, b1, b2 = F
    c00 = j11 * j22 - j12 * j21
    c01 = j12 * j20 - j10 * j22
    c02 = j10 * j21 - j11 * j20
    c10 = j02 * j21 - j01 * j22
    c11 = j00 * j22 - j02 * j20
    c12 = j01 * j20 - j00 * j21
    c20 = j01 * j12 - j02 * j11
    c21 = j02 * j10 - j00 * j12
    c22 = j00 * j11 - j01 * j10
    det = j00 * c00 + j01 * c01 + j02 * c02
    x0 = c00 * b0 + c10 * b1 + c20 * b2
    x1 = c01 * b0 + c11 * b1 + c21 * b2
    x2 = c02 * b0 + c12 * b1 + c22 * b2
    if not det != 0.0 or not _isfinite(det):
        return None
    r = 1.0 / det
    return [x0 * r, x1 * r, x2 * r], (c00 * r, c01 * r, c02 * r, c10 * r, c11 * r, c12 * r, c20 * r, c21 * r, c22 * r)


def _lin_apply(f, F):
    a0_0, a1_0, a2_0, a0_1, a1_1, a2_1, a0_2, a1_2, a2_2, = f
    c0, c1, c2, = F
    b0 = a0_0 * c0 + a0_1 * c1 + a0_2 * c2
    b1 = a1_0 * c0 + a1_1 * c1 + a1_2 * c2
    b2 = a2_0 * c0 + a2_1 * c1 + a2_2 * c2
    return [b0, b1, b2]


def _lin_update(f, F, z):
    a0_0, a1_0, a2_0, a0_1, a1_1, a2_1, a0_2, a1_2, a2_2, = f
    c0, c1, c2, = F
    b0 = a0_0 * c0 + a0_1 * c1 + a0_2 * c2
    b1 = a1_0 * c0 + a1_1 * c1 + a1_2 * c2
    b2 = a2_0 * c0 + a2_1 * c1 + a2_2 * c2
    z0, z1, z2, = z
    z0 = z0 - b0
    z1 = z1 - b1
    z2 = z2 - b2
    s = b0 + b1 + b2
    t = z0 + z1 + z2
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
    return [z0, z1, z2], dn, zn


def _lin_finish(dz, z):
    b0, b1, b2, = dz
    z0, z1, z2, = z
    z0 = z0 - b0
    z1 = z1 - b1
    z2 = z2 - b2
    s = b0 + b1 + b2
    t = z0 + z1 + z2
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
    return [z0, z1, z2], dn, zn

LINEAR = (_lin_factor_solve, _lin_apply, _lin_update, _lin_finish)


# ---- Newton's iterates with the kernels and the linear algebra fused: simplified with a kept
# J^{-1} (ITERATE) and full Newton (ITERATE_FULL); the operations of hpgen.runtime.newton.solve
# (hpgen.codegen.pyiterate) ----


def _newton_iterate(f, z, g, p, h, it, maxit, dprev, stol):
    """simplified-Newton iterates from z with J^{-1} = f (hpgen.codegen.pyiterate)"""
    a0_0, a1_0, a2_0, a0_1, a1_1, a2_1, a0_2, a1_2, a2_2, = f
    z0, z1, z2, = z
    p0, p1, p2, = p
    h0, = h
    try:
        while True:
            w0 = h0 * z2
            w1 = 0.5 * z1
            w2 = h0 * z1
            w3 = 0.3333333333333333 * z2
            w4 = h0 * z0
            w5 = 0.6666666666666666 * z2
            w6 = 2.0 * z0
            w7 = 0.25 * (((w0 * w5) + (w2 * z1)) + (w4 * w6))
            F0 = p0 + ((((w0 * w1) - (w2 * w3)) - (w4 * w7)) - w6)
            F1 = p1 + ((((w4 * w3) - z1) - (w2 * w7)) - (w0 * z0))
            F2 = p2 + ((w2 * z0) - ((w5 + (w4 * w1)) + (w0 * w7)))
            b0 = a0_0 * F0 + a0_1 * F1 + a0_2 * F2
            b1 = a1_0 * F0 + a1_1 * F1 + a1_2 * F2
            b2 = a2_0 * F0 + a2_1 * F1 + a2_2 * F2
            z0 = z0 - b0
            z1 = z1 - b1
            z2 = z2 - b2
            s = b0 + b1 + b2
            t = z0 + z1 + z2
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
            if it > 1 and dn >= dprev and dn <= 1e-11 * (1.0 + zn):
                code = 0
                break
            th = dn / dprev
            te = th if th > 0.05 else 0.05
            if dn <= stol * (1.0 + zn) or (it > 1 and te < 1.0 and te / (1.0 - te) * dn <= stol * (1.0 + zn)):
                code = 0
                break
            if it > 1 and dn > 0.2 * dprev:
                code = -2
                break
            if it >= maxit:
                code = 1
                break
            dprev = dn
            it += 1
    except (ArithmeticError, ValueError):
        return None
    rn = 0.0
    t = F0 if F0 >= 0.0 else -F0
    if t > rn:
        rn = t
    t = F1 if F1 >= 0.0 else -F1
    if t > rn:
        rn = t
    t = F2 if F2 >= 0.0 else -F2
    if t > rn:
        rn = t
    return code, [z0, z1, z2], it, dn, rn


ITERATE = _newton_iterate


def _newton_full(z, g, p, h, it, maxit, dprev, tol):
    """full-Newton iterates from z (hpgen.codegen.pyiterate)"""
    z0, z1, z2, = z
    p0, p1, p2, = p
    h0, = h
    try:
        while True:
            w0 = h0 * z2
            w1 = 0.5 * z1
            w2 = h0 * z1
            w3 = 0.3333333333333333 * z2
            w4 = h0 * z0
            w5 = 0.6666666666666666 * z2
            w6 = 2.0 * z0
            w7 = 0.25 * (((w0 * w5) + (w2 * z1)) + (w4 * w6))
            F0 = p0 + ((((w0 * w1) - (w2 * w3)) - (w4 * w7)) - w6)
            F1 = p1 + ((((w4 * w3) - z1) - (w2 * w7)) - (w0 * z0))
            F2 = p2 + ((w2 * z0) - ((w5 + (w4 * w1)) + (w0 * w7)))
            w7 = w7 * h0
            w6 = 0.25 * ((w6 * h0) + (2.0 * w4))
            J0 = (-2.0) - (w7 + (w4 * w6))
            w3 = w3 * h0
            J1 = (w3 - (w2 * w6)) - w0
            w1 = w1 * h0
            J2 = w2 - (w1 + (w0 * w6))
            w6 = 0.5 * w2
            J3 = ((0.5 * w0) - w3) - (w4 * w6)
            J4 = (-1.0) - (w7 + (w2 * w6))
            J5 = w4 - ((0.5 * w4) + (w0 * w6))
            w3 = 0.25 * ((w5 * h0) + (0.6666666666666666 * w0))
            J6 = (w1 - (0.3333333333333333 * w2)) - (w4 * w3)
            J7 = ((0.3333333333333333 * w4) - (w2 * w3)) - w4
            J8 = -(0.6666666666666666 + (w7 + (w0 * w3)))
            s = F0 + F1 + F2
            if not s - s == 0.0:
                return None
            res = _lin_factor_solve([J0, J1, J2, J3, J4, J5, J6, J7, J8], [F0, F1, F2], False)
            if res is None:
                return None
            b0, b1, b2, = res[0]
            z0 = z0 - b0
            z1 = z1 - b1
            z2 = z2 - b2
            s = b0 + b1 + b2
            t = z0 + z1 + z2
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
            if it > 1 and dn >= dprev and dn <= 1e-11 * (1.0 + zn):
                code = 0
                break
            if dn <= tol * (1.0 + zn):
                code = 0
                break
            if it >= maxit:
                code = 1
                break
            dprev = dn
            it += 1
    except (ArithmeticError, ValueError):
        return None
    rn = 0.0
    t = F0 if F0 >= 0.0 else -F0
    if t > rn:
        rn = t
    t = F1 if F1 >= 0.0 else -F1
    if t > rn:
        rn = t
    t = F2 if F2 >= 0.0 else -F2
    if t > rn:
        rn = t
    return code, [z0, z1, z2], it, dn, rn


ITERATE_FULL = _newton_full
