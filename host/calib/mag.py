"""Magnetometer calibration: hard iron (offset b) and soft iron (matrix W), m_cal = W (raw − b).

``model="full"`` fits an ellipsoid (hard + soft iron, W symmetric positive definite);
``model="hard"`` fits a sphere (offset only, W = scalar × identity) like seed 001 §7.3, which
assumed no soft iron.  ``field_norm`` (µT) scales W so that |m_cal| equals the local field
(seed 001 used 22.6 µT for Montevideo — make it configurable, there is no default place);
without it W keeps the volume (det W = 1) and |m_cal| is the fitted mean radius.

Quality figures reported with every fit:

* norm spread before/after: standard deviation of |m| (µT) and the relative spread
  std/mean (scale-free; its ratio before/after is the *spread reduction*);
* rotation coverage: eigenvalues of the scatter matrix E[u uᵀ] of the calibrated field
  directions u (1/3 each for a full sphere; → 0 when the directions stay in a plane) and the
  fraction of 32 equal-area direction cells visited.  Poor coverage → warnings; planar data →
  refusal, because the offset along the plane normal is then not observable; so is data that
  hardly changes (the unit was not turned: only noise, whose directions look isotropic).

Seed 001's gating is available as :func:`gate_norm`: samples whose calibrated norm leaves
±tol (0.5 µT in the seed) of the mean norm are replaced by the previous kept sample.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import least_squares

from kinefuse.host.calib import ellipsoid
from kinefuse.host.calib.affine import apply_affine
from kinefuse.host.errors import KinefuseError

#: thresholds for the coverage warnings / refusal
COVERAGE_MIN_EIG_WARN = 0.10
COVERAGE_MIN_EIG_REFUSE = 0.01
COVERAGE_CELLS_WARN = 0.5
#: refusal of readings that do not move (µT, largest standard deviation of the raw readings):
#: turning a unit through all orientations spreads them by about |B|/√3 per axis (≥ 12 µT
#: anywhere on Earth, |B| ≥ 22 µT), a still unit only by its noise (≲ 1 µT)
MOVEMENT_MIN_STD_UT = 2.0


@dataclass
class MagCalibration:
    W: np.ndarray
    b: np.ndarray                   # µT
    field_norm: float               # µT, |m_cal| the fit aims at
    model: str
    n_samples: int
    norm_std_before: float          # µT
    norm_std_after: float           # µT
    rel_spread_before: float        # std/mean
    rel_spread_after: float
    residual_rms: float             # µT, of |m_cal| − field_norm
    coverage: dict = field(default_factory=dict)
    warnings: list = field(default_factory=list)

    @property
    def spread_reduction(self) -> float:
        return self.rel_spread_before / self.rel_spread_after if self.rel_spread_after > 0 else float("inf")

    def apply(self, raw) -> np.ndarray:
        return apply_affine(raw, self.W, self.b)

    def to_json(self) -> dict:
        return {"W": self.W.tolist(), "bias": self.b.tolist(), "units": "uT",
                "model": self.model, "field_norm": self.field_norm, "n_samples": self.n_samples,
                "norm_std_before": self.norm_std_before, "norm_std_after": self.norm_std_after,
                "rel_spread_before": self.rel_spread_before,
                "rel_spread_after": self.rel_spread_after,
                "spread_reduction": self.spread_reduction, "residual_rms": self.residual_rms,
                "coverage": self.coverage, "warnings": list(self.warnings)}


def _fib_cells(n: int = 32) -> np.ndarray:
    k = np.arange(n) + 0.5
    z = 1.0 - 2.0 * k / n
    phi = np.pi * (1.0 + 5.0**0.5) * k
    r = np.sqrt(1.0 - z * z)
    return np.column_stack([r * np.cos(phi), r * np.sin(phi), z])


_CELLS = _fib_cells()


def coverage(directions) -> dict:
    """Coverage statistics of unit direction vectors (N×3)."""
    u = np.asarray(directions, dtype=float)
    u = u / np.maximum(np.linalg.norm(u, axis=1, keepdims=True), 1e-300)
    lam = np.linalg.eigvalsh(u.T @ u / len(u))
    cell = np.argmax(u @ _CELLS.T, axis=1)
    frac = len(np.unique(cell)) / len(_CELLS)
    return {"scatter_eigenvalues": lam.tolist(), "min_eigenvalue": float(lam[0]),
            "cells_visited": float(frac)}


def _sphere_fit(x: np.ndarray) -> tuple[np.ndarray, float]:
    A = np.column_stack([2 * x, np.ones(len(x))])
    y = (x * x).sum(axis=1)
    p, *_ = np.linalg.lstsq(A, y, rcond=None)
    b = p[:3]
    r2 = p[3] + b @ b
    if not r2 > 0:
        raise KinefuseError("sphere fit failed (data do not surround a centre)")

    def resid(q):
        return np.linalg.norm(x - q[:3], axis=1) - q[3]

    sol = least_squares(resid, np.concatenate([b, [np.sqrt(r2)]]), method="lm")
    return sol.x[:3], float(sol.x[3])


def _spread(m: np.ndarray) -> tuple[float, float]:
    n = np.linalg.norm(m, axis=1)
    return float(n.std()), float(n.std() / n.mean())


def calibrate(raw, *, model: str = "full", field_norm: float | None = None,
              min_samples: int = 50) -> MagCalibration:
    """Fit hard (and soft) iron from magnetometer samples (N×3, µT) taken in many orientations."""
    x = np.asarray(raw, dtype=float)
    if x.ndim != 2 or x.shape[1] != 3:
        raise KinefuseError("magnetometer data must be N×3 (µT)")
    x = x[np.all(np.isfinite(x), axis=1)]
    if len(x) < min_samples:
        raise KinefuseError(f"magnetometer calibration needs ≥ {min_samples} samples, got {len(x)}")
    if field_norm is not None and not field_norm > 0:
        raise KinefuseError("the local field norm must be positive (µT)")
    spread = float(np.sqrt(max(np.linalg.eigvalsh(np.cov(x.T))[-1], 0.0)))
    if spread < MOVEMENT_MIN_STD_UT:
        raise KinefuseError(
            f"magnetometer readings hardly change (largest standard deviation {spread:.2f} µT "
            f"< {MOVEMENT_MIN_STD_UT:g} µT): the unit was not turned; record a figure-eight "
            f"motion through all orientations")
    # coverage before fitting: directions about the data centroid (good enough to refuse planes)
    pre = coverage(x - x.mean(axis=0))
    if pre["min_eigenvalue"] < COVERAGE_MIN_EIG_REFUSE:
        raise KinefuseError(
            f"magnetometer data lie almost in a plane (smallest direction spread "
            f"{pre['min_eigenvalue']:.4f} < {COVERAGE_MIN_EIG_REFUSE}): the unit was turned "
            f"about one axis only; record a figure-eight motion through all orientations")
    if model == "full":
        e = ellipsoid.fit(x, radius=field_norm, kind="symmetric")
        W, b, r = e["M"], e["b"], e["r"]
    elif model == "hard":
        b, r0 = _sphere_fit(x)
        r = r0 if field_norm is None else float(field_norm)
        W = np.eye(3) * (r / r0)
    else:
        raise KinefuseError(f"unknown magnetometer model {model!r} (full|hard)")
    m = apply_affine(x, W, b)
    cov = coverage(m)
    warnings = []
    if cov["min_eigenvalue"] < COVERAGE_MIN_EIG_WARN:
        warnings.append(
            f"poor rotation coverage: field directions stay near a plane (smallest spread "
            f"{cov['min_eigenvalue']:.3f}, a full sphere gives 0.333); soft-iron terms and the "
            f"offset along the missing direction are uncertain")
    if cov["cells_visited"] < COVERAGE_CELLS_WARN:
        warnings.append(
            f"poor rotation coverage: only {100 * cov['cells_visited']:.0f}% of the direction "
            f"sphere visited; turn the unit through more orientations")
    sb, rb = _spread(x)
    sa, ra = _spread(m)
    res = np.linalg.norm(m, axis=1) - r
    return MagCalibration(W, b, float(r), model, len(x), sb, sa, rb, ra,
                          float(np.sqrt(np.mean(res**2))), cov, warnings)


def gate_norm(m_cal, tol: float = 0.5) -> tuple[np.ndarray, np.ndarray]:
    """Seed 001 gating: keep samples with | |m| − mean|m| | ≤ tol (µT); others are replaced
    by the previous kept sample (leading rejected samples by the first kept one).

    Returns (gated copy, boolean mask of kept samples).
    """
    if not (np.isfinite(tol) and tol > 0):
        raise KinefuseError(f"the magnetometer gate must be a positive number of µT, got {tol:g} "
                            f"(--gate, --mag-gate)")
    m = np.array(m_cal, dtype=float, copy=True)
    n = np.linalg.norm(m, axis=1)
    keep = np.abs(n - n.mean()) <= tol
    if not keep.any():
        raise KinefuseError(f"no magnetometer sample is within ±{tol} µT of the mean norm")
    idx = np.where(keep, np.arange(len(m)), -1)
    idx = np.maximum.accumulate(idx)
    idx[idx < 0] = np.argmax(keep)
    return m[idx], keep
