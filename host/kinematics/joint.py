"""Joint orientation and joint angles with explicitly named decompositions.

Joint orientation (distal segment relative to proximal segment, expressed in the proximal
segment frame):

    q_joint = q_GB_prox* ⊗ q_GB_dist,   q_GB = q_GS ⊗ q_SB

(seed 002 eq. 2.5 / seed 001 eq. 6.2 once each sensor is replaced by its segment).  With the
sensor-to-segment offsets q_SB from a calibration posture in which the joint is in its
reference position, q_joint is the identity — the angles are zero — at that posture.

Knee angles (segment frames of :mod:`kinefuse.host.kinematics.alignment`: X medio-lateral
pointing to the subject's left, Y proximal, Z anterior):

``"grood-suntay"`` — joint coordinate system of Grood & Suntay (1983) as recommended by the
ISB: flexion/extension about the thigh's medio-lateral axis (X), ab/adduction about the
floating axis, internal/external rotation about the shank's long axis (Y″): the intrinsic
sequence X–Z′–Y″ of q_joint.

``"seed001-zyx"`` — what seed 001 reports: the intrinsic Z–Y′–X″ angles of q_joint, with X =
flexion/extension, Y = internal/external rotation, Z = ab/adduction.  Not a JCS; offered for
comparison with ChakaMo results.

Signs (both conventions, ISB): flexion +, adduction (varus) +, internal rotation +, for the
right *and* the left knee — for the left knee the ab/adduction and rotation angles are negated
because X points medially on the right leg and laterally on the left leg.
"""
from __future__ import annotations

import numpy as np

from kinefuse.host.errors import KinefuseError
from kinefuse.host.kinematics import quat as Q

KNEE_CONVENTIONS = ("grood-suntay", "seed001-zyx")
ELBOW_SEQUENCES = ("XYZ", "ZYX")
ELBOW_INITS = ("zero-at-start", "seed002", "none")
KNEE_COLUMNS = ("flexion_deg", "adduction_deg", "internal_rotation_deg")


def joint_quaternion(q_GS_prox, q_GS_dist, q_SB_prox=None, q_SB_dist=None) -> np.ndarray:
    """q_joint = (q_GS_prox ⊗ q_SB_prox)* ⊗ (q_GS_dist ⊗ q_SB_dist); identity offsets if None."""
    qp = Q.normalize(q_GS_prox)
    qd = Q.normalize(q_GS_dist)
    if q_SB_prox is not None:
        qp = Q.mul(qp, Q.normalize(q_SB_prox))
    if q_SB_dist is not None:
        qd = Q.mul(qd, Q.normalize(q_SB_dist))
    return Q.mul(Q.conj(qp), qd)


def seed001_knee_quaternion(q_GS_thigh, q_GS_shank, R_SB_thigh, R_SB_shank,
                            *, convention: str = "standard") -> np.ndarray:
    """Seed 001 eqs. 6.1–6.3 exactly as published (for comparison and the errata test).

    q_cal = q_thigh_cal* ⊗ q_shank_cal (6.1); q_knee = q_thigh* ⊗ q_shank (6.2, raw sensor
    quaternions); q_final = q_knee ⊗ q_cal* (6.3), where q_*_cal are the quaternions of the
    two-posture matrices R = [X Y Z] (8.7/8.8) converted with ``convention``.

    With Madgwick's conversion (``"madgwick"``, the conjugate) the result is
    q_SB_thigh ⊗ q_joint ⊗ q_SB_thigh*: the identity at the calibration posture, but the joint
    rotation expressed about the thigh *sensor* axes instead of the segment axes.  With the
    standard conversion it is not even zero at the posture: there it equals
    q_SB_thigh ⊗ q_SB_shank* ⊗ q_SB_shank* ⊗ q_SB_thigh, i.e. (q_SB_shank*)² when the thigh
    sensor is aligned — the relative mounting offset applied twice (seed-errata note).
    Use :func:`joint_quaternion` instead.
    """
    qt_cal = Q.from_matrix(R_SB_thigh, convention)
    qs_cal = Q.from_matrix(R_SB_shank, convention)
    q_cal = Q.mul(Q.conj(qt_cal), qs_cal)
    q_knee = Q.mul(Q.conj(Q.normalize(q_GS_thigh)), Q.normalize(q_GS_shank))
    return Q.mul(q_knee, Q.conj(q_cal))


