"""The published BROAD orientation-error metric (Laidig et al., Data 2021, doi:10.3390/data6070072).

Quaternions are (w, x, y, z), Hamilton product, rotating sensor coordinates into the earth frame
(East-North-Up for BROAD).  For an estimate q_est and the optical reference q_ref:

* error quaternion in the earth frame  e = q_est ⊗ q_ref⁻¹  (both normalised)
* total       = 2·acos|e_w|
* heading     = 2·atan(|e_z / e_w|)          (rotation about the vertical earth axis)
* inclination = 2·acos(√(e_w² + e_z²))        (the remaining tilt)

A trial's score is the RMSE of each error over the samples with ``movement`` set, skipping samples
whose reference is NaN (markers lost); all results in degrees.  A group's score is the mean of its
trials' RMSEs.  A NaN *estimate* is not skipped: it makes the score NaN, so a broken filter cannot
look good.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Iterable, Mapping

import numpy as np

KINDS = ("total", "heading", "inclination")


def quat_mul(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Hamilton product a ⊗ b of (..., 4) arrays in w, x, y, z order."""
    a = np.asarray(a, dtype=np.float64)
    b = np.asarray(b, dtype=np.float64)
    aw, ax, ay, az = np.moveaxis(a, -1, 0)
    bw, bx, by, bz = np.moveaxis(b, -1, 0)
    return np.stack([aw * bw - ax * bx - ay * by - az * bz,
                     aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw], axis=-1)


def quat_conj(q: np.ndarray) -> np.ndarray:
    """Conjugate (= inverse for unit quaternions) of (..., 4) w, x, y, z quaternions."""
    q = np.asarray(q, dtype=np.float64)
    return q * np.array([1.0, -1.0, -1.0, -1.0])


def quat_normalise(q: np.ndarray) -> np.ndarray:
    q = np.asarray(q, dtype=np.float64)
    return q / np.linalg.norm(q, axis=-1, keepdims=True)


@dataclass(frozen=True)
class ErrorSeries:
    """Per-sample errors in degrees, NaN where the reference is NaN."""

    total: np.ndarray
    heading: np.ndarray
    inclination: np.ndarray

    def as_dict(self) -> dict[str, np.ndarray]:
        return {"total": self.total, "heading": self.heading, "inclination": self.inclination}


def error_series(q_est: np.ndarray, q_ref: np.ndarray) -> ErrorSeries:
    """Total, heading and inclination error (degrees) of every sample."""
    q_est = np.asarray(q_est, dtype=np.float64)
    q_ref = np.asarray(q_ref, dtype=np.float64)
    if q_est.shape != q_ref.shape or q_est.ndim != 2 or q_est.shape[1] != 4:
        raise ValueError(f"estimate has shape {q_est.shape}, reference {q_ref.shape}; "
                         f"both must be (N, 4) w, x, y, z")
    with np.errstate(invalid="ignore", divide="ignore"):
        e = quat_mul(quat_normalise(q_est), quat_conj(quat_normalise(q_ref)))
        ew, ez = np.abs(e[:, 0]), np.abs(e[:, 3])
        total = 2.0 * np.arccos(np.minimum(ew, 1.0))
        # atan(|e_z/e_w|) written as atan2 so that e_w = 0 (a 180° error) is defined
        heading = 2.0 * np.arctan2(ez, ew)
        inclination = 2.0 * np.arccos(np.minimum(np.sqrt(ew * ew + ez * ez), 1.0))
    return ErrorSeries(np.degrees(total), np.degrees(heading), np.degrees(inclination))


def scored_mask(q_ref: np.ndarray, movement: np.ndarray) -> np.ndarray:
    """Samples the metric uses: movement phase and a valid (non-NaN) reference."""
    return np.asarray(movement, dtype=bool) & ~np.isnan(np.asarray(q_ref)).any(axis=1)


def rmse(values: np.ndarray, mask: np.ndarray) -> float:
    """Root mean square of ``values[mask]``; NaN if no sample is selected or a value is NaN."""
    v = np.asarray(values, dtype=np.float64)[np.asarray(mask, dtype=bool)]
    if v.size == 0:
        return float("nan")
    return float(np.sqrt(np.mean(v * v)))


def score(q_est: np.ndarray, q_ref: np.ndarray, movement: np.ndarray) -> dict[str, float]:
    """BROAD RMSEs in degrees: {"total", "heading", "inclination"}."""
    series = error_series(q_est, q_ref)
    mask = scored_mask(q_ref, movement)
    return {k: rmse(v, mask) for k, v in series.as_dict().items()}


def score_trial(q_est: np.ndarray, trial) -> dict[str, float]:
    """:func:`score` of an estimate against a :class:`kinefuse.host.broad.Trial`."""
    return score(q_est, trial.quat_ref, trial.movement)


def mean_score(scores: Iterable[Mapping[str, float]]) -> dict[str, float]:
    """Mean over trials of each error kind (NaN if the list is empty or holds a NaN)."""
    scores = list(scores)
    if not scores:
        return {k: float("nan") for k in KINDS}
    return {k: float(np.mean([s[k] for s in scores])) for k in KINDS}


def group_scores(scores: Mapping[str, Mapping[str, float]],
                 groups: Mapping[str, str | None]) -> dict[str, dict[str, float]]:
    """Mean score of each group; ``groups`` maps trial name to its group (None = ungrouped)."""
    by_group: dict[str, list] = {}
    for name, s in scores.items():
        g = groups.get(name)
        if g is not None:
            by_group.setdefault(g, []).append(s)
    return {g: mean_score(v) for g, v in by_group.items()}
