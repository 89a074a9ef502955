"""Decode a recording (or a raw MAVLink capture) into per-stream, per-message arrays.

    streams = decode_file("walk.kfr")
    s = streams[0]
    raw = s.arrays[52500]          # structured array: _offset, _seq, _sysid, _compid, _signed, _len, fields...
    t = s.host_ns[52500]           # host monotonic ns of each frame (read that completed it)

Decoding uses :func:`kinefuse.host.link.batch.decode_all`, which yields exactly the frames of the
streaming decoder, at numpy speed.
"""
from __future__ import annotations

import contextvars
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.batch import decode_all
from kinefuse.host.link.decoder import Counters
from kinefuse.host.link.recording import MAGIC, Recording, StreamData, load


# progress of decode_file when no callback is passed: tick(fraction in 0..1) or None
PROGRESS: contextvars.ContextVar = contextvars.ContextVar("kinefuse_decode_progress", default=None)


@dataclass
class DecodedStream:
    stream: int
    info: dict
    counters: Counters
    arrays: dict = field(default_factory=dict)   # msgid -> structured array
    host_ns: dict = field(default_factory=dict)  # msgid -> int64 host monotonic ns (None: raw file)
    meta: list = field(default_factory=list)
    rx_bytes: int = 0
    unknown_ids: dict = field(default_factory=dict)  # unknown message id -> candidates


@dataclass
class DecodedFile:
    path: Path
    recording: Recording | None      # None for a raw capture or a tlog
    streams: dict                    # stream id -> DecodedStream
    clock: tuple | None = None       # (start host ns, start UNIX ns) when not from a recording
    kind: str = "raw MAVLink capture"

    @property
    def start_monotonic_ns(self) -> int:
        return self.recording.start_monotonic_ns if self.recording else (self.clock or (0, 0))[0]

    @property
    def start_unix_ns(self) -> int:
        return self.recording.start_unix_ns if self.recording else (self.clock or (0, 0))[1]

    @property
    def header(self) -> dict:
        if self.recording:
            return self.recording.header
        return {"format": self.kind, "streams": []}


def unknown_ids_text(unknown_ids: dict, least: int = 3, most: int = 3) -> str:
    """" (ids 52599 x50, ...)": the unknown message ids seen at least ``least`` times (a stray
    0xFD makes a one-off random id; a message of a newer firmware repeats), most frequent first."""
    top = sorted(((k, i) for i, k in unknown_ids.items() if k >= least), reverse=True)[:most]
    return f" (ids {', '.join(f'{i} x{k:,}' for k, i in top)}: a newer dialect?)" if top else ""


def is_recording(path) -> bool:
    try:
        with open(path, "rb") as f:
            return f.read(len(MAGIC)) == MAGIC
    except OSError:
        return False


def decode_stream(sd: StreamData, info: dict, msgids=None) -> DecodedStream:
    res = decode_all(sd.rx, msgids=msgids)
    out = DecodedStream(sd.stream, info, res.counters, meta=sd.meta, rx_bytes=len(sd.rx),
                        unknown_ids=res.unknown_ids)
    for mid, arr in res.arrays.items():
        out.arrays[mid] = arr
        if sd.read_end.size:
            # frame end offset: start + header + payload + CRC (+ signature)
            end = arr["_offset"] + 12 + _payload_len(sd.rx, arr["_offset"]) + np.where(arr["_signed"], 13, 0)
            out.host_ns[mid] = sd.host_time_ns(end)
        else:
            out.host_ns[mid] = None
    return out


def _payload_len(rx: bytes, offsets) -> np.ndarray:
    b = np.frombuffer(rx, np.uint8)
    return b[np.asarray(offsets) + 1].astype(np.int64)


def decode_tlog(path: Path, msgids=None) -> DecodedFile:
    """A MAVProxy/QGroundControl telemetry log: each frame preceded by its 8-byte big-endian
    UNIX time in us.  The stamps of the decoded frames are not counted in ``bytes_skipped``
    (which so counts only bytes that are neither: MAVLink 1 frames, which are not decoded, and
    damage)."""
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise KinefuseError(f"cannot read {path}: {exc.strerror or exc}") from None
    ds = decode_stream(StreamData(0, data), {"id": 0, "connection": f"tlog:{path}"}, msgids)
    # the decoder skipped each frame's 8-byte stamp as bytes outside any frame
    ds.counters.bytes_skipped = max(0, ds.counters.bytes_skipped - 8 * ds.counters.frames_ok)
    b = np.frombuffer(data, np.uint8)
    first = None
    for mid, arr in ds.arrays.items():
        off = arr["_offset"].astype(np.int64)
        idx = np.maximum(off - 8, 0)[:, None] + np.arange(8)
        stamp = (b[idx].astype(np.uint64) << (8 * np.arange(7, -1, -1)).astype(np.uint64)).sum(axis=1)
        ns = stamp.astype(np.int64) * 1000
        ds.host_ns[mid] = ns
        if ns.size:
            first = int(ns.min()) if first is None else min(first, int(ns.min()))
    return DecodedFile(path, None, {0: ds}, clock=(first or 0, first or 0), kind="MAVLink telemetry log (tlog)")


def decode_file(path, raw: bool = False, msgids=None, progress=None) -> DecodedFile:
    """Decode a .kfr recording, a .tlog, or with ``raw=True`` a plain MAVLink byte capture.

    ``progress``: ``tick(fraction)`` called as the work goes on (reading the chunks: 0-0.5,
    decoding stream by stream: 0.5-1); default: the :data:`PROGRESS` context hook."""
    tick = progress if progress is not None else PROGRESS.get()
    path = Path(path)
    if not path.exists():
        raise KinefuseError(f"{path}: no such file")
    if path.is_dir():
        raise KinefuseError(f"{path} is a directory, not a recording")
    if not path.is_file():
        # a pipe (/dev/stdin, <(...)) or a device: the file is opened more than once (its magic,
        # then its bytes), so what the first read took would be missing from the decode
        raise KinefuseError(f"{path} is not a regular file (a pipe or a device): save it to a file "
                            f"first (it is read more than once)")
    if path.suffix.lower() == ".tlog" and not is_recording(path):
        return decode_tlog(path, msgids)
    if not is_recording(path):
        if not raw:
            raise KinefuseError(f"{path} is not a kinefuse recording (.kfr); use --raw for a plain MAVLink capture")
        try:
            data = path.read_bytes()
        except OSError as exc:
            raise KinefuseError(f"cannot read {path}: {exc.strerror or exc}") from None
        sd = StreamData(0, data)
        return DecodedFile(path, None, {0: decode_stream(sd, {"id": 0, "connection": f"file:{path}"}, msgids)})
    rec = load(path, progress=None if tick is None else (lambda f: tick(0.5 * f)))
    total = sum(len(sd.rx) for sd in rec.streams.values()) or 1
    done, streams = 0, {}
    for sid, sd in sorted(rec.streams.items()):
        streams[sid] = decode_stream(sd, rec.stream_info(sid), msgids)
        done += len(sd.rx)
        if tick is not None:
            tick(0.5 + 0.5 * done / total)
    return DecodedFile(path, rec, streams)
