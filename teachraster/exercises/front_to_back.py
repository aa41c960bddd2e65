"""Exercise ``front_to_back`` (lesson 12): compositing transparent layers nearest first.

A GPU blends transparent fragments in submission order, so an engine sorts them back to
front and applies *over* (premultiplied: ``glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA)``,
Porter and Duff, *Compositing Digital Images*). Ray marchers, volume renderers and
depth-peeling do the reverse: they meet the nearest layer first and must stop once the
accumulated colour is opaque. The student derives the *under* step from over: what the
layers behind contribute is seen only through the transmittance 1 − A of those in front,
and premultiplied over is associative, so the nearest-first result equals the farthest-first
one.

Expected answers: premultiplied over (:func:`teachraster.blend_equation` with the factors of
``render(..., blend="premultiplied")``), applied from the farthest layer to the nearest onto
transparent black.

What the check cannot tell (r8): a loop that reverses the layers and blends them back to
front passes, since over is associative and the results are equal. The walk's order is not
observable either: the task hands over an (n, 4) array, and ``np.asarray`` (which any
solution may call) drops whatever an instrumented array would record. The derivation is the
lecturer's to read.
"""

from __future__ import annotations

import numpy as np

from ..core.blend_factors import BLEND_MODES, apply_blend
from .answers import as_numbers
from .cases import SEED
from .exercise import Exercise, variant_mistakes
from .scalars import vec
from .tolerance import all_close

PREMULTIPLIED = BLEND_MODES["premultiplied"]
CLEAR = np.zeros(4)


def back_to_front(layers: np.ndarray) -> np.ndarray:
    """The package's answer: premultiplied over from the last (farthest) layer to the first."""
    out = CLEAR.copy()
    for layer in np.asarray(layers, dtype=float)[::-1]:
        out = apply_blend(layer, out, *PREMULTIPLIED)
    return out


def _premultiplied(rgb, a) -> list:
    return [*(np.asarray(rgb, float) * a), a]


def layer_cases() -> list[tuple[str, tuple, np.ndarray]]:
    """(label, (layers,), RGBA): named stacks and seeded random ones, nearest layer first."""
    red, blue, green = _premultiplied([1, 0, 0], 0.5), _premultiplied([0, 0, 1], 0.5), \
        _premultiplied([0, 1, 0], 0.25)  # fmt: skip
    named = [
        ("red in front of blue", [red, blue]),
        ("one half-transparent red layer", [red]),
        ("blue in front of red", [blue, red]),
        ("an opaque layer in front hides the rest", [_premultiplied([1, 1, 0], 1.0), red, blue]),
        ("an opaque layer at the back", [green, red, _premultiplied([0.2, 0.2, 0.2], 1.0)]),
        ("an invisible layer (alpha 0) in between", [red, [0, 0, 0, 0], blue]),
        ("no layers at all", np.zeros((0, 4))),
    ]
    rng = np.random.default_rng(SEED + 80)
    for k in range(14):
        n = int(rng.integers(2, 7))
        a = rng.uniform(0.05, 1.0, n).round(3)
        named.append((f"random stack {k + 1}: {n} layers",
                      [_premultiplied(rng.uniform(0, 1, 3).round(3), x) for x in a]))  # fmt: skip
    out = []
    for label, layers in named:
        arr = np.asarray(layers, dtype=float).reshape(-1, 4)
        out.append((label, (arr.copy(),), back_to_front(arr)))
    return out


def as_rgba(value) -> np.ndarray:
    return as_numbers(value, (4,), "an RGBA colour, shape (4,)")


def same_rgba(got: np.ndarray, expected: np.ndarray, args=None) -> bool:
    """Within 1e-6: a composite computed in float32 is right."""
    return bool(np.isfinite(got).all()) and all_close(got, expected, 1e-6)


