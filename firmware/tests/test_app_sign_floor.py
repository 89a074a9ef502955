"""MAVLink 2 signing across a restart: the newest accepted timestamp survives it.

The unit stored its signing floor only with parameter writes, commands and key changes, so a
signed HIL_SENSOR (or TIMESYNC) recorded after the last such write was accepted again after a
reboot and switched the unit to HIL.  Now storage holds a reservation at or above every accepted
timestamp: a verified frame beyond it first moves it 60 s of ticks ahead in storage (at most one
such save per 10 s of device time), and a commanded reboot stores the newest timestamp itself.
"""
from __future__ import annotations

import hashlib
import struct
import time
import zlib

from kinefuse.host.link.codec import Encoder, frame_from_payload, signing_timestamp
from kinefuse.host.link.params import encode_value

KEY = hashlib.sha256(b"kinefuse floor key").digest()
RESERVE = 6_000_000          # KF_SIGN_RESERVE_TICKS (kf_handle.c): 60 s of 10 us ticks
SAVE_MIN_US = 10_000_000     # KF_SIGN_SAVE_MIN_US
HDR_TS = 48                  # kf_store_header.sign_timestamp offset
HIL_FLAG = 8                 # KF_UNIT_STATUS_FLAGS_HIL


def only(frames, name):
    return [f.msg for f in frames if f.msg._msgname == name]


class Signer:
    """Signed frames from system 255 / component 190, link 0, at the timestamps asked for."""

    def __init__(self, key=KEY):
        self.enc = Encoder(255, 190)
        self.key = key

    def __call__(self, name, ts, **fields) -> bytes:
        spec, payload = self.enc.payload(name, fields)
        frame = frame_from_payload(spec, payload, 255, 190, self.enc.seq, key=self.key, timestamp=ts)
        self.enc.seq = (self.enc.seq + 1) & 0xFF
        return frame


def hil(sign, ts, t_us=10_000):
    return sign("HIL_SENSOR", ts, time_usec=t_us, xacc=0.1, yacc=0.2, zacc=9.8, xgyro=0.01,
                ygyro=-0.02, zgyro=0.03, xmag=0.2, ymag=0.0, zmag=-0.4, temperature=21.0,
                fields_updated=0x1FF, id=0)


def param_set(sign, ts, name, value, ptype=3):
    return sign("PARAM_SET", ts, target_system=1, target_component=200, param_id=name,
                param_value=encode_value(value, ptype), param_type=ptype)


def keyed(unit, t0):
    unit.send("SETUP_SIGNING", target_system=1, target_component=200, secret_key=list(KEY),
              initial_timestamp=t0)
    unit.take()
    assert unit.param("KF_SIGNING") == 1


def answered(unit, frame) -> bool:
    """The unit handled the signed HIL_SENSOR: it answered with KF_RAW_SAMPLE."""
    unit.feed(frame)
    return len(only(unit.take(), "KF_RAW_SAMPLE")) == 1


def stored_floor(unit) -> int:
    """sign_timestamp of the newest valid copy (the higher sequence number of the two slots)."""
    img = unit.storage()
    best = None
    for base in (0, 2048):
        magic, _, count, seq = struct.unpack_from("<IHHI", img, base)
        end = base + 56 + 8 * count
        valid = magic == 0x4643464B and end + 4 <= base + 2048 \
            and struct.unpack_from("<I", img, end)[0] == zlib.crc32(img[base:end])
        if valid and (best is None or seq > best[0]):
            best = (seq, struct.unpack_from("<Q", img, base + HDR_TS)[0])
    return best[1]


def test_a_signed_hil_sample_is_refused_after_a_power_cycle(unit):
    """The reported defect: HIL_SENSOR accepted, reboot, the same frame accepted again."""
    t0 = signing_timestamp()
    keyed(unit, t0)
    sign = Signer()
    recorded = hil(sign, t0 + 100)                  # within the key's reservation
    assert answered(unit, recorded)
    far = hil(sign, t0 + 2 * RESERVE, 20_000)      # beyond it: stored ahead before it is used
    assert answered(unit, far)
    assert stored_floor(unit) == t0 + 3 * RESERVE
    unit.reboot()                                   # power cycle: no save on the way down
    failures = unit.counters()["signature_failures"]
    assert not answered(unit, recorded)
    assert not answered(unit, far)
    assert unit.counters()["signature_failures"] == failures + 2
    assert answered(unit, hil(sign, t0 + 3 * RESERVE + 1, 30_000))   # the host's clock moved on


