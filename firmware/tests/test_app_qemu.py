"""The same application on emulated Cortex-M4F (float32 filters, mps2-an386) and Cortex-M0
(fixed-point filters, mps2-an385), over the emulated UART: it announces itself, answers the
parameter protocol, keeps parameters through a reboot, and its HIL orientation equals the
generated models bit for bit (processor in the loop)."""
from __future__ import annotations

import time

import numpy as np
import pytest

from kinefuse.firmware.targets import toolchain_missing
from kinefuse.hil_tests.qemu import QemuSession, qemu_unavailable

pytestmark = [pytest.mark.qemu,
              pytest.mark.skipif(qemu_unavailable() is not None or toolchain_missing() is not None,
                                 reason=str(qemu_unavailable() or toolchain_missing()))]

FILTERS = ["madgwick", "flagship"]          # a subset keeps the cross builds short
SYSTEM = {"m4f": "f32", "m0": "q"}


@pytest.fixture(scope="module", params=["m4f", "m0"])
def board(request):
    from kinefuse.firmware.build import build_target
    target = request.param
    fw = build_target(target, filters=FILTERS)
    with QemuSession(fw.elf, target, uart="tcp") as q:
        from kinefuse.host.link.connection import open_connection
        from kinefuse.host.link.session import Session
        s = Session(open_connection(q.uart_url))
        try:
            yield target, fw, q, s
        finally:
            s.close()


def test_announces_itself(board):
    target, fw, q, s = board
    st = s.wait_for(lambda f: f.msgid == 52504, timeout=10)
    assert st is not None, q.stderr
    assert st.sysid == 1 and st.compid == 200
    assert st.msg.numeric_format == (1 if target == "m4f" else 2)
    assert st.msg.filter_id == 5                        # flagship
    from kinefuse.host.link.dialect import DIALECT_HASH
    assert st.msg.dialect_hash == DIALECT_HASH()
    assert s.wait_for(lambda f: f.msgid == 0, timeout=5) is not None      # HEARTBEAT


def test_parameters_and_reboot(board):
    from kinefuse.host.link.params import ParamClient, ParamError
    target, fw, q, s = board
    pc = ParamClient(s, 1, timeout=3.0)
    assert pc.get("KF_FILTER") == 5
    assert pc.set("KF_ORI_RATE_HZ", 33) == 33
    with pytest.raises(ParamError, match="rejected"):
        pc.set("KF_MW_BETA", 9.0)                       # the generated init's range [0, 5]
    with pytest.raises(ParamError, match="rejected"):
        pc.set("KF_FILTER", 9)                          # triad is not in this build
    s.send("COMMAND_LONG", target_system=1, target_component=200, command=246, param1=1.0)
    ack = s.wait_for(lambda f: f.msgid == 77 and f.msg.command == 246, timeout=10)
    assert ack is not None and ack.msg.result == 0
    # the board resets; its RAM storage (.noinit) survives, the clock restarts
    st = s.wait_for(lambda f: f.msgid == 52504 and f.msg.time_boot_us < 500_000, timeout=15)
    assert st is not None
    assert pc.get("KF_ORI_RATE_HZ") == 33


def test_hil_orientation_equals_the_model(board):
    from kinefuse.firmware.hostunit import hil_run, unit_model
    from kinefuse.host.link.params import ParamClient
    target, fw, q, s = board
    rng = np.random.default_rng(3)
    n = 40
    t = 1_000_000 + np.arange(n, dtype=np.int64) * 10_000          # 100 Hz
    acc = np.array([0.3, -0.2, 9.7]) + rng.normal(0, 0.05, (n, 3))
    gyr = np.array([0.5, -0.3, 1.0]) + rng.normal(0, 0.01, (n, 3))
    mag = np.array([10.0, 18.0, -40.0]) + rng.normal(0, 0.5, (n, 3))
    upd = np.arange(n) % 2 == 0
    pc = ParamClient(s, 1, timeout=3.0)
    pc.set("KF_RATE_HZ", 100)
    pc.set("KF_FILTER", 3)                             # madgwick: reset, nominal first step
    got = hil_run(s, t, acc, gyr, mag, upd, window=5, timeout=30)
    ref = unit_model("madgwick", SYSTEM[target], t, acc, gyr, mag, upd, rate_hz=100)
    assert np.array_equal(np.concatenate([got["acc"], got["gyr"], got["mag"]], 1), ref["counts"])
    assert np.array_equal(got["q"].view(np.uint32), ref["q"].view(np.uint32))
    pc.set("KF_FILTER", 5)
    got = hil_run(s, t + 1_000_000, acc, gyr, mag, upd, window=5, timeout=30)
    ref = unit_model("flagship", SYSTEM[target], t + 1_000_000, acc, gyr, mag, upd, rate_hz=100)
    assert np.array_equal(got["q"].view(np.uint32), ref["q"].view(np.uint32))


def test_hil_gyro_above_1877_dps_uses_gyro_shift_as_the_model(board):
    """KF_RAW_SAMPLE.gyro_shift on the target (its double arithmetic, nearbyint): rates through
    every shift and beyond, counts + shift + GYRO_CLIPPED equal to the host model."""
    from kinefuse.firmware.hostunit import hil_run, unit_model
    from kinefuse.host.link.params import ParamClient
    target, fw, q, s = board
    n = 24
    t = 3_000_000 + np.arange(n, dtype=np.int64) * 10_000
    acc = np.tile([0.3, -0.2, 9.7], (n, 1))
    dps = np.array([100, 1877, 1878, 2500, -2500, 3754, 3755, 7509, 7510, 15019, 15020, 20000] * 2, float)
    gyr = np.column_stack([np.radians(dps), 0.1 + 0 * dps, np.where(np.arange(n) % 2, -0.2, np.radians(1900.0))])
    mag = np.tile([10.0, 18.0, -40.0], (n, 1))
    upd = np.ones(n, bool)
    pc = ParamClient(s, 1, timeout=3.0)
    pc.set("KF_RATE_HZ", 100)
    pc.set("KF_FILTER", 3)
    got = hil_run(s, t, acc, gyr, mag, upd, window=4, timeout=30)
    ref = unit_model("madgwick", SYSTEM[target], t, acc, gyr, mag, upd, rate_hz=100)
    assert set(np.unique(got["gyro_shift"]).tolist()) == {0, 1, 2, 3}
    assert np.array_equal(got["gyro_shift"], ref["gyro_shift"])
    assert np.array_equal(np.concatenate([got["acc"], got["gyr"], got["mag"]], 1), ref["counts"])
    assert np.array_equal((got["flags"] & 2) != 0, np.abs(dps) >= 15020)   # clipped only beyond shift 3
    assert np.array_equal(got["q"].view(np.uint32), ref["q"].view(np.uint32))


def test_survives_garbage_on_the_uart(board):
    target, fw, q, s = board
    rng = np.random.default_rng(11)
    s.send_bytes(rng.integers(0, 256, 600, dtype=np.uint8).tobytes() + b"\x00" * 280)
    time.sleep(0.5)
    s.send("PARAM_REQUEST_READ", target_system=1, target_component=200, param_id="KF_UNIT_ID", param_index=-1)
    v = s.wait_for(lambda f: f.msgid == 22, timeout=10)
    assert v is not None and v.msg.param_id == "KF_UNIT_ID"
