"""The capstone: the student's own functions render the built-in scenes.

``capstone(scene, covers=..., barycentric=..., ...)`` plugs the functions the exercises asked
for into the pipeline through its stage overrides
(:mod:`teachraster.pipeline.planning.overrides`: one place per stage, no monkeypatching),
renders the scene with them and without them (the package's own rules: the reference), and
compares the two frames pixel by pixel. Each differing pixel is explained through its pixel
history (:mod:`.capstone_explain`): the first record where the two histories part says which
stage diverged (coverage, the depth test, interpolation, blending) and the student's function
is called again there, beside the package's answer; where every record agrees, the shading
after the pipeline (texture filtering, the MSAA resolve) is compared.

Each scene is small (48 × 36) and uses only the functions of its section of the course
(:data:`SCENES`), except the last, which uses them all: a student earns each scene's point
on its own. An unfinished function (``NotImplementedError``) makes the scene "not implemented
yet"; an exception, a wrong type or an endless loop is reported with the function's name.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass, field, replace
from functools import lru_cache

import numpy as np

from ..core.validate import as_int
from ..pipeline.rendering.render_scenes import render
from . import capstone_glass as glass
from . import capstone_samples as samples
from . import capstone_texels as texels
from . import output
from .alarm import CASE_WALL_FACTOR
from .capstone_explain import CHECKED_AS, check_words, explain_pixel
from .capstone_reports import own_report
from .capstone_rules import FUNCTIONS, Tracker, kept_state, rules, wrapped
from .capstone_scenes import capstone_scene
from .diagnosis import PRECISION_KINDS
from .report import CheckFailed, Failure, Report
from .running import CASE_SHARE, effective_budget, run_case, run_checker, wall_limit
from .running import budget as time_budget

#: Frame size of every scene.
W, H = 48, 36
#: The CPU seconds a scene's render may take by default: right functions take about a
#: second, a 20,000-step loop per call some four (the notebook's setup cell prints it;
#: ``TEACHRASTER_CHECK_BUDGET`` raises it for a class).
BUDGET = 10.0
#: The share of the scene's budget one call of a student's function may take, as one case of
#: ``ex.check`` may (2 s of CPU of 10): an endless loop stops there (r163 12-8: it ran the
#: whole 10 s, 40 to 81 s on a loaded machine; issue 30 asks about 2 s). A call of a right
#: function takes microseconds to milliseconds.
CALL_SHARE = CASE_SHARE
CALL_LIMIT = BUDGET * CALL_SHARE
#: The wall-clock seconds a scene's render may take by default, on a machine too busy to give
#: it its CPU time: the render is one case whose CPU limit is the whole budget, stopped at the
#: sooner of its case's cap and its check's (:func:`.running.run_case`); the notebook's setup
#: cell prints it and its "How the check works" quotes it (r219).
WALL_LIMIT = min(CASE_WALL_FACTOR * BUDGET, wall_limit(BUDGET))


#: How close a compared value must be, absolute and relative: 1e-6 is some 17 half-ulps of
#: float32 at 1 (6e-8), room for the several roundings of a function computing in float32, or
#: on imread's float32 texture, which is right; far below the typical mistakes' differences
#: (1e-4 and more), and weights rounded to 5 decimals (up to 5e-6 off) still fail (r148
#: D12-7: "float32's rounding" understated it); a texture
#: filter rounds (u, v) too, and float32's 2^-24 of u·W becomes up to W·2^-24 of a texel's
#: contrast (1e-4 for the scenes' 128-texel checkerboard; a mistake moves colours by 1e-2).
TOL, TEXTURE_TOL = 1e-6, 1e-4


@dataclass(frozen=True)
class CapstoneScene:
    """One scene of the capstone: what is rendered, with which functions, what is compared."""

    name: str
    words: str
    uses: tuple[str, ...]
    scene: str
    options: dict = field(default_factory=dict)
    compare: tuple[str, ...] = ("image",)
    glass: bool = False
    tie: bool = False
    sort: bool = False
    tol: float = TOL
    tiled: bool = False
    #: The texture tinted by ramps (so a u/v swap shows), its (u, v) as they are.
    tinted: bool = False
    #: What the scene cannot see of a function it takes, and where that is checked instead:
    #: (function, "cases" (its own exercise's) or another scene's name, why).
    blind: tuple[tuple[str, str, str], ...] = ()
    #: The student's covers asked at every sample position (an MSAA scene: the pipeline's
    #: coverage rule runs at centres only), compared as "sample_cover" (r148 D12-6).
    sample_covers: bool = False
    #: A scene whose package frame this one's is set against where yours matches (the third
    #: panel marks where the two differ: r40 12-3, what the A-buffer repairs), or None.
    contrast: str | None = None


#: Why the scenes cannot see some mistakes (every compared centre inside its triangle, an
#: opaque background, no depth write): the fallback that sees them is named beside each.
_INSIDE = ("barycentric", "cases", "every compared centre lies inside the triangle, where "
           "signed and unsigned areas give the same weights")  # fmt: skip
_ALPHA = ("over", "cases", "this scene's opaque background hides what over does to alpha")
_NO_WRITES = ("depth_passes", "cases", "no glass fragment writes its depth, so this scene's "
              "depth test never rejects one")  # fmt: skip
# r6: a covers with ties on left edges only passed the grid (its ties lie on diagonals)
_NO_TOP = ("covers", "cases", "no edge through one of its centres is horizontal, so it cannot "
           "tell whether ties on top edges are covered")  # fmt: skip
# r6: a depth_passes that writes the depth of a fragment whose writes[k] is False passed
_ALL_WRITE = ("depth_passes", "cases", "every fragment of this scene writes its depth, so it "
              "cannot tell whether one that does not leaves the stored depth alone")  # fmt: skip

#: The blind spots whose reason explains only some of the function's mistakes: the kinds
#: (of its own exercise's check) the reason is said for (r148 D12-8: a covers that raised, or
#: accepted one winding, was told "no edge through one of its centres is horizontal").
_REASON_KINDS = {
    _NO_TOP[2]: lambda kind: kind.endswith(" rule") or kind.endswith("owns its centres"),
    _INSIDE[2]: lambda kind: kind in ("absolute area", "unsigned areas", "clamped"),
    # r163 12-4: said of "only the nearest fragment passes", which the writes have nothing to do with
    _ALL_WRITE[2]: lambda kind: kind in ("glass writes", "glass untested"),
}

#: The debug views (lesson 11's overlays) a scene may compare, read with ``frame.overlay``.
OVERLAYS = ("overdraw", "depth_complexity")


def reason_fits(why: str, kind: str) -> bool:
    """Whether a blind spot's reason ``why`` explains a failure of kind ``kind`` (a typical
    mistake's, or several joined by " and "; an exception or a time-out has no such reason)."""
    if kind in ("raised", "timeout", "exit", "memory", "not implemented", "skipped"):
        return False
    fits = _REASON_KINDS.get(why)
    return fits is None or any(fits(k) for k in kind.split(" and "))


