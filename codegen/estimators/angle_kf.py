"""Kalman smoothing of one joint angle (seed 004: KF, EKF, UKF and square-root UKF).

Seed 004 (Callejas-Cuervo et al., "Estimadores no lineales", 2019) smooths an elbow angle that
the sensor's own fusion produces, with a KF, an EKF and a UKF, but never states the model.  The
models used here are written down in full:

Input: the measured angle z (rad, one joint angle, e.g. flexion), a validity flag, and dt.

``angle-kf`` — linear, constant angular velocity (white angular acceleration):
  x = (θ, θ̇);  θ_k = θ + θ̇ dt, θ̇_k = θ̇;  Q = q_acc [[dt³/3, dt²/2], [dt²/2, dt]]
  (continuous white acceleration of spectral density q_acc, rad²/s³);  z = θ + v, R = σ_z².

``angle-ekf``, ``angle-ukf``, ``angle-srukf`` — nonlinear: a harmonic oscillator about a slowly
moving centre with an unknown frequency (flexion-extension cycles):
  x = (θ, θ̇, c, Ω);  with d = θ − c and φ = Ω dt (the exact solution over dt for constant Ω):
    θ_k = c + d cos φ + (θ̇/Ω) sin φ,   θ̇_k = −d Ω sin φ + θ̇ cos φ,   c_k = c,   Ω_k = Ω
  Q: q_acc as above on (θ, θ̇) (model error), q_c dt on c, q_Ω dt on Ω (random walks);
  Ω is limited to [OMEGA_MIN, OMEGA_MAX] inside the model.  z = θ + v (linear), R = σ_z².
  The EKF linearises the transition (analytic Jacobian).  The UKF uses 2n+1 = 9 sigma points
  x ± sqrt(n/(1−W0)) (√P)_i with weights W0 and (1−W0)/(2n) (seed eqs. 55-58, Julier &
  Uhlmann); W0 is restricted to [0, 0.9]: every weight is then positive and O(1), whereas the
  scaled form with α = 1e-3 used by the seed's source makes W0 ≈ −10⁶ and the covariance a
  difference of huge numbers (useless in float32 or fixed point).  Sigma points are redrawn
  from the predicted mean and covariance for the update (seed eqs. 83-85); as the measurement
  is linear, the unscented update equals the Kalman update exactly (P_xz = P⁻ Hᵀ,
  P_zz = H P⁻ Hᵀ + R), which is what is computed.  The square-root UKF propagates S (P = S Sᵀ):
  S⁻ from a QR triangularisation (Givens rotations, :mod:`givens`) of [√W_i (x_i − x̄), √Q]
  with √W0 (x_0 − x̄) as one more row (W0 >= 0: an update, never a downdate), and the
  measurement update is the rank-one Cholesky downdate of S⁻ by K √P_zz (seed eq. 93, erratum:
  an n×1 column for a scalar measurement, not n×n), evaluated in closed form: for z = θ and a
  lower-triangular S⁻ it scales S⁻'s first column by sqrt(R/P_zz).
  Fixed point: the rotations take c, s from a block-scaled reciprocal norm (``rnorm``) and the
  downdate needs no pivot arithmetic; a square root of a² + b² and 1/r in a format for r down
  to 1e-9 (Q30.1) gave c and s errors of up to 20 % and q deviations of 3.7° in start-up
  transients.
Errata of the seed avoided: eq. 22 lacks Q (P⁻ = F P Fᵀ + Q here); identity matrices, not 1;
eq. 69 has no inverse (P = P⁻ − K P_zz Kᵀ); no numerical Jacobian (eq. 38 divides by zero for a
constant angle).

Outputs: the filtered angle and angular rate (and, for the oscillator filters, the frequency
estimate).  Covariance entries are stored one state variable each, so every entry gets a
fixed-point format suited to its own range.
"""
from __future__ import annotations

import math

from kinefuse.codegen.estimator import Estimator, InputSpec, Param, Var
from kinefuse.codegen.estimators.givens import givens_triangularise
from kinefuse.codegen.ir import BOOL
from kinefuse.codegen.mathlib import sincos
from kinefuse.codegen.scalar import (all_of, assume, clamp, fabs, fmax, inc_if, logical_and,
                                     logical_not, logical_or, rsqrt, select, sqrt)

