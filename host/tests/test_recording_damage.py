"""Damaged recordings: a damaged RX chunk whose header holds keeps its intact frames (the
MAVLink CRCs drop only those the damage touched), the damage is counted and reported by
`kinefuse stats` (text and JSON); implausible clock fits are flagged and a leading burst of
stale frames is left out of the fit."""
from __future__ import annotations

import io
import json

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from kinefuse.host import cli
from kinefuse.host.errors import KinefuseError
from kinefuse.host.link import recording, stats
from kinefuse.host.link.batch import decode_all
from kinefuse.host.link.codec import Encoder
from kinefuse.host.link.fakeunit import raw_frames
from kinefuse.host.link.frames import decode_file
from kinefuse.host.link.recording import RecordingWriter, load, make_header

FRAME = 46
FRAMES = raw_frames(1200, seed=11)
REF = decode_all(FRAMES).arrays[52500]


def _file(path, frames=FRAMES, per_chunk=51, reads=3):
    """RX chunks of ``per_chunk`` frames (in ``reads`` reads each) of stream 0, 10 ms apart."""
    head = make_header([{"id": 0, "connection": "test"}])
    t = head["start_monotonic_ns"]
    with RecordingWriter(path, head) as w:
        for a in range(0, len(frames), per_chunk * FRAME):
            b = frames[a:a + per_chunk * FRAME]
            cut = np.linspace(0, len(b), reads + 1).astype(int)
            w.rx(0, [(t + 2_000_000 * k, b[cut[k]:cut[k + 1]]) for k in range(reads)])
            t += 10_000_000
    return path


def _rx_chunks(data: bytes):
    _, body = recording.read_header(io.BytesIO(data), "x")
    return [c for c in recording.iter_chunks(data, body) if c.type == recording.RX]


def _counters(path):
    arr = decode_file(path).streams[0].arrays.get(52500)
    return np.zeros(0, np.int64) if arr is None else arr["sample_counter"].astype(np.int64)


def test_one_flipped_bit_costs_one_frame_not_the_chunk(tmp_path):
    p = _file(tmp_path / "a.kfr")
    data = bytearray(p.read_bytes())
    ch = _rx_chunks(bytes(data))[5]
    table = 4 + 8 * 3
    data[ch.offset + recording.CHUNK.size + table + 20 * FRAME + 7] ^= 0x10     # inside frame 20 of chunk 5
    p.write_bytes(bytes(data))
    rec = load(p)
    assert rec.damaged_chunks == 1 and rec.recovered_chunks == 1 and rec.skipped_bytes == 0
    got = _counters(p)
    assert got.tolist() == [k for k in range(1200) if k != 5 * 51 + 20]
    # the frames kept are the ones sent, and keep their read times
    df = decode_file(p)
    assert np.array_equal(df.streams[0].arrays[52500]["acc_x"], np.delete(REF["acc_x"], 5 * 51 + 20))


def test_a_damaged_read_table_keeps_the_bytes_with_the_chunk_time(tmp_path):
    p = _file(tmp_path / "t.kfr")
    data = bytearray(p.read_bytes())
    ch = _rx_chunks(bytes(data))[3]
    data[ch.offset + recording.CHUNK.size + 4 + 2] ^= 0x80       # first read's end offset
    p.write_bytes(bytes(data))
    rec = load(p)
    assert rec.recovered_chunks == 1
    assert _counters(p).tolist() == list(range(1200))             # every frame: only the table broke
    df = decode_file(p)
    host = df.streams[0].host_ns[52500]
    assert np.all(host[3 * 51:4 * 51] == ch.t_ns)                 # one read at the chunk's time
    assert df.streams[0].counters.bytes_skipped >= 24             # the table's bytes, as garbage


