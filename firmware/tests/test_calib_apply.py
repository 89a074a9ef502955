"""The on-unit calibration map (codegen/estimators/calib_apply.py): generated C equals its
model in every bit (f32 and q), follows the host's convention cal = M·(raw − b) with
raw = counts·scale, and with the default parameters gives exactly float32(counts)·float32(scale)
(the KF_RAW_SAMPLE units), so a host replaying raw samples reproduces the unit."""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.codegen import runner
from kinefuse.codegen.estimators.calib_apply import SENSORS
from kinefuse.host.calib.affine import apply_affine

N = 3000


@pytest.fixture(scope="module")
def case():
    rng = np.random.default_rng(8)
    inp = {k: rng.integers(-32768, 32768, size=(N, 3)).astype(float) for k in ("acc_raw", "gyr_raw", "mag_raw")}
    inp["acc_raw"][:5] = [[32767, -32768, 0]] * 5                   # full scale
    inp["dt_us"] = rng.integers(0, 1_000_001, size=N).astype(float)
    params, maps = {}, {}
    for s, scale, b_sd in (("acc", 4.79e-3, 0.3), ("gyr", 1.06e-3, 0.02), ("mag", 0.15, 30.0)):
        M = np.eye(3) + rng.normal(0, 0.03, (3, 3))
        b = rng.normal(0, b_sd, 3)
        maps[s] = (M, b, scale)
        params.update({f"{s}_m{i}{j}": M[i, j] for i in range(3) for j in range(3)})
        params.update({f"{s}_b{i}": b[i] for i in range(3)})
        params[f"{s}_scale"] = scale
    return inp, params, maps


@pytest.mark.parametrize("system", ["f32", "q"])
def test_c_equals_model_bit_for_bit(case, system):
    inp, params, _ = case
    c = runner.run("calib_apply", system, inp, params, raw=True)
    m = runner.run("calib_apply", f"{system}-model", inp, params, raw=True)
    for k in ("gyr", "acc", "mag", "dt"):
        assert np.array_equal(runner.bits(c[k]), runner.bits(m[k])), k


def test_reference_is_the_host_affine_map(case):
    inp, params, maps = case
    ref = runner.run("calib_apply", "ref", inp, params)
    for s, (M, b, scale) in maps.items():
        lim = 2 * SENSORS[s][4]
        expect = np.clip(apply_affine(inp[f"{s}_raw"] * scale, M, b), -lim, lim)
        assert np.allclose(ref[s], expect, rtol=0, atol=1e-9 * lim)
    assert np.allclose(ref["dt"][:, 0], inp["dt_us"] * 1e-6, rtol=1e-15, atol=0)


@pytest.mark.parametrize("system, tol", [("f32", {"acc": 1e-4, "gyr": 2e-5, "mag": 2e-3, "dt": 1e-7}),
                                         ("q", {"acc": 2e-5, "gyr": 2e-6, "mag": 5e-4, "dt": 1e-8})])
def test_accuracy_against_the_reference(case, system, tol):
    """Measured worst-case errors (m/s², rad/s, µT, s) stay within the stated bounds."""
    inp, params, _ = case
    ref = runner.run("calib_apply", "ref", inp, params)
    got = runner.run("calib_apply", system, inp, params)
    for k, t in tol.items():
        err = float(np.max(np.abs(got[k] - ref[k])))
        assert err < t, f"{system} {k}: {err:.3g}"


def test_defaults_give_exactly_the_message_units():
    rng = np.random.default_rng(2)
    counts = {k: rng.integers(-32768, 32768, size=(500, 3)).astype(float) for k in ("acc_raw", "gyr_raw", "mag_raw")}
    counts["acc_raw"] = np.clip(counts["acc_raw"], -31999, 31999)   # +-32 g: beyond, the map clamps
    inp = dict(counts, dt_us=np.full(500, 1000.0))
    out = runner.run("calib_apply", "f32", inp, None, raw=True)
    from kinefuse.host.link.dialect import RAW_SCALE
    for s, key in (("acc", "acc"), ("gyr", "gyro"), ("mag", "mag")):
        want = counts[f"{s}_raw"].astype(np.float32) * np.float32(RAW_SCALE[key])
        assert np.array_equal(out[s].view(np.uint32), want.astype(np.float32).view(np.uint32)), s
    assert np.all(out["dt"] == np.float32(1000.0) * np.float32(1e-6))


def test_outputs_are_in_the_filters_input_formats():
    """The q outputs feed the filters' kf_imu_input_q fields without conversion."""
    from kinefuse.firmware.generated.models import calib_apply_q, madgwick_q
    for k in ("gyr", "acc", "mag", "dt"):
        assert calib_apply_q.FORMATS[f"output.{k}"][0] == madgwick_q.FORMATS[f"input.{k}"][0]
