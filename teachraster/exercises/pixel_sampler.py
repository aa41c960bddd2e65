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
from .exercise import Exercise, Mistake, PackageAnswer, case_key, copies, variant_mistakes
from .pixel_level import FLOOR_UV, draw_lod_case, expected_lod, other_quads
from .quad_difference import FLOOR, inside, value_at
from .running import WrongAnswerType
from .scalars import num, vec
from .texture_filtering import (
    Pyramid,
    as_texel_value,
    expected_bilinear,
    expected_trilinear,
    no_level_above_q,
    same_value,
    trilinear_with,
)
from .tolerance import close


def _uv(xy, w, uv, x, y, **kw) -> np.ndarray:
    return np.array([value_at(xy, w, np.asarray(uv, float)[:, k], x, y, **kw) for k in (0, 1)])


def _unnormalised_uv(xy, w, uv, x, y) -> np.ndarray:
    """(u, v) weighted by λᵢ/wᵢ without dividing by their sum (r433 F3)."""
    lam = np.array([value_at(xy, w, e, x, y, affine=True) for e in np.eye(3)])
    return (lam / np.asarray(w, float)) @ np.asarray(uv, float)


def pixel_uv(xy, w, uv, row: int, col: int) -> np.ndarray:
    """(u, v) at pixel (row, col)'s own centre, perspective-correct (extrapolated)."""
    return _uv(xy, w, uv, col + 0.5, row + 0.5)


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
    # r405 F1: an RGB texture (its rng drawn last: the cases above stay as they were)
    rgb = Pyramid(mipmap(np.round(rng.uniform(0, 1, (8, 8, 3)), 3)))
    out[len(hard):len(hard)] = [
        (f"floor, pixel ({r}, {c}), 8×8 RGB pyramid: {why}", (rgb, xy, w, FLOOR_UV, r, c, wrap))
        for r, c, wrap, why in ((28, 14, "repeat", "three channels, λ between levels 0 and 1"),
                                (9, 15, "clamp", "three channels, towards the tip"))
    ]  # fmt: skip
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


_VARIANTS: dict = {}


def _remembered_variants(*args) -> dict:
    """:func:`_variants`, once per case (r509 S1: the table's memo keys no mip Pyramid, so
    every mistake computed every variant again: a wrong 7.4 cost 1.8–4.0 s of CPU)."""
    key = case_key(args)
    if key is None:
        return _variants(*args)
    if key not in _VARIANTS:
        if len(_VARIANTS) >= 256:
            _VARIANTS.clear()
        _VARIANTS[key] = _variants(*args)
    return _VARIANTS[key]


def _variants(pyramid, xy, w, uv, row, col, wrap) -> dict:
    """Each typical mistake's value on this case."""
    size = level_size(pyramid)
    lod = expected_lod(xy, w, uv, size, row, col)
    at = pixel_uv(xy, w, uv, row, col)
    r0, c0 = row - row % 2, col - col % 2
    lane = _uv(xy, w, uv, c0 + 0.5, r0 + 0.5)
    corner = _uv(xy, w, uv, col, row)
    affine = _uv(xy, w, uv, col + 0.5, row + 0.5, affine=True)

    def tri(u=at, lam=lod, mode=wrap, **kw):
        return trilinear_with(pyramid, u, lam, mode, **kw)

    def lod_with(size=size, rc=(row, col)):
        return expected_lod(xy, w, uv, size, *rc)

    one = np.ndim(pyramid[0]) == 2
    return {
        "channels averaged": None if one else float(np.mean(tri())),
        "first channel only": None if one else float(np.ravel(tri())[0]),
        # r450 M1: (u, v) taken modulo 1 by hand was told "is wrap passed on?"
        "(u, v) wrapped by hand": (
            None if wrap == "repeat" or np.all((at >= 0) & (at < 1)) else tri(u=np.mod(at, 1.0))
        ),
        "wrap fixed to 'repeat'": tri(mode="repeat"),
        "wrap fixed to 'clamp'": tri(mode="clamp"),
        "the quad's (u, v)": tri(u=lane),
        "affine (u, v)": tri(u=affine),
        "(u, v) at the corner": tri(u=corner),
        "λ/w not renormalised": tri(u=_unnormalised_uv(xy, w, uv, col + 0.5, row + 0.5)),
        "λ·w": tri(u=_uv(xy, w, uv, col + 0.5, row + 0.5, times_w=True)),
        "(u, v) in texels": tri(u=at * [size[1], size[0]]),
        "size read as (W, H)": tri(lam=expected_lod(xy, w, uv, size[::-1], row, col)),
        "the last level's size": tri(
            lam=expected_lod(xy, w, uv, np.shape(pyramid[-1])[:2], row, col)
        ),  # fmt: skip
        "level 1's size": tri(lam=lod_with(np.shape(pyramid[min(1, len(pyramid) - 1)])[:2])),
        "size (H, H)": tri(lam=lod_with((size[0], size[0]))),
        "(row, col) swapped in pixel_lod": tri(lam=lod_with(rc=(col, row))),
        "size (levels, levels)": tri(lam=lod_with((len(pyramid), len(pyramid)))),
        "(u, v) at (col, row)": tri(u=pixel_uv(xy, w, uv, col, row)),
        "(u, v) at (col, row), clamped": tri(u=_uv(xy, w, uv, row + 0.5, col + 0.5, clamp=True)),
        "(v, u)": tri(u=at[::-1]),
        "(u, v) at the quad's centre": tri(u=_uv(xy, w, uv, c0 + 1, r0 + 1)),
        "λ clamped to q − 1": tri(lam=min(max(lod, 0.0), len(pyramid) - 2)),
        "⌈λ⌉": tri(lam=float(np.ceil(lod))),
        "λ + ½": tri(lam=lod + 0.5),
        "λ/2": tri(lam=lod / 2),  # r462 H6
        "2λ": tri(lam=2 * lod),  # r450 H8: these three were told the generic questions
        "pyramid reversed": trilinear_with(list(pyramid)[::-1], at, lod, wrap),
        "(u, v) at (col + 1, row + 1)": tri(u=_uv(xy, w, uv, col + 1, row + 1)),
        "|λ|": tri(lam=abs(lod)),
        "λ not clamped": tri(clamp="weight"),
        "nearest level": tri(levels="nearest"),
        "⌊λ⌋'s level alone": tri(levels="lower"),
        "level 0 only": tri(levels="finest"),
    }


