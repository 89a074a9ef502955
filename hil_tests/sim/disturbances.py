"""Disturbances added to the physical signals before the sensor model.

Magnetic (earth frame, depend on time and sensor position):
  ``field_scale``      {t_start_s, t_end_s, factor, ramp_s=0}: the local field becomes
                       factor × the earth field (e.g. 2 → twice the norm; direction kept).
  ``uniform_field``    {t_start_s, t_end_s, field_uT: [E,N,U], ramp_s=0}: adds a constant vector.
  ``stationary_magnet``{position_m: [E,N,U], moment_Am2: [3], t_start_s?, t_end_s?}: point
                       dipole B = μ0/(4π)·(3r̂(r̂·m) − m)/|r|³ at the sensor position.
Magnetic (sensor frame):
  ``attached_magnet``  {t_start_s?, t_end_s?, offset_uT: [3], soft_iron: 3×3 = I}: while
                       attached m ← S·m + offset (hard + soft iron carried by the unit).
Inertial (sensor frame; *not* part of the rigid-body truth):
  ``taps``             {times_s: [...], acc_peak_ms2=60, gyr_peak_dps=20, duration_s=0.04,
                       directions: [[3],...] (default: random per tap)}: one full sine period
                       per tap on acc and gyro, so each tap has zero net velocity and zero net
                       rotation; the unmodelled rotation stays below gyr_peak·duration/π.
  ``vibration``        {t_start_s, t_end_s, freq_hz=40, acc_amp_ms2=[3], gyr_amp_dps=[3],
                       ramp_s=0}: sinusoids with random phases per axis (BROAD trial 26 shows
                       ≈ 40 Hz, ≈ 2 m/s² RMS, ≈ 1 °/s RMS at 285.7 Hz).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .segments import SpecError, positive, take, unit3, vec3
from .signals import window

MU0_4PI_UT = 0.1  # μ0/(4π) = 1e-7 T·m/A = 0.1 µT·m³/(A·m²)


def _envelope(t, t0, t1, ramp):
    t = np.asarray(t, dtype=float)
    if t1 <= t0:
        return np.zeros_like(t)
    if ramp and ramp > 0:
        return window(t1 - t0, ramp, t0)(t)[0]
    return ((t >= t0) & (t < t1)).astype(float)


def _window_keys(d, where, required=True):
    if required:
        t0, t1 = float(d["t_start_s"]), float(d["t_end_s"])
    else:
        t0, t1 = float(d.get("t_start_s", -np.inf)), float(d.get("t_end_s", np.inf))
    if not t1 > t0:
        raise SpecError(f"{where}: t_end_s must be after t_start_s")
    return t0, t1


def _ramp(d, where):
    r = float(d.get("ramp_s", 0.0))
    if not (np.isfinite(r) and r >= 0):         # (a negative or NaN ramp ran as no ramp)
        raise SpecError(f"{where}.ramp_s: must be >= 0 s, got {d.get('ramp_s')!r}")
    return r


@dataclass
class Disturbances:
    """All disturbances of a scenario, parsed.  Methods return additive terms or masks."""
    mag_earth: list
    mag_body: list
    inertial: list

    @classmethod
    def from_list(cls, items: list | None, rng: np.random.Generator) -> "Disturbances":
        me, mb, ine = [], [], []
        if items is not None and not isinstance(items, list):   # (a dict read as its keys)
            raise SpecError(f"disturbances: expected a list of objects, got {type(items).__name__}")
        for i, d in enumerate(items or []):
            w = f"disturbances[{i}]"
            if not isinstance(d, dict) or "type" not in d:
                raise SpecError(f"{w}: expected an object with a 'type'")
            kind = d["type"]
            if kind == "field_scale":
                take(d, w, ["type", "t_start_s", "t_end_s", "factor"], ["ramp_s"])
                me.append(("scale", *_window_keys(d, w), _ramp(d, w), float(d["factor"])))
            elif kind == "uniform_field":
                take(d, w, ["type", "t_start_s", "t_end_s", "field_uT"], ["ramp_s"])
                me.append(("uniform", *_window_keys(d, w), _ramp(d, w), vec3(d["field_uT"], w)))
            elif kind == "stationary_magnet":
                take(d, w, ["type", "position_m", "moment_Am2"], ["t_start_s", "t_end_s"])
                me.append(("dipole", *_window_keys(d, w, False), 0.0,
                           (vec3(d["position_m"], w), vec3(d["moment_Am2"], w))))
            elif kind == "attached_magnet":
                take(d, w, ["type", "offset_uT"], ["t_start_s", "t_end_s", "soft_iron"])
                s = np.asarray(d.get("soft_iron", np.eye(3)), dtype=float)
                if s.shape != (3, 3):
                    raise SpecError(f"{w}.soft_iron: expected a 3×3 matrix")
                mb.append((*_window_keys(d, w, False), vec3(d["offset_uT"], w), s))
            elif kind == "taps":
                take(d, w, ["type", "times_s"], ["acc_peak_ms2", "gyr_peak_dps", "duration_s", "directions"])
                times = np.atleast_1d(np.asarray(d["times_s"], dtype=float))
                if times.ndim != 1 or not np.all(np.isfinite(times)):   # (a NaN time: no tap)
                    raise SpecError(f"{w}.times_s: must be finite times in s, got {d['times_s']!r}")
                if "directions" in d:
                    dirs = np.array([unit3(x, f"{w}.directions") for x in d["directions"]])
                    if len(dirs) != len(times):
                        raise SpecError(f"{w}: directions must match times_s")
                else:
                    dirs = rng.normal(size=(len(times), 3))
                    dirs /= np.linalg.norm(dirs, axis=1, keepdims=True)
                gdirs = rng.normal(size=(len(times), 3))
                gdirs /= np.linalg.norm(gdirs, axis=1, keepdims=True)
                ine.append(("taps", times, dirs, gdirs, float(d.get("acc_peak_ms2", 60.0)),
                            np.radians(float(d.get("gyr_peak_dps", 20.0))),
                            positive(d.get("duration_s", 0.04), f"{w}.duration_s")))
            elif kind == "vibration":
                take(d, w, ["type", "t_start_s", "t_end_s"], ["freq_hz", "acc_amp_ms2", "gyr_amp_dps", "ramp_s"])
                ine.append(("vibration", *_window_keys(d, w), _ramp(d, w),
                            positive(d.get("freq_hz", 40.0), f"{w}.freq_hz"),
                            vec3(d.get("acc_amp_ms2", [3.0, 3.0, 2.0]), w),
                            np.radians(vec3(d.get("gyr_amp_dps", [1.5, 0.7, 0.8]), w)),
                            rng.uniform(0, 2 * np.pi, 6)))
            else:
                raise SpecError(f"{w}.type: unknown disturbance {kind!r}; known: field_scale, "
                                "uniform_field, stationary_magnet, attached_magnet, taps, vibration")
        return cls(me, mb, ine)

    # --- magnetic ------------------------------------------------------------------
    def mag_earth_add(self, t, p, earth_field) -> np.ndarray:
        """Earth-frame field added at times t (s) and positions p (N,3, m), µT."""
        t = np.asarray(t, dtype=float)
        out = np.zeros(t.shape + (3,))
        for kind, t0, t1, ramp, par in self.mag_earth:
            env = _envelope(t, t0, t1, ramp)[..., None]
            if kind == "scale":
                out += env * (par - 1.0) * earth_field
            elif kind == "uniform":
                out += env * par
            else:
                pos, mom = par
                r = p - pos
                rn = np.linalg.norm(r, axis=-1, keepdims=True)
                rn = np.maximum(rn, 1e-3)   # the dipole model is meaningless inside the magnet
                rh = r / rn
                out += env * MU0_4PI_UT * (3 * rh * np.sum(rh * mom, -1, keepdims=True) - mom) / rn ** 3
        return out

    def mag_body_apply(self, t, m_body) -> np.ndarray:
        out = m_body.copy()
        for t0, t1, offset, s in self.mag_body:
            on = (np.asarray(t) >= t0) & (np.asarray(t) < t1)
            out[on] = out[on] @ s.T + offset
        return out

    def mag_mask(self, t, p, earth_field) -> np.ndarray:
        """True where any magnetic disturbance changes the field by more than 0.5 µT."""
        t = np.asarray(t, dtype=float)
        m = np.linalg.norm(self.mag_earth_add(t, p, earth_field), axis=-1) > 0.5
        for t0, t1, offset, s in self.mag_body:
            m |= (t >= t0) & (t < t1)
        return m

    # --- inertial --------------------------------------------------------------------
    def inertial_add(self, t):
        """(acc add m/s², gyr add rad/s, active mask) in the sensor frame at times t."""
        t = np.asarray(t, dtype=float)
        acc = np.zeros(t.shape + (3,))
        gyr = np.zeros(t.shape + (3,))
        active = np.zeros(t.shape, dtype=bool)
        for item in self.inertial:
            if item[0] == "taps":
                _, times, dirs, gdirs, a_pk, g_pk, dur = item
                for tk, d, gd in zip(times, dirs, gdirs):
                    on = (t >= tk) & (t < tk + dur)
                    s = np.sin(2 * np.pi * (t[on] - tk) / dur)[:, None]
                    acc[on] += a_pk * s * d
                    gyr[on] += g_pk * s * gd
                    active |= on
            else:
                _, t0, t1, ramp, f, a_amp, g_amp, ph = item
                env = _envelope(t, t0, t1, ramp)[..., None]
                arg = 2 * np.pi * f * t[..., None]
                acc += env * a_amp * np.sin(arg + ph[:3])
                gyr += env * g_amp * np.sin(arg + ph[3:])
                active |= env[..., 0] > 0
        return acc, gyr, active
