"""Synthetic truth for the dynamic EKFs: analytic motion, inverse dynamics, noisy sensors.

The equations here are written independently of the filters' AD-based model code (closed-form
R, Ṙ, M and Q_g in numpy) so that the benchmarks and tests compare two implementations.

Double pendulum (seed 000 §3.3.1, Tables 3.1 / A.1): point 2 pinned at the origin; the bars
swing with θ2(t) = A cos(2πft), θ1(t) = −θ2(t) (A = 0.9 rad, f = 0.5 Hz, 3 s, Δt = 10 ms), so
point 0 moves up and down a vertical line (a squat-like motion) and the motion starts at rest.
The seed gives amplitude, frequency and duration but not the waveform; this one is ours.
Reactions (Fx, Fy, T2) at point 2 and the joint torque τ1 follow by inverse dynamics
(T2 is the moment the pin must supply for the prescribed motion).  Sensors: markers with white
camera noise plus skin-motion noise (white noise through a 2nd-order Butterworth low-pass at
the motion frequency, scaled to its standard deviation), efforts with white noise.

Leg (wearable): hip fixed; thigh and shank angles follow a gait-like periodic pattern
(Fourier series, 1 Hz stride: hip flexion-extension ±25°, knee flexion 5-65°).  Sensors: a
gyroscope (rad/s) and a two-axis accelerometer (m/s², specific force in the segment frame)
on each segment, white noise at the levels of a consumer IMU.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np

G = 9.81


# =============================================================================================
# Double pendulum
# =============================================================================================

@dataclasses.dataclass
class PendulumConfig:
    m1: float = 50.0            # kg (Table 3.1 and A.1)
    m2: float = 35.0            # kg (Table A.1; Table 3.1: 25)
    L: float = 0.8              # m
    g: float = G
    amplitude: float = 0.9      # rad
    freq: float = 0.5           # Hz
    duration: float = 3.0       # s
    dt: float = 0.01            # s
    sigma_marker: float = 1e-3  # m, camera (white); Table A.1
    sigma_skin: float = 1e-2    # m, skin motion (low-pass); Table 3.1
    sigma_force: float = 0.05   # N; Table A.1
    sigma_torque: float = 0.005  # N*m; Table A.1
    seed: int = 0

    @classmethod
    def table_3_1(cls, **kw):
        d = dict(m2=25.0, sigma_marker=2e-5, sigma_skin=1e-2, sigma_force=0.3, sigma_torque=0.3)
        d.update(kw)
        return cls(**d)

    @classmethod
    def table_a_1(cls, **kw):
        return cls(**kw)


# marker geometry (must match codegen.estimators.dynamics.models.PENDULUM_MARKERS)
MARKERS = ((1, 0.25, 0.05), (1, 0.75, -0.05), (2, 0.25, 0.05), (2, 0.75, -0.05))


def pendulum_motion(cfg: PendulumConfig, t: np.ndarray):
    """z, ż, z̈ (N, 4) of the prescribed motion (point 2 at the origin)."""
    w = 2.0 * math.pi * cfg.freq
    A, L = cfg.amplitude, cfg.L
    th2, th2d, th2dd = A * np.cos(w * t), -A * w * np.sin(w * t), -A * w * w * np.cos(w * t)
    th1, th1d, th1dd = -th2, -th2d, -th2dd
    # r0 = r2 - L u1 - L u2 with u = (sin th, -cos th), r2 = 0
    x0 = -L * np.sin(th1) - L * np.sin(th2)
    y0 = L * np.cos(th1) + L * np.cos(th2)
    x0d = -L * np.cos(th1) * th1d - L * np.cos(th2) * th2d
    y0d = -L * np.sin(th1) * th1d - L * np.sin(th2) * th2d
    x0dd = (L * np.sin(th1) * th1d ** 2 - L * np.cos(th1) * th1dd
            + L * np.sin(th2) * th2d ** 2 - L * np.cos(th2) * th2dd)
    y0dd = (-L * np.cos(th1) * th1d ** 2 - L * np.sin(th1) * th1dd
            - L * np.cos(th2) * th2d ** 2 - L * np.sin(th2) * th2dd)
    z = np.stack([x0, y0, th1, th2], 1)
    zd = np.stack([x0d, y0d, th1d, th2d], 1)
    zdd = np.stack([x0dd, y0dd, th1dd, th2dd], 1)
    return z, zd, zdd


def pendulum_R(z, L):
    """Seed eq. 3.57 and its time derivative pattern (closed form)."""
    t1, t2 = z[2], z[3]
    return np.array([[1, 0, 0, 0], [0, 1, 0, 0],
                     [1, 0, L * math.cos(t1), 0], [0, 1, L * math.sin(t1), 0],
                     [1, 0, L * math.cos(t1), L * math.cos(t2)],
                     [0, 1, L * math.sin(t1), L * math.sin(t2)]], dtype=float)


def pendulum_Rdot(z, zd, L):
    t1, t2 = z[2], z[3]
    w1, w2 = zd[2], zd[3]
    Rd = np.zeros((6, 4))
    Rd[2, 2] = Rd[4, 2] = -L * math.sin(t1) * w1
    Rd[3, 2] = Rd[5, 2] = L * math.cos(t1) * w1
    Rd[4, 3] = -L * math.sin(t2) * w2
    Rd[5, 3] = L * math.cos(t2) * w2
    return Rd


def pendulum_mbar(m1, m2):
    a1, b1, a2, b2, a12 = m1 / 3, m1 / 6, m2 / 3, m2 / 6, (m1 + m2) / 3
    return np.array([[a1, 0, b1, 0, 0, 0], [0, a1, 0, b1, 0, 0],
                     [b1, 0, a12, 0, b2, 0], [0, b1, 0, a12, 0, b2],
                     [0, 0, b2, 0, a2, 0], [0, 0, 0, b2, 0, a2]])


def pendulum_qbar(m1, m2, g):
    return -np.array([0, m1 * g / 2, 0, (m1 + m2) * g / 2, 0, m2 * g / 2])


def pendulum_Bt(z, L, residual=False):
    """Seed eq. 3.59 (+ the residual identity block)."""
    t1, t2 = z[2], z[3]
    B = np.array([[0, 1, 0, 0], [0, 0, 1, 0],
                  [-1, L * math.cos(t1), L * math.sin(t1), 0],
                  [1, L * math.cos(t2), L * math.sin(t2), 1]], dtype=float)
    if residual:
        B = np.hstack([B, np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 0]], float)])
    return B


def pendulum_M_Qg(z, zd, m1, m2, L, g):
    R = pendulum_R(z, L)
    Mb = pendulum_mbar(m1, m2)
    M = R.T @ Mb @ R
    Qg = R.T @ (pendulum_qbar(m1, m2, g) - Mb @ (pendulum_Rdot(z, zd, L) @ zd))
    return M, Qg


def pendulum_inverse_dynamics(z, zd, zdd, m1, m2, L, g):
    """T_e = [τ1 Fx Fy T2] with Bᵀ T_e = M z̈ − Q_g (Bᵀ is square and invertible)."""
    out = np.zeros((len(z), 4))
    for k in range(len(z)):
        M, Qg = pendulum_M_Qg(z[k], zd[k], m1, m2, L, g)
        out[k] = np.linalg.solve(pendulum_Bt(z[k], L), M @ zdd[k] - Qg)
    return out


def pendulum_markers(z, L):
    """(N, 8) marker coordinates."""
    out = np.zeros((len(z), 8))
    for k, (x0, y0, t1, t2) in enumerate(z):
        p = [np.array([x0, y0])]
        p.append(p[0] + L * np.array([math.sin(t1), -math.cos(t1)]))
        p.append(p[1] + L * np.array([math.sin(t2), -math.cos(t2)]))
        for i, (bar, s, d) in enumerate(MARKERS):
            a, b = p[bar - 1], p[bar]
            e = b - a
            nrm = np.array([-e[1], e[0]]) / L
            out[k, 2 * i:2 * i + 2] = a + s * e + d * nrm
    return out


def lowpass_noise(rng, n: int, cols: int, sigma: float, fc: float, fs: float) -> np.ndarray:
    """White noise through a 2nd-order Butterworth low-pass (zero phase), each column scaled
    to standard deviation sigma."""
    from scipy.signal import butter, filtfilt
    if sigma == 0.0:
        return np.zeros((n, cols))
    pad = 4 * int(fs / fc)
    w = rng.standard_normal((n + 2 * pad, cols))
    b, a = butter(2, fc / (fs / 2.0))
    y = filtfilt(b, a, w, axis=0)[pad:pad + n]
    return y * (sigma / y.std(axis=0))


@dataclasses.dataclass
class PendulumTrial:
    cfg: PendulumConfig
    t: np.ndarray             # (N,) s
    z: np.ndarray             # (N, 4) true x0 y0 θ1 θ2
    zd: np.ndarray
    zdd: np.ndarray
    te: np.ndarray            # (N, 4) true τ1 Fx Fy T2
    markers: np.ndarray       # (N, 8) measured
    marker_valid: np.ndarray  # (N, 4) bool
    efforts: np.ndarray       # (N, 4) measured τ1 Fx Fy T2
    effort_valid: np.ndarray  # (N, 4) bool
    dt: np.ndarray            # (N,)

    def inputs(self) -> dict[str, np.ndarray]:
        """The filter's input record (codegen runner format)."""
        return {"markers": self.markers, "marker_valid": self.marker_valid,
                "efforts": self.efforts, "effort_valid": self.effort_valid, "dt": self.dt}

    def peak_speed_time(self) -> float:
        """Time of the highest |θ̇1| after the first half period (occlusion study)."""
        k0 = int(0.5 / self.cfg.freq / self.cfg.dt / 2)
        return float(self.t[k0 + np.argmax(np.abs(self.zd[k0:, 2]))])


