"""Exercises ``broken_frame_1`` … ``broken_frame_6`` (lesson 11): find what broke a frame.

tinyrenderer's "visual troubleshooting", as graded exercises: each frame below was rendered
with one mistake a graphics programmer makes (in no particular order: a strip modelled
thinner than a pixel, which falls between the pixel centres, straight colours blended as
premultiplied, culling the wrong winding, transparent geometry drawn before what lies behind
it, a reversed depth mapping, surfaces too close for the depth buffer). The student sees the frame beside the
intended one, inspects pixel histories (``frame.history(row, col)``, the ``FrameInspector``)
and answers with a cause from :data:`CAUSES`, a pixel whose history shows it and the stage
(:data:`STAGES`) where that history first differs from the intended frame's.

What is hidden and what is not. The frames come in look-alike pairs (1-2, 3-4, 5-6) with
the same symptom, the same picture and the same intended picture pixel for pixel, so the
picture cannot tell a pair apart. Hidden: the cause (no public attribute or repr of a
:class:`BrokenFrame` names it), the frames' ``plan`` (withheld, the same text for every
frame: :data:`WITHHELD`), and the check's evidence test (private here). Not hidden:
``frame.trace`` and ``frame.attrs`` are the renderer's full records, the very data a pixel
history reads (window positions and depths, the drawing order, the culled flags, the
fragments' colours, the render settings in ``trace.debug.inputs``: frame 2 and its intended
frame cull back faces, frame 1 and its intended frame do not), so a student who reads those
arrays instead of histories finds the same evidence by a longer road. Each frame is rendered
with its own intended frame's settings (the mistake is in what is drawn).

One verdict for the whole answer: right only when the cause is right, the pixel is one the
mistake changed whose history shows the cause, and the stage is where that history first
differs from the intended one (stage by stage in the pipeline's order, each triangle matched
by its corners on screen, whatever its number). A wrong answer, whichever part is wrong, gets
the same words and the number of tries recorded, so a wrong stage is not told from a wrong
cause (r7: the stage's own message let 38 blind calls solve all six). That slows guessing, it
does not stop it: knowing the cause, the stage is one of four tries, and a blind loop over
causes and stages solves all six (r8: 77 calls). The mark says an answer is right, not how it
was found; grading the diagnosis itself needs the student's words or hidden checks
(docs/grading.md). This module is importable like any other (``_answer`` is private by name,
not hidden): the source ships with the package.
"""

from __future__ import annotations

import operator
from dataclasses import dataclass
from functools import cache

import numpy as np

from ..core.validate import as_int
from ..pipeline.planning.render_plan import Plan
from ..pipeline.rendering.render_triangles import Frame, render
from ..pipeline.rendering.scenes import get_scene
from .answers import refuse_non_answers, short
from .exercise import Exercise, Mistake
from .running import WrongAnswerType

#: Frame size: small, so that every pixel is easy to pick.
W, H = 64, 48

#: The causes a diagnosis may name (six occur, four do not), in alphabetical order: every
#: listing of them (the notebook's, a wrong form's message) follows this order, never the
#: frames' (r8: listed in the frames' order, the causes were the answer key).
_CAUSES = {
    "depth function": "the depth test compares in the wrong direction for the frame's depths, "
    "so it keeps the farther surface",
    "culled winding": "triangles that face the camera are culled",
    "z-fighting": "the depth buffer cannot tell two surfaces apart",
    "missing premultiplication": "straight-alpha colours are blended as premultiplied ones",
    "blend order": "transparent geometry is drawn before what lies behind it",
    # r7: the intended frame is the strip modelled 2 px thick, not the sliver with more
    # samples, so the cause is the geometry: a strip thinner than a pixel between the centres
    "sliver": "a triangle modelled thinner than a pixel, so thin that it falls between the "
    "pixel centres (the one sample of each pixel)",
    "depth test off": "later triangles overwrite nearer ones",
    "near-plane clipping": "geometry is cut away by the near plane",
    "affine interpolation": "attributes are interpolated without the divide by w",
    "texture filtering": "the wrong texture filter or mip level",
}
CAUSES = dict(sorted(_CAUSES.items()))


