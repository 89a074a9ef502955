"""Host build of generated C through cffi (API mode), cached by content hash.

Flags are explicit and come last, so they override what cffi takes from Python's sysconfig
(``-fwrapv -O3`` ...): ``-O2 -std=c99 -ffp-contract=off -fno-wrapv -fno-fast-math``.
The module name is a hash of sources + flags; parallel builds are serialised with a lock file.
"""
from __future__ import annotations

import fcntl
import hashlib
import importlib.util
import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from kinefuse.codegen.generate import GENERATED_DIR

HOST_CFLAGS = ["-O2", "-std=c99", "-ffp-contract=off", "-fno-wrapv", "-fno-fast-math",
               # sqrtf inline without the errno call path (results are the same: both are
               # the correctly rounded square root)
               "-fno-math-errno",
               "-Wall", "-Wno-unused-function", "-Wno-unused-variable",
               # cffi adds -g; GCC's variable tracking then dominates the build of a long
               # generated function (a 9k-statement EKF update: 24 s -> 10 s).  Debug info only:
               # the generated code is unchanged.
               "-fno-var-tracking-assignments"]


def cache_dir() -> Path:
    d = Path(os.environ.get("KINEFUSE_CACHE", Path.home() / ".cache" / "kinefuse")) / "cffi"
    d.mkdir(parents=True, exist_ok=True)
    return d


def host_cc() -> str:
    """The C compiler command setuptools (hence cffi) compiles with: $CC, else Python's own."""
    return os.environ.get("CC") or sysconfig.get_config_var("CC") or "cc"


_CC_IDENTITY: dict[str, str] = {}


def compiler_identity() -> str:
    """The command and ``--version`` output of :func:`host_cc` (run once per process and
    command)."""
    cc = host_cc()
    if cc not in _CC_IDENTITY:
        argv = shlex.split(cc)
        try:
            out = subprocess.run([argv[0], "--version"], capture_output=True, text=True,
                                 timeout=60)
            text = out.stdout + out.stderr
        except (OSError, subprocess.SubprocessError) as exc:
            text = f"unavailable: {exc}"      # the build itself then reports the problem
        _CC_IDENTITY[cc] = f"{cc}\n{text}"
    return _CC_IDENTITY[cc]


def cdef_of(header_text: str) -> str:
    """Declarations cffi can parse: the header without preprocessor lines."""
    return "\n".join(ln for ln in header_text.splitlines() if not ln.lstrip().startswith("#"))


def build(module_stem: str, headers: list[Path], sources: list[Path], extra_cdef: str = "",
          extra_source: str = "", cflags: list[str] | None = None, include_dirs=None):
    """Compile `sources` into a cffi extension exposing `headers`; returns (ffi, lib)."""
    from cffi import FFI

    flags = list(HOST_CFLAGS if cflags is None else cflags)
    include_dirs = [str(d) for d in (include_dirs or [GENERATED_DIR])]
    blob = hashlib.sha256()
    for p in headers + sources:
        blob.update(p.name.encode() + b"\0" + p.read_bytes())
    # the headers the sources may include (kf_fixed.h, the shared input types): a change there
    # must rebuild too, not load a module compiled against the old text
    for inc in include_dirs:
        for h in sorted(Path(inc).glob("*.h")):
            blob.update(h.name.encode() + b"\0" + h.read_bytes())
        blob.update(b"\1")     # one folder's headers end here
    # the folders' contents, not their paths: the same code generated into another temporary
    # folder loads the module built before instead of compiling (and caching) another copy
    blob.update(repr((flags, extra_cdef, extra_source, len(include_dirs), sys.version)).encode())
    # a compiler upgrade must rebuild, not load a module the old compiler made
    blob.update(compiler_identity().encode())
    name = f"_kf_{re.sub(r'[^a-zA-Z0-9_]', '_', module_stem)}_{blob.hexdigest()[:16]}"
    d = cache_dir()
    existing = _find_built(d, name)
    if existing is None:
        with open(d / f"{name}.lock", "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            existing = _find_built(d, name)
            if existing is None:
                ffi = FFI()
                cdef = "\n".join(cdef_of(h.read_text()) for h in headers) + "\n" + extra_cdef
                ffi.cdef(cdef)
                includes = "".join(f'#include "{h.name}"\n' for h in headers)
                ffi.set_source(name, includes + extra_source,
                               sources=[str(s) for s in sources], include_dirs=include_dirs,
                               extra_compile_args=flags)
                tmp = d / f"build_{name}_{os.getpid()}"
                try:
                    path = ffi.compile(tmpdir=str(tmp), verbose=False)
                    final = d / Path(path).name
                    os.replace(path, final)
                finally:
                    shutil.rmtree(tmp, ignore_errors=True)   # objects and C: only the .so is kept
                existing = final
    return _load(name, existing)


def _find_built(d: Path, name: str):
    for p in d.glob(f"{name}*.so"):
        return p
    return None


_LOADED: dict[str, object] = {}


def _load(name: str, path: Path):
    if name not in _LOADED:
        spec = importlib.util.spec_from_file_location(name, path)
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        _LOADED[name] = mod
    mod = _LOADED[name]
    return mod.ffi, mod.lib


def build_filter(name: str, system: str, gen_dir: Path = GENERATED_DIR):
    """Build the committed generated C of one filter; returns (ffi, lib)."""
    from kinefuse.codegen.estimator import generated_stem
    P = generated_stem(name, system)
    header = gen_dir / f"{P}.h"
    if not header.exists():
        raise FileNotFoundError(f"{header} does not exist; run `kinefuse codegen`")
    m = re.search(r'#include "(kf_\w+\.h)"', header.read_text())
    if m is None:      # not an AttributeError from deep in here
        raise ValueError(f"{header} does not include its input record header (kf_<record>_"
                         f"{system}.h): edited by hand? run `kinefuse codegen`")
    return build(P, [gen_dir / m.group(1), header], [gen_dir / f"{P}.c"], include_dirs=[gen_dir])
