"""``FrameInspector``: a whole frame with its debug overlays; click a pixel for its history.

What RenderDoc's texture viewer and pixel history do for a GPU frame, for a teachraster
frame: choose a built-in scene and a view (the shaded image or an overlay of
:mod:`teachraster.pipeline.debugging.overlays`), click a pixel (or move the row / column sliders),
and see every triangle on the way to it in submission order, with the test that stopped
each (:mod:`teachraster.pipeline.debugging.frame_history`): the table and the depth strip beside it.

Clicks work under ipympl (the canvas' own mouse events) and with the image display, where
the frame is shown by a small page-side widget (anywidget) that sends the clicked point
back; without anywidget the image is a plain ``ipywidgets.Image`` and the sliders choose.
"""

from __future__ import annotations

import html

import ipywidgets as widgets
import numpy as np
from matplotlib.patheffects import withStroke

from ..pipeline.debugging.frame_history import history_table
from ..pipeline.debugging.overlays import KINDS, quad_triangles
from ..pipeline.rendering.render_scenes import render
from ..pipeline.rendering.render_triangles import render as render_clip
from ..pipeline.rendering.scenes import SCENES, get_scene
from ..plotting import plot_history, plot_image, plot_overlay
from ..plotting.common import clear_axes
from ..plotting.frame_debug import fit_title, plot_triangle_edges
from .common import (
    SLIDER_COLUMN_WIDTH,
    Holdable,
    Shown,
    close_tree,
    control_row,
    fit_width,
    picture_row,
    style_context,
    title_html,
)
from .display import FigureDisplay, new_figure, png_bytes, resolve_backend

#: The views the chooser offers: the shaded image, then every overlay.
VIEWS = ("image", *KINDS)


#: The "nan" view's label on the built-in scenes: render refuses a NaN input, so it is 0 there
#: (lesson 11, §6, prints it for every scene); it stays offered, as the overlay to know.
NAN_ON_SCENES = "nan (0 on built-in scenes)"


def _views(frames: dict, view: str) -> list:
    """The views offered: all of :data:`VIEWS`, but with frames handed in and none holding a
    NaN pixel, not "nan" (an empty map offered in exercise 11), unless asked for. On the
    built-in scenes "nan" is offered under a label that says it is 0 there."""
    if not frames:
        return [(NAN_ON_SCENES, v) if v == "nan" else (v, v) for v in VIEWS]
    if view == "nan" or any(f.overlay("nan").any() for f in frames.values()):
        return list(VIEWS)
    return [v for v in VIEWS if v != "nan"]


#: The largest the frame is drawn, width and height in inches (a 4:3 frame: 6 × 4.5). Review
#: r82, 11-B: at 3 inches a 64-pixel frame gave 4.5 screen px a pixel, one pixel off under a
#: normal click, with the rest of the row empty; at 6, 9 px (the picture scales down to a
#: narrower column, 7.9 px a pixel in JupyterLab's 592-px column at 1024 × 768).
FRAME_BOX = (6.0, 6.2)
#: The frame figure's margins in inches: left (row labels and "row i"), top (column labels,
#: "column j" and the title), right (and bottom without a colour bar), then the colour
#: bar's gap under the frame, its height and the room under it for its ticks and label at
#: the classroom style's sizes (the first guess: :meth:`FrameInspector._bar_room` measures
#: them once drawn). The bar lies under the frame, so that every view has the same width
#: (review r44 D2: a bar on the right widened the figure by up to 1 inch in the overlay
#: views, and at 1280 px with the file browser open the history chart wrapped under it).
FRAME_MARGINS = (0.85, 1.0, 0.15, 0.12, 0.13, 0.75)
#: The history chart's figure, width and height in inches; it stands in a row of its own,
#: under the history table (r21 D3, r62 #4), not beside the frame.
HISTORY_SIZE = (4.6, 4.5)
#: The chart's width in inches where the history has a colour buffer (glass, a blended
#: frame): the frame's figure's width, so that each record's three colour swatches are
#: large enough to read and their label fits above them (review r211 11-4: at 4.6 inches
#: the glass sphere's four records gave swatches about 16 px wide).
HISTORY_COLOUR_WIDTH = FRAME_MARGINS[0] + FRAME_BOX[0] + FRAME_MARGINS[2]
#: The chart's Axes inside its figure, in inches: left (the depth ticks and label), right;
#: and in fractions of the height: bottom, height (the records' labels under it, the title).
HISTORY_AXES = (1.2, 0.14, 0.24, 0.66)

