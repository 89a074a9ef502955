"""Quaternion conventions and Euler decompositions (kinefuse.host.kinematics.quat)."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from kinefuse.host.kinematics import quat as Q

angles = st.floats(-3.0, 3.0, allow_nan=False)


def Rx(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def Ry(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def Rz(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


ROT = {"X": Rx, "Y": Ry, "Z": Rz}


def test_elementary_matches_textbook_matrices():
    for ax, f in ROT.items():
        np.testing.assert_allclose(Q.to_matrix(Q.elementary(ax, 0.7)), f(0.7), atol=1e-15)


def test_product_composes_matrices_and_rotate_maps_body_to_earth():
    p = Q.normalize(np.array([0.3, -0.2, 0.9, 0.1]))
    q = Q.normalize(np.array([-0.5, 0.4, 0.1, 0.7]))
    np.testing.assert_allclose(Q.to_matrix(Q.mul(p, q)), Q.to_matrix(p) @ Q.to_matrix(q), atol=1e-14)
    v = np.array([0.2, -1.0, 3.0])
    # q ⊗ (0,v) ⊗ q* written out with the product
    qv = Q.mul(Q.mul(q, np.r_[0.0, v]), Q.conj(q))
    np.testing.assert_allclose(Q.rotate(q, v), qv[1:], atol=1e-14)


@settings(max_examples=60, deadline=None)
@given(angles, st.floats(-1.5, 1.5), angles, st.sampled_from(["XYZ", "ZYX", "XZY", "YXZ", "ZXY", "YZX"]))
def test_euler_roundtrip_and_matrix_product(a, b, c, seq):
    """to_euler inverts from_euler, which builds R = R_i(a) R_j(b) R_k(c)."""
    q = Q.from_euler([a, b, c], seq)
    R = ROT[seq[0]](a) @ ROT[seq[1]](b) @ ROT[seq[2]](c)
    np.testing.assert_allclose(Q.to_matrix(q), R, atol=1e-12)
    np.testing.assert_allclose(Q.to_euler(q, seq), [a, b, c], atol=1e-7)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(-1, 1), min_size=4, max_size=4))
def test_seed002_eq_2_7_to_2_9_are_intrinsic_xyz(v):
    q = np.array(v)
    if np.linalg.norm(q) < 0.1:
        return
    # ours rebuild the rotation everywhere, gimbal lock included
    np.testing.assert_allclose(Q.to_matrix(Q.from_euler(Q.to_euler(q, "XYZ"), "XYZ")),
                               Q.to_matrix(q), atol=1e-7)
    seed = Q.seed002_eq_2_7_to_2_9(q)
    # the seed's literal formulas equal ours (mod 2π) away from gimbal lock, where they
    # degenerate to atan2(0, 0) for both ψ and ϕ
    if abs(np.sin(seed[1])) < 1 - 1e-6:
        d = seed - Q.to_euler(q, "XYZ")
        np.testing.assert_allclose(np.angle(np.exp(1j * d)), 0.0, atol=1e-6)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(-1, 1), min_size=4, max_size=4))
def test_from_matrix_inverts_to_matrix_and_madgwick_is_conjugate(v):
    q = np.array(v)
    if np.linalg.norm(q) < 0.1:
        return
    q = Q.normalize(q)
    # equal up to the sign (q and −q are the same rotation)
    assert abs(abs(float(Q.from_matrix(Q.to_matrix(q)) @ q)) - 1.0) < 1e-9
    # Madgwick's quatern2rotMat builds the transpose; his rotMat2quatern inverts that
    np.testing.assert_allclose(Q.to_matrix(Q.from_matrix(Q.to_matrix(q), "madgwick")),
                               Q.to_matrix(q).T, atol=1e-9)


@pytest.mark.parametrize("seq", ["XYZ", "ZYX", "XZY", "YXZ", "ZXY", "YZX"])
@pytest.mark.parametrize("b", [np.pi / 2, -np.pi / 2])
def test_gimbal_lock_still_rebuilds_the_rotation(seq, b):
    q = Q.from_euler([0.4, b, -0.3], seq)
    e = Q.to_euler(q, seq)
    assert e[2] == 0.0 and abs(e[1] - b) < 1e-6
    np.testing.assert_allclose(Q.to_matrix(Q.from_euler(e, seq)), Q.to_matrix(q), atol=1e-7)


def test_rotvec_roundtrip_and_small_angles():
    for rv in ([0.0, 0, 0], [1e-10, 0, 0], [0.3, -1.2, 2.0]):
        np.testing.assert_allclose(Q.to_rotvec(Q.from_rotvec(rv)), rv, atol=1e-12)


def test_bad_inputs_raise():
    with pytest.raises(ValueError):
        Q.to_euler([1, 0, 0, 0], "XXY")
    with pytest.raises(ValueError):
        Q.normalize([0, 0, 0, 0])
