"""The double-pendulum dynamic EKF of seed 000 §3.3 / Annex A (the validation benchmark of the
full-body observer): 4 markers and the reaction sensors observe a 12-state EKF
(z = [x0 y0 θ1 θ2], ż, T_e = [τ1 Fx Fy T2]; 15 states with the base residual).

The registered filter ``pendulum`` is the real-time choice of the seed ("FDMC": forward Euler,
second-order Φ, Taylor Σ_k, full sensitivity); every other combination of
:class:`~kinefuse.codegen.estimators.dynamics.ekf.Variant` is built on demand with
:func:`pendulum_variant` (the benchmark generates and compiles them into a cache).
"""
from __future__ import annotations

import math

from kinefuse.codegen.estimator import Estimator, InputSpec, Param, Var
from kinefuse.codegen.ir import BOOL, INT
from kinefuse.codegen.mathlib import atan2
from kinefuse.codegen.scalar import (all_of, any_of, fabs, fmax, inc_if, logical_and,
                                     logical_not, logical_or, select, sqrt, when)
from kinefuse.codegen.estimators.dynamics.ekf import (Variant, diag_sym_init, measurement_jacobian,
                                                      pack_sym, predict, sequential_update,
                                                      start_run_or_hold, tri_size, unpack_sym)
from kinefuse.codegen.estimators.dynamics.mbs import static_efforts
from kinefuse.codegen.estimators.dynamics.models import (PENDULUM_MARKERS, Pendulum,
                                                         pendulum_markers)

DT_MAX = 0.1            # s: longest step accepted
MARKER_LIM = 10.0       # m: |marker coordinate| accepted
EFFORT_LIM = 20000.0    # N or N*m: |effort sample| accepted
Z_LIM = (10.0, 10.0, 20.0, 20.0)      # m, m, rad, rad: estimates beyond these reset the filter
ZD_LIM = 100.0                        # m/s or rad/s
TE_LIM = 50000.0                      # N or N*m
P_LIM = 1e10                          # largest variance kept

PENDULUM_INPUT = InputSpec("pendulum", (
    Var("markers", 8, -MARKER_LIM, MARKER_LIM, "m",
        "marker positions m1x m1y m2x m2y m3x m3y m4x m4y (m1, m2 on bar 1; m3, m4 on bar 2), "
        "x horizontal, y up"),
    Var("marker_valid", 4, 0, 1, "", "1 when marker i was seen in this frame", BOOL),
    Var("efforts", 4, -EFFORT_LIM, EFFORT_LIM, "N*m, N, N, N*m",
        "effort sensors: joint torque tau1, reactions Fx, Fy (N) and T2 at point 2"),
    Var("effort_valid", 4, 0, 1, "", "1 when effort sensor i has a sample (tau1 is usually "
        "not measured)", BOOL),
    Var("dt", 1, 0.0, DT_MAX, "s", "time since the previous frame"),
), doc="One motion-capture frame of the double pendulum: markers and reaction sensors.  "
       "Non-finite or out-of-range values of a valid sensor are rejected (counted) and that "
       "sensor is treated as lost for the frame.")


def _params(residual: bool):
    ps = [
        Param("m1", 50.0, "kg", 0.5, 500.0, "mass of bar 1 (point 0 to point 1)"),
        Param("m2", 35.0, "kg", 0.5, 500.0, "mass of bar 2 (point 1 to point 2; seed Table A.1: "
              "35, Table 3.1: 25)"),
        Param("L", 0.8, "m", 0.1, 5.0, "length of each bar"),
        Param("g", 9.81, "m/s^2", 0.0, 20.0, "gravity"),
        Param("sigma_marker", 1e-3, "m", 1e-6, 1.0, "marker noise (standard deviation)"),
        Param("sigma_force", 0.05, "N", 1e-4, 1e3, "force sensor noise (standard deviation)"),
        Param("sigma_torque", 0.05, "N*m", 1e-4, 1e3, "torque sensor noise (standard deviation)"),
        Param("q_force", 1.0e5, "N^2/s", 1e-8, 1e9,
              "power spectral density of the rate of every force effort (random walk)"),
        Param("q_torque", 1.0e5, "(N*m)^2/s", 1e-8, 1e9,
              "power spectral density of the rate of every torque effort (random walk)"),
        Param("p0_pos", 0.02, "m or rad", 1e-6, 10.0, "initial standard deviation of z"),
        Param("p0_vel", 1.0, "m/s or rad/s", 1e-6, 100.0, "initial standard deviation of z'"),
        Param("p0_force", 10.0, "N", 1e-3, 1e4, "initial standard deviation of forces"),
        Param("p0_torque", 100.0, "N*m", 1e-3, 1e4, "initial standard deviation of torques"),
    ]
    if residual:
        ps += [Param("q_res_force", 1e-3, "N^2/s", 1e-10, 1e9,
                     "power spectral density of the rate of the residual force"),
               Param("q_res_moment", 1e-3, "(N*m)^2/s", 1e-10, 1e9,
                     "power spectral density of the rate of the residual moment"),
               Param("p0_residual", 1.0, "N or N*m", 1e-6, 1e4,
                     "initial standard deviation of the residual")]
    return tuple(ps)


