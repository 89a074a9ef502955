"""A small simulated kinefuse unit speaking the dialect (for tests, demos and the host tools).

It is NOT the firmware: it streams KF_RAW_SAMPLE (a unit rotating about a tilted axis, with
noise), KF_ORIENTATION (gyro strapdown integration), KF_UNIT_STATUS and HEARTBEAT, answers
TIMESYNC, the parameter protocol and COMMAND_LONG (MAV_CMD_KF_STREAM, SET_MESSAGE_INTERVAL,
REQUEST_MESSAGE, reboot, heading tare, filter reset), and can drift its clock, drop samples,
corrupt bytes, have a sensor that grants another rate than KF_RATE_HZ asks, a sensor that
stalls once (KF_UNIT_STATUS_FLAGS_SENSOR_FAULT, as the firmware) and a parameter storage that
fails (KF_UNIT_STATUS_FLAGS_STORAGE_ERROR and a STATUSTEXT, as the firmware) on purpose.

    pair = create_pty_pair()
    unit = FakeUnit(open_tty_raw(pair.device_path), unit_id=3, rate_hz=500).start()
    ... host reads pair.host ...
    unit.stop()
"""
from __future__ import annotations

import math
import threading
import time

import numpy as np

from kinefuse.host.link.codec import Encoder
from kinefuse.host.link.connection import Connection, ConnectionClosed
from kinefuse.host.link.decoder import StreamDecoder
from kinefuse.host.link.dialect import RAW_SCALE, STANDARD_GRAVITY, UNIT_COMPONENT_ID, DIALECT_HASH
from kinefuse.host.link.params import decode_value, encode_value

MSG_RAW, MSG_ORI, MSG_STATUS = 52500, 52501, 52504
CMD_STREAM, CMD_TARE, CMD_RESET = 52500, 52501, 52502
CMD_SET_INTERVAL, CMD_REQUEST_MESSAGE, CMD_REBOOT = 511, 512, 246
FIRMWARE_VERSION = (0 << 24) | (1 << 16) | (0 << 8) | 0  # 0.1.0 DEV
SEVERITY_ERROR = 3
STORAGE_TEXT = "parameter storage error: settings may be lost"     # the firmware's (kf_status.c)

# name -> (MAV_PARAM_TYPE, default, min, max)
DEFAULT_PARAMS = {
    "KF_UNIT_ID": (1, 1, 1, 254),
    "KF_RATE_HZ": (3, 1000, 1, 2000),
    "KF_ORI_RATE_HZ": (3, 100, 0, 1000),
    "KF_FILTER": (1, 1, 0, 7),
    "KF_MAG_ENABLE": (1, 1, 0, 1),
    "KF_ACC_TAU_S": (9, 3.0, 0.01, 100.0),
    "KF_SERIAL_NO": (5, 0x4B460001, 0, 0xFFFFFFFF),
    "KF_BATT_LOW_MV": (3, 3400, 0, 5000),
}


