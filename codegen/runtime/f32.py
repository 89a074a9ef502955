"""Python mirror of the few library calls binary32 generated code makes (sqrtf, fabsf) and of
kf_inc_if, for numpy float32 scalars and (``*_v``) arrays."""
from __future__ import annotations

import numpy as np

from kinefuse.codegen.runtime.q import kf_inc_if  # noqa: F401  (identical integer semantics)

sqrtf = np.sqrt          # correctly rounded, like sqrtf
sqrtf_v = np.sqrt
fabsf = abs              # exact
fabsf_v = np.abs
