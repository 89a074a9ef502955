"""CSV export: one file per message type, units in the column names, device and host times.

Columns: kinefuse messages start with ``t_s`` (the unit's clock, seconds since boot), then
``host_time_s`` (host monotonic clock when the frame was received, seconds since the recording
started), ``host_unix_s`` (the same as UTC UNIX seconds, from the header's clock pair),
``host_fit_s`` (``t_s`` mapped onto the host clock through the unit's device -> host clock fit,
seconds since the recording started: when the sample was taken, on the one host clock all
units of a recording share, free of the link's delay jitter -- the column to time-align the
CSVs of several units; as ``kinefuse stats`` fits it: lower envelope, a leading burst of stale
frames left out, one fit per device-clock segment), ``stream``, ``sysid``, ``compid``, ``seq``
and the payload fields; other messages start with ``host_time_s``.  Comment lines (``#``)
before the header name the recording, the unit (stream, connection, system id, firmware) and
its clock fit, and for KF_RAW_SAMPLE and KF_ORIENTATION the frames of their vectors and
quaternion.  Fields carry their unit as a
suffix (``time_boot_us``, ``acc_x_mps2``); kinefuse messages are converted to SI first:

- KF_RAW_SAMPLE: ``acc_*_mps2``, ``gyr_*_radps``, ``mag_*_uT``, ``temperature_degC`` (``nan`` where the
  sample does not flag it valid);
- KF_ORIENTATION: ``quat_w..z`` (sensor to earth), covariance ``cov_*_rad2`` (``nan`` where the unit
  sends none: all six zero);
- KF_UNIT_STATUS: ``battery_voltage_mV`` and ``battery_remaining_pct`` are ``nan`` where the unit
  does not know them (UINT16_MAX, -1);
- KF_EFFORTS: entries named after the model (e.g. ``tau1_Nm``, ``Fx_N``) when one model is used
  throughout, ``effort_<i>_si`` otherwise.
These names match the "plain kinefuse CSV" of ``kinefuse.host.readers`` (``t_s``, ``acc_x_mps2``,
``gyr_x_radps``, ``mag_x_uT``, ``quat_w``), so an exported unit file can be fed to
``kinefuse calibrate`` / ``report``.  When a message comes from several units (streams or
system ids) each unit gets its own file, ``<MESSAGE>_s<stream>_u<sysid>.csv``.
A raw MAVLink capture (no host times) gets no host columns.
"""
from __future__ import annotations

import contextlib
import csv
from pathlib import Path

import numpy as np

from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.dialect import RAW_SCALE
from kinefuse.host.link.hil import gyro_radps
from kinefuse.host.link.frames import DecodedFile
from kinefuse.host.link.spec import MessageSpec, kinefuse_dialect
from kinefuse.host.outputs import staged

_UNIT_SUFFIX = {"m/s/s": "mps2", "m/s": "mps", "rad/s": "radps", "mrad/s": "mradps", "deg/s": "degps",
                "cdeg/s": "cdegps", "ddeg/s": "ddegps", "%": "pct", "d%": "dpct", "c%": "cpct", "m^2": "m2",
                "cm^2": "cm2", "KiB/s": "KiBps", "MiB/s": "MiBps", "bytes/s": "Bps", "bits/s": "bps",
                "deg/2": "halfdeg", "m/s*5": "mps5", "mm/h": "mmph", "g/min": "gpmin", "cm^3/min": "cm3pmin",
                "L/h": "Lph", "cm^3": "cm3", "1E-2": "e-2", "2E-3": "2e-3", "360/255": "360per255"}

EFFORT_LAYOUTS = {  # KF_EFFORT_MODEL -> [(name, unit suffix)]; see kinefuse.xml
    1: [("tau1", "Nm"), ("Fx", "N"), ("Fy", "N"), ("T2", "Nm"), ("Fx0", "N"), ("Fy0", "N"), ("T0", "Nm")],
    2: [("hip_torque", "Nm"), ("knee_torque", "Nm")],
}
COV_NAMES = ["xx", "xy", "xz", "yy", "yz", "zz"]
# measurements whose "unknown" value (kinefuse.xml) is written as nan
_UNKNOWN = {("KF_UNIT_STATUS", "battery_voltage"): 0xFFFF, ("KF_UNIT_STATUS", "battery_remaining"): -1}


