"""The .kfr recording: round trip, truncation at any byte, damage, a really killed recorder, fsync."""
from __future__ import annotations

import io
import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from kinefuse.host.errors import KinefuseError
from kinefuse.host.link import recording
from kinefuse.host.link.decoder import decode_bytes
from kinefuse.host.link.fakeunit import raw_frames
from kinefuse.host.link.frames import decode_file
from kinefuse.host.link.recording import RecordingWriter, load, make_header

FRAME = 46  # bytes of a full KF_RAW_SAMPLE frame


def _write(path, frames: bytes, reads_per_chunk=5, read_size=300, t0=10**12, dt_ns=2_000_000):
    """RX chunks of several reads each; read k at t0 + k * dt_ns; returns [(end offset, t_ns)]."""
    head = make_header([{"id": 0, "connection": "test"}, {"id": 1, "connection": "test2"}])
    head["start_monotonic_ns"] = t0
    reads, pos, k = [], 0, 0
    with RecordingWriter(path, head) as w:
        while pos < len(frames):
            chunk = []
            for _ in range(reads_per_chunk):
                if pos >= len(frames):
                    break
                b = frames[pos:pos + read_size]
                chunk.append((t0 + k * dt_ns, b))
                pos += len(b)
                reads.append((pos, t0 + k * dt_ns))
                k += 1
            w.rx(0, chunk)
            w.tx(1, b"\x01\x02")
            w.meta(1, {"type": "event", "event": "test", "k": k})
    return reads


def test_round_trip_streams_reads_meta(tmp_path):
    frames = raw_frames(500, seed=1)
    reads = _write(tmp_path / "a.kfr", frames)
    rec = load(tmp_path / "a.kfr")
    assert rec.header["format"] == "kinefuse-recording" and rec.header["dialect"]["hash"].startswith("0x")
    assert not rec.truncated and rec.damaged_chunks == 0
    s0 = rec.streams[0]
    assert s0.rx == frames
    assert s0.read_end.tolist() == [e for e, _ in reads]
    assert s0.read_t_ns.tolist() == [t for _, t in reads]  # reads 2 ms apart: none merged
    assert rec.streams[1].tx == b"\x01\x02" * len(rec.streams[1].meta)
    assert rec.streams[1].meta[0]["event"] == "test"
    # host time of each frame = time of the read that completed it
    df = decode_file(tmp_path / "a.kfr")
    arr, host = df.streams[0].arrays[52500], df.streams[0].host_ns[52500]
    ends = arr["_offset"] + FRAME
    want = [next(t for e, t in reads if e >= end) for end in ends]
    assert host.tolist() == want


def test_close_reads_are_merged_with_the_later_time(tmp_path):
    head = make_header([{"id": 0}])
    with RecordingWriter(tmp_path / "m.kfr", head) as w:
        w.rx(0, [(1_000_000, b"ab"), (1_300_000, b"cd"), (5_000_000, b"ef")])  # 0.3 ms apart, then 4 ms
    s = load(tmp_path / "m.kfr").streams[0]
    assert s.rx == b"abcdef"
    assert s.read_end.tolist() == [4, 6] and s.read_t_ns.tolist() == [1_300_000, 5_000_000]


@pytest.fixture(scope="module")
def recorded(tmp_path_factory):
    p = tmp_path_factory.mktemp("rec") / "t.kfr"
    frames = raw_frames(300, seed=3)
    _write(p, frames, reads_per_chunk=3, read_size=257)
    return p.read_bytes(), frames


@pytest.mark.parametrize("n", [8, 9, 13, 20])
def test_a_file_cut_within_its_header_says_so(tmp_path, recorded, n):
    """Cut within the first 14 bytes (magic, version, length) it was 'not a kinefuse recording'."""
    p = tmp_path / "t.kfr"
    p.write_bytes(recorded[0][:n])
    with pytest.raises(KinefuseError, match="recording header is truncated"):
        load(p)


