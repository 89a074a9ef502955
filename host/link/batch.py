"""Batch (numpy) decoding of a complete buffer into structured arrays.

    arr, info = decode_batch(data, "KF_RAW_SAMPLE")   # one message type
    arr["acc_x"], arr["time_boot_us"], arr["_offset"], arr["_sysid"] ...

    result = decode_all(data)                        # every type, same frames as StreamDecoder
    result.arrays[52500], result.counters

Every 0xFD is a candidate.  Its header is read with vectorised indexing, candidates are grouped
by (message id, payload length) and the CRC of each group is computed at once (a 65536-entry
table, one lookup per 16-bit column).  ``decode_all`` then keeps, in order of position, each valid
frame that starts after the end of the previously kept one: exactly the rule of the streaming
decoder (which, after a failed candidate, resumes one byte later), so both give the same frames
and the same counters for the same bytes (a property test checks this).

``decode_batch`` looks at one message type only, so a frame of that type hidden in another
frame's payload would be found here (it needs 0xFD, a 3-byte id, a valid length and a matching
16-bit CRC by chance); use ``decode_all`` when that matters.
"""
from __future__ import annotations

import hashlib
from dataclasses import dataclass, field

import numpy as np

from kinefuse.host.link.crc import crc_numpy
from kinefuse.host.link.decoder import Counters
from kinefuse.host.link.spec import Dialect, MessageSpec, kinefuse_dialect

# header columns start with "_": MAVLink field names never do (PING and MISSION_* have a "seq")
# _len: the payload length as received (tells a status of an older firmware, without the
# extension fields that then decode as 0, from one that sent them)
HEADER_FIELDS = [("_offset", "<i8"), ("_seq", "u1"), ("_sysid", "u1"), ("_compid", "u1"), ("_signed", "?"),
                 ("_len", "u1")]


def _windows(arr: np.ndarray, width: int) -> np.ndarray:
    """Read-only (n - width + 1, width) view: row k is arr[k:k + width] (no copy)."""
    return np.lib.stride_tricks.sliding_window_view(arr, width)


def batch_dtype(spec: MessageSpec) -> np.dtype:
    """Header columns (_offset, _seq, _sysid, _compid, _signed, _len) + the payload fields (wire order)."""
    return np.dtype(HEADER_FIELDS + [(name, spec.dtype.fields[name][0]) for name in spec.fields])


def _crc_ok(arr, pos, plen, crc_extra) -> np.ndarray:
    """CRC check of candidates at ``pos`` (all with the same message id); bool array."""
    good = np.zeros(pos.size, dtype=bool)
    for length in np.unique(plen):
        idx = np.flatnonzero(plen == length)
        p = pos[idx]
        rows = _windows(arr, 9 + int(length))[p + 1]  # header after the magic byte + payload
        crc = crc_numpy(rows, crc_extra)
        got = arr[p + 10 + length].astype(np.uint16) | (arr[p + 11 + length].astype(np.uint16) << 8)
        good[idx] = crc == got
    return good


def _signature_ok(data: bytes, pos, stop, key: bytes) -> np.ndarray:
    ok = np.ones(pos.size, dtype=bool)
    for k in range(pos.size):
        s, e = int(pos[k]), int(stop[k])
        ok[k] = hashlib.sha256(key + data[s:e - 6]).digest()[:6] == data[e - 6:e]
    return ok


def _records(arr, spec: MessageSpec, pos, plen, signed) -> np.ndarray:
    payload = np.zeros((pos.size, spec.length), dtype=np.uint8)
    for length in np.unique(plen):
        idx = np.flatnonzero(plen == length)
        k = min(int(length), spec.length)   # zero-pads truncated payloads, truncates longer ones (MAVLink 2)
        payload[idx, :k] = _windows(arr, k)[pos[idx] + 10]
    fields = payload.view(spec.dtype).reshape(-1)
    out = np.empty(pos.size, dtype=batch_dtype(spec))
    out["_offset"] = pos
    out["_seq"] = arr[pos + 4]
    out["_sysid"] = arr[pos + 5]
    out["_compid"] = arr[pos + 6]
    out["_signed"] = signed
    out["_len"] = plen
    for name in spec.fields:
        out[name] = fields[name]
    return out


def _first_non_overlapping(pos, stop) -> np.ndarray:
    """Greedy in position order: keep a frame if it starts at/after the end of the last kept one."""
    keep = np.ones(pos.size, dtype=bool)
    if pos.size > 1 and np.any(pos[1:] < stop[:-1]):
        last = -1
        for k in range(pos.size):
            if pos[k] < last:
                keep[k] = False
            else:
                last = stop[k]
    return keep


