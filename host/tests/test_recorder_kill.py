"""Recorder kill at random points (hypothesis state machine).  The unit's bytes arrive in reads
split at random byte boundaries; the recorder's own chunking (``Recorder._tap`` /
``_flush_stream``, 0.25 s chunks) and the writer's flush/fsync policy run on a simulated clock;
at random moments the file is cut as a kill would leave it:

- process kill (SIGKILL): everything handed to the OS survives, the chunk being written may be
  cut at any byte;
- power cut: what was fsynced survives; of the rest any prefix, possibly zero-filled (file size
  written before the data).

Each cut copy must decode without error to exactly the first k samples sent (no corrupted,
duplicated or reordered sample), and every sample received more than 1 s before a power cut
(a process kill: more than one chunk interval plus one loop turn) must be in it.  A really
killed recorder process is tested in test_link_recording.py."""
from __future__ import annotations

import io
import os
import pathlib
import tempfile

import numpy as np
from hypothesis import HealthCheck, settings
from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, initialize, rule

from kinefuse.host.link import recorder as recorder_mod
from kinefuse.host.link import recording
from kinefuse.host.link.batch import decode_all
from kinefuse.host.link.fakeunit import raw_frames
from kinefuse.host.link.frames import decode_file
from kinefuse.host.link.recorder import Recorder, StreamState
from kinefuse.host.link.recording import RecordingWriter, make_header

FRAME = 46
FRAMES = raw_frames(6000, seed=3)
REF = decode_all(FRAMES).arrays[52500]
LOOP_S = 0.05          # Recorder.run turns at least this often (its poll waits <= 0.05 s)


class RecorderKill(RuleBasedStateMachine):
    @initialize()
    def start(self):
        self.dir = tempfile.TemporaryDirectory(prefix="kf-kill-")
        self.path = pathlib.Path(self.dir.name) / "r.kfr"
        self.ns = 10**12
        self.fsynced = 0
        self._patches = [(recording.time, "monotonic", recording.time.monotonic),
                         (recorder_mod.time, "monotonic_ns", recorder_mod.time.monotonic_ns),
                         (recording.os, "fsync", recording.os.fsync)]
        recording.time.monotonic = lambda: self.ns / 1e9
        recorder_mod.time.monotonic_ns = lambda: self.ns
        recording.os.fsync = self._fsync
        rec = Recorder.__new__(Recorder)          # the recorder's chunking code, without ports
        rec.chunk_interval_ns = int(Recorder.CHUNK_INTERVAL_S * 1e9)
        rec.writer = RecordingWriter(self.path, make_header([{"id": 0, "connection": "sim"}]),
                                     fsync_interval=Recorder.FSYNC_INTERVAL_S)
        self.rec, self.stream = rec, StreamState(0, "sim", None)
        self.tap = rec._tap(self.stream)
        self.sent = 0                              # bytes of FRAMES delivered so far
        self.reads = []                            # (end offset, host ns) of every read
        self.chunk_starts = []

    def _fsync(self, fd):
        self.fsynced = os.fstat(fd).st_size

    def teardown(self):
        for obj, name, orig in getattr(self, "_patches", []):
            setattr(obj, name, orig)
        if hasattr(self, "rec"):
            self.rec.writer.close()
            self.dir.cleanup()

    def _read(self, nbytes: int) -> None:
        b = FRAMES[self.sent:self.sent + nbytes]
        if b:
            self.sent += len(b)
            self.tap("rx", self.ns, b)
            self.reads.append((self.sent, self.ns))

    def _turn(self, dt: float) -> None:
        self.ns += int(dt * 1e9)
        before = self.rec.writer.bytes_written
        self.rec._flush_stream(self.stream)
        if self.rec.writer.bytes_written != before:
            self.chunk_starts.append((before, self.ns))

    @rule(nbytes=st.integers(1, 3 * FRAME))
    def receive(self, nbytes):
        """One read of the port: the next bytes of the stream, cut anywhere."""
        self._read(nbytes)

    @rule(dt=st.floats(0.0, LOOP_S))
    def loop_turn(self, dt):
        self._turn(dt)

    @rule(turns=st.integers(1, 40), per_turn=st.integers(0, 200))
    def stream_for(self, turns, per_turn):
        """Steady streaming: a read and a loop turn every LOOP_S (seconds pass)."""
        for _ in range(turns):
            self._read(per_turn)
            self._turn(LOOP_S)

    @rule(kind=st.sampled_from(["process", "power"]), frac=st.floats(0, 1), zeros=st.booleans())
    def kill(self, kind, frac, zeros):
        data = self.path.read_bytes()             # all that reached the OS
        if kind == "process":    # killed now: only a chunk being written now can be cut
            start, at = self.chunk_starts[-1] if self.chunk_starts else (len(data), None)
            lo = start if at == self.ns else len(data)
        else:
            lo = self.fsynced
        cut = lo + int(round(frac * (len(data) - lo)))
        tail = b"\0" * (len(data) - cut) if kind == "power" and zeros else b""
        copy = self.path.with_name("cut.kfr")
        copy.write_bytes(data[:cut] + tail)
        df = decode_file(copy)
        raw = df.streams[0].arrays.get(52500) if 0 in df.streams else None
        k = 0 if raw is None else raw.size
        if k:
            assert np.array_equal(raw["sample_counter"], np.arange(k)), "not a prefix of the samples sent"
            for name in ("acc_x", "gyro_z", "mag_y", "time_boot_us", "temperature"):
                assert np.array_equal(raw[name], REF[name][:k]), name
        bound_s = 1.0 if kind == "power" else Recorder.CHUNK_INTERVAL_S + LOOP_S
        old = [end for end, t in self.reads if t < self.ns - bound_s * 1e9]
        must = old[-1] // FRAME if old else 0
        assert k >= must, f"{kind}: {must - k} samples received more than {bound_s} s before the kill lost"


RecorderKill.TestCase.settings = settings(max_examples=30, stateful_step_count=40, deadline=None,
                                          suppress_health_check=[HealthCheck.too_slow])
TestRecorderKill = RecorderKill.TestCase
