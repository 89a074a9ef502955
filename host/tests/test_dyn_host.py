"""Host side of the dynamic EKF: truth generators against the filters' (independent) AD model,
the FCDI baseline, observability, the benchmark's metrics and command, and the fixed-point
emulator used to decide the leg's number system."""
from __future__ import annotations

import json
from types import SimpleNamespace as NS

import numpy as np
import pytest

from kinefuse.codegen.estimators.dynamics import mbs
from kinefuse.codegen.estimators.dynamics.models import Pendulum
from kinefuse.host.dynamics import bench as B
from kinefuse.host.dynamics import truth as T


def test_pendulum_truth_satisfies_the_filter_model():
    """Closed-form motion + inverse dynamics (truth.py) make the AD residual vanish."""
    cfg = T.PendulumConfig.table_a_1()
    tr = T.pendulum_trial(cfg)
    p = NS(m1=cfg.m1, m2=cfg.m2, L=cfg.L, g=cfg.g)
    for k in (0, 37, 150, 299):
        r = mbs.residual(Pendulum(), list(tr.z[k]), list(tr.zd[k]), list(tr.zdd[k]),
                         list(tr.te[k]), p)
        assert np.max(np.abs(np.array(r, float))) < 1e-6
    # point 2 stays pinned at the origin; point 0 moves vertically
    x0, y0, t1, t2 = tr.z.T
    assert np.allclose(x0 + cfg.L * (np.sin(t1) + np.sin(t2)), 0.0, atol=1e-12)
    assert np.allclose(x0, 0.0, atol=1e-12)
    # noise levels as configured
    clean = T.pendulum_markers(tr.z, cfg.L)
    sd = np.std(tr.markers - clean, axis=0)                      # skin 1 cm + camera 1 mm
    assert np.allclose(sd, np.hypot(0.01, 0.001), rtol=0.1)
    assert np.std(tr.efforts[:, 1:3] - tr.te[:, 1:3]) == pytest.approx(0.05, rel=0.15)
    assert not tr.effort_valid[:, 0].any() and tr.effort_valid[:, 1:].all()


def test_leg_truth_satisfies_the_filter_model():
    cfg = T.LegConfig(duration=1.0, foot_force=True)
    tr = T.leg_trial(cfg)
    p = NS(**cfg.params(), L2=cfg.L2)
    from kinefuse.codegen.estimators.dynamics.leg import _FootLeg
    for k in (0, 33, 71):
        r = mbs.residual(_FootLeg(), list(tr.z[k]), list(tr.zd[k]), list(tr.zdd[k]),
                         list(tr.te[k]), p)
        assert np.max(np.abs(np.array(r, float))) < 1e-9
    assert tr.te[:, 3].max() == pytest.approx(150.0, rel=0.01)


def test_leg_kinematic_start_inverts_the_accelerometer_model():
    """The leg EKF's start (leg.py _kinematic_start) against the truth's independent IMU model
    (truth.leg_imu) on a noise-free 1.8 Hz gait: with a gyroscope history whose three-point
    difference is exact (constant α), it returns the true angles, rates and angular
    accelerations, and inverse dynamics at them the true torques; with the trial's own
    100 Hz history the angles are within 0.06 rad (measured 0.041 here; 0.046 on a noisy
    1.4 Hz trial), where the quasi-static start (ω = α = 0, the old start) is 2.2 rad off."""
    from kinefuse.codegen.estimators.dynamics.leg import LegEKF
    from kinefuse.codegen.estimators.dynamics.models import Leg
    cfg = T.LegConfig(duration=0.6, stride_hz=1.8, sigma_gyr=0.0, sigma_acc=0.0)
    tr = T.leg_trial(cfg)
    p = NS(**cfg.params())
    h = 1.0 / cfg.rate_hz
    worst_diff, worst_static = 0.0, 0.0
    for k in range(2, len(tr.t)):
        w, a, f = list(tr.gyr[k]), tr.zdd[k], list(tr.acc[k])
        hist = [w[0] - a[0] * h, w[1] - a[1] * h, w[0] - 2 * a[0] * h, w[1] - 2 * a[1] * h]
        z0, zd0, zdd0 = LegEKF._kinematic_start(w, hist, f, h, h, p)
        assert np.allclose(z0, tr.z[k], atol=1e-9) and np.allclose(zdd0, a, atol=1e-7)
        assert zd0 == w
        te = mbs.static_efforts(Leg(), z0, zd0, [0.0, 0.0], (0, 1), p, zdd=zdd0)
        assert np.allclose(te, tr.te[k], atol=1e-6)
        hist = [*tr.gyr[k - 1], *tr.gyr[k - 2]]
        z0, _, _ = LegEKF._kinematic_start(w, hist, f, h, h, p)
        worst_diff = max(worst_diff, np.max(np.abs(np.array(z0) - tr.z[k])))
        z0, _, _ = LegEKF._kinematic_start([0.0, 0.0], [0.0] * 4, f, h, h, p)
        worst_static = max(worst_static, np.max(np.abs(np.array(z0) - tr.z[k])))
    assert worst_diff < 0.06 and worst_static > 1.0, (worst_diff, worst_static)


