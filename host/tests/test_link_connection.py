"""Connections: pty (host opened first, nothing lost), TCP/UDP on loopback, files, timeouts, errors."""
from __future__ import annotations

import os
import socket
import threading
import time

import pytest

from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.connection import (ConnectionClosed, Reader, create_pty_pair, open_connection,
                                           open_tty_raw, parse_baud)

posix = pytest.mark.skipif(os.name != "posix", reason="POSIX only")
PAYLOAD = bytes(range(256)) * 400  # 100 kB with every byte value (raw mode: no CR/LF mangling)


def _drain(conn, n, timeout=10.0) -> bytes:
    out, deadline = b"", time.monotonic() + timeout
    while len(out) < n and time.monotonic() < deadline:
        out += conn.read(0.1)
    return out


@posix
def test_pty_unit_writes_before_host_reads_nothing_lost():
    pair = create_pty_pair()
    dev = open_tty_raw(pair.device_path)
    try:
        writer = threading.Thread(target=dev.write, args=(PAYLOAD,))
        writer.start()            # the unit starts writing; the host reads only later
        time.sleep(0.2)
        got = _drain(pair.host, len(PAYLOAD))
        writer.join(5)
        assert got == PAYLOAD
        pair.host.write(b"\xfd\x00\x0d\x0a\x03")  # and the other way, byte-exact (raw mode)
        assert _drain(dev, 5) == b"\xfd\x00\x0d\x0a\x03"
    finally:
        dev.close()
        pair.host.close()


@posix
def test_pty_reopen_by_unit_does_not_end_host_side():
    pair = create_pty_pair()
    try:
        for k in range(2):  # the unit (e.g. a restarted simulator) opens, writes, closes, twice
            dev = open_tty_raw(pair.device_path)
            dev.write(bytes([k]) * 10)
            dev.close()
            assert _drain(pair.host, 10) == bytes([k]) * 10
    finally:
        pair.host.close()


def test_read_timeout_is_real_and_idle_does_not_spin():
    srv = socket.create_server(("127.0.0.1", 0))
    conn = open_connection(f"tcp:127.0.0.1:{srv.getsockname()[1]}")
    peer, _ = srv.accept()
    try:
        t0 = time.monotonic()
        assert conn.read(0.3) == b""
        assert 0.25 <= time.monotonic() - t0 < 2.0
        reader = Reader(conn, poll=0.05)
        cpu0 = time.process_time()
        time.sleep(0.6)
        assert time.process_time() - cpu0 < 0.1  # blocked in select, not polling
        peer.sendall(b"hello")
        items = reader.get(2.0)
        assert b"".join(d for _, d in items) == b"hello" and items[0][0] > 0
        assert reader.get(0.05) == []
        reader.stop()
    finally:
        peer.close()
        conn.close()
        srv.close()


def test_tcp_server_connection_and_disconnect_keeps_bytes():
    conn = open_connection("tcpin:127.0.0.1:0")
    port = conn.address[1]
    conn.write(b"early")  # before the unit connects: delivered on accept
    reader = Reader(conn, poll=0.05)
    unit = socket.create_connection(("127.0.0.1", port))
    try:
        assert unit.recv(16) == b"early"
        unit.sendall(PAYLOAD)
        unit.close()  # the unit disconnects right after writing
        got = b""
        deadline = time.monotonic() + 10
        while not reader.finished and time.monotonic() < deadline:
            got += b"".join(d for _, d in reader.get(0.1))
        got += b"".join(d for _, d in reader.get(0.1))
        assert got == PAYLOAD and reader.error is None
    finally:
        conn.close()


def test_udp_in_and_out():
    rx = open_connection("udpin:127.0.0.1:0")
    tx = open_connection(f"udpout:127.0.0.1:{rx.address[1]}")
    try:
        tx.write(b"abc")
        assert _drain(rx, 3, 5) == b"abc"
        rx.write(b"reply")  # goes back to the last sender
        assert _drain(tx, 5, 5) == b"reply"
    finally:
        rx.close()
        tx.close()


def test_file_connection_reads_everything_then_closes(tmp_path):
    (tmp_path / "c.bin").write_bytes(PAYLOAD)
    conn = open_connection(f"file:{tmp_path / 'c.bin'}")
    got = b""
    with pytest.raises(ConnectionClosed):
        while True:
            got += conn.read(0.1)
    assert got == PAYLOAD


@pytest.mark.parametrize("url, message", [
    ("", "empty connection string"),
    ("tcp:127.0.0.1", "expected HOST:PORT"),
    ("tcp:127.0.0.1:99999", "expected HOST:PORT"),
    ("udpin:127.0.0.1:abc", "expected HOST:PORT"),
    ("/dev/kinefuse-no-such-port", "cannot open serial port"),
    ("serial:/dev/kinefuse-no-such-port:115200", "cannot open serial port"),
    ("pty:/dev/kinefuse-no-such-pty", "cannot open"),
    ("file:/nonexistent/capture.bin", "cannot open"),
    ("fake:rate=abc", "bad value"),
    ("fake:speed=3", "bad fake unit option"),
    ("fake:rate=nan", "expected 1 .. 100000"),        # was an internal error (int(nan))
    ("fake:unit=999", "expected 1 .. 254"),           # was a unit whose thread died: no data
    ("fake:seed=-1", "bad value"),
])
def test_bad_connection_strings_are_one_line_errors(url, message):
    with pytest.raises(KinefuseError, match=message) as exc:
        open_connection(url)
    assert "\n" not in str(exc.value)


@pytest.mark.parametrize("baud", ["abc", "0", "-5", "1e9", "30000000"])
def test_bad_baud(baud):
    with pytest.raises(KinefuseError, match="bad baud rate"):
        parse_baud(baud)


def test_tcp_refused_is_a_one_line_error():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()  # nothing listens there now
    with pytest.raises(KinefuseError, match="cannot connect"):
        open_connection(f"tcp:127.0.0.1:{port}")
