"""Record the raw byte streams of one or more units into a ``.kfr`` file.

Each port gets a stream id (0, 1, ...) and a reader thread that timestamps every read with the
host monotonic clock; all streams share one file, so they are time-aligned through those host
times.  Received bytes are written as they are (the raw stream is the source of truth); frames
are also decoded live for progress, for warnings (likely wrong baud rate, dialect mismatch) and
to store what the units say about themselves (KF_UNIT_STATUS, parameters) as META chunks.
"""
from __future__ import annotations

import threading
import time
from dataclasses import dataclass, field

from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.connection import DEFAULT_BAUD, open_connection
from kinefuse.host.link.dialect import DIALECT_HASH
from kinefuse.host.link.recording import RecordingWriter, make_header
from kinefuse.host.link.session import Session

MSG_RAW, MSG_ORI, MSG_STATUS = 52500, 52501, 52504
CMD_STREAM, CMD_SET_INTERVAL = 52500, 511


def firmware_version_text(v: int) -> str:
    kind = {0: "dev", 64: "alpha", 128: "beta", 192: "rc", 255: "official"}.get(v & 0xFF, str(v & 0xFF))
    return f"{v >> 24}.{(v >> 16) & 0xFF}.{(v >> 8) & 0xFF}-{kind}"


@dataclass
class StreamState:
    id: int
    url: str
    session: Session
    pending: list = field(default_factory=list)   # [(t_ns, bytes)] not yet written
    pending_bytes: int = 0
    first_pending_ns: int = 0
    units: dict = field(default_factory=dict)     # sysid -> info
    msg_counts: dict = field(default_factory=dict)
    closed: bool = False
    error: str | None = None
    warned_baud: bool = False
    warnings: list = field(default_factory=list)


