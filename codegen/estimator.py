"""How an estimator is declared, traced and run as the float64 reference.

An estimator is a class with

* ``name`` and a docstring,
* ``inputs``: an :class:`InputSpec` (the per-sample input record; shared specs such as the IMU
  sample let the firmware feed any filter),
* ``params``: :class:`Param` (runtime settings with units, defaults and allowed ranges),
* ``state``: :class:`Var` (the filter state, with its physical range and initial value),
* ``outputs``: :class:`Var`,
* ``step(self, x, u, p)``: one filter step written with :mod:`kinefuse.codegen.scalar`.  ``x``,
  ``u`` and ``p`` give attribute access to state, inputs and parameters (a scalar for size-1
  variables, a tuple otherwise); it returns ``(next_state: dict, outputs: dict)``.

Ranges are part of the contract: they are what the fixed-point path derives its Q formats from,
and values outside an input's range are rejected by the filters.
"""
from __future__ import annotations

import dataclasses
import decimal
import math
import os
import sysconfig
import traceback
from types import SimpleNamespace
from typing import Any, ClassVar

import numpy as np

from kinefuse.codegen.ir import BOOL, INT, REAL, Graph
from kinefuse.codegen.scalar import Sym


def bound_text(v, upper: bool) -> str:
    """A range bound to 6 significant digits, rounded into the range (a max of 0.08726646 shown
    as 0.0872665 was a value the range check then refused); whole numbers as they are."""
    if isinstance(v, int):
        return str(v)
    if not math.isfinite(v) or float(f"{v:g}") == v:
        return f"{v:g}"
    d = decimal.Decimal(float(v))
    q = d.quantize(decimal.Decimal(1).scaleb(d.adjusted() - 5),
                   rounding=decimal.ROUND_FLOOR if upper else decimal.ROUND_CEILING)
    return f"{float(q):g}"


def range_text(lo, hi) -> str:
    return f"[{bound_text(lo, False)}, {bound_text(hi, True)}]"


@dataclasses.dataclass(frozen=True)
class Var:
    """A typed, ranged variable: a field of the input record, a state variable or an output."""
    name: str
    size: int = 1
    lo: float = -1.0
    hi: float = 1.0
    unit: str = ""
    doc: str = ""
    type: str = REAL
    init: Any = 0.0          # initial value (state only): scalar or tuple of `size`

    def init_values(self) -> tuple:
        v = self.init if isinstance(self.init, (tuple, list)) else (self.init,) * self.size
        if len(v) != self.size:
            raise ValueError(f"{self.name}: init has {len(v)} values, size is {self.size}")
        return tuple(v)


@dataclasses.dataclass(frozen=True)
class Param:
    """A runtime parameter with physical meaning.

    ``choices``: a switch or a count rather than a continuous setting (e.g. ``mode`` 0 = 6D,
    1 = 9D, read as ``p.mode > 0.5``): the only values allowed, whole numbers ``lo``, ``lo`` + 1,
    ..., ``hi`` (the unit's parameter table accepts exactly these, ``firmware/apptables.py``).
    ``labels``: optional names of the choices, same order (``--param mode=6d``)."""
    name: str
    default: float
    unit: str
    lo: float
    hi: float
    doc: str
    type: str = REAL
    choices: tuple[float, ...] = ()
    labels: tuple[str, ...] = ()

    def __post_init__(self):
        if self.choices:
            want = tuple(float(v) for v in range(int(self.lo), int(self.hi) + 1))
            if tuple(float(c) for c in self.choices) != want or self.lo != int(self.lo):
                raise ValueError(f"parameter {self.name}: choices must be the whole numbers "
                                 f"lo..hi ({self.lo:g}..{self.hi:g}), got {self.choices}")
            if self.default not in self.choices:
                raise ValueError(f"parameter {self.name}: default {self.default!r} is not a choice")
        if self.labels and len(self.labels) != len(self.choices):
            raise ValueError(f"parameter {self.name}: {len(self.labels)} labels for "
                             f"{len(self.choices)} choices")

    @classmethod
    def choice(cls, name: str, default: float, count: int, doc: str,
               labels: tuple[str, ...] = ()) -> "Param":
        """A switch (``count`` 2: 0 or 1) or a choice among 0 .. ``count`` - 1, unitless."""
        return cls(name, default, "", 0.0, float(count - 1), doc,
                   choices=tuple(float(i) for i in range(count)), labels=labels)

    def as_var(self) -> Var:
        return Var(self.name, 1, self.lo, self.hi, self.unit, self.doc, self.type, self.default)

    def choices_text(self) -> str:
        """'0 (6d), 1 (9d)' / '0, 1, 2'."""
        names = self.labels or ("",) * len(self.choices)
        return ", ".join(f"{c:g}" + (f" ({n})" if n else "") for c, n in zip(self.choices, names))

    def value(self, v, owner: str = "") -> float:
        """``v`` (a number, or one of ``labels``) checked against the declaration: finite, within
        [lo, hi] and, for a switch, one of ``choices``.  ValueError (one line) otherwise."""
        who = f"{owner}: parameter {self.name}" if owner else f"parameter {self.name}"
        if isinstance(v, str):
            text = v.strip()
            low = [s.lower() for s in self.labels]
            if text.lower() in low:
                return float(self.choices[low.index(text.lower())])
            try:
                v = float(text)
            except ValueError:
                raise ValueError(f"{who}={v!r} is not a number" + (
                    f" (choices: {self.choices_text()})" if self.choices else "")) from None
        if not isinstance(v, (int, float, np.integer, np.floating)):   # bool: 0 or 1
            raise ValueError(f"{who}={v!r} is not a number")
        v = float(v)
        if not math.isfinite(v):
            raise ValueError(f"{who}={v!r} is not finite")
        if self.choices:
            if v not in self.choices:
                raise ValueError(f"{who}={v:g} is not one of its choices {self.choices_text()}")
        elif not self.lo <= v <= self.hi:
            raise ValueError(f"{who}={v!r} outside {range_text(self.lo, self.hi)} {self.unit}".rstrip())
        return v


