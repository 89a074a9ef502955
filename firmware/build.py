"""Build the kinefuse unit application for the host, the Cortex-M4F and the Cortex-M0.

==========  ========================  ==============================  =========================
target      what                      filters                         output
==========  ========================  ==============================  =========================
``host``    SIL program (POSIX)       ``*_f32`` + leg EKF             executable
            firmware/ports/host       (``system="q"``: ``*_q``, tests)
``m4f``     QEMU ``mps2-an386`` port  ``*_f32`` (hardware float)      ELF / BIN / HEX + map
                                      + leg EKF
``m4f-q``   the same port             ``*_q`` (fixed point), all      ELF / BIN / HEX + map
                                      (PIL: q on the M4F too)
``m0``      QEMU ``mps2-an385`` port  ``*_q`` (fixed point), default  ELF / BIN / HEX + map
                                      flagship, madgwick, mahony,
                                      complementary; ``-Os``
==========  ========================  ==============================  =========================

The leg EKF (two-sensor mode, KF_EFFORTS) is generated in float32 only: the float32 builds link
it unless ``--no-leg``; the fixed-point builds (M0, ``m4f-q``, ``host-q``) never have it.  The M0 default
filter set and ``-Os`` make the image fit a 256 kB part; ``--filters all`` (or a list) and
``--opt`` override them.

The application sources are ``firmware/app/*.c``; the generated bindings there
(``kf_filters_gen.c``, ``kf_params_gen.inc``) come from :mod:`kinefuse.firmware.apptables`.
Every build uses the bit-exactness flags (``-std=c99 -ffp-contract=off -fno-fast-math``); the
Cortex-M builds go through :func:`kinefuse.firmware.targets.build` (board HAL, linker script,
``--gc-sections``, size report).

    python -m kinefuse.firmware.build all            # host + m4f + m0, size report
    python -m kinefuse.firmware.build m4f-q          # fixed-point filters on the M4F
    python -m kinefuse.firmware.build m0 --out out/  # copy ELF/BIN/HEX/map to out/
    python -m kinefuse.firmware.build tables [--check]
"""
from __future__ import annotations

import argparse
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

from kinefuse.firmware import apptables
from kinefuse.host.errors import KinefuseError

FIRMWARE_DIR = Path(__file__).resolve().parent
APP_DIR = FIRMWARE_DIR / "app"
GENERATED_DIR = FIRMWARE_DIR / "generated"
MAVLINK_DIR = FIRMWARE_DIR / "mavlink" / "generated"
HOST_PORT_DIR = FIRMWARE_DIR / "ports" / "host"

#: target -> number system of its filters by default (``build_target(..., system=)`` and the
#: CLI's ``m4f-q`` / ``host-q`` choose the other one)
TARGET_SYSTEM = {"host": "f32", "m4f": "f32", "m0": "q"}
#: filters of a Cortex-M build that names none (``filters=None``; ``"all"``: every wired one).
#: The M0 image with all ten fixed-point filters (337,404 B at -Os, 737,268 B at -O2) does not
#: fit a 256 kB part; with these four it is 124,860 B at -Os (README, "Unit firmware": measured
#: with `python -m kinefuse.firmware.build sizes`).  The M4F and the host build every wired filter.
DEFAULT_FILTERS = {"m0": ("flagship", "madgwick", "mahony", "complementary")}
#: optimisation of a build that names none: -Os on the M0 (size decides there: the default set at
#: -O2 is 260,876 B, 1.3 kB below 256 kB with no room for a board port's drivers), -O2 elsewhere
DEFAULT_OPT = {"host": "-O2", "m4f": "-O2", "m0": "-Os"}
C_FLAGS = ("-std=c99", "-ffp-contract=off", "-fno-fast-math", "-Wall", "-Wextra")
HOST_TX_BYTES = 65536
BOARD_TX_BYTES = 4096


class FirmwareBuildError(KinefuseError):
    """Compiling or linking the application failed (``.log`` has the compiler output)."""

    def __init__(self, message: str, log: str = ""):
        super().__init__(message)
        self.log = log


