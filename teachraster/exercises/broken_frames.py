"""Exercises ``broken_frame_1`` … ``broken_frame_6`` (lesson 11): find what broke a frame.

tinyrenderer's "visual troubleshooting", as graded exercises: each frame below was rendered
with one mistake a graphics programmer makes (a reversed depth mapping, culling the wrong
winding, surfaces too close for the depth buffer, straight colours blended as premultiplied,
transparent geometry drawn before what lies behind it, a triangle thinner than a pixel
drawn with one sample). The student sees the frame beside the intended one, inspects pixel
histories (``frame.history(row, col)``, the ``FrameInspector``) and answers with a cause from
:data:`CAUSES`, a pixel whose history shows it and the stage (:data:`STAGES`) where that
history first parts from the intended frame's.

The picture cannot name the cause: the frames come in look-alike pairs (1-2, 3-4, 5-6) with
the same symptom, the same picture and the same intended picture pixel for pixel, and every
frame is rendered with exactly its intended frame's settings (the mistake is in what is
drawn), so neither the picture nor the frame's attributes tell a pair apart; the histories
do. The check judges the evidence first (:func:`parts_at`, from the renderer's records) and
the cause only beside evidence that holds: a wrong cause then gets a hint drawn from the
frame's own record, never the answer; a cause beside evidence that does not hold is not
judged at all, so cycling through the causes earns nothing.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import numpy as np

from ..core.validate import as_int
from ..pipeline.rendering.render_triangles import Frame, render
from ..pipeline.rendering.scenes import get_scene
from .answers import refuse_non_answers, short
from .exercise import Exercise, Mistake
from .running import WrongAnswerType
from .scalars import num

#: Frame size: small, so that every pixel is easy to pick.
W, H = 64, 48

#: The causes a diagnosis may name (six occur, four do not).
CAUSES = {
    "depth function": "the depth test compares in the wrong direction for the frame's depths, "
    "so it keeps the farther surface",
    "culled winding": "triangles that face the camera are culled",
    "z-fighting": "the depth buffer cannot tell two surfaces apart",
    "missing premultiplication": "straight-alpha colours are blended as premultiplied ones",
    "blend order": "transparent geometry is drawn before what lies behind it",
    "sliver": "a triangle thinner than a pixel drawn with one sample per pixel",
    "depth test off": "later triangles overwrite nearer ones",
    "near-plane clipping": "geometry is cut away by the near plane",
    "affine interpolation": "attributes are interpolated without the divide by w",
    "texture filtering": "the wrong texture filter or mip level",
}


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
    bearing the cause's signature (:data:`SIGNATURES`)?"""
    if not (0 <= row < H and 0 <= col < W and _differs(number)[row, col]):
        return False
    frame = broken_frame(number).frame
    return bool(SIGNATURES[_answer(number)][0](frame, frame.history(row, col)))


def _tested(frame, h) -> bool:
    """Two or more fragments met the depth test here: its direction decided which is shown."""
    return sum(r.outcome in ("passed", "failed_depth") for r in h.records) >= 2


def _nearer_first(frame, h) -> bool:
    """Two blended fragments arrived nearer first."""
    depths = [r.depth for r in h.records if r.outcome == "passed"]
    return len(depths) >= 2 and any(a < b for a, b in zip(depths, depths[1:]))


def _thin_missed(frame, h) -> bool:
    """The thinnest triangle crosses the pixel's box but not its centre (no fragment)."""
    k = int(np.argmin(_altitudes(frame)))
    mine = [r for r in h.records if r.triangle == k]
    return bool(mine) and all(r.outcome == "not_covered" for r in mine)


