"""Exercise ``front_to_back`` (lesson 12b): compositing transparent layers nearest first.

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

The walk's order is observable (r8: a loop over ``layers[::-1]`` passed): the student's
function gets the layers as a one-pass iterator (:class:`LayerStream`), as a ray marcher meets
them, and must stop once the composite is opaque. A stack with an opaque layer in front of
others then tells: a loop from the farthest layer must read every layer first, and is named
(so is a nearest-first loop that never stops; the check cannot tell the two apart, and its
words say both).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ..core.blend_factors import BLEND_MODES, apply_blend
from .answers import as_numbers, low_precision
from .blend_display import colour_texts, swatches
from .blend_mistakes import EIGHT_BIT, WHOLE_NUMBERS
from .blending import blend_answers
from .cases import DRAWN, SEED, drawn_rng
from .exercise import Exercise, Mistake, PackageAnswer, variant_mistakes
from .scalars import num, vec
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


#: What a loop that blends each layer with the package's blend is told (r11 09-E: a right
#: loop with *under*'s factors, (ONE_MINUS_DST_ALPHA, ONE), was told the function "computes
#: this very answer"; it computes one step, whose factors are the derivation).
STEP_WORDS = ("the package's blend is not counted as your work: write the step yourself "
              "(choosing the factors of under, nearest first, is the derivation asked for; "
              "name them in a comment if you like)")  # fmt: skip


#: Layers of alpha 1 − 2⁻⁵³ (the last double below 1) in the stack that no opaque layer ends:
#: what each lets through, 2⁻⁵³, multiplied layer by layer underflows to 0 after 21 of them,
#: and two more tell a loop that reads on past it.
UNDERFLOW_LAYERS = 23


#: A premultiplied glow: light with alpha 0, covering nothing (exercise 9.2b's).
GLOW_LAYER = [0.3, 0.2, 0.05, 0.0]


def layer_cases() -> list[tuple[str, tuple, np.ndarray]]:
    """(label, (layers,), RGBA): named stacks and seeded random ones, nearest layer first."""
    red, blue, green = _premultiplied([1, 0, 0], 0.5), _premultiplied([0, 0, 1], 0.5), \
        _premultiplied([0, 1, 0], 0.25)  # fmt: skip
    named = [
        ("red in front of blue", [red, blue]),
        ("one half-transparent red layer", [red]),
        ("blue in front of red", [blue, red]),
        ("an opaque layer in front hides the rest", [_premultiplied([1, 1, 0], 1.0), red, blue]),
        (
            "an opaque layer in the middle",
            [green, red, _premultiplied([0.1, 0.4, 0.8], 1.0), blue, red, green],
        ),  # fmt: skip
        ("an opaque layer at the back", [green, red, _premultiplied([0.2, 0.2, 0.2], 1.0)]),
        ("an invisible layer (alpha 0) in between", [red, [0, 0, 0, 0], blue]),
        ("no layers at all", np.zeros((0, 4))),
        # r20 D-4: a stop at alpha 1 − 1e-7 or 1 − 1e-6 passed (the composite is within the
        # tolerance): alpha 1 − 2⁻²⁴ (float32's last value below 1, exact in both) after the
        # first layer, still below 1 after the second, 1 only at the third, so such a stop
        # reads too few layers, even testing at the top of the loop
        (
            "alpha just below 1 for two layers",
            [
                _premultiplied([1, 0, 0], 1 - 2.0**-24),
                _premultiplied([0, 1, 0], 0.25),
                _premultiplied([0, 0, 1], 1.0),
                blue,
            ],
        ),
        # r24 D-1: a stop closer to 1 (1 − 2⁻³⁰, 1 − 1e-9, math.isclose(A, 1)) passed: here
        # the alpha is 1 − 2⁻⁴⁰ (exact in float64) after the first layer, still below 1 after
        # the second (a loop testing at the top reads it), 1 only with the opaque third;
        # float32 rounds that alpha to 1, and a float32 answer may stop there
        (
            "alpha within 1e-12 of 1 before an opaque layer",
            [
                _premultiplied([1, 0.5, 0], 1 - 2.0**-40),
                _premultiplied([0, 1, 0], 0.25),
                _premultiplied([0, 0, 1], 1.0),
                blue,
            ],
        ),
        # r445 W1: a stop at 1 − 1e-13 (or 1 − 1e-16, the last double below 1) tested at the
        # top of the loop passed: the stacks above reach 1 one layer after they come that
        # close, and the loop's one allowed extra fetch hid the early stop. Here the alpha is
        # 1 − 2⁻⁵³ after the first layer and stays there for two faint layers (1 − 2⁻⁵³ + 2⁻⁵⁵
        # rounds back to it), 1 only with the opaque fourth
        (
            "alpha the last double below 1 for three layers",
            [
                _premultiplied([0.9, 0.3, 0.1], 1 - 2.0**-53),
                _premultiplied([0, 1, 0], 0.25),
                _premultiplied([0, 0, 1], 0.25),
                _premultiplied([1, 1, 1], 1.0),
                red,
            ],
        ),
        # r25 D-2: a loop that stops on a layer opaque by itself, not on the composite, passed:
        # here no layer is opaque, but the alpha is 1 after two (1 − 2⁻¹⁰⁶ rounds to 1) and
        # the light let through, 2⁻⁵³ a layer, underflows to 0 after 21; such a loop reads
        # all 23, while a test of the alpha (stops at 2) or of what is let through (at 21)
        # stops in time
        (
            "no layer opaque, but together they are",
            [
                _premultiplied([0.2 + 0.6 * (k % 2), 0.5, 0.8 - 0.6 * (k % 2)], 1 - 2.0**-53)
                for k in range(UNDERFLOW_LAYERS)
            ],
        ),
        # r445 W3: a loop that skips layers of alpha 0 (an "invisible" layer) passed: a
        # premultiplied layer with alpha 0 may carry light (9.2b's glow), and adds it
        ("a glow (light, alpha 0) between two layers", [red, GLOW_LAYER, blue]),
        # r483 W1: a loop that clamped its colour to its alpha (c ≤ α) passed: in every stack
        # above the composite covers more than it lights. Here it lights more than it covers
        ("a glow behind a faint layer", [_premultiplied([0, 0, 1], 0.25), GLOW_LAYER]),
    ]
    rng, now = np.random.default_rng(SEED + 80), drawn_rng()
    for k in range(14 + DRAWN):
        r = rng if k < 14 else now  # the last few drawn for this check (r11 09-B)
        n = int(r.integers(2, 7))
        a = r.uniform(0.05, 1.0, n).round(3)
        what = f"random stack {k + 1}" if k < 14 else f"stack drawn for this check {k - 13}"
        named.append((f"{what}: {n} layers",
                      [_premultiplied(r.uniform(0, 1, 3).round(3), x) for x in a]))  # fmt: skip
    out = []
    for label, layers in named:
        arr = np.asarray(layers, dtype=float).reshape(-1, 4)
        out.append((label, (arr.copy(),), back_to_front(arr)))
    return out


def as_rgba(value) -> np.ndarray:
    return as_numbers(value, (4,), "an RGBA colour, shape (4,)")


class LayerStream:
    """The layers of a case, nearest first, readable once (``for layer in layers``), each an
    RGBA array. It holds only the next-layer step of a generator made by the check
    (:func:`layer_stream`): the layers and the count of those read live in the check's own
    closure, so that neither is an attribute a student's function can read or reset (r14
    09-2: ``layers._layers`` read back to front, and ``layers.read = 0`` after reading them
    all, passed every case)."""

    __slots__ = ("_pull",)

    def __init__(self, pull):
        object.__setattr__(self, "_pull", pull)

    def __setattr__(self, name, value):
        raise AttributeError(f"the layers cannot be changed (setting {name!r})")

    def __iter__(self):
        return self

    def __next__(self) -> np.ndarray:
        return self._pull()

    def __array__(self, dtype=None, copy=None):
        raise TypeError("the layers come one at a time, nearest first, as a ray marcher meets "
                        "them: read them with a for loop (np.asarray cannot take them)")  # fmt: skip

    def __repr__(self) -> str:
        return "<layers, nearest first: read them once, with a for loop>"


def layer_stream(layers) -> tuple[LayerStream, Callable[[], int]]:
    """A :class:`LayerStream` of ``layers`` (nearest first), and how many of them it has
    handed out so far: the array and the count stay in this closure."""
    stack = np.asarray(layers, dtype=float).reshape(-1, 4)
    count = [0]

    def stream():
        for layer in stack:
            count[0] += 1
            yield layer.copy()

    return LayerStream(stream().__next__), lambda: count[0]


class Misread(np.ndarray):
    """A composite whose function read the wrong number of layers: ``read`` of them, the
    composite opaque after layer ``opaque`` (counted from 1). Never right."""

    read: int
    opaque: int


class ReadPast(Misread):
    """A composite whose function read layers behind the opaque one."""


class ReadShort(Misread):
    """A composite whose function stopped reading before the layer that makes it opaque:
    it stopped at an alpha below 1 (r20 D-4), however close its composite."""


def opaque_after(layers, dtype=float) -> int | None:
    """How many layers, nearest first, make the composite opaque (alpha exactly 1), or None;
    in ``dtype``'s arithmetic (float32: an alpha within 2⁻²⁵ of 1 is 1 there)."""
    return stop_window(layers, dtype)[0]


