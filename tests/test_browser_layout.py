"""Every widget a lesson shows stays usable on a projector, in JupyterLab and Notebook 7.

The browser probe of 2026-12-01 (issue 31, ``../shared/reviews/browser-2026-12-01.md`` §8)
found, at 1024×768 with JupyterLab's file browser open and at 150 % zoom, the
FrameInspector's frame shrunk to a 105–130 px thumbnail with its controls off screen, the
player's controls wrapped into six rows, CasePicker's titles colliding, and labels cut
("forma", "rule", "sort back to fro"). One notebook shows every widget class the lessons
show (small scenes, the lessons' classroom style); it runs once per front end and the same
page is measured at each size (the page resized, never run again). At each size, in each
widget's output:

- every picture (an ``img`` or ``canvas`` of a figure) is at least :data:`READABLE` CSS px
  wide, or as wide as it is drawn, or most of the column, when that is less: not shrunk to a
  thumbnail;
- every control and picture lies inside the output area and the window, horizontally: none
  cut off or off screen;
- each row of controls (a flex row holding controls) takes at most :data:`MOST_ROWS` lines,
  the page-side player's bar at most :data:`MOST_BAR_LINES`;
- no label, readout or button cuts its text (``scrollWidth <= clientWidth``), no row of
  controls is wider than its box (cut at the column's edge, or scrolled), and the widget's
  own box does not scroll sideways.

Uses the JupyterLab server and page of tests/test_browser.py; skipped, saying why, where
Playwright or Chromium is missing (CI makes them required).
"""

from __future__ import annotations

import pytest
from notebook_browser import _FINISHED, POLL_MS
from test_browser import WHY, lab, page  # noqa: F401
from test_browser_player import _run

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]

SETUP = """\
import numpy as np
import teachraster as tr
from teachraster.plotting import use_style
from teachraster import widgets as w
from teachraster.widgets.divide_cost import DivideCostExplorer
from teachraster.widgets.sampling_explorer import SamplingExplorer
style = use_style("classroom")  # as the lessons run (large fonts: larger figures)
tri = tr.Triangle([[1.2, 1.5], [13.7, 4.2], [5.1, 12.8]])
tri_u = tr.Triangle([[1.5, 2.25], [14.75, 5.5], [4.25, 14.5]], w=[1.0, 2.0, 4.0],
                    attrs={"u": [0.0, 1.0, 0.0]})  # lesson 04's
rows = [{"variant": v, "group": "interpolation", "divides": d, "multiplies": m,
         "additions": a, "error": 2 * e, "mean_abs_texels": e, "cycles": 1.0}
        for v, d, m, a, e in [("affine", 0, 6, 6, 3.0), ("subdivided N=16", 0.2, 9, 9, 0.6),
                              ("perspective", 2, 12, 10, 0.0)]]  # lesson 06's shape, made up"""

