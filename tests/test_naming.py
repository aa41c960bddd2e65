"""One vertex naming everywhere: v1, v2, v3 in the order given; edges E12, E23, E31.

Captions (every step of every method), plot labels, widget and CLI labels and the lesson
sources must never name a vertex v0 or an edge E01/E20, and a span fill and a half-plane fill
of the same triangle must be labelled alike (issue 18: "the same triangle is v1–v3 in one
panel and v0–v2 in the next").
"""

import json
import re
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster import plotting as tp  # noqa: E402

NOTEBOOKS = Path(__file__).resolve().parents[1] / "notebooks"

TRIANGLES = {
    "clockwise, input order differs from y order": [[8.5, 11.5], [2.5, 1.5], [11.5, 6.5]],
    "counter-clockwise": [[2.2, 2.1], [5.3, 10.6], [10.7, 3.4]],
    "flat-topped": [[1.5, 2.5], [10.5, 2.5], [5.5, 9.5]],
    "flat-bottomed": [[6.5, 1.5], [10.5, 9.5], [1.5, 9.5]],
    "zero height": [[1.5, 6.5], [7.5, 6.5], [11.5, 6.5]],
}
METHODS = ("span", "halfplane", "tiled")

#: Names from the other numbering (input order from 0) that must appear nowhere.
FORBIDDEN = re.compile(r"\bv0\b|\bE0[12]\b|\bE[12]0\b|\bE\d\b|λ_?0|\bw0\b|\bx0,y0\b")


def _names_ok(text: str) -> None:
    assert not FORBIDDEN.search(text), text
    for k in re.findall(r"\bv(\d+)\b", text):
        assert k in {"1", "2", "3"}, text
    for a, b in re.findall(r"\bE(\d)(\d)\b", text):
        assert a != b and {a, b} <= {"1", "2", "3"}, text


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("name", list(TRIANGLES))
def test_every_caption_names_vertices_v1_to_v3_and_edges_by_them(name, method):
    fill = tr.rasterize(tr.Triangle(TRIANGLES[name]), 12, 12, method=method, trace=True)
    trace = fill.trace
    for k in range(len(trace)):
        _names_ok(trace.caption(k))


def test_edges_are_named_in_walking_order():
    cw = tr.rasterize(tr.Triangle(TRIANGLES["clockwise, input order differs from y order"]), 12,
                      12, method="halfplane", trace=True).trace  # fmt: skip
    ccw = tr.rasterize(tr.Triangle(TRIANGLES["counter-clockwise"]), 12, 12, method="halfplane",
                       trace=True).trace  # fmt: skip
    names = [{m.group() for k in range(len(t)) for m in re.finditer(r"E\d\d", t.caption(k))}
             for t in (cw, ccw)]  # fmt: skip
    assert names[0] <= {"E12", "E23", "E31"} and names[0]
    assert names[1] <= {"E13", "E32", "E21"} and names[1]
    assert "walked v1→v3→v2" in ccw.caption(1)


def test_span_captions_keep_the_names_and_give_roles():
    xy = TRIANGLES["clockwise, input order differs from y order"]
    trace = tr.rasterize(tr.Triangle(xy), 12, 12, method="span", trace=True).trace
    assert (
        trace.caption(3)
        == "sorted by v: top v2 (2.5, 1.5), middle v3 (11.5, 6.5), bottom v1 (8.5, 11.5)"
    )
    split = trace.caption(4)
    assert "long edge v2-v1" in split and "point 4" in split
    assert "u4 = u_top + (v_mid-v_top)/(v_bot-v_top)*(u_bot-u_top)" in split
    assert "flat-bottom (v2, v3, point 4)" in split and "flat-top (v3, point 4, v1)" in split


def _label_state(artists):
    return [(a.get_text(), tuple(np.round(a.xy, 9)), tuple(np.round(a.get_position(), 9)))
            for a in artists]  # fmt: skip


