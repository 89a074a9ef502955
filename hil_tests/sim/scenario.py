"""Declarative scenarios and the simulation run.

A scenario is a JSON-friendly dict (or the :class:`Scenario` dataclass) so the same
description drives the Python models, the host SIL and QEMU runs::

    {
      "name": "slow_rotation", "description": "...", "seed": 0,
      "motion": {"kind": "body" | "gait" | "hinge", ...},   # see segments.py, gait.py, hinge.py
      "sensor": {"preset": "metamotionr", "rate_hz": 100, "mag_rate_hz": 20,
                 "gyr": {"bias_dps": [1, 1, 1]}, "acc": {...}, "mag": {...}},
      "sensor_overrides": {"distal": {...}},   # per-sensor changes on top of "sensor"
      "earth": {"g": 9.81, "field_uT": 49, "dip_deg": 64, "declination_deg": 0},
      "timing": {"jitter_s": 0, "stamp_jitter_s": 0, "stamp_resolution_s": 0,
                 "clock_drift_ppm": 0, "drop_prob": 0, "dup_prob": 0, "gaps_s": []},
      "disturbances": [{"type": "field_scale", ...}, ...],   # see disturbances.py
      "duration_s": null                       # default: the motion's duration
    }

:func:`run` returns one :class:`Recording` per sensor unit; :func:`simulate` one recording.
Randomness: ``numpy.random.SeedSequence(seed)`` spawns independent streams for the motion,
the disturbances and each sensor (timing, gyr, acc, mag), so the same seed gives identical
arrays and the streams do not shift when a scenario gains a sensor or a disturbance.
"""
from __future__ import annotations

import copy
import json
from dataclasses import asdict, dataclass, field

import numpy as np

from . import quat as Q
from .disturbances import Disturbances
from .earth import Earth
from .gait import gait_rig
from .hinge import hinge_rig
from .presets import preset
from .recording import Recording
from .rig import Rig, body_rig
from .segments import SpecError, take
from .timing import Timing, sample_count

RIGS = {"body": body_rig, "gait": gait_rig, "hinge": hinge_rig}
#: most samples one sensor stream may have (a simulation needs about 0.7 kB per sample: a larger
#: rate x duration would run out of memory and be killed instead of failing with a message)
MAX_SAMPLES = 10_000_000


@dataclass
class Scenario:
    name: str
    motion: dict
    description: str = ""
    sensor: dict = field(default_factory=lambda: {"preset": "metamotionr"})
    sensor_overrides: dict = field(default_factory=dict)
    earth: dict = field(default_factory=dict)
    timing: dict = field(default_factory=dict)
    disturbances: list = field(default_factory=list)
    duration_s: float | None = None
    seed: int = 0

    @classmethod
    def from_dict(cls, d: dict) -> "Scenario":
        take(d, "scenario", ["name", "motion"], list(cls.__dataclass_fields__))
        sc = cls(**copy.deepcopy(d))
        sc.validate()
        return sc

    @classmethod
    def from_json(cls, text: str) -> "Scenario":
        try:
            d = json.loads(text)
        except json.JSONDecodeError as exc:
            raise SpecError(f"scenario JSON: {exc}") from None
        return cls.from_dict(d)

    def to_dict(self) -> dict:
        return copy.deepcopy(asdict(self))

    def to_json(self, indent: int | None = 2) -> str:
        return json.dumps(self.to_dict(), indent=indent)

    def replace(self, **changes) -> "Scenario":
        d = self.to_dict()
        d.update(copy.deepcopy(changes))
        return Scenario.from_dict(d)

    def validate(self) -> None:
        """Build everything once (cheap): raises SpecError with a one-line message."""
        build(self)


@dataclass
class Built:
    rig: Rig
    sensors: dict          # sensor name → SensorModel
    earth: Earth
    timing: Timing
    disturbances: Disturbances
    duration: float


