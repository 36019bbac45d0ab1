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
import os
import pathlib

import yaml

from .._common.files import parse_text, read_text
from ..errors import FileFormatError, MechanismError
from .assembly import check_assembly
from .data import Mechanism, not_a_mechanism

__all__ = ["load", "save", "loads"]


def loads(text: str, *, where: str = "<text>") -> Mechanism:
    """Parse a mechanism from YAML (or JSON, which is valid YAML) text. A planetary set that
    cannot be assembled as given is reported with a :class:`gearlib.AssemblyWarning`
    (:func:`gearlib.assembly_conditions`), not refused."""
    if isinstance(text, (bytes, bytearray)):
        try:
            text = bytes(text).decode("utf-8-sig")
        except UnicodeDecodeError:
            raise FileFormatError(f"{where}: not UTF-8 text (expected YAML or JSON)") from None
    if not isinstance(text, str):
        hint = " (it is already a Mechanism)" if isinstance(text, Mechanism) else \
            " (for a file name use gl.load(path))" if isinstance(text, pathlib.PurePath) else ""
        raise FileFormatError(f"{where}: expected the text of a mechanism (YAML or JSON), got "
                              f"{'None' if text is None else type(text).__name__}{hint}")
    if not text.strip():
        raise FileFormatError(f"{where}: the file is empty; it should describe a mechanism (links, gear_pairs, ...)")
    data = parse_text(text, where)
    if not isinstance(data, dict):
        raise FileFormatError(
            f"{where}: the top level must be a mapping with `links`, `turning_pairs`, `gear_pairs`; "
            f"found {type(data).__name__}"
        )
    try:
        mech = Mechanism.from_dict(data)
    except MechanismError as err:
        raise type(err)(f"{where}: {err}") from None
    except RecursionError:
        raise FileFormatError(f"{where}: nested too deeply to be a mechanism") from None
    check_assembly(mech, where=where, stacklevel=3)
    return mech


def load(path) -> Mechanism:
    """Read a mechanism from a ``.yaml``, ``.yml`` or ``.json`` file."""
    if isinstance(path, Mechanism):
        raise FileFormatError("gl.load: this is already a Mechanism; gl.load reads a file name")
    path, text = read_text(path, "mechanism file")
    return loads(text, where=str(path))


def save(mech: Mechanism, path) -> None:
    """Write *mech* to *path*; JSON when the name ends in ``.json``, else YAML."""
    if not isinstance(mech, Mechanism):
        raise not_a_mechanism(mech)
    if path is None or isinstance(path, bool) or not isinstance(path, (str, os.PathLike)):
        raise FileFormatError(f"gl.save: expected a file name (a str or pathlib.Path), got {type(path).__name__}")
    path = pathlib.Path(path)
    data = mech.to_dict()
    if path.suffix.lower() == ".json":
        text = json.dumps(_jsonable(data), indent=2) + "\n"
    else:
        text = yaml.safe_dump(data, sort_keys=False, allow_unicode=True)
    try:
        path.write_text(text, encoding="utf-8")
    except OSError as err:
        raise FileFormatError(f"{path}: cannot be written ({err.strerror})") from None


def _jsonable(data):
    if isinstance(data, dict):
        return {str(k): _jsonable(v) for k, v in data.items()}
    if isinstance(data, (list, tuple)):
        return [_jsonable(v) for v in data]
    return data
