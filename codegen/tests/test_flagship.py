"""The flagship filter's generated code: bit-exact C and models (float32 and fixed point), the
float64 reference against the C, fixed point against float32, and the generated files.

Accuracy on BROAD and the comparison with VQF are benchmark figures (`kinefuse bench
accuracy --filter flagship --impl f32 --compare vqf`); the robustness scenarios are in
host/tests/test_flagship_robustness.py."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest

from kinefuse.codegen import estimators
from kinefuse.codegen import runner as cg
from kinefuse.codegen.generate import GENERATED_DIR, render_all

NAME = "flagship"
OUTPUTS = ("q", "q6", "q9", "rest", "mag_disturbed", "rejected", "bias")


def angle_deg(a, b):
    """Per-sample rotation angle between two quaternion arrays, degrees."""
    a = np.asarray(a, float)
    b = np.asarray(b, float)
    a = a / np.linalg.norm(a, axis=1, keepdims=True)
    b = b / np.linalg.norm(b, axis=1, keepdims=True)
    d = np.clip(np.abs(np.sum(a * b, axis=1)), 0.0, 1.0)
    return np.degrees(2.0 * np.arccos(d))


@pytest.fixture(scope="module")
def segment(excerpt_inputs):
    """3 000 samples of BROAD trial 08 across the start of its fast motion (28.5 s), with a
    slower magnetometer (every 3rd sample), jittered time steps and invalid samples injected."""
    _, inp = excerpt_inputs
    sl = slice(7000, 10000)
    seg = {k: np.array(v[sl]) for k, v in inp.items()}
    n = len(seg["dt"])
    seg["mag_valid"] = (np.arange(n) % 3) == 0
    rng = np.random.default_rng(7)
    seg["dt"] = seg["dt"] * rng.uniform(0.8, 1.2, n)
    seg["gyr"][500] = np.nan                       # non-finite gyroscope: sample rejected
    seg["acc"][900] = [np.inf, 0.0, 9.8]           # non-finite accelerometer
    seg["acc"][1300, 2] = 200.0                    # beyond +-16 g: saturated
    seg["mag"][1500] = [np.nan, 1.0, 1.0]          # invalid magnetometer reading (mag_valid)
    seg["dt"][1700] = 0.0                          # duplicate time stamp
    return seg


def defaults(**over):
    p = estimators.get(NAME).default_params()
    p.update(over)
    return p


@pytest.mark.parametrize("system", ["f32", "q"])
@pytest.mark.parametrize("mode", [0.0, 1.0])
def test_c_equals_model_bit_for_bit(segment, system, mode):
    prm = defaults(mode=mode)
    c = cg.run(NAME, system, segment, prm, raw=True)
    m = cg.run(NAME, f"{system}-model", segment, prm, raw=True)
    assert set(c) == set(OUTPUTS)
    for k in OUTPUTS:
        differ = np.any(cg.bits(c[k]) != cg.bits(m[k]), axis=1)
        assert not differ.any(), f"{system} {k}: {int(differ.sum())} samples differ, " \
                                 f"first at {int(np.argmax(differ))}"


def test_invalid_samples_are_counted_and_harmless(segment):
    out = cg.run(NAME, "f32", segment, defaults())
    for k in ("q", "q6", "q9", "bias"):
        assert np.all(np.isfinite(out[k])), k
    rej = out["rejected"][:, 0]
    # one count per bad sample: gyro NaN, acc inf, acc saturated, bad mag reading, dt = 0
    assert rej[-1] == 5
    assert rej[499] == 0 and rej[500] == 1 and rej[1700] == 5
    # a rejected sample changes nothing: the output equals the previous one
    assert np.array_equal(out["q"][500], out["q"][499])
    assert np.allclose(np.linalg.norm(out["q"], axis=1), 1.0, atol=1e-5)


def test_reference_equals_float32_closely(segment):
    """The float64 reference and the float32 C follow the same trajectory (gating decisions may
    flip on 1-ulp differences, so the comparison is on the orientation, not bits)."""
    n = 1500
    seg = {k: v[:n] for k, v in segment.items()}
    ref = cg.run(NAME, "ref", seg, defaults())
    f32 = cg.run(NAME, "f32", seg, defaults())
    assert np.max(angle_deg(ref["q"], f32["q"])) < 0.01
    assert np.max(np.abs(ref["bias"] - f32["bias"])) < 1e-5


def test_fixed_point_close_to_float32(excerpt_inputs):
    _, inp = excerpt_inputs
    f32 = cg.run(NAME, "f32", inp, defaults())
    q = cg.run(NAME, "q", inp, defaults())
    d = angle_deg(f32["q"], q["q"])
    assert np.percentile(d, 99) < 0.1 and np.max(d) < 0.5
    assert np.max(angle_deg(f32["q6"], q["q6"])) < 0.5


def test_mode_selects_the_output(segment):
    six = cg.run(NAME, "f32", segment, defaults(mode=0.0))
    nine = cg.run(NAME, "f32", segment, defaults(mode=1.0))
    assert np.array_equal(six["q"], six["q6"]) and np.array_equal(six["q9"], six["q6"])
    assert np.array_equal(nine["q"], nine["q9"])
    assert not six["mag_disturbed"].any()
    # 6D mode ignores the magnetometer entirely: garbage there changes nothing
    garbage = dict(segment, mag=np.full_like(segment["mag"], 3000.0))
    again = cg.run(NAME, "f32", garbage, defaults(mode=0.0), raw=True)
    first = cg.run(NAME, "f32", segment, defaults(mode=0.0), raw=True)
    for k in ("q", "bias"):
        assert np.array_equal(cg.bits(again[k]), cg.bits(first[k]))


def test_heading_correction_never_tilts(segment):
    """q9 = (rotation about the vertical) x q6: the 9D and 6D estimates share inclination."""
    out = cg.run(NAME, "ref", {k: v[:800] for k, v in segment.items()}, defaults())
    q6, q9 = out["q6"], out["q9"]
    # d = q9 q6^-1 must be a pure rotation about z: its x and y parts vanish
    w6, v6 = q6[:, :1], -q6[:, 1:]
    d_w = q9[:, :1] * w6 - np.sum(q9[:, 1:] * v6, axis=1, keepdims=True)
    d_v = q9[:, :1] * v6 + w6 * q9[:, 1:] + np.cross(q9[:, 1:], v6)
    assert np.max(np.abs(d_v[:, :2])) < 1e-12
    assert np.all(np.isfinite(d_w))


def test_generated_files_are_current():
    files = render_all([NAME])
    mine = {k: v for k, v in files.items() if k.startswith(f"{NAME}_") or
            k.startswith(f"models/{NAME}_")}
    assert len(mine) == 6
    for rel, text in mine.items():
        assert (GENERATED_DIR / rel).read_text() == text, f"{rel} is stale: run kinefuse codegen"


def test_fixed_point_c_has_no_oversized_shifts():
    """Every shift and power-of-two constant stays below 63 bits (no undefined behaviour, no
    format so coarse that a value loses all precision)."""
    text = (GENERATED_DIR / f"{NAME}_q.c").read_text()
    shifts = [int(s) for s in re.findall(r"(?:>>|<<) (\d+)", text)]
    assert shifts and max(shifts) < 63
    assert "9223372036854775808" not in text


def test_state_formats_resolve_the_physics():
    """Q formats chosen from the declared ranges: fine enough for what each state carries."""
    fm = cg.runner(NAME, "q").formats
    res = {k: 2.0 ** -v[0] for k, v in fm.items()}
    assert res["state.q_i"] <= 2 ** -30 and res["state.q_a"] <= 2 ** -30
    assert res["state.bias"] < 1e-9                       # rad/s
    assert res["state.p_head"] < 1e-8                     # rad^2
    assert res["state.lp_x"] < 1e-6                       # m/s^2
    assert res["state.cur_d"] <= 2 ** -30


def test_parameters_are_range_checked():
    est = estimators.get(NAME)
    with pytest.raises(ValueError):
        est.resolve_params({"tau_acc": 0.0})
    with pytest.raises(ValueError):
        est.resolve_params({"mode": 2.0})
    prm = est.resolve_params({"mode": 0.0})
    assert prm["mode"] == 0.0 and prm["tau_acc"] == 3.0
    # every parameter carries a unit string and a description
    assert all(p.doc for p in est.params)
    assert math.isclose(est.param("rest_th_gyr").default, math.radians(2.0))
