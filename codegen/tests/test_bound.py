"""scalar.bound: a clamp for the fixed-point range analysis only.

The float64 reference and the fixed-point path clamp (the same min/max nodes and fixed-point
code as scalar.clamp), binary32 emits nothing.  A bound is only right where the value never
leaves its bounds: then binary32 gives the bits it would give with the clamp, and differs from
the reference exactly as before.  These tests check the lowering (no binary32 statement, the
fixed-point clamp kept), that every bound of the registered filters is inactive on the test data
(counted in the reference), and that the binary32 C with every bound lowered as a clamp gives
the same bits as the generated C on that data (a bound that became active would differ there).
"""
from __future__ import annotations

import re
import types

import numpy as np
import pytest

from kinefuse.codegen import estimators, passes, scalar
from kinefuse.codegen import runner as cg
from kinefuse.codegen.emit import Lowered
from kinefuse.codegen.estimator import run_reference
from kinefuse.codegen.generate import GENERATED_DIR, _files_of, graph_of, source_file
from kinefuse.codegen.scalar import Sym, bound, clamp
from kinefuse.codegen.testing import random_imu

#: registered filters using bound(), with their number of bound nodes (min and max each count)
USERS = {"flagship": 30}


def _bound_nodes(name: str):
    return [n for n in graph_of(name).nodes if "bound" in n.attrs]


def test_registered_users_are_listed():
    found = {name: len(_bound_nodes(name)) for name in estimators.ESTIMATORS
             if _bound_nodes(name)}
    assert found == USERS


def test_reference_clamps_and_refuses_traced_limits():
    assert bound(25.0, -20.0, 20.0) == 20.0 and bound(-0.5, 0.0, 1.0) == 0.0
    assert bound(float("nan"), -1.0, 1.0) == clamp(float("nan"), -1.0, 1.0) == -1.0
    with pytest.raises(ValueError):
        bound(0.0, 1.0, -1.0)
    from kinefuse.codegen.ir import Graph
    g = Graph("t")
    x = Sym(g, g.input("input", "x", 0))
    with pytest.raises(TypeError):
        bound(0.0, x, 1.0)
    y = bound(x, -2.0, 2.0)
    assert [n.op for n in g.nodes if n.op not in ("const", "input")] == ["max", "min"]
    assert all(n.attrs == ("bound",) for n in g.nodes if n.op in ("min", "max"))
    assert y.n.op == "min"


@pytest.mark.parametrize("name", sorted(USERS))
def test_float32_c_has_no_bound_statement_and_fixed_point_keeps_the_clamp(name):
    """The f32 C of the filter computes no value of a bound node (its value is the clamped
    operand itself); the q C assigns every one (the saturation the range analysis needs)."""
    P = name.replace("-", "_")
    f32 = (GENERATED_DIR / f"{P}_f32.c").read_text()
    q = (GENERATED_DIR / f"{P}_q.c").read_text()
    nodes = _bound_nodes(name)
    assert len(nodes) == USERS[name]
    for n in nodes:
        assert not re.search(rf"\bt{n.id}\b", f32), f"f32 C computes bound node t{n.id} ({n.loc})"
        assert re.search(rf"const int32_t t{n.id} = ", q), f"q C lacks bound node t{n.id}"
    # the f32 OPS.md row leaves them out, the q row does not
    ops = (GENERATED_DIR / "OPS.md").read_text()
    rows = dict(re.findall(rf"^\| {re.escape(name)} \| (\w+) \| (\d+) ops", ops, re.M))
    assert int(rows["q"]) - int(rows["f32"]) == USERS[name]


# -- the test data -------------------------------------------------------------------------

