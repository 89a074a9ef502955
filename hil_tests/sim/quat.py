"""Quaternion helpers for the simulator (float64, vectorised over a leading axis).

Convention everywhere in ``kinefuse.hil_tests.sim``: q = (w, x, y, z), Hamilton product,
q maps sensor (body) coordinates to earth coordinates: v_earth = q ⊗ v_body ⊗ q*, i.e.
v_earth = R(q) @ v_body.  Body angular velocity ω (rad/s, body frame) obeys q̇ = ½ q ⊗ (0, ω).
The earth frame is East-North-Up (z up), as in BROAD.
"""
from __future__ import annotations

import numpy as np


def mul(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Hamilton product p ⊗ q (broadcasting over leading axes)."""
    p = np.asarray(p, dtype=float)
    q = np.asarray(q, dtype=float)
    pw, px, py, pz = np.moveaxis(p, -1, 0)
    qw, qx, qy, qz = np.moveaxis(q, -1, 0)
    return np.stack([pw * qw - px * qx - py * qy - pz * qz,
                     pw * qx + px * qw + py * qz - pz * qy,
                     pw * qy - px * qz + py * qw + pz * qx,
                     pw * qz + px * qy - py * qx + pz * qw], axis=-1)


def chain(q0, dq: np.ndarray) -> np.ndarray:
    """q0 ⊗ dq[0], q0 ⊗ dq[0] ⊗ dq[1], … (all partial products, (N,4)): integrating increments.
    A sequential loop in plain floats (each product needs the previous one)."""
    w, x, y, z = (float(v) for v in q0)
    out = np.empty((len(dq), 4))
    for k, (b0, b1, b2, b3) in enumerate(np.asarray(dq, dtype=float).tolist()):
        w, x, y, z = (w * b0 - x * b1 - y * b2 - z * b3, w * b1 + x * b0 + y * b3 - z * b2,
                      w * b2 - x * b3 + y * b0 + z * b1, w * b3 + x * b2 - y * b1 + z * b0)
        out[k] = w, x, y, z
    return out


def conj(q: np.ndarray) -> np.ndarray:
    q = np.asarray(q, dtype=float)
    return q * np.array([1.0, -1.0, -1.0, -1.0])


def normalize(q: np.ndarray) -> np.ndarray:
    q = np.asarray(q, dtype=float)
    return q / np.linalg.norm(q, axis=-1, keepdims=True)


def from_axis_angle(axis, angle) -> np.ndarray:
    """Rotation by ``angle`` (rad, array) about the unit ``axis`` (3,)."""
    axis = np.asarray(axis, dtype=float)
    axis = axis / np.linalg.norm(axis)
    half = 0.5 * np.asarray(angle, dtype=float)[..., None]
    return np.concatenate([np.cos(half), np.sin(half) * axis], axis=-1)


def from_rotvec(v) -> np.ndarray:
    """Quaternion of a rotation vector (rad, (...,3)); exact for small angles too."""
    v = np.asarray(v, dtype=float)
    ang = np.linalg.norm(v, axis=-1, keepdims=True)
    half = 0.5 * ang
    # sin(half)/ang with its Taylor series near 0 (avoids 0/0)
    k = np.where(ang > 1e-8, np.sin(half) / np.where(ang > 1e-8, ang, 1.0), 0.5 - ang ** 2 / 48.0)
    return np.concatenate([np.cos(half), k * v], axis=-1)


def to_rotvec(q) -> np.ndarray:
    """Rotation vector (rad) of q, choosing the representative with w >= 0."""
    q = normalize(q)
    q = np.where(q[..., :1] < 0, -q, q)
    s = np.linalg.norm(q[..., 1:], axis=-1, keepdims=True)
    ang = 2.0 * np.arctan2(s, q[..., :1])
    k = np.where(s > 1e-12, ang / np.where(s > 1e-12, s, 1.0), 2.0)
    return k * q[..., 1:]


def angle(q) -> np.ndarray:
    """Rotation angle (rad, in [0, π]) of q."""
    q = np.asarray(q, dtype=float)
    return 2.0 * np.arctan2(np.linalg.norm(q[..., 1:], axis=-1), np.abs(q[..., 0]))


def to_matrix(q) -> np.ndarray:
    """Rotation matrix R(q) (..., 3, 3) with v_earth = R @ v_body."""
    w, x, y, z = np.moveaxis(normalize(q), -1, 0)
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
    ], -2)


def rotate(q, v) -> np.ndarray:
    """R(q) @ v (body → earth)."""
    return np.einsum("...ij,...j->...i", to_matrix(q), np.asarray(v, dtype=float))


def rotate_inv(q, v) -> np.ndarray:
    """R(q)ᵀ @ v (earth → body)."""
    return np.einsum("...ji,...j->...i", to_matrix(q), np.asarray(v, dtype=float))


def from_euler_zyx(yaw, pitch, roll) -> np.ndarray:
    """q = Rz(yaw) ⊗ Ry(pitch) ⊗ Rx(roll) (intrinsic Z-Y'-X'', rad)."""
    return mul(mul(from_axis_angle([0, 0, 1], yaw), from_axis_angle([0, 1, 0], pitch)),
               from_axis_angle([1, 0, 0], roll))


def from_euler_zyx_deg(angles_deg) -> np.ndarray:
    y, p, r = np.radians(np.asarray(angles_deg, dtype=float))
    return from_euler_zyx(y, p, r)


def as_quat(value) -> np.ndarray:
    """Normalised quaternion (4,) from a (w,x,y,z) sequence."""
    q = np.asarray(value, dtype=float).reshape(4)
    n = np.linalg.norm(q)
    if not np.isfinite(n) or n < 1e-9:
        raise ValueError("quaternion must be finite and non-zero")
    return q / n


def matrix_to_quat(m) -> np.ndarray:
    """Quaternion (w ≥ 0) of a proper rotation matrix (3, 3)."""
    m = np.asarray(m, dtype=float)
    tr = np.trace(m)
    if tr > 0:
        s = 2.0 * np.sqrt(tr + 1.0)
        q = [0.25 * s, (m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s]
    else:
        i = int(np.argmax(np.diag(m)))
        j, k = (i + 1) % 3, (i + 2) % 3
        s = 2.0 * np.sqrt(1.0 + m[i, i] - m[j, j] - m[k, k])
        q = np.empty(4)
        q[0] = (m[k, j] - m[j, k]) / s
        q[1 + i] = 0.25 * s
        q[1 + j] = (m[j, i] + m[i, j]) / s
        q[1 + k] = (m[k, i] + m[i, k]) / s
    q = np.asarray(q, dtype=float)
    return q if q[0] >= 0 else -q
