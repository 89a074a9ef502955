"""The dynamic EKF building blocks: matrix exponentials against scipy, Van Loan, the Taylor
covariance, the scalar Joseph update against the batch update, integrators' order."""
from __future__ import annotations

import math
from types import SimpleNamespace as NS

import numpy as np
import pytest
from scipy.linalg import expm

from kinefuse.codegen.estimators.dynamics import ekf, mbs
from kinefuse.codegen.estimators.dynamics.models import Pendulum
from kinefuse.codegen.linalg import ZERO

PP = NS(m1=50.0, m2=35.0, L=0.8, g=9.81)
Z, ZD, TE = [0.1, 1.2, -0.6, 0.7], [0.2, -0.5, 2.0, -2.5], [120.0, 15.0, 700.0, -40.0]


def arr(m):
    return np.array([[float(v) for v in row] for row in m])


def pendulum_F(full=True):
    D = mbs.Dynamics(Pendulum(), Z, ZD, TE, PP)
    return ekf.build_F(*D.sensitivity(full=full), 4, 4)


@pytest.mark.parametrize("dt,tol", [(0.01, 1e-12), (0.05, 1e-9)])
def test_exact_phi_matches_scipy_expm(dt, tol):
    """Taylor order 6 after 2 squarings: ‖FΔt‖₁ is 0.86 at 100 Hz here, 4.3 at 20 Hz."""
    F = pendulum_F()
    Phi = arr(ekf.phi_matrix(F, dt, "ex"))
    want = expm(arr(F) * dt)
    assert np.max(np.abs(Phi - want)) < tol * max(1.0, np.max(np.abs(want)))
    # first and second order are the truncated series
    Fn = arr(F)
    assert np.allclose(arr(ekf.phi_matrix(F, dt, "pe")), np.eye(12) + Fn * dt, atol=0, rtol=1e-15)
    assert np.allclose(arr(ekf.phi_matrix(F, dt, "se")),
                       np.eye(12) + Fn * dt + Fn @ Fn * dt * dt / 2, rtol=1e-13, atol=1e-15)


@pytest.mark.parametrize("full", [True, False])
def test_van_loan_matches_the_block_matrix_exponential(full):
    """Σ_k from exp([[−F, Σ_x], [0, Fᵀ]]Δt) (seed eqs. 2.43-2.44): Σ_k = Φ · upper-right."""
    dt = 0.01
    F = pendulum_F(full)
    q = [1e5, 2e3, 3e3, 4e4]
    Sx = ekf.noise_matrix(q, 4)
    Phi, S = ekf.van_loan(F, Sx, dt)
    Fn, Sn = arr(F), arr(Sx)
    V = np.block([[-Fn, Sn], [np.zeros((12, 12)), Fn.T]]) * dt
    E = expm(V)
    Phi_want = E[12:, 12:].T
    S_want = Phi_want @ E[:12, 12:]
    assert np.max(np.abs(arr(Phi) - Phi_want)) < 1e-12
    assert np.max(np.abs(arr(S) - S_want)) < 1e-9 * np.max(np.abs(S_want))
    assert np.array_equal(arr(S), arr(S).T)
    # Taylor/Gibbs (seed eq. 2.45) is close to it for a small step, but not equal
    St = arr(ekf.sigma_ct(F, Sx, dt))
    want_ct = Sn * dt + (Fn @ Sn + Sn @ Fn.T) * dt ** 2 / 2 + Fn @ Sn @ Fn.T * dt ** 3 / 3
    assert np.allclose(St, want_ct, rtol=1e-13, atol=1e-12)
    rel = np.max(np.abs(St - S_want)) / np.max(np.abs(S_want))
    assert 0 < rel < 1e-2


def _batch_joseph(x, P, innov, H, r):
    S = H @ P @ H.T + np.diag(r)
    K = P @ H.T @ np.linalg.inv(S)
    IKH = np.eye(len(x)) - K @ H
    return x + K @ innov, IKH @ P @ IKH.T + K @ np.diag(r) @ K.T


