"""`kinefuse flash` up to the probe boundary: the exact command line built for each tool and
image, one-line errors for what is missing (MCU type, image, tool, probe, DFU device), and the
refusal to program an image that cannot run on the MCU named (the builds here are for QEMU's
MPS2 boards; an --image is checked against the MCU's memory map)."""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys

import pytest

from kinefuse.host.cli import main

HEX = ":020000040800F2\n:10000000000001200D0100080F0100081101000887\n:00000001FF\n"   # (was ...76: a bad checksum)
VECTORS = bytes.fromhex("000001200D0100080F01000811010008")    # SP 0x20010000, reset 0x0800010D


def ihex(address: int, data: bytes) -> str:
    """Intel HEX of ``data`` at ``address`` (ext. linear address record + 16-byte records)."""
    def rec(kind, addr, payload):
        body = bytes([len(payload), addr >> 8, addr & 0xFF, kind]) + payload
        return ":" + (body + bytes([(-sum(body)) & 0xFF])).hex().upper()
    lines, upper = [], None
    for k in range(0, len(data), 16):
        a = address + k
        if a >> 16 != upper:                    # a new 64 kB window: extended linear address
            upper = a >> 16
            lines.append(rec(4, 0, upper.to_bytes(2, "big")))
        lines.append(rec(0, a & 0xFFFF, data[k:k + 16]))
    return "\n".join(lines + [":00000001FF"]) + "\n"


IN_CI = os.environ.get("CI") == "true"      # .ci/run installs pyOCD and dfu-util: there they must run


def run(capsys, *argv):
    code = main(["flash", *argv])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture
def image(tmp_path):
    h = tmp_path / "fw.hex"
    h.write_text(HEX)
    assert ihex(0x08000000, VECTORS) == HEX
    b = tmp_path / "fw.bin"
    b.write_bytes(VECTORS)
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
    b.write_bytes((0x20040000).to_bytes(4, "little") + (0x1101).to_bytes(4, "little"))   # nRF52840 RAM top
    code, _, err = run(capsys, "--image", str(b), "--mcu", "nrf52840", "--dry-run")
    assert code == 2 and "needs --address" in err and err.count("\n") == 1
    code, out, _ = run(capsys, "--image", str(b), "--mcu", "nrf52840", "--address", "0x1000", "--dry-run", "--json")
    assert json.loads(out)["command"][-4:] == ["bin", "-a", "0x00001000", str(b)]


def test_dfu_util_command_line_takes_the_address_from_the_hex(capsys, image):
    code, out, _ = run(capsys, "--image", str(image / "fw.bin"), "--tool", "dfu-util", "--dfu-device", "0483:df11",
                       "--mcu", "stm32f411re", "--dry-run", "--json")
    assert code == 0
    assert json.loads(out)["command"] == ["dfu-util", "-a", "0", "-d", "0483:df11", "-s", "0x08000000:leave",
                                          "-D", str(image / "fw.bin")]
    (image / "app.bin").write_bytes(VECTORS)       # no .hex beside it: the address given decides
    code, out, err = run(capsys, "--image", str(image / "app.bin"), "--tool", "dfu-util", "--address", "0x08004000",
                         "--alt", "1", "--serial", "ABC", "--mcu", "stm32f411re", "--dry-run", "--json")
    assert code == 0, err
    assert json.loads(out)["command"] == ["dfu-util", "-a", "1", "-S", "ABC", "-s", "0x08004000:leave",
                                          "-D", str(image / "app.bin")]


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


@pytest.mark.parametrize("value", ["nan", "inf", "0", "-1"])
def test_timeout_must_be_a_positive_finite_number(capsys, image, value):
    # nan was accepted (`nan <= 0` is false) and handed to subprocess.run
    with pytest.raises(SystemExit) as exc:
        main(["flash", "--image", str(image / "fw.hex"), "--mcu", "stm32f411re", "--dry-run",
              "--timeout", value])
    err = capsys.readouterr().err
    assert exc.value.code == 2 and f"argument --timeout: {value} is not in (0, 86400]" in err


@pytest.mark.parametrize("opt", [["--target", "m0"], ["--filters", "madgwick"]])
def test_build_options_with_an_image_are_refused(capsys, image, opt):
    # they were ignored: the --image was flashed whatever --target or --filters said
    code, out, err = run(capsys, "--image", str(image / "fw.hex"), "--mcu", "stm32f411re", "--dry-run", *opt)
    assert code == 2 and out == "" and err.count("\n") == 1
    assert f"{opt[0]} chooses what to build; --image {image / 'fw.hex'} is flashed as it is" in err