def _suffix(unit: str | None) -> str:
    if not unit:
        return ""
    return "_" + _UNIT_SUFFIX.get(unit, unit.replace("/", "p").replace("^", "").replace("*", ""))


def _columns(spec: MessageSpec, arr: np.ndarray) -> list[tuple[str, np.ndarray, str]]:
    """[(column name, values, format)] for the payload of one message type."""
    cols = []
    name = spec.name
    if name == "KF_RAW_SAMPLE":
        cols.append(("time_boot_us", arr["time_boot_us"], "%d"))
        cols.append(("sample_counter", arr["sample_counter"], "%d"))
        gyr = gyro_radps(arr)   # x 2^gyro_shift per sample (the extension field; 0 when absent)
        for sensor, prefix, unit in (("acc", "acc", "mps2"), ("gyro", "gyr", "radps"), ("mag", "mag", "uT")):
            for k, ax in enumerate("xyz"):
                v = gyr[:, k] if sensor == "gyro" else arr[f"{sensor}_{ax}"] * RAW_SCALE[sensor]
                cols.append((f"{prefix}_{ax}_{unit}", v, "%.6g"))
        # the field holds a measurement only with KF_RAW_SAMPLE_FLAGS_TEMPERATURE_VALID (32): was
        # exported as a temperature (0.00 degC) without it; nan there, as the kfr reader does
        valid = (arr["flags"].astype(np.int64) & 32) != 0
        cols.append(("temperature_degC", np.where(valid, arr["temperature"] * RAW_SCALE["temperature"], np.nan),
                     "%.2f"))
        cols.append(("unit_id", arr["unit_id"], "%d"))
        cols.append(("flags", arr["flags"], "%d"))
        return cols
    efforts_model = None
    if name == "KF_EFFORTS" and arr.size:
        models = np.unique(arr["model_id"])
        if models.size == 1 and int(models[0]) in EFFORT_LAYOUTS:
            efforts_model = EFFORT_LAYOUTS[int(models[0])]
    no_cov = None
    if name == "KF_ORIENTATION" and "cov" in arr.dtype.names:   # all zero: "not provided" (kinefuse.xml), was
        no_cov = ~np.any(arr["cov"] != 0, axis=1)              # exported as a zero (perfectly certain) covariance
    for field, ctype, n in zip(spec.fields, spec.types, spec.array_lengths):
        unit = spec.units.get(field)
        if field == "time_boot_us":
            cols.append((field, arr[field], "%d"))
            continue
        if name == "KF_ORIENTATION" and field in ("q_w", "q_x", "q_y", "q_z"):
            cols.append(("quat_" + field[2], arr[field], "%.9g"))
            continue
        if ctype == "char":
            cols.append((field, np.char.decode(arr[field], "utf-8", "replace"), "%s"))
            continue
        fmt = "%.9g" if ctype in ("float", "double") else "%d"
        if n:
            for k in range(n):
                if name == "KF_ORIENTATION" and field == "cov":
                    cname = f"cov_{COV_NAMES[k]}_rad2"
                elif efforts_model is not None and field in ("effort", "effort_std"):
                    if k >= len(efforts_model):
                        continue
                    base, u = efforts_model[k]
                    cname = f"{base}_{u}" if field == "effort" else f"{base}_std_{u}"
                elif name == "KF_EFFORTS":
                    cname = f"{field}_{k}_si"
                else:
                    cname = f"{field}_{k}{_suffix(unit)}"
                values = arr[field][:, k]
                if no_cov is not None and field == "cov":
                    values = np.where(no_cov, np.nan, values)
                cols.append((cname, values, fmt))
        elif (name, field) in _UNKNOWN:   # the dialect's "unknown" value: was exported as 65535 mV, -1 %
            v = arr[field].astype(np.float64)
            cols.append((field + _suffix(unit), np.where(v == _UNKNOWN[(name, field)], np.nan, v), "%.9g"))
        else:
            cols.append((field + _suffix(unit), arr[field], fmt))
    if name in ("PARAM_VALUE", "PARAM_SET") and arr.size:  # integers travel bytewise in param_value
        from kinefuse.host.link.params import decode_value
        cols.append(("value", np.array([decode_value(float(v), int(t)) for v, t in
                                        zip(arr["param_value"], arr["param_type"])], dtype=object), "%s"))
    return cols


