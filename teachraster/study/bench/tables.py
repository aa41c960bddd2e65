"""The study's tables as lesson 06 prints them: one group's error, operations and bits.

:mod:`.report` writes the command line's table of medians; a lesson reads each variant's
*fastest* round instead (the least disturbed one) and prices it in operations
(:func:`teachraster.study.operation_counts.with_counts`). These helpers keep that
bookkeeping out of the lesson's first cell, so what a student sees first is graphics.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

from .settings import ERROR_MEASURE

#: The operation columns: (header, key, format, width).
OP_COLUMNS = (
    ("error", "error", "9.3g", 9),
    ("div", "divides", "7.4g", 7),
    ("mul", "multiplies", "7.4g", 7),
    ("add", "additions", "9.4g", 9),
    ("bits", "bits", "", 5),
    ("cycles", "cycles", "9.4g", 9),
)


def fastest(r: dict, timer: str = "time") -> float:
    """A variant's fastest round in seconds: the time lesson 06 compares.

    >>> fastest({"time_min_s": 0.002, "time_max_s": 0.005})
    0.002
    """
    return r[timer + "_min_s"]


def ratio(a: dict, b: dict, timer: str = "time") -> float:
    """``a``'s time over ``b``'s, each its fastest round.

    >>> ratio({"time_min_s": 3.0}, {"time_min_s": 2.0})
    1.5
    """
    return fastest(a, timer) / fastest(b, timer)


def table_lines(
    rows: Iterable[dict], group: str, extra: Iterable[tuple[str, Callable]] = ()
) -> list[str]:
    """The lines of one group's table, each at most about 80 characters.

    Parameters
    ----------
    rows : iterable of dict
        The study's rows with their operation counts.
    group : str
        The group to print (``"interpolation"``, ``"edge functions"``, ``"fill"``, ``"depth"``).
    extra : iterable of (header, format)
        Columns of the group's own: ``format(row)`` gives the cell's text.

    Returns
    -------
    list of str
        A heading, the error measure, the header and a line per variant. A column that reads
        the same in every row separates nothing: it is said once, last, as
        ``"every variant: ..."``.
    """
    block = [r for r in rows if r["group"] == group]
    name_w = max(len(r["variant"]) for r in block)
    columns = [
        (head, (lambda r, k=key, f=fmt: "-" if r[k] is None else format(r[k], f)), w)
        for head, key, fmt, w in OP_COLUMNS
    ]
    columns += [(head, fmt, max(6, len(head))) for head, fmt in extra]
    cells = {head: [fmt(r).strip() for r in block] for head, fmt, _ in columns}
    shown = [c for c in columns if len(set(cells[c[0]])) > 1]
    lines = [f"{group}, operations per {block[0]['per']}", f"error: {ERROR_MEASURE[group]}"]
    lines.append(f"{'variant':{name_w}s}" + "".join(f" {head:>{w}s}" for head, _, w in shown))
    for i, r in enumerate(block):
        lines.append(
            f"{r['variant']:{name_w}s}" + "".join(f" {cells[h][i]:>{w}s}" for h, _, w in shown)
        )
    same = [
        f"{head}{': n/a' if cells[head][0] == '-' else ' ' + cells[head][0]}"
        for head, _, _ in columns
        if len(set(cells[head])) == 1
    ]
    if same:
        lines.append("every variant: " + ", ".join(same))
    return lines


def table(rows: list[dict], group: str, extra: Iterable[tuple[str, Callable]] = ()) -> list[dict]:
    """Print :func:`table_lines` and return the group's rows."""
    print("\n".join(table_lines(rows, group, extra)))
    return [r for r in rows if r["group"] == group]