ANGLE_MAX = 3.2          # rad: joint angles (|θ| <= π)
RATE_MAX = 30.0          # rad/s: beyond the fastest human joint motions (throwing: ~20 rad/s)
OMEGA_MIN, OMEGA_MAX = 0.2, 30.0   # rad/s: oscillator frequency range (0.03-4.8 Hz)
DT_MAX = 0.2             # s: longest step (the angle comes at 5 Hz or faster; longer gaps reject)

ANGLE = InputSpec("angle", (
    Var("angle", 1, -ANGLE_MAX, ANGLE_MAX, "rad", "measured joint angle"),
    Var("angle_valid", 1, 0, 1, "", "1 when angle holds a measurement (0: predict only)", BOOL),
    Var("dt", 1, 0.0, DT_MAX, "s", "time since the previous sample"),
), doc="One joint-angle sample.  A sample with a non-finite or out-of-range angle or time step is "
       "rejected (the state is kept and a counter increments).")

# covariance bounds per state variable (standard deviations): θ, θ̇, c, Ω
SD_MAX = (0.5, 16.0, 0.5, 16.0)
NAMES = ("t", "r", "c", "w")        # θ, rate, centre, omega

ANGLE_OUT = Var("angle", 1, -ANGLE_MAX, ANGLE_MAX, "rad", "filtered angle")
RATE_OUT = Var("rate", 1, -RATE_MAX, RATE_MAX, "rad/s", "filtered angular rate")
OMEGA_OUT = Var("omega", 1, OMEGA_MIN, OMEGA_MAX, "rad/s", "oscillation frequency estimate")
REJECTED = Var("rejected", 1, 0, 2 ** 31 - 1, "samples", "samples rejected as non-finite or out "
               "of range", "int", init=0)
INIT = Var("initialised", 1, 0, 1, "", "1 once a measurement initialised the state", BOOL,
           init=False)


def p_vars(n: int, init_sd):
    """State variables P_ij (i <= j) of an n-state covariance, each with its own range."""
    out = []
    for i in range(n):
        for j in range(i, n):
            b = SD_MAX[i] * SD_MAX[j]
            lo = 0.0 if i == j else -b
            v0 = init_sd[i] * init_sd[i] if i == j else 0.0
            out.append(Var(f"P{NAMES[i]}{NAMES[j]}", 1, lo, b, "",
                           f"covariance of ({NAMES[i]}, {NAMES[j]}) (SI units)", init=v0))
    return tuple(out)


def get_p(x, n: int):
    return [[getattr(x, f"P{NAMES[min(i, j)]}{NAMES[max(i, j)]}") for j in range(n)]
            for i in range(n)]


def put_p(P, n: int) -> dict:
    out = {}
    for i in range(n):
        for j in range(i, n):
            b = SD_MAX[i] * SD_MAX[j]
            v = P[i][j]
            v = clamp(v, 0.0, b) if i == j else assume(v, -b, b)
            out[f"P{NAMES[i]}{NAMES[j]}"] = v
    return out


def s_vars(init_sd):
    """State variables S_ij (i >= j) of a lower Cholesky factor, |S_ij| <= SD_MAX[i]."""
    return tuple(Var(f"S{NAMES[i]}{NAMES[j]}", 1, 0.0 if i == j else -SD_MAX[i], SD_MAX[i], "",
                     f"Cholesky factor entry ({NAMES[i]}, {NAMES[j]}) (SI units)",
                     init=init_sd[i] if i == j else 0.0)
                 for i in range(4) for j in range(i + 1))


def get_s(x):
    return [[getattr(x, f"S{NAMES[i]}{NAMES[j]}") if j <= i else 0.0 for j in range(4)]
            for i in range(4)]


def put_s(S) -> dict:
    return {f"S{NAMES[i]}{NAMES[j]}": (clamp(S[i][j], 0.0, SD_MAX[i]) if i == j else
                                       assume(S[i][j], -SD_MAX[i], SD_MAX[i]))
            for i in range(4) for j in range(i + 1)}


def _sum(terms):
    out = None
    for t in terms:
        out = t if out is None else out + t
    return 0.0 if out is None else out


