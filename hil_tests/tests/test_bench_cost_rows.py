"""``kinefuse bench cost``: the rows promised by its --json schema (impl kinefuse|fusion|vqf),
and no row left out without a word.  Nothing is measured here: the measurement of one row is
replaced by a stub, QEMU's presence is faked and the pool runs threads."""
from __future__ import annotations

import concurrent.futures
import json

import pytest

from kinefuse.host.bench import common, cost
from kinefuse.host.cli import main
from kinefuse.host.errors import KinefuseError


@pytest.fixture
def fake_measure(monkeypatch):
    import kinefuse.hil_tests.qemu as q
    monkeypatch.setattr(q, "qemu_unavailable", lambda *a, **k: None)
    monkeypatch.setattr(concurrent.futures, "ProcessPoolExecutor", concurrent.futures.ThreadPoolExecutor)
    calls = []

    def job(kind, a, b, c, k, mix, profile=False, top=12, sensors="9d"):
        calls.append((kind, a, b, c, sensors))
        return {"impl": "kinefuse" if kind == "ours" else cost.competitor_impl(a), "filter": a,
                "format": b, "target": c, "instructions_per_update": 1.0, "flash_bytes": 1,
                "ram_bytes": 1, "k": k}
    monkeypatch.setattr(cost, "_job", job)
    return calls


@pytest.mark.parametrize("case,impl", [("fusion-ahrs-9d", "fusion"), ("vqf-9d-f32", "vqf")])
def test_a_failed_competitor_row_keeps_its_impl(monkeypatch, case, impl):
    # (the error row said impl "competitor": outside kinefuse|fusion|vqf, and no longer
    # matched with that library's other rows)
    def fail(*a, **k):
        raise KinefuseError("sdist not available offline")
    monkeypatch.setattr(cost, "measure_competitor", fail)
    row = cost._job("competitor", case, "f32", "m0", 1000, False)
    assert row["impl"] == impl and row["error"] == "sdist not available offline"
    assert row["instructions_per_update"] is None


def test_no_competitor_rows_without_f32_is_said(fake_measure, capsys):
    # --formats q dropped the Fusion and VQF rows without a word
    assert main(["bench", "cost", "--filters", "madgwick", "--formats", "q", "--targets", "m4f",
                 "--json"]) == 0
    out, err = capsys.readouterr()
    d = json.loads(out)
    rows = d["rows"]
    assert [(r["impl"], r["format"]) for r in rows] == [("kinefuse", "q")]
    assert "bytes" in d["units"] and "size_by_origin" in d["units"]
    assert "Fusion and VQF" in err and "f32" in err


def test_k_of_the_competitor_rows_is_said(fake_measure, capsys):
    assert main(["bench", "cost", "--filters", "madgwick", "--formats", "f32", "--targets", "m4f",
                 "--k", "100", "--json"]) == 0
    out, err = capsys.readouterr()
    assert {r["impl"] for r in json.loads(out)["rows"]} == {"kinefuse", "fusion", "vqf"}
    assert "--k 100" in err and "1000" in err


def test_json_run_shows_progress(fake_measure, monkeypatch, capsys):
    # the bar is on stderr; --json switched it off for a run of many minutes
    enabled = []
    real = common.progress

    def spy(on=True):
        enabled.append(on)
        return real(on)
    monkeypatch.setattr(common, "progress", spy)
    assert main(["bench", "cost", "--filters", "madgwick", "--formats", "f32", "--targets", "m4f",
                 "--no-competitors", "--json"]) == 0
    json.loads(capsys.readouterr().out)
    assert enabled == [True]


def test_a_trailing_comma_in_filters(fake_measure, capsys):
    # "madgwick," was refused as an unknown filter ''
    assert main(["bench", "cost", "--filters", "madgwick,", "--formats", "f32", "--targets", "m4f",
                 "--no-competitors", "--json"]) == 0
    assert [r["filter"] for r in json.loads(capsys.readouterr().out)["rows"]] == ["madgwick"]


def test_sensors_6d_plans_rows_without_magnetometer(fake_measure, capsys):
    assert main(["bench", "cost", "--filters", "madgwick,angle-kf", "--formats", "f32",
                 "--targets", "m4f", "--sensors", "9d,6d", "--json"]) == 0
    json.loads(capsys.readouterr().out)
    ours = [c for c in fake_measure if c[0] == "ours"]
    assert ours == [("ours", "madgwick", "f32", "m4f", "9d"), ("ours", "madgwick", "f32", "m4f", "6d"),
                    ("ours", "angle-kf", "f32", "m4f", None)]
    comp = {c[1]: c[4] for c in fake_measure if c[0] == "competitor"}
    assert comp == {"fusion-ahrs-9d": "9d", "fusion-ahrs-6d": "6d", "vqf-9d-f32": "9d",
                    "vqf-6d-f32": "6d"}


@pytest.mark.parametrize("given", ["", "9d,5d", "6d,6d"])
def test_sensors_refused(given, capsys):
    assert main(["bench", "cost", "--sensors", given]) != 0
    err = capsys.readouterr().err
    assert "--sensors" in err and "Traceback" not in err


def test_the_6d_table_has_no_magnetometer_reading():
    # the 6D rows are only 6D if no sample of their input table carries a reading
    from kinefuse.hil_tests.harness import cost as hc
    for sensors, want in (("9d", "1u"), ("6d", "0u")):
        c, _d, ctype, n = hc._table_sources("madgwick", "f32", sensors)
        body = c.read_text()
        assert f"kf_cost_in_{'6d_' if sensors == '6d' else ''}f32[KF_COST_N]" in body
        rows = [r for r in body.splitlines() if r.startswith("{")]
        assert len(rows) == n
        # mag_valid is the field after the three mag components: "}, 1u, " / "}, 0u, "
        assert all(f"}}, {want}, " in r for r in rows)
