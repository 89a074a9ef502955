"""The wearable dynamic EKF: a planar thigh-shank leg observed by one IMU (gyroscope +
accelerometer) per segment, estimating hip and knee torques in real time.

Seed 000 names velocity and acceleration sensors as the way to cut the delay of the efforts
estimated from positions; seed 003 says the same of gyroscopes and accelerometers.  With an
accelerometer the torque enters the measurement through z̈ = M⁻¹(Q_g + Bᵀ T_e), so its row
of H carries ∂a/∂z̈ · [z̈_z, z̈_ż, z̈_T] (chain rule through the same AD sensitivity).
The mean is integrated with classical Runge-Kutta 4 by default: forward Euler's truncation
error on the mean becomes a torque bias (shared/notes/dynamic-ekf.md).
"""
from __future__ import annotations

import math

from kinefuse.codegen.estimator import Estimator, InputSpec, Param, Var
from kinefuse.codegen.ir import BOOL, INT
from kinefuse.codegen.mathlib import atan2
from kinefuse.codegen.scalar import (all_of, fabs, fmax, inc_if, logical_and, logical_not,
                                     logical_or, select, sqrt, when)
from kinefuse.codegen.estimators.dynamics.ad import sincos
from kinefuse.codegen.estimators.dynamics.ekf import (Variant, diag_sym_init, measurement_jacobian,
                                                      pack_sym, predict, sequential_update,
                                                      start_run_or_hold, tri_size, unpack_sym)
from kinefuse.codegen.estimators.dynamics.mbs import Dynamics, point_kinematics, static_efforts
from kinefuse.codegen.estimators.dynamics.models import Leg

GYR_MAX = 2000.0 * math.pi / 180.0      # rad/s
ACC_MAX = 16.0 * 9.80665                # m/s^2
FOOT_MAX = 5000.0                       # N
DT_MAX = 0.1                            # s
DT_MIN_START = 1e-4                     # s: smallest step the start's difference formula uses
Z_LIM = 4.0 * math.pi                   # rad: estimates beyond these reset the filter
ZD_LIM = GYR_MAX                        # rad/s
TE_LIM = 1000.0                         # N*m or N
P_LIM = 1e8

LEG_INPUT = InputSpec("leg", (
    Var("gyr", 2, -GYR_MAX, GYR_MAX, "rad/s",
        "angular rate of the thigh and of the shank about the medio-lateral axis "
        "(counter-clockwise seen with walking direction +x: hip flexion positive)"),
    Var("acc", 4, -ACC_MAX, ACC_MAX, "m/s^2",
        "specific force in the segment frames: thigh (along the thigh towards the knee, "
        "anterior), shank (along the shank towards the ankle, anterior); +g along the "
        "segment's upward direction at rest"),
    Var("foot", 2, -FOOT_MAX, FOOT_MAX, "N", "external force at the ankle (x forward, y up), "
        "for the filter built with the foot force sensor"),
    Var("gyr_valid", 2, 0, 1, "", "1 when gyroscope i (thigh, shank) has a sample", BOOL),
    Var("acc_valid", 2, 0, 1, "", "1 when accelerometer i (thigh, shank) has a sample", BOOL),
    Var("foot_valid", 1, 0, 1, "", "1 when the foot force sensor has a sample", BOOL),
    Var("dt", 1, 0.0, DT_MAX, "s", "time since the previous sample"),
), doc="One sample of the two leg IMUs (and the optional ankle force sensor).  Non-finite or "
       "out-of-range values of a valid sensor are rejected (counted) and that sensor is "
       "treated as lost for the sample.")

# The noise and initial-uncertainty ranges are where the float32 filter was measured to work
# (README, "Dynamic multibody EKF"), not physical limits.  leg: every corner of this box and 200
# random points inside, on 10 simulated gait trials (1 Hz stride, 10 s), ran without a reset
# or skipped update.  Outside, float32 broke down where float64 did not: sigma_gyr 1e-5 /
# sigma_acc 1e-4 gave 446 resets and 31.6 N*m hip RMSE (float64: 0 resets, 0.138 N*m);
# sigma_gyr 3e-5 / sigma_acc 1e-2: 9 resets; q_torque 1e8 at the default noise: 1 reset, 1e9:
# 350; q_torque 1e-6: up to 618; p0_rate 10 or p0_torque 1e3 with sigma_gyr 1e-3 /
# sigma_acc 1e-2: resets at the start on some trials; leg_foot with sigma_foot 0.1 and
# q_force 1e8: 43 resets.  leg_foot inside the box: at sigma_gyr 0.1 with sigma_acc 0.01 some
# corners reset, mostly in float64 as well (the filter, not the number system).
F32_RANGE_NOTE = "; range: float32 measured to work inside it (dynamics/leg.py)"

