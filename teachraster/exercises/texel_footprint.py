"""Exercise 7.2 ``texel_weights(sizes, uv, lod, wrap)``: the texels a trilinear fetch reads.

r491 (from r433 T1, r418 T1: 7.2 ``bilinear`` was lesson 09's printed filter, 7.3
``trilinear`` its table row): the student returns, for a pyramid of level sizes (H, W)
(GL's floor rule: non-square, not powers of two), a (u, v) anywhere in the plane, an
unclamped λ and a wrap mode, every texel the texture unit reads as ``{(level, row, col):
weight}``, each texel once (weights of the same texel, read twice at a border or on a level
one texel high, added). That asks what no lesson cell prints as code: which levels λ needs
within the pyramid and each one's weight, where each level's own texel centres lie, which
texels wrap onto which at the border of a level one texel high or wide, and that clamp and
repeat part over a border band that widens level by level (half a texel of that level).

Expected answers are this module's exact reference (:func:`reference`, in Fractions: every
float is a dyadic rational, so x = u·W − ½, its floor and the weights are exact), cross-checked
by ``tests/test_exercises_r491.py`` against :func:`teachraster.sample` (``"trilinear"``) on
one-hot pyramids: each texel's weight is the package's value where that texel alone is 1.
The mistakes are wrong solutions run here (:func:`weights_with`'s knobs).
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from ..pipeline.texture import sample
from .answers import refuse_none_and_text
from .cases import SEED, fixed_and_drawn
from .exercise import Exercise, Mistake, PackageAnswer, variant_mistakes
from .running import WrongAnswerType
from .scalars import num, vec
from .texture_filtering import FILTER_MODULES

TOL = 1e-6  # as a texel's value (a float32 computation of a weight is right)
HALF = Fraction(1, 2)


def gl_sizes(h: int, w: int) -> list[tuple[int, int]]:
    """The (H, W) of every level of a pyramid whose level 0 is h × w (GL's floor rule).

    >>> gl_sizes(3, 5)
    [(3, 5), (1, 2), (1, 1)]
    """
    out = [(h, w)]
    while out[-1] != (1, 1):
        h, w = max(1, h // 2), max(1, w // 2)
        out.append((h, w))
    return out


def _wrapped(i: int, n: int, wrap: str) -> int:
    return i % n if wrap == "repeat" else min(max(i, 0), n - 1)


def level_split(q: int, lod) -> list[tuple[int, Fraction]]:
    """[(level, weight)] a trilinear fetch blends at ``lod`` on levels 0 to ``q`` (exact).

    >>> level_split(3, 1.25), level_split(3, -0.7), level_split(3, 3.4)
    ([(1, Fraction(3, 4)), (2, Fraction(1, 4))], [(0, Fraction(1, 1))], [(3, Fraction(1, 1))])
    """
    lam = min(max(Fraction(lod), Fraction(0)), Fraction(q))
    lower = math.floor(lam)
    t = lam - lower
    return [(lower, 1 - t)] if t == 0 else [(lower, 1 - t), (lower + 1, t)]


def reference(sizes, uv, lod, wrap) -> dict[tuple[int, int, int], float]:
    """{(level, row, col): weight} of every texel a trilinear fetch reads with a weight > 0.

    >>> reference([(4, 4), (2, 2), (1, 1)], (0.05, 0.375), 0, "repeat")
    {(0, 1, 3): 0.3, (0, 1, 0): 0.7}
    >>> reference([(4, 4), (2, 2), (1, 1)], (0.05, 0.375), 0, "clamp")
    {(0, 1, 0): 1.0}
    """
    out: dict[tuple[int, int, int], Fraction] = {}
    for level, weight in level_split(len(sizes) - 1, lod):
        h, w = (int(n) for n in sizes[level])
        x, y = Fraction(uv[0]) * w - HALF, Fraction(uv[1]) * h - HALF
        x0, y0 = math.floor(x), math.floor(y)
        fx, fy = x - x0, y - y0
        for r, wy in ((y0, 1 - fy), (y0 + 1, fy)):
            for c, wx in ((x0, 1 - fx), (x0 + 1, fx)):
                part = weight * wy * wx
                if part:
                    key = (level, _wrapped(r, h, wrap), _wrapped(c, w, wrap))
                    out[key] = out.get(key, Fraction(0)) + part
    return {k: float(v) for k, v in out.items()}


# -- the mistakes: a fetch with knobs ----------------------------------------------------------
def _index(i: int, n: int, wrap: str, how: str | None) -> int:
    if how == "fmod" and wrap == "repeat":  # C's remainder: keeps the sign (r497)
        return int(math.fmod(i, n))
    if how == "raw":  # no index wrapped at all (the (u, v) reduced instead)
        return i
    if how == "mod n-1" and wrap == "repeat":
        return i % max(n - 1, 1)
    if how == "clip n" and wrap == "clamp":
        return min(max(i, 0), n)
    if how == "mirror":  # clamp read as a mirror
        period = 2 * n
        i %= period
        return i if i < n else period - 1 - i
    return _wrapped(i, n, wrap)


def _levels(q: int, lod: float, how: str) -> list[tuple[int, float]] | None:
    lam = min(max(lod, 0.0), q)
    if how == "clamp q-1":  # r497: λ clamped to [0, q − 1]
        lam = min(max(lod, 0.0), max(q - 1, 0))
    elif how == "abs":  # r497: |λ|
        lam = min(abs(lod), q)
    if how == "unclamped":
        lower = math.floor(lod)
        return [(lower, 1 - (lod - lower)), (lower + 1, lod - lower)]
    if how == "split first":  # ⌊λ⌋ and the fraction taken before the clamp
        lower = math.floor(lod)
        t = lod - lower
        lo = min(max(lower, 0), q)
        return [(lo, 1 - t), (min(lo + 1, q), t)]
    if how == "nearest":  # GL's nearest level
        return [(0 if lam <= 0.5 else min(math.ceil(lam + 0.5) - 1, q), 1.0)]
    if how == "floor alone":
        return [(math.floor(lam), 1.0)]
    if how == "halves":
        lower = math.floor(lam)
        return [(lower, 0.5), (min(lower + 1, q), 0.5)] if lam != lower else [(lower, 1.0)]
    lower = math.floor(lam)
    t = lam - lower
    if how == "swapped":
        return [(lower, t), (min(lower + 1, q), 1 - t)]
    if how == "no level weight":
        return [(lower, 1.0), (min(lower + 1, q), 1.0)] if t else [(lower, 1.0)]
    return [(lower, 1 - t), (min(lower + 1, q), t)]


def weights_with(sizes, uv, lod, wrap, *, origin=-0.5, floor="floor", size_as="right",
                 wrap_as=None, levels="right", merge="add", keys="rc", uv_as="right",
                 coord="right", within="right"):  # fmt: skip
    """A trilinear fetch's texel weights (float64) with a knob turned for each mistake; the
    defaults give :func:`reference`'s answer. None where the mistake raises (a level beyond
    the pyramid).

    >>> weights_with([(4, 4), (2, 2), (1, 1)], (0.05, 0.375), 0, "repeat", origin=0.0)
    {(0, 1, 0): 0.4, (0, 1, 1): 0.1, (0, 2, 0): 0.4, (0, 2, 1): 0.1}
    """
    q = len(sizes) - 1
    split = _levels(q, float(lod), levels)
    out: dict[tuple[int, int, int], float] = {}
    mode = {"swapped": {"repeat": "clamp", "clamp": "repeat"}.get(wrap), "clamp": "clamp",
            "repeat": "repeat"}.get(wrap_as, wrap)  # fmt: skip
    how = wrap_as if wrap_as in ("mirror", "mod n-1", "clip n", "fmod") else None
    axes = {"rows tiled": ("repeat", mode), "rows clamped": ("clamp", mode)}.get(wrap_as)
    if wrap_as in ("rows tiled", "rows clamped") and axes[0] == wrap:
        return None  # the same as the right answer for this mode: says nothing
    if how == "mirror" and wrap == "repeat":
        how = None
    for level, weight in split:
        if not -len(sizes) <= level < len(sizes):
            return None
        h, w = (int(n) for n in sizes[level])
        if size_as == "wh":
            h, w = w, h
        elif size_as == "level 0":
            h, w = (int(n) for n in sizes[0])
        elif size_as == "exact halves":
            h, w = sizes[0][0] / 2**level, sizes[0][1] / 2**level
        elif size_as == "ceil":  # halved rounding up, from level 0
            h, w = -(-int(sizes[0][0]) // 2**level), -(-int(sizes[0][1]) // 2**level)
        elif size_as == "reversed":  # level k's size read from the coarse end
            h, w = (int(n) for n in sizes[q - level])
        elif size_as == "lower":  # r509: both levels read with level ⌊λ⌋'s size
            h, w = (int(n) for n in sizes[split[0][0]])
        u, v = float(uv[0]), float(uv[1])
        if uv_as == "vu":
            u, v = v, u
        elif uv_as == "per level":
            u, v = u / 2**level, v / 2**level
        elif uv_as in ("flip u", "flip v"):
            u, v = (1 - u, v) if uv_as == "flip u" else (u, 1 - v)
        elif uv_as == "reduced":  # (u, v) taken modulo 1, the indices then not wrapped
            u, v = (u % 1, v % 1) if wrap == "repeat" else (u, v)
        elif uv_as == "clamped" and wrap == "clamp":  # (u, v) clamped to [0, 1], then tiled
            u, v, mode = min(max(u, 0.0), 1.0), min(max(v, 0.0), 1.0), "repeat"
        elif uv_as == "clamped raw" and wrap == "clamp":  # r509: the indices then not clamped
            u, v = min(max(u, 0.0), 1.0), min(max(v, 0.0), 1.0)
        x, y = u * w + origin, v * h + origin
        if coord == "stretched":  # u·(W − 1): the first and last centres at u = 0 and 1
            x, y = u * (w - 1), v * (h - 1)
        elif coord == "u by H":
            x = u * h + origin
        elif coord == "halved level 0":  # level 0's W / 2ᵏ (2.5 for 5 → 2), wrapped by sizes
            x, y = u * sizes[0][1] / 2**level + origin, v * sizes[0][0] / 2**level + origin
        rounding = {"floor": math.floor, "int": int, "round": lambda t: math.floor(t + 0.5)}
        x0, y0 = rounding[floor](x), rounding[floor](y)
        fx, fy = x - x0, y - y0
        if within == "nearest":  # the nearest centre alone (NEAREST_MIPMAP_LINEAR)
            x0, y0, fx, fy = math.floor(x + 0.5), math.floor(y + 0.5), 0.0, 0.0
        elif within == "exchanged":  # x's fraction along y and y's along x
            fx, fy = fy, fx
        elif within == "fx for fy":
            fy = fx
        elif within == "u weights swapped":
            fx = 1 - fx  # the pair (x0, x0 + 1) read with (fx, 1 − fx)
        elif within == "v weights swapped":
            fy = 1 - fy  # the pair (y0, y0 + 1) read with (fy, 1 − fy)
        hi, wi = max(int(math.ceil(h)), 1), max(int(math.ceil(w)), 1)
        for r, wy in ((y0, 1 - fy), (y0 + 1, fy)):
            for c, wx in ((x0, 1 - fx), (x0 + 1, fx)):
                part = weight * wy * wx
                if part == 0 and merge != "assign zeros":
                    continue
                rmode, cmode = axes if axes else (mode, mode)
                rhow = ("raw" if (uv_as, wrap) in (("reduced", "repeat"), ("clamped raw", "clamp"))
                        else how)  # fmt: skip
                key = (level, _index(r, hi, rmode, rhow), _index(c, wi, cmode, rhow))
                if wrap_as == "other size" and wrap == "repeat":  # rows modulo W, columns H
                    key = (level, _index(r, wi, mode, None), _index(c, hi, mode, None))
                if keys == "cr":
                    key = (level, key[2], key[1])
                elif keys == "rc level":
                    key = (key[1], key[2], level)
                elif keys == "from coarse":
                    key = (q - level, key[1], key[2])
                elif keys == "lower":
                    key = (split[0][0], key[1], key[2])
                out[key] = out.get(key, 0.0) + part if merge == "add" else part
    return out


#: Each mistake's knob setting, and the words that name it (its cause, never the rule).
VARIANTS = {
    "texel corners": {"origin": 0.0},
    "half a texel the wrong way": {"origin": 0.5},
    "int() for floor": {"floor": "int"},
    "rounded to the nearest centre": {"floor": "round"},
    "sizes as (W, H)": {"size_as": "wh"},
    "level 0's size on every level": {"size_as": "level 0"},
    "sizes halved exactly": {"size_as": "exact halves"},
    "(v, u)": {"uv_as": "vu"},
    "(u, v) scaled per level": {"uv_as": "per level"},
    "row and col swapped": {"keys": "cr"},
    "wrap modes swapped": {"wrap_as": "swapped"},
    "always clamp": {"wrap_as": "clamp"},
    "always repeat": {"wrap_as": "repeat"},
    "clamp as a mirror": {"wrap_as": "mirror"},
    "repeat modulo W − 1": {"wrap_as": "mod n-1"},
    "indices clipped to [0, W]": {"wrap_as": "clip n"},
    "λ not clamped": {"levels": "unclamped"},
    "split before the clamp": {"levels": "split first"},
    "nearest level": {"levels": "nearest"},
    "⌊λ⌋ alone": {"levels": "floor alone"},
    "levels' weights swapped": {"levels": "swapped"},
    "halves": {"levels": "halves"},
    "no level weight": {"levels": "no level weight"},
    "overwritten": {"merge": "assign zeros"},
    "overwritten, zero weights skipped": {"merge": "assign"},
    # r497: each was told only the generic question, or a symptom
    "λ clamped to [0, q − 1]": {"levels": "clamp q-1"},
    "|λ|": {"levels": "abs"},
    "sizes halved rounding up": {"size_as": "ceil"},
    "sizes read from the coarse end": {"size_as": "reversed"},
    "u flipped": {"uv_as": "flip u"},
    "v flipped": {"uv_as": "flip v"},
    "(u, v) wrapped, not the indices": {"uv_as": "reduced"},
    "clamp as (u, v) clamped, then tiled": {"uv_as": "clamped"},
    "u·(W − 1)": {"coord": "stretched"},
    "u·H": {"coord": "u by H"},
    "level 0's size halved in real numbers": {"coord": "halved level 0"},
    "nearest texel on each level": {"within": "nearest"},
    "fractions exchanged": {"within": "exchanged"},
    "x's fraction along y too": {"within": "fx for fy"},
    "v's weights swapped": {"within": "v weights swapped"},
    "u's weights swapped": {"within": "u weights swapped"},
    "repeat with fmod": {"wrap_as": "fmod"},
    "rows wrapped with W": {"wrap_as": "other size"},
    "rows tiled under clamp": {"wrap_as": "rows tiled"},
    "rows clamped under repeat": {"wrap_as": "rows clamped"},
    "keys (row, col, level)": {"keys": "rc level"},
    # r509: each was told only "your texel (3, 0, -1) is not a texel"
    "clamp as (u, v) clamped, the indices not": {"uv_as": "clamped raw"},
    "both levels with ⌊λ⌋'s size": {"size_as": "lower"},
    "levels numbered from the last": {"keys": "from coarse"},
    "both levels keyed as ⌊λ⌋": {"keys": "lower"},
}


def _variants(sizes, uv, lod, wrap) -> dict:
    out = {}
    for kind, knobs in VARIANTS.items():
        got = weights_with(sizes, uv, lod, wrap, **knobs)
        if got is not None:
            out[kind] = got
    return out


MISTAKES = {
    "texel corners": "you put texel c's value at its left corner, u = c/W: a texel's value "
    "belongs at its centre, half a texel in from its sides, so every weight here is "
    "half a texel off",
    "half a texel the wrong way": "you moved half a texel the wrong way: a texel's centre lies "
    "half a texel to the right of its left side, so a u on a centre must give that texel alone",
    "int() for floor": "you rounded x towards zero (int()) where it is negative: left of the "
    "first centre the texel below x is column −1 (wrapped), not column 0",
    "rounded to the nearest centre": "you took the nearest texel centre as the first of the "
    "pair: the pair is the centre at or below x and the one above it, so that the weights "
    "stay in [0, 1]",
    "sizes as (W, H)": "you read each size as (W, H): `sizes` holds (H, W), rows first, like "
    "`texture.shape`, and u runs along the W columns",
    "level 0's size on every level": "you used level 0's size on every level: each level's "
    "texels are its own, 2ᵏ times as large, so the same (u, v) lies at other texel "
    "coordinates on each level",
    "sizes halved exactly": "you halved level 0's size 2ᵏ times in real numbers: a level's "
    "size is a whole number of texels, the one `sizes` gives (GL's floor rule: 5 → 2 → 1)",
    "(v, u)": "you read (u, v) as (v, u): u runs along the columns (left to right), v along "
    "the rows",
    "(u, v) scaled per level": "you divided (u, v) by 2ᵏ on level k: (u, v) is normalised, "
    "the same point of the texture on every level; only the texel size changes",
    "row and col swapped": "your keys are (level, col, row): the task asks (level, row, col), "
    "as the texture is indexed `[row, col]`",
    "wrap modes swapped": "your 'clamp' repeats and your 'repeat' clamps: the modes are the "
    "wrong way round",
    "always clamp": "you clamped the indices whatever `wrap` says: with 'repeat' the column "
    "beyond the last is the first again",
    "always repeat": "you wrapped the indices round whatever `wrap` says: with 'clamp' a "
    "column beyond the border is the border column",
    "clamp as a mirror": "your 'clamp' mirrors the texture at its border: 'clamp' repeats "
    "the border texel outwards, the same one however far out",
    "repeat modulo W − 1": "you wrapped indices modulo W − 1 (H − 1): the texture repeats "
    "every W columns, so column W is column 0",
    "indices clipped to [0, W]": "your indices run up to W (H): the last column is W − 1, "
    "column W does not exist",
    "λ not clamped": "you chose the levels from λ as given: below 0 or above the last level q "
    "there is no level, the fetch clamps λ to [0, q] first",
    "split before the clamp": "you split λ into level and fraction before clamping it: the "
    "fraction of an unclamped λ weights a level the clamp has already replaced",
    "nearest level": "you read the nearest level alone: trilinear blends the two levels "
    "around λ, so that nothing jumps where λ crosses a whole number",
    "⌊λ⌋ alone": "you read level ⌊λ⌋ alone: trilinear also reads the level above it, "
    "weighted by how far λ has gone towards it",
    "levels' weights swapped": "your levels' weights are swapped: the level λ is nearer must "
    "weigh more (at a whole λ, that level alone)",
    "halves": "you gave each of the two levels half: their weights follow λ, moving linearly "
    "from one level to the next",
    "no level weight": "each of your levels' texels add up to 1: the two levels are blended, "
    "so their weights are shared between them",
    "overwritten, zero weights skipped": "a texel read twice (wrapped onto itself at the "
    "border, or on a level one texel high or wide) kept the weight of its last read only: its "
    "weights add up",
    "overwritten": "a texel read twice (wrapped onto itself at the border, or on a level one "
    "texel high or wide) kept the weight of its last read only: its weights add up",
    "λ clamped to [0, q − 1]": "you clamped λ to [0, q − 1]: the last level q (1 × 1) is a "
    "level too, so λ is clamped to [0, q], and at λ ≥ q the fetch reads level q alone",
    "|λ|": "you took |λ|: a negative λ (the texture magnified) is clamped to 0, level 0 alone, "
    "not turned positive",
    "sizes halved rounding up": "your levels are level 0's size halved rounding up (5 → 3 → 2): "
    "GL halves rounding down (5 → 2 → 1); use each level's own (H, W) from `sizes`",
    "sizes read from the coarse end": "you read level k's size from the other end of `sizes`: "
    "`sizes` runs from level 0 (the finest) to the 1 × 1 level",
    "u flipped": "you flipped u (1 − u): the texture's column 0 lies at u = 0, so u is taken "
    "as it comes",
    "v flipped": "you flipped v (1 − v): the texture's row 0 lies at v = 0 (`texture[row, col]`, "
    "v down the rows; GL's first row of texel data is at t = 0), so v is taken as it comes",
    "(u, v) wrapped, not the indices": "you wrapped (u, v) into [0, 1) but not the texel "
    "indices: near the border the pair of centres around x still runs one past the first or "
    "last column; wrap the indices (modulo W) instead",
    "clamp as (u, v) clamped, then tiled": "with 'clamp' you clamped (u, v) to [0, 1] and then "
    "tiled the indices: at u = 0 the pair around x = −½ still reads the last column; clamp the "
    "indices to [0, W − 1] instead",
    "u·(W − 1)": "you put the first and last texel centres at u = 0 and u = 1 (x = u·(W − 1)): "
    "texel c's centre lies at u = (c + ½)/W, half a texel in from the border",
    "u·H": "you scaled u by the level's H: u runs along the W columns (x = u·W − ½), v along "
    "the H rows",
    "level 0's size halved in real numbers": "you scaled (u, v) by level 0's size halved 2ᵏ "
    "times in real numbers: a level's size is whole texels, the one `sizes` gives (GL's floor "
    "rule: 5 → 2 → 1, not 2.5)",
    "nearest texel on each level": "you read the nearest texel of each level alone "
    "(GL's NEAREST_MIPMAP_LINEAR): LINEAR_MIPMAP_LINEAR blends the four texels around (u, v) "
    "on each level",
    "fractions exchanged": "the two fractions are exchanged: x − ⌊x⌋ weighs the columns (along "
    "u) and y − ⌊y⌋ the rows",
    "x's fraction along y too": "you weighted the rows with x's fraction too: the rows' weights "
    "come from y − ⌊y⌋",
    "v's weights swapped": "along v your weights are swapped: the row at or above y weighs "
    "1 − (y − ⌊y⌋), the row below it y − ⌊y⌋",
    "u's weights swapped": "along u your weights are swapped: the column at or left of x "
    "weighs 1 − (x − ⌊x⌋), the column right of it x − ⌊x⌋",
    "repeat with fmod": "your row or column index is negative: C's remainder (`math.fmod`, "
    "`np.fmod`) keeps the sign; 'repeat' needs Python's %, which gives −1 % W = W − 1",
    "rows wrapped with W": "you wrapped the rows modulo W and the columns modulo H: rows repeat "
    "every H, columns every W",
    "rows tiled under clamp": "with 'clamp' you clamped the columns but tiled the rows: `wrap` "
    "holds for u and v alike",
    "rows clamped under repeat": "with 'repeat' you tiled the columns but clamped the rows: "
    "`wrap` holds for u and v alike",
    "keys (row, col, level)": "your keys are (row, col, level): the task asks (level, row, col)",
    "clamp as (u, v) clamped, the indices not": "with 'clamp' you clamped (u, v) to [0, 1] but "
    "not the texel indices: at u = 0 the pair around x = −½ still reads column −1; clamp the "
    "indices to [0, W − 1] instead",
    "both levels with ⌊λ⌋'s size": "you read level ⌊λ⌋ + 1 with level ⌊λ⌋'s size: each level "
    "has its own (H, W), `sizes[level]`",
    "levels numbered from the last": "you numbered the levels from the last: level 0 is the "
    "finest, the first of `sizes`",
    "both levels keyed as ⌊λ⌋": "you keyed the texels of level ⌊λ⌋ + 1 as level ⌊λ⌋: each "
    "texel's key holds its own level",
}


def _bad_key_fits(args, expected, got) -> bool | None:
    return None if not isinstance(got, dict) else _bad_key(args[0], got) is not None


def _bad_key(sizes, got):
    q = len(sizes) - 1
    for level, row, col in got:
        if not 0 <= level <= q:
            return (level, row, col), f"level {level} does not exist (levels 0 to q = {q})"
        h, w = sizes[level]
        if not (0 <= row < h and 0 <= col < w):
            return (level, row, col), (f"level {level} is {h} × {w} (H × W): rows 0 to "
                                       f"{h - 1}, columns 0 to {w - 1}")  # fmt: skip
    return None


def _bad_key_words(args, expected, got) -> str:
    key, why = _bad_key(args[0], got)
    return f"your texel {key} is not a texel: {why}"


def _sum_fits(args, expected, got) -> bool | None:
    if not isinstance(got, dict):
        return None
    return abs(sum(got.values()) - 1.0) > tolerance(args) and not _float16_fits(args, expected, got)


def _sum_words(args, expected, got) -> str:
    return (f"your weights add up to {num(sum(got.values()), 1.0)}: a fetch's weights add up to 1 "
            "(a texture of one colour everywhere filters to that colour)")  # fmt: skip


def _float16_fits(args, expected, got) -> bool | None:
    """Every weight within float16's rounding (2⁻¹¹ of the coordinates) and some beyond
    float32's: weights held in float16."""
    if not isinstance(got, dict):
        return None
    sizes, uv = args[0], args[1]
    h, w = sizes[0]
    scale = max(abs(float(uv[0])) * w, abs(float(uv[1])) * h, 1.0)
    return (_close(got, expected, 2.0**-10 * scale) and not _close(got, expected, tolerance(args))
            and not _split_alone(args, expected, got) and _decimals(got) is None)  # fmt: skip


