"""Alignment, joint orientation and joint-angle conventions; seed 002 misalignment study."""
import numpy as np
import pytest

from kinefuse.host.errors import KinefuseError
from kinefuse.host.kinematics import alignment, joint, misalignment, simulate
from kinefuse.host.kinematics import quat as Q

D = np.radians


# ----------------------------------------------------------------------------- two-posture
def _sensor_reading(q_GB, q_SB, v_earth=(0, 0, 9.81)):
    """What a sensor mounted with q_SB on a segment at q_GB reads for an earth vector."""
    q_GS = Q.mul(q_GB, Q.conj(q_SB))
    return Q.rotate(Q.conj(q_GS), v_earth)


def test_two_posture_recovers_mounting_and_knee_is_zero_at_calibration_posture():
    rng = np.random.default_rng(0)
    post = simulate.posture_orientations(0.0, rng)
    qsb = {s: simulate.random_mounting(10.0, rng) for s in ("thigh", "shank")}
    est = {}
    for s in qsb:
        est[s] = alignment.two_posture(_sensor_reading(post[f"standing_{s}"], qsb[s]),
                                       _sensor_reading(post[f"lying_{s}"], qsb[s]))
        assert alignment.mounting_error_deg(est[s], qsb[s]) < 1e-9
    # knee angles at the calibration (standing) posture: zero with the calibrated offsets
    q_GS = {s: Q.mul(post[f"standing_{s}"], Q.conj(qsb[s])) for s in qsb}
    qj = joint.joint_quaternion(q_GS["thigh"], q_GS["shank"], est["thigh"], est["shank"])
    for conv in joint.KNEE_CONVENTIONS:
        np.testing.assert_allclose(joint.knee_angles(qj, convention=conv), 0.0, atol=1e-9)
    # and not zero without them (the mounting offsets differ by several degrees)
    raw = joint.knee_angles(joint.joint_quaternion(q_GS["thigh"], q_GS["shank"]))
    assert np.abs(raw).max() > 2.0


def test_seed001_published_calibration_doubles_the_offset_with_the_standard_conversion():
    """Seed-errata: eqs. 6.1–6.3 zero the knee only with Madgwick's matrix conversion."""
    rng = np.random.default_rng(4)
    stand = simulate.Q_NEUTRAL
    q_SB_t = Q.identity()                               # thigh sensor aligned
    q_SB_s = simulate.random_mounting(8.0, rng)          # shank sensor 8° off
    q_GS_t = Q.mul(stand, Q.conj(q_SB_t))
    q_GS_s = Q.mul(stand, Q.conj(q_SB_s))
    R_t, R_s = Q.to_matrix(q_SB_t), Q.to_matrix(q_SB_s)
    std = joint.seed001_knee_quaternion(q_GS_t, q_GS_s, R_t, R_s, convention="standard")
    mad = joint.seed001_knee_quaternion(q_GS_t, q_GS_s, R_t, R_s, convention="madgwick")
    # standard: (q_SB_shank*)², i.e. a 16° rotation at the posture where the knee is straight
    assert np.degrees(Q.angle_between(std, Q.identity())) == pytest.approx(16.0, abs=1e-9)
    assert Q.angle_between(std, Q.mul(Q.conj(q_SB_s), Q.conj(q_SB_s))) < 1e-9
    assert Q.angle_between(mad, Q.identity()) < 1e-9


def test_two_posture_refuses_nearly_parallel_postures():
    with pytest.raises(KinefuseError, match="postures must differ"):
        alignment.two_posture([0, 0, 9.81], [0.5, 0, 9.8])


