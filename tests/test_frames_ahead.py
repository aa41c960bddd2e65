"""Pictures drawn ahead (``teachraster.widgets.ahead``): a slider explorer's figure at every
position of its slider, drawn while the kernel idles and sent to the page against the
figure's reference picture. Each must be the draft the kernel draws at that position, with
its caption (``FilterExplorer``: the full picture, which a release there then need not
send); drawing them must leave the explorer as it was; nothing is drawn before a page
listens; another control starts them again. (The page side: tests/test_browser_ahead.py.)"""

from __future__ import annotations

import zlib

import numpy as np
import pytest

from teachraster.widgets import FilterExplorer, LiveSlider, TexturedPlaneViewer
from teachraster.widgets.ahead import MOST_POSITIONS, slider_positions
from teachraster.widgets.depth_explorer import DepthPrecisionExplorer


def _make(name):
    if name == "viewer":
        ex = TexturedPlaneViewer(64, 48, tilt=30.0, backend="image")
        return ex, ex.tilt
    if name == "filter":
        ex = FilterExplorer(48, 36, tilt=80.0, samples=3, backend="image")
        return ex, ex.tilt
    if name == "tiles":
        import teachraster as tr
        from teachraster.widgets import TileExplorer

        tri = tr.Triangle([[1.2, 1.7], [30.5, 6.3], [9.1, 29.4]])
        ex = TileExplorer(tri, 32, 32, block_sizes=(16, 4, 1), backend="image")
        return ex, ex.level
    if name == "sampling":  # two sliders: the positions of the one moved last (samples)
        from teachraster.widgets.sampling_explorer import SamplingExplorer

        ex = SamplingExplorer(width=1.0, backend="image")
        return ex, ex.rate
    if name == "projection":
        from teachraster.widgets import ProjectionExplorer

        ex = ProjectionExplorer(q=0.3, backend="image")
        return ex, ex.q
    if name == "plane":  # nine sliders: the positions of the one moved last (v1 x)
        from teachraster.widgets import PlaneExplorer

        ex = PlaneExplorer(backend="image")
        ex.x[0].value = 3.0
        return ex, ex.x[0]
    ex = DepthPrecisionExplorer(backend="image")
    return ex, ex.near


def _listen(ex, slider):
    """The explorer's page messages, kept; the page says it listens."""
    page, sent = ex.display.widget, []
    page.send = lambda content, buffers=None: sent.append((content, buffers))
    slider.send = lambda content, buffers=None: None
    page._on_page_message(page, {"type": "ready"}, [])
    return page, sent


def _pictures(sent, ref) -> dict:
    """(slider, position) -> (picture, caption) from the "ahead" messages, the reference
    patched."""
    out = {}
    for content, buffers in sent:
        if content["type"] != "ahead":
            continue
        for entry, data in zip(content["entries"], buffers):
            pic = ref.copy()
            x, y, w, h = entry["place"]
            if w:
                raw = zlib.decompress(data) if entry["deflate"] else data
                pic[y : y + h, x : x + w] = np.frombuffer(raw, np.uint8).reshape(h, w, 4)
            out[entry["slider"], entry["k"]] = pic, entry["caption"]
    return out


def _draw_slider(ahead) -> None:
    """Draw the pictures of the slider moved last (the others' follow them), one a step: a
    batch of some seconds' drawing may reach into the next slider's."""
    while ahead.todo and ahead.todo[0][0] == ahead.which and ahead.step():
        pass


def _draw_ahead_until(ahead, k) -> None:
    """Draw pictures ahead, nearest to the slider's position first, until position ``k``'s
    full picture is kept (all of them are drawn and checked in
    test_pictures_drawn_ahead_are_the_drafts_at_their_positions; a release needs only its own,
    and drawing all 90 of FilterExplorer's made these tests 5 to 9 s of CPU each)."""
    while (ahead.which, k) not in ahead.kept and ahead.step():
        pass
    assert (ahead.which, k) in ahead.kept, k


