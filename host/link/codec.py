"""MAVLink 2 frame encoding (used by the fake unit, the parameter client, tests and benchmarks).

The output is byte-identical to pymavlink's ``MAVLink.pack`` (checked in the tests): payload in
wire order, trailing zero bytes truncated (at least one byte kept), CRC-16/MCRF4XX over header and
payload then CRC_EXTRA, optional signature block.
"""
from __future__ import annotations

import hashlib
import struct
import time

from kinefuse.host.link.crc import x25
from kinefuse.host.link.spec import Dialect, MessageSpec, kinefuse_dialect

MAGIC = 0xFD
HEADER = struct.Struct("<BBBBBBBHB")  # magic len incompat compat seq sysid compid msgid(lo16, hi8)
SIGNATURE_LEN = 13
IFLAG_SIGNED = 0x01
#: MAVLink signing time base: 1 January 2015 00:00:00 UTC, in 10 us ticks
SIGNING_EPOCH_UNIX_S = 1420070400


def truncate(payload: bytes) -> bytes:
    end = len(payload)
    while end > 1 and payload[end - 1] == 0:
        end -= 1
    return payload[:end]


def signing_timestamp(unix_s: float | None = None) -> int:
    """MAVLink signing timestamp (10 us ticks since 2015-01-01 UTC)."""
    t = time.time() if unix_s is None else unix_s
    return int((t - SIGNING_EPOCH_UNIX_S) * 1e5)


def frame_from_payload(spec: MessageSpec, payload: bytes, sysid: int, compid: int, seq: int,
                       key: bytes | None = None, link_id: int = 0, timestamp: int | None = None) -> bytes:
    """Wrap a full-length payload into a MAVLink 2 frame (signed when ``key`` is given)."""
    payload = truncate(payload)
    incompat = IFLAG_SIGNED if key is not None else 0
    head = HEADER.pack(MAGIC, len(payload), incompat, 0, seq & 0xFF, sysid, compid,
                       spec.msgid & 0xFFFF, spec.msgid >> 16)
    body = head + payload
    frame = body + struct.pack("<H", x25(body[1:], spec.crc_extra))
    if key is not None:
        ts = signing_timestamp() if timestamp is None else timestamp
        frame += bytes((link_id,)) + ts.to_bytes(6, "little")
        frame += hashlib.sha256(key + frame).digest()[:6]
    return frame


class Encoder:
    """Encodes messages of a dialect; keeps the 8-bit sequence number per encoder."""

    def __init__(self, sysid: int = 255, compid: int = 190, dialect: Dialect | None = None,
                 key: bytes | None = None, link_id: int = 0):
        self.dialect = dialect or kinefuse_dialect()
        self.sysid, self.compid = sysid, compid
        self.key, self.link_id = key, link_id
        self.seq = 0
        self._last_ts = -1

    def _timestamp(self) -> int | None:
        """Signing timestamps strictly increase per link (MAVLink 2 signing: a receiver refuses
        a repeated one as a replay), even for frames encoded within one 10 us tick."""
        if self.key is None:
            return None
        self._last_ts = max(signing_timestamp(), self._last_ts + 1)
        return self._last_ts

    def payload(self, name_or_id, fields: dict) -> tuple[MessageSpec, bytes]:
        spec = self.dialect[name_or_id]
        unknown = set(fields) - set(spec.fields)
        if unknown:
            raise KeyError(f"{spec.name} has no field(s) {sorted(unknown)}")
        values = []
        for name, ctype, n in zip(spec.fields, spec.types, spec.array_lengths):
            v = fields.get(name)
            if ctype == "char":
                values.append(b"" if v is None else v.encode() if isinstance(v, str) else bytes(v))
            elif n:
                v = list(v) if v is not None else []
                values.extend(v + [0] * (n - len(v)))
            else:
                values.append(0 if v is None else v)
        return spec, spec.struct.pack(*values)

    def encode(self, name_or_id, sysid: int | None = None, compid: int | None = None, **fields) -> bytes:
        """One frame; missing fields are zero.  Arrays as sequences, char arrays as str."""
        spec, payload = self.payload(name_or_id, fields)
        frame = frame_from_payload(spec, payload, self.sysid if sysid is None else sysid,
                                   self.compid if compid is None else compid, self.seq,
                                   key=self.key, link_id=self.link_id, timestamp=self._timestamp())
        self.seq = (self.seq + 1) & 0xFF
        return frame

    def encode_record(self, record, sysid: int | None = None, compid: int | None = None) -> bytes:
        """Encode a decoded record (namedtuple in wire order) again."""
        spec = self.dialect[record._msgid]
        payload = spec.struct.pack(*spec.flatten(record))
        frame = frame_from_payload(spec, payload, self.sysid if sysid is None else sysid,
                                   self.compid if compid is None else compid, self.seq,
                                   key=self.key, link_id=self.link_id, timestamp=self._timestamp())
        self.seq = (self.seq + 1) & 0xFF
        return frame
