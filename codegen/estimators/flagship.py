"""kinefuse flagship orientation filter: 6D and 9D orientation, gyroscope bias, rest and magnetic
disturbance status from one update.

Frames: S sensor; I almost-inertial (the gyroscope-only frame); E6 6D earth frame (z up, heading
free); E earth frame East-North-Up, y towards magnetic north.  Units SI (rad, rad/s, m/s^2, s);
the magnetometer in any unit (uT in BROAD): only its direction and relative magnitude are used.

* strapdown: q_i (S -> I) integrates the bias-corrected gyroscope with the two-sample coning
  term and a fourth-order step quaternion; every sample carries its own time step;
* inclination: the specific force is rotated into I and low-pass filtered there.  Linear
  acceleration integrates to a velocity change, so its mean in an inertial frame is small: the
  filtered vector is gravity.  The low-pass is the steady-state Kalman filter of (g, v) -- g the
  gravity in I, a random walk (the drift of I), v the velocity the specific force minus g
  integrates to, observed as zero-mean -- i.e. a second-order Butterworth low-pass of natural
  frequency (q/r)^(1/4).  q grows with the rotation rate (gyroscope scale and misalignment
  errors drift I in proportion to it) and r with the mean-square residual velocity
  (translation), so the time constant is tau_acc when slow and still (VQF's low-pass), shorter
  in fast rotation and longer under translation.  q_a (I -> E6) is corrected so that g points
  up.  Only q_a is corrected, so the low-pass state is never rotated by the filter's own
  corrections;
* heading: one rotation delta about the vertical (stored as (cos, sin) of delta/2) from the
  horizontal magnetic field, so the magnetometer never touches inclination.  A scalar Kalman
  filter sets the gain: the heading variance grows with time and shrinks with each accepted
  sample; tau_mag is the steady-state time constant.  After the start or a disturbance the
  variance is large and the heading converges quickly;
* magnetic disturbance: the field magnitude and dip (through a short noise low-pass) are compared
  with a learnt reference; a disagreement implausible for the heading variance is also rejected.
  A new field that stays consistent for mag_new_time while the sensor rotates becomes the
  reference; no rejection (field tests or gate) lasts longer than mag_reject_time: then the
  current field is adopted and an implausible heading is re-initialised from the reading.  The
  heading correction is an exact rotation for any disagreement (half-way quaternion), so any
  start converges;
* gyroscope bias: at rest (gyroscope and accelerometer still for rest_time) a Kalman update
  towards the low-pass gyroscope, whatever the orientation; in motion the inclination correction
  and (9D) the accepted heading correction feed an integral term whose gain follows the bias
  variance, so every component converges once the orientation varies.

One float32 (or fixed-point) update, no double-precision state, no division by a sample's
value that could be zero.  Outputs q (9D or 6D by mode), q6 and q9 from the same run, and the
status rest, mag_disturbed, rejected, bias.  Parameters have physical units and one default set
(VQF's published time constants and thresholds where the concept is the same).  Magnetometer
work, the first-sample alignment and the two bias paths are conditional regions (cost only).
"""
from __future__ import annotations

import math

from kinefuse.codegen.estimator import Estimator, Param, Var
from kinefuse.codegen.estimators.common import (ACC_MAX, ACC_NORM_MIN_SQ, DT_MAX, GYR_MAX, IMU,
                                                INITIALISED, MAG_MAX, REJECTED)
from kinefuse.codegen.ir import BOOL
from kinefuse.codegen.linalg import Quat, Vec3, vselect
from kinefuse.codegen.scalar import (all_of, any_of, assume, bound, clamp, fabs, fmax, fmin,
                                     inc_if, logical_and, logical_not, logical_or, rnorm, rsqrt,
                                     select, sqrt, when)

DEG = math.pi / 180.0
T_SAT = 1.0e4              # s; timers saturate here
BIAS_LIM = 10.0 * DEG      # rad/s; range of the bias state (bias_max cannot exceed it)
P_BIAS_MAX = (5.0 * DEG) ** 2
P_HEAD_MAX = 4.0           # rad^2; heading variance ceiling (about 115 deg)
N_MAX = 2.0 * MAG_MAX      # magnetometer magnitude range (any unit up to the input range)
LP_MAX = 2.0 * ACC_MAX     # m/s^2; range of the filtered specific force
V_MAX = 20.0               # m/s; range of the residual velocity of the inclination filter
RATIO_MAX = 1.0e4          # bound of each term of the adaptation ratio (time constant x/ 10)
STEP_MAX = 2.0             # rad; largest rotation accepted in one step (per axis)
UNIT = (-1.0, 1.0)


def _unit(v):
    """Components of a vector known to have unit length (or less)."""
    return Vec3(*(assume(c, *UNIT) for c in v))


def _strict_within(v, limit):
    """Every component finite and strictly inside +-limit (a value at full scale is saturated)."""
    return all_of(*(fabs(c) < limit for c in v))


def _clamp3(v, lo, hi, op=clamp):   # op=bound: a clamp for the range analysis only
    return Vec3(*(op(c, lo, hi) for c in v))