# ----------------------------------------------------------------------------- conventions
def test_knee_sign_conventions_right_and_left():
    """Segment frame X = left, Y = proximal, Z = anterior: the shank tilting its long axis
    forward is flexion (+); tilting its long axis to the right (−X) is adduction of the
    right knee (ankle moves medially) and abduction of the left; the shank's anterior axis
    turning left (+X) is internal rotation of the right knee."""
    flex = Q.elementary("X", D(30))
    add_r = Q.elementary("Z", D(5))
    rot_r = Q.elementary("Y", D(7))
    up = np.array([0, 1.0, 0])
    assert Q.rotate(flex, up)[2] > 0                    # long axis tilts anterior
    assert Q.rotate(add_r, up)[0] < 0                   # long axis tilts to the right
    assert Q.rotate(rot_r, [0, 0, 1.0])[0] > 0          # anterior turns left
    for conv in joint.KNEE_CONVENTIONS:
        np.testing.assert_allclose(joint.knee_angles(flex, convention=conv), [30, 0, 0], atol=1e-9)
        np.testing.assert_allclose(joint.knee_angles(add_r, convention=conv), [0, 5, 0], atol=1e-9)
        np.testing.assert_allclose(joint.knee_angles(rot_r, convention=conv), [0, 0, 7], atol=1e-9)
        np.testing.assert_allclose(joint.knee_angles(add_r, convention=conv, side="left"), [0, -5, 0], atol=1e-9)
        np.testing.assert_allclose(joint.knee_angles(rot_r, convention=conv, side="left"), [0, 0, -7], atol=1e-9)


def test_grood_suntay_is_x_then_floating_then_shank_long_axis():
    # flexion 60°, adduction 4°, rotation 10° composed as Rx Rz Ry: G&S returns them exactly,
    # the seed-001 ZYX decomposition of the same rotation does not (cross-talk at 60° flexion)
    q = Q.from_euler(D([60, 4, 10]), "XZY")
    np.testing.assert_allclose(joint.knee_angles(q, convention="grood-suntay"), [60, 4, 10], atol=1e-9)
    zyx = joint.knee_angles(q, convention="seed001-zyx")
    assert np.abs(zyx - [60, 4, 10]).max() > 1.0


def test_elbow_sequences():
    q = Q.from_euler(D([40, 3, -6]), "XYZ")
    np.testing.assert_allclose(joint.elbow_angles(q, sequence="XYZ"), [40, 3, -6], atol=1e-9)
    q = Q.from_euler(D([-6, 3, 40]), "ZYX")       # Z (int. rot.), Y′, X″ (flexion)
    np.testing.assert_allclose(joint.elbow_angles(q, sequence="ZYX"), [40, 3, -6], atol=1e-9)
    with pytest.raises(KinefuseError):
        joint.elbow_angles(q, sequence="ZXZ")
    with pytest.raises(KinefuseError):
        joint.knee_angles(q, convention="cardan")


# ----------------------------------------------------------------------------- seed 002 study
@pytest.mark.parametrize("lam, a, c, r2", [(60, 0.01389, 0.05043, 0.9995), (70, 0.02013, 0.1497, 0.9979)])
def test_seed002_misalignment_study_golden(lam, a, c, r2):
    """Seed 002 Tables 5.11/5.12 (Table 5.11 is λ = 70°, errata): parabolic fit of the
    |flexion error| against an arm-sensor misalignment δ ∈ {−20…20°} about X."""
    r = misalignment.seed002_study(lam)
    assert round(r["a"], 5) == a
    assert float(f"{r['c']:.4g}") == c
    assert round(r["r2"], 4) == r2
    assert abs(r["b"]) < 1e-12                     # symmetric in δ


def test_seed002_misalignment_about_y_and_z():
    d = misalignment.SEED002_DELTAS_DEG
    for lam in (0, 35, 70):
        np.testing.assert_allclose(misalignment.flexion_error(lam, d, axis="Y"), np.abs(d), atol=1e-9)
        np.testing.assert_allclose(misalignment.flexion_error(lam, d, axis="Z"), 0.0, atol=1e-9)
    # the X–Y′–Z″ decomposition of eqs. 2.7–2.9 does not show the parabolic error
    np.testing.assert_allclose(misalignment.flexion_error(60, d, axis="X", sequence="XYZ"), 0.0, atol=1e-9)


