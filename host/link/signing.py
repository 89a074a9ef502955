"""MAVLink 2 signing keys on the host, and setting or clearing a unit's key (SETUP_SIGNING).

Key format (``--key`` / ``--key-file`` / ``KINEFUSE_SIGNING_KEY``):

- exactly 64 hexadecimal digits: the 32-byte secret key itself;
- anything else: a passphrase; the key is SHA-256(passphrase as UTF-8), as MAVProxy's
  ``signing setup PASSPHRASE`` derives it (so a unit keyed with MAVProxy works here, and back);
- a key file holds one such line (surrounding whitespace ignored), or exactly 32 raw bytes.

What a kinefuse unit does (firmware/app/kf_handle.c): with no key set it accepts everything,
unsigned SETUP_SIGNING included -- so the first key is set over a link you trust (the USB cable,
not a radio).  With a key set, configuration (PARAM_SET), commands (COMMAND_LONG), HIL_SENSOR
and SETUP_SIGNING must be signed with that key; unsigned ones are refused (PARAM_ERROR
"permission denied", COMMAND_ACK MAV_RESULT_DENIED, or dropped) and reading (parameters,
TIMESYNC, the streams) stays open.  Changing the key needs SETUP_SIGNING signed with the
current key; an all-zero key turns signing off.  The unit answers SETUP_SIGNING with nothing,
so :func:`set_unit_key` checks the result by reading ``KF_SIGNING`` and by a signed
(or, after clearing, unsigned) harmless command.  A lost key cannot be cleared over the link:
erase the unit's storage (reflash with a chip erase).
"""
from __future__ import annotations

import hashlib
import os
import re
import time
from pathlib import Path

from kinefuse.host.errors import KinefuseError

ENV_KEY = "KINEFUSE_SIGNING_KEY"
UNIT_COMPONENT = 200
MAV_CMD_REQUEST_MESSAGE = 512
MSG_HEARTBEAT = 0
MSG_SYS_STATUS = 1
#: the one line told when a unit counted the host's unanswered signed frames as signature failures
REFUSED_TEXT = ("the unit refused the signature ({n} more signature failures): after a power cut it "
                "accepts signed frames only once the host clock passes its stored floor, at most 60 s; "
                "retry in a minute -- or the key differs: is it the right key (--key/--key-file)?")


def parse_key(text: str) -> bytes:
    """64 hex digits -> those 32 bytes; any other non-empty text -> SHA-256(text)."""
    t = text.strip()
    if not t:
        raise KinefuseError("empty signing key")
    if re.fullmatch(r"[0-9a-fA-F]{64}", t):
        return bytes.fromhex(t)
    return hashlib.sha256(t.encode("utf-8")).digest()


def read_key_file(path) -> bytes:
    p = Path(path)
    try:
        raw = p.read_bytes()
    except OSError as exc:
        raise KinefuseError(f"cannot read key file {p}: {exc.strerror or exc}") from None
    if len(raw) == 32:
        try:
            txt = raw.decode("ascii")
        except UnicodeDecodeError:
            return raw                      # 32 raw bytes
        if not txt.isprintable():
            return raw
    try:
        # utf-8-sig: a file saved by Notepad starts with a BOM, which made its 64 hex digits a
        # "passphrase" (the key its SHA-256, silently another key than the one written)
        lines = [ln for ln in raw.decode("utf-8-sig").splitlines() if ln.strip()]
    except UnicodeDecodeError:
        raise KinefuseError(f"key file {p}: neither 32 raw bytes nor a text line") from None
    if len(lines) != 1:
        raise KinefuseError(f"key file {p}: expected one line (64 hex digits or a passphrase), found {len(lines)}")
    return parse_key(lines[0])


