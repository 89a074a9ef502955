"""The host tool against a unit (firmware host build over a pty) that requires MAVLink 2
signing: `kinefuse signing` sets, changes and clears the key; `params`, `command`, `record`
and `live` refuse to pretend -- an unsigned (or wrongly signed) write or command is a one-line
error with exit status 2, and with --key/--key-file the same invocation works."""
from __future__ import annotations

import hashlib

import pytest

from kinefuse.firmware.hostunit import HostUnit
from kinefuse.host import cli
from kinefuse.host.link.params import ParamClient
from kinefuse.host.link.recording import load
from kinefuse.host.link.signing import parse_key, read_key_file

KEY_HEX = hashlib.sha256(b"kinefuse cli test").hexdigest()


@pytest.fixture
def run(capsys):
    def _run(*argv):
        code = cli.main([str(a) for a in argv])
        out, err = capsys.readouterr()
        return code, out, err
    return _run


def one_line_error(res, *texts, last_line=False):
    """Exit status 2 and the error in one line (``last_line``: the recorder's progress table may
    come before it on stderr in --json mode; the error is still one line, and the last)."""
    code, out, err = res
    lines = err.strip().splitlines()
    if last_line:
        assert sum(ln.startswith("kinefuse: error:") for ln in lines) == 1 and "warning" not in err, err
        lines = lines[-1:]
    assert code == 2 and len(lines) == 1 and lines[0].startswith("kinefuse: error:"), res
    for t in texts:
        assert t in lines[0], (t, lines[0])


def test_key_formats(tmp_path):
    assert parse_key(KEY_HEX) == bytes.fromhex(KEY_HEX)
    assert parse_key("  correct horse  ") == hashlib.sha256(b"correct horse").digest()   # as MAVProxy
    f = tmp_path / "k"
    f.write_text(KEY_HEX + "\n")
    assert read_key_file(f) == bytes.fromhex(KEY_HEX)
    f.write_bytes(bytes(range(200, 232)))
    assert read_key_file(f) == bytes(range(200, 232))


def test_signing_end_to_end(run, tmp_path):
    keyfile = tmp_path / "unit.key"
    code, out, _ = run("signing", "--generate", keyfile)
    assert code == 0 and keyfile.stat().st_mode & 0o077 == 0
    key = read_key_file(keyfile)
    with HostUnit(storage=tmp_path / "unit.storage") as unit:
        port = f"pty:{unit.device}"
        assert run("signing", "--port", port, "--json")[1].strip() == '{"signing": false, "unit": 1}'
        assert run("params", "--port", port, "--unit", 1, "--set", "KF_RATE_HZ=200")[0] == 0   # a lighter load
        port = [port, "--unit", "1"]     # no wait for a heartbeat (seen to take > 3 s on a loaded machine)
        code, out, err = run("signing", "--port", *port, "--new-key-file", keyfile)     # first key: unsigned
        assert code == 0 and "signing key set" in out, err
        s = unit.session()
        assert ParamClient(s, 1).get("KF_SIGNING") == 1
        s.close()                       # two readers of one pty would split its bytes

        # parameters: refused unsigned, refused with another key, written with the key
        one_line_error(run("params", "--port", *port, "--set", "KF_ORI_RATE_HZ=50"),
                       "permission denied", "--key")
        one_line_error(run("params", "--port", *port, "--key", "not the key", "--set", "KF_ORI_RATE_HZ=50"),
                       "right key")
        code, out, err = run("params", "--port", *port, "--key-file", keyfile, "--set", "KF_ORI_RATE_HZ=50")
        assert code == 0 and "KF_ORI_RATE_HZ = 50" in out, err

        # commands
        one_line_error(run("command", "--port", *port, "stop"), "MAV_RESULT_DENIED", "--key")
        assert run("command", "--port", *port, "--key-file", keyfile, "stop")[0] == 0
        one_line_error(run("command", "--port", *port, "--key-file", keyfile, "--json", "start", "--rate", "5000"),
                       "MAV_CMD_SET_MESSAGE_INTERVAL", "DENIED", "out of range")    # KF_RATE_HZ <= 2000

        # record --start: was 0 samples and exit 0
        out1 = tmp_path / "refused.kfr"
        one_line_error(run("record", "--port", port[0], "--out", out1, "--duration", "0.5", "--start", "--json"),
                       "refused MAV_CMD_KF_STREAM", "MAV_RESULT_DENIED", last_line=True)
        errors = [m["text"] for m in load(out1).streams[0].meta if m.get("type") == "error"]
        assert len(errors) == 1 and "DENIED" in errors[0]                 # the file says why it is empty
        one_line_error(run("record", "--port", port[0], "--out", tmp_path / "wrong.kfr", "--duration", "0.5",
                           "--start", "--key", "another key", "--no-params", "--json"),
                       "no COMMAND_ACK for MAV_CMD_KF_STREAM", "right key", last_line=True)
        out2 = tmp_path / "signed.kfr"
        code, _, err = run("record", "--port", port[0], "--out", out2, "--duration", "0.6", "--start",
                           "--rate", "200", "--key", key.hex(), "--json")
        assert code == 0, err
        rec = load(out2)
        params = [m["params"] for m in rec.streams[0].meta if m.get("type") == "params"]
        assert params and params[0]["KF_SIGNING"] == 1 and params[0]["KF_ORI_RATE_HZ"] == 50
        from kinefuse.host.link.frames import decode_file
        assert len(decode_file(out2).streams[0].arrays[52500]) > 50

        # live --start
        one_line_error(run("live", "--port", port[0], "--start", "--seconds", "0.5"), "MAV_CMD_KF_STREAM", "DENIED")

        # changing the key needs the current one; clearing it too
        one_line_error(run("signing", "--port", *port, "--new-key", "next"), "did not take the new key",
                       "another key")
        one_line_error(run("signing", "--port", *port, "--key", "wrong", "--clear"), "still requires signing")
        code, out, err = run("signing", "--port", *port, "--key-file", keyfile, "--new-key", "next")
        assert code == 0 and "signing key set" in out, err
        one_line_error(run("command", "--port", *port, "--key-file", keyfile, "stop"), "no COMMAND_ACK")
        code, out, err = run("signing", "--port", *port, "--key", "next", "--clear")
        assert code == 0 and "cleared" in out, err
        assert run("params", "--port", *port, "--set", "KF_ORI_RATE_HZ=40")[0] == 0
        assert run("command", "--port", *port, "stop")[0] == 0
