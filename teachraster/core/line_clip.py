"""The part of a segment inside a box around the image, computed exactly.

An unsnapped (floating-point) line keeps its end points as they are. Far from the origin a
double holds whole pixels or less (from about 1e16 px it cannot even hold a pixel's
half), so the rule's differences ``centre - end`` lose the sub-pixel position: such a line
would come out empty or wrong. GL clips lines to the view volume before rasterising them
(GL 4.6 §13.5, "Primitive Clipping"); here the segment is cut to a box a margin larger
than the image, in exact rational arithmetic (Liang-Barsky on ``Fraction``), and the new
end points are rounded once, near the image where a double resolves ~1e-15 px.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np


def clip_to_box(ends: np.ndarray, width: int, height: int, margin: float) -> np.ndarray | None:
    """(2, 2) end points of the part of ``ends[0] → ends[1]`` in the box
    ``[-margin, width + margin] × [-margin, height + margin]``, or None if it misses the box.

    An end inside the box comes back bit for bit; a clipped one is the exact intersection
    with the box, rounded once to the nearest double.

    >>> clip_to_box(np.array([[-1e17, 1.5], [1e17, 1.5]]), 4, 3, 2.0).tolist()
    [[-2.0, 1.5], [6.0, 1.5]]
    >>> clip_to_box(np.array([[1.0, -9.0], [3.0, -5.0]]), 4, 3, 2.0) is None
    True
    """
    a = [Fraction(float(v)) for v in ends[0]]
    b = [Fraction(float(v)) for v in ends[1]]
    lo = (Fraction(-margin), Fraction(-margin))
    hi = (Fraction(width) + Fraction(margin), Fraction(height) + Fraction(margin))
    t0, t1 = Fraction(0), Fraction(1)
    for axis in (0, 1):
        d = b[axis] - a[axis]
        # lo <= a + t d <= hi, as two conditions s (a + t d) <= s bound, s = -1 then +1.
        for sign, bound in ((-1, lo[axis]), (1, hi[axis])):
            num, den = sign * (bound - a[axis]), sign * d
            if den == 0:
                if num < 0:
                    return None
            elif den > 0:
                t1 = min(t1, num / den)
            else:
                t0 = max(t0, num / den)
    if t0 > t1:
        return None
    out = np.array(ends, dtype=np.float64)
    for k, t, kept in ((0, t0, t0 == 0), (1, t1, t1 == 1)):
        if not kept:
            out[k] = [float(a[i] + t * (b[i] - a[i])) for i in (0, 1)]
    return out
