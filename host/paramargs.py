"""``NAME=VALUE`` command-line assignments (``--param``, ``--range``): one parser, one-line errors.

The value is a float, or kept as text when it is not a number (a choice's label such as
``mode=6d``; the filter's declaration resolves and checks it, ``Estimator.resolve_params``).
Refused here: a missing ``=``, an empty name or value, a name given twice (which one would
win?), NaN and infinities.
"""
from __future__ import annotations

import math

from kinefuse.host.errors import KinefuseError


def parse_assignments(items: list[str] | None, option: str = "--param",
                      numbers_only: bool = False, form: str = "NAME=VALUE") -> dict[str, float | str]:
    """``["beta=0.1", "mode=6d"]`` -> ``{"beta": 0.1, "mode": "6d"}``.

    ``numbers_only``: a value that is not a number is an error (no labels); ``form``: how the
    error for a malformed item spells the expected shape."""
    out: dict[str, float | str] = {}
    for item in items or []:
        name, sep, text = item.partition("=")
        name, text = name.strip(), text.strip()
        if not sep or not name or not text:
            raise KinefuseError(f"{option} expects {form}, got {item!r}")
        if name in out:
            raise KinefuseError(f"{option} {name} given twice ({name}={out[name]!r} and {item!r}); "
                                f"give each name once")
        try:
            value: float | str = float(text)
        except ValueError:
            if numbers_only:
                raise KinefuseError(f"{option} {name}: {text!r} is not a number") from None
            value = text
        if isinstance(value, float) and not math.isfinite(value):
            raise KinefuseError(f"{option} {name}: value must be finite, got {text!r}")
        out[name] = value
    return out
