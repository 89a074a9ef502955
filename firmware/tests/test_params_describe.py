"""`kinefuse params --describe` against the firmware host build: every parameter the unit has is
described, and a fresh unit's values are the described defaults (the tables the host reads are
the unit's own)."""
from __future__ import annotations

import json

import numpy as np
import pytest

from kinefuse.firmware.hostunit import HostUnit
from kinefuse.host import cli


@pytest.fixture
def run(capsys):
    def _run(*argv):
        code = cli.main([str(a) for a in argv])
        out, err = capsys.readouterr()
        return code, out, err
    return _run


def test_every_unit_parameter_is_described_with_its_default(run, tmp_path):
    with HostUnit(storage=tmp_path / "unit.storage") as unit:
        code, out, err = run("params", "--port", f"pty:{unit.device}", "--describe", "--json")
        assert code == 0, err
        res = json.loads(out)
        values, info = res["params"], res["describe"]
        assert len(values) > 100
        missing = sorted(set(values) - set(info))
        assert not missing, missing
        for name, v in values.items():
            d = info[name]
            assert d["meaning"], name
            f32 = np.float32      # the unit holds and checks REAL32 values in float32
            assert f32(d["min"]) <= f32(v) <= f32(d["max"]), (name, v, d)
            assert np.float32(v) == np.float32(d["default"]), (name, v, d)   # a fresh unit
            if d["choices"]:
                assert v in d["choices"], (name, v, d)
        code, out, err = run("params", "--port", f"pty:{unit.device}", "--get", "KF_FL_MODE",
                             "--get", "KF_RATE_HZ", "--describe")
    assert code == 0, err
    lines = out.splitlines()
    assert lines[0].startswith("KF_FL_MODE = 1.0  (one of 0 | 1, default 1) flagship mode: 0: 6D"), lines
    assert lines[1].startswith("KF_RATE_HZ = 1000  ([1, 2000], default 1000) sensor sample rate"), lines
