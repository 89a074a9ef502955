"""Magnetometer calibration: hard iron (offset b) and soft iron (matrix W), m_cal = W (raw − b).

``model="full"`` fits an ellipsoid (hard + soft iron, W symmetric positive definite);
``model="hard"`` fits a sphere (offset only, W = scalar × identity) like seed 001 §7.3, which
assumed no soft iron; ``model="auto"`` (the default) fits the ellipsoid only when the readings
cover enough of the direction sphere for it (see :data:`FULL_MIN_CELLS`), else the sphere.  An
ellipsoid that the data cannot determine — it flattens the calibrated directions onto a plane
or distorts beyond any real soft iron — is refused (``full``) or replaced by the sphere
(``auto``), never written.  ``field_norm`` (µT) scales W so that |m_cal| equals the local field
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
#: ``auto`` fits soft iron when the sphere-calibrated directions visit at least this fraction of
#: the 32 direction cells.  Measured on simulated readings (48 µT field, offsets up to 30 µT,
#: soft iron ±5 %, 0.4 µT noise, 3 seeds each): directions in a cap of half-angle 80° (59-62 %
#: of the cells) gave heading-relevant direction errors over the whole sphere of 1.0-1.2°
#: (ellipsoid) vs 1.4-4.2° (sphere); 75° (53-56 %) 2.5° vs 1.5-4.4°; 70° (50 %) 6.3-7.3° vs
#: 1.5-4.5°; below 65° the ellipsoid's offset ran to thousands of µT.  Readings that go round
#: the horizon (a band, 66 % of the cells and more) fit the ellipsoid to 0.1-0.2°.
FULL_MIN_CELLS = 0.6
#: an ellipsoid fit is not determined by the data when its calibrated directions lie within
#: this of a plane (smallest scatter eigenvalue) or its W has a condition number above
#: FULL_MAX_COND (real soft iron distorts by a few per cent: condition numbers near 1.1)
FULL_MAX_COND = 3.0
#: the geomagnetic field's magnitude at the surface (µT, WMM: about 22 µT in the South Atlantic
#: anomaly to 67 µT near the magnetic poles), with a margin; a --field-norm outside it is
#: most likely in the wrong unit (nT, gauss) and is warned about
FIELD_NORM_EARTH_UT = (20.0, 70.0)
#: raw readings (µT, median |m|): the Earth's field with hard iron of up to thousands of µT
#: (sensor ranges ±1300-4900 µT); outside this the readings are not in µT
RAW_NORM_UT = (5.0, 5000.0)


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


def calibrate(raw, *, model: str = "auto", field_norm: float | None = None,
              min_samples: int = 50) -> MagCalibration:
    """Fit hard (and soft) iron from magnetometer samples (N×3, µT) taken in many orientations.

    ``model``: "auto" (default), "full" or "hard" (module docstring); the result's ``model``
    says which was fitted ("full" or "hard")."""
    x = np.asarray(raw, dtype=float)
    if x.ndim != 2 or x.shape[1] != 3:
        raise KinefuseError("magnetometer data must be N×3 (µT)")
    x = x[np.all(np.isfinite(x), axis=1)]
    if len(x) < min_samples:
        raise KinefuseError(f"magnetometer calibration needs ≥ {min_samples} samples, got {len(x)}")
    if field_norm is not None and not (np.isfinite(field_norm) and field_norm > 0):
        # inf passed the old "> 0" test and ended in an internal error (NaN W, eigvalsh)
        raise KinefuseError(f"the local field norm must be a positive, finite number of µT, got "
                            f"{field_norm:g} (--field-norm)")
    med = float(np.median(np.linalg.norm(x, axis=1)))
    if not RAW_NORM_UT[0] <= med <= RAW_NORM_UT[1]:
        # readings in gauss looked like a unit that was not turned ("standard deviation 0.2 µT")
        guess = "gauss (1 G = 100 µT)" if med < RAW_NORM_UT[0] else "nT (1 µT = 1000 nT)"
        raise KinefuseError(
            f"magnetometer readings have a median |m| of {med:.4g} µT, outside anything the Earth's "
            f"field ({FIELD_NORM_EARTH_UT[0]:g}–{FIELD_NORM_EARTH_UT[1]:g} µT) plus a sensor's hard iron "
            f"gives ({RAW_NORM_UT[0]:g}–{RAW_NORM_UT[1]:g} µT): are they in {guess}?")
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
    if model not in ("auto", "full", "hard"):
        raise KinefuseError(f"unknown magnetometer model {model!r} (auto|full|hard)")
    warnings = []
    if field_norm is not None and not FIELD_NORM_EARTH_UT[0] <= field_norm <= FIELD_NORM_EARTH_UT[1]:
        warnings.append(
            f"field norm {field_norm:g} µT is outside the Earth's field ({FIELD_NORM_EARTH_UT[0]:g}–"
            f"{FIELD_NORM_EARTH_UT[1]:g} µT): is it in nT or gauss? (1 gauss = 100 µT); the calibrated "
            f"readings are scaled to it")
    fitted = "hard"
    b, r0 = _sphere_fit(x)
    r = r0 if field_norm is None else float(field_norm)
    W = np.eye(3) * (r / r0)
    m = apply_affine(x, W, b)
    cov = coverage(m)
    use_full = model == "full" or (model == "auto" and cov["cells_visited"] >= FULL_MIN_CELLS)
    few_cells = model == "auto" and not use_full
    if few_cells:
        warnings.append(
            f"soft iron not fitted: the readings visit {100 * cov['cells_visited']:.0f}% of the "
            f"direction sphere, the ellipsoid needs {100 * FULL_MIN_CELLS:.0f}% (offset-only "
            f"model used; turn the unit through more orientations, upside down included)")
    if use_full:
        e = ellipsoid.fit(x, radius=field_norm, kind="symmetric")
        m_full = apply_affine(x, e["M"], e["b"])
        cov_full = coverage(m_full)
        cond = float(np.linalg.cond(e["M"]))
        why = None
        if cov_full["min_eigenvalue"] < COVERAGE_MIN_EIG_REFUSE:
            why = (f"it flattens the calibrated field directions onto a plane (smallest spread "
                   f"{cov_full['min_eigenvalue']:.4f})")
        elif not cond <= FULL_MAX_COND:
            why = f"its soft-iron matrix distorts by a factor {cond:.1f} (real soft iron: ~1.1)"
        if why is None:
            W, b, r, m, cov, fitted = e["M"], e["b"], e["r"], m_full, cov_full, "full"
        elif model == "full":
            raise KinefuseError(
                f"the readings do not determine hard and soft iron: the ellipsoid fit of "
                f"{len(x)} samples ({100 * cov['cells_visited']:.0f}% of the direction sphere) "
                f"is degenerate, {why}; turn the unit through all orientations, or use --model "
                f"hard (offset only)")
        else:
            warnings.append(f"soft iron not fitted: the ellipsoid fit is degenerate, {why} "
                            f"(offset-only model used)")
    if cov["min_eigenvalue"] < COVERAGE_MIN_EIG_WARN:
        warnings.append(
            f"poor rotation coverage: field directions stay near a plane (smallest spread "
            f"{cov['min_eigenvalue']:.3f}, a full sphere gives 0.333); soft-iron terms and the "
            f"offset along the missing direction are uncertain")
    if cov["cells_visited"] < COVERAGE_CELLS_WARN and not few_cells:
        warnings.append(
            f"poor rotation coverage: only {100 * cov['cells_visited']:.0f}% of the direction "
            f"sphere visited; turn the unit through more orientations")
    sb, rb = _spread(x)
    sa, ra = _spread(m)
    res = np.linalg.norm(m, axis=1) - r
    return MagCalibration(W, b, float(r), fitted, len(x), sb, sa, rb, ra,
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
