"""Parameter declarations: switches and choices are declared as such (``Param.choices``), and
``Estimator.resolve_params`` (every host entry point: run, replay, bench, plot, presets) takes
exactly the declared values; presets name only declared parameters."""
from __future__ import annotations

import math

import pytest

from kinefuse.codegen import estimators
from kinefuse.codegen.estimator import Estimator, Param

# parameters the step reads as a switch or an index (``p.mode > 0.5``, ``fabs(p.sequence - s)``)
CHOICES = {("flagship", "mode"): (0.0, 1.0), ("eskf", "mode"): (0.0, 1.0),
           ("vac", "adaptive"): (0.0, 1.0), ("triad", "primary"): (0.0, 1.0),
           ("joint-angle", "sequence"): (0.0, 1.0, 2.0), ("joint-angle", "mirror"): (0.0, 1.0)}


@pytest.mark.parametrize("name, param", sorted(CHOICES))
def test_switches_are_declared_as_choices(name, param):
    p = estimators.get(name).param(param)
    assert p.choices == CHOICES[name, param] and p.unit == ""


def test_only_the_known_switches_are_choices():
    declared = {(n, p.name) for n, cls in estimators.ESTIMATORS.items() for p in cls.params
                if p.choices}
    assert declared == set(CHOICES)


@pytest.mark.parametrize("value", [0.5, 0.7, 0.25, 0.999, 1e-9, 2.0, -1.0,
                                   math.nan, math.inf, "7d", "", "half"])
def test_flagship_mode_refuses_what_is_not_a_choice(value):
    est = estimators.get("flagship")
    with pytest.raises(ValueError, match="mode") as exc:
        est.resolve_params({"mode": value})
    assert "\n" not in str(exc.value)


@pytest.mark.parametrize("value, want", [(0.0, 0.0), (1, 1.0), ("6d", 0.0), ("9D", 1.0),
                                         (" 6d ", 0.0), ("0", 0.0), (True, 1.0)])
def test_flagship_mode_takes_its_choices_and_labels(value, want):
    for name in ("flagship", "eskf"):
        assert estimators.get(name).resolve_params({"mode": value})["mode"] == want


def test_labels_belong_to_their_parameter():
    """``6d`` is the flagship's mode, not a number any parameter takes (beta=6d was 0)."""
    with pytest.raises(ValueError, match="not a number"):
        estimators.get("madgwick").resolve_params({"beta": "6d"})
    with pytest.raises(ValueError, match="not a number"):
        estimators.get("vac").resolve_params({"adaptive": "9d"})


def test_joint_sequence_and_mirror():
    est = estimators.get("joint-angle")
    assert est.resolve_params({"sequence": 2, "mirror": True})["sequence"] == 2.0
    for bad in ({"sequence": 1.5}, {"sequence": 0.4}, {"mirror": 0.5}):
        with pytest.raises(ValueError, match="choices"):
            est.resolve_params(bad)


def test_non_finite_values_are_refused_for_every_parameter():
    for cls in estimators.ESTIMATORS.values():
        for p in cls.params:
            for v in (math.nan, math.inf, -math.inf):
                with pytest.raises(ValueError, match="not finite"):
                    cls.resolve_params({p.name: v})


def test_every_preset_is_valid_and_an_override_wins():
    for cls in estimators.ESTIMATORS.values():
        for preset, values in cls.presets.items():
            prm = cls.resolve_params(None, preset)
            assert all(prm[k] == v for k, v in values.items())
    mw = estimators.get("madgwick")
    assert mw.resolve_params({"beta": 0.05}, "seed001")["beta"] == 0.05      # override > preset
    assert mw.resolve_params(None, "seed001")["beta"] == 0.03
    with pytest.raises(ValueError, match="outside"):
        mw.resolve_params({"beta": 50.0}, "seed001")


def test_a_preset_naming_an_unknown_parameter_is_refused():
    class Bad(Estimator):
        name = "bad"
        params = (Param("gain", 1.0, "", 0.0, 2.0, "a gain"),)
        presets = {"typo": {"gian": 0.5}}
    with pytest.raises(ValueError, match="gian"):
        Bad.resolve_params(None, "typo")


def test_choices_must_be_the_whole_numbers_of_the_range():
    with pytest.raises(ValueError):
        Param("m", 0.0, "", 0.0, 1.0, "", choices=(0.0, 0.5, 1.0))
    with pytest.raises(ValueError):
        Param("m", 0.5, "", 0.0, 1.0, "", choices=(0.0, 1.0))      # default not a choice
    with pytest.raises(ValueError):
        Param.choice("m", 0.0, 2, "", labels=("a",))                 # one label for two choices


@pytest.mark.parametrize("system", ["f32", "q"])
@pytest.mark.parametrize("name, param", sorted(CHOICES))
def test_generated_init_takes_only_the_choices(name, param, system):
    """The C API's own guard: <f>_init refused a switch only outside [lo, hi], so a caller that
    skipped the host and unit checks could set mode = 0.5 (read as 9D by p.mode > 0.5)."""
    from kinefuse.codegen.build import build_filter
    from kinefuse.codegen.generate import lowered

    est = estimators.get(name)
    lo = lowered(name, system)
    P = f"{name.replace('-', '_')}_{system}"
    ffi, lib = build_filter(name, system)
    index = [p.name for p in est.params].index(param)

    def status(value):
        prm = ffi.new(f"{P}_params *")
        getattr(lib, f"{P}_default_params")(prm)
        if system == "f32":
            setattr(prm, param, value)
        else:
            setattr(prm, param, int(lo.sys.to_model(est.param(param).as_var(), [value], "param")[0]))
        st = ffi.new(f"{P}_state *")
        return getattr(lib, f"{P}_init")(st, prm)

    for c in CHOICES[name, param]:
        assert status(c) == 0
    choices = CHOICES[name, param]
    for bad in (0.5, choices[-1] - 0.25, 0.125):
        assert status(bad) == -(index + 1), bad
