"""Accelerometer multi-position static calibration.

Three methods, all producing the affine map ``acc_cal = M · (raw − b)`` of
:func:`kinefuse.host.calib.affine.apply_affine` (``b = 0`` for the first two):

``ls`` — seed 002 eq. 3.5 / Annex G: ``R = Aᵀ · pinv(Bᵀ)`` with A the expected gravity vectors
    and B the mean raw vectors of the poses (one row each); 2-D protocol (3 poses, x–y only,
    R 2×2) and 3-D protocol (6 poses, R 3×3).  No offset and no orthogonality constraint
    (det 0.991 in the seed's worked example).

``procrustes`` — the closest *rotation* (orthogonal, det +1) mapping the raw vectors onto the
    targets (SVD / Kabsch).  Use it when only a mounting rotation is wanted.

``full`` — bias, per-axis scale and axis misalignment.  With known targets (one expected
    gravity vector per pose) a linear least-squares fit of ``target = M raw + c`` (12 unknowns,
    ≥ 6 poses); without targets a nonlinear fit of ``|M (raw − b)| = g`` with M upper
    triangular (9 unknowns, ≥ 9 poses; with 6–8 poses only a diagonal scale + bias model,
    6 unknowns, is identifiable).

Every method first runs :func:`check_excitation`, which refuses degenerate pose sets.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import least_squares

from kinefuse.host.calib import ellipsoid
from kinefuse.host.calib.affine import apply_affine
from kinefuse.host.errors import KinefuseError

G_STANDARD = 9.80665  # m/s², standard gravity (seed 002 mixes 9.8066, 9.80665 and 9.81)


def seed002_targets_2d(g: float = 9.8066) -> np.ndarray:
    """Seed 002 eq. 3.2: expected (g_x, g_y) of the three 2-D protocol poses (3×2)."""
    return np.array([[-g, 0.0], [0.0, -g], [0.0, g]])


def seed002_targets_3d(g: float = 9.8066) -> np.ndarray:
    """Seed 002 eq. 3.3: expected gravity of the six 3-D protocol poses (6×3)."""
    return np.array([[0, -g, 0], [0, g, 0], [0, 0, g], [0, 0, -g], [-g, 0, 0], [g, 0, 0]], float)


def seed002_annex_g_targets(g: float = G_STANDARD) -> np.ndarray:
    """Seed 002 Annex G §17.3: the target matrix actually used in the worked example."""
    return np.array([[-g, 0, 0], [0, -g, 0], [0, 0, -g], [0, 0, g], [g, 0, 0], [-g, 0, 0]], float)


#: Seed 002 Annex G worked example (Xsens DOT 7 on the UR3e; m/s²).
SEED002_WORKED_EXAMPLE = {
    "raw_poses": np.array([[7.6467, 6.1838, -0.2367],
                           [6.3236, -7.5506, -0.2625],
                           [0.0265, -0.0547, 9.6081],
                           [0.0657, -0.0071, -10.0659],
                           [-7.5156, -6.2212, -0.2421],
                           [7.6009, 6.2452, -0.2297]]),
    "targets": seed002_annex_g_targets(G_STANDARD),
    "published_R": np.array([[-0.7665, -0.6419, -0.0032],
                             [-0.6310, 0.7702, 0.0004],
                             [-0.0230, 0.0160, -0.9956]]),
    "published_det": 0.9910,
    "sample_raw": np.array([7.6443, 6.1871, -0.2229]),
    "sample_calibrated": np.array([-9.8304, -0.0584, 0.1447]),
}


@dataclass
class AccelCalibration:
    method: str                     # ls | procrustes | full
    M: np.ndarray                   # d×d (d = 2 for the seed 2-D protocol, else 3)
    b: np.ndarray | None            # offset in raw units, None for ls/procrustes
    residual_rms: float             # m/s² (per component, or of |acc| − g without targets)
    n_poses: int
    model: str = ""                 # e.g. "targets-linear", "norm-upper", "norm-diagonal"
    residuals: np.ndarray = field(default_factory=lambda: np.zeros(0))
    condition: float = float("nan")
    warnings: list = field(default_factory=list)

    @property
    def det(self) -> float:
        return float(np.linalg.det(self.M))

    def apply(self, raw) -> np.ndarray:
        b = np.zeros(self.M.shape[0]) if self.b is None else self.b
        return apply_affine(raw, self.M, b)

    def to_json(self) -> dict:
        """The CLI's exact JSON: R, bias (or null), det, residual_rms."""
        return {"R": self.M.tolist(), "bias": None if self.b is None else self.b.tolist(),
                "det": self.det, "residual_rms": self.residual_rms}


