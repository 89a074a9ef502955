"""Persistence: two copies with a CRC; a power cut at any byte of a save loses nothing that was
saved before; damaged copies fall back to the other copy, then to the defaults."""
from __future__ import annotations

import numpy as np


def f32(x: float) -> float:
    return float(np.float32(x))


def test_values_survive_a_reboot(unit):
    unit.set_param("KF_MW_BETA", 0.2)
    unit.set_param("KF_ORI_RATE_HZ", 50)
    unit.set_param("KF_SERIAL_NO", 0xDEADBEEF)
    unit.reboot()
    assert unit.param("KF_MW_BETA") == f32(0.2)
    assert unit.param("KF_ORI_RATE_HZ") == 50
    assert unit.param("KF_SERIAL_NO") == 0xDEADBEEF
    assert unit.counters()["storage_errors"] == 0


def _cut_every_byte(unit, start_image: bytes, name: str, old, new, check):
    """Save `name = new` from `start_image` with the power failing after k bytes, for every k."""
    lib = unit.lib
    unit.restore_storage(start_image)
    unit.reboot()
    w0 = lib.kft_written()
    unit.set_param(name, new)
    total = lib.kft_written() - w0
    assert total > 100                      # a whole copy is written
    outcomes = []
    for k in range(total + 1):
        unit.restore_storage(start_image)
        unit.reboot()                       # the unit as it was before the save
        lib.kft_budget(k)                   # power fails after k bytes
        unit.set_param(name, new)
        lib.kft_budget(-1)                  # power back: a fresh boot reads the storage
        unit.reboot()
        got = unit.param(name)
        check(unit)
        outcomes.append(got)
        assert got == (new if k == total else old), f"power cut after {k} of {total} bytes"
    return total, outcomes


def test_power_cut_at_every_byte_of_a_save(unit):
    unit.set_param("KF_MW_BETA", 0.2)           # copy in slot 0
    unit.set_param("KF_ORI_RATE_HZ", 50)        # copy in slot 1: both slots hold valid copies
    image = unit.storage()

    def others_intact(u):
        assert u.param("KF_ORI_RATE_HZ") == 50  # the rest of the newest saved configuration

    total, outcomes = _cut_every_byte(unit, image, "KF_MW_BETA", f32(0.2), f32(0.3), others_intact)
    assert outcomes.count(f32(0.3)) == 1 and len(outcomes) == total + 1


def test_power_cut_during_the_first_save_keeps_the_defaults(unit):
    image = unit.storage()                      # erased storage (0xFF)
    assert set(image[:4096]) == {0xFF}

    def defaults(u):
        assert u.param("KF_ORI_RATE_HZ") == 100

    _cut_every_byte(unit, image, "KF_RATE_HZ", 1000, 500, defaults)


def test_a_damaged_copy_falls_back_to_the_other_then_to_defaults(unit):
    unit.set_param("KF_ORI_RATE_HZ", 50)        # seq 1 -> slot 0
    unit.set_param("KF_ORI_RATE_HZ", 25)        # seq 2 -> slot 1 (newest)
    image = bytearray(unit.storage())
    slot = 2048
    image[slot + 100] ^= 0x40                   # damage the newest copy
    unit.restore_storage(bytes(image))
    unit.reboot()
    assert unit.param("KF_ORI_RATE_HZ") == 50   # the previous copy
    image[100] ^= 0x01                          # and the older one too
    unit.restore_storage(bytes(image))
    unit.reboot()
    assert unit.param("KF_ORI_RATE_HZ") == 100  # defaults
    # the next save still works and wins
    unit.set_param("KF_ORI_RATE_HZ", 10)
    unit.reboot()
    assert unit.param("KF_ORI_RATE_HZ") == 10


