"""Every registered IMU filter, every loop of its number systems, identical in every bit.

f32: f32 model == host C == generated C on QEMU Cortex-M4F.  q: q model == host C == QEMU M4F
== QEMU M0.  CI runs a short case built from the simulator's scenario set (rest, constant
rate, random rotation, translation, magnetic disturbance, gyro bias, jitter/drops, gyro
saturation; a few seconds each, around the event a scenario is named for: scenarios.ci_case) plus a short BROAD excerpt; ``kinefuse sil report`` runs the full
set and full trials.  A mismatch names the first differing sample and its inputs.
"""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.hil_tests.harness import compare, loops, scenarios
from kinefuse.hil_tests.qemu import qemu_unavailable

FILTERS = loops.imu_filters()
CASES = [(n, s) for n in FILTERS for s in loops.systems(n)]
needs_qemu = pytest.mark.skipif(qemu_unavailable() is not None, reason=str(qemu_unavailable()))


@pytest.fixture(scope="module")
def ci_inputs():
    sims = scenarios.ci_cases(seconds=3.0)
    broad = scenarios.broad_case(scenarios.default_broad_trial(), 2000, 2600)
    # one series: each filter initialises from the first sample only, so later cases continue
    # from the previous state (the jumps are part of the test)
    return scenarios.concat(sims + [broad]).inputs


def test_ci_case_exercises_the_filters(ci_inputs):
    """The case has teeth: motion, rest, invalid magnetometer samples, saturation, jitter."""
    gyr = np.linalg.norm(ci_inputs["gyr"], axis=1)
    assert gyr.max() > 5.0 and (gyr < 0.05).sum() > 100
    assert (~ci_inputs["mag_valid"]).sum() > 100 and np.ptp(ci_inputs["dt"]) > 0.001
    assert len(ci_inputs["dt"]) > 2500
    assert ci_inputs["dt"].max() > 0.4                       # the 0.5 s gap of jitter_and_drops


def test_ci_pieces_hold_the_events_their_scenarios_are_named_for():
    """The first 3 s of magnetic_disturbance and jitter_and_drops had neither the field
    doubling (15-25 s) nor the gap (20 s): the CI case tested them as plain rotations."""
    dist = scenarios.ci_case("magnetic_disturbance", seconds=3.0)
    m = np.linalg.norm(dist.inputs["mag"], axis=1)[dist.inputs["mag_valid"].astype(bool)]
    assert m.max() > 1.8 * m.min() and dist.n == 300 and dist.name == "magnetic_disturbance 14-17 s"
    assert scenarios.ci_case("jitter_and_drops", seconds=3.0).inputs["dt"].max() > 0.4
    # scenarios whose events lie in the head (or that have none) keep the head
    assert scenarios.ci_case("magnetic_disturbance", seconds=20.0).name == "magnetic_disturbance"
    assert scenarios.ci_case("rest", seconds=3.0).n == 300


@pytest.mark.parametrize("name,system", CASES)
def test_model_and_host_c_identical(name, system, ci_inputs):
    lps = loops.bitexact_loops(name, system, qemu=False)
    outs = {lp: loops.run_loop(lp, name, ci_inputs) for lp in lps}
    ms = compare.compare_all(outs, ci_inputs)
    assert not ms, "\n".join(m.message() for m in ms)


@pytest.fixture(scope="module")
def qemu_programs(ci_inputs):
    """Cross-build every filter's batch programs up front, two at a time (CI has 2 cores)."""
    from concurrent.futures import ThreadPoolExecutor

    from kinefuse.hil_tests.harness.qemu_filter import filter_program
    jobs = []
    for name, system in CASES:
        _info, e = loops.encode(name, system, {k: v[:1] for k, v in ci_inputs.items()})
        for lp in loops.BITEXACT[system]:
            if lp.startswith("qemu-"):
                jobs.append((name, system, lp.split("-")[1], e.params))
    with ThreadPoolExecutor(2) as pool:
        list(pool.map(lambda j: filter_program(*j), jobs))
    return len(jobs)