def _variants(layers: np.ndarray) -> dict[str, np.ndarray]:
    """What typical nearest-first loops give (each one slip)."""

    def loop(step):
        acc = CLEAR.copy()
        for layer in layers:
            acc = step(acc, layer)
        return acc

    def straight(acc, c):  # multiplies the premultiplied colour by alpha again
        t = 1 - acc[3]
        return np.r_[acc[:3] + t * c[3] * c[:3], acc[3] + t * c[3]]

    return {
        "reversed": loop(lambda acc, c: apply_blend(c, acc, *PREMULTIPLIED)),
        "no transmittance": loop(lambda acc, c: acc + c),
        "double premultiplication": loop(straight),
        "alpha summed": loop(lambda acc, c: np.r_[acc[:3] + (1 - acc[3]) * c[:3], acc[3] + c[3]]),
        "nearest only": layers[0] if len(layers) else CLEAR,
        "farthest only": layers[-1] if len(layers) else CLEAR,
        "own alpha": loop(lambda acc, c: acc + (1 - c[3]) * c),
    }


MISTAKES = {
    "reversed": "you applied over with each new layer on top, as if the list ran from the "
    "farthest layer: the first layer is the nearest, and each later one lies *behind* what "
    "you have accumulated",
    "no transmittance": "you added the layers up: a layer behind is seen only through the "
    "layers in front, so weigh it by the transmittance 1 − A left by them (A: the alpha "
    "accumulated so far)",
    "double premultiplication": "you multiplied each layer's colour by its alpha: the colours "
    "are premultiplied already (that darkens every semi-transparent layer)",
    "alpha summed": "you added the alphas: coverage composes like colour, A ← A + (1 − A)·α",
    "nearest only": "you returned the nearest layer: the layers behind show through it where "
    "its alpha is below 1",
    "farthest only": "you returned the farthest layer (the last one): the layers in front of "
    "it cover it, each by its alpha",
    "own alpha": "you weighed each layer by 1 − its own alpha: a layer is seen through the "
    "layers in front of it, so weigh it by the transmittance 1 − A they leave (A: the alpha "
    "accumulated so far)",
}


def explain_layers(args, expected, got) -> str:
    """The stack's size, the composite and yours."""
    (layers,) = args
    return (f"for {len(layers)} layer(s) (nearest first) the composite is "
            f"{vec(expected, got)}; yours is {vec(got, expected)}")  # fmt: skip


def _rule(args, expected, got) -> str:
    return " (farthest first: C ← c_i + (1 − α_i)·C over each layer)"


def draw_layers(ax, case, got):
    """The layers as swatches over a checkerboard, then the expected and your composites."""
    (layers,) = case[1]
    expected = case[2]
    cells = list(layers) + [expected] + ([] if got is None else [np.asarray(got, float)])
    names = [f"layer {k}" for k in range(len(layers))] + ["expected"]
    names += [] if got is None else ["yours"]
    check = (np.indices((8, 8)).sum(axis=0) % 2)[..., None] * 0.3 + 0.6
    artists = []
    for k, c in enumerate(cells):
        c = np.clip(np.nan_to_num(c), 0, 1)
        image = c[:3] + (1 - c[3]) * check  # premultiplied over the checkerboard
        artists.append(ax.imshow(image, extent=(k * 1.2, k * 1.2 + 1, 1, 0)))
    ax.set_xlim(-0.1, len(cells) * 1.2)
    ax.set_ylim(1.05, -0.05)
    ax.set_xticks([k * 1.2 + 0.5 for k in range(len(cells))], names, fontsize="x-small",
                  rotation=30)  # fmt: skip
    ax.set_yticks([])
    ax.set_title("nearest layer first; composites over a checkerboard", fontsize="small")
    return artists


FRONT_TO_BACK = Exercise(
    "front_to_back", layer_cases, as_rgba, same_rgba, explain_layers, _rule,
    variant_mistakes(_variants, MISTAKES), draw=draw_layers,
)  # fmt: skip
