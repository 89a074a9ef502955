"""Batch driver round trip: N records in, N records out, on M4F and M0."""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.hil_tests.qemu import build_batch, qemu_unavailable, run_batch
from kinefuse.host.errors import KinefuseError

pytestmark = [pytest.mark.qemu,
              pytest.mark.skipif(qemu_unavailable() is not None, reason=str(qemu_unavailable()))]

# 7-byte records in, 5-byte records out: odd sizes exercise the aligned copies
STEP_SRC = r"""
#include <stdint.h>
#include <string.h>
void kf_test_step(const void *in, void *out)
{
    const uint8_t *b = (const uint8_t *)in;
    uint8_t o[5];
    uint32_t sum = 0u;
    uint8_t x = 0u;
    for (uint32_t i = 0u; i < 7u; i++) {
        sum += b[i];
        x = (uint8_t)(x ^ b[i]);
    }
    o[0] = (uint8_t)sum;
    o[1] = (uint8_t)(sum >> 8);
    o[2] = x;
    o[3] = b[0];
    o[4] = b[6];
    memcpy(out, o, sizeof o);
}
"""


def model(records: np.ndarray) -> np.ndarray:
    s = records.astype(np.uint32).sum(axis=1)
    x = np.bitwise_xor.reduce(records, axis=1)
    return np.stack([s & 0xFF, s >> 8, x, records[:, 0], records[:, 6]], axis=1).astype(np.uint8)


@pytest.fixture(scope="module")
def step_source(tmp_path_factory):
    p = tmp_path_factory.mktemp("batch") / "step.c"
    p.write_text(STEP_SRC)
    return p


@pytest.mark.parametrize("target", ["m4f", "m0"])
def test_round_trip_many_blocks(step_source, target):
    rng = np.random.default_rng(5)
    recs = rng.integers(0, 256, size=(25_000, 7), dtype=np.uint8)   # > 2 semihosting blocks
    prog = build_batch([step_source], "kf_test_step", in_size=7, out_size=5, target=target)
    out = np.frombuffer(prog.run(recs.tobytes(), timeout=60), dtype=np.uint8).reshape(-1, 5)
    np.testing.assert_array_equal(out, model(recs))


def test_empty_input_gives_empty_output(step_source):
    prog = build_batch([step_source], "kf_test_step", in_size=7, out_size=5, target="m0")
    assert prog.run(b"") == b""


def test_partial_record_is_rejected(step_source):
    prog = build_batch([step_source], "kf_test_step", in_size=7, out_size=5, target="m0")
    with pytest.raises(KinefuseError, match="multiple of the record size"):
        prog.run(b"\x00" * 10)


@pytest.mark.parametrize("target", ["m4f", "m0"])
def test_snippet_with_state_and_setup(target):
    """Running int64 sum of int32 inputs: needs setup and record order to be right."""
    vals = np.random.default_rng(9).integers(-2**31, 2**31, size=3000, dtype=np.int64).astype("<i4")
    out = run_batch([], "int32_t v; memcpy(&v, kf_in, 4); kf_acc += v; memcpy(kf_out, &kf_acc, 8);",
                    prelude="static int64_t kf_acc;", setup="kf_acc = 1000;",
                    in_size=4, out_size=8, data=vals.tobytes(), target=target)
    np.testing.assert_array_equal(np.frombuffer(out, "<i8"), 1000 + np.cumsum(vals.astype(np.int64)))


def test_failing_step_raises():
    with pytest.raises(KinefuseError, match="status 134"):
        run_batch([], '__asm__ volatile("udf #0");', in_size=4, out_size=4,
                  data=b"\x00" * 8, target="m0")
