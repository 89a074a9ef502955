"""Single-body motion built from segments that start and end at rest.

Each segment is described by a small dict (JSON-friendly; units in the key names) and lasts
``duration`` s.  Every segment starts where the previous one ended and starts/ends with zero
angular velocity, angular acceleration, velocity and linear acceleration, so a concatenation
is C² (smooth transitions) without any blending step.

Segment types (key ``type``):

``rest``            ``duration``
``rotate``          constant-rate rotation about ``axis`` (3,) in ``frame`` "body" (default)
                    or "earth"; give two of ``rate_dps``, ``angle_deg``, ``duration``;
                    ``blend_s`` (default 0.2) smooth acceleration at both ends.
``orient``          turn smoothly to an absolute orientation (``quat`` w,x,y,z or
                    ``euler_zyx_deg`` yaw,pitch,roll) in ``duration`` s (shortest path).
``random_rotation`` band-limited random rotation: ``duration``, ``rms_rate_dps`` (design RMS
                    of the three angle rates combined), ``band_hz`` [lo, hi], ``n_sines``
                    (per axis, default 6), ``ramp_s`` (default 1), optional ``seed``.
                    Returns to the start orientation at the end (the angles are windowed).
``translate``       back-and-forth: ``direction`` (3,) earth frame, ``amplitude_m``,
                    ``freq_hz``, ``duration``, ``ramp_s`` (default 1): p = p0 + d·A·sin(2πft)·w(t).
``random_motion``   random_rotation plus band-limited random translation: adds
                    ``translation_rms_m`` and ``translation_band_hz`` [lo, hi].
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import quat as Q
from .errors import SpecError
from .motion import (AxisRotation, Compose, Fixed, FixedPoint, OrientationSignal, Path3,
                     PositionSignal, RigidMotion)
from .signals import Profile, SineSum, window


def take(spec: dict, where: str, required=(), optional=()) -> dict:
    """Validate a spec dict: every required key present, no unknown keys."""
    if not isinstance(spec, dict):
        raise SpecError(f"{where}: expected an object, got {type(spec).__name__}")
    unknown = sorted(set(spec) - set(required) - set(optional))
    if unknown:
        raise SpecError(f"{where}: unknown key(s) {', '.join(unknown)}; "
                        f"allowed: {', '.join(sorted(set(required) | set(optional)))}")
    missing = [k for k in required if k not in spec]
    if missing:
        raise SpecError(f"{where}: missing key(s) {', '.join(missing)}")
    return spec


def vec3(x, where: str) -> np.ndarray:
    v = np.asarray(x, dtype=float)
    if v.shape != (3,) or not np.all(np.isfinite(v)):
        raise SpecError(f"{where}: expected 3 finite numbers, got {x!r}")
    return v


def unit3(x, where: str) -> np.ndarray:
    v = vec3(x, where)
    n = np.linalg.norm(v)
    if n < 1e-12:
        raise SpecError(f"{where}: direction must be non-zero")
    return v / n


def positive(x, where: str) -> float:
    try:
        v = float(x)
    except (TypeError, ValueError):
        raise SpecError(f"{where}: expected a number, got {x!r}") from None
    if not (v > 0 and np.isfinite(v)):
        raise SpecError(f"{where}: must be a positive number, got {x!r}")
    return v


def orientation_from_spec(spec: dict, where: str) -> np.ndarray:
    """{'quat': [w,x,y,z]} or {'euler_zyx_deg': [yaw, pitch, roll]} → unit quaternion."""
    if "quat" in spec and "euler_zyx_deg" in spec:
        raise SpecError(f"{where}: give quat or euler_zyx_deg, not both")
    if "quat" in spec:
        try:
            return Q.as_quat(spec["quat"])
        except ValueError as exc:
            raise SpecError(f"{where}.quat: {exc}") from None
    if "euler_zyx_deg" in spec:
        return Q.from_euler_zyx_deg(vec3(spec["euler_zyx_deg"], f"{where}.euler_zyx_deg"))
    return np.array([1.0, 0.0, 0.0, 0.0])


# ------------------------------------------------------------------------- segments
@dataclass
class Built:
    orientation: OrientationSignal
    position: PositionSignal
    duration: float
    moving: bool


def _rest(spec, q0, p0, rng, where):
    take(spec, where, ["type", "duration"])
    return Built(Fixed(tuple(q0)), FixedPoint(tuple(p0)), positive(spec["duration"], f"{where}.duration"), False)


def _rotate(spec, q0, p0, rng, where):
    take(spec, where, ["type", "axis"], ["rate_dps", "angle_deg", "duration", "blend_s", "frame"])
    axis = unit3(spec["axis"], f"{where}.axis")
    blend = float(spec.get("blend_s", 0.2))
    given = [k for k in ("rate_dps", "angle_deg", "duration") if k in spec]
    if len(given) != 2:
        raise SpecError(f"{where}: give exactly two of rate_dps, angle_deg, duration")
    if "angle_deg" in spec:
        angle = np.radians(float(spec["angle_deg"]))
        prof = Profile(0.0)
        if "rate_dps" in spec:
            prof.move_to(angle, rate=np.radians(positive(spec["rate_dps"], f"{where}.rate_dps")), blend=blend)
        else:
            prof.move_to(angle, duration=positive(spec["duration"], f"{where}.duration"), blend=blend)
    else:
        rate = np.radians(float(spec["rate_dps"]))
        dur = positive(spec["duration"], f"{where}.duration")
        b = min(blend, dur / 2)
        prof = Profile(0.0).move_to(rate * (dur - b), duration=dur, blend=b) if rate else Profile(0.0).hold(dur)
    sig = prof.build()
    rot = AxisRotation(tuple(axis), sig)
    frame = spec.get("frame", "body")
    if frame == "body":
        ori = Compose(Fixed(tuple(q0)), rot)
    elif frame == "earth":
        ori = Compose(rot, Fixed(tuple(q0)))
    else:
        raise SpecError(f"{where}.frame: expected 'body' or 'earth', got {frame!r}")
    return Built(ori, FixedPoint(tuple(p0)), prof.duration, True)


def _orient(spec, q0, p0, rng, where):
    take(spec, where, ["type", "duration"], ["quat", "euler_zyx_deg", "blend_s"])
    target = orientation_from_spec(spec, where)
    dur = positive(spec["duration"], f"{where}.duration")
    dq = Q.mul(Q.conj(q0), target)
    rv = Q.to_rotvec(dq)
    ang = float(np.linalg.norm(rv))
    axis = rv / ang if ang > 1e-12 else np.array([0.0, 0.0, 1.0])
    prof = Profile(0.0).move_to(ang, duration=dur, blend=float(spec.get("blend_s", dur / 2))) \
        if ang > 1e-12 else Profile(0.0).hold(dur)
    return Built(Compose(Fixed(tuple(q0)), AxisRotation(tuple(axis), prof.build())),
                 FixedPoint(tuple(p0)), dur, True)


def _random_angles(rng, dur, rms_rate, band, n_sines, ramp):
    """Three windowed sine sums whose rates have combined design RMS ``rms_rate`` (rad/s)."""
    lo, hi = band
    win = window(dur, ramp)
    sigs = []
    for _ in range(3):
        f = rng.uniform(lo, hi, n_sines)
        u = rng.uniform(0.5, 1.0, n_sines)
        w = 2 * np.pi * f
        c = (rms_rate / np.sqrt(3.0)) * np.sqrt(2.0) / np.sqrt(np.sum(u ** 2))
        amps = c * u / w
        ph = rng.uniform(0, 2 * np.pi, n_sines)
        sigs.append(win * SineSum(tuple(amps), tuple(f), tuple(ph)))
    return sigs


def _band(spec, key, where, default):
    band = spec.get(key, default)
    try:
        lo, hi = (float(b) for b in band)
    except (TypeError, ValueError):
        raise SpecError(f"{where}.{key}: expected [lo, hi] in Hz") from None
    if not (0 < lo <= hi):
        raise SpecError(f"{where}.{key}: need 0 < lo <= hi, got {band!r}")
    return lo, hi


def _non_negative(spec, key, where, default):
    v = float(spec.get(key, default))
    if not (np.isfinite(v) and v >= 0):     # (-90 ran as 90 with the motion's signs flipped)
        raise SpecError(f"{where}.{key}: must be >= 0, got {spec.get(key)!r}")
    return v


def _random_rotation_signal(spec, q0, rng, where, dur):
    rms = np.radians(_non_negative(spec, "rms_rate_dps", where, 90.0))
    band = _band(spec, "band_hz", where, (0.05, 0.5))
    n = int(spec.get("n_sines", 6))
    ramp = float(spec.get("ramp_s", 1.0))
    if n < 1:
        raise SpecError(f"{where}.n_sines: must be >= 1")
    # three orthonormal axes in a random direction: a generalised Euler sequence
    axes = Q.to_matrix(Q.normalize(rng.normal(size=4)))
    angles = _random_angles(rng, dur, rms, band, n, ramp)
    return Compose(Fixed(tuple(q0)), *(AxisRotation(tuple(axes[:, i]), angles[i]) for i in range(3)))


_RANDOM_KEYS = ["rms_rate_dps", "band_hz", "n_sines", "ramp_s", "seed"]


def _random_rotation(spec, q0, p0, rng, where):
    take(spec, where, ["type", "duration"], _RANDOM_KEYS)
    dur = positive(spec["duration"], f"{where}.duration")
    rng = np.random.default_rng(spec["seed"]) if "seed" in spec else rng
    return Built(_random_rotation_signal(spec, q0, rng, where, dur), FixedPoint(tuple(p0)), dur, True)


def _translate(spec, q0, p0, rng, where):
    take(spec, where, ["type", "direction", "amplitude_m", "freq_hz", "duration"], ["ramp_s"])
    d = unit3(spec["direction"], f"{where}.direction")
    dur = positive(spec["duration"], f"{where}.duration")
    s = window(dur, float(spec.get("ramp_s", 1.0))) * SineSum(
        (float(spec["amplitude_m"]),), (positive(spec["freq_hz"], f"{where}.freq_hz"),), (0.0,))
    return Built(Fixed(tuple(q0)), Path3(p0, [(d, s)]), dur, True)


def _random_motion(spec, q0, p0, rng, where):
    take(spec, where, ["type", "duration"], _RANDOM_KEYS + ["translation_rms_m", "translation_band_hz"])
    dur = positive(spec["duration"], f"{where}.duration")
    rng = np.random.default_rng(spec["seed"]) if "seed" in spec else rng
    ori = _random_rotation_signal(spec, q0, rng, where, dur)
    rms = _non_negative(spec, "translation_rms_m", where, 0.1)
    lo, hi = _band(spec, "translation_band_hz", where, (0.1, 1.0))
    win = window(dur, float(spec.get("ramp_s", 1.0)))
    terms = []
    for i in range(3):
        f = rng.uniform(lo, hi, 4)
        u = rng.uniform(0.5, 1.0, 4)
        amps = (rms / np.sqrt(3.0)) * np.sqrt(2.0) * u / np.sqrt(np.sum(u ** 2))
        terms.append((np.eye(3)[i], win * SineSum(tuple(amps), tuple(f), tuple(rng.uniform(0, 2 * np.pi, 4)))))
    return Built(ori, Path3(p0, terms), dur, True)


SEGMENT_TYPES = {
    "rest": _rest,
    "rotate": _rotate,
    "orient": _orient,
    "random_rotation": _random_rotation,
    "translate": _translate,
    "random_motion": _random_motion,
}


# ------------------------------------------------------------------------- sequence
class _SeqOrientation(OrientationSignal):
    def __init__(self, seq):
        self.seq = seq

    def __call__(self, t):
        t = np.asarray(t, dtype=float)
        q = np.empty(t.shape + (4,))
        w = np.empty(t.shape + (3,))
        wd = np.empty(t.shape + (3,))
        for idx, seg, tl in self.seq._pieces(t):
            q[idx], w[idx], wd[idx] = seg.orientation(tl)
        return q, w, wd

    def moving(self, t):
        return self.seq.moving(t)


class _SeqPosition(PositionSignal):
    def __init__(self, seq):
        self.seq = seq

    def __call__(self, t):
        t = np.asarray(t, dtype=float)
        out = [np.empty(t.shape + (3,)) for _ in range(3)]
        for idx, seg, tl in self.seq._pieces(t):
            p, v, a = seg.position(tl)
            out[0][idx], out[1][idx], out[2][idx] = p, v, a
        return tuple(out)

    def moving(self, t):
        return self.seq.moving(t)


class BodySequence:
    """Segments laid end to end from an initial orientation q0 and position p0 (m, ENU)."""

    def __init__(self, segments: list[dict], q0=(1.0, 0.0, 0.0, 0.0), p0=(0.0, 0.0, 0.0),
                 rng: np.random.Generator | None = None, where: str = "motion.segments"):
        if not isinstance(segments, list) or not segments:
            raise SpecError(f"{where}: expected a non-empty list of segments")
        rng = rng if rng is not None else np.random.default_rng(0)
        q = Q.as_quat(q0)
        p = np.asarray(p0, dtype=float)
        self.built: list[Built] = []
        self.starts: list[float] = []
        t = 0.0
        for i, spec in enumerate(segments):
            w = f"{where}[{i}]"
            if not isinstance(spec, dict) or spec.get("type") not in SEGMENT_TYPES:
                got = spec.get("type") if isinstance(spec, dict) else spec
                raise SpecError(f"{w}.type: unknown segment type {got!r}; "
                                f"known: {', '.join(SEGMENT_TYPES)}")
            b = SEGMENT_TYPES[spec["type"]](spec, q, p, rng, w)
            self.built.append(b)
            self.starts.append(t)
            t += b.duration
            end = np.array([b.duration])
            q = Q.normalize(b.orientation(end)[0][0])
            p = b.position(end)[0][0]
        self.duration = t
        self.orientation = _SeqOrientation(self)
        self.position = _SeqPosition(self)

    def _pieces(self, t):
        """(index mask, built segment, local time clipped to the segment) for each segment."""
        seg_idx = np.searchsorted(np.asarray(self.starts), t, side="right") - 1
        seg_idx = np.clip(seg_idx, 0, len(self.built) - 1)
        for i, b in enumerate(self.built):
            idx = seg_idx == i
            if np.any(idx):
                yield idx, b, np.clip(t[idx] - self.starts[i], 0.0, b.duration)

    def moving(self, t):
        t = np.asarray(t, dtype=float)
        m = np.zeros(t.shape, dtype=bool)
        for idx, b, tl in self._pieces(t):
            m[idx] = b.moving
        return m & (t >= 0) & (t <= self.duration)

    def body(self) -> RigidMotion:
        return RigidMotion(self.orientation, self.position)
