"""The host build (firmware/ports/host) as a unit on a pseudo-terminal, driven by the host
tools: the parameter client, the recorder, HIL injection compared bit for bit with the
generated models, persistence through a reboot and a restart, a sanitizer run."""
from __future__ import annotations

import os
import random
import shutil
import subprocess
import time

import numpy as np
import pytest

from kinefuse.firmware import hostunit
from kinefuse.firmware.hostunit import HostUnit, hil_run, unit_model
from kinefuse.host.link.params import ParamClient, ParamError, encode_value

pytestmark = pytest.mark.skipif(shutil.which("gcc") is None, reason="gcc not installed")

FILTER_IDS = {"complementary": 2, "madgwick": 3, "mahony": 4, "flagship": 5, "eskf": 6, "ecompass": 8,
              "triad": 9, "vac": 10, "vak": 11, "guo": 12}


@pytest.fixture(scope="module")
def broad_inputs():
    from kinefuse.host import broad, runner
    trial = broad.load_trial(broad.bundled_trials()[0])
    inp = runner.imu_inputs(trial)
    n = 500
    start = 7850                                    # rest, then the motion starts
    sl = slice(start, start + n)
    t_us = 5_000_000 + np.arange(n, dtype=np.int64) * 3500     # BROAD: 285.714 Hz = 3500 us
    t_us[150] += 1200                               # a late sample
    t_us[151:] += 1200
    return {"t": t_us, "acc": inp["acc"][sl], "gyr": inp["gyr"][sl], "mag": inp["mag"][sl],
            "upd": (np.arange(n) % 4) == 0}


@pytest.fixture(scope="module")
def hil_unit_f32():
    with HostUnit("f32", sensor=False) as u:
        yield u


@pytest.fixture(scope="module")
def hil_unit_q():
    with HostUnit("q", sensor=False) as u:
        yield u


def _configure(session, **values):
    """Set parameters, then restart the filter (setting KF_FILTER to its current value does
    not restart it): every case starts from a fresh filter and the nominal first time step."""
    pc = ParamClient(session, 1)
    for k, v in values.items():
        pc.set(k, v)
    session.send("COMMAND_LONG", target_system=1, target_component=200, command=52502)
    ack = session.wait_for(lambda f: f.msgid == 77 and f.msg.command == 52502, timeout=3)
    assert ack is not None and ack.msg.result == 0
    return pc


@pytest.mark.parametrize("name", list(FILTER_IDS))
def test_hil_orientation_is_bit_identical_to_the_models_f32(hil_unit_f32, broad_inputs, name):
    _hil_case(hil_unit_f32, "f32", name, broad_inputs, mode=0)


@pytest.mark.parametrize("name", list(FILTER_IDS))
def test_hil_orientation_is_bit_identical_to_the_models_q(hil_unit_q, broad_inputs, name):
    _hil_case(hil_unit_q, "q", name, broad_inputs, mode=0)


@pytest.mark.parametrize("system, name", [("f32", "flagship"), ("f32", "madgwick"), ("q", "flagship"),
                                          ("q", "vak"), ("f32", "eskf"), ("q", "eskf")])
def test_hil_direct_mode_is_bit_identical(hil_unit_f32, hil_unit_q, broad_inputs, system, name):
    _hil_case(hil_unit_f32 if system == "f32" else hil_unit_q, system, name, broad_inputs, mode=1)


def _hil_case(unit, system, name, d, mode):
    s = unit.session()
    try:
        _configure(s, KF_FILTER=FILTER_IDS[name], KF_RATE_HZ=286, KF_HIL_MODE=mode)
        got = hil_run(s, d["t"], d["acc"], d["gyr"], d["mag"], d["upd"])
    finally:
        s.close()
    ref = unit_model(name, system, d["t"], d["acc"], d["gyr"], d["mag"], d["upd"], rate_hz=286, mode=mode)
    n = len(d["t"])
    assert np.all(np.diff(got["counter"]) == 1)                    # one answer per sample, in order
    assert np.array_equal(got["time_us"], d["t"])                  # sample times echoed
    assert np.all(got["flags"] & 64)                               # SIMULATED
    assert np.array_equal(np.concatenate([got["acc"], got["gyr"], got["mag"]], 1), ref["counts"])
    same = np.all(got["q"].view(np.uint32) == ref["q"].view(np.uint32), axis=1)
    assert same.sum() == n, f"{n - same.sum()} of {n} samples differ, first at {np.argmin(same)}"
    # the attitude covariance (KF_ORIENTATION extension) where the filter has one, else absent
    assert np.array_equal(got["cov"].view(np.uint32), ref["cov"].view(np.uint32))
    if name == "eskf":
        assert np.all(got["cov"][:, 0] > 0)
    # and the unit did turn (a constant output would prove little)
    assert abs(float(np.dot(got["q"][0], got["q"][-1]))) < np.cos(np.radians(10) / 2)