def _decimals(got: dict) -> int | None:
    """The fewest decimals (1 to 5) every weight is rounded to, or None (r509 M2: weights
    rounded to 4 decimals were told "float16": the checker's rounding step names them)."""
    for d in range(1, 6):
        if all(abs(w - round(w, d)) <= 1e-12 for w in got.values()):
            return d
    return None


# -- r497: an unnamed failure split by level, then by axis ----------------------------------
def _per_level(weights: dict) -> dict[int, float]:
    out: dict[int, float] = {}
    for (k, _, _), w in weights.items():
        out[k] = out.get(k, 0.0) + w
    return out


def _level_alone(args, k: int) -> dict:
    """Level k's bilinear weights (summing to 1), keyed (k, row, col)."""
    sizes, uv, _, wrap = args
    return {(k, r, c): w for (_, r, c), w in reference([sizes[k]], uv, 0, wrap).items()}


def _own_level(got: dict, k: int, total: float) -> dict:
    return {key: w / total for key, w in got.items() if key[0] == k}


def _said(split: dict) -> str:
    shown = [f"level {k} {num(split[k])}" for k in sorted(split) if abs(split[k]) > TOL]
    return ", ".join(shown) or "nothing"


def _split_fits(args, expected, got) -> bool | None:
    if not isinstance(got, dict) or _bad_key(args[0], got) is not None:
        return None
    if factors(args, got) is not None:  # r509: the slips are named instead
        return None
    mine, right = _per_level(got), _per_level(expected)
    return any(abs(mine.get(k, 0.0) - right.get(k, 0.0)) > 4 * tolerance(args)
               for k in set(mine) | set(right))  # fmt: skip


