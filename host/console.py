"""Tables on the console: never cut.

rich squeezes a table into the console width and cuts what still does not fit with "…" — a
figure like 1,939 becomes "1,9…".  A file or pipe counts as 80 columns, so results redirected
to a log would be cut too.  `print_table` widens the console, only as far as needed, to the
narrowest layout that cuts nothing (long text cells may still wrap at spaces).
"""
from __future__ import annotations

import io

ELLIPSIS = "…"


def _probe(width: int):
    from rich.console import Console
    return Console(file=io.StringIO(), width=width, color_system=None, legacy_windows=False)


def _cuts(table, width: int) -> int:
    c = _probe(width)
    c.print(table)
    return c.file.getvalue().count(ELLIPSIS)


def fitting_width(table, width: int) -> int:
    """The smallest width >= `width` at which the table renders uncut."""
    from rich.measure import Measurement
    probe = _probe(width)
    widest = max(width, Measurement.get(probe, probe.options.update_width(1 << 16), table).maximum)
    uncut = _cuts(table, widest)        # "…" written by the caller itself, if any
    if _cuts(table, width) <= uncut:
        return width
    lo, hi = width, widest             # cut at lo, uncut at hi
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if _cuts(table, mid) <= uncut:
            hi = mid
        else:
            lo = mid
    return hi


def print_table(table, console=None) -> None:
    """Print a rich Table (or any renderable) without cutting any cell."""
    from rich.console import Console
    con = console if console is not None else Console()
    old = con.width
    con.width = fitting_width(table, old)
    try:
        con.print(table)
    finally:
        con.width = old