def divider(rate_hz: int, hz: int) -> int:
    """Every how many samples a stream at ``hz`` goes out at sensor rate ``rate_hz`` (0: off),
    as the firmware computes it (kf_config.c): rounded half up, at least 1 (Python's round()
    rounds half to even: 250 Hz / 100 Hz gave 2 here and 3 on the unit)."""
    if hz <= 0 or rate_hz <= 0:
        return 0
    return max(1, (int(rate_hz) + int(hz) // 2) // int(hz))


def interval_rate(interval_us: float):
    """MAV_CMD_SET_MESSAGE_INTERVAL interval (us) -> whole Hz as the firmware computes it
    (kf_handle.c: float32, rounded half up); None when the unit answers DENIED."""
    if math.isnan(interval_us) or 0 < interval_us < 100:
        return None                       # NaN, faster than 10 kHz
    rate = int(np.float32(1e6) / np.float32(interval_us) + np.float32(0.5))
    return None if rate == 0 else rate    # slower than 0.5 Hz (or inf) is not "off"


def _quat_mul(a, b):
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return np.array([w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                     w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2])


def _rotate_to_sensor(q, v):
    """Earth-frame vector -> sensor frame for q (sensor -> earth): conj(q) * v * q."""
    w, x, y, z = q
    r = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                  [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                  [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
    return r.T @ v


class FakeUnit:
    def __init__(self, conn: Connection, unit_id: int = 1, rate_hz: float = 1000.0, orientation_rate_hz: float = 100.0,
                 drift_ppm: float = 0.0, boot_offset_us: int = 0, streaming: bool = True, drop_every: int = 0,
                 corrupt_probability: float = 0.0, seed: int = 0, answer_params: bool = True,
                 param_list_loss_every: int = 0, sensor_grant_hz: int = 0, storage_error: bool = False,
                 sensor_gap: tuple | None = None):
        """``sensor_grant_hz``: the rate the sensor delivers whatever KF_RATE_HZ asks (0: the rate
        asked; the firmware test HAL's kft_sensor_grant); ``storage_error``: every load (boot) and
        save (parameter change) of the parameter storage fails; ``sensor_gap`` (N, MS): once,
        after N samples since boot, the sensor delivers nothing for MS ms (the host build's
        ``--sensor-gap N:MS``; here while streaming): a silence of 4 periods and at least
        100 ms is KF_UNIT_STATUS_FLAGS_SENSOR_FAULT in every status whose interval had it."""
        self.conn = conn
        self.params = {k: v[1] for k, v in DEFAULT_PARAMS.items()}
        self.params["KF_UNIT_ID"] = unit_id
        self.params["KF_RATE_HZ"] = int(rate_hz)
        self.params["KF_ORI_RATE_HZ"] = int(orientation_rate_hz)
        self.drift = drift_ppm * 1e-6
        self.boot_offset_us = boot_offset_us
        self.streaming = streaming
        self.drop_every = drop_every
        self.corrupt_probability = corrupt_probability
        self.answer_params = answer_params
        self.param_list_loss_every = param_list_loss_every  # drop every k-th PARAM_VALUE of a list
        self.sensor_grant_hz = int(sensor_grant_hz)
        self.storage_error = storage_error
        self.sensor_gap = None if sensor_gap is None else (int(sensor_gap[0]), int(sensor_gap[1]))
        self.gap = None         # (first device us without samples, first us with them again): once
        self.status_prev_us = None   # device time of the previous periodic status
        self.rng = np.random.default_rng(seed)
        self.enc = Encoder(sysid=unit_id, compid=UNIT_COMPONENT_ID)
        self.dec = StreamDecoder()
        self.counters = {"param_rejects": 0, "unknown_messages": 0, "frames_dropped": 0, "hil_invalid": 0}
        self.sent_samples = 0
        self.commands: list = []  # (command, params) received, for tests
        self._stop = threading.Event()
        self._thread = None
        self._reset_state()

    # ------------------------------------------------------------------------------ clock
    def _reset_state(self):
        self.t0_ns = time.monotonic_ns()
        self.sample_counter = 0
        self.cnt_ori = 0        # samples since the last KF_ORIENTATION (the firmware's cnt_ori)
        self.samples_taken = 0  # KF_UNIT_STATUS.samples: since boot (MAV_CMD_KF_STREAM p2 resets only the counter)
        self.next_sample_us = 0
        self.next_status_us = 0
        self.q = np.array([1.0, 0.0, 0.0, 0.0])
        self.bias = np.array([0.01, -0.02, 0.005])
        self.tared = False
        self.hil = False  # True after the first HIL_SENSOR: samples come from the host
        self.mag_present = False  # a magnetometer reading since boot (KF_UNIT_STATUS_FLAGS_MAG_PRESENT)
        # failed loads and saves of the parameter storage since boot (at boot: the load), and
        # their number at the last periodic status and at the last STATUSTEXT (kf_status.c)
        self.store_errors = int(self.storage_error)
        self.store_errors_status = self.store_errors_told = 0
        self._apply_rate()      # the sensor configured at boot (kf_app_init)

    def _apply_rate(self) -> bool:
        """The sensor configured for KF_RATE_HZ (kf_config_apply_rates): a rate it grants
        instead becomes KF_RATE_HZ; False (KF_RATE_HZ left as asked) when that rate is outside
        KF_RATE_HZ's range."""
        g = self.sensor_grant_hz
        if not g:
            return True
        lo, hi = DEFAULT_PARAMS["KF_RATE_HZ"][2:]
        if not lo <= g <= hi:
            return False
        self.params["KF_RATE_HZ"] = g
        return True

    def _save(self) -> None:
        """A parameter change is stored (kf_config_save); a failure is counted."""
        if self.storage_error:
            self.store_errors += 1

    def statustext(self, severity: int, text: str) -> bytes:
        """A STATUSTEXT frame (MAV_SEVERITY ``severity``), as kf_send_statustext sends it."""
        return self.enc.encode("STATUSTEXT", severity=severity, text=text, id=0, chunk_seq=0)

    def _status_tick(self, now_us: int) -> list:
        """The periodic status (kf_status_tick): HEARTBEAT, KF_UNIT_STATUS (STORAGE_ERROR: a
        storage failure since the previous one) and, after a failure since the last one told,
        STATUSTEXT ERROR "parameter storage error: settings may be lost"."""
        out = [self._heartbeat(), self._status(now_us)]
        self.status_prev_us = now_us
        self.store_errors_status = self.store_errors
        if self.store_errors != self.store_errors_told:
            self.store_errors_told = self.store_errors
            out.append(self.statustext(SEVERITY_ERROR, STORAGE_TEXT))
        return out

    def device_time_us(self) -> int:
        """Unit clock: us since boot, running (1 + drift) times as fast as the host clock."""
        return int((time.monotonic_ns() - self.t0_ns) * (1.0 + self.drift) / 1000) + self.boot_offset_us

    # ------------------------------------------------------------------------------ thread
    def start(self) -> "FakeUnit":
        self._thread = threading.Thread(target=self._run, name="kf-fake-unit", daemon=True)
        self._thread.start()
        return self

    def stop(self, close: bool = True) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join(2.0)
        if close:
            self.conn.close()

    def _run(self) -> None:
        try:
            while not self._stop.is_set():
                data = self.conn.read(0.002)
                out = []
                if data:
                    for f in self.dec.feed(data):
                        out += self._handle(f)
                out += self._emit_due()
                if out:
                    self._send(b"".join(out))
        except (ConnectionClosed, OSError):
            pass

    def _send(self, data: bytes) -> None:
        if self.corrupt_probability > 0:
            arr = bytearray(data)
            flips = self.rng.random(len(arr) * 8) < self.corrupt_probability
            for bit in np.flatnonzero(flips):
                arr[bit // 8] ^= 1 << (bit % 8)
            data = bytes(arr)
        self.conn.write(data)

    # ------------------------------------------------------------------------------ streams
    @property
    def period_us(self) -> float:
        return 1e6 / max(1, self.params["KF_RATE_HZ"])

    def _emit_due(self) -> list:
        now = self.device_time_us()
        out = []
        if now >= self.next_status_us:
            out += self._status_tick(now)
            self.next_status_us = now - now % 1_000_000 + 1_000_000
        if not self.streaming or self.hil:
            self.next_sample_us = max(self.next_sample_us, now)
            return out
        ori_every = divider(self.params["KF_RATE_HZ"], self.params["KF_ORI_RATE_HZ"])
        budget = 2000
        while self.next_sample_us <= now and budget:
            budget -= 1
            t = int(self.next_sample_us)
            if self.sensor_gap is not None and self.gap is None and self.samples_taken >= self.sensor_gap[0]:
                self.gap = (t, t + 1000 * self.sensor_gap[1])
            if self.gap is not None and self.gap[0] <= t < self.gap[1]:
                self.next_sample_us = self.gap[1]          # the sensor delivers nothing meanwhile
                continue
            self.next_sample_us += self.period_us
            frame = self._sample(t)
            self.mag_present = True                # every streamed sample has a magnetometer reading
            counter = self.sample_counter          # the counter this sample's frame carries
            self.sample_counter = (self.sample_counter + 1) & 0xFFFFFFFF
            self.samples_taken = (self.samples_taken + 1) & 0xFFFFFFFF
            if self.drop_every and self.sample_counter % self.drop_every == 0:
                self.counters["frames_dropped"] += 1
            else:
                out.append(frame)
                self.sent_samples += 1
            # as the firmware's due(): every ori_every-th sample since the counter was last reset
            # (rate change, stream start with counter reset), not sample_counter % ori_every
            if ori_every:
                self.cnt_ori += 1
                if self.cnt_ori >= ori_every:
                    self.cnt_ori = 0
                    out.append(self._orientation(t, counter))
        return out

    def _sample(self, t_us: int) -> bytes:
        dt = self.period_us * 1e-6
        s = t_us * 1e-6
        omega = np.array([0.6 * math.sin(2 * math.pi * 0.5 * s), 0.4 * math.cos(2 * math.pi * 0.3 * s),
                          1.2 * math.sin(2 * math.pi * 0.2 * s)])  # rad/s, sensor frame
        half = 0.5 * omega * dt
        self.q = _quat_mul(self.q, np.array([1.0, *half]))
        self.q /= np.linalg.norm(self.q)
        g = np.array([0.0, 0.0, STANDARD_GRAVITY])             # specific force at rest, ENU
        b = np.array([0.0, 19.0, -45.0])                        # uT, ENU (north, down)
        acc = _rotate_to_sensor(self.q, g) + self.rng.normal(0, 0.02, 3)
        gyro = omega + self.bias + self.rng.normal(0, 0.002, 3)
        mag = _rotate_to_sensor(self.q, b) + self.rng.normal(0, 0.3, 3)
        a = np.clip(np.round(acc / RAW_SCALE["acc"]), -32768, 32767).astype(int)
        w = np.clip(np.round(gyro / RAW_SCALE["gyro"]), -32768, 32767).astype(int)
        m = np.clip(np.round(mag / RAW_SCALE["mag"]), -32768, 32767).astype(int)
        flags = 8 | 16 | 32  # MAG_UPDATED | CALIBRATED | TEMPERATURE_VALID
        return self.enc.encode(MSG_RAW, time_boot_us=t_us, sample_counter=self.sample_counter,
                               acc_x=int(a[0]), acc_y=int(a[1]), acc_z=int(a[2]), gyro_x=int(w[0]),
                               gyro_y=int(w[1]), gyro_z=int(w[2]), mag_x=int(m[0]), mag_y=int(m[1]),
                               mag_z=int(m[2]), temperature=3150, unit_id=self.params["KF_UNIT_ID"], flags=flags)

    def _orientation(self, t_us: int, counter: int) -> bytes:
        """KF_ORIENTATION after the sample of time ``t_us`` and ``counter``: the dialect's
        time_boot_us and sample_counter of the newest KF_RAW_SAMPLE used (the same pair)."""
        # INITIALISED (| HEADING_TARED); not MAG_USED: filter_id 1 is gyroscope strapdown
        status = 1 | (64 if self.tared else 0)
        return self.enc.encode(MSG_ORI, time_boot_us=t_us, sample_counter=counter,
                               q_w=float(self.q[0]), q_x=float(self.q[1]), q_y=float(self.q[2]), q_z=float(self.q[3]),
                               rejected_samples=0, status=status, earth_frame=1, filter_id=1,
                               unit_id=self.params["KF_UNIT_ID"], cov=[1e-4, 0, 0, 1e-4, 0, 4e-4])

    def _sensor_fault(self, now_us: int) -> bool:
        """KF_UNIT_STATUS_FLAGS_SENSOR_FAULT in a status at ``now_us``: the sensor was silent for
        more than 4 periods and 100 ms (kf_config.c sensor_timeout_us) at some time since the
        previous periodic status (kf_app.c, kf_status.c)."""
        if self.gap is None:
            return False
        timeout = max(4e6 / max(1, self.params["KF_RATE_HZ"]), 100_000)
        start = self.gap[0] - self.period_us + timeout      # the last sample, then the timeout
        prev = -1 if self.status_prev_us is None else self.status_prev_us
        return start < self.gap[1] and start < now_us and self.gap[1] > prev

    def _heartbeat(self) -> bytes:
        return self.enc.encode("HEARTBEAT", type=0, autopilot=8, base_mode=0, custom_mode=0, system_status=4,
                               mavlink_version=3)

    def _status(self, now_us: int) -> bytes:
        c = self.dec.counters
        rate = self.params["KF_RATE_HZ"] if self.streaming else 0
        return self.enc.encode(
            MSG_STATUS, time_boot_us=now_us, firmware_version=FIRMWARE_VERSION, firmware_git_hash=0x0BADC0DE,
            dialect_hash=DIALECT_HASH(), samples=self.samples_taken, samples_dropped=0,
            frames_dropped=self.counters["frames_dropped"], rejected_samples=0, crc_errors=c.crc_errors,
            unknown_messages=self.counters["unknown_messages"], param_rejects=self.counters["param_rejects"],
            sensor_rate_requested=float(self.params["KF_RATE_HZ"]), sensor_rate_achieved=float(self.params["KF_RATE_HZ"]),
            raw_rate_requested=float(rate), raw_rate_achieved=float(rate),
            orientation_rate_requested=float(self.params["KF_ORI_RATE_HZ"] if self.streaming else 0),
            orientation_rate_achieved=float(self.params["KF_ORI_RATE_HZ"] if self.streaming else 0),
            battery_voltage=3900, cpu_load=123,
            # as the firmware: MAG_PRESENT once a magnetometer reading arrived, LOW_BATTERY below
            # KF_BATT_LOW_MV (its cell reads 3,900 mV: only with a threshold set above that),
            # STORAGE_ERROR after a failed load or save since the previous status
            status_flags=(1 if self.streaming else 0) | (2 if self.mag_present else 0) | 32
            | (8 if self.hil else 0) | (128 if self.store_errors != self.store_errors_status else 0)
            | (4 if self._sensor_fault(now_us) else 0)
            | (16 if 3900 < self.params["KF_BATT_LOW_MV"] else 0),
            battery_remaining=80, unit_id=self.params["KF_UNIT_ID"], filter_id=self.params["KF_FILTER"],
            numeric_format=1, earth_frame=1,
            # extensions: a strapdown integration never resets, one sensor (no sensor 1 rejections)
            numeric_resets=0, hil_invalid=self.counters["hil_invalid"], rejected_samples2=0)

    # ------------------------------------------------------------------------------ requests
    def _for_me(self, m) -> bool:
        ts = getattr(m, "target_system", 0)
        tc = getattr(m, "target_component", 0)
        return ts in (0, self.params["KF_UNIT_ID"]) and tc in (0, UNIT_COMPONENT_ID)

    def _handle(self, f) -> list:
        m = f.msg
        name = m._msgname
        if name == "TIMESYNC":
            if m.tc1 == 0:
                return [self.enc.encode("TIMESYNC", tc1=self.device_time_us() * 1000, ts1=m.ts1)]
            return []
        if not self._for_me(m):
            return []
        if name == "HIL_SENSOR":
            return self._hil_sample(m)
        if name == "PARAM_REQUEST_LIST":
            if not self.answer_params:
                return []
            k_loss = self.param_list_loss_every
            return [self._param_value(k) for k in range(len(self.params)) if not (k_loss and k % k_loss == 0)]
        if name == "PARAM_REQUEST_READ":
            if not self.answer_params:
                return []
            names = list(self.params)
            if m.param_index >= 0:
                if m.param_index < len(names):
                    return [self._param_value(m.param_index)]
                # as the unit: PARAM_ERROR (no such parameter), not silence (a host timeout)
                return [self._param_error(m.param_id, m.param_index, 1, f, count=False)]
            if m.param_id in self.params:
                return [self._param_value(names.index(m.param_id))]
            return [self._param_error(m.param_id, -1, 1, f, count=False)]
        if name == "PARAM_SET":
            return self._param_set(m, f) if self.answer_params else []
        if name == "COMMAND_LONG":
            return self._command(m, f)
        if name not in ("HEARTBEAT", "COMMAND_ACK"):
            self.counters["unknown_messages"] += 1
        return []

    def _hil_sample(self, m) -> list:
        """HIL mode: answer a HIL_SENSOR with the KF_RAW_SAMPLE the sensors would have given."""
        from kinefuse.host.link.hil import UT_PER_GAUSS, UPDATED_MAG, UPDATED_TEMPERATURE, raw_sample_counts
        values = (m.xacc, m.yacc, m.zacc, m.xgyro, m.ygyro, m.zgyro, m.xmag, m.ymag, m.zmag)
        if getattr(m, "id", 0) != 0 or any(math.isnan(v) for v in values):
            # as the firmware (one-sensor unit): not processed, no answer, counted in
            # KF_UNIT_STATUS.hil_invalid
            self.counters["hil_invalid"] += 1
            return []
        self.hil = True
        if m.fields_updated & UPDATED_MAG:
            self.mag_present = True
        temperature, updated = m.temperature, m.fields_updated
        if math.isnan(temperature):       # as the firmware: no measurement, not flagged valid
            temperature, updated = 0.0, updated & ~UPDATED_TEMPERATURE
        # as the firmware: the gyro with the smallest KF_RAW_SAMPLE.gyro_shift that fits int16
        a, g, mg, t, clip, shift = raw_sample_counts(
            [m.xacc, m.yacc, m.zacc], [m.xgyro, m.ygyro, m.zgyro],
            [m.xmag * UT_PER_GAUSS, m.ymag * UT_PER_GAUSS, m.zmag * UT_PER_GAUSS], temperature)
        flags = int(clip) | 16 | 64 | (8 if updated & UPDATED_MAG else 0) \
            | (32 if updated & UPDATED_TEMPERATURE else 0)
        frame = self.enc.encode(MSG_RAW, time_boot_us=m.time_usec, sample_counter=self.sample_counter,
                                acc_x=int(a[0]), acc_y=int(a[1]), acc_z=int(a[2]), gyro_x=int(g[0]), gyro_y=int(g[1]),
                                gyro_z=int(g[2]), mag_x=int(mg[0]), mag_y=int(mg[1]), mag_z=int(mg[2]),
                                temperature=int(t), unit_id=self.params["KF_UNIT_ID"], flags=flags,
                                gyro_shift=int(shift))
        self.sample_counter = (self.sample_counter + 1) & 0xFFFFFFFF
        self.samples_taken = (self.samples_taken + 1) & 0xFFFFFFFF
        self.sent_samples += 1
        return [frame]

    def _param_value(self, index: int) -> bytes:
        name = list(self.params)[index]
        ptype = DEFAULT_PARAMS[name][0]
        return self.enc.encode("PARAM_VALUE", param_id=name, param_value=encode_value(self.params[name], ptype),
                               param_type=ptype, param_count=len(self.params), param_index=index)

    def _param_error(self, name: str, index: int, error: int, f, count: bool = True) -> bytes:
        if count:                         # param_rejects counts rejected PARAM_SETs only (as the unit)
            self.counters["param_rejects"] += 1
        return self.enc.encode("PARAM_ERROR", target_system=f.sysid, target_component=f.compid,
                               param_id=name, param_index=index, error=error)

    def _param_set(self, m, f) -> list:
        if m.param_id not in self.params:
            return [self._param_error(m.param_id, -1, 1, f)]
        ptype, _, lo, hi = DEFAULT_PARAMS[m.param_id]
        index = list(self.params).index(m.param_id)
        value = decode_value(m.param_value, m.param_type)
        if m.param_type != ptype or not (lo <= value <= hi) or (isinstance(value, float) and math.isnan(value)) \
                or not self._set(m.param_id, value):
            return [self._param_error(m.param_id, index, 2, f), self._param_value(index)]
        if m.param_id == "KF_UNIT_ID":
            self.enc.sysid = int(value)
        return [self._param_value(index)]

    def _set(self, name: str, value) -> bool:
        """A checked parameter value applied (kf_config_set): a KF_RATE_HZ the sensor cannot
        deliver (its grant out of range) is refused, the old rate kept; a change is stored."""
        old = self.params[name]
        self.params[name] = value
        if name == "KF_RATE_HZ" and not self._apply_rate():
            self.params[name] = old
            return False
        if name in ("KF_RATE_HZ", "KF_ORI_RATE_HZ") and self.params[name] != old:
            self.cnt_ori = 0              # a change restarts the firmware's dividers (kf_config_apply_rates)
        if self.params[name] != old:
            self._save()
        return True

    def _ack(self, command: int, result: int, f) -> bytes:
        return self.enc.encode("COMMAND_ACK", command=command, result=result, progress=0, result_param2=0,
                               target_system=f.sysid, target_component=f.compid)

    def _command(self, m, f) -> list:
        p = (m.param1, m.param2, m.param3, m.param4, m.param5, m.param6, m.param7)
        self.commands.append((m.command, p))
        if m.command == CMD_STREAM:
            self.streaming = p[0] >= 0.5
            if self.streaming and p[1] >= 0.5:
                self.sample_counter = 0
                self.cnt_ori = 0
            return [self._ack(m.command, 0, f)]
        if m.command == CMD_SET_INTERVAL:
            msgid, interval = int(p[0]), p[1]
            key = {MSG_RAW: "KF_RATE_HZ", MSG_ORI: "KF_ORI_RATE_HZ"}.get(msgid)
            if key is None:
                return [self._ack(m.command, 3, f)]
            lo, hi = DEFAULT_PARAMS[key][2:]
            rate = 0 if interval < 0 else DEFAULT_PARAMS[key][1] if interval == 0 else interval_rate(interval)
            if rate is None or not lo <= rate <= hi or not self._set(key, rate):
                return [self._ack(m.command, 2, f)]
            return [self._ack(m.command, 0, f)]
        if m.command == CMD_REQUEST_MESSAGE:
            if int(p[0]) == MSG_STATUS:
                return [self._ack(m.command, 0, f), self._status(self.device_time_us())]
            return [self._ack(m.command, 3, f)]
        if m.command == CMD_REBOOT and int(p[0]) == 1:
            ack = self._ack(m.command, 0, f)
            self._reset_state()
            return [ack]
        if m.command == CMD_TARE:
            self.tared = True
            return [self._ack(m.command, 0, f)]
        if m.command == CMD_RESET:
            self.tared = False
            self.q = np.array([1.0, 0.0, 0.0, 0.0])
            return [self._ack(m.command, 0, f)]
        return [self._ack(m.command, 3, f)]


def raw_frames(n: int, unit_id: int = 1, rate_hz: float = 1000.0, seed: int = 0, start_counter: int = 0,
               seq0: int = 0) -> bytes:
    """``n`` KF_RAW_SAMPLE frames (full length, varied sensor values) for benchmarks and tests."""
    from kinefuse.host.link.batchenc import encode_batch
    rng = np.random.default_rng(seed)
    vals = rng.integers(-4000, 4000, size=(n, 10))
    vals[:, 2] += 1000
    names = ["acc_x", "acc_y", "acc_z", "gyro_x", "gyro_y", "gyro_z", "mag_x", "mag_y", "mag_z", "temperature"]
    v = {name: vals[:, k] for k, name in enumerate(names)}
    v["time_boot_us"] = (np.arange(n) * (1e6 / rate_hz)).astype(np.uint64)
    v["sample_counter"] = ((start_counter + np.arange(n)) & 0xFFFFFFFF).astype(np.uint32)
    v["unit_id"] = np.full(n, unit_id, np.uint8)
    v["flags"] = np.full(n, 8 | 16 | 32, np.uint8)  # non-zero last byte: every frame is 46 bytes
    return encode_batch("KF_RAW_SAMPLE", v, sysid=unit_id, compid=UNIT_COMPONENT_ID, seq0=seq0, n=n)


def _gap_option(v: str) -> tuple:
    """``N:MS`` of ``fake:sensor_gap=`` (ValueError: a bad one), as the host build's --sensor-gap."""
    n, sep, ms = v.partition(":")
    if not sep or not n.strip().isdigit() or not ms.strip().isdigit() or not 1 <= int(ms) <= 3_600_000:
        raise ValueError(v)
    return int(n), int(ms)


class FakeConnection(Connection):
    """Host end of a socket pair whose other end is driven by an in-process :class:`FakeUnit`.

    Connection string ``fake:[rate=1000,ori=100,unit=1,drift=0,drop=0,corrupt=0,stream=1,params=1,grant=0,
    storage_error=0,sensor_gap=N:MS]`` (all optional): try the host tools without hardware.  rate, ori: Hz;
    drift: ppm of the unit's clock; drop=k: every k-th sample lost; corrupt=p: each transmitted *bit* flips with
    probability p (a 46-byte frame survives with (1 - p)^368: p = 1e-4 loses about 4 % of the frames,
    p = 0.02 nearly all); stream=0: waits for MAV_CMD_KF_STREAM; params=0: a unit that does not
    answer the parameter protocol; grant=HZ: its sensor delivers HZ whatever KF_RATE_HZ asks (which
    then becomes HZ, as on the unit); storage_error=1: its parameter storage fails (KF_UNIT_STATUS
    STORAGE_ERROR and a STATUSTEXT ERROR at boot and after each parameter change);
    sensor_gap=N:MS: once, after N samples, its sensor delivers nothing for MS ms (1..3,600,000;
    as the host build's --sensor-gap): KF_UNIT_STATUS SENSOR_FAULT.
    """
    # option -> allowed range (a value outside made the unit's thread die: a silent, empty stream)
    LIMITS = {"rate": (1, 100_000), "ori": (0, 10_000), "unit": (1, 254), "drift": (-100_000, 100_000),
              "drop": (0, 2**31), "corrupt": (0, 1), "seed": (0, 2**32 - 1),
              "grant": (0, DEFAULT_PARAMS["KF_RATE_HZ"][3])}

    def __init__(self, options: str = ""):
        import socket as _socket
        from kinefuse.host.errors import KinefuseError
        from kinefuse.host.link.connection import SocketConnection
        keys = {"rate": ("rate_hz", float), "ori": ("orientation_rate_hz", float), "unit": ("unit_id", int),
                "drift": ("drift_ppm", float), "drop": ("drop_every", int), "corrupt": ("corrupt_probability", float),
                "stream": ("streaming", lambda v: bool(int(v))), "seed": ("seed", int),
                "params": ("answer_params", lambda v: bool(int(v))), "grant": ("sensor_grant_hz", int),
                "storage_error": ("storage_error", lambda v: bool(int(v))),
                "sensor_gap": ("sensor_gap", _gap_option)}
        kw = {}
        for part in filter(None, options.split(",")):
            k, _, v = part.partition("=")
            if k not in keys:
                raise KinefuseError(f"bad fake unit option {k!r} (known: {', '.join(keys)})")
            try:
                kw[keys[k][0]] = keys[k][1](v)
            except ValueError:
                want = " (expected N:MS: samples, then milliseconds 1..3600000)" if k == "sensor_gap" else ""
                raise KinefuseError(f"bad value for fake unit option {k}: {v!r}{want}") from None
            lo, hi = self.LIMITS.get(k, (None, None))
            if lo is not None and not lo <= kw[keys[k][0]] <= hi:   # NaN too
                raise KinefuseError(f"bad value for fake unit option {k}: {v!r} (expected {lo} .. {hi})")
        a, b = _socket.socketpair()
        self.url = f"fake:{options}"
        self._host = SocketConnection(a, self.url)
        self.unit = FakeUnit(SocketConnection(b, "fake-unit"), **kw).start()

    def read(self, timeout: float) -> bytes:
        return self._host.read(timeout)

    def write(self, data: bytes) -> None:
        self._host.write(data)

    def close(self) -> None:
        self.unit.stop()
        self._host.close()
