"""r295 (exercise 05, ``safe_near``): six typical slips were told only the symptom or the rule,
one was named as another, two printed numbers hid what they meant, and the report's figure
overlapped its tick labels.

H-1: NaN was told "a near plane lies between the eye and the surfaces, 0 < n < z", never
NaN. H-2..H-6: ``^`` for the power, a sign slipped solving for n, the bits ignored (16 or 24
always), a negated n. M-1: half the gap (the same n as NDC's step) was told only "NDC".
R-1: the accepted bounds 0.00275 and 0.00339 both printed "0.003"; R-2: 0.9995 of a step
printed "1 of a step" beside "too coarse". FIG-1/FIG-2/S-1: the report's figure.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import reasoning_solutions as sol

from teachraster import exercises as ex
from teachraster.exercises.near_plane import draw_near, explain_near, near_cases


def _first(fn):
    report = ex.check("safe_near", fn, budget=60)
    assert not report.passed, "a wrong variant passes"
    assert all(f.kind for f in report.failures), "every failure has a kind"
    return report.failures[0]


def _step(bits, scale=1.0):
    return scale / (2**bits - 1)


def _solve(step, z, gap, far):
    return step * far * z * z / (gap * far + step * z * z)


@pytest.mark.parametrize(
    "fn",
    [
        lambda z, g, f, b: math.nan,  # one object: told as a constant NaN
        lambda z, g, f, b: float("nan"),  # a new NaN each call: was told "0 < n < z"
        lambda z, g, f, b: math.nan if b == 24 else sol.safe_near(z, g, f, b),
    ],
    ids=["math.nan always", "a fresh NaN always", "on 24 bits"],
)
def test_nan_is_told_as_nan_not_as_out_of_range(fn):
    first = _first(fn)
    assert first.kind == "nan", first.explanation
    assert "holds NaN" in first.explanation and "0 < n < z" not in first.explanation


SLIPS = {
    "xor": (lambda z, g, f, b: _solve(1 / ((2 ^ b) - 1), z, g, f), "exclusive or"),
    "sign slip": (
        lambda z, g, f, b: _step(b) * f * z * z / (g * f - _step(b) * z * z),
        "a sign slipped",
    ),
    "negated": (lambda z, g, f, b: -sol.safe_near(z, g, f, b), "wrong sign"),
    "24 bits": (lambda z, g, f, b: sol.safe_near(z, g, f, 24), "24-bit buffer, whatever"),
    "16 bits": (lambda z, g, f, b: sol.safe_near(z, g, f, 16), "16-bit buffer, whatever"),
}


@pytest.mark.parametrize("kind", list(SLIPS))
def test_a_typical_slip_is_named_first(kind):
    fn, words = SLIPS[kind]
    first = _first(fn)
    assert first.kind == kind, first.explanation
    assert words in first.explanation, first.explanation
    assert "0 < n < z" not in first.explanation


def test_half_the_gap_is_named_beside_ndc():
    """M-1: gap/2 gives the very n of a 2/(2^bits − 1) step: both readings are said."""
    first = _first(lambda z, g, f, b: sol.safe_near(z, g / 2, f, b))
    assert first.kind == "ndc", first.explanation
    assert "NDC" in first.explanation and "halved the gap" in first.explanation


def _case(args):
    return next(c for c in near_cases() if c[1] == args)


def test_the_accepted_bounds_are_printed_apart():
    """R-1: told from each other, not only from the student's 8."""
    _, args, expected = _case((20.0, 2.0, 25.0, 16))
    words = explain_near(args, expected, 8.0)
    accepts = words.split("the check accepts ", 1)[1].split(",", 1)[0]
    low, high = accepts.split(" to ")
    assert low != high and float(low) < expected < float(high), accepts
    need = words.split("need n ≥ ", 1)[1].split(";", 1)[0]
    first_order, steps = need.split(" (to first order")[0], words.split("; ", 1)[1].split(" ")[0]
    assert first_order != steps, words


def test_less_than_one_step_is_not_printed_as_one():
    """R-2: 0.9995 of a step beside "too coarse"."""
    _, args, expected = _case((300.0, 0.005, 1000.0, 24))
    words = explain_near(args, expected, float(np.float16(expected)))
    assert "too coarse" in words, words
    apart = words.split("lie ", 1)[1].split(" of a step", 1)[0]
    assert float(apart) < 1 and apart != "1", words