def add_key_args(p, what: str = "parameter writes and commands") -> None:
    """--key / --key-file on a sub-command parser."""
    g = p.add_mutually_exclusive_group()
    g.add_argument("--key", metavar="KEY", help=f"MAVLink 2 signing key for {what}: 64 hex digits, or a "
                                                f"passphrase (key = SHA-256, as MAVProxy); default ${ENV_KEY}")
    g.add_argument("--key-file", metavar="FILE", help="read the signing key from FILE (one line as --key, "
                                                      "or 32 raw bytes)")


def key_from_args(args) -> bytes | None:
    # an empty --key / --key-file (e.g. --key "$UNSET") is an error: it fell through to
    # $KINEFUSE_SIGNING_KEY or no key, so writes went unsigned without a word
    for opt, value, want in (("--key", getattr(args, "key", None), "64 hex digits or a passphrase"),
                             ("--key-file", getattr(args, "key_file", None), "the file holding the key")):
        if value is not None and not str(value).strip():
            raise KinefuseError(f"{opt} is empty: give {want}")
    if getattr(args, "key", None) is not None:
        return parse_key(args.key)
    if getattr(args, "key_file", None) is not None:
        return read_key_file(args.key_file)
    env = os.environ.get(ENV_KEY)
    if env:
        return parse_key(env)
    return None


def key_id(key: bytes | None) -> str:
    """A short public name of a key (first 8 hex digits of SHA-256(key)), never the key."""
    return "none" if key is None else hashlib.sha256(key).hexdigest()[:8]


def set_unit_key(session, sysid: int, new_key: bytes | None, timeout: float = 1.0) -> dict:
    """Install ``new_key`` on unit ``sysid`` (None or all zeros: signing off) and check it took.

    The SETUP_SIGNING frame is signed with the session's current key (``session.encoder.key``),
    which must be the unit's current key when it has one.  Afterwards the session signs with
    the new key.  Raises KinefuseError when the unit did not take it."""
    from kinefuse.host.link.codec import signing_timestamp
    from kinefuse.host.link.params import ParamClient, ParamError
    key = bytes(32) if new_key is None else bytes(new_key)
    if len(key) != 32:
        raise KinefuseError("a signing key has 32 bytes")
    clearing = not any(key)
    old = session.encoder.key
    sent_ns = time.monotonic_ns()
    session.send("SETUP_SIGNING", target_system=sysid, target_component=UNIT_COMPONENT,
                 secret_key=list(key), initial_timestamp=signing_timestamp())
    session.encoder.key = None                       # reading needs no signature
    pc = ParamClient(session, sysid, timeout=timeout / 2)
    try:
        flag = pc.get("KF_SIGNING")
    except ParamError as exc:
        session.encoder.key = old
        raise KinefuseError(f"unit {sysid} did not answer after SETUP_SIGNING: {exc}") from None
    session.encoder.key = None if clearing else key
    ack = _probe(session, sysid, timeout)
    if clearing:
        if flag != 0 or ack != 0:
            session.encoder.key = old
            note = _refused_note(session, sysid, sent_ns, timeout)
            raise KinefuseError(f"unit {sysid} still requires signing (KF_SIGNING={flag})"
                                + (note or ": clearing the key needs --key with the unit's current key"))
    elif flag != 1 or ack != 0:
        session.encoder.key = old
        note = _refused_note(session, sysid, sent_ns, timeout) if flag == 1 else None
        why = ("it has another key: give the current one with --key/--key-file" if flag == 1
               else "KF_SIGNING is still 0")
        raise KinefuseError(f"unit {sysid} did not take the new key" + (note or f" ({why})"))
    return {"unit": sysid, "signing": bool(flag), "key_id": key_id(None if clearing else key)}


def _refused_note(session, sysid: int, sent_ns: int, timeout: float):
    """": <refused_text>" when the unit counted the SETUP_SIGNING signed with the current key
    (``session.encoder.key``; unsigned: None) as a signature failure, else None.  Without a
    SYS_STATUS from before it, one harmless command signed with that key is the retry: answered,
    the unit takes that key's signatures and it was not that."""
    _, n = unanswered_signed(session, sysid, sent_ns,
                             lambda: _probe(session, sysid, timeout, tries=1))
    return f": {refused_text(n)}" if n else None


