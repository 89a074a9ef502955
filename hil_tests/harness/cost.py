"""Cost of one filter update on Cortex-M4F and M0: exact instructions, estimated cycles, size.

Measured exactly like the competitors (:mod:`kinefuse.hil_tests.qemu.competitors`): the same
synthetic motion (100 Hz, rotations up to ~150 °/s, gravity and an Earth-like field, noise;
:func:`~kinefuse.hil_tests.qemu.competitors.motion`), ``WARMUP`` updates in the setup, then
``K`` counted updates on the following samples; the same flags (``-O2`` counted, ``-Os`` and
``-O2`` sizes), the same cost driver and the same size baseline (the input table is kept
referenced in the baseline program so only the filter's code and state count).

* instructions per update: ``(count(K) − count(0)) / K`` under QEMU's counting plugin, exact;
  includes callees (libm/libgcc soft-float on M0) and the driver loop (≈3 instructions).
* cycles: an *estimate* from the executed instruction mix (QEMU single-step trace over
  ``K_MIX`` updates, mnemonics from the disassembly) with the Cortex-M4 table: integer and FP
  data processing 1, loads/stores 2 (LDM/STM/PUSH/POP 1 + registers), VDIV/VSQRT 14, VFMA 3,
  integer divide 7, taken branches 3 (pipeline refill), other branches 1.  Not a measurement.
  µs at ``CLOCK_HZ`` = 64 MHz, zero wait states.
* flash = text + data, RAM = data + bss (static state; no stack) that the filter adds.
"""
from __future__ import annotations

import bisect
import os
import re
import subprocess
import tempfile
from collections import Counter
from pathlib import Path

import numpy as np

from kinefuse.codegen import estimators
from kinefuse.codegen.estimator import generated_stem
from kinefuse.codegen.generate import GENERATED_DIR
from kinefuse.codegen.runner import ModelInfo
from kinefuse.host.errors import KinefuseError

CLOCK_HZ = 64_000_000
K_MIX = 50                 # updates traced for the instruction mix


def _kind(name: str) -> str:
    """'imu' or 'angle' (the seed-004 joint-angle smoothers); others cannot be costed here."""
    kind = estimators.get(name).inputs.name
    if kind not in ("imu", "angle"):
        raise KinefuseError(f"cost measurement needs an IMU filter or a joint-angle smoother; "
                            f"{name} takes {kind}")
    return kind


SENSORS = ("9d", "6d")     # IMU motion with a magnetometer reading in every sample, or none


def _table_names(name: str, system: str, sensors: str = "9d") -> tuple[str, str]:
    """(file stem, array name) of the input table: IMU motion or a joint-angle series."""
    if sensors not in SENSORS:
        raise KinefuseError(f"sensors must be one of {', '.join(SENSORS)}, not {sensors!r}")
    if _kind(name) == "imu":
        six = "6d_" if sensors == "6d" else ""
        return f"kf_cost_{six}{system}", f"kf_cost_in_{six}{system}"
    if sensors != "9d":
        raise KinefuseError(f"{name} takes a joint-angle series: it has no 6D measurement")
    return f"kf_cost_angle_{system}", f"kf_cost_angle_in_{system}"


