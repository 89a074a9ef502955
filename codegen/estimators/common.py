"""What every orientation filter shares: the IMU sample record, its validation, and the
initial orientation from one accelerometer (+ magnetometer) sample.

Frames: the sensor frame is the IMU's own; the earth frame is East-North-Up (z up, y towards
magnetic north).  Orientation quaternions (w, x, y, z) map sensor to earth.  At rest the
accelerometer reads +g along the sensor's 'up' direction (specific force).
"""
from __future__ import annotations

import math

from kinefuse.codegen.estimator import InputSpec, Var
from kinefuse.codegen.ir import BOOL, INT
from kinefuse.codegen.linalg import Quat, Vec3, vselect
from kinefuse.codegen.scalar import (all_of, any_of, assume, clamp, fabs, fmax, fmin, logical_and,
                                     logical_not, logical_or, rsqrt, select, sqrt)

G = 9.81                                   # m/s^2, standard gravity used for ranges
GYR_MAX = 2000.0 * math.pi / 180.0         # rad/s  (+-2000 deg/s full scale)
ACC_MAX = 16.0 * 9.80665                   # m/s^2  (+-16 g full scale)
MAG_MAX = 4900.0                           # uT     (+-4900 uT full scale)
DT_MAX = 1.0                               # s      (longest step accepted)

IMU = InputSpec("imu", (
    Var("gyr", 3, -GYR_MAX, GYR_MAX, "rad/s", "angular rate, sensor frame"),
    Var("acc", 3, -ACC_MAX, ACC_MAX, "m/s^2",
        "specific force, sensor frame (+g upward at rest)"),
    Var("mag", 3, -MAG_MAX, MAG_MAX, "uT", "magnetic field, sensor frame"),
    Var("mag_valid", 1, 0, 1, "", "1 when mag holds a new sample (the magnetometer may be "
        "slower than the gyroscope)", BOOL),
    Var("dt", 1, 0.0, DT_MAX, "s", "time since the previous sample (per-sample: jitter and "
        "gaps are real)"),
), doc="One IMU sample.  A sample with a non-finite or out-of-range gyroscope, accelerometer or "
       "time step is rejected (the filter state is kept and a counter increments); an invalid "
       "magnetometer reading is ignored for that sample and counted too.")

# state and outputs every orientation filter has
Q_STATE = Var("q", 4, -1.0, 1.0, "", "orientation quaternion (w, x, y, z), sensor to earth (ENU)",
              init=(1.0, 0.0, 0.0, 0.0))
INITIALISED = Var("initialised", 1, 0, 1, "", "1 once the orientation was set from a sample",
                  BOOL, init=False)
REJECTED = Var("rejected", 1, 0, 2 ** 31 - 1, "samples",
               "samples (or magnetometer readings) rejected as non-finite or out of range",
               INT, init=0)
Q_OUT = Var("q", 4, -1.0, 1.0, "", "orientation quaternion (w, x, y, z), sensor to earth (ENU)")


def within(v, limit: float):
    """True when every component is finite and |v_i| <= limit (NaN compares false)."""
    return all_of(*(fabs(c) <= limit for c in v))


class SampleCheck:
    """Validation of one IMU sample."""

    def __init__(self, u):
        self.gyr = Vec3(*u.gyr)
        self.acc = Vec3(*u.acc)
        self.mag = Vec3(*u.mag)
        # dt for computations: the raw value may be anything (the sample is then rejected), the
        # clamped one keeps every intermediate bounded
        self.dt = clamp(u.dt, 0.0, DT_MAX)
        core = all_of(within(self.gyr, GYR_MAX), within(self.acc, ACC_MAX),
                      u.dt > 0.0, u.dt <= DT_MAX)
        mag_ok = within(self.mag, MAG_MAX)
        self.ok = core                                     # the sample can be used
        self.use_mag = all_of(core, u.mag_valid, mag_ok)   # ... and its magnetometer reading
        self.bad = logical_not(all_of(core, logical_not(logical_and(u.mag_valid,
                                                                    logical_not(mag_ok)))))


