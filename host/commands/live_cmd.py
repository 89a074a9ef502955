"""``kinefuse live``: a live view of the units on a connection (rates, loss, errors, orientation, battery).

    kinefuse live --port /dev/ttyUSB0
    kinefuse live --port fake:rate=500 --seconds 10       # simulated unit
    kinefuse live --port tcp:192.168.4.1:5760 --unit 2

Per unit: KF_RAW_SAMPLE rate achieved (on the unit's clock, last 2 s) vs requested (from
KF_UNIT_STATUS), samples lost (32-bit ``sample_counter``, wrap-safe; a frame the link delivered
after a later one, up to 50 ms late, is counted reordered, not lost), CRC errors of the link,
the latest KF_ORIENTATION as roll/pitch/yaw in degrees (intrinsic Z-Y'-X'' of the quaternion
sensor -> earth; the earth frame the unit states: ENU = yaw about Up, counter-clockwise from
East; NED = yaw about Down, clockwise from North), battery and status from KF_UNIT_STATUS.
The view only listens unless --start is given: then it sends MAV_CMD_KF_STREAM start (and
--rate's SET_MESSAGE_INTERVAL) to every unit first, checks the COMMAND_ACKs (a refusal is a
one-line error, exit status 2; a unit with a signing key needs --key/--key-file; a unit heard
that counted the signed start as a signature failure -- after a power cut, until the host's clock
passes its stored floor, at most 60 s -- is told so) and sends stop at the end.  Ctrl-C or --seconds ends it; with
stdout not a terminal it prints plain lines every --interval seconds instead of a table.
"""
from __future__ import annotations

import signal
import sys
import threading
import time
from collections import deque
from dataclasses import dataclass, field

import numpy as np

from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.signing import add_key_args, key_from_args

MSG_RAW, MSG_ORI, MSG_STATUS, MSG_STATUSTEXT = 52500, 52501, 52504, 253
RATE_WINDOW_US = 2_000_000
EARTH_FRAMES = {0: "unknown frame", 1: "ENU", 2: "NED"}
# KF_UNIT_STATUS_FLAGS; "mag": MAG_PRESENT (a magnetometer reading arrived since boot)
STATUS_FLAGS = ((1, "streaming"), (2, "mag"), (4, "SENSOR FAULT"), (8, "HIL"), (16, "LOW BATTERY"),
                (32, "calibrated"), (64, "TX OVERFLOW"), (128, "STORAGE ERROR"))


