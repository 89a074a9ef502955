"""The scalar-operation interface estimators are written against.

Estimator code uses ordinary arithmetic (``+ - * /``, unary ``-``, ``abs``, comparisons) plus the
functions of this module.  Called with Python floats it *is* the reference implementation
(float64); called with :class:`Sym` values (during tracing) the very same code records the typed
operation graph of :mod:`kinefuse.codegen.ir`.

Rules that keep both worlds identical:

* no Python ``if`` on values — use :func:`select` (both branches are evaluated);
* no ``math.*`` — use :func:`sqrt`, :func:`rsqrt`, :func:`fmin`, :func:`fmax`, :func:`clamp`;
  transcendental functions come from :mod:`kinefuse.codegen.mathlib` (written with these ops);
* logic with :func:`logical_and` / :func:`logical_or` / :func:`logical_not` (``~True`` is -2 in
  Python);
* :func:`assume` states a bound that holds mathematically but that interval arithmetic cannot prove
  (normalised vectors): the fixed-point path saturates there, the float paths ignore it;
* :func:`bound` is a clamp that only gives the range analysis finite bounds: the reference and
  the fixed-point path clamp, binary32 does not (nothing is emitted).
"""
from __future__ import annotations

import math
import os
import sys

from kinefuse.codegen.ir import BOOL, INT, INT32_MAX, REAL, Graph, Node

_CORE_FILES = {os.path.join(os.path.dirname(__file__), f)
               for f in ("scalar.py", "ir.py", "linalg.py", "estimator.py", "mathlib.py",
                         os.path.join("estimators", "dynamics", "ad.py"))}


def _loc() -> str:
    """file:line of the first caller outside the generator core and the dynamics filters'
    automatic differentiation (its dual numbers record every operation of a derivative): the
    reference line that asked for the operation, in the estimator or a shared reference module."""
    f = sys._getframe(2)
    while f is not None and f.f_code.co_filename in _CORE_FILES:
        f = f.f_back
    if f is None:
        return ""
    return f"{os.path.basename(f.f_code.co_filename)}:{f.f_lineno}"


class Sym:
    """A traced scalar: a node of the graph being recorded."""

    __slots__ = ("g", "n")

    def __init__(self, g: Graph, n: Node):
        self.g = g
        self.n = n

    @property
    def type(self) -> str:
        return self.n.type

    # -- helpers ------------------------------------------------------------------------
    def _lift(self, v) -> Node:
        if isinstance(v, Sym):
            if v.g is not self.g:
                raise ValueError("mixing values traced in different graphs")
            return v.n
        if isinstance(v, bool):
            return self.g.const(v, BOOL)
        if isinstance(v, (int, float)):
            if self.n.type == INT:
                return self.g.const(int(v), INT)
            return self.g.const(float(v), REAL)
        if hasattr(v, "dtype"):   # numpy scalar
            return self._lift(v.item())
        raise TypeError(f"cannot use {type(v).__name__} in a traced expression")

    def _op(self, op: str, *args, attrs: tuple = ()) -> "Sym":
        nodes = [self._lift(a) for a in args]
        return Sym(self.g, self.g.add(op, nodes, attrs=attrs, loc=_loc()))

    def _bin(self, op: str, a, b):
        """Operator methods: NotImplemented for a foreign operand type (e.g. a dual number
        holding Syms) so Python tries that type's reflected method; unsupported types still
        end in Python's TypeError."""
        for v in (a, b):
            if not isinstance(v, (Sym, bool, int, float)) and not hasattr(v, "dtype"):
                return NotImplemented
        return self._op(op, a, b)

    # -- arithmetic -----------------------------------------------------------------------
    def __add__(self, o): return self._bin("add", self, o)
    def __radd__(self, o): return self._bin("add", o, self)
    def __sub__(self, o): return self._bin("sub", self, o)
    def __rsub__(self, o): return self._bin("sub", o, self)
    def __mul__(self, o): return self._bin("mul", self, o)
    def __rmul__(self, o): return self._bin("mul", o, self)
    def __truediv__(self, o): return self._bin("div", self, o)
    def __rtruediv__(self, o): return self._bin("div", o, self)
    def __neg__(self): return self._op("neg", self)
    def __pos__(self): return self
    def __abs__(self): return self._op("abs", self)

    # -- comparisons (a > b is recorded as b < a: identical IEEE semantics, NaN included) ----
    def __lt__(self, o): return self._bin("lt", self, o)
    def __le__(self, o): return self._bin("le", self, o)
    def __gt__(self, o): return self._bin("lt", o, self)
    def __ge__(self, o): return self._bin("le", o, self)

    # -- logic ----------------------------------------------------------------------------
    def __and__(self, o): return self._bin("and", self, o)
    def __rand__(self, o): return self._bin("and", o, self)
    def __or__(self, o): return self._bin("or", self, o)
    def __ror__(self, o): return self._bin("or", o, self)
    def __invert__(self):
        # ~True is -2 (true) in the float64 reference: the C's !b would differ from it
        raise TypeError("~ on a traced value: use logical_not(b) (in Python ~True is -2)")

    def __bool__(self):
        raise TypeError("a traced value has no truth value while generating code (an if, "
                        "and/or/not, min()/max() or a chained comparison on it): use "
                        "select(cond, a, b), logical_and/or/not, fmin/fmax")

    def __float__(self):
        raise TypeError("a traced value cannot be converted to float while generating code")

    __hash__ = object.__hash__

    def __repr__(self):
        return f"Sym({self.n!r})"


