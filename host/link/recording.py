"""The ``.kfr`` recording: the raw byte stream of one or more units, self-described.

Layout (all little-endian)::

    file   = magic "\\x89KFR\\r\\n\\x1a\\n" | u16 version | u32 n | header JSON (n bytes) | u32 crc32(JSON)
             | chunk*
    chunk  = "kc" | u8 type | u8 stream | u32 length | i8 t_ns | u32 crc32(payload) | payload

- ``t_ns``: host monotonic clock (``time.monotonic_ns``) when the chunk's first read returned;
  the header holds ``start_unix_ns`` and ``start_monotonic_ns`` taken together, so
  UTC = start_unix_ns + (t - start_monotonic_ns).
- RX payload = u32 nreads | nreads x (u32 end offset, u32 dt_us after t_ns) | bytes received.
  Every read of the port keeps its own host time (reads closer than 1 ms are merged).
- TX payload = bytes the host sent; META payload = JSON (unit status, parameters, requested
  rates, events such as a disconnect).
- The recorder flushes every chunk to the OS (a killed process loses at most the chunk being
  gathered, <= 0.25 s plus one loop turn) and fsyncs every 0.5 s (a power cut loses what came
  after the last fsync and what was still being gathered: < 1 s); both checked by the state
  machine in host/tests/test_recorder_kill.py.
- A truncated file decodes up to the truncation: a partial last chunk still yields the bytes
  it holds (MAVLink CRCs protect the frames).  A damaged chunk whose header still checks out
  (marker, type, a stream of the header, and the next chunk or the end of the file right
  where its length says) is an RX chunk with damaged payload bytes: its bytes are kept and the
  MAVLink CRCs drop only the frames touched by the damage (a flipped bit costs one frame, not
  the chunk's 50); a read table that no longer makes sense is replaced by one read at the
  chunk's time, a chunk time out of line with its neighbours by the previous chunk's.  Any
  other damage is skipped by searching the next chunk marker whose CRC matches.
"""
from __future__ import annotations

import json
import os
import stat
import platform
import struct
import threading
import time
import zlib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from kinefuse.host.errors import KinefuseError

MAGIC = b"\x89KFR\r\n\x1a\n"
VERSION = 1
FILE_HEAD = struct.Struct("<8sHI")
CHUNK = struct.Struct("<2sBBIqI")  # marker, type, stream, length, t_ns, crc32
MARKER = b"kc"
RX, TX, META = 1, 2, 3
CHUNK_TYPES = {RX: "rx", TX: "tx", META: "meta"}
MAX_CHUNK = 1 << 24  # sanity bound for a chunk length read from a damaged file
READ_ENTRY = struct.Struct("<II")


def _crc32(b) -> int:
    return zlib.crc32(b) & 0xFFFFFFFF


def _software_versions() -> dict:
    out = {}
    try:
        from importlib.metadata import version
        for pkg in ("kinefuse", "pymavlink", "pyserial", "numpy"):
            try:
                out[pkg] = version(pkg)
            except Exception:
                pass
    except Exception:  # pragma: no cover
        pass
    return out


