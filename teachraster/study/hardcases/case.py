"""The hard case itself: its inputs, results and the registry of the catalogue."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np

from ...core.fill import Fill
from ...pipeline.rendering.render_triangles import Frame

#: Fill methods a screen-space case runs with.
FILL_METHODS = ("halfplane", "span")
#: Depth buffer formats, from most to fewest bits.
DEPTH_ORDER = ("float64", "float32", "unorm24", "unorm16")


# -- results ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class Fills:
    """Result of a screen-space case: one fill per triangle, and how often each pixel was hit."""

    fills: tuple[Fill, ...]
    counts: np.ndarray  # (H, W) int: number of triangles covering each pixel centre
    extra: Mapping[str, Any] | None = None  # case-specific results (e.g. culled coverage)


@dataclass(frozen=True)
class Rendered:
    """Result of a clip-space case.

    ``coverage`` is the union of the clipped window triangles (``frame.trace.window``) filled
    again by :func:`teachraster.rasterize` with the case's fill method: it must equal
    ``frame.coverage``, so the clip cases exercise both fill methods too.
    """

    frame: Frame
    coverage: np.ndarray


@dataclass(frozen=True)
class Naive:
    """What a naive implementation computed (fields depend on the case; unused ones are None).

    Attributes
    ----------
    counts : (H, W) int or None
        Naive coverage counts of the case's triangles.
    window : (N, 3, 3) float or None
        Window coordinates after dividing by w *before* clipping.
    values : mapping or None
        Named measurements (errors, coverages per offset, ...); ``"triangles"``, where the
        naive version fills other triangles than the case's (rounded ones), those.
    """

    counts: np.ndarray | None = None
    window: np.ndarray | None = None
    values: Mapping[str, Any] | None = None


# -- the case --------------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class HardCase:
    """One named hard case.

    Attributes
    ----------
    name : str
        Registry key.
    why : str
        One line: what makes it hard.
    kind : str
        "triangle", "triangles" (independent), "mesh" (watertight), "clip", "precision",
        "depth".
    expect : str
        What a correct rasteriser must do, in words (:meth:`check` is the same in code).
    inputs : mapping
        The case's data (read-only arrays).
    naive_does : str
        What the naive version does wrong ("" when the case has none).
    methods : tuple of str
        Fill methods the case runs with.
    """

    name: str
    why: str
    kind: str
    expect: str
    inputs: Mapping[str, Any]
    runner: Callable[[Mapping[str, Any], str], Any] = field(repr=False)
    checker: Callable[[Mapping[str, Any], Any], None] = field(repr=False)
    naive_does: str = ""
    naive_runner: Callable[[Mapping[str, Any]], Naive] | None = field(default=None, repr=False)
    naive_shows: Callable[[Mapping[str, Any], Any, Naive], str | None] | None = field(
        default=None, repr=False
    )
    methods: tuple[str, ...] = FILL_METHODS

    def run(self, method: str | None = None):
        """Execute the case with the core and return its result (see the module docstring).

        ``method`` is one of :attr:`methods` (default: the first).
        """
        method = self.methods[0] if method is None else method
        if method not in self.methods:
            raise ValueError(f"{self.name}: method must be one of {self.methods}, got {method!r}")
        return self.runner(self.inputs, method)

    def check(self, result) -> None:
        """Raise ``AssertionError`` (saying what is wrong) unless ``result`` meets ``expect``."""
        self.checker(self.inputs, result)

    @property
    def has_naive(self) -> bool:
        return self.naive_runner is not None

    def naive(self) -> Naive:
        """What the naive implementation described by ``naive_does`` computes."""
        if self.naive_runner is None:
            raise ValueError(f"{self.name} has no naive variant")
        return self.naive_runner(self.inputs)

    def naive_difference(self, ours, naive: Naive) -> str | None:
        """How the naive result visibly differs from ours (one line), or None if it does not."""
        if self.naive_shows is None:
            return None
        return self.naive_shows(self.inputs, ours, naive)

    @property
    def triangles(self) -> np.ndarray | None:
        """(n, 3, 2) screen-space triangles of a screen-space case, else None."""
        return self.inputs.get("triangles")


def frozen_inputs(**inputs) -> Mapping[str, Any]:
    for value in inputs.values():
        if isinstance(value, np.ndarray):
            value.flags.writeable = False
    return MappingProxyType(inputs)


# -- coverage cases --------------------------------------------------------------------------
CASES: dict[str, HardCase] = {}


def add_case(case: HardCase) -> None:
    assert case.name not in CASES, case.name
    CASES[case.name] = case


# -- registry --------------------------------------------------------------------------------
def get_case(name: str) -> HardCase:
    """The case called ``name``; ``ValueError`` lists the names when there is none."""
    if name not in CASES:
        raise ValueError(f"unknown hard case {name!r}; choose from {', '.join(CASES)}")
    return CASES[name]


def list_cases(kind: str | None = None) -> list[str]:
    """Names of all cases (of one ``kind`` if given), in catalogue order."""
    return [name for name, case in CASES.items() if kind is None or case.kind == kind]
