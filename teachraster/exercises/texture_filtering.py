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

import re
import textwrap

import numpy as np

from ..pipeline.mip_pyramid import mipmap
from ..pipeline.texture import sample
from .answers import as_numbers
from .cases import SEED, fixed_and_drawn
from .channel_order import channel_order_mistake
from .exercise import Exercise, Knobs, Mistake, PackageAnswer, Slip
from .scalars import num, vec
from .tolerance import TOL, all_close


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
    """A number or one value per channel (at most 4)."""
    return as_numbers(value, None, "a number, or one value per channel", max_size=16)


def same_value(got, expected, args) -> bool:
    """Within 1e-6 (of the values' size): a texture filtered in float32 (imread's) is right."""
    got = np.asarray(got, dtype=float)
    if got.size != np.size(expected):
        return False
    return all_close(got.reshape(np.shape(expected)), expected, 1e-6)


#: (the shift subtracted, the texels added to W): x = u·(W + span) − shift; "plus half" is
#: the half texel added, x = u·W + ½ (r301: the sign of the shift turned)
ORIGINS = {"centres": (0.5, 0), "corners": (0.0, 0), "stretched": (0.0, -1), "plus half": (-0.5, 0)}


def plain_bilinear(texture, uv, wrap, *, origin="centres", floor="floor", swap=False,
                   wrap_as=None, clamp=None, transpose=False, flip_u=False, flip_v=False,
                   blend="both", scale="right"):  # fmt: skip
    """A bilinear filter with knobs for the usual mistakes (the defaults are GL's LINEAR).

    ``origin`` "corners" samples at texel corners (x = u·W), "stretched" puts the first and
    last texel centres at u = 0 and 1 (x = u·(W − 1)), "plus half" adds the half texel
    (x = u·W + ½); ``floor="trunc"`` finds the texel to the
    left with int(); ``swap`` gives the left texel the weight of the right one (``"x"``, ``"y"``:
    along that axis only), ``swap="fractions"`` blends along x by y's fraction and along y by
    x's, ``swap="x for y"`` blends the two rows by x's fraction too; ``wrap_as``
    wraps with another mode whatever the case says (clamping x and y to the texel centres
    first is the same as ``wrap_as="clamp"``; ``"swapped"``: clamps for "repeat" and tiles for
    "clamp"; ``"mirror"``: mirrors for "clamp"; ``"columns"``: tiles the columns only, for "repeat"); ``clamp="uv"`` clamps (u, v) to [0, 1] first,
    ``clamp="mod"`` wraps (u, v) into [0, 1) first and then clamps the texels (``"mod
    repeat"``: for "repeat" only; ``"x mod"``: x = u·W − ½ and y wrapped into [0, W)
    and [0, H) for "repeat", then the texels clamped), ``"uv, tiled"`` clamps (u, v) for "clamp" and tiles the
    texels all the same;
    ``transpose`` swaps the texture's rows and columns (its H and W too), ``"index"`` reads
    texel (row, col) as ``texture[col, row]`` with H and W right (IndexError where col ≥ H, as
    the student's raises); ``flip_u`` takes 1 − u for u, ``flip_v`` 1 − v for v;
    ``blend="x only"`` blends along x within the row v lies in (⌊v·H⌋), ``"y only"`` along y
    within the column u lies in, ``"x only, row ⌊y⌋"`` along x within row ⌊y⌋ (the vertical
    fraction left at 0); ``floor="round"`` takes round(x) for ⌊x⌋ (a fraction in [−½, ½));
    ``scale="swapped"`` takes x = u·H − ½, y = v·W − ½; ``clamp="uv, upper index"`` wraps
    (u, v) for "repeat" (clamps them for "clamp") and then clamps only the right and lower
    texel indices, the left and upper ones used as they are (Python's index −1 is the last).
    """
    tex = np.asarray(texture, dtype=float)
    if transpose is True:
        tex = np.swapaxes(tex, 0, 1)
    h, w = tex.shape[:2]
    centre, span = ORIGINS[origin]
    u, v = np.clip(uv, 0.0, 1.0) if clamp == "uv" else np.asarray(uv, dtype=float)
    u, v = (1.0 - u if flip_u else u), (1.0 - v if flip_v else v)
    if clamp == "mod" or (clamp == "mod repeat" and wrap == "repeat"):
        u, v = np.mod(u, 1.0), np.mod(v, 1.0)  # (u, v) wrapped first, the texels clamped
        wrap_as = "clamp"
    if clamp == "uv, tiled" and wrap == "clamp":  # r317: 'clamp' as (u, v) clamped, tiled
        u, v = np.clip(u, 0.0, 1.0), np.clip(v, 0.0, 1.0)
        wrap_as = "repeat"
    if clamp == "uv, upper index":  # r362: (u, v) wrapped or clamped, the upper index clamped
        u, v = (np.mod(u, 1.0), np.mod(v, 1.0)) if wrap == "repeat" else np.clip([u, v], 0, 1)
    su, sv = (h, w) if scale == "swapped" else (w, h)  # r362: u scaled by H and v by W
    if scale == "eight":  # r450 H3: lesson 09's cell with its 8 × 8 texture pasted
        su, sv = 8, 8
    x, y = u * (su + span) - centre, v * (sv + span) - centre
    if clamp == "x mod" and wrap == "repeat":  # r375 F7: x = u·W − ½ wrapped, texels clamped
        x, y = np.mod(x, w), np.mod(y, h)
        wrap_as = "clamp"
    rounding = {"trunc": np.trunc, "round": np.round}.get(floor, np.floor)
    x0, y0 = rounding(np.array([x, y]))
    fx, fy = x - x0, y - y0
    if swap in (True, "x"):
        fx = 1 - fx
    if swap in (True, "y"):
        fy = 1 - fy
    if swap == "fractions":
        fx, fy = fy, fx
    if swap == "x for y":  # r375 F3: the rows blended by x's fraction
        fy = fx
    mode = wrap_as or wrap
    border = mode == "border" and wrap == "clamp"  # r450 H4: 0 beyond the border for 'clamp'
    mirrored = mode == "mirror" and wrap == "clamp"  # r462 H2 (GL's MIRRORED_REPEAT)
    mode = wrap if mode in ("border", "mirror") else mode
    if mode == "swapped":  # the two modes exchanged
        mode = "clamp" if wrap == "repeat" else "repeat"

    def index(i, n, tiled=None):
        tiled = mode == "repeat" if tiled is None else tiled
        if border or mirrored:
            return int(i) if border else mirror_index(i, n)
        return int(np.mod(i, n)) if tiled else int(np.clip(i, 0, n - 1))

    def texel(r, c):
        if border and not (0 <= r < h and 0 <= c < w):
            return 0.0 * tex[0, 0]
        return tex[c, r] if transpose == "index" else tex[r, c]

    rows_tiled = False if mode == "columns" else None  # r286: "repeat" on the columns only
    if mode == "columns":
        mode = wrap
    c0, c1 = index(x0, w), index(x0 + 1, w)
    r0, r1 = index(y0, h, rows_tiled), index(y0 + 1, h, rows_tiled)
    if mode == "modulo swapped" and wrap == "repeat":  # r390 N3: columns mod H, rows mod W
        c0, c1, r0, r1 = (
            int(np.mod(i, n)) for i, n in ((x0, h), (x0 + 1, h), (y0, w), (y0 + 1, w))
        )
    if clamp == "uv, upper index":
        c0, c1, r0, r1 = int(x0), min(int(x0) + 1, w - 1), int(y0), min(int(y0) + 1, h - 1)
    if blend == "x only, row ⌊y⌋":  # r362: the vertical fraction left at 0
        fy = 0.0
    if blend == "x only":  # r317: one row, the one v lies in, blended along x alone
        r0, fy = index(np.floor(v * h), h), 0.0
    if blend == "y only":
        c0, fx = index(np.floor(u * w), w), 0.0
    top = texel(r0, c0) * (1 - fx) + texel(r0, c1) * fx
    bottom = texel(r1, c0) * (1 - fx) + texel(r1, c1) * fx
    return top * (1 - fy) + bottom * fy


def mirror_index(i, n) -> int:
    """Texel index ``i`` of ``n`` mirrored at the borders: i mod 2n, read back from the far side."""
    m = int(np.mod(i, 2 * n))
    return m if m < n else 2 * n - 1 - m


def _channels_fit(args, expected, got) -> bool:
    return np.size(got) != np.size(expected)


def _channels_words(args, expected, got) -> str:
    n = np.size(expected)
    want = "one number (the texture has one channel)" if n == 1 else f"{n} values, one per channel"
    return f": your answer has {np.size(got)} value(s); here the answer is {want}"


CHANNELS = Mistake("channels", _channels_words, fits=_channels_fit)


# -- bilinear ---------------------------------------------------------------------------------
def _texture(rng, h, w, channels=0):
    shape = (h, w, channels) if channels else (h, w)
    return np.round(rng.uniform(0, 1, size=shape), 3)