def make_header(streams: list[dict], note: str | None = None, extra: dict | None = None) -> dict:
    """Header dict: clocks taken together, host and software, dialect hash, streams."""
    from kinefuse.host.link.dialect import DIALECT_HASH
    mono, unix = time.monotonic_ns(), time.time_ns()
    head = {
        "format": "kinefuse-recording",
        "version": VERSION,
        "start_unix_ns": unix,
        # whole seconds by integer division: unix / 1e9 rounded up within 0.12 us of a second,
        # and the stamp read a second late (":04.999999Z" for 03.99999995 s)
        "start_utc": time.strftime("%Y-%m-%dT%H:%M:%S", time.gmtime(unix // 10**9)) + f".{unix % 10**9 // 1000:06d}Z",
        "start_monotonic_ns": mono,
        "host": {"hostname": platform.node(), "platform": platform.platform(), "python": platform.python_version()},
        "software": _software_versions(),
        "dialect": {"name": "kinefuse", "hash": f"0x{DIALECT_HASH():08X}"},
        "streams": streams,
        "note": note,
    }
    if extra:
        head.update(extra)
    return head


class RecordingWriter:
    """Append-only writer; thread-safe.  ``fsync_interval`` bounds the loss on a power cut."""

    def __init__(self, path, header: dict, fsync_interval: float = 1.0):
        self.path = Path(path)
        try:
            self._f = open(self.path, "wb")
        except OSError as exc:
            raise KinefuseError(f"cannot create {self.path}: {exc.strerror or exc}") from None
        self._lock = threading.Lock()
        self._fsync_interval = fsync_interval
        self._last_sync = time.monotonic()
        self.bytes_written = 0
        self._synced_bytes = 0
        self.failed: KinefuseError | None = None   # the first write error (disk full...): raised again by close()
        body = json.dumps(header, sort_keys=True).encode()
        self._write(FILE_HEAD.pack(MAGIC, VERSION, len(body)) + body + struct.pack("<I", _crc32(body)))
        self.sync()

    def _write(self, b: bytes) -> None:
        self._f.write(b)
        self.bytes_written += len(b)

    def _failed(self, exc: OSError) -> KinefuseError:
        if self.failed is None:
            try:
                st = os.fstat(self._f.fileno())
                held = st.st_size if stat.S_ISREG(st.st_mode) else 0
            except (OSError, ValueError):
                held = 0
            what = (f"the file holds the recording up to there, {held:,} bytes" if held
                    else "nothing of the recording was written")    # e.g. a full disk at the start
            self.failed = KinefuseError(f"cannot write {self.path}: {exc.strerror or exc} ({what})")
        return self.failed

    def chunk(self, ctype: int, stream: int, payload: bytes, t_ns: int | None = None) -> None:
        t = time.monotonic_ns() if t_ns is None else t_ns
        with self._lock:
            if self.failed is not None:
                raise self.failed
            try:
                self._write(CHUNK.pack(MARKER, ctype, stream, len(payload), t, _crc32(payload)) + payload)
                self._f.flush()  # to the OS: survives a killed process
            except OSError as exc:
                raise self._failed(exc) from None
            self._sync_if_due_locked()

    def rx(self, stream: int, reads: list[tuple[int, bytes]]) -> None:
        """One RX chunk from consecutive reads [(t_ns, data), ...] of one stream."""
        if not reads:
            return
        t0 = reads[0][0]
        entries, data, end = [], [], 0
        group = None   # dt of the first read of the entry being merged into
        for t, b in reads:
            end += len(b)
            dt = max(0, (t - t0) // 1000)
            # merge reads < 1 ms after the first read of the entry (later time); measured from
            # the entry's latest read, reads every 0.9 ms chained into one entry: a whole
            # chunk's frames got its last read's time (up to 0.25 s late)
            if entries and dt - group < 1000:
                entries[-1] = (end, dt)
            else:
                entries.append((end, dt))
                group = dt
            data.append(b)
        head = struct.pack("<I", len(entries)) + b"".join(READ_ENTRY.pack(e, min(d, 0xFFFFFFFF)) for e, d in entries)
        self.chunk(RX, stream, head + b"".join(data), t0)

    def tx(self, stream: int, data: bytes, t_ns: int | None = None) -> None:
        self.chunk(TX, stream, bytes(data), t_ns)

    def meta(self, stream: int, obj: dict, t_ns: int | None = None) -> None:
        self.chunk(META, stream, json.dumps(obj, sort_keys=True, default=str).encode(), t_ns)

    def _sync_locked(self) -> None:
        try:
            self._f.flush()
            os.fsync(self._f.fileno())
        except OSError as exc:
            raise self._failed(exc) from None
        self._last_sync = time.monotonic()
        self._synced_bytes = self.bytes_written

    def sync(self) -> None:
        with self._lock:
            self._sync_locked()

    def _sync_if_due_locked(self) -> None:
        if (self.failed is None and self.bytes_written != self._synced_bytes
                and time.monotonic() - self._last_sync >= self._fsync_interval):
            self._sync_locked()

    def sync_due(self) -> None:
        """fsync if bytes were written since the last fsync and the interval has passed.  Called
        every loop turn: chunk() alone synced only when a later chunk came, so the last data
        before a stream went quiet stayed unsynced for as long as it stayed quiet."""
        with self._lock:
            self._sync_if_due_locked()

    def close(self) -> None:
        with self._lock:
            if not self._f.closed:
                try:
                    if self.failed is None:
                        self._sync_locked()
                finally:
                    try:
                        self._f.close()
                    except OSError:   # its buffer could not be written: self.failed says so
                        pass
            if self.failed is not None:
                raise self.failed

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


@dataclass
class Chunk:
    type: int
    stream: int
    t_ns: int
    payload: bytes
    offset: int            # file offset of the chunk header
    truncated: bool = False
    damaged: bool = False  # payload CRC failed (header plausible): bytes kept, frames checked by MAVLink


@dataclass
class StreamData:
    """Everything received on one stream, concatenated, with the host time of every read."""
    stream: int
    rx: bytes = b""
    read_end: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int64))   # end offset in rx
    read_t_ns: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int64))  # host monotonic ns
    tx: bytes = b""
    meta: list = field(default_factory=list)

    def host_time_ns(self, end_offsets) -> np.ndarray:
        """Host monotonic time of the read that delivered the byte before each end offset."""
        if self.read_end.size == 0:
            return np.zeros(len(end_offsets), np.int64)
        k = np.searchsorted(self.read_end, np.asarray(end_offsets, np.int64), side="left")
        return self.read_t_ns[np.minimum(k, self.read_end.size - 1)]


