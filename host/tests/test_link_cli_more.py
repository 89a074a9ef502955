"""More of the link CLI: parameters in the recording by default, warnings instead of failures
for a unit that does not answer or a connection of garbage, checked commands on a fake unit,
argument checks."""
from __future__ import annotations

import json

import pytest

from kinefuse.host.link.fakeunit import raw_frames
from kinefuse.host.link.recording import load


def _meta(path, kind):
    return [m for sd in load(path).streams.values() for m in sd.meta if m.get("type") == kind]


def test_parameters_are_recorded_by_default(run, tmp_path):
    out = tmp_path / "p.kfr"
    code, _, err = run("record", "--port", "fake:rate=200", "--out", out, "--duration", "0.3", "--json")
    assert code == 0, err
    (p,) = _meta(out, "params")
    assert p["sysid"] == 1 and p["params"]["KF_UNIT_ID"] == 1 and load(out).header["params_requested"] is True
    out2 = tmp_path / "n.kfr"
    assert run("record", "--port", "fake:rate=200", "--out", out2, "--duration", "0.3", "--no-params",
               "--json")[0] == 0
    assert _meta(out2, "params") == [] and load(out2).header["params_requested"] is False


def test_a_unit_that_does_not_answer_parameters_is_a_warning(run, tmp_path):
    out = tmp_path / "q.kfr"
    code, stdout, err = run("record", "--port", "fake:rate=200,params=0", "--out", out, "--duration", "0.3",
                            "--json")
    assert code == 0, err
    assert "parameters of unit 1 not read" in " ".join(err.split())
    assert any("parameters of unit 1 not read" in w["text"] for w in _meta(out, "warning"))
    assert any("not read" in w for w in json.loads(stdout)["warnings"])


def test_a_capture_of_garbage_or_without_a_unit_warns(run, tmp_path):
    junk = tmp_path / "junk.bin"
    junk.write_bytes(bytes(range(256)) * 3)                        # 768 bytes, no frame
    code, _, err = run("record", "--port", f"file:{junk}", "--out", tmp_path / "j.kfr", "--duration", "1")
    assert code == 0 and "no valid MAVLink 2 frame" in " ".join(err.split() + _words(tmp_path / "j.kfr"))
    cap = tmp_path / "frames.bin"
    cap.write_bytes(raw_frames(200))                                # frames, but nobody to answer
    code, _, err = run("record", "--port", f"file:{cap}", "--out", tmp_path / "c.kfr", "--duration", "1")
    assert code == 0
    assert any("no HEARTBEAT" in w["text"] for w in _meta(tmp_path / "c.kfr", "warning"))


def _words(path):
    return " ".join(w["text"] for w in _meta(path, "warning")).split()


def test_commands_on_a_fake_unit(run, tmp_path):
    code, out, err = run("command", "--port", "fake:stream=0", "start", "--rate", "200", "--json")
    assert code == 0 and json.loads(out) == {"accepted": ["MAV_CMD_SET_MESSAGE_INTERVAL", "MAV_CMD_KF_STREAM"],
                                             "action": "start", "unit": 1}, err
    for action in ("stop", "reset", "reboot"):
        assert run("command", "--port", "fake:", action)[0] == 0
    assert run("command", "--port", "fake:", "tare", "--heading", "30")[0] == 0
    assert run("command", "--port", "fake:", "start", "--reset-counter")[0] == 0
    out = tmp_path / "s.kfr"
    code, _, err = run("record", "--port", "fake:stream=0", "--out", out, "--duration", "0.4", "--start",
                       "--rate", "250", "--json")
    assert code == 0, err
    assert "warning" not in err


@pytest.mark.parametrize("second, text", [("FOO=1", "FOO: no such parameter (nothing written)"),
                                          ("KF_FILTER=1.5", "--set KF_FILTER: 1.5 is not an integer")])
def test_params_set_writes_nothing_when_an_item_is_bad(run, monkeypatch, second, text):
    """The unit's names and types are checked before the first write: KF_RATE_HZ was written,
    then FOO failed."""
    from kinefuse.host.link.params import ParamClient
    written = []
    real = ParamClient.set
    monkeypatch.setattr(ParamClient, "set", lambda self, name, value, *a, **k: (
        written.append(name), real(self, name, value, *a, **k))[1])
    code, out, err = run("params", "--port", "fake:", "--set", "KF_RATE_HZ=500", "--set", second)
    assert code == 2 and err.count("\n") == 1 and text in err, err
    assert written == []
    assert run("params", "--port", "fake:", "--set", "KF_RATE_HZ=500", "--set", "KF_ACC_TAU_S=0.5")[0] == 0
    assert written == ["KF_RATE_HZ", "KF_ACC_TAU_S"]


