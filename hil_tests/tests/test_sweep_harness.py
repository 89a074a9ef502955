"""Defect sweep of the harness: build cache keys, failed builds, missing images, the
instruction counter's result file, empty and edge-sized runs, hyphenated filter names."""
from __future__ import annotations

import types
from pathlib import Path

import numpy as np
import pytest

from kinefuse.firmware import targets
from kinefuse.hil_tests.harness import chunked, firmware, loops, motion, props
from kinefuse.hil_tests.harness.compare import compare
from kinefuse.hil_tests.qemu import insn, runner
from kinefuse.hil_tests.qemu.runner import QemuError, RunResult
from kinefuse.host.errors import KinefuseError

needs_arm = pytest.mark.skipif(targets.toolchain_missing() is not None,
                               reason=str(targets.toolchain_missing()))
needs_qemu = pytest.mark.skipif(runner.qemu_missing() is not None, reason=str(runner.qemu_missing()))


# ---- build cache ------------------------------------------------------------------------------

@needs_arm
def test_header_next_to_the_source_is_part_of_the_cache_key(tmp_path, monkeypatch):
    """``#include "local.h"`` from the source's own folder (no -I): changing it rebuilds."""
    monkeypatch.setenv("KINEFUSE_CACHE", str(tmp_path / "cache"))
    src = tmp_path / "src"
    src.mkdir()
    (src / "main.c").write_text('#include "local.h"\nstatic volatile char buf[N];\n'
                                "int main(void) { buf[0] = 1; return 0; }\n")
    (src / "local.h").write_text("#define N 16\n")
    first = targets.build([src / "main.c"], "m4f", hal=False, name="t")
    (src / "local.h").write_text("#define N 4096\n")
    second = targets.build([src / "main.c"], "m4f", hal=False, name="t")
    assert not second.cached
    assert second.elf != first.elf
    assert second.size.bss - first.size.bss >= 4096 - 16 - 8      # the new buffer, not the old image


@needs_arm
def test_failed_build_leaves_no_temporary_directory(tmp_path, monkeypatch):
    monkeypatch.setenv("KINEFUSE_CACHE", str(tmp_path / "cache"))
    bad = tmp_path / "bad.c"
    bad.write_text("int main(void) { return undeclared_name; }\n")
    with pytest.raises(targets.BuildError) as exc:
        targets.build([bad], "m4f", hal=False, name="bad")
    assert "\n" not in str(exc.value)
    left = [p.name for p in (tmp_path / "cache" / "build").iterdir()]
    assert left == []


# ---- QEMU: missing image, instruction counter's result ----------------------------------------

@needs_qemu
@pytest.mark.parametrize("how", ["run_elf", "session"])
def test_missing_image_is_a_one_line_error_before_qemu_starts(tmp_path, how):
    elf = tmp_path / "nope.elf"
    with pytest.raises(QemuError) as exc:
        if how == "run_elf":
            runner.run_elf(elf, "m4f", timeout=5)
        else:
            runner.QemuSession(elf, "m4f", uart="tcp").start()
    msg = str(exc.value)
    assert "\n" not in msg and str(elf) in msg and "does not exist" in msg and "build" in msg


def _fake_run(write):
    """A run_elf stand-in: the program 'exits 0'; ``write(path)`` plays the plugin."""
    def fake(elf, target, plugin=None, **kw):
        out = Path(dict(p.split("=", 1) for p in plugin.split(",")[1:] if "=" in p)["out"])
        write(out)
        return RunResult(0, b"", b"", b"", b"", 0.01, False, [])
    return fake


@pytest.mark.parametrize("content, needle", [
    ("", "lacks insns"),
    ("insns 10\nrange 0\n", "lacks window, windows"),
    ("insns ten\n", "unreadable line"),
])
def test_plugin_result_missing_or_garbled_is_a_one_line_error(monkeypatch, content, needle):
    monkeypatch.setattr(insn, "plugin_path", lambda: Path("/x/insn_count.so"))
    monkeypatch.setattr(insn, "run_elf", _fake_run(lambda p: p.write_text(content)))
    with pytest.raises(QemuError) as exc:
        insn.count_instructions("prog.elf", "m4f")
    assert needle in str(exc.value) and "\n" not in str(exc.value)


