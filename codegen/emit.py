"""Emitters: one lowered graph → C99 header + source, and the bit-exact Python model.

The same :class:`Lowered` object (graph + number system + statements) feeds both emitters, so the
C and the model are printed from identical statements in identical order.
"""
from __future__ import annotations

import inspect
import re
import textwrap

from kinefuse.codegen.estimator import Estimator, EstimatorError, Interface, Var, generated_stem
from kinefuse.codegen.fixed import FixedLowering
from kinefuse.codegen.float32 import Float32Lowering
from kinefuse.codegen.ir import BOOL, INT, REAL, Graph, Node
from kinefuse.codegen.render import (C_TYPES, C_ZERO, Assign, F32, Int, blocks,
                                     escaping, expr_names, render_c, render_c_assign, render_py,
                                     render_py_assign)

SYSTEMS = {"f32": Float32Lowering, "q": FixedLowering}
SYSTEM_TITLES = {
    "f32": "IEEE-754 binary32 (round to nearest even; no contraction, no fast-math)",
    "q": "fixed point: int32 values with per-variable Q formats, int64 intermediates, "
         "round half up, explicit saturation",
}
PREFIX = {"input": "u", "param": "p", "state": "x"}
CLASS_CONST, CLASS_PARAM, CLASS_INPUT, CLASS_STATE = 0, 1, 2, 3
_LEAF_CLASS = {"param": CLASS_PARAM, "input": CLASS_INPUT, "state": CLASS_STATE}


def leaf_name(kind: str, var: Var, index: int) -> str:
    return f"{PREFIX[kind]}_{var.name}" + (str(index) if var.size > 1 else "")


_C_KEYWORDS = frozenset(
    "auto break case char const continue default do double else enum extern float for goto if "
    "inline int long register restrict return short signed sizeof static struct switch typedef "
    "union unsigned void volatile while _Bool _Complex _Imaginary".split())
_IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def check_declaration(est: Estimator) -> None:
    """The names that become C identifiers and file names must be usable as such, and distinct:
    otherwise the C does not compile, or two values share one name in the Python model.  Ranges
    must not be empty, and initial states must lie in them."""
    def ident(what: str, name: str, text: str) -> None:
        if not isinstance(name, str) or not _IDENT.fullmatch(text) or text in _C_KEYWORDS:
            raise EstimatorError(f"{est.name or type(est).__name__}: {what} {name!r} is not usable "
                                 "as a C identifier (letters, digits and _, not starting with a "
                                 "digit, not a C keyword)")

    ident("filter name", est.name, str(est.name).replace("-", "_"))
    ident("input record name", est.inputs.name, est.inputs.name)
    leaves: dict[str, str] = {}
    params = tuple(q.as_var() for q in est.params)
    for kind, decl in (("input", est.inputs.fields), ("param", params), ("state", est.state),
                       ("output", est.outputs)):
        seen = set()
        for v in decl:
            ident(f"{kind}", v.name, v.name)
            if v.name in seen:
                raise EstimatorError(f"{est.name}: {kind} {v.name!r} is declared twice")
            seen.add(v.name)
            # an empty (or NaN) range gives formats and rejection tests that hold for nothing
            if v.type == REAL and not v.lo <= v.hi:
                raise EstimatorError(f"{est.name}: {kind} {v.name}: declared range "
                                     f"[{v.lo:g}, {v.hi:g}] is empty (lo > hi)")
            if kind == "output":
                continue
            if kind == "state":
                try:
                    init = v.init_values()
                except ValueError as exc:
                    raise EstimatorError(f"{est.name}: state {exc}") from None
                # fixed point would clip it silently; the float paths would start outside the
                # range the formats were chosen for
                bad = [x for x in init if v.type == REAL and not v.lo <= float(x) <= v.hi]
                if bad:
                    raise EstimatorError(f"{est.name}: state {v.name}: initial value {bad[0]!r} "
                                         f"outside its declared range [{v.lo:g}, {v.hi:g}]")
            for i in range(v.size):
                leaf = leaf_name(kind, v, i)
                if leaf in leaves:
                    raise EstimatorError(f"{est.name}: {kind} {v.name!r} and {leaves[leaf]} both "
                                         f"become the C variable {leaf}: rename one")
                leaves[leaf] = f"{kind} {v.name!r}"


