"""``kinefuse ports``: list serial ports (USB VID:PID, serial number, FTDI latency timer)."""
from __future__ import annotations

from kinefuse.host.link.cli_util import console, print_json
from kinefuse.host.console import print_table


def register(subparsers) -> None:
    p = subparsers.add_parser("ports", help="list serial ports (USB VID:PID, serial number)",
                              description=__doc__.strip("`").split(": ", 1)[-1])
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=run)


def run(args) -> int:
    from kinefuse.host.link.connection import list_ports
    ports = list_ports()
    if args.json:
        print_json({"ports": ports})
        return 0
    con = console()
    if not ports:
        con.print("no serial ports found")
        return 0
    from rich.table import Table
    t = Table("device", "VID:PID", "serial number", "description", "latency timer", box=None)
    for p in ports:
        lat = p["latency_timer_ms"]
        t.add_row(p["device"], p["vid_pid"] or "-", p["serial_number"] or "-",
                  p["description"] or p["product"] or "-",
                  "-" if lat is None else f"{lat} ms" + ("  (set 1 ms for streaming)" if lat > 2 else ""))
    print_table(t, con)
    return 0