def export_csv(df: DecodedFile, out_dir, messages: list[str] | None = None, progress=None) -> list[dict]:
    """Write one CSV per message type into ``out_dir``; returns [{message, file, rows}]."""
    out_dir = Path(out_dir)
    d = kinefuse_dialect()
    wanted = None
    if messages:
        wanted = set()
        for m in messages:
            if m.upper() not in d:
                raise KinefuseError(f"unknown message {m!r} (e.g. KF_RAW_SAMPLE, KF_ORIENTATION)")
            wanted.add(d[m].msgid)
    by_msg: dict[int, list] = {}
    for sid, ds in df.streams.items():
        for mid, arr in ds.arrays.items():
            if wanted is None or mid in wanted:
                by_msg.setdefault(mid, []).append((sid, arr, ds.host_ns.get(mid)))
    if not by_msg:      # nothing to write: no (empty) folder either
        return []
    made, p = [], out_dir
    while not p.exists() and p != p.parent:
        made.append(p)
        p = p.parent
    try:   # after the checks: a refused export leaves no empty folder
        out_dir.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise KinefuseError(f"cannot create {out_dir}: {exc.strerror or exc}") from None
    # Every CSV is written under a temporary name and renamed once all are complete: a full
    # disk or an interrupt part-way left a cut CSV (and the files before it) that read as a
    # whole export; now it leaves nothing (and, with --force, the earlier export as it was).
    try:
        with staged() as stage:
            written = _export(df, d, by_msg, out_dir, stage, progress)
    except BaseException as exc:
        for folder in made:             # innermost first
            with contextlib.suppress(OSError):
                folder.rmdir()
        if isinstance(exc, OSError):    # the rename
            raise KinefuseError(f"cannot write into {out_dir}: {exc.strerror or exc} (nothing exported)") from None
        if isinstance(exc, KinefuseError):
            raise KinefuseError(f"{exc} (nothing exported)") from None
        raise
    return written


def _export(df: DecodedFile, d, by_msg: dict, out_dir: Path, stage, progress) -> list[dict]:
    """Write the CSVs of :func:`export_csv` under the temporary names of ``stage``
    (:func:`~kinefuse.host.outputs.staged`)."""
    start_mono = df.start_monotonic_ns
    start_unix = df.start_unix_ns
    from kinefuse.host.link.stats import host_time_from_fit, unit_clock_segments
    clocks: dict = {}

    def clock(sid: int, sysid: int) -> list:
        if (sid, sysid) not in clocks:
            clocks[(sid, sysid)] = unit_clock_segments(df.streams[sid], sysid, start_mono)
        return clocks[(sid, sysid)]
    written = []
    for mid, parts in sorted(by_msg.items()):
        spec = d.get(mid)
        units = sorted({(sid, int(x)) for sid, arr, _ in parts for x in np.unique(arr["_sysid"])})
        per_unit = spec.name.startswith("KF_") and len(units) > 1
        groups = units if per_unit else [None]
        for unit in groups:
            sel = [(sid, arr if unit is None else arr[arr["_sysid"] == unit[1]],
                    host if unit is None or host is None else host[arr["_sysid"] == unit[1]])
                   for sid, arr, host in parts if unit is None or sid == unit[0]]
            arr = np.concatenate([p[1] for p in sel])
            stream = np.concatenate([np.full(p[1].size, p[0], np.int64) for p in sel])
            has_host = all(p[2] is not None for p in sel)
            cols = []
            if has_host:
                host = np.concatenate([p[2] for p in sel])
                if len(sel) > 1:   # streams merged by host time; one stream keeps its arrival order (a
                    # tlog's wall-clock stamps stepping back reordered its frames)
                    order = np.argsort(host, kind="stable")
                    arr, stream, host = arr[order], stream[order], host[order]
            if "time_boot_us" in arr.dtype.names and spec.name.startswith("KF_"):
                cols.append(("t_s", arr["time_boot_us"] / 1e6, "%.6f"))
            pairs = sorted({(int(a), int(b)) for a, b in zip(stream, arr["_sysid"])}) if arr.size else []
            if has_host:
                cols.append(("host_time_s", (host - start_mono) / 1e9, "%.6f"))
                cols.append(("host_unix_s", (start_unix + (host - start_mono)) / 1e9, "%.6f"))
                if "time_boot_us" in arr.dtype.names and spec.name.startswith("KF_"):
                    fit_t = np.full(arr.size, np.nan)
                    for sid, sysid in pairs:
                        m = (stream == sid) & (arr["_sysid"] == sysid)
                        fit_t[m] = host_time_from_fit(clock(sid, sysid), arr["time_boot_us"][m], host[m])
                    cols.append(("host_fit_s", fit_t, "%.6f"))
            cols += [("stream", stream, "%d"), ("sysid", arr["_sysid"], "%d"), ("compid", arr["_compid"], "%d"),
                     ("seq", arr["_seq"], "%d")]
            cols += _columns(spec, arr)
            fname = spec.name if unit is None else f"{spec.name}_s{unit[0]}_u{unit[1]}"
            path = out_dir / f"{fname}.csv"
            _write(stage.path(path), cols, arr.size, _comments(df, spec.name, pairs, clock if has_host else None), shown=path)
            written.append({"message": spec.name, "file": str(path), "rows": int(arr.size),
                            **({} if unit is None else {"stream": unit[0], "sysid": unit[1]})})
            if progress is not None:
                progress(spec.name, arr.size)
    return written


