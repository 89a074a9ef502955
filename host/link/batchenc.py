"""Vectorised encoding of many frames of one message type (numpy), byte-identical to pymavlink.

    data = encode_batch("KF_RAW_SAMPLE", {"time_boot_us": t, "acc_x": ax, ...}, sysid=1, compid=200)

Fields missing from ``values`` are zero; arrays are (N, n) columns.  MAVLink 2 trailing-zero
truncation is applied frame by frame, the CRC is computed per payload length group with the
65536-entry table.  Used to feed simulations (HIL_SENSOR at 1 kHz), benchmarks and tests.
"""
from __future__ import annotations

import numpy as np

from kinefuse.host.link.crc import crc_numpy
from kinefuse.host.link.spec import Dialect, kinefuse_dialect


def payload_matrix(spec, values, n: int | None = None) -> np.ndarray:
    """(N, payload length) uint8 matrix of full, untruncated payloads."""
    if isinstance(values, np.ndarray) and values.dtype.names:
        n = values.shape[0] if n is None else n
        get = lambda name: values[name] if name in values.dtype.names else None  # noqa: E731
    else:
        lengths = {len(np.atleast_1d(v)) for v in values.values() if np.ndim(v) > 0}
        n = n if n is not None else (lengths.pop() if len(lengths) == 1 else None)
        if n is None:
            raise ValueError("give n, or value arrays of one common length")
        unknown = set(values) - set(spec.fields)
        if unknown:
            raise KeyError(f"{spec.name} has no field(s) {sorted(unknown)}")
        get = values.get
    rec = np.zeros(n, dtype=spec.dtype)
    for name in spec.fields:
        v = get(name)
        if v is not None:
            rec[name] = v
    return rec.view(np.uint8).reshape(n, spec.length)


def encode_batch(message, values, sysid: int = 255, compid: int = 190, seq0: int = 0, n: int | None = None,
                 dialect: Dialect | None = None) -> bytes:
    """N frames of ``message`` (unsigned), sequence numbers seq0, seq0 + 1, ... (mod 256)."""
    dialect = dialect or kinefuse_dialect()
    spec = dialect[message]
    pay = payload_matrix(spec, values, n)
    n = pay.shape[0]
    if n == 0:
        return b""
    nz = pay != 0
    plen = np.where(nz.any(axis=1), spec.length - np.argmax(nz[:, ::-1], axis=1), 1)  # at least one byte
    head = np.zeros((n, 10), np.uint8)
    head[:, 0] = 0xFD
    head[:, 1] = plen
    head[:, 4] = (seq0 + np.arange(n)) & 0xFF
    head[:, 5] = sysid
    head[:, 6] = compid
    head[:, 7] = spec.msgid & 0xFF
    head[:, 8] = (spec.msgid >> 8) & 0xFF
    head[:, 9] = spec.msgid >> 16
    size = 12 + plen
    offsets = np.concatenate([[0], np.cumsum(size)[:-1]])
    out = np.empty(int(size.sum()), np.uint8)
    lengths = np.unique(plen)
    for length in lengths:
        rows = np.flatnonzero(plen == length)
        length = int(length)
        frame = np.empty((rows.size, 12 + length), np.uint8)
        frame[:, :10] = head[rows]
        frame[:, 10:10 + length] = pay[rows, :length]
        crc = crc_numpy(frame[:, 1:10 + length], spec.crc_extra)
        frame[:, 10 + length] = crc & 0xFF
        frame[:, 11 + length] = crc >> 8
        if lengths.size == 1:  # all frames of one length: the matrix is the stream
            return frame.tobytes()
        out[offsets[rows, None] + np.arange(12 + length)] = frame
    return out.tobytes()
