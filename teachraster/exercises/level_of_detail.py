"""Exercise ``mip_level(ddx, ddy, size)``: the level of detail λ of one pixel, unclamped.

Lesson 09 (Williams, *Pyramidal Parametrics*, 1983; the GL 4.6 spec, §8.14.1, eq. 8.7):
the pixel's footprint on the texture has two axes, the screen-space derivatives of (u, v)
scaled to texels, ``(du/dx · W, dv/dx · H)`` and ``(du/dy · W, dv/dy · H)``; GL's isotropic
rule takes the longer one, ρ = max of the two Euclidean lengths, and λ = log2 ρ. ``size`` is
the texture's (height, width), like ``texture.shape[:2]``. The expected answer is
:func:`teachraster.mip_level`; explanations quote the two axes and name the mistake whose
answer the student's reproduces.
"""

from __future__ import annotations

import math
import re
import textwrap

import numpy as np

from ..pipeline.texture_filters import footprint_axes, mip_level
from .answers import as_number
from .cases import SEED, fixed_and_drawn
from .exercise import Exercise, Knobs, PackageAnswer, Slip
from .scalars import num, vec
from .tolerance import close


def expected_level(ddx, ddy, size) -> float:
    return float(mip_level(np.asarray(ddx, dtype=float), np.asarray(ddy, dtype=float), size))


def _level_cases(rng, word):
    """Hard cases (λ = 0, between levels, either axis longer, non-square, magnified), random."""
    t = 1 / 64
    hard = [
        ("one texel per pixel", (t, 0), (0, t), (64, 64)),
        ("4 texels per pixel", (4 * t, 0), (0, 4 * t), (64, 64)),
        ("λ between levels 1 and 2", (3 * t, 0), (0, 3 * t), (64, 64)),
        ("the x axis longer", (8 * t, 0), (0, 2 * t), (64, 64)),
        ("the y axis longer", (t, 0), (0, 16 * t), (64, 64)),
        ("a diagonal axis", (3 * t, 4 * t), (-t, t), (64, 64)),
        ("a rotated square footprint", (2 * t, 2 * t), (-2 * t, 2 * t), (64, 64)),
        ("magnified: a quarter texel per pixel", (t / 4, 0), (0, t / 4), (64, 64)),
        ("negative derivatives", (-2 * t, 0), (0, -2 * t), (64, 64)),
        ("a wide texture (H = 32, W = 128)", (1 / 128, 0), (0, 2 / 32), (32, 128)),
        (
            "a tall texture (H = 256, W = 16), v changes along x",
            (0, 4 / 256),
            (1 / 16, 0),
            (256, 16),
        ),  # fmt: skip
        ("a receding floor", (0.01, 0.0005), (0.002, 0.03), (256, 256)),
    ]
    out = [
        (label, (np.array(dx, float), np.array(dy, float), size)) for label, dx, dy, size in hard
    ]
    for n in range(12):
        size = (int(2 ** rng.integers(2, 9)), int(2 ** rng.integers(2, 9)))
        if n % 4 == 3:
            size = (int(rng.integers(3, 300)), int(rng.integers(3, 300)))
        dx, dy = rng.normal(size=2) * 10 ** rng.uniform(-3, 0), rng.normal(size=2) * 10 ** rng.uniform(-3, 0)  # fmt: skip
        out.append((f"{word} {n + 1}", (dx, dy, size)))
    return [
        (
            f"{label}: ddx={vec(dx)}, ddy={vec(dy)}, size={size}",
            (dx, dy, size),
            expected_level(dx, dy, size),
        )  # fmt: skip
        for label, (dx, dy, size) in out
    ]


level_cases = fixed_and_drawn(_level_cases, SEED + 70)  # r49: some drawn per check


def explain_level(args, expected, got) -> str:
    ddx, ddy, (h, w) = args
    lx, ly = (float(a) for a in footprint_axes(ddx, ddy, (h, w)))
    return (
        f"on an H×W = {h}×{w} texture the footprint's axis "
        f"along x is {_AXIS_X}{_texels(lx)}, along y {_AXIS_Y}{_texels(ly)}{_RHO}"
        f"{num(max(lx, ly))}{_LAMBDA}"
        f"{num(expected, got)}; yours is {num(got, expected)}"
    )


