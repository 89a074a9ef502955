"""The unit application as a host process (software in the loop), and what it should output.

    from kinefuse.firmware.hostunit import HostUnit
    with HostUnit() as unit:                      # builds firmware/ports/host once (cached)
        s = unit.session()                        # a kinefuse.host.link Session on its pty
        ...                                       # or: kinefuse record --port pty:<unit.device>

    out = hil_run(s, time_us, acc, gyr, mag_uT)   # HIL_SENSOR in, KF_RAW_SAMPLE + KF_ORIENTATION back
    ref = unit_model("madgwick", "f32", time_us, acc, gyr, mag_uT, rate_hz=1000)
    two = joint_hil_run(s, prox, dist)             # two-sensor unit: HIL_SENSOR id 1 + id 0 in, KF_JOINT_ANGLE back
    ref = joint_model("flagship", "q", prox, dist, rate_hz=100, joint_params={"sequence": 0})
    ref = joint_model(..., calib={"acc_b0": 0.1}, calib2={"acc_b0": -0.2})   # each sensor's own map
    two = joint_hil_run(s, prox, dist, efforts=True)   # ... with KF_EFF_RATE_HZ != 0: KF_EFFORTS too
    ref = leg_model(prox, dist, rate_hz=100, joint_params=..., leg_params=...)   # the leg EKF's outputs

:func:`unit_model` computes, with the generated Python models, exactly what the unit computes
for HIL input: the HIL_SENSOR float32 fields -> counts (``KF_HIL_MODE`` 0: as
``kinefuse.host.link.hil.raw_counts``, then the generated calibration map ``calib_apply``; the
gyro fields KF_RAW_SAMPLE echoes are ``raw_gyro_counts``, with ``gyro_shift``) or
direct float32 values (mode 1: gyr, acc as sent, mag ``float32(gauss) * 100f``), the time step
from ``time_usec`` differences (the first sample: the nominal period ``round(1e6 / KF_RATE_HZ)``),
then the filter; the q build reports ``float32(raw) * 2^-frac`` in KF_ORIENTATION and, with
``KF_HIL_MODE`` bit 1 (:data:`HIL_Q_RAW`), the raw Q quaternion itself in a MEMORY_VECT after
each one (``hil_run(..., q_raw=True)``).  Parameters are float32 on the
unit: the q build converts the float32 value (``kf_q_from_f32``).
:func:`synthetic_samples` recomputes the host port's synthetic sensor (kf_host_sensor.c).
"""
from __future__ import annotations

import math
import os
import select
import subprocess
import time
from pathlib import Path

import numpy as np

from kinefuse.host.errors import KinefuseError

MSG_RAW, MSG_ORI, MSG_JOINT, MSG_EFFORTS, MSG_STATUS = 52500, 52501, 52502, 52503, 52504
MSG_MEMORY_VECT = 249
#: KF_HIL_MODE bits (firmware/app/kf_params.h): 1 direct float32 input, 2 raw Q quaternion out
HIL_DIRECT, HIL_Q_RAW = 1, 2
#: the raw-Q MEMORY_VECT: ver, type (kf_params.h KF_QRAW_VER, KF_QRAW_TYPE_Q)
QRAW_VER, QRAW_TYPE_Q = 0x4B, 1
UNIT_COMPONENT = 200
FRAC_OUT_Q = None  # per filter: read from the model


class HostUnit:
    """``kinefuse-unit`` (firmware/ports/host) running on a fresh pseudo-terminal.

    Args: system ``"f32"`` / ``"q"``; filters: subset to build (default all wired);
    storage: file path (None: RAM, lost at exit); sensor: synthetic IMU on/off;
    max_samples: the sensor stops after that many; wait_connect: start only when the first
    byte arrives; sanitize: ASan/UBSan build; extra: more command-line arguments.
    """

    def __init__(self, system: str = "f32", *, filters=None, storage=None, sensor: bool = True,
                 max_samples: int | None = None, wait_connect: bool = False, sanitize: bool = False,
                 extra=(), exe: str | os.PathLike | None = None, start_timeout: float = 10.0):
        self.system, self.filters, self.storage = system, filters, storage
        self.sensor, self.max_samples, self.wait_connect = sensor, max_samples, wait_connect
        self.sanitize, self.extra, self.exe = sanitize, list(extra), exe
        self.start_timeout = start_timeout
        self.proc: subprocess.Popen | None = None
        self.device: str | None = None
        self._sessions = []
        self.stderr_text = ""

    def command(self) -> list[str]:
        if self.exe is None:
            from kinefuse.firmware.build import build_host
            self.exe = build_host(self.system, filters=self.filters, sanitize=self.sanitize).exe
        cmd = [str(self.exe), "--uart", "pty"]
        if self.storage is not None:
            cmd += ["--storage", str(self.storage)]
        if not self.sensor:
            cmd.append("--no-sensor")
        if self.max_samples is not None:
            cmd += ["--max-samples", str(int(self.max_samples))]
        if self.wait_connect:
            cmd.append("--wait-connect")
        return cmd + [str(a) for a in self.extra]

    def start(self) -> "HostUnit":
        cmd = self.command()
        env = dict(os.environ)
        if self.sanitize:
            env.setdefault("ASAN_OPTIONS", "detect_leaks=0:abort_on_error=1")
            env.setdefault("UBSAN_OPTIONS", "halt_on_error=1:print_stacktrace=1")
        self.proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                     stderr=subprocess.PIPE, env=env)
        deadline = time.monotonic() + self.start_timeout
        buf = b""
        while time.monotonic() < deadline and b"\n" not in buf:
            r, _, _ = select.select([self.proc.stderr], [], [], 0.1)
            if r:
                chunk = os.read(self.proc.stderr.fileno(), 4096)
                if not chunk:
                    break
                buf += chunk
        line = buf.split(b"\n", 1)[0].decode(errors="replace")
        if not line.startswith("uart "):
            self.stop()
            raise KinefuseError(f"kinefuse-unit did not start: {line or 'no output'}")
        self.device = line.split(" ", 1)[1].strip()
        return self

    def session(self, key: bytes | None = None):
        """A new :class:`~kinefuse.host.link.session.Session` on the unit's pty."""
        from kinefuse.host.link.connection import open_tty_raw
        from kinefuse.host.link.session import Session
        s = Session(open_tty_raw(self.device), key=key)
        self._sessions.append(s)
        return s

    def stop(self, timeout: float = 5.0) -> int | None:
        for s in self._sessions:
            try:
                s.close()
            except Exception:  # noqa: BLE001 - closing goes on
                pass
        self._sessions.clear()
        if self.proc is None:
            return None
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        try:
            self.stderr_text = self.proc.stderr.read().decode(errors="replace")
        except (OSError, ValueError):
            pass
        self.proc.stderr.close()
        return self.proc.returncode

    def __enter__(self) -> "HostUnit":
        return self.start()

    def __exit__(self, *exc) -> None:
        self.stop()