def _streams(seed: int):
    root = np.random.SeedSequence(int(seed))
    motion, dist, sensors = root.spawn(3)
    return motion, dist, sensors


def build(sc: Scenario) -> Built:
    """Parse and assemble a scenario; any malformed value becomes a one-line SpecError."""
    try:
        with np.errstate(all="ignore"):     # (overflows: see run)
            return _build(sc)
    except SpecError:
        raise
    except (TypeError, ValueError, KeyError, IndexError) as exc:
        raise SpecError(f"scenario {sc.name!r}: invalid value ({type(exc).__name__}: {exc})") from None


def _build(sc: Scenario) -> Built:
    # (a seed of 1.5 ran as seed 1; a "sensor" that is not an object, e.g. [], as the default)
    whole = isinstance(sc.seed, (int, np.integer)) or (isinstance(sc.seed, float) and sc.seed.is_integer())
    if isinstance(sc.seed, bool) or not whole or sc.seed < 0:
        raise SpecError(f"seed: expected a whole number >= 0, got {sc.seed!r}")
    if sc.sensor is not None and not isinstance(sc.sensor, dict):
        raise SpecError(f"sensor: expected an object, got {type(sc.sensor).__name__}")
    if not isinstance(sc.motion, dict) or sc.motion.get("kind") not in RIGS:
        got = sc.motion.get("kind") if isinstance(sc.motion, dict) else sc.motion
        raise SpecError(f"motion.kind: unknown {got!r}; known: {', '.join(RIGS)}")
    ss_motion, ss_dist, _ = _streams(sc.seed)
    rig = RIGS[sc.motion["kind"]](sc.motion, np.random.default_rng(ss_motion))
    base = dict(sc.sensor or {})
    model = preset(base.get("preset", "metamotionr")).updated(base, "sensor")
    if not isinstance(sc.sensor_overrides, dict):
        raise SpecError("sensor_overrides: expected an object {sensor name: overrides}")
    unknown = sorted(set(sc.sensor_overrides) - set(rig.tracks))
    if unknown:
        raise SpecError(f"sensor_overrides: no sensor named {', '.join(unknown)}; "
                        f"this rig has {', '.join(rig.tracks)}")
    sensors = {}
    for name in rig.tracks:
        ov = sc.sensor_overrides.get(name, {})
        if not isinstance(ov, dict):    # ([["rate_hz", 50]] was read as {"rate_hz": 50})
            raise SpecError(f"sensor_overrides.{name}: expected an object, got {type(ov).__name__}")
        if "preset" in ov:
            raise SpecError(f"sensor_overrides.{name}: a per-sensor preset is not supported")
        sensors[name] = model.updated(ov, f"sensor_overrides.{name}")
    duration = rig.duration if sc.duration_s is None else float(sc.duration_s)
    if not duration > 0:
        raise SpecError("duration_s: must be > 0")
    for name, m in sensors.items():
        rate = max(m.rate_hz, m.mag_rate)
        if duration * rate > MAX_SAMPLES:
            raise SpecError(f"{duration:g} s at {rate:g} Hz is {duration * rate:.3g} samples for "
                            f"sensor {name}; at most {MAX_SAMPLES:,} (lower the rate or the "
                            f"duration)")
    return Built(rig, sensors, Earth.from_dict(sc.earth), Timing.from_dict(sc.timing),
                 Disturbances.from_list(sc.disturbances, np.random.default_rng(ss_dist)), duration)


def run(scenario, seed: int | None = None, **changes) -> dict:
    """Simulate every sensor of ``scenario`` (a Scenario, a dict or a library name).

    ``seed`` and any other Scenario field given as keyword (e.g. ``sensor={...}``) override
    the scenario's.  Returns {sensor name: Recording}.
    """
    sc = as_scenario(scenario)
    if seed is not None:
        changes["seed"] = int(seed)
    if changes:
        sc = sc.replace(**changes)
    b = build(sc)
    _, _, ss_sensors = _streams(sc.seed)
    per_sensor = ss_sensors.spawn(len(b.rig.tracks))
    # an overflow or NaN is reported once, as the one-line non-finite error of
    # _simulate_sensor, not as numpy warnings with source lines on stderr
    with np.errstate(all="ignore"):
        return {name: _simulate_sensor(sc, b, name, track, ss)
                for (name, track), ss in zip(b.rig.tracks.items(), per_sensor)}