#: (name, cell): every widget class a lesson shows, at a lesson's size or smaller (the
#: figures' size on screen does not depend on the grid's)
WIDGETS = [
    ("FillPlayer", "w.FillPlayer(tri, 16, 16, method='halfplane')"),
    (
        "FillPlayer compared",
        "p = w.FillPlayer(tri_u, 16, 16, method='halfplane', step=-1)\n"
        "p.comparison.selected_index = 0  # open: the steps fold\np",
    ),
    ("TriangleEditor", "w.TriangleEditor(tri_u, 16, 16, method='halfplane', comparison=False)"),
    ("FrameInspector", "w.FrameInspector('intersecting_triangles', 32, 24, view='image')"),
    ("PixelInspector", "w.PixelInspector(tri, 16, 12, row=3, col=9)"),
    ("CasePicker", "w.CasePicker('fan_spokes_through_centres')"),
    ("TileExplorer", "w.TileExplorer(tri, 32, 32, block_sizes=(16, 4, 1))"),
    ("DepthPrecisionExplorer", "w.DepthPrecisionExplorer('unorm16', near=0.1, far=100.0)"),
    ("TexturedPlaneViewer", "w.TexturedPlaneViewer(64, 48, tilt=60, checks=4)"),
    ("FilterExplorer", "w.FilterExplorer(48, 36, tilt=0, filter='nearest', repeats=6)"),
    ("PlaneExplorer", "w.PlaneExplorer()"),
    ("LinePlayer", "w.LinePlayer((0.5, 0.5), (12.5, 5.5), 14, 7, rule='bresenham')"),
    ("BlendingExplorer", "w.BlendingExplorer(size=(24, 24))"),
    ("ProjectionExplorer", "w.ProjectionExplorer()"),
    (
        "ZBufferStepper",
        "w.ZBufferStepper(tr.render(tr.get_scene('cube'), None, 24, 18, trace=True))",
    ),
    ("SamplingExplorer", "SamplingExplorer(rate=32)"),
    ("DivideCostExplorer", "DivideCostExplorer(rows)"),
    (
        "Predict",
        "w.Predict('Which way does it wind?', ['clockwise', 'counter-clockwise'], "
        "'clockwise', explain='The signed area is positive.')",
    ),
    (
        "PredictPixels",
        "w.PredictPixels('Click the pixels this triangle covers.', "
        "answer=tr.rasterize(tri, 8, 8).coverage)",
    ),
    (
        "PredictPoint",
        "w.PredictPoint('Where?', answer=(1.0, 2.0), draw=None, xlim=(0, 4), ylim=(0, 4))",
    ),
    ("PredictOrder", "w.PredictOrder('Nearest first?', ['a', 'b', 'c'], answer=['b', 'a', 'c'])"),
    ("PipelineMap", "w.PipelineMap()"),
    ("CrackExplorer", "w.CrackExplorer(8, 8)"),
    ("EdgeFunctionExplorer", "w.EdgeFunctionExplorer()"),
    ("AttributeSurfaces", "w.AttributeSurfaces()"),
    ("EyeRayExplorer", "w.EyeRayExplorer()"),
    ("DepthValuesExplorer", "w.DepthValuesExplorer()"),
    ("FootprintExplorer", "w.FootprintExplorer(24, 18)"),
    ("DiamondExplorer", "w.DiamondExplorer((1.5, 1.5), (6.4, 3.6), 8, 5)"),
]

#: A picture narrower than this (CSS px) is a thumbnail: at 1024×768 the probe found the
#: FrameInspector's frame at 105–130 px with tick labels of 6–7 px.
READABLE = 300
#: Lines a row of controls may wrap into (the player's took six at 150 %).
MOST_ROWS = 3
#: Lines the page-side player's bar (buttons, step slider, step, speed) may take: it took
#: three in a 315-px column (its slider on a line of its own) until it hid Play's word there.
MOST_BAR_LINES = 2

#: Window sizes (CSS px) and device pixel ratio. 150 % zoom is a 1400×900 window zoomed to
#: 150 %: Chromium's page zoom lays the page out in a 933×600 CSS-px viewport with
#: devicePixelRatio 1.5, which is what is emulated here (Emulation.setDeviceMetricsOverride);
#: CSS ``zoom`` on the page instead would leave the viewport 1400 px wide for JupyterLab's
#: layout (its panels measure in unzoomed pixels), so it would not narrow the column as a
#: real zoom does. JupyterLab keeps its file browser open (its default) at every size.
SIZES = {
    "1400x900": (1400, 900, 1),
    "1024x768": (1024, 768, 1),
    "150%": (933, 600, 1.5),
    # the probe's worst case: a 1024x768 projector at 150 % with the file browser open (a
    # 315-px column), where the player's controls took six rows
    "1024x768 at 150%": (683, 512, 1.5),
}

