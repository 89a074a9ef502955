"""Joint angles on a unit that hosts two sensors: the joint quaternion and its decomposition.

Same definitions as the host (:mod:`kinefuse.host.kinematics.joint`), so a unit and the host
report the same numbers:

    q_joint = (q_prox ⊗ q_SB_prox)* ⊗ (q_dist ⊗ q_SB_dist)

q_prox, q_dist: the two sensors' orientations (sensor → earth, any common earth frame, e.g. the
output of two filters); q_SB_*: sensor-to-segment offsets from a calibration (identity by
default; `kinefuse report` / the alignment tools compute them).  The angles are the intrinsic
Tait–Bryan angles (a, b, c), R(q_joint) = R_i(a) R_j(b) R_k(c), of the sequence chosen by
``sequence``:

* 0 — X–Z′–Y″, the Grood & Suntay knee joint coordinate system (segment frames X medio-lateral
  to the subject's left, Y proximal, Z anterior): (flexion, ab/adduction, internal rotation);
* 1 — X–Y′–Z″ (seed 002 eqs. 2.7–2.9, elbow): (flexion, abduction, internal rotation);
* 2 — Z–Y′–X″ (seed 001's reported angles, yaw–pitch–roll).

``mirror`` = 1 negates the second and third angles: ISB signs for a left limb, whose X axis points
laterally.  The middle angle lies in [-π/2, π/2], the others in (-π, π]; at the gimbal lock
(|middle| within 1e-3 rad of π/2 in f32, where the other two are not separable) c = 0 and a
carries a ± c, as on the host.

A sample whose quaternions are not finite or not near unit norm (|q|² outside [0.5, 2]) is
rejected: the last outputs are held and ``rejected`` increments.  Everything is bounded by unit
quaternions, so fixed point needs no declared ranges beyond them.
"""
from __future__ import annotations

import math

from kinefuse.codegen.estimator import Estimator, InputSpec, Param, Var
from kinefuse.codegen.estimators.common import REJECTED, within
from kinefuse.codegen.ir import BOOL
from kinefuse.codegen.linalg import Quat, rotation_rows, vselect
from kinefuse.codegen.mathlib import asin, atan2
from kinefuse.codegen.scalar import (all_of, assume, fabs, inc_if, logical_not, logical_or,
                                     select)

JOINT = InputSpec("joint", (
    Var("q_prox", 4, -1.0, 1.0, "", "orientation of the proximal sensor (w, x, y, z), sensor → "
        "earth"),
    Var("q_dist", 4, -1.0, 1.0, "", "orientation of the distal sensor, same earth frame"),
), doc="One pair of sensor orientations (normally two filters' outputs of the same instant).")

SEQUENCES = {0: (0, 2, 1), 1: (0, 1, 2), 2: (2, 1, 0)}   # axis indices (i, j, k) of each sequence
LOCK_SIN = math.cos(1e-3)           # |sin(middle)| above this: gimbal lock (about 0.06 deg)

ANGLES = Var("angles", 3, -math.pi, math.pi, "rad",
             "intrinsic angles (a, b, c) of the sequence; knee (0): flexion, ab/adduction, "
             "internal rotation")
Q_JOINT = Var("q_joint", 4, -1.0, 1.0, "", "joint quaternion (w, x, y, z): distal segment "
              "relative to the proximal segment, in the proximal segment frame")


_SEGMENT = {"prox": "proximal", "dist": "distal"}


def _offset_params(which: str) -> tuple[Param, ...]:
    return tuple(Param(f"{which}_{c}", 1.0 if c == "w" else 0.0, "", -1.0, 1.0,
                       f"{c} of the {_SEGMENT[which]} sensor-to-segment offset q_SB (normalised in use)")
                 for c in "wxyz")


def _matrix(q: Quat):
    """Rotation matrix of a unit quaternion, entries bounded to [-1, 1] for fixed point."""
    return [[assume(v, -1.0, 1.0) for v in row] for row in rotation_rows(q)]


def _pick(seq_is, values):
    """values[s] for the sequence s in use (a chain of selects on the sequence parameter)."""
    out = values[2]
    for s in (1, 0):
        out = select(seq_is[s], values[s], out)
    return out


