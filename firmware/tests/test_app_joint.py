"""Two-sensor mode of the unit application (KF_JOINT_ID != 0): the host build over a pty gets
the thigh sensor as HIL_SENSOR id 0 and the shank sensor as id 1, runs two instances of the
selected filter and the generated joint-angle step, and sends KF_JOINT_ANGLE at the orientation
rate; every angle equals, bit for bit, what the generated models compute (f32 and q)."""
from __future__ import annotations

import shutil

import numpy as np
import pytest

from kinefuse.firmware.hostunit import HostUnit, joint_hil_run, joint_model
from kinefuse.host.link.params import ParamClient

pytestmark = pytest.mark.skipif(shutil.which("gcc") is None, reason="gcc not installed")

N = 400
RATE = 100


@pytest.fixture(scope="module")
def knee():
    """A simulated step-up (seed 001 protocol), 4 s of it with the knee moving."""
    from kinefuse.host.kinematics import simulate
    P = simulate.knee_protocol(seed=4, n_cycles=3)
    i0 = max(0, int(P.truth.cycle_starts[0]) - 100)      # 1 s before the first cycle
    sl = slice(i0, i0 + N)
    t = 3_000_000 + np.arange(N, dtype=np.int64) * (1_000_000 // RATE)
    t[200:] += 700                                     # one late sample on both sensors
    seg = {}
    for name, off in (("thigh", 0), ("shank", 130)):    # the shank's samples 130 us later
        r = P.task[name]
        seg[name] = {"t": t + off, "acc": r.acc[sl], "gyr": r.gyr[sl], "mag": r.mag[sl],
                     "upd": (np.arange(N) % 5) == 0}
    # sensor-to-segment offsets as the unit holds them (KF_JA_PROX_* / DIST_*: q_SB, w x y z)
    offsets = {k: P.q_SB[k] for k in ("thigh", "shank")}
    return seg, offsets


def _set(session, **values):
    pc = ParamClient(session, 1)
    for k, v in values.items():
        pc.set(k, v)
    session.send("COMMAND_LONG", target_system=1, target_component=200, command=52502)
    ack = session.wait_for(lambda f: f.msgid == 77 and f.msg.command == 52502, timeout=3)
    assert ack is not None and ack.msg.result == 0


@pytest.mark.parametrize("system, name, sequence", [("f32", "flagship", 0), ("q", "flagship", 0),
                                                    ("f32", "madgwick", 1), ("q", "mahony", 2)])
def test_joint_angle_is_bit_identical_to_the_models(knee, system, name, sequence):
    seg, off = knee
    jp = {"sequence": float(sequence), "mirror": 0.0}
    for key, s in (("prox", "thigh"), ("dist", "shank")):
        jp.update({f"{key}_{c}": float(v) for c, v in zip("wxyz", off[s])})
    filters = {"flagship": 5, "madgwick": 3, "mahony": 4}
    with HostUnit(system, sensor=False) as unit:
        s = unit.session()
        _set(s, KF_FILTER=filters[name], KF_RATE_HZ=RATE, KF_JOINT_ID=4,
             **{f"KF_JA_{k.upper()}": v for k, v in jp.items()})
        got = joint_hil_run(s, seg["thigh"], seg["shank"])
        s.close()
    ref = joint_model(name, system, seg["thigh"], seg["shank"], rate_hz=RATE, joint_params=jp)
    assert not np.isnan(got["angles"]).any()                       # one KF_JOINT_ANGLE per sample
    same = np.all(got["angles"].view(np.uint32) == ref["angles"].view(np.uint32), axis=1)
    assert same.all(), f"{N - same.sum()} of {N} differ, first at {np.argmin(same)}"
    # the proximal filter is the unit's own (its KF_ORIENTATION agrees too)
    assert np.array_equal(got["q"].view(np.uint32), ref["q_prox"].view(np.uint32))
    assert np.array_equal(got["time_us"], seg["thigh"]["t"])
    seq_enum = {0: 2, 1: 1, 2: 6}[sequence]                          # KF_ANGLE_SEQUENCE XZY, XYZ, ZYX
    assert np.all(got["meta"] == [4, seq_enum, 1, 1])
    assert np.all(got["status"][50:] & 1)                            # VALID once both filters run
    assert np.ptp(np.degrees(got["angles"][:, 0 if sequence < 2 else 2])) > 20.0   # the knee did move


def calib_maps(seed: int = 11):
    """Two different calibration maps (calib_apply field -> value): sensor 0's and sensor 1's,
    M near identity, offsets of a real IMU's size, sensor 1 with a gyroscope scale of its own."""
    rng = np.random.default_rng(seed)
    maps = []
    for k in range(2):
        m = {}
        for pre, b in (("acc", 0.15), ("gyr", 0.012), ("mag", 12.0)):
            M = np.eye(3) + rng.normal(0, 0.03, (3, 3))
            m.update({f"{pre}_m{i}{j}": float(M[i, j]) for i in range(3) for j in range(3)})
            m.update({f"{pre}_b{i}": float(v) for i, v in enumerate(rng.normal(0, b, 3))})
        maps.append(m)
    maps[1]["gyr_scale"] = 0.00099
    return maps


def calib_params(calib: dict, sensor: int) -> dict:
    """{MAVLink name: value} of a calib_apply map for sensor 0 (KF_ACC_*) or 1 (KF_ACC2_*)."""
    from kinefuse.firmware.apptables import calib_param_name
    return {calib_param_name(k, sensor): v for k, v in calib.items()}


@pytest.mark.parametrize("system, name", [("f32", "flagship"), ("q", "mahony")])
def test_each_sensor_has_its_own_calibration_map(knee, system, name):
    """KF_ACC/GYR/MAG_* calibrate sensor 0, KF_ACC2/GYR2/MAG2_* sensor 1 (HIL counts mode):
    the joint angles equal the models fed with each sensor's own calibrated samples, bit for
    bit, and differ from sensor 1 taking sensor 0's map (the former behaviour)."""
    seg, off = knee
    jp = {"sequence": 0.0}
    for key, s in (("prox", "thigh"), ("dist", "shank")):
        jp.update({f"{key}_{c}": float(v) for c, v in zip("wxyz", off[s])})
    cal0, cal1 = calib_maps()
    with HostUnit(system, sensor=False) as unit:
        s = unit.session()
        _set(s, KF_FILTER={"flagship": 5, "mahony": 4}[name], KF_RATE_HZ=RATE, KF_JOINT_ID=4,
             **{f"KF_JA_{k.upper()}": v for k, v in jp.items()}, **calib_params(cal0, 0), **calib_params(cal1, 1))
        pc = ParamClient(s, 1)
        assert pc.get("KF_GYR2_SCALE") == np.float32(0.00099) and pc.get("KF_GYR_SCALE") == np.float32(0.001)
        got = joint_hil_run(s, seg["thigh"], seg["shank"])
        s.close()
    ref = joint_model(name, system, seg["thigh"], seg["shank"], rate_hz=RATE, joint_params=jp,
                      calib=cal0, calib2=cal1)
    same = np.all(got["angles"].view(np.uint32) == ref["angles"].view(np.uint32), axis=1)
    assert same.all(), f"{N - same.sum()} of {N} differ, first at {np.argmin(same)}"
    assert np.array_equal(got["q"].view(np.uint32), ref["q_prox"].view(np.uint32))   # sensor 0: its map
    # the filters were fed different maps: the same raw samples give other inputs with the other map
    other = joint_model(name, system, seg["thigh"], seg["shank"], rate_hz=RATE, joint_params=jp,
                        calib=cal0, calib2=cal0)
    assert not np.array_equal(ref["in_dist"]["gyr"], other["in_dist"]["gyr"])
    assert np.array_equal(ref["in_prox"]["gyr"], other["in_prox"]["gyr"])
    assert not np.array_equal(got["angles"].view(np.uint32), other["angles"].view(np.uint32))


def test_single_sensor_unit_ignores_sensor_1_and_sends_no_joint_angle(knee):
    seg, _ = knee
    short = {k: v[:20] for k, v in seg["thigh"].items()}
    with HostUnit("f32", sensor=False) as unit:
        s = unit.session()
        _set(s, KF_RATE_HZ=RATE)
        with pytest.raises(Exception, match="KF_JOINT_ANGLE missing"):
            joint_hil_run(s, short, {k: v[:20] for k, v in seg["shank"].items()}, timeout=1.5)
        s.close()
