"""Host side of the MAVLink parameter protocol for kinefuse units.

    client = ParamClient(session, target_system=1)
    params = client.fetch_all()           # {name: value}
    client.set("KF_RATE_HZ", 500)         # -> value echoed by the unit, or ParamError

Encoding: kinefuse units encode integer parameters bytewise in the float ``param_value``
(MAV_PROTOCOL_CAPABILITY_PARAM_ENCODE_BYTEWISE); REAL32 values are plain floats.  Limitation:
the host handles param_value as a Python float, so the few 32-bit integers whose bit pattern is a
signalling NaN (0x7F800001-0x7FBFFFFF, 0xFF800001-0xFFBFFFFF) would come back quietened.
Protocol (mavlink.io parameter service): PARAM_REQUEST_LIST streams every PARAM_VALUE; lost ones
are re-requested by index with PARAM_REQUEST_READ; PARAM_SET is answered with PARAM_VALUE (the new
value, or the unchanged one plus PARAM_ERROR when rejected) and re-sent on timeout.
Reads (PARAM_REQUEST_LIST, PARAM_REQUEST_READ) go unsigned even when the session has a key: a
keyed unit answers them (only writes need the signature), also right after a power cut and
whatever key the host has.  Writes (PARAM_SET) are signed with the session's key.
Signed requests that get no answer: when the unit counted them as signature failures (its
SYS_STATUS, :func:`kinefuse.host.link.signing.unanswered_signed`; e.g. after a power cut, until
the host's clock passes the unit's stored signing floor) the error says so (``refused``).
"""
from __future__ import annotations

import math
import struct
import time

from kinefuse.host.errors import KinefuseError

# MAV_PARAM_TYPE -> struct code of the integer held bytewise in param_value (REAL32 = 9: float)
INT_CODES = {1: "B", 2: "b", 3: "H", 4: "h", 5: "I", 6: "i"}
REAL32 = 9
TYPE_NAMES = {1: "UINT8", 2: "INT8", 3: "UINT16", 4: "INT16", 5: "UINT32", 6: "INT32", 9: "REAL32"}
UNIT_COMPONENT = 200


PERMISSION_DENIED = 3
# a unit whose sensor grants another rate than KF_RATE_HZ asks makes the granted rate KF_RATE_HZ
# and answers it (firmware/app/README.md, porting): applied, not refused
GRANTED_PARAMS = ("KF_RATE_HZ",)


class ParamError(KinefuseError):
    """A parameter could not be read or written (no answer, rejected, unknown name).

    ``code``: the unit's MAV_PARAM_ERROR when it sent one (3: permission denied -- a unit with
    a signing key refuses unsigned writes), else None."""

    def __init__(self, text: str, code: int | None = None, refused: int | None = None):
        super().__init__(text)
        self.code = code
        #: signed requests unanswered that the unit counted as signature failures (None: not that)
        self.refused = refused


def encode_value(value, ptype: int) -> float:
    """Value -> the float sent in param_value."""
    if ptype == REAL32:
        v = float(value)
        try:
            return struct.unpack("<f", struct.pack("<f", v))[0]
        except OverflowError:   # beyond float32 (about 3.4e38)
            raise ParamError(f"{value!r} is out of range for a REAL32 parameter") from None
    code = INT_CODES.get(ptype)
    if code is None:
        raise ParamError(f"parameter type {ptype} is not supported (8/16/32-bit integers, REAL32)")
    if not math.isfinite(float(value)):
        raise ParamError(f"{value!r} is not an integer ({TYPE_NAMES[ptype]} parameter)")
    iv = int(value)
    if float(value) != iv:
        raise ParamError(f"{value!r} is not an integer ({TYPE_NAMES[ptype]} parameter)")
    try:
        raw = struct.pack("<" + code, iv).ljust(4, b"\0")
    except struct.error:
        raise ParamError(f"{iv} is out of range for a {TYPE_NAMES[ptype]} parameter") from None
    return struct.unpack("<f", raw)[0]


def decode_value(param_value: float, ptype: int):
    """param_value -> int (bytewise) or float."""
    if ptype == REAL32 or ptype not in INT_CODES:
        return param_value
    raw = struct.pack("<f", param_value)
    code = INT_CODES[ptype]
    return struct.unpack_from("<" + code, raw)[0]


def same_value(a, b) -> bool:
    if isinstance(a, float) or isinstance(b, float):
        return a == b or (math.isnan(a) and math.isnan(b))
    return a == b


