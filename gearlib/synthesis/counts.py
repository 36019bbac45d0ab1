"""How many geared kinematic chains there are: the enumeration's counts beside the literature's.

:func:`chain_counts` counts the chains that :func:`~gearlib.synthesis.atlas.geared_chains`
enumerates, at both levels, without building them as mechanisms; that takes it one link
further, to nine links:

* the *coaxial* level counts **displacement graphs**: chains that differ only in which links
  share an axis (their coaxiality pattern) count as different;
* the *kinematic* level counts **rotation graphs**: only the gear pairs and their carriers
  count (the Willis equations), so the displacement graphs of one rotation graph, which
  differ only in their coaxiality, count once.

Nine links take about a minute, too long to run while the book is built, so the nine-link
counts are stored with how they were made (:func:`stored_counts`; ``make bench`` makes them
again and compares them with the published ones).

>>> c = gl.synthesis.chain_counts(6)
>>> c.coaxial, c.kinematic
(81, 27)
"""

from __future__ import annotations

import functools
import json
import numbers
import os
import pathlib
import time
from dataclasses import dataclass

from . import _chains
from ._trees import shapes
from ..errors import DataFormatError, FileFormatError

__all__ = ["MAX_COUNT_LINKS", "ChainCounts", "chain_counts", "PublishedCount", "PUBLISHED_COUNTS", "CountRow",
           "count_table", "StoredCounts", "stored_counts"]

MAX_COUNT_LINKS = 9
STORED = pathlib.Path(__file__).with_name("data") / "atlas_counts.json"
_FRACTIONATED = (False, True, "only")


@dataclass(frozen=True)
class ChainCounts:
    """The number of geared kinematic chains with *links* links and *dof* freedoms.

    ``coaxial``: displacement graphs; ``kinematic``: rotation graphs; ``fractionated``: which
    chains were counted (as in :func:`~gearlib.synthesis.atlas.geared_chains`); ``seconds``:
    how long the enumeration took when it ran (wall clock; the result is cached in the
    process), ``cpu_seconds`` the processor time it used (worker processes included).
    """

    links: int
    dof: int
    coaxial: int
    kinematic: int
    fractionated: bool | str = False
    seconds: float = 0.0
    cpu_seconds: float = 0.0

    def count(self, level: str) -> int:
        """The count at *level* (``"coaxial"`` or ``"kinematic"``)."""
        if level not in ("coaxial", "kinematic"):
            raise DataFormatError(f"level must be coaxial or kinematic, got {level!r}")
        return self.coaxial if level == "coaxial" else self.kinematic


def _integer(name, value, low, high=None):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < low or (
            high is not None and value > high):
        span = f"from {low} to {high}" if high is not None else f"of at least {low}"
        raise DataFormatError(f"{name} must be an integer {span}, got {value!r}")
    return int(value)


def _tree_counts(job):
    """The chains on one hypertree: how many are kept, and the kinematic codes of those."""
    n, groups, picks, fractionated = job
    kept, codes = 0, set()
    sorted_groups = tuple(sorted(groups))
    for triples in _chains._tree_chains(n, groups, picks):
        frac = _chains.fractionated(n, triples, sorted_groups)
        if (fractionated is False and frac) or (fractionated == "only" and not frac):
            continue
        kept += 1
        codes.add(_chains.canonical(n, (), triples, with_groups=False)[0])
    return kept, codes


@functools.cache
def _count(n: int, dof: int, fractionated, workers: int) -> ChainCounts:
    start, cpu = time.perf_counter(), _cpu()
    picks = n - 1 - dof
    jobs = [(n, groups, picks, fractionated) for groups in shapes(n)] if picks >= 1 else []
    if workers > 1 and len(jobs) > 1:
        from concurrent.futures import ProcessPoolExecutor

        with ProcessPoolExecutor(workers) as pool:  # the sum and the union do not depend on the order
            parts = list(pool.map(_tree_counts, jobs, chunksize=4))
    else:
        parts = [_tree_counts(job) for job in jobs]
    kept = sum(k for k, _ in parts)
    codes = set().union(*(c for _, c in parts))
    return ChainCounts(n, dof, kept, len(codes), fractionated, time.perf_counter() - start, _cpu() - cpu)


def _cpu() -> float:
    t = os.times()
    return t.user + t.system + t.children_user + t.children_system


