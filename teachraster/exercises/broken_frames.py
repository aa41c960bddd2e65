"""Exercises ``broken_frame_1`` … ``broken_frame_9`` (lesson 11): find what broke a frame.

tinyrenderer's "visual troubleshooting", as graded exercises: each frame below was rendered
with one mistake a graphics programmer makes (alphabetically, each in one frame or more:
transparent geometry drawn before what lies behind it, culling the wrong winding, a reversed
depth mapping, straight colours blended as premultiplied, a strip modelled thinner than a
pixel, surfaces too close for the depth buffer). The student sees the frame beside the intended
one, inspects pixel histories (``frame.history(row, col)``, the ``FrameInspector``) and answers
with a cause from :data:`CAUSES`, a pixel where the two frames differ, and the evidence
:data:`EVIDENCE` names for that cause: a number or colour read off that pixel's history (a
depth to its six printed decimals, a colour (r, g, b) or a distance to its four printed
decimals).

What is hidden and what is not. The frames come in look-alike groups (1-2, 3-4-9, 5-6-7-8)
with the same symptom, the same picture and the same intended picture pixel for pixel; frames that
look alike may or may not share a cause (r16 11-2: while each pair held two different causes,
solving one frame ruled its cause out for its partner). Two frames that share a cause never
bear its mark at the same pixels (r18-3: frame 7 was frame 1's mistake at the same pixels, and
frame 1's function passed it unread): frame 7 has frame 1's cause on the strip, frame 8 frame
6's with the thin triangle over other pixels, frame 9 frame 5's on the pane (off the strip's
pixels), so a diagnosis copied from a frame with the same cause fails, and each frame's
histories must be read. Hidden: the cause (no attribute or repr
of a :class:`BrokenFrame` names it; the module keeps only a salted hash of each frame's cause,
which hides the key from a reader, not from someone who hashes the ten names: an answer whose
code reads ``_KEY`` or ``_SALT``, under any name, is not counted), the frames' ``plan``
(:data:`WITHHELD`). Not hidden: ``frame.trace`` and ``frame.attrs``, the renderer's records
that the histories read, and this module's source, which shows how each frame is built. Neither
gives the point: the evidence is a value of the student's own pixel, derived from the frame's
history when the answer is checked (r8: the cause, a changed pixel and a stage named by the
cause passed, 77 blind calls solved all six).

The answer is a function ``broken_frame_n(b)`` that reads the diagnosis from the frame pair
``b`` it is given. The check calls it on the frame shown and on the same mistake redrawn at
check time with another look (:data:`_REDRAWN`: another wall and strip colour, other depths;
the same changed pixels), so a value harvested from the frame shown by a loop over its
history's values fails the redrawn frame (r9 11-1: 137 calls solved all six). What remains
open, said in docs/grading.md: a loop inside the function that tries answers against the
checker (a check started from inside the student's function never passes), and calls into
this module's private readers (reported "not counted", :data:`_PRIVATE`, from any thread).
The look-alike frames 1 and 2 take evidence of different kinds (the depth shown; the triangle
culled in one frame and drawn in the other, whose number the redrawn frame changes), so one
reader does not serve both causes (r11 11-D: a coin flip once the reader was written).

What a wrong answer is told, in this order: a check run inside the function; a pixel where
the two frames agree; the frame's cause at a changed pixel that does not show its mark
(:data:`_SIGNS`; the sliver's: the thin triangle passes through the pixel); a cause that is
not the frame's (the value is then not judged: r18-2); a triangle's number read off the
intended frame's history (r84 11-2: the cube's redrawn pair numbers its two frames apart); the
frame shown's value given for the redrawn frame; another surface's depth in the evidence's own
history (z-fighting: the wall's, r318); another record's value, or another field's, in the history
the list names (r377: said by triangle, field and frame); the evidence's value read off the
other frame of the pair, only where the history the list names lacks it (r309: the intended
frame's, or the broken frame's where the list asks the intended frame's; r377: with its
record); a depth no history prints but a fragment's as its frame draws it (the trace,
unrounded, r399: its triangle, frame and record said); a value that is not the evidence there (and a row and column, or the sliver's two
numbers, swapped: said first).
"""

from __future__ import annotations

import hashlib
import operator
import secrets
import textwrap
import threading
from dataclasses import dataclass, replace
from functools import cache, lru_cache

import numpy as np

from ..core.validate import as_int
from ..pipeline.planning.render_plan import Plan
from ..pipeline.rendering.render_triangles import Frame, render
from ..pipeline.rendering.scenes import get_scene
from .answers import refuse_non_answers, short
from .exercise import Exercise, Mistake, PackageAnswer
from .interrupt import transparent
from .report import NOTHING_DRAWN_FOR, issued
from .running import WrongAnswerType
from .tries import FREE_CAUSES

#: Frame size: small, so that every pixel is easy to pick.
W, H = 64, 48

#: The causes a diagnosis may name (six occur, three of them in two frames; four occur in none),
#: in alphabetical order: every listing of them (the notebook's, a wrong form's message)
#: follows this order, never the frames' (r8: listed in the frames' order, the causes were the
#: answer key).
CAUSES = {
    "affine interpolation": "attributes are interpolated without the divide by w",
    "blend order": "transparent geometry is drawn before what lies behind it",
    "culled winding": "triangles that face the camera are culled",
    "depth function": "the depth test compares in the wrong direction for the frame's depths, "
    "so it keeps the farther surface",
    "depth test off": "later triangles overwrite nearer ones",
    "missing premultiplication": "straight-alpha colours are blended as premultiplied ones",
    "near-plane clipping": "geometry is cut away by the near plane",
    # r7: the intended frame is the strip modelled 2 px thick, not the sliver with more
    # samples, so the cause is the geometry: a strip thinner than a pixel between the centres
    "sliver": "a triangle modelled thinner than a pixel, so thin that it falls between the "
    "pixel centres (the one sample of each pixel)",
    "texture filtering": "the wrong texture filter or mip level",
    # r8 11-6: every pixel ties here, so the pane loses everywhere; at an angle the two
    # surfaces would tie at some pixels only, in the stitched pattern the name comes from
    # r18-7: "in stitches: the name" read as if "stitches" were the name
    "z-fighting": "the depth buffer cannot tell two surfaces apart (where they tie at some "
    "pixels only, the two fight: each shows through the other in stitches)",
}

#: For each cause, the evidence an answer gives with it: what to read off the history of the
#: chosen pixel (the broken frame's, unless it says the intended frame's), and its kind.
EVIDENCE = {
    "affine interpolation": ("number", "the attribute value the pixel shows"),
    "blend order": ("colour", "the colour (r, g, b) the transparent fragment's blend wrote "
                    "(its 'after'), which a later write replaced"),
    # r11 11-D: not the depth shown, the evidence of its look-alike "depth function": one
    # reader for both left the cause a coin flip
    "culled winding": ("triangle", "the number (in this frame's history) of a triangle this "
                       "frame culls at the pixel and the intended frame draws there (its "
                       "fragment passes the depth test)"),
    "depth function": ("depth", "the depth of the fragment the pixel shows"),
    "depth test off": ("depth", "the depth of a fragment that passed though the stored depth "
                       "was nearer"),
    "missing premultiplication": ("colour", "the fragment colour (r, g, b) the blend received"),
    "near-plane clipping": ("number", "how far (px) the pixel's centre lies outside the edge "
                            "the near plane cut"),
    # r18-7: "lies outside it" read as the pixel
    "sliver": ("pair", "(how far (px) the centre of a pixel the thin triangle passes "
               "through lies outside that triangle, the depth of the fragment the intended "
               "frame draws there instead)"),
    "texture filtering": ("colour", "the texel colour (r, g, b) the pixel shows"),
    "z-fighting": ("depth", "the depth the fragment that fails on a tie in the broken frame "
                   "was meant to have: its depth in the intended frame's history"),
}  # fmt: skip


@dataclass(frozen=True, eq=False)  # by identity: a redrawn frame is another frame
class BrokenFrame:
    """One frame to diagnose, as the student gets it: the symptom as reported and the two
    frames. What broke it is the check's to know, not a field to read."""

    number: int
    symptom: str
    frame: Frame  # the broken one, traced
    intended: Frame  # what the programmer meant to draw

    def __repr__(self) -> str:
        return f"BrokenFrame({self.number}: {self.symptom!r}, .frame, .intended)"


def _as_frame(number) -> BrokenFrame:
    """The frame a check reads: a :class:`BrokenFrame` itself (a redrawn one), a case's
    expected :class:`_Number` (the frame of its case), or a number (the frame shown)."""
    if isinstance(number, BrokenFrame):
        return number
    return getattr(number, "b", None) or broken_frame(int(number))


def _differs(number) -> np.ndarray:
    """(H, W) bool: the pixels the mistake of frame ``number`` changed (colour, RGB)."""
    b = _as_frame(number)
    return ~np.isclose(_rgb(b.frame), _rgb(b.intended), atol=1e-6).all(axis=2)


#: sha256 of "<salt>|<frame>|<cause>", 32 hex digits: the key, not readable as text (anyone
#: may hash the ten causes: the point needs the pixel's evidence as well, see the docstring).
_SALT = "teachraster/broken-frames/r9"
_KEY = {1: "e68f66d3ea75110820cace3e308b0d6e", 2: "c6b79012eaf45d23d1a4d99109306658",
        3: "04b91d018fc9aec9a7aa6f32f59360cb", 4: "e2b44365fd55dbf77960b5922c872641",
        5: "38234cdea627c46e16be35257101261e", 6: "2413d43fbc57dd32560223caa37f49b2",
        7: "efdc574170a935ebbec1162e53c18d43", 8: "2a0c8faa4906343dfbf80a84c2f39564",
        9: "a9edd7c9c7d7ccbdf0c6cb5930679202"}  # fmt: skip


def _is_cause(number: int, cause: str) -> bool:
    """Is ``cause`` what broke frame ``number`` (by its salted hash)?"""
    return _keyed(number, cause)


def _keyed(number: int, cause: str) -> bool:
    """:func:`_is_cause`'s test, for the checker's reading of an answer (``as_diagnosis``):
    ``_is_cause`` is watched as a reader a student's answer may not call, from anywhere; this,
    as every private function here, only when called from outside the package."""
    digest = hashlib.sha256(f"{_SALT}|{number}|{cause}".encode()).hexdigest()[:32]
    return digest == _KEY[number]


@dataclass(frozen=True)
class _Pixel:
    """What the check reads at one pixel of one frame: both histories and where they part."""

    frame: Frame
    mine: object  # the broken frame's PixelHistory
    meant: object  # the intended frame's
    stage: str | None  # the first stage where they differ (:data:`STAGES`), None: they agree


def _pixel(number, row: int, col: int) -> _Pixel:
    b = _as_frame(number)
    mine, meant = b.frame.history(row, col), b.intended.history(row, col)
    stage = next((s for s, x, y in zip(STAGES, _stages(b.frame, mine), _stages(b.intended, meant))
                  if x != y), None)  # fmt: skip
    return _Pixel(b.frame, mine, meant, stage)


def _ties(p: _Pixel) -> list:
    """The broken history's fragments that fail on a tie (their depth equals the stored one)."""
    return [r for r in p.mine.records
            if r.outcome in ("failed_depth", "hi_z") and r.depth == r.depth_before]  # fmt: skip


