"""Sensor-to-segment alignment: two-posture (seed 001 §8.3), functional axis, static pose.

Every method returns ``q_SB``: the orientation of the *segment* (body) frame B relative to the
*sensor* frame S, so that the segment orientation in the earth frame G is
``q_GB = q_GS ⊗ q_SB`` (see :func:`segment_orientation`).  ``to_matrix(q_SB)`` has B's axes,
written in sensor coordinates, as its columns.

Segment frame used by the two-posture method (seed 001 §8.2–8.3), for thigh and shank alike:

* Y — longitudinal, pointing proximally (up when standing);
* Z — anterior (points up when lying supine);
* X = Y × Z — medio-lateral, pointing to the subject's **left** for both legs
  (right-handed frame).  Knee flexion is then a positive rotation about X.

Accelerometers read +g upwards at rest (specific force), so a static mean accelerometer
vector is the "up" direction in sensor coordinates.
"""
from __future__ import annotations

import numpy as np

from kinefuse.host.errors import KinefuseError
from kinefuse.host.kinematics import quat as Q


def _unit(v, what: str) -> np.ndarray:
    v = np.asarray(v, dtype=float).reshape(3)
    n = np.linalg.norm(v)
    if not np.isfinite(n) or n < 1e-9:
        raise KinefuseError(f"{what} is zero or not finite; cannot define an axis from it")
    return v / n


def frame_from_axes(y_axis, z_aux, *, min_angle_deg: float = 30.0) -> np.ndarray:
    """Right-handed orthonormal frame from a primary Y axis and an auxiliary Z direction.

    Seed 001 eqs. 8.1–8.8: X = Y × Z_aux / |…|, Z = X × Y; returns R = [X Y Z] (columns in
    sensor coordinates) — the matrix of q_SB.  Raises if Y and Z_aux are closer than
    ``min_angle_deg`` to parallel (the cross product would be dominated by noise).
    """
    y = _unit(y_axis, "primary (Y) axis")
    za = _unit(z_aux, "auxiliary (Z) axis")
    ang = np.degrees(np.arccos(np.clip(abs(y @ za), 0.0, 1.0)))
    if ang < min_angle_deg:
        raise KinefuseError(
            f"the two calibration directions are only {90 - ang:.0f}° from parallel "
            f"(angle between them {ang:.1f}° < {min_angle_deg:.0f}°): the postures must differ "
            f"by a large rotation (standing vs lying supine ≈ 90°)")
    x = np.cross(y, za)
    x /= np.linalg.norm(x)
    z = np.cross(x, y)
    return np.column_stack([x, y, z])


def two_posture(acc_standing, acc_lying, *, min_angle_deg: float = 30.0) -> np.ndarray:
    """Seed 001 §8.3 static two-posture calibration of one sensor → q_SB (w,x,y,z).

    ``acc_standing``: mean accelerometer vector (sensor frame, any unit) while the subject
    stands (segment Y vertical); ``acc_lying``: mean while lying supine (segment Z vertical).
    Pass means over static windows (see :mod:`kinefuse.host.calib.static`).
    """
    return Q.from_matrix(frame_from_axes(acc_standing, acc_lying, min_angle_deg=min_angle_deg))


def frame_from_flexion_axis(x_axis, y_up, *, min_angle_deg: float = 30.0) -> np.ndarray:
    """Frame with X = functional flexion axis and Y = the vertical seen while standing,
    orthogonalised against X (X is kept exactly, Y adjusted, Z = X × Y)."""
    x = _unit(x_axis, "flexion axis")
    yu = _unit(y_up, "vertical (Y) direction")
    ang = np.degrees(np.arccos(np.clip(abs(x @ yu), 0.0, 1.0)))
    if ang < min_angle_deg:
        raise KinefuseError(
            f"the flexion axis is within {ang:.1f}° of the vertical: it must be roughly "
            f"horizontal in the standing posture")
    y = yu - (yu @ x) * x
    y /= np.linalg.norm(y)
    z = np.cross(x, y)
    return np.column_stack([x, y, z])


def principal_axis(omega, *, min_rate: float = 0.3, sign_ref=None) -> tuple[np.ndarray, float]:
    """Principal axis of angular-velocity samples (N×3, rad/s) and its planarity ratio.

    Uses samples with |ω| ≥ ``min_rate`` rad/s (rest samples carry only noise and bias).
    Returns the unit axis (sign chosen so that ``axis @ sign_ref ≥ 0`` when given, otherwise
    so that its largest component is positive) and the ratio σ2/σ1 of the second to the first
    singular value (≈ 0 for a clean hinge motion).
    """
    w = np.asarray(omega, dtype=float)
    if w.ndim != 2 or w.shape[1] != 3:
        raise KinefuseError("angular velocity must be an N×3 array")
    sel = np.linalg.norm(w, axis=1) >= min_rate
    if sel.sum() < 20:
        raise KinefuseError(
            f"only {int(sel.sum())} gyroscope samples rotate faster than {min_rate} rad/s: "
            f"record a few flexion–extension repetitions for the functional calibration")
    _, s, vt = np.linalg.svd(w[sel], full_matrices=False)
    axis = vt[0]
    if sign_ref is not None:
        if axis @ np.asarray(sign_ref, dtype=float) < 0:
            axis = -axis
    elif axis[np.argmax(np.abs(axis))] < 0:
        axis = -axis
    return axis, float(s[1] / s[0])


