"""The fixed-point number system: Q formats chosen by range analysis, int32 storage, int64
intermediates, helpers from kf_fixed.h (mirrored in runtime/q.py).

How formats are chosen
1. Real intervals: every leaf has a declared range (inputs, parameters, state); intervals are
   propagated through the graph (x*x is known to be >= 0; a divisor or rsqrt argument whose
   interval touches 0, or a sqrt argument that may be negative, is a generator error naming the
   estimator line: guard it).  ``assume(x, lo, hi)`` narrows the interval of x itself.
2. Fractional bits: the largest f with max|interval| * 2^f within int32 (a 2^-12 margin).
   Sample inputs get one extra bit of headroom beyond their declared range, so out-of-range
   samples stay representable and are rejected by the filters rather than silently clipped.
3. Integer verification: the exact integer image of every operation is propagated through the
   chosen formats (all operations are monotone).  Where a raw value could leave +-(2^31-1) the
   operation saturates (kf_sat); int64 intermediates are checked against 2^63.  This, not step 1,
   is the proof that the generated C has no overflow.

Reciprocal square roots have a dynamic binary point (kf_dyn): their range (1/sqrt of a value near
0) is too wide for one static format; the product with a normalised result keeps full precision.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np

from kinefuse.codegen.ir import BOOL, INT, REAL, Graph, Node
from kinefuse.codegen.render import (Assign, Bin, Call, Int, Narrow, Rsh, RshRound, Sel, Shl, Un,
                                     Var, Wide)
from kinefuse.codegen.runtime import q as qrt

NAME = "q"
TITLE = "fixed point: int32 Q formats per variable, int64 intermediates, round half up"

RAW_MAX = 2 ** 31 - 1
I64_MAX = 2 ** 63 - 1
FRAC_MAX = 60          # finest format of any value
FRAC_MIN = -30         # coarsest
MARGIN = 1.0 + 2.0 ** -12


class RangeError(ValueError):
    """The estimator needs a guard: an interval could not be bounded."""


def frac_for(r: float) -> int:
    """Largest f with r * 2^f (plus margin) within int32."""
    if r == 0.0:
        return 30
    if not math.isfinite(r):
        raise RangeError("unbounded range")
    if r * MARGIN * 2.0 ** FRAC_MAX <= RAW_MAX:    # tiny ranges (even subnormal) take the cap
        return FRAC_MAX
    f = int(math.floor(math.log2(RAW_MAX / (r * MARGIN))))
    while r * MARGIN * 2.0 ** f > RAW_MAX:
        f -= 1
    while r * MARGIN * 2.0 ** (f + 1) <= RAW_MAX:
        f += 1
    return max(FRAC_MIN, min(FRAC_MAX, f))


def input_frac(lo: float, hi: float) -> int:
    """Format of a sample input: its declared range plus one bit of headroom."""
    return frac_for(2.0 * max(abs(lo), abs(hi)))


def q_name(f: int) -> str:
    """Q notation: Qm.f with m integer bits (excluding sign) = 31 - f."""
    return f"Q{31 - f}.{f}"


@dataclasses.dataclass
class Fmt:
    frac: int
    lo: int            # raw bounds that hold for the value (after saturation, if any)
    hi: int
    sat: bool = False  # the operation producing it saturates to [lo, hi]
    dyn: bool = False  # kf_dyn value (rsqrt)


def _ival_mul(a, b):
    c = [a[0] * b[0], a[0] * b[1], a[1] * b[0], a[1] * b[1]]
    c = [0.0 if x != x else x for x in c]   # 0 * inf
    return (min(c), max(c))


def _raw_of(x: float, f: int) -> int:
    return int(qrt.q_from_float(x, f, -RAW_MAX, RAW_MAX))


class FixedPlan:
    """Formats of every real value of one graph, with the proof obligations discharged."""

    def __init__(self, g: Graph, leaf_ranges: dict[tuple[str, str], tuple[float, float]],
                 where: str = ""):
        self.g = g
        self.where = where
        self.ival: dict[int, tuple[float, float]] = {}
        self.fmt: dict[int, Fmt] = {}
        self.leaf_fmt: dict[tuple[str, str], Fmt] = {}
        self._real_intervals(leaf_ranges)
        self._choose_formats()
        self._verify_integers()

    # -- step 1 ---------------------------------------------------------------------------
    def _err(self, n: Node, msg: str):
        raise RangeError(f"{self.where}: {msg} ({self._describe(n)})")

    def _describe(self, n: Node) -> str:
        """Which value: a declared variable by name, else the operation, its estimator line, its
        operands' ranges and the result it is stored as (if it is one)."""
        if n.op == "input":
            return f"{n.kind} {n.name}[{n.index}]"
        text = f"node %{n.id} {n.op}{' at ' + n.loc if n.loc else ''}"
        ops = []
        for a in n.args:
            if a.type != REAL or a.id not in self.ival:
                continue
            lo, hi = self.ival[a.id]
            iv = f"[{lo:g}, {hi:g}]"
            if a.op == "input":
                dlo, dhi = self._leaf_ranges[(a.kind, a.name)]
                iv = f"{a.kind} {a.name}[{a.index}] {iv}" + (
                    f" (declared [{dlo:g}, {dhi:g}] plus the sample inputs' headroom bit)"
                    if a.kind == "input" else "")
            ops.append(iv)
        if ops:
            text += ", operand ranges " + ", ".join(ops)
        stored = [f"{r.kind} {r.name}[{r.index}]" for r in self.g.results if r.node is n]
        if stored:
            text += ", stored as " + ", ".join(stored[:3])
        return text

    def _real_intervals(self, leaf_ranges):
        self._leaf_ranges = leaf_ranges
        users = self.g.users()
        self._input_frac: dict[tuple[str, str], int] = {}
        self._assumed: dict[int, tuple[float, float]] = {}
        for n in self.g.nodes:
            us = users[n.id]
            if n.type == REAL and n.op not in ("const", "input") and us and \
                    all(u.op == "assume" for u in us):
                lo = min(u.attrs[0] for u in us)
                hi = max(u.attrs[1] for u in us)
                self._assumed[n.id] = (lo, hi)
        for n in self.g.nodes:
            if n.type != REAL:
                continue
            a = [self.ival.get(x.id) for x in n.args]
            op = n.op
            if op == "const":
                iv = (n.value, n.value)
            elif op == "input":
                lo, hi = leaf_ranges[(n.kind, n.name)]
                if not (math.isfinite(lo) and math.isfinite(hi)):
                    self._err(n, f"declared range [{lo:g}, {hi:g}] of {n.kind} {n.name} is "
                                 "unbounded; fixed point needs finite bounds (or declare the "
                                 "estimator float32 only: systems = ('f32',))")
                if n.kind == "input":
                    # one bit of headroom: out-of-range samples stay representable
                    f = input_frac(lo, hi)
                    self._input_frac[(n.kind, n.name)] = f
                    r = RAW_MAX * 2.0 ** -f
                    iv = (-r, r)
                else:
                    iv = (lo, hi)
            elif op == "add":
                iv = (a[0][0] + a[1][0], a[0][1] + a[1][1])
            elif op == "sub":
                iv = (a[0][0] - a[1][1], a[0][1] - a[1][0])
            elif op == "mul":
                if n.args[0] is n.args[1]:
                    lo, hi = a[0]
                    m = max(lo * lo, hi * hi)
                    iv = (0.0 if lo <= 0.0 <= hi else min(lo * lo, hi * hi), m)
                else:
                    iv = _ival_mul(a[0], a[1])
            elif op == "div":
                lo, hi = a[1]
                if lo <= 0.0 <= hi:
                    self._err(n, f"divisor range [{lo:g}, {hi:g}] contains 0; "
                                 "guard it: x / fmax(d, eps)")
                iv = _ival_mul(a[0], (1.0 / hi, 1.0 / lo))
            elif op == "neg":
                iv = (-a[0][1], -a[0][0])
            elif op == "abs":
                lo, hi = a[0]
                iv = (0.0 if lo <= 0.0 <= hi else min(abs(lo), abs(hi)), max(abs(lo), abs(hi)))
            elif op == "sqrt":
                lo, hi = a[0]
                if lo < 0.0:
                    self._err(n, f"sqrt argument range [{lo:g}, {hi:g}] may be negative; "
                                 "guard it with fmax(x, 0.0)")
                iv = (math.sqrt(lo), math.sqrt(hi))
            elif op == "rsqrt":
                lo, hi = a[0]
                if lo <= 0.0:
                    self._err(n, f"rsqrt argument range [{lo:g}, {hi:g}] reaches 0; "
                                 "guard it with fmax(x, eps)")
                iv = (1.0 / math.sqrt(hi), 1.0 / math.sqrt(lo))
            elif op == "floor":
                lim = 2.0 ** 30
                iv = (math.floor(max(-lim, min(lim, a[0][0]))), math.floor(max(-lim, min(lim, a[0][1]))))
            elif op == "rnorm":
                eps = n.attrs[0]
                iv = (1.0 / math.sqrt(max(a[0][1], eps)), 1.0 / math.sqrt(max(a[0][0], eps)))
                if "scaled" in n.attrs[1:]:
                    clo, chi = a[-1]
                    if clo < 0.0:
                        self._err(n, f"rnorm scale range [{clo:g}, {chi:g}] may be negative")
                    iv = (clo * iv[0], chi * iv[1])
            elif op == "min":
                iv = (min(a[0][0], a[1][0]), min(a[0][1], a[1][1]))
            elif op == "max":
                iv = (max(a[0][0], a[1][0]), max(a[0][1], a[1][1]))
            elif op == "select":
                iv = (min(a[1][0], a[2][0]), max(a[1][1], a[2][1]))
            elif op == "assume":
                lo, hi = n.attrs
                iv = (max(lo, a[0][0]), min(hi, a[0][1]))
                if iv[0] > iv[1]:
                    iv = (lo, hi)
            else:
                raise NotImplementedError(op)
            if n.id in self._assumed:
                lo, hi = self._assumed[n.id]
                iv = (max(iv[0], lo), min(iv[1], hi))
            if not (math.isfinite(iv[0]) and math.isfinite(iv[1])):
                self._err(n, f"range [{iv[0]:g}, {iv[1]:g}] is unbounded; add a guard or assume()")
            self.ival[n.id] = iv

    # -- step 2 ---------------------------------------------------------------------------
    def _choose_formats(self):
        for n in self.g.nodes:
            if n.type != REAL:
                continue
            lo, hi = self.ival[n.id]
            r = max(abs(lo), abs(hi))
            if n.op in ("rsqrt", "rnorm"):
                self.fmt[n.id] = Fmt(0, 0, 0, dyn=True)
                continue
            if n.op == "const":
                f = frac_for(r) if r else 30
                raw = _raw_of(n.value, f)
                self.fmt[n.id] = Fmt(f, raw, raw)
                continue
            if n.op == "input":
                if n.kind == "input":
                    fm = Fmt(self._input_frac[(n.kind, n.name)], -RAW_MAX, RAW_MAX)
                else:
                    f = frac_for(r)
                    fm = Fmt(f, _raw_of(lo, f), _raw_of(hi, f))
                self.fmt[n.id] = fm
                self.leaf_fmt[(n.kind, n.name)] = fm
                continue
            f = frac_for(r)
            fa = [self.fmt[x.id].frac if x.type == REAL and not self.fmt[x.id].dyn else None
                  for x in n.args]
            if n.op in ("neg", "abs") and fa[0] is not None:
                f = fa[0]        # |raw| <= 2^31 - 1 keeps fitting: no rounding needed
            elif n.op == "div":
                f = min(f, fa[0] - fa[1] + 31)
            elif n.op == "sqrt":
                f = min(f, (fa[0] + 31) // 2)
            sat = n.id in self._assumed or n.op == "assume"
            self.fmt[n.id] = Fmt(f, _raw_of(lo, f), _raw_of(hi, f), sat=sat)

    # -- step 3 ---------------------------------------------------------------------------
    def _verify_integers(self):
        """Integer images of every op under the chosen formats (monotone ops: corners)."""
        for n in self.g.nodes:
            if n.type != REAL or n.op in ("const", "input") or self.fmt[n.id].dyn:
                continue
            fm = self.fmt[n.id]
            lo, hi = self._raw_image(n)   # also checks the int64 intermediates
            if fm.sat:
                # saturating op: the result lies in the declared bounds, whatever the image
                fm.lo, fm.hi = max(fm.lo, -RAW_MAX), min(fm.hi, RAW_MAX)
                if fm.lo > fm.hi:
                    fm.lo, fm.hi = fm.hi, fm.lo
                continue
            if lo < -RAW_MAX or hi > RAW_MAX:
                fm.sat = True
                fm.lo, fm.hi = max(lo, -RAW_MAX), min(hi, RAW_MAX)
            else:
                fm.lo, fm.hi = lo, hi

    def _raw_image(self, n: Node) -> tuple[int, int]:
        fm = self.fmt[n.id]
        op = n.op
        args = n.args
        A = [(self.fmt[x.id].lo, self.fmt[x.id].hi) if x.type == REAL else None for x in args]
        fa = [self.fmt[x.id].frac if x.type == REAL else None for x in args]
        f = fm.frac

        def corners(fn, x, y):
            vals = [fn(p, q) for p in x for q in y]
            return min(vals), max(vals)

        if op == "mul":
            if any(self.fmt[x.id].dyn for x in args):
                return (fm.lo, fm.hi)   # kf_mul_dyn always saturates
            k = fa[0] + fa[1] - f
            if args[0] is args[1]:
                lo, hi = A[0]
                p = sorted([0 if lo <= 0 <= hi else min(lo * lo, hi * hi), max(lo * lo, hi * hi)])
            else:
                p = corners(lambda x, y: x * y, A[0], A[1])
            self._check64(n, max(abs(p[0]), abs(p[1])))
            return (_rescale(p[0], k), _rescale(p[1], k))
        if op in ("add", "sub"):
            W, ka, kb, kr = add_shifts(fa[0], fa[1], f)
            a = (_rescale(A[0][0], ka), _rescale(A[0][1], ka))
            b = (_rescale(A[1][0], kb), _rescale(A[1][1], kb))
            s = (a[0] + b[0], a[1] + b[1]) if op == "add" else (a[0] - b[1], a[1] - b[0])
            self._check64(n, max(abs(s[0]), abs(s[1])) + (1 << max(kr - 1, 0)))
            return (_rescale(s[0], kr), _rescale(s[1], kr))
        if op == "neg":
            return (_rescale(-A[0][1], fa[0] - f), _rescale(-A[0][0], fa[0] - f))
        if op == "abs":
            lo, hi = A[0]
            m = max(abs(lo), abs(hi))
            mn = 0 if lo <= 0 <= hi else min(abs(lo), abs(hi))
            return (_rescale(mn, fa[0] - f), _rescale(m, fa[0] - f))
        if op == "sqrt":
            s = 2 * f - fa[0]
            lo, hi = A[0]
            self._check64(n, abs(hi) << max(s, 0))
            return (qrt.kf_isqrt_rnd(_rescale(lo, -s)), qrt.kf_isqrt_rnd(_rescale(hi, -s)))
        if op == "div":
            return (fm.lo, fm.hi)   # kf_div_rnd always saturates to the format's bounds
        if op == "floor":
            return tuple(_floor_raw(v, fa[0], f) for v in A[0])
        if op in ("min", "max", "select", "assume"):
            srcs = [(A[i], fa[i]) for i in range(len(args)) if args[i].type == REAL]
            los = [_rescale(r[0], ff - f) for r, ff in srcs]
            his = [_rescale(r[1], ff - f) for r, ff in srcs]
            if op == "assume":
                return (max(los[0], fm.lo), min(his[0], fm.hi))
            if op == "min":
                return (min(los), min(his))
            if op == "max":
                return (max(los), max(his))
            return (min(los), max(his))
        raise NotImplementedError(op)

    def _check64(self, n: Node, mag: int):
        if mag > I64_MAX:
            self._err(n, f"int64 intermediate may overflow ({mag:.3g})")

    # -- reporting --------------------------------------------------------------------------
    def format_table(self) -> list[tuple[str, str, str]]:
        return [(f"{k}.{name}", q_name(fm.frac), f"raw [{fm.lo}, {fm.hi}]")
                for (k, name), fm in self.leaf_fmt.items()]


def _rescale(v: int, k: int) -> int:
    """Integer semantics of a rescale by 2^-k (k > 0: rounding right shift)."""
    if k > 0:
        return (v + (1 << (k - 1))) >> k
    return v << (-k)


def add_shifts(fa: int, fb: int, f: int) -> tuple[int, int, int, int]:
    """Common format W of an addition and the shifts (operand a, operand b, result): a shift k
    means rescale by 2^-k.  Operands are aligned exactly unless their formats differ by more than
    31 bits, then the finer one is rounded."""
    W = max(fa, fb)
    if W - min(fa, fb) > 31:
        W = min(fa, fb) + 31
    return W, fa - W, fb - W, W - f


def div_shifts(s: int) -> tuple[int, int]:
    """Rescale shifts (numerator, denominator) computing round(a * 2^s / b) with int64 operands:
    the numerator is scaled up by at most 31 bits, the denominator by at most 31 bits; beyond
    that the numerator is rounded down."""
    if s >= 0:
        return -s, 0
    if s >= -31:
        return 0, s
    return -s - 31, -31


def div_operands(num, den, s: int):
    kn, kd = div_shifts(s)
    return rescale_expr(num, kn), rescale_expr(den, kd)


def rescale_expr(e, k: int):
    """int64 expression e rescaled by 2^-k (exact for k <= 0)."""
    if k > 0:
        return RshRound(e, k)
    return Shl(e, -k)


class FixedLowering:
    """Lowers graph nodes to fixed-point statements using a :class:`FixedPlan`."""

    name = NAME
    real_kind = "i32"

    def __init__(self, g: Graph, decl):
        self.g = g
        self.decl = decl
        self.plan = FixedPlan(g, decl.leaf_ranges(), where=decl.where)
        self.fmt = self.plan.fmt
        self.var_fmt = self._var_formats()

    def _var_formats(self) -> dict[tuple[str, str], Fmt]:
        """Storage formats of struct fields: leaves from the plan (or, if unused, from the
        declaration), outputs from their declared ranges."""
        out = dict(self.plan.leaf_fmt)
        for kind, var in self.decl.all_vars():
            if var.type != REAL or (kind, var.name) in out:
                continue
            r = max(abs(var.lo), abs(var.hi))
            if not math.isfinite(r):
                raise RangeError(f"{self.decl.where}: {kind} {var.name}: declared range "
                                 f"[{var.lo:g}, {var.hi:g}] is unbounded; fixed point needs "
                                 "finite bounds (or declare the estimator float32 only: "
                                 "systems = ('f32',))")
            if kind == "input":
                out[(kind, var.name)] = Fmt(input_frac(var.lo, var.hi), -RAW_MAX, RAW_MAX)
            else:
                f = frac_for(r)
                out[(kind, var.name)] = Fmt(f, _raw_of(var.lo, f), _raw_of(var.hi, f))
        return out

    # -- expressions -----------------------------------------------------------------------
    def ref(self, n: Node, names):
        if n.op == "const":
            if n.type == REAL:
                return Int(self.fmt[n.id].lo)
            return Int(int(n.value))
        return Var(names[n.id])

    def _conv(self, n: Node, names, f_to: int):
        """int64 expression of node n in format f_to (rounded when coarser)."""
        return rescale_expr(Wide(self.ref(n, names)), self.fmt[n.id].frac - f_to)

    def _fin(self, e, fm: Fmt, k_left: int = 0):
        """Narrow an int64 expression to the node's int32 (saturating if required)."""
        if fm.sat:
            return Call("kf_sat", (e, Int(fm.lo), Int(fm.hi)))
        return Narrow(e)

    def lower(self, n: Node, names) -> list[Assign] | str:
        t = names[n.id]
        op = n.op
        loc = n.loc
        if n.type != REAL and op not in ("lt", "le", "eq"):
            kind = "bool" if n.type == BOOL else "i32"
            a = [self.ref(x, names) for x in n.args]
            if op == "and":
                return [Assign(t, kind, Bin("&&", a[0], a[1]), loc)]
            if op == "or":
                return [Assign(t, kind, Bin("||", a[0], a[1]), loc)]
            if op == "not":
                return [Assign(t, kind, Un("!", a[0]), loc)]
            if op == "select":
                return [Assign(t, kind, Sel(a[0], a[1], a[2]), loc)]
            if op == "inc_if":
                return [Assign(t, kind, Call("kf_inc_if", (a[0], a[1])), loc)]
            raise NotImplementedError(op)
        if op in ("lt", "le", "eq"):
            x, y = n.args
            if x.type != REAL:
                return [Assign(t, "bool", Bin({"lt": "<", "le": "<=", "eq": "=="}[op],
                                              self.ref(x, names), self.ref(y, names)), loc)]
            W, ka, kb, _ = add_shifts(self.fmt[x.id].frac, self.fmt[y.id].frac, 0)
            fx, fy = self.fmt[x.id], self.fmt[y.id]
            A = (_rescale(fx.lo, ka), _rescale(fx.hi, ka))
            B = (_rescale(fy.lo, kb), _rescale(fy.hi, kb))
            decided = _decide(op, A, B)
            if decided is not None:   # the raw intervals settle it: no run-time comparison
                return [Assign(t, "bool", Int(int(decided)), loc)]
            ea = rescale_expr(Wide(self.ref(x, names)), ka)
            eb = rescale_expr(Wide(self.ref(y, names)), kb)
            return [Assign(t, "bool", Bin({"lt": "<", "le": "<=", "eq": "=="}[op], ea, eb), loc)]

        fm = self.fmt[n.id]
        f = fm.frac
        a = n.args
        qc = f"{q_name(f)}" if not fm.dyn else "dynamic"
        comment = f"{loc} {qc}".strip()
        if op == "mul":
            fx = [self.fmt[x.id] for x in a]
            if fx[0].dyn or fx[1].dyn:
                if fx[0].dyn and fx[1].dyn:
                    raise RangeError(f"{self.decl.where}: product of two reciprocal square "
                                     "roots (rsqrt/rnorm values) is not supported in fixed "
                                     f"point: multiply one by another value first (at {loc})")
                s, d = (a[1], a[0]) if fx[0].dyn else (a[0], a[1])
                kbase = self.fmt[s.id].frac - f
                return [Assign(t, "i32", Call("kf_mul_dyn", (self.ref(s, names), self.ref(d, names),
                                                              Int(kbase), Int(fm.lo), Int(fm.hi))),
                               comment)]
            k = fx[0].frac + fx[1].frac - f
            p = Bin("*", Wide(self.ref(a[0], names)), self.ref(a[1], names))
            if k >= 63:
                return [Assign(t, "i32", Int(qrt.kf_sat(0, fm.lo, fm.hi)), comment)]
            if k < 0 and fm.sat:
                return [Assign(t, "i32", Call("kf_lsh_sat", (p, Int(-k), Int(fm.lo), Int(fm.hi))),
                               comment)]
            return [Assign(t, "i32", self._fin(rescale_expr(p, k), fm), comment)]
        if op in ("add", "sub"):
            W, ka, kb, kr = add_shifts(self.fmt[a[0].id].frac, self.fmt[a[1].id].frac, f)
            ea = rescale_expr(Wide(self.ref(a[0], names)), ka)
            eb = rescale_expr(Wide(self.ref(a[1], names)), kb)
            s = Bin("+" if op == "add" else "-", ea, eb)
            if kr < 0 and fm.sat:
                return [Assign(t, "i32", Call("kf_lsh_sat", (s, Int(-kr), Int(fm.lo), Int(fm.hi))),
                               comment)]
            return [Assign(t, "i32", self._fin(rescale_expr(s, kr), fm), comment)]
        if op == "neg":
            e = rescale_expr(Un("-", Wide(self.ref(a[0], names))), self.fmt[a[0].id].frac - f)
            return [Assign(t, "i32", self._fin(e, fm), comment)]
        if op == "abs":
            x = Wide(self.ref(a[0], names))
            e = rescale_expr(Sel(Bin("<", x, Int(0)), Un("-", x), x), self.fmt[a[0].id].frac - f)
            return [Assign(t, "i32", self._fin(e, fm), comment)]
        if op == "sqrt":
            s = 2 * f - self.fmt[a[0].id].frac
            e = Call("kf_isqrt_rnd", (rescale_expr(Wide(self.ref(a[0], names)), -s),))
            return [Assign(t, "i32", self._fin(e, fm), comment)]
        if op == "rsqrt":
            return [Assign(t, "dyn", Call("kf_rsqrt_dyn", (self.ref(a[0], names),
                                                           Int(self.fmt[a[0].id].frac))), comment)]
        if op == "rnorm":
            scaled = "scaled" in n.attrs[1:]
            comps = a[1:-1] if scaled else a[1:]
            fc = min(self.fmt[x.id].frac for x in comps)
            stmts, vals = [], []
            for i, x in enumerate(comps):
                src = self.fmt[x.id]
                if x.op == "const":
                    vals.append(Int(_rescale(src.lo, src.frac - fc)))
                elif src.frac == fc:
                    vals.append(self.ref(x, names))
                else:   # coarser common format: fits int32
                    stmts.append(Assign(f"{t}_{i}", "i32", Narrow(self._conv(x, names, fc))))
                    vals.append(Var(f"{t}_{i}"))
            vals += [Int(0)] * (4 - len(vals))
            m_eps, e_eps = dyn_const_rsqrt(n.attrs[0])
            r = Call("kf_rnorm_dyn", tuple(vals) + (Int(fc), Int(m_eps), Int(e_eps)))
            if not scaled:
                return stmts + [Assign(t, "dyn", r, comment)]
            c = a[-1]
            if self.fmt[c.id].dyn:
                raise RangeError(f"{self.decl.where}: rnorm scaled by a reciprocal square root "
                                 f"(rsqrt/rnorm value) is not supported in fixed point (at {loc})")
            return stmts + [Assign(t + "_u", "dyn", r, comment),
                            Assign(t, "dyn", Call("kf_dyn_scale", (
                                Var(t + "_u"), self.ref(c, names), Int(self.fmt[c.id].frac))))]
        if op == "floor":
            fa = self.fmt[a[0].id].frac
            x = Wide(self.ref(a[0], names))
            # the integer part by an arithmetic (flooring) shift, then into the result format
            e = rescale_expr(Rsh(x, fa), -f) if fa > 0 else rescale_expr(x, fa - f)
            return [Assign(t, "i32", self._fin(e, fm), comment)]
        if op == "div":
            fa, fb = self.fmt[a[0].id].frac, self.fmt[a[1].id].frac
            num, den = div_operands(Wide(self.ref(a[0], names)), Wide(self.ref(a[1], names)),
                                    f + fb - fa)
            return [Assign(t, "i32", Call("kf_div_rnd", (num, den, Int(fm.lo), Int(fm.hi))),
                           comment)]
        if op in ("min", "max", "select", "assume"):
            data = a[1:] if op == "select" else a[:2] if op != "assume" else a[:1]
            stmts, vals = [], []
            for i, x in enumerate(data):
                src = self.fmt[x.id]
                if src.dyn:       # a reciprocal square root chosen as it is: into the format
                    name = f"{t}_{i}"
                    stmts.append(Assign(name, "i32", Call("kf_mul_dyn", (
                        Int(1), self.ref(x, names), Int(0 - f), Int(fm.lo), Int(fm.hi)))))
                    vals.append(Var(name))
                    continue
                if x.op != "const" and src.frac == f and (
                        not fm.sat or (fm.lo <= src.lo and src.hi <= fm.hi)):
                    vals.append(self.ref(x, names))   # already in format and bounds
                    continue
                e = self._conv(x, names, f)
                k_in = src.frac - f
                if fm.sat or (op in ("min", "max") and (_rescale(src.lo, k_in) < -RAW_MAX or
                                                      _rescale(src.hi, k_in) > RAW_MAX)):
                    # an operand of min/max may lie far outside the result's range (e.g. the
                    # very negative side of max(x, 0)) and not fit int32 in the result's finer
                    # format: clamping it into the result's bounds is exact for min/max
                    e = Call("kf_sat", (e, Int(fm.lo), Int(fm.hi)))
                else:
                    e = Narrow(e)
                if x.op == "const":
                    vals.append(Int(_rescale_const(self.fmt[x.id].lo, self.fmt[x.id].frac - f,
                                                   fm)))
                    continue
                name = f"{t}_{i}"
                stmts.append(Assign(name, "i32", e))
                vals.append(Var(name))
            if op == "assume":
                if not stmts and isinstance(vals[0], Var):
                    return vals[0].name
                return stmts + [Assign(t, "i32", vals[0], comment)]
            if op == "select":
                return stmts + [Assign(t, "i32", Sel(self.ref(a[0], names), vals[0], vals[1]),
                                       comment)]
            cmp = Bin("<", vals[0], vals[1]) if op == "min" else Bin("<", vals[1], vals[0])
            return stmts + [Assign(t, "i32", Sel(cmp, vals[0], vals[1]), comment)]
        raise NotImplementedError(op)

    # -- interface values -------------------------------------------------------------------
    def c_field_type(self, var) -> str:
        return {REAL: "int32_t", BOOL: "uint8_t", INT: "int32_t"}[var.type]

    def field_doc(self, var, kind: str) -> str:
        if var.type != REAL:
            return ""
        fm = self.var_fmt[(kind, var.name)]
        return f"{q_name(fm.frac)}: value = raw * 2^-{fm.frac}" if fm.frac >= 0 else \
            f"{q_name(fm.frac)}: value = raw * 2^{-fm.frac}"

    def store(self, n: Node, value, var, kind: str):
        """Expression converting node n's value into the field's storage format."""
        if var.type != REAL:
            return value
        dst = self.var_fmt[(kind, var.name)]
        if n.op == "const":
            return Int(_raw_of(n.value, dst.frac) if dst.lo <= _raw_of(n.value, dst.frac) <= dst.hi
                       else qrt.kf_sat(_raw_of(n.value, dst.frac), dst.lo, dst.hi))
        src = self.fmt[n.id]
        if src.dyn:
            return Call("kf_mul_dyn", (Int(1), value, Int(0 - dst.frac), Int(dst.lo), Int(dst.hi)))
        k = src.frac - dst.frac
        lo, hi = _rescale(src.lo, k), _rescale(src.hi, k)
        if k == 0 and dst.lo <= lo and hi <= dst.hi:
            return value
        e = rescale_expr(Wide(value), k)
        if dst.lo <= lo and hi <= dst.hi:
            return Narrow(e)
        if k < 0:
            return Call("kf_lsh_sat", (Wide(value), Int(-k), Int(dst.lo), Int(dst.hi)))
        return Call("kf_sat", (e, Int(dst.lo), Int(dst.hi)))

    def to_model(self, var, values, kind: str):
        """Host float values -> raw integers of the field (round half away, saturate, NaN->lo)."""
        if var.type == REAL:
            fm = self.var_fmt[(kind, var.name)]
            return qrt.q_from_float_v(np.asarray(values, dtype=np.float64), fm.frac, fm.lo, fm.hi)
        if var.type == BOOL:
            return np.asarray(values).astype(bool)
        return np.asarray(values).astype(np.int64)

    def from_model(self, var, values, kind: str):
        if var.type == REAL:
            fm = self.var_fmt[(kind, var.name)]
            return np.ldexp(np.asarray(values, dtype=np.float64), -fm.frac)
        return np.asarray(values)


def _decide(op: str, A: tuple[int, int], B: tuple[int, int]) -> bool | None:
    """The comparison's value when the operands' integer intervals alone determine it."""
    if op == "lt":
        return True if A[1] < B[0] else False if A[0] >= B[1] else None
    if op == "le":
        return True if A[1] <= B[0] else False if A[0] > B[1] else None
    if A[1] < B[0] or B[1] < A[0]:
        return False
    return True if A[0] == A[1] == B[0] == B[1] else None


def _floor_raw(v: int, fa: int, f: int) -> int:
    """Integer semantics of the floor lowering: raw v (frac fa) -> floor, in frac f."""
    if fa > 0:
        i = v >> fa
        return i << f if f >= 0 else _rescale(i, -f)
    return _rescale(v, fa - f)


def dyn_const_rsqrt(eps: float) -> tuple[int, int]:
    """1/sqrt(eps) as a normalised dyn constant (m in [2^30, 2^31), value = m * 2^-e), rounded
    to nearest, computed exactly."""
    from fractions import Fraction
    v = Fraction(eps)
    e = 30
    # find e with 2^30 <= 2^e / sqrt(eps) < 2^31, i.e. 2^60 <= 2^(2e) / eps < 2^62
    while Fraction(2) ** (2 * e) / v < 2 ** 60:
        e += 1
    while Fraction(2) ** (2 * e) / v >= 2 ** 62:
        e -= 1
    n = Fraction(2) ** (2 * e) / v
    r = math.isqrt(n.numerator // n.denominator)
    if Fraction(2 * r + 1, 2) ** 2 <= n:   # round to nearest
        r += 1
    if r >= 2 ** 31:
        r //= 2
        e -= 1
    return r, e


def _rescale_const(raw: int, k: int, fm: Fmt) -> int:
    # A constant operand of min/max/select is clamped into the result's bounds: exact (a bound
    # outside them is never the chosen value: min(x, 1000) with x <= 256 is x = min(x, 256)),
    # and it keeps int32 literals within int32.
    return qrt.kf_sat(_rescale(raw, k), fm.lo, fm.hi)