SCENES = {s.name: s for s in (
    CapstoneScene("grid", "a grid of quads: every centre covered once, both windings",
                  ("covers",), "grid", compare=("triangle_id", "overdraw"), blind=(_NO_TOP,)),
    CapstoneScene("single_triangle", "one triangle with red, green and blue corners",
                  ("barycentric",), "single_triangle", compare=("attrs",), blind=(_INSIDE,)),
    CapstoneScene("textured_floor", "a floor to the horizon: perspective-correct uv",
                  ("barycentric", "perspective_weights"), "textured_floor", compare=("attrs",),
                  blind=(_INSIDE,)),
    # r163 12-4: "depth_complexity" (the fragments that pass, lesson 11) too: only the final
    # winner shows in the frame, so a test that passed the nearest fragment alone passed it
    CapstoneScene("intersecting_triangles", "two triangles piercing each other and a green copy "
                  "of the red one drawn last: equal depths, ties", ("depth_passes",),
                  "intersecting_triangles", compare=("triangle_id", "depth", "depth_complexity"),
                  tie=True, blind=(_ALL_WRITE,)),
    CapstoneScene("glass", "the two triangles as glass: premultiplied colour blended over in "
                  "drawing order, no depth writes", ("depth_passes", "over"),
                  "intersecting_triangles", compare=("color",), glass=True,
                  blind=(_NO_WRITES, _ALPHA), contrast="glass_sorted"),
    CapstoneScene("glass_sorted", "the glass resolved per pixel from an A-buffer: every "
                  "fragment seen through those in front of it", ("over", "a_buffer"),
                  "intersecting_triangles", compare=("color",), glass=True, sort=True,
                  blind=(_ALPHA,)),
    CapstoneScene("floor_bilinear", "the floor's checkerboard filtered bilinearly",
                  ("bilinear",), "textured_floor", {"texture_filter": "bilinear"}, tol=TEXTURE_TOL,
                  tiled=True),
    CapstoneScene("floor_trilinear", "the floor's checkerboard filtered trilinearly",
                  ("trilinear",), "textured_floor", {"texture_filter": "trilinear"},
                  tol=TEXTURE_TOL, tiled=True),
    CapstoneScene("cube_msaa", "a cube with 4 samples per pixel, your covers at each sample "
                  "position, resolved", ("covers", "resolve"), "cube", {"samples": 4},
                  ("image", "sample_cover"), sample_covers=True),
    CapstoneScene("sphere", "a textured sphere: all of your rasteriser at once",
                  ("covers", "barycentric", "perspective_weights", "depth_passes", "bilinear"),
                  "uv_sphere", {"texture_filter": "bilinear"}, ("triangle_id", "image"),
                  tol=TEXTURE_TOL, tinted=True, blind=(
                      ("covers", "grid", "no pixel centre of the sphere lies on an edge"),
                      ("depth_passes", "intersecting_triangles", "no two of the sphere's "
                       "depths are equal, and no pixel holds more than two fragments"),
                      _INSIDE)),
)}  # fmt: skip


