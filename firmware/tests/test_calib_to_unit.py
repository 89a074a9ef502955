"""`kinefuse calibrate apply`: a unit calibration file reaches the unit (host build over a pty)
as its KF_ACC/GYR/MAG_* parameters, is read back, and the unit then applies exactly that map
(HIL in counts mode, compared bit for bit with the generated models).  A file of another unit,
or with a value the unit cannot hold, changes nothing.  `--sensor 1` writes a two-sensor unit's
second IMU's file to KF_ACC2/GYR2/MAG2_*, which the unit applies to sensor 1 only."""
from __future__ import annotations

import json
import shutil

import numpy as np
import pytest

from kinefuse.firmware.hostunit import HostUnit, hil_run, joint_hil_run, joint_model, unit_model
from kinefuse.host import cli
from kinefuse.host.calib import unitfile, unitparams
from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.params import ParamClient

pytestmark = pytest.mark.skipif(shutil.which("gcc") is None, reason="gcc not installed")

SERIAL = "0x4B460001"          # the unit's default KF_SERIAL_NO


def _doc(serial=SERIAL, mag_b=(15.0, 9.0, -20.0)):
    rng = np.random.default_rng(4)
    doc = unitfile.new(serial, {"acc_g": 16})
    for sensor, b in (("accel", (0.12, -0.08, 0.2)), ("gyro", (0.011, -0.004, 0.007)), ("mag", mag_b)):
        M = np.eye(3) + rng.normal(0, 0.02, (3, 3))
        unitfile.set_sensor(doc, sensor, M, b, method="test")
    return doc


def _run(capsys, *argv):
    code = cli.main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture(scope="module")
def unit():
    with HostUnit("f32", sensor=False) as u:
        yield u


def _calib_values(pc) -> dict:
    return {n: pc.get(n) for n in ("KF_ACC_M01", "KF_ACC_B2", "KF_GYR_M20", "KF_GYR_B0", "KF_MAG_M11", "KF_MAG_B1")}


def _model_calib(doc) -> dict:
    """The file's maps as calib_apply values (the models' calib=)."""
    calib = {}
    for sensor, pre in (("accel", "acc"), ("gyro", "gyr"), ("mag", "mag")):
        M, b = np.array(doc["sensors"][sensor]["M"]), np.array(doc["sensors"][sensor]["b"])
        calib.update({f"{pre}_m{i}{j}": M[i, j] for i in range(3) for j in range(3)})
        calib.update({f"{pre}_b{i}": b[i] for i in range(3)})
    return calib


def test_apply_writes_reads_back_and_the_unit_uses_it(unit, tmp_path, capsys):
    doc = _doc()
    path = tmp_path / "unit7.json"
    unitfile.save(doc, str(path))
    code, out, err = _run(capsys, "calibrate", "apply", "--calib", path, "--port", f"pty:{unit.device}", "--json")
    assert code == 0, err
    res = json.loads(out)
    assert res["verified"] and res["sensors"] == ["accel", "gyro", "mag"] and len(res["written"]) == 36
    assert res["unit_serial"] == 0x4B460001
    s = unit.session()
    try:
        pc = ParamClient(s, 1)
        for sensor, pre in (("accel", "ACC"), ("gyro", "GYR"), ("mag", "MAG")):
            M, b = np.array(doc["sensors"][sensor]["M"]), np.array(doc["sensors"][sensor]["b"])
            assert pc.get(f"KF_{pre}_M21") == np.float32(M[2, 1])
            assert pc.get(f"KF_{pre}_B0") == np.float32(b[0])
        # the unit applies exactly that map: HIL (counts mode) against the models with the file's values
        s.send("COMMAND_LONG", target_system=1, target_component=200, command=52502)
        assert s.wait_for(lambda f: f.msgid == 77 and f.msg.command == 52502, timeout=3).msg.result == 0
        n = 200
        rng = np.random.default_rng(1)
        t = 1_000_000 + np.arange(n, dtype=np.int64) * 1000
        acc = np.array([0.3, -0.2, 9.7]) + rng.normal(0, 0.05, (n, 3))
        gyr = np.array([0.2, -0.1, 0.4]) + rng.normal(0, 0.01, (n, 3))
        mag = np.array([18.0, 6.0, -40.0]) + rng.normal(0, 0.3, (n, 3))
        got = hil_run(s, t, acc, gyr, mag)
    finally:
        s.close()
    calib = _model_calib(doc)
    ref = unit_model("flagship", "f32", t, acc, gyr, mag, rate_hz=1000, calib=calib)
    plain = unit_model("flagship", "f32", t, acc, gyr, mag, rate_hz=1000)
    assert np.array_equal(got["q"].view(np.uint32), ref["q"].view(np.uint32))
    assert not np.array_equal(got["q"].view(np.uint32), plain["q"].view(np.uint32))   # the map mattered