# --------------------------------------------------------------------------- synthetic sensor

def _sin_table() -> np.ndarray:
    return np.array([round(1000 * math.sin(2 * math.pi * i / 256)) for i in range(256)], dtype=np.int64)


def _c_div(a, b):
    """C integer division (truncation towards zero)."""
    a = np.asarray(a, dtype=np.int64)
    q = np.abs(a) // b
    return np.where(a < 0, -q, q)


def _noise(k: np.ndarray, axis: int) -> np.ndarray:
    m = np.uint64(0xFFFFFFFF)
    k = k.astype(np.uint64)
    x = ((k & m) * np.uint64(2654435761)) & m
    x ^= (k >> np.uint64(32)) & m
    x ^= np.uint64((axis * 0x9E3779B9) & 0xFFFFFFFF)
    x ^= x >> np.uint64(15)
    x = (x * np.uint64(0x2C1B3C6D)) & m
    x ^= x >> np.uint64(12)
    return (x % np.uint64(7)).astype(np.int64) - 3


BOOT_RATE_HZ = 1000   # KF_RATE_HZ's default: the host sensor's rate until --rate arrives


def _rate_change(got: dict, k: np.ndarray, rate_hz: int, search_s: float = 2.0) -> int:
    """The unit counter at which the host sensor restarted at ``rate_hz``: the last received
    sample (within ``search_s`` of 1 kHz samples) equal to the new rate's sample 0 in every
    field (sample 0 of both rates is the same, so a stream that starts at the new rate has
    one such sample, at 0); 0 when none is (the comparison then reports the samples wrong)."""
    first = synthetic_samples(1, rate_hz)
    hit = (k < int(search_s * BOOT_RATE_HZ))
    for key in ("acc", "gyr", "mag"):
        hit &= np.all(got[key] == first[key][0], axis=1)
    idx = np.flatnonzero(hit)
    return int(k[idx[-1]]) if len(idx) else 0


def synthetic_samples(n: int, rate_hz: int, k0: int = 0) -> dict[str, np.ndarray]:
    """Samples k0..k0+n-1 of the host port's synthetic IMU (counts in KF_RAW_SAMPLE units),
    with t_rel_us = k * 1e6 // rate (time since the sensor started)."""
    k = np.arange(k0, k0 + n, dtype=np.int64)
    t = (k * 1_000_000) // int(rate_hz)
    ph = (t * 32) // 1_000_000
    s = _sin_table()
    sat = lambda v: np.clip(v, -32768, 32767)  # noqa: E731
    acc = np.stack([sat(_noise(k, 0)), sat(_noise(k, 1)), sat(1000 + _noise(k, 2))], axis=1)
    gyr = np.stack([sat(_noise(k, 3)), sat(_noise(k, 4)), sat(785 + _noise(k, 5))], axis=1)
    mag = np.stack([sat(_c_div(190 * s[ph & 255], 1000) + _noise(k, 6)),
                    sat(_c_div(190 * s[(ph + 64) & 255], 1000) + _noise(k, 7)),
                    sat(-450 + _noise(k, 8))], axis=1)
    return {"k": k, "t_rel_us": t, "acc": acc, "gyr": gyr, "mag": mag, "mag_valid": (k % 10) == 0}


# ------------------------------------------------------------------------------ HIL helpers

def hil_frames(time_us, acc, gyr, mag_uT, mag_updated=None, seq0: int = 0, key: bytes | None = None) -> list[bytes]:
    """One HIL_SENSOR frame per sample (SI units; mag in uT, sent in gauss).  With ``key`` the
    frames are signed, with strictly increasing signing timestamps."""
    from kinefuse.host.link.hil import hil_sensor_frames
    frames = _split(hil_sensor_frames(time_us, acc, gyr, mag_uT, mag_updated=mag_updated, seq0=seq0))
    if key is None:
        return frames
    from kinefuse.host.link.codec import frame_from_payload, signing_timestamp
    from kinefuse.host.link.spec import kinefuse_dialect
    spec = kinefuse_dialect()["HIL_SENSOR"]
    ts = signing_timestamp()
    out = []
    for k, f in enumerate(frames):
        payload = f[10:10 + f[1]].ljust(spec.length, b"\0")
        out.append(frame_from_payload(spec, payload, f[5], f[6], f[4], key=key, timestamp=ts + k + 1))
    return out