def _bilinear_cases(rng, word):
    """Texel centres and corners, the border in both wrap modes, odd sizes; then random."""
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
        (
            "a float32 image (as from imread)",
            _texture(rng, 4, 6, 3).astype(np.float32),
            (0.37, 0.61),
            "repeat",
        ),  # fmt: skip
        ("a float32 image, v past the border", t4.astype(np.float32), (0.62, 1.2), "repeat"),
    ]
    out = [(label, (tex, np.array(uv, dtype=float), wrap)) for label, tex, uv, wrap in hard]
    for n in range(14):
        h, w = (int(v) for v in rng.integers(1, 9, size=2))
        tex = _texture(rng, h, w, 3 if n % 3 == 2 else 0)
        uv = np.round(rng.uniform(-1.5, 2.5, size=2), 4)
        out.append((f"{word} {n + 1}: {h}×{w}", (tex, uv, ("repeat", "clamp")[n % 2])))
    return [
        (f"{label}, uv={vec(args[1])}, wrap={args[2]!r}", args, expected_bilinear(*args))
        for label, args in out
    ]


bilinear_cases = fixed_and_drawn(_bilinear_cases, SEED + 80)  # r49: some drawn per check


def explain_bilinear(args, expected, got) -> str:
    """The case and the two values: no x = u·W − ½, which 7.2 asks to find (r64 07 D2: every
    failure's header printed it); the slips that need it say it."""
    tex, uv, wrap = args
    h, w = tex.shape[:2]
    return (
        f"on an H×W = {h}×{w} texture the filtered value is {_value(expected, got)}; yours is "
        f"{_value(got, expected)}"
    )


def _value(a, b=None) -> str:
    a = np.asarray(a, dtype=float)
    if a.size == 1:
        other = None if b is None or np.size(b) != 1 else float(np.ravel(b)[0])
        return num(float(a.ravel()[0]), other)
    return vec(a, b if b is not None and np.size(b) == a.size else None)


def _xy(args):
    tex, uv, wrap = args
    h, w = tex.shape[:2]
    return uv[0] * w - 0.5, uv[1] * h - 0.5


def _trunc_words(args, expected, got) -> str:
    x, y = _xy(args)
    axis, value = ("x", x) if x < 0 else ("y", y)
    side = "left" if axis == "x" else "top"
    return (
        f"int() truncates toward zero: for {axis} = {num(value)} the texel to the {side} is "
        f"⌊{num(value)}⌋ = {num(np.floor(value))}, and the fraction stays in [0, 1)"
    )


def _round_words(args, expected, got) -> str:
    """round() for floor: said on the axis where the two differ (r362)."""
    x, y = _xy(args)
    axis, value = ("x", x) if np.round(x) != np.floor(x) else ("y", y)
    return (
        f"you took round({axis}) for the texel to the {'left' if axis == 'x' else 'top'}: for "
        f"{axis} = {num(value)} that is {num(np.round(value))}, but the two texels around "
        f"{axis} are ⌊{axis}⌋ = {num(np.floor(value))} and ⌊{axis}⌋ + 1, and the fraction "
        f"{axis} − ⌊{axis}⌋ stays in [0, 1)"
    )


def _wrap_words(mode):
    def words(args, expected, got):
        if mode == "clamp":
            return ("wrap 'repeat' tiles the texture: column −1 is column W − 1, column W is "
                    "column 0; you clamped to the border")  # fmt: skip
        return "wrap 'clamp' repeats the border texels outwards, it does not tile"

    return words


def _modes_swapped_words(args, expected, got) -> str:
    """The two wrap modes exchanged, said from the case's own mode (r219: told only the rule,
    as "always clamp" fitted its 'repeat' cases and "always repeat" its 'clamp' ones)."""
    asked, done = ("repeat", "clamped") if args[2] == "repeat" else ("clamp", "tiled")
    other = "tiled" if done == "clamped" else "clamped"
    return (f"the wrap modes are exchanged: for wrap {asked!r} you {done}, and for the other "
            f"mode you {other}; 'repeat' tiles the texture (column −1 is column W − 1), "
            "'clamp' extends the border texels outwards")  # fmt: skip


def _col_row_words(args, expected, got) -> str:
    """texture[col, row] with H and W right (r219: told only the rule; on a square texture
    it is the transposed texture, elsewhere another texel or an IndexError)."""
    h, w = args[0].shape[:2]
    return (f"you read texel (row, col) as texture[col, row]: numpy's first index is the row "
            f"(the H = {h} rows run along v), the second the column (the W = {w} columns run "
            "along u), so it is texture[row, col], texture[y, x]")  # fmt: skip