def _split_words(args, expected, got) -> str:
    sizes, _, lod, _ = args
    q = len(sizes) - 1
    mine, right = _per_level(got), _per_level(expected)
    lam = min(max(float(lod), 0.0), q)
    words = (f"your texels add up, level by level, to {_said(mine)}, where λ = {num(lod)} "
             f"(kept within [0, q] = [0, {q}]: {num(lam)}) weighs {_said(right)}")  # fmt: skip
    levels = sorted(k for k in mine if abs(mine[k]) > TOL)
    if len(levels) == 2 and levels[1] == levels[0] + 1 and abs(sum(mine.values()) - 1) <= 1e-6:
        words += f" (your split is that of λ = {num(levels[0] + mine[levels[1]])})"
    inner = all(_close(_own_level(got, k, mine[k]), _level_alone(args, k), 4 * tolerance(args))
                for k in levels)  # fmt: skip
    if inner and levels:
        words += ": within each level your texels are right, the split between levels is not"
    return words


def _split_alone(args, expected: dict, got: dict) -> bool:
    """Every level's own texels right, scaled by a level weight that is not the right one
    rounded to float16 (r497 M2: λ's fraction rounded to 2 decimals was told "float16": only
    the split between the levels is off)."""
    mine, right = _per_level(got), _per_level(expected)
    if _bad_key(args[0], got) is not None or any(abs(m) <= TOL for m in mine.values()):
        return False
    if all(abs(mine[k] - float(np.float16(right.get(k, 0.0)))) <= 2.0**-11 for k in mine):
        return False
    return all(_close(_own_level(got, k, mine[k]), _level_alone(args, k), tolerance(args))
               for k in mine)  # fmt: skip


