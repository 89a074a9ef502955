"""Multibody dynamics by AD (velocity-transformation formulation) against the seed's
hand-written matrices, independent closed forms, finite differences, and Pinocchio (a
test-only oracle, skipped when `pin` is not installed)."""
from __future__ import annotations

from types import SimpleNamespace as NS

import numpy as np
import pytest

from kinefuse.codegen.estimators.dynamics import mbs
from kinefuse.codegen.estimators.dynamics.models import Leg, Pendulum, pendulum_markers
from kinefuse.host.dynamics import truth as T

PP = NS(m1=50.0, m2=35.0, L=0.8, g=9.81)
LEG_CFG = T.LegConfig()
LP = NS(**LEG_CFG.params())

STATES = [([0.1, 0.2, 0.3, -0.5], [0.3, -0.2, 1.1, -0.7], [10.0, 5.0, 600.0, 3.0]),
          ([-0.4, 1.3, -2.0, 2.5], [0.0, 0.0, -3.0, 4.0], [-80.0, 40.0, 300.0, -20.0])]


def arr(m):
    return np.array([[float(v) for v in row] for row in m])


def vec(v):
    return np.array([float(x) for x in v])


@pytest.mark.parametrize("z,zd,te", STATES)
def test_pendulum_R_B_M_Q_match_seed_equations(z, zd, te):
    """R (seed eq. 3.57), Bᵀ (eq. 3.59), M = RᵀM̄R and Q_g = Rᵀ(Q̄ − M̄Ṙż) (eqs. 3.55, 2.16-17)
    typed from the seed in host/dynamics/truth.py, against the AD of the position functions."""
    model = Pendulum()
    _, R, Rdz = mbs.kinematics(model.phi, z, zd, PP)
    assert np.allclose(arr(R), T.pendulum_R(z, PP.L), atol=1e-8)
    assert np.allclose(vec(Rdz), T.pendulum_Rdot(z, zd, PP.L) @ np.array(zd), atol=1e-8)
    _, B = mbs.jacobian_of(model.conj, z, PP)
    assert np.allclose(arr(B).T, T.pendulum_Bt(z, PP.L), atol=1e-8)
    D = mbs.Dynamics(model, z, zd, te, PP)
    M, Qg = T.pendulum_M_Qg(np.array(z), np.array(zd), PP.m1, PP.m2, PP.L, PP.g)
    assert np.allclose(arr(D.M), M, rtol=1e-8, atol=1e-8)
    assert np.allclose(vec(D.Qg), Qg, rtol=1e-8, atol=1e-7)
    zdd = np.linalg.solve(M, Qg + T.pendulum_Bt(z, PP.L) @ np.array(te))
    assert np.allclose(vec(D.zdd), zdd, rtol=1e-8, atol=1e-7)


def test_residual_adds_the_identity_block():
    _, B = mbs.jacobian_of(Pendulum(residual=True).conj, STATES[0][0], PP)
    assert np.allclose(arr(B).T, T.pendulum_Bt(STATES[0][0], PP.L, residual=True), atol=1e-9)


def _fd_jacobian(fn, x, h=1e-6):
    x = np.asarray(x, float)
    cols = []
    for i in range(len(x)):
        e = np.zeros_like(x)
        e[i] = h
        cols.append((np.asarray(fn(x + e)) - np.asarray(fn(x - e))) / (2 * h))
    return np.array(cols).T


@pytest.mark.parametrize("model,p,z,zd,te", [
    (Pendulum(), PP, *STATES[0]), (Pendulum(), PP, *STATES[1]),
    (Pendulum(residual=True), PP, STATES[0][0], STATES[0][1], STATES[0][2] + [5.0, -3.0, 2.0]),
    (Leg(), LP, [0.4, -0.3], [2.0, -4.0], [12.0, -5.0]),
    (Leg(), LP, [-0.6, -1.5], [-1.0, 6.0], [-40.0, 20.0]),
])
def test_sensitivity_matches_finite_differences(model, p, z, zd, te):
    """[z̈_z, z̈_ż, z̈_T] by AD (seed eqs. 3.42-3.50 through the residual) against central
    differences of the forward dynamics."""
    n = len(z)
    A_z, A_zd, A_T = mbs.Dynamics(model, z, zd, te, p).sensitivity(full=True)
    ad_j = np.hstack([arr(A_z), arr(A_zd), arr(A_T)])

    def f(x):
        return [float(v) for v in mbs.zdd_of(model, list(x[:n]), list(x[n:2 * n]),
                                             list(x[2 * n:]), p)]
    fd = _fd_jacobian(f, np.array(z + zd + te, float))
    scale = np.max(np.abs(fd))
    assert np.max(np.abs(ad_j - fd)) < 1e-6 * max(scale, 1.0)
    # the simplified sensitivity keeps z̈_T only
    Z1, Z2, A_T2 = mbs.Dynamics(model, z, zd, te, p).sensitivity(full=False)
    assert all(v is mbs.ZERO for row in Z1 + Z2 for v in row)
    assert np.array_equal(arr(A_T2), arr(A_T))