#: The glass scenes' alpha per triangle (their colours are premultiplied by it): two different
#: alphas, so an A-buffer weighting a fragment by its own (1 − α) instead of the
#: transmittance of those in front of it fails (r137 D12-1: with two equal alphas the weights
#: agree at every pixel of two fragments).
GLASS_ALPHA = (0.6, 0.45)
#: The colour of the tie scene's copy of triangle 0 (drawn last, at exactly its depths).
TIE_COLOR = (0.2, 0.75, 0.3)


def render_with(spec: CapstoneScene, overrides=None):
    """The scene's traced frame, with ``overrides`` (None: the package's own rules)."""
    scene = capstone_scene(spec.scene, spec.tiled, spec.tinted)
    if spec.tie:  # the same vertices again, so every depth ties bit for bit with triangle 0's
        clip = scene.clip(W / H)
        colour = scene.mesh.corner("color")
        return render(np.concatenate([clip, clip[:1]]), W, H, trace=True, overrides=overrides,
                      attrs=np.concatenate([colour, np.full((1, 3, 3), TIE_COLOR)]),
                      **spec.options)  # fmt: skip
    if not spec.glass:
        return render(scene, None, W, H, trace=True, overrides=overrides, **spec.options)
    clip = scene.clip(W / H)
    alpha = np.repeat(np.resize(GLASS_ALPHA, len(clip))[:, None, None], 3, axis=1)
    # premultiplied: the colour times alpha
    rgba = np.concatenate([scene.mesh.corner("color") * alpha, alpha], axis=2)
    return render(clip, W, H, attrs=rgba, blend="premultiplied", depth_write=False,
                  clear_color=tuple(glass.BACKGROUND), trace=True, overrides=overrides)  # fmt: skip


def _frame(spec: CapstoneScene, functions=None, tracker=None):
    """The frame compared: the scene rendered with ``functions`` (None: the package's rules),
    and, for an A-buffer scene, every pixel resolved by ``a_buffer`` (or the package)."""
    if spec.sample_covers:  # covers runs at the samples, after the render (not a stage rule)
        rest = None if functions is None else {k: v for k, v in functions.items() if k != "covers"}
        frame = render_with(spec, None if rest is None else rules(rest, tracker))
        fn = None if functions is None else wrapped("covers", functions["covers"], tracker)
        return samples.sample_cover(frame, fn)
    overrides = None if functions is None else rules(functions, tracker)
    frame = render_with(spec, overrides)
    if not spec.sort:
        return frame
    if functions is None:
        return glass.resolved(frame, glass.package_resolve)
    a_buffer = wrapped("a_buffer", functions["a_buffer"], tracker)
    return glass.resolved(frame, a_buffer)


def _parts(spec: CapstoneScene, frame) -> list[np.ndarray]:
    out = []
    for name in spec.compare:
        value = frame.overlay(name) if name in OVERLAYS else getattr(frame, name)
        value = np.asarray(value, dtype=float)
        out.append(value.reshape(H, W, -1))
    return out


@lru_cache(maxsize=4)
def contrast_pixels(name: str) -> np.ndarray:
    """(n, 2) rows and columns where the package's frame of scene ``name`` differs from the
    package's frame of its :attr:`CapstoneScene.contrast` scene (drawing order against the
    A-buffer: the pixels the A-buffer repairs)."""
    spec = SCENES[name]
    other = SCENES[spec.contrast]
    mine, theirs = _frame(spec), _frame(other)
    return np.argwhere(differing(replace(spec, compare=other.compare), mine, theirs))


