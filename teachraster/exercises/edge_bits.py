"""Exercise ``edge_bits`` (exercise 10.1, lessons 06 and 07; r394 T1): how many bits E needs.

r394 T1: exercise 10's one graded task, ``robust_fill``, was lesson 07's "Your turn, Part 2"
written in y-down; nothing graded asked why float64 from differences is exact where float32
and A·x + B·y + C are not. This task asks it as numbers, for any range: vertices on the
``1/2**sub_bits``-px grid, every coordinate below ``2**range_bits`` px in size, every difference
the relative form takes (vertex to vertex, centre to vertex) below ``across`` px. For each form
of E, the width of the narrowest signed whole number (sign bit included) that holds its largest
product and the difference of two such, counted term by term in steps of the grid as lesson 06
counts (:func:`teachraster.core.fixed_point.range_budget`, the one count: the absolute form's
largest product multiplies two coordinates, the relative form's two differences), and the first
of float32, int32, float64, int64 that holds that many bits exactly
(:func:`.hard_case_precision.narrowest`). The task's own range, 2²⁰ px and 1,024 px on the
1/256-px grid, gives 58 bits (int64: float64's 54 do not hold C's products a.x·b.y and a.y·b.x) and 38
(float64).

The check runs several ranges, so a typed answer fails. Each slip is a knob of one wrong
solution (:data:`KNOBS`), alone or two at once, named only where it gives the answer: one bit
short (the sign bit, or the difference's bit, left out), one too many, the sub-pixel bits left
out or counted once, bits multiplied where a product adds them, A·x taken as the absolute form's
largest product, the two forms swapped, a type's width taken for what it holds exactly, a
float's sign bit not counted, the absolute count one bit more (A bounded by the whole range, or
A·x + B·y + C counted as three terms; r409 F4); r416 F1/F2: an int's sign not counted (told
apart from ``>`` for ``>=``, which fails at a float's edge too), two bits short, one form's factor
one bit wide (``across.bit_length()``, a centre bit, a coordinate's sign), the relative form
counted from the range, ``across`` taken as bits, bytes for bits. r419 F1: a combination is
named only where every part each slip changes is wrong in the answer and no form's count is
moved back by another slip (:func:`_with`), "your absolute count is right" is read from the
answer, never written into a slip; one form's own count slips (E's own bound in the relative
form, one bit short, one too many, two short in one form) and F4's (a count slip in one form
only, differences bounded by two coordinates, bytes typed as bits, sub-pixel bits twice or
multiplied) are knobs. r419 F3: ``across`` is any whole number of pixels (three of the ranges
are no power of two), so that its exponent is reasoned, not read off: int(log2(across)) rounded
down, ``across.bit_length()`` (right except for a power of two) and a fractional log2 doubled
and cut are the ``exponent`` knob's slips. Where every count is right and a type is not,
the words are about types (r409 F2). r430 F1: three more ranges put ``across`` in the bottom half
of its binade (130, 20, 300 px), where log2 rounded to nearest (the ``exponent`` knob's fourth
slip) is rounded down and a count from the largest values, one bit tighter, passes
(:func:`tight`); F2/F3: the absolute form two bits more names the three-term sum counted as
⌈log2 3⌉ = 2 bits beside a factor one bit wide, the centre bit a sign bit per factor too, and
a form's own count slip beside another says what it does ("leaves out one bit", :func:`_own`);
where no slip gives the answer, the recipe opens with what a wrong count says of itself, where
it can be told (:func:`_implied`: the sub-pixel bits left out of a factor, across times them).
r434 F1: a range of 2^k + 1 px (129), listed last, where ⌈log2(across − 1)⌉ for a difference's
bits is one short (the ``exponent`` knob's fifth slip); F2: ``np.finfo(t).nmant`` taken for
what a float holds (the hidden bit and the sign left out), told from the sign alone at 24
bits (:data:`NMANT`). The recipe is said once two different answers have failed
(:data:`HINTS`), with the worked count of one range the check does not use (:data:`WORKED`,
r416 F4).
"""

from __future__ import annotations

import math
import re

import numpy as np

from ..core.fixed_point import BitBudget, bit_budget, range_budget
from ..study.operation_counts import edge_bits_needed
from . import tries
from .answers import refuse_non_answers, short
from .exercise import Exercise, Knobs, Mistake, PackageAnswer, Slip
from .hard_case_precision import TYPES, exact_bits, narrowest
from .report import NOTHING_DRAWN_FOR
from .running import WrongAnswerType

#: The two forms of E, in the order the answer gives them.
FORMS = ("absolute", "relative")
#: What the answer is, as the refusals say it.
WHAT = ("((absolute bits, type), (relative bits, type)), each type one of "
        f"{', '.join(TYPES)} or None")  # fmt: skip
#: (range_bits, across, sub_bits): the task's own range first, then others, chosen so that
#: every slip fails a case (counts at a type's edge: 32 and 54 bits; 26 and 58, between an
#: int's and a float's; 66, which no type holds; a grid of 1/2 px). Never 0 sub-pixel bits:
#: pixel centres, at k + ½, would lie off the grid (a bit more: lesson 06's centre bit).
#: r419 F3: three widths across that are no power of two (200 px: 34 bits, a 64-bit float,
#: where its exponent rounded down gives 32, a 32-bit int), so that log2 is not the answer;
#: each in the top of its binade (across · 2^s − 1 ≥ 2^(d − ½) for its d bits), where a count
#: from the largest values, (2m²).bit_length() + 1, gives the same bits as lesson 06's.
#: r430 F1: three more in the bottom half of their binade (130, 20 and 300 px), where log2
#: rounded to nearest is rounded down (130 px: 32 bits, a 32-bit int, not 34 and a 64-bit
#: float) and a count from the largest values is one bit tighter than term by term: that
#: count holds every value too, and passes (:func:`tight`). Listed last, so that the first
#: failure of every other slip stays where it was. r434 F1: one across of 2^k + 1 px (129 px,
#: 26 bits, a 32-bit int), where ⌈log2(across − 1)⌉ is one bit short (24 bits, a 32-bit float);
#: listed last for the same reason.
RANGES = ((20, 1024, 8), (16, 64, 4), (10, 16, 8), (11, 256, 4), (18, 512, 8), (23, 2048, 8),
          (24, 4096, 8), (8, 8, 2), (12, 32, 1), (16, 200, 8), (20, 1000, 8),
          (12, 100, 4), (16, 130, 8), (12, 20, 4), (18, 300, 8), (16, 129, 4))  # fmt: skip