def _as_poses(raw, targets=None) -> tuple[np.ndarray, np.ndarray | None]:
    raw = np.asarray(raw, dtype=float)
    if raw.ndim != 2 or raw.shape[1] not in (2, 3):
        raise KinefuseError(f"poses must be an N×3 (or N×2 for the 2-D protocol) table of mean "
                            f"raw accelerations; got shape {raw.shape}")
    if not np.all(np.isfinite(raw)):
        raise KinefuseError("poses contain non-finite values")
    if targets is None:
        return raw, None
    targets = np.asarray(targets, dtype=float)
    if targets.shape != raw.shape:
        raise KinefuseError(f"targets must have the same shape as the poses "
                            f"({raw.shape[0]}×{raw.shape[1]}); got {targets.shape[0]}×"
                            f"{targets.shape[1] if targets.ndim > 1 else 1}")
    if not np.all(np.isfinite(targets)):
        raise KinefuseError("targets contain non-finite values")
    return raw, targets


def check_excitation(raw, targets=None, *, model: str = "rotation", max_cond: float = 1e3) -> float:
    """Refuse pose sets that cannot determine the requested model; returns a condition number.

    * ``rotation`` (ls / procrustes): the gravity directions must span the space (2-D: two
      non-parallel directions; 3-D: three non-coplanar ones).
    * ``affine`` (bias + full matrix from targets): additionally the design matrix
      [raw, 1] must have full rank — poses on both sides of each axis.
    * ``norm`` (bias + matrix from |acc| = g): directions must span 3-D and not crowd into
      one hemisphere; the Jacobian condition is checked after the fit.

    Why seed 002's own orthogonality check (§5.1.2, Annex F) cannot work: it regresses
    y = a_z · cos(θ) on [a_x, a_y, a_z, 1] for rotations about the sensor Z axis.  Its pose
    index θ only advances when a_z jumps by more than 0.3 m/s², which never happens in a
    rotation about Z, so θ stays 0 and the target y *is* the regressor a_z: least squares
    returns [s, u_x, u_y, u_z, o] = [1, 0, 0, 1, 0] for any sensor, orthogonal or not.  And
    rotations about one axis keep gravity in a plane, which cannot reveal the misalignment of
    the third axis anyway.  Here the poses must span all three directions.
    """
    raw = np.asarray(raw, dtype=float)
    d = raw.shape[1]
    _require_nonzero(raw, "pose", "measured acceleration")
    dirs = raw / np.linalg.norm(raw, axis=1, keepdims=True)
    if targets is not None:
        targets = np.asarray(targets, dtype=float)
        _require_nonzero(targets, "target", "expected gravity vector")
        tdirs = targets / np.linalg.norm(targets, axis=1, keepdims=True)
        sv_t = np.linalg.svd(tdirs, compute_uv=False)
        if len(sv_t) < d or not sv_t[-1] / sv_t[0] >= 1.0 / max_cond ** 0.5:
            raise KinefuseError(
                f"degenerate pose set: the target gravity directions span fewer than {d} "
                f"dimensions; use poses with gravity along every sensor axis")
    sv = np.linalg.svd(dirs, compute_uv=False)
    if len(raw) < d or not sv[-1] / sv[0] >= 1.0 / max_cond ** 0.5:
        plane = "a line" if d == 2 else "a plane (e.g. all poses are rotations about one axis)"
        raise KinefuseError(
            f"degenerate pose set: the measured gravity directions lie in {plane}; "
            f"add poses with gravity along the missing axis, both signs")
    cond = float(sv[0] / sv[-1])
    if model == "affine":
        D = np.column_stack([dirs, np.ones(len(raw))])
        svd = np.linalg.svd(D, compute_uv=False)
        if len(raw) < d + 1 or not svd[-1] / svd[0] >= 1.0 / max_cond:
            raise KinefuseError(
                "degenerate pose set for a bias fit: the poses do not surround the origin "
                "(each axis needs gravity in both directions, e.g. the 6 ± axis poses)")
        cond = float(svd[0] / svd[-1])
    elif model == "norm":
        S = dirs.T @ dirs / len(dirs)
        lam = np.linalg.eigvalsh(S)
        if lam[0] < 0.02:
            raise KinefuseError(
                f"degenerate pose set: gravity directions barely leave a plane (smallest "
                f"spread {lam[0]:.3f}, need ≥ 0.02); add poses with gravity along each axis")
        if np.linalg.norm(dirs.mean(axis=0)) > 0.75:
            raise KinefuseError(
                "degenerate pose set: all gravity directions crowd into one hemisphere, so the "
                "bias cannot be separated from the scale; add poses turned upside down")
    return cond