def _table_sources(name: str, system: str, sensors: str = "9d") -> tuple[Path, Path, str, int]:
    """Input records of the competitors' motion as a C table; returns (c, dir, ctype, n).
    ``sensors`` "6d": the same motion with no magnetometer reading (mag_valid 0 in every sample,
    as x-io Fusion's FusionAhrsUpdateNoMagnetometer and VQF's 6D case get it).
    The joint-angle smoothers get the same number of samples of the seed-004 servo protocol
    (20° sine at 5 rad/s, 35 Hz, 1.8° noise, 23 ms latency: ``kinefuse bench seed004``)."""
    from kinefuse.hil_tests.qemu.batch import write_generated
    from kinefuse.hil_tests.qemu.competitors import N_SAMPLES, RATE_HZ, motion

    est = estimators.get(name)
    kind = _kind(name)
    n = N_SAMPLES
    if kind == "imu":
        m = motion()
        inputs = {"gyr": m["gyr"].astype(float), "acc": m["acc"].astype(float),
                  "mag": m["mag"].astype(float), "mag_valid": np.full(n, sensors == "9d"),
                  "dt": np.full(n, 1.0 / RATE_HZ)}
    else:
        from kinefuse.host.bench.seed004 import long_series
        inputs = long_series(n)
    info = ModelInfo(name, system)
    enc = info.encode(inputs, est.resolve_params(None))
    ctype = f"kf_{kind}_input_{system}"
    tag, arr = _table_names(name, system, sensors)
    guard = tag.upper() + "_H"

    def lit(v, typ):
        if typ == "bool":
            return "1u" if v else "0u"
        if system == "q" or typ == "int":
            return str(int(v))
        return float.hex(float(v)) + "f"

    rows = []
    for i in range(n):
        parts = []
        for fname, size, typ in info.fields["input"]:
            vals = enc.inputs[fname][i]
            if size == 1:
                parts.append(lit(vals[0], typ))
            else:
                parts.append("{" + ", ".join(lit(x, typ) for x in vals) + "}")
        rows.append("{" + ", ".join(parts) + "}")
    header = (f'#ifndef {guard}\n#define {guard}\n'
              f'#include "kf_{kind}_{system}.h"\n#define KF_COST_N {n}u\n#define KF_WARMUP 400u\n'
              f"extern const {ctype} {arr}[KF_COST_N];\n#endif\n")
    body = (f'#include "{tag}.h"\nconst {ctype} {arr}[KF_COST_N] = {{\n'
            + ",\n".join(rows) + "\n};\n")
    hpath = write_generated(header, f"{tag}.h")
    cpath = write_generated(body, f"{tag}.c")
    sibling = cpath.parent / hpath.name
    if not sibling.is_file() or sibling.read_text() != header:
        tmp = sibling.with_name(f".{hpath.name}.{os.getpid()}")
        tmp.write_text(header)
        os.replace(tmp, sibling)
    return cpath, hpath.parent, ctype, n


def _snippets(name: str, system: str, sensors: str = "9d"):
    P = generated_stem(name, system)
    tag, arr = _table_names(name, system, sensors)
    # RAM counted: the state (which keeps its own copy of the parameters) and the output; the
    # parameters handed to init are a local, as x-io Fusion's settings are in its measurement
    prelude = (f'#include "{P}.h"\n#include "{tag}.h"\n'
               f"static {P}_state kf_st;\nstatic {P}_output kf_out;\n"
               "static volatile uintptr_t kf_keep_sink;\n")
    setup = (f"{P}_params kf_p;\n{P}_default_params(&kf_p);\n"
             f"if ({P}_init(&kf_st, &kf_p) != 0) {{ return 5; }}\n"
             f"for (uint32_t w = 0u; w < KF_WARMUP; ++w) {{ {P}_update(&kf_st, &{arr}[w], &kf_out); }}")
    call = f"{P}_update(&kf_st, &{arr}[KF_WARMUP + kf_i], &kf_out);"
    finish = "kf_keep_sink = (uintptr_t)&kf_out;"
    baseline = f"kf_keep_sink = (uintptr_t)&{arr}[0];"
    return prelude, setup, call, finish, baseline