class Lowered:
    """An estimator's optimised graph lowered to one number system."""

    def __init__(self, est: Estimator, graph: Graph, system: str):
        self.est = est          # (its declaration was checked when trace() made the graph)
        self.g = graph
        self.system = system
        self.iface = Interface(est)
        self.sys = SYSTEMS[system](graph, self.iface)
        self.vars = {(k, v.name): v for k, v in self.iface.all_vars()}
        self.names: dict[int, str] = {}
        self.cls: dict[int, int] = {}
        self.body: list[tuple[Node, list[Assign]]] = []
        self.guard_name: dict[int, str | None] = {}
        for n in graph.nodes:
            if n.op == "const":
                self.cls[n.id] = CLASS_CONST
                self.names[n.id] = f"t{n.id}"
                continue
            if n.op == "input":
                self.cls[n.id] = _LEAF_CLASS[n.kind]
                self.names[n.id] = leaf_name(n.kind, self.vars[(n.kind, n.name)], n.index)
                continue
            deps = list(n.args) + ([n.guard] if n.guard is not None else [])
            self.cls[n.id] = max(self.cls[a.id] for a in deps)
            self.guard_name[n.id] = self.names[n.guard.id] if n.guard is not None else None
            self.names[n.id] = f"t{n.id}"
            r = self.sys.lower(n, self.names)
            if isinstance(r, str):
                self.names[n.id] = r       # an alias (assume in the float path)
            else:
                self.body.append((n, r))
        self._drop_unread()

    def _drop_unread(self) -> None:
        """Remove statements whose value nobody reads: a number system may not need every
        operand (the fixed-point rnorm uses the components, not the squared norm)."""
        while True:
            reads = set(self.result_refs())
            for n, stmts in self.body:
                for st in stmts:
                    reads |= expr_names(st.expr)
                if self.guard_name.get(n.id):
                    reads.add(self.guard_name[n.id])
            body = [(n, stmts) for n, stmts in self.body if stmts and stmts[-1].name in reads]
            changed = len(body) != len(self.body)   # a node's statements end with its value
            self.body = body
            if not changed:
                self.reads = reads
                return

    # -- naming ---------------------------------------------------------------------------
    @property
    def prefix(self) -> str:
        return generated_stem(self.est.name, self.system)

    @property
    def input_struct(self) -> str:
        return f"kf_{self.est.inputs.name}_input_{self.system}"

    def result_expr(self, r):
        var = self.vars[(r.kind, r.name)]
        return self.sys.store(r.node, self.sys.ref(r.node, self.names), var, r.kind)

    def op_summary(self) -> str:
        return self.g.op_summary(getattr(self.sys, "free", None))

    def result_refs(self) -> set[str]:
        return set().union(*(expr_names(self.result_expr(r)) for r in self.g.results)) \
            if self.g.results else set()

    def zero_expr(self, kind: str):
        """The value of a guarded statement whose region did not run."""
        return {"f32": F32(0.0), "i32": Int(0), "i64": Int(0), "bool": Int(0)}.get(kind)


# =========================================================================================
# C
# =========================================================================================

def _c_ident(name: str) -> str:
    return name.replace("-", "_")


def _wrap_comment(text: str, indent: str = " * ") -> list[str]:
    out = []
    for para in inspect.cleandoc(text or "").split("\n\n"):
        lines = textwrap.wrap(" ".join(para.split()), 92 - len(indent))
        out += [indent + ln for ln in lines] + [indent.rstrip()]
    return out[:-1] if out else []


def _field_comment(lo: Lowered, kind: str, var: Var, default=None) -> str:
    parts = []
    if var.unit:
        parts.append(var.unit)
    if var.type == REAL:
        parts.append(f"range [{var.lo:g}, {var.hi:g}]")
    if default is not None:
        parts.append(f"default {default:g}")
    fd = lo.sys.field_doc(var, kind)
    if fd:
        parts.append(fd)
    head = ", ".join(parts)
    return f"{head}: {var.doc}" if var.doc else head