def test_a_commanded_reboot_stores_the_newest_timestamp_itself(unit):
    """No lock-out after `kinefuse command reboot`: the floor is the last accepted frame."""
    t0 = signing_timestamp()
    keyed(unit, t0)
    sign = Signer()
    recorded = hil(sign, t0 + 2 * RESERVE)
    assert answered(unit, recorded)
    last = t0 + 2 * RESERVE + 7
    unit.feed(sign("COMMAND_LONG", last, target_system=1, target_component=200, command=246, param1=1.0))
    assert unit.lib.kft_reboots() == 1
    assert stored_floor(unit) == last
    unit.reboot()
    assert not answered(unit, recorded)
    assert answered(unit, hil(sign, last + 1, 20_000))


def test_timestamps_are_not_saved_per_frame(unit):
    """A host on the MAVLink clock: 2,000 signed samples within the reservation write nothing;
    crossing it writes one copy."""
    t0 = signing_timestamp()
    keyed(unit, t0)
    sign = Signer()
    w0 = unit.lib.kft_written()
    for i in range(2000):
        unit.feed(hil(sign, t0 + 50 * (i + 1), 1000 * (i + 1)), polls=1)
        if i % 100 == 0:
            unit.take()
    assert len(only(unit.take(), "KF_RAW_SAMPLE")) > 0 and unit.counters()["frames_dropped"] == 0
    assert unit.lib.kft_written() == w0
    assert answered(unit, hil(sign, t0 + RESERVE + 1, 3_000_000))
    one_copy = unit.lib.kft_written() - w0
    assert 100 < one_copy < 2048


def test_saves_ahead_are_at_most_one_per_10_s(unit):
    """A host whose timestamps race ahead cannot wear the flash: a frame beyond the reservation
    less than 10 s (device time) after the previous such save is refused, not saved."""
    t0 = signing_timestamp()
    keyed(unit, t0)
    sign = Signer()
    unit.advance(1_000_000)
    assert answered(unit, hil(sign, t0 + 2 * RESERVE, 1000))      # first save ahead: allowed
    w = unit.lib.kft_written()
    failures = unit.counters()["signature_failures"]
    assert not answered(unit, hil(sign, t0 + 4 * RESERVE, 2000))  # 0 s later: refused
    unit.advance(SAVE_MIN_US - 1)
    assert not answered(unit, hil(sign, t0 + 4 * RESERVE + 1, 3000))
    assert unit.lib.kft_written() == w and unit.counters()["signature_failures"] == failures + 2
    unit.advance(1)
    assert answered(unit, hil(sign, t0 + 4 * RESERVE + 2, 5000))  # 10 s later: saved, accepted
    assert unit.lib.kft_written() > w
    assert stored_floor(unit) == t0 + 5 * RESERVE + 2


def _all_params(unit):
    return [unit.lib.kft_param_get(unit.app, i) for i in range(unit.lib.kft_param_count())]


def test_power_cut_at_every_byte_of_a_timestamp_save(unit):
    """The save ahead is a whole copy through kf_store (the other slot keeps the previous one):
    cut after any byte, the parameters are those saved before, every frame handled before the
    cut is refused after it; the frame whose save was cut was never handled on a real unit (the
    power failed first), so accepting it then is not a replay."""
    t0 = signing_timestamp()
    keyed(unit, t0)                                  # copy 1 (key, reservation t0 + RESERVE)
    sign = Signer()
    unit.feed(param_set(sign, t0 + 10, "KF_ORI_RATE_HZ", 50))      # copy 2: both slots valid
    unit.feed(param_set(sign, t0 + 20, "KF_MW_BETA", 0.25, 9))     # copy 3
    handled = [hil(sign, t0 + 30 + i, 1000 * (i + 1)) for i in range(5)]
    for f in handled:
        assert answered(unit, f)
    unit.reboot()                                   # the unit as it was before the save below
    image = unit.storage()
    params = _all_params(unit)
    assert unit.param("KF_ORI_RATE_HZ") == 50
    ahead = hil(sign, t0 + 2 * RESERVE, 90_000)     # beyond the reservation: a save ahead
    w0 = unit.lib.kft_written()
    assert answered(unit, ahead)
    total = unit.lib.kft_written() - w0
    assert total > 100
    for k in range(total + 1):
        unit.restore_storage(image)
        unit.reboot()
        unit.lib.kft_budget(k)                      # the power fails after k bytes
        unit.feed(ahead)
        unit.take()
        unit.lib.kft_budget(-1)
        unit.reboot()                               # power back
        assert _all_params(unit) == params, f"cut after {k} of {total} bytes"
        assert unit.counters()["storage_errors"] == 0
        for f in handled:
            assert not answered(unit, f), f"replay accepted after a cut at {k} of {total} bytes"
        assert stored_floor(unit) == (t0 + 3 * RESERVE if k == total else t0 + RESERVE)
        assert answered(unit, ahead) == (k < total)


# ---------------------------------------------------------------- the host build (a process)

