"""Cortex-M targets and the cross-build of C/C++ sources for them.

Two targets, both emulated by QEMU's MPS2 boards (``firmware/boards/mps2``):

==========  ==============  ======================================================  =========
target      QEMU machine    compiler flags                                          float
==========  ==============  ======================================================  =========
``m4f``     ``mps2-an386``  ``-mcpu=cortex-m4 -mthumb -mfloat-abi=hard               hardware
                            -mfpu=fpv4-sp-d16``                                     (single)
``m0``      ``mps2-an385``  ``-mcpu=cortex-m0 -mthumb -mfloat-abi=soft``            software
==========  ==============  ======================================================  =========

Every build uses the bit-exactness flags of ``shared/notes/bit-exact.md``
(``-std=c99 -ffp-contract=off -fno-fast-math``, plus ``-fno-math-errno`` as on the host; C++
gets ``-std=c++14`` with the same float
flags plus ``-fno-exceptions -fno-rtti``), ``-ffunction-sections -fdata-sections`` and
``--gc-sections`` so that sizes measure what is actually reachable, and the full newlib
(``--specs=nosys.specs``, not newlib-nano: nano's ``memcpy`` is a byte loop that would distort
instruction counts).  ``-O2`` unless told otherwise.

Example::

    from kinefuse.firmware.targets import build
    res = build(["main.c"], "m4f", include_dirs=["inc"])
    res.elf, res.bin, res.hex, res.size.flash, res.size.ram

Builds are cached under ``~/.cache/kinefuse/build/<hash>`` (``KINEFUSE_CACHE``, as for the
other kinefuse caches, or ``KINEFUSE_CACHE_DIR`` or ``XDG_CACHE_HOME`` move it); the hash covers
sources, headers in the include directories, board files, flags and the compiler version.
"""
from __future__ import annotations

import hashlib
import os
import re
import shutil
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterable, Mapping, Sequence

from kinefuse.host.errors import KinefuseError

FIRMWARE_DIR = Path(__file__).resolve().parent
BOARD_DIRS = {"mps2": FIRMWARE_DIR / "boards" / "mps2"}
HAL_INCLUDE_DIR = FIRMWARE_DIR / "app"

# Board sources: the runtime every program needs, and the HAL (kf_hal.h) on top of it.
_BOARD_RUNTIME = ("startup_mps2.c", "semihost.c")
_BOARD_HAL = ("kf_hal_mps2.c", "uart_cmsdk.c")

# -fno-math-errno: nothing reads errno after a math call, and with it GCC emits VSQRT alone instead
# of VSQRT + a call to libm's sqrtf for negative operands (which pulled in newlib's 1 kB reentrancy
# struct for errno); results are the same bits
C_FLAGS: tuple[str, ...] = ("-std=c99", "-ffp-contract=off", "-fno-fast-math", "-fno-math-errno")
CXX_FLAGS: tuple[str, ...] = ("-std=c++14", "-ffp-contract=off", "-fno-fast-math", "-fno-math-errno",
                              "-fno-exceptions", "-fno-rtti", "-fno-threadsafe-statics")
COMMON_FLAGS: tuple[str, ...] = ("-ffunction-sections", "-fdata-sections", "-Wall", "-Wextra", "-g")
CXX_SUFFIXES = (".cpp", ".cc", ".cxx", ".C")
ASM_SUFFIXES = (".S", ".s")
HEADER_SUFFIXES = (".h", ".hpp", ".hh", ".inc", ".inl")


@dataclass(frozen=True)
class Target:
    """A CPU configuration and the QEMU machine that runs it."""

    name: str
    description: str
    machine: str                    # qemu-system-arm -M ...
    arch_flags: tuple[str, ...]     # compiler/linker flags selecting CPU, ISA and float ABI
    hard_float: bool
    board: str = "mps2"
    board_clock_hz: int = 25_000_000  # MPS2 CPU clock (SysTick source)


