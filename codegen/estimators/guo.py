"""GUO: Guo's fast Kalman filter (FKF) for MARG orientation.

S. Guo, J. Wu, Z. Wang, J. Qian, "Novel MARG-Sensor Orientation Estimation Algorithm Using Fast
Kalman Filter", Journal of Sensors 2017, 8542153; seed 001 §5.4.2 ("GUO", the filter ChakaMo
chose), parameters of its §7.4.

State x = q (sensor → ENU), covariance P (4×4).  Per sample:
  predict  x⁻ = Φ q, Φ = I + dt/2 Ω(ω) (seed eq. 5.42; x⁻ normalised),
           P⁻ = Φ P Φᵀ + (dt/2)² Ξ Σ_g Ξᵀ,  Σ_g = var_gyr I,  with Ξ derived from
           q̇ = ½ q ⊗ (0, ω) (seed eq. 5.44 erratum: the printed Ξ, copied from Guo/Wu's MATLAB
           and the ahrs package, does not satisfy the kinematics); Ξ Ξᵀ = I − q qᵀ.
  measure  the accelerometer and magnetometer constraints R(q) â = up, R(q) m̂ = m_ref are the
           +1 eigenspaces of W_a v = −up ⊗ v ⊗ â and W_m v = −m_ref ⊗ v ⊗ m̂ (symmetric,
           W² = I), m_ref = (0, m_N, m_D) in ENU with m_D = â·m̂, m_N = sqrt(1 − m_D²) (eq. 5.36:
           the "M^L" there is the global-frame field).  The measurement is one alternating
           projection of the previous estimate: z = ¼ (W_a + I)(W_m + I) q, normalised
           (eqs. 5.37-5.38, the projectors applied to q, erratum) — exact tilt, heading pulled
           toward the field.
  noise    R = J Σ Jᵀ with J = ∂z/∂(â, m̂) in closed form (eqs. 5.39-5.41), Σ = diag(var_acc I,
           var_mag I) on the unit vectors (Guo/Wu's code uses the σ values as variances:
           erratum "σ meaning"), plus var_acc along z (the norm direction) and a floor.
  update   H = I (seed's "fast" update), via a Cholesky factor of P⁻ + R.
Square-root form (as VAK: :func:`algebraic.sr_quat_kf`): the state carries the lower Cholesky
factor S of P, predicted by a Givens triangularisation of [Φ S | u_g Ξ(q)] and updated as S U
with U Uᵀ = I − GᵀG; mathematically the same filter.  In fixed point the plain P (Q5.26,
steady state ~1e-3 s_ref against per-step changes of ~1e-6, rounded products) froze at 3-5
times the reference in the norm direction and settled 1-2 % above it in the rotation
directions (0.8 % of that from the process noise, whose var_gyr/var_acc had 7 fractional
bits: see step()); the q output deviated from the float64 reference by 0.21° RMS, 1.37° max
on BROAD (trial 01: 0.22° / 0.36°; the process noise fixed alone 0.22° / 0.35°, the factor
alone 0.030° / 0.059°, both 0.0012° / 0.0019°).
Samples without a magnetometer reading skip the W_m projection (z then keeps the predicted
heading) and give the heading direction a large variance.  Covariances are stored divided by
s_ref = var_acc max(1, var_mag/(16 var_acc)) (gains are unchanged by a common scale; the scaled
values suit one fixed-point format); the traces of the accelerometer and magnetometer parts of
R are capped at 64 and 128 s_ref (all number systems).  Initialisation: from the first valid sample (algebraic quaternion — instead of
the identity, from which the seed notes GUO's slow convergence and Guo's code runs 2000 warm-up
iterations), P = R there (scaled to a trace of at most 8 s_ref).
Defaults (ours, chosen once on the 12 BROAD trials): var_acc 0.01, var_gyr 0.001 rad²/s²,
var_mag 0.01 (only the ratios matter); the ``ahrs`` preset is that package's FKF setting.
"""
from __future__ import annotations

from kinefuse.codegen.estimator import Estimator, Param
from kinefuse.codegen.estimators.algebraic import (MIN_FIELD_SIN2, P_MAX, R_FLOOR, R_HEAD_MAX,
                                                   aqua, capped_gram, initial_factor, m_matrix,
                                                   predict_quaternion, sr_quat_kf, sr_state_var,
                                                   tilt_quaternion)
from kinefuse.codegen.estimators.common import (ACC_NORM_MIN_SQ, IMU, INITIALISED,
                                                MAG_NORM_MIN_SQ, Q_OUT, Q_STATE, REJECTED,
                                                SampleCheck)
