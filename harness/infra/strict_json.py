"""Strict JSON (RFC 8259) for every --json output and JSON file: NaN and infinities become null."""
import json
import math

import numpy as np


def plain(value):
    """`value` with every non-finite float as None and numpy scalars and arrays as Python's."""
    if isinstance(value, dict):
        return {k: plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return plain(value.tolist())
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def dumps(value, **keywords):
    """json.dumps of `value` made plain; anything else unknown as its str (default=str), never NaN."""
    return json.dumps(plain(value), allow_nan=False, default=keywords.pop("default", str), **keywords)