class Check:
    def __init__(self, u):
        self.dt = u.dt
        ok = all_of(fabs(u.angle) <= ANGLE_MAX, u.dt > 0.0, u.dt <= DT_MAX)
        self.ok = ok
        self.measure = logical_and(ok, u.angle_valid)
        self.bad = logical_not(ok)
        self.dtc = clamp(u.dt, 0.0, DT_MAX)        # dt for computations (range known)


def cv_noise(q_acc, dt):
    """Q of the white-acceleration model on (θ, θ̇): q_acc [[dt³/3, dt²/2], [dt²/2, dt]]."""
    qd = q_acc * dt
    return qd * dt * dt * (1.0 / 3.0), qd * dt * 0.5, qd


SIGMA_MEAS_MIN = 1e-3    # rad: smallest measurement noise accepted (bounds the whitened innovation)


def kalman_scalar_update(x, P, z, r, n: int):
    """Update with z = x_0 + v (H = e_0ᵀ), written with whitened quantities:
    S = P00 + R, g = P[:,0]/sqrt(S), e = (z − x0)/sqrt(S);  x += g e;  P −= g gᵀ
    (K = g/sqrt(S), K S Kᵀ = g gᵀ).  |g_i| <= sqrt(P_ii) (P_i0² <= P_ii P00 <= P_ii S) and
    |e| <= 2 ANGLE_MAX / SIGMA_MEAS_MIN: both bounds hold mathematically and keep the fixed-point
    formats narrow."""
    s = P[0][0] + r
    rs = rsqrt(fmax(s, r))
    nu = z - x[0]
    e = assume(nu * rs, -2.0 * ANGLE_MAX / SIGMA_MEAS_MIN, 2.0 * ANGLE_MAX / SIGMA_MEAS_MIN)
    g = [assume(P[i][0] * rs, -SD_MAX[i], SD_MAX[i]) for i in range(n)]
    xn = [x[i] + g[i] * e for i in range(n)]
    Pn = [[None] * n for _ in range(n)]
    for i in range(n):
        for j in range(i, n):
            v = P[i][j] - g[i] * g[j]
            Pn[i][j] = Pn[j][i] = v
    return xn, Pn


class AngleKF(Estimator):
    """Linear Kalman filter on (angle, rate) with a constant-rate model (module docstring)."""

    name = "angle-kf"
    title = "Joint-angle Kalman filter (constant-rate model)"
    inputs = ANGLE
    params = (
        Param("sigma_meas", 0.03, "rad", SIGMA_MEAS_MIN, 1.0, "measurement noise standard deviation"),
        Param("q_acc", 100.0, "rad^2/s^3", 1e-4, 1e5,
              "spectral density of the white angular acceleration"),
    )
    state = (Var("theta", 1, -ANGLE_MAX, ANGLE_MAX, "rad", "angle", init=0.0),
             Var("rate", 1, -RATE_MAX, RATE_MAX, "rad/s", "angular rate", init=0.0),
             INIT, REJECTED) + p_vars(2, (0.1, 10.0))
    outputs = (ANGLE_OUT, RATE_OUT, REJECTED)

    def step(self, x, u, p):
        chk = Check(u)
        dt = chk.dtc
        P = get_p(x, 2)
        # predict
        t1 = x.theta + x.rate * dt
        q00, q01, q11 = cv_noise(p.q_acc, dt)
        a = P[0][0] + 2.0 * dt * P[0][1] + dt * dt * P[1][1] + q00
        b = P[0][1] + dt * P[1][1] + q01
        c = P[1][1] + q11
        Pm = [[a, b], [b, c]]
        xm = [clamp(t1, -ANGLE_MAX, ANGLE_MAX), x.rate]
        r = p.sigma_meas * p.sigma_meas
        xu, Pu = kalman_scalar_update(xm, Pm, u.angle, r, 2)
        xn = [select(chk.measure, xu[i], xm[i]) for i in range(2)]
        Pn = [[select(chk.measure, Pu[i][j], Pm[i][j]) for j in range(2)] for i in range(2)]
        # initialise on the first measurement
        do_init = logical_and(chk.measure, logical_not(x.initialised))
        run = logical_and(chk.ok, x.initialised)
        theta = select(do_init, u.angle, select(run, xn[0], x.theta))
        rate = select(do_init, 0.0, select(run, xn[1], x.rate))
        P0 = [[r, 0.0], [0.0, 100.0]]
        Pf = [[select(do_init, P0[i][j], select(run, Pn[i][j], P[i][j])) for j in range(2)]
              for i in range(2)]
        theta = clamp(theta, -ANGLE_MAX, ANGLE_MAX)
        rate = clamp(rate, -RATE_MAX, RATE_MAX)
        rejected = inc_if(x.rejected, chk.bad)
        nx = {"theta": theta, "rate": rate, "initialised": logical_or(x.initialised, do_init),
              "rejected": rejected}
        nx.update(put_p(Pf, 2))
        return nx, {"angle": theta, "rate": rate, "rejected": rejected}


