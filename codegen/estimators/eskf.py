"""Error-state (indirect, multiplicative) Kalman filter for orientation: the principled baseline.

Seed 002, Annex B (the indirect Kalman filter of MATLAB's imufilter/ahrsfilter): the filter
estimates the *error* of a nominal state, injects it after each update and resets it to zero.

Nominal state: q (sensor -> East-North-Up), gyroscope bias b (rad/s, sensor frame), linear
acceleration a (m/s^2, sensor frame, a Gauss-Markov process).  Error state (9): dtheta (rad,
earth frame: R_true = exp([dtheta]x) R), db (rad/s), da (m/s^2).

* prediction: q <- q (x) exp((w - b) dt) (fourth-order step quaternion with the coning term),
  b <- b, a <- c a with c = exp(-dt / tau_lin) ~ 1 - dt/tau_lin + (dt/tau_lin)^2/2;
  P <- F P F^T + Q with F = [[I, -R dt, 0], [0, I, 0], [0, 0, c I]],
  Q = diag(gyr_noise^2 dt, bias_rw^2 dt, lin_sigma^2 (1 - c^2)) (+ the optional rate error);
* accelerometer: rotated into the earth frame, y = R f - (R a + g e_z) = [g e_z]x dtheta + R da
  + n (a in the sensor frame, so heading does not enter); n has the density acc_noise (one
  sample: acc_noise^2 / dt), which with gyr_noise sets the tilt time constant
  acc_noise / (g gyr_noise) (5.8 s by default); three sequential scalar updates (equivalent to
  the vector update for a diagonal noise: no matrix inverse), each gated at acc_gate sigma;
* magnetometer (9D, optional): the sine of the heading disagreement of the horizontal field,
  H = e_z (dtheta_z only: the field's dip never tilts the estimate), noise density mag_noise;
  rejected when the field magnitude leaves the learnt reference by mag_th or the disagreement
  exceeds mag_gate sigma; the rejection is bounded by mag_reject_time (no lock-out);
* covariance: Joseph form (I - K h) P (I - K h)^T + K r K^T for the gain actually applied,
  computed in normalised variables g = h P / sqrt(S) (see `scalar_update`): every quantity has
  the scale of sqrt(P), whatever S; only the upper triangle is computed and stored (exactly
  symmetric); after each step diagonals are floored and every entry is clamped to its block's
  range.  Positive definiteness in float32 and fixed point is checked by the tests (eigenvalues
  of the 9x9 matrix from the generated models' state);
* reset: dx is injected (q <- (1, dtheta/2) (x) q, renormalised; b += db; a += da) and set to 0;
  the reset Jacobian I - [dtheta/2]x is taken as I (dtheta is small: second order).

Fixed point: the covariance is stored in six blocks with their own ranges, so that each gets a
Q format matched to its physical scale (`P_BLOCKS`; the generator derives the format):
  P_tt  rad^2          [-0.1, 0.1]        (attitude sigma up to 18 deg)        -> Q-3.34
  P_bb  (rad/s)^2      [-1.2e-3, 1.2e-3]  (bias sigma up to 2 deg/s)           -> Q-9.40
  P_aa  (m/s^2)^2      [-25, 25]          (linear acceleration up to 5 m/s^2)  -> Q5.26
  cross blocks bounded by Cauchy-Schwarz from the diagonal ranges.
Why: one format for all 45 entries would have to cover 25 (m/s^2)^2 and resolve 1e-9 rad^2
(the attitude process noise of one sample): impossible in 32 bits.  A finer P_tt than Q1.30 keeps
that noise tens of LSB above the resolution; the per-term bounds sqrt(P_ii P_jj) of the update
give every product a format of its own scale.  A value beyond a range saturates (the heading
variance without a magnetometer is reported at the 18 deg ceiling).
Interval arithmetic sees neither a convex combination nor a clamp that follows, so where a value
is bounded by what comes after it, the bound is stated (`assume`), never changing a float value:
the reference field magnitude (a convex combination of itself and the reading: with twice its
range, x.ref_n lost a bit and was rounded up every sample, +0.02 uT on trial 32, enough to move
the norm test on borderline readings and the heading by 0.6 deg), the attitude process noise
(each term capped at P_TT, which P + q is clamped to: otherwise P_tt + q was rounded to Q8.23
every sample), each Joseph-form entry (within its block's range), and the state corrections
g nu (nu clamped at the largest value an applied update can have, the largest gate or the
innovation bound over sqrt(r_min), instead of NU_MAX; the product within twice the error
state's range, which dx + g nu is clamped to: with NU_MAX the bias corrections were rounded to
1.5e-8 rad/s per update, which left P_bb 2 % and P_tb 5 % off the reference).
"""
from __future__ import annotations

