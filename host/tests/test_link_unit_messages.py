"""What a unit says about itself reaches the user: STATUSTEXT in live/record/stats/decode, the
STORAGE_ERROR flag in live, and a dialect (CRC_EXTRA) mismatch named while recording."""
from __future__ import annotations

import json
import struct

from kinefuse.host.link.codec import Encoder
from kinefuse.host.link.crc import x25
from kinefuse.host.link.fakeunit import raw_frames
from kinefuse.host.link.spec import kinefuse_dialect

MINE = ("live_cmd", "record_cmd", "decode_cmd", "stats_cmd")
STORAGE = "parameter storage error: settings may be lost"
RANGE = "stored parameter out of range: default used"


def _capture(tmp_path, n=400):
    """Unit 1: raw samples, a KF_UNIT_STATUS with STORAGE_ERROR | MAG_PRESENT | STREAMING,
    an ERROR and a WARNING STATUSTEXT (text with rich-markup-like brackets in the second)."""
    enc = Encoder(sysid=1, compid=200)
    data = raw_frames(n, rate_hz=200.0)
    data += enc.encode("KF_UNIT_STATUS", time_boot_us=1_000_000, firmware_version=1 << 24, raw_rate_requested=200.0,
                       status_flags=128 | 2 | 1, battery_voltage=0xFFFF, battery_remaining=-1)
    data += enc.encode("STATUSTEXT", severity=3, text=STORAGE, id=0, chunk_seq=0)
    data += enc.encode("STATUSTEXT", severity=4, text=RANGE + " [KF_X]", id=0, chunk_seq=0)
    path = tmp_path / "cap.bin"
    path.write_bytes(data)
    return path


def test_live_prints_statustext_and_the_storage_error_flag(run, tmp_path):
    cap = _capture(tmp_path)
    code, out, err = run("live", "--port", f"file:{cap}", "--seconds", "3")
    assert code == 0, err
    assert f"unit 1 (file:{cap}) says ERROR: {STORAGE}" in out, out
    assert f"says WARNING: {RANGE} [KF_X]" in out
    last = [l for l in out.splitlines() if l.startswith("[")][-1]
    assert "STORAGE ERROR" in last and "mag" in last, last


def test_decode_lists_statustext(run, tmp_path):
    cap = _capture(tmp_path)
    code, out, err = run("decode", "--raw", cap)
    assert code == 0, err
    assert f"unit 1 said ERROR: {STORAGE}" in out and f"unit 1 said WARNING: {RANGE} [KF_X]" in out, out
    code, out, err = run("decode", "--raw", cap, "--json")
    (s,) = json.loads(out)["streams"]
    assert [(e["severity_name"], e["count"]) for e in s["statustexts"]] == [("ERROR", 1), ("WARNING", 1)]


def test_record_shows_statustext_while_recording(run, tmp_path):
    cap = _capture(tmp_path)
    out_file = tmp_path / "r.kfr"
    code, out, err = run("record", "--port", f"file:{cap}", "--out", out_file, "--duration", "1", "--no-timesync")
    assert code == 0, err
    assert f"unit says: unit 1 on file:{cap}: ERROR: {STORAGE}" in out, out
    assert f"WARNING: {RANGE} [KF_X]" in out
    # and stats of the recording lists them
    code, out, err = run("stats", out_file)
    assert code == 0, err
    assert f"unit 1 said ERROR: {STORAGE}" in out, out


def _mismatched_raw(n):
    """KF_RAW_SAMPLE frames whose CRC uses another CRC_EXTRA (a unit of another dialect version)."""
    spec = kinefuse_dialect()["KF_RAW_SAMPLE"]
    data = bytearray(raw_frames(n, rate_hz=1000.0))
    size = 12 + data[1]
    for k in range(0, len(data), size):
        body = bytes(data[k:k + size - 2])
        data[k + size - 2:k + size] = struct.pack("<H", x25(body[1:], (spec.crc_extra + 1) & 0xFF))
    return bytes(data)


def test_record_names_a_dialect_mismatch_not_a_wrong_baud_rate(run, tmp_path):
    """All raw samples failed their CRC (another CRC_EXTRA): the warning said "a damaged link or
    a wrong baud rate?"; crc_extra_mismatches tells the dialect mismatch."""
    enc = Encoder(sysid=1, compid=200)
    hb = enc.encode("HEARTBEAT", type=18, autopilot=8, base_mode=0, custom_mode=0, system_status=4,
                    mavlink_version=3)
    cap = tmp_path / "old.bin"
    cap.write_bytes(hb + _mismatched_raw(2000) + hb)
    code, out, err = run("record", "--port", f"file:{cap}", "--out", tmp_path / "o.kfr", "--duration", "1",
                         "--no-timesync", "--json")
    assert code == 0, err
    warnings = json.loads(out)["warnings"]
    assert any("KF_RAW_SAMPLE" in w and "dialect mismatch" in w for w in warnings), warnings
    assert not any("baud rate" in w for w in warnings), warnings


def test_joint_angle_status_bits_are_named_in_export_and_decode(run, tmp_path):
    """KF_JOINT_ANGLE_STATUS_NUMERIC_RESET (8): no status bit was named anywhere."""
    from kinefuse.host.link.export import export_csv
    from kinefuse.host.link.frames import decode_file
    enc = Encoder(sysid=1, compid=200)
    cap = tmp_path / "ja.bin"
    cap.write_bytes(b"".join(enc.encode("KF_JOINT_ANGLE", time_boot_us=1000 * k, status=9 if k == 0 else 1)
                             for k in range(3)))
    files = export_csv(decode_file(cap, raw=True), tmp_path / "csv")
    (f,) = [x for x in files if "KF_JOINT_ANGLE" in str(x["file"])]
    comments = [l for l in open(f["file"]) if l.startswith("#")]
    assert any("status: bitmask: 1 VALID, 2 NEAR_SINGULARITY, 4 HEADING_UNRELIABLE, 8 NUMERIC_RESET" in c
               for c in comments), comments
    code, out, err = run("decode", "--raw", cap, "--show", "1")
    assert code == 0, err
    assert "status=9, status_bits=VALID|NUMERIC_RESET" in out, out