BILINEAR_KNOBS = Knobs(plain_bilinear, {
    "origin": [
        Slip("texel corners", lambda a, e, g: f"you sampled at texel corners: texel centres are "
             f"at (i + ½)/W, so x = u·W − ½ (here {num(_xy(a)[0])}), not u·W", "corners"),
        Slip("u·(W − 1)", lambda a, e, g: "u·(W − 1) puts the first and last texel centres at "
             f"u = 0 and 1; texel centres are at (i + ½)/W, so x = u·W − ½ (here "
             f"{num(_xy(a)[0])})", "stretched"),
        # r301: the half texel added was told only the rule
        Slip("half texel added", lambda a, e, g: "you added the half texel, x = u·W + ½ and "
             "y = v·H + ½: every sample lands one whole texel right of and below its place, so "
             "at a texel's centre you read the texel diagonally below-right of it; texel centres are "
             f"at (i + ½)/W, so x = u·W − ½ (here {num(_xy(a)[0])})", "plus half"),
    ],
    "floor": [Slip("int() for floor", _trunc_words, "trunc"),
              Slip("round() for floor", _round_words, "round")],  # r362: told only the rule
    # r362: told only the rule (mip_level names the same slip)
    "scale": [Slip("u·H and v·W", lambda a, e, g: f"u runs along the W = {a[0].shape[1]} "
                   f"columns and v along the H = {a[0].shape[0]} rows; you scaled u by H and v "
                   "by W: x = u·W − ½, y = v·H − ½", "swapped"),
              Slip("lesson 09's 8 × 8", lambda a, e, g: "you placed the texels as if the "
                   "texture were 8 × 8 (x = u·8 − ½, lesson 09's texture): this one is H×W = "
                   f"{a[0].shape[0]}×{a[0].shape[1]}; take W and H from the array "
                   "(texture.shape[:2])", "eight")],
    "swap": [Slip("weights swapped", "the weight of the right (lower) texel is the fraction "
                  "x − ⌊x⌋ (y − ⌊y⌋); you gave it to the left (upper) one", True),
             # r40 07-1: swapped along one axis, this was called "nearest filtering"
             Slip("weights swapped", "the weight of the right texel is the fraction x − ⌊x⌋; "
                  "you gave it to the left one (the weights along x are swapped)", "x"),
             Slip("weights swapped", "the weight of the lower texel is the fraction y − ⌊y⌋; "
                  "you gave it to the upper one (the weights along y are swapped)", "y"),
             # r219 (a): x's fraction along y and y's along x was told only the rule
             Slip("fractions swapped", "the two fractions are exchanged: you blended the left "
                  "and right texels by y's fraction and the upper and lower ones by x's; each "
                  "axis takes its own", "fractions"),
             # r375 F3: the vertical blend by x's fraction was told only the rule
             Slip("rows blended by x's fraction", lambda a, e, g: "the blend between the two "
                  "rows uses x's fraction: the rows are weighted by y's own, the lower row by "
                  f"y − ⌊y⌋ (here y = {num(_xy(a)[1])}) and the upper by 1 − (y − ⌊y⌋)",
                  "x for y")],
    "wrap_as": [Slip("always clamp", _wrap_words("clamp"), "clamp"),
                Slip("always repeat", _wrap_words("repeat"), "repeat"),
                Slip("wrap modes swapped", _modes_swapped_words, "swapped"),
                Slip("'clamp' as a border of 0", "beyond the border you blended in 0 (GL's "
                     "CLAMP_TO_BORDER with a black border): wrap 'clamp' extends the border "
                     "texels outwards (CLAMP_TO_EDGE): clamp the texel indices to [0, W − 1] "
                     "and [0, H − 1]", "border"),
                # r462 H2: told the generic hint
                Slip("'clamp' as a mirror", "beyond the border you mirrored the texture (GL's "
                     "MIRRORED_REPEAT): wrap 'clamp' extends the border texels outwards "
                     "(CLAMP_TO_EDGE): clamp the texel indices to [0, W − 1] and [0, H − 1]",
                     "mirror"),
                # r390 N3: told the method ("which texel centres enclose (u, v)")
                Slip("modulo H and W swapped", lambda a, e, g: "you wrapped the column "
                     f"index modulo H = {a[0].shape[0]} and the row index modulo W = "
                     f"{a[0].shape[1]}: with wrap 'repeat' the columns repeat every W = "
                     f"{a[0].shape[1]} texels and the rows every H = {a[0].shape[0]}",
                     "modulo swapped"),
                Slip("repeat on columns only", "wrap 'repeat' tiles the texture along both "
                     "axes; you tiled the columns (u) but clamped the rows (v): wrap the row "
                     "index as you wrap the column index", "columns")],
    "clamp": [
        Slip("clamped (u, v) first", "you clamped (u, v) to [0, 1] first: with wrap 'repeat' a "
             "coordinate outside [0, 1] tiles, and near the border the texels beyond wrap "
             "around", "uv"),
        # r40 07-1: repeat as uv % 1 with the texels then clamped was "nearest filtering"
        Slip("wrapped (u, v), clamped texels", "you wrapped (u, v) into [0, 1) and then "
             "clamped the texels to the border: with wrap 'repeat' the texels beyond the border "
             "wrap around too (column −1 is column W − 1), so wrap the texel indices, not (u, v)",
             "mod"),
        # r317: the same for 'repeat' only ('clamp' right) was told only the rule
        Slip("wrapped (u, v), clamped texels", "you wrapped (u, v) into [0, 1) and then "
             "clamped the texels to the border: with wrap 'repeat' the texels beyond the border "
             "wrap around too (column −1 is column W − 1), so wrap the texel indices, not (u, v)",
             "mod repeat"),
        # r375 F7: x = u·W − ½ wrapped into [0, W) was named only on a random case
        Slip("wrapped x, clamped texels", "you wrapped x = u·W − ½ into [0, W) (and y into "
             "[0, H)) and then clamped the texel indices: between the last texel's centre and "
             "the border (x in [W − 1, W), as at u = 0, where x = −½ wraps to W − ½) the texel "
             "to the right is then column W − 1 again; with wrap 'repeat' it is column 0: wrap "
             "the texel indices (column W is column 0), not the coordinate", "x mod"),
        Slip("'clamp' tiles the texels", "with wrap 'clamp' you clamped (u, v) to [0, 1] but "
             "tiled the texel indices: at u = 0 the column left of the first is then the last "
             "one, column W − 1, and it blends in; 'clamp' clamps the texel indices (column −1 "
             "is column 0, the border texel), and then (u, v) need no clamping", "uv, tiled"),
        # r362: told only the rule
        Slip("(u, v) wrapped, upper index clamped", "you wrapped (u, v) into [0, 1) (clamped "
             "them for 'clamp') and then clamped only the right and lower texel indices: near "
             "u = 0 the left one, ⌊x⌋ = −1, is Python's index −1, the last column, in both "
             "modes, and for 'repeat' the right one beyond the last column is not column 0; "
             "wrap both texel indices as the mode says ('repeat': modulo W, 'clamp': to "
             "[0, W − 1]), and (u, v) need no wrapping", "uv, upper index"),
    ],
    "transpose": [Slip("rows and columns swapped", lambda a, e, g: f"u runs along the W = "
                       f"{a[0].shape[1]} columns, v along the H = {a[0].shape[0]} rows: "
                       "texture[row, col] is texture[y, x]", True),
                  Slip("indexed [col, row]", _col_row_words, "index")],
    # r219 (b): 1 − u was told only the rule; u and v both flipped are the two slips together
    "flip_u": [Slip("u flipped", "you flipped u (1 − u): the texture's column 0 lies at u = 0 "
                    "(GL's first texel of each row is at s = 0), so the filter takes u as it "
                    "comes", True)],
    # r199 12-7: (1 − v)·H − ½ was told "one of the four texels alone", though it blends
    "flip_v": [Slip("v flipped", "you flipped v (1 − v): the texture's row 0 lies at v = 0, "
                    "y = v·H − ½ (GL's first row of texel data is at t = 0), so the filter "
                    "takes v as it comes", True)],
    # r317: a blend along one axis only, in the row (column) the sample lies in, was told the rule
    "blend": [Slip("no vertical blend", "you blended along x only, within the one row v lies "
                   "in: bilinear blends two rows too, the one above the sample and the one below "
                   "it, each weighted by how close the sample lies to that row's centres",
                   "x only"),
              Slip("no horizontal blend", "you blended along y only, within the one column u "
                   "lies in: bilinear blends two columns too, the one left of the sample and the "
                   "one right of it, each weighted by how close the sample lies to that "
                   "column's centres", "y only"),
              # r362: row ⌊y⌋ blended along x alone was told only the rule
              Slip("no vertical blend", lambda a, e, g: "you blended along x only, in row "
                   f"⌊y⌋ alone (y = {num(_xy(a)[1])}): bilinear blends row ⌊y⌋ with row "
                   "⌊y⌋ + 1 below it, the lower row weighted by y − ⌊y⌋", "x only, row ⌊y⌋")],
})  # fmt: skip


def _nearest(tex, uv, wrap):
    return sample(tex, np.asarray(uv, dtype=float)[None], "nearest", wrap)[0]


def _one_texel(args, expected, got) -> bool:
    """Is ``got`` one of the four texels around (x, y) alone (nearest filtering, whichever
    way a tie between texels is broken)? r6: a floor(u·W) nearest passed as unnamed."""
    tex, uv, wrap = np.asarray(args[0], float), args[1], args[2]
    h, w = tex.shape[:2]
    x0, y0 = int(np.floor(uv[0] * w - 0.5)), int(np.floor(uv[1] * h - 0.5))
    index = (lambda i, n: i % n) if wrap == "repeat" else (lambda i, n: min(max(i, 0), n - 1))
    texels = [tex[index(r, h), index(c, w)] for r in (y0, y0 + 1) for c in (x0, x0 + 1)]
    return not all_close(got, expected) and (
        any(all_close(got, t) for t in texels) or _some_texel(tex, got)
    )


def _some_texel(tex: np.ndarray, got) -> bool:
    """Is ``got`` one texel of ``tex``, anywhere (a nearest filter that wraps the wrong way
    picks one beyond the four around (u, v): r199, the symptom must fit every failing case)?"""
    g = np.asarray(got, dtype=float)
    flat = tex.reshape(tex.shape[0] * tex.shape[1], -1)
    if g.size != flat.shape[1] or len(flat) > 4096:  # the exercise's textures are small
        return False
    if not np.isfinite(g).all():  # r286 C1: inf is within TOL·inf of every texel
        return False
    scale = np.maximum(1.0, np.maximum(np.abs(flat), np.abs(g.reshape(1, -1))))
    return bool((np.abs(flat - g.reshape(1, -1)) <= TOL * scale).all(axis=1).any())


def _one_texel_words(args, expected, got) -> str:
    """Nearest filtering only where ``got`` is the texel (u, v) lies in (GL's NEAREST, any
    tie): swapped weights give a neighbour of it, which is not nearest filtering (r40 07-1)."""
    tex, uv, wrap = np.asarray(args[0], float), args[1], args[2]
    h, w = tex.shape[:2]
    index = (lambda i, n: i % n) if wrap == "repeat" else (lambda i, n: min(max(i, 0), n - 1))
    fx, fy = uv[0] * w, uv[1] * h
    rows = {int(np.floor(fy)), int(np.ceil(fy)) - 1}  # a tie on a texel border: either one
    cols = {int(np.floor(fx)), int(np.ceil(fx)) - 1}
    if any(all_close(got, tex[index(r, h), index(c, w)]) for r in rows for c in cols):
        return ": that is one texel alone, nearest filtering; bilinear blends the four texels around (u, v)"
    x0, y0 = int(np.floor(fx - 0.5)), int(np.floor(fy - 0.5))
    if not any(all_close(got, tex[index(r, h), index(c, w)])
               for r in (y0, y0 + 1) for c in (x0, x0 + 1)):  # fmt: skip
        return (": that is one texel alone, and none of the four around (u, v): are the "
                f"indices wrapped as wrap {wrap!r} says? Bilinear blends those four")  # fmt: skip
    return (": that is one of the four texels around (u, v) alone, not the one (u, v) lies in; "
            "bilinear blends all four, each weighted by how close (u, v) lies to it")  # fmt: skip


BILINEAR_MISTAKES = [
    CHANNELS,
    # r64 07 D2: `return texture[0, 0]` was given the method
    Mistake("texel [0, 0]", ": that is texel [0, 0] (the upper-left one), whatever uv: a "
            "placeholder left in?", gives=lambda tex, uv, wrap: np.asarray(tex, float)[0, 0]),
    # r286 M3, M4: the channels in another order (the rule shared with 9.2's colours), and
    # a value that ignores uv
    channel_order_mistake(": the same values in another channel order", ": channel k of the "
                          "answer is channel k of the texture", tol=TOL),
    Mistake("texture's mean", ": that is the mean of the whole texture, whatever uv: bilinear "
            "blends only the four texels around (u, v)",
            gives=lambda tex, uv, wrap: np.asarray(tex, float).mean(axis=(0, 1))),
    # r301: one mean over every value, channels too, was told only the rule (it fails the
    # three-channel cases, which the per-channel mean above gives)
    Mistake("texture's mean, one number", ": that is the mean of all the texture's values "
            "as one number (its channels averaged together too), whatever uv: bilinear blends "
            "only the four texels around (u, v), each channel on its own",
            gives=lambda tex, uv, wrap: float(np.mean(np.asarray(tex, float)))),
    Mistake("nearest texel", ": that is the nearest texel; bilinear blends the four texels "
            "around (u, v)", gives=_nearest),
    # a symptom: a texel alone is also what swapped weights give at a texel centre (r40 07-1),
    # and what any blend gives where its (misplaced) sample lies on a texel centre: named only
    # where every failing answer is a texel alone (r199 12-7: a flipped v and a filter along x
    # only were told "one texel alone", each on the one case where it was)
    Mistake("one texel", _one_texel_words, fits=_one_texel, symptom=True,
            must_fit=lambda args, expected, got: True),
    BILINEAR_KNOBS,
]  # fmt: skip