def wired_filters() -> list[str]:
    """Filters listed in firmware/app/kf_filter_list.h (the full build)."""
    return [e.name for e in apptables.read_list()]


def default_filters(target: str) -> list[str]:
    """The filters a build of ``target`` links when none are named (see DEFAULT_FILTERS)."""
    return list(DEFAULT_FILTERS.get(target, wired_filters()))


def _subset(filters) -> list[str]:
    names = wired_filters()
    if filters is None or filters == "all" or list(filters) == ["all"]:
        return names
    if not list(filters):      # `--filters ,` built an application with no filter at all
        raise KinefuseError(f"no filter named: --filters takes wired filters ({', '.join(names)}) or all")
    bad = [f for f in filters if f not in names]
    if bad:
        raise KinefuseError(f"filter {bad[0]!r} is not wired into the application "
                            f"(kf_filter_list.h has: {', '.join(names)})")
    return [n for n in names if n in filters]


def app_sources(system: str, board_main: bool, filters=None, leg: bool = True) -> list[Path]:
    """Application C files + the generated filters it binds, for number system ``system``
    (``filters``: a subset of the wired filters; default all).  The f32 builds also link the leg
    EKF (``leg_f32``, two-sensor mode, KF_EFFORTS) unless ``leg`` is False (then build with
    ``_defines(..., leg=False)``, which defines KF_WITHOUT_LEG)."""
    if system not in ("f32", "q"):
        raise KinefuseError(f"number system must be 'f32' or 'q', not {system!r}")
    srcs = sorted(p for p in APP_DIR.glob("*.c") if p.name != "kf_main.c")
    if board_main:
        srcs.append(APP_DIR / "kf_main.c")
    names = _subset(filters) + [apptables.CALIB, apptables.JOINT]
    if system == "f32" and leg:
        names.append(apptables.LEG)            # generated in float32 only
    for n in names:
        p = GENERATED_DIR / f"{n}_{system}.c"
        if not p.is_file():
            raise KinefuseError(f"{p} is missing: run `kinefuse codegen`")
        srcs.append(p)
    return srcs


def git_hash() -> int:
    """First 32 bits of HEAD's commit hash (0 outside a git checkout)."""
    try:
        out = subprocess.run(["git", "rev-parse", "HEAD"], cwd=FIRMWARE_DIR, capture_output=True,
                             text=True, timeout=10)
        return int(out.stdout.strip()[:8], 16) if out.returncode == 0 else 0
    except (OSError, ValueError, subprocess.TimeoutExpired):
        return 0


def _defines(system: str, tx_bytes: int, with_git: bool, filters=None, leg: bool = True) -> dict[str, str]:
    d = {"KF_NUMERIC_Q": "1" if system == "q" else "0", "KF_TX_BUFFER_BYTES": f"{tx_bytes}u"}
    if system == "f32" and not leg:
        d["KF_WITHOUT_LEG"] = "1"
    keep = set(_subset(filters))
    for n in wired_filters():
        if n not in keep:
            d[f"KF_WITHOUT_{n.upper()}"] = "1"
    h = git_hash() if with_git else 0
    if h:
        d["KF_GIT_HASH"] = f"0x{h:08X}u"
    return d


def _check_tables() -> None:
    stale = apptables.check()
    if stale:
        raise KinefuseError(f"firmware/app/{stale[0]} is stale: run `python -m kinefuse.firmware.build tables`")


# -------------------------------------------------------------------------------------- host

@dataclass
class HostBuild:
    exe: Path
    system: str
    cached: bool


def _cache_root() -> Path:
    from kinefuse.firmware.targets import cache_dir
    return cache_dir("unit-host")