def test_plugin_that_wrote_nothing_is_reported(monkeypatch):
    monkeypatch.setattr(insn, "plugin_path", lambda: Path("/x/insn_count.so"))
    monkeypatch.setattr(insn, "run_elf", _fake_run(lambda p: None))
    with pytest.raises(QemuError, match="wrote no result"):
        insn.count_instructions("prog.elf", "m4f")


def test_plugin_result_is_read_exactly(monkeypatch):
    monkeypatch.setattr(insn, "plugin_path", lambda: Path("/x/insn_count.so"))
    monkeypatch.setattr(insn, "run_elf", _fake_run(
        lambda p: p.write_text("insns 123\nrange 45\nwindow 6\nwindows 1\n")))
    c = insn.count_instructions("prog.elf", "m4f")
    assert (c.total, c.in_range, c.window, c.windows) == (123, 45, 6, 1)


# ---- empty runs and chunk edges ---------------------------------------------------------------

def _inputs(n, seed=3):
    rng = np.random.default_rng(seed)
    ins, _ = motion.synth(motion.random_unit_quaternion(rng), props.smooth_rates(rng, n, 100.0, 3.0), 0.01)
    ins["mag_valid"] = rng.random(n) < 0.5
    return ins


@pytest.mark.parametrize("call", ["run_loop", "run_chunked", "reference_states"])
def test_zero_samples_is_a_clear_error(call):
    empty = {k: np.asarray(v)[:0] for k, v in _inputs(4).items()}
    with pytest.raises(KinefuseError, match="no samples"):
        if call == "run_loop":
            loops.run_loop("f32-model", "madgwick", empty)
        elif call == "run_chunked":
            chunked.run_chunked("host-f32", "madgwick", empty, [])
        else:
            chunked.reference_states("madgwick", empty)


N_EDGE = 12


@pytest.mark.parametrize("loop", ["f32-model", "host-f32", "host-q"])
@pytest.mark.parametrize("cuts", [list(range(1, N_EDGE)), [N_EDGE], [N_EDGE + 1], [0], [N_EDGE - 1]],
                         ids=["size1", "n", "n+1", "zero-cut", "last-alone"])
def test_chunk_edges_give_the_whole_run(loop, cuts):
    ins = _inputs(N_EDGE)
    whole = loops.run_loop(loop, "madgwick", ins)
    pieces = chunked.run_chunked(loop, "madgwick", ins, cuts)
    assert all(len(v) == N_EDGE for v in pieces.values())
    m = compare("whole", whole, "chunked", pieces, ins)
    assert m is None, m.message()


def test_hil_input_of_no_samples_has_no_stamps():
    n = 5
    ins = _inputs(n)
    case = types.SimpleNamespace(n=n, inputs=ins, rate_hz=100.0)
    for k in (0, 1, 3):
        h = firmware.HilInput.from_case(case, k)
        assert {len(v) for v in h.inputs().values()} == {k}


# ---- hyphenated filter names on QEMU ----------------------------------------------------------

@pytest.mark.qemu
@needs_arm
@needs_qemu
def test_hyphenated_filter_runs_on_qemu_bit_exact():
    """angle-kf's generated files are angle_kf_f32.*: the batch program must find them."""
    n = 20
    ins = {"angle": np.sin(np.arange(n) * 0.3), "angle_valid": np.arange(n) % 7 != 3,
           "dt": np.full(n, 0.01)}
    model = loops.run_loop("f32-model", "angle-kf", ins)
    got = loops.run_loop("qemu-m4f-f32", "angle-kf", ins)
    assert all(len(v) == n for v in got.values())
    m = compare("f32-model", model, "qemu-m4f-f32", got, ins)
    assert m is None, m.message()


# ---- instruction-mix trace: a run that printed nothing ----------------------------------------

def test_empty_execution_trace_is_an_error_not_zero_cycles(monkeypatch):
    from kinefuse.hil_tests.harness import cost
    monkeypatch.setattr(runner, "run_elf",
                        lambda *a, **kw: RunResult(0, b"", b"", b"", b"", 0.01, False, []))
    with pytest.raises(KinefuseError, match="no execution trace"):
        cost.per_update_trace(Path("prog.elf"), "m4f", 5)