def test_fcdi_recovers_tau1_from_clean_markers():
    cfg = T.PendulumConfig.table_a_1(sigma_marker=0.0, sigma_skin=0.0, sigma_force=0.0,
                                     sigma_torque=0.0)
    tr = T.pendulum_trial(cfg)
    from kinefuse.host.dynamics.fcdi import FcdiConfig, fcdi
    out = fcdi(tr.markers, tr.marker_valid, tr.efforts[:, 1:], tr.dt,
               FcdiConfig(sigma_a=100.0, sigma_marker=1e-4))
    assert np.max(np.abs(out["z"][50:] - tr.z[50:])) < 1e-3
    # finite differences lag half a sample: the torque error is bounded by that lag
    e = out["te"][50:, 0] - tr.te[50:, 0]
    assert np.sqrt(np.mean(e ** 2)) < 0.05 * np.sqrt(np.mean(tr.te[:, 0] ** 2))


def test_observability_findings():
    """Losing both markers of bar 1 makes the kinematic model unobservable but not the dynamic
    one with the reaction sensors (seed 000 calls the system unobservable then)."""
    tr = T.pendulum_trial(T.PendulumConfig.table_3_1())
    ob = B.observability_study(tr, 150)
    assert ob["dynamic_default_sensors"]["observable"]
    assert ob["dynamic_bar1_lost"]["observable"]
    assert not ob["dynamic_bar1_and_plate_lost"]["observable"]
    assert ob["kinematic_all_markers"]["observable"]
    assert ob["kinematic_bar1_lost"]["rank"] == 6


def test_lag_and_rms_metrics():
    t = np.arange(0, 5, 0.01)
    ref = np.sin(2 * np.pi * 0.8 * t) + 0.3 * np.sin(2 * np.pi * 2.1 * t)
    est = np.sin(2 * np.pi * 0.8 * (t - 0.013)) + 0.3 * np.sin(2 * np.pi * 2.1 * (t - 0.013))
    assert B.lag_ms(est, ref, 0.01) == pytest.approx(13.0, abs=1.0)
    assert B.lag_ms(ref, est, 0.01) == pytest.approx(-13.0, abs=1.0)
    assert B.rms(np.array([9.0, 3.0, 4.0])) == pytest.approx(np.sqrt(12.5))


