"""``kinefuse sim``: list, show and run simulator scenarios.

  kinefuse sim list [--json]
  kinefuse sim show NAME                      (the scenario as JSON: edit it, run the file)
  kinefuse sim run NAME|FILE.json [--seed N] [--preset P] [--rate HZ] [--mag-rate HZ]
                   [--duration S] [--out PATH.npz|.mat|.bin [--force]] [--json]

``--out`` writes one file per sensor (``PATH`` for a single sensor, ``stem_<sensor>.ext``
otherwise): ``.npz`` everything (``Recording.load``), ``.mat`` the BROAD layout plus t and
mag_valid, ``.bin`` packed ``kf_raw_sample`` records (firmware/app/kf_hal.h) for SIL/QEMU.
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np

from kinefuse.host.errors import KinefuseError
from kinefuse.host.console import print_table
from kinefuse.host import argtypes
from kinefuse.host.outputs import add_force_arg, check_new_file, staged


def register(subparsers) -> None:
    p = subparsers.add_parser("sim", help="motion and sensor simulator (ground-truth recordings)",
                              description=__doc__.splitlines()[0])
    sub = p.add_subparsers(dest="sim_command", metavar="ACTION", parser_class=type(p))
    ls = sub.add_parser("list", help="list the named scenarios")
    ls.add_argument("--json", action="store_true", help="one JSON object on stdout")
    ls.set_defaults(func=_list)
    sh = sub.add_parser("show", help="print a named scenario as JSON")
    sh.add_argument("name")
    sh.set_defaults(func=_show)
    rn = sub.add_parser("run", help="simulate a scenario (name or JSON file)")
    rn.add_argument("scenario", help="library name or path to a scenario .json")
    rn.add_argument("--seed", type=argtypes.seed, default=None, help="random seed (default: the scenario's)")
    rn.add_argument("--preset", default=None, help="sensor preset: xsens_dot, matrix, metamotionr, ideal (its noise, ranges and resolution; the scenario keeps its rates and error terms: bias, drift, scale, misalignment, iron)")
    rn.add_argument("--rate", type=float, default=None, help="acc/gyro output rate, Hz")
    rn.add_argument("--mag-rate", type=float, default=None, help="magnetometer rate, Hz")
    rn.add_argument("--duration", type=float, default=None, help="duration, s (default: the motion's)")
    rn.add_argument("--out", default=None, help="output file (.npz, .mat or .bin)")
    rn.add_argument("--json", action="store_true", help="one JSON object on stdout")
    add_force_arg(rn, "existing output files")
    rn.set_defaults(func=_run)
    p.set_defaults(func=lambda args: (p.print_help(), 2)[1])


def _list(args) -> int:
    from . import library
    items = {n: library._LIB[n]["description"] for n in library.names()}
    if args.json:
        print(json.dumps({"scenarios": items}))
        return 0
    from rich.table import Table
    t = Table("scenario", "description")
    for n, d in items.items():
        t.add_row(n, d)
    print_table(t)
    return 0


def _show(args) -> int:
    from .library import scenario
    print(scenario(args.name).to_json())
    return 0


def _load_scenario(arg: str):
    from .library import names, scenario
    from .scenario import Scenario
    if arg in names():
        return scenario(arg)
    if not arg.strip():     # (was read as the current folder: "cannot read scenario file : Is a directory")
        raise KinefuseError(f"scenario {arg!r}: empty; give a library name (see `kinefuse sim list`) "
                            f"or a scenario .json file")
    p = Path(arg)
    if p.suffix == ".json" or p.exists():
        try:
            text = p.read_text(encoding="utf-8")
        except OSError as exc:
            raise KinefuseError(f"cannot read scenario file {arg}: {exc.strerror}") from None
        except UnicodeDecodeError as exc:       # (was an internal error)
            raise KinefuseError(f"scenario file {arg}: not UTF-8 text (byte {exc.start}); "
                                f"save the JSON as UTF-8") from None
        return Scenario.from_json(text)
    raise KinefuseError(f"unknown scenario {arg!r}: not a library name (see `kinefuse sim list`) nor a file")


# what a sensor is (noise, full scale, resolution) comes from --preset; what the scenario does
# to it (bias, drift, scale, misalignment, iron, no magnetometer) is the scenario's point: kept
_SENSOR_PROPERTIES = ("noise_", "range_", "lsb_", "bits")


def _with_preset(scenario_sensor: dict, preset: str) -> dict:
    """The scenario's sensor section under another preset: the preset's noise, ranges and
    resolution, the scenario's rates and error terms (``bias_1dps --preset xsens_dot`` lost its
    1 °/s bias when the preset replaced the whole section)."""
    sensor = {"preset": preset}
    sensor.update({k: v for k, v in scenario_sensor.items() if k in ("rate_hz", "mag_rate_hz")})
    for ch in ("gyr", "acc", "mag"):
        over = scenario_sensor.get(ch)
        if isinstance(over, dict):
            kept = {k: v for k, v in over.items() if not k.startswith(_SENSOR_PROPERTIES)}
            if kept:
                sensor[ch] = kept
    return sensor


def _run(args) -> int:
    from .scenario import run
    from kinefuse.host.bench.common import given
    given("--preset", args.preset, "a sensor preset: xsens_dot, matrix, metamotionr or ideal")  # (was ignored)
    given("--out", args.out, "a .npz, .mat or .bin file name")        # (was ignored: nothing written)
    if args.out:
        _out_path(args.out, "x", 1)          # reject a bad file type before simulating
    sc = _load_scenario(args.scenario)
    sensor = dict(sc.sensor)
    if args.preset is not None:
        sensor = _with_preset(sc.sensor, args.preset)
    if args.rate is not None:
        sensor["rate_hz"] = args.rate
    if args.mag_rate is not None:
        sensor["mag_rate_hz"] = args.mag_rate
    changes = {"sensor": sensor}
    if args.duration is not None:
        changes["duration_s"] = args.duration
    if args.seed is not None:
        changes["seed"] = args.seed
    from rich.console import Console
    err = Console(stderr=True)
    with err.status(f"simulating {sc.name} …", spinner="dots") if sys.stderr.isatty() else _Null():
        recs = run(sc, **changes)
    if args.mag_rate is not None and not any(r.meta["sensor_model"].get("mag", {}).get("present", True)
                                             for r in recs.values()):
        # (was ignored: the summary even listed the rate of a magnetometer that is not there)
        raise KinefuseError(f"--mag-rate: the {recs[next(iter(recs))].meta['preset']} sensor has no magnetometer")
    summary = {"scenario": sc.name, "seed": int(changes.get("seed", sc.seed)), "sensors": {}}
    # the file names follow the rig's sensor units, known once the motion is built: every one is
    # checked before the first is written
    paths = {name: check_new_file(_out_path(args.out, name, len(recs)), args.force)
             for name in recs} if args.out else {}
    # every file is written under a temporary name and renamed once all are written: a failed
    # or interrupted write left the first sensor's file (or a truncated one) under its name
    with staged() as stage:
        for name, r in recs.items():
            s = _summary(r)
            if name in paths:
                _write(r, stage.path(paths[name]), shown=paths[name])
                s["file"] = str(paths[name])
            summary["sensors"][name] = s
    if args.json:
        print(json.dumps(summary))
        return 0
    from rich.table import Table
    t = Table("sensor", "samples", "s", "Hz acc/mag", "drop/dup", "max|gyr| °/s", "|acc| m/s²", "|mag| µT",
              title=f"{sc.name} (seed {summary['seed']})")
    for name, s in summary["sensors"].items():
        t.add_row(name, str(s["samples"]), f"{s['duration_s']:.1f}", f"{s['rate_hz']:g}/" + ("–" if s["mag_rate_hz"] is None else f"{s['mag_rate_hz']:g}"),
                  f"{s['dropped']}/{s['duplicated']}", f"{s['gyr_max_dps']:.1f}",
                  f"{s['acc_norm_min']:.2f}–{s['acc_norm_max']:.2f}",
                  "none" if s["mag_norm_min"] is None else f"{s['mag_norm_min']:.1f}–{s['mag_norm_max']:.1f}")
    con = Console()
    print_table(t, con)
    for name, s in summary["sensors"].items():
        if "file" in s:
            con.print(f"{name}: wrote {s['file']}")
    return 0


class _Null:
    def __enter__(self):
        return self

    def __exit__(self, *a):
        return False


def _summary(r) -> dict:
    an = np.linalg.norm(r.acc, axis=1)
    mn = np.linalg.norm(r.mag, axis=1)
    has_mag = bool(np.any(np.isfinite(mn)))
    from .timing import sample_count
    # (the last delivered index + 1 missed every sample dropped after it)
    n_nominal = sample_count(r.meta["duration_s"], r.meta["rate_hz"])
    return {"samples": len(r), "duration_s": float(r.t[-1] - r.t[0]) if len(r) else 0.0,
            # (a sensor without magnetometer was listed with one at the acc/gyro rate)
            "rate_hz": r.meta["rate_hz"], "mag_rate_hz": r.meta["mag_rate_hz"] if has_mag else None,
            "preset": r.meta["preset"],
            "dropped": n_nominal - len(np.unique(r.index)), "duplicated": len(r) - len(np.unique(r.index)),
            "gyr_max_dps": float(np.degrees(np.max(np.linalg.norm(r.gyr, axis=1)))),
            "acc_norm_min": float(an.min()), "acc_norm_max": float(an.max()),
            "mag_norm_min": float(np.nanmin(mn)) if has_mag else None,
            "mag_norm_max": float(np.nanmax(mn)) if has_mag else None,
            "moving_fraction": float(np.mean(r.movement))}


def _out_path(out: str, sensor: str, count: int) -> Path:
    p = Path(out)
    if p.suffix not in (".npz", ".mat", ".bin"):
        raise KinefuseError(f"--out {out}: use a .npz, .mat or .bin file name")
    return p if count == 1 else p.with_name(f"{p.stem}_{sensor}{p.suffix}")


def _write(r, path: Path, shown: Path | None = None) -> None:
    try:
        if path.suffix == ".bin":
            path.write_bytes(r.to_raw().tobytes())
        else:
            r.save(str(path))
    except OSError as exc:
        raise KinefuseError(f"cannot write {shown or path}: {exc.strerror}") from None
