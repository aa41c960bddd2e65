"""Exercises ``broken_frame_1`` … ``broken_frame_6`` (lesson 11): find what broke a frame.

tinyrenderer's "visual troubleshooting", as graded exercises: each frame below was rendered
with one mistake a graphics programmer makes (a reversed depth mapping, culling the wrong
winding, surfaces too close for the depth buffer, straight colours blended as premultiplied,
transparent geometry drawn before what lies behind it, a triangle thinner than a pixel
drawn without antialiasing). The student sees the frame beside the intended one, inspects pixel histories
(``frame.history(row, col)``, the ``FrameInspector``) and answers with a cause from
:data:`CAUSES` and a pixel whose history shows it. Two frames look alike (the cube showing
its hidden faces) and only their histories tell them apart.

A wrong cause gets a hint drawn from the frame's own record (what the history at the chosen
pixel, or the trace, shows that the cause cannot explain), never the answer; a pixel the
mistake did not change, or whose history does not bear the cause's signature
(:data:`SIGNATURES`), is refused.
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
    "z-fighting": (lambda f, h: any(r.outcome == "failed_depth" and r.depth == r.depth_before
                                    for r in h.records), "a fragment failed on a tie"),
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


def _rgba(colours, alpha=1.0) -> np.ndarray:
    """Per-triangle colours (n, 3) as per-vertex RGBA (n, 3, 4)."""
    c = np.asarray(colours, float)
    return np.repeat(np.concatenate([c, np.full((len(c), 1), alpha)], axis=1)[:, None], 3, 1)


def _quad(x0, y0, x1, y1):
    return [[[x0, y0], [x1, y0], [x1, y1]], [[x0, y0], [x1, y1], [x0, y1]]]


def _cube(**kwargs) -> Frame:
    scene = get_scene("cube")
    clip = scene.clip(W / H)
    clip = clip * np.array([1.6, 1.6, 1, 1])  # zoomed in: a narrower field of view
    if kwargs.pop("reverse_depth", False):
        clip = clip * np.array([1, 1, -1, 1])  # z/w negated: window depth 1 - d
    rgba = np.concatenate([scene.mesh.corner("color"), np.ones((len(clip), 3, 1))], axis=2)
    return render(clip, W, H, attrs=rgba, trace=True, clear_color=(1, 1, 1, 1), **kwargs)


def _decal(depth_format: str) -> Frame:
    wall = _quad(2, 2, 46, 34)
    sticker = _quad(12, 8, 36, 28)
    tilt = lambda xy: 0.4 + 0.2 * np.asarray(xy)[..., 0] / W  # noqa: E731 - a sloped plane
    z = np.concatenate([tilt(wall), tilt(sticker) - 2e-6])
    clip = window_triangles(np.concatenate([wall, sticker]), z)
    rgba = _rgba([[0.55, 0.55, 0.6]] * 2 + [[0.95, 0.6, 0.1]] * 2)
    return render(clip, W, H, attrs=rgba, depth_format=depth_format, trace=True,
                  clear_color=(1, 1, 1, 1))  # fmt: skip


def _glass(premultiply: bool) -> Frame:
    xy = [[[4, 4], [34, 6], [10, 32]], [[16, 10], [44, 12], [30, 34]]]
    colours, alpha = np.array([[0.9, 0.3, 0.1], [0.2, 0.4, 0.9]]), 0.45
    rgba = _rgba(colours * (alpha if premultiply else 1.0), alpha)
    clip = window_triangles(xy, [[0.6] * 3, [0.4] * 3])  # drawn farthest first
    return render(clip, W, H, attrs=rgba, blend="premultiplied", depth_write=False,
                  clear_color=(0.15, 0.15, 0.2, 1), trace=True)  # fmt: skip


def _wall_and_glass(glass_first: bool) -> Frame:
    """An opaque wall and a pane of glass in front of it, the glass drawn as lesson 11 §6
    teaches, with depth writes off (so only the order decides): drawn first, the wall that
    comes after it passes (the buffer holds no depth of the glass) and covers it."""
    wall, glass = _quad(4, 4, 44, 32), [[[10, 2], [40, 10], [20, 34]]]
    parts = [(glass, 0.3, [0.2, 0.5, 0.9], 0.4), (wall, 0.7, [0.55, 0.5, 0.45], 1.0)]
    if not glass_first:
        parts.reverse()
    xy = [t for tris, *_ in parts for t in tris]
    z = [[d] * 3 for tris, d, *_ in parts for _ in tris]
    rgba = np.concatenate([_rgba([c] * len(tris), a) for tris, _, c, a in parts])
    writes = np.concatenate([np.full(len(tris), a == 1.0) for tris, _, _, a in parts])
    return render(window_triangles(xy, z), W, H, attrs=rgba, blend="over", trace=True,
                  depth_write=writes, clear_color=(1, 1, 1, 1))  # fmt: skip


def _wire(samples: int) -> Frame:
    """A post and a wire. The post's edges lie on pixel boundaries (design units of 3 are 4
    px), so more samples change only the pixels the wire touches: the two frames differ by
    the cause alone."""
    post = _quad(3, 6, 9, 33)
    wire = [[[8.5, 9.2], [44.2, 23.7], [44.2, 24.0]]]
    clip = window_triangles(post + wire, [[0.5] * 3] * 3)
    rgba = _rgba([[0.45, 0.35, 0.25]] * 2 + [[0.1, 0.1, 0.1]])
    return render(clip, W, H, attrs=rgba, samples=samples, trace=True, clear_color=(1, 1, 1, 1))


#: Each frame's symptom as a user would report it: what is seen, never the mechanism.
_SPECS = [
    ("The cube of lesson 05a does not look as intended.", "depth function",
     lambda: _cube(reverse_depth=True), _cube),
    ("The cube does not look as intended here either.", "culled winding",
     lambda: _cube(cull="front"), lambda: _cube(cull="back")),
    ("The orange sticker on the wall does not look as intended.", "z-fighting",
     lambda: _decal("unorm16"), lambda: _decal("float64")),
    ("The two panes of coloured glass do not have the intended colours.",
     "missing premultiplication", lambda: _glass(False), lambda: _glass(True)),
    ("The blue pane does not look as intended.", "blend order",
     lambda: _wall_and_glass(True), lambda: _wall_and_glass(False)),
    ("The wire from the post does not look as intended.", "sliver", lambda: _wire(1),
     lambda: _wire(16)),
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


# -- the answer -------------------------------------------------------------------------------
def as_diagnosis(value) -> tuple[str, tuple[int, int]]:
    """(cause, (row, col)) from the student's answer, read strictly."""
    if isinstance(value, str) and " ".join(value.lower().replace("_", " ").split()) in CAUSES:
        # the cause without its pixel (r6: told to drop the quotes of a cause that is text)
        raise WrongAnswerType(f"returned only the cause {value!r}: return (cause, (row, col)), "
                              "the cause and a pixel whose history shows it")  # fmt: skip
    refuse_non_answers(value, "a pair (cause, (row, col))")
    try:
        cause, pixel = value
        row, col = pixel
    except (TypeError, ValueError):
        raise WrongAnswerType(
            f'returned {short(value)}: return a pair such as ("depth test off", (12, 30))'
        ) from None
    if not isinstance(cause, str):
        raise WrongAnswerType(f"returned the cause {short(cause)}, not a text: one of "
                              f"{list(CAUSES)}")  # fmt: skip
    key = " ".join(cause.lower().replace("_", " ").split())
    if key not in CAUSES:
        raise WrongAnswerType(f"returned the cause {cause!r}, which is not one of the causes "
                              f"(spell it as listed): {', '.join(CAUSES)}")  # fmt: skip
    try:
        row, col = int(row), int(col)
    except (TypeError, ValueError):
        raise WrongAnswerType(f"returned the pixel {short(pixel)}, not a pair of integers "
                              "(row, col)") from None  # fmt: skip
    if not (0 <= row < H and 0 <= col < W):
        raise WrongAnswerType(f"returned pixel ({row}, {col}), outside the {H} × {W} frame "
                              f"(rows 0–{H - 1}, columns 0–{W - 1})")  # fmt: skip
    return key, (row, col)