def stop_window(layers, dtype=float) -> tuple[int | None, int | None]:
    """(first, last): a right loop may stop after any layer from ``first`` to ``last``
    (counted from 1, nearest first, in ``dtype``'s arithmetic): where the accumulated alpha,
    A ← A + (1 − A)·α, is 1 (the task's test), or where the light let through, 1 − α
    multiplied layer by layer, is 0 (a test the task allows too). The two part where the
    alpha rounds to 1 before the light let through underflows to 0 (r25 D-2). ``first`` None:
    no stop is needed; ``last`` None: reading on is no mistake."""
    alphas = np.asarray(layers, dtype=float).reshape(-1, 4)[:, 3].astype(dtype)
    seen = np.cumprod(dtype(1) - alphas, dtype=dtype)
    through = np.flatnonzero(seen <= 0.0)
    last = int(through[0]) + 1 if through.size else None
    a, first = dtype(0), None
    for k, alpha in enumerate(alphas):
        a = dtype(a + (dtype(1) - a) * alpha)
        if a >= 1:
            first = k + 1
            break
    if first is None or last is None:  # the light never underflows: read on as you like
        return (first if first is not None else last), last
    return min(first, last), max(first, last)  # either may round first


def call_front_to_back(fn, args) -> np.ndarray:
    """Run ``fn`` on the case's layers as a :class:`LayerStream`; a composite read short of
    :func:`stop_window`'s first layer comes back as a :class:`ReadShort`, one read past its
    last (more than one layer behind it: a loop may fetch the next before it tests) as a
    :class:`ReadPast`."""
    (layers,) = args
    stream, read = layer_stream(layers)
    value = as_rgba(fn(stream))
    # a float32 answer is judged by float32's alphas (r24 D-1: its documented allowance), or
    # by float64's (r483 F1: a loop in Python floats that returns float32 read on, rightly)
    first, last = stop_window(layers)
    if low_precision(value):
        first, last = _either_window((first, last), stop_window(layers, np.float32))
    short = first is not None and read() < first
    past = last is not None and read() > last + 1
    if not (short or past):
        return value
    marked = np.asarray(value).view(ReadPast if past else ReadShort)
    marked.read, marked.opaque = read(), (last if past else first)
    return marked


