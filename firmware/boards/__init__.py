"""Board ports: C sources implementing ``firmware/app/kf_hal.h`` for each board.

Only data lives here (C, headers, linker scripts); :mod:`kinefuse.firmware.targets` knows which
files make up a board and how to build for it.
"""