# Winter (2009) for a 75 kg, 1.75 m adult (see host/dynamics/truth.py LegConfig)
_H, _M = 1.75, 75.0
_L1, _L2 = 0.245 * _H, 0.246 * _H
_DEFAULTS = dict(m1=0.100 * _M, m2=0.061 * _M, L1=_L1, c1=0.433 * _L1, c2=0.606 * _L2,
                 I1=0.100 * _M * (0.323 * _L1) ** 2, I2=0.061 * _M * (0.416 * _L2) ** 2)


def _params(foot: bool):
    d = _DEFAULTS
    ps = [
        Param("m1", d["m1"], "kg", 0.5, 50.0, "thigh mass"),
        Param("m2", d["m2"], "kg", 0.2, 30.0, "shank + foot mass"),
        Param("L1", d["L1"], "m", 0.1, 1.0, "hip to knee"),
        Param("c1", d["c1"], "m", 0.02, 1.0, "thigh centre of mass from the hip"),
        Param("c2", d["c2"], "m", 0.02, 1.0, "shank+foot centre of mass from the knee"),
        Param("I1", d["I1"], "kg*m^2", 1e-3, 5.0, "thigh moment of inertia about its CoM"),
        Param("I2", d["I2"], "kg*m^2", 1e-3, 5.0, "shank+foot moment of inertia about its CoM"),
        Param("g", 9.81, "m/s^2", 0.0, 20.0, "gravity"),
        Param("a1", 0.20, "m", 0.0, 1.0, "thigh IMU: distance along the thigh from the hip"),
        Param("b1", 0.07, "m", -0.3, 0.3, "thigh IMU: anterior offset from the thigh axis"),
        Param("a2", 0.20, "m", 0.0, 1.0, "shank IMU: distance along the shank from the knee"),
        Param("b2", 0.05, "m", -0.3, 0.3, "shank IMU: anterior offset from the shank axis"),
        Param("sigma_gyr", 0.005, "rad/s", 1e-3, 0.1, "gyroscope noise (standard deviation)"
              + F32_RANGE_NOTE),
        Param("sigma_acc", 0.05, "m/s^2", 1e-2, 1.0,
              "accelerometer noise (standard deviation; include model error: soft tissue)"
              + F32_RANGE_NOTE),
        Param("q_torque", 2.0e4, "(N*m)^2/s", 1e3, 1e6,
              "power spectral density of the rate of the joint torques (random walk)"
              + F32_RANGE_NOTE),
        Param("p0_angle", 0.2, "rad", 0.01, 1.0, "initial standard deviation of the angles"
              + F32_RANGE_NOTE),
        Param("p0_rate", 0.1, "rad/s", 0.01, 1.0, "initial standard deviation of the rates"
              + F32_RANGE_NOTE),
        Param("p0_torque", 30.0, "N*m", 1.0, 300.0, "initial standard deviation of the torques"
              + F32_RANGE_NOTE),
    ]
    if foot:
        ps += [Param("sigma_foot", 2.0, "N", 0.5, 1e3, "foot force sensor noise (std)"
                     + F32_RANGE_NOTE),
               Param("q_force", 1.0e6, "N^2/s", 1e3, 1e7,
                     "power spectral density of the rate of the ankle force" + F32_RANGE_NOTE),
               Param("p0_force", 100.0, "N", 1.0, 1e3, "initial standard deviation of the "
                     "ankle force" + F32_RANGE_NOTE)]
    return tuple(ps)