def _either_window(one, other) -> tuple[int | None, int | None]:
    """The stops either window allows: the earlier first, the later last (None: no bound)."""
    firsts, lasts = [one[0], other[0]], [one[1], other[1]]
    first = None if None in firsts else min(firsts)
    last = None if None in lasts else max(lasts)
    return first, last


def same_rgba(got: np.ndarray, expected: np.ndarray, args=None) -> bool:
    """Within 1e-6 (a composite computed in float32 is right), the walk stopped in time."""
    if isinstance(got, Misread):
        return False
    return bool(np.isfinite(got).all()) and all_close(got, expected, 1e-6)


#: A loop's slip, once as the task asks (stopping once the alpha reaches 1) and once never
#: stopping: a student's wrong loop may do either.
NEVER_STOPS = ", never stopping"


def _variants(layers: np.ndarray) -> dict[str, np.ndarray]:
    """What typical nearest-first loops give (each one slip), stopping at alpha 1 or not."""
    out = _loops(layers, stops=True)
    out.update({k + NEVER_STOPS: v for k, v in _loops(layers, stops=False).items()})
    return out


def _loops(layers: np.ndarray, stops: bool) -> dict[str, np.ndarray]:
    def loop(step, before_opaque=False, skip=0):
        acc = CLEAR.copy()
        for layer in layers[skip:]:
            if before_opaque and layer[3] >= 1:  # r9 F7: the opaque layer itself left out
                break
            acc = step(acc, layer)
            if stops and acc[3] >= 1:
                break
        return acc

    def under(acc, c):
        return acc + (1 - acc[3]) * c

    def straight(acc, c):  # multiplies the premultiplied colour by alpha again
        t = 1 - acc[3]
        return np.r_[acc[:3] + t * c[3] * c[:3], acc[3] + t * c[3]]

    return {
        "reversed": loop(lambda acc, c: apply_blend(c, acc, *PREMULTIPLIED)),
        "no transmittance": loop(lambda acc, c: acc + c),
        # r289 S2: the alpha weighed by 1 − A, the colour added whole
        "colour not weighed": loop(lambda acc, c: np.r_[acc[:3] + c[:3], under(acc, c)[3]]),
        "double premultiplication": loop(straight),
        "alpha summed": loop(lambda acc, c: np.r_[acc[:3] + (1 - acc[3]) * c[:3], acc[3] + c[3]]),
        # r24 D-5: the sum clamped to 1, colour right, got the rule restated
        "alpha summed, clamped": loop(
            lambda acc, c: np.r_[acc[:3] + (1 - acc[3]) * c[:3], min(1.0, acc[3] + c[3])]),
        **(
            {
                "nearest only": layers[0] if len(layers) else CLEAR,
                "farthest only": layers[-1] if len(layers) else CLEAR,
            }
            if stops
            else {}
        ),
        "own alpha": loop(lambda acc, c: acc + (1 - c[3]) * c),
        "alpha first": loop(_alpha_first),
        # r9: F6, F11, F12, F8 and F7 got the rule restated
        "colour by own alpha": loop(
            lambda acc, c: np.r_[acc[:3] + (1 - c[3]) * c[:3], acc[3] + (1 - acc[3]) * c[3]]),
        "colour by A": loop(lambda acc, c: np.r_[acc[:3] + acc[3] * c[:3], under(acc, c)[3]]),
        "alpha max": loop(lambda acc, c: np.r_[under(acc, c)[:3], max(acc[3], c[3])]),
        "returned straight": _straight(loop(under)),
        **({"before the opaque layer": loop(under, before_opaque=True)} if stops else {}),
        "nearest skipped": loop(under, skip=1),  # r513 M1: got the rule restated
    }  # fmt: skip


