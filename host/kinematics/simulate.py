"""Synthetic knee step-up and calibration recordings with known truth (tests and benchmarks).

Written because ``kinefuse.hil_tests.sim`` did not exist yet when this was needed; it only
produces what the alignment/joint-angle code needs: segment orientations, sensor mounting,
and IMU samples (acc, gyro, mag) consistent with them.

Earth frame: East-North-Up (z up), magnetic north = +y.  The subject faces north, so in the
neutral standing posture the segment frame (X = subject's left, Y = up, Z = anterior, see
:mod:`..alignment`) is X = west, Y = up, Z = north.

Step-up model (seed 001 §8.1, one leg on a step, 10 cycles of ≈ 3.4 s): the foot stays on the
step (ankle fixed at the origin); the shank pitches forward with the knee (ankle
dorsiflexion); the knee follows a flexion profile 70° → 82° (impulse, 30 %) → ≈ 3° (extension,
50 %) → back to 70° (fall), with ab/adduction and rotation coupled to flexion plus small
per-cycle variations; the thigh follows from the knee rotation.  Sensor positions move with the
segments, so the accelerometers see the linear acceleration of the body rising and falling.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.interpolate import PchipInterpolator

from kinefuse.host.kinematics import quat as Q
from kinefuse.host.readers.recording import Recording

G = 9.81
R_NEUTRAL = np.column_stack([[-1.0, 0, 0], [0, 0, 1.0], [0, 1.0, 0]])  # segment axes in ENU
Q_NEUTRAL = Q.from_matrix(R_NEUTRAL)
MAG_FIELD = 22.6 * np.array([0.0, np.cos(np.radians(33.0)), np.sin(np.radians(33.0))])  # µT, ENU


@dataclass
class StepUpTruth:
    t: np.ndarray
    q_GB_thigh: np.ndarray
    q_GB_shank: np.ndarray
    p_knee: np.ndarray
    angles_deg: np.ndarray        # (flexion, adduction, internal rotation), right knee, G&S
    cycle_starts: np.ndarray      # sample indices of cycle starts (0 % of the step-up cycle)


def _periodic(phase: np.ndarray, keys: list[tuple[float, float]]) -> np.ndarray:
    """Shape-preserving (PCHIP, no overshoot) periodic interpolation through key points."""
    x = np.array([k[0] for k in keys])
    y = np.array([k[1] for k in keys])
    xx = np.concatenate([x - 1.0, x, x + 1.0])
    yy = np.concatenate([y, y, y])
    return PchipInterpolator(xx, yy)(phase % 1.0)


def step_up(fs: float = 100.0, n_cycles: int = 10, cycle_s: float = 3.4, rest_s: float = 4.0,
            seed: int = 0) -> StepUpTruth:
    """Right-knee step-up: rest (knee flexed on the step), ``n_cycles`` cycles, rest."""
    rng = np.random.default_rng(seed)
    durs = cycle_s * (1.0 + 0.04 * rng.standard_normal(n_cycles))
    amps = 1.0 + 0.04 * rng.standard_normal(n_cycles)
    t_cyc = rest_s + np.concatenate([[0.0], np.cumsum(durs)])
    T = t_cyc[-1] + rest_s
    t = np.arange(int(round(T * fs))) / fs
    k = np.clip(np.searchsorted(t_cyc, t, side="right") - 1, 0, n_cycles - 1)
    inside = (t >= t_cyc[0]) & (t < t_cyc[-1])
    phase = np.where(inside, (t - t_cyc[k]) / durs[k], 0.0)
    flex_keys = [(0.0, 70.0), (0.30, 82.0), (0.50, 3.0), (0.62, 6.0), (0.80, 45.0)]
    flex = 70.0 + amps[k] * (_periodic(phase, flex_keys) - 70.0) * inside
    add = 1.5 + 3.0 * np.sin(2 * np.pi * phase) * inside + 0.02 * (flex - 70.0)
    rot = 4.0 + 0.08 * (flex - 70.0) + 2.0 * np.sin(4 * np.pi * phase) * inside
    # smooth slow drift of heading (deg) common to both segments
    heading = 3.0 * np.sin(2 * np.pi * t / 17.0) + 1.5 * np.sin(2 * np.pi * t / 5.3 + 1.0)
    ankle = 5.0 + 0.35 * flex + 1.0 * np.sin(2 * np.pi * t / 7.0)  # shank forward pitch, deg

    knee = np.radians(np.column_stack([flex, add, rot]))
    q_knee = Q.from_euler(knee, "XZY")
    q_head = Q.elementary("Z", np.radians(heading))
    q_shank = Q.mul(Q.mul(q_head, np.broadcast_to(Q_NEUTRAL, (len(t), 4))),
                    Q.elementary("X", np.radians(ankle)))
    q_thigh = Q.mul(q_shank, Q.conj(q_knee))
    L_shank = 0.42
    p_knee = Q.rotate(q_shank, np.broadcast_to([0.0, L_shank, 0.0], (len(t), 3)))
    starts = np.round(t_cyc[:-1] * fs).astype(int)
    return StepUpTruth(t, q_thigh, q_shank, p_knee, np.column_stack([flex, add, rot]), starts)


def sensor_pose(truth: StepUpTruth, segment: str, q_SB: np.ndarray):
    """Sensor orientation q_GS = q_GB ⊗ q_SB* and position (m) on ``thigh`` or ``shank``."""
    n = len(truth.t)
    if segment == "thigh":
        q_GB = truth.q_GB_thigh
        p = truth.p_knee + Q.rotate(q_GB, np.broadcast_to([0.0, 0.15, 0.07], (n, 3)))
    elif segment == "shank":
        q_GB = truth.q_GB_shank
        p = Q.rotate(q_GB, np.broadcast_to([0.0, 0.33, 0.04], (n, 3)))
    else:
        raise ValueError(segment)
    return Q.mul(q_GB, Q.conj(q_SB)), p


def imu(t, q_GS, p=None, *, rng=None, acc_noise=0.05, gyr_noise=0.005, gyr_bias=None,
        mag_noise=0.2, mag_field=MAG_FIELD, hard_iron=None, soft_iron=None,
        name: str = "simulated") -> Recording:
    """IMU samples consistent with an orientation trajectory q_GS (and positions p, m).

    gyro sample k is the mean body rate over [t_{k-1}, t_k] (so strapdown integration with
    q_k = q_{k-1} ⊗ exp(ω_k Δt) reproduces q exactly); acc = R_GSᵀ (p̈ + g ẑ); mag =
    W⁻¹ R_GSᵀ m_G + hard iron (the distortion a calibration W, b must undo).
    """
    rng = np.random.default_rng(0) if rng is None else rng
    t = np.asarray(t, float)
    n = len(t)
    dt = np.diff(t)
    q = Q.unwrap_sign(Q.normalize(q_GS))
    w = np.empty((n, 3))
    w[1:] = Q.to_rotvec(Q.mul(Q.conj(q[:-1]), q[1:])) / dt[:, None]
    w[0] = w[1] if n > 1 else 0.0
    if p is None:
        a_lin = np.zeros((n, 3))
    else:
        a_lin = np.gradient(np.gradient(p, t, axis=0), t, axis=0)
    Rt = np.swapaxes(Q.to_matrix(q), -1, -2)
    acc = np.einsum("nij,nj->ni", Rt, a_lin + np.array([0.0, 0.0, G]))
    mag = np.einsum("nij,j->ni", Rt, np.asarray(mag_field, float))
    if soft_iron is not None:
        mag = mag @ np.linalg.inv(np.asarray(soft_iron)).T
    if hard_iron is not None:
        mag = mag + np.asarray(hard_iron)
    b = np.zeros(3) if gyr_bias is None else np.asarray(gyr_bias, float)
    return Recording(
        t=t,
        acc=acc + acc_noise * rng.standard_normal((n, 3)),
        gyr=w + b + gyr_noise * rng.standard_normal((n, 3)),
        mag=mag + mag_noise * rng.standard_normal((n, 3)),
        fs=1.0 / float(np.median(dt)), source=name, fmt="simulated",
        metadata={"quat_true": q})


def static_posture(q_GB, q_SB, duration_s=10.0, fs=100.0, *, rng=None, tremor_deg=0.3,
                   **imu_kw) -> Recording:
    """A still posture (segment orientation q_GB) seen by a sensor mounted with q_SB, with a
    small physiological sway of ``tremor_deg`` so it is not perfectly still."""
    rng = np.random.default_rng(1) if rng is None else rng
    t = np.arange(int(duration_s * fs)) / fs
    sway = np.radians(tremor_deg) * np.column_stack(
        [np.sin(2 * np.pi * f * t + ph) for f, ph in zip((0.3, 0.4, 0.23), rng.uniform(0, 6, 3))])
    q = Q.mul(Q.mul(np.broadcast_to(Q.normalize(q_GB), (len(t), 4)), Q.from_rotvec(sway)),
              Q.conj(q_SB))
    return imu(t, q, rng=rng, **imu_kw)


def tumble(duration_s=60.0, fs=100.0, *, rng=None, **imu_kw) -> Recording:
    """Figure-eight-like tumbling through all orientations (magnetometer calibration)."""
    rng = np.random.default_rng(2) if rng is None else rng
    t = np.arange(int(duration_s * fs)) / fs
    f = np.array([0.071, 0.113, 0.053])
    ph = rng.uniform(0, 2 * np.pi, 3)
    ang = np.column_stack([np.pi * np.sin(2 * np.pi * f[0] * t + ph[0]),
                           0.5 * np.pi * np.sin(2 * np.pi * f[1] * t + ph[1]),
                           np.pi * np.sin(2 * np.pi * f[2] * t + ph[2])])
    q = Q.from_euler(ang, "ZYX")
    return imu(t, q, rng=rng, **imu_kw)


def random_mounting(angle_deg: float, rng) -> np.ndarray:
    """q_SB: sensor-to-segment offset of exactly ``angle_deg`` about a random axis."""
    ax = rng.standard_normal(3)
    return Q.from_axis_angle(ax, np.radians(angle_deg))


def posture_orientations(imperfection_deg: float = 0.0, rng=None) -> dict:
    """Segment orientations (q_GB) for the standing and supine calibration postures.

    Standing: neutral (Y up, Z north).  Supine: lying with the head to the south, anterior up
    (Z up, Y = south... i.e. the segment rotated −90° about its X axis).  ``imperfection_deg``
    tilts each posture about a random axis (subjects never stand perfectly upright).
    """
    rng = np.random.default_rng(3) if rng is None else rng
    stand = Q_NEUTRAL
    lie = Q.mul(Q_NEUTRAL, Q.elementary("X", -np.pi / 2))

    def tilt():
        return Q.from_axis_angle(rng.standard_normal(3), np.radians(imperfection_deg)) \
            if imperfection_deg else Q.identity()
    return {"standing_thigh": Q.mul(tilt(), stand), "standing_shank": Q.mul(tilt(), stand),
            "lying_thigh": Q.mul(tilt(), lie), "lying_shank": Q.mul(tilt(), lie)}


@dataclass
class KneeProtocol:
    """Recordings of the seed-001 protocol for both sensors, with the truth."""
    truth: StepUpTruth
    q_SB: dict                    # true mounting per segment
    task: dict                    # segment -> Recording (step-up)
    standing: dict
    lying: dict
    mag: dict                     # figure-eight recordings
    hard_iron: dict
    soft_iron: dict


def knee_protocol(*, seed: int = 0, misalign_deg: float = 10.0, posture_deg: float = 1.0,
                  fs: float = 100.0, n_cycles: int = 10, gyr_bias_sd: float = 0.02,
                  hard_iron_sd: float = 20.0) -> KneeProtocol:
    """Simulated seed-001 protocol: both sensors mounted ``misalign_deg`` off the segment axes
    (random axes), postures imperfect by ``posture_deg``, gyroscope biases, magnetometer hard
    and soft iron, sensor noise (acc 0.05 m/s², gyro 0.005 rad/s, mag 0.2 µT)."""
    rng = np.random.default_rng(seed)
    truth = step_up(fs=fs, n_cycles=n_cycles, seed=seed)
    post = posture_orientations(posture_deg, rng)
    out = KneeProtocol(truth, {}, {}, {}, {}, {}, {}, {})
    for seg in ("thigh", "shank"):
        q_SB = random_mounting(misalign_deg, rng)
        b = gyr_bias_sd * rng.standard_normal(3)
        hi = hard_iron_sd * rng.standard_normal(3)
        A = rng.standard_normal((3, 3)) * 0.05
        si = np.eye(3) + 0.5 * (A + A.T)
        kw = dict(gyr_bias=b, hard_iron=hi, soft_iron=si)
        q_GS, p = sensor_pose(truth, seg, q_SB)
        out.q_SB[seg] = q_SB
        out.hard_iron[seg], out.soft_iron[seg] = hi, si
        out.task[seg] = imu(truth.t, q_GS, p, rng=rng, name=f"sim-step-{seg}", **kw)
        out.standing[seg] = static_posture(post[f"standing_{seg}"], q_SB, 10.0, fs, rng=rng, **kw)
        out.lying[seg] = static_posture(post[f"lying_{seg}"], q_SB, 10.0, fs, rng=rng, **kw)
        out.mag[seg] = tumble(60.0, fs, rng=rng, **kw)
    return out


def squats(q_SB: dict, *, rng=None, n: int = 4, fs: float = 100.0, knee_deg: float = 80.0,
           gyr_bias_sd: float = 0.02) -> dict:
    """A functional-calibration trial: ``n`` squats from standing (knee 0 → ``knee_deg`` → 0,
    hip flexing half as much, both about the segments' X axes, 2 s each after 2 s of rest,
    4 s of rest at the end), seen by sensors mounted with ``q_SB`` (``{"thigh", "shank"}``, e.g.
    a :class:`KneeProtocol`'s); returns ``{"thigh": Recording, "shank": Recording}``."""
    rng = np.random.default_rng(0) if rng is None else rng
    t = np.arange(0, 2.0 * n + 6.0, 1.0 / fs)
    ph = np.clip((t - 2.0) / 2.0, 0, n)
    knee = np.radians(knee_deg / 2.0) * (1 - np.cos(2 * np.pi * ph))
    q_th = Q.mul(np.broadcast_to(Q_NEUTRAL, (len(t), 4)), Q.elementary("X", 0.5 * knee))
    q_sh = Q.mul(q_th, Q.elementary("X", -knee))
    return {seg: imu(t, Q.mul(qb, Q.conj(q_SB[seg])), rng=rng, name=f"sim-squat-{seg}",
                     gyr_bias=gyr_bias_sd * rng.standard_normal(3))
            for seg, qb in (("thigh", q_th), ("shank", q_sh))}


def elbow_flexion(seed: int = 0, n_cycles: int = 6, period_s: float = 2.5, rest_s: float = 3.0):
    """Seed-002-like elbow: arm still (tilted 10°, heading 20°), forearm flexing 0→90° about the
    arm's X axis for ``n_cycles`` cycles between rests; raw IMU recordings with gyro biases.
    Returns (arm Recording, forearm Recording, true flexion in degrees)."""
    rng = np.random.default_rng(seed)
    t = np.arange(0, 2 * rest_s + n_cycles * period_s, 0.01)
    ph = np.clip((t - rest_s) / period_s, 0, n_cycles)
    flex = np.radians(45) * (1 - np.cos(2 * np.pi * ph))
    q_arm = Q.mul(Q.elementary("Z", np.radians(20)), Q.elementary("X", np.radians(-10)))
    q_arm = np.broadcast_to(q_arm, (len(t), 4))
    q_fore = Q.mul(q_arm, Q.elementary("X", flex))
    arm = imu(t, q_arm, rng=rng, gyr_bias=[0.01, -0.02, 0.01], name="sim-arm")
    fore = imu(t, q_fore, rng=rng, gyr_bias=[-0.01, 0.0, 0.02], name="sim-forearm")
    return arm, fore, np.degrees(flex)
