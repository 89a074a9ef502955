"""Quaternion and Euler-angle helpers (numpy, vectorised over leading axes).

Conventions used throughout ``kinefuse.host.kinematics``:

* quaternions are ``(w, x, y, z)``, Hamilton product, unit norm;
* an orientation quaternion ``q_AB`` maps coordinates in frame B to frame A:
  ``v_A = q_AB ⊗ (0, v_B) ⊗ q_AB*``; its matrix ``R_AB = to_matrix(q_AB)`` satisfies
  ``v_A = R_AB @ v_B`` and its columns are B's axes written in A;
* composition: ``q_AC = q_AB ⊗ q_BC``;
* Euler decompositions are *intrinsic* Tait–Bryan sequences named by the order in which the
  rotations are applied: ``"XYZ"`` means X, then Y′, then Z″, i.e. ``R = Rx(a) Ry(b) Rz(c)``.
  Extrinsic sequences are the reversed intrinsic ones (extrinsic x-y-z == intrinsic Z-Y′-X″).
"""
from __future__ import annotations

import numpy as np

_AXES = {"X": 0, "Y": 1, "Z": 2}


def as_quat(q) -> np.ndarray:
    q = np.asarray(q, dtype=float)
    if q.shape[-1] != 4:
        raise ValueError(f"quaternions must have 4 components (w,x,y,z); got shape {q.shape}")
    return q


def normalize(q) -> np.ndarray:
    q = as_quat(q)
    n = np.linalg.norm(q, axis=-1, keepdims=True)
    if np.any(n == 0) or not np.all(np.isfinite(n)):
        raise ValueError("cannot normalise a zero or non-finite quaternion")
    return q / n


def conj(q) -> np.ndarray:
    q = as_quat(q)
    return q * np.array([1.0, -1.0, -1.0, -1.0])


def mul(p, q) -> np.ndarray:
    """Hamilton product p ⊗ q (broadcasts over leading axes)."""
    p = as_quat(p)
    q = as_quat(q)
    pw, px, py, pz = np.moveaxis(p, -1, 0)
    qw, qx, qy, qz = np.moveaxis(q, -1, 0)
    return np.stack([
        pw * qw - px * qx - py * qy - pz * qz,
        pw * qx + px * qw + py * qz - pz * qy,
        pw * qy - px * qz + py * qw + pz * qx,
        pw * qz + px * qy - py * qx + pz * qw,
    ], axis=-1)


def rotate(q, v) -> np.ndarray:
    """Rotate vectors ``v`` (…×3) by ``q``: returns q ⊗ (0,v) ⊗ q* (B coordinates → A)."""
    return np.einsum("...ij,...j->...i", to_matrix(q), np.asarray(v, dtype=float))


def identity(n: int | None = None) -> np.ndarray:
    if n is None:
        return np.array([1.0, 0.0, 0.0, 0.0])
    out = np.zeros((n, 4))
    out[:, 0] = 1.0
    return out


def from_axis_angle(axis, angle) -> np.ndarray:
    """Rotation of ``angle`` rad about ``axis`` (right-hand rule); axis need not be unit."""
    axis = np.asarray(axis, dtype=float)
    if isinstance(axis, np.ndarray) and axis.ndim == 0:
        raise ValueError("axis must be a 3-vector")
    n = np.linalg.norm(axis, axis=-1, keepdims=True)
    if np.any(n == 0):
        raise ValueError("rotation axis must be non-zero")
    angle = np.asarray(angle, dtype=float)[..., None]
    half = 0.5 * angle
    return np.concatenate([np.cos(half) * np.ones_like(n), np.sin(half) * axis / n], axis=-1)


def elementary(axis: str, angle) -> np.ndarray:
    """Rotation about a coordinate axis ``"X"``, ``"Y"`` or ``"Z"`` by ``angle`` rad."""
    e = np.zeros(3)
    e[_AXES[axis.upper()]] = 1.0
    angle = np.asarray(angle, dtype=float)
    return from_axis_angle(np.broadcast_to(e, angle.shape + (3,)), angle)


