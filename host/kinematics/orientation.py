"""Orientation from raw IMU data for the clinical reports: a pluggable filter parameter.

The reports take an orientation *filter* — a callable
``f(t [s], acc [m/s²], gyr [rad/s], mag [µT] or None) -> q_GS (N×4, w,x,y,z, sensor → ENU)``
or the name of one:

* a kinefuse filter name (``flagship``, the default, ``madgwick``, ``eskf`` ...; ``name@q`` for
  the fixed-point C): the generated float32 C run through :mod:`kinefuse.host.runner`;
* ``"simple"`` — :func:`complementary_filter` below: a small, documented stand-in written before
  the project's filters existed; kept as an independent cross-check;
* ``"module.path:function"`` — any importable callable with the signature above (how the
  project's filters plug in).
"""
from __future__ import annotations

import importlib
import math
from typing import Callable

import numpy as np

from kinefuse.host.errors import KinefuseError
from kinefuse.host.kinematics import quat as Q

G = 9.81


def initial_orientation(acc, mag=None) -> np.ndarray:
    """q_GS (ENU) from one accelerometer (+ magnetometer) vector: TRIAD with up = acc and, with
    a magnetometer, north = horizontal field; without it the heading is the sensor's own x–y."""
    up = np.asarray(acc, float)
    up = up / np.linalg.norm(up)
    if mag is not None and np.all(np.isfinite(mag)):
        m = np.asarray(mag, float)
        east = np.cross(m, up)
        if np.linalg.norm(east) > 1e-6 * np.linalg.norm(m):
            east /= np.linalg.norm(east)
            north = np.cross(up, east)
            # rows of R_SG... columns of R_GS^T: sensor coordinates of E, N, U
            return Q.from_matrix(np.vstack([east, north, up]))
    # heading undefined: choose east along the sensor x axis projected on the horizontal
    x = np.array([1.0, 0, 0]) if abs(up[0]) < 0.9 else np.array([0, 1.0, 0])
    east = x - (x @ up) * up
    east /= np.linalg.norm(east)
    north = np.cross(up, east)
    return Q.from_matrix(np.vstack([east, north, up]))


def complementary_filter(t, acc, gyr, mag=None, *, k_acc: float = 0.1, k_mag: float = 0.3,
                         acc_tol: float = 0.05, acc_span: float = 0.15, init_s: float = 0.2) -> np.ndarray:
    """Simple complementary filter (Mahony-style), returns q_GS (N×4, sensor → ENU).

    * prediction: q_k = q_{k−1} ⊗ exp(½ (ω_k + k_acc e_acc) Δt), gyroscope already bias-free;
    * inclination: e_acc = â × v̂ (measured up × predicted up, body frame); its weight falls
      linearly from 1 to 0 as | |a| − g | grows from ``acc_tol``·g to (acc_tol+acc_span)·g,
      so fast motion does not tilt the estimate;
    * heading (only with a calibrated magnetometer): the horizontal field direction in the
      earth frame is rotated towards north about the vertical at ``k_mag`` rad/s per rad, so the
      magnetometer never touches inclination;
    * start: TRIAD from the mean of the first ``init_s`` seconds.
    Gains are fixed defaults (not tuned per recording).  k_acc = 0.1 rad/s per rad trades
    inclination disturbance during fast motion against drift: on the independent simulator's
    walking scenario (``kinefuse.hil_tests.sim`` "gait", true mounting) the knee flexion RMSE is
    8.9° with k_acc = 0.5 and 4.2° with 0.1, while the simulated step-up stays ≤ 1.6° — see
    ``kinefuse bench joint-angles``.  The project's filters should replace it.
    """
    t = np.asarray(t, float)
    acc = np.asarray(acc, float)
    gyr = np.asarray(gyr, float)
    n = len(t)
    use_mag = mag is not None
    if use_mag:
        mag = np.asarray(mag, float)
    n0 = max(1, int(np.searchsorted(t, t[0] + init_s)))
    q = initial_orientation(acc[:n0].mean(axis=0), mag[:n0].mean(axis=0) if use_mag else None)
    w, x, y, z = (float(v) for v in q)
    out = np.empty((n, 4))
    out[0] = (w, x, y, z)
    dts = np.diff(t)
    for k in range(1, n):
        dt = dts[k - 1]
        ax, ay, az = acc[k]
        an = math.sqrt(ax * ax + ay * ay + az * az)
        # predicted up (third row of R_GS) in the body frame
        vx = 2 * (x * z - w * y)
        vy = 2 * (y * z + w * x)
        vz = 1 - 2 * (x * x + y * y)
        ex = ey = ez = 0.0
        if an > 0:
            dev = abs(an - G) / G
            wgt = min(1.0, max(0.0, 1.0 - (dev - acc_tol) / acc_span))
            if wgt > 0:
                ax, ay, az = ax / an, ay / an, az / an
                gain = k_acc * wgt
                ex = gain * (ay * vz - az * vy)
                ey = gain * (az * vx - ax * vz)
                ez = gain * (ax * vy - ay * vx)
        ox, oy, oz = gyr[k]
        ox += ex
        oy += ey
        oz += ez
        # q ⊗ exp(½ ω dt)
        th = math.sqrt(ox * ox + oy * oy + oz * oz) * dt
        if th > 0:
            s = math.sin(0.5 * th) / (th / dt)
            c = math.cos(0.5 * th)
            dw, dx, dy, dz = c, ox * s, oy * s, oz * s
            w, x, y, z = (w * dw - x * dx - y * dy - z * dz,
                          w * dx + x * dw + y * dz - z * dy,
                          w * dy - x * dz + y * dw + z * dx,
                          w * dz + x * dy - y * dx + z * dw)
        if use_mag:
            mx, my, mz = mag[k]
            # field in the earth frame: R_GS m
            me = (1 - 2 * (y * y + z * z)) * mx + 2 * (x * y - w * z) * my + 2 * (x * z + w * y) * mz
            mn = 2 * (x * y + w * z) * mx + (1 - 2 * (x * x + z * z)) * my + 2 * (y * z - w * x) * mz
            if me * me + mn * mn > 1e-12:
                err = math.atan2(me, mn)          # field direction east of north
                a = 0.5 * k_mag * err * dt        # rotate the estimate about up by +k err dt
                ca, sa = math.cos(a), math.sin(a)
                w, x, y, z = (ca * w - sa * z, ca * x - sa * y, ca * y + sa * x, ca * z + sa * w)
        nq = math.sqrt(w * w + x * x + y * y + z * z)
        w, x, y, z = w / nq, x / nq, y / nq, z / nq
        out[k] = (w, x, y, z)
    return out


