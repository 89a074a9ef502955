"""Forward-mode automatic differentiation over the scalar interface (tagged dual numbers).

A :class:`Dual` holds a value and a tuple of tangents (one per seeded direction).  Value and
tangents are whatever the scalar interface computes with: Python floats (the float64
reference), traced :class:`~kinefuse.codegen.scalar.Sym` values (code generation), or other
Duals (nested differentiation).  So the same model code yields its derivatives in the
reference, in the generated C and in the models, with no hand-typed derivative anywhere.

Why forward mode on scalars rather than symbolic differentiation of the traced graph: the
reference must run on floats (it *is* the Python code), and the derivative must be computed
by that same code; dual numbers do exactly that, and in the traced world they simply record
the derivative operations into the graph, where constant folding, CSE and dead-code removal
clean them up.

Structural zeros: an absent tangent is :data:`kinefuse.codegen.linalg.ZERO`; products and
sums skip it, so seeding direction j as ``(ZERO, ..., 1.0, ..., ZERO)`` costs nothing for
the other directions, and multiplications by the seed 1.0 are folded by the optimiser.

Nesting: every Dual carries a *tag* (a level).  An operation between Duals of different tags
treats the lower-tagged one as a constant of the higher-tagged one, and the higher-tagged
Dual stays on top.  Seeding an inner differentiation with a fresh, higher tag while the values
are outer Duals therefore computes mixed higher derivatives without perturbation confusion.
"""
from __future__ import annotations

import itertools

from kinefuse.codegen import mathlib
from kinefuse.codegen.linalg import ZERO, sadd, smul, ssub

_tags = itertools.count(1)


def new_tag() -> int:
    """A fresh tag, higher than every tag issued before (use one per differentiation level)."""
    return next(_tags)


def _neg(a):
    return ZERO if a is ZERO else -a


class Dual:
    """value + sum_i tangent_i * eps_i (eps_i eps_j = 0), at nesting level `tag`."""

    __slots__ = ("v", "d", "tag")

    def __init__(self, v, d, tag: int):
        self.v = v
        self.d = tuple(d)
        self.tag = tag

    # -- helpers -------------------------------------------------------------------------
    def _split(self, o):
        """(this level's value/tangents of o, or None when o is a constant at this level)."""
        if isinstance(o, Dual) and o.tag == self.tag:
            return o
        return None

    def _defer(self, o):
        """True when o is a Dual of a higher level: let o's operation run on top."""
        return isinstance(o, Dual) and o.tag > self.tag

    # -- arithmetic ----------------------------------------------------------------------
    def __add__(self, o):
        if self._defer(o):
            return o.__radd__(self)
        b = self._split(o)
        if b is None:
            return Dual(self.v + o, self.d, self.tag)
        return Dual(self.v + b.v, (sadd(x, y) for x, y in zip(self.d, b.d)), self.tag)

    def __radd__(self, o):
        if self._defer(o):
            return o.__add__(self)
        b = self._split(o)
        if b is None:
            return Dual(o + self.v, self.d, self.tag)
        return b.__add__(self)

    def __sub__(self, o):
        if self._defer(o):
            return o.__rsub__(self)
        b = self._split(o)
        if b is None:
            return Dual(self.v - o, self.d, self.tag)
        return Dual(self.v - b.v, (ssub(x, y) for x, y in zip(self.d, b.d)), self.tag)

    def __rsub__(self, o):
        if self._defer(o):
            return o.__sub__(self)
        b = self._split(o)
        if b is None:
            return Dual(o - self.v, (_neg(x) for x in self.d), self.tag)
        return b.__sub__(self)

    def __mul__(self, o):
        if o is ZERO:
            return ZERO
        if self._defer(o):
            return o.__rmul__(self)
        b = self._split(o)
        if b is None:
            return Dual(self.v * o, (smul(x, o) for x in self.d), self.tag)
        return Dual(self.v * b.v,
                    (sadd(smul(x, b.v), smul(self.v, y)) for x, y in zip(self.d, b.d)),
                    self.tag)

    def __rmul__(self, o):
        if o is ZERO:
            return ZERO
        if self._defer(o):
            return o.__mul__(self)
        b = self._split(o)
        if b is None:
            return Dual(o * self.v, (smul(o, x) for x in self.d), self.tag)
        return b.__mul__(self)

    def __truediv__(self, o):
        if self._defer(o):
            return o.__rtruediv__(self)
        b = self._split(o)
        if b is None:
            inv = 1.0 / o
            return Dual(self.v * inv, (smul(x, inv) for x in self.d), self.tag)
        inv = 1.0 / b.v
        v = self.v * inv
        # (a/b)' = (a' - (a/b) b') / b
        return Dual(v, (smul(ssub(x, smul(v, y)), inv) for x, y in zip(self.d, b.d)),
                    self.tag)

    def __rtruediv__(self, o):
        if self._defer(o):
            return o.__truediv__(self)
        b = self._split(o)
        if b is not None:
            return b.__truediv__(self)
        inv = 1.0 / self.v
        v = o * inv
        return Dual(v, (_neg(smul(smul(v, x), inv)) for x in self.d), self.tag)

    def __neg__(self):
        return Dual(-self.v, (_neg(x) for x in self.d), self.tag)

    def __pos__(self):
        return self

    def __repr__(self):
        return f"Dual[{self.tag}]({self.v!r}, {self.d!r})"

    def __bool__(self):
        raise TypeError("a Dual has no truth value (use select on its .v)")


# -- functions ------------------------------------------------------------------------------

def sincos(x):
    """(sin x, cos x) for floats, Syms and Duals (derivatives cos x, -sin x)."""
    if isinstance(x, Dual):
        s, c = sincos(x.v)
        return (Dual(s, (smul(c, t) for t in x.d), x.tag),
                Dual(c, (_neg(smul(s, t)) for t in x.d), x.tag))
    return mathlib.sincos(x)


def value(x, tag: int | None = None):
    """The value part of x at level `tag` (x itself when it is not a Dual of that level)."""
    if isinstance(x, Dual) and (tag is None or x.tag == tag):
        return x.v
    return x


def tangent(x, i: int, tag: int):
    """Tangent i of x at level `tag` (ZERO when x does not depend on that level)."""
    if isinstance(x, Dual) and x.tag == tag:
        return x.d[i]
    if isinstance(x, Dual) and x.tag > tag:
        raise ValueError("tangent of a lower level requested under a higher-level Dual")
    return ZERO


def seed(values, tag: int, directions=None):
    """Duals of `values` at level `tag`.  Default: direction i is the unit vector of value i
    (a Jacobian with respect to all of them).  `directions`: explicit tangent lists."""
    values = list(values)
    n = len(values)
    if directions is None:
        return [Dual(v, tuple(1.0 if j == i else ZERO for j in range(n)), tag)
                for i, v in enumerate(values)]
    return [Dual(v, tuple(d), tag) for v, d in zip(values, directions)]


def jacobian(fn, x, *args):
    """(f(x), J) with J[i][j] = d f_i / d x_j, by one forward pass with len(x) directions."""
    tag = new_tag()
    xs = seed(x, tag)
    ys = fn(xs, *args)
    vals = [value(y, tag) for y in ys]
    jac = [[tangent(y, j, tag) for j in range(len(xs))] for y in ys]
    return vals, jac


__all__ = ["Dual", "new_tag", "seed", "value", "tangent", "sincos", "jacobian"]
