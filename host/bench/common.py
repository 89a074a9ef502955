"""Shared pieces of the benchmarks: data selection, progress display, quaternion deviation."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from kinefuse.host.errors import KinefuseError


def given(option: str, value: str | None, what: str) -> str | None:
    """An option's value, refused when given but empty or blank (``--filter ""`` from an unset
    shell variable silently meant the default); None (not given) stays None."""
    if value is not None and not value.strip():
        raise KinefuseError(f"{option} {value!r}: empty; give {what} (or leave the option out)")
    return value


def name_list(option: str, value: str | None, default, example: str) -> list[str]:
    """The comma-separated names of ``option`` (``default`` when not given), refused when they
    name nothing (``--parts ""`` measured nothing and exited 0)."""
    if value is None:
        return list(default)
    names = [n.strip() for n in value.split(",") if n.strip()]
    if not names:
        raise KinefuseError(f"{option} {value!r}: names nothing (comma-separated names, e.g. "
                            f"{example})")
    return names


def no_repeats(option: str, names: list[str]) -> list[str]:
    """``names`` unless one is given twice (it was run twice and listed once, or twice)."""
    twice = [n for k, n in enumerate(names) if n in names[:k]]
    if twice:
        raise KinefuseError(f"{option} names {twice[0]} twice")
    return names


def trial_files(data: str | None) -> tuple[list[Path], str]:
    """--data DIR|FILE, or the default (shared BROAD folder, else the bundled excerpt)."""
    from kinefuse.host import broad
    given("--data", data, "a BROAD folder or trial file")
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
    console = Console(stderr=True)
    # (not a terminal: the bar drew nothing but left an empty line on stderr, before a
    # command's one-line error too)
    return Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                    TimeElapsedColumn(), console=console,
                    disable=not enabled or not console.is_terminal, transient=True)


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
