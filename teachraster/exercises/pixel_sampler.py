"""Exercise ``pixel_sample(pyramid, xy, w, uv, row, col, wrap)`` (lesson 09): the whole sampler.

The texture unit's work at one pixel of a triangle, composed from the student's own 7.1
``pixel_lod`` (λ from the pixel's quad), 7.3 ``trilinear`` and 7.2 ``bilinear`` (r390 F1,
"Three changes" 1: the sampler had been four printed formulas copied one at a time): the
texture's size read off the pyramid's level 0, λ from the quad, the pixel's *own*
perspective-correct (u, v) at its centre (the quad shares λ, not (u, v)), then trilinear
filtering, which clamps λ to the pyramid. The cases lie on 7.1's floor with small pyramids,
so that its far tip asks for a λ above the pyramid and its magnified copies for one below,
and its pixels on either side of a level's boundary show a seam where levels are not blended.

Expected answers: :func:`.pixel_level.expected_lod` and the package's trilinear ``sample``.
"""

from __future__ import annotations

import textwrap

import numpy as np

from ..pipeline.mip_pyramid import mipmap
from ..pipeline.texture import sample
from ..pipeline.texture_filters import mip_level
from ..pipeline.texturing.quad_derivatives import lane_values
from .cases import SEED, fixed_and_drawn
from .exercise import Exercise, PackageAnswer, variant_mistakes
from .pixel_level import FLOOR_UV, draw_lod_case, expected_lod
from .quad_difference import FLOOR, inside, value_at
from .scalars import num, vec
from .texture_filtering import (
    Pyramid,
    as_texel_value,
    expected_trilinear,
    same_value,
    trilinear_with,
)


def pixel_uv(xy, w, uv, row: int, col: int) -> np.ndarray:
    """(u, v) at pixel (row, col)'s own centre, perspective-correct (extrapolated)."""
    x, y = col + 0.5, row + 0.5
    return np.array([value_at(xy, w, np.asarray(uv, float)[:, k], x, y) for k in (0, 1)])


def level_size(pyramid) -> tuple[int, int]:
    return tuple(int(n) for n in np.shape(pyramid[0])[:2])


def expected_sample(pyramid, xy, w, uv, row, col, wrap) -> np.ndarray:
    lod = expected_lod(xy, w, uv, level_size(pyramid), row, col)
    return expected_trilinear(pyramid, pixel_uv(xy, w, uv, row, col), lod, wrap)


def _sample_cases(rng, word):
    """7.1's floor on pyramids of 8 × 8 (its far tip above level q = 3), 16 × 16 and 8 × 4,
    magnified too; seeded random triangles and pyramids."""
    xy, w, _ = FLOOR
    p8, p16, p84 = (Pyramid(mipmap(np.round(rng.uniform(0, 1, s), 3)))
                    for s in ((8, 8), (16, 16), (8, 4)))  # fmt: skip
    hard = [
        (p8, 28, 14, 1.0, "repeat", "by the near edge, λ between levels 0 and 1"),
        (p8, 29, 15, 1.0, "repeat", "the same quad, the lower-right lane"),
        (p8, 5, 14, 1.0, "repeat", "the far tip: λ above the pyramid"),
        (p8, 9, 15, 1.0, "clamp", "towards the tip, λ between levels 2 and 3"),
        (p8, 27, 3, 1.0, "repeat", "by the left edge: helpers outside"),
        (p16, 16, 20, 1.0, "repeat", "a 16 × 16 pyramid"),
        (p16, 21, 24, 1.0, "clamp", "by the right edge, 'clamp'"),
        (p84, 13, 11, 1.0, "repeat", "a non-square pyramid (8 × 4)"),
        (p8, 29, 15, 1 / 16, "repeat", "magnified: λ below 0"),
        (p8, 12, 10, 1 / 4, "clamp", "(u, v) over 1/4: λ just below 0"),
    ]
    out = [(f"floor, pixel ({r}, {c}), {'×'.join(map(str, level_size(p)))} pyramid: {why}",
            (p, xy, w, FLOOR_UV * s, r, c, wrap)) for p, r, c, s, wrap, why in hard]  # fmt: skip
    for k in range(8):
        txy, (r, c) = _covered_triangle(rng)
        tw = np.exp(rng.uniform(0, np.log(10), 3))
        tuv = np.round(rng.uniform(-2, 2, (3, 2)), 2)
        h, wt = (int(2 ** rng.integers(1, 5)) for _ in range(2))
        pyr = Pyramid(mipmap(np.round(rng.uniform(0, 1, (h, wt)), 3)))
        out.append((f"{word} {k + 1}, pixel ({r}, {c}), {h}×{wt} pyramid",
                    (pyr, txy, tw, tuv, r, c, ("repeat", "clamp")[k % 2])))  # fmt: skip
    return [(f"{label}, wrap={a[6]!r}", a, expected_sample(*a)) for label, a in out]