def _cases(number: int):
    return lambda: [("the cause", (), ("cause", number)),
                    ("a pixel whose history shows it", (), ("pixel", number))]  # fmt: skip


def _same(got, expected, args=None) -> bool:
    part, number = expected
    cause, (row, col) = got
    if part == "cause":
        return cause == _answer(number)
    return _shows(number, row, col)


def _changed(number: int, row: int, col: int) -> bool:
    """Did the mistake of frame ``number`` change pixel (row, col) (False outside it)?"""
    d = _differs(number)
    return bool(0 <= row < d.shape[0] and 0 <= col < d.shape[1] and d[row, col])


def _explain(args, expected, got) -> str:
    part, _ = expected
    cause, (row, col) = got
    if part == "pixel":
        if not _changed(expected[1], row, col):
            return f"pixel ({row}, {col}) is the same in this frame as in the intended one"
        return f"pixel ({row}, {col}) changed, but its history does not show what went wrong"
    return f"{cause!r} does not fit"


def _rule(args, expected, got) -> str:
    return ""


def _cause_words(args, expected, got) -> str:
    cause, (row, col) = got
    return hint(cause, broken_frame(expected[1]).frame, row, col)


#: A wrong answer is either part: the cause (a hint from the frame's record follows) or the
#: pixel (one the mistake did not change).
DIAGNOSIS_MISTAKES = (
    Mistake("cause", _cause_words, fits=lambda a, e, g: e[0] == "cause"),
    Mistake("pixel (col, row)", "a pixel is (row, col), the row first, and (col, row) = "
            "(x, y) is one the mistake changed: did you give (x, y)?", fits=lambda a, e, g:
            e[0] == "pixel" and _shows(e[1], g[1][1], g[1][0])),
    Mistake("pixel", lambda a, e, g: _pixel_words(e[1], *g[1]), fits=lambda a, e, g:
            e[0] == "pixel"),
)  # fmt: skip


