"""The unit application in the loop, every wired filter: SIL (host build f32 and q over a pty)
and PIL (QEMU Cortex-M4F with float32 and with fixed-point filters, Cortex-M0 with fixed-point
filters, UART0 on a loopback TCP port); HIL_SENSOR in, the real host decoder out.  Compared bit
for bit with the unit model (generated Python models on the same path): every KF_RAW_SAMPLE count,
KF_ORIENTATION's quaternion and covariance, and on the q builds the raw Q-format quaternion
(MEMORY_VECT after each KF_ORIENTATION, ``KF_HIL_MODE`` bit 1).

Sizes (QEMU's UART moves a few hundred samples per second: README, "Software- and
processor-in-the-loop"): SIL gets the simulator's CI scenarios (3 s each), a magnetic disturbance onset and 2,000 BROAD
samples for every filter, and one full BROAD trial (flagship, f32 and q); PIL gets ~1,000
samples per filter and target: pieces of five simulated scenarios (rotation, magnetic
disturbance onset, gyro saturation, timing jitter with drops and duplicates) and a BROAD
slice.  ``kinefuse sil report --firmware --pil-samples 0`` runs whole cases (README: the full
BROAD trial through every loop).
"""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.hil_tests.harness import compare, firmware, scenarios
from kinefuse.hil_tests.qemu import qemu_unavailable

pytestmark = pytest.mark.skipif(firmware.firmware_missing() is not None,
                                reason=str(firmware.firmware_missing()))
needs_qemu = pytest.mark.skipif(qemu_unavailable() is not None, reason=str(qemu_unavailable()))

WIRED = list(firmware.filter_ids()) if firmware.firmware_missing() is None else []
SIL = [(lp, n) for n in WIRED for lp in ("sil-f32", "sil-q")]
PIL = [(lp, n) for lp in ("pil-m4f-f32", "pil-m4f-q", "pil-m0-q") for n in WIRED]


@pytest.fixture(scope="module")
def sil_case():
    broad = scenarios.broad_case(scenarios.default_broad_trial(), 2000, 4000)
    onset = scenarios.sim_case("magnetic_disturbance").window(1400, 1700)      # |B| 49 -> 98 uT
    return scenarios.concat(scenarios.ci_cases(seconds=3.0) + [onset, broad],
                            "CI scenarios (3 s) + disturbance onset + BROAD[2000:4000]")


@pytest.fixture(scope="module")
def pil_case():
    return scenarios.concat([
        scenarios.sim_case("slow_rotation", seed=4, seconds=8.0).window(400, 650),   # moving, mag 20 Hz
        scenarios.sim_case("magnetic_disturbance").window(1400, 1600),   # |B| 49 -> 98 uT
        scenarios.sim_case("spin_saturation").window(550, 700),          # gyro at full scale
        scenarios.sim_case("jitter_and_drops").window(100, 250),         # dt jitter, drops, dt = 0
        scenarios.broad_case(scenarios.default_broad_trial(), 2000, 2250),
    ], "PIL pieces")


@pytest.fixture(scope="module")
def units():
    """One running unit per loop for the whole module (started on first use)."""
    running: dict[str, firmware.UnitRunner] = {}

    def get(loop):
        if loop not in running:
            running[loop] = firmware.UnitRunner(loop).__enter__()
        return running[loop]
    yield get
    for u in running.values():
        u.__exit__(None, None, None)


def _check(loop, name, case, units, n=0):
    m, got, ref = firmware.compare_unit(loop, name, case, n=n, runner=units(loop))
    assert m is None, m.message()
    assert np.all(np.diff(got["counter"]) == 1)
    # the orientation moved (by more than 5 degrees): a constant output would prove little
    assert np.abs(got["q"] @ got["q"][0]).min() < np.cos(np.radians(5) / 2)
    return got, ref


def test_cases_exercise_the_filters(sil_case, pil_case):
    for c, n in ((sil_case, 4000), (pil_case, 900)):
        gyr = np.linalg.norm(c.inputs["gyr"], axis=1)
        assert c.n > n and gyr.max() > 8.0 and (gyr < 0.05).sum() > 20
        assert (c.inputs["dt"] == 0).any() and c.inputs["dt"].max() > 0.015
        assert np.linalg.norm(c.inputs["mag"], axis=1).max() > 90


@pytest.mark.parametrize("loop,name", SIL)
def test_sil_every_filter_bit_exact(sil_case, units, loop, name):
    _check(loop, name, sil_case, units)


@pytest.mark.broad_full
@pytest.mark.parametrize("loop", ["sil-f32", "sil-q"])
def test_sil_full_broad_trial(units, loop):
    """A whole BROAD trial (56,940 samples with the shared data) through the host build."""
    path = scenarios.default_broad_trial()
    case = scenarios.broad_case(path)
    if case.n < 40_000:
        pytest.skip(f"{path.name} is the bundled excerpt, not a full trial")
    got, _ref = _check(loop, "flagship", case, units)
    assert len(got["q"]) == case.n


@pytest.mark.qemu
@needs_qemu
@pytest.mark.parametrize("loop,name", PIL)
def test_pil_every_filter_bit_exact(pil_case, units, loop, name):
    _check(loop, name, pil_case, units)


@pytest.mark.parametrize("loop", ["sil-q", pytest.param("pil-m0-q", marks=[pytest.mark.qemu, needs_qemu])])
def test_q_builds_are_compared_on_raw_bits(pil_case, units, loop):
    """The raw Q quaternion carries bits KF_ORIENTATION's binary32 cannot (so comparing it is
    stronger than comparing the float), and one flipped low bit of it is found."""
    got, ref = _check(loop, "flagship", pil_case, units, n=300)
    raw = got["q_raw"]
    assert np.any(raw.astype(np.float32).astype(np.int64) != raw)       # more than 24 bits
    assert np.array_equal(got["q"], (raw.astype(np.float32) * np.float32(2.0 ** -30)).astype(np.float32))
    out = firmware.compared_outputs("q", got, False)
    out["q_raw"] = out["q_raw"].copy()
    out["q_raw"][123, 2] ^= 1
    m = compare.compare("model", firmware.compared_outputs("q", ref, True), loop, out)
    assert m is not None and m.sample == 123 and m.fields == ["q_raw"]


def test_hil_input_from_case_keeps_units_and_stamps(pil_case):
    h = firmware.HilInput.from_case(pil_case, n=50)
    assert h.rate_hz == 100 and h.time_us[0] == 1_000_000
    assert np.allclose(np.diff(h.time_us), np.round(pil_case.inputs["dt"][1:50] * 1e6), atol=1)
    assert np.array_equal(h.acc, pil_case.inputs["acc"][:50])
    with pytest.raises(Exception, match="unknown firmware loop"):
        firmware.loop_target("pil-m3-f32")
    assert firmware.loop_target("pil-m4f-q") == ("m4f", "q") and firmware.loop_target("sil-f32") == ("host", "f32")