#: Per widget output (one per code cell after the first): what the assertions read.
MEASURE = """([readable]) => {
  const vw = document.documentElement.clientWidth;
  const visible = e => e.offsetWidth > 0 && e.offsetHeight > 0 && e.getClientRects().length
      && getComputedStyle(e).visibility !== 'hidden';
  const CONTROL = 'button, input:not([type=hidden]), select, textarea, .widget-readout, '
      + '.widget-label, .noUi-target';
  const TEXT = '.widget-label, .widget-readout, button, .widget-inline-hbox label';
  const SLACK = 3;  // px: ipywidgets' 2-px margin around a picture 100 % wide
  const WIDGET = '.jp-OutputArea-output.lm-Panel';  // a widget's view (no mime type)
  const cells = [...document.querySelectorAll('.jp-Notebook .jp-CodeCell')].slice(1);
  return cells.map(cell => {
    const out = [...cell.querySelectorAll('.jp-OutputArea-output')]
        .find(o => visible(o) && o.matches(WIDGET));
    if (!out) return null;
    const box = out.getBoundingClientRect();
    const left = Math.max(box.left, 0), right = Math.min(box.right, vw);
    const pictures = [...out.querySelectorAll('img, canvas')].filter(visible).map(p => {
      const r = p.getBoundingClientRect();
      const natural = p.tagName === 'IMG' ? p.naturalWidth
          : p.width / (p.dataset.scale ? +p.dataset.scale : window.devicePixelRatio);
      return {tag: p.tagName, w: Math.round(r.width), natural: Math.round(natural),
              left: r.left, right: r.right};
    }).filter(p => p.natural >= 100);  // icons and sprites are not pictures
    // narrower than readable only where the column is (less an accordion's inset)
    const small = pictures.filter(p => p.w < Math.min(readable, p.natural, 0.85 * (right - left)) - 1)
        .map(p => `${p.tag} ${p.w} of ${p.natural} px`);
    const outside = [...out.querySelectorAll(CONTROL + ', img, canvas')].filter(visible)
        .map(e => [e, e.getBoundingClientRect()])
        .filter(([e, r]) => r.left < left - SLACK || r.right > right + SLACK)
        .map(([e, r]) => `${e.tagName.toLowerCase()} '${(e.textContent || e.getAttribute('aria-label')
            || '').trim().slice(0, 20)}' ${Math.round(r.left)}..${Math.round(r.right)}`);
    const cut = [...out.querySelectorAll(TEXT)].filter(visible)
        .filter(e => e.scrollWidth > e.clientWidth + 1 && e.textContent.trim())
        .map(e => `'${e.textContent.trim().slice(0, 20)}' ${e.clientWidth} of ${e.scrollWidth}`);
    const wide = [...out.querySelectorAll('.widget-hbox, .tr-bar')].filter(visible)
        .filter(r => r.scrollWidth > r.clientWidth + 1)
        .map(r => `'${r.textContent.trim().slice(0, 20)}' ${r.clientWidth} of ${r.scrollWidth}`);
    // rows: the lines each flex row holding controls wraps its items into
    const isRow = e => { const s = getComputedStyle(e);
      return s.display.endsWith('flex') && s.flexDirection.startsWith('row'); };
    const linesOf = row => {
      const items = [...row.children].filter(visible).map(c => c.getBoundingClientRect())
          .sort((a, b) => a.top - b.top);
      let n = 0, bottom = -Infinity;
      for (const r of items) if (r.top >= bottom - 2) { n += 1; bottom = r.bottom; }
        else bottom = Math.max(bottom, r.bottom);
      return n;
    };
    // the widget's own box (the outermost): a picture 100 % wide plus ipywidgets' margins
    // scrolled the PixelInspector's box sideways by 4 px (review r194)
    const own = out.querySelector('.widget-vbox, .widget-hbox, .widget-box');
    const scrolls = own && visible(own) && own.scrollWidth > own.clientWidth + 1
        ? [`${own.clientWidth} of ${own.scrollWidth}`] : [];
    const lines = [...out.querySelectorAll('*')]
        .filter(e => visible(e) && isRow(e) && e.querySelector(CONTROL)).map(linesOf);
    // the page-side player's bar: its buttons, step slider, step and speed
    const bar = [...out.querySelectorAll('.tr-bar')].filter(visible).map(linesOf);
    const toggles = [...out.querySelectorAll('.widget-toggle-buttons')].filter(visible)
        .map(g => new Set([...g.querySelectorAll('button')].map(b => b.offsetTop)).size);
    return {width: Math.round(right - left), toggles: Math.max(0, ...toggles), dpr: window.devicePixelRatio, pictures: pictures.map(p => p.w),
            small, outside, cut, wide, scrolls, rows: Math.max(0, ...lines), bar: Math.max(0, ...bar)};
  });
}"""