def test_param_client_against_the_unit(tmp_path):
    store = tmp_path / "unit.storage"
    with HostUnit(storage=store, sensor=False) as unit:
        s = unit.session()
        pc = ParamClient(s, 1)
        params = pc.fetch_all()
        assert len(params) > 90 and params["KF_FILTER"] == 5 and params["KF_RATE_HZ"] == 1000
        assert isinstance(params["KF_FL_TAU_ACC"], float) and params["KF_SERIAL_NO"] == 0x4B460001
        assert pc.get("KF_MW_BETA") == pytest.approx(0.041)
        assert pc.set("KF_ORI_RATE_HZ", 25) == 25
        assert pc.set("KF_SERIAL_NO", 4_000_000_000) == 4_000_000_000
        assert pc.set("KF_FL_TAU_ACC", 4.5) == np.float32(4.5)
        for name, value in (("KF_ORI_RATE_HZ", 2000), ("KF_FL_TAU_ACC", 100.0), ("KF_SIGNING", 1)):
            with pytest.raises(ParamError, match="rejected"):
                pc.set(name, value)
        with pytest.raises(ParamError, match="no such parameter"):
            pc.get("KF_NOT_THERE")
        s.send("COMMAND_LONG", target_system=1, target_component=200, command=512, param1=52504.0)
        st = s.wait_for(lambda f: f.msgid == 52504 and f.msg.param_rejects >= 3, timeout=3)
        assert st is not None and st.msg.param_rejects == 3
        # reboot command: the values are back from storage, the clock restarted
        s.send("COMMAND_LONG", target_system=1, target_component=200, command=246, param1=1.0)
        assert s.wait_for(lambda f: f.msgid == 77 and f.msg.command == 246, timeout=3).msg.result == 0
        time.sleep(0.3)
        assert pc.get("KF_ORI_RATE_HZ") == 25
        s.close()
    with HostUnit(storage=store, sensor=False) as unit:             # power cycle: a new process
        pc = ParamClient(unit.session(), 1)
        assert pc.get("KF_ORI_RATE_HZ") == 25 and pc.get("KF_SERIAL_NO") == 4_000_000_000
        assert pc.get("KF_FL_TAU_ACC") == np.float32(4.5)


def test_power_cut_in_the_host_build(tmp_path):
    """The host storage (a file) under the same cut: the process dies mid-save (status 75) and
    the next start has the previous values."""
    store = tmp_path / "unit.storage"
    with HostUnit(storage=store, sensor=False) as unit:
        pc = ParamClient(unit.session(), 1)
        pc.set("KF_ORI_RATE_HZ", 40)
    size = store.stat().st_size
    for cut in (3, 400, 871):                     # header, entries, CRC of the next copy
        unit = HostUnit(storage=store, sensor=False, extra=["--storage-fail-after", str(cut)]).start()
        try:
            s = unit.session()
            s.send("PARAM_SET", target_system=1, target_component=200, param_id="KF_ORI_RATE_HZ",
                   param_value=encode_value(20, 3), param_type=3)
            assert unit.proc.wait(5) == 75
        finally:
            unit.stop()
        with HostUnit(storage=store, sensor=False) as unit:
            assert ParamClient(unit.session(), 1).get("KF_ORI_RATE_HZ") == 40
    assert store.stat().st_size == size


def test_streams_5_s_at_1_khz_into_a_recording_without_loss(tmp_path):
    """Host build -> pty -> `kinefuse record` -> .kfr -> decode: every sample, exactly."""
    res = hostunit.stream_check(5.0, 1000, out_dir=tmp_path)
    assert res["samples_received"] == 5000
    assert (res["lost"], res["duplicates"], res["wrong"], res["timing_errors"]) == (0, 0, 0, 0)
    assert res["unit_frames_dropped"] == 0 and res["unit_samples_dropped"] == 0
    assert res["crc_errors"] == 0 and res["ok"]


