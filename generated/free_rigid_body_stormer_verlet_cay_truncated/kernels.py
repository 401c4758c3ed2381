# hpgen generated module free_rigid_body_stormer_verlet_cay_truncated -- do not edit, regenerate with hpgen
# model: free_rigid_body
# options: tableau=stormer-verlet, tau=cay, rkmk=truncated
# hpgen version: 0.1.0
# content hash: 145538a3715a6e7c2cb73ee4ca1806edbe98d1ec1a2858cfb1ace272a30e9a17
"""Python backend of the hpgen module free_rigid_body_stormer_verlet_cay_truncated: straight-line kernels printed from the
CasADi SX algorithms (same operations, same order as the C backend).

Calling convention: every kernel takes flat float sequences (matrices column-major, h a
1-sequence) and returns a list of numpy float64 arrays, one per output, dense column-major.
Math that would raise in Python (division by zero, log(0), overflow, ...) returns the C99
IEEE result (inf/nan) instead, so non-finite values surface as they do in C.
Imports only math and numpy.
"""
import math

import numpy

N = 3
D = 3
NZ = 3


def _vec(a, size, name):
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


def residual(z, g, p, h):
    """residual(z[3], g[9], p[3], h[1]) -> [F[3]]"""
    z = _vec(z, 3, "residual: z")
    g = _vec(g, 9, "residual: g")
    p = _vec(p, 3, "residual: p")
    h = _vec(h, 1, "residual: h")
    r0 = [0.0] * 3
    w0 = p[0]
    w1 = h[0]
    w2 = z[1]
    w3 = w1 * w2
    w4 = 2.0
    w5 = w3 / w4 if w4 else _div(w3, w4)
    w6 = z[2]
    w7 = w1 * w6
    w8 = z[0]
    w1 = w1 * w8
    w9 = w7 * w1
    w10 = 4.0
    w9 = w9 / w10 if w10 else _div(w9, w10)
    w9 = w5 + w9
    w11 = 0.6666666666666666
    w11 = w11 * w6
    w9 = w9 * w11
    w6 = w3 * w1
    w6 = w6 / w10 if w10 else _div(w6, w10)
    w12 = w7 / w4 if w4 else _div(w7, w4)
    w6 = w6 - w12
    w6 = w6 * w2
    w9 = w9 + w6
    w6 = 1.0
    w13 = w1 * w1
    w13 = w13 / w10 if w10 else _div(w13, w10)
    w13 = w6 + w13
    w8 = 2.0 * w8
    w13 = w13 * w8
    w9 = w9 + w13
    w0 = w0 - w9
    r0[0] = w0
    w0 = p[1]
    w9 = w7 * w3
    w9 = w9 / w10 if w10 else _div(w9, w10)
    w4 = w1 / w4 if w4 else _div(w1, w4)
    w9 = w9 - w4
    w9 = w9 * w11
    w13 = w3 * w3
    w13 = w13 / w10 if w10 else _div(w13, w10)
    w13 = w6 + w13
    w13 = w13 * w2
    w9 = w9 + w13
    w13 = w1 * w3
    w13 = w13 / w10 if w10 else _div(w13, w10)
    w12 = w12 + w13
    w12 = w12 * w8
    w9 = w9 + w12
    w0 = w0 - w9
    r0[1] = w0
    w0 = p[2]
    w9 = w7 * w7
    w9 = w9 / w10 if w10 else _div(w9, w10)
    w6 = w6 + w9
    w6 = w6 * w11
    w3 = w3 * w7
    w3 = w3 / w10 if w10 else _div(w3, w10)
    w4 = w4 + w3
    w4 = w4 * w2
    w6 = w6 + w4
    w1 = w1 * w7
    w1 = w1 / w10 if w10 else _div(w1, w10)
    w1 = w1 - w5
    w1 = w1 * w8
    w6 = w6 + w1
    w0 = w0 - w6
    r0[2] = w0
    return [numpy.array(r0, dtype=numpy.float64)]


