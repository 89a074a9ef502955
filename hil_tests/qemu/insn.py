"""Exact counts of executed guest instructions with a small QEMU TCG plugin.

QEMU does not model Cortex-M cycle timing (no DWT CYCCNT); what it can count exactly is
executed instructions.  ``csrc/insn_count.c`` is built with the host ``gcc`` into
``~/.cache/kinefuse/qemu-plugin/`` on first use.

Counts are deterministic: the same ELF and inputs give the same number on every run.
Instructions in IT blocks whose condition fails are counted.
"""
from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import tempfile
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Sequence

from kinefuse.firmware.targets import Target, cache_dir
from kinefuse.hil_tests.qemu.runner import QemuError, RunResult, run_elf
from kinefuse.host.errors import KinefuseError

PLUGIN_SOURCE = "insn_count.c"


def plugin_missing() -> str | None:
    """None when the host compiler needed for the plugin exists, else a one-line reason."""
    if shutil.which("gcc") is None:
        return "host gcc not installed (needed to build the QEMU instruction-count plugin)"
    return None


def plugin_path() -> Path:
    """Build (once, content-hashed) and return the instruction-count plugin ``.so``."""
    reason = plugin_missing()
    if reason:
        raise QemuError(reason)
    src = resources.files("kinefuse.hil_tests.qemu.csrc").joinpath(PLUGIN_SOURCE).read_bytes()
    tag = hashlib.sha256(src).hexdigest()[:16]
    d = cache_dir("qemu-plugin")
    so = d / f"insn_count-{tag}.so"
    if so.is_file():
        return so
    with tempfile.TemporaryDirectory(dir=d) as tmp:
        c = Path(tmp) / PLUGIN_SOURCE
        c.write_bytes(src)
        out = Path(tmp) / "p.so"
        cmd = ["gcc", "-shared", "-fPIC", "-O2", "-std=c99", "-Wall", "-Wextra",
               "-fvisibility=hidden", "-o", str(out), str(c)]
        proc = subprocess.run(cmd, capture_output=True, text=True)
        if proc.returncode != 0:
            lines = proc.stderr.strip().splitlines()
            raise QemuError("building the QEMU plugin failed: "
                            + (lines[-1] if lines else f"gcc exited with status {proc.returncode}"))
        os.replace(out, so)       # atomic: concurrent builders end with the same file
    return so


@dataclass
class InstructionCount:
    """Result of :func:`count_instructions`.

    ``total``: every instruction the CPU executed from reset to semihosting exit.
    ``in_range``: those with ``lo <= address < hi`` (0 without a range).
    ``window``: instructions executed between the start marker (counted) and the stop marker
    (not counted), summed over ``windows`` start/stop pairs.
    """

    total: int
    in_range: int
    window: int
    windows: int
    run: RunResult


def count_instructions(elf: str | os.PathLike, target: str | Target, *,
                       address_range: tuple[int, int] | None = None,
                       markers: tuple[int, int] | None = None,
                       args: Sequence[str] = (),
                       stdin: bytes = b"",
                       timeout: float = 60.0,
                       cwd: str | os.PathLike | None = None,
                       check: bool = True) -> InstructionCount:
    """Run ``elf`` under QEMU with the counting plugin; the program must exit with status 0.

    ``address_range=(lo, hi)`` also counts instructions at ``lo <= pc < hi`` (e.g. one
    function: ``BuildResult.symbol(name)`` gives address and size).  ``markers=(start, stop)``
    counts from executing address ``start`` up to executing ``stop`` (e.g. two labels or
    function entry addresses).  Addresses are plain (Thumb bit cleared).  ``check=False``
    accepts any exit status (the count still needs a semihosting exit, not a timeout).
    """
    with tempfile.TemporaryDirectory(prefix="kf-insn-") as tmp:
        out = Path(tmp) / "count.txt"
        spec = f"{plugin_path()},out={out}"
        if "," in str(out):
            raise KinefuseError("temporary directory path contains a comma")
        if address_range is not None:
            lo, hi = address_range
            spec += f",lo={lo & ~1:#x},hi={hi:#x}"
        if markers is not None:
            start, stop = markers
            spec += f",start={start & ~1:#x},stop={stop & ~1:#x}"
        res = run_elf(elf, target, plugin=spec, args=args, stdin=stdin, timeout=timeout, cwd=cwd)
        if check or res.timed_out:
            res.check(Path(elf).name)
        if not out.is_file():
            detail = res.stderr.decode(errors="replace").strip().splitlines()
            raise QemuError("the instruction-count plugin wrote no result (was it loaded? "
                            f"QEMU needs TCG plugin support){': ' + detail[-1] if detail else ''}")
        values = parse_counts(out.read_text())
    return InstructionCount(values["insns"], values["range"], values["window"],
                            values["windows"], res)


_COUNT_KEYS = ("insns", "range", "window", "windows")


def parse_counts(text: str) -> dict[str, int]:
    """The plugin's ``key value`` lines; QemuError (one line) when a count is missing or not an
    integer (an empty or truncated result file must not become a traceback or a zero)."""
    values: dict[str, int] = {}
    for line in text.splitlines():
        parts = line.split()
        if not parts:
            continue
        if len(parts) != 2 or not parts[1].isdigit():
            raise QemuError(f"the instruction-count plugin wrote an unreadable line {line.strip()!r}")
        values[parts[0]] = int(parts[1])
    missing = [k for k in _COUNT_KEYS if k not in values]
    if missing:
        raise QemuError(f"the instruction-count plugin's result lacks {', '.join(missing)} "
                        "(the run ended before the plugin wrote it?)")
    return values
