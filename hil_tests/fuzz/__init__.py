"""Coverage-guided fuzzing of the unit application's parser, message and parameter handling.

``fuzz_app.c`` is the target (see its header for the input format and the invariants: every
parameter in range while running and after a power cut at any storage write, restored values
never invented); it links the real application sources (``firmware/app``, the generated
filters) with a RAM HAL.

* libFuzzer (clang, ``-fsanitize=fuzzer,address,undefined``), a bounded job (the test suite
  runs it for 30 s when clang is installed, as CI does; longer runs by hand)::

      python -m kinefuse.hil_tests.fuzz --seconds 600 [--jobs 2] [--corpus DIR]

  Needs ``clang`` and ``libclang-rt-14-dev`` (Debian 12).  Crashes are written to
  ``<work>/crash-*`` and reported with the command to replay them.
* replay build (gcc, ``-fsanitize=address,undefined``, ``-DKF_FUZZ_REPLAY``): runs a corpus
  once; the test suite uses it on a generated seed corpus (``hil_tests/tests/test_harness_fuzz.py``).
"""
from __future__ import annotations

import hashlib
import os
import random
import re
import shutil
import struct
import subprocess
from pathlib import Path

from kinefuse.host.errors import KinefuseError

HERE = Path(__file__).resolve().parent
TARGET = HERE / "fuzz_app.c"
SAN_FLAGS = ["-fsanitize=address,undefined", "-fno-sanitize-recover=all", "-fno-omit-frame-pointer"]
C_FLAGS = ["-std=c99", "-ffp-contract=off", "-fno-fast-math", "-g", "-O1"]


def cache_dir() -> Path:
    from kinefuse.firmware.targets import cache_dir as cd
    return cd("fuzz")


def _app_build_inputs(system: str = "f32", filters=None) -> tuple[list[Path], list[str], dict[str, str]]:
    from kinefuse.firmware import build as fb
    srcs = fb.app_sources(system, board_main=False, filters=filters)
    incs = ["-I", str(fb.APP_DIR), "-I", str(fb.GENERATED_DIR), "-isystem", str(fb.MAVLINK_DIR)]
    defs = fb._defines(system, 4096, False, filters)
    return srcs, incs, defs


def hashed_files(srcs: list[Path], incs: list[str]) -> list[Path]:
    """What a fuzz build depends on: the target, the sources and every header or ``.inc`` in
    the include directories (``-I``/``-isystem`` pairs; kf_params_gen.inc and the MAVLink
    headers included), so a change to any of them rebuilds."""
    files = [TARGET, *srcs]
    dirs = [Path(incs[i + 1]) for i in range(0, len(incs) - 1, 2) if incs[i] in ("-I", "-isystem")]
    for d in dirs + [TARGET.parent]:
        files += sorted(p for p in d.rglob("*") if p.suffix in (".h", ".inc") and p.is_file())
    return files


def build(kind: str = "replay", system: str = "f32", filters=None) -> Path:
    """Build the replay program (gcc + ASan/UBSan) or the libFuzzer binary (clang); cached by
    a hash of the sources and flags.  ``filters``: a subset of the wired filters (default all;
    fewer build faster).  Returns the executable."""
    srcs, incs, defs = _app_build_inputs(system, filters)
    if kind == "replay":
        cc = shutil.which("gcc")
        flags = C_FLAGS + SAN_FLAGS + ["-DKF_FUZZ_REPLAY"]
    elif kind == "libfuzzer":
        cc = shutil.which("clang")
        flags = C_FLAGS + ["-fsanitize=fuzzer,address,undefined", "-fno-sanitize-recover=undefined",
                           "-fno-omit-frame-pointer"]
    else:
        raise KinefuseError(f"unknown fuzz build {kind!r}")
    if cc is None:
        raise KinefuseError(f"{'gcc' if kind == 'replay' else 'clang'} not installed"
                            + ("" if kind == "replay" else " (apt-get install clang libclang-rt-14-dev)"))
    dflags = [f"-D{k}={v}" for k, v in sorted(defs.items())]
    h = hashlib.sha256()
    for p in hashed_files(srcs, incs):
        h.update(p.name.encode() + b"\0" + p.read_bytes())
    h.update(repr((cc, flags, dflags, system, filters)).encode())
    exe = cache_dir() / f"fuzz_app-{kind}-{system}-{h.hexdigest()[:16]}"
    if exe.is_file():
        return exe
    tmp = exe.with_name(exe.name + f".{os.getpid()}")
    cmd = [cc, *flags, *incs, *dflags, "-o", str(tmp), str(TARGET), *map(str, srcs), "-lm"]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        err = [ln for ln in proc.stderr.splitlines() if "error" in ln]
        raise KinefuseError("fuzz build failed: " + (err[0] if err else proc.stderr.strip()[-300:]))
    os.replace(tmp, exe)
    return exe


