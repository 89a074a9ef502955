"""Kinefuse unit recordings (``.kfr``, from ``kinefuse record``): one unit's KF_RAW_SAMPLE stream.

A ``.kfr`` file may hold several units (one per port, or several MAVLink systems on one link);
choose one with ``unit=``:

* ``unit=2`` (or ``"2"``, ``"u2"``): the unit with MAVLink system id 2 (= its unit id,
  parameter KF_UNIT_ID);
* ``unit="s1"``: the only unit recorded on stream 1 (the second ``--port``);
* ``unit="s1:2"`` (or ``"s1u2"``, export's ``s1_u2``): system id 2 on stream 1, needed when two
  ports carry units with the same id.

Without ``unit=`` a file with one unit is read; a file with several fails with a one-line
:class:`ReaderError` listing the units present (so does an unknown unit).

Samples (dialect ``firmware/mavlink/kinefuse.xml``) are converted to SI with the dialect's
scale factors (``RAW_SCALE``, the same as ``kinefuse export``): acc mG × 9.80665e-3 → m/s²,
gyro mrad/s × 2^gyro_shift × 1e-3 → rad/s (``gyro_shift``: 0 in recordings without it), mag mgauss × 0.1 → µT, temperature cdegC × 0.01 → °C.

**Time base.** ``t`` is the HOST clock: seconds of the host's monotonic clock since the
recording started (``metadata["start_unix_ns"]`` gives UTC of ``t = 0``).  Each sample's device
time (``time_boot_us``) is mapped with the device→host clock fit of ``kinefuse stats``
(:func:`kinefuse.host.link.stats.fit_clock`: host = offset + slope × device on the lower
envelope of the receive times, i.e. the unit's clock offset and drift are removed and link
jitter is not; a leading burst of frames queued before the recording is left out of the fit and
mapped by it), one fit per device-clock segment (a reboot starts a new one).  All units of one
recording therefore share one time base: their samples are synchronised to within the
difference of their minimum link latencies (about a millisecond over USB serial).  The fit
parameters are in ``metadata["clock"]``; ``metadata["clock_id"]`` is equal for recordings on
the same host clock (the kinematics reports then align them by time instead of by start).
The device time itself is kept in ``channels["device_time_s"]``.

**Losses and repeats.** Samples missing from the ``sample_counter`` sequence stay missing:
``t`` has a gap there (nothing is interpolated or invented; a warning counts them, see
``metadata["samples_lost"]``).  Repeated frames (same device time) are dropped
(``metadata["duplicates_dropped"]``).  A frame the link delivered after a later one (UDP, a
Wi-Fi bridge: frame N+1 before N) at most ``REORDER_US`` (50 ms) of device time behind the latest
of its clock segment is put back in its place by device time (``metadata["reordered"]``); it was
dropped, and taken for a reboot by ``kinefuse stats``.  ``channels`` also hold ``sample_counter`` (unwrapped),
``temperature_degC`` (NaN where not valid) and ``flags``.

**What the unit said.** ``metadata["unit_messages"]``: the unit's STATUSTEXTs (e.g. ERROR
"parameter storage error: settings may be lost") in arrival order, each with ``t`` (receive time
on the time base of ``t``), ``device_time_s`` (the unit's clock at its latest sample before it:
STATUSTEXT carries no time), ``severity``, ``severity_name`` and ``text``; WARNING or worse also
as a warning.  ``metadata["status_flags"]``: per message (KF_UNIT_STATUS ``status_flags``,
KF_ORIENTATION ``status``) how many frames had each bit set, e.g. ``{"KF_UNIT_STATUS":
{"STREAMING": 60, "STORAGE_ERROR": 1}, "KF_ORIENTATION": {"INPUT_CLIPPED": 3, ...}}``; a
SENSOR_FAULT, TX_OVERFLOW, STORAGE_ERROR or LOW_BATTERY status adds a warning.

**Magnetometer.** Present when the unit flags new magnetometer values
(KF_RAW_SAMPLE_FLAGS_MAG_UPDATED) in at least one sample, else ``mag`` is ``None``.  The
updated samples are ``mag_t``/``mag_native``; ``mag`` holds each of them until the next one
(as the unit does between its slower magnetometer readings).

**Damaged files.** A truncated recording (killed recorder, copied while recording) is read up to
the cut.  A damaged chunk whose header holds is recovered (its intact frames kept, checked by
their MAVLink CRCs: only frames the damage touched are lost); one whose header is damaged is
skipped up to the next intact chunk.  Both add a warning, which counts the damaged chunks
recovered and skipped (and the bytes lost), as ``kinefuse stats`` does.

A raw MAVLink byte capture (no ``.kfr`` header; give ``fmt="kfr"`` explicitly) or a ``.tlog`` is
read the same way; a raw capture has no host times, so ``t`` is then the unit's own clock
(``metadata["time_base"] == "device"``, not synchronised between units).
"""
from __future__ import annotations