def _weight_sum(args) -> float:
    """Σ λᵢ/wᵢ at the pixel's centre of the case ``args``."""
    _, xy, w, _, row, col, _ = args
    return float(np.sum(_unnormalised_uv(xy, w, np.ones((3, 1)), col + 0.5, row + 0.5)))


def _channels(how: str):
    def words(args, expected, got) -> str:
        n = np.size(expected)
        return (f"your sample has 1 channel where the texture has {n}: {how}; what does 7.3's "
                f"trilinear return on an (H, W, {n}) pyramid?")  # fmt: skip

    return words


def _fixed_wrap(args, expected, got) -> str:
    other = "clamp" if args[6] == "repeat" else "repeat"
    return (f"you filtered with wrap={other!r} where this case's wrap is {args[6]!r}: is the "
            "wrap argument passed on to trilinear?")  # fmt: skip


def _swapped_centre(args, expected, got) -> str:
    return (f"you took (u, v) at the centre of pixel ({args[5]}, {args[4]}): (row, col) "
            "swapped; x runs along a row (col + ½), y down the rows (row + ½)")  # fmt: skip


MISTAKES = {
    "channels averaged": _channels("you averaged its channels into one number"),
    "first channel only": _channels("you kept its first channel alone"),
    "(u, v) wrapped by hand": lambda a, e, g: (
        f"you wrapped the pixel's (u, v) = {vec(pixel_uv(*a[1:6]))} into [0, 1) yourself: "
        f"wrapping is what trilinear's `wrap` does, and with wrap={a[6]!r} a (u, v) beyond the "
        "texture reads its border texels, not the other side: pass (u, v) unchanged"
    ),
    "wrap fixed to 'repeat'": _fixed_wrap,
    "wrap fixed to 'clamp'": _fixed_wrap,
    "the quad's (u, v)": lambda a, e, g: (
        f"you filtered at the (u, v) of the quad's upper-left "
        f"lane: the quad shares one λ, but each pixel is shaded at its own (u, v); which (u, v) "
        f"belongs to pixel ({a[4]}, {a[5]})?"
    ),
    "affine (u, v)": "your (u, v) at the pixel is interpolated affinely: which interpolation "
    "does a texture coordinate get (lesson 04), the same as 7.1's lanes?",
    "λ/w not renormalised": lambda a, e, g: (
        f"your weights λᵢ/wᵢ do not sum to 1 (here {num(_weight_sum(a))}): perspective-correct "
        "weights are λᵢ/wᵢ divided by their sum (lesson 04)"
    ),
    "λ·w": "your (u, v) is weighted by λᵢ·wᵢ: perspective divides by w, the weights are "
    "λᵢ/wᵢ over their sum (lesson 04)",
    "(u, v) in texels": lambda a, e, g: (
        f"you passed (u, v) in texels (times W = {np.shape(a[0][0])[1]}, H = "
        f"{np.shape(a[0][0])[0]}): trilinear takes (u, v) normalised, 0–1 across the texture"
    ),
    "(u, v) at the corner": "you took (u, v) at the pixel's corner (col, row): where is a pixel "
    "shaded?",
    "size read as (W, H)": lambda a, e, g: (
        f"your λ reads the texture's size as (W, H): level "
        f"0 is {np.shape(a[0][0])[0]} rows × {np.shape(a[0][0])[1]} columns, and 7.1's `size` is "
        "`texture.shape[:2]`"
    ),
    "the last level's size": lambda a, e, g: (
        f"your λ is 7.1's minus {len(a[0]) - 1}: the steps in texels of the last, 1 × 1 level "
        f"(its size passed to pixel_lod), or {len(a[0]) - 1} subtracted from λ? λ counts "
        "texels of level 0, and 7.1's `size` is level 0's"
    ),
    "level 1's size": "your λ is 7.1's minus 1: the steps in texels of level 1 (its size, "
    "half level 0's, passed to pixel_lod), or 1 subtracted from λ? λ counts texels of level 0, "
    "and 7.1's `size` is level 0's",
    "size (H, H)": lambda a, e, g: (
        f"your size is ({np.shape(a[0][0])[0]}, {np.shape(a[0][0])[0]}): len(level 0) counts its "
        f"rows (H) only; this level 0 is {np.shape(a[0][0])[0]} × {np.shape(a[0][0])[1]}, and "
        "7.1's `size` is (H, W)"
    ),
    "(row, col) swapped in pixel_lod": lambda a, e, g: (
        f"your λ is that of pixel ({a[5]}, {a[4]}): you passed (col, row) to pixel_lod, whose "
        "arguments are (…, row, col)"
    ),
    "size (levels, levels)": lambda a, e, g: (
        f"your size is ({len(a[0])}, {len(a[0])}): len(pyramid) counts its levels; level 0 is "
        f"{np.shape(a[0][0])[0]} × {np.shape(a[0][0])[1]} texels, and 7.1's `size` is (H, W)"
    ),
    "(u, v) at (col, row)": _swapped_centre,
    "(u, v) at (col, row), clamped": _swapped_centre,
    "(v, u)": "you filtered at (v, u): trilinear takes (u, v), u across the texture",
    "(u, v) at the quad's centre": lambda a, e, g: (
        f"you filtered at the (u, v) of the quad's centre: the quad shares one λ, but each "
        f"pixel is shaded at its own (u, v); which (u, v) belongs to pixel ({a[4]}, {a[5]})?"
    ),
    "λ clamped to q − 1": lambda a, e, g: (
        f"you clamped λ to {len(a[0]) - 2}, one level below the top: this pyramid's levels are "
        f"0–{len(a[0]) - 1}; which level serves a λ above the top?"
    ),
    "⌈λ⌉": "that is the level ⌈λ⌉, rounded up: where λ crosses a whole number the picture "
    "jumps; 7.3's trilinear blends the two levels around λ itself",
    "λ + ½": "your λ is 7.1's plus ½ (a bias, or rounding to the nearer level prepared): "
    "7.3's trilinear takes λ itself",
    "λ/2": "your λ is half 7.1's: 7.3's trilinear takes 7.1's λ itself",
    "2λ": "your λ is twice 7.1's (log2 ρ² for log2 ρ?): 7.3's trilinear takes 7.1's λ itself",
    "pyramid reversed": "you filtered the pyramid reversed: level 0, pyramid[0], is the "
    "full-size texture and the last level is 1 × 1; λ counts levels from level 0",
    "(u, v) at (col + 1, row + 1)": lambda a, e, g: (
        f"you took (u, v) at ({a[5] + 1}, {a[4] + 1}) in (x, y), the pixel's lower-right "
        f"corner: pixel ({a[4]}, {a[5]}) is shaded at its centre (col + ½, row + ½)"
    ),
    "|λ|": "your λ is |λ|: the texture is magnified here (λ < 0, level 0); a negative λ "
    "is clamped to 0, not turned positive",
    "λ not clamped": "λ lies outside the pyramid here: what must the sampler do with it before "
    "choosing levels (7.3)?",
    "nearest level": "that is the nearest level alone: where λ crosses a whole number the "
    "picture jumps (a seam on the floor); 7.3's trilinear blends the two levels around λ",
    "⌊λ⌋'s level alone": "that is the level ⌊λ⌋ alone, the finer of the two around λ: "
    "where λ crosses a whole number the picture jumps (a seam on the floor); 7.3's "
    "trilinear blends the two levels",
    "level 0 only": "that is level 0 alone, whatever λ: this pixel's footprint spans several "
    "texels of level 0 (the texture aliases); filter at the λ of 7.1",
}


