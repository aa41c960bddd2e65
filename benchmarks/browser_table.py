"""The browser benchmark's table: one row per interaction, printed as Markdown
(``interaction | median | max | / rt | target``), ready to paste into docs/widgets.md.

A latency row (ms) is within its target when its median is at most the bound (the bounds
follow issue 31: a click or key within the round trip rt + 30 ms, the last picture at most
100 ms after a release); a frame-rate row (fps) when its median is at least the bound
(24 fps for a drag or a slider); a row without a bound is shown for its ratio to rt only.
"""

from __future__ import annotations

import statistics
from dataclasses import dataclass, field

#: issue 31's targets
CLICK_MS = 30.0  # a click or key: within rt + this
DRAG_FPS = 24.0  # a drag or a slider dragged
SETTLE_MS = 100.0  # the last picture after the release


@dataclass
class Row:
    """One interaction: its measurements and its target.

    ``unit`` is "ms" (latencies: median and max, and the ratio to rt), "fps" (frame rates:
    median and min) or "px"; ``bound`` the target (at most, for ms and px; at least, for
    fps), None for none; ``target`` how the target is written (the bound by default).
    """

    label: str
    values: list = field(default_factory=list)
    unit: str = "ms"
    bound: float | None = None
    target: str = ""
    note: str = ""

    def measured(self) -> list:
        """The values measured (a try that saw no picture is NaN: left out)."""
        return [v for v in self.values if v == v]

    def ok(self) -> bool | None:
        """Within the target (None: no target; False also when nothing was measured)."""
        if self.bound is None:
            return None
        if not self.measured():
            return False
        med = statistics.median(self.measured())
        return med >= self.bound if self.unit == "fps" else med <= self.bound


def click(label, values, rt, note="") -> Row:
    """A click or key, to its picture: within rt + 30 ms."""
    return Row(
        label, list(values), "ms", rt + CLICK_MS, f"≤ rt + 30 = {rt + CLICK_MS:.0f} ms", note
    )


def fps(label, values, bound=DRAG_FPS, note="") -> Row:
    """Pictures per second while dragged: at least ``bound``."""
    values = values if isinstance(values, list) else [values]
    return Row(label, list(values), "fps", bound, f"≥ {bound:g} fps", note)


def settle(label, values, note="") -> Row:
    """The last picture after the release: within 100 ms."""
    values = values if isinstance(values, list) else [values]
    return Row(label, list(values), "ms", SETTLE_MS, f"≤ {SETTLE_MS:.0f} ms", note)


def info(label, values, note="") -> Row:
    """A latency shown for its ratio to rt (no target)."""
    return Row(label, list(values), "ms", None, "", note)


def cell(row: Row, rt: float) -> list[str]:
    """The row's cells after its label: median, max (min for fps), / rt, target."""
    values = row.measured()
    if not values:
        if row.bound is not None:
            return ["—", "", "", f"{row.target} ✗ (no picture)"]
        return ["—", "", "", f"({row.note})" if row.note else ""]
    med = statistics.median(values)
    mark = {True: " ✓", False: " ✗", None: ""}[row.ok()]
    notes = [row.note] if row.note else []
    if len(values) < len(row.values):
        notes.append(f"{len(row.values) - len(values)} of {len(row.values)} tries: no picture")
    target = (f"{row.target}{mark}" + (f" ({'; '.join(notes)})" if notes else "")).strip()
    if row.unit == "fps":
        low = f"{min(values):.1f} min" if len(values) > 1 else ""
        return [f"{med:.1f} fps", low, "", target]
    if row.unit == "px":
        return [f"{med:.0f} px", "", "", target]
    return [f"{med:.1f} ms", f"{max(values):.1f} ms", f"{med / rt:.2f}", target]


def markdown(rows: list[Row], rt: float) -> str:
    """The rows as a Markdown table."""
    lines = ["| interaction | median | max | / rt | target |", "|---|---|---|---|---|"]
    for row in rows:
        lines.append("| " + " | ".join([row.label, *cell(row, rt)]) + " |")
    return "\n".join(lines)


def misses(rows: list[Row]) -> list[str]:
    """The labels of the rows that miss their target."""
    return [r.label for r in rows if r.ok() is False]