def _straight(c):
    """A premultiplied composite divided by its alpha (0 where the alpha is 0)."""
    return np.r_[np.divide(c[:3], c[3], out=np.zeros(3), where=c[3] > 0), c[3]]


def _alpha_first(acc, c):
    """The alpha updated first, and the colour weighted by the new transmittance."""
    alpha = acc[3] + (1 - acc[3]) * c[3]
    return np.r_[acc[:3] + (1 - alpha) * c[:3], alpha]


def _prefixes(layers) -> list[tuple[int, np.ndarray]]:
    """(m, composite of the m nearest layers) for each m short of all of them."""
    return [(m, back_to_front(layers[:m])) for m in range(1, len(layers))]


def _stopped_at(args, expected, got) -> tuple[int, float] | None:
    """(m, alpha) when ``got`` is the composite of the m nearest layers only, alpha < 1."""
    (layers,) = args
    for m, partial in _prefixes(layers):
        if partial[3] < 1 and all_close(np.asarray(got, float), partial, 1e-6):
            return m, float(partial[3])
    return None


def _read_short_words(args, expected, got) -> str:
    (layers,) = args
    k = max(got.read, 1)  # the alpha after the layers read, a fact of the stack
    left = float(np.prod(1 - np.asarray(layers, float)[:k, 3]))
    return (f"you read {got.read} of the {len(layers)} layers and stopped, but the composite "
            f"is opaque (alpha exactly 1) only with layer {got.opaque}: after layer {k} its "
            f"alpha is 1 − {left:.2g}, so your loop stopped at an alpha below 1. The layers "
            "behind still show through that transmittance, however little: a stop below 1 "
            "is not the exact composite the task asks for"
            # r24 D-1: the idiom a student warned about float equality writes
            + (" (math.isclose(A, 1) stops there too: test A >= 1)" if left < 1e-8 else ""))  # fmt: skip