def _c_field(lo: Lowered, kind: str, var: Var, default=None) -> str:
    t = lo.sys.c_field_type(var)
    dim = f"[{var.size}]" if var.size > 1 else ""
    return f"    {t} {var.name}{dim};  /* {_field_comment(lo, kind, var, default)} */"


def c_input_header(lo: Lowered) -> str:
    """kf_<spec>_input_<sys>: the input record several filters share."""
    spec = lo.est.inputs
    guard = f"KF_{spec.name.upper()}_{lo.system.upper()}_H"
    lines = [f"/*", f" * kf_{spec.name}_{lo.system}.h - the '{spec.name}' input record, "
             f"{SYSTEM_TITLES[lo.system]}.",
             " *", " * Generated by `kinefuse codegen` - do not edit."]
    if spec.doc:
        lines += [" *"] + _wrap_comment(spec.doc)
    if lo.system == "q":
        lines += [" *", " * Convert real values with kf_q_from_f32() (kf_fixed.h) or the host's "
                  "q_from_float: round half", " * away from zero, saturate."]
    lines += [" */", f"#ifndef {guard}", f"#define {guard}", "", "#include <stdint.h>", "",
              "typedef struct {"]
    lines += [_c_field(lo, "input", v) for v in spec.fields]
    lines += [f"}} {lo.input_struct};", "", f"#endif /* {guard} */", ""]
    return "\n".join(lines)


def c_header(lo: Lowered, source_file: str) -> str:
    est, P = lo.est, lo.prefix
    guard = f"{P.upper()}_H"
    lines = ["/*", f" * {P}.h - {est.title or est.name}: {SYSTEM_TITLES[lo.system]}.", " *",
             f" * Generated by `kinefuse codegen` from {source_file} - do not edit.",
             f" * One update: {lo.op_summary()}.", " *"]
    lines += _wrap_comment(est.__doc__ or "")
    lines += [" */", f"#ifndef {guard}", f"#define {guard}", "", "#include <stdint.h>",
              "", f'#include "kf_{est.inputs.name}_{lo.system}.h"', ""]
    lines.append(f"/* Parameters; set them with {P}_default_params() and change what you need. */")
    lines.append("typedef struct {")
    for p in est.params:
        lines.append(_c_field(lo, "param", p.as_var(), p.default))
    if not est.params:
        lines.append("    uint8_t unused;  /* no parameters */")
    lines += [f"}} {P}_params;", "", "/* Filter state (no hidden globals: one struct per filter instance). */",
              "typedef struct {", f"    {P}_params params;"]
    lines += [_c_field(lo, "state", v) for v in est.state]
    lines += [f"}} {P}_state;", "", "/* Outputs of one update. */", "typedef struct {"]
    lines += [_c_field(lo, "output", v) for v in est.outputs]
    lines += [f"}} {P}_output;", ""]
    lines += [
        "/* Fill p with the documented defaults. */",
        f"void {P}_default_params({P}_params *p);", "",
        "/* Initialise the state with parameters p.  Returns 0, or -(i + 1) when parameter i is",
        " * out of its range (NaN included); the defaults are used then. */",
        f"int {P}_init({P}_state *s, const {P}_params *p);", "",
        "/* One step: consume one input record, update the state, write the outputs. */",
        f"void {P}_update({P}_state *s, const {lo.input_struct} *in, {P}_output *out);", "",
        "/* n steps over arrays of records (the host's batch entry point). */",
        f"void {P}_run({P}_state *s, const {lo.input_struct} *in, {P}_output *out, uint32_t n);",
        "", f"#endif /* {guard} */", ""]
    return "\n".join(lines)


def _c_param_value(lo: Lowered, p) -> str:
    var = p.as_var()
    if lo.system == "f32":
        return render_c(F32(p.default)) if var.type == REAL else str(int(p.default))
    vals = lo.sys.to_model(var, [p.default], "param")
    return str(int(vals[0]))


