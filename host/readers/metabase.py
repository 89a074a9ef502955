"""MetaMotionR / MetaBase CSV (seed 001 §7.2, §8.5–8.6, Fig. 8.6).

Two layouts are accepted.

*Combined sheet* (seed 001 Fig. 8.6, one file per sensor unit, saved as CSV)::

    elapsed (s), x-axis (g), y-axis (g), z-axis (g), x-axis (deg/s), y-axis (deg/s),
    z-axis (deg/s), elapsed (s), x-axis (T), y-axis (T), z-axis (T), elapsed (s),
    temperature (C)

  Accelerometer and gyroscope share the first ``elapsed (s)`` column (100 Hz); the
  magnetometer (20 Hz) and thermometer (1 Hz) have their own ``elapsed (s)`` columns and
  their cells end early (blank below).

*Native MetaBase files*, one per sensor, header
  ``epoc (ms), timestamp (±hh:mm), elapsed (s), x-axis (<unit>), y-axis (…), z-axis (…)``
  with unit ``g``, ``deg/s`` or ``T``.  Give any one of them: siblings from the same session
  (file names that differ only in ``Accelerometer``/``Gyroscope``/``Magnetometer``) are found
  and merged, aligned on the ``epoc (ms)`` of their first samples (each file's ``elapsed (s)``
  starts at its own first sample).  Assumption: the file names follow MetaBase's
  ``<device>_<date>_<MAC>_<Sensor>_<rate>Hz_<fw>.csv`` pattern.

Units: acc g → m/s², gyro °/s → rad/s, mag T → µT.  The magnetometer is held onto the 100 Hz
time base (``mag``) and kept at its native rate (``mag_t``, ``mag_native``).  Acc and gyro
streams of different lengths are cut to the shorter (seed 001 ``revision_NAN``).  The gyroscope
value grid is checked against the configured range (``gyro_range_dps``, seed 001 saw ±2000 °/s
quantisation although ±500 °/s was configured).
"""
from __future__ import annotations

import glob
import os
import re

import numpy as np

from kinefuse.host.readers import table as T
from kinefuse.host.readers.recording import (DEG, G, ReaderError, Recording, check_acc_units,
                                             check_gyro_range, check_rate, check_time, zero_order_hold)

FORMAT = "metabase"
_SENSORS = ("Accelerometer", "Gyroscope", "Magnetometer")
#: rates of the seed-001 MetaMotionR recordings (a different rate is warned about)
RATE_HZ = 100.0
MAG_RATE_HZ = 20.0


def sniff(header_cells: list[str]) -> bool:
    low = [c.strip().lower() for c in header_cells]
    return "elapsed (s)" in low and any(c.startswith("x-axis (") for c in low)


def _axes(tab: T.Table, unit: str, start: int) -> list[int]:
    return [tab.col(f"{a}-axis ({unit})", start=start) for a in "xyz"]


def _check_mag_units(path: str, mag_T: np.ndarray) -> None:
    med = float(np.median(np.linalg.norm(mag_T, axis=1)))
    if med > 1e-2:
        raise ReaderError(path, f"magnetometer median magnitude is {med:.3g}: the header says "
                                f"tesla but the values look like µT or mG")


def _column_stream(path, tab, t_idx, val_idx, name):
    """Numeric stream whose cells may end early; returns (t, x, lines)."""
    idx = [t_idx] + val_idx
    arr = tab.numeric(idx, allow_empty=True)
    empty = tab.empty(idx)
    bad = ~empty & ~np.isfinite(arr)          # 'nan', 'inf', 1e400: a value, but not a finite one
    if bad.any():
        k, c = map(int, np.argwhere(bad)[0])
        raise ReaderError(path, f"{name}: column {tab.header[idx[c]]!r}: {arr[k, c]!r} is not a finite number",
                          int(tab.lines[k]))
    filled = ~empty.any(axis=1)
    partial = ~empty.all(axis=1) & ~filled
    if partial.any():
        k = int(np.argmax(partial))
        raise ReaderError(path, f"{name}: incomplete row (some axes empty)", int(tab.lines[k]))
    # once the stream ends it must not restart
    ends = np.flatnonzero(~filled)
    if len(ends) and filled[ends[0]:].any():
        k = ends[0] + int(np.argmax(filled[ends[0]:]))
        raise ReaderError(path, f"{name}: blank cell before more data", int(tab.lines[ends[0]]))
    n = int(filled.sum())
    return arr[:n, 0], arr[:n, 1:], tab.lines[:n]


