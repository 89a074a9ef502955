"""Sample timing: when samples are taken, what time stamps say, which ones arrive.

Nominal sample k is taken at k / (rate·(1 + drift)) true seconds (a clock running fast by
``clock_drift_ppm`` samples early) plus the sampling jitter (real irregular sampling, s, std,
clipped to ±0.4 of a period so the order is kept).  Its time stamp is the device clock at that
instant, true·(1 + drift), plus ``stamp_jitter_s`` (an error in the stamp only), rounded to
``stamp_resolution_s``.  Then samples are dropped (probability ``drop_prob`` each, and all
whose nominal time falls in a ``gaps_s`` interval) and duplicated (probability ``dup_prob``:
the same packet, values and stamp, delivered twice).  The first sample is never dropped.

``dt`` of a recording comes from the emitted stamps: dt[0] = 1/rate, dt[i] = t[i] − t[i−1]
(0 for a duplicate, a multiple of the period after drops).  A magnetometer at the acc/gyro rate
is sampled at the same instants; at a rate of its own it has jittered instants of its own.
A gyroscope sample covers the interval from the previous *nominal* sample's true instant to its
own (dropped or not; see ``scenario.interval_rates``).
"""
from __future__ import annotations

from dataclasses import asdict, dataclass, field

import numpy as np

from .segments import SpecError, take


@dataclass
class Timing:
    jitter_s: float = 0.0
    stamp_jitter_s: float = 0.0
    stamp_resolution_s: float = 0.0
    clock_drift_ppm: float = 0.0
    drop_prob: float = 0.0
    dup_prob: float = 0.0
    gaps_s: list = field(default_factory=list)

    @classmethod
    def from_dict(cls, d: dict | None) -> "Timing":
        if d is not None and not isinstance(d, dict):   # ([] ran without timing errors)
            raise SpecError(f"timing: expected an object, got {type(d).__name__}")
        d = dict(d or {})
        take(d, "timing", [], list(cls.__dataclass_fields__))
        try:
            t = cls(**{k: (float(v) if k != "gaps_s" else [tuple(map(float, g)) for g in v])
                       for k, v in d.items()})
        except (TypeError, ValueError):
            raise SpecError(f"timing: invalid values {d!r}") from None
        for k in ("jitter_s", "stamp_jitter_s", "stamp_resolution_s", "clock_drift_ppm"):
            if not np.isfinite(getattr(t, k)):      # (NaN or inf: NaN time stamps)
                raise SpecError(f"timing.{k}: must be finite")
        if not t.clock_drift_ppm > -1e6:            # (-1e6 ppm: a stopped clock, infinite instants)
            raise SpecError("timing.clock_drift_ppm: must be > -1000000 (a clock that runs)")
        for k in ("jitter_s", "stamp_jitter_s", "stamp_resolution_s"):
            if getattr(t, k) < 0:
                raise SpecError(f"timing.{k}: must be >= 0")
        for k in ("drop_prob", "dup_prob"):
            if not 0 <= getattr(t, k) < 1:
                raise SpecError(f"timing.{k}: must be in [0, 1)")
        for g in t.gaps_s:
            if len(g) != 2 or not g[1] > g[0]:
                raise SpecError(f"timing.gaps_s: each gap is [start, end] with end > start, got {g!r}")
        return t

    def to_dict(self) -> dict:
        d = asdict(self)
        d["gaps_s"] = [list(g) for g in self.gaps_s]
        return d

    # ------------------------------------------------------------------------------
    def instants(self, n: int, rate_hz: float, rng: np.random.Generator) -> np.ndarray:
        """True sampling instants (s) of n nominal samples."""
        k = np.arange(n, dtype=float)
        t = k / (rate_hz * (1.0 + 1e-6 * self.clock_drift_ppm))
        jit = rng.standard_normal(n) * self.jitter_s
        lim = 0.4 / rate_hz
        return t + np.clip(jit, -lim, lim)

    def stamps(self, t_true: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        s = t_true * (1.0 + 1e-6 * self.clock_drift_ppm) + rng.standard_normal(len(t_true)) * self.stamp_jitter_s
        if self.stamp_resolution_s > 0:
            s = np.round(s / self.stamp_resolution_s) * self.stamp_resolution_s
        return s

    def delivered(self, n: int, rate_hz: float, rng: np.random.Generator) -> np.ndarray:
        """Indices of the nominal samples in the order they are emitted (drops, duplicates)."""
        drop = rng.random(n) < self.drop_prob
        dup = rng.random(n) < self.dup_prob
        tn = np.arange(n) / rate_hz
        for a, b in self.gaps_s:
            drop |= (tn >= a) & (tn < b)
        if n:
            drop[0] = False
        keep = np.flatnonzero(~drop)
        return np.repeat(keep, np.where(dup[keep], 2, 1))


def sample_count(duration_s: float, rate_hz: float) -> int:
    """Samples at 0, 1/rate, … up to and including ``duration_s``."""
    return int(np.floor(duration_s * rate_hz + 1e-9)) + 1