def _covered_triangle(rng):
    """A random triangle and the pixel whose centre, covered, lies nearest its centroid (a
    GPU shades no pixel it does not cover, so a pixel's own (u, v) is never extrapolated)."""
    while True:
        txy = np.round(rng.uniform(0, 24, (3, 2)) * 256) / 256
        centre = txy.mean(axis=0)
        pixels = sorted(((r, c) for r in range(25) for c in range(25)
                         if inside(txy, c + 0.5, r + 0.5)),
                        key=lambda p: np.hypot(p[1] + 0.5 - centre[0], p[0] + 0.5 - centre[1]))  # fmt: skip
        if pixels:
            return txy, pixels[0]


sample_cases = fixed_and_drawn(_sample_cases, SEED + 95)  # r49: some drawn per check


def _shown(a, b) -> str:
    """One value as a number, channels as a tuple."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    return num(float(a), float(b)) if a.size == 1 and b.size == 1 else vec(a, b)


def explain_sample(args, expected, got) -> str:
    """λ and the pixel's (u, v) are what 7.4 asks to compose: the values only."""
    return f"the filtered value is {_shown(expected, got)}; yours is {_shown(got, expected)}"


def _variants(pyramid, xy, w, uv, row, col, wrap) -> dict:
    """Each typical mistake's value on this case."""
    size = level_size(pyramid)
    lod = expected_lod(xy, w, uv, size, row, col)
    at = pixel_uv(xy, w, uv, row, col)
    r0, c0 = row - row % 2, col - col % 2
    lane = np.array([value_at(xy, w, np.asarray(uv, float)[:, k], c0 + 0.5, r0 + 0.5)
                     for k in (0, 1)])  # fmt: skip
    corner = np.array([value_at(xy, w, np.asarray(uv, float)[:, k], col, row) for k in (0, 1)])
    affine = np.array([value_at(xy, w, np.asarray(uv, float)[:, k], col + 0.5, row + 0.5,
                                affine=True) for k in (0, 1)])  # fmt: skip

    def tri(u=at, lam=lod, **kw):
        return trilinear_with(pyramid, u, lam, wrap, **kw)

    return {
        "the quad's (u, v)": tri(u=lane),
        "affine (u, v)": tri(u=affine),
        "(u, v) at the corner": tri(u=corner),
        "size read as (W, H)": tri(lam=expected_lod(xy, w, uv, size[::-1], row, col)),
        "the last level's size": tri(
            lam=expected_lod(xy, w, uv, np.shape(pyramid[-1])[:2], row, col)
        ),  # fmt: skip
        "λ not clamped": tri(clamp="weight"),
        "nearest level": tri(levels="nearest"),
        "level 0 only": tri(levels="finest"),
    }


