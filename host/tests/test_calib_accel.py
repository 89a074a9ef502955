"""Accelerometer calibration: seed 002 worked example, Procrustes, full model, refusals."""
import numpy as np
import pytest

from kinefuse.host.calib import accel
from kinefuse.host.calib.affine import apply_affine
from kinefuse.host.errors import KinefuseError
from kinefuse.host.kinematics import quat as Q

G = accel.G_STANDARD

# Seed 002 Annex G §17.2–17.4: inputs, and the published outputs (4 decimals) — typed in from
# the seed (and the errata note), not produced by the code under test.
RAW = np.array([[7.6467, 6.1838, -0.2367], [6.3236, -7.5506, -0.2625], [0.0265, -0.0547, 9.6081],
                [0.0657, -0.0071, -10.0659], [-7.5156, -6.2212, -0.2421], [7.6009, 6.2452, -0.2297]])
TARGETS = np.array([[-G, 0, 0], [0, -G, 0], [0, 0, -G], [0, 0, G], [G, 0, 0], [-G, 0, 0]])
R_PUBLISHED = np.array([[-0.7665, -0.6419, -0.0032], [-0.6310, 0.7702, 0.0004], [-0.0230, 0.0160, -0.9956]])


def test_seed002_worked_example_reproduced_to_published_precision():
    cal = accel.fit_ls(RAW, TARGETS)
    assert np.abs(cal.M - R_PUBLISHED).max() <= 5e-5           # rounding to 4 decimals
    assert round(cal.det, 4) == 0.9910
    np.testing.assert_allclose(cal.apply([7.6443, 6.1871, -0.2229]), [-9.8304, -0.0584, 0.1447], atol=5e-5)
    assert cal.b is None
    # the module's constants are the same numbers
    ex = accel.SEED002_WORKED_EXAMPLE
    np.testing.assert_array_equal(ex["raw_poses"], RAW)
    np.testing.assert_array_equal(ex["published_R"], R_PUBLISHED)


def _rot(axis, deg):
    return Q.to_matrix(Q.from_axis_angle(axis, np.radians(deg)))


def test_seed002_2d_protocol_three_poses():
    """Eq. 3.2 targets (x–y only) and a sensor turned 35° about z: R is the 2-D rotation."""
    A2 = accel.seed002_targets_2d(9.8066)
    c, s = np.cos(np.radians(35)), np.sin(np.radians(35))
    R_true = np.array([[c, -s], [s, c]])
    raw = A2 @ R_true          # raw_i = R_trueᵀ target_i
    cal = accel.fit_ls(raw, A2)
    np.testing.assert_allclose(cal.M, R_true, atol=1e-12)
    assert cal.M.shape == (2, 2)


def test_procrustes_is_a_proper_rotation():
    R_true = _rot([0.3, -1, 0.4], 37)
    raw = TARGETS @ R_true + 0.01 * np.random.default_rng(0).standard_normal(TARGETS.shape)
    cal = accel.fit_procrustes(raw, TARGETS)
    np.testing.assert_allclose(cal.M.T @ cal.M, np.eye(3), atol=1e-12)
    assert cal.det == pytest.approx(1.0, abs=1e-12)
    assert np.degrees(np.arccos((np.trace(cal.M.T @ R_true) - 1) / 2)) < 0.2
    # on the seed example it is orthogonal where LS is not (det 0.991)
    assert accel.fit_procrustes(RAW, TARGETS).det == pytest.approx(1.0, abs=1e-12)


def _sensor(M_true_inv, b_true, targets, noise=0.0, seed=0):
    """raw = M⁻¹ target + b (the inverse of the calibration map) + noise."""
    rng = np.random.default_rng(seed)
    return targets @ M_true_inv.T + b_true + noise * rng.standard_normal(targets.shape)


def test_full_model_with_targets_recovers_bias_scale_misalignment():
    S = np.diag([1.02, 0.97, 1.01]) @ np.array([[1, 0.01, -0.02], [0, 1, 0.015], [0, 0, 1]])
    R = _rot([1, 2, 3], 12)
    M_inv = R @ S
    b = np.array([0.15, -0.08, 0.3])
    targets = np.vstack([accel.seed002_targets_3d(G), G * np.array([[1, 1, 0], [0, -1, 1], [1, 0, -1]]) / np.sqrt(2)])
    raw = _sensor(M_inv, b, targets)
    cal = accel.fit_full_targets(raw, targets)
    np.testing.assert_allclose(cal.M, np.linalg.inv(M_inv), atol=1e-10)
    np.testing.assert_allclose(cal.b, b, atol=1e-10)
    np.testing.assert_allclose(apply_affine(raw, cal.M, cal.b), targets, atol=1e-10)
    assert cal.residual_rms < 1e-10
    # json keys exactly as the CLI contract
    assert set(cal.to_json()) == {"R", "bias", "det", "residual_rms"}


def _sphere_poses(n, seed):
    rng = np.random.default_rng(seed)
    u = rng.standard_normal((n, 3))
    return G * u / np.linalg.norm(u, axis=1, keepdims=True)