class ParamClient:
    """Parameter protocol over a :class:`~kinefuse.host.link.session.Session`."""

    def __init__(self, session, target_system: int, target_component: int = UNIT_COMPONENT,
                 timeout: float = 0.5, retries: int = 3):
        self.s = session
        self.sys, self.comp = target_system, target_component
        self.timeout, self.retries = timeout, retries
        self.types: dict[str, int] = {}
        #: name -> (value asked, value the unit applied instead) of GRANTED_PARAMS writes
        self.granted: dict[str, tuple] = {}

    def _from_unit(self, f) -> bool:
        return f.sysid == self.sys and (self.comp == 0 or f.compid == self.comp)

    def _read(self, message: str, **fields) -> None:
        """Send a read request unsigned (a keyed unit answers those; a signed one it refuses
        after a power cut until the host's clock passes its stored floor, or with another key)."""
        enc = getattr(self.s, "encoder", None)
        if enc is not None and enc.key is not None:
            self.s.send(message, signed=False, target_system=self.sys, target_component=self.comp, **fields)
        else:
            self.s.send(message, target_system=self.sys, target_component=self.comp, **fields)

    def _unanswered(self, text: str, sent_ns: int, again=None):
        """The ParamError for signed requests sent since ``sent_ns`` that got no answer: when the
        unit counted them as signature failures it says so (refused_text).  ``again``: one more
        attempt when that cannot be told otherwise (signing.unanswered_signed); its answer is
        returned instead of an error."""
        from kinefuse.host.link.signing import refused_text, unanswered_signed
        answer, n = unanswered_signed(self.s, self.sys, sent_ns, again)
        if answer is not None:
            return answer
        if n:
            return ParamError(f"{text}: {refused_text(n)}", refused=n)
        return ParamError(text)

    def fetch_all(self, timeout: float = 5.0) -> dict:
        """Every parameter of the unit: {name: value} (ints decoded bytewise)."""
        self._read("PARAM_REQUEST_LIST")
        values: dict[int, tuple[str, object]] = {}
        count = None
        deadline = time.monotonic() + timeout
        quiet_since = time.monotonic()
        while time.monotonic() < deadline:
            f = self.s.wait_for(lambda f: f.msgid == 22 and self._from_unit(f), timeout=self.timeout)
            if f is not None:
                m = f.msg
                count = m.param_count
                if not 0 <= m.param_index < count:
                    # e.g. an answer to a read by name (index 65535): it took the place of a
                    # parameter still missing, and the list came back short without a word
                    continue
                values[m.param_index] = (m.param_id, decode_value(m.param_value, m.param_type))
                self.types[m.param_id] = m.param_type
                quiet_since = time.monotonic()
                if len(values) >= count:
                    break
                continue
            if count is None:
                if time.monotonic() - quiet_since > self.timeout * self.retries:
                    # the list went unsigned: no refused signature to tell
                    raise ParamError(f"no PARAM_VALUE from system {self.sys} (is the unit connected "
                                     f"and powered?)")
                self._read("PARAM_REQUEST_LIST")
                continue
            for idx in range(count):  # re-request what was lost
                if idx not in values:
                    self._read("PARAM_REQUEST_READ", param_id="", param_index=idx)
        if count is None or len(values) < count:
            missing = "?" if count is None else count - len(values)
            raise ParamError(f"parameter list incomplete: {missing} of {count} parameters missing")
        return {name: v for _, (name, v) in sorted(values.items())}

    def get(self, name: str):
        def ask():
            self._read("PARAM_REQUEST_READ", param_id=name, param_index=-1)
            return self.s.wait_for(lambda f: f.msgid in (22, 345) and self._from_unit(f)
                                   and f.msg.param_id == name, timeout=self.timeout)
        f = None
        for _ in range(self.retries):
            f = ask()
            if f is not None:
                break
        if f is None:       # an unsigned read: not a refused signature
            raise ParamError(f"no answer for parameter {name} from system {self.sys}")
        if f.msgid == 345:
            raise ParamError(f"{name}: {_error_text(f.msg.error)}", int(f.msg.error))
        self.types[name] = f.msg.param_type
        return decode_value(f.msg.param_value, f.msg.param_type)

    def set(self, name: str, value, ptype: int | None = None):
        """Write a parameter; returns the value the unit echoes.  Raises ParamError if rejected.

        A GRANTED_PARAMS write answered with another value was applied with the value the
        hardware gives (KF_RATE_HZ: the sensor's granted rate): that value is returned and
        ``granted[name]`` says so (it was reported as "rejected: the unit kept 500")."""
        if len(name.encode()) > 16:
            raise ParamError(f"parameter name {name!r} is longer than 16 characters")
        if ptype is None:
            ptype = self.types.get(name)
            if ptype is None:
                self.get(name)
                ptype = self.types[name]
        wire = encode_value(value, ptype)
        want = decode_value(wire, ptype)
        self.granted.pop(name, None)
        kept = None

        def ask():
            self.s.send("PARAM_SET", target_system=self.sys, target_component=self.comp,
                        param_id=name, param_value=wire, param_type=ptype)
            return self.s.wait_for(lambda f: f.msgid in (22, 345) and self._from_unit(f)
                                   and f.msg.param_id == name, timeout=self.timeout)

        def rejected(f):
            self.s.wait_for(lambda f: f.msgid == 22 and f.msg.param_id == name, timeout=self.timeout)
            return ParamError(f"{name} = {value!r} rejected: {_error_text(f.msg.error)}", int(f.msg.error))

        sent_ns = time.monotonic_ns()
        for _ in range(self.retries):
            f = ask()
            if f is None:
                continue
            if f.msgid == 345:
                raise rejected(f)
            got = decode_value(f.msg.param_value, f.msg.param_type)
            if same_value(got, want):
                return got
            # A unit refuses a write by echoing the value it kept, but a slow link can also
            # deliver a late answer to an earlier read here: wait until the parameter goes
            # quiet and ask again; only an answer after the quiet period decides.
            kept = got
            while self.s.wait_for(lambda f: f.msgid == 22 and self._from_unit(f)
                                  and f.msg.param_id == name, timeout=min(self.timeout, 0.3)):
                pass
        if kept is None:
            # no answer at all: a signed write the unit refused is told as such
            f = self._unanswered(f"no answer to PARAM_SET {name} from system {self.sys}", sent_ns, ask)
            if isinstance(f, ParamError):
                raise f
            if f.msgid == 345:
                raise rejected(f)
            kept = decode_value(f.msg.param_value, f.msg.param_type)
            if same_value(kept, want):
                return kept
        if name in GRANTED_PARAMS:
            self.granted[name] = (want, kept)
            return kept
        raise ParamError(f"{name} = {value!r} rejected: the unit kept {kept!r}")


def _error_text(code: int) -> str:
    return {1: "no such parameter", 2: "value out of range", 3: "permission denied",
            4: "component not found", 5: "read-only parameter"}.get(code, f"error {code}")