def _raw_answer(s, timeout):
    return s.wait_for(lambda f: f.msgid == 52500, timeout=timeout)


def _keyed_host_unit(unit, t0):
    from kinefuse.host.link.params import ParamClient
    s = unit.session()
    s.send("SETUP_SIGNING", target_system=1, target_component=200, secret_key=list(KEY),
           initial_timestamp=t0)
    assert ParamClient(s, 1).get("KF_SIGNING") == 1
    return s


def test_host_build_refuses_a_recorded_hil_sample_after_a_restart(tmp_path):
    """kinefuse-unit with a storage file: a signed HIL_SENSOR it answered, sent again to the
    next process on the same storage (a power cycle), is dropped: no HIL answer."""
    from kinefuse.firmware.hostunit import HostUnit
    store = tmp_path / "unit.storage"
    t0 = signing_timestamp()
    sign = Signer()
    recorded = hil(sign, t0 + 100)
    with HostUnit(storage=store, sensor=False) as unit:
        s = _keyed_host_unit(unit, t0)
        s.send_bytes(recorded)
        assert _raw_answer(s, 3) is not None
    with HostUnit(storage=store, sensor=False) as unit:
        s = unit.session()
        s.send_bytes(recorded)
        assert _raw_answer(s, 1.0) is None
        s.send_bytes(hil(sign, t0 + RESERVE + 1))   # past the stored reservation: handled
        assert _raw_answer(s, 3) is not None


def test_host_build_commanded_reboot_keeps_the_host_talking(tmp_path):
    """MAV_CMD_PREFLIGHT_REBOOT_SHUTDOWN: the floor is the reboot command's own timestamp, so
    the recorded sample is refused and the host's next frame is accepted at once."""
    from kinefuse.firmware.hostunit import HostUnit
    store = tmp_path / "unit.storage"
    t0 = signing_timestamp()
    sign = Signer()
    recorded = hil(sign, t0 + 100)
    with HostUnit(storage=store, sensor=False) as unit:
        s = _keyed_host_unit(unit, t0)
        s.send_bytes(recorded)
        assert _raw_answer(s, 3) is not None
        s.send_bytes(sign("COMMAND_LONG", t0 + 200, target_system=1, target_component=200,
                          command=246, param1=1.0))
        ack = s.wait_for(lambda f: f.msgid == 77 and f.msg.command == 246, timeout=3)
        assert ack is not None and ack.msg.result == 0
        time.sleep(0.3)
        s.send_bytes(recorded)
        assert _raw_answer(s, 1.0) is None
        s.send_bytes(hil(sign, t0 + 201))
        assert _raw_answer(s, 3) is not None
    assert stored_floor_file(store) == t0 + RESERVE + 201   # saved ahead after the reboot



def test_host_build_power_cut_during_the_timestamp_save(tmp_path):
    """The host build's storage file, the process dying mid-save (status 75) while a frame
    beyond the reservation is stored ahead: the next process has the parameters and the key,
    and refuses the sample handled before the cut."""
    from kinefuse.firmware.hostunit import HostUnit
    from kinefuse.host.link.params import ParamClient
    store = tmp_path / "unit.storage"
    t0 = signing_timestamp()
    sign = Signer()
    recorded = hil(sign, t0 + 100)
    with HostUnit(storage=store, sensor=False) as unit:
        s = _keyed_host_unit(unit, t0)
        s.send_bytes(param_set(sign, t0 + 50, "KF_ORI_RATE_HZ", 40))
        assert s.wait_for(lambda f: f.msgid == 22, timeout=3) is not None     # PARAM_VALUE
        s.send_bytes(recorded)
        assert _raw_answer(s, 3) is not None
    image = store.read_bytes()
    count = struct.unpack_from("<H", image, 2048 + 6)[0]      # copy 2 (the parameter) in slot 1
    copy = 56 + 8 * count + 4
    for cut in (3, 52, copy // 2, copy - 1):                  # header, floor, entries, CRC
        store.write_bytes(image)
        unit = HostUnit(storage=store, sensor=False, extra=["--storage-fail-after", str(cut)]).start()
        try:
            unit.session().send_bytes(hil(sign, t0 + 2 * RESERVE + cut))
            assert unit.proc.wait(5) == 75
        finally:
            unit.stop()
        with HostUnit(storage=store, sensor=False) as unit:
            s = unit.session()
            pc = ParamClient(s, 1)
            assert pc.get("KF_ORI_RATE_HZ") == 40 and pc.get("KF_SIGNING") == 1, cut
            s.send_bytes(recorded)
            assert _raw_answer(s, 1.0) is None, cut


def stored_floor_file(path):
    class _U:
        def storage(self):
            return path.read_bytes()[:4096]
    return stored_floor(_U())