class JointAngle(Estimator):
    """Joint quaternion and joint angles from two sensor orientations (knee: Grood & Suntay)."""

    name = "joint-angle"
    title = "Joint angles from two sensor orientations (Grood & Suntay knee, X-Y'-Z'', Z-Y'-X'')"
    inputs = JOINT
    params = (
        Param.choice("sequence", 0.0, 3,
                     "0: X-Z'-Y'' (Grood & Suntay knee), 1: X-Y'-Z'' (seed 002 elbow), 2: Z-Y'-X''"),
        Param.choice("mirror", 0.0, 2,
                     "1: negate the 2nd and 3rd angles (left limb, ISB signs)"),
    ) + _offset_params("prox") + _offset_params("dist")
    state = (
        Var("q_joint", 4, -1.0, 1.0, "", "last joint quaternion", init=(1.0, 0.0, 0.0, 0.0)),
        Var("angles", 3, -math.pi, math.pi, "rad", "last joint angles", init=0.0),
        Var("valid", 1, 0, 1, "", "1 once a sample gave angles", BOOL, init=False),
        REJECTED,
    )
    outputs = (Q_JOINT, ANGLES,
               Var("valid", 1, 0, 1, "", "1 once a sample gave angles (else angles are 0)", BOOL),
               REJECTED)

    def step(self, x, u, p):
        qp_raw, qd_raw = Quat(*u.q_prox), Quat(*u.q_dist)
        n_p, n_d = qp_raw.norm_sq(), qd_raw.norm_sq()
        ok = all_of(within(qp_raw, 1.0), within(qd_raw, 1.0),
                    n_p >= 0.5, n_p <= 2.0, n_d >= 0.5, n_d <= 2.0)
        off_p = Quat(p.prox_w, p.prox_x, p.prox_y, p.prox_z).normalized(1e-6)
        off_d = Quat(p.dist_w, p.dist_x, p.dist_y, p.dist_z).normalized(1e-6)
        seg_p = (qp_raw.normalized(0.5) * off_p).normalized(0.5)
        seg_d = (qd_raw.normalized(0.5) * off_d).normalized(0.5)
        qj = (seg_p.conj() * seg_d).normalized(0.5)
        # canonical sign w >= 0 (the same rotation; the angles do not depend on it)
        qj = vselect(qj.w < 0.0, Quat(*(-c for c in qj)), qj)
        R = _matrix(qj)

        seq_is = {s: fabs(p.sequence - s) < 0.5 for s in (0, 1)}
        eps = {s: 1.0 if (i, j, k) in ((0, 1, 2), (1, 2, 0), (2, 0, 1)) else -1.0
               for s, (i, j, k) in SEQUENCES.items()}
        el = lambda f: _pick(seq_is, [f(s, *SEQUENCES[s]) for s in (0, 1, 2)])
        sb = el(lambda s, i, j, k: eps[s] * R[i][k])
        b = asin(sb)
        a = atan2(el(lambda s, i, j, k: -eps[s] * R[j][k]), el(lambda s, i, j, k: R[k][k]))
        c = atan2(el(lambda s, i, j, k: -eps[s] * R[i][j]), el(lambda s, i, j, k: R[i][i]))
        # gimbal lock: only a ± c is defined; c = 0 and a from column j (as the host does)
        lock = fabs(sb) > LOCK_SIN
        a_lock = atan2(el(lambda s, i, j, k: eps[s] * R[k][j]), el(lambda s, i, j, k: R[j][j]))
        a = select(lock, a_lock, a)
        c = select(lock, 0.0, c)
        mirror = p.mirror > 0.5
        angles = (a, select(mirror, -b, b), select(mirror, -c, c))

        q_out = vselect(ok, qj, Quat(*x.q_joint))
        ang_out = tuple(select(ok, v, old) for v, old in zip(angles, x.angles))
        valid = logical_or(x.valid, ok)
        rejected = inc_if(x.rejected, logical_not(ok))
        nx = {"q_joint": q_out, "angles": ang_out, "valid": valid, "rejected": rejected}
        return nx, {"q_joint": q_out, "angles": ang_out, "valid": valid, "rejected": rejected}
