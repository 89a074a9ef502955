"""VAK: Valenti's linear Kalman filter with the algebraic (AQUA) measurement quaternion.

R. G. Valenti, I. Dryanovski, J. Xiao, "A Linear Kalman Filter for MARG Orientation Estimation
Using the Algebraic Quaternion Algorithm", IEEE Trans. Instrum. Meas. 65(2):467-481, 2016;
seed 001 §5.4.1 ("VAK"), parameters of its §7.4.

State x = q (sensor → ENU), covariance P (4×4).  Per sample:
  predict  x⁻ = Φ q, Φ = I + dt/2 Ω(ω) (seed eq. 5.33; x⁻ normalised),
           P⁻ = Φ P Φᵀ + Q,  Q = (dt/2)² Ξ Σ_g Ξᵀ = (dt/2)² σ_gyr² (I − q qᵀ)
           (seed eq. 5.34 erratum: Q has no minus sign, and Ξ is derived from q̇ = ½ q ⊗ (0, ω):
           Ξ(q) = [[−x, −y, −z], [w, −z, y], [z, w, −x], [−y, x, w]], Ξ Ξᵀ = I − q qᵀ);
  update   z = q_am (algebraic quaternion of the accelerometer and magnetometer, the sign
           nearest x⁻), H = I,  R = J Σ_u Jᵀ with Σ_u = diag(σ_acc² I/|a|², σ_mag² I/|m|²)
           (seed eqs. 5.26-5.32, Σ read as a product, erratum) — the Jacobian is evaluated in
           closed form through the earth-frame small-angle error (see
           :func:`algebraic.heading_sigma`); plus the tilt variance along z (the norm direction,
           which carries no information) so that P⁻ + R is always invertible.
  Samples without a magnetometer reading update the tilt only: z = the prediction with its
  tilt corrected by the accelerometer, heading variance R_HEAD_MAX (uninformative).
Covariances are stored divided by s_ref = (σ_acc/g)² max(1, (σ_mag g/(4 σ_acc B_REF))²),
B_REF = 20 µT (Kalman gains are unchanged by a common scale; the scaled values suit one
fixed-point format).  Limits (all number systems): tilt variance of a sample within [2^-10, 16]
s_ref, heading variance <= 128 s_ref, |a| taken within [g/4, 4g] for the noise model.  Initialisation: from the first valid sample
(algebraic quaternion; heading from the first magnetometer reading), P = R of that sample
(scaled to a trace of at most 8 s_ref).
Square-root form: the state carries the lower Cholesky factor S of P (P = S Sᵀ), predicted by a
Givens triangularisation of [Φ S | u_g Ξ(q)] and updated as S U with U Uᵀ = I − GᵀG
(:func:`algebraic.sr_update`); mathematically the same filter.  In fixed point the plain form's
P (8 down to ~1e-4 s_ref, per-step changes of a few LSB) froze 20-60 % away from the reference
and the q output drifted by up to 17° from it; the factor halves the dynamic range.
Defaults (ours, chosen once on the 12 BROAD trials): σ_acc 1 m/s² (it also has to cover
linear acceleration, which no white-noise model does), σ_gyr 0.01 rad/s, σ_mag 2 µT, and the
tilt-heading coupling of the measurement noise off (see ``coupling``; the seed preset keeps
Valenti's full Jacobian).
"""
from __future__ import annotations

from kinefuse.codegen.estimator import Estimator, Param
from kinefuse.codegen.estimators.algebraic import (MIN_FIELD_SIN2, R_HEAD_MAX, T_MAX, T_MIN,
                                                   align_sign, aqua, heading_sigma,
                                                   initial_factor, predict_quaternion,
                                                   r_from_sigma, sr_quat_kf, sr_state_var,
                                                   tilt_correction, tilt_quaternion)
from kinefuse.codegen.estimators.common import (ACC_NORM_MIN_SQ, IMU, INITIALISED,
                                                MAG_NORM_MIN_SQ, Q_OUT, Q_STATE, REJECTED,
                                                SampleCheck)
from kinefuse.codegen.estimators.vac import HEADING_SET, canonical
from kinefuse.codegen.linalg import Quat, Vec3, vselect
from kinefuse.codegen.scalar import (all_of, assume, clamp, fmax, inc_if, logical_and,
                                     logical_not, logical_or, rsqrt, select, when)

B_REF = 20.0      # uT: field strength for the covariance unit (weak end of the geomagnetic range)

S_VAR = sr_state_var()