#: The depth-test check box's words. Unticked, ``render(..., depth_test=False)``: every
#: fragment passes and still writes its depth, what GL calls ``glDepthFunc(GL_ALWAYS)``
#: (Direct3D ``D3D11_COMPARISON_ALWAYS``, Vulkan ``VK_COMPARE_OP_ALWAYS``), not what the APIs
#: call a disabled test (``glDisable(GL_DEPTH_TEST)``, ``DepthEnable = FALSE``,
#: ``depthTestEnable = VK_FALSE``), which writes no depth (review r261 M1: a box labelled
#: "depth test" behaved like no API's test-off).
DEPTH_TEST_LABEL = "depth test on (untick: ALWAYS, writes on)"

#: Alpha of every triangle of a scene drawn as glass (``glass=True``).
GLASS_ALPHA = 0.5


def glass_frame(name: str, width: int, height: int, **kwargs):
    """A built-in scene drawn as glass: its triangles with their colours (a grey per
    triangle where the scene has none) at alpha :data:`GLASS_ALPHA`, blended "over" in
    submission order onto white with depth writes off, traced: a frame whose pixel
    histories carry the colour before and after every fragment."""
    scene = get_scene(name)
    clip = scene.clip(width / height)
    n = len(clip)
    if "color" in scene.mesh.attrs:
        rgb = scene.mesh.corner("color")[..., :3]
    else:  # one grey per triangle, so layers tell apart
        rgb = np.repeat(np.linspace(0.25, 0.75, max(n, 1))[:n, None, None], 3, axis=1) * [1, 1, 1]
    rgba = np.concatenate([rgb, np.full((n, 3, 1), GLASS_ALPHA)], axis=2)
    return render_clip(clip, width, height, attrs=rgba, blend="over", depth_write=False,
                       clear_color=(1.0, 1.0, 1.0, 1.0), trace=True, **kwargs)  # fmt: skip


_CLICK_ESM = """
function render({ model, el }) {
  const img = document.createElement("img");
  img.style.maxWidth = "100%";
  img.style.cursor = "crosshair";
  img.alt = model.get("alt");
  img.className = "teachraster-figure teachraster-clickable";
  let url = null, clicks = 0;
  const show = () => {
    const blob = new Blob([model.get("value")], { type: "image/png" });
    if (url) URL.revokeObjectURL(url);
    url = URL.createObjectURL(blob);
    img.src = url;
  };
  show();
  model.on("change:value", show);
  img.addEventListener("click", (event) => {
    const box = img.getBoundingClientRect();
    clicks += 1;
    model.set("click", [(event.clientX - box.left) / box.width,
                        (event.clientY - box.top) / box.height, clicks]);
    model.save_changes();
  });
  el.appendChild(img);
  return () => { if (url) URL.revokeObjectURL(url); };
}
export default { render };
"""


def clicked_point(fig, ax, value, *, inside: bool = False):
    """The data point of ``ax`` under a click on the picture of ``fig``, from the click's
    ``value`` (its fraction of the picture from the top left, as :func:`click_image` sends it);
    None for no click, or, with ``inside``, for a click outside ``ax``."""
    if len(value) < 2:
        return None
    width, height = fig.canvas.get_width_height()
    # the picture's fraction from its top left -> display pixels (y up) -> data
    point = (value[0] * width, (1.0 - value[1]) * height)
    if inside and not ax.get_window_extent().contains(*point):
        return None
    return tuple(ax.transData.inverted().transform(point))


def click_image(alt: str = ""):
    """A PNG image widget that reports clicks as ``click`` = [x, y, n] (fractions of its
    width and height from the top left, n counting clicks), or None without anywidget."""
    try:
        import anywidget
        import traitlets
    except ImportError:
        return None

    class ClickImage(anywidget.AnyWidget):
        _esm = _CLICK_ESM
        value = traitlets.Bytes(b"").tag(sync=True)
        click = traitlets.List([]).tag(sync=True)
        alt = traitlets.Unicode("").tag(sync=True)

    return ClickImage(alt=alt)


def marker_xy(row: int, col: int, reach: float = 3.0):
    """(x, y) of the chosen pixel's marker: its outline, then four ticks ``reach`` pixels
    long pointing at it from outside (NaN separates the pieces, one line to update)."""
    r, c, gap = row, col, np.nan
    x = [c, c + 1, c + 1, c, c, gap, c - reach, c - 0.5, gap, c + 1.5, c + 1 + reach, gap,
         c + 0.5, c + 0.5, gap, c + 0.5, c + 0.5]  # fmt: skip
    y = [r, r, r + 1, r + 1, r, gap, r + 0.5, r + 0.5, gap, r + 0.5, r + 0.5, gap,
         r - reach, r - 0.5, gap, r + 1.5, r + 1 + reach]  # fmt: skip
    return x, y


