"""The typed SSA operation graph every estimator is traced into.

A :class:`Graph` is a list of :class:`Node` in topological order (each node's arguments come
before it).  Leaves are constants and named *inputs* (sample inputs, parameters, state read at the
start of the step).  The graph's *results* are named node references: the next state and the
outputs of one filter step.

Scalar types:

``real``  a real number: float64 in the reference, binary32 in the float path, a Q-format int32 in
          the fixed-point path;
``bool``  a truth value (comparisons, logic);
``int``   a 32-bit signed counter (saturating), identical in every number system.

The operation set is deliberately small and free of libm transcendentals, so that every number
system can implement each operation exactly (see ``notes/bit-exact.md``).
"""
from __future__ import annotations

import dataclasses
from collections import Counter
from typing import Iterable, Iterator

REAL, BOOL, INT = "real", "bool", "int"

INT32_MIN, INT32_MAX = -(2 ** 31), 2 ** 31 - 1


@dataclasses.dataclass(frozen=True)
class OpInfo:
    arity: int
    args: tuple[str, ...] | None  # argument types (None: checked by the op's own rule)
    result: str | None            # result type (None: same as the data arguments)
    commutative: bool = False
    doc: str = ""


# name -> OpInfo.  Leaves ('const', 'input') have arity 0.
OPS: dict[str, OpInfo] = {
    "const": OpInfo(0, (), None, doc="constant (value attribute)"),
    "input": OpInfo(0, (), None, doc="named input: sample field, parameter or state at step start"),
    "add": OpInfo(2, (REAL, REAL), REAL, True, "a + b"),
    "sub": OpInfo(2, (REAL, REAL), REAL, False, "a - b"),
    "mul": OpInfo(2, (REAL, REAL), REAL, True, "a * b"),
    "div": OpInfo(2, (REAL, REAL), REAL, False, "a / b"),
    "neg": OpInfo(1, (REAL,), REAL, False, "-a"),
    "abs": OpInfo(1, (REAL,), REAL, False, "|a|"),
    "sqrt": OpInfo(1, (REAL,), REAL, False, "sqrt(a), a >= 0"),
    "rsqrt": OpInfo(1, (REAL,), REAL, False, "1 / sqrt(a), a > 0"),
    "min": OpInfo(2, (REAL, REAL), REAL, False, "(a < b) ? a : b   (b when a is NaN)"),
    "max": OpInfo(2, (REAL, REAL), REAL, False, "(a > b) ? a : b   (b when a is NaN)"),
    "lt": OpInfo(2, None, BOOL, False, "a < b"),
    "le": OpInfo(2, None, BOOL, False, "a <= b"),
    "eq": OpInfo(2, None, BOOL, True, "a == b"),
    "and": OpInfo(2, (BOOL, BOOL), BOOL, True, "a && b"),
    "or": OpInfo(2, (BOOL, BOOL), BOOL, True, "a || b"),
    "not": OpInfo(1, (BOOL,), BOOL, False, "!a"),
    "select": OpInfo(3, None, None, False, "c ? a : b"),
    # identity on real numbers; tells the fixed-point path the value lies in [lo, hi]
    # (it saturates there).  Used where a bound holds mathematically but interval
    # arithmetic cannot prove it, e.g. the components of a normalised quaternion.
    "assume": OpInfo(1, (REAL,), REAL, False, "a, known to lie in [lo, hi]"),
    "inc_if": OpInfo(2, (INT, BOOL), INT, False, "saturating counter: a + (c ? 1 : 0)"),
    # floor of a value clamped to [-2^30, 2^30] (NaN gives -2^30): the one rounding primitive
    # range reductions need (mathlib); exact in every number system.
    "floor": OpInfo(1, (REAL,), REAL, False, "floor(clamp(a, -2^30, 2^30))"),
    # 1 / sqrt(max(n2, eps)) where n2 = x0^2 + ... + xk^2 is the first argument and x0..xk
    # (1 to 4 of them) follow.  The float paths use n2; the fixed-point path uses the
    # components with block scaling, so tiny vectors keep full precision.
    "rnorm": OpInfo(-1, None, REAL, False, "1 / sqrt(max(n2, eps)), n2 = sum of squares of x "
                    "(scaled: c / sqrt(...), c the last operand)"),
}

