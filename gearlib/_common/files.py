"""Reading a data file (a mechanism, a list of bearings) safely, in bounded time and memory.

Only a regular file is read (a FIFO would wait for a writer forever, ``/dev/zero`` never
ends), at most :data:`MAX_BYTES` of it. The text is parsed as JSON when it looks like JSON
(fast, for files of 100,000 links) and as YAML otherwise, with the C parser when PyYAML has
it. Whatever the syntax, a key given twice in one mapping is an error (YAML and JSON keep
the last one silently), aliases may not expand the data beyond :data:`MAX_NODES` values (an
"alias bomb" of a few lines would otherwise fill the memory), and nesting stops at
:data:`MAX_DEPTH`. Every error is a :class:`~gearlib.FileFormatError` whose message starts
with the file's name.
"""

from __future__ import annotations

import errno
import itertools
import json
import os
import pathlib
import re
import stat

import yaml

from ..errors import FileFormatError

__all__ = ["read_text", "parse_text", "MAX_BYTES", "MAX_NODES", "MAX_DEPTH"]

MAX_BYTES = 64 * 2**20   # 64 MiB: a 100,000-link mechanism takes about 10 MiB of JSON
MAX_NODES = 5_000_000    # values after expanding YAML aliases
MAX_DEPTH = 60           # nesting of lists and mappings (a mechanism needs 4)

_Base = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


class _Loader(_Base):
    """PyYAML's safe loader, refusing a key given twice in one mapping, with the resolution of
    plain scalars (``20``, ``a``, ``external``) remembered: a file of 100,000 gear pairs repeats
    a few hundred values a million times, and resolving each costs a regular expression."""

    def __init__(self, stream):
        super().__init__(stream)
        self._resolved: dict = {}

    def resolve(self, kind, value, implicit):
        if kind is not yaml.ScalarNode or len(value) > 40:
            return super().resolve(kind, value, implicit)
        key = (value, implicit)
        tag = self._resolved.get(key)
        if tag is None:
            tag = self._resolved[key] = super().resolve(kind, value, implicit)
        return tag

    def construct_mapping(self, node, deep=False):
        if any(k.tag == "tag:yaml.org,2002:merge" for k, _ in node.value):  # `<<: *base`: PyYAML's own way
            _duplicates(self, node, deep)
            return super().construct_mapping(node, deep=deep)
        mapping = {}
        for key_node, value_node in node.value:
            key = self.construct_object(key_node, deep=deep)
            try:
                seen = key in mapping
            except TypeError:
                raise FileFormatError(f"a mapping key must be a plain value, not {type(key).__name__} "
                                      f"(line {key_node.start_mark.line + 1})") from None
            if seen:
                raise FileFormatError(f"the key {key!r} is given twice in one mapping "
                                      f"(line {key_node.start_mark.line + 1}); keep one")
            mapping[key] = self.construct_object(value_node, deep=deep)
        return mapping


def _duplicates(loader, node, deep):
    seen = set()
    for key_node, _ in node.value:
        if key_node.tag == "tag:yaml.org,2002:merge":
            continue
        key = loader.construct_object(key_node, deep=deep)
        try:
            if key in seen:
                raise FileFormatError(f"the key {key!r} is given twice in one mapping "
                                      f"(line {key_node.start_mark.line + 1}); keep one")
            seen.add(key)
        except TypeError:
            return


def read_text(path, what: str = "file") -> tuple[pathlib.Path, str]:
    """``(path, text)`` of a regular UTF-8 file no larger than :data:`MAX_BYTES`."""
    if path is None or isinstance(path, bool) or not isinstance(path, (str, os.PathLike)):
        raise FileFormatError(f"{what}: expected a file name (a str or pathlib.Path), got "
                              f"{'None' if path is None else type(path).__name__}")
    if isinstance(path, str) and not path.strip():
        raise FileFormatError(f"{what}: the file name is empty")
    path = pathlib.Path(path)
    try:
        st = os.stat(path)
    except OSError as err:
        if err.errno == errno.ELOOP:
            raise FileFormatError(f"{path}: a symbolic link that loops back on itself") from None
        if err.errno in (errno.ENOENT, errno.ENOTDIR):
            raise FileFormatError(f"{path}: no such file") from None
        raise FileFormatError(f"{path}: cannot be read ({err.strerror})") from None
    if stat.S_ISDIR(st.st_mode):
        raise FileFormatError(f"{path}: is a directory, not a {what}")
    if not stat.S_ISREG(st.st_mode):
        kind = "a named pipe (FIFO)" if stat.S_ISFIFO(st.st_mode) else \
            "a device" if stat.S_ISCHR(st.st_mode) or stat.S_ISBLK(st.st_mode) else "not a regular file"
        raise FileFormatError(f"{path}: is {kind}; give a YAML or JSON file saved on disk")
    if st.st_size > MAX_BYTES:
        raise FileFormatError(f"{path}: is {st.st_size / 2**20:.0f} MiB; a {what} of more than "
                              f"{MAX_BYTES // 2**20} MiB is refused (is it the right file?)")
    try:
        with open(path, "rb") as f:
            raw = f.read(MAX_BYTES + 1)
    except OSError as err:
        raise FileFormatError(f"{path}: cannot be read ({err.strerror})") from None
    if len(raw) > MAX_BYTES:
        raise FileFormatError(f"{path}: is larger than {MAX_BYTES // 2**20} MiB; refused")
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise FileFormatError(f"{path}: not a text file (expected YAML or JSON in UTF-8)") from None
    return path, text