def differing(spec: CapstoneScene, mine, reference) -> np.ndarray:
    """(H, W) bool: pixels whose compared values differ (beyond the scene's tolerance; NaN
    equals NaN)."""
    out = np.zeros((H, W), dtype=bool)
    for a, b in zip(_parts(spec, mine), _parts(spec, reference)):
        same = np.isclose(a, b, rtol=spec.tol, atol=spec.tol) | (np.isnan(a) & np.isnan(b))
        out |= ~same.all(axis=2)
    return out


def capstone(scene: str, *, budget: float = BUDGET, **functions) -> CapstoneReport:
    """Render capstone scene ``scene`` (:data:`SCENES`) with the student's ``functions``.

    Never raises or hangs because of a student's function: the render runs within
    ``budget`` seconds of CPU (raised to ``TEACHRASTER_CHECK_BUDGET`` where a lecturer sets
    it higher), each call of a function within :data:`CALL_SHARE` of it; an exception, a wrong answer type or running out of time is a failure naming
    the function. What the functions print is kept aside and shown, capped, after the report.
    """
    if not isinstance(scene, str) or scene not in SCENES:
        raise ValueError(f"scene must be one of {list(SCENES)}, got {scene!r}")
    spec = SCENES[scene]
    missing = [name for name in spec.uses if name not in functions]
    unknown = [name for name in functions if name not in FUNCTIONS]
    if missing or unknown:
        raise TypeError(f"capstone({scene!r}) takes {', '.join(spec.uses)}; "
                        f"missing {missing}, unknown {unknown}")  # fmt: skip
    for name, fn in functions.items():
        if not callable(fn):
            raise TypeError(f"{name} must be a function, got {type(fn).__name__}")
    used = {name: functions[name] for name in spec.uses}
    reference = _frame(spec)
    tracker = Tracker()
    seconds = effective_budget(budget)
    # r174 12-2: a report's advice names the call the student made, not ex.check
    raise_call = f"ex.capstone({scene!r}, ..., budget={{seconds:g}})"
    with time_budget(seconds, raise_call=raise_call), output.captured() as printed:
        outcome = run_case(lambda: _frame(spec, used, tracker), seconds,
                           call=seconds * CALL_SHARE)  # fmt: skip
    if "a_buffer" in used and outcome.value is not None and not outcome.not_implemented:
        if run_checker(lambda: _a_buffer_failed(spec, used, outcome.value, reference), False):
            glass.count_try(outcome.value)  # r84 12-2: the order is said after two tries
    report = _report(spec, used, reference, outcome, tracker)
    if report.failures and outcome.value is not None:
        report = replace(report, failures=_state_failure(spec, used, tracker) + report.failures)
    if report.passed:  # a right frame from the package's own function does not count
        report = replace(report, package=package_use(used))
    if report.passed:  # r49: a record of the package's answers, replayed, passed a scene
        failures, aside = _own_checks(used)
        report = replace(report, failures=failures, aside=aside)
    if report.passed and tracker.precision is not None:
        report = replace(report, precision=f"your {tracker.precision[0]} answers "
                         f"{tracker.precision[1]}: right within its rounding, so they pass")  # fmt: skip
    if printed.lines:  # kept aside during the render (a print per pixel), shown capped
        report = replace(report, printed=printed.summary())
        printed.replay(sys.stdout)
    return report


def _state_failure(spec: CapstoneScene, used, tracker) -> list[Failure]:
    """r449: a function that answers its first call of the render otherwise when asked it
    again keeps state between calls; said first, as no pixel's history can explain it."""
    found = run_checker(lambda: kept_state(used, tracker), None)
    if found is None:
        return []
    name, before, again = found
    text = (f"your {name} keeps state from one call to the next: asked again, after a "
            f"render, with the arguments of the render's first call (the first pixel it was "
            f"asked about), it answered {_said(again)}, where it had answered {_said(before)}. A "
            "variable outside the function (or a default argument) that a call changes, such "
            "as a depth buffer kept between pixels? The pipeline calls it once per pixel with "
            "that pixel's data alone: start every call afresh. The pixels below were drawn "
            "with that state")  # fmt: skip
    return [Failure(spec.name, text, None, None, kind="keeps state")]


def _said(value) -> str:
    if isinstance(value, (bool, np.bool_)):
        return str(bool(value))
    values = np.asarray(value).ravel()
    if values.dtype.kind == "b":
        return "[" + ", ".join(str(bool(v)) for v in values) + "]"
    return "(" + ", ".join(f"{float(v):.4g}" for v in values) + ")"