def test_cycle_estimate_refuses_an_empty_per_update_trace():
    from collections import Counter

    from kinefuse.hil_tests.harness import cost
    build = types.SimpleNamespace(elf=Path("never-read.elf"))
    with pytest.raises(KinefuseError, match="identical"):
        cost.cycle_estimate(build, "m4f", 5, per=Counter())


# ---- fuzz build: cache key, replay timeout ----------------------------------------------------

def test_fuzz_build_key_covers_inc_and_mavlink_headers():
    from kinefuse.firmware import build as fb
    from kinefuse.hil_tests import fuzz
    srcs, incs, _defs = fuzz._app_build_inputs("f32", ["madgwick"])
    files = set(fuzz.hashed_files(srcs, incs))
    assert fb.APP_DIR / "kf_params_gen.inc" in files           # included by kf_params.c
    assert fb.MAVLINK_DIR / "mavlink_helpers.h" in files
    assert fb.GENERATED_DIR / "madgwick_f32.h" in files


def test_fuzz_replay_timeout_is_a_one_line_error(monkeypatch, tmp_path):
    import subprocess

    from kinefuse.hil_tests import fuzz
    monkeypatch.setattr(fuzz, "build", lambda *a, **kw: Path("/bin/true"))

    def hang(cmd, **kw):
        raise subprocess.TimeoutExpired(cmd, kw.get("timeout"))
    monkeypatch.setattr(fuzz.subprocess, "run", hang)
    with pytest.raises(KinefuseError) as exc:
        fuzz.replay(iter([tmp_path / "a", tmp_path / "b"]), timeout=2.5)
    assert "2 inputs" in str(exc.value) and "2.5 s" in str(exc.value) and "\n" not in str(exc.value)


# ---- HIL answers: repeated frames, a link that closes -----------------------------------------

class _FakeUnit:
    """A session whose 'unit' answers sample 0 twice (RAW and ORIENTATION) and sample 1 never."""

    def __init__(self, fail: Exception | None = None):
        self.fail, self.queue = fail, []

    def send_bytes(self, data):
        if self.fail:
            raise self.fail
        from kinefuse.firmware.hostunit import MSG_ORI, MSG_RAW
        raw = types.SimpleNamespace(flags=64, sample_counter=100, acc_x=1, acc_y=2, acc_z=3, gyro_x=0,
                                    gyro_y=0, gyro_z=0, mag_x=0, mag_y=0, mag_z=0, time_boot_us=0)
        ori = types.SimpleNamespace(sample_counter=100, q_w=1.0, q_x=0.0, q_y=0.0, q_z=0.0,
                                    cov=[0.0] * 6, status=0)
        for _ in range(2):
            self.queue += [(0, types.SimpleNamespace(msgid=MSG_RAW, msg=raw)),
                           (0, types.SimpleNamespace(msgid=MSG_ORI, msg=ori))]

    def poll(self, timeout):
        if self.fail:
            raise self.fail

    def drain(self):
        out, self.queue = self.queue, []
        return out


def _two_samples():
    return (np.array([1_000_000, 1_010_000]), np.tile([0.0, 0.0, 9.81], (2, 1)), np.zeros((2, 3)),
            np.tile([0.0, 20.0, -40.0], (2, 1)))


def test_repeated_answer_does_not_stand_in_for_a_missing_one():
    from kinefuse.firmware.hostunit import hil_run
    with pytest.raises(KinefuseError, match="1 answers missing"):
        hil_run(_FakeUnit(), *_two_samples(), timeout=0.3)


def test_link_closing_mid_run_is_a_one_line_error():
    from kinefuse.firmware.hostunit import hil_run
    with pytest.raises(KinefuseError) as exc:
        hil_run(_FakeUnit(OSError(5, "Input/output error")), *_two_samples(), timeout=0.3)
    assert "link to the unit failed" in str(exc.value) and "\n" not in str(exc.value)


def test_plugin_build_failure_without_compiler_output_is_reported(monkeypatch, tmp_path):
    import subprocess
    monkeypatch.setattr(insn, "cache_dir", lambda *parts: tmp_path)
    monkeypatch.setattr(insn.subprocess, "run",
                        lambda cmd, **kw: subprocess.CompletedProcess(cmd, 1, "", ""))
    with pytest.raises(QemuError, match="gcc exited with status 1"):
        insn.plugin_path()
    assert not list(tmp_path.iterdir())          # the temporary build folder went too