def from_rotvec(rv) -> np.ndarray:
    rv = np.asarray(rv, dtype=float)
    ang = np.linalg.norm(rv, axis=-1, keepdims=True)
    half = 0.5 * ang
    # sin(half)/ang -> 0.5 for tiny angles (series keeps it exact to double precision)
    with np.errstate(invalid="ignore", divide="ignore"):
        k = np.where(ang > 1e-8, np.sin(half) / np.where(ang > 0, ang, 1.0), 0.5 - ang**2 / 48.0)
    return np.concatenate([np.cos(half), k * rv], axis=-1)


def to_rotvec(q) -> np.ndarray:
    q = normalize(q)
    q = np.where(q[..., :1] < 0, -q, q)  # shortest rotation
    s = np.linalg.norm(q[..., 1:], axis=-1, keepdims=True)
    ang = 2.0 * np.arctan2(s, q[..., :1])
    with np.errstate(invalid="ignore", divide="ignore"):
        k = np.where(s > 1e-12, ang / np.where(s > 0, s, 1.0), 2.0)
    return k * q[..., 1:]


def angle_between(p, q) -> np.ndarray:
    """Rotation angle (rad) of p* ⊗ q, in [0, π]."""
    d = np.abs(np.sum(normalize(p) * normalize(q), axis=-1))
    return 2.0 * np.arccos(np.clip(d, 0.0, 1.0))


def to_matrix(q) -> np.ndarray:
    """Rotation matrix R with v_A = R v_B for q = q_AB (standard, passive-free convention)."""
    w, x, y, z = np.moveaxis(normalize(q), -1, 0)
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
    ], -2)


def from_matrix(R, convention: str = "standard") -> np.ndarray:
    """Quaternion of a rotation matrix (Shepperd's method, w ≥ 0).

    ``convention="standard"`` returns q with ``to_matrix(q) == R``.  ``convention="madgwick"``
    returns what Madgwick's MATLAB ``rotMat2quatern`` returns, which is the *conjugate*
    (his ``quatern2rotMat`` builds the transpose of the standard matrix).  Seed 001's knee
    calibration (eqs. 6.1–6.3) only zeroes the knee at the calibration posture with the
    latter; see :func:`kinefuse.host.kinematics.joint.seed001_knee_quaternion`.
    """
    R = np.asarray(R, dtype=float)
    if R.shape[-2:] != (3, 3):
        raise ValueError(f"rotation matrices must be 3×3; got shape {R.shape}")
    m = R
    tr = m[..., 0, 0] + m[..., 1, 1] + m[..., 2, 2]
    cand = np.stack([tr, m[..., 0, 0], m[..., 1, 1], m[..., 2, 2]], -1)
    k = np.argmax(cand, axis=-1)
    q = np.empty(R.shape[:-2] + (4,))
    # four branches, chosen per element for numerical stability
    for branch in range(4):
        sel = k == branch
        if not np.any(sel):
            continue
        r = m[sel]
        if branch == 0:
            s = 2.0 * np.sqrt(1.0 + r[:, 0, 0] + r[:, 1, 1] + r[:, 2, 2])
            qq = np.stack([0.25 * s, (r[:, 2, 1] - r[:, 1, 2]) / s,
                           (r[:, 0, 2] - r[:, 2, 0]) / s, (r[:, 1, 0] - r[:, 0, 1]) / s], -1)
        elif branch == 1:
            s = 2.0 * np.sqrt(1.0 + r[:, 0, 0] - r[:, 1, 1] - r[:, 2, 2])
            qq = np.stack([(r[:, 2, 1] - r[:, 1, 2]) / s, 0.25 * s,
                           (r[:, 0, 1] + r[:, 1, 0]) / s, (r[:, 0, 2] + r[:, 2, 0]) / s], -1)
        elif branch == 2:
            s = 2.0 * np.sqrt(1.0 + r[:, 1, 1] - r[:, 0, 0] - r[:, 2, 2])
            qq = np.stack([(r[:, 0, 2] - r[:, 2, 0]) / s, (r[:, 0, 1] + r[:, 1, 0]) / s,
                           0.25 * s, (r[:, 1, 2] + r[:, 2, 1]) / s], -1)
        else:
            s = 2.0 * np.sqrt(1.0 + r[:, 2, 2] - r[:, 0, 0] - r[:, 1, 1])
            qq = np.stack([(r[:, 1, 0] - r[:, 0, 1]) / s, (r[:, 0, 2] + r[:, 2, 0]) / s,
                           (r[:, 1, 2] + r[:, 2, 1]) / s, 0.25 * s], -1)
        q[sel] = qq
    q = np.where(q[..., :1] < 0, -q, q)
    q = normalize(q)
    if convention == "standard":
        return q
    if convention == "madgwick":
        return conj(q)
    raise ValueError(f"unknown matrix-to-quaternion convention {convention!r} (standard|madgwick)")


