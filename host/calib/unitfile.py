"""Per-unit calibration file (JSON): load, save, validate, merge.

Layout (``format`` = ``"kinefuse-calibration"``, ``version`` = 1)::

    {
      "format": "kinefuse-calibration", "version": 1,
      "serial": "DOT-7",                      # unit serial number (string)
      "date": "2024-05-04T09:16:00+00:00",   # last modification, ISO 8601
      "sensor_ranges": {"acc_g": 8, "gyr_dps": 2000, "mag_uT": 1300},   # configured ranges
      "sensors": {
        "accel": {"M": 3×3, "b": 3, "units": "m/s^2", "method": ..., "model": ...,
                  "residual_rms": ..., "n_poses": ..., "n_samples": ..., "date": ...},
        "gyro":  {"M": 3×3, "b": 3, "units": "rad/s", ...},
        "mag":   {"M": 3×3, "b": 3, "units": "uT", ...}
      },
      "history": {"accel": [earlier entries, oldest first], ...}   # optional
    }

Each sensor entry is the affine map cal = M · (raw − b) (:func:`..affine.apply_affine`), with
``raw`` already converted to SI-derived units by the reader (m/s², rad/s, µT).  Validation
checks the structure, shapes, finiteness, det M > 0, a sane condition number and units, and
reports the first problem in one line naming the file.  A new calibration of a sensor moves
the one it replaces to ``history`` (recordings made before stay reproducible).
"""
from __future__ import annotations

import contextlib
import datetime as _dt
import json
import math
import os

import numpy as np

from kinefuse.host.calib import unitparams
from kinefuse.host.calib.affine import apply_affine
from kinefuse.host.errors import KinefuseError

FORMAT = "kinefuse-calibration"
VERSION = 1
UNITS = {"accel": "m/s^2", "gyro": "rad/s", "mag": "uT"}
#: configured sensor ranges a unit file records (``calibrate --range NAME=VALUE``):
#: accelerometer ±g, gyroscope ±°/s, magnetometer ±µT
SENSOR_RANGES = ("acc_g", "gyr_dps", "mag_uT")
MAX_COND = 100.0  # a calibration matrix that far from a scaled rotation is a broken fit


def now_iso() -> str:
    return _dt.datetime.now(_dt.timezone.utc).replace(microsecond=0).isoformat()


def new(serial: str, sensor_ranges: dict | None = None) -> dict:
    return {"format": FORMAT, "version": VERSION, "serial": str(serial), "date": now_iso(),
            "sensor_ranges": dict(sensor_ranges or {}), "sensors": {}}


def set_sensor(doc: dict, sensor: str, M, b, *, method: str, **extra) -> dict:
    """Insert/replace one sensor's parameters (M, b) and provenance in ``doc``; a replaced entry
    is appended to ``doc["history"][sensor]``."""
    if sensor not in UNITS:
        raise KinefuseError(f"unknown sensor {sensor!r} (accel|gyro|mag)")
    M = np.asarray(M, dtype=float)
    b = np.zeros(3) if b is None else np.asarray(b, dtype=float)
    entry = {"M": M.tolist(), "b": b.tolist(), "units": UNITS[sensor], "method": method,
             "date": now_iso()}
    entry.update({k: _jsonable(v) for k, v in extra.items()})
    old = doc["sensors"].get(sensor)
    if old is not None:
        doc.setdefault("history", {}).setdefault(sensor, []).append(old)
    doc["sensors"][sensor] = entry
    doc["date"] = entry["date"]
    return doc


def _jsonable(v):
    if isinstance(v, np.ndarray):
        return v.tolist()
    if isinstance(v, (np.floating, np.integer)):
        return v.item()
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v


