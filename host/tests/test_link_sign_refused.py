"""A signed write or command the unit refuses is told as a refused signature, not a timeout.

The firmware keeps its signing-timestamp floor across restarts: after a power cut it drops signed
frames (counting them in SYS_STATUS.errors_count3) until the host's clock passes the stored
reservation, at most 60 s ahead.  The host showed that only as "no answer".  Tested against the
firmware's host build (kinefuse-unit on a pty, a storage file; stopping the process is a power
cut: nothing is stored on the way down).

Reading parameters needs no signature, also with --key: ``kinefuse params --key`` signed its reads
too, so after a power cut even reading failed (and with a wrong key, although the unit answers an
unsigned read); ``live --start`` (broadcast_command) told a power cut as "nobody answered"."""
from __future__ import annotations

import hashlib
import time

import pytest

from kinefuse.host.link.codec import signing_timestamp

KEY_HEX = hashlib.sha256(b"kinefuse refused signature test").hexdigest()
KEY = bytes.fromhex(KEY_HEX)
REFUSED = "the unit refused the signature"


@pytest.fixture
def unit_after_power_cut(tmp_path):
    """A keyed unit that accepted a signed write (its storage holds a reservation 60 s ahead of
    the host's clock), then lost power; the restarted unit."""
    from kinefuse.firmware.hostunit import HostUnit
    from kinefuse.host.link.params import ParamClient
    store = tmp_path / "unit.storage"
    first = HostUnit(storage=store, sensor=False).start()
    try:
        s = first.session()
        s.send("SETUP_SIGNING", target_system=1, target_component=200, secret_key=list(KEY),
               initial_timestamp=signing_timestamp())
        assert ParamClient(s, 1).get("KF_SIGNING") == 1
        s.encoder.key = KEY
        assert ParamClient(s, 1).set("KF_ORI_RATE_HZ", 50) == 50     # saves the reservation ahead
    finally:
        first.stop()                                                 # the power cut
    unit = HostUnit(storage=store, sensor=False).start()
    unit.t_cut = time.monotonic()
    yield unit
    unit.stop()


def one_line(res):
    code, out, err = res
    lines = err.strip().splitlines()
    assert code == 2 and len(lines) == 1 and lines[0].startswith("kinefuse: error:"), res
    return lines[0]


def test_cli_tells_a_refused_signature_after_a_power_cut(run, unit_after_power_cut):
    unit = unit_after_power_cut
    port = ["--port", f"pty:{unit.device}", "--unit", "1", "--key", KEY_HEX]
    line = one_line(run("params", *port, "--set", "KF_ORI_RATE_HZ=40"))
    assert REFUSED in line and "more signature failures" in line and "retry in a minute" in line, line
    # the read before the write goes unsigned and is answered: the write itself is refused
    assert "no answer to PARAM_SET" in line and "Traceback" not in line
    line = one_line(run("command", *port, "stop"))
    assert REFUSED in line and "no COMMAND_ACK" in line and "retry in a minute" in line, line
    # changing the key: SETUP_SIGNING has no answer; the refused signature is told too
    line = one_line(run("signing", *port, "--new-key", "next key"))
    assert "did not take the new key" in line and REFUSED in line, line
    assert time.monotonic() - unit.t_cut < 50, "too slow: the floor may have passed meanwhile"
    # an unsigned read still works: the unit is there, only the signatures were refused
    code, out, err = run("params", "--port", f"pty:{unit.device}", "--unit", "1", "--get", "KF_ORI_RATE_HZ")
    assert code == 0 and "KF_ORI_RATE_HZ = 50" in out, err


