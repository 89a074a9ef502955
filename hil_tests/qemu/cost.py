"""Exact per-call instruction counts and the flash/RAM a function adds, on M4F and M0.

Instructions per call (``instructions_per_call``): one driver program runs ``setup`` once and
the ``call`` snippet K times, K read at run time; the same ELF is run with K calls and with 0
calls under the counting plugin and ``(count(K) - count(0)) / K`` is returned.  Everything the
call executes is included (callees, soft-float and libm routines, ``memcpy``), plus the
driver's loop (counter increment, compare, branch: :func:`loop_overhead` measures it with an
empty call so it can be subtracted).  Counts are exact and deterministic; how many *cycles*
they take on silicon depends on the instruction mix, wait states and memory (see the
Cortex-M4 table in ``shared/notes/toolchain.md``), so cycles are an estimate.

Size (``size_delta``): the same driver linked with ``--gc-sections`` with and without the
setup/call (``KF_COST_BASELINE``); the difference of ``arm-none-eabi-size`` is what the code
adds: flash = text + data, RAM = data + bss (static state only; stack not included).  Report
``-Os`` (size-optimised, the usual flash figure) and ``-O2`` (the build whose instructions are
counted) — :func:`measure_call_cost` does both when asked.
"""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Iterable, Mapping, Sequence

from kinefuse.firmware.targets import BuildResult, SizeReport, Target, build, get_target
from kinefuse.hil_tests.qemu.batch import render_template, write_generated
from kinefuse.hil_tests.qemu.insn import count_instructions
from kinefuse.host.errors import KinefuseError

Paths = Iterable[str | os.PathLike]


@dataclass
class CallCost:
    """Cost of one call snippet on one target."""

    target: str
    k: int
    count_k: int                 # instructions of the whole program with K calls
    count_0: int                 # ... with 0 calls
    per_call: float              # (count_k - count_0) / k
    opt: str
    size: dict[str, SizeReport] = field(default_factory=dict)   # opt flag -> size delta
    size_origin: dict[str, dict[str, SizeReport]] = field(default_factory=dict)  # opt -> origin -> delta
    build: BuildResult | None = None

    def as_dict(self) -> dict:
        return {"target": self.target, "k": self.k, "count_k": self.count_k,
                "count_0": self.count_0, "instructions_per_call": self.per_call, "opt": self.opt,
                "size": {o: s.as_dict() for o, s in self.size.items()},
                "size_by_origin": {o: {k: v.as_dict() for k, v in d.items()}
                                   for o, d in self.size_origin.items()}}


def cost_program(sources: Paths, setup: str, call: str, target: str | Target, *,
                 prelude: str = "", finish: str = "", baseline_code: str = "",
                 include_dirs: Paths = (),
                 defines: Mapping[str, str | int | None] | None = None, opt: str = "-O2",
                 language: str = "c", baseline: bool = False,
                 extra_cflags: Sequence[str] = (), extra_ldflags: Sequence[str] = ()) -> BuildResult:
    """Build the cost driver (``baseline=True``: without setup and call, for size deltas)."""
    if language not in ("c", "c++"):
        raise KinefuseError(f"language must be 'c' or 'c++', not {language!r}")
    text = render_template("cost_driver.c", {"PRELUDE": prelude, "SETUP": setup, "CALL": call,
                                             "FINISH": finish, "BASELINE": baseline_code})
    driver = write_generated(text, "kf_cost_driver.cpp" if language == "c++" else "kf_cost_driver.c")
    defs = dict(defines or {})
    if baseline:
        defs["KF_COST_BASELINE"] = None
    return build([*sources, driver], get_target(target), include_dirs=include_dirs, defines=defs,
                 opt=opt, name="cost_base" if baseline else "cost", hal=False,
                 extra_cflags=extra_cflags, extra_ldflags=extra_ldflags)


def count_calls(elf_build: BuildResult, k: int, timeout: float = 120.0) -> int:
    """Total instructions of a cost program run with ``k`` calls."""
    if not 0 <= k < 10 ** 10:
        raise KinefuseError("k must be between 0 and 9 999 999 999")
    return count_instructions(elf_build.elf, elf_build.target, args=[f"{k:010d}"],
                              timeout=timeout).total