def _texels(n: float) -> str:
    """``1 texel``, ``2.5 texels`` (r85 07 D4: "1 texels")."""
    return f"{num(n)} texel" + ("" if num(n) == "1" else "s")


# the words of explain_level that state 7.1's formula, each replaced by a hint on the first
# failing tries (issue 30: hints before formulas; the per-case words gave it on every failure)
_AXIS_X, _AXIS_Y = "‖(du/dx·W, dv/dx·H)‖ = ", "‖(du/dy·W, dv/dy·H)‖ = "
_RHO, _LAMBDA = ", ρ = the longer = ", ", λ = log2 ρ = "


_NORMS = {
    "euclid": lambda a: math.hypot(*a),
    "max": lambda a: max(abs(a[0]), abs(a[1])),
    "sum": lambda a: abs(a[0]) + abs(a[1]),
    "squared": lambda a: a[0] ** 2 + a[1] ** 2,
}
_COMBINE = {
    "max": max,
    "min": min,
    "sum": lambda x, y: x + y,
    "root": lambda x, y: math.sqrt(x * x + y * y),
    "geometric": lambda x, y: math.sqrt(x * y),
    "mean": lambda x, y: (x + y) / 2,
    "x only": lambda x, y: x,  # r317: ddy ignored (ddx's axis alone), and the other way round
    "y only": lambda x, y: y,
}
_LOG = {"log2": math.log2, "ln": math.log, "log10": math.log10, "none": lambda r: r,
        "plus one": lambda r: math.log2(r) + 1, "floor": lambda r: math.floor(math.log2(r)),
        "round": lambda r: float(round(math.log2(r))),
        "ceil": lambda r: float(math.ceil(math.log2(r))), "plus half": lambda r: math.log2(r) + 0.5,
        "minus half": lambda r: math.log2(r) - 0.5,
        "log2(ρ − 1) + 1": lambda r: (math.log2(r - 1) + 1 if r > 1
                                          else -math.inf if r == 1 else math.nan)}  # fmt: skip


def level_with(ddx, ddy, size, *, scale="texels", norm="euclid", combine="max", log="log2", clamp=False, pair="step"):  # fmt: skip
    """mip_level with the usual mistakes as knobs (the defaults are GL's rule); ``pair``
    "coordinate" builds the axes as (∂u/∂x, ∂u/∂y) and (∂v/∂x, ∂v/∂y) (r85 07: unnamed);
    ``combine="area"`` takes ρ = √|det J|, the footprint's area as a square (r301)."""
    h, w = size
    sx, sy = {"texels": (w, h), "units": (1, 1), "swapped": (h, w), "W": (w, w), "H": (h, h)}[scale]
    ax = (float(ddx[0]) * sx, float(ddx[1]) * sy)
    ay = (float(ddy[0]) * sx, float(ddy[1]) * sy)
    if pair == "coordinate":
        ax, ay = (ax[0], ay[0]), (ax[1], ay[1])
    if combine == "vectors":  # r286 M3: ddx + ddy added as vectors, the diagonal step
        rho = _NORMS[norm]((ax[0] + ay[0], ax[1] + ay[1]))
    elif combine == "area":  # r301: ½·log2 |det J|, the side of a square of the same area
        rho = math.sqrt(abs(ax[0] * ay[1] - ax[1] * ay[0]))
    else:
        rho = _COMBINE[combine](_NORMS[norm](ax), _NORMS[norm](ay))
    if rho <= 0 and log != "none":
        return None
    lam = _LOG[log](rho)
    return max(lam, 0.0) if clamp else lam


def _shorter(args, expected, got) -> str:
    ddx, ddy, size = args
    lx, ly = (float(a) for a in footprint_axes(ddx, ddy, size))
    which = "x axis, ddx" if lx < ly else "y axis, ddy"
    return (
        f"your λ uses the shorter of the two footprint axes (here the {which}); GL takes the "
        "longer (ρ = max), so that no direction is undersampled"
    )