def test_scalar_joseph_updates_equal_the_batch_update():
    rng = np.random.default_rng(4)
    N, m = 7, 5
    A = rng.standard_normal((N, N))
    P = A @ A.T + np.eye(N)
    H = rng.standard_normal((m, N))
    H[1, 2:] = 0.0
    x = rng.standard_normal(N)
    innov = rng.standard_normal(m)
    r = rng.uniform(0.1, 2.0, m)
    Hl = [[ZERO if v == 0.0 else float(v) for v in row] for row in H]
    xs, Ps, skipped = ekf.sequential_update(list(x), P.tolist(), list(innov), Hl, list(r),
                                            [True] * m)
    xb, Pb = _batch_joseph(x, P, innov, H, r)
    assert not skipped
    assert np.allclose(np.array(xs, float), xb, rtol=1e-10, atol=1e-12)
    assert np.allclose(arr(Ps), Pb, rtol=1e-9, atol=1e-12)
    # a lost sensor: same as the batch update without its row
    use = [True, False, True, True, True]
    xs2, Ps2, _ = ekf.sequential_update(list(x), P.tolist(), list(innov), Hl, list(r), use)
    keep = np.array(use)
    xb2, Pb2 = _batch_joseph(x, P, innov[keep], H[keep], r[keep])
    assert np.allclose(np.array(xs2, float), xb2, rtol=1e-10, atol=1e-12)
    assert np.allclose(arr(Ps2), Pb2, rtol=1e-9, atol=1e-12)


def test_non_positive_innovation_variance_skips_and_reports():
    P = [[-4.0, 0.0], [0.0, 1.0]]                 # not positive definite: h P hᵀ + r < r/2
    x, Pn, skipped = ekf.sequential_update([1.0, 2.0], P, [0.5], [[1.0, ZERO]], [1.0], [True])
    assert skipped
    assert x == [1.0, 2.0] and arr(Pn).tolist() == [[-4.0, 0.0], [0.0, 1.0]]


def _simulate(variant, dt, t_end=0.5):
    model = Pendulum()
    z, zd = list(Z), list(ZD)
    v = ekf.Variant(integrator=variant, iterations=6)
    for _ in range(int(round(t_end / dt))):
        zdd = mbs.zdd_of(model, z, zd, TE, PP)
        z, zd = ekf.integrate(model, v, z, zd, TE, zdd, PP, dt)
    return np.array(z + zd, float)


def _exact(t_end=0.5):
    from scipy.integrate import solve_ivp
    model = Pendulum()

    def f(t, y):
        return np.concatenate([y[4:], np.array(mbs.zdd_of(model, list(y[:4]), list(y[4:]),
                                                            TE, PP), float)])
    return solve_ivp(f, (0, t_end), np.array(Z + ZD), rtol=1e-12, atol=1e-12,
                     method="DOP853").y[:, -1]


@pytest.mark.parametrize("name,order", [("fe", 1), ("heun", 2), ("tf", 2), ("tn", 2),
                                        ("rk4", 4)])
def test_integrators_have_their_order(name, order):
    ref = _exact()
    e1 = np.max(np.abs(_simulate(name, 0.01) - ref))
    e2 = np.max(np.abs(_simulate(name, 0.005) - ref))
    assert math.log2(e1 / e2) == pytest.approx(order, abs=0.35)


def test_fixed_point_and_newton_solve_the_same_trapezoidal_rule():
    """Both converge to the same implicit step (fixed point: linear rate ~ Δt‖F‖/2 per
    sweep, 6 sweeps here; Newton: quadratic)."""
    a, b = _simulate("tf", 0.01, 0.2), _simulate("tn", 0.01, 0.2)
    assert np.max(np.abs(a - b)) < 1e-7
    assert np.max(np.abs(a - _simulate("heun", 0.01, 0.2))) > 1e-6     # not just Heun