@pytest.mark.parametrize("argv, text", [
    # each was accepted and left out of the command line
    (["--serial", "ABC"], "--serial is a dfu-util option; this flashes with pyocd (--tool)"),
    (["--alt", "1"], "--alt is a dfu-util option; this flashes with pyocd (--tool)"),
    (["--tool", "dfu-util", "--probe", "0240"], "--probe is a pyOCD option; this flashes with dfu-util (--tool)"),
    (["--tool", "dfu-util", "--erase", "chip"], "--erase is a pyOCD option; this flashes with dfu-util (--tool)"),
])
def test_the_other_tools_options_are_refused(capsys, image, argv, text):
    code, out, err = run(capsys, "--image", str(image / "fw.bin"), "--mcu", "stm32f411re",
                         "--address", "0x08000000", "--dry-run", *argv)
    assert code == 2 and out == "" and err == f"kinefuse: error: {text}\n"


def test_missing_tool_is_reported(capsys, image, monkeypatch):
    monkeypatch.setenv("PATH", str(image))
    code, _, err = run(capsys, "--image", str(image / "fw.hex"), "--mcu", "stm32f411re")
    assert code == 2 and "pyocd not found: pip install pyocd" in err


@pytest.mark.skipif(shutil.which("pyocd") is None and not IN_CI, reason="pyocd not installed (pip install pyocd)")
def test_no_probe_is_one_line_with_the_real_pyocd(capsys, image):
    code, _, err = run(capsys, "--image", str(image / "fw.hex"), "--mcu", "stm32f411re", "--timeout", "60")
    assert code == 2 and err.count("\n") == 1
    assert "no debug probe connected" in err


@pytest.mark.skipif(shutil.which("pyocd") is None and not IN_CI, reason="pyocd not installed (pip install pyocd)")
def test_unknown_probe_id_with_the_real_pyocd(capsys, image):
    code, _, err = run(capsys, "--image", str(image / "fw.hex"), "--mcu", "stm32f411re", "--probe", "123abc")
    assert code == 2 and "123abc" in err and err.count("\n") == 1


@pytest.mark.skipif(shutil.which("dfu-util") is None and not IN_CI,
                    reason="dfu-util not installed (apt-get install dfu-util)")
def test_no_dfu_device_is_one_line_with_the_real_dfu_util(capsys, image):
    code, _, err = run(capsys, "--image", str(image / "fw.bin"), "--tool", "dfu-util", "--mcu", "stm32f411re",
                       "--timeout", "60")
    assert code == 2 and "no DFU device found" in err and err.count("\n") == 1


def test_explain_failure_parses_tool_output():
    from kinefuse.host.commands.flash_cmd import explain_failure
    assert "no debug probe" in explain_failure("pyocd", "0001 E No connected debug probes [load_cmd]", 1)
    assert "several DFU devices" in explain_failure("dfu-util", "More than one DFU capable USB device found!", 74)
    assert explain_failure("pyocd", "0001840 E Flash algorithm failed to erase [flash]", 1) == \
        "pyocd failed: Flash algorithm failed to erase [flash]"


MPS2_VECTORS = (0x20400000).to_bytes(4, "little") + (0x00000101).to_bytes(4, "little")   # as boards/mps2


@pytest.mark.parametrize("tool, mcu, data, address, text", [
    ("pyocd", "stm32f411re", MPS2_VECTORS, 0x0, "data at 0x00000000-0x00000007, outside stm32f411re's flash"),
    ("dfu-util", "stm32f411re", MPS2_VECTORS, 0x0, "outside stm32f411re's flash"),
    ("pyocd", "nrf52840", MPS2_VECTORS, 0x0, "stack pointer 0x20400000 is outside nrf52840's RAM"),
    ("pyocd", "stm32f411re", VECTORS[:4] + (0x08000100).to_bytes(4, "little"), 0x08000000, "not a Thumb address"),
    ("pyocd", "stm32f411re", VECTORS * 40000, 0x08000000, "outside stm32f411re's flash"),   # 640 kB > 512 kB
    ("pyocd", "cortex_m", VECTORS, 0x08000000, "no flash"),
    ("pyocd", "nosuchmcu9", VECTORS, 0x08000000, "memory map of --mcu nosuchmcu9 is unknown"),
], ids=["mps2-on-stm32", "mps2-dfu", "mps2-on-nrf52840", "arm-reset-vector", "too-big", "generic", "unknown"])
def test_an_image_for_another_board_is_refused(capsys, tmp_path, tool, mcu, data, address, text):
    h = tmp_path / "img.hex"
    h.write_text(ihex(address, data))
    (tmp_path / "img.bin").write_bytes(data)
    img = h if tool == "pyocd" else tmp_path / "img.bin"
    code, out, err = run(capsys, "--image", str(img), "--tool", tool, "--mcu", mcu, "--dry-run")
    assert code == 2 and text in err and err.count("\n") == 1 and out == "", err