def _c_state_init(lo: Lowered, var: Var) -> list[str]:
    vals = var.init_values()
    out = []
    if lo.system == "f32":
        enc = [render_c(F32(v)) if var.type == REAL else str(int(v)) for v in vals]
    else:
        enc = [str(int(v)) for v in lo.sys.to_model(var, list(vals), "state")]
    for i, e in enumerate(enc):
        idx = f"[{i}]" if var.size > 1 else ""
        out.append(f"    s->{var.name}{idx} = {e};")
    return out


def _c_param_check(lo: Lowered, p, i: int) -> str:
    """A parameter outside its range, or a switch that is not one of its choices (mode = 0.5
    would be read as 9D by ``p.mode > 0.5`` on one side and refused on the other), sets the
    status; NaN fails every comparison."""
    if p.choices:
        if lo.system == "f32":
            vals = [render_c(F32(c)) for c in p.choices]
        else:
            vals = [str(int(v)) for v in lo.sys.to_model(p.as_var(), list(p.choices), "param")]
        ok = " || ".join(f"(p->{p.name} == {v})" for v in vals)
    else:
        if lo.system == "f32":
            a, b = render_c(F32(p.lo)), render_c(F32(p.hi))
        else:
            fm = lo.sys.var_fmt[("param", p.name)]
            a, b = str(fm.lo), str(fm.hi)
        ok = f"(p->{p.name} >= {a}) && (p->{p.name} <= {b})"
    return f"    if (!({ok})) {{\n        status = -{i + 1};\n    }}"