#: The student's pixel_sample whose check is running (set by :func:`_call`): 7.4 composes the
#: student's own 7.1 and 7.3, and a failure is blamed on one of those where it is wrong (r405 F2).
#: "raised in" holds, by case (:func:`.exercise.case_key` of its arguments), where the
#: student's function raised on that case and with which arguments (r426 F1: one record, the
#: last call's, was read for every case after all had run, so each raising case quoted another
#: case's (u, v) and λ).
_RUNNING: dict = {"raised in": {}}


def _call(fn, args):
    """The student's answer on one case, the function noted for :func:`_own`; where it raises,
    the arguments of the student's own 7.1/7.2/7.3 function it raised in, recorded for this
    case at that moment, for :func:`_raised`."""
    if _RUNNING.get("fn") is not getattr(fn, "fn", fn):
        _RUNNING["raised in"] = {}  # another function: no case of the last one's is read
    _RUNNING["fn"] = getattr(fn, "fn", fn)  # the checker's recorder holds it as ``fn``
    key = case_key(args)  # before the call: the student may write into the arguments
    records = _RUNNING["raised in"]
    records.pop(key, None)
    try:
        answer = fn(*args)
    except Exception as exc:
        if key is not None:
            records[key] = _raised_in(exc)
        raise
    if answer is None:  # r433 F1: say which of their own functions gave the None
        words = _none_from_own(args)
        if words is not None:
            raise WrongAnswerType(words)
    return as_sample(answer)


