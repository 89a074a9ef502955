"""Two-segment hinge joint and the seed-001 hinge-board protocol.

motion = {kind: hinge, joint: {start_deg, steps: [...]}, hinge_axis?, base?, hinge_point_m?,
          proximal_sensor_m?, distal_sensor_m?, proximal_mount?, distal_mount?}

* proximal segment: a body motion (``base``: {initial?, position_m?, segments}; default: at
  rest, segment frame = earth frame, for the joint's whole duration);
* distal segment: q_distal = q_proximal ⊗ Rot(hinge_axis, θ(t)); its origin is the hinge point
  (``hinge_point_m`` in the proximal frame, default origin);
* sensors ``proximal`` and ``distal`` at ``*_sensor_m`` (segment frame, m; defaults
  (0, −0.10, 0) and (0, 0.10, 0): 10 cm either side of a hinge along x) turned by
  ``*_mount`` ({euler_zyx_deg} or {quat}, sensor → segment): sensor-to-segment misalignment;
* truth ``joint_angle`` = θ(t), rad (flexion positive about +hinge_axis).

Joint steps (degrees, seconds):
  {hold_s}                                  stay
  {move_to_deg, rate_dps | duration_s, blend_s?}     constant rate, smooth blends (default 0.1 s)
  {cycles, between_deg: [a, b], rate_dps | duration_s, blend_s?, pause_s?}
                                            n times a → b → a (must start at a)
"""
from __future__ import annotations

import numpy as np

from .motion import AxisRotation, Compose, RigidMotion, Track
from .rig import Rig, body_sequence_from_spec, mount_from_spec
from .segments import BodySequence, SpecError, positive, take, unit3, vec3
from .signals import Profile

DEFAULT_BLEND_S = 0.1


def joint_profile(spec: dict, where: str = "motion.joint") -> Profile:
    """A Profile in radians from the joint spec (degrees in the spec)."""
    take(spec, where, ["steps"], ["start_deg"])
    prof = Profile(np.radians(float(spec.get("start_deg", 0.0))))
    if not isinstance(spec["steps"], list) or not spec["steps"]:
        raise SpecError(f"{where}.steps: expected a non-empty list")
    for i, st in enumerate(spec["steps"]):
        w = f"{where}.steps[{i}]"
        if not isinstance(st, dict):
            raise SpecError(f"{w}: expected an object")
        if "hold_s" in st:
            take(st, w, ["hold_s"])
            prof.hold(positive(st["hold_s"], f"{w}.hold_s"))
        elif "move_to_deg" in st:
            take(st, w, ["move_to_deg"], ["rate_dps", "duration_s", "blend_s"])
            _move(prof, np.radians(float(st["move_to_deg"])), st, w)
        elif "cycles" in st:
            take(st, w, ["cycles", "between_deg"], ["rate_dps", "duration_s", "blend_s", "pause_s"])
            a, b = (np.radians(float(x)) for x in st["between_deg"])
            if abs(prof.end_value - a) > 1e-9:
                raise SpecError(f"{w}: cycles must start at between_deg[0] "
                                f"({np.degrees(a):g}°), the joint is at {np.degrees(prof.end_value):g}°")
            pause = float(st.get("pause_s", 0.0))
            if not (np.isfinite(pause) and pause >= 0):        # (a negative pause ran as none)
                raise SpecError(f"{w}.pause_s: must be >= 0 s, got {st.get('pause_s')!r}")
            n = st["cycles"]
            # (2.5 cycles ran as 2, and 0 or -3 as none: a joint that never moved)
            if isinstance(n, bool) or not float(n).is_integer() or float(n) < 1:
                raise SpecError(f"{w}.cycles: must be a whole number >= 1, got {n!r}")
            for _ in range(int(n)):
                _move(prof, b, st, w)
                if pause > 0:
                    prof.hold(pause)
                _move(prof, a, st, w)
                if pause > 0:
                    prof.hold(pause)
        else:
            raise SpecError(f"{w}: expected one of hold_s, move_to_deg, cycles")
    return prof


