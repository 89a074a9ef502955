"""What the author of a new estimator reference gets when it breaks the generator's rules
(codegen/scalar.py): one error naming the estimator, the source line and the rule."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest

from kinefuse.codegen import estimators
from kinefuse.codegen.emit import Lowered
from kinefuse.codegen.estimator import Estimator, EstimatorError, InputSpec, Param, Var, trace
from kinefuse.codegen.fixed import RangeError
from kinefuse.codegen.ir import BOOL, INT
from kinefuse.codegen.passes import optimize
from kinefuse.codegen.scalar import fmax, rsqrt, select, sqrt

COUNTER = Var("n", 1, 0, 2 ** 31 - 1, type=INT, init=0)


def make(name, step, state=(Var("s", 1, -10.0, 10.0), COUNTER),
         outputs=(Var("y", 1, -100.0, 100.0),)):
    """A small estimator whose step is `step(x, u, p) -> value of output y`."""
    class Broken(Estimator):
        """a deliberately broken reference"""
        inputs = InputSpec(name.replace("-", "_"), (Var("x", 2, -10.0, 10.0),
                                                    Var("ok", 1, 0, 1, type=BOOL)))
        params = (Param("k", 1.0, "", 0.5, 2.0, "a parameter"),)

        def step(self, x, u, p):
            return {"s": x.s, "n": x.n}, {"y": step(x, u, p)}

    Broken.name, Broken.state, Broken.outputs = name, state, outputs
    return Broken()


def generate(est):
    g = optimize(trace(est))
    for system in est.systems:
        Lowered(est, g, system)


# each broken line carries its case name in a comment: the error must point at that line
CASES = {
    "if": (lambda x, u, p: u.x[0] if u.x[0] > 0.0 else x.s,  # case:if
           "select(cond, a, b)"),
    "and": (lambda x, u, p: select(u.x[0] > 0.0 and u.ok, 1.0, 0.0),  # case:and
            "logical_and/or/not"),
    "builtin-min": (lambda x, u, p: min(u.x[0], 1.0),  # case:builtin-min
                    "fmin/fmax"),
    "math-sqrt": (lambda x, u, p: math.sqrt(u.x[0] * u.x[0]),  # case:math-sqrt
                  "no math.*"),
    "math-sin": (lambda x, u, p: math.sin(u.x[0]),  # case:math-sin
                 "mathlib"),
    "numpy": (lambda x, u, p: np.sqrt(u.x[0] * u.x[0]),  # case:numpy
              "no numpy"),
    "pow": (lambda x, u, p: u.x[0] ** 2,  # case:pow
            "x * x"),
    "invert": (lambda x, u, p: select(~u.ok, 1.0, 0.0),  # case:invert
               "logical_not"),
    "undeclared": (lambda x, u, p: u.gyro,  # case:undeclared
                   "no input named 'gyro'"),
    "int-arith": (lambda x, u, p: x.n * 2.0,  # case:int-arith
                  "counters"),
}


def _line_of(case: str) -> int:
    for i, line in enumerate(open(__file__).read().splitlines(), start=1):
        if line.rstrip().endswith(f"# case:{case}"):
            return i
    raise AssertionError(case)


@pytest.mark.parametrize("case", list(CASES))
def test_rule_break_names_estimator_line_and_rule(case):
    step, rule = CASES[case]
    with pytest.raises(ValueError) as exc:
        generate(make(f"brk_{case}", step))
    msg = str(exc.value)
    assert isinstance(exc.value, EstimatorError), repr(exc.value)
    assert msg.startswith(f"brk_{case}: "), msg
    assert f"test_generator_errors.py:{_line_of(case)}" in msg, msg
    assert rule in msg, msg
    assert "\n" not in msg


def test_step_must_return_two_dicts():
    class NoReturn(Estimator):
        """returns nothing"""
        name = "brk_noreturn"
        inputs = InputSpec("brk_noreturn", (Var("x", 1),))
        outputs = (Var("y"),)

        def step(self, x, u, p):
            pass

    with pytest.raises(EstimatorError, match=r"brk_noreturn.step must return \(next_state"):
        trace(NoReturn())


def test_wrong_result_type_names_the_estimator():
    est = make("brk_type", lambda x, u, p: u.ok)
    with pytest.raises(EstimatorError, match="brk_type.step: output y: declared real, step "
                                             "returned bool"):
        trace(est)


def _helper(v):
    return v if v > 0.0 else -v  # case:helper


def test_helper_frames_name_the_estimator_line_too():
    class UsesHelper(Estimator):
        """a rule broken in a helper step() calls"""
        name = "brk_helper"
        inputs = InputSpec("brk_helper", (Var("x", 1),))
        outputs = (Var("y"),)

        def step(self, x, u, p):
            return {}, {"y": _helper(u.x)}  # case:helper-call

    with pytest.raises(EstimatorError) as exc:
        trace(UsesHelper())
    msg = str(exc.value)
    assert f":{_line_of('helper')} " in msg and f":{_line_of('helper-call')} " in msg, msg


@pytest.mark.parametrize("case, step, words", [
    ("sqrt", lambda x, u, p: sqrt(u.x[0]), "sqrt argument range"),  # case:r-sqrt
    ("div", lambda x, u, p: 1.0 / u.x[0], "divisor range"),  # case:r-div
    ("rsqrt", lambda x, u, p: rsqrt(u.x[0] * u.x[0]), "rsqrt argument range"),  # case:r-rsqrt
])
def test_unguarded_operation_names_line_range_and_guard(case, step, words):
    with pytest.raises(RangeError) as exc:
        generate(make(f"brk_r{case}", step))
    msg = str(exc.value)
    assert msg.startswith(f"brk_r{case}: {words}"), msg
    assert f"test_generator_errors.py:{_line_of('r-' + case)}" in msg, msg
    assert "guard it" in msg and "fmax" in msg, msg
    if case != "rsqrt":
        # the operand is the sample input x: named, with the declared range it was widened from
        assert "input x[0]" in msg and "declared [-10, 10]" in msg, msg


def test_guarded_versions_pass():
    generate(make("ok_guarded", lambda x, u, p: sqrt(fmax(u.x[0], 0.0)) + 1.0 / fmax(u.x[1], 0.5)))


def test_unbounded_state_range_names_the_variable():
    est = make("brk_infstate", lambda x, u, p: x.s * 2.0,
               state=(Var("s", 1, -math.inf, math.inf), COUNTER))
    with pytest.raises(RangeError, match=r"brk_infstate: declared range \[-inf, inf\] of state s "
                                         r"is unbounded"):
        generate(est)


def test_unbounded_output_range_names_the_variable():
    est = make("brk_infout", lambda x, u, p: x.s, outputs=(Var("y", 1, 0.0, math.inf),))
    with pytest.raises(RangeError, match=r"brk_infout: output y: declared range \[0, inf\] is "
                                         r"unbounded"):
        generate(est)


def test_empty_range_is_refused():
    est = make("brk_empty", lambda x, u, p: x.s,
               state=(Var("s", 1, 10.0, -10.0), COUNTER))
    with pytest.raises(EstimatorError, match=r"brk_empty: state s: declared range \[10, -10\] "
                                             r"is empty"):
        generate(est)


def test_product_of_two_reciprocal_roots_names_the_line():
    def step(x, u, p):
        return rsqrt(fmax(u.x[0], 1.0)) * rsqrt(fmax(u.x[1], 1.0))  # case:dyn

    est = make("brk_dyn", step)
    with pytest.raises(RangeError) as exc:
        generate(est)
    msg = str(exc.value)
    assert msg.startswith("brk_dyn: product of two reciprocal square roots"), msg
    assert f"test_generator_errors.py:{_line_of('dyn')}" in msg, msg


def test_cli_reports_a_broken_reference_in_one_line(monkeypatch, tmp_path, capsys):
    from kinefuse.codegen import generate as gen
    from kinefuse.host import cli
    est = make("brk_cli", lambda x, u, p: math.sqrt(u.x[0]))  # case:cli
    monkeypatch.setitem(estimators.ESTIMATORS, "brk_cli", type(est))
    monkeypatch.setattr(gen, "GENERATED_DIR", tmp_path)
    for argv in (["codegen", "--filter", "brk_cli"], ["codegen", "--check", "--filter", "brk_cli"]):
        assert cli.main(argv) == 2
        err = capsys.readouterr().err
        assert "Traceback" not in err and "internal error" not in err, err
        assert len(err.strip().splitlines()) == 1, err
        assert "brk_cli" in err and f":{_line_of('cli')} " in err and "no math.*" in err, err
    assert not list(tmp_path.iterdir())        # nothing written


@pytest.mark.parametrize("change, words", [
    (dict(name="my filter"), "filter name 'my filter' is not usable as a C identifier"),
    (dict(state=(Var("int", 1, -10.0, 10.0), COUNTER)), "state 'int' is not usable"),
    (dict(state=(Var("s", 1, -10.0, 10.0), Var("s", 1), COUNTER)), "state 's' is declared twice"),
    # x_q0 would be both the first component of q and the scalar q0 (silently one value in the
    # Python model)
    (dict(state=(Var("q", 2), Var("q0", 1), COUNTER)), "become the C variable x_q0"),
    (dict(state=(Var("q", 4, init=(1.0, 0.0, 0.0)), COUNTER)),
     "brk_names: state q: init has 3 values, size is 4"),
    # fixed point would clip it to 1 without a word
    (dict(state=(Var("s", 1, 0.0, 1.0, init=1.5), COUNTER)),
     "state s: initial value 1.5 outside its declared range [0, 1]"),
])
def test_names_that_cannot_become_c_are_refused(change, words):
    est = make("brk_names", lambda x, u, p: 0.0, state=change.get("state", (Var("s"), COUNTER)))
    if "name" in change:
        type(est).name = change["name"]
    with pytest.raises(EstimatorError, match=re.escape(words)):
        generate(est)


def test_conflicting_shared_input_record_is_refused(monkeypatch):
    from kinefuse.codegen.generate import render_all
    a = make("brk_share_a", lambda x, u, p: x.s)
    b = make("brk_share_b", lambda x, u, p: x.s)
    type(b).inputs = InputSpec(type(a).inputs.name, (Var("x", 3, -10.0, 10.0),
                                                     Var("ok", 1, 0, 1, type=BOOL)))
    for est in (a, b):
        monkeypatch.setitem(estimators.ESTIMATORS, est.name, type(est))
    render_all(["brk_share_a"])            # each alone is fine
    with pytest.raises(ValueError, match=r"filters brk_share_a and brk_share_b both generate "
                                         r"kf_brk_share_a_f32\.h, with different contents"):
        render_all(["brk_share_a", "brk_share_b"])