def _state_outputs(residual: bool):
    """(state, outputs) declarations of the filter with or without the base residual."""
    efforts = Pendulum(residual).efforts
    ne = len(efforts)
    N = 8 + ne
    defaults = {p.name: p.default for p in _params(residual)}
    p0 = [defaults["p0_pos"] ** 2] * 4 + [defaults["p0_vel"] ** 2] * 4 + \
        [defaults["p0_torque"] ** 2, defaults["p0_force"] ** 2, defaults["p0_force"] ** 2,
         defaults["p0_torque"] ** 2] + ([defaults["p0_residual"] ** 2] * 3 if residual else [])
    state = (
        Var("z", 4, -20.0, 20.0, "m, m, rad, rad", "x0, y0, theta1, theta2"),
        Var("zd", 4, -ZD_LIM, ZD_LIM, "m/s, m/s, rad/s, rad/s", "rates of z"),
        Var("te", ne, -TE_LIM, TE_LIM, "N*m, N, N, N*m" + (", N, N, N*m" if residual else ""),
            "efforts " + " ".join(efforts)),
        Var("P", tri_size(N), -P_LIM, P_LIM, "SI", "error covariance, upper triangle "
            "row by row (order z, zd, te)", init=diag_sym_init(p0)),
        Var("initialised", 1, 0, 1, "", "1 once started from a full set of markers", BOOL,
            init=False),
        Var("rejected", 1, 0, 2 ** 31 - 1, "samples", "sensor samples rejected (non-finite "
            "or out of range) and frames with an invalid dt", INT, init=0),
        Var("skipped", 1, 0, 2 ** 31 - 1, "frames", "frames in which a scalar update was "
            "skipped because its innovation variance was not above half the sensor variance "
            "(the covariance lost positive definiteness)", INT, init=0),
        Var("resets", 1, 0, 2 ** 31 - 1, "", "restarts after a non-finite or out-of-range "
            "estimate", INT, init=0),
    )
    outputs = (
        Var("z", 4, -20.0, 20.0, "m, m, rad, rad", "estimated x0, y0, theta1, theta2"),
        Var("zd", 4, -ZD_LIM, ZD_LIM, "m/s, m/s, rad/s, rad/s", "estimated rates"),
        Var("te", ne, -TE_LIM, TE_LIM, "N*m, N, N, N*m", "estimated efforts "
            + " ".join(efforts)),
        Var("te_std", ne, 0.0, 1e5, "N*m, N, N, N*m", "standard deviation of the effort "
            "estimates (from P)"),
        Var("initialised", 1, 0, 1, "", "1 when the outputs are estimates", BOOL),
        Var("bar_lost", 1, 0, 1, "", "1 when both markers of a bar are missing in this frame "
            "(the state is not observable from positions: seed 000 §3.3.4)", BOOL),
        Var("skipped_now", 1, 0, 1, "", "1 when an update was skipped in this frame", BOOL),
        Var("reset_now", 1, 0, 1, "", "1 when the filter reset in this frame", BOOL),
        Var("rejected", 1, 0, 2 ** 31 - 1, "samples", "running count (see state)", INT),
        Var("skipped", 1, 0, 2 ** 31 - 1, "updates", "running count (see state)", INT),
        Var("resets", 1, 0, 2 ** 31 - 1, "", "running count (see state)", INT),
    )
    return state, outputs


