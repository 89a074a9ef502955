"""A tiny statement language between the number systems and the target languages.

A number system (:mod:`kinefuse.codegen.float32`, :mod:`kinefuse.codegen.fixed`) lowers each
graph node to :class:`Assign` statements over the expressions below; the renderers here print
them as C99, as scalar Python (the per-sample model loop) or as vectorised numpy (input-only parts
of a step, computed for all samples at once).  Because C and both Python forms are printed from
the same statements, the models mirror the C one to one.

Value kinds (``Assign.kind``): ``f32`` binary32, ``i32``/``i64`` signed integers, ``bool``,
``dyn`` a (mantissa, exponent) pair of the fixed-point path.
"""
from __future__ import annotations

import dataclasses
from typing import Union

import numpy as np


# -- expressions -------------------------------------------------------------------------------

@dataclasses.dataclass(frozen=True)
class Var:
    name: str


@dataclasses.dataclass(frozen=True)
class F32:
    """A binary32 literal (the value must be exactly representable)."""
    value: float


@dataclasses.dataclass(frozen=True)
class Int:
    value: int


@dataclasses.dataclass(frozen=True)
class Bin:
    """Binary operation; Bin("*", Wide(a), b) of two int32 is rendered in C as kf_smull(a, b)."""
    op: str   # + - * / < <= == && ||
    a: "Expr"
    b: "Expr"


@dataclasses.dataclass(frozen=True)
class Un:
    op: str   # - !
    a: "Expr"


@dataclasses.dataclass(frozen=True)
class Sel:
    c: "Expr"
    a: "Expr"
    b: "Expr"


@dataclasses.dataclass(frozen=True)
class Call:
    """A runtime helper present in both languages (C: kf_fixed.h / libm; Python: runtime)."""
    fn: str
    args: tuple


@dataclasses.dataclass(frozen=True)
class Wide:
    """Widen to int64 (C cast; no-op in Python)."""
    a: "Expr"


@dataclasses.dataclass(frozen=True)
class Narrow:
    """Narrow an int64 known to fit to int32 (C cast; no-op in Python)."""
    a: "Expr"


@dataclasses.dataclass(frozen=True)
class Shl:
    """a * 2**k for k >= 0 on int64 (written as a multiplication in C: no UB for negative a)."""
    a: "Expr"
    k: int


@dataclasses.dataclass(frozen=True)
class RshRound:
    """floor((a + 2**(k-1)) / 2**k), k >= 1: rounding right shift (round half up)."""
    a: "Expr"
    k: int


@dataclasses.dataclass(frozen=True)
class Field:
    """Member access of a dyn value: .m (mantissa) or .e (exponent)."""
    a: "Expr"
    name: str


@dataclasses.dataclass(frozen=True)
class Rsh:
    """floor(a / 2**k), k >= 1: arithmetic right shift."""
    a: "Expr"
    k: int


@dataclasses.dataclass(frozen=True)
class ToI32:
    """binary32 -> int32, truncating toward zero (the value is known to fit)."""
    a: "Expr"


@dataclasses.dataclass(frozen=True)
class ToF32:
    """int32 -> binary32 (round to nearest even)."""
    a: "Expr"


Expr = Union[Var, F32, Int, Bin, Un, Sel, Call, Wide, Narrow, Shl, RshRound, Field, Rsh,
             ToI32, ToF32]


@dataclasses.dataclass(frozen=True)
class Assign:
    name: str
    kind: str          # f32 | i32 | i64 | bool | dyn
    expr: Expr
    comment: str = ""


# -- C ------------------------------------------------------------------------------------------

C_TYPES = {"f32": "float", "i32": "int32_t", "i64": "int64_t", "bool": "int", "dyn": "kf_dyn"}


def f32_hex(value: float) -> str:
    """Exact binary32 literal: hex float with an f suffix (decimal would round twice)."""
    v = float(np.float32(value))
    if v != v:
        return "(0.0f / 0.0f)"
    if v in (float("inf"), float("-inf")):
        return ("-" if v < 0 else "") + "(1.0f / 0.0f)"
    if v == 0.0:
        return "-0.0f" if str(v).startswith("-") else "0.0f"
    mant, exp = v.hex().split("p")
    mant = mant.rstrip("0").rstrip(".")       # 0x1.8000000000000 -> 0x1.8, 0x1.0000000000000 -> 0x1
    return f"{mant}p{exp}f"


def c_int(v: int) -> str:
    if -(2 ** 31) < v < 2 ** 31:
        return str(v)
    return f"INT64_C({v})"


def render_c(e: Expr) -> str:
    if isinstance(e, Var):
        return e.name
    if isinstance(e, F32):
        return f32_hex(e.value)
    if isinstance(e, Int):
        return c_int(e.value)
    if isinstance(e, Bin):
        if e.op == "*" and isinstance(e.a, Wide):   # int32 x int32 -> int64 (kf_fixed.h)
            return f"kf_smull({render_c(e.a.a)}, {render_c(e.b)})"
        return f"({render_c(e.a)} {e.op} {render_c(e.b)})"
    if isinstance(e, Un):
        return f"({e.op}{render_c(e.a)})"
    if isinstance(e, Sel):
        return f"({render_c(e.c)} ? {render_c(e.a)} : {render_c(e.b)})"
    if isinstance(e, Call):
        return f"{e.fn}({', '.join(render_c(a) for a in e.args)})"
    if isinstance(e, Wide):
        return f"((int64_t){render_c(e.a)})"
    if isinstance(e, Narrow):
        return f"((int32_t){render_c(e.a)})"
    if isinstance(e, Shl):
        return render_c(e.a) if e.k == 0 else f"({render_c(e.a)} * {c_int(1 << e.k)})"
    if isinstance(e, RshRound):
        return f"(({render_c(e.a)} + {c_int(1 << (e.k - 1))}) >> {e.k})"
    if isinstance(e, Field):
        return f"{render_c(e.a)}.{e.name}"
    if isinstance(e, Rsh):
        return f"({render_c(e.a)} >> {e.k})"
    if isinstance(e, ToI32):
        return f"((int32_t){render_c(e.a)})"
    if isinstance(e, ToF32):
        return f"((float){render_c(e.a)})"
    raise TypeError(e)


