"""Errors a user can act on.  The command line prints them as one line, never a traceback."""


class KinefuseError(Exception):
    """A problem with the user's input, files or environment, described in one line."""


class UsageError(KinefuseError):
    """Bad command-line arguments."""