@dataclass(frozen=True)
class BrokenFrame:
    """One frame to diagnose, as the student gets it: the symptom as reported and the two
    frames. What broke it is the check's to know (:func:`_answer`), not a field to read."""

    number: int
    symptom: str
    frame: Frame  # the broken one, traced
    intended: Frame  # what the programmer meant to draw

    def __repr__(self) -> str:
        return f"BrokenFrame({self.number}: {self.symptom!r}, .frame, .intended)"


def _answer(number: int) -> str:
    """The cause of frame ``number``: read by the check only."""
    return _CAUSE_OF[number]


def _differs(number: int) -> np.ndarray:
    """(H, W) bool: the pixels the mistake of frame ``number`` changed (colour, RGB)."""
    b = broken_frame(number)
    return ~np.isclose(_rgb(b.frame), _rgb(b.intended), atol=1e-6).all(axis=2)


def _shows(number: int, row: int, col: int) -> bool:
    """Does pixel (row, col) of frame ``number`` show its cause: changed by it, and its history
    bearing the cause's signature (:data:`_SIGNATURES`)?"""
    if not (0 <= row < H and 0 <= col < W and _differs(number)[row, col]):
        return False
    frame = broken_frame(number).frame
    return bool(_SIGNATURES[_answer(number)][0](frame, frame.history(row, col)))


def _tested(frame, h) -> bool:
    """Two or more fragments met the depth test here: its direction decided which is shown."""
    return sum(r.outcome in ("passed", "failed_depth") for r in h.records) >= 2


def _nearer_first(frame, h) -> bool:
    """Two blended fragments arrived nearer first."""
    depths = [r.depth for r in h.records if r.outcome == "passed"]
    return len(depths) >= 2 and any(a < b for a, b in zip(depths, depths[1:]))


def _thin_missed(frame, h) -> bool:
    """The thinnest triangle crosses the pixel's box but not its centre (no fragment). r8: the
    records alone say "not covered" for every pixel of the triangle's bounding box, 36 of 96
    of them never crossed; the box test keeps only the pixels it passes through."""
    k = int(np.argmin(_altitudes(frame)))
    mine = [r for r in h.records if r.triangle == k]
    return (bool(mine) and all(r.outcome == "not_covered" for r in mine)
            and _crosses_box(frame.trace.window[k, :, :2], h.row, h.col))  # fmt: skip


def _crosses_box(xy: np.ndarray, row: int, col: int) -> bool:
    """Does the triangle with window corners ``xy`` (3, 2) overlap pixel (row, col)'s box
    [col, col + 1] × [row, row + 1] with some area? Separating axes: the box's two and the
    triangle's three edge normals; touching an edge is no crossing."""
    box = np.array([[col, row], [col + 1, row], [col + 1, row + 1], [col, row + 1]], float)
    edges = np.roll(xy, -1, axis=0) - xy
    axes = [np.array([1.0, 0.0]), np.array([0.0, 1.0]), *(e[::-1] * [1, -1] for e in edges)]
    for a in axes:
        t, b = xy @ a, box @ a
        if t.max() <= b.min() or b.max() <= t.min():
            return False
    return True


#: What a history shows for each cause that occurs: a test on (frame, history), and words.
_SIGNATURES = {
    "depth function": (_tested, "two or more fragments met the depth test there"),
    "culled winding": (lambda f, h: any(r.outcome == "culled" for r in h.records),
                       "a triangle there was culled"),
    "z-fighting": (lambda f, h: any(r.outcome in ("failed_depth", "hi_z")
                                    and r.depth == r.depth_before for r in h.records),
                   "a fragment failed on a tie"),
    "missing premultiplication": (lambda f, h: any(r.outcome == "passed" for r in h.records),
                                  "a fragment was blended there"),
    "blend order": (_nearer_first, "two blended fragments arrived nearer first"),
    "sliver": (_thin_missed, "the thinnest triangle crosses the pixel's box, not its centre"),
}  # fmt: skip


def _rgb(frame: Frame) -> np.ndarray:
    return np.nan_to_num(np.clip(frame.color[..., :3], 0, 1), nan=0.0)


def window_triangles(xy, z) -> np.ndarray:
    """Clip-space triangles (w = 1) whose window positions are ``xy`` (n, 3, 2) in a 48 × 36
    design grid (scaled to the frame) at window depths ``z`` (n, 3)."""
    xy, z = np.asarray(xy, float) * (W / 48), np.asarray(z, float)
    x, y = 2 * xy[..., 0] / W - 1, 1 - 2 * xy[..., 1] / H
    return np.stack([x, y, 2 * z - 1, np.ones_like(x)], axis=-1)