def _state_outputs(foot: bool):
    """(state, outputs) declarations of the filter with or without the ankle force."""
    efforts = Leg(foot=foot).efforts
    ne = len(efforts)
    N = 4 + ne
    d = {p.name: p.default for p in _params(foot)}
    p0 = [d["p0_angle"] ** 2] * 2 + [d["p0_rate"] ** 2] * 2 + [d["p0_torque"] ** 2] * 2 + \
        ([d["p0_force"] ** 2] * 2 if foot else [])
    units = "N*m, N*m" + (", N, N" if foot else "")
    state = (
        Var("z", 2, -Z_LIM, Z_LIM, "rad", "thigh and shank angles"),
        Var("zd", 2, -ZD_LIM, ZD_LIM, "rad/s", "their rates"),
        Var("te", ne, -TE_LIM, TE_LIM, units, "efforts " + " ".join(efforts)),
        Var("P", tri_size(N), -P_LIM, P_LIM, "SI", "error covariance, upper triangle "
            "row by row (order z, zd, te)", init=diag_sym_init(p0)),
        Var("initialised", 1, 0, 1, "", "1 once started", BOOL, init=False),
        Var("gyr_hist", 4, -GYR_MAX, GYR_MAX, "rad/s", "gyroscopes (thigh, shank) of the "
            "previous sample, then of the one before (0 where not valid): the start's "
            "angular accelerations"),
        Var("dt_prev", 1, 0.0, DT_MAX, "s", "dt of the previous sample (0 when invalid)"),
        Var("hist_ok", 2, 0, 1, "", "1 when both gyroscopes were valid in the previous "
            "sample; 1 when they were in the one before and the previous dt was valid", BOOL,
            init=False),
        Var("rejected", 1, 0, 2 ** 31 - 1, "samples", "sensor samples rejected (non-finite "
            "or out of range) and samples with an invalid dt", INT, init=0),
        Var("skipped", 1, 0, 2 ** 31 - 1, "samples", "samples in which a scalar update was "
            "skipped because its innovation variance was not above half the sensor variance "
            "(the covariance lost positive definiteness)", INT, init=0),
        Var("resets", 1, 0, 2 ** 31 - 1, "", "restarts after a non-finite or out-of-range "
            "estimate", INT, init=0),
    )
    outputs = (
        Var("z", 2, -Z_LIM, Z_LIM, "rad", "estimated thigh and shank angles"),
        Var("zd", 2, -ZD_LIM, ZD_LIM, "rad/s", "estimated rates"),
        Var("te", ne, -TE_LIM, TE_LIM, units, "estimated " + " ".join(efforts)),
        Var("te_std", ne, 0.0, 1e4, units, "standard deviation of the effort estimates"),
        Var("initialised", 1, 0, 1, "", "1 when the outputs are estimates", BOOL),
        Var("imu_lost", 1, 0, 1, "", "1 when a segment has neither gyroscope nor "
            "accelerometer in this sample", BOOL),
        Var("skipped_now", 1, 0, 1, "", "1 when an update was skipped in this sample", BOOL),
        Var("reset_now", 1, 0, 1, "", "1 when the filter reset in this sample", BOOL),
        Var("rejected", 1, 0, 2 ** 31 - 1, "samples", "running count (see state)", INT),
        Var("skipped", 1, 0, 2 ** 31 - 1, "updates", "running count (see state)", INT),
        Var("resets", 1, 0, 2 ** 31 - 1, "", "running count (see state)", INT),
    )
    return state, outputs