class Vak(Estimator):
    """Valenti's linear Kalman filter (VAK): quaternion state, gyroscope process model,
    algebraic accelerometer/magnetometer quaternion as the measurement (module docstring)."""

    name = "vak"
    title = "Valenti linear Kalman filter (AQUA measurement)"
    inputs = IMU
    params = (
        Param("sigma_acc", 1.0, "m/s^2", 0.001, 5.0,
              "accelerometer noise standard deviation (per axis)"),
        Param("sigma_gyr", 0.01, "rad/s", 0.0001, 1.0,
              "gyroscope noise standard deviation (per axis)"),
        Param("sigma_mag", 2.0, "uT", 0.001, 50.0,
              "magnetometer noise standard deviation (per axis)"),
        Param("coupling", 0.0, "", 0.0, 1.0,
              "tilt-heading correlation of the measurement noise: 1 = Valenti's full Jacobian "
              "(a heading innovation also corrects tilt), 0 = decoupled (the magnetometer "
              "never tilts the estimate; robust to magnetic disturbances)"),
        Param("gravity", 9.81, "m/s^2", 9.7, 9.9, "local gravity (normalises the covariances)"),
    )
    state = (Q_STATE, S_VAR, INITIALISED, HEADING_SET, REJECTED)
    outputs = (Q_OUT, REJECTED)
    presets = {
        # seed 001 §7.4: σ_acc 0.014, σ_gyr 0.004, σ_mag 0.05 (standard deviations, units as
        # above: the accelerometer value matches the 1.3-1.6 mg of its Table 7.2)
        "seed001": {"sigma_acc": 0.014, "sigma_gyr": 0.004, "sigma_mag": 0.05, "coupling": 1.0},
    }

    def step(self, x, u, p):
        chk = SampleCheck(u)
        q = Quat(*x.q)
        a, a2 = chk.acc.normalized(1e-6)
        m, m2 = chk.mag.normalized(1e-6)

        # noise in units of s_ref = (σ_acc/g)² λ, λ = max(1, (σ_mag g/(4 σ_acc B_REF))²):
        # the tilt variance, or 1/16 of the heading variance in a B_REF field if that is larger.
        # Computed in an order that keeps every intermediate in a narrow range (fixed point):
        # ratios first, clamped where the result is clamped anyway.
        g = p.gravity
        r_s = clamp(p.sigma_mag / p.sigma_acc, 0.0, 1024.0)
        sl = fmax(1.0, r_s * (g / (4.0 * B_REF)))                             # sqrt(λ)
        inv_l = 1.0 / (sl * sl)
        t = clamp(clamp(g * g / fmax(a2, ACC_NORM_MIN_SQ), 1.0 / 16.0, 16.0) * inv_l,
                  T_MIN, T_MAX)                                               # g²/(|a|² λ)
        g_m = g * rsqrt(fmax(m2, MAG_NORM_MIN_SQ))                             # g/|m|
        w_m = clamp(r_s * g_m / sl, 0.0, R_HEAD_MAX ** 0.5)
        smt = clamp(w_m * w_m, T_MIN, R_HEAD_MAX)        # (σ_mag²/|m|²) / s_ref
        dt = chk.dt
        u_g = clamp(dt * (g * (p.sigma_gyr / p.sigma_acc)) / sl, 0.0, 4.0)
        # u_g² = dt² σ_gyr² / s_ref, the per-step process noise k (<= K_MAX); the square-root
        # form uses u_g itself

        # prediction of the state
        q_pred = predict_quaternion(q, chk.gyr, dt)

        # measurement: the algebraic quaternion (with a field reading) or the tilt-corrected
        # prediction (without)
        q_am, _, l, gamma = aqua(a, m)
        use_acc = a2 >= ACC_NORM_MIN_SQ
        use_mag = all_of(chk.use_mag, m2 >= MAG_NORM_MIN_SQ, gamma >= MIN_FIELD_SIN2)
        g_p = Vec3(*(assume(c, -1.0, 1.0) for c in q_pred.rotate(a)))
        z_tilt = tilt_correction(g_p) * q_pred
        z = align_sign(vselect(use_mag, q_am, z_tilt), q_pred)
        s, c = heading_sigma(t, smt, gamma, l.z, use_mag, p.coupling)
        R = r_from_sigma(z, t, s, c)
        # the first field reading after a start without one sets the heading outright
        first_heading = logical_and(use_mag, logical_not(x.heading_set))
        do_update = logical_and(use_acc, logical_not(first_heading))
        q_kf, S_kf = sr_quat_kf(x, chk, q_pred, u_g, z, R, do_update)
        q_kf = vselect(first_heading, canonical(q_am), q_kf)

        # first valid sample: algebraic quaternion, P = R of that sample
        q_t = tilt_quaternion(a)
        q0 = canonical(vselect(use_mag, q_am, q_t))
        do_init = all_of(chk.ok, logical_not(x.initialised), use_acc)
        run = logical_and(chk.ok, x.initialised)
        # the factor of a new covariance (start, or the first heading: P = that sample's R) is
        # only computed on the samples that need it
        with when(logical_or(do_init, logical_and(run, first_heading))):
            R0 = r_from_sigma(q0, t, s, c)
            S0 = initial_factor([[select(do_init, R0[i][j], R[i][j]) for j in range(4)]
                                 for i in range(4)])
        S_kf = tuple(select(first_heading, r, v) for r, v in zip(S0, S_kf))
        q_next = vselect(do_init, q0, vselect(run, q_kf, q))
        S_next = tuple(select(do_init, r0, select(run, sk, sx))
                       for r0, sk, sx in zip(S0, S_kf, x.S))
        heading_next = logical_or(x.heading_set, logical_and(logical_or(do_init, run), use_mag))
        rejected = inc_if(x.rejected, chk.bad)
        nx = {"q": q_next, "S": S_next, "initialised": logical_or(x.initialised, do_init),
              "heading_set": heading_next, "rejected": rejected}
        return nx, {"q": q_next, "rejected": rejected}