TARGETS: dict[str, Target] = {
    "m4f": Target("m4f", "Cortex-M4F, single-precision FPU (hard-float ABI)", "mps2-an386",
                  ("-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard", "-mfpu=fpv4-sp-d16"), True),
    "m0": Target("m0", "Cortex-M0, ARMv6-M, software floating point", "mps2-an385",
                 ("-mcpu=cortex-m0", "-mthumb", "-mfloat-abi=soft"), False),
}


class ToolchainError(KinefuseError):
    """The ARM cross toolchain (or QEMU) is missing."""


class BuildError(KinefuseError):
    """Compilation or link failed; ``str()`` is one line, ``.log`` holds the compiler output."""

    def __init__(self, message: str, log: str = "", command: Sequence[str] = ()):
        super().__init__(message)
        self.log = log
        self.command = list(command)


@dataclass(frozen=True)
class SizeReport:
    """Section sizes in bytes as ``arm-none-eabi-size`` (Berkeley format) reports them.

    ``text`` is code + constants + vectors, ``data`` initialised RAM (its image also sits in
    flash), ``bss`` zeroed and ``.noinit`` RAM.  Stack and heap are not included.
    """

    text: int
    data: int
    bss: int

    @property
    def flash(self) -> int:
        return self.text + self.data

    @property
    def ram(self) -> int:
        return self.data + self.bss

    def __sub__(self, other: "SizeReport") -> "SizeReport":
        return SizeReport(self.text - other.text, self.data - other.data, self.bss - other.bss)

    def as_dict(self) -> dict[str, int]:
        return {"text": self.text, "data": self.data, "bss": self.bss,
                "flash": self.flash, "ram": self.ram}


@dataclass
class BuildResult:
    """Outputs of :func:`build`."""

    target: Target
    elf: Path
    bin: Path
    hex: Path
    map: Path
    size: SizeReport
    opt: str
    cached: bool = False
    commands: list[list[str]] = field(default_factory=list)

    def symbol(self, name: str) -> tuple[int, int]:
        """(address, size in bytes) of a symbol; Thumb function addresses have bit 0 cleared."""
        for sym_name, addr, size, _kind in self.symbols():
            if sym_name == name:
                return addr, size
        raise KinefuseError(f"symbol {name!r} not found in {self.elf.name}")

    def symbols(self) -> list[tuple[str, int, int, str]]:
        """All sized symbols as (name, address, size, nm type letter), largest first."""
        out = _run([tool("nm"), "-S", "--size-sort", "-r", str(self.elf)], "nm").stdout
        rows = []
        for line in out.splitlines():
            parts = line.split()
            if len(parts) == 4:
                addr, size, kind, sym_name = parts
                rows.append((sym_name, int(addr, 16) & ~1, int(size, 16), kind))
        return rows

    def size_by_origin(self) -> dict[str, SizeReport]:
        """Linked bytes per input file, from the linker map: archives by name (``libm.a``,
        ``libgcc.a``, ``libc.a``, ``libstdc++.a``), objects by source stem (``FusionAhrs``,
        ``kf_cost_driver``, ``startup_mps2``...), alignment padding as ``*fill*``."""
        return map_size_by_origin(self.map)

    def disassemble(self, symbol: str | None = None) -> str:
        """objdump -d text of the whole ELF or of one symbol."""
        cmd = [tool("objdump"), "-d", "--no-show-raw-insn"]
        if symbol:
            cmd.append(f"--disassemble={symbol}")
        return _run(cmd + [str(self.elf)], "objdump").stdout


def tool(name: str) -> str:
    """Path of an ``arm-none-eabi-*`` tool (``gcc``, ``g++``, ``size``, ``objcopy``, ...)."""
    exe = shutil.which(f"arm-none-eabi-{name}")
    if exe is None:
        raise ToolchainError(f"arm-none-eabi-{name} not found: apt-get install gcc-arm-none-eabi "
                             "libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib")
    return exe


def toolchain_missing() -> str | None:
    """None when the ARM cross toolchain is usable, else a one-line reason (for test skips)."""
    for name in ("gcc", "g++", "size", "objcopy", "nm"):
        if shutil.which(f"arm-none-eabi-{name}") is None:
            return f"arm-none-eabi-{name} not installed"
    return None