@dataclasses.dataclass(frozen=True)
class InputSpec:
    """The input record of one step.  Specs with the same name must be identical (they become one
    C struct that several filters share)."""
    name: str
    fields: tuple[Var, ...]
    doc: str = ""

    def field(self, name: str) -> Var:
        for f in self.fields:
            if f.name == name:
                return f
        raise KeyError(name)


class Estimator:
    """Base class of every estimator (see module docstring)."""

    name: ClassVar[str] = ""
    title: ClassVar[str] = ""
    inputs: ClassVar[InputSpec]
    params: ClassVar[tuple[Param, ...]] = ()
    state: ClassVar[tuple[Var, ...]] = ()
    outputs: ClassVar[tuple[Var, ...]] = ()
    # name -> {param: value}: published parameter sets users can ask for by name
    presets: ClassVar[dict[str, dict[str, float]]] = {}
    # number systems generated; an estimator that cannot run in fixed point says so here (and
    # documents why in its docstring)
    systems: ClassVar[tuple[str, ...]] = ("f32", "q")
    # True when an unusable accelerometer reading drops only the accelerometer (the sample is
    # counted as rejected and the gyroscope still propagates the orientation); False when any
    # bad gyroscope/accelerometer value holds the whole state
    gyro_only_on_bad_acc: ClassVar[bool] = False

    def step(self, x, u, p):  # pragma: no cover - abstract
        raise NotImplementedError

    # -- helpers ----------------------------------------------------------------------------
    @classmethod
    def param(cls, name: str) -> Param:
        for p in cls.params:
            if p.name == name:
                return p
        raise KeyError(name)

    @classmethod
    def default_params(cls) -> dict[str, float]:
        return {p.name: p.default for p in cls.params}

    @classmethod
    def resolve_params(cls, overrides: dict[str, float] | None = None,
                       preset: str | None = None) -> dict[str, float]:
        """Defaults, then a preset, then explicit overrides (an override wins over the preset);
        every value checked by :meth:`Param.value` (a label such as ``"6d"`` becomes its number)."""
        values = cls.default_params()
        if preset is not None:
            if preset not in cls.presets:
                raise ValueError(f"{cls.name} has no preset {preset!r} "
                                 f"(available: {', '.join(cls.presets) or 'none'})")
            unknown = [k for k in cls.presets[preset] if k not in values]
            if unknown:
                raise ValueError(f"{cls.name}: preset {preset!r} sets unknown parameter "
                                 f"{unknown[0]!r}")
            values.update(cls.presets[preset])
        for k, v in (overrides or {}).items():
            if k not in values:
                raise ValueError(f"{cls.name} has no parameter {k!r} "
                                 f"(parameters: {', '.join(values) or 'none'})")
            values[k] = v
        return {p.name: p.value(values[p.name], cls.name) for p in cls.params}


class _Fields(SimpleNamespace):
    """Attribute access to declared variables; a name that is not declared is an error that
    says what is declared (not SimpleNamespace's bare AttributeError)."""

    _what = "variable"

    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        raise AttributeError(f"no {self._what} named {name!r} is declared "
                             f"({self._what}s: {', '.join(vars(self)) or 'none'})")


