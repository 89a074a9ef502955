"""`kinefuse filters` and `kinefuse params --describe`: the ranges they show are ranges the
checks accept."""
from __future__ import annotations

import re

import numpy as np
import pytest

MINE = ("filters_cmd", "params_cmd")


def _range(line: str) -> tuple[float, float]:
    m = re.search(r"\[(\S+), (\S+)\]", line)
    assert m, line
    return float(m[1]), float(m[2])


def test_filters_shows_bounds_the_range_check_accepts(run, monkeypatch):
    """heading_rw's max 0.08726646 (5 deg/s^0.5) was shown as 0.0872665, and
    --param heading_rw=0.0872665 was then refused as outside the range."""
    from kinefuse.host import runner
    monkeypatch.setenv("COLUMNS", "400")      # one table row per line
    code, out, err = run("filters", "flagship", "eskf")
    assert code == 0, err
    checked = 0
    for name in ("flagship", "eskf"):
        block = out.split(f"{name} — ", 1)[1].split("  outputs:", 1)[0]
        for line in block.splitlines():
            cells = [c.strip() for c in re.split(r"[│┃]", line)]
            if len(cells) < 4 or not cells[3].startswith("["):
                continue
            lo, hi = _range(cells[3])
            for v in (lo, hi):
                runner.check_params(name, {cells[0]: v}, None)      # raises when refused
            checked += 1
        if name == "flagship":
            assert "[0.000174533, 0.0872664]" in block        # heading_rw, rounded into its range
    assert checked > 20


def test_describe_ranges_are_inside_the_units_float32_range():
    from kinefuse.firmware.apptables import parameter_table
    from kinefuse.host.commands.params_cmd import _describe_text, describe
    rows = [r for r in parameter_table() if not r["choices"]]
    info = describe([r["name"] for r in rows])
    lossy = 0
    for r in rows:
        lo, hi = _range(_describe_text(info[r["name"]]))
        assert np.float32(r["min"]) <= np.float32(lo) <= np.float32(hi) <= np.float32(r["max"]), r["name"]
        lossy += f"{r['max']:g}" != repr(float(r["max"]))
    assert lossy        # some bounds do not fit 6 digits (else this checks nothing)


@pytest.mark.parametrize("v, upper, text", [
    (0.08726646259971647, True, "0.0872664"), (0.08726646259971647, False, "0.0872665"),
    (-0.08726646259971647, True, "-0.0872665"), (0.5, True, "0.5"), (2000, True, "2000"),
    (4294967295, True, "4294967295"), (float("inf"), True, "inf"),
])
def test_bound_text_rounds_into_the_range(v, upper, text):
    from kinefuse.host.commands.filters_cmd import bound_text
    assert bound_text(v, upper) == text


def test_params_describe_of_a_unit(run):
    code, out, err = run("params", "--port", "fake:rate=500", "--describe")
    assert code == 0, err
    lines = {ln.split(" = ")[0]: ln for ln in out.splitlines() if " = " in ln}
    assert "([1, 2000], default 1000) sensor sample rate" in lines["KF_RATE_HZ"]
    assert lines["KF_ACC_TAU_S"].endswith("(not in this host's firmware tables)")


def test_a_range_error_shows_bounds_the_check_accepts():
    """heading_rw's max 0.08726646 was shown as 0.0872665 in the refusal, a value refused again."""
    import re

    from kinefuse.codegen import estimators
    est = estimators.get("flagship")
    with pytest.raises(ValueError) as exc:
        est.resolve_params({"heading_rw": 1.0})
    lo, hi = re.search(r"outside \[([^,]+), ([^\]]+)\]", str(exc.value)).groups()
    assert hi != f"{0.08726646259971647:g}"       # the 6-digit rounding that lies outside
    for v in (lo, hi):
        assert est.resolve_params({"heading_rw": float(v)})["heading_rw"] == float(v)
