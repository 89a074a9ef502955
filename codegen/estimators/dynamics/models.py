"""The planar multibody models: position-level definitions only (see :mod:`.mbs`).

Frames and units: x horizontal, y vertical up, SI units (m, rad, kg, N, N·m); angles are
absolute, counter-clockwise positive, measured from the downward vertical, so a body whose
angle is θ points from its proximal to its distal point along u = (sin θ, −cos θ).

Parameters are read from the filter's parameter namespace ``p`` (attribute access), so the same
model serves the reference (floats), the generated code (Syms) and host tools (a
``SimpleNamespace`` of floats).
"""
from __future__ import annotations

from kinefuse.codegen.linalg import ZERO
from kinefuse.codegen.estimators.dynamics.ad import sincos


# ---------------------------------------------------------------------------------------------
# Double pendulum of seed 000 §3.3 / Annex A
# ---------------------------------------------------------------------------------------------

class Pendulum:
    """Two uniform bars of length L: bar 1 from point 0 (the free start of the chain) to
    point 1 (the revolute joint), bar 2 from point 1 to point 2, where a pin to the ground is cut
    and replaced by the reaction (Fx, Fy, T2) - the force plate of the full-body model.

    Natural coordinates q = [x0 y0 x1 y1 x2 y2]; independent z = [x0 y0 θ1 θ2] with
    x1 = x0 + L sin θ1, y1 = y0 − L cos θ1 (likewise for point 2), so R = dq/dz is seed eq. 3.57.
    Efforts T_e = [τ1 Fx Fy T2]: τ1 acts on bar 2 and −τ1 on bar 1 (conjugate to θ2 − θ1),
    (Fx, Fy) at point 2 (conjugate to x2, y2), T2 on bar 2 (conjugate to θ2): Bᵀ is seed eq.
    3.59.  With ``residual``, a base residual (Frx, Fry, Mr) acts on bar 1 at point 0
    (conjugate to x0, y0, θ1): Bᵀ gains the identity block of seed §3.3.1.

    Parameters used: m1, m2 (kg), L (m), g (m/s²).
    """

    coords = ("x0", "y0", "theta1", "theta2")
    coord_units = ("m", "m", "rad", "rad")

    def __init__(self, residual: bool = False):
        self.residual = residual
        self.efforts = ("tau1", "Fx", "Fy", "T2") + (("Frx", "Fry", "Mr") if residual else ())
        self.effort_units = ("N*m", "N", "N", "N*m") + (("N", "N", "N*m") if residual else ())

    n = 4

    @staticmethod
    def points(z, p):
        x0, y0, t1, t2 = z
        s1, c1 = sincos(t1)
        s2, c2 = sincos(t2)
        x1 = x0 + p.L * s1
        y1 = y0 - p.L * c1
        x2 = x1 + p.L * s2
        y2 = y1 - p.L * c2
        return [x0, y0, x1, y1, x2, y2]

    def phi(self, z, p):
        return self.points(z, p)

    @staticmethod
    def mbar(p):
        """Seed eq. 3.55: per bar m/6 [[2I, I], [I, 2I]] on its two points."""
        a1, b1 = p.m1 / 3.0, p.m1 / 6.0
        a2, b2 = p.m2 / 3.0, p.m2 / 6.0
        a12 = (p.m1 + p.m2) / 3.0
        Z = ZERO
        return [[a1, Z, b1, Z, Z, Z],
                [Z, a1, Z, b1, Z, Z],
                [b1, Z, a12, Z, b2, Z],
                [Z, b1, Z, a12, Z, b2],
                [Z, Z, b2, Z, a2, Z],
                [Z, Z, Z, b2, Z, a2]]

    @staticmethod
    def qbar(p):
        """Seed eq. 3.55: each bar's weight split between its two points."""
        return [ZERO, -(p.m1 * p.g) * 0.5, ZERO, -((p.m1 + p.m2) * p.g) * 0.5,
                ZERO, -(p.m2 * p.g) * 0.5]

    def conj(self, z, p):
        q = self.points(z, p)
        s = [z[3] - z[2], q[4], q[5], z[3]]
        if self.residual:
            s += [z[0], z[1], z[2]]
        return s


# marker positions in each bar's frame: (fraction of L along the bar from its proximal point,
# offset in m to the left of the bar's direction) - skin markers sit off the bone axis
PENDULUM_MARKERS = ((1, 0.25, 0.05), (1, 0.75, -0.05), (2, 0.25, 0.05), (2, 0.75, -0.05))


