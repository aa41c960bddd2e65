"""Reporting the study: the Pareto front, the CSV, the table and the figures.

Matplotlib is imported inside the figure functions only, so the package stays numpy-only.
"""

from __future__ import annotations

import csv
import math
from collections.abc import Iterable
from pathlib import Path

import numpy as np

from .settings import COMMON_COLUMNS, ERROR_MEASURE, GROUPS, SUBDIVISIONS, TABLE_COLUMNS

#: The words the lessons and widgets use for the front, phrased as the rule
#: :func:`pareto_front` applies (weak dominance): a tie on cost with a larger error is off the
#: front (review r6, 06-1: "both cheaper and more accurate" kept such a variant in words only).
FRONT_DEFINITION = (
    "no other is at least as cheap and at least as accurate, and better on one of the two"
)


def pareto_front(rows: Iterable[dict], x: str = "time_median_s", y: str = "error") -> list[dict]:
    """The rows on the Pareto front (smaller ``x`` and ``y`` are better), by ``x``.

    A row is on it when :data:`FRONT_DEFINITION`: it is dominated when another is at least as
    good on both and better on one. Of rows with identical (x, y) the first is kept.

    >>> rows = [{"t": 1, "e": 5}, {"t": 2, "e": 1}, {"t": 3, "e": 3}, {"t": 4, "e": 0}]
    >>> [r["t"] for r in pareto_front(rows, "t", "e")]
    [1, 2, 4]
    """
    front, best = [], math.inf
    for r in sorted(rows, key=lambda r: (r[x], r[y])):
        if r[y] < best:
            front.append(r)
            best = r[y]
    return front


def columns(rows: list[dict]) -> list[str]:
    """CSV columns: the common ones, then every group's own, in first-seen order."""
    cols = list(COMMON_COLUMNS)
    for r in rows:
        cols += [k for k in r if k not in cols]
    return cols


