"""The Madgwick estimator's step (reference, float64) equals his published update evaluated
literally: objective f, Jacobian J, gradient J^T f normalised, q + (q (x) (0, w) / 2 - beta
grad / |grad|) dt, normalised (eq. 25-33, 42-46 of the 2010 report), MARG and IMU, in his
x-north / z-up frame.  The estimator evaluates the same filter in a reformulated way (gradient as
q (x) g on the unit sphere, one Newton renormalisation); this pins that down."""
from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from kinefuse.codegen import estimators


def _qmul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return np.array([aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw])


def _literal_step(q, gyr, acc, mag, dt, beta, use_acc=True, use_mag=True):
    """Madgwick's update as published (the ahrs package's layout of f and J)."""
    qw, qx, qy, qz = q
    a = acc / np.linalg.norm(acc)
    rows_f, rows_j = [], []
    if use_acc:
        rows_f += [2.0 * (qx * qz - qw * qy) - a[0],
                   2.0 * (qw * qx + qy * qz) - a[1],
                   2.0 * (0.5 - qx ** 2 - qy ** 2) - a[2]]
        rows_j += [[-2.0 * qy, 2.0 * qz, -2.0 * qw, 2.0 * qx],
                   [2.0 * qx, 2.0 * qw, 2.0 * qz, 2.0 * qy],
                   [0.0, -4.0 * qx, -4.0 * qy, 0.0]]
    if use_mag:
        m = mag / np.linalg.norm(mag)
        h = _qmul(q, _qmul(np.r_[0.0, m], q * np.array([1.0, -1.0, -1.0, -1.0])))
        bx, bz = math.hypot(h[1], h[2]), h[3]
        rows_f += [2.0 * bx * (0.5 - qy ** 2 - qz ** 2) + 2.0 * bz * (qx * qz - qw * qy) - m[0],
                   2.0 * bx * (qx * qy - qw * qz) + 2.0 * bz * (qw * qx + qy * qz) - m[1],
                   2.0 * bx * (qw * qy + qx * qz) + 2.0 * bz * (0.5 - qx ** 2 - qy ** 2) - m[2]]
        rows_j += [[-2.0 * bz * qy, 2.0 * bz * qz, -4.0 * bx * qy - 2.0 * bz * qw,
                    -4.0 * bx * qz + 2.0 * bz * qx],
                   [-2.0 * bx * qz + 2.0 * bz * qx, 2.0 * bx * qy + 2.0 * bz * qw,
                    2.0 * bx * qx + 2.0 * bz * qz, -2.0 * bx * qw + 2.0 * bz * qy],
                   [2.0 * bx * qy, 2.0 * bx * qz - 4.0 * bz * qx, 2.0 * bx * qw - 4.0 * bz * qy,
                    2.0 * bx * qx]]
    qdot = 0.5 * _qmul(q, np.r_[0.0, gyr])
    if rows_f:
        grad = np.array(rows_j).T @ np.array(rows_f)
        qdot = qdot - beta * grad / np.linalg.norm(grad)
    q_new = q + qdot * dt
    return q_new / np.linalg.norm(q_new), float(q_new @ q_new - 1.0)


def _tolerance(e):
    """float64 rounding, plus the Newton renormalisation when |q_new|^2 is within 1e-3 of 1:
    (3 - n) / 2 instead of 1 / sqrt(n), n = 1 + e, is off by 3/8 e^2 (relative)."""
    return 1e-12 + (0.4 * e * e if abs(e) <= 1e-3 else 0.0)


def _estimator_step(q, gyr, acc, mag, dt, beta, mag_valid=True):
    est = estimators.get("madgwick")
    x = SimpleNamespace(q=tuple(float(c) for c in q), initialised=True, t_wait=0.0, t_run=0.0,
                        rejected=0)
    u = SimpleNamespace(gyr=tuple(map(float, gyr)), acc=tuple(map(float, acc)),
                        mag=tuple(map(float, mag)), mag_valid=mag_valid, dt=float(dt))
    p = SimpleNamespace(beta=beta, beta_start=beta, start_time=0.0)
    nx, _ = est.step(x, u, p)
    return np.array(nx["q"], dtype=float)


def _samples(n, seed):
    rng = np.random.default_rng(seed)
    for _ in range(n):
        q = rng.normal(size=4)
        q /= np.linalg.norm(q)
        # a rotation rate and a time step as in BROAD (the update turns q by a small angle)
        gyr = rng.normal(scale=2.0, size=3)
        acc = rng.normal(size=3) * 3.0 + np.array([0.0, 0.0, 9.81])
        mag = rng.normal(size=3) * 30.0
        yield q, gyr, acc, mag, 1.0 / 285.714, float(rng.uniform(0.01, 0.5))


@pytest.mark.parametrize("mode", ["marg", "imu"])
def test_step_equals_published_update(mode):
    for q, gyr, acc, mag, dt, beta in _samples(300, 1 if mode == "marg" else 2):
        want, e = _literal_step(q, gyr, acc, mag, dt, beta, use_mag=(mode == "marg"))
        got = _estimator_step(q, gyr, acc, mag, dt, beta, mag_valid=(mode == "marg"))
        assert np.max(np.abs(got - want)) <= _tolerance(e), (got, want, e)


def test_free_fall_uses_the_field_objective_alone():
    """|a| < 1 m/s^2: the gravity objective is left out, the magnetic one stays (as before)."""
    for q, gyr, acc, mag, dt, beta in _samples(50, 3):
        acc = acc / np.linalg.norm(acc) * 0.5
        want, e = _literal_step(q, gyr, acc, mag, dt, beta, use_acc=False)
        got = _estimator_step(q, gyr, acc, mag, dt, beta)
        assert np.max(np.abs(got - want)) <= _tolerance(e), (got, want, e)


def test_large_steps_take_the_exact_normalisation():
    """A step far from unit norm (long time step, fast turn) is normalised exactly."""
    for q, gyr, acc, mag, _dt, beta in _samples(50, 4):
        gyr = np.clip(gyr * 5.0, -30.0, 30.0)      # within the +-2000 deg/s range
        want, e = _literal_step(q, gyr, acc, mag, 0.5, beta)
        assert abs(e) > 1e-3
        got = _estimator_step(q, gyr, acc, mag, 0.5, beta)
        assert np.max(np.abs(got - want)) <= 1e-12
