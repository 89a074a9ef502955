"""The simulator's user-facing error: one line, shown by the CLI without a traceback."""
from kinefuse.host.errors import KinefuseError


class SpecError(KinefuseError, ValueError):
    """A scenario/segment description is invalid (message is one line)."""
