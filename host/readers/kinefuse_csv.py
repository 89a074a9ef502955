"""Plain kinefuse CSV: one row per sample, SI units in the column names.

Columns (``t_s`` required, the rest optional by group)::

    t_s, acc_x_mps2, acc_y_mps2, acc_z_mps2, gyr_x_radps, gyr_y_radps, gyr_z_radps,
    mag_x_uT, mag_y_uT, mag_z_uT, quat_w, quat_x, quat_y, quat_z

Lines starting with ``#`` before the header are comments (kept in ``metadata["comments"]``).
Used for simulated recordings, converted files and the examples in the documentation.
"""
from __future__ import annotations

import numpy as np

from kinefuse.host.readers import table as T
from kinefuse.host.readers.recording import (ReaderError, Recording, check_acc_units,
                                             check_finite, check_time)

FORMAT = "kinefuse-csv"
GROUPS = {
    "acc": ("acc_x_mps2", "acc_y_mps2", "acc_z_mps2"),
    "gyr": ("gyr_x_radps", "gyr_y_radps", "gyr_z_radps"),
    "mag": ("mag_x_uT", "mag_y_uT", "mag_z_uT"),
    "quat": ("quat_w", "quat_x", "quat_y", "quat_z"),
}


def sniff(header_cells: list[str]) -> bool:
    return bool(header_cells) and header_cells[0].strip() == "t_s"


def read(path: str, **_) -> Recording:
    tab = T.read(path, header_pred=sniff)
    t = tab.numeric([tab.col("t_s")])[:, 0]
    fs, warnings = check_time(path, t, tab.lines, what="t_s")
    rec = Recording(t=t, fs=fs, source=path, fmt=FORMAT, warnings=warnings,
                    metadata={"comments": [p.lstrip("# ") for p in tab.preamble if p]})
    for name, cols in GROUPS.items():
        present = [tab.has(c) for c in cols]
        if name != "quat" and not any(present):
            # e.g. gyr_x_dps: another unit in the name; read as "no gyroscope data" before
            other = [h for h in tab.header if h and h.startswith(f"{name}_x_")]
            if other:
                raise ReaderError(path, f"column {other[0]}: this format takes SI units in the column "
                                        f"names ({', '.join(cols)}); convert the values and rename "
                                        f"the columns", 1 + len(tab.preamble))
        if any(present) and not all(present):
            raise ReaderError(path, f"incomplete {name} columns (need all of {', '.join(cols)})",
                              1 + len(tab.preamble))
        if all(present):
            a = tab.numeric([tab.col(c) for c in cols])
            check_finite(path, a, name, tab.lines)
            setattr(rec, name, a)
    if rec.acc is not None:
        check_acc_units(path, rec.acc, "m/s^2")
    if rec.quat is not None:
        n = np.linalg.norm(rec.quat, axis=1)
        bad = np.abs(n - 1) > 0.01
        if bad.any():
            k = int(np.argmax(bad))
            raise ReaderError(path, f"quaternion norm {n[k]:.4f} is not 1", int(tab.lines[k]))
        rec.quat = rec.quat / n[:, None]
    known = {c for cols in GROUPS.values() for c in cols} | {"t_s"}
    for j, h in enumerate(tab.header):
        if h and h not in known:
            rec.channels[h] = tab.numeric([j], allow_empty=True)[:, 0]
    return rec


def write(path: str, rec: Recording, comments: list[str] | None = None) -> None:
    """Write a Recording (t, acc, gyr, mag, quat and 1-D channels) in this format."""
    cols = ["t_s"]
    data = [np.asarray(rec.t, float)[:, None]]
    for name, names in GROUPS.items():
        a = getattr(rec, name)
        if a is not None:
            cols += list(names)
            data.append(np.asarray(a, float))
    for k, v in rec.channels.items():
        v = np.asarray(v, float)
        if v.ndim == 1:
            cols.append(k)
            data.append(v[:, None])
    arr = np.hstack(data)
    with open(path, "w", encoding="utf-8") as f:
        for c in comments or []:
            f.write(f"# {c}\n")
        f.write(",".join(cols) + "\n")
        np.savetxt(f, arr, delimiter=",", fmt="%.9g")