def test_a_damaged_header_is_skipped_and_consecutive_damaged_chunks_recovered(tmp_path):
    p = _file(tmp_path / "h.kfr")
    data = bytearray(p.read_bytes())
    chs = _rx_chunks(bytes(data))
    data[chs[2].offset + 5] ^= 0x01                               # length of chunk 2: lost
    for k in (3, 4, 5):                                           # payload bits of chunks 3-5
        data[chs[k].offset + recording.CHUNK.size + 28 + 10 * FRAME + 30] ^= 0x02
    data[chs[6].offset + 8 + 6] ^= 0x40                           # chunk 6: its time field
    p.write_bytes(bytes(data))
    rec = load(p)
    assert rec.damaged_chunks == 5 and rec.recovered_chunks == 4
    got = set(_counters(p).tolist())
    lost = set(range(1200)) - got
    assert set(range(2 * 51, 3 * 51)) <= lost                                        # chunk 2
    assert lost - set(range(2 * 51, 3 * 51 + 1)) == {3 * 51 + 10, 4 * 51 + 10, 5 * 51 + 10}
    host = decode_file(p).streams[0].host_ns[52500]
    assert np.all(np.diff(host) >= 0)                             # the damaged time was replaced


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(flips=st.lists(st.tuples(st.integers(0, 10**9), st.integers(0, 7)), min_size=1, max_size=6))
def test_random_bit_flips_never_accept_a_corrupted_sample(tmp_path, flips):
    p = tmp_path / "r.kfr"
    if not p.exists():
        _file(p, frames=FRAMES[:400 * FRAME])
    clean = p.read_bytes()
    _, body = recording.read_header(io.BytesIO(clean), "x")
    data = bytearray(clean)
    where = set()
    for pos, bit in flips:
        i = body + pos % (len(data) - body)
        data[i] ^= 1 << bit
        where.add(i)
    q = tmp_path / "flipped.kfr"
    q.write_bytes(bytes(data))
    arr = decode_file(q).streams[0].arrays.get(52500)
    got = np.zeros(0, np.int64) if arr is None else arr["sample_counter"].astype(np.int64)
    assert np.all(np.diff(got) > 0)
    for name in ("acc_x", "gyro_y", "mag_z", "time_boot_us"):       # every sample delivered is intact
        assert np.array_equal(arr[name], REF[name][got]) if got.size else True
    # flips only inside frame bytes of RX payloads cost at most one frame each
    chunks = _rx_chunks(clean)
    in_frames = all(any(c.offset + recording.CHUNK.size + 28 <= i < c.offset + recording.CHUNK.size + len(c.payload)
                        for c in chunks) for i in where)
    if in_frames:
        assert 400 - got.size <= len(where)


# ------------------------------------------------------------------------------- stats

def _clock_file(path, stale: int = 0, step_s: float = 0.0):
    """200 Hz for 20 s, unit +20 ppm; ``stale`` samples queued before the start arrive in one
    read; ``step_s``: the delay rises by that much half-way (a latency/offset jump)."""
    head = make_header([{"id": 0, "connection": "synthetic"}])
    t0 = head["start_monotonic_ns"]
    enc = Encoder(sysid=1, compid=200)
    rng = np.random.default_rng(2)
    reads = []
    burst = b""
    for k in range(4000 + stale):
        dev_us = 1_000_000 + 5000 * k
        f = enc.encode("KF_RAW_SAMPLE", time_boot_us=dev_us, sample_counter=k, acc_z=1000, flags=8)
        if k < stale:
            burst += f
            continue
        host = t0 + int((dev_us - 5000 * stale) * 1000 / (1 + 20e-6)) + 1_000_000 + int(rng.exponential(300_000))
        if k > 2000 + stale:
            host += int(step_s * 1e9)
        if burst:
            reads.append((host - 1000, burst))
            burst = b""
        reads.append((host, f))
    with RecordingWriter(path, head) as w:
        for a in range(0, len(reads), 100):
            w.rx(0, reads[a:a + 100])
    return path


def test_a_leading_stale_burst_is_left_out_of_the_clock_fit(tmp_path):
    p = _clock_file(tmp_path / "stale.kfr", stale=3000)     # 15 s queued before a 20 s recording
    (u,) = stats.compute(decode_file(p))["streams"][0]["units"]
    c = u["clock"]
    # the burst's last ~10 frames (< 50 ms old) are indistinguishable from live ones, and harmless
    assert 3000 - 12 <= c["excluded_leading"] <= 3000 and abs(c["drift_ppm"] - 20) < 5
    assert c["delay_above_min_ms"]["p95"] < 5
    assert any(f"{c['excluded_leading']} frames" in w and "burst" in w for w in u["warnings"])
    # without leaving them out the fit is what the audit saw: absurd
    arr = decode_file(p).streams[0]
    t = arr.arrays[52500]["time_boot_us"] / 1e6
    h = (arr.host_ns[52500] - decode_file(p).start_monotonic_ns) / 1e9
    assert abs(stats.fit_clock(t, h)["drift_ppm"]) > 1000


