"""Run Cortex-M code under QEMU: I/O, batch record processing, exact instruction counts, size.

Built on :mod:`kinefuse.firmware.targets` (cross-compilation for ``m4f`` / ``m0``).

* :func:`run_elf`, :class:`QemuSession` (:mod:`.runner`): run an ELF on ``mps2-an386`` (M4F)
  or ``mps2-an385`` (M0), talk over semihosting stdio or UART0 (TCP loopback or pty).
* :func:`build_batch`, :func:`run_batch` (:mod:`.batch`): N input records in, N output
  records out, around a user step, for bit-pattern comparison with Python models.
* :func:`count_instructions` (:mod:`.insn`): exact executed-instruction counts with a TCG
  plugin, optionally in an address range or between two marker addresses.
* :func:`instructions_per_call`, :func:`measure_call_cost`, :func:`size_delta`,
  :func:`loop_overhead` (:mod:`.cost`): per-call cost and flash/RAM a call adds.
* :mod:`.competitors`: x-io Fusion and VQF fetched from their PyPI sdists and measured the
  same way.
* :func:`qemu_unavailable`: None when everything needed is installed, else why not (tests
  skip with it).
"""
from __future__ import annotations

from kinefuse.firmware.targets import TARGETS, BuildError, BuildResult, SizeReport, build, toolchain_missing
from kinefuse.hil_tests.qemu.batch import BatchProgram, build_batch, run_batch
from kinefuse.hil_tests.qemu.cost import (CallCost, instructions_per_call, loop_overhead,
                                          measure_call_cost, size_delta)
from kinefuse.hil_tests.qemu.insn import InstructionCount, count_instructions, plugin_missing
from kinefuse.hil_tests.qemu.runner import QemuError, QemuSession, RunResult, qemu_missing, run_elf


def qemu_unavailable() -> str | None:
    """None when the ARM toolchain, QEMU and host gcc are all present, else a one-line reason."""
    return toolchain_missing() or qemu_missing() or plugin_missing()


__all__ = [
    "TARGETS", "BuildError", "BuildResult", "SizeReport", "build", "BatchProgram", "build_batch",
    "run_batch", "CallCost", "instructions_per_call", "loop_overhead", "measure_call_cost",
    "size_delta", "InstructionCount", "count_instructions", "QemuError", "QemuSession",
    "RunResult", "run_elf", "qemu_unavailable",
]
