"""Data-integrity cases of recordings: two units with one system id on one link, reboots."""
from __future__ import annotations

import json

import numpy as np
import pytest

from kinefuse.host.link import stats
from kinefuse.host.link.frames import decode_file
from kinefuse.host.readers import ReaderError, read_recording

from test_readers_kfr import _frames, _motion, _write_kfr

MINE = ("decode_cmd", "export_cmd", "stats_cmd")   # commands these tests run (see conftest.run)


def _same_id_on_one_link(path):
    """Two units, both system id 1, on one stream (behind one radio): 200 Hz each, booted 0.5 s
    and 7.3 s before the recording, their frames interleaved as they arrive."""
    t, acc, gyr, mag = _motion(2000)
    f1, _ = _frames(t, acc, gyr, mag, sysid=1, boot_s=0.5, drift_ppm=150)
    f2, _ = _frames(t + 0.0025, -acc, gyr, mag, sysid=1, boot_s=7.3, drift_ppm=-80, counter0=5000)
    items = sorted([(t[k], f1[k]) for k in range(2000)] + [(t[k] + 0.0025, f2[k]) for k in range(2000)],
                   key=lambda x: x[0])
    _write_kfr(path, [items])


def test_two_units_with_one_system_id_are_named_not_mixed(run, tmp_path):
    """stats said 0.15 Hz, 1999 resets and no warning; the kfr reader returned the two units'
    samples mixed into one series (with half of them "overlapping" dropped); export wrote them
    into one CSV without a word."""
    p = tmp_path / "same.kfr"
    _same_id_on_one_link(p)
    r = stats.compute(decode_file(p))
    assert [w for w in r["warnings"] if "two units with the same system id" in w and "unit 1" in w], r["warnings"]
    with pytest.raises(ReaderError) as e:
        read_recording(str(p))
    assert "two units with the same system id" in str(e.value) and "\n" not in str(e.value)
    code, out, err = run("export", p, "--out", tmp_path / "csv", "--json")
    assert code == 0, err
    assert any("two units with the same system id" in w for w in json.loads(out)["warnings"])
    # its unit line named all 2000 clock segments: one 300 kB comment line
    comments = [ln for ln in (tmp_path / "csv" / "KF_RAW_SAMPLE.csv").read_text().splitlines()
                if ln.startswith("#")]
    assert max(len(c) for c in comments) < 5000 and any("1,990 more device-clock segments" in c for c in comments)


def test_reboots_are_not_taken_for_two_units(tmp_path):
    """A unit rebooting six times (each restart near its boot time) stays one unit."""
    n = 600
    t, acc, gyr, mag = _motion(7 * n)
    items = []
    for k in range(7):
        sl = slice(k * n, (k + 1) * n)
        fr, _ = _frames(t[sl] - t[k * n], acc[sl], gyr[sl], mag[sl], sysid=3, boot_s=0.4 + 0.01 * (k % 2),
                        drift_ppm=20)
        items += [(t[k * n + i] + 0.2 * k, fr[i]) for i in range(n)]
    p = tmp_path / "reboots.kfr"
    _write_kfr(p, [items])
    r = stats.compute(decode_file(p))
    m = r["streams"][0]["units"][0]["messages"]["KF_RAW_SAMPLE"]
    assert m["resets"] == 6 and "interleaved_clocks" not in m
    assert not any("same system id" in w for w in r["warnings"])
    rec = read_recording(str(p))
    assert rec.metadata["device_clock_segments"] == 7 and len(rec) == 7 * n


def _wrong_extra_frames(n, extra_delta=7, seed=0):
    """KF_RAW_SAMPLE frames encoded with a CRC_EXTRA off by ``extra_delta`` (a unit built with
    another version of the message), between good KF_UNIT_STATUS frames."""
    from types import SimpleNamespace
    from kinefuse.host.link.codec import Encoder, frame_from_payload
    enc = Encoder(sysid=2, compid=200)
    spec, _ = enc.payload("KF_RAW_SAMPLE", {})
    other = SimpleNamespace(msgid=spec.msgid, crc_extra=(spec.crc_extra + extra_delta) % 256)
    out = b""
    for k in range(n):
        _, payload = enc.payload("KF_RAW_SAMPLE", {"time_boot_us": 1000 * k, "sample_counter": k,
                                                   "acc_z": 1000, "flags": 16})
        out += frame_from_payload(other, payload, 2, 200, k)
        if k % 10 == 0:
            out += enc.encode("KF_UNIT_STATUS", time_boot_us=1000 * k, unit_id=2)
    return out, spec.crc_extra, other.crc_extra


