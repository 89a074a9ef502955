"""Quaternion complementary filter: gyroscope integration blended toward the accelerometer
(inclination) and magnetometer (heading) orientation, in quaternion form."""
from __future__ import annotations

from kinefuse.codegen.estimator import Estimator, Param
from kinefuse.codegen.estimators.common import (ACC_NORM_MIN_SQ, IMU, INITIALISED, INIT_WAIT,
                                                MAG_NORM_MIN_SQ, Q_OUT, Q_STATE, REJECTED,
                                                SampleCheck, heading_correction,
                                                initial_quaternion, integrate_gyro, start_gate,
                                                tilt_correction)
from kinefuse.codegen.linalg import Quat, vselect
from kinefuse.codegen.scalar import all_of, inc_if, logical_and, logical_not, logical_or, select, when


class Complementary(Estimator):
    """Each sample: integrate the gyroscope (q ⊗ exp(ω dt/2), first order, normalised); rotate
    toward the measured gravity direction by the fraction dt/(tau_acc + dt) of the remaining
    tilt error; then rotate about the vertical toward magnetic north by dt/(tau_mag + dt) of the
    heading error.  Blending is done on quaternions (LERP of small corrections), never on Euler
    angles, so it has no wrap-around or gimbal-lock problems; the magnetometer acts on heading
    only.  Time constants are in seconds and work at any (varying) sample rate.  Accelerometer
    readings whose norm is further than `acc_gate` from g can be excluded (off by default: on BROAD,
    gating left the inclination uncorrected for whole seconds of fast motion and the heading
    correction, which relies on the inclination, went astray).
    """

    name = "complementary"
    title = "Quaternion complementary filter"
    inputs = IMU
    params = (
        Param("tau_acc", 5.0, "s", 0.01, 100.0,
              "time constant of the inclination correction (larger trusts the gyroscope longer)"),
        Param("tau_mag", 10.0, "s", 0.01, 1000.0, "time constant of the heading correction"),
        Param("acc_gate", 0.0, "m/s^2", 0.0, 100.0,
              "accelerometer used only when | |a| - 9.81 | is below this (0: always used)"),
    )
    state = (Q_STATE, INITIALISED, INIT_WAIT, REJECTED)
    outputs = (Q_OUT, REJECTED)

    def step(self, x, u, p):
        chk = SampleCheck(u)
        q = Quat(*x.q)
        q_pred = integrate_gyro(q, chk.gyr, chk.dt)

        a, a2 = chk.acc.normalized(1e-6)
        # | |a| - g | < gate  <=>  (g - gate)^2 < |a|^2 < (g + gate)^2 for gate < g
        lo = (9.81 - p.acc_gate) * (9.81 - p.acc_gate)
        hi = (9.81 + p.acc_gate) * (9.81 + p.acc_gate)
        in_band = all_of(a2 > select(p.acc_gate < 9.81, lo, 0.0), a2 < hi)
        use_acc = logical_and(a2 >= ACC_NORM_MIN_SQ, logical_or(p.acc_gate <= 0.0, in_band))
        k_acc = chk.dt / (p.tau_acc + chk.dt)
        q_tilt = vselect(use_acc, tilt_correction(q_pred, a, k_acc), q_pred)

        with when(chk.use_mag):   # the heading correction runs only when a reading arrived
            m, m2 = chk.mag.normalized(1e-6)
            k_mag = chk.dt / (p.tau_mag + chk.dt)
            q_head = heading_correction(q_tilt, m, k_mag)
        use_mag = logical_and(chk.use_mag, m2 >= MAG_NORM_MIN_SQ)
        q_new = vselect(use_mag, q_head, q_tilt)

        start, t_wait = start_gate(chk, x.initialised, x.t_wait)
        with when(start):   # only the first valid sample pays for the initial orientation
            q_init, init_ok = initial_quaternion(chk.acc, chk.mag, chk.use_mag)
        do_init = logical_and(start, init_ok)
        run = logical_and(chk.ok, x.initialised)
        q_next = vselect(do_init, q_init, vselect(run, q_new, q))
        rejected = inc_if(x.rejected, chk.bad)
        return ({"q": q_next, "initialised": logical_or(x.initialised, do_init), "t_wait": t_wait,
                 "rejected": rejected},
                {"q": q_next, "rejected": rejected})
