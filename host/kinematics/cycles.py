"""Cycle detection, time normalisation (0–100 %), mean ± SD curves and range of motion.

Step-up (seed 001 §8.1): a cycle starts with the foot on the step and the knee flexed
(0 %), rises through an impulse (≈ 30 %), reaches full extension (≈ 50 %) and falls back to
flexion (100 %).  Full extensions are the clearest landmarks, so they are detected first
(minima of flexion with prominence ≥ ``min_prominence`` × the recording's flexion range and at
least ``min_period_s`` apart), and a cycle is the span between the midpoints of consecutive
extension intervals: cycle k runs from mid(ext[k−1], ext[k]) to mid(ext[k], ext[k+1]), which
places extension at ≈ 50 % as in the seed.  The first and last extensions use the neighbouring
interval mirrored, when the recording covers it.  This rule is documented in every report.

Flexion–extension (elbow, seed 002): cycles run between consecutive extension minima (the
first starts at motion onset when the movement starts from rest).

Cycles whose flexion curve deviates from the mean by more than ``max_rmse_deg`` (RMS over the
normalised cycle) are rejected and listed (seed 001 ``media_ciclos`` does the same with an
unstated threshold).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.signal import find_peaks

from kinefuse.host.errors import KinefuseError

N_POINTS = 101  # 0, 1, …, 100 %


@dataclass
class CycleSet:
    bounds: list                    # [(i0, i1)] sample indices, i1 exclusive
    curves: np.ndarray              # (n_cycles, 101, n_angles), kept cycles
    kept: list                      # indices into bounds of the kept cycles
    rejected: list = field(default_factory=list)   # [(index, rmse_deg)]
    durations_s: np.ndarray = field(default_factory=lambda: np.zeros(0))
    edge_dropped: int = 0           # cycles dropped at each end (drop_edge); ``bounds`` excludes them

    @property
    def n_detected(self) -> int:
        """Cycles detected, the dropped edge cycles included."""
        return len(self.bounds) + 2 * self.edge_dropped

    def number(self, k: int) -> int:
        """1-based number, among all detected cycles, of ``bounds[k]`` (reports name cycles so)."""
        return self.edge_dropped + k + 1

    @property
    def mean(self) -> np.ndarray:
        return self.curves.mean(axis=0)

    @property
    def sd(self) -> np.ndarray:
        """Sample standard deviation over the kept cycles; NaN (not defined) for one cycle."""
        if len(self.curves) < 2:
            return np.full_like(self.curves[0], np.nan)
        return self.curves.std(axis=0, ddof=1)

    def rom(self) -> dict:
        """Per-angle range of motion over cycles: max − min of each cycle, mean ± SD (NaN for one
        cycle), and the max/min of the mean curve."""
        mx = self.curves.max(axis=1)
        mn = self.curves.min(axis=1)
        r = mx - mn
        sd = r.std(axis=0, ddof=1) if len(r) > 1 else np.full(r.shape[1], np.nan)   # not defined
        return {"rom_mean": r.mean(axis=0), "rom_sd": sd,
                "max_mean": mx.mean(axis=0), "min_mean": mn.mean(axis=0),
                "mean_curve_max": self.mean.max(axis=0), "mean_curve_min": self.mean.min(axis=0)}


def extension_minima(t, flexion, *, min_prominence: float = 0.4, min_period_s: float = 1.0) -> np.ndarray:
    t = np.asarray(t, float)
    f = np.asarray(flexion, float)
    span = float(np.nanmax(f) - np.nanmin(f))
    if not span > 5.0:
        raise KinefuseError(f"flexion varies by only {span:.1f}°: no flexion–extension cycles to detect")
    dt = float(np.median(np.diff(t)))
    pk, _ = find_peaks(-f, prominence=min_prominence * span, distance=max(1, int(min_period_s / dt)))
    return pk


def step_up_bounds(t, flexion, **kw) -> list:
    ext = extension_minima(t, flexion, **kw)
    n = len(t)
    if len(ext) < 2:
        raise KinefuseError(f"found {len(ext)} full extension(s); need ≥ 2 step-up cycles")
    mids = [(ext[i] + ext[i + 1]) // 2 for i in range(len(ext) - 1)]
    starts = [ext[0] - (mids[0] - ext[0])] + mids
    ends = mids + [ext[-1] + (ext[-1] - mids[-1])]
    # a cycle includes its end sample, the next cycle's start (as between_minima_bounds): ending
    # one sample before it made every duration one sample short and 100 % not the next 0 %
    return [(int(s), int(e) + 1) for s, e in zip(starts, ends) if s >= 0 and e < n]


def between_minima_bounds(t, flexion, *, min_prominence: float = 0.4, min_period_s: float = 1.0,
                          onset_frac: float = 0.05) -> list:
    """Cycles between consecutive extension minima.  A movement that starts (or ends) from rest
    has no minimum there — the rest is a flat edge — so a complete flexion before the first
    (after the last) minimum adds a cycle that starts at motion onset (ends at rest), found
    where flexion leaves (returns to) the extension level ± ``onset_frac`` of the range."""
    f = np.asarray(flexion, float)
    ext = list(extension_minima(t, f, min_prominence=min_prominence, min_period_s=min_period_s))
    span = float(np.nanmax(f) - np.nanmin(f))
    if ext:
        i0 = ext[0]
        j = int(np.argmax(f[:i0])) if i0 > 0 else 0
        if i0 > 0 and f[j] - max(f[0], f[i0]) >= min_prominence * span:
            level = f[i0] + onset_frac * span
            below = np.flatnonzero(f[:j] <= level)
            if len(below):
                ext.insert(0, int(below[-1]))
        i1 = ext[-1]
        if i1 < len(f) - 1:
            j = i1 + int(np.argmax(f[i1:]))
            if f[j] - max(f[-1], f[i1]) >= min_prominence * span:
                level = f[i1] + onset_frac * span
                above = np.flatnonzero(f[j:] <= level)
                if len(above):
                    ext.append(int(j + above[0]))
    if len(ext) < 2:
        raise KinefuseError(f"found {len(ext)} extension minimum/minima; need ≥ 2 to form a cycle")
    return [(int(a), int(b) + 1) for a, b in zip(ext[:-1], ext[1:])]


def normalise(t, angles, bounds, *, drop_edge: int = 0, max_rmse_deg: float = 10.0,
              ref_col: int = 0) -> CycleSet:
    """Resample each cycle to 0–100 % (linear interpolation in time) and reject outliers."""
    t = np.asarray(t, float)
    a = np.asarray(angles, float)
    if a.ndim == 1:
        a = a[:, None]
    n_all = len(bounds)
    if drop_edge:
        bounds = bounds[drop_edge:len(bounds) - drop_edge]
    if not bounds:
        raise KinefuseError(f"no complete cycle left after dropping the edge cycles: {n_all} cycle(s) "
                            f"detected, dropping {drop_edge} at each end (--drop-edge-cycles) leaves none")
    curves, durs = [], []
    for i0, i1 in bounds:
        tt = t[i0:i1]
        x = np.linspace(tt[0], tt[-1], N_POINTS)
        curves.append(np.column_stack([np.interp(x, tt, a[i0:i1, j]) for j in range(a.shape[1])]))
        durs.append(tt[-1] - tt[0])
    C = np.array(curves)
    kept = list(range(len(C)))
    rejected = []
    # iterative: drop the worst cycle while it deviates too much from the mean curve of the kept
    # cycles (itself included, as the README says: "the mean flexion curve")
    while len(kept) > 2:
        m = C[kept, :, ref_col].mean(axis=0)
        err = np.sqrt(((C[kept, :, ref_col] - m) ** 2).mean(axis=1))
        worst = int(np.argmax(err))
        if err[worst] <= max_rmse_deg:
            break
        rejected.append((kept[worst], float(err[worst])))
        kept.pop(worst)
    return CycleSet(bounds=list(bounds), curves=C[kept], kept=kept, rejected=rejected,
                    durations_s=np.array(durs)[kept], edge_dropped=(n_all - len(bounds)) // 2)
