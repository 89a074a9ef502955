"""Robustness of the flagship filter (generated float32 C) on simulated motion with analytic
ground truth (kinefuse.hil_tests.sim) and on property-based inputs (hypothesis).

Frames: quaternions sensor -> East-North-Up; angles in degrees unless a name says rad."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from kinefuse.codegen import estimators
from kinefuse.codegen import runner as cg
from kinefuse.hil_tests import sim
from kinefuse.host import runner as host_runner
from kinefuse.host.metrics import error_series, quat_conj, quat_mul

NAME = "flagship"
G = 9.81
FIELD = np.array([0.0, 20.0, -40.0])            # uT, ENU: north and down (dip 63 deg)


def params(**over):
    p = estimators.get(NAME).default_params()
    p.update(over)
    return p


def run(rec_or_inputs, **over):
    inp = rec_or_inputs if isinstance(rec_or_inputs, dict) else host_runner.imu_inputs(rec_or_inputs)
    return cg.run(NAME, "f32", inp, params(**over))


def signed_heading_deg(q_est, q_true):
    """Heading part of the earth-frame error e = q_est (x) q_true^-1, signed, degrees."""
    e = quat_mul(q_est, quat_conj(q_true))
    e = e * np.sign(e[:, :1] + 1e-300)
    return np.degrees(2.0 * np.arctan2(e[:, 3], e[:, 0]))


def rot_inv(q, v):
    """Earth -> sensor for (N,4) quaternions and (N,3) vectors."""
    vq = np.concatenate([np.zeros((len(v), 1)), v], axis=1)
    return quat_mul(quat_mul(quat_conj(q), vq), q)[:, 1:]


def static_inputs(q0, n=2000, rate=100.0, noise=0.0, seed=0):
    """A unit at rest in orientation q0 (ideal or noisy sensors)."""
    rng = np.random.default_rng(seed)
    q = np.tile(np.asarray(q0, float) / np.linalg.norm(q0), (n, 1))
    acc = rot_inv(q, np.tile([0.0, 0.0, G], (n, 1))) + rng.normal(0, 0.02 * noise, (n, 3))
    mag = rot_inv(q, np.tile(FIELD, (n, 1))) + rng.normal(0, 0.5 * noise, (n, 3))
    gyr = rng.normal(0, 0.002 * noise, (n, 3))
    return {"gyr": gyr, "acc": acc, "mag": mag, "mag_valid": np.ones(n, bool),
            "dt": np.full(n, 1.0 / rate)}, q


# -------------------------------------------------------------------------------------------------
# simulated scenarios


@pytest.fixture(scope="module")
def disturbance_run():
    rec = sim.simulate("magnetic_disturbance", seed=3)   # field 2x from 15 s to 25 s
    return rec, run(rec)


def test_magnetic_disturbance_is_detected_and_leaves_heading(disturbance_run):
    rec, out = disturbance_run
    t = rec.t
    during = (t > 15.5) & (t < 25.0)
    assert out["mag_disturbed"][during, 0].mean() > 0.95
    assert out["mag_disturbed"][(t > 8.0) & (t < 14.5), 0].mean() < 0.05
    h = signed_heading_deg(out["q9"], rec.q_true)
    before = np.median(h[(t > 12.0) & (t < 15.0)])
    after = h[t > 27.0]
    assert np.max(np.abs(after - before)) < 2.0         # after recovery
    assert np.max(np.abs(h[during] - before)) < 2.0     # and while the field is rejected


def test_stationary_6d_heading_drift_after_bias_convergence():
    """1 deg/s gyroscope bias on every axis, 120 s at rest, magnetometer ignored (6D)."""
    rec = sim.simulate("bias_1dps", seed=5)
    out = run(rec, mode=0.0)
    t = rec.t
    late = t > 60.0
    assert np.allclose(np.degrees(out["bias"][late]), 1.0, atol=0.03)   # gyro noise 0.05 deg/s
    assert out["rest"][late, 0].all()
    h = signed_heading_deg(out["q6"], rec.q_true)
    slope = np.polyfit(t[late], h[late], 1)[0] * 60.0    # deg/min
    assert abs(slope) < 0.5
    assert np.ptp(h[late]) < 0.5
    e = error_series(out["q6"], rec.q_true)
    assert np.max(e.inclination[late]) < 0.3


def vqf_6d(rec):
    """VQF (C++ reference implementation, default settings) on the same simulated data."""
    vqf = pytest.importorskip("vqf")
    out = vqf.VQF(float(np.median(rec.dt))).updateBatch(
        np.ascontiguousarray(rec.gyr), np.ascontiguousarray(rec.acc),
        np.ascontiguousarray(np.nan_to_num(rec.mag)))
    return np.asarray(out["quat6D"])


COMBINED_FINDING = pytest.mark.xfail(strict=True, reason=(
    "known weakness, found 2026-12-04 when the simulated gyroscope became the interval mean: on "
    "fast rotation with translation the flagship's inclination is 0.65 deg RMS vs VQF's 0.30 "
    "(seeds 1, 2, 3, 11). Its time constant shortens with the rotation rate (incl_rate_ref, for "
    "the scale errors of real gyroscopes, which this simulated one has none of) more than the "
    "translation lengthens it (incl_vel_ref 0.01 m/s instead of 0.2 gives 0.06 deg). The old "
    "instantaneous-rate convention put both filters ~1.4 deg off and hid it"))


@pytest.mark.parametrize("scenario", ["tapping", "vibration", "translation", "attached_magnet",
                                      "fast_rotation",
                                      pytest.param("combined", marks=COMBINED_FINDING)])
def test_inclination_as_good_as_vqf_on_simulated_motion(scenario):
    """Inclination RMS within 10 % (+0.05 deg) of VQF's on the same simulated recording."""
    rec = sim.simulate(scenario, seed=11)
    out = run(rec)
    settled = rec.t > 3.0
    mine = error_series(out["q9"], rec.q_true).inclination[settled]
    theirs = error_series(vqf_6d(rec), rec.q_true).inclination[settled]
    rms = lambda v: float(np.sqrt(np.mean(v ** 2)))                      # noqa: E731
    assert np.all(np.isfinite(out["q"]))
    assert rms(mine) <= 1.1 * rms(theirs) + 0.05


