"""Exercises ``bilinear(texture, uv, wrap)`` and ``trilinear(pyramid, uv, lod, wrap)``.

Lesson 09 (the GL 4.6 spec, §8.14.2 "Coordinate Wrapping and Texel Selection"; Heckbert,
*Fundamentals of Texture Mapping and Image Warping*): texel (r, c) of a W × H level has its
centre at ((c + ½)/W, (r + ½)/H); ``bilinear`` (GL's LINEAR) moves to texel units with
x = u·W − ½, y = v·H − ½, takes the four texels around (⌊x⌋, ⌊y⌋), wrapped ("repeat": column
−1 is column W − 1; "clamp": the border texel), and blends them by the fractions of x and y.
``trilinear`` (LINEAR_MIPMAP_LINEAR) clamps λ to the pyramid [0, q], filters levels ⌊λ⌋ and
⌊λ⌋ + 1 (at most q) bilinearly, each with its own size, and blends them by λ − ⌊λ⌋.

Expected answers are :func:`teachraster.sample`'s (filters ``"bilinear"`` and
``"trilinear"``). To name a mistake, the explanations compare the answer with a plain
bilinear filter written here with that mistake put in (corners for centres, truncation for
floor, swapped weights...), and with the package's own filters on other levels.
"""

from __future__ import annotations

from functools import cache

import numpy as np

from ..pipeline.mip_pyramid import mipmap
from ..pipeline.texture import sample
from .cases import SEED
from .running import WrongAnswerType
from .scalars import num, vec
from .scene_report import refuse_non_answers
from .tolerance import all_close


class Pyramid(list):
    """A mip pyramid as the trilinear cases pass it: the list of levels, level 0 first.

    numpy sees it as what it is, a sequence of levels (``np.size`` is their number,
    ``np.asarray`` an object array of them), instead of failing on their different shapes.
    """

    def __array__(self, dtype=None, copy=None):
        out = np.empty(len(self), dtype=object)
        for k, level in enumerate(self):
            out[k] = level
        return out


def expected_bilinear(texture, uv, wrap) -> np.ndarray:
    return sample(texture, np.asarray(uv, dtype=float)[None], "bilinear", wrap)[0]


def expected_trilinear(pyramid, uv, lod, wrap) -> np.ndarray:
    uv = np.asarray(uv, dtype=float)[None]
    return sample(pyramid, uv, "trilinear", wrap, lod=np.array([lod], dtype=float))[0]


def as_texel_value(value) -> np.ndarray:
    refuse_non_answers(value, "a number or a colour")
    if any(isinstance(v, str | bytes) for v in np.ravel(np.asarray(value, dtype=object))):
        raise WrongAnswerType(f"returned {value!r:.60}: text, not a number or a colour")
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise WrongAnswerType(f"returned {value!r:.60}, not a number or a colour") from None
    return arr


def same_value(got, expected, args) -> bool:
    got = np.asarray(got, dtype=float)
    if got.size != np.size(expected):
        return False
    return all_close(got.reshape(np.shape(expected)), expected)


def plain_bilinear(
    texture, uv, wrap, *, centre=0.5, floor=np.floor, swap=False, wrap_x=None, span=0
):
    """A bilinear filter with knobs for the usual mistakes (explanations only).

    ``centre`` is subtracted from u·W (0.5 is right, 0 samples at texel corners), ``floor``
    finds the texel to the left (``np.trunc`` is the int() mistake), ``swap`` gives the left
    texel the weight of the right one, ``wrap_x`` wraps with another mode, ``span=-1``
    stretches u over W − 1 texels (first centre at u = 0, last at u = 1).
    """
    tex = np.asarray(texture, dtype=float)
    h, w = tex.shape[:2]
    x, y = uv[0] * (w + span) - centre, uv[1] * (h + span) - centre
    x0, y0 = floor(x), floor(y)
    fx, fy = x - x0, y - y0
    if swap:
        fx, fy = 1 - fx, 1 - fy

    def index(i, n):
        mode = wrap if wrap_x is None else wrap_x
        return int(np.mod(i, n)) if mode == "repeat" else int(np.clip(i, 0, n - 1))

    c0, c1, r0, r1 = index(x0, w), index(x0 + 1, w), index(y0, h), index(y0 + 1, h)
    top = tex[r0, c0] * (1 - fx) + tex[r0, c1] * fx
    bottom = tex[r1, c0] * (1 - fx) + tex[r1, c1] * fx
    return top * (1 - fy) + bottom * fy