def _split(data: bytes) -> list[bytes]:
    out, i = [], 0
    while i < len(data):
        n = 12 + data[i + 1] + (13 if data[i + 2] & 1 else 0)
        out.append(data[i:i + n])
        i += n
    return out


def _link_closed_is_an_error(fn):
    """The unit's pty / TCP link failing mid-run (the unit exited or crashed: EIO on a pty,
    a reset connection) is a one-line KinefuseError, not a bare ``OSError: [Errno 5]``."""
    import functools

    @functools.wraps(fn)
    def wrapper(session, *args, **kwargs):
        try:
            return fn(session, *args, **kwargs)
        except OSError as exc:
            raise KinefuseError(f"HIL: the link to the unit failed ({exc.strerror or exc}): "
                                "did the unit exit or crash? (its stderr tells)") from None
    return wrapper


@_link_closed_is_an_error
def hil_run(session, time_us, acc, gyr, mag_uT, mag_updated=None, window: int = 100,
            timeout: float = 10.0, key: bytes | None = None, q_raw: bool = False) -> dict[str, np.ndarray]:
    """Send one HIL_SENSOR per sample (``window`` at a time, waiting for every answer before
    the next window: nothing can overflow) and collect the unit's answers.

    Returns arrays per sample: ``raw`` (acc, gyr, mag counts, flags), ``q`` (N, 4) float32 from
    KF_ORIENTATION (NaN where none came), ``cov``, ``counter`` (sample_counter echoed),
    ``status``, ``time_us`` echoed; with ``q_raw`` (a q build with ``KF_HIL_MODE`` bit 1 set)
    also ``q_raw`` (N, 4) int64, the raw Q quaternion of the MEMORY_VECT after each
    KF_ORIENTATION.  Raises KinefuseError when an answer is missing after ``timeout``."""
    frames = hil_frames(time_us, acc, gyr, mag_uT, mag_updated, key=key)
    n = len(frames)
    q = np.full((n, 4), np.nan, np.float32)
    cov = np.zeros((n, 6), np.float32)
    counters = np.full(n, -1, np.int64)
    t_echo = np.zeros(n, np.int64)
    status = np.zeros(n, np.int64)
    raw = np.zeros((n, 9), np.int64)
    flags = np.zeros(n, np.int64)
    shifts = np.zeros(n, np.int64)
    qr = np.zeros((n, 4), np.int64)
    first_counter = None
    got_raw = got_ori = 0
    got_qr = n if not q_raw else 0
    # answers counted once per sample: a repeated frame must not stand in for a missing one
    seen_raw, seen_ori, seen_qr = np.zeros(n, bool), np.zeros(n, bool), np.zeros(n, bool)
    last_ori = None                            # (index, sample_counter) of the newest KF_ORIENTATION
    session.poll(0)
    session.drain()                            # older frames (a sensor stream) are not answers
    for start in range(0, n, window):
        stop = min(n, start + window)
        session.send_bytes(b"".join(frames[start:stop]))
        deadline = time.monotonic() + timeout
        while got_ori < stop or got_raw < stop or got_qr < stop:
            if time.monotonic() > deadline:
                raise KinefuseError(f"HIL: {stop - min(got_raw, got_ori, got_qr)} answers missing after {timeout} s "
                                    f"(samples {start}..{stop - 1})")
            session.poll(0.05)
            for _, f in session.drain():
                if f.msgid == MSG_MEMORY_VECT and q_raw:
                    m = f.msg
                    if last_ori is None or m.ver != QRAW_VER or m.type != QRAW_TYPE_Q:
                        continue
                    # address: the low 16 bits of the sample counter (it follows its KF_ORIENTATION)
                    i = last_ori[0] - ((last_ori[1] - m.address) & 0xFFFF)
                    if 0 <= i < n:
                        qr[i] = np.frombuffer(bytes(b & 0xFF for b in m.value[:16]), "<i4")
                        got_qr += not seen_qr[i]
                        seen_qr[i] = True
                    continue
                if f.msgid not in (MSG_RAW, MSG_ORI):
                    continue
                m = f.msg
                if first_counter is None:
                    if f.msgid != MSG_RAW or not m.flags & 64:   # the first SIMULATED sample
                        continue
                    first_counter = m.sample_counter
                i = (m.sample_counter - first_counter) & 0xFFFFFFFF
                if i >= n:
                    continue
                if f.msgid == MSG_RAW:
                    raw[i] = [m.acc_x, m.acc_y, m.acc_z, m.gyro_x, m.gyro_y, m.gyro_z, m.mag_x, m.mag_y, m.mag_z]
                    shifts[i] = getattr(m, "gyro_shift", 0)   # extension field: 0 when absent
                    flags[i] = m.flags
                    counters[i] = m.sample_counter
                    t_echo[i] = m.time_boot_us
                    got_raw += not seen_raw[i]
                    seen_raw[i] = True
                else:
                    q[i] = np.array([m.q_w, m.q_x, m.q_y, m.q_z], np.float32)
                    cov[i] = np.asarray(m.cov, np.float32)
                    status[i] = m.status
                    got_ori += not seen_ori[i]
                    seen_ori[i] = True
                    last_ori = (i, m.sample_counter)
    out = {"q": q, "cov": cov, "counter": counters, "time_us": t_echo, "status": status,
           "acc": raw[:, 0:3], "gyr": raw[:, 3:6], "mag": raw[:, 6:9], "flags": flags,
           "gyro_shift": shifts}
    if q_raw:
        out["q_raw"] = qr
    return out


# ---------------------------------------------------------------------------------- model

def _f32(x) -> np.ndarray:
    return np.asarray(x, np.float64).astype(np.float32)