def _json_pairs(pairs):
    out = {}
    for k, v in pairs:
        if k in out:
            raise FileFormatError(f"the key {k!r} is given twice in one mapping; keep one")
        out[k] = v
    return out


_BRACKETS = re.compile(r"[^\[\]{}]+")
_BLOCK_RUN = re.compile(r"^[ \t?:-]{2000,}", re.M)


def _too_deep(text: str) -> bool:
    """Nesting far beyond :data:`MAX_DEPTH`, found before parsing: PyYAML's C parser recurses
    once per level and crashes the interpreter on about 100,000 levels."""
    brackets = _BRACKETS.sub("", text)
    if len(brackets) > MAX_DEPTH:
        depth = max(itertools.accumulate(1 if c in "[{" else -1 for c in brackets))
        if depth > MAX_DEPTH:
            return True
    return _BLOCK_RUN.search(text) is not None  # block nesting needs a character per level


def parse_text(text: str, where: str):
    """The data in *text* (JSON or YAML), checked for duplicate keys, alias expansion and nesting."""
    if _too_deep(text):
        raise FileFormatError(f"{where}: nested more than {MAX_DEPTH} levels deep; a mechanism needs 4")
    stripped = text.lstrip()
    data, parsed = None, False
    try:
        if stripped[:1] in ("{", "["):
            try:
                data, parsed = json.loads(text, object_pairs_hook=_json_pairs), True
            except ValueError as err:  # not JSON after all (or broken): YAML says where
                if isinstance(err, FileFormatError):
                    raise
        if not parsed:
            data = yaml.load(text, Loader=_Loader)  # noqa: S506 - a SafeLoader subclass
    except FileFormatError as err:
        raise FileFormatError(f"{where}: {err}") from None
    except yaml.YAMLError as err:
        mark = getattr(err, "problem_mark", None)
        at = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        problem = getattr(err, "problem", None) or "invalid syntax"
        raise FileFormatError(f"{where}: not valid YAML or JSON{at}: {problem}") from None
    except RecursionError:
        raise FileFormatError(f"{where}: nested more than {MAX_DEPTH} levels deep; a mechanism needs 4") from None
    except ValueError as err:  # Python refuses to read an integer of more than 4300 digits
        why = "a number has thousands of digits" if "digits" in str(err) else " ".join(str(err).split())[:200]
        raise FileFormatError(f"{where}: cannot be read: {why}") from None
    if not parsed and "&" in text and "*" in text:  # YAML anchors and aliases: shared parts to count
        check_size(data, where)
    return data


def check_size(data, where: str) -> None:
    """Refuse data whose aliases expand beyond :data:`MAX_NODES` values or that nests deeper
    than :data:`MAX_DEPTH` (shared objects are counted once per use, without expanding them)."""
    size: dict = {}
    stack = [(data, 0, False)]
    on_path: set = set()
    while stack:
        node, depth, done = stack.pop()
        if not isinstance(node, (list, dict)):
            continue
        key = id(node)
        if done:
            children = node.values() if isinstance(node, dict) else node
            total = 1 + sum(size.get(id(c), 1) for c in children)
            if isinstance(node, dict):
                total += len(node)
            size[key] = total
            on_path.discard(key)
            if total > MAX_NODES:
                raise FileFormatError(f"{where}: its aliases expand to more than {MAX_NODES:,} values "
                                      "(an alias bomb?); write the data out")
            continue
        if key in size:
            continue
        if key in on_path:
            raise FileFormatError(f"{where}: an alias refers to the value that contains it (a cycle)")
        if depth > MAX_DEPTH:
            raise FileFormatError(f"{where}: nested more than {MAX_DEPTH} levels deep; a mechanism needs 4")
        on_path.add(key)
        stack.append((node, depth, True))
        for child in (node.values() if isinstance(node, dict) else node):
            stack.append((child, depth + 1, False))
