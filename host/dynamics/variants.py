"""Generate, build and run estimator *instances* that are not registered filters (the 24
benchmark variants of the double-pendulum EKF, the residual versions...).

The files are produced by the same generator as `kinefuse codegen` (trace → optimise → lower →
emit) into a content-addressed cache (``$KINEFUSE_CACHE`` or ``~/.cache/kinefuse``,
sub-directory ``dyn``), compiled with the same cffi build and host flags, and run through the
codegen runner's encoding, so a variant behaves exactly like a committed generated filter.
"""
from __future__ import annotations

import hashlib
import importlib.util
import os
import time
from pathlib import Path

import numpy as np

from kinefuse.codegen import runner as cg_runner
from kinefuse.codegen.build import build as cffi_build
from kinefuse.codegen.emit import Lowered, c_header, c_input_header, c_source, py_model
from kinefuse.codegen.estimator import Estimator, run_reference, trace
from kinefuse.codegen.passes import optimize
from kinefuse.codegen.runtime import RUNTIME_DIR


def cache_dir() -> Path:
    d = Path(os.environ.get("KINEFUSE_CACHE", Path.home() / ".cache" / "kinefuse")) / "dyn"
    d.mkdir(parents=True, exist_ok=True)
    return d


_LOWERED: dict[tuple[str, str], Lowered] = {}


def lowered(est: Estimator, system: str = "f32") -> Lowered:
    key = (est.name, system)
    if key not in _LOWERED:
        _LOWERED[key] = Lowered(est, optimize(trace(est)), system)
    return _LOWERED[key]


def render(est: Estimator, system: str = "f32") -> dict[str, str]:
    """File name -> text of the generated C (header, source, input header, runtime) and model."""
    lo = lowered(est, system)
    src = f"codegen/estimators/dynamics ({type(est).__name__} instance)"
    P = lo.prefix
    return {f"{P}.h": c_header(lo, src), f"{P}.c": c_source(lo, src),
            f"{P}.py": py_model(lo, src),
            f"kf_{est.inputs.name}_{system}.h": c_input_header(lo),
            "kf_fixed.h": (RUNTIME_DIR / "kf_fixed.h").read_text()}


def write(est: Estimator, system: str = "f32") -> Path:
    files = render(est, system)
    h = hashlib.sha256("".join(k + "\0" + v for k, v in sorted(files.items())).encode())
    d = cache_dir() / f"{est.name}_{system}_{h.hexdigest()[:16]}"
    if not d.exists():
        tmp = d.with_name(d.name + f".tmp{os.getpid()}")
        tmp.mkdir(parents=True, exist_ok=True)
        for k, v in files.items():
            (tmp / k).write_text(v)
        try:
            os.replace(tmp, d)
        except OSError:      # another process won the race
            pass
    return d


class VariantRunner(cg_runner.CRunner):
    """cg_runner.CRunner for an estimator instance built from the cache (``model=True``: its
    generated Python model instead of the C).  ``cflags`` replaces the host flags of the C
    build (tests build at -O0 to save compile time; the IEEE flags keep the results)."""

    def __init__(self, est: Estimator, system: str = "f32", model: bool = False,
                 cflags: list[str] | None = None):
        self.est = est
        self.name, self.system = est.name, system
        d = write(est, system)
        P = f"{est.name}_{system}"
        spec = importlib.util.spec_from_file_location(f"_kf_dyn_model_{d.name}", d / f"{P}.py")
        self.mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(self.mod)
        self.fields = self.mod.FIELDS
        self.formats = getattr(self.mod, "FORMATS", {})
        self.P = P
        self.in_type = f"kf_{est.inputs.name}_input_{system}"
        self.is_model = model
        if not model:
            t0 = time.perf_counter()
            headers = [d / f"kf_{est.inputs.name}_{system}.h", d / f"{P}.h"]
            self.ffi, self.lib = cffi_build(P, headers, [d / f"{P}.c"], include_dirs=[d],
                                            cflags=cflags)
            self.build_seconds = time.perf_counter() - t0

    def run_encoded(self, e):
        if self.is_model:
            return cg_runner.ModelRunner.run_encoded(self, e)
        return super().run_encoded(e)

    def run(self, inputs, params=None, raw: bool = False) -> dict[str, np.ndarray]:
        prm = self.est.resolve_params(params)
        e = self.encode(inputs, prm)
        out = self.run_encoded(e)
        if raw:
            return out
        return {n: self.decode_values("output", n, t, out[n]) for n, s, t in self.fields["output"]}

    def time_run(self, inputs, params=None, repeat: int = 5) -> float:
        """Best wall time (s) of one batch call over all samples (encoding excluded)."""
        prm = self.est.resolve_params(params)
        e = self.encode(inputs, prm)
        best = float("inf")
        for _ in range(repeat):
            t0 = time.perf_counter()
            self.run_encoded(e)
            best = min(best, time.perf_counter() - t0)
        return best


def run_ref(est: Estimator, inputs, params=None) -> tuple[dict[str, np.ndarray], float]:
    """(outputs, CPU seconds) of the float64 reference (the estimator's Python code)."""
    t0 = time.process_time()
    out, _ = run_reference(est, inputs, est.resolve_params(params))
    return out, time.process_time() - t0


__all__ = ["VariantRunner", "run_ref", "write", "render", "lowered", "cache_dir"]
