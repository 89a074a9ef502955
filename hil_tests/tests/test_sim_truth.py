"""Ground truth of the simulator: ω integrates back to q, a and v are the derivatives of p,
rest reads g and the field, hinge and gait truths equal their designs."""
import numpy as np
import pytest

from kinefuse.hil_tests import sim
from kinefuse.hil_tests.sim import quat as Q
from kinefuse.hil_tests.sim.gait import HIP_KEYPOINTS, KNEE_KEYPOINTS
from kinefuse.hil_tests.sim.rig import joint_angle_between

IDEAL = {"preset": "ideal"}

OFFSET_BODY = {
    "name": "offset_body",
    "motion": {"kind": "body", "initial": {"euler_zyx_deg": [10, 20, 30]}, "sensor_offset_m": [0.05, -0.1, 0.2],
               "mount": {"euler_zyx_deg": [5, -7, 9]},
               "segments": [{"type": "rest", "duration": 0.5},
                            {"type": "rotate", "axis": [0, 1, 1], "rate_dps": 300, "angle_deg": 200, "frame": "earth"},
                            {"type": "random_motion", "duration": 4.0, "rms_rate_dps": 400, "band_hz": [0.3, 2.0],
                             "translation_rms_m": 0.3, "translation_band_hz": [0.5, 2.0]},
                            {"type": "orient", "euler_zyx_deg": [-40, 70, 100], "duration": 1.0}]},
}

# (scenario, sensor, window start, window end): windows cover transitions between segments
TRACKS = [("fast_rotation", "imu", 3.0, 13.0), ("combined", "imu", 60.0, 70.0), (OFFSET_BODY, "imu", 0.0, 7.5),
          ("gait", "shank", 0.0, 10.0), ("gait", "thigh", 25.0, 34.0), ("hinge_misaligned", "distal", 0.0, 10.0),
          ("hinge_misaligned", "proximal", 28.0, 34.0), ("constant_rotation", "imu", 0.0, 12.1)]


def _track(scenario, sensor):
    return sim.build(sim.scenario(scenario) if isinstance(scenario, str) else sim.Scenario.from_dict(scenario)) \
        .rig.tracks[sensor]


def _magnus_steps(track, t0, t1, h):
    """Fourth-order Magnus increments of q̇ = ½ q ⊗ (0, ω) from ω at the two Gauss points."""
    t = np.arange(t0, t1, h)
    c = np.sqrt(3.0) / 6.0
    w1 = track.evaluate(t + (0.5 - c) * h).w
    w2 = track.evaluate(t + (0.5 + c) * h).w
    theta = 0.5 * h * (w1 + w2) + (np.sqrt(3.0) / 12.0) * h * h * np.cross(w1, w2)
    return t, Q.from_rotvec(theta)


@pytest.mark.parametrize("scenario,sensor,t0,t1", TRACKS, ids=[f"{s if isinstance(s, str) else s['name']}-{n}"
                                                               for s, n, _, _ in TRACKS])
def test_omega_integrates_back_to_quaternion(scenario, sensor, t0, t1):
    track = _track(scenario, sensor)
    h = 1e-3
    t, dq = _magnus_steps(track, t0, t1, h)
    q = track.evaluate(np.append(t, t[-1] + h)).q
    # local: every step of the analytic ω reproduces the analytic q step (to 1e-11 rad; steps
    # that straddle a profile breakpoint, where the jerk jumps, to 1e-8 rad: O(h³·Δjerk))
    local = Q.angle(Q.mul(Q.conj(Q.mul(q[:-1], dq)), q[1:]))
    assert np.percentile(local, 99) < 1e-11
    assert local.max() < 1e-8
    # global: chaining all steps from q(t0) stays on the trajectory (measured ≤ 1.2e-8 rad)
    chained = Q.chain(q[0], dq)
    worst = float(Q.angle(Q.mul(Q.conj(chained), q[1:])).max())
    assert worst < 5e-8, f"integrated ω drifts {worst:.2e} rad from q over {t1 - t0} s"