#: the first orientation waits this long (s of valid samples) for a magnetometer reading.  A
#: magnetometer slower than the gyroscope has no reading in most samples, and a start from gravity
#: alone leaves the heading to the slow magnetic correction of madgwick, mahony and complementary
#: (simulated slow rotation, magnetometer at 20 Hz, started on a sample without a reading: 34 deg
#: of heading error, still 17-25 deg after 35 s).  Without a reading by then the start is 6D.
MAG_WAIT_S = 0.5
INIT_WAIT = Var("t_wait", 1, 0.0, MAG_WAIT_S, "s",
                "time the start has waited for a magnetometer reading (saturates)", init=0.0)


def start_gate(chk: "SampleCheck", initialised, t_wait):
    """(start, next t_wait): the first valid sample with a usable magnetometer reading starts the
    filter, or any valid sample once MAG_WAIT_S of them have had none (state INIT_WAIT)."""
    waiting = logical_and(chk.ok, logical_not(initialised))
    start = logical_and(waiting, logical_or(chk.use_mag, t_wait >= MAG_WAIT_S))
    return start, select(waiting, fmin(t_wait + chk.dt, MAG_WAIT_S), t_wait)


ACC_NORM_MIN_SQ = 1.0    # (m/s^2)^2: below |a| = 1 m/s^2 (free fall) gravity is not observable
MAG_NORM_MIN_SQ = 1.0    # uT^2


def initial_quaternion(acc: Vec3, mag: Vec3, use_mag):
    """Orientation from gravity (+ magnetic north when use_mag): the TRIAD construction.

    up = a/|a|, east = (m x up)/|m x up|, north = up x east; the rotation matrix sensor->earth has
    the rows (east, north, up).  Without a magnetometer the heading is chosen so the sensor's x
    axis points east as far as possible.  Returns (q, ok) where ok is false when the
    accelerometer is too small or the field is (nearly) parallel to gravity.
    """
    up, a2 = acc.normalized(1e-6)
    # heading reference: the magnetometer direction, or the sensor's y axis when there is none.
    # The field is normalised first: in fixed point one format serves both choices, and the
    # field's range (thousands of µT) would leave a unit vector's products a few bits.
    m_dir, _ = mag.normalized(1e-12)
    ref = vselect(use_mag, m_dir, Vec3(0.0, 1.0, 0.0))
    e_raw = ref.cross(up)
    e2 = e_raw.norm_sq()
    r2 = ref.norm_sq()
    # |m x up|^2 / |m|^2 = sin^2 of the angle between field and vertical
    degenerate = e2 <= 1e-4 * r2
    east, _ = e_raw.normalized(1e-12)
    east = vselect(degenerate, Vec3(1.0, 0.0, 0.0), east)
    north = up.cross(east)
    q = quat_from_rows(east, north, up)
    ok = logical_and(a2 >= ACC_NORM_MIN_SQ, logical_not(logical_and(use_mag, degenerate)))
    return q, ok