_FIELDS = {w: type("_Fields", (_Fields,), {"_what": w})
           for w in ("variable", "input", "parameter", "state variable")}


def _ns(vars_: tuple[Var, ...], values: dict[str, tuple],
        what: str = "variable") -> SimpleNamespace:
    return _FIELDS[what](**{v.name: values[v.name][0] if v.size == 1 else tuple(values[v.name])
                            for v in vars_})


def _flatten(est_name: str, what: str, decl: tuple[Var, ...], got: dict) -> dict[str, tuple]:
    missing = [v.name for v in decl if v.name not in got]
    extra = [k for k in got if k not in {v.name for v in decl}]
    if missing or extra:
        raise ValueError(f"{est_name}.step: {what} mismatch (missing {missing}, unexpected {extra})")
    out = {}
    for v in decl:
        val = got[v.name]
        vals = tuple(val) if isinstance(val, (tuple, list)) else (val,)
        if len(vals) != v.size:
            raise ValueError(f"{est_name}.step: {what} {v.name} has {len(vals)} values, "
                             f"declared size {v.size}")
        out[v.name] = vals
    return out


def generated_stem(name: str, system: str) -> str:
    """File stem and C identifier prefix of a filter's generated code in one number system
    (registry names may contain '-', C identifiers and module names may not): angle-kf, q ->
    angle_kf_q."""
    return f"{name.replace('-', '_')}_{system}"


def trace(est: Estimator) -> Graph:
    """Record one step of `est` as a raw (unoptimised) graph."""
    from kinefuse.codegen.emit import check_declaration   # emit imports this module
    check_declaration(est)
    g = Graph(est.name)

    def leaves(kind, decl):
        return {v.name: tuple(Sym(g, g.input(kind, v.name, i, v.type)) for i in range(v.size))
                for v in decl}

    u = leaves("input", est.inputs.fields)
    p = leaves("param", tuple(p.as_var() for p in est.params))
    x = leaves("state", est.state)
    try:
        res = est.step(_ns(est.state, x, "state variable"), _ns(est.inputs.fields, u, "input"),
                       _ns(tuple(q.as_var() for q in est.params), p, "parameter"))
    except EstimatorError:
        raise
    except Exception as exc:
        # a rule of the reference code broken (an `if` on a value, math.*, ...): one line naming
        # the estimator, its source line and the rule, not a traceback from inside the generator
        raise EstimatorError(f"{est.name}: {_where(exc)}: {_rule(exc)}") from exc
    if not (isinstance(res, tuple) and len(res) == 2 and all(isinstance(r, dict) for r in res)):
        raise EstimatorError(f"{est.name}.step must return (next_state: dict, outputs: dict), "
                             f"not {type(res).__name__}")
    nx, y = res
    for kind, decl, got in (("state", est.state, nx), ("output", est.outputs, y)):
        flat = _flatten(est.name, kind, decl, got)
        for v in decl:
            for i, val in enumerate(flat[v.name]):
                g.set_result(kind, v.name, i,
                             _as_node(g, val, v.type, f"{est.name}.step: {kind} {v.name}"))
    g.check()
    return g


class EstimatorError(TypeError, ValueError):
    """The reference code of an estimator breaks a rule of the generator (codegen/scalar.py).
    A TypeError as the bare errors were, and a ValueError as the other generator errors."""


_GENERATOR_DIR = os.path.dirname(os.path.abspath(__file__))
_CORE = {os.path.join(_GENERATOR_DIR, f) for f in
         ("scalar.py", "ir.py", "linalg.py", "estimator.py", "mathlib.py")}
_PACKAGE_DIR = os.path.dirname(_GENERATOR_DIR) + os.sep     # kinefuse's own files count
_LIBRARY_DIRS = tuple({os.path.abspath(sysconfig.get_paths()[k]) + os.sep
                       for k in ("stdlib", "purelib", "platlib")})


def _where(exc: BaseException) -> str:
    """Source line of the estimator code that failed: ``path:line (code)``, and the line of
    step() itself when that is not the same (the failure is in a helper it called)."""
    user = mine = None
    for fs in traceback.extract_tb(exc.__traceback__):
        f = os.path.abspath(fs.filename)
        if f in _CORE or fs.filename.startswith("<") or (
                f.startswith(_LIBRARY_DIRS) and not f.startswith(_PACKAGE_DIR)):
            continue
        user = fs
        if mine is None:
            mine = fs            # the outermost: step()

    def show(fs):
        f = os.path.abspath(fs.filename)
        rel = f[len(_PACKAGE_DIR):] if f.startswith(_PACKAGE_DIR) else fs.filename
        code = (fs.line or "").strip()
        return f"{rel}:{fs.lineno}" + (f" ({code[:80]})" if code else "")

    if user is None:
        return "in step()"
    if mine is None or mine is user:
        return show(user)
    return f"{show(user)}, called from {show(mine)}"