def as_sample(value) -> np.ndarray:
    """A number or one value per channel: an array of 2 or more axes (a (1, 1) or (1, 3) row
    of barycentric's kept) is not, as docs/exercises.md says shapes must match (r450 S1)."""
    try:
        shape = np.shape(value)
    except Exception:  # noqa: BLE001 - as_texel_value explains what this is
        shape = ()
    if len(shape) >= 2 and all(n == 1 for n in shape[:-1]):
        raise WrongAnswerType(f"returned an array of shape {shape}: the sample is a number, or "
                              "one value per channel, as trilinear returns it (a (1, …) row of "
                              "barycentric's kept? index it [0])")  # fmt: skip
    return as_texel_value(value)


#: The student's own functions 7.4 calls, and the arguments of each that the words quote.
CALLEES = {"trilinear": ("(u, v)", "λ"), "pixel_lod": (), "bilinear": ("(u, v)",)}


def _raised_in(exc) -> tuple[str, dict] | None:
    """(name, {argument: value}) of the outermost of the student's own functions (7.1's
    pixel_lod, 7.3's trilinear, the bilinear it calls) that ``exc`` was raised in, or None
    (r418 F3: a NaN (u, v) passed to the student's trilinear was told as a bare
    "ValueError: cannot convert float NaN to integer")."""
    tri = _own("trilinear")
    own = {"pixel_lod": _own("pixel_lod"), "trilinear": tri,
           "bilinear": None if tri is None else _own("bilinear", getattr(tri, "fn", tri))}  # fmt: skip
    codes = {getattr(f, "__code__", None): name for name, f in own.items() if f is not None}
    frames = []  # outermost first
    tb = exc.__traceback__
    while tb is not None:
        name = codes.get(tb.tb_frame.f_code)
        if name is not None:
            code, held = tb.tb_frame.f_code, tb.tb_frame.f_locals
            values = [held.get(v) for v in code.co_varnames[1 : code.co_argcount]]
            said = dict(zip(CALLEES[name], values))
            frames.append((name, {k: None if v is None else np.array(v, dtype=float, copy=True)
                                  for k, v in said.items() if v is None or _numbers(v)}))  # fmt: skip
        tb = tb.tb_next
    if not frames:
        return None
    # r426 F1: the outermost that got a NaN (where it came in), else the innermost (their
    # bilinear raising inside their trilinear was blamed on the trilinear, whose check passes)
    # r433 F1: a None argument is kept apart from NaN (np.array(None, float) is nan)
    bad = [f for f in frames
           if not all(v is not None and np.all(np.isfinite(v)) for v in f[1].values())]  # fmt: skip
    name, values = bad[0] if bad else frames[-1]
    outer = frames[0][0]
    return (name if name == outer else f"{name} (which your {outer} calls)"), values


def _numbers(value) -> bool:
    try:
        return np.asarray(value, dtype=float).size <= 4
    except (TypeError, ValueError):
        return False


def _own(name: str, fn=None):
    """The student's own function ``name`` (7.1's pixel_lod, 7.3's trilinear) that their
    pixel_sample (or ``fn``: 7.2's bilinear that their trilinear calls) calls, found among
    its globals or its closure; None if it calls none."""
    fn = _RUNNING.get("fn") if fn is None else fn
    code = getattr(fn, "__code__", None)
    if code is None or name not in code.co_names + code.co_freevars:
        return None
    held = dict(zip(code.co_freevars, [c.cell_contents for c in fn.__closure__ or ()]))
    found = held.get(name, getattr(fn, "__globals__", {}).get(name))
    return found if callable(found) else None


def _own_lod(args):
    """(the student's pixel_lod's λ, 7.1's λ) on this case, or None if theirs is right."""
    pyramid, xy, w, uv, row, col, _ = args
    mine = _own("pixel_lod")
    if mine is None:
        return None
    right = expected_lod(xy, w, uv, level_size(pyramid), row, col)
    got = float(np.ravel(mine(xy, w, uv, level_size(pyramid), row, col))[0])
    return None if close(got, right, 1e-5) else (got, right)


def _own_trilinear(args):
    """(the student's trilinear, 7.3's) at this pixel's λ and (u, v), or None if right."""
    pyramid, xy, w, uv, row, col, wrap = args
    mine = _own("trilinear")
    if mine is None:
        return None
    at = pixel_uv(xy, w, uv, row, col)
    lod = expected_lod(xy, w, uv, level_size(pyramid), row, col)
    right = expected_trilinear(pyramid, at, lod, wrap)
    got = np.asarray(mine(pyramid, at.copy(), lod, wrap), dtype=float)
    return None if same_value(got, right, None) else (got, right, lod, at)


