"""``kinefuse params``: read and write a unit's parameters (MAVLink parameter protocol).

    kinefuse params --port /dev/ttyUSB0                       # list all
    kinefuse params --port /dev/ttyUSB0 --describe            # ... with unit, range and meaning
    kinefuse params --port /dev/ttyUSB0 --get KF_RATE_HZ
    kinefuse params --port /dev/ttyUSB0 --set KF_RATE_HZ=500 --set KF_MAG_ENABLE=0
    kinefuse params --port /dev/ttyUSB0 --key-file unit.key --set KF_RATE_HZ=500   # signed writes

A unit with a signing key (``kinefuse signing``) refuses unsigned writes: a refused write is a
one-line error with exit status 2.  Reading needs no key: reads go unsigned even with --key
(a keyed unit answers them, also right after a power cut); only writes are signed.
"""
from __future__ import annotations

import math

from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.cli_util import console, print_json
from kinefuse.host.link.signing import add_key_args, key_from_args


def register(subparsers) -> None:
    p = subparsers.add_parser("params", help="list, read or write unit parameters",
                              description=__doc__.split("\n\n")[0].split(": ", 1)[-1])
    p.add_argument("--port", required=True, metavar="CONN", help="serial port or connection string")
    p.add_argument("--baud", default=921600, metavar="BAUD", help="serial baud rate (default 921600)")
    p.add_argument("--unit", type=int, metavar="SYSID", help="system id of the unit (default: first heartbeat)")
    p.add_argument("--get", action="append", default=[], metavar="NAME", help="read one parameter (repeatable)")
    p.add_argument("--set", action="append", default=[], metavar="NAME=VALUE", help="write one parameter (repeatable)")
    p.add_argument("--timeout", type=float, default=3.0, metavar="S", help="wait this long for the unit (default 3)")
    add_key_args(p, "parameter writes")
    p.add_argument("--describe", action="store_true",
                   help="also show each parameter's unit, range, default and meaning (from this "
                        "host's firmware tables: a unit with other firmware may differ)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=run)


def _parse_set(items: list[str]) -> list[tuple[str, float | int]]:
    """``NAME=VALUE`` items, all checked before anything is written: one-line errors for a
    malformed item, a name given twice, a non-finite value and, for the parameters the unit's
    generated table declares as choices (e.g. KF_FL_MODE: 0 = 6D, 1 = 9D), a value that is
    not one of them (the unit refuses those too)."""
    out: list[tuple[str, float | int]] = []
    for item in items:
        name, sep, value = item.partition("=")
        name, value = name.strip(), value.strip()
        if not sep or not name or not value:
            raise KinefuseError(f"bad --set {item!r}: expected NAME=VALUE")
        if any(n == name for n, _ in out):
            raise KinefuseError(f"--set {name} given twice: give each parameter once")
        try:
            v = int(value, 0)
        except ValueError:
            try:
                v = float(value)
            except ValueError:
                raise KinefuseError(f"bad value in --set {item!r}: not a number") from None
            if not math.isfinite(v):
                raise KinefuseError(f"bad value in --set {item!r}: must be finite")
        choices = _choices().get(name)
        if choices and float(v) not in choices:
            raise KinefuseError(f"--set {name}={value}: {name} is a choice: "
                                f"{', '.join(f'{c:g}' for c in choices)}")
        out.append((name, v))
    return out


def _choices() -> dict[str, tuple]:
    """MAVLink name -> allowed values of the generated parameters declared with choices."""
    try:
        from kinefuse.firmware.apptables import parameter_table
        return {r["name"]: r["choices"] for r in parameter_table() if r.get("choices")}
    except KinefuseError:       # generated models missing: the unit still checks
        return {}


def describe(names) -> dict[str, dict]:
    """MAVLink name -> {unit, min, max, default, choices, meaning} for the names this host's
    firmware tables know (the generated parameter table and the application's own rows); names
    they do not know are left out."""
    from kinefuse.firmware import apptables
    try:
        table = {r["name"]: r for r in apptables.parameter_table()}
    except KinefuseError:       # generated models missing: the application's own rows only
        table = {}
    app = apptables.app_parameters()
    out: dict[str, dict] = {}
    for n in names:
        if n in table:
            r = table[n]
            owner = r["owner"] + (" (sensor 1)" if r.get("sensor") == 1 else "")
            out[n] = {"unit": r["unit"], "min": r["min"], "max": r["max"], "default": r["default"],
                      "choices": list(r["choices"]), "meaning": f"{owner} {r['field']}: {r['doc']}"}
        elif n in app:
            r = app[n]
            out[n] = {"unit": "", "min": r["min"], "max": r["max"], "default": r["default"],
                      "choices": [], "meaning": r["doc"]}
    return out


def _describe_text(d: dict | None) -> str:
    from kinefuse.host.commands.filters_cmd import range_text
    if d is None:
        return "  (not in this host's firmware tables)"
    num = lambda v: str(v) if isinstance(v, int) else f"{v:g}"   # noqa: E731 (counts stay whole)
    rng = ("one of " + " | ".join(num(c) for c in d["choices"]) if d["choices"]
           else range_text(d["min"], d["max"]))
    unit = f"{d['unit']}, " if d["unit"] else ""
    return f"  ({unit}{rng}, default {num(d['default'])}) {d['meaning']}"


def run(args) -> int:
    from kinefuse.host.link.connection import open_connection, parse_baud
    from kinefuse.host.link.params import PERMISSION_DENIED, ParamClient, ParamError
    from kinefuse.host.link.session import Session
    if not args.timeout > 0:   # NaN too: "parameter list incomplete: ? of None parameters missing"
        raise KinefuseError("--timeout must be positive")
    if args.unit is not None and not 0 < args.unit < 256:   # 300 was an internal error (struct)
        raise KinefuseError("--unit must be a unit (MAVLink system) id 1..255")
    sets = _parse_set(args.set)
    key = key_from_args(args)
    conn = open_connection(args.port, parse_baud(args.baud))
    with Session(conn, key=key) as s:
        sysid = args.unit
        if sysid is None:
            from kinefuse.host.link.cli_util import first_unit
            sysid = first_unit(s, args.port, args.timeout)
        client = ParamClient(s, sysid)
        result: dict = {"unit": sysid}
        if sets:
            # every name read and every value encoded for its type before the first write:
            # --set KF_RATE_HZ=500 --set FOO=1 wrote KF_RATE_HZ, then failed on FOO
            from kinefuse.host.link.params import encode_value
            for name, _value in sets:
                if len(name.encode()) > 16:
                    raise ParamError(f"unit {sysid}: parameter name {name!r} is longer than 16 "
                                     f"characters (nothing written)")
            for name, value in sets:
                try:
                    client.get(name)
                    try:
                        encode_value(value, client.types[name])
                    except ParamError as exc:
                        raise ParamError(f"--set {name}: {exc}") from None
                except ParamError as exc:
                    # reads go unsigned (params.ParamClient): no answer is not a key matter
                    raise ParamError(f"unit {sysid}: {exc} (nothing written)", exc.code) from None
            result["set"] = {}
            for name, value in sets:
                try:
                    result["set"][name] = client.set(name, value)
                    if name in client.granted:
                        result.setdefault("granted", {})[name] = {"asked": client.granted[name][0],
                                                                   "applied": client.granted[name][1]}
                except ParamError as exc:
                    if exc.code == PERMISSION_DENIED:
                        hint = ("the key given is not the unit's" if key is not None
                                else "the unit requires signed writes: give its key with --key/--key-file")
                        raise ParamError(f"unit {sysid}: {exc} ({hint})", exc.code) from None
                    if exc.code is None and key is not None and exc.refused is None:
                        raise ParamError(f"unit {sysid}: {exc} (a unit drops frames signed with a key "
                                         f"other than its own: is it the right key?)") from None
                    raise ParamError(f"unit {sysid}: {exc}", exc.code, exc.refused) from None
        if args.get:
            result["get"] = {name: client.get(name) for name in args.get}
        if not sets and not args.get:
            result["params"] = client.fetch_all(timeout=max(args.timeout, 5.0))
    info = None
    if args.describe:
        info = describe([n for k in ("set", "get", "params") for n in result.get(k, {})])
        result["describe"] = info
    if args.json:
        print_json(result)
        return 0
    con = console()
    for key in ("set", "get", "params"):
        for name, value in result.get(key, {}).items():
            g = result.get("granted", {}).get(name) if key == "set" else None
            note = "  (written)" if key == "set" else ""
            if g is not None:   # applied with the sensor's rate: not a refusal
                note = (f"  (written: {g['asked']} asked, the unit's sensor delivers {g['applied']} Hz instead, "
                        f"now its {name})")
            con.print(f"{name} = {value}" + note
                      + (_describe_text(info.get(name)) if info is not None else ""), markup=False,
                      soft_wrap=True)
    return 0