#: What a history shows for each cause that occurs: a test on (frame, history), and words.
SIGNATURES = {
    "depth function": (_tested, "two or more fragments met the depth test there"),
    "culled winding": (lambda f, h: any(r.outcome == "culled" for r in h.records),
                       "a triangle there was culled"),
    "z-fighting": (lambda f, h: any(r.outcome in ("failed_depth", "hi_z")
                                    and r.depth == r.depth_before for r in h.records),
                   "a fragment failed on a tie"),
    "missing premultiplication": (lambda f, h: any(r.outcome == "passed" for r in h.records),
                                  "a fragment was blended there"),
    "blend order": (_nearer_first, "two blended fragments arrived nearer first"),
    "sliver": (_thin_missed, "a triangle crosses the pixel without covering its centre"),
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


@cache
def broken_frames() -> tuple[BrokenFrame, ...]:
    """The six frames, numbered from 1 (rendered once)."""
    return tuple(BrokenFrame(k + 1, symptom, broken(), intended())
                 for k, (symptom, _, broken, intended) in enumerate(_SPECS))  # fmt: skip


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
    """What each stage of pixel (row, col)'s history did, comparable across two frames."""
    records = frame.history(row, col).records
    keyed = [(_key(frame, r.piece), r) for r in records]
    culled = frozenset(k for k, r in keyed if r.outcome == "culled")
    covered = frozenset(k for k, r in keyed if r.outcome not in ("culled", "not_covered"))
    tested = frozenset((k, r.outcome == "passed") for k, r in keyed
                       if r.outcome in ("hi_z", "failed_depth", "passed"))  # fmt: skip
    blended = tuple((k, tuple(np.round(r.color, 6).tolist())) for k, r in keyed
                    if r.outcome == "passed")  # fmt: skip
    return culled, covered, tested, blended


def parts_at(number: int, row: int, col: int) -> str | None:
    """The first stage (:data:`STAGES`) at which pixel (row, col)'s history in frame
    ``number`` parts from its history in the intended frame (None: they agree throughout)."""
    b = broken_frame(number)
    mine, meant = _stages(b.frame, row, col), _stages(b.intended, row, col)
    return next((s for s, x, y in zip(STAGES, mine, meant) if x != y), None)


def _evidence(number: int, row: int, col: int, stage: str) -> bool:
    """Does (row, col, stage) hold: a pixel the mistake changed, whose history shows it and
    parts from the intended one at ``stage``, as the renderer's own records say?"""
    return _shows(number, row, col) and parts_at(number, row, col) == stage


# -- the answer -------------------------------------------------------------------------------
def _words(value) -> str:
    return " ".join(value.lower().replace("_", " ").replace("-", " ").split())


_CAUSE_KEYS = {_words(c): c for c in CAUSES}
_SHAPE = '(cause, (row, col), stage), such as ("depth test off", (12, 30), "depth test")'


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
    try:
        row, col = int(row), int(col)
    except (TypeError, ValueError):
        raise WrongAnswerType(f"returned the pixel {short(pixel)}, not a pair of integers "
                              "(row, col)") from None  # fmt: skip
    if not (0 <= row < H and 0 <= col < W):
        raise WrongAnswerType(f"returned pixel ({row}, {col}), outside the {H} × {W} frame "
                              f"(rows 0–{H - 1}, columns 0–{W - 1})")  # fmt: skip
    return _CAUSE_KEYS[_words(cause)], (row, col), _words(stage)


def _cases(number: int):
    return lambda: [("the evidence: a changed pixel and the stage where its history parts from "
                     "the intended one", (), ("evidence", number)),
                    ("the cause", (), ("cause", number))]  # fmt: skip


def _holds(number: int, got) -> bool:
    _, (row, col), stage = got
    return _evidence(number, row, col, stage)


def _same(got, expected, args=None) -> bool:
    part, number = expected
    # The cause is judged only beside evidence that holds: cycling through the causes with
    # made-up evidence never passes, and a refutation is drawn from a record the student read.
    return _holds(number, got) and (part == "evidence" or got[0] == _answer(number))


def _changed(number: int, row: int, col: int) -> bool:
    """Did the mistake of frame ``number`` change pixel (row, col) (False outside it)?"""
    d = _differs(number)
    return bool(0 <= row < d.shape[0] and 0 <= col < d.shape[1] and d[row, col])


def _explain(args, expected, got) -> str:
    part, _ = expected
    cause, (row, col), stage = got
    if part == "evidence":
        return f"you say pixel ({row}, {col})'s history parts from the intended one at {stage!r}"
    if not _holds(expected[1], got):  # not judged: never "does not fit", which would refute it
        return f"you name {cause!r}"
    return f"{cause!r} does not fit"


def _rule(args, expected, got) -> str:
    return ""


def _cause_words(args, expected, got) -> str:
    cause, (row, col), _ = got
    return hint(cause, expected[1], row, col)


def _stage_words(number: int, row: int, col: int, stage: str) -> str:
    """Why the stage does not hold at a pixel that shows the mistake: true, and the same words
    for a stage before or after the right one (no direction to home in on by trying)."""
    return (f"the two histories of pixel ({row}, {col}) do not first part at {stage!r}: read "
            "them side by side from the first record (frame.history and intended.history)")  # fmt: skip


def _unjudged(args, expected, got) -> str:
    return ("the cause is judged only beside evidence that holds (see the evidence case): "
            "read the pixel's history first")  # fmt: skip


#: A wrong answer's parts: the evidence (the pixel, then the stage) and, once it holds, the
#: cause (a hint from the frame's own record). A cause beside evidence that does not hold is
#: not judged at all, so no number of tries finds it without reading a history.
DIAGNOSIS_MISTAKES = (
    Mistake("cause not judged", _unjudged,
            fits=lambda a, e, g: e[0] == "cause" and not _holds(e[1], g)),
    Mistake("cause", _cause_words, fits=lambda a, e, g: e[0] == "cause"),
    Mistake("pixel (col, row)", "a pixel is (row, col), the row first, and (col, row) = "
            "(x, y) is one the mistake changed: did you give (x, y)?", fits=lambda a, e, g:
            e[0] == "evidence" and not _shows(e[1], *g[1]) and _shows(e[1], *g[1][::-1])),
    Mistake("stage", lambda a, e, g: _stage_words(e[1], *g[1], g[2]), fits=lambda a, e, g:
            e[0] == "evidence" and _shows(e[1], *g[1])),
    Mistake("pixel", lambda a, e, g: _pixel_words(e[1], *g[1]), fits=lambda a, e, g:
            e[0] == "evidence"),
)  # fmt: skip


def _pixel_words(number: int, row: int, col: int) -> str:
    if _changed(number, row, col):
        return (f"pixel ({row}, {col}) changed, but its history does not show what went wrong: "
                "compare it with the intended frame's history of the same pixel, or choose "
                "another changed pixel")  # fmt: skip
    return (f"pixel ({row}, {col}) is the same in this frame as in the intended one: choose a "
            "pixel the mistake changed (compare the two pictures), then read its history")  # fmt: skip


def hint(cause: str, number: int, row: int, col: int) -> str:
    """What frame ``number``'s record shows against ``cause`` (true of this frame; never names
    the right cause)."""
    frame = broken_frame(number).frame
    h = frame.history(row, col)
    trace, debug = frame.trace, frame.trace.debug
    failed = [r for r in h.records if r.outcome in ("failed_depth", "hi_z")]
    blend = debug.blend
    if cause == "culled winding" and not trace.culled.any():
        return "no triangle of this frame was culled: no history has a 'culled' record"
    if cause == "depth test off" and debug.inputs.depth_test:
        return "the depth test is on in this frame (every history says 'depth test on')"
    if cause == "near-plane clipping" and not (np.asarray(trace.clip_status) > 0).any():
        return "no triangle of this frame was clipped (frame.trace.clip_status is 0 throughout)"
    if cause == "affine interpolation":
        return ("every triangle of this frame has one colour at all three corners: "
                "interpolation, affine or perspective-correct, gives that colour everywhere")  # fmt: skip
    if cause == "texture filtering":
        return "this frame samples no texture: its colours are the triangles' own"
    if cause == "missing premultiplication" and (blend is None or blend.mode != "premultiplied"):
        if blend is None or blend.mode is None:
            return "this frame does not blend at all"
        if blend.mode == "over":  # r6: "whose factors expect straight colours" was obscure
            return ("the colours here are straight and blended with straight-alpha factors "
                    "(src·α + dst·(1−α)): nothing premultiplied is blended as straight, or "
                    "the reverse")  # fmt: skip
        return f"this frame blends with {blend.mode!r}, whose factors expect straight colours"
    if cause == "missing premultiplication":
        return _premultiplied_hint(number, row, col)
    if cause == "blend order":
        return _order_hint(h, blend)
    if cause == "z-fighting":
        return _fight_hint(h, row, col)
    if cause == "depth function":
        return _depth_hint(failed, row, col)
    if cause == "sliver":
        return f"every triangle of this frame is at least {num(_thinnest(frame))} px across"
    return f"it does not explain what pixel ({row}, {col})'s history shows: {h.outcomes}"


def _premultiplied_hint(number: int, row: int, col: int) -> str:
    """Premultiplied blending with the colours as meant: every fragment that reached the
    buffer brings the colour it brings in the intended frame (the same triangle, by its
    corners), so none of them was left unmultiplied."""
    b = broken_frame(number)
    meant = {k: c for k, c in _stages(b.intended, row, col)[3]}
    mine = _stages(b.frame, row, col)[3]
    if all(meant.get(k, c) == c for k, c in mine):
        return (f"every fragment that reaches the colour buffer at pixel ({row}, {col}) brings "
                "the colour it brings in the intended frame (compare the two histories' "
                "'fragment' colours): none was left unmultiplied")  # fmt: skip
    return f"the fragments at pixel ({row}, {col}) blend with the colours their history shows"


def _order_hint(h, blend) -> str:
    if blend is None or blend.mode is None:
        return "nothing in this frame is blended: every fragment replaces the colour before it"
    passed = [r for r in h.records if r.outcome == "passed"]
    depths = [r.depth for r in passed]
    if len(passed) < 2:
        return (f"only {len(passed)} fragment reaches the colour buffer at pixel ({h.row}, "
                f"{h.col}): there is no order to get wrong there")  # fmt: skip
    if all(a >= b for a, b in zip(depths, depths[1:])):
        return (f"at pixel ({h.row}, {h.col}) the fragments arrive farthest first (depths "
                f"{', '.join(num(d) for d in depths)}), the order blending needs")  # fmt: skip
    return f"the fragments at pixel ({h.row}, {h.col}) blend in the order their history shows"


def _fight_hint(h, row, col) -> str:
    depths = sorted({r.depth for r in h.records if np.isfinite(r.depth)})
    if len(depths) < 2:
        n = len([r for r in h.records if np.isfinite(r.depth)])
        reach = {0: "no fragment reaches", 1: "only 1 fragment reaches"}.get(
            n, f"all {n} fragments share one depth at")  # fmt: skip
        return f"{reach} pixel ({row}, {col}): nothing to fight"
    gap = min(b - a for a, b in zip(depths, depths[1:]))
    return (f"the fragments at pixel ({row}, {col}) have distinct stored depths (the closest "
            f"differ by {num(gap)}): the buffer tells them apart")  # fmt: skip


def _depth_hint(failed, row, col) -> str:
    if not failed:
        return (f"no fragment failed the depth test at pixel ({row}, {col}): the test decided "
                "nothing there")  # fmt: skip
    r = failed[0]
    if r.depth == r.depth_before:
        return (f"the fragment of triangle {r.triangle} that failed at pixel ({row}, {col}) "
                f"has exactly the stored depth {num(r.depth)}: a tie, which no strict test "
                "can settle either way")  # fmt: skip
    return (f"at pixel ({row}, {col}) triangle {r.triangle} failed at depth {num(r.depth)} "
            f"behind the stored {num(r.depth_before)}, and it is meant to lie behind: the test "
            "kept the nearer surface")  # fmt: skip


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
    number = case[2][1]
    b = broken_frame(number)
    gap = 12  # px between the two pictures: room for their tick labels
    artists = [ax.imshow(_rgb(b.frame), extent=(0, W, H, 0), interpolation="nearest"),
               ax.imshow(_rgb(b.intended), extent=(W + gap, 2 * W + gap, H, 0),
                         interpolation="nearest")]  # fmt: skip
    if got is not None and isinstance(got[0], str) and got[0] in CAUSES:  # an answer
        _, (row, col), _ = got
        artists += ax.plot([col, col + 1, col + 1, col, col], [row, row, row + 1, row + 1, row],
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