def _own_bilinear(args):
    """(the student's bilinear, 7.2's, the level) at this pixel's (u, v) on the first level
    trilinear reads where they differ, or None (r415 F2: a wrong 7.2 was blamed on 7.3)."""
    pyramid, xy, w, uv, row, col, wrap = args
    tri = _own("trilinear")
    mine = None if tri is None else _own("bilinear", getattr(tri, "fn", tri))
    if mine is None:
        return None
    at = pixel_uv(xy, w, uv, row, col)
    lam = min(max(expected_lod(xy, w, uv, level_size(pyramid), row, col), 0.0), len(pyramid) - 1)
    for k in sorted({int(np.floor(lam)), min(int(np.floor(lam)) + 1, len(pyramid) - 1)}):
        try:  # a helper of another signature is no 7.2 bilinear
            got = np.asarray(mine(pyramid[k], at.copy(), wrap), dtype=float)
        except Exception:  # noqa: BLE001 - the student's code
            return None
        right = expected_bilinear(pyramid[k], at, wrap)
        if not same_value(got, right, None):
            return got, right, k, at
    return None


def _fix_bilinear(args, expected, got) -> str:
    mine, right, k, at = _own_bilinear(args)
    return (f"your bilinear gives {_shown(mine, right)} on level {k} at (u, v) = {vec(at)} "
            f"where 7.2's answer is {_shown(right, mine)}: 7.2's check fails on it; fix "
            "bilinear first, then check this again")  # fmt: skip


def _raised(args, error) -> str:
    """r415 F2: the full shape (H, W, C) of an RGB level passed as 7.1's size; r418 F3: the
    student's own function it raised in, with the arguments it got (a NaN (u, v) named)."""
    if "raised ValueError" in error and "unpack" in error and np.ndim(args[0][0]) == 3:
        return (f": this pyramid is RGB, np.shape(level 0) is {np.shape(args[0][0])}; did your "
                "pixel_lod get it as `size`, and unpack it as (H, W)? 7.1's `size` is "
                "`shape[:2]`")  # fmt: skip
    inside = _RUNNING["raised in"].get(case_key(args))
    return "" if inside is None else _raised_inside(*inside, args, error)


def _raised_inside(name: str, values: dict, args, error: str) -> str:
    """The words for an exception raised in the student's own ``name`` called with
    ``values`` on the case of ``args``: a None met in an operation (a function without
    ``return``), and 7.3's words for a level above q, before the generic "does its own check
    pass?" (r426 F1: a missing upper clamp in their trilinear was a bare IndexError)."""
    nones = [k for k, v in values.items() if v is None]
    if nones:
        return _none_inside(name, nones)
    bad = [k for k, v in values.items() if not np.all(np.isfinite(v))]
    shown = ", ".join(f"{k} = {vec(v) if v.size > 1 else num(float(v))}" for k, v in values.items())
    bare = name.split(" (")[0]
    if not bad and "NoneType" in error:
        return (f": it raised inside your {name}, called with {shown}, on a None: does each of "
                "your functions return its value (one without `return` gives None)? Their own "
                "checks say which")  # fmt: skip
    if not bad and bare == "trilinear" and "λ" in values:
        above = no_level_above_q((args[0], None, float(values["λ"]), None), error)
        if above:
            return f": it raised inside your trilinear, called with {shown}{above}"
    if bad and "(u, v)" in bad:
        return (f": it raised inside your {name}, called with {shown}: the (u, v) passed to "
                f"{bare} is not a number; a 0/0 in your weights (a sum that is 0), or a NaN "
                "carried on?")  # fmt: skip
    if bad:
        return (f": it raised inside your {name}, called with {shown}: λ is not a number; what "
                "did your pixel_lod return here?")  # fmt: skip
    return (f": it raised inside your {name}, called with {shown}" if shown else
            f": it raised inside your {name}") + "; does its own check pass?"  # fmt: skip


def _none_inside(name: str, nones: list) -> str:
    """r433 F1: a None argument (a helper without ``return``) was told as "λ = nan"."""
    if nones == ["λ"]:
        return (f": it raised inside your {name}, called with λ = None: your pixel_lod returned "
                "nothing here (a missing `return`?); 7.1's check says so")  # fmt: skip
    said = " and ".join(f"{k} = None" for k in nones)
    return (f": it raised inside your {name}, called with {said}: the function that computes "
            f"{' and '.join(nones)} returned nothing (a missing `return`?)")  # fmt: skip


def _none_from_own(args) -> str | None:
    """r433 F1: where the student's pixel_sample returned None, the words for their own 7.1
    pixel_lod or 7.3 trilinear returning None on this case (the None came from there), or
    None."""
    pyramid, xy, w, uv, row, col, wrap = copies(args)
    lod = expected_lod(xy, w, uv, level_size(pyramid), row, col)
    at = pixel_uv(xy, w, uv, row, col)
    calls = (("pixel_lod", "7.1", (xy, w, uv, level_size(pyramid), row, col), ""),
             ("trilinear", "7.3", (pyramid, at.copy(), lod, wrap),
              f" at λ = {num(lod)}, (u, v) = {vec(at)}"))  # fmt: skip
    for name, task, call_args, where in calls:
        mine = _own(name)
        if mine is None:
            continue
        try:
            value = mine(*call_args)
        except Exception:  # noqa: BLE001 - the student's code
            continue
        if value is None:
            return (f"returned None, which came from your {name}: it returns None{where} (a "
                    f"missing `return`?); {task}'s check fails on it")  # fmt: skip
    return None


