"""``kinefuse flash``: program a unit with the kinefuse application through pyOCD or dfu-util.

    kinefuse flash --mcu stm32f411re                       # build for m4f, flash the HEX with pyOCD
    kinefuse flash --target m0 --mcu nrf51 --probe 0240000   # fixed-point build, one probe of several
    kinefuse flash --tool dfu-util --address 0x08000000      # BIN through the USB DFU bootloader
    kinefuse flash --image fw.hex --mcu stm32f411re --dry-run   # print the command only

The image is the application built for ``--target`` (``m4f``: float32 filters, ``m0``:
fixed-point filters, by default flagship, madgwick, mahony and complementary at ``-Os`` so that
it fits a 256 kB part; ``--filters`` builds a subset or ``all``) unless ``--image`` names one.  pyOCD gets
the HEX (addresses included, or the ELF), dfu-util the raw BIN at ``--address`` (default: the
image's load address).  pyOCD needs the MCU's target type (``--mcu``; ``pyocd list --targets``):
the generic Cortex-M target cannot program flash.

Only the QEMU MPS2 board ports exist (firmware/boards/mps2: flash and RAM at 0x00000000, CMSDK
UART, SysTick): the images built here run on ``mps2-an386`` (m4f) and ``mps2-an385`` (m0), not
on a real MCU, so ``kinefuse flash`` refuses to program a build into one (there is no board
port to match any ``--mcu``).  An image made elsewhere (``--image``, e.g. from your own board
port) is checked against the MCU's memory map before anything runs: every byte in its flash,
the initial stack pointer in its RAM, the reset vector a Thumb address in its flash (memory
maps: a built-in table of common parts -- ``MCU_MEMORY`` -- else pyOCD's built-in targets; an
MCU known to neither is refused).  dfu-util needs ``--mcu`` for that check too.
"""
from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

from kinefuse.host import argtypes
from kinefuse.host.errors import KinefuseError

TOOLS = ("pyocd", "dfu-util")
INSTALL = {"pyocd": "pip install pyocd", "dfu-util": "apt-get install dfu-util"}
# tool output -> one-line explanation (first match wins)
KNOWN_ERRORS = (
    (r"No connected debug probe matches unique ID '([^']*)'",
     "no connected debug probe has the unique ID {0} (pyocd list --probes shows the connected ones)"),
    (r"No (?:connected|available) debug probes?",
     "no debug probe connected (pyOCD found none: connect the probe and the unit's SWD cable)"),
    (r"Target type '?([\w.-]+)'? not recognized|not a recognized target type|Unknown target type",
     "pyOCD does not know the MCU type given with --mcu (see `pyocd list --targets`)"),
    (r"No DFU capable USB device available",
     "no DFU device found (put the unit in its USB bootloader, check the cable and udev permissions)"),
    (r"More than one DFU capable USB device found",
     "several DFU devices found: choose one with --dfu-device VID:PID or --serial"),
    (r"Cannot open DFU device|LIBUSB_ERROR_ACCESS",
     "the DFU device cannot be opened (permissions: add a udev rule or run as a user in plugdev)"),
)


# Memory of common parts (reference manuals / datasheets): flash regions, RAM regions, (start, size).
# pyOCD 0.46 has no built-in target for e.g. stm32f411re (it comes from a CMSIS pack), so the
# check does not depend on packs being installed.
_K = 1024
MCU_MEMORY = {
    "stm32f401xe": {"flash": [(0x08000000, 512 * _K)], "ram": [(0x20000000, 96 * _K)]},
    "stm32f411xe": {"flash": [(0x08000000, 512 * _K)], "ram": [(0x20000000, 128 * _K)]},
    "stm32f411xc": {"flash": [(0x08000000, 256 * _K)], "ram": [(0x20000000, 128 * _K)]},
    "stm32f405xg": {"flash": [(0x08000000, 1024 * _K)], "ram": [(0x20000000, 128 * _K), (0x10000000, 64 * _K)]},
    "stm32f407xg": {"flash": [(0x08000000, 1024 * _K)], "ram": [(0x20000000, 128 * _K), (0x10000000, 64 * _K)]},
    "stm32f051x8": {"flash": [(0x08000000, 64 * _K)], "ram": [(0x20000000, 8 * _K)]},
    "nrf52832": {"flash": [(0x00000000, 512 * _K)], "ram": [(0x20000000, 64 * _K)]},
    "nrf52840": {"flash": [(0x00000000, 1024 * _K)], "ram": [(0x20000000, 256 * _K)]},
}
MCU_ALIASES = {"stm32f401re": "stm32f401xe", "stm32f411re": "stm32f411xe", "stm32f411ce": "stm32f411xe",
               "stm32f411cc": "stm32f411xc", "stm32f405rg": "stm32f405xg", "stm32f407vg": "stm32f407xg",
               "stm32f051r8": "stm32f051x8"}
