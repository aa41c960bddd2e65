"""What an exercise is, for the checker: its cases, how an answer is read, and its mistakes.

Adding an exercise function is writing one :class:`Exercise`: cases with the package's answers,
a converter that reads the student's answer strictly, the rule in words with the case's numbers
(``explain``), and a table of typical :class:`Mistake` s, each a *wrong solution* the checker
runs itself (``gives``) with the words that name it. The checker never guesses a cause: it
names a mistake only where that mistake gives the student's very answer, and prefers the one
that gives it on every case (:mod:`.diagnosis`). A family of mistakes that can combine (a
bilinear filter sampling at texel corners *and* ignoring the wrap mode) is one function with
knobs (:class:`Knobs`); the checker tries them alone and in pairs. The registry in
:mod:`.checks` lists the exercises in course order.

>>> wrong = Mistake("doubled", "you doubled it", gives=lambda x: 2 * x)
>>> wrong.gives(3), wrong.say((3,), 3, 6)
(6, 'you doubled it')
"""

from __future__ import annotations

import dataclasses
import itertools
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np


@dataclass(frozen=True)
class Mistake:
    """A typical mistake: what it gives, and the words that name it.

    Attributes
    ----------
    kind : str
        A few words ("texel corners"): the report shows one failure of each kind first.
    words : str or callable
        Why the answer is wrong, in the rules' terms; ``words(args, expected, got)`` when the
        sentence quotes the case's numbers. It follows the case's numbers after ": " (or
        directly, when it starts with " (", ":", ";" or ".").
    gives : callable, optional
        ``gives(*args)``: the answer a student with this mistake returns (None: the mistake
        says nothing about this case).
    fits : callable, optional
        ``fits(args, expected, got) -> bool`` (None: it says nothing about this case) for a
        mistake no formula reproduces (float32 rounding, a symptom such as "keeps a vertex
        behind the plane").
    symptom : bool
        The words describe what is wrong, not why: named only when no cause fits.
    only_whole : bool
        Named only when it fits every answer of the check (float32 rounding: an answer off by
        more elsewhere has another cause).
    parts : tuple of Mistake
        For a combination of mistakes (:class:`Knobs`): the single mistakes it combines.
    must_fit : callable, optional
        ``must_fit(args, expected, got) -> bool``: the failing cases this mistake must give,
        every one of them, to be named at all (a tie rule: every failing case wrong only at
        centres on an edge; r84 10-2: a mirrored tie rule was named "E > 0" on one case and
        "E ≥ 0" on another, each right only there).
    parameter : callable, optional
        ``parameter(args, expected, got) -> float``: the one number a fitted mistake has on
        this case (an ε added to E, a constant factor); the mistake is named only where that
        number is the same on every failing case it fits (r164: an "ε" fitted case by case
        took a constant factor, whose ε grows with E, for a guard against dividing by 0).
    with_others : bool
        A second slip, named on the failing cases it fits only where every other failing case
        is named too (r248: float64 pixels at the far float64 ties, beside another slip of the
        same answer; a random answer's verdict there, with the rest unexplained, is no cause).
    reads : str, optional
        A name the student's code must read (a global or an attribute, such as ``det`` of
        ``np.linalg.det``) for the mistake to be named: two mistakes whose answers are the
        same on every case (r175 B5: ``det(M) == 0`` before a solve, and a solve whose
        LinAlgError is the test) are told apart by what the code reads
        (:func:`.package_answers.names_read`).
    unread : str, optional
        A parameter the student's function must never read for the mistake to be named
        (:func:`.package_answers.parameters_read`; r341 X-1: "wrap not passed on" was said of a
        trilinear that passes it on, to a bilinear that ignores it).
    consistent : bool
        Named on some failing cases only where it contradicts no passing answer: wherever it
        would change the answer and the student's is right, the student did not make it
        (r372 M4: an empty span matched a few cases of three wrong side tests by coincidence).
        A description (``fits``) with ``consistent`` is asked about the passing cases too
        (``got`` equal to ``expected`` there) and must not say False on any of them.
    """

    kind: str
    words: str | Callable[..., str]
    gives: Callable | None = None
    fits: Callable | None = None
    symptom: bool = False
    only_whole: bool = False
    parts: tuple = ()
    without: Callable | None = field(default=None, repr=False)  # (part) -> gives without it
    must_fit: Callable | None = field(default=None, repr=False)
    parameter: Callable | None = field(default=None, repr=False)
    reads: str | None = None
    with_others: bool = False
    unread: str | None = None
    consistent: bool = False

    def say(self, args, expected, got) -> str:
        return self.words(args, expected, got) if callable(self.words) else self.words


