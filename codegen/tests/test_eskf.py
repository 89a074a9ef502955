"""The error-state Kalman filter: its scalar Joseph-form update against a direct numpy
evaluation, bit-exact generated C and models, a positive-definite covariance in float32 and in
fixed point (eigenvalues of the full 9x9 matrix from the models' state), and accuracy on
simulated motion.  BROAD figures: `kinefuse bench accuracy --filter eskf --impl f32`."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest

from kinefuse.codegen import estimators
from kinefuse.codegen import runner as cg
from kinefuse.codegen.estimators import eskf as E
from kinefuse.codegen.generate import GENERATED_DIR, render_all
from kinefuse.codegen.linalg import ZERO

NAME = "eskf"
OUTPUTS = ("q", "bias", "lin_acc", "cov_att", "var_bias", "mag_disturbed", "rejected")


def defaults(**over):
    p = estimators.get(NAME).default_params()
    p.update(over)
    return p


@pytest.fixture(scope="module")
def segment(excerpt_inputs):
    """2 500 samples of BROAD trial 08 across the start of its fast motion, with a slower
    magnetometer and a few invalid samples."""
    _, inp = excerpt_inputs
    seg = {k: np.array(v[7500:10000]) for k, v in inp.items()}
    n = len(seg["dt"])
    seg["mag_valid"] = (np.arange(n) % 2) == 0
    seg["gyr"][400] = np.nan
    seg["acc"][800, 1] = 1e6
    seg["dt"][1200] = -0.01
    return seg


# -------------------------------------------------------------------------------------------------
# the update equations (float64 reference code)


def test_scalar_update_is_the_joseph_form():
    rng = np.random.default_rng(3)
    scale = np.array([1e-3] * 3 + [3e-4] * 3 + [0.5] * 3)       # sigmas within the block ranges
    for _ in range(50):
        a = rng.normal(size=(9, 9)) * scale[:, None]
        P = a @ a.T / 9.0 + np.diag(scale ** 2) * 0.1
        h = [ZERO if rng.random() < 0.4 else float(v) for v in rng.normal(size=9)]
        hv = np.array([0.0 if v is ZERO else v for v in h])
        r = float(rng.uniform(0.01, 2.0))
        dx = rng.normal(size=9) * scale * 0.1
        y = float(rng.normal())
        Pn, dxn = E.scalar_update([list(map(float, row)) for row in P], list(map(float, dx)), h,
                                  y, r, 1e-6, True)
        S = hv @ P @ hv + r
        K = P @ hv / S
        A = np.eye(9) - np.outer(K, hv)
        joseph = A @ P @ A.T + r * np.outer(K, K)
        assert np.allclose(np.array(Pn, float), joseph, rtol=1e-9, atol=1e-15)
        assert np.allclose(dxn, dx + K * (y - hv @ dx), rtol=1e-9, atol=1e-15)
        assert np.array_equal(np.array(Pn), np.array(Pn).T)       # exactly symmetric


def test_gate_and_disabled_update_leave_everything_unchanged():
    P = np.diag([1e-4] * 3 + [1e-6] * 3 + [0.25] * 3)
    h = [ZERO, -E.G, ZERO, ZERO, ZERO, ZERO, 1.0, ZERO, ZERO]
    P0 = [list(map(float, row)) for row in P]
    for use, y, gate in ((False, 0.1, None), (True, 50.0, 3.0)):
        Pn, dxn = E.scalar_update(P0, [0.0] * 9, h, y, 0.3, 1e-6, use, gate)
        assert np.array_equal(np.array(Pn, float), np.array(P0)) and not any(dxn)


def test_covariance_blocks_pack_and_unpack():
    rng = np.random.default_rng(1)
    a = rng.normal(size=(9, 9)) * 1e-3
    P = (a @ a.T).tolist()
    blocks = E.pack_p(P)
    assert sum(len(v) for v in blocks.values()) == 45
    back = E.unpack_p(type("X", (), blocks))
    assert np.allclose(np.array(back, float), np.array(P), atol=1e-12)


# -------------------------------------------------------------------------------------------------
# generated code


@pytest.mark.parametrize("system", ["f32", "q"])
def test_c_equals_model_bit_for_bit(segment, system):
    c = cg.run(NAME, system, segment, defaults(), raw=True)
    m = cg.run(NAME, f"{system}-model", segment, defaults(), raw=True)
    assert set(c) == set(OUTPUTS)
    for k in OUTPUTS:
        differ = np.any(cg.bits(c[k]) != cg.bits(m[k]), axis=1)
        assert not differ.any(), f"{system} {k}: {int(differ.sum())} samples differ"


def full_covariances(system, inputs, chunk=125):
    """The 9x9 covariance after every `chunk` samples, from the generated model's state."""
    r = cg.runner(NAME, f"{system}-model")
    enc = r.encode(inputs, estimators.get(NAME).resolve_params(defaults()))
    state = r.initial_state()
    Ps = []
    for a in range(0, enc.n, chunk):
        b = min(enc.n, a + chunk)
        cols = {k: [v[a:b, i] for i in range(v.shape[1])] for k, v in enc.inputs.items()}
        prm = {k: [v.item() if system == "q" else v] for k, v in enc.params.items()}
        _, state = r.mod.run(cols, prm, state, b - a)
        blocks = {}
        for name in E.P_BLOCKS:
            vals = np.array([float(v) for v in state[name]])
            if system == "q":
                vals = np.ldexp(vals, -r.formats[f"state.{name}"][0])
            blocks[name] = vals
        Ps.append(np.array(E.unpack_p(type("X", (), blocks)), float))
    return Ps