# QEMU board of each build target; real MCUs with a board port for it (none yet)
TARGET_BOARDS = {"m4f": "mps2-an386", "m0": "mps2-an385"}
BOARD_PORTS: dict[str, tuple[str, ...]] = {"mps2-an386": (), "mps2-an385": ()}


def register(subparsers) -> None:
    p = subparsers.add_parser("flash", help="program a unit (pyOCD or dfu-util)",
                              description=__doc__.split("\n\n")[0].split(": ", 1)[-1])
    p.add_argument("--target", choices=("m4f", "m0"), default=None,
                   help="build to flash when no --image: m4f (float32 filters) or m0 (fixed point); default m4f")
    p.add_argument("--image", metavar="FILE", help="flash this .hex/.elf/.bin instead of building")
    p.add_argument("--filters", metavar="A,B", help="build only these wired filters, or 'all' (default: all; "
                                                    "m0: flagship,madgwick,mahony,complementary)")
    p.add_argument("--tool", choices=TOOLS, default="pyocd", help="flashing tool (default pyocd)")
    p.add_argument("--mcu", metavar="TYPE", help="the unit's MCU: pyOCD target type (e.g. stm32f411re); "
                                                 "the image is checked against its memory map")
    p.add_argument("--probe", metavar="UID", help="pyOCD: debug probe unique ID (default: the only one)")
    p.add_argument("--erase", choices=("auto", "chip", "sector"), help="pyOCD erase mode")
    p.add_argument("--address", metavar="ADDR", help="dfu-util (or a .bin with pyOCD): load address, "
                                                     "e.g. 0x08000000 (default: from the image)")
    p.add_argument("--alt", type=int, default=None, metavar="N", help="dfu-util: alternate setting (default 0)")
    p.add_argument("--dfu-device", metavar="VID:PID", help="dfu-util: USB vendor:product id")
    p.add_argument("--serial", metavar="SERIAL", help="dfu-util: USB serial number of the device")
    p.add_argument("--timeout", type=argtypes.real(0, 86400, lo_open=True), default=180.0, metavar="S", help="give up after S seconds (default 180)")
    p.add_argument("--dry-run", action="store_true", help="print the command line, do not run it")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=run)


# ------------------------------------------------------------------------------------ image

def _parse_address(text: str | None) -> int | None:
    if text is None:
        return None
    try:
        v = int(text, 0)
    except ValueError:
        raise KinefuseError(f"bad --address {text!r}: expected a number such as 0x08000000") from None
    if not 0 <= v < 2 ** 32:
        raise KinefuseError(f"--address {text} is outside the 32-bit address space")
    return v


def hex_load_address(path: Path) -> int:
    """Lowest address of the data records of an Intel HEX file (records checked as by
    :func:`hex_segments`: a non-hexadecimal record was an internal error here)."""
    segs = hex_segments(path)
    if not segs:
        raise KinefuseError(f"{path} holds no data")
    return min(a for a, _data in segs)


def hex_segments(path: Path) -> list[tuple[int, bytes]]:
    """(address, bytes) of the data records of an Intel HEX file, merged where contiguous."""
    base, segs = 0, []
    for n, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
        line = line.strip()
        if not line:
            continue
        if not line.startswith(":") or len(line) < 11:
            raise KinefuseError(f"{path}: line {n} is not an Intel HEX record")
        try:
            raw = bytes.fromhex(line[1:])
        except ValueError:
            raise KinefuseError(f"{path}: line {n} is not hexadecimal") from None
        count, addr, kind = raw[0], (raw[1] << 8) | raw[2], raw[3]
        if len(raw) != count + 5 or sum(raw) & 0xFF:
            raise KinefuseError(f"{path}: line {n} has a bad length or checksum (damaged image?)")
        data = raw[4:4 + count]
        if kind == 0 and count:
            a = base + addr
            if segs and segs[-1][0] + len(segs[-1][1]) == a:
                segs[-1] = (segs[-1][0], segs[-1][1] + data)
            else:
                segs.append((a, data))
        elif kind == 2:
            base = int.from_bytes(data[:2], "big") << 4
        elif kind == 4:
            base = int.from_bytes(data[:2], "big") << 16
    return segs