# -- bilinear ---------------------------------------------------------------------------------
def _texture(rng, h, w, channels=0):
    shape = (h, w, channels) if channels else (h, w)
    return np.round(rng.uniform(0, 1, size=shape), 3)


@cache  # the same cases on every check: built once
def bilinear_cases():
    """Texel centres and corners, the border in both wrap modes, odd sizes; then random."""
    rng = np.random.default_rng(SEED + 80)
    t4, t28 = _texture(rng, 4, 4), _texture(rng, 2, 8)
    hard = [
        ("a texel centre", t4, (1.5 / 4, 2.5 / 4), "repeat"),
        ("a texel corner (four texels meet)", t4, (0.5, 0.5), "repeat"),
        ("u = 0, repeat: the last column blends in", t4, (0.0, 0.375), "repeat"),
        ("u = 0, clamp: the border texel", t4, (0.0, 0.375), "clamp"),
        ("u = 1, repeat (the same as u = 0)", t4, (1.0, 0.625), "repeat"),
        ("u = 1, clamp", t4, (1.0, 0.625), "clamp"),
        ("left of the texture, repeat", t4, (-0.3, 0.2), "repeat"),
        ("left of the texture, clamp", t4, (-0.3, 0.2), "clamp"),
        ("x between −1 and 0 (u = 0.05)", t4, (0.05, 0.4), "repeat"),
        ("u = 1.7, repeat", t4, (1.7, -0.45), "repeat"),
        ("a wide texture (H = 2, W = 8)", t28, (0.2, 0.6), "repeat"),
        ("a wide texture, v at the bottom border", t28, (0.55, 0.9), "clamp"),
        ("a 1×1 texture", _texture(rng, 1, 1), (0.3, 0.8), "repeat"),
        ("one row (H = 1)", _texture(rng, 1, 4), (0.4, 0.1), "repeat"),
        ("three channels", _texture(rng, 4, 4, 3), (0.3, 0.7), "repeat"),
        ("8-bit values", np.round(t4 * 255), (0.45, 0.55), "clamp"),
    ]
    out = [(label, (tex, np.array(uv, dtype=float), wrap)) for label, tex, uv, wrap in hard]
    for n in range(14):
        h, w = (int(v) for v in rng.integers(1, 9, size=2))
        tex = _texture(rng, h, w, 3 if n % 3 == 2 else 0)
        uv = np.round(rng.uniform(-1.5, 2.5, size=2), 4)
        out.append((f"random {n + 1}: {h}×{w}", (tex, uv, ("repeat", "clamp")[n % 2])))
    return [
        (f"{label}, uv={vec(args[1])}, wrap={args[2]!r}", args, expected_bilinear(*args))
        for label, args in out
    ]


def explain_bilinear(args, expected, got) -> str:
    tex, uv, wrap = args
    h, w = tex.shape[:2]
    x, y = uv[0] * w - 0.5, uv[1] * h - 0.5
    head = (
        f"uv={vec(uv)} on an H×W = {h}×{w} texture, wrap {wrap!r}: x = u·W − ½ = {num(x)}, "
        f"y = v·H − ½ = {num(y)}, the filtered value is {_value(expected, got)}; yours is "
        f"{_value(got, expected)}"
    )
    return head + _bilinear_mistake(tex, uv, wrap, x, y, got)


def _value(a, b=None) -> str:
    a = np.asarray(a, dtype=float)
    if a.ndim == 0:
        return num(float(a), None if b is None or np.size(b) != 1 else float(np.ravel(b)[0]))
    return vec(a, b if b is not None and np.size(b) == a.size else None)