import math

from kinefuse.codegen.estimator import Estimator, Param, Var
from kinefuse.codegen.estimators.common import (ACC_MAX, ACC_NORM_MIN_SQ, DT_MAX, GYR_MAX, IMU,
                                                INITIALISED, MAG_MAX, REJECTED)
from kinefuse.codegen.ir import BOOL
from kinefuse.codegen.linalg import (ZERO, Quat, Vec3, quadform, rotation_rows, sadd, smul, ssum,
                                    vselect)
from kinefuse.codegen.scalar import (all_of, any_of, assume, clamp, fabs, fmax, fmin, inc_if,
                                     logical_and, logical_not, logical_or, rnorm, rsqrt, select)

DEG = math.pi / 180.0
G = 9.81
T_SAT = 1.0e4
STEP_MAX = 2.0
BIAS_LIM = 10.0 * DEG
N_MAX = 2.0 * MAG_MAX
LIN_MAX = 4.0 * G            # m/s^2, range of the linear-acceleration estimate

# covariance blocks: name -> (rows, cols, symmetric, bound).  Indices 0-2 attitude, 3-5 bias,
# 6-8 linear acceleration.
P_TT, P_BB, P_AA = 0.1, (2.0 * DEG) ** 2, 25.0
P_BLOCKS = {
    "p_tt": ((0, 3), (0, 3), True, P_TT),
    "p_tb": ((0, 3), (3, 6), False, math.sqrt(P_TT * P_BB)),
    "p_ta": ((0, 3), (6, 9), False, math.sqrt(P_TT * P_AA)),
    "p_bb": ((3, 6), (3, 6), True, P_BB),
    "p_ba": ((3, 6), (6, 9), False, math.sqrt(P_BB * P_AA)),
    "p_aa": ((6, 9), (6, 9), True, P_AA),
}
# smallest variance kept on the diagonal of each block (a few LSB of its format)
P_FLOOR = {"p_tt": 1e-9, "p_bb": 1e-13, "p_aa": 1e-6}
DIAG_BOUND = [P_TT] * 3 + [P_BB] * 3 + [P_AA] * 3
# range of every entry (i, j): its block's bound
ENTRY_BOUND = [[None] * 9 for _ in range(9)]
for _rows, _cols, _sym, _bound in P_BLOCKS.values():
    for _i in range(*_rows):
        for _j in range(*_cols):
            ENTRY_BOUND[_i][_j] = ENTRY_BOUND[_j][_i] = _bound

ACC_NOISE_MIN = 0.01          # m/s^2: lower end of acc_noise (bounds the gains)
S_MAX = 1.0e6                 # largest innovation variance (acc_noise^2 / dt at 100 us)
NU_MAX = 1.0e3                # normalised innovations are clamped here (gated far below)
MAG_NOISE_MIN = 0.5 * DEG     # rad: lower end of mag_noise
ACC_GATE_MAX = 100.0          # upper end of acc_gate


def _block_len(rows, cols, sym):
    n = rows[1] - rows[0]
    return n * (n + 1) // 2 if sym else n * (cols[1] - cols[0])


def _block_entries(rows, cols, sym):
    out = []
    for i in range(rows[0], rows[1]):
        for j in range(cols[0], cols[1]):
            if sym and j < i:
                continue
            out.append((i, j))
    return out


