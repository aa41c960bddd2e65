"""r419, exercise 10.1 (``edge_bits``): F1, a slip is named only where every part it changes is
wrong in the answer (never two slips that cancel in a form, never "your absolute one right"
written into a slip's words); one form's own count slips (E's own bound in the relative form,
one bit short, one too many, two short in one form) are named in that form; F4: the slips
r419 found left to the generic hint (a count slip in one form only, differences bounded by two
coordinates, bytes typed as bits, sub-pixel bits twice or multiplied) are named."""

from __future__ import annotations

import re

import matplotlib
import pytest
from student_variants import R419_EDGE_BITS

from teachraster import exercises as ex
from teachraster.exercises import edge_bits as eb
from teachraster.exercises import tries

matplotlib.use("Agg")

#: A count slip of both forms made in one form, and the one-form slip that names it there.
ONE_FORM = {
    ("short", "absolute"): "the absolute count one bit short",
    ("short", "relative"): "E's own bound in the relative form",
    ("long", "absolute"): "the absolute count one bit more",
    ("long", "relative"): "the relative count one bit too many",
    ("two short", "absolute"): "the absolute count two bits short",
    ("two short", "relative"): "the relative count two bits short",
    ("centre bit", "absolute"): "the absolute factor one bit wide",
    ("centre bit", "relative"): "the relative factor one bit wide",
}


def _slips():
    """(knob, slip, form index) for every slip of every knob that changes that form alone."""
    out = []
    for name, slips in eb.KNOBS.knobs.items():
        for slip in slips if name not in ("order", "only") else ():
            for k in range(2):
                out.append(pytest.param(name, slip, k, id=f"{slip.value}-{eb.FORMS[k]}"))
    return out


def _in_one_form(name, slip, k):
    def edge_bits(range_bits, across, sub_bits):
        out = list(eb.answer(range_bits, across, sub_bits))
        out[k] = eb.KNOBS.gives(range_bits, across, sub_bits, **{name: slip.value})[k]
        return tuple(out)

    return edge_bits


def _calls_wrong(words: str, form: str) -> bool:
    """Does ``words`` say the form's count is wrong ("your relative count, 38, is two …",
    "your counts are one bit short")?"""
    return bool(
        re.search(rf"your {form} count, \d+, (?!is right)", words)
        or re.search(r"your counts are (?!right)", words)
        or "each of your counts" in words
    )


@pytest.mark.parametrize(("name", "slip", "k"), _slips())
def test_every_slip_in_one_form_is_named_in_that_form_and_never_in_the_other(name, slip, k):
    fn = _in_one_form(name, slip, k)
    if all(fn(*args) == eb.answer(*args) for args in eb.RANGES):
        pytest.skip("this slip does not change this form")
    tries.forget_hints("edge_bits")
    report = ex.check("edge_bits", fn)
    first = report.failures[0]
    form, other = eb.FORMS[k], eb.FORMS[1 - k]
    head, _, words = first.explanation.partition("; wrong: ")
    assert words.count(": ") >= 1 and len(words.split(": ", 1)[1]) > 20, first.explanation
    assert not _calls_wrong(words, other), first.explanation
    assert f"the {other} form's bits" not in words.split(": ")[0], first.explanation
    if name in ("absolute", "relative", "factor", "largest"):
        assert first.kind == slip.kind, (first.kind, first.explanation)
    elif (slip.value, form) in ONE_FORM:
        assert first.kind == ONE_FORM[slip.value, form], (first.kind, first.explanation)
    elif name == "count":  # said with the form it was made in, the other's count right
        assert first.kind == f"{slip.kind} and in the {form} form only", first.kind
        assert f"in your {form} count only" in words, first.explanation
    tries.forget_hints("edge_bits")


def test_no_combination_of_slips_calls_a_right_count_wrong_or_a_wrong_one_right():
    """Every combination, on every case it gives an answer: its words (each part's, as the
    report joins them) never say a right form's count is wrong, nor a wrong one's right."""
    said = 0
    for m in eb.KNOBS.mistakes():
        if not m.parts:
            continue
        for args in eb.RANGES:
            got, expected = m.gives(*args), eb.answer(*args)
            if got is None or got == expected:  # a passing case: nothing said
                continue
            # the parts the report says: those that change this case (diagnosis._active_parts)
            active = [p for p in m.parts if m.without(p)(*args) != got] or list(m.parts)
            words = "; and ".join(p.say(args, expected, got) for p in active)
            for k, form in enumerate(eb.FORMS):
                if got[k][0] == expected[k][0]:
                    assert not re.search(rf"your {form} count, \d+, (?!is right)", words), words
                else:
                    assert f"your {form} count is right" not in words, words
                    assert f"your {form} count, {got[k][0]}, is right" not in words, words
            said += 1
    assert said > 500