@pytest.mark.parametrize(
    "name", ["viewer", "filter", "depth", "tiles", "sampling", "projection", "plane"]
)
def test_pictures_drawn_ahead_are_the_drafts_at_their_positions(name):
    ex, slider = _make(name)
    page, sent = _listen(ex, slider)
    ahead = ex.display.frames_ahead
    shown, info = bytes(page._last), ex.info.value
    state = {k: v for k, v in vars(ex).items() if isinstance(v, (np.ndarray, float))}
    _draw_slider(ahead)  # the slider moved last (the others follow: a test of their own)
    pictures = _pictures(sent, page._ref)  # patched once: every entry decoded and copied
    assert ahead.drawn == len(ahead.values) == len(pictures)
    # the explorer as it was: the same state, caption and picture on show
    assert bytes(page._last) == shown and ex.info.value == info
    for key, value in state.items():
        now = vars(ex)[key]
        assert now is value or np.array_equal(now, value, equal_nan=True), key
    for k in (0, len(ahead.values) // 3, len(ahead.values) - 1):
        # the page drags there: the kernel's draft is the picture drawn ahead (drawn full:
        # the final value's picture, a key there)
        slider._on_page_message(slider, {"type": "value", "value": float(ahead.values[k]),
                                         "final": ahead.full, "seq": 1}, [])  # fmt: skip
        picture, caption = pictures[ahead.which, k]
        assert np.array_equal(picture, page._last), k
        assert caption == ex.info.value, k
    ex.close()


def test_nothing_is_drawn_ahead_until_a_page_listens_and_a_new_filter_starts_again():
    ex, slider = _make("filter")
    page, sent = ex.display.widget, []
    page.send = lambda content, buffers=None: sent.append((content, buffers))
    ahead = ex.display.frames_ahead
    ex.filter.value = "nearest"  # no page yet: nothing drawn, nothing to drop
    assert not ahead.step() and ahead.drawn == 0
    assert sent and all(c["type"] == "frame" for c, _ in sent)
    page._on_page_message(page, {"type": "ready"}, [])
    assert sent[-1][0] == {"type": "ahead-clear", "generation": 1, "keep": None}
    assert ahead.step() and ahead.drawn == 1
    # the nearest positions first
    first = [c["entries"][0]["k"] for c, _ in sent if c["type"] == "ahead"]
    assert ahead.values[first[0]] == slider.value
    ex.filter.value = "bilinear"  # another picture at every position: drawn again
    assert sent[-1][0] == {"type": "ahead-clear", "generation": 2, "keep": None}
    assert len(ahead.todo) == len(ahead.values)
    ex.close()
    assert not ahead.step()  # closed: nothing more


def test_a_page_opened_later_asks_for_a_new_reference_and_the_pictures_are_drawn_again():
    ex, slider = _make("depth")
    page, sent = _listen(ex, slider)
    ahead = ex.display.frames_ahead
    ahead.step()
    slider.value = 1.0  # a final picture: a patch against the reference, then the poster
    old = page.ref_frame
    assert page.poster_frame != old
    page._on_page_message(page, {"type": "ref", "ref": old - 1}, [])  # stale: ignored
    assert page.ref_frame == old
    page._on_page_message(page, {"type": "ref", "ref": old}, [])
    whole = [c for c, _ in sent if c["type"] == "frame"][-1]
    assert whole["place"] is None and page.ref_frame == whole["ref"] == page.poster_frame > old
    assert np.array_equal(page._ref, page._last)
    assert sent[-1][0] == {"type": "ahead-clear", "generation": 2, "keep": None}
    ex.close()


def test_patches_are_against_the_reference_picture():
    ex, slider = _make("viewer")
    page, sent = _listen(ex, slider)
    for v in (40.0, 50.0, 45.0):
        slider._on_page_message(slider, {"type": "value", "value": v, "final": False,
                                         "seq": 1}, [])  # fmt: skip
        content, (data,) = [(c, b) for c, b in sent if c["type"] == "frame"][-1]
        assert content["ref"] == page.ref_frame and content["caption"] == ex.info.value
        x, y, w, h = content["place"]
        picture = page._ref.copy()  # the reference with this one patch: the picture
        picture[y : y + h, x : x + w] = np.frombuffer(zlib.decompress(data), np.uint8).reshape(
            h, w, 4
        )
        assert np.array_equal(picture, page._last)
    ex.close()


def test_slider_positions_are_the_pages():
    s = LiveSlider(value=0.1, base=10, min=-2, max=1, step=0.05)
    values = slider_positions(s)
    assert len(values) == 61 and values[0] == pytest.approx(0.01) and values[-1] == 10.0
    assert values[27] == 10 ** round(-2 + 27 * 0.05, 10)  # decimal positions
    wide = LiveSlider(value=0.0, min=0.0, max=1000.0, step=1.0)
    assert len(slider_positions(wide)) > MOST_POSITIONS  # too many: not drawn ahead


def test_filters_drawn_ahead_are_sent_at_a_toggle_and_are_the_filters_pictures():
    ex, slider = _make("filter")
    fresh, _ = _make("filter")
    toggles = ex._toggles
    ex.filter.value = "nearest"  # no page listens: nothing drawn ahead
    assert not toggles.todo and not toggles.kept
    page, _sent = _listen(ex, slider)
    assert toggles.where == slider.value and "nearest" not in toggles.todo
    while toggles.todo:
        toggles.step()
    draws = ex.display.draws
    for f in ("anisotropic", "bilinear", "trilinear"):
        ex.filter.value = fresh.filter.value = f
        # the picture kept, sent without drawing; the explorer's state is the filter's
        assert ex.display.draws == draws
        assert np.array_equal(page._last, fresh.display.widget._last), f
        assert ex.rms == fresh.rms and ex.info.value == fresh.info.value, f
        np.testing.assert_array_equal(ex.image, fresh.image)
        while toggles.todo:
            toggles.step()
    slider.value = 60.0  # a new tilt: the kept pictures are of the old one
    assert toggles.take(80.0, "nearest") is None and toggles.where == 60.0
    ex.close()
    fresh.close()


def test_plane_explorer_draws_every_slider_the_one_moved_or_pressed_last_first():
    """Issue 31: f2's first drag went through the kernel (16 fps): only the slider moved last
    (v1 x) was drawn ahead. Every slider's positions are drawn now, the one pressed or moved
    last first, then the values' (f1-f3), then the vertices'; a slider that moves keeps its
    own pictures (they hold the others where they are) and the others' are drawn again."""
    from teachraster.widgets import PlaneExplorer

    ex = PlaneExplorer(backend="image")
    sliders = [*ex.x, *ex.y, *ex.f]
    page, sent = _listen(ex, sliders[0])
    for s in sliders:
        s.send = lambda content, buffers=None: None
    ahead = ex.display.frames_ahead
    assert ahead.which == 0 and sliders[0].link == f"{page.key}/0"
    counts = [len(slider_positions(s)) for s in sliders]
    assert len(ahead.todo) == sum(counts) == 3 * 65 + 3 * 57 + 3 * 31
    order = list(dict.fromkeys(i for i, _ in ahead.todo))
    assert order == [0, 6, 7, 8, 3, 1, 4, 2, 5]
    sliders[7]._on_page_message(sliders[7], {"type": "touch"}, [])  # f2 pressed
    assert ahead.which == 7 and ahead.todo[:31] == [(7, k) for k in sorted(
        range(31), key=lambda k: (abs(k - 19), k))]  # fmt: skip
    assert sent[-1][0]["type"] == "ahead-clear"  # a press drops nothing
    while ahead.todo[0][0] == 7 and ahead.step():
        pass
    ahead.step()  # one of the next slider (f1): dropped when f2 moves
    pictures = _pictures(sent, page._ref)
    for k in (0, 9):
        value = float(slider_positions(sliders[7])[k])
        sliders[7]._on_page_message(sliders[7], {"type": "value", "value": value,
                                                 "final": False, "seq": 1}, [])  # fmt: skip
        assert np.array_equal(pictures[7, k][0], page._last)
        assert pictures[7, k][1] == ex.info.value
        # f2 moved: its pictures stay good, the others' are stale (page and kernel alike)
        assert sent[-1][0] == {"type": "ahead-clear", "generation": ahead.generation,
                               "keep": 7}  # fmt: skip
        assert ahead.valid_from(7) < ahead.generation == ahead.valid_from(6)
        assert {i for i, _ in ahead.kept} == {7} and len(ahead.kept) == 31
        assert 7 not in {i for i, _ in ahead.todo} and len(ahead.todo) == sum(counts) - 31
    sliders[2].value = 9.0  # v3 x: its positions first now, f2's are stale
    assert ahead.which == 2 and ahead.todo[0][0] == 2 and not ahead.kept
    assert len(ahead.todo) == sum(counts)
    ex.close()


def test_a_vertex_dragged_in_the_page_holds_the_pictures_drawn_ahead_until_its_release():
    """Issue 31: the PlaneExplorer's vertex dragged at 22 fps on a quiet machine (round trip
    84 ms, the editor's 50): batches of pictures drawn ahead (up to 30 ms each) ran between
    the drag's positions. While a vertex is in hand nothing is drawn ahead; at the release
    the pictures start again from the new triangle."""
    from teachraster.widgets import PlaneExplorer

    ex = PlaneExplorer(backend="image")
    page, sent = _listen(ex, ex.x[0])
    ahead, steps = ex.display.frames_ahead, []
    step = ahead.step
    ahead.step = lambda seconds=0.0: steps.append(seconds) or step(seconds)
    ahead._schedule = lambda delay=0.0: None  # no event loop here: _run is called by hand
    ex._on_page_move(0, 4.0, 2.0, final=False)
    ahead._run()
    assert steps == [] and ahead.todo  # mid-drag: nothing drawn, nothing dropped
    ex._on_page_move(0, 4.5, 2.0, final=True)
    assert ex.x[0].value == 4.5 and ahead.generation >= 2
    ahead._run()
    assert len(steps) == 1 and sent[-1][0]["type"] == "ahead"
    ex.close()


def test_widget_messages_and_pictures_drawn_ahead_hold_one_lock():
    """Review r5, 05b: ipykernel 7 handles some widget messages on another thread than its
    event loop; a format toggled while the loop drew pictures ahead (the explorer set to another
    state, then put back) left the put-back state, or a blank picture, on show. Both hold
    ``common.DRAWING`` now, so neither runs in the middle of the other."""
    from teachraster.widgets.common import DRAWING

    ex, slider = _make("depth")
    held = []
    ex.format.observe(lambda _change: held.append(DRAWING._is_owned()), "value")
    ex.format._handle_msg({"content": {"data": {"method": "update", "state": {"index": 2}}}})
    assert ex.format.value == "float32"  # the page's click arrived
    page, sent = _listen(ex, slider)
    ahead = ex.display.frames_ahead
    step = ahead.step
    ahead.step = lambda seconds=0.0: held.append(DRAWING._is_owned()) or step(seconds)
    ahead._run()
    assert held == [True, True] and not DRAWING._is_owned()
    ex.close()


def test_a_final_value_the_kernel_holds_brings_the_full_picture():
    """Keys 80 -> 79 -> 80 while the kernel is busy: the page shows 79's and 80's pictures
    drawn ahead and sends 80 as final, the value the kernel holds. When the page does not
    say it shows 80's full picture drawn ahead, the full picture must follow (review
    08-09-r6: drafts were drawn ahead then, and nothing was drawn: the page kept 80's draft
    for good)."""
    ex, slider = _make("filter")
    page, sent = _listen(ex, slider)
    full = bytes(page._last)
    _draw_ahead_until(ex.display.frames_ahead, 80)  # the slider's position: drawn first
    ahead = _pictures(sent, page._ref)[0, 80]  # what the page shows from its store at 80
    assert bytes(ahead[0]) == full and "on release" not in ahead[1]  # the full picture
    before = len([c for c, _ in sent if c["type"] == "frame"])
    slider._on_page_message(slider, {"type": "value", "value": 80.0, "final": True, "seq": 1}, [])
    frames = [c for c, _ in sent if c["type"] == "frame"]
    assert len(frames) == before + 1 and "on release" not in frames[-1]["caption"]
    assert bytes(page._last) == full
    ex.close()


def _claim(ahead, k, **changes) -> dict:
    """What the page's final value says when it shows position ``k`` drawn ahead
    (drag.js: ``store.holding``), as the page would send it now."""
    page = ahead.display.widget
    claim = {"k": k, "generation": ahead.generation, "ref": page.ref_frame, "n": page._frame,
             "slider": ahead.which}  # fmt: skip
    return claim | changes


@pytest.mark.parametrize("name", ["projection", "plane", "depth"])
def test_a_release_on_a_full_picture_drawn_ahead_sends_nothing_for_the_other_explorers(name):
    """Issue 31: the last picture after a drag of ProjectionExplorer's q or PlaneExplorer's
    v1 x came up to 105 and 122 ms after the release (DepthPrecisionExplorer's near 126). They draw full pictures ahead too: a
    release on one draws and sends nothing and shows what setting the value from code does."""
    ex, slider = _make(name)
    page, sent = _listen(ex, slider)
    ahead = ex.display.frames_ahead
    assert ahead.full and ahead.slider is slider
    k = len(ahead.values) * 2 // 3
    # drawn until position k's picture is kept: a release needs only its own (every one of
    # the slider's pictures is checked in test_pictures_drawn_ahead_are_the_drafts_at_their_
    # positions, for these three explorers too)
    _draw_ahead_until(ahead, k)
    pictures = {k: v for (i, k), v in _pictures(sent, page._ref).items() if i == ahead.which}
    value = float(ahead.values[k])
    slider._on_page_message(slider, {"type": "value", "value": float(ahead.values[k - 1]),
                                     "final": False, "seq": 2}, [])  # fmt: skip
    draws, frames = ex.display.draws, len([c for c, _ in sent if c["type"] == "frame"])
    held = {"type": "value", "value": value, "final": True, "seq": 3, "held": _claim(ahead, k)}
    slider._on_page_message(slider, held, [])
    assert ex.display.draws == draws  # nothing drawn ...
    assert len([c for c, _ in sent if c["type"] == "frame"]) == frames  # ... nor sent
    direct, direct_slider = _make(name)
    direct_slider.value = value
    assert np.array_equal(page._last, pictures[k][0])
    assert np.array_equal(page._last, direct.display.widget._last)
    assert ex.info.value == direct.info.value == pictures[k][1]
    ex.close()
    direct.close()


def test_a_release_on_a_full_picture_drawn_ahead_sends_nothing_and_ends_as_from_code():
    """Issue 31: FilterExplorer's last picture after a drag came 104-175 ms after the release
    (the kernel drew the full picture there). Its pictures drawn ahead are now the full ones:
    a release (or a key) on one, the page saying it shows it, draws and sends no picture,
    and the explorer ends exactly as after setting the value from code: its state, caption,
    last picture (the next reference) and poster."""
    ex, slider = _make("filter")
    page, sent = _listen(ex, slider)
    ahead = ex.display.frames_ahead
    assert ahead.full
    k = int(np.argmin(np.abs(ahead.values - 75.0)))
    _draw_ahead_until(ahead, k)
    pictures = {k: v for (_, k), v in _pictures(sent, page._ref).items()}
    for v in (61.0, 70.0):  # drafts (a page showing pictures ahead sends none)
        slider._on_page_message(slider, {"type": "value", "value": v, "final": False,
                                         "seq": 2}, [])  # fmt: skip
    draws, frames = ex.display.draws, len([c for c, _ in sent if c["type"] == "frame"])
    held = {"type": "value", "value": 75.0, "final": True, "seq": 3, "held": _claim(ahead, k)}
    slider._on_page_message(slider, held, [])
    assert ex.display.draws == draws  # nothing drawn ...
    assert len([c for c, _ in sent if c["type"] == "frame"]) == frames  # ... nor sent
    direct, direct_slider = _make("filter")
    direct_slider.value = 75.0
    assert np.array_equal(page._last, pictures[k][0])
    assert np.array_equal(page._last, direct.display.widget._last)
    assert ex.info.value == direct.info.value == pictures[k][1]
    assert page.poster == direct.display.widget.poster
    for key in ("image", "truth", "error", "lod", "rms", "shown_tilt", "shown_filter"):
        a, b = getattr(ex, key), getattr(direct, key)
        same = a == b if isinstance(a, (str, float)) else np.array_equal(a, b, equal_nan=True)
        assert same, key
    # then another tilt from code, and back: the pictures are the fresh explorer's
    slider.value = direct_slider.value = 40.0
    assert bytes(page._last) == bytes(direct.display.widget._last)
    ex.close()
    direct.close()


@pytest.mark.parametrize("stale", ["n", "generation", "ref", "k", "slider"])
def test_a_release_whose_page_may_show_another_picture_brings_the_full_picture(stale):
    """The page's word is taken only while it holds: a picture of the kernel's on its way
    (a draft sent after the page's last frame), pictures drawn ahead since dropped (another
    filter), another reference, another position or slider. Then the full picture is drawn
    and sent, as without pictures drawn ahead."""
    ex, slider = _make("filter")
    page, sent = _listen(ex, slider)
    ahead = ex.display.frames_ahead
    k = int(np.argmin(np.abs(ahead.values - 75.0)))
    _draw_ahead_until(ahead, k)  # so that only the stale part of the claim can refuse it
    claim = _claim(ahead, k)
    claim[stale] = claim[stale] + (-1 if stale == "n" else 1)
    frames = len([c for c, _ in sent if c["type"] == "frame"])
    slider._on_page_message(slider, {"type": "value", "value": 75.0, "final": True, "seq": 1,
                                     "held": claim}, [])  # fmt: skip
    assert len([c for c, _ in sent if c["type"] == "frame"]) == frames + 1
    direct, direct_slider = _make("filter")
    direct_slider.value = 75.0
    assert bytes(page._last) == bytes(direct.display.widget._last)
    ex.close()
    direct.close()


def _png_pixels(png: bytes) -> np.ndarray:
    import io

    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(png)).convert("RGBA"))


