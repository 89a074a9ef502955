"""Run an estimator in any of its implementations on arrays of samples.

* ``ref``       the estimator's Python code on float64 (the reference);
* ``f32-model`` / ``q-model``  the generated Python models (bit-exact with the C);
* ``f32`` / ``q``              the generated C, compiled on the host (cffi batch entry point).

Host values are float64 arrays.  Encoding to the number system (binary32 rounding, or Q-format
raw integers with round-half-away and saturation) happens once, here, and the same encoded
values feed the C and the model, so their outputs can be compared bit for bit.
"""
from __future__ import annotations

import dataclasses
import hashlib
import importlib
import importlib.util
import sys
from pathlib import Path

import numpy as np

from kinefuse.codegen import estimators
from kinefuse.codegen.estimator import generated_stem, run_reference
from kinefuse.codegen.runtime import q as qrt

IMPLS = ("ref", "f32", "q", "f32-model", "q-model")


@dataclasses.dataclass
class Encoded:
    """Inputs/params/state in a number system's storage values."""
    inputs: dict[str, np.ndarray]      # name -> (N, size) float32 / int64 / bool
    params: dict[str, object]          # name -> scalar
    n: int


_MODULE_DIGEST: dict[str, bytes] = {}


def current_module(modname: str):
    """``importlib.import_module``, reloaded when the module's file changed since this process
    loaded it (the models were regenerated): never the interface of the old generated code."""
    mod = sys.modules.get(modname) or importlib.import_module(modname)
    path = getattr(mod, "__file__", None)
    if path and Path(path).is_file():
        digest = hashlib.sha256(Path(path).read_bytes()).digest()
        if _MODULE_DIGEST.setdefault(modname, digest) != digest:
            # the bytecode cache validates by mtime (seconds) and size: a file regenerated in
            # the same second with the same size would reload the old code
            Path(importlib.util.cache_from_source(path)).unlink(missing_ok=True)
            mod = importlib.reload(mod)
            _MODULE_DIGEST[modname] = digest
    return mod


class ModelInfo:
    """Interface metadata of a generated filter (from its generated Python model)."""

    def __init__(self, name: str, system: str, mod=None):
        self.name, self.system = name, system
        if mod is None:
            try:
                mod = current_module("kinefuse.firmware.generated.models."
                                     + generated_stem(name, system))
            except ModuleNotFoundError as exc:
                raise RuntimeError(f"no generated model for {name} ({system}); run "
                                   "`kinefuse codegen`") from exc
        self.mod = mod
        self.fields = self.mod.FIELDS
        self.formats = getattr(self.mod, "FORMATS", {})

    def encode_values(self, kind: str, name: str, typ: str, values) -> np.ndarray:
        values = np.asarray(values)
        if typ == "bool":
            return values.astype(bool)
        if typ == "int":
            return values.astype(np.int64)
        if self.system == "f32":
            # beyond binary32's range a value becomes ±inf, as the C conversion gives (IEEE
            # annex F): intended for hostile-input tests, not worth a warning
            with np.errstate(over="ignore"):
                return values.astype(np.float64).astype(np.float32)
        frac, lo, hi = self.formats[f"{kind}.{name}"]
        return qrt.q_from_float_v(values.astype(np.float64), frac, lo, hi)

    def decode_values(self, kind: str, name: str, typ: str, values) -> np.ndarray:
        values = np.asarray(values)
        if typ != "real":
            return values
        if self.system == "f32":
            return values.astype(np.float32).astype(np.float64)
        frac = self.formats[f"{kind}.{name}"][0]
        return np.ldexp(values.astype(np.float64), -frac)

    def encode(self, inputs: dict[str, np.ndarray], params: dict[str, float]) -> Encoded:
        enc, n = {}, None
        for name, size, typ in self.fields["input"]:
            if name not in inputs:
                raise ValueError(f"{self.name}: missing input {name!r}")
            a = np.asarray(inputs[name])
            a = a.reshape(len(a), -1)
            if a.shape[1] != size:
                raise ValueError(f"{self.name}: input {name} needs {size} columns, got {a.shape[1]}")
            n = len(a) if n is None else n
            if len(a) != n:
                raise ValueError(f"{self.name}: inputs differ in length")
            enc[name] = self.encode_values("input", name, typ, a)
        prm = {}
        for name, size, typ in self.fields["param"]:
            prm[name] = self.encode_values("param", name, typ, [params[name]])[0]
        return Encoded(enc, prm, n or 0)

    def initial_state(self) -> dict[str, list]:
        out = {}
        for name, size, typ in self.fields["state"]:
            vals = self.encode_values("state", name, typ, list(self.mod.STATE_INIT[name]))
            out[name] = [v.item() if typ != "real" or self.system == "q" else v for v in vals]
        return out


class ModelRunner(ModelInfo):
    """The generated Python model."""

    def run_encoded(self, e: Encoded) -> dict[str, np.ndarray]:
        inputs = {k: [v[:, i] for i in range(v.shape[1])] for k, v in e.inputs.items()}
        params = {k: [v.item() if self.system == "q" else v] for k, v in e.params.items()}
        outs, _ = self.mod.run(inputs, params, self.initial_state(), e.n)
        res = {}
        for name, size, typ in self.fields["output"]:
            dt = np.float32 if (typ == "real" and self.system == "f32") else \
                bool if typ == "bool" else np.int64
            cols = [np.asarray(c, dtype=dt).reshape(-1) for c in outs[name]]
            res[name] = np.stack(cols, axis=1) if cols else np.zeros((e.n, 0), dt)
        return res


