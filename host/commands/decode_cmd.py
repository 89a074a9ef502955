"""``kinefuse decode``: summary of a recording (or of a raw MAVLink capture with --raw).

    kinefuse decode walk.kfr
    kinefuse decode walk.kfr --show 5          # also print the first 5 messages of each type
    kinefuse decode capture.bin --raw --json
"""
from __future__ import annotations

import numpy as np

from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.cli_util import console, fmt_bytes, print_json
from kinefuse.host.console import print_table


def register(subparsers) -> None:
    p = subparsers.add_parser("decode", help="summarise a .kfr recording or raw MAVLink capture",
                              description=__doc__.split("\n\n")[0].split(": ", 1)[-1])
    p.add_argument("file", metavar="FILE", help=".kfr recording (or raw capture with --raw)")
    p.add_argument("--raw", action="store_true", help="FILE is a plain MAVLink byte capture")
    p.add_argument("--show", type=int, default=0, metavar="N", help="print the first N messages of each type")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=run)


def summarize(df) -> dict:
    from kinefuse.host.link.dialect import DIALECT_HASH
    from kinefuse.host.link.spec import kinefuse_dialect
    d = kinefuse_dialect()
    rec = df.recording
    head = df.header
    out = {"file": str(df.path), "format": head.get("format"), "start_utc": head.get("start_utc"),
           "note": head.get("note"), "streams": []}
    if rec is not None:
        dialect = head.get("dialect", {})
        out["dialect_hash"] = dialect.get("hash")
        out["dialect_match"] = dialect.get("hash") == f"0x{DIALECT_HASH():08X}"
        out["chunks"] = rec.chunks
        out["damaged_chunks"] = rec.damaged_chunks
        out["recovered_chunks"] = rec.recovered_chunks
        out["skipped_bytes"] = rec.skipped_bytes
        out["truncated"] = rec.truncated
        out["host"] = head.get("host", {}).get("hostname")
    for sid, ds in sorted(df.streams.items()):
        s = {"id": sid, "connection": ds.info.get("connection"), "bytes": ds.rx_bytes,
             "counters": ds.counters.as_dict(), "messages": {}, "events": [], "units": {},
             "unknown_ids": {str(k): v for k, v in sorted(ds.unknown_ids.items())}}
        for mid, arr in sorted(ds.arrays.items()):
            s["messages"][d.get(mid).name] = int(arr.size)
            for sysid in np.unique(arr["_sysid"]):
                s["units"].setdefault(str(int(sysid)), 0)
                s["units"][str(int(sysid))] += int(np.sum(arr["_sysid"] == sysid))
        host = [h for h in ds.host_ns.values() if h is not None and h.size]
        if host:
            s["host_span_s"] = (max(int(h.max()) for h in host) - min(int(h.min()) for h in host)) / 1e9
        from kinefuse.host.link.stats import statustexts, stream_crc_extra_mismatches
        s["statustexts"] = statustexts(ds, df.start_monotonic_ns)   # what the units said (STATUSTEXT)
        mm = stream_crc_extra_mismatches(df, sid)
        if mm is not None:
            s["crc_extra_mismatch"] = mm
        for m in ds.meta:
            if m.get("type") in ("event", "warning"):
                s["events"].append({k: v for k, v in m.items() if k != "t_ns"})
            elif m.get("type") == "unit_status":
                s.setdefault("firmware", {})[str(m.get("sysid"))] = m.get("firmware_version_text")
            elif m.get("type") == "params":
                s.setdefault("params", {})[str(m.get("sysid"))] = m.get("params")
        out["streams"].append(s)
    return out


def check_input(path, raw: bool) -> None:
    """What decode, export and stats refuse before decoding, in one line:

    - an empty FILE argument (it was read as the current folder);
    - a device (a serial port given as FILE with --raw hung reading it to its end; /dev/zero
      filled the memory) or a pipe (see below);
    - an empty file (a .kfr said "not a kinefuse recording; use --raw", with --raw it was
      summarised as 0 frames);
    - ``--raw`` on a .kfr recording or a .tlog: the decoder reads those by their own format
      whatever --raw says, so the recording's summary, CSVs (with host times) or statistics
      came back instead of the raw capture asked for."""
    from pathlib import Path
    from kinefuse.host.link.frames import is_recording
    if not str(path).strip():
        raise KinefuseError("FILE is empty: give a .kfr recording (or a raw capture with --raw)")
    p = Path(path)
    if p.is_char_device() or p.is_block_device():   # a serial port, /dev/zero: read to an end that never came
        raise KinefuseError(f"{p} is a device, not a file: decode, export and stats read recordings and "
                            f"capture files (record a port with kinefuse record --port {p})")
    if p.exists() and not p.is_dir() and not p.is_file():
        # a pipe (/dev/stdin, <(...)): the file is opened twice (its magic, then its bytes), and
        # the first read took a buffer's worth: 10 of 100 frames were decoded, without a word
        raise KinefuseError(f"{p} is a pipe, not a file: save it to a file first (it is read more than once)")
    if not p.is_file():
        return      # the decoder says what is wrong with it (missing, a directory)
    if p.stat().st_size == 0:
        raise KinefuseError(f"{p} is empty (0 bytes): nothing was recorded in it")
    if not raw:
        return
    if is_recording(p):
        raise KinefuseError(f"{p} is a kinefuse recording (.kfr), not a plain MAVLink capture: "
                            f"leave out --raw (it reads the file as its chunks, with host times)")
    if p.suffix.lower() == ".tlog":
        raise KinefuseError(f"{p} is read as a MAVLink telemetry log (.tlog, time-stamped frames), "
                            f"not a plain MAVLink capture: leave out --raw (or rename a plain capture)")