def test_an_implausible_drift_and_a_jump_are_flagged(tmp_path, capsys):
    p = _clock_file(tmp_path / "jump.kfr", step_s=0.08)
    r = stats.compute(decode_file(p))
    assert any("minimum delay changes by" in w for w in r["warnings"])
    good = stats.compute(decode_file(_clock_file(tmp_path / "ok.kfr")))
    assert good["warnings"] == [] and good["streams"][0]["units"][0]["clock"]["excluded_leading"] == 0
    dev = np.arange(0, 10, 0.005)
    fit = stats.fit_clock_checked(dev, 3.0 + dev * 1.002)                # a 2000 ppm "unit"
    assert any("implausible clock fit" in w for w in fit["warnings"])


def test_stats_reports_damaged_chunks_in_text_and_json(tmp_path, capsys):
    p = _file(tmp_path / "d.kfr")
    data = bytearray(p.read_bytes())
    chs = _rx_chunks(bytes(data))
    data[chs[1].offset + recording.CHUNK.size + 28 + 5] ^= 0x01
    data[chs[7].offset + 1] ^= 0x01                               # marker: skipped
    p.write_bytes(bytes(data))
    assert cli.main(["stats", str(p), "--json"]) == 0
    r = json.loads(capsys.readouterr().out)
    assert r["file_damage"] == {"chunks": len(chs) - 1, "damaged_chunks": 2, "recovered_chunks": 1,
                                "skipped_bytes": chs[8].offset - chs[7].offset, "truncated": False}
    assert any(w.startswith("2 damaged chunk(s): 1 recovered") for w in r["warnings"])
    assert cli.main(["stats", str(p)]) == 0
    out = capsys.readouterr().out
    assert "2 damaged (1 recovered)" in out and "warning: 2 damaged chunk(s)" in " ".join(out.split())


def test_kfr_reader_warning_counts_recovered_and_skipped_chunks(tmp_path):
    from kinefuse.host.readers import read_recording
    p = _file(tmp_path / "r.kfr")
    data = bytearray(p.read_bytes())
    chs = _rx_chunks(bytes(data))
    data[chs[2].offset + 5] ^= 0x01                               # header of chunk 2: skipped
    data[chs[5].offset + recording.CHUNK.size + 28 + 10 * FRAME + 30] ^= 0x02   # payload: recovered
    p.write_bytes(bytes(data))
    rec = read_recording(str(p), fmt="kfr")
    damage = [w for w in rec.warnings if "damaged chunk" in w]
    assert len(damage) == 1, rec.warnings
    assert "2 damaged chunk(s): 1 recovered" in damage[0] and "1 skipped" in damage[0], damage
    assert "chunk(s) skipped" not in damage[0]                   # the old message claimed all skipped
    assert rec.metadata["samples_lost"] == 51 + 1                 # chunk 2 and one frame of chunk 5


def test_a_stale_burst_longer_than_the_live_part_is_found_and_the_reader_maps_it(tmp_path):
    """30 s queued before a 20 s recording (a unit that streamed into a pty nobody read): most
    frames are stale, yet the burst is found, the fit is the live one, and the reader's host
    times of the queued samples lie before the start, spaced like the unit's clock."""
    from kinefuse.host.readers import read_recording
    p = _clock_file(tmp_path / "stale_long.kfr", stale=6000)
    (u,) = stats.compute(decode_file(p))["streams"][0]["units"]
    c = u["clock"]
    assert 6000 - 12 <= c["excluded_leading"] <= 6000 and abs(c["drift_ppm"] - 20) < 5
    rec = read_recording(str(p), "kfr")
    t = np.asarray(rec.t)
    assert t[0] < -25.0 and np.allclose(np.diff(t[:6000]), 0.005, atol=1e-6)


def test_a_flipped_bit_in_the_file_header_keeps_the_recording(tmp_path):
    """One flipped bit in the header's JSON made the whole recording unreadable ('header is
    damaged'); while the JSON still reads it is used, and every reader says so.  A header
    whose JSON no longer reads is still a one-line error."""
    p = _file(tmp_path / "h.kfr")
    data = bytearray(p.read_bytes())
    i = data.find(b'"connection": "test"') + len('"connection": "t')
    data[i] ^= 0x01                                       # "test" -> "tdst"
    p.write_bytes(bytes(data))
    rec = load(p)
    assert rec.header_damaged and rec.damaged_chunks == 1 and rec.recovered_chunks == 0
    assert _counters(p).tolist() == list(range(1200))     # every frame
    assert "file header is damaged" in stats.damage_text(rec)
    r = stats.compute(decode_file(p))
    assert any("file header is damaged" in w for w in r["warnings"])
    data[recording.FILE_HEAD.size] ^= 0x20                # '{' -> '[': not JSON any more
    p.write_bytes(bytes(data))
    with pytest.raises(KinefuseError, match="header is damaged"):
        load(p)
