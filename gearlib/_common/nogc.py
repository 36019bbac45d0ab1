"""Pause Python's cyclic garbage collector while a large structure is built.

Building the plan of a train with thousands of gear pairs allocates hundreds of thousands of
small containers that all stay alive. Once they outnumber a quarter of everything already
on the heap (numpy, sympy, matplotlib...), CPython starts full collections, each of which
walks the whole heap and finds nothing to free: above about 5,000 pairs that doubled the
time per pair. The collector is paused only for the call and restored as it was (the same
idiom as Mercurial's ``util.nogc``); garbage made meanwhile is collected later as usual.
"""

from __future__ import annotations

import gc
from contextlib import contextmanager
from functools import wraps

__all__ = ["paused_gc", "no_gc"]


@contextmanager
def paused_gc():
    """Disable the cyclic collector inside the block; re-enable it only if it was enabled.

    >>> import gc
    >>> with paused_gc():
    ...     gc.isenabled()
    False
    >>> gc.isenabled()
    True
    """
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def no_gc(fn):
    """Decorator: run *fn* with the cyclic collector paused (:func:`paused_gc`)."""
    @wraps(fn)
    def wrapper(*args, **kwargs):
        with paused_gc():
            return fn(*args, **kwargs)
    return wrapper
