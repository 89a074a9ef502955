"""Small helpers shared by the link commands (record, decode, export, stats, params, ports)."""
from __future__ import annotations

import contextlib
import json
import os
import sys


def console(json_mode: bool = False):
    """A rich console; on stderr when stdout carries the one JSON object."""
    from rich.console import Console
    return Console(stderr=json_mode, highlight=False)


def print_json(obj) -> None:
    """Exactly one JSON object on stdout."""
    sys.stdout.write(json.dumps(obj, sort_keys=True, default=_default) + "\n")
    sys.stdout.flush()


def _default(o):
    import numpy as np
    if isinstance(o, np.integer):
        return int(o)
    if isinstance(o, np.floating):
        return float(o)
    if isinstance(o, np.ndarray):
        return o.tolist()
    if isinstance(o, bytes):
        return o.hex()
    return str(o)


def check_distinct_ports(ports) -> None:
    """The same serial port or pty given twice (also as pty:PATH and PATH) is refused: two
    readers split its bytes between two streams, and each showed a third to two thirds of
    the samples lost.  ``fake:`` units and capture files (each read whole) may repeat."""
    from kinefuse.host.errors import KinefuseError
    seen: dict = {}
    for url in ports:
        if url.lower().startswith("fake:"):
            continue
        rest = url.partition(":")[2]
        path = next((p for p in (url, rest, rest.rpartition(":")[0]) if p and os.path.exists(p)), None)
        if path is not None and os.path.isfile(path):
            continue
        key = os.path.realpath(path) if path is not None else url
        if key in seen:
            raise KinefuseError(f"--port {url} is the connection of --port {seen[key]} again: give each "
                                f"port once (two readers would split its bytes, losing frames in both)")
        seen[key] = url


def first_unit(session, port: str, timeout: float) -> int:
    """The MAVLink system id of the first unit heard on ``session`` (its HEARTBEAT), or a
    one-line error: the connection ended (a capture file without a unit), or ``timeout`` s
    passed."""
    from kinefuse.host.errors import KinefuseError
    hb = session.wait_for(lambda f: f.msgid == 0 and f.sysid != 255, timeout=timeout)
    if hb is not None:
        return hb.sysid
    if session.reader.finished:     # it said "within 3 s" after a file had ended at once
        raise KinefuseError(f"{port} ended without a HEARTBEAT: no unit on that connection")
    raise KinefuseError(f"no HEARTBEAT on {port} within {timeout:g} s "
                        f"(unit off, wrong port or wrong baud rate?)")


RAW_RATE_MAX_HZ = 10_000   # the unit refuses message intervals below 100 us (firmware/app/kf_handle.c)


def check_unit_option(value, option: str = "--unit") -> None:
    """A blank unit option (``--unit "$UNSET"``) is refused: read as no option, the file's only
    unit was taken without a word."""
    from kinefuse.host.errors import KinefuseError
    if value is not None and not value.strip():
        raise KinefuseError(f"{option} is empty: give a unit (system) id such as 2, s1 or s1:2")


def check_raw_rate(rate, goes_with: str | None = None) -> None:
    """--rate (KF_RAW_SAMPLE, Hz) within what the unit accepts; ``goes_with`` names the option or
    action it needs when that is missing (None: it is present or not needed)."""
    from kinefuse.host.errors import KinefuseError
    if rate is None:
        return
    if goes_with is not None:
        raise KinefuseError(f"--rate goes with {goes_with}")
    if not 0 < rate <= RAW_RATE_MAX_HZ:   # NaN too
        raise KinefuseError(f"--rate must be in (0, {RAW_RATE_MAX_HZ}] Hz (the unit refuses faster "
                            f"rates), not {rate:g}")


def fmt_rate(x) -> str:
    return "-" if x is None else f"{x:,.1f}"


def fmt_bytes(n: int) -> str:
    for unit in ("B", "kB", "MB", "GB"):
        if n < 1000 or unit == "GB":
            return f"{n:.0f} {unit}" if unit == "B" else f"{n:.1f} {unit}"
        n /= 1000
    return f"{n} B"


@contextlib.contextmanager
def progress(con, description: str):
    """A progress bar on ``con`` (a terminal only; nothing when output is piped) for work that
    reports ``tick(fraction)``; also installed as the decoder's progress hook
    (:data:`kinefuse.host.link.frames.PROGRESS`), so code that decodes a recording deeper down
    (the .kfr reader of replay) moves the bar too."""
    from kinefuse.host.link import frames
    if not con.is_terminal:
        token = frames.PROGRESS.set(None)
        try:
            yield lambda fraction: None
        finally:
            frames.PROGRESS.reset(token)
        return
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn
    with Progress(TextColumn("{task.description}"), BarColumn(), TextColumn("{task.percentage:>3.0f}%"),
                  TimeElapsedColumn(), console=con, transient=True) as bar:
        task = bar.add_task(description, total=1.0)

        def tick(fraction: float) -> None:
            bar.update(task, completed=min(1.0, max(0.0, float(fraction))))
        token = frames.PROGRESS.set(tick)
        try:
            yield tick
        finally:
            frames.PROGRESS.reset(token)