def _blended(frame: Frame, h) -> list:
    """(triangle's corners, fragment colour) of every fragment the colour buffer received."""
    return [(_key(frame, r.piece), tuple(np.round(r.color, 6).tolist()))
            for r in h.records if r.outcome == "passed"]  # fmt: skip


def _reordered(p: _Pixel, b: BrokenFrame) -> bool:
    """The same fragments blended, in another order."""
    mine = [k for k, _ in _blended(b.frame, p.mine)]
    meant = [k for k, _ in _blended(b.intended, p.meant)]
    return mine != meant and sorted(map(sorted, mine)) == sorted(map(sorted, meant))


def _recoloured(p: _Pixel, b: BrokenFrame) -> bool:
    """The same fragments blended in the same order, one with another colour."""
    mine, meant = _blended(b.frame, p.mine), _blended(b.intended, p.meant)
    return [k for k, _ in mine] == [k for k, _ in meant] and mine != meant


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


#: The mark each cause leaves where the two histories of a pixel part: a test on (the pixel,
#: its frames) and the words a wrong cause is told. Each frame's changed pixels bear the mark
#: of its own cause only (tests/test_broken_frames.py), so a cause is judged by its mark at
#: the student's pixel as well as by the key.
_SIGNS = {
    "affine interpolation": (lambda p, b: b.frame.trace.debug.inputs.interpolation == "affine",
                             "its frame interpolates without the divide by w"),
    "blend order": (lambda p, b: p.stage == "blending" and _reordered(p, b),
                    "they first part at blending, the same fragments blended in another order"),
    "culled winding": (lambda p, b: p.stage == "culling",
                       "they first part at culling, a triangle culled in one and drawn in the "
                       "other"),
    "depth function": (lambda p, b: p.stage == "depth test" and not _ties(p),
                       "they first part at the depth test, a fragment kept in one and rejected "
                       "in the other, with no tie"),
    # r18-7: "its depth test is off" only said the name again
    "depth test off": (lambda p, b: not p.mine.depth_test,
                       "the history's first line says depth test off, and a fragment passes "
                       "though the depth stored before it is nearer"),
    "missing premultiplication": (lambda p, b: p.stage == "blending" and _recoloured(p, b),
                                  "they first part at blending, the same fragments in the same "
                                  "order, one with another colour"),
    "near-plane clipping": (lambda p, b: any(r.edge == "near" for r in p.mine.records),
                            "a triangle there is cut by the near plane"),
    "sliver": (lambda p, b: p.stage == "coverage" and _thin_missed(b.frame, p.mine),
               "they first part at coverage, where the thinnest triangle crosses the pixel but "
               "misses its centre"),
    "texture filtering": (lambda p, b: False, "a texture is sampled there"),
    "z-fighting": (lambda p, b: p.stage == "depth test" and bool(_ties(p)),
                   "they first part at the depth test, where a fragment fails on a tie (its "
                   "depth equal to the stored one)"),
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


@dataclass(frozen=True)
class _Look:
    """What a frame's values are, apart from its mistake: the wall's colour and depth (in
    16-bit steps, so that a pane 1e-6 nearer ties with it), the strip's straight colour and
    depth, and the cube's depths (clip z -> a z + c w: the same pixels, other depths). The
    check redraws each frame with another look (r9 11-1: a value harvested from the frame
    shown, by a loop over the history's values, fails the redrawn one)."""

    wall: tuple = (0.62, 0.56, 0.48)
    wall_steps: float = 39321  # 0.6 exactly in unorm16 (off the grid: 11.3b, r388 G3)
    strip: tuple = (0.2, 0.45, 0.85)
    strip_depth: float = 0.3
    cube: tuple = (1.0, 0.0)
    order: int = 0  # the cube's triangles drawn from this one on (r11 11-D: other numbers)
    # frame 2's intended cube's, where it differs (r84 11-2: a triangle's number read off
    # the intended frame's history passed, both frames numbering alike; a redrawn pair numbers
    # them apart, so that "a number the list asks for is the one in the frame's own history").
    # Not frame 1's: drawn in another order, its two faces would both pass, parting at blending
    meant_order: int | None = None
    # r377 F1: the cube's triangles listed backwards, so that every two of them swap, the two
    # of a face as well as the faces: where a pixel's history culls two or more, the first
    # culled triangle is another one (rolled only, "the first culled" stayed right at 439 of
    # the 446 pixels where it was; a roll after the reversal would restore each pair it wraps,
    # so the redrawn looks reverse with no roll: ``order`` 0)
    backwards: bool = False


#: The look of the frames shown, and the looks a check redraws them with (one at random).
_SHOWN = _Look()
_REDRAWN = (
    _Look((0.44, 0.63, 0.52), 45875, (0.85, 0.3, 0.2), 0.35, (0.9, 0.05), 0, 9, True),
    _Look((0.7, 0.66, 0.6), 32768, (0.3, 0.2, 0.75), 0.25, (0.85, -0.04), 0, 10, True),
    _Look((0.5, 0.52, 0.7), 42598, (0.9, 0.7, 0.1), 0.4, (0.95, 0.03), 0, 2, True),
)


def _cube(look: _Look, winding_reversed: bool = False, meant: bool = False, **kwargs) -> Frame:
    """The cube drawn with ``look``; ``meant``: the intended frame, in the look's
    ``meant_order`` where it has one."""
    scene = get_scene("cube")
    clip = scene.clip(W / H)
    clip = clip * np.array([1.6, 1.6, 1, 1])  # zoomed in: a narrower field of view
    a, c = look.cube
    clip[..., 2] = a * clip[..., 2] + c * clip[..., 3]  # other depths, the same pixels
    if kwargs.pop("reverse_depth", False):
        clip = clip * np.array([1, 1, -1, 1])  # z/w negated: window depth 1 - d
    rgba = np.concatenate([scene.mesh.corner("color"), np.ones((len(clip), 3, 1))], axis=2)
    if winding_reversed:  # the mesh's corners listed the other way round (data, not a setting)
        clip, rgba = clip[:, ::-1], rgba[:, ::-1]
    # the same triangles in another order: the same picture (the depth test decides), other
    # triangle numbers, so that a number typed in fails the redrawn frame
    order = look.meant_order if meant and look.meant_order is not None else look.order
    if look.backwards:
        clip, rgba = clip[::-1], rgba[::-1]
    clip, rgba = np.roll(clip, -order, axis=0), np.roll(rgba, -order, axis=0)
    return render(clip, W, H, attrs=rgba, trace=True, clear_color=(1, 1, 1, 1), **kwargs)


#: Frames 3 to 6 share one wall and one set of render settings (premultiplied blending,
#: a 16-bit depth buffer, one sample): each mistake is in what is drawn, never in a setting
#: a student could read off the frame and compare with the intended one's.
_ALPHA = 0.5  # the dark pane's
_STRIP_ALPHA = 0.6  # the tinted strip's
_WEDGE = [
    [[8, 13.5], [56, 25.5], [56, 27.5]],  # the strip as meant: 2 px tall throughout
    [[8, 13.5], [56, 27.5], [8, 15.5]],
]
# Along y = 20.5 + (x - 32) / 4 every pixel centre lies 0.125 px or more above or below the
# line, so a strip at most 0.1 px thick above it covers none, though its box reaches many.
_NEEDLE = [[[8, 14.5], [56, 26.5], [56, 26.6]]]
# The same needle along the strip's top edge (y = 19.5 + (x - 32) / 4: centres 0.125 px or
# more off it too): frame 8 is frame 6's picture pixel for pixel, but its needle crosses other
# pixels (not (22, 40), frame 6's solution's; 12 of its 36 are among frame 6's 60: two needles
# inside a 2-px strip cannot avoid each other's pixels), so frame 6's diagnosis, copied, fails
# it (r18-3: a look-alike sharing a cause must be read, not copied).
_NEEDLE_TOP = [[[8, 13.5], [56, 25.5], [56, 25.6]]]


def _pixels(parts, reverse_depth: bool = False) -> Frame:
    """Render ``parts`` [(triangles in pixels, depth, premultiplied RGBA)] in order over the
    wall's settings; a part with alpha < 1 (glass) writes no depth (lesson 11 §7). With
    ``reverse_depth`` every depth d is drawn at 1 - d (the data mapped the other way round,
    not a setting: the test still keeps the smaller)."""
    xy = [t for tris, *_ in parts for t in tris]
    z = [[1 - d if reverse_depth else d] * 3 for tris, d, _ in parts for _ in tris]
    rgba = np.concatenate([np.repeat(np.asarray([c], float)[:, None], 3 * len(tris), 0)
                           .reshape(len(tris), 3, 4) for tris, _, c in parts])  # fmt: skip
    writes = np.concatenate([np.full(len(tris), c[3] == 1.0) for tris, _, c in parts])
    clip = window_triangles(np.asarray(xy, float) * (48 / W), z)
    return render(clip, W, H, attrs=rgba, blend="premultiplied", depth_format="unorm16",
                  depth_write=writes, trace=True, clear_color=(1, 1, 1, 1))  # fmt: skip


def _wall(look: _Look):
    return (_quad(4, 4, 60, 44), look.wall_steps / 65535, [*look.wall, 1.0])


#: The pane's corners (x0, y0, x1, y1), px: in the wall's upper right, off the cube's changed
#: pixels and the strip's (r18-3: frame 9, blend order on the pane, is frame 5's cause; at
#: pixels frame 5's pane was on, frame 5's diagnosis copied passed it, and frame 1's at (24, 28)
#: would pass any pane frame with its cause).
_PANE = (48, 6, 58, 20)


def _pane(look: _Look, nearer: float, premultiplied: bool = True):
    """A dark pane ``nearer`` than the wall, whose straight colour is the wall's darkened by
    its alpha: blended as premultiplied without being multiplied, it adds exactly what it
    should have hidden."""
    straight = _ALPHA * np.asarray(look.wall)
    colour = straight * _ALPHA if premultiplied else straight
    return (_quad(*_PANE), look.wall_steps / 65535 - nearer, [*colour, _ALPHA])


def _strip(look: _Look, triangles):
    return (triangles, look.strip_depth, [*(np.asarray(look.strip) * _STRIP_ALPHA), _STRIP_ALPHA])


#: Each frame's symptom as a user would report it: what is seen, never the mechanism, and how
#: to draw it with a look (broken, intended). The frames come in look-alike groups (1-2, 3-4-9,
#: 5-6-7-8): the same symptom, the same picture and the same intended picture, pixel for pixel;
#: only the histories tell them apart (3 to 6 even share the broken picture: a plain wall).
#: r16 11-2: while every pair held two different causes, a solved frame ruled its cause out
#: for its partner; now the strip's group holds a cause twice and two others once, the pane's
#: three causes (one of them the strip's), so a look-alike's cause tells neither that it is nor that it is not the frame's. r18-3: frames
#: sharing a cause bear its mark at different pixels (the strip's, not the cube's; another
#: needle), so that one frame's diagnosis, copied, fails the other.
_SPECS = [
    ("The cube does not look as intended.",
     lambda k: _cube(k, reverse_depth=True), lambda k: _cube(k)),
    ("The cube does not look as intended.",
     lambda k: _cube(k, winding_reversed=True, cull="back"),
     lambda k: _cube(k, meant=True, cull="back")),
    ("The dark pane on the wall is missing.",
     lambda k: _pixels([_wall(k), _pane(k, 1e-6)]), lambda k: _pixels([_wall(k), _pane(k, 1e-3)])),
    ("The dark pane on the wall is missing.",
     lambda k: _pixels([_wall(k), _pane(k, 0.2, premultiplied=False)]),
     lambda k: _pixels([_wall(k), _pane(k, 0.2)])),
    ("The tinted strip across the wall is missing.",
     lambda k: _pixels([_strip(k, _WEDGE), _wall(k)]),
     lambda k: _pixels([_wall(k), _strip(k, _WEDGE)])),
    ("The tinted strip across the wall is missing.",
     lambda k: _pixels([_wall(k), _strip(k, _NEEDLE)]),
     lambda k: _pixels([_wall(k), _strip(k, _WEDGE)])),
    # r18-3: frame 7 was frame 1's mistake at the same pixels (frame 1's function passed it);
    # now the same mistake hides the strip, at other pixels, a look-alike of frames 5 and 6
    ("The tinted strip across the wall is missing.",
     lambda k: _pixels([_wall(k), _strip(k, _WEDGE)], reverse_depth=True),
     lambda k: _pixels([_wall(k), _strip(k, _WEDGE)])),
    ("The tinted strip across the wall is missing.",
     lambda k: _pixels([_wall(k), _strip(k, _NEEDLE_TOP)]),
     lambda k: _pixels([_wall(k), _strip(k, _WEDGE)])),
    ("The dark pane on the wall is missing.",
     lambda k: _pixels([_pane(k, 0.2), _wall(k)]), lambda k: _pixels([_wall(k), _pane(k, 0.2)])),
]  # fmt: skip


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
    """The frames, numbered from 1 (rendered once), their plans withheld."""
    return tuple(_drawn(n, _SHOWN) for n in range(1, len(_SPECS) + 1))


def _drawn(number: int, look: _Look) -> BrokenFrame:
    """Frame ``number`` drawn with ``look``, its plans withheld."""
    symptom, broken, intended = _SPECS[number - 1]
    return BrokenFrame(number, symptom, _handed_out(broken(look)), _handed_out(intended(look)))


def _redrawn(number: int, look: _Look | None = None) -> BrokenFrame:
    """Frame ``number`` with the same mistake, drawn at check time with another look (one of
    :data:`_REDRAWN` at random, unless ``look`` is given): the student's function must read
    its evidence from the frame it is given."""
    return _drawn(number, look or _REDRAWN[secrets.randbelow(len(_REDRAWN))])


def frame_3_gap(gap: float, look: int | None = None, off: float = 0.0) -> BrokenFrame:
    """Frame 3 redrawn with look number ``look`` of :data:`_REDRAWN` (None: one at random),
    its pane drawn ``gap`` nearer than the wall (frame 3's: 1e-6), for 11.3b (r377 F4: the
    fewest depth bits in which the pane wins, which a typed-in number must not pass), the
    wall ``off`` 16-bit steps off the look's (r388 G3: on the grid, the pane's stored depth
    minus its drawn one was the gap). Frame 3's check keeps :func:`_redrawn`."""
    _, _, intended = _SPECS[2]
    look = _REDRAWN[secrets.randbelow(len(_REDRAWN)) if look is None else look]
    wall = replace(look, wall_steps=look.wall_steps + off)
    broken = _pixels([_wall(wall), _pane(wall, gap)])
    return BrokenFrame(3, _SPECS[2][0], _handed_out(broken), _handed_out(intended(look)))


def frames_to_inspect() -> dict[str, Frame]:
    """Every frame of the exercise for ``FrameInspector(frames=...)``: "frame n" and
    "intended n" side by side in the list, so that a pixel's two histories can be compared
    (r7: the inspector held the broken frames only)."""
    return {f"{what} {b.number}": f for b in broken_frames()
            for what, f in (("frame", b.frame), ("intended", b.intended))}  # fmt: skip


def frame_pairs() -> dict[str, str]:
    """Each broken frame's name in :func:`frames_to_inspect` and its intended frame's, for
    ``FrameInspector(pairs=...)``: the two histories of a pixel side by side (r14, 11-6).

    >>> frame_pairs()["frame 1"]
    'intended 1'
    """
    return {f"frame {b.number}": f"intended {b.number}" for b in broken_frames()}


def _bears_mark(number: int, row: int, col: int) -> bool:
    """Does pixel (row, col) of frame ``number`` bear the mark of the frame's own cause
    (:data:`_SIGNS`): where its two histories part as that mistake makes them part?"""
    cause = next(c for c in CAUSES if _keyed(number, c))
    return bool(_SIGNS[cause][0](_pixel(number, row, col), _as_frame(number)))


def frame_marks() -> dict:
    """For ``FrameInspector(marks=...)``: each name of :func:`frames_to_inspect`, a test
    ``bears(row, col)`` of the changed pixels a frame opens at, those that bear the mark of
    its mistake (review r298 W2: frame 6 opened at (23, 47), where its thin triangle does not
    pass, and a diagnosis there is refused). It names no cause; it says only where the two
    histories part as the frame's mistake makes them part, as the check asks.

    >>> marks = frame_marks()
    >>> marks["frame 1"](24, 28), marks["intended 1"](0, 0)
    (True, False)
    """
    return {f"{what} {b.number}": (lambda row, col, n=b.number: _bears_mark(n, row, col))
            for b in broken_frames() for what in ("frame", "intended")}  # fmt: skip


#: Frame 3's follow-up (11.3b, :mod:`.broken_frame_steps`), printed in frame 3's note.
_STEPS_QUESTION = (
    "the histories' first line names the depth format, unorm16\n"
    "(lesson 05b), and they print each depth as that buffer stores it: the pane's tied at the\n"
    "wall's. The depth a triangle k is drawn at is frame.trace.window[k, :, 2]: read it with all\n"
    "its digits (not the six the histories print). How many bits must a unorm depth buffer have,\n"
    "at least, for frame 3's pane, the same distance in front of the wall as frame 3 draws it,\n"
    "to win the depth test at whatever depth the two are drawn? broken_frame_3_steps(b) returns\n"
    "that number, worked out from the depths b's trace holds."
)

#: A note on each frame (how it was made, and how its mistake usually shows), told once its
#: check has passed: the words name the mistake (r16 N2: kept in the notebook's locked cell,
#: they stood in its source, readable before the frame was solved). r18-5: every frame after
#: the first (whose cell prints its depths) has one, so that no note singles a frame out as
#: the contrived one.
_NOTES = {
    2: "Frame 2 is not contrived: a mesh whose corners are listed the other way round (as some\n"
    "tools export it) shows its inside wherever back faces are culled.",
    3: "Frame 3 is contrived so that the pane is missing everywhere: it lies parallel to the\n"
    "wall, so every pixel ties. At an angle the tie would come and go, and the two surfaces\n"
    "would show through each other in stitches.\n"
    # r309 M3: the follow-up that needs lesson 05b, asked only here (asked before 11.3 passes,
    # it would tell frame 3's cause)
    f"11.3b asks: {_STEPS_QUESTION}",
    # r18-4: "so that the pair looks alike" (the pair is a frame and its intended frame)
    # r18-3: "so that it looks like frame 3" told, once 11.4 passed, that frame 3's cause is
    # another (and "like frame 6", frame 6's cause): a note names no other frame
    4: "Frame 4 is contrived so that the pane vanishes into the wall: its straight colour is\n"
    "exactly its alpha times the wall's. The same mistake usually shows as a pane too bright.",
    5: "Frame 5 is not contrived: glass drawn before what lies behind it is replaced wherever an\n"
    "opaque surface is drawn after it, since the glass writes no depth (were it written, the\n"
    "surface behind would fail the depth test and the glass would show over the clear colour\n"
    "instead); transparent geometry is drawn last, back to front.",
    # r377 F6b: "between the rows of pixel centres" of a triangle that runs across 13 rows
    6: lambda: (
        "Frame 6 is contrived so that the strip is missing everywhere: the thin "
        f"triangle {_threads(6)}. A sliver usually shows as a broken, dotted line, where it covers "
        "a centre now and then."
    ),
    7: "Frame 7 is not contrived: with the depths mapped the other way round, glass in front of\n"
    "a wall drawn first fails the test wherever the wall is behind it.",
    8: lambda: (
        "Frame 8 is contrived so that the strip is missing everywhere: the thin "
        f"triangle, along the strip's top edge, {_threads(8)}. A sliver usually shows as a "
        "broken, dotted line, where it covers a centre now and then."
    ),
    9: "Frame 9 is not contrived: glass drawn before the wall behind it is replaced where the\n"
    "wall is drawn (the glass writes no depth); the usual cure draws transparent geometry\n"
    "last, back to front.",
}


def _threads(number: int) -> str:
    """How the thin triangle of frame ``number`` (as shown) misses every pixel centre, in
    words with the numbers its corners give: the rows of pixels it runs across, and in each
    column it crosses, how near it comes to the centres above and below it and how tall it is
    there (r377 F6b: "between the rows of pixel centres" said of a triangle across 13 rows)."""
    frame = broken_frame(number).frame
    xy = frame.trace.window[int(np.argmin(_altitudes(frame))), :, :2]
    cols = np.arange(np.ceil(xy[:, 0].min() - 0.5), np.floor(xy[:, 0].max() - 0.5) + 1) + 0.5
    spans = []
    for x in cols:  # the triangle's vertical extent on the column's line of centres
        ys = [ya + (yb - ya) * (x - xa) / (xb - xa)
              for (xa, ya), (xb, yb) in zip(xy, np.roll(xy, -1, axis=0), strict=True)
              if xa != xb and min(xa, xb) <= x <= max(xa, xb)]  # fmt: skip
        spans.append((min(ys), max(ys)))
    lo, hi = np.array(spans).T
    clear = min((lo - np.floor(lo - 0.5) - 0.5).min(), (np.ceil(hi - 0.5) + 0.5 - hi).min())
    rows = int(np.floor(xy[:, 1].max()) - np.floor(xy[:, 1].min())) + 1
    return (f"runs across {rows} rows of pixels, yet in each of the {len(cols)} columns it "
            f"crosses it threads between two pixel centres, {clear:.3f} px or more from each "
            f"(it is at most {(hi - lo).max():.3f} px tall there)")  # fmt: skip


#: Frame 1's note, before its depths (r377 F6c: the depths alone, where every other note
#: says how the frame was made and how its mistake usually shows).
FRAME_1_NOTE = (
    "Frame 1 is not contrived: its depths are mapped the other way round, near at 1 and far\n"
    "at 0 (reverse-Z: a reversed projection, often with glClipControl(..., GL_ZERO_TO_ONE)),\n"
    "while the depth test still keeps the smaller (GL_LESS, where reverse-Z needs GL_GREATER),\n"
    "so wherever two surfaces overlap the farther one is kept: the back of every object shows\n"
    "through its front. Its two faces' depths at one pixel:"
)

#: Frame 1's note: a pixel where the two faces overlap, and the triangles of the face in
#: front and of the face behind (in the intended frame's order), whose depths it prints.
FRAME_1_DEPTHS = (24, 28), 9, 3


def _frame_1_depths() -> str:
    """The two faces' depths at one pixel, in frame 1 and its intended frame (r22 D4: they
    were printed by a locked cell whose source, shown before any answer, named the pixel and
    the face in front)."""
    (row, col), front, behind = FRAME_1_DEPTHS
    pair = broken_frame(1)
    lines = []
    for what, frame in (("frame 1", pair.frame), ("intended frame", pair.intended)):
        depth = {r.triangle: r.depth for r in frame.history(row, col).records
                 if r.depth is not None}  # fmt: skip
        lines.append(f"{what} at ({row}, {col}): in front (triangle {front}) "
                     f"{depth[front]:.6f}, behind ({behind}) {depth[behind]:.6f}")  # fmt: skip
    return "\n".join(lines)


def frame_note(number: int, report) -> str:
    """What the notebook tells after frame ``number``'s check: its note (frame 1's: the two
    faces' depths at one pixel in both frames), once ``report`` (a report
    :func:`~.checks.check` returned for that frame) has passed; until then, where it will be
    told.

    >>> print(frame_note(4, None))
    A note on frame 4 is printed here once the check of broken_frame_4 above passes.
    """
    number = as_int("number", number)
    if number != 1 and number not in _NOTES:
        raise ValueError(f"number must be one of {[1, *sorted(_NOTES)]}, got {number}")
    name = f"broken_frame_{number}"
    if getattr(report, "exercise", None) == name and issued(report) and report.passed:
        if number == 1:
            return f"{FRAME_1_NOTE}\n{_frame_1_depths()}"
        note = _NOTES[number]
        return textwrap.fill(note(), 90) if callable(note) else note
    # r16 11-2: never "to look like frame 3", which hints that frame 3's cause is another;
    # r18-5: nor "contrived", which singled frame 4 out as the one whose mistake looks unlike it
    return f"A note on frame {number} is printed here once the check of {name} above passes."


def broken_frame(number: int) -> BrokenFrame:
    """Frame ``number`` (1 to the number of frames, 9)."""
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


def _stages(frame: Frame, h) -> tuple:
    """What each stage of a pixel's history ``h`` did, comparable across two frames: each
    triangle by its corners on screen (:func:`_key`), never by its number."""
    keyed = [(_key(frame, r.piece), r) for r in h.records]
    # Sets of triangles, compared across the frames: "coverage" differs when a triangle covers
    # the centre in one frame and not in the other, whether it is not_covered there or not
    # drawn at all (frame 6: the sliver and the 2 px strip have other corners).
    culled = frozenset(k for k, r in keyed if r.outcome == "culled")
    covered = frozenset(k for k, r in keyed if r.outcome not in ("culled", "not_covered"))
    tested = frozenset((k, r.outcome == "passed") for k, r in keyed
                       if r.outcome in ("hi_z", "failed_depth", "passed"))  # fmt: skip
    return culled, covered, tested, tuple(_blended(frame, h))


def _parts_at(number: int, row: int, col: int) -> str | None:
    """The first stage (:data:`STAGES`) at which pixel (row, col)'s history in frame
    ``number`` differs from its history in the intended frame (None: they agree)."""
    return _pixel(number, row, col).stage


def _evidence(number, cause: str, p: _Pixel) -> list:
    """The values :data:`EVIDENCE` names for ``cause`` at pixel ``p`` of frame ``number`` (a
    number, or a redrawn :class:`BrokenFrame`), read from its histories (empty where the pixel
    lacks the cause's mark): any one of them is the evidence."""
    b = _as_frame(number)
    if not _SIGNS[cause][0](p, b):
        return []
    mine = p.mine.records
    if cause == "depth function":
        return [r.depth for r in mine if r.shown]
    if cause == "culled winding":  # culled here, drawn there: where the histories part
        drawn = {_key(b.intended, r.piece) for r in p.meant.records if r.outcome == "passed"}
        return [r.triangle for r in mine
                if r.outcome == "culled" and _key(b.frame, r.piece) in drawn]  # fmt: skip
    if cause == "z-fighting":
        tied = {_key(b.frame, r.piece) for r in _ties(p)}
        return [r.depth for r in p.meant.records
                if r.outcome == "passed" and _key(b.intended, r.piece) in tied]  # fmt: skip
    if cause == "missing premultiplication":
        meant, blended = dict(_blended(b.intended, p.meant)), _blended(b.frame, p.mine)
        passed = [r for r in mine if r.outcome == "passed"]  # in the order of ``blended``
        return [r.color for r, (k, c) in zip(passed, blended) if meant.get(k) != c]
    if cause == "blend order":
        return [r.color_after for r in mine
                if r.outcome == "passed" and r.color[3] < 1 and r.hidden_by >= 0]  # fmt: skip
    if cause == "sliver":  # both sides of where they part: missed here, drawn there
        k = int(np.argmin(_altitudes(b.frame)))
        drawn = {_key(b.frame, r.piece) for r in mine}
        return [(r.outside, q.depth) for r in mine if r.triangle == k and r.outcome == "not_covered"
                for q in p.meant.records
                if q.outcome == "passed" and _key(b.intended, q.piece) not in drawn]  # fmt: skip
    return []  # the causes that occur in no frame: no value is their evidence


#: How far a value may be from the history's: half a unit of the last digit it prints (six
#: decimals for depths, with float noise; four for colours and distances, and a little more).
#: r399 F1, F4: 2e-6 for depths passed a depth 1.5e-6 off, and took frame 3's pane, drawn 1e-6
#: in front of the wall, for the wall: half the sixth decimal is below the frames' smallest
#: gap (1e-6), so 0.599999 is never 0.600000.
_DEPTH_TOLERANCE = 5e-7 + 1e-12
_TOLERANCE = {"depth": _DEPTH_TOLERANCE, "number": 6e-5, "colour": 1e-4,
              "pair": (6e-5, _DEPTH_TOLERANCE), "triangle": 0}  # fmt: skip


def _matches(kind: str, value, evidence: list) -> bool:
    """Is ``value`` (a number, colour channels, or a pair) one of ``evidence`` (colours
    compared on the value's channels: the records' RGBA on their r, g, b)?"""
    tol = _TOLERANCE[kind]
    if kind in ("depth", "number", "triangle"):
        return any(abs(value - e) <= tol for e in evidence)
    n = len(value)
    return any(np.all(np.abs(np.subtract(value, e[:n])) <= tol) for e in evidence)


# -- the answer -------------------------------------------------------------------------------
def _words(value) -> str:
    return " ".join(value.lower().replace("_", " ").replace("-", " ").split())


_CAUSE_KEYS = {_words(c): c for c in CAUSES}
_SHAPE = ('(cause, (row, col), evidence), such as ("depth test off", (12, 30), 0.25), the '
          "evidence being what the causes' list names for that cause")  # fmt: skip


def _index(name: str, value, pixel) -> int:
    """``value`` as a row or column: an integer (``operator.index``), never a bool or a float
    (r7: 24.7 was read as 24, True as 1)."""
    if isinstance(value, bool | np.bool_):
        raise WrongAnswerType(f"returned the pixel {short(pixel)}: {name} is a bool, not an "
                              "integer")  # fmt: skip
    try:
        return operator.index(value)
    except TypeError:
        pass
    if _integral(value, exact=False):  # r11 11-H: 24.0 was told "is not an integer"
        raise WrongAnswerType(f"returned the pixel {short(pixel)}: {name} {short(value)} is a "
                              f"float, not an int: give int({name}) (a pixel is (row, col), "
                              "two ints)")  # fmt: skip
    raise WrongAnswerType(f"returned the pixel {short(pixel)}: {name} {short(value)} is not "
                          "an integer (a pixel is (row, col), two whole numbers)")  # fmt: skip


def _integral(value, exact: bool = True) -> bool:
    """Is ``value`` an int (``operator.index``), or (``exact=False``) a float with no
    fraction?"""
    try:
        operator.index(value)
        return True
    except TypeError:
        x = None if exact else _real(value)
    return x is not None and float(x).is_integer()


def _real(value) -> float | None:
    """``value`` as a finite float, or None (a bool, text, NaN or something else)."""
    if isinstance(value, bool | np.bool_ | str | bytes):
        return None
    try:
        x = float(value)
    except (TypeError, ValueError):
        return None
    return x if np.isfinite(x) else None


def _as_evidence(cause: str, value):
    """The evidence for ``cause``, read strictly: a number, a colour (r, g, b) or a pair."""
    kind, what = EVIDENCE[cause]
    if isinstance(value, str) and _words(value) in STAGES:  # r8's answer form: a stage
        raise WrongAnswerType(f"returned the stage {value!r} as the evidence: the evidence for "
                              f"{cause!r} is {what}, read off the pixel's history")  # fmt: skip
    if kind == "triangle":
        # r298 S4: 9.0 is triangle 9 (an integral float, as for a row or column)
        if isinstance(value, bool | np.bool_) or not _integral(value, exact=False):
            raise WrongAnswerType(f"returned the evidence {short(value)}: for {cause!r} it is "
                                  f"a triangle's number, an int: {what}")  # fmt: skip
        return int(value)
    if kind in ("depth", "number"):
        x = _real(value)
        if x is None:
            raise WrongAnswerType(f"returned the evidence {short(value)}: for {cause!r} it is "
                                  f"one number, {what}")  # fmt: skip
        return x
    try:
        channels = [_real(v) for v in value] if not isinstance(value, str) else [None]
    except TypeError:
        channels = [None]
    size, form = (
        (3, "a colour (r, g, b), three numbers") if kind == "colour" else (2, "two numbers")
    )
    if kind == "colour" and len(channels) == 4 and None not in channels:
        # r309 S2: RGBA passed where the list asks (r, g, b); the alpha is no part of it
        raise WrongAnswerType(f"returned the evidence {short(value)}: for {cause!r} it is "
                              "(r, g, b): three numbers; yours has 4 (alpha? give "
                              f"value[:3]): {what}")  # fmt: skip
    if len(channels) != size or None in channels:
        raise WrongAnswerType(f"returned the evidence {short(value)}: for {cause!r} it is "
                              f"{form}: {what}")  # fmt: skip
    return tuple(channels)


def as_diagnosis(value, number: int | None = None) -> tuple[str, tuple[int, int], object]:
    """(cause, (row, col), evidence) from the student's answer, read strictly; for frame
    ``number``, the evidence of a cause that is not the frame's is not read strictly: that
    the cause is wrong is told first (r16 N1: the look-alike's cause with this frame's
    evidence was told the evidence's type was wrong, sending the student after a mistake the
    frame does not have, and such answers escaped the wrong-cause brake)."""
    if isinstance(value, str) and _words(value) in _CAUSE_KEYS:
        # the cause without its evidence (r6: told to drop the quotes of a cause that is text)
        raise WrongAnswerType(f"returned only the cause {value!r}: return {_SHAPE}")
    refuse_non_answers(value, "a triple (cause, (row, col), evidence)")
    if isinstance(value, tuple | list) and len(value) == 2:
        raise WrongAnswerType(f"returned {short(value)} without the evidence: return {_SHAPE}")
    try:
        cause, pixel, evidence = value
        row, col = pixel
    except (TypeError, ValueError):
        raise WrongAnswerType(f"returned {short(value)}: return {_SHAPE}") from None
    if not isinstance(cause, str):
        raise WrongAnswerType(f"returned the cause {short(cause)}, not a text: one of "
                              f"{list(CAUSES)}")  # fmt: skip
    if _words(cause) not in _CAUSE_KEYS:
        raise WrongAnswerType(f"returned the cause {cause!r}, which is not one of the causes "
                              f"(spell it as listed): {', '.join(CAUSES)}")  # fmt: skip
    row, col = _index("row", row, pixel), _index("col", col, pixel)
    if not (0 <= row < H and 0 <= col < W):
        raise WrongAnswerType(f"returned pixel ({row}, {col}), outside the {H} × {W} frame "
                              f"(rows 0–{H - 1}, columns 0–{W - 1})")  # fmt: skip
    cause = _CAUSE_KEYS[_words(cause)]
    if number is not None and not _keyed(int(number), cause):
        return cause, (row, col), _loose(evidence)
    return cause, (row, col), _as_evidence(cause, evidence)


def _loose(value):
    """Evidence kept as given, hashable (the verdicts are cached): a number, numbers, or its
    text."""
    if isinstance(value, int | np.integer) and not isinstance(value, bool | np.bool_):
        return int(value)  # r377 F6e: a triangle's number, quoted as "3", never "3.0"
    x = _real(value)
    if x is not None:
        return x
    try:
        return tuple(_real(v) for v in value) if not isinstance(value, str | bytes) else value
    except TypeError:
        return short(value)


class _Number(int):
    """A frame's number as its case's expected answer, holding the frame the case hands the
    student's function (``b``: the frame shown, or one redrawn for this check), and the answer
    the check accepted (``right``): the passing figure marks its pixel (r8 11-9)."""

    b = None
    right = None
    nested = False  # the case of a check run inside the student's own function
    shown = None  # the redrawn case's: the frame shown's case (its words are not repeated)
    told = None  # the frame shown's case: the (cause, row, col) told it is not the cause

    @classmethod
    def of(cls, b: BrokenFrame, nested: bool = False) -> _Number:
        number = cls(b.number)
        number.b, number.nested = b, nested
        return number


#: The threads running a student's diagnosis right now: a check started from inside one is a
#: search through the checker (r9: the verdict is an oracle), so its cases never pass.
_STUDENT_THREADS: set = set()


@transparent  # its finally only unmarks the thread: the interrupt must pass through it
def _call(fn, args):
    """Run the student's function on a case (marking its thread) and read its answer."""
    me = threading.get_ident()
    inside = me in _STUDENT_THREADS
    _STUDENT_THREADS.add(me)
    try:
        value = fn(*args)
    finally:
        if not inside:
            _STUDENT_THREADS.discard(me)
    return as_diagnosis(value, getattr(args[0], "number", None) if args else None)


def _cases(number: int):
    """Two cases: the frame shown, and the same mistake redrawn with another look, built for
    this check (r9 11-1: 137 calls harvesting one pixel's history passed all six)."""

    def cases():
        nested = threading.get_ident() in _STUDENT_THREADS
        shown, redrawn = broken_frame(number), _redrawn(number)
        first, second = _Number.of(shown, nested), _Number.of(redrawn, nested)
        second.shown = first  # r21 D8: a wrong cause told twice in full read as two mistakes
        return [("the frame shown", (shown,), first),
                ("the frame redrawn", (redrawn,), second)]  # fmt: skip

    return cases


def _right_at(b: BrokenFrame, cause: str, row: int, col: int, value) -> bool:
    """Is (cause, (row, col), value) right for ``b``: the frame's cause, a changed pixel whose
    histories bear its mark, and its evidence there?"""
    if not (0 <= row < H and 0 <= col < W and _differs(b)[row, col]):
        return False
    p = _pixel(b, row, col)
    return (_is_cause(b.number, cause) and _SIGNS[cause][0](p, b)
            and _matches(EVIDENCE[cause][0], value, _evidence(b, cause, p)))  # fmt: skip


def _judged(number, got) -> tuple[str, _Pixel | None]:
    """The verdict on one answer for the case's frame: "nested" (a check inside the student's
    function), "right", "pixel" (the frames agree there), "unmarked" (the frame's cause, at a
    changed pixel that does not show it), "cause", "intended" (the evidence triangle's number
    in the intended frame's history, not this frame's), "copied" (the frame shown's value,
    given for the redrawn one), "surface" (another surface's depth, :func:`_other_surface`),
    "other" (the evidence's value read off the other frame of the
    pair, :func:`_mirrored`), "drawn" (a fragment's depth as drawn, :func:`_drawn_source`)
    or "evidence"."""
    if getattr(number, "nested", False):
        return "nested", None
    return _judged_on(_as_frame(number), got)


# The figure and the words of one check read its verdicts again; a redrawn frame is 0.7 MB,
# so only the last few checks' are kept.
@lru_cache(maxsize=32)
def _judged_on(b: BrokenFrame, got) -> tuple[str, _Pixel | None]:
    """:func:`_judged` on frame ``b`` (the frame shown, or one redrawn for a check)."""
    cause, (row, col), value = got
    if not _differs(b)[row, col]:
        return "pixel", None
    p = _pixel(b, row, col)
    if not _SIGNS[cause][0](p, b):
        return ("unmarked" if _is_cause(b.number, cause) else "cause"), p
    if not _is_cause(b.number, cause):
        return "cause", p
    kind = EVIDENCE[cause][0]
    if _matches(kind, value, _evidence(b, cause, p)):
        return "right", p
    if kind == "triangle" and value in _meant_numbers(b, cause, p):
        return "intended", p
    if b is not broken_frame(b.number) and _right_at(
        broken_frame(b.number), cause, row, col, value
    ):
        return "copied", p
    # r318: the wall's depth for frame 3's pane is the wrong surface in the same history
    # (0.6 is also the depth the broken frame stores): said before "the other frame's"
    if _other_surface(cause, p, value):
        return "surface", p
    # r377 F2, F5: a value found in the history the list names is another record's (or
    # another field's) there, whichever frame also holds it; "the other frame's" only where
    # the named history lacks it. After "copied": a value typed in from the frame shown may
    # be, by chance, the redrawn pair's other frame's (frame 7's 0.4, a redrawn strip's depth)
    found = _source(b, cause, p, value)
    if found is not None and found[1].named:
        return "record", p
    if found is not None or _matches(kind, value, _mirrored(b, cause, p)[1]):
        return "other", p
    # r399 F1, F2: a depth no history prints, but a fragment's as its frame draws it (the
    # trace, unrounded; the histories print what the buffer stores)
    if _drawn_source(b, cause, p, value) is not None:
        return "drawn", p
    return "evidence", p


def _other_surface(cause: str, p: _Pixel, value):
    """For z-fighting, the record of another surface in the intended frame's history (the one
    the evidence is read from) whose depth ``value`` is (r318: the wall's, the stored depth the
    pane ties with, was told "the value in the other frame"); None otherwise."""
    if cause != "z-fighting":
        return None
    # a tie stores the wall's depth: the broken frame's tied value is the wall's too, and the
    # surface is named first (the evidence itself is judged "right" before this is asked)
    return next((r for r in p.meant.records
                 if r.depth is not None and _matches("depth", value, [r.depth])), None)  # fmt: skip


def _drawn_depth(frame: Frame, record, row: int, col: int) -> float:
    """The depth ``record``'s fragment is drawn at (pixel (row, col)'s centre on the plane of
    its triangle's window depths in the trace, unrounded): the history prints the depth the
    buffer stores (a 16-bit buffer: rounded to its steps)."""
    xyz = frame.trace.window[record.piece, :, :3]
    if np.ptp(xyz[:, 2]) == 0:  # a flat triangle (the wall, a pane, a strip)
        return float(xyz[0, 2])
    try:
        plane = np.linalg.solve(np.column_stack([xyz[:, :2], np.ones(3)]), xyz[:, 2])
    except np.linalg.LinAlgError:
        return float("nan")
    return float(plane @ [col + 0.5, row + 0.5, 1.0])


def _drawn_source(b: BrokenFrame, cause: str, p: _Pixel, value):
    """(the wrong part's words, :class:`_Source`) for a depth that is not the evidence but a
    fragment's depth at the pixel as its frame draws it (:func:`_drawn_depth`), the history
    the list names searched first; None otherwise (and for the sliver's pair with a wrong
    distance: that is said first)."""
    for part, kind, x, meant in _evidence_parts(cause, value):
        if kind != "depth":
            continue
        if cause == "sliver" and not _matches("number", value[0], _part_evidence(
                b, cause, p, "distance")):  # fmt: skip
            return None
        for named, intended in ((True, meant), (False, not meant)):
            frame, h = (b.intended, p.meant) if intended else (b.frame, p.mine)
            r = next((r for r in h.records if r.depth is not None and np.isfinite(r.depth)
                      and _matches(kind, x, [_drawn_depth(frame, r, h.row, h.col)])), None)  # fmt: skip
            if r is not None:
                whose = "the intended frame's" if intended else "the broken frame's"
                return part, _Source(named, whose, r, ("depth as drawn",))
    return None


def _meant_numbers(b: BrokenFrame, cause: str, p: _Pixel) -> set:
    """The numbers the intended frame's history gives the triangles whose numbers in the
    broken frame's history are the evidence (the same corners on screen): the evidence read
    off the other history (r84 11-2)."""
    evidence = set(_evidence(b, cause, p))
    keys = {_key(b.frame, r.piece) for r in p.mine.records if r.triangle in evidence}
    return {r.triangle for r in p.meant.records if _key(b.intended, r.piece) in keys}


def _mirrored(b: BrokenFrame, cause: str, p: _Pixel) -> tuple[str, list]:
    """The evidence's counterpart in the other frame of the pair: which history that is, and
    its values there (r309: a value read off the wrong frame of the pair, the commonest slip,
    was told only "your value is not ..."). The same triangles (by corners) as the evidence's,
    and for a depth the fragment the other frame shows; for the sliver, a depth of the broken
    frame's own fragments in place of the one the intended frame draws instead."""
    mine, meant = p.mine.records, p.meant.records
    if cause == "z-fighting":  # the evidence is the intended frame's: its counterpart, ours
        return "the broken frame's", [r.depth for r in _ties(p)]
    if cause == "sliver":
        found = {value for value, _ in _evidence(b, cause, p)}
        return "the broken frame's", [(d, r.depth) for d in found for r in mine
                                      if r.outcome == "passed"]  # fmt: skip
    keys = {_key(b.frame, r.piece) for r in mine if _read_from(b, cause, p, r)}
    same = [r for r in meant if _key(b.intended, r.piece) in keys]
    if cause == "depth function":
        shown = [r for r in meant if r.shown]
        return "the intended frame's", [r.depth for r in (*same, *shown) if r.depth is not None]
    if cause == "missing premultiplication":
        return "the intended frame's", [r.color for r in same if r.color]
    if cause == "blend order":
        return "the intended frame's", [r.color_after for r in same if r.color_after]
    return "the intended frame's", []


def _read_from(b: BrokenFrame, cause: str, p: _Pixel, record) -> bool:
    """Is ``record`` of the broken frame's history one the evidence of ``cause`` is read
    from (:func:`_evidence`)?"""
    if cause == "depth function":
        return bool(record.shown)
    if cause == "missing premultiplication":
        return record.outcome == "passed" and record.color in _evidence(b, cause, p)
    if cause == "blend order":
        return record.outcome == "passed" and record.color_after in _evidence(b, cause, p)
    return False


#: The fields of a history record a value of each kind may have been read from, and their
#: names in words (r377 F5: a value read off the wrong record was told only what it is not).
_FIELDS = {
    "depth": (("depth", "depth"), ("depth_before", "depth stored before it")),
    "number": (("outside", "distance outside {edge}"),),
    "colour": (("color", "fragment colour"), ("color_after", "'after'"),
               ("color_before", "'before'")),
}  # fmt: skip


@dataclass(frozen=True)
class _Source:
    """Where a wrong value was read: in which frame's history (``named``: the one the list
    reads that value from), off which record, and which of its fields (their words)."""

    named: bool
    whose: str
    record: object
    fields: tuple

    def label(self) -> str:
        """The record and field, as "triangle 0's depth"."""
        fields = " and ".join(f.format(edge=self.record.edge) for f in self.fields)
        return f"triangle {self.record.triangle}'s {fields}"

    def state(self) -> str:
        """What the record's history says of it."""
        r = self.record
        if r.outcome == "passed":
            return ("the fragment the pixel shows" if r.shown else
                    f"its fragment passed, then covered by triangle {r.hidden_by}")  # fmt: skip
        return {"failed_depth": "its fragment failed the depth test",
                "hi_z": "its fragment failed the Hi-Z test",
                "not_covered": "it does not cover the centre"}.get(r.outcome, r.outcome)  # fmt: skip


def _fields_of(kind: str, record, value) -> tuple:
    """The words of ``record``'s fields (:data:`_FIELDS`) that hold ``value``."""
    found = []
    for field, words in _FIELDS[kind]:
        x = getattr(record, field, None)
        if kind == "colour":
            held = bool(x) and _matches(kind, value, [x])
        else:
            held = x is not None and bool(np.isfinite(x)) and _matches(kind, value, [x])
        if held:
            found.append(words)
    return tuple(found)


def _evidence_parts(cause: str, value) -> list:
    """(words, kind, value, read off the intended frame's history?) for each part of an
    answer's evidence: the sliver's two numbers, or the one value."""
    if cause == "sliver":
        return [("distance", "number", value[0], False), ("depth", "depth", value[1], True)]
    return [("value", EVIDENCE[cause][0], value, cause == "z-fighting")]


def _source(b: BrokenFrame, cause: str, p: _Pixel, value):
    """(the wrong part's words, :class:`_Source`) for a value that is not the evidence but a
    field of a record in the pixel's two histories: the history the list names searched
    first, field by field (:data:`_FIELDS`' order), the records that hold the evidence first;
    None where it is in neither (or for a triangle's number)."""
    if EVIDENCE[cause][0] == "triangle":
        return None
    evidence = _evidence(b, cause, p)
    for i, (part, kind, x, meant) in enumerate(_evidence_parts(cause, value)):
        right = [e[i] for e in evidence] if cause == "sliver" else evidence
        if cause == "sliver" and _matches(kind, x, right):
            continue  # this part is right: the other one is wrong
        for named, intended in ((True, meant), (False, not meant)):
            h = p.meant if intended else p.mine
            records = sorted(h.records, key=lambda r: not _holds(kind, r, right))
            for field, _ in _FIELDS[kind]:
                r = next((r for r in records if field in _field_names(kind, r, x)), None)
                if r is not None:
                    whose = "the intended frame's" if intended else "the broken frame's"
                    return part, _Source(named, whose, r, _fields_of(kind, r, x))
        return None
    return None


def _field_names(kind: str, record, value) -> tuple:
    """The names of ``record``'s fields that hold ``value``."""
    words = dict(_FIELDS[kind])
    return tuple(f for f, w in words.items() if w in _fields_of(kind, record, value))


def _holds(kind: str, record, values) -> bool:
    """Does one of ``record``'s fields hold one of ``values``?"""
    return any(_fields_of(kind, record, v) for v in values)


def _part_evidence(b: BrokenFrame, cause: str, p: _Pixel, part: str) -> list:
    """The evidence's values for one part (words of :func:`_evidence_parts`)."""
    evidence = _evidence(b, cause, p)
    return [e[part == "depth"] for e in evidence] if cause == "sliver" else evidence


def _holder(b: BrokenFrame, cause: str, p: _Pixel, part: str):
    """The record of the named history that holds the evidence's ``part`` (words of
    :func:`_evidence_parts`), or None."""
    _, kind, _, meant = next(q for q in _evidence_parts(cause, (0.0, 0.0)) if q[0] == part)
    values = _part_evidence(b, cause, p, part)
    h = p.meant if meant else p.mine
    return next((r for r in h.records if _holds(kind, r, values)), None)


def _same(got, number, args=None) -> bool:
    right = _judged(number, got)[0] == "right"
    if right and isinstance(number, _Number) and number.b is broken_frame(int(number)):
        number.right = got
    return right


def _shown(cause: str, value) -> str:
    """The evidence as the explanation quotes it: a triangle by its number, a depth or a
    distance to the digits the history prints, a colour or a pair channel by channel (r12
    11-1: an int made the explanation fail, and the fallback said "expected 2", the frame's
    number read as the answer's triangle)."""
    if EVIDENCE[cause][0] == "triangle" and isinstance(value, int):
        return f"triangle {value}"
    if isinstance(value, float):
        return _six(value)
    if isinstance(value, tuple) and all(isinstance(v, float) for v in value):
        return f"({', '.join(map(_six, value))}{',' if len(value) == 1 else ''})"
    # the evidence of a cause that is not the frame's, as given, its numbers to the digits
    # the history prints (r21 D8: "(None, 0.29999237048905164)")
    return short(_rounded(value))


def _six(value: float) -> str:
    """A float to the six decimals the history prints, a whole one without ".0" (r388 G9:
    triangle 3, given under a depth cause, was quoted "3.0")."""
    whole = np.isfinite(value) and float(value).is_integer()
    return f"{int(value)}" if whole else f"{round(value, 6)}"


def _rounded(value):
    """``value`` with every float in it (in tuples and lists too) rounded to 6 decimals."""
    if isinstance(value, float | np.floating) and np.isfinite(value):
        return round(float(value), 6)
    if isinstance(value, tuple | list):
        return type(value)(_rounded(v) for v in value)
    return value


def _explain(args, number, got) -> str:
    cause, (row, col), value = got
    what = "frame" if _as_frame(number) is broken_frame(int(number)) else "redrawn frame"
    return f"{what} {int(number)}: {cause!r} at pixel ({row}, {col}) with {_shown(cause, value)}"


def _in_history(b: BrokenFrame, cause: str, row: int, col: int, value) -> bool:
    """Is ``value`` a value of its kind in pixel (row, col)'s two histories (a record's
    triangle, depth, distance or colour)? Then it was read at this pixel, not at another."""
    kind = EVIDENCE[cause][0]
    records = [*b.frame.history(row, col).records, *b.intended.history(row, col).records]
    if kind == "triangle":
        return any(r.triangle == value for r in records)
    if kind in ("depth", "number"):
        found = [v for r in records for v in (r.depth, r.outside) if v is not None]
        return _matches(kind, value, [v for v in found if np.isfinite(v)])
    if kind == "colour":
        return _matches(kind, value, [c for r in records for c in (r.color, r.color_after) if c])
    return False


def _swapped(number, got) -> str:
    """Words for an answer that is right with its row and column, or its pair, swapped ("":
    neither), a sentence of its own. A
    swap is claimed only where the value is not in the given pixel's own histories (r12 11-1:
    triangle 8, culled at (24, 28), is also the evidence at (28, 24); the student read the
    right pixel, the wrong record)."""
    b, (cause, (row, col), value) = _as_frame(number), got
    if _right_at(b, cause, col, row, value) and not _in_history(b, cause, row, col, value):
        return (f"Your value is the evidence at ({col}, {row}): a pixel is (row, col), the "
                "row first, then the column")  # fmt: skip
    if EVIDENCE[cause][0] == "pair" and _right_at(b, cause, row, col, tuple(value)[::-1]):
        return ("Your two numbers are in the other order: (the distance outside the thin "
                "triangle, the intended frame's depth)")  # fmt: skip
    return ""


def _history_hint(number, row, col, what: str) -> str:
    n = int(number)
    shown = (f"print(broken[{n}].frame.history({row}, {col}))"
             + (f" and print(broken[{n}].intended.history({row}, {col}))"
                if "intended" in what else ""))  # fmt: skip
    if _as_frame(number) is broken_frame(n):
        return shown
    # r12 11-5: the redrawn frame's values differ from the frame shown's
    inside = f"b.frame.history({row}, {col})" + (
        f" and b.intended.history({row}, {col})" if "intended" in what else "")  # fmt: skip
    verb = "tell" if "intended" in what else "tells"  # one print or two
    return (f"{inside} inside your function (this is the frame redrawn for the check, with "
            f"other values; in your notebook, {shown} {verb} of the frame shown)")  # fmt: skip


def _cause_words(args, number, got) -> str:
    """A cause that is not the frame's. The words are the same whether or not the pixel's
    histories bear the stated cause's mark (r13 11-2: "do / do not bear the mark of" told a
    loop over the ten causes which to keep): the stated cause does not explain them, what it
    would show, and where to look; never which other cause it is or is not."""
    cause, (row, col), _ = got
    if number.shown is not None and number.shown.told == (cause, row, col):
        return (f"{cause!r} at ({row}, {col}) again, and it is not this frame's cause either "
                "(the check runs your function on the frame shown and on one redrawn: the "
                "words above hold for both)")  # fmt: skip
    if number.shown is None:
        number.told = (cause, row, col)
    # r14: the instruction first, the stated cause's own mark last (the eye needs the first)
    words = (f"{cause!r} is not what the two histories of ({row}, {col}) show: find the first "
             "stage where they part, the cause is what acts there. Read "
             f"{_history_hint(number, row, col, 'the intended')} side by side, stage by stage "
             f"({', '.join(STAGES)}, then the colour shown). {cause!r} would show as: "
             f"{_SIGNS[cause][1]}")  # fmt: skip
    # r18-2: never whether the value is another cause's evidence (each evidence belongs to one
    # cause, so "read right: the evidence of another cause" named the cause after one guess);
    # the same words for every value
    return words + ". Your value is not judged while the cause is not the frame's"


def _unmarked_words(args, number, got) -> str:
    """The frame's cause at a changed pixel whose histories do not show it (r9 11.6: told "the
    cause is another", though it was right)."""
    cause, (row, col), _ = got
    if cause == "sliver":
        b = _as_frame(number)
        k = int(np.argmin(_altitudes(b.frame)))
        far = [r for r in b.frame.history(row, col).records if r.triangle == k]
        by = ""
        if far and far[0].outside:
            # r18-8: 0.6063 px read as inside a square that reaches 0.707 px along a diagonal;
            # towards an edge at an angle it reaches 0.5 (|cos| + |sin|) of its normal
            reach, edge = _reach(b.frame, far[0]), far[0].edge
            upto = ("touches it at a corner, no more" if abs(reach - far[0].outside) < 5e-5
                    else f"reaches only {reach:.4f} px from its centre towards {edge}")  # fmt: skip
            by = (f" (its centre lies {far[0].outside:.4f} px outside {edge}, and the square "
                  f"{upto})")  # fmt: skip
        return (f"the pictures differ at ({row}, {col}), but the thin triangle does not pass "
                f"through this pixel's square{by}, so the pixel cannot show a sliver: pick a "
                "pixel the thin triangle crosses without covering its centre")  # fmt: skip
    return (
        f"the pictures differ at ({row}, {col}), but its two histories do not show the "
        f"mark of {cause!r} ({_SIGNS[cause][1]}): pick a pixel whose histories do"
    )


def _reach(frame: Frame, record) -> float:
    """How far (px) a pixel's square reaches from its centre towards the edge ``record``
    names (E12, E23, E31 or the other way round): 0.5 (|cos| + |sin|) of the edge's normal's
    angle, 0.5 px towards a level edge, 0.707 px towards one at 45 degrees."""
    a, b = (int(d) - 1 for d in record.edge[1:3])
    dx, dy = frame.trace.window[record.piece, b, :2] - frame.trace.window[record.piece, a, :2]
    return float(0.5 * (abs(dx) + abs(dy)) / np.hypot(dx, dy))


def _evidence_words(args, number, got) -> str:
    cause, (row, col), _ = got
    kind, what = EVIDENCE[cause]
    digits = {
        "depth": "all six decimals it prints",
        "pair": "every digit it prints (the distance's four decimals, the depth's six)",
        "triangle": "its number in this frame (the same triangle in the intended frame has "
        "the same corners on screen, frame.trace.window[k, :, :2], whatever its number)",
    }.get(kind, "the four decimals it prints")
    swap = _swapped(number, got)  # r309 S1: the specific hint first, where the eye starts
    return ((f"{swap[0].lower()}{swap[1:]}. The" if swap else "the")
            + f" two histories of ({row}, {col}) do bear the mark of {cause!r} "
            f"({_SIGNS[cause][1]}), but your value is not {what}, at that pixel"
            + (_triangle_words(number, got) if kind == "triangle" else "")
            + f". Read it off {_history_hint(number, row, col, what)}, with {digits}")  # fmt: skip


def _triangle_words(number, got) -> str:
    """What the triangle given is at the pixel, in both histories (r12 11-1: the first culled
    triangle, 8, is culled here but not drawn in the intended frame)."""
    b, (_, (row, col), value) = _as_frame(number), got
    mine = [r for r in b.frame.history(row, col).records if r.triangle == value]
    if not mine:
        return f": triangle {value} does not reach this pixel in this frame's history"
    keys = {_key(b.frame, r.piece) for r in mine}
    there = [r.outcome for r in b.intended.history(row, col).records
             if _key(b.intended, r.piece) in keys]  # fmt: skip
    drawn = (
        f"the intended frame's history shows it {there[0]} here, not passed"
        if there
        else "the intended frame's history has no triangle with its corners here"
    )
    return f": triangle {value} is {mine[0].outcome} here, but {drawn}"


#: What each part of the evidence is, in the words of a wrong value's message (the sliver's
#: pair: EVIDENCE's words, one part at a time).
_PART_WORDS = {
    "distance": "how far (px) the pixel's centre lies outside the thin triangle, in the broken "
    "frame's history",
    "depth": "the depth of the fragment the intended frame draws there instead (where the "
    "broken frame draws none), in the intended frame's history",
}


def _yours(cause: str, part: str, value) -> str:
    """The wrong part of an answer's evidence, as a message quotes it."""
    if part == "value":
        return f"your value {_shown(cause, value)}"
    x = tuple(value)[0 if part == "distance" else 1]
    return f"your {part}, {round(x, 4 if part == 'distance' else 6)},"


def _sourced_words(number, got) -> tuple[str, _Source, str, str]:
    """(the wrong part quoted, where it was read, what the list asks, the evidence's record
    where it holds the value too) for a value found in
    the pixel's histories (:func:`_source`), the evidence's own record and field named
    (r377 F5: "0.46 is triangle 3's distance in the intended frame's history; the list asks
    for the thin triangle's, in this frame"), and the evidence's record where it holds the
    value too (frame 4's pane's 'after' is the wall's colour)."""
    cause, (row, col), value = got
    b = _as_frame(number)
    p = _pixel(b, row, col)
    part, src = _source(b, cause, p, value)
    what = EVIDENCE[cause][1] if part == "value" else _PART_WORDS[part]
    holder, also = _holder(b, cause, p, part), None
    if holder is not None:
        kind, x = next((k, v) for w, k, v, _ in _evidence_parts(cause, value) if w == part)
        if holder is not src.record and _fields_of(kind, holder, x):
            also = _Source(src.named, src.whose, holder, _fields_of(kind, holder, x))
        held = next(
            f for e in _part_evidence(b, cause, p, part) if (f := _fields_of(kind, holder, e))
        )
        what += f": here, triangle {holder.triangle}'s {held[0].format(edge=holder.edge)}"
    return _yours(cause, part, value), src, what, (f", as is {also.label()}" if also else "")


def _record_words(args, number, got) -> str:
    """A value read off the history the list names, but off another record or field
    (r377 F2: frame 8's wall depth, read off the intended frame as asked, was told "the value
    in the other frame"; F5: the value was told only what it is not)."""
    cause, (row, col), _ = got
    yours, src, what, also = _sourced_words(number, got)
    swap = _swapped(number, got)
    hint = _history_hint(number, row, col, "the intended" if "intended" in what else what)
    return ((f"{swap[0].lower()}{swap[1:]}. " if swap else "")
            + f"{yours} is {src.label()} in {src.whose} history of ({row}, {col}) "
            f"({src.state()}){also}, not the evidence: the list asks for {what}. Read it off "
            f"{hint}")  # fmt: skip


def _other_frame_words(args, number, got) -> str:
    """The evidence's value read off the other frame of the pair (:func:`_mirrored`), absent
    from the history the list names: said first, with the record it was read off (r377 F5),
    then where to read it (r309: five such answers were told only what was asked)."""
    cause, (row, col), value = got
    b = _as_frame(number)
    p = _pixel(b, row, col)
    if _source(b, cause, p, value) is not None:
        yours, src, what, _ = _sourced_words(number, got)
        own = "the intended frame's" if src.whose == "the broken frame's" else "the broken frame's"
        where = "" if "history" in what else f", in {own} history"
        return (f"{yours} is the value in the other frame of the pair ({src.whose} history of "
                f"({row}, {col}): {src.label()}, {src.state()}): the list asks for {what}"
                f"{where}. Read it off {_history_hint(number, row, col, 'the intended')}")  # fmt: skip
    whose = _mirrored(b, cause, p)[0]
    own = "the intended frame's" if whose == "the broken frame's" else "the broken frame's"
    what = EVIDENCE[cause][1]
    if cause == "sliver":
        part = f"your depth, {round(tuple(value)[1], 6)}, is"
        what = "the depth of the fragment the intended frame draws there instead"
    else:
        part = f"your value {_shown(cause, value)} is"
    where = "" if "history" in what else f", in {own} history"
    hint = _history_hint(number, row, col, "the intended" if "intended" in own else what)
    return (
        f"{part} the value in the other frame of the pair ({whose} history of ({row}, "
        f"{col})): the list asks for {what}{where}. Read it off {hint}"
    )


def _surface_words(args, number, got) -> str:
    """The depth of another surface in the intended frame's history (:func:`_other_surface`)."""
    cause, (row, col), value = got
    b = _as_frame(number)
    p = _pixel(b, row, col)
    r = _other_surface(cause, p, value)
    # the tied fragment's depth in the broken frame is the same number (r309's slip)
    also = _matches("depth", value, _mirrored(b, cause, p)[1])
    return (
        f"your value {_shown(cause, value)} is the depth of another surface: triangle "
        f"{r.triangle}'s in the intended frame's history of ({row}, {col}), the depth the "
        "buffer holds there"
        + (", and the tied fragment's in the broken frame's history" if also else "")
        + f": the list asks for {EVIDENCE[cause][1]}"
    )


def _drawn_words(args, number, got) -> str:
    """A depth read off the trace (as a frame draws it) where the list asks for a depth as
    the history prints it, stored (r399 F1: frame 3's pane as the broken frame draws it,
    0.599999, was told "the depth of another surface", the wall's 0.600000; F2: the intended
    pane as drawn, 0.599, was told only what it is not). Said: whose fragment, in which
    frame, and whether it is the evidence's own surface."""
    cause, (row, col), value = got
    b = _as_frame(number)
    p = _pixel(b, row, col)
    part, src = _drawn_source(b, cause, p, value)
    what = EVIDENCE[cause][1] if part == "value" else _PART_WORDS[part]
    meant = next(m for w, _, _, m in _evidence_parts(cause, value) if w == part)
    holder = _holder(b, cause, p, part)
    frame = b.intended if src.whose == "the intended frame's" else b.frame
    same = ""
    if holder is not None and _key(frame, src.record.piece) == _key(
        b.intended if meant else b.frame, holder.piece
    ):
        same = ("; the evidence's own fragment" if src.named else
                "; the evidence's surface, but in the other frame of the pair")  # fmt: skip
    bits = {"unorm16": "the 16-bit buffer", "unorm24": "the 24-bit buffer"}.get(
        p.mine.depth_format, "the depth buffer"
    )
    r, whose = src.record, src.whose.removesuffix("'s")
    return (f"{_yours(cause, part, value)} is triangle {r.triangle}'s depth as {whose} draws "
            f"it ({src.state()}{same}): "
            f"its trace's depth, frame.trace.window[{r.piece}, :, 2], unrounded, where the "
            f"histories print each depth as {bits} stores it (rounded to its steps): the list "
            f"asks for {what}, as the history prints it, with all six decimals. Read it off "
            f"{_history_hint(number, row, col, 'the intended' if meant else what)}")  # fmt: skip


def _other_look(number: int) -> str:
    """What the redrawn frame ``number`` changes (:class:`_Look`), in words: the cube has no
    wall or strip (r21 D6)."""
    symptom = _SPECS[number - 1][0]
    if "cube" in symptom:
        return "other depths and another drawing order (other triangle numbers)"
    thing = "pane" if "pane" in symptom else "strip"
    return f"another wall and {thing}: other colours and depths"


def _meant_words(args, number, got) -> str:
    """The triangle's number read off the intended frame's history (r84 11-2: it passed
    while both frames of a pair numbered their triangles alike)."""
    cause, (row, col), value = got
    return (
        f"you found the right triangle, but {value} is its number in the intended frame's "
        "history: the list asks for its number in this frame's own history, and the two "
        "frames of this pair number "
        "their triangles differently (they draw them in other orders; in the frame shown "
        "they happen to agree). Match the triangle by its corners on screen, "
        "frame.trace.window[k, :, :2] (the same in both frames, whatever its number), and "
        f"read its number off {_history_hint(number, row, col, 'the frame')}"
    )


def _copied_words(args, number, got) -> str:
    cause, (row, col), _ = got
    return (
        f"your value is the one frame {int(number)} shows at ({row}, {col}); this frame is "
        f"the same mistake redrawn with {_other_look(int(number))}, so its evidence "
        "differs: read it inside your function from the frame it is given (b.frame."
        f"history({row}, {col}), b.intended.history({row}, {col})), never typed in"
    )


def _nested_words(args, number, got) -> str:
    return (
        f"your broken_frame_{int(number)} ran a check inside itself: a check run from "
        "inside the answer never passes (trying answers against the checker is not a "
        "diagnosis)"
    )


def _rule(args, expected, got) -> str:
    return ""


def _verdict(name: str):
    return lambda a, e, g: _judged(e, g)[0] == name


def _pixel_words(a, e, g) -> str:
    swap = _swapped(e, g)
    return (f"frame {int(e)} and its intended frame have the same colour at ({g[1][0]}, "
            f"{g[1][1]}): pick a pixel where the two pictures differ, whose history the "
            "mistake changed" + (f". {swap}" if swap else ""))  # fmt: skip


#: What a wrong answer is told, one kind each (the module docstring says in which order).
DIAGNOSIS_MISTAKES = (
    Mistake("check inside", _nested_words, fits=_verdict("nested")),
    Mistake("pixel", _pixel_words, fits=_verdict("pixel")),
    Mistake("pixel without the mark", _unmarked_words, fits=_verdict("unmarked")),
    Mistake("cause", _cause_words, fits=_verdict("cause")),
    Mistake("the intended frame's number", _meant_words, fits=_verdict("intended")),
    Mistake("typed in", _copied_words, fits=_verdict("copied")),
    Mistake("another surface's depth", _surface_words, fits=_verdict("surface")),
    Mistake("another record's value", _record_words, fits=_verdict("record")),
    Mistake("the other frame's value", _other_frame_words, fits=_verdict("other")),
    Mistake("a depth as drawn", _drawn_words, fits=_verdict("drawn")),
    Mistake("evidence", _evidence_words, fits=_verdict("evidence")),
)


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


#: The failure picture's zoom on a sliver answer: pixels each side of the chosen one, and
#: the data units (frame pixels) the zoom takes beside the two frames (its height: the frame's).
ZOOM_REACH, ZOOM_SIZE = 2, H
#: The thin triangle's colour in the zoom: neither the strip's (blues) nor the wall's, nor the
#: chosen pixel's orange (Okabe-Ito reddish purple).
THIN_COLOUR = "#CC79A7"


def _draw(ax, case, got):
    """The broken frame with the chosen pixel marked, and the intended one beside it in the
    same axes (an inset outside the axes would be clipped by the figure's edge), each with
    its triangles' outlines (dashed where one covers no centre: the sliver,
    :func:`~teachraster.plotting.frame_debug.plot_triangle_edges`). For an answer naming
    "sliver", a zoom on the chosen pixel beside them: its square, the pixel centres and the
    thin triangle, which the explanation names (review r298 FIG1: they were not drawn)."""
    from matplotlib.transforms import Affine2D  # only where a figure is drawn

    from ..plotting.frame_debug import plot_triangle_edges

    number = int(case[2])
    if isinstance(got, _Number):  # the passing example: the answer accepted, if any
        got = got.right
    b = _as_frame(case[2])
    gap = 12  # px between the two pictures: room for their tick labels
    artists = [ax.imshow(_rgb(b.frame), extent=(0, W, H, 0), interpolation="nearest"),
               ax.imshow(_rgb(b.intended), extent=(W + gap, 2 * W + gap, H, 0),
                         interpolation="nearest")]  # fmt: skip
    for frame, x in ((b.frame, 0), (b.intended, W + gap)):
        lines = plot_triangle_edges(ax, frame)
        if lines is not None:
            lines.set_transform(Affine2D().translate(x, 0) + ax.transData)
            artists.append(lines)
    right, label = 2 * W + gap, "left: as rendered · right: as intended"
    answer = isinstance(got, tuple) and len(got) == 3 and got[0] in CAUSES
    if answer:  # an answer, as read
        _, (row, col), _ = got
        from matplotlib.patheffects import withStroke

        halo = [withStroke(linewidth=5, foreground="white")]  # r18-15: found on any colour
        for x in (col, col + W + gap):  # on both pictures (r7: on the broken one only)
            artists += ax.plot([x, x + 1, x + 1, x, x], [row, row, row + 1, row + 1, row],
                               color="#D55E00", lw=2.5, path_effects=halo)  # fmt: skip
        if got[0] == "sliver" and 0 <= row < H and 0 <= col < W:
            artists += _zoom(ax, b.frame, row, col, right + gap)
            right = right + gap + ZOOM_SIZE
            label = f"as rendered · as intended · ({row}, {col}) rendered, enlarged"
    ax.set_xlim(0, right)
    ax.set_ylim(H, 0)
    ax.set_xticks([0, W // 2, W - 1, W + gap, W + gap + W // 2, 2 * W + gap - 1],
                  ["0", str(W // 2), str(W - 1), "0", str(W // 2), str(W - 1)])  # fmt: skip
    ax.set_xlabel(label, fontsize="small")
    ax.set_title(f"frame {number}: {b.symptom}", fontsize="small")
    return artists


def _zoom(ax, frame: Frame, row: int, col: int, x0: float) -> list:
    """Pixel (row, col) of ``frame`` and :data:`ZOOM_REACH` pixels round it, enlarged into
    the square [x0, x0 + ZOOM_SIZE] × [0, H] of ``ax``: the picture, the pixel centres
    (dots), the pixel's square (orange) and the frame's thinnest triangle (:func:`_altitudes`,
    the one the check calls "the thin triangle"), read off its trace, clipped to the square."""
    from matplotlib.patches import Polygon, Rectangle

    n = 2 * ZOOM_REACH + 1
    scale = ZOOM_SIZE / n
    c0, r0 = col - ZOOM_REACH, row - ZOOM_REACH

    def at(x, y):  # frame window (x, y) -> the zoom's data coordinates
        return x0 + (np.asarray(x) - c0) * scale, (np.asarray(y) - r0) * scale

    padded = np.pad(_rgb(frame), ((ZOOM_REACH,) * 2, (ZOOM_REACH,) * 2, (0, 0)), constant_values=1)
    crop = padded[row : row + n, col : col + n]  # white beyond the frame's edge
    artists = [ax.imshow(crop, extent=(x0, x0 + ZOOM_SIZE, H, 0), interpolation="nearest")]
    box = Rectangle((x0, 0), ZOOM_SIZE, H, fill=False, lw=1, ec="#444444")
    artists.append(ax.add_patch(box))
    for k in range(1, n):  # the pixel grid
        artists += ax.plot(*at([c0 + k] * 2, [r0, r0 + n]), color="#888888", lw=0.5)
        artists += ax.plot(*at([c0, c0 + n], [r0 + k] * 2), color="#888888", lw=0.5)
    cx, cy = np.meshgrid(np.arange(c0, c0 + n) + 0.5, np.arange(r0, r0 + n) + 0.5)
    artists += ax.plot(*at(cx.ravel(), cy.ravel()), "o", color="#222222", ms=2.5)
    x, y = at([col, col + 1, col + 1, col, col], [row, row, row + 1, row + 1, row])
    artists += ax.plot(x, y, color="#D55E00", lw=2.5)
    k = int(np.argmin(_altitudes(frame)))
    # r309 S5: in the strip's own blue it read as the strip drawn; a colour of its own, dashed
    # as the outlines draw a triangle that covers no centre, named in a key
    thin = Polygon(np.column_stack(at(*frame.trace.window[k, :, :2].T)), closed=True,
                   fc=THIN_COLOUR, ec=THIN_COLOUR, alpha=0.75, lw=1.5, ls="--",
                   label="the thin triangle")  # fmt: skip
    artists.append(ax.add_patch(thin))
    thin.set_clip_path(box)
    # r377 F6a: the key at a classroom size (6 pt in the zoom's top row was about 5 pt on
    # screen), under the zoom, where no tick labels stand: wider than the zoom at that size
    from ..plotting.common import fs

    artists.append(ax.legend(handles=[thin], loc="upper right", bbox_to_anchor=(1, -0.01),
                             fontsize=fs(0.7), framealpha=0.9, borderpad=0.2,
                             handlelength=1.0, handletextpad=0.3, borderaxespad=0))  # fmt: skip
    return artists


#: The checker's own readers: a diagnosis that calls them reads the answer from the checker,
#: and is reported "not counted" (r9 11-2: the salted hash and ``_evidence`` gave 6/6).
_PRIVATE = tuple(
    PackageAnswer(f, words="read from the checker's private functions: not counted (read the "
                  "evidence off frame.history(row, col) yourself)")
    for f in (_is_cause, _pixel, _evidence, _judged_on.__wrapped__, _right_at, _stages, _ties,
              _meant_numbers,
              _thin_missed, _reordered, _recoloured, *(sign for sign, _ in _SIGNS.values()))
)  # fmt: skip


#: The key's data: code that reads them (the objects, a copy, or one of their texts, under
#: any name: r13 11-4) reads the cause off the checker (r11 11-E: hashing the ten causes with
#: ``_SALT`` against ``_KEY`` passed 6/6 with no private call).
_SECRETS = tuple(
    (name, value, "the frames' causes, hashed: not counted (name the cause the histories show)")
    for name, value in (("_KEY", _KEY), ("_SALT", _SALT))
)


#: Failing checks of one frame in a kernel before each further check waits (:mod:`.tries`;
#: r12 11-2: ten causes × 40 generic history readers passed all six frames, 2,100 checks in
#: 51 s). A diagnosis needs a handful; 25 leaves room for a student who tries pixel by pixel.
TRIES = 25
#: The first frame with no free wrong cause (:mod:`.tries`; frames before it have
#: :data:`.tries.FREE_CAUSES`): frames 7 to 9 come after six diagnoses (r21 D2: generic
#: readers written for frames 1 to 6 passed 7, 8 and 9 by trial, one wrong cause each, at no
#: cost). A right cause never waits.
LATER = 7


def frame_exercise(number: int) -> Exercise:
    """Exercise ``broken_frame_<number>``: fn() returns (cause, (row, col), evidence)."""
    return Exercise(
        f"broken_frame_{number}", _cases(number), as_diagnosis, _same, _explain, _rule,
        DIAGNOSIS_MISTAKES, draw=_draw, call=_call, answers=_PRIVATE, private=_SECRETS,
        tries=TRIES, free_causes=FREE_CAUSES if number < LATER else 0,
    )  # fmt: skip


#: The exercises, one a frame, for the registry: name -> how to build it.
EXERCISES = {
    f"broken_frame_{n}": (lambda n=n: frame_exercise(n)) for n in range(1, len(_SPECS) + 1)
}

# r399 F6: the stub's note says what these figures draw (the frames and your pixel, never the
# evidence): NOTHING_DRAWN_YET promised "the rule's answer beside yours"
NOTHING_DRAWN_FOR.update({name: (
    "Nothing drawn yet: once your function returns answers, the check draws its first failing "
    "case (or, when all pass, one of the cases): the frame as rendered beside the intended "
    "one, your pixel marked on both, never the evidence") for name in EXERCISES})  # fmt: skip
