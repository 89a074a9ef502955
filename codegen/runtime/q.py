"""Python mirror of kf_fixed.h: the same functions on Python ints (scalar) and on numpy int64
arrays (``*_v``, every sample at once).  Each function states the C function it mirrors; the
test suite checks them against the compiled C on random and edge inputs."""
from __future__ import annotations

import math

import numpy as np

INT32_MAX = 2 ** 31 - 1


def kf_sat(v, lo, hi):
    """kf_sat"""
    return lo if v < lo else (hi if v > hi else v)


def kf_sat_v(v, lo, hi):
    return np.clip(v, lo, hi)


def kf_lsh_sat(v, k, lo, hi):
    """kf_lsh_sat"""
    if k >= 62:
        return hi if v > 0 else (lo if v < 0 else kf_sat(0, lo, hi))
    if v > (hi >> k):
        return hi
    if v < -((-lo) >> k):
        return lo
    return v << k


def kf_lsh_sat_v(v, k, lo, hi):
    v = np.asarray(v, dtype=np.int64)
    if k >= 62:
        return np.where(v > 0, hi, np.where(v < 0, lo, kf_sat(0, lo, hi))).astype(np.int64)
    hi_lim, lo_lim = hi >> k, -((-lo) >> k)
    safe = np.clip(v, lo_lim, hi_lim)
    return np.where(v > hi_lim, hi, np.where(v < lo_lim, lo, safe << k)).astype(np.int64)


def kf_div_rnd(n, d, lo, hi):
    """kf_div_rnd"""
    if d == 0:
        return hi if n > 0 else (lo if n < 0 else kf_sat(0, lo, hi))
    un, ud = abs(n), abs(d)
    q, r = divmod(un, ud)
    if r >= ud - r:
        q += 1
    v = -q if ((n < 0) != (d < 0)) else q
    return kf_sat(v, lo, hi)


def kf_div_rnd_v(n, d, lo, hi):
    n = np.broadcast_to(np.asarray(n, dtype=np.int64), np.broadcast(n, d).shape)
    d = np.broadcast_to(np.asarray(d, dtype=np.int64), n.shape)
    out = np.empty(n.shape, dtype=np.int64)
    for i, (a, b) in enumerate(zip(n.tolist(), d.tolist())):
        out[i] = kf_div_rnd(a, b, lo, hi)
    return out


def kf_isqrt_rnd(n):
    """kf_isqrt_rnd"""
    if n <= 0:
        return 0
    r = math.isqrt(n)
    return r + 1 if n - r * r > r else r


def _isqrt_floor_v(n):
    """Exact floor(sqrt(n)) of int64 arrays 0 <= n < 2^63."""
    r = np.floor(np.sqrt(n.astype(np.float64))).astype(np.int64)
    for _ in range(2):
        r = np.where(r * r > n, r - 1, r)
        r = np.where((r + 1) * (r + 1) <= n, r + 1, r)
    return r


def kf_isqrt_rnd_v(n):
    n = np.asarray(n, dtype=np.int64)
    pos = np.maximum(n, 0)
    r = _isqrt_floor_v(pos)
    r = np.where(pos - r * r > r, r + 1, r)
    return np.where(n <= 0, 0, r)


