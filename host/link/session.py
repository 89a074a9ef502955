"""A MAVLink endpoint on a connection: reader thread + streaming decoder + encoder.

    with Session(open_connection("tcp:127.0.0.1:5760")) as s:
        s.send("COMMAND_LONG", target_system=1, target_component=200, command=52500, param1=1)
        ack = s.wait_for("COMMAND_ACK", timeout=1.0)

Frames are decoded in the caller's thread (``poll``/``wait_for``); received host times are the
monotonic ns of the read that completed the frame.  An optional ``tap(kind, t_ns, bytes)`` sees
every received and sent byte (the recorder uses it).
"""
from __future__ import annotations

import time
from collections import deque
from typing import Callable

from kinefuse.host.link.codec import Encoder
from kinefuse.host.link.connection import Connection, Reader
from kinefuse.host.link.decoder import Frame, StreamDecoder
from kinefuse.host.link.dialect import HOST_COMPONENT_ID, HOST_SYSTEM_ID


class Session:
    def __init__(self, conn: Connection, sysid: int = HOST_SYSTEM_ID, compid: int = HOST_COMPONENT_ID,
                 key: bytes | None = None, tap: Callable | None = None, keep: int = 20_000):
        self.conn = conn
        self.encoder = Encoder(sysid, compid, key=key)
        self.decoder = StreamDecoder(key=key)
        self.reader = Reader(conn)
        self.tap = tap
        self.frames: deque = deque(maxlen=keep)  # (t_ns, Frame), oldest dropped beyond ``keep``
        # message name -> frames decoded, whoever took them from ``frames`` (wait_for, drain)
        self.msg_counts: dict = {}

    # -- sending -------------------------------------------------------------------------------
    def send(self, message, signed: bool = True, **fields) -> bytes:
        """Encode and send one frame; signed with the session's key (``encoder.key``) when it
        has one, unless ``signed`` is False (e.g. reading parameters: a keyed unit answers
        unsigned reads, and after a power cut it refuses signed frames for up to 60 s).  An
        unsigned frame takes no signing timestamp: the signed ones still strictly increase."""
        if signed or self.encoder.key is None:
            frame = self.encoder.encode(message, **fields)
        else:
            key, self.encoder.key = self.encoder.key, None
            try:
                frame = self.encoder.encode(message, **fields)
            finally:
                self.encoder.key = key
        self.send_bytes(frame)
        return frame

    def send_bytes(self, data: bytes) -> None:
        if self.tap is not None:
            self.tap("tx", time.monotonic_ns(), data)
        self.conn.write(data)

    # -- receiving -----------------------------------------------------------------------------
    def poll(self, timeout: float = 0.0) -> int:
        """Decode what has arrived (waiting up to ``timeout`` for the first bytes); new frame count."""
        n = 0
        counts = self.msg_counts
        for t_ns, data in self.reader.get(timeout):
            if self.tap is not None:
                self.tap("rx", t_ns, data)
            for f in self.decoder.feed(data):
                self.frames.append((t_ns, f))
                name = f.msg._msgname
                counts[name] = counts.get(name, 0) + 1
                n += 1
        return n

    def wait_for(self, match, timeout: float = 1.0):
        """First queued or arriving frame matching ``match`` (message name, id or predicate).

        Returns (and removes from the queue) the Frame, or None after ``timeout`` s or at the
        end of the connection.  Non-matching frames stay queued (the newest ``keep``).
        """
        pred = _predicate(match)
        deadline = time.monotonic() + timeout
        start = 0
        while True:
            for k in range(start, len(self.frames)):
                if pred(self.frames[k][1]):
                    f = self.frames[k][1]
                    del self.frames[k]
                    return f
            left = deadline - time.monotonic()
            if left <= 0:
                return None
            before = len(self.frames)
            got = self.poll(min(left, 0.05))
            if not got and self.reader.finished:
                return None
            dropped = max(0, before + got - len(self.frames))  # overflow of the bounded queue
            start = max(0, before - dropped)

    def drain(self) -> list[tuple[int, Frame]]:
        """All queued frames (and forget them)."""
        self.poll(0)
        out = list(self.frames)
        self.frames.clear()
        return out

    def close(self) -> None:
        self.reader.stop()
        self.conn.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def _predicate(match) -> Callable[[Frame], bool]:
    if callable(match):
        return match
    if isinstance(match, str):
        name = match.upper()
        return lambda f: f.msg._msgname == name
    return lambda f: f.msgid == match
