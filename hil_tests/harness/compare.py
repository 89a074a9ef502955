"""Bit-pattern comparison of loop outputs, with the first differing sample and its inputs.

Binary32 values are compared as their uint32 patterns, exactly: ``-0.0`` and ``+0.0`` are
*different* patterns, and so are NaNs with different sign or payload (x86 and ARM produce
different default NaNs; no generated filter outputs a NaN on purpose, so a NaN on both sides
must not pass as "equal" and a NaN only the platforms disagree on is a difference too);
Q-format raw integers, counters and flags as integers.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np



@dataclass
class Mismatch:
    """The first sample where two loops differ."""

    a: str
    b: str
    sample: int
    differing_samples: int
    samples: int
    fields: list[str]
    inputs: dict = field(default_factory=dict)
    out_a: dict = field(default_factory=dict)
    out_b: dict = field(default_factory=dict)

    def message(self) -> str:
        def fmt(d):
            return "; ".join(f"{k}={v}" for k, v in d.items())
        return (f"{self.a} != {self.b}: {self.differing_samples} of {self.samples} samples differ; "
                f"first at sample {self.sample} in {', '.join(self.fields)}\n"
                f"  inputs: {fmt(self.inputs)}\n  {self.a}: {fmt(self.out_a)}\n"
                f"  {self.b}: {fmt(self.out_b)}")

    def as_dict(self) -> dict:
        return {"a": self.a, "b": self.b, "sample": self.sample,
                "differing_samples": self.differing_samples, "samples": self.samples,
                "fields": self.fields, "inputs": self.inputs, "out_a": self.out_a,
                "out_b": self.out_b}


def bits(a) -> np.ndarray:
    """Comparable bit patterns: the exact pattern of binary32 / binary64 (every NaN payload and
    the sign of zero kept), integers and flags as int64."""
    a = np.asarray(a)
    if a.dtype == np.float32:
        return a.view(np.uint32).astype(np.int64)
    if a.dtype == np.float64:            # the reference: its own patterns, never truncated to int
        return np.ascontiguousarray(a).view(np.int64)
    if a.dtype.kind == "f":
        raise ValueError(f"bit-exact comparison needs binary32, binary64 or integer outputs, not {a.dtype}")
    return a.astype(np.int64)


def _show(v: np.ndarray) -> list:
    v = np.asarray(v).reshape(-1)
    if v.dtype == np.float32:
        return [f"{float(x)!r}/0x{int(b):08x}" for x, b in zip(v, v.view(np.uint32))]
    return v.tolist()


def differing(out_a: dict[str, np.ndarray], out_b: dict[str, np.ndarray]) -> tuple[np.ndarray, dict]:
    """(per-sample bool 'any output differs', per-field bool arrays)."""
    if set(out_a) != set(out_b):
        raise ValueError(f"outputs differ in names: {sorted(out_a)} vs {sorted(out_b)}")
    per = {}
    n = None
    for k in out_a:
        a, b = np.asarray(out_a[k]), np.asarray(out_b[k])
        n = len(a) if n is None else n
        if len(a) != len(b):
            raise ValueError(f"output {k}: {len(a)} vs {len(b)} samples")
        # explicit widths: reshape(n, -1) fails for 0 samples; (n,) and (n, 1) are the same output
        wa, wb = (int(np.prod(x.shape[1:], dtype=np.int64)) for x in (a, b))
        if wa != wb:
            raise ValueError(f"output {k}: {wa} vs {wb} values per sample")
        per[k] = np.any(bits(a).reshape(len(a), wa) != bits(b).reshape(len(b), wb), axis=1)
    any_ = np.zeros(n or 0, bool)
    for v in per.values():
        any_ |= v
    return any_, per


def compare(a: str, out_a: dict, b: str, out_b: dict, inputs: dict | None = None) -> Mismatch | None:
    """None when identical in every bit of every output of every sample, else the first
    mismatch (with the sample's inputs when given: host values as fed to the encoders)."""
    any_, per = differing(out_a, out_b)
    if len(any_) == 0:      # "identical" over nothing would pass any loop that produced nothing
        raise ValueError(f"{a} vs {b}: no samples (or no outputs) to compare")
    if not any_.any():
        return None
    i = int(np.argmax(any_))
    return Mismatch(a, b, i, int(any_.sum()), len(any_), [k for k, v in per.items() if v[i]],
                    {k: np.asarray(v[i]).reshape(-1).tolist() for k, v in (inputs or {}).items()},
                    {k: _show(v[i]) for k, v in out_a.items()},
                    {k: _show(v[i]) for k, v in out_b.items()})


def compare_all(outputs: dict[str, dict], inputs: dict | None = None) -> list[Mismatch]:
    """Every loop against the first one (the model); the mismatches found."""
    names = list(outputs)
    if not names:
        return []
    first = names[0]
    return [m for m in (compare(first, outputs[first], n, outputs[n], inputs) for n in names[1:])
            if m is not None]