@dataclass(frozen=True)
class Slip:
    """One knob of a :class:`Knobs` family turned the wrong way: its value, kind and words."""

    kind: str
    words: str | Callable[..., str]
    value: Any
    reads: str | None = None  # as Mistake.reads and Mistake.unread
    unread: str | None = None


@dataclass(frozen=True)
class Knobs:
    """Mistakes that can combine: ``gives(*args, **settings)`` with some knobs turned.

    ``knobs`` maps each keyword of ``gives`` to the wrong settings it may take (its default is
    the right one); ``most`` is the most mistakes combined (1: alone only).
    """

    gives: Callable
    knobs: dict[str, Sequence[Slip]]
    most: int = 2

    def mistakes(self) -> list[Mistake]:
        """Every single slip, then every combination of up to ``most`` slips of different knobs."""
        singles = [(name, slip) for name, slips in self.knobs.items() for slip in slips]
        out = []
        for n in range(1, self.most + 1):
            for combo in itertools.combinations(singles, n):
                if len({name for name, _ in combo}) == n:
                    out.append(self._mistake(combo))
        return out

    def _mistake(self, combo) -> Mistake:
        settings = {name: slip.value for name, slip in combo}
        parts = tuple(Mistake(slip.kind, slip.words) for _, slip in combo)

        def gives(*args, settings=settings):
            return self.gives(*args, **settings)

        def without(part, combo=combo):
            rest = {name: slip.value for name, slip in combo if slip.kind != part.kind}
            return lambda *args: self.gives(*args, **rest)

        kind = " and ".join(p.kind for p in parts)
        reads = next((slip.reads for _, slip in combo if slip.reads), None)
        unread = next((slip.unread for _, slip in combo if slip.unread), None)
        if len(parts) == 1:
            return Mistake(kind, parts[0].words, gives, reads=reads, unread=unread)
        return Mistake(kind, "", gives, parts=parts, without=without, reads=reads, unread=unread)


@dataclass(frozen=True)
class PackageAnswer:
    """A package function that *is* an exercise's answer (``when(arguments)`` narrows it: the
    same ``tr.sample`` is bilinear's answer with ``filter="bilinear"`` only; ``words``: what
    the report says of its use, when it is not the package's public answer)."""

    function: Callable
    when: Callable[[dict], bool] | None = None
    what: str = "this very answer"  # what it computes, as the "not counted" note says
    words: str | None = None  # what the report says instead of "teachraster's <name>, which..."
    # modules whose every function, public too, is a part of this answer's computation,
    # watched as its own module's private helpers are (r13 09-1: line_rules.diamond)
    modules: tuple[str, ...] = ()
    # how the report names it, when its own name does not say (a lambda in a checker's table)
    label: str | None = None


