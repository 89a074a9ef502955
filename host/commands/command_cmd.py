"""``kinefuse command``: send a unit a command and check its answer (COMMAND_ACK).

    kinefuse command --port /dev/ttyUSB0 start --rate 500     # stream KF_RAW_SAMPLE at 500 Hz
    kinefuse command --port /dev/ttyUSB0 stop
    kinefuse command --port /dev/ttyUSB0 tare --heading 0     # current heading becomes 0 deg
    kinefuse command --port /dev/ttyUSB0 reset                # re-initialise the filter (clears a tare)
    kinefuse command --port /dev/ttyUSB0 reboot
    kinefuse command --port /dev/ttyUSB0 --key-file unit.key start   # a unit with a signing key

A refused or unanswered command is a one-line error with exit status 2 (MAV_RESULT_DENIED from
a unit with a signing key: give it with --key/--key-file).
"""
from __future__ import annotations

import math

from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.cli_util import console, print_json
from kinefuse.host.link.signing import add_key_args, key_from_args

ACTIONS = ("start", "stop", "tare", "reset", "reboot")


def register(subparsers) -> None:
    p = subparsers.add_parser("command", help="start/stop streaming, heading tare, filter reset, reboot",
                              description=__doc__.split("\n\n")[0].split(": ", 1)[-1])
    p.add_argument("action", choices=ACTIONS, help="start / stop streaming, heading tare, filter reset, reboot")
    p.add_argument("--port", required=True, metavar="CONN", help="serial port or connection string")
    p.add_argument("--baud", default=921600, metavar="BAUD", help="serial baud rate (default 921600)")
    p.add_argument("--unit", type=int, metavar="SYSID", help="system id of the unit (default: first heartbeat)")
    p.add_argument("--rate", type=float, metavar="HZ", help="start: KF_RAW_SAMPLE rate (SET_MESSAGE_INTERVAL first)")
    p.add_argument("--reset-counter", action="store_true", help="start: restart sample_counter at 0")
    p.add_argument("--heading", type=float, metavar="DEG",
                   help="tare: heading given to the current orientation, degrees (default 0)")
    add_key_args(p, "the command")
    p.add_argument("--timeout", type=float, default=3.0, metavar="S", help="wait this long for a heartbeat (default 3)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=run)


def run(args) -> int:
    from kinefuse.host.link import command as C
    from kinefuse.host.link.connection import open_connection, parse_baud
    from kinefuse.host.link.session import Session
    from kinefuse.host.link.cli_util import check_raw_rate
    check_raw_rate(args.rate, None if args.action == "start" else "start")
    if args.reset_counter and args.action != "start":
        raise KinefuseError("--reset-counter goes with start")
    if args.heading is not None and args.action != "tare":
        raise KinefuseError("--heading goes with tare")
    heading = 0.0 if args.heading is None else args.heading
    if not math.isfinite(heading):
        raise KinefuseError("--heading must be a finite number of degrees")
    if not args.timeout > 0:   # NaN too: it waited for ever for a unit that does not answer
        raise KinefuseError("--timeout must be positive")
    if args.unit is not None and not 0 < args.unit < 256:   # 300 was an internal error (struct)
        raise KinefuseError("--unit must be a unit (MAVLink system) id 1..255")
    key = key_from_args(args)
    conn = open_connection(args.port, parse_baud(args.baud))
    sent = []
    with Session(conn, key=key) as s:
        sysid = args.unit
        if sysid is None:
            from kinefuse.host.link.cli_util import first_unit
            sysid = first_unit(s, args.port, args.timeout)
        if args.action == "start":
            if args.rate:
                C.send_command(s, sysid, C.MAV_CMD_SET_MESSAGE_INTERVAL, float(C.MSG_KF_RAW_SAMPLE), 1e6 / args.rate)
                sent.append(C.command_name(C.MAV_CMD_SET_MESSAGE_INTERVAL))
            C.send_command(s, sysid, C.MAV_CMD_KF_STREAM, 1.0, 1.0 if args.reset_counter else 0.0)
        elif args.action == "stop":
            C.send_command(s, sysid, C.MAV_CMD_KF_STREAM, 0.0)
        elif args.action == "tare":
            C.send_command(s, sysid, C.MAV_CMD_KF_HEADING_TARE, math.radians(heading))
        elif args.action == "reset":
            C.send_command(s, sysid, C.MAV_CMD_KF_FILTER_RESET, 0.0)
        else:
            C.send_command(s, sysid, C.MAV_CMD_REBOOT, 1.0)
        sent.append(C.command_name({"start": C.MAV_CMD_KF_STREAM, "stop": C.MAV_CMD_KF_STREAM,
                                    "tare": C.MAV_CMD_KF_HEADING_TARE, "reset": C.MAV_CMD_KF_FILTER_RESET,
                                    "reboot": C.MAV_CMD_REBOOT}[args.action]))
    res = {"unit": sysid, "action": args.action, "accepted": sent}
    if args.json:
        print_json(res)
    else:
        console().print(f"unit {sysid}: {args.action} accepted")
    return 0