def run(args) -> int:
    from kinefuse.host.link.cli_util import progress
    from kinefuse.host.link.frames import decode_file, unknown_ids_text
    if args.show < 0:
        raise KinefuseError("--show must be 0 or more (messages per type)")
    check_input(args.file, args.raw)
    with progress(console(args.json), f"decoding {args.file}") as tick:
        df = decode_file(args.file, raw=args.raw, progress=tick)
    summary = summarize(df)
    if args.json:
        if args.show:
            summary["first_messages"] = _first(df, args.show)
        print_json(summary)
        return 0
    con = console()
    from rich.table import Table
    head = f"{summary['file']}: {summary['format']}"
    if summary.get("start_utc"):
        head += f", started {summary['start_utc']}"
    con.print(head)
    if summary.get("note"):
        con.print(f"note: {summary['note']}")
    if df.recording is not None:
        if not summary["dialect_match"]:
            con.print(f"[yellow]warning:[/] recorded with dialect {summary['dialect_hash']}, this kinefuse has "
                      f"a different one: messages may decode wrongly")
        if summary["truncated"]:
            con.print("[yellow]note:[/] the file ends inside a chunk (recorder killed?): decoded up to the end")
        if summary["damaged_chunks"]:
            from kinefuse.host.link.stats import damage_text
            con.print(f"[yellow]warning:[/] {damage_text(df.recording)}")
    for s in summary["streams"]:
        c = s["counters"]
        con.print(f"\nstream {s['id']} ({s['connection']}): {fmt_bytes(s['bytes'])}, {c['frames_ok']:,} frames, "
                  f"{c['crc_errors']} CRC errors, {c['bytes_skipped']:,} bytes skipped, "
                  f"{c['unknown_msgid']} unknown ids" + unknown_ids_text({int(k): v for k, v in s["unknown_ids"].items()})
                  + (f", {c['bad_incompat']} with unknown incompatibility flags" if c["bad_incompat"] else "")
                  + (f", {s['host_span_s']:.1f} s" if "host_span_s" in s else ""), soft_wrap=True)
        if s.get("firmware"):
            con.print("units: " + ", ".join(f"{k} (firmware {v})" for k, v in s["firmware"].items()))
        t = Table("message", "count", box=None)
        for name, n in s["messages"].items():
            t.add_row(name, f"{n:,}")
        print_table(t, con)
        for e in s["events"]:
            con.print(f"  {e.get('type')}: {e.get('text') or e.get('event')} {e.get('error') or ''}".rstrip())
        from kinefuse.host.link.stats import crc_extra_text, statustext_line
        for e in s["statustexts"]:   # the unit's text is not rich markup
            con.print("  " + statustext_line(e), style="yellow" if e["severity"] <= 4 else None,
                      markup=False, soft_wrap=True)
        for m in s.get("crc_extra_mismatch") or ():
            con.print(f"[yellow]warning:[/] {crc_extra_text(m)}", soft_wrap=True)
    if args.show:
        for name, rows in _first(df, args.show).items():
            con.print(f"\n[bold]{name}[/]")
            for r in rows:
                con.print("  " + ", ".join(f"{k}={v}" for k, v in r.items()))
    return 0


def _first(df, n: int) -> dict:
    from kinefuse.host.link.export import bit_names, bitmask_fields
    from kinefuse.host.link.spec import kinefuse_dialect
    d = kinefuse_dialect()
    out = {}
    for sid, ds in sorted(df.streams.items()):
        for mid, arr in sorted(ds.arrays.items()):
            rows = []
            masks = bitmask_fields(d.get(mid).name)
            for r in arr[:n]:
                row = {"stream": sid}
                for name in arr.dtype.names:
                    v = r[name]
                    row[name] = v.tolist() if isinstance(v, np.ndarray) else (
                        v.decode("utf-8", "replace").rstrip("\0") if isinstance(v, bytes) else v.item())
                    if name in masks:   # the status bits named (e.g. VALID|NUMERIC_RESET)
                        row[name + "_bits"] = bit_names(masks[name], row[name])
                rows.append(row)
            out.setdefault(d.get(mid).name, []).extend(rows)
    return out