def budgets(range_bits: int, across: int, sub_bits: int) -> dict[str, BitBudget]:
    """Each form's count: the absolute form multiplies coordinates below ``2**range_bits`` px,
    the relative form differences below ``across`` px, on the ``1/2**sub_bits`` grid.

    >>> {form: b.needed for form, b in budgets(20, 1024, 8).items()}
    {'absolute': 58, 'relative': 38}
    """
    return {"absolute": range_budget(2**range_bits, sub_bits),
            "relative": range_budget(across, sub_bits)}  # fmt: skip


def answer(range_bits: int, across: int, sub_bits: int) -> tuple:
    """((bits, type), (bits, type)) for the absolute form and the relative one.

    >>> answer(20, 1024, 8)
    ((58, 'int64'), (38, 'float64'))
    """
    return tuple((b.needed, narrowest(b.needed)) for b in budgets(range_bits, across,
                                                                   sub_bits).values())  # fmt: skip


def _label(range_bits: int, across: int, sub_bits: int) -> str:
    # r419 F5: short enough for the figure's title to take two lines, not three
    return (f"edge_bits({range_bits}, {across}, {sub_bits}): a 1/{2**sub_bits}-px grid, "
            f"coordinates below 2^{range_bits} px, differences below {across:,} px")  # fmt: skip


def cases() -> list[tuple[str, tuple, tuple]]:
    return [(_label(*args), args, answer(*args)) for args in RANGES]


#: Names whose meaning differs between C and numpy (r409 F3): refused, not read as numpy's.
AMBIGUOUS = ("float", "int", "double", "long", "single", "half", "short", "longlong", "intc",
             "float_", "int_", "longdouble")  # fmt: skip


#: r416 F3: the aside each C name needs (a numpy dtype or type class is read as numpy's).
C_NAMES = {
    "float": " (C's float is float32, numpy's and Python's float64: say which)",
    "int": " (C's int is 32 bits, numpy's int 64 on most systems: say int32 or int64)",
    "double": " (C's double is 64 bits, a float64: say so)",
    "long": " (C's long is 32 bits on Windows, 64 elsewhere: say int32 or int64)",
}
#: The aside for Python's own ``float`` and ``int`` classes.
PYTHON_NAMES = {
    float: " (Python's float is 64 bits, C's 32: say float32 or float64)",
    int: " (Python's int has no fixed width: say int32 or int64)",
}


def _type(value, form: str):
    """A type as its name: one of :data:`TYPES` (any case, "np." allowed), a numpy scalar type
    or dtype; None or "none": no type holds it. r409 F3: C's names ("float", "int", "double",
    "long") and Python's ``float`` and ``int`` are refused, never read as numpy's."""
    if value is None or (isinstance(value, str) and value.strip().lower() in ("none", "")):
        return None
    refusal = (f"returned {short(value)} as the {form} form's type: one of "
               f"{', '.join(map(repr, TYPES))}, or None")  # fmt: skip
    if isinstance(value, str):
        name = value.strip().lower().removeprefix("np.").removeprefix("numpy.")
        if name in AMBIGUOUS:
            refusal += C_NAMES.get(name, " (a C name, whose width differs between systems)")
    elif value is float or value is int:  # r416 F3: np.dtype("int64") == int is True
        name, refusal = None, refusal + PYTHON_NAMES[value]
    else:
        try:
            name = np.dtype(value).name
        except TypeError:
            name = None
    if name not in TYPES:
        raise WrongAnswerType(refusal)
    return name


def _bits(value, form: str) -> int:
    if isinstance(value, bool | np.bool_):
        raise WrongAnswerType(f"returned {short(value)} as the {form} form's bits: a whole number")
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise WrongAnswerType(f"returned {short(value)} as the {form} form's bits: a whole "
                              "number") from None  # fmt: skip
    if not np.isfinite(x) or not x.is_integer() or x < 1:
        raise WrongAnswerType(f"returned {short(value)} as the {form} form's bits: bits come in "
                              "whole numbers, 1 or more")  # fmt: skip
    return int(x)


def as_answer(value) -> tuple:
    """((bits, type), (bits, type)), read strictly; a dict keyed "absolute" and "relative" too."""
    if isinstance(value, dict) and set(value) == set(FORMS):
        value = tuple(value[form] for form in FORMS)
    refuse_non_answers(value, WHAT)
    pairs = value if isinstance(value, tuple | list) else None
    if (
        pairs is None
        or len(pairs) != 2
        or any(not isinstance(p, tuple | list) or len(p) != 2 for p in pairs)
    ):
        raise WrongAnswerType(f"returned {short(value)}: expected {WHAT}")
    return tuple((_bits(b, form), _type(t, form)) for (b, t), form in zip(pairs, FORMS))


def tight(range_bits: int, across: int, sub_bits: int) -> tuple:
    """r430 F1: the answer with the relative form counted from its largest values, the
    narrowest whole number that holds (b − a) × (p − a) for differences of at most
    m = across · 2^s − 1 steps: (2m²).bit_length() + 1 bits. One bit below term by term
    where across lies in the bottom half of its binade (130 px: 33, not 34), the same
    elsewhere; exact too, so it passes.

    >>> tight(16, 130, 8)
    ((50, 'float64'), (33, 'float64'))
    """
    m = across * 2**sub_bits - 1
    n = (2 * m * m).bit_length() + 1
    return (answer(range_bits, across, sub_bits)[0], (n, narrowest(n)))


def _same(got, expected, args=None) -> bool:
    return got == expected or (args is not None and got == tight(*args))


def _match(got, answer_, args=None) -> bool:
    """A mistake gives the student's answer; r441 H1 (n08): a relative part counted from the
    largest values (:func:`tight`, accepted) matches a mistake that leaves it right."""
    if answer_ is None:
        return False
    if args is not None and got != answer_ and got[1] == tight(*args)[1]:
        right = answer(*args)[1]
        if answer_[1] == right != got[1]:
            got = (got[0], right)
    return got == answer_


def explain(args, expected, got) -> str:
    """The student's counts, and which of the answer's four parts are wrong (never the right
    ones; the types are not named: the words name float32 only as its cause, r394)."""
    wrong = [f"the {form} form's {part}" for form, g, e in zip(FORMS, got, expected)
             for part, k in (("bits", 0), ("type", 1)) if g[k] != e[k]]  # fmt: skip
    return (f"yours is {got[0][0]} bits for the absolute form and {got[1][0]} for the relative "
            f"one; wrong: {', '.join(wrong)}")  # fmt: skip