def _read_past_words(args, expected, got) -> str:
    (layers,) = args
    head = (f"you read {got.read} of the {len(layers)} layers, but after layer {got.opaque} "
            "the composite is opaque (alpha 1) and nothing behind it can show: walking "
            "nearest first, stop there, as a ray marcher does")  # fmt: skip
    if got.read == len(layers):
        return head + (". A loop that runs from the farthest layer (the layers reversed) must "
                       "read them all first, and so must one that never stops (a test A > 1 "
                       "never fires: the alpha reaches 1, no more; test A >= 1), or one that "
                       "copies them first (list(layers) or np.array(layers) reads every layer); "
                       "one that stops may fetch one layer past the opaque one, no more")  # fmt: skip
    # r18 D-8: a loop that stopped, but late, was told it ran from the farthest layer
    return head + (f". Your loop stopped, but {got.read - got.opaque} layers after it: "
                   "fetching one more layer to find out that it may stop is allowed, more "
                   "is not")  # fmt: skip


def _none_opaque(args, got) -> bool:
    """No layer your function read is opaque by itself (alpha 1)."""
    (layers,) = args
    return bool((np.asarray(layers, float)[: got.read, 3] < 1).all())


def _no_opaque_layer_words(args, expected, got) -> str:
    """A loop read on where the composite is opaque though no layer is (r25 D-2: a loop that
    tests each layer's own alpha passed); the words name what it waits for, and the loops
    the check cannot tell from it."""
    (layers,) = args
    first, last = stop_window(layers)
    through = float(1 - np.asarray(layers, float)[:, 3].max())
    return (f"you read {got.read} of the {len(layers)} layers, and none of them is opaque by "
            f"itself: each lets at least {through:.2g} of the light behind it through. Together "
            f"they are: after layer {first} the accumulated alpha is 1, and after layer "
            f"{last} not even a trace of light gets through (1 − α multiplied layer by layer "
            "has underflowed to 0). Your loop read on past both: it waits for a layer that is "
            "opaque by itself, which never comes here (or it never stops, or reads every "
            "layer first, from the farthest: those read them all too)")  # fmt: skip


def _stopped_there(args, expected, got) -> bool:
    """The composite of the m nearest layers, from a function that read no more than m + 1 of
    them (a loop may fetch one more before it tests): a stop the check counted, not one it
    infers from the value (r289 C1: a function that read all 23 layers and returned the last,
    which equals the first layer's composite there, was told it stopped after layer 1)."""
    stop = _stopped_at(args, expected, got)
    if stop is None or isinstance(got, ReadPast):
        return False
    if isinstance(got, ReadShort):
        return got.read <= stop[0] + 1
    # unmarked: read within the stop window, or (a stack never opaque) not counted at all
    return stop_window(args[0])[0] is None


def _stopped_words(args, expected, got) -> str:
    m, alpha = _stopped_at(args, expected, got)
    # r12 09-5: num(0.99963) alone is "1", which read "the alpha was 1: below 1"; told from
    # 1 it keeps its digits, and "just below" says how close it came
    five = f"{alpha:.5f}".rstrip("0")  # as the colour tuple beside it prints it
    shown = max(num(alpha, 1.0), five if float(five) < 1 else "", key=len)
    near = "just below 1" if alpha > 0.99 else "below 1"
    head = (f"you stopped after layer {m} of {len(args[0])}" if isinstance(got, ReadShort) else
            f"your composite is that of the {m} nearest of the {len(args[0])} layers alone, "
            "as a loop that stops there gives it")  # fmt: skip
    return (f"{head}, where the alpha was {shown}, {near}: the layers behind still show through the transmittance 1 − A "
            f"= {1 - alpha:.2g}; stop only once the alpha is 1")  # fmt: skip


def _without_faint(layers) -> tuple[np.ndarray, list[int]]:
    """The layers less those of alpha below 1e-3 that carry light, and where those were
    (counted from 1)."""
    layers = np.asarray(layers, float).reshape(-1, 4)
    faint = [k for k, c in enumerate(layers) if c[3] < 1e-3 and c[:3].any()]
    return np.delete(layers, faint, axis=0), [k + 1 for k in faint]


