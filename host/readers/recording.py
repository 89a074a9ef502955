"""Common structure returned by every reader, and shared validation helpers.

Units and frames of :class:`Recording` (whatever the file used):

* ``t`` — seconds, strictly increasing, from the file's own clock (first sample not forced
  to 0; ``t - t[0]`` for elapsed time);
* ``acc`` — m/s², sensor frame, specific force (+g upwards at rest);
* ``gyr`` — rad/s, sensor frame;
* ``mag`` — µT, sensor frame, on the common time base ``t`` (slower magnetometers are held:
  each sample is repeated until the next one arrives, no interpolation); the native-rate
  samples are kept in ``mag_t``/``mag_native`` for calibration;
* ``quat`` — (w, x, y, z), the device's own orientation estimate, sensor → the device's earth
  frame (whatever that device uses; see ``metadata["quat_frame"]``);
* ``channels`` — any other per-sample column, named with its unit (``angle_raw_deg``…).

Absent sensors are ``None``.  Readers validate units, rates, gaps and monotonic time and raise
:class:`ReaderError` — a one-line message ``<file>: line <n>: <problem>``.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from kinefuse.host.errors import KinefuseError

G = 9.80665
DEG = np.pi / 180.0


class ReaderError(KinefuseError):
    """A file that cannot be read as claimed; message names file, line and problem."""

    def __init__(self, path: str, problem: str, line: int | None = None):
        where = f"{path}: line {line}: " if line is not None else f"{path}: "
        super().__init__(where + problem)
        self.path, self.line, self.problem = path, line, problem


@dataclass
class Recording:
    t: np.ndarray
    acc: np.ndarray | None = None
    gyr: np.ndarray | None = None
    mag: np.ndarray | None = None
    quat: np.ndarray | None = None
    channels: dict = field(default_factory=dict)
    fs: float = float("nan")
    source: str = ""
    fmt: str = ""
    metadata: dict = field(default_factory=dict)
    warnings: list = field(default_factory=list)
    mag_t: np.ndarray | None = None
    mag_native: np.ndarray | None = None

    def __len__(self) -> int:
        return len(self.t)

    @property
    def duration(self) -> float:
        return float(self.t[-1] - self.t[0]) if len(self.t) > 1 else 0.0

    def require(self, *names: str) -> None:
        """Raise a one-line error if a needed stream is missing."""
        for n in names:
            if getattr(self, n) is None:
                raise KinefuseError(f"{self.source}: {self.fmt} recording has no {n} data "
                                    f"(needed here)")

    def slice(self, i0: int, i1: int) -> "Recording":
        """Samples i0 ≤ i < i1 (native magnetometer samples in the same time span)."""
        def s(a):
            return None if a is None else a[i0:i1]
        r = Recording(self.t[i0:i1], s(self.acc), s(self.gyr), s(self.mag), s(self.quat),
                      {k: v[i0:i1] for k, v in self.channels.items()}, self.fs, self.source,
                      self.fmt, dict(self.metadata), list(self.warnings))
        if self.mag_t is not None and len(r.t):
            sel = (self.mag_t >= r.t[0]) & (self.mag_t <= r.t[-1])
            r.mag_t, r.mag_native = self.mag_t[sel], self.mag_native[sel]
        return r

    def mag_samples(self) -> np.ndarray | None:
        """Magnetometer samples at their native rate (for calibration fits)."""
        return self.mag_native if self.mag_native is not None else self.mag


# ----------------------------------------------------------------------------- validation
def check_time(path: str, t: np.ndarray, lines: np.ndarray | None = None, *,
               what: str = "time", gap_factor: float = 1.5) -> tuple[float, list[str]]:
    """Strictly increasing time; returns (nominal rate Hz, warnings about gaps)."""
    if len(t) < 2:
        raise ReaderError(path, f"only {len(t)} sample(s); need at least 2")
    if not np.all(np.isfinite(t)):
        k = int(np.argmax(~np.isfinite(t)))
        raise ReaderError(path, f"{what} is not a number", _line(lines, k))
    d = np.diff(t)
    if np.any(d <= 0):
        k = int(np.argmax(d <= 0)) + 1
        kind = "repeats" if d[k - 1] == 0 else "goes backwards"
        raise ReaderError(path, f"{what} {kind} ({t[k - 1]:.6g} -> {t[k]:.6g} s)", _line(lines, k))
    dt = float(np.median(d))
    warnings = []
    gaps = np.flatnonzero(d > gap_factor * dt)
    if len(gaps):
        missing = int(np.round(d[gaps] / dt).sum() - len(gaps))
        k = int(gaps[0]) + 1
        warnings.append(f"{path}: {len(gaps)} gap(s) in {what}, about {missing} sample(s) missing; "
                        f"first before line {_line(lines, k)} ({d[gaps[0]]:.4g} s instead of "
                        f"{dt:.4g} s)")
    return 1.0 / dt, warnings


def _line(lines, k):
    if lines is None:
        return k + 2  # header on line 1
    return int(lines[k])


def check_finite(path: str, a: np.ndarray, name: str, lines: np.ndarray | None = None) -> None:
    bad = ~np.all(np.isfinite(a.reshape(len(a), -1)), axis=1)
    if bad.any():
        k = int(np.argmax(bad))
        raise ReaderError(path, f"{name} value missing or not a number", _line(lines, k))


def check_finite_columns(path: str, a: np.ndarray, names: list[str], lines: np.ndarray | None = None) -> None:
    """Every value finite (NaN, inf and overflowing numbers such as 1e400 refused), naming
    the column and the line of the first bad one."""
    bad = ~np.isfinite(a)
    if bad.any():
        k, c = map(int, np.argwhere(bad)[0])
        raise ReaderError(path, f"column {names[c]!r}: {a[k, c]!r} is not a finite number", _line(lines, k))


def check_rate(path: str, fs: float, expected: tuple[float, ...], what: str, warnings: list,
               tol: float = 0.05) -> None:
    """Warn (one line) when the measured rate is not within ``tol`` of one of the rates the
    format is recorded at."""
    if not any(abs(fs - e) <= tol * e for e in expected):
        exp = " or ".join(f"{e:g}" for e in expected)
        warnings.append(f"{path}: {what} rate is {fs:.4g} Hz, not the expected {exp} Hz "
                        f"(check the export settings; times are used as recorded)")


def check_acc_units(path: str, acc: np.ndarray, unit: str) -> None:
    """Median |acc| must be near 1 g in the declared unit (catches g vs m/s² mix-ups)."""
    med = float(np.median(np.linalg.norm(acc, axis=1)))
    if unit == "m/s^2" and med < 3.0:
        raise ReaderError(path, f"accelerometer median magnitude is {med:.3g}: looks like g, "
                                f"but the format stores m/s²")
    if unit == "g" and med > 3.0:
        raise ReaderError(path, f"accelerometer median magnitude is {med:.3g}: looks like m/s², "
                                f"but the format stores g")


def check_gyro_range(path: str, gyr_dps: np.ndarray, expected_range_dps: float | None,
                     warnings: list) -> dict:
    """Infer the gyroscope LSB (16-bit) from the value grid; compare with the configured range.

    Seed 001 saw a MetaMotionR export quantised at the ±2000 °/s step although ±500 °/s was
    configured: the finest spacing between distinct values reveals the real full scale.
    """
    info = {}
    v = np.unique(np.round(np.abs(gyr_dps.ravel()), 6))
    steps = np.diff(v)
    steps = steps[steps > 1e-6]
    if len(steps) >= 10:
        lsb = float(np.percentile(steps, 5))
        rng = lsb * 32768.0
        info = {"gyr_lsb_dps": lsb, "gyr_range_dps_inferred": rng}
        if expected_range_dps is not None:
            ratio = rng / expected_range_dps
            if not 0.8 < ratio < 1.25:
                warnings.append(
                    f"{path}: gyroscope values are quantised at {lsb:.4g} °/s, i.e. a "
                    f"≈ ±{round(rng, -1):.0f} °/s range, but ±{expected_range_dps:g} °/s was configured")
    if expected_range_dps is not None:
        sat = np.abs(gyr_dps) >= 0.999 * expected_range_dps
        if sat.any():
            warnings.append(f"{path}: {int(sat.any(axis=1).sum())} gyroscope sample(s) at the "
                            f"±{expected_range_dps:g} °/s limit (saturated)")
    return info


def zero_order_hold(t_slow: np.ndarray, x_slow: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Latest slow sample at or before each t (the first slow sample before it starts)."""
    idx = np.searchsorted(t_slow, t, side="right") - 1
    return x_slow[np.clip(idx, 0, len(t_slow) - 1)]
