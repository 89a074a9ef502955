"""Runtime helpers of generated code: C (kf_fixed.h, copied into firmware/generated/) and their
Python mirrors (q.py for fixed point, f32.py for binary32), one function for one function."""
from pathlib import Path

RUNTIME_DIR = Path(__file__).resolve().parent
