"""Mahony's explicit complementary filter with proportional and integral (gyro bias) terms.

R. Mahony, T. Hamel, J.-M. Pflimlin, "Nonlinear complementary filters on the special orthogonal
group", IEEE TAC 53(5), 2008 (the 'explicit complementary filter with bias correction').
"""
from __future__ import annotations

from kinefuse.codegen.estimator import Estimator, Param, Var
from kinefuse.codegen.estimators.common import (ACC_NORM_MIN_SQ, IMU, INITIALISED,
                                                MAG_NORM_MIN_SQ, Q_OUT, Q_STATE, REJECTED,
                                                SampleCheck, initial_quaternion, integrate_gyro)
from kinefuse.codegen.linalg import Quat, Vec3, vselect
from kinefuse.codegen.scalar import (all_of, assume, clamp, fmax, inc_if, logical_and,
                                     logical_not, logical_or, select, sqrt, when)

BIAS_MAX = 0.5   # rad/s: the integral (gyro bias) state is limited to +-28.6 deg/s


class Mahony(Estimator):
    """ω_c = ω − b + k_P e and ḃ = −k_I e, with the error e the sum of cross products of measured
    and estimated directions: gravity (a × v̂) and, when a magnetometer reading is present, the
    field (m × ŵ), where the estimated field uses the horizontal/vertical components of the
    measured field in the earth frame (East-North-Up, north along +y).  The accelerometer is only
    used when | |a| − g | < `acc_gate` (an ungated Mahony diverges under fast translation).
    The bias integrator is a wide fixed-point state (range ±0.5 rad/s, 2^-31 rad/s steps) so small
    integral gains do not underflow.
    """

    name = "mahony"
    title = "Mahony explicit complementary filter"
    inputs = IMU
    params = (
        Param("kp", 0.2, "rad/s", 0.0, 20.0,
              "proportional gain k_P (1/k_P = 5 s: the crossover of the complementary filter)"),
        Param("ki", 0.01, "rad/s^2", 0.0, 5.0,
              "integral gain k_I (gyroscope bias; (k_P/2)^2 makes the loop critically damped)"),
        Param("acc_gate", 2.0, "m/s^2", 0.0, 100.0,
              "accelerometer used only when | |a| - 9.81 | is below this (0: always used)"),
    )
    state = (Q_STATE,
             Var("bias", 3, -BIAS_MAX, BIAS_MAX, "rad/s", "gyroscope bias estimate (integral term)",
                 init=0.0),
             INITIALISED, REJECTED)
    outputs = (Q_OUT, Var("bias", 3, -BIAS_MAX, BIAS_MAX, "rad/s", "gyroscope bias estimate"),
               REJECTED)

    def step(self, x, u, p):
        chk = SampleCheck(u)
        q = Quat(*x.q)
        b = Vec3(*x.bias)

        # gravity: measured a/|a| against the estimate v = R(q)^T e_z
        a, a2 = chk.acc.normalized(1e-6)
        v = q.earth_z_in_sensor()
        v = Vec3(*(assume(c, -1.0, 1.0) for c in v))
        lo = (9.81 - p.acc_gate) * (9.81 - p.acc_gate)
        hi = (9.81 + p.acc_gate) * (9.81 + p.acc_gate)
        in_band = all_of(a2 > select(p.acc_gate < 9.81, lo, 0.0), a2 < hi)
        use_acc = logical_and(a2 >= ACC_NORM_MIN_SQ, logical_or(p.acc_gate <= 0.0, in_band))
        e_acc = a.cross(v)

        # magnetic field: reference (0, b_h, b_z) from the measurement in the earth frame
        with when(chk.use_mag):
            m, m2 = chk.mag.normalized(1e-6)
            h = q.rotate(m)
            bh = sqrt(fmax(assume(h.x, -1.0, 1.0) * assume(h.x, -1.0, 1.0)
                           + assume(h.y, -1.0, 1.0) * assume(h.y, -1.0, 1.0), 0.0))
            wv = q.rotate_inv(Vec3(0.0, bh, assume(h.z, -1.0, 1.0)))
            wv = Vec3(*(assume(c, -1.0, 1.0) for c in wv))
            e_mag = m.cross(wv)
        use_mag = logical_and(chk.use_mag, m2 >= MAG_NORM_MIN_SQ)

        zero = Vec3(0.0, 0.0, 0.0)
        e = vselect(use_acc, e_acc, zero) + vselect(use_mag, e_mag, zero)
        b_new = Vec3(*(clamp(bi - p.ki * ei * chk.dt, -BIAS_MAX, BIAS_MAX) for bi, ei in zip(b, e)))
        omega = chk.gyr - b_new + e * p.kp
        q_new = integrate_gyro(q, omega, chk.dt)

        start = logical_and(chk.ok, logical_not(x.initialised))
        with when(start):   # only the first valid sample pays for the initial orientation
            q_init, init_ok = initial_quaternion(chk.acc, chk.mag, chk.use_mag)
        do_init = logical_and(start, init_ok)
        run = logical_and(chk.ok, x.initialised)
        q_next = vselect(do_init, q_init, vselect(run, q_new, q))
        b_next = vselect(run, b_new, b)
        rejected = inc_if(x.rejected, chk.bad)
        return ({"q": q_next, "bias": b_next, "initialised": logical_or(x.initialised, do_init),
                 "rejected": rejected},
                {"q": q_next, "bias": b_next, "rejected": rejected})