def _rule(exc: BaseException) -> str:
    """The rule a tracing failure breaks, in the words of codegen/scalar.py."""
    msg = str(exc)
    if "cannot be converted to float" in msg:
        return ("no math.* or float() on traced values: use sqrt, rsqrt, rnorm, fabs, fmin, "
                "fmax, clamp, floor (kinefuse.codegen.scalar) and sin, cos, atan2, asin, acos, "
                "exp (kinefuse.codegen.mathlib)")
    if "ufunc" in msg or "numpy" in msg.lower():
        return ("no numpy functions on traced values: use the functions of "
                "kinefuse.codegen.scalar / mathlib / linalg (" + msg + ")")
    if "** or pow()" in msg:
        return "no ** on traced values: write x * x (or sqrt(...))"
    if "arguments, got int" in msg:
        return msg + " (int values are counters: inc_if, select and comparisons only)"
    if isinstance(exc, (TypeError, ValueError)):
        return msg
    return f"{type(exc).__name__}: {msg}"


def _as_node(g: Graph, val, type_: str, what: str):
    if isinstance(val, Sym):
        if val.type != type_:
            raise EstimatorError(f"{what}: declared {type_}, step returned {val.type}")
        return val.n
    if type_ == BOOL:
        return g.const(bool(val), BOOL)
    if type_ == INT:
        return g.const(int(val), INT)
    return g.const(float(val), REAL)


def initial_state(est: Estimator) -> dict[str, tuple]:
    return {v.name: v.init_values() for v in est.state}


def run_reference(est: Estimator, inputs: dict[str, np.ndarray], params: dict[str, float] | None = None,
                  state: dict[str, tuple] | None = None):
    """Run the estimator's Python code on Python floats (float64): the reference.

    inputs: field name -> array of shape (N,) or (N, size).  Returns (outputs, final_state) with
    outputs as field name -> array (N, size) (float64, or int64/bool for int/bool outputs).
    """
    prm = est.resolve_params(params)
    pvals = {k: (float(v),) for k, v in prm.items()}
    pns = _ns(tuple(q.as_var() for q in est.params), pvals, "parameter")
    cols = {}
    n = None
    for f in est.inputs.fields:
        a = np.asarray(inputs[f.name])
        a = a.reshape(len(a), -1)
        if a.shape[1] != f.size:
            raise ValueError(f"input {f.name}: expected {f.size} columns, got {a.shape[1]}")
        n = len(a) if n is None else n
        if len(a) != n:
            raise ValueError("inputs differ in length")
        conv = (lambda c: [bool(v) for v in c]) if f.type == BOOL else \
               (lambda c: [int(v) for v in c]) if f.type == INT else (lambda c: c.tolist())
        cols[f.name] = [conv(a[:, i].astype(np.float64) if f.type == REAL else a[:, i])
                        for i in range(f.size)]
    st = dict(state) if state is not None else initial_state(est)
    outs = {v.name: [[] for _ in range(v.size)] for v in est.outputs}
    in_fields = est.inputs.fields
    for k in range(n or 0):
        u = _FIELDS["input"](**{f.name: cols[f.name][0][k] if f.size == 1
                                else tuple(c[k] for c in cols[f.name]) for f in in_fields})
        nx, y = est.step(_ns(est.state, st, "state variable"), u, pns)
        st = _flatten(est.name, "state", est.state, nx)
        yf = _flatten(est.name, "output", est.outputs, y)
        for v in est.outputs:
            for i, val in enumerate(yf[v.name]):
                outs[v.name][i].append(val)
    dtype = {REAL: np.float64, INT: np.int64, BOOL: np.bool_}
    result = {v.name: np.array(outs[v.name], dtype=dtype[v.type]).T.reshape(n or 0, v.size)
              for v in est.outputs}
    return result, st


class Interface:
    """The declared interface of an estimator as the number systems see it."""

    def __init__(self, est: Estimator):
        self.est = est
        self.where = est.name

    def all_vars(self) -> list[tuple[str, Var]]:
        e = self.est
        return ([("input", v) for v in e.inputs.fields]
                + [("param", p.as_var()) for p in e.params]
                + [("state", v) for v in e.state]
                + [("output", v) for v in e.outputs])

    def leaf_ranges(self) -> dict[tuple[str, str], tuple[float, float]]:
        return {(k, v.name): (float(v.lo), float(v.hi)) for k, v in self.all_vars()
                if k != "output"}