def _move(prof, target, st, w):
    blend = float(st.get("blend_s", DEFAULT_BLEND_S))
    if ("rate_dps" in st) == ("duration_s" in st):
        raise SpecError(f"{w}: give exactly one of rate_dps, duration_s")
    if "rate_dps" in st:
        prof.move_to(target, rate=np.radians(positive(st["rate_dps"], f"{w}.rate_dps")), blend=blend)
    else:
        prof.move_to(target, duration=positive(st["duration_s"], f"{w}.duration_s"), blend=blend)


def hinge_rig(spec: dict, rng) -> Rig:
    take(spec, "motion", ["kind", "joint"],
         ["hinge_axis", "base", "hinge_point_m", "proximal_sensor_m", "distal_sensor_m",
          "proximal_mount", "distal_mount"])
    prof = joint_profile(spec["joint"])
    theta = prof.build()
    dur = prof.duration
    if "base" in spec:
        seq = body_sequence_from_spec(spec["base"], rng, "motion.base")
    else:
        seq = BodySequence([{"type": "rest", "duration": dur}], rng=rng)
    dur = max(dur, seq.duration)
    prox = seq.body()
    axis = unit3(spec.get("hinge_axis", [1.0, 0.0, 0.0]), "motion.hinge_axis")
    hinge_pt = vec3(spec.get("hinge_point_m", [0.0, 0.0, 0.0]), "motion.hinge_point_m")
    dist = RigidMotion(Compose(prox.orientation, AxisRotation(tuple(axis), theta)),
                       prox.point(hinge_pt) if np.any(hinge_pt) else prox.origin)
    tracks = {
        "proximal": Track(prox, vec3(spec.get("proximal_sensor_m", [0.0, -0.10, 0.0]), "motion.proximal_sensor_m"),
                          mount_from_spec(spec.get("proximal_mount"), "motion.proximal_mount")),
        # the distal sensor's position is relative to the hinge point (distal origin)
        "distal": Track(dist, vec3(spec.get("distal_sensor_m", [0.0, 0.10, 0.0]), "motion.distal_sensor_m"),
                        mount_from_spec(spec.get("distal_mount"), "motion.distal_mount")),
    }

    def moving(t):
        return theta.moving(t) | seq.moving(t)
    return Rig(tracks, dur, moving, {"joint_angle": theta}, {"hinge_axis": axis.tolist()})


def seed001_steps(static_deg=(0, 30, 45, 60, 90), static_s=60.0, transition_dps=45.0,
                  rest_s=30.0, cycles=10, rates_dps=(45.0, 90.0), amplitude_deg=90.0,
                  blend_s=DEFAULT_BLEND_S, include_static=True, include_dynamic=True) -> dict:
    """Joint spec of the seed-001 hinge-board protocol (ChakaMo thesis §7.2).

    Static test: hold each angle of ``static_deg`` for ``static_s`` (seed: 0/30/60/90°, with 45°
    in its abstract, 60 s each), moving between them at ``transition_dps``, then back to 0.
    Dynamic test, for each rate: ``rest_s`` at 0°, ``cycles`` × (0 → amplitude → 0) at that
    constant rate (seed: 10 cycles, 45 °/s "slow" and 90 °/s "fast", 30 s rests before and
    after), ending with ``rest_s``.  With 0.1 s blends each half cycle lasts 90/rate + 0.1 s,
    so the slow test lasts 102 s and the fast one 82 s (seed: 100 s and 80 s).
    """
    steps: list = []
    cur = 0.0
    if include_static:
        for a in static_deg:
            if a != cur:
                steps.append({"move_to_deg": float(a), "rate_dps": transition_dps, "blend_s": blend_s})
                cur = a
            steps.append({"hold_s": float(static_s)})
        if cur != 0:
            steps.append({"move_to_deg": 0.0, "rate_dps": transition_dps, "blend_s": blend_s})
            cur = 0.0
    if include_dynamic:
        for r in rates_dps:
            steps.append({"hold_s": float(rest_s)})
            steps.append({"cycles": int(cycles), "between_deg": [0.0, float(amplitude_deg)],
                          "rate_dps": float(r), "blend_s": blend_s})
        steps.append({"hold_s": float(rest_s)})
    return {"start_deg": 0.0, "steps": steps}
