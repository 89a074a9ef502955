"""Instruction counter vs a hand-countable function, per-call cost and size deltas."""
from __future__ import annotations

import re

import pytest

from kinefuse.hil_tests.qemu import count_instructions, qemu_unavailable
from kinefuse.hil_tests.qemu.batch import csrc_path
from kinefuse.hil_tests.qemu.cost import (cost_program, count_calls, instructions_per_call,
                                          loop_overhead, size_delta)

pytestmark = [pytest.mark.qemu,
              pytest.mark.skipif(qemu_unavailable() is not None, reason=str(qemu_unavailable()))]

PRELUDE = "uint32_t kf_known_loop(uint32_t n);"
TARGETS = ["m4f", "m0"]
N = 100
K = 50


def known_loop_program(target, n=N):
    return cost_program([csrc_path("selftest_known_loop.c")], "", f"(void)kf_known_loop({n}u);",
                        target, prelude=PRELUDE)


@pytest.mark.parametrize("target", TARGETS)
def test_range_count_matches_hand_count(target):
    prog = known_loop_program(target)
    addr, size = prog.symbol("kf_known_loop")
    # the hand count assumes exactly these 6 instructions (Thumb-1: 2 bytes each)
    assert size == 12
    c = count_instructions(prog.elf, target, address_range=(addr, addr + size), args=[f"{K:010d}"])
    assert c.in_range == K * (3 * N + 3)
    assert c.total > c.in_range


@pytest.mark.parametrize("target", TARGETS)
def test_marker_window_matches_hand_count(target):
    prog = known_loop_program(target)
    start, _ = prog.symbol("kf_known_loop")
    end = _symbol_address(prog, "kf_known_loop_end")
    c = count_instructions(prog.elf, target, markers=(start, end), args=[f"{K:010d}"])
    assert c.windows == K
    assert c.window == K * (3 * N + 2)       # start instruction counted, stop instruction not


@pytest.mark.parametrize("target", TARGETS)
def test_per_call_count_matches_disassembly(target):
    """(count(K) - count(0)) equals K x (caller loop body from objdump + 3N + 3), give or take
    the loop's one-off entry instructions."""
    prog = known_loop_program(target)
    body = _loop_body_length(prog.disassemble("main"))
    diff = count_calls(prog, K) - count_calls(prog, 0)
    expected = K * (body + 3 * N + 3)
    assert 0 <= diff - expected <= 3, (diff, expected, body)


@pytest.mark.parametrize("target", TARGETS)
def test_instructions_per_call_differences_are_exact(target):
    src = [csrc_path("selftest_known_loop.c")]
    a = instructions_per_call(src, "", "(void)kf_known_loop(40u);", target, k=K, prelude=PRELUDE)
    b = instructions_per_call(src, "", "(void)kf_known_loop(10u);", target, k=K, prelude=PRELUDE)
    assert a - b == pytest.approx(3 * 30, abs=1e-9)
    overhead = loop_overhead(target, k=K)
    assert 2 <= overhead <= 6


def test_counts_are_deterministic():
    prog = known_loop_program("m0")
    assert count_calls(prog, 7) == count_calls(prog, 7)


@pytest.mark.parametrize("target", TARGETS)
def test_size_delta_of_a_static_buffer_and_function(tmp_path, target):
    src = tmp_path / "buf.c"
    src.write_text("#include <stdint.h>\nstatic uint8_t buf[100];\n"
                   "uint32_t kf_touch(uint32_t i) { buf[i & 63u] += 1u; return buf[3]; }\n")
    pre = "uint32_t kf_touch(uint32_t i);"
    d = size_delta([src], "", "(void)kf_touch(kf_i);", target, prelude=pre)
    assert 100 <= d.bss <= 103           # the buffer (+ alignment padding)
    assert d.data == 0
    _, fn_size = cost_program([src], "", "(void)kf_touch(kf_i);", target, prelude=pre,
                              opt="-Os").symbol("kf_touch")
    assert fn_size <= d.text < fn_size + 64   # kf_touch plus the call loop in main


def _symbol_address(prog, name):
    import subprocess
    from kinefuse.firmware.targets import tool
    out = subprocess.run([tool("nm"), str(prog.elf)], capture_output=True, text=True).stdout
    for line in out.splitlines():
        parts = line.split()
        if parts[-1] == name:
            return int(parts[0], 16) & ~1
    raise AssertionError(name)


def _loop_body_length(disasm: str) -> int:
    """Instructions of the backward-branch loop that contains ``bl <kf_known_loop>``."""
    insns = []
    for line in disasm.splitlines():
        m = re.match(r"\s*([0-9a-f]+):\s+(\S+)\s*(.*)", line)
        if m:
            insns.append((int(m.group(1), 16), m.group(2), m.group(3)))
    call = next(i for i, (_, op, args) in enumerate(insns) if op == "bl" and "kf_known_loop" in args)
    for addr, op, args in insns[call:]:
        if op.startswith("b") and op not in ("bl", "blx", "bx"):
            target = int(args.split()[0], 16)
            if target <= insns[call][0]:
                return sum(1 for a, _, _ in insns if target <= a <= addr)
    raise AssertionError("no loop around the call in:\n" + disasm)


@pytest.mark.parametrize("target", TARGETS)
def test_size_by_origin_adds_up_to_size(target):
    prog = known_loop_program(target)
    origin = prog.size_by_origin()
    assert sum(v.text for v in origin.values()) == prog.size.text
    assert sum(v.data for v in origin.values()) == prog.size.data
    assert sum(v.bss for v in origin.values()) == prog.size.bss
    assert origin["selftest_known_loop"].text == 12


def test_competitor_motion_is_physically_consistent():
    np = pytest.importorskip("numpy")
    from kinefuse.hil_tests.qemu.competitors import motion
    m = motion(n=300)
    assert all(v.dtype == np.float32 and v.shape == (300, 3) for v in m.values())
    assert np.allclose(np.linalg.norm(m["acc"], axis=1), 9.81, atol=0.2)            # m/s^2
    assert np.allclose(np.linalg.norm(m["mag"], axis=1), np.hypot(20, 44), atol=1.5)  # uT
    assert np.abs(m["gyr"]).max() < np.deg2rad(200)                                  # rad/s
    again = motion(n=300)
    assert all(np.array_equal(m[k], again[k]) for k in m)


def test_filter_cost_without_magnetometer_skips_the_field_step():
    # `bench cost --sensors 6d`: the same motion with mag_valid 0.  Madgwick's magnetic objective
    # sits in a conditional region, so its 6D update must execute fewer instructions; the count
    # is exact, so the same measurement twice gives the same number
    from kinefuse.hil_tests.harness.cost import measure_filter
    nine = measure_filter("madgwick", "f32", "m4f", k=20, size_opts=("-Os",), mix=False)
    six = measure_filter("madgwick", "f32", "m4f", k=20, size_opts=("-Os",), mix=False, sensors="6d")
    again = measure_filter("madgwick", "f32", "m4f", k=20, size_opts=("-Os",), mix=False, sensors="6d")
    assert (nine["sensors"], six["sensors"]) == ("9d", "6d")
    assert six["instructions_per_update"] == again["instructions_per_update"]
    assert 0 < six["instructions_per_update"] < nine["instructions_per_update"] - 30
    assert six["flash_bytes"] == nine["flash_bytes"]      # one update function for both