def chain_counts(n_links: int, dof: int = 1, *, fractionated=False, workers: int = 1) -> ChainCounts:
    """Count the geared kinematic chains with *n_links* links and *dof* freedoms at both levels.

    Parameters
    ----------
    n_links : int, 2 to ``MAX_COUNT_LINKS`` (9; nine links take about a minute, eight a few seconds).
    dof : int, at least 1.
    fractionated : False (default), True or ``"only"``, as in
        :func:`~gearlib.synthesis.atlas.geared_chains`.
    workers : int
        Processes to share the hypertrees among (1: this process only). The counts do not
        depend on it.

    Returns
    -------
    ChainCounts
        Cached: the same numbers as ``len(geared_chains(n_links, dof, level=...))``, which
        builds every chain as a mechanism and stops at eight links.

    >>> c = gl.synthesis.chain_counts(7, 2)
    >>> c.coaxial, c.kinematic
    (50, 20)
    """
    n = _integer("n_links", n_links, 2, MAX_COUNT_LINKS)
    f = _integer("dof", dof, 1)
    if fractionated not in _FRACTIONATED or isinstance(fractionated, int) and not isinstance(fractionated, bool):
        raise DataFormatError(f"fractionated must be False, True or 'only', got {fractionated!r}")
    return _count(n, f, fractionated, _integer("workers", workers, 1, 64))


# ---------------------------------------------------------------- published counts
@dataclass(frozen=True)
class PublishedCount:
    """A count of geared kinematic chains printed in the literature."""

    links: int
    dof: int
    level: str
    count: int | None
    source: str
    note: str = ""


# Nine links: gearlib's search and an enumeration that shares no code with it (tests/atlas_brute.py)
# agree hypertree by hypertree, under the rules that give the paper's counts for six to eight links.
# (The chapter says so at length; the note stays short enough for a table cell.)
_NINE = "{} more than gearlib and an independent enumeration find"

PUBLISHED_COUNTS = (
    PublishedCount(4, 1, "kinematic", 2, "Buchsbaum and Freudenstein (1970)",
                   "as quoted in later surveys; the 1970 paper itself was not consulted"),
    PublishedCount(5, 1, "kinematic", 6, "Buchsbaum and Freudenstein (1970)",
                   "as quoted in later surveys; the 1970 paper itself was not consulted"),
    PublishedCount(6, 1, "kinematic", 26, "Tsai (1987)",
                   "one graph short: Yang, Ding et al. (2019) settle the six-link count at 27"),
    PublishedCount(6, 1, "kinematic", 27, "Yang, Ding et al. (2019)"),
    PublishedCount(6, 1, "coaxial", 81, "Yang, Ding et al. (2019)"),
    PublishedCount(7, 1, "kinematic", 152, "Yang, Ding et al. (2019)"),
    PublishedCount(7, 1, "coaxial", 647, "Yang, Ding et al. (2019)"),
    PublishedCount(8, 1, "kinematic", 1070, "Yang, Ding et al. (2019)"),
    PublishedCount(8, 1, "coaxial", 6360, "Yang, Ding et al. (2019)"),
    PublishedCount(9, 1, "kinematic", 8654, "Yang, Ding et al. (2019)", _NINE.format(2)),
    PublishedCount(9, 1, "coaxial", 71837, "Yang, Ding et al. (2019)", _NINE.format(4)),
    PublishedCount(5, 2, "kinematic", 0, "Tsai and Lin (1989)", "no non-fractionated two-dof train has five or fewer links"),
    PublishedCount(6, 2, "kinematic", 2, "Tsai and Lin (1989)"),
    PublishedCount(7, 2, "kinematic", 20, "Tsai and Lin (1989)"),
    PublishedCount(7, 2, "coaxial", 50, "Tsai and Lin (1989)", "the '50 two-DOF seven-link GKCs' of Chen, Yao and Lee"),
    PublishedCount(8, 2, "coaxial", None, "Hsu (1994)",
                   "a project report in Chinese that Chen, Yao and Lee take their 8-link GKC from; not available here"),
)


@dataclass(frozen=True)
class CountRow:
    """One published count next to the enumeration (non-fractionated chains)."""

    links: int
    dof: int
    level: str
    enumerated: int
    published: int | None
    source: str
    note: str

    @property
    def agrees(self) -> bool | None:
        return None if self.published is None else self.enumerated == self.published


def _rows(found: dict) -> tuple[CountRow, ...]:
    """``PUBLISHED_COUNTS`` with a row for each ``(links, dof)`` in *found* (ChainCounts)."""
    return tuple(CountRow(p.links, p.dof, p.level, found[(p.links, p.dof)].count(p.level), p.count, p.source, p.note)
                 for p in PUBLISHED_COUNTS if (p.links, p.dof) in found)


