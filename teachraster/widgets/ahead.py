"""Pictures drawn ahead: a slider explorer's figure at every position of its slider, kept by
the page, so that dragging the slider or pressing an arrow key shows a picture at once,
without asking the kernel.

A slider explorer (one slider with a few dozen positions: the tilt of
:class:`~teachraster.widgets.TexturedPlaneViewer` and :class:`~teachraster.widgets.FilterExplorer`,
the near plane of ``DepthPrecisionExplorer``) draws, while the kernel idles, one position at
a time (nearest to the one on show first) exactly as a draft at that position looks, and
sends it to the page as a patch against the figure's reference picture
(:meth:`~teachraster.widgets.dragging.DragFigure.send_ahead`) with its caption. The page's
slider (``static/slider.js``) shows a position it has a picture for by itself and tells the
kernel only where it is released (the full picture then follows, as after any drag);
positions without one go to the kernel as drafts, coalesced, as before.

An explorer whose draft differs from its full picture only by what it can compute ahead
(``FilterExplorer``: the error panel, its note and colour bar) draws the *full* picture
ahead instead (``full``): a release or a key on a position drawn ahead then needs no
picture from the kernel. The page says so with the final value (``held``: the position it
shows by itself, the pictures' generation and reference, the last frame it had from the
kernel); when that is still the kernel's latest word, the kernel takes the picture's pixels
from the patch it kept (:meth:`FramesAhead.held`) and sends nothing; otherwise it draws and
sends the full picture, as for a draft. When another control
changes the picture (a filter, a depth format), the pictures kept are dropped and drawn
again.

An explorer with several sliders (``SamplingExplorer``, ``PlaneExplorer``'s nine) has every
slider's positions drawn, the slider moved or pressed last first: a first drag of any of
them finds its pictures in the page once the kernel has idled long enough (issue 31:
``PlaneExplorer``'s f2 dragged through the kernel at 16 fps). When one slider moves, its own
pictures stay good (they hold the others where they are) and the others' are drawn again.

Nothing is drawn while a widget message has reached the kernel and waits to be handled
(:func:`~teachraster.widgets.common.messages_waiting`; review r400 W1: a Check waited seconds
behind ``FilterExplorer``'s pictures and truths, drawn at every turn of the kernel's loop that
the message needed): a batch under way ends, and the next waits until it is handled.

Nothing is drawn until a page says it is listening (``ready``): a notebook run without a
browser (nbclient, the tests) draws nothing ahead, and a page opened later asks again.

A control's other options at the picture on show (:class:`TogglesAhead`: ``FilterExplorer``'s
filters, ``SamplingExplorer``'s shapes) and the few states of a PNG explorer's menus
(:class:`PicturesAhead`: ``CasePicker``'s cases and naive rules, ``DivideCostExplorer``'s error
measures and prices) are drawn ahead too, and kept by the kernel: choosing one sends its
picture at once.
"""

from __future__ import annotations

import asyncio
import time

import numpy as np

from ..plotting.frames import frame_rgba
from .common import DRAWING, WAIT_POLL_S, later, messages_waiting
from .dragging import dragged_within

#: Sliders with more positions than this are not drawn ahead (pictures the page would keep).
MOST_POSITIONS = 128
#: Seconds between two batches of pictures drawn ahead: a message arriving meanwhile is
#: answered first.
STEP_S = 0.01
#: Seconds of drawing in one batch (sent as one message: each costs the page and server
#: about as much as a small picture does)
BATCH_S = 0.03
#: Seconds a restart waits before drawing (a student toggling a control twice in a row is
#: answered first; the pictures are then drawn once)
RESTART_S = 0.4
#: Seconds between two looks whether a drag is over, while one is under way (issue 31: a
#: batch drawn between two positions of a drag delayed the next by up to BATCH_S; the
#: PlaneExplorer's vertex dragged at 22 fps, its round trip 84 ms against the editor's 50)
BUSY_S = 0.05
#: Seconds after a position dragged in the page (any figure of the kernel) during which a
#: drag counts as under way: its positions come every 30-100 ms
DRAG_GAP_S = 0.25