class CRunner(ModelInfo):
    """The generated C built on the host (one C call runs the whole recording)."""

    def __init__(self, name: str, system: str, mod=None, ffi_lib=None, input_spec: str | None = None):
        super().__init__(name, system, mod)
        if ffi_lib is None:
            from kinefuse.codegen.build import build_filter
            ffi_lib = build_filter(name, system)
            input_spec = estimators.get(name).inputs.name
        self.ffi, self.lib = ffi_lib
        self.P = generated_stem(name, system)
        self.in_type = f"kf_{input_spec}_input_{system}"

    def _dtype(self, ctype: str, kind: str) -> np.dtype:
        ffi = self.ffi
        names, formats, offsets = [], [], []
        for name, size, typ in self.fields[kind]:
            base = {"real": np.float32 if self.system == "f32" else np.int32,
                    "bool": np.uint8, "int": np.int32}[typ]
            names.append(name)
            formats.append((base, (size,)) if size > 1 else base)
            offsets.append(ffi.offsetof(ctype, name))
        return np.dtype({"names": names, "formats": formats, "offsets": offsets,
                         "itemsize": ffi.sizeof(ctype)})

    def run_encoded(self, e: Encoded) -> dict[str, np.ndarray]:
        call, collect = self.prepare(e)
        call()
        return collect()

    def prepare(self, e: Encoded):
        """(call, collect): `call()` runs the whole recording in one C call on records packed
        beforehand (what `kinefuse bench speed` times); `collect()` unpacks the outputs."""
        ffi, lib, P = self.ffi, self.lib, self.P
        in_dt = self._dtype(self.in_type, "input")
        out_dt = self._dtype(f"{P}_output", "output")
        rec = np.zeros(e.n, dtype=in_dt)
        for name, size, typ in self.fields["input"]:
            v = e.inputs[name]
            rec[name] = (v.reshape(e.n) if size == 1 else v).astype(in_dt[name].base)
        out = np.zeros(e.n, dtype=out_dt)
        params = ffi.new(f"{P}_params *")
        for name, size, typ in self.fields["param"]:
            setattr(params, name, e.params[name].item())
        state = ffi.new(f"{P}_state *")
        init, run_fn = getattr(lib, f"{P}_init"), getattr(lib, f"{P}_run")
        in_ptr = ffi.cast(f"{self.in_type} *", ffi.from_buffer(rec))
        out_ptr = ffi.cast(f"{P}_output *", ffi.from_buffer(out, require_writable=True))

        def call():
            status = init(state, params)
            if status != 0:
                raise ValueError(f"{self.name}: parameter {-status - 1} rejected by {P}_init")
            run_fn(state, in_ptr, out_ptr, e.n)

        def collect():
            res = {}
            for name, size, typ in self.fields["output"]:
                col = out[name].reshape(e.n, size)
                if typ == "real":
                    res[name] = col.astype(np.float32 if self.system == "f32" else np.int64)
                elif typ == "bool":
                    res[name] = col.astype(bool)
                else:
                    res[name] = col.astype(np.int64)
            return res

        call.keep = (rec, out, params, state)   # keep buffers alive with the closure
        return call, collect


_RUNNERS: dict[tuple[str, str, str], ModelInfo] = {}


def _generated_digest(name: str, system: str) -> str:
    """SHA-256 of the generated files a runner is made of: model, C source, every header."""
    from kinefuse.codegen.generate import GENERATED_DIR
    P = generated_stem(name, system)
    h = hashlib.sha256()
    for path in [GENERATED_DIR / "models" / f"{P}.py", GENERATED_DIR / f"{P}.c",
                 *sorted(GENERATED_DIR.glob("*.h"))]:
        h.update(path.name.encode() + b"\0")
        h.update(path.read_bytes() if path.is_file() else b"(missing)")
        h.update(b"\0")
    return h.hexdigest()


def runner(name: str, impl: str) -> ModelInfo:
    """Cached runner for impl in f32, q (C) or f32-model, q-model (per process, keyed on the
    generated files' content: regenerated code gets a new runner, not the old one)."""
    key = (name, impl, _generated_digest(name, impl.split("-")[0]))
    if key not in _RUNNERS:
        system = impl.split("-")[0]
        _RUNNERS[key] = (ModelRunner if impl.endswith("-model") else CRunner)(name, system)
    return _RUNNERS[key]


def run(name: str, impl: str, inputs: dict[str, np.ndarray], params: dict[str, float] | None = None,
        raw: bool = False) -> dict[str, np.ndarray]:
    """Run filter `name` in implementation `impl` over all samples.

    Returns output name -> (N, size) array: float64 host values, or (raw=True) the number
    system's own values (float32 / int64 raw) for bit-exact comparison."""
    est = estimators.get(name)
    prm = est.resolve_params(params)
    if impl == "ref":
        out, _ = run_reference(est, inputs, prm)
        return out
    if impl not in IMPLS:
        raise ValueError(f"unknown implementation {impl!r} (choose from {', '.join(IMPLS)})")
    r = runner(name, impl)
    e = r.encode(inputs, prm)
    out = r.run_encoded(e)
    if raw:
        return out
    return {name_: r.decode_values("output", name_, typ, out[name_])
            for name_, size, typ in r.fields["output"]}


def bits(a: np.ndarray) -> np.ndarray:
    """Comparable bit patterns: uint32 views of binary32 (every NaN payload and sign as it is:
    bit-exact means the same bits), ints as is."""
    a = np.asarray(a)
    if a.dtype == np.float32:
        return a.view(np.uint32).copy()
    return a.astype(np.int64)