def _quad(x0, y0, x1, y1):
    return [[[x0, y0], [x1, y0], [x1, y1]], [[x0, y0], [x1, y1], [x0, y1]]]


def _cube(winding_reversed: bool = False, **kwargs) -> Frame:
    scene = get_scene("cube")
    clip = scene.clip(W / H)
    clip = clip * np.array([1.6, 1.6, 1, 1])  # zoomed in: a narrower field of view
    if kwargs.pop("reverse_depth", False):
        clip = clip * np.array([1, 1, -1, 1])  # z/w negated: window depth 1 - d
    rgba = np.concatenate([scene.mesh.corner("color"), np.ones((len(clip), 3, 1))], axis=2)
    if winding_reversed:  # the mesh's corners listed the other way round (data, not a setting)
        clip, rgba = clip[:, ::-1], rgba[:, ::-1]
    return render(clip, W, H, attrs=rgba, trace=True, clear_color=(1, 1, 1, 1), **kwargs)


#: Frames 3 to 6 share one wall and one set of render settings (premultiplied blending,
#: a 16-bit depth buffer, one sample): each mistake is in what is drawn, never in a setting
#: a student could read off the frame and compare with the intended one's.
_WALL = [[0.62, 0.56, 0.48]]
_ALPHA = 0.5  # the dark pane's
_STRIP = (np.array([0.2, 0.45, 0.85]), 0.6)  # the tinted strip's straight colour and alpha
_WEDGE = [
    [[8, 13.5], [56, 25.5], [56, 27.5]],  # the strip as meant: 2 px tall throughout
    [[8, 13.5], [56, 27.5], [8, 15.5]],
]
# Along y = 20.5 + (x - 32) / 4 every pixel centre lies 0.125 px or more above or below the
# line, so a strip at most 0.1 px thick above it covers none, though its box reaches many.
_NEEDLE = [[[8, 14.5], [56, 26.5], [56, 26.6]]]


def _pixels(parts) -> Frame:
    """Render ``parts`` [(triangles in pixels, depth, premultiplied RGBA)] in order over the
    wall's settings; a part with alpha < 1 (glass) writes no depth (lesson 11 §6)."""
    xy = [t for tris, *_ in parts for t in tris]
    z = [[d] * 3 for tris, d, _ in parts for _ in tris]
    rgba = np.concatenate([np.repeat(np.asarray([c], float)[:, None], 3 * len(tris), 0)
                           .reshape(len(tris), 3, 4) for tris, _, c in parts])  # fmt: skip
    writes = np.concatenate([np.full(len(tris), c[3] == 1.0) for tris, _, c in parts])
    clip = window_triangles(np.asarray(xy, float) * (48 / W), z)
    return render(clip, W, H, attrs=rgba, blend="premultiplied", depth_format="unorm16",
                  depth_write=writes, trace=True, clear_color=(1, 1, 1, 1))  # fmt: skip


def _wall():
    return (_quad(4, 4, 60, 44), 0.6, [*_WALL[0], 1.0])


def _pane(depth: float, premultiplied: bool = True):
    """A dark pane whose straight colour is the wall's darkened by its alpha: blended as
    premultiplied without being multiplied, it adds exactly what it should have hidden."""
    straight = _ALPHA * np.asarray(_WALL[0])
    colour = straight * _ALPHA if premultiplied else straight
    return (_quad(20, 12, 44, 36), depth, [*colour, _ALPHA])


def _strip(triangles):
    colour, alpha = _STRIP
    return (triangles, 0.3, [*(colour * alpha), alpha])


