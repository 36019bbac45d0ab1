"""The mechanism argument of every public function: a :class:`Mechanism`, or where the intent
is plain a catalogue name or a mechanism file; anything else is a :class:`DataFormatError`
that names the argument and what it accepts (not an ``AttributeError`` deep inside).

>>> import gearlib as gl
>>> int(gl.dof("simple_planetary"))       # a catalogue name stands for its mechanism
1
>>> gl.dof(None)
Traceback (most recent call last):
...
gearlib.errors.DataFormatError: mech: expected a Mechanism (gl.load('file.yaml'), gl.catalog.load('name')) or a catalogue name; got None
"""

from __future__ import annotations

import functools
import os
import pathlib
import re
from functools import wraps

from ..errors import DataFormatError, UnknownLinkError
from .data import Mechanism, not_a_mechanism

__all__ = ["as_mechanism", "takes_mechanism", "catalogue_names", "catalogue_path", "load_catalogue"]

CATALOGUE = pathlib.Path(__file__).resolve().parents[1] / "catalog" / "data"
"""Where the catalogue's YAML files live (:mod:`gearlib.catalog` reads them through here)."""
_ENTRY = re.compile(r"^[A-Za-z0-9_][A-Za-z0-9_.-]{0,80}$")

_FILE_SUFFIXES = (".yaml", ".yml", ".json")


def _shown(obj) -> str:
    if obj is None or isinstance(obj, (bool, int, float)):
        return repr(obj)
    if isinstance(obj, str):
        return repr(obj if len(obj) <= 60 else obj[:57] + "...")
    return f"a {type(obj).__name__}"


@functools.cache
def catalogue_names() -> tuple:
    """Names of every catalogue entry (the YAML file names without ``.yaml``), sorted."""
    return tuple(sorted(p.stem for p in CATALOGUE.glob("*.yaml")))


def catalogue_path(name) -> pathlib.Path:
    """The YAML file of catalogue entry *name*; a name is a file name of the catalogue, never a
    path (``../`` cannot climb out of it)."""
    if not isinstance(name, str) or not _ENTRY.match(name) or name not in catalogue_names():
        shown = _shown(name) if not isinstance(name, str) else repr(name[:60])
        raise UnknownLinkError(f"no catalogue entry {shown}; entries are {', '.join(catalogue_names())}")
    return CATALOGUE / f"{name}.yaml"


@functools.cache
def _load_entry(name: str) -> Mechanism:
    from .io import load

    return load(catalogue_path(name))


def load_catalogue(name) -> Mechanism:
    """The catalogue mechanism *name* (read once, then the same object)."""
    catalogue_path(name)  # the name checked before it is cached
    return _load_entry(name)


def as_mechanism(obj, what: str = "mech") -> Mechanism:
    """*obj* as a :class:`Mechanism`: itself, a catalogue entry by name, or a ``.yaml``/``.json``
    file given as a path."""
    if isinstance(obj, Mechanism):
        return obj
    if isinstance(obj, str) and obj in catalogue_names():
        return load_catalogue(obj)
    if isinstance(obj, (str, os.PathLike)) and str(obj).lower().endswith(_FILE_SUFFIXES):
        from .io import load

        return load(pathlib.Path(obj))
    if isinstance(obj, str):
        raise DataFormatError(
            f"{what}: {_shown(obj)} is neither a catalogue name (gl.catalog.names()) nor a .yaml/.json file; "
            "give a Mechanism, a catalogue name or a file")
    raise not_a_mechanism(obj, what)


def takes_mechanism(fn):
    """Decorator: the function's first parameter is a mechanism, read by :func:`as_mechanism`."""
    name = fn.__code__.co_varnames[0]

    @wraps(fn)
    def wrapper(*args, **kwargs):
        if args:
            if type(args[0]) is not Mechanism:
                args = (as_mechanism(args[0], name), *args[1:])
        elif name in kwargs and type(kwargs[name]) is not Mechanism:
            kwargs[name] = as_mechanism(kwargs[name], name)
        return fn(*args, **kwargs)

    return wrapper
