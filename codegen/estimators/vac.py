"""VAC: Valenti's complementary filter with algebraic correction quaternions and adaptive gain.

R. G. Valenti, I. Dryanovski, J. Xiao, "Keeping a Good Attitude: A Quaternion-Based Orientation
Filter for IMUs and MARGs", Sensors 15(8):19302-19330, 2015 (the filter the `ahrs` package calls
AQUA); seed 001 §5.3.2 ("VAC"), parameters of its §7.4.

One step (sensor → ENU, our convention; Valenti's quaternion is the conjugate):
  1. prediction   q_ω = q + dt/2 · q ⊗ (0, ω), normalised                       (seed eq. 5.2)
  2. accelerometer g_p = q_ω ⊗ â ⊗ q_ω* (predicted up direction, earth frame);
                   Δq_acc = smallest rotation taking g_p to +z;
                   q' = scale(Δq_acc, α) ⊗ q_ω                                  (eqs. 5.14-5.17)
  3. magnetometer  l = q' ⊗ m̂ ⊗ q'* ; Δq_mag = rotation about z taking (l_x, l_y) to north;
                   q = scale(Δq_mag, β) ⊗ q'   — only on samples with a new magnetometer reading
  scale(Δq, g): LERP toward the identity + normalisation when Δq_w > ``slerp_threshold``,
  SLERP otherwise.  The magnetometer only turns the estimate about the vertical, so magnetic
  disturbances never tilt it.
Adaptive gain (seed Fig. 5.2, erratum fixed): e = | |a| − g | / g; α = gain_acc · f(e) with
  f = 1 for e <= t1, (t2 − e)/(t2 − t1) between, 0 above t2 (Valenti's printed (t2 − e)/t1 gives
  1.98 just above t1 with the seed's 0.05/0.15).
Initialisation: from the first valid sample (Valenti's algebraic quaternion); if that sample has
no magnetometer reading the heading is set by the first one that arrives (full correction once).
Not implemented: Valenti's optional gyroscope-bias estimation at rest (the seed does not use it).
Gains are per sample (as published): the same gains give longer time constants at lower rates.
Defaults (ours): α 0.001, β 0.0003, constant gain — time constants of about 3.5 s and 12 s at
BROAD's 285.7 Hz, chosen once on the 12 BROAD trials (at 100 Hz use about 3× these gains);
the adaptive gain lowered the BROAD score there (it stops the tilt correction during long
accelerations and lets gyroscope bias act), so it is off by default and on in the seed preset.
"""
from __future__ import annotations

import math

from kinefuse.codegen.estimator import Estimator, Param, Var
from kinefuse.codegen.estimators.algebraic import (aqua, heading_quaternion, scale_correction,
                                                   tilt_correction, tilt_quaternion)
from kinefuse.codegen.estimators.common import (ACC_NORM_MIN_SQ, IMU, INITIALISED,
                                                MAG_NORM_MIN_SQ, Q_OUT, Q_STATE, REJECTED,
                                                SampleCheck)
from kinefuse.codegen.ir import BOOL
from kinefuse.codegen.linalg import Quat, Vec3, vselect
from kinefuse.codegen.scalar import (all_of, assume, clamp, fabs, fmax, inc_if, logical_and,
                                     logical_not, logical_or, select, sqrt)

# sin² of 5°: below it the field is too close to vertical to define a heading
MIN_FIELD_ANGLE_SIN2 = math.sin(math.radians(5.0)) ** 2

HEADING_SET = Var("heading_set", 1, 0, 1, "",
                  "1 once a magnetometer reading has set the heading", BOOL, init=False)


def adaptive_factor(acc_norm, g, t1, t2):
    """Valenti's gain factor from the relative acceleration-magnitude error e = ||a| − g|/g:
    1 below t1, falling linearly to 0 at t2 (erratum-corrected slope 1/(t2 − t1))."""
    e = fabs(acc_norm - g) / g
    return clamp((t2 - e) / fmax(t2 - t1, 1e-3), 0.0, 1.0)


def canonical(q: Quat) -> Quat:
    """Same rotation with w >= 0."""
    flip = q.w < 0.0
    return Quat(*(select(flip, -c, c) for c in q))