def unpack_p(x) -> list:
    """The full symmetric 9x9 covariance from the stored blocks."""
    P = [[None] * 9 for _ in range(9)]
    for name, (rows, cols, sym, _) in P_BLOCKS.items():
        vals = getattr(x, name)
        for (i, j), v in zip(_block_entries(rows, cols, sym), vals):
            P[i][j] = v
            P[j][i] = v
    return P


def pack_p(P) -> dict:
    """Stored blocks (upper triangle) of a symmetric 9x9 covariance, each clamped to its range;
    diagonal entries floored."""
    out = {}
    for name, (rows, cols, sym, bound) in P_BLOCKS.items():
        vals = []
        for (i, j) in _block_entries(rows, cols, sym):
            lo = P_FLOOR[name] if i == j else -bound
            vals.append(clamp(P[i][j], lo, bound))
        out[name] = tuple(vals)
    return out


def clamp_p(P):
    """Every entry of a full symmetric covariance clamped to its block's range (diagonal
    floored): keeps each intermediate bounded (fixed point) and the semantics identical in
    every number system."""
    out = [[None] * 9 for _ in range(9)]
    for name, (rows, cols, sym, bound) in P_BLOCKS.items():
        for (i, j) in _block_entries(rows, cols, sym):
            lo = P_FLOOR[name] if i == j else -bound
            v = clamp(P[i][j], lo, bound)
            out[i][j] = v
            out[j][i] = v
    return out


DX_BOUND = [0.5] * 3 + [BIAS_LIM] * 3 + [LIN_MAX] * 3


def _strict_within(v, limit):
    return all_of(*(fabs(c) < limit for c in v))


def _clamp3(v, lo, hi):
    return Vec3(*(clamp(c, lo, hi) for c in v))


def _renorm(q: Quat) -> Quat:
    k = 1.5 - 0.5 * q.norm_sq()
    return Quat(*(assume(c * k, -1.0, 1.0) for c in q))


def scalar_update(P, dx, h, y, r, r_min, use, gate=None, nu_bound=NU_MAX):
    """One scalar Kalman update, Joseph form, in normalised variables.

    h: 9 entries (ZERO where structurally zero), y: the measurement residual at the prior
    (before this filter step's earlier updates), r: its noise variance (>= r_min > 0).
    With u = h P, S = h P h^T + r and 1/sqrt(S): g = u / sqrt(S) (|g_i| <= sqrt(P_ii)) and the
    normalised innovation nu = (y - h dx) / sqrt(S); the applied gain is K = g / sqrt(S), so
    dx += g nu and the Joseph form (I - K h) P (I - K h)^T + K r K^T becomes
    P - g g^T - g g^T + rho g g^T with rho = S (1/sqrt(S))^2 (1 up to rounding).  Every
    quantity keeps the scale of sqrt(P): precise in fixed point whatever S is.
    Returns (P', dx').  When `use` is false (or the gate rejects) nothing changes.
    nu_bound: the largest |nu| an applied update can have (the largest gate, or the bound of
    the innovation over sqrt(r_min)).  The correction g nu is formed with nu clamped there and
    is bounded by twice the error state's range (dx + g nu is clamped to it): both bounds leave
    every value unchanged and give the products a format of their own scale (with NU_MAX the
    bias corrections were rounded to 1.5e-8 rad/s, the dominant fixed-point error of the bias).
    """
    u = [ssum(smul(h[k], P[k][j]) for k in range(9)) for j in range(9)]     # u = h P
    s = assume(sadd(ssum(smul(h[k], u[k]) for k in range(9)), r), r_min, S_MAX)
    rs = rsqrt(s)
    g = [assume(u[i] * rs, -1.01 * math.sqrt(DIAG_BOUND[i]), 1.01 * math.sqrt(DIAG_BOUND[i]))
         for i in range(9)]
    innov = y - ssum(smul(h[k], dx[k]) for k in range(9))
    nu = clamp(innov * rs, -NU_MAX, NU_MAX)
    if gate is not None:   # innovation gate: |nu| > gate (standard deviations) rejects
        use = logical_and(use, nu * nu <= gate * gate)
    nu_c = clamp(nu, -nu_bound, nu_bound)
    dx_new = [select(use, clamp(assume(dx[i] + assume(g[i] * nu_c, -2.0 * DX_BOUND[i],
                                                      2.0 * DX_BOUND[i]),
                                       -DX_BOUND[i], DX_BOUND[i]), -DX_BOUND[i], DX_BOUND[i]),
                     dx[i])
              for i in range(9)]
    rho = assume(assume(s * rs, math.sqrt(r_min), math.sqrt(S_MAX)) * rs, 0.5, 2.0)
    Pn = [[None] * 9 for _ in range(9)]
    for i in range(9):
        for j in range(i, 9):
            b = 1.01 * math.sqrt(DIAG_BOUND[i] * DIAG_BOUND[j])
            t = assume(g[i] * g[j], -b, b)
            # the updated entry stays within its block's range (clamp_p saturates it there
            # anyway): assumed so, it is rounded once into the block's format (interval
            # arithmetic gives it 1-2 bits more range, and each of the four updates per
            # sample rounded P up by a quarter of that coarser LSB on average)
            v = assume(P[i][j] - t - t + rho * t, -ENTRY_BOUND[i][j], ENTRY_BOUND[i][j])
            v = select(use, v, P[i][j])
            Pn[i][j] = v
            Pn[j][i] = v
    return clamp_p(Pn), dx_new