def _parse_seq(seq: str) -> tuple[int, int, int]:
    s = seq.upper().replace("'", "").replace("′", "").replace("″", "").replace("-", "")
    if len(s) != 3 or set(s) - set("XYZ") or len(set(s)) != 3:
        raise ValueError(f"Euler sequence must be a Tait–Bryan permutation of XYZ, got {seq!r}")
    return _AXES[s[0]], _AXES[s[1]], _AXES[s[2]]


def to_euler(q, seq: str) -> np.ndarray:
    """Intrinsic Tait–Bryan angles (rad) ``(a, b, c)`` with ``R = R_i(a) R_j(b) R_k(c)``.

    ``seq`` names the axes in application order, e.g. ``"XYZ"`` (X–Y′–Z″, seed 002
    eqs. 2.7–2.9), ``"ZYX"`` (Z–Y′–X″, yaw–pitch–roll), ``"XZY"`` (Grood & Suntay knee JCS).
    The middle angle lies in [-90°, 90°]; the others in (-180°, 180°].
    """
    i, j, k = _parse_seq(seq)
    eps = 1.0 if (i, j, k) in ((0, 1, 2), (1, 2, 0), (2, 0, 1)) else -1.0
    R = to_matrix(q)
    sb = eps * R[..., i, k]
    b = np.arcsin(np.clip(sb, -1.0, 1.0))
    a = np.arctan2(-eps * R[..., j, k], R[..., k, k])
    c = np.arctan2(-eps * R[..., i, j], R[..., i, i])
    # gimbal lock (middle angle ±90°): only a ± c is defined; report c = 0 and take a from
    # column j, which is Ri(a) e_j = cos a e_j + ε sin a e_k when c = 0
    lock = np.abs(sb) > 1.0 - 1e-12
    if np.any(lock):
        a = np.where(lock, np.arctan2(eps * R[..., k, j], R[..., j, j]), a)
        c = np.where(lock, 0.0, c)
    return np.stack([a, b, c], axis=-1)


def from_euler(angles, seq: str) -> np.ndarray:
    """Inverse of :func:`to_euler`: q = q_i(a) ⊗ q_j(b) ⊗ q_k(c) (intrinsic)."""
    angles = np.asarray(angles, dtype=float)
    s = "XYZ"
    i, j, k = _parse_seq(seq)
    return mul(mul(elementary(s[i], angles[..., 0]), elementary(s[j], angles[..., 1])),
               elementary(s[k], angles[..., 2]))


def seed002_eq_2_7_to_2_9(q) -> np.ndarray:
    """Seed 002 eqs. 2.7–2.9 written out literally: (ψ_FE, ϑ_AA, ϕ_IE) in rad.

    These are the intrinsic X–Y′–Z″ angles (identical to ``to_euler(q, "XYZ")``); kept as a
    separate function so the equivalence is tested, not assumed.
    """
    q0, q1, q2, q3 = np.moveaxis(normalize(q), -1, 0)
    psi = np.arctan2(-2 * q2 * q3 + 2 * q0 * q1, q3**2 - q2**2 - q1**2 + q0**2)
    theta = np.arcsin(np.clip(2 * q1 * q3 + 2 * q0 * q2, -1.0, 1.0))
    phi = np.arctan2(-2 * q1 * q2 + 2 * q0 * q3, q1**2 + q0**2 - q3**2 - q2**2)
    return np.stack([psi, theta, phi], axis=-1)


def unwrap_sign(q) -> np.ndarray:
    """Flip signs so consecutive quaternions lie in the same hemisphere (for plotting/CSV)."""
    q = np.array(as_quat(q), dtype=float, copy=True)
    for n in range(1, len(q)):
        if np.dot(q[n], q[n - 1]) < 0:
            q[n] = -q[n]
    return q
