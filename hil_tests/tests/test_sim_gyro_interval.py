"""The simulated gyroscope reports the mean rate over the interval that ends at each sample
(what the filters integrate, ω_k·dt_k over (t[k−1], t[k]]; ``gyr.sampling`` "mean", the
default), so about a fixed axis a strapdown integration of the samples reproduces the true
orientation exactly; in multi-axis motion the mean rate differs from the interval's rotation
vector by the coning term (as a real integrating gyroscope's does), which "rotation" leaves out.
With the instantaneous rate at t[k] (``"instant"``, the convention before 2026-12-04, kept as
``truth["gyr_inst"]``) the integration ran ω·dt/2 ahead of ``q_true`` (0.45° at 90 °/s and
100 Hz) and, in fast multi-axis motion, drifted by degrees."""
import numpy as np
import pytest
from scipy.interpolate import PPoly

from kinefuse.hil_tests import sim
from kinefuse.hil_tests.sim import quat as Q
from kinefuse.hil_tests.sim.motion import AxisRotation, RigidMotion, Track
from kinefuse.hil_tests.sim.scenario import interval_rates
from kinefuse.hil_tests.sim.segments import SpecError
from kinefuse.hil_tests.sim.signals import PPolySignal
from kinefuse.hil_tests.sim.timing import Timing

IDEAL = {"preset": "ideal"}
EXACT_RAD = 1e-9


def _strapdown_error(q_true, gyr, dt, coning=False):
    """Angle (rad) between q_true[k] and q_true[0] ⊗ Π exp(φ_i/2), i = 1..k, φ_i = ω_i·dt_i: the
    filters' rule (each sample's rate over the step that ends at it), without their
    approximations; ``coning``: φ_i += θ_{i−1} × θ_i / 12 (θ = ω·dt), the flagship's rule."""
    theta = gyr * dt[:, None]
    phi = theta[1:].copy()
    if coning:
        phi += np.cross(theta[:-1], theta[1:]) / 12.0
    q = Q.chain(q_true[0], Q.from_rotvec(phi))
    return Q.angle(Q.mul(Q.conj(q_true[1:]), q))


def _constant_acceleration_track(alpha, axis):
    """Rotation about a fixed axis with angle α·t²/2 (constant angular acceleration α, rad/s²)."""
    # one piece on [−1, 100] s in the local coordinate s = t + 1: α/2·(s − 1)²
    pp = PPoly(np.array([[0.5 * alpha], [-alpha], [0.5 * alpha]]), np.array([-1.0, 100.0]))
    return Track(RigidMotion(AxisRotation(tuple(axis), PPolySignal(pp))))


@pytest.mark.parametrize("sampling", ["mean", "rotation"])
@pytest.mark.parametrize("alpha_dps2,rate_hz,jitter_s", [(90.0, 100.0, 0.0), (300.0, 100.0, 0.002),
                                                          (45.0, 60.0, 0.001)])
def test_constant_angular_acceleration_integrates_exactly(alpha_dps2, rate_hz, jitter_s, sampling):
    axis = np.array([1.0, -2.0, 0.5]) / np.linalg.norm([1.0, -2.0, 0.5])
    track = _constant_acceleration_track(np.radians(alpha_dps2), axis)
    t = Timing(jitter_s=jitter_s).instants(int(4 * rate_hz) + 1, rate_hz, np.random.default_rng(3))
    q = track.evaluate(t).q
    gyr = interval_rates(track, t, rate_hz, sampling)
    dt = np.concatenate([[1.0 / rate_hz], np.diff(t)])
    assert _strapdown_error(q, gyr, dt).max() < EXACT_RAD
    # about a fixed axis the rotation vector over the interval is the mean rate: the rate at
    # the interval's midpoint, ω(t) = α·t
    mid = t - 0.5 * dt
    np.testing.assert_allclose(gyr, np.radians(alpha_dps2) * mid[:, None] * axis, rtol=1e-12, atol=1e-12)
    # sample 0 closes the nominal period before it: from q(t0 − 1/rate) to q(t0)
    q_before = track.evaluate(t[:1] - 1.0 / rate_hz).q
    np.testing.assert_allclose(Q.mul(q_before, Q.from_rotvec(gyr[:1] / rate_hz)), q[:1], rtol=0, atol=1e-14)
    # the instantaneous rate (the old convention) runs ahead by α/2·Σ dt_i² (rad; ω·dt/2 at a
    # regular rate): each step adds α·t_i·dt_i where the rotation is α·(t_i² − t_{i−1}²)/2
    inst = track.evaluate(t).w
    old = _strapdown_error(q, inst, dt)
    lead = np.cumsum(np.radians(alpha_dps2) * dt[1:] ** 2 / 2)
    np.testing.assert_allclose(old, lead, rtol=0, atol=EXACT_RAD)
    assert old.max() > 1e4 * EXACT_RAD


