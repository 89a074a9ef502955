"""Defect sweep of the link area: each test fails without its fix."""
import os

import numpy as np
import pytest

from kinefuse.host import broad
from kinefuse.host.errors import KinefuseError


# --- broad: a garbage .npz was reported as "holds pickled Python objects" ---------------------

@pytest.mark.parametrize("content, why", [
    (bytes(range(256)) * 2, "not a zip archive"),
    (b"hello world\n", "not a zip archive"),
    (b"", "empty"),
])
def test_garbage_npz_gives_the_real_reason(tmp_path, content, why):
    p = tmp_path / "junk.npz"
    p.write_bytes(content)
    with pytest.raises(KinefuseError) as e:
        broad.load_trial(p)
    msg = str(e.value)
    assert "pickle" not in msg and why in msg and "junk.npz" in msg and "\n" not in msg


def test_npy_named_npz_is_named_as_such(tmp_path):
    p = tmp_path / "one.npz"
    with open(p, "wb") as fh:
        np.save(fh, np.zeros(3))
    with pytest.raises(KinefuseError, match="single .npy array"):
        broad.load_trial(p)


def test_npz_with_object_arrays_still_says_pickled(tmp_path):
    p = tmp_path / "obj.npz"
    np.savez(p, gyr=np.array([{"a": 1}], dtype=object))
    with pytest.raises(KinefuseError, match="pickled Python objects"):
        broad.load_trial(p)


# --- frames.decode_file: a pipe was opened twice, the bytes of the first read were lost -------

def test_decode_file_refuses_a_pipe_instead_of_losing_data():
    from kinefuse.host.link.frames import decode_file
    r, w = os.pipe()
    try:
        os.write(w, b"\x00" * 4000)   # fits the pipe buffer; EOF after it
        os.close(w)
        w = None
        with pytest.raises(KinefuseError, match="not a regular file"):
            decode_file(f"/dev/fd/{r}", raw=True)
    finally:
        os.close(r)
        if w is not None:
            os.close(w)


# --- params.fetch_all: a PARAM_VALUE with an index outside 0..count-1 completed the list ------

class _ScriptedSession:
    """wait_for() hands out queued frames; PARAM_REQUEST_READ by index queues that answer."""

    def __init__(self, table, first):
        from collections import namedtuple
        from kinefuse.host.link.decoder import Frame
        Msg = namedtuple("PARAM_VALUE", "param_id param_value param_type param_count param_index")
        self._frame = lambda i, idx=None: Frame(22, 4, 200, 0, Msg(table[i][0], float(table[i][1]), 9, len(table),
                                                                   i if idx is None else idx), False)
        self.queue = [self._frame(i, idx) for i, idx in first]
        self.sent = []

    def send(self, name, **fields):
        self.sent.append((name, fields))
        if name == "PARAM_REQUEST_READ" and fields["param_index"] >= 0:
            self.queue.append(self._frame(fields["param_index"]))

    def wait_for(self, pred, timeout=1.0):
        for k, f in enumerate(self.queue):
            if pred(f):
                return self.queue.pop(k)
        return None


def test_fetch_all_ignores_an_index_outside_the_list():
    from kinefuse.host.link.params import ParamClient
    table = [("KF_A", 1.0), ("KF_B", 2.0), ("KF_C", 3.0)]
    # index 2 lost; a stray answer to a read by name (index 65535) arrives instead
    s = _ScriptedSession(table, [(0, None), (1, None), (0, 65535)])
    got = ParamClient(s, 4, timeout=0.01).fetch_all(timeout=2.0)
    assert got == {"KF_A": 1.0, "KF_B": 2.0, "KF_C": 3.0}
    assert ("PARAM_REQUEST_READ", {"target_system": 4, "target_component": 200, "param_id": "",
                                   "param_index": 2}) in s.sent


# --- recorder summary: the PARAM_VALUE frames read by ParamClient were missing from "messages" -

def test_record_summary_counts_every_frame_it_received(tmp_path):
    from kinefuse.host.link.fakeunit import DEFAULT_PARAMS
    from kinefuse.host.link.frames import decode_file
    from kinefuse.host.link.recorder import Recorder
    out = tmp_path / "p.kfr"
    summary = Recorder(out, ["fake:rate=200"], fetch_params=True).run(0.5)
    (s,) = summary["streams"]
    assert s["messages"].get("PARAM_VALUE", 0) >= len(DEFAULT_PARAMS)
    assert sum(s["messages"].values()) == s["frames"]
    # the file holds exactly the frames the summary counts, message by message
    ds = decode_file(out).streams[0]
    from kinefuse.host.link.spec import kinefuse_dialect
    in_file = {kinefuse_dialect().get(mid).name: len(a) for mid, a in ds.arrays.items()}
    assert in_file == s["messages"]


