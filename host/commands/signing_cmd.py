"""``kinefuse signing``: show, set, change or clear a unit's MAVLink 2 signing key.

    kinefuse signing --generate unit.key                           # a new random key file (mode 0600)
    kinefuse signing --port /dev/ttyUSB0                           # does the unit require signing?
    kinefuse signing --port /dev/ttyUSB0 --new-key-file unit.key   # first key: over a trusted link
    kinefuse signing --port /dev/ttyUSB0 --key-file unit.key --new-key-file next.key   # change it
    kinefuse signing --port /dev/ttyUSB0 --key-file unit.key --clear                   # signing off

Keys: 64 hex digits, or a passphrase (key = SHA-256 of it, as MAVProxy's ``signing setup``), or
a file holding either (``--*-key-file``).  A unit without a key accepts the first one unsigned,
so set it over the USB cable, not a shared radio link; afterwards a new key or ``--clear``
needs the current key (``--key``/``--key-file``).  With a key set the unit refuses unsigned
parameter writes and commands (``kinefuse params``/``record``/``live``/``command`` take
``--key``/``--key-file``); reading parameters and the streams stays open.  The result is
checked by reading KF_SIGNING and by a signed harmless command.  A lost key cannot be cleared
over the link (erase the unit's storage with a chip erase when reflashing).
"""
from __future__ import annotations

import os
import secrets

from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.cli_util import console, print_json
from kinefuse.host.link.signing import add_key_args, key_from_args, key_id, parse_key, read_key_file


def register(subparsers) -> None:
    p = subparsers.add_parser("signing", help="set, change or clear a unit's MAVLink 2 signing key",
                              description=__doc__.split("\n\n")[0].split(": ", 1)[-1])
    p.add_argument("--port", metavar="CONN", help="serial port or connection string of the unit")
    p.add_argument("--baud", default=921600, metavar="BAUD", help="serial baud rate (default 921600)")
    p.add_argument("--unit", type=int, metavar="SYSID", help="system id of the unit (default: first heartbeat)")
    add_key_args(p, "SETUP_SIGNING (the unit's current key, when it has one)")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--new-key", metavar="KEY", help="install this key (64 hex digits or a passphrase)")
    g.add_argument("--new-key-file", metavar="FILE", help="install the key in FILE")
    g.add_argument("--clear", action="store_true", help="remove the key (the unit accepts unsigned configuration)")
    g.add_argument("--generate", metavar="FILE", help="write a new random key (64 hex digits) to FILE and exit")
    p.add_argument("--timeout", type=float, default=3.0, metavar="S", help="wait this long for a heartbeat (default 3)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=run)


def generate(path: str) -> dict:
    if os.path.exists(path):
        raise KinefuseError(f"{path} exists (not overwritten)")
    key = secrets.token_bytes(32)
    try:
        fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    except OSError as exc:
        raise KinefuseError(f"cannot create {path}: {exc.strerror or exc}") from None
    try:
        with os.fdopen(fd, "w") as f:
            f.write(key.hex() + "\n")
    except OSError as exc:   # a disk full: a cut key file would later read as a passphrase
        try:
            os.unlink(path)
        except OSError:
            pass
        raise KinefuseError(f"cannot write {path}: {exc.strerror or exc} (no key file written)") from None
    return {"file": path, "key_id": key_id(key)}


def run(args) -> int:
    con = console(args.json)
    if args.generate:
        res = generate(args.generate)
        if args.json:
            print_json(res)
        else:
            con.print(f"wrote a new key to {res['file']} (key id {res['key_id']})")
        return 0
    if not args.port:
        raise KinefuseError("give the unit's --port (or --generate FILE)")
    if args.unit is not None and not 0 < args.unit < 256:   # 300 was an internal error (struct)
        raise KinefuseError("--unit must be a unit (MAVLink system) id 1..255")
    if not args.timeout > 0:   # NaN waited for ever for a unit that does not answer
        raise KinefuseError("--timeout must be positive")
    if args.new_key is not None and not args.new_key.strip():   # was: show the key state, install none
        raise KinefuseError("--new-key is empty: give 64 hex digits or a passphrase")
    if args.new_key_file is not None and not args.new_key_file.strip():
        raise KinefuseError("--new-key-file is empty: give the file holding the new key")
    from kinefuse.host.link.connection import open_connection, parse_baud
    from kinefuse.host.link.params import ParamClient
    from kinefuse.host.link.session import Session
    from kinefuse.host.link.signing import set_unit_key
    key = key_from_args(args)
    new = parse_key(args.new_key) if args.new_key else read_key_file(args.new_key_file) if args.new_key_file else None
    if new is not None and not any(new):
        raise KinefuseError("an all-zero key turns signing off: use --clear")
    conn = open_connection(args.port, parse_baud(args.baud))
    with Session(conn, key=key) as s:
        sysid = args.unit
        if sysid is None:
            from kinefuse.host.link.cli_util import first_unit
            sysid = first_unit(s, args.port, args.timeout)
        if new is None and not args.clear:
            res = {"unit": sysid, "signing": bool(ParamClient(s, sysid).get("KF_SIGNING"))}
            text = (f"unit {sysid} requires signed configuration and commands" if res["signing"]
                    else f"unit {sysid} has no signing key (unsigned configuration accepted)")
        else:
            res = set_unit_key(s, sysid, None if args.clear else new)
            text = (f"unit {sysid}: signing key set (key id {res['key_id']})" if res["signing"]
                    else f"unit {sysid}: signing key cleared")
    if args.json:
        print_json(res)
    else:
        con.print(text)
    return 0
