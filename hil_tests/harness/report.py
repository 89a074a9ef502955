"""``kinefuse sil report``: the scenario set through every loop; Markdown + PNG.

For every IMU filter and scenario: orientation errors against ground truth (BROAD metric:
RMSE of total / heading / inclination over the scored samples, degrees) for f32 and q (and the
float64 reference with ``with_ref``); the bit-exactness table (every loop of a number system
compared bit for bit with its Python model, first differing sample with its inputs); and the
cost table of ``kinefuse bench cost --json`` when given.
"""
from __future__ import annotations

import json
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from kinefuse.hil_tests.harness import compare, loops, motion
from kinefuse.hil_tests.harness.scenarios import Case


@dataclass
class Report:
    cases: list[str]
    filters: list[str]
    errors: dict = field(default_factory=dict)      # (filter, case, system) -> {total, heading, inclination}
    bitexact: list = field(default_factory=list)    # rows
    cost: list = field(default_factory=list)
    seconds: float = 0.0
    firmware_speed: list = field(default_factory=list)   # per firmware loop: samples, seconds streaming

    def as_dict(self) -> dict:
        return {"cases": self.cases, "filters": self.filters,
                "errors": [{"filter": f, "case": c, "system": s, **v}
                           for (f, c, s), v in self.errors.items()],
                "bitexact": self.bitexact, "cost": self.cost, "seconds": self.seconds,
                "firmware_speed": self.firmware_speed}

    @property
    def all_bitexact(self) -> bool:
        return all(r["mismatch"] is None and not r.get("error") for r in self.bitexact)


def rmse_errors(q_est: np.ndarray, case: Case) -> dict[str, float]:
    mask = case.movement & np.all(np.isfinite(case.q_true), axis=1)
    if not mask.any():                     # static scenarios: score every sample with a reference
        mask = np.all(np.isfinite(case.q_true), axis=1)
    if not mask.any():      # no reference at all (a BROAD head before the optical markers
        # are seen): was NaN with numpy's "Mean of empty slice" warnings, and NaN in the JSON
        return {"total": None, "heading": None, "inclination": None, "scored": 0}
    tot, hd, inc = motion.errors_deg(q_est[mask], case.q_true[mask])
    return {"total": float(np.sqrt(np.mean(tot ** 2))), "heading": float(np.sqrt(np.mean(hd ** 2))),
            "inclination": float(np.sqrt(np.mean(inc ** 2))), "scored": int(mask.sum())}


def build_report(cases: list[Case], filters: list[str], loop_names: dict[str, list[str]] | None = None,
                 with_ref: bool = False, qemu: bool = True, firmware: bool = False,
                 progress: Callable[[str], None] | None = None, pil_samples: int | None = None,
                 sil_samples: int = 0, jobs: int = 1) -> Report:
    """Every filter and case through the loops of its number systems.  ``firmware``: also the
    unit application (SIL; PIL when ``qemu``) on the first ``sil_samples`` / ``pil_samples``
    samples of each case (0: the whole case; ``pil_samples`` None: ``firmware.PIL_SAMPLES``),
    one unit per loop, ``jobs`` loops at a time."""
    t0 = time.perf_counter()
    rep = Report([c.name for c in cases], filters)
    for name in filters:
        for case in cases:
            if with_ref:
                if progress:
                    progress(f"{name} / {case.name}: reference")
                ref = loops.run_loop("ref", name, case.inputs)
                rep.errors[(name, case.name, "ref")] = rmse_errors(ref["q"], case)
            for system in loops.systems(name):
                lps = (loop_names or {}).get(system) or loops.bitexact_loops(name, system, qemu=qemu)
                outs, errors = {}, {}
                for lp in lps:
                    if progress:
                        progress(f"{name} / {case.name}: {lp}")
                    try:
                        outs[lp] = loops.run_loop(lp, name, case.inputs)
                    except Exception as exc:        # reported in the table, not hidden
                        errors[lp] = f"{type(exc).__name__}: {exc}"
                first = next(iter(outs), None)
                for lp in lps:
                    row = {"filter": name, "case": case.name, "system": system, "model": first,
                           "loop": lp, "samples": case.n, "mismatch": None, "error": errors.get(lp)}
                    if lp in outs and first is not None and lp != first:
                        m = compare.compare(first, outs[first], lp, outs[lp], case.inputs)
                        row["mismatch"] = m.as_dict() if m else None
                    if lp != first:
                        rep.bitexact.append(row)
                if first is not None:
                    q = loops.decode(name, first, outs[first])["q"]
                    rep.errors[(name, case.name, system)] = rmse_errors(q, case)
    if firmware:
        _firmware_rows(rep, cases, filters, qemu, progress, pil_samples, sil_samples, jobs)
    rep.seconds = time.perf_counter() - t0
    return rep


