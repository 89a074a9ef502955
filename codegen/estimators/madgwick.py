"""Madgwick's gradient-descent orientation filter, IMU (6D) and MARG (9D) in one step.

S. Madgwick, "An efficient orientation filter for inertial and inertial/magnetic sensor arrays",
2010; and Madgwick, Harrison, Vaidyanathan, ICORR 2011.
"""
from __future__ import annotations

import dataclasses

from kinefuse.codegen.estimator import Estimator, Param, Var
from kinefuse.codegen.linalg import Quat, vselect
from kinefuse.codegen.scalar import (assume, clamp, fmax, inc_if, logical_and, logical_not,
                                     logical_or, select, sqrt, when)
from kinefuse.codegen.estimators.common import (ACC_NORM_MIN_SQ, IMU, INITIALISED,
                                                MAG_NORM_MIN_SQ, Q_OUT, Q_STATE, REJECTED,
                                                SampleCheck, initial_quaternion)

T_RUN_MAX = 60.0   # s; the run-time clock only needs to reach the end of the start-up phase


class Madgwick(Estimator):
    """Gyroscope integration corrected by one normalised gradient-descent step per sample on
    the misalignment of the measured gravity (and magnetic field) direction.

    Madgwick's equations are used as published, in his earth frame (x magnetic north, z up; the
    magnetic reference b = (b_x, 0, b_z) without the factor-2 error of many MARG copies); the state
    is kept in that frame and the output is turned into East-North-Up.  The field's direction in the earth frame is re-estimated
    every sample from the current orientation, so the magnetometer acts on heading and on
    inclination only through the gradient step.  Samples without a magnetometer reading use the
    gravity objective alone.  The orientation starts from the first valid sample (gravity and,
    if present, magnetic north); `beta_start` applies for the first `start_time` seconds.
    """

    name = "madgwick"
    title = "Madgwick gradient-descent orientation filter"
    inputs = IMU
    params = (
        Param("beta", 0.041, "rad/s", 0.0, 5.0,
              "gradient-descent gain (Madgwick's beta = sqrt(3/4) * gyroscope error; "
              "0.041 is his MARG value)"),
        Param("beta_start", 0.041, "rad/s", 0.0, 20.0, "gain during the start-up phase"),
        Param("start_time", 0.0, "s", 0.0, T_RUN_MAX, "duration of the start-up phase"),
    )
    state = (dataclasses.replace(Q_STATE, doc="orientation quaternion (w, x, y, z), sensor to "
                                  "earth, earth frame x north / z up (Madgwick's)"),
             INITIALISED,
             Var("t_run", 1, 0.0, T_RUN_MAX, "s", "time since initialisation (saturates)",
                 init=0.0),
             REJECTED)
    outputs = (Q_OUT, REJECTED)
    presets = {
        # seed 001 (ChakaMo): beta = 2 for the first 2 s, then 0.03
        "seed001": {"beta": 0.03, "beta_start": 2.0, "start_time": 2.0},
    }

    def step(self, x, u, p):
        chk = SampleCheck(u)
        # Madgwick's own frame (x magnetic north, z up) inside; ENU at the interface.  His
        # formulas replace w^2+x^2-y^2-z^2 by 1-2(y^2+z^2) etc.; those substitutions are not
        # rotation-equivariant, so deriving them in ENU would give a (slightly) different filter.
        q = Quat(*x.q)
        w, qx, qy, qz = q

        # gravity objective f_g = R(q)^T e_z - a/|a| and its gradient J_g^T f_g  (eq. 25-26)
        a, a2 = chk.acc.normalized(1e-6)
        f1 = 2.0 * (qx * qz - w * qy) - a.x
        f2 = 2.0 * (w * qx + qy * qz) - a.y
        f3 = 2.0 * (0.5 - qx * qx - qy * qy) - a.z
        grad_g = Quat(qx * f2 - qy * f1,
                      qz * f1 + w * f2 - 2.0 * qx * f3,
                      qz * f2 - w * f1 - 2.0 * qy * f3,
                      qx * f1 + qy * f2)

        # magnetic objective f_b = R(q)^T (b_x, 0, b_z) - m/|m|, reference from the measurement
        # rotated into the earth frame (eq. 27-28, 45-46); computed only when a reading arrived
        with when(chk.use_mag):
            m, m2 = chk.mag.normalized(1e-6)
            h = q.rotate(m)
            bx = sqrt(fmax(h.x * h.x + h.y * h.y, 0.0))
            bz = h.z
            fb1 = 2.0 * bx * (0.5 - qy * qy - qz * qz) + 2.0 * bz * (qx * qz - w * qy) - m.x
            fb2 = 2.0 * bx * (qx * qy - w * qz) + 2.0 * bz * (w * qx + qy * qz) - m.y
            fb3 = 2.0 * bx * (w * qy + qx * qz) + 2.0 * bz * (0.5 - qx * qx - qy * qy) - m.z
            grad_b = Quat(bx * qy * fb3 - bz * qy * fb1 + (bz * qx - bx * qz) * fb2,
                          bz * qz * fb1 + (bx * qy + bz * w) * fb2
                          + (bx * qz - 2.0 * bz * qx) * fb3,
                          (bx * qx + bz * qz) * fb2 - (2.0 * bx * qy + bz * w) * fb1
                          + (bx * w - 2.0 * bz * qy) * fb3,
                          (bz * qx - 2.0 * bx * qz) * fb1 + (bz * qy - bx * w) * fb2
                          + bx * qx * fb3)

        use_acc = a2 >= ACC_NORM_MIN_SQ
        use_mag = logical_and(chk.use_mag, m2 >= MAG_NORM_MIN_SQ)
        zero = Quat(0.0, 0.0, 0.0, 0.0)
        grad = vselect(use_acc, grad_g, zero) + vselect(use_mag, grad_b, zero)
        step = grad.normalized(1e-12)

        # rate of change: gyroscope kinematics minus the gain times the normalised gradient
        beta = select(x.t_run < p.start_time, p.beta_start, p.beta)
        qdot = (q * Quat(0.0, *chk.gyr)).scale(0.5) - step.scale(beta)
        q_new = (q + qdot.scale(chk.dt)).normalized()

        # first valid sample: orientation from gravity and magnetic north (ENU -> Madgwick frame)
        start = logical_and(chk.ok, logical_not(x.initialised))
        with when(start):
            q_init, init_ok = initial_quaternion(chk.acc, chk.mag, chk.use_mag)
        do_init = logical_and(start, init_ok)
        run = logical_and(chk.ok, x.initialised)
        q_next = vselect(do_init, enu_to_nwu(q_init), vselect(run, q_new, q))
        t_next = select(run, clamp(x.t_run + chk.dt, 0.0, T_RUN_MAX), x.t_run)
        rejected = inc_if(x.rejected, chk.bad)
        nx = {"q": q_next, "initialised": logical_or(x.initialised, do_init),
              "t_run": t_next, "rejected": rejected}
        return nx, {"q": nwu_to_enu(q_next), "rejected": rejected}


_C45 = 0.7071067811865476   # cos(45 deg) = sin(45 deg)


def nwu_to_enu(q: Quat) -> Quat:
    """(cos 45°, 0, 0, sin 45°) ⊗ q: the earth frame turned from x-north to x-east."""
    w, x, y, z = q
    return Quat(assume(_C45 * (w - z), -1.0, 1.0), assume(_C45 * (x - y), -1.0, 1.0),
                assume(_C45 * (x + y), -1.0, 1.0), assume(_C45 * (w + z), -1.0, 1.0))


def enu_to_nwu(q: Quat) -> Quat:
    """(cos 45°, 0, 0, -sin 45°) ⊗ q."""
    w, x, y, z = q
    return Quat(assume(_C45 * (w + z), -1.0, 1.0), assume(_C45 * (x + y), -1.0, 1.0),
                assume(_C45 * (y - x), -1.0, 1.0), assume(_C45 * (z - w), -1.0, 1.0))