def jacobian(z, g, p, h):
    """jacobian(z[3], g[9], p[3], h[1]) -> [J[9]]"""
    z = _vec(z, 3, "jacobian: z")
    g = _vec(g, 9, "jacobian: g")
    p = _vec(p, 3, "jacobian: p")
    h = _vec(h, 1, "jacobian: h")
    r0 = [0.0] * 9
    w0 = 0.6666666666666666
    w1 = z[2]
    w2 = w0 * w1
    w3 = 0.25
    w4 = h[0]
    w1 = w4 * w1
    w5 = w1 * w4
    w5 = w3 * w5
    w6 = w2 * w5
    w7 = z[1]
    w8 = w4 * w7
    w9 = w8 * w4
    w9 = w3 * w9
    w10 = w7 * w9
    w11 = w6 + w10
    w12 = z[0]
    w13 = 2.0 * w12
    w12 = w4 * w12
    w14 = 2.0 * w12
    w14 = w14 * w4
    w14 = w3 * w14
    w14 = w13 * w14
    w15 = 1.0
    w16 = w12 * w12
    w17 = 4.0
    w16 = w16 / w17 if w17 else _div(w16, w17)
    w16 = w15 + w16
    w16 = 2.0 * w16
    w14 = w14 + w16
    w11 = w11 + w14
    w11 = -w11
    r0[0] = w11
    w11 = w13 * w9
    w14 = 2.0
    w16 = w1 / w14 if w14 else _div(w1, w14)
    w18 = w12 * w8
    w18 = w18 / w17 if w17 else _div(w18, w17)
    w18 = w16 + w18
    w18 = 2.0 * w18
    w11 = w11 + w18
    w18 = 0.5
    w18 = w18 * w4
    w19 = w2 * w18
    w11 = w11 - w19
    w11 = -w11
    r0[1] = w11
    w11 = w7 * w18
    w20 = w13 * w5
    w21 = w12 * w1
    w21 = w21 / w17 if w17 else _div(w21, w17)
    w22 = w8 / w14 if w14 else _div(w8, w14)
    w21 = w21 - w22
    w21 = 2.0 * w21
    w20 = w20 + w21
    w20 = w11 + w20
    w20 = -w20
    r0[2] = w20
    w20 = w12 * w4
    w20 = w3 * w20
    w21 = w7 * w20
    w23 = w8 * w12
    w23 = w23 / w17 if w17 else _div(w23, w17)
    w23 = w23 - w16
    w21 = w21 + w23
    w19 = w19 + w21
    w19 = -w19
    r0[3] = w19
    w19 = 2.0 * w8
    w19 = w19 * w4
    w19 = w3 * w19
    w19 = w7 * w19
    w21 = w8 * w8
    w21 = w21 / w17 if w17 else _div(w21, w17)
    w21 = w15 + w21
    w19 = w19 + w21
    w6 = w6 + w19
    w19 = w13 * w20
    w6 = w6 + w19
    w6 = -w6
    r0[4] = w6
    w7 = w7 * w5
    w14 = w12 / w14 if w14 else _div(w12, w14)
    w5 = w8 * w1
    w5 = w5 / w17 if w17 else _div(w5, w17)
    w5 = w14 + w5
    w7 = w7 + w5
    w13 = w13 * w18
    w7 = w7 - w13
    w7 = -w7
    r0[5] = w7
    w20 = w2 * w20
    w12 = w1 * w12
    w12 = w12 / w17 if w17 else _div(w12, w17)
    w22 = w22 + w12
    w22 = w0 * w22
    w20 = w20 + w22
    w20 = w20 - w11
    w20 = -w20
    r0[6] = w20
    w9 = w2 * w9
    w8 = w1 * w8
    w8 = w8 / w17 if w17 else _div(w8, w17)
    w8 = w8 - w14
    w8 = w0 * w8
    w9 = w9 + w8
    w9 = w9 + w13
    w9 = -w9
    r0[7] = w9
    w9 = 2.0 * w1
    w9 = w9 * w4
    w3 = w3 * w9
    w2 = w2 * w3
    w1 = w1 * w1
    w1 = w1 / w17 if w17 else _div(w1, w17)
    w15 = w15 + w1
    w0 = w0 * w15
    w2 = w2 + w0
    w2 = w2 + w10
    w2 = w2 + w19
    w2 = -w2
    r0[8] = w2
    return [numpy.array(r0, dtype=numpy.float64)]