import contextlib

import re
from pathlib import Path

import numpy as np

from kinefuse.host.errors import KinefuseError
from kinefuse.host.readers.recording import ReaderError, Recording, zero_order_hold

FORMAT = "kfr"
MSG_RAW, MSG_ORI, MSG_STATUS, MSG_STATUSTEXT = 52500, 52501, 52504, 253
ACC_CLIPPED, GYRO_CLIPPED, MAG_CLIPPED, MAG_UPDATED = 1, 2, 4, 8
CALIBRATED, TEMPERATURE_VALID, SIMULATED = 16, 32, 64


def sniff_bytes(head: bytes) -> bool:
    """True when ``head`` (the first bytes of a file) starts with the ``.kfr`` magic."""
    from kinefuse.host.link.recording import MAGIC
    return head[:len(MAGIC)] == MAGIC


def _error(path: str, exc: KinefuseError) -> ReaderError:
    """The link code's one-line error as a ReaderError (``<file>: <problem>``)."""
    msg = str(exc)
    p = str(path)
    if msg.startswith(p):
        msg = msg[len(p):].lstrip(":").strip()
        msg = msg[3:] if msg.startswith("is ") else msg
    return ReaderError(path, msg)


_decoded: dict | None = None     # path -> decoded file, inside decode_once()


@contextlib.contextmanager
def decode_once():
    """Within the block each file is decoded once however many of its units are read (reading a
    unit decodes the whole file: the costly part for a long recording with many units)."""
    global _decoded
    outer = _decoded
    _decoded = {} if outer is None else outer
    try:
        yield
    finally:
        _decoded = outer


def decoded(path: str):
    """The decoded file (KF_RAW_SAMPLE, KF_ORIENTATION, KF_UNIT_STATUS, STATUSTEXT): decoded
    again on each call, once per file inside :func:`decode_once`."""
    if _decoded is None:
        return _decode_file(path)
    key = str(Path(path).resolve())
    if key not in _decoded:
        _decoded[key] = _decode_file(path)
    return _decoded[key]


def _decode_file(path: str):
    from kinefuse.host.link.frames import decode_file, is_recording
    p = Path(path)
    if p.suffix.lower() == ".kfr" and p.is_file() and not is_recording(p):
        raise ReaderError(path, "not a kinefuse recording (no .kfr header magic)")
    try:
        return decode_file(p, raw=True, msgids=(MSG_RAW, MSG_ORI, MSG_STATUS, MSG_STATUSTEXT))
    except KinefuseError as exc:
        raise _error(path, exc) from None


def _units(df) -> list[dict]:
    """Every (stream, system id) that sent KF_RAW_SAMPLE, with a label unique in the file."""
    found = []
    for sid, ds in sorted(df.streams.items()):
        arr = ds.arrays.get(MSG_RAW)
        if arr is None or not arr.size:
            continue
        ids, counts = np.unique(arr["_sysid"], return_counts=True)
        for s, n in zip(ids, counts):
            found.append({"stream": int(sid), "sysid": int(s), "samples": int(n),
                          "connection": ds.info.get("connection")})
    sysids = [u["sysid"] for u in found]
    for u in found:
        u["label"] = str(u["sysid"]) if sysids.count(u["sysid"]) == 1 else f"s{u['stream']}:{u['sysid']}"
    return found


