"""MATRIX IMU CSV export (layout from seed 002 Table 5.3; app v1.2.7, 100 Hz, ±8 g).

Header (first line containing ``acc_x``):
``dateTime, acc_x, acc_y, acc_z, gyr_x, gyr_y, gyr_z, bodySurface_temp, Ambient_temp,
hr_raw, hr, remarks`` — acc in g, gyr in °/s.

Assumptions (the seed does not state them; documented here):

* ``dateTime`` is day-first (``04/05/2023 09:16`` = 4 May 2023) and has *minute* resolution
  (a few rows carry seconds); it cannot time samples, so ``t = index / fs`` with the nominal
  rate ``fs`` (default 100 Hz, ``fs=`` to override) and the clock is used only to validate it:
  every sample's elapsed time must agree with its minute stamp within one minute, which
  catches a wrong rate or missing samples;
* 8191 is the "no reading" sentinel (seen in ``hr_raw``); it becomes NaN in auxiliary columns
  and is an error in sensor columns;
* temperatures and ``remarks`` appear on the first row only → metadata;
* the delimiter is sniffed (``,``, ``;`` or tab); with ``;`` a decimal comma is accepted.
"""
from __future__ import annotations

import datetime as _dt

import numpy as np

from kinefuse.host.readers import table as T
from kinefuse.host.readers.recording import (DEG, G, ReaderError, Recording, check_acc_units,
                                             check_finite_columns)

FORMAT = "matrix"
SENTINEL = 8191.0


def sniff(header_cells: list[str]) -> bool:
    low = [c.strip().lower() for c in header_cells]
    return "acc_x" in low and "datetime" in low


def _parse_clock(path: str, s: str, line: int) -> _dt.datetime:
    s = s.strip()
    for fmt in ("%d/%m/%Y %H:%M:%S", "%d/%m/%Y %H:%M", "%Y-%m-%d %H:%M:%S", "%Y-%m-%d %H:%M"):
        try:
            return _dt.datetime.strptime(s, fmt)
        except ValueError:
            continue
    raise ReaderError(path, f"dateTime {s!r} is not DD/MM/YYYY HH:MM[:SS]", line)


def read(path: str, *, fs: float | None = None, acc_range_g: float | None = 8.0, **_) -> Recording:
    fs = 100.0 if fs is None else float(fs)
    if not (np.isfinite(fs) and fs > 0):   # inf made every time 0
        raise ReaderError(path, f"sampling rate must be a positive number, got {fs}")
    tab = T.read(path, header_pred=sniff)
    lines = tab.lines
    names = ["acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"]
    data = tab.numeric([tab.col(c) for c in names])
    check_finite_columns(path, data, names, lines)
    if np.any(data == SENTINEL):
        r, c = map(int, np.argwhere(data == SENTINEL)[0])
        raise ReaderError(path, f"column {names[c]!r} holds the no-data sentinel 8191", int(lines[r]))
    acc_g, gyr_dps = data[:, :3], data[:, 3:]
    check_acc_units(path, acc_g, "g")
    warnings: list[str] = []
    if acc_range_g is not None:
        sat = np.abs(acc_g) >= 0.999 * acc_range_g
        if sat.any():
            warnings.append(f"{path}: {int(sat.any(axis=1).sum())} accelerometer sample(s) at the "
                            f"±{acc_range_g:g} g limit (saturated)")

    # --- time base from the nominal rate, validated against the minute clock
    n = len(data)
    t = np.arange(n) / fs
    ci = tab.col("dateTime")
    cache: dict = {}   # thousands of rows share one minute stamp
    clock = []
    for row, ln in zip(tab.rows, lines):
        key = row[ci].strip() if ci < len(row) else ""
        if key not in cache:
            cache[key] = _parse_clock(path, key, int(ln))
        clock.append(cache[key])
    c0 = clock[0]
    secs = np.array([(c - c0).total_seconds() for c in clock])
    back = np.diff(secs) < 0
    if back.any():
        k = int(np.argmax(back)) + 1
        raise ReaderError(path, f"dateTime goes backwards ({clock[k - 1]} -> {clock[k]})", int(lines[k]))
    has_sec = np.array([row[ci].count(":") == 2 for row in tab.rows])
    # a minute stamp places a sample within 60 s, a seconds stamp within 1 s; the first stamp's
    # resolution adds the same uncertainty to the start; 2 s tolerance for clock/rate drift
    slack = np.maximum(np.where(has_sec, 1.0, 60.0), 1.0 if has_sec[0] else 60.0) + 2.0
    off = t - secs
    bad = np.abs(off) > slack
    if bad.any():
        k = int(np.argmax(bad))
        raise ReaderError(path, f"sample {k + 1} is {t[k]:.1f} s after the first at {fs:g} Hz but "
                                f"the clock says {secs[k]:.0f} s: samples missing or the rate is "
                                f"not {fs:g} Hz (pass the right rate)", int(lines[k]))
    # every whole interior minute of the clock must hold fs·60 samples (± 5 %)
    minute = ((secs + c0.second) // 60).astype(int)
    counts = np.bincount(minute)
    meta = {"start_clock": c0.isoformat(), "units_in_file": {"acc": "g", "gyr": "deg/s"},
            "time_base": f"index / {fs:g} Hz (dateTime has minute resolution)"}
    if len(counts) > 2:
        interior = np.arange(1, len(counts) - 1)
        interior = interior[counts[interior] > 0]
        if len(interior):
            meta["fs_from_clock"] = float(np.median(counts[interior])) / 60.0
            dev = np.abs(counts[interior] / 60.0 - fs)
            worst = interior[int(np.argmax(dev))]
            if dev.max() > 0.05 * fs:
                k = int(np.argmax(minute == worst))
                raise ReaderError(path, f"the clock minute starting here holds {counts[worst]} samples, "
                                        f"not {60 * fs:g} ({fs:g} Hz): samples missing or the rate is "
                                        f"not {fs:g} Hz (pass the right rate)", int(lines[k]))
    channels = {}
    for name, key in (("bodySurface_temp", "body_surface_temp_C"), ("Ambient_temp", "ambient_temp_C"),
                      ("hr_raw", "hr_raw"), ("hr", "hr_bpm")):
        if tab.has(name):
            v = tab.numeric([tab.col(name)], allow_empty=True, sentinel=SENTINEL)[:, 0]
            if key.endswith("_C") and np.isfinite(v).sum() <= 1:
                meta[key] = float(v[np.isfinite(v)][0]) if np.isfinite(v).any() else None
            else:
                channels[key] = v
    if tab.has("remarks"):
        rj = tab.col("remarks")
        rem = [row[rj].strip() for row in tab.rows if rj < len(row) and row[rj].strip()]
        if rem:
            meta["remarks"] = rem
    return Recording(t=t, acc=acc_g * G, gyr=gyr_dps * DEG, channels=channels, fs=fs, source=path,
                     fmt=FORMAT, metadata=meta, warnings=warnings)