def update(z, g, p, h):
    """update(z[3], g[9], p[3], h[1]) -> [g1[9], p1[3]]"""
    z = _vec(z, 3, "update: z")
    g = _vec(g, 9, "update: g")
    p = _vec(p, 3, "update: p")
    h = _vec(h, 1, "update: h")
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
    w10 = w2 / w10 if w10 else _div(w2, w10)
    w13 = w12 + w9
    w14 = 2.0
    w13 = w13 / w14 if w14 else _div(w13, w14)
    w13 = w10 * w13
    w13 = w1 - w13
    w15 = w0 * w13
    w16 = g[3]
    w17 = w5 * w8
    w18 = w17 / w14 if w14 else _div(w17, w14)
    w18 = w3 + w18
    w18 = w10 * w18
    w19 = w16 * w18
    w15 = w15 + w19
    w19 = g[6]
    w20 = w5 * w3
    w21 = w20 / w14 if w14 else _div(w20, w14)
    w21 = w21 - w8
    w21 = w10 * w21
    w22 = w19 * w21
    w15 = w15 + w22
    r0[0] = w15
    w15 = g[1]
    w22 = w15 * w13
    w23 = g[4]
    w24 = w23 * w18
    w22 = w22 + w24
    w24 = g[7]
    w25 = w24 * w21
    w22 = w22 + w25
    r0[1] = w22
    w22 = g[2]
    w13 = w22 * w13
    w25 = g[5]
    w18 = w25 * w18
    w13 = w13 + w18
    w18 = g[8]
    w21 = w18 * w21
    w13 = w13 + w21
    r0[2] = w13
    w13 = w8 * w5
    w21 = w13 / w14 if w14 else _div(w13, w14)
    w21 = w21 - w3
    w21 = w10 * w21
    w26 = w0 * w21
    w27 = w12 + w6
    w27 = w27 / w14 if w14 else _div(w27, w14)
    w27 = w10 * w27
    w27 = w1 - w27
    w28 = w16 * w27
    w26 = w26 + w28
    w28 = w8 * w3
    w29 = w28 / w14 if w14 else _div(w28, w14)
    w29 = w5 + w29
    w29 = w10 * w29
    w30 = w19 * w29
    w26 = w26 + w30
    r0[3] = w26
    w26 = w15 * w21
    w30 = w23 * w27
    w26 = w26 + w30
    w30 = w24 * w29
    w26 = w26 + w30
    r0[4] = w26
    w21 = w22 * w21
    w27 = w25 * w27
    w21 = w21 + w27
    w29 = w18 * w29
    w21 = w21 + w29
    r0[5] = w21
    w21 = w3 * w5
    w29 = w21 / w14 if w14 else _div(w21, w14)
    w29 = w8 + w29
    w29 = w10 * w29
    w0 = w0 * w29
    w27 = w3 * w8
    w26 = w27 / w14 if w14 else _div(w27, w14)
    w26 = w26 - w5
    w26 = w10 * w26
    w16 = w16 * w26
    w0 = w0 + w16
    w16 = w9 + w6
    w16 = w16 / w14 if w14 else _div(w16, w14)
    w10 = w10 * w16
    w10 = w1 - w10
    w19 = w19 * w10
    w0 = w0 + w19
    r0[6] = w0
    w15 = w15 * w29
    w23 = w23 * w26
    w15 = w15 + w23
    w24 = w24 * w10
    w15 = w15 + w24
    r0[7] = w15
    w22 = w22 * w29
    w25 = w25 * w26
    w22 = w22 + w25
    w18 = w18 * w10
    w22 = w22 + w18
    r0[8] = w22
    w21 = w21 / w2 if w2 else _div(w21, w2)
    w8 = w8 / w14 if w14 else _div(w8, w14)
    w21 = w21 - w8
    w22 = 0.6666666666666666
    w22 = w22 * w11
    w21 = w21 * w22
    w3 = w3 / w14 if w14 else _div(w3, w14)
    w13 = w13 / w2 if w2 else _div(w13, w2)
    w13 = w3 + w13
    w13 = w13 * w7
    w21 = w21 + w13
    w6 = w6 / w2 if w2 else _div(w6, w2)
    w6 = w1 + w6
    w4 = 2.0 * w4
    w6 = w6 * w4
    w21 = w21 + w6
    r1[0] = w21
    w5 = w5 / w14 if w14 else _div(w5, w14)
    w27 = w27 / w2 if w2 else _div(w27, w2)
    w27 = w5 + w27
    w27 = w27 * w22
    w9 = w9 / w2 if w2 else _div(w9, w2)
    w9 = w1 + w9
    w9 = w9 * w7
    w27 = w27 + w9
    w17 = w17 / w2 if w2 else _div(w17, w2)
    w17 = w17 - w3
    w17 = w17 * w4
    w27 = w27 + w17
    r1[1] = w27
    w12 = w12 / w2 if w2 else _div(w12, w2)
    w1 = w1 + w12
    w1 = w1 * w22
    w28 = w28 / w2 if w2 else _div(w28, w2)
    w28 = w28 - w5
    w28 = w28 * w7
    w1 = w1 + w28
    w20 = w20 / w2 if w2 else _div(w20, w2)
    w8 = w8 + w20
    w8 = w8 * w4
    w1 = w1 + w8
    r1[2] = w1
    return [numpy.array(r0, dtype=numpy.float64), numpy.array(r1, dtype=numpy.float64)]


