"""The whole study: every group in turn, with times relative to each group's baseline."""

from __future__ import annotations

from .groups import bench_depth, bench_edges, bench_fill, bench_interpolation
from .settings import GROUPS, sizes, variant_names
from .timing import Progress


def run(quick: bool = False, *, repeat: int | None = None, progress: bool = False) -> list[dict]:
    """Measure every variant of every group; one dict per variant.

    Parameters
    ----------
    quick : bool
        Smaller images and meshes (same variants): a smoke run of a few seconds.
    repeat : int, optional
        Timed runs per variant (median taken); default 7, or 3 with ``quick``.
    progress : bool
        Draw a progress bar on stderr.

    Returns
    -------
    list of dict
        Keys :data:`COMMON_COLUMNS` plus each group's own measures.
    """
    cfg = sizes(quick)
    repeat = (3 if quick else 7) if repeat is None else int(repeat)
    names = variant_names(quick)
    # one step per variant (its error measured), one per timed block of variants
    steps = sum(len(v) for v in names.values()) + len(GROUPS) + 1  # fill: two sizes
    bar = Progress(steps, enabled=progress)
    rows = []
    for bench in (bench_interpolation, bench_edges, bench_fill, bench_depth):
        rows += bench(cfg, repeat, bar)
    return rows