LEVEL_KNOBS = Knobs(level_with, {
    "scale": [
        Slip("texture units", lambda a, e, g: f"the derivatives are in texture units; measure "
             f"them in texels (u times W = {a[2][1]}, v times H = {a[2][0]}) before taking "
             "lengths", "units"),
        Slip("W and H swapped", lambda a, e, g: f"u runs along the W = {a[2][1]} columns and v "
             f"along the H = {a[2][0]} rows; you scaled u by H and v by W", "swapped"),
        # r317: one size for both coordinates was told only the rule
        Slip("v scaled by W", lambda a, e, g: f"you scaled v by W = {a[2][1]} as well as u: "
             f"v runs along the H = {a[2][0]} rows, so its texels are v times H", "W"),
        Slip("u scaled by H", lambda a, e, g: f"you scaled u by H = {a[2][0]} as well as v: "
             f"u runs along the W = {a[2][1]} columns, so its texels are u times W", "H"),
    ],
    "norm": [
        Slip("largest component", "each axis' length is Euclidean, √(a² + b²), not its largest "
             "component (GL 4.6 §8.14.1 allows it as an approximation; this task asks for the ideal ρ)", "max"),
        Slip("|a| + |b|", "each axis' length is Euclidean, √(a² + b²), not |a| + |b|"
             " (GL 4.6 §8.14.1 allows it as an approximation; this task asks for the ideal ρ)", "sum"),
        Slip("squared length", "that is log2 of the squared length, twice λ: take the square "
             "root first (or halve the log)", "squared"),
    ],
    "combine": [
        Slip("shorter axis", _shorter, "min"),
        # r317: one derivative alone was told only the rule
        Slip("ddx alone", "your λ uses ddx alone, the footprint's axis along x: ddy, the axis "
             "along y, is a footprint axis too, and GL takes the longer of the two (ρ = max), "
             "so that no direction is undersampled", "x only"),
        Slip("ddy alone", "your λ uses ddy alone, the footprint's axis along y: ddx, the axis "
             "along x, is a footprint axis too, and GL takes the longer of the two (ρ = max), "
             "so that no direction is undersampled", "y only"),
        Slip("sum of the axes", "your λ uses the sum of the derivatives; GL takes the longer of "
             "the two footprint axes", "sum"),
        Slip("summed before the root", "you summed the squares of both axes before the root, "
             "√(|∂/∂x|² + |∂/∂y|²); GL takes the longer axis, ρ = max(|∂/∂x|, |∂/∂y|), each "
             "axis its own length", "root"),
        Slip("ddx + ddy as vectors", "you added ddx and ddy as vectors, ‖ddx + ddy‖: that is "
             "the step to the diagonal pixel; each derivative is its own footprint axis, and GL "
             "takes the longer of their two lengths", "vectors"),
        # r301: the footprint's area (a rule of the literature) was told only the rule
        Slip("footprint area", "your λ is ½·log2 of the footprint's area, |det J| (the "
             "parallelogram the two axes span, in texels²): that is the side of a square of "
             "the same area, shorter than the longer axis wherever the footprint is stretched "
             "or skewed; GL takes the longer axis (ρ = max), so that no direction is "
             "undersampled", "area"),
        Slip("geometric mean", "that is the log of the geometric mean of the axes; GL takes the "
             "longer axis", "geometric"),
        Slip("mean of the axes", "that is the mean of the two axes; GL takes the longer axis "
             "(ρ = max)", "mean"),
    ],
    "log": [
        Slip("ρ itself", "you returned ρ itself; λ = log2 ρ (each level halves the texels)",
             "none"),
        Slip("natural log", "that is the natural log; λ = log2 ρ", "ln"),
        Slip("log10", "that is log10; λ = log2 ρ", "log10"),
        Slip("one too many", "your λ is one more than log2 ρ: level 0 is the full texture, so "
             "one texel per pixel (ρ = 1) is λ = 0", "plus one"),
        Slip("rounded down", "you rounded λ down to a whole level (floor or int()): λ is "
             "fractional, and 7.3's trilinear blends the two levels around it", "floor"),
        # r362 W1, S6: ceil was told "rounded" where the drawn cases' λ lay in the upper half
        # of a level, and only the rule (1 kernel in 8) where one lay in the lower half
        Slip("rounded up", "you rounded λ up to a whole level (ceil): λ is log2 ρ as it comes, "
             "fractional in general, and 7.3's trilinear blends the two levels around it",
             "ceil"),
        # r301: λ rounded, and λ + ½ (GL's nearest-level rounding), were told only the rule
        Slip("rounded", "you rounded λ to a whole number: λ is log2 ρ as it comes, fractional "
             "in general; the level choice comes later (7.3's trilinear blends the two levels "
             "around it)", "round"),
        Slip("plus half", "your λ is log2 ρ + ½, half a level too many: the ½ belongs to "
             "rounding λ to the nearest level (GL's NEAREST_MIPMAP choice), which comes later; "
             "λ itself is log2 ρ, so one texel per pixel (ρ = 1) is λ = 0", "plus half"),
        # r390 N3: a constant −½ was told the rule; log2(ρ − 1) + 1's −inf "a division"
        Slip("minus half", lambda a, e, g: f"your λ is log2 ρ − ½ on every case (here "
             f"{num(g, e)} against {num(e, g)}), half a level too few: λ is log2 ρ as it "
             "comes, with no offset, so one texel per pixel (ρ = 1) is λ = 0", "minus half"),
        Slip("log2(ρ − 1) + 1", "your λ is log2(ρ − 1) + 1: at one texel per pixel (ρ = 1) "
             "that is log2 0 = −inf (a log of 0, not a division); log2 ρ alone is λ, 0 there, "
             "and log2(ρ − 1) + 1 equals it only at ρ = 2", "log2(ρ − 1) + 1"),
    ],
    "pair": [
        Slip("derivatives paired by coordinate", "you paired the derivatives by coordinate, "
             "(∂u/∂x, ∂u/∂y) and (∂v/∂x, ∂v/∂y); each footprint axis is where one pixel step "
             "takes (u, v): (∂u/∂x, ∂v/∂x) for a step right, (∂u/∂y, ∂v/∂y) for a step down",
             "coordinate"),
    ],
    "clamp": [
        Slip("clamped", "λ is unclamped here: a magnified texture (ρ < 1) has λ < 0", True),
    ],
})  # fmt: skip