def test_the_figure_labels_few_ticks_draws_the_band_and_says_a_nan():
    """FIG-1: within a decade every minor tick was labelled, overlapping; S-1: the accepted
    band; FIG-2: a NaN answer appears in the key."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    case = near_cases()[0]
    fig, ax = plt.subplots(figsize=(7, 4))
    draw_near(ax, case, case[2] * 1.001)
    fig.canvas.draw()
    labels = [t for t in ax.get_xticklabels(minor=True) + ax.get_xticklabels() if t.get_text()]
    lo, hi = ax.get_xlim()
    shown = [t for t in labels if lo <= t.get_position()[0] <= hi]
    assert 2 <= len(shown) <= 5, [t.get_text() for t in shown]
    boxes = sorted((t.get_window_extent() for t in shown), key=lambda b: b.x0)
    assert all(a.x1 < b.x0 for a, b in zip(boxes, boxes[1:])), "tick labels overlap"
    key = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any(t.startswith("accepted ") for t in key), key
    plt.close(fig)
    fig, ax = plt.subplots()
    draw_near(ax, case, math.nan)
    key = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any("your n nan" in t and "not a number" in t for t in key), key
    plt.close(fig)


# -- fixex05: exercise 5.2 (reverse_z_gap), the notebook's text -------------------------------


def _task_text(grade_id):
    import json
    from pathlib import Path

    path = Path(__file__).resolve().parent.parent / "notebooks/exercises/05_depth_precision.ipynb"
    cells = json.loads(path.read_text())["cells"]
    cell = next(c for c in cells if c["metadata"]["nbgrader"]["grade_id"] == grade_id)
    return "".join(cell["source"])


def test_the_tasks_state_the_slack_their_checks_allow_and_5_1_its_step():
    """The 1 % of both tasks is each checker's SLACK; 5.1 says the step in window depth (r295
    S-2: "steps of one integer" was the stored value's); 5.2 names float32 and both
    neighbours."""
    from teachraster.exercises import near_plane, reverse_z

    first, second = _task_text("safe_near_task"), _task_text("reverse_z_gap_task")
    for text, slack in ((first, near_plane.SLACK), (second, reverse_z.SLACK)):
        assert f"{slack:.0%}".replace("%", " %") in text, text
    assert "step\nof 1/(2^bits − 1) in window depth" in first, first
    assert "**float32**" in second and "either neighbour" in second, second


def test_reverse_z_gap_takes_either_neighbour_at_a_power_of_two_and_no_more():
    """At d = 1/4 the float above is twice as far as the float below: both pass; 2 % coarser
    than the coarser reading fails as too coarse."""
    from teachraster.exercises import reverse_z

    args = (1.6, 1.0, 2.0)
    assert float(reverse_z.reversed_depth(*args)) == 0.25
    below, above = sorted(set(reverse_z.readings(*args)))
    assert above == 2 * below
    expected = reverse_z.expected_gap(*args)
    for ok in (below, above, above * 1.005):
        assert reverse_z.same_gap(ok, expected, args)
    assert not reverse_z.same_gap(above * 1.02, expected, args)
    assert not reverse_z.same_gap(below * 0.99, expected, args)
    assert "too coarse" in reverse_z.explain_gap(args, expected, above * 1.02)


# -- fixex05b: r311 --------------------------------------------------------------------------


def test_r311_legends_sit_beside_the_axes_and_5_2_zooms_on_its_band():
    """FIG-2: 5.1's legend covered its lines; FIG-1: 5.2's 1 % band was a sliver on a log axis
    (an inset on a linear scale shows it, its ends as ticks). S-2: no "counting whole steps"."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.exercises import reverse_z

    case = near_cases()[-4]
    fig, ax = plt.subplots(figsize=(7, 4))
    draw_near(ax, case, case[2] / 2)
    fig.canvas.draw()
    assert ax.get_legend().get_window_extent().x0 > ax.get_window_extent().x1
    plt.close(fig)
    case = reverse_z.gap_cases()[0]
    fig, ax = plt.subplots(figsize=(7, 4))
    reverse_z.draw_gap(ax, case, case[2] * 1.3)
    (inset,) = ax.child_axes
    first, last = reverse_z.bounds(*case[1])
    assert list(inset.get_xticks()) == [first, last]
    assert any("yours →" in t.get_text() for t in inset.texts)
    plt.close(fig)
    assert "counting whole steps" not in _task_text("safe_near_task")


