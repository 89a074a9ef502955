"""Gait-like thigh and shank motion in the sagittal plane.

motion = {kind: gait, duration_s, cadence_spm?, stride_m?, rest_before_s?, rest_after_s?,
          heading_deg?, side?, hip_height_m?, thigh_length_m?, pelvis_vertical_m?,
          pelvis_lateral_m?, thigh_sensor_m?, shank_sensor_m?, thigh_mount?, shank_mount?}

Segment frames: x forward (walking direction), y to the subject's left, z up along the
segment (proximal direction) when standing.  ``heading_deg`` is the walking direction as an
ENU yaw (0 = east, 90 = north).  Hip flexion θ_h rotates the thigh about the segment's
right-pointing axis (−y); the shank's sagittal angle is θ_h − θ_k (knee flexion θ_k > 0 swings
the shank back).  The pelvis is upright (thigh angle = hip flexion).

Joint curves: one walking cycle (0 % = initial contact of this leg) as 8-harmonic Fourier
series fitted to a periodic spline through the key points below — textbook-shaped curves of
adult level walking (hip ≈ 30° at contact, ≈ −10° peak extension at 55 %, ≈ 34° peak flexion in
swing; knee ≈ 19° loading-response peak at 15 %, ≈ 62° swing peak at 73 %), not one
subject's data.  Walking speed = stride length × cadence / 120 (cadence in steps/min).  The
hip joint centre moves forward at that speed, bobs ``pelvis_vertical_m`` twice per stride
(lowest at double support) and sways ``pelvis_lateral_m`` once per stride.  Gait starts and
stops from quiet standing (straight leg) through a C² window one stride long, so the motion
and the accelerations stay continuous; foot-strike impacts are not modelled.

Sensors ``thigh`` and ``shank``: default on the lateral side 20 cm below the hip and 18 cm
below the knee, sensor axes = segment axes (``*_mount`` turns them).  Truths ``hip_flexion``
and ``knee_flexion`` (rad).
"""
from __future__ import annotations

import numpy as np
from scipy.interpolate import CubicSpline

from . import quat as Q
from .motion import AxisRotation, Compose, Fixed, Path3, RigidMotion, Track
from .rig import Rig, mount_from_spec
from .segments import SpecError, positive, take, vec3
from .signals import Fourier, window

# (percent of cycle, degrees)
HIP_KEYPOINTS = [(0, 30), (10, 26), (20, 18), (30, 9), (40, 1), (50, -8), (55, -10), (60, -6), (65, 2),
                 (70, 12), (75, 21), (80, 28), (85, 33), (90, 34), (95, 32), (100, 30)]
KNEE_KEYPOINTS = [(0, 5), (5, 10), (10, 16), (15, 19), (20, 17), (25, 13), (30, 9), (35, 6), (40, 5),
                  (45, 6), (50, 10), (55, 20), (60, 35), (65, 50), (70, 60), (73, 62), (75, 61),
                  (80, 55), (85, 40), (90, 22), (95, 8), (100, 5)]
HARMONICS = 8


def fourier_coefficients(keypoints, harmonics: int = HARMONICS):
    """(a0, a, b) in degrees of the periodic spline through ``keypoints`` (cycle fraction)."""
    x, y = np.asarray(keypoints, dtype=float).T
    spline = CubicSpline(x / 100.0, y, bc_type="periodic")
    m = 512
    f = np.fft.rfft(spline(np.arange(m) / m)) / m
    return f[0].real, 2 * f[1:harmonics + 1].real, -2 * f[1:harmonics + 1].imag


def cycle_curve(keypoints, period_s: float, phase_s: float = 0.0) -> Fourier:
    """Joint angle in rad as a Fourier series of period ``period_s`` (t = 0: initial contact)."""
    a0, a, b = fourier_coefficients(keypoints)
    k = np.pi / 180.0
    return Fourier(period_s, a0 * k, tuple(a * k), tuple(b * k), phase_s)


_KEYS = ["kind", "duration_s", "cadence_spm", "stride_m", "rest_before_s", "rest_after_s", "heading_deg",
         "side", "hip_height_m", "thigh_length_m", "pelvis_vertical_m", "pelvis_lateral_m",
         "thigh_sensor_m", "shank_sensor_m", "thigh_mount", "shank_mount"]