def validate(doc, source: str = "calibration") -> dict:
    """Raise KinefuseError naming ``source`` and the first problem; return ``doc``."""
    def bad(msg):
        raise KinefuseError(f"{source}: invalid calibration file: {msg}")

    if not isinstance(doc, dict):
        bad("top level must be a JSON object")
    if doc.get("format") != FORMAT:
        bad(f"'format' must be {FORMAT!r}")
    if doc.get("version") != VERSION:
        bad(f"unsupported version {doc.get('version')!r} (this kinefuse reads {VERSION})")
    if not isinstance(doc.get("serial"), str) or not doc["serial"].strip():
        bad("'serial' must be a non-empty string")
    try:
        _dt.datetime.fromisoformat(str(doc.get("date")))
    except ValueError:
        bad(f"'date' is not ISO 8601: {doc.get('date')!r}")
    if not isinstance(doc.get("sensor_ranges", {}), dict):
        bad("'sensor_ranges' must be an object")
    for k, v in doc.get("sensor_ranges", {}).items():
        if not isinstance(v, (int, float)) or not v > 0:
            bad(f"sensor range {k!r} must be a positive number")
    sensors = doc.get("sensors")
    if not isinstance(sensors, dict):
        bad("'sensors' must be an object")
    for name, e in sensors.items():
        if name not in UNITS:
            bad(f"unknown sensor {name!r} (accel|gyro|mag)")
        if not isinstance(e, dict):
            bad(f"sensors.{name} must be an object")
        try:
            M = np.asarray(e["M"], dtype=float)
            b = np.asarray(e["b"], dtype=float)
        except (KeyError, TypeError, ValueError):
            bad(f"sensors.{name} needs numeric 'M' (3×3) and 'b' (3)")
        if M.shape != (3, 3) or b.shape != (3,):
            bad(f"sensors.{name}: M must be 3×3 and b a 3-vector (got {M.shape}, {b.shape})")
        if not (np.all(np.isfinite(M)) and np.all(np.isfinite(b))):
            bad(f"sensors.{name}: non-finite parameters")
        if e.get("units") != UNITS[name]:
            bad(f"sensors.{name}: units must be {UNITS[name]!r}, got {e.get('units')!r}")
        if not np.linalg.det(M) > 0:
            bad(f"sensors.{name}: det M = {np.linalg.det(M):.4g} ≤ 0 (a reflection or singular map)")
        if np.linalg.cond(M) > MAX_COND:
            bad(f"sensors.{name}: M is ill-conditioned (cond {np.linalg.cond(M):.3g} > {MAX_COND:g})")
        if not isinstance(e.get("method"), str):
            bad(f"sensors.{name}: 'method' must be a string")
        # a map the unit would refuse is refused here too (calibrate apply, report --unit-cal):
        # |M_ij| <= 2 and b within the sensor's range hold for any real calibration
        why = unitparams.out_of_range(unitparams.sensor_values(name, M, b), named=False)
        if why:
            bad(f"sensors.{name}: {why}")
    history = doc.get("history", {})
    if not isinstance(history, dict):
        bad("'history' must be an object")
    for name, entries in history.items():
        if name not in UNITS:
            bad(f"history: unknown sensor {name!r} (accel|gyro|mag)")
        if not isinstance(entries, list) or not all(isinstance(e, dict) for e in entries):
            bad(f"history.{name} must be a list of calibration entries")
    return doc


def load(path: str) -> dict:
    try:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
    except FileNotFoundError:
        raise KinefuseError(f"{path}: calibration file not found") from None
    except json.JSONDecodeError as exc:
        raise KinefuseError(f"{path}: line {exc.lineno}: not valid JSON ({exc.msg})") from None
    except UnicodeDecodeError:
        raise KinefuseError(f"{path}: not a calibration file (binary, not UTF-8 JSON text)") from None
    except OSError as exc:
        raise KinefuseError(f"{path}: cannot read the calibration file ({exc.strerror or exc})") from None
    return validate(doc, path)


def save(doc: dict, path: str) -> None:
    validate(doc, path)
    tmp = f"{path}.tmp{os.getpid()}"
    try:
        with open(tmp, "w", encoding="utf-8") as f:
            json.dump(doc, f, indent=2)
            f.write("\n")
        os.replace(tmp, path)
    except OSError as exc:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise KinefuseError(f"cannot write {path}: {exc.strerror or exc}") from None


def load_or_new(path: str, serial: str | None, sensor_ranges: dict | None) -> dict:
    """Existing file (checked to belong to ``serial`` if given) or a new document."""
    if os.path.exists(path):
        doc = load(path)
        if serial and doc["serial"] != serial:
            raise KinefuseError(f"{path}: belongs to unit {doc['serial']!r}, not {serial!r}")
        if sensor_ranges:
            doc["sensor_ranges"].update(sensor_ranges)
        return doc
    if not serial:
        raise KinefuseError(f"{path} does not exist yet: give the unit's serial number (--serial)")
    return new(serial, sensor_ranges)


def apply(doc: dict, sensor: str, raw):
    """Apply the stored map of ``sensor`` to raw samples (identity if absent)."""
    e = doc["sensors"].get(sensor)
    if e is None:
        return np.asarray(raw, dtype=float)
    return apply_affine(np.asarray(raw, dtype=float), np.asarray(e["M"]), np.asarray(e["b"]))