def time_steps_us(time_us, rate_hz: int) -> np.ndarray:
    """dt in whole us as the unit takes it: differences clamped to [0, 1e6], first = nominal."""
    t = np.asarray(time_us, np.int64)
    dt = np.empty(len(t), np.int64)
    dt[0] = (1_000_000 + rate_hz // 2) // rate_hz
    dt[1:] = np.clip(np.diff(t), 0, 1_000_000)
    return dt


def unit_model(name: str, system: str, time_us, acc, gyr, mag_uT, mag_updated=None, *,
               rate_hz: int = 1000, mode: int = 0, params: dict | None = None,
               calib: dict | None = None, mag_enable: bool = True) -> dict[str, np.ndarray]:
    """What the unit outputs for HIL input (see the module docstring), from the generated
    models: ``q`` (N, 4) float32 as in KF_ORIENTATION, ``q_raw`` (q build: the raw Q values),
    ``counts`` (N, 9) as echoed in KF_RAW_SAMPLE, ``rejected``."""
    from kinefuse.codegen.runner import runner
    from kinefuse.host.link.hil import UT_PER_GAUSS, raw_counts, raw_gyro_counts
    n = len(time_us)
    acc32, gyr32 = _f32(acc).reshape(n, 3), _f32(gyr).reshape(n, 3)
    gauss32 = _f32(np.asarray(mag_uT, np.float64).reshape(n, 3) / UT_PER_GAUSS)
    upd = np.ones(n, bool) if mag_updated is None else np.asarray(mag_updated, bool)
    a, g, m, _, _ = raw_counts(acc32.astype(np.float64), gyr32.astype(np.float64),
                               gauss32.astype(np.float64) * UT_PER_GAUSS)
    # KF_RAW_SAMPLE's gyro fields: units of 2^gyro_shift mrad/s; the calibration map (int16
    # input) takes g, the 1 mrad/s counts saturated
    g_sent, shift, _ = raw_gyro_counts(gyr32.astype(np.float64))
    counts = np.concatenate([a, g_sent, m], axis=1).astype(np.int64)
    if mode == 0:
        out = counts_model(name, system, time_us, a, g, m, upd, rate_hz=rate_hz, params=params,
                           calib=calib, mag_enable=mag_enable)
        out["counts"] = counts
        out["gyro_shift"] = shift.astype(np.int64)
        return out
    dt_us = time_steps_us(time_us, rate_hz)
    fi = runner(name, f"{system}-model")
    mag32 = (gauss32 * np.float32(100.0)).astype(np.float32)
    dt32 = (dt_us.astype(np.float32) * np.float32(1e-6)).astype(np.float32)
    host = {"gyr": gyr32.astype(np.float64), "acc": acc32.astype(np.float64),
            "mag": mag32.astype(np.float64), "dt": dt32.astype(np.float64),
            "mag_valid": upd & bool(mag_enable)}
    inputs = {k: fi.encode_values("input", k, t, host[k].reshape(n, -1)) for k, _, t in fi.fields["input"]}
    out = _filter_model(name, system, inputs, n, params)
    out["inputs"] = inputs
    out["counts"] = counts
    out["gyro_shift"] = shift.astype(np.int64)
    return out


def counts_model(name: str, system: str, time_us, acc_counts, gyr_counts, mag_counts, mag_valid, *,
                 rate_hz: int = 1000, params: dict | None = None, calib: dict | None = None,
                 mag_enable: bool = True) -> dict[str, np.ndarray]:
    """What the unit outputs for samples given as counts (the sensor path, and HIL mode 0):
    the generated calibration map, then the filter (models, float32 parameter values)."""
    from kinefuse.codegen import estimators
    from kinefuse.codegen.runner import runner
    n = len(time_us)
    dt_us = time_steps_us(time_us, rate_hz)
    ci = runner("calib_apply", f"{system}-model")
    e = ci.encode({"acc_raw": np.asarray(acc_counts, float).reshape(n, 3),
                   "gyr_raw": np.asarray(gyr_counts, float).reshape(n, 3),
                   "mag_raw": np.asarray(mag_counts, float).reshape(n, 3),
                   "dt_us": dt_us.astype(float)}, _p32(estimators.get("calib_apply"), calib))
    co = ci.run_encoded(e)
    inputs = {"gyr": co["gyr"], "acc": co["acc"], "mag": co["mag"], "dt": co["dt"],
              "mag_valid": (np.asarray(mag_valid, bool) & bool(mag_enable)).reshape(n, 1)}
    out = _filter_model(name, system, inputs, n, params)
    out["inputs"] = inputs          # the filter input record (encoded: float32 or raw Q values)
    return out


def _p32(est, values) -> dict:
    """The unit's parameter values: float32."""
    prm = est.resolve_params(values)
    return {k: float(np.float32(v)) for k, v in prm.items()}


def _filter_model(name: str, system: str, inputs: dict, n: int, params) -> dict:
    from kinefuse.codegen import estimators
    from kinefuse.codegen.runner import Encoded, runner
    fr = runner(name, f"{system}-model")
    fp = _p32(estimators.get(name), params)
    enc_p = {k: fr.encode_values("param", k, t, [fp[k]])[0] for k, _, t in fr.fields["param"]}
    enc_in = {k: np.asarray(inputs[k]).reshape(n, -1) for k, _, _ in fr.fields["input"]}
    out = fr.run_encoded(Encoded(enc_in, enc_p, n))
    res = {"rejected": out.get("rejected"), "q_raw": None}
    for key, field in (("q", "q"), ("cov", "cov_att")):
        if field not in out:
            continue
        if system == "f32":
            res[key] = out[field].astype(np.float32)
        else:
            raw = out[field].astype(np.int64)
            res[key] = (raw.astype(np.float32) * np.float32(2.0 ** -fr.formats[f"output.{field}"][0])).astype(np.float32)
            if key == "q":
                res["q_raw"] = raw
    if "cov" not in res:                       # no covariance output: KF_ORIENTATION.cov all zero
        res["cov"] = np.zeros((n, 6), np.float32)
    return res


def joint_model(name: str, system: str, prox: dict, dist: dict, *, rate_hz: int = 1000, mode: int = 0,
                params: dict | None = None, joint_params: dict | None = None, calib: dict | None = None,
                calib2: dict | None = None, mag_enable: bool = True) -> dict[str, np.ndarray]:
    """What a two-sensor unit (``KF_JOINT_ID`` != 0) sends in KF_JOINT_ANGLE for HIL input:
    ``prox`` (HIL_SENSOR id 0) and ``dist`` (id 1) are dicts of ``t``, ``acc``, ``gyr``, ``mag``
    (µT) and optional ``upd``, one sample each per joint output, sensor 1's sample sent before
    sensor 0's.  Each sensor runs through :func:`unit_model` (its own filter instance and time
    steps, its own calibration map: ``calib`` = sensor 0's ``calib_apply`` values, KF_ACC/GYR/MAG_*;
    ``calib2`` = sensor 1's, KF_ACC2/GYR2/MAG2_*; None: the defaults); the joint step (generated ``joint_angle`` model, float32
    parameters) takes the two quaternions: f32 as float32, q the raw filter outputs requantised
    to the step's input format (round half up).  Returns ``angles`` (N, 3) float32 as sent
    (q: ``float32(raw) * 2^-frac``), ``valid``, ``rejected``, both sensors' ``q`` and the input
    records their filters were fed (``in_prox``, ``in_dist``: calibrated ``gyr``/``acc``/``mag``/
    ``dt`` as the model encodes them, float32 or raw Q values)."""
    from kinefuse.codegen import estimators
    from kinefuse.codegen.runner import Encoded, runner
    res = {}
    for key, d, cal in (("prox", prox, calib), ("dist", dist, calib2)):
        res[key] = unit_model(name, system, d["t"], d["acc"], d["gyr"], d["mag"], d.get("upd"), rate_hz=rate_hz,
                              mode=mode, params=params, calib=cal, mag_enable=mag_enable)
    n = len(prox["t"])
    jr = runner("joint_angle", f"{system}-model")
    jp = _p32(estimators.get("joint-angle"), joint_params)
    enc_p = {k: jr.encode_values("param", k, t, [jp[k]])[0] for k, _, t in jr.fields["param"]}
    inputs = {}
    for key in ("prox", "dist"):
        if system == "f32":
            inputs[f"q_{key}"] = res[key]["q"].astype(np.float32)
        else:
            fr = runner(name, "q-model")
            shift = fr.formats["output.q"][0] - jr.formats[f"input.q_{key}"][0]
            raw = res[key]["q_raw"].astype(np.int64)
            inputs[f"q_{key}"] = (raw + (1 << (shift - 1))) >> shift if shift > 0 else raw << -shift
    out = jr.run_encoded(Encoded(inputs, enc_p, n))
    if system == "f32":
        angles = out["angles"].astype(np.float32)
    else:
        frac = jr.formats["output.angles"][0]
        angles = (out["angles"].astype(np.int64).astype(np.float32) * np.float32(2.0 ** -frac)).astype(np.float32)
    return {"angles": angles, "valid": out["valid"][:, 0], "rejected": out["rejected"][:, 0],
            "q_prox": res["prox"]["q"], "q_dist": res["dist"]["q"],
            "in_prox": res["prox"]["inputs"], "in_dist": res["dist"]["inputs"]}


@_link_closed_is_an_error
def joint_hil_run(session, prox: dict, dist: dict, window: int = 50, timeout: float = 10.0,
                  efforts: bool = False, dist_sent=None) -> dict:
    """Two-sensor HIL: per sample k, HIL_SENSOR id 1 (``dist``) then id 0 (``prox``); collects
    KF_JOINT_ANGLE (angles float32, status, sample_counter, joint_id, sequence, units) and the
    KF_ORIENTATION of sensor 0, indexed by sample.  ``efforts``: also wait for one KF_EFFORTS per
    sample (the leg EKF on: ``effort``/``effort_std`` (N, 12) float32, ``eff_status``,
    ``eff_meta`` = model_id, count).  ``dist_sent`` (bool per sample): send sensor 1's sample k
    only where True (default: all)."""
    from kinefuse.host.link.hil import hil_sensor_frames
    n = len(prox["t"])
    sent = np.ones(n, bool) if dist_sent is None else np.asarray(dist_sent, bool)
    f0 = _split(hil_sensor_frames(prox["t"], prox["acc"], prox["gyr"], prox["mag"], mag_updated=prox.get("upd"),
                                  sensor_id=0))
    f1 = _split(hil_sensor_frames(dist["t"], dist["acc"], dist["gyr"], dist["mag"], mag_updated=dist.get("upd"),
                                  sensor_id=1))
    angles = np.full((n, 3), np.nan, np.float32)
    q = np.full((n, 4), np.nan, np.float32)
    status = np.zeros(n, np.int64)
    meta = np.zeros((n, 4), np.int64)       # joint_id, sequence, proximal_unit, distal_unit
    time_echo = np.zeros(n, np.int64)
    effort = np.full((n, 12), np.nan, np.float32)
    effort_std = np.full((n, 12), np.nan, np.float32)
    eff_status = np.zeros(n, np.int64)
    eff_meta = np.zeros((n, 2), np.int64)   # model_id, count
    eff_time = np.zeros(n, np.int64)
    first = None
    got = got_eff = 0
    session.poll(0)
    session.drain()
    for start in range(0, n, window):
        stop = min(n, start + window)
        session.send_bytes(b"".join((f1[k] if sent[k] else b"") + f0[k] for k in range(start, stop)))
        deadline = time.monotonic() + timeout
        while got < stop or (efforts and got_eff < stop):
            if time.monotonic() > deadline:
                what = "KF_JOINT_ANGLE" if got < stop else "KF_EFFORTS"
                raise KinefuseError(f"two-sensor HIL: {stop - min(got, got_eff if efforts else got)} {what} "
                                    f"missing after {timeout} s")
            session.poll(0.05)
            for _, f in session.drain():
                if f.msgid not in (MSG_RAW, MSG_ORI, MSG_JOINT, MSG_EFFORTS):
                    continue
                m = f.msg
                if first is None:
                    if f.msgid != MSG_RAW or not m.flags & 64:
                        continue
                    first = m.sample_counter
                i = (m.sample_counter - first) & 0xFFFFFFFF
                if i >= n:
                    continue
                if f.msgid == MSG_JOINT:
                    angles[i] = np.array([m.angle_1, m.angle_2, m.angle_3], np.float32)
                    status[i] = m.status
                    meta[i] = [m.joint_id, m.sequence, m.proximal_unit, m.distal_unit]
                    time_echo[i] = m.time_boot_us
                    got += 1
                elif f.msgid == MSG_ORI:
                    q[i] = np.array([m.q_w, m.q_x, m.q_y, m.q_z], np.float32)
                elif f.msgid == MSG_EFFORTS:
                    effort[i] = np.asarray(m.effort, np.float32)
                    effort_std[i] = np.asarray(m.effort_std, np.float32)
                    eff_status[i] = m.status
                    eff_meta[i] = [m.model_id, m.count]
                    eff_time[i] = m.time_boot_us
                    got_eff += 1
    out = {"angles": angles, "status": status, "meta": meta, "time_us": time_echo, "q": q}
    if efforts:
        out.update(effort=effort, effort_std=effort_std, eff_status=eff_status, eff_meta=eff_meta,
                   eff_time_us=eff_time)
    return out


# ----------------------------------------------------------------------------- leg EKF model

EFF_VALID, EFF_SENSOR_MISSING, EFF_UPDATE_SKIPPED, EFF_RESET = 1, 2, 4, 8   # KF_EFFORTS_STATUS
ACC_CLIPPED, GYRO_CLIPPED = 1, 2                                           # KF_RAW_SAMPLE_FLAGS


def calibrated_f32(time_us, acc, gyr, mag_uT, *, rate_hz: int = 1000, mode: int = 0,
                   calib: dict | None = None) -> dict[str, np.ndarray]:
    """A float32 unit's filter input record for HIL samples of one sensor: ``gyr``, ``acc``
    (N, 3) float32 (``KF_HIL_MODE`` 0: counts, then the generated calibration map; 1: the
    float32 values sent), ``dt`` (N,) float32 s (from the ``time_usec`` steps, first nominal)
    and the clipping ``flags`` (N,) the unit derives (KF_RAW_SAMPLE_FLAGS ACC/GYRO/MAG_CLIPPED)."""
    from kinefuse.codegen import estimators
    from kinefuse.codegen.runner import runner
    from kinefuse.host.link.hil import UT_PER_GAUSS, raw_counts, raw_sample_counts
    n = len(time_us)
    acc32, gyr32 = _f32(acc).reshape(n, 3), _f32(gyr).reshape(n, 3)
    gauss32 = _f32(np.asarray(mag_uT, np.float64).reshape(n, 3) / UT_PER_GAUSS)
    # mode 0: the flags of the filter input, the gyro clipped where the 1 mrad/s counts of the
    # calibration map's int16 input saturate (KF_RAW_SAMPLE may still carry it with gyro_shift)
    a, g, m, _, flags = raw_counts(acc32.astype(np.float64), gyr32.astype(np.float64),
                                   gauss32.astype(np.float64) * UT_PER_GAUSS)
    dt_us = time_steps_us(time_us, rate_hz)
    if mode == 1:
        # direct float32 input: GYRO_CLIPPED only beyond the largest gyro_shift (as sent)
        flags = raw_sample_counts(acc32.astype(np.float64), gyr32.astype(np.float64),
                                  gauss32.astype(np.float64) * UT_PER_GAUSS)[4]
        dt32 = (dt_us.astype(np.float32) * np.float32(1e-6)).astype(np.float32)
        return {"gyr": gyr32, "acc": acc32, "dt": dt32, "flags": flags}
    ci = runner("calib_apply", "f32-model")
    e = ci.encode({"acc_raw": a.astype(float), "gyr_raw": g.astype(float), "mag_raw": m.astype(float),
                   "dt_us": dt_us.astype(float)}, _p32(estimators.get("calib_apply"), calib))
    co = ci.run_encoded(e)
    return {"gyr": co["gyr"].astype(np.float32), "acc": co["acc"].astype(np.float32),
            "dt": co["dt"][:, 0].astype(np.float32), "flags": flags}


def leg_axes(q_sb) -> np.ndarray:
    """The unit's rows (gyr, acc along, acc anterior) x (sensor x, y, z), float32, for one
    sensor-to-segment offset q_SB (w, x, y, z; KF_JA_PROX_* / KF_JA_DIST_* as float32): every
    operation of kf_leg.c axes_of in the same order."""
    f = np.float32
    w, x, y, z = (f(v) for v in q_sb)
    n2 = ((w * w + x * x) + y * y) + z * z
    if not n2 >= f(1e-12):
        w, x, y, z = f(1.0), f(0.0), f(0.0), f(0.0)
    else:
        k = f(1.0) / np.sqrt(n2)
        w, x, y, z = w * k, x * k, y * k, z * k
    one, two = f(1.0), f(2.0)
    r00, r01, r02 = one - two * (y * y + z * z), two * (x * y - w * z), two * (x * z + w * y)
    r10, r11, r12 = two * (x * y + w * z), one - two * (x * x + z * z), two * (y * z - w * x)
    r20, r21, r22 = two * (x * z - w * y), two * (y * z + w * x), one - two * (x * x + y * y)
    return np.array([[-r00, -r10, -r20], [-r01, -r11, -r21], [r02, r12, r22]], np.float32)


def _dot_rows(row, v) -> np.ndarray:
    """(a0*v0 + a1*v1) + a2*v2 in float32 per sample (v: (N, 3) float32)."""
    return (row[0] * v[:, 0] + row[1] * v[:, 1]) + row[2] * v[:, 2]


def leg_model(prox: dict, dist: dict, *, rate_hz: int = 1000, mode: int = 0, leg_params: dict | None = None,
              joint_params: dict | None = None, calib: dict | None = None, calib2: dict | None = None,
              dist_sent=None) -> dict[str, np.ndarray]:
    """What a float32 two-sensor unit with the leg EKF on (``KF_JOINT_ID`` != 0, ``KF_EFF_RATE_HZ``
    != 0) sends in KF_EFFORTS for HIL input as :func:`joint_hil_run` sends it (``prox`` = thigh,
    HIL_SENSOR id 0; ``dist`` = shank, id 1, sent where ``dist_sent``): both sensors' calibrated
    samples (:func:`calibrated_f32`; ``calib`` sensor 0's map, ``calib2`` sensor 1's), mapped into the leg EKF's segment-frame inputs with the
    KF_JA_* offsets (:func:`leg_axes`; a sensor without a new sample, or with its clipping flag,
    is lost for the step), dt of sensor 0, then the generated leg model (``leg_f32``, float32
    parameters).  Returns ``effort``/``effort_std`` (N, 2) float32 (hip, knee), ``status``
    (KF_EFFORTS_STATUS bits of each sample's message), the leg inputs (``inputs``) and outputs
    (``out``)."""
    from kinefuse.codegen import estimators
    from kinefuse.codegen.runner import Encoded, runner
    n = len(prox["t"])
    sent = np.ones(n, bool) if dist_sent is None else np.asarray(dist_sent, bool)
    c0 = calibrated_f32(prox["t"], prox["acc"], prox["gyr"], prox["mag"], rate_hz=rate_hz, mode=mode, calib=calib)
    idx = np.flatnonzero(sent)
    c1s = calibrated_f32(np.asarray(dist["t"])[idx], np.asarray(dist["acc"])[idx], np.asarray(dist["gyr"])[idx],
                         np.asarray(dist["mag"])[idx], rate_hz=rate_hz, mode=mode, calib=calib2)
    c1 = {k: np.zeros((n,) + v.shape[1:], v.dtype) for k, v in c1s.items()}
    for k, v in c1s.items():
        c1[k][idx] = v
    jp = _p32(estimators.get("joint-angle"), joint_params)
    gyr = np.zeros((n, 2), np.float32)
    acc = np.zeros((n, 4), np.float32)
    g_ok = np.zeros((n, 2), bool)
    a_ok = np.zeros((n, 2), bool)
    for k, (c, fresh, side) in enumerate(((c0, np.ones(n, bool), "prox"), (c1, sent, "dist"))):
        ax = leg_axes([jp[f"{side}_{ch}"] for ch in "wxyz"])
        g_ok[:, k] = fresh & ((c["flags"] & GYRO_CLIPPED) == 0)
        a_ok[:, k] = fresh & ((c["flags"] & ACC_CLIPPED) == 0)
        gyr[:, k] = np.where(g_ok[:, k], _dot_rows(ax[0], c["gyr"]), np.float32(0.0))
        acc[:, 2 * k] = np.where(a_ok[:, k], _dot_rows(ax[1], c["acc"]), np.float32(0.0))
        acc[:, 2 * k + 1] = np.where(a_ok[:, k], _dot_rows(ax[2], c["acc"]), np.float32(0.0))
    lr = runner("leg", "f32-model")
    lp = _p32(estimators.get("leg"), leg_params)
    enc_p = {k: lr.encode_values("param", k, t, [lp[k]])[0] for k, _, t in lr.fields["param"]}
    inputs = {"gyr": gyr, "acc": acc, "foot": np.zeros((n, 2), np.float32), "gyr_valid": g_ok,
              "acc_valid": a_ok, "foot_valid": np.zeros((n, 1), bool), "dt": c0["dt"].reshape(n, 1)}
    out = lr.run_encoded(Encoded(inputs, enc_p, n))
    rejected = out["rejected"][:, 0].astype(np.int64)
    rej_step = np.diff(np.concatenate([[0], rejected])) != 0
    missing = ~(g_ok.all(1) & a_ok.all(1)) | out["imu_lost"][:, 0].astype(bool) | rej_step
    status = (EFF_VALID * out["initialised"][:, 0].astype(np.int64) + EFF_SENSOR_MISSING * missing
              + EFF_UPDATE_SKIPPED * out["skipped_now"][:, 0].astype(np.int64)
              + EFF_RESET * out["reset_now"][:, 0].astype(np.int64))
    return {"effort": out["te"].astype(np.float32), "effort_std": out["te_std"].astype(np.float32),
            "status": status, "inputs": inputs, "out": out}


# ------------------------------------------------------------------------ end-to-end stream

def stream_check(seconds: float, rate_hz: int = 1000, out_dir=None, system: str = "f32",
                 filters=None, record_margin_s: float = 2.0) -> dict:
    """The unit's host build streams ``seconds`` x ``rate_hz`` samples of its synthetic sensor
    over a pty; ``kinefuse record`` records them into a .kfr; the file is decoded and every
    KF_RAW_SAMPLE compared with what the sensor produced (recomputed here).

    Returns a summary: samples expected/received, lost, duplicated, wrong (any field differs),
    timing errors, the unit's own drop counters, recorder CRC errors, bytes and rates."""
    import tempfile
    from kinefuse.host.cli import main as cli_main
    from kinefuse.host.link.frames import decode_file
    n = int(round(seconds * rate_hz))
    tmp = tempfile.TemporaryDirectory(prefix="kf-stream-") if out_dir is None else None
    out = Path(tmp.name if tmp else out_dir) / f"stream_{rate_hz}hz_{n}.kfr"
    try:
        with HostUnit(system, filters=filters, max_samples=n, wait_connect=True) as unit:
            t0 = time.monotonic()
            args = ["record", "--port", f"pty:{unit.device}", "--out", str(out), "--force",
                    "--duration", f"{seconds + record_margin_s:g}", "--start", "--json"]
            if rate_hz != 1000:
                args += ["--rate", str(rate_hz)]
            import contextlib
            import io
            buf = io.StringIO()
            with contextlib.redirect_stdout(buf):
                code = cli_main(args)
            wall = time.monotonic() - t0
            if code != 0:
                raise KinefuseError(f"kinefuse record failed with status {code}")
        df = decode_file(out)
        st = df.streams[0]
        raw = st.arrays.get(MSG_RAW)
        status = st.arrays.get(MSG_STATUS)
        got = 0 if raw is None else len(raw)
        res = {"samples_expected": n, "samples_received": got, "rate_hz": rate_hz,
               "seconds": seconds, "file": str(out), "file_bytes": out.stat().st_size,
               "rx_bytes": st.rx_bytes, "crc_errors": st.counters.crc_errors,
               "bytes_skipped": st.counters.bytes_skipped, "wall_s": round(wall, 3)}
        if raw is None:
            res.update(lost=n, duplicates=0, wrong=0, timing_errors=0, ok=False)
            return res
        ctr = raw["sample_counter"].astype(np.int64)
        uniq, counts = np.unique(ctr, return_counts=True)
        res["duplicates"] = int((counts > 1).sum())
        expected = np.arange(n)
        res["lost"] = int(len(np.setdiff1d(expected, uniq)))
        res["unexpected"] = int(len(np.setdiff1d(uniq, expected)))
        order = np.argsort(ctr, kind="stable")
        r = raw[order][: n]
        k = r["sample_counter"].astype(np.int64)
        ok_idx = k < n
        k = k[ok_idx]
        r = r[ok_idx]
        fields = {"acc": ("acc_x", "acc_y", "acc_z"), "gyr": ("gyro_x", "gyro_y", "gyro_z"),
                  "mag": ("mag_x", "mag_y", "mag_z")}
        got = {key: np.stack([r[c].astype(np.int64) for c in cols], axis=1) for key, cols in fields.items()}
        got["mag_valid"] = (r["flags"] & 8) != 0
        # the unit streams from boot at its 1 kHz; --rate reaches it a few samples later and the
        # host sensor restarts its index and time base there, while the counter runs on: the
        # samples before the change are checked against the 1 kHz sensor, those after against
        # the new rate's from index 0 (every field of every sample is compared either way)
        c = _rate_change(got, k, rate_hz) if rate_hz != BOOT_RATE_HZ else 0
        res["samples_before_rate_change"] = c
        wrong = np.zeros(len(k), bool)
        timing = 0
        t = r["time_boot_us"].astype(np.int64)
        for sel, ref, idx in ((k < c, synthetic_samples(c, BOOT_RATE_HZ), k),
                              (k >= c, synthetic_samples(n, rate_hz), k - c)):
            if not np.any(sel):
                continue
            i = idx[sel]
            for key in fields:
                wrong[sel] |= np.any(got[key][sel] != ref[key][i], axis=1)
            wrong[sel] |= got["mag_valid"][sel] != ref["mag_valid"][i]
            ts = t[sel]
            timing += int(np.sum((ts - ts[0]) != (ref["t_rel_us"][i] - ref["t_rel_us"][i[0]])))
        res["wrong"] = int(wrong.sum())
        res["timing_errors"] = timing
        if status is not None and len(status):
            last = status[-1]
            res["unit_frames_dropped"] = int(last["frames_dropped"])
            res["unit_samples_dropped"] = int(last["samples_dropped"])
            res["unit_crc_errors"] = int(last["crc_errors"])
        t_new = t[k >= c]     # the rate asked for: after the change
        if len(t_new) > 1:
            res["achieved_rate_hz"] = round((len(t_new) - 1) / ((t_new[-1] - t_new[0]) * 1e-6), 3)
        res["ok"] = (res["lost"] == 0 and res["duplicates"] == 0 and res["wrong"] == 0
                     and res["unexpected"] == 0 and res["timing_errors"] == 0 and res["crc_errors"] == 0
                     and res.get("unit_frames_dropped", 0) == 0 and res.get("unit_samples_dropped", 0) == 0)
        return res
    finally:
        if tmp is not None:
            tmp.cleanup()