def simulate(scenario, seed: int | None = None, unit: str | None = None, **changes) -> Recording:
    """One sensor unit's Recording; ``unit`` names it when the rig has several (e.g.
    ``unit="distal"``).  Keyword changes are Scenario fields, e.g. ``sensor={"preset": "ideal"}``."""
    sc = as_scenario(scenario)
    recs = run(sc, seed, **changes)
    if unit is None:
        if len(recs) != 1:
            raise SpecError(f"scenario {sc.name!r} has sensor units {', '.join(recs)}; pass unit=")
        return next(iter(recs.values()))
    if unit not in recs:
        raise SpecError(f"scenario {sc.name!r} has no sensor unit {unit!r}; it has {', '.join(recs)}")
    return recs[unit]


def as_scenario(x) -> Scenario:
    if isinstance(x, Scenario):
        return x
    if isinstance(x, dict):
        return Scenario.from_dict(x)
    if isinstance(x, str):
        from .library import scenario as named
        return named(x)
    raise SpecError(f"expected a Scenario, dict or scenario name, got {type(x).__name__}")


#: Gauss-Legendre nodes (on [0, 1]) and weights of the interval means, 4 points on each half of
#: the interval: they integrate only the coning part of the mean (zero about a fixed axis)
_GL_X, _GL_W = np.polynomial.legendre.leggauss(4)
_MEAN_NODES = np.concatenate([(_GL_X + 1) / 4, (_GL_X + 1) / 4 + 0.5])
_MEAN_WEIGHTS = np.concatenate([_GL_W, _GL_W]) / 4


def _bortz_excess(theta: np.ndarray, w: np.ndarray) -> np.ndarray:
    """θ̇ − ω of the rotation vector θ of a body turning at body rate ω (Bortz):
    ½ θ×ω + (1 − (a/2)·cot(a/2))/a² · θ×(θ×ω), a = |θ|; zero when θ ∥ ω."""
    a2 = np.sum(theta * theta, axis=-1, keepdims=True)
    a = np.sqrt(a2)
    safe = np.where(a > 1e-3, a, 1.0)
    f = np.where(a > 1e-3, (1.0 - 0.5 * safe / np.tan(0.5 * safe)) / (safe * safe),
                 1.0 / 12.0 + a2 / 720.0)
    c = np.cross(theta, w)
    return 0.5 * c + f * np.cross(theta, c)