@dataclass
class Recording:
    path: Path
    header: dict
    streams: dict            # stream id -> StreamData
    chunks: int = 0
    damaged_chunks: int = 0  # damaged stretches (CRC or header failed), recovered ones included
    truncated: bool = False  # the file ends inside a chunk
    trailing_bytes: int = 0  # bytes after the last complete chunk
    recovered_chunks: int = 0  # damaged RX chunks whose bytes were kept (frames checked by their CRCs)
    skipped_bytes: int = 0   # file bytes of damaged stretches that were skipped
    header_damaged: bool = False  # its CRC failed but its JSON reads: used; counted in damaged_chunks

    @property
    def start_monotonic_ns(self) -> int:
        return int(self.header.get("start_monotonic_ns", 0))

    @property
    def start_unix_ns(self) -> int:
        return int(self.header.get("start_unix_ns", 0))

    def stream_info(self, stream: int) -> dict:
        for s in self.header.get("streams", []):
            if s.get("id") == stream:
                return s
        return {}


class HeaderCrcError(KinefuseError):
    """The header's CRC fails; ``header``: its JSON if that still reads (else None), ``start``:
    the offset of the first chunk."""

    def __init__(self, text: str, header: dict | None, start: int):
        super().__init__(text)
        self.header, self.start = header, start


def read_header(f, path) -> tuple[dict, int]:
    head = f.read(FILE_HEAD.size)
    if head[:8] == MAGIC and len(head) < FILE_HEAD.size:   # cut within the first 14 bytes
        raise KinefuseError(f"{path}: recording header is truncated")
    if len(head) < FILE_HEAD.size or head[:8] != MAGIC:
        raise KinefuseError(f"{path} is not a kinefuse recording (.kfr)")
    _, version, n = FILE_HEAD.unpack(head)
    if version > VERSION:
        raise KinefuseError(f"{path}: recording format version {version} is newer than this kinefuse ({VERSION})")
    body = f.read(n)
    crc = f.read(4)
    if len(body) < n or len(crc) < 4:
        raise KinefuseError(f"{path}: recording header is truncated")
    if struct.unpack("<I", crc)[0] != _crc32(body):
        try:
            header = json.loads(body)
        except ValueError:
            header = None
        raise HeaderCrcError(f"{path}: recording header is damaged (CRC mismatch)",
                             header if isinstance(header, dict) else None, FILE_HEAD.size + n + 4)
    try:
        header = json.loads(body)
    except ValueError:
        raise KinefuseError(f"{path}: recording header is not valid JSON") from None
    return header, FILE_HEAD.size + n + 4


def iter_chunks(data: bytes, start: int, stats: dict | None = None, streams=None):
    """Chunks of a recording body; resynchronises after damage; yields a partial last chunk.

    ``streams``: the stream ids of the header; with it, an RX chunk whose payload CRC fails but
    whose header checks out is yielded with ``damaged=True`` (see the module docstring)."""
    stats = stats if stats is not None else {}
    stats.setdefault("damaged", 0)
    stats.setdefault("recovered", 0)
    stats.setdefault("skipped_bytes", 0)
    stats.setdefault("truncated", False)
    stats.setdefault("trailing", 0)
    i, n = start, len(data)
    prev_t = None
    while i < n:
        if n - i < CHUNK.size:  # the file stops inside a chunk header
            stats["truncated"] = True
            stats["trailing"] = n - i
            return
        state = _chunk_state(data, i)
        if state == "damaged" and streams is not None:
            ch = _damaged_rx(data, i, streams, prev_t)
            if ch is not None:
                stats["damaged"] += 1
                stats["recovered"] += 1
                prev_t = ch.t_ns
                yield ch
                i = i + CHUNK.size + len(ch.payload)
                continue
        if state == "damaged":
            # One damaged stretch counts once: resume at the next header whose CRC holds (a
            # "kc" inside a payload or a CRC field is not taken for a chunk).
            stats["damaged"] += 1
            j = _next_good_chunk(data, i + 1, streams)
            if j < 0:
                stats["trailing"] = n - i
                stats["skipped_bytes"] += n - i
                return
            stats["skipped_bytes"] += j - i
            i = j
            continue
        marker, ctype, stream, length, t_ns, crc = CHUNK.unpack_from(data, i)
        body_start = i + CHUNK.size
        if state == "truncated":  # the file stops inside this chunk (killed recorder, copied while recording)
            stats["truncated"] = True
            stats["trailing"] = n - i
            yield Chunk(ctype, stream, t_ns, data[body_start:n], i, truncated=True)
            return
        prev_t = t_ns
        yield Chunk(ctype, stream, t_ns, data[body_start:body_start + length], i)
        i = body_start + length