class Eskf(Estimator):
    """Error-state (multiplicative) Kalman filter: attitude error, gyroscope bias and linear
    acceleration (seed 002, Annex B), accelerometer and optional magnetometer (heading)
    measurements, Joseph-form covariance update, covariance output.

    Outputs: q (sensor -> East-North-Up; heading from the magnetometer when mode = 1), bias
    (rad/s), lin_acc (m/s^2, sensor frame), cov_att (attitude error covariance in the earth
    frame, rad^2: xx, xy, xz, yy, yz, zz), var_bias ((rad/s)^2, per axis), mag_disturbed,
    rejected.
    """

    name = "eskf"
    gyro_only_on_bad_acc = True   # an unusable accelerometer: prediction only
    title = "error-state Kalman filter (attitude, gyroscope bias, linear acceleration)"
    inputs = IMU
    params = (
        Param.choice("mode", 1.0, 2, "0: 6D (magnetometer ignored), 1: 9D", labels=("6d", "9d")),
        Param("gyr_noise", 1.0 * DEG, "rad/s/Hz^0.5", 0.001 * DEG, 10.0 * DEG,
              "gyroscope rate noise density (includes scale-factor and misalignment errors)"),
        Param("gyr_rate_err", 0.0, "", 0.0, 0.2,
              "relative rate error (scale factor, misalignment, timing): adds "
              "(gyr_rate_err |w|)^2 per second to the attitude variance"),
        Param("bias_rw", 0.002 * DEG, "rad/s^1.5", 0.0, 1.0 * DEG,
              "gyroscope bias random walk"),
        Param("bias_sigma_init", 0.5 * DEG, "rad/s", 0.01 * DEG, 2.0 * DEG,
              "initial bias standard deviation"),
        Param("acc_noise", 1.0, "m/s^2 s^0.5", ACC_NOISE_MIN, 10.0,
              "accelerometer noise density, including the fast specific-force content that "
              "the linear-acceleration state does not explain (vibration, centripetal jitter); "
              "acc_noise / (g gyr_noise) is the tilt time constant"),
        Param("lin_sigma", 1.0, "m/s^2", 0.01, 5.0,
              "linear acceleration: standard deviation of the Gauss-Markov process"),
        Param("tau_lin", 0.1, "s", 0.005, 10.0,
              "linear acceleration: correlation time of the Gauss-Markov process"),
        Param("acc_gate", 3.0, "", 1.0, ACC_GATE_MAX,
              "accelerometer innovations beyond this many standard deviations are rejected "
              "(taps, impacts)"),
        Param("mag_noise", 9.0 * DEG, "rad s^0.5", MAG_NOISE_MIN, 90.0 * DEG,
              "heading noise density of the magnetometer (noise, calibration, local field); "
              "mag_noise / gyr_noise is the heading time constant"),
        Param("mag_sigma_gate", 10.0 * DEG, "rad", 0.1 * DEG, 90.0 * DEG,
              "heading standard deviation of one magnetometer sample, for the gate only"),
        Param("mag_th", 0.1, "", 0.01, 1.0,
              "largest relative deviation of the field magnitude from the learnt reference"),
        Param("mag_gate", 3.0, "", 1.0, 100.0,
              "innovations beyond this many standard deviations are rejected"),
        Param("tau_mag_ref", 20.0, "s", 1.0, 600.0, "time constant of the reference magnitude"),
        Param("mag_reject_time", 60.0, "s", 1.0, 3600.0,
              "longest rejection: afterwards the current magnitude becomes the reference"),
        Param("init_sigma_att", 5.0 * DEG, "rad", 0.1 * DEG, 18.0 * DEG,
              "initial attitude standard deviation (tilt; heading too when a magnetometer "
              "reading is available)"),
    )
    state = (
        Var("q", 4, -1.0, 1.0, "", "orientation sensor -> ENU", init=(1.0, 0.0, 0.0, 0.0)),
        Var("bias", 3, -BIAS_LIM, BIAS_LIM, "rad/s", "gyroscope bias", init=(0.0, 0.0, 0.0)),
        Var("lin", 3, -LIN_MAX, LIN_MAX, "m/s^2", "linear acceleration, sensor frame",
            init=(0.0, 0.0, 0.0)),
        Var("th_prev", 3, -STEP_MAX, STEP_MAX, "rad", "previous rotation increment (coning)",
            init=(0.0, 0.0, 0.0)),
        *(Var(name, _block_len(rows, cols, sym), -bound, bound, "",
              f"covariance block {name[2:]} (upper triangle, row-major)",
              init=tuple(0.0 for _ in range(_block_len(rows, cols, sym))))
          for name, (rows, cols, sym, bound) in P_BLOCKS.items()),
        Var("ref_n", 1, 0.0, N_MAX, "", "reference field magnitude (input unit)", init=0.0),
        Var("dist_t", 1, 0.0, T_SAT, "s", "time the magnetometer has been rejected", init=0.0),
        Var("t_mag", 1, 0.0, 2.0 * DT_MAX, "s", "time since the previous magnetometer reading",
            init=0.0),
        INITIALISED,
        REJECTED,
    )
    outputs = (
        Var("q", 4, -1.0, 1.0, "", "orientation sensor -> ENU"),
        Var("bias", 3, -BIAS_LIM, BIAS_LIM, "rad/s", "gyroscope bias estimate"),
        Var("lin_acc", 3, -LIN_MAX, LIN_MAX, "m/s^2", "linear acceleration, sensor frame"),
        Var("cov_att", 6, -P_TT, P_TT, "rad^2",
            "attitude error covariance, earth frame (xx, xy, xz, yy, yz, zz)"),
        Var("var_bias", 3, 0.0, P_BB, "(rad/s)^2", "bias variance per axis"),
        Var("mag_disturbed", 1, 0, 1, "", "1 while the magnetometer is rejected", BOOL),
        Var("rejected", 1, 0, 2 ** 31 - 1, "samples",
            "samples or sensor readings rejected as non-finite, saturated or out of range",
            REJECTED.type),
    )

    def step(self, x, u, p):
        nine = p.mode > 0.5
        gyr_ok = all_of(_strict_within(u.gyr, GYR_MAX), u.dt > 0.0, u.dt <= DT_MAX)
        acc_fine = _strict_within(u.acc, ACC_MAX)
        mag_fine = all_of(*(fabs(c) <= MAG_MAX for c in u.mag))
        bad = any_of(logical_not(gyr_ok), logical_not(acc_fine),
                     logical_and(u.mag_valid, logical_not(mag_fine)))
        gyr = _clamp3(Vec3(*u.gyr), -GYR_MAX, GYR_MAX)
        acc = _clamp3(Vec3(*u.acc), -ACC_MAX, ACC_MAX)
        mag = _clamp3(Vec3(*u.mag), -MAG_MAX, MAG_MAX)

        acc_ok = logical_and(gyr_ok, acc_fine)
        do_init = all_of(acc_ok, logical_not(x.initialised), acc.norm_sq() >= ACC_NORM_MIN_SQ)
        live = logical_or(x.initialised, do_init)
        run = logical_and(gyr_ok, x.initialised)
        use_mag = all_of(gyr_ok, live, nine, u.mag_valid, mag_fine)
        dt = select(run, clamp(u.dt, 0.0, DT_MAX), 0.0)

        # -- initial orientation: gravity (half-way quaternion), then heading from the field ----
        a_u, _ = acc.normalized(1e-6)
        a_u = Vec3(*(assume(c, -1.0, 1.0) for c in a_u))
        # half-angle forms (no trigonometry): (1 + cos, sin·axis) degenerates at 180 degrees, so
        # past 90 degrees the equivalent (sin, (1 - cos)·axis) form is used (an upside-down
        # start, or a heading opposite to magnetic north, would otherwise give the identity)
        up = a_u.z >= 0.0
        q_tilt = vselect(up, Quat(1.0 + a_u.z, a_u.y, -a_u.x, 0.0),
                         Quat(a_u.y, 1.0 - a_u.z, 0.0, a_u.x)).normalized(1e-12)  # x by 180°, then tilt
        r_m, _ = rnorm(mag, 1e-6)
        m_unit = Vec3(*(assume(c * r_m, -1.0, 1.0) for c in mag))
        m_t = Vec3(*(assume(c, -1.0, 1.0) for c in q_tilt.rotate(m_unit)))
        rh0, _ = rnorm((m_t.x, m_t.y), 1e-9)
        cos_h = assume(m_t.y * rh0, -1.0, 1.0)
        sin_h = assume(m_t.x * rh0, -1.0, 1.0)
        ahead = cos_h >= 0.0
        hq = vselect(ahead, Quat(1.0 + cos_h, 0.0, 0.0, sin_h),
                     Quat(sin_h, 0.0, 0.0, 1.0 - cos_h)).normalized(1e-12)
        # a product of unit quaternions is one: assumed so, the selection below keeps x.q in
        # its own format (a wider one would round x.q every sample)
        q_init = Quat(*(assume(c_, -1.0, 1.0) for c_ in vselect(use_mag, hq * q_tilt, q_tilt)))

        q = vselect(do_init, q_init, Quat(*x.q))
        bias = Vec3(*x.bias)
        lin = vselect(do_init, Vec3(0.0, 0.0, 0.0), Vec3(*x.lin))
        th_prev = vselect(do_init, Vec3(0.0, 0.0, 0.0), Vec3(*x.th_prev))

        # -- nominal prediction ------------------------------------------------------------------
        w = gyr - bias
        theta = _clamp3(w * dt, -STEP_MAX, STEP_MAX)
        phi = theta + th_prev.cross(theta) * (1.0 / 12.0)
        th2 = fmin(phi.norm_sq(), 4.0)
        s0 = 0.5 - th2 * (1.0 / 48.0)
        q = _renorm(q * Quat(1.0 - 0.125 * th2, s0 * phi.x, s0 * phi.y, s0 * phi.z))
        e = fmin(dt / p.tau_lin, 1.0)
        c = 1.0 - e + 0.5 * e * e                       # exp(-dt / tau_lin), second order
        lin = lin * c

        # -- covariance prediction ---------------------------------------------------------------
        P = unpack_p(x)
        # initial covariance (attitude, bias, linear acceleration)
        s_att = p.init_sigma_att * p.init_sigma_att
        s_head = select(use_mag, s_att, P_TT)
        s_b = p.bias_sigma_init * p.bias_sigma_init
        s_lin = p.lin_sigma * p.lin_sigma
        init_diag = [s_att, s_att, s_head, s_b, s_b, s_b, s_lin, s_lin, s_lin]
        P = [[select(do_init, init_diag[i] if i == j else 0.0, P[i][j]) for j in range(9)]
             for i in range(9)]
        R = rotation_rows(q)                                # sensor -> earth rotation matrix
        F = [[ZERO] * 9 for _ in range(9)]
        for i in range(3):
            F[i][i] = 1.0
            F[3 + i][3 + i] = 1.0
            F[6 + i][6 + i] = c
            for j in range(3):
                F[i][3 + j] = -(R[i][j] * dt)
        P = quadform(F, P)
        # attitude process noise: rate noise plus the rate-proportional error (scale factor,
        # misalignment, timing) of the rotation performed, taken as white over 1 s
        # Each term is capped at the attitude block's bound, which the sum P + q is clamped to
        # anyway (P >= 0): the same values, but the sum keeps a format of P_tt's scale (with
        # the rate term's range, 195 rad^2, it was Q8.23: every step rounded the attitude
        # variance to 1.2e-7 rad^2, a tenth of its per-sample change, and the heading variance
        # froze).
        w2 = fmin(w.norm_sq(), 4.0 * GYR_MAX * GYR_MAX)
        q_att = (fmin(p.gyr_noise * p.gyr_noise * dt, P_TT)
                 + fmin(p.gyr_rate_err * p.gyr_rate_err * w2 * dt, P_TT))
        q_b = p.bias_rw * p.bias_rw * dt
        q_lin = s_lin * (1.0 - c * c)
        for i, qv in enumerate([q_att] * 3 + [q_b] * 3 + [q_lin] * 3):
            P[i][i] = P[i][i] + qv
        P = clamp_p(P)

        # -- accelerometer: three scalar updates in the earth frame ------------------------------
        dx = [0.0] * 9
        f_e = Vec3(*(assume(c_, -ACC_MAX * 1.7321, ACC_MAX * 1.7321) for c_ in q.rotate(acc)))
        lin_e = Vec3(*(assume(c_, -LIN_MAX * 1.7321, LIN_MAX * 1.7321) for c_ in q.rotate(lin)))
        y_acc = f_e - Vec3(lin_e.x, lin_e.y, lin_e.z + G)
        # one sample covers dt seconds of a noise density: variance acc_noise^2 / dt
        r_acc = p.acc_noise * p.acc_noise / fmax(dt, 1e-4)
        r_acc_min = ACC_NOISE_MIN * ACC_NOISE_MIN / DT_MAX
        # y = [g e_z]x dtheta + R da (da in the sensor frame, so heading is not coupled in)
        h_rows = (
            [ZERO, -G, ZERO, ZERO, ZERO, ZERO, R[0][0], R[0][1], R[0][2]],
            [G, ZERO, ZERO, ZERO, ZERO, ZERO, R[1][0], R[1][1], R[1][2]],
            [ZERO, ZERO, ZERO, ZERO, ZERO, ZERO, R[2][0], R[2][1], R[2][2]],
        )
        use_acc = logical_and(acc_ok, run)
        for k in range(3):
            P, dx = scalar_update(P, dx, h_rows[k], y_acc[k], r_acc, r_acc_min, use_acc,
                                     p.acc_gate, ACC_GATE_MAX)

        # -- magnetometer: heading -----------------------------------------------------------------
        m_e = Vec3(*(assume(c_, -1.0, 1.0) for c_ in q.rotate(m_unit)))
        rh, _ = rnorm((m_e.x, m_e.y), 1e-9)
        ex = assume(m_e.x * rh, -1.0, 1.0)
        # the field must point north: a field east of north (ex > 0) means dtheta_z = ex
        y_mag = select(m_e.y >= 0.0, ex, select(ex >= 0.0, 1.0, -1.0))
        m_norm = assume(m_unit.dot(mag), 0.0, MAG_MAX * 1.7321)
        has_ref = logical_and(x.ref_n > 0.0, logical_not(do_init))
        norm_off = logical_and(has_ref, fabs(m_norm - x.ref_n) > p.mag_th * x.ref_n)
        t_mag = fmax(fmin(x.t_mag + dt, 2.0 * DT_MAX), 1e-4)
        r_mag = p.mag_noise * p.mag_noise / t_mag     # one reading covering t_mag seconds
        # gate: the disagreement against the heading variance plus one reading's spread
        s_mag = P[2][2] + p.mag_sigma_gate * p.mag_sigma_gate
        innov = y_mag - dx[2]
        gate_off = innov * innov > p.mag_gate * p.mag_gate * s_mag
        disturbed = all_of(use_mag, has_ref, logical_or(norm_off, gate_off))
        dist_t = select(disturbed, fmin(x.dist_t + dt, T_SAT), select(use_mag, 0.0, x.dist_t))
        # bounded rejection: after mag_reject_time the reading is used whatever the tests say
        # (the reference magnitude is re-learnt; a gate can never lock the heading out)
        relearn = logical_and(use_mag, logical_or(logical_not(has_ref),
                                                   dist_t >= p.mag_reject_time))
        accept = all_of(use_mag, run, logical_or(logical_not(disturbed), relearn))
        h_mag = [ZERO, ZERO, 1.0] + [ZERO] * 6
        r_mag_min = MAG_NOISE_MIN ** 2 / (2.0 * DT_MAX)
        # |y_mag - dx_z| <= 1 + DX_BOUND[2]: the largest normalised innovation
        P, dx = scalar_update(P, dx, h_mag, y_mag, r_mag, r_mag_min, accept,
                                 nu_bound=(1.0 + DX_BOUND[2]) / math.sqrt(r_mag_min))
        k_ref = fmin(dt / p.tau_mag_ref, 1.0)
        # a convex combination of the reference and the reading: within [0, N_MAX], so ref_n
        # keeps its format (interval arithmetic alone gives twice the range: one bit lost and
        # rounded up every sample, a bias of ~2e-6 uT per sample that moved the norm test)
        ref_n = select(relearn, m_norm,
                       select(accept, assume(x.ref_n + (m_norm - x.ref_n) * k_ref, 0.0, N_MAX),
                              x.ref_n))
        dist_t = select(relearn, 0.0, dist_t)
        disturbed = logical_and(disturbed, logical_not(relearn))

        # -- injection and reset ---------------------------------------------------------------------
        dth = [clamp(dx[i], -0.5, 0.5) for i in range(3)]
        q_new = (Quat(1.0, 0.5 * dth[0], 0.5 * dth[1], 0.5 * dth[2]) * q).normalized()
        q_new = Quat(*(assume(c_, -1.0, 1.0) for c_ in q_new))
        bias_new = _clamp3(bias + Vec3(dx[3], dx[4], dx[5]), -BIAS_LIM, BIAS_LIM)
        lin_new = _clamp3(lin + Vec3(dx[6], dx[7], dx[8]), -LIN_MAX, LIN_MAX)

        blocks = pack_p(P)
        # a rejected sample (gyroscope or time step unusable) keeps the state bit for bit: the
        # renormalisation of an unchanged q would otherwise move it by an LSB
        step = logical_or(run, do_init)
        nx = {
            "q": vselect(step, q_new, Quat(*x.q)),
            "bias": vselect(run, bias_new, bias),
            "lin": vselect(step, lin_new, Vec3(*x.lin)),
            "th_prev": vselect(run, theta, th_prev),
            **{k: tuple(select(step, a_, b_) for a_, b_ in zip(v_, getattr(x, k)))
               for k, v_ in blocks.items()},
            "ref_n": clamp(select(step, ref_n, x.ref_n), 0.0, N_MAX),
            "dist_t": select(step, dist_t, x.dist_t),
            "t_mag": select(use_mag, 0.0, fmin(x.t_mag + dt, 2.0 * DT_MAX)),
            "initialised": live,
            "rejected": inc_if(x.rejected, bad),
        }
        ptt = nx["p_tt"]
        pbb = nx["p_bb"]
        y = {"q": nx["q"], "bias": nx["bias"], "lin_acc": nx["lin"],
             "cov_att": ptt,
             "var_bias": (pbb[0], pbb[3], pbb[5]),
             "mag_disturbed": logical_and(live, disturbed),
             "rejected": nx["rejected"]}
        return nx, y
