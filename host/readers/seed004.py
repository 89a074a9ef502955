"""Seed 004 Arduino serial CSV (Callejas-Cuervo et al., §4.3.1).

The capture system (Arduino Mega + two MPU-9150, fusion on the board) prints one line per
sample, comma-separated, in this order: elbow angle without filtering (RAW), after the UKF,
after the EKF — all in degrees.  The book gives no time column and no header; its protocols
run at 35 Hz (maximum 45 Hz per MPU).

Assumptions: no header (a first line without numbers is skipped as a header); time is
``index / fs`` with ``fs`` = 35 Hz unless given; angles outside ±360° are rejected.  There is
no raw IMU data in this format: the :class:`Recording` carries the three angle channels
``angle_raw_deg``, ``angle_ukf_deg``, ``angle_ekf_deg`` only.
"""
from __future__ import annotations

import numpy as np

from kinefuse.host.readers import table as T
from kinefuse.host.readers.recording import ReaderError, Recording

FORMAT = "seed004-arduino"
COLUMNS = ("angle_raw_deg", "angle_ukf_deg", "angle_ekf_deg")


def _is_number(s: str) -> bool:
    try:
        float(s)
        return True
    except ValueError:
        return False


def sniff_lines(lines: list[str]) -> bool:
    data = [l for l in lines if l.strip()]
    if not data:
        return False
    body = data[1:] if not all(_is_number(c) for c in data[0].split(",")) else data
    return bool(body) and all(len(l.split(",")) == 3 and all(_is_number(c) for c in l.split(","))
                              for l in body[:20])


def read(path: str, *, fs: float | None = None, **_) -> Recording:
    fs = 35.0 if fs is None else float(fs)
    if not (np.isfinite(fs) and fs > 0):   # inf made every time 0
        raise ReaderError(path, f"sampling rate must be a positive number, got {fs}")
    tab = T.read(path, has_header=False, sep=",")
    rows, lines = tab.rows, tab.lines
    if rows and not any(_is_number(c) for c in rows[0]):
        rows, lines = rows[1:], lines[1:]
    if not rows:
        raise ReaderError(path, "no data rows")
    out = np.empty((len(rows), 3))
    for k, (row, ln) in enumerate(zip(rows, lines)):
        if len(row) != 3:
            raise ReaderError(path, f"expected 3 comma-separated values (RAW, UKF, EKF), got {len(row)}",
                              int(ln))
        for j, cell in enumerate(row):
            try:
                out[k, j] = float(cell)
            except ValueError:
                raise ReaderError(path, f"{COLUMNS[j]}: {cell.strip()!r} is not a number", int(ln)) from None
            if not np.isfinite(out[k, j]) or abs(out[k, j]) > 360.0:
                raise ReaderError(path, f"{COLUMNS[j]} = {cell.strip()} is not an angle in degrees",
                                  int(ln))
    t = np.arange(len(out)) / fs
    return Recording(t=t, channels={c: out[:, j] for j, c in enumerate(COLUMNS)}, fs=fs,
                     source=path, fmt=FORMAT,
                     metadata={"time_base": f"index / {fs:g} Hz (the format has no time column)",
                               "units_in_file": {"angles": "deg"}})