# ----------------------------------------------------------------------------- functional, static pose
def test_functional_flexion_axis_from_relative_angular_velocity():
    rng = np.random.default_rng(7)
    t = np.arange(0, 10, 0.01)
    knee = D(40) * (1 - np.cos(2 * np.pi * 0.5 * t))
    thigh_wobble = Q.from_rotvec(np.column_stack([0.2 * np.sin(t), 0.1 * np.sin(1.3 * t), 0.3 * np.sin(0.7 * t)]))
    q_GB_t = thigh_wobble
    q_GB_s = Q.mul(q_GB_t, Q.elementary("X", knee))
    m_t, m_s = simulate.random_mounting(15, rng), simulate.random_mounting(15, rng)
    q_GS_t, q_GS_s = Q.mul(q_GB_t, Q.conj(m_t)), Q.mul(q_GB_s, Q.conj(m_s))
    rt = simulate.imu(t, q_GS_t, rng=rng, gyr_noise=0.01)
    rs = simulate.imu(t, q_GS_s, rng=rng, gyr_noise=0.01)
    ax_t_true = Q.rotate(m_t, [1.0, 0, 0])     # segment X in sensor coordinates (R_SB e_x)
    ax_s_true = Q.rotate(m_s, [1.0, 0, 0])
    r = alignment.functional_flexion_axis(rt.gyr, rs.gyr, q_GS_t, q_GS_s,
                                          sign_ref_prox=ax_t_true, sign_ref_dist=ax_s_true)
    assert np.degrees(np.arccos(r["dist"] @ ax_s_true)) < 1.0
    assert np.degrees(np.arccos(r["prox"] @ ax_t_true)) < 1.0
    # combined with the standing vertical it rebuilds the mounting
    up_s = Q.rotate(Q.conj(Q.mul(simulate.Q_NEUTRAL, Q.conj(m_s))), [0, 0, 9.81])
    q_SB = alignment.functional_standing(r["dist"], up_s)
    assert alignment.mounting_error_deg(q_SB, m_s) < 1.0
    with pytest.raises(KinefuseError, match="faster than"):
        alignment.principal_axis(np.zeros((100, 3)))


def test_static_pose_offset_zeroes_the_joint_at_the_initial_pose():
    """Seed 002 eqs. 2.1–2.4 with GB q0 = identity: joint angles are 0 at t = 0."""
    q0_a = Q.normalize(np.array([0.9, 0.1, -0.3, 0.2]))
    q0_f = Q.normalize(np.array([0.5, -0.4, 0.6, 0.1]))
    qa = alignment.static_pose_offset(q0_a)
    qf = alignment.static_pose_offset(q0_f)
    qj = joint.joint_quaternion(q0_a, q0_f, qa, qf)
    assert Q.angle_between(qj, Q.identity()) < 1e-12
    # a later forearm rotation of 30° about the earth-frame x axis shows up as 30° flexion
    qf1 = Q.mul(Q.elementary("X", D(30)), q0_f)
    qj1 = joint.joint_quaternion(q0_a, qf1, qa, qf)
    np.testing.assert_allclose(joint.elbow_angles(qj1), [30, 0, 0], atol=1e-9)


def test_flexion_convention_matches_the_independent_simulator():
    """kinefuse.hil_tests.sim 'gait' (written independently): its true thigh/shank sensor
    orientations, sensors along its segment axes (x forward, y left, z up), give exactly its
    knee flexion truth through our G&S decomposition — same sign, same zero."""
    sim = pytest.importorskip("kinefuse.hil_tests.sim")
    recs = sim.run("gait", seed=1)
    q_SB = Q.from_matrix(np.column_stack([[0, 1.0, 0], [0, 0, 1.0], [1.0, 0, 0]]))
    qj = joint.joint_quaternion(recs["thigh"].q_true, recs["shank"].q_true, q_SB, q_SB)
    ang = joint.knee_angles(qj)
    np.testing.assert_allclose(ang[:, 0], np.degrees(recs["thigh"].truth["knee_flexion"]), atol=1e-9)
    np.testing.assert_allclose(ang[:, 1:], 0.0, atol=1e-9)
