"""The Python mirror (runtime/q.py) against the C helpers (runtime/kf_fixed.h), compiled."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from kinefuse.codegen.build import build
from kinefuse.codegen.runtime import RUNTIME_DIR
from kinefuse.codegen.runtime import q as rt

I32 = st.integers(-(2 ** 31) + 1, 2 ** 31 - 1)
I62 = st.integers(-(2 ** 62), 2 ** 62)
WRAP = r"""
int32_t w_sat(int64_t v, int32_t lo, int32_t hi) { return kf_sat(v, lo, hi); }
int32_t w_lsh_sat(int64_t v, int32_t k, int32_t lo, int32_t hi) { return kf_lsh_sat(v, k, lo, hi); }
int32_t w_div_rnd(int64_t n, int64_t d, int32_t lo, int32_t hi) { return kf_div_rnd(n, d, lo, hi); }
int64_t w_isqrt_rnd(int64_t n) { return kf_isqrt_rnd(n); }
void w_rsqrt_dyn64(int64_t y, int32_t fy, int32_t *m, int32_t *e)
{ kf_dyn r = kf_rsqrt_dyn64(y, fy); *m = r.m; *e = r.e; }
int32_t w_mul_dyn(int32_t a, int32_t m, int32_t e, int32_t kb, int32_t lo, int32_t hi)
{ kf_dyn r; r.m = m; r.e = e; return kf_mul_dyn(a, r, kb, lo, hi); }
void w_rnorm_dyn(int32_t a, int32_t b, int32_t c, int32_t d, int32_t f, int32_t em, int32_t ee,
                 int32_t *m, int32_t *e)
{ kf_dyn r = kf_rnorm_dyn(a, b, c, d, f, em, ee); *m = r.m; *e = r.e; }
int32_t w_q_from_f32(float x, int32_t f, int32_t lo, int32_t hi) { return kf_q_from_f32(x, f, lo, hi); }
void w_dyn_scale(int32_t m, int32_t e, int32_t cc, int32_t fc, int32_t *om, int32_t *oe)
{ kf_dyn r; r.m = m; r.e = e; r = kf_dyn_scale(r, cc, fc); *om = r.m; *oe = r.e; }
int64_t w_smull(int32_t a, int32_t b) { return kf_smull(a, b); }
uint64_t w_umull(uint32_t a, uint32_t b) { return kf_umull(a, b); }
uint64_t w_isqrt_floor(uint64_t n, uint64_t *rem) { return kf_isqrt_floor(n, rem); }
uint32_t w_udiv64_32(uint64_t n, uint32_t d, uint32_t *rem) { return kf_udiv64_32(n, d, rem); }
"""
CDEF = """
int32_t w_sat(int64_t v, int32_t lo, int32_t hi);
int32_t w_lsh_sat(int64_t v, int32_t k, int32_t lo, int32_t hi);
int32_t w_div_rnd(int64_t n, int64_t d, int32_t lo, int32_t hi);
int64_t w_isqrt_rnd(int64_t n);
void w_rsqrt_dyn64(int64_t y, int32_t fy, int32_t *m, int32_t *e);
int32_t w_mul_dyn(int32_t a, int32_t m, int32_t e, int32_t kb, int32_t lo, int32_t hi);
void w_rnorm_dyn(int32_t a, int32_t b, int32_t c, int32_t d, int32_t f, int32_t em, int32_t ee,
                 int32_t *m, int32_t *e);