@dataclass
class UnitView:
    stream: int
    sysid: int
    connection: str
    raw_frames: int = 0
    lost: int = 0
    resets: int = 0
    stride: int | None = None
    last_counter: int | None = None
    pending: list = field(default_factory=list)       # counters not yet checked for loss
    window: deque = field(default_factory=deque)      # device times (us) of the last RATE_WINDOW_US
    requested_hz: float | None = None
    rpy_deg: tuple | None = None
    earth_frame: str | None = None
    ori_frames: int = 0
    status: object = None                             # latest KF_UNIT_STATUS record
    repeats: int = 0                                  # frames delivered again (not samples)
    reordered: int = 0                                # frames swapped on the way (samples, late)
    max_t: int | None = None                          # latest device time of the current clock segment
    max_c: int | None = None                          # ... and its sample counter
    seen: dict = field(default_factory=dict)          # (time, counter) of its latest frames (bounded)

    # -- updates -------------------------------------------------------------------------------
    def raw(self, m) -> None:
        from kinefuse.host.link.stats import reordered
        self.raw_frames += 1
        t, c = int(m.time_boot_us), int(m.sample_counter)
        if self.max_t is not None and t <= self.max_t:
            if (t, c) in self.seen:
                # a frame delivered again (stats' rule, device_segments): was a counter reset,
                # and the step from it back onto the stream that many samples "lost"
                self.repeats += 1
                return
            if reordered(t, c, self.max_t, self.max_c):
                # frame N after N+1 (UDP, a Wi-Fi bridge): was a reboot and two samples lost
                self.reordered += 1
                self._late(t, c)
                return
            self.window.clear()                       # back onto a time not sent: a reboot
            self.seen.clear()
        self.max_t, self.max_c = t, c
        self._remember(t, c)
        self.window.append(t)
        while self.window and self.window[0] < t - RATE_WINDOW_US:
            self.window.popleft()
        self.pending.append(c)

    def _remember(self, t: int, c: int) -> None:
        self.seen[(t, c)] = None
        if len(self.seen) > 4096:
            del self.seen[next(iter(self.seen))]

    def _late(self, t: int, c: int) -> None:
        """A sample swapped on the way: into the rate window and the counters in its place;
        when the counters around it were already checked, the sample counted lost arrived."""
        import bisect
        self._remember(t, c)
        bisect.insort(self.window, t)
        k = len(self.pending)
        while k and 0 < (self.pending[k - 1] - c) & 0xFFFFFFFF < 1 << 31:   # pending[k - 1] after c
            k -= 1
        if k or self.last_counter is None or not 0 < (self.last_counter - c) & 0xFFFFFFFF < 1 << 31:
            self.pending.insert(k, c)
        elif self.lost:
            self.lost -= 1

    def settle_counters(self, final: bool = False) -> None:
        """Count lost samples in the counters received since the last call (wrap-safe); the
        stride (usual step, >1 for a decimated stream) is learned from the first 16 counters:
        the greatest common divisor of their steps, which stays the stride whatever was lost
        (their most common step was 2 or more on a link losing most frames: loss undercounted)."""
        from kinefuse.host.link.stats import counter_analysis
        if not self.pending:
            return
        if self.stride is None:
            if len(self.pending) < 16 and not final:
                return
            seq = ([] if self.last_counter is None else [self.last_counter]) + self.pending
            d = np.diff(np.asarray(seq, np.int64)) & 0xFFFFFFFF
            forward = d[(d > 0) & (d < 1 << 31)]
            self.stride = int(np.gcd.reduce(forward)) if forward.size else 1
        c = np.asarray(([] if self.last_counter is None else [self.last_counter]) + self.pending, np.int64)
        self.last_counter = int(c[-1])
        self.pending = []
        a = counter_analysis(c, stride=self.stride)
        self.lost += a["samples_lost"]
        self.resets += a["resets"]

    def orientation(self, m) -> None:
        from kinefuse.host.kinematics.quat import to_euler
        q = np.array([m.q_w, m.q_x, m.q_y, m.q_z], dtype=np.float64)
        self.ori_frames += 1
        if np.all(np.isfinite(q)) and np.linalg.norm(q) > 0.5:
            yaw, pitch, roll = np.degrees(to_euler(q, "ZYX"))
            self.rpy_deg = (float(roll), float(pitch), float(yaw))
            self.earth_frame = EARTH_FRAMES.get(int(m.earth_frame), f"frame {int(m.earth_frame)}")

    # -- derived -------------------------------------------------------------------------------
    @property
    def rate_hz(self) -> float | None:
        if len(self.window) < 3 or self.window[-1] <= self.window[0]:
            return None
        return (len(self.window) - 1) / ((self.window[-1] - self.window[0]) / 1e6)

    def battery_text(self) -> str:
        s = self.status
        if s is None:
            return "-"
        parts = []
        if int(s.battery_voltage) != 0xFFFF:
            parts.append(f"{int(s.battery_voltage) / 1000:.2f} V")
        if int(s.battery_remaining) >= 0:
            parts.append(f"{int(s.battery_remaining)} %")
        return " ".join(parts) or "unknown"

    def status_text(self) -> str:
        s = self.status
        if s is None:
            return "no KF_UNIT_STATUS yet"
        flags = int(s.status_flags)
        v = int(s.firmware_version)
        words = [w for bit, w in STATUS_FLAGS if flags & bit] or ["not streaming"]
        words.append(f"fw {v >> 24}.{(v >> 16) & 0xFF}.{(v >> 8) & 0xFF}")
        if int(s.samples_dropped):
            words.append(f"{int(s.samples_dropped)} dropped on unit")
        return ", ".join(words)

    def requested_text(self, unit: bool = False) -> str:
        """The requested rate: "?" unknown, "off", or the number (with " Hz" if ``unit``)."""
        if self.requested_hz is None:
            return "?"
        if self.requested_hz == 0:
            return "off"
        return f"{self.requested_hz:g}" + (" Hz" if unit else "")

    def orientation_text(self) -> str:
        if self.rpy_deg is None:
            return "no KF_ORIENTATION" if not self.ori_frames else "invalid"
        r, p, y = self.rpy_deg
        return f"roll {r:+7.1f} pitch {p:+6.1f} yaw {y:+7.1f} deg ({self.earth_frame})"


