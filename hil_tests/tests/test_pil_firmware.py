"""The unit application in the loop: SIL (host build over a pty) and PIL (QEMU Cortex-M4F with
float32 filters, Cortex-M0 with fixed-point filters, UART0 on a pty), HIL_SENSOR in, the real
host decoder out; every KF_ORIENTATION and every echoed KF_RAW_SAMPLE count compared bit for
bit with the unit model (generated Python models on the same path).

QEMU's UART is slow (a few kB/s), so PIL uses a short piece of a simulated scenario with
motion and magnetometer; ``kinefuse sil report --firmware`` runs longer ones.
"""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.hil_tests.harness import firmware, scenarios
from kinefuse.hil_tests.qemu import qemu_unavailable

pytestmark = pytest.mark.skipif(firmware.firmware_missing() is not None,
                                reason=str(firmware.firmware_missing()))
needs_qemu = pytest.mark.skipif(qemu_unavailable() is not None, reason=str(qemu_unavailable()))


@pytest.fixture(scope="module")
def case():
    c = scenarios.sim_case("slow_rotation", seed=4, seconds=8.0)
    return c.window(400, 800)           # moving, magnetometer at 20 Hz, 100 Hz samples


def _check(loop, name, case, n):
    m, got, ref = firmware.compare_unit(loop, name, case, n=n)
    assert m is None, m.message()
    assert np.all(np.diff(got["counter"]) == 1)
    # the orientation moved: a constant output would prove little
    assert abs(float(np.dot(got["q"][0], got["q"][-1]))) < np.cos(np.radians(5) / 2)


@pytest.mark.parametrize("system", ["f32", "q"])
def test_sil_host_unit_bit_exact(case, system):
    _check(f"sil-{system}", "madgwick", case, 400)


@pytest.mark.qemu
@needs_qemu
@pytest.mark.parametrize("loop,name", [("pil-m4f-f32", "flagship"), ("pil-m4f-f32", "madgwick"),
                                       ("pil-m0-q", "flagship"), ("pil-m0-q", "vak")])
def test_pil_qemu_unit_bit_exact(case, loop, name):
    _check(loop, name, case, 150)


def test_hil_input_from_case_keeps_units_and_stamps(case):
    h = firmware.HilInput.from_case(case, n=50)
    assert h.rate_hz == 100 and h.time_us[0] == 1_000_000
    assert np.allclose(np.diff(h.time_us), np.round(case.inputs["dt"][1:50] * 1e6), atol=1)
    assert np.array_equal(h.acc, case.inputs["acc"][:50])