class PendulumEKF(Estimator):
    """Reduced dynamic EKF of the double pendulum (seed 000 §3.3 / Annex A).

    State: z = [x0 y0 theta1 theta2] (m, m, rad, rad; point 0 and the absolute bar angles from
    the downward vertical, counter-clockwise), their rates, and the efforts T_e = [tau1 (N*m)
    joint torque between the bars, Fx Fy (N) and T2 (N*m) the reaction at point 2] (+ the base
    residual Frx Fry (N), Mr (N*m) at point 0) as random walks.  Dynamics in the
    velocity-transformation formulation with natural coordinates; every derivative by forward
    automatic differentiation.  Sensors: the 4 markers and the effort sensors flagged valid,
    processed one scalar at a time in Joseph form.  The filter starts from the first frame in
    which all four markers are seen (z from the markers, rates 0, efforts from their sensors,
    tau1 without its sensor from the static balance of the measured reactions, residual 0);
    an estimate that turns non-finite or leaves its range resets it (counted), so the outputs
    stay finite.
    """

    name = "pendulum"
    title = "Double-pendulum reduced dynamic EKF (seed 000)"
    inputs = PENDULUM_INPUT
    params = _params(False)
    state, outputs = _state_outputs(False)
    residual = False
    # float32 only: interval analysis cannot bound a covariance filter's values without
    # assumptions that would not hold for this 12-state filter (see the leg filter's q attempt)
    systems = ("f32",)

    def __init__(self, variant: Variant | None = None, name: str | None = None):
        self.variant = variant or Variant()
        residual = self.residual
        self.model = Pendulum(residual=residual)
        ne = len(self.model.efforts)
        self.N = 8 + ne
        if name is not None:
            self.name = name

    # -- pieces ---------------------------------------------------------------------------
    def _p0_diag(self, p):
        d = [p.p0_pos * p.p0_pos] * 4
        v = p.p0_vel * p.p0_vel
        f = p.p0_force * p.p0_force
        t = p.p0_torque * p.p0_torque
        diag = d + [v] * 4 + [t, f, f, t]
        if self.residual:
            r = p.p0_residual * p.p0_residual
            diag += [r, r, r]
        return diag

    def _qdiag(self, p):
        q = [p.q_torque, p.q_force, p.q_force, p.q_torque]
        if self.residual:
            q += [p.q_res_force, p.q_res_force, p.q_res_moment]
        return q

    def h_fn(self, z, zd, te, zdd, p):
        """Predicted sensors: 8 marker coordinates, then tau1, Fx, Fy, T2."""
        return pendulum_markers(z, p) + list(te[:4])

    @staticmethod
    def z_from_markers(mk, p):
        """z from the four markers (two per bar; seed marker geometry PENDULUM_MARKERS)."""
        out = []
        pts = []
        for bar in (1, 2):
            (_, sa, da), (_, sb, db) = [m for m in PENDULUM_MARKERS if m[0] == bar]
            ia = PENDULUM_MARKERS.index((bar, sa, da))
            ib = PENDULUM_MARKERS.index((bar, sb, db))
            ax, ay = mk[2 * ia], mk[2 * ia + 1]
            bx, by = mk[2 * ib], mk[2 * ib + 1]
            # m_b - m_a = (s_b - s_a) L u + (d_b - d_a) n, n = u rotated by +90 deg
            delta = atan2((db - da) * 1.0, (sb - sa) * p.L)
            alpha = atan2(by - ay, bx - ax) - delta      # direction of u from +x
            theta = alpha + math.pi / 2                  # u = (sin th, -cos th)
            theta = select(theta > math.pi, theta - 2.0 * math.pi, theta)
            pts.append((ax, ay, sa, da, theta))
        (ax, ay, sa, da, t1), (_, _, _, _, t2) = pts
        from kinefuse.codegen.estimators.dynamics.ad import sincos
        s1, c1 = sincos(t1)
        # r0 = m_a - s_a L u - d_a n,  u = (s1, -c1), n = (c1, s1)
        x0 = ax - (sa * p.L) * s1 - da * c1
        y0 = ay + (sa * p.L) * c1 - da * s1
        out = [x0, y0, t1, t2]
        return out

    # -- one step -------------------------------------------------------------------------
    def step(self, x, u, p):
        model, v = self.model, self.variant
        ne, N = len(model.efforts), self.N
        z, zd, te = list(x.z), list(x.zd), list(x.te)
        P = unpack_sym(list(x.P), N)
        dt = u.dt
        dt_ok = all_of(dt > 0.0, dt <= DT_MAX)

        mk = list(u.markers)
        ef = list(u.efforts)
        mk_ok = [all_of(u.marker_valid[i], fabs(mk[2 * i]) <= MARKER_LIM,
                        fabs(mk[2 * i + 1]) <= MARKER_LIM) for i in range(4)]
        ef_ok = [logical_and(u.effort_valid[i], fabs(ef[i]) <= EFFORT_LIM) for i in range(4)]
        n_bad = [logical_and(u.marker_valid[i], logical_not(mk_ok[i])) for i in range(4)] + \
                [logical_and(u.effort_valid[i], logical_not(ef_ok[i])) for i in range(4)]
        rejected = x.rejected
        for b in n_bad:
            rejected = inc_if(rejected, b)
        rejected = inc_if(rejected, logical_and(x.initialised, logical_not(dt_ok)))

        do_init = logical_and(logical_not(x.initialised), all_of(*mk_ok))
        run = logical_and(x.initialised, dt_ok)
        sm, sf, st = p.sigma_marker, p.sigma_force, p.sigma_torque
        rvar = [sm * sm] * 8 + [st * st, sf * sf, sf * sf, st * st]
        use = [mk_ok[i // 2] for i in range(8)] + ef_ok
        ys = mk + ef
        # (conditional regions only save work when they do not run; results are selected)
        with when(run):
            # prediction at the current estimate, then the update at the prior
            zn, zdn, Pp, _ = predict(model, v, z, zd, te, P, self._qdiag(p), p, dt)
            hv, H = measurement_jacobian(self.h_fn, zn, zdn, te, None, None, p)
            innov = [select(use[i], ys[i] - hv[i], 0.0) for i in range(12)]
            xu, Pu, skipped_now = sequential_update(zn + zdn + te, Pp, innov, H, rvar, use)
        with when(do_init):
            # start from a full set of markers: efforts from their sensors, tau1 without its
            # sensor from the static balance
            z0 = self.z_from_markers(mk, p)
            te0 = [select(ef_ok[i], ef[i], 0.0) for i in range(4)] + [0.0] * (ne - 4)
            tau1_static = static_efforts(model, z0, [0.0] * 4, te0, (0,), p)[0]
            te0[0] = select(ef_ok[0], ef[0], tau1_static)
        x_init = z0 + [0.0] * 4 + te0
        P0 = self._p0_diag(p)
        lims = list(Z_LIM) + [ZD_LIM] * 4 + [TE_LIM] * ne
        xs, Pn, init_next, reset_now = start_run_or_hold(
            x.initialised, do_init, run, x_init, P0, xu, Pu, z + zd + te, P, lims, P_LIM)
        skipped_now = logical_and(run, skipped_now)
        skipped = inc_if(x.skipped, skipped_now)
        resets = inc_if(x.resets, reset_now)

        zs, zds, tes = xs[:4], xs[4:8], xs[8:]
        te_std = [sqrt(fmax(Pn[8 + e][8 + e], 0.0)) for e in range(ne)]
        bar_lost = any_of(logical_not(logical_or(mk_ok[0], mk_ok[1])),
                          logical_not(logical_or(mk_ok[2], mk_ok[3])))
        nx = {"z": zs, "zd": zds, "te": tes, "P": pack_sym(Pn), "initialised": init_next,
              "rejected": rejected, "skipped": skipped, "resets": resets}
        y = {"z": zs, "zd": zds, "te": tes, "te_std": te_std, "initialised": init_next,
             "bar_lost": bar_lost, "skipped_now": skipped_now, "reset_now": reset_now,
             "rejected": rejected, "skipped": skipped, "resets": resets}
        return nx, y


class PendulumResidualEKF(PendulumEKF):
    """The double-pendulum EKF with the base residual (Frx, Fry, Mr) at point 0 in T_e
    (15 states, seed 000 §3.3.1): it absorbs what the model cannot explain, with its own
    plant noise."""

    name = "pendulum_res"
    title = "Double-pendulum reduced dynamic EKF with base residual (seed 000)"
    params = _params(True)
    state, outputs = _state_outputs(True)
    residual = True


def pendulum_variant(variant: Variant, residual: bool = False) -> PendulumEKF:
    """A filter instance for one benchmark variant, named pendulum_<variant tag>[_res]."""
    name = f"pendulum_{variant.tag}" + ("_res" if residual else "")
    cls = PendulumResidualEKF if residual else PendulumEKF
    return cls(variant, name=name)


__all__ = ["PendulumEKF", "PendulumResidualEKF", "pendulum_variant", "PENDULUM_INPUT"]
