"""gearlib: the library behind the open textbook on geared mechanisms.

Use it as ``import gearlib as gl``. Mechanisms are validated, immutable data
(:class:`Mechanism`, loadable with :func:`load` or from :mod:`gearlib.catalog`); analyses
are functions of a mechanism (:func:`speeds`, :func:`ratio`, :func:`dof`, ...); drawings take
``ax=``; exercise checks live in :mod:`gearlib.check`, the command line in :mod:`gearlib.cli`.

One subpackage per method of the book, each with its computations, drawings and widgets:

=======  ==========================  =============================================
chapter  subpackage                  method (paper)
=======  ==========================  =============================================
0, 1     :mod:`gearlib.mechanism`    data, graph, Willis equations, speeds, dof
2        :mod:`gearlib.units`        kinematic units (Liu, Chen and Chang)
3        :mod:`gearlib.gains`        unit-by-unit gains (Liu, Chen and Chang; Chen)
4        :mod:`gearlib.adjacency`    complex adjacency matrix (Penaud and Alazard)
5        :mod:`gearlib.davies`       Davies' method, efficiency (Laus)
6        :mod:`gearlib.synthesis`    differential synthesis, atlas (Chen, Yao and Lee)
7        :mod:`gearlib.linkages`     Davies' method for linkages and robots (Laus)
=======  ==========================  =============================================

Each subpackage lists its public names by module (``EXPORTS``) and the ones offered here as
``gl.<name>`` (``TOP``); every module loads on first use (PEP 562), so ``import gearlib``
stays quick and a reader who never draws never imports matplotlib. Importing gearlib changes
no global state (matplotlib settings, numpy print options, random generators).

>>> import gearlib as gl
>>> m = gl.catalog.simple_planetary(sun=24, ring=60)
>>> gl.ratio(m, output=4, input=1, ground=3)
Fraction(2, 7)
"""

import importlib

from . import errors as _errors

__version__ = "0.1.0"

# the methods of the book, in the order of its chapters
_METHODS = ("mechanism", "units", "gains", "adjacency", "davies", "synthesis", "linkages")
_PACKAGES = (*_METHODS, "catalog", "check", "cli")
_where: dict = {}


def _top_level() -> dict:
    """``{name: subpackage}`` for every ``gl.<name>``, from each method's ``TOP`` list (read on
    first use: each subpackage's ``__init__`` holds only its tables)."""
    if not _where:
        for short in _METHODS:
            pkg = importlib.import_module(f".{short}", __name__)
            for name in pkg.TOP:
                if name in _where or name in _PACKAGES:
                    raise RuntimeError(f"gl.{name} is offered twice (by {pkg.__name__})")
                _where[name] = pkg
    return _where


def __getattr__(name: str):
    if name == "__all__":
        value = [*_METHODS, "catalog", "check", *_top_level(), *_errors.__all__]
    elif name in _errors.__all__:
        value = getattr(_errors, name)
    elif name in _PACKAGES:
        value = importlib.import_module(f".{name}", __name__)
    elif name in _top_level():
        value = getattr(_where[name], name)
    else:
        raise AttributeError(f"module 'gearlib' has no attribute {name!r}")
    globals()[name] = value  # next time, no lookup
    return value


def __dir__():
    return sorted(set(globals()) | set(_top_level()) | set(_PACKAGES) | set(_errors.__all__))