def _glow_skipped(args, expected, got) -> bool:
    """r445 W3: the composite of the layers less the glows (alpha 0 or nearly, with light)."""
    kept, skipped = _without_faint(args[0])
    return bool(skipped) and all_close(np.asarray(got, float), back_to_front(kept), 1e-6)


def _clamped(layers) -> list[np.ndarray]:
    """r483 W1: the composite with its colour clamped to its alpha (c ≤ α), at the end or
    after every layer."""
    acc = CLEAR.copy()
    for layer in np.asarray(layers, float).reshape(-1, 4):
        acc = acc + (1 - acc[3]) * layer
        acc = np.r_[np.minimum(acc[:3], acc[3]), acc[3]]
        if acc[3] >= 1:
            break
    whole = back_to_front(layers)
    return [np.r_[np.minimum(whole[:3], whole[3]), whole[3]], acc]


def _colour_clamped(args, expected, got) -> bool:
    e = np.asarray(expected, float)
    if not (e[:3] > e[3] + 1e-6).any():  # the clamp changes nothing here
        return False
    g = np.asarray(got, float).ravel()
    return g.shape == (4,) and any(all_close(g, c, 1e-6) for c in _clamped(args[0]))


def _colour_clamped_words(args, expected, got) -> str:
    e = np.asarray(expected, float)
    return (f"you clamped the colour to the alpha, {num(e[3])} here: a premultiplied colour "
            "that covers what it lights is at most its alpha, but a glow (light with alpha 0) "
            "lights without covering, so the composite may carry more light than coverage; "
            "keep it (under only adds light, seen through the transmittance 1 − A)")  # fmt: skip


def _glow_skipped_words(args, expected, got) -> str:
    layers = np.asarray(args[0], float).reshape(-1, 4)
    k = _without_faint(layers)[1][0]
    return (f"you skipped layer {k}, {vec(layers[k - 1])}, for its alpha {num(layers[k - 1][3])}: "
            "it is a glow, premultiplied light covering nothing, and it adds its light, seen "
            "through the transmittance 1 − A of the layers in front, like any layer (only "
            "(0, 0, 0, 0) adds nothing)")  # fmt: skip


#: Mistakes no variant gives: the walk's order and where it stops (r8: a back-to-front loop
#: passed).
WALK = [
    Mistake("glow skipped", _glow_skipped_words, fits=_glow_skipped),
    Mistake("colour clamped to alpha", _colour_clamped_words, fits=_colour_clamped),
    Mistake("stopped below alpha 1", _read_short_words,
            fits=lambda a, e, g: isinstance(g, ReadShort) and all_close(g, e, 1e-6)),
    # r25 D-2: before the general words, which say "after layer k the composite is opaque"
    Mistake("waited for an opaque layer", _no_opaque_layer_words,
            fits=lambda a, e, g: isinstance(g, ReadPast) and all_close(g, e, 1e-6)
            and _none_opaque(a, g)),
    Mistake("read behind the opaque layer", _read_past_words,
            fits=lambda a, e, g: isinstance(g, ReadPast) and all_close(g, e, 1e-6)),
    Mistake("stopped early", _stopped_words, fits=_stopped_there),
    # r22 D-7: a right loop over white, and one rounded to whole numbers, got the rule
    Mistake("over white", "you composited over white: the task's background is transparent "
            "black, (0, 0, 0, 0), which adds no light and covers nothing, so the composite "
            "is the layers' alone", fits=lambda a, e, g: _over_white(e, g)),
    WHOLE_NUMBERS,
    EIGHT_BIT,  # r23 D-4
]  # fmt: skip


def _over_white(expected, got) -> bool:
    """The composite over an opaque white background: the white seen through 1 − A, added
    on all four channels or on the colour alone (r22 D-7)."""
    e, g = np.asarray(expected, float), np.asarray(got, float).ravel()
    if g.shape != (4,) or e[3] >= 1:
        return False
    white = e + (1 - e[3]) * np.ones(4)
    return all_close(g, white, 1e-6) or all_close(g, np.r_[white[:3], e[3]], 1e-6)