def _firmware_rows(rep: Report, cases: list[Case], filters: list[str], qemu: bool, progress,
                   pil_samples: int | None, sil_samples: int, jobs: int) -> None:
    """The unit application in the loop (SIL; PIL when ``qemu``) against the unit model: one
    unit per loop running every filter and case; the model's answers computed once per filter,
    number system, case and length."""
    from concurrent.futures import ThreadPoolExecutor

    from kinefuse.hil_tests.harness import firmware as fw
    if pil_samples is None:
        pil_samples = fw.PIL_SAMPLES
    by_loop: dict[str, list[tuple[str, str]]] = {}
    for name in filters:
        for system in loops.systems(name):
            for lp in fw.firmware_loops(name, system):
                if lp.startswith("pil-") and not qemu:
                    continue
                by_loop.setdefault(lp, []).append((name, system))
    # the models' answers first, in this thread: generated Python models hold the GIL for long
    # stretches, which would starve the streaming threads (each poll of a unit waits for it)
    lengths = {lp: (pil_samples if lp.startswith("pil-") else sil_samples) for lp in by_loop}
    cache: dict = {}
    for lp, todo in by_loop.items():
        for name, system in todo:
            for case in cases:
                hil = fw.HilInput.from_case(case, lengths[lp] or None)
                key = (name, system, case.name, len(hil.time_us))
                if key not in cache:
                    if progress:
                        progress(f"{name} / {case.name}: {system} unit model")
                    cache[key] = fw.compared_outputs(system, fw.expected(name, system, hil), True)

    def expected(name, system, case, hil):
        return cache[(name, system, case.name, len(hil.time_us))]

    def run(lp):
        rows = []
        n = lengths[lp]
        try:
            runner = fw.UnitRunner(lp, timeout=120.0).__enter__()
        except Exception as exc:            # reported in the table, not hidden
            for name, system in by_loop[lp]:
                rows += [_fw_row(name, c, system, lp, 0, error=f"{type(exc).__name__}: {exc}") for c in cases]
            return rows, None
        try:
            for name, system in by_loop[lp]:
                for case in cases:
                    if progress:
                        progress(f"{name} / {case.name}: {lp}")
                    hil = fw.HilInput.from_case(case, n or None)
                    row = _fw_row(name, case, system, lp, len(hil.time_us))
                    try:
                        t0 = runner.seconds
                        got = fw.compared_outputs(system, runner.run(name, hil), False)
                        row["seconds"] = runner.seconds - t0
                        m = compare.compare(f"{system} unit model", expected(name, system, case, hil), lp, got,
                                            hil.inputs())
                        row["mismatch"] = m.as_dict() if m else None
                    except Exception as exc:    # reported in the table, not hidden
                        row["error"] = f"{type(exc).__name__}: {exc}"
                    rows.append(row)
            speed = {"loop": lp, "samples": runner.samples, "seconds": runner.seconds,
                     "samples_per_s": runner.samples / runner.seconds if runner.seconds else None}
        finally:
            runner.__exit__(None, None, None)
        return rows, speed

    order = sorted(by_loop, key=lambda lp: not lp.startswith("pil-"))   # the long ones first
    for lp in order:
        if lp.startswith("pil-"):
            if progress:
                progress(f"building the {lp} image")
            try:
                fw.pil_image(lp)            # cross-built here, not by several threads at once
            except Exception:               # noqa: S110 - run() reports it per row
                pass
    with ThreadPoolExecutor(max(1, jobs)) as pool:
        results = list(pool.map(run, order))
    for rows, speed in results:
        rep.bitexact.extend(rows)
        if speed is not None:
            rep.firmware_speed.append(speed)