def _fix_lod(args, expected, got) -> str:
    mine, right = _own_lod(args)
    return (f"your pixel_lod gives λ = {num(mine, right)} here where 7.1's answer is "
            f"{num(right, mine)} (size {level_size(args[0])}, pixel ({args[4]}, {args[5]})): "
            "7.1's check fails on it; fix pixel_lod first, then check this again")  # fmt: skip


def _fix_trilinear(args, expected, got) -> str:
    mine, right, lod, at = _own_trilinear(args)
    tri = _own("trilinear")
    if _own("texel_weights", getattr(tri, "fn", tri)) is not None:  # r491: 7.3 is given
        return (f"7.3's trilinear, adding up your texel_weights, gives {_shown(mine, right)} at "
                f"λ = {num(lod)}, (u, v) = {vec(at)} where the right texels give "
                f"{_shown(right, mine)}: 7.2's check fails on it; fix texel_weights first, then "
                "check this again")  # fmt: skip
    return (f"your trilinear gives {_shown(mine, right)} at λ = {num(lod)}, (u, v) = {vec(at)} "
            f"where 7.3's answer is {_shown(right, mine)}: 7.3's check fails on it; fix "
            "trilinear first, then check this again")  # fmt: skip


#: Checked before the table: a wrong 7.1 or 7.3 is named there, not as this task's glue.
OWN = (
    Mistake("your pixel_lod (7.1)", _fix_lod, fits=lambda a, e, g: _own_lod(a) is not None),
    Mistake("your bilinear (7.2)", _fix_bilinear,
            fits=lambda a, e, g: _own_bilinear(a) is not None),
    Mistake("your trilinear (7.3)", _fix_trilinear,
            fits=lambda a, e, g: _own_trilinear(a) is not None),
)  # fmt: skip


RULE = (
    ": λ = 7.1's pixel_lod of the triangle at this pixel, with the size of level 0; (u, v) "
    "perspective-correct at this pixel's own centre; 7.3's trilinear of the pyramid there"
)
HINT = (
    ": which of your functions gives λ here, with which size; at which point is this pixel's "
    "(u, v) taken; which function filters the pyramid at that λ, with which wrap mode?"
)


def _value(fn, args):
    """The student's ``fn`` on ``args`` as an array of numbers, or None (it raised, or gave
    none)."""
    try:
        value = np.asarray(fn(*args), dtype=float)
    except Exception:  # noqa: BLE001 - the student's code: no value
        return None
    return value if np.all(np.isfinite(value)) else None


def _not_tried(fn, args, expected, got) -> str | None:
    """Why the failing value ``got`` shows no attempt at filtering this pixel (the words, with
    :data:`HINT`), or None for an attempt (r418 F1: ``pyramid[-1][0, 0]`` and then
    ``pyramid[0][row % 2, col % 2]`` were two tries that unlocked the steps). Any filter mixes
    texels with weights summing to 1, so a pyramid 1 brighter gives a value 1 brighter; and a
    sampler follows (u, v): where 1/3 of a texel added to every vertex's (u, v) moves the
    filtered value, an attempt's value moves too."""
    if fn is None or got is None:
        return None
    pyramid, xy, w, uv, row, col, wrap = args
    brighter = (Pyramid([np.asarray(level, float) + 1 for level in pyramid]), *copies(args[1:]))
    lit = _value(fn, brighter)
    if lit is not None and np.shape(lit) == np.shape(got) and np.allclose(lit, got, rtol=1e-9):
        return (f": with every texel of this pyramid 1 brighter your value is still "
                f"{_shown(got, got)}: does your function read the pyramid?" + HINT[1:])  # fmt: skip
    if lit is None or np.shape(lit) != np.shape(got) or not np.allclose(lit, got + 1, atol=1e-4):
        return (": with every texel of this pyramid 1 brighter a filtered value is 1 brighter "
                "(a filter's weights sum to 1); yours goes from "
                f"{_shown(got, got)} to {'no value' if lit is None else _shown(lit, lit)}:"
                + HINT[1:])  # fmt: skip
    h, wt = level_size(pyramid)
    shift = np.asarray(uv, float) + [1 / (3 * wt), 1 / (3 * h)]  # the same λ, (u, v) moved
    moved = (*copies((pyramid, xy, w)), shift, row, col, wrap)
    right = expected_sample(*moved)
    if np.allclose(right, expected, rtol=0, atol=1e-9):
        return HINT  # nothing here to tell a filter by: not counted
    mine = _value(fn, moved)
    if mine is not None and np.shape(mine) == np.shape(got) and np.allclose(mine, got, atol=1e-9):
        return (f": with 1/3 of a texel added to every vertex's (u, v) the filtered value "
                f"moves from {_shown(expected, right)} to {_shown(right, expected)}, yours stays "
                f"{_shown(got, got)}: does your value follow this pixel's (u, v)?" + HINT[1:])  # fmt: skip
    return _same_elsewhere(fn, args, expected, got) or _moved_together(fn, args, got)