def decode_batch(data, message, dialect: Dialect | None = None, key: bytes | None = None):
    """All valid frames of one message type in ``data``: (structured array, info dict).

    ``info``: candidates, crc_errors (candidates that failed the CRC), overlaps_dropped,
    signature_failures (with ``key``).
    """
    dialect = dialect or kinefuse_dialect()
    spec = dialect[message]
    arr = np.frombuffer(memoryview(data), dtype=np.uint8)
    n = arr.size
    info = {"candidates": 0, "crc_errors": 0, "overlaps_dropped": 0, "signature_failures": 0}
    if n < 12:
        return np.zeros(0, batch_dtype(spec)), info
    pos = np.flatnonzero(arr[: n - 11] == 0xFD)
    mid = spec.msgid
    sel = ((arr[pos + 7] == (mid & 0xFF)) & (arr[pos + 8] == ((mid >> 8) & 0xFF))
           & (arr[pos + 9] == (mid >> 16)) & (arr[pos + 2] <= 1))
    pos = pos[sel]
    plen = arr[pos + 1].astype(np.int64)
    signed = arr[pos + 2] == 1
    stop = pos + 12 + plen + np.where(signed, 13, 0)
    sel = (plen >= 1) & (stop <= n)   # longer payloads: a newer firmware's extensions, truncated
    pos, plen, signed, stop = pos[sel], plen[sel], signed[sel], stop[sel]
    info["candidates"] = int(pos.size)
    good = _crc_ok(arr, pos, plen, spec.crc_extra)
    info["crc_errors"] = int(pos.size - good.sum())
    pos, plen, signed, stop = pos[good], plen[good], signed[good], stop[good]
    keep = _first_non_overlapping(pos, stop)
    info["overlaps_dropped"] = int((~keep).sum())
    pos, plen, signed, stop = pos[keep], plen[keep], signed[keep], stop[keep]
    if key is not None and signed.any():
        ok = np.ones(pos.size, dtype=bool)
        ok[signed] = _signature_ok(bytes(data), pos[signed], stop[signed], key)
        info["signature_failures"] = int((~ok).sum())
        pos, plen, signed, stop = pos[ok], plen[ok], signed[ok], stop[ok]
    return _records(arr, spec, pos, plen, signed), info


@dataclass
class BatchResult:
    arrays: dict = field(default_factory=dict)   # msgid -> structured array (batch_dtype)
    counters: Counters = field(default_factory=Counters)
    #: (start, stop) of every accepted frame, in order (signature-rejected frames excluded)
    spans: np.ndarray = field(default_factory=lambda: np.zeros((0, 2), np.int64))
    #: unknown message id -> candidates (those counted in ``counters.unknown_msgid``)
    unknown_ids: dict = field(default_factory=dict)


def decode_all(data, dialect: Dialect | None = None, key: bytes | None = None,
               accept_unsigned: bool = True, msgids=None) -> BatchResult:
    """Every frame in a complete buffer, as the streaming decoder (feed + flush) would find them.

    ``msgids``: decode records only for these ids (the others are still parsed and counted).
    """
    dialect = dialect or kinefuse_dialect()
    arr = np.frombuffer(memoryview(data), dtype=np.uint8)
    n = arr.size
    res = BatchResult()
    c = res.counters
    c.bytes_in = n
    cand = np.flatnonzero(arr == 0xFD)
    hdr_ok = cand <= n - 10  # a complete header
    pos = cand[hdr_ok]
    inc = arr[pos + 2]
    msgid = arr[pos + 7].astype(np.int64) | (arr[pos + 8].astype(np.int64) << 8) | (arr[pos + 9].astype(np.int64) << 16)
    plen = arr[pos + 1].astype(np.int64)
    stop = pos + 12 + plen + np.where(inc == 1, 13, 0)

    # classify every candidate: 0 ok, 1 bad incompat, 2 unknown id, 3 empty payload, 4 incomplete, 5 crc
    # (a payload longer than the message's is accepted and truncated, as in the streaming decoder)
    kind = np.full(pos.size, 5, dtype=np.int8)
    kind[(inc & 0xFE) != 0] = 1
    known = np.isin(msgid, np.fromiter(dialect.ids, np.int64)) & (kind == 5)
    kind[(kind == 5) & ~known] = 2
    kind[known & (plen == 0)] = 3
    kind[(kind == 5) & (stop > n)] = 4
    check = np.flatnonzero(kind == 5)
    for mid in np.unique(msgid[check]):
        idx = check[msgid[check] == mid]
        good = _crc_ok(arr, pos[idx], plen[idx], dialect.get(int(mid)).crc_extra)
        kind[idx[good]] = 0

    # frames that pass the CRC consume their bytes (also when the signature then fails)
    valid = np.flatnonzero(kind == 0)
    keep = _first_non_overlapping(pos[valid], stop[valid])
    frames = valid[keep]
    deliver = np.ones(frames.size, dtype=bool)
    signed = inc[frames] == 1
    if key is not None:
        if signed.any():
            deliver[signed] = _signature_ok(bytes(data), pos[frames[signed]], stop[frames[signed]], key)
        c.signature_failures = int((signed & ~deliver).sum())
        if not accept_unsigned:
            c.unsigned_rejected = int((~signed).sum())
            deliver &= signed
    # candidates the streaming decoder never looks at: inside an accepted frame
    fstart, fstop = pos[frames], stop[frames]
    if fstart.size:
        k = np.searchsorted(fstart, pos, side="right") - 1
        inside = (k >= 0) & (pos < fstop[np.maximum(k, 0)])
    else:
        inside = np.zeros(pos.size, dtype=bool)
    outside = ~inside
    c.bad_incompat = int(np.sum(outside & (kind == 1)))
    c.unknown_msgid = int(np.sum(outside & (kind == 2)))
    ids, counts = np.unique(msgid[outside & (kind == 2)], return_counts=True)
    res.unknown_ids = {int(i): int(k) for i, k in zip(ids, counts)}
    c.bad_length = int(np.sum(outside & (kind == 3)))
    c.crc_errors = int(np.sum(outside & (kind == 5)))
    delivered = frames[deliver]
    c.frames_ok = int(delivered.size)
    c.bytes_skipped = int(n - np.sum(fstop[deliver] - fstart[deliver]))
    res.spans = np.stack([pos[delivered], stop[delivered]], axis=1) if delivered.size else res.spans
    wanted = None if msgids is None else set(msgids)
    for mid in np.unique(msgid[delivered]):
        if wanted is not None and int(mid) not in wanted:
            continue
        sel = delivered[msgid[delivered] == mid]
        res.arrays[int(mid)] = _records(arr, dialect.get(int(mid)), pos[sel], plen[sel], inc[sel] == 1)
    return res