def render_c_assign(s: Assign, indent: str = "    ", declare: bool = True) -> str:
    lhs = f"const {C_TYPES[s.kind]} {s.name}" if declare else s.name
    line = f"{indent}{lhs} = {render_c(s.expr)};"
    if s.comment:
        line += f"  /* {s.comment} */"
    return line


C_ZERO = {"f32": "0.0f", "i32": "0", "i64": "0", "bool": "0", "dyn": "{0, 0}"}


def expr_names(e) -> set[str]:
    """Names of the variables an expression reads."""
    if isinstance(e, Var):
        return {e.name}
    out: set[str] = set()
    for f in dataclasses.fields(e):
        v = getattr(e, f.name)
        if isinstance(v, tuple):
            for x in v:
                if not isinstance(x, (int, float, str)):
                    out |= expr_names(x)
        elif not isinstance(v, (int, float, str)) and v is not None:
            out |= expr_names(v)
    return out


def blocks(items):
    """Group (guard_name | None, [Assign]) items into maximal runs with the same guard:
    [(guard, [Assign, ...]), ...]."""
    out: list[tuple[str | None, list[Assign]]] = []
    for guard, stmts in items:
        if out and out[-1][0] == guard:
            out[-1][1].extend(stmts)
        else:
            out.append((guard, list(stmts)))
    return out


def escaping(blks, extra_refs: set[str]) -> set[str]:
    """Names assigned inside a guarded block and read outside it (or in extra_refs)."""
    all_reads = [set().union(*(expr_names(s.expr) for s in st)) if st else set() for _, st in blks]
    out: set[str] = set()
    for i, (guard, st) in enumerate(blks):
        if guard is None:
            continue
        assigned = {s.name for s in st}
        outside = set(extra_refs)
        for j, r in enumerate(all_reads):
            if j != i:
                outside |= r
        out |= assigned & outside
    return out


# -- Python -------------------------------------------------------------------------------------

PY_C_OPS = {"&&": "and", "||": "or"}


def render_py(e: Expr, vector: bool = False, consts: dict | None = None) -> str:
    """Python text of an expression.  Scalars: numpy float32 / Python int values.  vector=True:
    numpy arrays (every sample at once).  consts collects binary32 literals (name -> value) that
    the model binds once, so the loop does not rebuild them."""
    r = lambda x: render_py(x, vector, consts)  # noqa: E731
    if isinstance(e, Var):
        return e.name
    if isinstance(e, F32):
        v = float(np.float32(e.value))
        key = "K_" + (v.hex().replace("-", "m").replace(".", "_").replace("+", "p")
                      if v == v else "nan")
        if consts is not None:
            consts[key] = v
        return key
    if isinstance(e, Int):
        return str(e.value)
    if isinstance(e, Bin):
        op = e.op
        if op in PY_C_OPS:
            op = ("&" if op == "&&" else "|") if vector else PY_C_OPS[op]
        return f"({r(e.a)} {op} {r(e.b)})"
    if isinstance(e, Un):
        if e.op == "!":
            return f"(~{r(e.a)})" if vector else f"(not {r(e.a)})"
        return f"({e.op}{r(e.a)})"
    if isinstance(e, Sel):
        if vector:
            return f"_where({r(e.c)}, {r(e.a)}, {r(e.b)})"
        return f"({r(e.a)} if {r(e.c)} else {r(e.b)})"
    if isinstance(e, Call):
        fn = e.fn + ("_v" if vector else "")
        return f"rt.{fn}({', '.join(r(a) for a in e.args)})"
    if isinstance(e, (Wide, Narrow)):
        return r(e.a)
    if isinstance(e, Shl):
        return r(e.a) if e.k == 0 else f"({r(e.a)} << {e.k})"
    if isinstance(e, RshRound):
        return f"(({r(e.a)} + {1 << (e.k - 1)}) >> {e.k})"
    if isinstance(e, Field):
        return f"{r(e.a)}[{0 if e.name == 'm' else 1}]"
    if isinstance(e, Rsh):
        return f"({r(e.a)} >> {e.k})"
    if isinstance(e, ToI32):
        return f"{r(e.a)}.astype(np.int32)" if vector else f"int({r(e.a)})"
    if isinstance(e, ToF32):
        return f"{r(e.a)}.astype(np.float32)" if vector else f"F({r(e.a)})"
    raise TypeError(e)


def render_py_assign(s: Assign, vector: bool = False, consts: dict | None = None,
                     indent: str = "") -> str:
    e = s.expr
    if not vector and isinstance(e, Call) and e.fn == "kf_sat":
        # kf_sat inline (a call per saturation is the model's main cost); same semantics
        v, lo, hi = (render_py(x, False, consts) for x in e.args)
        return (f"{indent}{s.name} = {v}\n"
                f"{indent}{s.name} = {lo} if {s.name} < {lo} else ({hi} if {s.name} > {hi} "
                f"else {s.name})")
    return f"{indent}{s.name} = {render_py(e, vector, consts)}"