def test_streams_at_another_rate_into_a_recording_without_loss(tmp_path):
    """`bench firmware --rate 500` failed every time: the unit streams its first samples at
    1 kHz until the new rate arrives, and the host sensor restarts its index there, so every
    later sample was compared with the wrong reference sample."""
    res = hostunit.stream_check(2.0, 500, out_dir=tmp_path)
    assert res["samples_received"] == 1000
    assert (res["lost"], res["duplicates"], res["wrong"], res["timing_errors"]) == (0, 0, 0, 0), res
    assert 0 <= res["samples_before_rate_change"] < 200       # a few samples at 1 kHz
    assert res["achieved_rate_hz"] == pytest.approx(500.0, rel=1e-6) and res["ok"]


@pytest.mark.skipif(os.environ.get("KINEFUSE_LONG_TESTS") != "1",
                    reason="60 s end-to-end run: set KINEFUSE_LONG_TESTS=1 (or `kinefuse bench firmware`)")
def test_streams_60_s_at_1_khz_without_loss(tmp_path):
    res = hostunit.stream_check(60.0, 1000, out_dir=tmp_path)
    assert res["ok"] and res["samples_received"] == 60_000, res


def test_timesync_and_status_over_the_pty():
    with HostUnit(sensor=False) as unit:
        s = unit.session()
        hb = s.wait_for(lambda f: f.msgid == 0, timeout=3)
        assert hb is not None and hb.sysid == 1 and hb.compid == 200
        assert hb.msg.type == 0 and hb.msg.autopilot == 8
        s.send("TIMESYNC", tc1=0, ts1=42)
        t = s.wait_for(lambda f: f.msgid == 111, timeout=3)
        assert t is not None and t.msg.ts1 == 42 and t.msg.tc1 > 0
        st = s.wait_for(lambda f: f.msgid == 52504, timeout=3)
        from kinefuse.host.link.dialect import DIALECT_HASH
        assert st.msg.dialect_hash == DIALECT_HASH() and st.msg.numeric_format == 1


@pytest.mark.skipif(subprocess.run(["gcc", "-fsanitize=address,undefined", "-x", "c", "-", "-o", "/dev/null"],
                                   input=b"int main(void){return 0;}", capture_output=True).returncode != 0,
                    reason="gcc cannot build with -fsanitize=address,undefined here")