int32_t w_q_from_f32(float x, int32_t f, int32_t lo, int32_t hi);
void w_dyn_scale(int32_t m, int32_t e, int32_t cc, int32_t fc, int32_t *om, int32_t *oe);
int64_t w_smull(int32_t a, int32_t b);
uint64_t w_umull(uint32_t a, uint32_t b);
uint64_t w_isqrt_floor(uint64_t n, uint64_t *rem);
uint32_t w_udiv64_32(uint64_t n, uint32_t d, uint32_t *rem);
"""


# "native": the host's own 64-bit products and division and a float first guess for square roots;
# "portable": the 16 x 16 long multiplication, 32-bit division loop and digit-by-digit square
# root of the Cortex-M0 build; "no-fpu": native products, digit-by-digit square root (an M3 or
# M4 without FPU); "divlu": the two-digit 64/32 division of the M3/M4/M7 builds, with the
# float-seeded square root (the M4F).  Every helper is checked on every path.
@pytest.fixture(scope="module", params=["native", "portable", "no-fpu", "divlu"])
def c(request):
    define = {"native": "", "portable": "#define KF_PORTABLE_LONG_MUL\n",
              "no-fpu": "#define KF_PORTABLE_ISQRT\n",
              "divlu": "#define KF_PORTABLE_DIVLU\n"}[request.param]
    ffi, lib = build(f"qruntime_test_{request.param}", [], [], extra_cdef=CDEF,
                     extra_source=define + '#include "kf_fixed.h"\n' + WRAP,
                     include_dirs=[RUNTIME_DIR])
    return ffi, lib


EDGES32 = [-(2 ** 31), -(2 ** 31) + 1, -65537, -65536, -65535, -32769, -32768, -1, 0, 1, 32767,
           32768, 65535, 65536, 2 ** 31 - 1]


@settings(max_examples=300, deadline=None)
@given(a=st.one_of(st.integers(-(2 ** 31), 2 ** 31 - 1), st.sampled_from(EDGES32)),
       b=st.one_of(st.integers(-(2 ** 31), 2 ** 31 - 1), st.sampled_from(EDGES32)))
def test_long_products_are_exact(c, a, b):
    assert c[1].w_smull(a, b) == a * b
    ua, ub = a & 0xFFFFFFFF, b & 0xFFFFFFFF
    assert c[1].w_umull(ua, ub) == ua * ub


def test_long_products_at_every_edge_pair(c):
    for a in EDGES32:
        for b in EDGES32:
            assert c[1].w_smull(a, b) == a * b, (a, b)
            ua, ub = a & 0xFFFFFFFF, b & 0xFFFFFFFF
            assert c[1].w_umull(ua, ub) == ua * ub, (a, b)


def _bounds(a, b):
    return (a, b) if a <= b else (b, a)


@settings(max_examples=150, deadline=None)
@given(v=st.integers(-(2 ** 63) + 1, 2 ** 63 - 1), lo=I32, hi=I32)
def test_sat(c, v, lo, hi):
    lo, hi = _bounds(lo, hi)
    assert c[1].w_sat(v, lo, hi) == rt.kf_sat(v, lo, hi)


@settings(max_examples=150, deadline=None)
@given(v=I62, k=st.integers(0, 70), lo=I32, hi=I32)
def test_lsh_sat(c, v, k, lo, hi):
    lo, hi = _bounds(lo, hi)
    assert c[1].w_lsh_sat(v, k, lo, hi) == rt.kf_lsh_sat(v, k, lo, hi)
    assert rt.kf_lsh_sat(v, k, lo, hi) == max(lo, min(hi, v * 2 ** k))   # definition


@settings(max_examples=150, deadline=None)
@given(n=I62, d=st.one_of(st.integers(-(2 ** 62), 2 ** 62), st.integers(-3, 3)), lo=I32, hi=I32)
def test_div_rnd(c, n, d, lo, hi):
    lo, hi = _bounds(lo, hi)
    got = c[1].w_div_rnd(n, d, lo, hi)
    assert got == rt.kf_div_rnd(n, d, lo, hi)
    if d != 0:   # round half away from zero, from exact rationals
        from fractions import Fraction
        q = Fraction(n, d)
        r = math.floor(abs(q) + Fraction(1, 2)) * (1 if q >= 0 else -1)
        assert got == max(lo, min(hi, r))


UDIV_EDGE_D = [1, 2, 3, 0xFFFF, 0x10000, 0x10001, 0x7FFF8000, 0x8000, 0x12345, 2 ** 31 - 1, 2 ** 31,
               0x40000001, 0x7FFFFFFF & ~0xFFFF, 0x4000FFFF]


def _check_udiv(lib, ffi, n, d):
    rem = ffi.new("uint32_t *")
    q = lib.w_udiv64_32(n, d, rem)
    assert (q, rem[0]) == divmod(n, d), (n, d)


@settings(max_examples=400, deadline=None)
@given(d=st.one_of(st.integers(1, 2 ** 31), st.sampled_from(UDIV_EDGE_D)),
       hi=st.integers(0, 2 ** 32 - 1), lo=st.one_of(st.integers(0, 2 ** 32 - 1),
                                                   st.sampled_from([0, 1, 0xFFFF, 0x10000, 2 ** 32 - 1])))
def test_udiv64_32_is_floor_division(c, d, hi, lo):
    """The 64/32 division under kf_div_rnd and the reciprocal square root, on its whole domain
    (0 < d <= 2^31, quotient < 2^32): the quotient digits' correction steps included."""
    hi = hi % d
    _check_udiv(c[1], c[0], (hi << 32) | lo, d)


