"""The named scenario set.  ``scenario(name)`` returns a fresh, editable :class:`Scenario`.

Default sensor: the ``metamotionr`` preset (seed 001's unit: acc/gyro 100 Hz at ±4 g and
±500 °/s, magnetometer 20 Hz).  Scenarios whose motion exceeds those ranges switch the unit to
its ±16 g / ±2000 °/s ranges (``WIDE``) and say so; ``spin_saturation`` keeps ±500 °/s on purpose.
"""
from __future__ import annotations

import copy

from .hinge import seed001_steps
from .scenario import Scenario
from .segments import SpecError

TILT = [30.0, 10.0, -20.0]          # a generic start orientation, ZYX yaw/pitch/roll, degrees
WIDE = {"gyr": {"range_dps": 2000.0, "lsb_dps": 1 / 16.4},
        "acc": {"range_g": 16.0, "lsb_mg": 1000.0 / 2048.0}}


def _sensor(**over):
    d = {"preset": "metamotionr"}
    d.update(copy.deepcopy(over))
    return d


def _body(segments, initial=TILT, **kw):
    m = {"kind": "body", "initial": {"euler_zyx_deg": list(initial)}, "segments": segments}
    m.update(kw)
    return m


def _rest(d):
    return {"type": "rest", "duration": d}


def _slow(d, **kw):
    s = {"type": "random_rotation", "duration": d, "rms_rate_dps": 90.0, "band_hz": [0.05, 0.5]}
    s.update(kw)
    return s


SLOW = [_rest(5.0), _slow(60.0), _rest(5.0)]