#: Each frame's symptom as a user would report it: what is seen, never the mechanism. The
#: frames come in look-alike pairs (1-2, 3-4, 5-6): the same symptom, the same picture and
#: the same intended picture, pixel for pixel; only the histories tell them apart (3 to 6
#: even share the broken picture: a plain wall).
_SPECS = [
    ("The cube does not look as intended.", "depth function",
     lambda: _cube(reverse_depth=True), _cube),
    ("The cube does not look as intended.", "culled winding",
     lambda: _cube(winding_reversed=True, cull="back"), lambda: _cube(cull="back")),
    ("The dark pane on the wall is missing.", "z-fighting",
     lambda: _pixels([_wall(), _pane(0.6 - 1e-6)]), lambda: _pixels([_wall(), _pane(0.599)])),
    ("The dark pane on the wall is missing.", "missing premultiplication",
     lambda: _pixels([_wall(), _pane(0.4, premultiplied=False)]),
     lambda: _pixels([_wall(), _pane(0.4)])),
    ("The tinted strip across the wall is missing.", "blend order",
     lambda: _pixels([_strip(_WEDGE), _wall()]), lambda: _pixels([_wall(), _strip(_WEDGE)])),
    ("The tinted strip across the wall is missing.", "sliver",
     lambda: _pixels([_wall(), _strip(_NEEDLE)]), lambda: _pixels([_wall(), _strip(_WEDGE)])),
]  # fmt: skip
_CAUSE_OF = {k + 1: cause for k, (_, cause, *_) in enumerate(_SPECS)}


class _WithheldPlan(Plan):
    """The plan of a frame handed to the student: withheld, the same for every frame (r7: the
    plans told each pair apart, "cull='back' asked: 6 back-facing triangle(s) removed" beside
    "not asked", "576 transparent fragments blended" beside "0")."""

    def __str__(self) -> str:
        return WITHHELD

    def __getitem__(self, name: str):
        raise KeyError(f"no effect {name!r}: {WITHHELD}")


#: What ``frame.plan`` prints for every frame of the exercise, broken or intended.
WITHHELD = ("the plan is withheld in the broken-frame exercises (it would tell the frames of a "
            "pair apart without a pixel history): read frame.history(row, col)")  # fmt: skip


def _handed_out(frame: Frame) -> Frame:
    object.__setattr__(frame, "plan", _WithheldPlan(()))  # the frame is the exercise's own
    return frame


@cache
def broken_frames() -> tuple[BrokenFrame, ...]:
    """The six frames, numbered from 1 (rendered once), their plans withheld."""
    return tuple(BrokenFrame(k + 1, symptom, _handed_out(broken()), _handed_out(intended()))
                 for k, (symptom, _, broken, intended) in enumerate(_SPECS))  # fmt: skip


def frames_to_inspect() -> dict[str, Frame]:
    """Every frame of the exercise for ``FrameInspector(frames=...)``: "frame n" and
    "intended n" side by side in the list, so that a pixel's two histories can be compared
    (r7: the inspector held the broken frames only)."""
    return {f"{what} {b.number}": f for b in broken_frames()
            for what, f in (("frame", b.frame), ("intended", b.intended))}  # fmt: skip


def broken_frame(number: int) -> BrokenFrame:
    """Frame ``number`` (1 to 6)."""
    frames = broken_frames()
    number = as_int("number", number)  # the one integer rule: no bools, operator.index
    if not 1 <= number <= len(frames):
        raise ValueError(f"number must be 1 to {len(frames)}, got {number}")
    return frames[number - 1]


# -- the evidence -----------------------------------------------------------------------------
#: The stages of a pixel's history, in the pipeline's order: where a culled triangle, a centre
#: not covered, a depth test (or Hi-Z) and the colour buffer's writes show in its records.
STAGES = ("culling", "coverage", "depth test", "blending")


def _key(frame: Frame, piece: int) -> frozenset:
    """A triangle as the picture knows it: its corners on screen (x, y), in any order (so the
    same triangle matches across the two frames, drawn in another order or winding)."""
    xy = np.round(frame.trace.window[piece, :, :2], 6)
    return frozenset(map(tuple, xy.tolist()))


def _stages(frame: Frame, row: int, col: int) -> tuple:
    """What each stage of pixel (row, col)'s history did, comparable across two frames: each
    triangle by its corners on screen (:func:`_key`), never by its number."""
    records = frame.history(row, col).records
    keyed = [(_key(frame, r.piece), r) for r in records]
    # Sets of triangles, compared across the frames: "coverage" differs when a triangle covers
    # the centre in one frame and not in the other, whether it is not_covered there or not
    # drawn at all (frame 6: the sliver and the 2 px strip have other corners).
    culled = frozenset(k for k, r in keyed if r.outcome == "culled")
    covered = frozenset(k for k, r in keyed if r.outcome not in ("culled", "not_covered"))
    tested = frozenset((k, r.outcome == "passed") for k, r in keyed
                       if r.outcome in ("hi_z", "failed_depth", "passed"))  # fmt: skip
    blended = tuple((k, tuple(np.round(r.color, 6).tolist())) for k, r in keyed
                    if r.outcome == "passed")  # fmt: skip
    return culled, covered, tested, blended