def knee_angles(q_joint, *, convention: str = "grood-suntay", side: str = "right") -> np.ndarray:
    """Knee angles in degrees, columns (flexion, adduction, internal rotation), ISB signs.

    See the module docstring for the axis sequence of each convention.  ``side`` is
    ``"right"`` or ``"left"``.
    """
    if side not in ("right", "left"):
        raise KinefuseError(f"side must be 'right' or 'left', not {side!r}")
    if convention == "grood-suntay":
        a = np.degrees(Q.to_euler(q_joint, "XZY"))  # flexion, ab/ad (floating), rotation
        flex, add, rot = a[..., 0], a[..., 1], a[..., 2]
    elif convention == "seed001-zyx":
        a = np.degrees(Q.to_euler(q_joint, "ZYX"))  # Z: ab/ad, Y: rotation, X: flexion
        add, rot, flex = a[..., 0], a[..., 1], a[..., 2]
    else:
        raise KinefuseError(f"unknown knee convention {convention!r}; choose one of "
                            f"{', '.join(KNEE_CONVENTIONS)}")
    if side == "left":
        add, rot = -add, -rot
    return np.stack([flex, add, rot], axis=-1)


def knee_convention_text(convention: str, side: str) -> str:
    """One-line description printed in CSV headers and reports."""
    if convention == "grood-suntay":
        seq = "Grood & Suntay JCS = intrinsic X-Z'-Y'' of q_thigh*(x)q_shank"
    else:
        seq = "seed 001: intrinsic Z-Y'-X'' of q_thigh*(x)q_shank (not a JCS)"
    return (f"{side} knee, degrees; {seq}; segment frames X=medio-lateral (to subject's left), "
            f"Y=proximal, Z=anterior; ISB signs: +flexion, +adduction(varus), +internal rotation")


def elbow_angles(q_joint, *, sequence: str = "XYZ") -> np.ndarray:
    """Seed 002 elbow angles (deg): columns (ψ_FE flexion, ϑ_AA abduction, ϕ_IE int. rotation).

    ``"XYZ"``: intrinsic X–Y′–Z″ (seed 002 eqs. 2.7–2.9: ψ about X, ϑ about Y′, ϕ about Z″).
    ``"ZYX"``: the sequence the seed's MATLAB code actually uses (``quat2eul(q,'ZYX')``):
    flexion = X″ angle, abduction = Y′ angle, internal rotation = Z angle.
    Positive angles are right-hand rotations about the named segment axes.
    """
    seq = sequence.upper()
    if seq == "XYZ":
        return np.degrees(Q.to_euler(q_joint, "XYZ"))
    if seq == "ZYX":
        a = np.degrees(Q.to_euler(q_joint, "ZYX"))
        return np.stack([a[..., 2], a[..., 1], a[..., 0]], axis=-1)
    raise KinefuseError(f"unknown elbow sequence {sequence!r}; choose XYZ or ZYX")


def elbow_convention_text(sequence: str) -> str:
    seq = sequence.upper()
    if seq == "XYZ":
        d = "intrinsic X-Y'-Z'' (seed 002 eqs. 2.7-2.9)"
    else:
        d = "intrinsic Z-Y'-X'' (seed 002 MATLAB code, quat2eul 'ZYX')"
    return (f"elbow, degrees; {d} of q_arm*(x)q_forearm; flexion about X, abduction about Y, "
            f"internal rotation about Z; positive = right-hand rotation about the segment axis")