def test_bench_command_errors_are_one_line(capsys):
    from kinefuse.host.cli import main
    assert main(["bench", "dynamics", "--parts", "nonsense"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "unknown part" in err[0]
    assert main(["bench", "dynamics", "--jobs", "0"]) == 2


@pytest.mark.parametrize("argv, text", [
    (["--parts", "robustness", "--no-qemu"], "--no-qemu: option(s) of a part not run (--parts robustness)"),
    (["--parts", "leg", "--variants", "quick", "--no-ref"], "--variants, --no-ref: option(s) of a part not run"),
    (["--parts", "pendulum,robustness", "--no-fixed"], "--no-fixed: option(s) of a part not run"),
])
def test_bench_options_of_parts_not_run_are_refused(capsys, argv, text):
    """--no-qemu, --no-fixed, --variants and --no-ref were accepted and ignored when their part
    was not in --parts; refused before any work."""
    from kinefuse.host.cli import main
    assert main(["bench", "dynamics", "--json", *argv]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and err.startswith("kinefuse: error:") and text in err, err


def test_bench_jobs_without_pendulum_is_said(capsys, monkeypatch):
    """--jobs was silently ignored when the pendulum part (the only parallel one) was not run."""
    from kinefuse.host.cli import main
    seen = {}
    monkeypatch.setattr(B, "robustness", lambda bar, seed: {"ok": 1})
    monkeypatch.setattr(B, "tuning", lambda bar, seed: {"q_used": 1.0})
    monkeypatch.setattr(B, "pendulum_table",
                        lambda which, jobs, *a: seen.setdefault("jobs", jobs) and [])
    assert main(["bench", "dynamics", "--json", "--parts", "robustness", "--jobs", "4"]) == 0
    out, err = capsys.readouterr()
    assert json.loads(out) == {"robustness": {"ok": 1}}
    notes = [ln for ln in err.splitlines() if "--jobs" in ln]
    assert notes == ["kinefuse: note: --jobs applies to the pendulum part only; --parts "
                     "robustness runs in one process"], err
    # no note when --jobs is not given, nor when the pendulum part uses it
    assert main(["bench", "dynamics", "--json", "--parts", "robustness"]) == 0
    assert "--jobs" not in capsys.readouterr().err
    assert main(["bench", "dynamics", "--json", "--parts", "pendulum", "--jobs", "3"]) == 0
    assert "--jobs" not in capsys.readouterr().err and seen["jobs"] == 3
    # a refused option is the one line said: no note before it
    assert main(["bench", "dynamics", "--json", "--parts", "leg", "--jobs", "4", "--no-ref"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("kinefuse: error: --no-ref"), err


def test_bench_json_cleaning():
    from kinefuse.host.bench.dynamics import _clean
    out = _clean({"a": np.float32(1.5), "b": [float("nan"), np.int64(3)], "c": {1: np.inf}})
    assert json.loads(json.dumps(out)) == {"a": 1.5, "b": [None, 3], "c": {"1": None}}


def test_fixed_point_emulator_reproduces_the_generated_float32_c():
    """The emulator behind the fixed-point decision runs the filter's optimised graph with
    per-value rounding; in binary32 mode it must equal the generated C bit for bit."""
    from kinefuse.codegen import runner as cg
    from kinefuse.codegen.estimators.dynamics.leg import LegEKF
    from kinefuse.host.dynamics.fixed_leg import emulate
    cfg = T.LegConfig(duration=0.4)
    tr = T.leg_trial(cfg)
    prm = cfg.params()
    em, _, _ = emulate(LegEKF(), tr.inputs(), prm, "float32")
    c = cg.run("leg", "f32", tr.inputs(), prm)
    for k in ("z", "zd", "te", "te_std"):
        assert np.array_equal(em[k].astype(np.float32), c[k].astype(np.float32)), k


def test_leg_study_runs_end_to_end_on_a_short_trial():
    r = B.leg_study(qemu=False, duration=1.5, fixed=False)
    for k in ("hip_rmse_nm", "knee_rmse_nm", "lag_ms", "f32_vs_ref_max_nm"):
        assert np.isfinite(r[k]), k
    assert r["m4f_instructions_per_step"] is None
    assert r["observability"]["gyroscopes_only"]["rank"] < 6
    assert r["observability"]["all_sensors"]["observable"]
    json.dumps(r)


def test_fixed_point_study_runs_on_a_short_trial():
    from kinefuse.host.dynamics.fixed_leg import study
    r = study(0.3)
    assert r["generator"].startswith("RangeError")
    assert [o["margin"] for o in r["oracle_fixed_point"]] == [2.0, 16.0]
    json.dumps(r)


def test_tune_extends_its_grid_when_the_best_value_is_at_an_edge():
    import math
    grid = (1e3, 1e4, 1e5)

    def bowl(at):
        return lambda v: (math.log10(v) - math.log10(at)) ** 2
    inner = B.tune(bowl(1e4), grid)
    assert inner["best"] == 1e4 and list(inner["scores"]) == list(grid) and not inner["at_edge"]
    up = B.tune(bowl(1e7), grid, hi=1e9)             # extended 1e6, 1e7, 1e8: interior again
    assert up["best"] == 1e7 and max(up["scores"]) == 1e8 and not up["at_edge"]
    down = B.tune(bowl(1e1), grid, lo=1e-8)
    assert down["best"] == 1e1 and min(down["scores"]) == 1.0
    capped = B.tune(bowl(1e12), grid, hi=1e6)        # stops at the setting's upper limit
    assert capped["best"] == 1e6 and capped["at_edge"] and capped["at_limit"]
    far = B.tune(bowl(1e30), grid, max_extend=2)     # gives up after max_extend steps
    assert far["best"] == 1e7 and far["at_edge"] and not far["at_limit"]


def test_annex_a_plant_noise_is_tuned_on_another_seed_than_the_scored_one():
    tu = B.tuning(seed=0)
    assert tu["tuning_seed"] != tu["scored_seed"] == 0
    sweep = {s["q"]: s["rms_fe"] for s in tu["sweep"] if s["q"] not in B.Q_TABLE_A_1}
    assert tu["q_used"] == min(sweep, key=sweep.get) and not tu["at_edge"]
    # the scored seed's sweep is reported beside it, computed on a different trial
    scored = {s["q"]: s["rms_fe"] for s in tu["scored_seed_sweep"]}
    assert set(sweep) <= set(scored) and scored[tu["q_used"]] != sweep[tu["q_used"]]
