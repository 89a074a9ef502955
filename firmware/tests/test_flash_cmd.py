"""`kinefuse flash` up to the probe boundary: the exact command line built for each tool and
image, one-line errors for what is missing (MCU type, image, tool, probe, DFU device)."""
from __future__ import annotations

import json
import shutil
import subprocess
import sys

import pytest

from kinefuse.host.cli import main

HEX = ":020000040800F2\n:10000000000001200D0100080F0100081101000876\n:00000001FF\n"


def run(capsys, *argv):
    code = main(["flash", *argv])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture
def image(tmp_path):
    h = tmp_path / "fw.hex"
    h.write_text(HEX)
    b = tmp_path / "fw.bin"
    b.write_bytes(bytes(range(16)))
    e = tmp_path / "fw.elf"
    e.write_bytes(b"\x7fELF")
    return tmp_path


def test_pyocd_command_line(capsys, image):
    code, out, _ = run(capsys, "--image", str(image / "fw.hex"), "--mcu", "stm32f411re", "--probe", "0240ab",
                       "--erase", "sector", "--dry-run", "--json")
    assert code == 0
    res = json.loads(out)
    assert res["command"] == ["pyocd", "flash", "--no-wait", "-t", "stm32f411re", "-u", "0240ab", "-e", "sector",
                              "--format", "hex", str(image / "fw.hex")]


def test_pyocd_with_a_bin_needs_an_address(capsys, tmp_path):
    b = tmp_path / "only.bin"
    b.write_bytes(b"\0" * 8)
    code, _, err = run(capsys, "--image", str(b), "--mcu", "nrf52840", "--dry-run")
    assert code == 2 and "needs --address" in err and err.count("\n") == 1
    code, out, _ = run(capsys, "--image", str(b), "--mcu", "nrf52840", "--address", "0x1000", "--dry-run", "--json")
    assert json.loads(out)["command"][-4:] == ["bin", "-a", "0x00001000", str(b)]


def test_dfu_util_command_line_takes_the_address_from_the_hex(capsys, image):
    code, out, _ = run(capsys, "--image", str(image / "fw.bin"), "--tool", "dfu-util", "--dfu-device", "0483:df11",
                       "--dry-run", "--json")
    assert code == 0
    assert json.loads(out)["command"] == ["dfu-util", "-a", "0", "-d", "0483:df11", "-s", "0x08000000:leave",
                                          "-D", str(image / "fw.bin")]
    code, out, _ = run(capsys, "--image", str(image / "fw.bin"), "--tool", "dfu-util", "--address", "0x08004000",
                       "--alt", "1", "--serial", "ABC", "--dry-run", "--json")
    assert json.loads(out)["command"] == ["dfu-util", "-a", "1", "-S", "ABC", "-s", "0x08004000:leave",
                                          "-D", str(image / "fw.bin")]


@pytest.mark.parametrize("argv, text", [
    (["--image", "nope.hex", "--mcu", "x"], "not found"),
    (["--dry-run"], "--mcu"),
    (["--tool", "dfu-util", "--image", "IMG/hexonly/fw.hex", "--dry-run"], "raw .bin"),
    (["--tool", "dfu-util", "--image", "IMG/fw.bin", "--address", "zz", "--dry-run"], "bad --address"),
    (["--tool", "dfu-util", "--image", "IMG/fw.bin", "--dfu-device", "12:34", "--dry-run"], "VID:PID"),
    (["--image", "IMG/fw.hex", "--mcu", "bad type!", "--dry-run"], "bad --mcu"),
])
def test_user_errors_are_one_line(capsys, image, argv, text):
    (image / "hexonly").mkdir()
    (image / "hexonly" / "fw.hex").write_text(HEX)
    argv = [a.replace("IMG", str(image)) for a in argv]
    code, _, err = run(capsys, *argv)
    assert code == 2 and text in err and err.count("\n") == 1 and "Traceback" not in err


def test_missing_tool_is_reported(capsys, image, monkeypatch):
    monkeypatch.setenv("PATH", str(image))
    code, _, err = run(capsys, "--image", str(image / "fw.hex"), "--mcu", "stm32f411re")
    assert code == 2 and "pyocd not found: pip install pyocd" in err


@pytest.mark.skipif(shutil.which("pyocd") is None, reason="pyocd not installed (pip install pyocd)")
def test_no_probe_is_one_line_with_the_real_pyocd(capsys, image):
    code, _, err = run(capsys, "--image", str(image / "fw.hex"), "--mcu", "stm32f411re", "--timeout", "60")
    assert code == 2 and err.count("\n") == 1
    assert "no debug probe connected" in err


@pytest.mark.skipif(shutil.which("pyocd") is None, reason="pyocd not installed (pip install pyocd)")
def test_unknown_probe_id_with_the_real_pyocd(capsys, image):
    code, _, err = run(capsys, "--image", str(image / "fw.hex"), "--mcu", "stm32f411re", "--probe", "123abc")
    assert code == 2 and "123abc" in err and err.count("\n") == 1


@pytest.mark.skipif(shutil.which("dfu-util") is None, reason="dfu-util not installed (apt-get install dfu-util)")
def test_no_dfu_device_is_one_line_with_the_real_dfu_util(capsys, image):
    code, _, err = run(capsys, "--image", str(image / "fw.bin"), "--tool", "dfu-util", "--timeout", "60")
    assert code == 2 and "no DFU device found" in err and err.count("\n") == 1


def test_explain_failure_parses_tool_output():
    from kinefuse.host.commands.flash_cmd import explain_failure
    assert "no debug probe" in explain_failure("pyocd", "0001 E No connected debug probes [load_cmd]", 1)
    assert "several DFU devices" in explain_failure("dfu-util", "More than one DFU capable USB device found!", 74)
    assert explain_failure("pyocd", "0001840 E Flash algorithm failed to erase [flash]", 1) == \
        "pyocd failed: Flash algorithm failed to erase [flash]"


@pytest.mark.qemu
@pytest.mark.skipif(shutil.which("arm-none-eabi-gcc") is None, reason="arm-none-eabi-gcc not installed")
def test_builds_the_right_image_for_each_target(capsys, monkeypatch):
    from kinefuse.firmware import build
    monkeypatch.setattr(build, "git_hash", lambda: 0)      # the same (cached) build as the QEMU tests
    for target in ("m4f", "m0"):
        code, out, _ = run(capsys, "--target", target, "--filters", "madgwick,flagship", "--mcu", "cortex_m",
                           "--dry-run", "--json")
        res = json.loads(out)
        assert code == 0 and res["command"][-1].endswith(f"kinefuse-{target}.hex")
        assert res["flash_bytes"] > 10_000 and res["image"] == f"build {target} (madgwick,flagship)"
        # the fixed-point build for the M0: no hardware float instructions in its code
        if target == "m0":
            elf = res["command"][-1][:-4] + ".elf"
            dis = subprocess.run(["arm-none-eabi-objdump", "-d", elf], capture_output=True, text=True).stdout
            assert "vmul.f32" not in dis and "vadd.f32" not in dis
