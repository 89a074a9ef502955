"""Graph passes: constant folding, common-subexpression elimination, dead-code removal.

Every pass returns a new graph and preserves the float64 meaning of the graph *bit for bit*:
folding evaluates in float64 exactly as the reference does, and the only algebraic rewrites are
IEEE identities (x*1, x/1, x-0, --x, select(c, a, a)), so the optimised graph evaluated in float64
equals running the estimator's Python code.
"""
from __future__ import annotations

from typing import Callable

from kinefuse.codegen import scalar
from kinefuse.codegen.ir import BOOL, INT, INT32_MAX, REAL, Graph, Node


def eval_op(op: str, vals: list, attrs: tuple = ()):
    """Float64 (reference) semantics of one operation on Python values."""
    if op == "add":
        return vals[0] + vals[1]
    if op == "sub":
        return vals[0] - vals[1]
    if op == "mul":
        return vals[0] * vals[1]
    if op == "div":
        a, b = vals
        if b == 0.0:   # IEEE division by zero (Python would raise)
            if a != a or a == 0.0:
                return float("nan")
            neg = (a < 0) != (str(b).startswith("-"))
            return float("-inf") if neg else float("inf")
        return a / b
    if op == "neg":
        return -vals[0]
    if op == "abs":
        return abs(vals[0])
    if op == "sqrt":
        return scalar.sqrt(vals[0])
    if op == "rsqrt":
        return scalar.rsqrt(vals[0])
    if op == "floor":
        return scalar.floor(vals[0])
    if op == "rnorm":
        n2, eps = vals[0], attrs[0]
        r = scalar.rsqrt(n2 if n2 > eps else eps)
        return vals[-1] * r if "scaled" in attrs else r
    if op == "min":
        return vals[0] if vals[0] < vals[1] else vals[1]
    if op == "max":
        return vals[0] if vals[0] > vals[1] else vals[1]
    if op == "lt":
        return vals[0] < vals[1]
    if op == "le":
        return vals[0] <= vals[1]
    if op == "eq":
        return vals[0] == vals[1]
    if op == "and":
        return bool(vals[0]) and bool(vals[1])
    if op == "or":
        return bool(vals[0]) or bool(vals[1])
    if op == "not":
        return not vals[0]
    if op == "select":
        return vals[1] if vals[0] else vals[2]
    if op == "assume":
        return vals[0]
    if op == "inc_if":
        return min(vals[0] + 1, INT32_MAX) if vals[1] else vals[0]
    raise ValueError(f"cannot evaluate {op}")


def zero_of(type_: str):
    return {REAL: 0.0, INT: 0, BOOL: False}[type_]


def evaluate(g: Graph, env: dict[tuple[str, str, int], object]) -> dict[tuple[str, str, int], object]:
    """Evaluate the graph in float64 (a guarded node whose guard is false is 0 / false).
    env maps (kind, name, index) of inputs to values; returns (kind, name, index) of results."""
    val: dict[int, object] = {}
    for n in g.nodes:
        if n.op == "const":
            val[n.id] = n.value
        elif n.op == "input":
            val[n.id] = env[n.attrs]
        elif n.guard is not None and not val[n.guard.id]:
            val[n.id] = zero_of(n.type)
        else:
            val[n.id] = eval_op(n.op, [val[a.id] for a in n.args], n.attrs)
    return {(r.kind, r.name, r.index): val[r.node.id] for r in g.results}


# -- rebuilding ----------------------------------------------------------------------------

_MAP: dict[int, Node] = {}


def _copy(ng: Graph, n: Node, args: tuple[Node, ...]) -> Node:
    leaf = n.op in ("const", "input")
    guard = _MAP.get(n.guard.id) if n.guard is not None else None
    if guard is not None and guard.op == "const":
        guard = None if guard.value else guard   # always true: no region
    return ng.add(n.op, args, type=n.type if leaf else None, value=n.value, attrs=n.attrs,
                  loc=n.loc, guard=guard)


def rebuild(g: Graph, fn: Callable[[Graph, Node, tuple[Node, ...]], Node]) -> Graph:
    """New graph whose node for each old node is fn(new_graph, old_node, new_args)."""
    global _MAP
    ng = Graph(g.name)
    m: dict[int, Node] = {}
    saved, _MAP = _MAP, m
    try:
        for n in g.nodes:
            m[n.id] = fn(ng, n, tuple(m[a.id] for a in n.args))
    finally:
        _MAP = saved
    for r in g.results:
        ng.set_result(r.kind, r.name, r.index, m[r.node.id])
    return ng


