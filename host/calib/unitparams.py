"""A unit calibration file -> the unit's calibration parameters (``kinefuse calibrate apply``).

The file (:mod:`.unitfile`) holds per sensor the map ``cal = M · (raw − b)`` with ``raw`` in SI
units (m/s², rad/s, µT).  The unit applies the generated ``calib_apply`` map
``cal = M · (counts · scale − b)`` with the REAL32 parameters ``KF_<S>_M<ij>``, ``KF_<S>_B<i>``
and ``KF_<S>_SCALE`` (S = ACC, GYR, MAG).  A two-sensor unit (``KF_JOINT_ID`` != 0) has a second
map for its sensor 1, the same parameters as ``KF_<S>2_*`` (``KF_ACC2_M00`` …), and so two
calibration files, one per IMU, both with the unit's serial number: ``sensor=1``
(``kinefuse calibrate apply --sensor 1``) writes a file to sensor 1's parameters.  The file does
not say which sensor it is for.  So M and b go over unchanged (as float32, what the
parameter protocol carries); the scale is left as it is: the host reads a unit's KF_RAW_SAMPLE
counts in the dialect units (``kinefuse.host.link.dialect.RAW_SCALE``), which are the scale
parameters' defaults, and :func:`apply_to_unit` warns when the unit's scale differs from them.
Sensors absent from the file keep the values they have on the unit.

Sequence: check every value against the parameter ranges (nothing is written if one is out of
range), find the unit, compare its serial number (``KF_SERIAL_NO``) with the file's, read the
current values, write, then read every value back and compare it bit for bit with the float32
of the file's value.  A write the unit rejects restores the values already written.
"""
from __future__ import annotations

import math
import struct

import numpy as np

from kinefuse.host.errors import KinefuseError

#: unit-file sensor -> parameter prefix on the unit
PREFIX = {"accel": "ACC", "gyro": "GYR", "mag": "MAG"}
SERIAL_PARAM = "KF_SERIAL_NO"


def f32(v: float) -> float:
    return struct.unpack("<f", struct.pack("<f", float(v)))[0]


#: unit-file sensor -> the calib_apply field prefix
FIELD = {"accel": "acc", "gyro": "gyr", "mag": "mag"}
SENSORS = (0, 1)            # sensor 0 (KF_ACC_* ...) and, on a two-sensor unit, sensor 1 (KF_ACC2_* ...)


def param_name(sensor_key: str, part: str, sensor: int = 0) -> str:
    """The unit's parameter of ``part`` (``M01``, ``B2``, ``SCALE``) of the file's sensor
    ``sensor_key`` (accel|gyro|mag) for sensor 0 (``KF_ACC_M01``) or 1 (``KF_ACC2_M01``)."""
    from kinefuse.firmware.apptables import calib_param_name
    return calib_param_name(f"{FIELD[sensor_key]}_{part.lower()}", _sensor(sensor))


def _sensor(sensor) -> int:
    if sensor not in SENSORS:
        raise KinefuseError(f"sensor {sensor!r}: a unit has sensor 0 and, in the two-sensor mode, sensor 1")
    return int(sensor)


def _ranges(sensor: int = 0) -> dict[str, tuple[float, float, float]]:
    """KF_* calibration parameter of ``sensor`` -> (default, lo, hi) as float32, from the generated
    map (sensor 1's parameters have sensor 0's ranges and defaults)."""
    from kinefuse.codegen import estimators
    from kinefuse.firmware.apptables import calib_param_name
    est = estimators.get("calib_apply")
    return {calib_param_name(p.name, sensor): (f32(p.default), f32(p.lo), f32(p.hi)) for p in est.params}


def sensor_values(key: str, M, b, sensor: int = 0) -> dict[str, float]:
    """{parameter: float32 value} of one sensor's map (``key`` accel|gyro|mag)."""
    M = np.asarray(M, float)
    b = np.asarray(b, float)
    vals = {param_name(key, f"M{i}{j}", sensor): M[i, j] for i in range(3) for j in range(3)}
    vals.update({param_name(key, f"B{i}", sensor): b[i] for i in range(3)})
    return {k: f32(v) for k, v in vals.items()}


def out_of_range(vals: dict[str, float], sensor: int = 0, named: bool = True) -> str | None:
    """The first value outside the unit's parameter range, as a phrase (None: all inside);
    ``named``: with its parameter name (a file check names the entry instead: M[i][j], b[i])."""
    rng = _ranges(_sensor(sensor))
    for name, v in vals.items():
        _, lo, hi = rng[name]
        if not (math.isfinite(v) and lo <= v <= hi):
            part = name.rsplit("_", 1)[1]                 # M01, B0 (KF_MAG_B0 is a b)
            what = "M" if part.startswith("M") else "b"
            where = f"({name})" if named else (f"M[{part[1]}][{part[2]}]" if what == "M" else f"b[{part[1]}]")
            return f"{what} value {v:.6g} {where} is outside the unit's range [{lo:g}, {hi:g}]"
    return None