class LegEKF(Estimator):
    """Reduced dynamic EKF of a planar thigh-shank leg with the hip fixed: state
    z = [theta1 theta2] (rad, thigh and shank from the downward vertical, counter-clockwise =
    hip flexion), rates (rad/s), and the joint torques T_e = [tau_hip tau_knee] (N*m;
    tau_hip on the thigh from the pelvis, + flexing; tau_knee on the shank from the thigh, +
    extending the knee) as random walks.  Sensors: gyroscope and 2-axis accelerometer on each
    segment (positions a_i, b_i in the segment frames).  Runge-Kutta 4 for the mean,
    second-order Phi, Taylor noise covariance, scalar Joseph updates.  Starts, in motion or
    at rest, from the first sample with both accelerometers that has both gyroscopes in it and
    in the two samples before (:meth:`_kinematic_start`: angles from the gravity direction once
    the IMUs' own accelerations are removed, rates from the gyroscopes, angular accelerations
    from their difference, torques by inverse dynamics); a non-finite or out-of-range estimate
    resets it (counted).
    """

    name = "leg"
    title = "Wearable leg dynamic EKF: hip and knee torques from two IMUs"
    inputs = LEG_INPUT
    params = _params(False)
    state, outputs = _state_outputs(False)
    foot = False
    systems = ("f32",)      # the fixed-point attempt is documented in host/dynamics/fixed_leg.py

    def __init__(self, variant: Variant | None = None, name: str | None = None):
        self.variant = variant or Variant(integrator="rk4", phi="se", sigma="ct")
        self.model = Leg(foot=self.foot)
        ne = len(self.model.efforts)
        self.ne = ne
        self.N = 4 + ne
        if name is not None:
            self.name = name

    def _p0_diag(self, p):
        a, r, t = p.p0_angle * p.p0_angle, p.p0_rate * p.p0_rate, p.p0_torque * p.p0_torque
        d = [a, a, r, r, t, t]
        if self.foot:
            f = p.p0_force * p.p0_force
            d += [f, f]
        return d

    def _qdiag(self, p):
        q = [p.q_torque, p.q_torque]
        if self.foot:
            q += [p.q_force, p.q_force]
        return q

    @staticmethod
    def _kinematic_start(gyr, gyr_hist, acc, dt, dt_prev, p):
        """(z, ż, z̈) at the start from one sample of the accelerometers and three of the
        gyroscopes: exact for a rigid leg with the hip fixed, up to sensor noise and the
        error of the difference formula.

        Why not the quasi-static start (angles from the accelerometers as if at rest): an
        accelerometer measures gravity plus the IMU's own acceleration, which in gait is of
        the order of g (at a 1.4 Hz stride the shank's angular acceleration reaches
        80 rad/s²), so those angles were up to 2 rad off and the EKF, linearised there, took
        seconds to recover.  Nor waiting for a quasi-static moment (gyroscopes small,
        |f| ≈ g): continuous gait has none, and the restart after a sensor loss must work in
        motion too.  Instead the start inverts the filter's own accelerometer model.  With
        the hip fixed, an IMU's acceleration in its segment frame depends only on the
        segment's ω and α (the shank's also on the knee's acceleration, known once the
        thigh's angle is); ω comes from the gyroscope and α from its second-order backward
        difference over the last three samples (error h²/3 times the third derivative of ω;
        the two-point difference's error, h/2 times the second, left up to 0.18 rad in the
        start angles at a 1.4 Hz stride, this one 0.05).  What remains of the specific force
        is gravity in the segment frame, hence the angle.  At rest this is the quasi-static
        start.  Noise: the difference amplifies gyroscope noise by about 2.55/h, σ_α ≈
        1.3 rad/s² at σ_gyr = 0.005 rad/s and 100 Hz (≈ 0.03 rad thigh, 0.08 rad shank,
        inside the default p0_angle); far above 100 Hz a longer window would be needed."""
        # weights of ω_k, ω_k-1, ω_k-2 for steps h1 = dt, h2 = dt_prev: (2h1 + h2)/(h1(h1 + h2)),
        # (h1 + h2)/(h1 h2), h1/(h2(h1 + h2)) (3/2h, 2/h, 1/2h for equal steps); steps below
        # DT_MIN_START count as DT_MIN_START (also keeps the float64 reference, which
        # computes this region in every sample, from dividing by zero)
        r1 = 1.0 / fmax(dt, DT_MIN_START)
        r2 = 1.0 / fmax(dt_prev, DT_MIN_START)
        r12 = 1.0 / (fmax(dt, DT_MIN_START) + fmax(dt_prev, DT_MIN_START))
        c0, c1, c2 = r1 + r12, r1 + r2, r2 - r12
        w = [gyr[0], gyr[1]]
        al = [c0 * gyr[i] - c1 * gyr_hist[i] + c2 * gyr_hist[2 + i] for i in range(2)]
        # the IMU's acceleration from its segment's own rotation, in the segment frame
        # (u along, v anterior): a (α v − ω² u) + b (−α u − ω² v)
        own = [(-(p.a1 * (w[0] * w[0])) - p.b1 * al[0], p.a1 * al[0] - p.b1 * (w[0] * w[0])),
               (-(p.a2 * (w[1] * w[1])) - p.b2 * al[1], p.a2 * al[1] - p.b2 * (w[1] * w[1]))]
        # f − own = (W·u, W·v) with W = a_proximal − g_vec (world), u = (s, −c), v = (c, s):
        # (s, c) ∝ (Wx m_u + Wy m_v, Wx m_v − Wy m_u).  Thigh: W = (0, g).
        mu, mv = acc[0] - own[0][0], acc[1] - own[0][1]
        th1 = atan2(mv, -mu)
        s1, c1_ = sincos(th1)
        # shank: W = knee acceleration − g_vec, knee acceleration = L1 (α1 v1 − ω1² u1)
        w11 = w[0] * w[0]
        Wx = p.L1 * (al[0] * c1_ - w11 * s1)
        Wy = p.L1 * (al[0] * s1 + w11 * c1_) + p.g
        mu, mv = acc[2] - own[1][0], acc[3] - own[1][1]
        th2 = atan2(Wx * mu + Wy * mv, Wx * mv - Wy * mu)
        return [th1, th2], w, al

    def h_fn(self, z, zd, te, zdd, p):
        """Predicted sensors: gyro thigh, gyro shank, acc thigh (along, anterior), acc shank
        (along, anterior) [, foot x, y]."""
        _, _, acc = point_kinematics(self.model.imu_points, z, zd, zdd, p)
        out = [zd[0], zd[1]]
        for i in range(2):
            s, c = sincos(z[i])
            ax, ay = acc[2 * i], acc[2 * i + 1] + p.g     # a - g_vec, g_vec = (0, -g)
            out += [s * ax - c * ay, c * ax + s * ay]      # u = (s, -c), v = (c, s)
        if self.foot:
            out += [te[2], te[3]]
        return out

    def step(self, x, u, p):
        model, v, ne, N = self.model, self.variant, self.ne, self.N
        z, zd, te = list(x.z), list(x.zd), list(x.te)
        P = unpack_sym(list(x.P), N)
        dt = u.dt
        dt_ok = all_of(dt > 0.0, dt <= DT_MAX)

        gyr, acc, foot = list(u.gyr), list(u.acc), list(u.foot)
        g_ok = [logical_and(u.gyr_valid[i], fabs(gyr[i]) <= GYR_MAX) for i in range(2)]
        a_ok = [all_of(u.acc_valid[i], fabs(acc[2 * i]) <= ACC_MAX,
                       fabs(acc[2 * i + 1]) <= ACC_MAX) for i in range(2)]
        bad = [logical_and(u.gyr_valid[i], logical_not(g_ok[i])) for i in range(2)] + \
              [logical_and(u.acc_valid[i], logical_not(a_ok[i])) for i in range(2)]
        ys = gyr + acc
        use = g_ok + [a_ok[0], a_ok[0], a_ok[1], a_ok[1]]
        sg, sa = p.sigma_gyr, p.sigma_acc
        rvar = [sg * sg] * 2 + [sa * sa] * 4
        if self.foot:
            f_ok = all_of(u.foot_valid, fabs(foot[0]) <= FOOT_MAX, fabs(foot[1]) <= FOOT_MAX)
            bad.append(logical_and(u.foot_valid, logical_not(f_ok)))
            ys += foot
            use += [f_ok, f_ok]
            rvar += [p.sigma_foot * p.sigma_foot] * 2
        rejected = x.rejected
        for b in bad:
            rejected = inc_if(rejected, b)
        rejected = inc_if(rejected, logical_and(x.initialised, logical_not(dt_ok)))

        # The start needs the angular accelerations, from the gyroscopes of this sample and
        # the two before (see _kinematic_start): both gyroscopes valid in all three, and both
        # dts valid.
        g_both = logical_and(g_ok[0], g_ok[1])
        wh = list(x.gyr_hist)
        have_alpha = all_of(g_both, dt_ok, x.hist_ok[0], x.hist_ok[1])
        do_init = all_of(logical_not(x.initialised), a_ok[0], a_ok[1], have_alpha)
        run = logical_and(x.initialised, dt_ok)
        # (conditional regions only save work when they do not run; results are selected)
        with when(run):
            # prediction at the current estimate
            zn, zdn, Pp, _ = predict(model, v, z, zd, te, P, self._qdiag(p), p, dt)
            # sensors at the prior: the accelerometers need z̈ and its sensitivity there
            D = Dynamics(model, zn, zdn, te, p)
            sens = D.sensitivity(full=True)
            hv, H = measurement_jacobian(self.h_fn, zn, zdn, te, D.zdd, sens, p)
            innov = [select(use[i], ys[i] - hv[i], 0.0) for i in range(len(ys))]
            xu, Pu, skipped_now = sequential_update(zn + zdn + te, Pp, innov, H, rvar, use)
        with when(do_init):
            # start: angles from the gravity direction once the IMUs' own accelerations are
            # removed, rates from the gyroscopes, torques by inverse dynamics
            z0, zd0, zdd0 = self._kinematic_start(gyr, wh, acc, dt, x.dt_prev, p)
            te0 = [0.0, 0.0] + ([select(use[6], foot[0], 0.0), select(use[7], foot[1], 0.0)]
                                if self.foot else [])
            te0[:2] = static_efforts(model, z0, zd0, te0, (0, 1), p, zdd=zdd0)
        lims = [Z_LIM] * 2 + [ZD_LIM] * 2 + [TE_LIM] * ne
        xs, Pn, init_next, reset_now = start_run_or_hold(
            x.initialised, do_init, run, z0 + zd0 + te0, self._p0_diag(p), xu, Pu,
            z + zd + te, P, lims, P_LIM)
        skipped_now = logical_and(run, skipped_now)
        skipped = inc_if(x.skipped, skipped_now)
        resets = inc_if(x.resets, reset_now)
        zs, zds, tes = xs[:2], xs[2:4], xs[4:]
        te_std = [sqrt(fmax(Pn[4 + e][4 + e], 0.0)) for e in range(ne)]
        imu_lost = logical_not(all_of(*(logical_or(g_ok[i], a_ok[i]) for i in range(2))))
        nx = {"z": zs, "zd": zds, "te": tes, "P": pack_sym(Pn), "initialised": init_next,
              "gyr_hist": [select(g_both, gyr[0], 0.0), select(g_both, gyr[1], 0.0),
                           wh[0], wh[1]],
              "dt_prev": select(dt_ok, dt, 0.0),
              "hist_ok": [g_both, logical_and(x.hist_ok[0], dt_ok)],
              "rejected": rejected, "skipped": skipped, "resets": resets}
        y = {"z": zs, "zd": zds, "te": tes, "te_std": te_std, "initialised": init_next,
             "imu_lost": imu_lost, "skipped_now": skipped_now, "reset_now": reset_now,
             "rejected": rejected, "skipped": skipped, "resets": resets}
        return nx, y


