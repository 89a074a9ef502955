"""A unit calibration file -> the unit's calibration parameters (``kinefuse calibrate apply``).

The file (:mod:`.unitfile`) holds per sensor the map ``cal = M · (raw − b)`` with ``raw`` in SI
units (m/s², rad/s, µT).  The unit applies the generated ``calib_apply`` map
``cal = M · (counts · scale − b)`` with the REAL32 parameters ``KF_<S>_M<ij>``, ``KF_<S>_B<i>``
and ``KF_<S>_SCALE`` (S = ACC, GYR, MAG).  So M and b go over unchanged (as float32, what the
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


def _ranges() -> dict[str, tuple[float, float, float]]:
    """KF_* calibration parameter -> (default, lo, hi) as float32, from the generated map."""
    from kinefuse.codegen import estimators
    est = estimators.get("calib_apply")
    out = {}
    for p in est.params:
        s, _, rest = p.name.partition("_")
        out[f"KF_{s.upper()}_{rest.upper()}"] = (f32(p.default), f32(p.lo), f32(p.hi))
    return out


def plan(doc: dict, source: str) -> dict[str, float]:
    """{parameter: float32 value} for every sensor in the (validated) calibration ``doc``;
    raises KinefuseError naming ``source`` when a value is outside the unit's range."""
    rng = _ranges()
    out: dict[str, float] = {}
    for sensor, entry in doc["sensors"].items():
        pre = PREFIX[sensor]
        M = np.asarray(entry["M"], float)
        b = np.asarray(entry["b"], float)
        vals = {f"KF_{pre}_M{i}{j}": M[i, j] for i in range(3) for j in range(3)}
        vals.update({f"KF_{pre}_B{i}": b[i] for i in range(3)})
        for name, v in vals.items():
            _, lo, hi = rng[name]
            v32 = f32(v)
            if not (math.isfinite(v32) and lo <= v32 <= hi):
                what = "M" if "_M" in name else "b"
                raise KinefuseError(f"{source}: sensors.{sensor}: {what} value {v:.6g} ({name}) is outside "
                                    f"the unit's range [{lo:g}, {hi:g}]: not applied")
            out[name] = v32
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


def apply_to_unit(session, sysid: int, doc: dict, source: str, *, warn=lambda msg: None,
                  timeout: float = 0.5) -> dict:
    """Write the calibration ``doc`` to unit ``sysid`` over ``session`` and verify it.

    Returns ``{"unit", "serial", "sensors", "written": {name: value}, "changed", "verified"}``."""
    from kinefuse.host.link.dialect import RAW_SCALE
    from kinefuse.host.link.params import ParamClient, ParamError
    values = plan(doc, source)
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
        for sensor in doc["sensors"]:
            key = {"accel": "acc", "gyro": "gyro", "mag": "mag"}[sensor]
            name = f"KF_{PREFIX[sensor]}_SCALE"
            scale = client.get(name)
            if not _same_bits(scale, f32(RAW_SCALE[key])):
                warn(f"unit {sysid}: {name} = {scale:.7g}, not the KF_RAW_SAMPLE unit {RAW_SCALE[key]:.7g} "
                     f"that unit recordings are read in: the calibration assumes readings in that unit")
    except ParamError as exc:
        raise KinefuseError(f"unit {sysid}: {exc} (does its firmware apply calibrations?)") from None
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
    return {"unit": sysid, "serial": doc["serial"], "unit_serial": unit_serial,
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
