"""Batch programs: push N fixed-size input records through C code on an emulated Cortex-M.

The caller gives C sources, include directories, a step (a C snippet or a function name),
the record sizes and the input bytes; it gets the output bytes back, ready to compare bit
pattern by bit pattern with a Python model::

    from kinefuse.hil_tests.qemu import run_batch
    out = run_batch(["quat.c"], "quat_normalise", in_size=16, out_size=16,
                    data=q.astype("<f4").tobytes(), target="m0", include_dirs=["."])
    q_out = np.frombuffer(out, "<f4").reshape(-1, 4)

A function name ``f`` means ``void f(const void *in, void *out);`` (declared by the driver).
For anything else pass a snippet with ``prelude`` (includes, static state), ``setup`` (run
once) and ``step`` (run per record; ``kf_in`` points to the input record, ``kf_out`` to the
output record, both 8-byte aligned; ``kf_i`` is the record index within the current block)::

    run_batch(srcs, step="kf_mad_step(&st, (const float *)kf_in, (float *)kf_out);",
              prelude='#include "mad.h"\\nstatic kf_mad_state st;',
              setup="kf_mad_init(&st);", in_size=40, out_size=16, data=..., target="m4f")

Transport: semihosting file I/O in blocks of up to 64 KiB (``kf_batch_in.bin`` /
``kf_batch_out.bin`` in a temporary working directory).  Byte order is the target's:
little-endian.
"""
from __future__ import annotations

import hashlib
import os
import re
import tempfile
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Iterable, Mapping, Sequence

from kinefuse.firmware.targets import BuildResult, Target, build, cache_dir, get_target
from kinefuse.hil_tests.qemu.runner import QemuError, RunResult, run_elf
from kinefuse.host.errors import KinefuseError

_IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
BLOCK_BYTES = 64 * 1024       # per semihosting transfer and direction


def render_template(name: str, values: Mapping[str, str]) -> str:
    """Fill a ``csrc`` template's ``@KEY@`` placeholders."""
    text = resources.files("kinefuse.hil_tests.qemu.csrc").joinpath(name).read_text()
    for key, value in values.items():
        text = text.replace(f"@{key}@", value)
    leftover = re.search(r"@[A-Z_]+@", text)
    if leftover:
        raise KinefuseError(f"template {name}: placeholder {leftover.group(0)} not filled")
    return text


def csrc_path(name: str) -> Path:
    """Path of a file shipped in ``hil_tests/qemu/csrc`` (plugin, drivers, self-tests)."""
    path = Path(str(resources.files("kinefuse.hil_tests.qemu.csrc").joinpath(name)))
    if not path.is_file():
        raise KinefuseError(f"missing packaged C source {name}")
    return path


def write_generated(text: str, filename: str) -> Path:
    """Store generated source in a content-addressed cache directory (keeps builds cached)."""
    tag = hashlib.sha256((filename + "\0" + text).encode()).hexdigest()[:20]
    d = cache_dir("generated", tag)
    path = d / filename
    if not path.is_file() or path.read_text() != text:
        fd, tmp = tempfile.mkstemp(dir=d, prefix=".tmp-")   # unique: parallel writers
        with os.fdopen(fd, "w") as f:
            f.write(text)
        os.replace(tmp, path)
    return path


@dataclass
class BatchProgram:
    """A built batch driver; :meth:`run` can be called many times with different inputs."""

    build: BuildResult
    in_size: int
    out_size: int

    @property
    def target(self) -> Target:
        return self.build.target

    def run(self, data: bytes | bytearray | memoryview, *, timeout: float = 120.0) -> bytes:
        """Feed ``len(data) / in_size`` records; return the output records' bytes.

        Raises :class:`QemuError` if the program fails, times out or returns a wrong amount.
        """
        out, _res = self.run_detailed(data, timeout=timeout)
        return out

    def run_detailed(self, data: bytes | bytearray | memoryview, *,
                     timeout: float = 120.0) -> tuple[bytes, RunResult]:
        """Like :meth:`run`, also returning the :class:`RunResult` (wall time, console)."""
        raw = memoryview(data).cast("B")
        if len(raw) % self.in_size:
            raise KinefuseError(f"input is {len(raw)} bytes, not a multiple of the record size "
                                f"{self.in_size}")
        n = len(raw) // self.in_size
        with tempfile.TemporaryDirectory(prefix="kf-batch-") as tmp:
            Path(tmp, "kf_batch_in.bin").write_bytes(raw)
            res = run_elf(self.build.elf, self.target, cwd=tmp, timeout=timeout)
            res.check(f"batch program on {self.target.name}")
            out_path = Path(tmp, "kf_batch_out.bin")
            out = out_path.read_bytes() if out_path.exists() else b""
        if len(out) != n * self.out_size:
            raise QemuError(f"batch program wrote {len(out)} bytes for {n} records, expected "
                            f"{n * self.out_size}")
        return out, res


def build_batch(sources: Iterable[str | os.PathLike], step: str, *,
                in_size: int, out_size: int,
                target: str | Target = "m4f",
                include_dirs: Iterable[str | os.PathLike] = (),
                prelude: str = "", setup: str = "",
                defines: Mapping[str, str | int | None] | None = None,
                opt: str = "-O2",
                language: str = "c",
                extra_cflags: Sequence[str] = ()) -> BatchProgram:
    """Generate and build the batch driver around ``step`` (see the module docstring).

    ``language="c++"`` compiles the driver as C++ (for a C++ step).  Other arguments as in
    :func:`kinefuse.firmware.targets.build`.
    """
    if in_size <= 0 or out_size <= 0:
        raise KinefuseError("record sizes must be positive")
    if language not in ("c", "c++"):
        raise KinefuseError(f"language must be 'c' or 'c++', not {language!r}")
    step = step.strip()
    if _IDENT.fullmatch(step):
        prelude = f"{prelude}\nvoid {step}(const void *in, void *out);"
        step = f"{step}(kf_in, kf_out);"
    per_block = max(1, BLOCK_BYTES // max(in_size, out_size))
    text = render_template("batch_driver.c", {
        "PRELUDE": prelude, "SETUP": setup, "STEP": step,
        "IN_SIZE": str(in_size), "OUT_SIZE": str(out_size), "BLOCK": str(per_block)})
    driver = write_generated(text, "kf_batch_driver.cpp" if language == "c++" else "kf_batch_driver.c")
    res = build([*sources, driver], get_target(target), include_dirs=include_dirs, defines=defines,
                opt=opt, name="batch", hal=False, extra_cflags=extra_cflags)
    return BatchProgram(res, in_size, out_size)


def run_batch(sources: Iterable[str | os.PathLike], step: str, *,
              in_size: int, out_size: int, data: bytes | bytearray | memoryview,
              target: str | Target = "m4f",
              include_dirs: Iterable[str | os.PathLike] = (),
              prelude: str = "", setup: str = "",
              defines: Mapping[str, str | int | None] | None = None,
              opt: str = "-O2", language: str = "c",
              extra_cflags: Sequence[str] = (),
              timeout: float = 120.0) -> bytes:
    """Build (cached) and run a batch program in one call; returns the output bytes."""
    prog = build_batch(sources, step, in_size=in_size, out_size=out_size, target=target,
                       include_dirs=include_dirs, prelude=prelude, setup=setup, defines=defines,
                       opt=opt, language=language, extra_cflags=extra_cflags)
    return prog.run(data, timeout=timeout)