def functional_flexion_axis(gyr_prox, gyr_dist, q_prox=None, q_dist=None, *,
                            min_rate: float = 0.3, sign_ref_prox=None, sign_ref_dist=None,
                            max_planarity: float = 0.5) -> dict:
    """Flexion axis in both sensor frames from gyroscope data during flexion–extension.

    With the sensors' orientations ``q_prox``/``q_dist`` (q_GS, N×4) the relative angular
    velocity ω_rel = ω_dist − R_{dist←prox} ω_prox is formed in the distal sensor frame; its
    principal axis is the hinge axis, mapped into the proximal frame through the relative
    orientation.  Without orientations each gyroscope's own principal axis is used, which is
    valid when the motion is dominated by the hinge (e.g. seated knee extensions with the
    thigh still).  ``sign_ref_*`` fixes the axis sign (e.g. the nominal left-pointing axis).
    Returns ``{"prox": axis_S_prox, "dist": axis_S_dist, "planarity": ratio}``.
    """
    gp = np.asarray(gyr_prox, dtype=float)
    gd = np.asarray(gyr_dist, dtype=float)
    if gp.shape != gd.shape:
        raise KinefuseError("proximal and distal gyroscope arrays must have the same shape")
    if q_prox is None or q_dist is None:
        ap, rp = principal_axis(gp, min_rate=min_rate, sign_ref=sign_ref_prox)
        ad, rd = principal_axis(gd, min_rate=min_rate, sign_ref=sign_ref_dist)
        ratio = max(rp, rd)
    else:
        q_rel = Q.mul(Q.conj(Q.normalize(q_dist)), Q.normalize(q_prox))  # q_{dist←prox}
        w_rel = gd - Q.rotate(q_rel, gp)
        ad, ratio = principal_axis(w_rel, min_rate=min_rate, sign_ref=sign_ref_dist)
        # the hinge axis is fixed in both segments; average its image over the motion samples
        sel = np.linalg.norm(w_rel, axis=1) >= min_rate
        ap_all = Q.rotate(Q.conj(q_rel[sel]), np.broadcast_to(ad, (int(sel.sum()), 3)))
        ap = ap_all.mean(axis=0)
        ap /= np.linalg.norm(ap)
        if sign_ref_prox is not None and ap @ np.asarray(sign_ref_prox, float) < 0:
            raise KinefuseError("functional axis signs disagree between the two segments; "
                                "check the sign references")
    if ratio > max_planarity:
        raise KinefuseError(
            f"the recorded motion is not a clean flexion–extension (second/first singular "
            f"value {ratio:.2f} > {max_planarity}); repeat the functional trial")
    return {"prox": ap, "dist": ad, "planarity": ratio}


def functional_standing(axis_S, acc_standing) -> np.ndarray:
    """q_SB from a functional flexion axis (X) and the standing vertical (Y)."""
    return Q.from_matrix(frame_from_flexion_axis(axis_S, acc_standing))


def static_pose_offset(q_GS0, q_GB0=None) -> np.ndarray:
    """Seed 002 eqs. 2.2/2.4: sensor-to-segment offset from one known initial pose.

    ``q_SB = q_GS0* ⊗ q_GB0``, where q_GS0 is the sensor orientation at the initial instant
    and q_GB0 the segment orientation declared for that instant (identity = segment frame
    aligned with the earth frame).  The seed writes this product as "BSq_0*"; it is the
    offset that eqs. 2.1/2.3 right-multiply: q_GB(t) = q_GS(t) ⊗ q_SB.
    """
    q_GB0 = Q.identity() if q_GB0 is None else Q.normalize(q_GB0)
    return Q.mul(Q.conj(Q.normalize(q_GS0)), q_GB0)


def segment_orientation(q_GS, q_SB) -> np.ndarray:
    """q_GB = q_GS ⊗ q_SB (seed 002 eqs. 2.1/2.3)."""
    return Q.mul(Q.normalize(q_GS), Q.normalize(q_SB))


def mounting_error_deg(q_SB_est, q_SB_true) -> float:
    """Angle (deg) between an estimated and a true sensor-to-segment offset."""
    return float(np.degrees(Q.angle_between(q_SB_est, q_SB_true)))