def test_a_crc_extra_mismatch_is_named(tmp_path):
    """Frames of a message whose CRC_EXTRA differs (another version of the dialect) were only
    CRC errors: every one dropped, no reason given."""
    data, ours, theirs = _wrong_extra_frames(60)
    p = tmp_path / "cap.bin"
    p.write_bytes(data)
    df = decode_file(p, raw=True)
    assert 52500 not in df.streams[0].arrays and df.streams[0].counters.crc_errors == 60
    r = stats.compute(df)
    mm = r["streams"][0]["crc_extra_mismatch"]
    assert mm == [{"message": "KF_RAW_SAMPLE", "failed": 60, "crc_extra": ours, "crc_extra_found": theirs}]
    assert any("KF_RAW_SAMPLE" in w and "dialect mismatch" in w for w in r["warnings"])


def test_corrupted_frames_are_not_taken_for_a_crc_extra_mismatch(tmp_path):
    from kinefuse.host.link.codec import Encoder
    enc = Encoder(sysid=2, compid=200)
    rng = np.random.default_rng(1)
    frames = [bytearray(enc.encode("KF_RAW_SAMPLE", time_boot_us=1000 * k, sample_counter=k, acc_z=1000))
              for k in range(400)]
    for f in frames[::4]:                      # a flipped bit in every fourth frame
        i = int(rng.integers(10, len(f) - 2))
        f[i] ^= 1 << int(rng.integers(8))
    p = tmp_path / "noisy.bin"
    p.write_bytes(b"".join(frames))
    df = decode_file(p, raw=True)
    assert df.streams[0].counters.crc_errors >= 100
    r = stats.compute(df)
    assert r["streams"][0]["crc_extra_mismatch"] == []
    assert not any("dialect mismatch" in w for w in r["warnings"])


def test_decode_names_a_crc_extra_mismatch(run, tmp_path):
    data, ours, theirs = _wrong_extra_frames(30)
    p = tmp_path / "cap.bin"
    p.write_bytes(data)
    code, out, err = run("decode", p, "--raw")
    assert code == 0, err
    assert "KF_RAW_SAMPLE" in out and "dialect mismatch" in out and f"check with {theirs}" in out
    code, out, err = run("decode", p, "--raw", "--json")
    assert json.loads(out)["streams"][0]["crc_extra_mismatch"][0]["crc_extra_found"] == theirs


def test_export_states_the_frames_of_joint_angles_and_the_units_of_efforts(run, tmp_path):
    """KF_JOINT_ANGLE's CSV named neither the segment frames nor the angle sequence, KF_EFFORTS'
    effort_<i>_si not the unit."""
    from kinefuse.host.link.codec import Encoder
    enc = Encoder(sysid=4, compid=200)
    data = b"".join(enc.encode("KF_JOINT_ANGLE", time_boot_us=1000 * k, sample_counter=k, angle_1=0.1 * k,
                               joint_id=4, sequence=5) for k in range(5))
    data += b"".join(enc.encode("KF_EFFORTS", time_boot_us=1000 * k, sample_counter=k, model_id=7, count=2,
                                effort=[1.0, 2.0]) for k in range(5))
    p = tmp_path / "cap.bin"
    p.write_bytes(data)
    code, out, err = run("export", p, "--raw", "--out", tmp_path / "csv")
    assert code == 0, err
    text = (tmp_path / "csv" / "KF_JOINT_ANGLE.csv").read_text()
    comments = [ln for ln in text.splitlines() if ln.startswith("#")]
    assert any("proximal" in c and "distal" in c and "5 ZXY" in c for c in comments), comments
    header = next(ln for ln in text.splitlines() if not ln.startswith("#")).split(",")
    assert {"angle_1_rad", "angle_2_rad", "angle_3_rad", "sequence", "joint_id"} <= set(header)
    text = (tmp_path / "csv" / "KF_EFFORTS.csv").read_text()
    assert "effort_0_si" in text and any("effort_<i>_si" in ln and "N m" in ln
                                          for ln in text.splitlines() if ln.startswith("#"))