def write_csv(rows: list[dict], path) -> Path:
    path = Path(path)
    with path.open("w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=columns(rows), restval="")
        writer.writeheader()
        writer.writerows(rows)
    return path


def _fmt(v) -> str:
    if isinstance(v, float):
        return f"{v:.3g}"
    return str(v)


def format_table(rows: list[dict]) -> str:
    """A plain-text table, one block per group."""
    lines = []
    for group in GROUPS:
        block = [r for r in rows if r["group"] == group]
        if not block:
            continue
        extra = TABLE_COLUMNS[group]
        head = ["variant", "time (ms)", "x base", "error", *extra]
        body = [
            [
                r["variant"],
                f"{r['time_median_s'] * 1e3:.3g}",
                f"{r['time_ratio_to_baseline']:.2f}",
                _fmt(r["error"]),
                *(_fmt(r.get(c, "")) for c in extra),
            ]
            for r in block
        ]
        widths = [max(len(s) for s in col) for col in zip(head, *body)]
        lines.append(
            f"{group}: error = {ERROR_MEASURE[group]}; x base = time / {block[0]['baseline']}"
        )
        for cells in [head, *body]:
            lines.append(
                "  "
                + "  ".join(
                    c.rjust(w) if i else c.ljust(w) for i, (c, w) in enumerate(zip(cells, widths))
                )
            )
        lines.append("")
    return "\n".join(lines)


# -- plots (matplotlib imported here only) ----------------------------------------------------
#: The panels of the Pareto figure: (group, title, x key, y key, x label, y label, log x).
PANELS = (
    (
        "interpolation",
        "interpolation: error vs numpy time",
        "time_ms",
        "error",
        "time per run (ms, median)",
        ERROR_MEASURE["interpolation"],
        True,
    ),
    (
        "interpolation",
        "interpolation: error vs divides (the classic cost)",
        "divides_per_pixel",
        "error",
        "perspective divides per pixel (what a scalar span loop pays)",
        ERROR_MEASURE["interpolation"],
        False,
    ),
    (
        "edge functions",
        "edge functions: coverage errors",
        "time_ms",
        "error",
        "time per run (ms, median)",
        ERROR_MEASURE["edge functions"],
        True,
    ),
    (
        "edge functions",
        "edge functions: cracks in a watertight mesh",
        "time_ms",
        "cracks",
        "time per run (ms, median)",
        "mesh gaps + double hits (pixels)",
        True,
    ),
    (
        "fill",
        "fill algorithms",
        "time_ms",
        "error",
        "time per run (ms, median)",
        ERROR_MEASURE["fill"],
        True,
    ),
    (
        "depth",
        "depth storage and mapping",
        "time_ms",
        "error",
        "time per render (ms, median)",
        ERROR_MEASURE["depth"],
        True,
    ),
)


def _place_labels(ax, pts, texts, fontsize=7.5):
    """Label points without overlaps: greedy, each label tries slots above and below.

    Positions are worked out in axes fractions (the axes' limits and scales must be final);
    a label moved away from its point gets a thin leader line.
    """
    to_axes = ax.transData + ax.transAxes.inverted()
    char_w, line_h = 0.0058 * fontsize / 7.5 * 1.6, 0.034 * fontsize / 7.5
    placed = []
    order = sorted(range(len(pts)), key=lambda i: (pts[i][0], pts[i][1]))
    for i in order:
        px, py = to_axes.transform(pts[i])
        w = char_w * len(texts[i])
        for k in (0, 1, -1, 2, -2, 3, -3, 4, -4, 5, -5, 6, -6):
            x0, y0 = px + 0.012, py + 0.004 + k * line_h
            box = (x0, y0, x0 + w, y0 + line_h * 0.9)
            clash = any(
                box[0] < b[2] and b[0] < box[2] and box[1] < b[3] and b[1] < box[3] for b in placed
            )
            if not clash:
                break
        placed.append(box)
        ax.annotate(
            texts[i],
            pts[i],
            xytext=(x0, y0),
            textcoords="axes fraction",
            fontsize=fontsize,
            va="bottom",
            arrowprops={"arrowstyle": "-", "lw": 0.5, "color": "gray"} if k else None,
        )


def pareto_panel(ax, block, title, xkey, ykey, xlabel, ylabel, xlog):
    """One panel of :func:`pareto_figure`: the variants of ``block`` (rows of one group),
    error ``ykey`` against cost ``xkey``, with the Pareto front; for lessons that lay out
    the panels themselves."""
    pts = [dict(r, time_ms=r["time_median_s"] * 1e3) for r in block]
    errors = np.array([float(p[ykey]) for p in pts])
    exact = errors == 0
    integral = bool(np.all(errors == np.round(errors)))
    if exact.all():
        # Nothing to trade: every variant is exact, only the time differs.
        floor, ylog = 0.0, False
    else:
        floor, ylog = (0.5 if integral else errors[~exact].min() / 4), True
    for p, e in zip(pts, errors):
        p["_x"], p["_y"] = float(p[xkey]), max(float(e), floor)
    front = pareto_front(pts, "_x", "_y")
    on_front = {id(p) for p in front}
    xs, ys = [p["_x"] for p in pts], [p["_y"] for p in pts]
    if xlog:
        from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

        ax.set_xscale("log")
        ax.set_xlim(min(xs) / 1.3, max(xs) * 2.6)  # room for labels on the right
        # Plain numbers at 1, 2, 5 x 10^k: easier to read off than 2 x 10^0.
        ax.xaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
        ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
        ax.xaxis.set_minor_formatter(NullFormatter())
    else:
        span = max(xs) - min(xs) or 1.0
        ax.set_xlim(min(xs) - 0.05 * span, max(xs) + 0.45 * span)
    if ylog:
        ax.set_yscale("log")
        ax.set_ylim(min(ys) / 3, max(ys) * 6)
    else:
        ax.set_ylim(-1, 1)
        ax.set_yticks([0], ["0 (exact)"])
    if len(front) > 1:
        fx, fy = [p["_x"] for p in front], [p["_y"] for p in front]
        right = ax.get_xlim()[1]
        # A step line: the least error reachable within each time (or cost) budget.
        ax.step(
            fx + [right],
            fy + [fy[-1]],
            where="post",
            color="tab:red",
            lw=1.4,
            alpha=0.6,
            label="Pareto front",
            zorder=1,
        )
        ax.legend(loc="upper right", fontsize=8)
    for p in pts:
        best = id(p) in on_front
        ax.scatter(
            p["_x"],
            p["_y"],
            s=40 if best else 26,
            zorder=3,
            marker="o" if best else "s",
            color="tab:red" if best else "tab:blue",
        )
    if ylog and exact.any():
        ax.axhline(floor, color="gray", ls="--", lw=0.8)
        ax.annotate(
            "0 (exact)",
            (0.005, floor),
            xycoords=("axes fraction", "data"),
            xytext=(0, -10),
            textcoords="offset points",
            fontsize=8,
            color="gray",
        )
    _place_labels(ax, [(p["_x"], p["_y"]) for p in pts], [p["variant"] for p in pts])
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, which="major", alpha=0.3)
    note = " (all exact: only the time differs)" if exact.all() else ""
    ax.set_title(f"{title}{note}", fontsize=11)