def measure_filter(name: str, system: str, target: str, *, k: int = 1000,
                   size_opts=("-Os", "-O2"), mix: bool = True, sensors: str = "9d") -> dict:
    """Instructions per update (exact), cycle estimate, flash/RAM added (bytes)."""
    from kinefuse.hil_tests.qemu.cost import measure_call_cost

    src = GENERATED_DIR / f"{generated_stem(name, system)}.c"
    if not src.is_file():
        raise KinefuseError(f"{src} does not exist")
    table_c, table_dir, _ctype, n = _table_sources(name, system, sensors)
    if k > n - 400:
        raise KinefuseError(f"k must be at most {n - 400}")
    prelude, setup, call, finish, baseline = _snippets(name, system, sensors)
    cost = measure_call_cost([src, table_c], setup, call, target, k=k, prelude=prelude,
                             finish=finish, baseline_code=baseline,
                             include_dirs=[GENERATED_DIR, table_dir], size_opts=size_opts)
    row = {"impl": "kinefuse", "filter": name, "format": system, "target": target,
           "sensors": sensors if _kind(name) == "imu" else None,
           "instructions_per_update": cost.per_call, "k": k, "warmup": 400,
           "flash_bytes": cost.size["-Os"].flash if "-Os" in cost.size else None,
           "ram_bytes": cost.size["-Os"].ram if "-Os" in cost.size else None,
           "size": {o: s.as_dict() for o, s in cost.size.items()}}
    if mix:
        row.update(cycle_estimate(cost.build, target, K_MIX))
    return row


# ---- instruction mix and cycle estimate -------------------------------------------------------

_LINE = re.compile(r"^\s*([0-9a-f]+):\s+(\S.*)$")


def _disassembly(elf: Path) -> tuple[list[int], list[str], dict[int, int]]:
    from kinefuse.firmware.targets import tool
    out = subprocess.run([tool("objdump"), "-d", "--no-show-raw-insn", str(elf)],
                         capture_output=True, text=True, check=True).stdout
    addrs, mnems = [], []
    for line in out.splitlines():
        m = _LINE.match(line)
        if m:
            text = m.group(2).split(";")[0].strip()
            if not text or text.startswith("."):
                continue
            addrs.append(int(m.group(1), 16))
            mnems.append(text)
    order = sorted(range(len(addrs)), key=addrs.__getitem__)
    addrs = [addrs[i] for i in order]
    mnems = [mnems[i] for i in order]
    return addrs, mnems, {a: i for i, a in enumerate(addrs)}


def _trace_pcs(elf: Path, target: str, k: int, timeout: float = 600.0) -> Counter:
    from kinefuse.hil_tests.qemu.runner import run_elf
    with tempfile.TemporaryDirectory(prefix="kf-mix-") as tmp:
        log = Path(tmp) / "exec.log"
        res = run_elf(elf, target, args=[f"{k:010d}"], timeout=timeout,
                      extra_args=["-singlestep", "-d", "exec,nochain", "-D", str(log)])
        res.check("instruction-mix trace")
        pcs = Counter()
        pat = re.compile(rb"Trace \d+: 0x[0-9a-f]+ \[[0-9a-f]+/([0-9a-f]+)/")
        if log.is_file():
            with open(log, "rb") as f:
                for line in f:
                    m = pat.search(line)
                    if m:
                        pcs[int(m.group(1), 16)] += 1
    if not pcs:     # a program that ran executed instructions: an empty trace is a broken trace
        raise KinefuseError(f"instruction-mix trace: QEMU wrote no execution trace for {Path(elf).name} "
                            "(does this qemu-system-arm support -d exec,nochain?)")
    return pcs