def _parts_at(number: int, row: int, col: int) -> str | None:
    """The first stage (:data:`STAGES`) at which pixel (row, col)'s history in frame
    ``number`` differs from its history in the intended frame, stage by stage in the
    pipeline's order and triangle by triangle matched by its corners on screen (None: they
    agree throughout). Private: it is the answer's stage."""
    b = broken_frame(number)
    mine, meant = _stages(b.frame, row, col), _stages(b.intended, row, col)
    return next((s for s, x, y in zip(STAGES, mine, meant) if x != y), None)


def _evidence(number: int, row: int, col: int, stage: str) -> bool:
    """Does (row, col, stage) hold: a pixel the mistake changed, whose history shows it and
    differs from the intended one first at ``stage``, as the renderer's own records say?"""
    return _shows(number, row, col) and _parts_at(number, row, col) == stage


# -- the answer -------------------------------------------------------------------------------
def _words(value) -> str:
    return " ".join(value.lower().replace("_", " ").replace("-", " ").split())


_CAUSE_KEYS = {_words(c): c for c in CAUSES}
_SHAPE = '(cause, (row, col), stage), such as ("depth test off", (12, 30), "depth test")'


def _index(name: str, value, pixel) -> int:
    """``value`` as a row or column: an integer (``operator.index``), never a bool or a float
    (r7: 24.7 was read as 24, True as 1)."""
    if isinstance(value, bool | np.bool_):
        raise WrongAnswerType(f"returned the pixel {short(pixel)}: {name} is a bool, not an "
                              "integer")  # fmt: skip
    try:
        return operator.index(value)
    except TypeError:
        raise WrongAnswerType(f"returned the pixel {short(pixel)}: {name} {short(value)} is not "
                              "an integer (a pixel is (row, col), two whole numbers)") from None  # fmt: skip


def as_diagnosis(value) -> tuple[str, tuple[int, int], str]:
    """(cause, (row, col), stage) from the student's answer, read strictly."""
    if isinstance(value, str) and _words(value) in _CAUSE_KEYS:
        # the cause without its evidence (r6: told to drop the quotes of a cause that is text)
        raise WrongAnswerType(f"returned only the cause {value!r}: return {_SHAPE}, the "
                              "cause with its evidence")  # fmt: skip
    refuse_non_answers(value, "a triple (cause, (row, col), stage)")
    if isinstance(value, tuple | list) and len(value) == 2:
        raise WrongAnswerType(f"returned {short(value)} without the stage: return {_SHAPE}, "
                              f"the stage one of {list(STAGES)}")  # fmt: skip
    try:
        cause, pixel, stage = value
        row, col = pixel
    except (TypeError, ValueError):
        raise WrongAnswerType(f"returned {short(value)}: return {_SHAPE}") from None
    if not isinstance(cause, str):
        raise WrongAnswerType(f"returned the cause {short(cause)}, not a text: one of "
                              f"{list(CAUSES)}")  # fmt: skip
    if _words(cause) not in _CAUSE_KEYS:
        raise WrongAnswerType(f"returned the cause {cause!r}, which is not one of the causes "
                              f"(spell it as listed): {', '.join(CAUSES)}")  # fmt: skip
    if not isinstance(stage, str) or _words(stage) not in STAGES:
        raise WrongAnswerType(f"returned the stage {short(stage)}, which is not one of the "
                              f"stages (spell it as listed): {', '.join(STAGES)}")  # fmt: skip
    row, col = _index("row", row, pixel), _index("col", col, pixel)
    if not (0 <= row < H and 0 <= col < W):
        raise WrongAnswerType(f"returned pixel ({row}, {col}), outside the {H} × {W} frame "
                              f"(rows 0–{H - 1}, columns 0–{W - 1})")  # fmt: skip
    return _CAUSE_KEYS[_words(cause)], (row, col), _words(stage)


#: How many well-formed answers each frame's check has judged in this Python session: the
#: one thing a wrong answer is told besides "not right".
_TRIES: dict[int, int] = {}