def _first_sym(*vals):
    for v in vals:
        if isinstance(v, Sym):
            return v
    return None


# -- functions of the interface -----------------------------------------------------------

def sqrt(x):
    """Square root; the argument must be provably >= 0 (guard it with fmax(x, 0.0))."""
    if isinstance(x, Sym):
        return x._op("sqrt", x)
    return math.sqrt(x) if x >= 0.0 else math.nan


def rsqrt(x):
    """1 / sqrt(x); the argument must be provably > 0 (guard it with fmax(x, eps))."""
    if isinstance(x, Sym):
        return x._op("rsqrt", x)
    if x > 0.0:
        return 1.0 / math.sqrt(x)
    return math.inf if x == 0.0 else math.nan


def rnorm(xs, eps: float, split: bool = False, scale=None):
    """(1 / sqrt(max(|x|^2, eps)), |x|^2) for a vector x of 1 to 4 components: the scale that
    normalises x, and its squared norm.  Prefer it to rsqrt(sum of squares): the fixed-point path
    then keeps full precision for vectors of any length.

    scale: a value c >= 0 to return c / sqrt(max(|x|^2, eps)) instead (binary32 folds it into the
    division; fixed point keeps the dynamic binary point: kf_dyn_scale).
    split=True: for a norm on a filter's sample-to-sample dependency chain.  binary32 then
    computes sqrt(m) * (c/m) instead of c/sqrt(m): the square root and the division run side by
    side (one product more, ~1.5 instead of ~1 ulp); fixed point is unchanged."""
    xs = tuple(xs)
    sq = [c * c for c in xs]
    # pairwise: a quaternion's squared norm is two additions deep, not three (it lies on the
    # sample-to-sample dependency chain of every filter)
    n2 = sq[0] + sq[1] if len(sq) > 1 else sq[0]
    if len(sq) == 4:
        n2 = n2 + (sq[2] + sq[3])
    elif len(sq) == 3:
        n2 = n2 + sq[2]
    s = _first_sym(n2, *xs, *(() if scale is None else (scale,)))
    if s is not None:
        g = s.g
        args = [s._lift(n2)] + [s._lift(c) for c in xs]
        attrs = (float(eps),) + (("split",) if split else ())
        if scale is not None:
            args.append(s._lift(scale))
            attrs += ("scaled",)
        return Sym(g, g.add("rnorm", args, attrs=attrs, loc=_loc())), n2
    r = rsqrt(n2 if n2 > eps else eps)
    return (r if scale is None else scale * r), n2


FLOOR_LIMIT = float(2 ** 30)


def floor(x):
    """floor(x) for |x| <= 2^30; larger values are clamped there and NaN gives -2^30."""
    if isinstance(x, Sym):
        return x._op("floor", x)
    c = x if x > -FLOOR_LIMIT else -FLOOR_LIMIT
    c = c if c < FLOOR_LIMIT else FLOOR_LIMIT
    return float(math.floor(c))


def fabs(x):
    return abs(x)


def fmin(a, b):
    """``(a < b) ? a : b`` — returns b when a is NaN (so fmin(nan_value, limit) is finite)."""
    s = _first_sym(a, b)
    if s is not None:
        return s._op("min", a, b)
    return a if a < b else b


def fmax(a, b):
    """``(a > b) ? a : b`` — returns b when a is NaN."""
    s = _first_sym(a, b)
    if s is not None:
        return s._op("max", a, b)
    return a if a > b else b


def clamp(x, lo, hi):
    """Limit x to [lo, hi]; NaN becomes lo (fmax gives lo; identical in every number system)."""
    return fmin(fmax(x, lo), hi)


