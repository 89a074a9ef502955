"""Bit-exact float32 on M4F (hardware FPU), M0 (soft float) and the x86 host vs a numpy model.

The function is quaternion normalisation written one operation per statement
(csrc/selftest_quat_norm.c); the model performs the same float32 operations in the same
order.  Every output's bit pattern is compared; NaNs compare equal whatever their payload
(x86 produces 0xFFC00000, ARM 0x7FC00000).
"""
from __future__ import annotations

import ctypes
import shutil
import subprocess

import numpy as np
import pytest

from kinefuse.hil_tests.qemu import build_batch, qemu_unavailable
from kinefuse.hil_tests.qemu.batch import csrc_path

pytestmark = [pytest.mark.qemu,
              pytest.mark.skipif(qemu_unavailable() is not None, reason=str(qemu_unavailable()))]

FUNC = "kf_selftest_quat_normalise"


def model(q: np.ndarray) -> np.ndarray:
    q = q.astype(np.float32)
    with np.errstate(all="ignore"):
        ww, xx, yy, zz = (q[:, i] * q[:, i] for i in range(4))
        s3 = ((ww + xx) + yy) + zz
        inv = np.float32(1.0) / np.sqrt(s3)
        return q * inv[:, None]


def inputs(n: int = 20000, seed: int = 2024) -> np.ndarray:
    rng = np.random.default_rng(seed)
    q = rng.normal(size=(n, 4)).astype(np.float32)
    # wide exponents: overflow to inf, underflow into subnormals and zero
    q[n // 2:] *= (10.0 ** rng.uniform(-25, 25, size=(n - n // 2, 1))).astype(np.float32)
    special = np.array([[0, 0, 0, 0], [1, 0, 0, 0], [-0.0, 0, 0, 0], [np.inf, 1, 0, 0],
                        [np.nan, 0, 0, 0], [1e-45, 0, 0, 0], [3e38, 3e38, 0, 0],
                        [1e-20, 1e-20, 1e-20, 1e-20], [0.5, 0.5, 0.5, 0.5]], dtype=np.float32)
    q[:len(special)] = special
    return q


def same_bits(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    ua, ub = a.view(np.uint32), b.view(np.uint32)
    return (ua == ub) | (np.isnan(a) & np.isnan(b))


def test_flush_to_zero_is_off_in_this_process():
    tiny = np.array([1e-45], dtype=np.float32)
    assert tiny[0] != 0 and (tiny * np.float32(1.0))[0] != 0


@pytest.mark.parametrize("target", ["m4f", "m0"])
def test_quat_normalise_bit_exact_on_target(target):
    q = inputs()
    prog = build_batch([csrc_path("selftest_quat_norm.c")], FUNC, in_size=16, out_size=16,
                       target=target)
    out = np.frombuffer(prog.run(q.astype("<f4").tobytes(), timeout=60), dtype="<f4").reshape(-1, 4)
    expected = model(q)
    ok = same_bits(out, expected)
    assert ok.all(), f"{np.count_nonzero(~ok)} of {ok.size} outputs differ on {target}"
    # the comparison has teeth: results include normal values, infinities' NaNs and subnormals
    assert np.isnan(out).any() and (np.abs(out[np.isfinite(out)]) > 0.1).any()


@pytest.mark.skipif(shutil.which("gcc") is None, reason="host gcc not installed")
def test_quat_normalise_bit_exact_on_host(tmp_path):
    lib = tmp_path / "libqn.so"
    subprocess.run(["gcc", "-shared", "-fPIC", "-O2", "-std=c99", "-ffp-contract=off",
                    "-fno-fast-math", "-o", str(lib), str(csrc_path("selftest_quat_norm.c")), "-lm"],
                   check=True)
    fn = getattr(ctypes.CDLL(str(lib)), FUNC)
    fn.argtypes, fn.restype = [ctypes.c_void_p, ctypes.c_void_p], None
    q = inputs(4000)
    out = np.empty_like(q)
    for i in range(len(q)):
        fn(q[i].ctypes.data, out[i].ctypes.data)
    ok = same_bits(out, model(q))
    assert ok.all(), f"{np.count_nonzero(~ok)} host outputs differ"


def test_comparison_detects_a_one_ulp_change():
    q = inputs(100)
    a = model(q)
    b = a.copy()
    b.view(np.uint32)[50, 1] += 1
    assert not same_bits(a, b).all()
