"""Parameter properties of the unit, through the harness (host build over a pty, real host
parameter client):

* random parameter writes, valid and invalid, never leave the unit misconfigured: a valid
  write is echoed, an invalid one is refused and the old value stays, and after a restart
  from storage the unit has exactly the last accepted values;
* a power cut after any number of stored bytes (``--storage-fail-after``) never corrupts the
  configuration: after the restart every parameter has its last accepted value, except the
  one being written at the cut, which has its old or its new value.

The firmware's own storage tests (``firmware/tests/test_app_storage.py``) cut power at every
byte in-process; these go through the real link and process boundary.
"""
from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from kinefuse.hil_tests.harness import firmware

pytestmark = pytest.mark.skipif(firmware.firmware_missing() is not None,
                                reason=str(firmware.firmware_missing()))

# name -> (valid values, invalid values); ranges from firmware/app/kf_params.h
FILTER_IDS = list(firmware.filter_ids().values()) if firmware.firmware_missing() is None else [3]
WRITES = {
    # invalid: ids no filter is wired to (6, listed here before, is eskf's), and out of range
    "KF_FILTER": (FILTER_IDS + [0], [i for i in (1, 7, 13) if i not in FILTER_IDS] + [99, 1000]),
    "KF_RATE_HZ": ([50, 100, 200, 500, 1000], [0, 100000]),
    # bits: 1 direct float32, 2 raw Q quaternion out (fixed-point builds only: refused on this f32 unit)
    "KF_HIL_MODE": ([0, 1], [2, 3, 4, 7]),
    "KF_ORI_RATE_HZ": ([0, 10, 50, 100], [100000]),
}
write = st.sampled_from(sorted(WRITES)).flatmap(
    lambda n: st.tuples(st.just(n), st.booleans()).flatmap(
        lambda t: st.tuples(st.just(t[0]), st.just(t[1]),
                            st.sampled_from(WRITES[t[0]][0] if t[1] else WRITES[t[0]][1]))))


def _unit(storage, extra=()):
    from kinefuse.firmware.hostunit import HostUnit
    return HostUnit("f32", sensor=False, storage=storage, extra=list(extra))


def _values(session, names):
    from kinefuse.host.link.params import ParamClient
    pc = ParamClient(session, 1, timeout=2.0)
    return {n: pc.get(n) for n in names}


@settings(max_examples=6, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(writes=st.lists(write, min_size=1, max_size=8))
def test_random_writes_never_misconfigure(tmp_path, writes):
    from kinefuse.host.link.params import ParamClient, ParamError
    store = tmp_path / f"unit-{abs(hash(tuple(writes)))}.storage"
    names = sorted(WRITES)
    with _unit(store) as u:
        s = u.session()
        pc = ParamClient(s, 1, timeout=2.0)
        expect = {n: pc.get(n) for n in names}
        for name, valid, value in writes:
            if valid:
                assert pc.set(name, value) == value
                expect[name] = value
            else:
                with pytest.raises(ParamError):
                    pc.set(name, value)
            assert pc.get(name) == expect[name]
    with _unit(store) as u:                    # power up again from the stored configuration
        assert _values(u.session(), names) == expect


@settings(max_examples=4, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(cut=st.integers(0, 3000), writes=st.lists(write.filter(lambda w: w[1]), min_size=2, max_size=6))
def test_power_cut_at_any_storage_byte(tmp_path, cut, writes):
    from kinefuse.host.link.params import ParamClient, ParamError
    from kinefuse.host.errors import KinefuseError
    store = tmp_path / f"unit-{cut}-{abs(hash(tuple(writes)))}.storage"
    names = sorted(WRITES)
    with _unit(store) as u:
        before = _values(u.session(), names)
    accepted = dict(before)
    pending = None
    with _unit(store, ["--storage-fail-after", str(cut)]) as u:
        pc = ParamClient(u.session(), 1, timeout=1.0, retries=1)
        for name, _valid, value in writes:
            pending = (name, accepted[name], value)
            try:
                pc.set(name, value)
            except (ParamError, KinefuseError, OSError):
                break                          # the unit lost power during this write
            if u.proc.poll() is not None:
                break
            accepted[name] = value
            pending = None
    with _unit(store) as u:
        after = _values(u.session(), names)
    for n in names:
        if pending is not None and n == pending[0]:
            assert after[n] in (pending[1], pending[2]), (n, after[n], pending)
        else:
            assert after[n] == accepted[n], (n, after[n], accepted[n], cut)