MISTAKES = {
    "reversed": "you applied over with each new layer on top, as if the list ran from the "
    "farthest layer: the first layer is the nearest, and each later one lies *behind* what "
    "you have accumulated",
    "no transmittance": "you added the layers up: a layer behind is seen only through the "
    "layers in front, so weigh it by the transmittance 1 − A left by them (A: the alpha "
    "accumulated so far)",
    "colour not weighed": "you added each layer's colour whole, without the transmittance "
    "1 − A in front of it (your alpha is right): a layer behind is seen only through what the "
    "layers in front leave, so its colour counts (1 − A)·c, as its alpha does",
    "double premultiplication": "you multiplied each layer's colour by its alpha: the colours "
    "are premultiplied already (that darkens every semi-transparent layer)",
    "alpha summed": "you added the alphas: coverage composes like colour, A ← A + (1 − A)·α",
    "alpha summed, clamped": "you added the alphas and clamped the sum to 1: coverage "
    "composes like colour, so weigh each layer's alpha by the transmittance 1 − A too, "
    "A ← A + (1 − A)·α, as you weigh its colour",
    "nearest only": "you returned the nearest layer: the layers behind show through it where "
    "its alpha is below 1",
    "farthest only": "you returned the farthest layer (the last one): the layers in front of "
    "it cover it, each by its alpha",
    "own alpha": "you weighed each layer by 1 − its own alpha: a layer is seen through the "
    "layers in front of it, so weigh it by the transmittance 1 − A they leave (A: the alpha "
    "accumulated so far)",
    "alpha first": "you updated the accumulated alpha before the colour: a layer's colour is "
    "weighed by the transmittance 1 − A of the layers in front of it, the A from before this "
    "layer",
    "colour by own alpha": "you weighed each layer's colour by 1 − its own alpha (your alpha "
    "is right): a layer's colour is premultiplied already, and it is seen through the "
    "transmittance 1 − A of the layers in front of it (A: the alpha accumulated so far)",
    "colour by A": "you weighed each layer's colour by A, the alpha accumulated so far: that "
    "is how much the layers in front cover; what they let through is the transmittance 1 − A",
    "alpha max": "you kept the larger alpha: coverage composes like colour, A ← A + (1 − A)·α, "
    "so two half-covering layers cover three quarters, not a half",
    "returned straight": "you returned a straight colour (divided by the composite's alpha): "
    "the answer is premultiplied, the colour multiplied by the composite's alpha, as each "
    "layer is",
    "before the opaque layer": "you stopped before adding the opaque layer: the opaque layer "
    "itself is missing from your composite; add it (weighted by the transmittance 1 − A), then "
    "stop",
    "nearest skipped": "you left out the first layer, the nearest: your composite is that of "
    "the layers behind it alone; nothing lies in front of the nearest layer, so it counts "
    "whole (the transmittance before it is 1), and the layers behind show through it",
}


#: Each kind's words, the loops' never-stopping twins included.
WORDS = {**MISTAKES, **{k + NEVER_STOPS: w for k, w in MISTAKES.items() if "only" not in k}}


def explain_layers(args, expected, got) -> str:
    """The stack's size, the composite and yours."""
    (layers,) = args
    if isinstance(got, ReadPast):
        want, _ = colour_texts(expected, got)
        return f"for {len(layers)} layer(s) (nearest first) your composite {want} is right"
    if isinstance(got, ReadShort):  # within the tolerance: what is wrong is the stop
        want, yours = colour_texts(expected, got)
        return (f"for {len(layers)} layer(s) (nearest first) the composite is {want}; yours "
                f"is {yours}, within the check's tolerance")  # fmt: skip
    want, yours = colour_texts(expected, got)
    return f"for {len(layers)} layer(s) (nearest first) the composite is {want}; yours is {yours}"


def _rule(args, expected, got) -> str:
    return (": the composite is over applied from the farthest layer to the nearest; walking "
            "nearest first, each layer shows only through the transmittance 1 − A the layers "
            "in front of it leave (A: their alpha)")  # fmt: skip


#: Layers a figure draws one by one; a longer stack shows its first two and last two, those
#: marked, and one slot for each run of layers left out (r25 D-2: 23 layers' labels ran
#: into each other).
DRAWN_LAYERS = 12


def _layer_slots(n: int, marked) -> list:
    """The layer indices a figure draws, in order, with (first, last) for a run left out."""
    if n <= DRAWN_LAYERS:
        return list(range(n))
    keep = sorted({0, 1, n - 2, n - 1, *marked} & set(range(n)))
    out = []
    for k in keep:
        if out and k > out[-1] + 1:
            out.append((out[-1] + 1, k - 1))
        out.append(k)
    return out