def test_a_tlog_whose_clock_steps_back_keeps_its_frame_order(run, tmp_path):
    """A tlog is stamped with the host's wall clock; one stepping back 2 s (an NTP correction)
    made export sort the later frames before the earlier ones (t_s and sample_counter jumping
    back and forth in the CSV)."""
    from kinefuse.host.link.codec import Encoder
    enc = Encoder(sysid=2, compid=200)
    stamp = 1_700_000_000_000_000
    data = b""
    for k in range(40):
        stamp += 5000 if k != 20 else -2_000_000
        data += stamp.to_bytes(8, "big") + enc.encode("KF_RAW_SAMPLE", time_boot_us=5000 * k, sample_counter=k,
                                                        acc_z=1000)
    p = tmp_path / "x.tlog"
    p.write_bytes(data)
    code, out, err = run("export", p, "--out", tmp_path / "csv", "--messages", "KF_RAW_SAMPLE")
    assert code == 0, err
    rows = [ln.split(",") for ln in (tmp_path / "csv" / "KF_RAW_SAMPLE.csv").read_text().splitlines()
            if not ln.startswith("#")]
    counter = [int(r[rows[0].index("sample_counter")]) for r in rows[1:]]
    assert counter == list(range(40))


def test_decode_and_stats_name_the_unknown_message_ids(run, tmp_path):
    """Frames of a message this kinefuse does not know (a newer firmware) were only "50 unknown
    ids": now the id and its count are named."""
    from types import SimpleNamespace
    from kinefuse.host.link.codec import Encoder, frame_from_payload
    enc = Encoder(sysid=2, compid=200)
    newer = SimpleNamespace(msgid=52599, crc_extra=77)
    data = b""
    for k in range(50):
        data += enc.encode("KF_RAW_SAMPLE", time_boot_us=1000 * k, sample_counter=k, acc_z=1000)
        data += frame_from_payload(newer, bytes([k + 1, 2, 3, 4]), 2, 200, k)
    p = tmp_path / "cap.bin"
    p.write_bytes(data)
    df = decode_file(p, raw=True)
    assert df.streams[0].unknown_ids == {52599: 50} and df.streams[0].counters.unknown_msgid == 50
    for cmd in ("decode", "stats"):
        code, out, err = run(cmd, p, "--raw")
        assert code == 0, err
        assert "52599 x50" in out, out
    code, out, err = run("decode", p, "--raw", "--json")
    assert json.loads(out)["streams"][0]["unknown_ids"] == {"52599": 50}


def test_a_status_delivered_again_does_not_move_the_rate_change(tmp_path):
    """The rate change (100 -> 400 Hz at 10 s) was dated by the statuses after the unit's
    last step back of the clock: a status of 3 s delivered again at 14 s counted as a reboot,
    so the change was put at 15 s and the rate measured from there."""
    from kinefuse.host.link.codec import Encoder
    from kinefuse.host.link.recording import RecordingWriter, make_header
    path = tmp_path / "c.kfr"
    head = make_header([{"id": 0, "connection": "synthetic"}])
    t0 = head["start_monotonic_ns"]
    enc = Encoder(sysid=4, compid=200)
    reads, dev_us, k, last_status = [], 0, 0, -1
    replay = None
    while dev_us < 20_000_000:
        req = 100.0 if dev_us < 10_000_000 else 400.0
        frame = enc.encode("KF_RAW_SAMPLE", time_boot_us=dev_us, sample_counter=k, acc_z=1000, flags=8)
        if dev_us // 1_000_000 != last_status:
            last_status = dev_us // 1_000_000
            status = enc.encode("KF_UNIT_STATUS", time_boot_us=dev_us, raw_rate_requested=req, dialect_hash=0)
            frame += status
            if last_status == 3:
                replay = status
            if last_status == 14:
                frame += replay
        reads.append((t0 + 1000 * dev_us + 2_000_000, frame))
        dev_us += int(1e6 / req)
        k += 1
    reads.append((reads[-1][0] + 1000, replay))     # and once more as the file's last frame
    with RecordingWriter(path, head) as w:
        for a in range(0, len(reads), 50):
            w.rx(0, reads[a:a + 50])
    m = stats.compute(decode_file(path))["streams"][0]["units"][0]["messages"]["KF_RAW_SAMPLE"]
    assert m["requested_changes"] == 1 and m["rate_from_device_s"] == 10.0
    assert m["rate_hz"] == pytest.approx(400.0, rel=1e-9)
    assert m["requested_hz"] == 400.0 and m["rate_ratio"] == pytest.approx(1.0, rel=1e-9)   # was 100 Hz: 4.0