@dataclass(frozen=True)
class Exercise:
    """How one exercise is checked (see the module docstring).

    Attributes
    ----------
    name : str
        The function's name, as the notebook defines it.
    cases : callable
        ``cases()`` -> list of (label, args, expected): the catalogue's hard cases, then seeded
        random ones.
    convert : callable
        Reads the answer strictly (raising :class:`~.running.WrongAnswerType`, whose message
        says what was returned and what is expected).
    same : callable
        ``same(got, expected, args)``: is the answer right?
    explain : callable
        ``explain(args, expected, got)``: the case's numbers, the rule's answer and the
        student's ("for a=(1, 2), ... E = 25; yours is -25").
    rule : callable
        ``rule(args, expected, got)``: how the answer is found, said when no mistake fits.
    mistakes : sequence of Mistake or Knobs
        The typical mistakes, most specific first.
    float32 : callable, optional
        ``float32(args)``: the magnitude whose float32 rounding bounds the error of a float32
        computation of this case (coordinates squared for an edge function far from the
        origin). float32 is named only for an answer within that rounding.
    float32_floor : float
        The least scale that rounding is taken of (1: numbers of order 1, coordinates; 0:
        the scale alone, for answers far below 1, reverse-Z's Δz of 1e-8, where a floor of 1
        called 6× errors float32's rounding: r325 C3).
    float32_words : callable, optional
        ``float32_words(args, expected, got)``: words for float32 on this case (None: the
        general words).
    float32_makes_inf : bool
        Can float32 turn this exercise's finite inputs into ±inf (a difference cancelled to 0,
        then divided by)? Then an unnamed inf is said with ``float32_words``.
    constant : callable, optional
        ``constant(value)``: the words for an answer that never changes, if not the default.
    nan_words : str, optional
        The words for a NaN answer where NaN is a legal answer (``decal_bias``: no offset
        fits), in place of "a 0/0" (r340).
    answers : sequence of PackageAnswer
        The package's functions that are this exercise's answer (their use is reported and not
        counted).
    draw : callable
        ``draw(ax, case, got)`` draws one case (matplotlib imported there only).
    scene : callable, optional
        ``scene(fn)`` -> a :class:`~.scenes.Scene`: the student's function in a whole picture.
    call : callable, optional
        ``call(fn, args)`` runs the student's function on a case and converts its answer, when
        that is more than ``convert(fn(*args))`` (``covers`` is called once per pixel).
    match : callable, optional
        ``match(got, answer, args)``: does the student's answer equal what a mistake gives?
        (default: numbers within 1e-6 relative, others equal; ``clip_near`` compares polygons
        up to their starting vertex).
    compose : callable, optional
        ``compose(head, words)``: the explanation from the case's numbers and the mistake's
        words (default: the numbers first, see :func:`.diagnosis.compose`).
    example : int
        The case drawn when every case passes (r9: the first, opaque red over blue, showed
        nothing a translucent blend does).
    partial_names : bool
        A mistake may be named on the failing cases it explains while others fail for another
        reason (default). False: named only where it gives every failing answer, for mistakes
        that differ on a few cases only (r9: ``line_pixels``' "(−ε, −ε)" shared one failing
        answer with "p1 tested before moving", and named it).
    private : sequence of (str, object, str)
        (name, value, words): the checker's private data (exercise 11's salted key); an
        answer whose code reads the value, a copy of it or one of its texts, under any name
        (or a helper of its own does), is reported with ``words`` and not counted, as a call
        into :attr:`answers` is.
    tries : int, optional
        Failing checks of this task in one kernel before each further check waits (exercise
        11, whose verdict a blind loop could query: :mod:`.tries`); None: no limit.
    free_causes : int
        Distinct wrong causes of this task in one kernel that cost no wait (with
        :attr:`tries`; :data:`.tries.FREE_CAUSES` by default, none on exercise 11's frames 7
        to 9: r21 D2).
    reference : sequence of str
        Further checker modules whose functions compute this exercise's expected answers
        (``covers``' :mod:`.coverage`), watched with the module of :attr:`cases`: a student's
        call into them does not count (r14 09-1, :mod:`.package_answers`).
    once : sequence of (str, str)
        (text, short): a long sentence that many explanations share, said in full by the
        first failing case (in case order) whose explanation holds it and as ``short`` by the
        rest (r23 D-6: ``line_pixels``' ~90-word tie rule stood on every line).
    hints : sequence of (str, str)
        (text, hint): words that give away what the task asks to work out (a formula), said
        as ``hint`` until two different answers of the student's have failed in a kernel,
        in full after (r39: the first wrong try printed ⌈x_l − ½⌉, λ_i / w_i, the inequality
        for n; r46: rerunning the same cell printed them); :mod:`.tries` counts the answers.
        ``text`` may be a compiled ``re`` pattern (``hint`` its replacement) where the telling
        words hold the case's numbers (a crossing's t).
    slow : str, optional
        What the time-out words ask in place of :data:`.running.PER_PIXEL` ("a Python call
        per pixel?"), for a function called once per point, which has no pixels (r175 B7:
        ``barycentric``); None: those words.
    call_words : callable, optional
        ``call_words(*args)``: the case's arguments as Python the student can paste to call
        the function again, said before a case that gave no answer (an exception, None, a
        wrong type), with the traceback's last line in the student's code for an exception
        (r248 S1: 8.2's lines for an exception, None or NaN quoted no argument); None: the
        case's label alone.
    raised_words : callable, optional
        ``raised_words(args, error) -> str``: words added to a case on which the function
        raised ``error`` (the report's "your function raised IndexError: ..."), naming the
        mistake that raises there, or "" (r317: 7.3's level q + 1 at λ = q was told the
        symptom only); None: the error alone.
    none_words : callable, optional
        ``none_words(args, expected) -> str``: the words of a case on which the function
        returned None, in place of "returned None (a missing `return`?)", or "" to keep them
        (r439 M4: ``span`` returning None for a line with no covered centre); None: those.
    inputs_drawn : bool
        ``draw(ax, case, None)`` shows the case's inputs only, no answer (r8: 09's blends and
        lines): the untouched stub's figure draws the first case so. False (default): the
        stub's figure draws nothing, since the drawing would show the answer (issue 30, r46).
    tool_note : callable, optional
        ``tool_note(fn) -> str | None``: a remark on a passing answer that uses one of the
        package's tools, which counts (r420 P1: ``covers`` calling the package's
        ``edge_function``, the warm-up the notebook asks the student to write).
    """

    name: str
    cases: Callable[[], list]
    convert: Callable
    same: Callable
    explain: Callable
    rule: Callable
    mistakes: Sequence = ()
    float32: Callable | None = None
    float32_words: Callable | None = None
    float32_makes_inf: bool = False
    float32_floor: float = 1.0
    constant: Callable | None = None
    nan_words: str | None = None
    constant_nan: Callable | None = None
    answers: Sequence[PackageAnswer] = ()
    draw: Callable | None = None
    scene: Callable | None = None
    call: Callable | None = None
    match: Callable | None = None
    compose: Callable | None = None
    partial_names: bool = True
    example: int = 0
    private: Sequence[tuple[str, object, str]] = ()
    tries: int | None = None
    free_causes: int = 2
    reference: Sequence[str] = ()
    once: Sequence[tuple[str, str]] = ()
    hints: Sequence[tuple[str, str]] = ()
    inputs_drawn: bool = False
    slow: str | None = None
    call_words: Callable | None = None
    raised_words: Callable | None = None
    none_words: Callable | None = None
    tool_note: Callable | None = None

    def all_mistakes(self) -> list[Mistake]:
        """The mistakes table with every :class:`Knobs` family expanded (the same mistakes on
        every call: :mod:`.diagnosis` remembers each one's answers by the mistake)."""
        expanded = self.__dict__.get("_expanded")
        if expanded is None:
            expanded = []
            for m in self.mistakes:
                expanded.extend(m.mistakes() if isinstance(m, Knobs) else [m])
            object.__setattr__(self, "_expanded", expanded)  # frozen: set once, on first use
        return list(expanded)