def build_host(system: str = "f32", *, sanitize: bool = False, tx_bytes: int = HOST_TX_BYTES,
               with_git: bool = False, opt: str = "-O2", cc: str = "gcc", filters=None,
               leg: bool = True) -> HostBuild:
    """The host (SIL) program ``kinefuse-unit``, cached by a hash of sources, headers and flags.

    ``sanitize`` adds ``-fsanitize=address,undefined -fno-sanitize-recover`` (tests);
    ``filters`` builds a subset of the wired filters (the others answer as not built); ``leg``
    False leaves the leg EKF out (KF_EFF_RATE_HZ can then only be 0)."""
    _check_tables()
    if shutil.which(cc) is None:
        raise KinefuseError(f"{cc} not found: install a C compiler (apt-get install gcc)")
    srcs = app_sources(system, board_main=False, filters=filters, leg=leg) + sorted(HOST_PORT_DIR.glob("*.c"))
    defs = _defines(system, tx_bytes, with_git, filters, leg)
    flags = [opt, *C_FLAGS, *(f"-D{k}={v}" for k, v in sorted(defs.items())),
             f"-I{APP_DIR}", f"-I{GENERATED_DIR}", f"-I{HOST_PORT_DIR}", "-isystem", str(MAVLINK_DIR)]
    ldflags = ["-lm"]
    if sanitize:
        flags += ["-g", "-fsanitize=address,undefined", "-fno-sanitize-recover=all", "-fno-omit-frame-pointer"]
        ldflags = ["-fsanitize=address,undefined"] + ldflags
    h = hashlib.sha256(repr((flags, ldflags, cc)).encode())
    headers = [p for d in (APP_DIR, GENERATED_DIR, HOST_PORT_DIR, MAVLINK_DIR)
               for p in sorted(d.rglob("*")) if p.suffix in (".h", ".inc")]
    for p in srcs + headers:
        h.update(str(p.relative_to(FIRMWARE_DIR)).encode())
        h.update(p.read_bytes())
    key = h.hexdigest()[:20]
    out_dir = _cache_root() / key
    exe = out_dir / "kinefuse-unit"
    if exe.is_file():
        return HostBuild(exe, system, True)
    work = Path(tempfile.mkdtemp(prefix=".tmp-", dir=_cache_root()))
    try:
        def compile_one(i_src):
            i, src = i_src
            obj = work / f"{i:02d}_{src.stem}.o"
            proc = subprocess.run([cc, *flags, "-c", str(src), "-o", str(obj)], capture_output=True, text=True)
            return obj, proc
        with ThreadPoolExecutor(max_workers=max(1, min(4, os.cpu_count() or 1))) as pool:
            results = list(pool.map(compile_one, enumerate(srcs)))
        for obj, proc in results:
            if proc.returncode != 0:
                raise FirmwareBuildError(_first_error(proc.stderr, f"compiling {obj.stem} failed"), proc.stderr)
        proc = subprocess.run([cc, *[str(o) for o, _ in results], *ldflags, "-o", str(work / exe.name)],
                              capture_output=True, text=True)
        if proc.returncode != 0:
            raise FirmwareBuildError(_first_error(proc.stderr, "linking failed"), proc.stderr)
        try:
            work.rename(out_dir)
        except OSError:       # built by someone else meanwhile
            shutil.rmtree(work, ignore_errors=True)
    finally:
        if work.exists():
            shutil.rmtree(work, ignore_errors=True)
    return HostBuild(exe, system, False)


def _first_error(stderr: str, fallback: str) -> str:
    for line in stderr.splitlines():
        if " error" in line or "undefined reference" in line:
            return line.strip()[:300]
    return fallback


# ------------------------------------------------------------------------------- Cortex-M

