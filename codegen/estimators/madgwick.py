"""Madgwick's gradient-descent orientation filter, IMU (6D) and MARG (9D) in one step.

S. Madgwick, "An efficient orientation filter for inertial and inertial/magnetic sensor arrays",
2010; and Madgwick, Harrison, Vaidyanathan, ICORR 2011.

How the published step is evaluated (the same filter, fewer and shorter dependent operations):

* Gradient.  For an earth reference d_e (e_z for gravity, b = (b_x, 0, b_z) for the field), his
  objective is f = d - s with d = R(q)^T d_e in his substituted form and s the normalised
  measurement, and his gradient is J^T f (eq. 26, 30).  On the unit sphere |q| = 1, where the
  state lives, J^T f / 2 = q (x) ((d_e - d).(d_e + s), d x s) exactly (a polynomial identity
  modulo |q|^2 = 1; codegen/tests/test_madgwick_gradient.py checks the step against the
  literal formulas).
  The step is normalised, so the common factor 2 is left out, and |q (x) g| = |g|.
* Field reference.  h = q m q* (eq. 45): h_z = (R^T e_z).m, and |h| = |m| gives
  b_x = sqrt(h_x^2 + h_y^2) = sqrt(|m|^2 - h_z^2) (eq. 46), both from the raw reading.
* Update.  q + (q (x) (0, w) / 2 - beta q (x) g / |g|) dt (eq. 42-43) = q (x) p with
  p = (1, w dt / 2) - beta dt g / |g|; the result is normalised with |q (x) p|^2 = |q|^2 |p|^2 by
  one Newton step (error below 4e-7 when |q (x) p|^2 is within 1e-3 of 1 and dt <= 50 ms), and
  exactly in a conditional region otherwise (extreme rates or long time steps).
"""
from __future__ import annotations

import dataclasses

from kinefuse.codegen.estimator import Estimator, Param, Var
from kinefuse.codegen.linalg import Quat, Vec3, vselect
from kinefuse.codegen.scalar import (all_of, assume, clamp, fabs, fmax, fmin, inc_if,
                                     logical_and, logical_not, logical_or, rnorm, select, sqrt,
                                     when)
from kinefuse.codegen.estimators.common import (ACC_NORM_MIN_SQ, DT_MAX, IMU, INITIALISED,
                                                INIT_WAIT, MAG_MAX, MAG_NORM_MIN_SQ, Q_OUT,
                                                Q_STATE, REJECTED, SampleCheck, initial_quaternion,
                                                start_gate, within)

T_RUN_MAX = 60.0   # s; the run-time clock only needs to reach the end of the start-up phase
DT_NEAR = 0.05     # s; time steps up to this take the Newton renormalisation
SQRT3 = 1.7320508075688772


