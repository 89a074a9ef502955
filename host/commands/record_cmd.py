"""``kinefuse record``: record the raw MAVLink streams of one or more units into a .kfr file.

    kinefuse record --port /dev/ttyUSB0 --out walk.kfr --duration 60
    kinefuse record --port /dev/ttyUSB0 --port /dev/ttyUSB1 --out both.kfr --start --rate 500
    kinefuse record --port fake:rate=500 --out demo.kfr --duration 5      # simulated unit

The file holds every received byte with host receive times, the header describes the host,
the dialect and the connections; units' status and parameters are added as they are learned.
Stop with Ctrl-C (the file stays valid; a killed recorder loses at most the last second).
Every unit's parameter list is read into the file first (--no-params: not); a unit that does
not answer gives a warning.  --start/--rate commands are checked: a unit that refuses one (a
unit with a signing key refuses unsigned commands: --key/--key-file) ends the recording with
a one-line error and exit status 2.
"""
from __future__ import annotations

import signal
import threading
from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.cli_util import check_distinct_ports, console, fmt_bytes, print_json
from kinefuse.host.link.signing import add_key_args, key_from_args
from kinefuse.host.outputs import add_force_arg, check_new_file


def register(subparsers) -> None:
    p = subparsers.add_parser("record", help="record raw unit streams to a .kfr file",
                              description=__doc__.split("\n\n")[0].split(": ", 1)[-1])
    p.add_argument("--port", action="append", required=True, metavar="CONN",
                   help="serial port or connection string (repeat for several units): /dev/ttyUSB0, COM3, "
                        "serial:PATH:BAUD, pty:PATH, tcp:H:P, tcpin:H:P, udp:H:P, file:PATH, fake:[opts]")
    p.add_argument("--out", required=True, metavar="FILE.kfr", help="recording to create")
    p.add_argument("--duration", type=float, metavar="S", help="stop after S seconds (default: Ctrl-C)")
    p.add_argument("--baud", default=921600, metavar="BAUD", help="serial baud rate (default 921600)")
    p.add_argument("--start", action="store_true", help="send MAV_CMD_KF_STREAM start (and stop at the end)")
    p.add_argument("--rate", type=float, metavar="HZ", help="request this KF_RAW_SAMPLE rate (SET_MESSAGE_INTERVAL)")
    p.add_argument("--params", action="store_true", default=True,
                   help="read every unit's parameter list into the file first (the default)")
    p.add_argument("--no-params", dest="params", action="store_false",
                   help="do not request the parameter lists (a unit that does not answer only gives a warning)")
    p.add_argument("--no-timesync", action="store_true", help="do not send TIMESYNC requests (1 Hz, for latency)")
    p.add_argument("--note", help="free text stored in the header")
    add_key_args(p, "the commands sent (--start, --rate)")
    add_force_arg(p, "FILE")
    p.add_argument("--json", action="store_true", help="print the summary as one JSON object")
    p.set_defaults(func=run)


def run(args) -> int:
    from kinefuse.host.link.connection import parse_baud
    from kinefuse.host.link.cli_util import check_raw_rate
    from kinefuse.host.link.recorder import Recorder
    out = check_new_file(args.out, args.force, inputs=_port_paths(args.port))
    check_distinct_ports(args.port)
    if args.duration is not None and not args.duration > 0:   # NaN too (it recorded until Ctrl-C)
        raise KinefuseError("--duration must be positive")
    check_raw_rate(args.rate)
    baud = parse_baud(args.baud)
    key = key_from_args(args)
    rec = Recorder(out, args.port, baud=baud, note=args.note, timesync=not args.no_timesync,
                   start_streaming=args.start, rate_hz=args.rate, fetch_params=args.params, key=key)
    con = console(args.json)
    for w in rec.warnings:
        con.print(f"[yellow]warning:[/] {w}")

    # SIGTERM (e.g. `timeout`, a service manager) ends the recording like Ctrl-C
    prev = None
    if threading.current_thread() is threading.main_thread():
        prev = signal.signal(signal.SIGTERM, lambda *_: rec.stop())
    shown_warnings = len(rec.warnings)
    shown_texts = 0

    def unit_texts(printer, summary):
        """The units' STATUSTEXTs (a storage error...) as they come; not rich markup."""
        nonlocal shown_texts
        for text in summary["unit_texts"][shown_texts:]:
            printer.print(f"unit says: {text}", style="yellow", markup=False, soft_wrap=True)
        shown_texts = len(summary["unit_texts"])
    try:
        from rich.live import Live
        with Live(_table(rec.summary(), args.duration), console=con, refresh_per_second=4,
                  transient=False) as live:
            def tick(summary):
                nonlocal shown_warnings
                live.update(_table(summary, args.duration))
                for w in summary["warnings"][shown_warnings:]:
                    live.console.print(f"[yellow]warning:[/] {w}")
                shown_warnings = len(summary["warnings"])
                unit_texts(live.console, summary)
            failed = None
            try:
                summary = rec.run(args.duration, on_tick=tick)
            except KeyboardInterrupt:
                rec.close()
                summary = rec.summary()
            except KinefuseError as exc:      # a unit refused --start/--rate: the file says so too
                failed = exc
                summary = rec.summary()
            live.update(_table(summary, args.duration))
            for w in summary["warnings"][shown_warnings:]:
                live.console.print(f"[yellow]warning:[/] {w}")
            unit_texts(live.console, summary)
    finally:
        if prev is not None:
            signal.signal(signal.SIGTERM, prev)
    if failed is not None:
        if not con.is_terminal:
            con.print()
        raise failed
    if args.json:
        print_json(summary)
    else:
        if not con.is_terminal:
            con.print()
        con.print(f"wrote {summary['file']} ({fmt_bytes(summary['file_bytes'])}, {summary['elapsed_s']:.1f} s)")
    return 0


def _port_paths(ports) -> list[str]:
    """The files a connection string may name (file:PATH, pty:PATH, serial:PATH[:BAUD], a bare
    path): --out must be none of them, --force or not (file:capture.bin --out capture.bin
    --force replaced the capture with a recording of its first bytes)."""
    out = []
    for url in ports:
        rest = url.partition(":")[2]
        out += [url, rest, rest.rpartition(":")[0]]
    return [p for p in out if p]


def _table(summary: dict, duration):
    from rich.table import Table
    title = f"recording {summary['file']}  {summary['elapsed_s']:.1f} s" + (f" / {duration:g} s" if duration else "")
    t = Table("stream", "connection", "bytes", "frames", "CRC err", "skipped", "units", "state", title=title, box=None)
    for s in summary["streams"]:
        units = ", ".join(f"{u['sysid']}" + (f" fw {u['firmware_version']}" if u.get("firmware_version") else "")
                          for u in s["units"]) or "-"
        state = "closed" + (f": {s['error']}" if s["error"] else "") if s["closed"] else \
            "done" if summary.get("finished") else "recording"
        t.add_row(str(s["id"]), s["connection"], fmt_bytes(s["bytes"]), f"{s['frames']:,}", str(s["crc_errors"]),
                  str(s["bytes_skipped"]), units, state)
    return t