#: The longest line of :func:`quad_text`: shorter than the history table's own lines (at
#: most 80 characters), so that no triangle under the table hides behind its sideways scroll.
QUAD_TEXT_WIDTH = 60


def quad_text(frame, row: int, col: int) -> str:
    """The lines under the history in the quad overshading view: the quad of pixel
    (``row``, ``col``) and how many triangles shaded it, then those triangles, wrapped
    onto as many lines as they need (review r211 11-3: six triangles on one line ran past
    the table's box, and a student counted the five in view), then on a line of its own
    (review r96 11-1) the lanes launched (four per triangle) and the helpers among them
    (the overlay's value there, from the same counts). No line is longer than
    :data:`QUAD_TEXT_WIDTH` characters."""
    r0, c0 = row // 2 * 2, col // 2 * 2
    where = f"quad of rows {r0}–{r0 + 1}, cols {c0}–{c0 + 1}"
    shaded = quad_triangles(frame, row, col)
    if not shaded:
        return f"{where}:\nno triangle shaded a pixel of it, no lanes launched"
    lanes, useful = 4 * len(shaded), sum(shaded.values())
    # the triangles a line at a time, each "188 (1 px)" kept whole on its line
    each, line = [], ""
    for item in (f"{t} ({n} px)" for t, n in shaded.items()):
        if line and len(line) + len(item) + 3 > QUAD_TEXT_WIDTH:  # + ", " and ","
            each.append(line + ",")
            line = ""
        line = f"{line}, {item}" if line else f"  {item}"
    each.append(line)
    return "\n".join([f"{where}: shaded by {len(shaded)} triangle(s):", *each,
                      f"{lanes} lanes launched (4 each), {lanes - useful} helpers "
                      f"({(lanes - useful) / lanes:.0%})"])  # fmt: skip


def _checked_pairs(pairs, frames) -> dict:
    """``pairs`` (name: name of its pair, among ``frames``) made symmetric; errors name it."""
    if pairs is None:
        return {}
    if not frames or not isinstance(pairs, dict):
        raise TypeError(f"pairs must be a dict of frame names and needs frames, got {pairs!r:.60}")
    for name, other in pairs.items():
        if name not in frames or other not in frames or name == other:
            raise ValueError(
                f"pairs must pair two different names of frames, got {name!r}: {other!r}"
            )
    return {**{other: name for name, other in pairs.items()}, **pairs}


def _checked_frames(frames) -> dict | None:
    """``frames`` (name: traced Frame, all one size) or None; errors name the argument."""
    if frames is None:
        return None
    if not isinstance(frames, dict) or not frames:
        raise TypeError(f"frames must be a non-empty dict of name: Frame, got {frames!r:.60}")
    shapes = set()
    for name, frame in frames.items():
        if getattr(getattr(frame, "trace", None), "debug", None) is None:
            raise ValueError(f"frames[{name!r}] must be a Frame rendered with trace=True")
        if getattr(frame, "image", None) is None and frame.color is None:
            raise ValueError(f"frames[{name!r}] has no picture: render RGBA attributes")
        shapes.add(frame.triangle_id.shape)
    if len(shapes) != 1:
        raise ValueError(f"frames must all have one size, got {sorted(shapes)}")
    return dict(frames)


def _picture(frame) -> np.ndarray:
    """What the inspector draws of ``frame`` (its image, else its colour's RGB, NaN as 0),
    or its ``triangle_id`` where it has neither (a frame drawn without a colour buffer)."""
    shown = getattr(frame, "image", None)
    if shown is None and frame.color is not None:
        shown = frame.color[..., :3]
    if shown is None:
        return np.asarray(frame.triangle_id, float)[..., None]
    return np.nan_to_num(np.clip(np.asarray(shown, float), 0, 1), nan=0.0).reshape(
        *frame.triangle_id.shape, -1
    )