class Vac(Estimator):
    """Valenti's complementary filter (VAC): gyroscope prediction corrected by filtered
    algebraic quaternions, the accelerometer for tilt (adaptive gain) and the magnetometer for
    heading only (see the module docstring for the equations)."""

    name = "vac"
    title = "Valenti complementary filter (AQUA, adaptive gain)"
    inputs = IMU
    params = (
        Param("gain_acc", 0.001, "", 0.0, 1.0,
              "accelerometer correction gain α per accelerometer sample (LERP/SLERP fraction)"),
        Param("gain_mag", 0.0003, "", 0.0, 1.0,
              "magnetometer correction gain β per magnetometer reading"),
        Param.choice("adaptive", 0.0, 2, "1: scale α by the adaptive factor; 0: constant α"),
        Param("t1", 0.1, "", 0.0, 1.0,
              "relative |a| error below which the full α applies (Valenti: 0.1)"),
        Param("t2", 0.2, "", 0.0, 2.0,
              "relative |a| error above which the accelerometer is ignored (Valenti: 0.2)"),
        Param("slerp_threshold", 0.9, "", 0.0, 0.95,
              "LERP when the correction's w component exceeds this, SLERP otherwise (Valenti: 0.9)"),
        Param("gravity", 9.81, "m/s^2", 9.7, 9.9, "local gravity for the adaptive gain"),
    )
    state = (Q_STATE, INITIALISED, HEADING_SET, REJECTED)
    outputs = (Q_OUT, REJECTED)
    presets = {
        # seed 001 §7.4: G_acc 0.01, G_mag 0.001, adaptive gain thresholds 0.05-0.15
        "seed001": {"gain_acc": 0.01, "gain_mag": 0.001, "adaptive": 1.0, "t1": 0.05, "t2": 0.15},
        # Valenti 2015 / the ahrs package's AQUA defaults (constant gains 0.01)
        "valenti2015": {"gain_acc": 0.01, "gain_mag": 0.01, "adaptive": 0.0},
    }

    def step(self, x, u, p):
        chk = SampleCheck(u)
        q = Quat(*x.q)

        # 1. prediction (zero-order integration of q̇ = 1/2 q ⊗ (0, ω))
        q_w = (q + (q * Quat(0.0, *chk.gyr)).scale(0.5 * chk.dt)).normalized()

        # 2. accelerometer correction (tilt only)
        a, a2 = chk.acc.normalized(1e-6)
        g_p = Vec3(*(assume(c, -1.0, 1.0) for c in q_w.rotate(a)))
        dq_acc = tilt_correction(g_p)
        acc_norm = sqrt(fmax(a2, 0.0))
        f = adaptive_factor(acc_norm, p.gravity, p.t1, p.t2)
        alpha = select(p.adaptive > 0.5, p.gain_acc * f, p.gain_acc)
        use_acc = a2 >= ACC_NORM_MIN_SQ
        alpha = select(use_acc, alpha, 0.0)
        q1 = scale_correction(dq_acc, alpha, p.slerp_threshold) * q_w

        # 3. magnetometer correction (heading only), when a reading arrived
        m, m2 = chk.mag.normalized(1e-6)
        l = Vec3(*(assume(c, -1.0, 1.0) for c in q1.rotate(m)))
        dq_mag, gamma = heading_quaternion(l.x, l.y)
        use_mag = all_of(chk.use_mag, m2 >= MAG_NORM_MIN_SQ, gamma >= MIN_FIELD_ANGLE_SIN2)
        beta = select(x.heading_set, p.gain_mag, 1.0)      # the first reading sets the heading
        q2 = vselect(use_mag, scale_correction(canonical(dq_mag), beta, p.slerp_threshold) * q1,
                     q1)
        q_new = q2.normalized()

        # first valid sample: algebraic quaternion (tilt only without a magnetometer reading)
        q_am, _, _, gamma0 = aqua(a, m)
        mag0 = all_of(chk.use_mag, m2 >= MAG_NORM_MIN_SQ, gamma0 >= MIN_FIELD_ANGLE_SIN2)
        q_init = canonical(vselect(mag0, q_am, tilt_quaternion(a)))
        do_init = all_of(chk.ok, logical_not(x.initialised), use_acc)
        run = logical_and(chk.ok, x.initialised)
        q_next = vselect(do_init, q_init, vselect(run, q_new, q))
        heading_next = logical_or(x.heading_set,
                                  logical_or(logical_and(do_init, mag0), logical_and(run, use_mag)))
        rejected = inc_if(x.rejected, chk.bad)
        nx = {"q": q_next, "initialised": logical_or(x.initialised, do_init),
              "heading_set": heading_next, "rejected": rejected}
        return nx, {"q": q_next, "rejected": rejected}