class Madgwick(Estimator):
    """Gyroscope integration corrected by one normalised gradient-descent step per sample on
    the misalignment of the measured gravity (and magnetic field) direction.

    Madgwick's equations are used as published, in his earth frame (x magnetic north, z up; the
    magnetic reference b = (b_x, 0, b_z) without the factor-2 error of many MARG copies); the state
    is kept in that frame and the output is turned into East-North-Up.  The field's direction in
    the earth frame is re-estimated every sample from the current orientation, so the
    magnetometer acts on heading and on inclination only through the gradient step.  Samples
    without a magnetometer reading use the gravity objective alone.  The orientation starts from
    the first valid sample (gravity and, if present, magnetic north); `beta_start` applies for
    the first `start_time` seconds.  (The module docstring says how the step is evaluated.)
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
             INITIALISED, INIT_WAIT,
             Var("t_run", 1, 0.0, T_RUN_MAX, "s", "time since initialisation (saturates)",
                 init=0.0),
             REJECTED)
    outputs = (Q_OUT, REJECTED)
    presets = {
        # seed 001 (ChakaMo): beta = 2 for the first 2 s, then 0.03
        "seed001": {"beta": 0.03, "beta_start": 2.0, "start_time": 2.0},
    }

    def step(self, x, u, p):
        # Madgwick's own frame (x magnetic north, z up) inside; ENU at the interface.  His
        # formulas replace w^2+x^2-y^2-z^2 by 1-2(y^2+z^2) etc.; those substitutions are not
        # rotation-equivariant, so deriving them in ENU would give a (slightly) different filter.
        q = Quat(*x.q)
        w, qx, qy, qz = q
        x2, y2, z2 = qx + qx, qy + qy, qz + qz    # = 2 q_i exactly (an addition: x86 has two
        #                                               adders besides its two multipliers)
        # R(q)^T e_z, the vertical in sensor coordinates (eq. 25, substituted form)
        s2 = assume(x2 * qx + y2 * qy, 0.0, 2.0)                 # 1 - r2_z
        r2 = Vec3(assume(x2 * qz - y2 * w, -1.0, 1.0), assume(x2 * w + y2 * qz, -1.0, 1.0),
                  1.0 - s2)

        # gravity objective: r2 against a/|a| (eq. 25), gradient term ((e_z - r2).(e_z + a), r2 x a).
        # Traced before the magnetic objective: the same operations, but GCC's x86-64 code from
        # this order ran 5-6 % faster (register allocation; measured against x-io Fusion)
        a, a2 = Vec3(*u.acc).normalized(1e-6)
        v_g = _unit(r2.cross(a))
        rho_g = assume(s2 * (1.0 + a.z) - (r2.x * a.x + r2.y * a.y), -4.0, 4.0)

        # magnetic objective: d = R^T b = b_x r0 + b_z r2 against m/|m| (eq. 29, 45-46), its
        # gradient term g_b = ((b - d).(b + m), d x m); computed only when a reading arrived
        # (and used only when it is valid: use_mag below)
        with when(u.mag_valid):
            mag = Vec3(*(assume(c, -MAG_MAX, MAG_MAX) for c in u.mag))
            km, m2 = rnorm(mag, 1e-6)
            m = Vec3(*(assume(c * km, -1.0, 1.0) for c in mag))
            hz = assume(r2.dot(mag), -MAG_MAX * SQRT3, MAG_MAX * SQRT3)     # |r2| = 1
            bz = assume(hz * km, -1.0, 1.0)
            bx = assume(sqrt(fmax(m2 - hz * hz, 0.0)) * km, 0.0, 1.0)
            # R(q)^T e_x, magnetic north in sensor coordinates (substituted form)
            r0 = _unit(Vec3(1.0 - (y2 * qy + z2 * qz), x2 * qy - z2 * w, x2 * qz + y2 * w))
            d = _unit(r0 * bx + r2 * bz)                                     # |d| = |b| = 1
            v_b = _unit(d.cross(m))
            rho_b = assume((bx - d.x) * (bx + m.x) + ((bz - d.z) * (bz + m.z) - d.y * m.y),
                           -4.0, 4.0)                                        # |b - d|, |b + m| <= 2

        # the halved gradient J^T f / 2 (eq. 26, 30) is q (x) g.  (A sample that is rejected
        # as a whole keeps q below, so these selects only need each sensor's own usability.)
        use_acc = a2 >= ACC_NORM_MIN_SQ
        use_mag = all_of(u.mag_valid, within(Vec3(*u.mag), MAG_MAX), m2 >= MAG_NORM_MIN_SQ)
        zero3 = Vec3(0.0, 0.0, 0.0)
        v = vselect(use_acc, v_g, zero3) + vselect(use_mag, v_b, zero3)
        rho = select(use_acc, rho_g, 0.0) + select(use_mag, rho_b, 0.0)
        g = Quat(rho, v.x, v.y, v.z)             # the gradient, not normalised

        # q + (q (x) (0, w) / 2 - beta q (x) g / |g|) dt  (eq. 42-43) = q (x) p, normalised
        dt = clamp(u.dt, 0.0, DT_MAX)              # SampleCheck's clamped time step
        beta = select(x.t_run < p.start_time, p.beta_start, p.beta)
        q_new = _step(q, g, Vec3(*u.gyr), dt, beta)

        # the sample validation and bookkeeping come last in the generated code: nothing on
        # the long dependency chain above waits for them
        chk = SampleCheck(u)
        # first valid sample: orientation from gravity and magnetic north (ENU -> Madgwick frame)
        start, t_wait = start_gate(chk, x.initialised, x.t_wait)
        with when(start):
            q_init, init_ok = initial_quaternion(chk.acc, chk.mag, chk.use_mag)
            q_init = enu_to_nwu(q_init)
        do_init = logical_and(start, init_ok)
        run = logical_and(chk.ok, x.initialised)
        # do_init and run exclude each other: one select on the path of the update
        q_next = vselect(run, q_new, vselect(do_init, q_init, q))
        # t_run >= 0 and dt >= 0: only the upper limit can bind
        t_next = select(run, fmin(x.t_run + chk.dt, T_RUN_MAX), x.t_run)
        rejected = inc_if(x.rejected, chk.bad)
        nx = {"q": q_next, "initialised": logical_or(x.initialised, do_init), "t_wait": t_wait,
              "t_run": t_next, "rejected": rejected}
        return nx, {"q": nwu_to_enu(q_next), "rejected": rejected}


def _unit(v: Vec3) -> Vec3:
    """The components of a vector of length <= 1 (fixed point: their formats)."""
    return Vec3(*(assume(c, -1.0, 1.0) for c in v))


def _step(q: Quat, g: Quat, gyr: Vec3, dt, beta) -> Quat:
    """(q (x) p) / |q (x) p| with p = (1, w dt / 2) - beta dt g / |g|, |q (x) p|^2 = |q|^2 |p|^2.

    beta dt / |g| is one scaled rnorm, split: on the sample-to-sample chain binary32 then waits
    for max(sqrt, division) and one product, instead of sqrt, division and two products
    (measured 7 % faster per sample on x86-64); fixed point keeps it as a dynamic value.

    A step turns q by a small angle, so |q (x) p| is close to 1: one Newton step
    k = (3 - |q|^2 |p|^2) / 2 normalises (error 3/8 of the squared deviation, < 4e-7 for
    deviations below 1e-3); larger deviations (extreme rates, time steps or gains) take the
    exact 1/sqrt in a conditional region, with p formed there again for the full ranges.  On
    the Newton path every component of p and of its terms lies within +-2, which is what the
    fixed-point formats are chosen for (a p outside has |p|^2 >= 4: the exact path).
    """
    near = lambda v: assume(v, -2.0, 2.0)   # noqa: E731
    bdt = assume(beta * dt, 0.0, 1.0)       # beta <= 20: dt <= 1/20 on this path
    k, _ = rnorm(g, 1e-12, split=True, scale=bdt)    # beta dt / |g|
    s = Quat(*(assume(c * k, -1.0, 1.0) for c in g))   # |s| = bdt <= 1
    h = Vec3(*(near(c) for c in gyr * (0.5 * dt)))   # (w / 2) dt exactly, two products fewer
    p = Quat(near(1.0 - s.w), near(h.x - s.x), near(h.y - s.y), near(h.z - s.z))
    n2h = (0.5 * q.norm_sq()) * ((p.w * p.w + p.x * p.x) + (p.y * p.y + p.z * p.z))
    # with dt <= 1/20 every term lies within its bound (|w| <= 70 rad/s even out of range);
    # a longer time step is normalised exactly
    far = logical_or(fabs(n2h - 0.5) > 0.5e-3, dt > DT_NEAR)
    with when(far):
        gb = s.normalized(1e-24).scale(beta)   # g / |g| again from s, not from g: g's
        #                                         components need not stay live for this branch
        hf = gyr * (0.5 * dt)
        pf = Quat(1.0 - gb.w * dt, hf.x - gb.x * dt, hf.y - gb.y * dt, hf.z - gb.z * dt)
        q_far = (q * pf).normalized(1e-6)
    k = 1.5 - n2h
    return Quat(*(select(far, cf, assume(cn * k, -1.0, 1.0))
                  for cf, cn in zip(q_far, q * p)))


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