def test_the_count_from_a_status_seen_before_the_request(unit_after_power_cut):
    """A SYS_STATUS already received: its counter is the "before" (no extra attempt); every
    refused frame is counted."""
    from kinefuse.host.link.command import MAV_CMD_KF_STREAM, CommandError, send_command
    from kinefuse.host.link.params import ParamClient, ParamError
    s = unit_after_power_cut.session(key=KEY)
    deadline = time.monotonic() + 3
    while not any(f.msgid == 1 for _, f in s.frames):       # a SYS_STATUS queued (left there)
        assert time.monotonic() < deadline
        s.poll(0.05)
    with pytest.raises(ParamError) as e:
        ParamClient(s, 1, timeout=0.3, retries=2).set("KF_ORI_RATE_HZ", 40, ptype=3)
    assert e.value.refused is not None and e.value.refused >= 2, str(e.value)
    assert f"({e.value.refused} more signature failures)" in str(e.value)
    with pytest.raises(CommandError) as e:
        send_command(s, 1, MAV_CMD_KF_STREAM, 0.0, timeout=0.3, retries=2)
    assert e.value.refused is not None and REFUSED in str(e.value)


def test_an_unsigned_silence_is_still_a_plain_timeout(run):
    """No key: nothing is measured or claimed (a fake unit that does not answer parameters)."""
    line = one_line(run("params", "--port", "fake:params=0", "--unit", "1", "--timeout", "0.5",
                        "--get", "KF_RATE_HZ"))
    assert REFUSED not in line and "no answer" in line, line


# ------------------------------------------------ reads unsigned, broadcasts (was its own file)

def test_reads_work_at_once_after_a_power_cut_writes_are_refused(run, unit_after_power_cut):
    unit = unit_after_power_cut
    port = ["--port", f"pty:{unit.device}", "--unit", "1"]
    code, out, err = run("params", *port, "--key", KEY_HEX, "--get", "KF_ORI_RATE_HZ")
    assert code == 0 and "KF_ORI_RATE_HZ = 50" in out, err
    code, out, err = run("params", *port, "--key", KEY_HEX)              # the whole list
    assert code == 0 and "KF_ORI_RATE_HZ = 50" in out and "KF_SIGNING = 1" in out, err
    code, out, err = run("params", *port, "--key", "not the unit's key", "--get", "KF_SIGNING")
    assert code == 0 and "KF_SIGNING = 1" in out, err
    # the write still goes signed: refused (the floor), told as such; the read before it worked
    line = one_line(run("params", *port, "--key", KEY_HEX, "--set", "KF_ORI_RATE_HZ=40"))
    assert REFUSED in line and "no answer to PARAM_SET" in line and "nothing written" not in line, line
    assert time.monotonic() - unit.t_cut < 50, "too slow: the floor may have passed meanwhile"


def test_live_start_tells_a_refused_signature(run, unit_after_power_cut):
    unit = unit_after_power_cut
    line = one_line(run("live", "--port", f"pty:{unit.device}", "--start", "--seconds", "0.5",
                        "--key", KEY_HEX))
    assert REFUSED in line and "no COMMAND_ACK for MAV_CMD_KF_STREAM from unit 1" in line, line
    assert "Traceback" not in line
    assert time.monotonic() - unit.t_cut < 50, "too slow: the floor may have passed meanwhile"


def test_unsigned_send_keeps_the_signing_stream():
    """signed=False: no signature block, no timestamp taken; the key stays for the next frame."""
    from types import SimpleNamespace as NS

    from kinefuse.host.link.codec import IFLAG_SIGNED, Encoder
    from kinefuse.host.link.session import Session
    s = Session.__new__(Session)
    s.encoder, s.tap, sent = Encoder(255, 190, key=KEY), None, []
    s.conn = NS(write=sent.append)
    s.send("PARAM_SET", target_system=1, param_id="KF_A")
    ts = s.encoder._last_ts
    s.send("PARAM_REQUEST_READ", signed=False, target_system=1, param_id="KF_A", param_index=-1)
    assert s.encoder.key == KEY and s.encoder._last_ts == ts
    s.send("PARAM_SET", target_system=1, param_id="KF_A")
    assert [f[2] & IFLAG_SIGNED for f in sent] == [1, 0, 1]
    assert [len(f) for f in sent][1] == len(sent[1]) and s.encoder._last_ts > ts
    assert sent[1][1] + 12 == len(sent[1])            # header 10 + payload + crc 2: no signature


