"""Bit-exact Python models of the generated C."""
