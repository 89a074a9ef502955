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
from kinefuse.host.link.command import CommandError, command_name, refusal_text
from kinefuse.host.link.connection import DEFAULT_BAUD, open_connection
from kinefuse.host.link.dialect import DIALECT_HASH
from kinefuse.host.link.recording import RecordingWriter, make_header
from kinefuse.host.link.session import Session

MSG_RAW, MSG_ORI, MSG_STATUS, MSG_STATUSTEXT = 52500, 52501, 52504, 253
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
    closed: bool = False
    error: str | None = None
    warned_baud: bool = False
    warned_garbage: bool = False
    warnings: list = field(default_factory=list)
    acks: list = field(default_factory=list)      # (sysid, command, result) of COMMAND_ACKs seen
    recent: bytearray = field(default_factory=bytearray)   # the last RECENT_BYTES..2x received
    crc_checked_at: int = 0                       # CRC errors when last checked for a dialect mismatch
    warned_dialect: set = field(default_factory=set)       # messages named as CRC_EXTRA mismatches


RECENT_BYTES = 1 << 16   # kept to tell CRC_EXTRA mismatches (another dialect) from a damaged link
DIALECT_CHECK_CRC = 16    # CRC errors (then each doubling) that trigger that check


class Recorder:
    CHUNK_INTERVAL_S = 0.25
    FSYNC_INTERVAL_S = 0.5   # + a 0.25 s chunk + a loop turn: a power cut loses < 1 s

    def __init__(self, out, ports: list[str], baud: int = DEFAULT_BAUD, note: str | None = None,
                 timesync: bool = True, start_streaming: bool = False, rate_hz: float | None = None,
                 fetch_params: bool = False, chunk_interval: float = CHUNK_INTERVAL_S,
                 fsync_interval: float = FSYNC_INTERVAL_S,
                 key: bytes | None = None, ack_timeout: float = 1.0):
        """``key``: MAVLink 2 signing key for the commands sent (a unit with a key set refuses
        unsigned ones); ``fetch_params``: ask every unit for its parameter list first (stored as
        a META chunk; a unit that does not answer gives a warning, not a failure).  A command
        (--rate, --start) refused by a unit ends the recording with a CommandError."""
        if not ports:
            raise KinefuseError("no port given (--port)")
        self.streams: list[StreamState] = []
        self.timesync = timesync
        self.start_streaming = start_streaming
        self.rate_hz = rate_hz
        self.fetch_params = fetch_params
        self.key = key
        self.ack_timeout = ack_timeout
        self.chunk_interval_ns = int(chunk_interval * 1e9)
        self.warnings: list[str] = []
        self.unit_texts: list[str] = []   # the units' STATUSTEXTs, as lines (also in the file's bytes)
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
        extra = {"params_requested": bool(fetch_params), "commands_signed": key is not None}
        self.header = make_header(infos, note=note, extra=extra)
        try:
            self.writer = RecordingWriter(out, self.header, fsync_interval=fsync_interval)
        except Exception:
            for c in conns:
                c.close()
            raise
        for sid, conn in enumerate(conns):
            st = StreamState(sid, conn.url, None)  # session created below (its tap needs ``st``)
            st.session = Session(conn, tap=self._tap(st), key=key)
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
                st.recent += data
                if len(st.recent) > 2 * RECENT_BYTES:
                    del st.recent[:-RECENT_BYTES]
            else:
                self.writer.tx(st.id, data, t_ns)
        return tap

    def _flush_stream(self, st: StreamState, force: bool = False) -> None:
        if st.pending and (force or st.pending_bytes >= 1 << 16
                           or time.monotonic_ns() - st.first_pending_ns >= self.chunk_interval_ns):
            self.writer.rx(st.id, st.pending)
            st.pending, st.pending_bytes = [], 0
        self.writer.sync_due()

    # ------------------------------------------------------------------------------ live view
    def _look(self, st: StreamState, final: bool = False) -> None:
        for t_ns, f in st.session.drain():
            unit = st.units.setdefault(f.sysid, {"sysid": f.sysid, "first_t_ns": t_ns})
            if f.msgid == 77:
                st.acks.append((f.sysid, int(f.msg.command), int(f.msg.result)))
            if f.msgid == MSG_STATUSTEXT:   # e.g. "parameter storage error": the user must see it
                from kinefuse.host.link.stats import statustext_text
                self.unit_texts.append(f"unit {f.sysid} on {st.url}: {statustext_text(f.msg.severity, f.msg.text)}")
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
        if c.crc_errors >= max(DIALECT_CHECK_CRC, 2 * st.crc_checked_at):
            # frames that check with another CRC_EXTRA: a unit of another dialect version, not
            # a damaged link (the warnings below said "wrong baud rate?" for those too)
            st.crc_checked_at = c.crc_errors
            self._dialect_mismatch(st)
        if not st.warned_baud and (c.bytes_in >= 4096 or (final and c.bytes_in)) and c.frames_ok == 0:
            st.warned_baud = True
            if not self._dialect_mismatch(st):
                self._warn(st, f"{st.url}: {c.bytes_in} bytes but no valid MAVLink 2 frame: wrong baud rate "
                               f"(--baud) or not a kinefuse unit?")
        if not st.warned_garbage and c.bytes_in >= 65536 and c.frames_ok \
                and c.bytes_skipped > 0.5 * c.bytes_in:
            st.warned_garbage = True
            if not self._dialect_mismatch(st):
                self._warn(st, f"{st.url}: {c.bytes_skipped} of {c.bytes_in} bytes are not MAVLink 2 frames "
                               f"({c.crc_errors} CRC errors): a damaged link or a wrong baud rate?")

    def _dialect_mismatch(self, st: StreamState) -> bool:
        """Warn (once per message) of CRC_EXTRA mismatches in the recent bytes; True if any."""
        from kinefuse.host.link.stats import crc_extra_mismatches, crc_extra_text
        mm = crc_extra_mismatches(bytes(st.recent[-RECENT_BYTES:]))
        for m in mm:
            if m["message"] not in st.warned_dialect:
                st.warned_dialect.add(m["message"])
                self._warn(st, f"{st.url}: {crc_extra_text(m)}")
        return bool(mm) or bool(st.warned_dialect)

    def _warn(self, st: StreamState, text: str) -> None:
        st.warnings.append(text)
        self.warnings.append(text)
        self.writer.meta(st.id, {"type": "warning", "text": text})

    # ------------------------------------------------------------------------------ control
    def _command(self, st: StreamState, command: int, *params: float, confirmation: int = 0) -> None:
        p = list(params) + [0.0] * (7 - len(params))
        st.session.send("COMMAND_LONG", target_system=0, target_component=0, command=command,
                        confirmation=confirmation, param1=p[0], param2=p[1], param3=p[2], param4=p[3],
                        param5=p[4], param6=p[5], param7=p[6])

    def _keep_recording(self, st: StreamState) -> None:
        st.session.poll(0.02)
        self._look(st)
        self._flush_stream(st)

    def _checked_command(self, st: StreamState, command: int, *params: float, retries: int = 2) -> None:
        """Send to every unit of the stream; a refusal raises CommandError (after noting it in
        the file), no answer at all is a warning (a one-way link, or no unit)."""
        st.session.reader.first_read.wait(1.0)   # what waited at the open is read
        st.session.poll(0)
        self._look(st)      # the ACKs received so far answer no command sent now
        n0 = len(st.acks)
        for attempt in range(retries):
            self._command(st, command, *params, confirmation=attempt)
            deadline = time.monotonic() + self.ack_timeout
            while time.monotonic() < deadline:
                self._keep_recording(st)
                if any(c == command for _, c, _ in st.acks[n0:]):
                    deadline = min(deadline, time.monotonic() + 0.2)   # gather the other units' ACKs
            got = [(u, r) for u, c, r in st.acks[n0:] if c == command]
            if got:
                refused = [(u, r) for u, r in got if r != 0]
                if refused:
                    u, r = refused[0]
                    text = f"{st.url}: {refusal_text(u, command, r, self.key is not None)}"
                    self.writer.meta(st.id, {"type": "error", "text": text})
                    raise CommandError(text, r)
                return
        text = (f"{st.url}: no COMMAND_ACK for {command_name(command)} within {retries} x {self.ack_timeout:g} s")
        if self.key is not None:   # signed: a unit with another key drops it, silently
            text += " (a unit drops frames signed with a key other than its own: is it the right key?)"
            self.writer.meta(st.id, {"type": "error", "text": text})
            raise CommandError(text)
        self._warn(st, text + " (no unit answering on this connection?)")

    def _setup(self) -> None:
        if self.fetch_params:
            from kinefuse.host.link.params import ParamClient, ParamError
            for st in self.streams:
                # a TIMESYNC request first: its answer names the unit sooner than the 1 Hz
                # HEARTBEAT, and a unit that starts on the first byte it receives starts
                try:
                    st.session.send("TIMESYNC", tc1=0, ts1=time.monotonic_ns())
                except OSError:
                    pass
                hb = st.session.wait_for(lambda f: f.sysid != 255 and (f.msgid == 0 or (
                    f.msgid == 111 and f.msg.tc1 != 0)), timeout=2.5)
                if hb is None:
                    self._warn(st, f"{st.url}: no HEARTBEAT within 2.5 s: parameters not read")
                    continue
                st.session.frames.appendleft((time.monotonic_ns(), hb))
                try:
                    params = ParamClient(st.session, hb.sysid).fetch_all()
                    self.writer.meta(st.id, {"type": "params", "sysid": hb.sysid, "params": params})
                    st.units.setdefault(hb.sysid, {"sysid": hb.sysid})["params"] = len(params)
                except ParamError as exc:
                    self._warn(st, f"{st.url}: parameters of unit {hb.sysid} not read: {exc}")
                self._look(st)
                self._flush_stream(st)
        for st in self.streams:
            try:
                if self.rate_hz:
                    self._checked_command(st, CMD_SET_INTERVAL, float(MSG_RAW), 1e6 / self.rate_hz)
                if self.start_streaming:
                    self._checked_command(st, CMD_STREAM, 1.0)
            except OSError as exc:
                self._warn(st, f"{st.url}: cannot send commands: {exc}")

    def stop(self) -> None:
        self._stop.set()

    def run(self, duration: float | None = None, on_tick=None, tick: float = 0.25) -> dict:
        """Record until ``duration`` s, ``stop()``, or every connection closed; returns a summary."""
        next_sync = next_tick = time.monotonic()
        try:
            self._setup()
            # the duration counts from the end of the setup (parameters, commands): that long
            # of streaming is recorded, whatever the setup took
            t_end = None if duration is None else time.monotonic() + duration
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
            # the reader stops first: what it reads until then is written too (it was read
            # after the last poll and dropped with the session)
            st.session.reader.stop(join=5.0)
            try:
                st.session.poll(0)
                self._look(st, final=True)
            except Exception:  # noqa: BLE001 - closing must go on
                pass
            try:
                self._flush_stream(st, force=True)
            except KinefuseError:   # the disk is full...: writer.close() raises it once all is closed
                pass
            st.session.close()
        self.writer.close()

    def summary(self) -> dict:
        elapsed = (time.monotonic_ns() - self.started_ns) / 1e9
        streams = []
        for st in self.streams:
            c = st.session.decoder.counters
            streams.append({
                "id": st.id, "connection": st.url, "bytes": c.bytes_in, "frames": c.frames_ok,
                "crc_errors": c.crc_errors, "bytes_skipped": c.bytes_skipped,
                "messages": dict(st.session.msg_counts),   # the PARAM_VALUEs ParamClient took too
                "units": [dict(u) for u in st.units.values()], "closed": st.closed, "error": st.error,
            })
        return {"file": str(self.writer.path), "elapsed_s": round(elapsed, 3), "file_bytes": self.writer.bytes_written,
                "streams": streams, "warnings": list(self.warnings), "unit_texts": list(self.unit_texts),
                "finished": getattr(self, "_closed", False)}