def test_full_model_from_norms_only_recovers_upper_triangular_model():
    T = np.array([[1.02, 0.012, -0.02], [0, 0.97, 0.015], [0, 0, 1.01]])   # calibration matrix
    b = np.array([0.2, -0.1, 0.25])
    targets = _sphere_poses(14, 1)
    raw = _sensor(np.linalg.inv(T), b, targets, noise=0.002)
    cal = accel.fit_full_norm(raw)
    assert cal.model == "norm-upper"
    np.testing.assert_allclose(cal.b, b, atol=0.01)
    np.testing.assert_allclose(cal.M, T, atol=0.005)
    assert np.abs(np.linalg.norm(cal.apply(raw), axis=1) - G).max() < 0.02


def test_norm_model_needs_enough_poses_and_uses_diagonal_model_for_six():
    raw6 = _sensor(np.diag([1 / 1.02, 1 / 0.98, 1.0]), [0.1, 0, -0.1], accel.seed002_targets_3d(G))
    cal = accel.fit_full_norm(raw6)
    assert cal.model == "norm-diagonal"
    np.testing.assert_allclose(np.diag(cal.M), [1.02, 0.98, 1.0], atol=1e-6)
    np.testing.assert_allclose(cal.b, [0.1, 0, -0.1], atol=1e-6)
    with pytest.raises(KinefuseError, match="at least 9 distinct poses"):
        accel.fit_full_norm(raw6, model="upper")
    with pytest.raises(KinefuseError, match="at least 6"):
        accel.fit_full_norm(raw6[:5])


def test_degenerate_pose_sets_are_refused_with_a_clear_message():
    # rotations about the sensor z axis only (seed 002 §5.1.2 protocol): gravity stays in a plane
    ang = np.radians(np.arange(0, 360, 60))
    planar = G * np.column_stack([np.cos(ang), np.sin(ang), np.zeros_like(ang)])
    for method in ("ls", "procrustes", "full"):
        with pytest.raises(KinefuseError, match="degenerate pose set"):
            accel.fit(planar, planar, method=method)
    with pytest.raises(KinefuseError, match="degenerate pose set"):
        accel.fit_full_norm(np.vstack([planar, planar * 0.99]))
    # all poses in one hemisphere: bias inseparable from scale
    rng = np.random.default_rng(3)
    d = rng.standard_normal((12, 3))
    d[:, 2] = np.abs(d[:, 2]) + 2.0
    hemi = G * d / np.linalg.norm(d, axis=1, keepdims=True)
    with pytest.raises(KinefuseError, match="hemisphere"):
        accel.fit_full_norm(hemi)
    with pytest.raises(KinefuseError, match="needs the expected gravity"):
        accel.fit(RAW, None, method="ls")


@pytest.mark.parametrize("method", ["ls", "procrustes", "full"])
def test_zero_vectors_are_refused_without_warnings(method):
    """All-zero poses or targets: 0/0 = NaN used to pass the excitation check (ls gave R = 0,
    procrustes the identity, full a LinAlgError).  Now one clear error and no RuntimeWarning."""
    import warnings
    zeros = np.zeros((6, 3))
    targets = accel.seed002_annex_g_targets()
    one_zero = RAW.copy()
    one_zero[2] = 0.0
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for raw, tg, what in ((zeros, zeros, "pose 1"), (zeros, targets, "pose 1"), (RAW, zeros, "target 1"),
                              (one_zero, targets, "pose 3")):
            with pytest.raises(KinefuseError, match=f"degenerate pose set: {what} has a \\(near\\) zero"):
                accel.fit(raw, tg, method=method)
        if method == "full":
            with pytest.raises(KinefuseError, match="pose 1 has a"):
                accel.fit(zeros, None, method="full")


def test_seed002_orthogonality_regression_is_degenerate():
    """Annex F: y = a_z·cos θ with θ stuck at 0 regressed on [a_x, a_y, a_z, 1] returns
    [0, 0, 1, 0] for any sensor — even a badly non-orthogonal one — so it detects nothing."""
    rng = np.random.default_rng(5)
    skew = np.array([[1, 0.2, 0.1], [0, 1, -0.15], [0, 0, 1]])        # 10° class errors
    ang = np.repeat(np.radians(np.arange(0, 360, 60)), 50)
    g_true = G * np.column_stack([np.cos(ang), np.sin(ang), np.zeros_like(ang)])
    acc = g_true @ skew.T + 0.01 * rng.standard_normal(g_true.shape)
    theta_idx = np.zeros(len(acc), int)                 # the seed's index advances on |Δa_z| > 0.3
    for i in range(1, len(acc)):
        theta_idx[i] = theta_idx[i - 1] + (abs(acc[i, 2] - acc[i - 1, 2]) > 0.3)
    y = acc[:, 2] * np.cos(np.radians(60 * theta_idx))
    A = np.column_stack([acc, np.ones(len(acc))])
    theta = np.linalg.pinv(A.T @ A) @ A.T @ y
    np.testing.assert_allclose(theta, [0, 0, 1, 0], atol=1e-9)
    # our check refuses this pose set outright
    with pytest.raises(KinefuseError, match="degenerate pose set"):
        accel.check_excitation(acc, model="norm")