def pendulum_trial(cfg: PendulumConfig | None = None, tau1_sensor: bool = False
                   ) -> PendulumTrial:
    """A noisy trial; the default sensor set is the seed's (all but τ1)."""
    cfg = cfg or PendulumConfig()
    n = int(round(cfg.duration / cfg.dt))
    t = np.arange(n) * cfg.dt
    z, zd, zdd = pendulum_motion(cfg, t)
    te = pendulum_inverse_dynamics(z, zd, zdd, cfg.m1, cfg.m2, cfg.L, cfg.g)
    rng = np.random.default_rng(cfg.seed)
    mk = pendulum_markers(z, cfg.L)
    mk = mk + rng.standard_normal(mk.shape) * cfg.sigma_marker
    mk = mk + lowpass_noise(rng, n, 8, cfg.sigma_skin, cfg.freq, 1.0 / cfg.dt)
    eff = te + rng.standard_normal(te.shape) * np.array(
        [cfg.sigma_torque, cfg.sigma_force, cfg.sigma_force, cfg.sigma_torque])
    ev = np.ones((n, 4), bool)
    ev[:, 0] = tau1_sensor
    return PendulumTrial(cfg, t, z, zd, zdd, te, mk, np.ones((n, 4), bool), eff, ev,
                         np.full(n, cfg.dt))