def interval_rates(track, t_true: np.ndarray, rate_hz: float, sampling: str = "mean",
                   q: np.ndarray | None = None, w: np.ndarray | None = None) -> np.ndarray:
    """True gyroscope samples (N,3), rad/s, sensor frame, at the true (jittered, drifting)
    instants ``t_true`` of the nominal samples, each over the interval it closes
    (t[k−1], t[k]]; sample 0 closes the nominal period 1/rate before it.

    ``sampling`` (see :data:`.sensor.GYR_SAMPLING`): "mean" ∫ω dt / Δt (the interval's rotation
    vector less its coning part, integrated by Gauss-Legendre on the analytic body rate), "rotation" the rotation vector of q(t[k−1])⁻¹ ⊗ q(t[k]) / Δt (a plain
    strapdown step q_k = q_{k−1} ⊗ exp(ω_k·Δt_k/2) with the true steps reproduces q exactly),
    "instant" ω(t[k]).  Computed on the nominal samples, before drops and duplicates: a sample
    after a dropped one still covers only its own interval (a sensor's output register is
    overwritten each period whether or not it is read), a duplicate repeats its packet.
    ``q``, ``w``: the track's orientations and rates at ``t_true`` when already evaluated."""
    t_true = np.asarray(t_true, dtype=float)
    if sampling == "instant":
        return track.evaluate(t_true).w if w is None else w
    if not len(t_true):
        return np.zeros((0, 3))
    t_prev = np.concatenate([[t_true[0] - 1.0 / rate_hz], t_true[:-1]])
    step = t_true - t_prev
    w = track.evaluate(t_true).w if w is None else w
    turn = np.linalg.norm(w, axis=-1) * step
    if np.max(turn) > 0.5 * np.pi:      # the rotation vector of an interval is taken below 180°
        i = int(np.argmax(turn))
        raise SpecError(f"the sensor turns {np.degrees(turn[i]):.0f}° in one sample interval (at "
                        f"{t_true[i]:.3f} s, {np.degrees(np.linalg.norm(w[i])):.0f} °/s at {rate_hz:g} Hz): "
                        f"at most 90° per sample; raise rate_hz")
    if sampling == "rotation":
        q = track.evaluate(t_true).q if q is None else q
        q_prev = np.concatenate([track.evaluate(t_prev[:1]).q, q[:-1]])
        return Q.to_rotvec(Q.mul(Q.conj(q_prev), q)) / step[:, None]
    if sampling != "mean":
        raise SpecError(f"gyr.sampling: unknown {sampling!r}")
    # ∫ω ds = θ_k − ∫(θ̇ − ω) ds with θ(s) the rotation vector from q(t[k−1]) to q(s): the
    # rotation over the interval exactly, less its coning part, which the quadrature integrates
    # (a fixed axis has none: the mean is then the rotation's rate to rounding)
    q = track.evaluate(t_true).q if q is None else q
    k0 = track.evaluate(t_prev[:1])
    q_prev_inv = Q.conj(np.concatenate([k0.q, q[:-1]]))
    theta = Q.to_rotvec(Q.mul(q_prev_inv, q))
    # intervals at rest (no rotation, no rate at either end: the motion's rests) have no
    # coning part; only the others are integrated
    w_prev = np.concatenate([k0.w, w[:-1]])
    m = np.flatnonzero(np.any(theta != 0, axis=1) | np.any(w != 0, axis=1) | np.any(w_prev != 0, axis=1))
    for x, wt in zip(_MEAN_NODES, _MEAN_WEIGHTS):      # one node at a time: memory stays O(N)
        kn = track.evaluate(t_prev[m] + x * step[m])
        theta[m] -= wt * step[m, None] * _bortz_excess(Q.to_rotvec(Q.mul(q_prev_inv[m], kn.q)), kn.w)
    return theta / step[:, None]


