"""Choice parameters on the unit (``Param.choices``: switches such as KF_FL_MODE 0 = 6D / 1 = 9D,
read by the filter as ``mode > 0.5``): PARAM_SET takes exactly the declared values and refuses
anything between them, and a stored in-between value (written by a firmware without the check)
is replaced by the default at load, never used."""
from __future__ import annotations

import re
import struct
import zlib

import numpy as np
import pytest

from kinefuse.firmware import apptables


def only(frames, name):
    return [f.msg for f in frames if f.msg._msgname == name]


def _refused(unit, name, value):
    before = unit.param(name)
    frames = unit.set_param(name, value)
    errs = only(frames, "PARAM_ERROR")
    assert len(errs) == 1 and errs[0].error == 2 and errs[0].param_id == name, (name, value)
    assert unit.param(name) == before


@pytest.mark.parametrize("name, bad, good", [
    ("KF_FL_MODE", (0.5, 0.7, 0.25, 1e-7), (0.0, 1.0)),   # flagship (in the in-process build)
    ("KF_JA_SEQUENCE", (0.5, 1.5, 1.9999), (2.0, 1.0, 0.0)),
    ("KF_JA_MIRROR", (0.5,), (1.0, 0.0)),
])
def test_choice_parameters_take_only_their_values(unit, name, bad, good):
    for v in bad:
        _refused(unit, name, v)
    for v in good:
        frames = unit.set_param(name, v)
        assert not only(frames, "PARAM_ERROR") and unit.param(name) == v
    _refused(unit, name, float("nan"))
    _refused(unit, name, float("inf"))


def test_a_stored_in_between_choice_is_replaced_by_the_default(unit):
    unit.set_param("KF_FL_MODE", 0.0)                      # stored: 6D
    image = bytearray(unit.storage())
    h = 2166136261                                         # FNV-1a of the name (kf_store.h)
    for c in b"KF_FL_MODE":
        h = ((h ^ c) * 16777619) & 0xFFFFFFFF
    hdr, count = 56, struct.unpack_from("<H", image, 6)[0]
    for i in range(count):
        if struct.unpack_from("<I", image, hdr + 8 * i)[0] == h:
            struct.pack_into("<f", image, hdr + 8 * i + 4, 0.5)
            break
    else:
        raise AssertionError("entry not found")
    end = hdr + 8 * count
    struct.pack_into("<I", image, end, zlib.crc32(bytes(image[:end])))
    unit.restore_storage(bytes(image))
    unit.reboot()
    assert unit.param("KF_FL_MODE") == 1.0                 # the default, 9D
    assert unit.counters()["stored_rejects"] == 1


def test_the_generated_table_marks_every_declared_choice():
    """Every parameter declared with choices is a KF_CHOICE_ROW, every other a KF_PARAM_ROW."""
    text = (apptables.APP_DIR / "kf_params_gen.inc").read_text()
    rows = {n: kind for kind, n in re.findall(r'^(KF_\w+_ROW)\("(\w+)"', text, re.M)}
    table = apptables.parameter_table()
    assert {r["name"] for r in table} == set(rows)
    choice = {r["name"] for r in table if r["choices"]}
    assert {"KF_FL_MODE", "KF_EK_MODE", "KF_VC_ADAPTIVE", "KF_TR_PRIMARY", "KF_JA_SEQUENCE",
            "KF_JA_MIRROR"} <= choice
    assert all((rows[r["name"]] == "KF_CHOICE_ROW") == bool(r["choices"]) for r in table)
    for r in table:
        if r["choices"]:
            assert list(r["choices"]) == list(np.arange(r["min"], r["max"] + 1))