def gait_rig(spec: dict, rng) -> Rig:
    take(spec, "motion", ["kind", "duration_s"], _KEYS)
    walk = positive(spec["duration_s"], "motion.duration_s")
    cadence = positive(spec.get("cadence_spm", 105.0), "motion.cadence_spm")
    stride = positive(spec.get("stride_m", 1.3), "motion.stride_m")
    before = float(spec.get("rest_before_s", 2.0))
    after = float(spec.get("rest_after_s", 2.0))
    for k, v in (("rest_before_s", before), ("rest_after_s", after)):
        if not (np.isfinite(v) and v >= 0):     # (-1 started the walk before t = 0, mid-stride)
            raise SpecError(f"motion.{k}: must be >= 0 s, got {spec[k]!r}")
    side = spec.get("side", "right")
    if side not in ("right", "left"):
        raise SpecError(f"motion.side: expected 'right' or 'left', got {side!r}")
    lat = -1.0 if side == "right" else 1.0      # lateral (outward) direction along segment y
    T = 120.0 / cadence                          # stride (cycle) time, s
    speed = stride / T                           # m/s
    for k in ("heading_deg", "hip_height_m", "pelvis_vertical_m", "pelvis_lateral_m"):
        if k in spec and not np.isfinite(float(spec[k])):    # (NaN heading: an internal error)
            raise SpecError(f"motion.{k}: must be finite, got {spec[k]!r}")
    yaw = np.radians(float(spec.get("heading_deg", 0.0)))
    fwd = np.array([np.cos(yaw), np.sin(yaw), 0.0])
    left = np.array([-np.sin(yaw), np.cos(yaw), 0.0])
    h0 = float(spec.get("hip_height_m", 0.92))
    l_thigh = positive(spec.get("thigh_length_m", 0.45), "motion.thigh_length_m")
    az = float(spec.get("pelvis_vertical_m", 0.02))
    ay = float(spec.get("pelvis_lateral_m", 0.02))

    win = window(walk, min(T, walk / 2), t_start=before)
    phase = -before + (0.5 * T if side == "left" else 0.0)
    hip = win * cycle_curve(HIP_KEYPOINTS, T, phase)
    knee = win * cycle_curve(KNEE_KEYPOINTS, T, phase)
    # pelvis: forward at speed (windowed), vertical bob at 2/stride, lateral sway at 1/stride
    fwd_s = speed * win.antiderivative()
    bob = win * Fourier(T, 0.0, (0.0, -az), (0.0, 0.0), -before)
    sway = win * Fourier(T, 0.0, (0.0,), (lat * ay,), -before)
    hip_centre = Path3([0.0, lat * 0.09, h0], [(fwd, fwd_s), (np.array([0.0, 0.0, 1.0]), bob), (left, sway)])

    q_yaw = Q.from_axis_angle([0, 0, 1], yaw)
    flex_axis = (0.0, -1.0, 0.0)
    thigh = RigidMotion(Compose(Fixed(tuple(q_yaw)), AxisRotation(flex_axis, hip)), hip_centre)
    shank = RigidMotion(Compose(Fixed(tuple(q_yaw)), AxisRotation(flex_axis, hip - knee)),
                        thigh.point([0.0, 0.0, -l_thigh]))
    tracks = {
        "thigh": Track(thigh, vec3(spec.get("thigh_sensor_m", [0.0, lat * 0.08, -0.20]), "motion.thigh_sensor_m"),
                       mount_from_spec(spec.get("thigh_mount"), "motion.thigh_mount")),
        "shank": Track(shank, vec3(spec.get("shank_sensor_m", [0.0, lat * 0.05, -0.18]), "motion.shank_sensor_m"),
                       mount_from_spec(spec.get("shank_mount"), "motion.shank_mount")),
    }
    info = {"stride_time_s": T, "speed_mps": speed, "side": side}
    return Rig(tracks, before + walk + after, win.moving, {"hip_flexion": hip, "knee_flexion": knee}, info)
