"""CRC-16/MCRF4XX (the MAVLink "X.25" checksum): reference, fast scalar and vectorised forms.

MAVLink's checksum is the bit-reflected CRC-CCITT (poly 0x1021 reflected = 0x8408, init 0xFFFF,
no final xor).  ``binascii.crc_hqx`` computes the non-reflected CRC-CCITT in C; reflecting every
input byte (``bytes.translate``) and the 16-bit result turns one into the other:

    mcrf4xx(data) == reverse16(crc_hqx(data.translate(REVERSE_BITS), 0xFFFF))

so the hot path runs at C speed without a compiled helper.  ``crc_numpy`` checks many frames of
the same length at once (one table lookup per byte column).
"""
from __future__ import annotations

import binascii

import numpy as np

#: byte -> byte with its bits in reverse order
REVERSE_BITS = bytes(int(f"{b:08b}"[::-1], 2) for b in range(256))


def _make_table() -> list[int]:
    table = []
    for b in range(256):
        crc = b
        for _ in range(8):
            crc = (crc >> 1) ^ 0x8408 if crc & 1 else crc >> 1
        table.append(crc)
    return table


TABLE = _make_table()
TABLE_NP = np.array(TABLE, dtype=np.uint16)


def _make_table16() -> np.ndarray:
    """CRC register after shifting 16 zero bits through it: crc' = T16[crc ^ next 16-bit LE word]."""
    x = np.arange(65536, dtype=np.uint32)
    for _ in range(16):
        x = np.where(x & 1, (x >> 1) ^ 0x8408, x >> 1)
    return x.astype(np.uint16)


TABLE16_NP = _make_table16()


def x25_reference(data: bytes, crc: int = 0xFFFF) -> int:
    """Bit-by-bit table CRC-16/MCRF4XX (slow; the oracle for the fast forms)."""
    for b in data:
        crc = (crc >> 8) ^ TABLE[(crc ^ b) & 0xFF]
    return crc


def reverse16(value: int) -> int:
    return (REVERSE_BITS[value & 0xFF] << 8) | REVERSE_BITS[value >> 8]


def x25(data: bytes, crc_extra: int | None = None) -> int:
    """CRC-16/MCRF4XX of ``data`` (then of the CRC_EXTRA byte, if given), computed in C."""
    c = binascii.crc_hqx(bytes(data).translate(REVERSE_BITS), 0xFFFF)
    if crc_extra is not None:
        c = binascii.crc_hqx(bytes((REVERSE_BITS[crc_extra],)), c)
    return reverse16(c)


def crc_numpy(rows: np.ndarray, crc_extra: int) -> np.ndarray:
    """CRC of every row of a (frames x bytes) uint8 matrix, then of ``crc_extra``; uint16 array.

    Two bytes per step with a 65536-entry table (one xor and one lookup per 16-bit column).
    """
    rows = np.asarray(rows, dtype=np.uint8)
    crc = np.full(rows.shape[0], 0xFFFF, dtype=np.uint16)
    data = np.concatenate([rows, np.full((rows.shape[0], 1), crc_extra, np.uint8)], axis=1)
    if data.shape[1] % 2:
        crc = (crc >> 8) ^ TABLE_NP[(crc ^ data[:, 0]) & 0xFF]
        data = data[:, 1:]
    words = np.ascontiguousarray(data).view("<u2").T.copy()
    t16 = TABLE16_NP
    for w in words:
        crc = t16[crc ^ w]
    return crc