def _raised_why(used: dict, name: str) -> str:
    """r481 HN6: where the student's ``name`` raised during the render (no frame), the
    mistake its own exercise's check names, if it names one (a barycentric refusing the other
    winding was told only "raised ValueError"), else ""."""
    from .capstone_explain import named_mistake

    words = run_checker(lambda: named_mistake(used, name), "")
    return words if " names the mistake: " in words or " gives a hint: " in words else ""


def _a_buffer_failed(spec: CapstoneScene, used, mine, reference) -> bool:
    """Whether the frame differs while the student's ``over`` is right on its own exercise's
    cases: a failure of ``a_buffer``, counted towards its full words. r174 12-7: two
    failures of ``over`` alone handed over the A-buffer's order."""
    if not differing(spec, mine, reference).any():
        return False
    return bool(own_report(CHECKED_AS["over"], used["over"]).passed)


def _report(spec, used, reference, outcome, tracker) -> CapstoneReport:
    title = f"capstone {spec.name}"
    base = dict(exercise=title, spec=spec, functions=used, reference=reference)
    n = H * W
    behind = texels.texels_behind(used).get(tracker.name)  # r502: 12.7's given filter
    if outcome.not_implemented:
        return CapstoneReport(failures=[], n_cases=n, not_implemented=True,
                              unfinished="texel_weights" if behind else tracker.name,
                              **base)  # fmt: skip
    if outcome.error is not None:
        who = f"your {tracker.name}" if behind is None else texels.given(tracker.name)
        text = outcome.error.replace("your function", who, 1)
        # the pipeline calls each function once per pixel by design: the exercises' hint
        # would point at what the student cannot change (r40 12-6)
        text = text.replace(" (a Python call per pixel?)", " (the pipeline calls it once per "
                            "pixel by design, so each call must be quick: a long loop in it?)")  # fmt: skip
        text = text.replace("of the check's", "of the scene's", 1).replace(
            "the check's budget", "the scene's budget")  # fmt: skip
        if outcome.kind in ("raised", "type", "none") and behind is not None:  # r504 HN1
            text += run_checker(lambda: texels.blame(behind), "") or texels.changed_cell(
                tracker.name)  # fmt: skip
        elif outcome.kind == "raised" and "RecursionError" in text:  # r510 WF2
            text += run_checker(lambda: texels.each_other(used[tracker.name], tracker.name), "")
        elif outcome.kind == "raised":
            text += _raised_why(used, tracker.name) or run_checker(
                lambda: samples.ids_as_rows(used, tracker.name), "")  # fmt: skip
        return CapstoneReport(failures=[Failure(spec.name, text, None, None, kind=outcome.kind)],
                              n_cases=n, **base)  # fmt: skip
    mine = outcome.value
    wrong = np.argwhere(differing(spec, mine, reference))
    failures = [_pixel_failure(spec, used, mine, reference, (int(r), int(c)))
                for r, c in _spread(wrong)]  # fmt: skip
    failures = _one_per_stage(failures)
    failures += _own_cases(spec, used, failures)
    return CapstoneReport(failures=failures, n_cases=n, mine=mine, n_wrong=len(wrong), **base)


def _own_cases(spec: CapstoneScene, used, failures) -> list[Failure]:
    """What the scene cannot see (:attr:`CapstoneScene.blind`), checked where it shows: on the
    function's own exercise's cases, or in the capstone scene that sees it. A function the
    scene's pixels already blame is not checked twice."""
    out = []
    for name, where, why in spec.blind:
        if any(f"your {name}" in f.explanation for f in failures):
            continue
        failed = _fallback(name, used[name], where)
        why = _over_unused(spec, used) if name == "over" and spec.sort else why
        if failed is not None and failed.case.startswith(f"{name} on "):
            out.append(failed)  # that scene's own fallback: said once, not nested
        elif failed is not None:
            place = (check_words(CHECKED_AS.get(name, name), "own cases") if where == "cases"
                     else f"the {where} scene")  # fmt: skip
            said = failed.explanation if where == "cases" else \
                f"{failed.case}, {failed.kind}: {failed.explanation}"  # fmt: skip
            text = (f"your {name} fails {place}, which can show what this scene cannot ({why}): {said}"
                    if reason_fits(why, failed.kind) else f"your {name} fails {place}: {said}")  # fmt: skip
            if failed.kind == "timeout":  # r94 D12-5: no tie, no "call per pixel" to a time-out
                text = f"your {name} fails {place}: " + said.replace(
                    "(a Python call per pixel?)", f"(one call of {name} should take microseconds)")  # fmt: skip
            label = (check_words(CHECKED_AS.get(name, name), "own cases", short=True)
                     if where == "cases" else place)  # fmt: skip
            out.append(Failure(f"{name} on {label}", text, None, None, kind=failed.kind))
    return out


