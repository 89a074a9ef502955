"""Fixtures of the firmware application tests.

``inproc``: the application compiled with a test HAL (csrc/kf_hal_test.c) into a cffi module:
UART byte buffers, a clock the test sets, RAM storage with a write budget (power cut), a
sensor queue.  Fast and deterministic; the host program over a pty and QEMU are tested
separately.
"""
from __future__ import annotations

import hashlib
import importlib.util
import os
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
CSRC = HERE / "csrc"
INPROC_FILTERS = ("madgwick", "complementary", "flagship")

CDEF = """
typedef struct { uint32_t time_us; int16_t acc[3]; int16_t gyr[3]; int16_t mag[3]; uint8_t mag_valid; } kf_raw_sample;
uint32_t kft_app_size(void);
void kft_reset(uint32_t storage_size);
uint32_t kft_feed(const uint8_t *data, uint32_t len);
uint32_t kft_rx_left(void);
uint32_t kft_take(uint8_t *out, uint32_t max);
void kft_tx_limit(uint32_t bytes_per_call);
void kft_set_time(uint32_t us);
void kft_budget(int64_t bytes);
uint32_t kft_written(void);
uint8_t *kft_storage(void);
int kft_sensor_push(const kf_raw_sample *s);
int kft_sensor2_push(const kf_raw_sample *s);
int kft_reboots(void);
void kft_sensor_grant(int32_t hz);
void kft_set_battery_mv(uint16_t mv);
uint32_t kft_sensor_asked(void);
void kft_rejected(const void *app, uint32_t out[4]);
void kft_reset_filter2(void *app);
void kft_poison_filter(void *app, int sensor);
void kft_counters(const void *app, uint32_t out[12]);
uint32_t kft_param_count(void);
const char *kft_param_name(uint32_t i);
uint32_t kft_param_get(const void *app, uint32_t i);
uint8_t kft_param_type(uint32_t i);
void kft_output(const void *app, float q[4], int32_t q_raw[4]);
void kft_app_init(void *app);
int kft_app_poll(void *app);
"""
COUNTERS = ("crc_errors", "bad_frames", "unknown_ids", "unknown_messages", "param_rejects",
            "unsigned_refused", "signature_failures", "frames_ok", "frames_dropped", "samples",
            "storage_errors", "stored_rejects")