#: A named mistake's fix, as a question until two different answers have failed (r73 07-1:
#: the formula came with the first wrong answer; :attr:`.exercise.Exercise.hints`).
NAMED_HINTS = (
    (re.compile(r"texel centres are at \(i \+ ½\)/W, so x = u·W − ½ \(here [^()]*\)(?:, not u·W)?"),
     "where in u does texel i's centre lie, and so which x, in texels, is this u?"),
    (re.compile(r" is the fraction [xy] − ⌊[xy]⌋(?: \(y − ⌊y⌋\))?; you gave it to"),
     " must grow as the sample nears that texel; yours went to"),
    # r174 12-6: "yours went to level 0" was read as "yours is level 0" (it was level 1 alone)
    (re.compile(r"the weight of level (\d+) is the fraction λ − ⌊λ⌋ = [^;]*; you gave it to "
                r"level (\d+)"),
     r"the weight of level \1 must grow as λ nears that level; yours grows as λ nears level "
     r"\2 (the two levels' weights are swapped)"),
    (re.compile(r", level \d+ weighted by λ − ⌊λ⌋ = [^;:()]*"), " (with which weights?)"),
    ("(x = u·W, not u·W − ½)", "(where in u is a texel's centre?)"),
)  # fmt: skip


#: r122 N12-1: the clamp and what follows from it, asked back on the first tries (the words
#: were given in full on a first try, in 7.3's check and the capstone's floor_trilinear)
CLAMP_HINTS = (
    (re.compile(r"clamp it to \[0, q\] = \[0, (\d+)\] first"),
     r"the pyramid's levels run from 0 to q = \1: what λ does the filter use instead"),
    (", then take its levels and the weight (below 0 the texture is magnified and level 0 "
     "alone is filtered)", ", and which levels and weight follow from it?"),
    ("; the weight λ − ⌊λ⌋ then stays in [0, 1]", "? (can a weight lie outside [0, 1]?)"),
)  # fmt: skip


#: 7.2's rule for an answer no mistake explains, said once two different answers have failed,
#: and the question asked before (r64 07 D2: the method came with the first wrong answer).
BILINEAR_RULE = (
    ": in texel units x = u·W − ½ and y = v·H − ½ put the texel centres on whole numbers; "
    "blend the four texels around (⌊x⌋, ⌊y⌋) (indices wrapped) with weights from x − ⌊x⌋ and "
    "y − ⌊y⌋"
)
BILINEAR_HINT = (
    ": at a texel's centre the value must be that texel's, and between centres it must move "
    "smoothly from one to the next: which texel centres enclose (u, v) here, and how far is "
    "(u, v) from each, in texels? Work this case through by hand"
)


def _bilinear_rule(args, expected, got) -> str:
    return BILINEAR_RULE


#: The modules whose every function computes a part of a texture filter's answer (r148
#: D12-5: ``texel_fetch.bilinear_corner``, which finds the four texels and their weights,
#: and ``_bilinear_blend`` passed 12.7 as the student's work): the texel fetch for both, and
#: the choice and blend of levels for trilinear.
FILTER_MODULES = {
    "bilinear": ("teachraster.pipeline.texturing.texel_fetch",),
    "trilinear": ("teachraster.pipeline.texturing.texel_fetch",
                  "teachraster.pipeline.texturing.texture_filters"),
}  # fmt: skip


def _answers(filter_name):
    whole = PackageAnswer(sample, when=lambda a: a.get("filter") == filter_name,
                          modules=FILTER_MODULES[filter_name])  # fmt: skip
    if filter_name != "trilinear":
        return (whole,)
    # r174 12-3: 7.3 and 12.8 ask for each level filtered by the student's own bilinear; the
    # package's, ``tr.sample(level, uv, "bilinear", wrap)``, passed as the student's work
    level = PackageAnswer(sample, when=lambda a: a.get("filter") == "bilinear",
                          what="a level's bilinear filter, which this exercise asks of your own "
                          "bilinear")  # fmt: skip
    return (whole, level)


_INDEX_ERROR = re.compile(r"index (-?\d+) is out of bounds for axis (\d+) with size (\d+)")


def bilinear_raised(args, error) -> str:
    """Words for an IndexError of the student's bilinear, from the case's own indices (r462 H1,
    r450 H5: indices clipped to [0, W] and H and W swapped were told the raw error only)."""
    found = _INDEX_ERROR.search(error)
    if not error.startswith("your function raised IndexError") or found is None:
        return ""
    index, axis, size = (int(g) for g in found.groups())
    tex, uv, wrap = args
    h, w = np.shape(tex)[:2]
    if axis > 1:
        return ""
    n, other = (h, w) if axis == 0 else (w, h)
    one, many, big, coord = (
        ("row", "rows", "H", "y") if axis == 0 else ("column", "columns", "W", "x")
    )
    if size != n:
        return (f": your array's axis {axis} has {size} entries, where this texture (shape "
                f"{h}×{w}, texture[row, col]) has {big} = {n} {many} along it: are H and W, rows "
                "and columns, swapped (the texture transposed, or u scaled by H)?")  # fmt: skip
    c = (uv[1] * h if axis == 0 else uv[0] * w) - 0.5
    fix = (f"with wrap 'repeat' take each index modulo {big} = {n} ({one} {n} is {one} 0)"
           if wrap == "repeat" else
           f"with wrap 'clamp' clamp each index to [0, {big} − 1] = [0, {n - 1}]")  # fmt: skip
    if index < 0:
        return (f": {one} index {index}: Python reads a negative index from the end and raises "
                f"below −{n}; {fix}")  # fmt: skip
    lower = int(np.floor(c))
    if index in (lower, lower + 1) or index == n:
        which = (
            f"{one} ⌊{coord}⌋ + 1 = {lower + 1} ({coord} = {num(c)})"
            if index == lower + 1
            else f"{one} {index}"
        )
        past = "one past" if index == n else "past"
        clipped = (f"; you clamped to [0, {big}] = [0, {n}]" if index == n != lower + 1 and
                   wrap != "repeat" else "")  # fmt: skip
        return f": {which} is {past} the last {one}, {big} − 1 = {n - 1}{clipped}: {fix}"
    if index < other:
        return (f": {one} index {index} lies beyond the {big} = {n} {many} but within the "
                f"other axis's {other}: are H and W swapped (u scaled by H, v by W, or the row "
                "and column indices exchanged)? u runs along the W columns (x = u·W − ½), v "
                "along the H rows")  # fmt: skip
    return ""


def bilinear_exercise(scene) -> Exercise:
    return Exercise(
        "bilinear", bilinear_cases, as_texel_value, same_value, explain_bilinear,
        _bilinear_rule, BILINEAR_MISTAKES, answers=_answers("bilinear"),
        draw=draw_texture_case, scene=scene, hints=((BILINEAR_RULE, BILINEAR_HINT), *NAMED_HINTS),
        once=((BILINEAR_RULE, ": as said for the first failing case"),),
        inputs_drawn=True, raised_words=bilinear_raised,
        example=8,  # r362 FIG1: u = 0.05, 7.2's question (a texel centre had weights 1, 0, 0, 0)
    )  # fmt: skip


