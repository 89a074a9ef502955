"""MAVLink 2 signing: with a key set, unsigned configuration and commands are refused (and
counted), correctly signed ones accepted; bad signatures, other keys and replays are dropped,
also across a reboot; reading stays possible unsigned."""
from __future__ import annotations

import hashlib

import numpy as np
import pytest

from kinefuse.host.link.codec import Encoder, frame_from_payload, signing_timestamp
from kinefuse.host.link.params import encode_value

KEY = hashlib.sha256(b"kinefuse test key").digest()
OTHER = hashlib.sha256(b"someone else").digest()


class Signer:
    """Signed frames with strictly increasing timestamps (10 us ticks since 2015)."""

    def __init__(self, key: bytes, t0: int | None = None, link_id: int = 0):
        self.enc = Encoder(255, 190)
        self.key, self.link_id = key, link_id
        self.ts = signing_timestamp() if t0 is None else t0

    def __call__(self, name, **fields) -> bytes:
        spec, payload = self.enc.payload(name, fields)
        self.ts += 1
        frame = frame_from_payload(spec, payload, 255, 190, self.enc.seq, key=self.key,
                                   link_id=self.link_id, timestamp=self.ts)
        self.enc.seq = (self.enc.seq + 1) & 0xFF
        return frame


def only(frames, name):
    return [f.msg for f in frames if f.msg._msgname == name]


def param_set(name, value, ptype):
    return dict(target_system=1, target_component=200, param_id=name,
                param_value=encode_value(value, ptype), param_type=ptype)


def set_key(unit, key=KEY, signer=None, ts=None):
    fields = dict(target_system=1, target_component=200, secret_key=list(key),
                  initial_timestamp=signing_timestamp() if ts is None else ts)
    unit.feed(signer("SETUP_SIGNING", **fields) if signer else unit.enc.encode("SETUP_SIGNING", **fields))
    unit.take()


@pytest.fixture
def signed_unit(unit):
    set_key(unit)
    assert unit.param("KF_SIGNING") == 1
    return unit


def test_without_a_key_unsigned_configuration_is_accepted(unit):
    assert unit.param("KF_SIGNING") == 0
    unit.set_param("KF_ORI_RATE_HZ", 50)
    assert unit.param("KF_ORI_RATE_HZ") == 50


def test_unsigned_param_set_is_refused_with_a_key(signed_unit):
    u = signed_unit
    frames = u.set_param("KF_ORI_RATE_HZ", 50)
    err = only(frames, "PARAM_ERROR")
    assert len(err) == 1 and err[0].error == 3                  # permission denied
    assert only(frames, "PARAM_VALUE")[0].param_value == encode_value(100, 3)
    assert u.param("KF_ORI_RATE_HZ") == 100
    c = u.counters()
    assert c["unsigned_refused"] == 1 and c["param_rejects"] == 1


def test_signed_param_set_is_accepted(signed_unit):
    u = signed_unit
    sign = Signer(KEY)
    u.feed(sign("PARAM_SET", **param_set("KF_ORI_RATE_HZ", 50, 3)))
    v = only(u.take(), "PARAM_VALUE")
    assert len(v) == 1 and u.param("KF_ORI_RATE_HZ") == 50
    u.feed(sign("PARAM_SET", **param_set("KF_MW_BETA", 0.3, 9)))
    assert u.param("KF_MW_BETA") == np.float32(0.3)


def test_wrong_key_bad_signature_and_replay_are_dropped(signed_unit):
    u = signed_unit
    u.feed(Signer(OTHER)("PARAM_SET", **param_set("KF_ORI_RATE_HZ", 20, 3)))
    assert u.take() == [] and u.param("KF_ORI_RATE_HZ") == 100
    sign = Signer(KEY)
    good = sign("PARAM_SET", **param_set("KF_ORI_RATE_HZ", 30, 3))
    tampered = bytearray(good)
    tampered[-1] ^= 1                                            # signature byte
    u.feed(bytes(tampered))
    assert u.param("KF_ORI_RATE_HZ") == 100
    u.feed(good)
    assert u.param("KF_ORI_RATE_HZ") == 30
    u.feed(sign("PARAM_SET", **param_set("KF_ORI_RATE_HZ", 40, 3)))
    assert u.param("KF_ORI_RATE_HZ") == 40
    u.feed(good)                                                 # replayed: older timestamp
    assert u.param("KF_ORI_RATE_HZ") == 40
    assert u.counters()["signature_failures"] == 3


def test_replay_after_a_reboot_is_refused(signed_unit):
    u = signed_unit
    sign = Signer(KEY)
    recorded = sign("PARAM_SET", **param_set("KF_ORI_RATE_HZ", 30, 3))
    u.feed(recorded)
    u.feed(sign("PARAM_SET", **param_set("KF_ORI_RATE_HZ", 40, 3)))
    u.reboot()
    assert u.param("KF_SIGNING") == 1 and u.param("KF_ORI_RATE_HZ") == 40
    u.feed(recorded)                                             # fresh stream table, stored floor
    assert u.param("KF_ORI_RATE_HZ") == 40
    # a power cycle: the floor is the stored reservation (60 s of ticks past the key's
    # timestamp), which a host on real time has passed by the time it talks again
    u.feed(sign("PARAM_SET", **param_set("KF_ORI_RATE_HZ", 45, 3)))
    assert u.param("KF_ORI_RATE_HZ") == 40
    sign.ts += 6_000_000
    u.feed(sign("PARAM_SET", **param_set("KF_ORI_RATE_HZ", 50, 3)))
    assert u.param("KF_ORI_RATE_HZ") == 50


def test_commands_need_a_signature(signed_unit):
    u = signed_unit
    u.send("COMMAND_LONG", target_system=1, target_component=200, command=52500, param1=0.0)
    acks = only(u.take(), "COMMAND_ACK")
    assert len(acks) == 1 and acks[0].result == 2                # MAV_RESULT_DENIED
    u.feed(Signer(KEY)("COMMAND_LONG", target_system=1, target_component=200, command=52500, param1=0.0))
    acks = only(u.take(), "COMMAND_ACK")
    assert len(acks) == 1 and acks[0].result == 0


def test_reading_needs_no_signature(signed_unit):
    u = signed_unit
    u.send("PARAM_REQUEST_READ", target_system=1, target_component=200, param_id="KF_FILTER", param_index=-1)
    u.send("TIMESYNC", tc1=0, ts1=5)
    frames = u.take()
    assert len(only(frames, "PARAM_VALUE")) == 1 and len(only(frames, "TIMESYNC")) == 1


def test_unsigned_hil_and_key_change_are_dropped(signed_unit):
    u = signed_unit
    u.send("HIL_SENSOR", time_usec=1000, zacc=9.8, fields_updated=0x3F)
    assert only(u.take(), "KF_RAW_SAMPLE") == []
    set_key(u, OTHER)                                            # unsigned: refused
    assert u.counters()["unsigned_refused"] == 2
    u.feed(Signer(KEY)("PARAM_SET", **param_set("KF_ORI_RATE_HZ", 60, 3)))
    assert u.param("KF_ORI_RATE_HZ") == 60                       # the old key still rules


def test_signed_zero_key_turns_signing_off(signed_unit):
    u = signed_unit
    set_key(u, bytes(32), signer=Signer(KEY))
    assert u.param("KF_SIGNING") == 0
    u.set_param("KF_ORI_RATE_HZ", 70)
    assert u.param("KF_ORI_RATE_HZ") == 70
    u.reboot()
    assert u.param("KF_SIGNING") == 0 and u.param("KF_ORI_RATE_HZ") == 70
