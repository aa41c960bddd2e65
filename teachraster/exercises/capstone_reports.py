"""An exercise's own report on a function the capstone plugged in, run once per function.

Both the capstone's explanations (:mod:`.capstone_explain`) and its texture filters on the
student's ``texel_weights`` (:mod:`.capstone_texels`) ask for it; it lives here so neither
imports the other.
"""

from __future__ import annotations

import warnings
from functools import lru_cache

from . import output


def own_report(checked: str, fn):
    """Exercise ``checked``'s report on ``fn`` (run once per function: cached where ``fn``
    can be hashed), its output and warnings kept aside (the scene showed them)."""
    try:
        return _own_report(checked, fn)
    except TypeError:  # an unhashable callable: no cache
        return _own_report.__wrapped__(checked, fn)


@lru_cache(maxsize=32)
def _own_report(checked: str, fn):
    from .checks import check

    with output.captured(), warnings.catch_warnings():  # a second run: its warnings were shown
        warnings.simplefilter("ignore")
        return check(checked, fn)
