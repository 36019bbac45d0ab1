"""Reading and writing mechanisms as YAML or JSON files.

>>> import gearlib as gl, tempfile, pathlib
>>> m = gl.catalog.simple_planetary(sun=24, ring=60)
>>> path = pathlib.Path(tempfile.mkdtemp()) / "planetary.yaml"
>>> gl.save(m, path)
>>> gl.load(path) == m
True
"""

from __future__ import annotations

import json
import pathlib

import yaml

from ..errors import FileFormatError, MechanismError
from .assembly import check_assembly
from .data import Mechanism

__all__ = ["load", "save", "loads"]


def loads(text: str, *, where: str = "<text>") -> Mechanism:
    """Parse a mechanism from YAML (or JSON, which is valid YAML) text. A planetary set that
    cannot be assembled as given is reported with a :class:`gearlib.AssemblyWarning`
    (:func:`gearlib.assembly_conditions`), not refused."""
    if not text.strip():
        raise FileFormatError(f"{where}: the file is empty; it should describe a mechanism (links, gear_pairs, ...)")
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as err:
        mark = getattr(err, "problem_mark", None)
        at = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        problem = getattr(err, "problem", None) or "invalid syntax"
        raise FileFormatError(f"{where}: not valid YAML or JSON{at}: {problem}") from None
    if not isinstance(data, dict):
        raise FileFormatError(
            f"{where}: the top level must be a mapping with `links`, `turning_pairs`, `gear_pairs`; "
            f"found {type(data).__name__}"
        )
    try:
        mech = Mechanism.from_dict(data)
    except MechanismError as err:
        raise type(err)(f"{where}: {err}") from None
    check_assembly(mech, where=where, stacklevel=3)
    return mech


def load(path) -> Mechanism:
    """Read a mechanism from a ``.yaml``, ``.yml`` or ``.json`` file."""
    path = pathlib.Path(path)
    if not path.exists():
        raise FileFormatError(f"{path}: no such file")
    if path.is_dir():
        raise FileFormatError(f"{path}: is a directory, not a mechanism file")
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise FileFormatError(f"{path}: not a text file (expected YAML or JSON)") from None
    return loads(text, where=str(path))


def save(mech: Mechanism, path) -> None:
    """Write *mech* to *path*; JSON when the name ends in ``.json``, else YAML."""
    path = pathlib.Path(path)
    data = mech.to_dict()
    if path.suffix.lower() == ".json":
        text = json.dumps(_jsonable(data), indent=2) + "\n"
    else:
        text = yaml.safe_dump(data, sort_keys=False, allow_unicode=True)
    path.write_text(text, encoding="utf-8")


def _jsonable(data):
    if isinstance(data, dict):
        return {str(k): _jsonable(v) for k, v in data.items()}
    if isinstance(data, (list, tuple)):
        return [_jsonable(v) for v in data]
    return data