def _over_unused(spec: CapstoneScene, used) -> str:
    """Why an A-buffer scene cannot see ``over``'s mistake: the student's ``a_buffer`` composes
    with some ``over`` of its own, and may not call the one handed to the capstone at all (r49:
    "the opaque background hides" was said of an a_buffer that never called it)."""
    fn, over = used["a_buffer"], used["over"]
    code, names = getattr(fn, "__code__", None), getattr(fn, "__globals__", {})
    calls = code is not None and "over" in code.co_names and names.get("over") is over
    if code is not None and not calls and over not in (
            getattr(fn, "__defaults__", None) or ()):  # fmt: skip
        return (
            "your a_buffer never calls the over you passed (it composites with another "
            "function, or by itself), so this scene never ran your over"
        )
    return next(why for name, _, why in spec.blind if name == "over")


def package_use(used: dict) -> str | None:
    """Why the scene does not count although its frame is right: one of the functions is the
    package's own answer (a one-line wrapper of ``tr.sample``, ``tr.barycentric``, ...), or
    None. The rule is its exercise's, in one place: :func:`~.package_answers.package_note`,
    as ``ex.check`` runs it on the function's own cases (r40 12-1: four scenes passed with
    ``tr.*`` one-liners that ``ex.check`` refuses)."""
    from .checks import names

    for name, fn in _judged(used).items():
        checked = CHECKED_AS.get(name, name)
        if name == "a_buffer":  # no exercise of its own: the package's resolve (r163 12-5)
            note = glass.package_use(fn)
        elif checked in names():
            note = own_report(checked, fn).package
        else:
            continue
        if note is not None:  # its words name the function: "your bilinear calls ..."
            return note.replace(f"your {checked} ", f"your {name} ", 1)
    return None


def _judged(used: dict) -> dict:
    """``used`` with 12.7's given filters replaced by the student's ``texel_weights`` they add
    up (r502: its own exercise, 7.2, judges it), each function once."""
    behind = texels.texels_behind(used)
    out = {}
    for name, fn in used.items():
        if name in behind:
            out.setdefault("texel_weights", behind[name])
        else:
            out[name] = fn
    return out


def _own_checks(used: dict) -> tuple[list[Failure], str | None]:
    """Each function on its own exercise's check, whose cases include some drawn afresh:
    a function that only replays answers recorded from the package (right on this scene's
    pixels, r49: ``single_triangle`` passed so) fails them. Empty when all pass. Beside them
    a note, or None: ``perspective_weights`` failing only cases whose w no GPU meets (r126
    D12-1: exercise 3.2's w = 1e-310 failed a scene whose every pixel matched)."""
    from .checks import names

    out, aside = [], None
    for name, fn in _judged(used).items():
        checked = CHECKED_AS.get(name, name)
        if name == "a_buffer":  # no exercise of its own: its own stacks (r148 D12-4)
            said = run_checker(lambda fn=fn: glass.own_cases(fn),
                               "your a_buffer did not answer its own stacks in time")  # fmt: skip
            if said is not None:
                place = "its own stacks of three and four fragments"
                out.append(Failure(f"a_buffer on {place}", f"your a_buffer fails {place} (the "
                                   f"scene's pixels hold at most two): {said}", None, None,
                                   kind="sorting"))  # fmt: skip
            continue
        if checked not in names():
            continue
        report = own_report(checked, fn)
        # float32 within its rounding passes the capstone (:data:`TOL`), as in _fallback
        failed = None if report.passed else next(
            (f for f in report.failures if f.kind not in PRECISION_KINDS), None)  # fmt: skip
        if failed is not None and checked == "perspective_weights":
            failed, aside = _on_a_gpu(name, report.failures)
        if failed is not None:
            place = check_words(checked, "own cases")
            said = failed.explanation
            slip = "" if failed.kind != "value" else run_checker(  # no mistake named: r510 HN2
                lambda fn=fn, n=name: samples.resolve_slip({n: fn}, n), "")  # fmt: skip
            if slip:  # r510 HN2: the case's numbers, then the slip (not the generic question)
                at = said.find(")", said.find("; yours is (")) if "; yours is (" in said else -1
                said = (said[: at + 1] if at >= 0 else said) + slip
            if name == "texel_weights":  # r502: behind 12.7's given filters
                said = f"{said.replace('your function', 'your texel_weights')} ({texels.CHECK_CALL} runs them)"
            out.append(Failure(f"{name} on {check_words(checked, 'own cases', short=True)}",
                               f"your {name} fails {place} (some drawn "
                               f"afresh for this check): {failed.case}: {said}",
                               None, None, kind=failed.kind))  # fmt: skip
    return out, aside


