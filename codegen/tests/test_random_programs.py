"""Random programs through the whole generator: for every generated program and random inputs
(finite, out of range, NaN, inf), the compiled C and its Python model agree in every bit, in
float32 and in fixed point.  The programs exercise every operation, conditional regions, state
feedback, counters and saturation."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings, strategies as st

from kinefuse.codegen.estimator import Estimator, InputSpec, Param, Var
from kinefuse.codegen.ir import BOOL, INT
from kinefuse.codegen.runner import bits
from kinefuse.codegen.scalar import (assume, clamp, fabs, floor, fmax, fmin, inc_if, rnorm, rsqrt,
                                     select, sqrt, when)
from kinefuse.codegen.testing import build_adhoc

N_OPS = 18
instr = st.tuples(st.integers(0, N_OPS - 1), st.integers(0, 99), st.integers(0, 99),
                  st.integers(0, 99), st.floats(-8.0, 8.0, allow_nan=False).filter(lambda v: v != 0))
programs = st.lists(instr, min_size=3, max_size=24)


def make_estimator(program, uid: int):
    def interpret(pool, ins):
        op, i, j, k, c = ins
        a, b, d = pool[i % len(pool)], pool[j % len(pool)], pool[k % len(pool)]
        if op == 0:
            return a + b
        if op == 1:
            return a - b
        if op == 2:
            return a * b
        if op == 3:
            return a / (fabs(b) + 0.5)
        if op == 4:
            return -a
        if op == 5:
            return fabs(a)
        if op == 6:
            return sqrt(fmax(a, 0.0))
        if op == 7:
            kk, _ = rnorm((a, b, d), 1e-6)
            return assume(a * kk, -1.0, 1.0)
        if op == 8:
            return fmin(a, b)
        if op == 9:
            return fmax(a, b)
        if op == 10:
            return select(a < b, a, d)
        if op == 11:
            return clamp(a, -abs(c), abs(c))
        if op == 12:
            return floor(clamp(a, -1.0e4, 1.0e4) * 0.37)
        if op == 13:
            cond = a < b
            with when(cond):
                v = a * b - d
            return select(cond, v, a)
        if op == 14:
            return b * rsqrt(fmax(a * a, 0.01))
        if op == 15:        # a reciprocal square root (dynamic binary point) chosen by a select
            return select(a < b, rsqrt(fmax(fabs(a), 0.01)), d)
        if op == 16:        # a scaled rnorm, split or not (scale c/(1+|d|) in [0, 8])
            kk, _ = rnorm((a, b), 1e-6, split=i % 2 == 0, scale=abs(c) / (fabs(d) + 1.0))
            return assume(a * kk, -8.0, 8.0)
        return a * c

    class Prog(Estimator):
        """random program"""
        name = f"rand{uid}"
        inputs = InputSpec(f"rand{uid}", (Var("x", 3, -100.0, 100.0), Var("flag", 1, 0, 1, type=BOOL)))
        params = (Param("k", 1.0, "", 0.5, 2.0, "a parameter"),)
        state = (Var("s", 1, -10.0, 10.0, init=0.5), Var("n", 1, 0, 2 ** 31 - 1, type=INT, init=0))
        outputs = (Var("y", 3, -1e6, 1e6), Var("b", 1, 0, 1, type=BOOL),
                   Var("n", 1, 0, 2 ** 31 - 1, type=INT))

        def step(self, x, u, p):
            pool = [u.x[0], u.x[1], u.x[2], x.s, p.k, select(u.flag, u.x[0], x.s)]
            for ins in program:
                pool.append(interpret(pool, ins))
            n = inc_if(x.n, pool[-1] > 0.0)
            return ({"s": clamp(pool[-1], -10.0, 10.0), "n": n},
                    {"y": (pool[-1], pool[-2], pool[-3]), "b": pool[-2] < pool[-1], "n": n})

    return Prog()


def random_inputs(rng, n):
    x = rng.normal(0, 40, (n, 3))
    special = rng.random((n, 3)) < 0.05
    x[special] = rng.choice(np.array([np.nan, np.inf, -np.inf, 150.0, -1e12, 0.0]), special.sum())
    return {"x": x, "flag": rng.random(n) < 0.5}


_uid = iter(range(10 ** 9))


@settings(max_examples=12, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(program=programs, seed=st.integers(0, 2 ** 16))
# found in CI: a clamp to a subnormal range (the Q-format choice overflowed)
@example(program=[(0, 0, 0, 0, 1.0), (0, 0, 0, 0, 1.0), (11, 0, 0, 0, 2.225073858507e-311)], seed=0)
# the fixed-point select of a dynamic-point rsqrt did not compile (found in flagship's renorm)
@example(program=[(15, 0, 1, 2, 1.0), (2, 6, 3, 0, 1.0)], seed=1)
# scaled rnorm, split (i even) and not (i odd)
@example(program=[(16, 0, 1, 2, 3.0), (16, 1, 6, 0, 5.0), (2, 6, 7, 0, 1.0)], seed=2)
def test_random_program_c_equals_model(program, seed, tmp_path):
    est = make_estimator(program, next(_uid))
    runners = build_adhoc(est, tmp_path / est.name)
    inputs = random_inputs(np.random.default_rng(seed), 300)
    for system, (c, m) in runners.items():
        enc = c.encode(inputs, {"k": 1.3})
        oc, om = c.run_encoded(enc), m.run_encoded(enc)
        for key in oc:
            bc, bm = bits(oc[key]).reshape(300, -1), bits(om[key]).reshape(300, -1)
            bad = np.flatnonzero(np.any(bc != bm, axis=1))
            assert bad.size == 0, (f"{system} output {key} differs at samples {bad[:5]}: "
                                   f"C {oc[key][bad[0]]} model {om[key][bad[0]]} "
                                   f"inputs {enc.inputs['x'][bad[0]]}")


@pytest.mark.parametrize("split", [True, False], ids=["split", "unsplit"])
def test_scaled_rnorm_is_c_over_the_norm(split, tmp_path):
    # y = x0 * c / |(x0, x1)| with c = 3 / (|x2| + 1): the generated C of both number systems
    # against the float64 value (C and model agreeing is the test above)
    class Scaled(Estimator):
        """scaled rnorm"""
        name = f"scaled{next(_uid)}"
        inputs = InputSpec(name, (Var("x", 3, -100.0, 100.0),))
        params = ()
        state = (Var("n", 1, 0, 2 ** 31 - 1, type=INT, init=0),)
        outputs = (Var("y", 1, -3.0, 3.0),)

        def step(self, x, u, p):
            k, _ = rnorm((u.x[0], u.x[1]), 1e-6, split=split,
                         scale=3.0 / (fabs(u.x[2]) + 1.0))
            return {"n": x.n}, {"y": assume(u.x[0] * k, -3.0, 3.0)}

    runners = build_adhoc(Scaled(), tmp_path / "scaled")
    x = np.clip(np.random.default_rng(7).normal(0, 40, (300, 3)), -99.0, 99.0)
    x[:5, :2] = [[0.0, 0.0], [1e-4, 0.0], [0.0, -3e-4], [99.0, 99.0], [-0.5, 1e-3]]
    for system, tol in (("f32", 1e-6), ("q", 1e-6)):
        c, _ = runners[system]
        enc = c.encode({"x": x}, {})
        xq = c.decode_values("input", "x", "real", enc.inputs["x"])   # as the filter sees them
        a, b = xq[:, 0], xq[:, 1]
        want = a * (3.0 / (np.abs(xq[:, 2]) + 1.0)) / np.sqrt(np.maximum(a * a + b * b, 1e-6))
        got = c.decode_values("output", "y", "real", c.run_encoded(enc)["y"][:, 0])
        err = np.abs(got - want)
        assert np.max(err) < tol, (system, np.max(err), int(np.argmax(err)))
