"""Rigid-body motion with analytic angular velocity and linear acceleration.

Orientation signals return ``(q, ω, ω̇)``: q (N,4) sensor/body → earth (w,x,y,z), ω and ω̇ in
the *body* frame (rad/s, rad/s²).  Position signals return ``(p, v, a)`` in the earth frame
(ENU; m, m/s, m/s²).  Composition rules used (q = A ⊗ B, body rates):

    ω   = R_Bᵀ ω_A + ω_B
    ω̇   = R_Bᵀ ω̇_A − ω_B × (R_Bᵀ ω_A) + ω̇_B

and for a point fixed at r (body frame) on a body with origin o:

    p = o + R r,   v = v_o + ω_e × R r,   a = a_o + α_e × R r + ω_e × (ω_e × R r)

with ω_e = R ω, α_e = R ω̇ (earth frame).  Nothing is differentiated numerically.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import quat as Q
from .signals import ScalarSignal


# ---------------------------------------------------------------- orientation signals
class OrientationSignal:
    def __call__(self, t):  # pragma: no cover - abstract
        raise NotImplementedError

    def moving(self, t) -> np.ndarray:
        return np.zeros(np.shape(t), dtype=bool)


@dataclass(frozen=True)
class Fixed(OrientationSignal):
    q0: tuple = (1.0, 0.0, 0.0, 0.0)

    def __call__(self, t):
        t = np.asarray(t, dtype=float)
        q = np.broadcast_to(Q.as_quat(self.q0), t.shape + (4,)).copy()
        z = np.zeros(t.shape + (3,))
        return q, z, z.copy()


@dataclass(frozen=True)
class AxisRotation(OrientationSignal):
    """Rotation by angle(t) (rad) about a fixed unit axis (same axis in both frames)."""
    axis: tuple
    angle: ScalarSignal

    def __call__(self, t):
        n = np.asarray(self.axis, dtype=float)
        n = n / np.linalg.norm(n)
        f, d, dd = self.angle(t)
        return Q.from_axis_angle(n, f), d[..., None] * n, dd[..., None] * n

    def moving(self, t):
        return self.angle.moving(t)


class Compose(OrientationSignal):
    """q = parts[0] ⊗ parts[1] ⊗ … (left factors are outer/earth-side)."""

    def __init__(self, *parts: OrientationSignal):
        if not parts:
            raise ValueError("Compose needs at least one part")
        self.parts = parts

    def __call__(self, t):
        qa, wa, da = self.parts[0](t)
        for part in self.parts[1:]:
            qb, wb, db = part(t)
            wa_b = Q.rotate_inv(qb, wa)
            da = Q.rotate_inv(qb, da) - np.cross(wb, wa_b) + db
            wa = wa_b + wb
            qa = Q.mul(qa, qb)
        return qa, wa, da

    def moving(self, t):
        m = np.zeros(np.shape(t), dtype=bool)
        for p in self.parts:
            m |= p.moving(t)
        return m


# ---------------------------------------------------------------- position signals
class PositionSignal:
    def __call__(self, t):  # pragma: no cover - abstract
        raise NotImplementedError

    def moving(self, t) -> np.ndarray:
        return np.zeros(np.shape(t), dtype=bool)


@dataclass(frozen=True)
class FixedPoint(PositionSignal):
    p0: tuple = (0.0, 0.0, 0.0)

    def __call__(self, t):
        t = np.asarray(t, dtype=float)
        p = np.broadcast_to(np.asarray(self.p0, dtype=float), t.shape + (3,)).copy()
        z = np.zeros(t.shape + (3,))
        return p, z, z.copy()


class Path3(PositionSignal):
    """p = p0 + Σ_i direction_i · s_i(t) (earth frame, m)."""

    def __init__(self, p0, terms):
        self.p0 = np.asarray(p0, dtype=float)
        self.terms = [(np.asarray(d, dtype=float), s) for d, s in terms]

    def __call__(self, t):
        t = np.asarray(t, dtype=float)
        p = np.broadcast_to(self.p0, t.shape + (3,)).copy()
        v = np.zeros(t.shape + (3,))
        a = np.zeros(t.shape + (3,))
        for d, s in self.terms:
            f, df, ddf = s(t)
            p += f[..., None] * d
            v += df[..., None] * d
            a += ddf[..., None] * d
        return p, v, a

    def moving(self, t):
        m = np.zeros(np.shape(t), dtype=bool)
        for _, s in self.terms:
            m |= s.moving(t)
        return m


# ---------------------------------------------------------------- rigid bodies and points
@dataclass
class Kinematics:
    """Ground truth at sample instants t (s): q (N,4) body→earth; w, wd (N,3) body rad/s,
    rad/s²; p, v, a (N,3) earth-frame position m, velocity m/s, linear acceleration m/s²."""
    t: np.ndarray
    q: np.ndarray
    w: np.ndarray
    wd: np.ndarray
    p: np.ndarray
    v: np.ndarray
    a: np.ndarray
    moving: np.ndarray


class RigidMotion:
    """A body: orientation signal plus the trajectory of its origin."""

    def __init__(self, orientation: OrientationSignal, origin: PositionSignal | None = None):
        self.orientation = orientation
        self.origin = origin if origin is not None else FixedPoint()

    def point(self, r_body) -> "PointOnBody":
        return PointOnBody(self, r_body)

    def moving(self, t):
        return self.orientation.moving(t) | self.origin.moving(t)

    def evaluate(self, t, r_body=(0.0, 0.0, 0.0)) -> Kinematics:
        t = np.asarray(t, dtype=float)
        q, w, wd = self.orientation(t)
        p, v, a = _point_kinematics(q, w, wd, *self.origin(t), r_body)
        return Kinematics(t, q, w, wd, p, v, a, self.moving(t))


def _point_kinematics(q, w, wd, po, vo, ao, r_body):
    r = np.asarray(r_body, dtype=float)
    if not np.any(r):
        return po, vo, ao
    re = Q.rotate(q, np.broadcast_to(r, q.shape[:-1] + (3,)))
    we = Q.rotate(q, w)
    ae = Q.rotate(q, wd)
    return (po + re, vo + np.cross(we, re),
            ao + np.cross(ae, re) + np.cross(we, np.cross(we, re)))


class PointOnBody(PositionSignal):
    """Trajectory of the point fixed at r_body (m, body frame) on a rigid body."""

    def __init__(self, body: RigidMotion, r_body):
        self.body = body
        self.r = np.asarray(r_body, dtype=float)

    def __call__(self, t):
        q, w, wd = self.body.orientation(t)
        return _point_kinematics(q, w, wd, *self.body.origin(t), self.r)

    def moving(self, t):
        return self.body.moving(t)


class Track:
    """What one simulated sensor experiences: a body, where on it the sensor sits (r_body,
    m) and how it is turned on it (q_mount: sensor → body).  ``evaluate`` returns the sensor's
    own kinematics (q sensor → earth, ω in the sensor frame, a at the sensor's position)."""

    def __init__(self, body: RigidMotion, r_body=(0.0, 0.0, 0.0), q_mount=(1.0, 0.0, 0.0, 0.0)):
        self.body = body
        self.r = np.asarray(r_body, dtype=float)
        self.q_mount = Q.as_quat(q_mount)

    def evaluate(self, t) -> Kinematics:
        k = self.body.evaluate(t, self.r)
        qm = np.broadcast_to(self.q_mount, k.q.shape)
        return Kinematics(k.t, Q.mul(k.q, qm), Q.rotate_inv(qm, k.w), Q.rotate_inv(qm, k.wd),
                          k.p, k.v, k.a, k.moving)