def _plausible_header(data: bytes, i: int, streams) -> bool:
    """A chunk header at i that makes sense (marker, type, a stream of the header, a length that
    ends inside the file), whatever its payload CRC says."""
    if len(data) - i < CHUNK.size:
        return False
    marker, ctype, stream, length, _t, _crc = CHUNK.unpack_from(data, i)
    return (marker == MARKER and ctype in CHUNK_TYPES and stream in streams and length <= MAX_CHUNK
            and i + CHUNK.size + length <= len(data))


def _damaged_rx(data: bytes, i: int, streams, prev_t) -> Chunk | None:
    """An RX chunk at i whose payload CRC failed but whose header is intact (marker, type, a
    known stream, and the next chunk -- or the end of the file -- exactly after its length)."""
    marker, ctype, stream, length, t_ns, _crc = CHUNK.unpack_from(data, i)
    if marker != MARKER or ctype != RX or stream not in streams or length > MAX_CHUNK:
        return None
    end = i + CHUNK.size + length
    if end > len(data) or (end < len(data) and _chunk_state(data, end) != "ok"
                           and not _plausible_header(data, end, streams)):
        return None
    return Chunk(ctype, stream, t_ns, data[i + CHUNK.size:end], i, damaged=True)


def _chunk_state(data: bytes, i: int) -> str:
    """'ok', 'truncated' (plausible header, file ends inside the payload) or 'damaged'."""
    if len(data) - i < CHUNK.size:
        return "damaged"
    marker, ctype, _stream, length, _t, crc = CHUNK.unpack_from(data, i)
    if marker != MARKER or ctype not in CHUNK_TYPES or length > MAX_CHUNK:
        return "damaged"
    end = i + CHUNK.size + length
    if end > len(data):
        return "truncated"
    return "ok" if _crc32(data[i + CHUNK.size:end]) == crc else "damaged"


def _next_good_chunk(data: bytes, i: int, streams=None) -> int:
    """Offset of the next chunk header at or after i that checks out, or -1.

    With ``streams``, an RX chunk with a damaged payload but an intact header (followed by a
    good chunk) counts too.  A header that runs past the end of the file is taken only if no
    whole chunk follows it (a stray "kc" with a plausible length must not swallow the rest)."""
    partial = -1
    while True:
        j = data.find(MARKER, i)
        if j < 0:
            return partial
        state = _chunk_state(data, j)
        if state == "ok" or (state == "damaged" and streams is not None
                             and _damaged_rx(data, j, streams, None) is not None):
            return j
        if state == "truncated" and partial < 0:
            partial = j
        i = j + 1


def _rx_parts(chunk: Chunk):
    """(data, [(end, t_ns)]) of an RX chunk; tolerant of a truncated or damaged payload."""
    p = chunk.payload
    if len(p) < 4:
        return b"", []
    nreads = struct.unpack_from("<I", p)[0]
    table_end = 4 + 8 * nreads
    if chunk.damaged:
        entries = ([READ_ENTRY.unpack_from(p, 4 + 8 * k) for k in range(nreads)]
                   if table_end <= len(p) else None)
        ends = [e for e, _ in entries] if entries else []
        dts = [d for _, d in entries] if entries else []
        if not (entries and ends[-1] == len(p) - table_end and all(a < b for a, b in zip(ends, ends[1:]))
                and all(a <= b for a, b in zip(dts, dts[1:])) and dts[-1] <= 60_000_000):
            # the read table is what got damaged: all bytes after the count, one read time
            # (the MAVLink decoder skips the table's bytes as garbage)
            return p[4:], [(len(p) - 4, chunk.t_ns)]
    if table_end > len(p):  # truncated inside the read table: no data bytes survive
        return b"", []
    entries = [READ_ENTRY.unpack_from(p, 4 + 8 * k) for k in range(nreads)]
    data = p[table_end:]
    reads = []
    for end, dt in entries:
        if end > len(data):
            reads.append((len(data), chunk.t_ns + dt * 1000))
            break
        reads.append((end, chunk.t_ns + dt * 1000))
    if reads and reads[-1][0] < len(data):
        reads.append((len(data), reads[-1][1]))
    return data, reads