def _marginal(weights: dict, axis: int) -> dict[int, float]:
    out: dict[int, float] = {}
    for key, w in weights.items():
        out[key[axis]] = out.get(key[axis], 0.0) + w
    return {i: w for i, w in out.items() if abs(w) > TOL}


def _axis_fits(args, expected, got) -> bool | None:
    if not isinstance(got, dict) or _bad_key(args[0], got) is not None:
        return None
    if factors(args, got) is not None:  # r509: the slips are named instead
        return None
    return not _split_fits(args, expected, got)


def _axis_words(args, expected, got) -> str:
    sizes = args[0]
    right = _per_level(expected)
    tol = 4 * tolerance(args)
    for k in sorted(right):
        mine, theirs = _own_level(got, k, right[k]), _level_alone(args, k)
        if _close(mine, theirs, tol):
            continue
        h, w = sizes[k]
        parts = []
        for axis, name in ((2, "along u (columns)"), (1, "along v (rows)")):
            a, b = _marginal(mine, axis), _marginal(theirs, axis)
            if _close(a, b, tol):
                parts.append(f"{name} yours are right")
            else:
                said = lambda d: ", ".join(f"{i}: {num(d[i])}" for i in sorted(d)) or "none"  # noqa: E731
                parts.append(f"{name} the level's weights are {{{said(b)}}}, yours {{{said(a)}}}")
        return (f"level {k}'s weight is right, its texels are not: on level {k} ({h} × {w}), "
                + "; ".join(parts))  # fmt: skip
    return "your texels' weights differ within a level"


# -- r509 H1: slips named a level and an axis at a time -----------------------------------------
# A wrong answer no single knob gives (two slips, or one on one axis only) was told only "level
# 1's weight is right, its texels are not: ... along v (rows) the level's weights are ...". The
# fetch factors: the levels' weights (the split), then on each level a column weight times a
# row weight. Each factor is fitted to its own small catalogue of slips, and where every factor
# of the case is reproduced, the slips are named (the case's answer is then the one they give).
LEVEL_SLIPS = ("clamp q-1", "abs", "unclamped", "split first", "nearest", "floor alone",
               "halves", "swapped", "no level weight")  # fmt: skip