def test_sanitizers_on_hostile_input():
    """ASan + UBSan build: garbage, truncated frames, out-of-range parameters, HIL samples with
    extreme values, commands; the process must stay alive and report nothing."""
    from kinefuse.host.link.codec import Encoder
    from kinefuse.host.link.params import encode_value
    rng = random.Random(7)
    enc = Encoder(255, 190)
    pieces = []
    for i in range(300):
        kind = i % 6
        if kind == 0:
            pieces.append(bytes(rng.getrandbits(8) for _ in range(rng.randrange(0, 300))))
        elif kind == 1:
            f = enc.encode("PARAM_SET", target_system=1, target_component=200, param_id="KF_MW_BETA",
                           param_value=rng.choice([float("nan"), float("inf"), -1.0, 1e30, 0.5]), param_type=9)
            pieces.append(f[:rng.randrange(1, len(f) + 1)])
        elif kind == 2:
            v = rng.choice([float("inf"), -float("inf"), 1e30, -1e30, 0.0, 3.0, float("nan")])
            pieces.append(enc.encode("HIL_SENSOR", time_usec=rng.randrange(0, 2 ** 64), xacc=v, yacc=-v, zacc=9.8,
                                     xgyro=v, ygyro=0.1, zgyro=v, xmag=v, ymag=0.2, zmag=-0.4,
                                     temperature=v, fields_updated=rng.getrandbits(32)))
        elif kind == 3:
            pieces.append(enc.encode("COMMAND_LONG", target_system=0, target_component=0,
                                     command=rng.choice([52500, 52501, 52502, 511, 512, 520, 9999]),
                                     param1=rng.choice([float("nan"), 1.0, -1.0, 3e38, 52501.0]),
                                     param2=rng.choice([float("nan"), 0.0, -1.0, 50.0, 1e-9])))
        elif kind == 4:
            name = rng.choice(["KF_FILTER", "KF_RATE_HZ", "KF_ACC_M01", "KF_UNIT_ID", "KF_HIL_MODE"])
            ptype = rng.choice([1, 3, 9, 5])
            pieces.append(enc.encode("PARAM_SET", target_system=1, target_component=200, param_id=name,
                                     param_value=struct_float(rng.getrandbits(32)), param_type=ptype))
        else:
            pieces.append(enc.encode("PARAM_REQUEST_READ", target_system=1, target_component=200,
                                     param_id="", param_index=rng.randrange(-5, 200)))
    pieces.append(enc.encode("PARAM_SET", target_system=1, target_component=200, param_id="KF_HIL_MODE",
                             param_value=encode_value(1, 1), param_type=1))
    for v in (float("inf"), 1e30, 0.0):
        pieces.append(enc.encode("HIL_SENSOR", time_usec=123, xacc=v, zacc=9.8, xgyro=v, xmag=v,
                                 fields_updated=0x1FF))
    from kinefuse.firmware.build import build_host
    exe = build_host("f32", sanitize=True, filters=["madgwick", "flagship"]).exe
    env = dict(os.environ, ASAN_OPTIONS="detect_leaks=0:abort_on_error=1",
               UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1")
    proc = subprocess.run([str(exe), "--uart", "stdio", "--no-sensor"], input=b"".join(pieces),
                          capture_output=True, env=env, timeout=120)
    assert proc.returncode == 0, proc.stderr.decode(errors="replace")[-2000:]
    assert b"runtime error" not in proc.stderr and b"AddressSanitizer" not in proc.stderr
    from kinefuse.host.link.decoder import StreamDecoder
    got = StreamDecoder().feed(proc.stdout)
    assert any(f.msg._msgname == "PARAM_VALUE" for f in got)


def struct_float(bits: int) -> float:
    import struct
    return struct.unpack("<f", struct.pack("<I", bits))[0]


def test_heading_tare_rotates_quaternion_and_covariance(hil_unit_f32, broad_inputs):
    """After MAV_CMD_KF_HEADING_TARE(h) the earth frame is turned about its vertical: the
    sensor x axis has heading h and the ESKF covariance is rotated with the frame."""
    d = broad_inputs
    s = hil_unit_f32.session()
    try:
        _configure(s, KF_FILTER=FILTER_IDS["eskf"], KF_RATE_HZ=286, KF_HIL_MODE=0)
        n = 300
        hil_run(s, d["t"][:n], d["acc"][:n], d["gyr"][:n], d["mag"][:n], d["upd"][:n])
        s.send("COMMAND_LONG", target_system=1, target_component=200, command=52501, param1=1.0)
        ack = s.wait_for(lambda f: f.msgid == 77 and f.msg.command == 52501, timeout=3)
        assert ack is not None and ack.msg.result == 0
        got = hil_run(s, d["t"][n:n + 1], d["acc"][n:n + 1], d["gyr"][n:n + 1], d["mag"][n:n + 1], d["upd"][n:n + 1])
    finally:
        s.close()
    ref = unit_model("eskf", "f32", d["t"][:n + 1], d["acc"][:n + 1], d["gyr"][:n + 1], d["mag"][:n + 1],
                     d["upd"][:n + 1], rate_hz=286)
    q_cmd = ref["q"][n - 1].astype(float)                      # the orientation when the command came
    psi = 1.0 - np.arctan2(2 * (q_cmd[1] * q_cmd[2] + q_cmd[0] * q_cmd[3]), 1 - 2 * (q_cmd[2] ** 2 + q_cmd[3] ** 2))
    c, s_ = np.cos(psi), np.sin(psi)
    R = np.array([[c, -s_, 0], [s_, c, 0], [0, 0, 1]])
    tare = np.array([np.cos(psi / 2), 0, 0, np.sin(psi / 2)])
    w1, x1, y1, z1 = tare
    w2, x2, y2, z2 = ref["q"][n].astype(float)
    q_exp = np.array([w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                      w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2])
    qg = got["q"][0].astype(float)
    assert np.allclose(qg * np.sign(qg[0]), q_exp * np.sign(q_exp[0]), atol=2e-6)
    assert got["status"][0] & 64                                # HEADING_TARED
    C = np.zeros((3, 3))
    iu = np.triu_indices(3)
    C[iu] = ref["cov"][n]
    C = C + C.T - np.diag(np.diag(C))
    exp = (R @ C @ R.T)[iu]
    assert np.allclose(got["cov"][0], exp, rtol=1e-5, atol=1e-12)
    # the rotation did change it: the xz, yz terms turn with the frame
    assert not np.allclose(exp[[2, 4]], ref["cov"][n][[2, 4]], rtol=0.05, atol=0)


def test_signed_hil_with_a_streaming_sensor():
    """A unit with its sensor streaming and a signing key: signed HIL samples take over, the
    answers are the HIL samples' (not the sensor's), bit-identical to the model."""
    import hashlib
    from kinefuse.host.link.codec import signing_timestamp
    key = hashlib.sha256(b"hil key").digest()
    rng = np.random.default_rng(5)
    n = 120
    t = 50_000_000 + np.arange(n, dtype=np.int64) * 1000
    acc = np.array([0.0, 0.3, 9.8]) + rng.normal(0, 0.05, (n, 3))
    gyr = np.array([0.2, -0.1, 0.4]) + rng.normal(0, 0.01, (n, 3))
    mag = np.array([5.0, 19.0, -45.0]) + rng.normal(0, 0.3, (n, 3))
    with HostUnit(filters=None) as unit:
        s = unit.session()
        s.send("SETUP_SIGNING", target_system=1, target_component=200, secret_key=list(key),
               initial_timestamp=signing_timestamp())
        time.sleep(0.2)
        s.send("HIL_SENSOR", time_usec=1, zacc=9.8, fields_updated=0x3F)   # unsigned: refused
        got = hil_run(s, t, acc, gyr, mag, key=key)
    ref = unit_model("flagship", "f32", t, acc, gyr, mag, rate_hz=1000)
    assert np.array_equal(got["time_us"], t)
    assert np.array_equal(got["q"].view(np.uint32), ref["q"].view(np.uint32))


def test_replay_of_a_recording_that_started_late_matches_the_unit(tmp_path, capsys):
    """The unit streams before the recorder opens its pty (no --wait-connect): the recorder
    first reads a backlog whose host times crowd together (and, when the unit's transmit queue
    overflowed meanwhile, then a gap).  The replay takes its time steps from the unit's sample
    clock, so up to the first lost sample it equals the unit's own filter, and it says why the
    two differ after one.  (With host-clock steps it was 19.7 deg off before the gap.)"""
    from kinefuse.host.cli import main as cli_main
    from kinefuse.host.link import stats
    from kinefuse.host.link.frames import decode_file
    rec, est = tmp_path / "late.kfr", tmp_path / "est.csv"
    with HostUnit("f32") as unit:
        time.sleep(1.5)                  # the unit streams 1 kHz into a pty nobody reads
        assert cli_main(["record", "--port", f"pty:{unit.device}", "--out", str(rec), "--force",
                         "--duration", "1", "--start", "--rate", "200", "--json"]) == 0
    (u,) = stats.compute(decode_file(rec))["streams"][0]["units"]
    assert u["clock"]["excluded_leading"] > 100, u["clock"]    # the backlog came first
    capsys.readouterr()
    assert cli_main(["replay", str(rec), "--out", str(est), "--compare-unit"]) == 0
    line = capsys.readouterr().out.strip().splitlines()[-1]
    part = line.split("up to there, ")[1] if "samples were lost just before t = " in line else \
        line.split("matched; ")[1]
    if "up to there, " in line:
        assert int(part.split(" message")[0]) > 10, line
    rms = float(part.split("angle RMS ")[1].split(" deg")[0])
    mx = float(part.split("max ")[1].split(" deg")[0])
    assert rms == 0.0 and mx == 0.0, line


@pytest.mark.parametrize("argv,msg", [
    (["--only", "hil", "--hil-samples", "0"], "--hil-samples 0: must be at least 1"),    # was an IndexError
    (["--only", "hil", "--hil-samples", "-5"], "--hil-samples -5: must be at least 1"),  # was a ValueError
    (["--only", "stream", "--seconds", "inf"], "--seconds must be positive and finite"),  # streamed for ever
    # accepted and ignored: --only left their section out
    (["--only", "hil", "--seconds", "5"], "--seconds sets the stream section, which --only leaves out"),
    (["--only", "cost", "--rate", "500"], "--rate sets the stream section, which --only leaves out"),
    (["--only", "stream", "--hil-samples", "10"], "--hil-samples sets the hil section, which --only leaves out"),
])
def test_bench_firmware_bad_arguments(capsys, argv, msg):
    from kinefuse.host.cli import main
    rc = main(["bench", "firmware"] + argv)
    err = capsys.readouterr().err
    assert rc == 2 and msg in err and "Traceback" not in err and "internal error" not in err