#: gyroscope scale errors of the size seed 002 (Table 4.2) gives as the Xsens DOT's typical
#: sensitivity variation, 0.5 %, with alternating signs
GYR_SCALE_ERROR = [1.005, 0.995, 1.005]


@pytest.mark.parametrize("scenario, factor", [("fast_rotation", 0.8), ("combined", 1.1)])
def test_inclination_with_gyroscope_scale_errors_vs_vqf(scenario, factor):
    """What the rate term of the inclination time constant (incl_rate_ref) is for: with 0.5 %
    gyroscope scale errors, fast rotation alone leaves the flagship's inclination at least 20 %
    better than VQF's, and rotation with translation within 10 % (+0.05 deg) of it.  Without
    the term (incl_rate_ref 30 rad/s, measured 2026-12-04, seed 11) the flagship fails both:
    0.93 vs VQF 0.94 deg, and 1.28 vs 0.98 deg."""
    sc = sim.scenario(scenario)
    sensor = dict(sc.sensor)
    sensor["gyr"] = dict(sensor.get("gyr", {}), scale=GYR_SCALE_ERROR)
    rec = sim.simulate(sc, seed=11, sensor=sensor)
    out = run(rec)
    settled = rec.t > 3.0
    mine = error_series(out["q9"], rec.q_true).inclination[settled]
    theirs = error_series(vqf_6d(rec), rec.q_true).inclination[settled]
    rms = lambda v: float(np.sqrt(np.mean(v ** 2)))                      # noqa: E731
    assert rms(mine) <= factor * rms(theirs) + (0.05 if factor > 1.0 else 0.0)


def test_recovers_after_a_gap_and_jittered_steps():
    """0.5 s gap at 20 s, jitter, drops and duplicates (dt = 0 samples are rejected)."""
    rec = sim.simulate("jitter_and_drops", seed=11)
    out = run(rec)
    e = error_series(out["q9"], rec.q_true)
    assert np.all(np.isfinite(out["q"]))
    assert out["rejected"][-1, 0] == np.sum(~(rec.dt > 0.0))
    assert np.sqrt(np.mean(e.total[rec.t < 19.0] ** 2)) < 1.5
    assert np.sqrt(np.mean(e.total[rec.t > 50.0] ** 2)) < 1.0


@pytest.mark.parametrize("seed", [3, 11])
def test_a_gap_in_fast_rotation_is_bridged_by_the_mean_rate(seed):
    """The rotation of a 0.5 s gap at about 2 rad/s was integrated with the rate after it: 20-58
    deg of error after the gap, for seconds (RMS 12 and 43 deg over 20.4-25 s for these
    seeds).  The mean of the rates before and after it (trapezoid) leaves a few degrees."""
    rec = sim.simulate("jitter_and_drops", seed=seed)
    out = run(rec)
    e = error_series(out["q9"], rec.q_true)
    after = (rec.t > 20.4) & (rec.t < 25.0)
    assert np.sqrt(np.mean(e.total[after] ** 2)) < 5.0
    assert e.total[after].max() < 8.0


def test_attached_magnet_is_rejected():
    rec = sim.simulate("attached_magnet", seed=2)       # magnet rides on the unit 10-60 s
    out = run(rec)
    on = (rec.t > 11.0) & (rec.t < 60.0)
    assert out["mag_disturbed"][on, 0].mean() > 0.7
    e = error_series(out["q9"], rec.q_true)
    assert np.max(e.heading[rec.t > 5.0]) < 3.0


def test_saturated_gyroscope_is_rejected():
    """spin at 720 deg/s on a +-500 deg/s gyroscope: with gyr_range set to the sensor's full
    scale, the saturated samples are counted and the output stays finite."""
    rec = sim.simulate("spin_saturation", seed=1)
    full_scale = math.radians(500.0) * 0.99
    out = run(rec, gyr_range=full_scale)
    saturated = np.any(np.abs(rec.gyr) >= full_scale, axis=1)
    assert saturated.sum() > 100
    assert out["rejected"][-1, 0] == saturated.sum()
    assert np.all(np.isfinite(out["q"]))


