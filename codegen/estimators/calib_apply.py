"""On-unit calibration: raw sensor counts -> the filters' IMU input record (SI units).

The map is the host's (``kinefuse.host.calib.affine``): ``cal = M · (raw − b)`` per sensor, where
``raw`` is the uncalibrated reading in SI units.  On the unit the reading arrives as integer
counts, so the conversion to SI comes first, with one per-sensor scale factor:

    raw_SI = counts · scale            (scale: m/s² per count, rad/s per count, µT per count)
    cal    = M · (raw_SI − b)          (b in the same SI unit, M dimensionless)

Defaults: M = I, b = 0 and the scale of the KF_RAW_SAMPLE message units (1 mG = 9.80665e-3 m/s²,
1 mrad/s, 1 mgauss = 0.1 µT), so an uncalibrated unit feeds its filters
``float32(counts) · float32(scale)`` — one rounding, exactly what the dialect asks for, and what
a host replaying KF_RAW_SAMPLE frames reproduces.  (With M = I and b = 0 the float32 path gives
exactly that value: 1·v + 0·v' + 0·v'' = v.)

The time step is converted here too: ``dt = dt_us · 1e-6`` s, so the whole conversion from
what the sensor driver delivers (counts, microseconds) to the filter input is generated code
with a bit-exact model.

Calibrated values are clamped to twice the filters' input ranges (the headroom of the filters'
fixed-point input formats): a value beyond a filter's range is still out of range there, and the
filter rejects and counts the sample, in every number system alike.  Clamping here only keeps
the float and fixed-point outputs identical where the fixed-point format would saturate.
"""
from __future__ import annotations

from kinefuse.codegen.estimator import Estimator, InputSpec, Param, Var
from kinefuse.codegen.estimators.common import ACC_MAX, DT_MAX, GYR_MAX, MAG_MAX
from kinefuse.codegen.scalar import clamp

COUNTS_MIN, COUNTS_MAX = -32768.0, 32767.0
DT_US_MAX = 1_000_000.0

#: sensor -> (unit, default scale per count, largest scale accepted, largest offset, full range)
SENSORS = {
    "acc": ("m/s^2", 9.80665e-3, 0.01, 50.0, ACC_MAX),
    "gyr": ("rad/s", 1e-3, 0.0011, 1.0, GYR_MAX),
    "mag": ("uT", 0.1, 0.15, 1000.0, MAG_MAX),
}
M_LIMIT = 2.0          # |M_ij| accepted (a calibration matrix is a scaled near-rotation)
SCALE_MIN = 1e-7       # a zero scale would discard the sensor

CALIB = InputSpec("calib", (
    Var("acc_raw", 3, COUNTS_MIN, COUNTS_MAX, "counts", "accelerometer reading, sensor driver counts"),
    Var("gyr_raw", 3, COUNTS_MIN, COUNTS_MAX, "counts", "gyroscope reading, sensor driver counts"),
    Var("mag_raw", 3, COUNTS_MIN, COUNTS_MAX, "counts", "magnetometer reading, sensor driver counts"),
    Var("dt_us", 1, 0.0, DT_US_MAX, "us", "time since the previous sample, whole microseconds"),
), doc="One raw sample as the sensor driver delivers it: integer counts per axis and the time "
       "step in whole microseconds (integers, carried as exact real values).")


def _sensor_params(s: str) -> tuple[Param, ...]:
    unit, scale, scale_max, b_max, _ = SENSORS[s]
    ps = [Param(f"{s}_m{i}{j}", 1.0 if i == j else 0.0, "", -M_LIMIT, M_LIMIT,
                f"{s} calibration matrix M, row {i}, column {j}") for i in range(3) for j in range(3)]
    ps += [Param(f"{s}_b{i}", 0.0, unit, -b_max, b_max, f"{s} offset b, axis {i} ({unit})")
           for i in range(3)]
    ps.append(Param(f"{s}_scale", scale, f"{unit} per count", SCALE_MIN, scale_max,
                    f"{s} counts to {unit} (default: the KF_RAW_SAMPLE unit)"))
    return tuple(ps)


class CalibApply(Estimator):
    """Raw counts and microseconds to the IMU input record: cal = M · (counts · scale − b) per
    sensor (accelerometer m/s², gyroscope rad/s, magnetometer µT, sensor frame) and
    dt = dt_us · 1e-6 s.  Stateless; outputs clamped to twice the filters' input ranges."""

    name = "calib_apply"
    title = "Calibration map applied on the unit"
    inputs = CALIB
    params = _sensor_params("acc") + _sensor_params("gyr") + _sensor_params("mag")
    state = ()
    outputs = tuple(
        Var(s, 3, -2.0 * SENSORS[s][4], 2.0 * SENSORS[s][4], SENSORS[s][0],
            f"calibrated {s}, sensor frame (clamped to twice the filters' range)")
        for s in ("gyr", "acc", "mag")
    ) + (Var("dt", 1, 0.0, 2.0 * DT_MAX, "s", "time step"),)

    def step(self, x, u, p):
        out = {}
        for s in ("gyr", "acc", "mag"):
            counts = getattr(u, f"{s}_raw")
            scale = getattr(p, f"{s}_scale")
            v = [counts[i] * scale - getattr(p, f"{s}_b{i}") for i in range(3)]
            lim = 2.0 * SENSORS[s][4]
            out[s] = tuple(
                clamp(getattr(p, f"{s}_m{i}0") * v[0] + getattr(p, f"{s}_m{i}1") * v[1]
                      + getattr(p, f"{s}_m{i}2") * v[2], -lim, lim)
                for i in range(3))
        out["dt"] = clamp(u.dt_us, 0.0, DT_US_MAX) * 1e-6
        return {}, out