def guess(xi, g, p, h):
    """guess(xi[3], g[9], p[3], h[1]) -> [z0[3]]"""
    xi = _vec(xi, 3, "guess: xi")
    g = _vec(g, 9, "guess: g")
    p = _vec(p, 3, "guess: p")
    h = _vec(h, 1, "guess: h")
    r0 = [0.0] * 3
    w0 = xi[0]
    r0[0] = w0
    w0 = xi[1]
    r0[1] = w0
    w0 = xi[2]
    r0[2] = w0
    return [numpy.array(r0, dtype=numpy.float64)]


def legendre(g, xi):
    """legendre(g[9], xi[3]) -> [mu[3]]"""
    g = _vec(g, 9, "legendre: g")
    xi = _vec(xi, 3, "legendre: xi")
    r0 = [0.0] * 3
    w0 = xi[0]
    w0 = 2.0 * w0
    r0[0] = w0
    w0 = xi[1]
    r0[1] = w0
    w0 = 0.6666666666666666
    w1 = xi[2]
    w0 = w0 * w1
    r0[2] = w0
    return [numpy.array(r0, dtype=numpy.float64)]


def hessian(g, xi):
    """hessian(g[9], xi[3]) -> [H[9]]"""
    g = _vec(g, 9, "hessian: g")
    xi = _vec(xi, 3, "hessian: xi")
    r0 = [0.0] * 9
    w0 = 2.0
    r0[0] = w0
    w0 = 0.0
    r0[1] = w0
    r0[2] = w0
    r0[3] = w0
    w1 = 1.0
    r0[4] = w1
    r0[5] = w0
    r0[6] = w0
    r0[7] = w0
    w0 = 0.6666666666666666
    r0[8] = w0
    return [numpy.array(r0, dtype=numpy.float64)]


def energy(g, xi):
    """energy(g[9], xi[3]) -> [E[1]]"""
    g = _vec(g, 9, "energy: g")
    xi = _vec(xi, 3, "energy: xi")
    r0 = [0.0] * 1
    w0 = xi[0]
    w1 = 2.0 * w0
    w1 = w1 * w0
    w2 = xi[1]
    w2 = w2 * w2
    w1 = w1 + w2
    w3 = 0.6666666666666666
    w4 = xi[2]
    w3 = w3 * w4
    w3 = w3 * w4
    w1 = w1 + w3
    w3 = 0.5
    w3 = w3 * w2
    w0 = w0 * w0
    w3 = w3 + w0
    w0 = 0.3333333333333333
    w4 = w4 * w4
    w0 = w0 * w4
    w3 = w3 + w0
    w1 = w1 - w3
    r0[0] = w1
    return [numpy.array(r0, dtype=numpy.float64)]


def momentum(g, p):
    """momentum(g[9], p[3]) -> [m[3]]"""
    g = _vec(g, 9, "momentum: g")
    p = _vec(p, 3, "momentum: p")
    r0 = [0.0] * 3
    w0 = g[8]
    w1 = g[4]
    w2 = w0 * w1
    w3 = g[7]
    w4 = g[5]
    w5 = w3 * w4
    w2 = w2 - w5
    w5 = p[0]
    w2 = w2 * w5
    w6 = g[2]
    w7 = w6 * w3
    w8 = g[1]
    w9 = w8 * w0
    w7 = w7 - w9
    w9 = p[1]
    w7 = w7 * w9
    w2 = w2 + w7
    w7 = w4 * w8
    w10 = w1 * w6
    w7 = w7 - w10
    w10 = p[2]
    w7 = w7 * w10
    w2 = w2 + w7
    r0[0] = w2
    w2 = g[6]
    w7 = w2 * w4
    w11 = g[3]
    w12 = w0 * w11
    w7 = w7 - w12
    w7 = w7 * w5
    w12 = g[0]
    w0 = w12 * w0
    w13 = w6 * w2
    w0 = w0 - w13
    w0 = w0 * w9
    w7 = w7 + w0
    w6 = w11 * w6
    w4 = w4 * w12
    w6 = w6 - w4
    w6 = w6 * w10
    w7 = w7 + w6
    r0[1] = w7
    w7 = w3 * w11
    w6 = w2 * w1
    w7 = w7 - w6
    w7 = w7 * w5
    w2 = w8 * w2
    w3 = w12 * w3
    w2 = w2 - w3
    w2 = w2 * w9
    w7 = w7 + w2
    w1 = w1 * w12
    w11 = w11 * w8
    w1 = w1 - w11
    w1 = w1 * w10
    w7 = w7 + w1
    r0[2] = w7
    return [numpy.array(r0, dtype=numpy.float64)]