def _cases(number: int):
    return lambda: [("the diagnosis", (), number)]  # one case: a short title (r7 11-10)


def _right(number: int, got) -> bool:
    cause, (row, col), stage = got
    return cause == _answer(number) and _evidence(number, row, col, stage)


def _same(got, number, args=None) -> bool:
    # One verdict for the whole answer (r7: a separate verdict on the stage let a student find
    # it by trying the four, then the cause among few): counted here, once a check.
    _TRIES[number] = _TRIES.get(number, 0) + 1
    return _right(number, got)


#: The stage, as the verdict recalls it (the same words after every wrong answer).
_STAGE_MEANS = ("the stage is the first, in the pipeline's order, where the pixel's history in "
               "this frame differs from its history in the intended frame, comparing each "
               "triangle with the same triangle there: the same corners on screen, whatever its "
               "number in either frame (a triangle drawn in one frame only covers nothing in "
               "the other)")  # fmt: skip


def _explain(args, number, got) -> str:
    tries = _TRIES.get(number, 0)
    return (f"not right: the cause, the pixel and the stage are judged together, and which of "
            f"them is wrong is not said ({tries} {'try' if tries == 1 else 'tries'} of frame "
            f"{number} recorded in this session). A pixel must be one the mistake changed, "
            f"whose history shows the cause; {_STAGE_MEANS}")  # fmt: skip


def _rule(args, expected, got) -> str:
    return ""


#: No mistake is named: any wrong part gets the one verdict (:func:`_explain`).
DIAGNOSIS_MISTAKES = (Mistake("not right", "", fits=lambda a, e, g: True),)


def _thinnest(frame: Frame) -> float:
    """The smallest altitude (px) of the frame's triangles on screen."""
    return float(_altitudes(frame).min())


def _altitudes(frame: Frame) -> np.ndarray:
    """Each triangle's smallest altitude (px) on screen."""
    xy = frame.trace.window[:, :, :2]
    e = np.roll(xy, -1, axis=1) - xy
    area2 = np.abs(e[:, 0, 0] * e[:, 1, 1] - e[:, 0, 1] * e[:, 1, 0])
    longest = np.linalg.norm(e, axis=2).max(axis=1)
    return area2 / longest


def _draw(ax, case, got):
    """The broken frame with the chosen pixel marked, and the intended one beside it in the
    same axes (an inset outside the axes would be clipped by the figure's edge)."""
    number = case[2]
    b = broken_frame(number)
    gap = 12  # px between the two pictures: room for their tick labels
    artists = [ax.imshow(_rgb(b.frame), extent=(0, W, H, 0), interpolation="nearest"),
               ax.imshow(_rgb(b.intended), extent=(W + gap, 2 * W + gap, H, 0),
                         interpolation="nearest")]  # fmt: skip
    if isinstance(got, tuple) and len(got) == 3 and got[0] in CAUSES:  # an answer, as read
        _, (row, col), _ = got
        for x in (col, col + W + gap):  # on both pictures (r7: on the broken one only)
            artists += ax.plot([x, x + 1, x + 1, x, x], [row, row, row + 1, row + 1, row],
                               color="#D55E00", lw=2)  # fmt: skip
    ax.set_xlim(0, 2 * W + gap)
    ax.set_ylim(H, 0)
    ax.set_xticks([0, W // 2, W - 1, W + gap, W + gap + W // 2, 2 * W + gap - 1],
                  ["0", str(W // 2), str(W - 1), "0", str(W // 2), str(W - 1)])  # fmt: skip
    ax.set_xlabel("left: as rendered · right: as intended", fontsize="small")
    ax.set_title(f"frame {number}: {b.symptom}", fontsize="small")
    return artists


def frame_exercise(number: int) -> Exercise:
    """Exercise ``broken_frame_<number>``: fn() returns (cause, (row, col), stage)."""
    return Exercise(
        f"broken_frame_{number}", _cases(number), as_diagnosis, _same, _explain, _rule,
        DIAGNOSIS_MISTAKES, draw=_draw,
    )  # fmt: skip


#: The six exercises, for the registry: name -> how to build it.
EXERCISES = {f"broken_frame_{n}": (lambda n=n: frame_exercise(n)) for n in range(1, 7)}