def elf_segments(path: Path) -> list[tuple[int, bytes]]:
    """(load address, bytes) of the PT_LOAD segments of a 32-bit little-endian ELF."""
    import struct
    b = path.read_bytes()
    if len(b) < 52 or b[:4] != b"\x7fELF" or b[4] != 1 or b[5] != 1:
        raise KinefuseError(f"{path} is not a 32-bit little-endian ELF file")
    phoff, = struct.unpack_from("<I", b, 28)
    phentsize, phnum = struct.unpack_from("<HH", b, 42)
    segs = []
    for k in range(phnum):
        o = phoff + k * phentsize
        if o + 32 > len(b):
            raise KinefuseError(f"{path}: truncated ELF program header")
        ptype, offset, _vaddr, paddr, filesz = struct.unpack_from("<IIIII", b, o)
        if ptype == 1 and filesz:
            segs.append((paddr, b[offset:offset + filesz]))
    return sorted(segs)


def flashed_kind(img: dict, tool: str = "pyocd") -> str | None:
    """Which of the image's files the tool gets: dfu-util the .bin; pyOCD the file --image
    named (a sibling .hex of an --image fw.elf or fw.bin may be an older build: it was flashed
    instead), else the build's HEX, ELF or BIN."""
    if tool == "dfu-util":
        return "bin" if img.get("bin") is not None else None
    named = img.get("named")
    if named is not None and img.get(named) is not None:
        return named
    return next((k for k in ("hex", "elf", "bin") if img.get(k) is not None), None)


def image_segments(img: dict, address: int | None, tool: str = "pyocd") -> list[tuple[int, bytes]]:
    """(address, bytes) of the file the tool gets (see :func:`flashed_kind`)."""
    kind = flashed_kind(img, tool)
    if kind == "hex":
        return hex_segments(Path(img["hex"]))
    if kind == "elf":
        return elf_segments(Path(img["elf"]))
    if address is None:   # a .bin's address: from the .hex beside it
        address = img.get("address")
    if kind == "bin" and address is not None:
        return [(address, Path(img["bin"]).read_bytes())]
    return []


def mcu_memory(mcu: str) -> dict | None:
    """{'flash': [(start, size)], 'ram': [...], 'source': ...} of an MCU, or None if unknown."""
    name = mcu.lower()
    key = MCU_ALIASES.get(name, name)
    if key in MCU_MEMORY:
        return {**MCU_MEMORY[key], "source": "kinefuse's table"}
    try:
        from pyocd.target.builtin import BUILTIN_TARGETS
    except Exception:  # noqa: BLE001 - pyOCD missing or broken: no second source
        return None
    cls = BUILTIN_TARGETS.get(name)
    if cls is None:
        return None
    mm = getattr(cls, "MEMORY_MAP", None)
    regions = list(mm) if mm is not None else []
    flash = [(r.start, r.length) for r in regions if r.is_flash]
    ram = [(r.start, r.length) for r in regions if r.is_ram]
    if not flash:
        return {"flash": [], "ram": ram, "source": "pyOCD (no flash in its memory map)"}
    return {"flash": flash, "ram": ram, "source": "pyOCD"}


def _inside(regions, start: int, end: int) -> bool:
    return any(a <= start and end <= a + n for a, n in regions)