def test_symmetric_storage_round_trip():
    v = list(range(ekf.tri_size(5)))
    P = ekf.unpack_sym(v, 5)
    assert all(P[i][j] == P[j][i] for i in range(5) for j in range(5))
    assert ekf.pack_sym(P) == v


def _h_fd(h_of, x, h=1e-6):
    """Central differences of the measurement function h_of(state vector) -> list."""
    x = np.asarray(x, float)
    cols = []
    for i in range(len(x)):
        e = np.zeros_like(x)
        e[i] = h * max(1.0, abs(x[i]))
        cols.append((np.array(h_of(x + e), float) - np.array(h_of(x - e), float)) / (2 * e[i]))
    return np.array(cols).T


def _measurement_cases():
    from kinefuse.codegen.estimators.dynamics.leg import LegEKF, LegFootEKF
    from kinefuse.codegen.estimators.dynamics.pendulum import PendulumEKF, PendulumResidualEKF
    from kinefuse.host.dynamics import truth as T
    cfg = T.LegConfig()
    lp = NS(**cfg.params(), L2=cfg.L2)
    return [
        ("pendulum", PendulumEKF(), PP, Z, ZD, TE),
        ("pendulum_res", PendulumResidualEKF(), PP, Z, ZD, TE + [5.0, -3.0, 2.0]),
        ("leg", LegEKF(), lp, [0.4, -0.3], [2.0, -4.0], [12.0, -5.0]),
        ("leg", LegEKF(), lp, [-0.6, -1.5], [-1.0, 6.0], [-40.0, 20.0]),
        ("leg_foot", LegFootEKF(), lp, [0.3, -0.2], [1.5, -3.0], [20.0, -8.0, -15.0, 120.0]),
    ]


@pytest.mark.parametrize("case", range(5))
def test_measurement_jacobian_matches_finite_differences(case):
    """H as the filters build it (AD of h at fixed z̈ plus, for the accelerometers,
    ∂h/∂z̈ · [z̈_z, z̈_ż, z̈_T]) against central differences of the full measurement function,
    in which z̈ = M⁻¹(Q_g + BᵀT_e) is recomputed from the perturbed state."""
    name, est, p, z, zd, te = _measurement_cases()[case]
    model = est.model
    n, ne = len(z), len(te)
    needs_zdd = name.startswith("leg")
    if needs_zdd:
        D = mbs.Dynamics(model, z, zd, te, p)
        zdd, sens = D.zdd, D.sensitivity(full=True)
    else:
        zdd, sens = None, None
    hv, H = ekf.measurement_jacobian(est.h_fn, z, zd, te, zdd, sens, p)
    Ha = arr(H)

    def h_of(x):
        zz, zzd, tte = list(x[:n]), list(x[n:2 * n]), list(x[2 * n:])
        a = mbs.zdd_of(model, zz, zzd, tte, p) if needs_zdd else None
        return [float(v) for v in est.h_fn(zz, zzd, tte, a, p)]

    x = np.array(z + zd + te, float)
    assert np.allclose(np.array(hv, float), h_of(x), rtol=0, atol=1e-12)
    Hfd = _h_fd(h_of, x)
    assert Ha.shape == Hfd.shape == (len(hv), 2 * n + ne)
    scale = np.maximum(1.0, np.max(np.abs(Hfd), axis=1, keepdims=True))
    assert np.max(np.abs(Ha - Hfd) / scale) < 1e-6
    if needs_zdd:
        # the accelerometer rows depend on the torques only through z̈ (chain rule): without
        # the sensitivity term their T_e columns would be zero - the check above would fail
        acc_rows = Hfd[2:6, 2 * n:2 * n + 2]
        assert np.max(np.abs(acc_rows)) > 1e-2
        _, H0 = ekf.measurement_jacobian(est.h_fn, z, zd, te, list(zdd), None, p)
        assert np.max(np.abs(arr(H0)[2:6, 2 * n:])) == 0.0