def _fw_row(name, case, system, lp, n, error=None) -> dict:
    return {"filter": name, "case": case.name, "system": system, "model": f"{system} unit model",
            "loop": lp, "samples": n, "mismatch": None, "error": error}


def run_time_text(seconds: float) -> str:
    """The report's wall-clock time, said as such: "(0 s)" after a short run read as scenarios
    of no length."""
    return f"run time {seconds:,.0f} s" if seconds >= 10 else f"run time {seconds:.1f} s"


def write_markdown(rep: Report, out_dir: Path, png_name: str | None, path: Path | None = None) -> Path:
    """``out_dir``/sil_report.md, or ``path`` (the temporary name of a staged write)."""
    lines = ["# kinefuse SIL/PIL report", "",
             f"{len(rep.filters)} filters × {len(rep.cases)} scenarios, {run_time_text(rep.seconds)}. "
             "Errors: BROAD metric (e = q_est ⊗ q_true⁻¹; RMSE over scored samples; degrees; "
             "ENU earth frame).", ""]
    systems = sorted({s for (_f, _c, s) in rep.errors}, key=["ref", "f32", "q"].index)
    lines += ["## Orientation error against ground truth (total RMSE, degrees)", "",
              "Each cell: total (h heading, i inclination), RMSE in degrees.", ""]
    for system in systems:
        lines += [f"### {system}", "", "| scenario | " + " | ".join(rep.filters) + " |",
                  "|---|" + "---:|" * len(rep.filters)]
        for c in rep.cases:
            cells = []
            for f in rep.filters:
                e = rep.errors.get((f, c, system))
                cells.append("–" if not e else "n/a (no reference sample)" if e["total"] is None else
                             f"{e['total']:.2f} (h {e['heading']:.2f}, i {e['inclination']:.2f})")
            lines.append(f"| {c} | " + " | ".join(cells) + " |")
        lines.append("")
    lines += ["## Bit-exactness (every output bit of every sample against the Python model)", "",
              "| filter | format | loop | scenarios | samples | identical | first mismatch |",
              "|---|---|---|---:|---:|---|---|"]
    groups: dict = {}
    for r in rep.bitexact:
        groups.setdefault((r["filter"], r["system"], r["loop"]), []).append(r)
    for (f, s, lp), rows in groups.items():
        bad = [r for r in rows if r["mismatch"] or r["error"]]
        first = ""
        if bad:
            r = bad[0]
            first = (f"{r['case']}: {r['error']}" if r["error"] else
                     f"{r['case']} sample {r['mismatch']['sample']} ({', '.join(r['mismatch']['fields'])}); "
                     f"inputs {r['mismatch']['inputs']}")
        lines.append(f"| {f} | {s} | {lp} vs {rows[0]['model']} | {len(rows)} | "
                     f"{sum(r['samples'] for r in rows)} | {'yes' if not bad else 'NO'} | {first} |")
    lines.append("")
    if rep.firmware_speed:
        lines += ["Firmware loops (unit application, HIL_SENSOR in over its UART): samples streamed per "
                  "second of streaming (configuration excluded).", "",
                  "| loop | samples | seconds | samples/s |", "|---|---:|---:|---:|"]
        for r in rep.firmware_speed:
            sps = "" if r["samples_per_s"] is None else f"{r['samples_per_s']:,.0f}"
            lines.append(f"| {r['loop']} | {r['samples']:,} | {r['seconds']:.1f} | {sps} |")
        lines.append("")
    if rep.cost:
        lines += ["## Cost per update", "",
                  "Instructions exact (QEMU); cycles and µs at 64 MHz are a Cortex-M4 table estimate; "
                  "bytes added at -Os (own = the filter's object/state only).", "",
                  "| impl | filter | sensors | format | target | instructions | est. cycles | est. µs | flash | own flash | RAM | own RAM |",
                  "|---|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|"]
        for r in rep.cost:
            # (a 9D and a 6D row of one filter were indistinguishable; older JSON has no sensors)
            sx = r.get("sensors") or ""
            if r.get("error"):
                lines.append(f"| {r['impl']} | {r['filter']} | {sx} | {r['format']} | {r['target']} | error: {r['error']} |||||||")
                continue
            cyc = r.get("est_cycles_per_update")
            cyc_s = "" if cyc is None else f"{cyc:.0f}"
            us_s = "" if cyc is None else f"{r['est_us_at_64mhz']:.1f}"
            lines.append(f"| {r['impl']} | {r['filter']} | {sx} | {r['format']} | {r['target']} | "
                         f"{r['instructions_per_update']:.1f} | {cyc_s} | {us_s} | {r['flash_bytes']} | "
                         f"{r.get('own_flash_bytes', '')} | {r['ram_bytes']} | {r.get('own_ram_bytes', '')} |")
        lines.append("")
    if png_name:
        lines += [f"![errors]({png_name})", ""]
    path = Path(path) if path is not None else out_dir / "sil_report.md"
    path.write_text("\n".join(lines))
    return path


