"""Generated filter C on an emulated Cortex-M: the batch program (fast path for full trials).

The committed ``firmware/generated/<name>_<system>.c`` is cross-compiled with the project's
flags (:mod:`kinefuse.firmware.targets`) around the semihosting batch driver
(:mod:`kinefuse.hil_tests.qemu.batch`): one input record in, one output record out, per sample,
with the filter state kept across records.  Records have the C struct layouts of the
generated headers; the program checks sizes and offsets at compile time (a negative array
size fails the build), so a layout assumption that does not hold cannot pass silently.

Parameters are compiled into the program as their number system's storage values (binary32
hex literals or Q-format integers), the same values the host runners pass, so outputs can be
compared bit for bit with the Python models.
"""
from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass

import numpy as np

from kinefuse.codegen import estimators
from kinefuse.codegen.estimator import generated_stem
from kinefuse.codegen.generate import GENERATED_DIR
from kinefuse.codegen.runner import Encoded, ModelInfo
from kinefuse.host.errors import KinefuseError

# GCC's variable tracking dominates the build of long generated functions (debug info only:
# the code is the same; see codegen/build.py)
NO_VTA = ["-fno-var-tracking-assignments"]

_BASE = {"f32": {"real": np.dtype("<f4"), "bool": np.dtype("u1"), "int": np.dtype("<i4")},
         "q": {"real": np.dtype("<i4"), "bool": np.dtype("u1"), "int": np.dtype("<i4")}}


def record_dtype(fields: list[tuple[str, int, str]], system: str) -> np.dtype:
    """numpy layout of a generated C struct (natural alignment, as on AAPCS and x86-64)."""
    base = _BASE[system]
    return np.dtype([(name, base[typ], (size,)) if size > 1 else (name, base[typ])
                     for name, size, typ in fields], align=True)


def _c_literal(system: str, typ: str, value) -> str:
    if typ == "bool":
        return "1u" if bool(value) else "0u"
    if typ == "int" or system == "q":
        v = int(value)
        if not -2 ** 31 <= v < 2 ** 31:
            raise KinefuseError(f"value {v} does not fit int32")
        return f"(int32_t){v}" if v != -2 ** 31 else "(int32_t)(-2147483647 - 1)"
    f = float(np.float32(value))
    if not np.isfinite(f):
        raise KinefuseError(f"non-finite parameter value {f}")
    return float.hex(f) + "f"


def _layout_checks(ctype: str, dt: np.dtype, tag: str) -> str:
    """C declarations that fail to compile unless the struct matches ``dt``."""
    lines = [f"typedef char kf_chk_{tag}_size[(sizeof({ctype}) == {dt.itemsize}u) ? 1 : -1];"]
    for name in dt.names:
        off = dt.fields[name][1]
        lines.append(f"typedef char kf_chk_{tag}_{name}[(offsetof({ctype}, {name}) == {off}u) ? 1 : -1];")
    return "\n".join(lines)


@dataclass
class FilterProgram:
    """A built batch program of one generated filter on one target."""

    name: str
    system: str
    target: str
    info: ModelInfo
    in_dtype: np.dtype
    out_dtype: np.dtype
    program: object            # kinefuse.hil_tests.qemu.batch.BatchProgram

    def run_encoded(self, e: Encoded, timeout: float = 600.0) -> dict[str, np.ndarray]:
        rec = np.zeros(e.n, dtype=self.in_dtype)
        for name, size, typ in self.info.fields["input"]:
            v = e.inputs[name]
            rec[name] = (v.reshape(e.n) if size == 1 else v).astype(self.in_dtype[name].base)
        raw = self.program.run(rec.tobytes(), timeout=timeout)
        out = np.frombuffer(raw, dtype=self.out_dtype)
        res = {}
        for name, size, typ in self.info.fields["output"]:
            col = out[name].reshape(e.n, size)
            if typ == "real":
                res[name] = col.astype(np.float32 if self.system == "f32" else np.int64)
            elif typ == "bool":
                res[name] = col.astype(bool)
            else:
                res[name] = col.astype(np.int64)
        return res


def build_filter_program(name: str, system: str, target: str, params: dict[str, object],
                         opt: str = "-O2") -> FilterProgram:
    """Cross-build the batch program of filter ``name`` in ``system`` for ``target``.

    ``params``: encoded parameter values (``Encoded.params``: float32 or int storage values).
    """
    est = estimators.get(name)
    info = ModelInfo(name, system)
    P = generated_stem(name, system)
    src = GENERATED_DIR / f"{P}.c"
    if not src.is_file():
        raise KinefuseError(f"{src} does not exist (filter {name} has no {system} build)")
    in_type = f"kf_{est.inputs.name}_input_{system}"
    in_dt = record_dtype(info.fields["input"], system)
    out_dt = record_dtype(info.fields["output"], system)
    sets = []
    for pname, size, typ in info.fields["param"]:
        vals = np.atleast_1d(np.asarray(params[pname]))
        if size == 1:
            sets.append(f"kf_p.{pname} = {_c_literal(system, typ, vals[0])};")
        else:
            sets += [f"kf_p.{pname}[{i}] = {_c_literal(system, typ, vals[i])};" for i in range(size)]
    prelude = "\n".join([
        "#include <stddef.h>",
        f'#include "{P}.h"',
        f"static {P}_state kf_st;",
        f"static {P}_params kf_p;",
        _layout_checks(in_type, in_dt, "in"),
        _layout_checks(f"{P}_output", out_dt, "out"),
    ])
    setup = "\n".join([f"{P}_default_params(&kf_p);", *sets,
                       f"if ({P}_init(&kf_st, &kf_p) != 0) {{ return 5; }}"])
    step = f"{P}_update(&kf_st, (const {in_type} *)kf_in, ({P}_output *)kf_out);"
    from kinefuse.hil_tests.qemu.batch import build_batch

    prog = build_batch([src], step, in_size=in_dt.itemsize, out_size=out_dt.itemsize,
                       target=target, include_dirs=[GENERATED_DIR], prelude=prelude, setup=setup,
                       opt=opt, extra_cflags=NO_VTA)
    return FilterProgram(name, system, target, info, in_dt, out_dt, prog)


_CACHE: dict[tuple, FilterProgram] = {}


def _sources_digest(name: str, system: str) -> str:
    """SHA-256 of what the program compiles: the filter's generated C and every header it may
    include (its own, the shared input record, kf_fixed.h)."""
    P = generated_stem(name, system)
    h = hashlib.sha256()
    for path in [GENERATED_DIR / f"{P}.c", *sorted(GENERATED_DIR.glob("*.h"))]:
        h.update(path.name.encode() + b"\0")
        h.update(path.read_bytes() if path.is_file() else b"(missing)")
        h.update(b"\0")
    return h.hexdigest()


def filter_program(name: str, system: str, target: str, params: dict[str, object]) -> FilterProgram:
    """Cached :func:`build_filter_program` (per process; builds are also cached on disk).

    Keyed on the content of the generated sources, so regenerated C (``kinefuse codegen`` in the
    same process, a test writing new code) is built anew, never answered by a stale program."""
    key = (name, system, target, tuple(sorted((k, repr(np.asarray(v).tolist()))
                                              for k, v in params.items())),
           _sources_digest(name, system))
    if key not in _CACHE:
        _CACHE[key] = build_filter_program(name, system, target, params)
    return _CACHE[key]


def c_identifier_ok(name: str) -> bool:
    return re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name) is not None