def _simulate_sensor(sc: Scenario, b: Built, name: str, track, ss) -> Recording:
    model = b.sensors[name]
    timing_ss, gyr_ss, acc_ss, mag_ss = ss.spawn(4)
    trng = np.random.default_rng(timing_ss)
    fs, fm = model.rate_hz, model.mag_rate
    n = sample_count(b.duration, fs)
    m = sample_count(b.duration, fm)
    # draw order is fixed: instants, mag instants, stamps, delivery
    t_true = b.timing.instants(n, fs, trng)
    t_mag = b.timing.instants(m, fm, trng)
    if fm == fs:
        # at the acc/gyro rate the magnetometer is read with each sample: jittered instants of
        # its own left about a quarter of the samples holding the previous reading
        t_mag = t_true
    stamps = b.timing.stamps(t_true, trng)
    src = b.timing.delivered(n, fs, trng)

    k = track.evaluate(t_true)
    g_up = b.earth.gravity_up
    f_earth = k.a + g_up
    acc_true = Q.rotate_inv(k.q, f_earth)
    # the gyroscope reports the mean rate over the sample interval that ends at its instant
    # (what the filters integrate: ω_k·dt_k over (t[k−1], t[k]]; gyr.sampling); accelerometer
    # and magnetometer are instantaneous
    gyr_inst = k.w
    gyr_true = interval_rates(track, t_true, fs, model.gyr.sampling, q=k.q, w=k.w)
    d_acc, d_gyr, inertial_on = b.disturbances.inertial_add(t_true)
    gyr = model.gyr.apply(gyr_true + d_gyr, t_true, fs, np.random.default_rng(gyr_ss))
    acc = model.acc.apply(acc_true + d_acc, t_true, fs, np.random.default_rng(acc_ss))

    # magnetometer at its own instants, then held at the acc/gyro samples
    km = track.evaluate(t_mag)
    field_e = b.earth.field
    m_body = Q.rotate_inv(km.q, field_e + b.disturbances.mag_earth_add(t_mag, km.p, field_e))
    m_body = b.disturbances.mag_body_apply(t_mag, m_body)
    mag_samples = model.mag.apply(m_body, t_mag, fm, np.random.default_rng(mag_ss))
    # latest mag sample taken by then; 1 ns of slack: instants equal in exact arithmetic (a
    # 20 Hz magnetometer on every 5th sample of 100 Hz) differ in the last bit under clock drift
    j = np.searchsorted(t_mag, t_true + 1e-9, side="right") - 1
    j = np.maximum(j, 0)
    mag = mag_samples[j]

    mag_true = Q.rotate_inv(k.q, np.broadcast_to(field_e, k.q.shape[:-1] + (3,)))
    mag_dist = b.disturbances.mag_mask(t_true, k.p, field_e)
    moving = b.rig.moving(t_true)

    # emitted stream
    js = j[src]
    valid = np.ones(len(src), dtype=bool)
    valid[1:] = js[1:] != js[:-1]
    if not model.mag.present:
        valid[:] = False
    t_out = stamps[src]
    dt = np.empty(len(src))
    if len(src):
        dt[0] = 1.0 / fs
        dt[1:] = np.diff(t_out)
    truth = {"gyr_true": gyr_true[src], "gyr_inst": gyr_inst[src], "acc_true": acc_true[src],
             "mag_true": mag_true[src],
             "mag_disturbed": mag_dist[src], "acc_disturbed": inertial_on[src]}
    for jn, sig in b.rig.joints.items():
        truth[jn] = sig(t_true)[0][src]
    meta = {
        "scenario": sc.name, "sensor": name, "seed": int(sc.seed), "preset": model.name,
        "rate_hz": fs, "mag_rate_hz": fm, "duration_s": b.duration,
        "units": {"t": "s", "gyr": "rad/s", "acc": "m/s^2", "mag": "uT", "q_true": "w,x,y,z sensor->earth ENU",
                  "pos_true": "m ENU", "joint angles": "rad"},
        "lsb": {"acc": model.acc.lsb, "gyr": model.gyr.lsb, "mag": model.mag.lsb},
        "earth": b.earth.to_dict(), "sensor_model": model.to_dict(), "rig": b.rig.info,
        "scenario_spec": sc.to_dict(),
    }
    # a NaN or infinite number somewhere in the scenario (a disturbance's factor, a tap's peak,
    # a segment's rate) gave NaN samples and exit 0: refused, naming the streams it reached
    streams = {"t": t_out, "gyr": gyr[src], "acc": acc[src], "q_true": k.q[src]}
    if model.mag.present:
        streams["mag"] = mag[src]
    bad = [s for s, v in streams.items() if not np.all(np.isfinite(v))]
    if bad:
        raise SpecError(f"scenario {sc.name!r}: sensor {name}: non-finite {', '.join(bad)} samples "
                        f"(a NaN or infinite number in the scenario's motion or disturbances)")
    return Recording(t=t_out, dt=dt, gyr=gyr[src], acc=acc[src], mag=mag[src], mag_valid=valid,
                     q_true=k.q[src], movement=moving[src], pos_true=k.p[src], t_true=t_true[src],
                     index=src.astype(np.int64), truth=truth, meta=meta)
