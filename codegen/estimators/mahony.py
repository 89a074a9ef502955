"""Mahony's explicit complementary filter with proportional and integral (gyro bias) terms.

R. Mahony, T. Hamel, J.-M. Pflimlin, "Nonlinear complementary filters on the special orthogonal
group", IEEE TAC 53(5), 2008 (the 'explicit complementary filter with bias correction').

The magnetometer corrects heading only, as in W. Premerlani, P. Bizard, "Direction Cosine Matrix
IMU: Theory" (2009, eqs. 23-24: the yaw error applied about the earth's vertical expressed in the
body frame; ArduPilot's AP_AHRS_DCM) and PX4's Mahony-type attitude_estimator_q (the
magnetometer's heading error projected on the estimated vertical, the accelerometer's cross
product, and the gyro bias integrated only below 0.175 rad/s of rotation).
"""
from __future__ import annotations

from kinefuse.codegen.estimator import Estimator, Param, Var
from kinefuse.codegen.estimators.common import (ACC_NORM_MIN_SQ, IMU, INITIALISED, INIT_WAIT,
                                                MAG_NORM_MIN_SQ, Q_OUT, Q_STATE, REJECTED,
                                                SampleCheck, initial_quaternion, integrate_gyro,
                                                start_gate)
from kinefuse.codegen.linalg import Quat, Vec3, vselect
from kinefuse.codegen.scalar import (all_of, assume, clamp, fmax, inc_if, logical_and,
                                     logical_not, logical_or, select, sqrt, when)

BIAS_MAX = 0.5   # rad/s: the integral (gyro bias) state is limited to +-28.6 deg/s
BIAS_SPIN_MAX = 0.175   # rad/s (10 deg/s, PX4's value): the bias is integrated only below this rate


class Mahony(Estimator):
    """ω_c = ω − b + k_P e and ḃ = −k_I e, with the error e the cross product of the measured
    and estimated gravity directions (a × v̂) plus, when a magnetometer reading is present, a
    heading correction about the estimated vertical: with h = R(q) m̂ the measured field in the
    estimate's earth frame (East-North-Up, north along +y) and b = (0, |h_xy|, h_z) the reference
    built from it, e_m = ((h × b)·e_z) v̂ = h_x |h_xy| v̂ = |h_xy|² sin ψ v̂ for a heading error
    |ψ| ≤ 90°, held at ±|h_xy|² v̂ beyond (PX4 feeds back the wrapped angle ψ itself), so that
    ψ = 180° is not an equilibrium; exactly there the sign of h_x (+ for 0) picks the way round.

    Why heading only: the full field term m × ŵ = R(q)ᵀ (h × b) has, for a heading error ψ, the
    horizontal (tilt) part |h_xy| h_z (cos ψ − 1, −sin ψ), largest at ψ = 180° where h × b =
    (−2|h_xy| h_z, 0, 0) is a pure tilt, which the gravity term balances at 17.3° of
    inclination (64° dip): at rest upside
    down the filter stayed there (the float64 reference too; nearby starts left it only after
    hundreds of seconds).  With e_m along v̂ the magnetometer never changes inclination.  What is
    left is the accelerometer's own antipode (a × v̂ = 0 when the estimate is exactly upside
    down), as in every Mahony filter: unstable, but at rest on noise-free data the step's
    increments are below one ulp of the quaternion and the estimate does not leave it.

    The accelerometer is only used when | |a| − g | < `acc_gate` (an ungated Mahony diverges
    under fast translation), and the bias is integrated only while |ω| < 0.175 rad/s (PX4):
    without the magnetometer's tilt coupling, accelerations during fast translation that pass
    the gate otherwise wind the integrator up (BROAD fast translation: 57.9° total RMSE without
    this gate, 13.8° with it, 15.6° with the former full field term).
    The bias integrator is a wide fixed-point state (range ±0.5 rad/s, 2^-31 rad/s steps) so
    small integral gains do not underflow.
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
             INITIALISED, INIT_WAIT, REJECTED)
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

        # magnetic field, heading only: h = R(q) m is the measured field in the estimate's earth
        # frame, b = (0, |h_xy|, h_z) the reference built from it; the vertical component of
        # h x b, h_x |h_xy|, is applied about the earth's vertical (v in sensor coordinates)
        with when(chk.use_mag):
            m, m2 = chk.mag.normalized(1e-6)
            h = q.rotate(m)
            hx = assume(h.x, -1.0, 1.0)
            hy = assume(h.y, -1.0, 1.0)
            bh = sqrt(fmax(hx * hx + hy * hy, 0.0))
            # |h_xy|^2 sin(psi) up to |psi| = 90 deg, held at +-|h_xy|^2 beyond (north behind:
            # h_y < 0), so 180 deg is not an equilibrium; the sign of h_x picks the way round
            behind = hy < 0.0
            e_z = bh * select(behind, select(hx < 0.0, -bh, bh), hx)
            e_mag = v * e_z
        use_mag = logical_and(chk.use_mag, m2 >= MAG_NORM_MIN_SQ)

        zero = Vec3(0.0, 0.0, 0.0)
        e = vselect(use_acc, e_acc, zero) + vselect(use_mag, e_mag, zero)
        # integral term only at low rates (the errors are then dominated by the bias)
        slow = chk.gyr.norm_sq() < BIAS_SPIN_MAX * BIAS_SPIN_MAX
        ki_dt = select(slow, p.ki * chk.dt, 0.0)
        b_new = Vec3(*(clamp(bi - ki_dt * ei, -BIAS_MAX, BIAS_MAX) for bi, ei in zip(b, e)))
        omega = chk.gyr - b_new + e * p.kp
        q_new = integrate_gyro(q, omega, chk.dt)

        start, t_wait = start_gate(chk, x.initialised, x.t_wait)
        with when(start):   # only the first valid sample pays for the initial orientation
            q_init, init_ok = initial_quaternion(chk.acc, chk.mag, chk.use_mag)
        do_init = logical_and(start, init_ok)
        run = logical_and(chk.ok, x.initialised)
        q_next = vselect(do_init, q_init, vselect(run, q_new, q))
        b_next = vselect(run, b_new, b)
        rejected = inc_if(x.rejected, chk.bad)
        return ({"q": q_next, "bias": b_next, "initialised": logical_or(x.initialised, do_init),
                 "t_wait": t_wait,
                 "rejected": rejected},
                {"q": q_next, "bias": b_next, "rejected": rejected})