def list_units(path: str) -> list[dict]:
    """Units of a recording: [{label, stream, sysid, samples, connection}]."""
    return _units(decoded(path))


def _parse_unit(path: str, unit) -> tuple[int | None, int | None]:
    if isinstance(unit, (int, np.integer)) and not isinstance(unit, bool):
        return None, int(unit)
    m = re.fullmatch(r"(?:s(\d+)[:_/]?)?(?:u?(\d+))?", str(unit).strip().lower())
    if not m or (m.group(1) is None and m.group(2) is None):
        raise ReaderError(path, f"bad unit {unit!r}: expected a unit (system) id such as 2, "
                                f"s1 (the unit on stream 1) or s1:2")
    return (None if m.group(1) is None else int(m.group(1)),
            None if m.group(2) is None else int(m.group(2)))


def _describe(found: list[dict]) -> str:
    return ", ".join(f"{u['label']} ({u['samples']} frames, stream {u['stream']}"
                     + (f" {u['connection']}" if u.get("connection") else "") + ")" for u in found)


def _select(path: str, found: list[dict], unit) -> dict:
    if not found:
        raise ReaderError(path, "no KF_RAW_SAMPLE messages (no unit sensor data) in this recording")
    if unit is None or (isinstance(unit, str) and not unit.strip()):
        if len(found) == 1:
            return found[0]
        raise ReaderError(path, f"{len(found)} units in this recording: {', '.join(u['label'] for u in found)}; "
                                f"choose one with unit=ID (kinefuse calibrate: --unit; kinefuse report: "
                                f"--thigh-unit, --shank-unit, --arm-unit, --forearm-unit)")
    stream, sysid = _parse_unit(path, unit)
    hits = [u for u in found if (stream is None or u["stream"] == stream)
            and (sysid is None or u["sysid"] == sysid)]
    if len(hits) == 1:
        return hits[0]
    if not hits:
        raise ReaderError(path, f"unit {unit} is not in this recording; units present: {_describe(found)}")
    full = [f"s{h['stream']}:{h['sysid']}" for h in hits]
    raise ReaderError(path, f"unit {unit} is ambiguous ({', '.join(full)}): give the stream too, e.g. {full[0]}")


def _segments(dev: np.ndarray, cnt: np.ndarray) -> tuple[list[int], np.ndarray]:
    """(start indices of device-clock segments, mask of the frames that are not repeats): the
    clock goes back to a time not sent before in this segment and outside the reorder window (a
    reboot); a step back onto an already-sent (time, counter) is a repeat, one just behind the
    latest frame a frame swapped on the way.  The rule of ``kinefuse stats``
    (:func:`kinefuse.host.link.stats.device_segments`)."""
    from kinefuse.host.link.stats import device_segments
    return device_segments(dev, cnt)


def _unwrap(cnt: np.ndarray) -> np.ndarray:
    """A uint32 counter as int64 continuing across wraps (a step back stays a step back)."""
    if cnt.size == 0:
        return cnt.astype(np.int64)
    d = (cnt[1:].astype(np.int64) - cnt[:-1].astype(np.int64)) & 0xFFFFFFFF
    d = np.where(d >= 1 << 31, d - (1 << 32), d)
    return int(cnt[0]) + np.concatenate([[0], np.cumsum(d)])


STATUS_FIELDS = {MSG_STATUS: ("KF_UNIT_STATUS", "status_flags"), MSG_ORI: ("KF_ORIENTATION", "status")}
# KF_UNIT_STATUS bits worth a warning (LOW_BATTERY: the recording may end with the cell)
PROBLEM_FLAGS = ("SENSOR_FAULT", "TX_OVERFLOW", "STORAGE_ERROR", "LOW_BATTERY")


