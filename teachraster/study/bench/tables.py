"""The study's tables as lesson 06 prints them: one group's error, operations and bits.

:mod:`.report` writes the command line's table of medians; lesson 06 prices each variant in
operations instead (:func:`teachraster.study.operation_counts.with_counts`) and leaves the
simulator's time to ``benchmarks/bench_lesson06_signs.py``. These helpers keep that
bookkeeping out of the lesson's first cell, so what a student sees first is graphics.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from html import escape

from .settings import ERROR_MEASURE

#: The operation columns: (header, key, format, width); "Pentium" is the cost in issue cycles
#: at the Pentium's prices, the default of ``with_counts`` (its x87 FPU's for floating-point
#: variants, its integer unit's for integer ones: :mod:`teachraster.study.operation_counts`).
OP_COLUMNS = (
    ("error", "error", "9.3g", 9),
    ("div", "divides", "7.4g", 7),
    ("mul", "multiplies", "7.4g", 7),
    ("add", "additions", "9.4g", 9),
    ("bits", "bits", "", 5),
    ("Pentium", "cycles", "9.4g", 9),  # issue cycles at the Pentium's prices (the default)
)


def number(value, fmt: str = ".3g") -> str:
    """A table's number, short and in one piece: ``-`` for None; from 1,000 up a whole number
    with thousands separators (a count of pixels or cycles, not ``2.44e+03``); below 1e-6 one
    digit (rounding level: ``1e-13``, not ``1.42e-13``, which a narrow cell broke at its
    hyphen); else ``fmt``.

    >>> [number(v) for v in (None, 2438, 3713.4, 493230.0, 1.42e-13, 0.0, 5.757, 0.03125)]
    ['-', '2,438', '3,713', '493,230', '1e-13', '0', '5.76', '0.0312']
    """
    if value is None:
        return "-"
    if abs(value) >= 1000:
        return f"{value:,.0f}"
    if 0 < abs(value) < 1e-6:
        return f"{value:.0e}"
    return format(value, fmt)


def table_parts(
    rows: Iterable[dict],
    group: str,
    extra: Iterable[tuple[str, Callable]] = (),
    errors: Iterable[tuple[str, Callable]] = (),
) -> dict:
    """One group's table in parts: ``heading``, ``measure``, ``header`` (the columns that
    separate variants), ``body`` (a list of cells per variant), ``widths`` and ``note`` (the
    columns that read the same in every row, said once as ``"every variant: ..."``, or "").

    Parameters
    ----------
    rows : iterable of dict
        The study's rows with their operation counts.
    group : str
        The group to print (``"interpolation"``, ``"edge functions"``, ``"fill"``, ``"depth"``).
    extra : iterable of (header, format)
        Columns of the group's own: ``format(row)`` gives the cell's text.
    errors : iterable of (header, format)
        More columns of the group's own, shown right after ``error`` (the same error in
        other units).
    """
    block = [r for r in rows if r["group"] == group]
    columns = [
        (head, (lambda r, k=key, f=fmt: number(r[k], f)), w) for head, key, fmt, w in OP_COLUMNS
    ]
    columns[1:1] = [(head, fmt, max(6, len(head))) for head, fmt in errors]
    columns += [(head, fmt, max(6, len(head))) for head, fmt in extra]
    cells = {head: [fmt(r).strip() for r in block] for head, fmt, _ in columns}
    shown = [c for c in columns if len(set(cells[c[0]])) > 1]
    same = [
        f"{head}{': n/a' if cells[head][0] == '-' else ' ' + cells[head][0]}"
        for head, _, _ in columns
        if len(set(cells[head])) == 1
    ]
    return {
        "heading": f"{group}, operations per {block[0]['per']}",
        "measure": f"error: {ERROR_MEASURE[group]}",
        "header": ["variant"] + [head for head, _, _ in shown],
        "widths": [max(len(r["variant"]) for r in block)] + [w for _, _, w in shown],
        "body": [[r["variant"]] + [cells[h][i] for h, _, _ in shown] for i, r in enumerate(block)],
        "note": "every variant: " + ", ".join(same) if same else "",
    }


def table_lines(
    rows: Iterable[dict],
    group: str,
    extra: Iterable[tuple[str, Callable]] = (),
    errors: Iterable[tuple[str, Callable]] = (),
) -> list[str]:
    """The lines of one group's table (:func:`table_parts`), each at most about 80 characters:
    a heading, the error measure, the header and a line per variant, then the note."""
    t = table_parts(rows, group, extra, errors)

    def line(cells):
        name_w, *widths = t["widths"]
        return f"{cells[0]:{name_w}s}" + "".join(f" {c:>{w}s}" for c, w in zip(cells[1:], widths))

    lines = [t["heading"], t["measure"], line(t["header"])] + [line(b) for b in t["body"]]
    return lines + ([t["note"]] if t["note"] else [])


#: The font size of :func:`table_html`: read from the back of a room (the printed tables'
#: 13-px monospace could not be: review r152 06-6).
TABLE_FONT_PX = 20


def table_html(parts: dict) -> str:
    """:func:`table_parts` as an HTML table at :data:`TABLE_FONT_PX`: the heading and the
    error measure as its caption, numbers right-aligned, the note under it.

    >>> rows = [{"group": "fill", "variant": v, "per": "triangle", "error": 0, "divides": d,
    ...          "multiplies": 0, "additions": 1, "bits": None, "cycles": 1} for v, d in
    ...         (("span 256²", 1), ("halfplane 256²", 0))]
    >>> text = table_html(table_parts(rows, "fill"))
    >>> "<th>div</th>" in text and "every variant: error 0" in text
    True
    """
    px = TABLE_FONT_PX
    out = [f'<table style="font-size:{px}px;line-height:1.35">',
           f'<caption style="text-align:left;font-size:{px}px"><b>{escape(parts["heading"])}'
           f"</b>; {escape(parts['measure'])}</caption>",
           "<tr>" + "".join(f"<th>{escape(c)}</th>" for c in parts["header"]) + "</tr>"]  # fmt: skip
    for cells in parts["body"]:
        tds = [f'<td style="text-align:left">{escape(cells[0])}</td>']
        # numbers in one piece: "1.42e-13" broke at its hyphen in a narrow cell (r238 FIG1)
        tds += [f'<td style="text-align:right;white-space:nowrap">{escape(c)}</td>'
                for c in cells[1:]]  # fmt: skip
        out.append("<tr>" + "".join(tds) + "</tr>")
    out.append("</table>")
    if parts["note"]:
        out.append(f'<p style="font-size:{px}px">{escape(parts["note"])}</p>')
    return "\n".join(out)


def table(rows: list[dict], group: str, extra: Iterable[tuple[str, Callable]] = (), *,
          html: bool = False, keep: Callable[[dict], bool] | None = None,
          errors: Iterable[tuple[str, Callable]] = ()) -> list[dict]:  # fmt: skip
    """Print :func:`table_lines` (or, with ``html``, display :func:`table_html`: readable on
    a projector) and return the group's rows; ``keep`` selects the rows shown and returned,
    ``errors`` adds columns after the error's (:func:`table_parts`)."""
    rows = [r for r in rows if r["group"] == group and (keep is None or keep(r))]
    if html:
        from IPython.display import HTML, display

        display(HTML(table_html(table_parts(rows, group, extra, errors))))
    else:
        print("\n".join(table_lines(rows, group, extra, errors)))
    return rows


def folded_html(summary: str, lines: Iterable[str]) -> str:
    """Printed lines folded under a one-line summary: a ``<details>`` element, closed.

    >>> folded_html("the fronts", ["a < b", "c"])
    '<details><summary>the fronts</summary><pre>a &lt; b\\nc</pre></details>'
    """
    text = escape("\n".join(lines), quote=False)
    return f"<details><summary>{escape(summary)}</summary><pre>{text}</pre></details>"


def folded(summary: str, lines: Iterable[str]) -> None:
    """Display :func:`folded_html`: lines the text does not quote, one click away."""
    from IPython.display import HTML, display

    display(HTML(folded_html(summary, lines)))