@pytest.mark.qemu
@needs_qemu
@pytest.mark.parametrize("name,system", CASES)
def test_cortex_m_identical_to_model(name, system, ci_inputs, qemu_programs):
    lps = [f"{system}-model"] + [lp for lp in loops.BITEXACT[system] if lp.startswith("qemu-")]
    outs = {lp: loops.run_loop(lp, name, ci_inputs) for lp in lps}
    ms = compare.compare_all(outs, ci_inputs)
    assert not ms, "\n".join(m.message() for m in ms)


def test_comparison_reports_the_first_flipped_bit(ci_inputs):
    """One flipped bit in one output of one sample is found, with that sample's inputs."""
    out = loops.run_loop("f32-model", "madgwick", ci_inputs)
    bad = {k: v.copy() for k, v in out.items()}
    bad["q"].view(np.uint32)[1234, 2] ^= 1
    m = compare.compare("f32-model", out, "altered", bad, ci_inputs)
    assert m is not None and m.sample == 1234 and m.differing_samples == 1 and m.fields == ["q"]
    assert m.inputs["gyr"] == ci_inputs["gyr"][1234].tolist()
    assert "sample 1234" in m.message()
    q = loops.run_loop("q-model", "madgwick", ci_inputs)
    badq = {k: v.copy() for k, v in q.items()}
    badq["rejected"][7, 0] += 1
    assert compare.compare("a", q, "b", badq).sample == 7


def test_minus_zero_and_nan_payloads():
    """+0 and -0 differ; NaNs with different payloads or signs differ too (bit patterns)."""
    a = {"x": np.array([[0.0, 1.0]], np.float32)}
    b = {"x": np.array([[-0.0, 1.0]], np.float32)}
    m = compare.compare("a", a, "b", b)
    assert m is not None and m.sample == 0 and m.fields == ["x"]
    for pa, pb in ((0x7FC00000, 0xFFC00000), (0x7FC00000, 0x7FC00001), (0x7F800001, 0x7FC00000)):
        nan2 = np.array([pa, pb], np.uint32).view(np.float32)
        m = compare.compare("a", {"x": nan2[:1, None]}, "b", {"x": nan2[1:, None]})
        assert m is not None and m.sample == 0, (hex(pa), hex(pb))
    same = np.array([0x7FC00001], np.uint32).view(np.float32)
    assert compare.compare("a", {"x": same[:, None]}, "b", {"x": same.copy()[:, None]}) is None


def test_float64_outputs_compare_bits_not_truncated_values():
    """Reference (float64) outputs that differ below 1.0 are a mismatch, not equal int parts."""
    a = {"x": np.array([[0.25], [1.5]])}
    b = {"x": np.array([[0.5], [1.5]])}
    m = compare.compare("a", a, "b", b)
    assert m is not None and m.sample == 0 and m.differing_samples == 1


def test_mismatch_in_the_last_sample_is_reported_with_its_inputs():
    n = 5
    a = {"q": np.zeros((n, 4), np.float32), "flag": np.zeros((n, 1), bool)}
    b = {"q": a["q"].copy(), "flag": a["flag"].copy()}
    b["flag"][n - 1, 0] = True
    inputs = {"gyr": np.arange(3 * n, dtype=float).reshape(n, 3)}
    m = compare.compare("a", a, "b", b, inputs)
    assert m is not None and m.sample == 4 and m.differing_samples == 1 and m.fields == ["flag"]
    assert m.inputs == {"gyr": [12.0, 13.0, 14.0]}
    assert "first at sample 4 in flag" in m.message() and "gyr=[12.0, 13.0, 14.0]" in m.message()


@pytest.mark.parametrize("a, b", [({"q": np.zeros((0, 4), np.float32)}, {"q": np.zeros((0, 4), np.float32)}),
                                  ({}, {})], ids=["zero-samples", "no-outputs"])
def test_comparing_nothing_is_an_error_not_a_pass(a, b):
    with pytest.raises(ValueError, match="no samples"):
        compare.compare("a", a, "b", b)