def test_a_hex_record_with_a_bad_checksum_is_refused(capsys, tmp_path):
    h = tmp_path / "bad.hex"
    h.write_text(HEX.replace("0887", "0876"))
    code, _, err = run(capsys, "--image", str(h), "--mcu", "stm32f411re", "--dry-run")
    assert code == 2 and "checksum" in err and err.count("\n") == 1


def test_a_hex_record_that_is_not_hexadecimal_is_refused(capsys, tmp_path):
    # was an internal error (ValueError from int(..., 16)) while looking for the load address
    h = tmp_path / "bad.hex"
    h.write_text(":ZZ0000000000\n")
    code, _, err = run(capsys, "--image", str(h), "--mcu", "stm32f411re", "--dry-run")
    assert code == 2 and "line 1 is not hexadecimal" in err and err.count("\n") == 1, err


def test_dfu_util_needs_the_mcu_for_the_check(capsys, image):
    code, _, err = run(capsys, "--image", str(image / "fw.bin"), "--tool", "dfu-util", "--dry-run")
    assert code == 2 and "--mcu" in err and "memory map" in err and err.count("\n") == 1


def test_an_elf_is_checked_by_its_load_segments(capsys, tmp_path):
    import struct
    data = VECTORS
    ph = struct.pack("<IIIIIIII", 1, 52 + 32, 0x08000000, 0x08000000, len(data), len(data), 5, 4)
    head = b"\x7fELF" + bytes([1, 1, 1]) + bytes(9) + struct.pack("<HHIIIIIHHHHHH", 2, 40, 1, 0x08000101, 52, 0,
                                                                     0x5000400, 52, 32, 1, 0, 0, 0)
    elf = tmp_path / "fw.elf"
    elf.write_bytes(head + ph + data)
    code, out, err = run(capsys, "--image", str(elf), "--mcu", "stm32f411re", "--dry-run", "--json")
    assert code == 0 and json.loads(out)["command"][-3:] == ["--format", "elf", str(elf)], err
    code, _, err = run(capsys, "--image", str(elf), "--mcu", "nrf52840", "--dry-run")
    assert code == 2 and "outside nrf52840's flash" in err


def test_a_build_is_refused_for_a_real_mcu_before_building(capsys, monkeypatch):
    from kinefuse.firmware import build
    monkeypatch.setattr(build, "build_target", lambda *a, **k: pytest.fail("built although refused"))
    for target, board in (("m4f", "mps2-an386"), ("m0", "mps2-an385")):
        code, out, err = run(capsys, "--target", target, "--mcu", "stm32f411re", "--dry-run")
        assert code == 2 and err.count("\n") == 1 and out == ""
        assert f"linked for QEMU's {board} board" in err and "no board port exists for stm32f411re" in err


def _readelf_attributes(elf) -> str:
    return subprocess.run(["arm-none-eabi-readelf", "-A", str(elf)], capture_output=True, text=True,
                          check=True).stdout


def _functions(elf) -> dict[str, str]:
    """Disassembly of every function of an ELF: {name: body}."""
    dis = subprocess.run(["arm-none-eabi-objdump", "-d", "--no-show-raw-insn", str(elf)], capture_output=True,
                         text=True, check=True).stdout
    out, name = {}, None
    for line in dis.splitlines():
        if line.endswith(">:") and " <" in line:
            name = line.split(" <", 1)[1][:-2]
            out[name] = ""
        elif name is not None:
            out[name] += line + "\n"
    return out


