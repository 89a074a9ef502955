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
from pathlib import Path

from kinefuse.host.errors import KinefuseError

ENV_KEY = "KINEFUSE_SIGNING_KEY"
UNIT_COMPONENT = 200
MAV_CMD_REQUEST_MESSAGE = 512
MSG_HEARTBEAT = 0


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
            raise KinefuseError(f"unit {sysid} still requires signing (KF_SIGNING={flag}): clearing the key "
                                f"needs --key with the unit's current key")
    elif flag != 1 or ack != 0:
        session.encoder.key = old
        why = ("it has another key: give the current one with --key/--key-file" if flag == 1
               else "KF_SIGNING is still 0")
        raise KinefuseError(f"unit {sysid} did not take the new key ({why})")
    return {"unit": sysid, "signing": bool(flag), "key_id": key_id(None if clearing else key)}


def _probe(session, sysid: int, timeout: float):
    """Result of a harmless command (REQUEST_MESSAGE HEARTBEAT) as the session signs it now;
    None when no ACK came (a frame signed with a key the unit does not have is dropped)."""
    for _ in range(2):
        session.send("COMMAND_LONG", target_system=sysid, target_component=UNIT_COMPONENT,
                     command=MAV_CMD_REQUEST_MESSAGE, confirmation=0, param1=float(MSG_HEARTBEAT))
        f = session.wait_for(lambda f: f.msgid == 77 and f.sysid == sysid
                             and f.msg.command == MAV_CMD_REQUEST_MESSAGE, timeout=timeout)
        if f is not None:
            return int(f.msg.result)
    return None