def test_export_states_the_frames_of_the_standard_attitude_and_imu_messages(run, tmp_path):
    """A unit also sends ATTITUDE_QUATERNION (NED) and HIGHRES_IMU for ground stations: their
    CSVs had q1..q4 with neither the order (w first) nor the frame (NED, not the ENU of
    KF_ORIENTATION)."""
    from kinefuse.host.link.codec import Encoder
    enc = Encoder(sysid=4, compid=200)
    data = b"".join(enc.encode("ATTITUDE_QUATERNION", time_boot_ms=k, q1=1.0) for k in range(3))
    data += b"".join(enc.encode("HIGHRES_IMU", time_usec=k, zacc=9.8) for k in range(3))
    p = tmp_path / "cap.bin"
    p.write_bytes(data)
    code, out, err = run("export", p, "--raw", "--out", tmp_path / "csv")
    assert code == 0, err
    for name, words in (("ATTITUDE_QUATERNION", ("w, x, y, z", "NED")), ("HIGHRES_IMU", ("sensor axes", "xmag_gauss"))):
        comments = [ln for ln in (tmp_path / "csv" / f"{name}.csv").read_text().splitlines() if ln.startswith("#")]
        assert any(all(w in c for w in words) for c in comments), comments


def test_a_key_file_saved_with_a_bom_holds_the_same_key(tmp_path):
    """Notepad writes a UTF-8 BOM: its 64 hex digits were read as a passphrase (the key its
    SHA-256), silently another key than the one in the file."""
    from kinefuse.host.link.signing import read_key_file
    hexkey = "00112233445566778899aabbccddeeff" * 2
    p = tmp_path / "unit.key"
    p.write_bytes(b"\xef\xbb\xbf" + hexkey.encode() + b"\r\n")
    assert read_key_file(p) == bytes.fromhex(hexkey)
    p.write_bytes(b"\xef\xbb\xbfmy passphrase\r\n")
    q = tmp_path / "plain.key"
    q.write_bytes(b"my passphrase\n")
    assert read_key_file(p) == read_key_file(q)


def test_frames_swapped_on_the_way_are_not_taken_for_two_units(tmp_path):
    """A link that swaps neighbouring frames now and then (UDP): each late frame steps the clock
    back by one sample, later and later in the recording, but it is one unit."""
    t, acc, gyr, mag = _motion(2000)
    fr, _ = _frames(t, acc, gyr, mag, sysid=5, boot_s=2.0, drift_ppm=10)
    order = list(range(2000))
    for k in range(100, 1900, 150):
        order[k], order[k + 1] = order[k + 1], order[k]
    p = tmp_path / "swapped.kfr"
    _write_kfr(p, [[(t[max(k, j)], fr[j]) for k, j in enumerate(order)]])
    assert stats.interleaved_clocks(*_raw_columns(p)) is None
    r = stats.compute(decode_file(p))
    assert not any("same system id" in w for w in r["warnings"])
    read_recording(str(p))     # read, not refused


def _raw_columns(path):
    arr = decode_file(path).streams[0].arrays[52500]
    return arr["time_boot_us"], arr["sample_counter"]


def test_export_warns_of_a_message_lost_to_a_crc_extra_mismatch(run, tmp_path):
    """export wrote KF_UNIT_STATUS.csv and said nothing of the 40 KF_RAW_SAMPLE frames that all
    failed their CRC (another version of the message)."""
    data, ours, theirs = _wrong_extra_frames(40)
    p = tmp_path / "cap.bin"
    p.write_bytes(data)
    code, out, err = run("export", p, "--raw", "--out", tmp_path / "csv", "--json")
    assert code == 0, err
    res = json.loads(out)
    assert [f["message"] for f in res["files"]] == ["KF_UNIT_STATUS"]
    assert any("40 KF_RAW_SAMPLE" in w and "missing from the CSVs" in w for w in res["warnings"]), res["warnings"]