def build_inproc(system: str = "f32", filters=INPROC_FILTERS):
    """(ffi, lib) of the application + test HAL for number system ``system``."""
    from cffi import FFI
    from kinefuse.codegen.build import HOST_CFLAGS, cache_dir
    from kinefuse.firmware import build as fb
    srcs = fb.app_sources(system, board_main=False, filters=list(filters)) + [CSRC / "kf_hal_test.c"]
    defs = fb._defines(system, 65536, False, list(filters))
    flags = HOST_CFLAGS + ["-Wextra"] + [f"-D{k}={v}" for k, v in sorted(defs.items())]
    incs = [fb.APP_DIR, fb.GENERATED_DIR]
    h = hashlib.sha256(repr((CDEF, flags, sys.version, system)).encode())
    headers = [p for d in (fb.APP_DIR, fb.GENERATED_DIR) for p in sorted(d.glob("*.h"))]
    headers += sorted(fb.APP_DIR.glob("*.inc")) + sorted(CSRC.glob("*.h"))
    for p in srcs + headers:
        h.update(p.name.encode() + p.read_bytes())
    name = f"_kf_unit_inproc_{system}_{h.hexdigest()[:16]}"
    d = cache_dir()
    built = next(iter(d.glob(f"{name}*.so")), None)
    if built is None:
        import fcntl
        with open(d / f"{name}.lock", "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            built = next(iter(d.glob(f"{name}*.so")), None)
            if built is None:
                ffi = FFI()
                ffi.cdef(CDEF)
                ffi.set_source(name, '#include "kf_app.h"\n#include "kf_hal_test.h"\n',
                               sources=[str(s) for s in srcs], include_dirs=[str(i) for i in incs + [CSRC]],
                               extra_compile_args=flags + ["-isystem", str(fb.MAVLINK_DIR)])
                path = ffi.compile(tmpdir=str(d / f"build_{name}_{os.getpid()}"), verbose=False)
                built = d / Path(path).name
                os.replace(path, built)
    spec = importlib.util.spec_from_file_location(name, built)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod.ffi, mod.lib


class Unit:
    """One application instance on the test HAL."""

    def __init__(self, ffi, lib, storage_size: int = 4096, fresh: bool = True):
        from kinefuse.host.link.codec import Encoder
        from kinefuse.host.link.decoder import StreamDecoder
        self.ffi, self.lib = ffi, lib
        if fresh:
            lib.kft_reset(storage_size)
        self.mem = ffi.new("uint8_t[]", lib.kft_app_size() + 16)
        self.app = self.mem
        self.enc = Encoder(255, 190)
        self.dec = StreamDecoder(native=False)
        self.time_us = 0
        lib.kft_app_init(self.app)

    def reboot(self):
        """Power cycle: a new application instance on the same storage."""
        from kinefuse.host.link.decoder import StreamDecoder
        self.lib.kft_app_init(self.app)
        self.dec = StreamDecoder(native=False)

    def feed(self, data: bytes, polls: int = 8):
        left = data
        while left:
            n = self.lib.kft_feed(left, len(left))
            left = left[n:]
            self.poll(polls)
        self.poll(polls)

    def poll(self, n: int = 4):
        for _ in range(n):
            self.lib.kft_app_poll(self.app)
            while self.lib.kft_rx_left():
                self.lib.kft_app_poll(self.app)

    def advance(self, us: int):
        self.time_us = (self.time_us + us) & 0xFFFFFFFF
        self.lib.kft_set_time(self.time_us)

    def send(self, name, **fields):
        self.feed(self.enc.encode(name, **fields))

    def take(self) -> list:
        buf = self.ffi.new("uint8_t[]", 65536)
        out = []
        while True:
            n = self.lib.kft_take(buf, 65536)
            if n == 0:
                break
            out += self.dec.feed(bytes(self.ffi.buffer(buf, n)))
        return out

    def counters(self) -> dict:
        arr = self.ffi.new("uint32_t[12]")
        self.lib.kft_counters(self.app, arr)
        return dict(zip(COUNTERS, list(arr)))

    def param_index(self, name: str) -> int:
        for i in range(self.lib.kft_param_count()):
            if self.ffi.string(self.lib.kft_param_name(i)).decode() == name:
                return i
        raise KeyError(name)

    def param_raw(self, name: str) -> int:
        return self.lib.kft_param_get(self.app, self.param_index(name))

    def param(self, name: str):
        import struct
        i = self.param_index(name)
        raw = self.lib.kft_param_get(self.app, i)
        if self.lib.kft_param_type(i) == 9:
            return struct.unpack("<f", struct.pack("<I", raw))[0]
        return raw

    def set_param(self, name: str, value, ptype: int | None = None):
        from kinefuse.host.link.params import encode_value
        i = self.param_index(name)
        t = self.lib.kft_param_type(i) if ptype is None else ptype
        self.send("PARAM_SET", target_system=1, target_component=200, param_id=name,
                  param_value=encode_value(value, t) if t in (1, 2, 3, 4, 5, 6, 9) else float(value),
                  param_type=t)
        return self.take()

    def storage(self) -> bytes:
        return bytes(self.ffi.buffer(self.lib.kft_storage(), 8192))

    def restore_storage(self, image: bytes):
        self.ffi.memmove(self.lib.kft_storage(), image, len(image))


@pytest.fixture(scope="session")
def unit_type():
    """The Unit class for tests that make their own units (``from conftest import Unit`` found
    host/tests/conftest.py instead when both folders ran in one process)."""
    return Unit


@pytest.fixture(scope="session")
def inproc_builder():
    """build_inproc, for the same reason as unit_type."""
    return build_inproc


@pytest.fixture(scope="session")
def inproc_lib():
    return build_inproc("f32")


@pytest.fixture
def unit(inproc_lib):
    ffi, lib = inproc_lib
    return Unit(ffi, lib)