class LiveMonitor:
    """Per (stream, system id) unit state fed with decoded frames of the sessions."""

    def __init__(self, sessions: list, unit: int | None = None):
        self.sessions = sessions
        self.unit = unit
        self.units: dict = {}
        self.started = time.monotonic()
        self.texts: list[str] = []      # the units' STATUSTEXTs, as lines
        self.on_text = None             # on_text(line) as each arrives (run prints it)

    def feed(self, sid: int, frames) -> None:
        for _, f in frames:
            if f.msgid == MSG_STATUSTEXT and f.sysid != 255 and (self.unit is None or f.sysid == self.unit):
                # e.g. "parameter storage error: settings may be lost": was never shown
                from kinefuse.host.link.stats import statustext_text
                line = f"unit {f.sysid} ({self.sessions[sid].conn.url}) says {statustext_text(f.msg.severity, f.msg.text)}"
                self.texts.append(line)
                if self.on_text is not None:
                    self.on_text(line)
                continue
            if f.msgid not in (MSG_RAW, MSG_ORI, MSG_STATUS) or (self.unit is not None and f.sysid != self.unit):
                continue
            u = self.units.get((sid, f.sysid))
            if u is None:
                u = self.units[(sid, f.sysid)] = UnitView(sid, f.sysid, self.sessions[sid].conn.url)
            if f.msgid == MSG_RAW:
                u.raw(f.msg)
            elif f.msgid == MSG_ORI:
                u.orientation(f.msg)
            else:
                u.status = f.msg
                u.requested_hz = float(f.msg.raw_rate_requested)
        for (s, _), u in self.units.items():
            if s == sid:
                u.settle_counters()

    def crc_errors(self, sid: int) -> int:
        return int(self.sessions[sid].decoder.counters.crc_errors)

    def lines(self) -> list[str]:
        el = time.monotonic() - self.started
        out = []
        for (sid, sysid), u in sorted(self.units.items()):
            rate = u.rate_hz
            out.append(f"[{el:6.1f} s] unit {sysid} ({u.connection}): rate "
                       f"{'-' if rate is None else f'{rate:.1f}'} Hz (requested {u.requested_text(unit=True)}), "
                       f"lost {u.lost}" + (f" ({u.resets} counter resets)" if u.resets else "")
                       + (f", {u.reordered} reordered" if u.reordered else "")
                       + f", CRC errors {self.crc_errors(sid)}, {u.orientation_text()}, "
                         f"battery {u.battery_text()}, {u.status_text()}")
        seen = {sid for sid, _ in self.units}
        for sid, s in enumerate(self.sessions):
            if sid not in seen:
                c = s.decoder.counters
                who = f"unit {self.unit}" if self.unit is not None else "unit"
                out.append(f"[{el:6.1f} s] {s.conn.url}: no {who} data yet ({c.bytes_in} bytes, "
                           f"{c.frames_ok} frames, {c.crc_errors} CRC errors)")
        return out

    def table(self):
        from rich.table import Table
        el = time.monotonic() - self.started
        t = Table("unit", "connection", "rate Hz", "req Hz", "lost", "CRC", "roll°", "pitch°", "yaw°",
                  "frame", "battery", "status", box=None, pad_edge=False, collapse_padding=True,
                  title=f"kinefuse live  {el:.1f} s  (Ctrl-C to stop)",
                  caption="orientation: KF_ORIENTATION sensor->earth as intrinsic Z-Y'-X'' yaw, pitch, roll; "
                          "ENU: yaw about Up, counter-clockwise from East")
        # the numbers keep their width (on an 80-column terminal roll and yaw read "+2…" and the
        # status column was gone); the connection shrinks, battery and status wrap
        widths = {0: 4, 2: 7, 3: 6, 4: 4, 5: 3, 6: 6, 7: 6, 8: 6, 9: 5}
        for k, col in enumerate(t.columns):
            col.no_wrap = k in widths
            col.min_width = widths.get(k)
        t.columns[1].max_width, t.columns[1].min_width, t.columns[1].overflow = 24, 8, "ellipsis"
        for (sid, sysid), u in sorted(self.units.items()):
            rate = u.rate_hz
            ratio_low = rate is not None and u.requested_hz and rate < 0.95 * u.requested_hz
            rpy = ("-", "-", "-") if u.rpy_deg is None else tuple(f"{a:+.1f}" for a in u.rpy_deg)
            t.add_row(str(sysid), u.connection, "-" if rate is None else f"{rate:.1f}", u.requested_text(),
                      f"[red]{u.lost}[/]" if u.lost else "0", str(self.crc_errors(sid)), *rpy,
                      u.earth_frame or "-", u.battery_text(), u.status_text(),
                      style="yellow" if ratio_low else None)
        seen = {sid for sid, _ in self.units}
        for sid, s in enumerate(self.sessions):
            if sid not in seen:
                t.add_row("-", s.conn.url, "-", "-", "-", str(self.crc_errors(sid)), "-", "-", "-", "-", "-",
                          f"no unit data yet ({s.decoder.counters.bytes_in} bytes)")
        return t