def pareto_figure(rows: list[dict]):
    """Error against cost for every variant, one panel per measure, Pareto front drawn.

    Panels (:data:`PANELS`): interpolation error against time and against perspective
    divides per pixel; edge-function coverage errors and mesh cracks against time; fill
    and depth errors against time. Errors use a log axis; an error of exactly 0 is drawn on
    a dashed "0 (exact)" line below the smallest non-zero one. Red round markers are on the
    front (nothing is both faster and more accurate). Returns a
    ``matplotlib.figure.Figure`` (no pyplot state: safe in scripts and notebooks).
    """
    from matplotlib.figure import Figure

    fig = Figure(figsize=(16, 15), layout="constrained")
    axes = fig.subplots(3, 2).ravel()
    for ax, (group, title, xkey, ykey, xlabel, ylabel, xlog) in zip(axes, PANELS):
        block = [r for r in rows if r["group"] == group and ykey in r]
        if not block:
            ax.set_visible(False)
            continue
        pareto_panel(ax, block, title, xkey, ykey, xlabel, ylabel, xlog)
    fig.suptitle(
        f"Accuracy vs time: lower left is better; red = on the Pareto front ({FRONT_DEFINITION})",
        fontsize=13,
    )
    return fig


def subdivision_figure(rows: list[dict]):
    """Max and mean texel error of subdivided interpolation against N, with the two bounds."""
    from matplotlib.figure import Figure

    block = {r["variant"]: r for r in rows if r["group"] == "interpolation"}
    fig = Figure(figsize=(7, 4.5), layout="constrained")
    ax = fig.subplots()
    ns = [n for n in SUBDIVISIONS if f"subdivided N={n}" in block]
    for key, label, style in (("error", "max", "o-"), ("mean_abs_texels", "mean", "s--")):
        ax.plot(
            ns, [block[f"subdivided N={n}"][key] for n in ns], style, label=f"subdivided, {label}"
        )
        if "affine" in block:
            ax.axhline(block["affine"][key], color="tab:red", ls=":", lw=1)
            ax.annotate(
                f"affine, {label}",
                (ns[0], block["affine"][key]),
                fontsize=8,
                color="tab:red",
                xytext=(0, 3),
                textcoords="offset points",
            )
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("N: pixels between perspective-correct divides")
    ax.set_ylabel("|uv error| (texels of a 256-texel texture)")
    ax.set_title("Subdivided perspective: one divide every N pixels")
    ax.grid(True, which="both", alpha=0.25)
    ax.legend(fontsize=8)
    return fig


def plot(rows: list[dict], out_dir) -> list[Path]:
    """Write ``pareto.png`` and ``subdivision.png`` into ``out_dir``; return their paths."""
    out_dir = Path(out_dir)
    paths = [out_dir / "pareto.png", out_dir / "subdivision.png"]
    pareto_figure(rows).savefig(paths[0], dpi=110)
    subdivision_figure(rows).savefig(paths[1], dpi=110)
    return paths
