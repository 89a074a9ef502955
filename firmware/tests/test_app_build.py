"""Build hygiene of the application: generated bindings up to date, parameter names valid and
unique, strict C99 with every warning an error, no heap, and the Cortex-M sizes."""
from __future__ import annotations

import json
import shutil
import subprocess

import pytest

from kinefuse.firmware import apptables
from kinefuse.firmware import build as fb


def test_generated_bindings_are_up_to_date():
    stale = apptables.check()
    assert stale == [], f"run `python -m kinefuse.firmware.build tables` ({stale})"


def test_parameter_names():
    import re
    rows = apptables.parameter_table()
    app = re.findall(r'KF_APP_ROW\("(\w+)"', (fb.APP_DIR / "kf_params.c").read_text())
    names = app + [r["name"] for r in rows]
    assert len(names) == len(set(names))
    assert all(n.startswith("KF_") and len(n) <= 16 and re.fullmatch(r"[A-Z0-9_]+", n) for n in names)
    # storage keys (FNV-1a of the name) must be unique too
    def fnv(s):
        h = 2166136261
        for c in s.encode():
            h = ((h ^ c) * 16777619) & 0xFFFFFFFF
        return h
    assert len({fnv(n) for n in names}) == len(names)
    # every wired filter has both number systems generated
    for e in apptables.read_list():
        for system in ("f32", "q"):
            assert (fb.GENERATED_DIR / f"{e.name}_{system}.c").is_file()


def test_abbreviation_is_stable_and_bounded():
    assert apptables.abbreviate("beta", 10) == "BETA"
    assert apptables.abbreviate("bias_forget_time", 10) == "BIAS_FORGT"     # a readable override
    # the automatic rule: trim the longest word (the last of equals) until it fits
    assert apptables.abbreviate("a_very_long_parameter_name", 10) == "A_VE_L_P_N"
    assert apptables.abbreviate("slerp_threshold_x", 12) == "SLERP_THRE_X"


@pytest.mark.skipif(shutil.which("gcc") is None, reason="gcc not installed")
@pytest.mark.parametrize("q", [0, 1])
def test_strict_c99_without_warnings(q):
    srcs = [str(p) for p in sorted(fb.APP_DIR.glob("*.c"))] + [str(p) for p in sorted(fb.HOST_PORT_DIR.glob("*.c"))]
    cmd = ["gcc", "-std=c99", "-pedantic", "-Wall", "-Wextra", "-Wshadow", "-Wconversion", "-Wno-sign-conversion",
           "-Werror", "-fsyntax-only", f"-DKF_NUMERIC_Q={q}", f"-I{fb.APP_DIR}", f"-I{fb.GENERATED_DIR}",
           f"-I{fb.HOST_PORT_DIR}", "-isystem", str(fb.MAVLINK_DIR), *srcs]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr[-3000:]


@pytest.mark.qemu
@pytest.mark.skipif(shutil.which("arm-none-eabi-gcc") is None, reason="arm-none-eabi-gcc not installed")
@pytest.mark.parametrize("target", ["m4f", "m0"])
def test_no_heap_and_size(target):
    res = fb.build_target(target, filters=["madgwick", "flagship"])
    syms = {name for name, *_ in res.symbols()}
    nm = subprocess.run([shutil.which("arm-none-eabi-nm"), str(res.elf)], capture_output=True, text=True).stdout
    linked = {line.split()[-1] for line in nm.splitlines() if line.strip()}
    for f in ("malloc", "free", "calloc", "realloc", "_sbrk", "_malloc_r"):
        assert f not in linked and f not in syms, f"{f} is linked into the {target} application"
    # the float32 image carries the leg EKF (two-sensor mode, KF_EFFORTS), the fixed-point one not
    assert ("leg_f32_update" in syms) == (target == "m4f")
    # static RAM budget of a small wearable MCU (stack excluded), leg EKF included on the M4F
    assert res.size.ram < 16 * 1024, res.size
    assert res.size.flash > 10_000


@pytest.mark.qemu
@pytest.mark.skipif(shutil.which("arm-none-eabi-gcc") is None, reason="arm-none-eabi-gcc not installed")
def test_m0_default_build_fits_a_256k_part():
    """Without --filters the M0 links its default set (the image with all ten does not fit),
    at -Os; the fixed-point build has no leg EKF (float32 only)."""
    assert fb.default_filters("m0") == ["flagship", "madgwick", "mahony", "complementary"]
    assert fb.default_filters("m4f") == fb.wired_filters()
    res = fb.build_target("m0")
    assert res.opt == "-Os" and res.size.flash < 256 * 1024, res.size
    syms = {name for name, *_ in res.symbols()}
    assert {f"{n}_q_update" for n in fb.default_filters("m0")} <= syms
    assert not any(s.endswith("_q_update") and s[:-9] not in fb.default_filters("m0") + ["calib_apply", "joint_angle"]
                   for s in syms), sorted(s for s in syms if s.endswith("_q_update"))
    assert "leg_f32_update" not in syms