def _moved_together(fn, args, got) -> str | None:
    """The words for a value that changes where the triangle and the pixel move together by
    one quad (2 pixels right and down: the same λ, the same (u, v)), or None (r433 F2: junk
    mixing a vertex's (u, v) with the pixel's row and col unlocked the steps)."""
    pyramid, xy, w, uv, row, col, wrap = args
    moved = (*copies((pyramid,)), np.asarray(xy, float) + 2, *copies((w, uv)), row + 2, col + 2,
             wrap)  # fmt: skip
    mine = _value(fn, moved)
    if mine is not None and np.shape(mine) == np.shape(got) and np.allclose(mine, got, atol=1e-4):
        return None
    return (f": with the triangle and the pixel moved together by one quad (2 pixels right and "
            f"down, to pixel ({row + 2}, {col + 2})) the filtered value stays the same; yours "
            f"goes from {_shown(got, got)} to {'no value' if mine is None else _shown(mine, mine)}"
            ": does your value depend on the pixel's place in the triangle only (its λ, its "
            "(u, v))?" + HINT[1:])  # fmt: skip


def _same_elsewhere(fn, args, expected, got) -> str | None:
    """The words for a value that stays where the pixel moves to another quad of the triangle
    and the filtered value changes, or None (r426 F2: the pyramid filtered at the mean of the
    vertices' (u, v) with λ = 0, then level 0 at vertex 0's (u, v), read neither the pixel nor
    the triangle's position, and unlocked the steps)."""
    pyramid, xy, w, uv, row, col, wrap = args
    for r, c in other_quads(xy, row, col):
        right = expected_sample(*copies((pyramid, xy, w, uv)), r, c, wrap)
        if np.allclose(right, expected, rtol=0, atol=1e-6):
            continue
        mine = _value(fn, (*copies((pyramid, xy, w, uv)), r, c, wrap))
        if mine is None or np.shape(mine) != np.shape(got) or not np.allclose(mine, got, atol=1e-9):
            return None
        return (f": at pixel ({r}, {c}), another quad of this triangle, the filtered value is "
                f"{_shown(right, expected)}, here {_shown(expected, right)}; yours is "
                f"{_shown(got, got)} at both: does your value depend on the pixel (its λ, its "
                "(u, v))?" + HINT[1:])  # fmt: skip
    return None


def _rule(args, expected, got) -> str:
    """The steps (staged: :data:`RULE` until two answers failed), but only for a failing try
    that filters the pyramid at some (u, v) (:func:`_not_tried`): other tries never count
    towards them (r415 F1, r418 F1)."""
    words = _not_tried(_RUNNING.get("fn"), args, expected, got)
    return RULE if words is None else words


def sample_questions(pyramid) -> str:
    """7.4's questions answered on 7.1's floor with ``pyramid``: where pixel (27, 3), the one
    covered pixel of its quad, gets its λ and (u, v), and the values of two pixels of one
    quad (r418 P2: the questions had been the tip's level, 7.3's own, and one the task's
    words answered)."""
    xy, w, _ = FLOOR
    size = level_size(pyramid)
    lod = expected_lod(xy, w, FLOOR_UV, size, 27, 3)
    own = pixel_uv(xy, w, FLOOR_UV, 27, 3)
    lane = _uv(xy, w, FLOOR_UV, 2.5, 26.5)
    a, b = (expected_sample(pyramid, xy, w, FLOOR_UV, r, c, "repeat") for r, c in ((28, 14), (29, 15)))  # fmt: skip
    same = "the same" if np.allclose(a, b) else "different"
    return (
        f"7.4: (27, 3) gets its quad's λ = {num(lod)}, from the (u, v) of the three helpers "
        "alone (upper left, upper right, lower left; its own lane takes no part); the "
        "texture is read at its own centre (3.5, 27.5), "
        f"(u, v) = {vec(own)}, not at a helper's (upper-left: {vec(lane)}): the pixel shows "
        "the texture where it lies, and the helpers only give λ its steps. (28, 14) and "
        f"(29, 15) share λ but not (u, v): their values are {_shown(a, b)} and "
        f"{_shown(b, a)}, {same}"
    )


#: 7.4's "answer first" pixels on the floor: the one covered pixel of its quad, two of a quad.
SAMPLE_PIXELS = ((27, 3), (28, 14), (29, 15))