def test_two_slips_that_cancel_in_a_form_are_never_combined():
    """r419 y1: the relative form two bits short, the absolute right, was 'two bits short and
    the absolute factor one bit wide' (the absolute: −2 + 2)."""
    kinds = {m.kind for m in eb.KNOBS.mistakes()}
    assert "the absolute factor one bit wide and two bits short" in kinds  # a combination …
    y1 = R419_EDGE_BITS["edge bits, the relative form two bits short, the absolute right"][1]
    for m in eb.KNOBS.mistakes():  # … that never gives an answer whose absolute count is right
        if m.kind == "the absolute factor one bit wide and two bits short":
            assert all(m.gives(*args) is None for args in eb.RANGES)
            assert m.gives(20, 1024, 8) != y1(20, 1024, 8)


def test_the_figure_agrees_with_the_words_on_which_form_is_right():
    import matplotlib.pyplot as plt

    w35 = R419_EDGE_BITS[
        "edge bits, the relative form by E's own bound (2d + 1), the absolute term by term"
    ][1]
    tries.forget_hints("edge_bits")
    report = ex.check("edge_bits", w35)
    first = report.failures[0]
    assert "(your absolute count is right)" in first.explanation
    case = eb.cases()[0]  # every case fails; the first is the task's own range
    fig, ax = plt.subplots()
    eb.draw(ax, case, w35(*case[1]))
    labels = [t.get_text() for t in ax.texts]
    plt.close(fig)
    assert any(t.startswith("yours: 58 bits") and "(right)" in t for t in labels), labels
    assert any(t.startswith("yours: 37 bits") and "(right)" not in t for t in labels), labels
    tries.forget_hints("edge_bits")


# -- F3: across is any whole number of pixels ------------------------------------------------
def test_across_is_not_always_a_power_of_two_and_its_exponent_decides_a_type():
    import json
    from pathlib import Path

    nb = json.loads((Path(__file__).parents[1] / "notebooks/exercises/10_hard_cases.ipynb")
                    .read_text(encoding="utf-8"))  # fmt: skip
    task = next("".join(c["source"]) for c in nb["cells"]
                if c["metadata"].get("nbgrader", {}).get("grade_id") == "edge_bits_task")  # fmt: skip
    assert "not always a power of two" in task and "is\na power of two)" not in task
    odd = [args for args in eb.RANGES if args[1] & (args[1] - 1)]
    assert len(odd) >= 3
    # int(log2(across)) changes a type on one of them, not only a count
    floor = eb.KNOBS.gives
    assert any(floor(*a, exponent="across rounded down")[1][1] != eb.answer(*a)[1][1] for a in odd)


def test_every_range_counts_alike_by_bits_and_by_the_largest_values():
    """The check never depends on how a correct count is made: lesson 06's (a factor below 2^d
    steps has d bits) and one from the largest values, (2m²).bit_length() + 1, agree on every
    range whose across lies in the top of its binade (r419 c3); r430 F1: below it the count
    from the largest values is one bit tighter, and passes too (``eb.tight``)."""
    for r, a, s in eb.RANGES:
        top = a * 2**s - 1 >= 2 ** ((a - 1).bit_length() + s - 0.5)
        for k, (m, (bits, _)) in enumerate(
            zip((2 ** (r + s) - 1, a * 2**s - 1), eb.answer(r, a, s))
        ):
            tight = (2 * m * m).bit_length() + 1
            assert tight == bits - (k == 1 and not top), (r, a, s)
            assert eb.EDGE_BITS.same(eb.tight(r, a, s), eb.answer(r, a, s), (r, a, s))


def test_the_three_term_sum_adds_no_bit_on_every_range_the_check_uses():
    """r419 F3 (S): the words justify the exemption; it holds because on every range the
    partial sum C + A·x = E − B·y, |E| < 2^(2k+1) and |B·y| < 2^(k+d), stays below C's
    2^(2d+1) (k, d: the relative and the absolute factor's bits)."""
    for args in eb.RANGES:
        b = eb.budgets(*args)
        k, d = b["relative"].delta_bits, b["absolute"].delta_bits
        assert 2 ** (2 * k + 1) + 2 ** (k + d) <= 2 ** (2 * d + 1), args
    fn = R419_EDGE_BITS["edge bits, the absolute form as three terms and the relative from "
                        "across.bit_length()"][1]  # fmt: skip
    tries.forget_hints("edge_bits")
    text = ex.check("edge_bits", fn).failures[0].explanation
    assert "its partial sum C + A·x is E − B·y" in text, text
    tries.forget_hints("edge_bits")