@settings(max_examples=300, deadline=None)
@given(cut=st.floats(0, 1))
def test_truncated_anywhere_decodes_up_to_the_cut(tmp_path_factory, recorded, cut):
    data, frames = recorded
    n = int(cut * len(data))
    p = tmp_path_factory.mktemp("cut") / "t.kfr"
    p.write_bytes(data[:n])
    head_len = recording.FILE_HEAD.size + int.from_bytes(data[10:14], "little") + 4
    if n < head_len:
        with pytest.raises(KinefuseError):
            load(p)
        return
    rec = load(p)  # never raises past the header
    got, _ = decode_bytes(rec.streams[0].rx if 0 in rec.streams else b"")
    sent, _ = decode_bytes(frames)
    assert [f.msg for f in got] == [f.msg for f in sent[:len(got)]]  # a prefix, nothing invented
    # everything in chunks completed before the cut is there
    complete = 0
    for ch in recording.iter_chunks(data[:n], head_len):
        if ch.type == recording.RX and not ch.truncated:
            complete += len(recording._rx_parts(ch)[0])
    assert len(got) >= complete // FRAME
    boundaries = {head_len, len(data)} | {ch.offset for ch in recording.iter_chunks(data, head_len)}
    assert rec.truncated == (n not in boundaries)


def test_damaged_chunk_is_skipped(tmp_path):
    frames = raw_frames(200, seed=5)
    _write(tmp_path / "d.kfr", frames, reads_per_chunk=2, read_size=200)
    data = bytearray((tmp_path / "d.kfr").read_bytes())
    _, body = recording.read_header(io.BytesIO(bytes(data)), "d.kfr")
    second = list(recording.iter_chunks(bytes(data), body))[3]  # the second RX chunk
    assert second.type == recording.RX and len(second.payload) > 50
    data[second.offset + recording.CHUNK.size + 50] ^= 0xFF  # damage its payload
    (tmp_path / "d.kfr").write_bytes(bytes(data))
    rec = load(tmp_path / "d.kfr")
    assert rec.damaged_chunks == 1
    got, _ = decode_bytes(rec.streams[0].rx)
    assert len(got) >= 200 - 2 * 200 // FRAME - 2  # lost at most the frames touching that chunk


def test_damage_resync_ignores_markers_inside_payloads(tmp_path):
    """A damaged chunk whose payload holds "kc" bytes is one damaged stretch, and what follows survives."""
    head = make_header([{"id": 0}])
    payloads = [bytes([k]) * 40 + recording.MARKER * 30 + bytes([k]) * 40 for k in range(6)]
    with RecordingWriter(tmp_path / "m.kfr", head) as w:
        for k, p in enumerate(payloads):
            w.rx(0, [(10**9 + k, p)])
    data = bytearray((tmp_path / "m.kfr").read_bytes())
    _, body = recording.read_header(io.BytesIO(bytes(data)), "m.kfr")
    chunks = [c for c in recording.iter_chunks(bytes(data), body) if c.type == recording.RX]
    data[chunks[2].offset + recording.CHUNK.size + 20] ^= 0xFF
    rec = load_bytes(tmp_path, data)
    assert rec.damaged_chunks == 1 and not rec.truncated
    # its header is intact: the bytes are kept (the MAVLink CRCs judge the frames in them)
    damaged = bytearray(payloads[2])
    damaged[20 - 12] ^= 0xFF                      # payload = u32 count + one 8-byte read entry + bytes
    assert rec.recovered_chunks == 1
    assert rec.streams[0].rx == b"".join(payloads[:2] + [bytes(damaged)] + payloads[3:])
    data[chunks[2].offset + 4] ^= 0x40            # its length too: now skipped, the rest still found
    rec = load_bytes(tmp_path, data)
    assert rec.damaged_chunks == 1 and rec.recovered_chunks == 0
    assert rec.streams[0].rx == b"".join(payloads[:2] + payloads[3:])


def load_bytes(tmp_path, data):
    (tmp_path / "x.kfr").write_bytes(bytes(data))
    return load(tmp_path / "x.kfr")


def test_not_a_recording_and_missing(tmp_path):
    (tmp_path / "x.kfr").write_bytes(b"hello world, not a recording" * 10)
    with pytest.raises(KinefuseError, match="not a kinefuse recording"):
        load(tmp_path / "x.kfr")
    with pytest.raises(KinefuseError, match="no such file"):
        load(tmp_path / "missing.kfr")
    with pytest.raises(KinefuseError, match="directory"):
        load(tmp_path)