def draw_texture_case(ax, case, got):
    """The texture in texel units, the point (u·W, v·H) and, with the method, the texel
    centres; the expected value and yours below (r40 07-3: two bars of one number showed
    nothing of the filter). Before any answer (``got`` None) the inputs only. The four texels
    bilinear blends, each with its weight, and (x, y) = (u·W − ½, v·H − ½) are the method 7.2
    asks for: drawn once two different answers have failed, as the words say it (r64 07 D2).
    A pyramid (7.3) is drawn by :func:`draw_pyramid_case`."""
    from matplotlib.ticker import MaxNLocator

    from . import tries

    if isinstance(case[1][0], list):
        return draw_pyramid_case(ax, case, got)
    tex, uv, wrap = np.asarray(case[1][0], dtype=float), case[1][1], case[1][2]
    h, w = tex.shape[:2]
    px, py = uv[0] * w, uv[1] * h  # the point, in texel units from the texture's corner
    x0, y0 = np.floor(px - 0.5), np.floor(py - 0.5)
    passed = got is not None and same_value(got, case[2], None)
    # the method once earned: the full words given, or this answer right (a passing check)
    method = got is not None and (tries.hints_spent("bilinear") or passed)
    artists = draw_level(ax, tex, uv, wrap, weights=method)
    room = 0.8 if method else 0.2  # the weights written outwards, off the texels' centres
    ax.set_xlim(min(0, x0) - room, max(w, x0 + 2) + room)
    ax.set_ylim(max(h, y0 + 2) + 0.2, min(0, y0) - 0.2)
    ax.set_aspect("equal")
    # r286 FIG7: texel numbers are whole ("0.0 2.5 5.0 7.5" read as fractions of a texel)
    ax.xaxis.set_major_locator(MaxNLocator(integer=True))
    ax.yaxis.set_major_locator(MaxNLocator(integer=True))
    where = f"(u·W, v·H) = ({num(px)}, {num(py)}) texels"
    if method:
        where = f"x = {num(px - 0.5)}, y = {num(py - 0.5)} in texel centres"
    text = f"uv = {vec(uv)} (×), {where}"
    if got is not None:
        text += f";\nthe filtered value is {_value(case[2], got)}{_yours(got, case[2])}"
    if passed:  # r375 F2: 7.2's other questions, for this texture's W
        artists.append(beside(ax, bilinear_questions(w, uv[0])))
    artists.append(ax.set_xlabel(text, fontsize="x-small"))
    return artists


def beside(ax, words: str, width: int = 40):
    """``words`` beside the axes, right of it (a pass figure's answers to the task's "answer
    first" questions, r375 F2: under the picture they shrank it)."""
    text = "\n".join(textwrap.fill(line, width) for line in words.split("\n"))
    return ax.text(
        1.04, 0.5, text, transform=ax.transAxes, ha="left", va="center", fontsize="x-small"
    )


def _yours(got, expected) -> str:
    expected = np.ravel(expected)
    return "" if np.size(got) != expected.size else f", yours {_value(got, expected)}"


def bilinear_questions(w: int, u: float) -> str:
    """7.2's questions answered for a row of ``w`` texels (r375 F2: the pass figure answered
    only the first): ``u`` with "clamp", the u's of one texel's value, and of the plain
    average of columns 1 and 2."""
    x = u * w - 0.5
    c0 = int(np.floor(x))
    cols = [min(max(c, 0), w - 1) for c in (c0, c0 + 1)]
    t = x - c0
    centres = ", ".join(num((c + 0.5) / w) for c in range(w))
    middle = f"; columns 1 and 2 averaged at u = {num(2 / w)}" if w > 2 else ""
    blend = f"blends columns {cols[0]} and {cols[1]} by {num(1 - t)} and {num(t)}"
    if cols[0] == cols[1]:
        blend = f"takes column {cols[0]} alone (columns {c0} and {c0 + 1} both clamped to it)"
    # r390 N5: "clamp" holds the border texels' values outside the outer centres too
    edges = f"u ≤ {num(0.5 / w)} and u ≥ {num((w - 0.5) / w)}"
    return (f"7.2: with 'clamp', u = {num(u)} {blend}; one texel's value exactly with "
            f"'repeat' at u = {centres} (the texel centres), with 'clamp' there and at every "
            f"{edges} (column 0 or {w - 1}){middle}")  # fmt: skip


#: The texel weights' and wrapped boxes' labels: classroom size (r375 F6: 9 pt, touching)
LABEL_SIZE = 12


def draw_level(ax, tex, uv, wrap, *, at=(0.0, 0.0), texel=(1.0, 1.0), weights=False,
               labels=True, mark=True) -> list:  # fmt: skip
    """One level (a texture) drawn with texel (r, c)'s square from ``at`` + (c, r)·``texel``,
    framed (r375 F6: a white corner texel read as missing), the point (u, v) (×) and, with
    ``weights``, the texel centres and the four texels bilinear blends: boxed, each weight
    written off its centre on the side away from the point (never on the point, nor on a
    neighbour's label: r375 F6), a box beyond the border filled with the texel it stands for
    and named (without ``labels``, the boxes only; without ``mark``, no ×)."""
    from matplotlib.patches import Rectangle

    tex = np.asarray(tex, dtype=float)
    h, w = tex.shape[:2]
    (ox, oy), (sx, sy) = at, texel
    shown = tex / max(float(np.max(tex)), 1.0)  # 8-bit values drawn as [0, 1]
    shown = shown if shown.ndim == 2 or shown.shape[2] == 3 else shown[..., 0]
    artists = [ax.imshow(shown, cmap="gray", vmin=0, vmax=1, interpolation="nearest",
                         extent=(ox, ox + w * sx, oy + h * sy, oy)),
               ax.add_patch(Rectangle((ox, oy), w * sx, h * sy, fill=False,
                                      edgecolor="black", linewidth=1))]  # fmt: skip
    px, py = uv[0] * w, uv[1] * h
    x0, y0 = np.floor(px - 0.5), np.floor(py - 0.5)
    fx, fy = px - 0.5 - x0, py - 0.5 - y0
    if weights:
        cols, rows = np.meshgrid(np.arange(w) + 0.5, np.arange(h) + 0.5)
        artists += ax.plot(ox + cols.ravel() * sx, oy + rows.ravel() * sy, ".",
                           color="#ff9f1c", ms=4)  # fmt: skip
    for dx, dy in ((0, 0), (1, 0), (0, 1), (1, 1)) if weights else ():
        c, r = int(x0 + dx), int(y0 + dy)
        artists.append(ax.add_patch(Rectangle((ox + c * sx, oy + r * sy), sx, sy, fill=False,
                                              edgecolor="#2b7bba", linewidth=2)))  # fmt: skip
        name = _wrapped_box(ax, shown, c, r, wrap, (ox, oy), (sx, sy), artists)
        if not labels:
            continue
        weight = (fx if dx else 1 - fx) * (fy if dy else 1 - fy)
        # outwards, beyond the block's corner, a leader line to the texel's outer corner
        # (r390 N4: a label centred in the texel spread over texels not in the blend)
        out_x, out_y = (1 if dx else -1), (1 if dy else -1)
        cx, cy = ox + (c + 0.5 + 0.3 * out_x) * sx, oy + (r + 0.5 + 0.3 * out_y) * sy
        box = {"facecolor": "white", "alpha": 0.9, "pad": 1, "edgecolor": "#2b7bba", "lw": 0.5}
        # the texel a box beyond the border stands for under its weight, in one label
        lines = [f"w {weight:.2g}"] + ([f"= {name}"] if name else [])
        artists.append(ax.annotate("\n".join(lines if dy else lines[::-1]), (cx, cy),
                                   xytext=(9 * out_x, -9 * out_y), textcoords="offset points",
                                   color="#2b7bba", ha="left" if dx else "right",
                                   va="top" if dy else "bottom", fontsize=LABEL_SIZE, bbox=box,
                                   arrowprops={"arrowstyle": "-", "color": "#2b7bba", "lw": 1}))  # fmt: skip
    if mark:
        artists += ax.plot(ox + px * sx, oy + py * sy, "x", color="#d7301f", ms=10, mew=2)
    return artists


def _wrapped_box(ax, shown, c, r, wrap, at, texel, artists) -> str:
    """A box beyond the border filled with the texel it stands for; its name ("col 3"), or ""
    inside the texture (r362 FIG1: u = 0.05's column −1 was an empty box): "repeat" tiles,
    "clamp" takes the border."""
    from matplotlib.patches import Rectangle

    h, w = shown.shape[:2]
    if 0 <= c < w and 0 <= r < h:
        return ""
    if wrap == "repeat":
        cw, rw = c % w, r % h
    else:
        cw, rw = min(max(c, 0), w - 1), min(max(r, 0), h - 1)
    grey = np.broadcast_to(np.clip(shown[rw, cw], 0, 1), (3,))
    corner = (at[0] + c * texel[0], at[1] + r * texel[1])
    artists.append(ax.add_patch(Rectangle(corner, *texel, facecolor=tuple(grey),
                                          edgecolor="none", zorder=0)))  # fmt: skip
    return f"col {cw}" if 0 <= r < h else f"row {rw}" if 0 <= c < w else f"({rw}, {cw})"


#: 7.3's "answer first" λ's, for a pyramid of 8 × 8 down to 1 × 1 (r375 F2: never answered)
QUESTION_LODS = (1.25, 3.4, -0.7)


def level_weights(q: int, lod: float) -> dict[int, float]:
    """{level: weight} trilinear blends at ``lod`` on levels 0 to ``q`` (one level where λ,
    clamped to [0, q], is whole)."""
    _, _, d0, d1, t = _split(range(q + 1), lod)
    return {d0: 1.0} if d0 == d1 or t == 0 else {d0: 1.0 - t, d1: t}