def test_a_file_of_another_unit_is_refused_and_changes_nothing(unit, tmp_path, capsys):
    s = unit.session()
    try:
        before = _calib_values(ParamClient(s, 1))
    finally:
        s.close()
    path = tmp_path / "dot7.json"
    unitfile.save(_doc(serial="DOT-7", mag_b=(-5.0, -4.0, -22.0)), str(path))
    code, out, err = _run(capsys, "calibrate", "apply", "--calib", path, "--port", f"pty:{unit.device}")
    assert code == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "'DOT-7'" in lines[0] and "serial number 1262878721" in lines[0], err
    s = unit.session()
    try:
        assert _calib_values(ParamClient(s, 1)) == before
    finally:
        s.close()


def test_out_of_range_values_are_refused_before_connecting(tmp_path, capsys):
    path = tmp_path / "far.json"
    with pytest.raises(KinefuseError, match="outside the unit's range"):     # never written
        unitfile.save(_doc(mag_b=(1500.0, 0.0, 0.0)), str(path))
    path.write_text(json.dumps(_doc(mag_b=(1500.0, 0.0, 0.0))))               # a hand-made file
    code, out, err = _run(capsys, "calibrate", "apply", "--calib", path, "--port", "tcp:127.0.0.1:1")
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert "sensors.mag: b value 1500 b[0] is outside the unit's range [-1000, 1000]" in err, err
    # the range check of the apply itself (the unit's parameter names), on a map within the file check
    doc = _doc()
    vals = unitparams.plan(doc, "x")
    assert vals["KF_MAG_B0"] == 15.0
    path2 = tmp_path / "ok.json"
    unitfile.save(_doc(), str(path2))
    code, out, err = _run(capsys, "calibrate", "apply", "--calib", path2, "--dry-run", "--json")
    assert code == 0, err
    params = json.loads(out)["params"]
    assert len(params) == 36 and params["KF_MAG_B2"] == -20.0


@pytest.mark.parametrize("serial, unit_serial, ok", [("0x4B460001", 0x4B460001, True), ("1262878721", 0x4B460001, True),
                                                     ("DOT-7", 7, False), ("7", 8, False), ("0x7", 7, True)])
def test_serial_matching(serial, unit_serial, ok):
    from kinefuse.host.calib.unitparams import serial_matches
    assert serial_matches(serial, unit_serial) is ok


def test_apply_to_a_signed_unit_needs_its_key(tmp_path, capsys):
    """A unit with a signing key refuses the unsigned writes (one line, exit 2, nothing
    changed); with --key-file the same apply writes and reads back."""
    import hashlib
    key_hex = hashlib.sha256(b"calib apply test").hexdigest()
    keyfile = tmp_path / "unit.key"
    keyfile.write_text(key_hex + "\n")
    path = tmp_path / "unit7.json"
    unitfile.save(_doc(), str(path))
    with HostUnit("f32", sensor=False, storage=tmp_path / "unit.storage") as u:
        port = f"pty:{u.device}"
        code, out, err = _run(capsys, "signing", "--port", port, "--unit", "1", "--new-key-file", keyfile)
        assert code == 0, err
        s = u.session()
        before = _calib_values(ParamClient(s, 1))
        s.close()
        code, out, err = _run(capsys, "calibrate", "apply", "--calib", path, "--port", port, "--unit", "1")
        lines = err.strip().splitlines()
        assert code == 2 and len(lines) == 1 and lines[0].startswith("kinefuse: error:"), (code, err)
        s = u.session()
        assert _calib_values(ParamClient(s, 1)) == before
        s.close()
        code, out, err = _run(capsys, "calibrate", "apply", "--calib", path, "--port", port, "--unit", "1",
                              "--key-file", keyfile, "--json")
        assert code == 0, err
        res = json.loads(out)
        assert len(res["written"]) == 36


def _doc_seeded(seed: int, serial=SERIAL):
    rng = np.random.default_rng(seed)
    doc = unitfile.new(serial, {"acc_g": 16})
    for sensor, scale in (("accel", 0.15), ("gyro", 0.01), ("mag", 10.0)):
        unitfile.set_sensor(doc, sensor, np.eye(3) + rng.normal(0, 0.02, (3, 3)), rng.normal(0, scale, 3),
                            method="test")
    return doc