def _extremes(count: int = 12, n: int = 300):
    """In-range but extreme inputs as the property tests draw them (rates up to 30 rad/s,
    specific force up to 15 g, field up to 90x the earth's, dt 0.1 ms to 1 s)."""
    from kinefuse.hil_tests.harness import motion, props
    rng0 = np.random.default_rng(2026)
    for k in range(count):
        dt = float((1e-4, 0.001, 0.01, 0.1, 1.0)[k % 5])
        rng = np.random.default_rng(int(rng0.integers(0, 2 ** 32 - 1)))
        ins, _ = motion.synth(motion.random_unit_quaternion(rng),
                              props.smooth_rates(rng, n, 1.0 / dt, float(rng0.uniform(0, 30))), dt)
        ins["acc"] = ins["acc"] * float(rng0.uniform(0, 15)) + rng.normal(0, 1.0, (n, 3))
        ins["mag"] = ins["mag"] * float(rng0.uniform(0, 90)) + rng.normal(0, 1.0, (n, 3))
        ins["mag_valid"] = np.arange(n) % (1 + k % 5) == 0
        yield f"extreme{k}", ins


@pytest.fixture(scope="module")
def data():
    """(label, IMU inputs): the bundled BROAD excerpt, the simulator's CI cases, the catalogue
    test's hostile samples, random samples with bad values, property-test extremes."""
    from kinefuse.hil_tests.harness import scenarios
    from kinefuse.host import broad, runner
    import test_catalogue_bitexact as cat
    out = [("broad-excerpt", runner.imu_inputs(broad.load_trial(broad.bundled_trials()[0])))]
    out += [(c.name, c.inputs) for c in scenarios.ci_cases(seconds=6.0)]
    out.append(("hostile", cat.imu_inputs()[0]))
    out.append(("random-bad", random_imu(2000, seed=5, bad_fraction=0.05)))
    out += list(_extremes())
    return out


@pytest.mark.parametrize("name", sorted(USERS))
def test_no_bound_is_active_on_the_test_data(name, data, monkeypatch):
    """Every reference evaluation of a bound on the test data finds its operand within the
    bounds (the reference evaluates conditional regions too, so this covers more than the
    generated code runs)."""
    calls, active = [0], []

    def hook(x, lo, hi):
        calls[0] += 1
        if not lo <= x <= hi:
            active.append((x, lo, hi))

    monkeypatch.setattr(scalar, "_BOUND_HOOK", hook)
    est = estimators.get(name)
    for label, inputs in data:
        run_reference(est, inputs)
        assert not active, f"{name}: a bound is active on {label}: {active[:3]}"
    assert calls[0] > 0


def _clamped_f32(name: str, tmp_path):
    """The f32 C (and its runner) of `name` with every bound lowered as the clamp it is in the
    reference: the code the generator wrote before bound()."""
    from kinefuse.codegen.build import build

    def unbound(ng, n, args):
        new = passes._copy(ng, n, args)
        if "bound" in n.attrs:
            new.attrs = tuple(a for a in n.attrs if a != "bound")
        return new

    est = estimators.get(name)
    lo = Lowered(est, passes.rebuild(graph_of(name), unbound), "f32")
    files = _files_of(lo, source_file(name))
    for rel, text in files.items():
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text(text)
    P = lo.prefix
    mod = types.ModuleType(f"clamped_{P}")
    exec(compile(files[f"models/{P}.py"], f"<model {P}>", "exec"), mod.__dict__)
    spec_h = tmp_path / f"kf_{est.inputs.name}_f32.h"
    ffi_lib = build(f"clamped_{P}", [spec_h, tmp_path / f"{P}.h"], [tmp_path / f"{P}.c"],
                    include_dirs=[tmp_path, GENERATED_DIR])
    return files[f"{P}.c"], cg.CRunner(name, "f32", mod, ffi_lib, est.inputs.name)


@pytest.mark.parametrize("name", sorted(USERS))
def test_float32_bits_are_those_of_the_clamps(name, data, tmp_path):
    """The generated f32 C and the same C with the bounds as clamps give identical bits on
    the test data."""
    src, clamped = _clamped_f32(name, tmp_path)
    assert src.count("? ") > (GENERATED_DIR / f"{name.replace('-', '_')}_f32.c").read_text() \
        .count("? ") + USERS[name] - 1      # the variant does clamp
    est = estimators.get(name)
    prm = est.resolve_params({})
    for label, inputs in data:
        got = cg.run(name, "f32", inputs, prm, raw=True)
        ref = clamped.run_encoded(clamped.encode(inputs, prm))
        for key in got:
            assert np.array_equal(cg.bits(got[key]), cg.bits(ref[key])), (label, key)
