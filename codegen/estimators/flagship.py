"""kinefuse flagship orientation filter: 6D and 9D orientation, gyroscope bias, rest and magnetic
disturbance status from one update.

Structure (frames: S sensor, I almost-inertial, E6 6D earth frame (z up, heading free),
E earth frame East-North-Up, y towards magnetic north):

* strapdown: q_i (S -> I) integrates the bias-corrected gyroscope with a two-sample coning
  term and a second-order step quaternion, per-sample time step;
* inclination: the specific force is rotated into I and low-pass filtered there (two first-order
  stages, each tau_acc / 2: DC group delay tau_acc).  Linear acceleration integrates to a velocity
  change, so its mean in an inertial frame is small; the filtered vector is gravity.  q_a (I -> E6)
  is corrected so that the filtered vector points up.  Only q_a is corrected: the filter state is
  never rotated by its own corrections;
* heading: one scalar rotation delta about the vertical (stored as the quaternion (cos, sin) of
  delta/2) from the horizontal magnetic field, so the magnetometer never touches inclination.
  A scalar Kalman filter sets the gain: the heading variance grows with time (heading random
  walk) and shrinks with each accepted magnetometer sample; tau_mag is the steady-state time
  constant.  After an initialisation or a disturbance the variance is large, so the heading
  recovers quickly;
* magnetic disturbance: the field in the earth frame (horizontal magnitude, vertical component) is
  compared with a learned local reference; a sample further than mag_th * |B_ref| from it, or one
  whose heading disagreement is implausible for the current heading variance, is rejected.
  Rejection is bounded by mag_reject_time, after which the reference is re-learnt;
* gyroscope bias: at rest (gyroscope and accelerometer still for rest_time) a Kalman update
  towards the low-pass filtered gyroscope; in motion the inclination correction and (9D) the
  accepted heading correction feed an integral term, so every bias component converges as soon as
  the sensor's orientation varies, whatever it is.

Everything is one float32 (or fixed-point) update: no double-precision state.
"""
from __future__ import annotations

import math

from kinefuse.codegen.estimator import Estimator, Param, Var
from kinefuse.codegen.estimators.common import (ACC_MAX, DT_MAX, GYR_MAX, IMU, INITIALISED,
                                                MAG_MAX, REJECTED, initial_quaternion)
from kinefuse.codegen.ir import BOOL
from kinefuse.codegen.linalg import Quat, Vec3, vselect
from kinefuse.codegen.scalar import (all_of, any_of, assume, clamp, fabs, fmax, fmin, inc_if,
                                     logical_and, logical_not, logical_or, rnorm, select)

DEG = math.pi / 180.0
T_SAT = 1.0e4          # s; timers saturate here
BIAS_LIM = 10.0 * DEG  # rad/s; declared range of the bias state (bias_max may not exceed it)
P_HEAD_MAX = 4.0       # rad^2; heading variance ceiling (about 115 deg standard deviation)
REF_MAX = 200.0        # uT; declared range of the learned local field
LP_MAX = ACC_MAX       # m/s^2; declared range of the filtered specific force

UNIT = (-1.0, 1.0)


def _strict_within(v, limit):
    """Every component finite and strictly inside +-limit (a value at full scale is saturated)."""
    return all_of(*(fabs(c) < limit for c in v))


def _lp(y, x, k):
    """One first-order low-pass step y + k (x - y) of a vector."""
    return Vec3(*(yi + k * (xi - yi) for yi, xi in zip(y, x)))


def _clamp3(v, lo, hi):
    return Vec3(*(clamp(c, lo, hi) for c in v))