@pytest.mark.parametrize("scenario,sensor,t0,t1", TRACKS, ids=[f"{s if isinstance(s, str) else s['name']}-{n}"
                                                               for s, n, _, _ in TRACKS])
def test_velocity_and_acceleration_are_derivatives_of_position(scenario, sensor, t0, t1):
    track = _track(scenario, sensor)
    t = np.linspace(t0, t1, 4001)
    e = 1e-6
    k, kp, km = track.evaluate(t), track.evaluate(t + e), track.evaluate(t - e)
    v_fd = (kp.p - km.p) / (2 * e)
    a_fd = (kp.v - km.v) / (2 * e)
    assert np.abs(v_fd - k.v).max() < 1e-6
    assert np.abs(a_fd - k.a).max() < 1e-4
    w_fd = (kp.w - km.w) / (2 * e)
    assert np.abs(w_fd - k.wd).max() < 1e-3 * max(1.0, np.abs(k.wd).max())


def test_segments_join_smoothly():
    """No jump of q, ω or a across segment boundaries (the concatenation is C²)."""
    sc = sim.Scenario.from_dict(OFFSET_BODY)
    b = sim.build(sc)
    seq_starts = [0.5, 0.5 + 200 / 300 + 0.2, 0.5 + 200 / 300 + 0.2 + 4.0]
    tr = b.rig.tracks["imu"]
    for ts in seq_starts:
        lo, hi = tr.evaluate(np.array([ts - 1e-9])), tr.evaluate(np.array([ts + 1e-9]))
        assert Q.angle(Q.mul(Q.conj(lo.q), hi.q))[0] < 1e-7
        assert np.abs(lo.w - hi.w).max() < 1e-6
        assert np.abs(lo.a - hi.a).max() < 1e-5


@pytest.mark.parametrize("g,field,dip", [(9.81, 49.0, 64.0), (9.80665, 22.6, -35.0)])
def test_rest_reads_gravity_and_field(g, field, dip):
    rec = sim.simulate("rest", sensor=IDEAL, earth={"g": g, "field_uT": field, "dip_deg": dip})
    np.testing.assert_allclose(np.linalg.norm(rec.acc, axis=1), g, rtol=0, atol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(rec.mag, axis=1), field, rtol=0, atol=1e-12)
    # and in the right directions: +g up, field north and dipping by `dip`
    a_e = Q.rotate(rec.q_true, rec.acc)
    m_e = Q.rotate(rec.q_true, rec.mag)
    np.testing.assert_allclose(a_e, np.tile([0, 0, g], (len(rec), 1)), atol=1e-12)
    d = np.radians(dip)
    np.testing.assert_allclose(m_e, np.tile([0, field * np.cos(d), -field * np.sin(d)], (len(rec), 1)), atol=1e-12)
    assert not rec.movement.any()
    np.testing.assert_array_equal(rec.gyr, 0.0)


def test_rotation_reads_constant_rate_and_angle():
    rec = sim.simulate("constant_rotation", sensor=IDEAL)
    axis = np.ones(3) / np.sqrt(3)
    # between the blends (2.2 s .. 2 + 8 s) the gyro reads exactly 90 °/s about (1,1,1)/√3
    mid = (rec.t > 2.21) & (rec.t < 9.99)
    np.testing.assert_allclose(rec.gyr[mid], np.tile(np.radians(90) * axis, (mid.sum(), 1)), atol=1e-12)
    # rotated angle = 9° after the 0.2 s blend (90 °/s × 0.1 s), then 90 °/s: 180° at 4.1 s,
    # 360° at 6.1 s, 720° (back to the start) after the final blend
    q0 = rec.q_true[0]
    for t_k, expect in ((4.1, 180.0), (6.1, 0.0), (3.1, 90.0), (12.0, 0.0)):
        i = np.argmin(np.abs(rec.t - t_k))
        assert abs(rec.t[i] - t_k) < 1e-9
        assert abs(np.degrees(Q.angle(Q.mul(Q.conj(q0), rec.q_true[i]))) - expect) < 1e-6
    assert np.degrees(np.linalg.norm(rec.gyr, axis=1)).max() <= 90.0 + 1e-9


