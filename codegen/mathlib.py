"""Elementary functions written with the scalar interface (no libm).

libm's sinf/atan2f/expf differ between glibc, newlib and numpy in 10-40 % of inputs, so they
cannot appear where generated C must equal its model bit for bit.  These versions are polynomials
on reduced arguments built from + - * / floor and selects: the same code is the reference (float64),
the generated C and the models.  Accuracy (float64 evaluation): about 1e-9 absolute for sin/cos,
2e-8 rad for atan2/asin/acos, 2e-8 relative for exp — below binary32 resolution.
"""
from __future__ import annotations

import math

from kinefuse.codegen.scalar import assume, clamp, fabs, floor, fmax, fmin, select, sqrt

_PI = math.pi
# pi/2 split so that k * _PI2_HI is exact in binary32 for |k| < 2^12 (Cody & Waite)
_PI2_HI = 1.5703125
_PI2_LO = math.pi / 2 - 1.5703125


def _sin_poly(r):
    """sin(r), |r| <= pi/4: Taylor to r^11 (error < 2e-10)."""
    r2 = r * r
    p = -1.0 / 39916800.0
    for c in (1.0 / 362880.0, -1.0 / 5040.0, 1.0 / 120.0, -1.0 / 6.0):
        p = p * r2 + c
    return r + r * r2 * p


def _cos_poly(r):
    """cos(r), |r| <= pi/4: Taylor to r^12 (error < 2e-10)."""
    r2 = r * r
    p = 1.0 / 479001600.0
    for c in (-1.0 / 3628800.0, 1.0 / 40320.0, -1.0 / 720.0, 1.0 / 24.0):
        p = p * r2 + c
    return 1.0 - 0.5 * r2 + r2 * r2 * p


def _quadrant(x):
    """k = round(x / (pi/2)) and the reduced argument r = x - k pi/2 in [-pi/4, pi/4]."""
    k = floor(x * (2.0 / _PI) + 0.5)
    r = assume((x - k * _PI2_HI) - k * _PI2_LO, -0.7854, 0.7854)
    q = k - 4.0 * floor(k * 0.25)          # quadrant 0..3
    return r, q


def sincos(x):
    """(sin x, cos x) for |x| up to about 1e4 rad (argument reduction keeps ~1e-7 rad there)."""
    r, q = _quadrant(x)
    s, c = _sin_poly(r), _cos_poly(r)
    q0, q1, q2 = q < 0.5, q < 1.5, q < 2.5
    sin_x = select(q0, s, select(q1, c, select(q2, -s, -c)))
    cos_x = select(q0, c, select(q1, -s, select(q2, -c, s)))
    return assume(sin_x, -1.0, 1.0), assume(cos_x, -1.0, 1.0)


def sin(x):
    return sincos(x)[0]


def cos(x):
    return sincos(x)[1]


_TAN_PI_8 = math.tan(math.pi / 8)


def _atan_unit(t):
    """atan(t) for 0 <= t <= 1: t > tan(pi/8) is reduced with atan(t) = pi/4 + atan((t-1)/(t+1)),
    then an odd Taylor polynomial to t^17 on |t| <= tan(pi/8) (error < 2e-8)."""
    big = t > _TAN_PI_8
    u = select(big, (t - 1.0) / (t + 1.0), t)
    u = assume(u, -0.4143, 0.4143)
    u2 = u * u
    # atan(u) = u - u^3 (1/3 - u^2/5 + u^4/7 - ... - u^14/17)
    p = -1.0 / 17.0
    for i, c in enumerate((1 / 15, 1 / 13, 1 / 11, 1 / 9, 1 / 7, 1 / 5, 1 / 3)):
        p = p * u2 + (c if i % 2 == 0 else -c)
    a = u - u * u2 * p
    return select(big, a + _PI / 4, a)


def atan2(y, x):
    """atan2(y, x) in (-pi, pi]; atan2(0, 0) = 0."""
    ax, ay = fabs(x), fabs(y)
    mx = fmax(ax, ay)
    mn = fmin(ax, ay)
    t = assume(mn / fmax(mx, 1e-30), 0.0, 1.0)
    a = _atan_unit(t)
    a = select(ay > ax, _PI / 2 - a, a)
    a = select(x < 0.0, _PI - a, a)
    return select(y < 0.0, -a, a)


def asin(x):
    """asin(x) for x clamped to [-1, 1]."""
    x = clamp(x, -1.0, 1.0)
    return atan2(x, sqrt(fmax((1.0 - x) * (1.0 + x), 0.0)))


def acos(x):
    x = clamp(x, -1.0, 1.0)
    return atan2(sqrt(fmax((1.0 - x) * (1.0 + x), 0.0)), x)


_LN2_HI = 0.693145751953125          # exact in binary32 with trailing zeros
_LN2_LO = math.log(2.0) - 0.693145751953125


def exp(x):
    """exp(x) for x clamped to [-30, 30]: 2^n * exp(r), |r| <= ln2/2, Taylor to r^8, 2^n built
    from the bits of n (no libm, no bit tricks)."""
    x = clamp(x, -30.0, 30.0)
    n = floor(x * (1.0 / math.log(2.0)) + 0.5)
    r = assume((x - n * _LN2_HI) - n * _LN2_LO, -0.3466, 0.3466)
    p = 1.0 / 40320.0
    for c in (1 / 5040, 1 / 720, 1 / 120, 1 / 24, 1 / 6, 1 / 2, 1.0, 1.0):
        p = p * r + c
    # 2^n = 2^(sign * sum of bits): |n| <= 44 fits 6 bits
    an = fabs(n)
    scale_up, scale_dn = 1.0, 1.0
    rest = an
    for bit in (32.0, 16.0, 8.0, 4.0, 2.0, 1.0):
        has = rest >= bit
        rest = select(has, rest - bit, rest)
        scale_up = select(has, scale_up * 2.0 ** bit, scale_up)
        scale_dn = select(has, scale_dn * 2.0 ** -bit, scale_dn)
    return p * select(n < 0.0, scale_dn, scale_up)


__all__ = ["sin", "cos", "sincos", "atan2", "asin", "acos", "exp"]
