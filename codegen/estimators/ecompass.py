"""eCompass: orientation from one accelerometer + magnetometer sample (no memory, no gyroscope).

Seed 002 (calibration thesis, Annex C) uses MATLAB's ``ecompass``: R = [(a×m)×a, a×m, a] in
North-East-Down.  Here the same rotation is computed with Valenti's algebraic quaternion (tilt
from gravity, then heading from the horizontal field; :func:`algebraic.aqua`) and expressed
sensor → East-North-Up like every kinefuse filter.  Gravity is the primary vector: the tilt is
exact, the field only sets the heading.
"""
from __future__ import annotations

import math

from kinefuse.codegen.estimator import Estimator, Param, Var
from kinefuse.codegen.estimators.algebraic import aqua
from kinefuse.codegen.estimators.common import (ACC_NORM_MIN_SQ, IMU, MAG_NORM_MIN_SQ, Q_OUT,
                                                Q_STATE, REJECTED, SampleCheck)
from kinefuse.codegen.ir import BOOL
from kinefuse.codegen.linalg import Quat, vselect
from kinefuse.codegen.mathlib import sin
from kinefuse.codegen.scalar import all_of, inc_if, logical_and, logical_not, logical_or, select

DEGENERATE = Var("degenerate", 1, 0, 1, "",
                 "1 when gravity and the field are (nearly) parallel (angle below "
                 "min_angle_deg: no orientation defined) on a sample whose accelerometer and "
                 "magnetometer readings are otherwise usable; q is then held (see held)", BOOL)
HELD = Var("held", 1, 0, 1, "",
           "1 when q repeats the last valid orientation (the initial identity before the first) "
           "instead of one from this sample: degenerate, no magnetometer reading on this sample, "
           "an accelerometer or field norm below 1 m/s^2 or 1 uT, or a rejected sample (the "
           "rejected counter increments)", BOOL)
VALID = Var("valid", 1, 0, 1, "", "1 once a valid orientation was computed", BOOL, init=False)


class Ecompass(Estimator):
    """Memoryless accelerometer + magnetometer orientation (MATLAB ecompass / Valenti's algebraic
    quaternion), sensor → ENU.  Every sample with a magnetometer reading gives an independent
    orientation; samples without one, or where gravity and the field are within
    ``min_angle_deg`` of parallel (no heading defined; ``degenerate``), repeat the last valid
    orientation and raise ``held``.  Exact only at rest: linear acceleration tilts the estimate
    and magnetic disturbances turn it."""

    name = "ecompass"
    title = "eCompass (accelerometer + magnetometer, memoryless)"
    inputs = IMU
    params = (
        Param("min_angle_deg", 5.0, "deg", 0.5, 45.0,
              "smallest angle between the magnetic field and the vertical that still defines "
              "a heading (below it the sample is flagged degenerate)"),
    )
    state = (Q_STATE, VALID, REJECTED)
    outputs = (Q_OUT, DEGENERATE, HELD, REJECTED)

    def step(self, x, u, p):
        chk = SampleCheck(u)
        a, a2 = chk.acc.normalized(1e-6)
        m, m2 = chk.mag.normalized(1e-6)
        q_am, _, _, gamma = aqua(a, m)
        # gamma = sin² of the angle between field and vertical; compared with sin²(min angle)
        s = sin(p.min_angle_deg * (math.pi / 180.0))
        usable = all_of(chk.use_mag, a2 >= ACC_NORM_MIN_SQ, m2 >= MAG_NORM_MIN_SQ)
        parallel = logical_and(usable, gamma < s * s)
        ok = logical_and(usable, logical_not(parallel))
        flip = q_am.w < 0.0          # canonical sign w >= 0 (same rotation)
        q_am = Quat(*(select(flip, -c, c) for c in q_am))
        q = vselect(ok, q_am, x.q)
        rejected = inc_if(x.rejected, chk.bad)
        nx = {"q": q, "valid": logical_or(x.valid, ok), "rejected": rejected}
        return nx, {"q": q, "degenerate": parallel, "held": logical_not(ok), "rejected": rejected}
