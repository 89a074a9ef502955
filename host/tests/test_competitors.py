"""Competitor runners: frame conventions on synthetic motion, BROAD scores from notes/broad.md.

The synthetic trial is built from an analytic orientation (sensor -> ENU): the gyroscope gets
the body rates, the accelerometer the specific force R^T·(0,0,g) (reads +g upward at rest), the
magnetometer R^T·(0, B·cos dip, -B·sin dip) (magnetic north = +y).  A runner that gets a frame
or the quaternion direction wrong is off by 90° or more; the thresholds below are far from that.
"""
import math
from pathlib import Path

import numpy as np
import pytest

from kinefuse.host import broad, competitors, metrics
from kinefuse.host.errors import KinefuseError


def q_axis(axis, deg):
    u = np.asarray(axis, dtype=float)
    u = u / np.linalg.norm(u)
    h = math.radians(deg) / 2
    return np.array([math.cos(h), *(math.sin(h) * u)])


def rot(q):
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


@pytest.fixture(scope="module")
def synthetic():
    fs, seconds = 100.0, 20.0
    n = int(fs * seconds)
    t = np.arange(n) / fs
    w = np.stack([0.6 * np.sin(0.5 * t), 0.8 * np.cos(0.3 * t), 0.7 * np.sin(0.2 * t + 1)], axis=1)
    q = np.empty((n, 4))
    q[0] = metrics.quat_mul(q_axis([0, 0, 1], 120.0), q_axis([1, 0, 0], 25.0))
    for k in range(1, n):  # body-rate integration, exact for the mid-step rate
        wm = 0.5 * (w[k - 1] + w[k])
        ang = np.linalg.norm(wm) / fs
        q[k] = metrics.quat_mul(q[k - 1], np.r_[math.cos(ang / 2), math.sin(ang / 2) * wm / np.linalg.norm(wm)])
    dip = math.radians(64.0)
    field = np.array([0.0, 48.0 * math.cos(dip), -48.0 * math.sin(dip)])  # µT, ENU
    acc = np.array([rot(qk).T @ [0.0, 0.0, 9.81] for qk in q])
    mag = np.array([rot(qk).T @ field for qk in q])
    return broad.Trial("synthetic", fs, t, w, acc, mag, q, np.ones(n, dtype=bool))


def _last_errors(name, trial):
    res = competitors.run_competitor(name, trial)
    assert res.q.shape == (trial.n, 4)
    e = metrics.error_series(res.q, trial.quat_ref)
    last = slice(-500, None)  # the last 5 s, after every filter has converged
    return e.total[last].max(), e.heading[last].max(), e.inclination[last].max()


NORTH_REFERENCED = [n for n in competitors.competitor_names()
                    if competitors.COMPETITORS[n].nine_d and n != "ahrs-ekf"]


@pytest.mark.parametrize("name", NORTH_REFERENCED)
def test_frame_convention_9d(name, synthetic):
    if not competitors.available(name):
        pytest.skip(f"{competitors.get(name).pip} not installed")
    total, heading, incl = _last_errors(name, synthetic)
    assert total < 1.0, (name, total, heading, incl)


def test_frame_convention_ahrs_ekf(synthetic):
    """ahrs' EKF references heading to true north at Munich (WMM declination built in)."""
    if not competitors.available("ahrs-ekf"):
        pytest.skip("ahrs not installed")
    from ahrs.common.constants import MUNICH_HEIGHT, MUNICH_LATITUDE, MUNICH_LONGITUDE
    from ahrs.utils.wmm import WMM

    declination = abs(WMM(latitude=MUNICH_LATITUDE, longitude=MUNICH_LONGITUDE,
                          height=MUNICH_HEIGHT).D)
    total, heading, incl = _last_errors("ahrs-ekf", synthetic)
    assert heading == pytest.approx(declination, abs=0.5)
    assert incl < 1.0


def test_frame_convention_vqf_6d(synthetic):
    if not competitors.available("vqf-6d"):
        pytest.skip("vqf not installed")
    _, _, incl = _last_errors("vqf-6d", synthetic)
    assert incl < 1.0


def test_status_series(synthetic):
    if not competitors.available("vqf"):
        pytest.skip("vqf not installed")
    res = competitors.run_competitor("vqf", synthetic)
    assert set(res.status) == {"rest", "mag_disturbed"}
    assert all(v.dtype == bool and v.shape == (synthetic.n,) for v in res.status.values())
    assert not res.status["rest"][-500:].any()  # it keeps moving


def test_params_are_checked(synthetic):
    if not competitors.available("imufusion"):
        pytest.skip("imufusion not installed")
    with pytest.raises(KinefuseError, match="unknown parameter beta"):
        competitors.run_competitor("imufusion", synthetic, {"beta": 0.1})
    gain0 = competitors.run_competitor("imufusion", synthetic, {"gain": 0.0}).q
    assert not np.allclose(gain0, competitors.run_competitor("imufusion", synthetic).q)


def test_unknown_and_missing(monkeypatch):
    with pytest.raises(KinefuseError, match="unknown competitor"):
        competitors.get("nope")
    monkeypatch.setitem(competitors.COMPETITORS, "ghost", competitors.Competitor(
        "ghost", "kinefuse_no_such_module", "ghost-pkg", "test", None, {}))
    assert not competitors.available("ghost")
    with pytest.raises(KinefuseError, match="pip install ghost-pkg"):
        competitors.require("ghost")


def test_samples_per_s(synthetic):
    if not competitors.available("vqf"):
        pytest.skip("vqf not installed")
    rate = competitors.samples_per_s("vqf", synthetic, repeat=1)
    assert rate > 1000.0  # VQF's C++ batch update; a loose floor, real figures via bench speed
    assert competitors.samples_per_s("vqf", synthetic, max_samples=300, repeat=1) > 0


# Published/notes figures on the 12 BROAD trials (notes/broad.md), two decimals.
NOTES_12 = {
    "vqf": (3.08, 2.92, 0.83),
    "vqf-basic": (3.77, 3.55, 1.02),
    "vqf-offline": (2.59, 2.52, 0.57),
    "imufusion": (12.79, 11.40, 4.13),
    "imufusion-best": (6.57, 5.42, 3.17),
}
SHARED = broad.shared_broad_dir()


@pytest.mark.broad_full
@pytest.mark.skipif(SHARED is None or not Path(SHARED).is_dir(), reason="full BROAD not present")
@pytest.mark.parametrize("name", list(NOTES_12))
def test_reproduces_notes_on_12_trials(name, broad_trials):
    if not competitors.available(name):
        pytest.skip(f"{competitors.get(name).pip} not installed")
    scores = [metrics.score_trial(competitors.run_competitor(name, t, status=False).q, t)
              for t in broad_trials]
    mean = metrics.mean_score(scores)
    got = (mean["total"], mean["heading"], mean["inclination"])
    assert got == pytest.approx(NOTES_12[name], abs=0.005)  # equal after rounding to 0.01


@pytest.fixture(scope="module")
def broad_trials():
    files = broad.find_trials(SHARED)
    if len(files) != 12:
        pytest.skip(f"expected the 12 BROAD trials, found {len(files)}")
    return [broad.load_trial(f) for f in files]