ARITH = ("add", "sub", "mul", "div")
COMPARE = ("lt", "le", "eq")


class Node:
    """One SSA value.  Identity is the object; structural equality is :meth:`key`."""

    __slots__ = ("id", "op", "args", "type", "value", "attrs", "loc", "guard")

    def __init__(self, id: int, op: str, args: tuple["Node", ...], type: str,
                 value=None, attrs: tuple = (), loc: str = "", guard: "Node | None" = None):
        self.id = id
        self.op = op
        self.args = args
        self.type = type
        self.value = value   # const: the value (float/int/bool); input: None
        self.attrs = attrs   # ('kind', 'name', index) for inputs, (lo, hi) for assume,
        #                      ('bound',) for the min/max of scalar.bound (no binary32 code)
        self.loc = loc       # "file.py:line" of the estimator code that created it
        # bool node: the operation only runs when it holds (a conditional region); its value is
        # 0 / false otherwise, in every number system
        self.guard = guard

    def key(self):
        """Structural key used for common-subexpression elimination."""
        args = tuple(a.id for a in self.args)
        if OPS[self.op].commutative:
            args = tuple(sorted(args))
        value = self.value
        if self.op == "const" and self.type == REAL:
            # distinguish 0.0 and -0.0, and NaNs (never merged: NaN != NaN)
            value = (float(value).hex(),)
        return (self.op, self.type, args, value, self.attrs,
                self.guard.id if self.guard is not None else None)

    # -- input attributes ---------------------------------------------------------------
    @property
    def kind(self) -> str:
        return self.attrs[0]

    @property
    def name(self) -> str:
        return self.attrs[1]

    @property
    def index(self) -> int:
        return self.attrs[2]

    def __repr__(self):
        if self.op == "const":
            return f"%{self.id}=const({self.value!r}:{self.type})"
        if self.op == "input":
            return f"%{self.id}=input({self.kind}.{self.name}[{self.index}]:{self.type})"
        a = ", ".join(f"%{x.id}" for x in self.args)
        extra = f" {self.attrs}" if self.attrs else ""
        g = f" if %{self.guard.id}" if self.guard is not None else ""
        return f"%{self.id}={self.op}({a}){extra}:{self.type}{g}"


@dataclasses.dataclass(frozen=True)
class Result:
    """A named value the step produces: the next state or an output."""
    kind: str    # 'state' or 'output'
    name: str
    index: int
    node: Node


