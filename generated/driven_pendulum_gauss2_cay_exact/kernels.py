# hpgen generated module driven_pendulum_gauss2_cay_exact -- do not edit, regenerate with hpgen
# model: driven_pendulum
# options: tableau=gauss2, tau=cay, rkmk=exact
# hpgen version: 0.1.0
# content hash (normalized model + options): b76f001c568489b54c25240c2e6bce8e6b4f732e81abe16fca3e42f6b849b2ff
"""Python backend of the hpgen module driven_pendulum_gauss2_cay_exact: straight-line kernels printed from the
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

N = 2
D = 1
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
    try:
        w0, w1, w2 = z
        w4, _, w3, _ = g
        w5, = p
        w6, w8, w7 = h
        r0 = [0.0] * 3
        w9 = w6 * w0
        w10 = (w9 * w9) * 0.25
        w11 = 1.0 + w10
        w12 = (3.0000000000000004 * w0) + (0.4641016151377544 * w1)
        w13 = w12 / w11
        w14 = (w13 / w11) - w2
        w0 = ((-6.464101615137755) * w0) + (3.0000000000000004 * w1)
        w1 = w6 * w1
        w15 = (w1 * w1) * 0.25
        w16 = 1.0 + w15
        w17 = w0 / w16
        w18 = (w17 / w16) - w2
        w19 = (1.5000000000000002 * w14) + ((-3.2320508075688776) * w18)
        w20 = 0.5 * (w6 * w2)
        w14 = (0.2320508075688772 * w14) + (1.5000000000000002 * w18)
        w18 = w6 * w14
        w21 = w6 * w19
        w19 = w11 * (w19 - ((2.0 * w9) * (0.25 * (w13 * ((w20 + (0.5386751345948129 * w18)) + (0.25 * w21))))))
        w22 = 0.5 * w6
        r0[0] = ((w19 + ((((-0.5) * w13) + (w7 * (_f_cos((0.6666666666666666 * (w8 + (0.21132486540518713 * w6))))))) * w22)) + (((w3 * ((1.0 - w10) / w11)) - (w4 * (w9 / w11))) * w22)) / w6
        w9 = w16 * (w14 - ((2.0 * w1) * (0.25 * (w17 * ((w20 + (0.25 * w18)) + ((-0.03867513459481288) * w21))))))
        r0[1] = ((((((-0.5) * w17) + (w7 * (_f_cos((0.6666666666666666 * (w8 + (0.7886751345948129 * w6))))))) * w22) + (((w3 * ((1.0 - w15) / w16)) - (w4 * (w1 / w16))) * w22)) + w9) / w6
        w0 = w6 * ((0.5 * w12) + (0.5 * w0))
        r0[2] = w5 - ((((1.0 + ((w0 * w0) * 0.25)) * w2) + w9) + w19)
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 3
        w0 = 1.0
        w1 = h[0]
        w2 = z[0]
        w3 = w1 * w2
        w4 = w3 * w3
        w5 = 4.0
        w4 = w4 / w5 if w5 else _div(w4, w5)
        w6 = w0 + w4
        w7 = 1.5000000000000002
        w8 = 3.0000000000000004
        w9 = w8 * w2
        w10 = 0.4641016151377544
        w11 = z[1]
        w10 = w10 * w11
        w9 = w9 + w10
        w10 = w9 / w6 if w6 else _div(w9, w6)
        w12 = w10 / w6 if w6 else _div(w10, w6)
        w13 = z[2]
        w12 = w12 - w13
        w14 = w7 * w12
        w15 = -3.2320508075688776
        w16 = -6.464101615137755
        w16 = w16 * w2
        w8 = w8 * w11
        w16 = w16 + w8
        w11 = w1 * w11
        w8 = w11 * w11
        w8 = w8 / w5 if w5 else _div(w8, w5)
        w2 = w0 + w8
        w17 = w16 / w2 if w2 else _div(w16, w2)
        w18 = w17 / w2 if w2 else _div(w17, w2)
        w18 = w18 - w13
        w15 = w15 * w18
        w14 = w14 + w15
        w15 = 2.0 * w3
        w19 = 0.25
        w20 = 0.5
        w21 = w1 * w13
        w21 = w20 * w21
        w22 = 0.5386751345948129
        w23 = 0.2320508075688772
        w23 = w23 * w12
        w7 = w7 * w18
        w23 = w23 + w7
        w7 = w1 * w23
        w22 = w22 * w7
        w22 = w21 + w22
        w18 = w1 * w14
        w12 = w19 * w18
        w22 = w22 + w12
        w22 = w10 * w22
        w22 = w19 * w22
        w15 = w15 * w22
        w14 = w14 - w15
        w14 = w6 * w14
        w15 = -0.5
        w10 = w15 * w10
        w22 = h[2]
        w12 = 0.6666666666666666
        w24 = h[1]
        w25 = 0.21132486540518713
        w25 = w25 * w1
        w25 = w24 + w25
        w25 = w12 * w25
        w25 = _cos(w25)
        w25 = w22 * w25
        w10 = w10 + w25
        w25 = w20 * w1
        w10 = w10 * w25
        w10 = w14 + w10
        w26 = g[2]
        w4 = w0 - w4
        w4 = w4 / w6 if w6 else _div(w4, w6)
        w4 = w26 * w4
        w27 = g[0]
        w3 = w3 / w6 if w6 else _div(w3, w6)
        w3 = w27 * w3
        w4 = w4 - w3
        w4 = w4 * w25
        w10 = w10 + w4
        w10 = w10 / w1 if w1 else _div(w10, w1)
        r0[0] = w10
        w15 = w15 * w17
        w10 = 0.7886751345948129
        w10 = w10 * w1
        w24 = w24 + w10
        w12 = w12 * w24
        w12 = _cos(w12)
        w22 = w22 * w12
        w15 = w15 + w22
        w15 = w15 * w25
        w8 = w0 - w8
        w8 = w8 / w2 if w2 else _div(w8, w2)
        w26 = w26 * w8
        w8 = w11 / w2 if w2 else _div(w11, w2)
        w27 = w27 * w8
        w26 = w26 - w27
        w26 = w26 * w25
        w15 = w15 + w26
        w11 = 2.0 * w11
        w7 = w19 * w7
        w21 = w21 + w7
        w7 = -0.03867513459481288
        w7 = w7 * w18
        w21 = w21 + w7
        w17 = w17 * w21
        w19 = w19 * w17
        w11 = w11 * w19
        w23 = w23 - w11
        w2 = w2 * w23
        w15 = w15 + w2
        w15 = w15 / w1 if w1 else _div(w15, w1)
        r0[1] = w15
        w15 = p[0]
        w9 = w20 * w9
        w20 = w20 * w16
        w9 = w9 + w20
        w1 = w1 * w9
        w1 = w1 * w1
        w1 = w1 / w5 if w5 else _div(w1, w5)
        w0 = w0 + w1
        w0 = w0 * w13
        w0 = w0 + w2
        w0 = w0 + w14
        w15 = w15 - w0
        r0[2] = w15
    return [r0]


def residual(z, g, p, h):
    """residual(z[3], g[4], p[1], h[3]) -> [F[3]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "residual: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "residual: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (1,):
        p = p.tolist()
    else:
        p = _vec(p, 1, "residual: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (3,):
        h = h.tolist()
    else:
        h = _vec(h, 3, "residual: h")
    _r = _raw_residual(z, g, p, h)
    return [_fromiter(_r[0], _F64, 3)]


def _raw_jacobian(z, g, p, h):
    """jacobian on lists of Python floats -> [J[9]] as lists (see RAW)"""
    try:
        w0, w1, w2 = z
        w4, _, w3, _ = g
        w5, _, _ = h
        r0 = [0.0] * 9
        w6 = (3.0000000000000004 * w0) + (0.4641016151377544 * w1)
        w7 = w5 * w0
        w8 = (w7 * w7) * 0.25
        w9 = 1.0 + w8
        w10 = w6 / w9
        w11 = w10 / w9
        w12 = w11 - w2
        w0 = ((-6.464101615137755) * w0) + (3.0000000000000004 * w1)
        w1 = w5 * w1
        w13 = (w1 * w1) * 0.25
        w14 = 1.0 + w13
        w15 = w0 / w14
        w16 = w15 / w14
        w17 = w16 - w2
        w18 = (1.5000000000000002 * w12) + ((-3.2320508075688776) * w17)
        w19 = 2.0 * w7
        w20 = 0.5 * (w5 * w2)
        w12 = (0.2320508075688772 * w12) + (1.5000000000000002 * w17)
        w17 = w5 * w12
        w21 = w5 * w18
        w22 = (w20 + (0.5386751345948129 * w17)) + (0.25 * w21)
        w23 = 0.25 * (w10 * w22)
        w24 = 0.25 * (w19 * w5)
        w25 = (3.0000000000000004 / w9) - (w11 * w24)
        w11 = (w25 / w9) - ((w11 / w9) * w24)
        w26 = (-6.464101615137755) / w14
        w27 = w26 / w14
        w28 = (1.5000000000000002 * w11) + ((-3.2320508075688776) * w27)
        w29 = 2.0 * w5
        w11 = (0.2320508075688772 * w11) + (1.5000000000000002 * w27)
        w27 = w5 * w11
        w30 = w5 * w28
        w18 = ((w18 - (w19 * w23)) * w24) + (w9 * (w28 - ((w23 * w29) + (w19 * (0.25 * ((w22 * w25) + (w10 * ((0.5386751345948129 * w27) + (0.25 * w30)))))))))
        w23 = 0.5 * w5
        r0[0] = ((w18 + (w23 * ((-0.5) * w25))) - (w23 * ((w3 * ((w24 / w9) + ((((1.0 - w8) / w9) / w9) * w24))) + (w4 * ((w5 / w9) - (((w7 / w9) / w9) * w24)))))) / w5
        w7 = 2.0 * w1
        w8 = (w20 + (0.25 * w17)) + ((-0.03867513459481288) * w21)
        w11 = w14 * (w11 - (w7 * (0.25 * ((w8 * w26) + (w15 * ((0.25 * w27) + ((-0.03867513459481288) * w30)))))))
        r0[1] = ((w23 * ((-0.5) * w26)) + w11) / w5
        w0 = w5 * ((0.5 * w6) + (0.5 * w0))
        w6 = 2.0 * w0
        r0[2] = -(((w2 * (0.25 * (w6 * ((-1.7320508075688774) * w5)))) + w11) + w18)
        w11 = 0.4641016151377544 / w9
        w17 = w11 / w9
        w18 = 0.25 * (w7 * w5)
        w20 = (3.0000000000000004 / w14) - (w16 * w18)
        w16 = (w20 / w14) - ((w16 / w14) * w18)
        w21 = (1.5000000000000002 * w17) + ((-3.2320508075688776) * w16)
        w16 = (0.2320508075688772 * w17) + (1.5000000000000002 * w16)
        w17 = w5 * w16
        w24 = w5 * w21
        w21 = w9 * (w21 - (w19 * (0.25 * ((w22 * w11) + (w10 * ((0.5386751345948129 * w17) + (0.25 * w24)))))))
        r0[3] = (w21 + (w23 * ((-0.5) * w11))) / w5
        w11 = 0.25 * (w15 * w8)
        w8 = ((w12 - (w7 * w11)) * w18) + (w14 * (w16 - ((w11 * w29) + (w7 * (0.25 * ((w8 * w20) + (w15 * ((0.25 * w17) + ((-0.03867513459481288) * w24)))))))))
        r0[4] = (((w23 * ((-0.5) * w20)) - (w23 * ((w3 * ((w18 / w14) + ((((1.0 - w13) / w14) / w14) * w18))) + (w4 * ((w5 / w14) - (((w1 / w14) / w14) * w18)))))) + w8) / w5
        r0[5] = -(((w2 * (0.25 * (w6 * (1.7320508075688774 * w5)))) + w8) + w21)
        w1 = w9 * (1.7320508075688774 - (w19 * (0.25 * (w10 * ((w23 + ((-0.9330127018922194) * w5)) + (0.43301270189221935 * w5))))))
        r0[6] = w1 / w5
        w2 = w14 * ((-1.7320508075688774) - (w7 * (0.25 * (w15 * ((w23 + ((-0.43301270189221935) * w5)) + ((-0.06698729810778067) * w5))))))
        r0[7] = w2 / w5
        r0[8] = -(((1.0 + ((w0 * w0) * 0.25)) + w2) + w1)
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 9
        w0 = 1.5000000000000002
        w1 = 3.0000000000000004
        w2 = z[0]
        w3 = w1 * w2
        w4 = 0.4641016151377544
        w5 = z[1]
        w6 = w4 * w5
        w3 = w3 + w6
        w6 = 1.0
        w7 = h[0]
        w8 = w7 * w2
        w9 = w8 * w8
        w10 = 4.0
        w9 = w9 / w10 if w10 else _div(w9, w10)
        w11 = w6 + w9
        w12 = w3 / w11 if w11 else _div(w3, w11)
        w13 = w12 / w11 if w11 else _div(w12, w11)
        w14 = z[2]
        w15 = w13 - w14
        w16 = w0 * w15
        w17 = -3.2320508075688776
        w18 = -6.464101615137755
        w2 = w18 * w2
        w19 = w1 * w5
        w2 = w2 + w19
        w5 = w7 * w5
        w19 = w5 * w5
        w19 = w19 / w10 if w10 else _div(w19, w10)
        w20 = w6 + w19
        w21 = w2 / w20 if w20 else _div(w2, w20)
        w22 = w21 / w20 if w20 else _div(w21, w20)
        w23 = w22 - w14
        w24 = w17 * w23
        w16 = w16 + w24
        w24 = 2.0 * w8
        w25 = 0.25
        w26 = 0.5
        w27 = w7 * w14
        w27 = w26 * w27
        w28 = 0.5386751345948129
        w29 = 0.2320508075688772
        w15 = w29 * w15
        w23 = w0 * w23
        w15 = w15 + w23
        w23 = w7 * w15
        w30 = w28 * w23
        w30 = w27 + w30
        w31 = w7 * w16
        w32 = w25 * w31
        w30 = w30 + w32
        w32 = w12 * w30
        w32 = w25 * w32
        w33 = w24 * w32
        w16 = w16 - w33
        w33 = w24 * w7
        w33 = w25 * w33
        w16 = w16 * w33
        w34 = w1 / w11 if w11 else _div(w1, w11)
        w35 = w13 * w33
        w34 = w34 - w35
        w35 = w34 / w11 if w11 else _div(w34, w11)
        w13 = w13 / w11 if w11 else _div(w13, w11)
        w13 = w13 * w33
        w35 = w35 - w13
        w13 = w0 * w35
        w18 = w18 / w20 if w20 else _div(w18, w20)
        w36 = w18 / w20 if w20 else _div(w18, w20)
        w37 = w17 * w36
        w13 = w13 + w37
        w37 = 2.0 * w7
        w32 = w32 * w37
        w38 = w30 * w34
        w35 = w29 * w35
        w36 = w0 * w36
        w35 = w35 + w36
        w36 = w7 * w35
        w39 = w28 * w36
        w40 = w7 * w13
        w41 = w25 * w40
        w39 = w39 + w41
        w39 = w12 * w39
        w38 = w38 + w39
        w38 = w25 * w38
        w38 = w24 * w38
        w32 = w32 + w38
        w13 = w13 - w32
        w13 = w11 * w13
        w16 = w16 + w13
        w13 = w26 * w7
        w32 = -0.5
        w34 = w32 * w34
        w34 = w13 * w34
        w34 = w16 + w34
        w38 = g[2]
        w39 = w33 / w11 if w11 else _div(w33, w11)
        w9 = w6 - w9
        w9 = w9 / w11 if w11 else _div(w9, w11)
        w9 = w9 / w11 if w11 else _div(w9, w11)
        w9 = w9 * w33
        w39 = w39 + w9
        w39 = w38 * w39
        w9 = g[0]
        w41 = w7 / w11 if w11 else _div(w7, w11)
        w8 = w8 / w11 if w11 else _div(w8, w11)
        w8 = w8 / w11 if w11 else _div(w8, w11)
        w8 = w8 * w33
        w41 = w41 - w8
        w41 = w9 * w41
        w39 = w39 + w41
        w39 = w13 * w39
        w34 = w34 - w39
        w34 = w34 / w7 if w7 else _div(w34, w7)
        r0[0] = w34
        w34 = w32 * w18
        w34 = w13 * w34
        w39 = 2.0 * w5
        w23 = w25 * w23
        w27 = w27 + w23
        w23 = -0.03867513459481288
        w31 = w23 * w31
        w27 = w27 + w31
        w18 = w27 * w18
        w36 = w25 * w36
        w40 = w23 * w40
        w36 = w36 + w40
        w36 = w21 * w36
        w18 = w18 + w36
        w18 = w25 * w18
        w18 = w39 * w18
        w35 = w35 - w18
        w35 = w20 * w35
        w34 = w34 + w35
        w34 = w34 / w7 if w7 else _div(w34, w7)
        r0[1] = w34
        w3 = w26 * w3
        w26 = w26 * w2
        w3 = w3 + w26
        w3 = w7 * w3
        w26 = 2.0 * w3
        w2 = -1.7320508075688774
        w34 = w2 * w7
        w34 = w26 * w34
        w34 = w25 * w34
        w34 = w14 * w34
        w34 = w34 + w35
        w34 = w34 + w16
        w34 = -w34
        r0[2] = w34
        w4 = w4 / w11 if w11 else _div(w4, w11)
        w34 = w4 / w11 if w11 else _div(w4, w11)
        w16 = w0 * w34
        w1 = w1 / w20 if w20 else _div(w1, w20)
        w35 = w39 * w7
        w35 = w25 * w35
        w18 = w22 * w35
        w1 = w1 - w18
        w18 = w1 / w20 if w20 else _div(w1, w20)
        w22 = w22 / w20 if w20 else _div(w22, w20)
        w22 = w22 * w35
        w18 = w18 - w22
        w17 = w17 * w18
        w16 = w16 + w17
        w30 = w30 * w4
        w29 = w29 * w34
        w0 = w0 * w18
        w29 = w29 + w0
        w0 = w7 * w29
        w28 = w28 * w0
        w18 = w7 * w16
        w34 = w25 * w18
        w28 = w28 + w34
        w28 = w12 * w28
        w30 = w30 + w28
        w30 = w25 * w30
        w30 = w24 * w30
        w16 = w16 - w30
        w16 = w11 * w16
        w4 = w32 * w4
        w4 = w13 * w4
        w4 = w16 + w4
        w4 = w4 / w7 if w7 else _div(w4, w7)
        r0[3] = w4
        w32 = w32 * w1
        w32 = w13 * w32
        w4 = w35 / w20 if w20 else _div(w35, w20)
        w19 = w6 - w19
        w19 = w19 / w20 if w20 else _div(w19, w20)
        w19 = w19 / w20 if w20 else _div(w19, w20)
        w19 = w19 * w35
        w4 = w4 + w19
        w38 = w38 * w4
        w4 = w7 / w20 if w20 else _div(w7, w20)
        w5 = w5 / w20 if w20 else _div(w5, w20)
        w5 = w5 / w20 if w20 else _div(w5, w20)
        w5 = w5 * w35
        w4 = w4 - w5
        w9 = w9 * w4
        w38 = w38 + w9
        w38 = w13 * w38
        w32 = w32 - w38
        w38 = w21 * w27
        w38 = w25 * w38
        w9 = w39 * w38
        w15 = w15 - w9
        w15 = w15 * w35
        w38 = w38 * w37
        w27 = w27 * w1
        w0 = w25 * w0
        w23 = w23 * w18
        w0 = w0 + w23
        w0 = w21 * w0
        w27 = w27 + w0
        w27 = w25 * w27
        w27 = w39 * w27
        w38 = w38 + w27
        w29 = w29 - w38
        w29 = w20 * w29
        w15 = w15 + w29
        w32 = w32 + w15
        w32 = w32 / w7 if w7 else _div(w32, w7)
        r0[4] = w32
        w32 = 1.7320508075688774
        w29 = w32 * w7
        w26 = w26 * w29
        w26 = w25 * w26
        w14 = w14 * w26
        w14 = w14 + w15
        w14 = w14 + w16
        w14 = -w14
        r0[5] = w14
        w14 = -0.9330127018922194
        w14 = w14 * w7
        w14 = w13 + w14
        w16 = 0.43301270189221935
        w16 = w16 * w7
        w14 = w14 + w16
        w12 = w12 * w14
        w12 = w25 * w12
        w24 = w24 * w12
        w32 = w32 - w24
        w11 = w11 * w32
        w32 = w11 / w7 if w7 else _div(w11, w7)
        r0[6] = w32
        w32 = -0.43301270189221935
        w32 = w32 * w7
        w13 = w13 + w32
        w32 = -0.06698729810778067
        w32 = w32 * w7
        w13 = w13 + w32
        w21 = w21 * w13
        w25 = w25 * w21
        w39 = w39 * w25
        w2 = w2 - w39
        w20 = w20 * w2
        w7 = w20 / w7 if w7 else _div(w20, w7)
        r0[7] = w7
        w3 = w3 * w3
        w3 = w3 / w10 if w10 else _div(w3, w10)
        w6 = w6 + w3
        w6 = w6 + w20
        w6 = w6 + w11
        w6 = -w6
        r0[8] = w6
    return [r0]


def jacobian(z, g, p, h):
    """jacobian(z[3], g[4], p[1], h[3]) -> [J[9]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "jacobian: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "jacobian: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (1,):
        p = p.tolist()
    else:
        p = _vec(p, 1, "jacobian: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (3,):
        h = h.tolist()
    else:
        h = _vec(h, 3, "jacobian: h")
    _r = _raw_jacobian(z, g, p, h)
    return [_fromiter(_r[0], _F64, 9)]


def _raw_residual_jacobian(z, g, p, h):
    """residual_jacobian on lists of Python floats -> [F[3], J[9]] as lists (see RAW)"""
    try:
        w0, w1, w2 = z
        w4, _, w3, _ = g
        w5, = p
        w6, w8, w7 = h
        r0 = [0.0] * 3
        r1 = [0.0] * 9
        w9 = w6 * w0
        w10 = (w9 * w9) * 0.25
        w11 = 1.0 + w10
        w12 = (3.0000000000000004 * w0) + (0.4641016151377544 * w1)
        w13 = w12 / w11
        w14 = w13 / w11
        w15 = w14 - w2
        w0 = ((-6.464101615137755) * w0) + (3.0000000000000004 * w1)
        w1 = w6 * w1
        w16 = (w1 * w1) * 0.25
        w17 = 1.0 + w16
        w18 = w0 / w17
        w19 = w18 / w17
        w20 = w19 - w2
        w21 = (1.5000000000000002 * w15) + ((-3.2320508075688776) * w20)
        w22 = 2.0 * w9
        w23 = 0.5 * (w6 * w2)
        w15 = (0.2320508075688772 * w15) + (1.5000000000000002 * w20)
        w20 = w6 * w15
        w24 = w6 * w21
        w25 = (w23 + (0.5386751345948129 * w20)) + (0.25 * w24)
        w26 = 0.25 * (w13 * w25)
        w21 = w21 - (w22 * w26)
        w27 = w11 * w21
        w28 = 0.5 * w6
        w10 = (1.0 - w10) / w11
        w9 = w9 / w11
        r0[0] = ((w27 + ((((-0.5) * w13) + (w7 * (_f_cos((0.6666666666666666 * (w8 + (0.21132486540518713 * w6))))))) * w28)) + (((w3 * w10) - (w4 * w9)) * w28)) / w6
        w16 = (1.0 - w16) / w17
        w29 = w1 / w17
        w1 = 2.0 * w1
        w20 = (w23 + (0.25 * w20)) + ((-0.03867513459481288) * w24)
        w23 = 0.25 * (w18 * w20)
        w15 = w15 - (w1 * w23)
        w24 = w17 * w15
        r0[1] = ((((((-0.5) * w18) + (w7 * (_f_cos((0.6666666666666666 * (w8 + (0.7886751345948129 * w6))))))) * w28) + (((w3 * w16) - (w4 * w29)) * w28)) + w24) / w6
        w0 = w6 * ((0.5 * w12) + (0.5 * w0))
        w7 = 1.0 + ((w0 * w0) * 0.25)
        r0[2] = w5 - (((w7 * w2) + w24) + w27)
        w5 = 0.25 * (w22 * w6)
        w8 = (3.0000000000000004 / w11) - (w14 * w5)
        w12 = (w8 / w11) - ((w14 / w11) * w5)
        w14 = (-6.464101615137755) / w17
        w24 = w14 / w17
        w27 = (1.5000000000000002 * w12) + ((-3.2320508075688776) * w24)
        w30 = 2.0 * w6
        w12 = (0.2320508075688772 * w12) + (1.5000000000000002 * w24)
        w24 = w6 * w12
        w31 = w6 * w27
        w21 = (w21 * w5) + (w11 * (w27 - ((w26 * w30) + (w22 * (0.25 * ((w25 * w8) + (w13 * ((0.5386751345948129 * w24) + (0.25 * w31)))))))))
        r1[0] = ((w21 + (w28 * ((-0.5) * w8))) - (w28 * ((w3 * ((w5 / w11) + ((w10 / w11) * w5))) + (w4 * ((w6 / w11) - ((w9 / w11) * w5)))))) / w6
        w5 = w17 * (w12 - (w1 * (0.25 * ((w20 * w14) + (w18 * ((0.25 * w24) + ((-0.03867513459481288) * w31)))))))
        r1[1] = ((w28 * ((-0.5) * w14)) + w5) / w6
        w0 = 2.0 * w0
        r1[2] = -(((w2 * (0.25 * (w0 * ((-1.7320508075688774) * w6)))) + w5) + w21)
        w5 = 0.4641016151377544 / w11
        w8 = w5 / w11
        w9 = 0.25 * (w1 * w6)
        w10 = (3.0000000000000004 / w17) - (w19 * w9)
        w12 = (w10 / w17) - ((w19 / w17) * w9)
        w14 = (1.5000000000000002 * w8) + ((-3.2320508075688776) * w12)
        w8 = (0.2320508075688772 * w8) + (1.5000000000000002 * w12)
        w12 = w6 * w8
        w19 = w6 * w14
        w14 = w11 * (w14 - (w22 * (0.25 * ((w25 * w5) + (w13 * ((0.5386751345948129 * w12) + (0.25 * w19)))))))
        r1[3] = (w14 + (w28 * ((-0.5) * w5))) / w6
        w5 = (w15 * w9) + (w17 * (w8 - ((w23 * w30) + (w1 * (0.25 * ((w20 * w10) + (w18 * ((0.25 * w12) + ((-0.03867513459481288) * w19)))))))))
        r1[4] = (((w28 * ((-0.5) * w10)) - (w28 * ((w3 * ((w9 / w17) + ((w16 / w17) * w9))) + (w4 * ((w6 / w17) - ((w29 / w17) * w9)))))) + w5) / w6
        r1[5] = -(((w2 * (0.25 * (w0 * (1.7320508075688774 * w6)))) + w5) + w14)
        w0 = w11 * (1.7320508075688774 - (w22 * (0.25 * (w13 * ((w28 + ((-0.9330127018922194) * w6)) + (0.43301270189221935 * w6))))))
        r1[6] = w0 / w6
        w1 = w17 * ((-1.7320508075688774) - (w1 * (0.25 * (w18 * ((w28 + ((-0.43301270189221935) * w6)) + ((-0.06698729810778067) * w6))))))
        r1[7] = w1 / w6
        r1[8] = -((w7 + w1) + w0)
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 3
        r1 = [0.0] * 9
        w0 = 1.0
        w1 = h[0]
        w2 = z[0]
        w3 = w1 * w2
        w4 = w3 * w3
        w5 = 4.0
        w4 = w4 / w5 if w5 else _div(w4, w5)
        w6 = w0 + w4
        w7 = 1.5000000000000002
        w8 = 3.0000000000000004
        w9 = w8 * w2
        w10 = 0.4641016151377544
        w11 = z[1]
        w12 = w10 * w11
        w9 = w9 + w12
        w12 = w9 / w6 if w6 else _div(w9, w6)
        w13 = w12 / w6 if w6 else _div(w12, w6)
        w14 = z[2]
        w15 = w13 - w14
        w16 = w7 * w15
        w17 = -3.2320508075688776
        w18 = -6.464101615137755
        w2 = w18 * w2
        w19 = w8 * w11
        w2 = w2 + w19
        w11 = w1 * w11
        w19 = w11 * w11
        w19 = w19 / w5 if w5 else _div(w19, w5)
        w20 = w0 + w19
        w21 = w2 / w20 if w20 else _div(w2, w20)
        w22 = w21 / w20 if w20 else _div(w21, w20)
        w23 = w22 - w14
        w24 = w17 * w23
        w16 = w16 + w24
        w24 = 2.0 * w3
        w25 = 0.25
        w26 = 0.5
        w27 = w1 * w14
        w27 = w26 * w27
        w28 = 0.5386751345948129
        w29 = 0.2320508075688772
        w15 = w29 * w15
        w23 = w7 * w23
        w15 = w15 + w23
        w23 = w1 * w15
        w30 = w28 * w23
        w30 = w27 + w30
        w31 = w1 * w16
        w32 = w25 * w31
        w30 = w30 + w32
        w32 = w12 * w30
        w32 = w25 * w32
        w33 = w24 * w32
        w16 = w16 - w33
        w33 = w6 * w16
        w34 = -0.5
        w35 = w34 * w12
        w36 = h[2]
        w37 = 0.6666666666666666
        w38 = h[1]
        w39 = 0.21132486540518713
        w39 = w39 * w1
        w39 = w38 + w39
        w39 = w37 * w39
        w39 = _cos(w39)
        w39 = w36 * w39
        w35 = w35 + w39
        w39 = w26 * w1
        w35 = w35 * w39
        w35 = w33 + w35
        w40 = g[2]
        w4 = w0 - w4
        w4 = w4 / w6 if w6 else _div(w4, w6)
        w41 = w40 * w4
        w42 = g[0]
        w3 = w3 / w6 if w6 else _div(w3, w6)
        w43 = w42 * w3
        w41 = w41 - w43
        w41 = w41 * w39
        w35 = w35 + w41
        w35 = w35 / w1 if w1 else _div(w35, w1)
        r0[0] = w35
        w35 = w34 * w21
        w41 = 0.7886751345948129
        w41 = w41 * w1
        w38 = w38 + w41
        w37 = w37 * w38
        w37 = _cos(w37)
        w36 = w36 * w37
        w35 = w35 + w36
        w35 = w35 * w39
        w19 = w0 - w19
        w19 = w19 / w20 if w20 else _div(w19, w20)
        w36 = w40 * w19
        w37 = w11 / w20 if w20 else _div(w11, w20)
        w38 = w42 * w37
        w36 = w36 - w38
        w36 = w36 * w39
        w35 = w35 + w36
        w11 = 2.0 * w11
        w23 = w25 * w23
        w27 = w27 + w23
        w23 = -0.03867513459481288
        w31 = w23 * w31
        w27 = w27 + w31
        w31 = w21 * w27
        w31 = w25 * w31
        w36 = w11 * w31
        w15 = w15 - w36
        w36 = w20 * w15
        w35 = w35 + w36
        w35 = w35 / w1 if w1 else _div(w35, w1)
        r0[1] = w35
        w35 = p[0]
        w9 = w26 * w9
        w26 = w26 * w2
        w9 = w9 + w26
        w9 = w1 * w9
        w26 = w9 * w9
        w26 = w26 / w5 if w5 else _div(w26, w5)
        w0 = w0 + w26
        w26 = w0 * w14
        w26 = w26 + w36
        w26 = w26 + w33
        w35 = w35 - w26
        r0[2] = w35
        w35 = w24 * w1
        w35 = w25 * w35
        w16 = w16 * w35
        w26 = w8 / w6 if w6 else _div(w8, w6)
        w33 = w13 * w35
        w26 = w26 - w33
        w33 = w26 / w6 if w6 else _div(w26, w6)
        w13 = w13 / w6 if w6 else _div(w13, w6)
        w13 = w13 * w35
        w33 = w33 - w13
        w13 = w7 * w33
        w18 = w18 / w20 if w20 else _div(w18, w20)
        w36 = w18 / w20 if w20 else _div(w18, w20)
        w5 = w17 * w36
        w13 = w13 + w5
        w5 = 2.0 * w1
        w32 = w32 * w5
        w2 = w30 * w26
        w33 = w29 * w33
        w36 = w7 * w36
        w33 = w33 + w36
        w36 = w1 * w33
        w38 = w28 * w36
        w41 = w1 * w13
        w43 = w25 * w41
        w38 = w38 + w43
        w38 = w12 * w38
        w2 = w2 + w38
        w2 = w25 * w2
        w2 = w24 * w2
        w32 = w32 + w2
        w13 = w13 - w32
        w13 = w6 * w13
        w16 = w16 + w13
        w26 = w34 * w26
        w26 = w39 * w26
        w26 = w16 + w26
        w13 = w35 / w6 if w6 else _div(w35, w6)
        w4 = w4 / w6 if w6 else _div(w4, w6)
        w4 = w4 * w35
        w13 = w13 + w4
        w13 = w40 * w13
        w4 = w1 / w6 if w6 else _div(w1, w6)
        w3 = w3 / w6 if w6 else _div(w3, w6)
        w3 = w3 * w35
        w4 = w4 - w3
        w4 = w42 * w4
        w13 = w13 + w4
        w13 = w39 * w13
        w26 = w26 - w13
        w26 = w26 / w1 if w1 else _div(w26, w1)
        r1[0] = w26
        w26 = w34 * w18
        w26 = w39 * w26
        w18 = w27 * w18
        w36 = w25 * w36
        w41 = w23 * w41
        w36 = w36 + w41
        w36 = w21 * w36
        w18 = w18 + w36
        w18 = w25 * w18
        w18 = w11 * w18
        w33 = w33 - w18
        w33 = w20 * w33
        w26 = w26 + w33
        w26 = w26 / w1 if w1 else _div(w26, w1)
        r1[1] = w26
        w9 = 2.0 * w9
        w26 = -1.7320508075688774
        w18 = w26 * w1
        w18 = w9 * w18
        w18 = w25 * w18
        w18 = w14 * w18
        w18 = w18 + w33
        w18 = w18 + w16
        w18 = -w18
        r1[2] = w18
        w10 = w10 / w6 if w6 else _div(w10, w6)
        w18 = w10 / w6 if w6 else _div(w10, w6)
        w16 = w7 * w18
        w8 = w8 / w20 if w20 else _div(w8, w20)
        w33 = w11 * w1
        w33 = w25 * w33
        w36 = w22 * w33
        w8 = w8 - w36
        w36 = w8 / w20 if w20 else _div(w8, w20)
        w22 = w22 / w20 if w20 else _div(w22, w20)
        w22 = w22 * w33
        w36 = w36 - w22
        w17 = w17 * w36
        w16 = w16 + w17
        w30 = w30 * w10
        w29 = w29 * w18
        w7 = w7 * w36
        w29 = w29 + w7
        w7 = w1 * w29
        w28 = w28 * w7
        w36 = w1 * w16
        w18 = w25 * w36
        w28 = w28 + w18
        w28 = w12 * w28
        w30 = w30 + w28
        w30 = w25 * w30
        w30 = w24 * w30
        w16 = w16 - w30
        w16 = w6 * w16
        w10 = w34 * w10
        w10 = w39 * w10
        w10 = w16 + w10
        w10 = w10 / w1 if w1 else _div(w10, w1)
        r1[3] = w10
        w34 = w34 * w8
        w34 = w39 * w34
        w10 = w33 / w20 if w20 else _div(w33, w20)
        w19 = w19 / w20 if w20 else _div(w19, w20)
        w19 = w19 * w33
        w10 = w10 + w19
        w40 = w40 * w10
        w10 = w1 / w20 if w20 else _div(w1, w20)
        w37 = w37 / w20 if w20 else _div(w37, w20)
        w37 = w37 * w33
        w10 = w10 - w37
        w42 = w42 * w10
        w40 = w40 + w42
        w40 = w39 * w40
        w34 = w34 - w40
        w15 = w15 * w33
        w31 = w31 * w5
        w27 = w27 * w8
        w7 = w25 * w7
        w23 = w23 * w36
        w7 = w7 + w23
        w7 = w21 * w7
        w27 = w27 + w7
        w27 = w25 * w27
        w27 = w11 * w27
        w31 = w31 + w27
        w29 = w29 - w31
        w29 = w20 * w29
        w15 = w15 + w29
        w34 = w34 + w15
        w34 = w34 / w1 if w1 else _div(w34, w1)
        r1[4] = w34
        w34 = 1.7320508075688774
        w29 = w34 * w1
        w9 = w9 * w29
        w9 = w25 * w9
        w14 = w14 * w9
        w14 = w14 + w15
        w14 = w14 + w16
        w14 = -w14
        r1[5] = w14
        w14 = -0.9330127018922194
        w14 = w14 * w1
        w14 = w39 + w14
        w16 = 0.43301270189221935
        w16 = w16 * w1
        w14 = w14 + w16
        w12 = w12 * w14
        w12 = w25 * w12
        w24 = w24 * w12
        w34 = w34 - w24
        w6 = w6 * w34
        w34 = w6 / w1 if w1 else _div(w6, w1)
        r1[6] = w34
        w34 = -0.43301270189221935
        w34 = w34 * w1
        w39 = w39 + w34
        w34 = -0.06698729810778067
        w34 = w34 * w1
        w39 = w39 + w34
        w21 = w21 * w39
        w25 = w25 * w21
        w11 = w11 * w25
        w26 = w26 - w11
        w20 = w20 * w26
        w1 = w20 / w1 if w1 else _div(w20, w1)
        r1[7] = w1
        w0 = w0 + w20
        w0 = w0 + w6
        w0 = -w0
        r1[8] = w0
    return [r0, r1]


def residual_jacobian(z, g, p, h):
    """residual_jacobian(z[3], g[4], p[1], h[3]) -> [F[3], J[9]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "residual_jacobian: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "residual_jacobian: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (1,):
        p = p.tolist()
    else:
        p = _vec(p, 1, "residual_jacobian: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (3,):
        h = h.tolist()
    else:
        h = _vec(h, 3, "residual_jacobian: h")
    _r = _raw_residual_jacobian(z, g, p, h)
    return [_fromiter(_r[0], _F64, 3), _fromiter(_r[1], _F64, 9)]


def _raw_update(z, g, p, h):
    """update on lists of Python floats -> [g1[4], p1[1]] as lists (see RAW)"""
    try:
        w0, w1, w2 = z
        w3, w5, w4, w6 = g
        w7, _, _ = h
        r0 = [0.0] * 4
        r1 = [0.0] * 1
        w0 = w7 * ((0.5 * ((3.0000000000000004 * w0) + (0.4641016151377544 * w1))) + (0.5 * (((-6.464101615137755) * w0) + (3.0000000000000004 * w1))))
        w1 = (w0 * w0) * 0.25
        w7 = 1.0 + w1
        w1 = (1.0 - w1) / w7
        w0 = w0 / w7
        r0[0] = (w3 * w1) + (w4 * w0)
        r0[1] = (w5 * w1) + (w6 * w0)
        r0[2] = (w4 * w1) - (w3 * w0)
        r0[3] = (w6 * w1) - (w5 * w0)
        r1[0] = w7 * w2
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 4
        r1 = [0.0] * 1
        w0 = g[0]
        w1 = 1.0
        w2 = h[0]
        w3 = 0.5
        w4 = 3.0000000000000004
        w5 = z[0]
        w6 = w4 * w5
        w7 = 0.4641016151377544
        w8 = z[1]
        w7 = w7 * w8
        w6 = w6 + w7
        w6 = w3 * w6
        w7 = -6.464101615137755
        w7 = w7 * w5
        w4 = w4 * w8
        w7 = w7 + w4
        w3 = w3 * w7
        w6 = w6 + w3
        w2 = w2 * w6
        w6 = w2 * w2
        w3 = 4.0
        w6 = w6 / w3 if w3 else _div(w6, w3)
        w3 = w1 - w6
        w1 = w1 + w6
        w3 = w3 / w1 if w1 else _div(w3, w1)
        w6 = w0 * w3
        w7 = g[2]
        w2 = w2 / w1 if w1 else _div(w2, w1)
        w4 = w7 * w2
        w6 = w6 + w4
        r0[0] = w6
        w6 = g[1]
        w4 = w6 * w3
        w8 = g[3]
        w5 = w8 * w2
        w4 = w4 + w5
        r0[1] = w4
        w7 = w7 * w3
        w0 = w0 * w2
        w7 = w7 - w0
        r0[2] = w7
        w8 = w8 * w3
        w6 = w6 * w2
        w8 = w8 - w6
        r0[3] = w8
        w8 = z[2]
        w1 = w1 * w8
        r1[0] = w1
    return [r0, r1]


def update(z, g, p, h):
    """update(z[3], g[4], p[1], h[3]) -> [g1[4], p1[1]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "update: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "update: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (1,):
        p = p.tolist()
    else:
        p = _vec(p, 1, "update: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (3,):
        h = h.tolist()
    else:
        h = _vec(h, 3, "update: h")
    _r = _raw_update(z, g, p, h)
    return [_fromiter(_r[0], _F64, 4), _fromiter(_r[1], _F64, 1)]


def _raw_guess(xi, g, p, h):
    """guess on lists of Python floats -> [z0[3]] as lists (see RAW)"""
    w0, = xi
    w1, = p
    r0 = [0.0] * 3
    r0[0] = 0.21132486540518713 * w0
    r0[1] = 0.7886751345948129 * w0
    r0[2] = w1
    return [r0]


def guess(xi, g, p, h):
    """guess(xi[1], g[4], p[1], h[3]) -> [z0[3]]"""
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (1,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 1, "guess: xi")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "guess: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (1,):
        p = p.tolist()
    else:
        p = _vec(p, 1, "guess: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (3,):
        h = h.tolist()
    else:
        h = _vec(h, 3, "guess: h")
    _r = _raw_guess(xi, g, p, h)
    return [_fromiter(_r[0], _F64, 3)]


def _raw_legendre(g, xi, h):
    """legendre on lists of Python floats -> [mu[1]] as lists (see RAW)"""
    w0, = xi
    r0 = [0.0] * 1
    r0[0] = w0
    return [r0]


def legendre(g, xi, h):
    """legendre(g[4], xi[1], h[3]) -> [mu[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "legendre: g")
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (1,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 1, "legendre: xi")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (3,):
        h = h.tolist()
    else:
        h = _vec(h, 3, "legendre: h")
    _r = _raw_legendre(g, xi, h)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_hessian(g, xi, h):
    """hessian on lists of Python floats -> [H[1]] as lists (see RAW)"""
    r0 = [0.0] * 1
    r0[0] = 1.0
    return [r0]


def hessian(g, xi, h):
    """hessian(g[4], xi[1], h[3]) -> [H[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "hessian: g")
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (1,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 1, "hessian: xi")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (3,):
        h = h.tolist()
    else:
        h = _vec(h, 3, "hessian: h")
    _r = _raw_hessian(g, xi, h)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_energy(g, xi, h):
    """energy on lists of Python floats -> [E[1]] as lists (see RAW)"""
    w0, _, _, _ = g
    w1, = xi
    r0 = [0.0] * 1
    w1 = w1 * w1
    r0[0] = w1 - ((0.5 * w1) + w0)
    return [r0]


def energy(g, xi, h):
    """energy(g[4], xi[1], h[3]) -> [E[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "energy: g")
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (1,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 1, "energy: xi")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (3,):
        h = h.tolist()
    else:
        h = _vec(h, 3, "energy: h")
    _r = _raw_energy(g, xi, h)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_momentum(g, p):
    """momentum on lists of Python floats -> [m[1]] as lists (see RAW)"""
    w1, w3, w2, w0 = g
    w4, = p
    r0 = [0.0] * 1
    r0[0] = ((w0 * w1) - (w2 * w3)) * w4
    return [r0]


def momentum(g, p):
    """momentum(g[4], p[1]) -> [m[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "momentum: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (1,):
        p = p.tolist()
    else:
        p = _vec(p, 1, "momentum: p")
    _r = _raw_momentum(g, p)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_defect(g):
    """defect on lists of Python floats -> [e[1]] as lists (see RAW)"""
    w0, w1, w2, w3 = g
    r0 = [0.0] * 1
    w4 = _f_fabs(((w2 * w0) + (w3 * w1)))
    r0[0] = _fmax((_fmax((_fmax((_fmax((_f_fabs((((w0 * w0) + (w1 * w1)) - 1.0))), w4)), w4)), (_f_fabs((((w2 * w2) + (w3 * w3)) - 1.0))))), (_f_fabs((((w0 * w3) - (w2 * w1)) - 1.0))))
    return [r0]


def defect(g):
    """defect(g[4]) -> [e[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "defect: g")
    _r = _raw_defect(g)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_margin(z, h):
    """margin on lists of Python floats -> [m[1]] as lists (see RAW)"""
    w0, w1, _ = z
    w2, _, _ = h
    r0 = [0.0] * 1
    w3 = w2 * w0
    w3 = 4.0 - (w3 * w3)
    w4 = w2 * w1
    w4 = 4.0 - (w4 * w4)
    w0 = w2 * ((0.5 * ((3.0000000000000004 * w0) + (0.4641016151377544 * w1))) + (0.5 * (((-6.464101615137755) * w0) + (3.0000000000000004 * w1))))
    w0 = 4.0 - (w0 * w0)
    r0[0] = _fmin((_fmin((_fmin((_fmin((_fmin((_fmin(1.0, w3)), w3)), w4)), w4)), w0)), w0)
    return [r0]


def margin(z, h):
    """margin(z[3], h[3]) -> [m[1]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "margin: z")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (3,):
        h = h.tolist()
    else:
        h = _vec(h, 3, "margin: h")
    _r = _raw_margin(z, h)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_section(g, p):
    """section on lists of Python floats -> [s[1]] as lists (see RAW)"""
    r0 = [0.0] * 1
    r0[0] = 1.0
    return [r0]


def section(g, p):
    """section(g[4], p[1]) -> [s[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "section: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (1,):
        p = p.tolist()
    else:
        p = _vec(p, 1, "section: p")
    _r = _raw_section(g, p)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_chart_point(z, g, h, theta):
    """chart_point on lists of Python floats -> [g_theta[4]] as lists (see RAW)"""
    try:
        w0, w1, _ = z
        w2, w4, w3, w5 = g
        w6, _, _ = h
        w7, = theta
        r0 = [0.0] * 4
        w0 = w7 * (w6 * ((0.5 * ((3.0000000000000004 * w0) + (0.4641016151377544 * w1))) + (0.5 * (((-6.464101615137755) * w0) + (3.0000000000000004 * w1)))))
        w1 = (w0 * w0) * 0.25
        w6 = 1.0 + w1
        w1 = (1.0 - w1) / w6
        w0 = w0 / w6
        r0[0] = (w2 * w1) + (w3 * w0)
        r0[1] = (w4 * w1) + (w5 * w0)
        r0[2] = (w3 * w1) - (w2 * w0)
        r0[3] = (w5 * w1) - (w4 * w0)
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 4
        w0 = g[0]
        w1 = 1.0
        w2 = theta[0]
        w3 = h[0]
        w4 = 0.5
        w5 = 3.0000000000000004
        w6 = z[0]
        w7 = w5 * w6
        w8 = 0.4641016151377544
        w9 = z[1]
        w8 = w8 * w9
        w7 = w7 + w8
        w7 = w4 * w7
        w8 = -6.464101615137755
        w8 = w8 * w6
        w5 = w5 * w9
        w8 = w8 + w5
        w4 = w4 * w8
        w7 = w7 + w4
        w3 = w3 * w7
        w2 = w2 * w3
        w3 = w2 * w2
        w7 = 4.0
        w3 = w3 / w7 if w7 else _div(w3, w7)
        w7 = w1 - w3
        w1 = w1 + w3
        w7 = w7 / w1 if w1 else _div(w7, w1)
        w3 = w0 * w7
        w4 = g[2]
        w2 = w2 / w1 if w1 else _div(w2, w1)
        w1 = w4 * w2
        w3 = w3 + w1
        r0[0] = w3
        w3 = g[1]
        w1 = w3 * w7
        w8 = g[3]
        w5 = w8 * w2
        w1 = w1 + w5
        r0[1] = w1
        w4 = w4 * w7
        w0 = w0 * w2
        w4 = w4 - w0
        r0[2] = w4
        w8 = w8 * w7
        w3 = w3 * w2
        w8 = w8 - w3
        r0[3] = w8
    return [r0]


def chart_point(z, g, h, theta):
    """chart_point(z[3], g[4], h[3], theta[1]) -> [g_theta[4]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "chart_point: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "chart_point: g")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (3,):
        h = h.tolist()
    else:
        h = _vec(h, 3, "chart_point: h")
    if _type(theta) is _NDARRAY and theta.dtype is _F64 and theta.shape == (1,):
        theta = theta.tolist()
    else:
        theta = _vec(theta, 1, "chart_point: theta")
    _r = _raw_chart_point(z, g, h, theta)
    return [_fromiter(_r[0], _F64, 4)]


def _raw_observe(g, p, h):
    """observe on lists of Python floats -> [xi[1], E[1], m[1], e[1]] as lists (see RAW)"""
    w0, w3, w2, w1 = g
    w4, = p
    r0 = [0.0] * 1
    r1 = [0.0] * 1
    r2 = [0.0] * 1
    r3 = [0.0] * 1
    r0[0] = w4
    w5 = w4 * w4
    r1[0] = w5 - ((0.5 * w5) + w0)
    w5 = (w1 * w0) - (w2 * w3)
    r2[0] = w5 * w4
    w4 = _f_fabs(((w2 * w0) + (w1 * w3)))
    r3[0] = _fmax((_fmax((_fmax((_fmax((_f_fabs((((w0 * w0) + (w3 * w3)) - 1.0))), w4)), w4)), (_f_fabs((((w2 * w2) + (w1 * w1)) - 1.0))))), (_f_fabs((w5 - 1.0))))
    return [r0, r1, r2, r3]


def observe(g, p, h):
    """observe(g[4], p[1], h[3]) -> [xi[1], E[1], m[1], e[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "observe: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (1,):
        p = p.tolist()
    else:
        p = _vec(p, 1, "observe: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (3,):
        h = h.tolist()
    else:
        h = _vec(h, 3, "observe: h")
    _r = _raw_observe(g, p, h)
    return [_fromiter(_r[0], _F64, 1), _fromiter(_r[1], _F64, 1), _fromiter(_r[2], _F64, 1), _fromiter(_r[3], _F64, 1)]


def _raw_update_p(z, g, p, h):
    """update_p on lists of Python floats -> [p1[1]] as lists (see RAW)"""
    w0, w1, w2 = z
    w3, _, _ = h
    r0 = [0.0] * 1
    w0 = w3 * ((0.5 * ((3.0000000000000004 * w0) + (0.4641016151377544 * w1))) + (0.5 * (((-6.464101615137755) * w0) + (3.0000000000000004 * w1))))
    r0[0] = (1.0 + ((w0 * w0) * 0.25)) * w2
    return [r0]


def update_p(z, g, p, h):
    """update_p(z[3], g[4], p[1], h[3]) -> [p1[1]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "update_p: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "update_p: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (1,):
        p = p.tolist()
    else:
        p = _vec(p, 1, "update_p: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (3,):
        h = h.tolist()
    else:
        h = _vec(h, 3, "update_p: h")
    _r = _raw_update_p(z, g, p, h)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_velocity_step(g, p, xi, h):
    """velocity_step on lists of Python floats -> [xi1[1]] as lists (see RAW)"""
    w0, = p
    w1, = xi
    r0 = [0.0] * 1
    r0[0] = w1 - (w1 - w0)
    return [r0]


def velocity_step(g, p, xi, h):
    """velocity_step(g[4], p[1], xi[1], h[3]) -> [xi1[1]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "velocity_step: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (1,):
        p = p.tolist()
    else:
        p = _vec(p, 1, "velocity_step: p")
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (1,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 1, "velocity_step: xi")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (3,):
        h = h.tolist()
    else:
        h = _vec(h, 3, "velocity_step: h")
    _r = _raw_velocity_step(g, p, xi, h)
    return [_fromiter(_r[0], _F64, 1)]


def _raw_record(g, p, xi, h):
    """record on lists of Python floats -> [row[7]] as lists (see RAW)"""
    try:
        w0, w1, w2, w3 = g
        w4, = p
        w5, = xi
        _, w7, w6 = h
        r0 = [0.0] * 7
        r0[0] = w0
        r0[1] = w1
        r0[2] = w2
        r0[3] = w3
        r0[4] = w4
        w1 = w5 * w5
        r0[5] = w1 - ((0.5 * w1) + w0)
        r0[6] = (((-0.5) * w5) + (w6 * (_f_cos((0.6666666666666666 * w7))))) * w5
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 7
        w0 = g[0]
        r0[0] = w0
        w1 = g[1]
        r0[1] = w1
        w1 = g[2]
        r0[2] = w1
        w1 = g[3]
        r0[3] = w1
        w1 = p[0]
        r0[4] = w1
        w1 = xi[0]
        w2 = w1 * w1
        w3 = 0.5
        w3 = w3 * w2
        w3 = w3 + w0
        w2 = w2 - w3
        r0[5] = w2
        w2 = -0.5
        w2 = w2 * w1
        w3 = h[2]
        w0 = 0.6666666666666666
        w4 = h[1]
        w0 = w0 * w4
        w0 = _cos(w0)
        w3 = w3 * w0
        w2 = w2 + w3
        w2 = w2 * w1
        r0[6] = w2
    return [r0]


def record(g, p, xi, h):
    """record(g[4], p[1], xi[1], h[3]) -> [row[7]]"""
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "record: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (1,):
        p = p.tolist()
    else:
        p = _vec(p, 1, "record: p")
    if _type(xi) is _NDARRAY and xi.dtype is _F64 and xi.shape == (1,):
        xi = xi.tolist()
    else:
        xi = _vec(xi, 1, "record: xi")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (3,):
        h = h.tolist()
    else:
        h = _vec(h, 3, "record: h")
    _r = _raw_record(g, p, xi, h)
    return [_fromiter(_r[0], _F64, 7)]


def _raw_step_partials(z, g, p, h):
    """step_partials on lists of Python floats -> [Fs[6], Yz[6], Ys[4], FH[9], YH[6]] as lists (see RAW)"""
    try:
        w0, w1, w2 = z
        w3, w6, w4, w5 = g
        w7, w9, w8 = h
        r0 = [0.0] * 6
        r1 = [0.0] * 6
        r2 = [0.0] * 4
        r3 = [0.0] * 9
        r4 = [0.0] * 6
        w10 = 0.5 * w7
        w11 = w7 * w0
        w12 = (w11 * w11) * 0.25
        w13 = 1.0 + w12
        w12 = (1.0 - w12) / w13
        w14 = w11 / w13
        r0[0] = -((w10 * ((w12 * w3) + (w14 * w4))) / w7)
        w15 = w7 * w1
        w16 = (w15 * w15) * 0.25
        w17 = 1.0 + w16
        w16 = (1.0 - w16) / w17
        w18 = w15 / w17
        r0[1] = -((w10 * ((w16 * w3) + (w18 * w4))) / w7)
        r0[2] = 0.0
        r0[3] = 0.0
        r0[4] = 0.0
        r0[5] = 1.0
        w19 = (3.0000000000000004 * w0) + (0.4641016151377544 * w1)
        w20 = ((-6.464101615137755) * w0) + (3.0000000000000004 * w1)
        w21 = (0.5 * w19) + (0.5 * w20)
        w22 = w7 * w21
        w23 = (w22 * w22) * 0.25
        w24 = 1.0 + w23
        w23 = (1.0 - w23) / w24
        w25 = w22 / w24
        w26 = (w4 * w23) - (w3 * w25)
        w27 = (-1.7320508075688774) * w7
        w28 = w25 / w24
        w22 = 2.0 * w22
        w29 = 0.25 * (w22 * w27)
        w27 = (w27 / w24) - (w28 * w29)
        w30 = w23 / w24
        w31 = (w29 / w24) + (w30 * w29)
        w23 = (w5 * w23) - (w6 * w25)
        r1[0] = (w26 * ((w4 * w27) - (w3 * w31))) + (w23 * ((w5 * w27) - (w6 * w31)))
        r1[1] = w2 * w29
        w25 = 1.7320508075688774 * w7
        w27 = 0.25 * (w22 * w25)
        w25 = (w25 / w24) - (w28 * w27)
        w29 = (w27 / w24) + (w30 * w27)
        r1[2] = (w26 * ((w4 * w25) - (w3 * w29))) + (w23 * ((w5 * w25) - (w6 * w29)))
        r1[3] = w2 * w27
        r1[4] = 0.0
        r1[5] = w24
        r2[0] = (w26 * w26) + (w23 * w23)
        r2[1] = 0.0
        r2[2] = 0.0
        r2[3] = 0.0
        w19 = w19 / w13
        w25 = w19 / w13
        w27 = w25 - w2
        w20 = w20 / w17
        w29 = w20 / w17
        w31 = w29 - w2
        w32 = (1.5000000000000002 * w27) + ((-3.2320508075688776) * w31)
        w11 = 2.0 * w11
        w33 = 0.5 * (w7 * w2)
        w27 = (0.2320508075688772 * w27) + (1.5000000000000002 * w31)
        w31 = w7 * w27
        w34 = w7 * w32
        w35 = (w33 + (0.5386751345948129 * w31)) + (0.25 * w34)
        w36 = 0.25 * (w19 * w35)
        w37 = w32 - (w11 * w36)
        w38 = 0.25 * (w11 * w0)
        w39 = w25 * w38
        w25 = (w39 / w13) + ((w25 / w13) * w38)
        w15 = 2.0 * w15
        w40 = 0.25 * (w15 * w1)
        w41 = w29 * w40
        w29 = (w41 / w17) + ((w29 / w17) * w40)
        w42 = (1.5000000000000002 * w25) + ((-3.2320508075688776) * w29)
        w43 = 0.5 * w2
        w25 = (0.2320508075688772 * w25) + (1.5000000000000002 * w29)
        w29 = w27 - (w7 * w25)
        w32 = w32 - (w7 * w42)
        w11 = (w37 * w38) - (w13 * (w42 + ((w36 * (2.0 * w0)) + (w11 * (0.25 * ((w19 * ((w43 + (0.5386751345948129 * w29)) + (0.25 * w32))) - (w35 * w39)))))))
        w35 = 0.6666666666666666 * (w9 + (0.21132486540518713 * w7))
        w36 = _f_cos(w35)
        w19 = ((-0.5) * w19) + (w8 * w36)
        w35 = _f_sin(w35)
        w42 = (w4 * w12) - (w3 * w14)
        r3[0] = (((w11 + ((0.5 * w19) - (w10 * (((-0.5) * w39) + (w8 * (0.14088324360345808 * w35)))))) + ((0.5 * w42) - (w10 * ((w4 * ((w38 / w13) + ((w12 / w13) * w38))) + (w3 * ((w0 / w13) - ((w14 / w13) * w38))))))) / w7) - (((((w13 * w37) + (w19 * w10)) + (w42 * w10)) / w7) / w7)
        w0 = 0.6666666666666666 * (w9 + (0.7886751345948129 * w7))
        w9 = _f_cos(w0)
        w12 = ((-0.5) * w20) + (w8 * w9)
        w0 = _f_sin(w0)
        w13 = (w4 * w16) - (w3 * w18)
        w14 = (w33 + (0.25 * w31)) + ((-0.03867513459481288) * w34)
        w19 = 0.25 * (w20 * w14)
        w27 = w27 - (w15 * w19)
        w14 = (w27 * w40) - (w17 * (w25 + ((w19 * (2.0 * w1)) + (w15 * (0.25 * ((w20 * ((w43 + (0.25 * w29)) + ((-0.03867513459481288) * w32))) - (w14 * w41)))))))
        r3[1] = (((((0.5 * w12) - (w10 * (((-0.5) * w41) + (w8 * (0.5257834230632086 * w0))))) + ((0.5 * w13) - (w10 * ((w4 * ((w40 / w17) + ((w16 / w17) * w40))) + (w3 * ((w1 / w17) - ((w18 / w17) * w40))))))) + w14) / w7) - (((((w12 * w10) + (w13 * w10)) + (w17 * w27)) / w7) / w7)
        w1 = 0.25 * (w22 * w21)
        w2 = w2 * w1
        r3[2] = -((w2 + w14) + w11)
        r3[3] = -((w10 * (w8 * (0.6666666666666666 * w35))) / w7)
        r3[4] = -((w10 * (w8 * (0.6666666666666666 * w0))) / w7)
        r3[5] = 0.0
        r3[6] = (w10 * w36) / w7
        r3[7] = (w10 * w9) / w7
        r3[8] = 0.0
        w0 = (w21 / w24) - (w28 * w1)
        w1 = (w1 / w24) + (w30 * w1)
        r4[0] = (w26 * ((w4 * w0) - (w3 * w1))) + (w23 * ((w5 * w0) - (w6 * w1)))
        r4[1] = w2
        r4[2] = 0.0
        r4[3] = 0.0
        r4[4] = 0.0
        r4[5] = 0.0
    except (ArithmeticError, ValueError):
        # a zero divisor or a math domain/range error: recompute with C semantics
        r0 = [0.0] * 6
        r1 = [0.0] * 6
        r2 = [0.0] * 4
        r3 = [0.0] * 9
        r4 = [0.0] * 6
        w0 = 0.5
        w1 = h[0]
        w2 = w0 * w1
        w3 = 1.0
        w4 = z[0]
        w5 = w1 * w4
        w6 = w5 * w5
        w7 = 4.0
        w6 = w6 / w7 if w7 else _div(w6, w7)
        w8 = w3 - w6
        w6 = w3 + w6
        w8 = w8 / w6 if w6 else _div(w8, w6)
        w9 = g[0]
        w10 = w8 * w9
        w11 = w5 / w6 if w6 else _div(w5, w6)
        w12 = g[2]
        w13 = w11 * w12
        w10 = w10 + w13
        w10 = w2 * w10
        w10 = w10 / w1 if w1 else _div(w10, w1)
        w10 = -w10
        r0[0] = w10
        w10 = z[1]
        w13 = w1 * w10
        w14 = w13 * w13
        w14 = w14 / w7 if w7 else _div(w14, w7)
        w15 = w3 - w14
        w14 = w3 + w14
        w15 = w15 / w14 if w14 else _div(w15, w14)
        w16 = w15 * w9
        w17 = w13 / w14 if w14 else _div(w13, w14)
        w18 = w17 * w12
        w16 = w16 + w18
        w16 = w2 * w16
        w16 = w16 / w1 if w1 else _div(w16, w1)
        w16 = -w16
        r0[1] = w16
        w16 = 0.0
        r0[2] = w16
        r0[3] = w16
        r0[4] = w16
        r0[5] = w3
        w18 = 3.0000000000000004
        w19 = w18 * w4
        w20 = 0.4641016151377544
        w20 = w20 * w10
        w19 = w19 + w20
        w20 = w0 * w19
        w21 = -6.464101615137755
        w21 = w21 * w4
        w18 = w18 * w10
        w21 = w21 + w18
        w18 = w0 * w21
        w20 = w20 + w18
        w18 = w1 * w20
        w22 = w18 * w18
        w22 = w22 / w7 if w7 else _div(w22, w7)
        w7 = w3 - w22
        w3 = w3 + w22
        w7 = w7 / w3 if w3 else _div(w7, w3)
        w22 = w12 * w7
        w23 = w18 / w3 if w3 else _div(w18, w3)
        w24 = w9 * w23
        w22 = w22 - w24
        w24 = -1.7320508075688774
        w24 = w24 * w1
        w25 = w24 / w3 if w3 else _div(w24, w3)
        w26 = w23 / w3 if w3 else _div(w23, w3)
        w27 = 0.25
        w18 = 2.0 * w18
        w24 = w18 * w24
        w24 = w27 * w24
        w28 = w26 * w24
        w25 = w25 - w28
        w28 = w12 * w25
        w29 = w24 / w3 if w3 else _div(w24, w3)
        w30 = w7 / w3 if w3 else _div(w7, w3)
        w31 = w30 * w24
        w29 = w29 + w31
        w31 = w9 * w29
        w28 = w28 - w31
        w28 = w22 * w28
        w31 = g[3]
        w32 = w31 * w7
        w33 = g[1]
        w34 = w33 * w23
        w32 = w32 - w34
        w25 = w31 * w25
        w29 = w33 * w29
        w25 = w25 - w29
        w25 = w32 * w25
        w28 = w28 + w25
        r1[0] = w28
        w28 = z[2]
        w24 = w28 * w24
        r1[1] = w24
        w24 = 1.7320508075688774
        w24 = w24 * w1
        w25 = w24 / w3 if w3 else _div(w24, w3)
        w24 = w18 * w24
        w24 = w27 * w24
        w29 = w26 * w24
        w25 = w25 - w29
        w29 = w12 * w25
        w34 = w24 / w3 if w3 else _div(w24, w3)
        w35 = w30 * w24
        w34 = w34 + w35
        w35 = w9 * w34
        w29 = w29 - w35
        w29 = w22 * w29
        w25 = w31 * w25
        w34 = w33 * w34
        w25 = w25 - w34
        w25 = w32 * w25
        w29 = w29 + w25
        r1[2] = w29
        w24 = w28 * w24
        r1[3] = w24
        r1[4] = w16
        r1[5] = w3
        w24 = w7 * w12
        w29 = w23 * w9
        w24 = w24 - w29
        w24 = w22 * w24
        w7 = w7 * w31
        w23 = w23 * w33
        w7 = w7 - w23
        w7 = w32 * w7
        w24 = w24 + w7
        r2[0] = w24
        r2[1] = w16
        r2[2] = w16
        r2[3] = w16
        w24 = 1.5000000000000002
        w19 = w19 / w6 if w6 else _div(w19, w6)
        w7 = w19 / w6 if w6 else _div(w19, w6)
        w23 = w7 - w28
        w29 = w24 * w23
        w25 = -3.2320508075688776
        w21 = w21 / w14 if w14 else _div(w21, w14)
        w34 = w21 / w14 if w14 else _div(w21, w14)
        w35 = w34 - w28
        w36 = w25 * w35
        w29 = w29 + w36
        w5 = 2.0 * w5
        w36 = w1 * w28
        w36 = w0 * w36
        w37 = 0.5386751345948129
        w38 = 0.2320508075688772
        w23 = w38 * w23
        w35 = w24 * w35
        w23 = w23 + w35
        w35 = w1 * w23
        w39 = w37 * w35
        w39 = w36 + w39
        w40 = w1 * w29
        w41 = w27 * w40
        w39 = w39 + w41
        w41 = w19 * w39
        w41 = w27 * w41
        w42 = w5 * w41
        w42 = w29 - w42
        w43 = w5 * w4
        w43 = w27 * w43
        w44 = w42 * w43
        w45 = w7 * w43
        w46 = w45 / w6 if w6 else _div(w45, w6)
        w7 = w7 / w6 if w6 else _div(w7, w6)
        w7 = w7 * w43
        w46 = w46 + w7
        w7 = w24 * w46
        w13 = 2.0 * w13
        w47 = w13 * w10
        w47 = w27 * w47
        w48 = w34 * w47
        w49 = w48 / w14 if w14 else _div(w48, w14)
        w34 = w34 / w14 if w14 else _div(w34, w14)
        w34 = w34 * w47
        w49 = w49 + w34
        w25 = w25 * w49
        w7 = w7 + w25
        w25 = 2.0 * w4
        w41 = w41 * w25
        w25 = w0 * w28
        w38 = w38 * w46
        w24 = w24 * w49
        w38 = w38 + w24
        w24 = w1 * w38
        w24 = w23 - w24
        w37 = w37 * w24
        w37 = w25 + w37
        w49 = w1 * w7
        w29 = w29 - w49
        w49 = w27 * w29
        w37 = w37 + w49
        w37 = w19 * w37
        w39 = w39 * w45
        w37 = w37 - w39
        w37 = w27 * w37
        w5 = w5 * w37
        w41 = w41 + w5
        w7 = w7 + w41
        w7 = w6 * w7
        w44 = w44 - w7
        w7 = -0.5
        w19 = w7 * w19
        w41 = h[2]
        w5 = 0.6666666666666666
        w37 = h[1]
        w39 = 0.21132486540518713
        w39 = w39 * w1
        w39 = w37 + w39
        w39 = w5 * w39
        w49 = _cos(w39)
        w46 = w41 * w49
        w19 = w19 + w46
        w46 = w0 * w19
        w45 = w7 * w45
        w34 = 0.14088324360345808
        w39 = _sin(w39)
        w34 = w34 * w39
        w34 = w41 * w34
        w45 = w45 + w34
        w45 = w2 * w45
        w46 = w46 - w45
        w46 = w44 + w46
        w45 = w12 * w8
        w34 = w9 * w11
        w45 = w45 - w34
        w34 = w0 * w45
        w50 = w43 / w6 if w6 else _div(w43, w6)
        w8 = w8 / w6 if w6 else _div(w8, w6)
        w8 = w8 * w43
        w50 = w50 + w8
        w50 = w12 * w50
        w4 = w4 / w6 if w6 else _div(w4, w6)
        w11 = w11 / w6 if w6 else _div(w11, w6)
        w11 = w11 * w43
        w4 = w4 - w11
        w4 = w9 * w4
        w50 = w50 + w4
        w50 = w2 * w50
        w34 = w34 - w50
        w46 = w46 + w34
        w46 = w46 / w1 if w1 else _div(w46, w1)
        w6 = w6 * w42
        w19 = w19 * w2
        w6 = w6 + w19
        w45 = w45 * w2
        w6 = w6 + w45
        w6 = w6 / w1 if w1 else _div(w6, w1)
        w6 = w6 / w1 if w1 else _div(w6, w1)
        w46 = w46 - w6
        r3[0] = w46
        w46 = w7 * w21
        w6 = 0.7886751345948129
        w6 = w6 * w1
        w37 = w37 + w6
        w37 = w5 * w37
        w6 = _cos(w37)
        w45 = w41 * w6
        w46 = w46 + w45
        w45 = w0 * w46
        w7 = w7 * w48
        w19 = 0.5257834230632086
        w37 = _sin(w37)
        w19 = w19 * w37
        w19 = w41 * w19
        w7 = w7 + w19
        w7 = w2 * w7
        w45 = w45 - w7
        w7 = w12 * w15
        w19 = w9 * w17
        w7 = w7 - w19
        w0 = w0 * w7
        w19 = w47 / w14 if w14 else _div(w47, w14)
        w15 = w15 / w14 if w14 else _div(w15, w14)
        w15 = w15 * w47
        w19 = w19 + w15
        w19 = w12 * w19
        w15 = w10 / w14 if w14 else _div(w10, w14)
        w17 = w17 / w14 if w14 else _div(w17, w14)
        w17 = w17 * w47
        w15 = w15 - w17
        w15 = w9 * w15
        w19 = w19 + w15
        w19 = w2 * w19
        w0 = w0 - w19
        w45 = w45 + w0
        w35 = w27 * w35
        w36 = w36 + w35
        w35 = -0.03867513459481288
        w40 = w35 * w40
        w36 = w36 + w40
        w40 = w21 * w36
        w40 = w27 * w40
        w0 = w13 * w40
        w23 = w23 - w0
        w47 = w23 * w47
        w10 = 2.0 * w10
        w40 = w40 * w10
        w24 = w27 * w24
        w25 = w25 + w24
        w35 = w35 * w29
        w25 = w25 + w35
        w21 = w21 * w25
        w36 = w36 * w48
        w21 = w21 - w36
        w21 = w27 * w21
        w13 = w13 * w21
        w40 = w40 + w13
        w38 = w38 + w40
        w38 = w14 * w38
        w47 = w47 - w38
        w45 = w45 + w47
        w45 = w45 / w1 if w1 else _div(w45, w1)
        w46 = w46 * w2
        w7 = w7 * w2
        w46 = w46 + w7
        w14 = w14 * w23
        w46 = w46 + w14
        w46 = w46 / w1 if w1 else _div(w46, w1)
        w46 = w46 / w1 if w1 else _div(w46, w1)
        w45 = w45 - w46
        r3[1] = w45
        w18 = w18 * w20
        w27 = w27 * w18
        w28 = w28 * w27
        w47 = w28 + w47
        w47 = w47 + w44
        w47 = -w47
        r3[2] = w47
        w39 = w5 * w39
        w39 = w41 * w39
        w39 = w2 * w39
        w39 = w39 / w1 if w1 else _div(w39, w1)
        w39 = -w39
        r3[3] = w39
        w5 = w5 * w37
        w41 = w41 * w5
        w41 = w2 * w41
        w41 = w41 / w1 if w1 else _div(w41, w1)
        w41 = -w41
        r3[4] = w41
        r3[5] = w16
        w49 = w2 * w49
        w49 = w49 / w1 if w1 else _div(w49, w1)
        r3[6] = w49
        w2 = w2 * w6
        w2 = w2 / w1 if w1 else _div(w2, w1)
        r3[7] = w2
        r3[8] = w16
        w20 = w20 / w3 if w3 else _div(w20, w3)
        w26 = w26 * w27
        w20 = w20 - w26
        w12 = w12 * w20
        w3 = w27 / w3 if w3 else _div(w27, w3)
        w30 = w30 * w27
        w3 = w3 + w30
        w9 = w9 * w3
        w12 = w12 - w9
        w22 = w22 * w12
        w31 = w31 * w20
        w33 = w33 * w3
        w31 = w31 - w33
        w32 = w32 * w31
        w22 = w22 + w32
        r4[0] = w22
        r4[1] = w28
        r4[2] = w16
        r4[3] = w16
        r4[4] = w16
        r4[5] = w16
    return [r0, r1, r2, r3, r4]


def step_partials(z, g, p, h):
    """step_partials(z[3], g[4], p[1], h[3]) -> [Fs[6], Yz[6], Ys[4], FH[9], YH[6]]"""
    if _type(z) is _NDARRAY and z.dtype is _F64 and z.shape == (3,):
        z = z.tolist()
    else:
        z = _vec(z, 3, "step_partials: z")
    if _type(g) is _NDARRAY and g.dtype is _F64 and g.shape == (4,):
        g = g.tolist()
    else:
        g = _vec(g, 4, "step_partials: g")
    if _type(p) is _NDARRAY and p.dtype is _F64 and p.shape == (1,):
        p = p.tolist()
    else:
        p = _vec(p, 1, "step_partials: p")
    if _type(h) is _NDARRAY and h.dtype is _F64 and h.shape == (3,):
        h = h.tolist()
    else:
        h = _vec(h, 3, "step_partials: h")
    _r = _raw_step_partials(z, g, p, h)
    return [_fromiter(_r[0], _F64, 6), _fromiter(_r[1], _F64, 6), _fromiter(_r[2], _F64, 4), _fromiter(_r[3], _F64, 9), _fromiter(_r[4], _F64, 6)]


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
    g0, _, g2, _, = g
    p0, = p
    h0, h1, h2, = h
    try:
        while True:
            w0 = h0 * z0
            w1 = (w0 * w0) * 0.25
            w2 = 1.0 + w1
            w3 = (3.0000000000000004 * z0) + (0.4641016151377544 * z1)
            w4 = w3 / w2
            w5 = (w4 / w2) - z2
            w6 = ((-6.464101615137755) * z0) + (3.0000000000000004 * z1)
            w7 = h0 * z1
            w8 = (w7 * w7) * 0.25
            w9 = 1.0 + w8
            w10 = w6 / w9
            w11 = (w10 / w9) - z2
            w12 = (1.5000000000000002 * w5) + ((-3.2320508075688776) * w11)
            w13 = 0.5 * (h0 * z2)
            w5 = (0.2320508075688772 * w5) + (1.5000000000000002 * w11)
            w11 = h0 * w5
            w14 = h0 * w12
            w12 = w2 * (w12 - ((2.0 * w0) * (0.25 * (w4 * ((w13 + (0.5386751345948129 * w11)) + (0.25 * w14))))))
            w15 = 0.5 * h0
            F0 = ((w12 + ((((-0.5) * w4) + (h2 * (_f_cos((0.6666666666666666 * (h1 + (0.21132486540518713 * h0))))))) * w15)) + (((g2 * ((1.0 - w1) / w2)) - (g0 * (w0 / w2))) * w15)) / h0
            w0 = w9 * (w5 - ((2.0 * w7) * (0.25 * (w10 * ((w13 + (0.25 * w11)) + ((-0.03867513459481288) * w14))))))
            F1 = ((((((-0.5) * w10) + (h2 * (_f_cos((0.6666666666666666 * (h1 + (0.7886751345948129 * h0))))))) * w15) + (((g2 * ((1.0 - w8) / w9)) - (g0 * (w7 / w9))) * w15)) + w0) / h0
            w1 = h0 * ((0.5 * w3) + (0.5 * w6))
            F2 = p0 - ((((1.0 + ((w1 * w1) * 0.25)) * z2) + w0) + w12)
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
    g0, _, g2, _, = g
    p0, = p
    h0, h1, h2, = h
    try:
        while True:
            w0 = h0 * z0
            w1 = (w0 * w0) * 0.25
            w2 = 1.0 + w1
            w3 = (3.0000000000000004 * z0) + (0.4641016151377544 * z1)
            w4 = w3 / w2
            w5 = w4 / w2
            w6 = w5 - z2
            w7 = ((-6.464101615137755) * z0) + (3.0000000000000004 * z1)
            w8 = h0 * z1
            w9 = (w8 * w8) * 0.25
            w10 = 1.0 + w9
            w11 = w7 / w10
            w12 = w11 / w10
            w13 = w12 - z2
            w14 = (1.5000000000000002 * w6) + ((-3.2320508075688776) * w13)
            w15 = 2.0 * w0
            w16 = 0.5 * (h0 * z2)
            w6 = (0.2320508075688772 * w6) + (1.5000000000000002 * w13)
            w13 = h0 * w6
            w17 = h0 * w14
            w18 = (w16 + (0.5386751345948129 * w13)) + (0.25 * w17)
            w19 = 0.25 * (w4 * w18)
            w14 = w14 - (w15 * w19)
            w20 = w2 * w14
            w21 = 0.5 * h0
            w1 = (1.0 - w1) / w2
            w0 = w0 / w2
            F0 = ((w20 + ((((-0.5) * w4) + (h2 * (_f_cos((0.6666666666666666 * (h1 + (0.21132486540518713 * h0))))))) * w21)) + (((g2 * w1) - (g0 * w0)) * w21)) / h0
            w9 = (1.0 - w9) / w10
            w22 = w8 / w10
            w8 = 2.0 * w8
            w13 = (w16 + (0.25 * w13)) + ((-0.03867513459481288) * w17)
            w16 = 0.25 * (w11 * w13)
            w6 = w6 - (w8 * w16)
            w17 = w10 * w6
            F1 = ((((((-0.5) * w11) + (h2 * (_f_cos((0.6666666666666666 * (h1 + (0.7886751345948129 * h0))))))) * w21) + (((g2 * w9) - (g0 * w22)) * w21)) + w17) / h0
            w3 = h0 * ((0.5 * w3) + (0.5 * w7))
            w7 = 1.0 + ((w3 * w3) * 0.25)
            F2 = p0 - (((w7 * z2) + w17) + w20)
            w17 = 0.25 * (w15 * h0)
            w20 = (3.0000000000000004 / w2) - (w5 * w17)
            w5 = (w20 / w2) - ((w5 / w2) * w17)
            w23 = (-6.464101615137755) / w10
            w24 = w23 / w10
            w25 = (1.5000000000000002 * w5) + ((-3.2320508075688776) * w24)
            w26 = 2.0 * h0
            w5 = (0.2320508075688772 * w5) + (1.5000000000000002 * w24)
            w24 = h0 * w5
            w27 = h0 * w25
            w14 = (w14 * w17) + (w2 * (w25 - ((w19 * w26) + (w15 * (0.25 * ((w18 * w20) + (w4 * ((0.5386751345948129 * w24) + (0.25 * w27)))))))))
            J0 = ((w14 + (w21 * ((-0.5) * w20))) - (w21 * ((g2 * ((w17 / w2) + ((w1 / w2) * w17))) + (g0 * ((h0 / w2) - ((w0 / w2) * w17)))))) / h0
            w0 = w10 * (w5 - (w8 * (0.25 * ((w13 * w23) + (w11 * ((0.25 * w24) + ((-0.03867513459481288) * w27)))))))
            J1 = ((w21 * ((-0.5) * w23)) + w0) / h0
            w1 = 2.0 * w3
            J2 = -(((z2 * (0.25 * (w1 * ((-1.7320508075688774) * h0)))) + w0) + w14)
            w0 = 0.4641016151377544 / w2
            w3 = w0 / w2
            w5 = 0.25 * (w8 * h0)
            w14 = (3.0000000000000004 / w10) - (w12 * w5)
            w12 = (w14 / w10) - ((w12 / w10) * w5)
            w17 = (1.5000000000000002 * w3) + ((-3.2320508075688776) * w12)
            w3 = (0.2320508075688772 * w3) + (1.5000000000000002 * w12)
            w12 = h0 * w3
            w19 = h0 * w17
            w17 = w2 * (w17 - (w15 * (0.25 * ((w18 * w0) + (w4 * ((0.5386751345948129 * w12) + (0.25 * w19)))))))
            J3 = (w17 + (w21 * ((-0.5) * w0))) / h0
            w0 = (w6 * w5) + (w10 * (w3 - ((w16 * w26) + (w8 * (0.25 * ((w13 * w14) + (w11 * ((0.25 * w12) + ((-0.03867513459481288) * w19)))))))))
            J4 = (((w21 * ((-0.5) * w14)) - (w21 * ((g2 * ((w5 / w10) + ((w9 / w10) * w5))) + (g0 * ((h0 / w10) - ((w22 / w10) * w5)))))) + w0) / h0
            J5 = -(((z2 * (0.25 * (w1 * (1.7320508075688774 * h0)))) + w0) + w17)
            w0 = w2 * (1.7320508075688774 - (w15 * (0.25 * (w4 * ((w21 + ((-0.9330127018922194) * h0)) + (0.43301270189221935 * h0))))))
            J6 = w0 / h0
            w1 = w10 * ((-1.7320508075688774) - (w8 * (0.25 * (w11 * ((w21 + ((-0.43301270189221935) * h0)) + ((-0.06698729810778067) * h0))))))
            J7 = w1 / h0
            J8 = -((w7 + w1) + w0)
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