LEVEL_WORDS = {
    "clamp q-1": "λ clamped to [0, q − 1] (level q alone at λ ≥ q)",
    "abs": "|λ| (a negative λ is clamped to 0)",
    "unclamped": "λ not clamped to [0, q]",
    "split before the clamp": "λ split before the clamp",
    "split first": "λ split into level and fraction before the clamp",
    "nearest": "the nearest level alone (trilinear blends the two around λ)",
    "floor alone": "level ⌊λ⌋ alone (trilinear also reads the level above)",
    "halves": "each of the two levels weighted ½ (the weights follow λ)",
    "swapped": "the two levels' weights swapped (the nearer level weighs more)",
    "no level weight": "each level's texels adding up to 1 (the two levels share 1)",
}
AXIS = {2: ("u", "x", "W", "columns"), 1: ("v", "y", "H", "rows")}


def _axis_weights(s, n, wrap, slip, *, other, n0, k):
    """{index: weight} along one axis of a level of n texels at coordinate s, with ``slip``
    (a dict of this function's settings; {} is the right filter)."""
    if slip.get("flip"):
        s = 1 - s
    scale = {"other": other, "level 0": n0, "stretched": n - 1}.get(slip.get("scale"), n)
    x = s * scale + slip.get("origin", -0.5)
    if slip.get("scale") == "stretched":
        x = s * (n - 1)
    elif slip.get("scale") == "level 0 halved":
        x = (s * n0 - 0.5) / 2**k
    x0 = {"int": int, "round": lambda t: math.floor(t + 0.5)}.get(slip.get("pair"), math.floor)(x)
    f = x - x0
    if slip.get("weights") == "swapped":
        f = 1 - f
    elif slip.get("weights") == "smooth":
        f = f * f * (3 - 2 * f)
    pairs = ((x0, 1 - f), (x0 + slip.get("step", 1), f))
    if slip.get("weights") == "nearest":
        pairs = ((math.floor(x + 0.5), 1.0),)
    mode = slip.get("wrap", wrap)
    if (mode in ("abs", "mod n-1") and wrap == "clamp") or (mode == "mirror" and wrap == "repeat"):
        mode = wrap  # a slip of the other mode's code: this mode's indices are right
    out: dict[int, float] = {}
    for i, w in pairs:
        if w == 0:
            continue
        if mode == "abs":
            i = abs(i) % n
        elif mode == "mod n-1":
            i = i % max(n - 1, 1)
        elif mode == "mirror":
            i %= 2 * n
            i = i if i < n else 2 * n - 1 - i
        else:
            i = _wrapped(i, n, mode)
        out[i] = out.get(i, 0.0) + w
    return out


def _axis_slips(wrap: str) -> list[tuple[str, dict, str]]:
    """Each single-axis slip as (id, settings of :func:`_axis_weights`, words), the right
    filter first ("", {}); the words' {a} is u or v, {x} x or y, {n} W or H, {m} the other
    size, {c} columns or rows."""
    out: list[tuple[str, dict, str]] = [("", {}, "")]
    for flip in (False, True):
        for o in (-0.5, 0.0, 0.5, -0.25, 0.25, -0.75, -1.0, -1.5):
            if (flip, o) == (False, -0.5):
                continue
            said = [] if not flip else ["you flipped {a} (1 − {a}): {a} = 0 is the first of the "
                                        "{c}, so {a} is taken as it comes"]  # fmt: skip
            if o != -0.5:
                at = "" if o == 0 else f" {'+' if o > 0 else '−'} {abs(o):g}"
                said.append(f"your texel centres lie at {{x}} = {{a}}·{{n}}{at} ("
                            + ("texel corners; " if o == 0 else "") + "texel c's centre is "
                            "at {a} = (c + ½)/{n}, so {x} = {a}·{n} − ½)")  # fmt: skip
            name = ("flipped " if flip else "") + ("" if o == -0.5 else f"origin {o:+g}")
            out.append((name.strip(), {"flip": flip, "origin": o}, ", and ".join(said)))
    out += [
        (
            "scaled by the other size",
            {"scale": "other"},
            "you scaled {a} by the level's {m}: {a} counts the {n} {c}",
        ),
        (
            "level 0's size",
            {"scale": "level 0"},
            "you scaled {a} by level 0's {n} on every level: each level has its own {n}",
        ),
        (
            "centres at 0 and 1",
            {"scale": "stretched"},
            "you put the first and last centres at {a} = 0 and 1 ({x} = {a}·({n} − 1)): they lie "
            "half a texel in from the border",
        ),
        (
            "level 0's coordinate halved",
            {"scale": "level 0 halved"},
            "you halved level 0's {x} (({a}·{n}₀ − ½)/2ᵏ): level k's centres lie at "
            "{x} = {a}·{n}ₖ − ½, with its own {n}",
        ),
        (
            "weights swapped",
            {"weights": "swapped"},
            "your weights are swapped: the one of the {c} at or before {x} weighs "
            "1 − ({x} − ⌊{x}⌋), the next one {x} − ⌊{x}⌋",
        ),
        (
            "nearest",
            {"weights": "nearest"},
            "you read the nearest of the {c} alone: the two around {x} are blended",
        ),
        (
            "not linear",
            {"weights": "smooth"},
            "the right two {c}, but weights not linear in {x} (a smoothstep?): they are 1 − f "
            "and f, f = {x} − ⌊{x}⌋",
        ),
        (
            "int()",
            {"pair": "int"},
            "you rounded {x} towards zero (int()): left of the first centre the pair starts at "
            "−1 (⌊{x}⌋)",
        ),
        (
            "nearest first",
            {"pair": "round"},
            "you started the pair at the nearest centre: it starts at ⌊{x}⌋",
        ),
        ("step −1", {"step": -1}, "the pair's second texel is ⌊{x}⌋ − 1: it is ⌊{x}⌋ + 1"),
        ("abs", {"wrap": "abs"}, "index −1 became 1 (abs): 'repeat' gives −1 % {n} = {n} − 1"),
        (
            "modulo n − 1",
            {"wrap": "mod n-1"},
            "you wrapped modulo {n} − 1: the texture repeats every {n}",
        ),
    ]
    other = {"repeat": "clamp", "clamp": "repeat"}[wrap]
    out.append(("the other wrap", {"wrap": other},
                f"your {{c}} are {other}ed where `wrap` is {wrap!r}: `wrap` holds for u and v "
                "alike"))  # fmt: skip
    if wrap == "clamp":
        out.append(
            (
                "mirror",
                {"wrap": "mirror"},
                "your 'clamp' mirrors the {c}: it repeats the border texel outwards",
            )
        )
    return out


def _split_cands(args, got) -> list[str]:
    """The ids of :data:`LEVEL_SLIPS` that give the answer's level weights ("" first where
    they are right; "λ fitted" where only a λ of its own does); [] where none does."""
    sizes, _, lod, _ = args
    q = len(sizes) - 1
    mine = {k: w for k, w in _per_level(got).items() if abs(w) > TOL}
    tol = 4 * tolerance(args)

    def same(split):
        merged: dict[int, float] = {}
        for k, w in split:
            merged[k] = merged.get(k, 0.0) + w
        merged = {k: w for k, w in merged.items() if abs(w) > TOL}
        return set(merged) == set(mine) and all(abs(merged[k] - mine[k]) <= tol for k in mine)

    out = [""] if same(level_split(q, lod)) else []
    for how in LEVEL_SLIPS:
        split = _levels(q, float(lod), how)
        if split and all(0 <= k <= q for k, _ in split) and same(split):
            out.append(how)
    levels = sorted(mine)
    if ("" not in out and len(levels) == 2 and levels[1] == levels[0] + 1
            and abs(sum(mine.values()) - 1) <= tol):  # fmt: skip
        out.append("λ fitted")  # a λ of its own: says nothing where the split is right
    return out