def test_slower_magnetometer_and_variable_steps():
    rec = sim.simulate("slow_rotation", seed=4)         # magnetometer at 20 Hz, gyro at 100 Hz
    assert 0.15 < rec.mag_valid.mean() < 0.25
    out = run(rec)
    e = error_series(out["q9"], rec.q_true)
    assert np.sqrt(np.mean(e.total[rec.t > 3.0] ** 2)) < 1.5
    # the same motion sampled with a jittered, per-sample dt
    inp = host_runner.imu_inputs(rec)
    rng = np.random.default_rng(0)
    keep = np.sort(rng.choice(len(rec.t), size=int(0.7 * len(rec.t)), replace=False))
    sub = {k: np.asarray(v)[keep] for k, v in inp.items()}
    sub["dt"] = np.diff(np.concatenate([[rec.t[keep[0]] - 0.01], rec.t[keep]]))
    out2 = run(sub)
    e2 = error_series(out2["q9"], rec.q_true[keep])
    assert np.sqrt(np.mean(e2.total[rec.t[keep] > 3.0] ** 2)) < 2.0


def test_status_outputs_for_plots():
    outs = {v.name: v for v in estimators.get(NAME).outputs}
    assert {"rest", "mag_disturbed", "rejected", "bias"} <= set(outs)
    assert outs["bias"].size == 3 and outs["rest"].type == "bool"
    assert outs["mag_disturbed"].type == "bool" and outs["rejected"].type == "int"
    assert host_runner.default_filter() == NAME


# -------------------------------------------------------------------------------------------------
# property-based


unit_quat = st.lists(st.floats(-1.0, 1.0, allow_nan=False), min_size=4, max_size=4).filter(
    lambda v: np.linalg.norm(v) > 0.1)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(q0=unit_quat, wrong=unit_quat, n_wrong=st.integers(1, 20))
def test_recovers_from_any_initial_orientation(q0, wrong, n_wrong):
    """Whatever the true orientation and whatever the first samples claim (a knock: wrong
    gravity and field directions), the estimate converges to the truth: inclination within
    seconds; heading at the latest when the bounded rejection (mag_reject_time, 60 s) ends."""
    inp, q = static_inputs(q0, n=9000)
    wq = np.tile(np.asarray(wrong) / np.linalg.norm(wrong), (n_wrong, 1))
    inp["acc"][:n_wrong] = rot_inv(wq, np.tile([0.0, 0.0, G], (n_wrong, 1)))
    inp["mag"][:n_wrong] = rot_inv(wq, np.tile(FIELD, (n_wrong, 1)))
    out = run(inp)
    e = error_series(out["q9"], q)
    assert np.all(np.isfinite(out["q"]))
    assert np.max(e.inclination[2000:]) < 0.2
    assert e.total[-1] < 1.0


@pytest.fixture(scope="module")
def clean_motion():
    rec = sim.simulate("slow_rotation", seed=9)
    inp = host_runner.imu_inputs(rec)
    return inp, rec.q_true, run(inp)


BAD = st.sampled_from([np.nan, np.inf, -np.inf, 1e9, -1e9])


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(events=st.lists(st.tuples(st.integers(300, 6500), st.sampled_from(["gyr", "acc", "mag", "dt"]),
                                 st.integers(0, 2), BAD), min_size=1, max_size=15,
                       unique_by=lambda e: e[0]))
def test_non_finite_and_out_of_range_samples_are_rejected(clean_motion, events):
    inp, q_true, clean = clean_motion
    bad = {k: np.array(v, copy=True) for k, v in inp.items()}
    counted = 0
    for i, field, axis, value in events:
        if field == "dt":
            bad["dt"][i] = value
        else:
            bad[field][i, axis] = value
        if field != "mag" or bad["mag_valid"][i]:
            counted += 1
    out = run(bad)
    for k in ("q", "q6", "q9", "bias"):
        assert np.all(np.isfinite(out[k])), k
    assert out["rejected"][-1, 0] == counted
    e = error_series(out["q9"], q_true)
    assert np.sqrt(np.mean(e.total[300:] ** 2)) < 2.0
    assert angle_between(out["q"][-1], clean["q"][-1]) < 1.0


def angle_between(a, b):
    d = abs(float(np.dot(a, b)) / (np.linalg.norm(a) * np.linalg.norm(b)))
    return math.degrees(2.0 * math.acos(min(1.0, d)))


def test_cli_mode_parameter_maps_to_6d_and_9d():
    rec = sim.simulate("slow_rotation", seed=6)
    six = host_runner.run_filter(NAME, "f32", rec, host_runner.parse_params(["mode=6d"]))
    nine = host_runner.run_filter(NAME, "f32", rec, host_runner.parse_params(["mode=9D"]))
    assert np.array_equal(six.q, six.outputs["q6"]) and np.array_equal(nine.q, nine.outputs["q9"])
    assert set(six.status) >= {"rest", "mag_disturbed", "rejected"}