# =============================================================================================
# Leg
# =============================================================================================

@dataclasses.dataclass
class LegConfig:
    """Anthropometry after Winter (2009) for a 75 kg, 1.75 m adult: thigh 0.100 M, L 0.245 H,
    CoM 0.433 L from the hip, radius of gyration 0.323 L; leg+foot 0.061 M, shank L 0.246 H,
    CoM 0.606 of the shank length from the knee, radius of gyration 0.416 of that length."""
    mass: float = 75.0
    height: float = 1.75
    g: float = G
    a1: float = 0.20            # m, thigh IMU along the thigh from the hip
    b1: float = 0.07            # m, ... anterior offset (skin surface)
    a2: float = 0.20            # m, shank IMU along the shank from the knee
    b2: float = 0.05
    stride_hz: float = 1.0
    duration: float = 10.0      # s
    rate_hz: float = 100.0
    sigma_gyr: float = 0.0015   # rad/s (0.085 deg/s, consumer IMU at 100 Hz)
    sigma_acc: float = 0.03     # m/s^2 (3 mg)
    sigma_foot: float = 1.0     # N
    foot_force: bool = False    # apply an external ankle force (stance-like) and measure it
    seed: int = 0
    # Where the recording starts.  By default it starts in motion: at t = 0 the leg is in
    # terminal swing (hip flexed 0.48 rad, shank 0.26 rad) and decelerating fast (-20 / -39
    # rad/s^2 at a 1 Hz stride, -40 / -77 at 1.4 Hz).  phase shifts the gait (fraction of a
    # stride at t = 0); stand_s > 0 starts at rest instead, as a clinical protocol would: the
    # leg hangs still and vertical for stand_s, then the gait's amplitude grows smoothly
    # (quintic, so the angular accelerations are continuous) over one stride.
    phase: float = 0.0
    stand_s: float = 0.0

    @property
    def L1(self):
        return 0.245 * self.height

    @property
    def L2(self):
        return 0.246 * self.height

    @property
    def m1(self):
        return 0.100 * self.mass

    @property
    def m2(self):
        return 0.061 * self.mass

    @property
    def c1(self):
        return 0.433 * self.L1

    @property
    def c2(self):
        return 0.606 * self.L2

    @property
    def I1(self):
        return self.m1 * (0.323 * self.L1) ** 2

    @property
    def I2(self):
        return self.m2 * (0.416 * self.L2) ** 2

    def params(self) -> dict[str, float]:
        """Filter parameters (LegEKF names) for this subject."""
        return {"m1": self.m1, "m2": self.m2, "L1": self.L1, "c1": self.c1, "c2": self.c2,
                "I1": self.I1, "I2": self.I2, "g": self.g, "a1": self.a1, "b1": self.b1,
                "a2": self.a2, "b2": self.b2}