# fixed-axis motion (hinges, gait in the sagittal plane, a constant axis): mean rate = rotation
FIXED_AXIS = [("constant_rotation", None, {}), ("gait", "shank", {}), ("hinge_dynamic_fast", "distal", {}),
              ("hinge_protocol", "distal", {"timing": {"jitter_s": 0.002}}),
              ("gait", "thigh", {"sensor": {"preset": "ideal", "rate_hz": 60}, "timing": {"jitter_s": 0.003}})]


def _ids(cases):
    return [f"{n}-{u or 'imu'}{'-' + '-'.join(c) if c else ''}" for n, u, c in cases]


@pytest.mark.parametrize("name,unit,changes", FIXED_AXIS, ids=_ids(FIXED_AXIS))
def test_strapdown_of_the_samples_reproduces_q_true(name, unit, changes):
    changes = {"sensor": IDEAL, **changes}
    rec = sim.simulate(name, unit=unit, **changes)
    assert rec.meta["sensor_model"]["gyr"]["sampling"] == "mean"
    np.testing.assert_array_equal(rec.t, rec.t_true)        # no stamp errors: dt = true steps
    assert _strapdown_error(rec.q_true, rec.gyr, rec.dt).max() < EXACT_RAD
    np.testing.assert_array_equal(rec.gyr, rec.truth["gyr_true"])
    # the old convention (instantaneous rate at t[k]) was ahead by up to ω·dt/2
    old = _strapdown_error(rec.q_true, rec.truth["gyr_inst"], rec.dt)
    w_max = np.linalg.norm(rec.truth["gyr_inst"], axis=1).max()
    assert old.max() > 0.5 * w_max * rec.dt[1:].min() / 2
    # about a fixed axis the mean rate is the rotation's rate
    sensor = {**changes["sensor"], "gyr": {"sampling": "rotation"}}
    rot = sim.simulate(name, unit=unit, **{**changes, "sensor": sensor})
    np.testing.assert_allclose(rec.gyr, rot.gyr, rtol=0, atol=1e-12)


MULTI_AXIS = [("fast_rotation", None, {}), ("hinge_misaligned", "distal", {}),
              ("combined", None, {"timing": {"jitter_s": 0.002}})]


@pytest.mark.parametrize("name,unit,changes", MULTI_AXIS, ids=_ids(MULTI_AXIS))
def test_multi_axis_mean_rate_and_rotation(name, unit, changes):
    """"rotation": a plain strapdown step reproduces q_true exactly; "mean" (∫ω dt/Δt, what an
    integrating gyroscope measures): the plain step has the coning error, which the two-sample
    coning term removes to second order; the mean equals a fine quadrature of the true rate."""
    mean = sim.simulate(name, unit=unit, sensor=IDEAL, **changes)
    rot = sim.simulate(name, unit=unit, sensor={**IDEAL, "gyr": {"sampling": "rotation"}}, **changes)
    np.testing.assert_array_equal(mean.q_true, rot.q_true)
    assert _strapdown_error(rot.q_true, rot.gyr, rot.dt).max() < EXACT_RAD
    plain = _strapdown_error(mean.q_true, mean.gyr, mean.dt).max()
    coned = _strapdown_error(mean.q_true, mean.gyr, mean.dt, coning=True).max()
    old = _strapdown_error(mean.q_true, mean.truth["gyr_inst"], mean.dt).max()
    assert 1e-5 < plain and coned < plain / 4 and plain < old / 5    # (/4: with jitter, unequal steps)
    # the mean against 64 sub-intervals × 4 Gauss points of the analytic body rate
    sc = sim.scenario(name).replace(**changes) if changes else sim.scenario(name)
    track = sim.build(sc).rig.tracks[unit or "imu"]
    t = mean.t_true
    tp = np.concatenate([[t[0] - 1.0 / mean.rate_hz], t[:-1]])
    x, wt = np.polynomial.legendre.leggauss(4)
    fine = sum(wi / 2 / 64 * track.evaluate(tp + (t - tp) * (j + (xi + 1) / 2) / 64).w
               for j in range(64) for xi, wi in zip(x, wt))
    np.testing.assert_allclose(mean.gyr, fine, rtol=0, atol=1e-8)
    assert np.abs(rot.gyr - fine).max() > 1e-5