def test_apply_sensor_1_round_trip_on_a_two_sensor_unit(tmp_path, capsys):
    """Two files, one per IMU (same unit serial): --sensor 0 and --sensor 1 write KF_ACC_* and
    KF_ACC2_* ..., each read back; the joint angles are then the models' with each sensor's own
    map, bit for bit."""
    docs = [_doc_seeded(21), _doc_seeded(22)]
    paths = [tmp_path / "unit-thigh.json", tmp_path / "unit-shank.json"]
    for d, p in zip(docs, paths):
        unitfile.save(d, str(p))
    code, out, err = _run(capsys, "calibrate", "apply", "--calib", paths[1], "--dry-run", "--sensor", "1", "--json")
    assert code == 0, err
    dry = json.loads(out)
    assert dry["sensor"] == 1 and len(dry["params"]) == 36 and all("2_" in k for k in dry["params"])
    with HostUnit("f32", sensor=False) as u:
        port = f"pty:{u.device}"
        s = u.session()
        ParamClient(s, 1).set("KF_JOINT_ID", 4)
        s.close()
        res = []
        for sensor, p in enumerate(paths):
            code, out, err = _run(capsys, "calibrate", "apply", "--calib", p, "--port", port, "--sensor", sensor,
                                  "--json")
            assert code == 0 and err == "", err
            res.append(json.loads(out))
        assert [r["sensor"] for r in res] == [0, 1] and all(r["verified"] and len(r["written"]) == 36 for r in res)
        assert sorted(res[1]["written"]) == sorted("KF_" + n[3:6] + "2" + n[6:] for n in res[0]["written"])
        n = 120
        rng = np.random.default_rng(3)
        t = 1_000_000 + np.arange(n, dtype=np.int64) * 1000
        segs = []
        for k in range(2):
            segs.append({"t": t + 100 * k, "acc": np.array([0.3, -0.2 + k, 9.7]) + rng.normal(0, 0.05, (n, 3)),
                         "gyr": np.array([0.2, -0.1, 0.4 * k]) + rng.normal(0, 0.01, (n, 3)),
                         "mag": np.array([18.0, 6.0 * k, -40.0]) + rng.normal(0, 0.3, (n, 3))})
        s = u.session()
        try:
            pc = ParamClient(s, 1)
            for sensor, d in enumerate(docs):
                for key, pre in (("accel", "ACC"), ("gyro", "GYR"), ("mag", "MAG")):
                    M, b = np.array(d["sensors"][key]["M"]), np.array(d["sensors"][key]["b"])
                    tag = pre + ("2" if sensor else "")
                    assert pc.get(f"KF_{tag}_M21") == np.float32(M[2, 1])
                    assert pc.get(f"KF_{tag}_B0") == np.float32(b[0])
            s.send("COMMAND_LONG", target_system=1, target_component=200, command=52502)
            assert s.wait_for(lambda f: f.msgid == 77 and f.msg.command == 52502, timeout=3).msg.result == 0
            got = joint_hil_run(s, segs[0], segs[1])
        finally:
            s.close()
    cal0, cal1 = _model_calib(docs[0]), _model_calib(docs[1])
    ref = joint_model("flagship", "f32", segs[0], segs[1], calib=cal0, calib2=cal1)
    assert np.array_equal(got["angles"].view(np.uint32), ref["angles"].view(np.uint32))
    assert np.array_equal(got["q"].view(np.uint32), ref["q_prox"].view(np.uint32))
    shared = joint_model("flagship", "f32", segs[0], segs[1], calib=cal0, calib2=cal0)
    assert not np.array_equal(got["angles"].view(np.uint32), shared["angles"].view(np.uint32))


def test_apply_sensor_1_warns_on_a_one_sensor_unit_and_checks_its_ranges(unit, tmp_path, capsys):
    path = tmp_path / "shank.json"
    unitfile.save(_doc_seeded(23), str(path))
    code, out, err = _run(capsys, "calibrate", "apply", "--calib", path, "--port", f"pty:{unit.device}",
                          "--sensor", "1")
    lines = err.strip().splitlines()
    assert code == 0 and len(lines) == 1 and "KF_JOINT_ID 0" in lines[0], err
    assert "of sensor 1" in out
    # sensor 1's parameters have sensor 0's ranges: the apply names sensor 1's parameter
    with pytest.raises(KinefuseError, match=r"KF_MAG2_B0\) is outside the unit's range"):
        unitparams.plan(json.loads(json.dumps(_doc(mag_b=(1500.0, 0.0, 0.0)))), "far.json", 1)
    with pytest.raises(SystemExit):
        cli.main(["calibrate", "apply", "--calib", str(path), "--dry-run", "--sensor", "2"])
    assert "invalid choice" in capsys.readouterr().err