@pytest.mark.parametrize("argv, text", [
    (["decode", "--show", "-3", "x.kfr"], "--show must be 0 or more"),
    (["command", "--port", "fake:", "stop", "--rate", "5"], "--rate goes with start"),
    # accepted and ignored before: the unit got a plain stop / reset
    (["command", "--port", "fake:", "stop", "--reset-counter"], "--reset-counter goes with start"),
    (["command", "--port", "fake:", "reset", "--heading", "90"], "--heading goes with tare"),
    # NaN waited for ever for a unit that does not answer (a fake one answered at once)
    (["command", "--port", "fake:", "start", "--timeout", "nan"], "--timeout must be positive"),
    (["command", "--port", "fake:", "start", "--timeout", "-1"], "--timeout must be positive"),
    # an internal error (struct: ubyte format requires 0 <= number <= 255) or, for 0, no ACK
    (["command", "--port", "fake:", "start", "--unit", "300"], "--unit must be a unit (MAVLink system) id"),
    (["command", "--port", "fake:", "stop", "--unit", "0"], "--unit must be a unit (MAVLink system) id"),
    (["params", "--port", "fake:", "--unit", "-1"], "--unit must be a unit (MAVLink system) id"),
    (["params", "--port", "fake:", "--unit", "256", "--get", "KF_RATE_HZ"], "--unit must be a unit"),
    # --key "$UNSET": fell through to $KINEFUSE_SIGNING_KEY or no key (the write went unsigned)
    (["params", "--port", "fake:", "--key", "", "--set", "KF_RATE_HZ=500"], "--key is empty"),
    (["command", "--port", "fake:", "--key-file", " ", "start"], "--key-file is empty"),
    (["live", "--port", "fake:", "--rate", "5", "--seconds", "1"], "--rate goes with --start"),
    # record took up to 100 kHz, which the unit refuses (intervals below 100 us): the recording
    # went on at the old rate with only a warning about the refused command
    (["record", "--port", "fake:", "--rate", "20000", "--out", "x.kfr"], "--rate must be in (0, 10000] Hz"),
    (["record", "--port", "fake:", "--rate", "nan", "--out", "x.kfr"], "--rate must be in (0, 10000] Hz"),
    (["live", "--port", "fake:", "--start", "--rate", "0", "--seconds", "1"], "--rate must be in (0, 10000]"),
    (["command", "--port", "fake:", "start", "--rate", "1e5"], "--rate must be in (0, 10000] Hz"),
    (["signing", "--port", "fake:", "--new-key", "0" * 64], "use --clear"),
    (["signing"], "--port"),
    (["signing", "--port", "fake:", "--unit", "300"], "--unit must be a unit (MAVLink system) id"),
    (["signing", "--port", "fake:", "--timeout", "nan"], "--timeout must be positive"),
    (["signing", "--port", "fake:", "--new-key", ""], "--new-key is empty"),
    (["signing", "--port", "fake:", "--new-key-file", ""], "--new-key-file is empty"),
])
def test_argument_errors_are_one_line(run, argv, text):
    code, out, err = run(*argv)
    assert code == 2 and err.count("\n") == 1 and text in err, err


def test_fake_unit_orientation_status_matches_its_strapdown_filter():
    """The fake unit's KF_ORIENTATION (gyroscope strapdown, filter_id 1) carried MAG_USED."""
    from kinefuse.host.link.decoder import StreamDecoder
    from kinefuse.host.link.dialect import kinefuse as D
    from kinefuse.host.link.fakeunit import FakeUnit
    unit = FakeUnit(conn=None)
    for tared in (False, True):
        unit.tared = tared
        (f,) = StreamDecoder().feed(unit._orientation(1000, 1))
        assert f.msg.filter_id == D.KF_FILTER_GYRO_STRAPDOWN
        assert f.msg.status & D.KF_ORIENTATION_STATUS_INITIALISED
        assert not f.msg.status & D.KF_ORIENTATION_STATUS_MAG_USED
        assert bool(f.msg.status & D.KF_ORIENTATION_STATUS_HEADING_TARED) == tared


@pytest.mark.parametrize("command", [["command", "start"], ["params"], ["signing"]])
def test_a_capture_without_a_unit_says_so(run, tmp_path, command):
    """It said "no HEARTBEAT within 3 s (unit off, ...)" after the file had ended at once."""
    cap = tmp_path / "g.bin"
    cap.write_bytes(b"no mavlink here" * 10)
    code, out, err = run(command[0], "--port", f"file:{cap}", *command[1:])
    assert code == 2 and err.count("\n") == 1, err
    assert f"file:{cap} ended without a HEARTBEAT: no unit on that connection" in err, err
