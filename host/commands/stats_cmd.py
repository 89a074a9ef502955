"""``kinefuse stats``: link statistics of a recording, per stream and unit.

Rate achieved vs requested, samples lost (32-bit sample counter, wrap-safe), CRC errors,
device-to-host clock offset and drift (robust fit on the minimum-delay envelope, ppm), delay
above the minimum, latency from TIMESYNC round trips.  The requested rate is the last nonzero one
the unit's KF_UNIT_STATUS gave (0 is the stream off, e.g. the stop at the end of ``record
--start``); after a change of it or a stop and start, the rate is that of the last run at it.

    kinefuse stats walk.kfr
    kinefuse stats walk.kfr --json
"""
from __future__ import annotations

from kinefuse.host.link.cli_util import console, fmt_rate, print_json
from kinefuse.host.console import print_table


def register(subparsers) -> None:
    p = subparsers.add_parser("stats", help="link statistics: rates, loss, errors, clock drift, latency",
                              description=__doc__.split("\n\n")[0].split(": ", 1)[-1])
    p.add_argument("file", metavar="FILE", help=".kfr recording (or raw capture with --raw: no host times)")
    p.add_argument("--raw", action="store_true", help="FILE is a plain MAVLink byte capture")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=run)


def run(args) -> int:
    from kinefuse.host.link import stats
    from kinefuse.host.link.frames import decode_file, unknown_ids_text
    from kinefuse.host.link.cli_util import progress
    from kinefuse.host.commands.decode_cmd import check_input
    check_input(args.file, args.raw)
    with progress(console(args.json), f"decoding {args.file}") as tick:
        result = stats.compute(decode_file(args.file, raw=args.raw, progress=tick))
    if args.json:
        print_json(result)
        return 0
    con = console()
    from rich.table import Table
    con.print(f"{result['file']}" + (f" (started {result['start_utc']})" if result.get("start_utc") else ""))
    fd = result.get("file_damage")
    if fd is not None:
        con.print(f"file: {fd['chunks']:,} chunks, {fd['damaged_chunks']} damaged "
                  f"({fd['recovered_chunks']} recovered), {fd['skipped_bytes']:,} bytes skipped"
                  + (", truncated" if fd["truncated"] else ""))
    for s in result["streams"]:
        con.print(f"\n[bold]stream {s['id']}[/] {s['connection']}: {s['frames_ok']:,} frames, "
                  f"{s['crc_errors']} CRC errors, {s['bytes_skipped']:,} bytes skipped, "
                  f"{s['unknown_msgid']} unknown ids" + unknown_ids_text(s.get("unknown_ids", {}))
                  + (f", {s['bad_incompat']} with unknown incompatibility flags" if s.get("bad_incompat") else "")
                  + (f", {s['host_span_s']:.1f} s" if "host_span_s" in s else ""), soft_wrap=True)
        for u in s["units"]:
            line = f"unit {u['sysid']}"
            if "firmware_version" in u:
                line += f", firmware {u['firmware_version']}"
                if not u["dialect_match"]:
                    line += f" [yellow](dialect {u['dialect_hash']} differs from the host's)[/]"
            con.print(line)
            t = Table("message", "count", "rate Hz", "requested Hz", "ratio", "lost", "loss %", "resets", "reordered",
                      box=None)
            for name, m in u["messages"].items():
                ratio = m.get("rate_ratio")
                style = "yellow" if ratio is not None and ratio < 0.95 else None
                t.add_row(name, f"{m['count']:,}", fmt_rate(m.get("rate_hz")), fmt_rate(m.get("requested_hz")),
                          "-" if ratio is None else f"{ratio:.3f}", str(m.get("samples_lost", "-")),
                          "-" if "loss_fraction" not in m else f"{100 * m['loss_fraction']:.3f}",
                          str(m.get("resets", "-")), str(m.get("reordered", "-")), style=style)
            print_table(t, con)
            for name, m in u["messages"].items():
                note = rate_note(m)
                if note:
                    con.print(f"  {name}: {note}", soft_wrap=True)
            c = u.get("clock")
            if c:
                dm = c["delay_above_min_ms"]
                style = "[yellow]" if c.get("warnings") else ""
                con.print(f"  {style}clock ({c['reference']}, {c['points']:,} points over {c['span_s']:.1f} s"
                          + (f", first {c['excluded_leading']} left out" if c.get("excluded_leading") else "") + "): "
                          f"drift {c['drift_ppm']:+.1f} ppm (unit vs host), offset {c['offset_s']:.6f} s; "
                          f"delay above minimum median {dm['median']:.2f} ms, p95 {dm['p95']:.2f} ms, "
                          f"max {dm['max']:.2f} ms" + ("[/]" if style else ""))
            lat = u.get("latency")
            if lat:
                r = lat["timesync_rtt_ms"]
                con.print(f"  latency: TIMESYNC round trip min {r['min']:.2f} / median {r['median']:.2f} ms "
                          f"({r['count']} replies); one-way estimate {lat['one_way_estimate_ms']:.2f} ms")
            rep = u.get("unit_reported")
            if rep:
                # an extension counter an older firmware does not send: n/a, not a claimed 0
                con.print("  unit reports: " + ", ".join(
                    f"{k} {'n/a' if v is None else v}" for k, v in rep.items()
                    if v is not None or k in stats.STATUS_EXTENSIONS), soft_wrap=True)
        for e in s.get("statustexts", ()):
            # the unit's text is not rich markup; WARNING or worse in yellow
            con.print("  " + stats.statustext_line(e), style="yellow" if e["severity"] <= 4 else None,
                      soft_wrap=True, markup=False)
    if result["warnings"]:
        con.print()
    for w in result["warnings"]:
        con.print(f"[yellow]warning:[/] {w}")
    return 0


def rate_note(m: dict) -> str:
    """What a message's rate is measured over when the unit's statuses show its requested rate
    changing or its stream turned off (requested 0) and on again; whether it was off at the end.
    "" when the rate is that of the whole recording."""
    parts = []
    if m.get("requested_changes"):
        parts.append(f"the requested rate changed {m['requested_changes']} time(s)")
    if m.get("restarts"):
        parts.append(f"streaming turned off and on again {m['restarts']} time(s)")
    until = m.get("rate_until_device_s")
    stopped = bool(m.get("stopped_at_end"))
    # on again after the unit's last status (which said off): those samples' rate no status told
    later = "" if stopped else " (on again after the unit's last status: those samples not counted)"
    if parts:
        return (", ".join(parts) + f"; its rate is that from unit time {m['rate_from_device_s']:.1f} s on"
                + ("" if until is None else f", until it stopped before {until:.1f} s" + later))
    if until is not None:
        if stopped:
            return f"streaming off at the end (stopped before unit time {until:.1f} s)"
        return f"its rate is that until it stopped before unit time {until:.1f} s" + later
    return "streaming off at the end" if stopped else ""
