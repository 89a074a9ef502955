"""The fixed-point helpers as the Cortex-M builds compile them, against their Python mirror.

The host tests (codegen/tests/test_qruntime.py) cover the C paths a host can compile; the
Cortex-M0's Thumb-1 assembly division and the M4F's FPU-seeded square root exist only on the
targets, so the same helpers run here on QEMU, on random and edge operands."""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.codegen.runtime import RUNTIME_DIR
from kinefuse.codegen.runtime import q as rt
from kinefuse.hil_tests.qemu import qemu_unavailable, run_batch

pytestmark = [pytest.mark.qemu,
              pytest.mark.skipif(qemu_unavailable() is not None, reason=str(qemu_unavailable()))]

# record in: int64 a, int64 b, int32 c, int32 d, int32 op, pad -> 32 bytes; out: int64 x, int64 y
REC_IN = np.dtype([("a", "<i8"), ("b", "<i8"), ("c", "<i4"), ("d", "<i4"), ("op", "<i4"),
                   ("pad", "<i4")])
REC_OUT = np.dtype([("x", "<i8"), ("y", "<i8")])
OP_DIV, OP_RSQRT, OP_ISQRT = 0, 1, 2
PRELUDE = '#include <string.h>\n#include "kf_fixed.h"\n' + r"""
typedef struct { int64_t a, b; int32_t c, d, op, pad; } kf_rec_in;
typedef struct { int64_t x, y; } kf_rec_out;
"""
STEP = r"""
{
    kf_rec_in r;
    kf_rec_out o;
    memcpy(&r, kf_in, sizeof r);
    o.x = 0; o.y = 0;
    if (r.op == 0) {
        o.x = kf_div_rnd(r.a, r.b, r.c, r.d);
    } else if (r.op == 1) {
        kf_dyn v = kf_rsqrt_dyn64(r.a, r.c);
        o.x = v.m; o.y = v.e;
    } else {
        o.x = kf_isqrt_rnd(r.a);
    }
    memcpy(kf_out, &o, sizeof o);
}
"""
EDGE_D = [1, -1, 2, 3, -3, 7, 65535, 65536, 2 ** 30, 2 ** 31 - 1, -(2 ** 31 - 1), 2 ** 31,
          -(2 ** 31), 2 ** 31 + 1, 2 ** 32, 2 ** 40 + 5, -(2 ** 45)]


def _records(seed: int = 5) -> np.ndarray:
    rng = np.random.default_rng(seed)
    recs = []

    def add(op, a, b=0, c=0, d=0):
        if abs(a) <= 2 ** 62 and abs(b) <= 2 ** 62:    # the generated code's int64 operands
            recs.append((a, b, c, d, op, 0))

    # divisions: the generated code's operands (int32 divisor, numerator a scaled int32), the
    # borders of the 32-bit fast path (quotient 2^32 - 1, divisor 2^31) and wide divisors
    for _ in range(1500):
        d = int(rng.integers(-(2 ** 31), 2 ** 31))
        n = int(rng.integers(-(2 ** 31), 2 ** 31)) << int(rng.integers(0, 32))
        lo, hi = sorted(int(x) for x in rng.integers(-(2 ** 31) + 1, 2 ** 31, 2))
        add(OP_DIV, n, d, lo, hi)
        add(OP_DIV, n, d, -(2 ** 31) + 1, 2 ** 31 - 1)
    for d in EDGE_D:
        for n in (0, 1, -1, d // 2 if d else 0, (abs(d) << 32) - 1, abs(d) << 32, 2 ** 62,
                  -(2 ** 62), 3 * abs(d) + (abs(d) + 1) // 2, int(rng.integers(0, 2 ** 62))):
            add(OP_DIV, n, d, -(2 ** 31) + 1, 2 ** 31 - 1)
    for _ in range(300):
        add(OP_DIV, int(rng.integers(-(2 ** 62), 2 ** 62)), int(rng.integers(-(2 ** 62), 2 ** 62)),
            -(2 ** 31) + 1, 2 ** 31 - 1)
    # reciprocal square roots and square roots over the whole operand range
    for _ in range(600):
        y = int(rng.integers(1, 2 ** 62)) >> int(rng.integers(0, 62))
        add(OP_RSQRT, y, 0, int(rng.integers(-40, 91)))
        add(OP_ISQRT, int(rng.integers(0, 2 ** 62)) >> int(rng.integers(0, 62)))
    for y in (0, 1, 2, 3, 2 ** 30, 2 ** 60 - 1, 2 ** 60, 2 ** 61, 2 ** 62 - 1):
        add(OP_RSQRT, y, 0, 0)
        add(OP_RSQRT, y, 0, 1)
    for n in (0, 1, 2, 3, 4, 2 ** 32 - 1, 2 ** 32, 2 ** 62 - 1, 2 ** 62, (2 ** 31 + 1) ** 2 - 1):
        add(OP_ISQRT, n)
    return np.array(recs, dtype=REC_IN)


def _expected(recs: np.ndarray) -> np.ndarray:
    out = np.zeros(len(recs), dtype=REC_OUT)
    for i, r in enumerate(recs.tolist()):
        a, b, c, d, op, _ = r
        if op == OP_DIV:
            out[i] = (rt.kf_div_rnd(a, b, c, d), 0)
        elif op == OP_RSQRT:
            out[i] = rt.kf_rsqrt_dyn(a, c)
        else:
            out[i] = (rt.kf_isqrt_rnd(a), 0)
    return out


@pytest.mark.parametrize("target", ["m0", "m4f"])
def test_fixed_point_helpers_on_the_target_match_the_mirror(target):
    recs = _records()
    raw = run_batch([], STEP, in_size=REC_IN.itemsize, out_size=REC_OUT.itemsize,
                    data=recs.tobytes(), target=target, include_dirs=[RUNTIME_DIR],
                    prelude=PRELUDE, opt="-Os")
    got = np.frombuffer(raw, dtype=REC_OUT)
    want = _expected(recs)
    bad = np.flatnonzero((got["x"] != want["x"]) | (got["y"] != want["y"]))
    assert bad.size == 0, (f"{bad.size} of {len(recs)} differ; first: input {recs[bad[0]]}, "
                           f"target {got[bad[0]]}, mirror {want[bad[0]]}")