def _on_a_gpu(name: str, failures: list[Failure]) -> tuple[Failure | None, str | None]:
    """The first failure of ``perspective_weights`` on a case a GPU meets (w within float32's
    range), and a note on those it failed beyond that range (None where there are none)."""
    from .perspective_weighting import beyond_a_gpu

    counted = [f for f in failures if f.kind not in PRECISION_KINDS and not beyond_a_gpu(f.case)]
    beyond = [f for f in failures if beyond_a_gpu(f.case)]
    aside = None if not beyond else (
        f"your {name} still fails {len(beyond)} of exercise 3.2's cases whose w lie beyond "
        f"float32's range, such as {beyond[0].case}: a GPU never meets such w, so the scene "
        "does not count them (exercise 3.2's own check does: a simulator meets them)"
    )  # fmt: skip
    return (counted[0] if counted else None), aside


def _fallback(name: str, fn, where: str) -> Failure | None:
    """The first failure of ``fn`` on its own exercise's cases (``where`` = "cases") or in
    capstone scene ``where``, or None when it passes there."""
    if where == "cases":
        report = own_report(CHECKED_AS.get(name, name), fn)
    else:
        with output.captured():
            report = capstone(where, **{name: fn})
    if report.passed or report.not_implemented:
        return None
    # float32 within its rounding passes the capstone (:data:`TOL`), even where an exercise's
    # own cases ask for float64's digits
    return next((f for f in report.failures if f.kind not in PRECISION_KINDS), None)


def _spread(wrong: np.ndarray, most: int = 12) -> list:
    """The first differing pixel and up to ``most`` - 1 more spread over the rest."""
    if len(wrong) <= most:
        return list(wrong)
    picks = np.unique(np.linspace(0, len(wrong) - 1, most).astype(int))
    return list(wrong[picks])


def _pixel_failure(spec, used, mine, reference, pixel) -> Failure:
    stage, text = explain_pixel(spec, used, mine, reference, pixel)
    return Failure(f"pixel {pixel}", text, None, None, kind=stage)


def _one_per_stage(failures: list[Failure]) -> list[Failure]:
    """The first failure of each stage first (one mistake must not hide another)."""
    seen, first, rest = set(), [], []
    for f in failures:
        (rest if f.kind in seen else first).append(f)
        seen.add(f.kind)
    return first + rest


def _said_once(failures: list[Failure]) -> list[str]:
    """The failures' lines, each pixel of a stage already explained named by its coordinates
    only (r148 D12-10: three pixels of one mistake printed the same paragraph three times)."""
    lines, more = [], {}
    for f in failures:
        if f.case.startswith("pixel ") and f.kind in more:
            more[f.kind].append(f.case.removeprefix("pixel "))
            continue
        if f.case.startswith("pixel "):
            more[f.kind] = []
        lines.append(f"- {f.case}, {f.kind}: {f.explanation}")
    for kind, pixels in more.items():
        if pixels:
            lines.append(f"- {kind} differs at {', '.join(pixels)} too (report.explain_pixel"
                         "(row, col) tells each)")  # fmt: skip
    return lines