def cache_dir(*parts: str) -> Path:
    """``~/.cache/kinefuse/<parts>``: under ``$KINEFUSE_CACHE`` when set, like every other
    kinefuse cache (``KINEFUSE_CACHE_DIR``, the older name, and ``XDG_CACHE_HOME`` are honoured too)."""
    root = os.environ.get("KINEFUSE_CACHE") or os.environ.get("KINEFUSE_CACHE_DIR")
    if not root:
        root = os.path.join(os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"),
                            "kinefuse")
    path = Path(root, *parts)
    path.mkdir(parents=True, exist_ok=True)
    return path


def get_target(target: str | Target) -> Target:
    if isinstance(target, Target):
        return target
    try:
        return TARGETS[target]
    except KeyError:
        raise KinefuseError(f"unknown target {target!r} (choose from {', '.join(TARGETS)})") from None


def board_sources(board: str = "mps2", hal: bool = True) -> list[Path]:
    """C files of a board port: runtime (startup, semihosting) and optionally the HAL."""
    d = BOARD_DIRS[board]
    names = _BOARD_RUNTIME + (_BOARD_HAL if hal else ())
    return [d / n for n in names]


def build(sources: Iterable[str | os.PathLike],
          target: str | Target,
          *,
          include_dirs: Iterable[str | os.PathLike] = (),
          defines: Mapping[str, str | int | None] | None = None,
          opt: str = "-O2",
          name: str = "prog",
          out_dir: str | os.PathLike | None = None,
          hal: bool = True,
          libc: str = "nosys",
          extra_cflags: Sequence[str] = (),
          extra_ldflags: Sequence[str] = (),
          cache: bool = True) -> BuildResult:
    """Compile and link C/C++/assembly ``sources`` with the board runtime into an ELF.

    Args:
        sources: ``.c``, ``.cpp``/``.cc`` and ``.S`` files; one of them defines ``int main(void)``
            (its return value becomes QEMU's exit status through semihosting).
        target: ``"m4f"``, ``"m0"`` or a :class:`Target`.
        include_dirs: extra ``-I`` directories (the board directory and ``firmware/app`` for
            ``kf_hal.h`` are always included).
        defines: ``-D`` macros (value None gives a bare ``-DNAME``).
        opt: optimisation flag, ``"-O2"`` (default) or ``"-Os"``, ...
        name: base name of the outputs.
        out_dir: where to put ELF/BIN/HEX/map; default a content-hashed cache directory.
        hal: link the board HAL (UART, SysTick clock, storage); off for pure compute programs.
        libc: ``"nosys"`` (newlib, no I/O; the default) or ``"rdimon"`` (newlib with
            semihosting stdio: ``printf`` works, newlib's crt0 runs ``main``).
        extra_cflags / extra_ldflags: appended after the standard flags.
        cache: reuse an identical earlier build (only when ``out_dir`` is None).

    Returns a :class:`BuildResult`; raises :class:`BuildError` (one-line message, full
    compiler output in ``.log``) or :class:`ToolchainError`.
    """
    tgt = get_target(target)
    if libc not in ("nosys", "rdimon"):
        raise KinefuseError(f"libc must be 'nosys' or 'rdimon', not {libc!r}")
    srcs = [Path(s).resolve() for s in sources]
    for s in srcs:
        if not s.is_file():
            raise KinefuseError(f"source file not found: {s}")
    srcs += board_sources(tgt.board, hal)
    incs = [Path(d).resolve() for d in include_dirs] + [BOARD_DIRS[tgt.board], HAL_INCLUDE_DIR]
    defs = dict(defines or {})
    if libc == "rdimon":
        defs["KF_NEWLIB_CRT0"] = None
    dflags = [f"-D{k}" if v is None else f"-D{k}={v}" for k, v in sorted(defs.items())]
    base = list(tgt.arch_flags) + [opt] + list(COMMON_FLAGS) + dflags + [f"-I{d}" for d in incs]
    has_cxx = any(s.suffix in CXX_SUFFIXES for s in srcs)
    ld_script = BOARD_DIRS[tgt.board] / "mps2.ld"
    link_flags = [f"-T{ld_script}", "-Wl,--gc-sections"]
    if libc == "rdimon":
        link_flags += ["--specs=rdimon.specs"]
    else:
        link_flags += ["-nostartfiles", "--specs=nosys.specs"]
    link_flags += list(extra_ldflags)

    gcc, gxx = tool("gcc"), tool("g++")
    key_material = _hash_inputs(srcs, incs, [base, list(C_FLAGS), list(CXX_FLAGS), list(extra_cflags),
                                             link_flags, [name]],
                                _compiler_version(gcc), ld_script)
    if out_dir is None:
        final_dir = cache_dir("build", key_material[:20])
        if cache and (final_dir / f"{name}.elf").is_file() and (final_dir / "ok").is_file():
            return _result(tgt, final_dir, name, opt, cached=True)
        work = Path(tempfile.mkdtemp(prefix=".tmp-", dir=final_dir.parent))
    else:
        final_dir = Path(out_dir)
        final_dir.mkdir(parents=True, exist_ok=True)
        work = final_dir

    commands: list[list[str]] = []
    objs: list[Path] = []
    jobs = []
    for i, src in enumerate(srcs):
        obj = work / f"{i:02d}_{src.stem}.o"
        objs.append(obj)
        if src.suffix in CXX_SUFFIXES:
            cmd = [gxx] + base + list(CXX_FLAGS) + list(extra_cflags) + ["-c", str(src), "-o", str(obj)]
        elif src.suffix in ASM_SUFFIXES:
            cmd = [gcc] + base + ["-c", str(src), "-o", str(obj)]
        else:
            cmd = [gcc] + base + list(C_FLAGS) + list(extra_cflags) + ["-c", str(src), "-o", str(obj)]
        jobs.append(cmd)
    try:
        with ThreadPoolExecutor(max_workers=max(1, min(4, os.cpu_count() or 1))) as pool:
            for cmd, proc in zip(jobs, pool.map(_compile, jobs)):
                commands.append(cmd)
                if proc.returncode != 0:
                    raise BuildError(_first_error(proc.stderr, f"compiling failed for {tgt.name}"),
                                     proc.stderr, cmd)
        elf = work / f"{name}.elf"
        link = [gxx if has_cxx else gcc] + list(tgt.arch_flags) + [opt] + [str(o) for o in objs] \
            + link_flags + [f"-Wl,-Map={work / (name + '.map')}", "-o", str(elf)] + ["-lm"]
        commands.append(link)
        proc = subprocess.run(link, capture_output=True, text=True)
        if proc.returncode != 0:
            raise BuildError(_first_error(proc.stderr, f"linking failed for {tgt.name}"), proc.stderr, link)
        _run([tool("objcopy"), "-O", "binary", str(elf), str(work / f"{name}.bin")], "objcopy")
        _run([tool("objcopy"), "-O", "ihex", str(elf), str(work / f"{name}.hex")], "objcopy")
    except BaseException:
        if out_dir is None:      # a failed build leaves no half-built temporary directory behind
            shutil.rmtree(work, ignore_errors=True)
            try:
                final_dir.rmdir()        # nor the empty cache entry (only when empty)
            except OSError:
                pass
        raise

    if out_dir is None:
        (work / "ok").write_text("\n".join(" ".join(c) for c in commands) + "\n")
        try:
            if final_dir.exists():
                shutil.rmtree(final_dir)
            work.rename(final_dir)
        except OSError:          # another process finished the same build first: use theirs
            shutil.rmtree(work, ignore_errors=True)
    res = _result(tgt, final_dir, name, opt, cached=False)
    res.commands = commands
    return res