def _weights_words(q: int, lod: float) -> str:
    pairs = level_weights(q, lod)
    lam = min(max(lod, 0.0), q)
    clamped = "" if lam == lod else f" (λ clamped to {num(lam)})"
    if len(pairs) == 1:
        return f"level {next(iter(pairs))} alone{clamped}"
    return " + ".join(f"{num(t)}·level {d}" for d, t in pairs.items()) + clamped


def trilinear_questions(q: int) -> str:
    """7.3's question answered for levels 0 to ``q``: the levels and weights of each of
    :data:`QUESTION_LODS`."""
    said = "".join(f"\nλ = {num(lod)}: {_weights_words(q, lod)}" for lod in QUESTION_LODS)
    return f"7.3, on levels 0–{q}:{said}"


def draw_pyramid_case(ax, case, got):
    """7.3's case (r375 F5: level 0 was drawn, which λ = 1.5 does not read): before the
    method is earned every level side by side, each in (u, v) from 0 to 1, the point (×) on
    level 0 (r418 P1: on each, it answered 7.3's question whether (u, v) changes); with it (two different answers failed, or this one right) the levels λ reads, each
    with its four weighted texels and its level weight, the same (u, v) on both and the texels
    of the upper twice as large; a passing figure answers 7.3's λ's too."""
    from . import tries

    pyramid, uv, lod, wrap = case[1]
    q, lam, d0, d1, t = _split(pyramid, lod)
    passed = got is not None and same_value(got, case[2], None)
    method = got is not None and (tries.hints_spent("trilinear") or passed)
    weights = level_weights(q, lod) if method else {}
    shown = list(weights) if method else list(range(q + 1))
    artists, gap = [], 0.6 if method else 0.3  # r418 FIG2: "…, weight 0.75" met the next title
    for k, d in enumerate(shown):
        h, w = np.shape(pyramid[d])[:2]
        ox = k * (1 + gap)
        small = max(h, w) <= 8  # the weights written where a texel has room for them
        # r418 P1: before the method, the × on level 0 only (7.3 asks whether (u, v) changes)
        artists += draw_level(ax, pyramid[d], uv, wrap, at=(ox, 0.0), texel=(1 / w, 1 / h),
                              weights=method, labels=small, mark=method or k == 0)  # fmt: skip
        title = f"level {d} ({h}×{w})" + (f", weight {num(weights[d])}" if method else "")
        artists.append(ax.text(ox + 0.5, -0.04, title, ha="center", va="bottom",
                               fontsize=LABEL_SIZE))  # fmt: skip
    right = len(shown) * (1 + gap) - gap + 0.3
    if passed:  # 7.3's λ's beside the levels, inside the axes (its width follows the levels)
        artists.append(ax.text(right, 0.5, trilinear_questions(q), ha="left", va="center",
                               fontsize="x-small"))  # fmt: skip
    ax.set_xlim(-0.3, right + (2.2 if passed else 0.0))  # r418 FIG2: ")" met the frame
    ax.set_ylim(1.1, -0.2)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    where = "× on each level: the same (u, v)" if method else "× on level 0"
    text = f"uv = {vec(uv)} ({where}), λ = {num(lod)}"
    if method:
        text += f": {_weights_words(q, lod)}"
    if got is not None:
        text += f";\nthe filtered value is {_value(case[2], got)}{_yours(got, case[2])}"
    artists.append(ax.set_xlabel(text, fontsize="x-small"))
    return artists


# -- trilinear --------------------------------------------------------------------------------
def _trilinear_cases(rng, word):
    """λ below, on, between and above the levels; square and non-square pyramids; random."""
    p8, p84, p3 = (Pyramid(mipmap(_texture(rng, *s))) for s in ((8, 8), (8, 4), (8, 8, 3)))
    p32 = Pyramid(level.astype(np.float32) for level in mipmap(_texture(rng, 8, 8, 3)))
    hard = [
        ("λ = 0", p8, (0.3, 0.6), 0.0, "repeat"),
        ("λ = 1", p8, (0.3, 0.6), 1.0, "repeat"),
        ("λ between levels 1 and 2", p8, (0.3, 0.6), 1.5, "repeat"),
        ("λ = 0.25", p8, (0.71, 0.12), 0.25, "repeat"),
        ("λ = 2.75", p8, (0.71, 0.12), 2.75, "clamp"),
        ("λ < 0 (magnified)", p8, (0.4, 0.45), -2.0, "repeat"),
        ("λ = −0.5", p8, (0.3, 0.6), -0.5, "repeat"),
        ("λ = −0.25", p8, (0.71, 0.12), -0.25, "clamp"),
        ("λ = −1.75", p8, (0.55, 0.85), -1.75, "repeat"),
        ("λ = −3.4", p84, (0.2, 0.4), -3.4, "clamp"),
        ("λ = q, the 1×1 level", p8, (0.4, 0.45), 3.0, "repeat"),
        ("λ above the pyramid", p8, (0.4, 0.45), 7.0, "repeat"),
        ("λ = q + 0.5", p8, (0.6, 0.3), 3.5, "repeat"),
        ("a float32 pyramid (from imread), λ = 1.3", p32, (0.35, 0.65), 1.3, "repeat"),
        ("between the last two levels, at the border", p8, (0.02, 0.98), 2.5, "repeat"),
        ("between the last two levels, clamped at the border", p8, (0.02, 0.98), 2.5, "clamp"),
        ("a non-square pyramid (8×4, 4×2, 2×1, 1×1)", p84, (0.3, 0.8), 1.5, "repeat"),
        ("a non-square pyramid, λ = 2.25", p84, (0.9, 0.1), 2.25, "clamp"),
        ("three channels", p3, (0.55, 0.35), 0.75, "repeat"),
        ("λ = 1.25, 7.3's first question", p8, (0.3, 0.6), 1.25, "repeat"),  # r375 F5
    ]
    out = [(label, (pyr, np.array(uv, float), lod, wrap)) for label, pyr, uv, lod, wrap in hard]
    for n in range(12):
        h, w = (int(2 ** rng.integers(0, 5)) for _ in range(2))
        pyr = Pyramid(mipmap(_texture(rng, h, w, 3 if n % 4 == 1 else 0)))
        uv = np.round(rng.uniform(-0.5, 1.5, size=2), 4)
        lod = float(np.round(rng.uniform(-1, len(pyr)), 3))
        out.append((f"{word} {n + 1}: {h}×{w}", (pyr, uv, lod, ("repeat", "clamp")[n % 2])))
    return [
        (f"{label}, uv={vec(a[1])}{_lod_words(label, a[2])}, wrap={a[3]!r}", a,
         expected_trilinear(*a))
        for label, a in out
    ]  # fmt: skip


def _lod_words(label: str, lod: float) -> str:
    """ ", λ=…" unless the label is that already ("λ = 1": r64 07 D5, "λ = 1, …, λ=1")."""
    return "" if re.search(r"λ = [−\d.]+", label) else f", λ={num(lod)}"


trilinear_cases = fixed_and_drawn(_trilinear_cases, SEED + 90)  # r49: some drawn per check


def _split(pyramid, lod):
    q = len(pyramid) - 1
    lam = min(max(lod, 0.0), q)
    d0 = int(np.floor(lam))
    return q, lam, d0, min(d0 + 1, q), lam - d0


def explain_trilinear(args, expected, got) -> str:
    """The pyramid and the two values: how λ is clamped, which levels and their weight are
    what 7.3 asks to work out (r64 07 D1: every failure's header printed them); the slips and
    the rule (after two different wrong answers) say them."""
    pyramid, uv, lod, wrap = args
    sizes = [f"{lv.shape[0]}×{lv.shape[1]}" for lv in pyramid]
    return (
        f"a pyramid of {', '.join(sizes)} (q = {len(pyramid) - 1}): the filtered value is "
        f"{_value(expected, got)}; yours is {_value(got, expected)}"
    )