def _renorm(q: Quat) -> Quat:
    """q / |q|: one Newton step q (3 - |q|^2) / 2 when |q|^2 is within 1e-3 of 1 (no square
    root; the error is 3/8 of the squared deviation, < 4e-7), else (only after extreme steps)
    the exact 1/sqrt in a conditional region."""
    n2 = q.norm_sq()
    far = fabs(n2 - 1.0) > 1e-3
    with when(far):
        k_far = rsqrt(fmax(n2, 0.25))
    k = select(far, k_far, 1.5 - 0.5 * n2)
    return Quat(*(assume(c * k, -1.0, 1.0) for c in q))


def _fld(n, d):
    """A field record (magnitude, horizontal part, vertical part of the direction)."""
    return Vec3(n, d[0], d[1])


def _unfld(name, f):
    """State entries of a field record (bound: mixes of readings within the ranges)."""
    return {f"{name}_n": bound(f[0], 0.0, N_MAX),
            f"{name}_d": (bound(f[1], -1.0, 1.0), bound(f[2], -1.0, 1.0))}


class Flagship(Estimator):
    """kinefuse flagship orientation filter (6D + 9D, bias, rest, magnetic disturbance).

    Inputs: gyroscope rad/s, accelerometer m/s^2 (+g up at rest), magnetometer (any unit, uT
    in BROAD), mag_valid, per-sample dt in s.  Outputs, all sensor -> East-North-Up: q (9D when
    mode = 1, else 6D), q6 (inclination from the accelerometer, heading from the gyroscope only),
    q9 (heading from the magnetometer; equals q6 in mode 0); status rest, mag_disturbed,
    rejected (samples or sensor readings), bias (rad/s, sensor frame).
    """

    name = "flagship"
    gyro_only_on_bad_acc = True   # a saturated accelerometer: gyroscope-only step
    title = "kinefuse flagship orientation filter"
    inputs = IMU
    params = (
        Param.choice("mode", 1.0, 2, "0: 6D (magnetometer ignored), 1: 9D; q6 and q9 are "
                     "output in both", labels=("6d", "9d")),
        Param("tau_acc", 3.0, "s", 0.5, 20.0,
              "inclination time constant when rotating slowly without translation: DC group "
              "delay of the accelerometer low-pass filter in the almost-inertial frame"),
        Param("tau_mag", 20.0, "s", 1.0, 60.0,
              "steady-state time constant of the heading correction (longer than VQF's 9 s: "
              "the bias estimation keeps the gyroscope's heading drift small, and a long "
              "average rejects the field's spatial inhomogeneity indoors)"),
        Param("heading_rw", 0.2 * DEG, "rad/s^0.5", 0.01 * DEG, 5.0 * DEG,
              "heading random walk between magnetometer corrections (gyroscope bias residual)"),
        Param("tau_bias", 40.0, "s", 5.0, 1000.0,
              "time constant of the gyroscope bias estimation in motion while the bias is "
              "unknown (it slows down as the bias variance shrinks)"),
        Param("bias_sigma_init", 0.5 * DEG, "rad/s", 0.01 * DEG, 5.0 * DEG,
              "standard deviation of the bias before any estimate (and its ceiling)"),
        Param("bias_forget_time", 1000.0, "s", 1.0, 10000.0,
              "time in which the bias variance grows back to bias_sigma_init^2 (bias "
              "instability)"),
        Param("bias_sigma_rest", 0.03 * DEG, "rad/s", 0.001 * DEG, 1.0 * DEG,
              "noise of one low-pass filtered gyroscope sample used as the bias at rest"),
        Param("bias_max", 2.0 * DEG, "rad/s", 0.1 * DEG, BIAS_LIM,
              "largest bias accepted: the estimate is clipped, and a low-pass rate above it is "
              "never taken for rest"),
        Param("rest_th_gyr", 2.0 * DEG, "rad/s", 0.1 * DEG, 20.0 * DEG,
              "rest: largest deviation of the gyroscope from its low-pass value"),
        Param("rest_th_acc", 0.5, "m/s^2", 0.05, 5.0,
              "rest: largest deviation of the accelerometer from its low-pass value"),
        Param("rest_time", 1.5, "s", 0.1, 30.0, "rest: time the conditions must hold"),
        Param("tau_rest", 0.5, "s", 0.05, 5.0, "time constant of the rest-detection low-pass"),
        Param("tau_mag_noise", 0.05, "s", 0.001, 5.0,
              "time constant of the low-pass through which the disturbance tests see the field"),
        Param("mag_th", 0.1, "", 0.01, 1.0,
              "magnetic disturbance: largest deviation of the field magnitude from the "
              "reference, relative to it"),
        Param("mag_dip_th", math.sin(10.0 * DEG), "", 0.01, 1.0,
              "magnetic disturbance: largest sine of the dip difference from the reference "
              "(sin 10 deg)"),
        Param("mag_gate", 4.0, "", 1.0, 100.0,
              "heading disagreements beyond this many standard deviations are rejected"),
        Param("mag_sigma_gate", 10.0 * DEG, "rad", 0.1 * DEG, 90.0 * DEG,
              "standard deviation of one magnetometer heading (noise, calibration) in the gate"),
        Param("tau_mag_ref", 20.0, "s", 1.0, 600.0,
              "time constant of learning the reference (and candidate) field"),
        Param("mag_new_time", 20.0, "s", 1.0, 600.0,
              "a new field that stays consistent this long while the sensor rotates becomes "
              "the reference"),
        Param("mag_new_min_rate", 20.0 * DEG, "rad/s", 0.0, 360.0 * DEG,
              "rotation rate that counts as rotating for the new-field test"),
        Param("mag_reject_time", 60.0, "s", 1.0, 3600.0,
              "longest rejection: afterwards the current field becomes the reference"),
        Param("mag_min_undisturbed", 0.5, "s", 0.0, 10.0,
              "time the field must be undisturbed before heading corrections resume"),
        Param("gyr_range", GYR_MAX, "rad/s", 0.1, GYR_MAX,
              "gyroscope full scale: a sample at or beyond it is saturated and rejected"),
        Param("acc_range", ACC_MAX, "m/s^2", 1.0, ACC_MAX,
              "accelerometer full scale: a saturated sample is not used (gyroscope only)"),
        Param("incl_rate_ref", 0.9, "rad/s", 0.05, 30.0,
              "rotation rate at which the inclination time constant has shortened by 2^(1/4): "
              "gyroscope scale and misalignment errors drift the inertial frame in proportion "
              "to the rate, so faster rotation needs a faster inclination correction"),
        Param("incl_vel_ref", 0.2, "m/s", 0.01, 10.0,
              "residual velocity (RMS per axis) at which the inclination time constant has "
              "lengthened by 2^(1/4): under translation the accelerometer is trusted less"),
        Param("tau_vel", 2.0, "s", 0.1, 60.0,
              "time constant of the mean-square residual velocity"),
        Param("mag_rate_max", 100.0, "Hz", 1.0, 10000.0,
              "magnetometer readings are used at most this often (a faster magnetometer costs "
              "time, not accuracy: the heading time constant is seconds)"),
    )
    state = (
        Var("q_i", 4, -1.0, 1.0, "", "strapdown orientation, sensor -> almost-inertial frame",
            init=(1.0, 0.0, 0.0, 0.0)),
        Var("q_a", 4, -1.0, 1.0, "", "inclination correction, almost-inertial -> 6D earth",
            init=(1.0, 0.0, 0.0, 0.0)),
        Var("hd", 2, -1.0, 1.0, "", "heading correction (cos, sin) of delta/2: 6D -> 9D earth",
            init=(1.0, 0.0)),
        Var("bias", 3, -BIAS_LIM, BIAS_LIM, "rad/s", "gyroscope bias, sensor frame",
            init=(0.0, 0.0, 0.0)),
        Var("p_bias", 1, 0.0, P_BIAS_MAX, "(rad/s)^2", "bias variance (each axis)",
            init=(0.5 * DEG) ** 2),
        Var("lp_x", 3, -LP_MAX, LP_MAX, "m/s^2", "low-pass filtered specific force (gravity), "
            "frame I", init=(0.0, 0.0, 0.0)),
        Var("vel", 3, -V_MAX, V_MAX, "m/s", "residual velocity of the inclination filter, frame I",
            init=(0.0, 0.0, 0.0)),
        Var("vel_mean", 3, -V_MAX, V_MAX, "m/s", "low-pass of the residual velocity, frame I",
            init=(0.0, 0.0, 0.0)),
        Var("vel_ms", 1, 0.0, 4.0 * V_MAX * V_MAX, "(m/s)^2",
            "variance of the residual velocity per axis (low-pass)", init=0.0),
        Var("th_prev", 3, -STEP_MAX, STEP_MAX, "rad",
            "previous rotation increment (coning term)", init=(0.0, 0.0, 0.0)),
        Var("rest_gyr", 3, -GYR_MAX, GYR_MAX, "rad/s", "rest detection: gyroscope low-pass",
            init=(0.0, 0.0, 0.0)),
        Var("rest_acc", 3, -ACC_MAX, ACC_MAX, "m/s^2", "rest detection: accelerometer low-pass",
            init=(0.0, 0.0, 0.0)),
        Var("rest_t", 1, 0.0, T_SAT, "s", "time the rest conditions have held", init=0.0),
        Var("p_head", 1, 0.0, P_HEAD_MAX, "rad^2", "heading variance", init=P_HEAD_MAX),
        Var("dt_lp", 1, 0.0, DT_MAX, "s", "usual sample period (low-pass of the time steps)",
            init=0.0),
        Var("t_skip", 1, 0.0, DT_MAX, "s", "time of the rejected readings since the last "
            "regular step (bridged by the next one)", init=0.0),
        Var("dt_prev", 1, 0.0, DT_MAX, "s", "time step of the previous regular step (0: none)",
            init=0.0),
        Var("t_mag", 1, 0.0, 2.0 * DT_MAX, "s", "time since the previous magnetometer sample",
            init=0.0),
        Var("cur_n", 1, 0.0, N_MAX, "", "current field through the noise low-pass: magnitude (input unit)", init=0.0),
        Var("cur_d", 2, -1.0, 1.0, "", "current field through the noise low-pass: horizontal and vertical (up) parts of its "
            "direction", init=(0.0, 0.0)),
        Var("ref_n", 1, 0.0, N_MAX, "", "reference field: magnitude (input unit)", init=0.0),
        Var("ref_d", 2, -1.0, 1.0, "", "reference field: horizontal and vertical (up) parts of its "
            "direction", init=(0.0, 0.0)),
        Var("cand_n", 1, 0.0, N_MAX, "", "candidate new field: magnitude (input unit)", init=0.0),
        Var("cand_d", 2, -1.0, 1.0, "", "candidate new field: horizontal and vertical (up) parts of its "
            "direction", init=(0.0, 0.0)),
        Var("ref_t", 1, 0.0, T_SAT, "s", "time the reference has been learnt (0: none)",
            init=0.0),
        Var("cand_t", 1, 0.0, T_SAT, "s", "time the candidate has been consistent in rotation",
            init=0.0),
        Var("dist_t", 1, 0.0, T_SAT, "s", "rejection time (decays twice as fast when accepted)",
            init=0.0),
        Var("undist_t", 1, 0.0, T_SAT, "s", "time the field has been undisturbed", init=0.0),
        Var("mag_flag", 1, 0, 1, "", "the last magnetometer reading was rejected", BOOL,
            init=False),
        INITIALISED,
        REJECTED,
    )
    outputs = (
        Var("q", 4, -1.0, 1.0, "", "orientation sensor -> ENU: q9 in 9D mode, q6 in 6D mode"),
        Var("q6", 4, -1.0, 1.0, "", "6D orientation (heading from the gyroscope only)"),
        Var("q9", 4, -1.0, 1.0, "", "9D orientation (heading from the magnetometer)"),
        Var("rest", 1, 0, 1, "", "1 while the sensor is at rest", BOOL),
        Var("mag_disturbed", 1, 0, 1, "", "1 while the magnetic field is rejected", BOOL),
        Var("rejected", 1, 0, 2 ** 31 - 1, "samples",
            "samples or sensor readings rejected as non-finite, saturated or out of range",
            REJECTED.type),
        Var("bias", 3, -BIAS_LIM, BIAS_LIM, "rad/s", "gyroscope bias estimate, sensor frame"),
    )

    def step(self, x, u, p):
        nine = p.mode > 0.5
        # -- sample validation; clamped copies keep every intermediate bounded --------------
        gyr_ok = all_of(_strict_within(u.gyr, p.gyr_range), u.dt > 0.0, u.dt <= DT_MAX)
        acc_fine = _strict_within(u.acc, p.acc_range)
        mag_fine = all_of(*(fabs(c) <= MAG_MAX for c in u.mag))
        bad = any_of(logical_not(gyr_ok), logical_not(acc_fine),
                     logical_and(u.mag_valid, logical_not(mag_fine)))
        gyr = _clamp3(Vec3(*u.gyr), -GYR_MAX, GYR_MAX)
        acc = _clamp3(Vec3(*u.acc), -ACC_MAX, ACC_MAX)
        mag = _clamp3(Vec3(*u.mag), -MAG_MAX, MAG_MAX)

        # the first sample with a usable accelerometer initialises the filter: the same update
        # then runs from identity with dt = 0 and the low-pass state set to this sample, which
        # aligns gravity exactly; the first magnetometer reading sets the heading exactly
        acc_ok = logical_and(gyr_ok, acc_fine)
        do_init = all_of(acc_ok, logical_not(x.initialised),
                         acc.norm_sq() >= ACC_NORM_MIN_SQ)
        live = logical_or(x.initialised, do_init)
        run = logical_and(gyr_ok, x.initialised)        # a regular step
        acc_ok = logical_and(acc_ok, live)
        mag_ok = all_of(gyr_ok, live, nine, u.mag_valid, mag_fine)
        # a rejected reading leaves a gap: its time (one usual period when its own time step
        # is unusable; none for a duplicate, dt = 0) is bridged by the next regular step
        dt_lp = select(do_init, 0.0, x.dt_lp)
        dt_in_ok = logical_and(u.dt > 0.0, u.dt <= DT_MAX)
        dup = logical_and(u.dt >= 0.0, u.dt <= 0.0)
        skipped = select(dt_in_ok, clamp(u.dt, 0.0, DT_MAX), select(dup, 0.0, dt_lp))
        dt = select(run, fmin(clamp(u.dt, 0.0, DT_MAX) + x.t_skip, DT_MAX), 0.0)
        t_skip_new = select(run, 0.0, select(x.initialised, fmin(x.t_skip + skipped, DT_MAX),
                                             0.0))
        # a magnetometer reading is used at most mag_rate_max times a second (10 % jitter
        # allowed): a faster magnetometer adds cost, not information, to a heading filter whose
        # time constant is seconds; the first reading is always used
        t_mag = fmin(x.t_mag + dt, 2.0 * DT_MAX)         # time since the last reading used
        mag_due = logical_or(t_mag * p.mag_rate_max >= 0.9, logical_not(x.initialised))
        use_mag = logical_and(mag_ok, mag_due)

        one = Quat(1.0, 0.0, 0.0, 0.0)
        zero3 = Vec3(0.0, 0.0, 0.0)
        q_i = vselect(do_init, one, Quat(*x.q_i))
        q_a = vselect(do_init, one, Quat(*x.q_a))
        lp_x = vselect(do_init, acc, Vec3(*x.lp_x))
        vel = vselect(do_init, zero3, Vec3(*x.vel))
        vel_mean = vselect(do_init, zero3, Vec3(*x.vel_mean))
        vel_ms = select(do_init, 0.0, x.vel_ms)
        th_prev = vselect(do_init, zero3, Vec3(*x.th_prev))
        hw = select(do_init, 1.0, x.hd[0])
        hz = select(do_init, 0.0, x.hd[1])
        bias = Vec3(*x.bias)
        w = gyr - bias                                   # rad/s, sensor frame

        # -- strapdown ----------------------------------------------------------------------
        # rotation vector of the step: theta plus the two-sample coning term theta_prev x theta / 12
        # A step longer than twice the usual period means samples were lost: the rotation in the
        # missing time is integrated with the mean of the rates before and after the gap
        # (trapezoid) instead of the rate after it, which is second-order accurate where the
        # rectangle is first-order (a 0.5 s gap while the rate rose from 1.1 to 2.0 rad/s: 24 deg
        # of error with the rate after it).
        # The rate before is theta_prev / dt_prev (the usual period dt_lp is not settled in the
        # first second, when every step looks long against it).
        dt_prev = select(do_init, 0.0, x.dt_prev)
        gap = logical_and(dt_prev > 0.0, dt > 2.0 * dt_prev)
        with when(gap):
            w_before = _clamp3(th_prev * (1.0 / fmax(dt_prev, 1e-4)), -GYR_MAX, GYR_MAX)
            w_gap = (w + w_before) * 0.5
        theta = _clamp3(vselect(gap, w_gap, w) * dt, -STEP_MAX, STEP_MAX)
        phi = theta + th_prev.cross(theta) * (1.0 / 12.0)
        # a step beyond 2 rad (only with dt near its 1 s limit) is scaled to 2 rad, so the step
        # quaternion below stays near unit norm and the Newton renormalisation holds
        phi2 = phi.norm_sq()
        huge = phi2 > 4.0
        with when(huge):
            k_step = 2.0 * rsqrt(fmax(phi2, 4.0))
        phi = vselect(huge, phi * k_step, phi)
        th2 = fmin(phi2, 4.0)
        # (cos(a/2), sin(a/2)/a * phi) to fourth order in the angle a (error ~ a^5 / 480);
        # its norm is 1 - a^4/192, so one Newton step renormalises the product
        s0 = 0.5 - th2 * (1.0 / 48.0)
        dq = Quat(1.0 - 0.125 * th2, s0 * phi.x, s0 * phi.y, s0 * phi.z)
        q_i_new = vselect(run, _renorm(q_i * dq), q_i)   # a rejected step keeps it bit for bit

        # -- inclination ----------------------------------------------------------------------
        # gravity in frame I (the module doc): predict v += (a - g) dt, then the steady-state
        # gains of the zero-velocity pseudo-measurement, g += dt wn^2 v, v -= dt sqrt(2) wn v,
        # with wn^4 = wn0^4 (1 + |w|^2 / rate_ref^2) / (1 + <v^2> / vel_ref^2) and
        # wn0 = sqrt(2) / tau_acc (damping 1/sqrt(2), DC group delay sqrt(2)/wn)
        a_i = Vec3(*(assume(c, -ACC_MAX * 1.7321, ACC_MAX * 1.7321)
                     for c in q_i_new.rotate(acc)))
        vel_p = _clamp3(vel + (a_i - lp_x) * dt, -V_MAX, V_MAX)
        # the variance, not the mean square: a tilt error makes v grow steadily in one
        # direction (a mean), translation makes it oscillate; only the latter must lengthen
        # the time constant, or a large error would slow its own correction
        k_vel = fmin(dt / p.tau_vel, 1.0)
        vel_mean_new = _clamp3(vel_mean + (vel_p - vel_mean) * k_vel, -V_MAX, V_MAX, bound)
        vel_dev = vel_p - vel_mean_new
        vel_ms_new = clamp(vel_ms + (vel_dev.norm_sq() * (1.0 / 3.0) - vel_ms) * k_vel,
                           0.0, 4.0 * V_MAX * V_MAX)
        rate_term = fmin(w.norm_sq() * (1.0 / (p.incl_rate_ref * p.incl_rate_ref)), RATIO_MAX)
        # at rest the velocity is zero whatever v says: no lengthening (the last step's rest
        # state; a large initial error would otherwise look like translation)
        was_rest = x.rest_t >= p.rest_time
        # a velocity that persists in one direction is not translation (nobody keeps moving
        # one way in a room): it is the tilt error itself, so its mean power is discounted
        vel_osc = fmax(vel_ms_new - vel_mean_new.norm_sq() * (1.0 / 3.0), 0.0)
        vel_term = select(was_rest, 0.0,
                          fmin(vel_osc * (1.0 / (p.incl_vel_ref * p.incl_vel_ref)), RATIO_MAX))
        ratio = assume((1.0 + rate_term) / (1.0 + vel_term), 1.0 / (1.0 + RATIO_MAX),
                       1.0 + RATIO_MAX)
        s4 = assume(sqrt(sqrt(ratio)), 0.09, 10.01)      # wn / wn0, in [0.1, 10]
        inv_tau = 1.0 / p.tau_acc
        kv = fmin(2.0 * dt * inv_tau * s4, 1.0)          # dt sqrt(2) wn
        kx = fmin(kv * s4 * inv_tau, 1.0)                # dt wn^2
        lp_x_new = _clamp3(lp_x + vel_p * kx, -LP_MAX, LP_MAX)
        lp_v_new = _clamp3(vel_p * (1.0 - kv), -V_MAX, V_MAX, bound)   # |.| <= |vel_p|
        g_e = Vec3(*(assume(c, -LP_MAX * 1.7321, LP_MAX * 1.7321)
                     for c in q_a.rotate(lp_x_new)))
        gh, _ = g_e.normalized(1e-6)
        # the correction rotates the filtered direction onto +z.  Running: the small-angle
        # quaternion (1, gy/2, -gx/2, 0) (a step turns it by ~1e-4 rad: exact to third order)
        # and a Newton renormalisation; exactly upside down any horizontal axis will do (x);
        # large corrections converge over a few steps.  First sample: the exact half-way
        # quaternion (1 + gz, gy, -gx, 0) / |.| (a conditional region, cost only)
        flip = logical_and(gh.z < 0.0, fabs(gh.x) + fabs(gh.y) < 1e-3)
        gy_f = select(flip, 1e-3, gh.y)
        q_a_run = _renorm(Quat(1.0, 0.5 * gy_f, -0.5 * gh.x, 0.0) * q_a)
        with when(do_init):
            q_a_first = Quat(fmax(1.0 + gh.z, 1e-9), gy_f, -gh.x, 0.0).normalized(1e-12)
        q_a_new = vselect(acc_ok, vselect(do_init, q_a_first, q_a_run), q_a)
        lp_x_new = vselect(acc_ok, lp_x_new, lp_x)
        lp_v_new = vselect(acc_ok, lp_v_new, vel)
        vel_ms_new = select(acc_ok, vel_ms_new, vel_ms)
        vel_mean_new = vselect(acc_ok, vel_mean_new, vel_mean)
        q6 = q_a_new * q_i_new                           # product of unit quaternions
        # this step's correction (rad, E6 frame; sin of the angle): input of the bias estimation
        # (a bias of at most bias_max turns the frame by bias_max dt per step: a larger
        # correction is not drift and is limited to that here)
        c_max = p.bias_max * dt
        theta_c = vselect(logical_and(acc_ok, run),
                          Vec3(clamp(gh.y, -c_max, c_max), clamp(-gh.x, -c_max, c_max), 0.0),
                          zero3)

        # -- rest detection -------------------------------------------------------------------
        k_rest = fmin(dt / p.tau_rest, 1.0)
        rest_gyr = vselect(do_init, gyr, Vec3(*x.rest_gyr) + (gyr - Vec3(*x.rest_gyr)) * k_rest)
        rest_acc = vselect(do_init, acc, Vec3(*x.rest_acc) + (acc - Vec3(*x.rest_acc)) * k_rest)
        dev_g = _clamp3(gyr - rest_gyr, -1.0, 1.0).norm_sq()     # thresholds are below 1
        dev_a = _clamp3(acc - rest_acc, -10.0, 10.0).norm_sq()   # thresholds are below 10
        still = all_of(acc_ok, dev_g < p.rest_th_gyr * p.rest_th_gyr,
                       dev_a < p.rest_th_acc * p.rest_th_acc,
                       *(fabs(c) < p.bias_max for c in rest_gyr))
        rest_t = select(still, fmin(x.rest_t + dt, T_SAT), select(run, 0.0, x.rest_t))
        rest = rest_t >= p.rest_time
        rest_acc = vselect(acc_ok, rest_acc, Vec3(*x.rest_acc))

        # -- magnetometer --------------------------------------------------------------------
        # the heading variance grows every step (random walk: gyroscope bias residual); the
        # rest runs only with a reading (a conditional region: cost only, never results)
        # a step longer than twice the usual period means samples were lost: the rotation in
        # the missing time was integrated from one reading, so its variance (|w| t_missing)^2
        # is added (the heading then re-converges quickly after a gap)
        t_missing = assume(fmax(dt - 2.0 * dt_lp, 0.0), 0.0, DT_MAX)
        gap_var = fmin(w.norm_sq(), 4.0) * (t_missing * t_missing)
        dt_lp_new = select(run, dt_lp + (dt - dt_lp) * fmin(dt, 1.0), dt_lp)
        p_head_pred = select(do_init, P_HEAD_MAX,
                             fmin(x.p_head + p.heading_rw * p.heading_rw * dt + gap_var,
                                  P_HEAD_MAX))
        cur_old = _fld(x.cur_n, x.cur_d)
        cand_old = _fld(x.cand_n, x.cand_d)
        ref = _fld(x.ref_n, x.ref_d)
        with when(use_mag):
            # -- magnetometer: heading disagreement ------------------------------------------------
            r_m, _ = rnorm(mag, 1e-6)
            m_unit = _unit(mag * r_m)
            m_norm = assume(m_unit.dot(mag), 0.0, MAG_MAX * 1.7321)   # |m| in the input's unit
            m_e = _unit(q6.rotate(m_unit))                   # direction in the 6D earth frame
            cd = hw * hw - hz * hz                           # cos(delta)
            sd = 2.0 * hw * hz                               # sin(delta)
            mx = assume(cd * m_e.x - sd * m_e.y, *UNIT)      # ... in the 9D earth frame
            my = assume(sd * m_e.x + cd * m_e.y, *UNIT)
            rh, h2 = rnorm((mx, my), 1e-9)
            h_u = assume(h2 * rh, 0.0, 1.0)                  # horizontal part of the direction
            v_u = m_e.z                                      # vertical part (up)
            # horizontal field direction in the 9D frame: (sin, cos) of the heading disagreement
            # (field east of north > 0); north means ex = 0, ey = 1
            ex = assume(mx * rh, *UNIT)
            ey = assume(my * rh, *UNIT)

            # -- magnetometer: disturbance --------------------------------------------------------
            k_cur = select(do_init, 1.0, fmin(t_mag / p.tau_mag_noise, 1.0))
            cur = cur_old + (Vec3(m_norm, h_u, v_u) - cur_old) * k_cur
            c_n, c_h, c_v = cur

            def field_off(fld):
                """Magnitude beyond mag_th, or dip (sin of the difference) beyond mag_dip_th."""
                n_ref, h_ref, v_ref = fld
                norm_off = fabs(c_n - n_ref) > p.mag_th * n_ref
                dip_off = fabs(c_h * v_ref - c_v * h_ref) > p.mag_dip_th
                return logical_or(norm_off, dip_off)

            has_ref = logical_and(x.ref_t > 0.0, logical_not(do_init))
            disturbed_now = all_of(use_mag, has_ref, field_off(_fld(x.ref_n, x.ref_d)))

            # the gate compares the disagreement with the heading variance
            p_head = p_head_pred
            gate_var = p.mag_gate * p.mag_gate * (p_head + p.mag_sigma_gate * p.mag_sigma_gate)
            implausible = logical_or(ey < 0.0, ex * ex > gate_var)

            # candidate: a new field that stays consistent while the sensor rotates is a real
            # (homogeneous) field, not a disturbance moving with the sensor or passing by
            cand_off = logical_or(do_init, field_off(cand_old))
            rotating = rest_gyr.norm_sq() >= p.mag_new_min_rate * p.mag_new_min_rate
            k_cand = fmin(t_mag / p.tau_mag_ref, 1.0)
            cand = vselect(cand_off, cur, cand_old + (cur - cand_old) * k_cand)
            cand_t = select(cand_off, 0.0, select(rotating, fmin(x.cand_t + t_mag, T_SAT), x.cand_t))

            # rejection (field tests or gate) is bounded: the rejection time grows while readings
            # are rejected and decays twice as fast while they are accepted (noise at a threshold
            # does not restart the bound); at mag_reject_time the candidate field is adopted and an
            # implausible heading is re-initialised from the reading
            settled = logical_or(x.undist_t >= p.mag_min_undisturbed, logical_not(has_ref))
            h_first = logical_and(use_mag, logical_not(has_ref))
            rejected_now = all_of(use_mag, has_ref, logical_or(
                disturbed_now, logical_and(settled, implausible)))
            dist_t = select(rejected_now, fmin(x.dist_t + t_mag, T_SAT),
                            fmax(x.dist_t - 2.0 * t_mag, 0.0))
            undist_t = select(disturbed_now, 0.0, fmin(x.undist_t + t_mag, T_SAT))
            give_up = logical_and(rejected_now, dist_t >= p.mag_reject_time)
            adopt = logical_or(logical_and(disturbed_now, cand_t >= p.mag_new_time), give_up)
            reset_head = logical_or(h_first, logical_and(give_up, implausible))
            accept = logical_and(use_mag, any_of(
                all_of(logical_not(disturbed_now), settled, logical_not(implausible)),
                give_up, h_first))
            mag_disturbed = logical_and(nine, logical_or(
                rejected_now, logical_and(has_ref, logical_not(settled))))

            # -- heading update: R_c = heading_rw^2 tau_mag^2 (noise density) makes tau_mag the
            # steady-state time constant; a sample covering t_mag seconds has variance R_c / t_mag
            r_c = p.heading_rw * p.heading_rw * p.tau_mag * p.tau_mag
            # when a bounded rejection ends, the heading has gone uncorrected for a long time:
            # its variance is at least the disagreement seen (sin^2), so a plausible but large
            # disagreement is corrected in seconds, not at the steady-state time constant
            p_head = select(give_up, fmax(p_head, fmin(ex * ex, P_HEAD_MAX)), p_head)
            pt = p_head * t_mag
            k_head = select(reset_head, 1.0,
                            select(accept, assume(pt / fmax(pt + r_c, 1e-12), 0.0, 1.0), 0.0))
            # the disagreement as a rotation about the vertical: the half-way quaternion
            # (1 + ey, ex) / |.| = (cos, sin) of half the angle, exact for any angle; a fraction
            # k_head of it (normalised linear blend with the identity) is applied
            # (exactly south: the sense of the half turn is free; +z is taken)
            ex_s = select(logical_and(ey < 0.0, fabs(ex) < 1e-3), 1e-3, ex)
            rf, _ = rnorm((fmax(1.0 + ey, 1e-9), ex_s), 1e-12)
            fw = assume(fmax(1.0 + ey, 1e-9) * rf, 0.0, 1.0)
            fz = assume(ex_s * rf, *UNIT)
            cw = 1.0 - k_head + k_head * fw
            cz = k_head * fz
            hw_n = cw * hw - cz * hz                         # (cw, cz) (x) (hw, hz), about z
            hz_n = cw * hz + cz * hw
            rn, _ = rnorm((hw_n, hz_n), 1e-6)
            hd_new = (assume(hw_n * rn, *UNIT), assume(hz_n * rn, *UNIT))
            d_head = 2.0 * cz                                # rad (small angles), for the bias
            p_head = select(reset_head, P_HEAD_MAX,
                            select(accept, (1.0 - k_head) * p_head, p_head))

            # reference: learnt while accepted (1/N at first, then tau_mag_ref), or adopted
            ref_t = select(accept, fmin(x.ref_t + t_mag, T_SAT), x.ref_t)
            k_ref = fmin(t_mag * (1.0 / fmax(fmin(ref_t, p.tau_mag_ref), 1e-3)), 1.0)
            ref_new = vselect(h_first, cur, vselect(adopt, cand, vselect(
                logical_and(accept, has_ref), ref + (cur - ref) * k_ref, ref)))
            ref_t = select(logical_or(h_first, adopt), fmax(ref_t, 1e-3), ref_t)
            dist_t = select(give_up, 0.0, dist_t)
            undist_t = select(logical_or(adopt, h_first), p.mag_min_undisturbed, undist_t)

        hd_new = (select(use_mag, hd_new[0], hw), select(use_mag, hd_new[1], hz))
        d_head = select(use_mag, d_head, 0.0)
        p_head = select(use_mag, p_head, p_head_pred)
        mag_flag = select(use_mag, mag_disturbed, x.mag_flag)

        # -- gyroscope bias -------------------------------------------------------------------
        p0 = p.bias_sigma_init * p.bias_sigma_init
        p_bias = fmin(x.p_bias + p0 * (dt / p.bias_forget_time), p0)
        use_rest = logical_and(rest, run)
        with when(use_rest):
            # at rest: Kalman update towards the low-pass gyroscope (every orientation)
            r_rest = p.bias_sigma_rest * p.bias_sigma_rest
            k_b = assume(p_bias / (p_bias + r_rest), 0.0, 1.0)
            b_rest = bias + (rest_gyr - bias) * k_b
            p_rest = (1.0 - k_b) * p_bias
        with when(logical_not(use_rest)):
            # in motion: integral of the corrections (E6 frame) in the sensor frame; the gain
            # is 1/tau_bias while the bias is unknown and shrinks with its variance
            g_m = assume(p_bias / p0, 0.0, 1.0) * (1.0 / p.tau_bias)
            corr_s = q6.rotate_inv(Vec3(theta_c.x, theta_c.y, select(run, d_head, 0.0)))
            b_motion = bias - corr_s * g_m
        bias_new = _clamp3(vselect(use_rest, b_rest, b_motion), -p.bias_max, p.bias_max)
        p_bias = select(use_rest, p_rest, p_bias)

        q9 = Quat(hd_new[0], 0.0, 0.0, hd_new[1]) * q6

        # -- state and outputs ---------------------------------------------------------------------
        def on_mag(new, old):
            return select(use_mag, new, old)

        def von_mag(new, old):
            return vselect(use_mag, new, old)

        nx = {
            "q_i": q_i_new,
            "q_a": q_a_new,
            "hd": hd_new,
            "bias": bias_new,
            "p_bias": p_bias,
            "lp_x": lp_x_new,
            "vel": lp_v_new,
            "vel_mean": vel_mean_new,
            "vel_ms": vel_ms_new,
            "th_prev": vselect(run, theta, th_prev),   # a rejected sample keeps the last increment
            "rest_gyr": vselect(gyr_ok, rest_gyr, Vec3(*x.rest_gyr)),
            "rest_acc": rest_acc,
            "rest_t": rest_t,
            "p_head": select(live, p_head, x.p_head),
            "dt_lp": dt_lp_new,
            "t_skip": t_skip_new,
            "dt_prev": select(run, dt, dt_prev),
            "t_mag": on_mag(0.0, t_mag),
            **_unfld("cur", von_mag(cur, cur_old)),
            **_unfld("ref", von_mag(ref_new, ref)),
            **_unfld("cand", von_mag(cand, cand_old)),
            "ref_t": on_mag(ref_t, x.ref_t),
            "cand_t": on_mag(cand_t, x.cand_t),
            "dist_t": on_mag(dist_t, x.dist_t),
            "undist_t": on_mag(undist_t, x.undist_t),
            "initialised": live,
            "mag_flag": logical_and(live, mag_flag),
            "rejected": inc_if(x.rejected, bad),
        }
        y = {"q": vselect(nine, q9, q6), "q6": q6, "q9": q9,
             "rest": logical_and(run, rest),
             "mag_disturbed": all_of(live, nine, mag_flag),
             "rejected": nx["rejected"], "bias": bias_new}
        return nx, y