def test_case_pickers_pictures_drawn_ahead_are_its_pictures_and_are_shown_without_drawing():
    """A case and naive rule drawn ahead (on a figure of their own) are the picture, caption
    and state a picker shows there; choosing them then draws nothing. Nothing is asked for
    before a first change (a lesson run without a page)."""
    from teachraster.plotting.frames import frame_rgba
    from teachraster.widgets.case_picker import CasePicker

    picker = CasePicker("collinear", "E > 0", backend="image")
    ahead = picker._ahead
    assert not ahead.todo and not ahead.kept
    picker.rule.value = "E ≥ 0"
    picker.rule.value = "E > 0"  # back: the rules either side here come first, not this one
    assert ahead.todo[:2] == [("collinear", "whole px"), ("collinear", "E ≥ 0")]
    assert ("collinear", "E > 0") not in ahead.todo
    ahead.step()
    ahead.step()
    draws = picker.display.draws
    picker.rule.value = "E ≥ 0"
    assert picker.display.draws == draws  # the picture kept, sent without drawing
    fresh = CasePicker("collinear", "E ≥ 0", backend="image")
    assert np.array_equal(_png_pixels(picker.display.widget.value), frame_rgba(fresh.fig))
    assert picker.info.value == fresh.info.value and picker.passed == fresh.passed
    np.testing.assert_array_equal(picker.owner, fresh.owner)
    assert picker.view == fresh.view and picker.hubs == fresh.hubs
    picker.case.value = "near_flat"  # not kept: drawn as before
    assert picker.display.draws == draws + 1
    for p in (picker, fresh):
        p.close()


