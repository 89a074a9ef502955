"""Optional compiled frame scanner (``scan.c``) for the streaming decoder, via cffi (ABI mode).

Compiled on first use with ``$CC`` or ``gcc`` (``-O2 -std=c99 -shared -fPIC``) into a cache
folder (``$KINEFUSE_CACHE`` or ``~/.cache/kinefuse``) under a name holding the SHA-256 of the
source and flags, so an edited source is rebuilt and concurrent processes never see a half-written
library (written to a temporary name, then renamed).  Without a compiler, or with
``KINEFUSE_PURE_PYTHON=1``, the decoder uses its pure-Python scanner (same frames, slower).
"""
from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import sys
import tempfile
from functools import lru_cache
from pathlib import Path

SOURCE = Path(__file__).with_name("scan.c")
CFLAGS = ["-O2", "-std=c99", "-shared", "-fPIC"]
CDEF = """
int32_t kf_scan(const uint8_t *buf, int32_t n, int32_t final,
                const uint32_t *keys, const uint16_t *vals, uint32_t mask,
                int32_t *starts, uint64_t *counters, int32_t *keep);
"""
EMPTY = 0xFFFFFFFF


def cache_dir() -> Path:
    return Path(os.environ.get("KINEFUSE_CACHE") or Path.home() / ".cache" / "kinefuse")


@lru_cache(maxsize=None)
def load():
    """(ffi, lib) or None when no compiled scanner can be had."""
    if os.environ.get("KINEFUSE_PURE_PYTHON") or sys.platform.startswith("win"):
        return None
    try:
        from cffi import FFI
    except ImportError:
        return None
    cc = os.environ.get("CC") or shutil.which("gcc") or shutil.which("cc")
    if not cc:
        return None
    src = SOURCE.read_bytes()
    tag = hashlib.sha256(src + " ".join(CFLAGS).encode() + cc.encode()).hexdigest()[:16]
    lib_path = cache_dir() / f"kf_scan_{tag}.so"
    try:
        if not lib_path.exists():
            lib_path.parent.mkdir(parents=True, exist_ok=True)
            fd, tmp = tempfile.mkstemp(prefix="kf_scan_", suffix=".so", dir=lib_path.parent)
            os.close(fd)
            try:
                subprocess.run([cc, *CFLAGS, "-o", tmp, str(SOURCE)], check=True, capture_output=True, timeout=120)
                os.replace(tmp, lib_path)
            finally:
                if os.path.exists(tmp):
                    os.unlink(tmp)
        ffi = FFI()
        ffi.cdef(CDEF)
        return ffi, ffi.dlopen(str(lib_path))
    except (OSError, subprocess.SubprocessError):
        return None


def message_table(module):
    """Open-addressing table of the dialect's ids for ``kf_scan``: (keys, vals, mask) as cffi arrays."""
    native = load()
    if native is None:
        return None
    ffi, _ = native
    items = [(mid, cls.crc_extra, cls.unpacker.size) for mid, cls in module.mavlink_map.items()]
    size = 1
    while size < 4 * len(items):
        size *= 2
    mask = size - 1
    keys = [EMPTY] * size
    vals = [0] * size
    for mid, extra, length in items:
        h = (mid * 2654435761) & 0xFFFFFFFF & mask
        while keys[h] != EMPTY:
            h = (h + 1) & mask
        keys[h] = mid
        vals[h] = extra | (length << 8)
    return ffi.new("uint32_t[]", keys), ffi.new("uint16_t[]", vals), mask