_LIB = {
    "rest": dict(
        description="30 s at rest in a tilted orientation",
        motion=_body([_rest(30.0)])),
    "constant_rotation": dict(
        description="720° about the body axis (1,1,1)/√3 at 90 °/s (0.2 s blends), rests 2 s",
        motion=_body([_rest(2.0), {"type": "rotate", "axis": [1, 1, 1], "rate_dps": 90.0, "angle_deg": 720.0},
                      _rest(2.0)])),
    "slow_rotation": dict(
        description="band-limited random rotation, design RMS rate 90 °/s, 0.05-0.5 Hz, 60 s",
        motion=_body(SLOW)),
    "fast_rotation": dict(
        description="band-limited random rotation, design RMS rate 350 °/s, 0.2-1.5 Hz, 60 s (±2000 °/s range)",
        motion=_body([_rest(5.0), _slow(60.0, rms_rate_dps=350.0, band_hz=[0.2, 1.5]), _rest(5.0)]),
        sensor=_sensor(**WIDE)),
    "translation": dict(
        description="back-and-forth 0.3 m at 1 Hz along east, north, then 0.2 m up (peak 11.8 m/s²)",
        motion=_body([_rest(3.0),
                      {"type": "translate", "direction": [1, 0, 0], "amplitude_m": 0.3, "freq_hz": 1.0, "duration": 15.0},
                      _rest(2.0),
                      {"type": "translate", "direction": [0, 1, 0], "amplitude_m": 0.3, "freq_hz": 1.0, "duration": 15.0},
                      _rest(2.0),
                      {"type": "translate", "direction": [0, 0, 1], "amplitude_m": 0.2, "freq_hz": 1.0, "duration": 15.0},
                      _rest(3.0)])),
    "fast_translation": dict(
        description="back-and-forth 0.2 m at 2 Hz along east then north (peak 31.6 m/s², ±16 g range)",
        motion=_body([_rest(3.0),
                      {"type": "translate", "direction": [1, 0, 0], "amplitude_m": 0.2, "freq_hz": 2.0, "duration": 15.0},
                      _rest(2.0),
                      {"type": "translate", "direction": [0, 1, 0], "amplitude_m": 0.2, "freq_hz": 2.0, "duration": 15.0},
                      _rest(3.0)]),
        sensor=_sensor(**WIDE)),
    "combined": dict(
        description="fast random rotation (350 °/s design RMS) with random translation (0.3 m RMS), ±16 g/±2000 °/s",
        motion=_body([_rest(5.0), {"type": "random_motion", "duration": 60.0, "rms_rate_dps": 350.0,
                                   "band_hz": [0.2, 1.5], "translation_rms_m": 0.3,
                                   "translation_band_hz": [0.2, 1.5]}, _rest(5.0)]),
        sensor=_sensor(**WIDE)),
    "gait": dict(
        description="level walking, right thigh and shank sensors, 105 steps/min, 1.3 m stride, 30 s (±16 g/±2000 °/s)",
        motion={"kind": "gait", "duration_s": 30.0, "cadence_spm": 105.0, "stride_m": 1.3,
                "rest_before_s": 2.0, "rest_after_s": 2.0, "heading_deg": 90.0},
        sensor=_sensor(**WIDE)),
    "hinge_static": dict(
        description="seed-001 hinge board, static test: 0/30/45/60/90° held 60 s each (45 °/s between)",
        motion={"kind": "hinge", "joint": seed001_steps(include_dynamic=False)}),
    "hinge_dynamic": dict(
        description="seed-001 hinge board, dynamic tests: 30 s rest, 10 × 0→90→0° at 45 °/s, 30 s, "
                    "10 × at 90 °/s, 30 s",
        motion={"kind": "hinge", "joint": seed001_steps(include_static=False)}),
    "hinge_dynamic_slow": dict(
        description="seed-001 slow dynamic test: 30 s rest, 10 × 0→90→0° at 45 °/s, 30 s rest",
        motion={"kind": "hinge", "joint": seed001_steps(include_static=False, rates_dps=(45.0,))}),
    "hinge_dynamic_fast": dict(
        description="seed-001 fast dynamic test: 30 s rest, 10 × 0→90→0° at 90 °/s, 30 s rest",
        motion={"kind": "hinge", "joint": seed001_steps(include_static=False, rates_dps=(90.0,))}),
    "hinge_protocol": dict(
        description="seed-001 hinge board, static then both dynamic tests",
        motion={"kind": "hinge", "joint": seed001_steps()}),
    "hinge_misaligned": dict(
        description="hinge flexing 0-100° at 60 °/s while the proximal segment rotates slowly; "
                    "sensors misaligned on their segments (proximal 5/-8/12°, distal -10/6/15° ZYX)",
        motion={"kind": "hinge",
                "joint": {"start_deg": 0.0, "steps": [{"hold_s": 3.0},
                                                      {"cycles": 8, "between_deg": [0.0, 100.0], "rate_dps": 60.0},
                                                      {"hold_s": 3.0}]},
                "base": {"initial": {"euler_zyx_deg": TILT},
                         "segments": [_rest(3.0), _slow(28.0, rms_rate_dps=40.0), _rest(3.0)]},
                "proximal_mount": {"euler_zyx_deg": [5.0, -8.0, 12.0]},
                "distal_mount": {"euler_zyx_deg": [-10.0, 6.0, 15.0]}}),
    "magnetic_disturbance": dict(
        description="slow rotation; the field is 2× the earth field (same direction) from 15 s to 25 s",
        motion=_body([_rest(5.0), _slow(30.0), _rest(5.0)]),
        disturbances=[{"type": "field_scale", "t_start_s": 15.0, "t_end_s": 25.0, "factor": 2.0}]),
    "stationary_magnet": dict(
        description="random rotation and translation (0.2 m RMS) near a 0.5 A·m² dipole at (0.35, 0, 0) m",
        motion=_body([_rest(3.0), {"type": "random_motion", "duration": 40.0, "rms_rate_dps": 90.0,
                                   "translation_rms_m": 0.2, "translation_band_hz": [0.1, 0.5]}, _rest(3.0)]),
        disturbances=[{"type": "stationary_magnet", "position_m": [0.35, 0.0, 0.0], "moment_Am2": [0.0, 0.0, 0.5]}]),
    "attached_magnet": dict(
        description="slow rotation; from 10 s to 60 s a magnet rides on the unit: +(15,-10,20) µT, soft iron",
        motion=_body(SLOW),
        disturbances=[{"type": "attached_magnet", "t_start_s": 10.0, "t_end_s": 60.0, "offset_uT": [15.0, -10.0, 20.0],
                       "soft_iron": [[1.10, 0.05, 0.0], [0.05, 0.95, 0.0], [0.0, 0.0, 1.0]]}]),
    "tapping": dict(
        description="slow rotation with a tap (60 m/s², 20 °/s peaks, 40 ms) every 3 s from 8 s (±16 g)",
        motion=_body(SLOW),
        disturbances=[{"type": "taps", "times_s": [8.0 + 3.0 * i for i in range(18)]}],
        sensor=_sensor(**WIDE)),
    "vibration": dict(
        description="slow rotation with 40 Hz vibration (3/3/2 m/s², 1.5/0.7/0.8 °/s amplitudes) from 10 s to 55 s",
        motion=_body(SLOW),
        disturbances=[{"type": "vibration", "t_start_s": 10.0, "t_end_s": 55.0, "freq_hz": 40.0}]),
    "bias_1dps": dict(
        description="120 s stationary, tilted, with a constant gyro bias of 1 °/s on every axis",
        motion=_body([_rest(120.0)], initial=[40.0, 25.0, -30.0]),
        sensor=_sensor(gyr={"bias_dps": [1.0, 1.0, 1.0]})),
    "jitter_and_drops": dict(
        description="slow rotation; 0.5 ms sampling jitter, 0.2 ms stamp jitter, µs stamps, 2 % drops, "
                    "1 % duplicates, a 0.5 s gap at 20 s",
        motion=_body(SLOW),
        timing={"jitter_s": 0.0005, "stamp_jitter_s": 0.0002, "stamp_resolution_s": 1e-6,
                "drop_prob": 0.02, "dup_prob": 0.01, "gaps_s": [[20.0, 20.5]]}),
    "mag_calibration": dict(
        description="60 s of slow rotation through all orientations with hard iron (seed-001 unit DA offsets "
                    "15.05/9.45/-19.70 µT) and soft iron",
        motion=_body([_rest(2.0), _slow(60.0, rms_rate_dps=60.0, band_hz=[0.02, 0.3]), _rest(2.0)]),
        sensor=_sensor(mag={"hard_iron_uT": [15.05, 9.45, -19.70],
                            "soft_iron": [[1.05, 0.03, 0.0], [0.03, 0.97, 0.02], [0.0, 0.02, 1.01]]})),
    "six_position": dict(
        description="accelerometer calibration: each axis up then down for 10 s, with scale, bias and "
                    "misalignment errors on the accelerometer",
        motion=_body([_rest(10.0)] + [s for e in ([0, -90, 0], [0, 90, 0], [0, 0, 90], [0, 0, -90], [0, 0, 180])
                                      for s in ({"type": "orient", "euler_zyx_deg": e, "duration": 3.0}, _rest(10.0))],
                     initial=[0.0, 0.0, 0.0]),
        sensor=_sensor(acc={"bias_mg": [20.0, -15.0, 30.0], "scale": [1.01, 0.99, 1.02],
                            "misalignment": [[1.0, 0.005, -0.003], [0.0, 1.0, 0.004], [0.0, 0.0, 1.0]]})),
    "spin_saturation": dict(
        description="spin about z at 720 °/s for 5 s: the ±500 °/s gyro saturates",
        motion=_body([_rest(2.0), {"type": "rotate", "axis": [0, 0, 1], "rate_dps": 720.0, "duration": 5.0},
                      _rest(2.0)])),
}


def names() -> list[str]:
    return list(_LIB)


def scenario(name: str) -> Scenario:
    """A fresh Scenario of the library (edit it freely)."""
    if name not in _LIB:
        raise SpecError(f"unknown scenario {name!r}; known: {', '.join(_LIB)}")
    d = copy.deepcopy(_LIB[name])
    d.setdefault("sensor", _sensor())
    return Scenario.from_dict({"name": name, **d})