def build_target(target: str, *, opt: str | None = None, with_git: bool = False, out_dir=None, filters=None,
                 leg: bool = True, system: str | None = None):
    """Cross-build the application for ``m4f`` (float32 filters; with the leg EKF unless ``leg``
    is False) or ``m0`` (fixed point: no leg EKF), with the subset ``filters`` of the wired
    filters, ``"all"`` of them, or (None) the target's default set (:data:`DEFAULT_FILTERS`:
    M4F all, M0 flagship, madgwick, mahony, complementary); ``opt`` None: :data:`DEFAULT_OPT`.
    ``system`` ("f32" or "q") overrides the target's number system (:data:`TARGET_SYSTEM`):
    ``build_target("m4f", system="q")`` is the fixed-point application on the M4F (the PIL
    harness runs q on both Cortex-M targets); the image is named ``kinefuse-<target>-<system>``.

    Returns :class:`kinefuse.firmware.targets.BuildResult` (ELF/BIN/HEX/map, size)."""
    from kinefuse.firmware.targets import build
    if target not in ("m4f", "m0"):
        raise KinefuseError(f"unknown target {target!r} (choose from m4f, m0; host: build_host)")
    _check_tables()
    if system is None:
        system = TARGET_SYSTEM[target]
    elif system not in ("f32", "q"):
        raise KinefuseError(f"number system must be 'f32' or 'q', not {system!r}")
    default_system = system == TARGET_SYSTEM[target]
    opt = opt or DEFAULT_OPT[target]
    if filters is None:
        filters = default_filters(target) if default_system else "all"
    defs = _defines(system, BOARD_TX_BYTES, with_git, filters, leg)
    return build(app_sources(system, board_main=True, filters=filters, leg=leg), target,
                 include_dirs=[APP_DIR, GENERATED_DIR, MAVLINK_DIR], defines=defs, opt=opt,
                 name=f"kinefuse-{target}" + ("" if default_system else f"-{system}"), out_dir=out_dir,
                 extra_cflags=["-isystem", str(MAVLINK_DIR)])


def size_report(opts=("-O2", "-Os")) -> list[dict]:
    """Flash/RAM (static) of the application per Cortex-M target, filter set (the target's
    default, and on the M0 also all wired filters) and optimisation level, with the share of
    the generated code (filters, calibration, joint step, leg EKF; the leg EKF alone in
    ``flash_leg``), libraries and MAVLink/app code."""
    rows = []
    sets = [("m4f", "default"), ("m0", "default"), ("m0", "all")]
    for target, which in sets:
        for opt in opts:
            res = build_target(target, opt=opt, filters=None if which == "default" else "all")
            origin = res.size_by_origin()
            system = TARGET_SYSTEM[target]
            gen = {e.name for e in apptables.read_list()} | {apptables.CALIB, apptables.JOINT, apptables.LEG}
            filt = sum(v.flash for k, v in origin.items() if k.rsplit("_", 1)[0] in gen and k.endswith(system))
            libs = sum(v.flash for k, v in origin.items() if k.endswith(".a"))
            leg = origin.get(f"{apptables.LEG}_f32")
            names = default_filters(target) if which == "default" else wired_filters()
            rows.append({"target": target, "opt": opt, "system": system, "filter_set": which,
                         "filters": names, **res.size.as_dict(),
                         "flash_generated": filt, "flash_libraries": libs,
                         "flash_app": res.size.flash - filt - libs,
                         "flash_leg": leg.flash if leg is not None else 0,
                         "elf": str(res.elf)})
    return rows


# ------------------------------------------------------------------------------------- CLI

