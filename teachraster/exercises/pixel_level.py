"""Exercise ``pixel_lod(xy, w, uv, size, row, col)`` (lesson 09): the λ a GPU uses at a pixel.

Lesson 09's steps composed (r390 F1: 7.1's λ and 7.4's quad differences each copied one
printed formula): the pixel's 2×2 quad (aligned to even rows and columns), the triangle's
perspective-correct (u, v) at its lanes (helper lanes extrapolated, never clamped), the coarse
differences ddx = upper right − upper left and ddy = lower left − upper left, both scaled to
texels of level 0 (u by W, v by H), ρ the longer of the two steps' Euclidean lengths and
λ = log2 ρ, unclamped. The task prints none of these as one formula.

Expected answers: the renderer's own quad lanes (:func:`.quad_difference.lanes`) and
:func:`teachraster.mip_level`; its typical mistakes are the quad's (the pixel's own quad,
odd quads, helpers clamped, affine values, fine or centred differences, other lanes of the
quad, which GL and Direct3D allow: r415) and the level's (no scaling to texels, W and H
swapped, u alone, one step alone, the axes' mean, λ clamped at 0, rounded). An answer that
does not behave like a λ (it ignores the triangle's (u, v), does not grow by 1 as the steps
double) is told so and never brings the steps (r415 F1, r418 F1).
"""

from __future__ import annotations

import math
import textwrap

import numpy as np

from ..core.barycentrics import barycentric
from ..pipeline.texture_filters import mip_level
from ..pipeline.texturing.quad_derivatives import lane_values
from .answers import as_number, short
from .cases import SEED, fixed_and_drawn
from .exercise import Exercise, Mistake, PackageAnswer, variant_mistakes
from .level_of_detail import level_with
from .quad_difference import FLOOR, inside, lanes, value_at
from .running import WrongAnswerType
from .scalars import num, vec
from .tolerance import close

#: The floor of 7.4 with a texture tiled over it: u across, v into the distance.
FLOOR_UV = np.array([[0.0, 0.0], [4.0, 0.0], [2.0, 8.0]])


def quad_steps(xy, w, uv, row: int, col: int) -> tuple[np.ndarray, np.ndarray]:
    """(ddx, ddy) of (u, v) at pixel (row, col): the renderer's coarse quad differences."""
    r0, c0 = row - row % 2, col - col % 2
    q = np.stack([lanes(xy, w, np.asarray(uv, float)[:, k], r0, c0) for k in (0, 1)], axis=1)
    return q[1] - q[0], q[2] - q[0]


def expected_lod(xy, w, uv, size, row: int, col: int) -> float:
    ddx, ddy = quad_steps(xy, w, uv, row, col)
    return float(mip_level(ddx, ddy, size))


def _lod_cases(rng, word):
    """The floor's pixels (both steps deciding, helpers outside its edges, odd and even lanes)
    on square and non-square textures, magnified too; seeded random triangles."""
    xy, w, _ = FLOOR
    pixels = [(28, 14, (64, 64), 1.0, "inside, the quad's upper-left lane"),
              (29, 15, (64, 64), 1.0, "inside, the quad's lower-right lane"),
              (27, 3, (64, 64), 1.0, "next to the left edge: helpers outside"),
              (5, 14, (64, 64), 1.0, "at the far tip: the step down decides"),
              (20, 25, (64, 64), 1.0, "next to the right edge"),
              (29, 29, (64, 64), 1.0, "the near right corner"),
              (13, 11, (32, 128), 1.0, "a wide texture (H = 32, W = 128)"),
              (23, 17, (128, 16), 1.0, "a tall texture (H = 128, W = 16)"),
              (29, 15, (64, 64), 1 / 32, "magnified: (u, v) over 1/32 of the texture"),
              (27, 3, (64, 64), 1 / 32, "magnified, next to the left edge")]  # fmt: skip
    out = [(f"floor, pixel ({r}, {c}), size={size}: {why}", (xy, w, FLOOR_UV * s, size, r, c))
           for r, c, size, s, why in pixels]  # fmt: skip
    for k in range(10):
        txy = np.round(rng.uniform(0, 24, (3, 2)) * 256) / 256
        tw = np.exp(rng.uniform(0, np.log(10), 3))
        tuv = np.round(rng.uniform(-2, 2, (3, 2)), 2)
        size = (int(2 ** rng.integers(3, 9)), int(2 ** rng.integers(3, 9)))
        r, c = (int(v) for v in txy.mean(axis=0)[::-1])
        out.append((f"{word} {k + 1}, pixel ({r}, {c}), size={size}", (txy, tw, tuv, size, r, c)))
    return [(label, args, expected_lod(*args)) for label, args in out]


lod_cases = fixed_and_drawn(_lod_cases, SEED + 75)  # r49: some drawn per check


def same_lod(got, expected, args) -> bool:
    """Within 1e-5 (lanes in float32 pass: their differences lose some digits)."""
    return close(got, expected, 1e-5)


def explain_lod(args, expected, got) -> str:
    """The two λ's only: the quad, its lanes and the steps are what 7.1 asks to work out."""
    return f"λ = {num(expected, got)}; yours is {num(got, expected)}"


def _uv_at(xy, w, uv, x, y, **kw) -> np.ndarray:
    return np.array([value_at(xy, w, np.asarray(uv, float)[:, k], x, y, **kw) for k in (0, 1)])