_FRAMES = {   # the frames of the vectors and quaternions (kinefuse.xml), stated in the CSV itself
    "KF_RAW_SAMPLE": "acc_*_mps2 (specific force: a unit at rest with +z up reads acc_z_mps2 = +9.81), "
                     "gyr_*_radps (right-hand rule, relative to inertial space), mag_*_uT: along the sensor "
                     "axes x, y, z; temperature_degC: nan where the sample does not flag it valid",
    "KF_ORIENTATION": "quat_w, quat_x, quat_y, quat_z: rotation sensor -> earth frame (v_earth = q v_sensor "
                      "conj(q)); earth_frame: 1 ENU (x East, y North, z Up), 2 NED (x North, y East, z Down), "
                      "0 unknown; cov_*_rad2: covariance of the orientation error (small rotation vector in the "
                      "earth frame), nan where the unit sends none",
    # the joint angles' frames and sequence were stated nowhere in their CSV
    "KF_JOINT_ANGLE": "angle_1_rad, angle_2_rad, angle_3_rad: the distal segment frame relative to the proximal "
                      "one, R_prox_dist = R_a(angle_1) R_b(angle_2) R_c(angle_3) for the sequence abc of column "
                      "sequence (intrinsic: angle_1 about an axis of the proximal frame, angle_3 about one of the "
                      "distal frame; 1 XYZ, 2 XZY, 3 YXZ, 4 YZX, 5 ZXY (ISB hip, knee, ankle: flexion, adduction, "
                      "internal rotation), 6 ZYX, 7 YXY (ISB shoulder), 8 rotation vector (axis times angle) in "
                      "the proximal frame, 0 unknown); joint_id: 1/2 hip, 3/4 knee, 5/6 ankle, 7/8 shoulder "
                      "9/10 elbow, 11/12 wrist (left/right), 13 lumbar, 14 neck, 0 unknown",
    # the standard messages a unit also sends (for ground stations): their frames were not stated
    "ATTITUDE_QUATERNION": "q1, q2, q3, q4 = w, x, y, z: rotation sensor (body) -> NED earth frame (x North, "
                           "y East, z Down; MAVLink's convention: the KF_ORIENTATION of the same unit in NED); "
                           "rollspeed_radps, pitchspeed_radps, yawspeed_radps: about the sensor axes x, y, z",
    "HIGHRES_IMU": "xacc_mps2.. (specific force), xgyro_radps.., xmag_gauss..: along the sensor axes x, y, z",
    "KF_EFFORTS": "named columns carry their unit (N, Nm); effort_<i>_si, effort_std_<i>_si (models mixed or "
                  "unknown): entry i in the SI unit (N or N m) the row's model_id gives it; entries at or beyond "
                  "count are not estimates",
}


SEGMENTS_SHOWN = 10   # clock fits named in a CSV's unit line


def bitmask_fields(name: str) -> dict:
    """{field: {bit value: short name}} of a message's bitmask fields, from the dialect (so a
    bit added to kinefuse.xml, e.g. KF_JOINT_ANGLE_STATUS_NUMERIC_RESET, is named too)."""
    from kinefuse.host.link.dialect import module
    mod = module()
    cls = next((c for c in mod.mavlink_map.values() if c.msgname == name), None)
    if cls is None:
        return {}
    out = {}
    for field, display in getattr(cls, "fielddisplays_by_name", {}).items():
        enum = cls.fieldenums_by_name.get(field)
        if display != "bitmask" or enum not in mod.enums:
            continue
        out[field] = {int(v): e.name[len(enum) + 1:] if e.name.startswith(enum + "_") else e.name
                      for v, e in sorted(mod.enums[enum].items()) if not e.name.endswith("_ENUM_END")}
    return out


