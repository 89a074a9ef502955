"""Batch decoding of one message type from a large buffer into a numpy structured array.

    arr, info = decode_batch(data, "KF_RAW_SAMPLE")
    arr["acc_x"], arr["time_boot_us"], arr["offset"], arr["sysid"] ...

Every 0xFD whose header names the wanted message id with a possible length and incompat flags
is a candidate; the CRC of all candidates of the same payload length is computed at once with
numpy (one table lookup per byte column); overlapping accepted frames keep the first, like the
streaming decoder.  Payloads truncated by MAVLink 2 (trailing zeros) are zero-padded.

Difference from the streaming decoder: frames of other types are not parsed, so a wanted-type
frame hidden inside another frame's payload would be found here (it needs 0xFD, the 3-byte id,
a valid length and a matching 16-bit CRC by chance: ~2^-50 per byte of payload).
"""
from __future__ import annotations

import hashlib

import numpy as np

from kinefuse.host.link.crc import crc_numpy
from kinefuse.host.link.spec import Dialect, kinefuse_dialect

HEADER_FIELDS = [("offset", "<i8"), ("seq", "u1"), ("sysid", "u1"), ("compid", "u1"), ("signed", "?")]


def _windows(arr: np.ndarray, width: int) -> np.ndarray:
    """Read-only (n - width + 1, width) view: row k is arr[k:k + width] (no copy)."""
    return np.lib.stride_tricks.sliding_window_view(arr, width)


def batch_dtype(spec) -> np.dtype:
    """Header columns + the message's payload fields (wire order)."""
    return np.dtype(HEADER_FIELDS + [(name, spec.dtype.fields[name][0]) for name in spec.fields])


def decode_batch(data, message, dialect: Dialect | None = None, key: bytes | None = None):
    """All valid frames of one message type in ``data``: (structured array, info dict).

    ``info``: candidates, crc_errors (candidates that failed the CRC), overlaps_dropped,
    signature_failures (with ``key``).
    """
    dialect = dialect or kinefuse_dialect()
    spec = dialect[message]
    arr = np.frombuffer(memoryview(data), dtype=np.uint8)
    n = arr.size
    out_dtype = batch_dtype(spec)
    info = {"candidates": 0, "crc_errors": 0, "overlaps_dropped": 0, "signature_failures": 0}
    if n < 12:
        return np.zeros(0, out_dtype), info
    pos = np.flatnonzero(arr[: n - 11] == 0xFD)
    mid = spec.msgid
    sel = ((arr[pos + 7] == (mid & 0xFF)) & (arr[pos + 8] == ((mid >> 8) & 0xFF))
           & (arr[pos + 9] == (mid >> 16)) & (arr[pos + 2] <= 1))
    pos = pos[sel]
    plen = arr[pos + 1].astype(np.int64)
    signed = arr[pos + 2] == 1
    stop = pos + 12 + plen + np.where(signed, 13, 0)
    sel = (plen >= 1) & (plen <= spec.length) & (stop <= n)
    pos, plen, signed, stop = pos[sel], plen[sel], signed[sel], stop[sel]
    info["candidates"] = int(pos.size)

    good = np.zeros(pos.size, dtype=bool)
    for length in np.unique(plen):
        idx = np.flatnonzero(plen == length)
        rows = _windows(arr, 9 + int(length))[pos[idx] + 1]  # header after magic + payload
        crc = crc_numpy(rows, spec.crc_extra)
        got = arr[pos[idx] + 10 + length].astype(np.uint16) | (arr[pos[idx] + 11 + length].astype(np.uint16) << 8)
        good[idx] = crc == got
    info["crc_errors"] = int(pos.size - good.sum())
    pos, plen, signed, stop = pos[good], plen[good], signed[good], stop[good]

    if pos.size > 1 and np.any(pos[1:] < stop[:-1]):  # rare: keep the first of overlapping frames
        keep = np.ones(pos.size, dtype=bool)
        last_stop = -1
        for k in range(pos.size):
            if pos[k] < last_stop:
                keep[k] = False
            else:
                last_stop = stop[k]
        info["overlaps_dropped"] = int((~keep).sum())
        pos, plen, signed, stop = pos[keep], plen[keep], signed[keep], stop[keep]

    if key is not None and signed.any():
        keep = np.ones(pos.size, dtype=bool)
        raw = bytes(data)
        for k in np.flatnonzero(signed):
            s, e = int(pos[k]), int(stop[k])
            if hashlib.sha256(key + raw[s:e - 6]).digest()[:6] != raw[e - 6:e]:
                keep[k] = False
        info["signature_failures"] = int((~keep).sum())
        pos, plen, signed, stop = pos[keep], plen[keep], signed[keep], stop[keep]

    payload = np.zeros((pos.size, spec.length), dtype=np.uint8)
    for length in np.unique(plen):
        idx = np.flatnonzero(plen == length)
        payload[idx, :length] = _windows(arr, int(length))[pos[idx] + 10]
    fields = payload.view(spec.dtype).reshape(-1)
    out = np.empty(pos.size, dtype=out_dtype)
    out["offset"] = pos
    out["seq"] = arr[pos + 4]
    out["sysid"] = arr[pos + 5]
    out["compid"] = arr[pos + 6]
    out["signed"] = signed
    for name in spec.fields:
        out[name] = fields[name]
    return out, info