def trilinear_with(pyramid, uv, lod, wrap="repeat", *, clamp="lambda", weights="right",
                   levels="two", texels="bilinear", digits=None, lod_as=None):  # fmt: skip
    """trilinear with the usual mistakes as knobs (the defaults are GL's LINEAR_MIPMAP_LINEAR).

    ``clamp`` "weight" clamps the levels but weighs them by the raw λ − ⌊λ⌋, "extrapolate"
    weighs by λ minus the clamped lower level, "index" uses ⌊λ⌋ as a Python index (level −1
    is the last); ``weights="swapped"``; ``levels`` "nearest" (round(λ) alone), "round()"
    (the level Python's round() of the weight picks), "lower" (⌊λ⌋ alone) or "round for
    floor" (levels round(λ) and round(λ) + 1, weighted by λ − round(λ)), "round lower" (the
    same levels, weighted by λ − ⌊λ⌋), "coarsest first" (level d read as pyramid[q − d]);
    ``weights="half"`` (½ each between two levels); ``clamp="q - 1"``
    clamps λ to [0, q − 1]; ``weights="smoothstep"`` eases the weight, 3t² − 2t³ (r450 H6);
    ``digits`` rounds λ to that many decimals first (r450 H7); ``lod_as`` takes |λ|
    ("abs", :data:`ABS_LOD`), λ/2 ("half"), λ + ½ ("plus half") or λ held in float16 ("float16") for λ (r462); ``texels="level 0 size"`` filters every level with level 0's W
    and H (``"level 0 size, tiled"``: and tiles whatever the wrap); ``texels="nearest"`` filters each level with its nearest texel.
    """
    q = len(pyramid) - 1
    lod = lod if digits is None else round(float(lod), digits)
    lod = LOD_AS[lod_as](float(lod)) if lod_as else lod
    if clamp in ("lambda", "q - 1"):  # "q - 1": r286, the last level taken for q − 1
        lam = min(max(lod, 0.0), q if clamp == "lambda" else max(q - 1, 0))
        rounds = levels in ("round for floor", "round lower")
        lower = int(round(lam) if rounds else np.floor(lam))  # r317
        t = lam - (np.floor(lam) if levels == "round lower" else lower)  # r362
    else:
        lower = int(np.floor(lod))
        t = lod - lower
        if clamp in ("weight", "extrapolate"):
            lower = min(max(lower, 0), q)
            t = lod - lower if clamp == "extrapolate" else t
        elif not -len(pyramid) <= lower <= q:
            return None
    upper = min(lower + 1, q) if lower >= 0 else lower + 1

    def level(d):
        if texels.startswith("level 0 size"):  # r286: level 0's W and H for every level
            (h0, w0), (h, w) = np.shape(pyramid[0])[:2], np.shape(pyramid[d])[:2]
            uv_d = np.asarray(uv, dtype=float) * [w0 / w, h0 / h]
            tiled = {"wrap_as": "repeat"} if texels.endswith("tiled") else {}
            return plain_bilinear(pyramid[d], uv_d, wrap, **tiled)
        return _filter(pyramid[d], _level_uv(uv, d, texels), wrap, texels)

    if levels == "nearest":
        return level(int(np.clip(round(lod), 0, q)))
    if levels == "round()":  # r286: Python's round() of the weight, half to even
        return level(upper if round(t) else lower)
    if levels == "lower":
        return level(lower)
    if levels == "finest":
        return level(0)
    if levels == "upper":
        return level(upper)
    if levels == "coarsest first":  # r375 F9: pyramid[q − d] for level d
        lower, upper = q - lower, q - upper
    a, b = level(lower), level(upper)
    if texels == "upper uv halved":  # r426 F4: the coarser level read at (u, v)/2
        b = _filter(pyramid[upper], np.asarray(uv, dtype=float) / 2, wrap, "bilinear")
    if weights == "swapped":
        t = 1 - t
    if weights == "half":  # r375 F9: ½ each wherever λ lies between two levels
        t = 0.5 if 0 < t < 1 else t
    if weights == "smoothstep":
        t = t * t * (3 - 2 * t)
    return (1 - t) * a + t * b


#: r462 M1, H5: λ changed before its levels are taken (|λ| was told "Python's pyramid[-2]").
LOD_AS = {"abs": abs, "half": lambda lam: lam / 2, "plus half": lambda lam: lam + 0.5,
          "float16": lambda lam: float(np.float16(lam))}  # fmt: skip


#: How a mistaken trilinear filters one level: a bilinear mistake (of 7.2) as plain_bilinear's knob.
LEVEL_FILTERS = {
    "corners": {"origin": "corners"},
    "clamp": {"wrap_as": "clamp"},
    "swapped": {"swap": True},
    "transposed": {"transpose": True},
    "repeat": {"wrap_as": "repeat"},
}


def _level_uv(uv, d, texels):
    """(u, v) as a mistaken trilinear passes it to level ``d`` (scaled by 2^d or 2^−d: r64 07
    D4, uv taken for texel units that shrink with the level); unchanged otherwise."""
    scale = {"uv times 2^d": 2.0**d, "uv over 2^d": 2.0**-d}.get(texels, 1.0)
    return np.asarray(uv, dtype=float) * scale


def _filter(level, uv, wrap, texels):
    if texels == "nearest":
        return _nearest(level, uv, wrap)
    if texels in LEVEL_FILTERS:
        return plain_bilinear(level, uv, wrap, **LEVEL_FILTERS[texels])
    return expected_bilinear(level, uv, wrap)


_BILINEAR_FIRST = (
    ": each level is filtered with that mistake of bilinear (7.2); get bilinear's check to "
    "pass first, then build trilinear on it"
)


def _index_read(n, lower) -> str:
    """What ⌊λ⌋ < 0 reads as a Python index into a pyramid of ``n`` levels (r390 N2: "−1" and
    "the last one" were said whatever λ)."""
    said = f"⌊λ⌋ = {lower} is not a level"
    if lower < -n:
        return f"{said}: Python's pyramid[{lower}] raises IndexError"
    return f"{said}: Python's pyramid[{lower}] is level {n + lower}"


def _tri_words(text):
    def words(args, expected, got):
        pyramid, uv, lod, wrap = args
        q, lam, d0, d1, t = _split(pyramid, lod)
        near = int(np.clip(round(lod), 0, q))
        return text.format(
            d0=d0,
            d1=d1,
            t=num(t),
            near=near,
            lod=num(lod),
            q=q,
            lam=num(lam),
            off=num(lam - round(lam)),
            near_up=min(round(lam) + 1, q),
            index_read=_index_read(len(pyramid), int(np.floor(lod))),
            r0=q - d0,
            r1=q - d1,
            abs_lod=num(abs(lod)),
            half=num(lod / 2),
            plus=num(lod + 0.5),
            f16=num(float(np.float16(lod)), float(lod)),
            lod16=num(float(lod), float(np.float16(lod))),
        )

    return words


def _level0_tiled_words(args, expected, got) -> str:
    """Level 0's size, and every level tiled: the tiling said only where the case clamps."""
    tiled = ("" if args[3] == "repeat" else ", and tiled ('repeat') every level although this "
             f"case asks for wrap={args[3]!r}")  # fmt: skip
    return (f"you filtered every level with level 0's W and H (x = u·W₀ − ½){tiled}: each "
            "level's bilinear needs that level's own size, texel centres at (i + ½)/W_level")  # fmt: skip