def changed_pixel(frame, pair, row: int, col: int, bears=None) -> tuple[int, int]:
    """(row, col) itself where the pictures of ``frame`` and ``pair`` differ there, else the
    pixel nearest it where they differ (ties: the first in reading order), else (row, col):
    where a frame opens beside its pair (review r32 D11-2: every frame opened at (24, 32),
    where seven of exercise 11's nine pairs agree, and the two tables were the same). A
    pixel kept where it differs lets a student carry a pixel from a frame to its look-alike;
    the nearest one is one of many, no answer singled out. ``bears`` (row, col) -> bool, if
    given, narrows "differ" to the changed pixels it accepts (exercise 11: those that bear
    the mark of the frame's mistake, review r298 W2: frame 6 opened where its sliver does
    not pass), asked in order of distance until one is accepted; where it accepts none, the
    rule without it."""
    a, b = _picture(frame), _picture(pair)
    if a.shape != b.shape:  # one with colour, one without: compare what each shows
        a, b = (np.asarray(f.triangle_id, float)[..., None] for f in (frame, pair))
    differs = ~np.isclose(a, b, atol=1e-6).all(axis=2)
    if not differs.any():
        return row, col
    rows, cols = np.nonzero(differs)  # in reading order: a stable sort keeps the first tie
    near = np.argsort((rows - row) ** 2 + (cols - col) ** 2, kind="stable")
    if bears is not None:  # the pixel on show first, if it differs, then the nearest
        first = [k for k in near if (rows[k], cols[k]) == (row, col)]
        for k in first + [k for k in near if (rows[k], cols[k]) != (row, col)]:
            if bears(int(rows[k]), int(cols[k])):
                return int(rows[k]), int(cols[k])
    if differs[row, col]:
        return row, col
    return int(rows[near[0]]), int(cols[near[0]])


#: The history table's font size, alone and with its pair's beside it: 14 px where the window
#: is wide enough (review r82, 11-B: 12 px was too small for the back of a room), never less
#: than a projector's 12 px (the course's rule for text). The table is narrow
#: (:func:`history_table`, at most :data:`NARROW` characters a line): at 12 px it fits a
#: 592-px column (JupyterLab at 1024 x 768 with the file browser open), at 14 px a 674-px
#: one, so the size grows with the window (1.15 % of its width: 12 px up to a 1043-px
#: window, 14 px from 1218 px on), where the column (the window less the ~430-px file
#: browser and margins) holds the lines. Review r18: at 0.8em a table took 615 px and cut
#: "outside E12 by 6.1611 px"; at 0.75em (9.75 px) two fitted side by side, too small to
#: read. Two stand side by side only in a column of 2 x 578 + 24 px or more (at 12 px).
TABLE_FONT = PAIRED_FONT = "clamp(12px, 1.15vw, 14px)"


def _pre(text: str, size: str = TABLE_FONT) -> str:
    """A history table as HTML. Columns kept at any width: JupyterLab wraps a <pre>
    (pre-wrap), which broke every row of the table at 1024 px (review r9, lesson 11); a
    narrow column scrolls instead."""
    return (f"<pre style='font-size:{size};line-height:1.25;white-space:pre;overflow-x:auto'>"
            f"{html.escape(text)}</pre>")  # fmt: skip


def paired_tables(named) -> str:
    """Two history tables, ``named`` [(name, text)], as HTML: side by side where the column
    is wide enough, one under the other where not; each at most the column's width (a flex
    item is as wide as its longest line unless ``min-width:0``: the widget scrolled sideways,
    not the table), a longer line scrolling inside its own table."""
    tables = "".join(f"<div style='min-width:0;max-width:100%'><b>{html.escape(name)}</b>"
                     f"{_pre(text, PAIRED_FONT)}</div>" for name, text in named)  # fmt: skip
    return f"<div style='display:flex;flex-wrap:wrap;gap:0 24px'>{tables}</div>"


def _check_box(value: bool, description: str) -> widgets.Checkbox:
    """A check box as wide as its words (ipywidgets' default indent and 300 px took a row)."""
    return widgets.Checkbox(
        value=value, description=description, indent=False, layout=widgets.Layout(width="auto")
    )