#: what --opt takes (it is the compiler's first flag)
OPT_LEVELS = ("-O0", "-O1", "-O2", "-O3", "-Os", "-Og", "-Oz")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m kinefuse.firmware.build",
                                 description="build the kinefuse unit application")
    ap.add_argument("what", choices=("host", "host-q", "m4f", "m4f-q", "m0", "all", "tables", "sizes"))
    ap.add_argument("--out", help="copy the outputs into this folder")
    ap.add_argument("--opt", help="optimisation flag: " + ", ".join(OPT_LEVELS) + " (default -O2; m0: -Os)")
    ap.add_argument("--check", action="store_true", help="tables: exit 1 when the generated files are stale")
    ap.add_argument("--filters", help="comma-separated subset of the wired filters, or 'all' (default: all; "
                                      "m0: " + ",".join(DEFAULT_FILTERS["m0"]) + ")")
    ap.add_argument("--no-leg", action="store_true", help="float32 builds: leave the leg EKF (KF_EFFORTS) out")
    ap.add_argument("--json", action="store_true", help="print one JSON object")
    # `--opt -O2` (README, help): argparse takes -O2 for an option and refused it ("expected one
    # argument"); it is the value of --opt, as --opt=-O2 is
    argv = list(sys.argv[1:] if argv is None else argv)
    for i in range(len(argv) - 1, 0, -1):
        if argv[i - 1] == "--opt" and argv[i].startswith("-"):
            argv[i - 1:i + 1] = [f"--opt={argv[i]}"]
    args = ap.parse_args(argv)
    if args.opt is not None and args.opt not in OPT_LEVELS:
        ap.error(f"argument --opt: {args.opt!r} is not one of {', '.join(OPT_LEVELS)}")
    try:
        # options that do not apply to the action were ignored: refuse them
        given = [o for o, v in (("--out", args.out), ("--opt", args.opt), ("--filters", args.filters),
                                ("--no-leg", args.no_leg), ("--check", args.check)) if v]
        applies = {"tables": ("--check",), "sizes": ()}.get(args.what,
                                                            ("--out", "--opt", "--filters", "--no-leg"))
        extra = [o for o in given if o not in applies]
        if extra:
            raise KinefuseError(f"{extra[0]} does not apply to {args.what}"
                                + (" (its builds are fixed: every target, filter set and -O2/-Os)"
                                   if args.what == "sizes" else ""))
        if args.out and Path(args.out).exists() and not Path(args.out).is_dir():
            raise KinefuseError(f"--out {args.out} is a file, not a folder")
        if args.what == "tables":
            if args.check:
                stale = apptables.check()
                print(json.dumps({"stale": stale}) if args.json else
                      ("up to date" if not stale else "stale: " + ", ".join(stale)))
                return 1 if stale else 0
            written = apptables.write()
            print(json.dumps({"written": written}) if args.json else
                  ("\n".join(f"wrote firmware/app/{w}" for w in written) or "up to date"))
            return 0
        if args.what == "sizes":
            rows = size_report()
            if args.json:
                print(json.dumps({"sizes": rows}))
            else:
                print(f"{'target':7} {'set':8} {'opt':4} {'flash':>7} {'RAM':>7} {'generated':>9} {'(leg)':>7} "
                      f"{'libs':>7} {'app':>7}  filters")
                for r in rows:
                    print(f"{r['target']:7} {r['filter_set']:8} {r['opt']:4} {r['flash']:7d} {r['ram']:7d} "
                          f"{r['flash_generated']:9d} {r['flash_leg']:7d} {r['flash_libraries']:7d} "
                          f"{r['flash_app']:7d}  {','.join(r['filters'])}")
            return 0
        out = {}
        subset = [f.strip() for f in args.filters.split(",") if f.strip()] if args.filters else None
        leg = not args.no_leg
        todo = ("host", "m4f", "m0") if args.what == "all" else (args.what,)
        for t in todo:
            if t.startswith("host"):
                b = build_host("q" if t == "host-q" else "f32", with_git=True, opt=args.opt or DEFAULT_OPT["host"],
                               filters=subset, leg=leg)
                files = [b.exe]
                out[t] = {"exe": str(b.exe)}
            else:
                r = build_target(t.split("-")[0], opt=args.opt, with_git=True, filters=subset, leg=leg,
                                 system="q" if t.endswith("-q") else None)
                files = [r.elf, r.bin, r.hex, r.map]
                out[t] = {"elf": str(r.elf), "bin": str(r.bin), "hex": str(r.hex), **r.size.as_dict()}
            if args.out:
                d = Path(args.out)
                d.mkdir(parents=True, exist_ok=True)
                for f in files:
                    shutil.copy2(f, d / (f.name if not t.startswith("host") else f"kinefuse-unit-{t}"))
        if args.json:
            print(json.dumps(out))
        else:
            for t, v in out.items():
                extra = f"  flash {v['flash']} B, RAM {v['ram']} B" if "flash" in v else ""
                print(f"{t}: {v.get('elf') or v.get('exe')}{extra}")
        return 0
    except KinefuseError as exc:
        print(f"kinefuse: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