TRILINEAR_KNOBS = Knobs(trilinear_with, {
    "clamp": [
        Slip("λ not clamped", _tri_words("λ = {lod} lies outside the pyramid: clamp it to "
             "[0, q] = [0, {q}] first, then take its levels and the weight (below 0 the texture "
             "is magnified and level 0 alone is filtered)"), "weight"),
        Slip("λ not clamped", _tri_words("λ = {lod} lies outside the pyramid: clamp it to "
             "[0, q] = [0, {q}] first; the weight λ − ⌊λ⌋ then stays in [0, 1]"),
             "extrapolate"),
        Slip("λ clamped to [0, q − 1]", _tri_words("λ = {lod}: you clamped λ to [0, q − 1]; "
             "the pyramid's levels run from 0 to q = {q} (the last, 1×1 level is level q), so "
             "clamp λ to [0, {q}]"), "q - 1"),
        Slip("λ not clamped", _tri_words("λ = {lod} lies outside the pyramid: clamp it to "
             "[0, q] = [0, {q}] first ({index_read})"), "index"),
    ],
    "weights": [Slip("weights swapped", _tri_words("the weight of level {d1} is the fraction "
                     "λ − ⌊λ⌋ = {t}; you gave it to level {d0}"), "swapped"),
                # r375 F9: told only the rule
                Slip("weights ½ each", _tri_words("you weighted the two levels ½ each whatever "
                     "λ's fraction, so the value jumps as λ moves; trilinear blends levels {d0} "
                     "and {d1}, level {d1} weighted by λ − ⌊λ⌋ = {t}"), "half"),
                # r450 H6: the generic hint's properties (continuous, exact at whole λ) hold
                Slip("weight eased (smoothstep)", _tri_words("your weight of level {d1} is "
                     "eased (3t² − 2t³, a smoothstep): the value must change linearly between "
                     "levels, level {d1} weighted by λ − ⌊λ⌋ = {t} itself"), "smoothstep")],
    # r462 M1, H5: |λ| was blamed on Python's pyramid[-2]; λ/2, λ + ½ and a float16 λ were
    # told the generic hint
    "lod_as": [Slip("λ halved", _tri_words("your value is that of λ/2 = {half}, not of λ = "
                    "{lod}: use λ as it comes"), "half"),
               Slip("λ + ½", _tri_words("your value is that of λ + ½ = {plus}, not of λ = {lod} "
                    "(a bias, or rounding to the nearer level prepared?): use λ as it comes"),
                    "plus half"),
               Slip("λ in float16", _tri_words("your value is that of λ = {lod16} held in float16 "
                    "({f16}: 11 significant bits): keep λ as it comes, in float64"), "float16")],
    # r450 H7: λ rounded before use was told the generic hint
    "digits": [Slip("λ rounded", _tri_words("your value is that of λ = {lod} rounded to "
                    "1 decimal: use λ as it comes, unrounded"), 1),
               Slip("λ rounded", _tri_words("your value is that of λ = {lod} rounded to "
                    "2 decimals: use λ as it comes, unrounded"), 2)],
    "levels": [
        Slip("nearest level", _tri_words("that is level {near} alone (the nearest); trilinear "
             "blends levels {d0} and {d1}"), "nearest"),
        Slip("round() for the nearest level", _tri_words("that is one level alone, chosen "
             "with Python's round(), which rounds halves to even (round(0.5) = 0, round(2.5) = "
             "2); and trilinear takes no level alone: it blends levels {d0} and {d1}, level "
             "{d1} weighted by λ − ⌊λ⌋ = {t}"), "round()"),
        # r317: round(λ) for ⌊λ⌋ was told only the rule
        Slip("round() for floor", _tri_words("you took round(λ) for the lower level: λ = "
             "{lam} rounds to level {near}, so the weight λ − round(λ) = {off} and the levels "
             "blended are {near} and {near_up}; trilinear blends levels ⌊λ⌋ = {d0} and {d1}, "
             "level {d1} weighted by λ − ⌊λ⌋ = {t}"), "round for floor"),
        # r362: round(λ) for the lower level, the weight still λ − ⌊λ⌋, was told the rule
        Slip("round() for floor", _tri_words("you took round(λ) for the lower level: λ = "
             "{lam} rounds to level {near}, so you blended levels {near} and {near_up}; "
             "trilinear blends levels ⌊λ⌋ = {d0} and {d1}, level {d1} weighted by λ − ⌊λ⌋ = "
             "{t}"), "round lower"),
        # r375 F9: told only the rule
        Slip("levels counted from the coarsest", _tri_words("you counted the levels from the "
             "coarsest: pyramid[0] is level 0, the full-size texture, and pyramid[{q}] the 1×1 "
             "level q = {q}; λ = {lam} reads pyramid[{d0}] and pyramid[{d1}], you read "
             "pyramid[{r0}] and pyramid[{r1}]"), "coarsest first"),
        Slip("lower level only", _tri_words("that is level {d0} alone; trilinear blends it with "
             "level {d1} by {t}"), "lower"),
        Slip("upper level only", _tri_words("that is level {d1} alone; trilinear blends it with "
             "level {d0}, level {d1} weighted by λ − ⌊λ⌋ = {t}"), "upper"),
        Slip("level 0 only", _tri_words("that is level 0 alone, whatever λ: λ = {lod} picks "
             "levels {d0} and {d1} (the texture is minified, level 0 would alias)"), "finest"),
    ],
    "texels": [
        Slip("nearest texels", "you took the nearest texel of each level; trilinear filters "
             "each level bilinearly, with its own size", "nearest"),
        Slip("uv scaled per level", "you scaled uv by 2^level for each level (the same as "
             "filtering every level with level 0's W and H); (u, v) is "
             "normalised, from 0 to 1 across every level whatever its size, and bilinear finds "
             "the level's texels from that level's own W and H: pass uv unchanged",
             "uv times 2^d"),
        Slip("uv scaled per level", "you divided uv by 2^level for each level; (u, v) is "
             "normalised, from 0 to 1 across every level whatever its size, and bilinear finds "
             "the level's texels from that level's own W and H: pass uv unchanged",
             "uv over 2^d"),
        # r426 F4: the upper level's (u, v) halved, 7.3's prediction's trap
        Slip("uv rescaled per level", _tri_words("you read level {d1}, the coarser, at (u, v)/2: "
             "(u, v) is the same on every level (normalised, from 0 to 1 across each level "
             "whatever its size); only the texel size changes, and each level's bilinear reads "
             "that level's own W and H: pass uv unchanged to both levels"), "upper uv halved"),
        # after "uv scaled per level", the same answer where every level halves exactly
        Slip("level 0's size for every level", "you filtered every level with level 0's W "
             "and H (x = u·W₀ − ½): each level's bilinear needs that level's own size, "
             "texel centres at (i + ½)/W_level", "level 0 size"),
        Slip("level 0's size for every level", _level0_tiled_words, "level 0 size, tiled"),
        Slip("bilinear: texel corners", "the levels are sampled at texel corners (x = u·W, "
             "not u·W − ½)" + _BILINEAR_FIRST, "corners"),
        Slip("bilinear: always clamp", "the levels are clamped at the border whatever the wrap "
             "mode" + _BILINEAR_FIRST, "clamp"),
        # r85 07 D3: `wrap` not passed on was told to rethink its levels and weights
        Slip("wrap not passed on", lambda a, e, g: f"every level is tiled ('repeat') although "
             f"this case asks for wrap={a[3]!r}: pass trilinear's `wrap` on to each bilinear "
             "call (the default 'repeat' is only the default)", "repeat", unread="wrap"),
        # r341 X-1: the same answer from a trilinear that reads its wrap and passes it on
        Slip("bilinear: ignores wrap", lambda a, e, g: f"every level is tiled ('repeat') "
             f"although this case asks for wrap={a[3]!r}, and your trilinear reads its `wrap`: "
             "the bilinear it calls tiles whatever wrap says (7.2: 'clamp' repeats the border "
             "texels outwards); get bilinear's check to pass first (or, if trilinear reads "
             "`wrap` without handing it to each bilinear call, pass it on)", "repeat",
             reads="wrap"),
        Slip("bilinear: weights swapped", "within each level the texel weights are swapped"
             + _BILINEAR_FIRST, "swapped"),
        Slip("bilinear: rows and columns swapped", "each level's rows and columns are swapped"
             + _BILINEAR_FIRST, "transposed"),
    ],
})  # fmt: skip


#: 7.3's rule for an answer no mistake explains, said once two different answers have failed,
#: and the question asked before (r49, r64 07 D1).
TRILINEAR_RULE = (
    ": clamp λ to [0, q]; filter levels ⌊λ⌋ and ⌊λ⌋ + 1 (at most q) bilinearly, each with its "
    "own size (texel centres at (i + ½)/W_level, uv unchanged), then blend them "
    "(1 − t)·level ⌊λ⌋ + t·level ⌊λ⌋+1 with t = λ − ⌊λ⌋"
)
TRILINEAR_HINT = (
    ": which levels does this λ lie between, and which does the pyramid have? Weigh two levels "
    "so that the value changes continuously, and linearly, with λ and is a level's own value "
    "at a whole λ"
)


#: r462 M1: |λ| was blamed on Python's pyramid[-2] (λ = −2 reads level 2 both ways); named
#: only where it gives every answer, so that ⌊λ⌋ = −2 used as an index keeps its words.
ABS_LOD = Mistake("|λ|", _tri_words("your value is that of |λ| = {abs_lod}: a negative λ (the "
                  "texture magnified) is clamped to 0, level 0 alone, not turned positive"),
                  gives=lambda pyramid, uv, lod, wrap: trilinear_with(pyramid, uv, lod, wrap,
                                                                      lod_as="abs"),
                  only_whole=True)  # fmt: skip


def _trilinear_rule(args, expected, got) -> str:
    return TRILINEAR_RULE


def no_level_above_q(args, error) -> str:
    """An IndexError where ⌊λ⌋, λ clamped, is the last level q (λ in [q, q + 1), where a
    missing clamp of λ changes no level): the upper level taken as ⌊λ⌋ + 1 without the
    "at most q" (r317: told "raised IndexError: list index out of range" only)."""
    pyramid, _, lod, _ = args
    q = len(pyramid) - 1
    if not error.startswith("your function raised IndexError") or lod < q:
        return ""
    if lod >= q + 1:  # r375 F9: λ clamped to len(pyramid), or not at all, was told the error
        return (f": at λ = {num(lod)}, above the pyramid, λ clamped to [0, q] = [0, {q}] "
                f"reads level {q} alone: q = len(pyramid) − 1 is the last level's number, and "
                f"pyramid[{q + 1}] is out of range; clamp λ to [0, q] before taking its levels")  # fmt: skip
    return (f": at λ = {num(lod)}, ⌊λ⌋ = {q} is already the last level, q = {q}, and there "
            f"is no level q + 1 = {q + 1} (pyramid[{q + 1}] is out of range): the upper level "
            "is ⌊λ⌋ + 1 at most q, so here level q is blended with itself")  # fmt: skip


def trilinear_exercise(scene) -> Exercise:
    return Exercise(
        "trilinear", trilinear_cases, as_texel_value, same_value, explain_trilinear,
        _trilinear_rule, [CHANNELS, ABS_LOD, TRILINEAR_KNOBS], answers=_answers("trilinear"),
        draw=draw_texture_case, scene=scene,
        hints=((TRILINEAR_RULE, TRILINEAR_HINT), *CLAMP_HINTS, *NAMED_HINTS),
        once=((TRILINEAR_RULE, ": as said for the first failing case"),),
        inputs_drawn=True, raised_words=no_level_above_q,
        example=19,  # r375 F5: λ = 1.25, 7.3's first question (r362: λ = 0 was level 0 alone)
    )  # fmt: skip