def test_constant_rotation_old_lead_was_half_a_sample():
    """constant_rotation: 90 °/s about (1,1,1)/√3 at 100 Hz; on the plateau the instantaneous
    rate put the integration 0.45° ahead (the figure the simulator's README gave)."""
    rec = sim.simulate("constant_rotation", sensor=IDEAL)
    old = np.degrees(_strapdown_error(rec.q_true, rec.truth["gyr_inst"], rec.dt))
    plateau = (rec.t[1:] > 2.3) & (rec.t[1:] < 9.9)
    np.testing.assert_allclose(old[plateau], 90.0 * 0.01 / 2, rtol=0, atol=1e-6)
    assert np.degrees(_strapdown_error(rec.q_true, rec.gyr, rec.dt)).max() < np.degrees(EXACT_RAD)


def test_clock_drift_keeps_the_samples_true_rates():
    """Rates are per true second over the true interval: integrated with the true steps they
    reproduce q_true; the filters' steps come from the drifting stamps (+500 ppm here)."""
    rec = sim.simulate("fast_rotation", sensor={**IDEAL, "gyr": {"sampling": "rotation"}},
                       timing={"clock_drift_ppm": 500.0, "jitter_s": 0.001})
    steps = np.concatenate([[1.0 / rec.rate_hz], np.diff(rec.t_true)])
    assert _strapdown_error(rec.q_true, rec.gyr, steps).max() < EXACT_RAD
    np.testing.assert_allclose(rec.dt[1:] / steps[1:], 1.0 + 500e-6, rtol=1e-9)


def test_a_sample_after_drops_covers_only_its_own_interval():
    """A dropped sample is lost with its rotation: the next sample still reports the mean rate
    over its own period (as a sensor's output register does), not over the whole gap; a
    duplicate repeats the packet."""
    timing = {"jitter_s": 0.001}
    sensor = {**IDEAL, "gyr": {"sampling": "rotation"}}     # (its own interval below: rotation)
    full = sim.simulate("fast_rotation", seed=4, sensor=sensor, timing=timing)
    lossy = sim.simulate("fast_rotation", seed=4, sensor=sensor,
                         timing={**timing, "drop_prob": 0.05, "dup_prob": 0.02, "gaps_s": [[20.0, 20.5]]})
    np.testing.assert_array_equal(lossy.t_true, full.t_true[lossy.index])
    np.testing.assert_array_equal(lossy.gyr, full.gyr[lossy.index])
    step = np.diff(lossy.index)
    after_drop = np.flatnonzero(step > 1) + 1
    assert len(after_drop) > 100
    # its rate is the rotation from the (dropped) nominal sample before it to its own instant
    track = sim.build(sim.scenario("fast_rotation").replace(seed=4)).rig.tracks["imu"]
    k = lossy.index[after_drop]
    rel = Q.mul(Q.conj(track.evaluate(full.t_true[k - 1]).q), track.evaluate(full.t_true[k]).q)
    own = Q.to_rotvec(rel) / (full.t_true[k] - full.t_true[k - 1])[:, None]
    np.testing.assert_allclose(lossy.gyr[after_drop], own, rtol=0, atol=1e-12)
    dups = np.flatnonzero(step == 0) + 1
    assert len(dups) > 10
    np.testing.assert_array_equal(lossy.gyr[dups], lossy.gyr[dups - 1])


def test_rates_are_reproducible_and_noise_is_added_to_the_interval_rate():
    a = sim.simulate("hinge_dynamic_fast", unit="distal", seed=7)
    b = sim.simulate("hinge_dynamic_fast", unit="distal", seed=7)
    for name in ("gyr", "acc", "mag", "q_true", "t"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name))
    ideal = sim.simulate("hinge_dynamic_fast", unit="distal", seed=7, sensor=IDEAL)
    np.testing.assert_array_equal(a.truth["gyr_true"], ideal.gyr)
    # acc stays instantaneous: the specific force at the sampling instant
    np.testing.assert_array_equal(a.truth["acc_true"], ideal.acc)


def test_instant_sampling_is_the_old_convention_and_bad_values_are_refused():
    rec = sim.simulate("gait", unit="shank", sensor={**IDEAL, "gyr": {"sampling": "instant"}})
    np.testing.assert_array_equal(rec.gyr, rec.truth["gyr_inst"])
    track = sim.build(sim.scenario("gait")).rig.tracks["shank"]
    np.testing.assert_array_equal(rec.gyr, track.evaluate(rec.t_true).w)
    with pytest.raises(SpecError, match="sensor.gyr.sampling: expected one of mean, rotation, instant"):
        sim.simulate("gait", unit="shank", sensor={"gyr": {"sampling": "midpoint"}})
    with pytest.raises(SpecError, match="sensor.acc: unknown key"):
        sim.simulate("gait", unit="shank", sensor={"acc": {"sampling": "mean"}})
    with pytest.raises(SpecError, match="in one sample interval.*raise rate_hz"):
        sim.simulate("fast_rotation", sensor={**IDEAL, "rate_hz": 2})