def _bilinear_mistake(tex, uv, wrap, x, y, got) -> str:
    h, w = tex.shape[:2]
    other = "clamp" if wrap == "repeat" else "repeat"
    tries = [
        (lambda: plain_bilinear(tex, uv, wrap, centre=0.0),
         f": you sampled at texel corners: texel centres are at (i + ½)/W, so x = u·W − ½ "
         f"(here {num(x)}), not u·W"),
        (lambda: plain_bilinear(tex, uv, wrap, centre=0.0, span=-1),
         f": u·(W − 1) puts the first and last texel centres at u = 0 and 1; texel centres are "
         f"at (i + ½)/W, so x = u·W − ½ (here {num(x)})"),
        (lambda: plain_bilinear(tex, uv, wrap, floor=np.trunc),
         f": int() truncates toward zero: for {'x' if x < 0 else 'y'} = {num(min(x, y))} the "
         f"texel to the {'left' if x < 0 else 'top'} is ⌊{num(min(x, y))}⌋ = "
         f"{num(np.floor(min(x, y)))}, and the fraction stays in [0, 1)"),
        (lambda: plain_bilinear(tex, uv, wrap, swap=True),
         ": the weight of the right (lower) texel is the fraction x − ⌊x⌋ (y − ⌊y⌋); you "
         "gave it to the left (upper) one"),
        (lambda: sample(tex, uv[None], "nearest", wrap)[0],
         ": that is the nearest texel; bilinear blends the four texels around (x, y)"),
        (lambda: plain_bilinear(tex, uv, wrap, wrap_x=other),
         f": wrap {wrap!r} " + ("tiles the texture: column −1 is column W − 1, column W is "
         "column 0" if wrap == "repeat" else "repeats the border texels outwards, it does not "
         "tile")),
        (lambda: plain_bilinear(np.swapaxes(tex, 0, 1), uv, wrap),
         f": u runs along the W = {w} columns, v along the H = {h} rows: texture[row, col] "
         "is texture[y, x]"),
    ]  # fmt: skip
    for value, words in tries:
        try:
            if same_value(got, value(), None):
                return words
        except (IndexError, ValueError):
            continue
    return (
        ": blend the four texels around (⌊x⌋, ⌊y⌋) (indices wrapped) with weights from "
        "x − ⌊x⌋ and y − ⌊y⌋"
    )


def draw_texture_case(ax, case, got):
    """The texture (level 0), its texel centres, and the point (u, v) in texel units."""
    from .drawing import draw_values

    tex, uv = case[1][0], case[1][1]
    if isinstance(tex, list):
        tex = tex[0]
    expected = np.ravel(case[2])
    yours = None if got is None else np.ravel(got)
    if yours is not None and yours.size != expected.size:
        yours = None
    labels = [f"channel {k}" for k in range(expected.size)] if expected.size > 1 else ["value"]
    artists = draw_values(ax, labels, expected, yours)
    artists.append(ax.set_xlabel(f"uv = {vec(uv)} on a {tex.shape[0]}×{tex.shape[1]} texture"))
    return artists