# gait-like pattern: hip angle (thigh from vertical, + flexion) and knee flexion, Fourier
# coefficients (rad) of a 1-periodic function: value = c0 + sum a_k cos(2πkt) + b_k sin(2πkt)
_HIP = (0.05, ((0.40, 0.10), (0.03, -0.03)))           # ~ -20..+30 deg
_KNEE = (0.55, ((-0.25, -0.35), (-0.10, 0.08), (0.02, 0.03)))   # ~ 5..65 deg flexion


def _fourier(c, t, f):
    c0, terms = c
    v = np.full_like(t, c0)
    vd = np.zeros_like(t)
    vdd = np.zeros_like(t)
    for k, (a, b) in enumerate(terms, start=1):
        w = 2 * math.pi * k * f
        v += a * np.cos(w * t) + b * np.sin(w * t)
        vd += -a * w * np.sin(w * t) + b * w * np.cos(w * t)
        vdd += -a * w * w * np.cos(w * t) - b * w * w * np.sin(w * t)
    return v, vd, vdd


def _onset(t, t0, T):
    """Quintic smoothstep from 0 (t <= t0) to 1 (t >= t0 + T) and its two derivatives."""
    x = np.clip((t - t0) / T, 0.0, 1.0)
    e = x ** 3 * (10.0 - 15.0 * x + 6.0 * x * x)
    ed = 30.0 * x * x * (1.0 - x) ** 2 / T
    edd = 60.0 * x * (1.0 - x) * (1.0 - 2.0 * x) / (T * T)
    return e, ed, edd