class LegFootEKF(LegEKF):
    """The leg EKF with an ankle force sensor: T_e = [tau_hip tau_knee F_ax F_ay]."""

    name = "leg_foot"
    title = "Wearable leg dynamic EKF with an ankle force sensor"
    params = _params(True) + (Param("L2", _L2, "m", 0.1, 1.0, "knee to ankle"),)
    state, outputs = _state_outputs(True)
    foot = True

    def __init__(self, variant: Variant | None = None, name: str | None = None):
        super().__init__(variant, name)
        self.model = _FootLeg()


class _FootLeg(Leg):
    """Leg with the ankle force; the knee-to-ankle length is the parameter L2."""

    def __init__(self):
        super().__init__(foot=True)

    def conj(self, z, p):
        t1, t2 = z
        s1, c1 = sincos(t1)
        s2, c2 = sincos(t2)
        return [z[0], z[1] - z[0], p.L1 * s1 + p.L2 * s2, -(p.L1 * c1) - p.L2 * c2]


def leg_variant(variant: Variant, foot: bool = False) -> LegEKF:
    name = ("leg_foot_" if foot else "leg_") + variant.tag
    return (LegFootEKF if foot else LegEKF)(variant, name=name)


__all__ = ["LegEKF", "LegFootEKF", "leg_variant", "LEG_INPUT"]