def test_leg_matches_closed_form_and_imu_model():
    z, zd, te = [0.4, -0.3], [2.0, -4.0], [12.0, -5.0]
    D = mbs.Dynamics(Leg(), z, zd, te, LP)
    M, Q = T.leg_M_bias(LEG_CFG, z, zd)
    assert np.allclose(arr(D.M), M, rtol=1e-9, atol=1e-9)
    assert np.allclose(vec(D.Qg), Q, rtol=1e-8, atol=1e-8)
    # the filter's sensor model equals the truth generator's IMU model (independent code)
    from kinefuse.codegen.estimators.dynamics.leg import LegEKF
    zdd = vec(D.zdd)
    h = LegEKF().h_fn(z, zd, te, list(zdd), LP)
    gyr, acc = T.leg_imu(LEG_CFG, np.array([z]), np.array([zd]), np.array([zdd]))
    assert np.allclose(vec(h), np.concatenate([gyr[0], acc[0]]), atol=1e-8)


def test_pendulum_markers_match_truth_geometry():
    z = STATES[1][0]
    assert np.allclose(vec(pendulum_markers(z, PP)),
                       T.pendulum_markers(np.array([z]), PP.L)[0], atol=1e-9)


def test_static_efforts_balance_gravity():
    """At rest the quasi-static start is the exact inverse dynamics."""
    z = [0.1, 1.5, -0.3, 0.4]
    te = T.pendulum_inverse_dynamics(np.array([z]), np.zeros((1, 4)), np.zeros((1, 4)),
                                     PP.m1, PP.m2, PP.L, PP.g)[0]
    tau1 = mbs.static_efforts(Pendulum(), z, [0.0] * 4, [0.0, *te[1:]], (0,), PP)[0]
    assert tau1 == pytest.approx(te[0], rel=1e-8)
    zl = [0.3, -0.2]
    M, Q = T.leg_M_bias(LEG_CFG, zl, [0.0, 0.0])
    want = np.linalg.solve(np.array([[1.0, -1.0], [0.0, 1.0]]), -Q)
    got = mbs.static_efforts(Leg(), zl, [0.0, 0.0], [0.0, 0.0], (0, 1), LP)
    assert np.allclose(vec(got), want, rtol=1e-8)


# -- Pinocchio oracle (test-only dependency: pip install pin) --------------------------------

def _pin_leg(cfg):
    pin = pytest.importorskip("pinocchio")
    model = pin.Model()
    model.gravity.linear = np.array([0.0, -cfg.g, 0.0])

    def inertia(m, c, I):
        # rod along -y in the joint frame, CoM at (0, -c, 0), inertia I about z at the CoM
        return pin.Inertia(m, np.array([0.0, -c, 0.0]), np.diag([I, 1e-3, I]))
    j1 = model.addJoint(0, pin.JointModelRZ(), pin.SE3.Identity(), "hip")
    model.appendBodyToJoint(j1, inertia(cfg.m1, cfg.c1, cfg.I1), pin.SE3.Identity())
    j2 = model.addJoint(j1, pin.JointModelRZ(),
                        pin.SE3(np.eye(3), np.array([0.0, -cfg.L1, 0.0])), "knee")
    model.appendBodyToJoint(j2, inertia(cfg.m2, cfg.c2, cfg.I2), pin.SE3.Identity())
    return pin, model, model.createData()


@pytest.mark.parametrize("z,zd,te", [([0.4, -0.3], [2.0, -4.0], [12.0, -5.0]),
                                     ([-1.1, 0.2], [-3.0, 1.0], [-30.0, 8.0])])
def test_leg_against_pinocchio(z, zd, te):
    """Pinocchio's CRBA, RNEA and ABA derivatives (joint coordinates q1 = θ1, q2 = θ2 − θ1,
    i.e. q = T z, torques = T_e) against the AD model in absolute angles."""
    pin, model, data = _pin_leg(LEG_CFG)
    Tm = np.array([[1.0, 0.0], [-1.0, 1.0]])
    q, v = Tm @ np.array(z), Tm @ np.array(zd)
    tau = np.array(te)
    Mq = pin.crba(model, data, q)
    Mq = np.triu(Mq) + np.triu(Mq, 1).T
    b = pin.rnea(model, data, q, v, np.zeros(2))        # Coriolis + gravity
    D = mbs.Dynamics(Leg(), z, zd, te, LP)
    assert np.allclose(arr(D.M), Tm.T @ Mq @ Tm, rtol=1e-10, atol=1e-12)
    assert np.allclose(vec(D.Qg), -(Tm.T @ b), rtol=1e-8, atol=1e-8)
    pin.computeABADerivatives(model, data, q, v, tau)
    Ti = np.linalg.inv(Tm)
    dq, dv = np.array(data.ddq_dq), np.array(data.ddq_dv)
    Minv = np.array(data.Minv)
    Minv = np.triu(Minv) + np.triu(Minv, 1).T
    A_z, A_zd, A_T = D.sensitivity(full=True)
    assert np.allclose(arr(A_z), Ti @ dq @ Tm, rtol=1e-7, atol=1e-7)
    assert np.allclose(arr(A_zd), Ti @ dv @ Tm, rtol=1e-7, atol=1e-9)
    assert np.allclose(arr(A_T), Ti @ Minv, rtol=1e-8, atol=1e-10)
    assert np.allclose(vec(D.zdd), Ti @ pin.aba(model, data, q, v, tau), rtol=1e-8, atol=1e-8)
