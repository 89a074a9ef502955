"""Forward-mode AD (dual numbers over the scalar interface): values and derivatives against
finite differences and closed forms, nesting, structural zeros, tracing."""
from __future__ import annotations

import math

import numpy as np
import pytest

from kinefuse.codegen.estimators.dynamics import ad
from kinefuse.codegen.ir import Graph
from kinefuse.codegen.linalg import ZERO
from kinefuse.codegen.passes import evaluate, optimize
from kinefuse.codegen.scalar import Sym


def f_scalar(x, y):
    s, c = ad.sincos(x)
    return (s * y + 3.0) / (c + 2.0) - x * x / (1.0 + y * y) + 2.0 / (x + 4.0)


def f_float(x, y):
    return ((math.sin(x) * y + 3.0) / (math.cos(x) + 2.0) - x * x / (1.0 + y * y)
            + 2.0 / (x + 4.0))


@pytest.mark.parametrize("x,y", [(0.3, -0.7), (-2.1, 1.4), (5.0, 0.1)])
def test_gradient_matches_central_differences(x, y):
    val, jac = ad.jacobian(lambda v: [f_scalar(v[0], v[1])], [x, y])
    assert val[0] == pytest.approx(f_float(x, y), abs=1e-8)     # mathlib sin/cos ~1e-9
    h = 1e-6
    gx = (f_float(x + h, y) - f_float(x - h, y)) / (2 * h)
    gy = (f_float(x, y + h) - f_float(x, y - h)) / (2 * h)
    assert jac[0][0] == pytest.approx(gx, rel=1e-6, abs=1e-7)
    assert jac[0][1] == pytest.approx(gy, rel=1e-6, abs=1e-7)


def test_nested_duals_give_mixed_second_derivatives():
    """d²/dx dy of sin(x) y² x at (x, y): 2 y (cos x x + sin x) — needs tags (no perturbation
    confusion: the inner derivative is taken while the outer level is live)."""
    x0, y0 = 0.8, -1.3
    to, ti = ad.new_tag(), ad.new_tag()
    x = ad.Dual(x0, (1.0,), to)
    y = ad.Dual(ad.Dual(y0, (ZERO,), to), (1.0,), ti)    # inner level: d/dy
    s, _ = ad.sincos(x)
    f = s * y * y * x
    d_dy = ad.tangent(f, 0, ti)            # outer Dual: ∂f/∂y as a function of x
    mixed = ad.tangent(d_dy, 0, to)
    want = 2 * y0 * (math.cos(x0) * x0 + math.sin(x0))
    assert mixed == pytest.approx(want, rel=1e-8)
    # and the same with the levels created the other way round
    to2, ti2 = ad.new_tag(), ad.new_tag()
    y2 = ad.Dual(y0, (1.0,), to2)
    x2 = ad.Dual(ad.Dual(x0, (ZERO,), to2), (1.0,), ti2)
    s2, _ = ad.sincos(x2)
    g = s2 * y2 * y2 * x2
    assert ad.tangent(ad.tangent(g, 0, ti2), 0, to2) == pytest.approx(want, rel=1e-8)


def test_structural_zero_tangents_stay_structural():
    t = ad.new_tag()
    a = ad.Dual(2.0, (1.0, ZERO), t)
    b = ad.Dual(3.0, (ZERO, ZERO), t)
    c = a * b + b * 2.0
    assert c.d[1] is ZERO and c.d[0] == 3.0
    assert ad.tangent(5.0, 0, t) is ZERO


def test_duals_trace_into_the_graph_and_evaluate_like_floats():
    """The same AD code on Syms records a graph that, evaluated in float64, equals the float
    run bit for bit (what makes the generated derivatives the reference's derivatives)."""
    g = Graph("ad")
    xs = Sym(g, g.input("input", "x", 0))
    ys = Sym(g, g.input("input", "y", 0))
    val, jac = ad.jacobian(lambda v: [f_scalar(v[0], v[1])], [xs, ys])
    for i, node in enumerate([val[0], jac[0][0], jac[0][1]]):
        g.set_result("output", "o", i, node.n)
    g2 = optimize(g)
    x0, y0 = 0.37, -1.9
    res = evaluate(g2, {("input", "x", 0): x0, ("input", "y", 0): y0})
    fval, fjac = ad.jacobian(lambda v: [f_scalar(v[0], v[1])], [x0, y0])
    want = [fval[0], fjac[0][0], fjac[0][1]]
    got = [res[("output", "o", i)] for i in range(3)]
    assert np.array_equal(np.array(got, np.float64).view(np.uint64),
                          np.array(want, np.float64).view(np.uint64))


def test_syms_defer_to_duals_for_mixed_operations():
    g = Graph("mix")
    p = Sym(g, g.input("param", "p", 0))
    t = ad.new_tag()
    d = ad.Dual(p, (1.0,), t)
    for r in (p * d, p + d, p - d, p / d, d * p):
        assert isinstance(r, ad.Dual)
    with pytest.raises(TypeError):
        p * "text"