def variant_mistakes(variants: Callable, words: dict, symptoms: Sequence[Mistake] = ()) -> list:
    """A mistakes table from a function ``variants(*args) -> {kind: wrong answer}`` and the
    words of each kind, in ``words``' order (a variant missing from a case says nothing
    there), then ``symptoms``.

    >>> table = variant_mistakes(lambda x: {"doubled": 2 * x}, {"doubled": "you doubled it"})
    >>> table[0].kind, table[0].gives(3)
    ('doubled', 6)
    """

    # Each case's variants, computed once: every mistake of the table asks for the same case's,
    # and every check of the exercise runs the same cases (bounded: a few cases' arrays each).
    memo: dict = {}

    def of_case(args) -> dict:
        key = content_key(args)
        if key is None:  # a mip Pyramid (a list's subclass), a frozen dataclass: by case_key
            # (7.4's pixel_sample: each of its ~35 mistakes recomputed all ~35 variants)
            key = case_key(args)
            key = None if key is None else ("case", key)
        if key is None:
            return variants(*args)
        if key not in memo:
            if len(memo) >= 1024:  # (r439: span's 261 cases past 256 cleared it on every
                memo.clear()  # case, so each mistake recomputed every case's variants)
            memo[key] = variants(*args)
        return memo[key]

    def gives(kind):
        return lambda *args: of_case(args).get(kind)

    return [Mistake(kind, text, gives=gives(kind)) for kind, text in words.items()] + list(symptoms)