def measure_call_cost(sources: Paths, setup: str, call: str, target: str | Target, *,
                      k: int = 100, prelude: str = "", finish: str = "",
                      baseline_code: str = "", include_dirs: Paths = (),
                      defines: Mapping[str, str | int | None] | None = None,
                      opt: str = "-O2", size_opts: Sequence[str] = (),
                      language: str = "c", extra_cflags: Sequence[str] = (),
                      timeout: float = 120.0) -> CallCost:
    """Instructions per call at ``opt`` and, for each flag in ``size_opts``, the size delta.

    Snippets: ``prelude`` (file scope: includes, static data), ``setup`` (once, in a block
    that the call loop shares, so it may declare locals), ``call`` (K times; ``kf_i`` is the
    0-based call index), ``finish`` (once after the loop).  ``baseline_code`` runs instead of
    them in the size baseline program: use it to keep shared input tables referenced there
    (e.g. ``kf_keep(table);``) so they do not count as added by the call.
    """
    if k <= 0:
        raise KinefuseError("k must be positive")
    tgt = get_target(target)
    common = dict(prelude=prelude, finish=finish, baseline_code=baseline_code,
                  include_dirs=list(include_dirs), defines=defines, language=language,
                  extra_cflags=extra_cflags)
    sources = list(sources)
    prog = cost_program(sources, setup, call, tgt, opt=opt, **common)
    c0 = count_calls(prog, 0, timeout)
    ck = count_calls(prog, k, timeout)
    result = CallCost(tgt.name, k, ck, c0, (ck - c0) / k, opt, build=prog)
    for size_opt in size_opts:
        total, origin = size_delta_by_origin(sources, setup, call, tgt, opt=size_opt, **common)
        result.size[size_opt] = total
        result.size_origin[size_opt] = origin
    return result


def instructions_per_call(sources: Paths, setup_snippet: str, call_snippet: str,
                          target: str | Target, k: int = 100, **kwargs) -> float:
    """``(count(K calls) - count(0 calls)) / K`` for ``call_snippet`` on ``target``.

    Keyword arguments as in :func:`measure_call_cost` (``prelude``, ``include_dirs``,
    ``defines``, ``opt``, ``language``, ...).  Includes the driver loop's own instructions
    (see :func:`loop_overhead`).
    """
    return measure_call_cost(sources, setup_snippet, call_snippet, target, k=k, **kwargs).per_call


def loop_overhead(target: str | Target, *, opt: str = "-O2", k: int = 100) -> float:
    """Instructions per iteration of the cost driver's loop around an empty call."""
    return instructions_per_call([], "", '__asm__ volatile("");', target, k=k, opt=opt)


def size_delta(sources: Paths, setup: str, call: str, target: str | Target, **kwargs) -> SizeReport:
    """Bytes the setup + call add: size(driver with them) - size(driver without them).

    Keyword arguments: ``opt`` (default ``-Os``), ``prelude``, ``finish``, ``baseline_code``,
    ``include_dirs``, ``defines``, ``language``, ``extra_cflags``.
    """
    return size_delta_by_origin(sources, setup, call, target, **kwargs)[0]


def size_delta_by_origin(sources: Paths, setup: str, call: str, target: str | Target, *,
                         opt: str = "-Os", prelude: str = "", finish: str = "",
                         baseline_code: str = "", include_dirs: Paths = (),
                         defines: Mapping[str, str | int | None] | None = None,
                         language: str = "c", extra_cflags: Sequence[str] = ()
                         ) -> tuple[SizeReport, dict[str, SizeReport]]:
    """:func:`size_delta` and its split by origin (the sources' objects by stem, ``libm.a``,
    ``libgcc.a``, ``libc.a``...; from the linker maps), zero entries left out."""
    sources = list(sources)
    common = dict(prelude=prelude, finish=finish, baseline_code=baseline_code,
                  include_dirs=list(include_dirs), defines=defines, opt=opt, language=language,
                  extra_cflags=extra_cflags)
    with_it = cost_program(sources, setup, call, target, **common)
    without = cost_program(sources, setup, call, target, baseline=True, **common)
    a, b = with_it.size_by_origin(), without.size_by_origin()
    zero = SizeReport(0, 0, 0)
    origin = {k: a.get(k, zero) - b.get(k, zero) for k in sorted(set(a) | set(b))}
    origin = {k: v for k, v in origin.items() if v != zero}
    return with_it.size - without.size, origin
