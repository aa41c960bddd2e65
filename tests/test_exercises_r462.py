"""Review r462 (exercise 07): M1 7.3's |λ| was blamed on Python's pyramid[-2]; H1 7.2's
IndexError slips (indices clipped to [0, W], H and W swapped) were the bare error; H4-H7 λ
offset, halved or held in float16 (7.1, 7.3, 7.4) and 7.1's Frobenius, area and
backward-difference ρ were told the generic hint: each first explanation names the slip."""

from __future__ import annotations

import pytest
import student_variants as sv
from variant_checks import assert_first_named

from teachraster import exercises as ex
from teachraster.exercises import tries


@pytest.mark.parametrize("label", list(sv.R462))
def test_each_slip_is_named_first(label):
    name, fn, words, kind = sv.R462[label]
    first = assert_first_named(name, fn, words, kind).failures[0]
    assert "pyramid[-2] is level 2" not in first.explanation or "|λ|" not in label


def test_index_as_python_index_keeps_its_words():
    """M1's fix names |λ| only where it gives every answer: ⌊λ⌋ = −2 used as an index (int(),
    no lower clamp) still reads "Python's pyramid[-2] is level 2"."""
    fn = sv._r426("trilinear", "def trilinear(pyramid, uv, lod, wrap='repeat'):\n"
                  "    q = len(pyramid) - 1; lam = min(lod, q)\n"
                  "    lo = int(lam); hi = min(lo + 1, q); t = lam - lo\n"
                  "    return (1 - t) * bilinear(pyramid[lo], uv, wrap) + t * bilinear(pyramid[hi], uv, wrap)\n")  # fmt: skip
    tries.forget_hints()  # every task's: the words must not depend on the tests before it
    said = ex.check("trilinear", fn).failures[0].explanation
    tries.forget_hints()
    assert "Python's pyramid[-2] is level 2" in said, said