def _unnormalised(xy, w, uv, x, y) -> np.ndarray:
    """(u, v) at (x, y) weighted by λ/w without dividing by the weights' sum (r418 F2)."""
    mu = barycentric(xy, [[x, y]])[0] / np.asarray(w, float)
    return mu @ np.asarray(uv, float)


def _steps(xy, w, uv, r, c, centre=0.5, **kw):
    """(ddx, ddy) from the quad whose upper-left pixel is (r, c), values taken as ``kw`` says."""
    a = _uv_at(xy, w, uv, c + centre, r + centre, **kw)
    return (_uv_at(xy, w, uv, c + 1 + centre, r + centre, **kw) - a,
            _uv_at(xy, w, uv, c + centre, r + 1 + centre, **kw) - a)  # fmt: skip


def _ceil(lam) -> float | None:
    return None if lam is None else float(math.ceil(lam))


def _log2(rho) -> float | None:
    return math.log2(rho) if rho > 0 else None


def _variants(xy, w, uv, size, row, col) -> dict:
    """Each typical mistake's λ on this case (None where it has none)."""
    r0, c0 = row - row % 2, col - col % 2
    h, wt = size
    ddx, ddy = quad_steps(xy, w, uv, row, col)

    def lod(steps, **kw):
        return level_with(steps[0], steps[1], size, **kw)

    at = (col + 0.5, row + 0.5)
    fine = (_uv_at(xy, w, uv, c0 + 1.5, at[1]) - _uv_at(xy, w, uv, c0 + 0.5, at[1]),
            _uv_at(xy, w, uv, at[0], r0 + 1.5) - _uv_at(xy, w, uv, at[0], r0 + 0.5))  # fmt: skip
    centred = ((_uv_at(xy, w, uv, at[0] + 1, at[1]) - _uv_at(xy, w, uv, at[0] - 1, at[1])) / 2,
               (_uv_at(xy, w, uv, at[0], at[1] + 1) - _uv_at(xy, w, uv, at[0], at[1] - 1)) / 2)  # fmt: skip
    return {
        "the pixel's own quad": lod(_steps(xy, w, uv, row, col)),
        "quad of pixel (col, row)": lod(_steps(xy, w, uv, col - col % 2, row - row % 2)),
        "odd quads": lod(_steps(xy, w, uv, row - (row + 1) % 2, col - (col + 1) % 2)),
        # r509 H2: the quad snapped along one axis only was told the generic hint
        "column not snapped": None if col % 2 == 0 else lod(_steps(xy, w, uv, r0, col)),
        "row not snapped": None if row % 2 == 0 else lod(_steps(xy, w, uv, row, c0)),
        "helpers clamped": lod(_steps(xy, w, uv, r0, c0, clamp=True)),
        "affine": lod(_steps(xy, w, uv, r0, c0, affine=True)),
        "λ·w": lod(_steps(xy, w, uv, r0, c0, times_w=True)),
        "weights not normalised": lod(_unnormalised_steps(xy, w, uv, r0, c0)),
        **_other_lanes(xy, w, uv, r0, c0, lod),
        "quad index as its pixel": lod(_steps(xy, w, uv, row // 2, col // 2)),
        "corners": lod(_steps(xy, w, uv, r0, c0, centre=0.0)),
        "fine": lod(fine),
        "centred": lod(centred),
        "no texels": lod((ddx, ddy), scale="units"),
        "divided by the size": _log2(
            max(np.hypot(ddx[0] / wt, ddx[1] / h), np.hypot(ddy[0] / wt, ddy[1] / h))
        ),  # fmt: skip
        "W and H swapped": lod((ddx, ddy), scale="swapped"),
        "W − 1 and H − 1": level_with(ddx, ddy, (h - 1, wt - 1)),
        # r450 H1: one scale for both axes on a non-square texture was told the generic hint
        "max(H, W) for both": (
            None if h == wt else _log2(max(h, wt) * max(np.hypot(*ddx), np.hypot(*ddy)))
        ),
        # r497 H2: W (or H) for both axes, as on a square texture, was told the generic hint
        "W for both": None if h == wt else _log2(wt * max(np.hypot(*ddx), np.hypot(*ddy))),
        "H for both": None if h == wt else _log2(h * max(np.hypot(*ddx), np.hypot(*ddy))),
        "u alone": _log2(max(abs(ddx[0]), abs(ddy[0])) * wt),
        "v alone": _log2(max(abs(ddx[1]), abs(ddy[1])) * h),
        "ddx alone": lod((ddx, ddy), combine="x only"),
        "ddy alone": lod((ddx, ddy), combine="y only"),
        "mean of the steps": lod((ddx, ddy), combine="mean"),
        "sum of the steps": lod((ddx, ddy), combine="sum"),
        "largest component": lod((ddx, ddy), norm="max"),
        "clamped at 0": lod((ddx, ddy), clamp=True),
        "ρ itself": lod((ddx, ddy), log="none"),
        "rounded": lod((ddx, ddy), log="round"),
        "rounded down": lod((ddx, ddy), log="floor"),
        "rounded up": _ceil(lod((ddx, ddy))),
        # r462 H7 (r450 H2): λ held in float16 was told "does not behave like a λ"
        "float16": None if (right := lod((ddx, ddy))) is None else float(np.float16(right)),
        "backward differences": lod(_backward_steps(xy, w, uv, row, col)),
        **_log_slips(xy, w, uv, size, row, col),
    }


def _backward_steps(xy, w, uv, row, col):
    """r462 H4: (u, v) here minus at the pixel to the left, and minus at the pixel above."""
    here = _uv_at(xy, w, uv, col + 0.5, row + 0.5)
    return (here - _uv_at(xy, w, uv, col - 0.5, row + 0.5),
            here - _uv_at(xy, w, uv, col + 0.5, row - 0.5))  # fmt: skip


#: r415 F2: the coarse differences from other lanes of the quad, (row of ddx, column of ddy),
#: each lane 0 or 1 from the upper-left; "rows averaged" averages both rows and both columns.
OTHER_LANES = {"ddx from the lower row": (1, 0), "ddy from the right column": (0, 1),
               "ddx lower row, ddy right column": (1, 1), "rows averaged": None}  # fmt: skip


def _unnormalised_steps(xy, w, uv, r0, c0):
    """(ddx, ddy) from lanes whose (u, v) is weighted by λ/w, never divided by Σ λ/w."""
    a = _unnormalised(xy, w, uv, c0 + 0.5, r0 + 0.5)
    return (_unnormalised(xy, w, uv, c0 + 1.5, r0 + 0.5) - a,
            _unnormalised(xy, w, uv, c0 + 0.5, r0 + 1.5) - a)  # fmt: skip


def _other_lanes(xy, w, uv, r0, c0, lod) -> dict:
    """λ from the quad's other rows and columns (GL and Direct3D allow them: llvmpipe's are
    the upper row and the left column), and from both averaged."""
    at = {
        (dr, dc): _uv_at(xy, w, uv, c0 + dc + 0.5, r0 + dr + 0.5) for dr in (0, 1) for dc in (0, 1)
    }
    out = {}
    for kind, lanes_used in OTHER_LANES.items():
        if lanes_used is None:
            steps = ((at[0, 1] - at[0, 0] + at[1, 1] - at[1, 0]) / 2,
                     (at[1, 0] - at[0, 0] + at[1, 1] - at[0, 1]) / 2)  # fmt: skip
        else:
            r, c = lanes_used
            steps = (at[r, 1] - at[r, 0], at[1, c] - at[0, c])
        out[kind] = lod(steps)
    return out


def _lanes_words(kind: str):
    """The lanes of mistake ``kind``, and that GL and Direct3D allow other lanes."""
    used = OTHER_LANES[kind]
    which = ("you averaged the quad's two rows for ddx and its two columns for ddy: GL "
             "(dFdxCoarse) lets a GPU approximate the derivative within the quad, but"
             if used is None else
             f"your ddx comes from the quad's {('upper', 'lower')[used[0]]} row and your ddy "
             f"from its {('left', 'right')[used[1]]} column: GL (dFdxCoarse) and Direct3D "
             "(ddx_coarse) let a GPU take other lanes of the quad, so a conforming GPU may "
             "give your λ; but")  # fmt: skip
    return (f"{which} the task asks for llvmpipe's λ, and llvmpipe differences the upper-left "
            "lane's row and column (lesson 09 §2)")  # fmt: skip


def _log_slips(*args) -> dict:
    """r405 F3: the slips of the last step, told from λ's numbers: twice λ (log2 of ρ²), the
    natural log (λ·ln 2), λ / ln 2, and the shorter step's λ."""
    lx, ly = _axes(args)
    lam = _log2(max(lx, ly))
    if lam is None:
        return {}
    ddx, ddy = (np.asarray(d) * [args[3][1], args[3][0]] for d in quad_steps(*args[:3], *args[4:]))
    area = abs(float(ddx[0] * ddy[1] - ddx[1] * ddy[0]))
    return {"log2 of ρ²": 2 * lam, "natural log": lam * math.log(2),
            # r462 H4: both steps' lengths combined, and the footprint's area
            "both lengths combined": _log2(math.hypot(lx, ly)),
            "area": None if area == 0 else 0.5 * math.log2(area),
            "divided by ln 2": lam / math.log(2), "the shorter step": _log2(min(lx, ly)),
            "log2 of 1 + ρ": math.log2(1 + max(lx, ly))}  # fmt: skip


def _axes(args) -> tuple[float, float]:
    xy, w, uv, (h, wt), row, col = args
    ddx, ddy = quad_steps(xy, w, uv, row, col)
    return float(np.hypot(ddx[0] * wt, ddx[1] * h)), float(np.hypot(ddy[0] * wt, ddy[1] * h))


def _one_step(which: str):
    def words(args, expected, got) -> str:
        lx, ly = _axes(args)
        other, mine = ("down (ddy)", num(ly)) if which == "ddx" else ("right (ddx)", num(lx))
        return (f"your λ follows the step {'right' if which == 'ddx' else 'down'} alone; here "
                f"the step {other} is {mine} texels long: which of the two steps must λ "
                "follow so that neither skips texels?")  # fmt: skip

    return words


def _own_quad(args, expected, got) -> str:
    row, col = args[4], args[5]
    return (f"you differenced from pixel ({row}, {col}) itself, as if its quad began there: "
            "which 2×2 quad of lesson 09 §2 holds this pixel, and which lanes of it does a "
            "coarse difference use?")  # fmt: skip


def _clamped(args, expected, got) -> str:
    smaller = "smaller" if got < expected else "larger"
    return ("your (u, v) at a helper lane (a quad pixel outside the triangle) stops at the "
            f"triangle, so the step across the edge comes out wrong (λ {smaller}): what does "
            "the triangle's interpolation give past its edge?")  # fmt: skip


MISTAKES = {
    "the pixel's own quad": _own_quad,
    "quad of pixel (col, row)": lambda a, e, g: (
        f"you differenced the quad of pixel ({a[5]}, {a[4]}): row and col swapped; the quad's "
        "upper-left lane is found from the row (y) and the column (x) of this pixel"
    ),
    "odd quads": "your quads start on odd rows and columns: which pixel is the upper-left lane "
    "of the quad that holds this one?",
    "column not snapped": lambda a, e, g: (
        f"you differenced from pixel ({a[4] - a[4] % 2}, {a[5]}): the row is snapped to the "
        "quad's but the column is not; the quad's upper-left lane sits at an even row and an "
        f"even column, here ({a[4] - a[4] % 2}, {a[5] - a[5] % 2})"
    ),
    "row not snapped": lambda a, e, g: (
        f"you differenced from pixel ({a[4]}, {a[5] - a[5] % 2}): the column is snapped to the "
        "quad's but the row is not; the quad's upper-left lane sits at an even row and an "
        f"even column, here ({a[4] - a[4] % 2}, {a[5] - a[5] % 2})"
    ),
    "helpers clamped": _clamped,
    "affine": "you interpolated (u, v) affinely at the lanes: which interpolation does a "
    "texture coordinate get across a triangle whose vertices lie at different depths "
    "(lesson 04)?",
    "λ·w": "your lanes' (u, v) weight each vertex by w: perspective-correct interpolation "
    "divides by w (lesson 04): which weights does a vertex get, λ·w or λ/w?",
    "weights not normalised": "your lanes' (u, v) weight each vertex by λ/w but the weights "
    "are not normalised: λ/w of the three vertices do not sum to 1, so (u, v) comes out "
    "scaled (lesson 04): what must the weighted sum be divided by?",
    **{kind: _lanes_words(kind) for kind in OTHER_LANES},
    "quad index as its pixel": lambda a, e, g: (
        f"you took pixel ({a[4] // 2}, {a[5] // 2}) as the quad's upper-left lane: row // 2 "
        "numbers the quad; which pixel is its upper-left lane?"
    ),
    "corners": "you took (u, v) at the pixels' corners (col, row): where is a lane shaded?",
    "fine": "these are fine differences (each pixel its own row and column of the quad): the "
    "λ a texture reads here is the coarse one, one pair per quad, the same for its four "
    "pixels",
    "centred": "you took a centred difference around the pixel, across two pixels: a GPU has "
    "only the four lanes of the pixel's own quad, one pixel apart",
    "no texels": lambda a, e, g: (
        "your steps are in texture units (u and v run over [0, 1]): "
        f"λ counts texels of level 0; how many texels long is this texture along u, and along v "
        f"(size = {a[3]})?"
    ),
    "divided by the size": lambda a, e, g: (
        f"you divided the steps by the size ({a[3]}): a step of u = 1/W crosses one texel, "
        "so is a step in texels u·W or u / W?"
    ),
    "W and H swapped": lambda a, e, g: (
        f"size = {a[3]} is (H, W): you scaled u by H = "
        f"{a[3][0]} and v by W = {a[3][1]}, or you read uv's columns as (v, u) (the same "
        "numbers); u is uv's first column and counts the W texels of a row: which scales it?"
    ),
    "max(H, W) for both": lambda a, e, g: (
        f"you scaled both u and v by max(H, W) = {max(a[3])}: u counts the W = {a[3][1]} texels "
        f"of a row and v the H = {a[3][0]} texels of a column, so a step (du, dv) crosses "
        "(du·W, dv·H) texels"
    ),
    "W for both": lambda a, e, g: (
        f"you scaled both u and v by W = {a[3][1]}, as if the texture were square: v counts the "
        f"H = {a[3][0]} texels of a column, so a step (du, dv) crosses (du·W, dv·H) texels"
    ),
    "H for both": lambda a, e, g: (
        f"you scaled both u and v by H = {a[3][0]}, as if the texture were square: u counts the "
        f"W = {a[3][1]} texels of a row, so a step (du, dv) crosses (du·W, dv·H) texels"
    ),
    "W − 1 and H − 1": lambda a, e, g: (
        f"you scaled u by W − 1 = {a[3][1] - 1} and v by H − 1 = {a[3][0] - 1}: a texture of W "
        "texels spans W texel widths from u = 0 to u = 1; how many texels does a step of u "
        "cross?"
    ),
    "u alone": "your ρ follows u alone; a pixel step moves v too: how far, in texels, does one "
    "step move (u, v) as a straight line?",
    "v alone": "your ρ follows v alone; a pixel step moves u too: how far, in texels, does one "
    "step move (u, v) as a straight line?",
    "ddx alone": _one_step("ddx"),
    "ddy alone": _one_step("ddy"),
    "mean of the steps": lambda a, e, g: (
        "your ρ is the mean of the two steps' lengths "
        f"({num(_axes(a)[0])} and {num(_axes(a)[1])} texels): at that level the longer step "
        "still skips texels"
    ),
    "sum of the steps": lambda a, e, g: (
        "your ρ adds the two steps' lengths "
        f"({num(_axes(a)[0])} and {num(_axes(a)[1])} texels): the picture blurs more than it "
        "must; which one length decides whether a step skips texels?"
    ),
    "largest component": "each step's length is its larger component here: GL (§8.14.1) "
    "allows that approximation, but this task asks for llvmpipe's exact lengths; a step of 3 "
    "texels across and 4 down: how long is it?",
    "clamped at 0": "your λ is clamped at 0: here the texture is magnified and λ is "
    "negative; leave it unclamped (7.3's sampler keeps it within the pyramid)",
    "ρ itself": "you returned ρ itself: λ counts the halvings of the texel size",
    "log2 of ρ²": lambda a, e, g: (
        f"your λ is exactly twice the right one ({num(g)} = 2 × {num(e)}): that is log2 of ρ², "
        "the squared length; λ is log2 of the length itself"
    ),
    "natural log": "your λ is the right one times ln 2: that is the natural logarithm of ρ; "
    "λ counts halvings, so which base?",
    "divided by ln 2": "your λ is the right one divided by ln 2: log2 taken twice over (a "
    "log2 divided by ln 2 again)? λ = log2 ρ once",
    "the shorter step": lambda a, e, g: (
        f"your λ follows the shorter step ({num(min(_axes(a)))} texels; the other is "
        f"{num(max(_axes(a)))}): along the longer one a texel of that level is skipped; which "
        "step must λ follow so that neither skips texels?"
    ),
    "rounded": "you rounded λ to a whole number: λ is fractional in general (7.3 blends the "
    "two levels around it)",
    "rounded down": "you rounded λ down to a whole level: λ is fractional in general (7.3 "
    "blends the two levels around it)",
    "rounded up": "you rounded λ up to a whole level (⌈λ⌉): λ is fractional in general (7.3 "
    "blends the two levels around it)",
    "float16": lambda a, e, g: (
        f"your λ is the right one rounded to float16 ({num(e)} held as {num(g)}: 11 "
        "significant bits): compute λ in float64 and return it as it is"
    ),
    "backward differences": lambda a, e, g: (
        f"you differenced pixel ({a[4]}, {a[5]}) with the pixels to its left and above it: "
        "a GPU differences within the pixel's own 2×2 quad only (lesson 09 §2), upper right − "
        "upper left and lower left − upper left, the same pair for the quad's four pixels"
    ),
    "both lengths combined": lambda a, e, g: (
        "your ρ is √(|ddx|² + |ddy|²), both steps' lengths combined "
        f"({num(_axes(a)[0])} and {num(_axes(a)[1])} texels): the longer step alone decides "
        "whether a step skips texels"
    ),
    "area": "your λ is ½·log2 of the area |ddx × ddy| the pixel covers in texels (the "
    "footprint's geometric mean): a long, thin footprint then gets too fine a level and its "
    "longer step skips texels; λ follows the longer step's length",
    "log2 of 1 + ρ": lambda a, e, g: (
        f"your λ is log2(1 + ρ) (ρ = {num(max(_axes(a)))} texels, the longer step): λ counts "
        "halvings of ρ itself, so one texel per step (ρ = 1) is level 0 and a magnified "
        "texture (ρ < 1) gives λ < 0; a ρ of 0 never occurs on a triangle the check draws"
    ),
}


#: 7.1's steps for an answer no mistake explains, said once two different answers have
#: failed, and the question asked before.
RULE = (
    ": take the quad whose upper-left pixel is (row − row mod 2, col − col mod 2); (u, v) "
    "perspective-correct at its lanes' centres (extrapolated at helpers); ddx = upper right − "
    "upper left, ddy = lower left − upper left; each scaled to texels (u·W, v·H); "
    "λ = log2 of the longer Euclidean length"
)
HINT = (
    ": which quad holds this pixel and which of its lanes are differenced; (u, v) at each "
    "lane: which interpolation, and past the edge?; how many texels of level 0 does each step "
    "cross; which step decides? Work this case through by hand"
)


#: The student's pixel_lod whose check is running (set by :func:`_call`), for :func:`_rule`.
_RUNNING: dict = {}


def as_lod(value):
    """One number: an array that holds one (shape (1,), a row of barycentric's (1, 3) kept)
    is not one, as docs/exercises.md says shapes must match (r450 S1: it passed)."""
    try:
        shape, size = np.shape(value), np.size(value)
    except Exception:  # noqa: BLE001 - as_number explains what this is
        shape, size = (), 0
    if shape and size == 1 and not isinstance(value, str):  # other sizes: as_number's words
        raise WrongAnswerType(f"returned {short(value)}, an array of shape {shape}, not one "
                              "number: λ is one number (float(…), or [0] where a (1, …) row "
                              "of barycentric's was kept)")  # fmt: skip
    return as_number(value)


def _call(fn, args):
    """The student's answer on one case, the function noted for :func:`_rule`."""
    _RUNNING["fn"] = getattr(fn, "fn", fn)  # the checker's recorder holds it as ``fn``
    return as_lod(fn(*args))


def again(fn, args) -> float | None:
    """The student's ``fn`` on ``args`` as one finite number, or None (it raised, gave no
    number, or NaN)."""
    try:
        value = float(np.ravel(np.asarray(fn(*args), dtype=float))[0])
    except Exception:  # noqa: BLE001 - the student's code: no number
        return None
    return value if math.isfinite(value) else None


def other_quads(xy, row: int, col: int, most: int = 4) -> list[tuple[int, int]]:
    """Up to ``most`` pixels (row, col) whose centres triangle ``xy`` covers, outside pixel
    (row, col)'s 2 × 2 quad, farthest first: where a value that depends on the pixel differs
    from this one's (r426 F2, F3)."""
    xy = np.asarray(xy, dtype=float)
    (x0, y0), (x1, y1) = np.clip(xy.min(0), -512, 512), np.clip(xy.max(0), -512, 512)
    found = [(r, c) for r in range(int(np.floor(y0)), int(np.ceil(y1)))
             for c in range(int(np.floor(x0)), int(np.ceil(x1)))
             if (r // 2, c // 2) != (row // 2, col // 2) and inside(xy, c + 0.5, r + 0.5)]  # fmt: skip
    found.sort(key=lambda p: -math.hypot(p[0] - row, p[1] - col))
    return found[:most]


def _one_per_triangle(fn, args, expected, got):
    """(pixel, its λ, yours there) at a pixel of another quad of this triangle where λ differs
    from this one's and the student's λ does not, or None (r426 F3: a λ per triangle, texel
    area over pixel area, counted as a try)."""
    xy, w, uv, size, row, col = args
    if fn is None or got is None or not math.isfinite(float(got)):
        return None
    far = [(abs(there - expected), (r, c), there) for r, c in other_quads(xy, row, col)
           for there in [expected_lod(xy, w, uv, size, r, c)]]  # fmt: skip
    if not far or max(far)[0] < 1e-3:
        return None  # λ the same all over (an affine triangle): nothing to tell
    _, (r, c), there = max(far)
    mine = again(fn, (np.array(xy, float), np.array(w, float), np.array(uv, float), size, r, c))
    same = mine is not None and abs(mine - float(got)) < 1e-9
    return ((r, c), there, mine) if same else None


def _per_triangle_words(args, expected, got) -> str:
    (r, c), there, _ = _one_per_triangle(_RUNNING.get("fn"), args, expected, got)
    return (f"one λ for the whole triangle: λ varies per quad (at pixel ({r}, {c}), another "
            f"quad of this triangle, it is {num(there)}; here {num(expected)}); yours is "
            f"{num(got)} at both. A GPU takes λ from the steps of (u, v) across this pixel's own "
            "quad, not from the triangle as a whole (texel area over pixel area, or an edge's "
            "length)")  # fmt: skip


#: Checked before the table (a per-triangle λ may match no variant's value, or one by chance).
PER_TRIANGLE = Mistake(
    "one λ for the whole triangle", _per_triangle_words,
    fits=lambda a, e, g: _lod_like(_RUNNING.get("fn"), a, g)
    and _one_per_triangle(_RUNNING.get("fn"), a, e, g) is not None,
)  # fmt: skip


def _lod_like(fn, args, got) -> bool:
    """Does ``fn`` grow by 1 where the triangle's (u, v) doubles and where the texture's size
    doubles, as any λ built from steps in texels does (:func:`_not_tried`)?"""
    xy, w, uv, size, row, col = args
    if fn is None or got is None or not math.isfinite(float(got)):
        return False
    more = (np.array(xy, float), np.array(w, float))
    by_uv = again(fn, (*more, np.asarray(uv, float) * 2, size, row, col))
    by_size = again(fn, (*more, np.array(uv, float), (2 * size[0], 2 * size[1]), row, col))
    return all(x is not None and abs(x - got - 1) < 1e-3 for x in (by_uv, by_size))


#: How far from λ a try that behaves like a λ may lie and still count as an attempt at the
#: task (r418 F1): 2, ρ within a factor of 4.
NEAR = 2.0


def _not_tried(fn, args, expected, got) -> str | None:
    """Why the failing answer ``got`` shows no attempt at λ (the words, with :data:`HINT`), or
    None for an attempt (r418 F1: ``uv[1][0] + uv[2][1]`` and then ``np.sum(uv) + size[0]``,
    junk that reads uv, were two tries that unlocked the steps). Any λ built from steps in
    texels grows by exactly 1 when the triangle's (u, v) doubles, and by 1 when the texture's
    size doubles, and stays when 1 is added to every (u, v); an attempt does all three and
    lies within :data:`NEAR` of λ."""
    xy, w, uv, size, row, col = args
    if fn is None or got is None or not math.isfinite(float(got)):
        return None
    more = (np.array(xy, float), np.array(w, float))
    by_uv = again(fn, (*more, np.asarray(uv, float) * 2, size, row, col))
    by_size = again(fn, (*more, np.array(uv, float), (2 * size[0], 2 * size[1]), row, col))
    moved = again(fn, (*more, np.asarray(uv, float) + 1, size, row, col))  # the same steps
    grew = [x is not None and abs(x - got - 1) < 1e-3 for x in (by_uv, by_size)]
    if all(grew) and (moved is None or abs(moved - got) > 1e-3):
        return (f": with 1 added to every vertex's u and v (the same steps, the same λ) your "
                f"λ goes from {num(got)} to {'no number' if moved is None else num(moved)}: λ "
                "depends on how (u, v) changes from pixel to pixel, not on (u, v) itself:"
                + HINT[1:])  # fmt: skip
    if all(grew) and _one_per_triangle(fn, args, expected, got) is not None:
        return ": " + _per_triangle_words(args, expected, got) + ":" + HINT[1:]
    if all(grew) and abs(got - expected) <= NEAR:
        return None
    if all(grew):
        return (f": your λ grows by 1 when the steps double, as a λ does, but it is "
                f"{num(abs(got - expected))} from the right one (your ρ off by a factor of "
                f"{num(2 ** abs(got - expected))}):" + HINT[1:])  # fmt: skip
    if by_uv is not None and abs(by_uv - got) < 1e-9:
        return (f": with this triangle's (u, v) doubled your λ is still {num(got)}, where each "
                "step crosses twice the texels and λ grows by 1: does your λ use xy, w, uv "
                "and size?" + HINT[1:])  # fmt: skip
    said = [f"with {what} doubled, yours goes from {num(got)} to "
            f"{'no number' if x is None else num(x)}"
            for what, x, ok in (("this triangle's (u, v)", by_uv, grew[0]),
                                ("the texture's size", by_size, grew[1])) if not ok]  # fmt: skip
    return (": your answer does not behave like a level of detail: λ grows by exactly 1 when "
            "the triangle's (u, v) doubles, and by 1 when the texture's size doubles (each step "
            f"crosses twice the texels); {'; '.join(said)}:" + HINT[1:])  # fmt: skip


def _rule(args, expected, got) -> str:
    """The steps (staged: :data:`RULE` until two answers failed), but only for a failing try
    that behaves like a λ (:func:`_not_tried`): junk never counts towards them (r415 F1,
    r418 F1)."""
    words = _not_tried(_RUNNING.get("fn"), args, expected, got)
    return RULE if words is None else words


#: 7.1's "answer first" pixels on the floor (64 × 64 texture): two lanes of one quad, the
#: near edge's helpers, and the far tip, where the step down decides.
QUESTION_PIXELS = ((28, 14), (29, 15), (27, 3), (5, 14))


def lod_questions(size=(64, 64)) -> str:
    """7.1's questions answered on the floor: each pixel's λ and the step that decides it,
    and λ at the helper-side pixel with its helpers clamped."""
    xy, w, _ = FLOOR
    said = []
    for r, c in QUESTION_PIXELS:
        args = (xy, w, FLOOR_UV, size, r, c)
        lx, ly = _axes(args)
        step = "right (ddx)" if lx >= ly else "down (ddy)"
        said.append(f"({r}, {c}): λ = {num(expected_lod(*args))}, the step {step} decides")
    right = expected_lod(xy, w, FLOOR_UV, size, 27, 3)
    clamped = _variants(xy, w, FLOOR_UV, size, 27, 3)["helpers clamped"]
    way = "smaller" if clamped < right else "larger"
    return (f"7.1 on the floor: {'; '.join(said)}. (28, 14) and (29, 15) share a quad, so one "
            f"λ. With (27, 3)'s helpers clamped λ would be {num(clamped)}, {way}: the step "
            "across the edge stops at the triangle")  # fmt: skip


def draw_floor(ax, marked) -> list:
    """The whole floor the check draws, its covered pixels grey and the pixels ``marked``
    ((row, col) each) outlined and named: what a stub's figure shows (r418 FIG1: 7.1's
    questions name pixels of the floor that its 6 × 6 close-up never showed)."""
    from matplotlib.patches import Rectangle

    xy = FLOOR[0]
    n = 32
    covered = [[inside(xy, x + 0.5, y + 0.5) for x in range(n)] for y in range(n)]
    artists = [ax.imshow(np.where(covered, 0.82, 1.0), cmap="gray", vmin=0, vmax=1,
                         extent=(0, n, n, 0), interpolation="nearest")]  # fmt: skip
    ring = np.vstack([xy, xy[:1]])
    artists += ax.plot(ring[:, 0], ring[:, 1], color="black", linewidth=1.2)
    for r, c in marked:
        artists.append(ax.add_patch(Rectangle((c, r), 1, 1, fill=False, edgecolor="#ff9f1c",
                                              lw=2)))  # fmt: skip
        side = 1 if c < n / 2 else -1  # the name away from the floor's middle
        # two pixels a row or two apart: the upper name raised, the lower one lowered
        near = [r2 for r2, c2 in marked if 0 < abs(r2 - r) <= 2 and abs(c2 - c) <= 2]
        dy = 0 if not near else (7 if r < near[0] else -7)
        artists.append(ax.annotate(f"({r}, {c})", (c + 0.5, r + 0.5), xytext=(14 * side, dy),
                                   textcoords="offset points", va="center", fontsize="x-small",
                                   ha="left" if side > 0 else "right", color="#b35900",
                                   arrowprops={"arrowstyle": "-", "color": "#b35900"}))  # fmt: skip
    ax.set_xlim(0, n)
    ax.set_ylim(n, 0)
    ax.set_aspect("equal")
    return artists


def draw_lod_case(ax, case, got, overview=None, marked=QUESTION_PIXELS):
    """Close up on the pixel: the triangle's edges, the pixels around (covered grey), the
    pixel; λ and yours. A passing figure adds the pixel's quad with (u, v) at each lane
    (helpers hatched) and answers 7.1's questions; a failing one, once the hints are spent,
    outlines the quad (r418 FIG1). With no answer (``overview``: ``got`` None) on the floor,
    the whole floor with the questions' pixels ``marked`` (:func:`draw_floor`)."""
    from matplotlib.patches import Rectangle

    from . import tries

    _, (xy, w, uv, size, row, col), expected = case
    if (got is None if overview is None else overview) and np.array_equal(xy, FLOOR[0]):
        artists = draw_floor(ax, marked)
        text = (f"the floor the check draws, the questions' pixels marked; this case: pixel "
                f"({row}, {col}), texture size (H, W) = {size}")  # fmt: skip
        artists.append(ax.set_xlabel(textwrap.fill(text, 70), fontsize="x-small"))
        return artists
    r0, c0 = row - row % 2, col - col % 2
    passed = got is not None and same_lod(got, expected, case[1])
    ring = np.vstack([xy, xy[:1]])
    artists = ax.plot(ring[:, 0], ring[:, 1], color="black", linewidth=1.5)
    for y in range(r0 - 2, r0 + 4):
        for x in range(c0 - 2, c0 + 4):
            artists.append(ax.add_patch(Rectangle((x, y), 1, 1, edgecolor="#bbbbbb", lw=0.5,
                facecolor="#d2d2d2" if inside(xy, x + 0.5, y + 0.5) else "white")))  # fmt: skip
    if passed:  # the quad's lanes; the lower-right one takes part in no coarse difference
        for dr, dc in ((0, 0), (0, 1), (1, 0), (1, 1)):
            x, y = c0 + dc, r0 + dr
            covered = inside(xy, x + 0.5, y + 0.5)
            artists.append(ax.add_patch(Rectangle((x, y), 1, 1, fill=False, edgecolor="#2b7bba",
                                                  lw=1.5, hatch=None if covered else "//")))  # fmt: skip
            u, v = _uv_at(xy, w, uv, x + 0.5, y + 0.5)
            artists.append(ax.text(x + 0.5, y + 0.5, f"{u:.2f}\n{v:.2f}", ha="center",
                                   va="center", fontsize="xx-small",
                                   color="#888888" if (dr, dc) == (1, 1) else "black",
                                   bbox={"facecolor": "white", "alpha": 0.55,
                                         "edgecolor": "none", "pad": 1}))  # fmt: skip
    elif got is not None and tries.hints_spent("pixel_lod"):  # the quad, no values
        artists.append(ax.add_patch(Rectangle((c0, r0), 2, 2, fill=False, edgecolor="#2b7bba",
                                              lw=1.5)))  # fmt: skip
    artists.append(ax.add_patch(Rectangle((col, row), 1, 1, fill=False, edgecolor="#ff9f1c",
                                          lw=3)))  # fmt: skip
    ax.set_xlim(c0 - 2, c0 + 4)
    ax.set_ylim(r0 + 4, r0 - 2)
    ax.set_aspect("equal")
    text = f"pixel ({row}, {col}), texture size (H, W) = {size}"
    if got is not None:
        text += f"; λ = {num(expected, got)}, yours {num(got, expected)}"
    if got is not None and not passed and not tries.hints_spent("pixel_lod"):
        text += "; its quad not drawn: which it is, is question (1)"  # r426 FIG2
    if passed:
        ddx, ddy = quad_steps(xy, w, uv, row, col)
        said = (f"blue: its quad, (u, v) at each lane (hatched: a helper; grey: unused); "
                f"ddx = {vec(ddx)}, ddy = {vec(ddy)}")  # fmt: skip
        text += "\n" + textwrap.fill(said, 70) + "\n" + textwrap.fill(lod_questions(), 70)
    artists.append(ax.set_xlabel(text, fontsize="x-small"))
    return artists


def _offset(args, expected, got) -> float | None:
    """λ's error on this case, where it is one (r462 H4: λ − 0.5 was told the steps)."""
    if got is None or not math.isfinite(float(got)) or abs(got - expected) < 1e-6:
        return None
    return float(got - expected)


def _offset_words(args, expected, got) -> str:
    c = _offset(args, expected, got)
    return (f"your λ is the right one {'+' if c > 0 else '−'} {num(abs(c))} on every case (here "
            f"{num(got)} for {num(expected)}): a constant added (a bias), or every step counted "
            "in texels of a texture of another size (each halving of W and H subtracts 1)? "
            "7.1's λ is log2 of the longer step in texels of this size, nothing added")  # fmt: skip


#: Named only where one offset gives every answer (:attr:`.exercise.Mistake.parameter`).
LOD_OFFSET = Mistake("λ offset", _offset_words, fits=lambda a, e, g: _offset(a, e, g) is not None,
                     parameter=_offset, only_whole=True)  # fmt: skip


PIXEL_LOD = Exercise(
    "pixel_lod", lod_cases, as_lod, same_lod, explain_lod, _rule,
    (*variant_mistakes(_variants, MISTAKES), PER_TRIANGLE, LOD_OFFSET),  # affine's: per triangle
    answers=(PackageAnswer(mip_level), PackageAnswer(lane_values)),
    draw=draw_lod_case, hints=((RULE, HINT),), inputs_drawn=True, call=_call,
    once=((RULE, ": as said for the first failing case"),),
    reference=("teachraster.exercises.quad_difference",),  # lanes: the renderer's quad values
    example=2,  # pixel (27, 3): a quad with helpers outside the edge, 7.1's third question
    slow=" (one call computes one pixel's λ: it should take well under a millisecond)",
)  # fmt: skip