def check_image_for_mcu(args, img: dict) -> None:
    """Refuse (one line) an image that cannot run on --mcu; see the module docstring."""
    board = img.get("board")
    mcu = args.mcu
    if board is not None:
        ports = BOARD_PORTS.get(board, ())
        if mcu is None or mcu.lower() not in ports:
            raise KinefuseError(
                f"the {img['target']} build is linked for QEMU's {board} board (flash and RAM at 0x00000000, "
                f"CMSDK UART): no board port exists for {mcu or 'a real MCU'}, so it would not run there; "
                f"only the QEMU MPS2 ports exist (firmware/boards/mps2); flash your own port's image with --image")
        return
    if mcu is None:
        raise KinefuseError(f"name the unit's MCU with --mcu (e.g. stm32f411re): the image is checked against "
                            f"its memory map before {args.tool} runs")
    mem = mcu_memory(mcu)
    if mem is None:
        raise KinefuseError(f"the memory map of --mcu {mcu} is unknown (neither kinefuse's table nor pyOCD's "
                            f"built-in targets): cannot check that the image fits it")
    if not mem["flash"]:
        raise KinefuseError(f"--mcu {mcu} has no flash in its memory map ({mem['source']}): name the unit's "
                            f"actual MCU type, e.g. stm32f411re")
    segs = image_segments(img, _parse_address(args.address), args.tool)
    if not segs:
        raise KinefuseError(f"image {img['source']} holds no data")
    fl = ", ".join(f"0x{a:08X}-0x{a + n - 1:08X}" for a, n in mem["flash"])
    for a, data in segs:
        if not _inside(mem["flash"], a, a + len(data)):
            raise KinefuseError(f"image {img['source']} has data at 0x{a:08X}-0x{a + len(data) - 1:08X}, outside "
                                f"{mcu}'s flash ({fl}): it is linked for another board")
    first = segs[0]
    if len(first[1]) < 8:
        raise KinefuseError(f"image {img['source']}: no vector table at its start (0x{first[0]:08X})")
    sp = int.from_bytes(first[1][0:4], "little")
    reset = int.from_bytes(first[1][4:8], "little")
    ram = ", ".join(f"0x{a:08X}-0x{a + n - 1:08X}" for a, n in mem["ram"])
    if mem["ram"] and not any(a < sp <= a + n for a, n in mem["ram"]):
        raise KinefuseError(f"image {img['source']}: initial stack pointer 0x{sp:08X} is outside {mcu}'s RAM ({ram}): "
                            f"it is linked for another board")
    if not reset & 1 or not _inside(mem["flash"], reset & ~1, (reset & ~1) + 2):
        raise KinefuseError(f"image {img['source']}: reset vector 0x{reset:08X} is not a Thumb address in {mcu}'s "
                            f"flash ({fl}): it is linked for another board")


def _image(args) -> dict:
    """The files to flash: {'hex', 'bin', 'elf', 'address', 'source'} (missing ones None)."""
    if args.image:
        p = Path(args.image)
        if not p.is_file():   # a directory was reported "not found"
            raise KinefuseError(f"image {p} is a directory, not a firmware file" if p.is_dir() else
                                f"image {p} is not a regular file" if p.exists() else f"image {p} not found")
        suffix = p.suffix.lower()
        if suffix not in (".hex", ".ihex", ".elf", ".axf", ".bin"):
            raise KinefuseError(f"image {p}: expected .hex, .elf or .bin")
        img = {"hex": None, "bin": None, "elf": None, "source": str(p)}
        img["named"] = {".ihex": "hex", ".axf": "elf"}.get(suffix, suffix[1:])
        img[img["named"]] = p
        for k in ("hex", "bin", "elf"):       # siblings of a build (fw.elf, fw.hex, fw.bin)
            if img[k] is None and p.with_suffix(f".{k}").is_file():
                img[k] = p.with_suffix(f".{k}")
        img["address"] = hex_load_address(img["hex"]) if img["hex"] else None
        return img
    from kinefuse.firmware.build import build_target
    subset = [f.strip() for f in args.filters.split(",") if f.strip()] if args.filters else None
    res = build_target(args.target, with_git=True, filters=subset)
    return {"hex": res.hex, "bin": res.bin, "elf": res.elf, "address": hex_load_address(res.hex),
            "board": TARGET_BOARDS[args.target], "target": args.target,
            "source": f"build {args.target}" + (f" ({','.join(subset)})" if subset else ""),
            "flash_bytes": res.size.flash, "ram_bytes": res.size.ram}


# ---------------------------------------------------------------------------------- command

def command_line(args, img: dict) -> list[str]:
    """The exact command to run for this image and these options."""
    address = _parse_address(args.address)
    if args.tool == "pyocd":
        if not args.mcu:
            raise KinefuseError("name the unit's MCU with --mcu (its pyOCD target type, e.g. stm32f411re; "
                                "`pyocd list --targets`)")
        if not re.fullmatch(r"[A-Za-z0-9_.\-]+", args.mcu):
            raise KinefuseError(f"bad --mcu {args.mcu!r}")
        cmd = ["pyocd", "flash", "--no-wait", "-t", args.mcu]
        if args.probe:
            cmd += ["-u", args.probe]
        if args.erase:
            cmd += ["-e", args.erase]
        kind = flashed_kind(img, "pyocd")
        if kind in ("hex", "elf"):
            if address is not None:   # it was ignored: the image went to its own addresses
                raise KinefuseError(f"--address goes with a .bin image: the .{kind} {img[kind]} holds its own "
                                    f"load addresses (flash the .bin to place it elsewhere)")
            return cmd + ["--format", kind, str(img[kind])]
        if address is None:
            address = img.get("address")
        if address is None:
            raise KinefuseError("a .bin image needs --address (where it goes in flash)")
        return cmd + ["--format", "bin", "-a", f"0x{address:08X}", str(img["bin"])]
    # dfu-util: a raw binary at an address
    if img["bin"] is None:
        raise KinefuseError("dfu-util flashes a raw .bin: give --image FILE.bin (or a build, which has one)")
    if address is None:
        address = img.get("address")
    if address is None:
        raise KinefuseError("dfu-util needs the load address: --address 0x08000000 (or a .hex next to the .bin)")
    alt = 0 if args.alt is None else args.alt
    if not 0 <= alt <= 255:
        raise KinefuseError("--alt must be 0..255")
    cmd = ["dfu-util", "-a", str(alt)]
    if args.dfu_device:
        if not re.fullmatch(r"[0-9a-fA-F]{4}:[0-9a-fA-F]{4}", args.dfu_device):
            raise KinefuseError(f"bad --dfu-device {args.dfu_device!r}: expected VID:PID such as 0483:df11")
        cmd += ["-d", args.dfu_device]
    if args.serial:
        cmd += ["-S", args.serial]
    return cmd + ["-s", f"0x{address:08X}:leave", "-D", str(img["bin"])]