def _profile_expected(t, t_start, a, b, rate, blend, n):
    """Hand formula of n cycles a→b→a at plateau ``rate`` with blends (all degrees, s)."""
    d = abs(b - a)
    half = d / rate + blend
    out = np.full_like(t, np.nan)
    for c in range(2 * n):
        ts = t_start + c * half
        lo, hi = (a, b) if c % 2 == 0 else (b, a)
        sgn = np.sign(hi - lo)
        lin = (t >= ts + blend) & (t <= ts + half - blend)
        out[lin] = lo + sgn * rate * (blend / 2 + (t[lin] - ts - blend))
    return out


def test_hinge_joint_angle_equals_design():
    recs = sim.run("hinge_misaligned", sensor=IDEAL)
    p, d = recs["proximal"], recs["distal"]
    sc = sim.scenario("hinge_misaligned")
    mp = Q.from_euler_zyx_deg(sc.motion["proximal_mount"]["euler_zyx_deg"])
    md = Q.from_euler_zyx_deg(sc.motion["distal_mount"]["euler_zyx_deg"])
    # segment orientations = sensor orientations with the known mounts removed
    qp = Q.mul(p.q_true, Q.conj(mp))
    qd = Q.mul(d.q_true, Q.conj(md))
    measured = np.degrees(joint_angle_between(qp, qd, [1, 0, 0]))
    np.testing.assert_allclose(measured, np.degrees(d.truth["joint_angle"]), atol=1e-9)
    expected = _profile_expected(d.t, 3.0, 0.0, 100.0, 60.0, 0.1, 8)
    ok = ~np.isnan(expected)
    assert ok.sum() > 2000
    np.testing.assert_allclose(measured[ok], expected[ok], atol=1e-9)
    hold = (d.t < 3.0) | (d.t > 3.0 + 16 * (100 / 60 + 0.1))
    np.testing.assert_allclose(measured[hold], 0.0, atol=1e-9)
    # the misalignment is really there: raw sensor quaternions do not give the joint angle
    raw = np.degrees(joint_angle_between(p.q_true, d.q_true, [1, 0, 0]))
    assert np.abs(raw - measured).max() > 2.0


def test_seed001_protocol_design():
    recs = sim.run("hinge_protocol", sensor=IDEAL)
    d = recs["distal"]
    ang = np.degrees(d.truth["joint_angle"])
    # static holds 60 s at each angle, reached at 45 °/s with 0.1 s blends
    t_static = 0.0
    for a, prev in zip([0, 30, 45, 60, 90], [0, 0, 30, 45, 60]):
        if a != prev:
            t_static += abs(a - prev) / 45.0 + 0.1
        hold = (d.t > t_static + 0.01) & (d.t < t_static + 59.99)
        assert hold.sum() >= 5990
        np.testing.assert_allclose(ang[hold], a, atol=1e-9)
        t_static += 60.0
    t_static += 90 / 45.0 + 0.1                                 # back to 0
    assert abs(d.meta["duration_s"] - (t_static + 30 + 10 * 2 * 2.1 + 30 + 10 * 2 * 1.1 + 30)) < 1e-9
    dyn = d.t > t_static
    # 20 peaks at 90° (10 slow + 10 fast cycles), rests at 0°
    peaks = np.flatnonzero((ang[1:-1] > ang[:-2]) & (ang[1:-1] >= ang[2:]) & (ang[1:-1] > 45) & dyn[1:-1])
    assert len(peaks) == 20
    assert np.all(ang[peaks + 1] > 89.99)
    assert ang.max() <= 90.0 + 1e-9 and ang.min() >= -1e-9
    # plateau rates read by the distal gyro (hinge axis = sensor x): 45 and 90 °/s exactly
    rate = np.degrees(d.gyr[:, 0])
    for target in (45.0, 90.0):
        on = dyn & np.isclose(np.abs(rate), target, atol=1e-9)
        assert on.sum() > 500
    assert np.abs(rate).max() <= 90 + 1e-9
    # the proximal board never moves
    np.testing.assert_array_equal(recs["proximal"].gyr, 0.0)


