"""File-format readers returning one common :class:`Recording` (t s, acc m/s², gyr rad/s,
mag µT, device quaternion (w,x,y,z) if present, extra channels, metadata).

Formats (``fmt`` names): ``xsens-dot``, ``matrix``, ``metabase``, ``seed004-arduino``,
``broad-mat``, ``kinefuse-csv``, ``kfr``.  :func:`read_recording` detects the format from the
header (or the ``.mat`` / ``.npz`` / ``.kfr`` extension) unless ``fmt`` is given.

``kfr``: kinefuse units' recordings (``kinefuse record``), see :mod:`.kfr`.  One file may hold
several units: choose one with ``unit=`` (MAVLink system id = unit id, or ``s<stream>:<id>``);
times are on the host clock (device clock offset and drift fitted out), so units of one file
are synchronised; lost samples stay gaps.  ``fmt="kfr"`` also reads a raw MAVLink capture
(then on the unit's own clock); a ``.tlog`` is read as ``kfr`` too.  Every reader fails with a one-line
:class:`ReaderError` naming the file, the line and the problem.
"""
from __future__ import annotations

import os

from kinefuse.host.readers import broad, kfr, kinefuse_csv, matrix, metabase, seed004, xsens_dot
from kinefuse.host.readers.recording import ReaderError, Recording

READERS = {
    xsens_dot.FORMAT: xsens_dot.read,
    matrix.FORMAT: matrix.read,
    metabase.FORMAT: metabase.read,
    seed004.FORMAT: seed004.read,
    broad.FORMAT: broad.read,
    kinefuse_csv.FORMAT: kinefuse_csv.read,
    kfr.FORMAT: kfr.read,
}

__all__ = ["READERS", "ReaderError", "Recording", "detect_format", "read_recording"]


def _check_file(path: str) -> None:
    if not os.path.exists(path):
        raise ReaderError(path, "file not found")
    if os.path.isdir(path):
        raise ReaderError(path, "is a directory; give one recording file")
    if not os.path.isfile(path):   # a pipe is read more than once (detection, then the reader): data went missing
        raise ReaderError(path, "is not a regular file (a pipe or a device): save the recording to a file first")


def detect_format(path: str | os.PathLike) -> str:
    path = os.fspath(path)   # a Path was an AttributeError (path.lower())
    _check_file(path)
    if path.lower().endswith((".mat", ".npz")):
        return broad.FORMAT
    if path.lower().endswith((".kfr", ".tlog")):   # a telemetry log: read as kfr.py says
        return kfr.FORMAT
    try:
        if os.path.getsize(path) == 0:
            raise ReaderError(path, "the file is empty (0 bytes): no samples to read")
        with open(path, "rb") as f:
            if kfr.sniff_bytes(f.read(16)):
                return kfr.FORMAT
    except OSError as exc:
        raise ReaderError(path, f"cannot open ({exc.strerror})") from None
    try:
        with open(path, "rb") as f:
            raw = f.read(1 << 16)
    except OSError as exc:
        raise ReaderError(path, f"cannot open ({exc.strerror})") from None
    # UTF-16 with its BOM (Excel's "Unicode Text"): read as the table reader reads it
    enc = "utf-16" if raw[:2] in (b"\xff\xfe", b"\xfe\xff") else "utf-8-sig"
    head = (raw.decode(enc, errors="replace").splitlines(True) + [""] * 25)[:25]
    from kinefuse.host.readers.table import sniff_sep
    sep = sniff_sep([l for l in head if l.strip()][:10] or [","])
    for line in head:
        cells = [c.strip().strip('"') for c in line.rstrip("\r\n").split(sep)]
        for mod in (xsens_dot, matrix, metabase, kinefuse_csv):
            if mod.sniff(cells):
                return mod.FORMAT
    if seed004.sniff_lines(head):
        return seed004.FORMAT
    raise ReaderError(path, "unknown recording format (expected Xsens DOT, MATRIX, MetaBase, "
                            "seed-004 Arduino or kinefuse CSV, a BROAD .mat or bundled .npz trial, or a .kfr "
                            "unit recording)")


def read_recording(path: str | os.PathLike, fmt: str | None = None, **options) -> Recording:
    """Read ``path`` (format auto-detected unless ``fmt``); options go to the reader
    (``fs`` for MATRIX/seed-004, ``gyro_range_dps`` for MetaBase, ``acc_range_g`` for MATRIX,
    ``unit`` for ``kfr``)."""
    path = os.fspath(path)
    fmt = fmt or detect_format(path)
    if fmt not in READERS:
        raise ReaderError(path, f"unknown format {fmt!r}; choose one of {', '.join(READERS)}")
    _check_file(path)   # with fmt given too: a folder was an internal IsADirectoryError ("file not found" for .mat)
    return READERS[fmt](path, **options)