def _level_cands(args, got, k, weight) -> dict[int, list[str]] | None:
    """{axis: ids of the slips that give level k's own weights along it}, None where they
    are not a column weight times a row weight."""
    sizes, uv, _, wrap = args
    own = {(r, c): w / weight for (lv, r, c), w in got.items() if lv == k and abs(w) > TOL}
    keyed = {(k, r, c): w for (r, c), w in own.items()}
    cols, rows = _marginal(keyed, 2), _marginal(keyed, 1)
    tol = 4 * tolerance(args) / max(abs(weight), 1e-3)
    if len(own) > len(rows) * len(cols) or any(
        abs(own.get((r, c), 0.0) - wr * wc) > tol
        for r, wr in rows.items()
        for c, wc in cols.items()
    ):
        return None
    h, w = sizes[k]
    out = {}
    for axis, mine, s, n, m, n0 in ((2, cols, uv[0], w, h, sizes[0][1]),
                                    (1, rows, uv[1], h, w, sizes[0][0])):  # fmt: skip
        out[axis] = [name for name, slip, _ in _axis_slips(wrap)
                     if _close(_axis_weights(float(s), int(n), wrap, slip, other=int(m),
                                             n0=int(n0), k=k), mine, tol)]  # fmt: skip
    return out


_FACTORS: dict = {}


def factors(args, got) -> dict | None:
    """The answer taken apart: {"split": ids, 2: {level: ids along u}, 1: {level: ids along
    v}} (ids of the slips that give each factor, "" for the right one), or None where the
    answer is not a split times, on each level, column weights times row weights (or a key
    is not a texel). Remembered per answer: every mistake below asks it of every case."""
    key = (id(args), id(got))
    hit = _FACTORS.get(key)
    if hit is not None and hit[0] is args and hit[1] is got:
        return hit[2]
    out = None
    if isinstance(got, dict) and _bad_key(args[0], got) is None:
        out = {"split": _split_cands(args, got), 2: {}, 1: {}}
        for k, weight in sorted(_per_level(got).items()):
            if abs(weight) <= TOL:
                continue
            axes = _level_cands(args, got, k, weight)
            if axes is None:
                out = None
                break
            out[2][k], out[1][k] = axes[2], axes[1]
        if out is not None and (not out["split"] or not all(
                c for axis in (1, 2) for c in out[axis].values())):  # fmt: skip
            out = None
    if len(_FACTORS) > 4096:
        _FACTORS.clear()
    _FACTORS[key] = (args, got, out)
    return out


def _factor_state(found: dict, factor, slip: str) -> tuple[bool, bool]:
    """(does ``slip`` give this factor, is the factor right) for "split" or an axis."""
    if factor == "split":
        cands = [found["split"]]
    else:
        cands = list(found[factor].values())
    return all(slip in c for c in cands), all("" in c for c in cands)


def _factor_phrase(args, got: dict, factor, slip: str) -> str:
    sizes, _, lod, wrap = args
    if factor == "split":
        if slip == "λ fitted":  # r497's words: the levels' sums, the λ they stand for
            return _split_words(args, reference(*args), got)
        return f"your split between the levels is {LEVEL_WORDS[slip]}"
    a, x, n, c = AXIS[factor]
    words = {name: w for name, _, w in _axis_slips(wrap)}[slip]
    return f"along {a}, " + words.format(a=a, x=x, n=n, m=AXIS[3 - factor][2], c=c)


def _slip_mistake(factor, slip: str) -> Mistake:
    """The mistake "``slip`` in ``factor``": it fits a failing answer where the slip gives
    that factor and the factor is wrong, and every other wrong factor has a slip of its own
    (named too); it contradicts an answer where it would change a factor that is right."""

    def fits(args, expected, got):
        found = factors(args, got)
        if found is None:
            return None
        gives, right = _factor_state(found, factor, slip)
        if slip == "λ fitted" and right:
            return None
        if right and same_weights(got, expected, args):
            # a passing answer: one the slip leaves alone counts for it; one it would change
            # counts for nothing, not against it (r509: a second slip, (W, H) with v flipped,
            # read a drawn 2 × 1 level right, and the flip, dropped, lost to "swapped")
            return True if gives else None
        if not gives:
            return False
        return True if not right else None

    def words(args, expected, got):
        found = factors(args, got)
        said = [_factor_phrase(args, got, factor, slip)]
        for other in ("split", 2, 1):
            if other == factor or _factor_state(found, other, "")[1]:
                continue
            said += _factor_words(args, got, found, other)
        return "; and ".join(said)

    kind = f"levels: {slip}" if factor == "split" else f"along {AXIS[factor][0]}: {slip}"
    kind = "levels weighed wrong" if slip == "λ fitted" else kind  # r497's kind
    # consistent: asked of the passing answers too (those it leaves alone count for it)
    return Mistake(kind, words, fits=fits, symptom=True, consistent=True)


def _per_level_fits(args, expected, got) -> bool | None:
    """Only where a wrong factor has no one slip of its own (several, or none on every level):
    elsewhere that slip's own mistake speaks."""
    found = factors(args, got)
    if found is None or same_weights(got, expected, args):
        return None
    for factor in ("split", 2, 1):
        cands = [found["split"]] if factor == "split" else list(found[factor].values())
        if all("" in c for c in cands):
            continue
        if len([c for c in cands[0] if c and all(c in other for other in cands)]) != 1:
            return True
    return None


def _factor_words(args, got, found, factor) -> list[str]:
    """What is said of a wrong factor: its slip where one gives it on every level, the slips
    that do where several do, else level by level."""
    cands = [found["split"]] if factor == "split" else list(found[factor].values())
    common = [c for c in cands[0] if c and all(c in other for other in cands)]
    where = "the levels" if factor == "split" else AXIS[factor][0]
    if len(common) == 1:
        return [_factor_phrase(args, got, factor, common[0])]
    if len(common) > 3:  # a level one texel wide: many slips give its one texel
        return [f"along {where} a slip too ({len(common)} slips give these weights here; "
                "the other failing cases tell which)"]  # fmt: skip
    if common:
        if factor == "split":
            common = [_split_short(got, c) for c in common]
        return [f"along {where} a slip, one of: {'; '.join(common)} (each gives these "
                "weights here; the other failing cases tell which)"]  # fmt: skip
    return [f"on level {k} " + _factor_phrase(args, got, factor, c[0])
            for k, c in sorted(found[factor].items()) if "" not in c]  # fmt: skip


def _split_short(got: dict, how: str) -> str:
    if how != "λ fitted":
        return LEVEL_WORDS[how]
    mine = {k: w for k, w in _per_level(got).items() if abs(w) > TOL}
    low = min(mine)
    return f"the split of λ = {num(low + mine[low + 1])}"


def _per_level_words(args, expected, got) -> str:
    found = factors(args, got)
    said = []
    for factor in ("split", 2, 1):
        if not _factor_state(found, factor, "")[1]:
            said += _factor_words(args, got, found, factor)
    return "; and ".join(said)


SLIPS = tuple(
    [_slip_mistake("split", how) for how in (*LEVEL_SLIPS, "λ fitted")]
    + [
        _slip_mistake(axis, name) for axis in (2, 1) for name, _, _ in _axis_slips("clamp") if name
    ]  # fmt: skip
    + [Mistake("slips by level", _per_level_words, fits=_per_level_fits, symptom=True)]
)

FLOAT16 = Mistake(
    "float16",
    "your weights are the right ones rounded to float16 (about 3 decimals): compute "
    "them in float64",
    fits=_float16_fits,
    only_whole=True,
)


def _rounded_fits(args, expected, got) -> bool | None:
    if not isinstance(got, dict) or _bad_key(args[0], got) is not None:
        return None
    d = _decimals(got)
    return (
        d is not None
        and not _close(got, expected, tolerance(args))
        and _close(got, expected, 10.0**-d + 1e-12)
    )  # fmt: skip (a sum of roundings)