class _TwoUnits:
    """Units 1 and 2 send SYS_STATUS; unit 1 answers every COMMAND_LONG, unit 2 drops them and
    counts each as a signature failure (its SYS_STATUS.errors_count3)."""

    def __init__(self, key=KEY):
        from collections import deque
        from types import SimpleNamespace as NS
        self.NS = NS
        self.encoder = NS(key=key)
        self.reader = NS(finished=False)
        self.failures = 0
        self.frames = deque()
        self.sent = 0
        self._status(1, 0)
        self._status(2, 0)

    def _status(self, sysid, n, t=None):
        self.frames.append((time.monotonic_ns() - 10**9 if t is None else t,
                            self.NS(msgid=1, sysid=sysid, msg=self.NS(errors_count3=n))))

    def send(self, name, **fields):
        self.sent += 1
        self.failures += 1
        self.frames.append((time.monotonic_ns(), self.NS(msgid=77, sysid=1,
                                                         msg=self.NS(command=fields["command"], result=0))))

    def poll(self, timeout=0.0):
        time.sleep(min(timeout, 0.01))
        if timeout > 0:
            self._status(2, self.failures, time.monotonic_ns())
            return 1
        return 0

    def wait_for(self, pred, timeout=1.0):
        for k, (_, f) in enumerate(self.frames):
            if pred(f):
                del self.frames[k]
                return f
        self.poll(timeout)
        return None


def test_broadcast_tells_each_unit_that_refused_the_signature():
    from kinefuse.host.link.command import MAV_CMD_KF_STREAM, broadcast_command
    s = _TwoUnits()
    refused: dict = {}
    acks = broadcast_command(s, MAV_CMD_KF_STREAM, 1.0, timeout=0.2, refused=refused)
    assert acks == {1: 0} and refused == {2: s.sent}
    s = _TwoUnits(key=None)                     # unsigned: nothing measured or claimed
    refused = {}
    assert broadcast_command(s, MAV_CMD_KF_STREAM, 1.0, timeout=0.2, refused=refused) == {1: 0}
    assert refused == {}


# ------------------------------------------------------------- the counting itself (no unit)

class _Session:
    """Enough of a Session: SYS_STATUS frames with the counters given arrive one per poll."""

    def __init__(self, key=KEY, queued=(), arriving=()):
        from collections import deque
        from types import SimpleNamespace as NS
        self.encoder = NS(key=key)
        self.reader = NS(finished=False)
        self._f = lambda n: NS(msgid=1, sysid=1, msg=NS(errors_count3=n))
        self.frames = deque((time.monotonic_ns() - 10**9, self._f(n)) for n in queued)
        self.arriving = list(arriving)

    def poll(self, timeout=0.0):
        if self.arriving and timeout > 0:
            time.sleep(0.001)
            self.frames.append((time.monotonic_ns(), self._f(self.arriving.pop(0))))
            return 1
        time.sleep(timeout)
        return 0


@pytest.mark.parametrize("queued, arriving, again, want, asked", [
    ((5,), (8,), None, (None, 3), 0),              # a status from before: no extra attempt
    ((5,), (5,), None, (None, None), 0),           # not counted: not a refused signature
    ((), (5,), "answer", ("answer", None), 1),     # fresh connection: one more attempt, answered
    ((), (5, 6), None, (None, 1), 1),              # ... unanswered and counted
    ((), (), None, (None, None), 0),               # no SYS_STATUS at all (a fake unit): nothing said
])
def test_unanswered_signed(queued, arriving, again, want, asked):
    from kinefuse.host.link.signing import unanswered_signed
    s = _Session(queued=queued, arriving=arriving)
    calls = []

    def attempt():
        calls.append(1)
        return again
    assert unanswered_signed(s, 1, time.monotonic_ns(), attempt) == want
    assert len(calls) == asked


def test_unsigned_session_measures_nothing():
    from kinefuse.host.link.signing import unanswered_signed
    s = _Session(key=None, queued=(1,), arriving=(9,))
    assert unanswered_signed(s, 1, time.monotonic_ns(), lambda: 1 / 0) == (None, None)
    assert s.arriving == [9]