def size_of(elf: str | os.PathLike) -> SizeReport:
    """Berkeley section sizes of an ELF (``arm-none-eabi-size -B``)."""
    out = _run([tool("size"), "-B", str(elf)], "size").stdout.splitlines()
    text, data, bss = (int(v) for v in out[1].split()[:3])
    return SizeReport(text, data, bss)


_ALLOC_OUTPUTS = {".vectors": "text", ".text": "text", ".ARM.extab": "text", ".ARM.exidx": "text",
                  ".init_array": "text", ".data": "data", ".bss": "bss", ".noinit": "bss"}
_MAP_INPUT = re.compile(r"^ (\S+)?\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)\s+(\S.*)$")


def map_size_by_origin(map_path: str | os.PathLike) -> dict[str, SizeReport]:
    """Sum a GNU ld map's allocated input sections by origin (see ``size_by_origin``)."""
    sums: dict[str, list[int]] = {}
    kind_index = {"text": 0, "data": 1, "bss": 2}
    current: str | None = None
    in_map = False
    pending_name = False
    for line in Path(map_path).read_text(errors="replace").splitlines():
        if line.startswith("Linker script and memory map"):
            in_map = True
            continue
        if not in_map:
            continue
        if line and not line[0].isspace():
            out_name = line.split()[0]
            current = _ALLOC_OUTPUTS.get(out_name)
            continue
        if current is None:
            continue
        if line.startswith(" *fill*"):
            parts = line.split()
            if len(parts) >= 3:
                sums.setdefault("*fill*", [0, 0, 0])[kind_index[current]] += int(parts[2], 16)
            continue
        m = _MAP_INPUT.match(line)
        if m is None:
            pending_name = bool(re.match(r"^ \S+$", line))   # long section name on its own line
            continue
        if m.group(1) is None and not pending_name:
            continue
        pending_name = False
        size = int(m.group(3), 16)
        origin = m.group(4).strip()
        if size == 0 or origin.startswith("load address"):
            continue
        arch = re.search(r"([^/]+\.a)\(", origin)
        if arch:
            key = arch.group(1)
        else:
            key = re.sub(r"^\d+_", "", Path(origin).stem)
        sums.setdefault(key, [0, 0, 0])[kind_index[current]] += size
    return {k: SizeReport(*v) for k, v in sums.items()}


