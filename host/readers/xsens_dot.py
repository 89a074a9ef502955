"""Xsens DOT CSV export (layout from seed 002 Tables 5.2/17.1 and Annex G/H code).

Header (first line containing ``SampleTimeFine``; lines before it are kept as preamble):
``PacketCounter, SampleTimeFine, Quat_W, Quat_X, Quat_Y, Quat_Z, Acc_X, Acc_Y, Acc_Z,
Gyr_X, Gyr_Y, Gyr_Z`` — other export modes may add ``Euler_X/Y/Z`` (deg), ``FreeAcc_*``
(m/s²) or ``Mag_*`` (arbitrary units, normalised to the local field); they go to
``channels``.

Units: SampleTimeFine µs (uint32, wraps after 2³² µs ≈ 71.6 min — unwrapped here; 16 667 µs
per sample at 60 Hz); Acc m/s²; Gyr °/s (converted to rad/s); Quat (w,x,y,z) sensor → the
DOT's own earth frame, whose heading reference differs between units and power cycles
(seed 002 §6).

The first sample of an export can be all zero (seed-errata): a first row whose accelerometer
and gyroscope are exactly zero, or whose |acc| is below 1 m/s² while the recording's median is
near g, is dropped with a warning.
"""
from __future__ import annotations

import numpy as np

from kinefuse.host.readers import table as T
from kinefuse.host.readers.recording import (DEG, ReaderError, Recording, check_acc_units,
                                             check_finite, check_rate, check_time)

FORMAT = "xsens-dot"
#: output rates of the DOT recordings (seed 002: 60 Hz; the DOT also records at 120 Hz)
RATES_HZ = (60.0, 120.0)
ST_MAX = 2**32                       # SampleTimeFine is a uint32 microsecond counter


def sniff(header_cells: list[str]) -> bool:
    return any(c.strip().lower() == "sampletimefine" for c in header_cells)


def read(path: str, **_) -> Recording:
    tab = T.read(path, header_pred=sniff)
    lines = tab.lines
    st = tab.numeric([tab.col("SampleTimeFine")])[:, 0]
    warnings: list[str] = []
    acc = tab.numeric([tab.col(c) for c in ("Acc_X", "Acc_Y", "Acc_Z")]) if tab.has("Acc_X") else None
    gyr = tab.numeric([tab.col(c) for c in ("Gyr_X", "Gyr_Y", "Gyr_Z")]) if tab.has("Gyr_X") else None
    quat = (tab.numeric([tab.col(c) for c in ("Quat_W", "Quat_X", "Quat_Y", "Quat_Z")])
            if tab.has("Quat_W") else None)
    channels = {}
    for prefix, unit in (("Euler", "deg"), ("FreeAcc", "mps2"), ("Mag", "au")):
        if tab.has(f"{prefix}_X"):
            channels[f"{prefix.lower()}_{unit}"] = tab.numeric(
                [tab.col(f"{prefix}_{a}") for a in "XYZ"])
    if acc is None and gyr is None and quat is None:
        raise ReaderError(path, "no Acc_*, Gyr_* or Quat_* columns", 1 + len(tab.preamble))

    # --- the all-zero (or implausible) first sample
    keep = np.ones(len(st), dtype=bool)
    if len(st) > 2:
        # only the columns present: an orientation-only export (no Acc_*, Gyr_*) lost its first
        # sample, "empty", whatever it held
        present = [a for a in (acc, gyr) if a is not None] or [quat]
        zero_first = all(not np.any(a[0]) for a in present)
        if acc is not None and not zero_first:
            med = np.median(np.linalg.norm(acc[1:], axis=1))
            zero_first = np.linalg.norm(acc[0]) < 1.0 and med > 5.0
        if zero_first:
            keep[0] = False
            warnings.append(f"{path}: line {lines[0]}: first sample is empty (all-zero or "
                            f"|acc| < 1 m/s²) and was dropped")
    sel = np.flatnonzero(keep)
    st, lines = st[sel], lines[sel]
    acc = None if acc is None else acc[sel]
    gyr = None if gyr is None else gyr[sel]
    quat = None if quat is None else quat[sel]
    channels = {k: v[sel] for k, v in channels.items()}

    # --- time: unwrap the 32-bit microsecond counter
    check_finite(path, st, "SampleTimeFine", lines)
    bad = (st < 0) | (st >= ST_MAX) | (st != np.floor(st))
    if bad.any():
        k = int(np.argmax(bad))
        raise ReaderError(path, f"SampleTimeFine {st[k]:.10g} is not a 32-bit microsecond count "
                                f"(0 .. {ST_MAX - 1})", int(lines[k]))
    st = st.astype(np.int64)
    d = np.diff(st)
    wraps = d < -(2**31)
    # a wrap continues the clock (the step across it is a usual one); a fall by more than half
    # the range that lands far from that is the sensor restarting its clock: unwrapped, it
    # was a silent jump of up to 71 minutes forward ("a gap")
    usual = float(np.median(d[d > 0])) if np.any(d > 0) else 0.0
    restart = wraps & ((d + 2**32) > max(100 * usual, 60_000_000))   # a minute: a long gap may span a wrap
    if restart.any():
        k = int(np.argmax(restart)) + 1
        raise ReaderError(path, f"SampleTimeFine goes backwards ({st[k - 1]} -> {st[k]} us): not a wrap of the "
                                f"32-bit counter (the sensor restarted its clock?); give each part as its own file",
                          int(lines[k]))
    if wraps.any():
        st = st + np.concatenate([[0], np.cumsum(wraps)]) * (2**32)
        warnings.append(f"{path}: SampleTimeFine wrapped around {int(wraps.sum())} time(s) (unwrapped)")
    t = st / 1e6
    fs, w = check_time(path, t, lines, what="SampleTimeFine")
    warnings += w
    check_rate(path, fs, RATES_HZ, "sample", warnings)

    if acc is not None:
        check_finite(path, acc, "Acc", lines)
        check_acc_units(path, acc, "m/s^2")
    if gyr is not None:
        check_finite(path, gyr, "Gyr", lines)
        big = np.abs(gyr) > 2500.0
        if big.any():
            k = int(np.argmax(big.any(axis=1)))
            raise ReaderError(path, f"gyroscope value {gyr[k][big[k]][0]:.6g} °/s exceeds any DOT "
                                    f"range (±2000 °/s): wrong unit?", int(lines[k]))
        gyr = gyr * DEG
    if quat is not None:
        check_finite(path, quat, "Quat", lines)
        n = np.linalg.norm(quat, axis=1)
        bad = np.abs(n - 1.0) > 0.01
        if bad.any():
            k = int(np.argmax(bad))
            raise ReaderError(path, f"quaternion norm {n[k]:.4f} is not 1", int(lines[k]))
        quat = quat / n[:, None]
    return Recording(t=t, acc=acc, gyr=gyr, quat=quat, channels=channels, fs=fs, source=path,
                     fmt=FORMAT, warnings=warnings,
                     metadata={"preamble": tab.preamble, "units_in_file": {"acc": "m/s^2", "gyr": "deg/s",
                               "time": "us"}, "quat_frame": "Xsens DOT earth frame (unit-specific heading)"})