def test_fsync_at_least_every_second(tmp_path, monkeypatch):
    clock = [0.0]
    synced = []
    monkeypatch.setattr(recording.time, "monotonic", lambda: clock[0])
    monkeypatch.setattr(recording.os, "fsync", lambda fd: synced.append(clock[0]))
    w = RecordingWriter(tmp_path / "f.kfr", make_header([{"id": 0}]), fsync_interval=1.0)
    for k in range(100):  # a chunk every 0.1 s for 10 s
        clock[0] = 0.1 * (k + 1)
        w.rx(0, [(k, b"x" * 10)])
    w.close()
    gaps = np.diff([0.0] + synced)
    assert gaps.max() <= 1.0 + 1e-9 and len(synced) >= 10


KILL_SCRIPT = textwrap.dedent("""
    import sys, time
    from kinefuse.host.link.recorder import Recorder
    rec = Recorder(sys.argv[1], ["fake:rate=500"], chunk_interval=0.25, fsync_interval=1.0)
    print("started", time.monotonic_ns(), rec.header["start_monotonic_ns"], flush=True)
    rec.run(60)
""")


def test_killed_recorder_loses_at_most_a_second(tmp_path):
    out = tmp_path / "killed.kfr"
    p = subprocess.Popen([sys.executable, "-c", KILL_SCRIPT, str(out)], stdout=subprocess.PIPE, text=True)
    try:
        line = p.stdout.readline().split()
        assert line[0] == "started"
        start_mono = int(line[2])
        time.sleep(2.0)
        killed_at = time.monotonic_ns()
        os.kill(p.pid, signal.SIGKILL)
        p.wait(10)
    finally:
        if p.poll() is None:
            p.kill()
    df = decode_file(out)
    assert df.recording.chunks > 0
    host = df.streams[0].host_ns[52500]
    last = (host.max() - start_mono) / 1e9
    alive = (killed_at - start_mono) / 1e9
    assert alive - last <= 1.0, (alive, last)
    assert df.streams[0].arrays[52500].size >= 500 * (last - 0.5)


def test_tlog_frames_and_times_match_pymavlink(tmp_path):
    import struct as _struct
    from kinefuse.host.link.dialect import use_with_mavutil
    frames = raw_frames(300, unit_id=4, seed=9)
    t0_us = 1_700_000_000_000_000
    log = b"".join(_struct.pack(">Q", t0_us + 5000 * k) + frames[k * FRAME:(k + 1) * FRAME] for k in range(300))
    path = tmp_path / "flight.tlog"
    path.write_bytes(log)
    df = decode_file(path)
    arr, host = df.streams[0].arrays[52500], df.streams[0].host_ns[52500]
    assert arr.size == 300 and df.start_unix_ns == t0_us * 1000
    assert (host // 1000).tolist() == [t0_us + 5000 * k for k in range(300)]
    mavutil = use_with_mavutil()
    conn = mavutil.mavlink_connection(str(path))
    ref = []
    while True:
        m = conn.recv_match(type="KF_RAW_SAMPLE")
        if m is None:
            break
        ref.append((m.sample_counter, round(m._timestamp * 1e6)))
    assert ref == [(int(c), int(h // 1000)) for c, h in zip(arr["sample_counter"], host)]


def test_reads_every_half_millisecond_keep_their_times(tmp_path):
    """Reads 0.5 ms apart (a USB CDC unit at 1 kHz): merging compared each read with the
    entry's latest read, so the whole chunk chained into one entry and every frame in it got
    the last read's time (here 49.5 ms late for the first)."""
    head = make_header([{"id": 0}])
    reads = [(10**9 + k * 500_000, bytes([k])) for k in range(100)]
    with RecordingWriter(tmp_path / "h.kfr", head) as w:
        w.rx(0, reads)
    s = load(tmp_path / "h.kfr").streams[0]
    assert s.rx == bytes(range(100))
    got = s.host_time_ns(np.arange(1, 101))          # time of the read holding byte k
    true = np.array([t for t, _ in reads])
    assert np.all(got >= true) and np.max(got - true) < 1_000_000