def _rounded_words(args, expected, got) -> str:
    return (f"your weights are the right ones rounded to {_decimals(got)} decimals: a weight "
            "is a product of fractions, kept as it comes")  # fmt: skip


ROUNDED = Mistake("weights rounded", _rounded_words, fits=_rounded_fits, only_whole=True)


SYMPTOMS = (
    ROUNDED,
    FLOAT16,
    Mistake("no such texel", _bad_key_words, fits=_bad_key_fits, symptom=True),
    *SLIPS,
    Mistake("levels weighed wrong", _split_words, fits=_split_fits, symptom=True),
    Mistake("texels within a level", _axis_words, fits=_axis_fits, symptom=True),
    Mistake("weights do not add up to 1", _sum_words, fits=_sum_fits, symptom=True),
)


# -- reading and comparing answers -------------------------------------------------------------
MAX_TEXELS = 4096


def as_texel_weights(value) -> dict[tuple[int, int, int], float]:
    """The answer as {(level, row, col): weight} (ints and floats), read strictly."""
    refuse_none_and_text(value, "a dict {(level, row, col): weight}")
    if not isinstance(value, dict):
        raise WrongAnswerType(
            f"returned {'an' if type(value).__name__[0] in 'aeiou' else 'a'} "
            f"{type(value).__name__}, not a dict {{(level, row, col): weight}}: "
            "one entry per texel read, its weights added"
        )
    if len(value) > MAX_TEXELS:
        raise WrongAnswerType(f"returned {len(value)} texels: a fetch reads at most 8")
    out = {}
    for key, weight in value.items():
        if not (isinstance(key, tuple) and len(key) == 3
                and all(isinstance(k, (int, np.integer)) and not isinstance(k, (bool, np.bool_))
                        for k in key)):  # fmt: skip
            raise WrongAnswerType(
                f"has the key {key!r}: each key is a tuple of three whole numbers (level, "
                "row, col), such as (1, 0, 3)"
            )
        if isinstance(weight, (bool, np.bool_, str, bytes)) or weight is None:
            raise WrongAnswerType(f"gives texel {key!r} the weight {weight!r}, not a number")
        try:
            w = float(weight)
        except (TypeError, ValueError):
            raise WrongAnswerType(
                f"gives texel {key!r} the weight {weight!r}, not a number"
            ) from None
        out[tuple(int(k) for k in key)] = w
    return out


def tolerance(args) -> float:
    """1e-6, and float32's rounding of x = u·W (2⁻²² of it) where the point lies far out: a
    weight computed in float32 is right (a fraction of x = 40.3 is off by 4e-6 there)."""
    sizes, uv = args[0], args[1]
    h, w = sizes[0]
    return TOL + 2.0**-22 * max(abs(float(uv[0])) * w, abs(float(uv[1])) * h, 1.0)


def _close(a: dict, b: dict, tol: float = TOL) -> bool:
    for key in set(a) | set(b):
        x, y = a.get(key, 0.0), b.get(key, 0.0)
        if not abs(x - y) <= tol:  # NaN fails
            return False
    return True


def same_weights(got, expected, args) -> bool:
    """Every texel's weight within 1e-6 (a texel left out weighs 0), and no key that is not a
    texel of the pyramid (one read with weight 0 is no mistake)."""
    if not isinstance(got, dict) or _bad_key(args[0], got) is not None:
        return False
    return _close(got, expected, tolerance(args))


def match(got, value, args) -> bool:
    return isinstance(got, dict) and isinstance(value, dict) and _close(got, value, tolerance(args))


# -- cases -------------------------------------------------------------------------------------
def _case_words(sizes, uv, lod, wrap) -> str:
    shapes = ", ".join(f"{h}×{w}" for h, w in sizes)
    return f"levels {shapes}, uv={vec(uv)}, λ={num(lod)}, wrap={wrap!r}"


def _build(rng, word):
    """Borders in both modes on square, wide, tall and odd pyramids, λ below, between, on and
    above the levels; then random ones."""
    s44, s88 = gl_sizes(4, 4), gl_sizes(8, 8)
    wide, tall, odd = gl_sizes(2, 8), gl_sizes(8, 4), gl_sizes(3, 5)
    hard = [
        ("between two levels", s88, (0.4, 0.45), 1.25, "repeat"),
        ("magnified (λ < 0)", s88, (0.3, 0.6), -0.7, "repeat"),
        ("beyond the last level", s88, (0.3, 0.6), 3.4, "clamp"),
        ("λ on a level", s88, (0.7, 0.2), 2.0, "repeat"),
        ("λ = q exactly", s88, (0.7, 0.2), 3.0, "clamp"),
        ("u = 0.05 on 4 columns, repeat", s44, (0.05, 0.375), 0.0, "repeat"),
        ("u = 0.05 on 4 columns, clamp", s44, (0.05, 0.375), 0.0, "clamp"),
        ("left of the first centre, repeat (x in (−1, 0))", s88, (0.025, 0.3), 0.0, "repeat"),
        ("a corner, clamp, two levels", s88, (-0.3, 1.2), 0.5, "clamp"),
        ("a texel centre", s44, (0.625, 0.125), 0.0, "clamp"),
        ("a wide pyramid, level 1 one texel high", wide, (0.3, 0.9), 1.5, "repeat"),
        ("a wide pyramid, the bottom border, clamp", wide, (0.55, 0.9), 0.25, "clamp"),
        ("a tall pyramid, the right border, clamp", tall, (0.9, 0.3), 0.5, "clamp"),
        ("a tall pyramid, level 2 one texel wide", tall, (0.3, 0.6), 2.3, "repeat"),
        ("a 3×5 pyramid: level 1 is 1×2", odd, (0.5, 0.5), 0.6, "repeat"),
        ("a 3×5 pyramid, clamp", odd, (0.15, 0.9), 1.3, "clamp"),
        ("far outside, repeat", wide, (7.3, -2.6), 0.75, "repeat"),
        ("far outside, clamp", tall, (-5.2, 3.7), 1.75, "clamp"),
        ("inside the band where level 2's modes part", s88, (0.2, 0.5), 2.0, "clamp"),
        ("the same u, repeat", s88, (0.2, 0.5), 2.0, "repeat"),
        ("one level only (1×1)", [(1, 1)], (0.3, 0.8), 0.4, "repeat"),
        ("one level only (4×2)", [(4, 2)], (0.9, 0.05), -1.0, "repeat"),
        # r509 W1: λ ≥ q + 1 (a q taken as len(sizes), saved by a min on the upper level,
        # passed: the random λ stop below len(sizes))
        ("far above the pyramid (λ ≥ q + 1)", s88, (0.3, 0.6), 5.5, "repeat"),
        ("one level only (1×1), λ above it", [(1, 1)], (0.3, 0.6), 1.5, "clamp"),
    ]
    out = [(label, (sizes, (float(uv[0]), float(uv[1])), float(lod), wrap))
           for label, sizes, uv, lod, wrap in hard]  # fmt: skip
    for n in range(12):
        h, w = (int(v) for v in rng.integers(1, 17, size=2))
        sizes = gl_sizes(h, w)
        uv = tuple(float(t) for t in np.round(rng.uniform(-1.5, 2.5, size=2), 4))
        lod = float(np.round(rng.uniform(-1.0, len(sizes), 1)[0], 3))
        out.append((f"{word} {n + 1}", (sizes, uv, lod, ("repeat", "clamp")[n % 2])))
    return [(f"{label}: {_case_words(*args)}", args, reference(*args)) for label, args in out]


texel_cases = fixed_and_drawn(_build, SEED + 491)


# -- explanations ------------------------------------------------------------------------------
def _listing(weights: dict) -> str:
    keys = sorted(k for k, w in weights.items() if w != 0)
    if not keys:
        return "no texel"
    return ", ".join(f"{k}: {num(weights[k])}" for k in keys)