def test_r311_decal_bias_takes_every_offset_between_its_bounds_with_the_right_sign():
    """M-1: 5.3 is judged by its two conditions (r + m ≤ |o| ≤ what the object in front
    leaves), not closeness; the sign flips under reverse-Z; the task cites the APIs."""
    from teachraster.exercises import decal_bias as db

    for _, args, expected in db.bias_cases()[:8]:
        lo, hi = db.bounds(*args)
        sign = 1 if args[6] else -1
        assert 0 < lo < hi and expected == pytest.approx(sign * lo)
        for ok in (lo, (lo + hi) / 2, hi):
            assert db.same_offset(sign * ok, expected, args)
        for bad in (lo * 0.999, hi * 1.001, -lo):
            assert not db.same_offset(sign * bad, expected, args), (args, bad)
        two_steps = sign * (lo + db.step(args[5]))  # r316 item 3: llvmpipe's r passes
        assert db.same_offset(two_steps, expected, args)
    # r316 M-2: where the object leaves less than r + m, NaN is the answer and r + m fails
    tight = db.bias_cases()[8:10]
    assert all(db.impossible(args) and np.isnan(e) for _, args, e in tight)
    for _, args, e in tight:
        sign = 1 if args[6] else -1
        assert db.same_offset(np.nan, e, args) and not db.same_offset(
            sign * db.bounds(*args)[0], e, args
        )
    # r316 item 5: the hints hold m back (its number and the bounds that give it away)
    from teachraster.exercises.tries import apply_hints

    _, args, e = db.bias_cases()[0]
    said = apply_hints(db.explain_offset(args, e, e / 10), db.HINTS)
    assert "m (yours to work out)" in said and "steps behind" not in said
    assert db.num(db.slope(*args[:5])) not in said
    # r325 C1: so does the figure, on the same failure (its key gave m in steps)
    import matplotlib.pyplot as plt

    from teachraster.exercises import tries

    tries.forget_hints("decal_bias")
    fig, ax = plt.subplots()
    db.draw_offset(ax, db.bias_cases()[0], e / 10)
    key = " ".join(t.get_text() for t in ax.get_legend().get_texts())
    assert "m yours to work out" in key and db.num(db.slope(*args[:5]) / db.step(24)) not in key
    plt.close(fig)
    # r325 M1: room between r + m and r + 2m, where a test of r + m against room alone passes
    for _, args, e in db.bias_cases()[10:12]:
        r, m = db.step(args[5]), db.slope(*args[:5])
        assert np.isnan(e) and r + m < db.room(args[0], args[3], args[4], args[7]) < r + 2 * m
    text = _task_text("decal_bias_task")
    assert all(w in text for w in ("SlopeScaledDepthBias", "glPolygonOffset", "vkCmdSetDepthBias"))
    assert "slope factor of 1" in text and "np.nan" in text


def test_r340_depth_setup_cases_lie_clear_of_every_border_and_reverse_z_ignores_the_near_plane():
    """5.4 (r340 M3/M5): every case, fixed and drawn, is one that every reading of "resolves"
    agrees on, the fixed ones hold each outcome, and the words' claim holds: reverse-Z's Δz
    lies between 2^-24 and 2^-23 of z (1 − z/f) whatever the near plane; the table names r for
    all three APIs."""
    from teachraster.exercises import depth_setup as ds

    cases = ds.setup_cases()
    assert all(ds.clear_of_borders(*args) for _, args, _ in cases)
    assert {e[0] for _, _, e in cases[: len(ds.SETTINGS)]} == {ds.UNORM, ds.REVERSE, ds.NEITHER}
    for _, (z, _, far, nearest), _ in cases:
        fine, coarse = ds._finest(z, far)
        for n in (nearest / 100, nearest, min(10 * nearest, z / 2)):
            assert fine * (1 - 1e-9) <= ds.expected_gap(z, n, far) <= coarse * (1 + 1e-9)
    text = _task_text("decal_bias_task")
    assert all(w in text for w in ("minimum resolvable difference", "§14.6.5", "depthBiasExact"))