def test_firmware_builds_are_cached_under_kinefuse_cache(tmp_path, monkeypatch):
    """KINEFUSE_CACHE moves every kinefuse cache; the firmware's ignored it (only
    KINEFUSE_CACHE_DIR and XDG_CACHE_HOME) and wrote to ~/.cache/kinefuse."""
    from kinefuse.firmware.targets import cache_dir
    monkeypatch.delenv("KINEFUSE_CACHE_DIR", raising=False)
    monkeypatch.setenv("KINEFUSE_CACHE", str(tmp_path / "kc"))
    assert cache_dir("build") == tmp_path / "kc" / "build" and (tmp_path / "kc" / "build").is_dir()
    monkeypatch.delenv("KINEFUSE_CACHE")
    monkeypatch.setenv("KINEFUSE_CACHE_DIR", str(tmp_path / "old"))
    assert cache_dir("build") == tmp_path / "old" / "build"


def test_a_change_of_the_standard_flags_rebuilds(tmp_path, monkeypatch):
    """The cache key covered the architecture, -O and -D/-I flags but not the C/C++ flags: adding
    -fno-math-errno to them returned the builds made without it."""
    from kinefuse.firmware import targets
    if targets.toolchain_missing():
        pytest.skip(targets.toolchain_missing())
    monkeypatch.setenv("KINEFUSE_CACHE", str(tmp_path / "kc"))
    src = tmp_path / "f.c"
    src.write_text("int main(void) { return 0; }\n")
    first = targets.build([src], "m4f", hal=False)
    assert targets.build([src], "m4f", hal=False).elf == first.elf            # cached
    monkeypatch.setattr(targets, "C_FLAGS", targets.C_FLAGS + ("-fno-strict-aliasing",))
    assert targets.build([src], "m4f", hal=False).elf != first.elf


@pytest.mark.parametrize("argv, text", [
    # each was accepted and ignored: sizes builds its fixed sets, tables builds nothing
    (["sizes", "--filters", "madgwick"], "--filters does not apply to sizes"),
    (["sizes", "--opt=-O3"], "--opt does not apply to sizes"),
    (["sizes", "--out", "x"], "--out does not apply to sizes"),
    (["tables", "--opt=-O2"], "--opt does not apply to tables"),
    (["host", "--check"], "--check does not apply to host"),
])
def test_build_options_that_do_not_apply_are_refused(capsys, argv, text):
    assert fb.main(argv) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.startswith(f"kinefuse: error: {text}")
    assert err.count("\n") == 1


def test_build_out_must_not_be_a_file(capsys, tmp_path):
    # a file as --out was a FileExistsError traceback after the build
    f = tmp_path / "f"
    f.write_text("x")
    assert fb.main(["host", "--out", str(f)]) == 2
    assert capsys.readouterr().err == f"kinefuse: error: --out {f} is a file, not a folder\n"


@pytest.mark.skipif(shutil.which("arm-none-eabi-gcc") is None, reason="arm-none-eabi-gcc not installed")
def test_build_opt_takes_a_dashed_value_as_the_readme_writes_it(capsys):
    # `--opt -Os` was refused by argparse ("argument --opt: expected one argument")
    assert fb.main(["m4f", "--opt", "-Os", "--filters", "madgwick", "--json"]) == 0
    os_flash = json.loads(capsys.readouterr().out)["m4f"]["flash"]
    assert fb.main(["m4f", "--opt=-O2", "--filters", "madgwick", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["m4f"]["flash"] != os_flash       # the flag was used
    with pytest.raises(SystemExit) as exc:
        fb.main(["m4f", "--opt", "-DKF_X=1"])     # the compiler's first flag: a level, nothing else
    assert exc.value.code == 2 and "argument --opt: '-DKF_X=1' is not one of -O0" in capsys.readouterr().err


def test_build_with_an_empty_filter_list_is_refused(capsys):
    # `--filters ,` built (and flash would have programmed) an application without any filter
    assert fb.main(["m4f", "--filters", ","]) == 2
    err = capsys.readouterr().err
    assert err.startswith("kinefuse: error: no filter named: --filters takes wired filters (") and err.count("\n") == 1
