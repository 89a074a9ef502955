"""Automatic static-window detection from gyroscope and accelerometer.

A sample is *still* when, over a centred moving window of ``window_s`` seconds,

* every gyroscope axis has a standard deviation ≤ ``gyr_std_max`` (rad/s) and the gyroscope
  mean magnitude is ≤ ``gyr_abs_max`` (rad/s; generous, because an uncalibrated gyroscope has a
  bias — the standard-deviation test does the real work), and
* every accelerometer axis has a standard deviation ≤ ``acc_std_max`` (m/s²).

Runs of still samples at least ``min_duration_s`` long become windows; ``trim_s`` is removed at
both ends (settling after a move).  If the gyroscope is absent only the accelerometer test is
applied.  All calibrations that need rest data (accelerometer poses, gyroscope bias, the
standing/lying postures) use these windows.
"""
from __future__ import annotations

from dataclasses import dataclass, asdict

import numpy as np

from kinefuse.host.errors import KinefuseError


@dataclass(frozen=True)
class StaticConfig:
    window_s: float = 0.5
    gyr_std_max: float = 0.035      # rad/s (2 °/s)
    gyr_abs_max: float = 0.35       # rad/s (20 °/s)
    acc_std_max: float = 0.15       # m/s²
    min_duration_s: float = 1.0
    trim_s: float = 0.1

    def to_dict(self) -> dict:
        return asdict(self)

    @classmethod
    def from_args(cls, args) -> "StaticConfig":
        """From the ``--static-window`` ... ``--min-duration`` options calibrate and report share,
        checked."""
        return cls(window_s=args.static_window, gyr_std_max=args.gyr_std_max,
                   gyr_abs_max=args.gyr_abs_max, acc_std_max=args.acc_std_max,
                   min_duration_s=args.min_duration).check()

    def check(self) -> "StaticConfig":
        """Itself, after a one-line error for a threshold that is not a positive finite number
        (``trim_s`` may be 0); the flag is named as ``calibrate`` and ``report`` spell it."""
        import math
        for name, v in self.to_dict().items():
            ok = math.isfinite(v) and (v >= 0 if name == "trim_s" else v > 0)
            if not ok:
                flag = _FLAGS.get(name, name)
                raise KinefuseError(f"static detection: {name} must be positive and finite, got "
                                    f"{v:g} ({flag})")
        return self


_FLAGS = {"window_s": "--static-window", "gyr_std_max": "--gyr-std-max",
          "gyr_abs_max": "--gyr-abs-max", "acc_std_max": "--acc-std-max",
          "min_duration_s": "--min-duration"}


@dataclass(frozen=True)
class StaticWindow:
    start: int   # first sample index (inclusive)
    stop: int    # last sample index (exclusive)
    t0: float    # s
    t1: float    # s

    @property
    def n(self) -> int:
        return self.stop - self.start


def _moving(x: np.ndarray, w: int) -> tuple[np.ndarray, np.ndarray]:
    """Centred moving mean and standard deviation along axis 0 (edges use shorter windows)."""
    n = len(x)
    c1 = np.concatenate([np.zeros((1,) + x.shape[1:]), np.cumsum(x, axis=0)])
    c2 = np.concatenate([np.zeros((1,) + x.shape[1:]), np.cumsum(x * x, axis=0)])
    half = w // 2
    i = np.arange(n)
    lo = np.clip(i - half, 0, n)
    hi = np.clip(i - half + w, 0, n)
    cnt = (hi - lo).reshape((-1,) + (1,) * (x.ndim - 1)).astype(float)
    mean = (c1[hi] - c1[lo]) / cnt
    var = np.maximum((c2[hi] - c2[lo]) / cnt - mean * mean, 0.0)
    return mean, np.sqrt(var)


def still_mask(t, acc, gyr=None, config: StaticConfig = StaticConfig(), *,
               source: str | None = None) -> np.ndarray:
    """Boolean per-sample stillness (before the minimum-duration rule); ``source`` (the
    recording's file) prefixes the error messages."""
    where = f"{source}: " if source else ""
    t = np.asarray(t, dtype=float)
    acc = np.asarray(acc, dtype=float)
    if acc.ndim != 2 or acc.shape[1] != 3 or len(acc) != len(t):
        raise KinefuseError(f"{where}static detection needs N×3 accelerometer data matching the time base")
    if len(t) < 3:
        raise KinefuseError(f"{where}recording too short for static detection ({len(t)} sample(s), "
                            f"need at least 3)")
    dt = float(np.median(np.diff(t)))
    if not dt > 0:
        raise KinefuseError(f"{where}time stamps do not increase; cannot detect static windows")
    w = max(3, int(round(config.window_s / dt)))
    _, sa = _moving(acc, w)
    ok = np.all(sa <= config.acc_std_max, axis=1)
    if gyr is not None:
        gyr = np.asarray(gyr, dtype=float)
        mg, sg = _moving(gyr, w)
        ok &= np.all(sg <= config.gyr_std_max, axis=1)
        ok &= np.linalg.norm(mg, axis=1) <= config.gyr_abs_max
    return ok


def detect_static(t, acc, gyr=None, config: StaticConfig = StaticConfig(), *,
                  source: str | None = None) -> list[StaticWindow]:
    """Static windows (see the module docstring), in time order; ``source`` names the file
    in error messages."""
    t = np.asarray(t, dtype=float)
    ok = still_mask(t, acc, gyr, config, source=source)
    dt = float(np.median(np.diff(t)))
    trim = int(round(config.trim_s / dt))
    edges = np.flatnonzero(np.diff(np.concatenate([[0], ok.astype(np.int8), [0]])))
    out = []
    for s, e in zip(edges[::2], edges[1::2]):
        s2, e2 = s + trim, e - trim
        if e2 - s2 < 2:
            continue
        if t[e2 - 1] - t[s2] + dt < config.min_duration_s:
            continue
        out.append(StaticWindow(int(s2), int(e2), float(t[s2]), float(t[e2 - 1])))
    return out


def window_means(x, windows: list[StaticWindow]) -> np.ndarray:
    """Mean of ``x`` (N×k) over each window → (len(windows)×k)."""
    x = np.asarray(x, dtype=float)
    return np.array([x[w.start:w.stop].mean(axis=0) for w in windows]).reshape(len(windows), -1)


def require_windows(windows: list[StaticWindow], n_min: int, what: str,
                    config: StaticConfig) -> None:
    if len(windows) < n_min:
        raise KinefuseError(
            f"{what}: found {len(windows)} static window(s), need at least {n_min} "
            f"(still ≥ {config.min_duration_s:g} s with gyro std ≤ {config.gyr_std_max:g} rad/s, "
            f"mean |gyro| ≤ {config.gyr_abs_max:g} rad/s and acc std ≤ {config.acc_std_max:g} "
            f"m/s²; adjust the thresholds (--gyr-std-max, --gyr-abs-max, --acc-std-max, "
            f"--min-duration) if the recording is noisier)")