# ---------------------------------------------------------------------------------------------

def _result(tgt: Target, d: Path, name: str, opt: str, cached: bool) -> BuildResult:
    elf = d / f"{name}.elf"
    return BuildResult(tgt, elf, d / f"{name}.bin", d / f"{name}.hex", d / f"{name}.map",
                       size_of(elf), opt, cached)


def _compile(cmd: list[str]) -> subprocess.CompletedProcess:
    return subprocess.run(cmd, capture_output=True, text=True)


def _run(cmd: list[str], what: str) -> subprocess.CompletedProcess:
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        raise BuildError(_first_error(proc.stderr, f"{what} failed"), proc.stderr, cmd)
    return proc


def _first_error(stderr: str, fallback: str) -> str:
    for line in stderr.splitlines():
        if re.search(r"\berror\b|undefined reference|cannot find", line):
            return line.strip()[:300]
    return fallback


_VERSION_CACHE: dict[str, str] = {}


def _compiler_version(gcc: str) -> str:
    if gcc not in _VERSION_CACHE:
        _VERSION_CACHE[gcc] = subprocess.run([gcc, "--version"], capture_output=True,
                                             text=True).stdout.splitlines()[0]
    return _VERSION_CACHE[gcc]


def _hash_inputs(srcs: list[Path], incs: list[Path], flags: list[list[str]], version: str,
                 ld_script: Path) -> str:
    h = hashlib.sha256()
    h.update(repr(flags).encode())
    h.update(version.encode())
    files = list(srcs) + [ld_script]
    for d in incs:
        if d.is_dir():
            files += sorted(p for p in d.rglob("*") if p.suffix in HEADER_SUFFIXES and p.is_file())
    # ``#include "x.h"`` finds headers next to the including source without any -I: a changed
    # header there must rebuild too (not recursive: a source may sit in a large directory)
    seen = set(files)
    for d in sorted({s.parent for s in srcs}):
        files += sorted(p for p in d.glob("*") if p.suffix in HEADER_SUFFIXES and p.is_file()
                        and p not in seen)
    for f in files:
        h.update(str(f).encode())
        h.update(f.read_bytes())
    return h.hexdigest()