def _cycle_value(keypoints, frac):
    x, y = np.asarray(keypoints, float).T
    return np.interp(frac, x / 100, y)


def test_gait_truth_follows_design():
    sc = sim.scenario("gait")
    recs = sim.run(sc, sensor=IDEAL)
    th, sh = recs["thigh"], recs["shank"]
    T = 120.0 / sc.motion["cadence_spm"]
    before, walk = sc.motion["rest_before_s"], sc.motion["duration_s"]
    steady = (th.t > before + T) & (th.t < before + walk - T)
    frac = ((th.t - before) / T) % 1.0
    hip, knee = np.degrees(th.truth["hip_flexion"]), np.degrees(th.truth["knee_flexion"])
    # curves follow the key points within the Fourier fit error (≤ 0.4°)
    for kp, val in ((HIP_KEYPOINTS, hip), (KNEE_KEYPOINTS, knee)):
        near = steady & np.isin(np.round(frac * 100, 6), [x for x, _ in kp])
        assert near.sum() > 20
        assert np.abs(val[near] - _cycle_value(kp, frac[near])).max() < 0.4
    assert 60 < knee[steady].max() < 64 and -11 < hip[steady].min() < -9
    # sensor orientations (identity mounts): thigh pitch = hip flexion; shank relative to
    # thigh about the segment's −y axis = −knee flexion
    rel = np.degrees(joint_angle_between(th.q_true, sh.q_true, [0, -1, 0]))
    np.testing.assert_allclose(rel, -knee, atol=1e-9)
    q_yaw = Q.from_axis_angle([0, 0, 1], np.radians(sc.motion["heading_deg"]))
    pitch = np.degrees(joint_angle_between(np.tile(q_yaw, (len(th), 1)), th.q_true, [0, -1, 0]))
    np.testing.assert_allclose(pitch, hip, atol=1e-9)
    # walking speed: forward (north, heading 90°) travel = speed × (walk − one stride of ramps)
    speed = sc.motion["stride_m"] / T
    travel = th.pos_true[-1, 1] - th.pos_true[0, 1]
    assert abs(travel - speed * (walk - T)) < 1e-9
    # standing still before and after
    assert not th.movement[th.t < before].any() and not th.movement[th.t > before + walk].any()
    np.testing.assert_allclose(np.linalg.norm(sh.acc[sh.t < before - 0.01], axis=1), 9.81, atol=1e-12)


def test_hinge_distal_sensor_feels_centripetal_acceleration():
    """Independent physics: at a constant joint rate ω about a fixed hinge, a point at radius r
    accelerates by ω²·r towards the hinge and not at all along its path."""
    d = sim.simulate("hinge_dynamic_slow", sensor={"preset": "ideal"}, unit="distal")
    w = np.linalg.norm(d.gyr, axis=1)
    const = np.isclose(w, np.radians(45.0), rtol=0, atol=1e-12)
    assert const.sum() > 1000
    a_lin = Q.rotate(d.q_true, d.acc) - [0.0, 0.0, 9.81]       # earth frame
    r = d.pos_true                                              # hinge at the origin
    np.testing.assert_allclose(np.linalg.norm(r, axis=1), 0.10, atol=1e-12)
    np.testing.assert_allclose(a_lin[const], -(w[const] ** 2)[:, None] * r[const], atol=1e-12)
    # at rest before the cycles: nothing but gravity
    rest = d.t < 29.9
    np.testing.assert_allclose(a_lin[rest], 0.0, atol=1e-12)