def draw_elsewhere(display, explorer, compute) -> tuple:
    """Draw ``explorer``'s figure in the state ``compute()`` gives it, then put the explorer
    back as it was (its attributes and artists; nothing is sent).

    ``compute`` rebinds the explorer's attributes (``_compute_at``); the explorer has
    ``_set_artists()`` and ``_info_html()``. Returns the figure's pixels, the caption and
    the attributes ``compute`` rebound (the state those pixels show).
    """
    saved = dict(vars(explorer))
    try:
        compute()
        explorer._set_artists()
        display.draw()
        state = {k: v for k, v in vars(explorer).items() if saved.get(k, saved) is not v}
        return frame_rgba(display.fig), explorer._info_html(), state
    finally:
        for name, kept in saved.items():
            setattr(explorer, name, kept)
        explorer._set_artists()  # the artists back as on show (drawn at the next picture)


def show_kept(explorer, kept) -> None:
    """Show a picture kept ahead (``TogglesAhead`` / ``PicturesAhead``: its bytes, caption and
    the explorer's state when drawn): the state restored, the caption and the picture sent."""
    picture, caption, state = kept
    vars(explorer).update(state)
    explorer.info.value = caption
    explorer.display.refresh(picture)


def slider_positions(slider) -> np.ndarray:
    """The values a :class:`~teachraster.widgets.LiveSlider` can take, position by position.

    Examples
    --------
    >>> from teachraster.widgets import LiveSlider
    >>> slider_positions(LiveSlider(value=1.0, min=0.0, max=2.0, step=0.5)).tolist()
    [0.0, 0.5, 1.0, 1.5, 2.0]
    """
    n = int(np.floor((slider.max - slider.min) / slider.step + 1e-9)) + 1
    # decimal positions, as the page's range input names them (min + k step, rounded)
    positions = np.round(slider.min + slider.step * np.arange(n), 10)
    return slider.base**positions if slider.base > 0 else positions


