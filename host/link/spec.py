"""Message tables for the decoder and encoder, built once from the generated pymavlink module.

For every message id: CRC_EXTRA, full payload length (extensions included), the little-endian
struct of the payload in wire order, a namedtuple record type whose fields are in wire order
(numeric arrays as tuples, char arrays as ``str``), the matching packed numpy dtype, and units.
"""
from __future__ import annotations

import struct
from collections import namedtuple
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

_NP_TYPES = {
    "uint8_t": "u1", "int8_t": "i1", "uint16_t": "<u2", "int16_t": "<i2", "uint32_t": "<u4",
    "int32_t": "<i4", "uint64_t": "<u8", "int64_t": "<i8", "float": "<f4", "double": "<f8",
}
_STRUCT_SIZES = {"c": 1, "s": 1, "b": 1, "B": 1, "h": 2, "H": 2, "i": 4, "I": 4, "q": 8, "Q": 8, "f": 4, "d": 8}


@dataclass(frozen=True, eq=False)
class MessageSpec:
    msgid: int
    name: str
    crc_extra: int
    length: int                          # payload bytes with extensions, before truncation
    fields: tuple[str, ...]              # wire order
    types: tuple[str, ...]               # C types, wire order
    array_lengths: tuple[int, ...]       # 0 = scalar
    units: dict = field(repr=False)
    enums: dict = field(repr=False)
    struct: struct.Struct = field(repr=False)
    record: type = field(repr=False)     # namedtuple class (fields in wire order)
    convert: object = field(repr=False)  # flat struct tuple -> record, or None when flat is the record
    dtype: np.dtype = field(repr=False)
    pymavlink_class: type = field(repr=False)

    def to_record(self, values: tuple):
        return self.convert(values) if self.convert is not None else tuple.__new__(self.record, values)

    def flatten(self, record) -> tuple:
        """Record (or a sequence in wire order) -> flat tuple for ``struct.pack``."""
        out = []
        for value, ctype, n in zip(record, self.types, self.array_lengths):
            if ctype == "char":
                out.append(value.encode() if isinstance(value, str) else bytes(value))
            elif n:
                out.extend(value)
            else:
                out.append(value)
        return tuple(out)


def _converter(record_cls, types, array_lengths):
    """Build (with exec, for speed) a function mapping the flat struct tuple to the record."""
    parts, k, simple = [], 0, True
    for ctype, n in zip(types, array_lengths):
        if ctype == "char":
            parts.append(f"_s(t[{k}])")
            k, simple = k + 1, False
        elif n:
            parts.append(f"t[{k}:{k + n}]")
            k, simple = k + n, False
        else:
            parts.append(f"t[{k}]")
            k += 1
    if simple:
        return None
    src = f"def conv(t):\n    return _new(_cls, ({', '.join(parts)},))\n"
    env = {"_new": tuple.__new__, "_cls": record_cls, "_s": _cstring}
    exec(src, env)  # noqa: S102 - source built from the dialect's field list only
    return env["conv"]


def _cstring(raw: bytes) -> str:
    return raw.split(b"\0", 1)[0].decode("utf-8", "replace")


def _build(cls) -> MessageSpec:
    wire = list(cls.ordered_fieldnames)
    by_name_type = dict(zip(cls.fieldnames, cls.fieldtypes))
    by_name_len = dict(zip(cls.ordered_fieldnames, cls.array_lengths))  # wire order, unlike fieldtypes
    types = tuple(by_name_type[n] for n in wire)
    lengths = tuple(by_name_len[n] for n in wire)
    st = struct.Struct(cls.unpacker.format if isinstance(cls.unpacker.format, str) else cls.unpacker.format.decode())
    record = namedtuple(cls.msgname, wire)
    record._msgid = cls.id      # underscore names cannot collide with MAVLink field names
    record._msgname = cls.msgname
    dtype_fields = []
    for name, ctype, n in zip(wire, types, lengths):
        if ctype == "char":
            dtype_fields.append((name, f"S{max(n, 1)}"))
        elif n:
            dtype_fields.append((name, _NP_TYPES[ctype], (n,)))
        else:
            dtype_fields.append((name, _NP_TYPES[ctype]))
    dtype = np.dtype(dtype_fields)
    assert dtype.itemsize == st.size, (cls.msgname, dtype.itemsize, st.size)
    return MessageSpec(
        msgid=cls.id, name=cls.msgname, crc_extra=cls.crc_extra, length=st.size, fields=tuple(wire),
        types=types, array_lengths=lengths, units=dict(cls.fieldunits_by_name),
        enums=dict(cls.fieldenums_by_name), struct=st, record=record,
        convert=_converter(record, types, lengths), dtype=dtype, pymavlink_class=cls)


class Dialect:
    """All message specs of one generated pymavlink module, by id and by name (built on first use)."""

    def __init__(self, module):
        self.module = module
        self.ids = frozenset(module.mavlink_map)
        self._id_by_name = {c.msgname: mid for mid, c in module.mavlink_map.items()}
        self._specs: dict[int, MessageSpec] = {}

    def get(self, msgid: int) -> MessageSpec | None:
        spec = self._specs.get(msgid)
        if spec is None and msgid in self.ids:
            spec = self._specs[msgid] = _build(self.module.mavlink_map[msgid])
        return spec

    def __getitem__(self, key) -> MessageSpec:
        msgid = self._id_by_name[key.upper()] if isinstance(key, str) else key
        spec = self.get(msgid)
        if spec is None:
            raise KeyError(key)
        return spec

    def __contains__(self, key) -> bool:
        return (key.upper() in self._id_by_name) if isinstance(key, str) else key in self.ids

    def all(self) -> list[MessageSpec]:
        return [self.get(mid) for mid in sorted(self.ids)]

    def enum_name(self, enum: str, value: int) -> str | None:
        entries = self.module.enums.get(enum, {})
        entry = entries.get(value)
        return entry.name if entry is not None else None


@lru_cache(maxsize=None)
def kinefuse_dialect() -> Dialect:
    from kinefuse.host.link.dialect import module
    return Dialect(module())
