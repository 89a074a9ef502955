"""The generated dynamic EKFs (pendulum, leg, leg_foot): committed files up to date, C equal to
its Python model in every bit of every output, float32 against the float64 reference, bad
input handled with status outputs and finite estimates, the leg's accuracy targets."""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.codegen import runner as cg
from kinefuse.codegen.generate import GENERATED_DIR, render_all
from kinefuse.host.dynamics import truth as T

NAMES = ["pendulum", "leg", "leg_foot"]


def test_committed_generated_files_are_up_to_date():
    files = render_all(NAMES)
    mine = {k: v for k, v in files.items() if any(k.startswith(p) or k.startswith("models/" + p)
                                                 or k == f"kf_{p}_f32.h" for p in NAMES)}
    assert mine, "nothing rendered"
    stale = [k for k, v in mine.items()
             if not (GENERATED_DIR / k).exists() or (GENERATED_DIR / k).read_text() != v]
    assert not stale, f"run kinefuse codegen: stale {stale}"


def _bits_equal(a, b):
    return all(np.array_equal(cg.bits(a[k]), cg.bits(b[k])) for k in a)


def _pendulum_inputs(n=300, seed=1):
    tr = T.pendulum_trial(T.PendulumConfig.table_a_1(seed=seed))
    inp = {k: np.array(v, copy=True) for k, v in tr.inputs().items()}
    # occlusion of bar 1, a lost plate, and bad samples of every kind
    inp["marker_valid"][120:150, 0:2] = False
    inp["markers"][120:150, 0:4] = np.nan
    inp["effort_valid"][200:210, 1:] = False
    inp["markers"][60, 3] = np.inf               # flagged valid: must be rejected
    inp["markers"][61, 5] = 1e6
    inp["efforts"][70, 2] = np.nan
    inp["dt"][80] = np.nan
    inp["dt"][81] = -0.01
    inp["dt"][82] = 5.0
    return tr, {k: v[:n] for k, v in inp.items()}


def test_pendulum_c_equals_model_bit_for_bit_and_handles_bad_input():
    tr, inp = _pendulum_inputs()
    c = cg.run("pendulum", "f32", inp, raw=True)
    m = cg.run("pendulum", "f32-model", inp, raw=True)
    assert _bits_equal(c, m)
    out = cg.run("pendulum", "f32", inp)
    for k in ("z", "zd", "te", "te_std"):
        assert np.all(np.isfinite(out[k])), k
    assert out["rejected"][-1, 0] == 6            # 2 markers, 1 effort, 3 dt
    assert out["bar_lost"][120:150, 0].all() and not out["bar_lost"][:120, 0].any()
    assert out["resets"][-1, 0] == 0 and out["initialised"][1:, 0].all()
    # the estimate keeps following the truth through the occlusion
    assert np.max(np.abs(out["z"][100:250, 2] - tr.z[100:250, 2])) < 0.2


def test_pendulum_float32_tracks_the_reference():
    """Measured property of the generated float32 filter (reference: the estimator's Python
    code in float64), on 100 frames."""
    tr, inp = _pendulum_inputs(100)
    ref = cg.run("pendulum", "ref", inp)
    f32 = cg.run("pendulum", "f32", inp)
    assert np.max(np.abs(f32["z"] - ref["z"])) < 1e-4
    assert np.max(np.abs(f32["te"] - ref["te"])) < 0.1      # N, N*m; efforts of hundreds


def test_pendulum_survives_long_loss_of_all_markers_and_restarts():
    tr, inp = _pendulum_inputs(300, seed=2)
    inp["marker_valid"][50:250] = False          # 2 s without any marker
    inp["markers"][50:250] = 1e9
    out = cg.run("pendulum", "f32", inp)
    for k in ("z", "zd", "te", "te_std"):
        assert np.all(np.isfinite(out[k]))
    assert np.all(np.abs(out["z"]) <= 20.0)
    # what happened is reported: either it kept predicting (finite, flagged) or it reset
    assert out["bar_lost"][50:250, 0].all()
    # after the markers return it is back on the truth
    assert np.max(np.abs(out["z"][280:, 2:] - tr.z[280:, 2:])) < 0.05 or \
        out["resets"][-1, 0] > 0


LEG = T.LegConfig(duration=3.0, seed=3)


@pytest.fixture(scope="module")
def leg_run():
    tr = T.leg_trial(LEG)
    prm = LEG.params()
    return tr, prm, cg.run("leg", "ref", tr.inputs(), prm), cg.run("leg", "f32", tr.inputs(), prm)


def test_leg_c_equals_model_bit_for_bit(leg_run):
    tr, prm, _, _ = leg_run
    inp = tr.inputs()
    inp["acc_valid"][100:130, 1] = False
    inp["gyr"][50, 0] = np.nan
    inp["acc"][51, 2] = -1e4
    inp["dt"][52] = 0.0
    c = cg.run("leg", "f32", inp, prm, raw=True)
    m = cg.run("leg", "f32-model", inp, prm, raw=True)
    assert _bits_equal(c, m)
    out = cg.run("leg", "f32", inp, prm)
    assert out["rejected"][-1, 0] == 3 and np.all(np.isfinite(out["te"]))


def test_leg_targets(leg_run):
    """Issue targets: hip/knee torque RMSE <= 1 N*m, lag <= 20 ms, float32 within 0.01 N*m of
    the reference (after the first second, which the filter needs to converge)."""
    from kinefuse.host.dynamics.bench import leg_metrics
    tr, _, ref, f32 = leg_run
    m = leg_metrics(f32, tr)
    assert m["hip_rmse_nm"] <= 1.0 and m["knee_rmse_nm"] <= 1.0, m
    assert abs(m["hip_lag_ms"]) <= 20.0 and abs(m["knee_lag_ms"]) <= 20.0, m
    assert np.max(np.abs(f32["te"][1:] - ref["te"][1:])) <= 0.01


def test_leg_foot_c_equals_model_and_estimates_the_ankle_force():
    cfg = T.LegConfig(duration=2.0, seed=4, foot_force=True)
    tr = T.leg_trial(cfg)
    prm = dict(cfg.params(), L2=cfg.L2)
    c = cg.run("leg_foot", "f32", tr.inputs(), prm, raw=True)
    m = cg.run("leg_foot", "f32-model", tr.inputs(), prm, raw=True)
    assert _bits_equal(c, m)
    out = cg.run("leg_foot", "f32", tr.inputs(), prm)
    k = 100
    assert np.sqrt(np.mean((out["te"][k:, :2] - tr.te[k:, :2]) ** 2)) < 2.0
    assert np.sqrt(np.mean((out["te"][k:, 2:] - tr.te[k:, 2:]) ** 2)) < 5.0