def select(cond, a, b):
    """``cond ? a : b`` (both a and b are computed)."""
    s = _first_sym(cond, a, b)
    if s is None:
        return a if cond else b
    if not isinstance(cond, Sym):
        return a if cond else b   # a constant condition selects at trace time
    if not isinstance(a, Sym) and not isinstance(b, Sym):
        t = INT if (isinstance(a, int) and not isinstance(a, bool)
                    and isinstance(b, int) and not isinstance(b, bool)) else REAL
        if isinstance(a, bool) and isinstance(b, bool):
            t = BOOL
        g = cond.g
        return Sym(g, g.add("select", [cond.n, g.const(a, t), g.const(b, t)], loc=_loc()))
    ref = a if isinstance(a, Sym) else b
    g = ref.g
    return Sym(g, g.add("select", [cond.n, ref._lift(a), ref._lift(b)], loc=_loc()))


def bound(x, lo: float, hi: float):
    """clamp(x, lo, hi) in the float64 reference and in fixed point (the same min/max nodes and
    fixed-point code as :func:`clamp`, marked ``bound``); the identity in binary32, where it
    costs nothing.

    For a clamp that exists only so that interval arithmetic sees finite bounds: x must lie in
    [lo, hi] (and not be NaN) for every sample whose result is used, in float64 and binary32,
    e.g. a convex combination of values already within the bounds.  binary32 then differs from
    the reference only where the clamp is active, so a bound that becomes active shows up as a
    binary32 deviation (codegen/tests/test_bound.py counts activations on the test data).  A
    clamp that acts on reachable values, or keeps NaN or inf out of binary32, stays ``clamp``."""
    if isinstance(lo, Sym) or isinstance(hi, Sym):
        raise TypeError("bound: lo and hi must be numbers (use clamp for traced limits)")
    if lo > hi:
        raise ValueError("bound: lo > hi")
    if isinstance(x, Sym):
        m = x._op("max", x, lo, attrs=("bound",))
        return m._op("min", m, hi, attrs=("bound",))
    if _BOUND_HOOK is not None:
        _BOUND_HOOK(x, lo, hi)
    return clamp(x, lo, hi)


#: called as hook(x, lo, hi) by every reference (float) evaluation of :func:`bound`; tests set
#: it to count activations (None: nothing is called)
_BOUND_HOOK = None


def assume(x, lo: float, hi: float):
    """x, which is known to lie in [lo, hi] (the fixed-point path saturates there)."""
    if lo > hi:
        raise ValueError("assume: lo > hi")
    if isinstance(x, Sym):
        return x._op("assume", x, attrs=(float(lo), float(hi)))
    return x


def logical_and(a, b):
    s = _first_sym(a, b)
    if s is not None:
        return s._op("and", a, b)
    return bool(a) and bool(b)


def logical_or(a, b):
    s = _first_sym(a, b)
    if s is not None:
        return s._op("or", a, b)
    return bool(a) or bool(b)


def logical_not(a):
    if isinstance(a, Sym):
        return a._op("not", a)
    return not a


def all_of(*conds):
    out = conds[0]
    for c in conds[1:]:
        out = logical_and(out, c)
    return out


def any_of(*conds):
    out = conds[0]
    for c in conds[1:]:
        out = logical_or(out, c)
    return out


def inc_if(counter, cond):
    """Saturating 32-bit counter increment: counter + 1 when cond holds."""
    if isinstance(counter, Sym) or isinstance(cond, Sym):
        s = _first_sym(counter, cond)
        g = s.g
        c = counter.n if isinstance(counter, Sym) else g.const(int(counter), INT)
        k = cond.n if isinstance(cond, Sym) else g.const(bool(cond), BOOL)
        return Sym(g, g.add("inc_if", [c, k], loc=_loc()))
    return min(counter + 1, INT32_MAX) if cond else counter


class when:
    """A conditional region: ``with when(cond): ...``.

    Operations recorded inside only run when cond holds (an ``if`` in the generated C and in the
    models); a value computed inside reads as 0 (false) when cond does not hold.  Use such values
    under their condition only, e.g. ``select(cond, inside_value, other)`` or ``cond & inside``:
    the float64 reference (plain Python) computes the region unconditionally.  Regions only change
    cost, never results.  They nest.
    """

    def __init__(self, cond):
        self.cond = cond
        self.g = cond.g if isinstance(cond, Sym) else None

    def __enter__(self):
        if self.g is not None:
            c = self.cond.n
            if self.g.guards:   # nested: the conjunction, computed in the outer region
                c = self.g.add("and", [self.g.guards[-1], c], loc=_loc())
            self.g.guards.append(c)
        return self

    def __exit__(self, *exc):
        if self.g is not None:
            self.g.guards.pop()
        return False


def is_traced(*vals) -> bool:
    return _first_sym(*vals) is not None
