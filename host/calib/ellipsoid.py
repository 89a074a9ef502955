"""Ellipsoid fitting shared by the magnetometer and the norm-based accelerometer calibration.

Points x on a distorted sphere satisfy |M (x − b)| = r for some offset b, matrix M and
radius r.  Only MᵀM is observable from norms (any rotation Q gives |Q M (x − b)| = |M (x − b)|),
so a gauge must be chosen:

* ``"symmetric"`` — M symmetric positive definite (closest to "no rotation"; used for the
  magnetometer soft-iron matrix);
* ``"upper"`` — M upper triangular with positive diagonal (sensor x axis kept, y in the
  sensor x–y plane; the usual accelerometer scale/misalignment model).

The fit is algebraic (least-squares quadric, centred and scaled for conditioning) followed by
a Gauss–Newton refinement of the norm residuals |M (x − b)| − r (scipy ``least_squares``).
"""
from __future__ import annotations

import numpy as np
from scipy.optimize import least_squares

from kinefuse.host.errors import KinefuseError


def _sym_sqrt(A: np.ndarray) -> np.ndarray:
    lam, V = np.linalg.eigh(A)
    return (V * np.sqrt(lam)) @ V.T


def gauge(M: np.ndarray, kind: str) -> np.ndarray:
    """Matrix with the same MᵀM in the requested gauge (``symmetric`` or ``upper``)."""
    S = M.T @ M
    if kind == "symmetric":
        return _sym_sqrt(S)
    if kind == "upper":
        return np.linalg.cholesky(S).T
    raise ValueError(f"unknown gauge {kind!r}")


def algebraic_fit(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Least-squares quadric through points → (b, A) with (x − b)ᵀ A (x − b) = 1, A ≻ 0."""
    x = np.asarray(x, dtype=float)
    if x.ndim != 2 or x.shape[1] != 3:
        raise KinefuseError("ellipsoid fit needs N×3 points")
    if len(x) < 9:
        raise KinefuseError(f"ellipsoid fit needs at least 9 points, got {len(x)}")
    mu = x.mean(axis=0)
    s = float(np.sqrt(((x - mu) ** 2).sum(axis=1).mean()))
    if not s > 0:
        raise KinefuseError("all points are identical; nothing to fit")
    u = (x - mu) / s
    X, Y, Z = u.T
    D = np.column_stack([X * X, Y * Y, Z * Z, 2 * Y * Z, 2 * X * Z, 2 * X * Y, 2 * X, 2 * Y, 2 * Z])
    theta, *_ = np.linalg.lstsq(D, np.ones(len(u)), rcond=None)
    a, b_, c, f, g, h, p, q, r = theta
    A = np.array([[a, h, g], [h, b_, f], [g, f, c]])
    v = np.array([p, q, r])
    try:
        centre = -np.linalg.solve(A, v)
    except np.linalg.LinAlgError as exc:
        raise KinefuseError("data do not determine an ellipsoid (singular quadric)") from exc
    k = 1.0 + centre @ A @ centre
    An = A / k
    if not np.all(np.linalg.eigvalsh(An) > 0):
        raise KinefuseError("data do not lie on an ellipsoid (fit is not positive definite): "
                            "the orientations are too poorly spread")
    # back to original units: x = mu + s u
    return mu + s * centre, An / (s * s)


def fit(x: np.ndarray, *, radius: float | None = None, kind: str = "symmetric",
        refine: bool = True) -> dict:
    """Fit |M (x − b)| = r.  ``radius=None`` keeps the volume (det M = 1, r = mean radius).

    Returns ``{"M", "b", "r", "residual_rms", "jac_cond"}``; ``jac_cond`` is the condition
    number of the column-scaled Jacobian at the solution (large = poorly excited).
    """
    x = np.asarray(x, dtype=float)
    b0, A = algebraic_fit(x)
    # (x-b)^T A (x-b) = 1  ->  |sqrt(A)(x-b)| = 1 ; scale to the requested radius
    S = _sym_sqrt(A)
    if radius is None:
        r = float(np.linalg.det(S)) ** (-1.0 / 3.0)   # geometric-mean semi-axis
    else:
        r = float(radius)
    M0 = gauge(S * r, kind)

    idx = np.triu_indices(3) if kind == "upper" else np.triu_indices(3)

    def unpack(p):
        m = np.zeros((3, 3))
        m[idx] = p[3:9]
        if kind == "symmetric":
            m = m + np.triu(m, 1).T
        return p[:3], m

    def resid(p):
        b, m = unpack(p)
        return np.linalg.norm((x - b) @ m.T, axis=1) - r

    p0 = np.concatenate([b0, M0[idx]])
    if refine:
        sol = least_squares(resid, p0, method="lm", x_scale="jac")
        p = sol.x
        J = sol.jac
    else:
        p = p0
        J = None
    b, M = unpack(p)
    M = gauge(M, kind)  # restore the sign convention (positive diagonal / SPD)
    res = resid(np.concatenate([b, M[idx]]))
    if J is None:
        eps = 1e-6
        J = np.column_stack([(resid(p + eps * e) - resid(p - eps * e)) / (2 * eps)
                             for e in np.eye(len(p))])
    Js = J / np.maximum(np.linalg.norm(J, axis=0), 1e-300)
    sv = np.linalg.svd(Js, compute_uv=False)
    cond = float(sv[0] / sv[-1]) if sv[-1] > 0 else float("inf")
    if radius is None:
        # keep det M = 1 after refinement: rescale M and r together
        d = float(np.linalg.det(M)) ** (1.0 / 3.0)
        M = M / d
        r = r / d
    return {"M": M, "b": b, "r": r, "residual_rms": float(np.sqrt(np.mean(res**2))),
            "jac_cond": cond}