# ----------------------------------------------------------------------------------------------
# the oscillator model


def _sinc_g(phi):
    """(sin φ/φ, (sin φ/φ − cos φ)/φ², sin φ, cos φ) for φ >= 0: Taylor series below 0.5 rad
    (no cancellation), the direct quotients above."""
    s, co = sincos(phi)
    p2 = phi * phi
    small = phi < 0.5
    sinc_s = 1.0 - p2 * (1.0 / 6.0 - p2 * (1.0 / 120.0 - p2 * (1.0 / 5040.0)))
    g_s = 1.0 / 3.0 - p2 * (1.0 / 30.0 - p2 * (1.0 / 840.0 - p2 * (1.0 / 45360.0)))
    inv_phi = 1.0 / fmax(phi, 0.5)
    sinc_l = s * inv_phi
    g_l = (sinc_l - co) * (inv_phi * inv_phi)
    sinc = assume(select(small, sinc_s, sinc_l), -0.25, 1.0)
    g = assume(select(small, g_s, g_l), -0.5, 0.34)
    return sinc, g, s, co


def osc_f(x, dt):
    """Transition of (θ, θ̇, c, Ω) over dt (exact for constant Ω); Ω limited to its range.
    sin(Ω dt)/Ω is written dt·sinc(Ω dt) (no division by Ω)."""
    th, v, c, w = x
    w = clamp(w, OMEGA_MIN, OMEGA_MAX)
    phi = w * dt
    sinc, g, s, co = _sinc_g(phi)
    d = th - c
    th1 = c + d * co + v * (dt * sinc)
    v1 = -d * w * s + v * co
    return [th1, v1, c, w], (s, co, d, sinc, g, w)