class FrameInspector(Holdable):
    """A built-in scene rendered with ``trace=True``: a view chooser, a pixel's history.

    Parameters
    ----------
    scene : str
        A built-in scene (:data:`teachraster.pipeline.rendering.scenes.SCENES`).
    width, height : int
        Frame size (small frames keep each pixel clickable).
    view : str
        "image" or an overlay kind (:data:`VIEWS`).
    row, col : int
        The pixel whose history is shown first (by default the centre; with ``pairs``, the
        pixel nearest it where the frame and its pair differ: :func:`changed_pixel`).
    samples : {1, 4}
    depth_test : bool
        Unticked, ``depth_test=False``: GL's ``glDepthFunc(GL_ALWAYS)``, depth still written
        (:data:`DEPTH_TEST_LABEL`).
    glass : bool
        Draw the scene as glass (:func:`glass_frame`): the history then shows the colour
        buffer before and after every fragment.
    frames : dict of str to Frame, optional
        Traced frames to inspect instead of the built-in scenes (lesson 11's broken frames):
        the chooser offers their names; samples, depth test and glass then do nothing and
        are not shown.
    pairs : dict of str to str, optional
        With ``frames``: each frame's pair (a broken frame and the one intended). A check box
        then shows the chosen pixel's history in the pair beside its history in the frame on
        show, as an engineer compares two captures in two RenderDoc windows (review r14,
        exercise 11: the inspector showed one frame, the other was read from memory). A frame
        chosen in the list opens at a pixel where it and its pair differ (review r32).
    marks : dict of str to callable, optional
        With ``pairs``: for a frame's name, ``bears(row, col) -> bool``, the changed pixels
        the frame should open at (:func:`changed_pixel`; exercise 11's
        ``ex.frame_marks()``: those that bear the mark of the frame's mistake).
    backend, style
        As for the other widgets.

    Attributes
    ----------
    frame : Frame
        The current frame (traced).
    history : PixelHistory
        The chosen pixel's history; ``table.value`` shows it as text.
    pair_history : PixelHistory or None
        The same pixel's history in the pair of the frame on show, while it is shown beside.

    Examples
    --------
    >>> w = FrameInspector("intersecting_triangles", 32, 24, backend="image")
    >>> w.view.value = "depth_complexity"
    >>> w.row.value, w.col.value = 12, 16
    >>> w.history.row, w.history.col
    (12, 16)
    >>> w.click_at(3.5, 5.5)      # a click at window (x, y): column 3, row 5
    >>> (w.row.value, w.col.value)
    (5, 3)
    >>> w.close()
    """

    #: ``teachraster html``: the offline page steps through every view (the image and each overlay) (:mod:`.offline`)
    _offline_sweep_ = "view"

    def __init__(self, scene: str = "intersecting_triangles", width: int = 64,
                 height: int = 48, *, view: str = "image", row: int | None = None,
                 col: int | None = None, samples: int = 1, depth_test: bool = True,
                 glass: bool = False, frames: dict | None = None, pairs: dict | None = None,
                 marks: dict | None = None, backend: str = "auto",
                 style: str | None = None) -> None:  # fmt: skip
        self.frames = _checked_frames(frames)
        self.pairs = _checked_pairs(pairs, self.frames)
        self.marks = dict(marks or {})
        if self.frames:
            scene = scene if scene in self.frames else next(iter(self.frames))
            height, width = next(iter(self.frames.values())).triangle_id.shape
        self.width, self.height = width, height
        self.backend = resolve_backend(backend)
        choices = list(self.frames) if self.frames else list(SCENES)
        # narrower than ipywidgets' 300 px (the check boxes as wide as their text): at
        # 1024 x 768 with the file browser open (a 592-px column) the controls took 5 lines
        menu, short = widgets.Layout(width="260px"), widgets.Layout(width="150px")
        # labels as wide as their words, not ipywidgets' 80 px: the room goes to the choice
        # (review r159, lesson 11: "nan (0 on built-in scenes)" was cut, 146 px in 142)
        fitted = {"description_width": "initial"}
        self.scene = widgets.Dropdown(options=choices, value=scene, description="scene",
                                      layout=fit_width(menu), style=fitted)  # fmt: skip
        self.view = widgets.Dropdown(options=_views(self.frames, view), value=view,
                                     description="view", layout=menu, style=fitted)  # fmt: skip
        self.samples = widgets.Dropdown(options=[1, 4], value=samples, description="samples",
                                        layout=short)  # fmt: skip
        self.depth_test = _check_box(depth_test, DEPTH_TEST_LABEL)
        self.glass = _check_box(glass, "glass (blend over)")
        # each as wide as the column: ipywidgets' ~125-px track gave ~2 px a step for 48 or
        # 64 values (review r62, lesson 11 #4)
        self.row = widgets.IntSlider(value=height // 2 if row is None else row, min=0,
                                     max=height - 1, description="row",
                                     layout=widgets.Layout(width=SLIDER_COLUMN_WIDTH))  # fmt: skip
        self.col = widgets.IntSlider(value=width // 2 if col is None else col, min=0,
                                     max=width - 1, description="col",
                                     layout=widgets.Layout(width=SLIDER_COLUMN_WIDTH))  # fmt: skip
        if self.pairs and row is None and col is None:  # open where the pair differs
            pair = self.frames[self.pairs[scene]] if scene in self.pairs else None
            if pair is not None:
                self.row.value, self.col.value = changed_pixel(
                    self.frames[scene],
                    pair,
                    self.row.value,
                    self.col.value,
                    self.marks.get(scene),
                )
        self.beside = _check_box(bool(self.pairs), "its pair beside")
        # the table scrolls sideways in its own box where the column is narrower than its
        # lines (a 315-px column at 1024 x 768 and 150 %): its content is as wide as its
        # longest line, and without this the whole widget scrolled
        self.table = widgets.HTML(layout=widgets.Layout(overflow="auto hidden", max_width="100%"))
        self._render()
        with style_context(style):
            self.fig = new_figure((5.0, 3.9), self.backend)  # sized by _fit_figure
            self.ax = self.fig.add_axes((0.17, 0.06, 0.6, 0.8))
            # the overlays' colour bar: one Axes of its own, reused, so that changing the
            # view never takes room from the frame (a colour bar made with ax= would)
            self.cax = self.fig.add_axes((0.8, 0.14, 0.028, 0.64))
            self.hist_fig = new_figure(HISTORY_SIZE, self.backend)
            # room for written-out depths (0.9676) and two-line sample labels under MSAA;
            # placed by _fit_history
            self.hist_ax = self.hist_fig.add_axes((0.26, 0.24, 0.71, 0.66))
            self._draw_frame()
            self._draw_history()
            self._make_displays()
        # first: the pixel moves where the pair differs, then the frame is drawn there
        self.scene.observe(self._to_changed_pixel, "value")
        for control in (self.scene, self.samples, self.depth_test, self.glass):
            control.observe(self._rerender, "value")
            control.disabled = bool(self.frames) and control is not self.scene
        self.view.observe(self._view_changed, "value")
        self.beside.observe(self._beside_changed, "value")
        for control in (self.row, self.col):
            control.observe(self._pixel_changed, "value")
        title = title_html(
            "Frame inspector: why is this pixel what it is?",
            "Choose a view; click a pixel (or move row and col) to see every triangle on the "
            "way to it, in submission order, and the test that stopped each.",
        )
        # what is shown (scene, view) and how it is rendered: two rows, each wrapping. Given
        # frames, the second row does nothing: left out, not greyed out (review r11, 11-F:
        # disabled controls read as broken ones)
        rows = [control_row([self.scene, self.view, *([self.beside] if self.pairs else [])])]
        if not self.frames:
            rows.append(control_row([self.samples, self.depth_test, self.glass]))
        controls = widgets.VBox(rows)
        # r21 D3, r62 #4: the table(s) right under the picture, then the chart (below both
        # figures they stood ~700 px under the picture clicked). Not beside the picture in
        # one row: at 1024 x 768 and 150 % the table's lines (479 px) were cut in a 315-px
        # row, where straight in the box they scroll
        figures = [picture_row([self.frame_widget]), self.table,
                   picture_row([self.hist_display.widget])]  # fmt: skip
        # the two sliders straight in the box, as the TileExplorer's block slider: 100 % wide in a
        # wrapping row they would overflow it by their margins
        self.widget = widgets.VBox([title, controls, self.row, self.col, *figures])

    # -- state ---------------------------------------------------------------------------
    def _render(self) -> None:
        options = dict(samples=self.samples.value, depth_test=self.depth_test.value)
        if self.frames:
            self.frame = self.frames[self.scene.value]
        elif self.glass.value:
            self.frame = glass_frame(self.scene.value, self.width, self.height, **options)
        else:
            self.frame = render(get_scene(self.scene.value), None, self.width, self.height,
                                trace=True, **options)  # fmt: skip
        self._show_history()

    def _show_history(self) -> None:
        row, col = self.row.value, self.col.value
        self.history = self.frame.history(row, col)
        pair = self.pairs.get(self.scene.value) if self.beside.value else None
        self.pair_history = None if pair is None else self.frames[pair].history(row, col)
        # r21 D4: the pair's two tables with the same columns, so their rows line up
        text = history_table(self.history, narrow=True, like=self.pair_history, fold=True)
        if self.view.value == "quad_overshading":  # who launched this quad's lanes
            text += "\n\n" + quad_text(self.frame, row, col)
        if self.pair_history is None:
            self.table.value = _pre(text)
            return
        beside = history_table(self.pair_history, narrow=True, like=self.history, fold=True)
        self.table.value = paired_tables(((self.scene.value, text), (pair, beside)))

    def _bar_room(self) -> float:
        """Inches under the colour bar that its ticks and label take, as drawn, and a
        little more (a fixed room would cut a two-line label or leave a short one's empty)."""
        canvas = self.fig.canvas
        renderer = canvas.get_renderer() if hasattr(canvas, "get_renderer") else None
        if renderer is None:
            return FRAME_MARGINS[-1]
        low = self.cax.get_tightbbox(renderer).y0 / self.fig.dpi
        return self.cax.get_position().y0 * self.fig.get_size_inches()[1] - low + 0.06

    def _fit_figure(self, label: float | None = None) -> None:
        """Size the frame's figure to what it draws: the frame at its own aspect (no band
        above and below it), the labels left of and above it, and the colour bar's room
        under it only in a view that has one (an empty band in the image view: review r12,
        exercise 11), ``label`` inches for its ticks and label (:meth:`_bar_room`; by
        default :data:`FRAME_MARGINS`'). The width is the same in every view (review r44
        D2); the frame keeps its size and its place from the top left."""
        scale = min(FRAME_BOX[0] / self.width, FRAME_BOX[1] / self.height)  # inches a pixel
        w, h = self.width * scale, self.height * scale
        left, top, edge, gap, bar, room = FRAME_MARGINS
        label = room if label is None else label
        below = gap + bar + label if self.view.value != "image" else edge
        fw, fh = left + w + edge, below + h + top
        if not np.allclose(self.fig.get_size_inches(), (fw, fh)):  # a live canvas resizes
            self.fig.set_size_inches(fw, fh)
        self.ax.set_position((left / fw, below / fh, w / fw, h / fh))
        inset = 0.06 * w  # the bar a little shorter than the frame: its end ticks' room
        self.cax.set_position(((left + inset) / fw, label / fh, (w - 2 * inset) / fw,
                               bar / fh))  # fmt: skip

    def _draw_frame(self) -> None:
        ax = self.ax
        clear_axes(ax)
        self.cax.set_visible(self.view.value != "image")
        self._fit_figure()
        if self.view.value == "image":
            shown = getattr(self.frame, "image", None)
            if shown is None or self.glass.value:
                shown = self.frame.color[..., :3]
            image = np.where(np.isnan(shown), 1.0, np.clip(shown, 0, 1))
            plot_image(ax, image)
            glass = " (glass)" if self.glass.value else ""  # what is drawn (review r8, 11)
            # r21 D9: a frame handed in is named by its key ("frame 1"), a scene is not
            name = self.scene.value if self.frames else f"{self.scene.value}: the frame"
            ax.set_title(f"{name}{glass}", fontsize="small")
        else:
            plot_overlay(ax, self.frame, self.view.value, cax=self.cax,
                         orientation="horizontal")  # fmt: skip
            self._fit_figure(self._bar_room())  # the ticks and label as drawn (review r18)
            # the label centred on the figure, not on the bar (which lies right of the row
            # labels): "samples passed depth, per pixel" is wider than the bar
            box = self.cax.get_position()
            self.cax.xaxis.label.set_x((0.5 - box.x0) / box.width)
        # where triangles meet (r90 11-4: fan's hub), in every view, and every submitted
        # triangle, dashed where it covers no centre (r298 W1: the sliver was in none)
        plot_triangle_edges(ax, self.frame)
        fit_title(ax)
        # the pixel's outline and four ticks pointing at it, with a white halo: one pixel of
        # a 64-pixel frame must be found on a projector, on any colour
        self.marker = ax.plot(*marker_xy(self.row.value, self.col.value), color="#D55E00",
                              lw=2, zorder=6, solid_capstyle="butt",
                              path_effects=[withStroke(linewidth=4.5, foreground="white")])[0]  # fmt: skip

    def _fit_history(self) -> None:
        """Size the history chart to what it draws: :data:`HISTORY_COLOUR_WIDTH` wide where
        the history has a colour buffer (swatches above the depths), else
        :data:`HISTORY_SIZE`; the Axes keeps its margins in inches (:data:`HISTORY_AXES`)."""
        width = HISTORY_COLOUR_WIDTH if self.history.blend is not None else HISTORY_SIZE[0]
        if not np.isclose(self.hist_fig.get_size_inches()[0], width):  # a live canvas resizes
            self.hist_fig.set_size_inches(width, HISTORY_SIZE[1])
        left, right, bottom, height = HISTORY_AXES
        self.hist_ax.set_position((left / width, bottom, (width - left - right) / width, height))

    def _draw_history(self) -> None:
        self._fit_history()
        clear_axes(self.hist_ax)
        plot_history(self.hist_ax, self.history)
        if self.frames:  # r22 D1: whose history, as the chart stands under the pair's table
            self.hist_ax.set_title(self.history_title(), fontsize="small")
            fit_title(self.hist_ax)

    def history_title(self) -> str:
        """The chart's title: the frame whose history it draws (with the pair's table shown
        beside, the frame on display: "frame 5 (on display): row 23, col 41"), so that a
        chart under the pair's table is not read as the pair's (review r22, D1). Short enough
        to keep its size in the classroom style ("intended 5 (on display): pixel (row 23,
        col 41)" shrank to 11.8 px)."""
        row, col = self.history.row, self.history.col
        if not self.frames:
            return f"pixel (row {row}, col {col})"
        if self.pair_history is None:
            return f"{self.scene.value}: pixel (row {row}, col {col})"
        return f"{self.scene.value} (on display): row {row}, col {col}"

    # -- display -------------------------------------------------------------------------
    def _make_displays(self) -> None:
        self.hist_display = FigureDisplay(self.hist_fig, self.backend)
        self.clicker = None
        if self.backend == "ipympl":
            self.frame_display = FigureDisplay(self.fig, "ipympl")
            self.frame_widget = self.frame_display.widget
            self.fig.canvas.mpl_connect("button_press_event", self._on_press)
            return
        self.frame_display = None
        self.clicker = click_image(alt="the frame: click a pixel for its history")
        if self.clicker is None:
            self.frame_display = FigureDisplay(self.fig, "image")
            self.frame_widget = self.frame_display.widget
            return
        self.clicker.observe(self._on_click, "click")
        self.frame_widget = self.clicker
        self._refresh_frame()

    def _refresh_frame(self) -> None:
        if self.frame_display is not None:
            self.frame_display.refresh()
            return
        self.fig.canvas.draw()
        self.clicker.value = png_bytes(self.fig)

    def _refresh(self, frame: bool = True) -> None:
        if frame:
            self._refresh_frame()
        self.hist_display.refresh()

    # -- events --------------------------------------------------------------------------
    def click_at(self, x: float, y: float) -> None:
        """Choose the pixel under window point (x, y) (pixels, y down), as a click does."""
        col, row = int(np.floor(x)), int(np.floor(y))
        if 0 <= row < self.height and 0 <= col < self.width:
            with self._holding():
                self.row.value, self.col.value = row, col
            self._pixel_changed(None)

    def _on_press(self, event) -> None:
        if event.inaxes is self.ax and event.xdata is not None:
            self.click_at(event.xdata, event.ydata)

    def _on_click(self, change) -> None:
        point = clicked_point(self.fig, self.ax, change["new"])
        if point is not None:
            self.click_at(*point)

    def _pixel_changed(self, change) -> None:
        if self._quiet:
            return
        self._show_history()
        self.marker.set_data(*marker_xy(self.row.value, self.col.value))
        self._draw_history()
        self._refresh()

    def _beside_changed(self, change) -> None:
        self._show_history()
        self._draw_history()  # the chart's title says whether a pair is beside
        self.hist_display.refresh()

    def _view_changed(self, change) -> None:
        self._show_history()  # the quad overshading view adds the quad's triangles
        self._draw_frame()
        self._refresh_frame()

    def _to_changed_pixel(self, change) -> None:
        """A frame chosen beside its pair opens at a pixel where the two differ
        (:func:`changed_pixel`); the pixel is set quietly, then :meth:`_rerender` (observing
        the chooser after this) draws the frame, its marker and the history there."""
        pair = self.pairs.get(self.scene.value)
        if pair is None:
            return
        at = changed_pixel(self.frames[self.scene.value], self.frames[pair], self.row.value,
                           self.col.value, self.marks.get(self.scene.value))  # fmt: skip
        with self._holding():
            self.row.value, self.col.value = at

    def _rerender(self, change) -> None:
        self._render()
        self._draw_frame()
        self._draw_history()
        self._refresh()

    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)

    # a saved notebook reopened without a kernel shows its last picture, not "model not found"
    _ipython_display_ = Shown._ipython_display_
    noun = "inspector"  # the stand-in's hint: "No kernel is running this inspector"

    def close(self) -> None:
        """Close every widget of the inspector."""
        for display in (self.frame_display, self.hist_display):
            if display is not None:
                display.close()
        close_tree(self.widget)
        for control in (self.samples, self.depth_test, self.glass, self.beside):  # maybe not in it
            control.close()
