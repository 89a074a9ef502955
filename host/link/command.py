"""COMMAND_LONG with its COMMAND_ACK checked: a refused command is an error, not silence.

    result = send_command(session, 1, MAV_CMD_KF_STREAM, 1.0)     # raises CommandError if refused
    acks = broadcast_command(session, MAV_CMD_KF_STREAM, 1.0)     # {sysid: result} of every unit

MAV_RESULT_DENIED from a kinefuse unit means that it requires signed commands (a key is set on
it) or that a value is out of range (e.g. a KF_RAW_SAMPLE rate above KF_RATE_HZ's 2000 Hz): the
error names both when the command went unsigned, the range when it was signed.  A signed
command left unanswered because the unit refused its signature (counted in its SYS_STATUS: after
a power cut, until the host's clock passes the unit's stored signing floor, at most 60 s; or
another key) is told as such, not only as a timeout; broadcast_command tells it per unit heard
that did not answer (``refused``).
"""
from __future__ import annotations

import time

from kinefuse.host.errors import KinefuseError

UNIT_COMPONENT = 200
MSG_COMMAND_ACK = 77
MAV_CMD_KF_STREAM, MAV_CMD_KF_HEADING_TARE, MAV_CMD_KF_FILTER_RESET = 52500, 52501, 52502
MAV_CMD_SET_MESSAGE_INTERVAL, MAV_CMD_REQUEST_MESSAGE, MAV_CMD_REBOOT = 511, 512, 246
MSG_KF_RAW_SAMPLE = 52500
COMMAND_NAMES = {MAV_CMD_KF_STREAM: "MAV_CMD_KF_STREAM", MAV_CMD_KF_HEADING_TARE: "MAV_CMD_KF_HEADING_TARE",
                 MAV_CMD_KF_FILTER_RESET: "MAV_CMD_KF_FILTER_RESET",
                 MAV_CMD_SET_MESSAGE_INTERVAL: "MAV_CMD_SET_MESSAGE_INTERVAL",
                 MAV_CMD_REQUEST_MESSAGE: "MAV_CMD_REQUEST_MESSAGE", MAV_CMD_REBOOT: "MAV_CMD_PREFLIGHT_REBOOT_SHUTDOWN"}
RESULTS = {0: "ACCEPTED", 1: "TEMPORARILY_REJECTED", 2: "DENIED", 3: "UNSUPPORTED", 4: "FAILED",
           5: "IN_PROGRESS", 6: "CANCELLED"}
RESULT_HINTS = {
    1: "not possible now (e.g. no orientation yet for a heading tare)",
    2: "a value out of range, or the unit requires signed commands: give its key with --key/--key-file",
    3: "this unit does not support it",
    4: "the unit could not do it",
}


class CommandError(KinefuseError):
    """A command was refused by a unit or not answered."""

    def __init__(self, text: str, result: int | None = None, refused: int | None = None):
        super().__init__(text)
        self.result = result
        #: unanswered signed commands the unit counted as signature failures (None: not that)
        self.refused = refused


def command_name(cmd: int) -> str:
    return COMMAND_NAMES.get(cmd, f"command {cmd}")


def refusal_text(sysid: int, cmd: int, result: int, signed: bool = False) -> str:
    """One line for a refused command; ``signed``: it was sent signed (DENIED then means an
    out-of-range value, not a missing key)."""
    hint = "a value out of range" if signed and result == 2 else RESULT_HINTS.get(result)
    return (f"unit {sysid} refused {command_name(cmd)}: MAV_RESULT_{RESULTS.get(result, result)}"
            + (f" ({hint})" if hint else ""))


def _pack(command: int, params, target_system: int, confirmation: int) -> dict:
    p = [float(x) for x in params] + [0.0] * (7 - len(params))
    return dict(target_system=target_system, target_component=0 if target_system == 0 else UNIT_COMPONENT,
                command=command, confirmation=confirmation, param1=p[0], param2=p[1], param3=p[2],
                param4=p[3], param5=p[4], param6=p[5], param7=p[6])


def _is_ack(command: int, sysid: int | None):
    return lambda f: (f.msgid == MSG_COMMAND_ACK and f.msg.command == command
                      and (sysid is None or f.sysid == sysid))