def _read_combined(path: str, tab: T.Table, gyro_range_dps):
    warnings: list[str] = []
    e0 = tab.col("elapsed (s)")
    t, acc_g, ln = _column_stream(path, tab, e0, _axes(tab, "g", e0), "accelerometer")
    t2, gyr, _ = _column_stream(path, tab, e0, _axes(tab, "deg/s", e0), "gyroscope")
    n = min(len(t), len(t2))
    if len(t) != len(t2):
        warnings.append(f"{path}: accelerometer has {len(t)} and gyroscope {len(t2)} samples; "
                        f"cut to {n}")
    t, acc_g, gyr, ln = t[:n], acc_g[:n], gyr[:n], ln[:n]
    mag_t = mag = None
    low = [h.strip().lower() for h in tab.header]
    if "x-axis (t)" in low:
        jm = low.index("x-axis (t)")
        em = _time_column(path, tab, low, jm)
        mag_t, mag, mln = _column_stream(path, tab, em, _axes(tab, "T", em), "magnetometer")
        fsm, w = check_time(path, mag_t, mln, what="magnetometer elapsed (s)")
        warnings += w
        check_rate(path, fsm, (MAG_RATE_HZ,), "magnetometer", warnings)
    temp = None
    if "temperature (c)" in low:
        jt = low.index("temperature (c)")
        et = _time_column(path, tab, low, jt)
        tt, tv, _ = _column_stream(path, tab, et, [jt], "temperature")
        temp = (tt, tv[:, 0])
    return t, acc_g, gyr, ln, mag_t, mag, temp, warnings


def _time_column(path: str, tab: T.Table, low: list[str], j: int) -> int:
    """The ``elapsed (s)`` column that times column ``j``: the nearest one before it."""
    before = [i for i in range(j) if low[i] == "elapsed (s)"]
    if not before:
        raise ReaderError(path, f"column {tab.header[j]!r} has no 'elapsed (s)' column before it "
                                f"(each sensor's values follow their own time column)", 1 + len(tab.preamble))
    return before[-1]


def _siblings(path: str) -> dict:
    base = os.path.basename(path)
    for s in _SENSORS:
        if s in base:
            pre, post = base.split(s, 1)
            post_pat = re.sub(r"_[0-9.]+Hz", "_*Hz", post)
            found = {}
            for s2 in _SENSORS:
                hits = sorted(glob.glob(os.path.join(os.path.dirname(path) or ".",
                                                     glob.escape(pre) + s2 + post_pat)))
                if hits:
                    found[s2] = hits[0]
            found[s] = path
            return found
    return {}


def _read_native(path: str, tab: T.Table):
    """One native MetaBase file → (sensor, t, xyz, lines, start): ``start`` is the UNIX time
    in ms at which its ``elapsed (s)`` is 0, from its first ``epoc (ms)`` (None without one;
    kept in ms: differences of UNIX seconds lose a fraction of a microsecond)."""
    low = [h.strip().lower() for h in tab.header]
    e = tab.col("elapsed (s)")
    for unit, sensor in (("g", "Accelerometer"), ("deg/s", "Gyroscope"), ("t", "Magnetometer")):
        if f"x-axis ({unit})" in low:
            t, x, ln = _column_stream(path, tab, e, _axes(tab, unit if unit != "t" else "T", e), sensor)
            start = None
            if "epoc (ms)" in low and len(t):
                ep = tab.numeric([low.index("epoc (ms)")], allow_empty=True)[0, 0]
                if np.isfinite(ep):
                    start = ep - 1e3 * t[0]
            return sensor, t, x, ln, start
    raise ReaderError(path, "no x-axis (g), x-axis (deg/s) or x-axis (T) column", 1)


def _pair_by_time(path, t, acc_g, gyr, ln, tg, warnings):
    """Accelerometer and gyroscope samples paired by index, checked by time: a sample lost in
    the middle of one file shifted every later pair by a sample (the gyroscope's motion placed
    a period early or late, silently).  Where a pair is more than half a period apart, the
    samples are paired by nearest time instead and those without a partner dropped (warned):
    returns (t, acc, gyr, lines) then, else None."""
    m = min(len(t), len(tg))
    if m < 2:
        return None
    dt = float(np.median(np.diff(t)))
    if not dt > 0 or np.all(np.abs(tg[:m] - t[:m]) <= 0.5 * dt):
        return None     # index pairs hold (the longer file is cut at its end)
    j = np.clip(np.searchsorted(tg, t), 1, len(tg) - 1)
    j = np.where(np.abs(tg[j - 1] - t) <= np.abs(tg[j] - t), j - 1, j)
    ok = np.abs(tg[j] - t) <= 0.5 * dt
    idx = np.flatnonzero(ok)
    ok[idx[1:][j[idx][1:] == j[idx][:-1]]] = False      # each gyroscope sample once
    acc_only, gyr_only = int((~ok).sum()), len(tg) - int(ok.sum())
    warnings.append(f"{path}: accelerometer and gyroscope samples paired by time, not by index (samples "
                    f"lost inside a file): {acc_only} accelerometer and {gyr_only} gyroscope sample(s) "
                    f"without a partner dropped; first near elapsed {float(t[int(np.argmax(~ok))]):.3f} s"
                    if acc_only else
                    f"{path}: accelerometer and gyroscope samples paired by time, not by index (samples "
                    f"lost inside a file): {gyr_only} gyroscope sample(s) without a partner dropped")
    return t[ok], acc_g[ok], gyr[j[ok]], ln[ok]