def test_stored_values_are_checked_at_load(unit):
    """A stored value outside its range (e.g. a range narrowed by a firmware update) is
    replaced by the default and counted, never used."""
    import struct
    import zlib
    unit.set_param("KF_ORI_RATE_HZ", 50)
    image = bytearray(unit.storage())
    # find the entry of KF_ORI_RATE_HZ (FNV-1a of the name) in slot 0 and put 5000 there
    h = 2166136261
    for c in b"KF_ORI_RATE_HZ":
        h = ((h ^ c) * 16777619) & 0xFFFFFFFF
    hdr = 56
    count = struct.unpack_from("<H", image, 6)[0]
    for i in range(count):
        off = hdr + 8 * i
        if struct.unpack_from("<I", image, off)[0] == h:
            struct.pack_into("<I", image, off + 4, 5000)
            break
    else:
        raise AssertionError("entry not found")
    end = hdr + 8 * count
    struct.pack_into("<I", image, end, zlib.crc32(bytes(image[:end])))   # a valid copy again
    unit.restore_storage(bytes(image))
    unit.reboot()
    assert unit.param("KF_ORI_RATE_HZ") == 100
    assert unit.counters()["stored_rejects"] == 1


def test_storage_layout_matches_the_documented_format(unit):
    """Header magic 'KFCF', version 1, entry count, CRC-32 (zlib) over header + entries."""
    import struct
    import zlib
    unit.set_param("KF_UNIT_ID", 7)
    image = unit.storage()
    magic, version, count, seq = struct.unpack_from("<IHHI", image, 0)
    assert magic == 0x4643464B and version == 1 and seq == 1
    assert count == unit.lib.kft_param_count() - 1       # every parameter but read-only KF_SIGNING
    end = 56 + 8 * count
    assert struct.unpack_from("<I", image, end)[0] == zlib.crc32(image[:end])


def _fnv(name: str) -> int:
    h = 2166136261
    for c in name.encode():
        h = ((h ^ c) * 16777619) & 0xFFFFFFFF
    return h


def test_an_image_without_sensor_1_calibration_still_loads(unit):
    """Sensor 1's calibration rows (KF_ACC2/GYR2/MAG2_*) came after the others: the older rows
    keep their indices, and a copy saved by a firmware without them (the same layout, fewer
    entries) loads with every value it holds and sensor 1's map at its defaults."""
    import struct
    import zlib
    from kinefuse.firmware.apptables import parameter_table
    new = [r["name"] for r in parameter_table() if r.get("sensor") == 1]
    assert len(new) == 39 and "KF_ACC2_M00" in new and "KF_MAG2_SCALE" in new
    total = unit.lib.kft_param_count()
    assert [unit.param_index(n) for n in new] == list(range(total - len(new), total))   # appended
    unit.set_param("KF_ACC_B0", 0.3)
    unit.set_param("KF_GYR_M01", 0.02)
    unit.set_param("KF_MW_BETA", 0.2)
    unit.set_param("KF_ACC2_B0", -0.4)          # in the image, then cut out of it below
    image = bytearray(unit.storage())
    slot = 2048                                 # seq 4: the newest copy is in slot 1
    count = struct.unpack_from("<H", image, slot + 6)[0]
    drop = {_fnv(n) for n in new}
    entries = [image[slot + 56 + 8 * i: slot + 64 + 8 * i] for i in range(count)]
    old = [e for e in entries if struct.unpack_from("<I", e)[0] not in drop]
    assert len(old) == count - len(new)
    copy = bytearray(image[slot:slot + 56]) + b"".join(old)
    struct.pack_into("<H", copy, 6, len(old))
    copy += struct.pack("<I", zlib.crc32(bytes(copy)))
    older = bytearray(b"\xff" * len(image))     # only the older firmware's copy: slot 0
    older[:len(copy)] = copy
    unit.restore_storage(bytes(older))
    unit.reboot()
    assert unit.param("KF_ACC_B0") == f32(0.3) and unit.param("KF_GYR_M01") == f32(0.02)
    assert unit.param("KF_MW_BETA") == f32(0.2)
    assert unit.param("KF_ACC2_B0") == 0.0 and unit.param("KF_ACC2_M00") == 1.0   # defaults
    assert unit.counters()["stored_rejects"] == 0 and unit.counters()["storage_errors"] == 0
    unit.set_param("KF_ACC2_B0", -0.4)          # the next save holds every row again
    unit.reboot()
    assert unit.param("KF_ACC2_B0") == f32(-0.4) and unit.param("KF_ACC_B0") == f32(0.3)
    assert struct.unpack_from("<H", unit.storage(), 2048 + 6)[0] == count
