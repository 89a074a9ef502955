"""The BROAD metric against cases computed by hand (quaternions built from axis and angle).

Rotation about a unit axis u by angle a is (cos a/2, sin a/2 · u).  For e = qz(a) ⊗ qx(b):
e_w = cos(a/2)cos(b/2), e_z = sin(a/2)cos(b/2), so heading = 2·atan(tan(a/2)) = a,
inclination = 2·acos(cos(b/2)) = b and total = 2·acos(cos(a/2)·cos(b/2)).
"""
import math

import numpy as np
import pytest

from kinefuse.host import metrics


def q_axis(axis, deg):
    u = np.asarray(axis, dtype=float)
    u = u / np.linalg.norm(u)
    h = math.radians(deg) / 2
    return np.array([math.cos(h), *(math.sin(h) * u)])


def mul(*qs):
    """Hamilton product written out independently of metrics.quat_mul."""
    out = np.array([1.0, 0.0, 0.0, 0.0])
    for q in qs:
        w1, x1, y1, z1 = out
        w2, x2, y2, z2 = q
        out = np.array([w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
                        w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                        w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
                        w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2])
    return out


Q_REF = q_axis([1.0, 2.0, 3.0], 70.0)  # an arbitrary sensor -> ENU orientation
Z, X, Y = [0, 0, 1], [1, 0, 0], [0, 1, 0]


def errors(q_est, q_ref=Q_REF):
    s = metrics.error_series(np.atleast_2d(q_est), np.atleast_2d(q_ref))
    return s.total[0], s.heading[0], s.inclination[0]


def test_pure_heading_error_in_earth_frame():
    t, h, i = errors(mul(q_axis(Z, 10.0), Q_REF))
    assert t == pytest.approx(10.0, abs=1e-9)
    assert h == pytest.approx(10.0, abs=1e-9)
    assert i == pytest.approx(0.0, abs=1e-6)


def test_pure_tilt_error():
    t, h, i = errors(mul(q_axis([1, 1, 0], 7.0), Q_REF))
    assert t == pytest.approx(7.0, abs=1e-9)
    assert h == pytest.approx(0.0, abs=1e-9)
    assert i == pytest.approx(7.0, abs=1e-9)


def test_mixed_error():
    a, b = 30.0, 40.0
    t, h, i = errors(mul(q_axis(Z, a), q_axis(X, b), Q_REF))
    total = 2 * math.degrees(math.acos(math.cos(math.radians(a / 2)) * math.cos(math.radians(b / 2))))
    assert total == pytest.approx(49.63, abs=0.01)  # cos15°·cos20° = 0.90767 = cos 24.81°
    assert t == pytest.approx(total, abs=1e-9)
    assert h == pytest.approx(a, abs=1e-9)
    assert i == pytest.approx(b, abs=1e-9)


def test_sensor_frame_yaw_is_not_earth_heading():
    # sensor lying on its side (90° about x): a 10° turn about the *sensor* z axis is a turn
    # about earth -y, i.e. a pure inclination error
    ref = q_axis(X, 90.0)
    t, h, i = errors(mul(ref, q_axis(Z, 10.0)), ref)
    assert (t, h) == (pytest.approx(10.0, abs=1e-9), pytest.approx(0.0, abs=1e-6))
    assert i == pytest.approx(10.0, abs=1e-9)


def test_sign_and_scale_do_not_matter():
    q = mul(q_axis(Z, 12.0), q_axis(Y, 5.0), Q_REF)
    base = errors(q)
    assert errors(-q) == pytest.approx(base, abs=1e-9)
    assert errors(3.0 * q, -0.5 * Q_REF) == pytest.approx(base, abs=1e-9)


def test_half_turn():
    t, h, i = errors(mul(q_axis(X, 180.0), Q_REF))
    assert t == pytest.approx(180.0, abs=1e-6)
    assert i == pytest.approx(180.0, abs=1e-6)
    assert h == pytest.approx(0.0, abs=1e-6)


def test_rmse_uses_movement_and_skips_nan_reference():
    heading = [3.0, 4.0, 12.0, 50.0, 5.0]
    movement = np.array([1, 1, 0, 1, 1], dtype=bool)
    q_ref = np.tile(Q_REF, (5, 1))
    q_est = np.array([mul(q_axis(Z, h), Q_REF) for h in heading])
    q_ref[3] = np.nan  # markers lost on sample 3: not scored although moving
    s = metrics.score(q_est, q_ref, movement)
    assert s["heading"] == pytest.approx(math.sqrt((9 + 16 + 25) / 3), abs=1e-9)
    assert s["total"] == pytest.approx(math.sqrt((9 + 16 + 25) / 3), abs=1e-9)
    assert s["inclination"] == pytest.approx(0.0, abs=1e-6)
    series = metrics.error_series(q_est, q_ref)
    assert np.isnan(series.total[3]) and series.total[2] == pytest.approx(12.0)


def test_nan_estimate_is_not_hidden():
    q_ref = np.tile(Q_REF, (3, 1))
    q_est = q_ref.copy()
    q_est[1] = np.nan
    s = metrics.score(q_est, q_ref, np.ones(3, dtype=bool))
    assert all(math.isnan(v) for v in s.values())
    s = metrics.score(q_est, q_ref, np.array([True, False, True]))
    assert s == {"total": 0.0, "heading": 0.0, "inclination": 0.0}


def test_no_scored_samples_gives_nan():
    q = np.tile(Q_REF, (4, 1))
    assert math.isnan(metrics.score(q, q, np.zeros(4, dtype=bool))["total"])


def test_shape_mismatch_is_rejected():
    with pytest.raises(ValueError):
        metrics.error_series(np.zeros((3, 4)), np.zeros((4, 4)))


def test_group_score_is_mean_of_trials():
    scores = {"a": {"total": 1.0, "heading": 2.0, "inclination": 3.0},
              "b": {"total": 3.0, "heading": 4.0, "inclination": 5.0},
              "c": {"total": 10.0, "heading": 10.0, "inclination": 10.0}}
    groups = {"a": "rotation", "b": "rotation", "c": "tapping"}
    g = metrics.group_scores(scores, groups)
    assert g["rotation"] == {"total": 2.0, "heading": 3.0, "inclination": 4.0}
    assert g["tapping"]["total"] == 10.0
    assert metrics.mean_score(scores.values())["total"] == pytest.approx(14.0 / 3)


def test_quat_mul_matches_hand_product():
    a, b = q_axis([1, -2, 0.5], 33.0), q_axis([0.3, 1, 1], 121.0)
    assert metrics.quat_mul(a, b) == pytest.approx(mul(a, b), abs=1e-15)
    assert metrics.quat_mul(a, metrics.quat_conj(a)) == pytest.approx([1, 0, 0, 0], abs=1e-15)
