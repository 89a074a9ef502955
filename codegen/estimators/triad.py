"""TRIAD: orientation from two vector observations (Black 1964; Shuster & Oh 1981).

Seed 002 (§2.2, eqs. 2.27–2.33): from the body vectors b1 (primary), b2 and their earth-frame
references r1, r2, build the triads w = (b1, b×, b1×b×) and v = (r1, r×, r1×r×) with
b× = b1×b2/|b1×b2| (r× likewise); A = Σ v_i w_iᵀ maps sensor to earth.  Here b1, b2 are the
measured up direction (accelerometer) and field direction (magnetometer); r1 = +z (up) and r2 =
the unit reference field in East-North-Up, (0, cos δ, −sin δ) for a dip δ (positive downward).

``primary`` chooses which observation is matched exactly: 0 = gravity (the usual choice; the
dip then does not matter, and the result equals :mod:`ecompass`), 1 = magnetic field (the tilt
then depends on the reference dip being right).  No memory and no gyroscope.
"""
from __future__ import annotations

import math

from kinefuse.codegen.estimator import Estimator, Param, Var
from kinefuse.codegen.estimators.common import (ACC_NORM_MIN_SQ, IMU, MAG_NORM_MIN_SQ, Q_OUT,
                                                Q_STATE, REJECTED, SampleCheck, quat_from_rows)
from kinefuse.codegen.estimators.ecompass import DEGENERATE, HELD
from kinefuse.codegen.ir import BOOL
from kinefuse.codegen.linalg import Vec3, vselect
from kinefuse.codegen.mathlib import sin, sincos
from kinefuse.codegen.scalar import all_of, assume, inc_if, logical_and, logical_not, logical_or


def _unit_cross(a: Vec3, b: Vec3):
    """(a×b/|a×b|, |a×b|²) for unit a, b."""
    c = a.cross(b)
    c = Vec3(*(assume(v, -1.0, 1.0) for v in c))
    u, n2 = c.normalized(1e-12)
    return u, n2


def triad_matrix(b1: Vec3, b2: Vec3, r1: Vec3, r2: Vec3):
    """Rows of A = v1 w1ᵀ + v2 w2ᵀ + v3 w3ᵀ (sensor → earth) and |b1×b2|² (the degeneracy
    measure: sin² of the angle between the two observations)."""
    bx, s2 = _unit_cross(b1, b2)
    rx, _ = _unit_cross(r1, r2)
    b3 = b1.cross(bx)
    r3 = r1.cross(rx)
    rows = []
    for i in range(3):
        rows.append(Vec3(*(assume(r1[i] * b1[j] + rx[i] * bx[j] + r3[i] * b3[j], -1.0, 1.0)
                           for j in range(3))))
    return rows, s2


class Triad(Estimator):
    """TRIAD from one accelerometer + magnetometer sample, sensor → ENU.  Samples without a
    magnetometer reading, or with the two vectors within ``min_angle_deg`` of parallel
    (``degenerate``), repeat the last valid orientation and raise ``held``."""

    name = "triad"
    title = "TRIAD (two-vector attitude, memoryless)"
    inputs = IMU
    params = (
        Param.choice("primary", 0.0, 2,
                     "observation matched exactly: 0 = gravity (accelerometer), 1 = magnetic field"),
        Param("dip_deg", 64.0, "deg", -90.0, 90.0,
              "reference field dip (inclination, positive downward; used when primary = 1)"),
        Param("min_angle_deg", 5.0, "deg", 0.5, 45.0,
              "smallest angle between field and gravity that defines an orientation"),
    )
    state = (Q_STATE, Var("valid", 1, 0, 1, "", "1 once a valid orientation was computed",
                          BOOL, init=False), REJECTED)
    outputs = (Q_OUT, DEGENERATE, HELD, REJECTED)
    presets = {
        # seed 001's site: Montevideo, field 22.6 uT with a dip of about -36 deg (upward)
        "montevideo": {"dip_deg": -36.0},
    }

    def step(self, x, u, p):
        chk = SampleCheck(u)
        a, a2 = chk.acc.normalized(1e-6)
        m, m2 = chk.mag.normalized(1e-6)
        up = Vec3(0.0, 0.0, 1.0)
        sd, cd = sincos(p.dip_deg * (math.pi / 180.0))
        ref_m = Vec3(0.0, cd, -sd)
        mag_first = p.primary > 0.5
        b1 = vselect(mag_first, m, a)
        b2 = vselect(mag_first, a, m)
        r1 = vselect(mag_first, ref_m, up)
        r2 = vselect(mag_first, up, ref_m)
        rows, s2 = triad_matrix(b1, b2, r1, r2)
        q_t = quat_from_rows(*rows)
        s = sin(p.min_angle_deg * (math.pi / 180.0))
        usable = all_of(chk.use_mag, a2 >= ACC_NORM_MIN_SQ, m2 >= MAG_NORM_MIN_SQ)
        parallel = logical_and(usable, s2 < s * s)
        ok = logical_and(usable, logical_not(parallel))
        q = vselect(ok, q_t, x.q)
        rejected = inc_if(x.rejected, chk.bad)
        nx = {"q": q, "valid": logical_or(x.valid, ok), "rejected": rejected}
        return nx, {"q": q, "degenerate": parallel, "held": logical_not(ok), "rejected": rejected}