# --- commands: a COMMAND_ACK received before the command was sent was taken as its answer -----

def _session_with_a_stale_ack():
    import socket
    from kinefuse.host.link.codec import Encoder
    from kinefuse.host.link.connection import SocketConnection
    from kinefuse.host.link.session import Session
    a, b = socket.socketpair()
    # e.g. the ACK of a previous run's "stop", left in the buffer: result 0 (accepted)
    b.sendall(Encoder(1, 200).encode("COMMAND_ACK", command=52500, result=0))
    s = Session(SocketConnection(a, "pair"))   # the command follows at once (as live --start does)
    return s, b      # b: the unit end, which answers nothing (it dropped a wrongly signed command)


def test_broadcast_command_ignores_an_ack_received_before_sending():
    from kinefuse.host.link import command as C
    s, b = _session_with_a_stale_ack()
    try:
        assert C.broadcast_command(s, C.MAV_CMD_KF_STREAM, 1.0, timeout=0.2) == {}
    finally:
        s.close()
        b.close()


def test_send_command_ignores_an_ack_received_before_sending():
    from kinefuse.host.link import command as C
    s, b = _session_with_a_stale_ack()
    try:
        with pytest.raises(C.CommandError, match="no COMMAND_ACK"):
            C.send_command(s, 1, C.MAV_CMD_KF_STREAM, 1.0, timeout=0.2, retries=1)
    finally:
        s.close()
        b.close()


def test_recorder_start_ignores_an_ack_received_before_sending(tmp_path, monkeypatch):
    import kinefuse.host.link.recorder as R
    from kinefuse.host.link.command import CommandError
    conns = []

    def fake_open(url, baud):   # a connection holding the stale ACK, whose unit answers nothing
        import socket
        from kinefuse.host.link.codec import Encoder
        from kinefuse.host.link.connection import SocketConnection
        x, y = socket.socketpair()
        y.sendall(Encoder(1, 200).encode("COMMAND_ACK", command=52500, result=0))
        conns.append(y)
        return SocketConnection(x, url)

    monkeypatch.setattr(R, "open_connection", fake_open)
    rec = R.Recorder(tmp_path / "r.kfr", ["pair"], start_streaming=True, timesync=False,
                     key=bytes(range(32)), ack_timeout=0.2)
    try:
        with pytest.raises(CommandError, match="no COMMAND_ACK"):
            rec.run(1.0)
    finally:
        rec.close()
        for y in conns:
            y.close()


def test_live_start_with_a_wrong_key_is_refused_despite_a_stale_ack():
    from kinefuse.host.commands.live_cmd import start_streaming
    from kinefuse.host.link.command import CommandError
    s, b = _session_with_a_stale_ack()
    s.encoder.key = bytes(range(32))          # signed: a unit with another key drops it silently
    try:
        with pytest.raises(CommandError, match="right key"):
            start_streaming([s], None)
    finally:
        s.close()
        b.close()


# --- recorder.close: bytes the reader got after the last poll were dropped with the session ---

def test_recorder_writes_every_byte_received_up_to_the_end(tmp_path):
    from kinefuse.host.link.recorder import Recorder
    from kinefuse.host.link.recording import load
    out = tmp_path / "end.kfr"
    rec = Recorder(out, ["fake:rate=5000"], timesync=False)
    summary = rec.run(0.3)
    received = rec.streams[0].session.reader.bytes      # counted where the bytes are read
    assert received > 0
    assert len(load(out).streams[0].rx) == received == summary["streams"][0]["bytes"]


# --- signing --generate: a failed write (disk full) left a cut key file and a traceback --------

def test_generate_key_on_a_full_disk_leaves_no_key_file(tmp_path, monkeypatch, capsys):
    import errno
    from kinefuse.host import cli
    from kinefuse.host.commands import signing_cmd
    real_fdopen = os.fdopen

    class Full:
        def __init__(self, f):
            self.f = f

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self.f.close()

        def write(self, text):
            self.f.write(text[:10])
            self.f.flush()
            raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(signing_cmd.os, "fdopen", lambda fd, mode: Full(real_fdopen(fd, mode)))
    key = tmp_path / "unit.key"
    code = cli.main(["signing", "--generate", str(key)])
    err = capsys.readouterr().err
    assert code == 2 and err == f"kinefuse: error: cannot write {key}: No space left on device (no key file written)\n"
    assert not key.exists()