class FramesAhead:
    """Draw ``explorer``'s figure at every position of its sliders while the kernel idles.

    Parameters
    ----------
    display : SliderDisplay
        The explorer's figure in the page (reference mode).
    sliders : LiveSlider or list of LiveSlider
        The sliders whose positions are drawn, each linked to the figure in the page. With
        several (``SamplingExplorer``'s two, ``PlaneExplorer``'s nine), the positions of the
        one moved or pressed last first, then the others' (``order``). The pictures along
        a slider do not depend on where that slider is, only on the others: when it moves,
        its own pictures stay good and the others' are drawn again.
    explorer : object
        Has ``_compute_at(value)`` (its state at the slider value, attributes rebound, not
        changed in place; with several sliders ``_compute_at(value, which)``, ``which`` the
        slider's index), ``_set_artists()`` (its artists from that state, nothing drawn)
        and ``_info_html()`` (the caption); ``display.draw`` then draws the figure.
    full : bool
        Draw the full picture at each position (as a final value there shows it), not the
        draft; the patches sent are kept (``FilterExplorer``: about 70 kB each) so that a
        release on a position the page showed by itself costs no drawing (:meth:`held`).
    busy : callable, optional
        True while the explorer is dragged otherwise than by ``sliders`` (``PlaneExplorer``'s
        vertices in the page): drawing waits for the release. (A drag of a slider drawn
        ahead is not waited for: its pictures, as they arrive, let the page answer it.)
    order : list of int, optional
        The sliders (indices) in the order their positions are drawn after those of the
        slider moved last; by default as given.

    Notes
    -----
    Each picture sent has a generation; the page (``static/drag.js``, its store) keeps the
    same rule: a picture of slider ``i`` is good while its generation is at least
    :meth:`valid_from` ``(i)``. A restart that keeps slider ``i``'s pictures (it moved)
    raises that bound for the others only.
    """

    def __init__(self, display, sliders, explorer, *, full: bool = False, busy=None,
                 order=None) -> None:  # fmt: skip
        self.display, self.explorer, self.full = display, explorer, full
        self.busy = busy
        #: full mode: (slider, position) -> its patch as sent, ``(place, bytes)``
        self.kept: dict[tuple[int, int], tuple] = {}
        #: the (slider, position) pictures the page has, still good
        self.sent: set[tuple[int, int]] = set()
        self.sliders = list(sliders) if isinstance(sliders, (list, tuple)) else [sliders]
        self.order = list(range(len(self.sliders))) if order is None else list(order)
        self.which = 0  # the slider moved or pressed last: its positions first
        self.generation = 0
        #: pictures older than this generation are stale, but for ``exempt``: (the slider
        #: moved last, the generation its own pictures are good from)
        self.floor = 0
        self.exempt: tuple[int, int] | None = None
        self.todo: list[tuple[int, int]] = []
        self.drawn = 0
        self._handle = None
        self._loop = None  # the kernel's event loop, where the pictures are drawn
        self.closed = any(len(slider_positions(s)) > MOST_POSITIONS for s in self.sliders)
        #: a page listens (it said ``ready``): nothing is drawn for nobody
        self.listening = False
        #: called once a page listens (other pictures an explorer draws ahead for it)
        self.on_listening: list = []
        page = display.widget
        for i, s in enumerate(self.sliders):
            s.link = f"{page.key}/{i}"
            if len(self.sliders) > 1:
                s.observe(lambda change, i=i: self._moved(i), "value")
                s.on_touch(lambda i=i: self._touched(i))
        page.on_ready = page.on_reference = self._page_ready

    @property
    def slider(self):
        """The slider moved or pressed last."""
        return self.sliders[self.which]

    @property
    def values(self) -> np.ndarray:
        """The values of its positions."""
        return slider_positions(self.slider)

    def valid_from(self, i: int) -> int:
        """The oldest generation whose pictures of slider ``i`` are still good."""
        if self.exempt is not None and self.exempt[0] == i:
            return self.exempt[1]
        return self.floor

    def _moved(self, i: int) -> None:
        # slider i moved: the pictures along the others are stale, its own stay good, and
        # it is the likelier to move again
        self.which = i
        self.restart(keep=i)

    def _touched(self, i: int) -> None:
        # slider i pressed (or focused): nothing is stale, its positions come first
        if i != self.which and not self.closed and self.listening:
            self.which = i
            self.todo = self._todo()

    def _page_ready(self) -> None:
        self.listening = True
        self.restart()
        for callback in self.on_listening:
            callback()

    def restart(self, keep: int | None = None) -> None:
        """Drop the pictures drawn so far (the page does too) and draw them again, the slider
        moved last first, nearest to its position first (another control changed the
        picture). ``keep``: the slider whose pictures stay good (it alone moved)."""
        if self.closed or not self.listening:
            return
        since = None if keep is None else self.valid_from(keep)
        self.generation += 1
        self.floor, self.exempt = self.generation, None if keep is None else (keep, since)
        self.kept = {key: v for key, v in self.kept.items() if key[0] == keep}
        self.sent = {key for key in self.sent if key[0] == keep}
        self.display.widget.send({"type": "ahead-clear", "generation": self.generation,
                                  "keep": keep})  # fmt: skip
        self.todo = self._todo()
        if keep is not None and self._handle is not None:
            return  # a slider dragged through the kernel: its drafts do not hold drawing back
        if self._handle is not None:
            self._handle.cancel()
            self._handle = None
        self._schedule(RESTART_S)

    def _todo(self) -> list[tuple[int, int]]:
        """The pictures still to draw: (slider, position), the slider moved last first, then
        the others in ``order``, each nearest to its slider's position first."""
        todo = []
        for i in [self.which, *(j for j in self.order if j != self.which)]:
            values = slider_positions(self.sliders[i])
            here = int(np.argmin(np.abs(values - self.sliders[i].value)))
            near = sorted(range(len(values)), key=lambda k: (abs(k - here), k))
            todo += [(i, k) for k in near if (i, k) not in self.sent]
        return todo

    def _schedule(self, delay: float = STEP_S) -> None:
        try:
            loop = asyncio.get_running_loop()
        except RuntimeError:
            # a widget message handled on another thread than the kernel's loop (ipykernel
            # 7): scheduled from the loop; no loop seen yet (plain Python, tests): step() by hand
            if self._loop is not None and not self._loop.is_closed():
                self._loop.call_soon_threadsafe(self._schedule, delay)
            return
        self._loop = loop
        if self._handle is None:
            self._handle = loop.call_later(delay, self._run)

    def _run(self) -> None:
        self._handle = None
        # a point dragged in any figure of the kernel (another widget's too: with every
        # slider of a PlaneExplorer to draw, seconds of batches ran between the positions
        # of a TriangleEditor's drag in the same kernel) is answered first
        if (self.busy is not None and self.busy()) or dragged_within(DRAG_GAP_S):
            self._schedule(BUSY_S)
            return
        if messages_waiting():  # a Check, a toggle: handled first (review r400 W1)
            self._schedule(WAIT_POLL_S)
            return
        # never in the middle of a widget message handled on another thread (common.DRAWING)
        with DRAWING:
            more = self.step(BATCH_S)
        if more:
            self._schedule()

    def step(self, seconds: float = 0.0) -> bool:
        """Draw the next positions' pictures for about ``seconds`` (one at least) and send
        them in one message; False when none is left."""
        if self.closed or not self.todo:
            return False
        start, batch = time.perf_counter(), []
        # a widget message reaching the kernel ends the batch (its reply waits for none of it)
        while self.todo and (not batch or (time.perf_counter() - start < seconds
                                           and not messages_waiting())):  # fmt: skip
            i, k = self.todo.pop(0)
            value = float(slider_positions(self.sliders[i])[k])
            rgba, caption = self.picture_at(value, i)
            batch.append((i, k, rgba, caption))
        patches = self.display.widget.send_ahead(batch, self.generation)
        keys = [(i, k) for i, k, _, _ in batch]
        if self.full:
            self.kept.update(zip(keys, patches))
        self.sent.update(keys)
        self.drawn += len(batch)
        return bool(self.todo)

    def held(self) -> np.ndarray | None:
        """The pixels the page shows by itself at the value of the slider whose final value
        the kernel handles, when they are the full picture there and the page says it shows
        them (the final value's ``held``, see the module); else None (the picture is then
        drawn and sent)."""
        page = self.display.widget
        i = next((j for j, s in enumerate(self.sliders) if getattr(s, "held", None)), None)
        if not self.full or i is None or self.sliders[i].dragging:
            return None
        slider, claim = self.sliders[i], self.sliders[i].held
        try:
            k, generation = int(claim["k"]), int(claim["generation"])
            # pictures good now, against the page's reference, and no picture from the
            # kernel on its way: the page's last frame is the kernel's last
            current = (self.valid_from(i) <= generation <= self.generation
                       and (int(claim["ref"]), int(claim["n"]), int(claim.get("slider", 0)))
                       == (page.ref_frame, page._frame, i))  # fmt: skip
        except (KeyError, TypeError, ValueError):
            return None
        if not current or (i, k) not in self.kept:
            return None
        if float(slider_positions(slider)[k]) != slider.value:
            return None
        return page.unpatch(*self.kept[(i, k)])

    def picture_at(self, value: float, i: int | None = None) -> tuple[np.ndarray, str]:
        """The figure's pixels and caption with slider ``i`` (default: the one moved last) at
        ``value``, as a draft there shows them (with ``full``, as a final value there
        does); the explorer's state and artists are put back as they were (nothing sent)."""
        i = self.which if i is None else i
        ex, which = self.explorer, [i] if len(self.sliders) > 1 else []
        slider = self.sliders[i]
        slider.dragging = not self.full  # as a draft at that value looks
        try:
            rgba, caption, _ = draw_elsewhere(
                self.display, ex, lambda: ex._compute_at(value, *which)
            )
        finally:
            slider.dragging = False
        return rgba, caption

    def close(self) -> None:
        self.closed = True
        self.todo = []
        self.kept = {}
        self.sent = set()
        if self._handle is not None:
            self._handle.cancel()