MISTAKES = {
    "the quad's (u, v)": lambda a, e, g: (
        f"you filtered at the (u, v) of the quad's upper-left "
        f"lane: the quad shares one λ, but each pixel is shaded at its own (u, v); which (u, v) "
        f"belongs to pixel ({a[4]}, {a[5]})?"
    ),
    "affine (u, v)": "your (u, v) at the pixel is interpolated affinely: which interpolation "
    "does a texture coordinate get (lesson 04), the same as 7.1's lanes?",
    "(u, v) at the corner": "you took (u, v) at the pixel's corner (col, row): where is a pixel "
    "shaded?",
    "size read as (W, H)": lambda a, e, g: (
        f"your λ reads the texture's size as (W, H): level "
        f"0 is {np.shape(a[0][0])[0]} rows × {np.shape(a[0][0])[1]} columns, and 7.1's `size` is "
        "`texture.shape[:2]`"
    ),
    "the last level's size": "your λ measures the steps in texels of the last, 1 × 1 level: "
    "λ counts texels of level 0; which level's size does 7.1's `size` want?",
    "λ not clamped": "λ lies outside the pyramid here: what must the sampler do with it before "
    "choosing levels (7.3)?",
    "nearest level": "that is the nearest level alone: where λ crosses a whole number the "
    "picture jumps (a seam on the floor); 7.3's trilinear blends the two levels around λ",
    "level 0 only": "that is level 0 alone, whatever λ: this pixel's footprint spans several "
    "texels of level 0 (the texture aliases); filter at the λ of 7.1",
}


RULE = (
    ": λ = 7.1's pixel_lod of the triangle at this pixel, with the size of level 0; (u, v) "
    "perspective-correct at this pixel's own centre; 7.3's trilinear of the pyramid there"
)
HINT = (
    ": which of your functions gives λ here, with which size; at which point is this pixel's "
    "(u, v) taken; which function filters the pyramid at that λ?"
)


def _rule(args, expected, got) -> str:
    return RULE


def sample_questions(pyramid) -> str:
    """7.4's questions answered on 7.1's floor with ``pyramid``: the level the tip reads, and
    the values of two pixels of one quad."""
    xy, w, _ = FLOOR
    q, size = len(pyramid) - 1, level_size(pyramid)
    tip = expected_lod(xy, w, FLOOR_UV, size, 5, 14)
    read = f"level {q} alone (λ clamped to {q})" if tip >= q else f"levels around λ = {num(tip)}"
    a, b = (expected_sample(pyramid, xy, w, FLOOR_UV, r, c, "repeat") for r, c in ((28, 14), (29, 15)))  # fmt: skip
    same = "the same" if np.allclose(a, b) else "different"
    return (
        f"7.4: the tip (5, 14) asks for λ = {num(tip)}: {read}. (28, 14) and (29, 15) share "
        f"λ but not (u, v): {_shown(a, b)} and {_shown(b, a)}, {same} values"
    )


def draw_sample_case(ax, case, got):
    """7.1's close-up at the pixel (the quad drawn once the check passes); the filtered value
    and yours, with λ and (u, v) once it passes."""
    _, (pyramid, xy, w, uv, row, col, wrap), expected = case
    size = level_size(pyramid)
    lod = expected_lod(xy, w, uv, size, row, col)
    passed = got is not None and same_value(got, expected, None)
    artists = draw_lod_case(ax, ("", (xy, w, uv, size, row, col), lod), lod if passed else None)
    text = f"pixel ({row}, {col}), level 0 {size[0]}×{size[1]}, wrap={wrap!r}"
    if got is not None:
        text += f"; value {_shown(expected, got)}, yours {_shown(got, expected)}"
    if passed:
        q = len(pyramid) - 1
        text += (f"\nλ = {num(lod)} (pyramid 0–{q}), (u, v) at the pixel's centre = "
                 f"{vec(pixel_uv(xy, w, uv, row, col))}\n{textwrap.fill(sample_questions(pyramid), 75)}")  # fmt: skip
    artists.append(ax.set_xlabel(text, fontsize="x-small"))
    return artists


PIXEL_SAMPLE = Exercise(
    "pixel_sample", sample_cases, as_texel_value, same_value, explain_sample, _rule,
    variant_mistakes(_variants, MISTAKES),
    answers=(PackageAnswer(sample, when=lambda a: a.get("filter") == "trilinear"),
             PackageAnswer(mip_level), PackageAnswer(lane_values)),
    draw=draw_sample_case, hints=((RULE, HINT),), inputs_drawn=True,
    once=((RULE, ": as said for the first failing case"),),
    reference=("teachraster.exercises.quad_difference", "teachraster.exercises.pixel_level",
               "teachraster.exercises.texture_filtering"),
    example=2,  # the far tip: λ above the pyramid, clamped
)  # fmt: skip