def _require_nonzero(v: np.ndarray, what: str, meaning: str, rel: float = 1e-3) -> None:
    """Every row must be a usable direction: not (near) zero.  A static pose measures gravity,
    so an all-zero row is a placeholder or a broken reading, and it would make every
    direction test 0/0 (NaN compares false: the check would pass)."""
    norms = np.linalg.norm(v, axis=1)
    big = float(norms.max()) if len(norms) else 0.0
    small = np.flatnonzero(~(norms > max(rel * big, 1e-9)))
    if len(small):
        k = int(small[0])
        many = f" ({len(small)} of {len(v)})" if len(small) > 1 else ""
        raise KinefuseError(f"degenerate pose set: {what} {k + 1} has a (near) zero {meaning} "
                            f"(|v| = {norms[k]:.3g}){many}; every static pose measures gravity")


def fit_ls(raw, targets) -> AccelCalibration:
    """Seed 002 least-squares matrix R = Aᵀ · pinv(Bᵀ) (A: targets, B: raw poses)."""
    raw, targets = _as_poses(raw, targets)
    cond = check_excitation(raw, targets, model="rotation")
    R = targets.T @ np.linalg.pinv(raw.T)
    res = raw @ R.T - targets
    return AccelCalibration("ls", R, None, float(np.sqrt(np.mean(res**2))), len(raw),
                            model="seed002-ls", residuals=res, condition=cond)


def fit_procrustes(raw, targets) -> AccelCalibration:
    """Orthogonal R (det +1) minimising Σ |R raw_i − target_i|² (Kabsch)."""
    raw, targets = _as_poses(raw, targets)
    cond = check_excitation(raw, targets, model="rotation")
    H = targets.T @ raw
    U, _, Vt = np.linalg.svd(H)
    D = np.eye(raw.shape[1])
    D[-1, -1] = np.sign(np.linalg.det(U @ Vt)) or 1.0
    R = U @ D @ Vt
    res = raw @ R.T - targets
    return AccelCalibration("procrustes", R, None, float(np.sqrt(np.mean(res**2))), len(raw),
                            model="rotation", residuals=res, condition=cond)


def fit_full_targets(raw, targets, *, min_poses: int = 6) -> AccelCalibration:
    """Linear least squares target = M raw + c on known targets; b = −M⁻¹ c."""
    raw, targets = _as_poses(raw, targets)
    if raw.shape[1] != 3:
        raise KinefuseError("the full model needs 3-axis poses")
    if len(raw) < min_poses:
        raise KinefuseError(f"the full model needs at least {min_poses} poses, got {len(raw)}")
    cond = check_excitation(raw, targets, model="affine")
    D = np.column_stack([raw, np.ones(len(raw))])
    P, *_ = np.linalg.lstsq(D, targets, rcond=None)
    M = P[:3].T
    c = P[3]
    if not abs(np.linalg.det(M)) > 1e-12 * max(float(np.abs(M).max()), 1e-300) ** 3:
        raise KinefuseError("degenerate pose set: the fitted matrix is singular (det 0); "
                            "use poses with gravity along each axis in both directions")
    b = -np.linalg.solve(M, c)
    res = apply_affine(raw, M, b) - targets
    return AccelCalibration("full", M, b, float(np.sqrt(np.mean(res**2))), len(raw),
                            model="targets-linear", residuals=res, condition=cond)