# -- trilinear --------------------------------------------------------------------------------
@cache  # the same cases on every check: built once
def trilinear_cases():
    """λ below, on, between and above the levels; square and non-square pyramids; random."""
    rng = np.random.default_rng(SEED + 90)
    p8, p84, p3 = (Pyramid(mipmap(_texture(rng, *s))) for s in ((8, 8), (8, 4), (8, 8, 3)))
    hard = [
        ("λ = 0: level 0 only", p8, (0.3, 0.6), 0.0, "repeat"),
        ("λ = 1: level 1 only", p8, (0.3, 0.6), 1.0, "repeat"),
        ("λ between levels 1 and 2", p8, (0.3, 0.6), 1.5, "repeat"),
        ("λ = 0.25", p8, (0.71, 0.12), 0.25, "repeat"),
        ("λ = 2.75", p8, (0.71, 0.12), 2.75, "clamp"),
        ("λ < 0 (magnified): clamped to 0", p8, (0.4, 0.45), -2.0, "repeat"),
        ("λ = q, the 1×1 level", p8, (0.4, 0.45), 3.0, "repeat"),
        ("λ above the pyramid: clamped to q", p8, (0.4, 0.45), 7.0, "repeat"),
        ("between the last two levels, at the border", p8, (0.02, 0.98), 2.5, "repeat"),
        ("between the last two levels, clamped at the border", p8, (0.02, 0.98), 2.5, "clamp"),
        ("a non-square pyramid (8×4, 4×2, 2×1, 1×1)", p84, (0.3, 0.8), 1.5, "repeat"),
        ("a non-square pyramid, λ = 2.25", p84, (0.9, 0.1), 2.25, "clamp"),
        ("three channels", p3, (0.55, 0.35), 0.75, "repeat"),
    ]
    out = [(label, (pyr, np.array(uv, float), lod, wrap)) for label, pyr, uv, lod, wrap in hard]
    for n in range(12):
        h, w = (int(2 ** rng.integers(0, 5)) for _ in range(2))
        pyr = Pyramid(mipmap(_texture(rng, h, w, 3 if n % 4 == 1 else 0)))
        uv = np.round(rng.uniform(-0.5, 1.5, size=2), 4)
        lod = float(np.round(rng.uniform(-1, len(pyr)), 3))
        out.append((f"random {n + 1}: {h}×{w}", (pyr, uv, lod, ("repeat", "clamp")[n % 2])))
    return [
        (f"{label}, uv={vec(a[1])}, λ={num(a[2])}, wrap={a[3]!r}", a, expected_trilinear(*a))
        for label, a in out
    ]


def explain_trilinear(args, expected, got) -> str:
    pyramid, uv, lod, wrap = args
    q = len(pyramid) - 1
    lam = min(max(lod, 0.0), q)
    d0, d1 = int(np.floor(lam)), min(int(np.floor(lam)) + 1, q)
    t = lam - d0
    a, b = (expected_bilinear(pyramid[d], uv, wrap) for d in (d0, d1))
    sizes = [f"{lv.shape[0]}×{lv.shape[1]}" for lv in pyramid]
    head = (
        f"uv={vec(uv)}, λ = {num(lod)} on a pyramid of {', '.join(sizes)} (q = {q}): λ "
        f"clamped to [0, {q}] is {num(lam)}, levels {d0} and {d1} blended by {num(t)}: "
        f"{_value(a)} and {_value(b)} give {_value(expected, got)}; yours is {_value(got, expected)}"
    )
    return head + _trilinear_mistake(pyramid, uv, lod, wrap, (d0, d1, t, a, b), got)


def _trilinear_mistake(pyramid, uv, lod, wrap, split, got) -> str:
    d0, d1, t, a, b = split
    q = len(pyramid) - 1
    near = int(np.clip(round(lod), 0, q))
    tries = [
        (
            t * a + (1 - t) * b,
            f": the weight of level {d1} is the fraction λ − ⌊λ⌋ = {num(t)}; "
            f"you gave it to level {d0}",
        ),
        (
            expected_bilinear(pyramid[near], uv, wrap),
            f": that is level {near} alone (the nearest); trilinear blends levels {d0} and {d1}",
        ),
        (a, f": that is level {d0} alone; trilinear blends it with level {d1} by {num(t)}"),
    ]
    for value, words in tries:
        if same_value(got, value, None):
            return words
    if lod < 0 or lod > q:
        return (
            f": λ = {num(lod)} lies outside the pyramid: clamp it to [0, q] = [0, {q}] first "
            "(below 0 the texture is magnified and level 0 is filtered)"
        )
    return (
        ": filter each level bilinearly with its own size (texel centres at (i + ½)/W_level), "
        "then (1 − t)·level ⌊λ⌋ + t·level ⌊λ⌋+1"
    )