@pytest.mark.parametrize("system", ["f32", "q"])
def test_covariance_stays_positive_definite(segment, system):
    Ps = full_covariances(system, segment)
    assert len(Ps) == 20
    for P in Ps:
        assert np.array_equal(P, P.T)
        # correlation matrix: scale-free test of definiteness
        d = np.sqrt(np.diag(P))
        assert np.all(d > 0)
        assert np.linalg.eigvalsh(P / np.outer(d, d)).min() > 1e-6


def test_covariance_output_is_the_state(segment):
    out = cg.run(NAME, "f32", segment, defaults())
    ca = out["cov_att"]
    assert np.all(ca[:, [0, 3, 5]] > 0) and np.all(out["var_bias"] > 0)
    P = full_covariances("f32", segment, chunk=len(segment["dt"]))[-1]
    assert np.allclose(ca[-1], P[np.triu_indices(3)], rtol=1e-6)
    assert np.allclose(out["var_bias"][-1], np.diag(P)[3:6], rtol=1e-6)


def test_invalid_samples_are_counted(segment):
    out = cg.run(NAME, "f32", segment, defaults())
    assert out["rejected"][-1, 0] == 3
    for k in ("q", "bias", "lin_acc", "cov_att"):
        assert np.all(np.isfinite(out[k]))


def test_fixed_point_close_to_float32(excerpt_inputs):
    _, inp = excerpt_inputs
    f = cg.run(NAME, "f32", inp, defaults())
    q = cg.run(NAME, "q", inp, defaults())
    d = np.abs(np.sum(f["q"] * q["q"], axis=1))
    ang = np.degrees(2 * np.arccos(np.clip(d, 0, 1)))
    assert np.percentile(ang, 99) < 0.3 and np.max(ang) < 1.0


def test_generated_files_are_current_and_shifts_bounded():
    files = render_all([NAME])
    for rel, text in files.items():
        if rel.startswith(f"{NAME}_") or rel.startswith(f"models/{NAME}_"):
            assert (GENERATED_DIR / rel).read_text() == text, f"{rel} is stale"
    text = (GENERATED_DIR / f"{NAME}_q.c").read_text()
    assert max(int(s) for s in re.findall(r"(?:>>|<<) (\d+)", text)) < 63


def test_block_formats_follow_their_scales():
    fm = cg.runner(NAME, "q").formats
    assert fm["state.p_tt"][0] >= 33            # attitude variance: resolution <= 1.2e-10 rad^2
    assert fm["state.p_bb"][0] >= 39            # bias variance (rad/s)^2
    assert fm["state.p_aa"][0] >= 25            # linear acceleration (m/s^2)^2


# -------------------------------------------------------------------------------------------------
# behaviour on simulated motion


def test_tracks_simulated_motion_and_bias():
    from kinefuse.hil_tests import sim
    from kinefuse.host import runner as host_runner
    from kinefuse.host.metrics import error_series
    rec = sim.simulate("slow_rotation", seed=2)
    out = cg.run(NAME, "f32", host_runner.imu_inputs(rec), defaults())
    e = error_series(out["q"], rec.q_true)
    settled = rec.t > 3.0
    assert np.sqrt(np.mean(e.inclination[settled] ** 2)) < 1.0
    assert np.sqrt(np.mean(e.total[settled] ** 2)) < 3.0
    rec = sim.simulate("bias_1dps", seed=2)
    out = cg.run(NAME, "f32", host_runner.imu_inputs(rec), defaults())
    # the estimate converges and is consistent with its own variance (within 2 sigma)
    err = np.abs(np.degrees(out["bias"][-1]) - 1.0)
    sigma = np.degrees(np.sqrt(out["var_bias"][-1]))
    assert np.all(err < 2.0 * sigma) and np.all(err < 0.1)
    assert np.all(out["var_bias"][-1] < 0.1 * out["var_bias"][100])
    # the reported tilt uncertainty shrinks at rest (to the steady state set by gyr_noise and
    # acc_noise: about 2.5 deg with the defaults, which cover gyroscope errors in fast motion)
    assert out["cov_att"][-1, 0] < out["cov_att"][10, 0]
    assert math.degrees(math.sqrt(out["cov_att"][-1, 0])) < 3.0

