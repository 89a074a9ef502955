"""Timing: dropped/duplicated samples in t/dt, jitter, clock drift, multi-rate magnetometer."""
import numpy as np

from kinefuse.hil_tests import sim


def test_regular_timing():
    rec = sim.simulate("slow_rotation", sensor={"preset": "metamotionr"})
    n = int(70 * 100) + 1
    assert len(rec) == n
    np.testing.assert_array_equal(rec.index, np.arange(n))
    np.testing.assert_allclose(rec.t, np.arange(n) / 100.0, rtol=0, atol=1e-12)
    np.testing.assert_allclose(rec.dt, 0.01, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(rec.t, rec.t_true)


def test_drops_and_duplicates_show_in_t_and_dt():
    rec = sim.simulate("jitter_and_drops", seed=1)
    fs = rec.rate_hz
    idx = rec.index
    step = np.diff(idx)
    assert np.all(step >= 0)
    dups = np.flatnonzero(step == 0) + 1
    drops = int(np.sum(np.maximum(step - 1, 0)))
    n_nom = int(70 * fs) + 1
    # 2 % random drops + the 0.5 s gap (50 samples); 1 % duplicates
    assert 50 + 0.01 * n_nom < drops < 50 + 0.03 * n_nom
    assert 0.005 * n_nom < len(dups) < 0.02 * n_nom
    # a duplicate repeats the packet: same stamp (dt = 0), same values
    np.testing.assert_array_equal(rec.dt[dups], 0.0)
    for name in ("gyr", "acc", "mag", "q_true"):
        np.testing.assert_array_equal(getattr(rec, name)[dups], getattr(rec, name)[dups - 1])
    assert not rec.mag_valid[dups].any()
    # dt is the difference of the emitted stamps; after k missing samples it spans k+1 periods
    np.testing.assert_array_equal(rec.dt[1:], np.diff(rec.t))
    assert rec.dt[0] == 1 / fs
    nd = step > 0
    np.testing.assert_allclose(rec.dt[1:][nd], step[nd] / fs, rtol=0, atol=0.004)   # 0.5 ms + 0.2 ms jitter
    # the gap: no sample with nominal time in [20, 20.5) s
    tn = idx / fs
    assert not np.any((tn >= 20.0) & (tn < 20.5))
    gap = np.flatnonzero((tn[:-1] < 20.0) & (tn[1:] >= 20.5))
    assert len(gap) == 1 and rec.dt[gap[0] + 1] > 0.5
    # stamps on a 1 µs grid, jittered around the nominal instants
    np.testing.assert_allclose(rec.t * 1e6, np.round(rec.t * 1e6), rtol=0, atol=1e-6)
    err = rec.t - tn
    assert 0.0003 < np.std(err) < 0.0008 and np.abs(err).max() < 0.4 / fs + 0.0015


def test_sampling_jitter_moves_truth_with_the_stamp():
    """Sampling jitter is real irregular sampling: q_true follows the true instant, and the
    stamp (without stamp jitter) is that instant."""
    rec = sim.simulate("slow_rotation", sensor={"preset": "ideal"}, timing={"jitter_s": 0.001})
    assert np.std(rec.t - rec.index / 100.0) > 0.0005
    np.testing.assert_array_equal(rec.t, rec.t_true)
    ref = sim.build(sim.scenario("slow_rotation")).rig.tracks["imu"].evaluate(rec.t)
    np.testing.assert_array_equal(rec.q_true, ref.q)


def test_clock_drift():
    rec = sim.simulate("rest", sensor={"preset": "ideal"}, timing={"clock_drift_ppm": 1000.0})
    # a clock 1000 ppm fast samples 0.1 % early in true time; its stamps stay nominal
    np.testing.assert_allclose(rec.t, rec.index / 100.0, rtol=0, atol=1e-12)
    np.testing.assert_allclose(rec.t_true, rec.index / 100.0 / 1.001, rtol=0, atol=1e-12)


def test_magnetometer_at_its_own_rate_is_held():
    rec = sim.simulate("slow_rotation", sensor={"preset": "metamotionr", "mag": {"lsb_uT": 0}})
    assert rec.meta["mag_rate_hz"] == 20.0
    v = rec.mag_valid
    np.testing.assert_array_equal(np.flatnonzero(v), np.arange(0, len(rec), 5))
    # held: between valid samples the value does not change
    for k in np.flatnonzero(~v):
        assert np.array_equal(rec.mag[k], rec.mag[k - 1])
    # a valid sample is the field at that instant (σ ≤ 0.56 µT), not a stale one
    err = rec.mag[v] - rec.truth["mag_true"][v]
    assert np.abs(err).max() < 3.0
    ideal = sim.simulate("slow_rotation", sensor={"preset": "ideal", "mag_rate_hz": 20.0})
    np.testing.assert_array_equal(ideal.mag[ideal.mag_valid], ideal.truth["mag_true"][ideal.mag_valid])
    stale = ~ideal.mag_valid & ideal.movement
    assert np.abs(ideal.mag[stale] - ideal.truth["mag_true"][stale]).max() > 0.1


def test_magnetometer_faster_than_output_keeps_latest():
    rec = sim.simulate("slow_rotation", sensor={"preset": "ideal", "rate_hz": 50.0, "mag_rate_hz": 100.0})
    assert rec.mag_valid.all()
    np.testing.assert_allclose(rec.mag, rec.truth["mag_true"], atol=1e-12)


def test_sampling_jitter_keeps_a_same_rate_magnetometer_in_step():
    """A magnetometer at the acc/gyro rate is read with each sample: with sampling jitter it
    had instants of its own, so about a quarter of the samples held the previous reading
    (mag_valid False, one period stale) although every sample carries a new one."""
    rec = sim.simulate("slow_rotation", seed=1, sensor={"preset": "ideal"}, timing={"jitter_s": 0.001})
    assert rec.meta["mag_rate_hz"] == rec.rate_hz
    assert rec.mag_valid.all()
    np.testing.assert_allclose(rec.mag, rec.truth["mag_true"], rtol=0, atol=1e-9)


def test_clock_drift_keeps_the_magnetometer_on_its_samples():
    """A 20 Hz magnetometer on a 100 Hz unit is read at every 5th sample.  With clock drift
    the two instants, equal in exact arithmetic, differed in the last bit: some readings were
    attached one sample late (mag_valid steps of 4 and 6, the held value 10 ms stale)."""
    for fs, fm, ppm in ((100.0, 20.0, 1000.0), (120.0, 40.0, 13.0)):
        rec = sim.simulate("slow_rotation", sensor={"preset": "ideal", "rate_hz": fs, "mag_rate_hz": fm},
                           timing={"clock_drift_ppm": ppm})
        step = int(fs / fm)
        np.testing.assert_array_equal(np.flatnonzero(rec.mag_valid), np.arange(0, len(rec), step))
        v = rec.mag_valid
        np.testing.assert_allclose(rec.mag[v], rec.truth["mag_true"][v], rtol=0, atol=1e-9)