class Flagship(Estimator):
    """kinefuse flagship orientation filter (6D + 9D, bias, rest, magnetic disturbance).

    Inputs: gyroscope rad/s, accelerometer m/s^2 (+g up at rest), magnetometer uT (any
    calibrated unit works: only directions and ratios are used), mag_valid, per-sample dt in s.
    Outputs: q (9D when mode = 1, else 6D), q6 (inclination exact, heading from the gyroscope),
    q9 (heading from the magnetometer; equals q6 in mode 0), all sensor -> East-North-Up, and
    the status rest, mag_disturbed, rejected, bias (rad/s, sensor frame).
    """

    name = "flagship"
    title = "kinefuse flagship orientation filter"
    inputs = IMU
    params = (
        Param("mode", 1.0, "", 0.0, 1.0, "0: 6D (magnetometer ignored), 1: 9D; q6 and q9 are "
              "output in both"),
        Param("tau_acc", 3.0, "s", 0.5, 20.0,
              "inclination time constant: DC group delay of the accelerometer low-pass filter "
              "in the almost-inertial frame"),
        Param("tau_mag", 9.0, "s", 1.0, 60.0,
              "steady-state time constant of the heading correction"),
        Param("heading_rw", 0.2 * DEG, "rad/s^0.5", 0.01 * DEG, 5.0 * DEG,
              "heading random walk between magnetometer corrections (gyroscope bias residual)"),
        Param("tau_bias", 40.0, "s", 5.0, 1000.0,
              "time constant of the gyroscope bias estimation in motion"),
        Param("bias_sigma_init", 0.5 * DEG, "rad/s", 0.01 * DEG, 5.0 * DEG,
              "standard deviation of the bias before any estimate (and its ceiling)"),
        Param("bias_forget_time", 100.0, "s", 1.0, 1000.0,
              "time in which the bias uncertainty grows back to bias_sigma_init"),
        Param("bias_sigma_rest", 0.03 * DEG, "rad/s", 0.001 * DEG, 1.0 * DEG,
              "noise of one low-pass filtered gyroscope sample used as bias at rest"),
        Param("bias_max", 2.0 * DEG, "rad/s", 0.1 * DEG, BIAS_LIM,
              "largest bias accepted (the bias estimate is clipped; a faster low-pass "
              "rotation is never taken for rest)"),
        Param("rest_th_gyr", 2.0 * DEG, "rad/s", 0.1 * DEG, 20.0 * DEG,
              "rest: largest deviation of the gyroscope from its low-pass value"),
        Param("rest_th_acc", 0.5, "m/s^2", 0.05, 5.0,
              "rest: largest deviation of the accelerometer from its low-pass value"),
        Param("rest_time", 1.5, "s", 0.1, 30.0, "rest: time the conditions must hold"),
        Param("tau_rest", 0.5, "s", 0.05, 5.0, "time constant of the rest-detection low-pass"),
        Param("mag_th", 0.1, "", 0.01, 1.0,
              "magnetic disturbance: largest distance of the earth-frame field (horizontal, "
              "vertical) from the learned reference, relative to its magnitude"),
        Param("mag_gate", 4.0, "sigma", 1.0, 100.0,
              "heading disagreements beyond this many standard deviations are rejected"),
        Param("mag_sigma_gate", 10.0 * DEG, "rad", 0.1 * DEG, 90.0 * DEG,
              "standard deviation of one magnetometer heading (noise, calibration) for the "
              "gate"),
        Param("tau_mag_ref", 20.0, "s", 1.0, 600.0,
              "time constant of learning the local field reference"),
        Param("mag_reject_time", 60.0, "s", 1.0, 3600.0,
              "longest continuous rejection: afterwards the current field becomes the reference"),
        Param("mag_min_undisturbed", 0.5, "s", 0.0, 10.0,
              "time the field must be undisturbed before heading corrections resume"),
        Param("gyr_range", GYR_MAX, "rad/s", 0.1, GYR_MAX,
              "gyroscope full scale: a sample at or beyond it is saturated and rejected"),
        Param("acc_range", ACC_MAX, "m/s^2", 1.0, ACC_MAX,
              "accelerometer full scale: a saturated sample is not used for inclination"),
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
        Var("p_bias", 1, 0.0, (5.0 * DEG) ** 2, "(rad/s)^2", "bias variance (each axis)",
            init=(0.5 * DEG) ** 2),
        Var("lp1", 3, -LP_MAX, LP_MAX, "m/s^2", "specific force low-pass, stage 1, frame I",
            init=(0.0, 0.0, 0.0)),
        Var("lp2", 3, -LP_MAX, LP_MAX, "m/s^2", "specific force low-pass, stage 2, frame I",
            init=(0.0, 0.0, 0.0)),
        Var("w_prev", 3, -2.0 * GYR_MAX, 2.0 * GYR_MAX, "rad/s",
            "previous bias-corrected angular rate (coning term)", init=(0.0, 0.0, 0.0)),
        Var("rest_gyr", 3, -GYR_MAX, GYR_MAX, "rad/s", "rest detection: gyroscope low-pass",
            init=(0.0, 0.0, 0.0)),
        Var("rest_acc", 3, -ACC_MAX, ACC_MAX, "m/s^2", "rest detection: accelerometer low-pass",
            init=(0.0, 0.0, 0.0)),
        Var("rest_t", 1, 0.0, T_SAT, "s", "time the rest conditions have held", init=0.0),
        Var("p_head", 1, 0.0, P_HEAD_MAX, "rad^2", "heading variance", init=P_HEAD_MAX),
        Var("t_mag", 1, 0.0, 2.0 * DT_MAX, "s", "time since the previous magnetometer sample",
            init=0.0),
        Var("ref_h", 1, 0.0, REF_MAX, "uT", "learned local field: horizontal magnitude",
            init=0.0),
        Var("ref_v", 1, -REF_MAX, REF_MAX, "uT", "learned local field: vertical component (up)",
            init=0.0),
        Var("ref_t", 1, 0.0, T_SAT, "s", "time the reference has been learnt (undisturbed)",
            init=0.0),
        Var("dist_t", 1, 0.0, T_SAT, "s", "time the field has been disturbed", init=0.0),
        Var("undist_t", 1, 0.0, T_SAT, "s", "time the field has been undisturbed", init=0.0),
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
            "samples (or parts: accelerometer, magnetometer) rejected as non-finite, saturated "
            "or out of range", REJECTED.type),
        Var("bias", 3, -BIAS_LIM, BIAS_LIM, "rad/s", "gyroscope bias estimate, sensor frame"),
    )

    def step(self, x, u, p):
        gyr, acc, mag, dt = Vec3(*u.gyr), Vec3(*u.acc), Vec3(*u.mag), u.dt
        nine = p.mode > 0.5

        # -- sample validation --------------------------------------------------------------
        gyr_ok = all_of(_strict_within(gyr, p.gyr_range), dt > 0.0, dt <= DT_MAX)
        acc_ok = logical_and(gyr_ok, _strict_within(acc, p.acc_range))
        mag_fine = all_of(*(fabs(c) <= MAG_MAX for c in mag))
        use_mag_raw = all_of(gyr_ok, u.mag_valid, mag_fine)
        bad = any_of(logical_not(gyr_ok), logical_not(acc_ok),
                     logical_and(u.mag_valid, logical_not(mag_fine)))
        use_mag_raw = logical_and(use_mag_raw, nine)
        dt = select(gyr_ok, dt, 0.0)      # a rejected sample advances nothing

        q_i, q_a = Quat(*x.q_i), Quat(*x.q_a)
        bias = Vec3(*x.bias)

        # -- strapdown integration --------------------------------------------------------------
        w = gyr - bias
        w_prev = Vec3(*x.w_prev)
        # rotation vector of the step: w dt plus the two-sample coning term (w_prev x w) dt^2/12
        cone = w_prev.cross(w) * (dt * dt * (1.0 / 12.0))
        phi = w * dt + cone
        th2 = fmin(phi.norm_sq(), 1.0)
        # (cos(th/2), sin(th/2)/th * phi) to fourth order in th (error ~ th^5 / 480)
        c0 = 1.0 - 0.125 * th2
        s0 = 0.5 - th2 * (1.0 / 48.0)
        dq = Quat(c0, s0 * phi.x, s0 * phi.y, s0 * phi.z)
        q_i_new = (q_i * dq).normalized()

        # -- inclination: low-pass of the specific force in the almost-inertial frame ----------
        k_acc = clamp(dt * 2.0 / p.tau_acc, 0.0, 1.0)
        a_i = q_i_new.rotate(acc)
        lp1 = _clamp3(_lp(Vec3(*x.lp1), a_i, k_acc), -LP_MAX, LP_MAX)
        lp2 = _clamp3(_lp(Vec3(*x.lp2), lp1, k_acc), -LP_MAX, LP_MAX)
        g_e = q_a.rotate(lp2)
        gh, _ = g_e.normalized(1e-6)
        # C = (1 + gz, gy, -gx, 0) rotates the filtered direction onto +z (half-way quaternion);
        # the floor keeps an upside-down start well defined (any noise then leaves it)
        corr = Quat(fmax(1.0 + gh.z, 1e-3), gh.y, -gh.x, 0.0)
        q_a_corr = (corr * q_a).normalized()
        q_a_new = vselect(acc_ok, q_a_corr, q_a)
        lp1 = vselect(acc_ok, lp1, Vec3(*x.lp1))
        lp2 = vselect(acc_ok, lp2, Vec3(*x.lp2))
        q6 = (q_a_new * q_i_new).normalized()

        # correction angle (rad, E6 frame) of this step: sin(angle) = |gh_horizontal|
        theta_e = vselect(acc_ok, Vec3(gh.y, -gh.x, 0.0), Vec3(0.0, 0.0, 0.0))

        # -- rest detection -------------------------------------------------------------------
        k_rest = clamp(dt / p.tau_rest, 0.0, 1.0)
        rest_gyr = _lp(Vec3(*x.rest_gyr), gyr, k_rest)
        rest_acc = _lp(Vec3(*x.rest_acc), acc, k_rest)
        dev_g = (gyr - rest_gyr).norm_sq()
        dev_a = (acc - rest_acc).norm_sq()
        still = all_of(acc_ok, dev_g < p.rest_th_gyr * p.rest_th_gyr,
                       dev_a < p.rest_th_acc * p.rest_th_acc,
                       *(fabs(c) < p.bias_max for c in rest_gyr))
        rest_t = select(still, fmin(x.rest_t + dt, T_SAT), 0.0)
        rest = rest_t >= p.rest_time
        rest_gyr = vselect(gyr_ok, rest_gyr, Vec3(*x.rest_gyr))
        rest_acc = vselect(acc_ok, rest_acc, Vec3(*x.rest_acc))

        # -- heading (9D) --------------------------------------------------------------------
        m_e = q6.rotate(mag)                         # field in the 6D earth frame
        hw, hz = x.hd
        cd = hw * hw - hz * hz                       # cos(delta)
        sd = 2.0 * hw * hz                           # sin(delta)
        mx = cd * m_e.x - sd * m_e.y                 # field in the 9D earth frame (horizontal)
        my = sd * m_e.x + cd * m_e.y
        rh, h2 = rnorm((mx, my), 1e-6)
        h_mag = h2 * rh                              # horizontal magnitude, uT
        v_mag = m_e.z                                # vertical component (up), uT
        # sine of the heading disagreement (field east of north > 0); beyond 90 deg it saturates
        ex = assume(mx * rh, -1.0, 1.0)
        err = select(my >= 0.0, ex, select(ex >= 0.0, 1.0, -1.0))

        t_mag = fmin(x.t_mag + dt, 2.0 * DT_MAX)
        ref_h, ref_v = x.ref_h, x.ref_v
        ref_n2 = ref_h * ref_h + ref_v * ref_v
        dh = h_mag - ref_h
        dv = v_mag - ref_v
        field_off = (dh * dh + dv * dv) > p.mag_th * p.mag_th * ref_n2
        has_ref = x.ref_t > 0.0
        disturbed_now = logical_and(use_mag_raw, logical_and(has_ref, field_off))

        # heading variance prediction: random walk
        p_head = fmin(x.p_head + p.heading_rw * p.heading_rw * dt, P_HEAD_MAX)
        # gate: a disagreement implausible for the current variance (plus magnetometer noise)
        gate_var = p.mag_gate * p.mag_gate * (p_head + p.mag_sigma_gate * p.mag_sigma_gate)
        implausible = err * err > gate_var

        dist_t = select(disturbed_now, fmin(x.dist_t + dt, T_SAT),
                        select(use_mag_raw, 0.0, x.dist_t))
        undist_t = select(disturbed_now, 0.0,
                          select(use_mag_raw, fmin(x.undist_t + dt, T_SAT), x.undist_t))
        give_up = dist_t >= p.mag_reject_time
        settled = undist_t >= p.mag_min_undisturbed
        accept = all_of(use_mag_raw, logical_not(disturbed_now), settled,
                        logical_or(logical_not(implausible), logical_not(has_ref)))
        mag_disturbed = logical_and(nine, logical_or(logical_and(has_ref, logical_not(settled)),
                                                     disturbed_now))

        # Kalman gain: R_c = heading_rw^2 tau_mag^2 (continuous noise density) makes tau_mag the
        # steady-state time constant; one sample covering t_mag seconds has variance R_c / t_mag
        r_c = p.heading_rw * p.heading_rw * p.tau_mag * p.tau_mag
        pt = p_head * fmax(t_mag, 1e-4)
        k_head = pt / fmax(pt + r_c, 1e-12)
        k_head = select(accept, clamp(k_head, 0.0, 1.0), 0.0)
        d_head = k_head * err                        # heading correction, rad
        hw_n = hw - hz * (0.5 * d_head)
        hz_n = hz + hw * (0.5 * d_head)
        rn, _ = rnorm((hw_n, hz_n), 1e-6)
        hd_new = (assume(hw_n * rn, -1.0, 1.0), assume(hz_n * rn, -1.0, 1.0))
        p_head = select(accept, (1.0 - k_head) * p_head, p_head)
        t_mag = select(use_mag_raw, 0.0, t_mag)

        # local field reference: learnt while undisturbed, re-learnt after too long a rejection
        ref_t = select(accept, fmin(x.ref_t + dt, T_SAT), x.ref_t)
        k_ref = clamp(dt / fmax(fmin(ref_t, p.tau_mag_ref), 1e-3), 0.0, 1.0)
        relearn = logical_and(use_mag_raw, logical_or(logical_not(has_ref), give_up))
        learn = logical_and(accept, has_ref)
        ref_h_new = select(relearn, h_mag, select(learn, ref_h + k_ref * (h_mag - ref_h), ref_h))
        ref_v_new = select(relearn, v_mag, select(learn, ref_v + k_ref * (v_mag - ref_v), ref_v))
        ref_t = select(relearn, fmax(dt, 1e-3), ref_t)
        dist_t = select(relearn, 0.0, dist_t)
        undist_t = select(logical_and(relearn, has_ref), 0.0, undist_t)

        # -- gyroscope bias ---------------------------------------------------------------------
        p0 = p.bias_sigma_init * p.bias_sigma_init
        p_bias = fmin(x.p_bias + p0 * dt / p.bias_forget_time, p0)
        # at rest: Kalman update towards the low-pass gyroscope
        r_rest = p.bias_sigma_rest * p.bias_sigma_rest
        k_b = p_bias / fmax(p_bias + r_rest, 1e-20)
        use_rest = logical_and(rest, gyr_ok)
        b_rest = bias + (rest_gyr - bias) * k_b
        p_rest = (1.0 - k_b) * p_bias
        # in motion: integral of the corrections (E6 frame) expressed in the sensor frame
        corr_e = Vec3(theta_e.x, theta_e.y, d_head)
        corr_s = q6.rotate_inv(corr_e)
        b_motion = bias - corr_s * (1.0 / p.tau_bias)
        bias_new = vselect(use_rest, b_rest, vselect(gyr_ok, b_motion, bias))
        bias_new = _clamp3(bias_new, -p.bias_max, p.bias_max)
        p_bias = select(use_rest, p_rest, p_bias)

        # -- outputs ------------------------------------------------------------------------------
        hd_q = Quat(hd_new[0], 0.0, 0.0, hd_new[1])
        q9 = hd_q * q6

        # -- initialisation from the first valid sample --------------------------------------------
        q_init, init_ok = initial_quaternion(acc, mag, use_mag_raw)
        do_init = all_of(acc_ok, logical_not(x.initialised), init_ok)
        run = logical_and(gyr_ok, x.initialised)
        a_init = q_init.rotate(acc)
        m_init = q_init.rotate(mag)
        mh2 = m_init.x * m_init.x + m_init.y * m_init.y
        rmi, _ = rnorm((m_init.x, m_init.y), 1e-6)

        def pick(init_v, run_v, keep_v):
            return select(do_init, init_v, select(run, run_v, keep_v))

        def vpick(init_v, run_v, keep_v):
            vals = [pick(a, b, c) for a, b, c in zip(init_v, run_v, keep_v)]
            return type(run_v)(*vals) if isinstance(run_v, (Quat, Vec3)) else tuple(vals)

        one = Quat(1.0, 0.0, 0.0, 0.0)
        zero3 = Vec3(0.0, 0.0, 0.0)
        q_i_out = vpick(q_init, q_i_new, q_i)
        q_a_out = vpick(one, q_a_new, q_a)
        hd_out = vpick((1.0, 0.0), hd_new, tuple(x.hd))
        q6_out = vpick(q_init, q6, (q_a * q_i))
        q9_out = vpick(q_init, q9, Quat(x.hd[0], 0.0, 0.0, x.hd[1]) * (q_a * q_i))
        init_mag = logical_and(use_mag_raw, mh2 > 1e-6)
        nx = {
            "q_i": q_i_out,
            "q_a": q_a_out,
            "hd": hd_out,
            "bias": vpick(bias, bias_new, bias),
            "p_bias": pick(x.p_bias, p_bias, x.p_bias),
            "lp1": vpick(_clamp3(a_init, -LP_MAX, LP_MAX), lp1, Vec3(*x.lp1)),
            "lp2": vpick(_clamp3(a_init, -LP_MAX, LP_MAX), lp2, Vec3(*x.lp2)),
            "w_prev": vpick(zero3, _clamp3(w, -2.0 * GYR_MAX, 2.0 * GYR_MAX), w_prev),
            "rest_gyr": vpick(gyr, rest_gyr, Vec3(*x.rest_gyr)),
            "rest_acc": vpick(acc, rest_acc, Vec3(*x.rest_acc)),
            "rest_t": pick(0.0, rest_t, x.rest_t),
            "p_head": pick(P_HEAD_MAX, p_head, x.p_head),
            "t_mag": pick(0.0, t_mag, x.t_mag),
            "ref_h": pick(select(init_mag, clamp(mh2 * rmi, 0.0, REF_MAX), 0.0),
                          clamp(ref_h_new, 0.0, REF_MAX), ref_h),
            "ref_v": pick(select(init_mag, clamp(m_init.z, -REF_MAX, REF_MAX), 0.0),
                          clamp(ref_v_new, -REF_MAX, REF_MAX), ref_v),
            "ref_t": pick(select(init_mag, 1e-3, 0.0), ref_t, x.ref_t),
            "dist_t": pick(0.0, dist_t, x.dist_t),
            "undist_t": pick(0.0, undist_t, x.undist_t),
            "initialised": logical_or(x.initialised, do_init),
            "rejected": inc_if(x.rejected, bad),
        }
        q_out = vselect(nine, q9_out, q6_out)
        y = {"q": q_out, "q6": q6_out, "q9": q9_out,
             "rest": logical_and(run, rest),
             "mag_disturbed": logical_and(run, mag_disturbed),
             "rejected": nx["rejected"], "bias": nx["bias"]}
        return nx, y