def _unit_reports(ds, sysid: int, raw, start_ns: int | None) -> dict:
    """What a unit said about itself, for the metadata:

    * ``unit_messages``: its STATUSTEXTs in arrival order, [{"t", "device_time_s", "severity",
      "severity_name", "text"}]; ``t`` on the recording's time base (host receive time, or the
      device clock in a capture without host times); STATUSTEXT carries no time of its own, so
      ``device_time_s`` is that of the unit's latest KF_RAW_SAMPLE before it (None before the first);
    * ``status_flags``: {message: {bit: number of frames with it set}} of KF_UNIT_STATUS
      ``status_flags`` and KF_ORIENTATION ``status`` (STORAGE_ERROR, INPUT_CLIPPED, ...)."""
    from kinefuse.host.link.export import bitmask_fields
    from kinefuse.host.link.stats import clean_statustext, severity_name
    out: dict = {"unit_messages": [], "status_flags": {}}
    for mid, (name, fld) in STATUS_FIELDS.items():
        arr = ds.arrays.get(mid)
        if arr is None:
            continue
        v = arr[fld][arr["_sysid"] == sysid].astype(np.int64)
        counts = {bit: int(np.count_nonzero(v & b)) for b, bit in bitmask_fields(name)[fld].items()}
        if v.size:
            out["status_flags"][name] = {bit: n for bit, n in counts.items() if n}
    arr = ds.arrays.get(MSG_STATUSTEXT)
    if arr is None:
        return out
    rows = arr["_sysid"] == sysid
    host = ds.host_ns.get(MSG_STATUSTEXT)
    host = None if host is None or start_ns is None else (host[rows] - start_ns) / 1e9
    before = np.searchsorted(raw["_offset"], arr["_offset"][rows]) - 1
    for k, r in enumerate(arr[rows]):
        dev = None if before[k] < 0 else int(raw["time_boot_us"][before[k]]) / 1e6
        t = dev if host is None else float(host[k])
        out["unit_messages"].append({"t": t, "device_time_s": dev, "severity": int(r["severity"]),
                                     "severity_name": severity_name(r["severity"]),
                                     "text": clean_statustext(r["text"])})
    return out


