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

    def job(kind, a, b, c, k, mix, profile=False, top=12):
        calls.append((kind, a, b, c))
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