def explain(args, expected, got) -> str:
    """The texels where the two answers part (at most four), each with both weights."""
    keys = sorted(k for k in set(expected) | set(got)
                  if not abs(expected.get(k, 0.0) - got.get(k, 0.0)) <= TOL)  # fmt: skip
    if not keys:  # right weights on a texel that does not exist (read with weight 0)
        return f"the fetch reads {_listing(expected)}; yours also names {sorted(got)}"
    parts = [f"{k} weighs {num(expected.get(k, 0.0), got.get(k, 0.0))}, yours "
             f"{num(got.get(k, 0.0), expected.get(k, 0.0))}" for k in keys[:4]]  # fmt: skip
    more = f" (and {len(keys) - 4} more texels)" if len(keys) > 4 else ""
    n = len([k for k in expected if expected[k]])
    return f"the fetch reads {n} texel{'' if n == 1 else 's'}: " + "; ".join(parts) + more


RULE = (
    ": clamp λ to [0, q]; levels ⌊λ⌋ and ⌊λ⌋ + 1 weigh 1 − (λ − ⌊λ⌋) and λ − ⌊λ⌋; on each, "
    "x = u·W − ½, y = v·H − ½ with that level's own (H, W), the texels around (⌊x⌋, ⌊y⌋) "
    "wrapped as `wrap` says, weighted by the fractions; a texel read twice adds its weights"
)
HINT = (
    ": which levels does this λ need, and how much does each weigh? On each, where do that "
    "level's texel centres lie in u and v, which centres enclose (u, v), and what does `wrap` "
    "make of one beyond the border? Work this case through by hand"
)


def _rule(args, expected, got) -> str:
    return RULE


def raised_words(args, error) -> str:
    sizes, _, lod, _ = args
    q = len(sizes) - 1
    lam = min(max(float(lod), 0.0), q)
    if "division by zero" in error and lam == math.floor(lam) and (lam == q or q == 0):
        return (f": λ = {num(lod)} is at or beyond the last level q = {q}, where ⌊λ⌋ and the "
                "level above it are one level: a division by (upper − lower) = 0? There the "
                "fetch reads level q alone, with weight 1")  # fmt: skip
    if "by zero" in error:
        return (": a level 0 texels high or wide: did you halve level 0's size yourself? `sizes` "
                "gives each level's own (H, W), at least 1 × 1 (GL halves and rounds down, but "
                "never below 1)")  # fmt: skip
    if "index out of range" in error and lod >= q and lam == q:
        # r509 M1: told "λ lies outside the pyramid" where λ was clamped but level q + 1 read
        return (f": at λ = {num(lod)} your function read a level beyond the last, q = {q} "
                f"(len(sizes) − 1): the "
                f"fetch clamps λ to [0, q] and at λ = q reads level q alone (level ⌊λ⌋ + 1 = "
                f"{q + 1} does not exist, not even with weight 0)")  # fmt: skip
    if "index out of range" in error and not 0 <= lod < q:
        return (f": λ = {num(lod)} lies outside the pyramid's levels 0 to q = {q}: what does "
                "the fetch do with such a λ before it chooses levels?")  # fmt: skip
    return ""


# -- the figure ----------------------------------------------------------------------------------
def questions() -> str:
    """The task's "answer first" questions, answered from :func:`reference` (the pass figure)."""
    wide = reference(gl_sizes(2, 8), (0.3, 0.9), 1.5, "repeat")
    bands = []
    for lod in (0, 2):
        grid = [k / 1024 for k in range(513)]
        parts = [u for u in grid if reference(gl_sizes(8, 8), (u, 0.5), lod, "clamp")
                 != reference(gl_sizes(8, 8), (u, 0.5), lod, "repeat")]  # fmt: skip
        low = max(parts) + 1 / 1024
        bands.append(f"λ = {lod}: u < {num(low)}, u > {num(1 - low)}")
    sizes = ", ".join(f"{h}×{w}" for h, w in gl_sizes(3, 5))
    return (f"7.2's questions:\n(1) 2×8, λ = 1.5, (0.3, 0.9),\nrepeat: {len(wide)} texels\n"
            f"(2) clamp ≠ repeat on 8×8,\n{bands[0]}\n{bands[1]}\n(3) {sizes}")  # fmt: skip


def draw(ax, case, got):
    """Each level the fetch reads (before an answer: every level), in (u, v) from 0 to 1, the
    point (×); the expected weights on their texels once the method is earned or the answer is
    right, the student's in red on theirs."""
    from matplotlib.patches import Rectangle

    from . import tries

    sizes, uv, lod, wrap = case[1]
    expected = case[2]
    passed = got is not None and same_weights(got, expected, case[1])
    method = got is not None and (tries.hints_spent("texel_weights") or passed)
    shown = sorted({k[0] for k in expected}) if got is not None else list(range(len(sizes)))
    shown = shown[:4]
    artists = []
    gap = 0.35
    pu, pv = uv[0] % 1 if wrap == "repeat" else uv[0], uv[1] % 1 if wrap == "repeat" else uv[1]
    for n, level in enumerate(shown):
        h, w = sizes[level]
        ox = n * (1 + gap)
        for r in range(h):
            for c in range(w):
                key = (level, r, c)
                shade = expected.get(key, 0.0) if method else 0.0
                ax.add_patch(Rectangle((ox + c / w, r / h), 1 / w, 1 / h, edgecolor="#2b7bba",
                                       facecolor=(0.17, 0.48, 0.73, 0.15 + 0.6 * shade)
                                       if shade else "white", lw=0.8))  # fmt: skip
                mine = got.get(key, 0.0) if isinstance(got, dict) else 0.0
                if method and shade and w <= 4 and h <= 4:
                    artists.append(
                        ax.text(
                            ox + (c + 0.5) / w,
                            (r + 0.35) / h,
                            num(shade),
                            ha="center",
                            va="center",
                            fontsize="xx-small",
                        )
                    )
                if mine and not passed and w <= 4 and h <= 4:
                    artists.append(ax.text(ox + (c + 0.5) / w, (r + 0.7) / h, num(mine),
                                           ha="center", va="center", fontsize="xx-small",
                                           color="#d62728"))  # fmt: skip
        artists.append(ax.text(ox + 0.5, -0.04, f"level {level} ({h}×{w})", ha="center",
                               va="bottom", fontsize="x-small"))  # fmt: skip
        if 0 <= pu <= 1 and 0 <= pv <= 1:
            ax.plot([ox + pu], [pv], "x", color="black", markersize=7)
    right = len(shown) * (1 + gap) - gap
    if passed:
        artists.append(ax.text(right + 0.15, 0.5, questions(), ha="left", va="center",
                               fontsize="x-small"))  # fmt: skip
    ax.set_xlim(-0.1, right + (1.9 if passed else 0.1))
    ax.set_ylim(1.1, -0.2)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    where = "" if (pu, pv) == tuple(uv) else f" (× at {vec((pu, pv))}, the same texels)"
    text = f"{_case_words(*case[1])}{where}"
    if got is not None and not passed:
        text += "\nred: your weights" + ("; blue: the fetch's" if method else "")
    artists.append(ax.set_xlabel(text, fontsize="x-small"))
    return artists


TEXEL_WEIGHTS = Exercise(
    "texel_weights", texel_cases, as_texel_weights, same_weights, explain, _rule,
    variant_mistakes(_variants, MISTAKES, SYMPTOMS), match=match,
    answers=(PackageAnswer(sample, modules=FILTER_MODULES["trilinear"]),),
    draw=draw, hints=((RULE, HINT),), once=((RULE, ": as said for the first failing case"),),
    inputs_drawn=True, raised_words=raised_words, partial_names=True,
    example=10,  # the wide pyramid of the task's first question
)  # fmt: skip