def bit_names(bits: dict, value: int) -> str:
    """"VALID|NUMERIC_RESET" of a bitmask value (unknown bits as numbers); "-" for none."""
    value = int(value)
    words = [n for b, n in bits.items() if value & b]
    rest = value & ~sum(bits)
    words += [str(1 << k) for k in range(rest.bit_length()) if rest >> k & 1]
    return "|".join(words) or "-"


def _comments(df: DecodedFile, name: str, pairs, clock) -> list[str]:
    """The ``#`` lines of a CSV: recording, unit(s), time columns and clock fits."""
    start = df.header.get("start_utc")      # none for a raw capture or a tlog (was "started None")
    out = [f"kinefuse export of {df.path} ({df.header.get('format')}" + (f", started {start}" if start else "")
           + f"): {name}"]
    for sid, sysid in pairs:
        ds = df.streams[sid]
        fw = next((m.get("firmware_version_text") for m in ds.meta
                   if m.get("type") == "unit_status" and m.get("sysid") == sysid), None)
        line = (f"unit: system id {sysid}, stream {sid} ({ds.info.get('connection', '?')})"
                + (f", firmware {fw}" if fw else ""))
        if clock is not None and name.startswith("KF_"):
            segs = clock(sid, sysid)
            if segs:
                shown = segs[:SEGMENTS_SHOWN]   # thousands (units mixed on one id) made one 200 kB line
                line += "; clock fit: " + "; ".join(
                    f"host = {sg['offset_s']:.6f} s + {sg['slope']:.9f} x t_s ({sg['drift_ppm']:+.1f} ppm, "
                    f"{sg['points']} {sg['reference']} points"
                    + (f", first {sg['excluded_leading']} left out" if sg["excluded_leading"] else "") + ")"
                    + (f" [{'; '.join(sg['warnings'])}]" if sg["warnings"] else "") for sg in shown)
                if len(segs) > len(shown):
                    line += f"; and {len(segs) - len(shown):,} more device-clock segments"
            else:
                line += "; no clock fit (too few samples): host_fit_s is nan"   # it said "empty"
        out.append(line)
    if name in _FRAMES:
        out.append(_FRAMES[name])
    for field, bits in bitmask_fields(name).items():   # what the bits of status/flags columns mean
        out.append(f"{field}: bitmask: " + ", ".join(f"{b} {n}" for b, n in bits.items()))
    if clock is not None and name.startswith("KF_"):
        out.append("t_s: unit clock, s since boot; host_time_s: host receive time, s since the recording "
                   "started; host_unix_s: the same as UNIX time; host_fit_s: t_s on the host clock "
                   "through the unit's clock fit (common to all units of the recording: align on it)")
    return out


def _write(path: Path, cols, rows: int, comments=(), block: int = 50_000, shown: Path | None = None) -> None:
    """Write one CSV to ``path`` (errors name ``shown``, the file it becomes)."""
    shown = path if shown is None else shown
    try:
        f = open(path, "w", newline="")
    except OSError as exc:
        raise KinefuseError(f"cannot write {shown}: {exc.strerror or exc}") from None
    try:   # a full disk fails here, not at open
        with f:
            for c in comments:
                f.write("# " + c.replace("\n", " ") + "\n")
            f.write(",".join(c[0] for c in cols) + "\n")
            if any(c[2] == "%s" for c in cols):  # strings: csv module quotes what needs quoting
                w = csv.writer(f, lineterminator="\n")
                for r in range(rows):
                    w.writerow([c[1][r] if c[2] == "%s" else c[2] % c[1][r] for c in cols])
                return
            fmt = ",".join(c[2] for c in cols)
            for a in range(0, rows, block):
                b = min(rows, a + block)
                table = np.empty((b - a, len(cols)), dtype=object)
                for k, c in enumerate(cols):
                    table[:, k] = c[1][a:b].tolist()
                f.write("\n".join(fmt % tuple(row) for row in table) + ("\n" if b > a else ""))
    except OSError as exc:
        raise KinefuseError(f"cannot write {shown}: {exc.strerror or exc}") from None
