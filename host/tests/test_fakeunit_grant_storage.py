"""The fake unit's sensor may grant another rate than KF_RATE_HZ asks, and its parameter storage
may fail, as on the firmware (kf_config_apply_rates: the granted rate becomes KF_RATE_HZ;
kf_status.c: STORAGE_ERROR in the next KF_UNIT_STATUS and a STATUSTEXT ERROR after it)."""
from __future__ import annotations

import pytest

from kinefuse.host.errors import KinefuseError
from kinefuse.host.link import stats
from kinefuse.host.link.codec import Encoder
from kinefuse.host.link.decoder import StreamDecoder
from kinefuse.host.link.fakeunit import FakeConnection, FakeUnit
from kinefuse.host.link.frames import decode_file
from kinefuse.host.link.params import encode_value
from kinefuse.host.readers import read_recording

MINE = ("live_cmd", "record_cmd")
STORAGE_ERROR = 128
STORAGE_TEXT = "parameter storage error: settings may be lost"     # firmware/app/kf_status.c


def _decode(frames):
    return [f.msg for f in StreamDecoder().feed(b"".join(frames))]


def _tick(u, now_us):
    return [(m._msgname, m) for m in _decode(u._status_tick(now_us))]


def _param_set(u, name, value, ptype=3):
    (f,) = StreamDecoder().feed(Encoder(255, 190).encode(
        "PARAM_SET", target_system=1, target_component=200, param_id=name,
        param_value=encode_value(value, ptype), param_type=ptype))
    return _decode(u._handle(f))


def test_the_granted_rate_becomes_kf_rate_hz():
    u = FakeUnit(None, rate_hz=1000, sensor_grant_hz=500)
    assert u.params["KF_RATE_HZ"] == 500                       # at boot
    u.next_status_us = 1 << 62
    u.device_time_us = lambda: 36_000
    raw = [m for m in _decode(u._emit_due()) if m._msgname == "KF_RAW_SAMPLE"]
    assert [m.time_boot_us for m in raw] == list(range(0, 36_001, 2000))    # 500 Hz, not 1 kHz
    (pv,) = _param_set(u, "KF_RATE_HZ", 400)
    assert pv._msgname == "PARAM_VALUE" and pv.param_id == "KF_RATE_HZ" and u.params["KF_RATE_HZ"] == 500
    (st,) = _decode([u._status(0)])
    assert st.sensor_rate_requested == 500.0


def test_a_grant_out_of_range_keeps_the_rate_asked():
    """As kf_config_apply_rates: a rate the parameter cannot hold is refused, the old one kept."""
    u = FakeUnit(None, rate_hz=1000, sensor_grant_hz=5000)
    assert u.params["KF_RATE_HZ"] == 1000
    err, pv = _param_set(u, "KF_RATE_HZ", 400)
    assert err._msgname == "PARAM_ERROR" and pv.param_id == "KF_RATE_HZ" and u.params["KF_RATE_HZ"] == 1000
    with pytest.raises(KinefuseError, match="option grant: '5000' .expected 0 .. 2000"):
        FakeConnection("grant=5000")


def test_a_failing_storage_says_so_once_per_failure():
    u = FakeUnit(None, storage_error=True)
    first = _tick(u, 0)                                        # the load at boot failed
    assert [n for n, _ in first] == ["HEARTBEAT", "KF_UNIT_STATUS", "STATUSTEXT"]
    assert first[1][1].status_flags & STORAGE_ERROR
    assert first[2][1].severity == 3 and first[2][1].text.rstrip("\0") == STORAGE_TEXT
    again = _tick(u, 1_000_000)                                # nothing failed since
    assert [n for n, _ in again] == ["HEARTBEAT", "KF_UNIT_STATUS"] and not again[1][1].status_flags & STORAGE_ERROR
    _param_set(u, "KF_ORI_RATE_HZ", 100)                       # unchanged: not stored
    assert [n for n, _ in _tick(u, 2_000_000)][-1] == "KF_UNIT_STATUS"
    _param_set(u, "KF_ORI_RATE_HZ", 50)                        # stored: the save fails
    after = _tick(u, 3_000_000)
    assert after[1][1].status_flags & STORAGE_ERROR and after[-1][0] == "STATUSTEXT"
    ok = FakeUnit(None)
    assert [n for n, _ in _tick(ok, 0)] == ["HEARTBEAT", "KF_UNIT_STATUS"]
    assert not _tick(ok, 0)[1][1].status_flags & STORAGE_ERROR


def test_live_shows_the_fake_units_storage_error(run):
    code, out, err = run("live", "--port", "fake:storage_error=1", "--seconds", "1.2")
    assert code == 0, err
    assert f"unit 1 (fake:storage_error=1) says ERROR: {STORAGE_TEXT}" in out, out


def test_recording_a_unit_that_grants_another_rate_and_fails_its_storage(run, tmp_path):
    """The host against a unit whose sensor grants 500 Hz for the 400 asked with --rate and whose
    storage fails: stats finds it running at the 500 Hz it reports, the kfr reader carries its
    STATUSTEXT and STORAGE_ERROR flag."""
    p = tmp_path / "u.kfr"
    code, out, err = run("record", "--port", "fake:rate=200,grant=500,storage_error=1", "--out", p,
                         "--duration", "2.5", "--rate", "400")     # it streams from boot
    assert code == 0, err
    assert f"unit 1 on fake:rate=200,grant=500,storage_error=1: ERROR: {STORAGE_TEXT}" in out, out
    (u,) = stats.compute(decode_file(p))["streams"][0]["units"]
    m = u["messages"]["KF_RAW_SAMPLE"]
    assert m["requested_hz"] == 500 and m["rate_hz"] == pytest.approx(500, rel=0.02), u
    r = read_recording(str(p))
    texts = [(e["severity_name"], e["text"]) for e in r.metadata["unit_messages"]]
    assert ("ERROR", STORAGE_TEXT) in texts                    # the load at boot failed
    assert r.metadata["status_flags"]["KF_UNIT_STATUS"]["STORAGE_ERROR"] >= 1
    assert any(f"said ERROR: {STORAGE_TEXT}" in w for w in r.warnings), r.warnings