def leg_motion(cfg: LegConfig, t):
    """z = [θ1, θ2] (thigh, shank absolute from the downward vertical), ż, z̈; knee flexion is
    θ1 − θ2.  See LegConfig.phase and stand_s for where the trial starts."""
    tg = t + cfg.phase / cfg.stride_hz
    h, hd, hdd = _fourier(_HIP, tg, cfg.stride_hz)
    k, kd, kdd = _fourier(_KNEE, tg, cfg.stride_hz)
    z = np.stack([h, h - k], 1)
    zd = np.stack([hd, hd - kd], 1)
    zdd = np.stack([hdd, hdd - kdd], 1)
    if cfg.stand_s > 0:
        e, ed, edd = (v[:, None] for v in _onset(t, cfg.stand_s, 1.0 / cfg.stride_hz))
        z, zd, zdd = e * z, ed * z + e * zd, edd * z + 2.0 * ed * zd + e * zdd
    return z, zd, zdd


def leg_M_bias(cfg: LegConfig, z, zd):
    """Closed-form M(z) and Q_g(z, ż) of the two-link leg in absolute angles."""
    t1, t2 = z
    w1, w2 = zd
    m1, m2, L1, c1, c2, I1, I2, g = cfg.m1, cfg.m2, cfg.L1, cfg.c1, cfg.c2, cfg.I1, cfg.I2, cfg.g
    c12 = math.cos(t1 - t2)
    s12 = math.sin(t1 - t2)
    M = np.array([[I1 + m1 * c1 ** 2 + m2 * L1 ** 2, m2 * L1 * c2 * c12],
                  [m2 * L1 * c2 * c12, I2 + m2 * c2 ** 2]])
    Q = np.array([-m2 * L1 * c2 * s12 * w2 ** 2 - (m1 * c1 + m2 * L1) * g * math.sin(t1),
                  m2 * L1 * c2 * s12 * w1 ** 2 - m2 * c2 * g * math.sin(t2)])
    return M, Q


def leg_ankle(cfg: LegConfig, z):
    t1, t2 = z
    return np.array([cfg.L1 * math.sin(t1) + cfg.L2 * math.sin(t2),
                     -cfg.L1 * math.cos(t1) - cfg.L2 * math.cos(t2)])


def leg_ankle_jacobian(cfg: LegConfig, z):
    t1, t2 = z
    return np.array([[cfg.L1 * math.cos(t1), cfg.L2 * math.cos(t2)],
                     [cfg.L1 * math.sin(t1), cfg.L2 * math.sin(t2)]])


def leg_Bt(cfg: LegConfig, z, foot: bool):
    """Generalised forces of [τ_hip, τ_knee (, F_ax, F_ay)] (columns)."""
    B = np.array([[1.0, -1.0], [0.0, 1.0]])
    if foot:
        B = np.hstack([B, leg_ankle_jacobian(cfg, z).T])
    return B


def leg_foot_force(cfg: LegConfig, t):
    """A stance-like external force at the ankle (N): during the first 60 % of each stride an
    upward push of up to 150 N and a small backward shear; zero otherwise."""
    ph = (t * cfg.stride_hz + cfg.phase) % 1.0
    s = np.where(ph < 0.6, np.sin(np.pi * ph / 0.6) ** 2, 0.0)
    if cfg.stand_s > 0:
        s = s * _onset(t, cfg.stand_s, 1.0 / cfg.stride_hz)[0]
    return np.stack([-20.0 * s, 150.0 * s], 1)