def write_png(rep: Report, out_dir: Path, path: Path | None = None) -> Path | None:
    """``out_dir``/sil_report.png (or ``path``); None, and nothing written, without f32/q errors."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    systems = [s for s in ("f32", "q") if any(k[2] == s for k in rep.errors)]
    if not systems:
        return None
    fig, axes = plt.subplots(len(systems), 1, figsize=(max(8, 0.9 * len(rep.cases) + 3), 3.6 * len(systems)),
                             squeeze=False)
    width = 0.8 / max(1, len(rep.filters))
    x = np.arange(len(rep.cases))
    for ax, system in zip(axes[:, 0], systems):
        for i, f in enumerate(rep.filters):
            vals = [rep.errors.get((f, c, system), {}).get("total") for c in rep.cases]
            vals = [np.nan if v is None else v for v in vals]
            ax.bar(x + i * width - 0.4 + width / 2, vals, width, label=f)
        ax.set_yscale("log")
        ax.set_ylabel("total RMSE [deg]")
        ax.set_title(f"orientation error vs ground truth ({system})")
        ax.set_xticks(x)
        ax.set_xticklabels(rep.cases, rotation=30, ha="right", fontsize=8)
        ax.grid(axis="y", alpha=0.3)
    axes[0, 0].legend(fontsize=7, ncol=min(5, len(rep.filters)))
    fig.tight_layout()
    path = Path(path) if path is not None else out_dir / "sil_report.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def load_cost(path: str | Path) -> list[dict]:
    from kinefuse.host.errors import KinefuseError
    try:
        data = json.loads(Path(path).read_text())
    except OSError as exc:      # (the message without "[Errno 21] ...: 'path'" repeated)
        raise KinefuseError(f"cannot read cost JSON {path}: {exc.strerror or exc}") from None
    except ValueError as exc:
        raise KinefuseError(f"cannot read cost JSON {path}: {exc}") from None
    # checked here, before the report runs: a row without these keys was a KeyError from
    # write_markdown once every loop had run
    rows = data.get("rows") if isinstance(data, dict) else None
    need = ("impl", "filter", "format", "target")
    for k, r in enumerate(rows if isinstance(rows, list) else []):
        ok = isinstance(r, dict) and all(x in r for x in need) and (
            r.get("error") or all(isinstance(r.get(x), (int, float)) and not isinstance(r.get(x), bool)
                                  for x in ("instructions_per_update", "flash_bytes", "ram_bytes")))
        if not ok:
            raise KinefuseError(f"{path}: row {k} of 'rows' is not a `kinefuse bench cost --json` row "
                                f"(needs {', '.join(need)}, instructions_per_update, flash_bytes, ram_bytes)")
    if not isinstance(rows, list):
        raise KinefuseError(f"{path} is not `kinefuse bench cost --json` output (no 'rows' list)")
    if not rows:        # (the report then had no cost table, without a word)
        raise KinefuseError(f"{path}: its 'rows' list is empty: no cost to include")
    return rows
