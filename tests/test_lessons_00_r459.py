"""Review r459 (lesson 00, fresh read): the cube reveal, the marker question, the editor's
labels, and the density of two markdown cells.

C1: the cube's explanation said a centre off a shared edge "is inside exactly one", beside the
OUTLINE note saying both or neither; it now says two triangles on either side of the edge.
S1: the marker question's explanation names the affine lure and turns the verdict's units
into u. S2: the question's picture keys the marker. S3: the editor's comparison keeps its
vertex labels inside the panels (a vertex dragged to the top put "v3" over the heatmap's
title). S4: the error map's text, one paragraph a subject. S5: the Try it, a list.
"""

import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

import teachraster as tr  # noqa: E402

NOTEBOOKS = Path(__file__).resolve().parent.parent / "notebooks"
TOUR = tr.Triangle([[2.2, 1.5], [13.7, 5.2], [5.1, 12.8]], w=[1.0, 2.0, 4.0],
                   attrs={"u": [0.0, 1.0, 0.0]})  # fmt: skip


def _cell(cell_id: str) -> str:
    nb = json.loads((NOTEBOOKS / "00_tour.ipynb").read_text())
    return "".join(next(c for c in nb["cells"] if c.get("id") == cell_id)["source"])


def _flat(text: str) -> str:
    return " ".join(text.split())


def _run(*cell_ids) -> dict:
    """Lesson 00's import cell, then ``cell_ids`` on the tour triangle (the cells above them
    stood in for by ``tri``, ``W`` and ``H``)."""
    ns: dict = {}
    exec(_cell("c01").replace("%matplotlib inline", ""), ns)
    ns["plt"].show = lambda: None
    ns.update(tri=TOUR, W=16, H=16)
    for cell_id in cell_ids:
        exec(_cell(cell_id), ns)
    return ns


def test_c1_the_cube_reveal_agrees_with_its_note():
    ns = _run("tour-q-fragments")
    said = _flat(ns["q_fragments"].explain)
    assert "Two triangles on either side of a shared edge" in said
    assert "a centre beside it is inside exactly one of them" in said
    assert "(on the outline, both lie on one side)" in said
    assert "a centre off it is inside exactly one;" not in said
    assert "inside both or neither" in ns["q_fragments"].notes[ns["OUTLINE"]]
    ns["q_fragments"].close()


def test_s1_s2_the_marker_question():
    import contextlib
    import io

    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        ns = _run("tour-side-view", "tour-q-half", "tour-half-answer")
    # S1: the lure named, the verdict's units in u, each number as the held cell prints it
    said = _flat(ns["q_half"].explain)
    assert "A marker at the middle, u = 0.5, is the affine guess" in said
    assert round(ns["u_half_affine"], 12) == 0.5 and round(ns["edge_length"], 2) == 2.24
    units = f"{ns['half_tolerance'] * ns['edge_length']:.3f}"
    assert units == "0.112"
    assert f"the edge is 2.24 long, so {units} units is 0.05 in u" in said
    assert f"within ±0.05 of u, {units} units along the edge" in printed.getvalue()
    # S2: the question's picture keys the marker, after the plot's own key
    fig, ax = plt.subplots()
    ns["asked_side_view"](ax)
    texts = [t.get_text() for t in ax.get_legend().get_texts()]
    assert texts[-1] == "your marker: drag it" and "screen point q" in texts
    assert texts.count("eye rays, where they meet it") == 1
    plt.close("all")


def test_s3_the_editors_labels_stay_inside_its_panels():
    from teachraster.plotting import use_style
    from teachraster.widgets import TriangleEditor

    with use_style("classroom"):
        editor = TriangleEditor(TOUR, 16, 16)
    try:
        view = editor.interp_view
        for x, y in ((7.1, 0.5), (0.3, 15.6), (15.7, 8.0)):  # top, bottom left, right side
            editor.set_vertex(2, x=x, y=y)
            view.fig.canvas.draw()
            renderer = view.fig.canvas.get_renderer()
            for drawn in view.triangles:
                ax = drawn.outline.axes
                frame = ax.get_window_extent(renderer)
                title = ax.title.get_window_extent(renderer)
                for label in drawn.labels:
                    box = label.get_window_extent(renderer)
                    assert frame.x0 <= box.x0 and box.x1 <= frame.x1, (label.get_text(), x, y)
                    assert frame.y0 <= box.y0 and box.y1 <= frame.y1, (label.get_text(), x, y)
                    assert not box.overlaps(title), (label.get_text(), ax.get_title())
    finally:
        editor.close()
    # the player keeps its own placement, beside or inside the frames (review r241)
    from teachraster.plotting.views import InterpolationView

    view = InterpolationView(tr.rasterize(TOUR, 16, 16, trace=True), "u")
    assert all(not t.inside for t in view.triangles)
    plt.close(view.fig)


def test_s4_s5_the_error_text_and_the_try_it():
    text = _cell("tour-error-text")
    paragraphs = [p for p in text.split("\n\n") if p.strip()]
    assert [p.split("**")[1] for p in paragraphs] == [
        "In the figure above",
        "Where the error is zero:",
        "On a texture",
    ]
    assert len(text.split()) < 330  # r408/r459: 370 words in five paragraphs
    assert "you predict there in §6" not in text
    assert "§6 asks you to predict" in _flat(text) and "§7 lets you tilt one" in text
    try_it = _cell("c14")
    try_it = try_it[try_it.index("**Try it:**") :]
    items = [ln for ln in try_it.splitlines() if ln.startswith("- ")]
    assert len(items) == 3 and items[0].startswith("- Drag v1 onto a pixel centre")
    assert all(len(ln) <= 100 for ln in try_it.splitlines())