def _level_rule(args, expected, got) -> str:
    return ": λ = log2 max(‖∂(u·W, v·H)/∂x‖, ‖∂(u·W, v·H)/∂y‖)"


def same_level(got, expected, args) -> bool:
    """Within 1e-6: GPUs compute λ with far fewer bits; float32 is right."""
    return close(got, expected, 1e-6)


def exercise(scene) -> Exercise:
    return Exercise(
        "mip_level", level_cases, as_number, same_level, explain_level,
        _level_rule, [LEVEL_KNOBS], answers=(PackageAnswer(mip_level),), draw=draw_level_case,
        scene=scene, inputs_drawn=True, hints=HINTS,
        example=4,  # r362 FIG1: 1 × 16 texels, 7.1's question (λ = 0 showed two unit arrows)
    )  # fmt: skip


#: issue 30 (r49): 7.1 asks for this formula; the first wrong tries ask back. The scene's
#: pixel explanations use them too (r64: the picture's line printed the formula).
HINTS = (
    (": λ = log2 max(‖∂(u·W, v·H)/∂x‖, ‖∂(u·W, v·H)/∂y‖)",
     ": λ counts the halvings that bring the footprint's longer axis, measured in "
     "texels of level 0, down to one texel"),
    (_AXIS_X, ""), (_AXIS_Y, ""), (_RHO, " (ρ = "),
    (_LAMBDA, "), λ = "),
    # r85 07 D1: the axes in texels and ρ answer 7.1's three steps: the first tries get λ only
    (re.compile(r" the footprint's axis along x is .+? texels?, along y .+? texels? \(ρ = .+?\), "),
     ", "),
    (re.compile(r"measure them in texels \(u times W = \d+, v times H = \d+\) before taking "
                r"lengths"),
     "λ counts in texels of level 0: how many texels long is the texture along u, and along v?"),
    # r73 07-1: a named mistake's fix as a question first
    ("; GL takes the longer axis, ρ = max(|∂/∂x|, |∂/∂y|), each axis its own length",
     ": which one length of the footprint decides whether some direction is undersampled?"),
    # r375 F8: these fixes came with the first, "a hint only", failure
    (re.compile(r"GL takes the longer(?: of the two| axis)? \(ρ = max\), so that no direction is "
                r"undersampled"),
     "which axis must λ follow so that no direction is undersampled?"),
    (re.compile(r"that is (the natural log|log10); λ = log2 ρ"),
     r"that is \1: which log counts the halvings of the texel size?"),
    ("twice λ: take the square root first (or halve the log)",
     "twice λ: is an axis' length its square?"),
    # r390 F8: the Euclidean length itself came with the first, "a hint only", failure
    (re.compile(r"each axis' length is Euclidean, √\(a² \+ b²\), not (its largest component|"
                r"\|a\| \+ \|b\|)"),
     r"each axis' length is a straight line's, not \1: how long is a step of 3 texels "
     "across and 4 down?"),
)  # fmt: skip