@settings(max_examples=200, deadline=None)
@given(d=st.integers(2 ** 31, 2 ** 32 - 1), hi=st.integers(0, 2 ** 32 - 1), lo=st.integers(0, 2 ** 32 - 1))
def test_udiv64_32_wide_divisors(c, request, d, hi, lo):
    """Divisors above 2^31 (the float-seeded square root's Newton step) where there is long
    multiplication; the M0's shift-subtract loop is not used for them."""
    if request.node.callspec.params["c"] == "portable":
        pytest.skip("the shift-subtract loop takes d <= 2^31 only")
    _check_udiv(c[1], c[0], (hi % d << 32) | lo, d)


def test_udiv64_32_edges(c):
    for d in UDIV_EDGE_D:
        for hi in (0, 1, d // 2, d - 1):
            for lo in (0, 1, 0xFFFF, 0x10000, 0xFFFF0000, 2 ** 32 - 1, d - 1 if d <= 2 ** 32 else 0):
                _check_udiv(c[1], c[0], (hi % d << 32) | lo, d)


@settings(max_examples=150, deadline=None)
@given(n=st.integers(-5, 2 ** 63 - 1))
def test_isqrt_rnd(c, n):
    got = c[1].w_isqrt_rnd(n)
    assert got == rt.kf_isqrt_rnd(n)
    if n > 0:   # nearest integer to sqrt(n)
        assert (got - 0.5) ** 2 <= n <= (got + 0.5) ** 2 or abs(got - math.sqrt(n)) <= 0.5


@settings(max_examples=150, deadline=None)
@given(y=st.integers(-10, 2 ** 62 - 1), fy=st.integers(-40, 90))
def test_rsqrt_dyn(c, y, fy):
    ffi, lib = c
    m, e = ffi.new("int32_t *"), ffi.new("int32_t *")
    lib.w_rsqrt_dyn64(y, fy, m, e)
    assert (m[0], e[0]) == rt.kf_rsqrt_dyn(y, fy)
    assert 2 ** 30 <= m[0] < 2 ** 31
    yy = max(y, 1)
    exact = 1.0 / math.sqrt(yy * 2.0 ** -fy)
    assert abs(m[0] * 2.0 ** -e[0] / exact - 1) < 2e-9


@settings(max_examples=150, deadline=None)
@given(a=I32, m=st.integers(2 ** 30, 2 ** 31 - 1), e=st.integers(-40, 120),
       kb=st.integers(-60, 60), lo=I32, hi=I32)
def test_mul_dyn(c, a, m, e, kb, lo, hi):
    lo, hi = _bounds(lo, hi)
    assert c[1].w_mul_dyn(a, m, e, kb, lo, hi) == rt.kf_mul_dyn(a, (m, e), kb, lo, hi)


@settings(max_examples=200, deadline=None)
@given(m=st.integers(2 ** 30, 2 ** 31 - 1), e=st.integers(-40, 120),
       cc=st.one_of(I32, st.integers(-2, 3), st.just(2 ** 31 - 1)), fc=st.integers(-10, 60))
def test_dyn_scale(c, m, e, cc, fc):
    ffi, lib = c
    om, oe = ffi.new("int32_t *"), ffi.new("int32_t *")
    lib.w_dyn_scale(m, e, cc, fc, om, oe)
    assert (om[0], oe[0]) == rt.kf_dyn_scale((m, e), cc, fc)
    if cc <= 0:
        assert om[0] == 0
        return
    assert 2 ** 30 <= om[0] < 2 ** 31                  # normalised again
    exact = m * 2.0 ** -e * cc * 2.0 ** -fc
    assert abs(om[0] * 2.0 ** -oe[0] / exact - 1) <= 2.0 ** -31   # rounded to nearest


@settings(max_examples=150, deadline=None)
@given(v=st.lists(st.one_of(I32, st.integers(-3, 3)), min_size=4, max_size=4),
       f=st.integers(-20, 60))
def test_rnorm_dyn(c, v, f):
    ffi, lib = c
    em, ee = 2 ** 30 + 12345, 20      # some eps constant
    m, e = ffi.new("int32_t *"), ffi.new("int32_t *")
    lib.w_rnorm_dyn(*v, f, em, ee, m, e)
    assert (m[0], e[0]) == rt.kf_rnorm_dyn(*v, f, em, ee)
    n2 = sum((x * 2.0 ** -f) ** 2 for x in v)
    if n2 > 0:
        exact = min(1.0 / math.sqrt(n2), em * 2.0 ** -ee)
        assert abs(m[0] * 2.0 ** -e[0] / exact - 1) < 1e-8


@settings(max_examples=150, deadline=None)
@given(x=st.floats(width=32, allow_nan=True, allow_infinity=True), f=st.integers(-30, 60))
def test_q_from_f32_matches_host_conversion(c, x, f):
    lo, hi = -(2 ** 31 - 1), 2 ** 31 - 1
    assert c[1].w_q_from_f32(x, f, lo, hi) == rt.q_from_float(x, f, lo, hi)
    assert rt.q_from_float_v(np.array([x]), f, lo, hi)[0] == rt.q_from_float(x, f, lo, hi)


def test_vector_helpers_equal_scalar_ones():
    rng = np.random.default_rng(1)
    n = rng.integers(-(2 ** 40), 2 ** 40, 500)
    d = rng.integers(-(2 ** 20), 2 ** 20, 500)
    assert rt.kf_div_rnd_v(n, d, -(2 ** 31 - 1), 2 ** 31 - 1).tolist() == \
        [rt.kf_div_rnd(int(a), int(b), -(2 ** 31 - 1), 2 ** 31 - 1) for a, b in zip(n, d)]
    v = rng.integers(0, 2 ** 62, 500)
    assert rt.kf_isqrt_rnd_v(v).tolist() == [rt.kf_isqrt_rnd(int(x)) for x in v]
    assert rt.kf_lsh_sat_v(d, 12, -(2 ** 31 - 1), 2 ** 31 - 1).tolist() == \
        [rt.kf_lsh_sat(int(x), 12, -(2 ** 31 - 1), 2 ** 31 - 1) for x in d]


def test_vector_dyn_product_broadcasts_a_per_run_scale():
    """A parameter-only reciprocal (one dyn value) times per-sample values (seen as a model bug)."""
    a = np.array([3, -7, 2 ** 30], dtype=np.int64)
    r = rt.kf_rsqrt_dyn(12345, 10)
    got = rt.kf_mul_dyn_v(a, r, 4, -(2 ** 31 - 1), 2 ** 31 - 1)
    assert got.tolist() == [rt.kf_mul_dyn(int(x), r, 4, -(2 ** 31 - 1), 2 ** 31 - 1) for x in a]


def test_a_changed_included_header_rebuilds(tmp_path, monkeypatch):
    # the cffi cache key covers the headers of the include directories, not only the sources
    # given: a helper changed in kf_fixed.h must not be served from a module built before
    monkeypatch.setenv("KINEFUSE_CACHE", str(tmp_path / "cache"))
    inc = tmp_path / "inc"
    inc.mkdir()
    src = tmp_path / "w.c"
    src.write_text('#include "k.h"\nint w(void) { return K; }\n')
    answers = []
    for k in (1, 2):
        (inc / "k.h").write_text(f"#define K {k}\n")
        _, lib = build("header_key_test", [], [src], extra_cdef="int w(void);",
                       include_dirs=[inc])
        answers.append(lib.w())
    assert answers == [1, 2]


def _squares_and_neighbours():
    out = [0, 1, 2, 3, 2 ** 32 - 1, 2 ** 32, 2 ** 60, 2 ** 62 - 1, 2 ** 63 - 1, 2 ** 64 - 1]
    for r in (1, 2, 65535, 65536, 2 ** 28 - 1, 2 ** 28, 2 ** 29 - 1, 2 ** 29, 2 ** 30, 2 ** 31 - 1,
              2 ** 31, 2 ** 32 - 1):
        out += [r * r - 1, r * r, r * r + 1, r * r + 2 * r, (r + 1) ** 2 - 1]
    return [v for v in out if 0 <= v < 2 ** 64]


@settings(max_examples=300, deadline=None)
@given(n=st.one_of(st.integers(0, 2 ** 64 - 1), st.integers(0, 2 ** 32),
                   st.integers(2 ** 60, 2 ** 62 - 1), st.sampled_from(_squares_and_neighbours())))
def test_isqrt_floor_is_exact(c, n):
    ffi, lib = c
    rem = ffi.new("uint64_t *")
    r = lib.w_isqrt_floor(n, rem)
    assert r == math.isqrt(n) and rem[0] == n - r * r


def test_isqrt_floor_at_squares_and_neighbours(c):
    ffi, lib = c
    rem = ffi.new("uint64_t *")
    for n in _squares_and_neighbours():
        r = lib.w_isqrt_floor(n, rem)
        assert (r, rem[0]) == (math.isqrt(n), n - math.isqrt(n) ** 2), n