@dataclass(frozen=True)
class CapstoneReport(Report):
    """A :class:`.Report` of one capstone scene: its pixels are its cases.

    ``compare(axes)`` draws the student's frame, the package's and the differing pixels,
    the first one marked.
    """

    spec: CapstoneScene | None = field(default=None, repr=False)
    functions: dict = field(default_factory=dict, repr=False)
    reference: object = field(default=None, repr=False)
    mine: object = field(default=None, repr=False)
    n_wrong: int = 0
    unfinished: str | None = None
    #: A note beside a pass: what the scene does not count (:func:`_on_a_gpu`), or None.
    aside: str | None = None

    def __str__(self) -> str:
        return self._with_printed(self._summary())

    def _summary(self) -> str:
        behind = texels.texels_behind(self.functions)
        uses = ", ".join(f"texel_weights (through 12.7's {u})" if u in behind else u
                         for u in self.spec.uses)  # fmt: skip
        head = f"{self.exercise} ({self.spec.words}; your {uses})"
        if self.not_implemented and self.unfinished == "texel_weights":
            return (f"{head}: not implemented yet (texel_weights is not written yet: it raises "
                    "NotImplementedError; replace `raise NotImplementedError()` in 12.7's cell "
                    "with your code from exercise 7.2, then run that cell and this one again)")  # fmt: skip
        if self.not_implemented:
            return (f"{head}: not implemented yet ({self.unfinished} raises "
                    "NotImplementedError: replace `raise NotImplementedError()` with your "
                    "code, then run its cell and this one again)")  # fmt: skip
        if self.passed:
            note = "" if self.precision is None else f" ({self.precision})"
            if self.aside is not None:
                return f"{head}: all {self.n_cases} pixels match the package's, and the scene passes{note} ({self.aside})"  # fmt: skip
            return (f"{head}: all {self.n_cases} pixels match the package's (all cases "
                    f"pass){note}")  # fmt: skip
        if self.package is not None and self.mine is not None and not self.failures:
            return (f"{head}: all {self.n_cases} pixels match the package's, but not "
                    f"counted: {self.package}")  # fmt: skip
        if self.mine is None:
            return f"{head}: no frame: {self.failures[0].explanation}"
        if self.n_wrong == 0:  # r49: failed through another scene's or exercise's cases
            lines = [f"{head}: fails, though all {self.n_cases} pixels match the package's"]
        else:
            lines = [f"{head}: {self.n_wrong} of {self.n_cases} pixels differ from the package's"]
        lines += _said_once(self.shown())
        return "\n".join(lines)

    def assert_passed(self) -> None:
        """Do nothing when the scene passed; else raise ``AssertionError`` naming the scene
        only: the check cell's ``show(report)`` printed the report just above (r163 12-9:
        nbgrader's traceback repeated the first pixel's explanation under it; r174 12-9: its
        first line, the whole of a "not implemented yet" report, was still said twice)."""
        if not self.passed:
            # r173 D5: one line, not this method's source (:class:`.report.CheckFailed`)
            raise CheckFailed(f"{self.exercise} does not pass: the report printed above "
                              "says why (print(report) prints it again)")  # fmt: skip

    def differing_pixels(self) -> np.ndarray:
        """(n, 2) rows and columns where the student's frame differs; none where the scene
        was not rendered with the student's functions (:meth:`no_difference` says why)."""
        if self.mine is None:
            return np.zeros((0, 2), dtype=int)
        return np.argwhere(differing(self.spec, self.mine, self.reference))

    def not_rendered(self) -> str | None:
        """Why the scene has no frame of the student's to compare (a function unfinished,
        raising or out of time), or None when it was rendered."""
        if self.mine is not None:
            return None
        if self.not_implemented or not self.failures:
            why = (f"your {self.unfinished or 'function'} raises NotImplementedError: replace "
                   "`raise NotImplementedError()` with your code and run its cell again")  # fmt: skip
        else:
            why = self.failures[0].explanation
        return (f"{self.spec.name} was not rendered with your functions, so there is no pixel "
                f"of yours to compare: {why}")  # fmt: skip

    def no_difference(self) -> str:
        """What to say where :meth:`differing_pixels` is empty: the scene was not rendered
        (r84 12-1: "no pixel differs" was printed for a stub), or every pixel matches."""
        if self.mine is None:
            return self.not_rendered()
        words = f"no pixel differs: all {self.n_cases} pixels match the package's"
        if self.failures:  # failed through its own exercise's cases or another scene's
            return f"{words}; the scene fails for another reason: see the report above"
        return words

    def explain_pixel(self, row: int, col: int) -> str:
        """Why pixel (``row``, ``col``) of your frame differs from the package's (the stage
        where its histories part), or that it does not."""
        row, col = as_int("row", row), as_int("col", col)
        if not (0 <= row < H and 0 <= col < W):
            raise ValueError(f"(row, col) must lie in the {H} × {W} frame, got ({row}, {col})")
        if self.mine is None:
            return self.not_rendered()
        if not differing(self.spec, self.mine, self.reference)[row, col]:
            return f"pixel ({row}, {col}) matches the package's"
        stage, text = explain_pixel(self.spec, self.functions, self.mine, self.reference,
                                    (row, col))  # fmt: skip
        return f"pixel ({row}, {col}), {stage}: {text}"

    def repaired_pixels(self) -> np.ndarray:
        """(n, 2) pixels where the scene's :attr:`CapstoneScene.contrast` scene differs
        (:func:`contrast_pixels`); empty where it has none."""
        if self.spec.contrast is None:
            return np.zeros((0, 2), dtype=int)
        return contrast_pixels(self.spec.name)

    def compare(self, axes=None, pixel="first"):
        """Three panels: your frame, the package's, the differing pixels (``pixel``, or the
        first differing one, marked); returns the artists."""
        from .capstone_drawing import draw_capstone

        return draw_capstone(self, axes, pixel)
