"""Gyroscope calibration: bias from static windows, scale/misalignment from known rates.

The bias is the sample-weighted mean of the gyroscope over the *static windows* of a
recording (:mod:`kinefuse.host.calib.static`) — never the mean of a whole recording, which
includes the motion (seed 002 Annex H subtracts the whole-recording mean).  The spread of the
per-window means is reported: a large spread means the bias drifts (temperature) or a window
was not really still.

With known rotation rates (turntable / robot joint at constant speed) the full map
ω_cal = M (ω_raw − b) is fitted by linear least squares from ≥ 4 windows whose known rate
vectors, together with rest, span 3-D.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from kinefuse.host.calib import static as S
from kinefuse.host.calib.affine import apply_affine
from kinefuse.host.errors import KinefuseError


@dataclass
class GyroCalibration:
    M: np.ndarray                  # 3×3 (identity unless rates were given)
    b: np.ndarray                  # rad/s
    n_windows: int
    n_samples: int
    window_spread: float           # rad/s, max |window mean − b|; NaN with one window
    residual_rms: float = float("nan")   # rad/s, only with known rates
    method: str = "static-bias"
    windows: list = field(default_factory=list)

    def apply(self, raw) -> np.ndarray:
        return apply_affine(raw, self.M, self.b)

    def to_json(self) -> dict:
        return {"M": self.M.tolist(), "bias": self.b.tolist(), "units": "rad/s",
                "method": self.method, "n_windows": self.n_windows, "n_samples": self.n_samples,
                "window_spread": None if not np.isfinite(self.window_spread) else self.window_spread,
                "residual_rms": None if not np.isfinite(self.residual_rms) else self.residual_rms}


def bias_from_static(t, gyr, acc, config: S.StaticConfig = S.StaticConfig(),
                     windows: list[S.StaticWindow] | None = None, *,
                     source: str | None = None) -> GyroCalibration:
    """Gyroscope bias (rad/s) from the static windows of a recording (``source``: its file,
    named in errors)."""
    gyr = np.asarray(gyr, dtype=float)
    if windows is None:
        windows = S.detect_static(t, acc, gyr, config, source=source)
    S.require_windows(windows, 1, "gyroscope bias", config)
    sums = np.array([gyr[w.start:w.stop].sum(axis=0) for w in windows])
    counts = np.array([w.n for w in windows], dtype=float)
    b = sums.sum(axis=0) / counts.sum()
    means = sums / counts[:, None]
    # one window has no spread to show (it was reported as 0: "no drift", which it cannot tell)
    spread = float(np.max(np.linalg.norm(means - b, axis=1))) if len(windows) > 1 else float("nan")
    return GyroCalibration(np.eye(3), b, len(windows), int(counts.sum()), spread,
                           windows=[(w.t0, w.t1) for w in windows])


def fit_scale(measured_means, known_rates, *, rest_means=None) -> GyroCalibration:
    """Fit ω_known = M (ω_meas − b) from constant-rate windows (rad/s).

    ``measured_means``/``known_rates``: K×3 window means and the true rates; ``rest_means``
    (optional, R×3) are static windows whose true rate is zero.  Needs ≥ 4 rows in total
    whose known rates affinely span 3-D (e.g. +/− about each axis, or three axes plus rest).
    """
    meas = np.asarray(measured_means, dtype=float).reshape(-1, 3)
    known = np.asarray(known_rates, dtype=float).reshape(-1, 3)
    if meas.shape != known.shape:
        raise KinefuseError("measured and known rate tables must have the same number of rows")
    if rest_means is not None:
        rest = np.asarray(rest_means, dtype=float).reshape(-1, 3)
        meas = np.vstack([meas, rest])
        known = np.vstack([known, np.zeros_like(rest)])
    if len(meas) < 4:
        raise KinefuseError(f"gyroscope scale fit needs ≥ 4 windows (rates + rest), got {len(meas)}")
    if not (np.all(np.isfinite(meas)) and np.all(np.isfinite(known))):
        raise KinefuseError("gyroscope scale fit: the rate tables contain non-finite values")
    D = np.column_stack([meas, np.ones(len(meas))])
    sv = np.linalg.svd(np.column_stack([known, np.ones(len(known))]), compute_uv=False)
    if sv[-1] / sv[0] < 1e-3:
        raise KinefuseError("known rates do not excite all three axes (they must affinely span "
                            "3-D: rotate about each axis, and include rest or both directions)")
    sv = np.linalg.svd(D, compute_uv=False)
    if sv[-1] / sv[0] < 1e-3:
        # the known rates span 3-D but the gyroscope did not see them: the fit would divide
        # noise by noise (a unit that lay still gave scale factors of several hundred)
        raise KinefuseError("the measured rates in the windows do not span 3-D although the known "
                            "ones do: the gyroscope did not turn as stated (are t_start, t_end the "
                            "recording's times in seconds?)")
    P, *_ = np.linalg.lstsq(D, known, rcond=None)
    M = P[:3].T
    gain = float(abs(np.linalg.det(M)) ** (1.0 / 3.0))
    if not 0.5 <= gain <= 2.0:
        # real gyroscope scale errors are a few per cent: known rates in °/s against a gyroscope
        # in rad/s gave M ≈ 57·I, printed as a calibration without a word
        hint = " (°/s instead of rad/s?)" if 40 < gain < 80 else ""
        raise KinefuseError(f"the known rates are {gain:.3g} × the measured ones: not the same unit{hint}; "
                            f"give the rate windows' wx, wy, wz in rad/s")
    b = -np.linalg.solve(M, P[3])
    res = apply_affine(meas, M, b) - known
    return GyroCalibration(M, b, len(meas), 0, float("nan"),
                           residual_rms=float(np.sqrt(np.mean(res**2))), method="known-rates")


def scale_from_recording(t, gyr, acc, rate_windows, config: S.StaticConfig = S.StaticConfig(), *,
                         source: str | None = None) -> GyroCalibration:
    """Known-rate calibration from one recording.

    ``rate_windows``: rows (t_start, t_end, ωx, ωy, ωz) — time span (s) during which the true
    angular velocity (rad/s, sensor frame) was constant and known.  Static windows detected in
    the recording are added as zero-rate rows.
    """
    t = np.asarray(t, dtype=float)
    gyr = np.asarray(gyr, dtype=float)
    rw = np.asarray(rate_windows, dtype=float)
    if rw.ndim != 2 or rw.shape[1] != 5:
        raise KinefuseError("rate windows must have 5 columns: t_start, t_end, wx, wy, wz")
    for k, (t0, t1, *w) in enumerate(rw):
        if not np.all(np.isfinite(rw[k])):
            raise KinefuseError(f"rate window {k + 1}: t_start, t_end, wx, wy, wz must be finite numbers")
        if not t1 > t0:
            raise KinefuseError(f"rate window {k + 1}: t_end {t1:g} s is not after t_start {t0:g} s")
    meas, known = [], []
    for k, (t0, t1, *w) in enumerate(rw):
        sel = (t >= t0) & (t <= t1)
        if sel.sum() < 10:
            raise KinefuseError(f"rate window {k + 1} ({t0:g}–{t1:g} s) contains {int(sel.sum())} "
                                f"samples; need ≥ 10")
        meas.append(gyr[sel].mean(axis=0))
        known.append(w)
    # rest rows: static windows that do not overlap a known-rate window (a slow turntable
    # can look "still" to the detector)
    windows = [w for w in S.detect_static(t, acc, gyr, config, source=source)
               if not any(w.t0 <= b_ and a <= w.t1 for a, b_, *_ in rw)]
    rest = S.window_means(gyr, windows) if windows else None
    cal = fit_scale(np.array(meas), np.array(known), rest_means=rest)
    cal.n_samples = int(sum(((t >= a) & (t <= b_)).sum() for a, b_, *_ in rw))
    return cal