class Graph:
    """Nodes in topological order plus the named results of one filter step."""

    def __init__(self, name: str = ""):
        self.name = name
        self.nodes: list[Node] = []
        self.results: list[Result] = []
        self._next_id = 0
        self.guards: list[Node] = []   # stack of open conditional regions (tracing)

    # -- construction ---------------------------------------------------------------------
    def add(self, op: str, args: Iterable[Node] = (), type: str | None = None, value=None,
            attrs: tuple = (), loc: str = "", guard: "Node | None | bool" = True) -> Node:
        """Append a node.  guard=True: the innermost open conditional region (none for leaves);
        a Node or None: exactly that."""
        args = tuple(args)
        if guard is True:
            guard = self.guards[-1] if (self.guards and op not in ("const", "input")) else None
        info = OPS.get(op)
        if info is None:
            raise ValueError(f"unknown operation {op!r}")
        if info.arity == -1:
            extra = 1 if "scaled" in attrs else 0     # rnorm's scale operand, last
            if not 2 + extra <= len(args) <= 5 + extra or any(a.type != REAL for a in args):
                raise ValueError(f"{op} takes n2, 1 to 4 real components and, scaled, a scale")
        elif len(args) != info.arity:
            raise ValueError(f"{op} takes {info.arity} arguments, got {len(args)}")
        rtype = _result_type(op, info, args, type)
        if guard is not None and guard.type != BOOL:
            raise TypeError("a guard must be a bool value")
        node = Node(self._next_id, op, args, rtype, value, attrs, loc, guard)
        self._next_id += 1
        self.nodes.append(node)
        return node

    def const(self, value, type: str = REAL) -> Node:
        if type == REAL:
            value = float(value)
        elif type == INT:
            value = int(value)
        else:
            value = bool(value)
        return self.add("const", type=type, value=value)

    def input(self, kind: str, name: str, index: int, type: str = REAL) -> Node:
        return self.add("input", type=type, attrs=(kind, name, index))

    def set_result(self, kind: str, name: str, index: int, node: Node) -> None:
        self.results.append(Result(kind, name, index, node))

    # -- queries --------------------------------------------------------------------------
    def inputs(self, kind: str | None = None) -> list[Node]:
        return [n for n in self.nodes if n.op == "input" and (kind is None or n.kind == kind)]

    def results_of(self, kind: str) -> list[Result]:
        return [r for r in self.results if r.kind == kind]

    def __iter__(self) -> Iterator[Node]:
        return iter(self.nodes)

    def __len__(self) -> int:
        return len(self.nodes)

    def users(self) -> dict[int, list[Node]]:
        """node id -> nodes that use it as an argument."""
        out: dict[int, list[Node]] = {n.id: [] for n in self.nodes}
        for n in self.nodes:
            for a in n.args:
                out[a.id].append(n)
        return out

    def op_counts(self, free=None) -> Counter:
        """Operations per kind, leaves and free ops (assume; nodes for which free(node) holds)
        excluded."""
        return Counter(n.op for n in self.nodes if n.op not in ("const", "input", "assume")
                       and not (free is not None and free(n)))

    def op_summary(self, free=None) -> str:
        """One readable line: total and per-operation counts."""
        counts = self.op_counts(free)
        total = sum(counts.values())
        parts = ", ".join(f"{op} {counts[op]}" for op in OPS if counts.get(op))
        return f"{total} ops ({parts})" if total else "0 ops"

    def check(self) -> None:
        """Verify topological order and that results reference nodes of this graph."""
        seen = set()
        for n in self.nodes:
            for a in n.args + ((n.guard,) if n.guard is not None else ()):
                if a.id not in seen:
                    raise AssertionError(f"{n!r} uses %{a.id} before its definition")
            seen.add(n.id)
        for r in self.results:
            if r.node.id not in seen:
                raise AssertionError(f"result {r.kind}.{r.name}[{r.index}] is not in the graph")

    def dump(self) -> str:
        lines = [repr(n) + (f"   # {n.loc}" if n.loc else "") for n in self.nodes]
        lines += [f"{r.kind}.{r.name}[{r.index}] = %{r.node.id}" for r in self.results]
        return "\n".join(lines)


def _result_type(op: str, info: OpInfo, args: tuple[Node, ...], type: str | None) -> str:
    if op in ("const", "input"):
        if type not in (REAL, BOOL, INT):
            raise ValueError(f"{op} needs a type")
        return type
    if info.args is not None:
        for a, want in zip(args, info.args):
            if a.type != want:
                raise TypeError(f"{op} expects {want} arguments, got {a.type}")
        return info.result
    if op in COMPARE:
        if args[0].type != args[1].type or args[0].type == BOOL:
            raise TypeError(f"{op} compares two real or two int values, got "
                            f"{args[0].type} and {args[1].type}")
        return BOOL
    if op == "rnorm":
        return REAL
    if op == "select":
        c, a, b = args
        if c.type != BOOL:
            raise TypeError("select condition must be bool")
        if a.type != b.type:
            raise TypeError(f"select branches differ in type: {a.type} vs {b.type}")
        return a.type
    raise AssertionError(op)
