"""C sources used by :mod:`kinefuse.hil_tests.qemu` (TCG plugin, program drivers)."""