def drop_stale_acks(session, command: int) -> int:
    """Forget the COMMAND_ACKs for ``command`` received so far (an answer to an earlier command,
    e.g. a previous run's stop left in a pty's buffer, was taken for the answer to this one:
    a unit that dropped a wrongly signed start "accepted" it); the number dropped."""
    first = getattr(session.reader, "first_read", None)
    if first is not None:
        first.wait(1.0)     # a fresh connection: what waited at the open is read
    session.poll(0)
    frames = session.frames
    keep = [x for x in frames if not (x[1].msgid == MSG_COMMAND_ACK and x[1].msg.command == command)]
    n = len(frames) - len(keep)
    if n:
        frames.clear()
        frames.extend(keep)
    return n


def send_command(session, sysid: int, command: int, *params: float, timeout: float = 1.0,
                 retries: int = 3, check: bool = True) -> int:
    """Send to one unit and wait for its ACK (re-sent with confirmation+1 on timeout).

    Returns the MAV_RESULT; with ``check`` a refusal raises CommandError; no answer at all
    always raises CommandError (result None)."""
    drop_stale_acks(session, command)
    sent = {"n": 0}

    def ask():
        session.send("COMMAND_LONG", **_pack(command, params, sysid, sent["n"]))
        sent["n"] += 1
        return session.wait_for(_is_ack(command, sysid), timeout=timeout)

    sent_ns = time.monotonic_ns()
    f = None
    for _ in range(retries):
        f = ask()
        if f is not None:
            break
    text = (f"no COMMAND_ACK for {command_name(command)} from unit {sysid} "
            f"within {retries} x {timeout:g} s")
    if f is None:
        # a signed command the unit refused (dropped and counted) is told as such
        from kinefuse.host.link.signing import refused_text, unanswered_signed
        f, n = unanswered_signed(session, sysid, sent_ns, ask)
        if f is None:
            raise CommandError(f"{text}: {refused_text(n)}" if n else text, refused=n)
    r = int(f.msg.result)
    if check and r != 0:
        raise CommandError(refusal_text(sysid, command, r, session.encoder.key is not None), r)
    return r


def broadcast_command(session, command: int, *params: float, timeout: float = 1.0, retries: int = 2,
                      settle: float = 0.2, on_wait=None, refused: dict | None = None) -> dict:
    """Send to every unit on the connection (target 0); {sysid: MAV_RESULT} of the ACKs seen
    (empty: nobody answered).  After the first ACK, others are gathered for ``settle`` s.
    ``on_wait`` is called while waiting (the recorder keeps writing what arrives).

    ``refused`` (a dict, filled in): for a signed command, {sysid: n} of the units heard on the
    connection (SYS_STATUS) that did not answer and counted n more signature failures meanwhile
    (signing.unanswered_signed: e.g. after a power cut) -- so the caller tells a refused
    signature, not only "nobody answered"."""
    acks: dict = {}
    drop_stale_acks(session, command)
    sent_ns = time.monotonic_ns()
    sent = {"n": 0}

    def gather(only=None):
        session.send("COMMAND_LONG", **_pack(command, params, 0, sent["n"]))
        sent["n"] += 1
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            f = session.wait_for(_is_ack(command, None), timeout=min(0.05, max(0.0, deadline - time.monotonic())))
            if on_wait is not None:
                on_wait()
            if f is not None:
                acks.setdefault(f.sysid, int(f.msg.result))
                if only is None:
                    deadline = min(deadline, time.monotonic() + settle)
                elif f.sysid == only:
                    return f
        return None

    for _ in range(retries):
        gather()
        if acks:
            break
    if refused is not None and session.encoder.key is not None:
        from kinefuse.host.link.signing import MSG_SYS_STATUS, unanswered_signed
        session.poll(0)
        heard = sorted({f.sysid for _, f in session.frames if f.msgid == MSG_SYS_STATUS} - set(acks))
        for sysid in heard:
            # one more broadcast when no status from before tells the count (a fresh connection)
            f, n = unanswered_signed(session, sysid, sent_ns, lambda: gather(only=sysid))
            if f is None and n:
                refused[sysid] = n
    return acks