def test_divide_cost_explorers_other_measure_drawn_ahead_is_its_picture():
    """The other error measure at this price, drawn ahead, is the picture, caption and front
    the explorer shows there; the toggle then draws nothing."""
    from widget_examples import _rows

    from teachraster.plotting.frames import frame_rgba
    from teachraster.widgets.divide_cost import DivideCostExplorer

    ex = DivideCostExplorer(_rows(), backend="image")
    assert not ex._ahead.todo and not ex._ahead.kept  # nothing before a first change
    ex.divide.value = 10.0
    # the other measure here first, then the prices either side (the price list unchanged)
    p5 = "Pentium (P5)"
    assert ex._ahead.todo == [(10.0, "mean error", 2, p5), (12.0, "max error", 2, p5),
                              (8.0, "max error", 2, p5)]  # fmt: skip
    ex._ahead.step()
    draws = ex.display.draws
    ex.error.value = "mean error"
    assert ex.display.draws == draws  # the picture kept, sent without drawing
    kept, info, front = ex.display.widget.value, ex.info.value, ex.front
    ex._ahead.close()  # now drawn by the explorer itself, on its own figure
    ex._ahead = None
    ex.update(replot=True)
    assert np.array_equal(_png_pixels(kept), frame_rgba(ex.fig))
    assert ex.info.value == info and ex.front == front
    ex.close()