def read(path: str, *, gyro_range_dps: float | None = None, **_) -> Recording:
    tab = T.read(path, header_pred=sniff)
    low = [h.strip().lower() for h in tab.header]
    warnings: list[str] = []
    meta: dict = {"units_in_file": {"acc": "g", "gyr": "deg/s", "mag": "T"}}
    if low.count("elapsed (s)") >= 2 or ("x-axis (g)" in low and "x-axis (deg/s)" in low):
        t, acc_g, gyr, ln, mag_t, mag, temp, w = _read_combined(path, tab, gyro_range_dps)
        warnings += w
        meta["layout"] = "combined sheet (seed 001 Fig. 8.6)"
    else:
        files = _siblings(path) or {"?": path}
        streams = {}
        for s, p in files.items():
            tb = tab if p == path else T.read(p, header_pred=sniff)
            sensor, ts, x, lns, start = _read_native(p, tb)
            streams[sensor] = (ts, x, lns, p, start)
        meta["layout"] = "native MetaBase files"
        meta["files"] = {k: v[3] for k, v in streams.items()}
        if "Accelerometer" not in streams or "Gyroscope" not in streams:
            raise ReaderError(path, "MetaBase session needs the Accelerometer and Gyroscope files "
                                    f"(found: {', '.join(streams) or 'none'})")
        t, acc_g, ln, pa, a_start = streams["Accelerometer"]
        t2, gyr, _, pg, g_start = streams["Gyroscope"]
        # the gyroscope's times on the accelerometer's elapsed (s), to check the pairing below
        tg = t2 + ((g_start - a_start) / 1e3 if a_start is not None and g_start is not None
                   else (t[0] - t2[0] if len(t) and len(t2) else 0.0))
        # Each file's elapsed (s) starts at its own first sample: the streams were paired by
        # index and the magnetometer held on as if all had started together, however far apart
        # their epoc (ms) said they started.  Aligned on epoc: a later-starting gyroscope drops
        # the accelerometer samples before its first (and vice versa); magnetometer times shift.
        if a_start is not None and g_start is not None and len(t) >= 2:
            dt_a = float(np.median(np.diff(t)))
            k = int(round((g_start - a_start) / 1e3 / dt_a)) if dt_a > 0 else 0
            if k:
                if k > 0:
                    t, acc_g, ln = t[k:], acc_g[k:], ln[k:]
                else:
                    gyr, tg = gyr[-k:], tg[-k:]
                warnings.append(f"{path}: the gyroscope file starts {abs(g_start - a_start):.0f} ms "
                                f"{'after' if k > 0 else 'before'} the accelerometer file (epoc (ms)): "
                                f"the first {abs(k)} {'accelerometer' if k > 0 else 'gyroscope'} sample(s) "
                                f"dropped to pair them")
                t2 = t2[:len(gyr)]
        paired = _pair_by_time(path, t, acc_g, gyr, ln, tg, warnings)
        if paired is not None:
            t, acc_g, gyr, ln = paired
            t2 = t
        n = min(len(t), len(t2))
        if len(t) != len(t2):
            warnings.append(f"{path}: accelerometer has {len(t)} and gyroscope {len(t2)} samples; "
                            f"cut to {n}")
        t, acc_g, gyr, ln = t[:n], acc_g[:n], gyr[:n], ln[:n]
        mag_t = mag = None
        if "Magnetometer" in streams:
            mag_t, mag, mln, pm, m_start = streams["Magnetometer"]
            if m_start is not None and a_start is not None:
                mag_t = mag_t + (m_start - a_start) / 1e3   # onto the accelerometer's elapsed (s)
            fsm, w = check_time(pm, mag_t, mln, what="magnetometer elapsed (s)")
            warnings += w
            check_rate(pm, fsm, (MAG_RATE_HZ,), "magnetometer", warnings)
        temp = None
    fs, w = check_time(path, t, ln, what="elapsed (s)")
    warnings += w
    check_rate(path, fs, (RATE_HZ,), "accelerometer/gyroscope", warnings)
    check_acc_units(path, acc_g, "g")
    meta.update(check_gyro_range(path, gyr, gyro_range_dps, warnings))
    rec = Recording(t=t, acc=acc_g * G, gyr=gyr * DEG, fs=fs, source=path, fmt=FORMAT,
                    metadata=meta, warnings=warnings)
    if mag is not None:
        _check_mag_units(path, mag)
        rec.mag_t = mag_t
        rec.mag_native = mag * 1e6
        rec.mag = zero_order_hold(mag_t, rec.mag_native, t)
        meta["mag_fs"] = 1.0 / float(np.median(np.diff(mag_t)))
    if temp is not None:
        meta["temperature_C"] = {"t": temp[0].tolist(), "value": temp[1].tolist()}
    return rec