def spoken(name: str | None) -> str:
    """A type as the words say it: "a 32-bit float", never "float32" (:mod:`.diagnosis` takes
    that word for a precision diagnosis)."""
    if name is None:
        return "no type of these"
    t = np.dtype(name)
    return f"a {t.itemsize * 8}-bit {'float' if t.kind == 'f' else 'int'}"


def worked(args, form: str) -> str:
    """One form's count in steps of the grid, its numbers from :func:`budgets` (said once two
    answers have failed: :data:`HINTS`)."""
    b = budgets(*args)[form]
    factor = "coordinates" if form == "absolute" else "differences"
    return (
        f" (worked: the {form} form's {factor} are below 2^{b.delta_bits} steps, its "
        f"products below 2^{b.product_bits}, a difference of two below 2^{b.edge_bits}: "
        f"{b.needed} bits with the sign: {spoken(narrowest(b.needed))})"
    )


#: r416 F4: the full words work a range the check does not use (never one of the exercise's own
#: answers): lesson 06's Direct3D 16.8 over 2^16 px, differences below 128 px.
WORKED = (16, 128, 8)
assert WORKED not in RANGES


def _worked_both(args) -> str:
    r, a, s = args  # no parenthesis inside: HINTS holds the words back until they are spent
    return (f" (worked: a range the check does not use, coordinates below 2^{r} px, differences "
            f"below {a:,} px, on the 1/{2**s}-px grid)" + worked(args, "absolute")
            + worked(args, "relative"))  # fmt: skip


