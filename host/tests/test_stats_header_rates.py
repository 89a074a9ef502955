"""A damaged recording header (still valid text) whose ``requested_rates_hz`` is not a map of
message names to rates: stats warns and ignores the field (it was a traceback: ``.get`` of a
list, a rate divided by a string)."""
from __future__ import annotations

import json

import pytest

from kinefuse.host.link.fakeunit import raw_frames
from kinefuse.host.link.recording import RecordingWriter, make_header

MINE = ("stats_cmd",)


def _recording(path, rates):
    info = {"id": 0, "connection": "fake:test", "requested_rates_hz": rates}
    head = make_header([info])
    t0 = head["start_monotonic_ns"]
    data = raw_frames(400, rate_hz=200)     # no KF_UNIT_STATUS: the header's rate is the one asked
    with RecordingWriter(path, head) as w:
        w.rx(0, [(t0 + 1_000_000 * k, data[k * 460:(k + 1) * 460]) for k in range(len(data) // 460 + 1)])
    return path


@pytest.mark.parametrize("rates", [["KF_RAW_SAMPLE", 200], "200", {"KF_RAW_SAMPLE": "fast"},
                                   {"KF_RAW_SAMPLE": [200]}, 7, {"KF_RAW_SAMPLE": True}])
def test_a_bad_requested_rates_field_is_a_warning(run, tmp_path, rates):
    path = _recording(tmp_path / "bad.kfr", rates)
    code, out, err = run("stats", path, "--json")
    assert code == 0 and "Traceback" not in err, err
    res = json.loads(out)
    assert any("requested_rates_hz" in w and "ignored" in w for w in res["warnings"]), res["warnings"]
    m = res["streams"][0]["units"][0]["messages"]["KF_RAW_SAMPLE"]
    assert "requested_hz" not in m and m["count"] == 400


def test_a_good_requested_rate_is_used(run, tmp_path):
    path = _recording(tmp_path / "good.kfr", {"KF_RAW_SAMPLE": 200})
    code, out, err = run("stats", path, "--json")
    res = json.loads(out)
    assert code == 0 and not any("requested_rates_hz" in w for w in res["warnings"]), res["warnings"]
    assert res["streams"][0]["units"][0]["messages"]["KF_RAW_SAMPLE"]["requested_hz"] == 200
