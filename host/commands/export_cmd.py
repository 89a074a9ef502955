"""``kinefuse export``: one CSV per message type (units in the column names, device and host times).

    kinefuse export walk.kfr --out walk_csv/
    kinefuse export walk.kfr --out walk_csv/ --messages KF_RAW_SAMPLE,KF_ORIENTATION
"""
from __future__ import annotations

from pathlib import Path

from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.cli_util import console, print_json
from kinefuse.host.outputs import add_force_arg, check_output_dir


def register(subparsers) -> None:
    p = subparsers.add_parser("export", help="export a recording to CSV files (one per message type)",
                              description=__doc__.split("\n\n")[0].split(": ", 1)[-1])
    p.add_argument("file", metavar="FILE", help=".kfr recording (or raw capture with --raw)")
    p.add_argument("--out", required=True, metavar="DIR", help="output folder (created)")
    p.add_argument("--messages", metavar="LIST", help="comma-separated message names (default: all)")
    p.add_argument("--raw", action="store_true", help="FILE is a plain MAVLink byte capture")
    p.add_argument("--json", action="store_true", help="print one JSON object listing the files")
    add_force_arg(p, "CSV files an earlier export left in DIR")
    p.set_defaults(func=run)


def run(args) -> int:
    from rich.progress import Progress
    from kinefuse.host.link.export import export_csv
    from kinefuse.host.link.frames import decode_file
    con = console(args.json)
    messages = None if args.messages is None else [m.strip() for m in args.messages.split(",") if m.strip()]
    if messages == []:   # --messages "" (an empty variable) exported every message
        raise KinefuseError("--messages names no message: give names such as KF_RAW_SAMPLE,KF_ORIENTATION "
                            "(or leave it out for all)")
    from kinefuse.host.commands.decode_cmd import check_input
    check_input(args.file, args.raw)
    if not args.out.strip():   # Path("") is the current folder: the CSVs landed there
        raise KinefuseError("--out is empty: give the folder for the CSV files")
    check_output_dir(args.out, args.force, pattern="*.csv")
    with Progress(console=con, transient=True, disable=not con.is_terminal) as prog:   # piped: no blank line
        task = prog.add_task("decoding", total=None)
        df = decode_file(args.file, raw=args.raw)
        out = Path(args.out)
        before = set(out.glob("*.csv")) if out.is_dir() else set()
        total = sum(a.size for ds in df.streams.values() for a in ds.arrays.values())
        prog.update(task, description="writing CSV", total=max(1, total), completed=0)
        files = export_csv(df, args.out, messages, progress=lambda name, n: prog.advance(task, n))
    warnings = _warnings(df)
    others = sorted(before - {Path(f["file"]) for f in files})
    if others:   # an earlier export's files would pass for this recording's
        warnings.append(f"{out} also holds {len(others)} CSV file(s) this export did not write "
                        f"({', '.join(p.name for p in others[:3])}{', ...' if len(others) > 3 else ''}): "
                        f"from an earlier export?")
    for w in warnings:
        con.print(f"[yellow]warning:[/] {w}")
    if args.json:
        print_json({"file": str(df.path), "out": str(args.out), "files": files, "warnings": warnings})
    else:
        for f in files:
            con.print(f"{f['file']}: {f['rows']:,} rows")
        if not files:
            con.print("no messages to export" + _held_text(df, messages), soft_wrap=True, markup=False)
    return 0


def _held_text(df, messages) -> str:
    """For --messages naming none the file holds: what it does hold."""
    if not messages:
        return ""
    from kinefuse.host.link.spec import kinefuse_dialect
    d = kinefuse_dialect()
    held = {mid for ds in df.streams.values() for mid, a in ds.arrays.items() if a.size}
    names = sorted(d[mid].name for mid in held if mid in d)
    return (f": {df.path} holds no {', '.join(m.upper() for m in messages)}"
            + (f" (it holds {', '.join(names)})" if names else " (it holds no messages)"))


def _warnings(df) -> list[str]:
    """What the exported CSVs miss: a truncated file or damaged chunks (as decode and stats say),
    and units whose frames are two units' mixed (one system id on one link)."""
    import numpy as np
    from kinefuse.host.link.spec import kinefuse_dialect
    from kinefuse.host.link.stats import (crc_extra_text, interleaved_clocks, interleaved_text,
                                          stream_crc_extra_mismatches)
    out, mixed_units = [], set()
    for sid, ds in sorted(df.streams.items()):
        # a message of another dialect version fails every CRC: none of it is in the CSVs
        out += [f"stream {sid}: {crc_extra_text(m)}: missing from the CSVs"
                for m in stream_crc_extra_mismatches(df, sid) or ()]
        for mid, arr in sorted(ds.arrays.items()):
            spec = kinefuse_dialect().get(mid)
            if spec is None or not spec.name.startswith("KF_") or "time_boot_us" not in arr.dtype.names:
                continue
            for sysid in np.unique(arr["_sysid"]):
                if (sid, int(sysid)) in mixed_units:   # one warning per unit
                    continue
                a = arr[arr["_sysid"] == sysid]
                mixed = interleaved_clocks(a["time_boot_us"],
                                           a["sample_counter"] if "sample_counter" in a.dtype.names else None)
                if mixed is not None:
                    mixed_units.add((sid, int(sysid)))
                    out.append(f"stream {sid} " + interleaved_text(int(sysid), spec.name, mixed,
                                                                   "in one CSV with one t_s clock"))
    rec = df.recording
    if rec is None:
        return out
    if rec.truncated:
        out.append(f"{df.path}: the recording is truncated (ends inside a chunk): exported up to the cut")
    if rec.damaged_chunks:
        from kinefuse.host.link.stats import damage_text
        out.append(f"{df.path}: {damage_text(rec)}: frames in the damaged parts are missing from "
                   f"the CSVs")
    return out