def _implied(args, expected, got) -> str:
    """r430 F3 (w27, x8, x17): where no slip of the table gives the answer, what a wrong count
    says of itself, where it can be told: factors of k bits (a count 2k + 2), the sub-pixel
    bits left out of them, across times the sub-pixel bits, the absolute form's count one bit
    short; each beside the right factor. Nothing where the count shows nothing."""
    r, a, s = args
    said = []
    for k, form in enumerate(FORMS):
        n = got[k][0]
        if n == expected[k][0]:
            continue
        right = r + s if form == "absolute" else _exponent(a) + s
        mine = f"your {form} count, {n},"
        if form == "relative" and n == 2 * (r + s) + 1:
            what = (
                f"{mine} is the absolute form's count, one bit short; its factors are differences"
            )
        elif n % 2 or not 1 <= (n - 2) // 2 != right:
            continue
        elif (f := (n - 2) // 2) == right - s:
            what = (
                f"{mine} leaves the {s} sub-pixel bits out of each factor ({f} bits, 2 · {f} + 2)"
            )
        elif form == "relative" and f == math.ceil(math.log2(a * s)):
            what = (f"{mine} multiplies across by the sub-pixel bits, {s}, not by 2^{s} ({f} "
                    f"bits per factor, 2 · {f} + 2)")  # fmt: skip
        else:
            what = f"{mine} is what factors of {f} bits give (2 · {f} + 2)"
        said.append(f"{what}: {_factor_words(args, form)}")
    return ": " + "; ".join(said) + "; in general," if said else ":"


def _rule(args, expected, got) -> str:
    held = ", ".join(f"{spoken(t)} {exact_bits(t)}" for t in TYPES)
    return (f"{_implied(args, expected, got)} count in steps of the grid, as lesson 06 does, term by term (recipe: a factor "
            "below 2^k steps has k bits, a product's bits are its factors' added, a difference "
            "of two products takes one more, the sign one more; the bits of a whole number each "
            f"type holds exactly, sign included: {held}){_worked_one(args)}")  # fmt: skip


def _worked_one(args) -> str:
    """r409 change 2, r416 F4: one worked count, of :data:`WORKED` (a range the check does not
    use), said on the first listed case's words only (the recipe is said on every case)."""
    return _worked_both(WORKED) if tuple(args) == RANGES[0] else ""


def _type_rule(args, expected, got) -> str:
    """r409 F2: every count right, a type wrong: the words are about types, never counting;
    None said only where it is wrong (F1), ``>`` for ``>=`` named."""
    said = []
    for form, (n, t), (_, e) in zip(FORMS, got, expected):
        if t == e:
            continue
        if e is None:
            said.append(f"no type of the four holds the {form} form's {n} bits: its type is None")
        elif t is None:
            said.append(f"your None for the {form} form: {spoken(e)} holds {n} bits")
        elif t == narrowest(n, lambda name: exact_bits(name) - 1):
            said.append(f"a type that holds exactly the {form} form's {n} bits holds them: "
                        f"compare with >=, not >{_NO_SIGN_ANY}")  # fmt: skip
    held = ", ".join(f"{spoken(t)} {exact_bits(t)}" for t in TYPES)
    return ("your counts are right, the type is not: the first of the four, in the order "
            "the task lists them, that holds every whole number of that many bits, sign "
            "included (a float holds fewer than its width)"
            f"{'; ' + '; '.join(said) if said else ''} (recipe: the bits of a whole number each "
            f"type holds exactly, sign included: {held})")  # fmt: skip


def _raw(
    range_bits,
    across,
    sub_bits,
    *,
    count="right",
    largest="C",
    holds="exactly",
    order="as asked",
    absolute="C's",
    relative="right",
    factor="right",
    exponent="right",
    only="both",
) -> tuple:
    """The answer a student gives with some slips (:data:`KNOBS`), whatever they cancel."""
    b = budgets(range_bits, across, sub_bits)
    bits = {form: b[form].delta_bits for form in FORMS}
    # r419 F3: across's exponent (its own knob: it combines with a factor's slip; a
    # slip that bounds the relative factor otherwise replaces it)
    if exponent == "across rounded down":  # int(np.log2(across)): right for 2^k only
        bits["relative"] += across.bit_length() - 1 - _exponent(across)
    elif exponent == "across.bit_length()":  # right except for a power of two
        bits["relative"] += across.bit_length() - _exponent(across)
    elif exponent == "across rounded to nearest":  # r430 F1: round(log2(across))
        bits["relative"] += int(np.floor(np.log2(across) + 0.5)) - _exponent(across)
    elif exponent == "across - 1's log2":  # r434 F1: ceil(log2(across - 1)), short at 2^k + 1
        bits["relative"] += math.ceil(math.log2(across - 1)) - _exponent(across)
    elif exponent == "fractional log2":  # r419 c4, c5: int(2 * (log2(across) + s) + 2)
        bits["relative"] += float(np.log2(across)) - _exponent(across)
    if factor == "relative wider":  # r416 F2: a centre bit or a sign in the relative factor
        bits["relative"] += 1
    elif factor == "absolute wider":
        bits["absolute"] += 1
    elif factor == "across as bits":
        bits["relative"] = across + sub_bits
    elif factor == "relative from the range":
        bits["relative"] = bits["absolute"]
    elif factor == "relative from two coordinates":  # r419 F4 w25: |a − b| < 2 · 2^range_bits
        bits["relative"] = bits["absolute"] + 1
    factors = {form: (bits[form], bits[form]) for form in FORMS}
    if largest == "A·x":
        factors["absolute"] = (bits["absolute"], bits["relative"])
    held = _HELD[holds]
    out = []
    for form in FORMS:
        k, m = factors[form]
        s = sub_bits
        slip = count if only in ("both", form) else "right"  # r419 F4: a count slip in one form
        n = {"right": k + m + 2, "short": k + m + 1, "long": k + m + 3, "two short": k + m,
             "no sub-pixel": k + m - 2 * s + 2, "sub-pixel once": k + m - s + 2,
             "sub-pixel twice": k + m + 2 * s + 2, "sub-pixel multiplied": (k + m - 2 * s) * s + 2,
             "multiplied": k * m + 2, "centre bit": k + m + 4, "bytes": k + m + 2,
             "bytes typed": -(-(k + m + 2) // 8)}[slip]  # fmt: skip
        # r419 F1: one form's own count off (x1, x3, y1–y3, w35: E's own bound in one form)
        own = absolute if form == "absolute" else relative
        n += {"one more": 1, "one short": -1, "two short": -2}.get(own, 0)
        if form == "relative" and relative == "one product":  # r441 H1 (n07): |E| ≤ m²
            m = across * 2**sub_bits - 1
            n = (m * m).bit_length() + 1
        n = int(n)  # a fractional log2 of across, cut by int() as its author's code does
        out.append((-(-n // 8) if slip == "bytes" else n, narrowest(n, held)))
    return tuple(out[::-1]) if order == "swapped" else tuple(out)


def _parts(answer_, right) -> set:
    """The parts (form, 0 for bits or 1 for type) of ``answer_`` that differ from ``right``."""
    return {(f, k) for f in range(2) for k in range(2) if answer_[f][k] != right[f][k]}


def _with(*args, **settings) -> tuple | None:
    """r419 F1: the answer of some slips together, or None where one of them changes a part
    the others change back (a combination is named only where every part each slip changes
    is wrong in the answer, and no form's count is moved back: never "your absolute count is
    right" beside a slip of it). Compared in the forms' own order (swapped ones put back)."""
    out = _raw(*args, **settings)
    if len(settings) > 1:
        right = _raw(*args)
        mine = _in_order(out, settings)
        wrong = _parts(mine, right)
        only = {"only": settings["only"]} if "only" in settings else {}  # one form's slips
        for name, value in settings.items():
            alone = _in_order(_raw(*args, **{**only, name: value}), {name: value})
            if not _parts(alone, right) <= wrong or any(
                (o[0] - r[0]) * (o[0] - r[0]) < (o[0] - r[0]) * (a[0] - r[0])
                for o, a, r in zip(mine, alone, right)
            ):  # a form's count the others move back (y2: −1 in both, +2 in one) is no cause
                return None
    return out


def _in_order(answer_, settings) -> tuple:
    """An answer with its forms in the task's order (put back where ``order`` swapped them)."""
    return answer_[::-1] if settings.get("order") == "swapped" else answer_


#: What each type is taken to hold: exactly (a float's significand with its hidden bit, and its
#: sign), its width, or a float's significand alone, the sign not counted.
_HELD = {
    "exactly": exact_bits,
    "width": lambda t: np.dtype(t).itemsize * 8,
    "no sign": lambda t: exact_bits(t) - (np.dtype(t).kind == "f"),
    "nmant": lambda t: exact_bits(t) - 2 * (np.dtype(t).kind == "f"),  # r434 F2
    "int no sign": lambda t: exact_bits(t) - (np.dtype(t).kind == "i"),  # r416 F1
    # r441 H2: a float's range (log2 of np.finfo(t).max: 128, 1024) for what it holds (n09);
    # no float ever (np.finfo(t).precision's decimal digits, or the ints tried first: n10, w15)
    "range": lambda t: (
        int(np.log2(float(np.finfo(t).max))) + 1 if np.dtype(t).kind == "f" else exact_bits(t)
    ),
    "no float": lambda t: 0 if np.dtype(t).kind == "f" else exact_bits(t),
    ">": lambda t: exact_bits(t) - 1,  # held > bits: every type one bit short
}


def _counts(args, got, expected=None) -> str:
    """ "yours are 57 and 37"; r419 F4: "in your relative count only, 22; your absolute count,
    58, is right" where one form's count is right (read from the answer)."""
    right = [expected is not None and g[0] == e[0] for g, e in zip(got, expected or got)]
    if any(right) and not all(right):
        k = right.index(False)
        return (f"in your {FORMS[k]} count only, {got[k][0]}; your {FORMS[1 - k]} count, "
                f"{got[1 - k][0]}, is right")  # fmt: skip
    return f"yours are {got[0][0]} and {got[1][0]}"


def _grid(args) -> str:
    s = args[2]
    return f"1/{2**s}-px" if s else "1-px"


#: Lesson 06's count: Direct3D's 16.8 over 2^16 px (49 bits by E's own bound, 50 term by term).
_D3D = range_budget(2**16, 8)


def _counts_are(a, e, g, value: str, what: str) -> str:
    """r419 F1: "your counts are one bit short" only where that slip alone gives both counts;
    beside another slip, what it does to each count."""
    alone = sorted(n for n, _ in g) == sorted(n for n, _ in _raw(*a, count=value))
    return (f"your counts are {what} ({_counts(a, g, e)})" if alone
            else f"each of your counts is {what} for its factors ({_counts(a, g, e)})")  # fmt: skip


def _one_right(e, g, form: str) -> str:
    """r419 F1: " (your relative count is right)" where the other form's count is right, read
    from the answer (never written into a slip's words)."""
    other = 1 - FORMS.index(form)
    return f" (your {FORMS[other]} count is right)" if g[other][0] == e[other][0] else ""


SHORT = Slip("one bit short", lambda a, e, g: (
    f"{_counts_are(a, e, g, 'short', 'one bit short')}: the sign bit, or the bit a difference of "
    "two products adds to the larger product's, left out; or E's own bound (|E| at most the "
    f"largest product: lesson 06's {_D3D.least_needed} for 16.8 over 2^16 px) where the task "
    f"counts term by term (lesson 06's {_D3D.needed})"), "short")  # fmt: skip
TWO_SHORT = Slip("two bits short", lambda a, e, g: (
    f"{_counts_are(a, e, g, 'two short', 'two bits short')}: both the bit a difference of two "
    "products adds to the larger product's and the sign bit left out: a product's bits, "
    f"then one more for the difference, one more for the sign{_NARROW}"), "two short")  # fmt: skip
BYTES = Slip("bytes, not bits", lambda a, e, g: (
    f"{_counts(a, g, e)}: bytes, not bits; the answer counts bits (a 64-bit int "
    "is 8 bytes)"), "bytes")  # fmt: skip
#: r419 F4 w34: bytes, and each type chosen for that many bits.
BYTES_TYPED = Slip("bytes, not bits", lambda a, e, g: (
    f"{_counts(a, g, e)}: bytes, not bits, and your types are chosen for that "
    "many bits; the answer counts bits (a 64-bit int is 8 bytes)"), "bytes typed")  # fmt: skip


#: r441 M1 (n15, n19): a factor one bit narrow gives the same count as two bits left out
#: (2(k − 1) + 2 = 2k): the words say both.
_NARROW = (
    "; or each factor counted one bit narrow (a coordinate below 2^r px in size has r "
    "bits in pixels, its sign counted once, at the end, not in each factor; a "
    "difference below across px is below across · 2^s steps)"
)


def _narrow(a, form: str) -> str:
    """r441 M1: one form's two bits short, said beside its factor one bit narrow."""
    return f"; or each factor counted one bit narrow: {_factor_words(a, form)}"


def _exponent(across: int) -> int:
    """The least k with ``across <= 2**k``: a difference below ``across`` px is below 2^k px."""
    return (across - 1).bit_length()


def _factor_words(a, form: str) -> str:
    """A form's factor in steps of the grid, its exponent said (r419 F3: across any width)."""
    if form == "relative":
        k = _exponent(a[1])
        below = f"= 2^{k} px is" if a[1] == 2**k else f"is below 2^{k} px, so"
        return (f"a difference below {a[1]:,} px {below} below 2^{k + a[2]} steps: "
                f"{k + a[2]} bits per factor")  # fmt: skip
    return (f"a coordinate below 2^{a[0]} px is below 2^{a[0] + a[2]} steps: {a[0] + a[2]} "
            "bits per factor")  # fmt: skip


REL_WIDER = Slip("the relative factor one bit wide", lambda a, e, g: (
    f"your relative count, {g[1][0]}, counts each factor one bit wide{_one_right(e, g, 'relative')}: {_factor_words(a, 'relative')}"
    f", not {_exponent(a[1]) + a[2] + 1} (the centres, at k + ½ px, are on the grid already: no "
    "centre bit; the one sign bit is counted at the end, not one in each factor; and a "
    f"difference is below across, {a[1]:,} px, not twice it)"),
    "relative wider")  # fmt: skip
#: r419 F3: across any width: its bits rounded down (int(log2(across))) or across.bit_length().
FLOOR = Slip("across's exponent rounded down", lambda a, e, g: (
    f"your relative count, {g[1][0]}, rounds across's exponent down"
    f"{_one_right(e, g, 'relative')}: {a[1]:,} px lies between 2^{_exponent(a[1]) - 1} and "
    f"2^{_exponent(a[1])} px: {_factor_words(a, 'relative')}, not {_exponent(a[1]) - 1 + a[2]}"),
    "across rounded down")  # fmt: skip
#: r430 F1: round(log2(across)): right in the top half of a binade, rounded down below it.
NEAREST = Slip("across's exponent rounded to nearest", lambda a, e, g: (
    f"your relative count, {g[1][0]}, rounds across's exponent to nearest"
    f"{_one_right(e, g, 'relative')}: {a[1]:,} px lies between 2^{_exponent(a[1]) - 1} and "
    f"2^{_exponent(a[1])} px, nearer 2^{_exponent(a[1]) - 1} in log2 (log2({a[1]:,}) = "
    f"{np.log2(a[1]):.2f}), but a difference up to {a[1] - 1:,} px needs "
    f"{_exponent(a[1])} bits in pixels, not {_exponent(a[1]) - 1}: round log2 up: "
    f"{_factor_words(a, 'relative')}"), "across rounded to nearest")  # fmt: skip
#: r434 F1: the bits of a difference up to across − 1 px taken as ⌈log2(across − 1)⌉ (w29, w38):
#: right except where across − 1 is a power of two.
LESS_ONE = Slip("the bits of across − 1 as ⌈log2(across − 1)⌉", lambda a, e, g: (
    f"your relative count, {g[1][0]}, takes ⌈log2(across − 1)⌉ for the bits of a difference"
    f"{_one_right(e, g, 'relative')}: a difference reaches across − 1 px, and a whole number n "
    "has ⌈log2(n + 1)⌉ bits (n.bit_length()), not ⌈log2 n⌉, one fewer where n is a power of "
    f"two: at {a[1]:,} px across, a difference of {a[1] - 1:,} px needs {_exponent(a[1])} bits "
    f"in pixels, not {_exponent(a[1]) - 1}: {_factor_words(a, 'relative')}"),
    "across - 1's log2")  # fmt: skip
FRACTIONAL = Slip("a fractional log2 of across", lambda a, e, g: (
    f"your relative count, {g[1][0]}, doubles a fractional exponent, log2({a[1]:,}) = "
    f"{np.log2(a[1]):.2f}, and cuts the sum to a whole number{_one_right(e, g, 'relative')}: a "
    f"factor has a whole number of bits: {_factor_words(a, 'relative')}"),
    "fractional log2")  # fmt: skip
BIT_LENGTH = Slip("across.bit_length() for its exponent", lambda a, e, g: (
    f"your relative count, {g[1][0]}, takes across.bit_length() for the exponent"
    f"{_one_right(e, g, 'relative')}: across.bit_length() is {a[1].bit_length()}, the bits of "
    f"{a[1]:,} itself, but a difference below it is at most {a[1] - 1:,} px: "
    f"{_factor_words(a, 'relative')}, not {a[1].bit_length() + a[2]}"),
    "across.bit_length()")  # fmt: skip
ABS_WIDER = Slip("the absolute factor one bit wide", lambda a, e, g: (
    f"your absolute count, {g[0][0]}, adds two bits{_one_right(e, g, 'absolute')}; two slips "
    "give it: each factor counted one bit wide, or A·x + B·y + C counted as a sum of three "
    "terms, ⌈log2 3⌉ = 2 bits more. The factors: "
    f"{_factor_words(a, 'absolute')}; its sign is the one sign bit counted at the end, not a "
    "bit in each factor (and the centres are on the grid already: no centre bit). The sum adds "
    "no bit: its partial sum C + A·x is E − B·y, and E and B·y, whose factors include "
    "differences below across, stay far below C's products"), "absolute wider")  # fmt: skip
REL_RANGE = Slip("the relative form from the range", lambda a, e, g: (
    f"your relative count, {g[1][0]}, is the absolute form's: the relative form's factors are "
    f"differences, below {a[1]:,} px (across), not coordinates below 2^{a[0]} px"),
    "relative from the range")  # fmt: skip
#: r419 F4 w25: a difference of two coordinates bounded by twice the range.
REL_TWO_COORDS = Slip("the relative form from two coordinates", lambda a, e, g: (
    f"your relative count, {g[1][0]}, bounds a difference by two coordinates, 2 · 2^{a[0]} px{_one_right(e, g, 'relative')}: "
    f"the relative form's differences (vertex to vertex, centre to vertex) are below across, "
    f"{a[1]:,} px, however far out the triangle lies: {_factor_words(a, 'relative')}"),
    "relative from two coordinates")  # fmt: skip
ACROSS_BITS = Slip("across taken as bits", lambda a, e, g: (
    f"your relative count, {g[1][0]}, takes across, {a[1]:,} px, for a number of bits: it is a "
    f"length; its bits are its exponent, {_exponent(a[1])} (differences below "
    f"2^{_exponent(a[1])} px)"), "across as bits")  # fmt: skip
LONG = Slip("one bit too many", lambda a, e, g: (
    f"{_counts_are(a, e, g, 'long', 'one bit too many')}: a difference of two products below "
    "2^p is below 2^(p + 1), and the sign takes one bit more: no bit beyond (a factor below "
    "2^k steps is at most 2^k − 1: k bits, not k + 1)"), "long")  # fmt: skip
CENTRE = Slip("a centre bit per factor", lambda a, e, g: (
    f"{_counts_are(a, e, g, 'centre bit', 'two bits too many')}: you add a bit per factor for the "
    "pixel centres (lesson 06's centre bit) or for each factor's sign, but with "
    f"{a[2]} sub-pixel bits (1 or more) the centres, at k + ½ px, are on the grid already, and "
    "the one sign bit is counted at the end, not one in each factor: a factor below 2^k steps "
    "has k bits"),
    "centre bit")  # fmt: skip
NO_SUB = Slip("no sub-pixel bits", lambda a, e, g: (
    f"you count whole pixels ({_counts(a, g, e)}): on the {_grid(a)} grid a factor has {a[2]} bits "
    f"more than in pixels, so a product {2 * a[2]} more"), "no sub-pixel")  # fmt: skip
ONCE = Slip("sub-pixel bits once", lambda a, e, g: (
    f"you count the sub-pixel bits once per product ({_counts(a, g, e)}): both of its factors are on "
    f"the {_grid(a)} grid, {a[2]} bits each, so a product has {2 * a[2]}"),
    "sub-pixel once")  # fmt: skip
#: r419 F4 w36, z3: the sub-pixel bits added twice per factor, or multiplied with a factor's.
TWICE = Slip("sub-pixel bits twice per factor", lambda a, e, g: (
    f"you add the sub-pixel bits twice per factor ({_counts(a, g, e)}): a length in steps of "
    f"1/{2**a[2]} px has {a[2]} bits more than in pixels, once per factor, so a product "
    f"{2 * a[2]} more"), "sub-pixel twice")  # fmt: skip
SUB_MULTIPLIED = Slip("sub-pixel bits multiplied", lambda a, e, g: (
    f"you multiply a factor's bits by the sub-pixel bits ({_counts(a, g, e)}): a length below 2^k "
    f"px is below 2^k · 2^{a[2]} = 2^(k + {a[2]}) steps on the {_grid(a)} grid: the sub-pixel "
    "bits are added to a factor's, not multiplied"), "sub-pixel multiplied")  # fmt: skip
MULTIPLIED = Slip("bits multiplied", lambda a, e, g: (
    f"you multiply bits ({_counts(a, g, e)}): numbers below 2^k and 2^l multiply to below "
    "2^k · 2^l = 2^(k + l), so a product's bits are its factors' added"), "multiplied")  # fmt: skip
A_X = Slip("A·x as the largest product", lambda a, e, g: (
    f"your absolute count, {g[0][0]}, takes A·x (a difference times a coordinate) for the "
    "largest product: C = a.x·b.y − a.y·b.x multiplies two coordinates, each below "
    f"2^{a[0]} px"), "A·x")  # fmt: skip
SWAPPED = Slip("forms swapped", lambda a, e, g: (
    "your absolute and relative answers are swapped: the absolute form A·x + B·y + C "
    f"multiplies coordinates (below 2^{a[0]} px), the relative form differences (below "
    f"{a[1]:,} px)"), "swapped")  # fmt: skip
WIDTH = Slip("a type's width for what it holds", lambda a, e, g: (
    "you take a type's width for what it holds exactly: a 32-bit float holds every whole "
    f"number up to 2^{exact_bits('float32') - 1} in size, {exact_bits('float32')} bits with the "
    f"sign, a 64-bit float {exact_bits('float64')}; only an integer type holds its whole width"),
    "width")  # fmt: skip
INT_NO_SIGN = Slip("an int's sign bit not counted", lambda a, e, g: (
    "your counts are right; you take an int to hold one bit less than its width: an int32 "
    f"holds {exact_bits('int32')} bits with its sign (np.iinfo(np.int32).bits counts the sign): "
    f"every whole number from −2^{exact_bits('int32') - 1} to 2^{exact_bits('int32') - 1} − 1; "
    f"an int64 {exact_bits('int64')}"), "int no sign")  # fmt: skip
#: r441 M2 (n20): every type taken one bit short gives the answers of ``>`` for ``>=``.
_NO_SIGN_ANY = ("; or you take every type to hold one bit less than it does, its sign left out "
                "(np.finfo(t).nmant + 1 and np.iinfo(t).max.bit_length() count no sign): a "
                f"32-bit float holds {exact_bits('float32')} bits with its sign, a 32-bit int "
                f"{exact_bits('int32')}, a 64-bit float {exact_bits('float64')}, a 64-bit int "
                f"{exact_bits('int64')}")  # fmt: skip
GREATER = Slip("> for >=", lambda a, e, g: (
    "your counts are right, the type is not: a type that holds exactly as many bits as the "
    f"count holds them: compare with >=, not >{_NO_SIGN_ANY}"), ">")  # fmt: skip
NO_SIGN = Slip("a float's sign bit not counted", lambda a, e, g: (
    "you take a float to hold its significand's bits only: a 32-bit float holds every whole "
    f"number up to 2^{exact_bits('float32') - 1} in size, of either sign, so "
    f"{exact_bits('float32')} bits with the sign, a 64-bit float {exact_bits('float64')}"),
    "no sign")  # fmt: skip
#: r441 H2 (n09): a float's range taken for what it holds exactly.
RANGE = Slip("a float's range for what it holds", lambda a, e, g: (
    "your counts are right, the type is not: you choose a 32-bit float for every count, as if "
    "a float held every whole number up to its range (a 32-bit float's np.finfo(t).max is "
    "about 2^128) or as if one type fitted all: above 2^24 a 32-bit float skips "
    f"whole numbers (2^24 + 1 is none of its numbers): it holds every whole number up to 2^24 "
    f"in size, {exact_bits('float32')} bits with the sign; a 64-bit float "
    f"{exact_bits('float64')}"), "range")  # fmt: skip
#: r441 H2 (n10, w15): never a float: np.finfo(t).precision read as bits, or the ints first.
NO_FLOAT = Slip("never a float", lambda a, e, g: (
    "your counts are right, the type is not: you never choose a float, where one holds the "
    "count: the order is a 32-bit float, a 32-bit int, a 64-bit float, a 64-bit int, and a "
    "float holds every whole number "
    f"of its significand's bits, sign included: a 32-bit float {exact_bits('float32')} bits, a "
    f"64-bit float {exact_bits('float64')} (np.finfo(t).precision counts decimal digits, "
    f"{np.finfo(np.float32).precision} and {np.finfo(np.float64).precision}, not bits)"),
    "no float")  # fmt: skip
#: r434 F2 (w13): np.finfo(t).nmant taken for what a float holds: the hidden bit and the sign
#: left out (told apart from the sign alone where a count lies between: 24 bits, 53).
NMANT = Slip("a float's nmant for what it holds", lambda a, e, g: (
    "you take a float to hold np.finfo(t).nmant bits: nmant counts the stored fraction bits "
    f"only ({exact_bits('float32') - 2} for a 32-bit float); the significand has a hidden "
    f"leading 1 as well, so a 32-bit float holds {exact_bits('float32') - 1} significant bits "
    f"with the hidden one, and a sign bit: {exact_bits('float32')} bits in all (a 64-bit "
    f"float: {exact_bits('float64') - 2} + 2 = {exact_bits('float64')})"), "nmant")  # fmt: skip


def _own(a, e, g, form: str, value: str, alone: str, part: str) -> str:
    """r430 F3 (x3): a form's own count slip, "your relative count, 37, is one bit short (your
    absolute count is right)" where that slip alone gives the count; beside another slip of
    that form, what this one does ("leaves out one bit"), never a total it is not."""
    k = FORMS.index(form)
    if _raw(*a, **{form: value})[k][0] == g[k][0]:
        return f"your {form} count, {g[k][0]}, {alone}{_one_right(e, g, form)}"
    return f"your {form} count, {g[k][0]}, {part}"


ABS_MORE = Slip("the absolute count one bit more", lambda a, e, g: (
    _own(a, e, g, "absolute", "one more", "is one bit more than C's count",
         "adds one bit to C's count") + "; three slips give it: "
    f"A = a.y − b.y bounded by the whole range, 2^{a[0]} px (it is a difference of two "
    f"vertices, below {a[1]:,} px), or A·x + B·y + C counted as a sum of three terms (the sum "
    "adds no bit: its partial sum C + A·x is E − B·y, and E and B·y, whose factors include "
    "differences below across, stay far below C's products); or, counted from the largest "
    f"values, a coordinate taken as 2^{a[0] + a[2]} steps: below it, it is at most "
    f"2^{a[0] + a[2]} − 1 ({a[0] + a[2]} bits)"),
    "one more")  # fmt: skip
#: r419 F1: one form's own count off, the other's right (each said from the answer).
ABS_SHORT = Slip("the absolute count one bit short", lambda a, e, g: (
    f"{_own(a, e, g, 'absolute', 'one short', 'is one bit short', 'leaves out one bit')}: C = a.x·b.y − a.y·b.x is a difference of "
    "two products: a product's bits, one more for the difference (C's own bound, |C| at most "
    "its larger product, leaves it out), one more for the sign"), "one short")  # fmt: skip
ABS_TWO_SHORT = Slip("the absolute count two bits short", lambda a, e, g: (
    f"{_own(a, e, g, 'absolute', 'two short', 'is two bits short', 'leaves out two bits')}: both the bit the difference "
    "a.x·b.y − a.y·b.x adds to its larger product's and the sign bit left out"
    f"{_narrow(a, 'absolute')} (its sign counted once, at the end)"),
    "two short")  # fmt: skip
REL_BOUND = Slip("E's own bound in the relative form", lambda a, e, g: (
    f"{_own(a, e, g, 'relative', 'one short', 'is one bit short', 'leaves out one bit')}: E's own bound? |E| is at most its larger "
    f"product (lesson 06's {_D3D.least_needed} for 16.8 over 2^16 px), but the task counts term "
    f"by term (lesson 06's {_D3D.needed}): E = (b − a) × (p − a) is a difference of two "
    "products: a product's bits, one more for the difference, one more for the sign (or the "
    "sign bit left out)"), "one short")  # fmt: skip
REL_LONG = Slip("the relative count one bit too many", lambda a, e, g: (
    f"{_own(a, e, g, 'relative', 'one more', 'is one bit too many', 'adds one bit too many')}: E = (b − a) × (p − a) is a difference "
    "of two products: a product's bits, one more for the difference, one more for the sign, "
    "no bit beyond (a factor below 2^k steps is at most 2^k − 1: k bits, not k + 1)"),
    "one more")  # fmt: skip
#: r419 F4 (x10, w37): a count slip made in one form only (alone it changes nothing).
ONLY_ABS = Slip("in the absolute form only", (
    "that slip in one form only: one rule counts both, as you counted the relative one"),
    "absolute")  # fmt: skip
ONLY_REL = Slip("in the relative form only", (
    "that slip in one form only: one rule counts both, as you counted the absolute one"),
    "relative")  # fmt: skip
#: r441 H1 (n07): the relative form counted from its largest values with one product, m², for
#: E's bound (E's own bound where across tops its binade, one bit less elsewhere).
ONE_PRODUCT = Slip("the relative count from one product", lambda a, e, g: (
    f"your relative count, {g[1][0]}, bounds E by one product, m² (m = across · 2^s − 1 = "
    f"{a[1] * 2**a[2] - 1:,} steps, the largest difference){_one_right(e, g, 'relative')}: "
    "E = (b − a) × (p − a) is a difference of two products, each up to m² in size and of "
    "either sign, so |E| reaches 2m²: one bit more, and the sign: (2m²).bit_length() + 1 bits "
    "if you count from the largest values, or term by term as lesson 06 does"),
    "one product")  # fmt: skip
REL_TWO_SHORT = Slip("the relative count two bits short", lambda a, e, g: (
    f"{_own(a, e, g, 'relative', 'two short', 'is two bits short', 'leaves out two bits')}: both the bit a difference of two "
    f"products adds to the larger product's and the sign bit left out{_narrow(a, 'relative')}"),
    "two short")  # fmt: skip


def _types_only(args, expected, got) -> bool:
    """Every count right, a type wrong (r409 F2)."""
    return all(g[0] == e[0] for g, e in zip(got, expected)) and got != expected


#: r409 F2: a type-only mistake no knob names (ints listed first, > for >=, None never
#: returned): words about types, never about counting.
TYPES_ONLY = Mistake("types only", _type_rule, fits=_types_only, symptom=True)

#: The slips, alone or two at once (of different knobs).
#: r419 F1: one form's own slips first, so that of two combinations giving one answer the one
#: whose parts each change a different form is named (w39: the absolute count one more and
#: across.bit_length(), not one too many in both and the relative one more again).
KNOBS = Knobs(_with, {"absolute": (ABS_MORE, ABS_SHORT, ABS_TWO_SHORT),
                      "relative": (REL_BOUND, REL_LONG, REL_TWO_SHORT, ONE_PRODUCT),
                      "factor": (REL_WIDER, ABS_WIDER, REL_RANGE, REL_TWO_COORDS, ACROSS_BITS),
                      "exponent": (FLOOR, FRACTIONAL, BIT_LENGTH, NEAREST, LESS_ONE),
                      "count": (SHORT, LONG, NO_SUB, ONCE, MULTIPLIED, CENTRE, TWO_SHORT, BYTES,
                                BYTES_TYPED, TWICE, SUB_MULTIPLIED),
                      "largest": (A_X,), "holds": (WIDTH, NO_SIGN, INT_NO_SIGN, GREATER, NMANT,
                                                      RANGE, NO_FLOAT),
                      "order": (SWAPPED,), "only": (ONLY_ABS, ONLY_REL)}, most=2)  # fmt: skip

#: The recipe and the worked counts, said once two different answers have failed.
HINTS = ((re.compile(r" \((recipe|worked): [^)]*\)"), ""),)


def draw(ax, case, got):
    """The student's two counts; the bits each type holds exactly once the words say them
    (the hints spent) or the answer passed (never the answer before)."""
    artists = []
    told = tries.hints_spent("edge_bits") or got == case[2]
    for t in TYPES if told else ():
        artists.append(ax.axhline(exact_bits(t), color="#888888", linestyle=":", linewidth=1))
        artists.append(ax.annotate(f"{t}: {exact_bits(t)} bits", (1.02, exact_bits(t)),
                                   xycoords=("axes fraction", "data"), va="center",
                                   fontsize="x-small"))  # fmt: skip
    if isinstance(got, tuple) and len(got) == 2:
        for k, (n, t) in enumerate(got):
            right = (n, t) == case[2][k]  # r409 F6: a right part is grey, a wrong one red
            # r419 F1: which of the two is wrong, as the words' "wrong:" list says it
            said = [f"{n} bits" + (" (wrong)" if n != case[2][k][0] and not right else ""),
                    f"{t}" + (" (wrong)" if t != case[2][k][1] and not right else "")]  # fmt: skip
            artists += ax.plot([k], [n], "x", color="#888888" if right else "#d7301f", ms=11,
                               mew=2)  # fmt: skip
            artists.append(
                ax.annotate(
                    f"yours: {chr(10).join(said)}{' (right)' if right else ''}",
                    (k, n),
                    xytext=(9, 0),
                    va="center",
                    textcoords="offset points",
                    fontsize="x-small",
                )
            )
    # r430 F6: the label on two lines ("yours: 32 bits (wrong)" over "int32 (wrong)"), so the
    # panel ends just past the relative form's label, no empty half
    ax.set_xlim(-0.45, 2.05)
    ax.set_xticks([0, 1], [f"{form} form" for form in FORMS])
    ax.set_ylabel("bits, sign included")
    counts = [n for n, _ in got] if isinstance(got, tuple) and len(got) == 2 else []
    ax.set_ylim(0, max([72, *(n + 8 for n in counts)]))
    return artists


#: The exercise, for the registry.
EDGE_BITS = Exercise(
    "edge_bits", cases, as_answer, _same, explain, _rule, (KNOBS, TYPES_ONLY), match=_match, draw=draw,
    hints=HINTS, answers=(PackageAnswer(range_budget, what="lesson 06's count itself"),
                          PackageAnswer(edge_bits_needed, what="lesson 06's count itself"),
                          # r441 S1: its sibling, which counts differences up to extent px
                          PackageAnswer(bit_budget, what="lesson 06's count itself")),
    reference=("teachraster.exercises.hard_case_precision",),
    # r409 F6: edge_bits has no pixels; one call counts bits of two numbers
    slow=" (one call counts the bits of two forms: it should take microseconds)",
)  # fmt: skip

# the stub's note says what this figure draws (never the answer)
NOTHING_DRAWN_FOR[EDGE_BITS.name] = (
    "Nothing drawn yet: once your function returns answers, the check draws its first failing "
    "case (or, when all pass, one of the cases): your two counts of bits, and the bits each type "
    "holds once the words have said them; never the rule's answer"
)