def test_sampling_shape_drawn_ahead_is_sent_at_a_toggle_and_is_the_shapes_picture():
    ex, slider = _make("sampling")
    fresh, _ = _make("sampling")
    page, _sent = _listen(ex, slider)
    toggles = ex._toggles
    assert toggles.where == (32.0, 1.0) and toggles.todo == ["gaussian"]
    toggles.step()
    draws = ex.display.draws
    ex.kernel.value = fresh.kernel.value = "gaussian"
    assert ex.display.draws == draws  # the picture kept, sent without drawing
    assert np.array_equal(page._last, fresh.display.widget._last)
    assert ex.info.value == fresh.info.value
    assert ex.result.rms_error == fresh.result.rms_error
    ex.rate.value = 40.0  # elsewhere: the kept pictures are of the old place
    assert toggles.take((32.0, 1.0), "box") is None and toggles.where == (40.0, 1.0)
    ex.close()
    fresh.close()


def test_a_case_picker_in_a_kernel_keeps_the_pictures_it_draws():
    """With an event loop running (a kernel), a case or rule the picker drew itself is
    kept: coming back to it draws nothing (without one, as above, every change draws)."""
    import asyncio

    from teachraster.widgets.case_picker import CasePicker

    picker = CasePicker("collinear", "E > 0", backend="image")

    async def toggle_twice():
        picker.rule.value = "E ≥ 0"
        shown = picker.display.widget.value
        picker.rule.value = "E > 0"
        draws = picker.display.draws
        picker.rule.value = "E ≥ 0"
        return shown, draws

    shown, draws = asyncio.run(toggle_twice())
    assert picker.display.draws == draws and picker.display.widget.value == shown
    assert ("collinear", "E > 0") in picker._ahead.kept
    picker.close()