def content_key(value):
    """A hashable key equal for equal contents (arrays by dtype, shape and bytes), or None for
    a value it cannot read (then nothing is remembered).

    >>> content_key((np.arange(3), 2, "x")) == content_key((np.arange(3), 2, "x"))
    True
    >>> content_key(object()) is None
    True
    """
    if isinstance(value, np.ndarray):
        return ("array", value.dtype.str, value.shape, value.tobytes())
    if isinstance(value, (bool, int, float, str, type(None), np.generic)):
        return (type(value).__name__, value)
    if type(value) in (tuple, list):
        keys = tuple(content_key(v) for v in value)
        return None if None in keys else (type(value).__name__, keys)
    return None


def case_key(value):
    """:func:`content_key`, also of a frozen dataclass's fields (a coverage case) and of a
    list's subclass (a mip :class:`~.texture_filtering.Pyramid`), each with its type: a key
    of a case's arguments, equal only for arguments no mistake can tell apart.

    >>> from .cases import CoverageCase
    >>> a = CoverageCase("a", np.zeros((1, 3, 2)), (0, 0), (4, 4))
    >>> case_key((a,)) == case_key((CoverageCase("a", np.zeros((1, 3, 2)), (0, 0), (4, 4)),))
    True
    >>> case_key((a,)) == case_key((CoverageCase("a", np.ones((1, 3, 2)), (0, 0), (4, 4)),))
    False
    """
    if isinstance(value, (list, np.ndarray)) and type(value) not in (list, np.ndarray):
        if getattr(value, "__dict__", None) != {} or isinstance(value, np.ndarray):
            return None  # state beside the items (or slots, or an array subclass): unknown
    if isinstance(value, list) or type(value) is tuple:
        keys = tuple(case_key(v) for v in value)
        return None if None in keys else (type(value), keys)
    # by their bits: -0.0 is not 0.0 (1 / x tells them apart), and NaN is NaN
    if type(value) is float:
        return (float, np.float64(value).tobytes())
    if isinstance(value, np.inexact):
        return (type(value), value.tobytes())
    params = getattr(type(value), "__dataclass_params__", None)
    if params is not None and params.frozen and not isinstance(value, type):
        keys = tuple(case_key(getattr(value, f.name)) for f in dataclasses.fields(value))
        return None if None in keys else (type(value), keys)
    return content_key(value)


def copies(args) -> tuple:
    """Fresh copies of a case's arguments (a student may write into them), lists included."""
    return tuple(_copy(a) for a in args)


def _copy(value):
    if isinstance(value, np.ndarray):
        return value.copy()
    if isinstance(value, list):
        return type(value)(_copy(v) for v in value)  # a Pyramid stays a Pyramid
    return value