def classify(mnemonic: str, taken: float) -> float:
    """Estimated Cortex-M4 cycles of one executed instruction (see the module docstring)."""
    op = mnemonic.split()[0].lower()
    base = op.split(".")[0]
    if base in ("vdiv", "vsqrt"):
        return 14.0
    if base in ("vfma", "vfms", "vfnma", "vfnms", "vmla", "vmls"):
        return 3.0
    if base in ("sdiv", "udiv"):
        return 7.0
    if base in ("vldr", "vstr") or re.match(r"^(ldr|str|ldrex|strex)", base):
        return 2.0
    if re.match(r"^(ldm|stm|push|pop|vpush|vpop|vldm|vstm)", base):
        regs = mnemonic[mnemonic.find("{") + 1:mnemonic.find("}")] if "{" in mnemonic else ""
        nreg = 0
        for part in regs.split(","):
            part = part.strip()
            if "-" in part:
                a, b = part.split("-")
                nreg += int(re.sub(r"\D", "", b)) - int(re.sub(r"\D", "", a)) + 1
            elif part:
                nreg += 1
        return 1.0 + max(nreg, 1) + (2.0 if "pc" in regs else 0.0)
    if re.match(r"^(b|bl|blx|bx|cbz|cbnz)(eq|ne|cs|cc|mi|pl|vs|vc|hi|ls|ge|lt|gt|le|hs|lo|al)?(\.[nw])?$", op) \
            or base in ("b", "bl", "blx", "bx", "cbz", "cbnz"):
        return 1.0 + 2.0 * taken
    return 1.0


def per_update_trace(elf: Path, target: str, k: int) -> Counter:
    """Executed count of every instruction address over k updates (trace of k minus trace of 0)."""
    with_k = _trace_pcs(elf, target, k)
    without = _trace_pcs(elf, target, 0)
    per = Counter()
    for pc, c in with_k.items():
        d = c - without.get(pc, 0)
        if d:
            per[pc] = d
    return per


def cycle_estimate(build, target: str, k: int = K_MIX, per: Counter | None = None) -> dict:
    """Estimated cycles per update from a single-step trace of K and 0 calls."""
    if k <= 0:
        raise KinefuseError("cycle estimate: k must be positive")
    if per is None:
        per = per_update_trace(build.elf, target, k)
    if not per:
        raise KinefuseError(f"cycle estimate: the traces of {k} and of 0 updates are identical "
                            "(the counted updates did not run?)")
    addrs, mnems, index = _disassembly(build.elf)
    cycles = 0.0
    classes = Counter()
    unknown = 0
    for pc, c in per.items():
        i = index.get(pc)
        if i is None:
            j = bisect.bisect_right(addrs, pc) - 1
            unknown += c
            if j < 0:
                continue
            i = j
        mn = mnems[i]
        # taken fraction: how often the next executed instruction was not the next address
        nxt = addrs[i + 1] if i + 1 < len(addrs) else None
        fall = per.get(nxt, 0) if nxt is not None else 0
        taken = 1.0 - min(1.0, fall / c) if c else 0.0
        cyc = classify(mn, taken)
        cycles += c * cyc
        classes[_class(mn)] += c
    total = sum(per.values())
    cpu = cycles / k
    return {"traced_instructions_per_update": total / k,
            "est_cycles_per_update": cpu,
            "est_us_at_64mhz": cpu / CLOCK_HZ * 1e6,
            "mix_per_update": {c: v / k for c, v in sorted(classes.items())},
            "cycle_model": "Cortex-M4 table estimate (not measured)"}


# ---- profile: where the instructions of one update go ------------------------------------------

_REF_COMMENT = re.compile(r"/\* ([\w.-]+\.py:\d+)")


def _function_symbols(elf: Path) -> list[tuple[int, str]]:
    from kinefuse.firmware.targets import tool
    out = subprocess.run([tool("nm"), "-n", str(elf)], capture_output=True, text=True,
                         check=True).stdout
    syms = []
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[1] in "tTwW":
            syms.append((int(parts[0], 16) & ~1, parts[2].split(".")[0]))   # foo.constprop.0 -> foo
    return syms