def _repair_chunk_times(ts: np.ndarray, chunks) -> int:
    """Read times of one stream in place: RX chunks of a stream are written in time order, so
    a chunk whose time field is out of line with its neighbours (the header's t_ns is not under
    the payload CRC) is shifted onto its predecessor's last read.  Returns how many."""
    fixed = 0
    for j in range(1, len(chunks)):
        a, n = chunks[j]
        if not n:
            continue
        pa, pn = chunks[j - 1]
        if not pn or ts[a] >= ts[pa + pn - 1]:
            continue
        # out of order with the previous chunk: this one is too early, or the previous too late
        if j >= 2 and chunks[j - 2][1] and ts[pa] > ts[a] >= ts[chunks[j - 2][0] + chunks[j - 2][1] - 1]:
            qa, qn = chunks[j - 2]
            ts[pa:pa + pn] += ts[qa + qn - 1] - ts[pa]
        else:
            ts[a:a + n] += ts[pa + pn - 1] - ts[a]
        fixed += 1
    return fixed


def load(path, progress=None) -> Recording:
    """Read a whole recording into memory (raw bytes per stream + read times + metadata).

    ``progress``: ``tick(fraction of the file read)``, called about every MB."""
    path = Path(path)
    try:
        raw = path.read_bytes()
    except FileNotFoundError:
        raise KinefuseError(f"{path}: no such file") from None
    except IsADirectoryError:
        raise KinefuseError(f"{path} is a directory, not a recording") from None
    except OSError as exc:
        raise KinefuseError(f"cannot read {path}: {exc.strerror or exc}") from None
    import io
    header_damaged = False
    try:
        header, start = read_header(io.BytesIO(raw), path)
    except HeaderCrcError as exc:   # a flipped bit in the header need not cost the recording
        if exc.header is None:
            raise
        header, start, header_damaged = exc.header, exc.start, True
    streams: dict[int, dict] = {}
    stats: dict = {}
    n_chunks = 0
    ids = {s.get("id") for s in header.get("streams", []) if isinstance(s, dict)}
    next_tick = 0
    for ch in iter_chunks(raw, start, stats, streams=ids):
        n_chunks += 1
        if progress is not None and ch.offset >= next_tick:
            progress(ch.offset / len(raw))
            next_tick = ch.offset + (1 << 20)
        s = streams.setdefault(ch.stream, {"rx": [], "ends": [], "ts": [], "tx": [], "meta": [], "n": 0})
        if ch.type == RX:
            data, reads = _rx_parts(ch)
            base = s["n"]
            s.setdefault("chunks", []).append((len(s["ts"]), len(reads)))
            for end, t in reads:
                s["ends"].append(base + end)
                s["ts"].append(t)
            s["rx"].append(data)
            s["n"] += len(data)
        elif ch.type == TX and not ch.damaged:
            s["tx"].append(ch.payload)
        elif ch.type == META and not ch.truncated:
            try:
                obj = json.loads(ch.payload)
            except ValueError:
                continue
            obj.setdefault("t_ns", ch.t_ns)
            s["meta"].append(obj)
    out = {}
    for sid, s in streams.items():
        ts = np.array(s["ts"], np.int64)
        bad_times = _repair_chunk_times(ts, s.get("chunks", []))
        stats["damaged"] += bad_times
        stats["recovered"] += bad_times
        out[sid] = StreamData(sid, b"".join(s["rx"]), np.array(s["ends"], np.int64), ts,
                              b"".join(s["tx"]), s["meta"])
    for info in header.get("streams", []):
        sid = info.get("id")
        if isinstance(sid, int) and sid not in out:
            out[sid] = StreamData(sid)
    if progress is not None:
        progress(1.0)
    return Recording(path, header, out, n_chunks, stats.get("damaged", 0) + header_damaged,
                     stats.get("truncated", False), stats.get("trailing", 0),
                     stats.get("recovered", 0), stats.get("skipped_bytes", 0), header_damaged)