def defect(g):
    """defect(g[9]) -> [e[1]]"""
    g = _vec(g, 9, "defect: g")
    r0 = [0.0] * 1
    w0 = g[0]
    w1 = w0 * w0
    w2 = g[1]
    w3 = w2 * w2
    w1 = w1 + w3
    w3 = g[2]
    w4 = w3 * w3
    w1 = w1 + w4
    w4 = 1.0
    w1 = w1 - w4
    w1 = math.fabs(w1)
    w5 = g[3]
    w6 = w5 * w0
    w7 = g[4]
    w8 = w7 * w2
    w6 = w6 + w8
    w8 = g[5]
    w9 = w8 * w3
    w6 = w6 + w9
    w6 = math.fabs(w6)
    w1 = _fmax(w1, w6)
    w6 = g[6]
    w9 = w6 * w0
    w10 = g[7]
    w11 = w10 * w2
    w9 = w9 + w11
    w11 = g[8]
    w12 = w11 * w3
    w9 = w9 + w12
    w9 = math.fabs(w9)
    w1 = _fmax(w1, w9)
    w9 = w0 * w5
    w12 = w2 * w7
    w9 = w9 + w12
    w12 = w3 * w8
    w9 = w9 + w12
    w9 = math.fabs(w9)
    w1 = _fmax(w1, w9)
    w9 = w5 * w5
    w12 = w7 * w7
    w9 = w9 + w12
    w12 = w8 * w8
    w9 = w9 + w12
    w9 = w9 - w4
    w9 = math.fabs(w9)
    w1 = _fmax(w1, w9)
    w9 = w6 * w5
    w12 = w10 * w7
    w9 = w9 + w12
    w12 = w11 * w8
    w9 = w9 + w12
    w9 = math.fabs(w9)
    w1 = _fmax(w1, w9)
    w9 = w0 * w6
    w12 = w2 * w10
    w9 = w9 + w12
    w12 = w3 * w11
    w9 = w9 + w12
    w9 = math.fabs(w9)
    w1 = _fmax(w1, w9)
    w9 = w5 * w6
    w12 = w7 * w10
    w9 = w9 + w12
    w12 = w8 * w11
    w9 = w9 + w12
    w9 = math.fabs(w9)
    w1 = _fmax(w1, w9)
    w9 = w6 * w6
    w12 = w10 * w10
    w9 = w9 + w12
    w12 = w11 * w11
    w9 = w9 + w12
    w9 = w9 - w4
    w9 = math.fabs(w9)
    w1 = _fmax(w1, w9)
    w9 = w7 * w11
    w12 = w10 * w8
    w9 = w9 - w12
    w0 = w0 * w9
    w11 = w2 * w11
    w10 = w10 * w3
    w11 = w11 - w10
    w5 = w5 * w11
    w0 = w0 - w5
    w2 = w2 * w8
    w7 = w7 * w3
    w2 = w2 - w7
    w6 = w6 * w2
    w0 = w0 + w6
    w0 = w0 - w4
    w0 = math.fabs(w0)
    w1 = _fmax(w1, w0)
    r0[0] = w1
    return [numpy.array(r0, dtype=numpy.float64)]


def margin(z, h):
    """margin(z[3], h[1]) -> [m[1]]"""
    z = _vec(z, 3, "margin: z")
    h = _vec(h, 1, "margin: h")
    r0 = [0.0] * 1
    w0 = 1.0
    w1 = 4.0
    w2 = h[0]
    w3 = z[0]
    w3 = w2 * w3
    w3 = w3 * w3
    w4 = z[1]
    w4 = w2 * w4
    w4 = w4 * w4
    w3 = w3 + w4
    w4 = z[2]
    w2 = w2 * w4
    w2 = w2 * w2
    w3 = w3 + w2
    w1 = w1 - w3
    w0 = _fmin(w0, w1)
    w0 = _fmin(w0, w1)
    w0 = _fmin(w0, w1)
    w0 = _fmin(w0, w1)
    r0[0] = w0
    return [numpy.array(r0, dtype=numpy.float64)]


KERNELS = {
    "residual": residual,
    "jacobian": jacobian,
    "update": update,
    "guess": guess,
    "legendre": legendre,
    "hessian": hessian,
    "energy": energy,
    "momentum": momentum,
    "defect": defect,
    "margin": margin,
}