#: every widget's view is in the page (its picture may follow)
SHOWN = """() => [...document.querySelectorAll('.jp-Notebook .jp-CodeCell')].slice(1)
    .every(c => c.querySelector('.jp-OutputArea-output.lm-Panel > .lm-Widget'))"""
NOT_SHOWN = """() => [...document.querySelectorAll('.jp-Notebook .jp-CodeCell')].slice(1)
    .map((c, i) => [i, c.querySelector('.jp-OutputArea').innerText.slice(0, 200)])
    .filter(([i, t]) => !document.querySelectorAll('.jp-Notebook .jp-CodeCell')[i + 1]
        .querySelector('.jp-OutputArea-output.lm-Panel > .lm-Widget'))"""


def _resize(tab, size: str, redrawn: bool = True) -> None:
    """Lay the page out at ``size`` (and, with ``redrawn``, give the widgets that follow their
    width the time to redraw). The zoom's override lasts as long as the DevTools session that
    set it (it ends with the session): the session is kept on the page until the next size."""
    width, height, scale = SIZES[size]
    zoom = getattr(tab, "_tr_zoom", None)
    if zoom is not None:
        zoom.detach()  # its override ends
        tab._tr_zoom = None
    tab.set_viewport_size({"width": width, "height": height})
    if scale != 1:
        tab._tr_zoom = tab.context.new_cdp_session(tab)
        tab._tr_zoom.send("Emulation.setDeviceMetricsOverride", {
            "width": width, "height": height, "deviceScaleFactor": scale, "mobile": False})  # fmt: skip
    if redrawn:
        tab.wait_for_timeout(1500)  # widgets that follow their width redraw (ResizeObserver)


def _measure(tab, base: str, app: str) -> dict:
    cells = [SETUP] + [cell for _, cell in WIDGETS]
    _run(tab, base, cells, f"layout_{app.split('/')[0]}.ipynb", app=app)
    try:
        tab.wait_for_function(_FINISHED, arg=len(cells), timeout=300_000, polling=POLL_MS)
    except Exception:  # noqa: BLE001 (say which cells had not run: timed out once under load)
        prompts = tab.evaluate("""() => [...document.querySelectorAll(
            '.jp-Notebook .jp-CodeCell .jp-InputPrompt')].map(p => p.textContent.trim())""")
        raise AssertionError(f"the cells had not all run in 300 s; prompts: {prompts}") from None
    failed = tab.locator('.jp-OutputArea-output[data-mime-type="application/vnd.jupyter.error"]')
    assert not failed.count(), failed.first.inner_text()[-3000:]
    try:
        tab.wait_for_function(SHOWN, timeout=120_000, polling=POLL_MS)
    except Exception:  # noqa: BLE001 (say which)
        raise AssertionError(f"no widget shown: {tab.evaluate(NOT_SHOWN)}") from None
    tab.wait_for_timeout(3000)  # pictures arrive after the views
    found = {}
    try:
        for size in SIZES:
            _resize(tab, size)
            found[size] = dict(zip([n for n, _ in WIDGETS],
                                   tab.evaluate(MEASURE, [READABLE]), strict=True))  # fmt: skip
    finally:  # the page back to its size; nothing is measured after it, so no redraw awaited
        _resize(tab, "1400x900", redrawn=False)
    return found


#: (size, widget, what) known and open. Empty: the FrameInspector's box scrolled in a 315-px
#: column (479 px: its history table's lines) until the table scrolled in its own box.
KNOWN: set = set()


def _problems(found: dict) -> list:
    bad = []
    for size, widgets in found.items():
        for name, m in widgets.items():
            if m is None:
                bad.append((size, name, "not shown"))
                continue
            for what in ("small", "outside", "cut", "wide", "scrolls"):
                if m[what] and (size, name, what) not in KNOWN:
                    bad.append((size, name, what, m[what][:3]))
            if m["rows"] > MOST_ROWS:
                bad.append((size, name, "rows", m["rows"]))
            if m["bar"] > MOST_BAR_LINES:
                bad.append((size, name, "player bar lines", m["bar"]))
    return bad