def plan(doc: dict, source: str, sensor: int = 0) -> dict[str, float]:
    """{parameter: float32 value} for every sensor in the (validated) calibration ``doc``, as
    the parameters of the unit's sensor ``sensor`` (0: KF_ACC_* ..., 1: KF_ACC2_* ...); raises
    KinefuseError naming ``source`` when a value is outside the unit's range."""
    sensor = _sensor(sensor)
    out: dict[str, float] = {}
    for key, entry in doc["sensors"].items():
        vals = sensor_values(key, entry["M"], entry["b"], sensor)
        why = out_of_range(vals, sensor)
        if why:
            raise KinefuseError(f"{source}: sensors.{key}: {why}: not applied")
        out.update(vals)
    if not out:
        raise KinefuseError(f"{source}: the calibration file holds no sensor calibration")
    return out


def serial_matches(file_serial: str, unit_serial: int) -> bool:
    """The file's serial (a string) names the unit's KF_SERIAL_NO (a uint32): decimal or
    0x-hex notation of the same number."""
    try:
        return int(str(file_serial).strip(), 0) == int(unit_serial)
    except ValueError:
        return False


def _same_bits(a: float, b: float) -> bool:
    return struct.pack("<f", float(a)) == struct.pack("<f", float(b))


def apply_to_unit(session, sysid: int, doc: dict, source: str, *, sensor: int = 0, warn=lambda msg: None,
                  timeout: float = 0.5) -> dict:
    """Write the calibration ``doc`` to the parameters of sensor ``sensor`` (0, or 1 of a
    two-sensor unit) of unit ``sysid`` over ``session`` and verify it.

    Returns ``{"unit", "serial", "sensor", "sensors", "written": {name: value}, "changed",
    "verified"}``."""
    from kinefuse.host.link.dialect import RAW_SCALE
    from kinefuse.host.link.params import ParamClient, ParamError
    sensor = _sensor(sensor)
    values = plan(doc, source, sensor)
    client = ParamClient(session, sysid, timeout=timeout)
    try:
        unit_serial = client.get(SERIAL_PARAM)
    except ParamError as exc:
        if "no such parameter" not in str(exc):
            raise KinefuseError(f"unit {sysid}: cannot read {SERIAL_PARAM}: {exc}") from None
        unit_serial = None
        warn(f"unit {sysid} reports no serial number ({SERIAL_PARAM}): not checked against "
             f"{source}'s {doc['serial']!r}")
    if unit_serial is not None and not serial_matches(doc["serial"], unit_serial):
        raise KinefuseError(f"{source}: calibration of unit {doc['serial']!r}, but unit {sysid} reports "
                            f"serial number {unit_serial} (0x{int(unit_serial):08X}): not applied")
    try:
        before = {name: client.get(name) for name in values}
        for key in doc["sensors"]:
            unit_key = {"accel": "acc", "gyro": "gyro", "mag": "mag"}[key]
            name = param_name(key, "SCALE", sensor)
            scale = client.get(name)
            if not _same_bits(scale, f32(RAW_SCALE[unit_key])):
                warn(f"unit {sysid}: {name} = {scale:.7g}, not the KF_RAW_SAMPLE unit {RAW_SCALE[unit_key]:.7g} "
                     f"that unit recordings are read in: the calibration assumes readings in that unit")
    except ParamError as exc:
        hint = ("does its firmware have a calibration map for sensor 1 (KF_ACC2_* ...)?" if sensor
                else "does its firmware apply calibrations?")
        raise KinefuseError(f"unit {sysid}: {exc} ({hint})") from None
    if sensor == 1:
        try:
            joint = client.get("KF_JOINT_ID")
        except ParamError:
            joint = None
        if joint == 0:
            warn(f"unit {sysid} is not in the two-sensor mode (KF_JOINT_ID 0): sensor 1's map is stored "
                 f"but used only once KF_JOINT_ID is set")
    written: list[str] = []
    try:
        for name, v in values.items():
            client.set(name, v, ptype=9)
            written.append(name)
    except ParamError as exc:
        restored = _restore(client, before, written)
        raise KinefuseError(f"unit {sysid}: {exc}; {restored}") from None
    bad = []
    for name, v in values.items():
        try:
            got = client.get(name)
        except ParamError as exc:
            raise KinefuseError(f"unit {sysid}: read-back of {name} failed: {exc}") from None
        if not _same_bits(got, v):
            bad.append(f"{name} = {got!r}, expected {v!r}")
    if bad:
        raise KinefuseError(f"unit {sysid}: read-back differs for {len(bad)} parameters ({bad[0]})")
    return {"unit": sysid, "serial": doc["serial"], "unit_serial": unit_serial, "sensor": sensor,
            "sensors": sorted(doc["sensors"]), "written": values,
            "changed": sorted(n for n in values if not _same_bits(before[n], values[n])),
            "verified": True}


def _restore(client, before: dict, written: list[str]) -> str:
    if not written:
        return "nothing was written"
    failed = 0
    for name in written:
        try:
            client.set(name, before[name], ptype=9)
        except Exception:  # noqa: BLE001 - restoring goes on
            failed += 1
    if failed:
        return (f"restoring the {len(written)} parameters already written failed for {failed}: "
                f"the unit's calibration is now mixed, apply again")
    return f"the {len(written)} parameters already written were restored"