def osc_jacobian(x, dt, aux):
    """∂f/∂x of :func:`osc_f` (Ω inside its range); ∂θ_k/∂Ω = −d dt sin φ − θ̇ Ω dt³ g(φ),
    g = (sinc φ − cos φ)/φ² (the stable form of θ̇ (dt cos φ/Ω − sin φ/Ω²))."""
    th, v, c, _ = x
    s, co, d, sinc, g, w = aux
    return [
        [co, dt * sinc, 1.0 - co, -d * dt * s - v * w * (dt * dt * dt) * g],
        [-w * s, co, w * s, -d * (s + w * dt * co) - v * dt * s],
        [0.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]


OSC_PARAMS = (
    Param("sigma_meas", 0.03, "rad", SIGMA_MEAS_MIN, 1.0, "measurement noise standard deviation"),
    Param("q_acc", 1.0, "rad^2/s^3", 1e-6, 1e4,
          "spectral density of the angular acceleration the oscillator does not explain"),
    Param("q_center", 0.01, "rad^2/s", 1e-8, 10.0, "random-walk density of the centre angle"),
    Param("q_omega", 1.0, "rad^2/s^3", 1e-6, 100.0,
          "random-walk density of the frequency Ω ((rad/s)²/s)"),
    Param("omega0", 8.0, "rad/s", OMEGA_MIN, OMEGA_MAX,
          "initial frequency (a high start keeps the sigma points clear of the lower limit)"),
)
OSC_INIT_SD = (0.03, 3.0, 0.5, 5.0)


def osc_state(sqrt_form: bool = False):
    return (Var("theta", 1, -ANGLE_MAX, ANGLE_MAX, "rad", "angle", init=0.0),
            Var("rate", 1, -RATE_MAX, RATE_MAX, "rad/s", "angular rate", init=0.0),
            Var("center", 1, -ANGLE_MAX, ANGLE_MAX, "rad", "centre of the oscillation", init=0.0),
            Var("omega", 1, OMEGA_MIN, OMEGA_MAX, "rad/s", "frequency", init=3.0),
            INIT, REJECTED) + (s_vars(OSC_INIT_SD) if sqrt_form else p_vars(4, OSC_INIT_SD))


def osc_noise(p, dt):
    """Q of the oscillator model (4×4, structural zeros as 0.0)."""
    q00, q01, q11 = cv_noise(p.q_acc, dt)
    return [[q00, q01, 0.0, 0.0], [q01, q11, 0.0, 0.0], [0.0, 0.0, p.q_center * dt, 0.0],
            [0.0, 0.0, 0.0, p.q_omega * dt]]


def clamp_state(xs):
    return [clamp(xs[0], -ANGLE_MAX, ANGLE_MAX), clamp(xs[1], -RATE_MAX, RATE_MAX),
            clamp(xs[2], -ANGLE_MAX, ANGLE_MAX), clamp(xs[3], OMEGA_MIN, OMEGA_MAX)]


def osc_finish(x, u, p, chk, xn, Pn, P, sqrt_form: bool = False):
    """Initialisation, state selection and outputs shared by the oscillator filters.  With
    ``sqrt_form`` Pn and P are lower Cholesky factors (stored as S_ij, i >= j)."""
    do_init = logical_and(chk.measure, logical_not(x.initialised))
    run = logical_and(chk.ok, x.initialised)
    x0 = [u.angle, 0.0, u.angle, p.omega0]
    r = p.sigma_meas * p.sigma_meas
    d0 = (p.sigma_meas, OSC_INIT_SD[1], OSC_INIT_SD[2], OSC_INIT_SD[3]) if sqrt_form else \
        (r, OSC_INIT_SD[1] ** 2, OSC_INIT_SD[2] ** 2, OSC_INIT_SD[3] ** 2)
    P0 = [[d0[i] if i == j else 0.0 for j in range(4)] for i in range(4)]
    xs = [x.theta, x.rate, x.center, x.omega]
    xf = clamp_state([select(do_init, x0[i], select(run, xn[i], xs[i])) for i in range(4)])
    Pf = [[select(do_init, P0[i][j], select(run, Pn[i][j], P[i][j])) for j in range(4)]
          for i in range(4)]
    rejected = inc_if(x.rejected, chk.bad)
    nx = {"theta": xf[0], "rate": xf[1], "center": xf[2], "omega": xf[3],
          "initialised": logical_or(x.initialised, do_init), "rejected": rejected}
    nx.update(put_s(Pf) if sqrt_form else put_p(Pf, 4))
    return nx, {"angle": xf[0], "rate": xf[1], "omega": xf[3], "rejected": rejected}


def matmul(A, B):
    return [[_sum(A[i][k] * B[k][j] for k in range(len(B)) if not _zero(A[i][k])
                  and not _zero(B[k][j])) for j in range(len(B[0]))] for i in range(len(A))]


def _zero(v):
    return isinstance(v, float) and v == 0.0


class AngleEKF(Estimator):
    """Extended Kalman filter on (angle, rate, centre, frequency) with the oscillator model
    (module docstring)."""

    name = "angle-ekf"
    title = "Joint-angle extended Kalman filter (oscillator model)"
    inputs = ANGLE
    params = OSC_PARAMS
    state = osc_state()
    outputs = (ANGLE_OUT, RATE_OUT, OMEGA_OUT, REJECTED)

    def step(self, x, u, p):
        chk = Check(u)
        dt = chk.dtc
        P = get_p(x, 4)
        xs = [x.theta, x.rate, x.center, x.omega]
        xm, aux = osc_f(xs, dt)
        F = osc_jacobian(xs, dt, aux)
        FP = matmul(F, P)
        Q = osc_noise(p, dt)
        Pm = [[None] * 4 for _ in range(4)]
        for i in range(4):
            for j in range(i, 4):
                v = _sum(FP[i][k] * F[j][k] for k in range(4) if not _zero(F[j][k]))
                if not _zero(Q[i][j]):
                    v = v + Q[i][j]
                Pm[i][j] = Pm[j][i] = v
        xm = clamp_state(xm)
        r = p.sigma_meas * p.sigma_meas
        xu, Pu = kalman_scalar_update(xm, Pm, u.angle, r, 4)
        xn = [select(chk.measure, xu[i], xm[i]) for i in range(4)]
        Pn = [[select(chk.measure, Pu[i][j], Pm[i][j]) for j in range(4)] for i in range(4)]
        return osc_finish(x, u, p, chk, xn, Pn, P)


# ----------------------------------------------------------------------------------------------
# unscented filters

N = 4


def cholesky(P, floor: float):
    """Lower Cholesky factor of an n×n covariance (pivots floored; |L_ij| <= sqrt(P_ii))."""
    n = len(P)
    L = [[0.0] * n for _ in range(n)]
    for j in range(n):
        d = P[j][j]
        for k in range(j):
            d = d - L[j][k] * L[j][k]
        ljj = sqrt(fmax(d, floor))
        L[j][j] = assume(ljj, floor ** 0.5, SD_MAX[j])
        inv = 1.0 / L[j][j]
        for i in range(j + 1, n):
            s = P[i][j]
            for k in range(j):
                s = s - L[i][k] * L[j][k]
            L[i][j] = assume(s * inv, -SD_MAX[i], SD_MAX[i])
    return L


def sigma_points(xm, L, gamma):
    """2n+1 points: x, x + γ L[:, i], x − γ L[:, i]."""
    pts = [list(xm)]
    for sgn in (1.0, -1.0):
        for i in range(N):
            pts.append([xm[k] + sgn * gamma * L[k][i] for k in range(N)])
    return pts


def ut_weights(w0):
    """W0 and W_i = (1 − W0)/(2n); γ = sqrt(n/(1 − W0))."""
    wi = (1.0 - w0) * (1.0 / (2.0 * N))
    gamma = sqrt(N / fmax(1.0 - w0, 0.1))
    return wi, gamma


UKF_PARAMS = OSC_PARAMS + (
    Param("w0", 0.0, "", 0.0, 0.9,
          "weight of the central sigma point (W_i = (1 − W0)/(2n); spread sqrt(n/(1 − W0)))"),
)
P_FLOOR = 1e-9


def propagate(xs, L, p, dt):
    """Sigma points of (xs, L Lᵀ) through the oscillator: returns (mean, deviations, W_i)."""
    wi, gamma = ut_weights(p.w0)
    pts = sigma_points(xs, L, gamma)
    fp = [osc_f(pt, dt)[0] for pt in pts]
    mean = [p.w0 * fp[0][k] + wi * _sum(fp[j][k] for j in range(1, 2 * N + 1))
            for k in range(N)]
    dev = [[fp[j][k] - mean[k] for k in range(N)] for j in range(2 * N + 1)]
    return mean, dev, wi


class AngleUKF(Estimator):
    """Unscented Kalman filter on (angle, rate, centre, frequency) with the oscillator model
    (module docstring)."""

    name = "angle-ukf"
    title = "Joint-angle unscented Kalman filter (oscillator model)"
    inputs = ANGLE
    params = UKF_PARAMS
    state = osc_state()
    outputs = (ANGLE_OUT, RATE_OUT, OMEGA_OUT, REJECTED)

    def step(self, x, u, p):
        chk = Check(u)
        dt = chk.dtc
        P = get_p(x, N)
        xs = [x.theta, x.rate, x.center, x.omega]
        mean, dev, wi = propagate(xs, cholesky(P, P_FLOOR), p, dt)
        Q = osc_noise(p, dt)
        Pm = [[None] * N for _ in range(N)]
        for i in range(N):
            for j in range(i, N):
                v = p.w0 * (dev[0][i] * dev[0][j]) + wi * _sum(dev[k][i] * dev[k][j]
                                                              for k in range(1, 2 * N + 1))
                if not _zero(Q[i][j]):
                    v = v + Q[i][j]
                Pm[i][j] = Pm[j][i] = v
        xm = clamp_state(mean)
        r = p.sigma_meas * p.sigma_meas
        # linear measurement: the unscented update is the Kalman update (module docstring)
        xu, Pu = kalman_scalar_update(xm, Pm, u.angle, r, N)
        xn = [select(chk.measure, xu[i], xm[i]) for i in range(N)]
        Pn = [[select(chk.measure, Pu[i][j], Pm[i][j]) for j in range(N)] for i in range(N)]
        return osc_finish(x, u, p, chk, xn, Pn, P)


class AngleSRUKF(Estimator):
    """Square-root unscented Kalman filter on (angle, rate, centre, frequency) with the
    oscillator model: the covariance is carried as its Cholesky factor (module docstring)."""

    name = "angle-srukf"
    title = "Joint-angle square-root UKF (oscillator model)"
    inputs = ANGLE
    params = UKF_PARAMS
    state = osc_state(sqrt_form=True)
    outputs = (ANGLE_OUT, RATE_OUT, OMEGA_OUT, REJECTED)

    def step(self, x, u, p):
        chk = Check(u)
        dt = chk.dtc
        S0 = get_s(x)
        xs = [x.theta, x.rate, x.center, x.omega]
        mean, dev, wi = propagate(xs, S0, p, dt)
        # S⁻: QR of [sqrt(W_i) dev_i (i = 0..2n), sqrt(Q)]ᵀ (W0 >= 0: its point is one more row)
        swi = sqrt(fmax(wi, 0.0))
        sw0 = sqrt(fmax(p.w0, 0.0))
        rows = [[swi * dev[k][i] for i in range(N)] for k in range(1, 2 * N + 1)]
        sq = sqrt(fmax(p.q_acc * dt, 0.0))                   # white-acceleration Q, closed form
        rows.append([sq * dt * (1.0 / math.sqrt(3.0)), sq * (math.sqrt(3.0) / 2.0), 0.0, 0.0])
        rows.append([0.0, sq * 0.5, 0.0, 0.0])
        rows.append([0.0, 0.0, sqrt(fmax(p.q_center * dt, 0.0)), 0.0])
        rows.append([0.0, 0.0, 0.0, sqrt(fmax(p.q_omega * dt, 0.0))])
        rows.append([sw0 * dev[0][i] for i in range(N)])
        # every row of the pre-array and of its rotations is bounded by the factor's row norms
        # (Q formats: the bounds of the stored factor's columns, 4 SD_MAX as before)
        Rt = givens_triangularise(rows, [4.0 * SD_MAX[k] for k in range(N)])
        S = [[assume(Rt[j][i], 0.0 if i == j else -2.0 * SD_MAX[i], 2.0 * SD_MAX[i])
              if j <= i else 0.0 for j in range(N)] for i in range(N)]        # Rᵀ
        xm = clamp_state(mean)
        # measurement z = θ: P_zz = S_00² + R, P_xz = S S_0ᵀ = S[:,0] S_00, K = P_xz / P_zz;
        # written with g = K sqrt(P_zz) (bounded by SD_MAX) and the whitened innovation
        r = p.sigma_meas * p.sigma_meas
        pzz = S[0][0] * S[0][0] + r
        rs = rsqrt(fmax(pzz, r))
        g = [assume(S[i][0] * S[0][0] * rs, -SD_MAX[i], SD_MAX[i]) for i in range(N)]
        e = assume((u.angle - xm[0]) * rs, -2.0 * ANGLE_MAX / SIGMA_MEAS_MIN,
                   2.0 * ANGLE_MAX / SIGMA_MEAS_MIN)
        xu = [xm[i] + g[i] * e for i in range(N)]
        # S⁺ = cholupdate(S⁻, K sqrt(P_zz), −1) (seed eq. 93), in closed form: row 0 of the
        # lower-triangular S⁻ is (S_00, 0, 0, 0), so P⁺ = S⁻ (I − S_00²/P_zz e_0 e_0ᵀ) S⁻ᵀ and the
        # downdated factor is S⁻ with column 0 scaled by sqrt(R/P_zz) (no pivot can cancel)
        f = assume(p.sigma_meas * rs, 0.0, 1.0)
        Su = [[assume(S[i][0] * f, 0.0 if i == 0 else -2.0 * SD_MAX[i], 2.0 * SD_MAX[i])
               if j == 0 else S[i][j] for j in range(N)] for i in range(N)]
        xn = [select(chk.measure, xu[i], xm[i]) for i in range(N)]
        Sn = [[select(chk.measure, Su[i][j], S[i][j]) for j in range(N)] for i in range(N)]
        return osc_finish(x, u, p, chk, xn, Sn, S0, sqrt_form=True)
