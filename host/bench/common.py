"""Shared pieces of the benchmarks: data selection, progress display, quaternion deviation."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from kinefuse.host.errors import KinefuseError


def trial_files(data: str | None) -> tuple[list[Path], str]:
    """--data DIR|FILE, or the default (shared BROAD folder, else the bundled excerpt)."""
    from kinefuse.host import broad
    if data is None:
        files, where = broad.default_data()
    else:
        files, where = broad.find_trials(data), str(data)
    if not files:
        raise KinefuseError(f"no trials found in {where}")
    return files, where


def progress(enabled: bool = True):
    """A rich progress bar on stderr (a no-op when stderr is not a terminal and not forced)."""
    from rich.console import Console
    from rich.progress import (BarColumn, MofNCompleteColumn, Progress, TextColumn,
                               TimeElapsedColumn)
    return Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                    TimeElapsedColumn(), console=Console(stderr=True), disable=not enabled,
                    transient=True)


def quat_angle_deg(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Rotation angle between orientations a and b (N,4), degrees, accurate near zero:
    2 atan2(|v|, |w|) of a* ⊗ b."""
    a = np.asarray(a, float)
    b = np.asarray(b, float)
    aw, ax, ay, az = a.T
    bw, bx, by, bz = b.T
    w = aw * bw + ax * bx + ay * by + az * bz
    x = aw * bx - ax * bw - ay * bz + az * by
    y = aw * by + ax * bz - ay * bw - az * bx
    z = aw * bz - ax * by + ay * bx - az * bw
    return np.degrees(2.0 * np.arctan2(np.sqrt(x * x + y * y + z * z), np.abs(w)))


def eprint(*a):
    print(*a, file=sys.stderr)
