"""The link commands through the real CLI entry point: one-line errors, --json, fake units."""
from __future__ import annotations

import json

import pytest

from kinefuse.host import cli

MINE_BENCH = ("bench.decode",)
MINE = ("record_cmd", "decode_cmd", "export_cmd", "stats_cmd", "params_cmd", "ports_cmd")


def _one_line_error(code, out, err, text):
    assert code == 2, (code, out, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("kinefuse: error:") and text in lines[0], err
    assert "Traceback" not in err


@pytest.mark.parametrize("argv, text", [
    (["decode", "{tmp}/missing.kfr"], "no such file"),
    (["decode", "{tmp}/junk.kfr"], "not a kinefuse recording"),
    (["stats", "{tmp}"], "directory"),
    (["export", "{tmp}/junk.kfr", "--out", "{tmp}/csv"], "not a kinefuse recording"),
    (["export", "{tmp}/junk.kfr", "--out", "{tmp}/csv", "--messages", ""], "--messages names no message"),  # all
    (["export", "{tmp}/junk.kfr", "--out", "{tmp}/csv", "--messages", " , "], "--messages names no message"),
    (["record", "--port", "/dev/kinefuse-no-such-port", "--out", "{tmp}/r.kfr", "--duration", "1"],
     "cannot open serial port"),
    (["record", "--port", "fake:", "--out", "{tmp}/r.kfr", "--baud", "fast"], "bad baud rate"),
    (["record", "--port", "fake:", "--out", "{tmp}/r.kfr", "--duration", "nan"], "--duration must be"),  # forever
    (["record", "--port", "fake:", "--out", "{tmp}/no/such/dir/r.kfr"], "does not exist"),
    (["record", "--port", "fake:", "--out", "{tmp}/junk.kfr"], "exists"),
    (["params", "--port", "tcp:127.0.0.1:1"], "cannot connect"),
    (["params", "--port", "fake:", "--set", "KF_RATE_HZ"], "expected NAME=VALUE"),
    (["params", "--port", "fake:", "--set", "KF_ACC_TAU_S=1e40"], "out of range for a REAL32"),  # OverflowError
    (["params", "--port", "fake:", "--timeout", "nan"], "--timeout must be positive"),
    # KF_RATE_HZ <= 2000: DENIED for the value, not (only) for a missing signing key
    (["record", "--port", "fake:", "--out", "{tmp}/r.kfr", "--duration", "1", "--start", "--rate", "5000"],
     "a value out of range"),
])
def test_bad_input_gives_one_line(run, tmp_path, argv, text):
    (tmp_path / "junk.kfr").write_bytes(b"\x00garbage" * 100)
    _one_line_error(*run(*[a.format(tmp=tmp_path) for a in argv]), text)


def test_record_decode_stats_export(run, tmp_path):
    out = tmp_path / "two.kfr"
    code, stdout, err = run("record", "--port", "fake:rate=400,drop=50", "--port", "fake:unit=2,rate=100",
                            "--out", out, "--duration", "2.5", "--params", "--json")
    assert code == 0, err
    summary = json.loads(stdout)
    assert [s["id"] for s in summary["streams"]] == [0, 1]
    assert summary["streams"][0]["frames"] > 100 and summary["streams"][0]["crc_errors"] == 0

    code, stdout, _ = run("decode", out, "--json", "--show", "1")
    dec = json.loads(stdout)
    assert dec["dialect_match"] and not dec["truncated"]
    s0, s1 = dec["streams"]
    assert s0["messages"]["KF_RAW_SAMPLE"] > 100 and s1["messages"]["KF_ORIENTATION"] > 10
    assert s0["params"]["1"]["KF_RATE_HZ"] == 400 and s1["firmware"]["2"] == "0.1.0-dev"
    assert dec["first_messages"]["KF_RAW_SAMPLE"][0]["time_boot_us"] == 0

    code, stdout, _ = run("stats", out, "--json")
    st = json.loads(stdout)
    raw0 = st["streams"][0]["units"][0]["messages"]["KF_RAW_SAMPLE"]
    assert raw0["requested_hz"] == 400 and raw0["samples_lost"] > 0  # the fake unit drops every 50th
    assert 0.9 < raw0["rate_ratio"] < 1.0
    assert "latency" in st["streams"][1]["units"][0]

    code, stdout, _ = run("export", out, "--out", tmp_path / "csv", "--json")
    files = {f["file"].rsplit("/", 1)[-1]: f["rows"] for f in json.loads(stdout)["files"]}
    assert files["KF_RAW_SAMPLE_s0_u1.csv"] == s0["messages"]["KF_RAW_SAMPLE"]
    lines = [ln for ln in (tmp_path / "csv" / "KF_RAW_SAMPLE_s0_u1.csv").read_text().splitlines()
             if not ln.startswith("#")]                     # '#' lines name the unit and its clock fit
    header = lines[0].split(",")
    assert header[:4] == ["t_s", "host_time_s", "host_unix_s", "host_fit_s"]
    for col in ("acc_x_mps2", "gyr_z_radps", "mag_y_uT", "temperature_degC", "sample_counter"):
        assert col in header
    ori = [ln for ln in (tmp_path / "csv" / "KF_ORIENTATION_s1_u2.csv").read_text().splitlines()
           if not ln.startswith("#")]
    assert "quat_w" in ori[0] and "cov_zz_rad2" in ori[0]
    # the exported unit file is a "plain kinefuse CSV" for the readers package
    row = dict(zip(header, lines[1].split(",")))
    assert 9.0 < (sum(float(row[f"acc_{a}_mps2"]) ** 2 for a in "xyz")) ** 0.5 < 10.6


@pytest.mark.parametrize("port", ["file:{cap}", "{cap}"])
def test_record_never_overwrites_its_input_capture(run, tmp_path, port):
    """--port file:cap.bin --out cap.bin --force replaced the 230 kB capture with a recording
    of its first bytes."""
    from kinefuse.host.link.fakeunit import raw_frames
    cap = tmp_path / "cap.bin"
    data = raw_frames(2000)
    cap.write_bytes(data)
    _one_line_error(*run("record", "--port", port.format(cap=cap), "--out", cap, "--force", "--duration", "1",
                         "--no-params"), "is the input")
    assert cap.read_bytes() == data


def test_the_same_port_twice_is_refused(run, tmp_path):
    """Two readers of one pty split its bytes: 29 % and 70 % of the samples 'lost'."""
    from kinefuse.host.link.connection import create_pty_pair
    pair = create_pty_pair()
    try:
        path = pair.device_path
        _one_line_error(*run("record", "--port", f"pty:{path}", "--port", path, "--out", tmp_path / "d.kfr",
                             "--duration", "1", "--no-params"), "give each port once")
    finally:
        pair.host.close()
    assert not (tmp_path / "d.kfr").exists()
    # simulated units and capture files may repeat
    assert run("record", "--port", "fake:", "--port", "fake:", "--out", tmp_path / "f.kfr", "--duration", "0.2",
               "--no-params", "--json")[0] == 0


def test_truncated_recording_still_decodes(run, tmp_path):
    out = tmp_path / "t.kfr"
    assert run("record", "--port", "fake:rate=300", "--out", out, "--duration", "1.5")[0] == 0
    data = out.read_bytes()
    out.write_bytes(data[: len(data) * 2 // 3 + 7])
    code, stdout, _ = run("decode", out, "--json")
    dec = json.loads(stdout)
    assert code == 0 and dec["truncated"] and dec["streams"][0]["messages"]["KF_RAW_SAMPLE"] > 100


def test_params_command(run):
    code, stdout, err = run("params", "--port", "fake:unit=5,rate=100", "--json")
    assert code == 0, err
    assert json.loads(stdout) == {"unit": 5, "params": {"KF_UNIT_ID": 5, "KF_RATE_HZ": 100, "KF_ORI_RATE_HZ": 100,
                                                        "KF_FILTER": 1, "KF_MAG_ENABLE": 1, "KF_ACC_TAU_S": 3.0,
                                                        "KF_SERIAL_NO": 0x4B460001, "KF_BATT_LOW_MV": 3400}}
    code, stdout, _ = run("params", "--port", "fake:unit=5", "--set", "KF_ACC_TAU_S=1.5", "--get", "KF_FILTER",
                          "--json")
    assert json.loads(stdout) == {"unit": 5, "set": {"KF_ACC_TAU_S": 1.5}, "get": {"KF_FILTER": 1}}
    _one_line_error(*run("params", "--port", "fake:unit=5", "--set", "KF_RATE_HZ=5000"), "rejected")


def test_ports_json(run):
    code, stdout, _ = run("ports", "--json")
    assert code == 0 and isinstance(json.loads(stdout)["ports"], list)


def test_bench_decode_json_shape(run):
    code, stdout, err = run("bench", "decode", "--frames", "3000", "--repeat", "1", "--bit-error-frames", "5000",
                            "--fake-magic-frames", "2000", "--json")
    assert code == 0, err
    r = json.loads(stdout)
    assert set(r) == {"frames", "msgs_per_s", "fake_magic", "bit_errors"}
    assert set(r["msgs_per_s"]) == {"kinefuse_stream", "kinefuse_batch", "pymavlink"}
    assert set(r["fake_magic"]) == {"sent", "kinefuse", "pymavlink"}
    assert set(r["bit_errors"]) == {"intact", "recovered", "false_accepts"}
    assert r["fake_magic"]["kinefuse"] == r["fake_magic"]["sent"] == 2000
    assert r["bit_errors"]["recovered"] == r["bit_errors"]["intact"] and r["bit_errors"]["false_accepts"] == 0


def test_record_warns_on_a_likely_wrong_baud_rate(run, tmp_path):
    import numpy as np
    noise = np.random.default_rng(0).integers(0, 256, 20_000, dtype=np.uint8)
    noise[noise == 0xFD] = 0  # what a unit at the wrong baud rate looks like: bytes, never a frame
    (tmp_path / "noise.bin").write_bytes(noise.tobytes())
    code, stdout, err = run("record", "--port", f"file:{tmp_path / 'noise.bin'}", "--out", tmp_path / "n.kfr",
                            "--duration", "5", "--json")
    summary = json.loads(stdout)
    assert code == 0 and summary["streams"][0]["frames"] == 0 and summary["streams"][0]["closed"]
    assert any("wrong baud rate" in w for w in summary["warnings"])
    code, stdout, _ = run("decode", tmp_path / "n.kfr", "--json")
    assert any("wrong baud rate" in (e.get("text") or "") for e in json.loads(stdout)["streams"][0]["events"])


def test_stats_on_a_tlog(run, tmp_path):
    import struct as _struct
    from kinefuse.host.link.fakeunit import raw_frames
    frames = raw_frames(1000, unit_id=2, rate_hz=100, seed=1)
    log = b"".join(_struct.pack(">Q", 1_700_000_000_000_000 + 10_000 * k + 1500) + frames[k * 46:(k + 1) * 46]
                   for k in range(1000) if k != 500)
    (tmp_path / "x.tlog").write_bytes(log)
    code, stdout, _ = run("stats", tmp_path / "x.tlog", "--json")
    stream = json.loads(stdout)["streams"][0]
    # the 8-byte stamps are the tlog's format, not skipped bytes (999 of them were reported)
    assert stream["frames_ok"] == 999 and stream["bytes_skipped"] == 0
    u = stream["units"][0]
    assert u["messages"]["KF_RAW_SAMPLE"]["samples_lost"] == 1
    # host times count from the first tlog stamp, which is 1.5 ms after device time 0: offset 0
    assert abs(u["clock"]["drift_ppm"]) < 1 and u["clock"]["offset_s"] == pytest.approx(0.0, abs=1e-6)
    cut = (8 + 46) * 10 + 8                   # five junk bytes between the 11th stamp and its frame
    (tmp_path / "y.tlog").write_bytes(log[:cut] + b"\x01\x02\x03\x04\x05" + log[cut:])
    code, stdout, _ = run("stats", tmp_path / "y.tlog", "--json")
    stream = json.loads(stdout)["streams"][0]
    assert stream["frames_ok"] == 999 and stream["bytes_skipped"] == 5


def test_export_of_a_truncated_recording_warns(run, tmp_path):
    """export said nothing about a cut file (decode and stats did): the CSVs looked complete."""
    out = tmp_path / "t.kfr"
    assert run("record", "--port", "fake:rate=300", "--out", out, "--duration", "1.5")[0] == 0
    data = out.read_bytes()
    out.write_bytes(data[: len(data) * 2 // 3 + 7])
    code, stdout, err = run("export", out, "--out", tmp_path / "csv", "--json")
    assert code == 0
    assert any("truncated" in w for w in json.loads(stdout)["warnings"])
    assert "warning:" in err and "truncated" in err
    code, stdout, err = run("export", out, "--out", tmp_path / "csv2")
    assert code == 0 and "truncated" in stdout + err


def test_ctrl_c_while_the_commands_are_imported_is_one_line(monkeypatch, capsys):
    """`kinefuse record ...` then Ctrl-C within its first second (the imports): a traceback."""
    def interrupted(name):
        raise KeyboardInterrupt
    monkeypatch.setattr(cli, "_load", interrupted)
    assert cli.main(["record", "--port", "fake:", "--out", "x.kfr"]) == 130
    out, err = capsys.readouterr()
    assert err == "kinefuse: interrupted\n" and out == ""


def test_export_into_a_folder_of_an_earlier_export_warns(run, tmp_path):
    """Exporting into a folder holding another recording's CSVs replaced and mixed them without a
    word: now refused without --force (nothing touched), and with --force the files it did not
    write are named; a refused export (unknown --messages) left an empty folder; piped, an
    unusable file printed a blank line on stdout before the one-line error."""
    from kinefuse.host.link.recorder import Recorder
    one, two = tmp_path / "one.kfr", tmp_path / "two.kfr"
    Recorder(one, ["fake:rate=200"]).run(0.4)
    Recorder(two, ["fake:rate=200", "fake:unit=2,rate=200"]).run(0.4)
    out = tmp_path / "csv"
    assert run("export", two, "--out", out)[0] == 0
    before = {f.name: f.read_bytes() for f in out.iterdir()}
    _one_line_error(*run("export", one, "--out", out), f"{out} already holds")
    assert {f.name: f.read_bytes() for f in out.iterdir()} == before     # nothing replaced
    code, stdout, _ = run("export", one, "--out", out, "--json", "--force")
    res = json.loads(stdout)
    assert code == 0 and any("6 CSV file(s) this export did not write" in w and "KF_RAW_SAMPLE_s0_u1.csv" in w
                             for w in res["warnings"]), res["warnings"]
    code, stdout, _ = run("export", one, "--out", out, "--json", "--force")   # its own files are not counted
    assert code == 0 and any("6 CSV file(s)" in w for w in json.loads(stdout)["warnings"])
    _one_line_error(*run("export", one, "--out", tmp_path / "new", "--messages", "NOPE"), "unknown message")
    assert not (tmp_path / "new").exists()
    # a message the recording does not hold: nothing to write, and no empty folder either
    code, stdout, _ = run("export", one, "--out", tmp_path / "none", "--messages", "HIL_SENSOR")
    assert code == 0 and "no messages to export" in stdout and not (tmp_path / "none").exists()
    # ... and it says what the file does hold (it only said "no messages to export")
    assert "holds no HIL_SENSOR" in stdout and "KF_RAW_SAMPLE" in stdout.split("it holds", 1)[1], stdout
    (tmp_path / "junk.kfr").write_bytes(b"\x00garbage" * 100)
    code, stdout, err = run("export", tmp_path / "junk.kfr", "--out", tmp_path / "j")
    assert code == 2 and stdout == "", repr(stdout)


class _FullAfter:
    """A file that takes ``room`` bytes, then fails like a full disk (ENOSPC)."""

    def __init__(self, f, room):
        self._f, self.room = f, room

    def write(self, b):
        import errno
        if len(b) > self.room:
            self._f.write(b[:self.room])
            self.room = 0
            raise OSError(errno.ENOSPC, "No space left on device")
        self.room -= len(b)
        return self._f.write(b)

    def __getattr__(self, name):
        return getattr(self._f, name)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self._f.close()


def test_disk_full_while_recording_is_one_line_and_keeps_what_was_written(run, tmp_path):
    """A full disk was an internal error (OSError) and left the sessions open."""
    import os
    from kinefuse.host.errors import KinefuseError
    from kinefuse.host.link.recorder import Recorder
    from kinefuse.host.link.recording import load
    if os.path.exists("/dev/full"):
        # "(the recording holds what was written before)" when nothing had been
        _one_line_error(*run("record", "--port", "fake:", "--out", "/dev/full", "--force", "--duration", "0.3"),
                        "No space left on device (nothing of the recording was written)")
    out = tmp_path / "full.kfr"
    rec = Recorder(out, ["fake:rate=500"])
    head = rec.writer.bytes_written
    rec.writer._f = _FullAfter(rec.writer._f, 20_000)
    with pytest.raises(KinefuseError, match=r"cannot write .*No space left on device \(the file holds "
                                            r"the recording up to there, [\d,]+ bytes\)"):
        rec.run(3.0)
    assert out.stat().st_size == head + 20_000
    r = load(out)                      # the part written before the disk filled up
    assert len(r.streams[0].rx) > 10_000 and r.truncated


def test_disk_full_while_exporting_is_one_line(run, tmp_path, monkeypatch):
    """It was an internal error (OSError from the CSV writes)."""
    import builtins
    from kinefuse.host.link import export
    from kinefuse.host.link.recorder import Recorder
    rec = tmp_path / "r.kfr"
    Recorder(rec, ["fake:rate=200"]).run(0.4)
    monkeypatch.setattr(export, "open", lambda *a, **k: _FullAfter(builtins.open(*a, **k), 300), raising=False)
    _one_line_error(*run("export", rec, "--out", tmp_path / "csv"), "No space left on device")