def quat_from_rows(r0: Vec3, r1: Vec3, r2: Vec3) -> Quat:
    """Unit quaternion of the rotation matrix with rows r0, r1, r2 (Shepperd's method: the
    largest of the four candidate denominators is used, so nothing divides by ~0)."""
    m00, m01, m02 = r0
    m10, m11, m12 = r1
    m20, m21, m22 = r2
    tr = m00 + m11 + m22
    # 4 w^2 = 1 + tr, 4 x^2 = 1 + m00 - m11 - m22, ...
    cw = 1.0 + tr
    cx = 1.0 + m00 - m11 - m22
    cy = 1.0 - m00 + m11 - m22
    cz = 1.0 - m00 - m11 + m22
    use_w = all_of(cw >= cx, cw >= cy, cw >= cz)
    use_x = all_of(logical_not(use_w), cx >= cy, cx >= cz)
    use_y = all_of(logical_not(use_w), logical_not(use_x), cy >= cz)
    use_z = logical_not(any_of(use_w, use_x, use_y))
    c = select(use_w, cw, select(use_x, cx, select(use_y, cy, cz)))
    # the largest of the four is >= 1 (they sum to 4), so the floor never binds for a rotation
    s = rsqrt(fmax(c, 0.25))           # 1 / sqrt(c)
    half = 0.5 * c * s                 # the chosen component, sqrt(c) / 2
    k = 0.5 * s                        # 1 / (4 * chosen component)
    d_wx = (m21 - m12) * k
    d_wy = (m02 - m20) * k
    d_wz = (m10 - m01) * k
    d_xy = (m01 + m10) * k
    d_xz = (m02 + m20) * k
    d_yz = (m12 + m21) * k
    w = select(use_w, half, select(use_x, d_wx, select(use_y, d_wy, d_wz)))
    x = select(use_x, half, select(use_w, d_wx, select(use_y, d_xy, d_xz)))
    y = select(use_y, half, select(use_w, d_wy, select(use_x, d_xy, d_yz)))
    z = select(use_z, half, select(use_w, d_wz, select(use_x, d_xz, d_yz)))
    q = Quat(assume(w, -1.0, 1.0), assume(x, -1.0, 1.0), assume(y, -1.0, 1.0),
             assume(z, -1.0, 1.0))
    # keep w >= 0 (the same rotation either way; a canonical sign helps comparisons)
    flip = q.w < 0.0
    return Quat(*(select(flip, -c_, c_) for c_ in q))


# -- corrections shared by the complementary filters ------------------------------------------

def tilt_correction(q: Quat, acc_unit: Vec3, gain):
    """Rotate q towards the measured gravity direction by the fraction `gain` (0..1).

    g = R(q) a (measured 'up' in the earth frame).  The rotation taking g onto e_z has the
    unnormalised quaternion (1 + g_z, g_y, -g_x, 0) (half-angle form: no square root, no division
    by 1 + g_z); it is blended with the identity (LERP) by `gain` and applied in the earth frame,
    so q' = dq ⊗ q.  Rotations about the vertical are untouched: heading is not disturbed.
    """
    g = q.rotate(acc_unit)
    g = Vec3(assume(g.x, -1.0, 1.0), assume(g.y, -1.0, 1.0), assume(g.z, -1.0, 1.0))
    full = Quat(1.0 + g.z, g.y, -g.x, 0.0).normalized(1e-12, split=True)
    dq = Quat(1.0 - gain + gain * full.w, gain * full.x, gain * full.y, 0.0).normalized(1e-12,
                                                                              split=True)
    return dq * q


def heading_correction(q: Quat, mag_unit: Vec3, gain):
    """Rotate q about the earth's vertical towards magnetic north (+y in ENU) by `gain` (0..1).

    l = R(q) m; the rotation about z taking (l_x, l_y) onto +y has the unnormalised quaternion
    (L + l_y, 0, 0, l_x) with L = |(l_x, l_y)|.  Only heading changes: inclination is never
    disturbed by the magnetometer.
    """
    l = q.rotate(mag_unit)
    lx, ly = assume(l.x, -1.0, 1.0), assume(l.y, -1.0, 1.0)
    horiz = sqrt(fmax(lx * lx + ly * ly, 0.0))
    full = Quat(horiz + ly, 0.0, 0.0, lx).normalized(1e-12, split=True)
    dq = Quat(1.0 - gain + gain * full.w, 0.0, 0.0, gain * full.z).normalized(1e-12, split=True)
    return dq * q


def integrate_gyro(q: Quat, omega: Vec3, dt) -> Quat:
    """Strapdown step q + dt/2 q ⊗ (0, ω), normalised."""
    qdot = (q * Quat(0.0, omega.x, omega.y, omega.z)).scale(0.5)
    return (q + qdot.scale(dt)).normalized(split=True)
