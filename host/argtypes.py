"""argparse types for numeric options: a bad value is a one-line usage error before any work
("argument --runs: 0 is not 1 .. 100000"), never a traceback from deep inside a simulation."""
from __future__ import annotations

import argparse
import math


def integer(lo: int, hi: int | None = None):
    """An int in [lo, hi] (hi None: no upper bound)."""
    def parse(text: str) -> int:
        try:
            v = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
        if v < lo or (hi is not None and v > hi):
            raise argparse.ArgumentTypeError(f"{v} is not {lo} .. {hi}" if hi is not None
                                             else f"{v} is less than {lo}")
        return v
    parse.__name__ = "integer"      # argparse names the type in its messages
    return parse


#: random seeds (numpy's generators take non-negative integers)
seed = integer(0)


def real(lo: float, hi: float, *, lo_open: bool = False, hi_open: bool = False):
    """A finite float in the interval from lo to hi (open at either end on request)."""
    def parse(text: str) -> float:
        try:
            v = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
        ok = math.isfinite(v) and (v > lo if lo_open else v >= lo) and (v < hi if hi_open else v <= hi)
        if not ok:
            raise argparse.ArgumentTypeError(f"{text} is not in {'(' if lo_open else '['}{lo:g}, "
                                             f"{hi:g}{')' if hi_open else ']'}")
        return v
    parse.__name__ = "number"
    return parse