def param_names() -> list[str]:
    """Parameter names of the application (from its sources and generated tables)."""
    from kinefuse.firmware import build as fb
    names = set()
    for p in list(fb.APP_DIR.glob("*.c")) + list(fb.APP_DIR.glob("*.inc")):
        names.update(re.findall(r'"(KF_[A-Z0-9_]{1,13})"', p.read_text(errors="replace")))
    return sorted(names)


def seed_corpus(out: Path, n: int = 40, seed: int = 1) -> list[Path]:
    """Inputs made of real frames: PARAM_SETs with valid and invalid values (all types, NaN,
    huge, wrong type), reads, list requests, commands, HIL samples, and damage (truncation,
    flipped bits, stray magic bytes), each with a storage write budget."""
    from kinefuse.host.link.codec import Encoder
    rng = random.Random(seed)
    enc = Encoder(255, 190)
    names = param_names() or ["KF_FILTER", "KF_RATE_HZ", "KF_UNIT_ID"]
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    for i in range(n):
        frames = []
        for _ in range(rng.randint(1, 25)):
            kind = rng.random()
            if kind < 0.45:
                v = rng.choice([0.0, 1.0, 3.0, 5.0, 100.0, 1000.0, -1.0, 1e30, float("nan"), float("inf"),
                                rng.uniform(-1e4, 1e4), struct.unpack("<f", struct.pack("<I", rng.getrandbits(32)))[0]])
                frames.append(enc.encode("PARAM_SET", target_system=1, target_component=200,
                                         param_id=rng.choice(names), param_value=v,
                                         param_type=rng.choice([1, 3, 5, 6, 9, 0, 200])))
            elif kind < 0.55:
                frames.append(enc.encode("PARAM_REQUEST_READ", target_system=1, target_component=200,
                                         param_id=rng.choice(names), param_index=rng.choice([-1, 0, 5, 9999])))
            elif kind < 0.6:
                frames.append(enc.encode("PARAM_REQUEST_LIST", target_system=1, target_component=200))
            elif kind < 0.75:
                frames.append(enc.encode("COMMAND_LONG", target_system=1, target_component=200,
                                         command=rng.choice([52500, 52501, 52502, 511, 512, 246, 241, 9999]),
                                         param1=rng.choice([0.0, 1.0, 2.0, float("nan"), 1e9]),
                                         param2=rng.choice([0.0, 1.0, 52500.0, 1e6])))
            else:
                frames.append(enc.encode("HIL_SENSOR", time_usec=rng.getrandbits(40),
                                         xacc=rng.uniform(-200, 200), zacc=9.81, xgyro=rng.uniform(-40, 40),
                                         xmag=rng.uniform(-60, 60), fields_updated=rng.choice([0x3F, 0x1FF, 0])))
        data = bytearray(b"".join(frames))
        if i % 3 == 1 and data:
            for _ in range(rng.randint(1, 6)):
                p = rng.randrange(len(data) * 8)
                data[p // 8] ^= 1 << (p % 8)
        if i % 5 == 2:
            data = data[: rng.randrange(len(data) + 1)] + b"\xfd" + bytes(rng.getrandbits(8) for _ in range(20))
        budget = 0xFFFF if i % 4 == 0 else rng.randrange(0, 3000)
        p = out / f"seed-{i:03d}"
        p.write_bytes(struct.pack("<H", budget) + bytes(data))
        paths.append(p)
    return paths


def replay(paths, timeout: float = 300.0, filters=None) -> subprocess.CompletedProcess:
    paths = list(paths)
    exe = build("replay", filters=filters)
    env = dict(os.environ, ASAN_OPTIONS="detect_leaks=0:abort_on_error=1",
               UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1")
    try:
        return subprocess.run([str(exe), *map(str, paths)], capture_output=True, text=True,
                              timeout=timeout, env=env)
    except subprocess.TimeoutExpired:
        raise KinefuseError(f"fuzz replay of {len(paths)} inputs did not finish within "
                            f"{timeout:g} s (a hang in the application? replay fewer inputs "
                            "to find it)") from None


def fuzz(seconds: int, jobs: int = 1, corpus: Path | None = None, work: Path | None = None) -> int:
    """Run libFuzzer for ``seconds`` (wall); returns its exit status (0: no finding)."""
    exe = build("libfuzzer")
    work = work or cache_dir() / "work"
    work.mkdir(parents=True, exist_ok=True)
    corpus = corpus or work / "corpus"
    if not corpus.is_dir() or not any(corpus.iterdir()):
        seed_corpus(corpus)
    cmd = [str(exe), f"-max_total_time={seconds}", "-max_len=8192", "-timeout=10",
           "-rss_limit_mb=2048", f"-artifact_prefix={work}/", "-print_final_stats=1", str(corpus)]
    if jobs > 1:
        cmd[1:1] = [f"-jobs={jobs}", f"-workers={jobs}"]
    env = dict(os.environ, ASAN_OPTIONS="detect_leaks=0", UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1")
    print("running:", " ".join(cmd), flush=True)
    return subprocess.run(cmd, cwd=work, env=env).returncode
