"""Reading and writing linkages as YAML or JSON, and the catalogue of the book's linkages.

Catalogue entries are YAML files in ``gearlib/linkages/data/`` (copy one to start your own):
``laus_slider_crank`` (the thesis' RRRP slider-crank, section 4.2) and ``laus_3upu`` (its
3-UPU parallel robot with Coulomb friction, section 4.3), each with the thesis' dimensions,
named ``parameters`` and tasks.

>>> import gearlib as gl
>>> gl.linkages.names()
['laus_3upu', 'laus_slider_crank']
>>> robot = gl.linkages.load("laus_3upu")
>>> robot.dof, [t.name for t in robot.tasks]
(3, ['lift', 'lift_half', 'ellipse'])
"""

from __future__ import annotations

import json
import pathlib
from collections.abc import Mapping

import yaml

from ..errors import FileFormatError, GearlibError, UnknownLinkError
from .data import Linkage

__all__ = ["load", "loads", "save", "names", "path", "read_data"]

DATA = pathlib.Path(__file__).with_name("data")


def names() -> list[str]:
    """Names of the catalogue's linkages."""
    return sorted(p.stem for p in DATA.glob("*.yaml"))


def path(name: str) -> pathlib.Path:
    """The YAML file of catalogue entry *name*."""
    p = DATA / f"{name}.yaml"
    if not p.exists():
        raise UnknownLinkError(f"no catalogue linkage {name!r}; entries are {', '.join(names())}")
    return p


def read_data(text: str, where: str = "<text>") -> dict:
    """The mapping in a YAML or JSON text, or a clear error."""
    if not text.strip():
        raise FileFormatError(f"{where}: the file is empty; it should describe a linkage (links, joints, ...)")
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as err:
        mark = getattr(err, "problem_mark", None)
        at = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        raise FileFormatError(f"{where}: not valid YAML or JSON{at}: {getattr(err, 'problem', None) or 'syntax'}") \
            from None
    if not isinstance(data, Mapping):
        raise FileFormatError(f"{where}: the top level must be a mapping with `links`, `joints`, ...; found "
                              f"{type(data).__name__}")
    return dict(data)


def loads(text: str, *, where: str = "<text>", parameters: Mapping | None = None) -> Linkage:
    """A linkage from YAML or JSON text; *parameters* override the file's ``parameters``."""
    data = read_data(text, where)
    if parameters:
        data["parameters"] = {**(data.get("parameters") or {}), **parameters}
    try:
        return Linkage.from_dict(data)
    except GearlibError as err:
        raise type(err)(f"{where}: {err}") from None
    except (TypeError, ValueError, AttributeError) as err:  # a malformed value deep in the data
        raise FileFormatError(f"{where}: cannot read the linkage ({err})") from None


def load(source, *, parameters: Mapping | None = None) -> Linkage:
    """A linkage from a ``.yaml``/``.yml``/``.json`` file, or the catalogue entry of that name;
    *parameters* override the file's."""
    p = pathlib.Path(source)
    if isinstance(source, str) and not p.suffix and "/" not in source and not p.exists():
        if source in names():
            return loads(path(source).read_text(encoding="utf-8"), where=source, parameters=parameters)
        raise FileFormatError(f"{source}: no such file, and no catalogue linkage of that name (entries: "
                              f"{', '.join(names())})")
    if not p.exists():
        raise FileFormatError(f"{p}: no such file")
    if p.is_dir():
        raise FileFormatError(f"{p}: is a directory, not a linkage file")
    try:
        text = p.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise FileFormatError(f"{p}: not a text file (expected YAML or JSON)") from None
    return loads(text, where=str(p), parameters=parameters)


def save(linkage: Linkage, target) -> None:
    """Write *linkage* to a file: JSON when the name ends in ``.json``, else YAML."""
    target = pathlib.Path(target)
    data = linkage.to_dict()
    if target.suffix.lower() == ".json":
        target.write_text(json.dumps(data, indent=2, default=str) + "\n", encoding="utf-8")
    else:
        target.write_text(yaml.safe_dump(data, sort_keys=False, allow_unicode=True), encoding="utf-8")