def _outer_lines(elf: Path, pcs: list[int]) -> list[tuple[str, int] | None]:
    """(file, line) of the outermost caller of each address (through inlining), None if unknown."""
    from kinefuse.firmware.targets import tool
    out = subprocess.run([tool("addr2line"), "-i", "-a", "-e", str(elf)] + [hex(p) for p in pcs],
                         capture_output=True, text=True, check=True).stdout.splitlines()
    res: dict[int, tuple[str, int] | None] = {}
    cur = None
    for line in out:
        if line.startswith("0x"):
            cur = int(line, 16)
            res[cur] = None
            continue
        path, _, num = line.rpartition(":")
        num = num.split()[0] if num else ""
        if cur is not None and path != "??" and num.isdigit():
            res[cur] = (path, int(num))          # later lines are outer callers
    return [res.get(p) for p in pcs]


def profile(elf: Path, per: Counter, k: int, top: int = 12) -> dict:
    """Instructions per update by function (after inlining: libgcc, libm and the runtime helpers
    GCC kept out of line) and by reference-source line (the ``/* file.py:N */`` comment of the
    generated C statement the instruction belongs to, through inlining)."""
    syms = _function_symbols(elf)
    starts = [a for a, _ in syms]
    entry = {a: n for a, n in syms}
    fn_of: dict[int, str] = {}
    by_fn: Counter = Counter()
    calls: Counter = Counter()
    for pc, c in per.items():
        j = bisect.bisect_right(starts, pc) - 1
        fn_of[pc] = syms[j][1] if j >= 0 else "?"
        by_fn[fn_of[pc]] += c
        if pc in entry:
            calls[entry[pc]] += c
    pcs = sorted(per)
    gen_dir = GENERATED_DIR.resolve()
    texts: dict[str, list[str] | None] = {}     # generated C sources by path (None: not one)
    by_ref: Counter = Counter()
    for pc, loc in zip(pcs, _outer_lines(elf, pcs)):
        key = f"in {fn_of[pc]} (out of line)"
        if loc is not None:
            path, num = loc
            if path not in texts:
                texts[path] = None
                if path.endswith(".c") and Path(path).parent.resolve() == gen_dir:
                    try:
                        texts[path] = Path(path).read_text().splitlines()
                    except OSError:
                        texts[path] = []
            src = texts[path]
            if src is not None:
                m = _REF_COMMENT.search(src[num - 1]) if 0 < num <= len(src) else None
                key = m.group(1) if m else f"{Path(path).name}: generated glue (no reference line)"
        by_ref[key] += per[pc]
    total = sum(per.values())
    fns = [{"name": n, "instructions_per_update": c / k, "calls_per_update": calls.get(n, 0) / k}
           for n, c in by_fn.most_common(top)]
    if len(by_fn) > top:   # the rest in one entry, so every list adds up to the total
        rest = sum(c for _, c in by_fn.most_common()[top:])
        fns.append({"name": f"({len(by_fn) - top} other functions)",
                    "instructions_per_update": rest / k, "calls_per_update": None})
    refs = [{"where": w, "instructions_per_update": c / k} for w, c in by_ref.most_common(top)]
    if len(by_ref) > top:
        rest = sum(c for _, c in by_ref.most_common()[top:])
        refs.append({"where": f"({len(by_ref) - top} other lines)", "instructions_per_update": rest / k})
    return {"functions": fns, "reference_lines": refs,
            "traced_instructions_per_update": total / k, "traced_updates": k}


def _class(mn: str) -> str:
    base = mn.split()[0].lower().split(".")[0]
    if base in ("vdiv", "vsqrt"):
        return "fp_div_sqrt"
    if base.startswith("v") and base not in ("vldr", "vstr", "vpush", "vpop", "vldm", "vstm", "vmov", "vmrs", "vmsr"):
        return "fp_arith"
    if base in ("vldr", "vstr", "vpush", "vpop", "vldm", "vstm") or re.match(r"^(ldr|str|ldm|stm|push|pop)", base):
        return "load_store"
    if re.match(r"^(b|bl|blx|bx|cbz|cbnz)([a-z]{2})?$", base):
        return "branch"
    if base in ("mul", "mla", "mls", "smull", "umull", "smlal", "umlal", "muls"):
        return "int_mul"
    return "other"
