"""Lazy exports: each public name of a package is imported from its module on first use (PEP 562).

A subpackage of gearlib declares what it offers in one table, ``EXPORTS``: each of its public
modules with the names that module defines, and old module names kept as aliases (a string
naming the module they stand for)::

    EXPORTS = {
        "fractionation": ("Fractionation", "kinematic_units"),
        "drawing": ("draw_units",),
        "unit_plot": "drawing",      # gl.unit_plot is gearlib.units.drawing
    }
    __getattr__, __dir__, __all__ = lazy(__name__, EXPORTS)

so that ``import gearlib.units`` imports nothing but this table, and ``gearlib.draw_units``
imports :mod:`gearlib.units.drawing` when it is first read. ``tests/test_layout.py`` checks
every table against the modules' own ``__all__``.
"""

from __future__ import annotations

import importlib
import sys

__all__ = ["lazy", "names_and_modules"]


def names_and_modules(exports: dict) -> tuple[dict, dict]:
    """``({name: module}, {public module name: module})`` from an ``EXPORTS`` table."""
    where: dict = {}
    modules: dict = {}
    for key, value in exports.items():
        if isinstance(value, str):
            modules[key] = value
            continue
        modules[key] = key
        for name in value:
            if name in where:
                raise RuntimeError(f"{name!r} is exported by both {where[name]!r} and {key!r}")
            where[name] = key
    return where, modules


def lazy(package: str, exports: dict):
    """``(__getattr__, __dir__, __all__)`` for *package* from its ``EXPORTS`` table."""
    where, modules = names_and_modules(exports)

    def __getattr__(name: str):
        if name in where:
            value = getattr(importlib.import_module(f"{package}.{where[name]}"), name)
        elif name in modules:
            value = importlib.import_module(f"{package}.{modules[name]}")
        else:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        setattr(sys.modules[package], name, value)  # next time, no lookup
        return value

    def __dir__():
        return sorted(set(vars(sys.modules[package])) | set(where) | set(modules))

    return __getattr__, __dir__, list(where) + [m for m in modules if m not in where]
