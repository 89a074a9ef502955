"""Streaming MAVLink 2 decoder that never raises and never loses a good frame to a bad one.

    dec = StreamDecoder()
    for chunk in chunks:
        for f in dec.feed(chunk):          # Frame(msgid, sysid, compid, seq, msg, signed)
            print(f.msg._msgname, f.msg)   # msg: namedtuple of the payload fields (wire order)
    dec.flush()                            # end of stream: settle the incomplete tail
    dec.counters                           # frames_ok, crc_errors, bytes_skipped, ...

Rules (see /work/shared/notes/mavlink.md for why):
- a candidate is a 0xFD found with ``bytes.find``; when it fails (unknown incompat flag, unknown
  message id, empty payload, bad CRC) the search resumes ONE byte later, never after the
  claimed length (pymavlink's way, which loses the good frames a stray 0xFD+length covers);
- after a good frame the search continues after it;
- the CRC uses the dialect's CRC_EXTRA (binascii.crc_hqx on bit-reversed bytes: C speed);
- signed frames (incompat flag 0x01, 13-byte signature) are accepted; with ``key`` their
  SHA-256 signature is verified, and ``accept_unsigned=False`` drops unsigned frames;
- a payload longer than the message's (a newer firmware's extension fields) is accepted and
  truncated to the known fields, as MAVLink 2 says; a shorter one is zero-padded;
- memory is bounded: at most one incomplete frame (<= 280 bytes) is kept between calls;
- any chunking of the byte stream yields the same frames.
"""
from __future__ import annotations

import gc
import hashlib
import struct
from binascii import crc_hqx
from collections import namedtuple
from dataclasses import dataclass, asdict

from kinefuse.host.link.crc import REVERSE_BITS
from kinefuse.host.link.spec import Dialect, kinefuse_dialect

MAGIC = b"\xfd"
MAX_FRAME = 10 + 255 + 2 + 13  # header + payload + CRC + signature
_HEADER = struct.Struct("<xBBxBBBHB")  # len, incompat, seq, sysid, compid, msgid lo16, msgid hi8

Frame = namedtuple("Frame", "msgid sysid compid seq msg signed")
Frame.__doc__ = "A decoded frame: header fields and ``msg``, the payload record (a namedtuple)."


@dataclass
class Counters:
    frames_ok: int = 0
    crc_errors: int = 0          # candidates with a known id and possible length whose CRC failed
    bytes_skipped: int = 0       # bytes not part of an accepted frame
    unknown_msgid: int = 0       # candidates whose message id is not in the dialect
    bad_incompat: int = 0        # candidates with incompat flags other than 0x01
    bad_length: int = 0          # candidates with an empty payload (longer ones are truncated, MAVLink 2)
    signature_failures: int = 0  # signed frames whose signature did not verify (with a key)
    unsigned_rejected: int = 0   # unsigned frames dropped because accept_unsigned=False
    bytes_in: int = 0

    def as_dict(self) -> dict:
        return asdict(self)