@pytest.mark.parametrize("app", ["lab/tree", "notebooks"])
def test_every_widget_is_usable_at_projector_sizes(lab, page, app):  # noqa: F811
    found = _measure(page, lab, app)
    if app == "lab/tree":
        assert page.locator(".jp-FileBrowser").first.is_visible()  # the sidebar takes room
    for size, widgets in found.items():  # the table, shown when the test fails
        for name, m in widgets.items():
            print(f"{app:9} {size:9} {name:24} {m}")
    assert _problems(found) == []
    for size in SIZES:  # the player's bar is there and measured, at every size
        assert found[size]["FillPlayer"]["bar"] >= 1, size
    for size in ("1400x900", "1024x768"):  # the format's toggles on one line (they took 2)
        assert found[size]["DepthPrecisionExplorer"]["toggles"] == 1, size
    assert not page.errors, page.errors[:3]


#: The left edge of each control label's text in the DivideCostExplorer's row, by its text.
LABEL_LEFTS = """() => {
    const out = {};
    for (const el of document.querySelectorAll('.widget-label')) {
        const text = el.textContent.trim();
        if (!['divide =', 'error'].includes(text) || !el.firstChild) continue;
        const range = document.createRange();
        range.selectNodeContents(el);
        out[text] = Math.round(range.getBoundingClientRect().left);
    }
    return out;
}"""


@pytest.fixture(scope="module")
def divide_cost(lab, page):  # noqa: F811
    """One DivideCostExplorer run for the module's two tests of it (each measures the page,
    neither changes it: the resize is undone); a worker that runs only one builds its own."""
    cells = [SETUP, "DivideCostExplorer(rows)"]
    _run(page, lab, cells, "divide_cost.ipynb")
    page.wait_for_function(_FINISHED, arg=len(cells), timeout=300_000, polling=POLL_MS)
    page.locator(".widget-label:text-is('error')").wait_for(timeout=120_000)
    page.locator(".tr-readout .widget-readout").first.wait_for(timeout=120_000)
    return page


def test_the_divide_cost_labels_line_up_when_the_row_wraps(divide_cost):
    """Review r24 06-8: at 1024 x 768 (a 592-px column) the "error" label wraps under the
    slider flush left, while "divide =" sat right-aligned in the slider's description box,
    indented: the two labels start at the same left edge (within a widget's margin)."""
    tab = divide_cost
    try:
        _resize(tab, "1024x768")
        lefts = tab.evaluate(LABEL_LEFTS)
        top = tab.evaluate("""() => [...document.querySelectorAll('.widget-label')]
            .filter(e => ['divide =', 'error'].includes(e.textContent.trim()))
            .map(e => Math.round(e.getBoundingClientRect().top))""")
    finally:
        _resize(tab, "1400x900", redrawn=False)
    assert set(lefts) == {"divide =", "error"}, lefts
    assert len(set(top)) == 2, top  # the row wrapped (else there is nothing to line up)
    assert abs(lefts["divide ="] - lefts["error"]) <= 4, lefts


#: Each DivideCostExplorer slider's label and read-out: their text and computed font sizes.
READOUT_SIZES = """() => [...document.querySelectorAll('.tr-readout')].map(s => {
    const label = s.querySelector('.widget-label'), readout = s.querySelector('.widget-readout');
    return [label.textContent.trim(), readout.textContent.trim(),
            parseFloat(getComputedStyle(label).fontSize),
            parseFloat(getComputedStyle(readout).fontSize)];
})"""


def test_the_divide_cost_readouts_are_as_large_as_their_labels(divide_cost):
    """Review r243 FIG1: the sliders' read-outs ("17", "2") were JupyterLab's 13 px beside their
    16-px labels ("divide =", "attributes k ="), the smallest text on the widget: they are at
    least their labels' size."""
    tab = divide_cost
    sizes = tab.evaluate(READOUT_SIZES)
    assert [s[:2] for s in sizes] == [["divide =", "17"], ["attributes k =", "2"]], sizes
    assert all(readout >= max(16, label) for _, _, label, readout in sizes), sizes
    assert not tab.errors, tab.errors[:3]