def leg_imu(cfg: LegConfig, z, zd, zdd):
    """Ideal gyro (N, 2) and accelerometer (N, 4: seg1 along, seg1 normal, seg2 along,
    seg2 normal) readings."""
    n = len(z)
    gyr = zd.copy()
    acc = np.zeros((n, 4))
    for k in range(n):
        t1, t2 = z[k]
        w1, w2 = zd[k]
        a1_, a2_ = zdd[k]
        u1 = np.array([math.sin(t1), -math.cos(t1)])
        v1 = np.array([math.cos(t1), math.sin(t1)])
        u2 = np.array([math.sin(t2), -math.cos(t2)])
        v2 = np.array([math.cos(t2), math.sin(t2)])
        # d u/dθ = v, d v/dθ = -u
        # p1 = a1 u1 + b1 v1
        acc1 = (cfg.a1 * (a1_ * v1 - w1 ** 2 * u1) + cfg.b1 * (-a1_ * u1 - w1 ** 2 * v1))
        knee_acc = cfg.L1 * (a1_ * v1 - w1 ** 2 * u1)
        acc2 = knee_acc + cfg.a2 * (a2_ * v2 - w2 ** 2 * u2) + cfg.b2 * (-a2_ * u2 - w2 ** 2 * v2)
        gvec = np.array([0.0, -cfg.g])
        f1 = acc1 - gvec
        f2 = acc2 - gvec
        acc[k] = [f1 @ u1, f1 @ v1, f2 @ u2, f2 @ v2]
    return gyr, acc


@dataclasses.dataclass
class LegTrial:
    cfg: LegConfig
    t: np.ndarray
    z: np.ndarray
    zd: np.ndarray
    zdd: np.ndarray
    te: np.ndarray            # (N, 2 or 4) true τ_hip, τ_knee (, F_ax, F_ay)
    gyr: np.ndarray           # (N, 2) rad/s
    acc: np.ndarray           # (N, 4) m/s^2
    foot: np.ndarray          # (N, 2) N (measured; zeros when there is no sensor)
    dt: np.ndarray

    def inputs(self, gyr_valid=True, acc_valid=True, foot_valid=None) -> dict:
        n = len(self.t)
        fv = self.cfg.foot_force if foot_valid is None else foot_valid
        return {"gyr": self.gyr, "acc": self.acc, "foot": self.foot,
                "gyr_valid": np.broadcast_to(np.asarray(gyr_valid, bool), (n, 2)).copy(),
                "acc_valid": np.broadcast_to(np.asarray(acc_valid, bool), (n, 2)).copy(),
                "foot_valid": np.full(n, bool(fv)), "dt": self.dt}


def leg_trial(cfg: LegConfig | None = None) -> LegTrial:
    cfg = cfg or LegConfig()
    n = int(round(cfg.duration * cfg.rate_hz))
    t = np.arange(n) / cfg.rate_hz
    z, zd, zdd = leg_motion(cfg, t)
    foot = cfg.foot_force
    F = leg_foot_force(cfg, t) if foot else np.zeros((n, 2))
    te = np.zeros((n, 4 if foot else 2))
    for k in range(n):
        M, Q = leg_M_bias(cfg, z[k], zd[k])
        gen = M @ zdd[k] - Q
        if foot:
            gen = gen - leg_ankle_jacobian(cfg, z[k]).T @ F[k]
        te[k, :2] = np.linalg.solve(np.array([[1.0, -1.0], [0.0, 1.0]]), gen)
        if foot:
            te[k, 2:] = F[k]
    gyr, acc = leg_imu(cfg, z, zd, zdd)
    rng = np.random.default_rng(cfg.seed)
    gyr = gyr + rng.standard_normal(gyr.shape) * cfg.sigma_gyr
    acc = acc + rng.standard_normal(acc.shape) * cfg.sigma_acc
    foot_meas = F + (rng.standard_normal(F.shape) * cfg.sigma_foot if foot else 0.0)
    return LegTrial(cfg, t, z, zd, zdd, te, gyr, acc, foot_meas, np.full(n, 1.0 / cfg.rate_hz))


__all__ = ["PendulumConfig", "PendulumTrial", "pendulum_trial", "pendulum_motion",
           "pendulum_inverse_dynamics", "pendulum_M_Qg", "pendulum_Bt", "pendulum_R",
           "pendulum_markers", "LegConfig", "LegTrial", "leg_trial", "leg_M_bias", "leg_imu",
           "leg_motion", "lowpass_noise"]