from kinefuse.codegen.estimators.vac import HEADING_SET, canonical
from kinefuse.codegen.linalg import Quat, vselect
from kinefuse.codegen.scalar import (all_of, assume, clamp, fmax, fmin, inc_if, logical_and,
                                     logical_not, logical_or, select, sqrt, when)

R_HEAD_GUO = R_HEAD_MAX      # cap of the magnetometer part of R̃ (trace), and the no-field
P_MAX_GUO = P_MAX             # heading variance; |P̃_ij| bound
ACC_CAP = 64.0                # cap of the accelerometer part of R̃ (trace)
J_MAX = 6.5                   # |∂z/∂u| <= (1/m_N + 1)/2 with m_N >= sin 5°: bound for assume()

R_TRACE = ACC_CAP + 1.0 + R_HEAD_GUO + 4.0 * R_FLOOR    # tr R̃: Ra + inv_l z zᵀ + Rm + floor

S_VAR = sr_state_var(P_MAX_GUO)


def _pure(v) -> Quat:
    return Quat(0.0, v[0], v[1], v[2])


def _unit(i: int) -> Quat:
    return Quat(0.0, *(1.0 if k == i else 0.0 for k in range(3)))


def guo_measurement(q: Quat, a, m, use_mag):
    """Guo's measurement quaternion from the previous estimate q and the unit vectors a, m,
    and the columns of its Jacobian (projected off z, unnormalised: divide by |p|²).
    Returns (z, |p|², J_acc columns (3), J_mag columns (3))."""
    up = Quat(0.0, 0.0, 0.0, 1.0)
    A = _pure(a)
    Mq = _pure(m)
    m_d = clamp(a.dot(m), -1.0, 1.0)
    m_n = sqrt(fmax(1.0 - m_d * m_d, 0.0))
    inv_mn = 1.0 / fmax(m_n, MIN_FIELD_SIN2 ** 0.5)
    r = Quat(0.0, 0.0, m_n, m_d)                         # m_ref, ENU
    dr = Quat(0.0, 0.0, assume(-m_d * inv_mn, -11.5, 11.5), 1.0)   # ∂m_ref/∂m_D
    T = r * q
    u_m = (q - T * Mq).scale(0.5)                         # (W_m + I) q / 2
    u = vselect(use_mag, u_m, q)
    p = (u - up * u * A).scale(0.5)                       # (W_a + I) u / 2
    z = p.normalized()
    p2 = p.norm_sq()
    D = dr * q * Mq
    zero = Quat(0.0, 0.0, 0.0, 0.0)

    def proj(dp: Quat):
        k = z.dot(dp)
        return Quat(*(assume(dp[i] - z[i] * k, -J_MAX, J_MAX) for i in range(4)))

    ja, jm = [], []
    for i in range(3):
        e = _unit(i)
        du_a = vselect(use_mag, D.scale(-0.5 * m[i]), zero)
        dp_a = (du_a - up * du_a * A - up * u * e).scale(0.5)
        du_m = (D.scale(a[i]) + T * e).scale(-0.5)
        dp_m = (du_m - up * du_m * A).scale(0.5)
        ja.append(proj(dp_a))
        jm.append(proj(dp_m))
    return z, p2, ja, jm