def c_source(lo: Lowered, source_file: str) -> str:
    est, P = lo.est, lo.prefix
    lines = ["/*", f" * {P}.c - {est.title or est.name}: {SYSTEM_TITLES[lo.system]}.", " *",
             f" * Generated by `kinefuse codegen` from {source_file} - do not edit.",
             " * Each statement performs one operation in graph order; the Python model",
             f" * firmware/generated/models/{P}.py executes the same statements.",
             " * Build with -std=c99 -ffp-contract=off and without -ffast-math: the guards below",
             " * catch what the preprocessor can see.",
             " */", f'#include "{P}.h"', "", "#include <float.h>", "#include <stdint.h>"]
    if lo.system == "f32":
        lines += ["#include <math.h>  /* sqrtf, fabsf only: both correctly rounded */"]
    lines += ['#include "kf_fixed.h"  /* kf_inc_if; fixed-point helpers */', "",
              "#if !defined(FLT_EVAL_METHOD) || (FLT_EVAL_METHOD != 0)",
              '#error "kinefuse generated code needs FLT_EVAL_METHOD == 0 (no excess precision)"',
              "#endif", "#ifdef __FAST_MATH__",
              '#error "kinefuse generated code must not be built with -ffast-math"', "#endif"]
    if lo.system == "f32":
        # a*b+c fused into one rounding changes results.  Clang honours the C99 pragma; GCC
        # ignores it, but does not contract in ISO C mode (-std=c99); its GNU modes do unless
        # -ffp-contract=off, which the preprocessor cannot see (say so with KF_FP_CONTRACT_OFF)
        lines += ["#if defined(__clang__)", "#pragma STDC FP_CONTRACT OFF",
                  "#elif defined(__GNUC__) && !defined(__STRICT_ANSI__) && !defined(KF_FP_CONTRACT_OFF)",
                  '#error "kinefuse generated code: build with -std=c99 (GNU C modes fuse a*b+c), '
                  'or with -ffp-contract=off -DKF_FP_CONTRACT_OFF"',
                  "#endif"]
    lines += [""]
    lines += [f"void {P}_default_params({P}_params *p)", "{"]
    for p in est.params:
        lines.append(f"    p->{p.name} = {_c_param_value(lo, p)};")
    if not est.params:
        lines.append("    p->unused = 0u;")
    lines += ["}", "", f"int {P}_init({P}_state *s, const {P}_params *p)", "{",
              "    int status = 0;"]
    for i, p in reversed(list(enumerate(est.params))):
        lines.append(_c_param_check(lo, p, i))
    lines += ["    if (status != 0) {", f"        {P}_default_params(&s->params);", "    } else {",
              "        s->params = *p;", "    }"]
    for v in est.state:
        lines += _c_state_init(lo, v)
    lines += ["    return status;", "}", ""]
    # update
    lines += [f"void {P}_update({P}_state *s, const {lo.input_struct} *in, {P}_output *out)", "{"]
    # each read of an input, parameter or state field is placed just before the first statement
    # (or guarded region) that uses it: loaded at the top, most of them would sit in registers or
    # stack slots through the whole update (2.5 % fewer instructions for the flagship on the M4F)
    loads: dict[str, str] = {}
    for n in lo.g.inputs():
        if lo.names[n.id] not in lo.reads:
            continue
        var = lo.vars[(n.kind, n.name)]
        src = {"input": "in->", "param": "s->params.", "state": "s->"}[n.kind] + var.name
        if var.size > 1:
            src += f"[{n.index}]"
        ctype = {REAL: "float" if lo.system == "f32" else "int32_t", BOOL: "int",
                 INT: "int32_t"}[var.type]
        if var.type == BOOL:
            src = f"({src} != 0u)"
        loads[lo.names[n.id]] = f"    const {ctype} {lo.names[n.id]} = {src};"

    def load_before(stmts, guard=None) -> None:
        used = set().union(*(expr_names(st.expr) for st in stmts)) | {guard}
        for name in [nm for nm in loads if nm in used]:
            lines.append(loads.pop(name))

    blks = blocks([(lo.guard_name[n.id], stmts) for n, stmts in lo.body])
    esc = escaping(blks, lo.result_refs())
    for guard, stmts in blks:
        if guard is None:
            for st in stmts:
                load_before([st])
                lines.append(render_c_assign(st))
            continue
        load_before(stmts, guard)
        for s in stmts:   # values used after the region: declared before it, 0 if it is skipped
            if s.name in esc:
                lines.append(f"    {C_TYPES[s.kind]} {s.name} = {C_ZERO[s.kind]};")
        lines.append(f"    if ({guard}) {{")
        lines += [render_c_assign(s, "        ", declare=s.name not in esc) for s in stmts]
        lines.append("    }")
    lines += list(loads.values())     # fields only copied to the results
    for r in lo.g.results:
        var = lo.vars[(r.kind, r.name)]
        dst = ("s->" if r.kind == "state" else "out->") + var.name + (
            f"[{r.index}]" if var.size > 1 else "")
        val = render_c(lo.result_expr(r))
        if var.type == BOOL:
            val = f"(uint8_t)({val} ? 1u : 0u)"
        lines.append(f"    {dst} = {val};")
    lines += ["}", "", f"void {P}_run({P}_state *s, const {lo.input_struct} *in, {P}_output *out, uint32_t n)",
              "{", "    uint32_t i;", "    for (i = 0u; i < n; i++) {",
              f"        {P}_update(s, &in[i], &out[i]);", "    }", "}", ""]
    return "\n".join(lines)


# =========================================================================================
# Python model
# =========================================================================================

def _py_literal_value(v) -> str:
    return repr(v)