def register(subparsers) -> None:
    p = subparsers.add_parser("live", help="live view of the units on a connection: rate, loss, errors, "
                                           "orientation, battery",
                              description=__doc__.split("\n\n")[0].split(": ", 1)[-1])
    p.add_argument("--port", action="append", required=True, metavar="CONN",
                   help="serial port or connection string (repeat for several): /dev/ttyUSB0, COM3, "
                        "serial:PATH:BAUD, pty:PATH, tcp:H:P, tcpin:H:P, udp:H:P, file:PATH, fake:[opts]")
    p.add_argument("--unit", type=int, metavar="ID", help="show only this unit (MAVLink system id)")
    p.add_argument("--seconds", type=float, metavar="S", help="stop after S seconds (default: Ctrl-C)")
    p.add_argument("--baud", default=921600, metavar="BAUD", help="serial baud rate (default 921600)")
    p.add_argument("--interval", type=float, default=1.0, metavar="S",
                   help="seconds between plain lines when stdout is not a terminal (default 1)")
    p.add_argument("--start", action="store_true", help="start the units' streaming first (and stop it at the end)")
    p.add_argument("--rate", type=float, metavar="HZ", help="with --start: request this KF_RAW_SAMPLE rate")
    add_key_args(p, "--start's commands")
    p.set_defaults(func=run)


def start_streaming(sessions, rate_hz: float | None) -> list[str]:
    """MAV_CMD_KF_STREAM start (after SET_MESSAGE_INTERVAL) to every unit of every session;
    a refusal raises CommandError; returns warnings for connections where nobody answered."""
    from kinefuse.host.link import command as C
    warnings = []
    steps = ([(C.MAV_CMD_SET_MESSAGE_INTERVAL, (float(C.MSG_KF_RAW_SAMPLE), 1e6 / rate_hz))] if rate_hz else []) \
        + [(C.MAV_CMD_KF_STREAM, (1.0,))]
    for s in sessions:
        for cmd, params in steps:
            refused: dict = {}
            acks = C.broadcast_command(s, cmd, *params, refused=refused)
            for sysid, r in sorted(acks.items()):
                if r != 0:
                    raise C.CommandError(f"{s.conn.url}: {C.refusal_text(sysid, cmd, r, s.encoder.key is not None)}", r)
            if refused:     # a unit heard but not answering counted the signed command as refused
                from kinefuse.host.link.signing import refused_text
                sysid, n = sorted(refused.items())[0]
                more = f" (and unit(s) {', '.join(map(str, sorted(refused)[1:]))} too)" if len(refused) > 1 else ""
                raise C.CommandError(f"{s.conn.url}: no COMMAND_ACK for {C.command_name(cmd)} from unit "
                                     f"{sysid}{more}: {refused_text(n)}", refused=n)
            if not acks:
                text = f"{s.conn.url}: no COMMAND_ACK for {C.command_name(cmd)}"
                if s.encoder.key is not None:    # a unit with another key drops signed frames silently
                    raise C.CommandError(text + " (a unit drops frames signed with a key other than its own: "
                                                "is it the right key?)")
                warnings.append(text + " (no unit answering?)")
                break
    return warnings


def stop_streaming(sessions) -> None:
    from kinefuse.host.link import command as C
    for s in sessions:
        try:
            s.send("COMMAND_LONG", target_system=0, target_component=0, command=C.MAV_CMD_KF_STREAM,
                   confirmation=0, param1=0.0, param2=0.0, param3=0.0, param4=0.0, param5=0.0,
                   param6=0.0, param7=0.0)
        except OSError:
            pass