@pytest.mark.qemu
@pytest.mark.skipif(shutil.which("arm-none-eabi-gcc") is None, reason="arm-none-eabi-gcc not installed")
def test_builds_the_right_image_for_each_target(monkeypatch):
    """m4f: ARMv7E-M with the single-precision FPU, float32 filters in FPU registers; m0:
    ARMv6-M, no FPU, the fixed-point filters (``*_q_update``) linked and no soft-float call
    (``__aeabi_f*``) inside them."""
    import argparse

    from kinefuse.firmware import build
    from kinefuse.host.commands import flash_cmd
    monkeypatch.setattr(build, "git_hash", lambda: 0)      # the same (cached) build as the QEMU tests
    imgs = {}
    for target in ("m4f", "m0"):
        args = argparse.Namespace(image=None, target=target, filters="madgwick,flagship")
        img = imgs[target] = flash_cmd._image(args)
        assert img["hex"].name == f"kinefuse-{target}.hex" and img["board"] == flash_cmd.TARGET_BOARDS[target]
        assert img["flash_bytes"] > 10_000 and img["source"] == f"build {target} (madgwick,flagship)"
    a4, a0 = _readelf_attributes(imgs["m4f"]["elf"]), _readelf_attributes(imgs["m0"]["elf"])
    assert "Tag_CPU_arch: v7E-M" in a4 and "Tag_FP_arch: VFPv4-D16" in a4 and "Tag_ABI_VFP_args: VFP registers" in a4
    assert "Tag_CPU_arch: v6S-M" in a0 and "Tag_FP_arch" not in a0 and "Tag_ABI_VFP_args" not in a0
    f0, f4 = _functions(imgs["m0"]["elf"]), _functions(imgs["m4f"]["elf"])
    q_updates = sorted(n for n in f0 if n.endswith("_q_update"))
    assert {"madgwick_q_update", "flagship_q_update"} <= set(q_updates), q_updates
    assert not any(n.endswith("_f32_update") for n in f0)
    for name in q_updates:
        assert "__aeabi_f" not in f0[name] and "__aeabi_d" not in f0[name], name   # integer arithmetic only
        assert "vmul" not in f0[name] and "vadd" not in f0[name]
    f32_updates = [n for n in f4 if n.endswith("_f32_update")]
    assert {"madgwick_f32_update", "flagship_f32_update"} <= set(f32_updates)
    assert "vmul.f32" in f4["madgwick_f32_update"] and "__aeabi_f" not in f4["madgwick_f32_update"]


def test_pyocd_flashes_the_image_named_not_a_sibling_hex(capsys, tmp_path):
    # --image fw.elf / fw.bin with an (older) fw.hex beside it: the .hex was flashed and checked
    import struct
    ph = struct.pack("<IIIIIIII", 1, 52 + 32, 0x08000000, 0x08000000, len(VECTORS), len(VECTORS), 5, 4)
    head = b"\x7fELF" + bytes([1, 1, 1]) + bytes(9) + struct.pack("<HHIIIIIHHHHHH", 2, 40, 1, 0x08000101, 52, 0,
                                                                     0x5000400, 52, 32, 1, 0, 0, 0)
    elf = tmp_path / "fw.elf"
    elf.write_bytes(head + ph + VECTORS)
    (tmp_path / "fw.bin").write_bytes(VECTORS)
    (tmp_path / "fw.hex").write_text(ihex(0x0, MPS2_VECTORS))      # another board's, stale
    code, out, err = run(capsys, "--image", str(elf), "--mcu", "stm32f411re", "--dry-run", "--json")
    assert code == 0, err
    assert json.loads(out)["command"][-3:] == ["--format", "elf", str(elf)]
    code, out, err = run(capsys, "--image", str(tmp_path / "fw.bin"), "--mcu", "stm32f411re",
                         "--address", "0x08000000", "--dry-run", "--json")
    assert code == 0, err
    assert json.loads(out)["command"][-4:] == ["bin", "-a", "0x08000000", str(tmp_path / "fw.bin")]
    # the .hex named is the one checked and flashed
    code, _, err = run(capsys, "--image", str(tmp_path / "fw.hex"), "--mcu", "stm32f411re", "--dry-run")
    assert code == 2 and "outside stm32f411re's flash" in err


def test_an_image_that_is_a_directory_is_named_so(capsys, tmp_path):
    d = tmp_path / "fw.hex"
    d.mkdir()
    code, _, err = run(capsys, "--image", str(d), "--mcu", "stm32f411re", "--dry-run")
    assert code == 2 and err == f"kinefuse: error: image {d} is a directory, not a firmware file\n"


def test_an_address_with_a_hex_for_pyocd_is_refused(capsys, image):
    # it was ignored: the .hex went to its own addresses (over a bootloader the address avoided)
    code, out, err = run(capsys, "--image", str(image / "fw.hex"), "--mcu", "stm32f411re",
                         "--address", "0x08004000", "--dry-run")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "--address goes with a .bin image" in err