def test_every_slider_explorers_first_picture_is_its_default_picture():
    """Review r26 (lesson 10's TileExplorer): a picture sent as a patch while the explorer is
    being made reaches no view (the cell has not displayed it yet), so a view shows the first
    picture, the reference and poster. Every slider explorer's first picture must therefore be
    the one it shows at its defaults: TileExplorer's was the finished walk under "level 0"."""
    from widget_examples import examples

    from teachraster.widgets.live_slider import SliderDisplay

    checked = []
    for name, make in sorted(examples().items()):
        widget = make()
        try:
            display = getattr(widget, "display", None)
            if not isinstance(display, SliderDisplay):
                continue
            page = display.widget
            assert page.ref_frame == page.poster_frame == 1, (name, page.ref_frame, page._frame)
            assert np.array_equal(page._ref, page._last), name
            checked.append(name)
        finally:
            widget.close()
    assert "TileExplorer" in checked and len(checked) >= 7, checked


def test_sampling_key_names_the_filter_width_on_show_moved_and_drawn_ahead():
    """Panel 1's key says the filter's width ("prefiltered, width 4.00"): in the picture sent
    after a move and in the pictures drawn ahead along the filter slider, not the key cached
    at the first draw (review r127 08-1: "width 0.00 (none: the signal)" beside a slider at
    1.00 or 4.00). Checked against a fresh explorer drawn at that width."""
    from teachraster.plotting.frames import frame_rgba
    from teachraster.plotting.sampling import prefiltered_key
    from teachraster.widgets.sampling_explorer import SamplingExplorer

    ex = SamplingExplorer(width=0.0, backend="image")
    page, sent = _listen(ex, ex.width)
    ex.width.value = 0.5  # the filter, moved last: its positions are drawn ahead first
    ahead = ex.display.frames_ahead
    _draw_slider(ahead)
    pictures = {k: v for (i, k), v in _pictures(sent, page._ref).items() if i == ahead.which}
    for width in (1.0, 4.0):
        fresh = SamplingExplorer(width=width, backend="image")
        assert fresh.art.filtered.axes.get_legend().get_texts()[1].get_text() == (
            prefiltered_key(width)
        )
        k = int(np.flatnonzero(np.isclose(ahead.values, width))[0])
        assert np.array_equal(pictures[k][0], frame_rgba(fresh.fig)), width
        ex.width.value = width
        assert np.array_equal(page._last, frame_rgba(fresh.fig)), width
        assert np.array_equal(frame_rgba(ex.fig), frame_rgba(fresh.fig)), width
        fresh.close()
    ex.close()