def run(args) -> int:
    from kinefuse.host.link.connection import open_connection, parse_baud
    from kinefuse.host.link.session import Session
    if args.seconds is not None and not args.seconds > 0:
        raise KinefuseError("--seconds must be positive")
    if not args.interval > 0:
        raise KinefuseError("--interval must be positive")
    if args.unit is not None and not 0 < args.unit < 256:
        raise KinefuseError("--unit must be a unit (MAVLink system) id 1..255")
    from kinefuse.host.link.cli_util import check_distinct_ports, check_raw_rate
    check_raw_rate(args.rate, None if args.start else "--start")
    check_distinct_ports(args.port)
    baud = parse_baud(args.baud)
    key = key_from_args(args)
    sessions = []
    try:
        for url in args.port:
            sessions.append(Session(open_connection(url, baud), key=key))
        if args.start:
            for w in start_streaming(sessions, args.rate):
                print(f"kinefuse: warning: {w}", file=sys.stderr)
    except BaseException:
        if args.start:      # a unit on an earlier connection may already be streaming
            stop_streaming(sessions)
        for s in sessions:
            s.close()
        raise
    mon = LiveMonitor(sessions, args.unit)
    stop = threading.Event()
    prev = None
    if threading.current_thread() is threading.main_thread():
        prev = signal.signal(signal.SIGTERM, lambda *_: stop.set())
    tty = sys.stdout.isatty()
    interrupted = False
    try:
        if tty:
            from rich.console import Console
            from rich.live import Live
            with Live(mon.table(), console=Console(), refresh_per_second=4, transient=False) as live:
                mon.on_text = lambda line: live.console.print(line, style="yellow", markup=False, soft_wrap=True)
                interrupted = _loop(mon, sessions, args.seconds, 0.25, lambda: live.update(mon.table()), stop)
                live.update(mon.table())
        else:
            mon.on_text = lambda line: print(line, flush=True)
            def emit():
                print("\n".join(mon.lines()), flush=True)
            interrupted = _loop(mon, sessions, args.seconds, args.interval, emit, stop)
    finally:
        if prev is not None:
            signal.signal(signal.SIGTERM, prev)
        if args.start:
            stop_streaming(sessions)
        for s in sessions:
            s.close()
    for u in mon.units.values():
        u.settle_counters(final=True)
    if not tty:
        print("\n".join(mon.lines()) + "\n" + _end_text(interrupted, sessions), flush=True)
    else:
        print(_end_text(interrupted, sessions), file=sys.stderr)
    if not mon.units:
        which = f"unit {args.unit}" if args.unit is not None else "kinefuse unit"
        raise KinefuseError(f"no {which} data received on {', '.join(args.port)}")
    return 0


def _end_text(interrupted: bool, sessions) -> str:
    closed = [s.conn.url for s in sessions if s.reader.closed.is_set() and s.reader.error]
    why = "interrupted" if interrupted else "done"
    return f"live view {why}" + (f"; connection closed: {', '.join(closed)}" if closed else "")


def _loop(mon: LiveMonitor, sessions, seconds, interval: float, show, stop: threading.Event) -> bool:
    """Poll the sessions (blocking waits, no busy loop) until --seconds, Ctrl-C, SIGTERM or every
    connection closed; ``show()`` every ``interval`` s.  True when interrupted by Ctrl-C."""
    start = time.monotonic()
    t_end = None if seconds is None else start + seconds
    next_show = start + interval
    try:
        while not stop.is_set():
            now = time.monotonic()
            if t_end is not None and now >= t_end:
                break
            live = [(sid, s) for sid, s in enumerate(sessions) if not s.reader.finished]
            if not live:   # what is still queued (e.g. read while --start waited for ACKs) counts
                for sid, s in enumerate(sessions):
                    mon.feed(sid, s.drain())
                break
            wait = min(0.1, next_show - now, (t_end - now) if t_end is not None else 0.1)
            wait = max(0.0, wait) / len(live)
            for sid, s in live:
                s.poll(wait)
                mon.feed(sid, s.drain())
            now = time.monotonic()
            if now >= next_show and (t_end is None or now < t_end):  # the end shows itself
                next_show += interval
                show()
    except KeyboardInterrupt:
        return True
    return False