def _is_const(n: Node, value=None) -> bool:
    if n.op != "const":
        return False
    if value is None:
        return True
    if n.type != REAL:
        return n.value == value
    # exact value and sign (x - (-0.0) is not x for x = +0.0 ... -0.0 handled by str)
    return n.value == value and str(n.value) == str(float(value))


def fold_constants(g: Graph) -> Graph:
    """Evaluate operations on constants; apply exact IEEE identities."""

    def fn(ng: Graph, n: Node, args: tuple[Node, ...]) -> Node:
        if n.op in ("const", "input"):
            return _copy(ng, n, args)
        op = n.op
        if n.guard is not None and m_guard_false(n):
            return ng.const(zero_of(n.type), n.type)   # a region that never runs
        if all(a.op == "const" for a in args):
            v = eval_op(op, [a.value for a in args], n.attrs)
            t = n.type
            return ng.const(v, t)
        if op == "select":
            c, a, b = args
            if c.op == "const":
                return a if c.value else b
            if a is b:
                return a
        if op == "mul":
            if _is_const(args[1], 1.0):
                return args[0]
            if _is_const(args[0], 1.0):
                return args[1]
        if op == "div" and _is_const(args[1], 1.0):
            return args[0]
        if op == "sub" and _is_const(args[1], 0.0):
            return args[0]
        if op == "neg" and args[0].op == "neg":
            return args[0].args[0]
        if op == "not" and args[0].op == "not":
            return args[0].args[0]
        if op in ("and", "or"):
            for x, y in ((args[0], args[1]), (args[1], args[0])):
                if x.op == "const":
                    if op == "and":
                        return y if x.value else ng.const(False, BOOL)
                    return ng.const(True, BOOL) if x.value else y
        if op == "inc_if" and args[1].op == "const" and not args[1].value:
            return args[0]
        return _copy(ng, n, args)

    return rebuild(g, fn)


def m_guard_false(n: Node) -> bool:
    g = _MAP.get(n.guard.id)
    return g is not None and g.op == "const" and not g.value


def cse(g: Graph) -> Graph:
    """Merge structurally identical nodes (commutative operands sorted).  A node in a conditional
    region also reuses an identical unconditional node computed before it."""
    seen: dict[tuple, Node] = {}

    def fn(ng: Graph, n: Node, args: tuple[Node, ...]) -> Node:
        new = _copy(ng, n, args)
        k = new.key()
        if n.op == "const" and n.type == REAL and n.value != n.value:
            return new  # NaN constants are never merged
        old = seen.get(k)
        if old is None and new.guard is not None:
            old = seen.get(k[:-1] + (None,))
        if old is not None:
            ng.nodes.pop()   # drop the duplicate we just appended
            return old
        seen[k] = new
        return new

    return rebuild(g, fn)


def dce(g: Graph, keep_inputs: bool = True) -> Graph:
    """Remove nodes no result depends on (inputs are kept so the interface stays complete)."""
    live: set[int] = {r.node.id for r in g.results}
    for n in reversed(g.nodes):
        if n.id in live:
            live.update(a.id for a in n.args)
            if n.guard is not None:
                live.add(n.guard.id)
    if keep_inputs:
        live.update(n.id for n in g.nodes if n.op == "input")

    global _MAP
    ng = Graph(g.name)
    m: dict[int, Node] = {}
    saved, _MAP = _MAP, m
    try:
        for n in g.nodes:
            if n.id in live:
                m[n.id] = _copy(ng, n, tuple(m[a.id] for a in n.args))
    finally:
        _MAP = saved
    for r in g.results:
        ng.set_result(r.kind, r.name, r.index, m[r.node.id])
    return ng


def optimize(g: Graph) -> Graph:
    """fold → CSE → DCE until the graph stops shrinking."""
    while True:
        before = len(g)
        g = dce(cse(fold_constants(g)))
        if len(g) >= before:
            return g


# convenience for type checks in tests
__all__ = ["eval_op", "evaluate", "rebuild", "fold_constants", "cse", "dce", "optimize",
           "REAL", "BOOL", "INT"]