def py_model(lo: Lowered, source_file: str) -> str:
    """The bit-exact Python model of the C: same statements, numpy float32 or Python int values;
    nodes that depend only on the sample's inputs are computed for all samples at once."""
    est, P = lo.est, lo.prefix
    is_f32 = lo.system == "f32"
    consts: dict[str, float] = {}
    users_in_loop: set[int] = set()
    for n, _ in lo.body:
        if lo.cls[n.id] == CLASS_STATE:
            users_in_loop.update(a.id for a in n.args)
            if n.guard is not None:
                users_in_loop.add(n.guard.id)
    for r in lo.g.results:
        if lo.cls[r.node.id] == CLASS_STATE or r.kind == "state":
            users_in_loop.add(r.node.id)

    hoisted, vector, loop = [], [], []
    for n, stmts in lo.body:
        c = lo.cls[n.id]
        (hoisted if c <= CLASS_PARAM else vector if c == CLASS_INPUT else loop).append(
            (lo.guard_name[n.id], stmts))
    # names used after the conditional region that computed them (as in the C)
    esc = escaping(blocks([(lo.guard_name[n.id], st) for n, st in lo.body]), lo.result_refs())
    zero_py = {"f32": "K_ZERO", "i32": "0", "i64": "0", "bool": "False", "dyn": "(0, 0)"}

    def masked(items, vector: bool, indent: str) -> list[str]:
        """Regions outside the loop run unconditionally; their escaping values are then set to
        0 where the region's condition is false, exactly what the C reads."""
        out = []
        for guard, stmts in items:
            for st in stmts:
                out.append(render_py_assign(st, vector, consts, indent))
                if guard is not None and st.name in esc:
                    z = zero_py[st.kind]
                    if st.kind == "dyn":
                        out.append(f"{indent}{st.name} = tuple(_where({guard}, c_, 0) for c_ in {st.name})"
                                   if vector else f"{indent}{st.name} = {st.name} if {guard} else (0, 0)")
                    elif vector:
                        out.append(f"{indent}{st.name} = _where({guard}, {st.name}, {z})")
                    else:
                        out.append(f"{indent}{st.name} = {st.name} if {guard} else {z}")
        return out

    def looped(items, indent: str) -> list[str]:
        out = []
        for guard, stmts in blocks(items):
            if guard is None:
                out += [render_py_assign(st, False, consts, indent) for st in stmts]
                continue
            out += [f"{indent}{st.name} = {zero_py[st.kind]}" for st in stmts if st.name in esc]
            out.append(f"{indent}if {guard}:")
            out += [render_py_assign(st, False, consts, indent + "    ") for st in stmts]
        return out

    ind1, ind2 = "    ", "        "
    code = []
    # parameters and state into locals
    for n in lo.g.inputs("param"):
        var = lo.vars[(n.kind, n.name)]
        code.append(f"{ind1}{lo.names[n.id]} = params[{var.name!r}][{n.index}]")
    code += masked(hoisted, False, ind1)
    # inputs (columns) and input-only nodes, all samples at once
    for n in lo.g.inputs("input"):
        var = lo.vars[(n.kind, n.name)]
        code.append(f"{ind1}{lo.names[n.id]} = inputs[{var.name!r}][{n.index}]")
    code += masked(vector, True, ind1)
    # per-sample extraction of vector values the loop needs
    extract = []
    for n in lo.g.nodes:
        if lo.cls.get(n.id) == CLASS_INPUT and n.id in users_in_loop and n.op != "const":
            name = lo.names[n.id]
            if name.startswith("t") or name.startswith("u_"):
                extract.append((name, n.type))
    extract = sorted(set(extract))
    for name, typ in extract:
        if is_f32 and typ == REAL:
            code.append(f"{ind1}L_{name} = _f32_list({name}, n)")
        else:
            code.append(f"{ind1}L_{name} = _int_list({name}, n)")
    extract = [e[0] for e in extract]
    # state
    for v in est.state:
        code.append(f"{ind1}_st = state[{v.name!r}]")
        for i in range(v.size):
            code.append(f"{ind1}{leaf_name('state', v, i)} = _st[{i}]")
    # outputs: loop-computed ones are appended per sample, others computed once
    out_loop, out_vec = [], []
    for r in lo.g.results_of("output"):
        (out_loop if lo.cls[r.node.id] == CLASS_STATE else out_vec).append(r)
    for r in out_loop:
        code.append(f"{ind1}O_{r.name}{r.index} = []")
        code.append(f"{ind1}A_{r.name}{r.index} = O_{r.name}{r.index}.append")
    # outputs that do not depend on the state: all samples at once, before the loop rebinds
    # the names of the vector values it extracts
    for r in out_vec:
        code.append(f"{ind1}V_{r.name}{r.index} = _bcast({render_py(lo.result_expr(r), True, consts)}, n)")
    code.append(f"{ind1}for k in range(n):")
    for name in extract:
        code.append(f"{ind2}{name} = L_{name}[k]")
    code += looped(loop, ind2)
    for r in out_loop:
        code.append(f"{ind2}A_{r.name}{r.index}({render_py(lo.result_expr(r), False, consts)})")
    st_results = lo.g.results_of("state")
    if st_results:
        lhs = ", ".join(leaf_name("state", lo.vars[("state", r.name)], r.index) for r in st_results)
        rhs = ", ".join(render_py(lo.result_expr(r), False, consts) for r in st_results)
        code.append(f"{ind2}{lhs} = {rhs}")
    if not loop and not out_loop and not st_results:
        code.append(f"{ind2}pass")
    # results
    code.append(f"{ind1}outputs = {{}}")
    for v in est.outputs:
        cols = []
        for i in range(v.size):
            r = next(x for x in lo.g.results_of("output") if x.name == v.name and x.index == i)
            cols.append(f"O_{r.name}{r.index}" if r in out_loop else f"V_{r.name}{r.index}")
        code.append(f"{ind1}outputs[{v.name!r}] = [{', '.join(cols)}]")
    code.append(f"{ind1}new_state = {{}}")
    for v in est.state:
        code.append(f"{ind1}new_state[{v.name!r}] = [{', '.join(leaf_name('state', v, i) for i in range(v.size))}]")
    code.append(f"{ind1}return outputs, new_state")

    head = [f'"""Bit-exact Python model of {P}.c ({SYSTEM_TITLES[lo.system]}).',
            "", f"Generated by `kinefuse codegen` from {source_file} - do not edit.",
            "The statements are those of the C, in the same order.", '"""',
            "import numpy as np", "",
            f"from kinefuse.codegen.runtime import {'f32' if is_f32 else 'q'} as rt", "",
            f"NAME = {est.name!r}", f"SYSTEM = {lo.system!r}", "_where = np.where", ""]
    head += model_metadata(lo)
    if is_f32:
        head += ["F = np.float32", "K_ZERO = F(0.0)", ""]
        for k, v in sorted(consts.items()):
            head.append(f"{k} = F(float.fromhex({v.hex()!r}))" if v == v else f"{k} = F('nan')")
    head += ["", "",
             "def _f32_list(a, n):",
             "    a = np.asarray(a, dtype=np.float32)",
             "    return list(np.broadcast_to(a, (n,))) if a.ndim == 0 else list(a)",
             "", "",
             "def _int_list(a, n):",
             "    if isinstance(a, tuple):     # kf_dyn: (mantissas, exponents) -> (m, e) per sample",
             "        return list(zip(_int_list(a[0], n), _int_list(a[1], n)))",
             "    a = np.asarray(a)",
             "    return np.broadcast_to(a, (n,)).tolist()",
             "", "",
             "def _bcast(a, n):",
             "    a = np.asarray(a)",
             "    return np.broadcast_to(a, (n,)).copy() if a.ndim == 0 else a",
             "", "",
             "def run(inputs, params, state, n):",
             '    """inputs: field -> list of per-element arrays (model values); params: name -> [value];',
             '    state: name -> list of values.  Returns (outputs: name -> list of arrays or lists, state)."""']
    if is_f32:
        head.append("    with np.errstate(all='ignore'):")
        head.append("        return _run(inputs, params, state, n)")
        head += ["", "", "def _run(inputs, params, state, n):"]
    else:
        head.append("    return _run(inputs, params, state, n)")
        head += ["", "", "def _run(inputs, params, state, n):"]
    return "\n".join(head + code) + "\n"


def model_metadata(lo: Lowered) -> list[str]:
    """Interface description the runners use to convert host values (no re-tracing needed)."""
    est = lo.est
    fields = {k: [(v.name, v.size, v.type) for kk, v in lo.iface.all_vars() if kk == k]
              for k in ("input", "param", "state", "output")}
    lines = ["# field layout: kind -> [(name, size, type)]", f"FIELDS = {fields!r}"]
    lines.append(f"DEFAULTS = {({p.name: p.default for p in est.params})!r}")
    lines.append(f"STATE_INIT = {({v.name: v.init_values() for v in est.state})!r}")
    if lo.system == "q":
        fm = {f"{k}.{n}": (f.frac, f.lo, f.hi) for (k, n), f in sorted(lo.sys.var_fmt.items())}
        lines.append("# Q formats of real fields: 'kind.name' -> (fractional bits, raw lo, raw hi)")
        lines.append(f"FORMATS = {fm!r}")
    return lines + [""]
