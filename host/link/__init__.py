"""The host side of the kinefuse MAVLink 2 link.

- ``dialect``     the generated pymavlink module of ``firmware/mavlink/kinefuse.xml``
- ``regen``       regenerates the C headers and the Python module (``--check`` for CI)
- ``decoder``     streaming decoder (resumes one byte after a bad candidate, never raises)
- ``batch``       numpy batch decoder for one message type (CRC-checked structured arrays)
- ``connection``  serial / pty / TCP / UDP / file connections with a reader thread
- ``recording``   the ``.kfr`` raw-stream recording format (writer and reader)
- ``export``, ``stats``, ``params``: CSV export, link statistics, parameter protocol
- ``fakeunit``    a small simulated unit speaking the dialect (tests, demos, harness)
"""