class TogglesAhead:
    """The pictures a control's other options give where the figure is, drawn while the kernel
    idles and kept by the kernel: choosing one then sends its picture at once.

    ``FilterExplorer``'s filter: at the tilt on show, the picture of every other filter (the
    full picture, error and colour bar included), one per idle call; a new tilt drops them.

    Parameters
    ----------
    display : SliderDisplay
        The explorer's figure in the page.
    explorer : object
        Has ``_compute_at(where, option)`` (its state there with that option, attributes
        rebound), ``_set_artists()`` and ``_info_html()``, as for :class:`FramesAhead`.
    options : sequence
        The control's options.
    """

    def __init__(self, display, explorer, options) -> None:
        self.display, self.explorer, self.options = display, explorer, list(options)
        self.kept: dict = {}  # option -> (pixels, caption, the state it rebinds)
        self.where = None
        self.todo: list = []
        self.closed = False

    def start(self, where, option) -> None:
        """The picture on show is at ``where`` with ``option``: draw the others there."""
        if where != self.where:
            self.kept.clear()
        self.where = where
        self.todo = [o for o in self.options if o != option and o not in self.kept]
        later(self.step, idle_only=True)

    def take(self, where, option):
        """``(pixels, caption, state)`` of ``option`` at ``where`` when kept, else None."""
        return self.kept.get(option) if where == self.where else None

    def step(self) -> None:
        """Draw one option's picture and keep it; the next at the next idle call."""
        if self.closed or not self.todo:
            return
        option, ex = self.todo.pop(0), self.explorer
        compute = lambda: ex._compute_at(self.where, option)  # noqa: E731
        with DRAWING:  # later() holds it too; also when called by hand
            self.kept[option] = draw_elsewhere(self.display, ex, compute)
        later(self.step, idle_only=True)

    def close(self) -> None:
        self.closed = True
        self.kept.clear()