def fit_full_norm(raw, *, g: float = G_STANDARD, model: str = "auto",
                  max_cond: float = 1e4) -> AccelCalibration:
    """Nonlinear least squares on |M (raw − b)| = g (no targets needed).

    ``model``: ``"upper"`` (bias + scale + misalignment, M upper triangular, ≥ 9 poses),
    ``"diagonal"`` (bias + scale, ≥ 6 poses) or ``"auto"`` (upper if ≥ 9 poses).
    """
    raw, _ = _as_poses(raw)
    if raw.shape[1] != 3:
        raise KinefuseError("the full model needs 3-axis poses")
    n = len(raw)
    if model == "auto":
        model = "upper" if n >= 9 else "diagonal"
    need = 9 if model == "upper" else 6
    if n < need:
        raise KinefuseError(
            f"|acc| = g calibration with the {model} model needs at least {need} distinct "
            f"poses, got {n} (each pose gives one equation); record more orientations or "
            f"give the expected gravity vector of each pose (--targets)")
    cond0 = check_excitation(raw, model="norm")
    if model == "upper":
        e = ellipsoid.fit(raw, radius=g, kind="upper")
        M, b, cond = e["M"], e["b"], e["jac_cond"]
    elif model == "diagonal":
        def resid(p):
            return np.linalg.norm((raw - p[:3]) * p[3:], axis=1) - g
        p0 = np.concatenate([raw.mean(axis=0) * 0.0, np.full(3, g / np.mean(np.linalg.norm(raw, axis=1)))])
        sol = least_squares(resid, p0, method="lm", x_scale="jac")
        b, M = sol.x[:3], np.diag(sol.x[3:])
        J = sol.jac / np.maximum(np.linalg.norm(sol.jac, axis=0), 1e-300)
        sv = np.linalg.svd(J, compute_uv=False)
        cond = float(sv[0] / sv[-1]) if sv[-1] > 0 else float("inf")
    else:
        raise KinefuseError(f"unknown accelerometer model {model!r} (auto|upper|diagonal)")
    if not cond < max_cond:
        raise KinefuseError(
            f"poorly excited pose set: the fit is ill-conditioned (condition {cond:.3g} ≥ "
            f"{max_cond:g}); use poses with gravity along each axis in both directions")
    res = np.linalg.norm(apply_affine(raw, M, b), axis=1) - g
    warnings = []
    if n == need:
        # as many equations as unknowns: the fit passes through every pose, the residual is 0 by
        # construction (it was printed as a perfect "residual_rms = 0.00000 m/s²")
        warnings.append(f"{n} poses for the {need} unknowns of the {model} model: the fit is exactly "
                        f"determined, so its residual (0 by construction) says nothing about its quality; "
                        f"record more poses to check it")
    return AccelCalibration("full", M, b, float(np.sqrt(np.mean(res**2))), n,
                            model=f"norm-{model}", residuals=res, condition=max(cond, cond0),
                            warnings=warnings)


def fit(raw, targets=None, *, method: str = "ls", g: float = G_STANDARD) -> AccelCalibration:
    """Dispatch on ``method`` (ls | procrustes | full); ``full`` without targets uses norms."""
    if method == "ls":
        if targets is None:
            raise KinefuseError("method 'ls' needs the expected gravity vector of each pose (--targets)")
        return fit_ls(raw, targets)
    if method == "procrustes":
        if targets is None:
            raise KinefuseError("method 'procrustes' needs the expected gravity vector of each pose (--targets)")
        return fit_procrustes(raw, targets)
    if method == "full":
        return fit_full_targets(raw, targets) if targets is not None else fit_full_norm(raw, g=g)
    raise KinefuseError(f"unknown accelerometer method {method!r}; choose ls, procrustes or full")
