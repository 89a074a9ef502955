"""Seed 002 §5.4: synthetic study of sensor-to-segment misalignment on the flexion angle.

Set-up reproduced from the seed (UR3e elbow model, eq. 2.18):

* the arm (proximal) sensor stays at the identity; the forearm (distal) sensor rotates by the
  flexion reference λ about its Y axis (the simulated motion axis);
* both segments are initialised with the static-pose method (eqs. 2.1–2.4) at t = 0, when both
  sensors are at the identity, but the arm's declared initial segment orientation carries a
  misalignment error δ about one sensor axis: GB q'_A0 = q_axis(δ) (eq. 2.19 with one
  non-zero error angle);
* the joint quaternion (eq. 2.5) is decomposed with the sequence the seed's code uses
  (``quat2eul(q, 'ZYX')``) and the flexion estimate is the Y′ angle; the error is
  |ε| = |flexion_est − λ|;
* for δ ∈ {−20°, −18°, …, 20°} a parabola |ε| = a δ² + b δ + c is fitted (δ in degrees).

Published (Tables 5.11/5.12, X-axis misalignment): λ = 60°: a = 0.01389, c = 0.05043,
R² = 0.9995; λ = 70°: a = 0.02013, c = 0.1497 (Table 5.11's caption says λ = 10°, its numbers
are for 70° — errata).  A misalignment about Y shifts flexion by exactly |δ|; about Z it leaves
flexion unchanged.

Why the error is parabolic: with the arm frame tilted by δ about X the joint rotation becomes
Rx(−δ)·Ry(λ) whose Z–Y′–X″ middle angle is asin(cos δ · sin λ) — second order in δ.  With the
X–Y′–Z″ sequence of eqs. 2.7–2.9 the same rotation gives exactly λ (see tests).
"""
from __future__ import annotations

import numpy as np

from kinefuse.host.kinematics import alignment, joint
from kinefuse.host.kinematics import quat as Q

SEED002_DELTAS_DEG = np.arange(-20.0, 21.0, 2.0)


def flexion_error(lam_deg: float, delta_deg, *, axis: str = "X", sequence: str = "ZYX") -> np.ndarray:
    """|flexion_est − λ| (deg) for misalignments ``delta_deg`` of the arm sensor about ``axis``."""
    delta = np.atleast_1d(np.asarray(delta_deg, dtype=float))
    n = delta.size
    q_GS_arm = Q.identity(n)                                         # arm sensor: still
    q_GS_fore = Q.elementary("Y", np.full(n, np.radians(lam_deg)))   # forearm: flexed about Y
    q_GS_arm0 = Q.identity(n)                                        # both at identity at t = 0
    q_GS_fore0 = Q.identity(n)
    q_GB_arm0_err = Q.elementary(axis, np.radians(delta))            # eq. 2.19, one error angle
    q_SB_arm = alignment.static_pose_offset(q_GS_arm0, q_GB_arm0_err)
    q_SB_fore = alignment.static_pose_offset(q_GS_fore0)
    qj = joint.joint_quaternion(q_GS_arm, q_GS_fore, q_SB_arm, q_SB_fore)
    ang = np.degrees(Q.to_euler(qj, sequence))
    flex = ang[:, 1]  # the Y′ angle: the seed's flexion axis in this set-up
    return np.abs(flex - lam_deg)


def parabola_fit(x, y) -> dict:
    """Least-squares y = a x² + b x + c with R², adjusted R² and RMSE (MATLAB ``fit`` style)."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    A = np.column_stack([x**2, x, np.ones_like(x)])
    coef, *_ = np.linalg.lstsq(A, y, rcond=None)
    res = y - A @ coef
    sse = float(res @ res)
    sst = float(((y - y.mean()) ** 2).sum())
    n, p = len(x), 3
    r2 = 1.0 - sse / sst if sst > 0 else float("nan")
    return {"a": float(coef[0]), "b": float(coef[1]), "c": float(coef[2]), "r2": r2,
            "r2_adj": 1.0 - (1.0 - r2) * (n - 1) / (n - p), "rmse": float(np.sqrt(sse / (n - p)))}


def seed002_study(lam_deg: float, *, axis: str = "X", deltas_deg=SEED002_DELTAS_DEG,
                  sequence: str = "ZYX") -> dict:
    """Run the seed-002 study for one flexion reference; returns the fit and the raw errors."""
    err = flexion_error(lam_deg, deltas_deg, axis=axis, sequence=sequence)
    out = parabola_fit(deltas_deg, err)
    out.update({"lambda_deg": float(lam_deg), "axis": axis, "sequence": sequence,
                "delta_deg": np.asarray(deltas_deg, float).tolist(), "abs_error_deg": err.tolist()})
    return out