class Guo(Estimator):
    """Guo's fast Kalman filter (GUO): quaternion state, gyroscope process model, measurement
    quaternion from one alternating projection onto the accelerometer and magnetometer
    constraint spaces, H = I (module docstring)."""

    name = "guo"
    title = "Guo fast Kalman filter (FKF)"
    inputs = IMU
    params = (
        Param("var_acc", 0.01, "", 1e-6, 1.0,
              "variance of each component of the unit accelerometer vector"),
        Param("var_gyr", 0.001, "rad^2/s^2", 1e-8, 10.0,
              "gyroscope noise variance per axis"),
        Param("var_mag", 0.01, "", 1e-6, 10.0,
              "variance of each component of the unit magnetometer vector"),
    )
    state = (Q_STATE, S_VAR, INITIALISED, HEADING_SET, REJECTED)
    outputs = (Q_OUT, REJECTED)
    presets = {
        # seed 001 §7.4: "σ_acc 0.001, σ_gyr 0.3, σ_mag 0.4", used as variances like the
        # reference FKF code
        "seed001": {"var_acc": 0.001, "var_gyr": 0.3, "var_mag": 0.4},
        # the ahrs package's FKF defaults (sigma_a = sigma_g = sigma_m = 0.01, variances)
        "ahrs": {"var_acc": 0.01, "var_gyr": 0.01, "var_mag": 0.01},
    }

    def step(self, x, u, p):
        chk = SampleCheck(u)
        q = Quat(*x.q)
        a, a2 = chk.acc.normalized(1e-6)
        m, m2 = chk.mag.normalized(1e-6)
        use_acc = a2 >= ACC_NORM_MIN_SQ
        m_d = a.dot(m)
        use_mag = all_of(chk.use_mag, m2 >= MAG_NORM_MIN_SQ, 1.0 - m_d * m_d >= MIN_FIELD_SIN2)

        # noise in units of s_ref = var_acc λ, λ = max(1, var_mag/(16 var_acc)), from the
        # standard deviations: a ratio of variances spans 1e-8..1e7, which left the fixed-point
        # path 7 fractional bits (var_gyr/var_acc = 0.1 became 13/128, +1.6 % process noise)
        sa = sqrt(p.var_acc)
        r_m = clamp(sqrt(p.var_mag) / sa, 0.0, 100.0)          # sqrt(var_mag/var_acc)
        rho = r_m * r_m
        sl = fmax(1.0, 0.25 * r_m)                              # sqrt(λ)
        inv_l = 1.0 / (sl * sl)
        c_g = clamp(sqrt(p.var_gyr) / (sa * sl), 0.0, 1e3)      # sqrt(var_gyr / s_ref), 1/s
        # u_g = min(dt c_g, 4): the per-step process noise k = u_g² = dt² var_gyr / s_ref (the
        # square-root form uses u_g itself).  Written as min(dt, 4/c_g) c_g, so that the
        # product's bound is the result's (<= 4, plus the rounding of 4/c_g) and not
        # DT_MAX × 1e3: its fixed-point format then keeps 28 fractional bits
        dt_g = fmin(chk.dt, 4.0 / fmax(c_g, 1.0))
        u_g = clamp(assume(dt_g * c_g, 0.0, 4.0 + 2.0 ** -8), 0.0, 4.0)

        # first valid sample: algebraic quaternion; its measurement covariance gives P
        q_am, _, _, _ = aqua(a, m)
        q0 = canonical(vselect(use_mag, q_am, tilt_quaternion(a)))
        do_init = all_of(chk.ok, logical_not(x.initialised), use_acc)
        base = vselect(x.initialised, q, q0)

        # measurement (from the previous estimate) and its covariance
        z, p2, ja, jm = guo_measurement(base, a, m, use_mag)
        inv_p2 = 1.0 / fmax(p2, 1.0 / 16.0)
        Ra = capped_gram(ja, 4.0 * inv_l * inv_p2, ACC_CAP)
        Rm = capped_gram(jm, 4.0 * clamp(rho * inv_l, 0.0, 16.0) * inv_p2, R_HEAD_GUO)
        M = m_matrix(z)
        R = [[None] * 4 for _ in range(4)]
        for i in range(4):
            for j in range(i, 4):
                v = Ra[i][j] + inv_l * (z[i] * z[j]) + select(use_mag, Rm[i][j],
                                                    R_HEAD_GUO * (M[i][2] * M[j][2]))
                if i == j:
                    v = v + R_FLOOR
                R[i][j] = R[j][i] = assume(v, -2.0 * R_HEAD_GUO, 2.0 * R_HEAD_GUO)

        q_pred = predict_quaternion(q, chk.gyr, chk.dt)
        # the first field reading after a start without one sets the heading outright
        first_heading = logical_and(use_mag, logical_not(x.heading_set))
        do_update = logical_and(use_acc, logical_not(first_heading))
        zz = vselect(z.dot(q_pred) < 0.0, z.scale(-1.0), z)
        q_kf, S_kf = sr_quat_kf(x, chk, q_pred, u_g, zz, R, do_update, P_MAX_GUO,
                                2.0 * R_HEAD_GUO)
        q_kf = vselect(first_heading, canonical(q_am), q_kf)

        run = logical_and(chk.ok, x.initialised)
        # a new covariance (start, or the first heading: P = that sample's R, whose measurement
        # is taken from q0 at the start) as its factor, only on the samples that need it
        with when(logical_or(do_init, logical_and(run, first_heading))):
            S0 = initial_factor(R, R_TRACE)
        S_kf = tuple(select(first_heading, r_, v) for r_, v in zip(S0, S_kf))
        q_next = vselect(do_init, q0, vselect(run, q_kf, q))
        S_next = tuple(select(do_init, r_, select(run, sk, sx))
                       for r_, sk, sx in zip(S0, S_kf, x.S))
        heading_next = logical_or(x.heading_set, logical_and(logical_or(do_init, run), use_mag))
        rejected = inc_if(x.rejected, chk.bad)
        nx = {"q": q_next, "S": S_next, "initialised": logical_or(x.initialised, do_init),
              "heading_set": heading_next, "rejected": rejected}
        return nx, {"q": q_next, "rejected": rejected}
