"""Why one pixel of the student's capstone frame differs: the stage where the histories part.

Both frames are traced, so ``frame.history(row, col)`` tells each pixel's story in
submission order (:mod:`teachraster.pipeline.debugging.frame_history`). The records are
walked side by side; the first pair that disagrees names the stage:

- one covers the centre and the other does not: **coverage** (the student's ``covers`` is
  asked again, and the top-left rule says why the package decides otherwise);
- both cover it but one passes the depth test: the **depth test** (the pixel's fragments,
  their depths and depth writes, the student's ``depth_passes`` against the package's);
- both pass with other values: **interpolation** (``barycentric``, then
  ``perspective_weights``, against the package's weights at that centre);
- the same fragment leaves other colours behind: **blending** (``over``).

Where the function's own exercise (or, for the depth test, exercise 4's table) recognises a
typical mistake in it, the explanation names that mistake too (:func:`named_mistake`: the
exercise's check, run once per function, over all its cases).

When every record agrees, the difference lies after the pipeline: **texture filtering**
(``bilinear``, ``trilinear``), the MSAA **resolve** or the A-buffer's **sorting** (its
**A-buffer resolve** where a pixel has one fragment, or the background is forgotten)
(``a_buffer``, :mod:`.capstone_glass`). The student's functions are called
again only through :func:`.running.run_checker` (a strange answer costs a plain sentence).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from ..core.barycentrics import barycentric
from ..core.blend_factors import linear_to_srgb, srgb_to_linear
from ..core.interpolation import convex_weights, weights_per_row
from ..core.snapping import snap
from ..pipeline.texturing.mip_pyramid import mipmap
from ..pipeline.texturing.texture import sample
from ..pipeline.texturing.texture_filters import mip_level
from ..pipeline.visibility.zbuffer import passed_on_arrival
from . import capstone_glass as glass
from . import capstone_samples as samples
from . import capstone_texels as texels
from .capstone_reports import own_report
from .capstone_scenes import capstone_scene
from .coverage import explain_pixel as explain_coverage
from .coverage_checks import AT_VERTICES, ON_BOX_SIDE
from .diagnosis import honest_on
from .exercise import Knobs
from .interpolation import rounded_decimals, rounded_words
from .running import WrongAnswerType, last_line, run_checker
from .scalars import vec
from .zbuffer_pixel import DEPTH_MISTAKES, as_passes, depth_cases

#: Capstone functions whose exercise's table of mistakes can name what is wrong with them.
CHECKED_BY = ("covers", "barycentric", "perspective_weights", "depth_passes", "over",
              "bilinear", "trilinear", "resolve")  # fmt: skip

#: The exercise whose check names a capstone function's mistakes, where it is not its own
#: name (the capstone's glass is premultiplied).
CHECKED_AS = {"over": "over_premultiplied"}


def check_words(checked: str, what: str = "check", short: bool = False) -> str:
    """How a report names check ``checked``'s ``what`` ("check" or "own cases"): "the
    depth_passes exercise's check". r222 item 3: no notebook holds an exercise named
    over_premultiplied; the student writes ``over`` in 12.5 from lesson 12b §4's rule, so its
    check is named by that function and that lesson (``short``: without the lesson, for a
    failure's label, which its sentence follows)."""
    if checked == CHECKED_AS["over"]:
        if short:
            return f"over's {what}"
        runs = "runs it" if what == "check" else "runs them"
        return (f"over's {what} (lesson 12b §4's premultiplied over: "
                f'ex.check("{checked}", over) {runs})')  # fmt: skip
    if checked in NO_EXERCISE:  # r510 MN1: checks that no exercise notebook runs any more
        if short:
            return f"{checked}'s {what}"
        call = f'ex.check("{checked}", {checked})'
        if what == "check":
            return f"the {checked} check ({call} runs it)"
        return f"the {checked} check's {what} ({call} runs them)"
    return f"the {checked} exercise's {what}"


#: Checks the capstone calls whose task no exercise notebook asks for any more (6.2 is
#: ``resolve_fragments`` since r490, 7.2 ``texel_weights`` with 7.3's filters given since
#: r491): a report calls them by their call, not by an exercise the student never met.
NO_EXERCISE = ("resolve", "bilinear", "trilinear")


#: The capstone's tolerance (some 17 of float32's half-ulps at 1: a float32 computation's
#: roundings pass), as :mod:`.capstone_render` compares (its ``TOL``).
TOL = 1e-6

#: Outcomes that mean "the centre was covered" (Hi-Z rejects covered fragments).
COVERED = ("hi_z", "failed_depth", "passed")


def explain_pixel(spec, used, mine, reference, pixel) -> tuple[str, str]:
    """(stage, explanation) of why ``pixel`` of ``mine`` differs from ``reference``."""
    row, col = pixel
    if spec.sample_covers:
        said = samples.explain(lambda xy, p: _call(used, "covers", xy, p),
                               lambda where, centre: covers_words(used, where, centre),
                               mine, reference, row, col)  # fmt: skip
        return (
            ("sample coverage", said)
            if said is not None
            else _shading(spec, used, reference, pixel)
        )
    if spec.uses != ("resolve",):
        ours = {(r.piece, r.sample): r for r in reference.history(row, col).records}
        for rm in mine.history(row, col).records:
            rr = ours.get((rm.piece, rm.sample))
            if rr is None:
                continue
            said = _record_difference(used, reference, pixel, rm, rr)
            if said is not None:
                return said
    return _shading(spec, used, reference, pixel)


def _record_difference(used, reference, pixel, rm, rr):
    covered_m, covered_r = rm.outcome in COVERED, rr.outcome in COVERED
    if covered_m != covered_r:
        return "coverage", _coverage(used, reference, pixel, rr, covered_r)
    if (rm.outcome == "passed") != (rr.outcome == "passed"):
        return "depth test", _depth(used, reference, pixel)
    if rm.value and rr.value and not np.allclose(rm.value, rr.value, rtol=TOL, atol=TOL):
        return "interpolation", _interpolation(used, reference, pixel, rr)
    if rm.color_after and not np.allclose(rm.color_after, rr.color_after, rtol=TOL, atol=TOL):
        return "blending", _blending(used, pixel, rr)
    return None


def named_mistake(used, name, where: str = "", case: tuple | None = None,
                  also: tuple = ()) -> str:  # fmt: skip
    """ ": <words>" of the typical mistake exercise ``name``'s own check finds in the student's
    function (over all its cases, :mod:`.diagnosis`), or "" when it names none. ``where``:
    where the point shown lies in its triangle (:func:`.capstone_samples.point_place`); a mistake that cannot
    change a point there is not named (r49: no winding swap and E > 0 was blamed on the tie
    rule at a centre strictly inside; r449 MN1/MN2: "a special case for vertices" at a point
    that is no vertex); another is named first.
    ``case``: the pixel's (args, the package's answer, the student's), on which words that
    blame float32 must hold too (:func:`.diagnosis.honest_on`, the checker's one rule).
    ``also``: further (args, the package's answer) of the scene; with them the mistake named
    must give the student's answer at the pixel and on each of them, and is said with the
    pixel's numbers (:func:`_exact_words`)."""
    fn = used.get(name)
    if name not in CHECKED_BY or fn is None:
        return ""
    try:
        words = _mistake_words(name, fn, where)
    except TypeError:  # an unhashable callable: no cache, no name
        return ""
    checked = CHECKED_AS.get(name, name)
    # where the function raised at the pixel (no answer), there is nothing to reproduce
    # r481: a perspective_weights mistake is said at a pixel only where it gives the pixel's
    # answer (w rounded to integers was told exercise 3.2's `np.divide(..., where=)` NaN)
    exact = also or name == "perspective_weights"
    if exact and case is not None and case[2] is not None and words.startswith(_head(checked)):
        words = run_checker(lambda: _exact_words(used, name, case, also), "")
    words = _staged(checked, words)
    if case is not None and words:
        from .checks import exercise

        words = run_checker(lambda: honest_on(exercise(checked), *case, words), words)
    return words


def _head(checked: str) -> str:
    return f"; {check_words(checked)} names the mistake: "


def _exact_words(used, name, case: tuple, also) -> str:
    """The words of a mistake of the exercise's table, of a kind its check names in the
    student's function, that gives the student's answer at the pixel (``case``) and at every
    point of ``also``, said with the pixel's numbers; else that none does. r219: one point
    may not tell two mistakes apart (the weights along x or along both axes swapped, one
    texel or another): a mistake is named only where it gives every answer tried, as
    :data:`.hiz_tile.EXACT` asks, and one the check names on its own cases is not said of a
    pixel it does not explain."""
    from .checks import exercise
    from .diagnosis import gives_every_answer, named_on

    checked = CHECKED_AS.get(name, name)
    spec = exercise(checked)
    kinds = _kinds_named(checked, used[name])
    cases = [case]
    for args, expected in also:
        yours, error = _call(used, name, *args)
        if not error:  # a point where the function raised tells nothing of a mistake
            cases.append((args, expected, yours))
    for m in _candidates(spec, kinds):
        if gives_every_answer(spec, m, cases):
            return _head(checked) + named_on(spec, m, *case).lstrip(" .:;")
    where = f"your answers here and at the {len(cases) - 1} other points of the scene tried"
    return (f"; {check_words(checked)} names {_kinds_words(kinds)} on its own cases, "
            f"but no such mistake gives {where if also else 'your answer here'}: compare "
            "your answer here with the rule")  # fmt: skip


def _kinds_named(checked: str, fn) -> list:
    """The kinds of the typical mistakes exercise ``checked``'s check names in ``fn``, in
    the order its failures name them (a combination by its parts)."""
    from .checks import exercise

    table = _words_by_kind(exercise(checked).mistakes)
    out = []
    for failure in counted_failures(checked, own_report(checked, fn)):
        for kind in _table_parts(failure.kind, table):
            if kind not in out:
                out.append(kind)
    return out


def _table_parts(kind: str, table: dict) -> list:
    """A failure's kind as kinds of ``table``: itself, or the parts of a combination ([]
    when it is none of the table's, such as "value" or "raised")."""
    parts = [kind] if kind in table else kind.split(" and ")
    return parts if all(part in table for part in parts) else []


def _candidates(spec, kinds: list) -> list:
    """The mistakes of ``spec``'s table (its combinations too) made of ``kinds`` only, single
    ones first, each in the table's order (as the check prefers them)."""
    chosen = set(kinds)
    fit = [m for m in spec.all_mistakes()
           if {p.kind for p in m.parts or (m,)} <= chosen]  # fmt: skip
    return sorted(fit, key=lambda m: len(m.parts))


def _kinds_words(kinds: list) -> str:
    quoted = [f"'{kind}'" for kind in kinds]
    return quoted[0] if len(quoted) == 1 else ", ".join(quoted[:-1]) + " and " + quoted[-1]


def _staged(checked: str, words: str) -> str:
    """The exercise's words in the mode its own check is in (r107 N12-1: the capstone gave
    the area ratio, λ_i / w_i, on the first wrong try): hints until two different answers of
    the task have failed in this kernel, here or in the exercise (the check that named the
    mistake, :func:`own_report`, counted this one), and "a hint only" said as the exercise
    says it."""
    from .checks import exercise
    from .tries import HINT_ONLY, staged

    said, hinted = staged(checked, words, exercise(checked).hints)
    if not hinted:
        return said
    said = said.replace(" names the mistake: ", " gives a hint: ", 1)
    return f"{said}; {HINT_ONLY}"


@lru_cache(maxsize=32)
def _mistake_words(name, fn, where: str = "") -> str:
    from .checks import exercise

    checked = CHECKED_AS.get(name, name)
    table = _words_by_kind(exercise(checked).mistakes)
    report = own_report(checked, fn)
    head = _head(checked)
    dropped = []
    for failure in counted_failures(checked, report):
        parts = _table_parts(failure.kind, table)
        kept = [kind for kind in parts if _changes(kind, table[kind], where)]
        dropped += [kind for kind in parts if kind not in kept and kind not in dropped]
        if not kept:
            continue
        words = [table[kind] for kind in kept]  # r449: the parts that can change this point
        if all(isinstance(w, str) for w in words):
            return head + "; and ".join(words)
        if len(kept) < len(parts):  # the case's sentence would say the other parts too
            continue
        # words that quote the case: the case's sentence, said to be the exercise's case (its
        # numbers are not this pixel's)
        return f"{head}in its own case {failure.case}, {failure.explanation}"
    if dropped and where in PLACES:
        return _not_here(checked, dropped, where)
    return _unnamed(checked, report)


#: How :func:`point_place`'s answers are said (r449 MN1/MN2).
PLACES = {
    "inside": "strictly inside its triangle, on no edge",
    "outside": "strictly outside an edge of its triangle",
    "edge": "on an edge but at no vertex of its triangle",
}


def _changes(kind: str, words, where: str) -> bool:
    """Whether typical mistake ``kind`` (its ``words``) of ``covers`` can change the answer at
    a point ``where`` (:func:`.capstone_samples.point_place`; "" when unknown): a tie rule's
    and a bounding-box test's with <= only on an edge or at a vertex, a special case for
    vertices only at a vertex."""
    if where in ("inside", "outside") and (_about_ties(kind) or words == ON_BOX_SIDE):
        return False  # a box test with <= refuses only centres on a left or top edge (r438 H3)
    return not (words == AT_VERTICES and where not in ("", "vertex"))


def _not_here(checked: str, dropped: list, where: str) -> str:
    """r449 MN1/MN2: the check's own cases show ``dropped`` mistakes, none of which can change
    a point ``where``: said as the check's finding there, and this point left to the rule."""
    return (f"; {check_words(checked)} names {_kinds_words(dropped)} on its own cases, but "
            f"this point lies {PLACES[where]}, where that cannot change the answer: the "
            "mistake here is another one (vertices or p moved, or another test?): compare "
            "your answer here with the rule")  # fmt: skip


def _about_ties(kind: str) -> bool:
    """Whether typical mistake ``kind`` of ``covers`` is about centres on edges (a tie rule)."""
    return kind.endswith(" rule") or kind.endswith("owns its centres")


def _unnamed(checked: str, report) -> str:
    """What the exercise's check says when no typical mistake of its table fits: its first
    explanation (the rule in words with the case's numbers, or its constant-answer or float32
    diagnosis), or, when the function passes there, that the scene asks what the cases do not."""
    failures = counted_failures(checked, report)
    if report.passed or (report.failures and not failures):
        return (f"; your function passes {check_words(checked, 'own cases')}"
                f"{_ON_A_GPU if report.failures else ''}, so the scene asks it something they "
                "do not: compare its answer here with the rule")  # fmt: skip
    if report.stopped is not None or not failures:
        return ""
    return f"; {check_words(checked)}, on its own cases, says: {failures[0].explanation}"


_ON_A_GPU = " that a GPU meets (those with w beyond float32's range do not count here)"


def counted_failures(checked: str, report) -> list:
    """``report``'s failures that a scene may explain a pixel by: r481 MN1, a perspective
    slip at large w was told the overflow of exercise 3.2's w = 1e-310 case, which the plain
    λ/w fails too and the scene does not count (:func:`.perspective_weighting.beyond_a_gpu`)."""
    if checked != "perspective_weights":
        return list(report.failures)
    from .perspective_weighting import beyond_a_gpu

    return [f for f in report.failures if not beyond_a_gpu(f.case)]


def _words_by_kind(mistakes) -> dict:
    """Each single typical mistake's words (a table's combinations are named by their parts)."""
    out = {}
    for m in mistakes:
        knobs = isinstance(m, Knobs)
        for single in m.mistakes() if knobs else [m]:
            if single.parts or not single.words:
                continue
            words = single.words
            words = words.lstrip(" .:;") if isinstance(words, str) else words
            # r174 12-5: one kind, several words (weights swapped along x, y or both): the
            # table cannot tell which; the case's own explanation does (a non-str entry)
            same = not knobs or out.get(single.kind, words) == words
            out[single.kind] = words if same else (words,)
    return out


def _call(used, name, *args):
    """The student's ``name`` on copies of ``args``: (value, "") or (None, why not)."""
    fn = used.get(name)
    if fn is None:
        return None, ""

    def body():
        try:
            return fn(*(a.copy() if isinstance(a, np.ndarray) else a for a in args)), ""
        except Exception as exc:  # noqa: BLE001 - a student's bug is reported, not raised
            return None, f"your {name} raised {last_line(exc)} here"

    return run_checker(body, (None, f"your {name} did not answer here in time"))


def _coverage(used, reference, pixel, rr, covered) -> str:
    row, col = pixel
    xy = snap(reference.trace.window[rr.piece, :, :2])
    p = np.array([col + 0.5, row + 0.5])
    yours, error = _call(used, "covers", xy, p)
    asked = f"covers({_points(xy)}, {vec(p)})"
    said = error or f"your {asked} returned {yours!r}"
    why, _, _ = explain_coverage(xy, p, covered)
    named = covers_words(used, samples.point_place(xy, p))
    # r114 D12-2: the edge's kind (exercise 1's question) was given on the first try: the
    # sentence in the mode covers' own check is in, as the quoted exercise words are
    why = _covers_staged(why)
    return f"triangle {rr.triangle}: {said}; the package: {why}{named}"


def covers_words(used, where: str, centre: str = "") -> str:
    """The words for the student's covers mistake, in one order for every scene (r273 12-1):
    what its own check finds (a constant answer, one winding, ...) first; ``centre``, the
    words of a covers that tests the pixel's centre, only where that check finds nothing
    and the MSAA scene offers them (its answers match the centre's on every differing
    sample)."""
    named = named_mistake(used, "covers", where=where)
    if centre and (
        not named
        or named.startswith(f"; your function passes {check_words('covers', 'own cases')}")
    ):
        return centre
    return named


def _covers_staged(words: str) -> str:
    """``words`` with covers' hints in place until two different answers of it have failed."""
    from .checks import exercise
    from .tries import staged

    return staged("covers", words, exercise("covers").hints)[0]


def _points(xy) -> str:
    return "[" + ", ".join(vec(v) for v in xy) + "]"


def _depth(used, reference, pixel) -> str:
    row, col = pixel
    records = [r for r in reference.history(row, col).records if r.outcome in COVERED]
    depths = np.array([r.depth for r in records])
    writes = np.array([r.depth_write for r in records])
    expected = passed_on_arrival(np.zeros(len(depths), np.int64), depths, writes)
    yours, error = _call(used, "depth_passes", depths, writes)
    said = error or f"your depth_passes returned {_bools(yours)}"
    why = _depth_mistake(used, depths, writes, yours, expected) or (
        "" if error else named_mistake(used, "depth_passes")
    )
    from .tries import hints_spent

    # r174 12-4: the rule is the repair of a tie mistake: said once the hints are spent
    rule = ("strictly nearer than the depth last written" if hints_spent("depth_passes")
            else "exercise 4's rule")  # fmt: skip
    return (f"the fragments of triangles {[r.triangle for r in records]} reach it in drawing "
            f"order with depths {vec(depths)} and depth writes {_bools(writes)}: {said}, the "
            f"package's test passes {_bools(expected)} ({rule}){why}")  # fmt: skip


def _depth_mistake(used, depths, writes, yours, expected) -> str:
    """Exercise 4's name for the mistake that gives ``yours`` here and the student's answers
    to exercise 4's named sequences (or nothing when none, or several, fit)."""
    try:
        got = as_passes(yours)
    except WrongAnswerType:
        return ""
    if got.shape != expected.shape or np.array_equal(got, expected):
        return ""
    here = [m for m in DEPTH_MISTAKES if np.array_equal(m.gives(depths, writes), got)]
    # r199 12-4: one mistake that fits this pixel alone may fit by chance (three fragments,
    # a few verdicts: "first only" gave ">"'s answer), so it too must fit exercise 4's named
    # sequences, or be one its own check finds
    fits = run_checker(lambda: _fit_everywhere(used["depth_passes"], here), here) if here else []
    if here and not fits:  # r94 D12-1: two mistakes in one function: the one its check finds
        fits = run_checker(lambda: _found_by_own_check(used["depth_passes"], here), [])
    if len(fits) != 1 or not isinstance(fits[0].words, str):
        return ""
    # staged as exercise 4's check stages it (r174 12-4), which counts this answer first
    run_checker(lambda: own_report("depth_passes", used["depth_passes"]), None)
    return _staged("depth_passes", f": {fits[0].words}")


def _found_by_own_check(fn, mistakes) -> list:
    """The ``mistakes`` that exercise 4's own check names in ``fn`` (on some of its cases):
    with two mistakes in one function none gives every answer, and the pixel's answer may fit
    one of them and another the function does not make (r94 D12-1: ``<=`` with glass writing
    depth, at a tie, was quoted the glass's words, the exercise's first)."""
    report = own_report("depth_passes", fn)
    kinds = {k for f in report.failures for k in f.kind.split(" and ")}
    return [m for m in mistakes if m.kind in kinds]


def _fit_everywhere(fn, mistakes) -> list:
    """The ``mistakes`` that give what ``fn`` gives on every named sequence of exercise 4."""
    cases = [args for label, args, _ in depth_cases() if not label.startswith("random")]
    answers = [as_passes(fn(d.copy(), w.copy())) for d, w in cases]
    return [m for m in mistakes
            if all(np.array_equal(m.gives(d, w), a) for (d, w), a in zip(cases, answers))]  # fmt: skip


def _bools(values) -> str:
    try:
        return "[" + ", ".join("True" if bool(v) else "False" for v in values) + "]"
    except TypeError:
        return repr(values)


def _interpolation(used, reference, pixel, rr) -> str:
    row, col = pixel
    debug = reference.trace.debug
    xy = debug.fragments.vertices[rr.piece]
    w = debug.clipped.clip[rr.piece, :, 3]
    p = np.array([col + 0.5, row + 0.5])
    ours = convex_weights(barycentric(xy, p[None]))[0]
    head = f"triangle {rr.triangle} at {vec(p)}, vertices {_points(xy)}"
    if "barycentric" in used:
        yours, error = _call(used, "barycentric", xy, p)
        if error or yours is None or not np.allclose(yours, ours, rtol=TOL, atol=TOL):
            said = error or f"your barycentric returned {vec(yours, ours)}"
            why = "" if error else _weights_why(used, yours, ours, (xy, p))
            return f"{head}: {said}; the package's weights are {vec(ours, yours)}{why}"
    mu = ours if np.all(w == w[0]) else weights_per_row(ours[None], w[None])[0]
    yours, error = _call(used, "perspective_weights", ours, w)
    said = error or f"your perspective_weights(λ, w) returned {vec(yours, mu)}"
    named = named_mistake(used, "perspective_weights", case=((ours, w), mu, yours))
    if not error and " names the mistake: " not in named and " gives a hint: " not in named:
        named = _divided_by(ours, w, yours) + named
    return (f"{head}: λ = {vec(ours)} and w = {vec(w)}; {said}, the package's are "
            f"{vec(mu, yours)}{named}")  # fmt: skip


def _divided_by(lam, w, yours) -> str:
    """r481 MN1: what the student's weights at a pixel divided λ by, where the own check names
    no mistake: read back as λ_i / w'_i normalised, the w' in their ratios beside the pixel's
    w (a w capped, squared or changed for far w only, which the own cases may not show),
    or "" where the weights are no such quotient or the ratios agree within 1e-3."""
    lam, w = np.asarray(lam, dtype=float), np.asarray(w, dtype=float)
    try:
        got = np.asarray(yours, dtype=float).reshape(3)
    except (TypeError, ValueError):
        return ""
    if not (np.all(lam > 0) and np.all(got > 0) and np.all(np.isfinite(got))):
        return ""
    if abs(float(got.sum()) - 1) > 1e-6:
        return ""
    near = int(np.argmin(w))
    theirs, pixel = (lam / got) / (lam[near] / got[near]), w / w[near]
    if np.allclose(theirs, pixel, rtol=1e-3):
        return ""
    far = pixel > 1 + 1e-9
    power = np.log(theirs[far]) / np.log(pixel[far]) if far.any() else np.array([np.nan])
    which = {2: "the squares of this pixel's w (λ_i / w_i², not λ_i / w_i)",
             0.5: "the square roots of this pixel's w"}  # fmt: skip
    how = next((words for k, words in which.items() if np.allclose(power, k, rtol=1e-3)),
               "other w than this pixel's: is a w changed before the divide (capped, rounded, "
               "or another for far w only)?")  # fmt: skip
    return (f"; your weights are λ_i / w'_i normalised, with w' in the ratios "
            f"{_ratios(theirs)} where this pixel's w are in the ratios {_ratios(pixel)}: you "
            f"divided by {how}")  # fmt: skip


def _ratios(values: np.ndarray) -> str:
    return "(" + " : ".join(f"{float(v):.4g}" for v in values) + ")"


#: The words of exercise 3.1's mistake "epsilon added to the area" (a common rescale).
_ADDED_TO_AREA = "added a small number"


def _weights_why(used, yours, ours, case: tuple) -> str:
    """What is wrong with the student's weights ``yours`` at this pixel: rounded to a few
    decimals where they are, else the mistake exercise 3.1's check names, but a rescale (a
    number added to E(v1, v2, v3)) only where this pixel's weights are one common multiple of
    the package's (r148 D12-2: weights rounded to 5 decimals were told "you added a small
    number to E", fitted on a case whose three weights are equal), else their difference.
    ``case``: the pixel's (xy, p), on which float32 is named only within its rounding."""
    case = (case, ours, yours)
    try:
        got = np.asarray(yours, dtype=float).reshape(3)
    except (TypeError, ValueError):
        return named_mistake(used, "barycentric")
    if not np.isfinite(got).all():
        return named_mistake(used, "barycentric")
    if rounded_decimals(got, ours) is not None:
        return rounded_words(got, ours)
    off = float(np.max(np.abs(got - ours)))
    named = named_mistake(used, "barycentric", case=case)
    if _ADDED_TO_AREA in named and not _one_scale(got, ours):
        return (f"; your weights are off by up to {off:.1e}, more than float64's rounding "
                "(about 1e-16), and not by one common factor (a number added to E(v1, v2, v3) "
                "would scale all three alike): compare each with E of its edge over "
                "E(v1, v2, v3)")  # fmt: skip
    return named


def _one_scale(got: np.ndarray, ours: np.ndarray) -> bool:
    """Whether ``got`` is one common multiple of ``ours`` (within float64's rounding)."""
    scale = float(np.sum(got)) / float(np.sum(ours))
    return bool(np.allclose(got, scale * ours, rtol=1e-9, atol=1e-12))


def _blending(used, pixel, rr) -> str:
    src, dst = np.array(rr.color), np.array(rr.color_before)
    yours, error = _call(used, "over", src, dst)
    said = error or f"your over(src, dst) returned {vec(yours, rr.color_after)}"
    return (f"triangle {rr.triangle}'s fragment src = {vec(src)} lands on dst = {vec(dst)}: "
            f"{said}, the package's blend gives {vec(rr.color_after, yours)}"
            f"{named_mistake(used, 'over', case=((src, dst), rr.color_after, yours))}")  # fmt: skip


def _shading(spec, used, reference, pixel) -> tuple[str, str]:
    """Every record agrees: the texture filter or the resolve after the pipeline differs."""
    row, col = pixel
    if "a_buffer" in used:
        text = glass.explain(used["a_buffer"], reference, row, col)
        # r84 12-3: one fragment has nothing to sort; a missing background is no order either
        alone = len(glass.fragments(reference, row, col)[0]) <= 1
        return ("A-buffer resolve" if alone or glass.NO_BACKGROUND in text else "sorting"), text
    if "bilinear" in used or "trilinear" in used:
        return "texture filtering", _texture(spec, used, reference, row, col)
    if "resolve" in used:
        return "resolve", _resolve(used, reference, row, col)
    return "frame", "your frame differs here, yet every record of the pixel's history agrees"


def _texture(spec, used, reference, row, col) -> str:
    tex = capstone_scene(spec.scene, spec.tiled, spec.tinted).texture
    uv = reference.attr("uv")[row, col]
    head = f"every record of its history agrees; at uv = {vec(uv)}"
    name = "bilinear" if "bilinear" in used else "trilinear"
    behind = texels.texel_source(used[name])  # r502: 12.7's given filter on texel_weights
    if name == "bilinear":
        args = (tex, uv, "repeat")
        ours, asked = sample(tex, uv[None], "bilinear")[0], "bilinear(texture, uv, 'repeat')"
    else:
        uvs = reference.layout["uv"]
        lod = float(mip_level(reference.ddx[row, col, uvs], reference.ddy[row, col, uvs],
                              tex.shape))  # fmt: skip
        args = (mipmap(tex), uv, lod, "repeat")
        ours, asked = reference.image[row, col], f"trilinear(pyramid, uv, {lod:.4g}, 'repeat')"
    yours, error = _call(used, name, *args)
    if behind is None:
        said = error or f"your {asked} returned {vec(yours, ours)}"
        also = _scene_points(reference, tex) if name == "bilinear" else ()
        named = named_mistake(used, name, case=(args, ours, yours), also=also)
    else:
        who = f"12.7's {name}, adding up your texel_weights,"
        said = error.replace(f"your {name}", who, 1) or (
            f"12.7's {asked}, adding up your texel_weights, returned {vec(yours, ours)}")  # fmt: skip
        named = _texel_words(behind, name, args)
    return f"{head} {said}, the package's {name} filter gives {vec(ours, yours)}{named}"


def _texel_words(texel_weights, name: str, args: tuple) -> str:
    """What exercise 7.2's check says of the ``texel_weights`` behind 12.7's ``name``; where
    it passes, what the texels are at this pixel (``args``: the filter's), and only where
    they are right there, that the given cell was changed (r510)."""
    said = run_checker(lambda: texels.blame(texel_weights), "")
    if said:
        return said
    pyramid = [args[0]] if name == "bilinear" else args[0]
    sizes = [tuple(np.shape(level)[:2]) for level in pyramid]
    lod, wrap = (0.0, args[2]) if name == "bilinear" else (args[2], args[3])
    here = run_checker(lambda: texels.at_pixel(texel_weights, sizes, args[1], lod, wrap), "")
    return here or texels.changed_cell(name)


#: Covered pixels of the scene, spread over the frame, at which a named filter mistake must
#: give the student's answers too (r219; each costs one call of the function).
POINTS = 8


def _scene_points(reference, tex) -> tuple:
    """(args, the package's bilinear answer) at :data:`POINTS` covered pixels spread over
    the frame, in reading order: the scene's own points, right and wrong ones."""
    uv = reference.attr("uv").reshape(-1, 2)
    covered = np.flatnonzero(np.isfinite(uv).all(axis=1))
    if not len(covered):
        return ()
    picks = covered[np.unique(np.linspace(0, len(covered) - 1, POINTS).round().astype(int))]
    return tuple(((tex, uv[k].copy(), "repeat"), sample(tex, uv[k][None], "bilinear")[0])
                 for k in picks)  # fmt: skip


def _resolve(used, reference, row, col) -> str:
    colours = reference.sample_attrs[row, col]
    ids = reference.sample_triangle_id[row, col]
    ours = reference.image[row, col]
    yours, error = _call(used, "resolve", colours, ids, np.ones(3))
    said = error or f"your resolve returned {vec(yours, ours)}"
    why = _srgb_average(colours, ids, np.ones(3), yours, ours) if not error else None
    why = why or run_checker(lambda: samples.ids_as_rows(used, "resolve"), "")  # r504 RAW1
    why = why or run_checker(lambda: samples.nan_weighed(used, "resolve"), "")  # r510 WF1
    if not why:  # r510 HN3: a named mistake first, then one colour for many samples
        why = named_mistake(used, "resolve", case=((colours, ids, np.ones(3)), ours, yours))
        if " names the mistake: " not in why:
            why = run_checker(lambda: samples.resolve_slip(used, "resolve"), "") or why
    return (f"its samples show triangles {ids.tolist()} with colours "
            f"{', '.join(vec(c) for c in colours)} (NaN: uncovered; the background is white): "
            f"{said}, the package's resolve gives {vec(ours, yours)}{why}")  # fmt: skip


def _srgb_average(colours, ids, background, yours, ours) -> str | None:
    """ "; words" when ``yours`` averages in the wrong space, or None: the samples averaged as
    sRGB-encoded numbers (float, or 8-bit codes) and decoded again (r148 D12-3), or, the other
    way, decoded as if encoded, averaged and encoded again: lesson 08's sRGB resolve (the old
    exercise 6.3's ``resolve_srgb``), which lesson 08 recommends for encoded samples (r174
    12-1). Either was asked about its uncovered samples, which it handled right."""
    try:
        got = np.asarray(yours, dtype=float).reshape(3)
    except (TypeError, ValueError):
        return None
    linear = np.where(np.asarray(ids)[:, None] >= 0, np.asarray(colours, dtype=float),
                      np.asarray(background, dtype=float))  # fmt: skip
    if np.allclose(got, ours, rtol=TOL, atol=TOL):
        return None
    if _as_encoded(linear, got, ours):
        return ("; you averaged as lesson 08's sRGB resolve does: your answer is the "
                "samples decoded from sRGB, averaged and encoded again "
                f"{vec(linear_to_srgb(srgb_to_linear(linear).mean(axis=0)))}, where the resolve "
                f"is their plain mean {vec(ours)}: these samples are light already (the "
                "pipeline's float colours, not an 8-bit sRGB buffer's), so the plain mean (as in "
                "exercise 6.2) is the one wanted here; decoding is for samples stored encoded")  # fmt: skip
    encoded = linear_to_srgb(np.clip(linear, 0.0, 1.0))
    as_float = srgb_to_linear(encoded.mean(axis=0))
    as_codes = srgb_to_linear(np.round(encoded * 255).mean(axis=0) / 255)
    if np.allclose(as_float, ours, atol=1e-3):
        return None  # here the two averages agree: nothing to tell apart
    fits = np.allclose(got, as_float, rtol=1e-5, atol=1e-5) or np.allclose(got, as_codes, atol=2e-3)
    if not fits:
        return None
    return ("; you averaged in sRGB instead of linear light: your answer is the mean of the "
            "samples' sRGB-encoded values (as floats or as 8-bit codes), decoded: "
            f"{vec(as_float)}, where the resolve is the mean of their linear values "
            f"{vec(ours)}: encoded numbers are not light, so "
            "average the linear colours (each uncovered sample as the background) and leave "
            "the encoding to the display (lesson 12b §6)")  # fmt: skip


def _as_encoded(linear: np.ndarray, got: np.ndarray, ours: np.ndarray) -> bool:
    """Whether ``got`` is the samples (uncovered ones as the background) treated as encoded:
    decoded, averaged, encoded again, where that differs from their plain mean ``ours``."""
    light = linear_to_srgb(srgb_to_linear(linear).mean(axis=0))
    if np.allclose(light, ours, atol=1e-3):
        return False  # here the two averages agree: nothing to tell apart
    return bool(np.allclose(got, light, rtol=1e-5, atol=1e-5))