@pytest.mark.parametrize(
    "name", ["clockwise, input order differs from y order", "counter-clockwise"]
)
def test_span_and_halfplane_fills_are_labelled_alike(name):
    tri = tr.Triangle(TRIANGLES[name])
    fig, axes = plt.subplots(1, 2)
    drawn = []
    for ax, method in zip(axes, ["span", "halfplane"]):
        tp.plot_pixel_grid(ax, 12, 12)
        fill = tr.rasterize(tri, 12, 12, method=method, trace=True)
        drawn.append(tp.plot_triangle(ax, fill, edge_labels=True))
    span, half = drawn
    assert _label_state(span.labels) == _label_state(half.labels)
    assert [a.get_text() for a in span.labels] == ["v1", "v2", "v3"]
    assert _label_state(span.edge_labels) == _label_state(half.edge_labels)
    for artist in span.edge_labels:
        _names_ok(artist.get_text())
    plt.close(fig)


def test_edge_value_titles_barycentric_titles_and_pixel_labels_use_the_names():
    fill = tr.rasterize(tr.Triangle(TRIANGLES["counter-clockwise"]), 12, 12, method="halfplane",
                        samples=4, trace=True)  # fmt: skip
    fig, axes = plt.subplots(2, 3)
    for k in range(3):
        tp.plot_edge_values(axes[0, k], fill, k)
        _names_ok(axes[0, k].get_title())
    tp.plot_barycentric(axes[1, 0], fill)
    tp.plot_barycentric(axes[1, 1], fill, channel=0)
    assert axes[1, 1].get_title() == "barycentric λ1: 1 at v1, 0 opposite"
    result = tp.plot_pixel_samples(axes[1, 2], fill, 4, 5)
    for ax in axes.ravel():
        _names_ok(ax.get_title())
    for label in result.labels:
        _names_ok(label.get_text())
    plt.close(fig)


def test_cli_help_and_errors_use_the_names():
    import argparse

    from teachraster.cli.arguments import parse_attr, parse_w, parse_xy
    from teachraster.cli.parser import build_parser

    parser = build_parser()
    subs = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    for sub in subs.choices.values():
        _names_ok(sub.format_help())
    for parse, bad in [(parse_xy, "1,2 3,4"), (parse_w, "1,2"), (parse_attr, "1u=0,1,0")]:
        with pytest.raises(argparse.ArgumentTypeError) as err:
            parse(bad)
        _names_ok(str(err.value))


def _sources():
    for path in sorted(NOTEBOOKS.rglob("*.ipynb")):
        if ".ipynb_checkpoints" in path.parts:
            continue
        for i, cell in enumerate(json.loads(path.read_text(encoding="utf-8"))["cells"]):
            yield f"{path.relative_to(NOTEBOOKS)} cell {i}", "".join(cell["source"])


#: The other numbering in lesson text and code: v0, E01/E20, λ0 (also in LaTeX).
LESSON_FORBIDDEN = re.compile(
    r"\bv0\b|\bE01\b|\bE20\b|λ_?0|\\lambda_0|\\mathbf\{v\}_0|\bv_0\b|E_\{01\}|E_\{20\}|\blam0"
)


#: A note's own numbering may be quoted right after the note is named ("the CS148 notes
#: $v_0, v_1, v_2$" in the tour's table of symbols); anywhere else it is the wrong numbering.
QUOTED = re.compile(r"CS148 notes \$[^$]*$")


def test_no_lesson_names_a_vertex_from_zero():
    found = [(where, m.group()) for where, text in _sources()
             for m in LESSON_FORBIDDEN.finditer(text)
             if not QUOTED.search(text[max(0, m.start() - 40):m.start()])]  # fmt: skip
    assert not found, found


def test_a_quoted_numbering_is_only_allowed_after_its_note():
    quoted = "the CS148 notes $v_0, v_1, v_2$"
    assert QUOTED.search(quoted[: quoted.index("v_0")])
    assert not QUOTED.search("the vertices $"[-40:])