class Recorder:
    def __init__(self, out, ports: list[str], baud: int = DEFAULT_BAUD, note: str | None = None,
                 timesync: bool = True, start_streaming: bool = False, rate_hz: float | None = None,
                 fetch_params: bool = False, chunk_interval: float = 0.25, fsync_interval: float = 1.0):
        if not ports:
            raise KinefuseError("no port given (--port)")
        self.streams: list[StreamState] = []
        self.timesync = timesync
        self.start_streaming = start_streaming
        self.rate_hz = rate_hz
        self.fetch_params = fetch_params
        self.chunk_interval_ns = int(chunk_interval * 1e9)
        self.warnings: list[str] = []
        self._stop = threading.Event()
        conns = []
        try:
            for url in ports:
                conns.append(open_connection(url, baud))
        except Exception:
            for c in conns:
                c.close()
            raise
        infos = []
        for sid, conn in enumerate(conns):
            info = {"id": sid, **conn.describe()}
            if rate_hz:
                info["requested_rates_hz"] = {"KF_RAW_SAMPLE": rate_hz}
            infos.append(info)
            latency = info.get("latency_timer_ms")
            if latency is not None and latency > 2:
                self.warnings.append(f"{conn.url}: FTDI latency timer is {latency} ms (1 ms gives smoother timing: "
                                     f"echo 1 > /sys/bus/usb-serial/devices/<tty>/latency_timer)")
        self.header = make_header(infos, note=note)
        try:
            self.writer = RecordingWriter(out, self.header, fsync_interval=fsync_interval)
        except Exception:
            for c in conns:
                c.close()
            raise
        for sid, conn in enumerate(conns):
            st = StreamState(sid, conn.url, None)  # session created below (its tap needs ``st``)
            st.session = Session(conn, tap=self._tap(st))
            self.streams.append(st)
        self.started_ns = time.monotonic_ns()

    # ------------------------------------------------------------------------------ bytes
    def _tap(self, st: StreamState):
        def tap(kind, t_ns, data):
            if kind == "rx":
                if not st.pending:
                    st.first_pending_ns = t_ns
                st.pending.append((t_ns, data))
                st.pending_bytes += len(data)
            else:
                self.writer.tx(st.id, data, t_ns)
        return tap

    def _flush_stream(self, st: StreamState, force: bool = False) -> None:
        if st.pending and (force or st.pending_bytes >= 1 << 16
                           or time.monotonic_ns() - st.first_pending_ns >= self.chunk_interval_ns):
            self.writer.rx(st.id, st.pending)
            st.pending, st.pending_bytes = [], 0

    # ------------------------------------------------------------------------------ live view
    def _look(self, st: StreamState) -> None:
        for t_ns, f in st.session.drain():
            name = f.msg._msgname
            st.msg_counts[name] = st.msg_counts.get(name, 0) + 1
            unit = st.units.setdefault(f.sysid, {"sysid": f.sysid, "first_t_ns": t_ns})
            if f.msgid == MSG_STATUS:
                m = f.msg
                fw = firmware_version_text(m.firmware_version)
                if unit.get("firmware_version") != fw or unit.get("dialect_hash") != m.dialect_hash:
                    unit.update(firmware_version=fw, firmware_git_hash=f"{m.firmware_git_hash:08x}",
                                dialect_hash=m.dialect_hash, unit_id=m.unit_id)
                    meta = {"type": "unit_status", "sysid": f.sysid, "compid": f.compid,
                            "status": m._asdict(), "firmware_version_text": fw}
                    self.writer.meta(st.id, meta, t_ns)
                    if m.dialect_hash != DIALECT_HASH():
                        self._warn(st, f"unit {f.sysid} on {st.url} was built with dialect hash "
                                       f"0x{m.dialect_hash:08X}, host has 0x{DIALECT_HASH():08X}: update one of them")
        c = st.session.decoder.counters
        if not st.warned_baud and c.bytes_in >= 4096 and c.frames_ok == 0:
            st.warned_baud = True
            self._warn(st, f"{st.url}: {c.bytes_in} bytes but no valid MAVLink 2 frame: wrong baud rate "
                           f"(--baud) or not a kinefuse unit?")

    def _warn(self, st: StreamState, text: str) -> None:
        st.warnings.append(text)
        self.warnings.append(text)
        self.writer.meta(st.id, {"type": "warning", "text": text})

    # ------------------------------------------------------------------------------ control
    def _command(self, st: StreamState, command: int, *params: float) -> None:
        p = list(params) + [0.0] * (7 - len(params))
        st.session.send("COMMAND_LONG", target_system=0, target_component=0, command=command, confirmation=0,
                        param1=p[0], param2=p[1], param3=p[2], param4=p[3], param5=p[4], param6=p[5], param7=p[6])

    def _setup(self) -> None:
        for st in self.streams:
            try:
                if self.rate_hz:
                    self._command(st, CMD_SET_INTERVAL, float(MSG_RAW), 1e6 / self.rate_hz)
                if self.start_streaming:
                    self._command(st, CMD_STREAM, 1.0)
            except OSError as exc:
                self._warn(st, f"{st.url}: cannot send commands: {exc}")
        if self.fetch_params:
            from kinefuse.host.link.params import ParamClient, ParamError
            for st in self.streams:
                hb = st.session.wait_for(lambda f: f.msgid == 0, timeout=2.5)
                if hb is None:
                    self._warn(st, f"{st.url}: no HEARTBEAT within 2.5 s: parameters not read")
                    continue
                st.session.frames.appendleft((time.monotonic_ns(), hb))
                try:
                    params = ParamClient(st.session, hb.sysid).fetch_all()
                    self.writer.meta(st.id, {"type": "params", "sysid": hb.sysid, "params": params})
                    st.units.setdefault(hb.sysid, {"sysid": hb.sysid})["params"] = len(params)
                except ParamError as exc:
                    self._warn(st, f"{st.url}: parameters not read: {exc}")

    def stop(self) -> None:
        self._stop.set()

    def run(self, duration: float | None = None, on_tick=None, tick: float = 0.25) -> dict:
        """Record until ``duration`` s, ``stop()``, or every connection closed; returns a summary."""
        t_end = None if duration is None else time.monotonic() + duration
        next_sync = next_tick = time.monotonic()
        try:
            self._setup()
            while not self._stop.is_set():
                now = time.monotonic()
                if t_end is not None and now >= t_end:
                    break
                open_streams = [st for st in self.streams if not st.closed]
                if not open_streams:
                    break
                wait = 0.05 / len(open_streams)
                for st in open_streams:
                    st.session.poll(wait)
                    self._look(st)
                    self._flush_stream(st)
                    if st.session.reader.finished:
                        st.session.poll(0)
                        self._look(st)
                        self._flush_stream(st, force=True)
                        st.closed = True
                        st.error = st.session.reader.error
                        self.writer.meta(st.id, {"type": "event", "event": "disconnected", "error": st.error})
                if self.timesync and now >= next_sync:
                    next_sync = now + 1.0
                    for st in open_streams:
                        try:
                            st.session.send("TIMESYNC", tc1=0, ts1=time.monotonic_ns())
                        except OSError:
                            pass
                if on_tick is not None and now >= next_tick:
                    next_tick = now + tick
                    on_tick(self.summary())
        finally:
            self.close()
        return self.summary()

    def close(self) -> None:
        if getattr(self, "_closed", False):
            return
        self._closed = True
        for st in self.streams:
            if self.start_streaming and not st.closed:
                try:
                    self._command(st, CMD_STREAM, 0.0)
                except OSError:
                    pass
            try:
                st.session.poll(0)
                self._look(st)
            except Exception:  # noqa: BLE001 - closing must go on
                pass
            self._flush_stream(st, force=True)
            st.session.close()
        self.writer.close()

    def summary(self) -> dict:
        elapsed = (time.monotonic_ns() - self.started_ns) / 1e9
        streams = []
        for st in self.streams:
            c = st.session.decoder.counters
            streams.append({
                "id": st.id, "connection": st.url, "bytes": c.bytes_in, "frames": c.frames_ok,
                "crc_errors": c.crc_errors, "bytes_skipped": c.bytes_skipped, "messages": dict(st.msg_counts),
                "units": [dict(u) for u in st.units.values()], "closed": st.closed, "error": st.error,
            })
        return {"file": str(self.writer.path), "elapsed_s": round(elapsed, 3), "file_bytes": self.writer.bytes_written,
                "streams": streams, "warnings": list(self.warnings), "finished": getattr(self, "_closed", False)}
