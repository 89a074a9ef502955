"""The IEEE-754 binary32 number system.

Each graph node becomes one C statement with one operation (``-ffp-contract=off`` and the
``FLT_EVAL_METHOD == 0`` guard keep the compiler from fusing or widening), and the Python model
executes the same statements on numpy float32 values.  Only correctly rounded operations are used
(+ − × ÷ sqrtf fabsf, comparisons), so C and model agree bit for bit on every IEEE machine.

Semantics worth knowing:
  min(a, b) = (a < b) ? a : b and max(a, b) = (a > b) ? a : b — the second operand wins when the
  first is NaN; rsqrt(x) = 1.0f / sqrtf(x) (two rounded operations); rnorm with a scale c is
  c / sqrtf(m), and split (on a dependency chain) sqrtf(m) * (c / m), three; assume() and
  the min/max of a bound() are the identity (no statement).
"""
from __future__ import annotations

from kinefuse.codegen.ir import BOOL, INT, REAL, Graph, Node
from kinefuse.codegen.render import Assign, Bin, Call, F32, Int, Sel, ToF32, ToI32, Un, Var

NAME = "f32"
C_REAL = "float"
TITLE = "IEEE-754 binary32, round to nearest even, no contraction, no fast-math"

_BIN = {"add": "+", "sub": "-", "mul": "*", "div": "/", "lt": "<", "le": "<=", "eq": "==",
        "and": "&&", "or": "||"}


class Float32Lowering:
    """Lowers graph nodes to binary32 statements."""

    name = NAME
    real_kind = "f32"

    @staticmethod
    def free(n: Node) -> bool:
        """Nodes that emit no statement here (not counted in OPS.md): the min/max of a bound."""
        return n.op in ("min", "max") and "bound" in n.attrs

    def __init__(self, g: Graph, decl):
        self.g = g
        self.decl = decl

    # the value of a node as an expression: constants inline, others by name
    def ref(self, n: Node, names: dict[int, str]):
        if n.op == "const":
            if n.type == REAL:
                return F32(n.value)
            return Int(int(n.value))
        return Var(names[n.id])

    def lower(self, n: Node, names: dict[int, str]) -> list[Assign] | str:
        """Statements computing node n into names[n.id]; or the name of an existing value when
        the node is an alias (assume)."""
        a = [self.ref(x, names) for x in n.args]
        t = names[n.id]
        kind = {REAL: "f32", BOOL: "bool", INT: "i32"}[n.type]
        op = n.op
        if op in _BIN:
            return [Assign(t, kind, Bin(_BIN[op], a[0], a[1]), n.loc)]
        if op == "neg":
            return [Assign(t, kind, Un("-", a[0]), n.loc)]
        if op == "not":
            return [Assign(t, kind, Un("!", a[0]), n.loc)]
        if op == "abs":
            return [Assign(t, kind, Call("fabsf", (a[0],)), n.loc)]
        if op == "sqrt":
            return [Assign(t, kind, Call("sqrtf", (a[0],)), n.loc)]
        if op == "rsqrt":
            return [Assign(t + "_s", kind, Call("sqrtf", (a[0],)), n.loc),
                    Assign(t, kind, Bin("/", F32(1.0), Var(t + "_s")))]
        if op == "floor":
            lim = F32(2.0 ** 30)
            c1, c2 = Var(t + "_a"), Var(t + "_b")
            return [Assign(t + "_a", kind, Sel(Bin("<", F32(-(2.0 ** 30)), a[0]), a[0], F32(-(2.0 ** 30))),
                           n.loc),
                    Assign(t + "_b", kind, Sel(Bin("<", c1, lim), c1, lim)),
                    Assign(t + "_i", "f32", ToF32(ToI32(c2))),
                    Assign(t, kind, Sel(Bin("<", c2, Var(t + "_i")),
                                        Bin("-", Var(t + "_i"), F32(1.0)), Var(t + "_i")))]
        if op == "rnorm":
            eps = F32(n.attrs[0])
            c = a[-1] if "scaled" in n.attrs[1:] else F32(1.0)
            m = [Assign(t + "_m", kind, Sel(Bin("<", eps, a[0]), a[0], eps), n.loc),
                 Assign(t + "_s", kind, Call("sqrtf", (Var(t + "_m"),)))]
            if "split" in n.attrs[1:]:   # sqrt(m) * (c/m): sqrtf and the division overlap
                return m + [Assign(t + "_r", kind, Bin("/", c, Var(t + "_m"))),
                            Assign(t, kind, Bin("*", Var(t + "_s"), Var(t + "_r")))]
            return m + [Assign(t, kind, Bin("/", c, Var(t + "_s")))]
        if op in ("min", "max") and "bound" in n.attrs:   # scalar.bound: the identity here
            return names[n.args[0].id] if n.args[0].op != "const" else [
                Assign(t, kind, a[0], n.loc)]
        if op == "min":
            return [Assign(t, kind, Sel(Bin("<", a[0], a[1]), a[0], a[1]), n.loc)]
        if op == "max":
            return [Assign(t, kind, Sel(Bin("<", a[1], a[0]), a[0], a[1]), n.loc)]
        if op == "select":
            return [Assign(t, kind, Sel(a[0], a[1], a[2]), n.loc)]
        if op == "assume":
            return names[n.args[0].id] if n.args[0].op != "const" else [
                Assign(t, kind, a[0], n.loc)]
        if op == "inc_if":
            return [Assign(t, kind, Call("kf_inc_if", (a[0], a[1])), n.loc)]
        raise NotImplementedError(op)

    # -- interface values -------------------------------------------------------------------
    def c_field_type(self, var) -> str:
        return {REAL: "float", BOOL: "uint8_t", INT: "int32_t"}[var.type]

    def field_doc(self, var, kind: str) -> str:
        return ""

    def store(self, n: Node, value, var, kind: str):
        """Expression stored into a state/output field from the node's value."""
        return value

    def load_input(self, var, c_expr: str):
        return c_expr

    def to_model(self, var, values):
        """Host values (float64 arrays) -> what the model and the C structs hold."""
        import numpy as np
        if var.type == REAL:
            return np.asarray(values, dtype=np.float64).astype(np.float32)
        if var.type == BOOL:
            return np.asarray(values).astype(bool)
        return np.asarray(values).astype(np.int64)

    def from_model(self, var, values):
        import numpy as np
        if var.type == REAL:
            return np.asarray(values, dtype=np.float32).astype(np.float64)
        return np.asarray(values)