def _skipped(layers) -> range:
    """The layers (0-based) that no right loop reads: those behind the one it may fetch after
    the opaque composite (:func:`stop_window`'s last); empty where it may read them all."""
    _, last = stop_window(layers)
    return range(last + 1, len(layers)) if last is not None else range(0)


def draw_layers(ax, case, got):
    """The layers as swatches over a checkerboard, then the expected and your composites
    (before any answer, the layers only: the figure never shows the answer first); layers
    read behind the opaque one crossed out and labelled "read", but the one a loop may fetch
    to find out that it can stop (labelled "allowed"); in any other figure, the layers no
    right loop reads (those behind that one) greyed, as the key says."""
    from matplotlib.patches import Rectangle

    (layers,) = case[1]
    # numbers: eight labels share the axes' width (r11 09-D: "layer 6expected"); "yours" on
    # the line of the others (r18 D-8: it stood a line lower in every figure)
    names = [str(k + 1) for k in range(len(layers))]
    past = range(got.opaque + 1, got.read) if isinstance(got, ReadPast) else range(0)
    if isinstance(got, ReadPast):  # r18 D-8: the task allows one layer fetched past it
        names[got.opaque] += "\nallowed"
    for k in past:  # r12 09-7: expected = yours; what is wrong is the layers read
        names[k] += "\nread"
    marked = [k for k, n in enumerate(names) if "\n" in n]
    if isinstance(got, ReadShort):  # r20 D-4: stopped before the layer that makes it opaque
        for k in range(got.read, got.opaque):
            names[k] += "\nnot read"
        marked += [got.read, got.opaque - 1]
    skipped = _skipped(layers) if got is not None and not isinstance(got, Misread) else range(0)
    # r326 S3: the passing figure shows what a right loop never reads, too (greyed, said in
    # the key: a word under each of six layers ran into the next)
    marked += [skipped.start, skipped.stop - 1] if skipped else []
    slots = _layer_slots(len(layers), marked)
    runs = [p for p, k in enumerate(slots) if isinstance(k, tuple)]
    cells = [np.zeros(4) if isinstance(k, tuple) else layers[k] for k in slots]
    shown = [f"{k[0] + 1}–{k[1] + 1}" if isinstance(k, tuple) else names[k] for k in slots]
    if got is not None:
        cells += [case[2], np.asarray(got, float)]
        shown += ["expected", "yours"]
    # r19 E-6: "expected" and "yours" nearly touched, the composites a gap apart from layers
    artists = swatches(ax, cells, shown, gap=len(slots) + 1 if got is not None else None)
    for p in runs:  # a run of layers left out: its numbers under a slot of dots
        artists[p].remove()
        artists[p] = ax.text(p * 1.3 + 0.5, 0.5, "…", ha="center", va="center")
    for p, k in enumerate(slots):  # crossed out: read behind the opaque layer
        x = p * 1.3  # swatches' spacing (blend_display.swatches)
        if k in past:
            artists += ax.plot([x, x + 1, x, x + 1], [0, 1, 1, 0], color="#D55E00", lw=2)
        if k in skipped or (isinstance(k, tuple) and k[0] in skipped):  # greyed: never read
            artists.append(ax.add_patch(Rectangle((x, 0), 1, 1, facecolor="white", alpha=0.7,
                                                  edgecolor="none")))  # fmt: skip
    key = ("layers 1, 2, ..., nearest first; premultiplied, drawn over a checkerboard" +
           ("\ngreyed: layers no right loop reads (it may fetch one past the opaque "
            "composite)" if skipped else ""))  # fmt: skip
    artists.append(ax.set_xlabel(key, fontsize="x-small"))
    return artists


FRONT_TO_BACK = Exercise(
    "front_to_back", layer_cases, as_rgba, same_rgba, explain_layers, _rule,
    variant_mistakes(_variants, WORDS, WALK), draw=draw_layers, call=call_front_to_back,
    # r9: back_to_front fed the layers up to the opaque one passed unflagged; the package's
    # blend functions compute the over step the task asks you to turn round
    answers=(PackageAnswer(back_to_front), *blend_answers(STEP_WORDS)), inputs_drawn=True, example=4,  # opaque in the middle
)  # fmt: skip