def read(path: str, *, unit=None, **_) -> Recording:
    """One unit of a ``.kfr`` recording (or raw MAVLink capture) as a :class:`Recording`."""
    from kinefuse.host.link.dialect import RAW_SCALE
    from kinefuse.host.link.hil import gyro_radps
    from kinefuse.host.link.stats import clock_jumps, counter_analysis, fit_clock, in_device_order, leading_stale
    path = str(path)
    df = decoded(path)
    found = _units(df)
    u = _select(path, found, unit)
    ds = df.streams[u["stream"]]
    arr = ds.arrays[MSG_RAW]
    rows = arr["_sysid"] == u["sysid"]
    a = arr[rows]
    host_ns = ds.host_ns.get(MSG_RAW)
    host = None if host_ns is None else (host_ns[rows] - df.start_monotonic_ns) / 1e9
    dev = a["time_boot_us"].astype(np.int64)
    cnt = a["sample_counter"].astype(np.int64)
    warnings: list[str] = []
    name = f"unit {u['label']}"

    # --- device-clock segments, repeats, host time
    from kinefuse.host.link.stats import interleaved_clocks, interleaved_text
    mixed = interleaved_clocks(dev, cnt)
    if mixed is not None:   # two units' samples mixed into one series: was read as one unit
        raise ReaderError(path, interleaved_text(u["label"], "KF_RAW_SAMPLE", mixed,
                                                 "they cannot be read as one unit"))
    starts, fresh = _segments(dev, cnt)
    jumps = clock_jumps(dev, cnt) if host is not None else ()
    if len(jumps):   # one fit across a clock step is meaningless: each side gets its own
        warnings.append(f"{path}: {name}: the device clock jumped forward {len(jumps)} time(s) with the sample "
                        f"counter running on (first by {(dev[jumps[0]] - dev[jumps[0] - 1]) / 1e6:,.1f} s at "
                        f"sample {int(jumps[0])}): each part mapped to the host clock by its own fit")
        starts = sorted(set(starts) | {int(j) for j in jumps})
    starts = starts + [dev.size]
    if host is None and len(starts) > 2:
        warnings.append(f"{path}: {name}: device clock restarted {len(starts) - 2} time(s) and this capture "
                        f"has no host times: only the last segment is read")
        starts = starts[-2:]
    keep_idx, t_parts, clocks = [], [], []
    duplicates, lost, gaps, reordered = 0, 0, 0, 0
    counters = []
    for s, e in zip(starts[:-1], starts[1:]):
        duplicates += int(np.count_nonzero(~fresh[s:e]))
        idx, late = in_device_order(dev, fresh, s, e)   # a frame swapped on the way back in its place
        reordered += late
        dev_s = dev[idx] / 1e6
        if host is None:
            t_seg = dev_s
        else:
            # frames queued before the recording (a pty or serial buffer's backlog) arrive in a
            # burst that would bend the fit: fitted without them, mapped like the rest
            stale = leading_stale(dev_s, host[idx])
            fit = fit_clock(dev_s[stale:], host[idx][stale:])
            if fit is None:  # too few samples for the robust fit: offset only, on the lower envelope
                fit = {"slope": 1.0, "offset_s": float(np.min(host[idx] - dev_s)), "drift_ppm": 0.0,
                       "points": int(idx.size)}
            t_seg = fit["offset_s"] + fit["slope"] * dev_s
            clocks.append({k: fit[k] for k in ("offset_s", "slope", "drift_ppm", "points")
                           if k in fit} | ({"delay_above_min_ms": fit["delay_above_min_ms"]}
                                           if "delay_above_min_ms" in fit else {}))
        c = _unwrap(cnt[idx])
        ca = counter_analysis(cnt[idx])
        lost += ca["samples_lost"]
        if ca["stride"]:
            gaps += int(np.sum(np.diff(c) > ca["stride"]))
        keep_idx.append(idx)
        t_parts.append(t_seg)
        counters.append(c)
    idx = np.concatenate(keep_idx)
    t = np.concatenate(t_parts)
    counter = np.concatenate(counters)
    # host times of consecutive segments must not overlap (a fit across a reboot gap)
    prev = np.maximum.accumulate(np.concatenate([[-np.inf], t[:-1]]))
    inc = t > prev
    if not inc.all():
        warnings.append(f"{path}: {name}: {int((~inc).sum())} sample(s) overlapping an earlier device-clock "
                        f"segment in host time dropped")
        idx, t, counter = idx[inc], t[inc], counter[inc]
    if t.size < 2:
        raise ReaderError(path, f"{name} has only {t.size} sample(s); need at least 2")
    a = a[idx]
    flags = a["flags"].astype(np.int64)

    acc = np.column_stack([a[f"acc_{x}"] for x in "xyz"]).astype(np.float64) * RAW_SCALE["acc"]
    gyr = gyro_radps(a)    # x 2^gyro_shift per sample (0 in recordings without the field)
    mag_all = np.column_stack([a[f"mag_{x}"] for x in "xyz"]).astype(np.float64) * RAW_SCALE["mag"]
    temp = np.where(flags & TEMPERATURE_VALID, a["temperature"].astype(np.float64) * RAW_SCALE["temperature"],
                    np.nan)
    upd = (flags & MAG_UPDATED) != 0
    mag = mag_t = mag_native = None
    if upd.any():
        mag_t, mag_native = t[upd], mag_all[upd]
        mag = zero_order_hold(mag_t, mag_native, t)

    dt = np.diff(t)
    fs = 1.0 / float(np.median(dt))
    if lost:
        k = int(np.argmax(dt > 1.5 * np.median(dt)))
        warnings.append(f"{path}: {name}: {lost} sample(s) lost in {gaps} gap(s) of the sample counter "
                        f"(kept as gaps, nothing interpolated); first after t = {t[k]:.3f} s")
    if duplicates:
        warnings.append(f"{path}: {name}: {duplicates} repeated sample(s) dropped")
    for bit, what in ((ACC_CLIPPED, "accelerometer"), (GYRO_CLIPPED, "gyroscope"), (MAG_CLIPPED, "magnetometer")):
        n = int(np.count_nonzero(flags & bit))
        if n:
            warnings.append(f"{path}: {name}: {n} sample(s) with the {what} clipped (at its range)")
    calibrated = bool(np.all(flags & CALIBRATED))
    if not calibrated:
        warnings.append(f"{path}: {name}: {int(np.count_nonzero(~flags & CALIBRATED))} sample(s) are uncalibrated "
                        f"readings (the unit's calibration not applied; give a unit calibration file)")
    rec = df.recording
    if rec is not None and rec.truncated:
        warnings.append(f"{path}: the recording is truncated (ends inside a chunk): read up to the cut")
    if rec is not None and rec.damaged_chunks:
        from kinefuse.host.link.stats import damage_text    # recovered vs skipped, as `kinefuse stats`
        warnings.append(f"{path}: {damage_text(rec)}")

    meta = {
        "unit": u["label"], "sysid": u["sysid"], "stream": u["stream"], "connection": u.get("connection"),
        "units_in_file": [x["label"] for x in found], "source_kind": df.kind if rec is None else "kfr",
        "time_base": "device" if host is None else "host",
        "samples_lost": int(lost), "duplicates_dropped": int(duplicates), "reordered": int(reordered),
        "device_clock_segments": len(keep_idx),
        "calibrated_on_unit": calibrated, "simulated": bool(np.any(flags & SIMULATED)),
        "mag_present": bool(upd.any()),
        "unit_id": int(np.bincount(a["unit_id"].astype(np.int64)).argmax()),
    }
    if host is not None:
        meta["clock"] = clocks[0] if len(clocks) == 1 else clocks
        meta["start_unix_ns"] = int(df.start_unix_ns)
        meta["start_monotonic_ns"] = int(df.start_monotonic_ns)
        meta["clock_id"] = f"host:{df.start_unix_ns}:{df.start_monotonic_ns}"
        if rec is not None:
            meta["start_utc"] = rec.header.get("start_utc")
    st = ds.arrays.get(MSG_STATUS)
    if st is not None:
        st = st[st["_sysid"] == u["sysid"]]
        if st.size:
            v = int(st[-1]["firmware_version"])
            meta["firmware_version"] = f"{v >> 24}.{(v >> 16) & 0xFF}.{(v >> 8) & 0xFF}"
    reports = _unit_reports(ds, u["sysid"], arr[rows], None if host is None else df.start_monotonic_ns)
    meta.update(reports)
    flags_seen = reports["status_flags"].get("KF_UNIT_STATUS", {})
    bad = [f"{bit} in {flags_seen[bit]} of {st.size}" for bit in PROBLEM_FLAGS if bit in flags_seen]
    if bad:
        warnings.append(f"{path}: {name}: its KF_UNIT_STATUS said {', '.join(bad)} status message(s)")
    from kinefuse.host.link.stats import statustext_line, statustexts
    warnings += [f"{path}: {statustext_line(e)}" for e in statustexts(ds, df.start_monotonic_ns)
                 if e["sysid"] == u["sysid"] and e["severity"] <= 4]    # WARNING or worse
    return Recording(t=t, acc=acc, gyr=gyr, mag=mag, fs=fs, source=path, fmt=FORMAT, metadata=meta,
                     warnings=warnings, mag_t=mag_t, mag_native=mag_native,
                     channels={"device_time_s": dev[idx] / 1e6, "sample_counter": counter,
                               "temperature_degC": temp, "flags": flags})