def explain_failure(tool: str, output: str, code: int) -> str:
    """One line for a failed run of the flashing tool."""
    for pattern, text in KNOWN_ERRORS:
        m = re.search(pattern, output)
        if m:
            return text.format(*m.groups())
    lines = [ln.strip() for ln in output.splitlines() if ln.strip()]
    errs = [ln for ln in lines if re.search(r"\berror\b|\bfail", ln, re.I)]
    detail = (errs or lines or [f"exit status {code}"])[-1]
    detail = re.sub(r"^\d+\s+[EWC]\s+", "", detail)     # pyOCD's log prefix
    return f"{tool} failed: {detail[:200]}"


def run(args) -> int:
    from kinefuse.host.link.cli_util import console, print_json
    con = console(args.json)
    if args.timeout <= 0:
        raise KinefuseError("--timeout must be positive")
    if args.image and (args.target or args.filters):     # (they were ignored: the image was flashed)
        raise KinefuseError(f"{'--target' if args.target else '--filters'} chooses what to build; "
                            f"--image {args.image} is flashed as it is: give one or the other")
    args.target = args.target or "m4f"
    # the other tool's options were ignored
    other = ((("--alt", args.alt), ("--dfu-device", args.dfu_device), ("--serial", args.serial))
             if args.tool == "pyocd" else (("--probe", args.probe), ("--erase", args.erase)))
    unused = [o for o, v in other if v is not None]
    if unused:
        raise KinefuseError(f"{unused[0]} is a {'dfu-util' if args.tool == 'pyocd' else 'pyOCD'} option; "
                            f"this flashes with {args.tool} (--tool)")
    if args.tool == "pyocd" and not args.mcu:
        command_line(args, {"hex": None, "bin": None, "elf": None})   # the one-line error, before building
    if not args.image:      # before building: no board port matches any real MCU
        check_image_for_mcu(args, {"board": TARGET_BOARDS[args.target], "target": args.target})
    with con.status("building the application..." if not args.image else "checking the image..."):
        img = _image(args)
    cmd = command_line(args, img)
    check_image_for_mcu(args, img)
    result = {"tool": args.tool, "command": cmd, "image": img["source"], "file": cmd[-1]}
    for k in ("flash_bytes", "ram_bytes"):
        if k in img:
            result[k] = img[k]
    if args.dry_run:
        result["dry_run"] = True
        if args.json:
            print_json(result)
        else:
            con.print(" ".join(cmd), highlight=False, soft_wrap=True)
        return 0
    exe = shutil.which(cmd[0])
    if exe is None:
        raise KinefuseError(f"{cmd[0]} not found: {INSTALL[cmd[0]]}")
    try:
        with con.status(f"flashing with {args.tool}..."):
            proc = subprocess.run([exe] + cmd[1:], capture_output=True, text=True, timeout=args.timeout)
    except subprocess.TimeoutExpired:
        raise KinefuseError(f"{args.tool} did not finish within {args.timeout:g} s (probe or bootloader stuck?)") from None
    if proc.returncode != 0:
        raise KinefuseError(explain_failure(args.tool, (proc.stdout or "") + "\n" + (proc.stderr or ""),
                                            proc.returncode))
    result["flashed"] = True
    if args.json:
        print_json(result)
    else:
        con.print(f"flashed {result['file']} with {args.tool}")
    return 0