def draw_sample_case(ax, case, got):
    """7.1's close-up at the pixel (the quad drawn once the check passes); the filtered value
    and yours, with λ and (u, v) once it passes; with no answer, the whole floor with 7.4's
    pixels marked."""
    _, (pyramid, xy, w, uv, row, col, wrap), expected = case
    size = level_size(pyramid)
    lod = expected_lod(xy, w, uv, size, row, col)
    passed = got is not None and same_value(got, expected, None)
    # r426 FIG1: a case with no answer (it raised) marks its own pixel on the floor too
    marked = (
        SAMPLE_PIXELS if got is not None else tuple(dict.fromkeys((*SAMPLE_PIXELS, (row, col))))
    )
    artists = draw_lod_case(ax, ("", (xy, w, uv, size, row, col), lod), lod if passed else None,
                            overview=got is None, marked=marked)  # fmt: skip
    text = f"pixel ({row}, {col}), level 0 {size[0]}×{size[1]}, wrap={wrap!r}"
    if got is None and np.array_equal(xy, FLOOR[0]):  # the whole floor (r418 FIG1)
        text = f"the floor the check draws, the questions' pixels marked; this case: {text}"
    if got is not None:
        text += f"; value {_shown(expected, got)}, yours {_shown(got, expected)}"
    if passed:
        q = len(pyramid) - 1
        text += (f"\nλ = {num(lod)} (pyramid 0–{q}), (u, v) at the pixel's centre = "
                 f"{vec(pixel_uv(xy, w, uv, row, col))}\n{textwrap.fill(sample_questions(pyramid), 75)}")  # fmt: skip
    artists.append(ax.set_xlabel(text, fontsize="x-small"))
    return artists


def _fitted_lod(args, got) -> float | None:
    """The λ at which the pyramid, filtered trilinearly at the pixel's own (u, v), gives ``got``
    (the nearest to 7.1's λ where several do), or None: the value is linear in λ between two
    levels, so each pair of levels gives at most one (r462 H6, r450 H8)."""
    pyramid, xy, w, uv, row, col, wrap = args
    at = pixel_uv(xy, w, uv, row, col)
    values = [np.ravel(expected_bilinear(level, at, wrap)).astype(float) for level in pyramid]
    g = np.ravel(np.asarray(got, dtype=float))
    if g.size != values[0].size or not np.all(np.isfinite(g)):
        return None
    lod = expected_lod(xy, w, uv, level_size(pyramid), row, col)
    found = []
    for k in range(len(pyramid) - 1):
        a, b = values[k], values[k + 1]
        steep = np.abs(b - a) > 1e-6
        if not steep.any():
            continue
        t = float(np.mean((g - a)[steep] / (b - a)[steep]))
        if -1e-9 <= t <= 1 + 1e-9 and np.allclose(a + t * (b - a), g, rtol=0, atol=1e-7):
            found.append(k + min(max(t, 0.0), 1.0))
    return min(found, key=lambda lam: abs(lam - lod)) if found else None


def _lod_offset(args, expected, got):
    """The offsets of λ that give ``got`` on this case, as a range (lo, hi): one number where
    the fitted λ lies between the ends of the pyramid, open-ended at an end (λ clamped there)."""
    if np.allclose(np.asarray(got, float), expected, rtol=0, atol=1e-9):
        return None
    fitted = _fitted_lod(args, got)
    if fitted is None:
        return None
    pyramid, xy, w, uv, row, col, _ = args
    lod = expected_lod(xy, w, uv, level_size(pyramid), row, col)
    d, q = fitted - lod, len(pyramid) - 1
    if abs(d) < 1e-6:
        return None
    lo = -np.inf if fitted <= 1e-9 else d - 1e-4
    hi = np.inf if fitted >= q - 1e-9 else d + 1e-4
    return (lo, hi)


def _lod_offset_words(args, expected, got) -> str:
    pyramid, xy, w, uv, row, col, _ = args
    lod = expected_lod(xy, w, uv, level_size(pyramid), row, col)
    fitted = _fitted_lod(args, got)
    d = fitted - lod
    return (f"your value is the pyramid filtered at this pixel's own (u, v) with λ = {num(fitted)}, "
            f"where 7.1's λ here is {num(lod)} ({'+' if d > 0 else '−'}{num(abs(d))}): the same "
            "offset on every case; a bias added to λ, or λ from another size? 7.3's trilinear "
            "takes 7.1's λ itself")  # fmt: skip


#: Named only where one offset of λ gives every failing answer (:attr:`.Mistake.parameter`).
LOD_OFFSET = Mistake("λ offset", _lod_offset_words,
                     fits=lambda a, e, g: _lod_offset(a, e, g) is not None,
                     parameter=_lod_offset, only_whole=True)  # fmt: skip


PIXEL_SAMPLE = Exercise(
    "pixel_sample", sample_cases, as_sample, same_value, explain_sample, _rule,
    (*OWN, *variant_mistakes(_remembered_variants, MISTAKES), LOD_OFFSET), call=_call,
    answers=(PackageAnswer(sample, when=lambda a: a.get("filter") == "trilinear"),
             PackageAnswer(mip_level), PackageAnswer(lane_values)),
    draw=draw_sample_case, hints=((RULE, HINT),), inputs_drawn=True, raised_words=_raised,
    once=((RULE, ": as said for the first failing case"),),
    reference=("teachraster.exercises.quad_difference", "teachraster.exercises.pixel_level",
               "teachraster.exercises.texture_filtering"),
    example=4,  # pixel (27, 3), its quad's one covered pixel: 7.4's first question (r418)
    slow=" (one call computes one pixel's value: it should take well under a millisecond)",
)  # fmt: skip
