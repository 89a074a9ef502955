"""A rig: the sensors of a scenario, where they ride, and its joint-angle truths."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from . import quat as Q
from .motion import Track
from .segments import BodySequence, orientation_from_spec, take, vec3


@dataclass
class Rig:
    tracks: dict                 # sensor name → Track
    duration: float              # s
    moving: Callable             # t → bool array (designed motion phase of the whole rig)
    joints: dict = field(default_factory=dict)   # name → ScalarSignal (rad)
    info: dict = field(default_factory=dict)     # rig parameters worth recording


def mount_from_spec(spec, where: str) -> np.ndarray:
    """Sensor → segment rotation from {'quat': …} or {'euler_zyx_deg': …} (None = identity)."""
    if spec is None:
        return np.array([1.0, 0.0, 0.0, 0.0])
    take(spec, where, [], ["quat", "euler_zyx_deg"])
    return orientation_from_spec(spec, where)


def body_sequence_from_spec(spec: dict, rng, where: str) -> BodySequence:
    take(spec, where, ["segments"], ["initial", "position_m"])
    q0 = orientation_from_spec(take(spec.get("initial", {}), f"{where}.initial", [], ["quat", "euler_zyx_deg"]),
                               f"{where}.initial")
    p0 = vec3(spec.get("position_m", [0.0, 0.0, 0.0]), f"{where}.position_m")
    return BodySequence(spec["segments"], q0, p0, rng, f"{where}.segments")


def body_rig(spec: dict, rng) -> Rig:
    """motion = {kind: body, segments: [...], initial?, position_m?, sensor_offset_m?, mount?}

    One sensor, ``imu``.  ``sensor_offset_m`` puts it away from the body origin (body frame,
    m) so rotations add centripetal/tangential acceleration; ``mount`` turns it on the body.
    """
    take(spec, "motion", ["kind", "segments"], ["initial", "position_m", "sensor_offset_m", "mount"])
    seq = body_sequence_from_spec({k: spec[k] for k in ("segments", "initial", "position_m") if k in spec},
                                  rng, "motion")
    r = vec3(spec.get("sensor_offset_m", [0.0, 0.0, 0.0]), "motion.sensor_offset_m")
    track = Track(seq.body(), r, mount_from_spec(spec.get("mount"), "motion.mount"))
    return Rig({"imu": track}, seq.duration, seq.moving)


def joint_angle_between(q_proximal, q_distal, axis) -> np.ndarray:
    """Signed angle (rad) of q_proximal* ⊗ q_distal about ``axis`` (proximal frame), assuming
    the relative rotation is about that axis (a hinge); used to check hinge truths."""
    rel = Q.mul(Q.conj(q_proximal), q_distal)
    n = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    return 2.0 * np.arctan2(rel[..., 1:] @ n, rel[..., 0])