def _probe(session, sysid: int, timeout: float, tries: int = 2):
    """Result of a harmless command (REQUEST_MESSAGE HEARTBEAT) as the session signs it now;
    None when no ACK came (a frame signed with a key the unit does not have is dropped)."""
    for _ in range(tries):
        session.send("COMMAND_LONG", target_system=sysid, target_component=UNIT_COMPONENT,
                     command=MAV_CMD_REQUEST_MESSAGE, confirmation=0, param1=float(MSG_HEARTBEAT))
        f = session.wait_for(lambda f: f.msgid == 77 and f.sysid == sysid
                             and f.msg.command == MAV_CMD_REQUEST_MESSAGE, timeout=timeout)
        if f is not None:
            return int(f.msg.result)
    return None


# ------------------------------------------------------------------ why a signed frame went unanswered
#
# A kinefuse unit drops a signed frame it refuses (bad signature, another key, a timestamp at or
# below its floor -- after a power cut the stored reservation, up to 60 s ahead of the host's
# clock) without an answer, and counts it: SYS_STATUS.errors_count3 (firmware/app/kf_send.c;
# KF_UNIT_STATUS does not carry it), sent with every 1 Hz status.  The host asks nothing (a
# REQUEST_MESSAGE would need a signature too): it compares the counter of the newest SYS_STATUS
# received before its first frame with that of the first one received after it gave up.

def _failures(f) -> int:
    return int(f.msg.errors_count3)


def signature_failures_before(session, sysid: int, t_ns: int):
    """errors_count3 of the newest SYS_STATUS from ``sysid`` the session received before
    ``t_ns`` (monotonic ns) and still holds, or None."""
    session.poll(0)
    for t, f in reversed(session.frames):
        if t < t_ns and f.msgid == MSG_SYS_STATUS and f.sysid == sysid:
            return _failures(f)
    return None


def next_signature_failures(session, sysid: int, timeout: float = 2.0):
    """errors_count3 of the first SYS_STATUS from ``sysid`` received from now on (the unit sends
    one a second), or None after ``timeout`` s or at the end of the connection.  The frame stays
    queued."""
    cut = time.monotonic_ns()
    deadline = time.monotonic() + timeout
    while True:
        found = None
        for t, f in reversed(session.frames):    # newest first: the last match is the oldest
            if t <= cut:
                break
            if f.msgid == MSG_SYS_STATUS and f.sysid == sysid:
                found = f
        if found is not None:
            return _failures(found)
        left = deadline - time.monotonic()
        if left <= 0:
            return None
        if not session.poll(min(left, 0.05)) and session.reader.finished:
            return None


def unanswered_signed(session, sysid: int, sent_ns: int, again=None):
    """After signed frames to unit ``sysid`` sent from ``sent_ns`` (monotonic ns) on went
    unanswered: ``(answer, n)`` -- n > 0 when the unit counted n more signature failures since
    (None: it did not, or it cannot be told; nothing is said then).

    Without a SYS_STATUS received before ``sent_ns`` (a fresh connection) the counter is read
    now, ``again()`` makes ONE more attempt (a bounded retry: send once more, wait for the
    answer; returns it or None) and the counter is read after it; an answer it gets is returned
    as ``answer`` (n None).  An unsigned session: (None, None) at once."""
    if session.encoder.key is None:
        return None, None
    before = signature_failures_before(session, sysid, sent_ns)
    if before is None:
        if again is None:
            return None, None
        before = next_signature_failures(session, sysid)
        if before is None:
            return None, None
        answer = again()
        if answer is not None:
            return answer, None
    after = next_signature_failures(session, sysid)
    if after is None or after <= before:
        return None, None
    return None, after - before


def refused_text(n: int) -> str:
    return REFUSED_TEXT.format(n=n)