class StreamDecoder:
    """Incremental decoder: ``feed(bytes) -> list[Frame]``; never raises on any input."""

    def __init__(self, dialect: Dialect | None = None, key: bytes | None = None,
                 accept_unsigned: bool = True, msgids: set[int] | None = None, native: bool | None = None):
        """``native``: use the compiled scanner (None: when available, see ``native.py``)."""
        self.dialect = dialect or kinefuse_dialect()
        self.key = key
        self.accept_unsigned = accept_unsigned
        self.only = None if msgids is None else frozenset(msgids)
        self.counters = Counters()
        self._buf = b""
        # msgid -> (reversed CRC_EXTRA byte, payload length, unpack_from, unpack, record class, converter)
        self._table: dict = {}
        self._native = None
        if native is not False:
            from kinefuse.host.link import native as nat
            lib = nat.load()
            if lib is not None:
                table = getattr(self.dialect, "_native_table", None)
                if table is None:
                    table = self.dialect._native_table = nat.message_table(self.dialect.module)
                self._native = (lib[0], lib[1], *table)
            elif native:
                raise RuntimeError("the compiled scanner is not available (no C compiler or cffi?)")

    @property
    def is_native(self) -> bool:
        return self._native is not None

    # -- table -----------------------------------------------------------------------------
    def _entry(self, msgid: int):
        spec = self.dialect.get(msgid)
        if spec is None:
            return None
        entry = (bytes((REVERSE_BITS[spec.crc_extra],)), spec.length, spec.struct.unpack_from,
                 spec.struct.unpack, spec.record, spec.convert)
        self._table[msgid] = entry
        return entry

    # -- decoding ----------------------------------------------------------------------------
    def feed(self, data: bytes) -> list[Frame]:
        """Decode everything complete in ``data`` (plus what was kept from earlier calls)."""
        if not data:
            return []
        self.counters.bytes_in += len(data)
        buf = self._buf + bytes(data) if self._buf else bytes(data)
        frames, keep = self._scan_paused_gc(buf, final=False)
        self._buf = buf[keep:]
        return frames

    def flush(self) -> list[Frame]:
        """End of stream: decide the kept tail (incomplete candidates fail; later frames still count)."""
        buf, self._buf = self._buf, b""
        if not buf:
            return []
        frames, _ = self._scan_paused_gc(buf, final=True)
        return frames

    @property
    def pending(self) -> int:
        """Bytes kept for an incomplete frame."""
        return len(self._buf)

    def _scan_paused_gc(self, buf: bytes, final: bool):
        # The records are acyclic tuples; letting the cyclic GC walk the growing result list
        # every 700 allocations costs up to 40 % of the decoding time, so pause it meanwhile.
        scan = self._scan_native if self._native is not None else self._scan
        if not gc.isenabled():
            return scan(buf, final)
        gc.disable()
        try:
            return scan(buf, final)
        finally:
            gc.enable()

    def _scan_native(self, buf: bytes, final: bool):
        ffi, lib, keys, vals, mask = self._native
        n = len(buf)
        starts = ffi.new("int32_t[]", n // 13 + 1)
        cnt = ffi.new("uint64_t[5]")
        keep = ffi.new("int32_t *")
        found = lib.kf_scan(ffi.from_buffer(buf), n, 1 if final else 0, keys, vals, mask, starts, cnt, keep)
        unpack_header = _HEADER.unpack_from
        table_get = self._table.get
        new = tuple.__new__
        out = []
        append = out.append
        key, only, strict = self.key, self.only, self.key is not None and not self.accept_unsigned
        skipped = sig_fail = uns_rej = 0
        checks = key is not None or only is not None
        last_id = -1
        full = unpack_from = unpack = record = conv = None
        for i in ffi.unpack(starts, found):
            plen, inc, seq, sysid, compid, mid16, mid8 = unpack_header(buf, i)
            msgid = mid16 | (mid8 << 16)
            if msgid != last_id:  # streams are mostly runs of one message type
                _, full, unpack_from, unpack, record, conv = table_get(msgid) or self._entry(msgid)
                last_id = msgid
            if checks:
                stop = i + 12 + plen + (13 if inc else 0)
                if inc:
                    if key is not None and \
                            hashlib.sha256(key + buf[i:stop - 6]).digest()[:6] != buf[stop - 6:stop]:
                        sig_fail += 1
                        skipped += stop - i
                        continue
                elif strict:
                    uns_rej += 1
                    skipped += stop - i
                    continue
                if only is not None and msgid not in only:
                    continue
            values = unpack_from(buf, i + 10) if plen >= full else unpack(buf[i + 10:i + 10 + plen] + bytes(full - plen))
            append(new(Frame, (msgid, sysid, compid, seq, new(record, values) if conv is None else conv(values),
                               inc == 1)))
        c = self.counters
        c.frames_ok += found - sig_fail - uns_rej
        c.crc_errors += cnt[0]
        c.unknown_msgid += cnt[1]
        c.bad_incompat += cnt[2]
        c.bad_length += cnt[3]
        c.bytes_skipped += cnt[4] + skipped
        c.signature_failures += sig_fail
        c.unsigned_rejected += uns_rej
        return out, keep[0]

    def _scan(self, buf: bytes, final: bool):
        n = len(buf)
        tb = memoryview(buf.translate(REVERSE_BITS))
        find = buf.find
        unpack_header = _HEADER.unpack_from
        table_get = self._table.get
        new = tuple.__new__
        out = []
        append = out.append
        key = self.key
        only = self.only
        accept_unsigned = self.accept_unsigned
        ok = crc_err = skipped = unknown = bad_inc = bad_len = sig_fail = uns_rej = 0
        i = 0
        keep = n
        while True:
            if i >= n:
                break
            if buf[i] != 253:  # not at a frame boundary: search (C speed)
                j = find(MAGIC, i)
                if j < 0:
                    skipped += n - i
                    break
                skipped += j - i
                i = j
            if n - i < 10:
                if final:
                    skipped += n - i
                else:
                    keep = i
                break
            plen, inc, seq, sysid, compid, mid16, mid8 = unpack_header(buf, i)
            if inc & 0xFE:
                bad_inc += 1
                skipped += 1
                i += 1
                continue
            msgid = mid16 | (mid8 << 16)
            entry = table_get(msgid)
            if entry is None:
                entry = self._entry(msgid)
                if entry is None:
                    unknown += 1
                    skipped += 1
                    i += 1
                    continue
            extra, full, unpack_from, unpack, record, conv = entry
            # a longer payload is a newer firmware's extension fields: MAVLink 2 (pymavlink, the C
            # library) keeps the known fields (CRC over the payload as received); dropping it lost
            # every frame of such a message
            if plen == 0:
                bad_len += 1
                skipped += 1
                i += 1
                continue
            end = i + 12 + plen
            stop = end + 13 if inc else end
            if stop > n:
                if final:  # the stream ended inside this candidate: it fails, look further
                    skipped += 1
                    i += 1
                    continue
                keep = i
                break
            c = crc_hqx(extra, crc_hqx(tb[i + 1:end - 2], 0xFFFF))
            if c != ((tb[end - 2] << 8) | tb[end - 1]):
                crc_err += 1
                skipped += 1
                i += 1
                continue
            if inc:
                if key is not None and hashlib.sha256(key + buf[i:stop - 6]).digest()[:6] != buf[stop - 6:stop]:
                    sig_fail += 1
                    skipped += stop - i
                    i = stop
                    continue
            elif key is not None and not accept_unsigned:
                uns_rej += 1
                skipped += stop - i
                i = stop
                continue
            if only is not None and msgid not in only:
                ok += 1
                i = stop
                continue
            if plen >= full:   # longer: the known fields, the newer extensions ignored
                values = unpack_from(buf, i + 10)
            else:
                values = unpack(buf[i + 10:i + 10 + plen] + bytes(full - plen))
            msg = new(record, values) if conv is None else conv(values)
            append(new(Frame, (msgid, sysid, compid, seq, msg, inc == 1)))
            ok += 1
            i = stop
        c = self.counters
        c.frames_ok += ok
        c.crc_errors += crc_err
        c.bytes_skipped += skipped
        c.unknown_msgid += unknown
        c.bad_incompat += bad_inc
        c.bad_length += bad_len
        c.signature_failures += sig_fail
        c.unsigned_rejected += uns_rej
        return out, keep


def decode_bytes(data: bytes, dialect: Dialect | None = None, **kw) -> tuple[list[Frame], Counters]:
    """Decode a complete byte string (feed + flush)."""
    dec = StreamDecoder(dialect, **kw)
    frames = dec.feed(data)
    frames += dec.flush()
    return frames, dec.counters