def pendulum_markers(z, p):
    """Marker coordinates [m1x m1y ... m4x m4y] (linear in the natural coordinates)."""
    q = Pendulum.points(z, p)
    out = []
    for bar, s, d in PENDULUM_MARKERS:
        px, py = q[2 * (bar - 1)], q[2 * (bar - 1) + 1]
        qx, qy = q[2 * bar], q[2 * bar + 1]
        ex, ey = qx - px, qy - py                  # L u
        k = d / p.L                                # offset along the left normal (−uy, ux)
        out.append(px + s * ex - k * ey)
        out.append(py + s * ey + k * ex)
    return out


# ---------------------------------------------------------------------------------------------
# Wearable leg: thigh and shank(+foot) in the sagittal plane, hip joint fixed
# ---------------------------------------------------------------------------------------------

class Leg:
    """Thigh (hip → knee) and shank with foot (knee → ankle) in the sagittal plane; the hip
    joint is fixed at the origin (a pelvis held by a gait trainer or a treadmill harness, a
    seated or lying exercise), walking direction +x.

    z = [θ1, θ2]: absolute thigh and shank angles from the downward vertical, counter-clockwise
    (hip flexion, leg swinging forward, is +θ1).  q = [xG1 yG1 θ1 xG2 yG2 θ2]: centre of mass
    and angle of each segment, M̄ = diag(m1, m1, I1, m2, m2, I2), Q̄ = gravity.
    Efforts T_e = [τ_hip, τ_knee] (+ [F_ax, F_ay] with the foot force sensor):
    τ_hip acts on the thigh from the pelvis (conjugate to θ1: + = flexing moment),
    τ_knee on the shank and −τ_knee on the thigh (conjugate to θ2 − θ1: + = knee extension
    moment, the shank rotating forward relative to the thigh), (F_ax, F_ay) an external force
    applied at the ankle (conjugate to the ankle's x, y).

    Parameters used: m1, m2 (kg), L1 (m, hip to knee), c1, c2 (m, CoM from the proximal
    joint), I1, I2 (kg·m², about the CoM), g (m/s²).
    """

    coords = ("theta1", "theta2")
    coord_units = ("rad", "rad")
    n = 2

    def __init__(self, foot: bool = False, L2: float = 0.43):
        self.foot = foot
        self.L2 = L2      # knee to ankle (m); only the ankle force uses it
        self.efforts = ("tau_hip", "tau_knee") + (("F_ax", "F_ay") if foot else ())
        self.effort_units = ("N*m", "N*m") + (("N", "N") if foot else ())

    def phi(self, z, p):
        t1, t2 = z
        s1, c1 = sincos(t1)
        s2, c2 = sincos(t2)
        kx, ky = p.L1 * s1, -(p.L1 * c1)
        return [p.c1 * s1, -(p.c1 * c1), t1, kx + p.c2 * s2, ky - p.c2 * c2, t2]

    @staticmethod
    def mbar(p):
        Z = ZERO
        return [[p.m1, Z, Z, Z, Z, Z], [Z, p.m1, Z, Z, Z, Z], [Z, Z, p.I1, Z, Z, Z],
                [Z, Z, Z, p.m2, Z, Z], [Z, Z, Z, Z, p.m2, Z], [Z, Z, Z, Z, Z, p.I2]]

    @staticmethod
    def qbar(p):
        return [ZERO, -(p.m1 * p.g), ZERO, ZERO, -(p.m2 * p.g), ZERO]

    def conj(self, z, p):
        s = [z[0], z[1] - z[0]]
        if self.foot:
            t1, t2 = z
            s1, c1 = sincos(t1)
            s2, c2 = sincos(t2)
            s += [p.L1 * s1 + self.L2 * s2, -(p.L1 * c1) - self.L2 * c2]
        return s

    @staticmethod
    def imu_points(z, p):
        """Positions [x1 y1 x2 y2] of the IMUs: on segment i at (a_i along the segment from its
        proximal joint, b_i to the left of it, i.e. anterior for a forward-facing leg)."""
        t1, t2 = z
        s1, c1 = sincos(t1)
        s2, c2 = sincos(t2)
        kx, ky = p.L1 * s1, -(p.L1 * c1)
        # u = (s, -c), left normal v = (c, s)
        return [p.a1 * s1 + p.b1 * c1, -(p.a1 * c1) + p.b1 * s1,
                kx + p.a2 * s2 + p.b2 * c2, ky - p.a2 * c2 + p.b2 * s2]


__all__ = ["Pendulum", "PENDULUM_MARKERS", "pendulum_markers", "Leg"]