FILTERS: dict[str, Callable] = {"simple": complementary_filter}


def generated_filter(name: str, impl: str = "f32") -> Callable:
    """One of kinefuse's generated IMU filters (float32 C by default) as a report filter:
    the per-sample time step comes from t, a magnetometer reading counts when it is finite."""
    from types import SimpleNamespace

    from kinefuse.host import runner

    def run(t, acc, gyr, mag=None):
        t = np.asarray(t, float)
        n = len(t)
        dt = np.diff(t, prepend=t[0] - (t[1] - t[0] if n > 1 else 0.01))
        mag_arr = np.zeros((n, 3)) if mag is None else np.asarray(mag, float)
        rec = SimpleNamespace(gyr=np.asarray(gyr, float), acc=np.asarray(acc, float), mag=mag_arr,
                              dt=dt, rate_hz=1.0 / float(np.median(dt)),
                              mag_valid=np.all(np.isfinite(mag_arr), axis=1) if mag is not None
                              else np.zeros(n, bool))
        return runner.run_filter(name, impl, rec).q

    run.__name__ = f"kinefuse_{name}_{impl}"
    return run


def default_filter_name() -> str:
    from kinefuse.host import runner
    return runner.default_filter()


def resolve_filter(spec) -> Callable:
    """A callable filter from a callable, a kinefuse filter name (``flagship``, ``madgwick`` ...,
    optionally ``name@q`` for fixed point), ``simple`` (the stand-in below) or
    ``"module:function"``."""
    if callable(spec):
        return spec
    if isinstance(spec, str):
        if spec in FILTERS:
            return FILTERS[spec]
        from kinefuse.host import runner
        name, _, impl = spec.partition("@")
        if name in runner.imu_filter_names():
            return generated_filter(name, impl or "f32")
        if ":" in spec:
            mod, _, fn = spec.partition(":")
            try:
                f = getattr(importlib.import_module(mod), fn)
            except (ImportError, AttributeError) as exc:
                raise KinefuseError(f"cannot load orientation filter {spec!r}: {exc}") from None
            if not callable(f):
                raise KinefuseError(f"orientation filter {spec!r} is not callable")
            return f
    from kinefuse.host import runner
    raise KinefuseError(f"unknown orientation filter {spec!r}; use a kinefuse IMU filter "
                        f"({', '.join(runner.imu_filter_names())}; name@q for fixed point), "
                        f"{', '.join(FILTERS)} or 'module:function'")


def yaw_alignment(q_GB_ref, q_GB_other) -> np.ndarray:
    """Rotation D about the earth vertical such that D ⊗ q_GB_other has its anterior axis (Z)
    in the same vertical plane as q_GB_ref's (both averaged over the given samples).  If the
    anterior axes are near vertical (e.g. sensors mounted flat and no alignment calibration),
    the medio-lateral axes (X) are used instead."""
    for axis in ([0, 0, 1.0], [1.0, 0, 0]):
        za = Q.rotate(q_GB_ref, np.broadcast_to(axis, np.shape(q_GB_ref)[:-1] + (3,)))
        zb = Q.rotate(q_GB_other, np.broadcast_to(axis, np.shape(q_GB_other)[:-1] + (3,)))
        za = np.atleast_2d(za).mean(axis=0)
        zb = np.atleast_2d(zb).mean(axis=0)
        if np.hypot(za[0], za[1]) >= 0.3 and np.hypot(zb[0], zb[1]) >= 0.3:
            ang = math.atan2(za[1], za[0]) - math.atan2(zb[1], zb[0])
            return Q.elementary("Z", ang)
    raise KinefuseError("cannot align headings: neither the anterior nor the medio-lateral "
                        "segment axes are horizontal in the reference posture")