def count_table(max_links: int = 7, *, workers: int = 1) -> tuple[CountRow, ...]:
    """The enumeration's counts of non-fractionated chains beside ``PUBLISHED_COUNTS``,
    for chains of at most *max_links* links (up to ``MAX_COUNT_LINKS``; eight links take a
    few seconds, nine about a minute: :func:`stored_counts` has them from a stored run).

    >>> [(r.links, r.enumerated, r.published) for r in gl.atlas.count_table(5) if r.dof == 1]
    [(4, 2, 2), (5, 6, 6)]
    """
    if isinstance(max_links, bool) or not isinstance(max_links, numbers.Integral) or not (
            2 <= max_links <= MAX_COUNT_LINKS):
        raise DataFormatError(f"max_links must be an integer from 2 to {MAX_COUNT_LINKS}, got {max_links!r}")
    wanted = sorted({(p.links, p.dof) for p in PUBLISHED_COUNTS if p.links <= max_links})
    return _rows({key: chain_counts(*key, workers=workers) for key in wanted})


# ---------------------------------------------------------------- a stored run
@dataclass(frozen=True)
class StoredCounts:
    """Counts from a run of the enumeration stored in a file, with how they were made.

    ``counts``: the :class:`ChainCounts` of the run; ``command``: what made the file;
    ``date``: when (UTC, ISO 8601); ``commit``: gearlib's git commit then (``""`` if unknown);
    ``machine``: a description of the computer; ``peak_memory_mb``: the run's peak memory.
    """

    counts: tuple
    command: str
    date: str
    commit: str
    machine: str
    peak_memory_mb: float | None
    path: str

    @property
    def rows(self) -> tuple[CountRow, ...]:
        """The stored counts beside ``PUBLISHED_COUNTS`` (non-fractionated chains)."""
        return _rows({(c.links, c.dof): c for c in self.counts if c.fractionated is False})

    @property
    def seconds(self) -> float:
        """The time the stored enumerations took, in seconds."""
        return sum(c.seconds for c in self.counts)


def record(counts, *, command: str, commit: str = "") -> dict:
    """The JSON record :func:`stored_counts` reads: *counts* (ChainCounts) with provenance."""
    import datetime
    import platform

    try:
        import resource

        peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024  # kB on Linux
    except (ImportError, OSError):
        peak = None
    cpu = platform.processor() or platform.machine()
    try:
        for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    memory = ""
    try:
        for line in pathlib.Path("/proc/meminfo").read_text().splitlines():
            if line.startswith("MemTotal:"):
                memory = f", {int(line.split()[1]) / 2**20:.0f} GiB of memory"
                break
    except (OSError, ValueError, IndexError):
        pass
    machine = (f"{cpu}, {os.cpu_count()} CPUs{memory}, {platform.system()} {platform.release()}, "
               f"Python {platform.python_version()}")
    return {
        "about": "Counts of geared kinematic chains by gearlib's enumeration (gearlib.synthesis.chain_counts): "
                 "coaxial = displacement graphs, kinematic = rotation graphs. Written by `make bench`.",
        "command": command,
        "date": datetime.datetime.now(datetime.UTC).replace(microsecond=0).isoformat(),
        "commit": commit,
        "machine": machine,
        "peak_memory_mb": None if peak is None else round(peak, 1),
        "counts": [{"links": c.links, "dof": c.dof, "fractionated": c.fractionated, "coaxial": c.coaxial,
                    "kinematic": c.kinematic, "seconds": round(c.seconds, 2), "cpu_seconds": round(c.cpu_seconds, 2)}
                   for c in counts],
    }


def stored_counts(path=None) -> StoredCounts:
    """The counts of the stored run, eight and nine links (or of the record in *path*), with provenance.

    >>> stored = gl.synthesis.stored_counts()
    >>> [(c.links, c.dof) for c in stored.counts]
    [(8, 1), (9, 1)]
    """
    path = pathlib.Path(STORED if path is None else path)
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
        counts = tuple(ChainCounts(int(c["links"]), int(c["dof"]), int(c["coaxial"]), int(c["kinematic"]),
                                   c.get("fractionated", False), float(c["seconds"]), float(c.get("cpu_seconds", 0)))
                       for c in data["counts"])
        return StoredCounts(counts, str(data["command"]), str(data["date"]), str(data.get("commit", "")),
                            str(data["machine"]), data.get("peak_memory_mb"), str(path))
    except OSError as err:
        raise FileFormatError(f"{path}: cannot read the stored counts ({err.strerror or err})") from None
    except (ValueError, KeyError, TypeError) as err:
        raise FileFormatError(f"{path}: not a record of chain counts ({type(err).__name__}: {err})") from None
