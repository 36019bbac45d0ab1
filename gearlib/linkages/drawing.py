"""Drawings of linkages: sketches, coupling graphs, powers along a task (filled in below)."""

from __future__ import annotations

__all__ = ["draw_linkage", "draw_linkage_graph", "plot_task_powers"]


def draw_linkage(*args, **kwargs):  # pragma: no cover - replaced below
    raise NotImplementedError


def draw_linkage_graph(*args, **kwargs):  # pragma: no cover
    raise NotImplementedError


def plot_task_powers(*args, **kwargs):  # pragma: no cover
    raise NotImplementedError