def kf_rsqrt_dyn(y, fy):
    """kf_rsqrt_dyn / kf_rsqrt_dyn64 -> (m, e) with value = m * 2^-e"""
    n = 1 if y <= 0 else y
    s = 0
    if fy & 1:
        if n >= (1 << 61):
            n = (n + 1) >> 1
            s = -1
        else:
            n <<= 1
            s = 1
    # normalise n to [2^60, 2^62) in steps of two bits
    shift = max(0, (60 - n.bit_length() + 2) // 2 * 2)
    n <<= shift
    s += shift
    while n < (1 << 60):
        n <<= 2
        s += 2
    r = math.isqrt(n)
    m = ((1 << 61) + (r >> 1)) // r
    e = 61 - (fy + s) // 2
    if m >= (1 << 31):
        m >>= 1
        e -= 1
    return (m, e)


kf_rsqrt_dyn64 = kf_rsqrt_dyn


def kf_rnorm_dyn(a, b, c, d, f, eps_m, eps_e):
    """kf_rnorm_dyn"""
    a, b, c, d = abs(a), abs(b), abs(c), abs(d)
    big = max(a, b, c, d)
    if big == 0:
        return (eps_m, eps_e)
    if big >= 1073741824:            # 2^30: halve, rounded
        a, b, c, d = (a + 1) >> 1, (b + 1) >> 1, (c + 1) >> 1, (d + 1) >> 1
        s = -1
    else:                            # the smallest s with big * 2^s >= 2^29 (the C loop)
        s = 30 - big.bit_length()
        a, b, c, d = a << s, b << s, c << s, d << s
    m, e = kf_rsqrt_dyn(a * a + b * b + c * c + d * d, 2 * (f + s))
    if e < eps_e or (e == eps_e and m > eps_m):
        return (eps_m, eps_e)
    return (m, e)


def kf_rnorm_dyn_v(a, b, c, d, f, eps_m, eps_e):
    arrs = [np.asarray(v, dtype=np.int64) for v in (a, b, c, d)]
    shape = np.broadcast(*arrs).shape
    arrs = [np.broadcast_to(v, shape).tolist() for v in arrs]
    out = [kf_rnorm_dyn(*vals, f, eps_m, eps_e) for vals in zip(*arrs)]
    return (np.array([o[0] for o in out], dtype=np.int64),
            np.array([o[1] for o in out], dtype=np.int64))


def kf_rsqrt_dyn_v(y, fy):
    y = np.asarray(y, dtype=np.int64)
    out = [kf_rsqrt_dyn(int(v), fy) for v in y.tolist()]
    return (np.array([o[0] for o in out], dtype=np.int64),
            np.array([o[1] for o in out], dtype=np.int64))


def kf_dyn_scale(r, c, fc):
    """kf_dyn_scale"""
    m0, e0 = r
    if c <= 0 or m0 <= 0:
        return (0, 0)
    p = m0 * c
    sh = max(0, p.bit_length() - 31)
    if sh > 0:
        m = (p + (1 << (sh - 1))) >> sh
        if m >= (1 << 31):
            m >>= 1
            sh += 1
    else:
        m = p
        while m < (1 << 30):
            m <<= 1
            sh -= 1
    return (m, e0 + fc - sh)


def kf_dyn_scale_v(r, c, fc):
    m, e, c = np.broadcast_arrays(np.asarray(r[0], dtype=np.int64), np.asarray(r[1], dtype=np.int64),
                                  np.asarray(c, dtype=np.int64))
    out = [kf_dyn_scale((mm, ee), cc, fc) for mm, ee, cc in
           zip(m.ravel().tolist(), e.ravel().tolist(), c.ravel().tolist())]
    return (np.array([o[0] for o in out], dtype=np.int64).reshape(m.shape),
            np.array([o[1] for o in out], dtype=np.int64).reshape(m.shape))


def kf_mul_dyn(a, r, kbase, lo, hi):
    """kf_mul_dyn"""
    p = a * r[0]
    k = kbase + r[1]
    if k >= 63:
        return kf_sat(0, lo, hi)
    if k > 0:
        return kf_sat((p + (1 << (k - 1))) >> k, lo, hi)
    return kf_lsh_sat(p, -k, lo, hi)


def kf_mul_dyn_v(a, r, kbase, lo, hi):
    a, m, e = np.broadcast_arrays(np.asarray(a, dtype=np.int64), np.asarray(r[0], dtype=np.int64),
                                  np.asarray(r[1], dtype=np.int64))
    return np.array([kf_mul_dyn(x, (mm, ee), kbase, lo, hi)
                     for x, mm, ee in zip(a.ravel().tolist(), m.ravel().tolist(),
                                          e.ravel().tolist())], dtype=np.int64).reshape(a.shape)


def kf_inc_if(c, cond):
    """kf_inc_if"""
    return c + 1 if (cond and c < INT32_MAX) else c


def kf_inc_if_v(c, cond):  # pragma: no cover - counters depend on state, never vectorised
    raise NotImplementedError


def q_from_float(x: float, f: int, lo: int, hi: int) -> int:
    """Host conversion of a real value to raw with f fractional bits: round half away from zero,
    clamp to [lo, hi], NaN -> lo.  For binary32 inputs it equals kf_q_from_f32 (tested)."""
    if x != x:
        return lo
    if x in (math.inf, -math.inf):
        return hi if x > 0 else lo
    v = math.ldexp(abs(x), f)   # exact: a power-of-two scaling
    if v >= 2.0 ** 62:
        return hi if x > 0 else lo
    fl = math.floor(v)
    r = int(fl) + (1 if v - fl >= 0.5 else 0)   # v - fl is exact
    r = -r if x < 0 else r
    return kf_sat(r, lo, hi)


def q_from_float_v(x, f: int, lo: int, hi: int):
    """Vectorised q_from_float for float64 arrays."""
    x = np.asarray(x, dtype=np.float64)
    with np.errstate(invalid="ignore", over="ignore"):
        v = np.ldexp(np.abs(x), f)
        fl = np.floor(v)
        r = fl + ((v - fl) >= 0.5)
        r = np.where(x < 0, -r, r)
        big = float(2 ** 62)
        r = np.clip(np.nan_to_num(r, nan=-big, posinf=big, neginf=-big), -big, big)
    out = np.clip(r.astype(np.int64), lo, hi)
    return np.where(np.isnan(x), lo, out).astype(np.int64)
