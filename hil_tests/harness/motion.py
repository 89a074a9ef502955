"""Exact synthetic IMU input for property checks: piecewise-constant body rates.

Sample k's gyroscope reading ω_k (rad/s, sensor frame) is the constant body rate over the
interval dt_k ending at sample k, so the true orientation is exactly
q_k = q_{k-1} ⊗ exp(ω_k dt_k / 2) (no discretisation error between truth and what a strapdown
step can know).  Accelerometer = R(q_k)ᵀ g e_z (specific force, +g up at rest, no linear
acceleration), magnetometer = R(q_k)ᵀ m_ENU in µT.  Earth frame East-North-Up; quaternions
(w, x, y, z) sensor → earth.
"""
from __future__ import annotations

import numpy as np

G = 9.81                                  # m/s²
FIELD_UT = 49.0                           # µT
DIP_DEG = 64.0                            # magnetic dip (field points down in the north)


def field_enu(heading_deg: float = 0.0, strength_ut: float = FIELD_UT, dip_deg: float = DIP_DEG) -> np.ndarray:
    """Earth field in ENU, µT; ``heading_deg`` turns magnetic north from +y towards −x
    (counter-clockwise seen from above)."""
    h = np.radians(heading_deg)
    d = np.radians(dip_deg)
    horiz = strength_ut * np.cos(d)
    return np.array([-horiz * np.sin(h), horiz * np.cos(h), -strength_ut * np.sin(d)])


def qmul(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    a, b = np.asarray(a, float), np.asarray(b, float)
    aw, ax, ay, az = np.moveaxis(a, -1, 0)
    bw, bx, by, bz = np.moveaxis(b, -1, 0)
    return np.stack([aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw], axis=-1)


def qconj(q: np.ndarray) -> np.ndarray:
    return np.asarray(q, float) * np.array([1.0, -1.0, -1.0, -1.0])


def qexp(rotvec: np.ndarray) -> np.ndarray:
    """Unit quaternion of a rotation vector (rad), (..., 3) -> (..., 4)."""
    v = np.asarray(rotvec, float)
    ang = np.linalg.norm(v, axis=-1, keepdims=True)
    half = 0.5 * ang
    s = np.where(ang > 1e-12, np.sin(half) / np.where(ang > 1e-12, ang, 1.0), 0.5)
    return np.concatenate([np.cos(half), v * s], axis=-1)


def qz(angle_rad: float) -> np.ndarray:
    """Rotation about the earth's vertical (z, ENU) by angle_rad (counter-clockwise from above)."""
    return np.array([np.cos(angle_rad / 2), 0.0, 0.0, np.sin(angle_rad / 2)])


def rotate_to_sensor(q: np.ndarray, v_earth: np.ndarray) -> np.ndarray:
    """R(q)ᵀ v for each q (N,4): an earth-frame vector in sensor coordinates."""
    q = np.asarray(q, float)
    v = np.broadcast_to(np.asarray(v_earth, float), q.shape[:-1] + (3,))
    qv = np.concatenate([np.zeros(q.shape[:-1] + (1,)), v], axis=-1)
    return qmul(qmul(qconj(q), qv), q)[..., 1:]


def synth(q0, omega: np.ndarray, dt, field=None, mag_valid=True, g: float = G):
    """(inputs, q_true): the 'imu' input record for body rates ``omega`` (N,3) rad/s."""
    omega = np.asarray(omega, float).reshape(-1, 3)
    n = len(omega)
    dt = np.broadcast_to(np.asarray(dt, float), (n,)).copy()
    q = np.zeros((n, 4))
    cur = np.asarray(q0, float) / np.linalg.norm(q0)
    steps = qexp(omega * dt[:, None]).tolist()
    moving = np.any(omega != 0.0, axis=1).tolist()
    w, x, y, z = cur.tolist()
    rows = [] if any(moving[1:]) else [(w, x, y, z)] * n
    for k in range(n if not rows else 0):          # plain floats: ~50x faster than numpy on 4-vectors
        if k > 0 and moving[k]:
            bw, bx, by, bz = steps[k]
            w, x, y, z = (w * bw - x * bx - y * by - z * bz, w * bx + x * bw + y * bz - z * by,
                          w * by - x * bz + y * bw + z * bx, w * bz + x * by - y * bx + z * bw)
            s = (w * w + x * x + y * y + z * z) ** -0.5
            w, x, y, z = w * s, x * s, y * s, z * s
        rows.append((w, x, y, z))
    q[:] = rows
    acc = rotate_to_sensor(q, [0.0, 0.0, g])
    f = field_enu() if field is None else np.asarray(field, float)
    mag = rotate_to_sensor(q, f)
    inputs = {"gyr": omega.copy(), "acc": acc, "mag": mag,
              "mag_valid": np.broadcast_to(np.asarray(mag_valid, bool), (n,)).copy(), "dt": dt}
    return inputs, q


def errors_deg(q_est: np.ndarray, q_ref: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(total, heading, inclination) errors in degrees of e = q_est ⊗ q_ref⁻¹ (BROAD metric)."""
    a = np.asarray(q_est, float)
    a = a / np.linalg.norm(a, axis=-1, keepdims=True)
    b = np.asarray(q_ref, float)
    b = b / np.linalg.norm(b, axis=-1, keepdims=True)
    e = qmul(a, qconj(b))
    w, z = np.abs(e[..., 0]), e[..., 3]
    total = np.degrees(2 * np.arccos(np.clip(w, 0.0, 1.0)))
    heading = np.degrees(2 * np.arctan2(np.abs(z), w))
    incl = np.degrees(2 * np.arccos(np.clip(np.sqrt(e[..., 0] ** 2 + z ** 2), 0.0, 1.0)))
    return total, heading, incl


def random_unit_quaternion(rng: np.random.Generator) -> np.ndarray:
    q = rng.normal(size=4)
    return q / np.linalg.norm(q)
