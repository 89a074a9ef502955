"""Runs in pieces that carry the filter state across piece boundaries, and per-sample states.

A unit never sees a recording at once: samples arrive one by one (or in link-sized chunks),
so a filter's outputs must not depend on how the input is cut.  These helpers run the
reference, the Python models and the host C (one ``init``, then ``run`` per piece on the same
state struct) over arbitrary pieces, and expose the state after every sample.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

from kinefuse.codegen import estimators, runner as cg
from kinefuse.codegen.estimator import initial_state, run_reference
from kinefuse.hil_tests.harness.loops import encode, sample_count, system_of


def _pieces(n: int, cuts: Sequence[int]) -> list[tuple[int, int]]:
    edges = [0] + sorted({int(c) for c in cuts if 0 < int(c) < n}) + [n]
    return list(zip(edges[:-1], edges[1:]))


def _concat(parts: list[dict[str, np.ndarray]]) -> dict[str, np.ndarray]:
    return {k: np.concatenate([p[k] for p in parts], axis=0) for k in parts[0]}


def run_chunked(loop: str, name: str, inputs: dict, cuts: Sequence[int],
                params: dict | None = None) -> dict[str, np.ndarray]:
    """Outputs of ``loop`` (``ref``, ``f32-model``, ``q-model``, ``host-f32``, ``host-q``) over
    ``inputs`` cut at the sample indices ``cuts``, the state carried between pieces."""
    n = sample_count(name, inputs)
    pieces = _pieces(n, cuts)
    if loop == "ref":
        est = estimators.get(name)
        prm = est.resolve_params(params)
        st = initial_state(est)
        parts = []
        for a, b in pieces:
            out, st = run_reference(est, {k: np.asarray(v)[a:b] for k, v in inputs.items()}, prm, st)
            parts.append(out)
        return _concat(parts)
    system = system_of(loop)
    info, e = encode(name, system, inputs, params)
    if loop.endswith("-model"):
        mod = info.mod
        params_m = {k: [v.item() if system == "q" else v] for k, v in e.params.items()}
        state = info.initial_state()
        parts = []
        for a, b in pieces:
            ins = {k: [v[a:b, i] for i in range(v.shape[1])] for k, v in e.inputs.items()}
            outs, state = mod.run(ins, params_m, state, b - a)
            parts.append(_model_outputs(info, outs, b - a))
        return _concat(parts)
    if loop.startswith("host-"):
        return _host_chunked(name, system, e, pieces)
    raise ValueError(f"run_chunked does not support loop {loop!r}")


def _model_outputs(info, outs, n) -> dict[str, np.ndarray]:
    res = {}
    for name, size, typ in info.fields["output"]:
        dt = np.float32 if (typ == "real" and info.system == "f32") else \
            bool if typ == "bool" else np.int64
        cols = [np.asarray(c, dtype=dt).reshape(-1) for c in outs[name]]
        res[name] = np.stack(cols, axis=1) if cols else np.zeros((n, 0), dt)
    return res


def _host_chunked(name: str, system: str, e, pieces) -> dict[str, np.ndarray]:
    r = cg.runner(name, system)
    ffi, lib, P = r.ffi, r.lib, r.P
    in_dt = r._dtype(r.in_type, "input")
    out_dt = r._dtype(f"{P}_output", "output")
    rec = np.zeros(e.n, dtype=in_dt)
    for fname, size, typ in r.fields["input"]:
        v = e.inputs[fname]
        rec[fname] = (v.reshape(e.n) if size == 1 else v).astype(in_dt[fname].base)
    out = np.zeros(e.n, dtype=out_dt)
    params = ffi.new(f"{P}_params *")
    for pname, size, typ in r.fields["param"]:
        setattr(params, pname, e.params[pname].item())
    state = ffi.new(f"{P}_state *")
    if getattr(lib, f"{P}_init")(state, params) != 0:
        raise ValueError(f"{name}: parameters rejected by {P}_init")
    run_fn = getattr(lib, f"{P}_run")
    in_base = ffi.cast(f"{r.in_type} *", ffi.from_buffer(rec))
    out_base = ffi.cast(f"{P}_output *", ffi.from_buffer(out, require_writable=True))
    for a, b in pieces:
        run_fn(state, in_base + a, out_base + a, b - a)
    res = {}
    for fname, size, typ in r.fields["output"]:
        col = out[fname].reshape(e.n, size)
        res[fname] = (col.astype(np.float32 if system == "f32" else np.int64) if typ == "real"
                      else col.astype(bool) if typ == "bool" else col.astype(np.int64))
    return res


def host_states(name: str, system: str, inputs: dict, params: dict | None = None
                ) -> tuple[dict[str, np.ndarray], dict[str, np.ndarray]]:
    """(outputs, states): the host C run one ``update`` at a time, the state struct read after
    every sample.  States are storage values (float32 / Q raw int64 / int / bool), (N, size)."""
    sample_count(name, inputs)
    r = cg.runner(name, system)
    info, e = encode(name, system, inputs, params)
    ffi, lib, P = r.ffi, r.lib, r.P
    in_dt = r._dtype(r.in_type, "input")
    rec = np.zeros(e.n, dtype=in_dt)
    for fname, size, typ in r.fields["input"]:
        v = e.inputs[fname]
        rec[fname] = (v.reshape(e.n) if size == 1 else v).astype(in_dt[fname].base)
    out_dt = r._dtype(f"{P}_output", "output")
    out = np.zeros(e.n, dtype=out_dt)
    params_c = ffi.new(f"{P}_params *")
    for pname, size, typ in r.fields["param"]:
        setattr(params_c, pname, e.params[pname].item())
    state = ffi.new(f"{P}_state *")
    if getattr(lib, f"{P}_init")(state, params_c) != 0:
        raise ValueError(f"{name}: parameters rejected by {P}_init")
    update = getattr(lib, f"{P}_update")
    in_base = ffi.cast(f"{r.in_type} *", ffi.from_buffer(rec))
    out_base = ffi.cast(f"{P}_output *", ffi.from_buffer(out, require_writable=True))
    fields = r.fields["state"]
    states = {f: np.zeros((e.n, size), np.float32 if (typ == "real" and system == "f32")
                          else bool if typ == "bool" else np.int64)
              for f, size, typ in fields}
    for i in range(e.n):
        update(state, in_base + i, out_base + i)
        for f, size, typ in fields:
            v = getattr(state, f)
            states[f][i] = [v[j] for j in range(size)] if size > 1 else v
    outs = {}
    for fname, size, typ in r.fields["output"]:
        col = out[fname].reshape(e.n, size)
        outs[fname] = (col.astype(np.float32 if system == "f32" else np.int64) if typ == "real"
                       else col.astype(bool) if typ == "bool" else col.astype(np.int64))
    return outs, states


def reference_states(name: str, inputs: dict, params: dict | None = None) -> dict[str, np.ndarray]:
    """The float64 reference's state after every sample, (N, size) per state variable."""
    est = estimators.get(name)
    prm = est.resolve_params(params)
    st = initial_state(est)
    n = sample_count(name, inputs)
    rows = {v.name: np.zeros((n, v.size)) for v in est.state}
    for i in range(n):
        _, st = run_reference(est, {k: np.asarray(v)[i:i + 1] for k, v in inputs.items()}, prm, st)
        for v in est.state:
            rows[v.name][i] = [float(x) for x in st[v.name]]
    return rows
