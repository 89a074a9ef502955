"""IR construction and the passes: folding, CSE, DCE, conditional regions, op counts."""
from __future__ import annotations

import math

import numpy as np
import pytest

from kinefuse.codegen import estimators
from kinefuse.codegen.estimator import run_reference, trace
from kinefuse.codegen.ir import BOOL, REAL, Graph
from kinefuse.codegen.passes import cse, dce, evaluate, fold_constants, optimize
from kinefuse.codegen.scalar import Sym, fmax, rnorm, select, sqrt, when

from kinefuse.codegen.testing import random_imu


def _g():
    g = Graph("t")
    a = Sym(g, g.input("input", "a", 0))
    b = Sym(g, g.input("input", "b", 0))
    return g, a, b


def test_fold_evaluates_constants_in_float64():
    g, a, _ = _g()
    c = Sym(g, g.const(0.1)) * 3.0 + 1e-17
    g.set_result("output", "y", 0, (a + c).n)
    f = fold_constants(g)
    consts = [n.value for n in f.nodes if n.op == "const"]
    assert 0.1 * 3.0 + 1e-17 in consts            # folded exactly as Python computes it
    assert [n.op for n in f.nodes if n.op not in ("const", "input")] == ["add"]


def test_fold_only_applies_exact_identities():
    g, a, b = _g()
    y1 = a * 1.0          # exact: folded
    y2 = a * 0.0          # not exact for NaN/inf: kept
    y3 = a + 0.0          # -0 + 0 = +0: kept
    y4 = -(-b)            # exact: folded
    for i, y in enumerate((y1, y2, y3, y4)):
        g.set_result("output", "y", i, y.n)
    f = optimize(g)
    res = {r.index: r.node for r in f.results}
    assert res[0].op == "input" and res[3].op == "input"
    assert res[1].op == "mul" and res[2].op == "add"


def test_cse_merges_commutative_operands_and_dce_drops_dead_code():
    g, a, b = _g()
    x = a * b
    y = b * a             # same product
    _dead = sqrt(fmax(a, 0.0)) * 5.0
    g.set_result("output", "y", 0, (x + y).n)
    o = optimize(g)
    assert o.op_counts() == {"mul": 1, "add": 1}
    assert "sqrt" not in o.op_summary()


def test_cse_never_merges_nan_constants():
    g = Graph("t")
    n1, n2 = g.const(float("nan")), g.const(float("nan"))
    g.set_result("output", "y", 0, n1)
    g.set_result("output", "y", 1, n2)
    assert len(cse(g).nodes) == 2


def test_guarded_nodes_reuse_earlier_unguarded_ones_but_not_the_reverse():
    g, a, b = _g()
    c = a < b
    p = a * b
    with when(c):
        q = a * b          # identical to p, computed before: reused
        r = a + b
    s = a + b              # identical to r but r only runs under c: not reused
    g.set_result("output", "y", 0, select(c, q, p).n)
    g.set_result("output", "y", 1, select(c, r, s).n)
    o = optimize(g)
    assert o.op_counts()["mul"] == 1
    assert o.op_counts()["add"] == 2


def test_guarded_value_is_zero_when_its_region_is_skipped():
    g, a, b = _g()
    with when(a < b):
        y = a * 2.0
    g.set_result("output", "y", 0, y.n)
    o = optimize(g)
    assert evaluate(o, {("input", "a", 0): 1.0, ("input", "b", 0): 2.0})[("output", "y", 0)] == 2.0
    assert evaluate(o, {("input", "a", 0): 3.0, ("input", "b", 0): 2.0})[("output", "y", 0)] == 0.0


def test_traced_value_has_no_truth_value():
    g, a, b = _g()
    with pytest.raises(TypeError, match="select"):
        if a < b:
            pass


def test_type_errors_are_reported():
    g, a, b = _g()
    with pytest.raises(TypeError):
        g.add("add", [(a < b).n, a.n])
    with pytest.raises(TypeError):
        g.add("select", [a.n, a.n, b.n])


def test_rnorm_is_the_inverse_norm_in_the_reference():
    k, n2 = rnorm((3.0, 4.0), 1e-12)
    assert n2 == 25.0 and k == 0.2
    k0, _ = rnorm((0.0, 0.0, 0.0), 1e-12)
    assert math.isclose(k0, 1e6)


@pytest.mark.parametrize("name", ["madgwick", "mahony", "complementary"])
def test_optimised_graph_in_float64_equals_the_reference_bit_for_bit(name):
    """The tracer and every pass preserve the meaning of the estimator's own Python code."""
    est = estimators.get(name)
    g = optimize(trace(est))
    inputs = random_imu(300, seed=3, bad_fraction=0.05)
    ref, _ = run_reference(est, inputs)
    prm = est.resolve_params()
    state = {(k, v.name, i): val for k, decl in (("state", est.state),)
             for v in decl for i, val in enumerate(v.init_values())}
    for k in range(300):
        env = dict(state)
        for f in est.inputs.fields:
            col = np.asarray(inputs[f.name]).reshape(300, -1)
            for i in range(f.size):
                v = col[k, i]
                env[("input", f.name, i)] = bool(v) if f.type == BOOL else float(v)
        for p in est.params:
            env[("param", p.name, 0)] = prm[p.name]
        out = evaluate(g, env)
        for v in est.outputs:
            for i in range(v.size):
                got, want = out[("output", v.name, i)], ref[v.name][k, i]
                if v.type == REAL:
                    assert np.float64(got).tobytes() == np.float64(want).tobytes(), (k, v.name, i)
                else:
                    assert got == want
        state = {("state", n, i): out[("state", n, i)] for (_, n, i) in state}


def test_op_summary_is_readable():
    g = optimize(trace(estimators.get("madgwick")))
    s = g.op_summary()
    assert s.split()[0].isdigit() and "mul" in s and "rnorm" in s