def _pixel_words(number: int, row: int, col: int) -> str:
    if _on_wide(number, row, col):
        return "it lies on the post, which is wider than a pixel: choose a pixel along the wire"
    if _changed(number, row, col):
        return ("compare its history with the intended frame's history of the same pixel, or "
                "choose another changed pixel whose history shows the mistake")  # fmt: skip
    return "choose a pixel the mistake changed (compare the two pictures), then read its history"


def _on_wide(number: int, row: int, col: int) -> bool:
    """Frame 6 only: is the pixel's centre covered by a triangle other than the thinnest (the
    post), and not crossed by the thin one (the wire)?"""
    if _answer(number) != "sliver":
        return False
    frame = broken_frame(number).frame
    k = int(np.argmin(_altitudes(frame)))
    records = frame.history(row, col).records
    return not any(r.triangle == k for r in records) and any(
        r.outcome != "not_covered" for r in records
    )


def hint(cause: str, frame: Frame, row: int, col: int) -> str:
    """What the frame's record shows against ``cause`` (true of this frame; never names the
    right cause)."""
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
    if cause == "blend order":
        return _order_hint(h, blend)
    if cause == "z-fighting":
        return _fight_hint(h, row, col)
    if cause == "depth function":
        return _depth_hint(failed, row, col)
    if cause == "sliver":
        return f"every triangle of this frame is at least {num(_thinnest(frame))} px across"
    return f"it does not explain what pixel ({row}, {col})'s history shows: {h.outcomes}"


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
        _, (row, col) = got
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
    """Exercise ``broken_frame_<number>``: fn() returns (cause, (row, col))."""
    return Exercise(
        f"broken_frame_{number}", _cases(number), as_diagnosis, _same, _explain, _rule,
        DIAGNOSIS_MISTAKES, draw=_draw,
    )  # fmt: skip


#: The six exercises, for the registry: name -> how to build it.
EXERCISES = {f"broken_frame_{n}": (lambda n=n: frame_exercise(n)) for n in range(1, 7)}