class PicturesAhead:
    """Pictures of an explorer's menus and toggles, drawn while the kernel idles on a figure
    of their own and kept by the kernel: choosing one of them then sends its picture at once.

    For the explorers whose few states (a case and a naive rule; an error measure) each
    cost a whole figure (artists made anew, axes laid out: 100-500 ms): ``CasePicker`` and
    ``DivideCostExplorer``. The figure the page shows is never touched: ``draw`` renders on
    a second one, made as the first, so that a picture kept is the one the explorer draws
    in that state (tests/test_frames_ahead.py).

    Parameters
    ----------
    draw : callable
        ``draw(key)`` -> ``(png, caption, state)``: the picture of state ``key`` (PNG bytes),
        its caption and the attributes the explorer holds in that state.
    most : int
        Pictures kept at most (the oldest dropped first).
    """

    def __init__(self, draw, most: int = 64) -> None:
        self.draw, self.most = draw, most
        self.kept: dict = {}  # key -> (png, caption, state), oldest first
        self.todo: list = []
        self.drawn = 0
        self.closed = False

    def take(self, key):
        """``(png, caption, state)`` of ``key`` when kept, else None."""
        return self.kept.get(key)

    def keep(self, key, picture) -> None:
        """Keep ``picture`` = ``(png, caption, state)``, drawn by the explorer itself for
        ``key``: coming back to it then costs nothing either. Only where pictures are drawn
        ahead at all (a kernel's event loop runs): run without one (tests, a script), every
        change draws its figure, as a picker without pictures kept does."""
        try:
            asyncio.get_running_loop()
        except RuntimeError:
            return
        self.kept[key] = picture
        while len(self.kept) > self.most:
            self.kept.pop(next(iter(self.kept)))

    def want(self, keys) -> None:
        """Draw the pictures of ``keys`` not kept yet, in this order, one per idle call (a
        student's click meanwhile is answered first); the ones asked before are dropped."""
        self.todo = [k for k in dict.fromkeys(keys) if k not in self.kept]
        later(self.step, idle_only=True)

    def step(self) -> None:
        """Draw and keep the next picture; the one after at the next idle call."""
        if self.closed or not self.todo:
            return
        key = self.todo.pop(0)
        with DRAWING:  # later() holds it too; also when called by hand
            self.kept[key] = self.draw(key)
        self.drawn += 1
        while len(self.kept) > self.most:
            self.kept.pop(next(iter(self.kept)))
        later(self.step, idle_only=True)

    def close(self) -> None:
        self.closed = True
        self.todo = []
        self.kept.clear()
