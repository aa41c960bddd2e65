"""How the blend checks show colours (exercise 9.2, lesson 12b's blend exercises, and
:mod:`.front_to_back`): in words, two colours printed with one number format
(:func:`colour_texts`), and as swatches over a checkerboard (:func:`swatches`): src and dst,
then the expected blend only beside an answer, so that the figure never shows the answer
first."""

from __future__ import annotations

import numpy as np

from .answers import as_numbers
from .scalars import NOISE, vec


def as_rgba(value) -> np.ndarray:
    return as_numbers(value, (4,), "an RGBA colour, shape (4,)")


def colour_texts(expected, got) -> tuple[str, str]:
    """Two RGBA colours, printed alike: each value with the same number of decimals in both
    (exact when 5 suffice, else the fewest that tell every two values apart), so that one
    value never prints two ways and two values never print alike (r8: 0.4375 was printed
    "0.4375" in one colour and "0.438" in the other).

    >>> colour_texts([0.1875, 0.4375, 0.1875, 0.625], [0.1875, 0.4375, 0.1875, 0.4375])
    ('(0.1875, 0.4375, 0.1875, 0.625)', '(0.1875, 0.4375, 0.1875, 0.4375)')
    >>> colour_texts([0.3, 0.12345678], [0.3, 0.12345679])
    ('(0.3, 0.12345678)', '(0.3, 0.12345679)')
    """
    e, g = np.asarray(expected, float).ravel(), np.asarray(got, float).ravel()
    values = [x for x in np.r_[e, g] if np.isfinite(x)]

    def text(x, d):
        if not np.isfinite(x):
            return repr(float(x))
        t = f"{x:.{d}f}".rstrip("0").rstrip(".")
        return "0" if t in ("", "-0") else t

    def tells_apart(d):
        return all(text(x, d) != text(y, d) for x in values for y in values
                   if abs(x - y) > NOISE * max(1.0, abs(x), abs(y)))  # fmt: skip

    exact = next((d for d in range(3, 6) if all(float(text(x, d)) == x for x in values)), None)
    digits = exact or next((d for d in range(3, 17) if tells_apart(d)), 17)
    return tuple("(" + ", ".join(text(x, digits) for x in v) + ")" for v in (e, g))


def explain_blend(args, expected, got) -> str:
    src, dst = args
    want, yours = colour_texts(expected, got)
    return f"src = {vec(src)}, dst = {vec(dst)}: the blend is {want}; yours is {yours}"


def swatches(ax, cells, names, straight=(), gap=None):
    """RGBA colours as swatches over a checkerboard, each named with its four numbers below.

    ``cells`` are premultiplied, except those whose index is in ``straight``. From index
    ``gap`` on, the swatches stand a little further right (their labels apart from those
    before them). Returns the artists.
    """
    check = (np.indices((8, 8)).sum(axis=0) % 2)[..., None] * 0.3 + 0.6
    left = [k * 1.3 + (0.6 if gap is not None and k >= gap else 0) for k in range(len(cells))]
    artists = []
    for k, c in enumerate(cells):
        c = np.clip(np.nan_to_num(np.asarray(c, float)), 0, 1)
        rgb = c[:3] * c[3] if k in straight else c[:3]
        image = np.clip(rgb + (1 - c[3]) * check, 0, 1)  # premultiplied over the checkerboard
        artists.append(ax.imshow(image, extent=(left[k], left[k] + 1, 1, 0)))
    ax.set_xlim(-0.15, max(left[-1] + 1.3 if left else 0, 2 * 1.3))
    ax.set_ylim(1.05, -0.05)
    ax.set_xticks([x + 0.5 for x in left], names, fontsize="x-small")
    ax.set_yticks([])
    return artists


def _two_lines(rgba: str) -> str:
    """ "(r, g, b, a)" as "(r, g," over "b, a)": four columns fit under their swatches; with
    numbers of more than four digits, one number a line (r11 09-D: "(0.1875, 0.4375," ran into
    its neighbour's label: four labels share the axes' width, however the swatches are spaced)."""
    r, g, rest = rgba.split(", ", 2)
    if len(f"{r}, {g},") > 13:
        return ",\n".join(rgba.split(", "))
    return f"{r}, {g},\n{rest}"


def blend_drawer(mode: str):
    """draw(ax, case, got): src and dst as swatches, then the expected blend and yours (r8:
    the bars never showed src and dst); before any answer (``got`` None), src and dst only,
    so that the figure never shows the answer first."""
    straight_in = mode in ("over", "from straight", "straight")

    def draw(ax, case, got):
        src, dst = case[1]
        cells, names = [src, dst], ["src", "dst"]
        if got is not None:
            want, yours = colour_texts(case[2], got)
            cells += [case[2], got]
            names += [f"expected\n{_two_lines(want)}", f"yours\n{_two_lines(yours)}"]
        names[:2] = [f"{n}\n{_two_lines(vec(c))}" for n, c in zip(names[:2], cells[:2])]
        straight = (0, 1) if straight_in else ()
        straight += (2, 3) if mode in ("over", "straight") else ()
        artists = swatches(ax, cells, names, straight)
        kinds = {
            "over": "straight inputs and results",
            "premultiplied": "premultiplied inputs and results",
            "atop": "premultiplied inputs and results",
            "from straight": "straight inputs, premultiplied results",
            "straight": "straight inputs and results",
        }
        artists.append(ax.set_xlabel(f"{kinds[mode]}, drawn over a checkerboard",
                                     fontsize="x-small"))  # fmt: skip
        return artists

    return draw