def hinted(name: str, words: str, hints) -> str:
    """``words`` with ``hints`` in place of the formula until two different answers of task
    ``name`` have failed (the check's own staging, :func:`.checks._hinted`), for words said
    outside the report (a picture's pixel)."""
    from .tries import staged

    return staged(name, words, hints)[0]


def level_questions(lx: float, ly: float) -> str:
    """7.1's question answered for a footprint of axes ``lx`` and ``ly`` texels: the level of
    the shorter axis and of the two axes' mean, and the texels each skips along the longer."""
    longer = max(lx, ly)
    said = []
    for what, rho in (("the shorter axis", min(lx, ly)), ("the axes' mean", (lx + ly) / 2)):
        lam = math.log2(rho)
        said.append(f"{what} gives λ = {num(lam)}, where a step along the longer axis crosses "
                    f"{num(longer / 2**lam)} texels")  # fmt: skip
    return "7.1: " + "; ".join(said) + " (aliasing: texels skipped)"


def draw_level_case(ax, case, got):
    """The footprint's two axes in texels, and the circle of radius ρ GL fits around them."""
    ddx, ddy, (h, w) = case[1]
    sx, sy = (w, h) if got is not None else (1, 1)  # in texels: step (1) of 7.1, after a try
    ax_x = np.array([ddx[0] * sx, ddx[1] * sy])
    ax_y = np.array([ddy[0] * sx, ddy[1] * sy])
    rho = max(np.hypot(*ax_x), np.hypot(*ax_y))
    artists = [
        ax.annotate("", ax_x, (0, 0), arrowprops={"arrowstyle": "->", "color": "#2b7bba"}),
        ax.annotate("", ax_y, (0, 0), arrowprops={"arrowstyle": "->", "color": "#ff9f1c"}),
    ]
    if got is None:  # before any answer the two axes only (r64: the stub shows no answer)
        ax.set_xlabel(f"ddx (blue), ddy (orange) in texture units; W × H = {w} × {h}")
    else:
        angle = np.linspace(0, 2 * np.pi, 90)
        artists += ax.plot(rho * np.cos(angle), rho * np.sin(angle), color="#888888",
                           linestyle=":")  # fmt: skip
        text = f"texels (blue ∂/∂x, orange ∂/∂y): λ = {num(case[2])}, yours {num(got, case[2])}"
        if same_level(got, case[2], None):  # r375 F2: 7.1's other question, on this footprint
            words = level_questions(np.hypot(*ax_x), np.hypot(*ax_y))
            artists.append(ax.text(1.04, 0.5, textwrap.fill(words, 40), transform=ax.transAxes,
                                   ha="left", va="center", fontsize="x-small"))  # fmt: skip
        ax.set_xlabel(text)
    ax.set_xlim(-1.2 * rho, 1.2 * rho)
    ax.set_ylim(1.2 * rho, -1.2 * rho)
    ax.set_aspect("equal")
    return artists
